/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The candidate test of vsph_pair_gather_as in 2-D and 3-D with AVX-512
 * (docs/performance.md): eight candidates at a time, their r_j - r_i and
 * s^2 computed as the portable loop computes them (x = pos_j - x_i per
 * component, s^2 = (x0 x0 + x1 x1) + x2 x2: the same operations, so the
 * same bits),
 * the neighbours' x, s^2 and index packed into the chunk by the lanes'
 * compress rather than found bit by bit and gathered again; with AVX2,
 * four at a time. Chosen at run time (vsph_pair_x86_simd), each function
 * alone built for its instructions: the rest of the code, its
 * reductions' widths included, is the build's. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "pair.h"

#if VSPH_PAIR_X86 && defined(__AVX2__)

#include <immintrin.h>

/* A whole vector is stored at m, the neighbours so far: m < CHUNK when a
 * block of at most 64 candidates begins and grows by at most the lanes
 * tested before a store, so a store at candidate c of a block ends at
 * m + W <= (CHUNK - 1) + c + W <= CHUNK - 1 + 64 (c + W <= 64). */
_Static_assert(VSPH_PAIR_CHUNK_MAX >= VSPH_PAIR_CHUNK - 1 + 64,
               "a chunk holds a whole vector stored at its last neighbour");
_Static_assert(sizeof(size_t) == 8, "indices stored as 64-bit lanes");

