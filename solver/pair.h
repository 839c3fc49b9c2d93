/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_PAIR_H
#define VSPH_SOLVER_PAIR_H

#include <stddef.h>
#include <stdint.h>

#include "../common/consts.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "particles.h"

/** @file pair.h
 *  @brief The one neighbour loop and the one pair function of every
 *  physical term (THEORY sections 3 and 5). Every sum over neighbours in
 *  vsph (the solver's right-hand side, the viscous operators of the
 *  analysis, PVWF's two passes, the moment sums) walks its neighbours with
 *  vsph_pair_gather, chunk by chunk, and adds each term through the
 *  functions below, so a term exists in exactly one place.
 *
 *  Conventions (THEORY section 0): x = r_j - r_i, s = |x|,
 *  grad_i W_ij = -x W'(s)/s. The iterator hands out F = W'(s)/s <= 0 and
 *  VF = V_j F, so no loop takes a square root or divides by s.
 *
 *  Each term function is pure: it returns (or sets) the pair's share, so
 *  a chunk's shares are computed in one vectorised loop. The solver's
 *  right-hand side sums them lane by lane in that loop (omp simd
 *  reduction); the other loops store them and sum in neighbour order. Either
 *  way a sum depends only on the build (the vector width), never on the
 *  thread count: 1 and 2 threads give bitwise-identical results, and two
 *  builds (say ARCH= against the AVX2 default) agree to rounding.
 *
 *  Everything here is static inline (STYLE B3: small hot helpers in the
 *  module header) but the candidate test's SIMD versions on x86-64
 *  (solver/pair_x86.c), which the inline gather calls. No I/O, no
 *  allocation. */

/* ------------------------------------------------------------- the loop */

/** Kernel quantities every pair needs, loaded once per loop (STYLE B7). */
struct vsph_pair_kernel {
  int dim;       /*!< 1, 2 or 3 */
  double H2;     /*!< squared support radius (kappa h)^2 (m^2) */
  double h_inv2; /*!< 1/h^2 */
  double dwq;    /*!< sigma_d h^{-d-2}, see vsph_kernel_dwq_factor */
  int dfq_id;    /*!< the kernel's vsph_kernel_dfq_id */
  int simd;      /*!< the candidate test in 2-D and 3-D: 2 by AVX-512, 1
                      by AVX2 (pair_x86.c), 0 by the portable loops; set
                      by vsph_pair_kernel_init (a struct filled by hand
                      must set it, 0 at least) */
};

/** Candidate neighbours of one cell: index ranges [lo, hi) in a fixed
 *  order (from vsph_cells_ranges, or one range for a direct sum). */
struct vsph_pair_ranges {
  size_t n;                        /*!< number of ranges */
  size_t lo[VSPH_CELLS_MAXRANGES]; /*!< first index of each range */
  size_t hi[VSPH_CELLS_MAXRANGES]; /*!< one past the last */
};

/** One neighbour j of particle i within the support. */
struct vsph_pair {
  size_t j;    /*!< neighbour index */
  double x[3]; /*!< r_j - r_i (m); entries beyond dim are not set */
  double s2;   /*!< |x|^2 (m^2), 0 < s2 < H2 */
  double F;    /*!< W'(s)/s (m^{-d-2}), <= 0 */
  double VF;   /*!< V_j W'(s)/s */
};

/** vsph_pair_gather fills a chunk until it holds at least this many
 *  neighbours (or the candidates run out)... */
#define VSPH_PAIR_CHUNK 64
/** ... testing the candidates 64 at a time, so a chunk holds at most
 *  this many. */
#define VSPH_PAIR_CHUNK_MAX (VSPH_PAIR_CHUNK + 63)

/** A chunk of neighbours of particle i, in range order. */
struct vsph_pair_chunk {
  size_t m;                         /*!< pairs in the chunk */
  size_t j[VSPH_PAIR_CHUNK_MAX];    /*!< neighbour indices */
  double x[3][VSPH_PAIR_CHUNK_MAX]; /*!< x[a][k]: component a of r_j - r_i */
  double s2[VSPH_PAIR_CHUNK_MAX];   /*!< |x|^2 */
  double F[VSPH_PAIR_CHUNK_MAX];    /*!< W'(s)/s */
  double VF[VSPH_PAIR_CHUNK_MAX];   /*!< V_j W'(s)/s */
};

/** At most this many receivers share one walk of their cell's rows
 *  (vsph_pair_cell_begin). */
#define VSPH_PAIR_JOINT 8

/** The upper walks (vsph_pair_begin_upper) of one cell's receivers,
 *  made together, VSPH_PAIR_JOINT at a time, where the CPU allows
 *  (vsph_pair_cell_begin): each receiver's first chunk, and where its
 *  walk goes on alone. */
