/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* pair.h first, outside the guard: pair.h includes this file after the
 * pair's geometry (its contact SPH uses these terms), so a program that
 * includes this header alone gets the whole of pair.h and this file once. */
#include "../pair.h"

#ifndef VSPH_SOLVER_FORMS_TAKEDA_H
#define VSPH_SOLVER_FORMS_TAKEDA_H

/** @file takeda.h
 *  @brief Takeda-type direct second derivatives (Basa et al.'s model A,
 *  docs/theory.md section 8), plain and with the Shepard correction (A[0]):
 *  per-particle sums of a first pass that make the whole force. The pair
 *  terms; the descriptors are in takeda.c. Included by solver/pair.h, after
 *  the pair's geometry. */

/** Per-particle sums of Takeda-type direct second derivatives (Basa et
 *  al.'s model A, docs/theory.md section 8), un-differenced as Basa's
 *  eq. (27): \<d_ab f\>_i = sum_j V_j f_j d_ab W_ij, the sum taking j = i
 *  too. With d_a W_ij = -F x_a and d_ab W_ij = x_a x_b/s^2 (W'' - F) +
 *  delta_ab F (eq. 28; derivatives at r_i), for f = 1 and for each
 *  velocity component, so that the Shepard-corrected derivatives of
 *  eq. (23) can be finished from them. Row-major d x d blocks. */
struct vsph_pair_takeda {
  double s0;       /*!< sum V W */
  double s1[3];    /*!< sum V d_a W */
  double s2[9];    /*!< sum V d_ab W */
  double f0[3];    /*!< [c]: sum V u^c W */
  double f1[3][3]; /*!< [c][a]: sum V u^c d_a W */
  double f2[3][9]; /*!< [c][ab]: sum V u^c d_ab W */
};

/** @brief Add neighbour j (pair @p pr, volume @p vj, velocity @p uj,
 *  W_ij = @p w and W''(s) = @p d2w) to the sums @p acc. */
VSPH_CONSTS_SPECIALISE void vsph_pair_takeda_add(struct vsph_pair_takeda *acc,
                                                 const struct vsph_pair *pr,
                                                 int dim, double vj,
                                                 const double uj[3], double w,
                                                 double d2w) {
  const double e = (d2w - pr->F) / pr->s2;
  double d1[3], d2[9];
  for (int a = 0; a < dim; a++) {
    d1[a] = -vj * pr->F * pr->x[a];
    for (int b = 0; b < dim; b++)
      d2[a * dim + b] = vj * (e * pr->x[a] * pr->x[b] + (a == b ? pr->F : 0.0));
  }
  acc->s0 += vj * w;
  for (int a = 0; a < dim; a++) acc->s1[a] += d1[a];
  for (int e2 = 0; e2 < dim * dim; e2++) acc->s2[e2] += d2[e2];
  for (int c = 0; c < dim; c++) {
    acc->f0[c] += vj * w * uj[c];
    for (int a = 0; a < dim; a++) acc->f1[c][a] += d1[a] * uj[c];
    for (int e2 = 0; e2 < dim * dim; e2++) acc->f2[c][e2] += d2[e2] * uj[c];
  }
}

/** @brief Add particle i's own term (j = i): volume @p vi, velocity
 *  @p ui, W(0) = @p w0, W''(0) = @p d2w0 (d_ab W(0) = delta_ab W''(0)). */
static inline void vsph_pair_takeda_self(struct vsph_pair_takeda *acc, int dim,
                                         double vi, const double ui[3],
                                         double w0, double d2w0) {
  acc->s0 += vi * w0;
  for (int a = 0; a < dim; a++) acc->s2[a * dim + a] += vi * d2w0;
  for (int c = 0; c < dim; c++) {
    acc->f0[c] += vi * w0 * ui[c];
    for (int a = 0; a < dim; a++) acc->f2[c][a * dim + a] += vi * d2w0 * ui[c];
  }
}

/** @brief Model A's force density from the sums: with D_c,ab the second
 *  derivatives of u^c, (div tau)_a = mu sum_b D_a,bb + (mu + lambda)
 *  sum_b D_b,ab (Basa's eq. 6 for lambda = -2 mu/3). @p shepard 0: the
 *  plain sums (eq. 27); 1: the derivatives of the Shepard interpolant
 *  \<f\>/\<1\> (eq. 23), which answer a uniform field with exactly zero. */
static inline void vsph_pair_takeda_finish(const struct vsph_pair_takeda *acc,
                                           int dim, int shepard, double mu,
                                           double lambda, double f[3]) {
  double D[3][9];
  const double s0 = acc->s0, r1 = 1.0 / s0, r2 = r1 * r1, r3 = r2 * r1;
  for (int c = 0; c < dim; c++)
    for (int a = 0; a < dim; a++)
      for (int b = 0; b < dim; b++) {
        const int ab = a * dim + b;
        D[c][ab] =
            shepard ? (acc->f2[c][ab] * s0 - acc->f1[c][b] * acc->s1[a] -
                       acc->f1[c][a] * acc->s1[b] - acc->f0[c] * acc->s2[ab]) *
                              r2 +
                          2.0 * acc->f0[c] * acc->s1[a] * acc->s1[b] * r3
                    : acc->f2[c][ab];
      }
  for (int a = 0; a < dim; a++) {
    double lap = 0.0, gdiv = 0.0;
    for (int b = 0; b < dim; b++) {
      lap += D[a][b * dim + b];
      gdiv += D[b][a * dim + b];
    }
    f[a] = mu * lap + (mu + lambda) * gdiv;
  }
}

#endif /* VSPH_SOLVER_FORMS_TAKEDA_H */
