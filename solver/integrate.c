/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "integrate.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "cells_internal.h"
#include "pair.h"
#include "particles.h"
#include "particles_internal.h"
#include "walls_internal.h"

/* The integrated fields: r, u, rho, and e for the gas law only. */
static int nfields(const struct vsph_integrate *s) {
  return 2 * s->p->dim + 1 + (s->props.eq.eos == VSPH_EQUATIONS_EOS_GAS);
}

static double *field(struct vsph_particles *p, int f) {
  const int d = p->dim;
  return f < d        ? p->pos[f]
         : f < 2 * d  ? p->vel[f - d]
         : f == 2 * d ? p->rho
                      : p->e;
}

/* The per-particle buffers beside the particle set, for its capacity:
 * their contents are rebuilt every step (and every evaluation), so they
 * are allocated afresh, not copied. */
/* Whether the budget's scratch (extra: the viscous parts, XSPH's
 * velocity) has arrays of its own: with RK4 it is read only between
 * steps (vsph_integrate_diagnostics), when y0, the step's start state, is
 * idle, and lies in y0's first d + 1 fields (d + 1 <= 2 d + 1): a quarter
 * of a 2-D run's buffers fewer. The transport velocity and the leapfrog
 * keep their own. */
static int extra_own(const struct vsph_integrate *s) {
  return s->props.eq.tvf || s->props.leapfrog;
}

static int buffers_alloc(struct vsph_integrate *s) {
  const size_t cap = s->p->cap;
  const int d = s->p->dim;
  vsph_viscous_ws_free(s->vws);
  vsph_walls_ghosts_free(s->gh);
  free(s->where);
  s->vws = NULL;
  s->gh = NULL;
  s->where = NULL;
  for (int f = 0; f < 8; f++) { /* ks grows below, keeping its rates */
    free(s->y0[f]);
    s->y0[f] = NULL;
  }
  for (int f = 0; f < 4; f++) {
    if (extra_own(s)) free(s->extra[f]);
    s->extra[f] = NULL;
  }
  const int corr = s->props.eq.corr != VSPH_PAIR_CORR_NONE;
  if ((vsph_viscous_first_pass(s->props.eq.visc.form) || corr) &&
      !(s->vws = vsph_viscous_ws_alloc(cap, d)))
    return VSPH_ENOMEM;
  if (corr && vsph_viscous_ws_corr(s->vws)) return VSPH_ENOMEM;
  const int evolving = s->props.walls.solid == VSPH_WALLS_EVOLVING,
            fixed = s->props.walls.solid == VSPH_WALLS_FIXED;
  /* evolving wall particles: the nearest rows' scratch only, a particle
   * in the rows of at most every plane; fixed ones: the periodic images */
  if (s->props.walls.n > 0 && (!s->props.walls.solid || evolving || fixed) &&
      !(s->gh = vsph_walls_ghosts_alloc(
            &s->props.walls,
            evolving ? (size_t)s->props.walls.n * s->n_fluid + 1 : cap)))
    return VSPH_ENOMEM;
  int ok = (s->where = malloc(cap * sizeof *s->where)) != NULL;
  for (int f = 0; f < nfields(s); f++) {
    ok = ok && (s->y0[f] = malloc(cap * sizeof(double))) != NULL;
    /* the rates kept by id (transport velocity, leapfrog) survive a
     * growth of the set within a step: realloc keeps them */
    double *const k = ok ? realloc(s->ks[f], cap * sizeof(double)) : NULL;
    if (k) s->ks[f] = k;
    ok = ok && k != NULL;
  }
  for (int f = 0; f < d + 1; f++)
    ok = ok && (s->extra[f] = extra_own(s) ? malloc(cap * sizeof(double))
                                           : s->y0[f]) != NULL;
  if (!ok)
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the integrator for %zu particles",
              cap);
  return VSPH_OK;
}

/* Room for n particles (fluid and ghosts): the particle set keeps its live
 * particles, the buffers are made afresh. Grows by half the particles
 * beyond the fluid (ghosts, images, wall particles) and 64 more than
 * asked, so a wave's slowly changing ghost count does not regrow every
 * step; not by a share of the fluid, whose count does not change (an
 * eighth of every array, zeroed and so resident, cost the standing wave
 * about 12 B a particle). */
static int reserve(struct vsph_integrate *s, size_t n) {
  if (n <= s->p->cap) return VSPH_OK;
  const size_t beyond = n > s->n_fluid ? n - s->n_fluid : 0;
  const int st = vsph_particles_reserve(s->p, n + beyond / 2 + 64);
  return st ? st : buffers_alloc(s);
}

struct vsph_integrate *vsph_integrate_alloc(
    const struct vsph_integrate_props *ip, struct vsph_particles *fluid) {
  if (!ip || !fluid || !ip->eq.visc.kernel) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "vsph_integrate_alloc: a NULL argument or kernel");
    vsph_particles_free(fluid);
    return NULL;
  }
  /* the transport-velocity scheme reads every neighbour's transport
   * velocity, which a ghost (mirrored or periodic image) does not carry:
   * it runs beside wall particles only (as the run layer requires) */
  if (ip->eq.tvf && ip->walls.n > 0 && !ip->walls.solid) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "the transport-velocity scheme needs wall particles, "
                       "not ghost walls");
    vsph_particles_free(fluid);
    return NULL;
  }
  struct vsph_integrate *s = calloc(1, sizeof *s);
  if (!s) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate the integrator");
    vsph_particles_free(fluid);
    return NULL;
  }
  s->props = *ip;
  s->n_fluid = fluid->n;
  /* wall particles continue the fluid's lattice, spacing dx = V^(1/d);
   * a fluid particle has escaped once it passes their first row, dx/2
   * behind the wall (the scene's box is the walls) */
  if (ip->walls.solid && fluid->n > 0) {
    const double v = fluid->vol[0], dx = fluid->dim == 1   ? v
                                         : fluid->dim == 2 ? sqrt(v)
                                                           : cbrt(v);
    s->props.walls.dx = dx;
    for (int a = 0; a < fluid->dim; a++) {
      s->props.box_lo[a] -= 0.5 * dx;
      s->props.box_hi[a] += 0.5 * dx;
    }
  }
  for (size_t i = 0; i < fluid->n; i++) fluid->id[i] = i;
  s->p = fluid; /* taken; the ghosts, if any, grow it in prepare */
  if (!(s->cells = vsph_cells_alloc()) ||
      !(s->sweep = vsph_equations_sweep_alloc()) || buffers_alloc(s)) {
    vsph_integrate_free(s);
    return NULL;
  }
  return s;
}

