/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* reports/measures.c, the claims' figures over several runs or rows: each
 * on small tables worked by hand, at the edges that decide (ties, a run
 * not measured, an empty set). */
#include <check.h>
#include <math.h>

#include "../reports/measures.h"
#include "check_suites.h"

/* The range of the finite values only; none: +inf, -inf, 0. */
START_TEST(test_extent_of_finite_values) {
  const double x[] = {3.0, NAN, -1.5, INFINITY, 2.0, -INFINITY};
  double lo, hi;
  size_t n;
  vsph_measures_extent(x, 6, &lo, &hi, &n);
  ck_assert_double_eq(lo, -1.5);
  ck_assert_double_eq(hi, 3.0);
  ck_assert_uint_eq(n, 3);
  vsph_measures_extent(x + 1, 1, &lo, &hi, &n);
  ck_assert(isinf(lo) && lo > 0 && isinf(hi) && hi < 0);
  ck_assert_uint_eq(n, 0);
  vsph_measures_extent(x, 1, NULL, NULL, &n); /* any output may be NULL */
  ck_assert_uint_eq(n, 1);
}
END_TEST

/* The largest and smallest as chains of fmax and fmin: a NaN passed over,
 * infinities counted; from NaN, NaN only where every value is. */
START_TEST(test_largest_smallest) {
  const double x[] = {1.0, NAN, 3.0, -INFINITY};
  ck_assert_double_eq(vsph_measures_largest(x, 4, 0.0), 3.0);
  ck_assert_double_eq(vsph_measures_largest(x, 4, 5.0), 5.0);
  ck_assert_double_eq(vsph_measures_largest(x + 3, 1, 0.0), 0.0);
  ck_assert_double_eq(vsph_measures_smallest(x, 4, INFINITY), -INFINITY);
  ck_assert_double_eq(vsph_measures_smallest(x, 3, INFINITY), 1.0);
  ck_assert(isnan(vsph_measures_largest(x + 1, 1, NAN)));
  ck_assert_double_eq(vsph_measures_largest(x + 1, 2, NAN), 3.0);
  const double y[] = {2.0, INFINITY};
  ck_assert(isinf(vsph_measures_largest(y, 2, 0.0)));
  ck_assert_double_eq(vsph_measures_largest(y, 0, -1.0), -1.0);
}
END_TEST

/* A ladder's steps: |0.5 - 0.25|, |0.375 - 0.5| (exact in doubles); one
 * rung not measured: none of them. The first index of the largest and the
 * smallest; a NaN beats nothing; none: -1. */
START_TEST(test_steps_and_arg) {
  const double x[] = {0.25, 0.5, 0.375};
  double d[2];
  ck_assert_int_eq(vsph_measures_steps(x, 3, d), 1);
  ck_assert_double_eq(d[0], 0.25);
  ck_assert_double_eq(d[1], 0.125);
  const double y[] = {0.25, NAN, 0.375};
  ck_assert_int_eq(vsph_measures_steps(y, 3, d), 0);
  ck_assert(isnan(d[0]) && isnan(d[1]));
  const double w[] = {1.0, 3.0, 3.0, 0.5, NAN};
  ck_assert_int_eq(vsph_measures_arg(w, 5, 1), 1);
  ck_assert_int_eq(vsph_measures_arg(w, 5, -1), 3);
  ck_assert_int_eq(vsph_measures_arg(w + 4, 1, 1), 0);
  ck_assert_int_eq(vsph_measures_arg(w, 0, 1), -1);
}
END_TEST

/* The largest factor either way: (2, 1) and (1, 4) -> 4; equal tables 1;
 * a value not positive or not measured: infinitely far. */
START_TEST(test_max_factor_either_way) {
  const double a[] = {2.0, 1.0, 3.0}, b[] = {1.0, 4.0, 3.0};
  ck_assert_double_eq(vsph_measures_max_factor(a, b, 3), 4.0);
  ck_assert_double_eq(vsph_measures_max_factor(b, a, 3), 4.0);
  ck_assert_double_eq(vsph_measures_max_factor(a + 2, b + 2, 1), 1.0);
  ck_assert_double_eq(vsph_measures_max_factor(a, b, 0), 1.0);
  const double z[] = {2.0, 0.0, 3.0}, q[] = {2.0, NAN, 3.0},
               m[] = {2.0, -4.0, 3.0};
  ck_assert(isinf(vsph_measures_max_factor(z, b, 3)));
  ck_assert(isinf(vsph_measures_max_factor(q, b, 3)));
  ck_assert(isinf(vsph_measures_max_factor(b, m, 3)));
}
END_TEST

