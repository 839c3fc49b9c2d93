/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_ANALYSIS_SERIES_H
#define VSPH_ANALYSIS_SERIES_H

#include <stddef.h>

#include "../common/api.h"

/** @file series.h
 *  @brief Measures of a run's energy series, on plain arrays (the columns
 *  of its energy.csv): interpolation, the decay error against a
 *  reference, the onset of a departure from it, the energy lost against
 *  the reference's loss, the trapezoid integral of a rate, and the
 *  extrapolation in h and h/dx that the stretching square's reference
 *  takes (docs/theory.md section 6). The report's parts read runs and call
 *  these; tests/check_series.c holds each to an independent computation.
 *  Also the self-convergence of a resolution ladder (successive rungs
 *  against each other, vsph_series_selfconv). No I/O. A NULL array
 *  where rows are to be read is refused: NaN (a measure), -1
 *  (vsph_series_cfl_pick), VSPH_EINVAL (vsph_series_selfconv, reported);
 *  vsph_series_plateau then gives NaN for both, and does nothing
 *  without its outputs. */

/** @brief y at @p x by linear interpolation in the table (t[k], y[k]),
 *  t ascending (repeated values allowed); NaN outside [t[0], t[n-1]] or
 *  for n = 0. */
VSPH_API double vsph_series_interp(const double *t, const double *y, size_t n,
                                   double x);

/** @brief The extrapolation to h -> 0 and then to the lattice error
 *  eps -> 0 of four values e[r][m]: two h/dx values r (lattice errors
 *  eps[r]), each at two resolutions m, the second twice the first. Per
 *  r, Richardson for first order, E_r = 2 e[r][1] - e[r][0]; then linear
 *  in eps through (eps[0], E_0) and (eps[1], E_1), at eps = 0. @p e is
 *  read only (a C array of arrays cannot be passed as const). */
VSPH_API double vsph_series_extrapolate(double e[2][2], const double eps[2]);

/** @brief The decay error max_k |E_k/E_0 - R_k/R_0| of a series E against
 *  a reference R taken at the same times, each normalised by its own
 *  first value (a weakly compressible start carries an O(Ma^2) offset of
 *  E_0 that no resolution removes). Rows where the reference is not
 *  finite (past its table) are left out; so is a row whose term is NaN
 *  (fmax drops it: a NaN of the run's is not seen here, the run's status
 *  says it stopped); 0 when none is left. */
VSPH_API double vsph_series_decay_error(const double *E, const double *R,
                                        size_t n);

/** @brief The same against a reference given as a table (tr, Rr) of m
 *  points, interpolated linearly at the run's times t (rows past the
 *  table are left out). */
VSPH_API double vsph_series_decay_error_table(const double *t, const double *E,
                                              size_t n, const double *tr,
                                              const double *Rr, size_t m);

/** @brief When a run's rate dE/dt (table t, dE of n rows) first departs
 *  from a reference rate (table tr, dR of m points) by more than
 *  @p threshold of it, judged at the reference's points tr[1..m-1]: the
 *  first such tr[k], or the first one past the run's end or stop (where
 *  the run's rate is not finite); NaN when it never departs. */
VSPH_API double vsph_series_onset(const double *t, const double *dE, size_t n,
                                  const double *tr, const double *dR, size_t m,
                                  double threshold);

/** @brief The integral of y over [t[0], t[row]] by the trapezoid rule. */
VSPH_API double vsph_series_integral(const double *t, const double *y,
                                     size_t row);

/** @brief Energy @p lost over the reference's share lost: (lost/E0)
 *  against 1 - R/R0 (each normalised by its own initial energy); NaN
 *  where the reference has lost nothing (its first row). */
VSPH_API double vsph_series_loss_ratio(double lost, double E0, double R0,
                                       double R);

/** @brief The first scaled time scale t[k] >= @p from at which e[k]
 *  reaches @p level (a failure criterion, as Basa et al.'s eq. (38) error
 *  at 12 %); NaN when none does. */
VSPH_API double vsph_series_first_reach(const double *t, const double *e,
                                        size_t n, double scale, double from,
                                        double level);

