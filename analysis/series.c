/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "series.h"

#include <math.h>
#include <stdlib.h>

#include "../common/status.h"
#include "scaling.h"

double vsph_series_interp(const double *t, const double *y, size_t n,
                          double x) {
  if (n == 0 || !t || !y || x < t[0] || x > t[n - 1]) return (double)NAN;
  size_t a = 0, b = n - 1;
  while (b - a > 1) {
    const size_t m = (a + b) / 2;
    if (t[m] <= x)
      a = m;
    else
      b = m;
  }
  if (t[b] == t[a]) return y[a];
  return y[a] + (y[b] - y[a]) * (x - t[a]) / (t[b] - t[a]);
}

double vsph_series_extrapolate(double e[2][2], const double eps[2]) {
  if (!e || !eps) return (double)NAN;
  const double e2 = 2.0 * e[0][1] - e[0][0], e3 = 2.0 * e[1][1] - e[1][0];
  return e3 - eps[1] * (e2 - e3) / (eps[0] - eps[1]);
}

double vsph_series_decay_error(const double *E, const double *R, size_t n) {
  if (n && (!E || !R)) return (double)NAN;
  double err = 0.0;
  for (size_t k = 0; k < n; k++)
    if (isfinite(R[k])) err = fmax(err, fabs(E[k] / E[0] - R[k] / R[0]));
  return err;
}

double vsph_series_decay_error_table(const double *t, const double *E, size_t n,
                                     const double *tr, const double *Rr,
                                     size_t m) {
  if ((n && (!t || !E)) || (m && (!tr || !Rr))) return (double)NAN;
  if (n == 0) return 0.0;
  const double R0 = vsph_series_interp(tr, Rr, m, t[0]);
  double err = 0.0;
  for (size_t k = 0; k < n; k++) {
    const double R = vsph_series_interp(tr, Rr, m, t[k]);
    if (isfinite(R)) err = fmax(err, fabs(E[k] / E[0] - R / R0));
  }
  return err;
}

double vsph_series_onset(const double *t, const double *dE, size_t n,
                         const double *tr, const double *dR, size_t m,
                         double threshold) {
  if ((n && (!t || !dE)) || (m > 1 && (!tr || !dR))) return (double)NAN;
  for (size_t k = 1; k < m; k++) {
    const double d = vsph_series_interp(t, dE, n, tr[k]);
    if (!isfinite(d)) return tr[k]; /* past the run's end or stop */
    if (fabs(d - dR[k]) > threshold * fabs(dR[k])) return tr[k];
  }
  return (double)NAN;
}

double vsph_series_integral(const double *t, const double *y, size_t row) {
  if (row && (!t || !y)) return (double)NAN;
  double s = 0.0;
  for (size_t k = 1; k <= row; k++)
    s += 0.5 * (y[k] + y[k - 1]) * (t[k] - t[k - 1]);
  return s;
}

double vsph_series_loss_ratio(double lost, double E0, double R0, double R) {
  const double lost_ref = 1.0 - R / R0;
  return lost_ref != 0.0 ? (lost / E0) / lost_ref : (double)NAN;
}

double vsph_series_first_reach(const double *t, const double *e, size_t n,
                               double scale, double from, double level) {
  if (n && (!t || !e)) return (double)NAN;
  for (size_t k = 0; k < n; k++)
    if (t[k] * scale >= from && e[k] >= level) return t[k] * scale;
  return (double)NAN;
}

double vsph_series_failure(const double *t, const double *e, size_t n,
                           double scale, double from, double level,
                           double t_stop, char *why) {
  char none;
  if (!why) why = &none;
  if (n && !t) {
    *why = ' ';
    return (double)NAN;
  }
  const double te =
      e ? vsph_series_first_reach(t, e, n, scale, from, level) : (double)NAN;
  if (!isnan(te)) {
    *why = 'e';
    return te;
  }
  if (!isnan(t_stop)) {
    *why = 'p';
    return t_stop * scale;
  }
  *why = ' ';
  return (double)INFINITY;
}

double vsph_series_tail_mean(const double *t, const double *y, size_t n,
                             double frac) {
  if (n == 0 || !t || !y) return (double)NAN;
  const double t0 = frac * t[n - 1];
  double s = 0.0;
  size_t m = 0;
  for (size_t k = 0; k < n; k++)
    if (t[k] >= t0) s += y[k], m++;
  return s / (double)m; /* m >= 1: the last row is in */
}

double vsph_series_tail_range(const double *t, const double *y, size_t n,
                              double frac) {
  if (n == 0 || !t || !y) return (double)NAN;
  const double t0 = frac * t[n - 1];
  double lo = INFINITY, hi = -INFINITY;
  for (size_t k = 0; k < n; k++)
    if (t[k] >= t0) lo = fmin(lo, y[k]), hi = fmax(hi, y[k]);
  return hi - lo; /* the last row is in */
}

