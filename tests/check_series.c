/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* analysis/series.c on plain arrays, each measure against a closed form
 * computed here. */
#include <check.h>
#include <math.h>

#include "../analysis/series.h"
#include "../common/status.h"
#include "check_suites.h"

/* A linear function is interpolated exactly (to rounding: 1e-15 of its
 * values) at any point, repeated abscissae included; outside the table,
 * and for an empty one, NaN. */
/* An order fitted through the stable points only: y = x^2 at three
 * stable points, and a stopped one off the line (x 8, y 1) left out;
 * fewer than two stable points give none. */
START_TEST(test_slope_where) {
  const double x[4] = {1, 2, 4, 8}, y[4] = {1, 4, 16, 1};
  const int ok[4] = {1, 1, 1, 0}, one[4] = {0, 0, 1, 0};
  size_t ns = 0;
  ck_assert_double_eq_tol(vsph_series_slope_where(x, y, ok, 4, &ns), 2.0,
                          1e-12);
  ck_assert_uint_eq(ns, 3);
  ck_assert(isnan(vsph_series_slope_where(x, y, one, 4, &ns)));
  ck_assert_uint_eq(ns, 1);
}
END_TEST

START_TEST(test_interp_linear_exact_nan_outside) {
  const double t[6] = {0.0, 0.5, 0.5, 1.5, 2.25, 3.0};
  double y[6];
  for (int k = 0; k < 6; k++) y[k] = 2.0 * t[k] + 1.0;
  for (double x = 0.0; x <= 3.0; x += 0.0625)
    ck_assert_double_eq_tol(vsph_series_interp(t, y, 6, x), 2.0 * x + 1.0,
                            1e-15 * 7.0);
  ck_assert(isnan(vsph_series_interp(t, y, 6, -1e-9)));
  ck_assert(isnan(vsph_series_interp(t, y, 6, 3.0 + 1e-9)));
  ck_assert(isnan(vsph_series_interp(t, y, 0, 0.0)));
}
END_TEST

/* Four values built as E* + k eps_r + c_r h_m, h_1 = h_0/2: first-order
 * Richardson removes c_r h exactly and the line in eps lands on E*; to
 * rounding (1e-14 of the values). */
START_TEST(test_extrapolate) {
  const double Es = 1.234, k = 5.0, eps[2] = {0.02, 0.005}, c[2] = {0.3, -0.7},
               h0 = 0.1;
  double e[2][2];
  for (int r = 0; r < 2; r++)
    for (int m = 0; m < 2; m++)
      e[r][m] = Es + k * eps[r] + c[r] * h0 / (1 << m);
  ck_assert_double_eq_tol(vsph_series_extrapolate(e, eps), Es, 1e-14 * 2.0);
}
END_TEST

/* E = 3 e^-t against R = 7 e^-1.02t: the normalised gap e^-t - e^-1.02t
 * peaks at t* = ln(1.02)/0.02, a sample point here; its value there by
 * the closed form (rounding: 1e-15). Rows where R is NaN are left out,
 * even one that would be larger. */
START_TEST(test_decay_error) {
  enum { N = 41 };
  const double ts = log(1.02) / 0.02;
  double t[N], E[N], R[N];
  for (int k = 0; k < N; k++) {
    t[k] = ts * k / 20.0; /* t[20] = t* */
    E[k] = 3.0 * exp(-t[k]);
    R[k] = 7.0 * exp(-1.02 * t[k]);
  }
  const double want = exp(-ts) - exp(-1.02 * ts);
  ck_assert_double_eq_tol(vsph_series_decay_error(E, R, N), want, 1e-15);
  E[30] = 0.0, R[30] = NAN; /* a gap of 1 - e^-... there: left out */
  ck_assert_double_eq_tol(vsph_series_decay_error(E, R, N), want, 1e-15);
  /* the same reference as a coarse table of a linear function: exact */
  const double tr[3] = {0.0, 1.0, 4.0}, Rr[3] = {10.0, 8.0, 2.0};
  double Et[5], tt[5] = {0.0, 0.5, 1.0, 2.0, 5.0};
  for (int k = 0; k < 5; k++) Et[k] = 5.0;
  /* 1 - (10 - 2 t)/10 = t/5 at t = 2 (t = 5 lies past the table) */
  ck_assert_double_eq_tol(vsph_series_decay_error_table(tt, Et, 5, tr, Rr, 3),
                          0.4, 1e-15);
}
END_TEST

