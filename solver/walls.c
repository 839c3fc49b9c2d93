/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "walls.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "particles.h"
#include "particles_internal.h"
#include "share_internal.h"
#include "walls_internal.h"

/* One nearest-row entry: coordinates, the tangential velocity relative to
 * the wall (3), the depth. */
#define BAND_STRIDE 7

static const char *const solid_names[] = {
    [VSPH_WALLS_GHOSTS] = "ghosts",
    [VSPH_WALLS_ADAMI] = "adami",
    [VSPH_WALLS_EVOLVING] = "evolving",
    [VSPH_WALLS_FIXED] = "fixed",
};
_Static_assert(sizeof solid_names / sizeof solid_names[0] ==
                   VSPH_WALLS_SOLID_COUNT,
               "wall-particle name table out of sync");

const char *vsph_walls_solid_name(int s) {
  return s >= 0 && s < VSPH_WALLS_SOLID_COUNT ? solid_names[s] : "unknown";
}

int vsph_walls_solid_resolve(const char *name, int *s) {
  if (!name || !s)
    VSPH_FAIL(VSPH_EINVAL, "vsph_walls_solid_resolve: a NULL argument");
  for (int k = VSPH_WALLS_ADAMI; k < VSPH_WALLS_SOLID_COUNT; k++)
    if (!strcmp(name, solid_names[k])) {
      *s = k;
      return VSPH_OK;
    }
  VSPH_FAIL(VSPH_EINVAL, "unknown wall particles '%s' (adami, evolving, fixed)",
            name);
}

static const char *const velocity_names[] = {
    [VSPH_WALLS_VEL_MIRROR] = "mirror",
    [VSPH_WALLS_VEL_LINEAR] = "linear",
};
_Static_assert(sizeof velocity_names / sizeof velocity_names[0] ==
                   VSPH_WALLS_VEL_COUNT,
               "wall-velocity name table out of sync");

const char *vsph_walls_velocity_name(int v) {
  return v >= 0 && v < VSPH_WALLS_VEL_COUNT ? velocity_names[v] : "unknown";
}

int vsph_walls_velocity_resolve(const char *name, int *v) {
  if (!name || !v)
    VSPH_FAIL(VSPH_EINVAL, "vsph_walls_velocity_resolve: a NULL argument");
  for (int k = 0; k < VSPH_WALLS_VEL_COUNT; k++)
    if (!strcmp(name, velocity_names[k])) {
      *v = k;
      return VSPH_OK;
    }
  VSPH_FAIL(VSPH_EINVAL, "unknown wall velocity '%s' (mirror, linear)", name);
}

int vsph_walls_add_periodic(struct vsph_walls *w, int axis, double lo,
                            double hi) {
  if (!w) VSPH_FAIL(VSPH_EINVAL, "vsph_walls_add_periodic: a NULL argument");
  if (w->n + 2 > VSPH_WALLS_MAX || !(hi > lo) || axis < 0 || axis > 2)
    VSPH_FAIL(VSPH_EINVAL, "cannot add a periodic axis %d over [%g, %g)", axis,
              lo, hi);
  for (int e = 0; e < 2; e++) {
    const int q = w->n++;
    w->axis[q] = axis;
    w->pos[q] = e ? hi : lo;
    w->side[q] = e ? -1 : +1;
    w->kind[q] = VSPH_WALLS_PERIODIC;
    w->uw[q][0] = w->uw[q][1] = w->uw[q][2] = 0.0;
  }
  return VSPH_OK;
}

double vsph_walls_period(const struct vsph_walls *w, int axis) {
  if (!w) return NAN;
  double lo = NAN, hi = NAN;
  for (int q = 0; q < w->n; q++)
    if (w->kind[q] == VSPH_WALLS_PERIODIC && w->axis[q] == axis)
      *(w->side[q] > 0 ? &lo : &hi) = w->pos[q];
  return isfinite(lo) && isfinite(hi) ? hi - lo : 0.0;
}

void vsph_walls_wrap(const struct vsph_walls *w, struct vsph_particles *p,
                     size_t n_fluid) {
  if (!w || !p) return;
  for (int q = 0; q < w->n; q++) {
    if (w->kind[q] != VSPH_WALLS_PERIODIC || w->side[q] < 0) continue;
    const int a = w->axis[q];
    const double lo = w->pos[q], L = vsph_walls_period(w, a);
    double *x = p->pos[a];
    for (size_t i = 0; i < p->n; i++) {
      if (p->id[i] >= n_fluid) continue;
      if (x[i] < lo) x[i] += L * ceil((lo - x[i]) / L);
      if (x[i] >= lo + L) x[i] -= L * floor((x[i] - lo) / L);
    }
  }
}