void vsph_series_plateau(const double *t, const double *E, const double *R,
                         const double *v, size_t n, double scale, double lo,
                         double hi, double *work, size_t cap, double *spread,
                         double *median) {
  if (!spread || !median) return;
  if ((n && (!t || !E || !R || !v)) || (cap && !work)) {
    *spread = *median = (double)NAN;
    return;
  }
  double qlo = INFINITY, qhi = -INFINITY;
  size_t nv = 0;
  for (size_t k = 0; k < n; k++) {
    const double ts = t[k] * scale;
    if (ts >= lo && ts <= hi && R[k] > 0.0) {
      const double q = E[k] / R[k];
      qlo = fmin(qlo, q);
      qhi = fmax(qhi, q);
      if (nv < cap) work[nv++] = v[k];
    }
  }
  /* insertion sort: a few hundred values */
  for (size_t a = 1; a < nv; a++)
    for (size_t b = a; b > 0 && work[b - 1] > work[b]; b--) {
      const double w = work[b];
      work[b] = work[b - 1];
      work[b - 1] = w;
    }
  *median = nv ? work[nv / 2] : (double)NAN;
  *spread = nv ? (qhi - qlo) / (0.5 * (qhi + qlo)) : (double)NAN;
}

int vsph_series_cfl_pick(const double *err, const int *ok, size_t n, int ncfl,
                         double fraction) {
  if (n && ncfl > 1 && (!err || !ok)) return -1;
  int best = 0;
  for (int c = 1; c < ncfl; c++) {
    int fine = 1;
    for (size_t r = 0; r < n; r++) {
      const double *e = err + r * (size_t)ncfl;
      const int *s = ok + r * (size_t)ncfl;
      if (s[c] && s[0]) fine &= fabs(e[c] - e[0]) <= fraction * e[0];
    }
    if (!fine) break; /* every smaller CFL must be fine too */
    best = c;
  }
  return best;
}

double vsph_series_interp_cubic(const double *t, const double *y, size_t n,
                                double x) {
  if (n < 4 || !t || !y) return vsph_series_interp(t, y, n, x);
  if (x < t[0] || x > t[n - 1]) return (double)NAN;
  size_t a = 0, b = n - 1; /* t[a] <= x <= t[b], b = a + 1 */
  while (b - a > 1) {
    const size_t m = (a + b) / 2;
    if (t[m] <= x)
      a = m;
    else
      b = m;
  }
  const size_t s = a == 0 ? 0 : a + 2 >= n ? n - 4 : a - 1;
  double v = 0.0;
  for (size_t i = s; i < s + 4; i++) {
    double l = 1.0;
    for (size_t j = s; j < s + 4; j++) {
      if (j == i) continue;
      if (!(t[i] != t[j])) return vsph_series_interp(t, y, n, x); /* repeat */
      l *= (x - t[j]) / (t[i] - t[j]);
    }
    v += l * y[i];
  }
  return v;
}

/* r_f^p (r_c^p - 1)/(r_f^p - 1), continuous through p = 0 */
static double order_ratio(double p, double lc, double lf) {
  if (p == 0.0) return lc / lf;
  return exp(p * lf) * expm1(p * lc) / expm1(p * lf);
}

double vsph_series_order(double d_c, double d_f, double r_c, double r_f) {
  if (!(d_c > 0.0 && d_f > 0.0 && isfinite(d_c) && isfinite(d_f) && r_c > 1.0 &&
        r_f > 1.0 && isfinite(r_c) && isfinite(r_f)))
    return (double)NAN;
  const double q = d_c / d_f, lc = log(r_c), lf = log(r_f);
  if (r_c == r_f) { /* the usual ladder: the closed form */
    const double p = log(q) / lc;
    return fabs(p) <= 20.0 ? p : (double)NAN;
  }
  double lo = -20.0, hi = 20.0; /* the ratio rises with p */
  if (!(order_ratio(lo, lc, lf) <= q && q <= order_ratio(hi, lc, lf)))
    return (double)NAN;
  for (int it = 0; it < 200 && hi - lo > 1e-13; it++) {
    const double m = 0.5 * (lo + hi);
    if (order_ratio(m, lc, lf) < q)
      lo = m;
    else
      hi = m;
  }
  return 0.5 * (lo + hi);
}

/* The leading rows of a rung whose time and value are finite. */
static size_t finite_rows(const struct vsph_series_rung *r) {
  size_t n = 0;
  if (!r->t || !r->E) return 0;
  while (n < r->n && isfinite(r->t[n]) && isfinite(r->E[n])) n++;
  return n;
}

