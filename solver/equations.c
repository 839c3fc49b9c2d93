/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "equations.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "cells_internal.h"
#include "equations_internal.h"
#include "pair.h"
#include "particles.h"
#include "share_internal.h"
#include "viscous_internal.h"
#include "walls.h"

static const char *const EOS_NAMES[VSPH_EQUATIONS_EOS_COUNT] = {
    [VSPH_EQUATIONS_EOS_LINEAR] = "linear",
    [VSPH_EQUATIONS_EOS_TAIT] = "tait",
    [VSPH_EQUATIONS_EOS_GAS] = "gas",
    [VSPH_EQUATIONS_EOS_ISOTHERMAL] = "isothermal"};

static const char *const CORR_NAMES[VSPH_PAIR_CORR_COUNT] = {
    [VSPH_PAIR_CORR_NONE] = "none",
    [VSPH_PAIR_CORR_SHEPARD] = "shepard",
    [VSPH_PAIR_CORR_BONETLOK] = "bonetlok"};

static const char *const SCHEME_NAMES[VSPH_EQUATIONS_SCHEME_COUNT] = {
    [VSPH_EQUATIONS_WCSPH] = "wcsph", [VSPH_EQUATIONS_CONTACT] = "contact"};

int vsph_equations_scheme_resolve(const char *name, int *scheme) {
  if (!name || !scheme)
    VSPH_FAIL(VSPH_EINVAL, "vsph_equations_scheme_resolve: a NULL argument");
  for (*scheme = 0; *scheme < VSPH_EQUATIONS_SCHEME_COUNT; ++*scheme)
    if (strcmp(name, SCHEME_NAMES[*scheme]) == 0) return VSPH_OK;
  *scheme = -1;
  VSPH_FAIL(VSPH_EINVAL, "unknown scheme Solver:scheme = '%s' (wcsph, contact)",
            name);
}

int vsph_equations_eos_resolve(const char *name, int *eos) {
  if (!name || !eos)
    VSPH_FAIL(VSPH_EINVAL, "vsph_equations_eos_resolve: a NULL argument");
  for (*eos = 0; *eos < VSPH_EQUATIONS_EOS_COUNT; ++*eos)
    if (strcmp(name, EOS_NAMES[*eos]) == 0) return VSPH_OK;
  *eos = -1;
  VSPH_FAIL(VSPH_EINVAL,
            "unknown state equation Solver:eos = '%s' (linear, tait, gas, "
            "isothermal)",
            name);
}

int vsph_equations_corr_resolve(const char *name, int *corr) {
  if (!name || !corr)
    VSPH_FAIL(VSPH_EINVAL, "vsph_equations_corr_resolve: a NULL argument");
  for (*corr = 0; *corr < VSPH_PAIR_CORR_COUNT; ++*corr)
    if (strcmp(name, CORR_NAMES[*corr]) == 0) return VSPH_OK;
  *corr = -1;
  VSPH_FAIL(VSPH_EINVAL,
            "unknown correction Solver:correction = '%s' (none, shepard, "
            "bonetlok)",
            name);
}

const char *vsph_equations_eos_name(int eos) {
  return eos >= 0 && eos < VSPH_EQUATIONS_EOS_COUNT ? EOS_NAMES[eos]
                                                    : "unknown";
}

const char *vsph_equations_scheme_name(int scheme) {
  return scheme >= 0 && scheme < VSPH_EQUATIONS_SCHEME_COUNT
             ? SCHEME_NAMES[scheme]
             : "unknown";
}

const char *vsph_equations_corr_name(int corr) {
  return corr >= 0 && corr < VSPH_PAIR_CORR_COUNT ? CORR_NAMES[corr]
                                                  : "unknown";
}

void vsph_equations_body_force(const struct vsph_equations_props *ep,
                               const double x[3], double g[3]) {
  if (!ep || !x || !g) return;
  body_force(ep, x, g);
}

double vsph_equations_potential(const struct vsph_equations_props *ep,
                                const double x[3]) {
  if (!ep || !x) return NAN;
  const int d = ep->visc.dim;
  if (ep->body == VSPH_EQUATIONS_BODY_RADIAL) {
    double r2 = 0.0;
    for (int k = 0; k < d; k++) r2 += x[k] * x[k];
    return 0.5 * ep->beta * ep->beta * r2;
  }
  if (ep->body == VSPH_EQUATIONS_BODY_GRAVITY) return ep->g * x[d - 1];
  return 0.0;
}

/* Basa et al.'s corrections, first pass: S_i = sum_j V_j W_ij (j = i
 * included), a_i = sum_j V_j grad_i W_ij and, for Bonet-Lok, L_i = M_i^-1
 * with M_i = sum_j V_j g0_ij (x) (r_j - r_i) (the identity where M is
 * singular), for every fluid particle. W needs s: a square root per pair. */
static void corr_pass(const struct vsph_equations_props *ep,
                      const struct vsph_particles *p, size_t n_fluid,
                      const struct vsph_cells *cells,
                      const struct vsph_pair_kernel *pk, double w0,
                      struct vsph_viscous_ws *ws) {
  const int dim = p->dim, bl = ep->corr == VSPH_PAIR_CORR_BONETLOK;
  const struct vsph_kernel_type *k = ep->visc.kernel;
  const double h = ep->visc.h, wf = pow(h, -dim);
  struct vsph_share sh; /* runs of cells, owner first */
  vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel
  for (size_t c, run[2] = {0, 0};
       vsph_share_next_cell(&sh, cells->ncells, run, &c);) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    for (size_t i = cells->start[c]; i < cells->start[c] + cells->count[c];
         i++) {
      if (p->id[i] >= n_fluid) continue;
      double S = p->vol[i] * w0, a[3] = {0, 0, 0}, M[9] = {0},
             L[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
      struct vsph_pair_iter it;
      struct vsph_pair_chunk b;
      for (int pass = 0; pass < 1 + bl; pass++) {
        vsph_pair_begin(&it, pk, p, &rg, i);
        while (vsph_pair_gather(&it, dim, pk->dfq_id, &b))
          for (size_t q = 0; q < b.m; q++) {
            struct vsph_pair pr;
            vsph_pair_at(&b, q, dim, &pr);
            const double vj = p->vol[pr.j];
            const double w = vsph_kernel_w(k, dim, sqrt(pr.s2) / h) * wf;
            if (pass == 0) {
              S += vj * w;
              for (int e = 0; e < dim; e++) a[e] -= vj * pr.F * pr.x[e];
              continue;
            }
            double g0[3];
            vsph_pair_corr_grad(&pr, dim, w, S, a, NULL, 0, g0);
            for (int e = 0; e < dim; e++)
              for (int f = 0; f < dim; f++)
                M[e * dim + f] += vj * g0[e] * pr.x[f];
          }
      }
      if (bl) {
        for (int e = 0; e < 9; e++) L[e] = 0.0;
        for (int e = 0; e < dim; e++) L[e * dim + e] = 1.0;
        vsph_viscous_invert_sym(dim, M, L, ep->visc.det_tol);
      }
      ws->S[i] = S;
      for (int e = 0; e < dim; e++) ws->a[e][i] = a[e];
      for (int e = 0; e < dim * dim; e++) ws->L[e][i] = L[e];
    }
  }
}

/* One fluid particle of contact SPH (Parshikov et al. eqs. 5, 6, 35;
 * docs/theory.md section 12): every pair through vsph_pair_contact (the Riemann
 * solution) and, with a viscosity, vsph_pair_contact_visc. The acoustic
 * solver's dissipative parts go to acc_visc and drho_delta, so that the energy
 * budget accounts for them. */