struct vsph_pair_cell {
  size_t end;                                /*!< one past the cell's last */
  int together;                              /*!< its walks go together */
  size_t s0;                                 /*!< the group's first ... */
  size_t group;                              /*!< ... and its receivers */
  size_t m[VSPH_PAIR_JOINT];                 /*!< each receiver's neighbours
                                                  in b; SIZE_MAX: none made,
                                                  it walks alone */
  size_t r[VSPH_PAIR_JOINT];                 /*!< the range its walk goes on
                                                  in; SIZE_MAX: it ends */
  size_t j[VSPH_PAIR_JOINT];                 /*!< ... and the candidate */
  struct vsph_pair_chunk b[VSPH_PAIR_JOINT]; /*!< each receiver's first
                                                  chunk */
};

/** Iterator over the neighbours j != i of particle i, in range order. The
 *  fields are private: read the pairs, not the iterator. */
struct vsph_pair_iter {
  const struct vsph_pair_kernel *pk; /*!< kernel of the loop */
  const double *pos[3];              /*!< positions (components < dim) */
  const double *vol;                 /*!< volumes */
  const struct vsph_pair_ranges *rg; /*!< candidate ranges */
  size_t i;                          /*!< receiving particle */
  size_t r, j, end;                  /*!< range, next index, range end */
  size_t jmin;                       /*!< no candidate below this index */
  double xi[3];                      /*!< r_i */
  struct vsph_pair_chunk *ready;     /*!< the walk's first chunk, made by
                                          its cell's joint walk; NULL: none */
  size_t ready_m;                    /*!< its neighbours */
  size_t ready_r, ready_j;           /*!< where the walk goes on after it
                                          (range, candidate); ready_r =
                                          SIZE_MAX: it ends there */
};

/** @brief The next block of candidates of the walk @p it: at most 64
 *  consecutive indices [*j0, *j0 + n) of its current range (j >= jmin),
 *  moving to the next range where one is spent; the walk moves past the
 *  block. @return n, or 0 when the ranges are exhausted. */
static inline size_t vsph_pair_next_block(struct vsph_pair_iter *it,
                                          size_t *j0) {
  for (;;) {
    if (it->j < it->jmin) it->j = it->jmin;
    if (it->j < it->end) break;
    if (++it->r >= it->rg->n) return 0;
    it->j = it->rg->lo[it->r];
    it->end = it->rg->hi[it->r];
  }
  *j0 = it->j;
  const size_t n = it->end - it->j > 64 ? 64 : it->end - it->j;
  it->j += n;
  return n;
}

/* The candidate test (2-D and 3-D) with AVX-512 or AVX2
 * (solver/pair_x86.c), the widest the CPU has, chosen at run time by the
 * library: in builds that target AVX2 (the program, the installed
 * library's x86-64-v3 copy); the baseline copy answers "portable" (its
 * vsph_pair_x86_simd returns 0), so code built against either copy, with
 * or without AVX2, links and runs. The same neighbours, r_j - r_i and
 * s^2, to the bit, as the portable loop of vsph_pair_gather_as (code that
 * includes this header needs -ffp-contract=off, GCC's default with
 * -std=c11, for its own portable loop to agree to the bit). Exported
 * because the inline gather calls them from a caller's code. */
#if defined(__x86_64__) && defined(__GNUC__) && defined(__LP64__)
#define VSPH_PAIR_X86 1
/** @brief The level of the candidate test the CPU allows: 2 AVX-512
 *  (F, VL, DQ), 1 AVX2, 0 the portable loops; VSPH_PAIR_SIMD = avx2 or
 *  portable in the environment caps it (avx512 or any other value: no
 *  cap; for comparisons); 0 always in the library's baseline copy. Read
 *  by vsph_pair_kernel_init into vsph_pair_kernel::simd. */
VSPH_API int vsph_pair_x86_simd(void);
/** @brief vsph_pair_gather_as's candidate test (2-D or 3-D, pk->dim)
 *  by AVX-512: fills
 *  @p b's j, x and s2 with the next neighbours of the walk @p it (as the
 *  portable loop would, to the bit) and returns how many. Call only where
 *  vsph_pair_x86_simd() returns 2. */
VSPH_API size_t vsph_pair_x86_candidates_avx512(struct vsph_pair_iter *it,
                                                struct vsph_pair_chunk *b);
/** @brief The same by AVX2 (vsph_pair_x86_simd() >= 1). */
VSPH_API size_t vsph_pair_x86_candidates_avx2(struct vsph_pair_iter *it,
                                              struct vsph_pair_chunk *b);
