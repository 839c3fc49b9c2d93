/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "cells.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "particles.h"

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
  free(c->key);
  free(c->perm);
  free(c->dscratch);
  free(c->iscratch);
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
  free(c->dscratch);
  free(c->iscratch);
  c->key = malloc(n * sizeof *c->key);
  c->perm = malloc(n * sizeof *c->perm);
  c->dscratch = malloc(n * sizeof *c->dscratch);
  c->iscratch = malloc(n * sizeof *c->iscratch);
  if (!c->key || !c->perm || !c->dscratch || !c->iscratch) {
    c->cap_n = 0;
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate cell scratch for %zu", n);
  }
  c->cap_n = n;
  return VSPH_OK;
}

/* The next build's number: unique across every cell list and thread. */
static unsigned long next_gen(void) {
  static atomic_ulong gen = 0;
  return atomic_fetch_add(&gen, 1) + 1;
}

int vsph_cells_build_direct(struct vsph_cells *c,
                            const struct vsph_particles *p) {
  c->gen = 0; /* no longer the build a plan was made on */
  int st = reserve_cells(c, 1);
  if (st) return st;
  c->dim = p->dim;
  c->direct = 1;
  c->edge = INFINITY;
  c->nc[0] = c->nc[1] = c->nc[2] = 1;
  c->ncells = 1;
  c->start[0] = 0;
  c->count[0] = p->n;
  c->gen = next_gen();
  return VSPH_OK;
}

int vsph_cells_build(struct vsph_cells *c, struct vsph_particles *p,
                     double radius) {
  const int dim = p->dim;
  const size_t n = p->n;
  c->gen = 0; /* no longer the build a plan was made on */
  if (!(radius > 0.0) || !isfinite(radius))
    VSPH_FAIL(VSPH_EINVAL, "cell radius must be positive, got %g", radius);
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int k = 0; k < dim; k++) {
    lo[k] = INFINITY;
    hi[k] = -INFINITY;
    for (size_t i = 0; i < n; i++) {
      const double x = p->pos[k][i];
      if (!isfinite(x))
        VSPH_FAIL(VSPH_EINVAL, "particle %zu has a non-finite position",
                  p->id[i]);
      lo[k] = x < lo[k] ? x : lo[k];
      hi[k] = x > hi[k] ? x : hi[k];
    }
    if (n == 0) lo[k] = hi[k] = 0.0;
    /* positions spread over more than the largest double: no grid */
    if (!isfinite(hi[k] - lo[k]))
      VSPH_FAIL(VSPH_EINVAL,
                "the particles span %g to %g along axis %d: too far apart",
                lo[k], hi[k], k);
  }
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
  c->ncells = ncells;
  for (int k = 0; k < 3; k++) {
    c->lo[k] = lo[k];
    c->nc[k] = k < dim ? (size_t)floor((hi[k] - lo[k]) / edge) + 1 : 1;
  }
  int st = reserve_cells(c, ncells);
  if (!st) st = reserve_particles(c, n);
  if (st) return st;

  /* Counting sort by cell key; stable, so equal keys keep input order. */
  memset(c->count, 0, ncells * sizeof *c->count);
  for (size_t i = 0; i < n; i++) {
    size_t key = 0;
    for (int k = dim - 1; k >= 0; k--) {
      size_t ck = (size_t)floor((p->pos[k][i] - lo[k]) / edge);
      if (ck >= c->nc[k]) ck = c->nc[k] - 1;
      key = key * c->nc[k] + ck;
    }
    c->key[i] = key;
    c->count[key]++;
  }
  size_t acc = 0;
  for (size_t q = 0; q < ncells; q++) {
    c->start[q] = acc;
    acc += c->count[q];
  }
  for (size_t i = 0; i < n; i++) c->perm[c->start[c->key[i]]++] = i;
  for (size_t q = 0; q < ncells; q++) c->start[q] -= c->count[q];
  vsph_particles_permute(p, c->perm, c->dscratch, c->iscratch);
  c->gen = next_gen();
  return VSPH_OK;
}

size_t vsph_cells_ranges(const struct vsph_cells *c, size_t cell,
                         size_t lo[VSPH_CELLS_MAXRANGES],
                         size_t hi[VSPH_CELLS_MAXRANGES]) {
  if (c->direct) {
    lo[0] = 0;
    hi[0] = c->count[0];
    return 1;
  }
  /* Cell key = ix + nc0 * (iy + nc1 * iz), as built above. */
  const size_t nx = c->nc[0], ny = c->nc[1], nz = c->nc[2];
  const size_t ix = cell % nx, iy = (cell / nx) % ny, iz = cell / (nx * ny);
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