VSPH_CONSTS_SPECIALISE size_t contact_one(
    const struct vsph_equations_ctx *rc, const struct vsph_particles *p,
    const struct vsph_pair_ranges *rg, size_t i, struct vsph_equations_out *out,
    double *min_s2, const int dim, const int kid, const int visc) {
  struct vsph_pair_vec ui = {{0, 0, 0}};
  for (int k = 0; k < dim; k++) ui.v[k] = p->vel[k][i];
  const unsigned char *const mat = p->mat;
  const int mi = mat ? mat[i] : 0;
  const double rhoi = p->rho[i], pi = p->p[i], Zi = rhoi * rc->cmat[mi];
  const double *const rho = p->rho, *const pp = p->p;
  const double *const vel[3] = {p->vel[0], dim > 1 ? p->vel[1] : NULL,
                                dim > 2 ? p->vel[2] : NULL};
  double cont = 0.0, diff = 0.0, ms2 = INFINITY;
  double ap0 = 0, ap1 = 0, ap2 = 0, av0 = 0, av1 = 0, av2 = 0;
  size_t nint = 0;
  struct vsph_pair_iter it;
  struct vsph_pair_chunk b;
  vsph_pair_begin(&it, &rc->pk, p, rg, i);
  while (vsph_pair_gather(&it, dim, kid, &b)) {
    const size_t m = b.m;
    /* the pairs' shares: a map, no sums, so that it vectorises (a sum in
     * the same loop kept it scalar) */
    double sc[VSPH_PAIR_CHUNK_MAX], sd[VSPH_PAIR_CHUNK_MAX],
        fa[3][VSPH_PAIR_CHUNK_MAX], fv[3][VSPH_PAIR_CHUNK_MAX];
    size_t mjk[VSPH_PAIR_CHUNK_MAX]; /* j's materials, the test outside */
    const double uiv[3] = {ui.v[0], ui.v[1], ui.v[2]};
    if (mat)
      for (size_t k = 0; k < m; k++) mjk[k] = mat[b.j[k]];
    else
      for (size_t k = 0; k < m; k++) mjk[k] = 0;
#pragma omp simd
    for (size_t k = 0; k < m; k++) {
      struct vsph_pair pr;
      vsph_pair_at(&b, k, dim, &pr);
      const size_t j = pr.j;
      const size_t mj = mjk[k];
      /* set one by one, no aggregate copy (which keeps the loop scalar) */
      struct vsph_pair_vec uik, uj, du;
      double dux = 0.0;
      for (int a = 0; a < 3; a++) {
        uik.v[a] = uiv[a];
        uj.v[a] = a < dim ? vel[a][j] : 0.0;
        du.v[a] = uj.v[a] - uiv[a];
        if (a < dim) dux += du.v[a] * pr.x[a];
      }
      const struct vsph_pair_contact_share sh = vsph_pair_contact(
          &pr, dim, sqrt(pr.s2), pi, pp[j], Zi, rho[j] * rc->cmat[mj], uik, uj);
      double g[3] = {0, 0, 0};
      if (visc) {
        const struct vsph_pair_visc gv =
            vsph_pair_contact_visc(&pr, dim, rc->etap[mi][mj], du, dux);
        for (int a = 0; a < dim; a++) g[a] = gv.f[a];
      }
      sc[k] = sh.cont;
      sd[k] = sh.diff;
      for (int a = 0; a < dim; a++) {
        fa[a][k] = sh.f[a] + g[a];
        fv[a][k] = sh.fd[a] + g[a];
      }
    }
    /* i's sums, lane by lane */
#pragma omp simd reduction(+ : cont, diff, ap0, ap1, ap2, av0, av1, av2) \
    reduction(min : ms2)
    for (size_t k = 0; k < m; k++) {
      ms2 = b.s2[k] < ms2 ? b.s2[k] : ms2;
      cont += sc[k];
      diff += sd[k];
      ap0 += fa[0][k];
      av0 += fv[0][k];
      if (dim > 1) {
        ap1 += fa[1][k];
        av1 += fv[1][k];
      }
      if (dim > 2) {
        ap2 += fa[2][k];
        av2 += fv[2][k];
      }
    }
    nint += m;
  }
  const double ap[3] = {ap0, ap1, ap2}, av[3] = {av0, av1, av2};
  const double rinv = rc->fixed[mi] ? 0.0 : 1.0 / rhoi;
  double gb[3] = {0, 0, 0};
  if (!rc->fixed[mi]) body_force(rc->ep, it.xi, gb);
  out->drho[i] = rhoi * cont;
  for (int k = 0; k < dim; k++) out->acc[k][i] = rinv * ap[k] + gb[k];
  if (rc->parts) {
    for (int k = 0; k < dim; k++) out->acc_visc[k][i] = rinv * av[k];
    out->drho_delta[i] = rhoi * diff;
  }
  *min_s2 = ms2;
  return nint;
}

/* The fluid particles of cell c for contact SPH. */
VSPH_CONSTS_SPECIALISE size_t contact_cell(const struct vsph_equations_ctx *rc,
                                           const struct vsph_particles *p,
                                           const struct vsph_cells *cells,
                                           size_t c, size_t n_fluid,
                                           struct vsph_equations_out *out,
                                           double *min_s2, const int dim,
                                           const int kid, const int visc) {
  struct vsph_pair_ranges rg;
  vsph_pair_ranges_cell(&rg, cells, c);
  const size_t i0 = cells->start[c], i1 = i0 + cells->count[c];
  size_t total = 0;
  double ms2 = INFINITY;
  for (size_t i = i0; i < i1; i++) {
    if (p->id[i] >= n_fluid) continue;
    double m;
    total += contact_one(rc, p, &rg, i, out, &m, dim, kid, visc);
    ms2 = m < ms2 ? m : ms2;
  }
  *min_s2 = ms2;
  return total;
}

/* The general copy, the form's pair functions called through its
 * descriptor: every shape of a form without loops of its own (model A,
 * the Laplacian forms, MEAF-eta), and of every form with Solver's
 * loop_general. */
static size_t rhs_general(const struct vsph_equations_ctx *rc,
                          const struct vsph_particles *p,
                          const struct vsph_cells *cells, size_t c,
                          size_t n_fluid, struct vsph_equations_out *out,
                          double *min_s2) {
  return rhs_cell(rc, p, cells, c, n_fluid, out, min_s2, rc->pk.dim,
                  rc->vl.pair, rc->vl.pair_g, rc->dhc > 0.0, rc->pk.dfq_id,
                  rc->reduce, rc->corr, rc->tvf);
}

/* The Gaussian's specialised loops of the run's shape, its form's
 * family's (the right-hand side's gather and the sweep choose from the
 * one row): 2-D or 3-D, a form with loops of its own, no reduced pairs,
 * corrections or transport velocity; NULL where only the general gather
 * serves. */
static const struct vsph_viscous_shape_loops *gauss_loops(
    const struct vsph_equations_ctx *rc) {
  const struct vsph_viscous_loops *const L =
      vsph_viscous_types[rc->vl.form]->loops;
  if (!L || rc->pk.dfq_id != VSPH_KERNEL_DFQ_GAUSSIAN || rc->pk.dim < 2 ||
      rc->reduce || rc->corr || rc->tvf)
    return NULL;
  return &L->gauss[rc->pk.dim - 2][rc->dhc > 0.0];
}

/* The loop for the run's shape, chosen once per evaluation: its form's
 * family's (the 2-D quintic spline with the transport velocity, the 2-D
 * cubic B-spline, the 3h Gaussian, or its loop for any other shape), the
 * general one for a form without loops of its own. */
static vsph_equations_cell_fn *rhs_choose(const struct vsph_equations_ctx *rc) {
  const struct vsph_viscous_loops *const L =
      vsph_viscous_types[rc->vl.form]->loops;
  if (rc->ep->loop_general || !L) return rhs_general;
  const int plain2 =
      rc->pk.dim == 2 && !rc->reduce && !rc->corr && !(rc->dhc > 0.0);
  if (plain2 && rc->tvf && rc->pk.dfq_id == VSPH_KERNEL_DFQ_QUINTIC && L->tvf)
    return L->tvf;
  if (plain2 && !rc->tvf && rc->pk.dfq_id == VSPH_KERNEL_DFQ_CUBIC)
    return L->cubic;
  const struct vsph_viscous_shape_loops *const g = gauss_loops(rc);
  return g ? g->cell : L->any;
}

/* Every cell through the chosen loop, in parallel (gather form: each
 * thread writes only its own particles). */
static void run_cells(const struct vsph_equations_ctx *rc,
                      vsph_equations_cell_fn *cell_loop,
                      const struct vsph_particles *p,
                      const struct vsph_cells *cells, size_t n_fluid,
                      struct vsph_equations_out *out) {
  size_t total = 0;
  double min_s2 = INFINITY;
  /* integer sum and min: exact, so the same for any thread count; the
   * cells in runs, each thread its own first */
  struct vsph_share sh;
  vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel reduction(+ : total) reduction(min : min_s2)
  for (size_t c, run[2] = {0, 0};
       vsph_share_next_cell(&sh, cells->ncells, run, &c);) {
    double m;
    total += cell_loop(rc, p, cells, c, n_fluid, out, &m);
    min_s2 = m < min_s2 ? m : min_s2;
  }
  out->interactions = total;
  out->min_s2 = min_s2;
}

/* Contact SPH's loops: the shear test's shapes (3-D, Wendland C2 or the
 * cubic B-spline, inviscid or viscous), the cylinders' (2-D, Wendland C2)
 * and the 3h Gaussian's (2-D and 3-D) specialised, any other general. */
#define CONTACT_SHAPE(name, D, KID, VISC)                                      \
  static size_t name(const struct vsph_equations_ctx *rc,                      \
                     const struct vsph_particles *p,                           \
                     const struct vsph_cells *cells, size_t c, size_t n_fluid, \
                     struct vsph_equations_out *out, double *min_s2) {         \
    return contact_cell(rc, p, cells, c, n_fluid, out, min_s2, D, KID, VISC);  \
  }