/* dE = -1 against dR = -1 + 0.1 t with threshold 0.05: the gap 0.1 t
 * exceeds 0.05 |dR| past t = 0.05/0.105 = 0.476..., so at the reference's
 * point 0.5; a run that stops at 0.3 departs at the first point past its
 * end, 0.4; a threshold never reached gives NaN. */
START_TEST(test_onset_first_point_past_gap) {
  double t[11], dE[11], tr[11], dR[11];
  for (int k = 0; k <= 10; k++) {
    t[k] = tr[k] = 0.1 * k;
    dE[k] = -1.0;
    dR[k] = -1.0 + 0.1 * tr[k];
  }
  ck_assert_double_eq(vsph_series_onset(t, dE, 11, tr, dR, 11, 0.05), tr[5]);
  ck_assert_double_eq(vsph_series_onset(t, dE, 4, tr, dR, 11, 0.05), tr[4]);
  ck_assert(isnan(vsph_series_onset(t, dE, 11, tr, dR, 11, 0.5)));
}
END_TEST

/* The trapezoid rule integrates a linear rate exactly on an uneven grid:
 * int_0^T (2 - 3t) dt = 2T - 1.5 T^2 (rounding, 1e-15); an energy lost
 * over the reference's share by hand: (0.3/2)/(1 - 3/4) = 0.6. */
START_TEST(test_integral_loss) {
  const double t[5] = {0.0, 0.1, 0.35, 0.4, 1.0};
  double y[5];
  for (int k = 0; k < 5; k++) y[k] = 2.0 - 3.0 * t[k];
  for (size_t row = 0; row < 5; row++)
    ck_assert_double_eq_tol(vsph_series_integral(t, y, row),
                            2.0 * t[row] - 1.5 * t[row] * t[row], 1e-15);
  ck_assert_double_eq_tol(vsph_series_loss_ratio(0.3, 2.0, 4.0, 3.0), 0.6,
                          1e-15);
  ck_assert(isnan(vsph_series_loss_ratio(0.3, 2.0, 4.0, 4.0)));
}
END_TEST

/* The first reach of a level after a start, on a scaled time axis: e =
 * t/4 reaches 0.12 at t = 0.48, the first sample at or past it 0.5, times
 * scale 2 = 1.0; from a later start (scaled 1.6) it is that start's
 * sample; a level never reached gives NaN. */
START_TEST(test_first_reach) {
  double t[11], e[11];
  for (int k = 0; k <= 10; k++) t[k] = 0.1 * k, e[k] = t[k] / 4.0;
  ck_assert_double_eq(vsph_series_first_reach(t, e, 11, 2.0, 0.0, 0.12),
                      t[5] * 2.0);
  ck_assert_double_eq(vsph_series_first_reach(t, e, 11, 2.0, 1.6, 0.12),
                      t[8] * 2.0);
  ck_assert(isnan(vsph_series_first_reach(t, e, 11, 2.0, 0.0, 0.3)));
}
END_TEST

/* Basa's failure time on e = t/4 (scale 2): reaching 0.12 first (at the
 * scaled 1.0, as test_first_reach) wins over a later stop; a stop with
 * the level never reached gives the stop's scaled time, 2 x 0.7; neither
 * gives infinity; a missing error column only the stop. */
START_TEST(test_failure_time_first_reach_or_stop) {
  double t[11], e[11];
  for (int k = 0; k <= 10; k++) t[k] = 0.1 * k, e[k] = t[k] / 4.0;
  char why = 'x';
  ck_assert_double_eq(vsph_series_failure(t, e, 11, 2.0, 0.0, 0.12, 0.7, &why),
                      t[5] * 2.0);
  ck_assert_int_eq(why, 'e');
  ck_assert_double_eq(vsph_series_failure(t, e, 11, 2.0, 0.0, 0.3, 0.7, &why),
                      1.4);
  ck_assert_int_eq(why, 'p');
  ck_assert(isinf(vsph_series_failure(t, e, 11, 2.0, 0.0, 0.3, NAN, &why)));
  ck_assert_int_eq(why, ' ');
  ck_assert_double_eq(
      vsph_series_failure(t, NULL, 11, 2.0, 0.0, 0.12, 0.7, &why), 1.4);
  ck_assert_int_eq(why, 'p');
}
END_TEST

