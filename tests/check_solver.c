/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Solver regression tests (issue 3): short runs at low resolution with
 * tolerances tied to theory or to the measured behaviour. */
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../analysis/references.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/files.h"
#include "../io/vtk.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/diagnostics.h"
#include "../solver/integrate.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "check_suites.h"

/* A scene at res particles across, h/dx = 4/3, 3h Gaussian, CFL 1. */
static struct vsph_integrate *make_run(const char *scene, int form, size_t res,
                                       struct vsph_scene *sc,
                                       const char *set_key,
                                       const char *set_val) {
  struct vsph_params *prm = vsph_params_alloc();
  if (set_key) ck_assert_int_eq(vsph_params_set(prm, set_key, set_val), 0);
  ck_assert_int_eq(vsph_scene_init(sc, vsph_scene_find(scene), prm), 0);
  vsph_params_free(prm);
  struct vsph_particles *fluid = NULL;
  ck_assert_int_eq(sc->type->init(sc, res, &fluid), 0);
  const double h = 4.0 / 3.0 * sc->ref_length / (double)res;
  struct vsph_integrate_props ip;
  ck_assert_int_eq(
      vsph_scene_integrate_props(sc, form, &vsph_gaussian_type, h, &ip), 0);
  ip.cfl = 1.0;
  ip.rho_band = 0.2;
  ip.min_dist = 0.05 * sc->ref_length / (double)res;
  struct vsph_integrate *s = vsph_integrate_alloc(&ip, fluid);
  ck_assert_ptr_nonnull(s);
  return s;
}

/* The standing wave with MGF at @p res across after one step (its state
 * evaluated, its ghosts and cell list made), @p sc kept for it. */
static struct vsph_integrate *stepped_wave(struct vsph_scene *sc, size_t res) {
  struct vsph_integrate *s =
      make_run("standing-wave", VSPH_VISCOUS_MGF, res, sc, NULL, NULL);
  ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
  return s;
}

/* Stretching square at t = 0 against dE_k/dt = -4 mu A0^2 L^2 (THEORY
 * 6.2): PVWF within 1 % (exact discrete identity), MGF within 10 % (its
 * lattice error, -6 %, partly offset by the surface deficit: +1.2 %
 * measured at L/dx = 40), MEAF between 40 and 60 % (P_grad is half). */
START_TEST(test_stretching_initial_power) {
  const double exact = -4.0 * 0.05 * 1.0 * 1.0; /* mu A0^2 L^2, rho0 = 1 */
  double ratio[3];
  for (int form = 0; form < 3; form++) {
    struct vsph_scene sc;
    struct vsph_integrate *s =
        make_run("stretching-square", form, 40, &sc, NULL, NULL);
    struct vsph_equations_energy en;
    struct vsph_equations_budget b;
    ck_assert_int_eq(vsph_integrate_diagnostics(s, &en, &b), 0);
    ratio[form] = b.P_visc / exact;
    vsph_integrate_free(s);
  }
  ck_assert_double_lt(fabs(ratio[VSPH_VISCOUS_PVWF] - 1.0), 0.01);
  ck_assert_double_lt(fabs(ratio[VSPH_VISCOUS_MGF] - 1.0), 0.10);
  ck_assert_double_ge(ratio[VSPH_VISCOUS_MEAF], 0.40);
  ck_assert_double_le(ratio[VSPH_VISCOUS_MEAF], 0.60);
}
END_TEST

/* The stretching square's initial pressure: by default the Poisson
 * solution, whose centre value is 2 rho A0^2 times the torsion function's
 * maximum on the unit square, 0.0736713 L^2 (Timoshenko & Goodier; the
 * boundary values +-2 mu A0 cancel at the centre by symmetry), here
 * within 1 % (the FFT grid's and the lattice's interpolation error, 0.2 %
 * measured at L/dx = 40); with Scene:pressure=0 zero everywhere (the flow
 * then settles it by sound waves; issue 43's runs measure what that
 * costs). */
START_TEST(test_stretching_initial_pressure) {
  for (int zero = 0; zero < 2; zero++) {
    struct vsph_scene sc;
    struct vsph_integrate *s = make_run("stretching-square", 0, 40, &sc,
                                        zero ? "Scene:pressure" : NULL, "0");
    const struct vsph_particles *p = s->p;
    double pc = 0, rc = INFINITY, pmax = 0;
    for (size_t i = 0; i < s->n_fluid; i++) {
      const double pr = sc.c0 * sc.c0 * (p->rho[i] - sc.rho0);
      const double r = hypot(p->pos[0][i], p->pos[1][i]);
      pmax = fmax(pmax, fabs(pr));
      if (r < rc) rc = r, pc = pr;
    }
    if (zero)
      ck_assert_double_eq(pmax, 0.0);
    else
      ck_assert_double_lt(fabs(pc / (2 * 0.0736713) - 1), 0.01);
    vsph_integrate_free(s);
  }
}
END_TEST

/* Vortex patch: over 200 RK4 steps MGF and PVWF conserve the angular
 * momentum to 1e-10 relative. Their pair forces are torque-free, so the
 * semi-discrete system conserves L_z exactly; what remains is RK4's error
 * on this bilinear invariant, O(dt^4) over the run: measured 3.1e-10,
 * 4.4e-11, 1.1e-11 at R/dx = 16, 24, 32, hence R/dx = 24 here. MEAF does
 * not conserve it (measured 1.5e-2). MEAF also dissipates more than MGF
 * (it dissipates the rotation). */
START_TEST(test_vortex_angular_momentum) {
  double dL[3], P0[3];
  for (int form = 0; form < 3; form++) {
    struct vsph_scene sc;
    struct vsph_integrate *s =
        make_run("vortex-patch", form, 24, &sc, NULL, NULL);
    struct vsph_equations_energy e0, e1;
    struct vsph_equations_budget b;
    ck_assert_int_eq(vsph_integrate_diagnostics(s, &e0, &b), 0);
    P0[form] = b.P_visc;
    for (int k = 0; k < 200; k++) {
      ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
      ck_assert_int_eq(vsph_integrate_check(s), 0);
    }
    vsph_equations_energy_compute(&s->props.eq, s->p, s->n_fluid, &e1);
    dL[form] = fabs(e1.Lz - e0.Lz) / fabs(e0.Lz);
    vsph_integrate_free(s);
  }
  ck_assert_double_lt(dL[VSPH_VISCOUS_MGF], 1e-10);
  ck_assert_double_lt(dL[VSPH_VISCOUS_PVWF], 1e-10);
  ck_assert_double_gt(dL[VSPH_VISCOUS_MEAF], 1e-3);
  ck_assert_double_gt(fabs(P0[VSPH_VISCOUS_MEAF]), fabs(P0[VSPH_VISCOUS_MGF]));
}
END_TEST

/* The energy budget closes without walls and delta-SPH: the
 * PVW-compatible pressure/continuity pair conserves E_k + E_c exactly at
 * the semi-discrete level, so d(E_k + E_p + E_c)/dt - P_visc is rounding
 * (1e-10 of P_visc); with delta-SPH on, P_delta closes it the same way. */