CONTACT_SHAPE(contact_c2_3, 3, VSPH_KERNEL_DFQ_C2, 0)
CONTACT_SHAPE(contact_c2_3v, 3, VSPH_KERNEL_DFQ_C2, 1)
CONTACT_SHAPE(contact_cubic_3, 3, VSPH_KERNEL_DFQ_CUBIC, 0)
CONTACT_SHAPE(contact_cubic_3v, 3, VSPH_KERNEL_DFQ_CUBIC, 1)
CONTACT_SHAPE(contact_c2_2, 2, VSPH_KERNEL_DFQ_C2, 0)
CONTACT_SHAPE(contact_c2_2v, 2, VSPH_KERNEL_DFQ_C2, 1)
CONTACT_SHAPE(contact_gauss_2, 2, VSPH_KERNEL_DFQ_GAUSSIAN, 0)
CONTACT_SHAPE(contact_gauss_2v, 2, VSPH_KERNEL_DFQ_GAUSSIAN, 1)
CONTACT_SHAPE(contact_gauss_3, 3, VSPH_KERNEL_DFQ_GAUSSIAN, 0)
CONTACT_SHAPE(contact_gauss_3v, 3, VSPH_KERNEL_DFQ_GAUSSIAN, 1)
#undef CONTACT_SHAPE

static size_t contact_general(const struct vsph_equations_ctx *rc,
                              const struct vsph_particles *p,
                              const struct vsph_cells *cells, size_t c,
                              size_t n_fluid, struct vsph_equations_out *out,
                              double *min_s2) {
  return contact_cell(rc, p, cells, c, n_fluid, out, min_s2, rc->pk.dim,
                      rc->pk.dfq_id, rc->cvisc);
}

static vsph_equations_cell_fn *contact_choose(
    const struct vsph_equations_ctx *rc) {
  if (rc->ep->loop_general) return contact_general;
  if (rc->pk.dim == 2 && rc->pk.dfq_id == VSPH_KERNEL_DFQ_C2)
    return rc->cvisc ? contact_c2_2v : contact_c2_2;
  /* the 3h Gaussian, the solver's default kernel (and the bench's) */
  if (rc->pk.dfq_id == VSPH_KERNEL_DFQ_GAUSSIAN && rc->pk.dim >= 2)
    return rc->pk.dim == 2 ? (rc->cvisc ? contact_gauss_2v : contact_gauss_2)
                           : (rc->cvisc ? contact_gauss_3v : contact_gauss_3);
  if (rc->pk.dim != 3) return contact_general;
  if (rc->pk.dfq_id == VSPH_KERNEL_DFQ_C2)
    return rc->cvisc ? contact_c2_3v : contact_c2_3;
  if (rc->pk.dfq_id == VSPH_KERNEL_DFQ_CUBIC)
    return rc->cvisc ? contact_cubic_3v : contact_cubic_3;
  return contact_general;
}

/* Contact SPH's loop constants: each material's sound speed and each
 * pair's eta_eff - zeta eta_eff^num (Parshikov et al. eqs. 30-32 and 26). */
static int contact_init(const struct vsph_equations_props *ep,
                        struct vsph_equations_ctx *rc) {
  if (ep->nmat < 1 || ep->nmat > VSPH_EQUATIONS_MAT_MAX)
    VSPH_FAIL(VSPH_EINVAL, "contact SPH needs 1 to %d materials, not %d",
              VSPH_EQUATIONS_MAT_MAX, ep->nmat);
  if (ep->eos != VSPH_EQUATIONS_EOS_LINEAR || ep->corr || ep->reduce ||
      ep->tvf || ep->delta > 0.0 || ep->solid)
    VSPH_FAIL(VSPH_EINVAL,
              "contact SPH takes the linear law and no correction, "
              "reduction, delta-SPH, transport velocity or wall particles");
  rc->cvisc = 0;
  for (int a = 0; a < ep->nmat; a++) {
    const struct vsph_equations_mat *ma = &ep->mat[a];
    rc->cmat[a] = ma->c0;
    rc->fixed[a] = ma->fixed;
    for (int b = 0; b < ep->nmat; b++) {
      const struct vsph_equations_mat *mb = &ep->mat[b];
      rc->etap[a][b] =
          vsph_equations_eta_eff(ma->mu, ma->rho0, mb->mu, mb->rho0) -
          ep->zeta_num * vsph_equations_eta_eff(ma->eta_num, ma->rho0,
                                                mb->eta_num, mb->rho0);
      rc->cvisc |= rc->etap[a][b] != 0.0;
    }
  }
  return VSPH_OK;
}

/* ------------------------------------------------- the symmetric sweep */

struct vsph_equations_sweep *vsph_equations_sweep_alloc(void) {
  struct vsph_equations_sweep *sw = calloc(1, sizeof *sw);
  if (!sw)
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate a sweep workspace");
  return sw;
}

void vsph_equations_sweep_free(struct vsph_equations_sweep *sw) {
  if (!sw) return;
  free(sw->off);
  free(sw->buf);
  free(sw->rows);
  free(sw->flags);
  free(sw);
}

size_t vsph_equations_sweep_bytes(const struct vsph_equations_sweep *sw) {
  if (!sw) return 0;
  return sizeof *sw + sw->cap_off * sizeof(size_t) +
         (sw->cap_buf + sw->cap_rows) * sizeof(double) + sw->cap_flags;
}

/* The blocks of this evaluation, the cells' (planned with their build on
 * @p n particles), and their buffers, nf doubles per particle, laid end to
 * end. */
static int sweep_plan(struct vsph_equations_sweep *sw,
                      const struct vsph_cells *cells, size_t n, int nf) {
  if (cells->blk_n != n || cells->blk_c0 == NULL)
    VSPH_FAIL(VSPH_EINVAL,
              "the cells were built on %zu particles, the sweep runs on %zu: "
              "rebuild them",
              cells->blk_n, n);
  sw->nblk = cells->nblk;
  sw->c0 = cells->blk_c0;
  sw->lo = cells->blk_lo;
  sw->hi = cells->blk_hi;
  if (sw->nblk + 1 > sw->cap_off) {
    const size_t cap = 2 * (sw->nblk + 1);
    size_t *r = realloc(sw->off, cap * sizeof *r);
    if (!r) VSPH_FAIL(VSPH_ENOMEM, "cannot grow the sweep's %zu blocks", cap);
    sw->off = r;
    sw->cap_off = cap;
  }
  size_t total = 0;
  for (size_t b = 0; b < sw->nblk; b++) {
    sw->off[b] = total;
    total += (sw->hi[b] - sw->lo[b]) * (size_t)nf;
  }
  if (total > sw->cap_buf) {
    const size_t cap = total + total / 4;
    double *r = realloc(sw->buf, cap * sizeof *r);
    if (!r)
      VSPH_FAIL(VSPH_ENOMEM, "cannot grow the sweep's buffers to %zu MiB",
                cap * sizeof *r >> 20);
    sw->buf = r;
    sw->cap_buf = cap;
  }
  return VSPH_OK;
}

/* Block b's particles [*i0, *i1); returns the first block whose pairs
 * reach into it (blocks before it hold nothing of b's particles). */
static size_t sweep_span(const struct vsph_equations_sweep *sw,
                         const struct vsph_cells *cells, size_t b, size_t *i0,
                         size_t *i1) {
  const size_t last = sw->c0[b + 1] - 1;
  *i0 = sw->lo[b];
  *i1 = cells->start[last] + cells->count[last];
  for (size_t e = 0; e < b; e++)
    if (sw->hi[e] > *i0) return e;
  return b;
}

/* The particles of block b, [i0, i1), their nf sums each into the rows
 * of @p t: every buffer of blocks first..b that reaches into the block
 * added over the block's particles in one contiguous run, in block order
 * (so each particle's sum is its entries added in block order, from
 * zero). */
static void sweep_rows(const struct vsph_equations_sweep *sw, size_t first,
                       size_t b, size_t i0, size_t i1, int nf, double *t) {
  memset(t, 0, (i1 - i0) * (size_t)nf * sizeof *t);
  for (size_t e = first; e <= b; e++) {
    const size_t end = sw->hi[e] < i1 ? sw->hi[e] : i1;
    if (end <= i0) continue;
    const double *q = sw->buf + sw->off[e] + (i0 - sw->lo[e]) * (size_t)nf;
    const size_t m = (end - i0) * (size_t)nf;
    for (size_t k = 0; k < m; k++) t[k] += q[k];
  }
}

/* The particles of the largest block (the rows sweep_rows needs). */
static size_t sweep_most(const struct vsph_equations_sweep *sw,
                         const struct vsph_cells *cells) {
  size_t most = 1;
  for (size_t b = 0; b < sw->nblk; b++) {
    const size_t last = sw->c0[b + 1] - 1,
                 end = cells->start[last] + cells->count[last];
    most = end - sw->lo[b] > most ? end - sw->lo[b] : most;
  }
  return most;
}

