/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_GRADE_H
#define VSPH_REPORTS_GRADE_H

/** @file grade.h
 *  @brief The rules that turn a claim's measured figures into its grade,
 *  each threshold a named constant with its origin (the paper's stated
 *  precision, a run's own swing, or a documented choice of ours, said as
 *  such). The claims of reports/report_*.c call these instead of writing
 *  numbers inline; tests/check_grade.c holds every rule at, just below and
 *  just above its threshold, on values worked by hand. Within reports/
 *  and the tests only. */

/** What a rule says of a claim's measure. */
enum vsph_grade {
  VSPH_GRADE_AGREES = 0, /*!< the measure meets the claim */
  VSPH_GRADE_PARTLY,     /*!< one of two measures meets it */
  VSPH_GRADE_DIFFERS,    /*!< measured, and it does not */
  VSPH_GRADE_UNMEASURED  /*!< not measured (NaN, or a span cut short) */
};

/** An observed order "is" the integer n when it rounds to n: |p - n| is
 *  below this. Origin: a paper's "converges linearly" names an integer
 *  order and no precision, so the nearest integer decides (an observed
 *  0.6 is first order, 0.4 is not). */
#define VSPH_GRADE_ORDER_HALFWIDTH 0.5

/** @brief 1 when the observed order @p p rounds to @p n
 *  (|p - n| < VSPH_GRADE_ORDER_HALFWIDTH), 0 when not, -1 for NaN. */
int vsph_grade_order_is(double p, int n);

/** @brief A ladder's self-convergence against a claimed integer order
 *  @p n, by its two measures (the largest difference and its RMS over
 *  time, vsph_series_selfconv): both round to n, AGREES; one, PARTLY;
 *  neither, DIFFERS; either NaN, or @p partial (a rung stopped, so the
 *  differences do not cover the run), UNMEASURED. */
enum vsph_grade vsph_grade_orders(double p_max, double p_rms, int n,
                                  int partial);

/** @brief A ladder's self-convergence against a claim that it
 *  "converges", at no stated order: both measures' orders round to 1 or
 *  more (p > 1 - VSPH_GRADE_ORDER_HALFWIDTH, the boundary excluded as in
 *  vsph_grade_order_is), AGREES; one, PARTLY; neither, DIFFERS; NaN or
 *  @p partial, UNMEASURED. */
enum vsph_grade vsph_grade_converges(double p_max, double p_rms, int partial);

/** @brief Half a unit of the last digit of a figure stated to @p digits
 *  significant digits: the precision a paper implies by writing it so
 *  ("about 80 %", 0.8 to one digit: 0.05; "0.55 %", 0.0055 to two:
 *  0.00005). 0 for a zero figure or digits < 1. */
double vsph_grade_halfunit(double stated, int digits);

/** An identity that holds "exactly at the discrete level" holds to
 *  rounding: a relative error below this. Origin: measured, PVWF's
 *  dissipation identity on 25 600 particles leaves 2e-15 (section 4 of
 *  the report; random rounding over n terms grows like sqrt(n) u, 2e-14
 *  here); 1e-12 leaves a factor of 50 over that for other sets and
 *  cancellations. */
#define VSPH_GRADE_ROUNDING 1e-12

/** @brief 1 when |@p value - @p stated| <= @p halfwidth (the bound is
 *  inclusive), 0 when not or when either is NaN. */
int vsph_grade_within(double value, double stated, double halfwidth);

/** How far apart a measure must be to call one case "failing" beside
 *  others that "agree": a factor of sqrt(10), half a decade on the
 *  logarithmic axes the papers' figures are read on. Origin: a documented
 *  choice of ours (the papers say "quickly diverges", "much higher", with
 *  no figure); it is the grade's only separation factor. */
#define VSPH_GRADE_APART 3.1622776601683795

/** @brief 1 when @p bad >= VSPH_GRADE_APART * @p good and @p bad > 0
 *  (both errors, non-negative: two zeros are not apart), 0 when not or
 *  when either is NaN. */
int vsph_grade_apart(double bad, double good);

/** @brief 1 when @p a exceeds @p b by more than @p noise (the measure's
 *  own swing: a difference inside it is no difference), 0 when not or
 *  when any is NaN. "Larger" in a paper's sense, with no factor asked. */
int vsph_grade_larger(double a, double b, double noise);

/** @brief Whether a run's stop holds when only the time step changes:
 *  of @p n runs of one set-up at different steps (@p stopped[k] 1: it
 *  stopped as unstable), 1 when all stopped or none did, 0 when some did
 *  and some did not (the stop moves with the step: a marginal run, which
 *  no verdict may rest on), -1 for n = 0. */
int vsph_grade_stop_holds(const int *stopped, int n);

#endif /* VSPH_REPORTS_GRADE_H */