struct vsph_walls_ghosts *vsph_walls_ghosts_alloc(const struct vsph_walls *w,
                                                  size_t cap) {
  if (!w) return NULL;
  struct vsph_walls_ghosts *gh = calloc(1, sizeof *gh);
  const size_t c = cap ? cap : 1;
  const int linear = w->noslip && w->velocity == VSPH_WALLS_VEL_LINEAR;
  if (gh) {
    gh->cap = cap;
    gh->src = malloc(c * sizeof *gh->src);
    gh->mask = malloc(c * sizeof *gh->mask);
    /* each nearest-row particle has a ghost across its plane (band <=
     * reach): at most cap entries */
    if (linear) {
      gh->band = malloc(c * BAND_STRIDE * sizeof *gh->band);
      gh->bent = malloc(c * sizeof *gh->bent);
      /* at most as many bins as entries, one more bound per plane */
      gh->bfirst = malloc((c + VSPH_WALLS_MAX) * sizeof *gh->bfirst);
    }
  }
  if (!gh || !gh->src || !gh->mask ||
      (linear && (!gh->band || !gh->bent || !gh->bfirst))) {
    vsph_walls_ghosts_free(gh);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate %zu ghosts", cap);
    return NULL;
  }
  return gh;
}

void vsph_walls_ghosts_free(struct vsph_walls_ghosts *gh) {
  if (!gh) return;
  free(gh->src);
  free(gh->mask);
  free(gh->band);
  free(gh->bent);
  free(gh->bfirst);
  free(gh);
}

/* Distance of particle s from plane q (positive on the fluid side). */
static double depth(const struct vsph_walls *w, const struct vsph_particles *p,
                    size_t s, int q) {
  return w->side[q] * (p->pos[w->axis[q]][s] - w->pos[q]);
}

/* Entry band b's share of a fit at tangential distance r (m) from the
 * ghost: the sums of extrapolate. */
static void fit_add(const struct vsph_walls *w, const double *b, double r,
                    int dim, double num[3], double *den) {
  const double db = b[6];
  const double wt = (1.0 - r / w->window) * (1.0 - db / w->band);
  for (int k = 0; k < dim; k++) num[k] += wt * db * b[3 + k];
  *den += wt * db * db;
}

/* The bin of coordinate x along plane q's binned axis: in [0, nbin) for a
 * periodic axis (x reduced into one period), else possibly outside it. */
static double bin_of(const struct vsph_walls_ghosts *gh, int q, double x) {
  const double L = gh->bper[q];
  double u = x - gh->bx0[q];
  if (L > 0.0) {
    u -= L * floor(u / L);
    if (u >= L) u -= L;
    /* a rounding below 0 (u/L rounded up to a whole number): position 0,
     * which is next to the last bin on the circle */
    if (u < 0.0) u = 0.0;
  }
  return floor(u / gh->bwidth[q]);
}

/* Bin plane q's entries (after rows has listed them) along its first
 * tangential axis in bins at least the window wide; too few entries or
 * bins (or a non-finite coordinate) leave it unbinned. */