START_TEST(test_budget_residual) {
  const char *scenes[2] = {"stretching-square", "vortex-patch"};
  for (int sci = 0; sci < 2; sci++)
    for (int delta = 0; delta < 2; delta++) {
      struct vsph_scene sc;
      struct vsph_integrate *s =
          make_run(scenes[sci], VSPH_VISCOUS_MGF, 20, &sc, NULL, NULL);
      s->props.eq.delta = delta ? 0.1 : 0.0;
      for (int k = 0; k < 5; k++)
        ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
      struct vsph_equations_energy en;
      struct vsph_equations_budget b;
      ck_assert_int_eq(vsph_integrate_diagnostics(s, &en, &b), 0);
      ck_assert_double_lt(fabs(b.residual), 1e-10 * fabs(b.P_visc));
      if (delta) ck_assert_double_ne(b.P_delta, 0.0);
      vsph_integrate_free(s);
    }
}
END_TEST

/* Standing wave at H/dx = 40: E_k oscillates with period pi/omega (THEORY
 * 6.3, Lighthill); the minima of E_k (where 1 + cos 2 omega t vanishes) are
 * located by a parabola through the three samples around each, and their
 * spacing must match pi/omega within 2 % (measured +0.30 %). */
START_TEST(test_standing_wave_period) {
  struct vsph_scene sc;
  struct vsph_integrate *s =
      make_run("standing-wave", VSPH_VISCOUS_MGF, 40, &sc, NULL, NULL);
  const double omega = sc.u.wave.omega, half = VSPH_PI / omega;
  double tq[3] = {0}, eq[3] = {0}, minima[4];
  int nmin = 0;
  while (s->t < 1.9 * half && nmin < 2) {
    ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
    ck_assert_int_eq(vsph_integrate_check(s), 0);
    struct vsph_equations_energy en;
    vsph_equations_energy_compute(&s->props.eq, s->p, s->n_fluid, &en);
    tq[0] = tq[1], eq[0] = eq[1];
    tq[1] = tq[2], eq[1] = eq[2];
    tq[2] = s->t, eq[2] = en.Ek;
    if (s->steps >= 3 && eq[1] < eq[0] && eq[1] <= eq[2]) {
      /* vertex of the parabola through the three points */
      const double a =
          (eq[2] - eq[1]) / (tq[2] - tq[1]) - (eq[1] - eq[0]) / (tq[1] - tq[0]);
      const double b = (eq[1] - eq[0]) / (tq[1] - tq[0]);
      const double m0 = 0.5 * (tq[0] + tq[1]), m1 = 0.5 * (tq[1] + tq[2]);
      minima[nmin++] = m0 - b * (m1 - m0) / a;
    }
  }
  vsph_integrate_free(s);
  ck_assert_int_eq(nmin, 2);
  ck_assert_double_eq_tol(minima[1] - minima[0], half, 0.02 * half);
  ck_assert_double_eq_tol(minima[0], 0.5 * half, 0.05 * half);
}
END_TEST

/* One and two threads give bitwise-identical states after a few steps
 * (gather loops; exact integer and min reductions), walls included, for
 * every formulation (_i, the form's id; MGF with delta-SPH), at the
 * CPU's SIMD level, on the standing wave at 16 across: one block of the
 * sweep for most forms (test_groups_threads_bitwise, in the equations
 * suite, takes several blocks at every level). */
START_TEST(test_threads_bitwise) {
  double *state[2];
  size_t n = 0;
  const int threads = omp_get_max_threads();
  for (int t = 0; t < 2; t++) {
    omp_set_num_threads(t + 1);
    struct vsph_scene sc;
    struct vsph_integrate *s =
        make_run("standing-wave", _i, 16, &sc, NULL, NULL);
    if (_i == VSPH_VISCOUS_MGF) s->props.eq.delta = 0.1;
    for (int k = 0; k < 5; k++)
      ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
    n = s->n_fluid;
    state[t] = malloc(5 * n * sizeof(double));
    for (size_t i = 0; i < s->p->n; i++) {
      const size_t id = s->p->id[i];
      if (id >= n) continue;
      state[t][id] = s->p->pos[0][i];
      state[t][n + id] = s->p->pos[1][i];
      state[t][2 * n + id] = s->p->vel[0][i];
      state[t][3 * n + id] = s->p->vel[1][i];
      state[t][4 * n + id] = s->p->rho[i];
    }
    vsph_integrate_free(s);
  }
  omp_set_num_threads(threads);
  ck_assert_int_eq(memcmp(state[0], state[1], 5 * n * sizeof(double)), 0);
  free(state[0]);
  free(state[1]);
}
END_TEST

/* Fluid at rest under gravity between free-slip walls stays at rest: the
 * hydrostatic ghost correction balances the pressure gradient. Over 200
 * steps the largest speed stays below 1 % of sqrt(g H) (measured 3.9e-4 at
 * H/dx = 20). */
START_TEST(test_hydrostatic_rest) {
  struct vsph_scene sc;
  struct vsph_integrate *s =
      make_run("standing-wave", VSPH_VISCOUS_MGF, 20, &sc, NULL, NULL);
  for (size_t i = 0; i < s->p->n; i++) s->p->vel[0][i] = s->p->vel[1][i] = 0;
  for (int k = 0; k < 200; k++)
    ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
  double vmax = 0.0;
  for (size_t i = 0; i < s->p->n; i++)
    if (s->p->id[i] < s->n_fluid)
      vmax = fmax(vmax, hypot(s->p->vel[0][i], s->p->vel[1][i]));
  const double scale = sqrt(sc.g * sc.ref_length);
  ck_assert_msg(vmax < 0.01 * scale, "max speed %g of sqrt(gH) = %g", vmax,
                scale);
  vsph_integrate_free(s);
}
END_TEST

/* A run pushed past RK4's stability limit stops cleanly: the check
 * reports a reason, nothing crashes. Measured limit on the vortex patch:
 * stable at CFL 3, out of the density band within 8 steps at CFL 4. */
START_TEST(test_unstable_detected) {
  struct vsph_scene sc;
  struct vsph_integrate *s =
      make_run("vortex-patch", VSPH_VISCOUS_MGF, 16, &sc, NULL, NULL);
  s->props.cfl = 4.0;
  int bad = 0;
  for (int k = 0; k < 400 && !bad; k++) {
    const int st = vsph_integrate_step(s, vsph_integrate_dt(s));
    bad = st != 0 || vsph_integrate_check(s);
  }
  ck_assert_msg(bad, "CFL 4 stayed stable");
  ck_assert_uint_gt(strlen(s->reason), 0);
  ck_assert_uint_gt(strlen(s->reason), 0);
  vsph_integrate_free(s);
}
END_TEST

