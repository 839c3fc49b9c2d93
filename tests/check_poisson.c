/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <math.h>

#include "../solver/poisson.h"
#include "check_suites.h"

/* Manufactured solutions: lap p = f with p on the boundary. */
static double cubic(double x, double y, void *c) {
  (void)c;
  return 0.7 * x * x * x - 1.1 * y * y * y + 0.3 * x * x * y - 0.45 * x * y +
         2.385;
}
static double cubic_lap(double x, double y, void *c) {
  (void)c;
  return 4.2 * x - 6.6 * y + 0.6 * y;
}
static double smooth(double x, double y, void *c) {
  (void)c;
  return sin(1.3 * x + 0.4) * cosh(0.7 * y);
}
static double smooth_lap(double x, double y, void *c) {
  (void)c;
  return (0.49 - 1.69) * sin(1.3 * x + 0.4) * cosh(0.7 * y);
}
static double bilinear(double x, double y, void *c) {
  (void)c;
  return 1.0 + 2.0 * x - 3.0 * y + 0.5 * x * y; /* harmonic */
}
static double zero(double x, double y, void *c) {
  (void)x, (void)y, (void)c;
  return 0.0;
}

static double max_node_error(size_t n, double side, vsph_poisson_fn *p,
                             vsph_poisson_fn *lap) {
  struct vsph_poisson *ps = vsph_poisson_alloc(n, side);
  ck_assert_ptr_nonnull(ps);
  ck_assert_int_eq(vsph_poisson_solve(ps, lap, p, NULL), 0);
  const double h = vsph_poisson_spacing(ps), lo = -0.5 * side;
  double err = 0.0;
  for (size_t j = 1; j <= n; j++)
    for (size_t i = 1; i <= n; i++)
      err = fmax(err, fabs(vsph_poisson_node(ps, i, j) -
                           p(lo + (double)i * h, lo + (double)j * h, NULL)));
  vsph_poisson_free(ps);
  return err;
}

/* The 5-point Laplacian is exact for cubics, so the discrete solution is
 * the exact one at the nodes: only rounding remains (the inverse has a
 * condition number ~ n^2 ~ 1e3, so ~1e-13; tol 1e-11). */
START_TEST(test_cubic_exact) {
  ck_assert_double_lt(max_node_error(31, 1.2348, cubic, cubic_lap), 1e-11);
  ck_assert_double_lt(max_node_error(40, 0.6180, cubic, cubic_lap), 1e-11);
}
END_TEST

/* A transcendental solution converges at second order: the node error
 * ratio per halving of h is 4 (tol 3.8-4.2). */
START_TEST(test_second_order) {
  const double e1 = max_node_error(15, 1.0, smooth, smooth_lap);
  const double e2 = max_node_error(31, 1.0, smooth, smooth_lap);
  const double e3 = max_node_error(63, 1.0, smooth, smooth_lap);
  ck_assert_double_gt(e1, 1e-7); /* a real discretisation error */
  ck_assert_double_eq_tol(e1 / e2, 4.0, 0.2);
  ck_assert_double_eq_tol(e2 / e3, 4.0, 0.2);
}
END_TEST

/* Bilinear interpolation reproduces a harmonic bilinear field anywhere in
 * the square (tol: rounding of the solve, 1e-12). */
START_TEST(test_bilinear_field_interpolated_exactly) {
  struct vsph_poisson *ps = vsph_poisson_alloc(20, 2.0);
  ck_assert_int_eq(vsph_poisson_solve(ps, zero, bilinear, NULL), 0);
  for (double x = -0.99; x < 1.0; x += 0.1237)
    for (double y = -0.99; y < 1.0; y += 0.0931)
      ck_assert_double_eq_tol(vsph_poisson_interp(ps, x, y),
                              bilinear(x, y, NULL), 1e-12);
  vsph_poisson_free(ps);
}
END_TEST

START_TEST(test_bad_grid_or_length_refused) {
  vsph_test_silence();
  ck_assert_ptr_null(vsph_poisson_alloc(1, 1.0));
  ck_assert_ptr_null(vsph_poisson_alloc(8, -1.0));
}
END_TEST

Suite *vsph_poisson_suite(void) {
  Suite *s = suite_create("poisson");
  TCase *tc = tcase_create("fftw");
  tcase_add_test(tc, test_cubic_exact);
  tcase_add_test(tc, test_second_order);
  tcase_add_test(tc, test_bilinear_field_interpolated_exactly);
  tcase_add_test(tc, test_bad_grid_or_length_refused);
  suite_add_tcase(s, tc);
  return s;
}