static void bin_plane(const struct vsph_walls *w, struct vsph_walls_ghosts *gh,
                      int dim, int q, size_t *nbins) {
  gh->nbin[q] = 0;
  gh->boff[q] = *nbins;
  const size_t ne = gh->nband[q];
  int t = 0;
  while (t == w->axis[q]) t++;
  if (t >= dim || ne < 8 || !(w->window > 0.0)) return;
  const double *b0 = gh->band + gh->bstart[q] * BAND_STRIDE;
  /* the bins at least the window wide, with a margin for rounding */
  const double wmin = w->window * (1.0 + 1e-9);
  double lo = INFINITY, hi = -INFINITY;
  for (size_t e = 0; e < ne; e++) {
    /* any non-finite tangential coordinate: the whole row, as before, so
     * that a NaN reaches every fit it reached */
    for (int k = 0; k < dim; k++)
      if (k != w->axis[q] && !isfinite(b0[e * BAND_STRIDE + k])) return;
    const double x = b0[e * BAND_STRIDE + t];
    lo = fmin(lo, x);
    hi = fmax(hi, x);
  }
  const double L = vsph_walls_period(w, t);
  const double span = L > 0.0 ? L : hi - lo;
  if (!isfinite(span)) return;
  const double nb_d = floor(span / wmin);
  size_t nb = nb_d < (double)ne ? (size_t)nb_d : ne;
  if (nb < 3) return; /* three bins would be the whole row */
  gh->baxis[q] = t;
  gh->bper[q] = L;
  gh->bx0[q] = L > 0.0 ? 0.0 : lo;
  gh->bwidth[q] = span / (double)nb;
  size_t *const first = gh->bfirst + *nbins;
  for (size_t k = 0; k <= nb; k++) first[k] = 0;
  for (size_t e = 0; e < ne; e++) { /* counts, then starts */
    const double bb = bin_of(gh, q, b0[e * BAND_STRIDE + t]);
    first[(bb < (double)nb ? (size_t)bb : nb - 1) + 1]++;
  }
  for (size_t k = 0; k < nb; k++) first[k + 1] += first[k];
  size_t *const ent = gh->bent + gh->bstart[q];
  for (size_t e = 0; e < ne; e++) { /* stable: ascending within a bin */
    const double bb = bin_of(gh, q, b0[e * BAND_STRIDE + t]);
    const size_t k = bb < (double)nb ? (size_t)bb : nb - 1;
    ent[first[k]++] = e;
  }
  for (size_t k = nb; k > 0; k--) first[k] = first[k - 1]; /* restore */
  first[0] = 0;
  gh->nbin[q] = nb;
  *nbins += nb + 1;
}

/* Linear extrapolation of ghost i (its position set) across plane q at
 * depth d behind it: the tangential velocity u_w - gamma d, gamma fitted
 * by hat-weighted least squares to the nearest row of plane q. Returns 0
 * (the caller mirrors) where no row particle lies within the window. */
static int extrapolate(const struct vsph_walls *w,
                       const struct vsph_walls_ghosts *gh,
                       const struct vsph_particles *p, size_t i, int q,
                       double d) {
  const int dim = p->dim, a = w->axis[q];
  double per[3] = {0, 0, 0};
  for (int k = 0; k < dim; k++)
    if (k != a) per[k] = vsph_walls_period(w, k);
  double num[3] = {0, 0, 0}, den = 0.0;
  const double *const b0 = gh->band + gh->bstart[q] * BAND_STRIDE;
  /* the entries to visit, ascending: three bins' (merged), or all */
  const size_t *lst[3] = {NULL, NULL, NULL};
  size_t len[3] = {0, 0, 0}, nl = 0, ne = gh->nband[q];
  /* the bins only for a ghost at a finite place (else the whole row) */
  int finite = gh->nbin[q] != 0;
  for (int k = 0; k < dim && finite; k++)
    if (k != a) finite = isfinite(p->pos[k][i]);
  if (finite) {
    const double xb = p->pos[gh->baxis[q]][i];
    const size_t nb = gh->nbin[q];
    const size_t *const first = gh->bfirst + gh->boff[q];
    const size_t *const ent = gh->bent + gh->bstart[q];
    const double bb = bin_of(gh, q, xb);
    for (int o = -1; o <= 1; o++) {
      double k = bb + o;
      if (gh->bper[q] > 0.0) /* circular: nb >= 3, so three distinct */
        k = k < 0.0 ? k + (double)nb : k >= (double)nb ? k - (double)nb : k;
      if (!(k >= 0.0 && k < (double)nb)) continue;
      const size_t kk = (size_t)k;
      lst[nl] = ent + first[kk];
      len[nl++] = first[kk + 1] - first[kk];
    }
    ne = len[0] + len[1] + len[2];
  }
  size_t at[3] = {0, 0, 0};
  for (size_t v = 0; v < ne; v++) {
    size_t e = v;
    if (nl) { /* the smallest head of the lists */
      int best = -1;
      for (int l = 0; l < (int)nl; l++)
        if (at[l] < len[l] && (best < 0 || lst[l][at[l]] < lst[best][at[best]]))
          best = l;
      e = lst[best][at[best]++];
    }
    const double *const b = b0 + e * BAND_STRIDE;
    double r2 = 0.0;
    for (int k = 0; k < dim; k++) {
      if (k == a) continue;
      double dx = b[k] - p->pos[k][i];
      if (per[k] > 0.0) dx -= per[k] * nearbyint(dx / per[k]);
      r2 += dx * dx;
    }
    const double r = sqrt(r2);
    if (r >= w->window) continue;
    fit_add(w, b, r, dim, num, &den);
  }
  if (!(den > 0.0)) return 0;
  for (int k = 0; k < dim; k++)
    if (k != a) p->vel[k][i] = w->uw[q][k] - num[k] / den * d;
  return 1;
}