/* + + - (below the floor) - + : two changes over the rows used; the
 * unused row's sign and a value below the floor are passed over. */
START_TEST(test_sign_changes) {
  const double f[] = {1.0, 2.0, -1e-20, -3.0, 5.0, -7.0};
  const int use[] = {1, 1, 1, 1, 1, 0};
  ck_assert_int_eq(vsph_measures_sign_changes(f, use, 6, 1e-12), 2);
  const int all[] = {1, 1, 1, 1, 1, 1};
  ck_assert_int_eq(vsph_measures_sign_changes(f, all, 6, 1e-12), 3);
  /* a floor of 0 gives the tiny value its sign: + + - - + - */
  ck_assert_int_eq(vsph_measures_sign_changes(f, all, 6, 0.0), 3);
  ck_assert_int_eq(vsph_measures_sign_changes(f, all, 6, 4.0), 1); /* 5, -7 */
  const double g[] = {NAN, 1.0, -1.0};
  ck_assert_int_eq(vsph_measures_sign_changes(g, all, 3, 0.0), 1);
  /* an exact zero has no sign (a linear field's interior): + 0 + */
  const double z0[] = {1.0, 0.0, 2.0};
  ck_assert_int_eq(vsph_measures_sign_changes(z0, all, 3, 0.0), 0);
  /* no floor measured: nothing read, not "no change" */
  ck_assert_int_eq(vsph_measures_sign_changes(f, all, 6, NAN), -1);
}
END_TEST

/* The closest of four: errors 0.3, 0.1, 0.2, 0.05 with the last stopped:
 * the second, next 0.2, gap 0.1, the largest swing of those that ended;
 * a tie keeps the first; none ended: -1, +inf, NaN, 0. */
START_TEST(test_closest_of_forms) {
  const double u[] = {0.3, 0.1, 0.2, 0.05}, sw[] = {0.01, 0.02, 0.04, 0.5};
  int ok[] = {1, 1, 1, 0};
  struct vsph_measures_closest c;
  vsph_measures_closest(u, sw, ok, 4, &c);
  ck_assert_int_eq(c.best, 1);
  ck_assert_double_eq(c.next, 0.2);
  /* 0.2 - 0.1 in doubles: 0.1 within a rounding of 0.1 (1.4e-17) */
  ck_assert_double_eq_tol(c.gap, 0.1, 1e-16);
  ck_assert_double_eq(c.swing, 0.04);
  const double tie[] = {0.1, 0.1, 0.3, 0.4};
  vsph_measures_closest(tie, sw, ok, 4, &c);
  ck_assert_int_eq(c.best, 0);
  ck_assert_double_eq(c.gap, 0.0);
  /* an error not measured counts as a form that did not end, wherever it
   * stands in the order */
  const double un[] = {NAN, 0.1, 0.2, 0.3}, un2[] = {0.1, NAN, 0.2, 0.3};
  const int all4[] = {1, 1, 1, 1};
  vsph_measures_closest(un, sw, all4, 4, &c);
  ck_assert_int_eq(c.best, 1);
  ck_assert_double_eq(c.next, 0.2);
  ck_assert_double_eq(c.swing, 0.5);
  vsph_measures_closest(un2, sw, all4, 4, &c);
  ck_assert_int_eq(c.best, 0);
  ck_assert_double_eq(c.next, 0.2);
  const int none[] = {0, 0, 0, 0};
  vsph_measures_closest(u, sw, none, 4, &c);
  ck_assert_int_eq(c.best, -1);
  ck_assert(isinf(c.next) && isnan(c.gap));
  ck_assert_double_eq(c.swing, 0.0);
}
END_TEST

/* Three forms (the first two robust) over Re 0.5, 5, 50, the run to t* =
 * 10: form 0 fails at Re 50 (t* 4), form 1 never, form 2 at Re 5 (t* 2)
 * and 50 (t* 1). any 5 by form 2; first 50 (a robust form's); held 5
 * (both robust hold at 0.5 and 5); scores 10+10+4, 30, 10+2+1. */