/* Particle i's right-hand side from its sums @p s (sweep_finish). */
static inline void finish_one(const struct vsph_equations_ctx *rc,
                              const struct vsph_particles *p, size_t i, int dim,
                              const double *s, struct vsph_equations_out *out) {
  const double rhoi = p->rho[i], rinv = 1.0 / rhoi;
  const double cont = s[SW_CONT(dim)], dsum = s[SW_DELTA(dim)];
  if (rc->gas) out->de[i] = p->p[i] * cont * rinv;
  double x[3] = {0, 0, 0}, g[3];
  for (int a = 0; a < dim; a++) x[a] = p->pos[a][i];
  body_force(rc->ep, x, g);
  out->drho[i] = rhoi * cont + rc->dhc * dsum;
  for (int a = 0; a < dim; a++) out->acc[a][i] = rinv * s[SW_F + a] + g[a];
  if (rc->parts) {
    for (int a = 0; a < dim; a++)
      out->acc_visc[a][i] = rinv * s[SW_VISC(dim) + a];
    out->drho_delta[i] = rc->dhc * dsum;
  }
}

/* Each fluid particle's sums from the block buffers that hold it, in
 * block order, into the right-hand side: block by block, each buffer
 * that reaches into the block added over the block's particles in one
 * contiguous run (the same additions, in the same order per particle, as
 * sweep_sums), into a scratch row of @p nf doubles a particle. Fields past
 * nf (the delta-SPH sum without delta-SPH) are zero. */
/* What a finish does with one block's rows (sweep_each_block): the
 * particles [i0, i1), nf sums each in @p t. */
typedef void sweep_rows_fn(void *ctx, size_t i0, size_t i1, int nf,
                           const double *t);

/* Every block's rows (sweep_rows) handed to @p fn, the blocks in
 * parallel, each thread with scratch rows of its own in the workspace
 * (grown here, outside the parallel region: no allocation per
 * evaluation once it has its size). */
static int sweep_each_block(struct vsph_equations_sweep *sw,
                            const struct vsph_cells *cells, int nf,
                            sweep_rows_fn *fn, void *ctx) {
  if (!sw->nblk) return VSPH_OK;
  const size_t most = sweep_most(sw, cells), per = most * (size_t)nf;
  const size_t need = per * (size_t)omp_get_max_threads();
  if (need > sw->cap_rows) {
    double *r = realloc(sw->rows, need * sizeof *r);
    if (!r) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the sweep's rows");
    sw->rows = r;
    sw->cap_rows = need;
  }
  double *const rows = sw->rows;
  struct vsph_share sh; /* each thread its own blocks first */
  vsph_share_init(&sh, sw->nblk);
#pragma omp parallel
  {
    double *const t = rows + per * (size_t)omp_get_thread_num();
    for (size_t b; (b = vsph_share_next(&sh)) != SIZE_MAX;) {
      size_t i0, i1;
      const size_t first = sweep_span(sw, cells, b, &i0, &i1);
      sweep_rows(sw, first, b, i0, i1, nf, t);
      fn(ctx, i0, i1, nf, t);
    }
  }
  return VSPH_OK;
}

/* The right-hand side's finish (sweep_finish). */
struct finish_ctx {
  const struct vsph_equations_ctx *rc;
  const struct vsph_particles *p;
  size_t n_fluid;
  struct vsph_equations_out *out;
};

/* finish_one's operations for a block's rows in 2-D without the gas law
 * or the parts, the body force one vector for all (no radial force), in
 * strips of 64 particles: a loop that computes every particle's values
 * and one that stores the fluid's, so that both vectorise (a store under
 * a condition beside a division does not, with traps kept). A ghost's or
 * wall particle's values are computed from whatever its entries hold
 * (1/rho of rho = 0 is an infinity) and never stored; vsph enables no
 * floating-point trap. The same operations, so the same bits. @p nf 3 or
 * 4 (the delta-SPH sum), a constant (always inlined). */
VSPH_CONSTS_SPECIALISE void finish_rows2(const struct finish_ctx *f, size_t i0,
                                         size_t i1, const int nf,
                                         const double *t) {
  const struct vsph_particles *p = f->p;
  const size_t *const id = p->id;
  const size_t n_fluid = f->n_fluid;
  const double *const rho = p->rho;
  double *const drho = f->out->drho, *const a0 = f->out->acc[0],
                *const a1 = f->out->acc[1];
  const double dhc = f->rc->dhc;
  double x[3] = {0, 0, 0}, g[3];
  body_force(f->rc->ep, x, g); /* the same at every x */
  for (size_t s0 = i0; s0 < i1; s0 += 64) {
    const size_t e = i1 - s0 < 64 ? i1 - s0 : 64;
    const double *const ts = t + (s0 - i0) * (size_t)nf;
    double dr[64], b0[64], b1[64];
#pragma omp simd
    for (size_t k = 0; k < e; k++) {
      const double *const s = ts + k * (size_t)nf;
      const double rhoi = rho[s0 + k], rinv = 1.0 / rhoi;
      dr[k] = rhoi * s[SW_CONT(2)] + dhc * (nf > 3 ? s[SW_DELTA(2)] : 0.0);
      b0[k] = rinv * s[SW_F] + g[0];
      b1[k] = rinv * s[SW_F + 1] + g[1];
    }
#pragma omp simd
    for (size_t k = 0; k < e; k++)
      if (id[s0 + k] < n_fluid) { /* a ghost's entries are left alone */
        drho[s0 + k] = dr[k];
        a0[s0 + k] = b0[k];
        a1[s0 + k] = b1[k];
      }
  }
}

static void finish_rows(void *ctx, size_t i0, size_t i1, int nf,
                        const double *t) {
  const struct finish_ctx *f = ctx;
  if (f->p->dim == 2 && !f->rc->gas && !f->rc->parts &&
      f->rc->ep->body != VSPH_EQUATIONS_BODY_RADIAL && (nf == 3 || nf == 4)) {
    if (nf == 3)
      finish_rows2(f, i0, i1, 3, t);
    else
      finish_rows2(f, i0, i1, 4, t);
    return;
  }
  for (size_t i = i0; i < i1; i++) {
    if (f->p->id[i] >= f->n_fluid) continue;
    double s[3 + 2 + 3] = {0};
    for (int a = 0; a < nf; a++) s[a] = t[(i - i0) * (size_t)nf + a];
    finish_one(f->rc, f->p, i, f->p->dim, s, f->out);
  }
}

/* Each fluid particle's sums from the block buffers that hold it, in
 * block order (sweep_rows), into the right-hand side. Fields past nf
 * (the delta-SPH sum without delta-SPH) are zero. */
static int sweep_finish(const struct vsph_equations_ctx *rc,
                        const struct vsph_particles *p, size_t n_fluid,
                        const struct vsph_cells *cells,
                        struct vsph_equations_sweep *sw, int nf,
                        struct vsph_equations_out *out) {
  struct finish_ctx f = {rc, p, n_fluid, out};
  return sweep_each_block(sw, cells, nf, finish_rows, &f);
}

/* The sweep for the run's shape, or NULL where only the general gather
 * serves (the row rhs_choose takes). */
static vsph_equations_sweep_fn *sweep_choose(
    const struct vsph_equations_ctx *rc) {
  const struct vsph_viscous_shape_loops *const g = gauss_loops(rc);
  return g ? g->sweep : NULL;
}

/* PVWF's (model B's) first pass by the sweep, one block: each pair's
 * unit terms -F x (x) x and -F du (x) x of B and Mg (vsph_pair_pvwf_grad,
 * even in the pair: i takes V_j of them, j V_i), i's summed field by
 * field, j's added to the block's buffer, as sweep_block. Every particle
 * receives, ghosts too: the second pass reads their A. In 2-D by cell
 * groups where the CPU allows (grad_block2). */
