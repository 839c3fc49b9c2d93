/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* reports/grade.c: every rule at, just below and just above its
 * threshold, on values worked by hand. */
#include <check.h>
#include <float.h>
#include <math.h>

#include "../reports/grade.h"
#include "check_suites.h"

/* The nearest integer decides an order: 0.5 is not first order (the
 * bound is strict), the next double above it is, and so is anything up to
 * just below 1.5; NaN is not measured. */
START_TEST(test_order_is_nearest_integer) {
  ck_assert_int_eq(vsph_grade_order_is(0.5, 1), 0);
  ck_assert_int_eq(vsph_grade_order_is(nextafter(0.5, 1.0), 1), 1);
  ck_assert_int_eq(vsph_grade_order_is(nextafter(1.5, 1.0), 1), 1);
  ck_assert_int_eq(vsph_grade_order_is(1.5, 1), 0);
  ck_assert_int_eq(vsph_grade_order_is(2.2, 2), 1);
  ck_assert_int_eq(vsph_grade_order_is(NAN, 1), -1);
}
END_TEST

/* Both measures first order: agrees (the square's MGF, 0.87 and 0.86);
 * one (the wave's MGF, 0.60 by the largest difference, 0.25 by the RMS):
 * partly; neither: differs; a NaN or a span cut short by a stop: not
 * measured, whatever the values. */
START_TEST(test_orders_grade_both_measures) {
  ck_assert_int_eq(vsph_grade_orders(0.87, 0.86, 1, 0), VSPH_GRADE_AGREES);
  ck_assert_int_eq(vsph_grade_orders(0.60, 0.25, 1, 0), VSPH_GRADE_PARTLY);
  ck_assert_int_eq(vsph_grade_orders(0.25, 0.60, 1, 0), VSPH_GRADE_PARTLY);
  ck_assert_int_eq(vsph_grade_orders(0.36, -0.07, 1, 0), VSPH_GRADE_DIFFERS);
  ck_assert_int_eq(vsph_grade_orders(0.87, 0.86, 1, 1), VSPH_GRADE_UNMEASURED);
  ck_assert_int_eq(vsph_grade_orders(NAN, 0.86, 1, 0), VSPH_GRADE_UNMEASURED);
}
END_TEST

/* Converges at some order: both orders above 0.5 (0.5 itself does not
 * count, as vsph_grade_order_is has it: it does not round to 1), one of
 * them, neither; NaN or a stop. The vortex patch's MGF on rings (1.89,
 * 1.88) converges. */
START_TEST(test_converges_above_half) {
  ck_assert_int_eq(vsph_grade_converges(1.89, 1.88, 0), VSPH_GRADE_AGREES);
  ck_assert_int_eq(
      vsph_grade_converges(nextafter(0.5, 1.0), nextafter(0.5, 1.0), 0),
      VSPH_GRADE_AGREES);
  ck_assert_int_eq(vsph_grade_converges(nextafter(0.5, 1.0), 0.5, 0),
                   VSPH_GRADE_PARTLY);
  ck_assert_int_eq(vsph_grade_converges(0.3, -1.0, 0), VSPH_GRADE_DIFFERS);
  ck_assert_int_eq(vsph_grade_converges(1.0, 1.0, 1), VSPH_GRADE_UNMEASURED);
  ck_assert_int_eq(vsph_grade_converges(1.0, NAN, 0), VSPH_GRADE_UNMEASURED);
}
END_TEST

/* Half a unit of the last stated digit, by hand: "about 80 %" (0.8, one
 * digit) 0.05; 0.55 % (0.0055, two) 5e-5; Re 256 (three) 0.5; 0.001 and
 * 1000 (whose log10 sit on integers) 5e-4 and 500; 0.2848 (four) 5e-5;
 * zero or no digits: 0. Relative tolerance 1e-12 (pow's rounding). */
START_TEST(test_halfunit_of_last_digit) {
  static const struct {
    double v;
    int d;
    double want;
  } c[] = {{0.8, 1, 0.05},   {0.0055, 2, 5e-5},  {256.0, 3, 0.5},
           {0.001, 1, 5e-4}, {1000.0, 1, 500.0}, {0.2848, 4, 5e-5},
           {-0.8, 1, 0.05},  {0.0, 2, 0.0},      {0.8, 0, 0.0}};
  for (size_t k = 0; k < sizeof c / sizeof c[0]; k++)
    if (c[k].want == 0.0)
      ck_assert_double_eq(vsph_grade_halfunit(c[k].v, c[k].d), 0.0);
    else
      ck_assert_double_eq_tol(vsph_grade_halfunit(c[k].v, c[k].d), c[k].want,
                              1e-12 * c[k].want);
}
END_TEST

