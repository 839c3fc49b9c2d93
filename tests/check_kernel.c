/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../common/consts.h"
#include "../kernels/kernel.h"
#include "../solver/pair.h"
#include "../solver/sweep_x86.h"
#include "check_suites.h"

struct kd {
  const struct vsph_kernel_type *k;
  int dim;
};

static double moment_integrand(double q, void *v) {
  const struct kd *p = v;
  return pow(q, p->dim - 1) * vsph_kernel_w(p->k, p->dim, q);
}

/* _i runs over kernel x dimension. */
START_TEST(test_normalisation) {
  const struct vsph_kernel_type *k = vsph_kernel_get((size_t)_i / 3);
  struct kd p = {k, _i % 3 + 1};
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
  gsl_function fn = {moment_integrand, &p};
  double total = 0.0;
  for (double lo = 0.0; lo < k->kappa; lo += 1.0) { /* split at the knots */
    double res, err;
    ck_assert_int_eq(
        gsl_integration_qag(&fn, lo, fmin(lo + 1.0, k->kappa), 0.0, 1e-13, 200,
                            GSL_INTEG_GAUSS41, ws, &res, &err),
        0);
    total += res;
  }
  gsl_integration_workspace_free(ws);
  /* surface of the unit sphere in d dimensions: 2, 2 pi, 4 pi */
  const double area[3] = {2.0, 2.0 * VSPH_PI, 4.0 * VSPH_PI};
  /* tol: quadrature requested at 1e-13; sigma literals carry 17+ digits */
  ck_assert_double_eq_tol(area[p.dim - 1] * total, 1.0, 1e-11);
}
END_TEST

START_TEST(test_derivative_fd) {
  const struct vsph_kernel_type *k = vsph_kernel_get((size_t)_i / 3);
  const int dim = _i % 3 + 1;
  const double eps = 1e-5;
  double scale = 0.0;
  for (double q = 0.0; q < k->kappa; q += 0.01)
    scale = fmax(scale, fabs(vsph_kernel_dw(k, dim, q)));
  /* high-entropy points away from the knots at q = 1, 2 */
  const double qs[] = {0.1234, 0.5871, 0.9345, 1.2348,
                       1.6180, 1.8765, 2.385,  2.7182};
  for (size_t m = 0; m < sizeof qs / sizeof qs[0]; m++) {
    const double q = qs[m] * k->kappa / 3.0;
    const double fd =
        (vsph_kernel_w(k, dim, q + eps) - vsph_kernel_w(k, dim, q - eps)) /
        (2.0 * eps);
    /* centred difference: error ~ eps^2 w''' / 6 ~ 1e-10, rounding
     * ~ 1e-16 / eps = 1e-11; 1e-8 of the slope scale covers both */
    ck_assert_double_eq_tol(vsph_kernel_dw(k, dim, q), fd, 1e-8 * scale);
    /* and w'' against a centred difference of w' (same error budget on
     * the scale of w'') */
    double scale2 = 0.0;
    for (double p = 0.0; p < k->kappa; p += 0.01)
      scale2 = fmax(scale2, fabs(vsph_kernel_d2w(k, dim, p)));
    const double fd2 =
        (vsph_kernel_dw(k, dim, q + eps) - vsph_kernel_dw(k, dim, q - eps)) /
        (2.0 * eps);
    ck_assert_double_eq_tol(vsph_kernel_d2w(k, dim, q), fd2, 1e-8 * scale2);
  }
}
END_TEST

START_TEST(test_sign_and_support) {
  const struct vsph_kernel_type *k = vsph_kernel_get((size_t)_i / 3);
  const int dim = _i % 3 + 1;
  for (double q = 0.0; q <= k->kappa + 0.5; q += 0.0137) {
    ck_assert(vsph_kernel_w(k, dim, q) >= 0.0);
    ck_assert(vsph_kernel_dw(k, dim, q) <= 0.0);
    if (q >= k->kappa) {
      ck_assert(vsph_kernel_w(k, dim, q) == 0.0);
      ck_assert(vsph_kernel_dw(k, dim, q) == 0.0);
    }
  }
  /* continuity at the support edge: w(kappa^-) -> 0 (1e-12 of w(0)) */
  ck_assert_double_eq_tol(vsph_kernel_w(k, dim, k->kappa * (1 - 1e-12)), 0.0,
                          1e-12 * vsph_kernel_w(k, dim, 0.0));
}
END_TEST

/* The loops' (df/dq)/q from q^2 against df(q)/q (tol: rounding of a few
 * operations, 1e-13 of the slope scale). */
START_TEST(test_dfq_matches_df_over_q) {
  const struct vsph_kernel_type *k = vsph_kernel_get((size_t)_i / 3);
  const int dim = _i % 3 + 1;
  double scale = 0.0;
  for (double q = 0.01; q < k->kappa; q += 0.01)
    scale = fmax(scale, fabs(k->df[dim - 1](q) / q));
  for (double q = 0.0137; q < k->kappa + 0.3; q += 0.0123)
    ck_assert_double_eq_tol(k->dfq[dim - 1](q * q), k->df[dim - 1](q) / q,
                            1e-13 * scale);
}
END_TEST

