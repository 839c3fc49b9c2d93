/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_EQUATIONS_INTERNAL_H
#define VSPH_SOLVER_EQUATIONS_INTERNAL_H

/* The right-hand side's neighbour loops as templates (VSPH_CONSTS_SPECIALISE
 * bodies with the dimension, the kernel, the switches and the viscous pair
 * function as parameters): the gather of one cell (rhs_cell) and the
 * symmetric sweep of one block (sweep_block). solver/equations.c
 * instantiates the general loop, each family of formulations with loops of
 * its own its specialised ones (solver/forms/, through
 * solver/viscous_internal.h's VSPH_VISCOUS_LOOPS), where a constant pair
 * function inlines and the component loops unroll; solver/sweep_x86.c reads its
 * structs for the Brookshaw forms' 2-D sweep in AVX-512 lanes, which
 * sweep_block hands their blocks to. Within solver/ only. */

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "../common/consts.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "equations.h"
#include "pair.h"
#include "particles.h"
#include "sweep_x86.h"
#include "viscous.h"

/* The body force at x (the public function's, without its argument check:
 * the loops call it per particle). */
static inline void body_force(const struct vsph_equations_props *ep,
                              const double x[3], double g[3]) {
  g[0] = g[1] = g[2] = 0.0;
  const int d = ep->visc.dim;
  if (ep->body == VSPH_EQUATIONS_BODY_RADIAL) {
    for (int k = 0; k < d; k++) g[k] = -ep->beta * ep->beta * x[k];
  } else if (ep->body == VSPH_EQUATIONS_BODY_GRAVITY) {
    g[d - 1] = -ep->g; /* the last axis points up */
  } else if (ep->body == VSPH_EQUATIONS_BODY_UNIFORM) {
    g[0] = ep->f;
  }
}

/* Loop constants of the right-hand side, loaded once per evaluation. */
struct vsph_equations_ctx {
  const struct vsph_equations_props *ep;
  struct vsph_pair_kernel pk;       /* kernel, h: the neighbour loop */
  struct vsph_viscous_loop vl;      /* the viscous term */
  double dhc;                       /* delta h c0 (delta-SPH), 0: off */
  int parts;                        /* fill acc_visc / drho_delta */
  int gas;                          /* the gas law: the energy equation too */
  int reduce;                       /* Basa's pressure reduction */
  int corr;                         /* vsph_pair_corr */
  const struct vsph_viscous_ws *ws; /* the corrections' S, a, L */
  int tvf;                          /* the transport-velocity scheme */
  double pb;                        /* its background pressure */
  double w0;                        /* W(0) */
  double wf;                        /* h^-d: W = wf w(s/h) */
  /* contact SPH: each material's sound speed, and each pair of
   * materials' eta_eff - zeta eta_eff^num (0: no viscous term) */
  double cmat[VSPH_EQUATIONS_MAT_MAX];
  double etap[VSPH_EQUATIONS_MAT_MAX][VSPH_EQUATIONS_MAT_MAX];
  int cvisc;
  int fixed[VSPH_EQUATIONS_MAT_MAX]; /* materials held in place */
};

/* The viscous share of pair @p pr by the pair function @p pair (NULL:
 * none, the per-particle forms'): a constant @p pair (a family's loops)
 * inlines, the general loop calls its form's through the descriptor. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_visc viscous_share(
    vsph_viscous_pair_fn *const pair, const struct vsph_viscous_loop *lp,
    const int dim, const struct vsph_pair *pr, const struct vsph_pair_vec du,
    double dux, const double Ai[9]) {
  if (pair) return pair(lp, dim, pr, du, dux, Ai);
  const struct vsph_pair_visc r = {{0.0, 0.0, 0.0}, 0.0};
  return r;
}

/* The transport-velocity scheme's terms of pair @p pr (i's row): the
 * anisotropic stress (A_i + A_j) . grad_i W = -F (A_i + A_j) x taken off
 * the pressure share @p f (A_i in @p tA; j's from its density @p rhoj,
 * velocities @p vel and transport velocities @p tv), and the background
 * push's share, returned: 2 pb in place of the pressure sum. */
