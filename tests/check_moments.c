/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <gsl/gsl_integration.h>
#include <math.h>

#include "../analysis/moments.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "check_suites.h"

static gsl_integration_workspace *wo, *wi;
static void ws_setup(void) {
  wo = gsl_integration_workspace_alloc(1000);
  wi = gsl_integration_workspace_alloc(1000);
}
static void ws_teardown(void) {
  gsl_integration_workspace_free(wo);
  gsl_integration_workspace_free(wi);
}

/* Quadrature against THEORY section 2 at half (depth 0) and full support
 * (depth kappa and beyond), every kernel, every dimension: G = S, S/2;
 * M = delta, delta/2; F = N = 0 inside; F, N surface forms with C_F, C_N
 * from the closed formula (an independent one-dimensional quadrature). */
START_TEST(test_theory_values) {
  const struct vsph_kernel_type *k = vsph_kernel_get((size_t)_i / 3);
  const int dim = _i % 3 + 1;
  double C_F, C_N;
  ck_assert_int_eq(vsph_moments_constants(k, dim, 1e-12, wo, &C_F, &C_N), 0);
  const double depths[3] = {0.0, k->kappa, k->kappa + 0.61};
  for (int m = 0; m < 3; m++) {
    struct vsph_moments q, th;
    ck_assert_int_eq(
        vsph_moments_quadrature(k, dim, depths[m], 1e-10, wo, wi, &q), 0);
    vsph_moments_theory(dim, m == 0, C_F, C_N, &th);
    double gap[4];
    vsph_moments_gap(&q, &th, gap);
    /* tol: quadrature requested at 1e-10 relative; F and N scale with
     * C_F ~ 1.5, G and M with 1. */
    ck_assert_double_le(gap[0], 1e-9 * C_F);
    ck_assert_double_le(gap[1], 1e-9);
    ck_assert_double_le(gap[2], 1e-9 * C_N);
    ck_assert_double_le(gap[3], 1e-9);
  }
}
END_TEST

/* The untruncated Gaussian w = exp(-q^2)/pi^{d/2}: the paper's Appendix B
 * constants C_F = K/(3 sqrt pi) (2-D), K/(4 sqrt pi) (3-D), C_N = 2/sqrt
 * pi. Support 7h: exp(-49) ~ 5e-22 is far below the tolerance. */
static double f_gauss_inf(double q) { return q < 7.0 ? exp(-q * q) : 0.0; }
static double df_gauss_inf(double q) {
  return q < 7.0 ? -2.0 * q * exp(-q * q) : 0.0;
}
static const struct vsph_kernel_type gauss_inf = {
    .name = "gaussian-untruncated",
    .kappa = 7.0,
    .sigma = {1.0 / VSPH_SQRTPI, 1.0 / VSPH_PI, 1.0 / (VSPH_PI * VSPH_SQRTPI)},
    .f = {f_gauss_inf, f_gauss_inf, f_gauss_inf},
    .df = {df_gauss_inf, df_gauss_inf, df_gauss_inf},
    .reference = "test only",
};

START_TEST(test_paper_gaussian_constants) {
  for (int dim = 2; dim <= 3; dim++) {
    const double K = 2.0 * (dim + 2);
    const double want_F =
        dim == 2 ? K / (3.0 * VSPH_SQRTPI) : K / (4.0 * VSPH_SQRTPI);
    const double want_N = 2.0 / VSPH_SQRTPI;
    double C_F, C_N;
    ck_assert_int_eq(
        vsph_moments_constants(&gauss_inf, dim, 1e-12, wo, &C_F, &C_N), 0);
    ck_assert_double_eq_tol(C_F, want_F, 1e-10); /* quadrature 1e-12 */
    ck_assert_double_eq_tol(C_N, want_N, 1e-10);
    /* and through the surface tensors themselves: F_ddd = -2 C_F */
    struct vsph_moments q;
    ck_assert_int_eq(
        vsph_moments_quadrature(&gauss_inf, dim, 0.0, 1e-10, wo, wi, &q), 0);
    ck_assert_double_eq_tol(q.F[dim - 1][dim - 1][dim - 1], -2.0 * want_F,
                            1e-9);
    ck_assert_double_eq_tol(q.N[dim - 1], -want_N, 1e-9);
  }
}
END_TEST

