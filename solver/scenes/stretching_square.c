/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Stretching square: a free square under pure strain (Colagrossi et al.
 * 2011, Sec. VI B; THEORY 6.2). Initial pressure from lap p = -2 rho A0^2
 * with p = 2 mu n.D0.n on the edges, by the FFTW sine-transform solver
 * (or zero, Scene:pressure=0, to measure what the Poisson start is worth).
 * Parameters: struct vsph_scene_square (solver/scene.h). */
#include <math.h>

#include "../../common/params.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../lattice.h"
#include "../particles.h"
#include "../poisson.h"
#include "../scene.h"

#define S struct vsph_scene_square
static const struct vsph_params_spec params[] = {
    VSPH_PARAMS_REAL_SPEC(S, L, 1.0, 1e-6, 1e6, "side of the square (m)"),
    VSPH_PARAMS_REAL_SPEC(S, A0, 1.0, -1e6, 1e6,
                          "strain rate, u = A0 (x, -y) (1/s)"),
    VSPH_PARAMS_REAL_SPEC(S, nu, 0.05, 0.0, 1e6,
                          "kinematic viscosity (m^2/s); Re = L^2 A0/nu"),
    VSPH_PARAMS_REAL_SPEC(S, rho0, 1.0, 1e-6, 1e9,
                          "reference density (kg/m^2)"),
    VSPH_PARAMS_REAL_SPEC(S, c0, 0.0, 0.0, 1e9,
                          "sound speed (m/s); 0: 10 max(U, sqrt(dp/rho0))"),
    VSPH_PARAMS_REAL_SPEC(S, t_end, 1.0, 1e-9, 1e9, "default end time (s)"),
    VSPH_PARAMS_INT_SPEC(S, poisson_grid, 0, 0, 4096,
                         "interior nodes per side of the pressure grid; 0: "
                         "4 res (at least 16)"),
    VSPH_PARAMS_INT_SPEC(S, pressure, 1, 0, 1,
                         "initial pressure: 1 the Poisson solution, 0 zero "
                         "(the flow then settles it by sound waves)"),
};
#undef S

struct bc {
  double L, mu, A0, rho0;
};

/* lap p = -2 rho0 A0^2 (steady inviscid balance of u = A0 (x, -y)) */
static double rhs_fn(double x, double y, void *c) {
  (void)x, (void)y;
  const struct bc *b = c;
  return -2.0 * b->rho0 * b->A0 * b->A0;
}

/* p = 2 mu n.D0.n: +2 mu A0 on x = +-L/2, -2 mu A0 on y = +-L/2; at a
 * corner the two meet and the mean 0 is used. */
static double bc_fn(double x, double y, void *c) {
  const struct bc *b = c;
  const double ax = fabs(x), ay = fabs(y);
  if (ax > ay) return 2.0 * b->mu * b->A0;
  if (ay > ax) return -2.0 * b->mu * b->A0;
  return 0.0;
}

static int solve(const struct vsph_scene *sc, size_t n,
                 struct vsph_poisson **out) {
  const struct vsph_scene_square *sq = &sc->u.square;
  struct bc b = {sq->L, sc->mu, sq->A0, sc->rho0};
  struct vsph_poisson *ps = vsph_poisson_alloc(n, sq->L);
  if (!ps) return VSPH_ENOMEM;
  const int st = vsph_poisson_solve(ps, rhs_fn, bc_fn, &b);
  if (st) {
    vsph_poisson_free(ps);
    return st;
  }
  *out = ps;
  return VSPH_OK;
}

static int setup(struct vsph_scene *sc) {
  const struct vsph_scene_square *sq = &sc->u.square;
  const double L = sq->L;
  sc->ref_length = L;
  sc->rho0 = sq->rho0;
  sc->mu = sq->rho0 * sq->nu;
  sc->t_end = sq->t_end;
  sc->body = VSPH_EQUATIONS_BODY_NONE;
  sc->U_max = fabs(sq->A0) * L / sqrt(2.0); /* at the corners */
  struct vsph_poisson *ps = NULL;
  const int st = solve(sc, 64, &ps); /* pressure range for c0 only */
  if (st) return st;
  double pmin = INFINITY, pmax = -INFINITY;
  for (size_t j = 0; j <= 65; j++)
    for (size_t i = 0; i <= 65; i++) {
      pmin = fmin(pmin, vsph_poisson_node(ps, i, j));
      pmax = fmax(pmax, vsph_poisson_node(ps, i, j));
    }
  vsph_poisson_free(ps);
  sc->dp_max = pmax - pmin;
  sc->c0 = vsph_scene_sound_speed(sc, sq->c0);
  if (!(sc->c0 > 0.0))
    VSPH_FAIL(VSPH_EINVAL,
              "stretching-square: the flow is at rest and no sound speed "
              "is given (set Scene:c0)");
  /* the square stretches to L e^{A0 t}/2 along x: keep a wide box */
  const double reach = 0.5 * L * exp(fabs(sq->A0) * sc->t_end) + 2.0 * L;
  for (int k = 0; k < 2; k++) {
    sc->box_lo[k] = -reach;
    sc->box_hi[k] = reach;
  }
  return VSPH_OK;
}

static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const struct vsph_scene_square *sq = &sc->u.square;
  struct vsph_lattice_props lp = {.dim = 2};
  int st = vsph_lattice_square(&lp, sq->L, res, out);
  if (st) return st;
  struct vsph_particles *p = *out;
  const size_t n = sq->poisson_grid > 0 ? sq->poisson_grid : 4 * res;
  struct vsph_poisson *ps = NULL;
  if ((st = solve(sc, n < 16 ? 16 : n, &ps))) {
    vsph_particles_free(p);
    *out = NULL;
    return st;
  }
  for (size_t i = 0; i < p->n; i++) {
    const double x = p->pos[0][i], y = p->pos[1][i];
    p->vel[0][i] = sq->A0 * x;
    p->vel[1][i] = -sq->A0 * y;
    vsph_scene_set_pressure(sc, p, i,
                            sq->pressure ? vsph_poisson_interp(ps, x, y) : 0.0);
  }
  vsph_poisson_free(ps);
  return VSPH_OK;
}

const struct vsph_scene_type vsph_stretching_square_type = {
    .name = "stretching-square",
    .description = "free square under pure strain (Sec. VI B)",
    .length_name = "L",
    .area = 1.0,
    .params = params,
    .nparams = sizeof params / sizeof params[0],
    .setup = setup,
    .init = init,
};