/* Within a halfwidth, the bound inclusive (exact binary values: 0.75 is
 * 0.25 from 0.5), one ulp beyond it out; NaN out. */
START_TEST(test_within_inclusive_bound) {
  ck_assert_int_eq(vsph_grade_within(0.75, 0.5, 0.25), 1);
  ck_assert_int_eq(vsph_grade_within(0.25, 0.5, 0.25), 1);
  ck_assert_int_eq(vsph_grade_within(nextafter(0.75, 1.0), 0.5, 0.25), 0);
  ck_assert_int_eq(vsph_grade_within(NAN, 0.5, 0.25), 0);
  ck_assert_int_eq(vsph_grade_within(0.5, 0.5, NAN), 0);
}
END_TEST

/* Apart by half a decade: exactly sqrt(10) times is apart (inclusive),
 * the next double below is not; NaN is not. */
START_TEST(test_apart_inclusive_at_half_decade) {
  ck_assert_double_eq_tol(VSPH_GRADE_APART * VSPH_GRADE_APART, 10.0, 1e-14);
  ck_assert_int_eq(vsph_grade_apart(VSPH_GRADE_APART * 2.0, 2.0), 1);
  ck_assert_int_eq(
      vsph_grade_apart(nextafter(VSPH_GRADE_APART * 2.0, 0.0), 2.0), 0);
  ck_assert_int_eq(vsph_grade_apart(NAN, 2.0), 0);
  ck_assert_int_eq(vsph_grade_apart(1.0, NAN), 0);
  ck_assert_int_eq(vsph_grade_apart(0.0, 0.0), 0); /* two zeros: not apart */
  ck_assert_int_eq(vsph_grade_apart(DBL_MIN, 0.0), 1);
}
END_TEST

/* Larger beyond the noise: a difference of exactly the noise is not
 * (strict, 0.75 - 0.5 = 0.25 in binary), a hair more is; with no noise
 * any excess counts; NaN never. */
START_TEST(test_larger_strictly_beyond_noise) {
  ck_assert_int_eq(vsph_grade_larger(0.75, 0.5, 0.25), 0);
  ck_assert_int_eq(vsph_grade_larger(nextafter(0.75, 1.0), 0.5, 0.25), 1);
  ck_assert_int_eq(vsph_grade_larger(0.5000001, 0.5, 0.0), 1);
  ck_assert_int_eq(vsph_grade_larger(0.5, 0.5, 0.0), 0);
  ck_assert_int_eq(vsph_grade_larger(NAN, 0.5, 0.0), 0);
}
END_TEST

/* A stop holds when every run at the steps tried stopped, or none did;
 * one that stopped at three CFLs and ran at the fourth (as PVWF on the
 * wave at H/dx = 120 once did) is marginal; no runs: -1. */
START_TEST(test_stop_holds) {
  const int all[3] = {1, 1, 1}, none[2] = {0, 0}, mixed[4] = {1, 1, 1, 0};
  ck_assert_int_eq(vsph_grade_stop_holds(all, 3), 1);
  ck_assert_int_eq(vsph_grade_stop_holds(none, 2), 1);
  ck_assert_int_eq(vsph_grade_stop_holds(mixed, 4), 0);
  ck_assert_int_eq(vsph_grade_stop_holds(mixed, 3), 1);
  ck_assert_int_eq(vsph_grade_stop_holds(all, 0), -1);
}
END_TEST

Suite *vsph_grade_suite(void) {
  Suite *s = suite_create("grade");
  TCase *tc = tcase_create("rules");
  tcase_add_test(tc, test_order_is_nearest_integer);
  tcase_add_test(tc, test_orders_grade_both_measures);
  tcase_add_test(tc, test_converges_above_half);
  tcase_add_test(tc, test_halfunit_of_last_digit);
  tcase_add_test(tc, test_within_inclusive_bound);
  tcase_add_test(tc, test_apart_inclusive_at_half_decade);
  tcase_add_test(tc, test_larger_strictly_beyond_noise);
  tcase_add_test(tc, test_stop_holds);
  suite_add_tcase(s, tc);
  return s;
}