VSPH_CONSTS_SPECIALISE struct vsph_pair_vec tvf_pair(
    const struct vsph_pair *pr, const int dim, const double *tA, double rhoj,
    const double *const *vel, const double *const *tv, size_t j, double pb,
    double *f) {
  for (int a = 0; a < dim; a++) {
    double s = 0.0;
    for (int c = 0; c < dim; c++)
      s += (tA[a * dim + c] + rhoj * vel[a][j] * (tv[c][j] - vel[c][j])) *
           pr->x[c];
    f[a] -= pr->VF * s;
  }
  return vsph_pair_pressure(pr, dim, 2.0 * pb);
}

/* Particle i's correction terms from the first pass's workspace @p ws:
 * its S, a and (@p bl, Bonet and Lok's) L. */
VSPH_CONSTS_SPECIALISE void corr_load(const struct vsph_viscous_ws *ws,
                                      size_t i, const int dim, const int bl,
                                      double *cS, double *ca, double *cL) {
  *cS = ws->S[i];
  for (int e = 0; e < dim; e++) ca[e] = ws->a[e][i];
  for (int e = 0; e < dim * dim && bl; e++) cL[e] = ws->L[e][i];
}

/* i's own term of the corrected pressure sum, added to @p ap: g_ii =
 * -W(0) a/S^2 (L) with @p w0 = W(0), i's volume @p vi and pressure
 * @p pi. */
VSPH_CONSTS_SPECIALISE void corr_self(double w0, double vi, double pi, size_t i,
                                      const int dim, double cS,
                                      const double *ca, const double *cL,
                                      const int bl, double *ap) {
  struct vsph_pair self = {.j = i, .s2 = 0.0, .F = 0.0, .VF = 0.0};
  double cg[3], fs[3];
  vsph_pair_corr_grad(&self, dim, w0, cS, ca, cL, bl, cg);
  vsph_pair_pressure_g(vi, dim, 2.0 * pi, cg, fs);
  for (int k = 0; k < dim; k++) ap[k] += fs[k];
}

/* Particle i's rates from its sums (rhs_one's last step): the continuity
 * sum @p cont and delta-SPH's @p dsum, the pressure and viscous sums
 * @p ap and @p av, the transport velocity's background push @p tb (NULL:
 * none), and the body force at i's place @p xi. */
VSPH_CONSTS_SPECIALISE void rhs_write(const struct vsph_equations_ctx *rc,
                                      const struct vsph_particles *p, size_t i,
                                      const double *xi, const int dim,
                                      double cont, double dsum,
                                      const double *ap, const double *av,
                                      const double *tb,
                                      struct vsph_equations_out *out) {
  const double rhoi = p->rho[i], rinv = 1.0 / rhoi;
  /* the gas law's energy equation, de/dt = (p/rho^2) (d rho/dt) of the
   * continuity sum (docs/theory.md section 10): the compression work of
   * the pressure terms, ghosts included; delta-SPH moves rho, not e */
  if (rc->gas) out->de[i] = p->p[i] * cont * rinv;
  double g[3];
  body_force(rc->ep, xi, g);
  out->drho[i] = rhoi * cont + rc->dhc * dsum;
  for (int k = 0; k < dim; k++) out->acc[k][i] = rinv * (ap[k] + av[k]) + g[k];
  if (tb)
    for (int k = 0; k < dim; k++) p->bacc[k][i] = rinv * tb[k];
  if (rc->parts) {
    for (int k = 0; k < dim; k++) out->acc_visc[k][i] = rinv * av[k];
    out->drho_delta[i] = rc->dhc * dsum;
  }
}

/* Particle i's own state for its pair loop (rhs_one): its velocity and
 * PVWF's A_i; with @p tvf the transport velocity's A_i; with @p corr the
 * corrections' S, a and (Bonet and Lok's) L. */
struct rhs_i {
  double ui[3], Ai[9], tA[9];
  double rhoi, pi;
  double cS, ca[3], cL[9];
};

