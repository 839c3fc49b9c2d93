/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The shear layer of Parshikov, Medin, Rublev & Dyachkov (Parshikov et al.
 * sections 3 and 5; docs/theory.md section 12): two half-spaces sliding at +-U0
 * along y, u_y = U0 sign(x), in a box periodic along y and z. The paper
 * bounds x by rigid slip walls at x = +-W/2; here x is periodic over 2W
 * instead, the paper's box and its mirror image: the slip walls are then
 * planes of symmetry of the initial state (the lattice is symmetric about
 * them), so the flow in (-W/2, W/2) is the paper's, with no wall code.
 * Materials from Parshikov et al.'s Table 1 (solver/materials.c): `material`
 * for x > 0, `left` for x < 0 (two materials need contact SPH). By default the
 * paper's §3.1: lead at +-500 m/s, 800 nm between the slip walls, D0 = 10 nm
 * (res 80), contact SPH with Wendland C2 at alpha = 0.5 (the scene's Solver
 * defaults), to 4.5 ns. The periods along y and z are 30 nm, not the paper's
 * 400 and 40: the flow is uniform in y and z (every particle of a slab of the
 * lattice moves alike), so they need only exceed the kernel's reach (20 nm
 * here); 3 x 3 particles instead of 40 x 4 make the default run 18 times
 * cheaper (seconds, not minutes). Parameters: struct vsph_scene_shear
 * (solver/scene.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../common/params.h"
#include "../../common/status.h"
#include "../equations.h"
#include "../materials.h"
#include "../particles.h"
#include "../scene.h"
#include "../walls.h"

#define S struct vsph_scene_shear
static const struct vsph_params_spec shear_params[] = {
    VSPH_PARAMS_REAL_SPEC(S, W, 800e-9, 1e-12, 1e3,
                          "the paper's box along x, between its slip walls "
                          "(m); the period is 2 W"),
    VSPH_PARAMS_REAL_SPEC(S, Ly, 30e-9, 1e-12, 1e3,
                          "period along y (m; the paper's 400e-9 holds the "
                          "same uniform flow)"),
    VSPH_PARAMS_REAL_SPEC(S, Lz, 30e-9, 1e-12, 1e3,
                          "period along z (m; the paper's 40e-9 likewise)"),
    VSPH_PARAMS_REAL_SPEC(S, U0, 500.0, 1e-9, 1e5,
                          "initial speed of each half, u_y = U0 sign(x) "
                          "(m/s)"),
    VSPH_PARAMS_REAL_SPEC(S, t_end, 4.5e-9, 1e-15, 1e9, "default end time (s)"),
    VSPH_PARAMS_INT_SPEC(S, viscous, 1, 0, 1,
                         "1: the materials' physical viscosity; 0: none "
                         "(the inviscid run that measures the numerical "
                         "one)"),
    VSPH_PARAMS_NAME_SPEC(S, material, "lead",
                          "material for x > 0, a row of Parshikov et al.'s "
                          "Table 1: lithium, benzene, paraffin, water, "
                          "nitromethane, glycerol, nacl, silica, lif, "
                          "aluminium, corundum, titanium, zinc, iron, nickel, "
                          "copper, lead, tantalum, uranium, tungsten"),
    VSPH_PARAMS_NAME_SPEC(S, left, "same",
                          "material for x < 0: same, or another row (two "
                          "materials need Solver:scheme = contact)"),
};
#undef S

/* The paper's scheme and resolution (Parshikov et al. §3.1): contact SPH,
 * Wendland C2 at alpha = 0.5 (h = D0), D0 = W/80 = 10 nm. */
static const char *const solver_defaults[] = {
    "scheme=contact", "kernel=wendland2", "alpha=0.5", "res=80", NULL};

static int setup(struct vsph_scene *sc) {
  struct vsph_scene_shear *sh = &sc->u.shear;
  const struct vsph_material *mr, *ml;
  if (vsph_materials_resolve(sh->material, &mr)) return VSPH_EINVAL;
  ml = mr;
  if (strcmp(sh->left, "same") != 0 && vsph_materials_resolve(sh->left, &ml))
    return VSPH_EINVAL;
  if (sh->viscous && (!isfinite(mr->eta) || !isfinite(ml->eta)))
    VSPH_FAIL(VSPH_EINVAL,
              "shear: Table 1 gives %s no viscosity: set Scene:viscous = 0",
              !isfinite(mr->eta) ? mr->name : ml->name);
  sc->dim = 3;
  sc->ref_length = sh->W;
  sc->area = 2.0 * sh->Ly * sh->Lz / (sh->W * sh->W);
  sc->nmat = ml == mr ? 1 : 2;
  /* material 0 for x > 0, 1 for x < 0 */
  const struct vsph_material *mm[2] = {mr, ml};
  for (int m = 0; m < sc->nmat; m++)
    sc->mat[m] =
        (struct vsph_equations_mat){.rho0 = mm[m]->rho0,
                                    .c0 = mm[m]->c0,
                                    .mu = sh->viscous ? mm[m]->eta : 0.0};
  sc->rho0 = mr->rho0;
  sc->c0 = fmax(mr->c0, ml->c0);
  /* the time step's viscous limit: the larger kinematic viscosity */
  sc->mu = sc->mat[0].mu;
  if (sc->nmat > 1 && sc->mat[1].mu / ml->rho0 > sc->mu / sc->rho0)
    sc->mu = sc->mat[1].mu * sc->rho0 / ml->rho0;
  sc->t_end = sh->t_end;
  sc->body = VSPH_EQUATIONS_BODY_NONE;
  sc->U_max = sh->U0;
  sc->dp_max = 0.0;
  struct vsph_walls wl = {.n = 0, .rho0 = sc->rho0, .c0 = sc->c0};
  if (vsph_walls_add_periodic(&wl, 0, -sh->W, sh->W) ||
      vsph_walls_add_periodic(&wl, 1, 0.0, sh->Ly) ||
      vsph_walls_add_periodic(&wl, 2, 0.0, sh->Lz))
    return VSPH_EINVAL;
  sc->walls = wl;
  sc->box_lo[0] = -2.0 * sh->W;
  sc->box_hi[0] = 2.0 * sh->W;
  sc->box_lo[1] = -sh->Ly;
  sc->box_hi[1] = 2.0 * sh->Ly;
  sc->box_lo[2] = -sh->Lz;
  sc->box_hi[2] = 2.0 * sh->Lz;
  return VSPH_OK;
}

/* A simple cubic lattice of spacing D0 = W/res, (i + 1/2) D0 from each
 * face, so that no particle sits on the interface or a symmetry plane;
 * y and z spaced to fill their periods exactly. */
static int init(const struct vsph_scene *sc, size_t res,
                struct vsph_particles **out) {
  const struct vsph_scene_shear *sh = &sc->u.shear;
  const double d0 = sh->W / (double)res;
  const size_t nx = 2 * res;
  const size_t ny = (size_t)fmax(1.0, nearbyint(sh->Ly / d0));
  const size_t nz = (size_t)fmax(1.0, nearbyint(sh->Lz / d0));
  if ((double)nx * (double)ny * (double)nz > 1e9)
    VSPH_FAIL(VSPH_EINVAL, "shear: %zu x %zu x %zu particles is too many", nx,
              ny, nz);
  const double dy = sh->Ly / (double)ny, dz = sh->Lz / (double)nz;
  struct vsph_particles *p = vsph_particles_alloc(nx * ny * nz, 3);
  if (!p) return VSPH_ENOMEM;
  if (sc->nmat > 1 && vsph_particles_mat_alloc(p)) {
    vsph_particles_free(p);
    return VSPH_ENOMEM;
  }
  for (size_t k = 0; k < nz; k++)
    for (size_t j = 0; j < ny; j++)
      for (size_t i = 0; i < nx; i++) {
        const size_t q = p->n++;
        const double x = -sh->W + (i + 0.5) * d0;
        const int m = x > 0.0 ? 0 : 1;
        p->pos[0][q] = x;
        p->pos[1][q] = (j + 0.5) * dy;
        p->pos[2][q] = (k + 0.5) * dz;
        p->vel[0][q] = p->vel[2][q] = 0.0;
        p->vel[1][q] = x > 0.0 ? sh->U0 : -sh->U0;
        p->vol[q] = d0 * dy * dz;
        p->rho[q] = sc->mat[sc->nmat > 1 ? m : 0].rho0;
        p->m[q] = p->rho[q] * p->vol[q];
        p->p[q] = 0.0;
        if (p->mat) p->mat[q] = (unsigned char)m;
      }
  *out = p;
  return VSPH_OK;
}

const struct vsph_scene_type vsph_shear_type = {
    .name = "shear",
    .description =
        "shear layer of one or two materials (Parshikov et al.), "
        "3-D",
    .length_name = "W",
    .area = 0.05,
    .params = shear_params,
    .nparams = sizeof shear_params / sizeof shear_params[0],
    .setup = setup,
    .init = init,
    .solver_defaults = solver_defaults,
};
