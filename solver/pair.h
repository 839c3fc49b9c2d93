#ifndef VSPH_SOLVER_PAIR_H
#define VSPH_SOLVER_PAIR_H

#include <stddef.h>

#include "../common/consts.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "particles.h"

/** @file pair.h
 *  @brief The one neighbour loop and the one pair function of every
 *  physical term (THEORY sections 3 and 5). Every sum over neighbours in
 *  vsph (the solver's right-hand side, the viscous operators of the
 *  analysis, PVWF's two passes, the moment sums) walks its neighbours with
 *  vsph_pair_next and adds each term through the functions below, so a
 *  term exists in exactly one place.
 *
 *  Conventions (THEORY section 0): x = r_j - r_i, s = |x|,
 *  grad_i W_ij = -x W'(s)/s. The iterator hands out F = W'(s)/s <= 0 and
 *  VF = V_j F, so no loop takes a square root or divides by s.
 *
 *  Everything here is static inline (STYLE B3: small hot helpers in the
 *  module header). No I/O, no allocation. */

/* ------------------------------------------------------------- the loop */

/** Kernel quantities every pair needs, loaded once per loop (STYLE B7). */
struct vsph_pair_kernel {
  int dim;             /*!< 1, 2 or 3 */
  double H2;           /*!< squared support radius (kappa h)^2 (m^2) */
  double h_inv2;       /*!< 1/h^2 */
  double dwq;          /*!< sigma_d h^{-d-2}, see vsph_kernel_dwq_factor */
  vsph_kernel_fn *dfq; /*!< (df/dq)/q as a function of q^2 */
};

/** Candidate neighbours of one cell: index ranges [lo, hi) in a fixed
 *  order (from vsph_cells_ranges, or one range for a direct sum). */
struct vsph_pair_ranges {
  size_t n;                        /*!< number of ranges */
  size_t lo[VSPH_CELLS_MAXRANGES]; /*!< first index of each range */
  size_t hi[VSPH_CELLS_MAXRANGES]; /*!< one past the last */
};

/** One neighbour j of particle i within the support. */
struct vsph_pair {
  size_t j;    /*!< neighbour index */
  double x[3]; /*!< r_j - r_i (m); entries beyond dim are not set */
  double s2;   /*!< |x|^2 (m^2), 0 < s2 < H2 */
  double F;    /*!< W'(s)/s (m^{-d-2}), <= 0 */
  double VF;   /*!< V_j W'(s)/s */
};

/** Iterator over the neighbours j != i of particle i, in range order. The
 *  fields are private: read the pair, not the iterator. */
struct vsph_pair_iter {
  const struct vsph_pair_kernel *pk; /*!< kernel of the loop */
  const double *pos[3];              /*!< positions (components < dim) */
  const double *vol;                 /*!< volumes */
  const struct vsph_pair_ranges *rg; /*!< candidate ranges */
  size_t i;                          /*!< receiving particle */
  size_t r, j, end;                  /*!< range, next index, range end */
  double xi[3];                      /*!< r_i */
};

/** @brief Kernel quantities for kernel @p k, dimension @p dim and
 *  smoothing length @p h (m). H2 is formed as kappa h kappa h: a truncated
 *  kernel whose w' jumps at kappa (the 3h Gaussian) must classify a pair
 *  lying on the support edge identically in every loop, and every loop
 *  takes it from here. */
static inline void vsph_pair_kernel_init(struct vsph_pair_kernel *pk,
                                         const struct vsph_kernel_type *k,
                                         int dim, double h) {
  pk->dim = dim;
  pk->H2 = k->kappa * h * k->kappa * h;
  pk->h_inv2 = 1.0 / (h * h);
  pk->dwq = vsph_kernel_dwq_factor(k, dim, h);
  pk->dfq = k->dfq[dim - 1];
}

/** @brief The candidate ranges of cell @p cell of @p cells. */
static inline void vsph_pair_ranges_cell(struct vsph_pair_ranges *rg,
                                         const struct vsph_cells *cells,
                                         size_t cell) {
  rg->n = vsph_cells_ranges(cells, cell, rg->lo, rg->hi);
}