VSPH_CONSTS_SPECIALISE void grad_block(const struct vsph_pair_kernel *pk,
                                       const struct vsph_particles *p,
                                       const struct vsph_cells *cells,
                                       const struct vsph_equations_sweep *sw,
                                       size_t blk, const int dim,
                                       const int kid) {
  const int dd = dim * dim, nf = 2 * dd;
  const size_t lo = sw->lo[blk];
  double *const buf = sw->buf + sw->off[blk];
  memset(buf, 0, (sw->hi[blk] - lo) * (size_t)nf * sizeof *buf);
  const double *const vol = p->vol;
  const double *const vel[3] = {p->vel[0], dim > 1 ? p->vel[1] : NULL,
                                dim > 2 ? p->vel[2] : NULL};
  struct vsph_pair_cell pc; /* the cell's walks, together (sweep_block) */
  for (size_t c = sw->c0[blk]; c < sw->c0[blk + 1]; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    const size_t c0 = cells->start[c], cnt = cells->count[c];
    vsph_pair_cell_begin(&pc, pk, c0, cnt, dim);
    for (size_t i = c0; i < c0 + cnt; i++) {
      double ui[3] = {0, 0, 0}, sums[18] = {0};
      for (int a = 0; a < dim; a++) ui[a] = vel[a][i];
      const double Vi = vol[i];
      struct vsph_pair_iter it;
      struct vsph_pair_chunk own;
      const struct vsph_pair_chunk *b;
      vsph_pair_begin_upper_in(&it, pk, p, &rg, &pc, i);
      while (vsph_pair_next_chunk(&it, dim, kid, 1, &own, &b)) {
        const size_t m = b->m;
        double u[18][VSPH_PAIR_CHUNK_MAX], vj[VSPH_PAIR_CHUNK_MAX];
#pragma omp simd
        for (size_t k = 0; k < m; k++) {
          struct vsph_pair pr;          /* VF = F: unit terms, V_i and V_j */
          vsph_pair_at(b, k, dim, &pr); /* applied below */
          struct vsph_pair_vec du;
          for (int a = 0; a < dim; a++) du.v[a] = vel[a][pr.j] - ui[a];
          const struct vsph_pair_grad gr = vsph_pair_pvwf_grad(&pr, dim, du);
          for (int e = 0; e < dd; e++) {
            u[e][k] = gr.B[e];
            u[dd + e][k] = gr.M[e];
          }
          vj[k] = vol[pr.j];
        }
        if (nf == 8) { /* i's sums, lane by lane, in one loop */
          double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0, s4 = 0.0, s5 = 0.0,
                 s6 = 0.0, s7 = 0.0;
#pragma omp simd reduction(+ : s0, s1, s2, s3, s4, s5, s6, s7)
          for (size_t k = 0; k < m; k++) {
            s0 += vj[k] * u[0][k];
            s1 += vj[k] * u[1][k];
            s2 += vj[k] * u[2][k];
            s3 += vj[k] * u[3][k];
            s4 += vj[k] * u[4][k];
            s5 += vj[k] * u[5][k];
            s6 += vj[k] * u[6][k];
            s7 += vj[k] * u[7][k];
          }
          const double se[8] = {s0, s1, s2, s3, s4, s5, s6, s7};
          for (int e = 0; e < 8; e++) sums[e] += se[e];
        } else
          for (int e = 0; e < nf; e++) { /* i's sums, lane by lane */
            double s = 0.0;
#pragma omp simd reduction(+ : s)
            for (size_t k = 0; k < m; k++) s += vj[k] * u[e][k];
            sums[e] += s;
          }
        if (VSPH_PAIR_X86 && nf == 8 && pk->simd)
          vsph_sweep_x86_add8_avx2(buf, lo, b->j, m, u[0], VSPH_PAIR_CHUNK_MAX,
                                   Vi);
        else
          for (size_t k = 0; k < m; k++) { /* j's, in pair order */
            double *const q = buf + (b->j[k] - lo) * (size_t)nf;
            for (int e = 0; e < nf; e++) q[e] += Vi * u[e][k];
          }
      }
      double *const q = buf + (i - lo) * (size_t)nf;
      for (int e = 0; e < nf; e++) q[e] += sums[e];
    }
  }
}

/* grad_block in 2-D: by cell groups in AVX-512 lanes, or AVX2 ones,
 * where the CPU has them and the build allows it (VSPH_SWEEP_X86_GROUPS;
 * solver/sweep_x86.c, within rounding) and the kernel is the 3h Gaussian
 * they are built for, else the loops above */
static void grad_block2(const struct vsph_pair_kernel *pk,
                        const struct vsph_particles *p,
                        const struct vsph_cells *cells,
                        const struct vsph_equations_sweep *sw, size_t blk) {
  const int G = VSPH_KERNEL_DFQ_GAUSSIAN;
#if VSPH_SWEEP_X86_GROUPS
  if (pk->simd == 2 && pk->dfq_id == G) {
    vsph_sweep_x86_grad2_avx512(pk, p, cells, sw, blk);
    return;
  }
  if (pk->simd == 1 && pk->dfq_id == G) {
    vsph_sweep_x86_grad2_avx2(pk, p, cells, sw, blk);
    return;
  }
#endif
  grad_block(pk, p, cells, sw, blk, 2, G);
}

/* PVWF's first pass's finish (grad_sweep): B and Mg of each particle. */
struct grad_ctx {
  const struct vsph_viscous_props *vp;
  struct vsph_viscous_ws *ws;
};

static void grad_rows(void *ctx, size_t i0, size_t i1, int nf,
                      const double *t) {
  const struct grad_ctx *g = ctx;
  (void)nf; /* 2 d^2, as vsph_viscous_pvwf_finish_rows reads them */
  vsph_viscous_pvwf_finish_rows(g->vp, g->ws, i0, i1, t);
}

/* PVWF's first pass by the sweep for the 2-D and 3-D Gaussian: the
 * blocks, then every particle's B and Mg from its buffers in block order,
 * finished by vsph_viscous_pvwf_finish_rows (vsph_viscous_pvwf_finish's
 * operations, a block's rows at a time). */
static int grad_sweep(const struct vsph_viscous_props *vp,
                      const struct vsph_pair_kernel *pk,
                      const struct vsph_particles *p,
                      const struct vsph_cells *cells,
                      struct vsph_equations_sweep *sw,
                      struct vsph_viscous_ws *ws) {
  if (!ws || ws->cap < p->n || ws->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "%s needs a workspace for %zu particles",
              vsph_viscous_label(vp->form), p->n);
  const int dim = p->dim, dd = dim * dim, nf = 2 * dd;
  const int st = sweep_plan(sw, cells, p->n, nf);
  if (st) return st;
  const int G = VSPH_KERNEL_DFQ_GAUSSIAN;
  struct vsph_share sh; /* each thread its own blocks first */
  vsph_share_init(&sh, sw->nblk);
#pragma omp parallel
  for (size_t b; (b = vsph_share_next(&sh)) != SIZE_MAX;)
    if (dim == 2)
      grad_block2(pk, p, cells, sw, b);
    else
      grad_block(pk, p, cells, sw, b, 3, G);
  struct grad_ctx g = {vp, ws};
  const int sf = sweep_each_block(sw, cells, nf, grad_rows, &g);
  if (sf) return sf;
  size_t nfb = 0; /* serial: reproducible */
  for (size_t i = 0; i < p->n; i++) nfb += ws->fallback[i];
  ws->n_fallback = nfb;
  return VSPH_OK;
}

/* Row @p out (@p n bytes) the OR of the rows @p in, in + n, ...
 * (@p m of them). */
static void or_rows(unsigned char *restrict out,
                    const unsigned char *restrict in, size_t n, size_t m) {
  memcpy(out, in, n);
  for (size_t y = 1; y < m; y++)
    for (size_t i = 0; i < n; i++) out[i] |= in[y * n + i];
}

/* In a set with ghosts or wall particles (id >= n_fluid), each cell's
 * flag sw->clean: 1 where none lies in its ranges (vsph_cells_ranges: the
 * cells within VSPH_CELLS_SUB of it along each axis, clipped to the
 * grid), so that sweep_count need not look its receivers' neighbours up.
 * Each cell's own first, then the window along x, y and z in turn (an
 * axis of one cell left out): along x line by line; along y and z, whose
 * cells lie a stride apart, row by row (a row: the stride's cells in
 * memory order, each the OR of the window's rows, so that a thread writes
 * bytes of its own and the loop runs along memory); in a direct set (one
 * cell, every particle) the one flag. @p team 1: called by every thread
 * of the region sweep_clean opens, each pass shared evenly and ended by a
 * barrier; 0: one thread does it all, with no worksharing construct or
 * barrier (it may run inside another region, a report's lane, whose team
 * a worksharing loop would bind to). Returns the flags (in @p a or @p b).
 */
static unsigned char *sweep_clean_passes(const struct vsph_cells *cells,
                                         const size_t *id, size_t n_fluid,
                                         unsigned char *a, unsigned char *b,
                                         const int team) {
  const size_t nc = cells->ncells;
  size_t c0 = 0, c1 = nc;
  if (team) vsph_share_even(nc, &c0, &c1);
  for (size_t c = c0; c < c1; c++) {
    unsigned g = 0;
    const size_t e = cells->start[c] + cells->count[c];
    for (size_t i = cells->start[c]; i < e; i++) g |= id[i] >= n_fluid;
    a[c] = (unsigned char)g;
  }
  const size_t S = VSPH_CELLS_SUB;
  size_t stride = 1;
  for (int k = 0; k < 3 && !cells->direct; k++) {
    const size_t len = cells->nc[k];
    if (len > 1) {
      if (team) {
#pragma omp barrier
      }
      /* stride 1: lines of len cells; else rows of stride cells, len of
       * them to a window's axis */
      const size_t units = stride == 1 ? nc / len : nc / stride;
      size_t q0 = 0, q1 = units;
      if (team) vsph_share_even(units, &q0, &q1);
      for (size_t q = q0; q < q1; q++) {
        if (stride == 1) { /* line q: cells q len + x */
          const size_t base = q * len;
          for (size_t x = 0; x < len; x++) {
            const size_t x0 = x >= S ? x - S : 0,
                         x1 = x + S < len ? x + S : len - 1;
            unsigned g = 0;
            for (size_t y = x0; y <= x1; y++) g |= a[base + y];
            b[base + x] = (unsigned char)g;
          }
        } else { /* row q: position x of its axis, the others o */
          const size_t x = q % len, o = q - x;
          const size_t x0 = x >= S ? x - S : 0,
                       x1 = x + S < len ? x + S : len - 1;
          or_rows(b + q * stride, a + (o + x0) * stride, stride, x1 - x0 + 1);
        }
      }
      unsigned char *const t = a;
      a = b;
      b = t;
    }
    stride *= len;
  }
  if (team) {
#pragma omp barrier
  }
  for (size_t c = c0; c < c1; c++) a[c] = !a[c];
  return a; /* read after the region's closing barrier */
}

