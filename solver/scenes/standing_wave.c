/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Standing wave in a tank with free-slip walls (Colagrossi et al. 2011,
 * Sec. VI C; THEORY 6.3). The amplitude eps = 2A/lambda = 0.05 is
 * [reconstructed]: the seed's value is unreadable.
 * Parameters: struct vsph_scene_wave (solver/scene.h). */
#include <math.h>

#include "../../common/consts.h"
#include "../../common/params.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../lattice.h"
#include "../particles.h"
#include "../scene.h"

#define W struct vsph_scene_wave
static const struct vsph_params_spec params[] = {
    VSPH_PARAMS_REAL_SPEC(W, lambda, 2.0, 1e-6, 1e6,
                          "wavelength (m); tank width L = lambda/2 = depth H"),
    VSPH_PARAMS_REAL_SPEC(W, eps, 0.05, 1e-9, 0.5,
                          "steepness 2A/lambda [reconstructed]"),
    VSPH_PARAMS_REAL_SPEC(W, Re, 140.0, 1.0, 1e9,
                          "Reynolds number lambda U_max/nu"),
    VSPH_PARAMS_REAL_SPEC(W, g, 9.81, 1e-6, 1e6, "gravity (m/s^2)"),
    VSPH_PARAMS_REAL_SPEC(W, rho0, 1.0, 1e-6, 1e9,
                          "reference density (kg/m^2)"),
    VSPH_PARAMS_REAL_SPEC(W, c0, 0.0, 0.0, 1e9,
                          "sound speed (m/s); 0: 10 max(U, sqrt(g H))"),
    VSPH_PARAMS_REAL_SPEC(W, t_end, 8.0, 1e-9, 1e9, "default end time (s)"),
};
#undef W

void vsph_standing_wave_velocity(const struct vsph_scene_wave *w, double x,
                                 double y, double u[2]) {
  if (!w || !u) return;
  const double k = w->k, H = w->L;
  const double a = w->A * w->g / w->omega * k / cosh(k * H);
  u[0] = -a * cosh(k * (y + H)) * sin(k * x);
  u[1] = a * sinh(k * (y + H)) * cos(k * x);
}

static int setup(struct vsph_scene *sc) {
  struct vsph_scene_wave *w = &sc->u.wave;
  const double lambda = w->lambda, g = w->g;
  const double L = 0.5 * lambda, H = L, k = 2.0 * VSPH_PI / lambda;
  const double A = 0.5 * w->eps * lambda;
  const double omega = sqrt(g * k * tanh(k * H));
  sc->ref_length = H;
  sc->rho0 = w->rho0;
  sc->U_max = A * g * k / omega; /* |grad phi0| at the surface */
  const double nu = lambda * sc->U_max / w->Re;
  sc->mu = sc->rho0 * nu;
  sc->t_end = w->t_end;
  sc->body = VSPH_EQUATIONS_BODY_GRAVITY;
  sc->g = g;
  sc->dp_max = sc->rho0 * g * H; /* hydrostatic */
  sc->c0 = vsph_scene_sound_speed(sc, w->c0);
  w->L = L;
  w->k = k;
  w->omega = omega;
  w->A = A;
  w->nu = nu;
  /* free-slip walls x = 0, x = L and bottom y = -H */
  struct vsph_walls wl = {.n = 3,
                          .axis = {0, 0, 1},
                          .pos = {0.0, L, -H},
                          .side = {+1, -1, +1},
                          .noslip = 0,
                          .g = g,
                          .rho0 = sc->rho0,
                          .c0 = sc->c0};
  sc->walls = wl;
  sc->box_lo[0] = -0.5 * L;
  sc->box_hi[0] = 1.5 * L;
  sc->box_lo[1] = -1.5 * H;
  sc->box_hi[1] = H;
  return VSPH_OK;
}

static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const struct vsph_scene_wave *w = &sc->u.wave;
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
    vsph_standing_wave_velocity(w, x, y, u);
    p->vel[0][i] = u[0];
    p->vel[1][i] = u[1];
    /* hydrostatic pressure under a flat surface */
    vsph_scene_set_pressure(sc, p, i, -sc->rho0 * sc->g * y);
  }
  return VSPH_OK;
}

static void rest_velocity(const struct vsph_scene *sc, const double x[3],
                          double u[3]) {
  double v[2];
  vsph_standing_wave_velocity(&sc->u.wave, x[0], x[1], v);
  u[0] = v[0];
  u[1] = v[1];
  u[2] = 0.0;
}

const struct vsph_scene_type vsph_standing_wave_type = {
    .name = "standing-wave",
    .description = "standing wave in a tank with free-slip walls (Sec. VI C)",
    .length_name = "H",
    .area = 1.0,
    .params = params,
    .nparams = sizeof params / sizeof params[0],
    .cfl = 2.0, /* the time-step study's pick (docs/theory.md 5) */
    .setup = setup,
    .init = init,
    .rest_velocity = rest_velocity,
};
