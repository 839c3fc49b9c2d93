/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_FVREF_H
#define VSPH_REPORTS_FVREF_H

#include <stddef.h>

#include "../analysis/series.h"

/** @file fvref.h
 *  @brief The committed finite-volume references (reference/data, made by
 *  scripts/reference with OpenFOAM v1912; reference/README.md): the
 *  stretching square's grid ladder (interFoam, volume of fluid, Re 20) and
 *  the lid-driven cavity's (icoFoam, Re 100 and 1000). The report reads
 *  only these files, and derives from them what it says of the references
 *  themselves: their own convergence order, the finest grid's error
 *  estimate, the time step's and the air's share, the energy budget.
 *  Nothing here runs OpenFOAM. */

/** The square's grids: 40, 80, 160 cells across L at the common time step
 *  dt A0 = 1/1600, 320 at half of it (reference/README.md). */
#define VSPH_FVREF_SQ_GRIDS 4
/** The grids the report judges against: all four, each corrected for its
 *  step by a run at half of it (at 320 cells, Courant 0.1 and 0.05: at the
 *  common step's 0.2 the correction does not hold, reference/README.md). */
#define VSPH_FVREF_SQ_LADDER 4
/** Rows of a square file: t A0 = 0, 0.005, ..., 1. */
#define VSPH_FVREF_SQ_ROWS 201
/** The cavity's grids: 32, 64, 128, 256 cells per side. */
#define VSPH_FVREF_CAV_GRIDS 4
/** Most rows of a cavity E_k file: t = 0, 0.1, ..., 80 s. */
#define VSPH_FVREF_CAV_ROWS 801
/** The largest miss of the finest square grid's energy budget,
 *  |dE_k/dt - P| / |P| for t A0 >= 0.05, that vsph_fvref_check accepts.
 *  Origin: the smeared interface's share of the alpha-weighted integrals
 *  (two or three cells of 320) and the splitting error of the step, each
 *  a fraction of a per cent on the committed ladder (its table in the
 *  report); 1 % is several times either. */
#define VSPH_FVREF_BUDGET 0.01
/** Ghia et al.'s points per centreline. */
#define VSPH_FVREF_GHIA 17

/** A square series: E_k, dE_k/dt (differences of the solver's steps), the
 *  viscous power -2 mu int alpha D:D and the liquid's volume, the full
 *  square per unit depth, at t[k]. */
struct vsph_fvref_sqseries {
  int ok; /*!< 1: read, VSPH_FVREF_SQ_ROWS rows */
  double E[VSPH_FVREF_SQ_ROWS], dE[VSPH_FVREF_SQ_ROWS], P[VSPH_FVREF_SQ_ROWS],
      vol[VSPH_FVREF_SQ_ROWS];
  double wall_s; /*!< the solver's wall time (its meta file) */
  long steps;    /*!< its time steps */
  int procs;     /*!< the processes it ran on */
};

/** The square: the ladder, the checks beside it and what they say. */
struct vsph_fvref_square {
  int ok;                       /*!< 1: every grid read */
  double t[VSPH_FVREF_SQ_ROWS]; /*!< t A0 (A0 = 1) */
  int n[VSPH_FVREF_SQ_GRIDS];   /*!< cells across L */
  struct vsph_fvref_sqseries g[VSPH_FVREF_SQ_GRIDS];
  /** each grid at half its step: 40 to 160 cells run the common step,
   *  dt A0 = 1/1600, and half of it; 320 cells half of it and a quarter */
  struct vsph_fvref_sqseries half[VSPH_FVREF_SQ_GRIDS];
  /** 320 cells at the common step (Courant 0.2), read as a check: there
   *  the step's error left after the 4/3 correction exceeds the grid's */
  struct vsph_fvref_sqseries co2;
  /** at 80 cells, density ratios 100 and 10000 (the ladder's 1000) */
  struct vsph_fvref_sqseries r100, r10000;
  /** at 80 cells, the wider domain (1.6 L x 0.8 L against 1.2 L x 0.7 L) */
  struct vsph_fvref_sqseries wide;
  /** self-convergence of the corrected E_k/E_k(0) over the judged grids
   *  (the measure the report uses for SPH's ladders); remainder is the
   *  finest judged grid's error estimate */
  struct vsph_series_selfconv sc;
  /** the finest grid's (320, corrected) error band for E_k/E_k(0): the
   *  Richardson remainder of the corrected ladder, the step correction's
   *  uncertainty there (2/3 time_err[3]: from the second order's 4/3 to a
   *  first order's 2), the air's and the far sides' shares, added; NaN
   *  when one is not measured */
  double band;
  /** max over t of the |E/E0| difference between the ladder's step and
   *  half of it, at 40, 80, 160 and 320 cells (the step is the same, so
   *  the Courant number doubles with the grid and the outer correctors'
   *  splitting error grows with it) */
  double time_err[VSPH_FVREF_SQ_LADDER];
  /** its growth per doubling, time_err[1..3] / time_err[0..2] */
  double time_grow[VSPH_FVREF_SQ_LADDER - 1];
  /** max over t of |E/E0(ratio 1000) - E/E0(ratio 10000)| and
   *  |E/E0(100) - E/E0(1000)| at 80 cells: the air's share */
  double air_err, air_err100;
  /** max over t of |E/E0(wide) - E/E0| at 80 cells: the far sides' share */
  double dom_err;
  /** the finest grid's energy budget: max over t in [0.05, 1] of
   *  |dE_k/dt - P| / |P|, of its run at half its step (Courant 0.05, the
   *  run its corrected values lie nearer to) */
  double budget;
  /** the same at the common step (Courant 0.2 at 320 cells), where the
   *  outer correctors' splitting error shows */
  double budget_full;
  /** per grid: E_k(0) over the exact (1/12) (1 - 1/n^2) of the
   *  cell-centred quadrature, P(0) over -4 mu A0^2 L^2, the share of E_k
   *  dissipated by t A0 = 1 */
  double e0_ratio[VSPH_FVREF_SQ_GRIDS], p0_ratio[VSPH_FVREF_SQ_GRIDS],
      share[VSPH_FVREF_SQ_GRIDS];
  /** each grid's E_k/E_k(0) corrected for the step (time_err's
   *  comment): the ladder the order, the remainder and the SPH
   *  comparisons read */
  double Ec[VSPH_FVREF_SQ_GRIDS][VSPH_FVREF_SQ_ROWS];
  /** the finest grid's E_k/E_k(0) extrapolated to the limit (Richardson at
   *  the observed order of the largest differences), at each t */
  double Ex[VSPH_FVREF_SQ_ROWS];
};

