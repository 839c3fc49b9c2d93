/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* io/vtk (issue 6 of the ParaView review): snapshots as VTK XML PolyData
 * with binary appended, zlib-compressed data, the form ParaView writes
 * itself. The writer against vsph_vtk_read (bitwise round trip) and
 * against a reader written here from VTK's description of the format
 * (the header's tags one by one, each array inflated block by block), so
 * that a file both readers agree on is not merely self-consistent; the
 * 2-D vorticity is the scalar omega_z; every array is described; a run's
 * snapshots fall at round times, each the state a run ending there
 * reaches. `make paraview-check` opens the same files in ParaView
 * itself. */
#include <errno.h>
#include <float.h>
#include <gsl/gsl_rng.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include "../common/status.h"
#include "../io/files.h"
#include "../io/vtk.h"
#include "../solver/diagnostics.h"
#include "../solver/particles.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "check_suites.h"

/* ---- the independent reader ---- */

enum { VTP_MAX = 32 };

/* One array of a .vtp as its header tag and its inflated bytes. */
struct vtp_array {
  char tag[16]; /* DataArray or Array */
  char name[64], type[16];
  int ncomp;
  size_t ntuples;  /* NumberOfTuples (FieldData), else 0 */
  uint64_t blocks; /* the compressed layout: number of blocks, */
  uint64_t block;  /* the block size, */
  uint64_t last;   /* the partial last block's size (0: full) */
  size_t nbytes;
  unsigned char *bytes;
};

struct vtp {
  char *text;  /* the whole file */
  size_t len;  /* its bytes */
  char *vtk;   /* the VTKFile tag */
  char *piece; /* the Piece tag */
  struct vtp_array a[VTP_MAX];
  size_t na;
};

/* Attribute KEY of the tag starting at @p tag (up to its '>') into val;
 * 0 when absent. */
static int tag_attr(const char *tag, const char *key, char *val, size_t n) {
  const char *end = strchr(tag, '>');
  char k[64];
  snprintf(k, sizeof k, " %s=\"", key);
  const char *s = strstr(tag, k);
  if (!s || !end || s > end) return 0;
  s += strlen(k);
  size_t m = 0;
  while (s[m] != '"' && m + 1 < n) m++;
  memcpy(val, s, m);
  val[m] = '\0';
  return 1;
}

static uint64_t u64_at(const unsigned char *p) {
  uint64_t v;
  memcpy(&v, p, sizeof v);
  return v;
}

/* Parse @p path: every DataArray/Array tag of the header in file order,
 * each array's blocks inflated. Fails the test on any inconsistency. */
static void vtp_load(const char *path, struct vtp *v) {
  memset(v, 0, sizeof *v);
  FILE *f = fopen(path, "rb");
  ck_assert_ptr_nonnull(f);
  fseek(f, 0, SEEK_END);
  v->len = (size_t)ftell(f);
  fseek(f, 0, SEEK_SET);
  v->text = malloc(v->len + 1);
  ck_assert_uint_eq(fread(v->text, 1, v->len, f), v->len);
  v->text[v->len] = '\0';
  fclose(f);
  char *app = strstr(v->text, "<AppendedData encoding=\"raw\">\n_");
  ck_assert_ptr_nonnull(app);
  const unsigned char *data =
      (const unsigned char *)app + strlen("<AppendedData encoding=\"raw\">\n_");
  const size_t dlen = v->len - (size_t)(data - (unsigned char *)v->text);
  *app = '\0'; /* the header is the text before */
  v->vtk = strstr(v->text, "<VTKFile ");
  v->piece = strstr(v->text, "<Piece ");
  ck_assert_ptr_nonnull(v->vtk);
  ck_assert_ptr_nonnull(v->piece);
  for (char *t = v->text; (t = strchr(t, '<')) != NULL; t++) {
    const int da = !strncmp(t, "<DataArray ", 11),
              sa = !strncmp(t, "<Array ", 7);
    if (!da && !sa) continue;
    ck_assert_uint_lt(v->na, VTP_MAX);
    struct vtp_array *a = &v->a[v->na++];
    char val[64];
    snprintf(a->tag, sizeof a->tag, "%s", da ? "DataArray" : "Array");
    ck_assert(tag_attr(t, "Name", a->name, sizeof a->name));
    ck_assert(tag_attr(t, "type", a->type, sizeof a->type));
    a->ncomp =
        tag_attr(t, "NumberOfComponents", val, sizeof val) ? atoi(val) : 1;
    if (tag_attr(t, "NumberOfTuples", val, sizeof val))
      a->ntuples = strtoul(val, NULL, 10);
    ck_assert(tag_attr(t, "format", val, sizeof val));
    ck_assert_str_eq(val, "appended");
    ck_assert(tag_attr(t, "offset", val, sizeof val));
    const size_t off = strtoul(val, NULL, 10);
    ck_assert_uint_le(off + 24, dlen);
    a->blocks = u64_at(data + off);
    a->block = u64_at(data + off + 8);
    a->last = u64_at(data + off + 16);
    const unsigned char *z = data + off + 24 + 8 * a->blocks;
    a->bytes = malloc(a->blocks * a->block + 1);
    for (uint64_t b = 0; b < a->blocks; b++) {
      const uint64_t zs = u64_at(data + off + 24 + 8 * b);
      ck_assert_uint_le((size_t)(z - data) + zs, dlen);
      uLongf got = (uLongf)a->block;
      ck_assert_int_eq(uncompress(a->bytes + a->nbytes, &got, z, (uLong)zs),
                       Z_OK);
      /* every block is full but a partial last one */
      ck_assert_uint_eq(got,
                        b + 1 == a->blocks && a->last ? a->last : a->block);
      a->nbytes += got;
      z += zs;
    }
  }
}

static void vtp_free(struct vtp *v) {
  for (size_t k = 0; k < v->na; k++) free(v->a[k].bytes);
  free(v->text);
}

static const struct vtp_array *vtp_find(const struct vtp *v, const char *n) {
  for (size_t k = 0; k < v->na; k++)
    if (!strcmp(v->a[k].name, n)) return &v->a[k];
  return NULL;
}

/* Value k of array a as a double (Float64, Int64 or UInt8). */
static double vtp_value(const struct vtp_array *a, size_t k) {
  if (!strcmp(a->type, "Float64")) {
    ck_assert_uint_le((k + 1) * 8, a->nbytes);
    double x;
    memcpy(&x, a->bytes + 8 * k, 8);
    return x;
  }
  if (!strcmp(a->type, "Float32")) {
    ck_assert_uint_le((k + 1) * 4, a->nbytes);
    float x;
    memcpy(&x, a->bytes + 4 * k, 4);
    return x;
  }
  if (!strcmp(a->type, "Int64")) {
    ck_assert_uint_le((k + 1) * 8, a->nbytes);
    int64_t x;
    memcpy(&x, a->bytes + 8 * k, 8);
    return (double)x;
  }
  ck_assert_str_eq(a->type, "UInt8");
  ck_assert_uint_lt(k, a->nbytes);
  return a->bytes[k];
}

double *vsph_test_vtp_values(const char *path, const char *name, int *ncomp,
                             size_t *count) {
  struct vtp v;
  vtp_load(path, &v);
  const struct vtp_array *a = vtp_find(&v, name);
  double *out = NULL;
  if (a) {
    const size_t width = strcmp(a->type, "UInt8") ? 8 : 1;
    *count = a->nbytes / width;
    *ncomp = a->ncomp;
    out = malloc((*count ? *count : 1) * sizeof *out);
    for (size_t k = 0; k < *count; k++) out[k] = vtp_value(a, k);
  }
  vtp_free(&v);
  return out;
}

/* ---- a particle set with high-entropy values ---- */

struct fixture {
  struct vsph_particles *p;
  struct vsph_diagnostics dg;
  size_t n; /* fluid particles; 7 more (ids n..n+6) stand for ghosts */
  double t;
};

/* n fluid particles in dim dimensions (and 7 ghosts), ids shuffled so that
 * the set's order is not the file's; diagnostics (indexed by id) with
 * every component set, so writing a wrong one shows. */
static void fixture_make(struct fixture *fx, int dim, size_t n, int mat) {
  const size_t ng = 7, nt = n + ng;
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  gsl_rng_set(rng, 2385);
  struct vsph_particles *p = vsph_particles_alloc(nt, dim);
  ck_assert_ptr_nonnull(p);
  p->n = nt;
  if (mat) ck_assert_int_eq(vsph_particles_mat_alloc(p), 0);
  for (size_t i = 0; i < nt; i++) {
    p->id[i] = i;
    for (int a = 0; a < dim; a++) {
      p->pos[a][i] = -1.2348 + 2.385 * gsl_rng_uniform(rng);
      p->vel[a][i] = 0.0371 * (gsl_rng_uniform(rng) - 0.5);
    }
    p->rho[i] = 998.2 * (1.0 + 0.01 * gsl_rng_uniform(rng));
    p->m[i] = 0.123 * (1.0 + 0.1 * gsl_rng_uniform(rng));
    p->p[i] = 1.2348e3 * (gsl_rng_uniform(rng) - 0.3);
    if (mat) p->mat[i] = (unsigned char)(gsl_rng_uniform(rng) < 0.3);
  }
  for (size_t i = nt - 1; i > 0; i--) { /* Fisher-Yates */
    const size_t j = gsl_rng_uniform_int(rng, i + 1), s = p->id[i];
    p->id[i] = p->id[j];
    p->id[j] = s;
  }
  struct vsph_diagnostics *dg = &fx->dg;
  memset(dg, 0, sizeof *dg);
  dg->n = n;
  dg->dim = dim;
  dg->h = 0.0123456789; /* not short in decimal */
  for (int a = 0; a < 3; a++) {
    dg->vort[a] = malloc((n ? n : 1) * sizeof(double));
    for (size_t k = 0; k < n; k++)
      dg->vort[a][k] = (a + 1) * (gsl_rng_uniform(rng) - 0.5);
  }
  dg->divr = malloc((n ? n : 1) * sizeof(double));
  dg->surf = malloc(n ? n : 1);
  for (size_t k = 0; k < n; k++) {
    dg->divr[k] = 1.0 + gsl_rng_uniform(rng);
    dg->surf[k] = dg->divr[k] < 1.5;
  }
  fx->p = p;
  fx->n = n;
  fx->t = 0.1234567890123456789 * 2.385; /* not short in decimal */
  gsl_rng_free(rng);
}

static void fixture_free(struct fixture *fx) {
  vsph_diagnostics_free(&fx->dg);
  vsph_particles_free(fx->p);
}

/* The cases: dimension, particles, material. 4096 scalars fill exactly
 * one 32768-byte block (the "last" field is 0); 5003 gives partial last
 * blocks; 1 a single short one. */
static const struct {
  int dim;
  size_t n;
  int mat;
} cases[] = {{2, 5003, 0}, {3, 5003, 1}, {2, 4096, 0}, {3, 1, 0}};
enum { NCASES = sizeof cases / sizeof cases[0] };

static void write_case(int c, struct fixture *fx, char *dir, char *path,
                       size_t n) {
  fixture_make(fx, cases[c].dim, cases[c].n, cases[c].mat);
  ck_assert_ptr_nonnull(mkdtemp(dir));
  ck_assert_int_eq(
      vsph_vtk_write(dir, "s.vtp", fx->p, fx->n, fx->t, &fx->dg, NULL), 0);
  snprintf(path, n, "%s/s.vtp", dir);
}

static void clean_case(struct fixture *fx, const char *dir, const char *path) {
  ck_assert_int_eq(remove(path), 0);
  /* nothing else was left there (the writer's scratch file unlinked) */
  ck_assert_msg(rmdir(dir) == 0, "%s: %s", dir, strerror(errno));
  fixture_free(fx);
}

/* Write, then read back with vsph_vtk_read: every double bitwise equal
 * (the format stores them raw; no tolerance), in id order, the ghosts
 * left out; volume is m/rho computed the same way (one IEEE division, so
 * exact too); 2-D vorticity comes back as (0, 0, omega_z). */
/* The walls beside a snapshot (vsph_vtk_write_walls): the particles
 * beyond the fluid, in id order whatever their place in the set, typed 1
 * (the first n_wall of them: wall particles) or 2 (images), their
 * pressure and mass bitwise, the smoothing length given; an h not
 * positive refused. */
START_TEST(test_walls_file_in_id_order_typed) {
  struct vsph_particles *p = vsph_particles_alloc(7, 2);
  ck_assert_ptr_nonnull(p);
  p->n = 7;
  const size_t id[7] = {4, 0, 6, 1, 5, 2, 3}; /* fluid 0-2, walls 3-6 */
  for (size_t i = 0; i < 7; i++) {
    p->id[i] = id[i];
    p->pos[0][i] = 0.1 * (double)id[i] + 1e-3;
    p->pos[1][i] = -0.2 * (double)id[i];
    p->vel[0][i] = p->vel[1][i] = 0.0;
    p->rho[i] = 1000.0 + (double)id[i];
    p->p[i] = 2.385 * (double)id[i];
    p->m[i] = 0.75 + 0.5 * (double)id[i];
  }
  char dir[] = "/tmp/vsph_wallsXXXXXX", path[64];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  vsph_test_silence(); /* h must be positive: refused, nothing written */
  ck_assert_int_eq(vsph_vtk_write_walls(dir, "w.vtp", p, 3, 2, 0.0, 0.5),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_vtk_write_walls(dir, "w.vtp", p, 3, 2, NAN, 0.5),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_vtk_write_walls(dir, "w.vtp", p, 3, 2, 0.037, 0.5), 0);
  snprintf(path, sizeof path, "%s/w.vtp", dir);
  int nc = 0;
  size_t nv = 0;
  double *ty = vsph_test_vtp_values(path, "type", &nc, &nv);
  double *ids = vsph_test_vtp_values(path, "id", &nc, &nv);
  double *pr = vsph_test_vtp_values(path, "pressure", &nc, &nv);
  double *ms = vsph_test_vtp_values(path, "mass", &nc, &nv);
  double *hs = vsph_test_vtp_values(path, "smoothing_length", &nc, &nv);
  ck_assert_ptr_nonnull(ms);
  ck_assert_ptr_nonnull(hs);
  ck_assert_ptr_nonnull(ty);
  ck_assert_ptr_nonnull(ids);
  ck_assert_ptr_nonnull(pr);
  ck_assert_uint_eq(nv, 4);
  for (size_t k = 0; k < 4; k++) {
    ck_assert(ids[k] == (double)(3 + k));        /* id order */
    ck_assert(ty[k] == (3 + k < 3 + 2 ? 1 : 2)); /* walls, then images */
    ck_assert(pr[k] == 2.385 * (double)(3 + k));
    ck_assert(ms[k] == 0.75 + 0.5 * (double)(3 + k)); /* bitwise */
    ck_assert(hs[k] == 0.037);
  }
  free(ms);
  free(hs);
  free(ty);
  free(ids);
  free(pr);
  remove(path);
  rmdir(dir);
  vsph_particles_free(p);
}
END_TEST

START_TEST(test_snapshot_reads_back_bitwise) {
  struct fixture fx;
  char dir[] = "/tmp/vsph_vtkXXXXXX", path[64];
  write_case(_i, &fx, dir, path, sizeof path);
  const struct vsph_particles *p = fx.p;
  const int dim = cases[_i].dim;
  struct vsph_vtk_snapshot s;
  ck_assert_int_eq(vsph_vtk_read(path, &s), 0);
  ck_assert_uint_eq(s.n, fx.n);
  ck_assert(s.t == fx.t);
  ck_assert_int_eq(s.vort_ncomp, dim == 2 ? 1 : 3);
  size_t seen = 0;
  for (size_t i = 0; i < p->n; i++) {
    const size_t k = p->id[i];
    if (k >= fx.n) continue;
    seen++;
    for (int a = 0; a < 3; a++) {
      ck_assert(s.pos[3 * k + a] == (a < dim ? p->pos[a][i] : 0.0));
      ck_assert(s.vel[3 * k + a] == (a < dim ? p->vel[a][i] : 0.0));
      const double w = dim == 3 || a == 2 ? fx.dg.vort[a][k] : 0.0;
      ck_assert(s.vort[3 * k + a] == w);
    }
    ck_assert(s.rho[k] == p->rho[i]);
    ck_assert(s.p[k] == p->p[i]);
    ck_assert(s.vol[k] == p->m[i] / p->rho[i]);
    ck_assert(s.divr[k] == fx.dg.divr[k]);
    ck_assert(s.surf[k] == fx.dg.surf[k]);
    ck_assert(s.mat[k] == (p->mat ? p->mat[i] : 0));
  }
  ck_assert_uint_eq(seen, fx.n);
  vsph_vtk_snapshot_free(&s);
  /* mass and smoothing length per particle, as a ParaView user reads
   * them: each bitwise (raw doubles) */
  int nc = 0;
  size_t nv = 0;
  double *m = vsph_test_vtp_values(path, "mass", &nc, &nv);
  double *h = vsph_test_vtp_values(path, "smoothing_length", &nc, &nv);
  ck_assert_ptr_nonnull(m);
  ck_assert_ptr_nonnull(h);
  ck_assert_uint_eq(nv, fx.n);
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] < fx.n) {
      ck_assert(m[p->id[i]] == p->m[i]);
      ck_assert(h[p->id[i]] == fx.dg.h);
    }
  free(m);
  free(h);
  clean_case(&fx, dir, path);
}
END_TEST

