/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* pair.h first, outside the guard: pair.h includes this file after the
 * pair's geometry (its contact SPH uses these terms), so a program that
 * includes this header alone gets the whole of pair.h and this file once. */
#include "../pair.h"

#ifndef VSPH_SOLVER_FORMS_BROOKSHAW_H
#define VSPH_SOLVER_FORMS_BROOKSHAW_H

/** @file brookshaw.h
 *  @brief Brookshaw's form and its kin (docs/theory.md sections 3 and 8): MGF
 *  (Monaghan & Gingold), Violeau & Issa's (Basa et al.'s model C) and Cleary's
 *  (model D), one pair term with their constants K and eta. The pair terms;
 *  the descriptors are in brookshaw.c. Included by solver/pair.h, after the
 *  pair's geometry. */

/** @brief MGF, Monaghan & Gingold, Eq. (4.20), THEORY 3, and its
 *  Brookshaw-type kin (docs/theory.md, section 8):
 *  (div V)_i = K mu sum_j V_j (u_j - u_i).(r_j - r_i)/(s^2 + eta^2)
 *  grad_i W_ij. MGF: K = 2(d+2), eta = 0; Violeau & Issa (Basa's model C):
 *  K = 2(d+2), eta = 0.1 h; Cleary (model D): K = 2 xi, eta = 0.1 h.
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param Kmu K mu (Pa s); @param eta2 eta^2 (m^2; 0 for MGF, which then
 *  adds an exact zero). @param dux (u_j - u_i).x (m^2/s).
 *  @return the pair's share -K mu V_j F (du.x)/(s^2 + eta^2) x and its
 *  dissipation density (K mu/2) V_j F (du.x)^2/(s^2 + eta^2) (THEORY 4),
 *  so that sum_i V_i of the sums is sum_i V_i u_i.(div V)_i. The 2-D
 *  sweep with the Gaussian computes this share, with the continuity and
 *  pressure terms, in AVX-512 lanes too (solver/sweep_x86.c): change both
 *  (test_sweep_scatter_simd holds them within rounding). */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc vsph_pair_mgf(
    const struct vsph_pair *pr, int dim, double Kmu, double eta2, double dux) {
  struct vsph_pair_visc r;
  const double c = -Kmu * pr->VF * dux / (pr->s2 + eta2);
  for (int k = 0; k < dim; k++) r.f[k] = c * pr->x[k];
  r.dens = -0.5 * c * dux; /* (K mu/2) V_j F (du.x)^2/s^2, one division */
  return r;
}

/** @brief The Brookshaw forms' pair share with the corrected gradient
 *  @p g in place of grad_i W = -F x (Basa et al.'s corrections,
 *  docs/theory.md section 10): K mu V_j (du.x)/(s^2 + eta^2) g into @p f,
 *  @p vj = V_j; with g = -F x it is vsph_pair_mgf's share. */
VSPH_CONSTS_SPECIALISE void vsph_pair_mgf_g(const struct vsph_pair *pr, int dim,
                                            double Kmu, double eta2, double vj,
                                            double dux, const double g[3],
                                            double f[3]) {
  const double c = Kmu * vj * dux / (pr->s2 + eta2);
  for (int k = 0; k < dim; k++) f[k] = c * g[k];
}

#endif /* VSPH_SOLVER_FORMS_BROOKSHAW_H */
