/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The symmetric sweep's scatter of j's shares by AVX2 (docs/
 * performance.md): four pairs' shares transposed in registers, then a
 * receiver's fields loaded, added and stored as one vector (four fields)
 * or a pair of lanes and one lane (three), in place of a scalar load, add
 * and store per field. Whole loads and stores, no masks: a masked store is
 * not forwarded to the next particle's load of the same entry. Built for
 * its instructions alone (target attribute), as solver/pair_x86.c. And the
 * 2-D sweep by cell groups of the Brookshaw forms, MEAF and the stress
 * forms' second pass, for AVX-512
 * (vsph_sweep_x86_groups2_avx512) and for AVX2 (_avx2), and the stress
 * forms' first pass in the same walk (vsph_sweep_x86_grad2_avx512,
 * _avx2): a cell's
 * receivers, eight at a time, against whole vectors of eight (four)
 * consecutive candidates, every pair's work in the lanes whether the pair
 * lies within the support or not (masked, or cleared), as GROMACS's
 * cluster-pair kernels do: no candidate list, gather or scatter. */
#include "sweep_x86.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "equations_internal.h"
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

#if VSPH_SWEEP_X86_GROUPS
#define AVX512 __attribute__((target("avx512f,avx512vl,avx512dq")))

/* The lanes of the last @p left < 8 entries of a run, or all eight */
static inline __attribute__((always_inline)) AVX512 __mmask8
lanes_left(size_t left) {
  return left >= 8 ? (__mmask8)0xff : (__mmask8)((1u << left) - 1u);
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

AVX512 void vsph_sweep_x86_expneg8(const double *x, double *y, size_t n) {
  for (size_t k = 0; k < n; k += 8) {
    const __mmask8 km = lanes_left(n - k);
    _mm512_mask_storeu_pd(y + k, km, expneg8(_mm512_maskz_loadu_pd(km, x + k)));
  }
}

/* Add fields A, B, C, D (0 to 3; D where @p nf is 4, a constant where
 * inlined) of @p nl <= 8 consecutive particles' j shares to their entries
 * q[0 .. nf nl - 1] (nf fields a particle): the lanes interleaved in
 * registers (three fields by two-source permutes, four by a 4 x 4
 * transpose of pairs of lanes), then whole vectors loaded, added and
 * stored, or masked ones for a range's last particles (whose next
 * entries, at the end of the block's buffer, are another block's, which
 * another thread may be writing) */
static inline __attribute__((always_inline)) AVX512 void addj(
    double *q, const int nf, __m512d A, __m512d B, __m512d C, __m512d D,
    size_t nl) {
  __m512d o[4];
  if (nf == 3) {
    /* lane l of T = A, B interleaved; of the output, T or C (8 on) */
    const __m512i a0 = _mm512_setr_epi64(0, 8, 0, 1, 9, 0, 2, 10),
                  b0 = _mm512_setr_epi64(0, 1, 8, 3, 4, 9, 6, 7),
                  a1 = _mm512_setr_epi64(0, 3, 11, 0, 4, 12, 0, 5),
                  b1 = _mm512_setr_epi64(10, 1, 2, 11, 4, 5, 12, 7),
                  a2 = _mm512_setr_epi64(13, 0, 6, 14, 0, 7, 15, 0),
                  b2 = _mm512_setr_epi64(0, 13, 2, 3, 14, 5, 6, 15);
    o[0] = _mm512_permutex2var_pd(_mm512_permutex2var_pd(A, a0, B), b0, C);
    o[1] = _mm512_permutex2var_pd(_mm512_permutex2var_pd(A, a1, B), b1, C);
    o[2] = _mm512_permutex2var_pd(_mm512_permutex2var_pd(A, a2, B), b2, C);
    o[3] = _mm512_setzero_pd();
  } else {
    /* (A B) and (C D) pairs of lanes, particle by particle, then the
     * pairs of particles 2k and 2k + 1 gathered in o[k] */
    const __m512d ab0 = _mm512_unpacklo_pd(A, B), /* particles 0, 2, 4, 6 */
        ab1 = _mm512_unpackhi_pd(A, B),           /* 1, 3, 5, 7 */
        cd0 = _mm512_unpacklo_pd(C, D), cd1 = _mm512_unpackhi_pd(C, D);
    const __m512i lo2 = _mm512_setr_epi64(0, 1, 8, 9, 2, 3, 10, 11),
                  hi2 = _mm512_setr_epi64(4, 5, 12, 13, 6, 7, 14, 15);
    /* (AB, CD) of particles 0, 2 (then 4, 6) and of 1, 3 (5, 7) */
    const __m512d e0 = _mm512_permutex2var_pd(ab0, lo2, cd0),
                  e1 = _mm512_permutex2var_pd(ab1, lo2, cd1),
                  e2 = _mm512_permutex2var_pd(ab0, hi2, cd0),
                  e3 = _mm512_permutex2var_pd(ab1, hi2, cd1);
    o[0] = _mm512_shuffle_f64x2(e0, e1, 0x44); /* particles 0, 1 */
    o[1] = _mm512_shuffle_f64x2(e0, e1, 0xee); /* 2, 3 */
    o[2] = _mm512_shuffle_f64x2(e2, e3, 0x44); /* 4, 5 */
    o[3] = _mm512_shuffle_f64x2(e2, e3, 0xee); /* 6, 7 */
  }
  if (nl == 8) {
    for (int v = 0; v < nf; v++)
      _mm512_storeu_pd(q + 8 * v,
                       _mm512_add_pd(_mm512_loadu_pd(q + 8 * v), o[v]));
    return;
  }
  const size_t n = (size_t)nf * nl;
  for (int v = 0; v < nf; v++) {
    const size_t e = 8 * (size_t)v;
    const __mmask8 k = n > e ? lanes_left(n - e) : 0;
    _mm512_mask_storeu_pd(q + e, k,
                          _mm512_add_pd(_mm512_maskz_loadu_pd(k, q + e), o[v]));
  }
}

AVX512 void vsph_sweep_x86_addj8(double *q, int nf, const double *const f[4],
                                 size_t nl) {
  const __m512d D = nf == 4 ? _mm512_loadu_pd(f[3]) : _mm512_setzero_pd();
  if (nf == 4)
    addj(q, 4, _mm512_loadu_pd(f[0]), _mm512_loadu_pd(f[1]),
         _mm512_loadu_pd(f[2]), D, nl);
  else
    addj(q, 3, _mm512_loadu_pd(f[0]), _mm512_loadu_pd(f[1]),
         _mm512_loadu_pd(f[2]), D, nl);
}

/* One block of the sweep (solver/sweep_x86.h). For each cell of the block,
 * its receivers i in groups of at most eight (i0 on), and for each of the
 * cell's ranges from i0 + 1, each vector of eight consecutive candidates
 * j, loaded once for the group: each receiver's pairs j > i within the
 * support are its lanes (the candidate test's x = r_j - r_i and s^2,
 * unfused, so that a pair on the support's edge is classified as in every
 * loop); the kernel factor F = dwq (-2 e^{-q^2}) and the terms of
 * vsph_pair_pressure, the viscous term @p visc (vsph_pair_mgf,
 * vsph_pair_meaf or vsph_pair_pvwf_force), vsph_pair_continuity and
 * (@p delta) vsph_pair_delta are computed in all eight lanes and kept in
 * those (c = F du.x; f = F (p_i + p_j - Kmu du.x / (s^2 + eta^2)) x for
 * Brookshaw's term, F (p_i + p_j) x - 2 mu F du for MEAF's, F ((p_i +
 * p_j) x - (A_i + A_j) x) for the stress forms'; d = -2 F (rho_j -
 * rho_i)); i's sums
 * (V_j c, V_j f, V_j d) go on in eight lanes over its vectors, summed once
 * at its end into its entry, where i is fluid; j's shares (V_i c, -V_i f,
 * -V_i d) are summed over the group's receivers, in their order, then
 * added to the candidates' entries, a vector of three or four fields at a
 * time (addj). The same terms as the scalar loops, fused where they
 * meet and summed in another order: within rounding of them. The
 * interactions (each fluid receiver of a pair once: j's fluid by its id
 * unless the cell is clean) and the least s^2 of a pair with a fluid
 * receiver come from the same masks, so exactly as the loops give them. */
static inline __attribute__((always_inline)) AVX512 size_t
groups2_block(const struct vsph_equations_ctx *rc,
              const struct vsph_particles *p, const struct vsph_cells *cells,
              size_t n_fluid, const struct vsph_equations_sweep *sw, size_t blk,
              double *min_s2, const int delta, const int visc) {
  const int nf = delta ? 4 : 3; /* SW_FIELDS(2, delta, 0) */
  const size_t lo = sw->lo[blk];
  double *const buf = sw->buf + sw->off[blk];
  memset(buf, 0, (sw->hi[blk] - lo) * (size_t)nf * sizeof *buf);
  const double *const px = p->pos[0], *const py = p->pos[1],
                      *const vx = p->vel[0], *const vy = p->vel[1],
                      *const pp = p->p, *const vol = p->vol,
                      *const rho = p->rho;
  const size_t *const id = p->id;
  const double *const *const sA = (const double *const *)rc->vl.A; /* stress */
  const int fluid_only = p->n == n_fluid; /* no ghosts nor wall particles */
  const __m512d H2 = _mm512_set1_pd(rc->pk.H2),
                vhi2 = _mm512_set1_pd(rc->pk.h_inv2),
                vdwq = _mm512_set1_pd(-2.0 * rc->pk.dwq), /* -2 exact */
      vnc = _mm512_set1_pd(
          visc == VSPH_SWEEP_X86_BROOKSHAW_TERM ? -rc->vl.Kmu : -rc->vl.two_mu),
                veta2 = _mm512_set1_pd(rc->vl.eta2), nine = _mm512_set1_pd(9.0);
  const __m512i lane = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0),
                vnfl = _mm512_set1_epi64((long long)n_fluid);
  __m512d vmin = _mm512_set1_pd(HUGE_VAL);
  size_t total = 0;
  for (size_t c = sw->c0[blk]; c < sw->c0[blk + 1]; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    const size_t s0 = cells->start[c], end = s0 + cells->count[c];
    /* its ranges hold no ghost or wall particle: every j fluid */
    const int clean = fluid_only || (sw->clean && sw->clean[c]);
    for (size_t i0 = s0; i0 < end; i0 += 8) {
      const size_t g = end - i0 < 8 ? end - i0 : 8; /* receivers i0 + q */
      __m512d ac[8], af0[8], af1[8], ad[8];         /* i's sums, lane by lane */
      int fi[8];
      for (size_t q = 0; q < g; q++) {
        ac[q] = af0[q] = af1[q] = ad[q] = _mm512_setzero_pd();
        fi[q] = id[i0 + q] < n_fluid;
      }
      for (size_t r = 0; r < rg.n; r++) {
        const size_t hi = rg.hi[r];
        /* no receiver of the group has a pair below i0 + 1 */
        for (size_t j = rg.lo[r] > i0 ? rg.lo[r] : i0 + 1; j < hi; j += 8) {
          const __mmask8 live = lanes_left(hi - j);
          const __m512d X = _mm512_maskz_loadu_pd(live, px + j),
                        Y = _mm512_maskz_loadu_pd(live, py + j),
                        U0 = _mm512_maskz_loadu_pd(live, vx + j),
                        U1 = _mm512_maskz_loadu_pd(live, vy + j),
                        P = _mm512_maskz_loadu_pd(live, pp + j),
                        V = _mm512_maskz_loadu_pd(live, vol + j),
                        R = delta ? _mm512_maskz_loadu_pd(live, rho + j)
                                  : _mm512_setzero_pd();
          /* the stress forms' A_j (T L, row by row: A0 A1 / A2 A3) */
          const int st = visc == VSPH_SWEEP_X86_STRESS_TERM;
          const __m512d A0 = st ? _mm512_maskz_loadu_pd(live, sA[0] + j)
                                : _mm512_setzero_pd(),
                        A1 = st ? _mm512_maskz_loadu_pd(live, sA[1] + j)
                                : _mm512_setzero_pd(),
                        A2 = st ? _mm512_maskz_loadu_pd(live, sA[2] + j)
                                : _mm512_setzero_pd(),
                        A3 = st ? _mm512_maskz_loadu_pd(live, sA[3] + j)
                                : _mm512_setzero_pd();
          const __m512i J =
              _mm512_add_epi64(_mm512_set1_epi64((long long)j), lane);
          const __mmask8 fj = /* the fluid candidates */
              clean ? live
                    : _mm512_mask_cmplt_epu64_mask(
                          live, _mm512_maskz_loadu_epi64(live, id + j), vnfl);
          __m512d JA = _mm512_setzero_pd(), JB = JA, JC = JA, JD = JA;
          __mmask8 any = 0;
          for (size_t q = 0; q < g; q++) {
            const size_t i = i0 + q;
            const __m512d dx = _mm512_sub_pd(X, _mm512_set1_pd(px[i])),
                          dy = _mm512_sub_pd(Y, _mm512_set1_pd(py[i]));
            const __m512d s2 =
                _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
            /* the pairs: j > i, within the support */
            const __mmask8 k = _mm512_mask_cmp_pd_mask(
                _mm512_mask_cmpgt_epu64_mask(live, J,
                                             _mm512_set1_epi64((long long)i)),
                s2, H2, _CMP_LT_OQ);
            if (!k) continue;
            any |= k;
            const __mmask8 kf = fi[q] ? k : k & fj; /* a fluid receiver */
            vmin = _mm512_mask_min_pd(vmin, kf, vmin, s2);
            total += (size_t)__builtin_popcount((unsigned)(k & fj)) +
                     (fi[q] ? (size_t)__builtin_popcount((unsigned)k) : 0);
            /* F, 0 from q^2 = 9 and in every other lane */
            const __m512d q2 = _mm512_mul_pd(s2, vhi2);
            const __mmask8 in =
                _mm512_mask_cmp_pd_mask(k, q2, nine, _CMP_LT_OQ);
            const __m512d F = _mm512_maskz_mul_pd(in, vdwq, expneg8(q2));
            const __m512d du0 = _mm512_sub_pd(U0, _mm512_set1_pd(vx[i])),
                          du1 = _mm512_sub_pd(U1, _mm512_set1_pd(vy[i]));
            const __m512d dux =
                _mm512_fmadd_pd(du1, dy, _mm512_mul_pd(du0, dx));
            /* the shares of every lane; only the lanes in `in` (q^2 < 9)
             * are added anywhere below: another may hold 0/0 (i's own
             * lane, s^2 = 0) or a far candidate's non-finite values. A
             * pair with q^2 rounded to 9 has F = 0 and adds nothing, where
             * the scalar loops add F x = 0 (NaN only if a value of the
             * pair is not finite) */
            const __m512d cc = _mm512_mul_pd(F, dux);
            const __m512d ps = _mm512_add_pd(_mm512_set1_pd(pp[i]), P);
            __m512d f0, f1;
            if (visc == VSPH_SWEEP_X86_BROOKSHAW_TERM) {
              const __m512d fx = _mm512_mul_pd(
                  F,
                  _mm512_add_pd(ps, _mm512_div_pd(_mm512_mul_pd(vnc, dux),
                                                  _mm512_add_pd(s2, veta2))));
              f0 = _mm512_mul_pd(fx, dx);
              f1 = _mm512_mul_pd(fx, dy);
            } else if (visc == VSPH_SWEEP_X86_MEAF_TERM) {
              /* MEAF: F (p_i + p_j) x - 2 mu F du */
              const __m512d fp = _mm512_mul_pd(F, ps),
                            fv = _mm512_mul_pd(F, vnc);
              f0 = _mm512_fmadd_pd(fp, dx, _mm512_mul_pd(fv, du0));
              f1 = _mm512_fmadd_pd(fp, dy, _mm512_mul_pd(fv, du1));
            } else { /* PVWF, B: F ((p_i + p_j) x - (A_i + A_j) x) */
              const __m512d S0 = _mm512_add_pd(A0, _mm512_set1_pd(sA[0][i])),
                            S1 = _mm512_add_pd(A1, _mm512_set1_pd(sA[1][i])),
                            S2 = _mm512_add_pd(A2, _mm512_set1_pd(sA[2][i])),
                            S3 = _mm512_add_pd(A3, _mm512_set1_pd(sA[3][i]));
              f0 = _mm512_mul_pd(
                  F,
                  _mm512_fmsub_pd(
                      ps, dx, _mm512_fmadd_pd(S0, dx, _mm512_mul_pd(S1, dy))));
              f1 = _mm512_mul_pd(
                  F,
                  _mm512_fmsub_pd(
                      ps, dy, _mm512_fmadd_pd(S2, dx, _mm512_mul_pd(S3, dy))));
            }
            const __m512d Vi = _mm512_set1_pd(vol[i]);
            JA = _mm512_mask3_fnmadd_pd(Vi, f0, JA, in);
            JB = _mm512_mask3_fnmadd_pd(Vi, f1, JB, in);
            JC = _mm512_mask3_fmadd_pd(Vi, cc, JC, in);
            ac[q] = _mm512_mask3_fmadd_pd(V, cc, ac[q], in);
            af0[q] = _mm512_mask3_fmadd_pd(V, f0, af0[q], in);
            af1[q] = _mm512_mask3_fmadd_pd(V, f1, af1[q], in);
            if (delta) { /* d = -2 F (rho_j - rho_i), odd */
              const __m512d dd =
                  _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(-2.0), F),
                                _mm512_sub_pd(R, _mm512_set1_pd(rho[i])));
              JD = _mm512_mask3_fnmadd_pd(Vi, dd, JD, in);
              ad[q] = _mm512_mask3_fmadd_pd(V, dd, ad[q], in);
            }
          }
          if (any)
            addj(buf + (j - lo) * (size_t)nf, nf, JA, JB, JC, JD,
                 hi - j < 8 ? hi - j : 8);
        }
      }
      for (size_t q = 0; q < g; q++) { /* a ghost's sums are never read */
        if (!fi[q]) continue;
        double *const e = buf + (i0 + q - lo) * (size_t)nf;
        e[0] += _mm512_reduce_add_pd(af0[q]);
        e[1] += _mm512_reduce_add_pd(af1[q]);
        e[2] += _mm512_reduce_add_pd(ac[q]);
        if (delta) e[3] += _mm512_reduce_add_pd(ad[q]);
      }
    }
  }
  *min_s2 = _mm512_reduce_min_pd(vmin);
  return total;
}

