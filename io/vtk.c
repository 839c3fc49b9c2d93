#include "vtk.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../solver/diagnostics.h"
#include "../solver/particles.h"
#include "files.h"

/* One ASCII DataArray of n tuples of ncomp values taken by get(k, c). */
struct column {
  const char *name, *type;
  int ncomp;
};

static void open_array(FILE *f, const struct column *c) {
  fprintf(f,
          "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
          "format=\"ascii\">\n",
          c->type, c->name, c->ncomp);
}

int vsph_vtk_write(const char *dir, const char *name,
                   const struct vsph_particles *p, size_t n_fluid, double t,
                   const struct vsph_diagnostics *dg) {
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
  const size_t n = n_fluid;
  fprintf(f,
          "<?xml version=\"1.0\"?>\n"
          "<!-- vsph particles t = %.10g -->\n"
          "<VTKFile type=\"PolyData\" version=\"0.1\" "
          "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
          "<PolyData>\n<FieldData>\n"
          "<DataArray type=\"Float64\" Name=\"TimeValue\" "
          "NumberOfTuples=\"1\" format=\"ascii\">%.10g</DataArray>\n"
          "</FieldData>\n"
          "<Piece NumberOfPoints=\"%zu\" NumberOfVerts=\"%zu\" "
          "NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
          "<Points>\n",
          t, t, n, n);
  const struct column pts = {"Points", "Float64", 3};
  open_array(f, &pts);
  for (size_t k = 0; k < n; k++) {
    const size_t i = order[k];
    fprintf(f, "%.10g %.10g %.10g\n", p->pos[0][i], d > 1 ? p->pos[1][i] : 0.0,
            d > 2 ? p->pos[2][i] : 0.0);
  }
  fprintf(f, "</DataArray>\n</Points>\n<Verts>\n");
  fprintf(f,
          "<DataArray type=\"Int64\" Name=\"connectivity\" "
          "format=\"ascii\">\n");
  for (size_t k = 0; k < n; k++) fprintf(f, "%zu\n", k);
  fprintf(f,
          "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
          "format=\"ascii\">\n");
  for (size_t k = 0; k < n; k++) fprintf(f, "%zu\n", k + 1);
  fprintf(f,
          "</DataArray>\n</Verts>\n"
          "<PointData Scalars=\"pressure\" Vectors=\"velocity\">\n");
  const struct column vel = {"velocity", "Float64", 3};
  open_array(f, &vel);
  for (size_t k = 0; k < n; k++) {
    const size_t i = order[k];
    fprintf(f, "%.10g %.10g %.10g\n", p->vel[0][i], d > 1 ? p->vel[1][i] : 0.0,
            d > 2 ? p->vel[2][i] : 0.0);
  }
  fprintf(f, "</DataArray>\n");
  const struct column rho = {"density", "Float64", 1};
  open_array(f, &rho);
  for (size_t k = 0; k < n; k++) fprintf(f, "%.12g\n", p->rho[order[k]]);
  fprintf(f, "</DataArray>\n");
  const struct column pr = {"pressure", "Float64", 1};
  open_array(f, &pr);
  for (size_t k = 0; k < n; k++) fprintf(f, "%.10g\n", p->p[order[k]]);
  fprintf(f, "</DataArray>\n");
  const struct column vol = {"volume", "Float64", 1};
  open_array(f, &vol);
  for (size_t k = 0; k < n; k++) {
    const size_t i = order[k];
    fprintf(f, "%.10g\n", p->m[i] / p->rho[i]);
  }
  fprintf(f, "</DataArray>\n");
  if (p->mat) { /* contact SPH with two materials (1: the second or a held
                   body) */
    const struct column mat = {"material", "UInt8", 1};
    open_array(f, &mat);
    for (size_t k = 0; k < n; k++) fprintf(f, "%d\n", p->mat[order[k]]);
    fprintf(f, "</DataArray>\n");
  }
  if (dg) {
    const struct column vort = {"vorticity", "Float64", 3};
    open_array(f, &vort);
    for (size_t k = 0; k < n; k++)
      fprintf(f, "%.10g %.10g %.10g\n", dg->vort[0][k], dg->vort[1][k],
              dg->vort[2][k]);
    fprintf(f, "</DataArray>\n");
    const struct column divr = {"div_r", "Float64", 1};
    open_array(f, &divr);
    for (size_t k = 0; k < n; k++) fprintf(f, "%.8g\n", dg->divr[k]);
    fprintf(f, "</DataArray>\n");
    const struct column surf = {"free_surface", "UInt8", 1};
    open_array(f, &surf);
    for (size_t k = 0; k < n; k++) fprintf(f, "%d\n", dg->surf[k]);
    fprintf(f, "</DataArray>\n");
  }
  const struct column id = {"id", "Int64", 1};
  open_array(f, &id);
  for (size_t k = 0; k < n; k++) fprintf(f, "%zu\n", k);
  fprintf(f,
          "</DataArray>\n</PointData>\n</Piece>\n</PolyData>\n"
          "</VTKFile>\n");
  free(order);
  return vsph_files_close(f, dir, name);
}