int vsph_pair_x86_simd(void) {
  const char *cap = getenv("VSPH_PAIR_SIMD");
  const int most = !cap || !*cap              ? 2
                   : !strcmp(cap, "avx2")     ? 1
                   : !strcmp(cap, "portable") ? 0
                                              : 2;
  if (most >= 2 && __builtin_cpu_supports("avx512f") &&
      __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq"))
    return 2;
  if (most >= 1 && __builtin_cpu_supports("avx2")) return 1;
  return 0;
}

/* Append the neighbours (lanes set in @p k) of one vector of candidates,
 * their x, s^2 and index, to chunk @p b at m by the lanes' compress: whole
 * vectors, the lanes past the neighbours written over by the next
 * (candidates_avx512 and the joint walk's lanes_avx512). Returns the new
 * count. */
static inline
    __attribute__((always_inline, target("avx512f,avx512vl,avx512dq"))) size_t
    append_avx512(struct vsph_pair_chunk *b, size_t m, __mmask8 k, __m512d dx,
                  __m512d dy, __m512d dz, __m512d s2, __m512i j,
                  const int dim) {
  _mm512_storeu_pd(b->x[0] + m, _mm512_maskz_compress_pd(k, dx));
  _mm512_storeu_pd(b->x[1] + m, _mm512_maskz_compress_pd(k, dy));
  if (dim == 3) _mm512_storeu_pd(b->x[2] + m, _mm512_maskz_compress_pd(k, dz));
  _mm512_storeu_pd(b->s2 + m, _mm512_maskz_compress_pd(k, s2));
  _mm512_storeu_si512((void *)(b->j + m), _mm512_maskz_compress_epi64(k, j));
  return m + (size_t)__builtin_popcount((unsigned)k);
}

/* The test of one vector of candidates X, Y, Z (live lanes @p live)
 * against receiver (xi, yi, zi), broadcast: their x = r_j - r_i in *dx,
 * *dy, *dz and s^2 in *s2, and which live lanes lie within H2 (the
 * candidate test's and the joint walk's one test: the same operations,
 * so the same bits). @p dim 2 or 3, a constant where inlined. */
static inline
    __attribute__((always_inline, target("avx512f,avx512vl,avx512dq"))) __mmask8
    near_avx512(__m512d X, __m512d Y, __m512d Z, __m512d xi, __m512d yi,
                __m512d zi, __mmask8 live, __m512d H2, const int dim,
                __m512d *dx, __m512d *dy, __m512d *dz, __m512d *s2) {
  *dx = _mm512_sub_pd(X, xi);
  *dy = _mm512_sub_pd(Y, yi);
  *dz = dim == 3 ? _mm512_sub_pd(Z, zi) : _mm512_setzero_pd();
  __m512d q = _mm512_add_pd(_mm512_mul_pd(*dx, *dx), _mm512_mul_pd(*dy, *dy));
  if (dim == 3) q = _mm512_add_pd(q, _mm512_mul_pd(*dz, *dz));
  *s2 = q;
  return _mm512_mask_cmp_pd_mask(live, q, H2, _CMP_LT_OQ);
}

/* dim 2 or 3, a constant where inlined */
static inline
    __attribute__((always_inline, target("avx512f,avx512vl,avx512dq"))) size_t
    candidates_avx512(struct vsph_pair_iter *it, struct vsph_pair_chunk *b,
                      const int dim) {
  const __m512d H2 = _mm512_set1_pd(it->pk->H2);
  const __m512d xi = _mm512_set1_pd(it->xi[0]), yi = _mm512_set1_pd(it->xi[1]),
                zi = _mm512_set1_pd(dim == 3 ? it->xi[2] : 0.0);
  const __m512i lane = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  const double *const px = it->pos[0], *const py = it->pos[1],
                      *const pz = dim == 3 ? it->pos[2] : NULL;
  const size_t i = it->i;
  size_t m = 0;
  while (m < VSPH_PAIR_CHUNK) {
    size_t j0;
    const size_t n = vsph_pair_next_block(it, &j0);
    if (!n) break;
    for (size_t c = 0; c < n; c += 8) {
      const __mmask8 live =
          n - c >= 8 ? (__mmask8)0xff : (__mmask8)((1u << (n - c)) - 1u);
      __m512d dx, dy, dz, s2;
      __mmask8 k =
          near_avx512(_mm512_maskz_loadu_pd(live, px + j0 + c),
                      _mm512_maskz_loadu_pd(live, py + j0 + c),
                      dim == 3 ? _mm512_maskz_loadu_pd(live, pz + j0 + c)
                               : _mm512_setzero_pd(),
                      xi, yi, zi, live, H2, dim, &dx, &dy, &dz, &s2);
      if (i - (j0 + c) < 8) k &= (__mmask8) ~(1u << (i - (j0 + c)));
      if (!k) continue;
      /* m + 8 stays within the chunk */
      const __m512i j =
          _mm512_add_epi64(_mm512_set1_epi64((long long)(j0 + c)), lane);
      m = append_avx512(b, m, k, dx, dy, dz, s2, j, dim);
    }
  }
  return m;
}

__attribute__((target("avx512f,avx512vl,avx512dq"))) size_t
vsph_pair_x86_candidates_avx512(struct vsph_pair_iter *it,
                                struct vsph_pair_chunk *b) {
  return it->pk->dim == 3 ? candidates_avx512(it, b, 3)
                          : candidates_avx512(it, b, 2);
}

/* A cell's upper walks together (vsph_pair_x86_upper_cell_avx512, _avx2),
 * for receivers pc->s0.. (cnt of them) by vectors of W candidates: the
 * rows before their own hold no j > i; in their own row (they are
 * consecutive in it) each walks from i + 1; in the rows after it each
 * vector of candidates is loaded once (LOAD(j0, c, n): X, Y, Z, J and the
 * live lanes) and tested against every receiver whose first chunk is
 * still open (LANES(i, q)). A walk's blocks are its own walk's (64
 * candidates from the start of each range, or from i + 1), and as there
 * a chunk holding VSPH_PAIR_CHUNK neighbours or more at the end of a
 * block is complete: that walk goes on alone from the next block (pc->r,
 * pc->j). The body of upper_cell_avx512 and _avx2, so that the two widths
 * share one walk: a macro, not a function, because its vectors are of
 * the width's own intrinsic types and a function built for one target
 * cannot take the other's (the one macro template of the code). */
#define UPPER_CELL_WALK(W, LOAD, LANES)                                        \
  do {                                                                         \
    const size_t i0 = pc->s0;                                                  \
    size_t row0 = 0; /* the receivers' own row */                              \
    while (row0 < rg->n && !(rg->lo[row0] <= i0 && i0 < rg->hi[row0])) row0++; \
    if (row0 == rg->n || i0 + cnt > rg->hi[row0]) {                            \
      /* not all in one of these ranges: each walks alone */                   \
      for (size_t q = 0; q < cnt; q++) pc->m[q] = SIZE_MAX;                    \
      break;                                                                   \
    }                                                                          \
    /* the counts in a local array: the chunks' stores cannot alias it */      \
    size_t m[VSPH_PAIR_JOINT];                                                 \
    unsigned open = 0; /* the walks still in their first chunk */              \
    for (size_t q = 0; q < cnt; q++) {                                         \
      const size_t i = i0 + q, j0 = i + 1, n = rg->hi[row0] - j0;              \
      m[q] = 0;                                                                \
      pc->r[q] = SIZE_MAX; /* the walk ends with its first chunk ... */        \
      open |= 1u << q;                                                         \
      for (size_t c = 0; c < n; c += (W)) {                                    \
        LOAD(j0, c, n);                                                        \
        LANES(i, q);                                                           \
        const size_t e = c + (W) < n ? c + (W) : n;                            \
        if ((e % 64 == 0 || e == n) && m[q] >= VSPH_PAIR_CHUNK) {              \
          pc->r[q] = row0; /* ... or goes on alone from here */                \
          pc->j[q] = j0 + e;                                                   \
          open &= ~(1u << q);                                                  \
          break;                                                               \
        }                                                                      \
      }                                                                        \
    }                                                                          \
    for (size_t r = row0 + 1; r < rg->n && open; r++) {                        \
      const size_t j0 = rg->lo[r], n = rg->hi[r] - j0;                         \
      for (size_t c = 0; c < n && open; c += (W)) {                            \
        LOAD(j0, c, n);                                                        \
        const size_t e = c + (W) < n ? c + (W) : n;                            \
        const int ends = e % 64 == 0 || e == n; /* a block ends */             \
        for (size_t q = 0; q < cnt; q++) {                                     \
          if (!(open >> q & 1u)) continue;                                     \
          LANES(i0 + q, q);                                                    \
          if (ends && m[q] >= VSPH_PAIR_CHUNK) {                               \
            pc->r[q] = r;                                                      \
            pc->j[q] = j0 + e;                                                 \
            open &= ~(1u << q);                                                \
          }                                                                    \
        }                                                                      \
      }                                                                        \
    }                                                                          \
    for (size_t q = 0; q < cnt; q++) pc->m[q] = m[q];                          \
  } while (0)

/* UPPER_CELL_WALK's lanes by AVX-512 in @p dim (a constant where
 * inlined): the candidates X, Y, Z, J (live lanes @p live) tested for
 * receiver i, its neighbours' x, s^2 and index appended to @p b at *m as
 * the candidate test appends them (the same operations, so the same
 * bits) */
static inline
    __attribute__((always_inline, target("avx512f,avx512vl,avx512dq"))) void
    lanes_avx512(const double *const pos[3], size_t i, __m512d X, __m512d Y,
                 __m512d Z, __m512i J, __mmask8 live, __m512d H2,
                 struct vsph_pair_chunk *b, size_t *m, const int dim) {
  __m512d dx, dy, dz, s2;
  const __mmask8 k =
      near_avx512(X, Y, Z, _mm512_set1_pd(pos[0][i]), _mm512_set1_pd(pos[1][i]),
                  dim == 3 ? _mm512_set1_pd(pos[2][i]) : _mm512_setzero_pd(),
                  live, H2, dim, &dx, &dy, &dz, &s2);
  *m = append_avx512(b, *m, k, dx, dy, dz, s2, J, dim);
}

static inline
    __attribute__((always_inline, target("avx512f,avx512vl,avx512dq"))) void
    upper_cell_avx512(const struct vsph_pair_kernel *pk,
                      const double *const pos[3],
                      const struct vsph_pair_ranges *rg,
                      struct vsph_pair_cell *pc, size_t cnt, const int dim) {
  const __m512d H2 = _mm512_set1_pd(pk->H2);
  const __m512i lane = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
#define LOAD512(J0, C, N)                                                     \
  const __mmask8 live =                                                       \
      (N) - (C) >= 8 ? (__mmask8)0xff : (__mmask8)((1u << ((N) - (C))) - 1u); \
  const __m512d X = _mm512_maskz_loadu_pd(live, pos[0] + (J0) + (C)),         \
                Y = _mm512_maskz_loadu_pd(live, pos[1] + (J0) + (C)),         \
                Z = dim == 3                                                  \
                        ? _mm512_maskz_loadu_pd(live, pos[2] + (J0) + (C))    \
                        : _mm512_setzero_pd();                                \
  const __m512i J =                                                           \
      _mm512_add_epi64(_mm512_set1_epi64((long long)((J0) + (C))), lane)
#define LANES512(I, Q) \
  lanes_avx512(pos, (I), X, Y, Z, J, live, H2, &pc->b[Q], &m[Q], dim)
  UPPER_CELL_WALK(8, LOAD512, LANES512);
#undef LANES512
#undef LOAD512
}

__attribute__((target("avx512f,avx512vl,avx512dq"))) void
vsph_pair_x86_upper_cell_avx512(const struct vsph_pair_kernel *pk,
                                const double *const pos[3],
                                const struct vsph_pair_ranges *rg,
                                struct vsph_pair_cell *pc, size_t cnt) {
  if (pk->dim == 3)
    upper_cell_avx512(pk, pos, rg, pc, cnt, 3);
  else
    upper_cell_avx512(pk, pos, rg, pc, cnt, 2);
}

/* The same with AVX2 (x86-64-v3), four candidates at a time: AVX2 has no
 * compress, so the neighbours' lanes are moved to the front by a
 * permutation looked up by the lane mask (each double as two 32-bit
 * halves). */
/* PERM[mask]: the 32-bit lanes of the neighbours' doubles first, in lane
 * order; the rest any (written over) */
static const int32_t PERM[16][8] = {
    {0, 1, 2, 3, 4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7},
    {2, 3, 2, 3, 4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7},
    {4, 5, 2, 3, 4, 5, 6, 7}, {0, 1, 4, 5, 4, 5, 6, 7},
    {2, 3, 4, 5, 4, 5, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7},
    {6, 7, 2, 3, 4, 5, 6, 7}, {0, 1, 6, 7, 4, 5, 6, 7},
    {2, 3, 6, 7, 4, 5, 6, 7}, {0, 1, 2, 3, 6, 7, 6, 7},
    {4, 5, 6, 7, 4, 5, 6, 7}, {0, 1, 4, 5, 6, 7, 6, 7},
    {2, 3, 4, 5, 6, 7, 6, 7}, {0, 1, 2, 3, 4, 5, 6, 7}};

/* append_avx512 with AVX2: the neighbours' lanes (bits set in @p k) moved
 * to the front by the permutation PERM[k] (candidates_avx2 and the joint
 * walk's lanes_avx2) */
static inline __attribute__((always_inline, target("avx2"))) size_t append_avx2(
    struct vsph_pair_chunk *b, size_t m, unsigned k, __m256d dx, __m256d dy,
    __m256d dz, __m256d s2, __m256i j, const int dim) {
  const __m256i p = _mm256_loadu_si256((const __m256i *)(const void *)PERM[k]);
  _mm256_storeu_pd(b->x[0] + m, _mm256_castps_pd(_mm256_permutevar8x32_ps(
                                    _mm256_castpd_ps(dx), p)));
  _mm256_storeu_pd(b->x[1] + m, _mm256_castps_pd(_mm256_permutevar8x32_ps(
                                    _mm256_castpd_ps(dy), p)));
  if (dim == 3)
    _mm256_storeu_pd(b->x[2] + m, _mm256_castps_pd(_mm256_permutevar8x32_ps(
                                      _mm256_castpd_ps(dz), p)));
  _mm256_storeu_pd(b->s2 + m, _mm256_castps_pd(_mm256_permutevar8x32_ps(
                                  _mm256_castpd_ps(s2), p)));
  _mm256_storeu_si256((__m256i *)(void *)(b->j + m),
                      _mm256_permutevar8x32_epi32(j, p));
  return m + (size_t)__builtin_popcount(k);
}

/* near_avx512 with AVX2: @p live the live lanes' bits */
static inline __attribute__((always_inline, target("avx2"))) unsigned near_avx2(
    __m256d X, __m256d Y, __m256d Z, __m256d xi, __m256d yi, __m256d zi,
    unsigned live, __m256d H2, const int dim, __m256d *dx, __m256d *dy,
    __m256d *dz, __m256d *s2) {
  *dx = _mm256_sub_pd(X, xi);
  *dy = _mm256_sub_pd(Y, yi);
  *dz = dim == 3 ? _mm256_sub_pd(Z, zi) : _mm256_setzero_pd();
  __m256d q = _mm256_add_pd(_mm256_mul_pd(*dx, *dx), _mm256_mul_pd(*dy, *dy));
  if (dim == 3) q = _mm256_add_pd(q, _mm256_mul_pd(*dz, *dz));
  *s2 = q;
  return (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(q, H2, _CMP_LT_OQ)) & live;
}

static inline __attribute__((always_inline, target("avx2"))) size_t
candidates_avx2(struct vsph_pair_iter *it, struct vsph_pair_chunk *b,
                const int dim) {
  const __m256d H2 = _mm256_set1_pd(it->pk->H2);
  const __m256d xi = _mm256_set1_pd(it->xi[0]), yi = _mm256_set1_pd(it->xi[1]),
                zi = _mm256_set1_pd(dim == 3 ? it->xi[2] : 0.0);
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3);
  const double *const px = it->pos[0], *const py = it->pos[1],
                      *const pz = dim == 3 ? it->pos[2] : NULL;
  const size_t i = it->i;
  size_t m = 0;
  while (m < VSPH_PAIR_CHUNK) {
    size_t j0;
    const size_t n = vsph_pair_next_block(it, &j0);
    if (!n) break;
    for (size_t c = 0; c < n; c += 4) {
      const size_t left = n - c;
      const __m256i live = _mm256_cmpgt_epi64(
          _mm256_set1_epi64x((long long)(left < 4 ? left : 4)), lane);
      __m256d dx, dy, dz, s2;
      unsigned k = near_avx2(
          _mm256_maskload_pd(px + j0 + c, live),
          _mm256_maskload_pd(py + j0 + c, live),
          dim == 3 ? _mm256_maskload_pd(pz + j0 + c, live)
                   : _mm256_setzero_pd(),
          xi, yi, zi, (unsigned)_mm256_movemask_pd(_mm256_castsi256_pd(live)),
          H2, dim, &dx, &dy, &dz, &s2);
      if (i - (j0 + c) < 4) k &= ~(1u << (i - (j0 + c)));
      if (!k) continue;
      const __m256i j =
          _mm256_add_epi64(_mm256_set1_epi64x((long long)(j0 + c)), lane);
      m = append_avx2(b, m, k, dx, dy, dz, s2, j, dim);
    }
  }
  return m;
}