static void sweep_clean(struct vsph_equations_sweep *sw,
                        const struct vsph_cells *cells,
                        const struct vsph_particles *p, size_t n_fluid) {
  const size_t nc = cells->ncells;
  sw->clean = NULL;
  if (2 * nc > sw->cap_flags) {
    unsigned char *f = realloc(sw->flags, 2 * nc);
    if (!f) return;
    sw->flags = f;
    sw->cap_flags = 2 * nc;
  }
  unsigned char *const a = sw->flags, *const b = sw->flags + nc;
  if (p->n < VSPH_CELLS_PARALLEL) { /* no region: it costs more */
    sw->clean = sweep_clean_passes(cells, p->id, n_fluid, a, b, 0);
    return;
  }
  const unsigned char *clean = NULL;
#pragma omp parallel
  {
    const unsigned char *const f =
        sweep_clean_passes(cells, p->id, n_fluid, a, b, 1);
    if (omp_get_thread_num() == 0) clean = f;
  }
  sw->clean = clean;
}

/* The right-hand side by the symmetric sweep: the blocks in parallel
 * (each its own buffer), then every particle from its buffers. */
static int run_sweep(const struct vsph_equations_ctx *rc,
                     vsph_equations_sweep_fn *fn,
                     const struct vsph_particles *p,
                     const struct vsph_cells *cells, size_t n_fluid,
                     struct vsph_equations_out *out) {
  struct vsph_equations_sweep *sw = out->sweep;
  const int dim = p->dim, nf = SW_FIELDS(dim, rc->dhc > 0.0, rc->parts);
  sw->clean = NULL;
  const int st = sweep_plan(sw, cells, p->n, nf);
  if (st) return st;
  if (p->n != n_fluid) sweep_clean(sw, cells, p, n_fluid);
  size_t total = 0;
  double min_s2 = INFINITY;
  /* integer sum and min: exact, so the same for any thread count; each
   * thread its own blocks first */
  struct vsph_share sh;
  vsph_share_init(&sh, sw->nblk);
#pragma omp parallel reduction(+ : total) reduction(min : min_s2)
  for (size_t b; (b = vsph_share_next(&sh)) != SIZE_MAX;) {
    double m;
    total += fn(rc, p, cells, n_fluid, sw, b, nf, &m);
    min_s2 = m < min_s2 ? m : min_s2;
  }
  const int sf = sweep_finish(rc, p, n_fluid, cells, sw, nf, out);
  if (sf) return sf;
  out->interactions = total;
  out->min_s2 = min_s2;
  return VSPH_OK;
}

int vsph_equations_rhs(const struct vsph_equations_props *ep,
                       struct vsph_particles *p, size_t n_fluid,
                       const struct vsph_cells *cells,
                       struct vsph_viscous_ws *ws,
                       struct vsph_equations_out *out) {
  if (!cells) VSPH_FAIL(VSPH_EINVAL, "vsph_equations_rhs: a NULL argument");
  const struct vsph_viscous_props *vp = &ep->visc;
  if (vp->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "props dimension %d, particles %d", vp->dim, p->dim);
  if (ep->scheme != VSPH_EQUATIONS_CONTACT && !vsph_viscous_type_get(vp->form))
    VSPH_FAIL(VSPH_EINVAL, "unknown viscous formulation %d", vp->form);
  const size_t n = p->n;
  const int gas = ep->eos == VSPH_EQUATIONS_EOS_GAS;
  if (gas && (!out->de || !p->e))
    VSPH_FAIL(VSPH_EINVAL, "the gas law needs the particles' energy fields");
  if (ep->tvf && !p->tvel[0])
    VSPH_FAIL(VSPH_EINVAL, "the transport velocity needs its fields");
  if (!ep->solid && ep->nmat <= 1 && ep->eos == VSPH_EQUATIONS_EOS_LINEAR) {
    /* the linear law of one material, in a loop that vectorises: the
     * operations of vsph_equations_pressure's, so the same bits */
    const double c2 = ep->c0 * ep->c0, rho0 = ep->rho0;
    const double *const rho = p->rho, *const m = p->m;
    double *const pr = p->p, *const vol = p->vol;
#pragma omp parallel for simd schedule(static)
    for (size_t i = 0; i < n; i++) {
      pr[i] = c2 * (rho[i] - rho0);
      vol[i] = m[i] / rho[i];
    }
  } else if (!ep->solid) {
    const unsigned char *const mat = ep->nmat > 1 ? p->mat : NULL;
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) {
      if (mat) { /* two materials: each its own linear law */
        const struct vsph_equations_mat *ma = &ep->mat[mat[i]];
        p->p[i] = ma->c0 * ma->c0 * (p->rho[i] - ma->rho0);
      } else {
        p->p[i] = vsph_equations_pressure(ep, p->rho[i], gas ? p->e[i] : 0.0);
      }
      p->vol[i] = p->m[i] / p->rho[i];
    }
  }
  if (ep->scheme == VSPH_EQUATIONS_CONTACT) {
    struct vsph_equations_ctx rc = {
        .ep = ep, .parts = out->acc_visc[0] != NULL && out->drho_delta != NULL};
    const int st = contact_init(ep, &rc);
    if (st) return st;
    vsph_pair_kernel_init(&rc.pk, vp->kernel, vp->dim, vp->h);
    run_cells(&rc, contact_choose(&rc), p, cells, n_fluid, out);
    return VSPH_OK;
  }
  struct vsph_equations_ctx rc = {
      .ep = ep,
      .dhc = ep->delta * vp->h * ep->c0,
      .parts = out->acc_visc[0] != NULL && out->drho_delta != NULL,
      .gas = gas,
      .reduce = ep->reduce,
      .corr = ep->corr,
      .ws = ws,
      .tvf = ep->tvf,
      .pb = ep->pb,
  };
  vsph_pair_kernel_init(&rc.pk, vp->kernel, vp->dim, vp->h);
  vsph_viscous_loop_init(&rc.vl, vp,
                         vsph_viscous_first_pass(vp->form) ? ws : NULL);
  vsph_equations_sweep_fn *sweep = out->sweep ? sweep_choose(&rc) : NULL;
  /* the first pass: by the sweep where the second goes by it */
  const int st = sweep && vsph_viscous_passes(vp->form) == 2
                     ? grad_sweep(vp, &rc.pk, p, cells, out->sweep, ws)
                     : vsph_viscous_prepare(vp, p, cells, ws);
  if (st) return st;
  if (ep->corr) {
    if (!vsph_viscous_corrigible(vp->form)) {
      char list[256];
      VSPH_FAIL(
          VSPH_EINVAL,
          "the kernel corrections apply to the corrigible forms (%s), not %s",
          vsph_viscous_list(VSPH_VISCOUS_CORRIGIBLE, list, sizeof list),
          vsph_viscous_name(vp->form));
    }
    if (!ws || !ws->S || ws->cap < p->n)
      VSPH_FAIL(VSPH_EINVAL, "the kernel corrections need a workspace");
    rc.wf = pow(vp->h, -vp->dim);
    rc.w0 = vsph_kernel_w(vp->kernel, vp->dim, 0.0) * rc.wf;
    corr_pass(ep, p, n_fluid, cells, &rc.pk, rc.w0, ws);
  }
  if (sweep) return run_sweep(&rc, sweep, p, cells, n_fluid, out);
  run_cells(&rc, rhs_choose(&rc), p, cells, n_fluid, out);
  return VSPH_OK;
}

/* The Adami sweeps' and XSPH's kernel shapes: the kernel's own f, or
 * one of two 2-D kernels inlined (the same operations: the same bits). */
enum { SHAPE_GENERAL = 0, SHAPE_QUINTIC2, SHAPE_CUBIC2 };

/* Adami et al.'s walls, particle i of cell range @p rg: a fluid
 * particle's summation density (with the transport velocity), or a wall
 * particle's pressure and velocity from its fluid neighbours. SHAPE: the
 * 2-D quintic spline (the cavity's) or cubic B-spline (the channels')
 * inlined, else the kernel's f. */