/* Copy source s into ghost slot i, imaged across the planes in mask. */
static void image(const struct vsph_walls *w,
                  const struct vsph_walls_ghosts *gh, struct vsph_particles *p,
                  size_t s, size_t i, unsigned mask) {
  const int d = p->dim;
  int nmirror = 0, last = -1;
  double uw[3] = {0, 0, 0};
  for (int k = 0; k < d; k++) {
    p->pos[k][i] = p->pos[k][s];
    p->vel[k][i] = p->vel[k][s];
  }
  for (int q = 0; q < w->n; q++) {
    if (!(mask & (1u << q))) continue;
    const int a = w->axis[q];
    if (w->kind[q] == VSPH_WALLS_PERIODIC) {
      p->pos[a][i] += w->side[q] * vsph_walls_period(w, a);
      continue;
    }
    p->pos[a][i] = 2.0 * w->pos[q] - p->pos[a][i];
    if (!w->noslip) p->vel[a][i] = -p->vel[a][i]; /* normal reversed */
    for (int k = 0; k < d; k++) uw[k] += w->uw[q][k];
    nmirror++;
    last = q;
  }
  if (w->noslip && nmirror > 0) {
    const int lin = w->velocity == VSPH_WALLS_VEL_LINEAR && nmirror == 1;
    if (lin) p->vel[w->axis[last]][i] = -p->vel[w->axis[last]][s]; /* normal */
    if (!lin || !extrapolate(w, gh, p, i, last, depth(w, p, s, last)))
      for (int k = 0; k < d; k++)
        p->vel[k][i] = 2.0 * uw[k] / nmirror - p->vel[k][s];
  }
  double pr = w->c0 * w->c0 * (p->rho[s] - w->rho0);
  if (w->g != 0.0) pr += w->rho0 * w->g * (p->pos[d - 1][s] - p->pos[d - 1][i]);
  p->rho[i] = w->rho0 + pr / (w->c0 * w->c0);
  p->p[i] = pr; /* the linear law's; a run's own law recomputes it */
  if (p->e) p->e[i] = p->e[s];
  if (p->mat) p->mat[i] = p->mat[s];
  p->m[i] = p->m[s];
  p->vol[i] = p->m[i] / p->rho[i];
}

/* The two ends of each periodic axis as a bit mask. */
static void ends(const struct vsph_walls *w, unsigned pair[3]) {
  pair[0] = pair[1] = pair[2] = 0;
  for (int q = 0; q < w->n; q++)
    if (w->kind[q] == VSPH_WALLS_PERIODIC) pair[w->axis[q]] |= 1u << q;
}

/* An image across the planes of mask exists unless it holds both ends of
 * a periodic axis (their shifts cancel). */
static int image_ok(unsigned mask, const unsigned pair[3]) {
  for (int a = 0; a < 3; a++)
    if (pair[a] && (mask & pair[a]) == pair[a]) return 0;
  return 1;
}

/* The planes within reach of fluid particle s, as a bit mask. */
static unsigned near_planes(const struct vsph_walls *w,
                            const struct vsph_particles *p, size_t s,
                            double reach) {
  unsigned near = 0;
  for (int q = 0; q < w->n; q++) /* a solid set's walls are particles */
    if (depth(w, p, s, q) < reach &&
        !(w->solid && w->kind[q] == VSPH_WALLS_MIRROR))
      near |= 1u << q;
  return near;
}

/* The nearest row of each no-slip plane (linear extrapolation): serial, in
 * index order, so the fits are the same for any thread count. */
static void rows(const struct vsph_walls *w, const struct vsph_particles *p,
                 size_t n_fluid, struct vsph_walls_ghosts *gh) {
  size_t e = 0, nbins = 0;
  for (int q = 0; q < w->n; q++) {
    gh->bstart[q] = e;
    gh->nband[q] = 0;
    gh->nbin[q] = 0;
    if (w->kind[q] != VSPH_WALLS_MIRROR) continue;
    for (size_t i = 0; i < p->n && e < gh->cap; i++) {
      if (p->id[i] >= n_fluid) continue;
      const double d = depth(w, p, i, q);
      if (!(d > 0.0 && d < w->band)) continue;
      double *b = gh->band + e * BAND_STRIDE;
      for (int k = 0; k < 3; k++) {
        b[k] = k < p->dim ? p->pos[k][i] : 0.0;
        b[3 + k] =
            k < p->dim && k != w->axis[q] ? p->vel[k][i] - w->uw[q][k] : 0.0;
      }
      b[6] = d;
      e++;
      gh->nband[q]++;
    }
    bin_plane(w, gh, p->dim, q, &nbins);
  }
}

