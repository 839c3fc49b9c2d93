/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Renormalised Gaussian truncated at 3h: the kernel of Colagrossi et al.,
 * PRE 84, 026705 (2011), Sec. VI; THEORY.md section 1. */
#include <math.h>

#include "../common/consts.h"
#include "kernel.h"

/* e^{-9}: the value of e^{-q^2} at the support radius q = 3 (a macro: it
 * enters the static initialiser below), and erf(3). */
#define E9 1.2340980408667954950e-4
#define ERF3 0.99997790950300141456

static double f_gauss(double q) { return q < 3.0 ? exp(-q * q) - E9 : 0.0; }
static double df_gauss(double q) {
  return q < 3.0 ? -2.0 * q * exp(-q * q) : 0.0;
}

static double d2f_gauss(double q) {
  return q < 3.0 ? (4.0 * q * q - 2.0) * exp(-q * q) : 0.0;
}

/* sigma_d = 1 / int_{|q|<3} (e^{-q^2} - e^{-9}) d^d q, in closed form:
 *   d=1: sqrt(pi) erf(3) - 6 e^{-9}
 *   d=2: pi (1 - 10 e^{-9})            (THEORY.md)
 *   d=3: pi^{3/2} erf(3) - 42 pi e^{-9}
 * Verified by quadrature in tests. */
const struct vsph_kernel_type vsph_gaussian_type = {
    .name = "gaussian",
    .kappa = 3.0,
    .sigma = {1.0 / (VSPH_SQRTPI * ERF3 - 6.0 * E9),
              1.0 / (VSPH_PI * (1.0 - 10.0 * E9)),
              1.0 / (VSPH_PI * VSPH_SQRTPI * ERF3 - 42.0 * VSPH_PI * E9)},
    .f = {f_gauss, f_gauss, f_gauss},
    .df = {df_gauss, df_gauss, df_gauss},
    .d2f = {d2f_gauss, d2f_gauss, d2f_gauss},
    .dfq = {vsph_kernel_dfq_gaussian, vsph_kernel_dfq_gaussian,
            vsph_kernel_dfq_gaussian},
    .dfq_id = {VSPH_KERNEL_DFQ_GAUSSIAN, VSPH_KERNEL_DFQ_GAUSSIAN,
               VSPH_KERNEL_DFQ_GAUSSIAN},
    .reference = "renormalised Gaussian, kappa=3 (Colagrossi et al. 2011)",
};