VSPH_CONSTS_SPECIALISE void rhs_load(const struct vsph_equations_ctx *rc,
                                     const struct vsph_particles *p, size_t i,
                                     const int dim, const int corr,
                                     const int tvf, struct rhs_i *s) {
  for (int k = 0; k < 3; k++) s->ui[k] = 0.0, s->ca[k] = 0.0;
  for (int k = 0; k < 9; k++) s->Ai[k] = 0.0, s->tA[k] = 0.0, s->cL[k] = 0.0;
  for (int k = 0; k < dim; k++) s->ui[k] = p->vel[k][i];
  vsph_viscous_load_A(&rc->vl, i, s->Ai);
  s->rhoi = p->rho[i], s->pi = p->p[i], s->cS = 1.0;
  if (tvf)
    for (int a = 0; a < dim; a++)
      for (int c = 0; c < dim; c++)
        s->tA[a * dim + c] = s->rhoi * s->ui[a] * (p->tvel[c][i] - s->ui[c]);
  if (corr)
    corr_load(rc->ws, i, dim, corr == VSPH_PAIR_CORR_BONETLOK, &s->cS, s->ca,
              s->cL);
}

/* The corrected pair (rhs_one with @p corr, the general loop only): every
 * grad W of pair @p pr corrected (vsph_pair_corr_grad), its pressure share
 * into @p f and its viscous share into @p g by the form's corrected pair
 * term @p pair_g (its descriptor's), du = u_j - u_i (@p du) and @p dux =
 * du.x. Returns the continuity share. */
VSPH_CONSTS_SPECIALISE double rhs_corr_pair(
    const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
    const struct rhs_i *s, const struct vsph_pair *pr, const int dim,
    vsph_viscous_pair_g_fn *const pair_g, const double du[3], double dux,
    double f[3], double g[3]) {
  const size_t j = pr->j;
  const double vj = p->vol[j], h = rc->ep->visc.h;
  const double w =
      vsph_kernel_w(rc->ep->visc.kernel, dim, sqrt(pr->s2) / h) * rc->wf;
  double cg[3];
  vsph_pair_corr_grad(pr, dim, w, s->cS, s->ca, s->cL,
                      rc->corr == VSPH_PAIR_CORR_BONETLOK, cg);
  vsph_pair_pressure_g(vj, dim, s->pi + p->p[j], cg, f);
  pair_g(&rc->vl, dim, pr, vj, du, dux, cg, g);
  return vsph_pair_continuity_g(vj, dim, du, cg);
}

/* Particle i's last step (rhs_one): its own viscous share, the corrected
 * pressure sum's own term (@p corr), the reduction (@p reduce: the
 * neighbours' pressures @p pn, sum_j V_j F x @p gx, over @p nint
 * neighbours), then its rates (rhs_write). */
VSPH_CONSTS_SPECIALISE void rhs_finish(
    const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
    size_t i, const struct rhs_i *s, const double *xi, const int dim,
    const int corr, const int reduce, size_t nint, double pn,
    const double gx[3], double cont, double dsum, double ap[3], double av[3],
    const double *tb, struct vsph_equations_out *out) {
  vsph_viscous_own(&rc->vl, i, av);
  if (corr)
    corr_self(rc->w0, p->vol[i], s->pi, i, dim, s->cS, s->ca, s->cL,
              corr == VSPH_PAIR_CORR_BONETLOK, ap);
  if (reduce) { /* Basa's eq. (20): p_i + p_j - 2 pbar_i, i among the mean */
    const double pbar = (s->pi + pn) / (double)(nint + 1);
    for (int k = 0; k < dim; k++) ap[k] -= 2.0 * pbar * gx[k];
  }
  rhs_write(rc, p, i, xi, dim, cont, dsum, ap, av, tb, out);
}

/* One fluid particle: every term of THEORY 5 gathered over its neighbours,
 * each through its pair function (pair.h, solver/forms/). Per chunk of
 * neighbours, the pairs' shares are computed in one loop the compiler
 * vectorises (gathers and arithmetic, no sums), then summed in neighbour
 * order. Inlined once per dimension, pair function and switch (see
 * rhs_cell): the constants unroll the component loops and inline the
 * pair function. */
