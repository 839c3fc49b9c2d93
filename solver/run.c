/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "run.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/scratch.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "integrate.h"
#include "lattice.h"
#include "materials.h"
#include "particles.h"
#include "viscous.h"

/* The "Solver" section: the one place of each default, bound and meaning
 * (vsph scenes, vsph run --help and used_parameters.yml read it). */
/* What the section is read into: the settings, and the names that
 * vsph_run_props_init resolves into the settings they name (struct
 * vsph_run_props holds each setting once, as what its name resolves to). */
struct solver_read {
  struct vsph_run_props rp;
  char visc[VSPH_PARAMS_NAME_MAX], kernel[VSPH_PARAMS_NAME_MAX],
      eos[VSPH_PARAMS_NAME_MAX], correction[VSPH_PARAMS_NAME_MAX],
      density[VSPH_PARAMS_NAME_MAX], integrator[VSPH_PARAMS_NAME_MAX],
      scheme[VSPH_PARAMS_NAME_MAX];
};
#define P struct solver_read
/* a setting read as it is: its field in rp, its key the field's name */
#define REAL_SPEC(field, def_, lo_, hi_, help_)                          \
  {                                                                      \
    .key = #field, .kind = VSPH_PARAMS_REAL, .def = (def_), .lo = (lo_), \
    .hi = (hi_), .offset = offsetof(struct solver_read, rp.field),       \
    .help = (help_)                                                      \
  }
#define INT_SPEC(field, def_, lo_, hi_, help_)                          \
  {                                                                     \
    .key = #field, .kind = VSPH_PARAMS_INT, .def = (def_), .lo = (lo_), \
    .hi = (hi_), .offset = offsetof(struct solver_read, rp.field),      \
    .help = (help_)                                                     \
  }
static const struct vsph_params_spec SOLVER[] = {
    VSPH_PARAMS_NAME_SPEC(P, visc, "mgf",
                          "viscous formulation: " VSPH_VISCOUS_NAMES
                          " (docs/theory.md sections 3 and 8: vi, cleary, "
                          "takeda(0), twopass are Basa et al.'s models C, D, "
                          "A, B); scheme wcsph only"),
    REAL_SPEC(xi, VSPH_VISCOUS_XI_CLEARY, 0.1, 100.0,
              "Cleary's coefficient xi (visc = cleary only; "
              "4.96333 Cleary, 4.24 Basa et al.)"),
    REAL_SPEC(zeta, 0.0, 0.0, 1e6,
              "bulk viscosity over the shear viscosity, zeta/mu "
              "(visc = er only; 0: MEAF in 2-D)"),
    VSPH_PARAMS_NAME_SPEC(P, kernel, "gaussian",
                          "gaussian, cubic, quintic, wendland2, wendland4"),
    INT_SPEC(res, 40, 4, 4000,
             "particles across the reference length (R, L, H, W "
             "or S)"),
    REAL_SPEC(hdx, VSPH_CONSTS_HDX, 0.5, 8.0, "h/dx"),
    REAL_SPEC(t_end, 0.0, 0.0, 1e9, "end time (s); 0: the scene's"),
    REAL_SPEC(cfl, 1.0, 1e-3, 4.0,
              "Courant number of the RK4 time step (the "
              "standing wave's and the vortex patch's own: 2; tvf: "
              "dt = cfl/4 h/(c0 + |u|max); contact: cfl/2)"),
    REAL_SPEC(dt, 0.0, 0.0, 1e9,
              "a fixed time step (s) in place of the rule's "
              "(cfl), stable or not: a run it makes unstable "
              "stops cleanly (Vukcevic et al. fix 1e-6 s); 0: "
              "the rule"),
    REAL_SPEC(delta, 0.0, 0.0, 1.0,
              "delta-SPH coefficient; 0: off (0.1 is usual)"),
    REAL_SPEC(relax, 0.0, 0.0, 1e3,
              "relaxed start: the particles first settle at rest "
              "for this long (s), their velocity damped with the "
              "time constant relax/20, then take the scene's "
              "initial velocity where they settled (scenes whose "
              "initial state is at rest but for the velocity: "
              "the standing wave); 0: start on the lattice"),
    REAL_SPEC(rho_band, 0.2, 1e-6, 10.0,
              "stop as unstable when |rho/rho0 - 1| exceeds it"),
    REAL_SPEC(min_gap, 0.05, 0.0, 0.99,
              "stop as unstable when two particles come closer "
              "than min_gap dx (pairing)"),
    INT_SPEC(outputs, 200, 1, 1e6, "energy rows over the run"),
    INT_SPEC(snapshots, 10, 0, 1e4,
             "VTK snapshots over the run (at most outputs); 0: "
             "none"),
    REAL_SPEC(perturb, 0.0, 0.0, 0.49,
              "random shift of the initial lattice, fraction of "
              "dx"),
    INT_SPEC(seed, VSPH_CONSTS_SEED, 0, 4294967295.0,
             "seed of that shift (mt19937)"),
    INT_SPEC(max_steps, 1e8, 1, 1e12,
             "refuse a run estimated to need more steps; stop "
             "one that reaches it"),
    REAL_SPEC(max_memory, VSPH_CONSTS_MAX_MEMORY, 1e-3, 4096,
              "refuse a run estimated to need more memory (GiB)"),
    REAL_SPEC(checkpoint_s, 600.0, 0.0, 1e9,
              "wall time (s) between checkpoints of a run in a "
              "folder (runs/rundir; 0: only on SIGTERM/SIGINT); "
              "not part of the cache key"),
    VSPH_PARAMS_NAME_SPEC(P, eos, "linear",
                          "state equation: linear (c0^2 (rho - rho0)), tait "
                          "(gamma 7), gas (ideal gas, gamma 1.4, with the "
                          "energy equation) or isothermal (c0^2 rho, the "
                          "absolute pressure: Morris et al. 1997); only "
                          "linear with gravity"),
    REAL_SPEC(p0, 0.0, 0.0, 1e9,
              "gas: reference pressure (Pa), c0 = sqrt(1.4 "
              "p0/rho0); 0: p0 = rho0 c0^2/1.4 from the scene's "
              "c0"),
    INT_SPEC(reduce, 0, 0, 1,
             "1: Basa et al.'s local pressure reduction (p_i + "
             "p_j - 2 pbar_i in the pressure gradient)"),
    VSPH_PARAMS_NAME_SPEC(P, correction, "none",
                          "Basa et al.'s kernel-gradient correction of "
                          "every term: none, shepard ([0]) or bonetlok "
                          "([1]); the corrigible forms only "
                          "(" VSPH_VISCOUS_CORRIGIBLE_NAMES ")"),
    INT_SPEC(tvf, 0, 0, 1,
             "1: the transport-velocity scheme (Adami, Hu & "
             "Adams 2013: density by summation, background "
             "pressure, kick-drift-kick at cfl/4); scenes with "
             "wall particles (cavity); the pair forms and the "
             "Laplacians (the table of formulations)"),
    REAL_SPEC(pb, 0.0, 0.0, 1e12,
              "tvf: background pressure (Pa); 0: rho0 c0^2"),
    VSPH_PARAMS_NAME_SPEC(P, density, "continuity",
                          "the density: continuity (integrated) or "
                          "summation (rho_i = sum_j m_j W_ij over the fluid "
                          "and the ghosts or wall particles, before each "
                          "evaluation; Basa et al.'s choice); tvf sums "
                          "always; not with scheme contact"),
    VSPH_PARAMS_NAME_SPEC(P, integrator, "rk4",
                          "time stepping: rk4 (classical Runge-Kutta) or "
                          "leapfrog (drift-kick-drift at cfl/4, Vukcevic et "
                          "al.'s eq. 22); tvf has its own kick-drift-kick"),
    REAL_SPEC(xsph, 0.0, 0.0, 1.0,
              "XSPH's epsilon: the particles drift with u + eps "
              "sum_j (m_j/rho_j) (u_j - u_i) W_ij (Vukcevic et "
              "al. 0.3); leapfrog only, not with the cavity's "
              "wall particles; 0: off"),
    VSPH_PARAMS_NAME_SPEC(P, scheme, "wcsph",
                          "wcsph (THEORY 5 with the viscous formulation "
                          "visc) or contact (Parshikov et al.'s Godunov-type "
                          "SPH: the acoustic Riemann solution between each "
                          "pair, the contact viscous stress; a visc given "
                          "with it is refused, as it would have no effect)"),
    REAL_SPEC(alpha, 0.0, 0.0, 4.0,
              "contact: h = 2 alpha dx (Parshikov's h_ij = "
              "alpha (D_i + D_j) at the initial spacing); 0: "
              "h = hdx dx"),
    REAL_SPEC(zeta_num, 0.0, 0.0, 1.0,
              "contact: the fraction zeta of the numerical "
              "viscosity removed by the correcting tensor"),
    REAL_SPEC(eta_num, 0.0, 0.0, 10.0,
              "contact: the numerical viscosity over Z dx; 0: "
              "Parshikov's fit, eq. (37), at alpha = h/(2 dx)"),
    INT_SPEC(probe_points, 0, 0, VSPH_RUN_PROBES_MAX,
             "probes evenly on the segment (probe_x0, probe_y0) "
             "to (probe_x1, probe_y1), ends included; 1: the "
             "point (probe_x0, probe_y0); each output row, "
             "into probes.csv (the Shepard-normalised kernel "
             "interpolation of the fluid's velocity, pressure "
             "and density); 0: none"),
    REAL_SPEC(probe_x0, 0.0, -1e9, 1e9, "first probe's x (m)"),
    REAL_SPEC(probe_y0, 0.0, -1e9, 1e9, "first probe's y (m)"),
    REAL_SPEC(probe_x1, 0.0, -1e9, 1e9,
              "last probe's x (m); probe_points >= 2"),
    REAL_SPEC(probe_y1, 0.0, -1e9, 1e9,
              "last probe's y (m); probe_points >= 2"),
    REAL_SPEC(probe_z, 0.0, -1e9, 1e9, "the probes' z (m); 3-D scenes only"),
};