/* With walls the particle set holds the ghosts each step makes, counted
 * before they are made, and grows by half the ghosts and 64 over that (no
 * share of the fluid: every array is zeroed to its capacity, so resident):
 * a standing wave at H/dx = 40 (about 600 ghosts, 5 layers along 3 walls)
 * keeps its capacity within that bound of fluid + ghosts (the 8 of the
 * allocator's rounding, and the ghosts a later step may add: a quarter
 * more), under twice the fluid (the worst case, 3 images per particle, was
 * 4x). Growing keeps the particles' values. */
START_TEST(test_ghost_capacity) {
  struct vsph_scene sc;
  struct vsph_integrate *s =
      make_run("standing-wave", VSPH_VISCOUS_MGF, 40, &sc, NULL, NULL);
  for (int k = 0; k < 3; k++)
    ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
  const size_t n = s->p->n, nf = s->n_fluid;
  ck_assert_uint_gt(n, nf); /* there are ghosts */
  ck_assert_uint_le(s->p->cap, n + (n - nf) / 2 + 64 + 8 + (n - nf) / 4);
  ck_assert_uint_lt(s->p->cap, 2 * nf);
  /* vsph_particles_reserve keeps the n live values */
  struct vsph_particles *p = s->p;
  const double x = p->pos[0][n - 1], r = p->rho[0];
  const size_t id = p->id[n / 2];
  ck_assert_int_eq(vsph_particles_reserve(p, 3 * p->cap), 0);
  ck_assert_uint_ge(p->cap, 3 * n);
  ck_assert(p->pos[0][n - 1] == x && p->rho[0] == r && p->id[n / 2] == id);
  vsph_integrate_free(s);
  /* finer (H/dx = 120: ghosts about a tenth of the set), the slack is the
   * ghosts' share, well under a sixteenth of the set (an eighth of it
   * was the rule before) */
  s = make_run("standing-wave", VSPH_VISCOUS_MGF, 120, &sc, NULL, NULL);
  ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
  const size_t n2 = s->p->n, nf2 = s->n_fluid;
  ck_assert_uint_le(s->p->cap, n2 + (n2 - nf2) / 2 + 64 + 8);
  ck_assert_uint_lt(s->p->cap - n2, n2 / 16);
  vsph_integrate_free(s);
}
END_TEST

/* A particle on a free-slip plane meets its own mirror image there: one
 * fluid element, mirrored, and no pairing (docs/theory.md section 5). The
 * standing wave at rest, H/dx = 10: the particle nearest (L, -H/2) moved
 * to 1e-4 dx from the wall x = L, one step: the step's closest pair (the
 * particle and its image, 2e-4 dx apart) is below the 0.05 dx limit, yet
 * the check lets the run go on. Across a no-slip plane the same stops it
 * (the particle reached the wall); and two distinct particles 0.01 dx
 * apart stop it on either, with the particle at the wall (its own image
 * the closest pair) or not. */
START_TEST(test_own_image) {
  for (int pass = 0; pass < 4; pass++) {
    struct vsph_scene sc;
    struct vsph_integrate *s =
        make_run("standing-wave", VSPH_VISCOUS_MGF, 10, &sc, NULL, NULL);
    struct vsph_particles *p = s->p;
    const double L = sc.ref_length, dx = L / 10.0;
    size_t a = 0, b = 0;
    double best = INFINITY, second = INFINITY;
    for (size_t i = 0; i < p->n; i++) {
      p->vel[0][i] = p->vel[1][i] = 0.0;
      const double d = hypot(p->pos[0][i] - L, p->pos[1][i] + 0.5 * L);
      if (d < best)
        second = best, b = a, best = d, a = i;
      else if (d < second)
        second = d, b = i;
    }
    p->pos[0][a] = L - 1e-4 * dx;
    if (pass == 1) s->props.walls.noslip = 1;
    if (pass == 2) { /* a distinct pair, away from the wall */
      p->pos[0][a] = p->pos[0][b] - 0.01 * dx;
      p->pos[1][a] = p->pos[1][b];
    }
    if (pass == 3) { /* the one at the wall and a distinct pair inside */
      size_t c = a == 0 ? 1 : 0, d = 2;
      while (d == a || d == c) d++;
      p->pos[0][c] = 0.5 * L, p->pos[1][c] = -0.5 * L;
      p->pos[0][d] = 0.5 * L + 0.01 * dx, p->pos[1][d] = -0.5 * L;
    }
    ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
    ck_assert_double_lt(s->min_dist, s->props.min_dist);
    const int bad = vsph_integrate_check(s);
    ck_assert_msg(bad == (pass > 0), "pass %d: %s", pass, s->reason);
    if (pass) ck_assert_ptr_nonnull(strstr(s->reason, "pairing"));
    vsph_integrate_free(s);
  }
}
END_TEST

/* The relaxed start (Solver:relax): the standing wave at H/dx = 10 settles
 * 0.5 s at rest, then its clock reads 0 with no step taken, every fluid
 * particle has the scene's initial velocity where it settled (to the bit:
 * the same function at the same point), and the particles moved, but by
 * far less than a spacing (bound 0.1 dx). Settled means at rest: with
 * hardly a wave (eps = 1e-6) the largest kinetic energy over the next
 * 0.5 s is below a hundredth of the lattice start's (measured 1.3e-9
 * against 4.1e-6 J/m after a 1 s relaxation). A scene whose initial
 * state is not at rest (the vortex patch) refuses it. */
