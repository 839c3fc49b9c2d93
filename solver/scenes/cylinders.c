/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Stokes flow through a periodic array of cylinders (Parshikov et al.,
 * Parshikov et al. section 5.5, Table 2; docs/theory.md section 12): in 2-D,
 * one cylinder of diameter d at the centre of the periodic square of side S =
 * d/(d/S), held in place as a body of contact-SPH particles (the lattice points
 * inside it, a material with no viscosity of its own: the fluid sticks to it
 * through the Riemann solution, Parshikov et al.'s "extremely viscous" ball),
 * the fluid driven by a uniform force f along x. f is the force per unit mass
 * that gives, in Stokes flow with the physical viscosity, the superficial
 * velocity U = Re eta/(rho d) by eq. (39): f rho0 (S^2 - pi d^2/4) = eta U
 * F/(eta U). Contact SPH only (the held body is a second material). Parameters:
 * struct vsph_scene_cylinders (solver/scene.h). */
#include <math.h>
#include <stdio.h>

#include "../../common/consts.h"
#include "../../common/params.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../materials.h"
#include "../particles.h"
#include "../scene.h"
#include "../walls.h"

/* Defaults: Parshikov et al.'s glycerol case, d = 1 mm, d/S = 0.5, Re = 0.005
 */
#define S struct vsph_scene_cylinders
static const struct vsph_params_spec cylinders_params[] = {
    VSPH_PARAMS_REAL_SPEC(S, d, 1e-3, 1e-9, 1e3, "cylinder diameter (m)"),
    VSPH_PARAMS_REAL_SPEC(S, dS, 0.5, 0.05, 0.8, "d/S, S the period"),
    VSPH_PARAMS_REAL_SPEC(S, Re, 0.005, 1e-6, 1.0,
                          "Reynolds number rho U d/eta, U the superficial "
                          "velocity the drive gives by eq. (39)"),
    VSPH_PARAMS_REAL_SPEC(S, t_end, 5e-4, 1e-12, 1e6, "default end time (s)"),
    VSPH_PARAMS_NAME_SPEC(S, material, "glycerol",
                          "the fluid, a row of Parshikov et al.'s Table 1 "
                          "with a viscosity (vsph scenes: shear lists them)"),
};
#undef S

static int setup(struct vsph_scene *sc) {
  struct vsph_scene_cylinders *cy = &sc->u.cyl;
  const struct vsph_material *m;
  if (vsph_materials_resolve(cy->material, &m)) return VSPH_EINVAL;
  if (!isfinite(m->eta))
    VSPH_FAIL(VSPH_EINVAL, "cylinders: Table 1 gives %s no viscosity", m->name);
  cy->S = cy->d / cy->dS;
  cy->eta = m->eta;
  cy->U = cy->Re * m->eta / (m->rho0 * cy->d);
  const double area = cy->S * cy->S - 0.25 * VSPH_PI * cy->d * cy->d;
  cy->f = m->eta * cy->U * vsph_materials_drag_row(cy->dS) / (m->rho0 * area);
  sc->dim = 2;
  sc->ref_length = cy->S;
  sc->area = 1.0;
  sc->nmat = 2;
  sc->mat[0] =
      (struct vsph_equations_mat){.rho0 = m->rho0, .c0 = m->c0, .mu = m->eta};
  sc->mat[1] = (struct vsph_equations_mat){
      .rho0 = m->rho0, .c0 = m->c0, .mu = 0.0, .fixed = 1};
  sc->rho0 = m->rho0;
  sc->c0 = m->c0;
  sc->mu = m->eta;
  sc->t_end = cy->t_end;
  sc->body = VSPH_EQUATIONS_BODY_UNIFORM;
  sc->f = cy->f;
  sc->U_max = cy->U;
  sc->dp_max = 0.0;
  struct vsph_walls wl = {.n = 0, .rho0 = sc->rho0, .c0 = sc->c0};
  if (vsph_walls_add_periodic(&wl, 0, 0.0, cy->S) ||
      vsph_walls_add_periodic(&wl, 1, 0.0, cy->S))
    return VSPH_EINVAL;
  sc->walls = wl;
  for (int a = 0; a < 2; a++) {
    sc->box_lo[a] = -cy->S;
    sc->box_hi[a] = 2.0 * cy->S;
  }
  return VSPH_OK;
}

/* The square lattice (i + 1/2) D0, D0 = S/res; the points within d/2 of
 * the centre are the cylinder (material 1). */
static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const struct vsph_scene_cylinders *cy = &sc->u.cyl;
  const double d0 = cy->S / (double)res, c = 0.5 * cy->S, r = 0.5 * cy->d;
  struct vsph_particles *p = vsph_particles_alloc(res * res, 2);
  if (!p) return VSPH_ENOMEM;
  if (vsph_particles_mat_alloc(p)) {
    vsph_particles_free(p);
    return VSPH_ENOMEM;
  }
  size_t nsolid = 0;
  for (size_t j = 0; j < res; j++)
    for (size_t i = 0; i < res; i++) {
      const size_t q = p->n++;
      const double x = (i + 0.5) * d0, y = (j + 0.5) * d0;
      p->pos[0][q] = x;
      p->pos[1][q] = y;
      p->vel[0][q] = p->vel[1][q] = 0.0;
      p->vol[q] = d0 * d0;
      p->rho[q] = sc->rho0;
      p->m[q] = sc->rho0 * d0 * d0;
      p->p[q] = 0.0;
      const int solid = hypot(x - c, y - c) < r;
      p->mat[q] = (unsigned char)solid;
      nsolid += (size_t)solid;
    }
  if (nsolid < 4) {
    vsph_particles_free(p);
    VSPH_FAIL(VSPH_EINVAL,
              "cylinders: %zu particles across the cylinder at res %zu: "
              "raise res",
              nsolid, res);
  }
  *out = p;
  return VSPH_OK;
}

/* The scene holds two materials (the fluid and the held cylinder), which
 * only contact SPH runs: by default the paper's (Parshikov et al. §5.5),
 * Wendland C2 at alpha = 0.5. */
static const char *const solver_defaults[] = {
    "scheme=contact", "kernel=wendland2", "alpha=0.5", NULL};

const struct vsph_scene_type vsph_cylinders_type = {
    .name = "cylinders",
    .description =
        "Stokes flow through a periodic array of cylinders "
        "(Parshikov et al.), 2-D, contact SPH",
    .length_name = "S",
    .area = 1.0,
    .params = cylinders_params,
    .nparams = sizeof cylinders_params / sizeof cylinders_params[0],
    .setup = setup,
    .init = init,
    .solver_defaults = solver_defaults,
};
