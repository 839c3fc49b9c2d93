/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Cubic B-spline, Monaghan (1992), Annu. Rev. Astron. Astrophys. 30, 543,
 * Eq. (2.6); THEORY.md section 1. */
#include <math.h>

#include "../common/consts.h"
#include "kernel.h"

static double f_cubic(double q) { return vsph_kernel_f_cubic(q); }

static double df_cubic(double q) {
  if (q < 1.0) return -3.0 * q + 2.25 * q * q;
  if (q < 2.0) {
    const double t = 2.0 - q;
    return -0.75 * t * t;
  }
  return 0.0;
}

static double d2f_cubic(double q) {
  if (q < 1.0) return -3.0 + 4.5 * q;
  if (q < 2.0) return 1.5 * (2.0 - q);
  return 0.0;
}

const struct vsph_kernel_type vsph_cubic_type = {
    .name = "cubic",
    .kappa = 2.0,
    .sigma = {2.0 / 3.0, 10.0 / (7.0 * VSPH_PI), 1.0 / VSPH_PI},
    .f = {f_cubic, f_cubic, f_cubic},
    .df = {df_cubic, df_cubic, df_cubic},
    .d2f = {d2f_cubic, d2f_cubic, d2f_cubic},
    .dfq = {vsph_kernel_dfq_cubic, vsph_kernel_dfq_cubic,
            vsph_kernel_dfq_cubic},
    .dfq_id = {VSPH_KERNEL_DFQ_CUBIC, VSPH_KERNEL_DFQ_CUBIC,
               VSPH_KERNEL_DFQ_CUBIC},
    .reference = "cubic B-spline (Monaghan 1992)",
};