/** @brief A long run's failure time, Basa et al.'s way: the first scaled
 *  time at or past @p from at which the error e reaches @p level
 *  (vsph_series_first_reach; *why = 'e'), else the scaled time
 *  @p t_stop * scale at which the solver stopped the run as unstable
 *  (*why = 'p'; @p t_stop NaN for a run that finished), else infinity
 *  (*why = ' '). A NULL @p e (no error column) never reaches; @p why
 *  may be NULL. */
VSPH_API double vsph_series_failure(const double *t, const double *e, size_t n,
                                    double scale, double from, double level,
                                    double t_stop, char *why);

/** @brief The mean of y over the rows with t[k] >= @p frac t[n-1] (the
 *  last 1 - frac of the run: a steady state's value with its row noise
 *  averaged); NaN for n = 0. */
VSPH_API double vsph_series_tail_mean(const double *t, const double *y,
                                      size_t n, double frac);

/** @brief The spread max - min of y over the same rows as
 *  vsph_series_tail_mean (t[k] >= @p frac t[n-1]): the swing of a steady
 *  state's value over its averaging window; NaN for n = 0. */
VSPH_API double vsph_series_tail_range(const double *t, const double *y,
                                       size_t n, double frac);

/** @brief Over the rows whose scaled time scale t[k] lies in [lo, hi] and
 *  whose R[k] > 0: the spread (max - min)/((max + min)/2) of E[k]/R[k]
 *  into *spread, and the median of v[k] over the first @p cap of those
 *  rows (the upper one of an even count; @p work holds @p cap doubles)
 *  into *median; NaN for none. */
VSPH_API void vsph_series_plateau(const double *t, const double *E,
                                  const double *R, const double *v, size_t n,
                                  double scale, double lo, double hi,
                                  double *work, size_t cap, double *spread,
                                  double *median);

/** @brief The time step's rule: of @p n rows of @p ncfl errors (@p err) and
 *  stability flags (@p ok) at increasing CFL numbers, the first the
 *  smallest CFL, the largest index c such that every row stable at c and
 *  at the first has |err_c - err_0| <= @p fraction err_0, and so does every
 *  smaller index (0 when none). */
VSPH_API int vsph_series_cfl_pick(const double *err, const int *ok, size_t n,
                                  int ncfl, double fraction);

/** @brief y at @p x by the cubic through the four rows nearest @p x
 *  (Lagrange's form, on any grid; the four end rows at the table's ends,
 *  the line through two rows for n < 4): exact for a cubic polynomial,
 *  and an error O(dt^4) on a smooth series where the linear
 *  vsph_series_interp leaves O(dt^2) -- the difference that decides when
 *  two runs' series are compared at slightly different output times
 *  (vsph_series_selfconv). NaN outside [t[0], t[n-1]] or for n = 0; t
 *  strictly ascending. */
VSPH_API double vsph_series_interp_cubic(const double *t, const double *y,
                                         size_t n, double x);

/** Most rungs a resolution ladder may have (vsph_series_selfconv). */
#define VSPH_SERIES_RUNGS_MAX 8

/** One rung of a resolution ladder: a run's series (t, E, n rows, those
 *  past a stop absent or not finite) and its particle spacing h (any
 *  unit: only the ratios between rungs are read). */
struct vsph_series_rung {
  const double *t; /*!< times */
  const double *E; /*!< energies at those times */
  size_t n;        /*!< rows */
  double h;        /*!< particle spacing */
};

/** A ladder's self-convergence: how successive resolutions approach each
 *  other, whatever the reference (the measure of "converges linearly";
 *  docs/theory.md section 6). */
