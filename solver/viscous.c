/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "viscous.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "forms/forms.h"
#include "pair.h"
#include "particles.h"
#include "share_internal.h"
#include "viscous_internal.h"

/* Every formulation (docs/theory.md, sections 3 and 8), each described
 * in its family's file of solver/forms/. The first
 * VSPH_VISCOUS_PAPER_COUNT are the free-surface study's. */
const struct vsph_viscous_type
    *const vsph_viscous_types[VSPH_VISCOUS_FORM_COUNT] = {
        [VSPH_VISCOUS_MGF] = &vsph_brookshaw_mgf,
        [VSPH_VISCOUS_MEAF] = &vsph_morris_meaf,
        [VSPH_VISCOUS_PVWF] = &vsph_stress_pvwf,
        [VSPH_VISCOUS_VI] = &vsph_brookshaw_vi,
        [VSPH_VISCOUS_CLEARY] = &vsph_brookshaw_cleary,
        [VSPH_VISCOUS_TWOPASS] = &vsph_stress_twopass,
        [VSPH_VISCOUS_TAKEDA] = &vsph_takeda_a,
        [VSPH_VISCOUS_TAKEDA0] = &vsph_takeda_a0,
        [VSPH_VISCOUS_ER] = &vsph_er_er,
        [VSPH_VISCOUS_VISC01] = &vsph_zheng_visc01,
        [VSPH_VISCOUS_VISC02] = &vsph_zheng_visc02,
        [VSPH_VISCOUS_VISC03] = &vsph_zheng_visc03,
        [VSPH_VISCOUS_VISC04] = &vsph_zheng_visc04,
        [VSPH_VISCOUS_MEAFETA] = &vsph_morris_meafeta,
};

const struct vsph_viscous_type *vsph_viscous_type_get(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT ? vsph_viscous_types[form]
                                                     : NULL;
}

const char *vsph_viscous_limit_name(int limit) {
  static const char *const names[] = {
      [VSPH_VISCOUS_LIMIT_STRESS] = "stress",
      [VSPH_VISCOUS_LIMIT_GRADIENT] = "gradient",
      [VSPH_VISCOUS_LIMIT_LAPLACIAN] = "laplacian"};
  return limit >= 0 && limit < (int)(sizeof names / sizeof *names)
             ? names[limit]
             : "unknown";
}

const char *vsph_viscous_name(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT
             ? vsph_viscous_types[form]->name
             : "unknown";
}

int vsph_viscous_find(const char *name) {
  if (!name) return -1;
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++)
    if (strcmp(vsph_viscous_types[k]->name, name) == 0) return k;
  return -1;
}

const char *vsph_viscous_label(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT
             ? vsph_viscous_types[form]->label
             : "?";
}

const char *vsph_viscous_list(unsigned flags, char *buf, size_t n) {
  if (!buf) return NULL;
  size_t len = 0;
  if (n) buf[0] = '\0';
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT && len < n; k++)
    if ((vsph_viscous_types[k]->flags & flags) == flags)
      len += (size_t)snprintf(buf + len, n - len, "%s%s", len ? ", " : "",
                              vsph_viscous_types[k]->name);
  return buf;
}

int vsph_viscous_resolve(const char *name, int *form) {
  if (!name || !form)
    VSPH_FAIL(VSPH_EINVAL, "vsph_viscous_resolve: a NULL argument");
  *form = vsph_viscous_find(name);
  if (*form >= 0) return VSPH_OK;
  char list[256];
  VSPH_FAIL(VSPH_EINVAL, "unknown formulation '%s' (%s)", name,
            vsph_viscous_list(0, list, sizeof list));
}