VSPH_CONSTS_SPECIALISE size_t rhs_one(
    const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
    const struct vsph_pair_ranges *rg, size_t i, struct vsph_equations_out *out,
    double *min_s2, const int dim, vsph_viscous_pair_fn *const pair,
    vsph_viscous_pair_g_fn *const pair_g, const int delta, const int kid,
    const int reduce, const int corr, const int tvf) {
  struct rhs_i s;
  rhs_load(rc, p, i, dim, corr, tvf, &s);
  const double rhoi = s.rhoi, pi = s.pi;
  const double *const ui = s.ui, *const tA = s.tA, *const Ai = s.Ai;
  const double *const rho = p->rho, *const pp = p->p;
  const double *const vel[3] = {p->vel[0], dim > 1 ? p->vel[1] : NULL,
                                dim > 2 ? p->vel[2] : NULL};
  const double *const tv[3] = {p->tvel[0], p->tvel[1], p->tvel[2]};
  double cont = 0.0, dsum = 0.0, ms2 = INFINITY;
  /* the reduction's neighbour pressures and sum_j V_j F x */
  double pn = 0.0, gx0 = 0.0, gx1 = 0.0, gx2 = 0.0;
  size_t nint = 0;
  struct vsph_pair_iter it;
  struct vsph_pair_chunk b;
  vsph_pair_begin(&it, &rc->pk, p, rg, i);
  /* the sums, one per component: scalars, so the loop can reduce them
   * lane by lane */
  double ap0 = 0, ap1 = 0, ap2 = 0, av0 = 0, av1 = 0, av2 = 0;
  double tb0 = 0, tb1 = 0, tb2 = 0; /* the background push's sum */
  while (vsph_pair_gather(&it, dim, kid, &b)) {
    const size_t m = b.m;
#pragma omp simd reduction(+ : cont, dsum, ap0, ap1, ap2, av0, av1, av2, \
                              pn, gx0, gx1, gx2, tb0, tb1, tb2)         \
    reduction(min : ms2)
    for (size_t k = 0; k < m; k++) {
      struct vsph_pair pr;
      vsph_pair_at(&b, k, dim, &pr);
      const size_t j = pr.j;
      double du[3], dux = 0.0, f[3], g[3];
      struct vsph_pair_vec duv;
      for (int a = 0; a < dim; a++) {
        du[a] = duv.v[a] = vel[a][j] - ui[a];
        dux += du[a] * pr.x[a];
      }
      ms2 = pr.s2 < ms2 ? pr.s2 : ms2;
      if (delta) dsum += vsph_pair_delta(&pr, rho[j] - rhoi);
      if (corr) { /* every grad W corrected (the general loop only) */
        cont += rhs_corr_pair(rc, p, &s, &pr, dim, pair_g, du, dux, f, g);
      } else { /* not through a helper: the loop vectorises as it stands */
        cont += vsph_pair_continuity(&pr, dux);
        const struct vsph_pair_vec fp =
            vsph_pair_pressure(&pr, dim, pi + pp[j]);
        const struct vsph_pair_visc gv =
            viscous_share(pair, &rc->vl, dim, &pr, duv, dux, Ai);
        for (int a = 0; a < dim; a++) f[a] = fp.v[a], g[a] = gv.f[a];
      }
      if (tvf) {
        const struct vsph_pair_vec fbv =
            tvf_pair(&pr, dim, tA, rho[j], vel, tv, j, rc->pb, f);
        tb0 += fbv.v[0];
        if (dim > 1) tb1 += fbv.v[1];
        if (dim > 2) tb2 += fbv.v[2];
      }
      if (reduce) {
        pn += pp[j];
        gx0 += pr.VF * pr.x[0];
        if (dim > 1) gx1 += pr.VF * pr.x[1];
        if (dim > 2) gx2 += pr.VF * pr.x[2];
      }
      ap0 += f[0];
      av0 += g[0];
      if (dim > 1) {
        ap1 += f[1];
        av1 += g[1];
      }
      if (dim > 2) {
        ap2 += f[2];
        av2 += g[2];
      }
    }
    nint += m;
  }
  double ap[3] = {ap0, ap1, ap2}, av[3] = {av0, av1, av2};
  const double gx[3] = {gx0, gx1, gx2}, tb[3] = {tb0, tb1, tb2};
  rhs_finish(rc, p, i, &s, it.xi, dim, corr, reduce, nint, pn, gx, cont, dsum,
             ap, av, tvf ? tb : NULL, out);
  *min_s2 = ms2;
  return nint;
}