START_TEST(test_relax_settles_then_starts) {
  static const char *const set[] = {"Solver:res=10", "Solver:relax=0.5",
                                    "Solver:t_end=1", NULL};
  struct vsph_scene sc;
  struct vsph_run *run = vsph_test_run(&vsph_standing_wave_type, set, &sc);
  const struct vsph_particles *p = run->integ->p;
  ck_assert_double_eq(run->integ->t, 0.0);
  ck_assert_uint_eq(run->integ->steps, 0);
  /* the lattice it started from */
  struct vsph_particles *lat = NULL;
  ck_assert_int_eq(sc.type->init(&sc, 10, &lat), 0);
  const double dx = sc.ref_length / 10.0;
  double moved = 0.0;
  size_t nf = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= run->n_fluid) continue;
    nf++;
    const size_t j = p->id[i];
    moved = fmax(moved, hypot(p->pos[0][i] - lat->pos[0][j],
                              p->pos[1][i] - lat->pos[1][j]));
    double u[2];
    vsph_standing_wave_velocity(&run->scene.u.wave, p->pos[0][i], p->pos[1][i],
                                u);
    ck_assert(p->vel[0][i] == u[0] && p->vel[1][i] == u[1]);
  }
  ck_assert_uint_eq(nf, lat->n);
  ck_assert_double_gt(moved, 1e-9 * dx);
  ck_assert_double_lt(moved, 0.1 * dx);
  vsph_particles_free(lat);
  vsph_run_free(run);
  /* settled: the spurious motion of a still tank, lattice against relaxed */
  double kmax[2];
  for (int k = 0; k < 2; k++) {
    static const char *const still[2][5] = {
        {"Solver:res=10", "Scene:eps=1e-6", "Solver:t_end=0.5", NULL},
        {"Solver:res=10", "Scene:eps=1e-6", "Solver:t_end=0.5",
         "Solver:relax=1", NULL}};
    struct vsph_run *rs =
        vsph_test_run(&vsph_standing_wave_type, still[k], NULL);
    kmax[k] = 0.0;
    while (rs->state == VSPH_RUN_RUNNING) {
      ck_assert_int_eq(vsph_run_iterate(rs), VSPH_OK);
      const struct vsph_particles *q = rs->integ->p;
      double ek = 0.0;
      for (size_t i = 0; i < q->n; i++)
        if (q->id[i] < rs->n_fluid)
          ek += 0.5 * q->m[i] *
                (q->vel[0][i] * q->vel[0][i] + q->vel[1][i] * q->vel[1][i]);
      kmax[k] = fmax(kmax[k], ek);
    }
    ck_assert_int_eq(rs->state, VSPH_RUN_DONE);
    vsph_run_free(rs);
  }
  ck_assert_double_lt(kmax[1], 0.01 * kmax[0]);
  /* refused where the start is not at rest */
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_set(prm, "Solver:relax", "1"), 0);
  struct vsph_run_props rp;
  struct vsph_scene vs;
  ck_assert_int_eq(vsph_run_props_init(&rp, prm), 0);
  ck_assert_int_eq(vsph_scene_init(&vs, &vsph_vortex_patch_type, prm), 0);
  vsph_params_free(prm);
  vsph_test_silence();
  struct vsph_run *r2 = NULL;
  ck_assert_int_eq(vsph_run_alloc(&rp, &vs, &r2), VSPH_EINVAL);
  ck_assert_ptr_null(r2);
}
END_TEST

/* Each named setting is held once in struct vsph_run_props, as what its
 * name resolves to: every word each setting takes read back from the
 * resolved value by the name functions (the same word), and a word read
 * by vsph_run_props_init lands on its kind; out of range, "unknown". */
START_TEST(test_run_props_names) {
  for (int k = 0; k < VSPH_EQUATIONS_EOS_COUNT; k++) {
    int got = -2;
    ck_assert_int_eq(
        vsph_equations_eos_resolve(vsph_equations_eos_name(k), &got), 0);
    ck_assert_int_eq(got, k);
  }
  for (int k = 0; k < VSPH_EQUATIONS_SCHEME_COUNT; k++) {
    int got = -2;
    ck_assert_int_eq(
        vsph_equations_scheme_resolve(vsph_equations_scheme_name(k), &got), 0);
    ck_assert_int_eq(got, k);
  }
  for (int k = 0; k < VSPH_PAIR_CORR_COUNT; k++) {
    int got = -2;
    ck_assert_int_eq(
        vsph_equations_corr_resolve(vsph_equations_corr_name(k), &got), 0);
    ck_assert_int_eq(got, k);
  }
  ck_assert_str_eq(vsph_equations_eos_name(-1), "unknown");
  ck_assert_str_eq(vsph_equations_scheme_name(VSPH_EQUATIONS_SCHEME_COUNT),
                   "unknown");
  ck_assert_str_eq(vsph_equations_corr_name(VSPH_PAIR_CORR_COUNT), "unknown");
  /* the words as the Solver section reads them */
  static const char *const set[][2] = {
      {"Solver:visc", "meaf"},         {"Solver:kernel", "cubic"},
      {"Solver:eos", "tait"},          {"Solver:correction", "shepard"},
      {"Solver:density", "summation"}, {"Solver:integrator", "leapfrog"}};
  struct vsph_params *prm = vsph_params_alloc();
  for (size_t k = 0; k < sizeof set / sizeof set[0]; k++)
    ck_assert_int_eq(vsph_params_set(prm, set[k][0], set[k][1]), 0);
  struct vsph_run_props rp;
  ck_assert_int_eq(vsph_run_props_init(&rp, prm), 0);
  vsph_params_free(prm);
  ck_assert_str_eq(vsph_viscous_name(rp.form), "meaf");
  ck_assert_str_eq(rp.ktype->name, "cubic");
  ck_assert_str_eq(vsph_equations_eos_name(rp.eos_kind), "tait");
  ck_assert_str_eq(vsph_equations_corr_name(rp.corr), "shepard");
  ck_assert_str_eq(vsph_equations_scheme_name(rp.scheme_kind), "wcsph");
  ck_assert_int_eq(rp.summation, 1);
  ck_assert_int_eq(rp.leapfrog, 1);
  ck_assert_str_eq(vsph_run_method(&rp), "meaf");
  /* the public table's names lie beyond struct vsph_run_props (they are
   * not kept there): vsph_params_load refuses to write past it */
  size_t n = 0;
  const struct vsph_params_spec *spec = vsph_run_params(&n);
  struct {
    struct vsph_run_props rp;
    unsigned char canary[512];
  } guard;
  memset(&guard, 0xA5, sizeof guard);
  vsph_test_silence();
  ck_assert_int_eq(
      vsph_params_load(NULL, "Solver", spec, n, &guard.rp, sizeof guard.rp),
      VSPH_EINVAL);
  for (size_t k = 0; k < sizeof guard.canary; k++)
    ck_assert_uint_eq(guard.canary[k], 0xA5);
}
END_TEST

/* The right-hand side with the cell list against the O(N^2) path. */
START_TEST(test_rhs_cells_vs_direct) {
  struct vsph_scene sc;
  struct vsph_integrate *s =
      make_run("vortex-patch", VSPH_VISCOUS_PVWF, 12, &sc, NULL, NULL);
  struct vsph_particles *p = s->p;
  const size_t n = p->n;
  double *a = malloc(6 * n * sizeof *a);
  struct vsph_equations_out out = {.drho = a, .acc = {a + n, a + 2 * n}};
  struct vsph_cells *c = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build_direct(c, p), 0);
  ck_assert_int_eq(vsph_equations_rhs(&s->props.eq, p, n, c, s->vws, &out), 0);
  double *ref = a + 3 * n; /* by id */
  for (size_t i = 0; i < n; i++) {
    ref[p->id[i]] = a[i];
    ref[n + p->id[i]] = a[n + i];
  }
  ck_assert_int_eq(vsph_cells_build(c, p, 3.0 * s->props.eq.visc.h), 0);
  ck_assert_int_eq(vsph_equations_rhs(&s->props.eq, p, n, c, s->vws, &out), 0);
  double scale = 0.0;
  for (size_t i = 0; i < n; i++) scale = fmax(scale, fabs(a[n + i]));
  for (size_t i = 0; i < n; i++) {
    ck_assert_double_eq_tol(a[i], ref[p->id[i]],
                            1e-12 * fabs(ref[p->id[i]]) + 1e-15);
    ck_assert_double_eq_tol(a[n + i], ref[n + p->id[i]], 1e-12 * scale);
  }
  vsph_cells_free(c);
  free(a);
  vsph_integrate_free(s);
}
END_TEST

