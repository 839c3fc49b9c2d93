/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The lid-driven cavity (SPHERIC benchmark 3; docs/theory.md, section 9):
 * fluid in the square [0, L]^2 from rest, the lid y = L sliding at U from
 * t = 0, no-slip walls all round. Re = U L/nu; Ghia, Ghia & Shin (1982)
 * tabulate the steady centreline profiles at Re = 100, 400 and 1000
 * (analysis/references.c). Walls: fixed wall particles with Adami et al.'s
 * (2012) state (the default) or Basa et al.'s (2009) evolving density and
 * extrapolated tangential velocity (Scene:walls = evolving), the lid's
 * rows (corners included) moving at U. No body force. Stable with the
 * transport-velocity scheme (Solver:tvf = 1); the mirrored ghosts of the
 * channels pair at the singular corners within 0.05 s (docs/theory.md, section
 * 9). Parameters: struct vsph_scene_cavity (solver/scene.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../common/params.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../particles.h"
#include "../scene.h"
#include "../walls.h"

/* Defaults: the unit square and lid speed at Re = 100 to t = 10 s, as
 * Adami et al. (2013) run it; c0 = 10 U. */
#define S struct vsph_scene_cavity
static const struct vsph_params_spec cavity_params[] = {
    VSPH_PARAMS_REAL_SPEC(S, L, 1.0, 1e-9, 1e6, "side of the square (m)"),
    VSPH_PARAMS_REAL_SPEC(S, U, 1.0, 1e-9, 1e6, "lid speed (m/s)"),
    VSPH_PARAMS_REAL_SPEC(S, Re, 100.0, 1e-3, 1e5,
                          "Reynolds number U L/nu (Ghia et al. tabulate "
                          "100, 400 and 1000)"),
    VSPH_PARAMS_REAL_SPEC(S, rho0, 1.0, 1e-6, 1e9,
                          "reference density (kg/m^2)"),
    VSPH_PARAMS_REAL_SPEC(S, c0, 0.0, 0.0, 1e9, "sound speed (m/s); 0: 10 U"),
    VSPH_PARAMS_REAL_SPEC(S, t_end, 10.0, 1e-9, 1e9, "default end time (s)"),
    VSPH_PARAMS_NAME_SPEC(S, walls, "adami",
                          "wall particles: adami (Adami et al. 2012: "
                          "pressure and velocity from the fluid) or evolving "
                          "(Basa et al. 2009: density by continuity, the "
                          "tangential velocity extrapolated)"),
};
#undef S

static int setup(struct vsph_scene *sc) {
  struct vsph_scene_cavity *cv = &sc->u.cavity;
  const double L = cv->L;
  int solid;
  if (strcmp(cv->walls, "adami") && strcmp(cv->walls, "evolving"))
    VSPH_FAIL(VSPH_EINVAL, "unknown Scene:walls '%s' (adami, evolving)",
              cv->walls);
  if (vsph_walls_solid_resolve(cv->walls, &solid)) return VSPH_EINVAL;
  cv->nu = cv->U * L / cv->Re;
  sc->ref_length = L;
  sc->rho0 = cv->rho0;
  sc->mu = cv->rho0 * cv->nu;
  sc->t_end = cv->t_end;
  sc->body = VSPH_EQUATIONS_BODY_NONE;
  sc->U_max = cv->U;
  sc->dp_max = 0.0;
  sc->c0 = vsph_scene_sound_speed(sc, cv->c0);
  /* x = 0, x = L, y = 0, y = L (the lid, moving along +x) */
  struct vsph_walls wl = {.n = 4,
                          .axis = {0, 0, 1, 1},
                          .pos = {0.0, L, 0.0, L},
                          .side = {+1, -1, +1, -1},
                          .kind = {VSPH_WALLS_MIRROR, VSPH_WALLS_MIRROR,
                                   VSPH_WALLS_MIRROR, VSPH_WALLS_MIRROR},
                          .noslip = 1,
                          .velocity = VSPH_WALLS_VEL_LINEAR,
                          .solid = solid,
                          .rho0 = sc->rho0,
                          .c0 = sc->c0};
  wl.uw[3][0] = cv->U;
  sc->walls = wl;
  for (int a = 0; a < 2; a++) { /* the integrator widens it by dx/2: the
                                   first row of wall particles */
    sc->box_lo[a] = 0.0;
    sc->box_hi[a] = L;
  }
  return VSPH_OK;
}

/* res x res particles at ((i + 1/2) dx, (j + 1/2) dx), at rest, none on a
 * wall. */
static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const double dx = sc->u.cavity.L / (double)res;
  return vsph_scene_rectangle(sc, res, res, dx, dx, out);
}

const struct vsph_scene_type vsph_cavity_type = {
    .name = "cavity",
    .description = "lid-driven cavity (SPHERIC 3; Ghia et al.'s profiles)",
    .length_name = "L",
    .area = 1.0,
    .params = cavity_params,
    .nparams = sizeof cavity_params / sizeof cavity_params[0],
    .setup = setup,
    .init = init,
};