/* groups2_block with @p delta and @p visc constants (a term it does not
 * know aborts: the stress term would read rc->vl.A, NULL for the others) */
#define GROUPS_DISPATCH(BLOCK)                                           \
  return visc == VSPH_SWEEP_X86_BROOKSHAW_TERM                           \
             ? (delta ? BLOCK(rc, p, cells, n_fluid, sw, blk, min_s2, 1, \
                              VSPH_SWEEP_X86_BROOKSHAW_TERM)             \
                      : BLOCK(rc, p, cells, n_fluid, sw, blk, min_s2, 0, \
                              VSPH_SWEEP_X86_BROOKSHAW_TERM))            \
         : visc == VSPH_SWEEP_X86_MEAF_TERM                              \
             ? (delta ? BLOCK(rc, p, cells, n_fluid, sw, blk, min_s2, 1, \
                              VSPH_SWEEP_X86_MEAF_TERM)                  \
                      : BLOCK(rc, p, cells, n_fluid, sw, blk, min_s2, 0, \
                              VSPH_SWEEP_X86_MEAF_TERM))                 \
         : visc == VSPH_SWEEP_X86_STRESS_TERM                            \
             ? (delta ? BLOCK(rc, p, cells, n_fluid, sw, blk, min_s2, 1, \
                              VSPH_SWEEP_X86_STRESS_TERM)                \
                      : BLOCK(rc, p, cells, n_fluid, sw, blk, min_s2, 0, \
                              VSPH_SWEEP_X86_STRESS_TERM))               \
             : (abort(), (size_t)0) /* no such term */

