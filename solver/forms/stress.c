/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of PVWF and the two-pass strain-rate form (model B): a
 * stress pass, then its divergence (solver/viscous.h's struct
 * vsph_viscous_type; their pair terms in stress.h). */
#include "forms.h"

/* The pair functions (vsph_viscous_pair_fn): the terms with the loop's
 * constants. */
static struct vsph_pair_visc pair_stress(const struct vsph_viscous_loop *lp,
                                         int dim, const struct vsph_pair *pr,
                                         struct vsph_pair_vec du, double dux,
                                         const double Ai[9]) {
  (void)du, (void)dux;
  return vsph_viscous_pair_stress(pr, dim, Ai, lp->A);
}

#define FS VSPH_VISCOUS_FREE_SURFACE

const struct vsph_viscous_type vsph_stress_pvwf = {
    .name = "pvwf",
    .label = "PVWF",
    .cite =
        "principle of virtual work, Colagrossi et al. 2011, "
        "Eqs. (4.18)-(4.19)",
    .pass = VSPH_VISCOUS_PASS_STRESS,
    .family = VSPH_VISCOUS_FAMILY_STRESS,
    .flags = FS | VSPH_VISCOUS_RENORM,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES,
    .limit = VSPH_VISCOUS_LIMIT_STRESS,
    .eta = 0.0,
    .params = "det_tol",
    .pair = pair_stress};

const struct vsph_viscous_type vsph_stress_twopass = {
    .name = "twopass",
    .label = "B",
    .cite =
        "two-pass strain rate, Watkins et al. 1996 (Basa et al. "
        "2009, model B, eq. 29; Vukcevic et al. 2012)",
    .pass = VSPH_VISCOUS_PASS_STRESS,
    .family = VSPH_VISCOUS_FAMILY_STRESS,
    .flags = 0,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_STOKES3,
    .limit = VSPH_VISCOUS_LIMIT_STRESS,
    .eta = 0.0,
    .params = "",
    .pair = pair_stress};
