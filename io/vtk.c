/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "vtk.h"

#include <errno.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <zlib.h>

#include "../common/scratch.h"
#include "../common/status.h"
#include "../solver/diagnostics.h"
#include "../solver/particles.h"
#include "files.h"

/* zlib's level 1: on a 4900-particle standing-wave snapshot (555 kB of
 * arrays) it compresses within 1 % of levels 6 and 9 (doubles leave
 * deflate little beyond the zeros and the repeated high bytes) in 13 ms
 * against 34 ms and 275 ms (measured 2026-11-25). */
enum { LEVEL = 1 };

/* A frame's level, 9: written once, for an archive, so its size counts
 * rather than its time (measured: FRAME_LEVEL_NOTE). */
enum { FRAME_LEVEL = 9 };

/* The arrays of one file: 2 FieldData, Points, 2 Verts, at most 9
 * PointData. */
enum { MAX_ARRAYS = 16, DESC_LEN = 4096 };

/* What follows the appended block. */
#define TRAILER "\n</AppendedData>\n</VTKFile>\n"

/* Where an array goes in the XML. */
enum section { FIELD, POINTS, VERTS, POINT_DATA };

/* One array of the file being written. */
struct entry {
  enum section sec;
  const char *name, *type; /* VTK's type name: Float64, Int64, UInt8, String */
  int ncomp;
  size_t ntuples; /* FieldData: tuples (PointData has NumberOfPoints) */
  size_t offset;  /* of its compressed data in the appended block */
};

/* A file being assembled: the appended block (every array compressed in
 * VTK's layout) as it is made, in a scratch file of the folder it goes to
 * (unlinked at once: nothing stays behind), so that no more than a few
 * blocks of it are held in memory; the list of arrays, and their
 * descriptions, each "name: what (unit)" and NUL-terminated as VTK
 * stores a string array. */
struct out {
  const char *dir;  /* where the file and its scratch go */
  FILE *spill;      /* the appended block so far, len bytes */
  size_t len;       /* (opened by the first array) */
  unsigned char *z; /* a wave of compressed blocks, zcap bytes */
  size_t zcap;
  unsigned char *raw; /* a wave of a gathered array, rawcap bytes */
  size_t rawcap;
  char *spill_path; /* the scratch file's name where it could not be
                       unlinked at once, else NULL */
  struct entry e[MAX_ARRAYS];
  size_t ne;
  char desc[DESC_LEN];
  size_t desc_len, ndesc;
  const volatile sig_atomic_t *stop; /* NULL, or stop when set */
  size_t nverts;                     /* vertex cells: n, or 0 (a frame) */
  int level;                         /* zlib's: LEVEL, or FRAME_LEVEL */
  int no_scalars, no_vectors;        /* a frame without pressure, velocity */
};

/* Blocks compressed at once: a few for each thread, so that the threads
 * share the work while only these blocks are held. */
static size_t wave_blocks(void) { return 8 * (size_t)omp_get_max_threads(); }

/* Where a gathered array's elements come from (struct src): element k,
 * the particle order[k] (k itself where order is NULL). */
struct src {
  void (*fill)(const struct src *s, size_t e0, size_t ne, void *out);
  size_t esz;               /* bytes an element */
  const size_t *order;      /* particles in the file's order, or NULL */
  const double *const *vec; /* a vector's 3 components (NULL: 0) */
  const double *v, *w;      /* a scalar field (w: the volume's rho) */
  const unsigned char *u8;  /* a byte field */
  const size_t *ids;        /* ids, written as Int64 */
  size_t limit;             /* walls' type: 1 below it, else 2 */
  double c;                 /* a constant */
};

static size_t elem_at(const struct src *s, size_t k) {
  return s->order ? s->order[k] : k;
}

static void fill_vec(const struct src *s, size_t e0, size_t ne, void *out) {
  double *x = out;
  for (size_t k = 0; k < ne; k++)
    for (int a = 0; a < 3; a++)
      x[3 * k + a] = s->vec[a] ? s->vec[a][elem_at(s, e0 + k)] : 0.0;
}

static void fill_scalar(const struct src *s, size_t e0, size_t ne, void *out) {
  double *x = out;
  for (size_t k = 0; k < ne; k++) x[k] = s->v[elem_at(s, e0 + k)];
}

static void fill_volume(const struct src *s, size_t e0, size_t ne, void *out) {
  double *x = out;
  for (size_t k = 0; k < ne; k++) {
    const size_t i = elem_at(s, e0 + k);
    x[k] = s->v[i] / s->w[i];
  }
}

static void fill_const(const struct src *s, size_t e0, size_t ne, void *out) {
  (void)e0;
  double *x = out;
  for (size_t k = 0; k < ne; k++) x[k] = s->c;
}

static void fill_u8(const struct src *s, size_t e0, size_t ne, void *out) {
  unsigned char *x = out;
  for (size_t k = 0; k < ne; k++) x[k] = s->u8[elem_at(s, e0 + k)];
}

/* vertex cells: element k is k + c (the connectivity c = 0, the offsets
 * c = 1), and the fluid's id (c = 0) */
static void fill_iota(const struct src *s, size_t e0, size_t ne, void *out) {
  int64_t *x = out;
  for (size_t k = 0; k < ne; k++) x[k] = (int64_t)(e0 + k) + (int64_t)s->c;
}

static void fill_ids(const struct src *s, size_t e0, size_t ne, void *out) {
  int64_t *x = out;
  for (size_t k = 0; k < ne; k++) x[k] = (int64_t)s->ids[elem_at(s, e0 + k)];
}

static void fill_type(const struct src *s, size_t e0, size_t ne, void *out) {
  unsigned char *x = out;
  for (size_t k = 0; k < ne; k++)
    x[k] = s->ids[elem_at(s, e0 + k)] < s->limit ? 1 : 2;
}

/* Append @p nbytes at @p raw as one array in the layout of
 * vtkZLibDataCompressor with header_type UInt64: [number of blocks]
 * [block size][size of the last block if partial, else 0][compressed size
 * of each block], then each block deflated on its own. The blocks are
 * compressed in parallel a wave at a time, each into its own slot, then
 * written in order (the header's sizes filled in at the end): the bytes do
 * not depend on the threads. VSPH_EINTR when *o->stop is set (checked
 * before each block; the file is then not written). */
