/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of MGF, Violeau & Issa's and Cleary's forms: Brookshaw's
 * pair term with their K and eta (solver/viscous.h's struct vsph_viscous_type;
 * their pair terms in brookshaw.h). */
/* this family's 2-D Gaussian sweep goes by cell groups in AVX-512 or AVX2
 * lanes, Brookshaw's term (solver/sweep_x86.h;
 * solver/viscous_internal.h) */
#define VSPH_VISCOUS_GROUPS VSPH_SWEEP_X86_BROOKSHAW_TERM
#include "forms.h"

/* The pair function (vsph_viscous_pair_fn): the term with the loop's
 * constants, inlined into the family's loops below. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc pair_brookshaw(
    const struct vsph_viscous_loop *lp, int dim, const struct vsph_pair *pr,
    struct vsph_pair_vec du, double dux, const double Ai[9]) {
  (void)du, (void)Ai;
  return vsph_pair_mgf(pr, dim, lp->Kmu, lp->eta2, dux);
}

/* The corrected pair function (vsph_viscous_pair_g_fn). */
VSPH_CONSTS_SPECIALISE double pair_g_brookshaw(
    const struct vsph_viscous_loop *lp, int dim, const struct vsph_pair *pr,
    double vj, const double du[3], double dux, const double g[3], double f[3]) {
  vsph_pair_mgf_g(pr, dim, lp->Kmu, lp->eta2, vj, dux, g, f);
  return vsph_forms_dens_g(dim, f, du);
}

/* MGF's loops, which serve VI and Cleary too (their K and eta are the
 * loop's constants). */
VSPH_VISCOUS_LOOPS(loops, pair_brookshaw, pair_g_brookshaw, 1)

#define FS VSPH_VISCOUS_FREE_SURFACE
#define CO VSPH_VISCOUS_CORRIGIBLE
#define TV VSPH_VISCOUS_TVF

const struct vsph_viscous_type vsph_brookshaw_mgf = {
    .name = "mgf",
    .label = "MGF",
    .cite =
        "Monaghan & Gingold 1983; Colagrossi et al. 2011, "
        "Eq. (4.20)",
    .pass = VSPH_VISCOUS_PASS_NONE,
    .loops = &loops,
    .flags = FS | CO | TV,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_STRESS,
    .eta = 0.0,
    .params = "",
    .pair = pair_brookshaw,
    .pair_g = pair_g_brookshaw};

const struct vsph_viscous_type vsph_brookshaw_vi = {
    .name = "vi",
    .label = "VI",
    .legend = "VI (C)",
    .cite = "Violeau & Issa 2007 (Basa et al. 2009, model C, eq. 33)",
    .pass = VSPH_VISCOUS_PASS_NONE,
    .loops = &loops,
    .flags = CO | TV,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_STRESS,
    .eta = VSPH_VISCOUS_ETA,
    .params = "eta",
    .pair = pair_brookshaw,
    .pair_g = pair_g_brookshaw};

const struct vsph_viscous_type vsph_brookshaw_cleary = {
    .name = "cleary",
    .label = "Cleary",
    .legend = "Cleary (D)",
    .cite = "Cleary 1998 (Basa et al. 2009, model D, eq. 34)",
    .pass = VSPH_VISCOUS_PASS_NONE,
    .loops = &loops,
    .flags = CO | TV | VSPH_VISCOUS_XI,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_STRESS,
    .eta = VSPH_VISCOUS_ETA,
    .params = "xi, eta",
    .pair = pair_brookshaw,
    .pair_g = pair_g_brookshaw};
