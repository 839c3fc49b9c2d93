#include "equations.h"

#include <math.h>
#include <string.h>

#include "../common/status.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "particles.h"

void vsph_equations_body_force(const struct vsph_equations_props *ep,
                               const double x[3], double g[3]) {
  g[0] = g[1] = g[2] = 0.0;
  const int d = ep->visc.dim;
  if (ep->body == VSPH_EQUATIONS_BODY_RADIAL) {
    for (int k = 0; k < d; k++) g[k] = -ep->beta * ep->beta * x[k];
  } else if (ep->body == VSPH_EQUATIONS_BODY_GRAVITY) {
    g[d - 1] = -ep->g; /* the last axis points up */
  }
}

double vsph_equations_potential(const struct vsph_equations_props *ep,
                                const double x[3]) {
  const int d = ep->visc.dim;
  if (ep->body == VSPH_EQUATIONS_BODY_RADIAL) {
    double r2 = 0.0;
    for (int k = 0; k < d; k++) r2 += x[k] * x[k];
    return 0.5 * ep->beta * ep->beta * r2;
  }
  if (ep->body == VSPH_EQUATIONS_BODY_GRAVITY) return ep->g * x[d - 1];
  return 0.0;
}

/* One fluid particle: continuity (with delta-SPH), pressure and viscous
 * sums over its neighbours. grad_i W = -x W'/s with x = r_j - r_i. */
struct rhs_ctx {
  const struct vsph_equations_props *ep;
  int dim, form;
  double H2, h_inv2, dw_fac, K, mu, dhc; /* dhc = delta h c0 */
  vsph_kernel_fn *dfq;                   /* (df/dq)/q from q^2 */
  int parts;                             /* fill acc_visc / drho_delta */
};

static size_t rhs_one(const struct rhs_ctx *rc, const struct vsph_particles *p,
                      const struct vsph_viscous_ws *ws, size_t i, size_t nr,
                      const size_t *lo, const size_t *hi,
                      struct vsph_equations_out *out, double *min_s2) {
  const int dim = rc->dim, form = rc->form;
  double xi[3] = {0, 0, 0}, ui[3] = {0, 0, 0}, Ai[9] = {0};
  for (int k = 0; k < dim; k++) {
    xi[k] = p->pos[k][i];
    ui[k] = p->vel[k][i];
  }
  if (form == VSPH_VISCOUS_PVWF)
    for (int a = 0; a < dim * dim; a++) Ai[a] = ws->A[a][i];
  const double rhoi = p->rho[i], pi = p->p[i];
  double cont = 0.0, dsum = 0.0, ap[3] = {0, 0, 0}, av[3] = {0, 0, 0};
  size_t nint = 0;
  double ms2 = INFINITY;
  for (size_t r = 0; r < nr; r++)
    for (size_t j = lo[r]; j < hi[r]; j++) {
      double x[3], s2 = 0.0;
      for (int k = 0; k < dim; k++) {
        x[k] = p->pos[k][j] - xi[k];
        s2 += x[k] * x[k];
      }
      if (s2 >= rc->H2 || j == i) continue;
      nint++;
      ms2 = s2 < ms2 ? s2 : ms2;
      /* W'/s = sigma h^{-d-2} (df/dq)/q <= 0, from q^2: no square root */
      const double F = rc->dw_fac * rc->dfq(s2 * rc->h_inv2);
      const double Vj = p->vol[j], VF = Vj * F;
      double du[3], dux = 0.0;
      for (int k = 0; k < dim; k++) {
        du[k] = p->vel[k][j] - ui[k];
        dux += du[k] * x[k];
      }
      /* continuity: -rho_i V_j (u_j - u_i).grad_i W = rho_i V_j F du.x */
      cont += VF * dux;
      /* delta-SPH: V_j psi_ij.grad_i W = -2 V_j (rho_j - rho_i) F */
      if (rc->dhc > 0.0) dsum += -2.0 * VF * (p->rho[j] - rhoi);
      /* pressure: -(1/rho_i) V_j (p_i + p_j) grad_i W */
      const double cp = VF * (pi + p->p[j]);
      for (int k = 0; k < dim; k++) ap[k] += cp * x[k];
      /* viscous (div V)_i, THEORY 3 */
      if (form == VSPH_VISCOUS_MGF) {
        const double cv = -rc->K * rc->mu * VF * dux / s2;
        for (int k = 0; k < dim; k++) av[k] += cv * x[k];
      } else if (form == VSPH_VISCOUS_MEAF) {
        const double cv = -2.0 * rc->mu * VF;
        for (int k = 0; k < dim; k++) av[k] += cv * du[k];
      } else {
        for (int a = 0; a < dim; a++) {
          double y = 0.0;
          for (int b = 0; b < dim; b++)
            y += (ws->A[a * dim + b][j] + Ai[a * dim + b]) * x[b];
          av[a] -= VF * y;
        }
      }
    }
  const double rinv = 1.0 / rhoi;
  double g[3];
  vsph_equations_body_force(rc->ep, xi, g);
  out->drho[i] = rhoi * cont + rc->dhc * dsum;
  for (int k = 0; k < dim; k++) out->acc[k][i] = rinv * (ap[k] + av[k]) + g[k];
  if (rc->parts) {
    for (int k = 0; k < dim; k++) out->acc_visc[k][i] = rinv * av[k];
    out->drho_delta[i] = rc->dhc * dsum;
  }
  *min_s2 = ms2;
  return nint;
}