/** One cavity grid: E_k(t) (rho = 1, per unit depth) and the centrelines
 *  at the end time at Ghia's points. */
struct vsph_fvref_cavgrid {
  int ok;
  size_t nrow;
  double t[VSPH_FVREF_CAV_ROWS], E[VSPH_FVREF_CAV_ROWS];
  double u[VSPH_FVREF_GHIA], v[VSPH_FVREF_GHIA];   /*!< u_x(y), u_y(x) */
  double gu[VSPH_FVREF_GHIA], gv[VSPH_FVREF_GHIA]; /*!< Ghia's values */
  double yu[VSPH_FVREF_GHIA], xv[VSPH_FVREF_GHIA]; /*!< Ghia's points */
  /** RMS and largest |FV - Ghia| over the 15 + 15 interior points */
  double ghia_rms, ghia_max;
  double wall_s;
  long steps;
};

/** A cavity ladder at one Reynolds number. */
struct vsph_fvref_cavity {
  int ok; /*!< every grid read */
  double Re, t_end;
  int n[VSPH_FVREF_CAV_GRIDS];
  struct vsph_fvref_cavgrid g[VSPH_FVREF_CAV_GRIDS];
  /** successive differences of E_k at t_end between grids, their order,
   *  and the finest grid's Richardson estimate of its error */
  double dE[VSPH_FVREF_CAV_GRIDS - 1], order, remainder;
};

/** Everything under one folder. */
struct vsph_fvref {
  const char *dir; /*!< the folder read, or NULL */
  struct vsph_fvref_square sq;
  struct vsph_fvref_cavity cav[2]; /*!< Re 100, 1000 */
};

/** @brief Read the references in folder @p dir (NULL: none) into @p fv
 *  (heap: the struct is large). A file that is missing leaves its part's
 *  ok at 0 (the report then says "not tested"); one that is there and
 *  malformed (columns, rows, times) is an error.
 *  @return VSPH_OK, or VSPH_EIO (reported). */
int vsph_fvref_read(const char *dir, struct vsph_fvref *fv);

/** @brief The committed references against what is known of them
 *  exactly (each tolerance's origin in fvref.c): the square's E_k(0)
 *  against (6.42)'s energy on its cells, its P(0) against
 *  -4 mu A0^2 L^2, its volume, an E_k that only falls, an energy budget
 *  that closes, a ladder that converges; the cavity's start from rest,
 *  its Ghia column against vsph's own table, its finest grid against
 *  Ghia within the table's precision. @return 0 when all hold, else the
 *  number that fail, the first said in @p why (@p n bytes). A part not
 *  read (ok 0) is not checked. */
int vsph_fvref_check(const struct vsph_fvref *fv, char *why, size_t n);

/** @brief The finest judged square grid's (160) E_k/E_k(0), corrected
 *  for the step,
 *  at @p t (linear between rows; NaN outside [0, 1] or when not read). */
double vsph_fvref_square_at(const struct vsph_fvref_square *s, double t);

/** @brief The finest cavity grid's E_k at @p t (linear; NaN outside). */
double vsph_fvref_cavity_at(const struct vsph_fvref_cavity *c, double t);

#endif /* VSPH_REPORTS_FVREF_H */
