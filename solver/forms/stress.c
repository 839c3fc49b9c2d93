/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of PVWF and the two-pass strain-rate form (model B): a
 * stress pass, then its divergence (solver/viscous.h's struct
 * vsph_viscous_type; their pair terms in stress.h). */
/* their second pass's 2-D Gaussian sweep goes by cell groups in AVX-512
 * or AVX2 lanes, the stress term (solver/sweep_x86.h,
 * solver/viscous_internal.h) */
#define VSPH_VISCOUS_GROUPS VSPH_SWEEP_X86_STRESS_TERM
#include "../../kernels/kernel.h"
#include "forms.h"

/* The pair function (vsph_viscous_pair_fn), their second pass: the
 * share -V_j F (A_j + A_i) x of vsph_pair_pvwf_force and no density
 * (theirs is -T_i:D_i, from the first pass); inlined into the family's
 * loops below. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc pair_stress(
    const struct vsph_viscous_loop *lp, int dim, const struct vsph_pair *pr,
    struct vsph_pair_vec du, double dux, const double Ai[9]) {
  (void)du, (void)dux;
  const struct vsph_pair_vec f = vsph_pair_pvwf_force(pr, dim, Ai, lp->A);
  struct vsph_pair_visc r = {.dens = 0.0};
  for (int k = 0; k < dim; k++) r.f[k] = f.v[k];
  return r;
}

/* PVWF's loops, which serve model B too (its A_i in the workspace). */
VSPH_VISCOUS_LOOPS(loops, pair_stress, NULL, 0)

/* PVWF pass 1 for particle i: the sums B and Mg over its neighbours
 * (vsph_pair_pvwf_grad), then L_i = B^-1, the renormalised grad u, D_i,
 * T_i = 2 mu D_i + lambda tr(D_i) I, A_i = T_i L_i and -T_i:D_i. Model B
 * (renorm 0): L_i = I, Watkins' differenced gradient sum_j V_j du (x)
 * grad_i W (Basa's model B, Vukcevic's eq. 13). */
VSPH_CONSTS_SPECIALISE void pass1(const struct vsph_viscous_props *vp,
                                  const struct vsph_pair_kernel *pk,
                                  const struct vsph_particles *p,
                                  const struct vsph_pair_ranges *rg, size_t i,
                                  struct vsph_viscous_ws *ws, const int dim,
                                  const int kid) {
  double B[9] = {0}, Mg[9] = {0}, ui[3] = {0};
  for (int a = 0; a < dim; a++) ui[a] = p->vel[a][i];
  struct vsph_pair_iter it;
  struct vsph_pair_chunk bt;
  vsph_pair_begin(&it, pk, p, rg, i);
  /* the sums as scalars, one per entry (dim^2 of the nine are used), so
   * the loop reduces them lane by lane (as the right-hand side does) */
  double B0 = 0, B1 = 0, B2 = 0, B3 = 0, B4 = 0, B5 = 0, B6 = 0, B7 = 0, B8 = 0;
  double M0 = 0, M1 = 0, M2 = 0, M3 = 0, M4 = 0, M5 = 0, M6 = 0, M7 = 0, M8 = 0;
  const int dd = dim * dim;
  while (vsph_pair_gather(&it, dim, kid, &bt)) {
    const size_t m = bt.m;
#pragma omp simd reduction(+ : B0, B1, B2, B3, B4, B5, B6, B7, B8, M0, M1, \
                               M2, M3, M4, M5, M6, M7, M8)
    for (size_t k = 0; k < m; k++) {
      struct vsph_pair pr;
      vsph_pair_at(&bt, k, dim, &pr);
      struct vsph_pair_vec du;
      for (int a = 0; a < dim; a++) du.v[a] = p->vel[a][pr.j] - ui[a];
      const struct vsph_pair_grad gr = vsph_pair_pvwf_grad(&pr, dim, du);
      const double *const bB = gr.B, *const bM = gr.M;
      B0 += bB[0];
      M0 += bM[0];
      if (dd > 1) {
        B1 += bB[1], B2 += bB[2], B3 += bB[3];
        M1 += bM[1], M2 += bM[2], M3 += bM[3];
      }
      if (dd > 4) {
        B4 += bB[4], B5 += bB[5], B6 += bB[6], B7 += bB[7], B8 += bB[8];
        M4 += bM[4], M5 += bM[5], M6 += bM[6], M7 += bM[7], M8 += bM[8];
      }
    }
  }
  const double Bs[9] = {B0, B1, B2, B3, B4, B5, B6, B7, B8},
               Ms[9] = {M0, M1, M2, M3, M4, M5, M6, M7, M8};
  for (int e = 0; e < dd; e++) {
    B[e] = Bs[e];
    Mg[e] = Ms[e];
  }
  vsph_viscous_pvwf_finish(vp, ws, i, B, Mg);
}

/* The first pass of particle i, the dimension and kernel fixed outside
 * the loop: the 2-D Gaussian and cubic B-spline (Basa's channels) have
 * their own copies, any other runs the general one. */
static void first_stress(const struct vsph_viscous_props *vp,
                         const struct vsph_pair_kernel *pk,
                         const struct vsph_particles *p,
                         const struct vsph_pair_ranges *rg, size_t i,
                         struct vsph_viscous_ws *ws) {
  const int G = VSPH_KERNEL_DFQ_GAUSSIAN, C = VSPH_KERNEL_DFQ_CUBIC;
  if (vp->dim == 2 && pk->dfq_id == G)
    pass1(vp, pk, p, rg, i, ws, 2, G);
  else if (vp->dim == 2 && pk->dfq_id == C)
    pass1(vp, pk, p, rg, i, ws, 2, C);
  else
    pass1(vp, pk, p, rg, i, ws, vp->dim, pk->dfq_id);
}

#define FS VSPH_VISCOUS_FREE_SURFACE

const struct vsph_viscous_type vsph_stress_pvwf = {
    .name = "pvwf",
    .label = "PVWF",
    .cite =
        "principle of virtual work, Colagrossi et al. 2011, "
        "Eqs. (4.18)-(4.19)",
    .pass = VSPH_VISCOUS_PASS_STRESS,
    .loops = &loops,
    .flags = FS | VSPH_VISCOUS_RENORM,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES,
    .limit = VSPH_VISCOUS_LIMIT_STRESS,
    .eta = 0.0,
    .params = "det_tol",
    .pair = pair_stress,
    .first = first_stress};

const struct vsph_viscous_type vsph_stress_twopass = {
    .name = "twopass",
    .label = "B",
    .legend = "two-pass (B)",
    .cite =
        "two-pass strain rate, Watkins et al. 1996 (Basa et al. "
        "2009, model B, eq. 29; Vukcevic et al. 2012)",
    .pass = VSPH_VISCOUS_PASS_STRESS,
    .loops = &loops,
    .flags = 0,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES3,
    .limit = VSPH_VISCOUS_LIMIT_STRESS,
    .eta = 0.0,
    .params = "",
    .pair = pair_stress,
    .first = first_stress};