int vsph_viscous_props_init(struct vsph_viscous_props *vp, int form,
                            const struct vsph_kernel_type *kernel, int dim,
                            double h, double mu) {
  if (form < 0 || form >= VSPH_VISCOUS_FORM_COUNT)
    VSPH_FAIL(VSPH_EINVAL, "unknown viscous formulation %d", form);
  if (dim < 1 || dim > 3)
    VSPH_FAIL(VSPH_EINVAL, "dimension %d outside 1-3", dim);
  if (!kernel) VSPH_FAIL(VSPH_EINVAL, "no kernel given");
  if (!(h > 0.0) || !isfinite(h))
    VSPH_FAIL(VSPH_EINVAL, "smoothing length must be positive, got %g", h);
  if (!(mu >= 0.0) || !isfinite(mu))
    VSPH_FAIL(VSPH_EINVAL, "viscosity must be non-negative, got %g", mu);
  vp->form = form;
  vp->dim = dim;
  vp->kernel = kernel;
  vp->h = h;
  vp->mu = mu;
  /* THEORY.md section 3: MGF implies lambda = mu; PVWF zero bulk viscosity.
   * Models A and B (docs/theory.md section 8): Basa et al.'s eq. (4) and
   * Vukcevic et al.'s eq. (13) take lambda = -2 mu/3, the 3-D Stokes value,
   * in 2-D too; kept as the papers have it. */
  const struct vsph_viscous_type *t = vsph_viscous_types[form];
  vp->lambda = t->lambda == VSPH_VISCOUS_LAMBDA_STOKES    ? -2.0 * mu / dim
               : t->lambda == VSPH_VISCOUS_LAMBDA_STOKES3 ? -2.0 * mu / 3.0
                                                          : mu;
  vp->zeta = 0.0;
  vp->det_tol = 1e-8;
  vp->xi = VSPH_VISCOUS_XI_CLEARY;
  /* eta = 0.1 h: Basa et al.'s C and D; the usual choice for Zheng et
   * al.'s hybrid forms, who give none (their patch test keeps 0) */
  vp->eta = t->eta;
  return VSPH_OK;
}

struct vsph_viscous_ws *vsph_viscous_ws_alloc(size_t cap, int dim) {
  struct vsph_viscous_ws *ws = calloc(1, sizeof *ws);
  if (!ws) goto fail;
  ws->cap = cap;
  ws->dim = dim;
  for (int a = 0; a < dim * dim; a++)
    if (!(ws->A[a] = malloc((cap ? cap : 1) * sizeof(double)))) goto fail;
  ws->dens = malloc((cap ? cap : 1) * sizeof(double));
  ws->fallback = malloc(cap ? cap : 1);
  if (!ws->dens || !ws->fallback) goto fail;
  return ws;
fail:
  vsph_viscous_ws_free(ws);
  vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                     "cannot allocate a viscous workspace for %zu", cap);
  return NULL;
}

int vsph_viscous_ws_corr(struct vsph_viscous_ws *ws) {
  if (!ws) VSPH_FAIL(VSPH_EINVAL, "vsph_viscous_ws_corr: a NULL argument");
  if (ws->S) return VSPH_OK;
  const size_t c = ws->cap ? ws->cap : 1;
  int ok = (ws->S = malloc(c * sizeof(double))) != NULL;
  for (int a = 0; a < ws->dim; a++)
    ok = ok && (ws->a[a] = malloc(c * sizeof(double))) != NULL;
  for (int a = 0; a < ws->dim * ws->dim; a++)
    ok = ok && (ws->L[a] = malloc(c * sizeof(double))) != NULL;
  if (!ok)
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the corrections of %zu particles",
              ws->cap);
  return VSPH_OK;
}

void vsph_viscous_ws_free(struct vsph_viscous_ws *ws) {
  if (!ws) return;
  free(ws->S);
  for (int a = 0; a < 3; a++) free(ws->a[a]);
  for (int a = 0; a < 9; a++) free(ws->L[a]);
  for (int a = 0; a < 9; a++) free(ws->A[a]);
  free(ws->dens);
  free(ws->fallback);
  free(ws);
}

int vsph_viscous_invert_sym(int dim, const double *b, double *inv, double tol) {
  double tr = 0.0;
  for (int a = 0; a < dim; a++) tr += b[a * dim + a];
  double scale = tr / dim;
  if (!(scale > 0.0)) return 0;
  double det;
  if (dim == 1) {
    det = b[0];
    if (!(det > tol * scale)) return 0;
    inv[0] = 1.0 / det;
    return 1;
  }
  if (dim == 2) {
    det = b[0] * b[3] - b[1] * b[2];
    if (!(det > tol * scale * scale)) return 0;
    const double di = 1.0 / det;
    inv[0] = b[3] * di;
    inv[1] = -b[1] * di;
    inv[2] = -b[2] * di;
    inv[3] = b[0] * di;
    return 1;
  }
  const double c00 = b[4] * b[8] - b[5] * b[7];
  const double c01 = b[5] * b[6] - b[3] * b[8];
  const double c02 = b[3] * b[7] - b[4] * b[6];
  det = b[0] * c00 + b[1] * c01 + b[2] * c02;
  if (!(det > tol * scale * scale * scale)) return 0;
  const double di = 1.0 / det;
  inv[0] = c00 * di;
  inv[1] = (b[2] * b[7] - b[1] * b[8]) * di;
  inv[2] = (b[1] * b[5] - b[2] * b[4]) * di;
  inv[3] = c01 * di;
  inv[4] = (b[0] * b[8] - b[2] * b[6]) * di;
  inv[5] = (b[2] * b[3] - b[0] * b[5]) * di;
  inv[6] = c02 * di;
  inv[7] = (b[1] * b[6] - b[0] * b[7]) * di;
  inv[8] = (b[0] * b[4] - b[1] * b[3]) * di;
  return 1;
}