START_TEST(test_robustness_map) {
  const double inf = INFINITY;
  const double tf[] = {inf, inf, 4.0, inf, inf, inf, inf, 2.0, 1.0};
  const double re[] = {0.5, 5.0, 50.0};
  const int robust[] = {1, 1, 0};
  struct vsph_measures_map m;
  ck_assert_int_eq(vsph_measures_map(tf, re, robust, 3, 3, 10.0, &m), 0);
  ck_assert_double_eq(m.any, 5.0);
  ck_assert_int_eq(m.who, 2);
  ck_assert_double_eq(m.first, 50.0);
  ck_assert_double_eq(m.held, 5.0);
  ck_assert_double_eq(m.score[0], 24.0);
  ck_assert_double_eq(m.score[1], 30.0);
  ck_assert_double_eq(m.score[2], 13.0);
  /* the first in order on a tie at the least Re; nothing fails */
  const double tie[] = {inf, 3.0, inf, inf, 3.0, inf, inf, inf, inf};
  ck_assert_int_eq(vsph_measures_map(tie, re, robust, 3, 3, 10.0, &m), 0);
  ck_assert_int_eq(m.who, 0);
  ck_assert_double_eq(m.held, 50.0); /* both robust hold at 0.5 and 50 */
  const double never[9] = {inf, inf, inf, inf, inf, inf, inf, inf, inf};
  ck_assert_int_eq(vsph_measures_map(never, re, robust, 3, 3, 10.0, &m), 0);
  ck_assert(isinf(m.any) && isinf(m.first) && m.who == -1);
  ck_assert_double_eq(m.held, 50.0);
  /* a failure time not measured: its form's score too, and its Re is not
   * held (form 0 at Re 5) */
  const double part[] = {inf, NAN, inf, inf, inf, inf, inf, inf, inf};
  ck_assert_int_eq(vsph_measures_map(part, re, robust, 3, 3, 10.0, &m), 0);
  ck_assert(isnan(m.score[0]));
  ck_assert_double_eq(m.score[1], 30.0);
  ck_assert_double_eq(m.held, 50.0);
  const double part2[] = {inf, inf, NAN, inf, inf, inf, inf, inf, inf};
  ck_assert_int_eq(vsph_measures_map(part2, re, robust, 3, 3, 10.0, &m), 0);
  ck_assert_double_eq(m.held, 5.0);
  ck_assert(isinf(m.any) && m.who == -1);
  const double shuffled[] = {5.0, 50.0, 0.5}; /* the largest, in any order */
  ck_assert_int_eq(vsph_measures_map(never, shuffled, robust, 3, 3, 10, &m), 0);
  ck_assert_double_eq(m.held, 50.0);
  ck_assert_int_eq(vsph_measures_map(never, re, robust,
                                     VSPH_MEASURES_MAP_MAXF + 1, 0, 1, &m),
                   -1);
}
END_TEST

/* A sweep of three c over two dt (largest first):
 *   c0: runs, runs  errors 0.02, 0.01  zigzag 0.3
 *   c1: stops at 0.2, runs  error -, 0.05  zigzag 0.1
 *   c2: stops at 0.1, stops at 0.3
 * nbad 3 of 6; mixed at c1; acc (0.02 - 0.01)/0.01 = 1 at c0; rise
 * 0.01/0.02 = 0.5; turn at c1; lag at c2 only, 0.3/0.1 = 3; zigzag over
 * c0 and c1: lowest 0.1 at c1, highest 0.3 at c0. */