/* A frame (vsph_vtk_write_frame) of a written snapshot, at 10 and 4
 * mantissa bits and each choice of fields, read by the reader written
 * here: each float it holds is its double rounded to nearest at that many
 * bits, so its dropped bits are zero and it lies within 2^-(bits+1) of
 * single precision's value, itself within 2^-24 of the double (the 2^-23
 * below covers both the latter and the product of the two); the largest
 * error over the 5003 random values is above 2^-(bits+2), so the rounding
 * is at @p bits, not finer. No density, volume or vertex cells, and a
 * field not asked for is absent. vsph_vtk_read gives the same floats,
 * widened, frame_bits and frame_fields; an out-of-range bits or fields is
 * refused with nothing written. */
START_TEST(test_frame_rounds_to_mantissa_bits) {
  struct fixture fx;
  char dir[] = "/tmp/vsph_vtkXXXXXX", path[64], fpath[80];
  write_case(_i, &fx, dir, path, sizeof path);
  struct vsph_vtk_snapshot s;
  ck_assert_int_eq(vsph_vtk_read(path, &s), 0);
  ck_assert_int_eq(s.frame_bits, 0);
  ck_assert_uint_eq(s.frame_fields, 0u);
  const size_t n = s.n;
  snprintf(fpath, sizeof fpath, "%s/f.vtp", dir);
  static const int bitsv[2] = {10, 4};
  for (int b = 0; b < 2; b++)
    for (unsigned fields = 0; fields < 4; fields++) {
      const int bits = bitsv[b];
      ck_assert_int_eq(vsph_vtk_write_frame(dir, "f.vtp", &s, bits, fields), 0);
      struct vtp v;
      vtp_load(fpath, &v);
      char val[32];
      ck_assert(tag_attr(v.piece, "NumberOfVerts", val, sizeof val));
      ck_assert_str_eq(val, "0");
      ck_assert_ptr_null(vtp_find(&v, "density"));
      ck_assert_ptr_null(vtp_find(&v, "volume"));
      ck_assert_ptr_null(vtp_find(&v, "connectivity"));
      const int vel = fields & VSPH_VTK_FRAME_VELOCITY,
                sca = (fields & VSPH_VTK_FRAME_SCALARS) != 0;
      const int w2 = sca && cases[_i].dim == 2;
      const struct {
        const char *name;
        int present, ncomp, stride, comp;
        const double *of;
      } arr[] = {{"Points", 1, 3, 1, 0, s.pos},
                 {"velocity", vel, 3, 1, 0, s.vel},
                 {"pressure", sca, 1, 1, 0, s.p},
                 {"vorticity_z", w2, 1, 3, 2, s.vort}};
      const double bound = ldexp(1.0, -(bits + 1)) + ldexp(1.0, -23);
      const uint32_t low = (UINT32_C(1) << (23 - bits)) - 1;
      double worst = 0.0;
      for (size_t a = 0; a < sizeof arr / sizeof *arr; a++) {
        const struct vtp_array *fa = vtp_find(&v, arr[a].name);
        if (!arr[a].present) {
          ck_assert_ptr_null(fa);
          continue;
        }
        ck_assert_ptr_nonnull(fa);
        ck_assert_str_eq(fa->type, "Float32");
        ck_assert_int_eq(fa->ncomp, arr[a].ncomp);
        ck_assert_uint_eq(fa->nbytes, 4 * n * (size_t)arr[a].ncomp);
        for (size_t k = 0; k < n * (size_t)arr[a].ncomp; k++) {
          const double x = arr[a].of[arr[a].stride * k + arr[a].comp];
          uint32_t u;
          memcpy(&u, fa->bytes + 4 * k, 4);
          ck_assert_uint_eq(u & low, 0u);
          const double y = vtp_value(fa, k), e = fabs(y - x);
          ck_assert_msg(e <= bound * fabs(x), "%s[%zu]: %.17g for %.17g",
                        arr[a].name, k, y, x);
          if (x != 0.0) worst = fmax(worst, e / fabs(x));
        }
      }
      const struct vtp_array *fs = vtp_find(&v, "free_surface");
      ck_assert(sca ? fs != NULL : fs == NULL);
      for (size_t k = 0; sca && k < n; k++)
        ck_assert(vtp_value(fs, k) == s.surf[k]);
      if (n > 1000) ck_assert(worst > ldexp(1.0, -(bits + 2)));
      struct vsph_vtk_snapshot f;
      ck_assert_int_eq(vsph_vtk_read(fpath, &f), 0);
      ck_assert_int_eq(f.frame_bits, bits);
      ck_assert_uint_eq(f.frame_fields, fields);
      ck_assert_uint_eq(f.n, n);
      ck_assert(f.t == s.t);
      const struct vtp_array *fp = vtp_find(&v, "Points");
      for (size_t k = 0; k < 3 * n; k++) {
        ck_assert(f.pos[k] == vtp_value(fp, k));
        ck_assert(vel || f.vel[k] == 0.0);
      }
      for (size_t k = 0; k < n; k++) {
        ck_assert(f.rho[k] == 0.0 && f.vol[k] == 0.0);
        ck_assert(sca || (f.p[k] == 0.0 && f.surf[k] == 0.0));
      }
      vsph_vtk_snapshot_free(&f);
      vtp_free(&v);
      remove(fpath);
    }
  ck_assert_int_eq(vsph_vtk_write_frame(dir, "f.vtp", &s, 0, 3u), VSPH_EINVAL);
  ck_assert_int_eq(vsph_vtk_write_frame(dir, "f.vtp", &s, 24, 3u), VSPH_EINVAL);
  ck_assert_int_eq(vsph_vtk_write_frame(dir, "f.vtp", &s, 10, 4u), VSPH_EINVAL);
  ck_assert_int_eq(access(fpath, F_OK), -1);
  vsph_vtk_snapshot_free(&s);
  clean_case(&fx, dir, path);
}
END_TEST