/** @brief The upper walks (vsph_pair_begin_upper) of a cell's @p cnt <=
 *  VSPH_PAIR_JOINT consecutive receivers pc->s0, pc->s0 + 1, ... at once
 *  by AVX-512: in the rows after their own, each vector of candidates is
 *  tested against every receiver in turn. For receiver q, pc->b[q] gets
 *  the j, x and s2 of its first chunk's neighbours, pc->m[q] their count:
 *  the chunk vsph_pair_gather_as fills first for that walk, to the bit
 *  (the same operations, the same blocks, in range order); where that
 *  chunk is full before the walk ends, pc->r[q] and pc->j[q] say where the
 *  walk goes on (else pc->r[q] = SIZE_MAX). @p rg: the ranges of the
 *  receivers' cell (a cell list's: vsph_pair_cell_begin; where the
 *  receivers are not all in one range, each is left to walk alone, m[q]
 *  = SIZE_MAX); @p pos: the positions (components < pk->dim). Call only
 *  where vsph_pair_x86_simd() returns 2 (vsph_pair_begin_upper_in
 *  chooses). */
VSPH_API void vsph_pair_x86_upper_cell_avx512(const struct vsph_pair_kernel *pk,
                                              const double *const pos[3],
                                              const struct vsph_pair_ranges *rg,
                                              struct vsph_pair_cell *pc,
                                              size_t cnt);
/** @brief The same by AVX2 (vsph_pair_x86_simd() >= 1). */
VSPH_API void vsph_pair_x86_upper_cell_avx2(const struct vsph_pair_kernel *pk,
                                            const double *const pos[3],
                                            const struct vsph_pair_ranges *rg,
                                            struct vsph_pair_cell *pc,
                                            size_t cnt);
#else
#define VSPH_PAIR_X86 0
static inline int vsph_pair_x86_simd(void) { return 0; }
#endif

/** @brief Kernel quantities for kernel @p k, dimension @p dim and
 *  smoothing length @p h (m). H2 is formed as kappa h kappa h: a truncated
 *  kernel whose w' jumps at kappa (the 3h Gaussian) must classify a pair
 *  lying on the support edge identically in every loop, and every loop
 *  takes it from here. */
static inline void vsph_pair_kernel_init(struct vsph_pair_kernel *pk,
                                         const struct vsph_kernel_type *k,
                                         int dim, double h) {
  pk->dim = dim;
  pk->H2 = k->kappa * h * k->kappa * h;
  pk->h_inv2 = 1.0 / (h * h);
  pk->dwq = vsph_kernel_dwq_factor(k, dim, h);
  pk->dfq_id = k->dfq_id[dim - 1];
  pk->simd = dim >= 2 ? vsph_pair_x86_simd() : 0;
}

/** @brief The candidate ranges of cell @p cell of @p cells. */
static inline void vsph_pair_ranges_cell(struct vsph_pair_ranges *rg,
                                         const struct vsph_cells *cells,
                                         size_t cell) {
  rg->n = vsph_cells_ranges(cells, cell, rg->lo, rg->hi);
}

/** @brief One range holding every particle 0..n-1 (direct sums). */
static inline void vsph_pair_ranges_all(struct vsph_pair_ranges *rg, size_t n) {
  rg->n = 1;
  rg->lo[0] = 0;
  rg->hi[0] = n;
}

/** @brief Start iterating over the neighbours of particle @p i. */
static inline void vsph_pair_begin(struct vsph_pair_iter *it,
                                   const struct vsph_pair_kernel *pk,
                                   const struct vsph_particles *p,
                                   const struct vsph_pair_ranges *rg,
                                   size_t i) {
  it->pk = pk;
  it->vol = p->vol;
  it->rg = rg;
  it->i = i;
  it->r = 0;
  it->j = rg->n > 0 ? rg->lo[0] : 0;
  it->end = rg->n > 0 ? rg->hi[0] : 0;
  it->jmin = 0;
  it->ready = NULL;
  it->ready_m = 0;
  for (int k = 0; k < 3; k++) {
    it->pos[k] = k < pk->dim ? p->pos[k] : NULL;
    it->xi[k] = k < pk->dim ? p->pos[k][i] : 0.0;
  }
}

/** @brief Start iterating over the neighbours j > i of particle @p i only
 *  (each unique pair once: the symmetric sweep of equations.c). */
static inline void vsph_pair_begin_upper(struct vsph_pair_iter *it,
                                         const struct vsph_pair_kernel *pk,
                                         const struct vsph_particles *p,
                                         const struct vsph_pair_ranges *rg,
                                         size_t i) {
  vsph_pair_begin(it, pk, p, rg, i);
  it->jmin = i + 1;
}

