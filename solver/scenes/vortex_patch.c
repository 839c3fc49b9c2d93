/* Vortex patch: a disc with non-uniform angular velocity held by a radial
 * body force (Colagrossi et al. 2011, Sec. VI A; THEORY 6.1). The initial
 * profile is [reconstructed]: the seed's Eq. (6.39) is unreadable.
 * Derived values: d[0] = R, d[1] = l^2, d[2] = omega0, d[3] = nu. */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <math.h>

#include "../../common/consts.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../lattice.h"
#include "../particles.h"
#include "../scene.h"

enum { P_R, P_L2, P_OMEGA0, P_BETA, P_NU, P_RHO0, P_C0, P_TEND, NP };

static const struct vsph_scene_param params[NP] = {
    [P_R] = {"R", 1.0, "patch radius (m)"},
    [P_L2] = {"l2", 0.1, "profile parameter l^2 (m^2) [reconstructed]"},
    [P_OMEGA0] = {"omega0", 1.0, "angular velocity at the centre (rad/s)"},
    [P_BETA] = {"beta", VSPH_PI / 8.0, "radial body force -beta^2 r (1/s)"},
    [P_NU] = {"nu", 1e-3, "kinematic viscosity (m^2/s)"},
    [P_RHO0] = {"rho0", 1.0, "reference density (kg/m^2)"},
    [P_C0] = {"c0", 0.0, "sound speed (m/s); 0: 10 max(U, sqrt(dp/rho0))"},
    [P_TEND] = {"t_end", 100.0, "default end time (s)"},
};

double vsph_vortex_patch_omega(double omega0, double l2, double R, double r) {
  return omega0 * l2 *
         (1.0 / (l2 + r * r) + r * r / ((l2 + R * R) * (l2 + R * R)));
}

/* dp/dr = rho0 (omega^2 - beta^2) r, p(R) = 0 (THEORY 6.1). */
static double dpdr(double r, void *v) {
  const struct vsph_scene *sc = v;
  const double w =
      vsph_vortex_patch_omega(sc->v[P_OMEGA0], sc->v[P_L2], sc->v[P_R], r);
  return sc->v[P_RHO0] * (w * w - sc->v[P_BETA] * sc->v[P_BETA]) * r;
}

static int pressure(const struct vsph_scene *sc, gsl_integration_workspace *ws,
                    double r, double *p) {
  gsl_function f = {dpdr, (void *)sc};
  double res, err;
  const int st = gsl_integration_qag(&f, r, sc->v[P_R], 0.0, 1e-12, ws->limit,
                                     GSL_INTEG_GAUSS21, ws, &res, &err);
  if (st && st != GSL_EROUND)
    VSPH_FAIL(VSPH_ELIB, "vortex pressure quadrature: %s", gsl_strerror(st));
  *p = -res;
  return VSPH_OK;
}

static int setup(struct vsph_scene *sc) {
  const double R = sc->v[P_R];
  if (!(R > 0) || !(sc->v[P_L2] > 0) || !(sc->v[P_NU] >= 0) ||
      !(sc->v[P_RHO0] > 0) || !(sc->v[P_TEND] > 0) || !(sc->v[P_C0] >= 0))
    VSPH_FAIL(VSPH_EINVAL,
              "vortex-patch: R, l2, rho0, t_end must be > 0, "
              "nu and c0 >= 0");
  sc->ref_length = R;
  sc->rho0 = sc->v[P_RHO0];
  sc->mu = sc->rho0 * sc->v[P_NU];
  sc->t_end = sc->v[P_TEND];
  sc->body = VSPH_EQUATIONS_BODY_RADIAL;
  sc->beta = sc->v[P_BETA];
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(100);
  if (!ws) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a workspace");
  double pmin = 0.0, pmax = 0.0;
  sc->U_max = 0.0;
  int st = VSPH_OK;
  for (int k = 0; k <= 1000 && !st; k++) { /* profile sampled at R/1000 */
    const double r = R * k / 1000.0;
    double p = 0.0;
    sc->U_max = fmax(sc->U_max, r * fabs(vsph_vortex_patch_omega(
                                        sc->v[P_OMEGA0], sc->v[P_L2], R, r)));
    st = pressure(sc, ws, r, &p);
    pmin = fmin(pmin, p);
    pmax = fmax(pmax, p);
  }
  gsl_integration_workspace_free(ws);
  if (st) return st;
  sc->dp_max = pmax - pmin;
  sc->c0 = vsph_scene_sound_speed(sc, P_C0);
  sc->d[0] = R;
  sc->d[1] = sc->v[P_L2];
  sc->d[2] = sc->v[P_OMEGA0];
  sc->d[3] = sc->v[P_NU];
  for (int k = 0; k < 2; k++) {
    sc->box_lo[k] = -3.0 * R;
    sc->box_hi[k] = 3.0 * R;
  }
  return VSPH_OK;
}

static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  struct vsph_lattice_props lp = {.dim = 2};
  int st = vsph_lattice_disc(&lp, sc->v[P_R], 2 * res, out);
  if (st) return st;
  struct vsph_particles *p = *out;
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(100);
  if (!ws) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a workspace");
  for (size_t i = 0; i < p->n && !st; i++) {
    const double x = p->pos[0][i], y = p->pos[1][i], r = hypot(x, y);
    const double w =
        vsph_vortex_patch_omega(sc->v[P_OMEGA0], sc->v[P_L2], sc->v[P_R], r);
    p->vel[0][i] = -w * y;
    p->vel[1][i] = w * x;
    double pr = 0.0;
    st = pressure(sc, ws, r, &pr);
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
    .params = params,
    .nparams = NP,
    .setup = setup,
    .init = init,
};