/* x in single precision, then rounded to nearest (ties away from zero) at
 * @p bits mantissa bits by frexp and round: an independent statement of
 * the frame's rounding (normal floats; NaN, infinities and zeros as they
 * are; past FLT_MAX it overflows to infinity, as IEEE conversion does). */
static float ref_round(double x, int bits) {
  const float f = (float)x;
  if (!isfinite(f) || f == 0.0f) return f;
  int e;
  const double m = frexp((double)f, &e); /* f = m 2^e, 0.5 <= |m| < 1 */
  return (float)ldexp(round(ldexp(m, bits + 1)), e - bits - 1);
}

/* The frame's rounding on chosen values, each float the file holds
 * equal to ref_round's: exact ties (away from zero), a carry into the
 * exponent, negatives, zeros of both signs, infinities, NaN, FLT_MAX
 * (to infinity), a tiny normal float and plain values; at 10 and 3
 * bits. A frame is not made of a frame. */
START_TEST(test_frame_rounding) {
  const double tie = 1.0 + ldexp(1.0, -11),
               v[] = {1.0, -1.0,    tie,   -tie,       1.0 - ldexp(1.0, -13),
                      3.0, 0.0,     -0.0,  INFINITY,   -INFINITY,
                      NAN, FLT_MAX, 1e-30, 123456.789, -0.0371};
  const size_t n = sizeof v / sizeof *v;
  struct vsph_vtk_snapshot s = {0};
  s.n = n;
  s.vort_ncomp = 1;
  double *buf = calloc(13 * n, sizeof *buf);
  ck_assert_ptr_nonnull(buf);
  s.pos = buf, s.vel = buf + 3 * n, s.vort = buf + 6 * n, s.p = buf + 9 * n;
  s.surf = buf + 10 * n, s.rho = buf + 11 * n, s.vol = buf + 12 * n;
  for (size_t k = 0; k < n; k++) {
    s.pos[3 * k] = v[k];
    s.vel[3 * k + 1] = -v[k];
    s.p[k] = 0.5 * v[k];
  }
  char dir[] = "/tmp/vsph_vtkXXXXXX", fpath[80];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  snprintf(fpath, sizeof fpath, "%s/f.vtp", dir);
  static const int bitsv[2] = {10, 3};
  for (int b = 0; b < 2; b++) {
    const int bits = bitsv[b];
    ck_assert_int_eq(vsph_vtk_write_frame(dir, "f.vtp", &s, bits, 3u), 0);
    struct vtp f;
    vtp_load(fpath, &f);
    const struct vtp_array *pa = vtp_find(&f, "Points"),
                           *va = vtp_find(&f, "velocity"),
                           *ra = vtp_find(&f, "pressure");
    ck_assert(pa && va && ra);
    for (size_t k = 0; k < n; k++) {
      const double want[3] = {v[k], -v[k], 0.5 * v[k]};
      const double got[3] = {vtp_value(pa, 3 * k), vtp_value(va, 3 * k + 1),
                             vtp_value(ra, k)};
      for (int a = 0; a < 3; a++) {
        const float r = ref_round(want[a], bits);
        ck_assert_msg(
            isnan(r) ? isnan(got[a])
                     : got[a] == (double)r && !signbit(got[a]) == !signbit(r),
            "%.17g at %d bits: %.17g, not %.9g", want[a], bits, got[a],
            (double)r);
      }
    }
    ck_assert(vtp_value(pa, 3 * 2) == 1.0 + ldexp(1.0, -bits) || bits != 10);
    ck_assert(vtp_value(pa, 3 * 4) == 1.0 || bits != 10);
    vtp_free(&f);
    remove(fpath);
  }
  struct vsph_vtk_snapshot f = s;
  f.frame_bits = 10;
  vsph_test_silence();
  ck_assert_int_eq(vsph_vtk_write_frame(dir, "f.vtp", &f, 10, 3u), VSPH_EINVAL);
  ck_assert_int_eq(access(fpath, F_OK), -1);
  rmdir(dir);
  free(buf);
}
END_TEST

