/* Standing wave in a tank with free-slip walls (Colagrossi et al. 2011,
 * Sec. VI C; THEORY 6.3). The amplitude eps = 2A/lambda = 0.05 is
 * [reconstructed]: the seed's value is unreadable.
 * Derived values: d[0] = k, d[1] = omega, d[2] = A, d[3] = nu. */
#include <math.h>

#include "../../common/consts.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../lattice.h"
#include "../particles.h"
#include "../scene.h"

enum { P_LAMBDA, P_EPS, P_RE, P_G, P_RHO0, P_C0, P_TEND, NP };

static const struct vsph_scene_param params[NP] = {
    [P_LAMBDA] = {"lambda", 2.0,
                  "wavelength (m); tank width L = lambda/2 = "
                  "depth H"},
    [P_EPS] = {"eps", 0.05, "steepness 2A/lambda [reconstructed]"},
    [P_RE] = {"Re", 140.0, "Reynolds number lambda U_max/nu"},
    [P_G] = {"g", 9.81, "gravity (m/s^2)"},
    [P_RHO0] = {"rho0", 1.0, "reference density (kg/m^2)"},
    [P_C0] = {"c0", 0.0, "sound speed (m/s); 0: 10 max(U, sqrt(g H))"},
    [P_TEND] = {"t_end", 8.0, "default end time (s)"},
};

void vsph_standing_wave_velocity(double A, double g, double k, double H,
                                 double omega, double x, double y,
                                 double u[2]) {
  const double a = A * g / omega * k / cosh(k * H);
  u[0] = -a * cosh(k * (y + H)) * sin(k * x);
  u[1] = a * sinh(k * (y + H)) * cos(k * x);
}

static int setup(struct vsph_scene *sc) {
  const double lambda = sc->v[P_LAMBDA], g = sc->v[P_G];
  if (!(lambda > 0) || !(sc->v[P_EPS] > 0) || !(sc->v[P_RE] > 0) || !(g > 0) ||
      !(sc->v[P_RHO0] > 0) || !(sc->v[P_TEND] > 0) || !(sc->v[P_C0] >= 0))
    VSPH_FAIL(VSPH_EINVAL,
              "standing-wave: lambda, eps, Re, g, rho0, t_end "
              "must be > 0, c0 >= 0");
  const double L = 0.5 * lambda, H = L, k = 2.0 * VSPH_PI / lambda;
  const double A = 0.5 * sc->v[P_EPS] * lambda;
  const double omega = sqrt(g * k * tanh(k * H));
  sc->ref_length = H;
  sc->rho0 = sc->v[P_RHO0];
  sc->U_max = A * g * k / omega; /* |grad phi0| at the surface */
  const double nu = lambda * sc->U_max / sc->v[P_RE];
  sc->mu = sc->rho0 * nu;
  sc->t_end = sc->v[P_TEND];
  sc->body = VSPH_EQUATIONS_BODY_GRAVITY;
  sc->g = g;
  sc->dp_max = sc->rho0 * g * H; /* hydrostatic */
  sc->c0 = vsph_scene_sound_speed(sc, P_C0);
  sc->d[0] = k;
  sc->d[1] = omega;
  sc->d[2] = A;
  sc->d[3] = nu;
  /* free-slip walls x = 0, x = L and bottom y = -H */
  struct vsph_walls w = {.n = 3,
                         .axis = {0, 0, 1},
                         .pos = {0.0, L, -H},
                         .side = {+1, -1, +1},
                         .noslip = 0,
                         .g = g,
                         .rho0 = sc->rho0,
                         .c0 = sc->c0};
  sc->walls = w;
  sc->box_lo[0] = -0.5 * L;
  sc->box_hi[0] = 1.5 * L;
  sc->box_lo[1] = -1.5 * H;
  sc->box_hi[1] = H;
  return VSPH_OK;
}

static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const double H = sc->ref_length, L = H;
  struct vsph_lattice_props lp = {.dim = 2};
  /* a square lattice of side L = H centred on (L/2, -H/2) */
  int st = vsph_lattice_square(&lp, L, res, out);
  if (st) return st;
  struct vsph_particles *p = *out;
  for (size_t i = 0; i < p->n; i++) {
    const double x = p->pos[0][i] + 0.5 * L, y = p->pos[1][i] - 0.5 * H;
    p->pos[0][i] = x;
    p->pos[1][i] = y;
    double u[2];
    vsph_standing_wave_velocity(sc->d[2], sc->g, sc->d[0], H, sc->d[1], x, y,
                                u);
    p->vel[0][i] = u[0];
    p->vel[1][i] = u[1];
    /* hydrostatic pressure under a flat surface */
    vsph_scene_set_pressure(sc, p, i, -sc->rho0 * sc->g * y);
  }
  return VSPH_OK;
}

const struct vsph_scene_type vsph_standing_wave_type = {
    .name = "standing-wave",
    .description = "standing wave in a tank with free-slip walls (Sec. VI C)",
    .length_name = "H",
    .params = params,
    .nparams = NP,
    .setup = setup,
    .init = init,
};