int vsph_series_selfconv(const struct vsph_series_rung *rung, size_t nrung,
                         struct vsph_series_selfconv *out) {
  if (!rung || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_series_selfconv: a NULL argument");
  if (nrung < 2 || nrung > VSPH_SERIES_RUNGS_MAX)
    VSPH_FAIL(VSPH_EINVAL, "a ladder of %zu rungs (2 to %d)", nrung,
              VSPH_SERIES_RUNGS_MAX);
  size_t nf[VSPH_SERIES_RUNGS_MAX];
  double span = INFINITY, longest = -INFINITY;
  for (size_t k = 0; k < nrung; k++) {
    nf[k] = finite_rows(&rung[k]);
    if (nf[k] == 0 || rung[k].E[0] == 0.0)
      VSPH_FAIL(VSPH_EINVAL, "rung %zu has no finite first row, or E(0) = 0",
                k + 1);
    if (!(rung[k].h > 0.0) || (k > 0 && !(rung[k].h < rung[k - 1].h)))
      VSPH_FAIL(VSPH_EINVAL, "rung %zu: the spacing must fall, coarse first",
                k + 1);
    const double end = rung[k].t[nf[k] - 1];
    span = fmin(span, end);
    longest = fmax(longest, end);
  }
  out->nrung = nrung;
  out->span = span;
  out->partial = span < longest - 1e-9 * fabs(longest);
  /* every pair on one set of times, the finest rung's rows in the span:
   * the differences then differ only by the rungs, not by where they
   * were sampled (both rungs of a pair by the cubic, the finest itself) */
  const struct vsph_series_rung *fin = &rung[nrung - 1];
  for (size_t k = 0; k + 1 < nrung; k++) {
    const struct vsph_series_rung *c = &rung[k], *f = &rung[k + 1];
    double mx = NAN, sq = 0.0, t0 = NAN, tp = NAN, dp = NAN;
    /* the span's end within the tolerance partial allows, so a last row
     * that ends a hair past it (a run's end at t_end (1 - 1e-12)) is in */
    const double tend = span + 1e-9 * fabs(span);
    for (size_t i = 0; i < nf[nrung - 1] && fin->t[i] <= tend; i++) {
      const double x = fmin(fin->t[i], span);
      const double ec = vsph_series_interp_cubic(c->t, c->E, nf[k], x);
      const double ef =
          k + 2 == nrung ? fin->E[i]
                         : vsph_series_interp_cubic(f->t, f->E, nf[k + 1], x);
      if (!isfinite(ec) || !isfinite(ef)) continue; /* before a first row */
      const double d = ef / f->E[0] - ec / c->E[0];
      mx = isnan(mx) ? fabs(d) : fmax(mx, fabs(d));
      if (isnan(t0))
        t0 = x;
      else
        sq += 0.5 * (d * d + dp * dp) * (x - tp);
      tp = x;
      dp = d;
    }
    out->dmax[k] = mx; /* NaN where the rungs share no row */
    out->drms[k] = tp > t0 ? sqrt(sq / (tp - t0)) : fabs(dp);
  }
  out->order_max = out->order_rms = out->remainder = (double)NAN;
  if (nrung >= 3) {
    const size_t k = nrung - 3;
    const double rc = rung[k].h / rung[k + 1].h;
    const double rf = rung[k + 1].h / rung[k + 2].h;
    out->order_max = vsph_series_order(out->dmax[k], out->dmax[k + 1], rc, rf);
    out->order_rms = vsph_series_order(out->drms[k], out->drms[k + 1], rc, rf);
    if (out->order_max > 0.0)
      out->remainder = out->dmax[k + 1] / expm1(out->order_max * log(rf));
  }
  return VSPH_OK;
}

double vsph_series_slope_where(const double *x, const double *y, const int *ok,
                               size_t n, size_t *ns) {
  size_t m = 0;
  if (n && (!x || !y || !ok)) {
    if (ns) *ns = 0;
    return (double)NAN;
  }
  double *sx = malloc((n ? n : 1) * sizeof *sx),
         *sy = malloc((n ? n : 1) * sizeof *sy);
  double slope = NAN;
  if (sx && sy) {
    for (size_t k = 0; k < n; k++)
      if (ok[k]) sx[m] = x[k], sy[m++] = y[k];
    if (m >= 2) slope = vsph_scaling_slope(sx, sy, m);
  }
  free(sx);
  free(sy);
  if (ns) *ns = m;
  return slope;
}

double vsph_series_log_between(double x, double a, double b) {
  if (!(x > 0.0 && a > 0.0 && b > 0.0) || !isfinite(x) || !isfinite(a) ||
      !isfinite(b) || a == b)
    return NAN;
  return fabs(log(x / a)) / fabs(log(b / a));
}

int vsph_series_ratio_history(const double *t, const double *y, size_t n,
                              const double *tr, const double *yr, size_t nr,
                              double t0, double t1, double edge,
                              struct vsph_series_ratio *out) {
  if (!t || !y || !tr || !yr || !out || n == 0 || !(t0 <= t1))
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_series_ratio_history: no history, or a "
              "window that ends before it starts");
  out->seen = 0;
  out->below = 1;
  out->peak = -INFINITY;
  for (size_t i = 0; i < n; i++) {
    if (t[i] < t0 || t[i] > t1) continue;
    const double x = y[i] / vsph_series_interp(tr, yr, nr, t[i]);
    out->seen = 1;
    out->below &= x < edge;
    out->peak = isnan(x) || isnan(out->peak) ? (double)NAN : fmax(out->peak, x);
  }
  out->t_last = fmin(t[n - 1], t1);
  out->last = vsph_series_interp(t, y, n, out->t_last) /
              vsph_series_interp(tr, yr, nr, out->t_last);
  return VSPH_OK;
}