/* The tail mean of y = t^2 on t = 0, 0.1, ..., 1 from 0.8 t_end: the
 * rows 0.8, 0.9, 1.0, (0.64 + 0.81 + 1)/3 by hand (the row at 0.8 is in:
 * 0.8 x 1.0 is 0.8 in doubles as 0.1 x 8 is); one row: itself; none: NaN. */
START_TEST(test_tail_mean) {
  double t[11], y[11];
  for (int k = 0; k <= 10; k++) t[k] = k / 10.0, y[k] = t[k] * t[k];
  ck_assert_double_eq_tol(vsph_series_tail_mean(t, y, 11, 0.8),
                          (0.64 + 0.81 + 1.0) / 3.0, 1e-15);
  ck_assert_double_eq(vsph_series_tail_mean(t, y, 1, 0.8), y[0]);
  ck_assert(isnan(vsph_series_tail_mean(t, y, 0, 0.8)));
  /* its range there: y rises, so y(1) - y(0.8) = 1 - 0.64; a row before
   * the window (y[0] = 5) does not count */
  y[0] = 5.0;
  ck_assert_double_eq_tol(vsph_series_tail_range(t, y, 11, 0.8), 1.0 - 0.64,
                          1e-15);
  ck_assert(isnan(vsph_series_tail_range(t, y, 0, 0.8)));
}
END_TEST

/* A plateau by hand: E/R = 1, 1.02, 0.98 on the rows inside [lo, hi]
 * (R > 0), so the spread is 0.04/1.0; v there 5, 1, 3 (median 3); rows
 * outside and one with R = 0 left out. */
START_TEST(test_plateau_spread_and_median) {
  const double t[7] = {0, 1, 2, 3, 4, 5, 6};
  const double R[7] = {1, 2, 2, 0, 5, 4, 1};
  const double E[7] = {9, 2, 2.04, 7, 4.9, 4.0, 9};
  const double v[7] = {100, 5, 1, 50, 3, 2, 100};
  double work[8], spread, median;
  /* scale 0.5: rows 1-5 have scaled times 0.5-2.5 inside [0.5, 2.0] */
  vsph_series_plateau(t, E, R, v, 7, 0.5, 0.5, 2.0, work, 8, &spread, &median);
  ck_assert_double_eq_tol(spread, 0.04 / 1.0, 1e-15);
  ck_assert_double_eq(median, 3.0);
  vsph_series_plateau(t, E, R, v, 7, 0.5, 10.0, 20.0, work, 8, &spread,
                      &median);
  ck_assert(isnan(spread) && isnan(median));
}
END_TEST

/* The time step's rule, worked by hand on rows of errors at CFL 0.5, 1,
 * 1.5, 2 (10 %): changes of 1 %, 5 %, 9 % all pass (index 3, CFL 2);
 * 11 % at CFL 1.5 stops it at CFL 1 even if CFL 2 were fine again; a row
 * unstable at CFL 1.5 and 2 (stable at 0.5) is left to the stability
 * verdict, not the accuracy rule; a row unstable at 0.5 counts nowhere;
 * a change of exactly the fraction passes (the bound is inclusive). */