void vsph_integrate_free(struct vsph_integrate *s) {
  if (!s) return;
  vsph_particles_free(s->p);
  vsph_cells_free(s->cells);
  vsph_equations_sweep_free(s->sweep);
  vsph_viscous_ws_free(s->vws);
  vsph_walls_ghosts_free(s->gh);
  free(s->where);
  free(s->order0);
  for (int f = 0; f < 8; f++) {
    free(s->y0[f]);
    free(s->ks[f]);
  }
  for (int f = 0; f < 4; f++)
    if (extra_own(s)) free(s->extra[f]);
  free(s);
}

static double max_speed(const struct vsph_integrate *s) {
  const struct vsph_particles *p = s->p;
  const size_t n = p->n, n_fluid = s->n_fluid, *const id = p->id;
  const int dim = p->dim;
  double v2 = 0.0;
  /* a maximum is exact in any order, so the same for any thread count; a
   * NaN u2 leaves v2 as fmax would */
#pragma omp parallel for reduction(max   \
                                   : v2) \
    schedule(static) if (n >= VSPH_PARTICLES_MOVE_PARALLEL)
  for (size_t i = 0; i < n; i++) {
    double u2 = 0.0;
    for (int k = 0; k < dim; k++) u2 += p->vel[k][i] * p->vel[k][i];
    if (id[i] < n_fluid && u2 > v2) v2 = u2;
  }
  return sqrt(v2);
}

double vsph_integrate_dt(const struct vsph_integrate *s) {
  if (!s) return (double)NAN;
  if (s->props.dt > 0.0) return s->props.dt;
  const struct vsph_equations_props *ep = &s->props.eq;
  const double h = ep->visc.h;
  double c0 = ep->c0, nu = ep->visc.mu / ep->rho0;
  for (int m = 0; m < ep->nmat; m++) { /* contact: the fastest material,
                                           its viscosity and the part of
                                           the numerical one removed */
    const struct vsph_equations_mat *ma = &ep->mat[m];
    c0 = fmax(c0, ma->c0);
    nu = fmax(nu, (ma->mu + ep->zeta_num * ma->eta_num) / ma->rho0);
  }
  double gmax = 0.0;
  if (ep->body == VSPH_EQUATIONS_BODY_GRAVITY) gmax = fabs(ep->g);
  if (ep->body == VSPH_EQUATIONS_BODY_UNIFORM) gmax = fabs(ep->f);
  if (ep->body == VSPH_EQUATIONS_BODY_RADIAL) {
    const struct vsph_particles *p = s->p;
    for (size_t i = 0; i < p->n; i++) {
      double r2 = 0.0;
      for (int k = 0; k < p->dim; k++) r2 += p->pos[k][i] * p->pos[k][i];
      gmax = fmax(gmax, ep->beta * ep->beta * sqrt(r2));
    }
  }
  return vsph_integrate_dt_rule(s->props.cfl,
                                s->props.leapfrog ? 2
                                : ep->tvf         ? 1
                                                  : 0,
                                ep->scheme == VSPH_EQUATIONS_CONTACT, h, c0,
                                max_speed(s), nu, gmax);
}

double vsph_integrate_dt_rule(double cfl, int split, int contact, double h,
                              double c0, double umax, double nu, double gmax) {
  const double f = split ? 0.25 : contact ? 0.5 : 1.0;
  const double g = split == 2 ? 0.25 : 1.0;
  double dt = f * cfl * h / (c0 + umax);
  if (nu > 0.0) dt = fmin(dt, g * 0.125 * h * h / nu);
  if (gmax > 0.0) dt = fmin(dt, 0.25 * sqrt(h / gmax));
  return dt;
}

/* The summed density of a particle on the full lattice of spacing dx
 * (rho0 = 1): dx^d sum_k W(|k| dx): what every particle of the initial
 * lattice sums where the wall particles continue it. */
static double lattice_sum(const struct vsph_viscous_props *vp, double dx) {
  const int d = vp->dim;
  const double H = vp->kernel->kappa * vp->h;
  const long L = (long)ceil(H / dx);
  double S = 0.0;
  for (long a = -L; a <= L; a++)
    for (long b = d > 1 ? -L : 0; b <= (d > 1 ? L : 0); b++)
      for (long c = d > 2 ? -L : 0; c <= (d > 2 ? L : 0); c++) {
        const double r = dx * sqrt((double)(a * a + b * b + c * c));
        if (r < H) S += vsph_kernel_w(vp->kernel, d, r / vp->h);
      }
  return S * pow(dx / vp->h, d);
}

/* How deep wall particles are laid: a support; fixed ones two, so that
 * every one a fluid particle reaches sums a full support (and a two-pass
 * form's first pass has its own). */
static double solid_reach(const struct vsph_integrate *s) {
  const struct vsph_viscous_props *vp = &s->props.eq.visc;
  const double H = vp->kernel->kappa * vp->h;
  return s->props.walls.solid == VSPH_WALLS_FIXED ? 2.0 * H : H;
}

/* The wall particles (ids n_fluid ..), laid once. */
static size_t n_wall(const struct vsph_integrate *s) {
  const struct vsph_walls *w = &s->props.walls;
  return w->solid ? vsph_walls_solid_count(w, s->p->dim, w->dx, solid_reach(s))
                  : 0;
}

size_t vsph_integrate_wall_count(const struct vsph_integrate *s) {
  return s ? n_wall(s) : 0;
}

/* The map from each particle's id to its slot (s->where), the set's ids
 * being distinct: a scatter, in parallel for a large set. */
static void map_ids(struct vsph_integrate *s) {
  const size_t n = s->p->n, *const id = s->p->id;
  size_t *const where = s->where;
#pragma omp parallel for schedule(static) if (n >= VSPH_PARTICLES_MOVE_PARALLEL)
  for (size_t i = 0; i < n; i++) where[id[i]] = i;
}

