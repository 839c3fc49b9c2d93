/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The claims' figures over several runs or rows (measures.h). */
#include "measures.h"

#include <math.h>

void vsph_measures_extent(const double *x, size_t n, double *lo, double *hi,
                          size_t *count) {
  double l = INFINITY, h = -INFINITY;
  size_t m = 0;
  for (size_t k = 0; k < n; k++)
    if (isfinite(x[k])) {
      l = fmin(l, x[k]);
      h = fmax(h, x[k]);
      m++;
    }
  if (lo) *lo = l;
  if (hi) *hi = h;
  if (count) *count = m;
}

double vsph_measures_largest(const double *x, size_t n, double from) {
  for (size_t k = 0; k < n; k++) from = fmax(from, x[k]);
  return from;
}

double vsph_measures_smallest(const double *x, size_t n, double from) {
  for (size_t k = 0; k < n; k++) from = fmin(from, x[k]);
  return from;
}

int vsph_measures_steps(const double *x, size_t n, double *d) {
  int all = 1;
  for (size_t k = 0; k < n; k++) all &= isfinite(x[k]) != 0;
  for (size_t k = 0; k + 1 < n; k++)
    d[k] = all ? fabs(x[k + 1] - x[k]) : (double)NAN;
  return all;
}

int vsph_measures_arg(const double *x, int n, int sign) {
  if (n <= 0) return -1;
  int best = 0;
  for (int k = 1; k < n; k++)
    if (sign > 0 ? x[k] > x[best] : x[k] < x[best]) best = k;
  return best;
}

double vsph_measures_max_factor(const double *a, const double *b, size_t n) {
  double far = 1.0;
  for (size_t k = 0; k < n; k++) {
    if (!(a[k] > 0 && b[k] > 0 && isfinite(a[k]) && isfinite(b[k])))
      return INFINITY;
    const double q = a[k] / b[k];
    far = fmax(far, fmax(q, 1.0 / q));
  }
  return far;
}

int vsph_measures_sign_changes(const double *f, const int *use, size_t n,
                               double floor) {
  if (isnan(floor)) return -1; /* no floor measured: no sign read */
  int last = 0, changes = 0;
  for (size_t k = 0; k < n; k++) {
    if (!use[k] || !(fabs(f[k]) >= floor) || f[k] == 0.0) continue;
    const int s = f[k] > 0 ? 1 : -1;
    changes += last && s != last;
    last = s;
  }
  return changes;
}

void vsph_measures_closest(const double *u, const double *swing, const int *ok,
                           int n, struct vsph_measures_closest *out) {
  int best = -1;
  double sw = 0.0, next = INFINITY;
  for (int f = 0; f < n; f++) {
    if (!ok[f] || isnan(u[f])) continue; /* an error not measured: out */
    sw = isnan(swing[f]) || isnan(sw) ? (double)NAN : fmax(sw, swing[f]);
    if (best < 0 || u[f] < u[best]) best = f;
  }
  for (int f = 0; f < n; f++)
    if (f != best && ok[f] && !isnan(u[f])) next = fmin(next, u[f]);
  out->best = best;
  out->next = next;
  out->gap = best >= 0 ? next - u[best] : (double)NAN;
  out->swing = sw;
}

int vsph_measures_map(const double *tf, const double *re, const int *robust,
                      int nf, int nre, double cap,
                      struct vsph_measures_map *out) {
  if (nf < 0 || nf > VSPH_MEASURES_MAP_MAXF || nre < 0) return -1;
  *out = (struct vsph_measures_map){
      .any = INFINITY, .who = -1, .first = INFINITY, .held = 0.0};
  for (int f = 0; f < nf; f++)
    for (int q = 0; q < nre; q++) {
      const double t = tf[f * nre + q];
      /* a time not measured: the score too (fmin would pass it over) */
      out->score[f] += isnan(t) ? t : fmin(t, cap);
      if (robust[f] && isfinite(t)) out->first = fmin(out->first, re[q]);
      if (isfinite(t) && re[q] < out->any) out->any = re[q], out->who = f;
    }
  for (int q = 0; q < nre; q++) { /* the largest Re all robust forms hold */
    int all = 1; /* held: +inf; a time not measured holds nothing */
    for (int f = 0; f < nf; f++)
      if (robust[f]) all &= isinf(tf[f * nre + q]) && tf[f * nre + q] > 0;
    if (all) out->held = fmax(out->held, re[q]);
  }
  return 0;
}