/* The probe keys apply to probes: a coordinate given with none, or a
 * segment's end given with one point, would have no effect. */
static int check_probes(const struct vsph_run_props *rp,
                        const struct vsph_params *prm) {
  static const char *const KEYS[] = {"probe_x0", "probe_y0", "probe_x1",
                                     "probe_y1", "probe_z"};
  if (rp->probe_points >= 2 && (!vsph_params_given(prm, "Solver:probe_x1") ||
                                !vsph_params_given(prm, "Solver:probe_y1")))
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:probe_points = %zu puts probes on a segment: give its "
              "end, Solver:probe_x1 and probe_y1",
              rp->probe_points);
  for (size_t k = 0; k < sizeof KEYS / sizeof KEYS[0]; k++) {
    char key[40];
    snprintf(key, sizeof key, "Solver:%s", KEYS[k]);
    if (!vsph_params_given(prm, key)) continue;
    if (rp->probe_points == 0)
      VSPH_FAIL(VSPH_EINVAL,
                "Solver:%s has no effect without Solver:probe_points", KEYS[k]);
    if (rp->probe_points == 1 && k >= 2 && k < 4)
      VSPH_FAIL(VSPH_EINVAL,
                "Solver:%s has no effect with one probe (probe_points = 1 "
                "reads the point (probe_x0, probe_y0))",
                KEYS[k]);
  }
  return VSPH_OK;
}

/* The sound speed of the run: the scene's, or the gas law's at p0. */
static double run_c0(const struct vsph_run_props *rp,
                     const struct vsph_scene *sc) {
  if (rp->eos_kind == VSPH_EQUATIONS_EOS_GAS && rp->p0 > 0.0)
    return sqrt(VSPH_EQUATIONS_GAS_GAMMA * rp->p0 / sc->rho0);
  return sc->c0;
}
#undef P
#undef REAL_SPEC
#undef INT_SPEC

const struct vsph_params_spec *vsph_run_params(size_t *n) {
  if (!n) return NULL;
  *n = sizeof SOLVER / sizeof SOLVER[0];
  return SOLVER;
}

