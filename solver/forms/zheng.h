/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* pair.h first, outside the guard: pair.h includes this file after the
 * pair's geometry (its contact SPH uses these terms), so a program that
 * includes this header alone gets the whole of pair.h and this file once. */
#include "../pair.h"

#ifndef VSPH_SOLVER_FORMS_ZHENG_H
#define VSPH_SOLVER_FORMS_ZHENG_H

/** @file zheng.h
 *  @brief Zheng, Ma & Shao's (2018) four Laplacian forms VISC-01..04
 *  (docs/theory.md section 7), per-particle sums of one neighbour pass, each
 *  finished in its own way; the viscous forms mu lap u of section 8 and the
 *  patch test's operators. The pair terms; the descriptors are in zheng.c.
 *  Included by solver/pair.h, after the pair's geometry. */

/** The four Laplacian forms of Zheng, Ma & Shao (2018) (docs/theory.md
 *  section 7), all applied per velocity component. */
enum vsph_pair_lap_form {
  VSPH_PAIR_LAP_HYBRID = 0,   /*!< VISC-01, Brookshaw / Morris (15) */
  VSPH_PAIR_LAP_DIRECT,       /*!< VISC-02, twice-differentiated kernel (16) */
  VSPH_PAIR_LAP_SCHWAIGER,    /*!< VISC-03, Schwaiger (2008) corrected (17) */
  VSPH_PAIR_LAP_RENORMALISED, /*!< VISC-04, Oger et al. (2007) (20) */
  VSPH_PAIR_LAP_COUNT
};

/** Per-particle sums from which every form is finished (one neighbour
 *  pass serves all four; x = r_j - r_i, F = W'/s, df = f_j - f_i). */
struct vsph_pair_lap {
  double M[9]; /*!< -sum V F x (x) x: the renormalisation matrix (19) */
  double a[3]; /*!< -sum V F x = sum V grad_i W */
  double h1;   /*!< -sum V F df s^2/(s^2 + eta^2) */
  double S[9]; /*!< -sum V F df x (x) x/(s^2 + eta^2) */
  double g[3]; /*!< -sum V F df x (the gradient before Gamma) */
  double k2;   /*!< sum V df (W'' - W'/s) */
};

/** @brief Accumulate pair @p pr into @p acc: @p vj = V_j, @p df =
 *  f_j - f_i, @p d2w = W''(s) (m^{-d-2}), @p eta2 the regulariser eta^2
 *  (m^2). */
VSPH_CONSTS_SPECIALISE void vsph_pair_lap_add(struct vsph_pair_lap *acc,
                                              const struct vsph_pair *pr,
                                              int dim, double vj, double df,
                                              double d2w, double eta2) {
  const double VF = pr->VF, r = 1.0 / (pr->s2 + eta2);
  for (int a = 0; a < dim; a++) {
    acc->a[a] -= VF * pr->x[a];
    acc->g[a] -= VF * df * pr->x[a];
    for (int b = 0; b < dim; b++) {
      acc->M[a * dim + b] -= VF * pr->x[a] * pr->x[b];
      acc->S[a * dim + b] -= VF * df * pr->x[a] * pr->x[b] * r;
    }
  }
  acc->h1 -= VF * df * pr->s2 * r;
  acc->k2 += vj * df * (d2w - pr->F);
}

/** @brief The Laplacian of form @p form from the sums of particle i
 *  (docs/theory.md section 7):
 *  - VISC-01: 2 h1 (= 2 sum V (f_i - f_j) r_ij.grad W/(r^2 + eta^2));
 *  - VISC-02: 2/(d + 2) k2 ([reconstructed]: the printed form without the
 *    factor returns (d + 2)/2 times the Laplacian);
 *  - VISC-03: (d / H) (2 h1 - 2 grad f . a), grad f = Gamma g,
 *    H = tr M (the trace the paper writes H_bb), Gamma = M^-1;
 *  - VISC-04: 2 Gamma^T : S.
 *  @p Gamma is M^-1 (the caller inverts M; identity where singular).
 *  @return the Laplacian (units of f / m^2). */
static inline double vsph_pair_lap_finish(const struct vsph_pair_lap *acc,
                                          int dim, int form,
                                          const double Gamma[9]) {
  switch (form) {
    case VSPH_PAIR_LAP_HYBRID:
      return 2.0 * acc->h1;
    case VSPH_PAIR_LAP_DIRECT:
      return 2.0 / (dim + 2.0) * acc->k2;
    case VSPH_PAIR_LAP_SCHWAIGER: {
      double H = 0.0, ga = 0.0;
      for (int a = 0; a < dim; a++) {
        H += acc->M[a * dim + a];
        double grad = 0.0; /* (Gamma g)_a */
        for (int b = 0; b < dim; b++) grad += Gamma[a * dim + b] * acc->g[b];
        ga += grad * acc->a[a];
      }
      return dim / H * (2.0 * acc->h1 - 2.0 * ga);
    }
    case VSPH_PAIR_LAP_RENORMALISED: {
      double y = 0.0; /* 2 sum V (f_i - f_j) F x.(Gamma x)/(s^2 + eta^2) */
      for (int a = 0; a < dim; a++)
        for (int b = 0; b < dim; b++)
          y += Gamma[a * dim + b] * acc->S[b * dim + a];
      return 2.0 * y;
    }
    default:
      return NAN;
  }
}

#endif /* VSPH_SOLVER_FORMS_ZHENG_H */