struct vsph_series_selfconv {
  size_t nrung; /*!< rungs, coarse first */
  double span;  /*!< the common time span [0, span]: every rung's last
                     finite row reaches it */
  int partial;  /*!< 1: a rung ends before another (stopped): span is the
                     earliest end, not the run's */
  /** per pair of successive rungs k, k + 1 (k < nrung - 1), over the
   *  span at the finest rung's rows (one set of times for every pair):
   *  max |E_{k+1}/E_{k+1}(0) - E_k/E_k(0)| (a rung other than the finest
   *  interpolated by vsph_series_interp_cubic), and the same
   *  difference's RMS over time (trapezoid rule); both NaN where the
   *  rungs share no row */
  double dmax[VSPH_SERIES_RUNGS_MAX - 1], drms[VSPH_SERIES_RUNGS_MAX - 1];
  /** the observed order from the last two differences of each kind
   *  (vsph_series_order); NaN with two rungs */
  double order_max, order_rms;
  /** the finest rung's estimated distance from the limit, by Richardson:
   *  the last max difference / (r^p - 1) at the observed order p and the
   *  last ratio r (NaN where p <= 0 or is NaN) */
  double remainder;
};

/** @brief The order p of E_h = E + C h^p from two successive differences
 *  d_c = |E_{h0} - E_{h1}| and d_f = |E_{h1} - E_{h2}| and the refinement
 *  ratios r_c = h0/h1, r_f = h1/h2 (> 1): the root of
 *  r_f^p (r_c^p - 1)/(r_f^p - 1) = d_c/d_f, ln(d_c/d_f)/ln r for equal
 *  ratios r; negative when the differences grow. NaN for a difference
 *  not positive and finite, a ratio not above 1, or a root outside
 *  [-20, 20]. */
VSPH_API double vsph_series_order(double d_c, double d_f, double r_c,
                                  double r_f);

/** @brief The self-convergence of @p nrung rungs (2 to
 *  VSPH_SERIES_RUNGS_MAX, coarse first, h decreasing) into @p out.
 *  @return VSPH_OK, or VSPH_EINVAL (rung count, a rung without a finite
 *  first row or with E(0) = 0, h not decreasing). */
VSPH_API int vsph_series_selfconv(const struct vsph_series_rung *rung,
                                  size_t nrung,
                                  struct vsph_series_selfconv *out);

/** @brief The log-log slope of @p y against @p x (vsph_scaling_slope)
 *  over the points whose @p ok is nonzero, their number into @p ns (may
 *  be NULL): an order is never fitted through a run that stopped, whose
 *  figure is up to its stop. NaN with fewer than two such points. */
VSPH_API double vsph_series_slope_where(const double *x, const double *y,
                                        const int *ok, size_t n, size_t *ns);

/** A history over a reference history (vsph_series_ratio_history). */
struct vsph_series_ratio {
  int seen;      /*!< some row lay in the window */
  int below;     /*!< every such row's ratio below the edge (1 with none) */
  double peak;   /*!< the largest ratio over those rows (NaN where one is
                      NaN; -inf with none) */
  double t_last; /*!< the history's last time, or the window's end if
                      sooner */
  double last;   /*!< the ratio there (both interpolated) */
};

/** @brief History (@p t, @p y, @p n rows) over reference (@p tr, @p yr,
 *  @p nr rows, read by vsph_series_interp) at each of its rows in
 *  [@p t0, @p t1], against @p edge, into @p out: a run's E_k history over
 *  a finite-volume one, say, whether it stays below 1 less the reference's
 *  own error throughout. @return VSPH_OK or VSPH_EINVAL (a NULL pointer,
 *  n = 0, t0 > t1). */
VSPH_API int vsph_series_ratio_history(const double *t, const double *y,
                                       size_t n, const double *tr,
                                       const double *yr, size_t nr, double t0,
                                       double t1, double edge,
                                       struct vsph_series_ratio *out);

/** @brief Where @p x lies between @p a and @p b on a logarithmic scale:
 *  |ln(x/a)| / |ln(b/a)|, 0 at a, 1 at b's distance from a (either side).
 *  A claim's "differs" reads it as nearer a contrary law (b) than the
 *  paper's (a) from 0.5 on: halfway in ratio, sqrt(a b). NaN where any of
 *  the three is not positive and finite, or a = b. */
VSPH_API double vsph_series_log_between(double x, double a, double b);

#endif /* VSPH_ANALYSIS_SERIES_H */