AVX512 size_t vsph_sweep_x86_groups2_avx512(
    const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
    const struct vsph_cells *cells, size_t n_fluid,
    const struct vsph_equations_sweep *sw, size_t blk, int delta, int visc,
    double *min_s2) {
  GROUPS_DISPATCH(groups2_block);
}

/* The 8 x 8 transpose of rows r[0..7] (field a of particles 0-7) into
 * o[0..7] (fields 0-7 of particle l): pairs of lanes interleaved, then
 * 128-bit blocks gathered twice */
static inline __attribute__((always_inline)) AVX512 void transpose8(
    const __m512d r[8], __m512d o[8]) {
  __m512d t[8], u[8];
  for (int a = 0; a < 8; a += 2) { /* t[a]: (r_a r_a+1) of 0, 2, 4, 6 */
    t[a] = _mm512_unpacklo_pd(r[a], r[a + 1]);
    t[a + 1] = _mm512_unpackhi_pd(r[a], r[a + 1]); /* of 1, 3, 5, 7 */
  }
  for (int s = 0; s < 2; s++) { /* s 0: particles 0, 2, 4, 6; 1: the odd */
    /* (t0, t2) and (t4, t6): blocks 0, 2 of each, then 1, 3 */
    u[4 * s] = _mm512_shuffle_f64x2(t[s], t[2 + s], 0x88);
    u[4 * s + 1] = _mm512_shuffle_f64x2(t[s], t[2 + s], 0xdd);
    u[4 * s + 2] = _mm512_shuffle_f64x2(t[4 + s], t[6 + s], 0x88);
    u[4 * s + 3] = _mm512_shuffle_f64x2(t[4 + s], t[6 + s], 0xdd);
    o[s] = _mm512_shuffle_f64x2(u[4 * s], u[4 * s + 2], 0x88);
    o[4 + s] = _mm512_shuffle_f64x2(u[4 * s], u[4 * s + 2], 0xdd);
    o[2 + s] = _mm512_shuffle_f64x2(u[4 * s + 1], u[4 * s + 3], 0x88);
    o[6 + s] = _mm512_shuffle_f64x2(u[4 * s + 1], u[4 * s + 3], 0xdd);
  }
}

