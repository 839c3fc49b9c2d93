/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "cells.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "cells_internal.h"
#include "particles.h"
#include "particles_internal.h"
#include "share_internal.h"

struct vsph_cells *vsph_cells_alloc(void) {
  struct vsph_cells *c = calloc(1, sizeof *c);
  if (!c)
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate a cell list");
  return c;
}

void vsph_cells_free(struct vsph_cells *c) {
  if (!c) return;
  free(c->start);
  free(c->count);
  free(c->key); /* the one scratch block (reserve_particles, or
                 * reserve_owned: then perhaps a set's former array) */
  free(c->perm);
  free(c->blk_c0);
  free(c->blk_lo);
  free(c->blk_hi);
  free(c);
}

static int reserve_cells(struct vsph_cells *c, size_t ncells) {
  if (ncells <= c->cap_cells) return VSPH_OK;
  size_t *s = realloc(c->start, ncells * sizeof *s);
  if (!s) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate %zu cells", ncells);
  c->start = s;
  size_t *n = realloc(c->count, ncells * sizeof *n);
  if (!n) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate %zu cells", ncells);
  c->count = n;
  c->cap_cells = ncells;
  return VSPH_OK;
}

static int reserve_particles(struct vsph_cells *c, size_t n) {
  if (n <= c->cap_n) return VSPH_OK;
  free(c->key);
  free(c->perm);
  /* one block of 8 bytes a particle serves the keys, then (the keys read)
   * the permutation's doubles and indices, each written before it is
   * read: 16 bytes a particle fewer than three blocks */
  _Static_assert(sizeof(double) == sizeof(size_t), "8-byte scratch");
  void *blk = malloc(n * sizeof(size_t));
  c->key = blk;
  c->dscratch = blk;
  c->iscratch = blk;
  c->perm = malloc(n * sizeof *c->perm);
  c->owned = 0;
  if (!blk || !c->perm) {
    c->cap_n = 0;
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate cell scratch for %zu", n);
  }
  c->cap_n = n;
  return VSPH_OK;
}

/* The scratch for a set's own arrays (vsph_cells_build_owned,
 * vsph_cells_lend): the block of keys from the set's allocation, of its
 * capacity @p cap, so that it can take the place of any of its arrays. */
static int reserve_owned(struct vsph_cells *c, size_t cap) {
  /* kept only for a set of the same capacity: after a move the block is
   * one of the set's former arrays, of its capacity exactly */
  if (c->owned && cap == c->cap_n) return VSPH_OK;
  free(c->key);
  free(c->perm);
  c->key = vsph_particles_spare_alloc(cap);
  c->dscratch = (double *)c->key;
  c->iscratch = c->key;
  c->perm = malloc(cap * sizeof *c->perm);
  c->owned = 1;
  if (!c->key || !c->perm) {
    c->cap_n = 0;
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate cell scratch for %zu", cap);
  }
  c->cap_n = cap;
  return VSPH_OK;
}

/* The blocks of the build (struct vsph_cells): runs of whole cells of
 * about vsph_cells_block_size(n) particles, each with the index range its
 * pairs reach (every j > i of its particles lies in its cells' ranges). */