/* The blocks are compressed in parallel: the file's bytes are the same
 * whether 1 or 2 threads wrote it. With the stop flag raised the writer
 * abandons the file before it is opened (VSPH_EINTR; the folder stays
 * empty, no temporary), and writes it whole once the flag is down. */
START_TEST(test_threads_and_stop) {
  struct fixture fx;
  char dir[] = "/tmp/vsph_vtkXXXXXX", path[64], two[80];
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  write_case(_i, &fx, dir, path, sizeof path);
  size_t l1 = 0, l2 = 0;
  char *b1 = vsph_files_slurp(path, &l1);
  ck_assert_ptr_nonnull(b1);
  omp_set_num_threads(2);
  ck_assert_int_eq(
      vsph_vtk_write(dir, "two.vtp", fx.p, fx.n, fx.t, &fx.dg, NULL), 0);
  omp_set_num_threads(threads);
  snprintf(two, sizeof two, "%s/two.vtp", dir);
  char *b2 = vsph_files_slurp(two, &l2);
  ck_assert_ptr_nonnull(b2);
  ck_assert(l1 == l2 && !memcmp(b1, b2, l1));
  free(b2);
  remove(two);
  remove(path);
  volatile sig_atomic_t stop = 1;
  ck_assert_int_eq(
      vsph_vtk_write(dir, "s.vtp", fx.p, fx.n, fx.t, &fx.dg, &stop),
      VSPH_EINTR);
  ck_assert_int_eq(rmdir(dir), 0); /* empty: nothing was written */
  ck_assert_ptr_nonnull(mkdtemp(strcpy(dir, "/tmp/vsph_vtkXXXXXX")));
  stop = 0;
  ck_assert_int_eq(
      vsph_vtk_write(dir, "s.vtp", fx.p, fx.n, fx.t, &fx.dg, &stop), 0);
  snprintf(path, sizeof path, "%s/s.vtp", dir);
  b2 = vsph_files_slurp(path, &l2);
  ck_assert_ptr_nonnull(b2);
  ck_assert(l1 == l2 && !memcmp(b1, b2, l1));
  free(b1);
  free(b2);
  clean_case(&fx, dir, path);
}
END_TEST

