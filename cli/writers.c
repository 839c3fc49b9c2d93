#include "writers.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../analysis/moments.h"
#include "../common/status.h"
#include "../solver/particles.h"

cJSON *vsph_writers_array(const double *v, size_t n) {
  cJSON *a = cJSON_CreateArray();
  for (size_t i = 0; i < n; i++)
    cJSON_AddItemToArray(
        a, isfinite(v[i]) ? cJSON_CreateNumber(v[i]) : cJSON_CreateNull());
  return a;
}

void vsph_writers_number(cJSON *obj, const char *key, double v) {
  if (isfinite(v))
    cJSON_AddNumberToObject(obj, key, v);
  else
    cJSON_AddNullToObject(obj, key);
}

void vsph_writers_moments(cJSON *obj, const struct vsph_moments *m) {
  const int d = m->dim;
  cJSON *F = cJSON_CreateArray(), *G = cJSON_CreateArray();
  cJSON *M = cJSON_CreateArray();
  for (int i = 0; i < d; i++) {
    cJSON *Fi = cJSON_CreateArray(), *Gi = cJSON_CreateArray();
    cJSON_AddItemToArray(M, vsph_writers_array(m->M[i], (size_t)d));
    for (int j = 0; j < d; j++) {
      cJSON *Gij = cJSON_CreateArray();
      cJSON_AddItemToArray(Fi, vsph_writers_array(m->F[i][j], (size_t)d));
      for (int l = 0; l < d; l++)
        cJSON_AddItemToArray(Gij, vsph_writers_array(m->G[i][j][l], (size_t)d));
      cJSON_AddItemToArray(Gi, Gij);
    }
    cJSON_AddItemToArray(F, Fi);
    cJSON_AddItemToArray(G, Gi);
  }
  cJSON_AddItemToObject(obj, "F", F);
  cJSON_AddItemToObject(obj, "G", G);
  cJSON_AddItemToObject(obj, "N", vsph_writers_array(m->N, (size_t)d));
  cJSON_AddItemToObject(obj, "M", M);
}

int vsph_writers_print_json(cJSON *obj) {
  char *s = cJSON_Print(obj);
  cJSON_Delete(obj);
  if (!s) VSPH_FAIL(VSPH_ENOMEM, "cannot format JSON");
  puts(s);
  free(s);
  return VSPH_OK;
}

FILE *vsph_writers_open(const char *dir, const char *name) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s.tmp", dir, name);
  FILE *f = fopen(path, "w");
  if (!f)
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot write %s: %s",
                       path, strerror(errno));
  return f;
}

int vsph_writers_close(FILE *f, const char *dir, const char *name) {
  char tmp[4096], path[4096];
  snprintf(tmp, sizeof tmp, "%s/%s.tmp", dir, name);
  snprintf(path, sizeof path, "%s/%s", dir, name);
  const int bad = ferror(f);
  if (fclose(f) != 0 || bad || rename(tmp, path) != 0) {
    remove(tmp);
    VSPH_FAIL(VSPH_EIO, "cannot write %s", path);
  }
  return VSPH_OK;
}

int vsph_writers_json_file(cJSON *obj, const char *dir, const char *name) {
  char *s = cJSON_Print(obj);
  cJSON_Delete(obj);
  if (!s) VSPH_FAIL(VSPH_ENOMEM, "cannot format JSON");
  FILE *f = vsph_writers_open(dir, name);
  if (!f) {
    free(s);
    return VSPH_EIO;
  }
  fputs(s, f);
  fputc('\n', f);
  free(s);
  return vsph_writers_close(f, dir, name);
}

int vsph_writers_mkdir(const char *dir) {
  char buf[4096];
  snprintf(buf, sizeof buf, "%s", dir);
  for (char *c = buf + 1; *c; c++) {
    if (*c != '/') continue;
    *c = '\0';
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
      VSPH_FAIL(VSPH_EIO, "cannot create %s: %s", buf, strerror(errno));
    *c = '/';
  }
  if (mkdir(buf, 0777) != 0 && errno != EEXIST)
    VSPH_FAIL(VSPH_EIO, "cannot create %s: %s", buf, strerror(errno));
  return VSPH_OK;
}

int vsph_writers_vtk(const char *dir, const char *name,
                     const struct vsph_particles *p, size_t n_fluid, double t) {
  size_t *order = malloc((n_fluid ? n_fluid : 1) * sizeof *order);
  if (!order) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a snapshot");
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] < n_fluid) order[p->id[i]] = i;
  FILE *f = vsph_writers_open(dir, name);
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
  return vsph_writers_close(f, dir, name);
}

char *vsph_writers_slurp(const char *path, size_t *len) {
  FILE *f = fopen(path, "rb");
  if (!f) return NULL;
  char *b = NULL;
  long n = -1;
  if (fseek(f, 0, SEEK_END) == 0) n = ftell(f);
  if (n >= 0 && fseek(f, 0, SEEK_SET) == 0) b = malloc((size_t)n + 1);
  if (b && fread(b, 1, (size_t)n, f) != (size_t)n) {
    free(b);
    b = NULL;
  }
  fclose(f);
  if (!b) return NULL;
  b[n] = '\0';
  if (len) *len = (size_t)n;
  return b;
}