/* Diagnostics on a square of particles in rigid rotation u = W(-y, x):
 * per particle the SPH curl is exactly W times div r (both sums are
 * -V F s^2 weighted; an algebraic identity, so to rounding); inside,
 * div r is d = 2 to the lattice error of the 3h Gaussian at h/dx = 4/3
 * (measured 1e-3 here; 1 % allowed), so the vorticity is 2 W; the flag
 * marks the outer row (div r there about 1.1) and no particle more than 3
 * rows in; the set itself is left untouched (same order, same values).
 * Also the snapshot file round trip (io/vtk stores the doubles raw:
 * exact; tests/check_vtk.c tests the format itself). */
START_TEST(test_diagnostics) {
  struct vsph_lattice_props lp = {.dim = 2};
  struct vsph_particles *p = NULL;
  const size_t nac = 30;
  ck_assert_int_eq(vsph_lattice_square(&lp, 1.0, nac, &p), 0);
  const double W = 0.7321, dx = 1.0 / nac, h = 4.0 / 3.0 * dx;
  for (size_t i = 0; i < p->n; i++) {
    p->vel[0][i] = -W * p->pos[1][i];
    p->vel[1][i] = W * p->pos[0][i];
    p->p[i] = 0.1 * (double)i;
  }
  const double x7 = p->pos[0][7];
  struct vsph_diagnostics dg;
  ck_assert_int_eq(
      vsph_diagnostics_compute(p, p->n, &vsph_gaussian_type, h, &dg, NULL), 0);
  ck_assert(p->pos[0][7] == x7 && p->id[7] == 7);
  size_t inner = 0;
  for (size_t i = 0; i < p->n; i++) {
    const size_t id = p->id[i];
    ck_assert_double_eq_tol(dg.vort[2][id], W * dg.divr[id], 1e-12);
    const double xa = fabs(p->pos[0][i]), ya = fabs(p->pos[1][i]);
    const double edge = 0.5 - fmax(xa, ya); /* distance to the edge */
    if (edge > 3 * h) {
      inner++;
      ck_assert_double_eq_tol(dg.divr[id], 2.0, 0.02);
      ck_assert_double_eq_tol(dg.vort[2][id], 2 * W, 0.02 * W);
      ck_assert_int_eq(dg.surf[id], 0);
    }
    if (edge < 0.5 * dx + 1e-12) ck_assert_int_eq(dg.surf[id], 1);
    if (edge > 3.5 * dx) ck_assert_int_eq(dg.surf[id], 0);
  }
  ck_assert_uint_gt(inner, 100);
  /* stopped (the flag raised): VSPH_EINTR, nothing left allocated */
  struct vsph_diagnostics stopped;
  volatile sig_atomic_t stop = 1;
  ck_assert_int_eq(vsph_diagnostics_compute(p, p->n, &vsph_gaussian_type, h,
                                            &stopped, &stop),
                   VSPH_EINTR);
  ck_assert(!stopped.divr && !stopped.surf && !stopped.vort[2]);
  char dir[] = "/tmp/vsph_vtpXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  ck_assert_int_eq(vsph_vtk_write(dir, "s.vtp", p, p->n, 1.25, &dg, NULL), 0);
  char path[64];
  snprintf(path, sizeof path, "%s/s.vtp", dir);
  struct vsph_vtk_snapshot sn;
  ck_assert_int_eq(vsph_vtk_read(path, &sn), 0);
  ck_assert_uint_eq(sn.n, p->n);
  ck_assert_double_eq(sn.t, 1.25);
  for (size_t i = 0; i < p->n; i++) {
    const size_t id = p->id[i];
    ck_assert(sn.pos[3 * id] == p->pos[0][i]);
    ck_assert(sn.vel[3 * id + 1] == p->vel[1][i]);
    ck_assert(sn.p[id] == p->p[i]);
    ck_assert(sn.vort[3 * id + 2] == dg.vort[2][id]);
    ck_assert(sn.divr[id] == dg.divr[id]);
    ck_assert_double_eq(sn.surf[id], dg.surf[id]);
  }
  vsph_vtk_snapshot_free(&sn);
  remove(path);
  rmdir(dir);
  vsph_diagnostics_free(&dg);
  vsph_particles_free(p);
}
END_TEST

/* Probes (solver/diagnostics) on a square lattice [-1/2, 1/2]^2 of 30
 * across, u = a + b x and p = c - d y: at the centre, a lattice point
 * whose support is whole, the kernel's weights are symmetric, so the
 * Shepard interpolation reads the linear fields exactly (to rounding:
 * 1e-12) with fill = sum_j V_j W_j, 1 to the lattice error (1 % as for
 * div r); at a corner the fill is about a quarter (0.25 +- 0.05: the
 * Gaussian's tail cut at 3h, the lattice's half cell); far outside,
 * NaN and 0. Made periodic along x with period 1 (the lattice's rows
 * meet across x = -1/2, 1/2), a probe on that edge reads a whole
 * support: its fill is that of x = 0 (likewise between two columns) to
 * 1e-12, and a constant field exactly. A NULL argument or h <= 0 is refused. */
START_TEST(test_probe_interpolates_linear_fields) {
  struct vsph_lattice_props lp = {.dim = 2};
  struct vsph_particles *p = NULL;
  const size_t nac = 30;
  ck_assert_int_eq(vsph_lattice_square(&lp, 1.0, nac, &p), 0);
  const double dx = 1.0 / nac, h = 4.0 / 3.0 * dx;
  for (size_t i = 0; i < p->n; i++) {
    p->vel[0][i] = 0.3 + 2.0 * p->pos[0][i];
    p->vel[1][i] = -1.5;
    p->p[i] = 7.0 - 4.0 * p->pos[1][i];
    p->rho[i] = 1000.0;
    p->m[i] = 1000.0 * dx * dx;
  }
  /* the lattice's points sit at the cell centres: (k + 1/2) dx - 1/2 */
  const double c0 = 0.5 * dx, zero[3] = {0.0, 0.0, 0.0};
  const double mid[3] = {c0, c0, 0.0};
  struct vsph_diagnostics_probe r;
  ck_assert_int_eq(
      vsph_diagnostics_probe(p, p->n, &vsph_gaussian_type, h, zero, mid, &r),
      0);
  ck_assert_double_eq_tol(r.u[0], 0.3 + 2.0 * c0, 1e-12);
  ck_assert_double_eq_tol(r.u[1], -1.5, 1e-12);
  ck_assert_double_eq(r.u[2], 0.0);
  ck_assert_double_eq_tol(r.p, 7.0 - 4.0 * c0, 1e-12);
  ck_assert_double_eq_tol(r.rho, 1000.0, 1e-9);
  ck_assert_double_eq_tol(r.fill, 1.0, 0.01);
  /* x = 0, between two columns as the edge x = 1/2 is */
  const double between[3] = {0.0, c0, 0.0};
  ck_assert_int_eq(vsph_diagnostics_probe(p, p->n, &vsph_gaussian_type, h, zero,
                                          between, &r),
                   0);
  const double fill_between = r.fill;
  const double corner[3] = {0.5, 0.5, 0.0}, out[3] = {3.0, 0.0, 0.0};
  ck_assert_int_eq(
      vsph_diagnostics_probe(p, p->n, &vsph_gaussian_type, h, zero, corner, &r),
      0);
  ck_assert_double_eq_tol(r.fill, 0.25, 0.05);
  ck_assert_int_eq(
      vsph_diagnostics_probe(p, p->n, &vsph_gaussian_type, h, zero, out, &r),
      0);
  ck_assert(isnan(r.u[0]) && isnan(r.u[2]) && isnan(r.p) && isnan(r.rho) &&
            r.fill == 0.0);
  /* periodic along x: the edge x = 1/2 at the centre's y */
  const double per[3] = {1.0, 0.0, 0.0}, edge[3] = {0.5, c0, 0.0};
  ck_assert_int_eq(
      vsph_diagnostics_probe(p, p->n, &vsph_gaussian_type, h, per, edge, &r),
      0);
  ck_assert_double_eq_tol(r.fill, fill_between, 1e-12);
  ck_assert_double_eq_tol(r.u[1], -1.5, 1e-12);
  ck_assert_int_eq(
      vsph_diagnostics_probe(p, p->n, &vsph_gaussian_type, 0.0, zero, mid, &r),
      VSPH_EINVAL);
  ck_assert_int_eq(vsph_diagnostics_probe(p, p->n, NULL, h, zero, mid, &r),
                   VSPH_EINVAL);
  vsph_particles_free(p);
}
END_TEST