/* A receiver's seven sums s (x (x) x's entries (0, 0), (0, 1), (1, 1),
 * then du (x) x's four) added to its eight fields e (B row by row, then
 * Mg): the (0, 1) entry in both of B's off-diagonal fields */
static inline __attribute__((always_inline)) void grad_own(double *e,
                                                           const double s[7]) {
  e[0] += s[0];
  e[1] += s[1];
  e[2] += s[1];
  e[3] += s[2];
  for (int f = 3; f < 7; f++) e[f + 1] += s[f];
}

/* PVWF's (model B's) first pass, one block (sweep_x86.h), by grad_block's
 * terms (solver/equations.c) in the walk of groups2_block: each pair
 * j > i within the support, every particle a receiver (ghosts too),
 * gives G = -F = 2 dwq e^{-q^2} and the unit terms G x (x) x and
 * G du (x) x (vsph_pair_pvwf_grad), i their V_j multiple and j their
 * V_i one (even in the pair). x (x) x is symmetric: its entry (0, 1)
 * is made once and stored in both of its fields. i's sums go on in eight
 * lanes over its vectors, summed once at its end; j's are summed over the
 * group's receivers, in their order, then added to the candidates'
 * entries, a whole vector of eight fields a particle (transpose8). The
 * lanes outside the support are kept out of every add by the mask. */
static inline __attribute__((always_inline)) AVX512 void grad2_block(
    const struct vsph_pair_kernel *pk, const struct vsph_particles *p,
    const struct vsph_cells *cells, const struct vsph_equations_sweep *sw,
    size_t blk) {
  const size_t lo = sw->lo[blk];
  double *const buf = sw->buf + sw->off[blk];
  memset(buf, 0, (sw->hi[blk] - lo) * 8 * sizeof *buf);
  const double *const px = p->pos[0], *const py = p->pos[1],
                      *const vx = p->vel[0], *const vy = p->vel[1],
                      *const vol = p->vol;
  const __m512d H2 = _mm512_set1_pd(pk->H2), vhi2 = _mm512_set1_pd(pk->h_inv2),
                vdwq = _mm512_set1_pd(2.0 * pk->dwq), /* 2 exact */
      nine = _mm512_set1_pd(9.0);
  const __m512i lane = _mm512_set_epi64(7, 6, 5, 4, 3, 2, 1, 0);
  for (size_t c = sw->c0[blk]; c < sw->c0[blk + 1]; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    const size_t s0 = cells->start[c], end = s0 + cells->count[c];
    for (size_t i0 = s0; i0 < end; i0 += 8) {
      const size_t g = end - i0 < 8 ? end - i0 : 8; /* receivers i0 + q */
      /* i's sums, lane by lane: x (x) x's entries (0, 0), (0, 1), (1, 1),
       * then du (x) x's four */
      __m512d ai[8][7];
      for (size_t q = 0; q < g; q++)
        for (int e = 0; e < 7; e++) ai[q][e] = _mm512_setzero_pd();
      for (size_t r = 0; r < rg.n; r++) {
        const size_t hi = rg.hi[r];
        /* no receiver of the group has a pair below i0 + 1 */
        for (size_t j = rg.lo[r] > i0 ? rg.lo[r] : i0 + 1; j < hi; j += 8) {
          const __mmask8 live = lanes_left(hi - j);
          const __m512d X = _mm512_maskz_loadu_pd(live, px + j),
                        Y = _mm512_maskz_loadu_pd(live, py + j),
                        U0 = _mm512_maskz_loadu_pd(live, vx + j),
                        U1 = _mm512_maskz_loadu_pd(live, vy + j),
                        V = _mm512_maskz_loadu_pd(live, vol + j);
          const __m512i J =
              _mm512_add_epi64(_mm512_set1_epi64((long long)j), lane);
          __m512d aj[7];
          for (int e = 0; e < 7; e++) aj[e] = _mm512_setzero_pd();
          __mmask8 any = 0;
          for (size_t q = 0; q < g; q++) {
            const size_t i = i0 + q;
            const __m512d dx = _mm512_sub_pd(X, _mm512_set1_pd(px[i])),
                          dy = _mm512_sub_pd(Y, _mm512_set1_pd(py[i]));
            const __m512d s2 =
                _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
            /* the pairs: j > i, within the support */
            const __mmask8 k = _mm512_mask_cmp_pd_mask(
                _mm512_mask_cmpgt_epu64_mask(live, J,
                                             _mm512_set1_epi64((long long)i)),
                s2, H2, _CMP_LT_OQ);
            if (!k) continue;
            any |= k;
            /* G, 0 from q^2 = 9 on; only the lanes in `in` are added */
            const __m512d q2 = _mm512_mul_pd(s2, vhi2);
            const __mmask8 in =
                _mm512_mask_cmp_pd_mask(k, q2, nine, _CMP_LT_OQ);
            const __m512d G = _mm512_maskz_mul_pd(in, vdwq, expneg8(q2));
            const __m512d du0 = _mm512_sub_pd(U0, _mm512_set1_pd(vx[i])),
                          du1 = _mm512_sub_pd(U1, _mm512_set1_pd(vy[i]));
            /* i's: V_j G x, then times x and du; j's: V_i G x */
            const __m512d wj = _mm512_mul_pd(V, G),
                          wi = _mm512_mul_pd(_mm512_set1_pd(vol[i]), G);
            const __m512d tx[2] = {_mm512_mul_pd(wj, dx),
                                   _mm512_mul_pd(wi, dx)},
                          ty[2] = {_mm512_mul_pd(wj, dy),
                                   _mm512_mul_pd(wi, dy)};
            for (int s = 0; s < 2; s++) {
              __m512d *const a = s ? aj : ai[q];
              a[0] = _mm512_mask3_fmadd_pd(tx[s], dx, a[0], in);
              a[1] = _mm512_mask3_fmadd_pd(tx[s], dy, a[1], in);
              a[2] = _mm512_mask3_fmadd_pd(ty[s], dy, a[2], in);
              a[3] = _mm512_mask3_fmadd_pd(tx[s], du0, a[3], in);
              a[4] = _mm512_mask3_fmadd_pd(ty[s], du0, a[4], in);
              a[5] = _mm512_mask3_fmadd_pd(tx[s], du1, a[5], in);
              a[6] = _mm512_mask3_fmadd_pd(ty[s], du1, a[6], in);
            }
          }
          if (!any) continue;
          /* the eight fields (B0 B1 B2 B3 M0 M1 M2 M3) of each candidate */
          const __m512d rj[8] = {aj[0], aj[1], aj[1], aj[2],
                                 aj[3], aj[4], aj[5], aj[6]};
          __m512d o[8];
          transpose8(rj, o);
          const size_t nl = hi - j < 8 ? hi - j : 8;
          double *const e = buf + (j - lo) * 8;
          for (size_t l = 0; l < nl; l++)
            _mm512_storeu_pd(e + 8 * l,
                             _mm512_add_pd(_mm512_loadu_pd(e + 8 * l), o[l]));
        }
      }
      for (size_t q = 0; q < g; q++) {
        double si[7];
        for (int f = 0; f < 7; f++) si[f] = _mm512_reduce_add_pd(ai[q][f]);
        grad_own(buf + (i0 + q - lo) * 8, si);
      }
    }
  }
}

