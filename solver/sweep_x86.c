/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The symmetric sweep's scatter of j's shares by AVX2 (docs/
 * performance.md): four pairs' shares transposed in registers, then a
 * receiver's fields loaded, added and stored as one vector (four fields)
 * or a pair of lanes and one lane (three), in place of a scalar load, add
 * and store per field. Whole loads and stores, no masks: a masked store is
 * not forwarded to the next particle's load of the same entry. Built for
 * its instructions alone (target attribute), as solver/pair_x86.c. And the
 * Brookshaw forms' 2-D sweep for AVX-512: the chunk's kernel, terms, sums
 * and adds in its lanes (brookshaw2_chunk), inlined into the sweep's
 * block loops (sweep_block_parts of solver/equations_internal.h, included
 * at the end of this file in a region built for AVX-512). */
#include "sweep_x86.h"

#include <math.h>
#include <stdlib.h>

#include "pair.h"

#if VSPH_PAIR_X86 && defined(__AVX2__)

#include <immintrin.h>

/* The 4 x 4 transpose of rows r[0..3] (field a of pairs k .. k + 3) into
 * p[0..3] (fields 0-3 of pair k + l). */
static inline __attribute__((always_inline, target("avx2"))) void transpose4(
    const __m256d r[4], __m256d p[4]) {
  const __m256d t0 = _mm256_unpacklo_pd(r[0], r[1]),
                t1 = _mm256_unpackhi_pd(r[0], r[1]),
                t2 = _mm256_unpacklo_pd(r[2], r[3]),
                t3 = _mm256_unpackhi_pd(r[2], r[3]);
  p[0] = _mm256_permute2f128_pd(t0, t2, 0x20);
  p[1] = _mm256_permute2f128_pd(t1, t3, 0x20);
  p[2] = _mm256_permute2f128_pd(t0, t2, 0x31);
  p[3] = _mm256_permute2f128_pd(t1, t3, 0x31);
}

/* nf 3 or 4, a constant where inlined */
static inline __attribute__((always_inline, target("avx2"))) void add_avx2(
    double *buf, size_t lo, const int nf, const size_t *jj, size_t m,
    const double *js, size_t stride) {
  size_t k = 0;
  for (; k + 4 <= m; k += 4) {
    /* row a: field a of pairs k .. k + 3 */
    const __m256d r0 = _mm256_loadu_pd(js + k),
                  r1 = _mm256_loadu_pd(js + stride + k),
                  r2 = _mm256_loadu_pd(js + 2 * stride + k);
    const __m256d t0 = _mm256_unpacklo_pd(r0, r1),
                  t1 = _mm256_unpackhi_pd(r0, r1);
    if (nf == 4) {
      const __m256d r[4] = {r0, r1, r2, _mm256_loadu_pd(js + 3 * stride + k)};
      __m256d p[4];
      transpose4(r, p);
      for (int l = 0; l < 4; l++) {
        double *const q = buf + (jj[k + (size_t)l] - lo) * 4;
        _mm256_storeu_pd(q, _mm256_add_pd(_mm256_loadu_pd(q), p[l]));
      }
    } else {
      /* fields 0 and 1 of pair k + l as two lanes, field 2 alone */
      const __m128d p[4] = {
          _mm256_castpd256_pd128(t0), _mm256_castpd256_pd128(t1),
          _mm256_extractf128_pd(t0, 1), _mm256_extractf128_pd(t1, 1)};
      double c[4];
      _mm256_storeu_pd(c, r2);
      for (int l = 0; l < 4; l++) {
        double *const q = buf + (jj[k + (size_t)l] - lo) * 3;
        _mm_storeu_pd(q, _mm_add_pd(_mm_loadu_pd(q), p[l]));
        q[2] += c[l];
      }
    }
  }
  for (; k < m; k++) { /* the last pairs, as the scalar loop */
    double *const q = buf + (jj[k] - lo) * (size_t)nf;
    for (int a = 0; a < nf; a++) q[a] += js[(size_t)a * stride + k];
  }
}

#if VSPH_SWEEP_X86_BROOKSHAW
#define AVX512 __attribute__((target("avx512f,avx512vl,avx512dq")))

/* The lanes of the last @p left < 8 entries of a run, or all eight */
static inline __attribute__((always_inline)) AVX512 __mmask8
lanes_left(size_t left) {
  return left >= 8 ? (__mmask8)0xff : (__mmask8)((1u << left) - 1u);
}