/** @brief One range holding every particle 0..n-1 (direct sums). */
static inline void vsph_pair_ranges_all(struct vsph_pair_ranges *rg, size_t n) {
  rg->n = 1;
  rg->lo[0] = 0;
  rg->hi[0] = n;
}

/** @brief Start iterating over the neighbours of particle @p i. */
static inline void vsph_pair_begin(struct vsph_pair_iter *it,
                                   const struct vsph_pair_kernel *pk,
                                   const struct vsph_particles *p,
                                   const struct vsph_pair_ranges *rg,
                                   size_t i) {
  it->pk = pk;
  it->vol = p->vol;
  it->rg = rg;
  it->i = i;
  it->r = 0;
  it->j = rg->n > 0 ? rg->lo[0] : 0;
  it->end = rg->n > 0 ? rg->hi[0] : 0;
  for (int k = 0; k < 3; k++) {
    it->pos[k] = k < pk->dim ? p->pos[k] : NULL;
    it->xi[k] = k < pk->dim ? p->pos[k][i] : 0.0;
  }
}

/** @brief The next neighbour j != i with s^2 < H2 into @p pr.
 *  @param dim the loop's dimension (= pk->dim), passed by the caller so that
 *  a caller specialised on a constant dimension gets unrolled loops.
 *  @return 1 if there is one, 0 when the ranges are exhausted. */
VSPH_CONSTS_SPECIALISE int vsph_pair_next(struct vsph_pair_iter *it, int dim,
                                          struct vsph_pair *pr) {
  const struct vsph_pair_kernel *pk = it->pk;
  const double H2 = pk->H2;
  for (;;) {
    while (it->j < it->end) {
      const size_t j = it->j++;
      double s2 = 0.0;
      for (int k = 0; k < dim; k++) {
        const double x = it->pos[k][j] - it->xi[k];
        pr->x[k] = x;
        s2 += x * x;
      }
      if (s2 >= H2 || j == it->i) continue;
      pr->j = j;
      pr->s2 = s2;
      pr->F = pk->dwq * pk->dfq(s2 * pk->h_inv2);
      pr->VF = it->vol[j] * pr->F;
      return 1;
    }
    if (++it->r >= it->rg->n) return 0;
    it->j = it->rg->lo[it->r];
    it->end = it->rg->hi[it->r];
  }
}

/* ------------------------------------------------------------ the terms */

/** @brief Continuity, Eq. (3.13) of Colagrossi et al. (2011), THEORY 5:
 *  d rho_i/dt = -rho_i sum_j V_j (u_j - u_i).grad_i W_ij
 *             =  rho_i sum_j V_j F (u_j - u_i).x.
 *  @param dux (u_j - u_i).x (m^2/s). @return this pair's share of the sum
 *  (the caller multiplies the sum by rho_i). */
VSPH_CONSTS_SPECIALISE double vsph_pair_continuity(const struct vsph_pair *pr,
                                                   double dux) {
  return pr->VF * dux;
}

/** @brief delta-SPH density diffusion (Antuono et al. 2010, simple form;
 *  THEORY 5): V_j psi_ij.grad_i W_ij with psi_ij = 2 (rho_j - rho_i) x/s^2,
 *  = -2 V_j F (rho_j - rho_i). The caller multiplies the sum by
 *  delta h c0. @param drho rho_j - rho_i. */
VSPH_CONSTS_SPECIALISE double vsph_pair_delta(const struct vsph_pair *pr,
                                              double drho) {
  return -2.0 * pr->VF * drho;
}

/** @brief Pressure gradient, the PVW-compatible form of Eq. (3.13):
 *  -(1/rho_i) sum_j V_j (p_i + p_j) grad_i W_ij. Adds V_j F (p_i + p_j) x
 *  to @p acc; the caller divides the sum by rho_i.
 *  @param psum p_i + p_j (Pa). */