/* The settings given by name, resolved into @p rp (what they name). */
static int resolve_names(const struct solver_read *nm,
                         struct vsph_run_props *rp) {
  int st;
  if ((st = vsph_viscous_resolve(nm->visc, &rp->form)) ||
      (st = vsph_kernel_resolve(nm->kernel, &rp->ktype)) ||
      (st = vsph_equations_eos_resolve(nm->eos, &rp->eos_kind)) ||
      (st = vsph_equations_corr_resolve(nm->correction, &rp->corr)) ||
      (st = vsph_equations_scheme_resolve(nm->scheme, &rp->scheme_kind)))
    return st;
  if (!strcmp(nm->density, "summation"))
    rp->summation = 1;
  else if (strcmp(nm->density, "continuity"))
    VSPH_FAIL(VSPH_EINVAL,
              "unknown Solver:density '%s' (continuity or summation)",
              nm->density);
  if (!strcmp(nm->integrator, "leapfrog"))
    rp->leapfrog = 1;
  else if (strcmp(nm->integrator, "rk4"))
    VSPH_FAIL(VSPH_EINVAL, "unknown Solver:integrator '%s' (rk4 or leapfrog)",
              nm->integrator);
  return VSPH_OK;
}

int vsph_run_props_for_scene(struct vsph_run_props *rp,
                             const struct vsph_scene_type *type,
                             struct vsph_params *prm) {
  if (!rp || !type || !prm)
    VSPH_FAIL(VSPH_EINVAL, "vsph_run_props_for_scene: a NULL argument");
  const int st = vsph_scene_solver_defaults(type, prm);
  return st ? st : vsph_run_props_init(rp, prm);
}

int vsph_run_props_init(struct vsph_run_props *out, struct vsph_params *prm) {
  if (!out) VSPH_FAIL(VSPH_EINVAL, "vsph_run_props_init: a NULL argument");
  memset(out, 0, sizeof *out);
  struct solver_read sr;
  memset(&sr, 0, sizeof sr);
  struct vsph_run_props *const rp = &sr.rp;
  int st = vsph_params_load(prm, "Solver", SOLVER,
                            sizeof SOLVER / sizeof SOLVER[0], &sr, sizeof sr);
  if (!st) st = resolve_names(&sr, rp);
  if (st) return st;
  const char *const visc = sr.visc;
  char pair_forms[256];
  vsph_viscous_list(VSPH_VISCOUS_CORRIGIBLE, pair_forms, sizeof pair_forms);
  if (rp->corr != VSPH_PAIR_CORR_NONE && !vsph_viscous_corrigible(rp->form))
    VSPH_FAIL(
        VSPH_EINVAL,
        "Solver:correction = %s applies to the corrigible forms (%s), not %s",
        sr.correction, pair_forms, visc);
  if (rp->tvf &&
      (!(vsph_viscous_type_get(rp->form)->flags & VSPH_VISCOUS_TVF) ||
       rp->corr != VSPH_PAIR_CORR_NONE || rp->reduce || rp->delta > 0.0 ||
       rp->eos_kind != VSPH_EQUATIONS_EOS_LINEAR)) {
    char tvf_forms[256];
    vsph_viscous_list(VSPH_VISCOUS_TVF, tvf_forms, sizeof tvf_forms);
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:tvf = 1 takes one of %s with the linear law and no "
              "correction, reduction or delta, not visc = %s",
              tvf_forms, visc);
  }
  const int contact = rp->scheme_kind == VSPH_EQUATIONS_CONTACT;
  /* contact SPH has no viscous form: its pairs take the Riemann solution
   * and the contact viscous stress, so a visc given with it would be
   * silently unused (and PVWF's two supports asked for periods it does not
   * need) */
  if (contact && vsph_params_given(prm, "Solver:visc"))
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:visc = %s has no effect with Solver:scheme = contact "
              "(its pairs take the Riemann solution and the contact viscous "
              "stress, not a viscous form): drop visc, or choose scheme "
              "wcsph",
              visc);
  if (!contact && (rp->alpha > 0.0 || rp->zeta_num > 0.0 || rp->eta_num > 0.0))
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:alpha, zeta_num and eta_num apply to Solver:scheme = "
              "contact only");
  if (contact && (rp->tvf || rp->corr != VSPH_PAIR_CORR_NONE || rp->reduce ||
                  rp->delta > 0.0 || rp->eos_kind != VSPH_EQUATIONS_EOS_LINEAR))
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:scheme = contact takes the linear law and no tvf, "
              "correction, reduction or delta (its Riemann solution does "
              "their work)");
  if (contact && rp->alpha > 0.0) {
    if (!(2.0 * rp->alpha >= 0.5))
      VSPH_FAIL(VSPH_EINVAL, "Solver:alpha = %g is below 0.25 (h < dx/2)",
                rp->alpha);
    rp->hdx = 2.0 * rp->alpha;
  }
  if (rp->pb > 0.0 && !rp->tvf)
    VSPH_FAIL(VSPH_EINVAL, "Solver:pb applies to Solver:tvf = 1 only");
  if (contact && rp->summation)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:density = summation does not apply to Solver:scheme = "
              "contact (its density follows the Riemann solution's strain "
              "rate)");
  if (rp->p0 > 0.0 && rp->eos_kind != VSPH_EQUATIONS_EOS_GAS)
    VSPH_FAIL(VSPH_EINVAL, "Solver:p0 applies to Solver:eos = gas only");
  if (rp->leapfrog && (rp->tvf || contact))
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:integrator = leapfrog does not apply with tvf = 1 or "
              "scheme contact (each has its own stepping)");
  if (rp->leapfrog && rp->eos_kind == VSPH_EQUATIONS_EOS_GAS)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:integrator = leapfrog takes a barotropic law, not gas");
  if (rp->xsph > 0.0 && !rp->leapfrog)
    VSPH_FAIL(VSPH_EINVAL, "Solver:xsph needs Solver:integrator = leapfrog");
  if ((st = check_probes(rp, prm))) return st;
  rp->probe_z_given = vsph_params_given(prm, "Solver:probe_z");
  if (rp->snapshots > rp->outputs)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:snapshots (%zu) must not exceed "
              "Solver:outputs (%zu)",
              rp->snapshots, rp->outputs);
  *out = *rp;
  return VSPH_OK;
}