START_TEST(test_cfl_rule) {
  const double e1[] = {1.0, 1.01, 1.05, 0.91};
  const int s1[] = {1, 1, 1, 1};
  ck_assert_int_eq(vsph_series_cfl_pick(e1, s1, 1, 4, 0.1), 3);
  const double e2[] = {1.0, 1.01, 1.05, 0.91, 2.0, 2.02, 2.22, 2.0};
  const int s2[] = {1, 1, 1, 1, 1, 1, 1, 1};
  ck_assert_int_eq(vsph_series_cfl_pick(e2, s2, 2, 4, 0.1), 1);
  const double e3[] = {1.0, 1.01, 5.0, 9.0, 2.0, 2.0, 2.1, 2.1};
  const int s3[] = {1, 1, 0, 0, 1, 1, 1, 1};
  ck_assert_int_eq(vsph_series_cfl_pick(e3, s3, 2, 4, 0.1), 3);
  const int s4[] = {0, 1, 1, 1, 1, 1, 1, 1};
  const double e4[] = {1.0, 9.0, 9.0, 9.0, 2.0, 2.0, 2.0, 2.0};
  ck_assert_int_eq(vsph_series_cfl_pick(e4, s4, 2, 4, 0.1), 3);
  const double e5[] = {1.0, 1.125, 1.25, 1.25}; /* exact in binary */
  ck_assert_int_eq(vsph_series_cfl_pick(e5, s1, 1, 4, 0.125), 1);
}
END_TEST

/* The cubic through the nearest four rows reproduces a cubic polynomial
 * on an uneven grid to rounding (1e-13 of its values, a few operations
 * on numbers of order 10), at the table's ends too; three rows fall back
 * to the line (exact on a line); outside the table, NaN. */
START_TEST(test_interp_cubic) {
  const double t[7] = {0.0, 0.3, 0.45, 1.2, 1.25, 2.0, 3.1};
  double y[7];
  for (int k = 0; k < 7; k++)
    y[k] = 1.0 - 2.0 * t[k] + 0.5 * t[k] * t[k] + 0.25 * t[k] * t[k] * t[k];
  for (double x = 0.0; x <= 3.1; x += 0.01) {
    const double want = 1.0 - 2.0 * x + 0.5 * x * x + 0.25 * x * x * x;
    ck_assert_double_eq_tol(vsph_series_interp_cubic(t, y, 7, x), want,
                            1e-13 * (1.0 + fabs(want)));
  }
  ck_assert(isnan(vsph_series_interp_cubic(t, y, 7, -1e-9)));
  ck_assert(isnan(vsph_series_interp_cubic(t, y, 7, 3.1 + 1e-9)));
  const double tl[3] = {0.0, 1.0, 3.0}, yl[3] = {1.0, 3.0, 7.0};
  ck_assert_double_eq_tol(vsph_series_interp_cubic(tl, yl, 3, 2.0), 5.0, 1e-15);
  /* local: the four rows nearest x, no other. On y = t^4 at t = 0..6, x =
   * 2.5 takes rows 1-4, whose cubic through (1,1), (2,16), (3,81), (4,256)
   * gives 2.5^4 - (2.5-1)(2.5-2)(2.5-3)(2.5-4) = 39.0625 - 0.5625 = 38.5
   * (a quartic's Lagrange remainder, worked by hand); a far row changed
   * moves nothing */
  double t4[7], y4[7];
  for (int k = 0; k < 7; k++) t4[k] = k, y4[k] = pow(k, 4.0);
  ck_assert_double_eq_tol(vsph_series_interp_cubic(t4, y4, 7, 2.5), 38.5,
                          1e-12);
  y4[6] = 1e6;
  ck_assert_double_eq_tol(vsph_series_interp_cubic(t4, y4, 7, 2.5), 38.5,
                          1e-12);
}
END_TEST

/* The order of E_h = E + C h^p from two successive differences, worked by
 * hand: C (h0^p - h1^p) and C (h1^p - h2^p) give p back, p = 1 and 2 at
 * the ratio 2 (the closed form, rounding: 1e-12) and p = 1.3 at the
 * unequal ratios 2.5 and 1.6 (the bisection's root, to 1e-9); differences
 * that grow by the ratio give -1; a zero difference or a ratio of 1, NaN. */
/* Where x lies between a and b in logarithm, worked by hand: 10 between 1
 * and 100 is halfway (ln 10 / ln 100), and so is 0.1 (the other side); a
 * is 0 and b is 1; 1000 is 1.5; a and b may be either way round; a
 * figure not positive and finite, or a = b, gives NaN. Tolerance: one
 * rounding of two logarithms and a quotient, a few 1e-16. */