/* Ghosts (walls only), the cell list with a skin, and the id -> index map. */
static int prepare(struct vsph_integrate *s, double skin) {
  const struct vsph_viscous_props *vp = &s->props.eq.visc;
  const double H = vp->kernel->kappa * vp->h;
  int st;
  const int fixed = s->props.walls.solid == VSPH_WALLS_FIXED;
  if (s->props.walls.solid) { /* laid once, fixed */
    const struct vsph_walls *w = &s->props.walls;
    if (s->p->n == s->n_fluid) {
      const size_t nw = n_wall(s), n0 = s->p->n;
      if ((st = reserve(s, s->n_fluid + nw)) ||
          (st = vsph_walls_solid_generate(w, s->p, s->n_fluid, w->dx,
                                          solid_reach(s))))
        return st;
      for (size_t i = n0; i < s->p->n; i++) { /* the walls' own velocity */
        double x[3] = {0, 0, 0}, u[3];
        for (int a = 0; a < s->p->dim; a++) x[a] = s->p->pos[a][i];
        vsph_walls_solid_velocity(w, s->p->dim, x, u);
        for (int a = 0; a < s->p->dim; a++) s->p->vel[a][i] = u[a];
      }
      /* evolving walls start where the fluid's sum starts: the full
       * lattice's density [reconstructed], so the fluid at rest stays so */
      if (w->solid == VSPH_WALLS_EVOLVING && s->props.eq.summation) {
        const double rho = w->rho0 * lattice_sum(vp, w->dx);
        for (size_t i = s->n_fluid; i < s->p->n; i++) s->p->rho[i] = rho;
      }
    }
  }
  if (s->props.walls.n > 0 && (!s->props.walls.solid || fixed)) {
    /* ghosts; beside fixed wall particles, the fluid's periodic images */
    const struct vsph_walls *w = &s->props.walls;
    vsph_walls_wrap(w, s->p, s->n_fluid);
    /* a two-pass form (PVWF) differentiates its first pass: ghosts two
     * supports deep (Basa et al.: 4h rather than 2h); so do the fluid's
     * periodic images beside fixed wall particles, which a wall particle
     * a support beyond the period's end sums */
    const double reach = (fixed ? 2.0 : vsph_viscous_passes(vp->form)) * H;
    const size_t nw = n_wall(s);
    const size_t ng = vsph_walls_count(w, s->p, s->n_fluid, reach + skin);
    if ((st = reserve(s, s->n_fluid + nw + ng))) return st;
    s->gh->keep = nw; /* after reserve: it may make gh afresh */
    /* the set is the integrator's own: its arrays are moved, not copied
     * (through the cell list's scratch, free until its build) */
    size_t *perm;
    void **spare;
    if ((st = vsph_cells_lend(s->cells, s->p, &perm, &spare)) ||
        (st = vsph_walls_generate_moved(w, s->p, s->n_fluid, reach + skin,
                                        s->gh, perm, spare)))
      return st;
  }
  if ((st = vsph_cells_build_owned(s->cells, s->p, H + skin))) return st;
  map_ids(s);
  return VSPH_OK;
}

static int rhs(struct vsph_integrate *s, int parts, size_t *nint,
               double *min_s2) {
  struct vsph_particles *p = s->p;
  int st = VSPH_OK;
  if (s->props.walls.solid == VSPH_WALLS_EVOLVING) {
    vsph_walls_solid_extrapolate(&s->props.walls, p, s->n_fluid, s->gh);
    st = vsph_equations_walls_evolving(&s->props.eq, p, s->n_fluid, s->cells);
  } else if (s->props.walls.solid == VSPH_WALLS_ADAMI) {
    st = vsph_equations_walls_adami(&s->props.eq, &s->props.walls, p,
                                    s->n_fluid, s->cells);
  } else {
    if (s->props.walls.n > 0) /* the ghosts where their sources are */
      vsph_walls_update(&s->props.walls, p, s->n_fluid, s->gh, s->where);
    if (s->props.eq.summation) { /* fixed wall particles sum theirs too */
      vsph_equations_density_sum(&s->props.eq, p, s->n_fluid + n_wall(s),
                                 s->cells);
      if (s->props.walls.n > 0) /* and their density from the new sum */
        vsph_walls_update(&s->props.walls, p, s->n_fluid, s->gh, s->where);
    }
  }
  if (st) return st;
  /* the budget's evaluation (parts: the viscous force and delta-SPH's
   * rate apart) by the gather, whose sums need no buffers: by the sweep
   * it would hold 2 d + 2 fields a particle, twice a step's, and set the
   * run's peak memory; it changes no state, and its budget's sums differ
   * from the sweep's in their order only */
  struct vsph_equations_out out = {
      .drho = p->drho, .de = p->de, .sweep = parts ? NULL : s->sweep};
  for (int k = 0; k < p->dim; k++) {
    out.acc[k] = p->acc[k];
    if (parts) out.acc_visc[k] = s->extra[k];
  }
  if (parts) out.drho_delta = s->extra[p->dim];
  st = vsph_equations_rhs(&s->props.eq, p, s->n_fluid, s->cells, s->vws, &out);
  if (nint) *nint += out.interactions;
  if (min_s2) *min_s2 = fmin(*min_s2, out.min_s2);
  return st;
}

/* After an evaluation: the closing kick u += kick a (kick 0 after the
 * very first evaluation), and the evaluation's a and a_b kept by particle
 * id in ks[0..2d-1] (which this step does not otherwise use): an energy
 * row between steps evaluates again at another velocity and must not
 * change the next step's opening kick. */
static void tvf_close(struct vsph_integrate *s, double kick) {
  struct vsph_particles *p = s->p;
  const int d = p->dim;
  const size_t n = p->n, nf = s->n_fluid;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    const size_t id = p->id[i];
    if (id >= nf) continue;
    for (int k = 0; k < d; k++) {
      p->vel[k][i] += kick * p->acc[k][i];
      s->ks[k][id] = p->acc[k][i];
      s->ks[d + k][id] = p->bacc[k][i];
    }
  }
  s->kept = 1;
}

/* The transport-velocity scheme (Adami, Hu & Adams 2013), kick-drift-kick
 * with the density by summation: u += dt/2 a; tvel = u + dt/2 a_b;
 * r += dt tvel; evaluate; u += dt/2 a. The opening kick reuses the last
 * step's evaluation, as Adami et al. do (one evaluation a step; the very
 * first step evaluates at its start). */
static int step_tvf(struct vsph_integrate *s, double dt) {
  struct vsph_particles *p = s->p;
  const int d = p->dim;
  size_t nint = 0;
  double min_s2 = INFINITY;
  int st;
  if (!s->kept) {
    if ((st = prepare(s, 0.0)) || (st = rhs(s, 0, &nint, &min_s2))) return st;
    tvf_close(s, 0.0);
  }
  const size_t n = p->n, nf = s->n_fluid;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    const size_t id = p->id[i];
    if (id >= nf) continue;
    for (int k = 0; k < d; k++) {
      p->vel[k][i] += 0.5 * dt * s->ks[k][id];
      p->tvel[k][i] = p->vel[k][i] + 0.5 * dt * s->ks[d + k][id];
      p->pos[k][i] += dt * p->tvel[k][i];
    }
  }
  if ((st = prepare(s, 0.0)) || (st = rhs(s, 0, &nint, &min_s2))) return st;
  tvf_close(s, 0.5 * dt);
  s->t += dt;
  s->steps++;
  s->interactions = nint;
  s->min_dist = sqrt(min_s2);
  return VSPH_OK;
}

/* The leapfrog's drift velocity at the current positions and velocities,
 * by particle id into ks[0..d-1]: u, plus XSPH's share with the ghosts'
 * velocities refreshed from their sources. */