/* Outputs due at the current state, advancing the schedule past it. A row
 * (not for a state stopped as unstable: it may hold non-finite values) and
 * a snapshot are due at the first step end at or past each multiple of
 * their interval, and at the end; a snapshot is otherwise taken at its own
 * time before the step that would pass it (vsph_run_iterate). */
static unsigned schedule(struct vsph_run *r) {
  const double t = vsph_run_time(r);
  const int final = r->state == VSPH_RUN_DONE;
  const int unstable = r->state == VSPH_RUN_UNSTABLE;
  unsigned due = 0;
  if (t >= r->next_out * (1.0 - 1e-12) || final || unstable) {
    if (!unstable) due |= VSPH_RUN_ROW;
    while (r->next_out <= t * (1.0 + 1e-12)) r->next_out += r->out_dt;
  }
  if (r->props.snapshots > 0 &&
      (t >= r->next_snap * (1.0 - 1e-12) || final || unstable)) {
    due |= VSPH_RUN_SNAPSHOT;
    while (r->next_snap <= t * (1.0 + 1e-12)) r->next_snap += r->snap_dt;
  }
  return due;
}

/* The settings a scene cannot take together (a law of state that needs
 * confinement, wall particles a scheme has not, ...), refused in one line
 * each; VSPH_OK where none applies. */
static int check_combination(const struct vsph_run_props *rp,
                             const struct vsph_scene *sc) {
  unsigned sides = 0; /* bit 2a + (side > 0): a plane bounds axis a */
  for (int q = 0; q < sc->walls.n; q++)
    sides |= 1u << (2 * sc->walls.axis[q] + (sc->walls.side[q] > 0));
  if ((rp->eos_kind == VSPH_EQUATIONS_EOS_GAS ||
       rp->eos_kind == VSPH_EQUATIONS_EOS_ISOTHERMAL) &&
      sides != (1u << (2 * sc->dim)) - 1u)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:eos = %s needs a confined scene (walls or periodic "
              "ends all round): at rho0 its pressure is p0 > 0, and a free "
              "surface would expand",
              vsph_equations_eos_name(rp->eos_kind));
  if (rp->xsph > 0.0 && sc->walls.solid && sc->walls.solid != VSPH_WALLS_FIXED)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:xsph does not take wall particles yet (%s has them): "
              "their velocities are set per evaluation, the drift reads them "
              "after the kick",
              sc->type->name);
  if (rp->relax > 0.0 && (!sc->type->rest_velocity || rp->tvf || rp->leapfrog ||
                          rp->scheme_kind == VSPH_EQUATIONS_CONTACT))
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:relax needs a scene whose initial state is at rest "
              "but for its velocity (the standing wave), run by RK4 with "
              "WCSPH; %s%s cannot start relaxed",
              sc->type->name,
              sc->type->rest_velocity ? " with this scheme or integrator" : "");
  if (rp->probe_z_given && sc->dim < 3)
    VSPH_FAIL(VSPH_EINVAL, "Solver:probe_z applies to 3-D scenes, not %s",
              sc->type->name);
  if (rp->probe_points > 0) { /* the segment's ends within the scene's box */
    const double ends[2][3] = {
        {rp->probe_x0, rp->probe_y0, rp->probe_z},
        {rp->probe_points > 1 ? rp->probe_x1 : rp->probe_x0,
         rp->probe_points > 1 ? rp->probe_y1 : rp->probe_y0, rp->probe_z}};
    static const char *const AX[2][3] = {{"probe_x0", "probe_y0", "probe_z"},
                                         {"probe_x1", "probe_y1", "probe_z"}};
    for (int e = 0; e < 2; e++)
      for (int a = 0; a < sc->dim; a++)
        if (!(ends[e][a] >= sc->box_lo[a] && ends[e][a] <= sc->box_hi[a]))
          VSPH_FAIL(VSPH_EINVAL,
                    "Solver:%s = %g lies outside %s's box, %g to %g along "
                    "that axis",
                    AX[e][a], ends[e][a], sc->type->name, sc->box_lo[a],
                    sc->box_hi[a]);
  }
  if (rp->tvf && sc->walls.solid != VSPH_WALLS_ADAMI)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:tvf = 1 needs a scene with Adami et al.'s wall "
              "particles (cavity with Scene:walls = adami), not %s",
              sc->type->name);
  if (rp->scheme_kind == VSPH_EQUATIONS_CONTACT && sc->walls.solid)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:scheme = contact has no wall particles (%s has them)",
              sc->type->name);
  if (rp->scheme_kind != VSPH_EQUATIONS_CONTACT && sc->nmat > 1)
    VSPH_FAIL(VSPH_EINVAL,
              "%s holds two materials: it needs Solver:scheme = contact",
              sc->type->name);
  if (sc->walls.solid == VSPH_WALLS_ADAMI &&
      rp->eos_kind != VSPH_EQUATIONS_EOS_LINEAR)
    VSPH_FAIL(VSPH_EINVAL,
              "the wall particles of %s need Solver:eos = linear (their "
              "density is the linear law's; Scene:walls = evolving takes "
              "tait or isothermal)",
              sc->type->name);
  if (sc->walls.solid == VSPH_WALLS_EVOLVING &&
      rp->eos_kind == VSPH_EQUATIONS_EOS_GAS)
    VSPH_FAIL(VSPH_EINVAL,
              "evolving wall particles take Solver:eos = linear, tait or "
              "isothermal, not gas");
  if (rp->eos_kind != VSPH_EQUATIONS_EOS_LINEAR &&
      sc->body == VSPH_EQUATIONS_BODY_GRAVITY)
    VSPH_FAIL(VSPH_EINVAL,
              "Solver:eos = %s needs a scene without gravity (the ghosts' "
              "hydrostatic density follows the linear law)",
              vsph_equations_eos_name(rp->eos_kind));
  return VSPH_OK;
}

