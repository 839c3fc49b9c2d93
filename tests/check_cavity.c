/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The lid-driven cavity (issue 11): Ghia et al.'s tables against mass
 * conservation, the wall particles' state (Adami et al. 2012) and the
 * summation density against a direct lattice sum, the transport
 * velocity's background push on a uniform lattice, and 1 against 2
 * threads. */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/references.h"
#include "../common/params.h"
#include "../kernels/kernel.h"
#include "../solver/integrate.h"
#include "../solver/particles.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "check_suites.h"

/* The steady flow carries no net flux across either centreline: the
 * trapezoid rule on Ghia et al.'s 17 points gives int u dy = int v dx = 0
 * up to its own error on their uneven spacing (panels up to 0.17 L wide,
 * max|u''| dy^2/12 each): measured 0.2 % to 4.0 % of int |u|. Bound 6 %:
 * it catches a flipped sign, a value in the wrong row or a slip in the
 * first decimal, not a slip in the fifth (the tables were compared with
 * two public transcriptions by hand). */
START_TEST(test_ghia_flux) {
  static const double RE[3] = {100.0, 400.0, 1000.0};
  struct vsph_references_ghia g;
  ck_assert(vsph_references_ghia(RE[_i], &g));
  ck_assert_uint_eq(g.n, 17);
  double fu = 0, au = 0, fv = 0, av = 0;
  for (size_t q = 0; q + 1 < g.n; q++) {
    double d = g.y[q] - g.y[q + 1];
    ck_assert_double_gt(d, 0.0);
    fu += 0.5 * d * (g.u[q] + g.u[q + 1]);
    au += 0.5 * d * (fabs(g.u[q]) + fabs(g.u[q + 1]));
    d = g.x[q] - g.x[q + 1];
    ck_assert_double_gt(d, 0.0);
    fv += 0.5 * d * (g.v[q] + g.v[q + 1]);
    av += 0.5 * d * (fabs(g.v[q]) + fabs(g.v[q + 1]));
  }
  ck_assert_double_lt(fabs(fu), 0.06 * au);
  ck_assert_double_lt(fabs(fv), 0.06 * av);
  /* the walls: u = U on the lid, 0 elsewhere */
  ck_assert_double_eq(g.u[0], 1.0);
  ck_assert_double_eq(g.u[16] + g.v[0] + g.v[16], 0.0);
  ck_assert(!vsph_references_ghia(200.0, &g));
}
END_TEST

/* A cavity run of res 16 (quintic, h = dx), with or without the
 * transport velocity. */
static struct vsph_run *cavity_run_visc(int tvf, const char *visc) {
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_int_eq(vsph_params_set(prm, "Solver:res", "16"), 0);
  ck_assert_int_eq(vsph_params_set(prm, "Solver:kernel", "quintic"), 0);
  ck_assert_int_eq(vsph_params_set(prm, "Solver:hdx", "1"), 0);
  ck_assert_int_eq(vsph_params_set(prm, "Solver:visc", visc), 0);
  ck_assert_int_eq(vsph_params_set(prm, "Solver:tvf", tvf ? "1" : "0"), 0);
  struct vsph_run_props rp;
  struct vsph_scene sc;
  ck_assert_int_eq(vsph_run_props_init(&rp, prm), 0);
  ck_assert_int_eq(vsph_scene_init(&sc, &vsph_cavity_type, prm), 0);
  vsph_params_free(prm);
  struct vsph_run *run = NULL;
  ck_assert_int_eq(vsph_run_alloc(&rp, &sc, &run), 0);
  return run;
}

static struct vsph_run *cavity_run(int tvf) {
  return cavity_run_visc(tvf, "meaf");
}

/* Zheng et al.'s Laplacians run the transport-velocity cavity (their
 * claims are about it): VISC-01 is MEAF-eta (Morris with r^2 + eta^2)
 * written as a per-component Laplacian by its own pass, so the cavity run
 * with each, by two different code paths, gives the same flow. 16 x 16
 * at Re 100 to t = 0.3 s (about 200 steps): E_k, the viscous power and
 * the momentum agree to 1e-9 relative (measured 1e-13 to 1e-10: the two
 * sums round differently, and the steps carry it). */