static void drift_velocity(struct vsph_integrate *s) {
  struct vsph_particles *p = s->p;
  const int d = p->dim;
  const size_t n = p->n, nf = s->n_fluid;
  if (s->props.xsph > 0.0) {
    if (s->props.walls.n > 0 &&
        (!s->props.walls.solid ||
         s->props.walls.solid == VSPH_WALLS_FIXED)) /* the kicked u */
      vsph_walls_update(&s->props.walls, p, nf, s->gh, s->where);
    double *w[3] = {s->extra[0], d > 1 ? s->extra[1] : NULL,
                    d > 2 ? s->extra[2] : NULL};
    vsph_equations_xsph(&s->props.eq, p, nf, s->cells, s->props.xsph, w);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++)
      for (int k = 0; k < d; k++)
        s->ks[k][p->id[i]] = p->id[i] < nf ? w[k][i] : 0.0;
  } else {
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++)
      for (int k = 0; k < d; k++)
        s->ks[k][p->id[i]] = p->id[i] < nf ? p->vel[k][i] : 0.0;
  }
  s->kept = 1;
}

/* Half a drift: r += dt/2 w, w by id. */
static void half_drift(struct vsph_integrate *s, double dt) {
  struct vsph_particles *p = s->p;
  const int d = p->dim;
  const size_t n = p->n, nf = s->n_fluid;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++)
    if (p->id[i] < nf)
      for (int k = 0; k < d; k++) p->pos[k][i] += 0.5 * dt * s->ks[k][p->id[i]];
}

/* The leapfrog's rates by particle id for the next step's mid-step
 * prediction: a into ks[d..2d-1], d rho/dt into ks[2d] (wall particles'
 * too). */
static void keep_rates(struct vsph_integrate *s) {
  struct vsph_particles *p = s->p;
  const int d = p->dim;
  const size_t n = p->n;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    const size_t id = p->id[i]; /* every particle (a checkpoint writes
                                   them all; only fluid and evolving walls
                                   are read) */
    for (int k = 0; k < d; k++) s->ks[d + k][id] = p->acc[k][i];
    s->ks[2 * d][id] = p->drho[i];
  }
}

/* Vukcevic et al.'s drift-kick-drift leapfrog (vsph_integrate_step). The
 * mid-step evaluation takes the velocity and the integrated density
 * predicted with the last step's rates, u + dt/2 a_prev, rho + dt/2
 * drho_prev [reconstructed: the paper does not say which velocity enters
 * the velocity-dependent forces; with u_n the scheme is first order, with
 * the prediction second, as the paper's "error roughly dt^2" asks]. */
static int step_leapfrog(struct vsph_integrate *s, double dt) {
  struct vsph_particles *p = s->p;
  const int d = p->dim;
  size_t nint = 0;
  double min_s2 = INFINITY;
  int st;
  if (!s->kept) { /* the very first step: w and the rates at the start */
    if ((st = prepare(s, 0.0)) || (st = rhs(s, 0, NULL, NULL))) return st;
    keep_rates(s);
    drift_velocity(s);
  }
  half_drift(s, dt);
  const int rho_fluid = !s->props.eq.summation,
            rho_wall = s->props.walls.solid == VSPH_WALLS_EVOLVING;
  const size_t nf = s->n_fluid;
  /* the cells and ghosts at the mid-step positions (this may grow the
   * set: y0 is made afresh, ks keeps its rates) */
  if ((st = prepare(s, 0.0))) return st;
  double *const rho0 = s->y0[2 * d];
  /* u_n and rho_n by id (prepare moved no velocity or density), then the
   * prediction */
  for (size_t i = 0; i < p->n; i++) {
    const size_t id = p->id[i];
    if (id < nf) {
      for (int k = 0; k < d; k++) s->y0[k][id] = p->vel[k][i];
      rho0[id] = p->rho[i];
    } else if (rho_wall) {
      rho0[id] = p->rho[i];
    }
  }
  const size_t n = p->n;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    const size_t id = p->id[i];
    const int fluid = id < nf;
    if (fluid ? rho_fluid : rho_wall)
      p->rho[i] = rho0[id] + 0.5 * dt * s->ks[2 * d][id];
    if (fluid)
      for (int k = 0; k < d; k++)
        p->vel[k][i] = s->y0[k][id] + 0.5 * dt * s->ks[d + k][id];
  }
  if ((st = rhs(s, 0, &nint, &min_s2))) return st;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) { /* the kick, from u_n and rho_n */
    const size_t id = p->id[i];
    const int fluid = id < nf;
    if (fluid ? rho_fluid : rho_wall) p->rho[i] = rho0[id] + dt * p->drho[i];
    if (fluid)
      for (int k = 0; k < d; k++)
        p->vel[k][i] = s->y0[k][id] + dt * p->acc[k][i];
  }
  keep_rates(s);
  drift_velocity(s);
  half_drift(s, dt);
  s->t += dt;
  s->steps++;
  s->interactions = nint;
  s->min_dist = sqrt(min_s2);
  return VSPH_OK;
}

static int keep_order(struct vsph_integrate *s);
static void put_back(struct vsph_integrate *s, size_t n0);

int vsph_integrate_step(struct vsph_integrate *s, double dt) {
  if (!s) VSPH_FAIL(VSPH_EINVAL, "vsph_integrate_step: a NULL argument");
  /* (a NaN step made a NaN skin, refused by the cell list as a radius) */
  if (!(dt >= 0.0) || !isfinite(dt))
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_integrate_step: the step %g is not a finite number >= 0",
              dt);
  if (s->props.eq.tvf) return step_tvf(s, dt);
  if (s->props.leapfrog) return step_leapfrog(s, dt);
  /* the particles' order as the step finds them, to put back if it is
   * stopped */
  if (s->stop && keep_order(s)) return VSPH_ENOMEM;
  struct vsph_particles *p = s->p;
  const int d = p->dim, nf = nfields(s);
  /* Skin: a pair closes in by at most 2 dt max|u| over a step; factor 1.5
   * for the velocity change within the step. */
  const double skin = 3.0 * dt * max_speed(s);
  int st = prepare(s, skin);
  if (st) return st;
  const size_t n = p->n;
  double *k[8], *y[8]; /* rates and state fields, looked up once */
  for (int f = 0; f < nf; f++) y[f] = field(p, f);
  for (int f = 0; f < d; f++) k[f] = p->vel[f]; /* dr/dt = u */
  for (int f = 0; f < d; f++) k[d + f] = p->acc[f];
  k[2 * d] = p->drho;
  k[2 * d + 1] = p->de; /* the gas law's energy (nf says whether) */
  /* y0, the state the step starts from, is also what a stopped step puts
   * back (put_back): copied by the threads, each the share of every field
   * that its stages' loops below take (the same static schedule over the
   * same strips of 64; a small set by one thread, as a parallel region's
   * start costs more) */