/* Sound speed @p a's row of the sweep into @p w. */
static void sweep_row(const struct vsph_measures_sweep_in *in, int a,
                      struct vsph_measures_sweep *w) {
  const int nd = in->nd;
  const char *o = in->out[a];
  const double *e = in->err[a];
  int same = 1, all_r = 1, all_e = 1;
  double lo = INFINITY, hi = -INFINITY;
  for (int b = 0; b < nd; b++) {
    w->ntot++;
    w->nbad += o[b] != 'r';
    same &= o[b] == o[0];
    all_r &= o[b] == 'r';
    all_e &= isfinite(e[b]) != 0;
    if (isfinite(e[b])) lo = fmin(lo, e[b]), hi = fmax(hi, e[b]);
  }
  w->open |= all_r && !all_e; /* a change not measured: acc and rise NaN */
  w->out[a] = same ? o[0] : 'm';
  if (!same && w->mixed < 0) w->mixed = a;
  if (all_r && lo > 0 && hi >= lo && !((hi - lo) / lo <= w->acc))
    w->acc = (hi - lo) / lo;
  for (int b = 1; b < nd && all_r; b++) { /* a ratio not measured: NaN */
    const double q = e[b] / e[b - 1];
    w->rise = isnan(q) || isnan(w->rise) ? (double)NAN : fmax(w->rise, q);
  }
  /* a smaller dt helps: a physical run below a non-physical one, or (the
   * claim's rule on lag) a stop delayed */
  int turns = 0;
  for (int b = 1; b < nd; b++) turns |= o[b] == 'r' && o[b - 1] != 'r';
  if (turns && w->turn < 0) w->turn = a;
  w->lag[a] = (double)NAN;
  if (same && o[0] == 's' && nd > 1) {
    double other = 0.0; /* the larger dts' latest stop; NaN if one is not */
    for (int b = 0; b + 1 < nd; b++)
      other =
          isnan(in->t_stop[a][b]) ? (double)NAN : fmax(other, in->t_stop[a][b]);
    w->lag[a] = other > 0.0 ? in->t_stop[a][nd - 1] / other : (double)NAN;
  }
  const double z = in->zig[a];
  if (o[nd - 1] == 'r' && isfinite(z)) {
    if (w->alo < 0 || z < w->zlo) w->zlo = z, w->alo = a;
    if (w->ahi < 0 || z > w->zhi) w->zhi = z, w->ahi = a;
  }
}

int vsph_measures_sweep(const struct vsph_measures_sweep_in *in,
                        struct vsph_measures_sweep *w) {
  if (in->nc < 0 || in->nc > VSPH_MEASURES_SWEEP_MAXC || in->nd < 1 ||
      in->nd > VSPH_MEASURES_SWEEP_MAXD)
    return -1;
  *w = (struct vsph_measures_sweep){.mixed = -1,
                                    .acc = (double)NAN,
                                    .rise = -(double)INFINITY,
                                    .turn = -1,
                                    .zlo = (double)NAN,
                                    .zhi = (double)NAN,
                                    .alo = -1,
                                    .ahi = -1};
  for (int a = 0; a < in->nc; a++) sweep_row(in, a, w);
  if (w->open) w->acc = (double)NAN;
  if (!isfinite(w->acc) || in->nd < 2)
    w->rise = (double)NAN; /* no change, no fall */
  return 0;
}

void vsph_measures_ratios(const struct vsph_series_ratio *hr, const int *group,
                          size_t n, struct vsph_measures_ratios *out) {
  *out = (struct vsph_measures_ratios){.peak = -INFINITY,
                                       .lo = INFINITY,
                                       .hi = -INFINITY,
                                       .t_lo = INFINITY,
                                       .t_hi = -INFINITY};
  for (size_t k = 0; k < n; k++) {
    const double p = hr[k].peak;
    out->peak = isnan(p) || isnan(out->peak) ? (double)NAN : fmax(out->peak, p);
    if (!hr[k].seen) continue;
    out->measured++;
    out->under += hr[k].below != 0;
    for (int g = 0; g < VSPH_MEASURES_GROUPS; g++)
      out->seen_in[g] += (group[k] >> g) & 1;
    out->t_lo = fmin(out->t_lo, hr[k].t_last);
    out->t_hi = fmax(out->t_hi, hr[k].t_last);
    if (isfinite(hr[k].last)) {
      out->lo = fmin(out->lo, hr[k].last);
      out->hi = fmax(out->hi, hr[k].last);
    }
  }
}