/* Between the surface and kappa h, F and N decay to zero and G, M rise to
 * their full values (THEORY 2): monotone profiles in 2-D and 3-D. */
START_TEST(test_depth_profiles) {
  const struct vsph_kernel_type *k = &vsph_gaussian_type;
  for (int dim = 2; dim <= 3; dim++) {
    const int n = dim - 1;
    double prevF = -INFINITY, prevN = -INFINITY, prevG = 0, prevM = 0;
    for (double d = 0.0; d <= k->kappa + 1e-9; d += 0.25) {
      struct vsph_moments q;
      ck_assert_int_eq(vsph_moments_quadrature(k, dim, d, 1e-10, wo, wi, &q),
                       0);
      ck_assert_double_ge(q.F[n][n][n], prevF);
      ck_assert_double_ge(q.N[n], prevN);
      ck_assert_double_ge(q.G[n][n][n][n], prevG);
      ck_assert_double_ge(q.M[n][n], prevM);
      prevF = q.F[n][n][n];
      prevN = q.N[n];
      prevG = q.G[n][n][n][n];
      prevM = q.M[n][n];
    }
  }
}
END_TEST

static double sum_gap(int dim, int kind, double perturb, double hdx,
                      double depth, double gap[4]) {
  const struct vsph_kernel_type *k = &vsph_gaussian_type;
  struct vsph_lattice_props lp = {.dim = dim,
                                  .kind = kind,
                                  .dx = 1.0 / hdx,
                                  .perturb = perturb,
                                  .seed = 2385};
  struct vsph_particles *p = NULL;
  size_t c;
  ck_assert_int_eq(
      vsph_lattice_halfspace(&lp, k->kappa + 2.0 / hdx, depth, &p, &c), 0);
  struct vsph_moments s, q;
  ck_assert_int_eq(vsph_moments_sum(k, p, c, 1.0, &s), 0);
  vsph_particles_free(p);
  ck_assert_int_eq(vsph_moments_quadrature(k, dim, depth, 1e-10, wo, wi, &q),
                   0);
  vsph_moments_gap(&s, &q, gap);
  return fmax(fmax(gap[0], gap[1]), fmax(gap[2], gap[3]));
}

/* Particle sums converge to the quadrature as h/dx grows. At the surface
 * the top row sits on the plane, so the tangential entries carry an
 * O(dx/h) part: at least first order (ratio >= 1.8 per doubling, 2 ideal,
 * margin for the higher-order terms). In full support the square-lattice
 * gap falls much faster. */
START_TEST(test_sums_converge) {
  for (int dim = 2; dim <= 3; dim++) {
    double g[4];
    const double hdx3 = dim == 2 ? 8.0 : 6.0;
    const double a = sum_gap(dim, VSPH_LATTICE_SQUARE, 0, hdx3 / 4, 0.0, g);
    const double b = sum_gap(dim, VSPH_LATTICE_SQUARE, 0, hdx3 / 2, 0.0, g);
    const double c = sum_gap(dim, VSPH_LATTICE_SQUARE, 0, hdx3, 0.0, g);
    ck_assert_double_ge(a / b, 1.8);
    ck_assert_double_ge(b / c, 1.8);
    const double fa = sum_gap(dim, VSPH_LATTICE_SQUARE, 0, 1.0, 3.5, g);
    const double fc = sum_gap(dim, VSPH_LATTICE_SQUARE, 0, 2.0, 3.5, g);
    ck_assert_double_le(fc, 0.1 * fa);
  }
  /* hexagonal and perturbed sets converge too (2-D, full support) */
  double g[4];
  ck_assert_double_le(sum_gap(2, VSPH_LATTICE_HEX, 0, 3.0, 3.5, g),
                      0.1 * sum_gap(2, VSPH_LATTICE_HEX, 0, 1.0, 3.5, g));
  ck_assert_double_le(sum_gap(2, VSPH_LATTICE_SQUARE, 0.1, 4.0, 3.5, g),
                      0.5 * sum_gap(2, VSPH_LATTICE_SQUARE, 0.1, 1.0, 3.5, g));
}
END_TEST