/* F and VF of the chunk's m pairs from their q^2, for the kernel shape
 * kid (a constant where inlined from vsph_pair_fvf); with @p unit, VF = F
 * (the symmetric sweeps' unit shares: no gather of V_j). */
VSPH_CONSTS_SPECIALISE void vsph_pair_fvf_shape(const struct vsph_pair_iter *it,
                                                struct vsph_pair_chunk *b,
                                                const double *q2, size_t m,
                                                int kid, const int unit) {
  const double dwq = it->pk->dwq;
#pragma omp simd
  for (size_t k = 0; k < m; k++) {
    const double F = dwq * vsph_kernel_dfq_shape(kid, q2[k]);
    b->F[k] = F;
    b->VF[k] = unit ? F : it->vol[b->j[k]] * F;
  }
}

/* The same with the shape chosen outside the loop: a caller specialised on
 * its kernel passes a constant and the switch folds away; any other gets
 * the loop of its kernel, vectorised all the same. */
VSPH_CONSTS_SPECIALISE void vsph_pair_fvf(const struct vsph_pair_iter *it,
                                          struct vsph_pair_chunk *b,
                                          const double *q2, size_t m, int kid,
                                          const int unit) {
  switch (kid) {
    case VSPH_KERNEL_DFQ_GAUSSIAN:
      vsph_pair_fvf_shape(it, b, q2, m, VSPH_KERNEL_DFQ_GAUSSIAN, unit);
      break;
    case VSPH_KERNEL_DFQ_CUBIC:
      vsph_pair_fvf_shape(it, b, q2, m, VSPH_KERNEL_DFQ_CUBIC, unit);
      break;
    case VSPH_KERNEL_DFQ_QUINTIC:
      vsph_pair_fvf_shape(it, b, q2, m, VSPH_KERNEL_DFQ_QUINTIC, unit);
      break;
    case VSPH_KERNEL_DFQ_C2:
      vsph_pair_fvf_shape(it, b, q2, m, VSPH_KERNEL_DFQ_C2, unit);
      break;
    case VSPH_KERNEL_DFQ_C2_1D:
      vsph_pair_fvf_shape(it, b, q2, m, VSPH_KERNEL_DFQ_C2_1D, unit);
      break;
    case VSPH_KERNEL_DFQ_C4:
      vsph_pair_fvf_shape(it, b, q2, m, VSPH_KERNEL_DFQ_C4, unit);
      break;
    default:
      vsph_pair_fvf_shape(it, b, q2, m, VSPH_KERNEL_DFQ_C4_1D, unit);
  }
}

/** @brief Finish a chunk whose @p m neighbours' j, x and s2 are set (by
 *  the candidate test, or vsph_pair_x86_upper_cell_avx512 for walk @p it):
 *  their F and VF (@p kid, @p unit as in vsph_pair_gather_as) and b->m.
 *  @return m. */
VSPH_CONSTS_SPECIALISE size_t vsph_pair_chunk_ready(
    const struct vsph_pair_iter *it, struct vsph_pair_chunk *b, size_t m,
    int kid, const int unit) {
  b->m = m;
  double q2[VSPH_PAIR_CHUNK_MAX];
#pragma omp simd
  for (size_t k = 0; k < m; k++) q2[k] = b->s2[k] * it->pk->h_inv2;
  vsph_pair_fvf(it, b, q2, m, kid, unit);
  return m;
}

/** @brief Begin the upper walks of the cell of receivers s0 ..
 *  s0 + cnt - 1: vsph_pair_begin_upper_in, called for each in turn, walks
 *  the rows together for groups of up to VSPH_PAIR_JOINT of them where
 *  the CPU has AVX-512 or AVX2 (pk->simd, in 2-D and 3-D;
 *  vsph_pair_x86_upper_cell_avx512, _avx2), and gives each the chunks its
 *  own walk would; otherwise each walks alone. The ranges must be a cell
 *  list's for this cell (vsph_pair_ranges_cell: ascending, not
 *  overlapping, the cell's particles consecutive in one of them); a
 *  receiver called out of turn, or not of the cell, walks alone. The
 *  struct is about 57 KB (eight chunks): one per loop, not per cell. */
VSPH_CONSTS_SPECIALISE void vsph_pair_cell_begin(
    struct vsph_pair_cell *pc, const struct vsph_pair_kernel *pk, size_t s0,
    size_t cnt, const int dim) {
  pc->end = s0 + cnt;
  pc->together = VSPH_PAIR_X86 && dim >= 2 && pk->simd && cnt >= 2;
  pc->s0 = s0;
  pc->group = 0;
}