AVX512 void vsph_sweep_x86_grad2_avx512(const struct vsph_pair_kernel *pk,
                                        const struct vsph_particles *p,
                                        const struct vsph_cells *cells,
                                        const struct vsph_equations_sweep *sw,
                                        size_t blk) {
  grad2_block(pk, p, cells, sw, blk);
}

/* ------------------------------------------------------------------------
 * The same sweep with AVX2 and FMA (x86-64-v3), four lanes: where the CPU
 * has AVX2 but not AVX-512 (pk.simd 1), or where VSPH_PAIR_SIMD=avx2 caps
 * it. The group is still eight receivers; a vector of candidates is four.
 * AVX2 has no mask registers: a lane's condition is a vector of all ones
 * or all zeros, and a share outside the support is cleared by an and
 * (not kept out of an add by a mask, as above): each share that is added
 * anywhere, and the volumes it is multiplied by, are anded with the
 * pairs' lanes, so that a lane outside the support adds +0 and never
 * 0 * inf. */
#define AVX2 __attribute__((target("avx2,fma")))

/* All ones in the lanes of the last @p left < 4 entries of a run, or all
 * four */
static inline __attribute__((always_inline)) AVX2 __m256i
lanes_left4(size_t left) {
  static const long long ones[8] = {-1, -1, -1, -1, 0, 0, 0, 0};
  return _mm256_loadu_si256(
      (const __m256i *)(const void *)(ones + 4 - (left < 4 ? left : 4)));
}

/* expneg8 in four lanes: the same reduction, fused, and 2^{-n} built from
 * its exponent bits as vsph_kernel_expneg builds it (AVX2 has no scalef;
 * exact for 0 <= x <= 700, where 1023 - n is a normal exponent; another
 * lane's result may be anything, and is cleared by the caller) */
static inline __attribute__((always_inline)) AVX2 __m256d expneg4(__m256d x) {
#define K(v) _mm256_set1_pd(v)
  const __m256d shift = K(VSPH_KERNEL_EXPNEG_SHIFT);
  const __m256d m = _mm256_fmadd_pd(x, K(VSPH_KERNEL_EXPNEG_LOG2E), shift);
  const __m256d n = _mm256_sub_pd(m, shift);
  const __m256d r =
      _mm256_fnmadd_pd(n, K(VSPH_KERNEL_EXPNEG_LN2_LO),
                       _mm256_fnmadd_pd(n, K(VSPH_KERNEL_EXPNEG_LN2_HI), x));
  const __m256d r2 = _mm256_mul_pd(r, r), r4 = _mm256_mul_pd(r2, r2),
                r8 = _mm256_mul_pd(r4, r4);
  const __m256d p =
      VSPH_KERNEL_EXPNEG_TAYLOR(_mm256_fmadd_pd, K, r, r2, r4, r8);
#undef K
  /* the low bits of m hold n: 2^{-n}'s exponent is 1023 - n */
  const __m256i e = _mm256_slli_epi64(
      _mm256_sub_epi64(
          _mm256_set1_epi64x((long long)(1023ull + 0x0008000000000000ull)),
          _mm256_and_si256(_mm256_castpd_si256(m),
                           _mm256_set1_epi64x(0x000fffffffffffffll))),
      52);
  return _mm256_mul_pd(p, _mm256_castsi256_pd(e));
}

AVX2 void vsph_sweep_x86_expneg4(const double *x, double *y, size_t n) {
  for (size_t k = 0; k < n; k += 4) {
    const __m256i km = lanes_left4(n - k);
    _mm256_maskstore_pd(y + k, km, expneg4(_mm256_maskload_pd(x + k, km)));
  }
}

/* addj with four lanes: fields A, B, C, D (D where @p nf is 4) of
 * @p nl <= 4 consecutive particles added to q[0 .. nf nl - 1]: four
 * fields by a 4 x 4 transpose (a particle's entries one whole vector),
 * three by permutes and blends into three vectors of four entries,
 * masked past the last particle's (the next entries may be another
 * block's) */