START_TEST(test_cavity_laplacian_forms) {
  struct vsph_run *a = cavity_run_visc(1, "visc01");
  struct vsph_run *b = cavity_run_visc(1, "meafeta");
  while (vsph_run_time(a) < 0.3) ck_assert_int_eq(vsph_run_iterate(a), 0);
  while (vsph_run_time(b) < 0.3) ck_assert_int_eq(vsph_run_iterate(b), 0);
  ck_assert_double_eq_tol(vsph_run_time(a), vsph_run_time(b), 1e-12);
  struct vsph_equations_energy ea, eb;
  struct vsph_equations_budget ba, bb;
  ck_assert_int_eq(vsph_integrate_diagnostics(a->integ, &ea, &ba), 0);
  ck_assert_int_eq(vsph_integrate_diagnostics(b->integ, &eb, &bb), 0);
  ck_assert(ea.Ek > 1e-4); /* the lid has set the fluid moving */
  ck_assert_double_eq_tol(ea.Ek, eb.Ek, 1e-9 * eb.Ek);
  ck_assert_double_eq_tol(ba.P_visc, bb.P_visc, 1e-9 * fabs(bb.P_visc));
  ck_assert_double_eq_tol(ea.P[0], eb.P[0], 1e-9 * fabs(eb.P[0]) + 1e-15);
  vsph_run_free(a);
  vsph_run_free(b);
}
END_TEST

/* On the initial lattice, the wall particles continue the fluid's lattice
 * (three layers for the quintic's 3h), so every fluid particle's
 * summation density is the infinite lattice's, rho0 dx^2 sum_(i,j) W,
 * summed here directly; every fluid pressure is c0^2 (rho - rho0); a wall
 * particle with fluid neighbours takes that same pressure (a Shepard
 * average of equal values) and the velocity 2 u_w - u_f for a uniform
 * fluid velocity u_f; one without keeps p = 0 and u_w. The background
 * push sums to zero over a full symmetric lattice. Rounding: 1e-12. */
START_TEST(test_cavity_wall_state) {
  struct vsph_run *run = cavity_run(1);
  struct vsph_integrate *s = run->integ;
  struct vsph_particles *p = s->p;
  const double uf[2] = {0.3, -0.2}, dx = run->dx, h = run->h;
  const double U = run->scene.u.cavity.U, c2 = s->props.eq.c0 * s->props.eq.c0;
  for (size_t i = 0; i < p->n; i++)
    for (int k = 0; k < 2; k++) p->vel[k][i] = uf[k];
  struct vsph_equations_energy en;
  struct vsph_equations_budget b;
  ck_assert_int_eq(vsph_integrate_diagnostics(s, &en, &b), 0);
  double lat = 0.0;
  for (int i = -4; i <= 4; i++)
    for (int j = -4; j <= 4; j++)
      lat += vsph_kernel_w(run->props.ktype, 2, hypot(i, j) * dx / h) / (h * h);
  const double rho = s->props.eq.rho0 * dx * dx * lat, pf = c2 * (rho - 1.0);
  ck_assert_double_gt(fabs(rho - 1.0), 1e-6); /* not trivially rho0 */
  size_t nwall = 0, nlid = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] < s->n_fluid) {
      ck_assert_double_eq_tol(p->rho[i], rho, 1e-12);
      ck_assert_double_eq_tol(p->p[i], pf, 1e-12 * c2);
      for (int k = 0; k < 2; k++)
        ck_assert_double_eq_tol(p->bacc[k][i], 0.0, 1e-12 * s->props.eq.pb);
      continue;
    }
    nwall++;
    const double x = p->pos[0][i], y = p->pos[1][i];
    const int lid = y > 1.0;
    nlid += (size_t)lid;
    /* within the support of a fluid particle? (the fluid fills [0, 1]^2
     * at (i + 1/2) dx: the nearest one is at the clamped point) */
    const double cx = fmin(fmax(x, 0.5 * dx), 1.0 - 0.5 * dx);
    const double cy = fmin(fmax(y, 0.5 * dx), 1.0 - 0.5 * dx);
    const int near = hypot(x - cx, y - cy) < 3.0 * h * (1 - 1e-9);
    const double uw = lid ? U : 0.0;
    ck_assert_double_eq_tol(p->p[i], near ? pf : 0.0, 1e-12 * c2);
    ck_assert_double_eq_tol(p->vel[0][i], near ? 2 * uw - uf[0] : uw, 1e-12);
    ck_assert_double_eq_tol(p->vel[1][i], near ? -uf[1] : 0.0, 1e-12);
  }
  /* 22^2 - 16^2 lattice points outside the square, 22 x 3 above the lid */
  ck_assert_uint_eq(nwall, 22 * 22 - 16 * 16);
  ck_assert_uint_eq(nlid, 22 * 3);
  vsph_run_free(run);
}
END_TEST

/* Basa et al.'s cavity (2009) at 16 x 16: the cubic spline at
 * dx/h = 0.637, summation density, Tait's law, Cleary's form (their D)
 * and evolving wall particles. */