static int add(struct out *o, enum section sec, const char *name,
               const char *type, int ncomp, size_t ntuples, const void *raw,
               const struct src *src, size_t nbytes) {
  const volatile sig_atomic_t *stop = o->stop;
  VSPH_ASSERT(o->ne < MAX_ARRAYS);
  if (!o->spill &&
      !(o->spill = vsph_scratch_open(o->dir, VSPH_VTK_SCRATCH, &o->spill_path)))
    VSPH_FAIL(VSPH_EIO, "cannot write a snapshot's scratch file in %s: %s",
              o->dir, strerror(errno));
  const size_t nblocks = (nbytes + VSPH_VTK_BLOCK - 1) / VSPH_VTK_BLOCK;
  const size_t slot = compressBound(VSPH_VTK_BLOCK);
  const size_t wave = nblocks < wave_blocks() ? nblocks : wave_blocks();
  if (wave * slot > o->zcap) {
    unsigned char *z = realloc(o->z, wave * slot);
    if (!z) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a snapshot's %s", name);
    o->z = z;
    o->zcap = wave * slot;
  }
  /* a gathered array: a wave's bytes at a time, from the elements that
   * hold them (an element may straddle two waves) */
  const size_t rawneed = src ? wave * VSPH_VTK_BLOCK + 2 * src->esz : 0;
  if (rawneed > o->rawcap) {
    unsigned char *r = realloc(o->raw, rawneed);
    if (!r) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a snapshot's %s", name);
    o->raw = r;
    o->rawcap = rawneed;
  }
  uint64_t *zl = calloc(3 + nblocks, sizeof *zl);
  if (!zl) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a snapshot's %s", name);
  zl[0] = nblocks;
  zl[1] = VSPH_VTK_BLOCK;
  zl[2] = nbytes % VSPH_VTK_BLOCK;
  const size_t at = o->len, head = (3 + nblocks) * sizeof *zl;
  /* the header's place, its sizes filled in once known */
  int st = fwrite(zl, 1, head, o->spill) == head ? VSPH_OK : VSPH_EIO;
  size_t len = head;
  for (size_t w0 = 0; w0 < nblocks && !st; w0 += wave) {
    const size_t nw = nblocks - w0 < wave ? nblocks - w0 : wave;
    const size_t lo = w0 * VSPH_VTK_BLOCK;
    const unsigned char *in0 = (const unsigned char *)raw + lo;
    if (src) {
      const size_t hi =
          lo + nw * VSPH_VTK_BLOCK < nbytes ? lo + nw * VSPH_VTK_BLOCK : nbytes;
      const size_t e0 = lo / src->esz, e1 = (hi + src->esz - 1) / src->esz;
      src->fill(src, e0, e1 - e0, o->raw);
      in0 = o->raw + (lo - e0 * src->esz);
    }
    int bad = 0; /* a zlib failure (the lowest such block's status) */
#pragma omp parallel for schedule(dynamic, 1) reduction(min : bad)
    for (size_t b = 0; b < nw; b++) {
      if (stop && *stop) continue; /* a flag only ever raised: seen below */
      const size_t g = w0 + b;
      const size_t in =
          g + 1 < nblocks ? VSPH_VTK_BLOCK : nbytes - g * VSPH_VTK_BLOCK;
      uLongf zlen = (uLongf)slot;
      const int zs = compress2(o->z + b * slot, &zlen, in0 + b * VSPH_VTK_BLOCK,
                               (uLong)in, o->level);
      if (zs != Z_OK && zs < bad) bad = zs;
      zl[3 + g] = zlen;
    }
    if (bad) {
      free(zl);
      VSPH_FAIL(VSPH_ELIB, "zlib cannot compress %s: %s", name, zError(bad));
    }
    if (stop && *stop) {
      free(zl);
      return VSPH_EINTR;
    }
    for (size_t b = 0; b < nw && !st; b++) { /* in order */
      const size_t zb = (size_t)zl[3 + w0 + b];
      if (fwrite(o->z + b * slot, 1, zb, o->spill) != zb) st = VSPH_EIO;
      len += zb;
    }
  }
  if (!st && (fseeko(o->spill, (off_t)(at + 3 * sizeof *zl), SEEK_SET) ||
              fwrite(zl + 3, sizeof *zl, nblocks, o->spill) != nblocks ||
              fseeko(o->spill, 0, SEEK_END)))
    st = VSPH_EIO;
  free(zl);
  if (st)
    VSPH_FAIL(VSPH_EIO, "cannot write a snapshot's %s to its scratch file: %s",
              name, strerror(errno));
  o->e[o->ne++] = (struct entry){sec, name, type, ncomp, ntuples, at};
  o->len = at + len;
  return VSPH_OK;
}

/* An array of @p nbytes held whole at @p raw. */
static int add_array(struct out *o, enum section sec, const char *name,
                     const char *type, int ncomp, size_t ntuples,
                     const void *raw, size_t nbytes) {
  return add(o, sec, name, type, ncomp, ntuples, raw, NULL, nbytes);
}

/* A PointData (or Points, Verts) array of @p n elements gathered from
 * @p src a wave at a time: never held whole. */
static int add_gathered(struct out *o, enum section sec, const char *name,
                        const char *type, int ncomp, const struct src *src,
                        size_t n) {
  return add(o, sec, name, type, ncomp, 0, NULL, src, n * src->esz);
}

/* Describe array @p name: "name: what (unit)". A unit ending in '^' takes
 * the dimension (kg/m^2 in 2-D, per unit depth). */
static void describe(struct out *o, const char *name, const char *what,
                     const char *unit, int dim) {
  const size_t room = sizeof o->desc - o->desc_len;
  const size_t u = strlen(unit);
  const int w = u && unit[u - 1] == '^'
                    ? snprintf(o->desc + o->desc_len, room, "%s: %s (%s%d)",
                               name, what, unit, dim)
                    : snprintf(o->desc + o->desc_len, room, "%s: %s (%s)", name,
                               what, unit);
  VSPH_ASSERT(w > 0 && (size_t)w < room);
  if (w > 0 && (size_t)w < room) {
    o->desc_len += (size_t)w + 1; /* the NUL ends the string */
    o->ndesc++;
  }
}