/* Refuse, before allocating anything, a run that would not fit in
 * rp->max_memory or would need more than rp->max_steps steps, saying the
 * estimate. Steps: t_end over THEORY 5's time step at t = 0 with the
 * scene's U_max and largest body force. */
static int check_cost(const struct vsph_run_props *rp,
                      const struct vsph_scene *sc, double t_end,
                      struct vsph_run_estimate *e) {
  const double dx = sc->ref_length / (double)rp->res, h = rp->hdx * dx;
  const double n =
      sc->area * pow((double)rp->res, sc->dim) + 4.0 * (double)rp->res;
  /* ghosts: a layer of reach/dx + 1 particles along each wall, over at
   * most twice the fluid's side (n^((d-1)/d)), corners included */
  /* fixed wall particles' periodic images reach two supports too */
  const double deep = rp->scheme_kind == VSPH_EQUATIONS_CONTACT ? 1.0
                      : sc->walls.solid == VSPH_WALLS_FIXED
                          ? fmax(2.0, vsph_viscous_passes(rp->form))
                          : vsph_viscous_passes(rp->form);
  for (int a = 0; a < sc->dim; a++) {
    const double L = vsph_walls_period(&sc->walls, a);
    const double reach = deep * rp->ktype->kappa * h;
    if (L > 0.0 && !(L > 1.25 * reach))
      VSPH_FAIL(VSPH_EINVAL,
                "the periodic length %g m is too short for the kernel's "
                "reach %g m%s: lengthen the period (the scene's length, Ly or "
                "Lz) or raise res",
                L, reach,
                deep > 1 ? " (two supports for a two-pass form or fixed wall "
                           "particles)"
                         : "");
  }
  const double layers = ceil(deep * rp->ktype->kappa * rp->hdx) + 1.0;
  e->neighbours = (sc->dim == 2 ? VSPH_PI : 4.0 * VSPH_PI / 3.0) *
                  pow(rp->ktype->kappa * rp->hdx, sc->dim) * deep;
  const double ghosts =
      sc->walls.n * layers * 2.0 * pow(n, (sc->dim - 1.0) / sc->dim);
  /* the lattice the scene lays, which the integrator takes */
  /* with snapshots, the state a snapshot within a step is reached from,
   * kept while it is written: in a scratch file, but counted for where
   * none can be made (vsph_integrate_pack_lean's arrays:
   * positions, velocities, m, rho, id; V and p with wall particles or
   * the transport velocity, and its two vectors; the gas law's energy;
   * the material, one byte counted as a double) */
  const double side =
      rp->snapshots > 0
          ? (n + ghosts) * 8.0 *
                (2.0 * sc->dim + 4.0 +
                 (rp->tvf || sc->walls.solid ? 2.0 : 0.0) +
                 (rp->tvf ? 2.0 * sc->dim : 0.0) +
                 (rp->eos_kind == VSPH_EQUATIONS_EOS_GAS ? 1.0 : 0.0))
          : 0.0;
  const double bytes =
      vsph_integrate_bytes_estimate(sc->dim, n, ghosts,
                                    rp->corr != VSPH_PAIR_CORR_NONE
                                        ? 2
                                        : vsph_viscous_first_pass(rp->form),
                                    (int)rp->tvf) +
      side;
  e->particles = n;
  e->bytes = bytes;
  const double gib = bytes / (1024.0 * 1024.0 * 1024.0);
  if (gib > rp->max_memory)
    VSPH_FAIL(VSPH_EINVAL,
              "res %zu needs up to about %.3g GiB (%.3g particles), more than "
              "Solver:max_memory = %g GiB: lower res or raise max_memory",
              rp->res, gib, n, rp->max_memory);
  const int bad = check_combination(rp, sc);
  if (bad) return bad;
  const double gmax = sc->body == VSPH_EQUATIONS_BODY_GRAVITY ? fabs(sc->g)
                      : sc->body == VSPH_EQUATIONS_BODY_RADIAL
                          ? sc->beta * sc->beta * sc->ref_length
                      : sc->body == VSPH_EQUATIONS_BODY_UNIFORM ? fabs(sc->f)
                                                                : 0.0;
  const double rule = vsph_integrate_dt_rule(
      rp->cfl,
      rp->leapfrog ? 2
      : rp->tvf    ? 1
                   : 0,
      rp->scheme_kind == VSPH_EQUATIONS_CONTACT, h, run_c0(rp, sc), sc->U_max,
      sc->mu / sc->rho0, gmax);
  const double dt = rp->dt > 0 ? rp->dt : rule;
  const double steps = t_end / dt;
  e->steps = steps;
  if (!(steps <= (double)rp->max_steps))
    VSPH_FAIL(VSPH_EINVAL,
              "the run needs about %.3g steps (dt = %.3g s to t_end = %g s), "
              "more than Solver:max_steps = %zu: shorten t_end or raise "
              "max_steps",
              steps, dt, t_end, rp->max_steps);
  return VSPH_OK;
}

int vsph_run_estimate(const struct vsph_run_props *rp,
                      const struct vsph_scene *sc,
                      struct vsph_run_estimate *e) {
  if (!rp || !sc || !e)
    VSPH_FAIL(VSPH_EINVAL, "vsph_run_estimate: a NULL argument");
  return check_cost(rp, sc, rp->t_end > 0 ? rp->t_end : sc->t_end, e);
}

/* The relaxed start (Solver:relax, docs/theory.md section 5): the fluid
 * at rest, its density and pressure the scene's, runs for relax seconds
 * with its velocity damped after each step by exp(-dt/tau), tau =
 * relax/20 (a drag -u/tau: an underdamped mode's amplitude falls by
 * e^(-T/(2 tau)) = e^-10 over the relaxation; an overdamped slow mode of
 * angular frequency w decays as e^(-w^2 tau T) = e^(-20 w^2 tau^2), so it
 * settles where w^2 tau^2 is not much below 1/20: the standing wave's own
 * mode, w tau of about 0.55 at relax = 2 s, is near critical); then the
 * clock is set back to 0 and each fluid particle takes the scene's
 * initial velocity where it settled, with the density it settled to. A
 * relaxation that goes unstable is an error (the run cannot start). */