START_TEST(test_sweep_figures) {
  struct vsph_measures_sweep_in in = {.nc = 3, .nd = 2};
  const char out[3][2] = {{'r', 'r'}, {'s', 'r'}, {'s', 's'}};
  const double err[3][2] = {{0.02, 0.01}, {NAN, 0.05}, {NAN, NAN}};
  const double ts[3][2] = {{NAN, NAN}, {0.2, NAN}, {0.1, 0.3}};
  const double zig[3] = {0.3, 0.1, NAN};
  for (int a = 0; a < 3; a++) {
    for (int b = 0; b < 2; b++) {
      in.out[a][b] = out[a][b];
      in.err[a][b] = err[a][b];
      in.t_stop[a][b] = ts[a][b];
    }
    in.zig[a] = zig[a];
  }
  struct vsph_measures_sweep w;
  ck_assert_int_eq(vsph_measures_sweep(&in, &w), 0);
  ck_assert_int_eq(w.nbad, 3);
  ck_assert_int_eq(w.ntot, 6);
  ck_assert_int_eq(w.mixed, 1);
  ck_assert_int_eq(w.out[0], 'r');
  ck_assert_int_eq(w.out[1], 'm');
  ck_assert_int_eq(w.out[2], 's');
  ck_assert_double_eq(w.acc, 1.0);
  ck_assert_double_eq(w.rise, 0.5);
  ck_assert_int_eq(w.turn, 1);
  ck_assert(isnan(w.lag[0]) && isnan(w.lag[1]));
  /* 0.3/0.1 in doubles: within a few roundings of 3 (4.4e-16 each) */
  ck_assert_double_eq_tol(w.lag[2], 3.0, 1e-15);
  ck_assert_double_eq(w.zlo, 0.1);
  ck_assert_int_eq(w.alo, 1);
  ck_assert_double_eq(w.zhi, 0.3);
  ck_assert_int_eq(w.ahi, 0);
  /* an error not measured where all run: neither the change nor the rise
   * is measured (not a change of 0 over the one measured) */
  in.err[0][1] = NAN;
  ck_assert_int_eq(vsph_measures_sweep(&in, &w), 0);
  ck_assert(isnan(w.acc) && isnan(w.rise) && w.open);
  /* a stop not measured at a larger dt: that c's lag is not measured */
  in.err[0][1] = 0.01;
  in.t_stop[2][0] = NAN;
  ck_assert_int_eq(vsph_measures_sweep(&in, &w), 0);
  ck_assert(isnan(w.lag[2]));
  ck_assert_double_eq(w.acc, 1.0);
  /* the larger dts' latest stop at 0: no ratio (not infinite) */
  in.t_stop[2][0] = 0.0;
  ck_assert_int_eq(vsph_measures_sweep(&in, &w), 0);
  ck_assert(isnan(w.lag[2]));
  in.t_stop[2][0] = 0.1;
  /* no c where every dt runs: no change measured, no rise */
  in.out[0][1] = 'a';
  in.err[0][1] = 0.01;
  ck_assert_int_eq(vsph_measures_sweep(&in, &w), 0);
  ck_assert(isnan(w.acc) && isnan(w.rise));
  ck_assert_int_eq(w.nbad, 4);
  ck_assert_int_eq(w.mixed, 0);
  ck_assert_int_eq(w.alo, 1); /* c0's smallest dt agitates: not counted */
  ck_assert_int_eq(w.ahi, 1);
  in.nd = VSPH_MEASURES_SWEEP_MAXD + 1;
  ck_assert_int_eq(vsph_measures_sweep(&in, &w), -1);
}
END_TEST

/* Three runs over one reference: E's, seen and below throughout (peak 0.9,
 * last 0.8 at 30 s); one at the paper's resolution, seen, not below (peak
 * 1.1, its last ratio not measured, at 20 s); D's, not seen. Two
 * measured, one under, the peak 1.1, the last ratios' range 0.8 alone,
 * times 20-30 s, one seen in each of the first and third groups. */
START_TEST(test_ratios_gathered) {
  struct vsph_series_ratio hr[3] = {
      {.seen = 1, .below = 1, .peak = 0.9, .t_last = 30, .last = 0.8},
      {.seen = 1, .below = 0, .peak = 1.1, .t_last = 20, .last = NAN},
      {.seen = 0, .below = 1, .peak = -INFINITY, .t_last = 0.5, .last = NAN}};
  const int group[3] = {1, 4, 2};
  struct vsph_measures_ratios g;
  vsph_measures_ratios(hr, group, 3, &g);
  ck_assert_int_eq(g.measured, 2);
  ck_assert_int_eq(g.under, 1);
  ck_assert_double_eq(g.peak, 1.1);
  ck_assert_double_eq(g.lo, 0.8);
  ck_assert_double_eq(g.hi, 0.8);
  ck_assert_double_eq(g.t_lo, 20.0);
  ck_assert_double_eq(g.t_hi, 30.0);
  ck_assert_int_eq(g.seen_in[0], 1);
  ck_assert_int_eq(g.seen_in[1], 0);
  ck_assert_int_eq(g.seen_in[2], 1);
  /* a peak not measured, even an unseen run's: the peak is not */
  hr[2].peak = NAN;
  vsph_measures_ratios(hr, group, 3, &g);
  ck_assert(isnan(g.peak));
  /* none: the empty extents */
  vsph_measures_ratios(hr, group, 0, &g);
  ck_assert(g.measured == 0 && isinf(g.peak) && g.peak < 0);
  ck_assert(isinf(g.t_lo) && g.t_lo > 0 && isinf(g.hi) && g.hi < 0);
}
END_TEST

Suite *vsph_measures_suite(void) {
  Suite *s = suite_create("measures");
  TCase *tc = tcase_create("core");
  tcase_add_test(tc, test_extent_of_finite_values);
  tcase_add_test(tc, test_largest_smallest);
  tcase_add_test(tc, test_steps_and_arg);
  tcase_add_test(tc, test_max_factor_either_way);
  tcase_add_test(tc, test_sign_changes);
  tcase_add_test(tc, test_closest_of_forms);
  tcase_add_test(tc, test_robustness_map);
  tcase_add_test(tc, test_sweep_figures);
  tcase_add_test(tc, test_ratios_gathered);
  suite_add_tcase(s, tc);
  return s;
}