struct expect {
  const char *name, *type;
  int ncomp;
};

/* The file decoded here: VTK's header attributes; each PointData array's
 * name, type and components (2-D: the scalar vorticity_z and no
 * "vorticity"; 3-D: the 3-vector); every array's compressed blocks as the
 * layout says (blocks = ceil(bytes/32768), last = bytes mod 32768); the
 * values against the inputs bitwise, vorticity_z against the z component;
 * vertices 0..n-1 with offsets 1..n; TimeValue the exact time. */
START_TEST(test_file_layout_decoded_bitwise) {
  struct fixture fx;
  char dir[] = "/tmp/vsph_vtkXXXXXX", path[64], val[64];
  write_case(_i, &fx, dir, path, sizeof path);
  const int dim = cases[_i].dim;
  const size_t n = fx.n;
  struct vtp v;
  vtp_load(path, &v);
  const uint16_t one = 1;
  unsigned char little;
  memcpy(&little, &one, 1);
  ck_assert(tag_attr(v.vtk, "type", val, sizeof val));
  ck_assert_str_eq(val, "PolyData");
  ck_assert(tag_attr(v.vtk, "byte_order", val, sizeof val));
  ck_assert_str_eq(val, little ? "LittleEndian" : "BigEndian");
  ck_assert(tag_attr(v.vtk, "header_type", val, sizeof val));
  ck_assert_str_eq(val, "UInt64");
  ck_assert(tag_attr(v.vtk, "compressor", val, sizeof val));
  ck_assert_str_eq(val, "vtkZLibDataCompressor");
  ck_assert(tag_attr(v.piece, "NumberOfPoints", val, sizeof val));
  ck_assert_uint_eq(strtoul(val, NULL, 10), n);
  ck_assert(tag_attr(v.piece, "NumberOfVerts", val, sizeof val));
  ck_assert_uint_eq(strtoul(val, NULL, 10), n);
  /* the arrays, their types and components: exactly these */
  struct expect want[18] = {{"TimeValue", "Float64", 1},
                            {"array_descriptions", "String", 1},
                            {"Points", "Float64", 3},
                            {"connectivity", "Int64", 1},
                            {"offsets", "Int64", 1},
                            {"velocity", "Float64", 3},
                            {"density", "Float64", 1},
                            {"pressure", "Float64", 1},
                            {"volume", "Float64", 1},
                            {"mass", "Float64", 1},
                            {"smoothing_length", "Float64", 1},
                            {"div_r", "Float64", 1},
                            {"free_surface", "UInt8", 1},
                            {"id", "Int64", 1}};
  size_t nw = 14;
  if (dim == 2) want[nw++] = (struct expect){"vorticity_z", "Float64", 1};
  if (dim == 3) want[nw++] = (struct expect){"vorticity", "Float64", 3};
  if (cases[_i].mat) want[nw++] = (struct expect){"material", "UInt8", 1};
  ck_assert_uint_eq(v.na, nw);
  for (size_t k = 0; k < nw; k++) {
    const struct vtp_array *a = vtp_find(&v, want[k].name);
    ck_assert_msg(a != NULL, "no array %s", want[k].name);
    ck_assert_str_eq(a->type, want[k].type);
    ck_assert_int_eq(a->ncomp, want[k].ncomp);
    ck_assert_str_eq(a->tag, strcmp(a->type, "String") ? "DataArray" : "Array");
    const size_t width = !strcmp(a->type, "UInt8") ? 1 : 8;
    if (strcmp(a->type, "String") && strcmp(a->name, "TimeValue"))
      ck_assert_uint_eq(a->nbytes, n * (size_t)a->ncomp * width);
    ck_assert_uint_eq(a->blocks, (a->nbytes + 32767) / 32768);
    ck_assert_uint_eq(a->block, 32768);
    ck_assert_uint_eq(a->last, a->nbytes % 32768);
  }
  ck_assert_ptr_null(vtp_find(&v, dim == 2 ? "vorticity" : "vorticity_z"));
  ck_assert(vtp_value(vtp_find(&v, "TimeValue"), 0) == fx.t);
  const struct vtp_array *pts = vtp_find(&v, "Points"),
                         *vel = vtp_find(&v, "velocity"),
                         *w = vtp_find(&v,
                                       dim == 2 ? "vorticity_z" : "vorticity"),
                         *con = vtp_find(&v, "connectivity"),
                         *off = vtp_find(&v, "offsets"),
                         *id = vtp_find(&v, "id");
  const struct vsph_particles *p = fx.p;
  for (size_t i = 0; i < p->n; i++) {
    const size_t k = p->id[i];
    if (k >= n) continue;
    for (int a = 0; a < 3; a++) {
      ck_assert(vtp_value(pts, 3 * k + a) == (a < dim ? p->pos[a][i] : 0.0));
      ck_assert(vtp_value(vel, 3 * k + a) == (a < dim ? p->vel[a][i] : 0.0));
    }
    if (dim == 2) ck_assert(vtp_value(w, k) == fx.dg.vort[2][k]);
    for (int a = 0; a < 3 && dim == 3; a++)
      ck_assert(vtp_value(w, 3 * k + a) == fx.dg.vort[a][k]);
    ck_assert(vtp_value(con, k) == (double)k);
    ck_assert(vtp_value(off, k) == (double)(k + 1));
    ck_assert(vtp_value(id, k) == (double)k);
  }
  vtp_free(&v);
  clean_case(&fx, dir, path);
}
END_TEST

/* array_descriptions: one NUL-terminated string per tuple, each
 * "names: what (unit)", together naming every array of the file; the
 * units follow the dimension (docs/theory.md section 6 gives the
 * free-surface thresholds 1.5 and 2.4). The header comment repeats them
 * for a reader of the text. */
