/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of Zheng et al.'s Laplacian forms VISC-01..04 as viscous
 * forms (their first pass makes the whole force) (solver/viscous.h's struct
 * vsph_viscous_type; their pair terms in zheng.h). */
#include "forms.h"

/* VISC-0x for particle i: mu lap u_c of each component, into A[0..dim-1],
 * and u_i.(div V)_i. */
static void first_zheng(const struct vsph_viscous_props *vp,
                        const struct vsph_pair_kernel *pk,
                        const struct vsph_particles *p,
                        const struct vsph_pair_ranges *rg, size_t i,
                        struct vsph_viscous_ws *ws) {
  const int dim = vp->dim;
  const double *const vel[3] = {p->vel[0], p->vel[1], p->vel[2]};
  double lap[3] = {0, 0, 0}, P = 0.0;
  vsph_viscous_laplacians(
      pk, vp->kernel, vp->h, vp->eta * vp->h * vp->eta * vp->h, vp->det_tol,
      vsph_viscous_types[vp->form]->lap, p, rg, i, dim, vel, lap);
  for (int a = 0; a < dim; a++) {
    ws->A[a][i] = vp->mu * lap[a];
    P += p->vel[a][i] * ws->A[a][i];
  }
  ws->dens[i] = P;
  ws->fallback[i] = 0;
}

#define TV VSPH_VISCOUS_TVF

const struct vsph_viscous_type vsph_zheng_visc01 = {
    .name = "visc01",
    .label = "VISC-01",
    .legend = "VISC-01 (hybrid, η 0.1 h)",
    .cite =
        "Zheng et al. 2018, VISC-01: Brookshaw/Morris hybrid "
        "(eq. 15)",
    .pass = VSPH_VISCOUS_PASS_LAPLACIAN,
    .flags = TV,
    .lap = VSPH_PAIR_LAP_HYBRID,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = VSPH_VISCOUS_ETA,
    .params = "eta",
    .pair = NULL,
    .first = first_zheng};

const struct vsph_viscous_type vsph_zheng_visc02 = {
    .name = "visc02",
    .label = "VISC-02",
    .legend = "VISC-02 (direct)",
    .cite =
        "Zheng et al. 2018, VISC-02: twice-differentiated kernel "
        "(eq. 16)",
    .pass = VSPH_VISCOUS_PASS_LAPLACIAN,
    .flags = TV,
    .lap = VSPH_PAIR_LAP_DIRECT,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = 0.0,
    .params = "",
    .pair = NULL,
    .first = first_zheng};

const struct vsph_viscous_type vsph_zheng_visc03 = {
    .name = "visc03",
    .label = "VISC-03",
    .legend = "VISC-03 (Schwaiger)",
    .cite =
        "Zheng et al. 2018, VISC-03: Schwaiger's corrected "
        "Laplacian (eq. 17)",
    .pass = VSPH_VISCOUS_PASS_LAPLACIAN,
    .flags = TV,
    .lap = VSPH_PAIR_LAP_SCHWAIGER,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = VSPH_VISCOUS_ETA,
    .params = "eta, det_tol",
    .pair = NULL,
    .first = first_zheng};

const struct vsph_viscous_type vsph_zheng_visc04 = {
    .name = "visc04",
    .label = "VISC-04",
    .legend = "VISC-04 (Oger)",
    .cite =
        "Zheng et al. 2018, VISC-04: Oger's renormalised "
        "gradient (eq. 20)",
    .pass = VSPH_VISCOUS_PASS_LAPLACIAN,
    .flags = TV,
    .lap = VSPH_PAIR_LAP_RENORMALISED,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_LAPLACIAN,
    .eta = VSPH_VISCOUS_ETA,
    .params = "eta, det_tol",
    .pair = NULL,
    .first = first_zheng};