/* vsph_viscous_pvwf_finish for dimension @p dim (a constant where
 * inlined) and @p renorm, the form's VSPH_VISCOUS_RENORM */
VSPH_CONSTS_SPECIALISE void pvwf_finish(const struct vsph_viscous_props *vp,
                                        struct vsph_viscous_ws *ws, size_t i,
                                        const double B[9], const double Mg[9],
                                        const int renorm, const int dim) {
  double L[9] = {0}, G[9] = {0};
  ws->fallback[i] =
      renorm ? !vsph_viscous_invert_sym(dim, B, L, vp->det_tol) : 0;
  if (ws->fallback[i] || !renorm)
    for (int a = 0; a < dim; a++) L[a * dim + a] = 1.0;
  /* (grad u)_ab = sum_j V_j du_a (L grad_i W)_b = (Mg L^T)_ab, L symmetric */
  for (int a = 0; a < dim; a++)
    for (int b = 0; b < dim; b++) {
      double g = 0.0;
      for (int c = 0; c < dim; c++) g += Mg[a * dim + c] * L[b * dim + c];
      G[a * dim + b] = g;
    }
  double D[9], T[9], trD = 0.0;
  for (int a = 0; a < dim; a++) trD += G[a * dim + a];
  double TD = 0.0;
  for (int a = 0; a < dim; a++)
    for (int b = 0; b < dim; b++) {
      D[a * dim + b] = 0.5 * (G[a * dim + b] + G[b * dim + a]);
      T[a * dim + b] =
          2.0 * vp->mu * D[a * dim + b] + (a == b ? vp->lambda * trD : 0.0);
      TD += T[a * dim + b] * D[a * dim + b];
    }
  for (int a = 0; a < dim; a++)
    for (int b = 0; b < dim; b++) {
      double s = 0.0;
      for (int c = 0; c < dim; c++) s += T[a * dim + c] * L[c * dim + b];
      ws->A[a * dim + b][i] = s;
    }
  ws->dens[i] = -TD;
}

void vsph_viscous_pvwf_finish(const struct vsph_viscous_props *vp,
                              struct vsph_viscous_ws *ws, size_t i,
                              const double B[9], const double Mg[9]) {
  if (!vp || !ws || !B || !Mg || !vsph_viscous_type_get(vp->form)) return;
  pvwf_finish(vp, ws, i, B, Mg,
              (vsph_viscous_types[vp->form]->flags & VSPH_VISCOUS_RENORM) != 0,
              vp->dim);
}

void vsph_viscous_pvwf_finish_rows(const struct vsph_viscous_props *vp,
                                   struct vsph_viscous_ws *ws, size_t i0,
                                   size_t i1, const double *t) {
  const int dim = vp->dim, nf = 2 * dim * dim,
            renorm = (vsph_viscous_types[vp->form]->flags &
                      VSPH_VISCOUS_RENORM) != 0;
  for (size_t i = i0; i < i1; i++) {
    const double *const s = t + (i - i0) * (size_t)nf;
    if (dim == 2)
      pvwf_finish(vp, ws, i, s, s + 4, renorm, 2);
    else
      pvwf_finish(vp, ws, i, s, s + nf / 2, renorm, dim);
  }
}

/* vsph_viscous_laplacians for dimension dim (a constant where inlined) */
VSPH_CONSTS_SPECIALISE void laplacians(
    const struct vsph_pair_kernel *pk, const struct vsph_kernel_type *k,
    double h, double eta2, double tol, int lap, const struct vsph_particles *p,
    const struct vsph_pair_ranges *rg, size_t i, int nf,
    const double *const f[3], double out[3], const int dim) {
  const double d2fac = pow(h, -(dim + 2));
  struct vsph_pair_lap acc[3];
  memset(acc, 0, sizeof acc);
  struct vsph_pair_iter it;
  struct vsph_pair_chunk b;
  vsph_pair_begin(&it, pk, p, rg, i);
  while (vsph_pair_gather(&it, dim, pk->dfq_id, &b))
    for (size_t m = 0; m < b.m; m++) {
      struct vsph_pair pr;
      vsph_pair_at(&b, m, dim, &pr);
      /* W'' only for VISC-02 (a square root per pair) */
      const double d2w = lap == VSPH_PAIR_LAP_DIRECT
                             ? vsph_kernel_d2w(k, dim, sqrt(pr.s2) / h) * d2fac
                             : 0.0;
      for (int c = 0; c < nf; c++)
        vsph_pair_lap_add(&acc[c], &pr, dim, p->vol[pr.j], f[c][pr.j] - f[c][i],
                          d2w, eta2);
    }
  double G[9] = {0};
  for (int a = 0; a < dim; a++) G[a * dim + a] = 1.0;
  vsph_viscous_invert_sym(dim, acc[0].M, G, tol);
  for (int c = 0; c < nf; c++)
    out[c] = vsph_pair_lap_finish(&acc[c], dim, lap, G);
}