/* The arrays every particle file opens with, described: the time, the
 * points (in @p order) and one vertex cell per point; @p what gives the
 * three descriptions. */
static int add_geometry(struct out *o, const struct vsph_particles *p,
                        const size_t *order, size_t n, double t,
                        const char *const what[3]) {
  const int d = p->dim;
  const double *pos[3] = {p->pos[0], d > 1 ? p->pos[1] : NULL,
                          d > 2 ? p->pos[2] : NULL};
  int st = add_array(o, FIELD, "TimeValue", "Float64", 1, 1, &t, sizeof t);
  describe(o, "TimeValue", what[0], "s", d);
  const struct src xs = {
      .fill = fill_vec, .esz = 3 * sizeof(double), .order = order, .vec = pos};
  if (!st) st = add_gathered(o, POINTS, "Points", "Float64", 3, &xs, n);
  describe(o, "Points", what[1], "m", d);
  const struct src conn = {.fill = fill_iota, .esz = sizeof(int64_t)},
                   offs = {.fill = fill_iota, .esz = sizeof(int64_t), .c = 1};
  if (!st) st = add_gathered(o, VERTS, "connectivity", "Int64", 1, &conn, n);
  if (!st) st = add_gathered(o, VERTS, "offsets", "Int64", 1, &offs, n);
  describe(o, "connectivity, offsets", what[2], "dimensionless", d);
  return st;
}

/* The particles' state after the geometry, described: velocity, density,
 * pressure, volume and mass, gathered in @p order. */
static int add_state(struct out *o, const struct vsph_particles *p,
                     const size_t *order, size_t n) {
  const int d = p->dim;
  const size_t e8 = sizeof(double);
  int st = VSPH_OK;
  const double *vel[3] = {p->vel[0], d > 1 ? p->vel[1] : NULL,
                          d > 2 ? p->vel[2] : NULL};
  const struct src us = {
      .fill = fill_vec, .esz = 3 * e8, .order = order, .vec = vel};
  if (!st) st = add_gathered(o, POINT_DATA, "velocity", "Float64", 3, &us, n);
  describe(o, "velocity", "velocity u_x, u_y, u_z (u_z = 0 in 2-D)", "m/s", d);
  const struct src rho = {
      .fill = fill_scalar, .esz = e8, .order = order, .v = p->rho};
  if (!st) st = add_gathered(o, POINT_DATA, "density", "Float64", 1, &rho, n);
  describe(o, "density", "density rho, per unit depth in 2-D", "kg/m^", d);
  const struct src pr = {
      .fill = fill_scalar, .esz = e8, .order = order, .v = p->p};
  if (!st) st = add_gathered(o, POINT_DATA, "pressure", "Float64", 1, &pr, n);
  describe(o, "pressure", "pressure p from the state equation", "Pa", d);
  const struct src vol = {
      .fill = fill_volume, .esz = e8, .order = order, .v = p->m, .w = p->rho};
  if (!st) st = add_gathered(o, POINT_DATA, "volume", "Float64", 1, &vol, n);
  describe(o, "volume", "particle volume m/rho", "m^", d);
  const struct src ms = {
      .fill = fill_scalar, .esz = e8, .order = order, .v = p->m};
  if (!st) st = add_gathered(o, POINT_DATA, "mass", "Float64", 1, &ms, n);
  describe(o, "mass", "particle mass m (per unit depth in 2-D)",
           d == 3   ? "kg"
           : d == 2 ? "kg/m"
                    : "kg/m^",
           2);
  return st;
}

/* The arrays that only some snapshots have, described: with diagnostics
 * @p dg (or NULL) the smoothing length, vorticity, div_r and the free
 * surface; the material index of a two-material run. */
static int add_extras(struct out *o, const struct vsph_particles *p,
                      const size_t *order, size_t n,
                      const struct vsph_diagnostics *dg) {
  const int d = p->dim;
  const size_t n8 = n * sizeof(double), e8 = sizeof(double);
  int st = VSPH_OK;
  if (dg) {
    const struct src hs = {.fill = fill_const, .esz = e8, .c = dg->h};
    if (!st)
      st =
          add_gathered(o, POINT_DATA, "smoothing_length", "Float64", 1, &hs, n);
    describe(o, "smoothing_length",
             "smoothing length h (the same for every particle; the kernel "
             "reaches kappa h)",
             "m", 1);
  }
  if (p->mat) {
    const struct src mat = {
        .fill = fill_u8, .esz = 1, .order = order, .u8 = p->mat};
    if (!st) st = add_gathered(o, POINT_DATA, "material", "UInt8", 1, &mat, n);
    describe(o, "material",
             "material index: 0 the first fluid, 1 the second fluid or the "
             "held body (two-material contact runs)",
             "dimensionless", d);
  }
  if (dg && d == 2) { /* indexed by id already: written as it is */
    if (!st)
      st = add_array(o, POINT_DATA, "vorticity_z", "Float64", 1, 0, dg->vort[2],
                     n8);
    describe(o, "vorticity_z",
             "SPH vorticity omega_z = sum_j V_j (grad_i W_ij x (u_j - u_i))_z, "
             "signed: positive counter-clockwise",
             "1/s", d);
  }
  if (dg && d == 3) {
    const double *w[3] = {dg->vort[0], dg->vort[1], dg->vort[2]};
    const struct src ws = {.fill = fill_vec, .esz = 3 * e8, .vec = w};
    if (!st)
      st = add_gathered(o, POINT_DATA, "vorticity", "Float64", 3, &ws, n);
    describe(o, "vorticity",
             "SPH vorticity omega = sum_j V_j grad_i W_ij x (u_j - u_i)", "1/s",
             d);
  }
  if (dg) {
    if (!st)
      st = add_array(o, POINT_DATA, "div_r", "Float64", 1, 0, dg->divr, n8);
    describe(o, "div_r",
             "divergence of the position, sum_j V_j (r_j - r_i).grad_i W_ij: "
             "the dimension inside the fluid (to the lattice error), about "
             "half of it at a free surface (docs/theory.md section 6)",
             "dimensionless", d);
    if (!st)
      st = add_array(o, POINT_DATA, "free_surface", "UInt8", 1, 0, dg->surf, n);
    char what[160];
    snprintf(what, sizeof what,
             "free-surface flag: 1 where div_r < %g (Lee et al. 2008), else 0",
             vsph_diagnostics_surface_threshold(d));
    describe(o, "free_surface", what, "dimensionless", d);
  }
  return st;
}