/* The fluid particles of cell c; returns the interactions, the closest
 * pair in *min_s2. Inlined into one function per loop shape (the general
 * loop in equations.c, a family's in its file of solver/forms/). */
VSPH_CONSTS_SPECIALISE size_t
rhs_cell(const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
         const struct vsph_cells *cells, size_t c, size_t n_fluid,
         struct vsph_equations_out *out, double *min_s2, const int dim,
         vsph_viscous_pair_fn *const pair, vsph_viscous_pair_g_fn *const pair_g,
         const int delta, const int kid, const int reduce, const int corr,
         const int tvf) {
  struct vsph_pair_ranges rg;
  vsph_pair_ranges_cell(&rg, cells, c);
  const size_t i0 = cells->start[c], i1 = i0 + cells->count[c];
  size_t total = 0;
  double ms2 = INFINITY;
  for (size_t i = i0; i < i1; i++) {
    if (p->id[i] >= n_fluid) continue;
    double m;
    total += rhs_one(rc, p, &rg, i, out, &m, dim, pair, pair_g, delta, kid,
                     reduce, corr, tvf);
    ms2 = m < ms2 ? m : ms2;
  }
  *min_s2 = ms2;
  return total;
}

/* One cell's loop, specialised. */
typedef size_t vsph_equations_cell_fn(const struct vsph_equations_ctx *rc,
                                      const struct vsph_particles *p,
                                      const struct vsph_cells *cells, size_t c,
                                      size_t n_fluid,
                                      struct vsph_equations_out *out,
                                      double *min_s2);

/* ------------------------------------------------- the symmetric sweep */

struct vsph_equations_sweep {
  /* the blocks of this evaluation: the cells' own (struct vsph_cells,
   * planned with their build), borrowed */
  size_t nblk;      /* blocks */
  const size_t *c0; /* first cell of each block; c0[nblk] = ncells */
  const size_t *lo; /* the first particle each block's buffer holds ... */
  const size_t *hi; /* ... and one past its last */
  size_t *off;      /* where each block's buffer starts in buf (doubles) */
  size_t cap_off;   /* allocated offsets */
  double *buf;      /* the blocks' buffers, nf doubles per particle */
  size_t cap_buf;   /* allocated doubles */
  double *rows;     /* each thread's scratch rows (sweep_each_block) */
  size_t cap_rows;  /* allocated doubles */
  /* in a set with ghosts or wall particles: per cell, 1 where none lies
   * in its ranges (sweep_clean), so that its receivers' interactions are
   * counted without looking each pair's j up; NULL: look every j up */
  const unsigned char *clean;
  unsigned char *flags; /* its room: two bytes a cell */
  size_t cap_flags;     /* allocated bytes */
};

/* One block's sweep, specialised. */
typedef size_t vsph_equations_sweep_fn(const struct vsph_equations_ctx *rc,
                                       const struct vsph_particles *p,
                                       const struct vsph_cells *cells,
                                       size_t n_fluid,
                                       const struct vsph_equations_sweep *sw,
                                       size_t blk, int nf, double *min_s2);

/* The buffer fields of a particle: the force (pressure and viscous) per
 * component, the continuity sum, the delta-SPH sum, and, with parts, the
 * viscous force alone. */
#define SW_F 0
#define SW_CONT(d) (d)
#define SW_DELTA(d) ((d) + 1)
#define SW_VISC(d) ((d) + 2)
/* The buffer's fields: force and continuity; the delta-SPH sum with
 * delta-SPH or the parts; the viscous force with the parts (run_sweep
 * plans the buffers with it, sweep_block_parts fills them). */
#define SW_FIELDS(d, delta, parts) \
  ((parts) ? SW_VISC(d) + (d) : SW_DELTA(d) + ((delta) ? 1 : 0))

/* Add the first @p na fields of the @p m pairs' shares @p js to their
 * receivers j (@p jj) in block buffer @p buf (first particle @p lo,
 * @p nf fields each), in pair order. */