/* a[j[l]] in lane l */
static inline __attribute__((always_inline)) AVX512 __m512d
lanes_of(const double *a, const size_t *j) {
  return _mm512_set_pd(a[j[7]], a[j[6]], a[j[5]], a[j[4]], a[j[3]], a[j[2]],
                       a[j[1]], a[j[0]]);
}

/* e^{-x} for 0 <= x <= 700, eight lanes: vsph_kernel_expneg's method
 * (n = round(x / ln 2), r = x - n ln 2 in Cody-Waite's two parts, the
 * degree-12 Taylor polynomial of e^{-r}, VSPH_KERNEL_EXPNEG_TAYLOR, times
 * 2^{-n}), its reduction by fused multiply-adds (one rounding each) and
 * 2^{-n} applied by scalef (exact), so not its bits: within 1e-15 of
 * libm's (test_expneg_within_1e15_of_exp, through
 * vsph_sweep_x86_expneg8) */
static inline __attribute__((always_inline)) AVX512 __m512d expneg8(__m512d x) {
#define K(v) _mm512_set1_pd(v)
  const __m512d shift = K(VSPH_KERNEL_EXPNEG_SHIFT);
  const __m512d n = _mm512_sub_pd(
      _mm512_fmadd_pd(x, K(VSPH_KERNEL_EXPNEG_LOG2E), shift), shift);
  const __m512d r =
      _mm512_fnmadd_pd(n, K(VSPH_KERNEL_EXPNEG_LN2_LO),
                       _mm512_fnmadd_pd(n, K(VSPH_KERNEL_EXPNEG_LN2_HI), x));
  const __m512d r2 = _mm512_mul_pd(r, r), r4 = _mm512_mul_pd(r2, r2),
                r8 = _mm512_mul_pd(r4, r4);
  const __m512d p =
      VSPH_KERNEL_EXPNEG_TAYLOR(_mm512_fmadd_pd, K, r, r2, r4, r8);
#undef K
  return _mm512_scalef_pd(p, _mm512_sub_pd(_mm512_setzero_pd(), n));
}

/* The Brookshaw forms' chunk (solver/sweep_x86.h: what
 * vsph_sweep_x86_brookshaw2 does with each chunk): for the @p m
 * neighbours jj[k] of receiver i (their x0, x1 = r_j - r_i and s2; F not
 * set), the kernel factor (@p dwq, @p h_inv2), the continuity, pressure
 * and viscous (Kmu, eta2: vsph_pair_mgf) shares, eight pairs at a time,
 * the last ones masked; i's sums added to sums[0] (continuity),
 * sums[1..2] (force), each in eight lanes, then the lanes in
 * _mm512_reduce_add_pd's order; j's shares (-V_i f, V_i c) added to
 * entries buf + (jj[k] - lo) * 3, fields 0 and 1 as a pair of lanes and
 * field 2 alone. The same terms as the scalar loops, not their bits:
 * products and sums fused where they meet (d u . x, F (p_i + p_j + the
 * viscous factor) rather than the pressure and viscous shares apart, i's
 * sums), another exponential (expneg8) and another order of i's sums:
 * within rounding of the four-lane loops (test_sweep_scatter_simd).
 * Receiver i's velocity @p ui0, @p ui1, pressure @p pi and volume @p Vi;
 * the set's velocities @p vx, @p vy, pressures @p pp and volumes @p vol.
 * Returns the least of @p rs2 and the chunk's s2 (exact in any order). */
