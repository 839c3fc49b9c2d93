/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* pair.h first, outside the guard: pair.h includes this file after the
 * pair's geometry (its contact SPH uses these terms), so a program that
 * includes this header alone gets the whole of pair.h and this file once. */
#include "../pair.h"

#ifndef VSPH_SOLVER_FORMS_STRESS_H
#define VSPH_SOLVER_FORMS_STRESS_H

/** @file stress.h
 *  @brief The stress forms (docs/theory.md sections 3 and 8): PVWF (the
 *  principle of virtual work, renormalised) and the two-pass strain-rate form
 *  (Basa et al.'s model B, Vukcevic et al.'s scheme): a first pass of velocity
 *  gradients, then the stress's divergence. The pair terms; the descriptors
 *  are in stress.c. Included by solver/pair.h, after the pair's geometry. */

/** @brief PVWF pass 1, Eqs. (4.18)-(4.19), THEORY 3: the pair's terms of
 *  B = sum_j V_j grad_i W_ij (x) x = sum_j V_j (-F) x (x) x, whose inverse
 *  is L_i, and of Mg = sum_j V_j (-F) du (x) x, so that the renormalised
 *  gradient is (grad u)_i = Mg L_i (row-major d x d, entry [a*dim+b]).
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param du u_j - u_i. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_grad vsph_pair_pvwf_grad(
    const struct vsph_pair *pr, int dim, const struct vsph_pair_vec du) {
  struct vsph_pair_grad r;
  const double c = -pr->VF;
  for (int a = 0; a < dim; a++)
    for (int b = 0; b < dim; b++) {
      r.B[a * dim + b] = c * pr->x[a] * pr->x[b];
      r.M[a * dim + b] = c * du.v[a] * pr->x[b];
    }
  return r;
}

/** @brief PVWF pass 2, Eq. (4.19), THEORY 3:
 *  (div V)_i = sum_j V_j (T_j L_j + T_i L_i) grad_i W_ij. @return the
 *  pair's -V_j F (A_j + A_i) x with A = T L from pass 1.
 *  @param pr the pair (x = r_j - r_i, s2, F, VF); @param dim the dimension.
 *  @param Ai A_i (row-major); @param A A[a*dim+b][j] of every particle. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_vec vsph_pair_pvwf_force(
    const struct vsph_pair *pr, int dim, const double Ai[9],
    double *const A[9]) {
  struct vsph_pair_vec f;
  const size_t j = pr->j;
  for (int a = 0; a < dim; a++) {
    double y = 0.0;
    for (int b = 0; b < dim; b++)
      y += (A[a * dim + b][j] + Ai[a * dim + b]) * pr->x[b];
    f.v[a] = -(pr->VF * y);
  }
  return f;
}

#endif /* VSPH_SOLVER_FORMS_STRESS_H */
