/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Quintic spline, Morris, Fox & Zhu (1997), J. Comput. Phys. 136, 214,
 * Eq. (27); THEORY.md section 1. */
#include <math.h>

#include "../common/consts.h"
#include "kernel.h"

static double pow4p(double t) { return t > 0.0 ? t * t * t * t : 0.0; }

static double f_quintic(double q) { return vsph_kernel_f_quintic(q); }

static double df_quintic(double q) {
  if (q >= 3.0) return 0.0;
  return -5.0 * (pow4p(3.0 - q) - 6.0 * pow4p(2.0 - q) + 15.0 * pow4p(1.0 - q));
}

static double pow3p(double t) { return t > 0.0 ? t * t * t : 0.0; }

static double d2f_quintic(double q) {
  if (q >= 3.0) return 0.0;
  return 20.0 * (pow3p(3.0 - q) - 6.0 * pow3p(2.0 - q) + 15.0 * pow3p(1.0 - q));
}

const struct vsph_kernel_type vsph_quintic_type = {
    .name = "quintic",
    .kappa = 3.0,
    .sigma = {1.0 / 120.0, 7.0 / (478.0 * VSPH_PI), 1.0 / (120.0 * VSPH_PI)},
    .f = {f_quintic, f_quintic, f_quintic},
    .df = {df_quintic, df_quintic, df_quintic},
    .d2f = {d2f_quintic, d2f_quintic, d2f_quintic},
    .dfq = {vsph_kernel_dfq_quintic, vsph_kernel_dfq_quintic,
            vsph_kernel_dfq_quintic},
    .dfq_id = {VSPH_KERNEL_DFQ_QUINTIC, VSPH_KERNEL_DFQ_QUINTIC,
               VSPH_KERNEL_DFQ_QUINTIC},
    .reference = "quintic spline (Morris, Fox & Zhu 1997)",
};