VSPH_CONSTS_SPECIALISE void adami_one(const struct vsph_equations_props *ep,
                                      const struct vsph_walls *w,
                                      struct vsph_particles *p, size_t n_fluid,
                                      const struct vsph_pair_kernel *pk,
                                      const struct vsph_pair_ranges *rg,
                                      size_t i, double w0, double wf,
                                      const int shape) {
  const int quintic = shape == SHAPE_QUINTIC2, cubic = shape == SHAPE_CUBIC2;
  const int dim = quintic || cubic ? 2 : p->dim;
  const struct vsph_kernel_type *k = ep->visc.kernel;
  const double h = ep->visc.h, sig = k->sigma[dim - 1];
  const int wall = p->id[i] >= n_fluid;
  double S = wall ? 0.0 : p->m[i] * w0, sp = 0.0, su[3] = {0, 0, 0};
  struct vsph_pair_iter it;
  struct vsph_pair_chunk b;
  vsph_pair_begin(&it, pk, p, rg, i);
  const double *const m = p->m, *const pp = p->p;
  const double *const v0 = p->vel[0], *const v1 = dim > 1 ? p->vel[1] : NULL,
                      *const v2 = dim > 2 ? p->vel[2] : NULL;
  const size_t *const id = p->id;
  double su0 = 0.0, su1 = 0.0, su2 = 0.0;
  while (vsph_pair_gather(&it, dim,
                          quintic ? VSPH_KERNEL_DFQ_QUINTIC
                          : cubic ? VSPH_KERNEL_DFQ_CUBIC
                                  : pk->dfq_id,
                          &b)) {
    if (!wall) { /* summation: every neighbour's mass */
#pragma omp simd reduction(+ : S)
      for (size_t q = 0; q < b.m; q++) {
        struct vsph_pair pr;
        vsph_pair_at(&b, q, dim, &pr);
        const double s = sqrt(pr.s2) / h;
        S += m[pr.j] *
             (quintic ? sig * vsph_kernel_f_quintic(s)
              : cubic ? sig * vsph_kernel_f_cubic(s)
                      : vsph_kernel_w(k, dim, s)) *
             wf;
      }
      continue;
    }
    /* a wall particle: its fluid neighbours only */
#pragma omp simd reduction(+ : S, sp, su0, su1, su2)
    for (size_t q = 0; q < b.m; q++) {
      struct vsph_pair pr;
      vsph_pair_at(&b, q, dim, &pr);
      const size_t j = pr.j;
      const double s = sqrt(pr.s2) / h;
      const double w1 = (quintic ? sig * vsph_kernel_f_quintic(s)
                         : cubic ? sig * vsph_kernel_f_cubic(s)
                                 : vsph_kernel_w(k, dim, s)) *
                        wf;
      /* a wall neighbour weighs 0, and its p and u (which this sweep
       * writes, on another thread perhaps) are not read */
      const int fj = id[j] < n_fluid;
      const double wk = fj ? w1 : 0.0;
      S += wk;
      sp += (fj ? pp[j] : 0.0) * wk;
      su0 += (fj ? v0[j] : 0.0) * wk;
      if (dim > 1) su1 += (fj ? v1[j] : 0.0) * wk;
      if (dim > 2) su2 += (fj ? v2[j] : 0.0) * wk;
    }
  }
  su[0] = su0, su[1] = su1, su[2] = su2;
  if (!wall) {
    p->rho[i] = S;
    p->p[i] = vsph_equations_pressure(ep, S, 0.0);
    p->vol[i] = p->m[i] / S;
    return;
  }
  double x[3] = {0, 0, 0}, uw[3];
  for (int a = 0; a < dim; a++) x[a] = p->pos[a][i];
  vsph_walls_solid_velocity(w, dim, x, uw);
  const double pw = S > 0.0 ? sp / S : 0.0;
  const double c2 = ep->c0 * ep->c0;
  p->p[i] = pw;
  p->rho[i] = ep->rho0 + pw / c2; /* the linear law inverted */
  p->vol[i] = p->m[i] / p->rho[i];
  for (int a = 0; a < dim; a++) {
    p->vel[a][i] = S > 0.0 ? 2.0 * uw[a] - su[a] / S : uw[a];
    if (p->tvel[a]) p->tvel[a][i] = p->vel[a][i];
  }
}

/* Whether the Adami sweeps take their specialised quintic copy. */
static int adami_shape(const struct vsph_equations_props *ep,
                       const struct vsph_pair_kernel *pk, int dim) {
  if (ep->loop_general || dim != 2) return SHAPE_GENERAL;
  if (pk->dfq_id == VSPH_KERNEL_DFQ_QUINTIC &&
      ep->visc.kernel->f[1] == vsph_quintic_type.f[1])
    return SHAPE_QUINTIC2;
  if (pk->dfq_id == VSPH_KERNEL_DFQ_CUBIC &&
      ep->visc.kernel->f[1] == vsph_cubic_type.f[1])
    return SHAPE_CUBIC2;
  return SHAPE_GENERAL;
}

void vsph_equations_density_sum(const struct vsph_equations_props *ep,
                                struct vsph_particles *p, size_t n_fluid,
                                const struct vsph_cells *cells) {
  if (!ep || !p || !cells) return;
  const int dim = p->dim;
  const struct vsph_kernel_type *k = ep->visc.kernel;
  const double h = ep->visc.h, wf = pow(h, -dim);
  const double w0 = vsph_kernel_w(k, dim, 0.0) * wf;
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, k, dim, h);
  const int shape = adami_shape(ep, &pk, dim);
  /* the fluid's sweep of the Adami walls (no wall is read there) */
  struct vsph_share sh; /* runs of cells, owner first */
  vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel
  for (size_t c, run[2] = {0, 0};
       vsph_share_next_cell(&sh, cells->ncells, run, &c);) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    for (size_t i = cells->start[c]; i < cells->start[c] + cells->count[c];
         i++) {
      if (p->id[i] >= n_fluid) continue;
      if (shape == SHAPE_QUINTIC2)
        adami_one(ep, NULL, p, n_fluid, &pk, &rg, i, w0, wf, SHAPE_QUINTIC2);
      else if (shape == SHAPE_CUBIC2)
        adami_one(ep, NULL, p, n_fluid, &pk, &rg, i, w0, wf, SHAPE_CUBIC2);
      else
        adami_one(ep, NULL, p, n_fluid, &pk, &rg, i, w0, wf, SHAPE_GENERAL);
    }
  }
}

int vsph_equations_walls_adami(const struct vsph_equations_props *ep,
                               const struct vsph_walls *w,
                               struct vsph_particles *p, size_t n_fluid,
                               const struct vsph_cells *cells) {
  if (!w || !p || !cells)
    VSPH_FAIL(VSPH_EINVAL, "vsph_equations_walls_adami: a NULL argument");
  if (ep->eos != VSPH_EQUATIONS_EOS_LINEAR)
    VSPH_FAIL(VSPH_EINVAL, "wall particles need the linear state equation");
  const int dim = p->dim;
  const struct vsph_kernel_type *k = ep->visc.kernel;
  const double h = ep->visc.h;
  const double wf = pow(h, -dim), w0 = vsph_kernel_w(k, dim, 0.0) * wf;
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, k, dim, h);
  const int shape = adami_shape(ep, &pk, dim);
  /* two sweeps: the fluid (density, pressure, volume), then the walls,
   * which read the fluid's pressure */
  for (int sweep = 0; sweep < 2; sweep++) {
    struct vsph_share sh; /* runs of cells, owner first */
    vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel
    for (size_t c, run[2] = {0, 0};
         vsph_share_next_cell(&sh, cells->ncells, run, &c);) {
      struct vsph_pair_ranges rg;
      vsph_pair_ranges_cell(&rg, cells, c);
      for (size_t i = cells->start[c]; i < cells->start[c] + cells->count[c];
           i++) {
        const int wall = p->id[i] >= n_fluid;
        if (wall != sweep) continue;
        if (!wall && !ep->summation && !ep->tvf) { /* continuity's density */
          p->p[i] = vsph_equations_pressure(ep, p->rho[i], 0.0);
          p->vol[i] = p->m[i] / p->rho[i];
          continue;
        }
        if (shape == SHAPE_QUINTIC2)
          adami_one(ep, w, p, n_fluid, &pk, &rg, i, w0, wf, SHAPE_QUINTIC2);
        else if (shape == SHAPE_CUBIC2)
          adami_one(ep, w, p, n_fluid, &pk, &rg, i, w0, wf, SHAPE_CUBIC2);
        else
          adami_one(ep, w, p, n_fluid, &pk, &rg, i, w0, wf, SHAPE_GENERAL);
      }
    }
  }
  return VSPH_OK;
}

/* An evolving wall particle i (Basa et al. 2009): its continuity rate
 * from the fluid neighbours, the particle at rest,
 * d rho_i/dt = rho_i sum_f V_f F u_f.x. */