static inline __attribute__((always_inline)) AVX512 double brookshaw2_chunk(
    const size_t *jj, const double *x0, const double *x1, const double *s2,
    size_t m, const double *vx, const double *vy, const double *pp,
    const double *vol, double ui0, double ui1, double pi, double Vi,
    double h_inv2, double dwq, double Kmu, double eta2, double sums[3],
    double *buf, size_t lo, double rs2) {
  const __m512d vui0 = _mm512_set1_pd(ui0), vui1 = _mm512_set1_pd(ui1),
                vpi = _mm512_set1_pd(pi), vVi = _mm512_set1_pd(Vi),
                vnVi = _mm512_set1_pd(-Vi), vhi2 = _mm512_set1_pd(h_inv2),
                vdwq = _mm512_set1_pd(-2.0 * dwq), /* -2 exact: F's factor */
      vnKmu = _mm512_set1_pd(-Kmu), veta2 = _mm512_set1_pd(eta2),
                nine = _mm512_set1_pd(9.0);
  __m512d vmin = _mm512_set1_pd(rs2);
  /* i's sums, lane by lane: the masked lanes add 0 */
  __m512d ac = _mm512_setzero_pd(), af0 = ac, af1 = ac;
  for (size_t k = 0; k < m; k += 8) {
    const int full = m - k >= 8;
    const __mmask8 km = lanes_left(m - k);
    /* past the chunk: x = 0 and s2 infinite, so F = 0 and every share 0 */
    const __m512d X0 = _mm512_maskz_loadu_pd(km, x0 + k),
                  X1 = _mm512_maskz_loadu_pd(km, x1 + k),
                  S2 = _mm512_mask_loadu_pd(_mm512_set1_pd(HUGE_VAL), km,
                                            s2 + k);
    vmin = _mm512_min_pd(vmin, S2);
    /* F = dwq (-2 e^{-q^2}), 0 from q^2 = 9 */
    const __m512d q2 = _mm512_mul_pd(S2, vhi2);
    const __mmask8 in = _mm512_cmp_pd_mask(q2, nine, _CMP_LT_OQ);
    const __m512d F = _mm512_maskz_mul_pd(in, vdwq, expneg8(q2));
    /* the lanes past the chunk read pair k's neighbour again */
    size_t jt[8];
    const size_t *j = jj + k;
    if (!full) {
      for (size_t l = 0; l < 8; l++) jt[l] = j[l < m - k ? l : 0];
      j = jt;
    }
    const __m512d U0 = lanes_of(vx, j), U1 = lanes_of(vy, j),
                  P = lanes_of(pp, j), V = lanes_of(vol, j);
    /* d u . x; c = F d u . x (continuity); F (p_i + p_j - Kmu d u . x /
     * (s2 + eta2)) x (pressure and viscous force, vsph_pair_mgf's and
     * vsph_pair_pressure's terms) */
    const __m512d dux =
        _mm512_fmadd_pd(_mm512_sub_pd(U1, vui1), X1,
                        _mm512_mul_pd(_mm512_sub_pd(U0, vui0), X0));
    const __m512d c = _mm512_mul_pd(F, dux);
    const __m512d fx = _mm512_mul_pd(
        F, _mm512_add_pd(_mm512_add_pd(vpi, P),
                         _mm512_div_pd(_mm512_mul_pd(vnKmu, dux),
                                       _mm512_add_pd(S2, veta2))));
    const __m512d f0 = _mm512_mul_pd(fx, X0), f1 = _mm512_mul_pd(fx, X1);
    /* j's shares (-V_i f, V_i c), added to their receivers' entries (the
     * receivers of a chunk are distinct, so each entry gets one add a
     * pair, in any order) */
    const __m512d g0 = _mm512_mul_pd(vnVi, f0), g1 = _mm512_mul_pd(vnVi, f1);
    const __m512d t0 = _mm512_unpacklo_pd(g0, g1), /* pairs 0, 2, 4, 6 */
        t1 = _mm512_unpackhi_pd(g0, g1);           /* pairs 1, 3, 5, 7 */
    __m128d q01[8];                                /* pair l's fields 0 and 1 */
    q01[0] = _mm512_castpd512_pd128(t0);
    q01[1] = _mm512_castpd512_pd128(t1);
    q01[2] = _mm512_extractf64x2_pd(t0, 1);
    q01[3] = _mm512_extractf64x2_pd(t1, 1);
    q01[4] = _mm512_extractf64x2_pd(t0, 2);
    q01[5] = _mm512_extractf64x2_pd(t1, 2);
    q01[6] = _mm512_extractf64x2_pd(t0, 3);
    q01[7] = _mm512_extractf64x2_pd(t1, 3);
    double c2[8];
    _mm512_storeu_pd(c2, _mm512_mul_pd(vVi, c));
#define ADD_J(l)                                             \
  do {                                                       \
    double *const q = buf + (jj[k + (l)] - lo) * 3;          \
    _mm_storeu_pd(q, _mm_add_pd(_mm_loadu_pd(q), q01[(l)])); \
    q[2] += c2[(l)];                                         \
  } while (0)
    if (full) /* eight, without a test each */
      for (size_t l = 0; l < 8; l++) ADD_J(l);
    else
      for (size_t l = 0; l < m - k; l++) ADD_J(l);
#undef ADD_J
    ac = _mm512_fmadd_pd(V, c, ac);
    af0 = _mm512_fmadd_pd(V, f0, af0);
    af1 = _mm512_fmadd_pd(V, f1, af1);
  }
  sums[0] += _mm512_reduce_add_pd(ac);
  sums[1] += _mm512_reduce_add_pd(af0);
  sums[2] += _mm512_reduce_add_pd(af1);
  return _mm512_reduce_min_pd(vmin);
}