/* The loops reach the kernel through its dfq_id (solver/pair.h): the
 * shape behind the id is the descriptor's dfq, bit for bit (tol 0: the
 * same inline function, or a wrong id). */
START_TEST(test_dfq_id) {
  const struct vsph_kernel_type *k = vsph_kernel_get((size_t)_i / 3);
  const int dim = _i % 3 + 1;
  for (double q = 0.0137; q < k->kappa + 0.3; q += 0.0123)
    ck_assert(vsph_kernel_dfq_shape(k->dfq_id[dim - 1], q * q) ==
              k->dfq[dim - 1](q * q));
}
END_TEST

/* vsph_kernel_expneg over an array, as expneg_worst takes it */
static void expneg_scalar(const double *x, double *y, size_t n) {
  for (size_t k = 0; k < n; k++) y[k] = vsph_kernel_expneg(x[k]);
}

/* The worst relative error against libm's exp of @p f (y[k] = e^{-x[k]}
 * for k < n) over the whole range [0, 700]: dense near 0..9 (the
 * Gaussian's support in q^2), sparser beyond, and the reduction's
 * breakpoints (x near n ln 2 / 2, r = +-ln2/2). */
static double expneg_worst(void (*f)(const double *, double *, size_t)) {
  enum { NX = 900001 + 3 * 1000 };
  double *x = malloc(2 * NX * sizeof *x), *y = x + NX;
  ck_assert_ptr_nonnull(x);
  size_t n = 0;
  for (int s = 0; s <= 900000; s++)
    x[n++] = s < 600000 ? 1.5e-5 * s : 9.0 + 691.0 * (s - 600000) / 3e5;
  for (int k = 1; k < 2000; k += 2) {
    const double mid = 0.5 * k * 0.69314718055994530942;
    if (mid >= 700.0) break;
    x[n++] = nextafter(mid, 0.0);
    x[n++] = mid;
    x[n++] = nextafter(mid, 1e3);
  }
  f(x, y, n);
  double worst = 0.0;
  for (size_t k = 0; k < n; k++)
    worst = fmax(worst, fabs(y[k] - exp(-x[k])) / exp(-x[k]));
  free(x);
  return worst;
}

/* The branch-free e^{-x} of the loops, and the groups' sweeps' eight-lane
 * (AVX-512) and four-lane (AVX2) ones (solver/sweep_x86.c: the same
 * method, their reduction fused) where this build and CPU have them,
 * against libm's exp over [0, 700]: relative error at most 1e-15, the
 * bound the kernel's documentation states (the degree-12 remainder is
 * 2e-16, the rest is rounding). */
START_TEST(test_expneg_within_1e15_of_exp) {
  ck_assert_double_le(expneg_worst(expneg_scalar), 1e-15);
  ck_assert(vsph_kernel_expneg(0.0) == 1.0);
  int lanes = 0; /* the lane widths tested */
#if VSPH_SWEEP_X86_GROUPS
  static void (*const fn[2])(const double *, double *, size_t) = {
      vsph_sweep_x86_expneg4, vsph_sweep_x86_expneg8};
  for (int level = 1; level <= vsph_pair_x86_simd(); level++) {
    ck_assert_double_le(expneg_worst(fn[level - 1]), 1e-15);
    double zero = 0.0, y = 0.0;
    fn[level - 1](&zero, &y, 1);
    ck_assert(y == 1.0);
    lanes++;
  }
#endif
  if (lanes < 2)
    fprintf(stderr,
            "test_expneg_within_1e15_of_exp: %s in this build or CPU; "
            "left out\n",
            lanes ? "no AVX-512 sweep" : "no groups' sweep");
}
END_TEST

START_TEST(test_kernel_find_and_get_agree) {
  ck_assert_uint_eq(vsph_kernel_count(), 5);
  for (size_t i = 0; i < vsph_kernel_count(); i++) {
    const struct vsph_kernel_type *k = vsph_kernel_get(i);
    ck_assert_ptr_nonnull(k);
    ck_assert_ptr_eq(vsph_kernel_find(k->name), k);
  }
  ck_assert_ptr_null(vsph_kernel_find("gauss"));
  ck_assert_ptr_null(vsph_kernel_get(5));
  ck_assert_ptr_eq(vsph_kernel_find("gaussian"), &vsph_gaussian_type);
}
END_TEST

Suite *vsph_kernel_suite(void) {
  Suite *s = suite_create("kernel");
  TCase *tc = tcase_create("properties");
  const int n = (int)vsph_kernel_count() * 3;
  tcase_add_loop_test(tc, test_normalisation, 0, n);
  tcase_add_loop_test(tc, test_derivative_fd, 0, n);
  tcase_add_loop_test(tc, test_sign_and_support, 0, n);
  tcase_add_loop_test(tc, test_dfq_matches_df_over_q, 0, n);
  tcase_add_loop_test(tc, test_dfq_id, 0, n);
  tcase_add_test(tc, test_expneg_within_1e15_of_exp);
  tcase_add_test(tc, test_kernel_find_and_get_agree);
  suite_add_tcase(s, tc);
  return s;
}
