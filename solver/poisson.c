/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "poisson.h"

#include <fftw3.h>
#include <math.h>
#include <stdlib.h>

#include "../common/consts.h"
#include "../common/status.h"

struct vsph_poisson {
  size_t n;       /* interior nodes per side */
  double side, h; /* square side and node spacing */
  double *sol;    /* (n+2) x (n+2), fftw_malloc: the boundary ring around
                     the right-hand side, then around the solution */
  double *lam;    /* n eigenvalues of the 1-D second difference * h^2 */
  fftw_plan plan; /* 2-D RODFT00 in place on sol's n x n interior (one
                     array, not a copy: the grid is 16 nodes per particle
                     at the default 4 res across) */
};

struct vsph_poisson *vsph_poisson_alloc(size_t n, double side) {
  if (n < 2 || !(side > 0.0)) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "Poisson grid needs n >= 2 and side > 0");
    return NULL;
  }
  struct vsph_poisson *ps = calloc(1, sizeof *ps);
  if (!ps) goto fail;
  ps->n = n;
  ps->side = side;
  ps->h = side / (double)(n + 1);
  ps->sol = fftw_malloc((n + 2) * (n + 2) * sizeof(double));
  ps->lam = malloc(n * sizeof(double));
  if (!ps->sol || !ps->lam) goto fail;
  /* the interior, node (1, 1) on, rows n + 2 apart (FFTW's advanced
   * interface: an embedded array) */
  const int dims[2] = {(int)n, (int)n}, embed[2] = {(int)n + 2, (int)n + 2};
  const fftw_r2r_kind kinds[2] = {FFTW_RODFT00, FFTW_RODFT00};
  double *in = ps->sol + (n + 2) + 1;
  /* FFTW's planner is not thread-safe (its execute is): the report runs
   * scenes side by side */
#pragma omp critical(vsph_poisson_fftw_planner)
  ps->plan = fftw_plan_many_r2r(2, dims, 1, in, embed, 1, 0, in, embed, 1, 0,
                                kinds, FFTW_ESTIMATE);
  if (!ps->plan) {
    vsph_status_report(VSPH_ELIB, __FILE__, __LINE__,
                       "FFTW could not plan a %zu x %zu sine transform", n, n);
    vsph_poisson_free(ps);
    return NULL;
  }
  /* Eigenvalues of (p_{k+1} - 2 p_k + p_{k-1}) on sin(pi (k+1)(m+1)/(n+1)):
   * 2 cos(pi (m+1)/(n+1)) - 2. */
  for (size_t m = 0; m < n; m++)
    ps->lam[m] = 2.0 * cos(VSPH_PI * (double)(m + 1) / (double)(n + 1)) - 2.0;
  return ps;
fail:
  vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                     "cannot allocate a %zu x %zu Poisson grid", n, n);
  vsph_poisson_free(ps);
  return NULL;
}

void vsph_poisson_free(struct vsph_poisson *ps) {
  if (!ps) return;
  if (ps->plan) {
#pragma omp critical(vsph_poisson_fftw_planner)
    fftw_destroy_plan(ps->plan);
  }
  fftw_free(ps->sol);
  free(ps->lam);
  free(ps);
}

double vsph_poisson_spacing(const struct vsph_poisson *ps) { return ps->h; }

double vsph_poisson_node(const struct vsph_poisson *ps, size_t i, size_t j) {
  return ps->sol[j * (ps->n + 2) + i];
}

int vsph_poisson_solve(struct vsph_poisson *ps, vsph_poisson_fn *f,
                       vsph_poisson_fn *g, void *ctx) {
  const size_t n = ps->n, m = n + 2;
  const double h = ps->h, lo = -0.5 * ps->side, ih2 = 1.0 / (h * h);
  double *S = ps->sol;
  /* Boundary ring, corners included (they enter the interpolation only). */
  for (size_t k = 0; k <= n + 1; k++) {
    const double t = lo + (double)k * h;
    S[k * m + 0] = g(lo, t, ctx);        /* west */
    S[k * m + (n + 1)] = g(-lo, t, ctx); /* east */
    S[0 * m + k] = g(t, lo, ctx);        /* south */
    S[(n + 1) * m + k] = g(t, -lo, ctx); /* north */
  }
  /* Right-hand side with the boundary values moved over. */
  for (size_t j = 1; j <= n; j++)
    for (size_t i = 1; i <= n; i++) {
      double r = f(lo + (double)i * h, lo + (double)j * h, ctx);
      if (i == 1) r -= S[j * m] * ih2;
      if (i == n) r -= S[j * m + n + 1] * ih2;
      if (j == 1) r -= S[i] * ih2;
      if (j == n) r -= S[(n + 1) * m + i] * ih2;
      if (!isfinite(r))
        VSPH_FAIL(VSPH_EINVAL, "non-finite Poisson data at node (%zu, %zu)", i,
                  j);
      S[j * m + i] = r; /* read above only on the ring */
    }
  /* Forward DST-I, divide by the eigenvalues, inverse (the same transform
   * scaled by 1/(2(n+1)) per dimension). */
  fftw_execute(ps->plan);
  const double norm = 1.0 / (4.0 * (double)(n + 1) * (double)(n + 1));
  for (size_t b = 0; b < n; b++)
    for (size_t a = 0; a < n; a++)
      S[(b + 1) * m + a + 1] *= norm * h * h / (ps->lam[a] + ps->lam[b]);
  fftw_execute(ps->plan);
  return VSPH_OK;
}

double vsph_poisson_interp(const struct vsph_poisson *ps, double x, double y) {
  const size_t m = ps->n + 2;
  const double lo = -0.5 * ps->side;
  double fx = (x - lo) / ps->h, fy = (y - lo) / ps->h;
  const double top = (double)(ps->n + 1);
  fx = fx < 0.0 ? 0.0 : (fx > top ? top : fx);
  fy = fy < 0.0 ? 0.0 : (fy > top ? top : fy);
  size_t i = (size_t)fx, j = (size_t)fy;
  if (i > ps->n) i = ps->n;
  if (j > ps->n) j = ps->n;
  const double tx = fx - (double)i, ty = fy - (double)j;
  const double *S = ps->sol;
  return (1 - tx) * (1 - ty) * S[j * m + i] + tx * (1 - ty) * S[j * m + i + 1] +
         (1 - tx) * ty * S[(j + 1) * m + i] + tx * ty * S[(j + 1) * m + i + 1];
}