static inline __attribute__((always_inline)) AVX2 void addj4(
    double *q, const int nf, __m256d A, __m256d B, __m256d C, __m256d D,
    size_t nl) {
  if (nf == 4) {
    const __m256d r[4] = {A, B, C, D};
    __m256d o[4];
    transpose4(r, o);
    for (size_t l = 0; l < nl; l++)
      _mm256_storeu_pd(q + 4 * l,
                       _mm256_add_pd(_mm256_loadu_pd(q + 4 * l), o[l]));
    return;
  }
  /* (A0 B0 C0 A1), (B1 C1 A2 B2), (C2 A3 B3 C3) */
  const __m256d o[3] = {
      _mm256_blend_pd(_mm256_blend_pd(_mm256_permute4x64_pd(A, 0x40),
                                      _mm256_permute4x64_pd(B, 0x00), 0x2),
                      _mm256_permute4x64_pd(C, 0x00), 0x4),
      _mm256_blend_pd(_mm256_blend_pd(_mm256_permute4x64_pd(B, 0x81), C, 0x2),
                      A, 0x4),
      _mm256_blend_pd(_mm256_blend_pd(_mm256_permute4x64_pd(C, 0xc2),
                                      _mm256_permute4x64_pd(A, 0x0c), 0x2),
                      _mm256_permute4x64_pd(B, 0x30), 0x4)};
  if (nl == 4) {
    for (int v = 0; v < 3; v++)
      _mm256_storeu_pd(q + 4 * v,
                       _mm256_add_pd(_mm256_loadu_pd(q + 4 * v), o[v]));
    return;
  }
  const size_t n = 3 * nl;
  for (size_t e = 0; e < n; e += 4) {
    const __m256i k = lanes_left4(n - e);
    _mm256_maskstore_pd(q + e, k,
                        _mm256_add_pd(_mm256_maskload_pd(q + e, k), o[e / 4]));
  }
}

AVX2 void vsph_sweep_x86_addj4(double *q, int nf, const double *const f[4],
                               size_t nl) {
  const __m256d D = nf == 4 ? _mm256_loadu_pd(f[3]) : _mm256_setzero_pd();
  if (nf == 4)
    addj4(q, 4, _mm256_loadu_pd(f[0]), _mm256_loadu_pd(f[1]),
          _mm256_loadu_pd(f[2]), D, nl);
  else
    addj4(q, 3, _mm256_loadu_pd(f[0]), _mm256_loadu_pd(f[1]),
          _mm256_loadu_pd(f[2]), D, nl);
}

/* The sum of four lanes */
static inline __attribute__((always_inline)) AVX2 double sum4(__m256d v) {
  const __m128d s =
      _mm_add_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_add_sd(s, _mm_unpackhi_pd(s, s)));
}

/* groups2_block in four lanes: the same walk, terms and order (eight
 * receivers a group, each vector of candidates loaded once for it), the
 * masks vectors of all ones */