START_TEST(test_descriptions_name_every_array) {
  struct fixture fx;
  char dir[] = "/tmp/vsph_vtkXXXXXX", path[64];
  write_case(_i, &fx, dir, path, sizeof path);
  const int dim = cases[_i].dim;
  struct vtp v;
  vtp_load(path, &v);
  const struct vtp_array *d = vtp_find(&v, "array_descriptions");
  ck_assert_ptr_nonnull(d);
  ck_assert_uint_gt(d->nbytes, 0);
  ck_assert_int_eq(d->bytes[d->nbytes - 1], '\0');
  char named[1024] = ",";
  size_t count = 0;
  for (size_t at = 0; at < d->nbytes; at += strlen((char *)d->bytes + at) + 1) {
    const char *s = (const char *)d->bytes + at, *colon = strstr(s, ": ");
    count++;
    ck_assert_msg(
        colon != NULL && s[strlen(s) - 1] == ')' && strstr(s, " (") != NULL,
        "not \"names: what (unit)\": %s", s);
    strncat(named, s, (size_t)(colon - s)); /* "a, b" -> ",a,b," */
    strcat(named, ",");
    ck_assert_ptr_nonnull(strstr(v.text, s)); /* in the header comment */
    if (!strncmp(s, "density:", 8))
      ck_assert_ptr_nonnull(strstr(s, dim == 2 ? "(kg/m^2)" : "(kg/m^3)"));
    if (!strncmp(s, "volume:", 7))
      ck_assert_ptr_nonnull(strstr(s, dim == 2 ? "(m^2)" : "(m^3)"));
    if (!strncmp(s, "free_surface:", 13))
      ck_assert_ptr_nonnull(strstr(s, dim == 2 ? "< 1.5" : "< 2.4"));
  }
  ck_assert_uint_eq(count, d->ntuples);
  for (char *c = named; *c; c++)
    if (*c == ' ') memmove(c, c + 1, strlen(c));
  for (size_t k = 0; k < v.na; k++) {
    if (!strcmp(v.a[k].name, "array_descriptions")) continue;
    char key[80];
    snprintf(key, sizeof key, ",%s,", v.a[k].name);
    ck_assert_msg(strstr(named, key) != NULL, "%s is not described",
                  v.a[k].name);
  }
  vtp_free(&v);
  clean_case(&fx, dir, path);
}
END_TEST

/* Snapshots that vsph_vtk_read must refuse (VSPH_EIO, reported): none
 * there, an ASCII one of an older vsph, one cut short, one with a
 * compressed byte changed (zlib's Adler-32 catches it), one claiming more
 * points than it holds, one whose arrays run past its end. */
START_TEST(test_read_refuses_damaged_files) {
  struct fixture fx;
  char dir[] = "/tmp/vsph_vtkXXXXXX", path[64], bad[80];
  write_case(0, &fx, dir, path, sizeof path);
  size_t len;
  char *text;
  {
    FILE *f = fopen(path, "rb");
    fseek(f, 0, SEEK_END);
    len = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    text = malloc(len);
    ck_assert_uint_eq(fread(text, 1, len, f), len);
    fclose(f);
  }
  snprintf(bad, sizeof bad, "%s/bad.vtp", dir);
  struct vsph_vtk_snapshot s;
  vsph_test_silence();
  ck_assert_int_eq(vsph_vtk_read(bad, &s), VSPH_EIO);
  const char *ascii =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" "
      "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<PolyData>\n"
      "<FieldData>\n<DataArray type=\"Float64\" Name=\"TimeValue\" "
      "NumberOfTuples=\"1\" format=\"ascii\">0.5</DataArray>\n</FieldData>\n"
      "<Piece NumberOfPoints=\"1\">\n</Piece>\n</PolyData>\n</VTKFile>\n";
  const char *vel = strstr(text, "Name=\"velocity\"");
  ck_assert_ptr_nonnull(vel);
  const size_t voff = strtoul(strstr(vel, "offset=\"") + 8, NULL, 10);
  const size_t data = (size_t)(strstr(text, "\n_") + 2 - text);
  char *np = strstr(text, "NumberOfPoints=\"5003\"");
  ck_assert_ptr_nonnull(np);
  for (int k = 0; k < 5; k++) {
    FILE *f = fopen(bad, "wb");
    if (k == 0) fputs(ascii, f);
    if (k == 1) fwrite(text, 1, len - 1000, f);
    if (k == 2) { /* a byte inside velocity's first compressed block */
      text[data + voff + 24 + 8 * 4 + 500] ^= 0x5a;
      fwrite(text, 1, len, f);
      text[data + voff + 24 + 8 * 4 + 500] ^= 0x5a;
    }
    if (k == 3) {
      memcpy(np, "NumberOfPoints=\"5004\"", 21);
      fwrite(text, 1, len, f);
      memcpy(np, "NumberOfPoints=\"5003\"", 21);
    }
    if (k == 4) { /* the second half gone, the closing tags kept */
      fwrite(text, 1, len / 2, f);
      fwrite(text + len - 28, 1, 28, f);
    }
    fclose(f);
    ck_assert_msg(vsph_vtk_read(bad, &s) == VSPH_EIO, "case %d read", k);
    ck_assert_int_eq(vsph_test_last_status(), VSPH_EIO);
    ck_assert_ptr_null(s.pos);
  }
  free(text);
  remove(bad);
  clean_case(&fx, dir, path);
}
END_TEST

/* Two files' bytes the same (both must exist). */
static int same_bytes(const char *a, const char *b) {
  size_t la = 0, lb = 0;
  char *x = vsph_files_slurp(a, &la), *y = vsph_files_slurp(b, &lb);
  ck_assert_msg(x && y, "cannot read %s or %s", a, b);
  const int same = la == lb && !memcmp(x, y, la);
  free(x);
  free(y);
  return same;
}

/* A run's snapshots.pvd against its energy.csv: the snapshots fall at
 * k t_end / 4 exactly (the text "0.025", the TimeValue the double nearest
 * it), between the energy rows but for the first and the last, which are
 * rows' times; the files read back with the run's particle count. The
 * state at a snapshot's own time is the one a run ending there reaches
 * with its last step cut to land on it (an independent run to 0.025 s
 * with the same rows until then: byte for byte the same snapshot and
 * walls), and the run's path is untouched by it (energy.csv byte for
 * byte that of the run without snapshots). */
