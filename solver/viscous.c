#include "viscous.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "particles.h"

static const char *const viscous_names[] = {
    [VSPH_VISCOUS_MGF] = "mgf",
    [VSPH_VISCOUS_MEAF] = "meaf",
    [VSPH_VISCOUS_PVWF] = "pvwf",
};
_Static_assert(sizeof viscous_names / sizeof viscous_names[0] ==
                   VSPH_VISCOUS_FORM_COUNT,
               "viscous name table out of sync");

const char *vsph_viscous_name(int form) {
  return form >= 0 && form < VSPH_VISCOUS_FORM_COUNT ? viscous_names[form]
                                                     : "unknown";
}

int vsph_viscous_find(const char *name) {
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++)
    if (strcmp(viscous_names[k], name) == 0) return k;
  return -1;
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
  /* THEORY.md section 3: MGF implies lambda = mu; PVWF zero bulk viscosity. */
  vp->lambda = form == VSPH_VISCOUS_PVWF ? -2.0 * mu / dim : mu;
  vp->det_tol = 1e-8;
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

void vsph_viscous_ws_free(struct vsph_viscous_ws *ws) {
  if (!ws) return;
  for (int a = 0; a < 9; a++) free(ws->A[a]);
  free(ws->dens);
  free(ws->fallback);
  free(ws);
}

/* Inverse of a symmetric positive semi-definite d x d matrix (row-major);
 * returns 0 and leaves inv untouched when det <= tol (tr/d)^d. */
