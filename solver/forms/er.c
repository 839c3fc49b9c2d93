/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of Espanol & Revenga's form (solver/viscous.h's struct
 * vsph_viscous_type; their pair terms in er.h). */
#include "forms.h"

/* The pair functions (vsph_viscous_pair_fn): the terms with the loop's
 * constants. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc pair_er(
    const struct vsph_viscous_loop *lp, int dim, const struct vsph_pair *pr,
    struct vsph_pair_vec du, double dux, const double Ai[9]) {
  (void)Ai;
  return vsph_pair_er(pr, dim, lp->er_a, lp->er_b, du, dux);
}

/* The corrected pair function (vsph_viscous_pair_g_fn). */
VSPH_CONSTS_SPECIALISE double pair_g_er(const struct vsph_viscous_loop *lp,
                                        int dim, const struct vsph_pair *pr,
                                        double vj, const double du[3],
                                        double dux, const double g[3],
                                        double f[3]) {
  vsph_pair_er_g(pr, dim, lp->er_a, lp->er_b, vj, du, dux, g, f);
  return vsph_forms_dens_g(dim, f, du);
}

/* ER's loops. */
VSPH_VISCOUS_LOOPS(loops, pair_er, pair_g_er, 1)

#define CO VSPH_VISCOUS_CORRIGIBLE
#define TV VSPH_VISCOUS_TVF

const struct vsph_viscous_type vsph_er_er = {
    .name = "er",
    .label = "ER",
    .cite = "Espanol & Revenga 2003 (docs/theory.md, section 8)",
    .pass = VSPH_VISCOUS_PASS_NONE,
    .loops = &loops,
    .flags = CO | TV,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_GRADIENT,
    .eta = 0.0,
    .params = "zeta",
    .pair = pair_er,
    .pair_g = pair_g_er};