START_TEST(test_run_times) {
  char dir[] = "/tmp/vsph_pvdXXXXXX", args[700], path[700], other[700];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  static const char *const RUNS[3][2] = {
      {"r", "--t-end 0.1 --outputs 8 --snapshots 4"},
      {"none", "--t-end 0.1 --outputs 8 --snapshots 0"},
      {"short", "--t-end 0.025 --outputs 2 --snapshots 1"}};
  for (int k = 0; k < 3; k++) {
    snprintf(args, sizeof args,
             "run standing-wave --res 10 %s --out %s/%s --quiet", RUNS[k][1],
             dir, RUNS[k][0]);
    struct vsph_test_outcome *o = vsph_test_cli(args);
    ck_assert_msg(o->status == 0, "%s", o->err);
  }
  static char csv[1 << 16], pvd[1 << 14];
  snprintf(path, sizeof path, "%s/r/energy.csv", dir);
  vsph_test_slurp(path, csv, sizeof csv);
  snprintf(path, sizeof path, "%s/r/snapshots.pvd", dir);
  vsph_test_slurp(path, pvd, sizeof pvd);
  char rows[16][32];
  size_t nrows = 0;
  for (const char *l = strchr(csv, '\n'); l && l[1]; l = strchr(l + 1, '\n')) {
    ck_assert_uint_lt(nrows, 16);
    const size_t w = strcspn(l + 1, ",");
    snprintf(rows[nrows++], sizeof rows[0], "%.*s", (int)w, l + 1);
  }
  ck_assert_uint_eq(nrows, 9); /* t = 0 and 8 outputs */
  static const char *const WANT[] = {"0", "0.025", "0.05", "0.075", "0.1"};
  size_t nsnap = 0, nwalls = 0; /* part 1: the walls of the snapshot before */
  char last_ts[32] = "";
  for (const char *d = pvd; (d = strstr(d, "timestep=\"")) != NULL; nsnap++) {
    d += 10;
    char ts[32], file[64];
    snprintf(ts, sizeof ts, "%.*s", (int)strcspn(d, "\""), d);
    const char *fa = strstr(d, "file=\"") + 6;
    snprintf(file, sizeof file, "%.*s", (int)strcspn(fa, "\""), fa);
    if (!strncmp(strstr(d, "part=\"") + 6, "1\"", 2)) {
      ck_assert_str_eq(ts, last_ts); /* at its snapshot's time */
      ck_assert(!strncmp(file, "walls_", 6));
      nwalls++;
      nsnap--;
      continue;
    }
    ck_assert_uint_lt(nsnap, 5);
    ck_assert_str_eq(ts, WANT[nsnap]);
    size_t r = 0;
    while (r < nrows && strcmp(rows[r], ts)) r++;
    /* the first and the last are rows' times, the others between rows */
    ck_assert_msg((r < nrows) == (nsnap == 0 || nsnap == 4),
                  "snapshot %zu at %s: a row's time %d", nsnap, ts, r < nrows);
    snprintf(last_ts, sizeof last_ts, "%s", ts);
    snprintf(path, sizeof path, "%s/r/%s", dir, file);
    struct vsph_vtk_snapshot s;
    ck_assert_int_eq(vsph_vtk_read(path, &s), 0);
    ck_assert(s.t == strtod(ts, NULL)); /* the round value's double */
    ck_assert_uint_eq(s.vort_ncomp, 1);
    ck_assert_uint_gt(s.n, 50);
    vsph_vtk_snapshot_free(&s);
  }
  ck_assert_uint_eq(nsnap, 5);                /* t = 0 and 4 snapshots */
  ck_assert_uint_eq(nwalls, 5);               /* the tank beside each */
  ck_assert_str_eq(last_ts, rows[nrows - 1]); /* the end is a snapshot */
  static const char *const SAME[] = {"snap", "walls"};
  for (int k = 0; k < 2; k++) {
    snprintf(path, sizeof path, "%s/r/%s_0001.vtp", dir, SAME[k]);
    snprintf(other, sizeof other, "%s/short/%s_0001.vtp", dir, SAME[k]);
    ck_assert_msg(same_bytes(path, other), "%s differs from %s", path, other);
  }
  snprintf(path, sizeof path, "%s/r/energy.csv", dir);
  snprintf(other, sizeof other, "%s/none/energy.csv", dir);
  ck_assert_msg(same_bytes(path, other), "snapshots moved the run's path");
  snprintf(args, sizeof args, "rm -rf '%s'", dir);
  ck_assert_int_eq(system(args), 0);
}
END_TEST

/* The path untouched by snapshots under each integrator and on each kind
 * of snapshot: RK4 with snapshots within steps (the standing wave, and
 * with a fixed dt of 0.005 s, snapshots at 0.025 k on step ends with no
 * row there), the leapfrog (Poiseuille) and the transport velocity's
 * kick-drift-kick (the cavity with Adami's walls): energy.csv and the
 * last snapshot (every double exact) byte for byte those of the run with
 * one snapshot; every snapshot at its round time, its pressures the law
 * of state's p = c0^2 (rho - rho0) of its own densities (a snapshot that
 * showed its step's last stage would not be: the referee's finding). */
static const char *const PATH_CASES[][2] = {
    {"standing-wave", "--res 10 --t-end 0.1 --outputs 7"},
    {"standing-wave", "--res 10 --dt 0.005 --t-end 0.1 --outputs 5"},
    {"poiseuille",
     "--res 8 --t-end 0.05 --outputs 7 --set "
     "Solver:integrator=leapfrog"},
    {"cavity",
     "--res 8 --t-end 0.05 --outputs 7 --set Solver:tvf=1 --set "
     "Scene:walls=adami"}};
enum { NPATH = sizeof PATH_CASES / sizeof PATH_CASES[0] };

START_TEST(test_snapshots_leave_path) {
  char dir[] = "/tmp/vsph_pathXXXXXX", args[800], a[700], b[700];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  static const char *const SNAPS[2] = {"4", "1"};
  for (int k = 0; k < 2; k++) {
    snprintf(args, sizeof args, "run %s %s --snapshots %s --out %s/s%s --quiet",
             PATH_CASES[_i][0], PATH_CASES[_i][1], SNAPS[k], dir, SNAPS[k]);
    struct vsph_test_outcome *o = vsph_test_cli(args);
    ck_assert_msg(o->status == 0, "%s: %s", args, o->err);
  }
  snprintf(a, sizeof a, "%s/s4/energy.csv", dir);
  snprintf(b, sizeof b, "%s/s1/energy.csv", dir);
  ck_assert_msg(same_bytes(a, b), "%s: snapshots moved the path",
                PATH_CASES[_i][1]);
  snprintf(a, sizeof a, "%s/s4/snap_0004.vtp", dir);
  snprintf(b, sizeof b, "%s/s1/snap_0001.vtp", dir);
  ck_assert_msg(same_bytes(a, b), "%s: the last snapshots differ",
                PATH_CASES[_i][1]);
  /* t_end / 4 apart: the double nearest each round decimal */
  const double t_end = strstr(PATH_CASES[_i][1], "0.05 ") ? 0.05 : 0.1;
  for (int k = 0; k <= 4; k++) {
    snprintf(a, sizeof a, "%s/s4/snap_%04d.vtp", dir, k);
    struct vsph_vtk_snapshot sn;
    ck_assert_int_eq(vsph_vtk_read(a, &sn), 0);
    char want[32];
    snprintf(want, sizeof want, "%.15g", t_end * k / 4.0);
    ck_assert_msg(sn.t == strtod(want, NULL), "%s: snapshot %d at %.17g",
                  PATH_CASES[_i][1], k, sn.t);
    /* the law of state through the first particle's density and
     * pressure: dp/drho the same for every particle to rounding (the
     * slope c0^2 itself differs by scene and law) */
    double lo = INFINITY, hi = -INFINITY;
    for (size_t i = 1; i < sn.n; i++) {
      const double dr = sn.rho[i] - sn.rho[0];
      if (fabs(dr) < 1e-9 * sn.rho[0]) continue;
      const double c2 = (sn.p[i] - sn.p[0]) / dr;
      lo = fmin(lo, c2);
      hi = fmax(hi, c2);
    }
    /* a linear law (every case here): one slope; the rounding of p over
     * density differences of at least 1e-9 rho0 is about 1e-9 relative
     * (|rho - rho0| <= 0.01 rho0), 1e-4 leaves room */
    if (lo <= hi)
      ck_assert_msg(hi - lo <= 1e-4 * fabs(hi),
                    "%s: snapshot %d's pressures are not its densities' "
                    "(dp/drho %g to %g)",
                    PATH_CASES[_i][1], k, lo, hi);
    vsph_vtk_snapshot_free(&sn);
  }
  snprintf(args, sizeof args, "rm -rf '%s'", dir);
  ck_assert_int_eq(system(args), 0);
}
END_TEST

/* A snapshot whose vector arrays span 30 blocks, more than a wave of the
 * compression (8 blocks a thread) on 1 and 3 threads: read back bitwise,
 * the same bytes on both, and nothing but the file left in the folder. */