/** @brief vsph_pair_begin_upper for receiver @p i of the cell @p pc
 *  begun (vsph_pair_cell_begin; its receivers in turn, @p rg its
 *  ranges): where the receivers walk together, the group's walk is made
 *  with its first receiver, and this walk gives its chunk first, then
 *  goes on alone. */
VSPH_CONSTS_SPECIALISE void vsph_pair_begin_upper_in(
    struct vsph_pair_iter *it, const struct vsph_pair_kernel *pk,
    const struct vsph_particles *p, const struct vsph_pair_ranges *rg,
    struct vsph_pair_cell *pc, size_t i) {
  vsph_pair_begin_upper(it, pk, p, rg, i);
  if (!pc->together || i < pc->s0 || i >= pc->end) return;
#if VSPH_PAIR_X86
  if (i >= pc->s0 + pc->group) { /* the next group: made now */
    const size_t left = pc->end - i;
    pc->s0 = i;
    /* the fewest groups, of sizes as even as can be (nine: five, four;
     * never eight and a last one walking alone) */
    const size_t ng = (left + VSPH_PAIR_JOINT - 1) / VSPH_PAIR_JOINT;
    pc->group = (left + ng - 1) / ng;
    if (pc->group < 2) return; /* one receiver left: it walks alone */
    const double *const pos[3] = {p->pos[0], p->pos[1],
                                  pk->dim > 2 ? p->pos[2] : NULL};
    if (pk->simd == 2)
      vsph_pair_x86_upper_cell_avx512(pk, pos, rg, pc, pc->group);
    else
      vsph_pair_x86_upper_cell_avx2(pk, pos, rg, pc, pc->group);
  }
  const size_t q = i - pc->s0;
  if (pc->group >= 2 && pc->m[q] != SIZE_MAX) {
    it->ready = &pc->b[q];
    it->ready_m = pc->m[q];
    it->ready_r = pc->r[q];
    it->ready_j = pc->j[q];
  }
#else
  (void)p, (void)rg;
#endif
}

/** @brief The next chunk of neighbours j != i (j > i after
 *  vsph_pair_begin_upper) with s^2 < H2 into @p b.
 *  The candidates are tested 64 at a time in one vectorised loop that sets
 *  a bit per neighbour (no branch); the set bits, lowest first, give the
 *  neighbours in range order; then two vectorised loops give their
 *  geometry (s2 computed exactly as in the test) and kernel factors.
 *  Where pk->simd is set (x86-64, 2-D and 3-D), the test and the geometry
 *  are one pass of SIMD lanes whose neighbours are packed by a compress
 *  (vsph_pair_x86_candidates_avx512, _avx2): the same chunk, to the bit.
 *  @param it the walk over particle i's candidates.
 *  @param dim the loop's dimension (= pk->dim).
 *  @param kid its kernel (= pk->dfq_id): both passed by the caller so
 *  that a caller specialised on constants gets unrolled loops and the
 *  kernel inlined.
 *  @param unit 1 sets VF = F (a symmetric sweep's unit shares), 0 VF =
 *  V_j F.
 *  @param b receives the chunk.
 *  @return the neighbours in the chunk (b->m); 0 when the ranges are
 *  exhausted. */
VSPH_CONSTS_SPECIALISE size_t vsph_pair_gather_as(struct vsph_pair_iter *it,
                                                  int dim, int kid,
                                                  const int unit,
                                                  struct vsph_pair_chunk *b) {
  double q2[VSPH_PAIR_CHUNK_MAX];
#if VSPH_PAIR_X86
  if (dim >= 2 && it->pk->simd) {
    if (it->r >= it->rg->n) { /* the walk is over: no call to learn it */
      b->m = 0;
      return 0;
    }
    const size_t m = it->pk->simd == 2 ? vsph_pair_x86_candidates_avx512(it, b)
                                       : vsph_pair_x86_candidates_avx2(it, b);
    return vsph_pair_chunk_ready(it, b, m, kid, unit);
  }
#endif
  const double H2 = it->pk->H2;
  const size_t i = it->i;
  size_t m = 0;
  while (m < VSPH_PAIR_CHUNK) {
    size_t j0;
    const size_t n = vsph_pair_next_block(it, &j0);
    if (!n) break;
    unsigned long long w = 0;
#pragma omp simd reduction(| : w)
    for (size_t c = 0; c < n; c++) {
      double s2 = 0.0;
      for (int k = 0; k < dim; k++) {
        const double x = it->pos[k][j0 + c] - it->xi[k];
        s2 += x * x;
      }
      w |= (unsigned long long)(s2 < H2) << c;
    }
    if (i - j0 < n) w &= ~(1ull << (i - j0)); /* not i itself */
    for (; w; w &= w - 1) b->j[m++] = j0 + (size_t)__builtin_ctzll(w);
  }
#pragma omp simd
  for (size_t k = 0; k < m; k++) {
    double s2 = 0.0;
    for (int a = 0; a < dim; a++) {
      const double x = it->pos[a][b->j[k]] - it->xi[a];
      b->x[a][k] = x;
      s2 += x * x;
    }
    b->s2[k] = s2;
    q2[k] = s2 * it->pk->h_inv2;
  }
  vsph_pair_fvf(it, b, q2, m, kid, unit);
  b->m = m;
  return m;
}