/* The scenes' own Courant number (docs/theory.md 5: the time-step study
 * picks CFL 2 for the standing wave and the vortex patch): it enters the
 * parameters unless Solver:cfl is given, a given visc included (unlike
 * the contact scenes' defaults), and only for the study's runs (WCSPH,
 * RK4, the rule's step: not with contact SPH, the transport velocity,
 * leapfrog or a fixed dt); the others keep the table's 1. Then,
 * through `vsph run`: the default run of the wave is the run at
 * --set Solver:cfl=2 byte for byte (energy.csv), and it takes half the
 * steps of the run at CFL 1 (the rule's dt is linear in the CFL: the
 * counts agree to 1 step over the 0.6 s, where max|u| barely moves). */
static double cfl_of(const char *scene, const char *key, const char *val) {
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_ptr_nonnull(prm);
  if (key) ck_assert_int_eq(vsph_params_set(prm, key, val), 0);
  ck_assert_int_eq(vsph_scene_solver_defaults(vsph_scene_find(scene), prm), 0);
  double cfl;
  ck_assert_int_eq(vsph_params_get_double_or(prm, "Solver:cfl", 1.0, &cfl), 0);
  vsph_params_free(prm);
  return cfl;
}

/* A library caller's run of a scene gets the scene's own Solver defaults
 * through vsph_run_props_for_scene, as `vsph run` does: the shear scene
 * runs contact SPH (vsph_run_props_init alone: the WCSPH scheme), unless
 * the caller names a formulation; applied twice, the same props. */
START_TEST(test_run_props_for_scene) {
  const struct vsph_scene_type *shear = vsph_scene_find("shear");
  ck_assert_ptr_nonnull(shear);
  struct vsph_run_props a, b, c;
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_int_eq(vsph_run_props_init(&a, prm), 0);
  ck_assert_int_eq(a.scheme_kind, VSPH_EQUATIONS_WCSPH);
  ck_assert_int_eq(vsph_run_props_for_scene(&b, shear, prm), 0);
  ck_assert_int_eq(b.scheme_kind, VSPH_EQUATIONS_CONTACT);
  ck_assert_int_eq(vsph_run_props_for_scene(&c, shear, prm), 0);
  ck_assert_int_eq(memcmp(&b, &c, sizeof b), 0);
  vsph_params_free(prm);
  prm = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_set(prm, "Solver:visc", "mgf"), 0);
  ck_assert_int_eq(vsph_run_props_for_scene(&b, shear, prm), 0);
  ck_assert_int_eq(b.scheme_kind, VSPH_EQUATIONS_WCSPH);
  vsph_params_free(prm);
}
END_TEST

static double run_steps(const char *dir, const char *name, const char *set,
                        char *csv, size_t n) {
  char args[600], path[600];
  snprintf(args, sizeof args,
           "run standing-wave --res 10 --t-end 0.6 --snapshots 0 %s --out "
           "%s/%s --quiet",
           set, dir, name);
  struct vsph_test_outcome *o = vsph_test_cli(args);
  ck_assert_msg(o->status == 0, "%s", o->err);
  snprintf(path, sizeof path, "%s/%s/energy.csv", dir, name);
  vsph_test_slurp(path, csv, n);
  static char js[1 << 14];
  snprintf(path, sizeof path, "%s/%s/run.json", dir, name);
  vsph_test_slurp(path, js, sizeof js);
  const char *s = strstr(js, "\"steps\":");
  ck_assert_ptr_nonnull(s);
  return strtod(s + 8, NULL);
}

START_TEST(test_scene_cfl) {
  ck_assert_double_eq(cfl_of("standing-wave", NULL, NULL), 2.0);
  ck_assert_double_eq(cfl_of("vortex-patch", NULL, NULL), 2.0);
  ck_assert_double_eq(cfl_of("vortex-patch", "Solver:visc", "pvwf"), 2.0);
  ck_assert_double_eq(cfl_of("standing-wave", "Solver:cfl", "0.7"), 0.7);
  /* the study's runs alone: WCSPH, RK4, the rule's step */
  ck_assert_double_eq(cfl_of("standing-wave", "Solver:scheme", "wcsph"), 2.0);
  ck_assert_double_eq(cfl_of("vortex-patch", "Solver:scheme", "contact"), 1.0);
  ck_assert_double_eq(cfl_of("standing-wave", "Solver:integrator", "leapfrog"),
                      1.0);
  ck_assert_double_eq(cfl_of("standing-wave", "Solver:tvf", "1"), 1.0);
  ck_assert_double_eq(cfl_of("standing-wave", "Solver:dt", "1e-4"), 1.0);
  ck_assert_double_eq(cfl_of("standing-wave", "Solver:dt", "0.0"), 2.0);
  ck_assert_double_eq(cfl_of("stretching-square", NULL, NULL), 1.0);
  ck_assert_double_eq(cfl_of("poiseuille", NULL, NULL), 1.0);
  ck_assert_double_eq(cfl_of("cavity", NULL, NULL), 1.0);
  char dir[] = "/tmp/vsph_cflXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  static char a[1 << 16], b[1 << 16], c[1 << 16];
  const double na = run_steps(dir, "own", "", a, sizeof a);
  const double nb = run_steps(dir, "two", "--set Solver:cfl=2", b, sizeof b);
  const double nc = run_steps(dir, "one", "--set Solver:cfl=1", c, sizeof c);
  ck_assert_str_eq(a, b);
  ck_assert_double_eq(na, nb);
  ck_assert_double_gt(na, 10.0);
  ck_assert_double_eq_tol(nc, 2.0 * na, 1.0);
  char cmd[700];
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  ck_assert_int_eq(system(cmd), 0);
}
END_TEST