START_TEST(test_compression_waves_thread_independent) {
  struct fixture fx;
  fixture_make(&fx, 2, 40000, 0);
  char dir[] = "/tmp/vsph_wavesXXXXXX", a[64], b[64];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  snprintf(a, sizeof a, "%s/a.vtp", dir);
  snprintf(b, sizeof b, "%s/b.vtp", dir);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  ck_assert_int_eq(vsph_vtk_write(dir, "a.vtp", fx.p, fx.n, fx.t, &fx.dg, NULL),
                   0);
  omp_set_num_threads(3);
  ck_assert_int_eq(vsph_vtk_write(dir, "b.vtp", fx.p, fx.n, fx.t, &fx.dg, NULL),
                   0);
  omp_set_num_threads(threads);
  ck_assert(same_bytes(a, b));
  struct vsph_vtk_snapshot s;
  ck_assert_int_eq(vsph_vtk_read(a, &s), 0);
  ck_assert_uint_eq(s.n, fx.n);
  for (size_t i = 0; i < fx.p->n; i++) {
    const size_t k = fx.p->id[i];
    if (k >= fx.n) continue;
    for (int c = 0; c < 2; c++) {
      ck_assert(s.pos[3 * k + c] == fx.p->pos[c][i]);
      ck_assert(s.vel[3 * k + c] == fx.p->vel[c][i]);
    }
    ck_assert(s.rho[k] == fx.p->rho[i]);
  }
  vsph_vtk_snapshot_free(&s);
  ck_assert_int_eq(remove(b), 0);
  clean_case(&fx, dir, a);
}
END_TEST

/* Snapshots within steps keep the step's start in a scratch file in
 * TMPDIR, or in memory where none can be made there: the same files
 * either way (every snapshot, energy.csv), and nothing left in TMPDIR. */
START_TEST(test_kept_state_place) {
  char dir[] = "/tmp/vsph_keptXXXXXX", tmp[64], args[400], a[300], b[300];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  snprintf(tmp, sizeof tmp, "%s/tmp", dir);
  ck_assert_int_eq(mkdir(tmp, 0700), 0);
  const char *was = getenv("TMPDIR");
  char *old_tmp = was ? strdup(was) : NULL;
  static const char *const where[2] = {"file", "memory"};
  for (int k = 0; k < 2; k++) {
    char bad[80];
    snprintf(bad, sizeof bad, "%s/none/here", dir);
    setenv("TMPDIR", k ? bad : tmp, 1);
    snprintf(args, sizeof args,
             "run standing-wave --res 10 --t-end 0.1 --outputs 5 --snapshots "
             "3 --out %s/%s --quiet",
             dir, where[k]);
    struct vsph_test_outcome *o = vsph_test_cli(args);
    ck_assert_msg(o->status == 0, "%s: %s", args, o->err);
  }
  static const char *const files[] = {"energy.csv", "snap_0001.vtp",
                                      "snap_0002.vtp", "snap_0003.vtp"};
  for (size_t q = 0; q < sizeof files / sizeof files[0]; q++) {
    snprintf(a, sizeof a, "%s/file/%s", dir, files[q]);
    snprintf(b, sizeof b, "%s/memory/%s", dir, files[q]);
    ck_assert_msg(same_bytes(a, b), "%s differs", files[q]);
  }
  ck_assert_int_eq(rmdir(tmp), 0); /* empty: the scratch file unlinked */
  /* and where the state waits, seen from the run itself: at the first
   * snapshot within a step, in a file where TMPDIR can hold one, else in
   * memory */
  for (int k = 0; k < 2; k++) {
    if (!k) ck_assert_int_eq(mkdir(tmp, 0700), 0);
    setenv("TMPDIR", k ? "/nonexistent/vsph" : tmp, 1);
    static const char *const set[] = {"Solver:res=10", "Solver:t_end=0.1",
                                      "Solver:outputs=5", "Solver:snapshots=3",
                                      NULL};
    struct vsph_run *run =
        vsph_test_run(vsph_scene_find("standing-wave"), set, NULL);
    while (!run->side && !run->side_file && run->state == VSPH_RUN_RUNNING)
      ck_assert_int_eq(vsph_run_iterate(run), 0);
    ck_assert_msg(
        k ? run->side && !run->side_file : run->side_file && !run->side,
        "the kept state is not in %s", where[k]);
    vsph_run_free(run);
    if (!k) ck_assert_int_eq(rmdir(tmp), 0);
  }
  if (old_tmp) {
    setenv("TMPDIR", old_tmp, 1);
    free(old_tmp);
  } else {
    unsetenv("TMPDIR");
  }
  snprintf(args, sizeof args, "rm -rf '%s'", dir);
  ck_assert_int_eq(system(args), 0);
}
END_TEST

/* A run's walls file types its particles: the cavity's Adami walls and
 * lid are wall particles (1), none an image (2); the standing wave's
 * mirror ghosts are all images. */
START_TEST(test_walls_typed) {
  char dir[] = "/tmp/vsph_typedXXXXXX", args[400], path[300];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  static const char *const runs[2][2] = {
      {"cavity", "--set Scene:walls=adami --set Solver:tvf=1"},
      {"standing-wave", ""}};
  for (int k = 0; k < 2; k++) {
    snprintf(args, sizeof args,
             "run %s --res 8 --t-end 0.01 --snapshots 1 --outputs 1 %s "
             "--out %s/%d --quiet",
             runs[k][0], runs[k][1], dir, k);
    struct vsph_test_outcome *o = vsph_test_cli(args);
    ck_assert_msg(o->status == 0, "%s: %s", args, o->err);
    snprintf(path, sizeof path, "%s/%d/walls_0001.vtp", dir, k);
    int nc = 0;
    size_t n = 0;
    double *type = vsph_test_vtp_values(path, "type", &nc, &n);
    ck_assert_ptr_nonnull(type);
    ck_assert_uint_gt(n, 0);
    for (size_t i = 0; i < n; i++)
      ck_assert_msg(type[i] == (k ? 2.0 : 1.0), "%s: particle %zu typed %g",
                    runs[k][0], i, type[i]);
    free(type);
  }
  snprintf(args, sizeof args, "rm -rf '%s'", dir);
  ck_assert_int_eq(system(args), 0);
}
END_TEST

Suite *vsph_vtk_suite(void) {
  Suite *s = suite_create("vtk");
  TCase *tc = tcase_create("snapshots");
  tcase_set_timeout(tc, 20);
  tcase_add_loop_test(tc, test_snapshot_reads_back_bitwise, 0, NCASES);
  tcase_add_test(tc, test_walls_file_in_id_order_typed);
  tcase_add_loop_test(tc, test_frame_rounds_to_mantissa_bits, 0, NCASES);
  tcase_add_test(tc, test_frame_rounding);
  tcase_add_loop_test(tc, test_file_layout_decoded_bitwise, 0, NCASES);
  tcase_add_loop_test(tc, test_threads_and_stop, 0, NCASES);
  tcase_add_loop_test(tc, test_descriptions_name_every_array, 0, NCASES);
  tcase_add_test(tc, test_read_refuses_damaged_files);
  tcase_add_test(tc, test_run_times);
  tcase_add_test(tc, test_compression_waves_thread_independent);
  tcase_add_test(tc, test_kept_state_place);
  tcase_add_test(tc, test_walls_typed);
  tcase_add_loop_test(tc, test_snapshots_leave_path, 0, NPATH);
  suite_add_tcase(s, tc);
  return s;
}