#pragma omp parallel if (n >= VSPH_PARTICLES_MOVE_PARALLEL)
  for (int f = 0; f < nf; f++) {
    const double *const yf = y[f];
    double *const y0f = s->y0[f];
#pragma omp for schedule(static) nowait
    for (size_t s0 = 0; s0 < n; s0 += 64)
      memcpy(y0f + s0, yf + s0, (n - s0 < 64 ? n - s0 : 64) * sizeof *y0f);
  }
  static const double a[4] = {0.0, 0.5, 0.5, 1.0}, w[4] = {1, 2, 2, 1};
  size_t nint = 0;
  double min_s2 = INFINITY;
  const size_t *const id = p->id;
  /* each field over the ids [lo, hi): the fluid's; a summed density is no
   * state (each evaluation sums it afresh; its continuity rate is kept for
   * the budget only); evolving wall particles' density is */
  size_t lo[8], hi[8];
  for (int f = 0; f < nf; f++) lo[f] = 0, hi[f] = s->n_fluid;
  if (s->props.eq.summation) lo[2 * d] = s->n_fluid;
  if (s->props.walls.solid == VSPH_WALLS_EVOLVING) hi[2 * d] = SIZE_MAX;
  for (int stage = 0; stage < 4; stage++) {
    if (s->stop && *s->stop) { /* between stages: as if never begun */
      put_back(s, n);
      return VSPH_EINTR;
    }
    if ((st = rhs(s, 0, &nint, &min_s2))) return st;
    /* accumulate k_stage and form the next stage state, field by field
     * (contiguous, vectorised); ghosts are left alone (they are mirrored
     * afresh before every evaluation) */
    /* the sum of the k's starts at 0.0 in stage 0 (no array to clear),
     * and the last stage also makes the new state: y0 + dt/6 sum */
    const double c = stage < 3 ? a[stage + 1] * dt : dt / 6.0, wk = w[stage];
#pragma omp parallel
    for (int f = 0; f < nf; f++) {
      const size_t lof = lo[f], hif = hi[f];
      if (lof >= hif) continue;
      const double *const kf = k[f], *const y0f = s->y0[f];
      double *const ksf = s->ks[f], *const yf = y[f];
      /* static: each thread keeps its particles from field to field; in
       * strips of 64, a loop that makes every particle's values and one
       * that stores those of the particles the field is advanced for, so
       * that both vectorise (a ghost's values are made from whatever its
       * entries hold, its ks never written, and never stored; vsph
       * enables no floating-point trap) */
#pragma omp for schedule(static) nowait
      for (size_t s0 = 0; s0 < n; s0 += 64) {
        const size_t e = n - s0 < 64 ? n - s0 : 64;
        double sum[64], next[64];
#pragma omp simd
        for (size_t q = 0; q < e; q++) {
          const size_t i = s0 + q;
          const double kv = kf[i];
          sum[q] = (stage ? ksf[i] : 0.0) + wk * kv;
          next[q] = y0f[i] + c * (stage < 3 ? kv : sum[q]);
        }
#pragma omp simd
        for (size_t q = 0; q < e; q++)
          if (id[s0 + q] >= lof && id[s0 + q] < hif) {
            ksf[s0 + q] = sum[q];
            yf[s0 + q] = next[q];
          }
      }
    }
  }
  s->t += dt;
  s->steps++;
  s->interactions = nint;
  s->min_dist = sqrt(min_s2);
  return VSPH_OK;
}

/* 1 when particle j is an image of fluid particle i itself (a mirrored
 * ghost or periodic image made from it, corners included; never a fixed
 * wall particle). */
static int own_image(const struct vsph_integrate *s, size_t i, size_t j) {
  const struct vsph_particles *p = s->p;
  if (!s->gh) return 0;
  const size_t base = s->n_fluid + s->gh->keep;
  return p->id[j] >= base && p->id[j] - base < s->gh->n &&
         s->gh->src[p->id[j] - base] == p->id[i];
}

/* 1 when the run's walls hold a free-slip mirror plane (a plane of
 * symmetry, where a particle may meet its own image). */
static int symmetry_planes(const struct vsph_integrate *s) {
  const struct vsph_walls *w = &s->props.walls;
  if (!s->gh || w->solid || w->noslip) return 0;
  for (int q = 0; q < w->n; q++)
    if (w->kind[q] == VSPH_WALLS_MIRROR) return 1;
  return 0;
}

/* The closest pair with a fluid particle a, its neighbour b any particle
 * (fluid, a ghost or periodic image, a wall particle): into a[0], b[0]
 * with its squared distance returned; and the closest pair but for a
 * particle and its own image into a[1], b[1], d2[1] (a particle at a
 * mirror plane meets its own image there, and that is no pairing: its
 * image is itself, mirrored; vsph_integrate_check). One scan; none:
 * index n, distance infinity. A stop for pairing says where. */
static void closest_pair(const struct vsph_integrate *s, size_t a[2],
                         size_t b[2], double d2[2]) {
  const struct vsph_particles *p = s->p;
  d2[0] = d2[1] = INFINITY;
  a[0] = b[0] = a[1] = b[1] = p->n;
  for (size_t c = 0; c < s->cells->ncells; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, s->cells, c);
    for (size_t i = s->cells->start[c];
         i < s->cells->start[c] + s->cells->count[c]; i++) {
      if (p->id[i] >= s->n_fluid) continue;
      for (size_t r = 0; r < rg.n; r++)
        for (size_t j = rg.lo[r]; j < rg.hi[r]; j++) {
          if (j == i) continue;
          double e = 0.0;
          for (int k = 0; k < p->dim; k++) {
            const double d = p->pos[k][j] - p->pos[k][i];
            e += d * d;
          }
          if (e < d2[0]) d2[0] = e, a[0] = i, b[0] = j;
          if (e < d2[1] && !own_image(s, i, j)) d2[1] = e, a[1] = i, b[1] = j;
        }
    }
  }
}

