/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Channel start-up flows (Basa, Quinlan & Lastiwka 2009; Morris, Fox & Zhu
 * 1997; docs/theory.md, section 9): fluid between no-slip walls y = 0 and
 * y = W, periodic in x, from rest. Poiseuille: driven by a uniform force
 * f = 2 nu U0/d^2 (d = W/2), Re = U0 d/nu (Basa et al.'s definition).
 * Couette: the wall y = W moves at v0 from t = 0, Re = v0 W/nu (Morris').
 * Walls only here: mirrored ghosts with the wall velocity by linear
 * extrapolation (the default, Basa et al.'s choice) or by mirroring.
 * Parameters: struct vsph_scene_channel (solver/scene.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../common/params.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../lattice.h"
#include "../particles.h"
#include "../scene.h"
#include "../walls.h"

/* Defaults: Poiseuille as Basa et al. (W = 1, nu = 1, rho = 1, Re = 0.5,
 * U0 = 1 m/s, 20 x 20 particles), Couette as Morris et al. (W = 1 mm,
 * nu = 1e-6, rho = 1000, v0 = 2.5e-5 m/s, length W/2). */
#define S struct vsph_scene_channel
#define CHANNEL_SPECS(W_, LEN, RE, NU, RHO, TEND, REDOC)                     \
  VSPH_PARAMS_REAL_SPEC(S, W, W_, 1e-9, 1e6, "width between the walls (m)"), \
      VSPH_PARAMS_REAL_SPEC(S, length, LEN, 1e-9, 1e6,                       \
                            "periodic length along x (m)"),                  \
      VSPH_PARAMS_REAL_SPEC(S, Re, RE, 1e-9, 1e5, REDOC),                    \
      VSPH_PARAMS_REAL_SPEC(S, nu, NU, 1e-12, 1e6,                           \
                            "kinematic viscosity (m^2/s)"),                  \
      VSPH_PARAMS_REAL_SPEC(S, rho0, RHO, 1e-6, 1e9,                         \
                            "reference density (kg/m^2)"),                   \
      VSPH_PARAMS_REAL_SPEC(S, c0, 0.0, 0.0, 1e9,                            \
                            "sound speed (m/s); 0: 10 U (U0 or v0)"),        \
      VSPH_PARAMS_REAL_SPEC(S, t_end, TEND, 1e-9, 1e9,                       \
                            "default end time (s)"),                         \
      VSPH_PARAMS_NAME_SPEC(S, walls, "linear",                              \
                            "walls: ghosts with the wall velocity linear "   \
                            "(extrapolated wall shear) or mirror; or fixed " \
                            "(wall particles at the wall's velocity, "       \
                            "Vukcevic et al.; the period a whole number of " \
                            "rows' spacing)")
static const struct vsph_params_spec poiseuille_params[] = {CHANNEL_SPECS(
    1.0, 1.0, 0.5, 1.0, 1.0, 0.5,
    "Reynolds number U0 (W/2)/nu, U0 the steady centreline speed")};
static const struct vsph_params_spec couette_params[] = {
    CHANNEL_SPECS(1e-3, 5e-4, 0.025, 1e-6, 1e3, 1.0,
                  "Reynolds number v0 W/nu, v0 the moving wall's speed")};
#undef CHANNEL_SPECS
#undef S

static int setup(struct vsph_scene *sc, int couette) {
  struct vsph_scene_channel *ch = &sc->u.channel;
  const double W = ch->W, d = 0.5 * W;
  int wv = VSPH_WALLS_VEL_MIRROR;
  const int fixed = !strcmp(ch->walls, "fixed");
  /* an unknown name is reported by the resolver */
  if (!fixed && strcmp(ch->walls, "linear") && strcmp(ch->walls, "mirror"))
    VSPH_FAIL(VSPH_EINVAL, "unknown Scene:walls '%s' (linear, mirror, fixed)",
              ch->walls);
  if (!fixed && vsph_walls_velocity_resolve(ch->walls, &wv)) return VSPH_EINVAL;
  ch->couette = couette;
  ch->U = couette ? ch->Re * ch->nu / W : ch->Re * ch->nu / d;
  ch->f = couette ? 0.0 : 2.0 * ch->nu * ch->U / (d * d);
  sc->ref_length = W;
  sc->rho0 = ch->rho0;
  sc->mu = ch->rho0 * ch->nu;
  sc->t_end = ch->t_end;
  sc->body = couette ? VSPH_EQUATIONS_BODY_NONE : VSPH_EQUATIONS_BODY_UNIFORM;
  sc->f = ch->f;
  sc->U_max = ch->U;
  sc->dp_max = 0.0;
  sc->c0 = vsph_scene_sound_speed(sc, ch->c0);
  struct vsph_walls wl = {.n = 2,
                          .axis = {1, 1},
                          .pos = {0.0, W},
                          .side = {+1, -1},
                          .kind = {VSPH_WALLS_MIRROR, VSPH_WALLS_MIRROR},
                          .noslip = 1,
                          .velocity = wv,
                          .solid = fixed ? VSPH_WALLS_FIXED : 0,
                          .rho0 = sc->rho0,
                          .c0 = sc->c0};
  if (couette) wl.uw[1][0] = ch->U;
  if (vsph_walls_add_periodic(&wl, 0, 0.0, ch->length)) return VSPH_EINVAL;
  sc->walls = wl;
  sc->box_lo[0] = -W - ch->length;
  sc->box_hi[0] = W + 2.0 * ch->length;
  sc->box_lo[1] = -0.5 * W;
  sc->box_hi[1] = 1.5 * W;
  return VSPH_OK;
}

static int setup_poiseuille(struct vsph_scene *sc) { return setup(sc, 0); }
static int setup_couette(struct vsph_scene *sc) { return setup(sc, 1); }

/* res rows across W at y = (j + 1/2) dx, no particle on a wall; round(
 * length/dx) columns spaced to fill the period exactly. */
static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const struct vsph_scene_channel *ch = &sc->u.channel;
  const double dy = ch->W / (double)res;
  const size_t nx = (size_t)fmax(1.0, nearbyint(ch->length / dy));
  const double dxx = ch->length / (double)nx;
  if (nx > 1000000)
    VSPH_FAIL(VSPH_EINVAL, "channel: %zu columns is too many", nx);
  /* fixed wall particles continue one square lattice across the seam */
  if (sc->walls.solid && !(fabs(dxx - dy) <= 1e-9 * dy))
    VSPH_FAIL(VSPH_EINVAL,
              "channel: fixed walls need the period (%g m) to hold a whole "
              "number of the rows' spacing %g m (res %zu)",
              ch->length, dy, res);
  return vsph_scene_rectangle(sc, nx, res, dxx, dy, out);
}

const struct vsph_scene_type vsph_channel_poiseuille_type = {
    .name = "poiseuille",
    .description = "Poiseuille start-up in a periodic channel (Basa et al.)",
    .length_name = "W",
    .area = 1.0,
    .params = poiseuille_params,
    .nparams = sizeof poiseuille_params / sizeof poiseuille_params[0],
    .setup = setup_poiseuille,
    .init = init,
};

const struct vsph_scene_type vsph_channel_couette_type = {
    .name = "couette",
    .description = "Couette start-up in a periodic channel (Morris et al.)",
    .length_name = "W",
    .area = 0.5,
    .params = couette_params,
    .nparams = sizeof couette_params / sizeof couette_params[0],
    .setup = setup_couette,
    .init = init,
};
