/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/params.h"
#include "../common/status.h"
#include "integrate.h"
#include "particles.h"

static const struct vsph_scene_type *const scene_table[] = {
    &vsph_vortex_patch_type,    &vsph_stretching_square_type,
    &vsph_standing_wave_type,   &vsph_channel_poiseuille_type,
    &vsph_channel_couette_type, &vsph_cavity_type,
    &vsph_shear_type,           &vsph_cylinders_type,
};

int vsph_scene_is_channel(const struct vsph_scene_type *type) {
  return type == &vsph_channel_poiseuille_type ||
         type == &vsph_channel_couette_type;
}

int vsph_scene_has_profile(const struct vsph_scene_type *type) {
  return vsph_scene_is_channel(type) || type == &vsph_cavity_type;
}

size_t vsph_scene_count(void) {
  return sizeof scene_table / sizeof scene_table[0];
}

const struct vsph_scene_type *vsph_scene_get(size_t i) {
  return i < vsph_scene_count() ? scene_table[i] : NULL;
}

const struct vsph_scene_type *vsph_scene_find(const char *name) {
  if (!name) return NULL;
  for (size_t i = 0; i < vsph_scene_count(); i++)
    if (!strcmp(scene_table[i]->name, name)) return scene_table[i];
  return NULL;
}

/* 1 if @p key is given with another value than @p plain (read as a
 * string; the solver reads each of these keys anyway). */
static int given_other(struct vsph_params *prm, const char *key,
                       const char *plain) {
  if (!vsph_params_given(prm, key)) return 0;
  const char *v;
  if (vsph_params_get_string_or(prm, key, plain, &v)) return 1;
  if (!strcmp(plain, "0")) { /* a number: 0 in any spelling is plain */
    char *end;
    const double x = strtod(v, &end);
    return !(end != v && *end == '\0' && x == 0.0);
  }
  return strcmp(v, plain) != 0;
}

int vsph_scene_solver_defaults(const struct vsph_scene_type *type,
                               struct vsph_params *prm) {
  if (!prm)
    VSPH_FAIL(VSPH_EINVAL, "vsph_scene_solver_defaults: a NULL argument");
  /* the scene's own CFL: its RK4 runs of the WCSPH scheme (the study's),
   * not contact SPH, the transport velocity, leapfrog or a fixed step */
  if (type->cfl > 0.0 && !vsph_params_given(prm, "Solver:cfl") &&
      !given_other(prm, "Solver:scheme", "wcsph") &&
      !given_other(prm, "Solver:tvf", "0") &&
      !given_other(prm, "Solver:integrator", "rk4") &&
      !given_other(prm, "Solver:dt", "0")) {
    char v[32];
    snprintf(v, sizeof v, "%.17g", type->cfl);
    const int st = vsph_params_set(prm, "Solver:cfl", v);
    if (st) return st;
  }
  if (!type->solver_defaults || vsph_params_given(prm, "Solver:visc"))
    return VSPH_OK;
  if (vsph_params_given(prm, "Solver:scheme")) { /* theirs, or none */
    const char *given, *mine = "";
    vsph_params_get_string_or(prm, "Solver:scheme", "", &given);
    for (const char *const *d = type->solver_defaults; *d; d++)
      if (!strncmp(*d, "scheme=", 7)) mine = *d + 7;
    if (strcmp(given, mine)) return VSPH_OK;
  }
  for (const char *const *d = type->solver_defaults; *d; d++) {
    const char *eq = strchr(*d, '=');
    char key[64];
    snprintf(key, sizeof key, "Solver:%.*s", (int)(eq - *d), *d);
    if (vsph_params_given(prm, key)) continue;
    /* a default alpha would set h = 2 alpha dx over a given hdx */
    if (!strcmp(key, "Solver:alpha") && vsph_params_given(prm, "Solver:hdx"))
      continue;
    const int st = vsph_params_set(prm, key, eq + 1);
    if (st) return st;
  }
  return VSPH_OK;
}