VSPH_CONSTS_SPECIALISE void sweep_add(double *buf, size_t lo, const int nf,
                                      const size_t *jj, size_t m,
                                      double js[][VSPH_PAIR_CHUNK_MAX],
                                      const int na) {
  for (size_t k = 0; k < m; k++) {
    double *const q = buf + (jj[k] - lo) * (size_t)nf;
    for (int a = 0; a < na; a++) q[a] += js[a][k];
  }
}

/* Add particle i's own sums to its entry @p q of a block's buffer: the
 * force @p fs, continuity @p cont, delta-SPH's @p dsum (where the buffer
 * holds it) and (@p parts) the viscous part @p vs. */
VSPH_CONSTS_SPECIALISE void sweep_own(double *q, const int dim, int nf,
                                      const int parts, const double *fs,
                                      const double *vs, double cont,
                                      double dsum) {
  for (int a = 0; a < dim; a++) q[SW_F + a] += fs[a];
  q[SW_CONT(dim)] += cont;
  if (nf > SW_DELTA(dim)) q[SW_DELTA(dim)] += dsum;
  if (parts)
    for (int a = 0; a < dim; a++) q[SW_VISC(dim) + a] += vs[a];
}

/* The interactions of chunk @p b of particle i's pairs (sweep_block):
 * each fluid receiver counts once (j: all of them where no ghost can be
 * among them, @p fluid_only; i: all its pairs where it is fluid, @p fi). The
 * chunk's closest pair into @p rs2 (i's, where it is fluid), or, where i
 * is a ghost, its fluid neighbours' closest into @p ms2 (all of them where
 * every j is fluid). */
VSPH_CONSTS_SPECIALISE size_t sweep_count(const struct vsph_pair_chunk *b,
                                          const size_t *id, size_t n_fluid,
                                          int fluid_only, int fi, double *rs2,
                                          double *ms2) {
  const size_t m = b->m;
  double r = *rs2;
#pragma omp simd reduction(min : r)
  for (size_t k = 0; k < m; k++) r = b->s2[k] < r ? b->s2[k] : r;
  *rs2 = r;
  size_t nfj = m; /* fluid receivers j: all, in a set without ghosts */
  if (!fluid_only) {
    nfj = 0;
    for (size_t k = 0; k < m; k++) nfj += id[b->j[k]] < n_fluid;
  }
  if (!fi)
    for (size_t k = 0; k < m; k++)
      if (nfj == m || id[b->j[k]] < n_fluid)
        *ms2 = b->s2[k] < *ms2 ? b->s2[k] : *ms2;
  return nfj + (fi ? m : 0);
}

/* The sweep of one block: each particle i of its cells meets its
 * neighbours j > i once. The pair's unit shares (V_i and V_j left out)
 * are computed in one vectorised loop per chunk: the force s (pressure
 * and viscous, odd in the pair: i gets V_j s, j gets -V_i s), the
 * continuity c = F du.x (even: i gets V_j c, j V_i c) and the delta-SPH
 * term d = -2 F (rho_j - rho_i) (odd). i's shares are summed in that loop
 * (lane by lane, as the gather does), j's then added to the block's
 * buffer in pair order; i's sums go to the buffer after its row, so every
 * particle's entry in a block depends on the block's pairs and their
 * order alone. A pair of two ghosts is computed as any other (its shares
 * go to entries nobody reads). Returns the interactions (each fluid
 * receiver of a pair counts once) and the closest pair. */