/* vsph_integrate_pack_lean leaves out exactly the rates (d accelerations
 * and d rho/dt a particle, ghosts included) and, where there are no wall
 * particles (the standing wave's walls are ghosts), volume and pressure,
 * which read back as NaN; and two steps from the
 * lean state are bitwise those from the whole one (nothing a step reads
 * was left out; a rate read before it is written would show as NaN). */
START_TEST(test_pack_lean) {
  struct vsph_scene sc;
  struct vsph_integrate *s = stepped_wave(&sc, 12);
  struct vsph_particles *p = s->p;
  const int d = p->dim;
  const size_t nfull = vsph_integrate_pack(s, NULL),
               nlean = vsph_integrate_pack_lean(s, NULL);
  /* the rates, and (no wall particles: the wave's walls are ghosts)
   * volume and pressure */
  ck_assert_uint_eq(nfull - nlean, p->n * (size_t)(d + 3) * sizeof(double));
  unsigned char *full = malloc(nfull), *lean = malloc(nlean);
  ck_assert_ptr_nonnull(full);
  ck_assert_ptr_nonnull(lean);
  ck_assert_uint_eq(vsph_integrate_pack(s, full), nfull);
  ck_assert_uint_eq(vsph_integrate_pack_lean(s, lean), nlean);
  const double dt = vsph_integrate_dt(s);
  double *after[2][3];
  size_t n_after[2];
  for (int k = 0; k < 2; k++) {
    ck_assert_int_eq(k ? vsph_integrate_restore(s, lean, nlean)
                       : vsph_integrate_restore(s, full, nfull),
                     0);
    if (k) /* the rates as the lean state leaves them */
      for (size_t i = 0; i < p->n; i++) {
        ck_assert(isnan(p->drho[i]));
        for (int a = 0; a < d; a++) ck_assert(isnan(p->acc[a][i]));
      }
    for (int st = 0; st < 2; st++)
      ck_assert_int_eq(vsph_integrate_step(s, dt), 0);
    n_after[k] = p->n;
    for (int a = 0; a < d; a++) {
      after[k][a] = malloc(p->n * sizeof(double));
      ck_assert_ptr_nonnull(after[k][a]);
      memcpy(after[k][a], p->vel[a], p->n * sizeof(double));
    }
  }
  ck_assert_uint_eq(n_after[0], n_after[1]);
  for (int a = 0; a < d; a++) {
    ck_assert_mem_eq(after[0][a], after[1][a], n_after[0] * sizeof(double));
    free(after[0][a]);
    free(after[1][a]);
  }
  free(full);
  free(lean);
  vsph_integrate_free(s);
}
END_TEST

/* A saved state whose particle ids are damaged, one equal to the count
 * (within the set's capacity) or one given twice (the map from id to slot
 * is filled in parallel, which two equal ids would race on), is refused
 * by a fresh integrator of the scene (a refused one is to be freed:
 * integrate.h), and the good state is restored and steps on. */
START_TEST(test_restore_refuses_bad_ids) {
  struct vsph_scene sc;
  struct vsph_integrate *s = stepped_wave(&sc, 12);
  struct vsph_particles *p = s->p;
  const size_t n = vsph_integrate_pack(s, NULL);
  unsigned char *buf[3] = {malloc(n), malloc(n), malloc(n)}; /* good, bad */
  for (int k = 0; k < 3; k++) ck_assert_ptr_nonnull(buf[k]);
  ck_assert_uint_eq(vsph_integrate_pack(s, buf[0]), n);
  ck_assert_uint_lt(p->n, p->cap); /* the map has room past the count */
  /* bad 1: id[1] repeats id[0]; bad 2: the last id one past the count */
  size_t *const at[2] = {&p->id[1], &p->id[p->n - 1]};
  const size_t was[2] = {*at[0], *at[1]}, put[2] = {p->id[0], p->n};
  for (int k = 0; k < 2; k++) {
    *at[k] = put[k];
    ck_assert_uint_eq(vsph_integrate_pack(s, buf[k + 1]), n);
    *at[k] = was[k];
  }
  vsph_integrate_free(s);
  for (int k = 0; k < 3; k++) {
    s = make_run("standing-wave", VSPH_VISCOUS_MGF, 12, &sc, NULL, NULL);
    ck_assert_int_eq(vsph_integrate_restore(s, buf[k], n),
                     k ? VSPH_EINVAL : VSPH_OK);
    if (!k) ck_assert_int_eq(vsph_integrate_step(s, vsph_integrate_dt(s)), 0);
    vsph_integrate_free(s);
    free(buf[k]);
  }
}
END_TEST

/* The diagnostics of a run's evaluated state on its own cell list
 * (vsph_diagnostics_compute_cells, no copy) are bitwise those of the
 * sorted copy, and both do not move by a bit when the particles come in
 * the opposite order (each sum runs over the neighbours in the order of
 * their offsets); a cell list narrower than the kernel is refused. */
