#include "vtk.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../solver/particles.h"
#include "files.h"

int vsph_vtk_write(const char *dir, const char *name,
                   const struct vsph_particles *p, size_t n_fluid, double t) {
  size_t *order = malloc((n_fluid ? n_fluid : 1) * sizeof *order);
  if (!order) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a snapshot");
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] < n_fluid) order[p->id[i]] = i;
  FILE *f = vsph_files_open(dir, name);
  if (!f) {
    free(order);
    return VSPH_EIO;
  }
  const int d = p->dim;
  fprintf(f,
          "# vtk DataFile Version 3.0\nvsph particles t = %.10g\nASCII\n"
          "DATASET POLYDATA\nPOINTS %zu double\n",
          t, n_fluid);
  for (size_t k = 0; k < n_fluid; k++) {
    const size_t i = order[k];
    fprintf(f, "%.10g %.10g %.10g\n", p->pos[0][i], d > 1 ? p->pos[1][i] : 0.0,
            d > 2 ? p->pos[2][i] : 0.0);
  }
  fprintf(f, "VERTICES %zu %zu\n", n_fluid, 2 * n_fluid);
  for (size_t k = 0; k < n_fluid; k++) fprintf(f, "1 %zu\n", k);
  fprintf(f, "POINT_DATA %zu\nVECTORS velocity double\n", n_fluid);
  for (size_t k = 0; k < n_fluid; k++) {
    const size_t i = order[k];
    fprintf(f, "%.10g %.10g %.10g\n", p->vel[0][i], d > 1 ? p->vel[1][i] : 0.0,
            d > 2 ? p->vel[2][i] : 0.0);
  }
  fprintf(f, "SCALARS density double 1\nLOOKUP_TABLE default\n");
  for (size_t k = 0; k < n_fluid; k++) fprintf(f, "%.12g\n", p->rho[order[k]]);
  fprintf(f, "SCALARS pressure double 1\nLOOKUP_TABLE default\n");
  for (size_t k = 0; k < n_fluid; k++) fprintf(f, "%.10g\n", p->p[order[k]]);
  fprintf(f, "SCALARS id int 1\nLOOKUP_TABLE default\n");
  for (size_t k = 0; k < n_fluid; k++) fprintf(f, "%zu\n", k);
  free(order);
  return vsph_files_close(f, dir, name);
}

int vsph_vtk_pvd_open(struct vsph_vtk_pvd *pvd, const char *dir) {
  char path[4096];
  snprintf(path, sizeof path, "%s/snapshots.pvd", dir);
  pvd->dir = dir;
  pvd->f = fopen(path, "w");
  if (!pvd->f)
    VSPH_FAIL(VSPH_EIO, "cannot write %s: %s", path, strerror(errno));
  fprintf(pvd->f,
          "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" "
          "version=\"0.1\">\n<Collection>\n");
  return VSPH_OK;
}

int vsph_vtk_pvd_add(struct vsph_vtk_pvd *pvd, double t, const char *file) {
  fprintf(pvd->f, "<DataSet timestep=\"%.10g\" file=\"%s\"/>\n", t, file);
  if (fflush(pvd->f) != 0 || ferror(pvd->f))
    VSPH_FAIL(VSPH_EIO, "cannot write %s/snapshots.pvd", pvd->dir);
  return VSPH_OK;
}

int vsph_vtk_pvd_close(struct vsph_vtk_pvd *pvd) {
  if (!pvd->f) return VSPH_OK;
  fprintf(pvd->f, "</Collection>\n</VTKFile>\n");
  const int bad = ferror(pvd->f);
  const int closed = fclose(pvd->f);
  pvd->f = NULL;
  if (bad || closed)
    VSPH_FAIL(VSPH_EIO, "cannot write %s/snapshots.pvd", pvd->dir);
  return VSPH_OK;
}