static void evolving_one(struct vsph_particles *p, size_t n_fluid,
                         const struct vsph_pair_kernel *pk,
                         const struct vsph_pair_ranges *rg, size_t i) {
  const int dim = p->dim;
  struct vsph_pair_iter it;
  struct vsph_pair_chunk b;
  vsph_pair_begin(&it, pk, p, rg, i);
  double cont = 0.0;
  while (vsph_pair_gather(&it, dim, pk->dfq_id, &b))
    for (size_t q = 0; q < b.m; q++) {
      struct vsph_pair pr;
      vsph_pair_at(&b, q, dim, &pr);
      if (p->id[pr.j] >= n_fluid) continue;
      double dux = 0.0;
      for (int a = 0; a < dim; a++) dux += p->vel[a][pr.j] * pr.x[a];
      cont += vsph_pair_continuity(&pr, dux);
    }
  p->drho[i] = p->rho[i] * cont;
}

/* XSPH's velocity of particle i (range rg), for a kernel shape (as
 * adami_one: the 2-D cubic B-spline inlined, else the kernel's f). */
VSPH_CONSTS_SPECIALISE void xsph_one(const struct vsph_equations_props *ep,
                                     const struct vsph_particles *p,
                                     const struct vsph_pair_kernel *pk,
                                     const struct vsph_pair_ranges *rg,
                                     size_t i, double eps, double wf,
                                     double *const w[3], const int shape) {
  const int cubic = shape == SHAPE_CUBIC2, dim = cubic ? 2 : p->dim;
  const struct vsph_kernel_type *k = ep->visc.kernel;
  const double h = ep->visc.h, sig = k->sigma[dim - 1];
  double sum[3] = {0, 0, 0};
  struct vsph_pair_iter it;
  struct vsph_pair_chunk b;
  vsph_pair_begin(&it, pk, p, rg, i);
  while (vsph_pair_gather(&it, dim, cubic ? VSPH_KERNEL_DFQ_CUBIC : pk->dfq_id,
                          &b)) {
    double Wq[VSPH_PAIR_CHUNK_MAX];
#pragma omp simd
    for (size_t q = 0; q < b.m; q++) {
      const double s = sqrt(b.s2[q]) / h;
      Wq[q] =
          (cubic ? sig * vsph_kernel_f_cubic(s) : vsph_kernel_w(k, dim, s)) *
          wf;
    }
    for (size_t q = 0; q < b.m; q++) { /* in pair order */
      const size_t j = b.j[q];
      const double Vj = p->m[j] / p->rho[j];
      for (int a = 0; a < dim; a++)
        sum[a] += Vj * (p->vel[a][j] - p->vel[a][i]) * Wq[q];
    }
  }
  for (int a = 0; a < dim; a++) w[a][i] = p->vel[a][i] + eps * sum[a];
}

void vsph_equations_xsph(const struct vsph_equations_props *ep,
                         const struct vsph_particles *p, size_t n_fluid,
                         const struct vsph_cells *cells, double eps,
                         double *const w[3]) {
  if (!ep || !p || !cells || !w) return;
  const int dim = p->dim;
  const struct vsph_kernel_type *k = ep->visc.kernel;
  const double h = ep->visc.h, wf = pow(h, -dim);
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, k, dim, h);
  const int cubic = adami_shape(ep, &pk, dim) == SHAPE_CUBIC2;
  struct vsph_share sh; /* runs of cells, owner first */
  vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel
  for (size_t c, run[2] = {0, 0};
       vsph_share_next_cell(&sh, cells->ncells, run, &c);) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    for (size_t i = cells->start[c]; i < cells->start[c] + cells->count[c];
         i++) {
      if (p->id[i] >= n_fluid) continue;
      if (cubic)
        xsph_one(ep, p, &pk, &rg, i, eps, wf, w, SHAPE_CUBIC2);
      else
        xsph_one(ep, p, &pk, &rg, i, eps, wf, w, SHAPE_GENERAL);
    }
  }
}

int vsph_equations_walls_evolving(const struct vsph_equations_props *ep,
                                  struct vsph_particles *p, size_t n_fluid,
                                  const struct vsph_cells *cells) {
  if (!ep || !p || !cells)
    VSPH_FAIL(VSPH_EINVAL, "vsph_equations_walls_evolving: a NULL argument");
  if (ep->eos == VSPH_EQUATIONS_EOS_GAS)
    VSPH_FAIL(VSPH_EINVAL, "evolving wall particles take a barotropic law");
  const int dim = p->dim;
  const struct vsph_kernel_type *k = ep->visc.kernel;
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, k, dim, ep->visc.h);
  /* the walls' p and V first (the fluid's sum reads only masses), then
   * the fluid: summed or continuity's density, p and V */
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] >= n_fluid) {
      p->p[i] = vsph_equations_pressure(ep, p->rho[i], 0.0);
      p->vol[i] = p->m[i] / p->rho[i];
    }
  if (ep->summation)
    vsph_equations_density_sum(ep, p, n_fluid, cells);
  else
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < p->n; i++)
      if (p->id[i] < n_fluid) {
        p->p[i] = vsph_equations_pressure(ep, p->rho[i], 0.0);
        p->vol[i] = p->m[i] / p->rho[i];
      }
  /* the walls' continuity rates read the fluid's volumes */
  struct vsph_share sh; /* runs of cells, owner first */
  vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel
  for (size_t c, run[2] = {0, 0};
       vsph_share_next_cell(&sh, cells->ncells, run, &c);) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    for (size_t i = cells->start[c]; i < cells->start[c] + cells->count[c]; i++)
      if (p->id[i] >= n_fluid) evolving_one(p, n_fluid, &pk, &rg, i);
  }
  return VSPH_OK;
}

void vsph_equations_energy_compute(const struct vsph_equations_props *ep,
                                   const struct vsph_particles *p,
                                   size_t n_fluid,
                                   struct vsph_equations_energy *en) {
  if (!ep || !p || !en) return;
  memset(en, 0, sizeof *en);
  const int d = p->dim;
  const double c2 = ep->c0 * ep->c0, gt = VSPH_EQUATIONS_TAIT_GAMMA;
  const double e0 = vsph_equations_gas_e0(ep);
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    const int mi = p->mat ? p->mat[i] : 0; /* contact: its material */
    const double m = p->m[i], rr = vsph_equations_rho0(ep, mi) / p->rho[i];
    const double cm = vsph_equations_c0(ep, mi);
    double x[3] = {0, 0, 0}, u2 = 0.0;
    for (int k = 0; k < d; k++) {
      x[k] = p->pos[k][i];
      u2 += p->vel[k][i] * p->vel[k][i];
      en->P[k] += m * p->vel[k][i];
    }
    en->Ek += 0.5 * m * u2;
    en->Ep += m * vsph_equations_potential(ep, x);
    /* int_rho0^rho p/r^2 dr of the state equation (the gas: e - e0) */
    if (ep->eos == VSPH_EQUATIONS_EOS_TAIT)
      en->Ec += m * c2 / gt *
                ((pow(1.0 / rr, gt - 1.0) - 1.0) / (gt - 1.0) + rr - 1.0);
    else if (ep->eos == VSPH_EQUATIONS_EOS_GAS)
      en->Ec += m * (p->e[i] - e0);
    else if (ep->eos == VSPH_EQUATIONS_EOS_ISOTHERMAL) /* c^2 ln(rho/rho0) */
      en->Ec -= m * cm * cm * log(rr);
    else
      en->Ec += m * cm * cm * (-log(rr) + rr - 1.0);
    if (d >= 2) en->Lz += m * (x[0] * p->vel[1][i] - x[1] * p->vel[0][i]);
  }
}

void vsph_equations_budget_compute(const struct vsph_equations_props *ep,
                                   const struct vsph_particles *p,
                                   size_t n_fluid,
                                   const struct vsph_equations_out *out,
                                   struct vsph_equations_budget *b) {
  if (!ep || !p || !out || !b) return;
  memset(b, 0, sizeof *b);
  const int d = p->dim;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    const double m = p->m[i], rho = p->rho[i];
    double x[3] = {0, 0, 0}, g[3];
    for (int k = 0; k < d; k++) x[k] = p->pos[k][i];
    body_force(ep, x, g);
    for (int k = 0; k < d; k++) {
      const double u = p->vel[k][i];
      b->dEk += m * u * out->acc[k][i];
      b->dEp -= m * g[k] * u;
      if (out->acc_visc[0]) b->P_visc += m * u * out->acc_visc[k][i];
    }
    if (ep->eos == VSPH_EQUATIONS_EOS_GAS) { /* e is its own field: delta-SPH
                                                 moves rho, not e */
      b->dEc += m * out->de[i];
      continue;
    }
    /* a barotropic law: e'(rho) = p/rho^2 */
    const double de = p->p[i] / (rho * rho);
    b->dEc += m * de * out->drho[i];
    if (out->drho_delta) b->P_delta += m * de * out->drho_delta[i];
  }
  b->residual = b->dEk + b->dEp + b->dEc - b->P_visc - b->P_delta;
}