int vsph_equations_rhs(const struct vsph_equations_props *ep,
                       struct vsph_particles *p, size_t n_fluid,
                       const struct vsph_cells *cells,
                       struct vsph_viscous_ws *ws,
                       struct vsph_equations_out *out) {
  const struct vsph_viscous_props *vp = &ep->visc;
  if (vp->dim != p->dim)
    VSPH_FAIL(VSPH_EINVAL, "props dimension %d, particles %d", vp->dim, p->dim);
  const size_t n = p->n;
  const double c2 = ep->c0 * ep->c0;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < n; i++) {
    p->p[i] = c2 * (p->rho[i] - ep->rho0); /* linear state equation */
    p->vol[i] = p->m[i] / p->rho[i];
  }
  const int st = vsph_viscous_prepare(vp, p, cells, ws);
  if (st) return st;
  const struct vsph_kernel_type *k = vp->kernel;
  struct rhs_ctx rc = {
      .ep = ep,
      .dim = vp->dim,
      .form = vp->form,
      .H2 = k->kappa * vp->h * k->kappa * vp->h,
      .h_inv2 = 1.0 / (vp->h * vp->h),
      .dw_fac = k->sigma[vp->dim - 1] * pow(vp->h, -(vp->dim + 2)),
      .K = 2.0 * (vp->dim + 2),
      .mu = vp->mu,
      .dhc = ep->delta * vp->h * ep->c0,
      .dfq = k->dfq[vp->dim - 1],
      .parts = out->acc_visc[0] != NULL && out->drho_delta != NULL,
  };
  size_t total = 0;
  double min_s2 = INFINITY;
  /* integer sum and min: exact, so the same for any thread count */
#pragma omp parallel for schedule(dynamic, 8) reduction(+ : total) \
    reduction(min : min_s2)
  for (size_t c = 0; c < cells->ncells; c++) {
    size_t lo[VSPH_CELLS_MAXRANGES], hi[VSPH_CELLS_MAXRANGES];
    const size_t nr = vsph_cells_ranges(cells, c, lo, hi);
    const size_t i0 = cells->start[c], i1 = i0 + cells->count[c];
    for (size_t i = i0; i < i1; i++)
      if (p->id[i] < n_fluid) {
        double m;
        total += rhs_one(&rc, p, ws, i, nr, lo, hi, out, &m);
        min_s2 = m < min_s2 ? m : min_s2;
      }
  }
  out->interactions = total;
  out->min_s2 = min_s2;
  return VSPH_OK;
}

void vsph_equations_energy_compute(const struct vsph_equations_props *ep,
                                   const struct vsph_particles *p,
                                   size_t n_fluid,
                                   struct vsph_equations_energy *en) {
  memset(en, 0, sizeof *en);
  const int d = p->dim;
  const double c2 = ep->c0 * ep->c0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    const double m = p->m[i], rr = ep->rho0 / p->rho[i];
    double x[3] = {0, 0, 0}, u2 = 0.0;
    for (int k = 0; k < d; k++) {
      x[k] = p->pos[k][i];
      u2 += p->vel[k][i] * p->vel[k][i];
      en->P[k] += m * p->vel[k][i];
    }
    en->Ek += 0.5 * m * u2;
    en->Ep += m * vsph_equations_potential(ep, x);
    en->Ec += m * c2 * (-log(rr) + rr - 1.0);
    if (d >= 2) en->Lz += m * (x[0] * p->vel[1][i] - x[1] * p->vel[0][i]);
  }
}

void vsph_equations_budget_compute(const struct vsph_equations_props *ep,
                                   const struct vsph_particles *p,
                                   size_t n_fluid,
                                   const struct vsph_equations_out *out,
                                   struct vsph_equations_budget *b) {
  memset(b, 0, sizeof *b);
  const int d = p->dim;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    const double m = p->m[i], rho = p->rho[i];
    double x[3] = {0, 0, 0}, g[3];
    for (int k = 0; k < d; k++) x[k] = p->pos[k][i];
    vsph_equations_body_force(ep, x, g);
    for (int k = 0; k < d; k++) {
      const double u = p->vel[k][i];
      b->dEk += m * u * out->acc[k][i];
      b->dEp -= m * g[k] * u;
      if (out->acc_visc[0]) b->P_visc += m * u * out->acc_visc[k][i];
    }
    /* e'(rho) = c0^2 (rho - rho0)/rho^2 = p/rho^2 */
    const double de = p->p[i] / (rho * rho);
    b->dEc += m * de * out->drho[i];
    if (out->drho_delta) b->P_delta += m * de * out->drho_delta[i];
  }
  b->residual = b->dEk + b->dEp + b->dEc - b->P_visc - b->P_delta;
}
