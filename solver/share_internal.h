/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_SHARE_INTERNAL_H
#define VSPH_SOLVER_SHARE_INTERNAL_H

/* The sweep's blocks (and the gathers' runs of cells, below) shared out
 * among threads, owner first (within solver/ only). Thread t of T owns the
 * blocks [t nblk / T, (t + 1) nblk / T): about the run of particles a static
 * loop over them gives it, so the thread that sweeps a block's pairs is the one
 * that sums its particles' rows and moves them in the integrator's stages, and
 * their arrays stay in its core's cache. It takes its own blocks in order, then
 * the next ones of the other threads' (a thread that lost its core to
 * another process holds no one up, as with a dynamic schedule). Which
 * thread does a block never changes what the block computes. */

#include <omp.h>
#include <stddef.h>
#include <stdint.h>

/* The calling thread's even share [*i0, *i1) of @p n items in a parallel
 * region (thread t of T: [t n / T, (t + 1) n / T)); the whole outside
 * one. */
static inline void vsph_share_even(size_t n, size_t *i0, size_t *i1) {
  const size_t nt = (size_t)omp_get_num_threads();
  const size_t t = (size_t)omp_get_thread_num();
  *i0 = n * t / nt;
  *i1 = n * (t + 1) / nt;
}

/* At most this many owners; more threads take blocks as thieves. */
#define VSPH_SHARE_MAX 64

struct vsph_share {
  int nt;                      /* owners */
  size_t next[VSPH_SHARE_MAX]; /* each owner's next block (atomic) */
  size_t end[VSPH_SHARE_MAX];  /* one past its last */
};

/* Share @p nblk blocks among the threads a parallel region will have
 * (omp_get_max_threads()); before the region. */
static inline void vsph_share_init(struct vsph_share *s, size_t nblk) {
  int nt = omp_get_max_threads();
  nt = nt < 1 ? 1 : nt > VSPH_SHARE_MAX ? VSPH_SHARE_MAX : nt;
  s->nt = nt;
  for (int t = 0; t < nt; t++) {
    s->next[t] = nblk * (size_t)t / (size_t)nt;
    s->end[t] = nblk * (size_t)(t + 1) / (size_t)nt;
  }
}

/* The next block for the calling thread of the region: its own first,
 * then another's; SIZE_MAX when none is left. */
static inline size_t vsph_share_next(struct vsph_share *s) {
  const int t = omp_get_thread_num() % s->nt;
  for (int k = 0; k < s->nt; k++) {
    const int v = (t + k) % s->nt;
    size_t b;
#pragma omp atomic read
    b = s->next[v];
    if (b >= s->end[v]) continue; /* spent (a counter only grows) */
#pragma omp atomic capture
    b = s->next[v]++;
    if (b < s->end[v]) return b;
  }
  return SIZE_MAX;
}

/* The gathers' cells, shared out the same way in runs of this many
 * consecutive cells (a run of cells is a run of particles, the particles
 * being sorted by cell): as fine as the dynamic schedule's chunks they
 * replace, so that any thread count finds work. */
#define VSPH_SHARE_CELLS 8

/* Share @p ncells cells in runs (vsph_share_init's blocks are runs). */
static inline void vsph_share_init_cells(struct vsph_share *s, size_t ncells) {
  vsph_share_init(s, (ncells + VSPH_SHARE_CELLS - 1) / VSPH_SHARE_CELLS);
}

/* The calling thread's next run of cells [*c0, *c1) of @p ncells (a
 * share from vsph_share_init_cells); 0 when none is left. */
static inline int vsph_share_next_cells(struct vsph_share *s, size_t ncells,
                                        size_t *c0, size_t *c1) {
  const size_t r = vsph_share_next(s);
  if (r == SIZE_MAX) return 0;
  *c0 = r * VSPH_SHARE_CELLS;
  *c1 = *c0 + VSPH_SHARE_CELLS < ncells ? *c0 + VSPH_SHARE_CELLS : ncells;
  return 1;
}

/* The calling thread's next cell *@p c of @p ncells, run by run
 * (vsph_share_next_cells); @p run, the thread's own [first, end) of its
 * current run, starts as {0, 0}. 0 when none is left. So a region's loop
 * over the cells is one loop:
 *   for (size_t c, run[2] = {0, 0}; vsph_share_next_cell(&sh, n, run, &c);) */
static inline int vsph_share_next_cell(struct vsph_share *s, size_t ncells,
                                       size_t run[2], size_t *c) {
  if (run[0] >= run[1] && !vsph_share_next_cells(s, ncells, &run[0], &run[1]))
    return 0;
  *c = run[0]++;
  return 1;
}

#endif /* VSPH_SOLVER_SHARE_INTERNAL_H */
