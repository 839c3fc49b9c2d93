#include "series.h"

#include <math.h>

double vsph_series_interp(const double *t, const double *y, size_t n,
                          double x) {
  if (n == 0 || x < t[0] || x > t[n - 1]) return (double)NAN;
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
  const double e2 = 2.0 * e[0][1] - e[0][0], e3 = 2.0 * e[1][1] - e[1][0];
  return e3 - eps[1] * (e2 - e3) / (eps[0] - eps[1]);
}

double vsph_series_decay_error(const double *E, const double *R, size_t n) {
  double err = 0.0;
  for (size_t k = 0; k < n; k++)
    if (isfinite(R[k])) err = fmax(err, fabs(E[k] / E[0] - R[k] / R[0]));
  return err;
}

double vsph_series_decay_error_table(const double *t, const double *E, size_t n,
                                     const double *tr, const double *Rr,
                                     size_t m) {
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
  for (size_t k = 1; k < m; k++) {
    const double d = vsph_series_interp(t, dE, n, tr[k]);
    if (!isfinite(d)) return tr[k]; /* past the run's end or stop */
    if (fabs(d - dR[k]) > threshold * fabs(dR[k])) return tr[k];
  }
  return (double)NAN;
}

double vsph_series_integral(const double *t, const double *y, size_t row) {
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
  for (size_t k = 0; k < n; k++)
    if (t[k] * scale >= from && e[k] >= level) return t[k] * scale;
  return (double)NAN;
}

double vsph_series_failure(const double *t, const double *e, size_t n,
                           double scale, double from, double level,
                           double t_stop, char *why) {
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
  if (n == 0) return (double)NAN;
  const double t0 = frac * t[n - 1];
  double s = 0.0;
  size_t m = 0;
  for (size_t k = 0; k < n; k++)
    if (t[k] >= t0) s += y[k], m++;
  return s / (double)m; /* m >= 1: the last row is in */
}

double vsph_series_tail_range(const double *t, const double *y, size_t n,
                              double frac) {
  if (n == 0) return (double)NAN;
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