static int plan_blocks(struct vsph_cells *c, size_t n) {
  c->nblk = 0;
  const size_t target = vsph_cells_block_size(n);
  size_t nblk = 0, acc = 0;
  int open = 0; /* a block is open: the next cell joins it */
  for (size_t q = 0; q < c->ncells; q++) {
    if (!open) nblk++, open = 1;
    acc += c->count[q];
    if (acc >= target) acc = 0, open = 0;
  }
  if (nblk + 1 > c->cap_blk) {
    const size_t cap = 2 * (nblk + 1);
    size_t **q[3] = {&c->blk_c0, &c->blk_lo, &c->blk_hi};
    for (int a = 0; a < 3; a++) {
      size_t *r = realloc(*q[a], cap * sizeof *r);
      if (!r) VSPH_FAIL(VSPH_ENOMEM, "cannot grow the cells' %zu blocks", cap);
      *q[a] = r;
    }
    c->cap_blk = cap;
  }
  size_t b = 0;
  acc = 0;
  open = 0;
  for (size_t q = 0; q < c->ncells; q++) {
    if (!open) c->blk_c0[b++] = q, open = 1;
    acc += c->count[q];
    if (acc >= target) acc = 0, open = 0;
  }
  c->blk_c0[nblk] = c->ncells;
  /* each block's reach: the cells' ranges, block by block in parallel */
#pragma omp parallel for schedule(dynamic, 4)
  for (b = 0; b < nblk; b++) {
    const size_t first = c->blk_c0[b], last = c->blk_c0[b + 1];
    size_t lo = c->start[first], hi = lo;
    for (size_t q = first; q < last; q++) {
      size_t rlo[VSPH_CELLS_MAXRANGES], rhi[VSPH_CELLS_MAXRANGES];
      const size_t nr = vsph_cells_ranges(c, q, rlo, rhi);
      for (size_t r = 0; r < nr; r++) hi = rhi[r] > hi ? rhi[r] : hi;
      const size_t end = c->start[q] + c->count[q];
      hi = end > hi ? end : hi;
    }
    c->blk_lo[b] = lo;
    c->blk_hi[b] = hi;
  }
  c->nblk = nblk;
  c->blk_n = n;
  return VSPH_OK;
}

int vsph_cells_build_direct(struct vsph_cells *c,
                            const struct vsph_particles *p) {
  if (!c || !p)
    VSPH_FAIL(VSPH_EINVAL, "vsph_cells_build_direct: a NULL argument");
  c->nblk = 0; /* no blocks until this build has its own */
  c->blk_n = SIZE_MAX;
  int st = reserve_cells(c, 1);
  if (st) return st;
  c->dim = p->dim;
  c->direct = 1;
  c->edge = INFINITY;
  c->nc[0] = c->nc[1] = c->nc[2] = 1;
  c->ncells = 1;
  c->start[0] = 0;
  c->count[0] = p->n;
  return plan_blocks(c, p->n);
}

/* The span of particles [i0, i1) along each axis, widened into @p lo and
 * @p hi; bit k set if a position along axis k there is not finite. */
static int span(const struct vsph_particles *p, size_t i0, size_t i1,
                double lo[3], double hi[3]) {
  int bad = 0;
  for (int k = 0; k < p->dim; k++) {
    const double *const x = p->pos[k];
    double l = lo[k], h = hi[k];
    for (size_t i = i0; i < i1; i++) {
      bad |= !isfinite(x[i]) << k;
      l = x[i] < l ? x[i] : l;
      h = x[i] > h ? x[i] : h;
    }
    lo[k] = l;
    hi[k] = h;
  }
  return bad;
}

/* The cell keys of particles [i0, i1) on @p c's grid (lo, edge, nc set). */
static void keys(struct vsph_cells *c, const struct vsph_particles *p,
                 size_t i0, size_t i1) {
  /* the grid in locals: the keys' stores could alias c's counts */
  const double lo[3] = {c->lo[0], c->lo[1], c->lo[2]}, edge = c->edge;
  const size_t nc[3] = {c->nc[0], c->nc[1], c->nc[2]};
  const int dim = p->dim;
  size_t *const key = c->key;
  for (size_t i = i0; i < i1; i++) {
    size_t kk = 0;
    for (int k = dim - 1; k >= 0; k--) {
      size_t ck = (size_t)floor((p->pos[k][i] - lo[k]) / edge);
      if (ck >= nc[k]) ck = nc[k] - 1;
      kk = kk * nc[k] + ck;
    }
    key[i] = kk;
  }
}

/* The counting sort's part for cells [q0, q1) of @p c (its keys made):
 * their counts and starts, and the places in perm of their particles, in
 * index order. The particles below q0 give the first start. Every
 * particle's key is read, so each share costs two passes over the keys;
 * the shares write disjoint counts, starts and places: the same perm as
 * one share of all the cells. */