VSPH_CONSTS_SPECIALISE void vsph_pair_pressure(const struct vsph_pair *pr,
                                               int dim, double psum,
                                               double acc[3]) {
  const double c = pr->VF * psum;
  for (int k = 0; k < dim; k++) acc[k] += c * pr->x[k];
}

/** @brief MGF, Monaghan & Gingold, Eq. (4.20), THEORY 3:
 *  (div V)_i = K mu sum_j V_j (u_j - u_i).(r_j - r_i)/s^2 grad_i W_ij.
 *  Adds -K mu V_j F (du.x)/s^2 x to @p acc.
 *  @param Kmu K mu with K = vsph_kernel_mg_factor(dim) (Pa s).
 *  @return the pair's dissipation density (K mu/2) V_j F (du.x)^2/s^2
 *  (THEORY 4), so that sum_i V_i of the sums is sum_i V_i u_i.(div V)_i. */
VSPH_CONSTS_SPECIALISE double vsph_pair_mgf(const struct vsph_pair *pr, int dim,
                                            double Kmu, double dux,
                                            double acc[3]) {
  const double c = -Kmu * pr->VF * dux / pr->s2;
  for (int k = 0; k < dim; k++) acc[k] += c * pr->x[k];
  return -0.5 * c * dux; /* (K mu/2) V_j F (du.x)^2/s^2, one division */
}

/** @brief MEAF, Morris, Fox & Zhu (1997), Eq. (4.30), THEORY 3:
 *  (div V)_i = 2 mu sum_j V_j W'/s (u_i - u_j). Adds -2 mu V_j F du to
 *  @p acc (du = u_j - u_i). @param two_mu 2 mu (Pa s).
 *  @return the pair's dissipation density mu V_j F |du|^2 (THEORY 4). */
VSPH_CONSTS_SPECIALISE double vsph_pair_meaf(const struct vsph_pair *pr,
                                             int dim, double two_mu,
                                             const double du[3],
                                             double acc[3]) {
  const double c = -two_mu * pr->VF;
  double du2 = 0.0;
  for (int k = 0; k < dim; k++) {
    acc[k] += c * du[k];
    du2 += du[k] * du[k];
  }
  return 0.5 * two_mu * pr->VF * du2;
}

/** @brief PVWF pass 1, Eqs. (4.18)-(4.19), THEORY 3: the sums
 *  B = sum_j V_j grad_i W_ij (x) x = sum_j V_j (-F) x (x) x, whose inverse
 *  is L_i, and Mg = sum_j V_j (-F) du (x) x, so that the renormalised
 *  gradient is (grad u)_i = Mg L_i (row-major d x d, entry [a*dim+b]). */
VSPH_CONSTS_SPECIALISE void vsph_pair_pvwf_grad(const struct vsph_pair *pr,
                                                int dim, const double du[3],
                                                double B[9], double Mg[9]) {
  const double c = -pr->VF;
  for (int a = 0; a < dim; a++)
    for (int b = 0; b < dim; b++) {
      B[a * dim + b] += c * pr->x[a] * pr->x[b];
      Mg[a * dim + b] += c * du[a] * pr->x[b];
    }
}

/** @brief PVWF pass 2, Eq. (4.19), THEORY 3:
 *  (div V)_i = sum_j V_j (T_j L_j + T_i L_i) grad_i W_ij. Adds
 *  -V_j F (A_j + A_i) x to @p acc with A = T L from pass 1.
 *  @param Ai A_i (row-major); @param A A[a*dim+b][j] of every particle. */
VSPH_CONSTS_SPECIALISE void vsph_pair_pvwf_force(const struct vsph_pair *pr,
                                                 int dim, const double Ai[9],
                                                 double *const A[9],
                                                 double acc[3]) {
  const size_t j = pr->j;
  for (int a = 0; a < dim; a++) {
    double y = 0.0;
    for (int b = 0; b < dim; b++)
      y += (A[a * dim + b][j] + Ai[a * dim + b]) * pr->x[b];
    acc[a] -= pr->VF * y;
  }
}

#endif /* VSPH_SOLVER_PAIR_H */
