/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The descriptors of MEAF and Morris, Fox & Zhu's regularised original
 * (solver/viscous.h's struct vsph_viscous_type; their pair terms in morris.h).
 */
/* MEAF's 2-D Gaussian sweep goes by cell groups in AVX-512 or AVX2 lanes,
 * MEAF's term (solver/sweep_x86.h, solver/viscous_internal.h). The
 * family's only loops are MEAF's: MEAF-eta runs the general loop, and
 * must not be given these (they would drop its eta;
 * test_bad_props_refused_names_listed in tests/check_viscous.c holds its
 * loops to none). */
#define VSPH_VISCOUS_GROUPS VSPH_SWEEP_X86_MEAF_TERM
#include "forms.h"

/* The pair functions (vsph_viscous_pair_fn): the terms with the loop's
 * constants. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc pair_meaf(
    const struct vsph_viscous_loop *lp, int dim, const struct vsph_pair *pr,
    struct vsph_pair_vec du, double dux, const double Ai[9]) {
  (void)dux, (void)Ai;
  return vsph_pair_meaf(pr, dim, lp->two_mu, du);
}

static struct vsph_pair_visc pair_meafeta(const struct vsph_viscous_loop *lp,
                                          int dim, const struct vsph_pair *pr,
                                          struct vsph_pair_vec du, double dux,
                                          const double Ai[9]) {
  (void)dux, (void)Ai;
  return vsph_pair_meafeta(pr, dim, lp->two_mu, lp->eta2, du);
}

/* MEAF's corrected pair function (vsph_viscous_pair_g_fn). */
VSPH_CONSTS_SPECIALISE double pair_g_meaf(const struct vsph_viscous_loop *lp,
                                          int dim, const struct vsph_pair *pr,
                                          double vj, const double du[3],
                                          double dux, const double g[3],
                                          double f[3]) {
  (void)dux;
  vsph_pair_meaf_g(pr, dim, lp->two_mu, vj, du, g, f);
  return vsph_forms_dens_g(dim, f, du);
}

/* MEAF's loops (MEAF-eta runs the general loop). */
VSPH_VISCOUS_LOOPS(loops_meaf, pair_meaf, pair_g_meaf, 1)

#define FS VSPH_VISCOUS_FREE_SURFACE
#define CO VSPH_VISCOUS_CORRIGIBLE
#define TV VSPH_VISCOUS_TVF

const struct vsph_viscous_type vsph_morris_meaf = {
    .name = "meaf",
    .label = "MEAF",
    .legend = "MEAF (E)",
    .cite =
        "Morris, Fox & Zhu 1997; Colagrossi et al. 2011, "
        "Eq. (4.30)",
    .pass = VSPH_VISCOUS_PASS_NONE,
    .loops = &loops_meaf,
    .flags = FS | CO | TV,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_GRADIENT,
    .eta = 0.0,
    .params = "",
    .pair = pair_meaf,
    .pair_g = pair_g_meaf};

const struct vsph_viscous_type vsph_morris_meafeta = {
    .name = "meafeta",
    .label = "MEAF-eta",
    .cite =
        "Morris, Fox & Zhu 1997 with r^2 + eta^2 (Basa et al. "
        "2009, model E as Morris et al. print it)",
    .pass = VSPH_VISCOUS_PASS_NONE,
    .flags = TV,
    .lap = -1,
    .lambda = VSPH_VISCOUS_LAMBDA_MU,
    .limit = VSPH_VISCOUS_LIMIT_GRADIENT,
    .eta = VSPH_VISCOUS_ETA,
    .params = "eta",
    .pair = pair_meafeta};