/* The arrays of the snapshot into o, described. */
static int build(struct out *o, const struct vsph_particles *p,
                 const size_t *order, size_t n, double t,
                 const struct vsph_diagnostics *dg) {
  const int d = p->dim;
  static const char *const geometry[3] = {
      "time of the snapshot, the exact double (snapshots.pvd and energy.csv "
      "print it to 10 significant digits)",
      "particle positions x, y, z (z = 0 in 2-D)",
      "one vertex cell per particle, so that every representation shows it"};
  int st = add_geometry(o, p, order, n, t, geometry);
  if (!st) st = add_state(o, p, order, n);
  if (!st) st = add_extras(o, p, order, n, dg);
  const struct src ids = {.fill = fill_iota, .esz = sizeof(int64_t)};
  if (!st) st = add_gathered(o, POINT_DATA, "id", "Int64", 1, &ids, n);
  describe(o, "id",
           "particle id, its index in the initial set; the points are in id "
           "order",
           "dimensionless", d);
  if (!st)
    st = add_array(o, FIELD, "array_descriptions", "String", 1, o->ndesc,
                   o->desc, o->desc_len);
  return st;
}

static const char *host_byte_order(void) {
  const uint16_t one = 1;
  unsigned char first;
  memcpy(&first, &one, 1);
  return first ? "LittleEndian" : "BigEndian";
}

static void write_tag(FILE *f, const struct entry *e) {
  if (e->sec == FIELD)
    fprintf(f,
            "<%s type=\"%s\" Name=\"%s\" NumberOfTuples=\"%zu\" "
            "format=\"appended\" offset=\"%zu\"/>\n",
            strcmp(e->type, "String") ? "DataArray" : "Array", e->type, e->name,
            e->ntuples, e->offset);
  else
    fprintf(f,
            "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
            "format=\"appended\" offset=\"%zu\"/>\n",
            e->type, e->name, e->ncomp, e->offset);
}

static void write_section(FILE *f, const struct out *o, enum section sec) {
  for (size_t k = 0; k < o->ne; k++)
    if (o->e[k].sec == sec) write_tag(f, &o->e[k]);
}

/* The XML header (the descriptions also as a comment, for a reader of the
 * text), then the appended block, copied from its scratch file.
 * VSPH_OK or VSPH_EIO (the scratch file unreadable). */
static int write_file(FILE *f, const struct out *o, size_t n, double t) {
  fprintf(f,
          "<?xml version=\"1.0\"?>\n"
          "<!-- vsph particles at t = %.17g s. Arrays (FieldData "
          "array_descriptions holds the same):\n",
          t);
  for (const char *s = o->desc; s < o->desc + o->desc_len; s += strlen(s) + 1)
    fprintf(f, "  %s\n", s);
  fprintf(f,
          "-->\n"
          "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"%s\" "
          "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\">\n"
          "<PolyData>\n<FieldData>\n",
          host_byte_order());
  write_section(f, o, FIELD);
  fprintf(f,
          "</FieldData>\n"
          "<Piece NumberOfPoints=\"%zu\" NumberOfVerts=\"%zu\" "
          "NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
          "<PointData%s%s>\n",
          n, o->nverts, o->no_scalars ? "" : " Scalars=\"pressure\"",
          o->no_vectors ? "" : " Vectors=\"velocity\"");
  write_section(f, o, POINT_DATA);
  fprintf(f, "</PointData>\n<Points>\n");
  write_section(f, o, POINTS);
  fprintf(f, "</Points>\n<Verts>\n");
  write_section(f, o, VERTS);
  fprintf(f,
          "</Verts>\n</Piece>\n</PolyData>\n"
          "<AppendedData encoding=\"raw\">\n_");
  char chunk[1 << 16];
  size_t left = o->len;
  if (o->spill && fseeko(o->spill, 0, SEEK_SET)) return VSPH_EIO;
  while (left > 0) {
    const size_t want = left < sizeof chunk ? left : sizeof chunk;
    if (fread(chunk, 1, want, o->spill) != want) return VSPH_EIO;
    fwrite(chunk, 1, want, f);
    left -= want;
  }
  fputs(TRAILER, f);
  return VSPH_OK;
}

/* A file's arrays @p o (built, status @p st) written as DIR/NAME where
 * they were built whole, @p n points at time @p t; @p o freed (may be
 * NULL) either way. Returns the status. */
static int emit(struct out *o, int st, const char *dir, const char *name,
                size_t n, double t) {
  FILE *f = st ? NULL : vsph_files_open(dir, name);
  if (!st && !f) st = VSPH_EIO;
  if (!st && write_file(f, o, n, t)) {
    vsph_files_discard(f, dir, name);
    st = VSPH_EIO;
    vsph_status_report(st, __FILE__, __LINE__,
                       "cannot read back the scratch file of %s/%s", dir, name);
  } else if (!st) {
    st = vsph_files_close(f, dir, name);
  }
  if (o) {
    if (o->spill) fclose(o->spill);
    if (o->spill_path) unlink(o->spill_path);
    free(o->spill_path);
    free(o->z);
    free(o->raw);
  }
  free(o);
  return st;
}

/* The arrays of a file of @p n particles (vertex cells, snapshot level)
 * with its particle order. NULL, nothing held, where they cannot be had. */
static struct out *out_alloc(const char *dir, size_t n, size_t **order) {
  *order = malloc((n ? n : 1) * sizeof **order);
  struct out *o = calloc(1, sizeof *o);
  if (!*order || !o) {
    free(*order);
    free(o);
    return NULL;
  }
  o->dir = dir;
  o->nverts = n;
  o->level = LEVEL;
  return o;
}