/** @brief vsph_pair_gather_as with V_j F in VF: the gathers' chunk. */
VSPH_CONSTS_SPECIALISE size_t vsph_pair_gather(struct vsph_pair_iter *it,
                                               int dim, int kid,
                                               struct vsph_pair_chunk *b) {
  return vsph_pair_gather_as(it, dim, kid, 0, b);
}

/** @brief The next chunk of walk @p it as vsph_pair_gather_as makes it
 *  (@p dim, @p kid, @p unit as there), into @p own or, for the first
 *  where the walk's cell made it (vsph_pair_begin_upper_in), that one:
 *  *@p bp points at it. @return its neighbours; 0 when the walk is
 *  over. */
VSPH_CONSTS_SPECIALISE size_t vsph_pair_next_chunk(
    struct vsph_pair_iter *it, int dim, int kid, const int unit,
    struct vsph_pair_chunk *own, const struct vsph_pair_chunk **bp) {
  struct vsph_pair_chunk *const b = it->ready;
  if (!b) {
    *bp = own;
    return vsph_pair_gather_as(it, dim, kid, unit, own);
  }
  it->ready = NULL;
  if (it->ready_r == SIZE_MAX) { /* the walk is over after this chunk */
    it->r = it->rg->n;
    it->j = it->end = 0;
  } else { /* it goes on here */
    it->r = it->ready_r;
    it->j = it->ready_j;
    it->end = it->rg->hi[it->r];
  }
  *bp = b;
  return vsph_pair_chunk_ready(it, b, it->ready_m, kid, unit);
}

/** @brief Pair k of chunk @p b as a vsph_pair (for the term functions). */
VSPH_CONSTS_SPECIALISE void vsph_pair_at(const struct vsph_pair_chunk *b,
                                         size_t k, int dim,
                                         struct vsph_pair *pr) {
  pr->j = b->j[k];
  for (int a = 0; a < dim; a++) pr->x[a] = b->x[a][k];
  pr->s2 = b->s2[k];
  pr->F = b->F[k];
  pr->VF = b->VF[k];
}

/* ------------------------------------------------------------ the terms */

/* The term functions return their vector shares by value: an output
 * array passed by pointer from inside a vectorised loop makes the loop's
 * locals addressable, and GCC then leaves the loop scalar. */

/** A vector of a pair (entries beyond the dimension not set). */
struct vsph_pair_vec {
  double v[3]; /*!< components */
};

/** A pair's viscous share and its dissipation density. */
struct vsph_pair_visc {
  double f[3]; /*!< the share of (div V)_i (entries beyond dim not set) */
  double dens; /*!< the pair's dissipation density (THEORY 4) */
};

/** The pair terms of PVWF's first pass (row-major d x d). */
struct vsph_pair_grad {
  double B[9]; /*!< the share of B */
  double M[9]; /*!< the share of Mg */
};

/** @brief Continuity, Eq. (3.13) of Colagrossi et al. (2011), THEORY 5:
 *  d rho_i/dt = -rho_i sum_j V_j (u_j - u_i).grad_i W_ij
 *             =  rho_i sum_j V_j F (u_j - u_i).x.
 *  @param pr the pair (x = r_j - r_i, s2, F, VF).
 *  @param dux (u_j - u_i).x (m^2/s). @return this pair's share of the sum
 *  (the caller multiplies the sum by rho_i). */
VSPH_CONSTS_SPECIALISE double vsph_pair_continuity(const struct vsph_pair *pr,
                                                   double dux) {
  return pr->VF * dux;
}

/** @brief delta-SPH density diffusion (Antuono et al. 2010, simple form;
 *  THEORY 5): V_j psi_ij.grad_i W_ij with psi_ij = 2 (rho_j - rho_i) x/s^2,
 *  = -2 V_j F (rho_j - rho_i). The caller multiplies the sum by
 *  delta h c0. @param pr the pair (x = r_j - r_i, s2, F, VF).
 *  @param drho rho_j - rho_i. */
