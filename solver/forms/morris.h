/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* pair.h first, outside the guard: pair.h includes this file after the
 * pair's geometry (its contact SPH uses these terms), so a program that
 * includes this header alone gets the whole of pair.h and this file once. */
#include "../pair.h"

#ifndef VSPH_SOLVER_FORMS_MORRIS_H
#define VSPH_SOLVER_FORMS_MORRIS_H

/** @file morris.h
 *  @brief Morris, Fox & Zhu's forms (docs/theory.md sections 3 and 8): MEAF
 *  (Basa et al.'s model E) and the original regularised one, MEAF-eta. The
 *  pair terms; the descriptors are in morris.c. Included by solver/pair.h,
 *  after the pair's geometry. */

/** @brief MEAF, Morris, Fox & Zhu (1997), Eq. (4.30), THEORY 3:
 *  (div V)_i = 2 mu sum_j V_j W'/s (u_i - u_j).
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param du u_j - u_i;
 *  @param two_mu 2 mu (Pa s). @return the pair's share -2 mu V_j F du and
 *  its dissipation density mu V_j F |du|^2 (THEORY 4). */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc vsph_pair_meaf(
    const struct vsph_pair *pr, int dim, double two_mu,
    const struct vsph_pair_vec du) {
  struct vsph_pair_visc r;
  const double c = -two_mu * pr->VF;
  double du2 = 0.0;
  for (int k = 0; k < dim; k++) {
    r.f[k] = c * du.v[k];
    du2 += du.v[k] * du.v[k];
  }
  r.dens = 0.5 * two_mu * pr->VF * du2;
  return r;
}

/** @brief Morris, Fox & Zhu's (1997) original, regularised form (Basa
 *  et al.'s model E with r^2 + eta^2 in the denominator, as Morris et al.
 *  print it; docs/theory.md, section 8): with uniform mu,
 *  (div V)_i = 2 mu sum_j V_j (r_ij.grad_i W_ij)/(s^2 + eta^2) (u_i - u_j)
 *            = 2 mu sum_j V_j F s^2/(s^2 + eta^2) (u_i - u_j);
 *  eta = 0 gives MEAF.
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param du u_j - u_i; @param two_mu 2 mu (Pa s);
 *  @param eta2 eta^2 (m^2). @return the pair's share and its dissipation
 *  density mu V_j F s^2/(s^2 + eta^2) |du|^2 (THEORY 4). */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc vsph_pair_meafeta(
    const struct vsph_pair *pr, int dim, double two_mu, double eta2,
    const struct vsph_pair_vec du) {
  struct vsph_pair_visc r;
  const double c = -two_mu * pr->VF * pr->s2 / (pr->s2 + eta2);
  double du2 = 0.0;
  for (int k = 0; k < dim; k++) {
    r.f[k] = c * du.v[k];
    du2 += du.v[k] * du.v[k];
  }
  r.dens = -0.5 * c * du2;
  return r;
}

/** @brief MEAF's pair share with the corrected gradient @p g in place of
 *  grad_i W = -F x (Basa et al.'s corrections, docs/theory.md section 10):
 *  2 mu V_j (x.g)/s^2 du into @p f, @p vj = V_j, @p du = u_j - u_i; with
 *  g = -F x it is vsph_pair_meaf's share. */
VSPH_CONSTS_SPECIALISE void vsph_pair_meaf_g(const struct vsph_pair *pr,
                                             int dim, double two_mu, double vj,
                                             const double du[3],
                                             const double g[3], double f[3]) {
  double xg = 0.0;
  for (int k = 0; k < dim; k++) xg += pr->x[k] * g[k];
  const double c = two_mu * vj * xg / pr->s2;
  for (int k = 0; k < dim; k++) f[k] = c * du[k];
}

#endif /* VSPH_SOLVER_FORMS_MORRIS_H */