/* The text between the opening tag of the DataArray called NAME and its
 * closing tag, or NULL. */
static const char *array_body(const char *text, const char *name) {
  char key[96];
  snprintf(key, sizeof key, "Name=\"%s\"", name);
  const char *a = strstr(text, key);
  if (!a) return NULL;
  const char *b = strchr(a, '>');
  return b ? b + 1 : NULL;
}

/* n*ncomp numbers from s into out; 0 on success. */
static int read_numbers(const char *s, size_t count, double *out) {
  char *e;
  for (size_t k = 0; k < count; k++) {
    out[k] = strtod(s, &e);
    if (e == s) return -1;
    s = e;
  }
  return 0;
}

int vsph_vtk_read(const char *path, struct vsph_vtk_snapshot *s) {
  memset(s, 0, sizeof *s);
  char *text = vsph_files_slurp(path, NULL);
  if (!text) VSPH_FAIL(VSPH_EIO, "cannot read %s", path);
  const char *np = strstr(text, "NumberOfPoints=\"");
  const char *tv = array_body(text, "TimeValue");
  const char *px = array_body(text, "Points");
  const char *vx = array_body(text, "velocity");
  const char *pp = array_body(text, "pressure");
  const char *wx = array_body(text, "vorticity");
  const char *sf = array_body(text, "free_surface");
  if (!np || !tv || !px || !vx || !pp) {
    free(text);
    VSPH_FAIL(VSPH_EIO, "%s is not a vsph snapshot", path);
  }
  s->n = strtoul(np + 16, NULL, 10);
  s->t = strtod(tv, NULL);
  const size_t n = s->n ? s->n : 1;
  s->pos = malloc(3 * n * sizeof(double));
  s->vel = malloc(3 * n * sizeof(double));
  s->p = malloc(n * sizeof(double));
  s->vort = malloc(3 * n * sizeof(double));
  s->surf = malloc(n * sizeof(double));
  int bad = !s->pos || !s->vel || !s->p || !s->vort || !s->surf;
  if (!bad)
    bad = read_numbers(px, 3 * s->n, s->pos) ||
          read_numbers(vx, 3 * s->n, s->vel) || read_numbers(pp, s->n, s->p) ||
          (wx ? read_numbers(wx, 3 * s->n, s->vort) : 0) ||
          (sf ? read_numbers(sf, s->n, s->surf) : 0);
  if (!wx && !bad) memset(s->vort, 0, 3 * n * sizeof(double));
  if (!sf && !bad) memset(s->surf, 0, n * sizeof(double));
  free(text);
  if (bad) {
    vsph_vtk_snapshot_free(s);
    VSPH_FAIL(VSPH_EIO, "%s: a data array is short or unreadable", path);
  }
  return VSPH_OK;
}

void vsph_vtk_snapshot_free(struct vsph_vtk_snapshot *s) {
  free(s->pos);
  free(s->vel);
  free(s->p);
  free(s->vort);
  free(s->surf);
  memset(s, 0, sizeof *s);
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
  fprintf(pvd->f, "<DataSet timestep=\"%.10g\" part=\"0\" file=\"%s\"/>\n", t,
          file);
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