int vsph_vtk_write(const char *dir, const char *name,
                   const struct vsph_particles *p, size_t n_fluid, double t,
                   const struct vsph_diagnostics *dg,
                   const volatile sig_atomic_t *stop) {
  if (!dir || !name || !p)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_write: a NULL argument");
  if (n_fluid > p->n || (dg && dg->n < n_fluid))
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_vtk_write: %zu fluid particles, more than the set's %zu "
              "or the diagnostics'",
              n_fluid, p->n);
  const size_t n = n_fluid;
  size_t *order;
  struct out *o = out_alloc(dir, n, &order);
  if (!o)
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a snapshot of %zu particles", n);
  o->stop = stop;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] < n) order[p->id[i]] = i;
  const int st = build(o, p, order, n, t, dg);
  free(order);
  return emit(o, st, dir, name, n, t);
}

int vsph_vtk_write_mapped(const char *dir, const char *name,
                          const struct vsph_particles *p, size_t n_fluid,
                          const size_t *where, double t,
                          const struct vsph_diagnostics *dg,
                          const volatile sig_atomic_t *stop) {
  if (!dir || !name || !p || !where)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_write_mapped: a NULL argument");
  if (dg && dg->n < n_fluid)
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_vtk_write_mapped: diagnostics of %zu particles, not %zu",
              dg->n, n_fluid);
  const size_t n = n_fluid;
  for (size_t id = 0; id < n; id++)
    if (where[id] >= p->n || p->id[where[id]] != id)
      VSPH_FAIL(VSPH_EINVAL,
                "vsph_vtk_write_mapped: fluid particle %zu is not where the "
                "map says",
                id);
  struct out *o = calloc(1, sizeof *o);
  if (!o)
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a snapshot of %zu particles", n);
  o->dir = dir;
  o->nverts = n;
  o->level = LEVEL;
  o->stop = stop;
  return emit(o, build(o, p, where, n, t, dg), dir, name, n, t);
}

/* ---- walls ---- */

int vsph_vtk_write_walls(const char *dir, const char *name,
                         const struct vsph_particles *p, size_t n_fluid,
                         size_t n_wall, double h, double t) {
  if (!dir || !name || !p)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_write_walls: a NULL argument");
  if (!(h > 0.0) || !isfinite(h))
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_write_walls: h = %g is not positive", h);
  /* the particles beyond the fluid, in id order */
  size_t n = 0;
  for (size_t i = 0; i < p->n; i++) n += p->id[i] >= n_fluid;
  size_t *order;
  struct out *o = out_alloc(dir, n, &order);
  if (!o) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the walls of a snapshot");
  size_t k = 0;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] >= n_fluid) order[k++] = i;
  for (size_t a = 1; a < n; a++) /* by id (few, nearly sorted already) */
    for (size_t b = a; b > 0 && p->id[order[b - 1]] > p->id[order[b]]; b--) {
      const size_t tmp = order[b];
      order[b] = order[b - 1];
      order[b - 1] = tmp;
    }
  const int d = p->dim;
  const size_t e8 = sizeof(double);
  static const char *const what[3] = {"time of the snapshot, the exact double",
                                      "positions x, y, z (z = 0 in 2-D)",
                                      "one vertex cell per particle"};
  int st = add_geometry(o, p, order, n, t, what);
  const double *vel[3] = {p->vel[0], d > 1 ? p->vel[1] : NULL,
                          d > 2 ? p->vel[2] : NULL};
  const struct src us = {
      .fill = fill_vec, .esz = 3 * e8, .order = order, .vec = vel};
  if (!st) st = add_gathered(o, POINT_DATA, "velocity", "Float64", 3, &us, n);
  describe(o, "velocity",
           "velocity: a wall particle's the wall's (the cavity's lid moves), "
           "an image's its fluid particle's, mirrored",
           "m/s", d);
  const struct src rho = {
      .fill = fill_scalar, .esz = e8, .order = order, .v = p->rho};
  if (!st) st = add_gathered(o, POINT_DATA, "density", "Float64", 1, &rho, n);
  describe(o, "density", "density rho, per unit depth in 2-D", "kg/m^", d);
  const struct src pr = {
      .fill = fill_scalar, .esz = e8, .order = order, .v = p->p};
  if (!st) st = add_gathered(o, POINT_DATA, "pressure", "Float64", 1, &pr, n);
  describe(o, "pressure", "pressure p", "Pa", d);
  const struct src ty = {.fill = fill_type,
                         .esz = 1,
                         .order = order,
                         .ids = p->id,
                         .limit = n_fluid + n_wall};
  const struct src ms = {
      .fill = fill_scalar, .esz = e8, .order = order, .v = p->m};
  if (!st) st = add_gathered(o, POINT_DATA, "mass", "Float64", 1, &ms, n);
  describe(o, "mass",
           "particle mass m (per unit depth in 2-D): a wall particle's as "
           "its wall gives it, an image's its fluid particle's",
           d == 3   ? "kg"
           : d == 2 ? "kg/m"
                    : "kg/m^",
           2);
  const struct src hs = {.fill = fill_const, .esz = e8, .c = h};
  if (!st)
    st = add_gathered(o, POINT_DATA, "smoothing_length", "Float64", 1, &hs, n);
  describe(o, "smoothing_length",
           "smoothing length h (the fluid's; the kernel reaches kappa h)", "m",
           1);
  if (!st) st = add_gathered(o, POINT_DATA, "type", "UInt8", 1, &ty, n);
  describe(o, "type",
           "1: a wall particle (fixed walls, the cavity's lid), 2: an image "
           "of a fluid particle (a mirror ghost or a periodic image)",
           "dimensionless", d);
  const struct src ids = {
      .fill = fill_ids, .esz = sizeof(int64_t), .order = order, .ids = p->id};
  if (!st) st = add_gathered(o, POINT_DATA, "id", "Int64", 1, &ids, n);
  describe(o, "id", "the particle's id (the fluid's ids come first)",
           "dimensionless", d);
  if (!st)
    st = add_array(o, FIELD, "array_descriptions", "String", 1, o->ndesc,
                   o->desc, o->desc_len);
  free(order);
  return emit(o, st, dir, name, n, t);
}

/* ---- frames ---- */

/* @p v in single precision rounded to nearest (ties away from zero) at
 * @p bits mantissa bits: the low 23 - bits bits of its pattern dropped
 * after adding half of the last kept one, a carry into the exponent
 * being the correct rounding up; NaN and infinities as they are. */