/* The sources of each parallel share of the ghosts' making: fixed runs of
 * the set, whatever the thread count, so every ghost lands in the same
 * slot (and below two runs, one thread: the same ghosts). */
#define GHOST_RUN 2048

/* The end of run @p r of @p n sources. */
static size_t run_end(size_t r, size_t n) {
  return (r + 1) * GHOST_RUN < n ? (r + 1) * GHOST_RUN : n;
}

/* The images fluid particles [i0, i1) of @p p make (ids below
 * @p n_fluid). */
static size_t count_images(const struct vsph_walls *w,
                           const struct vsph_particles *p, size_t n_fluid,
                           double reach, const unsigned pair[3], size_t i0,
                           size_t i1) {
  size_t n = 0;
  for (size_t i = i0; i < i1; i++) {
    if (p->id[i] >= n_fluid) continue;
    /* the non-empty subsets of the near planes that make an image */
    const unsigned near = near_planes(w, p, i, reach);
    for (unsigned mask = near; mask; mask = (mask - 1) & near)
      n += (size_t)image_ok(mask, pair);
  }
  return n;
}

size_t vsph_walls_count(const struct vsph_walls *w,
                        const struct vsph_particles *p, size_t n_fluid,
                        double reach) {
  if (!w || !p) return 0;
  unsigned pair[3];
  ends(w, pair);
  size_t n = 0; /* a sum of counts: the same for any thread count */
  if (p->n >= 2 * GHOST_RUN) {
#pragma omp parallel reduction(+ : n)
    {
      size_t i0, i1;
      vsph_share_even(p->n, &i0, &i1);
      n = count_images(w, p, n_fluid, reach, pair, i0, i1);
    }
  } else {
    n = count_images(w, p, n_fluid, reach, pair, 0, p->n);
  }
  return n;
}

/* A new ghost's arrays that image() does not set (its rates, transport
 * velocity and background pressure's acceleration; no evaluation reads a
 * ghost's rates, and the transport-velocity scheme, which reads its
 * neighbours' transport velocity, runs beside wall particles only:
 * vsph_integrate_alloc) set to 0, so that every array of the set is the
 * same whatever its slot held before. */
static void rates_cleared(struct vsph_particles *p, size_t i) {
  for (int k = 0; k < p->dim; k++) {
    p->acc[k][i] = 0.0;
    if (p->tvel[k]) p->tvel[k][i] = 0.0;
    if (p->bacc[k]) p->bacc[k][i] = 0.0;
  }
  p->drho[i] = 0.0;
  if (p->de) p->de[i] = 0.0;
}

/* The ghosts of the fluid particles [a, b) of @p p (the set compacted:
 * no ghost among them), made from index @p i0 of the set and ghost @p g0
 * on, in index order, each source's subsets of planes in mask order;
 * with @p make 0 only counted. Returns how many. */
static size_t images(const struct vsph_walls *w, struct vsph_particles *p,
                     size_t n_fluid, double reach, const unsigned pair[3],
                     size_t a, size_t b, struct vsph_walls_ghosts *gh,
                     size_t i0, size_t g0, int make) {
  const size_t base = n_fluid + gh->keep;
  size_t g = g0;
  for (size_t s = a; s < b; s++) { /* the fluid, among the kept walls */
    if (p->id[s] >= n_fluid) continue;
    const unsigned near = near_planes(w, p, s, reach);
    /* every non-empty subset of the near planes: images and corner images
     * (never both ends of one periodic axis: their shifts cancel) */
    for (unsigned mask = near; mask; mask = (mask - 1) & near) {
      if (!image_ok(mask, pair)) continue;
      if (make) {
        const size_t i = i0 + (g - g0);
        gh->src[g] = p->id[s];
        gh->mask[g] = mask;
        p->id[i] = base + g;
        image(w, gh, p, s, i, mask);
        rates_cleared(p, i);
      }
      g++;
    }
  }
  return g - g0;
}

/* Run @p r of the fluid among the set's first @p n particles: its ghosts
 * counted into at[r + 1] (@p make 0), or made from slot n + at[r] (make
 * 1, at[] summed). */