static int invert_sym(int dim, const double *b, double *inv, double tol) {
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

/* Quantities every pair loop needs, loaded once (STYLE B7). */
struct pair_ctx {
  int dim;
  double H2;      /* (kappa h)^2 */
  double h_inv2;  /* 1/h^2 */
  double dwq_fac; /* sigma_d h^{-d-2}: W'(s)/s = dwq_fac dfq(s^2/h^2) */
  vsph_kernel_fn *dfq;
};

static void pair_ctx_init(struct pair_ctx *pc,
                          const struct vsph_viscous_props *vp) {
  const struct vsph_kernel_type *k = vp->kernel;
  const double H = k->kappa * vp->h;
  pc->dim = vp->dim;
  pc->H2 = H * H;
  pc->h_inv2 = 1.0 / (vp->h * vp->h);
  pc->dwq_fac = k->sigma[vp->dim - 1] * pow(vp->h, -(vp->dim + 2));
  pc->dfq = k->dfq[vp->dim - 1];
}

/* MGF (4.20) and MEAF (4.30) for particle i: one pass. */
static void mgf_meaf_one(const struct vsph_viscous_props *vp,
                         const struct pair_ctx *pc,
                         const struct vsph_particles *p, size_t i, size_t nr,
                         const size_t *lo, const size_t *hi, double f[3],
                         double *dens) {
  const int dim = pc->dim;
  const double K = 2.0 * (dim + 2);
  double acc[3] = {0, 0, 0}, pd = 0.0;
  for (size_t r = 0; r < nr; r++)
    for (size_t j = lo[r]; j < hi[r]; j++) {
      if (j == i) continue;
      double x[3], du[3], s2 = 0.0;
      for (int k = 0; k < dim; k++) {
        x[k] = p->pos[k][j] - p->pos[k][i];
        s2 += x[k] * x[k];
      }
      if (s2 >= pc->H2) continue;
      const double F = pc->dwq_fac * pc->dfq(s2 * pc->h_inv2); /* W'/s */
      const double Vj = p->vol[j];
      for (int k = 0; k < dim; k++) du[k] = p->vel[k][j] - p->vel[k][i];
      if (vp->form == VSPH_VISCOUS_MGF) {
        double dux = 0.0;
        for (int k = 0; k < dim; k++) dux += du[k] * x[k];
        /* K mu V_j (du.x)/s^2 grad_i W, grad_i W = -x W'/s */
        const double c = -K * Vj * dux * F / s2;
        for (int k = 0; k < dim; k++) acc[k] += c * x[k];
        pd += Vj * dux * dux * F / s2;
      } else {
        /* 2 mu V_j W'/s (u_i - u_j) */
        const double c = -2.0 * Vj * F;
        double du2 = 0.0;
        for (int k = 0; k < dim; k++) {
          acc[k] += c * du[k];
          du2 += du[k] * du[k];
        }
        pd += Vj * F * du2;
      }
    }
  for (int k = 0; k < dim; k++) f[k] = vp->mu * acc[k];
  if (dens)
    *dens = vp->form == VSPH_VISCOUS_MGF ? 0.5 * K * vp->mu * pd : vp->mu * pd;
}

/* PVWF pass 1 for particle i: L_i, renormalised grad u, D_i, T_i, A_i. */
static void pvwf_pass1(const struct vsph_viscous_props *vp,
                       const struct pair_ctx *pc,
                       const struct vsph_particles *p, size_t i, size_t nr,
                       const size_t *lo, const size_t *hi,
                       struct vsph_viscous_ws *ws) {
  const int dim = pc->dim;
  double B[9] = {0}, Mg[9] = {0}, L[9] = {0}, G[9] = {0};
  for (size_t r = 0; r < nr; r++)
    for (size_t j = lo[r]; j < hi[r]; j++) {
      if (j == i) continue;
      double x[3], s2 = 0.0;
      for (int k = 0; k < dim; k++) {
        x[k] = p->pos[k][j] - p->pos[k][i];
        s2 += x[k] * x[k];
      }
      if (s2 >= pc->H2) continue;
      /* V_j (-W'/s): grad_i W (x) x = (-W'/s) x (x) x */
      const double c = -p->vol[j] * pc->dwq_fac * pc->dfq(s2 * pc->h_inv2);
      for (int a = 0; a < dim; a++) {
        const double du = p->vel[a][j] - p->vel[a][i];
        for (int b = 0; b < dim; b++) {
          B[a * dim + b] += c * x[a] * x[b];
          Mg[a * dim + b] += c * du * x[b];
        }
      }
    }
  ws->fallback[i] = !invert_sym(dim, B, L, vp->det_tol);
  if (ws->fallback[i])
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

/* PVWF pass 2: sum_j V_j (A_j + A_i) grad_i W (Eq. 4.19). */
static void pvwf_pass2(const struct pair_ctx *pc,
                       const struct vsph_particles *p, size_t i, size_t nr,
                       const size_t *lo, const size_t *hi,
                       const struct vsph_viscous_ws *ws, double f[3]) {
  const int dim = pc->dim;
  double Ai[9], acc[3] = {0, 0, 0};
  for (int a = 0; a < dim * dim; a++) Ai[a] = ws->A[a][i];
  for (size_t r = 0; r < nr; r++)
    for (size_t j = lo[r]; j < hi[r]; j++) {
      if (j == i) continue;
      double x[3], s2 = 0.0;
      for (int k = 0; k < dim; k++) {
        x[k] = p->pos[k][j] - p->pos[k][i];
        s2 += x[k] * x[k];
      }
      if (s2 >= pc->H2) continue;
      const double c = -p->vol[j] * pc->dwq_fac * pc->dfq(s2 * pc->h_inv2);
      for (int a = 0; a < dim; a++) {
        double y = 0.0;
        for (int b = 0; b < dim; b++)
          y += (ws->A[a * dim + b][j] + Ai[a * dim + b]) * x[b];
        acc[a] += c * y;
      }
    }
  for (int k = 0; k < dim; k++) f[k] = acc[k];
}

int vsph_viscous_prepare(const struct vsph_viscous_props *vp,
                         const struct vsph_particles *p,
                         const struct vsph_cells *cells,
                         struct vsph_viscous_ws *ws) {
  if (vp->form != VSPH_VISCOUS_PVWF) return VSPH_OK;
  if (!ws || ws->cap < p->n || ws->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "PVWF needs a workspace for %zu particles", p->n);
  struct pair_ctx pc;
  pair_ctx_init(&pc, vp);
#pragma omp parallel for schedule(dynamic, 8)
  for (size_t c = 0; c < cells->ncells; c++) {
    size_t lo[VSPH_CELLS_MAXRANGES], hi[VSPH_CELLS_MAXRANGES];
    const size_t nr = vsph_cells_ranges(cells, c, lo, hi);
    const size_t i0 = cells->start[c], i1 = i0 + cells->count[c];
    for (size_t i = i0; i < i1; i++) pvwf_pass1(vp, &pc, p, i, nr, lo, hi, ws);
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
  if (vp->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "props dimension %d, particles %d", vp->dim, p->dim);
  const int pvwf = vp->form == VSPH_VISCOUS_PVWF;
  int st = vsph_viscous_prepare(vp, p, cells, ws);
  if (st) return st;
  struct pair_ctx pc;
  pair_ctx_init(&pc, vp);
  const int dim = vp->dim;
#pragma omp parallel for schedule(dynamic, 8)
  for (size_t c = 0; c < cells->ncells; c++) {
    size_t lo[VSPH_CELLS_MAXRANGES], hi[VSPH_CELLS_MAXRANGES];
    const size_t nr = vsph_cells_ranges(cells, c, lo, hi);
    const size_t i0 = cells->start[c], i1 = i0 + cells->count[c];
    for (size_t i = i0; i < i1; i++) {
      double f[3] = {0, 0, 0};
      if (!pvwf) {
        double d = 0.0;
        mgf_meaf_one(vp, &pc, p, i, nr, lo, hi, f, dens ? &d : NULL);
        if (dens) dens[i] = d;
      } else {
        pvwf_pass2(&pc, p, i, nr, lo, hi, ws, f);
        if (dens) dens[i] = ws->dens[i];
      }
      for (int k = 0; k < dim; k++) out[k][i] = f[k];
    }
  }
  return VSPH_OK;
}
