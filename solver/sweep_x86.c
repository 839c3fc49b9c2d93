/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The symmetric sweep's scatter of j's shares by AVX2 (docs/
 * performance.md): four pairs' shares transposed in registers, then a
 * receiver's fields loaded, added and stored as one vector (four fields)
 * or a pair of lanes and one lane (three), in place of a scalar load, add
 * and store per field. Whole loads and stores, no masks: a masked store is
 * not forwarded to the next particle's load of the same entry. Built for
 * its instructions alone (target attribute), as solver/pair_x86.c. */
#include "sweep_x86.h"

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