static void ghost_run(const struct vsph_walls *w, struct vsph_particles *p,
                      size_t n_fluid, double reach, const unsigned pair[3],
                      size_t n, struct vsph_walls_ghosts *gh, size_t *at,
                      size_t r, int make) {
  const size_t a = r * GHOST_RUN, b = run_end(r, n);
  if (make)
    images(w, p, n_fluid, reach, pair, a, b, gh, n + at[r], at[r], 1);
  else
    at[r + 1] = images(w, p, n_fluid, reach, pair, a, b, gh, 0, 0, 0);
}

/* Every run (ghost_run), in parallel from two runs of the set's size up;
 * below, with no region (its wake-up would cost more). */
static void ghost_runs(const struct vsph_walls *w, struct vsph_particles *p,
                       size_t n_fluid, double reach, const unsigned pair[3],
                       size_t n, struct vsph_walls_ghosts *gh, size_t *at,
                       int make) {
  const size_t nrun = (n + GHOST_RUN - 1) / GHOST_RUN;
  if (n >= 2 * GHOST_RUN) {
#pragma omp parallel for schedule(dynamic, 1)
    for (size_t r = 0; r < nrun; r++)
      ghost_run(w, p, n_fluid, reach, pair, n, gh, at, r, make);
  } else {
    for (size_t r = 0; r < nrun; r++)
      ghost_run(w, p, n_fluid, reach, pair, n, gh, at, r, make);
  }
}

/* The slots of the set's first @p n whose id is below @p base, in order,
 * into @p perm; returns how many. From VSPH_PARTICLES_MOVE_PARALLEL slots
 * the threads (at most VSPH_SHARE_MAX) take even shares: each counts its
 * own, then writes them from the sum of the counts before it (the same
 * list as one thread's). */
static size_t kept_in_order(const size_t *id, size_t n, size_t base,
                            size_t *perm) {
  if (n < VSPH_PARTICLES_MOVE_PARALLEL) { /* small: one thread */
    size_t m = 0;
    for (size_t i = 0; i < n; i++)
      if (id[i] < base) perm[m++] = i;
    return m;
  }
  size_t cnt[VSPH_SHARE_MAX], kept = 0;
  const int most = omp_get_max_threads();
#pragma omp parallel num_threads(most < VSPH_SHARE_MAX ? most : VSPH_SHARE_MAX)
  {
    const int t = omp_get_thread_num();
    size_t i0, i1;
    vsph_share_even(n, &i0, &i1);
    size_t c = 0;
    for (size_t i = i0; i < i1; i++) c += id[i] < base;
    cnt[t] = c;
#pragma omp barrier
    size_t at = 0;
    for (int u = 0; u < t; u++) at += cnt[u];
    for (size_t i = i0; i < i1; i++)
      if (id[i] < base) perm[at++] = i;
    if (t == omp_get_num_threads() - 1) kept = at;
  }
  return kept;
}

/* vsph_walls_generate, and with @p perm and @p spare
 * (vsph_walls_generate_moved) the compaction by a move of the set's own
 * arrays */
static int generate(const struct vsph_walls *w, struct vsph_particles *p,
                    size_t n_fluid, double reach, struct vsph_walls_ghosts *gh,
                    size_t *perm, void **spare) {
  /* Compact: keep the fluid (and the fixed wall particles) in their
   * current order, every field the set has with them (as
   * vsph_particles_permute moves them: the transport velocity set before
   * a step's cell list is read after it) */
  const size_t base = n_fluid + gh->keep;
  size_t n = 0;
  if (perm) { /* the kept in order, then moved by swaps */
    n = kept_in_order(p->id, p->n, base, perm);
    if (n < p->n) vsph_particles_move(p, perm, n, spare);
  } else {
    double *f[VSPH_PARTICLES_DOUBLES];
    const int nd = vsph_particles_doubles(p, f);
    for (size_t i = 0; i < p->n; i++) {
      if (p->id[i] >= base) continue;
      if (n != i) {
        for (int a = 0; a < nd; a++) f[a][n] = f[a][i];
        if (p->mat) p->mat[n] = p->mat[i];
        p->id[n] = p->id[i];
      }
      n++;
    }
  }
  p->n = n;
  gh->n = 0;
  if (gh->band) rows(w, p, n_fluid, gh);
  /* one image per end is enough only when the period exceeds the reach */
  for (int a = 0; a < p->dim; a++) {
    const double L = vsph_walls_period(w, a);
    if (L > 0.0 && !(L > reach))
      VSPH_FAIL(VSPH_EINVAL,
                "periodic length %g is not longer than the reach %g", L, reach);
  }
  unsigned pair[3];
  ends(w, pair);
  /* each run's ghosts counted, their first slots summed in order, then
   * made, the runs in parallel */
  const size_t nrun = (n + GHOST_RUN - 1) / GHOST_RUN;
  size_t *const at = malloc((nrun + 1) * sizeof *at);
  if (!at) VSPH_FAIL(VSPH_ENOMEM, "cannot plan the ghosts of %zu", n);
  ghost_runs(w, p, n_fluid, reach, pair, n, gh, at, 0);
  at[0] = 0;
  for (size_t r = 0; r < nrun; r++) at[r + 1] += at[r];
  const size_t ng = at[nrun];
  if (ng > gh->cap || n + ng > p->cap) {
    free(at);
    VSPH_FAIL(VSPH_ENOMEM, "ghost capacity %zu exceeded", gh->cap);
  }
  ghost_runs(w, p, n_fluid, reach, pair, n, gh, at, 1);
  free(at);
  p->n = n + ng;
  gh->n = ng;
  return VSPH_OK;
}