static void sort_cells(struct vsph_cells *c, size_t n, size_t q0, size_t q1) {
  if (q0 == q1) return; /* no cells (more threads than cells) */
  const size_t *const key = c->key;
  size_t *const count = c->count, *const start = c->start,
                *const perm = c->perm;
  memset(count + q0, 0, (q1 - q0) * sizeof *count);
  size_t acc = 0; /* the particles in the cells below q0 */
  for (size_t i = 0; i < n; i++) {
    const size_t k = key[i];
    if (k < q0)
      acc++;
    else if (k < q1)
      count[k]++;
  }
  for (size_t q = q0; q < q1; q++) {
    start[q] = acc;
    acc += count[q];
  }
  for (size_t i = 0; i < n; i++) {
    const size_t k = key[i];
    if (k >= q0 && k < q1) perm[start[k]++] = i;
  }
  for (size_t q = q0; q < q1; q++) start[q] -= count[q];
}

/* vsph_cells_build, and with @p owned, vsph_cells_build_owned: the
 * particles moved by swapping the set's arrays with the scratch block
 * (vsph_particles_move) instead of copied back. */
static int build(struct vsph_cells *c, struct vsph_particles *p, double radius,
                 int owned) {
  const int dim = p->dim;
  const size_t n = p->n;
  /* no cells nor blocks until this build has its own: a failed build
   * leaves an empty list that a sweep refuses (blk_n), not the last one's
   * counts over arrays it may have outgrown */
  c->nblk = 0;
  c->ncells = 0;
  c->blk_n = SIZE_MAX;
  if (!(radius > 0.0) || !isfinite(radius))
    VSPH_FAIL(VSPH_EINVAL, "cell radius must be positive, got %g", radius);
  /* the bounding box: a minimum and a maximum are exact in any order, so
   * the threads' shares give the same box */
  double lo[3] = {INFINITY, INFINITY, INFINITY};
  double hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  int bad = 0;
  if (n >= VSPH_CELLS_PARALLEL) {
#pragma omp parallel reduction(min                                       \
                               : lo[:3]) reduction(max                   \
                                                   : hi[:3]) reduction(| \
                                                                       : bad)
    {
      size_t i0, i1;
      vsph_share_even(n, &i0, &i1);
      bad = span(p, i0, i1, lo, hi);
    }
  } else {
    bad = span(p, 0, n, lo, hi);
  }
  for (int k = 0; k < dim; k++) {
    if (bad >> k & 1) /* the first, as a serial scan names it */
      for (size_t i = 0; i < n; i++)
        if (!isfinite(p->pos[k][i]))
          VSPH_FAIL(VSPH_EINVAL, "particle %zu has a non-finite position",
                    p->id[i]);
    if (n == 0) lo[k] = hi[k] = 0.0;
    /* positions spread over more than the largest double: no grid */
    if (!isfinite(hi[k] - lo[k]))
      VSPH_FAIL(VSPH_EINVAL,
                "the particles span %g to %g along axis %d: too far apart",
                lo[k], hi[k], k);
  }
  for (int k = dim; k < 3; k++) lo[k] = hi[k] = 0.0;
  /* Cell edge >= radius / SUB; widen the cells if the grid would hold far
   * more cells than particles (a scattered set), which keeps memory O(N). */
  double edge = radius / VSPH_CELLS_SUB;
  size_t ncells;
  const double max_cells = 8.0 * (double)n + 4096.0;
  for (;;) {
    double total = 1.0;
    for (int k = 0; k < dim; k++) total *= floor((hi[k] - lo[k]) / edge) + 1.0;
    if (total <= max_cells) {
      ncells = (size_t)total;
      break;
    }
    edge *= 2.0;
  }
  c->dim = dim;
  c->direct = 0;
  c->edge = edge;
  for (int k = 0; k < 3; k++) {
    c->lo[k] = lo[k];
    c->nc[k] = k < dim ? (size_t)floor((hi[k] - lo[k]) / edge) + 1 : 1;
  }
  int st = reserve_cells(c, ncells);
  if (!st) st = owned ? reserve_owned(c, p->cap) : reserve_particles(c, n);
  if (st) return st;
  c->ncells = ncells;
  /* one block for the three (a move since the last build, through
   * vsph_cells_lend, may have swapped it) */
  c->dscratch = (double *)c->key;
  c->iscratch = c->key;

  /* Counting sort by cell key; stable, so equal keys keep input order.
   * The keys in parallel (one a particle), then each thread sorts the
   * particles of its even share of the cells (sort_cells), in the same
   * region: no serial part, during which the other threads would sleep. */
  if (n >= VSPH_CELLS_PARALLEL) {
#pragma omp parallel
    {
      size_t i0, i1;
      vsph_share_even(n, &i0, &i1);
      keys(c, p, i0, i1);
#pragma omp barrier
      vsph_share_even(ncells, &i0, &i1);
      sort_cells(c, n, i0, i1);
    }
  } else {
    keys(c, p, 0, n);
    sort_cells(c, n, 0, ncells);
  }
  if (owned) { /* the keys are read: their block is the move's spare */
    void *spare = c->key;
    vsph_particles_move(p, c->perm, n, &spare);
    c->key = spare;
    c->dscratch = spare;
    c->iscratch = spare;
  } else {
    vsph_particles_permute(p, c->perm, c->dscratch, c->iscratch);
  }
  return plan_blocks(c, n);
}