int vsph_integrate_check(struct vsph_integrate *s) {
  if (!s) return 1;
  const struct vsph_particles *p = s->p;
  const struct vsph_integrate_props *ip = &s->props;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= s->n_fluid) continue;
    const double rho0 = vsph_equations_rho0(&ip->eq, p->mat ? p->mat[i] : 0);
    int bad = !isfinite(p->rho[i]) || (p->e && !isfinite(p->e[i]));
    for (int k = 0; k < p->dim; k++)
      bad |= !isfinite(p->pos[k][i]) || !isfinite(p->vel[k][i]);
    if (bad) {
      snprintf(s->reason, sizeof s->reason, "non-finite state of particle %zu",
               p->id[i]);
      return 1;
    }
    for (int k = 0; k < p->dim; k++)
      if (p->pos[k][i] < ip->box_lo[k] || p->pos[k][i] > ip->box_hi[k]) {
        snprintf(s->reason, sizeof s->reason,
                 "particle %zu left the domain (x_%d = %.4g)", p->id[i], k + 1,
                 p->pos[k][i]);
        return 1;
      }
    if (fabs(p->rho[i] / rho0 - 1.0) > ip->rho_band) {
      snprintf(s->reason, sizeof s->reason,
               "density of particle %zu out of band (rho/rho0 = %.4g)",
               p->id[i], p->rho[i] / rho0);
      return 1;
    }
  }
  if (s->steps > 0 && s->min_dist < ip->min_dist) {
    /* where: the closest pair now (the cells are the step's, the
     * positions moved by one step since). A particle and its own image
     * across a free-slip plane, a plane of symmetry, are one fluid element
     * mirrored (the image may meet it at the plane, or pass it): no
     * pairing, and the closest distinct pair decides. Across a no-slip
     * plane the particle has reached the wall: a stop, as any pair */
    size_t aa[2], bb[2];
    double dd[2];
    closest_pair(s, aa, bb, dd);
    size_t a = aa[0], b = bb[0];
    double d = s->min_dist;
    if (a < p->n && symmetry_planes(s)) {
      /* the step's closest pair may have been an own image at one of its
       * stages: the closest distinct pair now decides */
      if (!(sqrt(dd[1]) < ip->min_dist)) {
        s->reason[0] = '\0';
        return 0;
      }
      a = aa[1], b = bb[1], d = sqrt(dd[1]);
    }
    if (a < p->n)
      snprintf(s->reason, sizeof s->reason,
               "particle pairing: two particles %.3g apart (limit %.3g), "
               "%zu and %s%zu near (%.3g, %.3g)",
               d, ip->min_dist, p->id[a],
               p->id[b] < s->n_fluid ? "" : "image/wall ", p->id[b],
               p->pos[0][a], p->dim > 1 ? p->pos[1][a] : 0.0);
    else
      snprintf(s->reason, sizeof s->reason,
               "particle pairing: two particles %.3g apart (limit %.3g)",
               s->min_dist, ip->min_dist);
    return 1;
  }
  s->reason[0] = '\0';
  return 0;
}

int vsph_integrate_diagnostics(struct vsph_integrate *s,
                               struct vsph_equations_energy *en,
                               struct vsph_equations_budget *b) {
  if (!s || !en || !b)
    VSPH_FAIL(VSPH_EINVAL, "vsph_integrate_diagnostics: a NULL argument");
  int st = prepare(s, 0.0);
  if (!st) st = rhs(s, 1, NULL, NULL);
  if (st) return st;
  struct vsph_equations_out out = {
      .drho = s->p->drho, .drho_delta = s->extra[s->p->dim], .de = s->p->de};
  for (int k = 0; k < s->p->dim; k++) {
    out.acc[k] = s->p->acc[k];
    out.acc_visc[k] = s->extra[k];
  }
  vsph_equations_energy_compute(&s->props.eq, s->p, s->n_fluid, en);
  vsph_equations_budget_compute(&s->props.eq, s->p, s->n_fluid, &out, b);
  return VSPH_OK;
}

/* Bytes of the integrator's buffers for particle capacity cap in d
 * dimensions, cell scratch for cap_n particles and cap_cells cells. */
static size_t layout_bytes(size_t d, size_t cap, size_t cap_n, size_t cap_cells,
                           int ws, int ghosts, int tvf) {
  /* the fields, the gas law's e and de counted (an upper bound) */
  size_t b = cap * (3 * d + 7) * sizeof(double) + cap * sizeof(size_t);
  b += cap_n * 2 * sizeof(size_t); /* the cells' permutation and scratch */
  b += cap_cells * 2 * sizeof(size_t);
  /* the first-pass workspace (ws >= 1) and its corrections' S, a, L (2) */
  if (ws >= 1) b += cap * (d * d + 1) * sizeof(double) + cap;
  if (ws >= 2) b += cap * (1 + d + d * d) * sizeof(double);
  /* ghosts: source and mask, and (linear walls) the nearest rows' entries
   * (7 doubles) and their bins (two indices), counted for any wall */
  if (ghosts)
    b += cap * (3 * sizeof(size_t) + sizeof(unsigned) + 7 * sizeof(double));
  if (tvf) b += cap * 2 * d * sizeof(double);            /* tvel, bacc */
  b += cap * sizeof(size_t);                             /* where */
  b += cap * (2 * (2 * d + 2) + d + 1) * sizeof(double); /* RK, extra */
  /* the symmetric sweep's block buffers: 2 d + 2 doubles a particle (a
   * first pass: 2 d^2), times 2.5 for the blocks' overlap and the
   * buffer's growth (an estimate: 1.35 and 2.0 measured for MGF and PVWF
   * at 42 000 particles in 2-D) */
  const size_t nf = ws >= 1 && 2 * d * d > 2 * d + 2 ? 2 * d * d : 2 * d + 2;
  b += cap * nf * 5 / 2 * sizeof(double);
  return b;
}

size_t vsph_integrate_bytes(const struct vsph_integrate *s) {
  /* the sweep counted by its estimate: what it holds depends on the
   * evaluations it has seen, and a resumed run must report the same */
  if (!s) return 0;
  return layout_bytes((size_t)s->p->dim, s->p->cap, s->cells->cap_n,
                      s->cells->cap_cells, s->vws ? (s->vws->S ? 2 : 1) : 0,
                      s->gh != NULL, s->p->tvel[0] != NULL);
}

double vsph_integrate_bytes_estimate(int dim, double n_fluid, double n_ghosts,
                                     int ws, int tvf) {
  if (dim < 1 || dim > 3) return (double)NAN;
  /* the capacity reserve() grows to, and the most cells vsph_cells_build
   * makes (8 per particle + 4096) */
  const int walls = n_ghosts > 0.0;
  const double n = n_fluid + n_ghosts;
  const double cap = walls ? n + n / 8 + 64 : n + 8;
  const double per = (double)layout_bytes((size_t)dim, 1, 1, 8, ws, walls, tvf);
  return cap * per + 4096.0 * 2 * sizeof(size_t);
}

/* ------------------------------------------------------ the whole state */

/* A cursor over a state buffer (sizing when buf is NULL), or over a file
 * (f: written or read in place of buf or in; bad set by a short write). */
struct cursor {
  unsigned char *buf;
  const unsigned char *in;
  size_t at, len;
  FILE *f;
  int bad;
};

static void put(struct cursor *c, const void *src, size_t n) {
  if (c->f) {
    if (fwrite(src, 1, n, c->f) != n) c->bad = 1;
  } else if (c->buf) {
    memcpy(c->buf + c->at, src, n);
  }
  c->at += n;
}

static int get(struct cursor *c, void *dst, size_t n) {
  if (n > c->len - c->at) return 0;
  if (c->f) {
    if (fread(dst, 1, n, c->f) != n) return 0;
  } else {
    memcpy(dst, c->in + c->at, n);
  }
  c->at += n;
  return 1;
}