START_TEST(test_bad_args_refused) {
  vsph_test_silence();
  struct vsph_moments q;
  const struct vsph_kernel_type *k = &vsph_cubic_type;
  ck_assert_int_eq(vsph_moments_quadrature(k, 4, 0.0, 1e-10, wo, wi, &q),
                   1 /* VSPH_EINVAL */);
  ck_assert_int_eq(vsph_moments_quadrature(k, 2, -0.5, 1e-10, wo, wi, &q), 1);
  ck_assert_int_eq(vsph_moments_quadrature(k, 2, 0.0, 1e-15, wo, wi, &q), 1);
  ck_assert_int_eq(vsph_moments_quadrature(k, 2, 0.0, 1e-10, wo, wo, &q), 1);
}
END_TEST

/* The public entry points refuse a NULL or out-of-range argument with
 * VSPH_EINVAL instead of dereferencing it: an unknown kernel name gives a
 * NULL vsph_kernel_find, which a caller may pass on. */
START_TEST(test_null_and_out_of_range_refused) {
  vsph_test_silence();
  struct vsph_moments q;
  double cf, cn;
  const struct vsph_kernel_type *k = &vsph_cubic_type;
  ck_assert_ptr_null(vsph_kernel_find("no-such-kernel"));
  ck_assert_int_eq(vsph_moments_quadrature(NULL, 2, 0.0, 1e-10, wo, wi, &q),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_moments_quadrature(k, 2, 0.0, 1e-10, NULL, wi, &q),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_moments_quadrature(k, 2, 0.0, 1e-10, wo, wi, NULL),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_moments_constants(NULL, 2, 1e-10, wo, &cf, &cn),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_moments_constants(k, 2, 1e-10, wo, NULL, &cn),
                   VSPH_EINVAL);
  ck_assert_int_eq(vsph_moments_sum(k, NULL, 0, 1.0, &q), VSPH_EINVAL);
  struct vsph_moments_result r;
  ck_assert_int_eq(vsph_moments_compute(NULL, &r), VSPH_EINVAL);
  struct vsph_moments_props mp;
  ck_assert_int_eq(vsph_moments_props_init(&mp, NULL), VSPH_OK);
  ck_assert_int_eq(vsph_moments_compute(&mp, NULL), VSPH_EINVAL);
  /* each field out of range in turn, the rest as the defaults */
  struct vsph_moments_props bad[7];
  for (int i = 0; i < 7; i++) bad[i] = mp;
  bad[0].kernel = vsph_kernel_find("no-such-kernel");
  bad[1].dim = 0;
  bad[2].dim = 4;
  bad[3].depth = -1.0;
  bad[4].epsrel = 0.0;
  bad[5].particles = 1, bad[5].lattice_kind = 7;
  bad[6].particles = 1, bad[6].hdx = 0.0;
  for (int i = 0; i < 7; i++)
    ck_assert_msg(vsph_moments_compute(&bad[i], &r) == VSPH_EINVAL,
                  "case %d accepted", i);
}
END_TEST

Suite *vsph_moments_suite(void) {
  Suite *s = suite_create("moments");
  TCase *tc = tcase_create("quadrature");
  tcase_add_checked_fixture(tc, ws_setup, ws_teardown);
  tcase_add_loop_test(tc, test_theory_values, 0, (int)vsph_kernel_count() * 3);
  tcase_add_test(tc, test_paper_gaussian_constants);
  tcase_add_test(tc, test_depth_profiles);
  tcase_add_test(tc, test_bad_args_refused);
  tcase_add_test(tc, test_null_and_out_of_range_refused);
  suite_add_tcase(s, tc);
  TCase *ts = tcase_create("sums");
  tcase_add_checked_fixture(ts, ws_setup, ws_teardown);
  tcase_set_timeout(ts, 60);
  tcase_add_test(ts, test_sums_converge);
  suite_add_tcase(s, ts);
  return s;
}