VSPH_CONSTS_SPECIALISE double vsph_pair_delta(const struct vsph_pair *pr,
                                              double drho) {
  return -2.0 * pr->VF * drho;
}

/** @brief Pressure gradient, the PVW-compatible form of Eq. (3.13):
 *  -(1/rho_i) sum_j V_j (p_i + p_j) grad_i W_ij. @return the pair's
 *  V_j F (p_i + p_j) x; the caller sums and divides by rho_i.
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param psum p_i + p_j (Pa). */
VSPH_CONSTS_SPECIALISE struct vsph_pair_vec vsph_pair_pressure(
    const struct vsph_pair *pr, int dim, double psum) {
  struct vsph_pair_vec f;
  const double c = pr->VF * psum;
  for (int k = 0; k < dim; k++) f.v[k] = c * pr->x[k];
  return f;
}

/* ------------------------------------------------- the formulations' terms */

/* Each family of viscous formulations keeps its pair terms beside its
 * descriptors in solver/forms/ (docs/theory.md section 8 says how to add
 * one). */
#include "forms/brookshaw.h"
#include "forms/er.h"
#include "forms/morris.h"
#include "forms/stress.h"
#include "forms/takeda.h"
#include "forms/zheng.h"

/* ------------------------------- contact SPH (docs/theory.md, section 12) */

/** The acoustic Riemann problem's contact state (vsph_pair_riemann). */
struct vsph_pair_riemann_state {
  double P; /*!< the contact pressure P* */
  double U; /*!< the contact velocity U* along the pair's line */
};

/** @brief The acoustic (linearised) Riemann solution between particle i
 *  (left) and j (right) along e = (r_j - r_i)/|r_j - r_i|, Parshikov et
 *  al. eqs. (8)-(9): with Z = rho c the impedances and U^R =
 * u.e, P* = (p_j Z_i + p_i Z_j - Z_i Z_j (U_j^R - U_i^R))/(Z_i + Z_j), U*^R =
 * (U_i^R Z_i + U_j^R Z_j - p_j + p_i)/(Z_i + Z_j). It is the exact solution of
 * the linear acoustic Riemann problem: the contact state keeps p + Z_i U along
 * i's outgoing characteristic and p - Z_j U along j's. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_riemann_state vsph_pair_riemann(
    double pi, double pj, double Zi, double Zj, double uRi, double uRj) {
  const double r = 1.0 / (Zi + Zj);
  const struct vsph_pair_riemann_state st = {
      (pj * Zi + pi * Zj - Zi * Zj * (uRj - uRi)) * r,
      (uRi * Zi + uRj * Zj - pj + pi) * r};
  return st;
}

/** The shares of one pair in contact SPH (Parshikov et al. eqs. 5-6), with the
 *  acoustic Riemann solution in place of the pair averages. */
struct vsph_pair_contact_share {
  double cont;  /*!< 2 V_j F s (U*^R - U_i^R): the caller multiplies the sum
                     by rho_i for d rho_i/dt = -rho_i eps_i (eq. 5; with
                     U* the mean it is vsph_pair_continuity) */
  double diff;  /*!< the part of cont from U*'s pressure term,
                     2 V_j F s (p_i - p_j)/(Z_i + Z_j): a density diffusion */
  double f[3];  /*!< 2 V_j F P* x: the caller divides the sum by rho_i
                     (eq. 6; with P* the mean it is vsph_pair_pressure) */
  double fd[3]; /*!< the part of f from P*'s velocity term,
                     -2 V_j F Z_i Z_j/(Z_i + Z_j) (U_j^R - U_i^R) x: the
                     acoustic solver's numerical viscosity */
};