static struct vsph_run *cavity_run_basa(void) {
  static const char *const SET[] = {"Solver:res=16",
                                    "Solver:kernel=cubic",
                                    "Solver:hdx=1.5699",
                                    "Solver:visc=cleary",
                                    "Solver:density=summation",
                                    "Solver:eos=tait",
                                    "Scene:walls=evolving",
                                    NULL};
  return vsph_test_run(&vsph_cavity_type, SET, NULL);
}

/* The full lattice's summed density, rho0 dx^2 sum_(i,j) W, summed here
 * directly. */
static double lattice_rho(const struct vsph_run *run) {
  const double dx = run->dx, h = run->h;
  double lat = 0.0;
  for (int i = -4; i <= 4; i++)
    for (int j = -4; j <= 4; j++)
      lat += vsph_kernel_w(run->props.ktype, 2, hypot(i, j) * dx / h) / (h * h);
  return run->integ->props.eq.rho0 * dx * dx * lat;
}

/* Evolving wall particles on the initial lattice, the fluid sheared,
 * u = (gamma y, 0):
 * - every fluid particle sums the full lattice's density (the walls
 *   continue it) and every wall particle starts there, so the pressure
 *   is Tait's of that density everywhere, written out here;
 * - a wall particle below the floor (one plane) carries the shear on,
 *   u_x = gamma y < 0 (a least-squares line through exact linear data),
 *   u_y = 0; one beside a side wall gets the fluid's u_y = 0 continued,
 *   and u_x = 0; the corners their prescribed velocity (0 below, U at
 *   the lid's);
 * - each wall particle's continuity rate equals a brute-force sum over
 *   every fluid particle, rho_w sum_f V_f (W'(r)/r) u_f.(r_f - r_w).
 * Rounding: 1e-12 relative. */
START_TEST(test_cavity_evolving_state) {
  struct vsph_run *run = cavity_run_basa();
  struct vsph_integrate *s = run->integ;
  struct vsph_particles *p = s->p;
  const double gam = 0.7, U = run->scene.u.cavity.U, h = run->h;
  const struct vsph_equations_props *ep = &s->props.eq;
  for (size_t i = 0; i < p->n; i++) {
    p->vel[0][i] = gam * p->pos[1][i];
    p->vel[1][i] = 0.0;
  }
  struct vsph_equations_energy en;
  struct vsph_equations_budget b;
  ck_assert_int_eq(vsph_integrate_diagnostics(s, &en, &b), 0);
  const double rho = lattice_rho(run), rr = rho / ep->rho0;
  const double pt = ep->rho0 * ep->c0 * ep->c0 / 7.0 * (pow(rr, 7.0) - 1.0);
  ck_assert_double_gt(fabs(rr - 1.0), 1e-3); /* 1.0033: not rho0 */
  size_t nfloor = 0, nside = 0;
  for (size_t i = 0; i < p->n; i++) {
    ck_assert_double_eq_tol(p->rho[i], rho, 1e-12);
    ck_assert_double_eq_tol(p->p[i], pt, 1e-12 * ep->c0 * ep->c0);
    if (p->id[i] < s->n_fluid) continue;
    const double x = p->pos[0][i], y = p->pos[1][i];
    const int inx = x > 0.0 && x<1.0, iny = y> 0.0 && y < 1.0;
    if (inx && y < 0.0) {
      nfloor++;
      ck_assert_double_eq_tol(p->vel[0][i], gam * y, 1e-12);
      ck_assert_double_eq_tol(p->vel[1][i], 0.0, 1e-12);
    } else if (iny) {
      nside++;
      ck_assert_double_eq_tol(p->vel[0][i], 0.0, 1e-12);
      ck_assert_double_eq_tol(p->vel[1][i], 0.0, 1e-12);
    } else if (!inx) { /* a corner */
      ck_assert_double_eq_tol(p->vel[0][i], y > 1.0 ? U : 0.0, 1e-12);
      ck_assert_double_eq_tol(p->vel[1][i], 0.0, 1e-12);
    }
    double cont = 0.0;
    for (size_t j = 0; j < p->n; j++) {
      if (p->id[j] >= s->n_fluid) continue;
      const double dx = p->pos[0][j] - x, dy = p->pos[1][j] - y;
      const double r = hypot(dx, dy);
      if (!(r < 2.0 * h)) continue;
      const double F =
          vsph_kernel_dw(run->props.ktype, 2, r / h) / (h * h * h) / r;
      cont += p->vol[j] * F * (p->vel[0][j] * dx + p->vel[1][j] * dy);
    }
    ck_assert_double_eq_tol(p->drho[i], p->rho[i] * cont,
                            1e-12 * gam * rho / h);
  }
  ck_assert_uint_eq(nfloor, 16 * 4); /* four layers: ceil(2h/dx) */
  ck_assert_uint_eq(nside, 2 * 16 * 4);
  vsph_run_free(run);
}
END_TEST