int vsph_walls_generate(const struct vsph_walls *w, struct vsph_particles *p,
                        size_t n_fluid, double reach,
                        struct vsph_walls_ghosts *gh) {
  if (!w || !p || !gh)
    VSPH_FAIL(VSPH_EINVAL, "vsph_walls_generate: a NULL argument");
  return generate(w, p, n_fluid, reach, gh, NULL, NULL);
}

int vsph_walls_generate_moved(const struct vsph_walls *w,
                              struct vsph_particles *p, size_t n_fluid,
                              double reach, struct vsph_walls_ghosts *gh,
                              size_t *perm, void **spare) {
  if (!w || !p || !gh || !perm || !spare)
    VSPH_FAIL(VSPH_EINVAL, "vsph_walls_generate_moved: a NULL argument");
  return generate(w, p, n_fluid, reach, gh, perm, spare);
}

void vsph_walls_update(const struct vsph_walls *w, struct vsph_particles *p,
                       size_t n_fluid, struct vsph_walls_ghosts *gh,
                       const size_t *where) {
  if (!w || !p || !gh || !where) return;
  if (gh->band) rows(w, p, n_fluid, gh);
  /* ghost g is id base + g: found by the map, not by a scan of every
   * slot; each thread refreshes the ghosts in its even share of the
   * slots, so that it writes no cache line another thread's ghosts are
   * in but at the shares' ends (a share of the ghosts instead cost the
   * wave's two threads half as much again: docs/performance.md). Every
   * thread reads the map entry of every ghost. A slot
   * that does not hold the ghost (a stale map) is left alone. */
  const size_t base = n_fluid + gh->keep;
#pragma omp parallel
  {
    size_t i0, i1;
    vsph_share_even(p->n, &i0, &i1);
    for (size_t g = 0; g < gh->n; g++) {
      const size_t i = where[base + g];
      if (i >= i0 && i < i1 && p->id[i] == base + g)
        image(w, gh, p, where[gh->src[g]], i, gh->mask[g]);
    }
  }
}

/* The box of a solid wall set: lo/hi per axis from its planes; 0 when an
 * axis of the first dim lacks either end. */
static int solid_box(const struct vsph_walls *w, int dim, double lo[3],
                     double hi[3], unsigned *periodic) {
  unsigned have = 0;
  *periodic = 0;
  for (int q = 0; q < w->n; q++) {
    if (w->axis[q] >= dim) continue;
    const int a = w->axis[q], up = w->side[q] > 0;
    /* a periodic axis bounds the box too: its wall particles run over the
     * period and a reach beyond (fixed walls only) */
    if (w->kind[q] == VSPH_WALLS_PERIODIC) {
      if (w->solid != VSPH_WALLS_FIXED) continue;
      *periodic |= 1u << a;
    }
    if (up)
      lo[a] = w->pos[q];
    else
      hi[a] = w->pos[q];
    have |= 1u << (2 * a + up);
  }
  return have == (1u << (2 * dim)) - 1u;
}

/* Lattice counts: n[a] cells across the box, l layers beyond it; bit a of
 * *periodic: axis a is periodic. */
static int solid_lattice(const struct vsph_walls *w, int dim, double dx,
                         double reach, double lo[3], long n[3], long *l,
                         unsigned *periodic) {
  double hi[3] = {0, 0, 0};
  lo[0] = lo[1] = lo[2] = 0.0;
  if (!solid_box(w, dim, lo, hi, periodic) || !(dx > 0.0)) return 0;
  for (int a = 0; a < 3; a++)
    n[a] = a < dim ? (long)nearbyint((hi[a] - lo[a]) / dx) : 1;
  *l = (long)ceil(reach / dx - 1e-9);
  return 1;
}