/* UPPER_CELL_WALK's lanes by AVX2 (lanes_avx512 with four) */
static inline __attribute__((always_inline, target("avx2"))) void lanes_avx2(
    const double *const pos[3], size_t i, __m256d X, __m256d Y, __m256d Z,
    __m256i J, unsigned live, __m256d H2, struct vsph_pair_chunk *b, size_t *m,
    const int dim) {
  __m256d dx, dy, dz, s2;
  const unsigned k =
      near_avx2(X, Y, Z, _mm256_set1_pd(pos[0][i]), _mm256_set1_pd(pos[1][i]),
                dim == 3 ? _mm256_set1_pd(pos[2][i]) : _mm256_setzero_pd(),
                live, H2, dim, &dx, &dy, &dz, &s2);
  *m = append_avx2(b, *m, k, dx, dy, dz, s2, J, dim);
}

static inline __attribute__((always_inline, target("avx2"))) void
upper_cell_avx2(const struct vsph_pair_kernel *pk, const double *const pos[3],
                const struct vsph_pair_ranges *rg, struct vsph_pair_cell *pc,
                size_t cnt, const int dim) {
  const __m256d H2 = _mm256_set1_pd(pk->H2);
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3);
#define LOAD256(J0, C, N)                                                     \
  const size_t left = (N) - (C);                                              \
  const __m256i livev = _mm256_cmpgt_epi64(                                   \
      _mm256_set1_epi64x((long long)(left < 4 ? left : 4)), lane);            \
  const unsigned live =                                                       \
      (unsigned)_mm256_movemask_pd(_mm256_castsi256_pd(livev));               \
  const __m256d X = _mm256_maskload_pd(pos[0] + (J0) + (C), livev),           \
                Y = _mm256_maskload_pd(pos[1] + (J0) + (C), livev),           \
                Z = dim == 3 ? _mm256_maskload_pd(pos[2] + (J0) + (C), livev) \
                             : _mm256_setzero_pd();                           \
  const __m256i J =                                                           \
      _mm256_add_epi64(_mm256_set1_epi64x((long long)((J0) + (C))), lane)