void vsph_scene_solver_defaults_text(const struct vsph_scene_type *type,
                                     char *buf, size_t len) {
  if (!type || !buf) return;
  size_t n = 0;
  buf[0] = '\0';
  for (const char *const *d = type->solver_defaults; d && *d && n < len; d++)
    n += (size_t)snprintf(buf + n, len - n, "%s%s", n ? " " : "", *d);
}

int vsph_scene_init(struct vsph_scene *sc, const struct vsph_scene_type *type,
                    struct vsph_params *prm) {
  if (!sc || !type) VSPH_FAIL(VSPH_EINVAL, "vsph_scene_init: a NULL argument");
  memset(sc, 0, sizeof *sc);
  sc->type = type;
  sc->dim = 2;
  sc->area = type->area; /* a scene whose size is a parameter sets its own */
  /* the table's offsets are into the type's member of the union, which
   * starts at the union's address */
  const int st = vsph_params_load(prm, "Scene", type->params, type->nparams,
                                  &sc->u, sizeof sc->u);
  if (st) return st;
  return type->setup(sc);
}

double vsph_scene_sound_speed(const struct vsph_scene *sc, double c0) {
  if (!sc) return NAN;
  if (c0 > 0.0) return c0;
  /* THEORY 5: c0 = 10 max(U_max, sqrt(dp_max / rho0)) */
  return 10.0 * fmax(sc->U_max, sqrt(sc->dp_max / sc->rho0));
}

int vsph_scene_integrate_props(const struct vsph_scene *sc, int form,
                               const struct vsph_kernel_type *k, double h,
                               struct vsph_integrate_props *ip) {
  if (!sc || !k || !ip)
    VSPH_FAIL(VSPH_EINVAL, "vsph_scene_integrate_props: a NULL argument");
  memset(ip, 0, sizeof *ip);
  const int st =
      vsph_viscous_props_init(&ip->eq.visc, form, k, sc->dim, h, sc->mu);
  if (st) return st;
  ip->eq.rho0 = sc->rho0;
  ip->eq.c0 = sc->c0;
  ip->eq.body = sc->body;
  ip->eq.beta = sc->beta;
  ip->eq.g = sc->g;
  ip->eq.f = sc->f;
  ip->walls = sc->walls;
  /* fixed wall particles' p and V follow from their density by the law,
   * like every particle's: not set aside by the equations */
  ip->eq.solid =
      sc->walls.solid == VSPH_WALLS_FIXED ? VSPH_WALLS_GHOSTS : sc->walls.solid;
  /* linear extrapolation [reconstructed]: the wall shear fitted to the
   * fluid within h of the wall and within h along it */
  ip->walls.band = h;
  ip->walls.window = h;
  for (int a = 0; a < 3; a++) {
    ip->box_lo[a] = sc->box_lo[a];
    ip->box_hi[a] = sc->box_hi[a];
  }
  return VSPH_OK;
}

void vsph_scene_set_pressure(const struct vsph_scene *sc,
                             struct vsph_particles *p, size_t i, double pr) {
  if (!sc || !p) return;
  p->rho[i] = sc->rho0 + pr / (sc->c0 * sc->c0);
  p->m[i] = p->rho[i] * p->vol[i];
}

int vsph_scene_rectangle(const struct vsph_scene *sc, size_t nx, size_t ny,
                         double dx, double dy, struct vsph_particles **out) {
  if (!sc || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_scene_rectangle: a NULL argument");
  struct vsph_particles *p = vsph_particles_alloc(nx * ny, 2);
  if (!p) return VSPH_ENOMEM;
  for (size_t j = 0; j < ny; j++)
    for (size_t i = 0; i < nx; i++) {
      const size_t k = p->n++;
      p->pos[0][k] = (i + 0.5) * dx;
      p->pos[1][k] = (j + 0.5) * dy;
      p->vel[0][k] = p->vel[1][k] = 0.0;
      p->vol[k] = dx * dy;
      vsph_scene_set_pressure(sc, p, k, 0.0);
    }
  *out = p;
  return VSPH_OK;
}
