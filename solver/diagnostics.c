/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "diagnostics.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "pair.h"
#include "particles.h"

double vsph_diagnostics_surface_threshold(int dim) {
  return dim == 3 ? 2.4 : dim == 2 ? 1.5 : dim == 1 ? 0.75 : (double)NAN;
}

void vsph_diagnostics_free(struct vsph_diagnostics *d) {
  if (!d) return;
  if (!d->lent) {
    for (int a = 0; a < 3; a++) free(d->vort[a]);
    free(d->divr);
  }
  free(d->surf);
  memset(d, 0, sizeof *d);
}

/* A lean copy of the fields the sums read (positions, velocities,
 * volumes, ids; the cell list sorts it, and sorts only the arrays a set
 * has): 2 d + 2 arrays, not a whole set's 3 d + 6, a snapshot's peak
 * memory the less. */
static struct vsph_particles *copy_of(const struct vsph_particles *p) {
  struct vsph_particles *q = calloc(1, sizeof *q);
  if (!q) return NULL;
  const size_t cap = p->n ? p->n : 1, nb = cap * sizeof(double);
  q->n = p->n;
  q->cap = cap;
  q->dim = p->dim;
  int ok = (q->vol = malloc(nb)) && (q->id = malloc(cap * sizeof(size_t)));
  for (int a = 0; a < p->dim && ok; a++)
    ok = (q->pos[a] = malloc(nb)) && (q->vel[a] = malloc(nb));
  if (!ok) {
    vsph_particles_free(q);
    return NULL;
  }
  for (int a = 0; a < p->dim; a++) {
    memcpy(q->pos[a], p->pos[a], p->n * sizeof(double));
    memcpy(q->vel[a], p->vel[a], p->n * sizeof(double));
  }
  memcpy(q->vol, p->vol, p->n * sizeof(double));
  memcpy(q->id, p->id, p->n * sizeof(size_t));
  return q;
}

/* One neighbour's share of particle i's sums. */
struct share {
  double x[3], du[3], VF, s2;
};

/* The canonical order of a particle's neighbours: by their offset x, then
 * (a neighbour and a mirror image of it can share an offset) by the
 * velocity difference and the weights; neighbours equal in all of these
 * add the same share, so their order does not matter. The sums then do
 * not depend on the particles' order, nor on the cell list that found
 * them. */
static int by_offset(const void *a, const void *b) {
  const struct share *u = a, *v = b;
  const double ku[8] = {u->x[0],  u->x[1],  u->x[2], u->du[0],
                        u->du[1], u->du[2], u->VF,   u->s2};
  const double kv[8] = {v->x[0],  v->x[1],  v->x[2], v->du[0],
                        v->du[1], v->du[2], v->VF,   v->s2};
  for (int k = 0; k < 8; k++)
    if (ku[k] != kv[k]) return ku[k] < kv[k] ? -1 : 1;
  return 0;
}

/* The diagnostics of the fluid particles of @p q (sorted by @p cells)
 * into @p d (allocated, zeroed). VSPH_OK, VSPH_EINTR or VSPH_ENOMEM. */
static int sums(const struct vsph_particles *q, size_t n,
                const struct vsph_cells *cells,
                const struct vsph_kernel_type *k, double h,
                struct vsph_diagnostics *d, const volatile sig_atomic_t *stop) {
  const int dim = q->dim;
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, k, dim, h);
  const double thr = vsph_diagnostics_surface_threshold(dim);
  const int kid = pk.dfq_id;
  int nomem = 0; /* a thread's list could not grow */
  /* gather: particle i writes only its own entries */