/* The particle arrays in a fixed order, present or not: the count
 * returned, sz[] each element's size; bit k of *derived set where array k
 * is one that every evaluation writes before anything reads it: the
 * rates (the accelerations, d rho/dt, de/dt). Not so volume and pressure
 * (wall particles' are read by the fluid's summed density before the
 * walls' own are made again) nor the transport velocity and its
 * acceleration (read by the next step's first kick). */
static int arrays(struct vsph_particles *p, void **a[32], size_t sz[32],
                  uint64_t *derived, uint64_t *volp) {
  int n = 0;
  uint64_t dv = 0, vp = 0;
  for (int k = 0; k < p->dim; k++) {
    sz[n] = sizeof(double), a[n++] = (void **)&p->pos[k];
    sz[n] = sizeof(double), a[n++] = (void **)&p->vel[k];
    dv |= 1ull << n, sz[n] = sizeof(double), a[n++] = (void **)&p->acc[k];
    sz[n] = sizeof(double), a[n++] = (void **)&p->tvel[k];
    sz[n] = sizeof(double), a[n++] = (void **)&p->bacc[k];
  }
  double **sc[7] = {&p->m, &p->rho, &p->vol, &p->p, &p->drho, &p->e, &p->de};
  static const int fresh[7] = {0, 0, 0, 0, 1, 0, 1};
  for (int k = 0; k < 7; k++) {
    if (fresh[k]) dv |= 1ull << n;
    if (k == 2 || k == 3) vp |= 1ull << n;
    sz[n] = sizeof(double), a[n++] = (void **)sc[k];
  }
  sz[n] = sizeof *p->mat, a[n++] = (void **)&p->mat;
  sz[n] = sizeof *p->id, a[n++] = (void **)&p->id;
  *derived = dv;
  *volp = vp;
  return n;
}

/* The arrays a lean pack leaves out (bits as arrays() numbers them): the
 * rates; and volume and pressure where no wall particles and no
 * transport velocity are (every evaluation then makes them from the
 * density first, ghosts and images included; wall particles' are read by
 * the fluid's sums before their own are made again, and the transport
 * velocity's step reads them). */
static uint64_t lean_out(const struct vsph_integrate *s, uint64_t derived,
                         uint64_t volp) {
  const int made = !s->props.eq.tvf && !s->props.walls.solid;
  return derived | (made ? volp : 0);
}

/* The fields kept by id between steps (s->kept): 2d for the transport
 * velocity, 2d + 1 for the leapfrog (w, a, d rho/dt), none for RK4. */
static int kept_fields(const struct vsph_integrate *s) {
  return s->props.eq.tvf     ? 2 * s->p->dim
         : s->props.leapfrog ? 2 * s->p->dim + 1
                             : 0;
}

/* ... and their length: the transport velocity's by fluid id, the
 * leapfrog's by every id (evolving wall particles' density rates). */
static size_t kept_len(const struct vsph_integrate *s) {
  return s->props.eq.tvf ? s->n_fluid : s->p->n;
}

/* vsph_integrate_pack, and with @p lean 1 vsph_integrate_pack_lean, into
 * the cursor @p cur's buffer or file */
static size_t pack(const struct vsph_integrate *s, struct cursor *cur,
                   int lean) {
  struct cursor c = *cur;
  struct vsph_particles *p = s->p;
  const uint64_t head[6] = {(uint64_t)p->dim,   (uint64_t)p->n,
                            (uint64_t)p->cap,   (uint64_t)s->n_fluid,
                            (uint64_t)s->steps, (uint64_t)s->interactions};
  put(&c, head, sizeof head);
  put(&c, &s->t, sizeof s->t);
  put(&c, &s->min_dist, sizeof s->min_dist);
  put(&c, s->reason, sizeof s->reason);
  void **a[32];
  size_t sz[32];
  uint64_t derived, volp;
  const int na = arrays(p, a, sz, &derived, &volp);
  uint64_t have = 0;
  for (int k = 0; k < na; k++) have |= (uint64_t)(*a[k] != NULL) << k;
  if (lean) have &= ~lean_out(s, derived, volp);
  put(&c, &have, sizeof have);
  for (int k = 0; k < na; k++)
    if (have >> k & 1) put(&c, *a[k], p->n * sz[k]);
  const int32_t kept = s->kept;
  put(&c, &kept, sizeof kept);
  if (kept) /* the rates kept by particle id */
    for (int f = 0; f < kept_fields(s); f++)
      put(&c, s->ks[f], kept_len(s) * sizeof(double));
  *cur = c;
  return c.at;
}

size_t vsph_integrate_pack(const struct vsph_integrate *s, unsigned char *buf) {
  struct cursor c = {.buf = buf};
  if (!s) return 0;
  return pack(s, &c, 0);
}

size_t vsph_integrate_pack_lean(const struct vsph_integrate *s,
                                unsigned char *buf) {
  struct cursor c = {.buf = buf};
  if (!s) return 0;
  return pack(s, &c, 1);
}

size_t vsph_integrate_pack_lean_file(const struct vsph_integrate *s,
                                     FILE *out) {
  if (!s || !out) return 0;
  struct cursor c = {.f = out};
  const size_t len = pack(s, &c, 1);
  return c.bad || fflush(out) ? 0 : len;
}

/* vsph_integrate_unpack, and with @p exact 0 vsph_integrate_restore: a
 * capacity grown since the packing is kept (a set cannot shrink in place;
 * the capacity decides no value, only when the set grows next) */