static float round_bits(double v, int bits) {
  float f = (float)v;
  if (bits >= 23 || !isfinite(f)) return f;
  uint32_t u;
  memcpy(&u, &f, sizeof u);
  const uint32_t drop = (uint32_t)(23 - bits);
  u = (u + (UINT32_C(1) << (drop - 1))) & ~((UINT32_C(1) << drop) - 1);
  memcpy(&f, &u, sizeof f);
  return f;
}

static int build_frame(struct out *o, const struct vsph_vtk_snapshot *s,
                       int bits, unsigned fields, float *x, unsigned char *u8) {
  const size_t n = s->n, n4 = n * sizeof(float);
  const double b = bits, fl = fields;
  int st =
      add_array(o, FIELD, "TimeValue", "Float64", 1, 1, &s->t, sizeof s->t);
  describe(o, "TimeValue", "time of the frame, the exact double", "s", 2);
  if (!st)
    st = add_array(o, FIELD, "frame_bits", "Float64", 1, 1, &b, sizeof b);
  describe(o, "frame_bits",
           "a frame: every Float32 here is its run's double in single "
           "precision rounded to nearest at this many mantissa bits (a "
           "relative error of at most 2^-(bits+1) beyond single precision's "
           "2^-24, for normal floats)",
           "dimensionless", 2);
  if (!st)
    st = add_array(o, FIELD, "frame_fields", "Float64", 1, 1, &fl, sizeof fl);
  describe(o, "frame_fields",
           "what the frame holds beyond the positions: 1 the velocity, 2 the "
           "pressure, vorticity and free-surface flag, 3 both",
           "dimensionless", 2);
  for (size_t k = 0; k < 3 * n; k++) x[k] = round_bits(s->pos[k], bits);
  if (!st) st = add_array(o, POINTS, "Points", "Float32", 3, 0, x, 3 * n4);
  describe(o, "Points", "particle positions x, y, z", "m", 2);
  if (fields & VSPH_VTK_FRAME_VELOCITY) {
    for (size_t k = 0; k < 3 * n; k++) x[k] = round_bits(s->vel[k], bits);
    if (!st)
      st = add_array(o, POINT_DATA, "velocity", "Float32", 3, 0, x, 3 * n4);
    describe(o, "velocity", "velocity u_x, u_y, u_z", "m/s", 2);
  }
  if (fields & VSPH_VTK_FRAME_SCALARS) {
    for (size_t k = 0; k < n; k++) x[k] = round_bits(s->p[k], bits);
    if (!st) st = add_array(o, POINT_DATA, "pressure", "Float32", 1, 0, x, n4);
    describe(o, "pressure", "pressure p from the state equation", "Pa", 2);
    if (s->vort_ncomp == 1) {
      for (size_t k = 0; k < n; k++)
        x[k] = round_bits(s->vort[3 * k + 2], bits);
      if (!st)
        st = add_array(o, POINT_DATA, "vorticity_z", "Float32", 1, 0, x, n4);
      describe(o, "vorticity_z", "SPH vorticity omega_z, signed", "1/s", 2);
    }
    for (size_t k = 0; k < n; k++) u8[k] = s->surf[k] != 0.0;
    if (!st)
      st = add_array(o, POINT_DATA, "free_surface", "UInt8", 1, 0, u8, n);
    describe(o, "free_surface", "free-surface flag (as in the snapshot)",
             "dimensionless", 2);
  }
  if (!st)
    st = add_array(o, FIELD, "array_descriptions", "String", 1, o->ndesc,
                   o->desc, o->desc_len);
  return st;
}

int vsph_vtk_write_frame(const char *dir, const char *name,
                         const struct vsph_vtk_snapshot *s, int bits,
                         unsigned fields) {
  if (!dir || !name || !s)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_write_frame: a NULL argument");
  if (bits < 1 || bits > 23)
    VSPH_FAIL(VSPH_EINVAL, "a frame keeps 1-23 mantissa bits, not %d", bits);
  if (fields > (VSPH_VTK_FRAME_VELOCITY | VSPH_VTK_FRAME_SCALARS))
    VSPH_FAIL(VSPH_EINVAL, "a frame's fields are 0-3, not %u", fields);
  if (s->frame_bits)
    VSPH_FAIL(VSPH_EINVAL, "a frame is made of a snapshot, not of a frame");
  const size_t len = s->n ? s->n : 1;
  float *x = malloc(3 * len * sizeof *x);
  unsigned char *u8 = malloc(len);
  struct out *o = calloc(1, sizeof *o);
  int st = x && u8 && o ? VSPH_OK : VSPH_ENOMEM;
  if (st)
    vsph_status_report(st, __FILE__, __LINE__,
                       "cannot allocate a frame of %zu particles", s->n);
  if (!st) {
    o->dir = dir;
    o->level = FRAME_LEVEL;
    o->no_vectors = !(fields & VSPH_VTK_FRAME_VELOCITY);
    o->no_scalars = !(fields & VSPH_VTK_FRAME_SCALARS);
    st = build_frame(o, s, bits, fields, x, u8);
  }
  free(x);
  free(u8);
  return emit(o, st, dir, name, s->n, s->t);
}

/* ---- reading back ---- */

/* A file read: its XML header (NUL-terminated) and appended block. */
struct in {
  const char *head;
  const unsigned char *data;
  size_t len;
  int frame; /* a frame's (vsph_vtk_write_frame): Float32 arrays allowed */
};

/* The value of attribute KEY in the tag [tag, end) into val; 0 if absent. */
static int attr(const char *tag, const char *end, const char *key, char *val,
                size_t cap) {
  char k[48];
  snprintf(k, sizeof k, " %s=\"", key);
  const size_t kl = strlen(k);
  for (const char *s = tag; s + kl <= end; s++) {
    if (strncmp(s, k, kl)) continue;
    const char *v = s + kl, *q = memchr(v, '"', (size_t)(end - v));
    if (!q || (size_t)(q - v) >= cap) return 0;
    memcpy(val, v, (size_t)(q - v));
    val[q - v] = '\0';
    return 1;
  }
  return 0;
}

