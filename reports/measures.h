/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_MEASURES_H
#define VSPH_REPORTS_MEASURES_H

#include <stddef.h>

#include "../analysis/series.h"

/** @file measures.h
 *  @brief The figures the claims read that gather several runs or rows
 *  into one: the closest of a set, the first failure on a map, a sweep's
 *  outcome, sign changes, the largest factor between two tables, a range.
 *  Plain arrays in, figures out, no runs or files: each is worked by hand
 *  in tests/check_measures.c, and the report parts call them (the claims'
 *  arithmetic on single figures stands in their blocks, `let`). Within
 *  reports/ and the tests only. */

/** @brief The least and largest of the finite values among @p x[0..n)
 *  into *lo, *hi (+inf and -inf where none) and how many are finite into
 *  *count (any may be NULL). */
void vsph_measures_extent(const double *x, size_t n, double *lo, double *hi,
                          size_t *count);

/** @brief The largest of @p from and the values of @p x[0..n) that are
 *  not NaN (a figure not measured is passed over; infinities count), as a
 *  chain of fmax from @p from; with @p from NaN, NaN where every value is.
 *  vsph_measures_smallest likewise with fmin. */
double vsph_measures_largest(const double *x, size_t n, double from);
/** @brief The smallest: vsph_measures_largest with fmin. */
double vsph_measures_smallest(const double *x, size_t n, double from);

/** @brief A ladder's successive differences |x[k+1] - x[k]|, k < n - 1,
 *  into @p d, each NaN unless every x is finite (a difference read only
 *  where the whole ladder was measured). @return 1 where they were, else
 *  0. */
int vsph_measures_steps(const double *x, size_t n, double *d);

/** @brief The index of the largest of @p x[0..n) (@p sign 1) or the
 *  smallest (@p sign -1): the first on a tie, entry 0 where nothing beats
 *  it (a NaN beats nothing); -1 where n is 0. */
int vsph_measures_arg(const double *x, int n, int sign);

/** @brief The largest factor either way between @p a[k] and @p b[k] over
 *  k < @p n, max(a/b, b/a), and at least 1 (1 where n is 0); a pair with
 *  a value not positive or not finite counts as infinitely far (+inf), so
 *  a table not measured is never near. */
double vsph_measures_max_factor(const double *a, const double *b, size_t n);

/** @brief How often @p f[0..n) changes sign, in order, over the entries
 *  with @p use[k] set, passing over those whose size is below @p floor (a
 *  value at rounding level has no sign), exactly zero or not measured
 *  (NaN); -1 where
 *  @p floor itself is NaN (nothing can be read). */
int vsph_measures_sign_changes(const double *f, const int *use, size_t n,
                               double floor);

/** @brief The closest of several forms to a reference, as the claim
 *  visc_best reads it. */
struct vsph_measures_closest {
  int best;     /*!< the form with the least error among those that ended
                     (the first on a tie); -1: none ended */
  double next;  /*!< the least error of the others that ended (+inf: none) */
  double gap;   /*!< next - its error (NaN where best is -1) */
  double swing; /*!< the largest swing of those that ended (0: none; NaN
                     where one of theirs is not measured) */
};

/** @brief Of @p n forms with errors @p u, swings @p swing (each error's
 *  own range over its window) and whether each ended (@p ok), the closest,
 *  the next and the largest swing, into @p out; a form whose error is not
 *  measured (NaN) counts as one that did not end. */
void vsph_measures_closest(const double *u, const double *swing, const int *ok,
                           int n, struct vsph_measures_closest *out);

/** Most forms a robustness map holds. */
#define VSPH_MEASURES_MAP_MAXF 16

/** @brief A robustness map's figures (Basa et al.'s Fig. 5), as the
 *  claims map_failure and map_robust read them. */
struct vsph_measures_map {
  double score[VSPH_MEASURES_MAP_MAXF]; /*!< per form: the sum over Re of
                                             min(t_fail, cap) */
  double any;   /*!< the least Re at which any form fails (+inf: none) */
  int who;      /*!< the first form in order failing there (-1: none) */
  double first; /*!< the least Re at which a robust form fails (+inf) */
  double held;  /*!< the largest Re at which every robust form holds (0:
                     none) */
};