#pragma omp parallel
  {
    struct share *sh = NULL;
    size_t cap = 0;
    int short_of = 0;
#pragma omp for schedule(dynamic, 16)
    for (size_t c = 0; c < cells->ncells; c++) {
      if ((stop && *stop) || short_of) continue; /* seen below */
      struct vsph_pair_ranges rg;
      vsph_pair_ranges_cell(&rg, cells, c);
      for (size_t i = cells->start[c]; i < cells->start[c] + cells->count[c];
           i++) {
        const size_t id = q->id[i];
        if (id >= n) continue;
        double ui[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++) ui[a] = q->vel[a][i];
        struct vsph_pair_iter it;
        struct vsph_pair_chunk b;
        size_t m = 0;
        vsph_pair_begin(&it, &pk, q, &rg, i);
        while (vsph_pair_gather(&it, dim, kid, &b)) {
          if (m + b.m > cap) {
            const size_t nc = 2 * (m + b.m);
            struct share *g = realloc(sh, nc * sizeof *g);
            if (!g) {
              short_of = 1;
              break;
            }
            sh = g;
            cap = nc;
          }
          for (size_t r = 0; r < b.m; r++, m++) {
            const size_t j = b.j[r];
            struct share *e = &sh[m];
            for (int a = 0; a < 3; a++) {
              e->x[a] = a < dim ? b.x[a][r] : 0.0;
              e->du[a] = a < dim ? q->vel[a][j] - ui[a] : 0.0;
            }
            e->VF = b.VF[r];
            e->s2 = b.s2[r];
          }
        }
        if (short_of) break;
        if (m > 1) qsort(sh, m, sizeof *sh, by_offset);
        double w[3] = {0, 0, 0}, dr = 0.0;
        for (size_t r = 0; r < m; r++) {
          const double *x = sh[r].x, *du = sh[r].du, VF = sh[r].VF;
          /* grad_i W_ij = -x F: omega -= VF x cross du, div r -= VF s2 */
          dr -= VF * sh[r].s2;
          w[2] -= VF * (x[0] * du[1] - x[1] * du[0]);
          if (dim == 3) {
            w[0] -= VF * (x[1] * du[2] - x[2] * du[1]);
            w[1] -= VF * (x[2] * du[0] - x[0] * du[2]);
          }
        }
        if (dim >= 2) d->vort[2][id] = w[2];
        if (dim == 3) {
          d->vort[0][id] = w[0];
          d->vort[1][id] = w[1];
        }
        d->divr[id] = dr;
        d->surf[id] = dr < thr;
      }
    }
    free(sh);
    if (short_of) {
#pragma omp atomic write
      nomem = 1;
    }
  }
  if (nomem)
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the diagnostics' neighbour lists");
  return stop && *stop ? VSPH_EINTR : VSPH_OK;
}

/* The result arrays of @p n particles (zero; in @p room where not NULL,
 * as vsph_diagnostics_compute_cells says), and whether @p p's positions
 * are all finite. VSPH_OK or VSPH_ENOMEM (@p d freed). */
static int start(const struct vsph_particles *p, size_t n, double h,
                 double *const room[4], struct vsph_diagnostics *d,
                 int *finite) {
  memset(d, 0, sizeof *d);
  d->n = n;
  d->dim = p->dim;
  d->h = h;
  const size_t len = n ? n : 1;
  d->lent = room != NULL;
  int ok = 1;
  for (int a = 0; a < 3; a++) { /* 3-D all three, 2-D omega_z, 1-D none */
    if (p->dim < 3 && !(p->dim == 2 && a == 2)) continue;
    d->vort[a] = !room    ? calloc(len, sizeof(double))
                 : a == 2 ? room[1]
                          : room[2 + a];
    ok &= d->vort[a] != NULL;
  }
  d->divr = room ? room[0] : calloc(len, sizeof(double));
  if (room) /* zero, as calloc's */
    for (size_t i = 0; i < n; i++) {
      d->divr[i] = 0.0;
      for (int a = 0; a < 3; a++)
        if (d->vort[a]) d->vort[a][i] = 0.0;
    }
  d->surf = calloc(len, 1);
  if (!ok || !d->divr || !d->surf) {
    vsph_diagnostics_free(d);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the diagnostics of %zu particles",
              n);
  }
  /* a state stopped as unstable may hold non-finite positions: its
   * diagnostics are NaN (the snapshot is still written) */
  int fin = 1;
  for (int a = 0; a < p->dim; a++)
    for (size_t i = 0; i < p->n; i++) fin &= isfinite(p->pos[a][i]) != 0;
  if (!fin)
    for (size_t i = 0; i < n; i++) {
      for (int a = 0; a < 3; a++)
        if (d->vort[a]) d->vort[a][i] = NAN;
      d->divr[i] = NAN;
    }
  *finite = fin;
  return VSPH_OK;
}

