/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Vortex patch: a disc with non-uniform angular velocity held by a radial
 * body force (Colagrossi et al. 2011, Sec. VI A; THEORY 6.1). The initial
 * profile is [reconstructed]: the seed's Eq. (6.39) is unreadable; its
 * form and weight meet every fact the paper states (THEORY 6.1).
 * Parameters: struct vsph_scene_vortex (solver/scene.h). */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <string.h>

#include "../../common/consts.h"
#include "../../common/params.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../lattice.h"
#include "../particles.h"
#include "../scene.h"

#define V struct vsph_scene_vortex
static const struct vsph_params_spec params[] = {
    VSPH_PARAMS_REAL_SPEC(V, R, 1.0, 1e-6, 1e6, "patch radius (m)"),
    VSPH_PARAMS_REAL_SPEC(V, l2, 0.1, 1e-12, 1e12,
                          "profile parameter l^2 (m^2)"),
    VSPH_PARAMS_REAL_SPEC(V, a, VSPH_VORTEX_PATCH_A, -1e6, 1e6,
                          "weight of the l^2 profile over a rigid rotation "
                          "(1: no rotation added) [reconstructed]"),
    VSPH_PARAMS_REAL_SPEC(V, omega0, 1.0, -1e6, 1e6,
                          "angular velocity at the centre (rad/s)"),
    VSPH_PARAMS_REAL_SPEC(V, beta, VSPH_PI / 8.0, 0.0, 1e6,
                          "radial body force -beta^2 r (1/s)"),
    VSPH_PARAMS_REAL_SPEC(V, nu, 1e-3, 0.0, 1e6, "kinematic viscosity (m^2/s)"),
    VSPH_PARAMS_REAL_SPEC(V, rho0, 1.0, 1e-6, 1e9,
                          "reference density (kg/m^2)"),
    VSPH_PARAMS_REAL_SPEC(V, c0, 0.0, 0.0, 1e9,
                          "sound speed (m/s); 0: 10 max(U, sqrt(dp/rho0))"),
    VSPH_PARAMS_REAL_SPEC(V, t_end, 100.0, 1e-9, 1e9, "default end time (s)"),
    VSPH_PARAMS_NAME_SPEC(V, layout, "rings",
                          "particle layout: rings (concentric, equal "
                          "volumes) or cartesian (square lattice cut to "
                          "the disc) [reconstructed]"),
};
#undef V

double vsph_vortex_patch_omega(double omega0, double l2, double a, double R,
                               double r) {
  const double g =
      l2 * (1.0 / (l2 + r * r) + r * r / ((l2 + R * R) * (l2 + R * R)));
  return omega0 * (1.0 - a + a * g);
}

/* dp/dr = rho0 (omega^2 - beta^2) r, p(R) = 0 (THEORY 6.1). */
static double dpdr(double r, void *v) {
  const struct vsph_scene_vortex *vp = v;
  const double w = vsph_vortex_patch_omega(vp->omega0, vp->l2, vp->a, vp->R, r);
  return vp->rho0 * (w * w - vp->beta * vp->beta) * r;
}

static int pressure(const struct vsph_scene_vortex *vp,
                    gsl_integration_workspace *ws, double r, double *p) {
  gsl_function f = {dpdr, (void *)vp};
  double res, err;
  const int st = gsl_integration_qag(&f, r, vp->R, 0.0, 1e-12, ws->limit,
                                     GSL_INTEG_GAUSS21, ws, &res, &err);
  if (st && st != GSL_EROUND)
    VSPH_FAIL(VSPH_ELIB, "vortex pressure quadrature: %s", gsl_strerror(st));
  *p = -res;
  return VSPH_OK;
}

static int setup(struct vsph_scene *sc) {
  const struct vsph_scene_vortex *vp = &sc->u.vortex;
  const double R = vp->R;
  if (strcmp(vp->layout, "rings") && strcmp(vp->layout, "cartesian"))
    VSPH_FAIL(VSPH_EINVAL,
              "vortex-patch: unknown layout '%s' (rings, cartesian)",
              vp->layout);
  sc->ref_length = R;
  sc->rho0 = vp->rho0;
  sc->mu = vp->rho0 * vp->nu;
  sc->t_end = vp->t_end;
  sc->body = VSPH_EQUATIONS_BODY_RADIAL;
  sc->beta = vp->beta;
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(100);
  if (!ws) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a workspace");
  double pmin = 0.0, pmax = 0.0;
  sc->U_max = 0.0;
  int st = VSPH_OK;
  for (int k = 0; k <= 1000 && !st; k++) { /* profile sampled at R/1000 */
    const double r = R * k / 1000.0;
    double p = 0.0;
    sc->U_max = fmax(sc->U_max, r * fabs(vsph_vortex_patch_omega(
                                        vp->omega0, vp->l2, vp->a, R, r)));
    st = pressure(vp, ws, r, &p);
    pmin = fmin(pmin, p);
    pmax = fmax(pmax, p);
  }
  gsl_integration_workspace_free(ws);
  if (st) return st;
  sc->dp_max = pmax - pmin;
  sc->c0 = vsph_scene_sound_speed(sc, vp->c0);
  if (!(sc->c0 > 0.0))
    VSPH_FAIL(VSPH_EINVAL,
              "vortex-patch: the flow is at rest and no sound speed is "
              "given (set Scene:c0)");
  for (int k = 0; k < 2; k++) {
    sc->box_lo[k] = -3.0 * R;
    sc->box_hi[k] = 3.0 * R;
  }
  return VSPH_OK;
}

static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const struct vsph_scene_vortex *vp = &sc->u.vortex;
  struct vsph_lattice_props lp = {.dim = 2};
  int st = strcmp(vp->layout, "cartesian")
               ? vsph_lattice_disc(&lp, vp->R, 2 * res, out)
               : vsph_lattice_disc_cartesian(&lp, vp->R, 2 * res, out);
  if (st) return st;
  struct vsph_particles *p = *out;
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(100);
  if (!ws) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a workspace");
  for (size_t i = 0; i < p->n && !st; i++) {
    const double x = p->pos[0][i], y = p->pos[1][i], r = hypot(x, y);
    const double w =
        vsph_vortex_patch_omega(vp->omega0, vp->l2, vp->a, vp->R, r);
    p->vel[0][i] = -w * y;
    p->vel[1][i] = w * x;
    double pr = 0.0;
    st = pressure(vp, ws, r, &pr);
    vsph_scene_set_pressure(sc, p, i, pr);
  }
  gsl_integration_workspace_free(ws);
  return st;
}

const struct vsph_scene_type vsph_vortex_patch_type = {
    .name = "vortex-patch",
    .description =
        "disc with non-uniform rotation held by a radial force "
        "(Sec. VI A)",
    .length_name = "R",
    .area = VSPH_PI,
    .params = params,
    .nparams = sizeof params / sizeof params[0],
    .cfl = 2.0, /* the time-step study's pick (docs/theory.md 5) */
    .setup = setup,
    .init = init,
};