#define LANES256(I, Q) \
  lanes_avx2(pos, (I), X, Y, Z, J, live, H2, &pc->b[Q], &m[Q], dim)
  UPPER_CELL_WALK(4, LOAD256, LANES256);
#undef LANES256
#undef LOAD256
}

__attribute__((target("avx2"))) void vsph_pair_x86_upper_cell_avx2(
    const struct vsph_pair_kernel *pk, const double *const pos[3],
    const struct vsph_pair_ranges *rg, struct vsph_pair_cell *pc, size_t cnt) {
  if (pk->dim == 3)
    upper_cell_avx2(pk, pos, rg, pc, cnt, 3);
  else
    upper_cell_avx2(pk, pos, rg, pc, cnt, 2);
}

__attribute__((target("avx2"))) size_t vsph_pair_x86_candidates_avx2(
    struct vsph_pair_iter *it, struct vsph_pair_chunk *b) {
  return it->pk->dim == 3 ? candidates_avx2(it, b, 3)
                          : candidates_avx2(it, b, 2);
}

#elif VSPH_PAIR_X86

/* The baseline copy (no AVX2 in the build): the portable loops always; the
 * candidate functions are never called (vsph_pair_kernel_init sets simd 0)
 * and exist so that code built with AVX2 links against this copy too. */
int vsph_pair_x86_simd(void) { return 0; }

size_t vsph_pair_x86_candidates_avx512(struct vsph_pair_iter *it,
                                       struct vsph_pair_chunk *b) {
  (void)it;
  (void)b;
  abort();
}

size_t vsph_pair_x86_candidates_avx2(struct vsph_pair_iter *it,
                                     struct vsph_pair_chunk *b) {
  (void)it;
  (void)b;
  abort();
}

void vsph_pair_x86_upper_cell_avx512(const struct vsph_pair_kernel *pk,
                                     const double *const pos[3],
                                     const struct vsph_pair_ranges *rg,
                                     struct vsph_pair_cell *pc, size_t cnt) {
  (void)pk;
  (void)pos;
  (void)rg;
  (void)pc;
  (void)cnt;
  abort();
}

void vsph_pair_x86_upper_cell_avx2(const struct vsph_pair_kernel *pk,
                                   const double *const pos[3],
                                   const struct vsph_pair_ranges *rg,
                                   struct vsph_pair_cell *pc, size_t cnt) {
  vsph_pair_x86_upper_cell_avx512(pk, pos, rg, pc, cnt);
}

#endif