VSPH_CONSTS_SPECIALISE size_t sweep_block_parts(
    const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
    const struct vsph_cells *cells, size_t n_fluid,
    const struct vsph_equations_sweep *sw, size_t blk, double *min_s2,
    const int dim, vsph_viscous_pair_fn *const pair, const int delta,
    const int kid, const int parts) {
  /* the buffer's fields (solver/equations.c sets them so), a constant
   * here, as are the fields j's shares fill: the viscous part's with the
   * parts, the delta-SPH sum with delta-SPH or the parts */
  const int nf = SW_FIELDS(dim, delta, parts);
  const int dsw = delta || parts; /* the buffer holds delta-SPH's sum */
  const size_t lo = sw->lo[blk];
  double *const buf = sw->buf + sw->off[blk];
  memset(buf, 0, (sw->hi[blk] - lo) * (size_t)nf * sizeof *buf);
  const double *const rho = p->rho, *const pp = p->p, *const vol = p->vol;
  const size_t *const id = p->id;
  const double *const vel[3] = {p->vel[0], dim > 1 ? p->vel[1] : NULL,
                                dim > 2 ? p->vel[2] : NULL};
  size_t total = 0;
  double ms2 = INFINITY;
  const int fluid_only = p->n == n_fluid; /* no ghosts nor wall particles */
  /* a cell's receivers walk their rows together where the CPU allows:
   * each gets the chunks its own walk would give, to the bit */
  struct vsph_pair_cell pc;
  for (size_t c = sw->c0[blk]; c < sw->c0[blk + 1]; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    const size_t s0 = cells->start[c], cnt = cells->count[c];
    vsph_pair_cell_begin(&pc, &rc->pk, s0, cnt, dim);
    /* its receivers' neighbours all fluid: none looked up to count */
    const int clean = fluid_only || (sw->clean && sw->clean[c]);
    for (size_t i = s0; i < s0 + cnt; i++) {
      const int fi = id[i] < n_fluid;
      double ui[3] = {0, 0, 0}, Ai[9] = {0};
      for (int a = 0; a < dim; a++) ui[a] = vel[a][i];
      vsph_viscous_load_A(&rc->vl, i, Ai);
      const double rhoi = rho[i], pi = pp[i], Vi = vol[i];
      double cont = 0, dsum = 0, f0 = 0, f1 = 0, f2 = 0, v0 = 0, v1 = 0, v2 = 0,
             rs2 = INFINITY;
      struct vsph_pair_iter it;
      struct vsph_pair_chunk own;
      const struct vsph_pair_chunk *bq;
      vsph_pair_begin_upper_in(&it, &rc->pk, p, &rg, &pc, i);
      while (vsph_pair_next_chunk(&it, dim, kid, 1, &own, &bq)) {
        const size_t m = bq->m;
        /* i's unit shares; j's shares (V_i applied, signed for j) */
        double sf[3][VSPH_PAIR_CHUNK_MAX], sv[3][VSPH_PAIR_CHUNK_MAX],
            sc[VSPH_PAIR_CHUNK_MAX], sd[VSPH_PAIR_CHUNK_MAX],
            vj[VSPH_PAIR_CHUNK_MAX], js[8][VSPH_PAIR_CHUNK_MAX];
        /* the pairs' unit shares: a map, no sums, so that it vectorises */
#pragma omp simd
        for (size_t k = 0; k < m; k++) {
          struct vsph_pair pr;           /* VF = F: unit shares, V_i and V_j */
          vsph_pair_at(bq, k, dim, &pr); /* applied below */
          const size_t j = pr.j;
          struct vsph_pair_vec du;
          double dux = 0.0;
          for (int a = 0; a < dim; a++) {
            du.v[a] = vel[a][j] - ui[a];
            dux += du.v[a] * pr.x[a];
          }
          sc[k] = vsph_pair_continuity(&pr, dux);
          if (dsw) sd[k] = delta ? vsph_pair_delta(&pr, rho[j] - rhoi) : 0.0;
          const struct vsph_pair_vec f =
              vsph_pair_pressure(&pr, dim, pi + pp[j]);
          const struct vsph_pair_visc g =
              viscous_share(pair, &rc->vl, dim, &pr, du, dux, Ai);
          for (int a = 0; a < dim; a++) {
            sf[a][k] = f.v[a] + g.f[a];
            if (parts) sv[a][k] = g.f[a];
            js[SW_F + a][k] = -(Vi * sf[a][k]);
            if (parts) js[SW_VISC(dim) + a][k] = -(Vi * g.f[a]);
          }
          js[SW_CONT(dim)][k] = Vi * sc[k];
          if (dsw) js[SW_DELTA(dim)][k] = -(Vi * sd[k]);
          vj[k] = vol[j];
        }
        /* i's sums, lane by lane */
#pragma omp simd reduction(+ : cont, dsum, f0, f1, f2, v0, v1, v2)
        for (size_t k = 0; k < m; k++) {
          cont += vj[k] * sc[k];
          if (dsw) dsum += vj[k] * sd[k];
          f0 += vj[k] * sf[0][k];
          if (parts) v0 += vj[k] * sv[0][k];
          if (dim > 1) {
            f1 += vj[k] * sf[1][k];
            if (parts) v1 += vj[k] * sv[1][k];
          }
          if (dim > 2) {
            f2 += vj[k] * sf[2][k];
            if (parts) v2 += vj[k] * sv[2][k];
          }
        }
        /* j's shares, in pair order (a ghost's are never read): the
         * force, continuity and (delta) the diffusion, or every field */
        if (VSPH_PAIR_X86 && (nf == 3 || nf == 4) && rc->pk.simd)
          vsph_sweep_x86_add_avx2(buf, lo, nf, bq->j, m, js[0],
                                  VSPH_PAIR_CHUNK_MAX);
        else
          sweep_add(buf, lo, nf, bq->j, m, js, nf);
        total += sweep_count(bq, id, n_fluid, clean, fi, &rs2, &ms2);
      }
      if (!fi) continue;
      ms2 = rs2 < ms2 ? rs2 : ms2;
      const double fs[3] = {f0, f1, f2}, vs[3] = {v0, v1, v2};
      sweep_own(buf + (i - lo) * (size_t)nf, dim, nf, parts, fs, vs, cont,
                dsum);
    }
  }
  *min_s2 = ms2;
  return total;
}

