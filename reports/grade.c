/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The grading rules of the claims (grade.h). */
#include "grade.h"

#include <math.h>

int vsph_grade_order_is(double p, int n) {
  if (isnan(p)) return -1;
  return fabs(p - (double)n) < VSPH_GRADE_ORDER_HALFWIDTH;
}

enum vsph_grade vsph_grade_orders(double p_max, double p_rms, int n,
                                  int partial) {
  const int a = vsph_grade_order_is(p_max, n),
            b = vsph_grade_order_is(p_rms, n);
  if (partial || a < 0 || b < 0) return VSPH_GRADE_UNMEASURED;
  return a && b   ? VSPH_GRADE_AGREES
         : a || b ? VSPH_GRADE_PARTLY
                  : VSPH_GRADE_DIFFERS;
}

enum vsph_grade vsph_grade_converges(double p_max, double p_rms, int partial) {
  if (partial || isnan(p_max) || isnan(p_rms)) return VSPH_GRADE_UNMEASURED;
  const double lo = 1.0 - VSPH_GRADE_ORDER_HALFWIDTH;
  const int a = p_max > lo, b = p_rms > lo;
  return a && b   ? VSPH_GRADE_AGREES
         : a || b ? VSPH_GRADE_PARTLY
                  : VSPH_GRADE_DIFFERS;
}

double vsph_grade_halfunit(double stated, int digits) {
  if (!(stated != 0.0) || !isfinite(stated) || digits < 1) return 0.0;
  /* the place of the leading digit, then of the last stated one */
  double lead = floor(log10(fabs(stated)));
  if (pow(10.0, lead + 1.0) <= fabs(stated)) lead += 1.0; /* log10 rounded */
  if (pow(10.0, lead) > fabs(stated)) lead -= 1.0;        /* down or up */
  return 0.5 * pow(10.0, lead - (double)(digits - 1));
}

int vsph_grade_within(double value, double stated, double halfwidth) {
  return fabs(value - stated) <= halfwidth; /* NaN compares false */
}

int vsph_grade_apart(double bad, double good) {
  return bad > 0.0 && bad >= VSPH_GRADE_APART * good;
}

int vsph_grade_larger(double a, double b, double noise) {
  return a - b > noise;
}

int vsph_grade_stop_holds(const int *stopped, int n) {
  if (n <= 0) return -1;
  int some = 0, all = 1;
  for (int k = 0; k < n; k++) {
    some |= stopped[k] != 0;
    all &= stopped[k] != 0;
  }
  return all || !some;
}