size_t vsph_walls_solid_count(const struct vsph_walls *w, int dim, double dx,
                              double reach) {
  if (!w) return 0;
  double lo[3];
  long n[3], l;
  unsigned per;
  if (!solid_lattice(w, dim, dx, reach, lo, n, &l, &per)) return 0;
  size_t all = 1, in = 1; /* in: the fluid's and its periodic images' */
  for (int a = 0; a < dim; a++) {
    all *= (size_t)(n[a] + 2 * l);
    in *= (size_t)(per >> a & 1 ? n[a] + 2 * l : n[a]);
  }
  return all - in;
}

int vsph_walls_solid_generate(const struct vsph_walls *w,
                              struct vsph_particles *p, size_t n_fluid,
                              double dx, double reach) {
  if (!w || !p)
    VSPH_FAIL(VSPH_EINVAL, "vsph_walls_solid_generate: a NULL argument");
  const int dim = p->dim;
  double lo[3];
  long n[3], l;
  unsigned per;
  if (!solid_lattice(w, dim, dx, reach, lo, n, &l, &per))
    VSPH_FAIL(VSPH_EINVAL, "solid walls need two planes on every axis");
  const size_t count = vsph_walls_solid_count(w, dim, dx, reach);
  if (p->n + count > p->cap)
    VSPH_FAIL(VSPH_ENOMEM, "room for %zu wall particles exceeded", count);
  const double vol = pow(dx, dim);
  const long kz = dim > 2 ? n[2] + l : 1, jy = dim > 1 ? n[1] + l : 1;
  size_t g = 0;
  for (long k = dim > 2 ? -l : 0; k < kz; k++)
    for (long j = dim > 1 ? -l : 0; j < jy; j++)
      for (long i = -l; i < n[0] + l; i++) {
        const long c[3] = {i, j, k};
        int inside = 1;
        for (int a = 0; a < dim; a++)
          inside &= (per >> a & 1) || (c[a] >= 0 && c[a] < n[a]);
        if (inside) continue;
        const size_t q = p->n++;
        for (int a = 0; a < dim; a++) {
          p->pos[a][q] = lo[a] + ((double)c[a] + 0.5) * dx;
          p->vel[a][q] = 0.0;
        }
        p->m[q] = w->rho0 * vol;
        p->rho[q] = w->rho0;
        p->vol[q] = vol;
        p->p[q] = 0.0;
        p->drho[q] = 0.0;
        p->id[q] = n_fluid + g++;
      }
  return VSPH_OK;
}

void vsph_walls_solid_velocity(const struct vsph_walls *w, int dim,
                               const double x[3], double u[3]) {
  if (!w || !x || !u) return;
  u[0] = u[1] = u[2] = 0.0;
  for (int q = 0; q < w->n; q++) {
    if (w->kind[q] != VSPH_WALLS_MIRROR) continue;
    const int a = w->axis[q];
    const int behind = w->side[q] > 0 ? x[a] < w->pos[q] : x[a] > w->pos[q];
    int moving = 0;
    for (int k = 0; k < dim; k++) moving |= w->uw[q][k] != 0.0;
    if (behind && moving) {
      for (int k = 0; k < dim; k++) u[k] = w->uw[q][k];
      return;
    }
  }
}

void vsph_walls_solid_extrapolate(const struct vsph_walls *w,
                                  struct vsph_particles *p, size_t n_fluid,
                                  struct vsph_walls_ghosts *gh) {
  if (!w || !p || !gh) return;
  rows(w, p, n_fluid, gh);
  const int dim = p->dim;
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] < n_fluid) continue;
    double x[3] = {0, 0, 0}, u[3];
    for (int a = 0; a < dim; a++) x[a] = p->pos[a][i];
    vsph_walls_solid_velocity(w, dim, x, u);
    int nbehind = 0, last = -1;
    for (int q = 0; q < w->n; q++)
      if (w->kind[q] == VSPH_WALLS_MIRROR && depth(w, p, i, q) < 0.0) {
        nbehind++;
        last = q;
      }
    for (int a = 0; a < dim; a++) p->vel[a][i] = u[a];
    /* behind one plane: the tangential components extrapolated, the
     * normal one the prescribed (the plane's velocity is tangential) */
    if (nbehind == 1) extrapolate(w, gh, p, i, last, -depth(w, p, i, last));
  }
}