START_TEST(test_log_between) {
  ck_assert_double_eq_tol(vsph_series_log_between(10.0, 1.0, 100.0), 0.5,
                          1e-15);
  ck_assert_double_eq_tol(vsph_series_log_between(0.1, 1.0, 100.0), 0.5, 1e-15);
  ck_assert_double_eq_tol(vsph_series_log_between(1000.0, 1.0, 100.0), 1.5,
                          1e-15);
  ck_assert_double_eq_tol(vsph_series_log_between(2.3 * 3.0, 2.3, 2.3 * 9.0),
                          0.5, 1e-15);
  ck_assert_double_eq(vsph_series_log_between(2.3, 2.3, 23.0), 0.0);
  ck_assert_double_eq_tol(vsph_series_log_between(23.0, 2.3, 23.0), 1.0, 1e-15);
  ck_assert_double_eq_tol(vsph_series_log_between(10.0, 100.0, 1.0), 0.5,
                          1e-15);
  const double bad[][3] = {{0.0, 1.0, 2.0},      {1.0, 0.0, 2.0},
                           {1.0, 1.0, -2.0},     {NAN, 1.0, 2.0},
                           {1.0, INFINITY, 2.0}, {1.0, 2.0, 2.0}};
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++)
    ck_assert_msg(
        isnan(vsph_series_log_between(bad[k][0], bad[k][1], bad[k][2])),
        "case %zu", k);
}
END_TEST

/* A history over a reference, worked by hand: the reference 10 + t on
 * rows at 0, 2, 4, 6 (read between them linearly, exact here), the
 * history 0.9 of it at t = 0.5 ... 5.5: in the window [1, 5] its rows 1.5
 * ... 4.5 all at 0.9 (peak 0.9; below an edge of 0.95, not below 0.9: the
 * rule is strict), its last time 5 (the window's end, sooner than 5.5),
 * the ratio there 0.9 (both interpolated). A NaN row makes the peak NaN;
 * a window holding no row is not seen; no rows or a reversed window are
 * refused. Tolerance: a few roundings of 0.9 (1e-15). */
START_TEST(test_ratio_history) {
  const double tr[4] = {0, 2, 4, 6}, yr[4] = {10, 12, 14, 16};
  double t[6], y[6];
  for (int i = 0; i < 6; i++) {
    t[i] = 0.5 + i;
    y[i] = 0.9 * (10.0 + t[i]);
  }
  struct vsph_series_ratio h;
  ck_assert_int_eq(
      vsph_series_ratio_history(t, y, 6, tr, yr, 4, 1.0, 5.0, 0.95, &h),
      VSPH_OK);
  ck_assert_int_eq(h.seen, 1);
  ck_assert_int_eq(h.below, 1);
  ck_assert_double_eq_tol(h.peak, 0.9, 1e-15);
  ck_assert_double_eq(h.t_last, 5.0);
  ck_assert_double_eq_tol(h.last, 0.9, 1e-15);
  ck_assert_int_eq(
      vsph_series_ratio_history(t, y, 6, tr, yr, 4, 1.0, 5.0, 0.9, &h),
      VSPH_OK);
  ck_assert_int_eq(h.below, 0);
  y[2] = NAN;
  ck_assert_int_eq(
      vsph_series_ratio_history(t, y, 6, tr, yr, 4, 1.0, 5.0, 0.95, &h),
      VSPH_OK);
  ck_assert(isnan(h.peak));
  ck_assert_int_eq(
      vsph_series_ratio_history(t, y, 6, tr, yr, 4, 5.6, 5.9, 0.95, &h),
      VSPH_OK);
  ck_assert_int_eq(h.seen, 0);
  ck_assert_int_eq(h.below, 1);
  vsph_test_silence();
  ck_assert_int_eq(
      vsph_series_ratio_history(t, y, 0, tr, yr, 4, 1.0, 5.0, 0.95, &h),
      VSPH_EINVAL);
  ck_assert_int_eq(
      vsph_series_ratio_history(t, y, 6, tr, yr, 4, 5.0, 1.0, 0.95, &h),
      VSPH_EINVAL);
}
END_TEST