int vsph_cells_build(struct vsph_cells *c, struct vsph_particles *p,
                     double radius) {
  if (!c || !p) VSPH_FAIL(VSPH_EINVAL, "vsph_cells_build: a NULL argument");
  return build(c, p, radius, 0);
}

int vsph_cells_build_owned(struct vsph_cells *c, struct vsph_particles *p,
                           double radius) {
  if (!c || !p)
    VSPH_FAIL(VSPH_EINVAL, "vsph_cells_build_owned: a NULL argument");
  return build(c, p, radius, 1);
}

int vsph_cells_lend(struct vsph_cells *c, const struct vsph_particles *p,
                    size_t **perm, void ***spare) {
  const int st = reserve_owned(c, p->cap);
  if (st) return st;
  *perm = c->perm;
  *spare = (void **)&c->key;
  return VSPH_OK;
}

size_t vsph_cells_ranges(const struct vsph_cells *c, size_t cell,
                         size_t lo[VSPH_CELLS_MAXRANGES],
                         size_t hi[VSPH_CELLS_MAXRANGES]) {
  if (!c || !lo || !hi) return 0;
  if (c->direct) {
    lo[0] = 0;
    hi[0] = c->count[0];
    return 1;
  }
  /* Cell key = ix + nc0 * (iy + nc1 * iz), as built above. */
  const size_t nx = c->nc[0], ny = c->nc[1], nz = c->nc[2];
  if (cell >= c->ncells) return 0; /* no such cell */
  /* two divisions, one where the grid is one cell deep (2-D) */
  const size_t line = cell / nx, iz = nz > 1 ? line / ny : 0;
  const size_t ix = cell - line * nx, iy = line - iz * ny;
  const size_t S = VSPH_CELLS_SUB;
  const size_t z0 = iz >= S ? iz - S : 0, z1 = iz + S < nz ? iz + S : nz - 1;
  const size_t y0 = iy >= S ? iy - S : 0, y1 = iy + S < ny ? iy + S : ny - 1;
  const size_t x0 = ix >= S ? ix - S : 0, x1 = ix + S < nx ? ix + S : nx - 1;
  size_t nr = 0;
  for (size_t z = z0; z <= z1; z++)
    for (size_t y = y0; y <= y1; y++) {
      /* the cells along x are contiguous in memory: one range per row */
      const size_t row = (z * ny + y) * nx;
      const size_t a = c->start[row + x0];
      const size_t b = c->start[row + x1] + c->count[row + x1];
      if (b > a) {
        lo[nr] = a;
        hi[nr] = b;
        nr++;
      }
    }
  return nr;
}