static inline __attribute__((always_inline)) AVX2 size_t
groups2_block4(const struct vsph_equations_ctx *rc,
               const struct vsph_particles *p, const struct vsph_cells *cells,
               size_t n_fluid, const struct vsph_equations_sweep *sw,
               size_t blk, double *min_s2, const int delta, const int visc) {
  const int nf = delta ? 4 : 3; /* SW_FIELDS(2, delta, 0) */
  const size_t lo = sw->lo[blk];
  double *const buf = sw->buf + sw->off[blk];
  memset(buf, 0, (sw->hi[blk] - lo) * (size_t)nf * sizeof *buf);
  const double *const px = p->pos[0], *const py = p->pos[1],
                      *const vx = p->vel[0], *const vy = p->vel[1],
                      *const pp = p->p, *const vol = p->vol,
                      *const rho = p->rho;
  const long long *const id = (const long long *)(const void *)p->id;
  const double *const *const sA = (const double *const *)rc->vl.A; /* stress */
  const int fluid_only = p->n == n_fluid; /* no ghosts nor wall particles */
  const __m256d H2 = _mm256_set1_pd(rc->pk.H2),
                vhi2 = _mm256_set1_pd(rc->pk.h_inv2),
                vdwq = _mm256_set1_pd(-2.0 * rc->pk.dwq), /* -2 exact */
      vnc = _mm256_set1_pd(
          visc == VSPH_SWEEP_X86_BROOKSHAW_TERM ? -rc->vl.Kmu : -rc->vl.two_mu),
                veta2 = _mm256_set1_pd(rc->vl.eta2), nine = _mm256_set1_pd(9.0);
  /* AVX2 compares 64-bit lanes as signed only: the indices (below the
   * set's size) are compared as they are; the ids (any size_t: a ghost's
   * may be 2^63 or more) with their top bits flipped, which orders them
   * as unsigned */
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3),
                top = _mm256_set1_epi64x(LLONG_MIN),
                vnfl = _mm256_xor_si256(_mm256_set1_epi64x((long long)n_fluid),
                                        top);
  __m256d vmin = _mm256_set1_pd(HUGE_VAL);
  size_t total = 0;
  for (size_t c = sw->c0[blk]; c < sw->c0[blk + 1]; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    const size_t s0 = cells->start[c], end = s0 + cells->count[c];
    /* its ranges hold no ghost or wall particle: every j fluid */
    const int clean = fluid_only || (sw->clean && sw->clean[c]);
    for (size_t i0 = s0; i0 < end; i0 += 8) {
      const size_t g = end - i0 < 8 ? end - i0 : 8; /* receivers i0 + q */
      __m256d ac[8], af0[8], af1[8], ad[8];         /* i's sums, lane by lane */
      int fi[8];
      for (size_t q = 0; q < g; q++) {
        ac[q] = af0[q] = af1[q] = ad[q] = _mm256_setzero_pd();
        fi[q] = p->id[i0 + q] < n_fluid;
      }
      for (size_t r = 0; r < rg.n; r++) {
        const size_t hi = rg.hi[r];
        /* no receiver of the group has a pair below i0 + 1 */
        for (size_t j = rg.lo[r] > i0 ? rg.lo[r] : i0 + 1; j < hi; j += 4) {
          const __m256i live = lanes_left4(hi - j);
          /* whole vectors by plain loads, a range's last by masked ones
           * (which never read past it) */
          const int whole = hi - j >= 4;
#define LOAD4(a) (whole ? _mm256_loadu_pd(a) : _mm256_maskload_pd((a), live))
          const __m256d X = LOAD4(px + j), Y = LOAD4(py + j),
                        U0 = LOAD4(vx + j), U1 = LOAD4(vy + j),
                        P = LOAD4(pp + j), V = LOAD4(vol + j),
                        R = delta ? LOAD4(rho + j) : _mm256_setzero_pd();
          /* the stress forms' A_j (T L, row by row: A0 A1 / A2 A3) */
          const int st = visc == VSPH_SWEEP_X86_STRESS_TERM;
          const __m256d A0 = st ? LOAD4(sA[0] + j) : _mm256_setzero_pd(),
                        A1 = st ? LOAD4(sA[1] + j) : _mm256_setzero_pd(),
                        A2 = st ? LOAD4(sA[2] + j) : _mm256_setzero_pd(),
                        A3 = st ? LOAD4(sA[3] + j) : _mm256_setzero_pd();
#undef LOAD4
          const __m256i J =
              _mm256_add_epi64(_mm256_set1_epi64x((long long)j), lane);
          const __m256i fj = /* the fluid candidates */
              clean
                  ? live
                  : _mm256_and_si256(
                        live, _mm256_cmpgt_epi64(
                                  vnfl, _mm256_xor_si256(
                                            _mm256_maskload_epi64(id + j, live),
                                            top)));
          const unsigned fjm =
              (unsigned)_mm256_movemask_pd(_mm256_castsi256_pd(fj));
          __m256d JA = _mm256_setzero_pd(), JB = JA, JC = JA, JD = JA;
          int any = 0;
          for (size_t q = 0; q < g; q++) {
            const size_t i = i0 + q;
            const __m256d dx = _mm256_sub_pd(X, _mm256_set1_pd(px[i])),
                          dy = _mm256_sub_pd(Y, _mm256_set1_pd(py[i]));
            const __m256d s2 =
                _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
            /* the pairs: j > i, within the support */
            const __m256d k = _mm256_and_pd(
                _mm256_castsi256_pd(_mm256_and_si256(
                    live,
                    _mm256_cmpgt_epi64(J, _mm256_set1_epi64x((long long)i)))),
                _mm256_cmp_pd(s2, H2, _CMP_LT_OQ));
            const unsigned km = (unsigned)_mm256_movemask_pd(k);
            if (!km) continue;
            any = 1;
            /* a fluid receiver */
            const __m256d kf =
                fi[q] ? k : _mm256_and_pd(k, _mm256_castsi256_pd(fj));
            vmin = _mm256_blendv_pd(vmin, _mm256_min_pd(vmin, s2), kf);
            total += (size_t)__builtin_popcount(km & fjm) +
                     (fi[q] ? (size_t)__builtin_popcount(km) : 0);
            const __m256d q2 = _mm256_mul_pd(s2, vhi2);
            /* the lanes added anywhere: pairs with q^2 < 9 */
            const __m256d in =
                _mm256_and_pd(k, _mm256_cmp_pd(q2, nine, _CMP_LT_OQ));
            const __m256d F = _mm256_mul_pd(vdwq, expneg4(q2));
            const __m256d du0 = _mm256_sub_pd(U0, _mm256_set1_pd(vx[i])),
                          du1 = _mm256_sub_pd(U1, _mm256_set1_pd(vy[i]));
            const __m256d dux =
                _mm256_fmadd_pd(du1, dy, _mm256_mul_pd(du0, dx));
            /* every share cleared outside `in`, and the volumes too (a
             * far lane may hold anything, even 0/0 in i's own lane) */
            const __m256d cc = _mm256_and_pd(_mm256_mul_pd(F, dux), in);
            const __m256d ps = _mm256_add_pd(_mm256_set1_pd(pp[i]), P);
            __m256d f0, f1;
            if (visc == VSPH_SWEEP_X86_BROOKSHAW_TERM) {
              const __m256d fx = _mm256_mul_pd(
                  F,
                  _mm256_add_pd(ps, _mm256_div_pd(_mm256_mul_pd(vnc, dux),
                                                  _mm256_add_pd(s2, veta2))));
              f0 = _mm256_and_pd(_mm256_mul_pd(fx, dx), in);
              f1 = _mm256_and_pd(_mm256_mul_pd(fx, dy), in);
            } else if (visc == VSPH_SWEEP_X86_MEAF_TERM) {
              /* MEAF: F (p_i + p_j) x - 2 mu F du */
              const __m256d fp = _mm256_mul_pd(F, ps),
                            fv = _mm256_mul_pd(F, vnc);
              f0 = _mm256_and_pd(
                  _mm256_fmadd_pd(fp, dx, _mm256_mul_pd(fv, du0)), in);
              f1 = _mm256_and_pd(
                  _mm256_fmadd_pd(fp, dy, _mm256_mul_pd(fv, du1)), in);
            } else { /* PVWF, B: F ((p_i + p_j) x - (A_i + A_j) x) */
              const __m256d S0 = _mm256_add_pd(A0, _mm256_set1_pd(sA[0][i])),
                            S1 = _mm256_add_pd(A1, _mm256_set1_pd(sA[1][i])),
                            S2 = _mm256_add_pd(A2, _mm256_set1_pd(sA[2][i])),
                            S3 = _mm256_add_pd(A3, _mm256_set1_pd(sA[3][i]));
              f0 = _mm256_and_pd(
                  _mm256_mul_pd(
                      F, _mm256_fmsub_pd(
                             ps, dx,
                             _mm256_fmadd_pd(S0, dx, _mm256_mul_pd(S1, dy)))),
                  in);
              f1 = _mm256_and_pd(
                  _mm256_mul_pd(
                      F, _mm256_fmsub_pd(
                             ps, dy,
                             _mm256_fmadd_pd(S2, dx, _mm256_mul_pd(S3, dy)))),
                  in);
            }
            const __m256d Vi = _mm256_and_pd(_mm256_set1_pd(vol[i]), in),
                          Vj = _mm256_and_pd(V, in);
            JA = _mm256_fnmadd_pd(Vi, f0, JA);
            JB = _mm256_fnmadd_pd(Vi, f1, JB);
            JC = _mm256_fmadd_pd(Vi, cc, JC);
            ac[q] = _mm256_fmadd_pd(Vj, cc, ac[q]);
            af0[q] = _mm256_fmadd_pd(Vj, f0, af0[q]);
            af1[q] = _mm256_fmadd_pd(Vj, f1, af1[q]);
            if (delta) { /* d = -2 F (rho_j - rho_i), odd */
              const __m256d dd = _mm256_and_pd(
                  _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(-2.0), F),
                                _mm256_sub_pd(R, _mm256_set1_pd(rho[i]))),
                  in);
              JD = _mm256_fnmadd_pd(Vi, dd, JD);
              ad[q] = _mm256_fmadd_pd(Vj, dd, ad[q]);
            }
          }
          if (any)
            addj4(buf + (j - lo) * (size_t)nf, nf, JA, JB, JC, JD,
                  hi - j < 4 ? hi - j : 4);
        }
      }
      for (size_t q = 0; q < g; q++) { /* a ghost's sums are never read */
        if (!fi[q]) continue;
        double *const e = buf + (i0 + q - lo) * (size_t)nf;
        e[0] += sum4(af0[q]);
        e[1] += sum4(af1[q]);
        e[2] += sum4(ac[q]);
        if (delta) e[3] += sum4(ad[q]);
      }
    }
  }
  const __m128d m2 =
      _mm_min_pd(_mm256_castpd256_pd128(vmin), _mm256_extractf128_pd(vmin, 1));
  *min_s2 = _mm_cvtsd_f64(_mm_min_sd(m2, _mm_unpackhi_pd(m2, m2)));
  return total;
}

AVX2 size_t vsph_sweep_x86_groups2_avx2(const struct vsph_equations_ctx *rc,
                                        const struct vsph_particles *p,
                                        const struct vsph_cells *cells,
                                        size_t n_fluid,
                                        const struct vsph_equations_sweep *sw,
                                        size_t blk, int delta, int visc,
                                        double *min_s2) {
  GROUPS_DISPATCH(groups2_block4);
}

