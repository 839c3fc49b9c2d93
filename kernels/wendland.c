/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Wendland C2 and C4 kernels, support 2h: Wendland (1995), Adv. Comput.
 * Math. 4, 389; normalisations as in Dehnen & Aly (2012), MNRAS 425, 1068,
 * Table 1 (rescaled to support 2h); THEORY.md section 1. The 1-D variants
 * are the lower-order Wendland functions for d = 1. */
#include <math.h>

#include "../common/consts.h"
#include "kernel.h"

/* C2: (1 - q/2)^4 (2q + 1) in 2-D/3-D, (1 - q/2)^3 (1.5q + 1) in 1-D. */
static double f_c2(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t2 = t * t;
  return t2 * t2 * (2.0 * q + 1.0);
}
static double df_c2(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return -5.0 * q * t * t * t; /* d/dq of t^4 (2q+1) */
}
static double f_c2_1d(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return t * t * t * (1.5 * q + 1.0);
}
static double df_c2_1d(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return -3.0 * q * t * t; /* d/dq of t^3 (1.5q+1) */
}

/* C4: (1 - q/2)^6 (35q^2/12 + 3q + 1) in 2-D/3-D,
 *     (1 - q/2)^5 (2q^2 + 2.5q + 1) in 1-D. */
static double f_c4(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t3 = t * t * t;
  return t3 * t3 * (35.0 / 12.0 * q * q + 3.0 * q + 1.0);
}
static double df_c4(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t5 = t * t * t * t * t;
  /* -3 t^5 (35q^2/12 + 3q + 1) + t^6 (35q/6 + 3) = -(7/3) q t^5 (5q + 2) */
  return -7.0 / 3.0 * q * t5 * (5.0 * q + 2.0);
}
static double f_c4_1d(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t5 = t * t * t * t * t;
  return t5 * (2.0 * q * q + 2.5 * q + 1.0);
}
static double df_c4_1d(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t4 = t * t * t * t;
  /* -2.5 t^4 (2q^2 + 2.5q + 1) + t^5 (4q + 2.5) = -3.5 q t^4 (2q + 1) */
  return -3.5 * q * t4 * (2.0 * q + 1.0);
}

/* Second derivatives, by differentiating the df above once more. */
static double d2f_c2(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return 5.0 * t * t * (2.0 * q - 1.0);
}
static double d2f_c2_1d(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return 3.0 * t * (1.5 * q - 1.0);
}
static double d2f_c4(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q, t4 = t * t * t * t;
  return 7.0 / 3.0 * t4 * (17.5 * q * q - 4.0 * q - 2.0);
}
static double d2f_c4_1d(double q) {
  if (q >= 2.0) return 0.0;
  const double t = 1.0 - 0.5 * q;
  return 3.5 * t * t * t * (6.0 * q * q - 1.5 * q - 1.0);
}

const struct vsph_kernel_type vsph_wendland_c2_type = {
    .name = "wendland2",
    .kappa = 2.0,
    .sigma = {5.0 / 8.0, 7.0 / (4.0 * VSPH_PI), 21.0 / (16.0 * VSPH_PI)},
    .f = {f_c2_1d, f_c2, f_c2},
    .df = {df_c2_1d, df_c2, df_c2},
    .d2f = {d2f_c2_1d, d2f_c2, d2f_c2},
    .dfq = {vsph_kernel_dfq_c2_1d, vsph_kernel_dfq_c2, vsph_kernel_dfq_c2},
    .dfq_id = {VSPH_KERNEL_DFQ_C2_1D, VSPH_KERNEL_DFQ_C2, VSPH_KERNEL_DFQ_C2},
    .reference = "Wendland C2 (Wendland 1995), support 2h",
};

const struct vsph_kernel_type vsph_wendland_c4_type = {
    .name = "wendland4",
    .kappa = 2.0,
    .sigma = {3.0 / 4.0, 9.0 / (4.0 * VSPH_PI), 495.0 / (256.0 * VSPH_PI)},
    .f = {f_c4_1d, f_c4, f_c4},
    .df = {df_c4_1d, df_c4, df_c4},
    .d2f = {d2f_c4_1d, d2f_c4, d2f_c4},
    .dfq = {vsph_kernel_dfq_c4_1d, vsph_kernel_dfq_c4, vsph_kernel_dfq_c4},
    .dfq_id = {VSPH_KERNEL_DFQ_C4_1D, VSPH_KERNEL_DFQ_C4, VSPH_KERNEL_DFQ_C4},
    .reference = "Wendland C4 (Wendland 1995), support 2h",
};
