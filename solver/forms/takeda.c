/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of Takeda-type direct second derivatives, model A and A[0]
 * (their first pass makes the whole force) (solver/viscous.h's struct
 * vsph_viscous_type; their pair terms in takeda.h). */
#include <math.h>
#include <string.h>

#include "../../kernels/kernel.h"
#include "forms.h"

/* Model A for particle i: the sums of direct second derivatives over its
 * neighbours and itself (vsph_pair_takeda_add, _self), finished plain or
 * Shepard-corrected into its force density (in A[0..dim-1]), and the
 * density u_i.(div V)_i. W and W'' need s itself: one square root per
 * pair, the price of this form. */
VSPH_CONSTS_SPECIALISE void pass(const struct vsph_viscous_props *vp,
                                 const struct vsph_pair_kernel *pk,
                                 const struct vsph_particles *p,
                                 const struct vsph_pair_ranges *rg, size_t i,
                                 struct vsph_viscous_ws *ws, const int dim) {
  const struct vsph_kernel_type *k = vp->kernel;
  const double h = vp->h, wfac = pow(h, -dim), d2fac = wfac / (h * h);
  struct vsph_pair_takeda acc;
  memset(&acc, 0, sizeof acc);
  double ui[3] = {0, 0, 0};
  for (int a = 0; a < dim; a++) ui[a] = p->vel[a][i];
  vsph_pair_takeda_self(&acc, dim, p->vol[i], ui,
                        vsph_kernel_w(k, dim, 0.0) * wfac,
                        vsph_kernel_d2w(k, dim, 0.0) * d2fac);
  struct vsph_pair_iter it;
  struct vsph_pair_chunk bt;
  vsph_pair_begin(&it, pk, p, rg, i);
  while (vsph_pair_gather(&it, dim, pk->dfq_id, &bt)) {
    for (size_t q = 0; q < bt.m; q++) {
      struct vsph_pair pr;
      vsph_pair_at(&bt, q, dim, &pr);
      const double s = sqrt(pr.s2) / h;
      double uj[3] = {0, 0, 0};
      for (int a = 0; a < dim; a++) uj[a] = p->vel[a][pr.j];
      vsph_pair_takeda_add(&acc, &pr, dim, p->vol[pr.j], uj,
                           vsph_kernel_w(k, dim, s) * wfac,
                           vsph_kernel_d2w(k, dim, s) * d2fac);
    }
  }
  double f[3];
  vsph_pair_takeda_finish(
      &acc, dim,
      (vsph_viscous_types[vp->form]->flags & VSPH_VISCOUS_SHEPARD) != 0, vp->mu,
      vp->lambda, f);
  double P = 0.0;
  for (int a = 0; a < dim; a++) {
    ws->A[a][i] = f[a];
    P += ui[a] * f[a];
  }
  ws->dens[i] = P;
  ws->fallback[i] = 0;
}

/* The first pass of particle i, the dimension fixed outside the loop. */
static void first_takeda(const struct vsph_viscous_props *vp,
                         const struct vsph_pair_kernel *pk,
                         const struct vsph_particles *p,
                         const struct vsph_pair_ranges *rg, size_t i,
                         struct vsph_viscous_ws *ws) {
  if (vp->dim == 2)
    pass(vp, pk, p, rg, i, ws, 2);
  else
    pass(vp, pk, p, rg, i, ws, vp->dim);
}

const struct vsph_viscous_type vsph_takeda_a = {
    .name = "takeda",
    .label = "A",
    .legend = "Takeda (A)",
    .cite =
        "direct second derivatives, Takeda et al. 1994 (Basa et "
        "al. 2009, model A, eqs. 27-28)",
    .pass = VSPH_VISCOUS_PASS_TAKEDA,
    .flags = 0,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES3,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = 0.0,
    .params = "",
    .pair = NULL,
    .first = first_takeda};

const struct vsph_viscous_type vsph_takeda_a0 = {
    .name = "takeda0",
    .label = "A[0]",
    .legend = "Takeda, Shepard (A[0])",
    .cite = "model A, Shepard-corrected (Basa et al. 2009, eq. 23)",
    .pass = VSPH_VISCOUS_PASS_TAKEDA,
    .flags = VSPH_VISCOUS_SHEPARD,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES3,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = 0.0,
    .params = "",
    .pair = NULL,
    .first = first_takeda};