/* grad2_block in four lanes: the same walk, terms and order, the lanes
 * outside the support cleared by an and: the weights V G and the
 * differences x and du (a far candidate may hold an infinite velocity,
 * volume or position, i's own lane inf - inf where i's velocity is
 * infinite, and 0 times an infinite value is not 0) */
static inline __attribute__((always_inline)) AVX2 void grad2_block4(
    const struct vsph_pair_kernel *pk, const struct vsph_particles *p,
    const struct vsph_cells *cells, const struct vsph_equations_sweep *sw,
    size_t blk) {
  const size_t lo = sw->lo[blk];
  double *const buf = sw->buf + sw->off[blk];
  memset(buf, 0, (sw->hi[blk] - lo) * 8 * sizeof *buf);
  const double *const px = p->pos[0], *const py = p->pos[1],
                      *const vx = p->vel[0], *const vy = p->vel[1],
                      *const vol = p->vol;
  const __m256d H2 = _mm256_set1_pd(pk->H2), vhi2 = _mm256_set1_pd(pk->h_inv2),
                vdwq = _mm256_set1_pd(2.0 * pk->dwq), /* 2 exact */
      nine = _mm256_set1_pd(9.0);
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3);
  for (size_t c = sw->c0[blk]; c < sw->c0[blk + 1]; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    const size_t s0 = cells->start[c], end = s0 + cells->count[c];
    for (size_t i0 = s0; i0 < end; i0 += 8) {
      const size_t g = end - i0 < 8 ? end - i0 : 8; /* receivers i0 + q */
      __m256d ai[8][7]; /* i's sums, lane by lane, as grad2_block's */
      for (size_t q = 0; q < g; q++)
        for (int e = 0; e < 7; e++) ai[q][e] = _mm256_setzero_pd();
      for (size_t r = 0; r < rg.n; r++) {
        const size_t hi = rg.hi[r];
        /* no receiver of the group has a pair below i0 + 1 */
        for (size_t j = rg.lo[r] > i0 ? rg.lo[r] : i0 + 1; j < hi; j += 4) {
          const __m256i live = lanes_left4(hi - j);
          /* whole vectors by plain loads, a range's last by masked ones */
          const int whole = hi - j >= 4;
#define LOAD4(a) (whole ? _mm256_loadu_pd(a) : _mm256_maskload_pd((a), live))
          const __m256d X = LOAD4(px + j), Y = LOAD4(py + j),
                        U0 = LOAD4(vx + j), U1 = LOAD4(vy + j),
                        V = LOAD4(vol + j);
#undef LOAD4
          const __m256i J =
              _mm256_add_epi64(_mm256_set1_epi64x((long long)j), lane);
          __m256d aj[7];
          for (int e = 0; e < 7; e++) aj[e] = _mm256_setzero_pd();
          int any = 0;
          for (size_t q = 0; q < g; q++) {
            const size_t i = i0 + q;
            const __m256d dx = _mm256_sub_pd(X, _mm256_set1_pd(px[i])),
                          dy = _mm256_sub_pd(Y, _mm256_set1_pd(py[i]));
            const __m256d s2 =
                _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
            /* the pairs: j > i, within the support */
            const __m256d k = _mm256_and_pd(
                _mm256_castsi256_pd(_mm256_and_si256(
                    live,
                    _mm256_cmpgt_epi64(J, _mm256_set1_epi64x((long long)i)))),
                _mm256_cmp_pd(s2, H2, _CMP_LT_OQ));
            if (!_mm256_movemask_pd(k)) continue;
            any = 1;
            const __m256d q2 = _mm256_mul_pd(s2, vhi2);
            /* the lanes added anywhere: pairs with q^2 < 9 */
            const __m256d in =
                _mm256_and_pd(k, _mm256_cmp_pd(q2, nine, _CMP_LT_OQ));
            const __m256d G = _mm256_mul_pd(vdwq, expneg4(q2));
            const __m256d wj = _mm256_and_pd(_mm256_mul_pd(V, G), in),
                          wi = _mm256_and_pd(
                              _mm256_mul_pd(_mm256_set1_pd(vol[i]), G), in),
                          cx = _mm256_and_pd(dx, in),
                          cy = _mm256_and_pd(dy, in),
                          du0 = _mm256_and_pd(
                              _mm256_sub_pd(U0, _mm256_set1_pd(vx[i])), in),
                          du1 = _mm256_and_pd(
                              _mm256_sub_pd(U1, _mm256_set1_pd(vy[i])), in);
            const __m256d tx[2] = {_mm256_mul_pd(wj, cx),
                                   _mm256_mul_pd(wi, cx)},
                          ty[2] = {_mm256_mul_pd(wj, cy),
                                   _mm256_mul_pd(wi, cy)};
            for (int s = 0; s < 2; s++) {
              __m256d *const a = s ? aj : ai[q];
              a[0] = _mm256_fmadd_pd(tx[s], cx, a[0]);
              a[1] = _mm256_fmadd_pd(tx[s], cy, a[1]);
              a[2] = _mm256_fmadd_pd(ty[s], cy, a[2]);
              a[3] = _mm256_fmadd_pd(tx[s], du0, a[3]);
              a[4] = _mm256_fmadd_pd(ty[s], du0, a[4]);
              a[5] = _mm256_fmadd_pd(tx[s], du1, a[5]);
              a[6] = _mm256_fmadd_pd(ty[s], du1, a[6]);
            }
          }
          if (!any) continue;
          /* B's four fields and Mg's of each candidate, two transposes */
          const __m256d rb[4] = {aj[0], aj[1], aj[1], aj[2]},
                        rm[4] = {aj[3], aj[4], aj[5], aj[6]};
          __m256d ob[4], om[4];
          transpose4(rb, ob);
          transpose4(rm, om);
          const size_t nl = hi - j < 4 ? hi - j : 4;
          double *const e = buf + (j - lo) * 8;
          for (size_t l = 0; l < nl; l++) {
            _mm256_storeu_pd(e + 8 * l,
                             _mm256_add_pd(_mm256_loadu_pd(e + 8 * l), ob[l]));
            _mm256_storeu_pd(
                e + 8 * l + 4,
                _mm256_add_pd(_mm256_loadu_pd(e + 8 * l + 4), om[l]));
          }
        }
      }
      for (size_t q = 0; q < g; q++) {
        double si[7];
        for (int f = 0; f < 7; f++) si[f] = sum4(ai[q][f]);
        grad_own(buf + (i0 + q - lo) * 8, si);
      }
    }
  }
}

AVX2 void vsph_sweep_x86_grad2_avx2(const struct vsph_pair_kernel *pk,
                                    const struct vsph_particles *p,
                                    const struct vsph_cells *cells,
                                    const struct vsph_equations_sweep *sw,
                                    size_t blk) {
  grad2_block4(pk, p, cells, sw, blk);
}
#undef GROUPS_DISPATCH
#undef AVX2

#endif /* VSPH_SWEEP_X86_GROUPS */

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