/** @brief The map of @p nf forms (at most VSPH_MEASURES_MAP_MAXF) over
 *  @p nre Reynolds numbers @p re: @p tf[f * nre + q] form f's failure time
 *  at re[q] (+inf: it held to the end; NaN: not measured, which makes the
 *  form's score NaN and holds at no Re), @p robust[f] whether the claim
 *  names it robust, @p cap the run's end (a form that holds scores it);
 *  into @p out. @return 0, or -1 for too many forms (out untouched). */
int vsph_measures_map(const double *tf, const double *re, const int *robust,
                      int nf, int nre, double cap,
                      struct vsph_measures_map *out);

/** Most sound speeds and time steps a sweep holds. */
#define VSPH_MEASURES_SWEEP_MAXC 8
#define VSPH_MEASURES_SWEEP_MAXD 4

/** @brief A time-step sweep (Vukcevic et al.'s dt against c): per sound
 *  speed a and time step b (largest first), how the run ended ('r' runs,
 *  'a' runs but agitated, 's' stopped), its final error, its stop time, and
 *  per a the zigzag of the smallest dt's run. */
struct vsph_measures_sweep_in {
  int nc, nd;
  char out[VSPH_MEASURES_SWEEP_MAXC][VSPH_MEASURES_SWEEP_MAXD];
  double err[VSPH_MEASURES_SWEEP_MAXC][VSPH_MEASURES_SWEEP_MAXD];
  double t_stop[VSPH_MEASURES_SWEEP_MAXC][VSPH_MEASURES_SWEEP_MAXD];
  double zig[VSPH_MEASURES_SWEEP_MAXC];
};

/** @brief What a sweep shows, as the claims p003_combos and p003_dt read
 *  it. */
struct vsph_measures_sweep {
  int nbad, ntot; /*!< non-physical runs (stopped or agitated); runs */
  int mixed;      /*!< the first c whose dts do not all end alike (-1) */
  char out[VSPH_MEASURES_SWEEP_MAXC]; /*!< per c: its outcome where every
                                           dt ends alike, else 'm' */
  double acc;  /*!< the largest (max - min)/min of the error over dt at a c
                    whose runs all run (NaN: none) */
  double rise; /*!< the largest ratio of the error at a dt to the error at
                    the next larger dt over the c whose runs all run (below
                    1: the error falls as dt does); NaN where acc is, or a
                    ratio is not measured */
  int turn;    /*!< the first c where a smaller dt turns a non-physical run
                    into a physical one (-1: none) */
  double lag[VSPH_MEASURES_SWEEP_MAXC]; /*!< per c where every dt stops:
                                             the smallest dt's stop over the
                                             larger ones' latest (NaN at the
                                             others, and where a stop is not
                                             measured or the latest is not
                                             positive) */
  double zlo, zhi; /*!< the smallest dt's zigzag over the c whose run there
                        runs: lowest, highest (NaN: none) */
  int alo, ahi;    /*!< at which c (-1) */
  int open;        /*!< 1: a c whose runs all run has an error not
                        measured (acc and rise are then NaN) */
};

/** @brief The figures of sweep @p in into @p w. @return 0, or -1 for a
 *  sweep larger than the arrays (w untouched). */
int vsph_measures_sweep(const struct vsph_measures_sweep_in *in,
                        struct vsph_measures_sweep *w);

/** Groups a run of vsph_measures_ratios may belong to (bits). */
#define VSPH_MEASURES_GROUPS 3

/** @brief Several runs' histories over one reference
 *  (vsph_series_ratio_history), gathered, as the claim cavity_ek reads
 *  them. */
struct vsph_measures_ratios {
  int measured;      /*!< the runs with a row in the window (seen) */
  int under;         /*!< of those, the runs below the edge throughout */
  double peak;       /*!< the largest ratio over every run's window (NaN where
                          one is; -inf with none) */
  double lo, hi;     /*!< the seen runs' last ratios, the finite ones: least
                          and largest (+inf, -inf with none) */
  double t_lo, t_hi; /*!< the seen runs' last times: least and largest */
  int seen_in[VSPH_MEASURES_GROUPS]; /*!< the seen runs in each group */
};

/** @brief Runs @p hr[0..n) gathered into @p out; @p group[k] the bits
 *  (1 << g, g < VSPH_MEASURES_GROUPS) of run k's groups. */
void vsph_measures_ratios(const struct vsph_series_ratio *hr, const int *group,
                          size_t n, struct vsph_measures_ratios *out);

#endif /* VSPH_REPORTS_MEASURES_H */