void vsph_viscous_laplacians(const struct vsph_pair_kernel *pk,
                             const struct vsph_kernel_type *k, double h,
                             double eta2, double tol, int lap,
                             const struct vsph_particles *p,
                             const struct vsph_pair_ranges *rg, size_t i,
                             int nf, const double *const f[3], double out[3]) {
  if (!pk || !k || !p || !rg || !f || !out) return;
  if (pk->dim == 2)
    laplacians(pk, k, h, eta2, tol, lap, p, rg, i, nf, f, out, 2);
  else
    laplacians(pk, k, h, eta2, tol, lap, p, rg, i, nf, f, out, pk->dim);
}

int vsph_viscous_prepare(const struct vsph_viscous_props *vp,
                         const struct vsph_particles *p,
                         const struct vsph_cells *cells,
                         struct vsph_viscous_ws *ws) {
  if (!vp || !p || !cells)
    VSPH_FAIL(VSPH_EINVAL, "vsph_viscous_prepare: a NULL argument");
  if (!vsph_viscous_type_get(vp->form))
    VSPH_FAIL(VSPH_EINVAL, "unknown viscous formulation %d", vp->form);
  if (!vsph_viscous_first_pass(vp->form)) return VSPH_OK;
  if (!ws || ws->cap < p->n || ws->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "%s needs a workspace for %zu particles",
              vsph_viscous_label(vp->form), p->n);
  /* the family's first pass (solver/forms/), particle by particle */
  vsph_viscous_first_fn *const first = vsph_viscous_types[vp->form]->first;
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, vp->kernel, vp->dim, vp->h);
  struct vsph_share sh; /* runs of cells, owner first */
  vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel
  for (size_t c, run[2] = {0, 0};
       vsph_share_next_cell(&sh, cells->ncells, run, &c);) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    const size_t i0 = cells->start[c], i1 = i0 + cells->count[c];
    for (size_t i = i0; i < i1; i++) first(vp, &pk, p, &rg, i, ws);
  }
  size_t nf = 0; /* serial: reproducible */
  for (size_t i = 0; i < p->n; i++) nf += ws->fallback[i];
  ws->n_fallback = nf;
  return VSPH_OK;
}

int vsph_viscous_compute(const struct vsph_viscous_props *vp,
                         const struct vsph_particles *p,
                         const struct vsph_cells *cells,
                         struct vsph_viscous_ws *ws, double *const out[3],
                         double *dens) {
  if (!vp || !p || !cells || !ws || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_viscous_compute: a NULL argument");
  if (vp->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "props dimension %d, particles %d", vp->dim, p->dim);
  const int st = vsph_viscous_prepare(vp, p, cells, ws);
  if (st) return st;
  const int dim = vp->dim, first = vsph_viscous_first_pass(vp->form);
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, vp->kernel, dim, vp->h);
  struct vsph_viscous_loop lp;
  vsph_viscous_loop_init(&lp, vp, first ? ws : NULL);
  /* the form's own loop for the 2-D Gaussian, else the general one */
  const struct vsph_viscous_loops *const own =
      vsph_viscous_types[vp->form]->loops;
  const int G = VSPH_KERNEL_DFQ_GAUSSIAN;
  vsph_viscous_cell_fn *const fn =
      own && dim == 2 && pk.dfq_id == G ? own->force : NULL;
  const double *const fd = first ? ws->dens : NULL;
  struct vsph_share sh; /* runs of cells, owner first */
  vsph_share_init_cells(&sh, cells->ncells);
#pragma omp parallel
  for (size_t c, run[2] = {0, 0};
       vsph_share_next_cell(&sh, cells->ncells, run, &c);)
    if (fn)
      fn(&lp, &pk, p, cells, c, out, dens, fd);
    else
      force_cell(&lp, &pk, p, cells, c, out, dens, fd, dim, lp.pair, pk.dfq_id);
  return VSPH_OK;
}