AVX512 void vsph_sweep_x86_expneg8(const double *x, double *y, size_t n) {
  for (size_t k = 0; k < n; k += 8) {
    const __mmask8 km = lanes_left(n - k);
    _mm512_mask_storeu_pd(y + k, km, expneg8(_mm512_maskz_loadu_pd(km, x + k)));
  }
}

#endif /* VSPH_SWEEP_X86_BROOKSHAW: the chunk */

__attribute__((target("avx2"))) void vsph_sweep_x86_add_avx2(
    double *buf, size_t lo, int nf, const size_t *jj, size_t m,
    const double *js, size_t stride) {
  if (nf == 4)
    add_avx2(buf, lo, 4, jj, m, js, stride);
  else
    add_avx2(buf, lo, 3, jj, m, js, stride);
}

__attribute__((target("avx2"))) void vsph_sweep_x86_add8_avx2(
    double *buf, size_t lo, const size_t *jj, size_t m, const double *u,
    size_t stride, double v) {
  const __m256d vv = _mm256_set1_pd(v);
  size_t k = 0;
  for (; k + 4 <= m; k += 4) {
    __m256d r[4], p0[4], p1[4];
    for (int a = 0; a < 4; a++)
      r[a] = _mm256_mul_pd(vv, _mm256_loadu_pd(u + (size_t)a * stride + k));
    transpose4(r, p0);
    for (int a = 0; a < 4; a++)
      r[a] =
          _mm256_mul_pd(vv, _mm256_loadu_pd(u + (size_t)(4 + a) * stride + k));
    transpose4(r, p1);
    for (int l = 0; l < 4; l++) {
      double *const q = buf + (jj[k + (size_t)l] - lo) * 8;
      _mm256_storeu_pd(q, _mm256_add_pd(_mm256_loadu_pd(q), p0[l]));
      _mm256_storeu_pd(q + 4, _mm256_add_pd(_mm256_loadu_pd(q + 4), p1[l]));
    }
  }
  for (; k < m; k++) { /* the last pairs, as the scalar loop */
    double *const q = buf + (jj[k] - lo) * 8;
    for (int a = 0; a < 8; a++) q[a] += v * u[(size_t)a * stride + k];
  }
}

/* The sweep's block loops (solver/equations_internal.h) built here for
 * AVX-512 too, so that the chunk above inlines into them: their other
 * work has no sum in floating point (the chunk's are its own), so it is
 * the generic instance's to the bit. The header's inline
 * functions keep the AVX-512 target in the rest of this file: this
 * region stays at its end, and nothing below it calls them. */
#if VSPH_SWEEP_X86_BROOKSHAW
#ifdef VSPH_SOLVER_EQUATIONS_INTERNAL_H
#error "solver/equations_internal.h must first be included here"
#endif
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512dq")
#define VSPH_SWEEP_BROOKSHAW2_CHUNK brookshaw2_chunk
#include "equations_internal.h"

size_t vsph_sweep_x86_brookshaw2(const struct vsph_equations_ctx *rc,
                                 const struct vsph_particles *p,
                                 const struct vsph_cells *cells, size_t n_fluid,
                                 const struct vsph_equations_sweep *sw,
                                 size_t blk, double *min_s2) {
  return sweep_block_parts(rc, p, cells, n_fluid, sw, blk, min_s2, 2, NULL, 0,
                           VSPH_KERNEL_DFQ_GAUSSIAN, 0, 2);
}
#pragma GCC pop_options
#endif

#else

void vsph_sweep_x86_add8_avx2(double *buf, size_t lo, const size_t *jj,
                              size_t m, const double *u, size_t stride,
                              double v) {
  (void)buf;
  (void)lo;
  (void)jj;
  (void)m;
  (void)u;
  (void)stride;
  (void)v;
  abort();
}

void vsph_sweep_x86_add_avx2(double *buf, size_t lo, int nf, const size_t *jj,
                             size_t m, const double *js, size_t stride) {
  (void)buf;
  (void)lo;
  (void)nf;
  (void)jj;
  (void)m;
  (void)js;
  (void)stride;
  abort();
}

#endif
