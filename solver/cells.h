/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_CELLS_H
#define VSPH_SOLVER_CELLS_H

#include <stddef.h>

#include "../common/api.h"

struct vsph_particles;

/** @file cells.h
 *  @brief Cell-linked neighbour list (SWIFT's space-owns, cells-view design).
 *  Building it sorts the particles by cell with a counting sort so each cell
 *  is a contiguous index range; the cells hold only ranges. The O(N^2) path
 *  is the same structure with one cell holding every particle, so the fast
 *  and the reference loops share their code. No I/O. */

/** Cells per interaction radius: the edge is radius/2 and a particle's
 *  neighbours lie within 2 cells, so the scanned area is (5/2)^d radius^d
 *  instead of 3^d radius^d (30 % fewer candidates in 2-D). */
#define VSPH_CELLS_SUB 2

/** Maximum number of neighbour cell ranges: one contiguous x-row per
 *  (y, z) offset, (2 SUB + 1)^2. */
#define VSPH_CELLS_MAXRANGES 25

/** Uniform grid of cells with edge >= radius / VSPH_CELLS_SUB. */
struct vsph_cells {
  int dim;          /*!< dimension */
  int direct;       /*!< 1: a single cell, the O(N^2) reference path */
  double edge;      /*!< cell edge (m) */
  double lo[3];     /*!< lower corner of the grid (m) */
  size_t nc[3];     /*!< cells along each axis (1 beyond dim) */
  size_t ncells;    /*!< total cells */
  size_t *start;    /*!< first particle of each cell */
  size_t *count;    /*!< particles in each cell */
  size_t cap_cells; /*!< allocated length of start and count */
  size_t *key;      /*!< scratch: cell of each particle ... */
  size_t *perm;     /*!< scratch: sorting permutation */
  double *dscratch; /*!< ... then, in the same block as key, scratch for
                         the particle permutation */
  size_t *iscratch; /*!< (the same block again) */
  size_t cap_n;     /*!< allocated length of the per-particle scratch */
  /* the build's blocks, for a sweep over pairs in parallel
   * (solver/equations.c): runs of whole cells of about
   * vsph_cells_block_size(n) particles, with the index range each one's
   * pairs reach; planned with the cells, so no plan outlives them */
  size_t blk_n;   /*!< particles the blocks were planned for */
  size_t nblk;    /*!< blocks */
  size_t cap_blk; /*!< allocated blocks */
  size_t *blk_c0; /*!< first cell of each block; blk_c0[nblk] = ncells */
  size_t *blk_lo; /*!< the first particle a block's pairs reach ... */
  size_t *blk_hi; /*!< ... and one past its last */
  int owned;      /*!< key's block is from a set's allocation, of
                       exactly cap_n entries, that set's capacity (the
                       integrator's builds; internal) */
};

/** @brief Particles per block of a sweep: enough blocks for a few threads
 *  to share out (32 at 42 000 particles: a machine with more threads than
 *  blocks leaves some idle in the sweep), few enough that the buffers'
 *  overlap (a block's neighbours reach about two cell rows beyond it)
 *  stays small. A function of the particle count alone: never of the
 *  threads. */
static inline size_t vsph_cells_block_size(size_t n) {
  const size_t t = n / 32;
  return t < 512 ? 512 : t > 8192 ? 8192 : t;
}

/** @brief Allocate an empty cell list. NULL on failure. */
VSPH_API struct vsph_cells *vsph_cells_alloc(void);

/** @brief Free a cell list; NULL is a no-op. */
VSPH_API void vsph_cells_free(struct vsph_cells *c);

/** @brief Bin the particles into cells of edge >= @p radius / 2 and sort
 *  them by cell (fields are permuted; id[] keeps the original index).
 *  @param c the cell list (vsph_cells_alloc).
 *  @param p the particles, reordered by cell.
 *  @param radius interaction radius (m), > 0.
 *  @return VSPH_OK, VSPH_EINVAL (radius <= 0 or non-finite positions),
 *  VSPH_ENOMEM.
 *  @note Grows its own buffers when the particle or cell count grows. */
VSPH_API int vsph_cells_build(struct vsph_cells *c, struct vsph_particles *p,
                              double radius);

/** @brief Set up the O(N^2) reference path: one cell holding all particles
 *  (particles are not reordered). */
VSPH_API int vsph_cells_build_direct(struct vsph_cells *c,
                                     const struct vsph_particles *p);

/** @brief Index ranges [lo[r], hi[r]) of the cells within reach of
 *  @p cell (itself included), in a fixed order: every particle within the
 *  build radius of a particle of @p cell lies in them. Returns the number
 *  of ranges (0 for a cell the list does not have). */
VSPH_API size_t vsph_cells_ranges(const struct vsph_cells *c, size_t cell,
                                  size_t lo[VSPH_CELLS_MAXRANGES],
                                  size_t hi[VSPH_CELLS_MAXRANGES]);

#endif /* VSPH_SOLVER_CELLS_H */
