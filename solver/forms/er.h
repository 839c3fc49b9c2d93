/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* pair.h first, outside the guard: pair.h includes this file after the
 * pair's geometry (its contact SPH uses these terms), so a program that
 * includes this header alone gets the whole of pair.h and this file once. */
#include "../pair.h"

#ifndef VSPH_SOLVER_FORMS_ER_H
#define VSPH_SOLVER_FORMS_ER_H

/** @file er.h
 *  @brief Espanol & Revenga's form (docs/theory.md section 8), with its bulk
 *  viscosity zeta; in 2-D with zeta = 0 it is MEAF. The pair terms; the
 *  descriptors are in er.c. Included by solver/pair.h, after the pair's
 *  geometry. */

/** @brief Espanol & Revenga (2003), docs/theory.md section 8: with
 *  F_ER = -W'/s and the number density 1/V,
 *  (div V)_i = sum_j V_j F (a du + b (du.x) x / s^2), where
 *  a = zeta - mu (d+2)/d and b = -(d+2)(zeta + mu (d-2)/d) give
 *  mu lap u + (zeta + mu (1 - 2/d)) grad div u in the continuum (zeta the
 *  bulk viscosity). In 2-D with zeta = 0, b = 0 and a = -2 mu: MEAF.
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param a,b as above (Pa s); @param du u_j - u_i; @param dux du.x.
 *  @return the pair's share and its dissipation density -f.du/2
 *  (THEORY 4), so that sum_i V_i of the sums is sum_i V_i u_i.(div V)_i. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc vsph_pair_er(
    const struct vsph_pair *pr, int dim, double a, double b,
    const struct vsph_pair_vec du, double dux) {
  struct vsph_pair_visc r;
  const double c1 = a * pr->VF, c2 = b * pr->VF * dux / pr->s2;
  double du2 = 0.0;
  for (int k = 0; k < dim; k++) {
    r.f[k] = c1 * du.v[k] + c2 * pr->x[k];
    du2 += du.v[k] * du.v[k];
  }
  r.dens = -0.5 * (c1 * du2 + c2 * dux);
  return r;
}

/** @brief Espanol & Revenga's pair share with the corrected gradient @p g
 *  in place of grad_i W = -F x (Basa et al.'s corrections, docs/theory.md
 *  section 10): -V_j (x.g)/s^2 (a du + b (du.x) x/s^2) into @p f,
 *  @p vj = V_j, @p du = u_j - u_i, @p dux = du.x; with g = -F x it is
 *  vsph_pair_er's share. */
VSPH_CONSTS_SPECIALISE void vsph_pair_er_g(const struct vsph_pair *pr, int dim,
                                           double a, double b, double vj,
                                           const double du[3], double dux,
                                           const double g[3], double f[3]) {
  double xg = 0.0;
  for (int k = 0; k < dim; k++) xg += pr->x[k] * g[k];
  const double c = -vj * xg / pr->s2, cb = b * dux / pr->s2;
  for (int k = 0; k < dim; k++) f[k] = c * (a * du[k] + cb * pr->x[k]);
}

#endif /* VSPH_SOLVER_FORMS_ER_H */