static int relax(struct vsph_run *r) {
  struct vsph_integrate *s = r->integ;
  struct vsph_particles *p = s->p;
  const double T = r->props.relax, tau = T / 20.0;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] < r->n_fluid)
      for (int k = 0; k < p->dim; k++) p->vel[k][i] = 0.0;
  while (s->t < T * (1.0 - 1e-12)) {
    double dt = vsph_integrate_dt(s);
    if (s->t + dt > T) dt = T - s->t;
    int st = vsph_integrate_step(s, dt);
    if (st) return st;
    if (vsph_integrate_check(s))
      VSPH_FAIL(VSPH_EFAIL, "the relaxed start went unstable at t = %.3g s: %s",
                s->t, s->reason);
    const double damp = exp(-dt / tau);
    for (size_t i = 0; i < p->n; i++)
      if (p->id[i] < r->n_fluid)
        for (int k = 0; k < p->dim; k++) p->vel[k][i] *= damp;
  }
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= r->n_fluid) continue;
    double x[3] = {0.0, 0.0, 0.0}, u[3];
    for (int k = 0; k < p->dim; k++) x[k] = p->pos[k][i];
    r->scene.type->rest_velocity(&r->scene, x, u);
    for (int k = 0; k < p->dim; k++) p->vel[k][i] = u[k];
  }
  s->t = 0.0;
  s->steps = 0;
  return VSPH_OK;
}