/* Inflate the array at @p offset of the appended block into exactly
 * @p nbytes at @p dst; 0, or -1 if its blocks do not add up to that. */
static int inflate_array(const struct in *in, size_t offset, void *dst,
                         size_t nbytes) {
  uint64_t h[3];
  if (offset > in->len || in->len - offset < sizeof h) return -1;
  memcpy(h, in->data + offset, sizeof h);
  const uint64_t nb = h[0], bs = h[1], last = h[2];
  const size_t room = in->len - offset - sizeof h;
  if (nb > room / 8) return -1;
  if (nb == 0) return nbytes == 0 ? 0 : -1;
  if (bs == 0 || last >= bs || (nb - 1) > nbytes / bs ||
      (nb - 1) * bs + (last ? last : bs) != nbytes)
    return -1;
  const unsigned char *sizes = in->data + offset + sizeof h;
  const unsigned char *z = sizes + 8 * nb;
  size_t left = room - 8 * nb;
  for (uint64_t b = 0; b < nb; b++) {
    uint64_t zs;
    memcpy(&zs, sizes + 8 * b, sizeof zs);
    const uLong want = (uLong)(b + 1 < nb || !last ? bs : last);
    uLongf got = want;
    if (zs > left ||
        uncompress((Bytef *)dst + b * bs, &got, z, (uLong)zs) != Z_OK ||
        got != want)
      return -1;
    z += zs;
    left -= zs;
  }
  return 0;
}

/* Array NAME (@p ntuples tuples of @p ncomp components of type Float64 or
 * UInt8, or in a frame Float32) into @p out as doubles: 1, 0 if the file
 * has no such array, -1 if it differs or is damaged. */
static int read_array(const struct in *in, const char *name, int ncomp,
                      size_t ntuples, double *out) {
  char key[64], type[16], val[32];
  snprintf(key, sizeof key, "Name=\"%s\"", name);
  const char *m = strstr(in->head, key);
  if (!m) return 0;
  const char *tag = m, *end = strchr(m, '>');
  while (tag > in->head && *tag != '<') tag--;
  if (!end || !attr(tag, end, "type", type, sizeof type)) return -1;
  const int nc =
      attr(tag, end, "NumberOfComponents", val, sizeof val) ? atoi(val) : 1;
  if (nc != ncomp || !attr(tag, end, "format", val, sizeof val) ||
      strcmp(val, "appended") || !attr(tag, end, "offset", val, sizeof val))
    return -1;
  const size_t offset = strtoull(val, NULL, 10), count = ntuples * nc;
  if (!strcmp(type, "Float64"))
    return inflate_array(in, offset, out, count * sizeof(double)) ? -1 : 1;
  if (!strcmp(type, "Float32") && in->frame) { /* widened in place, from
                                                  the end (float k lies
                                                  below double k) */
    if (inflate_array(in, offset, out, count * sizeof(float))) return -1;
    for (size_t k = count; k-- > 0;) {
      float f;
      memcpy(&f, (const unsigned char *)out + k * sizeof f, sizeof f);
      out[k] = f;
    }
    return 1;
  }
  if (strcmp(type, "UInt8")) return -1;
  unsigned char *u8 = malloc(count ? count : 1);
  const int bad = !u8 || inflate_array(in, offset, u8, count);
  for (size_t k = 0; k < count && !bad; k++) out[k] = u8[k];
  free(u8);
  return bad ? -1 : 1;
}

/* Check the header of @p text (@p len bytes) and find its appended block;
 * NULL, or what is wrong. */
static const char *open_input(char *text, size_t len, struct in *in,
                              size_t *n) {
  char *ad = strstr(text, "<AppendedData encoding=\"raw\">");
  if (!ad)
    return "not a binary VTK snapshot (one in ASCII from an older vsph? "
           "rerun it)";
  char *u = ad + strlen("<AppendedData encoding=\"raw\">");
  while (u < text + len && (*u == '\n' || *u == ' ')) u++;
  if (u >= text + len || *u != '_') return "no '_' opens the appended data";
  *u = '\0'; /* the header ends here */
  in->head = text;
  in->data = (const unsigned char *)u + 1;
  in->len = len - (size_t)(u + 1 - text);
  const size_t tl = strlen(TRAILER);
  if (in->len < tl || memcmp(in->data + in->len - tl, TRAILER, tl))
    return "cut short (no closing tags)";
  in->len -= tl;
  const char *vf = strstr(text, "<VTKFile"), *end = vf ? strchr(vf, '>') : NULL;
  char val[64];
  if (!end || !attr(vf, end, "type", val, sizeof val) ||
      strcmp(val, "PolyData"))
    return "not VTK XML PolyData";
  if (!attr(vf, end, "header_type", val, sizeof val) || strcmp(val, "UInt64") ||
      !attr(vf, end, "compressor", val, sizeof val) ||
      strcmp(val, "vtkZLibDataCompressor"))
    return "not zlib-compressed with UInt64 headers";
  if (!attr(vf, end, "byte_order", val, sizeof val) ||
      strcmp(val, host_byte_order()))
    return "written in the other byte order";
  const char *piece = strstr(text, "<Piece");
  end = piece ? strchr(piece, '>') : NULL;
  if (!end || !attr(piece, end, "NumberOfPoints", val, sizeof val))
    return "no NumberOfPoints";
  *n = strtoull(val, NULL, 10);
  return NULL;
}