START_TEST(test_order_from_two_differences) {
  const double C = 0.37;
  for (int p = 1; p <= 2; p++) {
    const double dc = C * (pow(0.1, p) - pow(0.05, p));
    const double df = C * (pow(0.05, p) - pow(0.025, p));
    ck_assert_double_eq_tol(vsph_series_order(dc, df, 2.0, 2.0), p, 1e-12);
  }
  const double p = 1.3, h0 = 0.1, h1 = 0.04, h2 = 0.025;
  const double dc = C * (pow(h0, p) - pow(h1, p)),
               df = C * (pow(h1, p) - pow(h2, p));
  ck_assert_double_eq_tol(vsph_series_order(dc, df, h0 / h1, h1 / h2), p, 1e-9);
  ck_assert_double_eq_tol(vsph_series_order(1.0, 2.0, 2.0, 2.0), -1.0, 1e-15);
  ck_assert(isnan(vsph_series_order(0.0, 1.0, 2.0, 2.0)));
  ck_assert(isnan(vsph_series_order(1.0, 0.5, 1.0, 2.0)));
}
END_TEST

/* A synthetic ladder E_h(t) = E(t) + C h^p t, E(t) = 2 + e^-t cos 3t, at
 * h = 0.1, 0.05, 0.025 on three unequal, jittered time grids (about 400
 * rows over [0, 2]): every E_h(0) = E(0) = 3, so the successive
 * differences of E_h/E_h(0) are C (h_k^p - h_{k+1}^p) t / 3, whose max
 * over [0, 2] is at t = 2 and whose RMS over it is 2/sqrt(3) times the
 * factor. Tolerances: the rungs are interpolated by the cubic, whose
 * error here is at most 2e-9 of E (measured), 7e-10 of E/E(0); the
 * largest difference sits at t = 2, a row every rung shares, where no
 * interpolation enters, so dmax holds to 1e-6 relative; stopped at 1.3,
 * the last row is the finest rung's own and the others' error, 7e-10,
 * stays within 1e-6 of 2 f (2e-9 at the smallest f, p = 2); the trapezoid
 * rule on t^2 errs by about dt^2/6 (1e-5 relative) on the RMS; the orders
 * then by less than 1e-3. The finest rung's remainder by Richardson is
 * C h_2^p T/3 exactly at the exact order. Then the finest rung stopped at
 * t = 1.3 (its later rows NaN): the span is its last row and the
 * differences end there. Last, unequal ratios (h = 0.1, 0.04, 0.025: 2.5
 * then 1.6) at p = 1.3: the order by the bisection, and the remainder at
 * the last ratio 1.6, again C h_2^p T/3 (1e-3 relative). */
enum { NMAX = 420 };

/* Three rungs E_h(t) = 2 + e^-t cos 3t + C h_k^p t on [0, T], rung k on
 * its own jittered grid of 380 + 17 k rows (both ends exact), into @p t,
 * @p E and @p rung. */
static void ladder(double t[3][NMAX], double E[3][NMAX], const double h[3],
                   double C, double p, double T,
                   struct vsph_series_rung rung[3]) {
  for (int k = 0; k < 3; k++) {
    const size_t n = 380 + 17 * (size_t)k;
    const double dt = T / (double)(n - 1);
    for (size_t i = 0; i < n; i++) {
      t[k][i] = i == 0 || i == n - 1
                    ? dt * (double)i
                    : dt * ((double)i + 0.3 * sin((double)(i + k)));
      E[k][i] =
          2.0 + exp(-t[k][i]) * cos(3.0 * t[k][i]) + C * pow(h[k], p) * t[k][i];
    }
    rung[k] = (struct vsph_series_rung){t[k], E[k], n, h[k]};
  }
}