START_TEST(test_diagnostics_order) {
  struct vsph_scene sc;
  struct vsph_integrate *s = stepped_wave(&sc, 16);
  struct vsph_equations_energy en;
  struct vsph_equations_budget bu;
  ck_assert_int_eq(vsph_integrate_diagnostics(s, &en, &bu), 0);
  struct vsph_particles *p = s->p;
  const struct vsph_kernel_type *k = s->props.eq.visc.kernel;
  const double h = s->props.eq.visc.h;
  const size_t nf = s->n_fluid;
  struct vsph_diagnostics a, b, c, r;
  ck_assert_int_eq(
      vsph_diagnostics_compute_cells(p, nf, s->cells, k, h, NULL, &a, NULL), 0);
  ck_assert_int_eq(vsph_diagnostics_compute(p, nf, k, h, &b, NULL), 0);
  /* into the rates (free between steps), as a run's snapshot does: the
   * same bits, and the lent arrays not freed (vsph_integrate_free frees
   * them: a double free would abort) */
  double *const room[4] = {p->acc[0], p->acc[1], NULL, p->drho};
  ck_assert_int_eq(
      vsph_diagnostics_compute_cells(p, nf, s->cells, k, h, room, &r, NULL), 0);
  ck_assert(r.divr == p->acc[0] && r.vort[2] == p->acc[1]);
  ck_assert_mem_eq(a.vort[2], r.vort[2], nf * sizeof(double));
  ck_assert_mem_eq(a.divr, r.divr, nf * sizeof(double));
  ck_assert_mem_eq(a.surf, r.surf, nf);
  /* the file through the integrator's map: the same bytes as through an
   * order of its own; a map that is not the particles' is refused */
  char dir[] = "/tmp/vsph_mappedXXXXXX", fa[64], fb[64], fc[64];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  snprintf(fa, sizeof fa, "%s/a.vtp", dir);
  snprintf(fb, sizeof fb, "%s/b.vtp", dir);
  snprintf(fc, sizeof fc, "%s/c.vtp", dir);
  ck_assert_int_eq(vsph_vtk_write(dir, "a.vtp", p, nf, s->t, &r, NULL), 0);
  ck_assert_int_eq(
      vsph_vtk_write_mapped(dir, "b.vtp", p, nf, s->where, s->t, &r, NULL), 0);
  size_t la, lb;
  char *ta = vsph_files_slurp(fa, &la), *tb = vsph_files_slurp(fb, &lb);
  ck_assert(ta && tb && la == lb && !memcmp(ta, tb, la));
  free(ta);
  free(tb);
  const size_t w0 = s->where[0];
  s->where[0] = s->where[1];
  ck_assert_int_eq(
      vsph_vtk_write_mapped(dir, "c.vtp", p, nf, s->where, s->t, &r, NULL),
      VSPH_EINVAL);
  s->where[0] = w0;
  ck_assert_int_ne(access(fc, F_OK), 0);
  ck_assert_int_eq(remove(fa), 0);
  ck_assert_int_eq(remove(fb), 0);
  ck_assert_int_eq(rmdir(dir), 0);
  vsph_diagnostics_free(&r);
  /* the arrays the sums read, reversed */
  const int d = p->dim;
  double *f[8];
  int nfd = 0;
  for (int q = 0; q < d; q++) f[nfd++] = p->pos[q], f[nfd++] = p->vel[q];
  f[nfd++] = p->vol;
  for (size_t i = 0, j = p->n - 1; i < j; i++, j--) {
    for (int q = 0; q < nfd; q++) {
      const double t = f[q][i];
      f[q][i] = f[q][j];
      f[q][j] = t;
    }
    const size_t t = p->id[i];
    p->id[i] = p->id[j];
    p->id[j] = t;
  }
  ck_assert_int_eq(vsph_diagnostics_compute(p, nf, k, h, &c, NULL), 0);
  const struct vsph_diagnostics *o[2] = {&b, &c};
  for (int q = 0; q < 2; q++) {
    ck_assert_mem_eq(a.vort[2], o[q]->vort[2], nf * sizeof(double));
    ck_assert_mem_eq(a.divr, o[q]->divr, nf * sizeof(double));
    ck_assert_mem_eq(a.surf, o[q]->surf, nf);
  }
  size_t surface = 0;
  for (size_t i = 0; i < nf; i++) surface += a.surf[i];
  ck_assert_uint_gt(surface, 0); /* the free surface is there */
  vsph_diagnostics_free(&a);
  vsph_diagnostics_free(&b);
  vsph_diagnostics_free(&c);
  struct vsph_diagnostics e;
  ck_assert_int_eq(vsph_diagnostics_compute_cells(p, nf, s->cells, k, 3.0 * h,
                                                  NULL, &e, NULL),
                   VSPH_EINVAL);
  vsph_integrate_free(s);
}
END_TEST

/* The same in 3-D (a contact run of the shear layer, evaluated by its
 * first row): the vorticity's three components and div r written into
 * the rates (room[2], room[3]: omega_x, omega_y) are bitwise the sorted
 * copy's. */
START_TEST(test_diagnostics_room_3d) {
  static const char *const set[] = {
      "Solver:scheme=contact", "Solver:kernel=wendland2",
      "Solver:alpha=0.5",      "Solver:res=8",
      "Scene:Ly=4e-7",         "Scene:Lz=4e-7",
      "Solver:t_end=1e-10",    NULL};
  struct vsph_run *run = vsph_test_run(vsph_scene_find("shear"), set, NULL);
  ck_assert_int_eq(vsph_run_iterate(run), 0);
  struct vsph_run_row row;
  ck_assert_int_eq(vsph_run_row(run, &row), 0);
  ck_assert(run->evaluated);
  struct vsph_integrate *s = run->integ;
  struct vsph_particles *p = s->p;
  ck_assert_int_eq(p->dim, 3);
  const struct vsph_kernel_type *k = s->props.eq.visc.kernel;
  const double h = s->props.eq.visc.h;
  const size_t nf = s->n_fluid;
  struct vsph_diagnostics a, r;
  ck_assert_int_eq(vsph_diagnostics_compute(p, nf, k, h, &a, NULL), 0);
  double *const room[4] = {p->acc[0], p->acc[1], p->acc[2], p->drho};
  ck_assert_int_eq(
      vsph_diagnostics_compute_cells(p, nf, s->cells, k, h, room, &r, NULL), 0);
  ck_assert(r.divr == room[0] && r.vort[2] == room[1] && r.vort[0] == room[2] &&
            r.vort[1] == room[3]);
  double most = 0.0;
  for (int c = 0; c < 3; c++) {
    ck_assert_mem_eq(a.vort[c], r.vort[c], nf * sizeof(double));
    for (size_t i = 0; i < nf; i++) most = fmax(most, fabs(a.vort[c][i]));
  }
  ck_assert_double_gt(most, 0.0); /* the shear layer turns */
  ck_assert_mem_eq(a.divr, r.divr, nf * sizeof(double));
  ck_assert_mem_eq(a.surf, r.surf, nf);
  vsph_diagnostics_free(&a);
  vsph_diagnostics_free(&r);
  vsph_run_free(run);
}
END_TEST

Suite *vsph_solver_suite(void) {
  Suite *s = suite_create("solver");
  TCase *tc = tcase_create("runs");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, test_stretching_initial_power);
  tcase_add_test(tc, test_run_props_names);
  tcase_add_test(tc, test_stretching_initial_pressure);
  tcase_add_test(tc, test_diagnostics);
  tcase_add_test(tc, test_probe_interpolates_linear_fields);
  tcase_add_test(tc, test_vortex_angular_momentum);
  tcase_add_test(tc, test_budget_residual);
  tcase_add_test(tc, test_standing_wave_period);
  tcase_add_test(tc, test_scene_cfl);
  tcase_add_test(tc, test_run_props_for_scene);
  tcase_add_loop_test(tc, test_threads_bitwise, 0, VSPH_VISCOUS_FORM_COUNT);
  tcase_add_test(tc, test_ghost_capacity);
  tcase_add_test(tc, test_hydrostatic_rest);
  tcase_add_test(tc, test_own_image);
  tcase_add_test(tc, test_relax_settles_then_starts);
  tcase_add_test(tc, test_unstable_detected);
  tcase_add_test(tc, test_rhs_cells_vs_direct);
  tcase_add_test(tc, test_pack_lean);
  tcase_add_test(tc, test_restore_refuses_bad_ids);
  tcase_add_test(tc, test_diagnostics_order);
  tcase_add_test(tc, test_diagnostics_room_3d);
  suite_add_tcase(s, tc);
  return s;
}