static int unpack(struct vsph_integrate *s, const unsigned char *buf, FILE *in,
                  size_t len, size_t *used, int exact) {
  if (!s || (!buf && !in))
    VSPH_FAIL(VSPH_EINVAL, "vsph_integrate_unpack: a NULL argument");
  size_t used_own;
  if (!used) used = &used_own;
  struct cursor c = {.in = buf, .len = len, .f = in};
  struct vsph_particles *p = s->p;
  uint64_t head[6], have;
  double t, min_dist;
  char reason[sizeof s->reason];
  if (!get(&c, head, sizeof head) || !get(&c, &t, sizeof t) ||
      !get(&c, &min_dist, sizeof min_dist) || !get(&c, reason, sizeof reason) ||
      !get(&c, &have, sizeof have))
    VSPH_FAIL(VSPH_EINVAL, "the saved state is cut short");
  if (head[0] != (uint64_t)p->dim || head[3] != (uint64_t)s->n_fluid ||
      head[1] < s->n_fluid || head[1] > head[2] || head[2] > (1ull << 40))
    VSPH_FAIL(VSPH_EINVAL,
              "the saved state holds %llu particles in %llu-D, this run "
              "%zu in %d-D",
              (unsigned long long)head[3], (unsigned long long)head[0],
              s->n_fluid, p->dim);
  void **a[32];
  size_t sz[32];
  uint64_t derived, volp;
  const int na = arrays(p, a, sz, &derived, &volp);
  const uint64_t out = lean_out(s, derived, volp);
  for (int k = 0; k < na; k++) /* a lean pack leaves some out */
    if ((have >> k & 1) != (*a[k] != NULL) && !(*a[k] && (out >> k & 1)))
      VSPH_FAIL(VSPH_EINVAL, "the saved state's fields are not this run's");
  /* the very capacity the run had: the buffers as they were */
  const size_t cap0 = p->cap;
  int st = vsph_particles_reserve(p, (size_t)head[2]);
  if (!st && (exact ? p->cap != (size_t)head[2] : p->cap < (size_t)head[2]))
    VSPH_FAIL(VSPH_EINVAL, "the saved capacity %llu cannot be restored",
              (unsigned long long)head[2]);
  /* the buffers follow the capacity (they hold no state: the next step
   * writes them before it reads them); kept as they are where it stayed,
   * as a snapshot's restore finds it, not made afresh each time */
  if (!st && p->cap != cap0) st = buffers_alloc(s);
  if (st) return st;
  p->n = (size_t)head[1];
  for (int k = 0; k < na; k++) {
    if (!*a[k]) continue;
    if (have >> k & 1) {
      if (!get(&c, *a[k], p->n * sz[k]))
        VSPH_FAIL(VSPH_EINVAL, "the saved state is cut short");
    } else { /* left out: NaN until an evaluation computes it,
                so that a read before that shows (every one is double) */
      double *x = *a[k];
      for (size_t i = 0; i < p->n; i++) x[i] = (double)NAN;
    }
  }
  int32_t kept;
  if (!get(&c, &kept, sizeof kept))
    VSPH_FAIL(VSPH_EINVAL, "the saved state is cut short");
  if (kept && !kept_fields(s))
    VSPH_FAIL(VSPH_EINVAL, "the saved state's fields are not this run's");
  if (kept)
    for (int f = 0; f < kept_fields(s); f++)
      if (!get(&c, s->ks[f], kept_len(s) * sizeof(double)))
        VSPH_FAIL(VSPH_EINVAL, "the saved state is cut short");
  /* each id below the count and none twice: they index the map from id
   * to slot (the set's capacity long), made here (the steps fill it by a
   * parallel scatter, which two equal ids would race on) */
  for (size_t i = 0; i < p->cap; i++) s->where[i] = SIZE_MAX;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= p->n || s->where[p->id[i]] != SIZE_MAX)
      VSPH_FAIL(VSPH_EINVAL, "the saved state's particle ids are damaged");
    s->where[p->id[i]] = i;
  }
  s->kept = kept != 0;
  s->t = t;
  s->min_dist = min_dist;
  s->steps = (size_t)head[4];
  s->interactions = (size_t)head[5];
  memcpy(s->reason, reason, sizeof reason);
  s->reason[sizeof s->reason - 1] = '\0';
  *used = c.at;
  return VSPH_OK;
}

int vsph_integrate_unpack(struct vsph_integrate *s, const unsigned char *buf,
                          size_t len, size_t *used) {
  return unpack(s, buf, NULL, len, used, 1);
}

int vsph_integrate_restore(struct vsph_integrate *s, const unsigned char *buf,
                           size_t len) {
  size_t used = 0;
  const int st = unpack(s, buf, NULL, len, &used, 0);
  if (!st && used != len)
    VSPH_FAIL(VSPH_EINVAL, "the kept state has %zu bytes too many", len - used);
  return st;
}

int vsph_integrate_restore_file(struct vsph_integrate *s, FILE *in,
                                size_t len) {
  size_t used = 0;
  if (!s || !in)
    VSPH_FAIL(VSPH_EINVAL, "vsph_integrate_restore_file: a NULL argument");
  if (fseek(in, 0, SEEK_SET))
    VSPH_FAIL(VSPH_EIO, "cannot read back the kept state");
  const int st = unpack(s, NULL, in, len, &used, 0);
  if (!st && used != len)
    VSPH_FAIL(VSPH_EINVAL, "the kept state has %zu bytes too many", len - used);
  return st;
}

/* The ids in the order the step finds them (s->order0, s->n0): what
 * its preparation's wrap, ghosts and sort change besides the state. */
static int keep_order(struct vsph_integrate *s) {
  const struct vsph_particles *p = s->p;
  if (p->cap > s->order0_cap) {
    size_t *o = realloc(s->order0, p->cap * sizeof *o);
    if (!o)
      VSPH_FAIL(VSPH_ENOMEM, "cannot keep the order of %zu particles", p->cap);
    s->order0 = o;
    s->order0_cap = p->cap;
  }
  memcpy(s->order0, p->id, p->n * sizeof *p->id);
  s->n0 = p->n;
  return VSPH_OK;
}

/* A stopped RK4 step put back as it began: the state fields from y0 (its
 * @p n particles after its preparation: wrapped across periodic ends,
 * ghosts made, sorted by cell), then every array in the order the step
 * found (s->order0: the order decides the ghosts' making and the sums'
 * order, so the resumed step is bitwise the step never stopped), without
 * a copy of the whole set kept at every step. A wrapped position is
 * wrapped again to itself, and the ghosts are made afresh by the next
 * preparation: what entries the old ghosts held does not matter, nor do
 * the fields computed afresh before they are read (pressure, volume,
 * rates). The stages leave mass, id and order alone. */
static void put_back(struct vsph_integrate *s, size_t n) {
  struct vsph_particles *p = s->p;
  const int nf = nfields(s);
  for (int f = 0; f < nf; f++)
    memcpy(field(p, f), s->y0[f], n * sizeof(double));
  /* each array back into the first order, through scratch ks[0] (the
   * abandoned step's rates: cap doubles); an id the preparation dropped
   * (a ghost) keeps whatever its place holds */
  for (size_t i = 0; i < s->n0; i++) s->where[s->order0[i]] = SIZE_MAX;
  map_ids(s); /* n is p->n */
  void **a[32];
  size_t sz[32];
  uint64_t derived, volp;
  const int na = arrays(p, a, sz, &derived, &volp);
  unsigned char *const tmp = (unsigned char *)s->ks[0];
  for (int k = 0; k < na; k++) {
    unsigned char *const x = *a[k];
    if (!x || x == (unsigned char *)p->id) continue;
    const size_t e = sz[k];
    for (size_t i = 0; i < s->n0; i++) {
      const size_t id = s->order0[i], at = s->where[id];
      if (at < n && p->id[at] == id)
        memcpy(tmp + i * e, x + at * e, e);
      else
        memcpy(tmp + i * e, x + i * e, e);
    }
    memcpy(x, tmp, s->n0 * e);
  }
  memcpy(p->id, s->order0, s->n0 * sizeof *p->id);
  p->n = s->n0;
  map_ids(s);
}