int vsph_run_alloc(const struct vsph_run_props *rp, const struct vsph_scene *sc,
                   struct vsph_run **out) {
  if (!rp || !sc || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_run_alloc: a NULL argument");
  *out = NULL;
  struct vsph_run_estimate e;
  const int cost =
      check_cost(rp, sc, rp->t_end > 0 ? rp->t_end : sc->t_end, &e);
  if (cost) return cost;
  struct vsph_run *r = calloc(1, sizeof *r);
  if (!r) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a run");
  r->props = *rp;
  r->scene = *sc;
  struct vsph_particles *fluid = NULL;
  int st = sc->type->init(&r->scene, rp->res, &fluid);
  if (st) goto fail;
  r->dx = r->scene.ref_length / (double)rp->res;
  r->h = rp->hdx * r->dx;
  r->t_end = rp->t_end > 0 ? rp->t_end : r->scene.t_end;
  if (rp->perturb > 0 &&
      (st = vsph_lattice_perturb(fluid, rp->perturb * r->dx,
                                 (unsigned long)rp->seed, (size_t)-1)))
    goto fail;
  struct vsph_integrate_props ip;
  if ((st = vsph_scene_integrate_props(&r->scene, rp->form, rp->ktype, r->h,
                                       &ip)))
    goto fail;
  ip.cfl = rp->cfl;
  ip.dt = rp->dt;
  ip.rho_band = rp->rho_band;
  ip.min_dist = rp->min_gap * r->dx;
  ip.eq.delta = rp->delta;
  ip.eq.visc.xi = rp->xi;
  ip.eq.visc.zeta = rp->zeta * ip.eq.visc.mu;
  ip.eq.eos = rp->eos_kind;
  ip.eq.c0 = run_c0(rp, &r->scene);
  ip.eq.reduce = (int)rp->reduce;
  ip.eq.corr = rp->corr;
  ip.eq.tvf = (int)rp->tvf;
  ip.eq.summation = rp->summation || rp->tvf;
  ip.leapfrog = rp->leapfrog;
  ip.xsph = rp->xsph;
  ip.eq.pb = rp->pb > 0.0 ? rp->pb : ip.eq.rho0 * ip.eq.c0 * ip.eq.c0;
  if (rp->tvf && (st = vsph_particles_tvf_alloc(fluid))) goto fail;
  if (rp->scheme_kind == VSPH_EQUATIONS_CONTACT) {
    /* each material's numerical viscosity, eta_num = k Z D0 with k from
     * eq. (37) at alpha = h/(2 dx) unless given */
    const double k = rp->eta_num > 0.0
                         ? rp->eta_num
                         : vsph_materials_eta_num_fit(0.5 * rp->hdx);
    ip.eq.scheme = VSPH_EQUATIONS_CONTACT;
    ip.eq.zeta_num = rp->zeta_num;
    ip.eq.nmat = r->scene.nmat > 0 ? r->scene.nmat : 1;
    if (r->scene.nmat > 0)
      for (int m = 0; m < ip.eq.nmat; m++) ip.eq.mat[m] = r->scene.mat[m];
    else
      ip.eq.mat[0] = (struct vsph_equations_mat){
          .rho0 = ip.eq.rho0, .c0 = ip.eq.c0, .mu = ip.eq.visc.mu};
    for (int m = 0; m < ip.eq.nmat; m++) /* none for a body held fixed */
      ip.eq.mat[m].eta_num =
          ip.eq.mat[m].fixed ? 0.0
                             : k * ip.eq.mat[m].rho0 * ip.eq.mat[m].c0 * r->dx;
  }
  if (rp->eos_kind == VSPH_EQUATIONS_EOS_GAS) { /* p = p0 rho/rho0 at t = 0 */
    if ((st = vsph_particles_energy_alloc(fluid))) goto fail;
    for (size_t i = 0; i < fluid->n; i++)
      fluid->e[i] = vsph_equations_gas_e0(&ip.eq);
  }
  r->n_fluid = fluid->n;
  r->integ = vsph_integrate_alloc(&ip, fluid); /* takes fluid */
  fluid = NULL;
  if (!r->integ) {
    st = VSPH_ENOMEM;
    goto fail;
  }
  if (rp->relax > 0.0 && (st = relax(r))) goto fail;
  r->out_dt = r->t_end / (double)rp->outputs;
  r->snap_dt =
      rp->snapshots > 0 ? r->t_end / (double)rp->snapshots : (double)INFINITY;
  r->state = VSPH_RUN_RUNNING;
  r->due = schedule(r);
  *out = r;
  return VSPH_OK;
fail:
  vsph_particles_free(fluid);
  vsph_run_free(r);
  return st;
}

void vsph_run_free(struct vsph_run *r) {
  if (!r) return;
  vsph_integrate_free(r->integ);
  free(r->side);
  if (r->side_file) fclose(r->side_file);
  free(r);
}

/* The time of the snapshot nearest @p t: t_end k / snapshots, and where
 * that is a round decimal to 15 significant digits within two rounding
 * errors, the double nearest the decimal (0.1 x 3 / 4 = 0.07500000000000001
 * becomes 0.075's double; 0.1 / 3 stays as it is). */
static double snap_time(const struct vsph_run *r, double t) {
  const double exact =
      r->t_end * nearbyint(t / r->snap_dt) / (double)r->props.snapshots;
  char txt[32];
  snprintf(txt, sizeof txt, "%.15g", exact);
  const double dec = strtod(txt, NULL);
  return fabs(dec - exact) <= 2.0 * DBL_EPSILON * fabs(exact) ? dec : exact;
}

/* The step's start kept (r->side_len bytes, vsph_integrate_pack_lean's)
 * while a snapshot within the step is written: in an unlinked scratch
 * file (vsph_scratch_open), out of the run's memory (the kept state would
 * otherwise add its 7 doubles a particle to the run's peak), or where
 * none can be written, in memory (r->side). */
static int side_keep(struct vsph_run *r) {
  const struct vsph_integrate *s = r->integ;
  /* TMPDIR; memory where the file system cannot unlink an open file */
  FILE *f = vsph_scratch_open(NULL, "vsph-state-", NULL);
  if (f) {
    const size_t len = vsph_integrate_pack_lean_file(s, f);
    if (len) {
      r->side_file = f;
      r->side_len = len;
      return VSPH_OK;
    }
    fclose(f);
  }
  const size_t len = vsph_integrate_pack_lean(s, NULL);
  unsigned char *buf = malloc(len);
  if (!buf) VSPH_FAIL(VSPH_ENOMEM, "cannot keep the state for a snapshot");
  vsph_integrate_pack_lean(s, buf);
  r->side = buf;
  r->side_len = len;
  return VSPH_OK;
}

/* Whether a step's start is kept. */
static int side_kept(const struct vsph_run *r) {
  return r->side != NULL || r->side_file != NULL;
}

/* Forget the kept state. */
static void side_drop(struct vsph_run *r) {
  free(r->side);
  if (r->side_file) fclose(r->side_file);
  r->side = NULL;
  r->side_file = NULL;
  r->side_len = 0;
}

/* Back from a snapshot's own time to the state it was reached from. */
static int side_back(struct vsph_run *r) {
  const int st =
      r->side_file
          ? vsph_integrate_restore_file(r->integ, r->side_file, r->side_len)
          : vsph_integrate_restore(r->integ, r->side, r->side_len);
  side_drop(r);
  return st;
}

/* The state at the snapshot time r->side_t: the current state kept
 * (side_keep: what a step reads), then, where r->side_t lies beyond the
 * current time (strictly within the coming step), a step of its own to it
 * (the time set to it exactly, the step count left as it was: the run's
 * steps are those of its path); then one evaluation, so that its
 * pressures, ghosts and wall particles are this state's, as an energy row
 * leaves them (a step leaves its last stage's). The next vsph_run_iterate
 * puts the kept state back. Interruptible 0: a stop is not seen within
 * the step (the restore of a checkpoint taken there). VSPH_OK; or the
 * state put back as it was and 1 where the step went unstable (the
 * snapshot then waits for the step's end, as any other output),
 * VSPH_EINTR where it was stopped, or an internal failure. */
static int side_step(struct vsph_run *r, int interruptible) {
  struct vsph_integrate *s = r->integ;
  const size_t steps = s->steps;
  int st = side_keep(r);
  if (st) return st;
  if (r->side_t > s->t * (1.0 + 1e-12)) {
    const volatile sig_atomic_t *stop = s->stop;
    if (!interruptible) s->stop = NULL;
    st = vsph_integrate_step(s, r->side_t - s->t);
    s->stop = stop;
    /* unstable, whether or not the step also failed, as the run's own
     * step judges it (vsph_run_iterate) */
    const int bad = st != VSPH_EINTR && vsph_integrate_check(s);
    if (st || bad) {
      const int back = side_back(r);
      return back ? back : bad ? 1 : st;
    }
  }
  s->t = r->side_t;
  s->steps = steps;
  struct vsph_equations_energy en;
  struct vsph_equations_budget b;
  st = vsph_integrate_diagnostics(s, &en, &b);
  r->evaluated = st == VSPH_OK;
  return st;
}

int vsph_run_iterate(struct vsph_run *r) {
  if (!r) VSPH_FAIL(VSPH_EINVAL, "vsph_run_iterate: a NULL argument");
  r->due = 0;
  r->evaluated = 0;
  if (side_kept(r)) {
    const int back = side_back(r);
    if (back) return back;
  }
  if (r->state != VSPH_RUN_RUNNING) return VSPH_OK;
  struct vsph_integrate *s = r->integ;
  double dt = vsph_integrate_dt(s);
  if (s->t + dt > r->t_end) dt = r->t_end - s->t;
  /* a snapshot strictly within this step (beyond the schedule's 1e-12
   * at its end): first the state at its own time */
  if (r->props.snapshots > 0 && s->t + dt > r->next_snap * (1.0 + 1e-12)) {
    r->side_t = snap_time(r, r->next_snap);
    const int side = side_step(r, 1);
    if (side == VSPH_OK) {
      r->due = VSPH_RUN_SNAPSHOT;
      while (r->next_snap <= r->side_t * (1.0 + 1e-12))
        r->next_snap += r->snap_dt;
      return VSPH_OK;
    }
    if (side != 1) return side;
  }
  const int st = vsph_integrate_step(s, dt);
  if (st == VSPH_EINTR) return st; /* put back as the step found it */
  r->pairs += (double)s->interactions;
  int bad = vsph_integrate_check(s);
  if (st && !bad) return st; /* a failure of the code, not of the run */
  if (!bad && s->steps >= r->props.max_steps) {
    snprintf(s->reason, sizeof s->reason,
             "step limit: Solver:max_steps = %zu reached at dt = %.3g s",
             r->props.max_steps, dt);
    bad = 1;
  }
  if (bad) {
    r->state = VSPH_RUN_UNSTABLE;
    r->t_unstable = s->t;
    snprintf(r->reason, sizeof r->reason, "%s", s->reason);
  } else if (s->t >= r->t_end * (1.0 - 1e-12)) {
    r->state = VSPH_RUN_DONE;
  }
  r->due = schedule(r);
  /* a snapshot on this step's end, the run going on and no row here to
   * evaluate the state: evaluated aside, at its round time, and put back
   * (an evaluation between steps moves the path at rounding) */
  if (r->due == VSPH_RUN_SNAPSHOT && r->state == VSPH_RUN_RUNNING) {
    r->side_t = snap_time(r, s->t);
    const int side = side_step(r, 1);
    if (side) return side;
  }
  return VSPH_OK;
}

int vsph_run_row(struct vsph_run *r, struct vsph_run_row *row) {
  if (!r || !row) VSPH_FAIL(VSPH_EINVAL, "vsph_run_row: a NULL argument");
  row->t = vsph_run_time(r);
  const int st = vsph_integrate_diagnostics(r->integ, &row->en, &row->b);
  r->evaluated = st == VSPH_OK;
  return st;
}

double vsph_run_time(const struct vsph_run *r) {
  return r ? r->integ->t : (double)NAN;
}

size_t vsph_run_steps(const struct vsph_run *r) {
  return r ? r->integ->steps : 0;
}

size_t vsph_run_bytes(const struct vsph_run *r) {
  if (!r) return 0;
  return vsph_integrate_bytes(r->integ);
}

size_t vsph_run_fallbacks(const struct vsph_run *r) {
  if (!r) return 0;
  return r->integ->vws ? r->integ->vws->n_fallback : 0;
}

/* The driver's own state beside the integrator's. */
struct run_state {
  double t_unstable, pairs, out_dt, snap_dt, next_out, next_snap, t_end;
  int32_t due, state;
  char reason[160];
  double side_t;       /* with side 1: packed at a snapshot's own time, the */
  int32_t side, spare; /* integrator's state that of the step's start */
};

size_t vsph_run_pack(const struct vsph_run *r, unsigned char *buf) {
  if (!r) return 0;
  struct run_state rs;
  memset(&rs, 0, sizeof rs);
  rs.t_unstable = r->t_unstable;
  rs.pairs = r->pairs;
  rs.out_dt = r->out_dt;
  rs.snap_dt = r->snap_dt;
  rs.next_out = r->next_out;
  rs.next_snap = r->next_snap;
  rs.t_end = r->t_end;
  rs.due = (int32_t)r->due;
  rs.state = r->state;
  memcpy(rs.reason, r->reason, sizeof rs.reason);
  rs.side = side_kept(r);
  rs.side_t = r->side_t;
  if (buf) memcpy(buf, &rs, sizeof rs);
  if (r->side && buf) /* the state the snapshot's is made again from */
    memcpy(buf + sizeof rs, r->side, r->side_len);
  if (r->side_file && buf &&
      (fseek(r->side_file, 0, SEEK_SET) ||
       fread(buf + sizeof rs, 1, r->side_len, r->side_file) != r->side_len))
    return 0; /* cannot be read back */
  if (side_kept(r)) return sizeof rs + r->side_len;
  return sizeof rs +
         vsph_integrate_pack(r->integ, buf ? buf + sizeof rs : NULL);
}

int vsph_run_unpack(struct vsph_run *r, const unsigned char *buf, size_t len) {
  if (!r || !buf) VSPH_FAIL(VSPH_EINVAL, "vsph_run_unpack: a NULL argument");
  struct run_state rs;
  if (len < sizeof rs) VSPH_FAIL(VSPH_EINVAL, "the saved state is cut short");
  memcpy(&rs, buf, sizeof rs);
  /* the schedule must be this run's, to the bit */
  if (memcmp(&rs.out_dt, &r->out_dt, sizeof rs.out_dt) ||
      memcmp(&rs.t_end, &r->t_end, sizeof rs.t_end) ||
      (rs.state != VSPH_RUN_RUNNING && rs.state != VSPH_RUN_DONE &&
       rs.state != VSPH_RUN_UNSTABLE) ||
      (rs.due & ~(int32_t)(VSPH_RUN_ROW | VSPH_RUN_SNAPSHOT)) ||
      (rs.side != 0 && rs.side != 1))
    VSPH_FAIL(VSPH_EINVAL, "the saved state is not this run's");
  size_t used = 0;
  const int st =
      vsph_integrate_unpack(r->integ, buf + sizeof rs, len - sizeof rs, &used);
  if (st) return st;
  if (used != len - sizeof rs)
    VSPH_FAIL(VSPH_EINVAL, "the saved state has %zu bytes too many",
              len - sizeof rs - used);
  r->t_unstable = rs.t_unstable;
  r->pairs = rs.pairs;
  r->snap_dt = rs.snap_dt;
  r->next_out = rs.next_out;
  r->next_snap = rs.next_snap;
  r->due = (unsigned)rs.due; /* what its driver had not yet written */
  r->state = rs.state;
  memcpy(r->reason, rs.reason, sizeof rs.reason);
  r->reason[sizeof r->reason - 1] = '\0';
  side_drop(r);
  r->side_t = rs.side_t;
  r->evaluated = 0;
  /* packed at a snapshot's own time: that state made again, to the bit,
   * from the step's start, whatever a stop asks meanwhile */
  const int side = rs.side ? side_step(r, 0) : VSPH_OK;
  if (side == 1) /* went unstable where it had not */
    VSPH_FAIL(VSPH_EINVAL,
              "the saved state's snapshot at t = %.10g s cannot be made again",
              rs.side_t);
  return side;
}