START_TEST(test_selfconv_recovers_order_and_remainder) {
  static double t[3][NMAX], E[3][NMAX];
  const double C = 0.5, hs[3] = {0.1, 0.05, 0.025}, T = 2.0;
  for (int p = 1; p <= 2; p++) {
    struct vsph_series_rung rung[3];
    ladder(t, E, hs, C, p, T, rung);
    struct vsph_series_selfconv sc;
    ck_assert_int_eq(vsph_series_selfconv(rung, 3, &sc), VSPH_OK);
    ck_assert_int_eq(sc.partial, 0);
    ck_assert_double_eq_tol(sc.span, T, 1e-15);
    for (int k = 0; k < 2; k++) {
      const double f = C * (pow(hs[k], p) - pow(hs[k + 1], p)) / 3.0;
      ck_assert_double_eq_tol(sc.dmax[k], f * T, 1e-6 * f * T);
      ck_assert_double_eq_tol(sc.drms[k], f * T / sqrt(3.0), 1e-4 * f * T);
    }
    ck_assert_double_eq_tol(sc.order_max, p, 1e-3);
    ck_assert_double_eq_tol(sc.order_rms, p, 1e-3);
    const double rem = C * pow(hs[2], p) * T / 3.0;
    ck_assert_double_eq_tol(sc.remainder, rem, 1e-3 * rem);
    /* the finest rung stops at t = 1.3 */
    size_t stop = 0;
    while (t[2][stop + 1] <= 1.3) stop++;
    for (size_t i = stop + 1; i < rung[2].n; i++) E[2][i] = NAN;
    ck_assert_int_eq(vsph_series_selfconv(rung, 3, &sc), VSPH_OK);
    ck_assert_int_eq(sc.partial, 1);
    ck_assert_double_eq(sc.span, t[2][stop]);
    for (int k = 0; k < 2; k++) {
      const double f = C * (pow(hs[k], p) - pow(hs[k + 1], p)) / 3.0;
      ck_assert_double_eq_tol(sc.dmax[k], f * sc.span, 1e-6 * f * T);
    }
    ck_assert_double_eq_tol(sc.order_max, p, 1e-3);
  }
  /* unequal ratios, p = 1.3 */
  {
    const double hu[3] = {0.1, 0.04, 0.025}, p = 1.3;
    struct vsph_series_rung rung[3];
    ladder(t, E, hu, C, p, T, rung);
    struct vsph_series_selfconv sc;
    ck_assert_int_eq(vsph_series_selfconv(rung, 3, &sc), VSPH_OK);
    ck_assert_double_eq_tol(sc.order_max, p, 1e-3);
    ck_assert_double_eq_tol(sc.order_rms, p, 1e-3);
    /* Richardson at the last ratio 1.6: d_12 / (1.6^p - 1) = C h_2^p T/3 */
    const double rem = C * pow(hu[2], p) * T / 3.0;
    ck_assert_double_eq_tol(sc.remainder, rem, 1e-3 * rem);
  }
  /* refused: one rung, a spacing that does not fall, E(0) = 0 */
  vsph_test_silence();
  struct vsph_series_rung r2[2] = {{t[0], E[0], 10, 0.1},
                                   {t[1], E[1], 10, 0.1}};
  struct vsph_series_selfconv sc;
  ck_assert_int_eq(vsph_series_selfconv(r2, 1, &sc), VSPH_EINVAL);
  ck_assert_int_eq(vsph_series_selfconv(r2, 2, &sc), VSPH_EINVAL);
  const double z[2] = {0.0, 1.0};
  r2[1] = (struct vsph_series_rung){t[1], z, 2, 0.05};
  ck_assert_int_eq(vsph_series_selfconv(r2, 2, &sc), VSPH_EINVAL);
}
END_TEST

Suite *vsph_series_suite(void) {
  Suite *s = suite_create("series");
  TCase *tc = tcase_create("measures");
  tcase_add_test(tc, test_interp_linear_exact_nan_outside);
  tcase_add_test(tc, test_slope_where);
  tcase_add_test(tc, test_extrapolate);
  tcase_add_test(tc, test_decay_error);
  tcase_add_test(tc, test_onset_first_point_past_gap);
  tcase_add_test(tc, test_integral_loss);
  tcase_add_test(tc, test_first_reach);
  tcase_add_test(tc, test_plateau_spread_and_median);
  tcase_add_test(tc, test_failure_time_first_reach_or_stop);
  tcase_add_test(tc, test_tail_mean);
  tcase_add_test(tc, test_cfl_rule);
  tcase_add_test(tc, test_interp_cubic);
  tcase_add_test(tc, test_order_from_two_differences);
  tcase_add_test(tc, test_log_between);
  tcase_add_test(tc, test_ratio_history);
  tcase_add_test(tc, test_selfconv_recovers_order_and_remainder);
  suite_add_tcase(s, tc);
  return s;
}