/** @brief Pair @p pr's contact-SPH shares: @p s = |x|, pressures @p pi,
 *  @p pj, impedances @p Zi, @p Zj, velocities @p ui, @p uj. Antisymmetric
 *  in i and j, so momentum is conserved pair by pair. Returned by value,
 *  as every pair function: a share written through a pointer makes the
 *  caller's locals addressable, and the loop is then not vectorised. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_contact_share vsph_pair_contact(
    const struct vsph_pair *pr, int dim, double s, double pi, double pj,
    double Zi, double Zj, const struct vsph_pair_vec ui,
    const struct vsph_pair_vec uj) {
  double uRi = 0.0, uRj = 0.0;
  for (int a = 0; a < dim; a++) {
    uRi += ui.v[a] * pr->x[a];
    uRj += uj.v[a] * pr->x[a];
  }
  const double rs = 1.0 / s;
  uRi *= rs;
  uRj *= rs;
  const struct vsph_pair_riemann_state st =
      vsph_pair_riemann(pi, pj, Zi, Zj, uRi, uRj);
  struct vsph_pair_contact_share sh = {0.0, 0.0, {0, 0, 0}, {0, 0, 0}};
  const double c = 2.0 * pr->VF * s;
  sh.cont = c * (st.U - uRi);
  sh.diff = c * (pi - pj) / (Zi + Zj);
  const double cf = 2.0 * pr->VF * st.P;
  const double cd = -2.0 * pr->VF * Zi * Zj / (Zi + Zj) * (uRj - uRi);
  for (int a = 0; a < dim; a++) {
    sh.f[a] = cf * pr->x[a];
    sh.fd[a] = cd * pr->x[a];
  }
  return sh;
}

/** @brief The viscous traction of contact SPH, Parshikov et al. eq. (35) in the
 *  frame-free form (docs/theory.md section 12): the pair's
 *  (2/rho_i) V_j |W'| tau^R with tau^R = eta' (du + (du.e) e/3)/s, i.e.
 *  -2 eta' V_j F (du + (du.x) x/(3 s^2)): Espanol & Revenga's pair with
 *  a = -2 eta', b = -2 eta'/3, through vsph_pair_er (the one copy).
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param etap eta_eff - zeta eta_eff^num (Pa s); @param du u_j - u_i.
 *  @param dux du.x.
 *  @return the pair's share and its dissipation density. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc vsph_pair_contact_visc(
    const struct vsph_pair *pr, int dim, double etap,
    const struct vsph_pair_vec du, double dux) {
  return vsph_pair_er(pr, dim, -2.0 * etap, -2.0 / 3.0 * etap, du, dux);
}

/* ------------------------------- kernel corrections (Basa et al. §4) */

/** Basa et al.'s consistency corrections of the kernel gradient (their
 *  eqs. 21-26, docs/theory.md section 10), a switch of the solver: every
 *  grad_i W_ij of the right-hand side replaced by g_ij. */
enum vsph_pair_corr {
  VSPH_PAIR_CORR_NONE = 0, /*!< grad_i W_ij */
  VSPH_PAIR_CORR_SHEPARD,  /*!< [0]: the gradient of the Shepard kernel
                                W_ij/S_i, grad W/S_i - W a_i/S_i^2 */
  VSPH_PAIR_CORR_BONETLOK, /*!< [1]: L_i times the [0] gradient, L_i the
                                inverse of sum_j V_j g0_ij (x) (r_j - r_i) */
  VSPH_PAIR_CORR_COUNT
};

/** @brief The corrected gradient g_ij of pair @p pr (W_ij = @p w) for
 *  particle i's sums S = sum_j V_j W_ij (j = i included), a = sum_j V_j
 *  grad_i W_ij and (Bonet-Lok, @p bl = 1) L (row-major); @p w = W(0) and
 *  F x = 0 give i's own term. */
VSPH_CONSTS_SPECIALISE void vsph_pair_corr_grad(const struct vsph_pair *pr,
                                                int dim, double w, double S,
                                                const double a[3],
                                                const double L[9], int bl,
                                                double g[3]) {
  const double r1 = 1.0 / S, r2 = w * r1 * r1;
  double g0[3];
  for (int k = 0; k < dim; k++) g0[k] = -pr->F * pr->x[k] * r1 - r2 * a[k];
  for (int k = 0; k < dim; k++) {
    if (!bl) {
      g[k] = g0[k];
      continue;
    }
    double y = 0.0;
    for (int c = 0; c < dim; c++) y += L[k * dim + c] * g0[c];
    g[k] = y;
  }
}

/** @brief Continuity with a corrected gradient: the pair's
 *  -V_j (u_j - u_i).g (the caller multiplies the sum by rho_i; with
 *  g = grad_i W = -F x it is vsph_pair_continuity). */
VSPH_CONSTS_SPECIALISE double vsph_pair_continuity_g(double vj, int dim,
                                                     const double du[3],
                                                     const double g[3]) {
  double y = 0.0;
  for (int k = 0; k < dim; k++) y += du[k] * g[k];
  return -vj * y;
}

/** @brief The pressure gradient with a corrected gradient: sets @p f to
 *  -V_j (p_i + p_j) g (with g = -F x, vsph_pair_pressure's share). */
VSPH_CONSTS_SPECIALISE void vsph_pair_pressure_g(double vj, int dim,
                                                 double psum, const double g[3],
                                                 double f[3]) {
  for (int k = 0; k < dim; k++) f[k] = -vj * psum * g[k];
}

#endif /* VSPH_SOLVER_PAIR_H */