/* sweep_block_parts with the parts (rc->parts) a constant too; @p nf,
 * the buffer's fields, is what run_sweep planned by the same SW_FIELDS
 * that sweep_block_parts makes a constant of. @p groups (a family's
 * VSPH_VISCOUS_GROUPS: VSPH_SWEEP_X86_BROOKSHAW_TERM for the Brookshaw
 * forms' loops, VSPH_SWEEP_X86_MEAF_TERM for MEAF's,
 * VSPH_SWEEP_X86_STRESS_TERM for PVWF's and B's, 0 for the others): in
 * 2-D with the Gaussian, with delta-SPH or without, without the parts, on
 * a CPU with AVX-512 or AVX2 and in a build that allows it
 * (VSPH_SWEEP_X86_GROUPS), the block goes to
 * vsph_sweep_x86_groups2_avx512 or _avx2 (within rounding,
 * solver/sweep_x86.h). */
VSPH_CONSTS_SPECIALISE size_t
sweep_block(const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
            const struct vsph_cells *cells, size_t n_fluid,
            const struct vsph_equations_sweep *sw, size_t blk, int nf,
            double *min_s2, const int dim, vsph_viscous_pair_fn *const pair,
            const int delta, const int kid, const int groups) {
  (void)nf; /* = SW_FIELDS(dim, delta, rc->parts): run_sweep's plan */
#if VSPH_SWEEP_X86_GROUPS
  /* the Brookshaw forms, MEAF, PVWF or B in 2-D with the Gaussian: their
   * sweep by cell groups in AVX-512 lanes, or AVX2 ones, where the CPU has
   * them (solver/sweep_x86.c), within rounding */
  if (groups && dim == 2 && kid == VSPH_KERNEL_DFQ_GAUSSIAN && !rc->parts &&
      rc->pk.simd)
    return rc->pk.simd == 2
               ? vsph_sweep_x86_groups2_avx512(rc, p, cells, n_fluid, sw, blk,
                                               delta, groups, min_s2)
               : vsph_sweep_x86_groups2_avx2(rc, p, cells, n_fluid, sw, blk,
                                             delta, groups, min_s2);
#else
  (void)groups; /* read only where the groups' sweeps are built */
#endif
  return rc->parts ? sweep_block_parts(rc, p, cells, n_fluid, sw, blk, min_s2,
                                       dim, pair, delta, kid, 1)
                   : sweep_block_parts(rc, p, cells, n_fluid, sw, blk, min_s2,
                                       dim, pair, delta, kid, 0);
}

#endif /* VSPH_SOLVER_EQUATIONS_INTERNAL_H */