/* The integrator advances the evolving walls' density: the fluid moving
 * down onto the floor, u = (0, -v), compresses the wall particles below
 * it, and one short RK4 step changes each by dt d(rho)/dt of the start
 * to within 1e-3 of the change (the rates drift by O(v dt/dx) = 1e-5
 * over the step). */
START_TEST(test_cavity_evolving_step) {
  struct vsph_run *run = cavity_run_basa();
  struct vsph_integrate *s = run->integ;
  struct vsph_particles *p = s->p;
  const double v = 0.1, dt = 2e-6;
  for (size_t i = 0; i < p->n; i++) p->vel[0][i] = 0.0, p->vel[1][i] = -v;
  struct vsph_equations_energy en;
  struct vsph_equations_budget b;
  ck_assert_int_eq(vsph_integrate_diagnostics(s, &en, &b), 0);
  const size_t nf = s->n_fluid, nw = p->n - nf;
  double *r0 = calloc(nw, sizeof *r0), *d0 = calloc(nw, sizeof *d0);
  double dmax = 0.0;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] >= nf) {
      r0[p->id[i] - nf] = p->rho[i];
      d0[p->id[i] - nf] = p->drho[i];
      dmax = fmax(dmax, p->drho[i]);
    }
  ck_assert_double_gt(dmax, 0.1 * v / run->dx); /* the floor compressed */
  ck_assert_int_eq(vsph_integrate_step(s, dt), 0);
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] < nf) continue;
    const size_t w = p->id[i] - nf;
    ck_assert_double_eq_tol(p->rho[i] - r0[w], dt * d0[w], 1e-3 * dt * dmax);
  }
  free(r0);
  free(d0);
  vsph_run_free(run);
}
END_TEST

/* Gather form: 1 and 2 threads give the same bits after 20 steps of the
 * transport-velocity scheme (wall state, summation, kick-drift-kick),
 * and (_i = 1) of Basa et al.'s cavity (evolving walls, summation, RK4),
 * its wall densities included; and, for the transport velocity, an energy
 * row after every step (an evaluation at another velocity) does not
 * change them: the step keeps its own rates. (Under RK4 a row does change
 * the last bits, with Adami's walls as with these: the step's cell list
 * is rebuilt from the order the row's left. A run writes its rows on a
 * fixed schedule, so it stays reproducible.) */
START_TEST(test_cavity_threads) {
  double *state[3];
  size_t n = 0;
  const int nt = _i ? 2 : 3;
  for (int t = 0; t < nt; t++) {
    omp_set_num_threads(t == 1 ? 2 : 1);
    struct vsph_run *run = _i ? cavity_run_basa() : cavity_run(1);
    for (int k = 0; k < 20; k++) {
      ck_assert_int_eq(vsph_run_iterate(run), 0);
      struct vsph_run_row row;
      if (t == 2) ck_assert_int_eq(vsph_run_row(run, &row), 0);
    }
    ck_assert_int_eq(run->state, VSPH_RUN_RUNNING);
    const struct vsph_particles *p = run->integ->p;
    n = p->n; /* fluid and wall particles */
    state[t] = calloc(4 * n, sizeof(double));
    for (size_t i = 0; i < p->n; i++) {
      const size_t id = p->id[i];
      /* a wall particle's state: the evolving density (the rest is set
       * afresh by each evaluation, an energy row's too) */
      if (id >= run->n_fluid) {
        if (_i) state[t][3 * n + id] = p->rho[i];
        continue;
      }
      state[t][id] = p->pos[0][i];
      state[t][n + id] = p->pos[1][i];
      state[t][2 * n + id] = p->vel[0][i];
      state[t][3 * n + id] = p->rho[i];
    }
    vsph_run_free(run);
  }
  ck_assert_int_eq(memcmp(state[0], state[1], 4 * n * sizeof(double)), 0);
  if (nt > 2)
    ck_assert_int_eq(memcmp(state[0], state[2], 4 * n * sizeof(double)), 0);
  for (int t = 0; t < nt; t++) free(state[t]);
}
END_TEST

Suite *vsph_cavity_suite(void) {
  Suite *s = suite_create("cavity");
  TCase *tc = tcase_create("cavity");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, test_ghia_flux, 0, 3);
  tcase_add_test(tc, test_cavity_wall_state);
  tcase_add_loop_test(tc, test_cavity_threads, 0, 2);
  tcase_add_test(tc, test_cavity_evolving_state);
  tcase_add_test(tc, test_cavity_evolving_step);
  tcase_add_test(tc, test_cavity_laplacian_forms);
  suite_add_tcase(s, tc);
  return s;
}