int vsph_vtk_read(const char *path, struct vsph_vtk_snapshot *s) {
  if (!s) VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_read: a NULL argument");
  memset(s, 0, sizeof *s);
  if (!path) VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_read: a NULL argument");
  size_t flen = 0;
  char *text = vsph_files_slurp(path, &flen);
  if (!text) VSPH_FAIL(VSPH_EIO, "cannot read %s", path);
  struct in in;
  size_t n = 0;
  const char *why = open_input(text, flen, &in, &n);
  if (!why && n > in.len) why = "more points than bytes"; /* no huge calloc */
  if (why) {
    free(text);
    VSPH_FAIL(VSPH_EIO, "%s: %s", path, why);
  }
  const size_t len = n ? n : 1;
  s->n = n;
  double **one[] = {&s->rho, &s->p, &s->vol, &s->divr, &s->surf, &s->mat};
  double **three[] = {&s->pos, &s->vel, &s->vort};
  int bad = 0;
  for (size_t k = 0; k < sizeof one / sizeof *one; k++)
    bad |= !(*one[k] = calloc(len, sizeof(double)));
  for (size_t k = 0; k < sizeof three / sizeof *three; k++)
    bad |= !(*three[k] = calloc(3 * len, sizeof(double)));
  if (bad) {
    free(text);
    vsph_vtk_snapshot_free(s);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate %s (%zu particles)", path, n);
  }
  /* the state must be there (a frame's part of it); the diagnostics and
   * material may not be */
  double fb = 0.0, ff = 0.0; /* a frame: both, each a whole number in range */
  in.frame = 0;
  const int frame = read_array(&in, "frame_bits", 1, 1, &fb);
  const int ffs = read_array(&in, "frame_fields", 1, 1, &ff);
  const int framed = frame == 1 && ffs == 1 && fb >= 1.0 && fb <= 23.0 &&
                     fb == floor(fb) && ff >= 0.0 && ff <= 3.0 &&
                     ff == floor(ff);
  s->frame_bits = framed ? (int)fb : 0;
  s->frame_fields = framed ? (unsigned)ff : 0u;
  in.frame = framed;
  const int vel = !framed || (s->frame_fields & VSPH_VTK_FRAME_VELOCITY);
  const int sca = !framed || (s->frame_fields & VSPH_VTK_FRAME_SCALARS);
  /* a frame holds exactly what frame_fields says (the 2-D vorticity and
   * the free-surface flag with the pressure), a snapshot all but the
   * optional diagnostics and material */
  bad = frame < 0 || ffs != frame || (frame && !framed) ||
        read_array(&in, "TimeValue", 1, 1, &s->t) != 1 ||
        read_array(&in, "Points", 3, n, s->pos) != 1 ||
        read_array(&in, "velocity", 3, n, s->vel) != vel ||
        read_array(&in, "density", 1, n, s->rho) != !framed ||
        read_array(&in, "pressure", 1, n, s->p) != sca ||
        read_array(&in, "volume", 1, n, s->vol) != !framed ||
        (framed ? read_array(&in, "div_r", 1, n, s->divr) != 0
                : read_array(&in, "div_r", 1, n, s->divr) < 0) ||
        (framed ? read_array(&in, "free_surface", 1, n, s->surf) != sca
                : read_array(&in, "free_surface", 1, n, s->surf) < 0) ||
        (framed ? read_array(&in, "material", 1, n, s->mat) != 0
                : read_array(&in, "material", 1, n, s->mat) < 0);
  if (!bad) { /* 2-D: omega_z, spread into the z slots; 3-D: the vector */
    const int w1 = read_array(&in, "vorticity_z", 1, n, s->vort);
    const int w3 = w1 ? 0 : read_array(&in, "vorticity", 3, n, s->vort);
    bad = w1 < 0 || w3 < 0 || (framed && !sca && (w1 || w3));
    s->vort_ncomp = w1 > 0 ? 1 : w3 > 0 ? 3 : 0;
    for (size_t k = n; w1 > 0 && k-- > 0;) { /* k < 3k: not yet overwritten */
      const double w = s->vort[k];
      s->vort[3 * k] = s->vort[3 * k + 1] = 0.0;
      s->vort[3 * k + 2] = w;
    }
  }
  free(text);
  if (bad) {
    vsph_vtk_snapshot_free(s);
    VSPH_FAIL(VSPH_EIO, "%s: an array is missing, short or damaged", path);
  }
  return VSPH_OK;
}

void vsph_vtk_snapshot_free(struct vsph_vtk_snapshot *s) {
  if (!s) return;
  free(s->pos);
  free(s->vel);
  free(s->rho);
  free(s->p);
  free(s->vol);
  free(s->vort);
  free(s->divr);
  free(s->surf);
  free(s->mat);
  memset(s, 0, sizeof *s);
}

int vsph_vtk_pvd_open(struct vsph_vtk_pvd *pvd, const char *dir) {
  if (!pvd || !dir)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_pvd_open: a NULL argument");
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

int vsph_vtk_pvd_reopen(struct vsph_vtk_pvd *pvd, const char *dir, long keep) {
  if (!pvd || !dir)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_pvd_reopen: a NULL argument");
  char path[4096];
  snprintf(path, sizeof path, "%s/snapshots.pvd", dir);
  pvd->dir = dir;
  pvd->f = vsph_files_reopen(dir, "snapshots.pvd", keep);
  if (!pvd->f)
    VSPH_FAIL(VSPH_EIO, "cannot write %s: %s", path, strerror(errno));
  return VSPH_OK;
}

int vsph_vtk_pvd_add(struct vsph_vtk_pvd *pvd, double t, const char *file) {
  return vsph_vtk_pvd_add_part(pvd, t, 0, file);
}

int vsph_vtk_pvd_add_part(struct vsph_vtk_pvd *pvd, double t, int part,
                          const char *file) {
  if (!pvd || !pvd->f || !file)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_pvd_add: a NULL argument, or closed");
  if (part < 0 || part > 1)
    VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_pvd_add_part: part %d, not 0 or 1", part);
  fprintf(pvd->f, "<DataSet timestep=\"%.10g\" part=\"%d\" file=\"%s\"/>\n", t,
          part, file);
  if (fflush(pvd->f) != 0 || ferror(pvd->f))
    VSPH_FAIL(VSPH_EIO, "cannot write %s/snapshots.pvd", pvd->dir);
  return VSPH_OK;
}

int vsph_vtk_pvd_close(struct vsph_vtk_pvd *pvd) {
  if (!pvd) VSPH_FAIL(VSPH_EINVAL, "vsph_vtk_pvd_close: a NULL argument");
  if (!pvd->f) return VSPH_OK;
  fprintf(pvd->f, "</Collection>\n</VTKFile>\n");
  const int bad = ferror(pvd->f);
  const int closed = fclose(pvd->f);
  pvd->f = NULL;
  if (bad || closed)
    VSPH_FAIL(VSPH_EIO, "cannot write %s/snapshots.pvd", pvd->dir);
  return VSPH_OK;
}