int vsph_diagnostics_compute(const struct vsph_particles *p, size_t n,
                             const struct vsph_kernel_type *k, double h,
                             struct vsph_diagnostics *d,
                             const volatile sig_atomic_t *stop) {
  if (!d) VSPH_FAIL(VSPH_EINVAL, "vsph_diagnostics_compute: a NULL argument");
  memset(d, 0, sizeof *d);
  if (!p || !k || !(h > 0.0) || n > p->n)
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_diagnostics_compute: a NULL argument, h <= 0 "
              "or more particles than the set holds");
  if (stop && *stop) return VSPH_EINTR;
  int finite;
  int st = start(p, n, h, NULL, d, &finite);
  if (st || !finite) return st;
  struct vsph_particles *q = copy_of(p);
  struct vsph_cells *cells = vsph_cells_alloc();
  if (!q || !cells) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate the diagnostics of %zu particles", n);
    st = VSPH_ENOMEM;
  }
  if (!st) st = vsph_cells_build(cells, q, k->kappa * h);
  if (!st) st = sums(q, n, cells, k, h, d, stop);
  vsph_cells_free(cells);
  vsph_particles_free(q);
  if (st) vsph_diagnostics_free(d);
  return st;
}

int vsph_diagnostics_compute_cells(const struct vsph_particles *p, size_t n,
                                   const struct vsph_cells *cells,
                                   const struct vsph_kernel_type *k, double h,
                                   double *const room[4],
                                   struct vsph_diagnostics *d,
                                   const volatile sig_atomic_t *stop) {
  if (d) memset(d, 0, sizeof *d);
  if (!p || !cells || !k || !d || !(h > 0.0) || n > p->n ||
      (!cells->direct &&
       cells->edge * VSPH_CELLS_SUB < k->kappa * h * (1.0 - 1e-12)))
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_diagnostics_compute_cells: a NULL argument, h <= 0, "
              "more particles than the set holds or cells narrower than "
              "the kernel's reach");
  if (stop && *stop) return VSPH_EINTR;
  size_t held = 0; /* the cell list is p's: it holds its particles */
  for (size_t c = 0; c < cells->ncells; c++) held += cells->count[c];
  if (cells->dim != p->dim || held != p->n)
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_diagnostics_compute_cells: the cell list "
              "holds %zu particles in %d-D, the set %zu in %d-D",
              held, cells->dim, p->n, p->dim);
  if (room && (!room[0] || !room[1] || (p->dim == 3 && (!room[2] || !room[3]))))
    VSPH_FAIL(VSPH_EINVAL, "vsph_diagnostics_compute_cells: a NULL room");
  int finite;
  int st = start(p, n, h, room, d, &finite);
  if (st || !finite) return st;
  st = sums(p, n, cells, k, h, d, stop);
  if (st) vsph_diagnostics_free(d);
  return st;
}

int vsph_diagnostics_probe(const struct vsph_particles *p, size_t n,
                           const struct vsph_kernel_type *k, double h,
                           const double period[3], const double x[3],
                           struct vsph_diagnostics_probe *out) {
  if (!p || !k || !period || !x || !out || !(h > 0.0))
    VSPH_FAIL(VSPH_EINVAL, "vsph_diagnostics_probe: a NULL argument or h <= 0");
  const int dim = p->dim;
  const double reach2 = (k->kappa * h) * (k->kappa * h);
  const double norm = k->sigma[dim - 1] / pow(h, dim);
  double s = 0.0, su[3] = {0.0, 0.0, 0.0}, sp = 0.0, sr = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n) continue;
    double r2 = 0.0;
    for (int a = 0; a < dim; a++) {
      double d = x[a] - p->pos[a][i];
      if (period[a] > 0.0) d -= period[a] * nearbyint(d / period[a]);
      r2 += d * d;
    }
    if (!(r2 < reach2)) continue;
    const double w = p->m[i] / p->rho[i] * norm * k->f[dim - 1](sqrt(r2) / h);
    s += w;
    for (int a = 0; a < dim; a++) su[a] += w * p->vel[a][i];
    sp += w * p->p[i];
    sr += w * p->rho[i];
  }
  const double inv = s > 0.0 ? 1.0 / s : (double)NAN;
  for (int a = 0; a < 3; a++) /* beyond dim 0, or NaN as the rest */
    out->u[a] = a < dim ? su[a] * inv : 0.0 * inv;
  out->p = sp * inv;
  out->rho = sr * inv;
  out->fill = s;
  return VSPH_OK;
}
