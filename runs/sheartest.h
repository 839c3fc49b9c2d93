/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_RUNS_SHEARTEST_H
#define VSPH_RUNS_SHEARTEST_H

#include <signal.h>
#include <stddef.h>

struct vsph_contact_shear;

/** @file shear.h
 *  @brief The shear test's results as CSV (analysis/contact): the
 *  profiles with both fits, and a summary that reads back (the report's
 *  cache). Texts are built in memory; the caller writes them with
 *  vsph_files_write (atomic). */

/** @brief The profiles: t, x, u, u_fit, dy, dy_fit per slab and profile
 *  time (the fits' exact solutions at the fitted nu). Caller frees; NULL
 *  after reporting on failure. */
char *vsph_sheartest_csv_profiles(const struct vsph_contact_shear *cs);

/** @brief One row per profile time: t, nu_u, rms_u, nu_dy, rms_dy, and
 *  the run's n, D0, W, U0, rho0, c0, t_end, steps, wall_s, stable,
 *  t_stop on every row. Caller frees; NULL after reporting on failure. */
char *vsph_sheartest_csv_summary(const struct vsph_contact_shear *cs);

/** @brief Read a summary back into @p cs (the scalars and fits; no
 *  profiles). @return VSPH_OK, or VSPH_EIO if it cannot be read or is
 *  not a summary (not reported: a missing cache is normal). */
int vsph_sheartest_csv_load(const char *path, struct vsph_contact_shear *cs);

struct vsph_params;

/** @brief The shear test's progress line on stderr ("vsph contact:
 *  shear t = ... / ... s, ... s"), as vsph_contact_shear's progress. */
void vsph_sheartest_progress(void *ctx, double t, double t_end, double wall);

/** @brief Measure (vsph_contact_shear_measure, @p nprof profile times,
 *  silent when @p quiet) into folder @p dir: summary.csv and
 *  profiles.csv. With @p cache, as runs/rundir's cache: the key
 *  (vsph_rundir_key of @p prm as given, after "contact NPROF") is written
 *  to key.txt last, a folder whose key.txt matches is not measured again
 *  (*cached = 1), and key.txt goes first when a measurement starts.
 *  The test checkpoints into DIR/checkpoint.bin (its key, then its state)
 *  every Solver:checkpoint_s of wall time and when @p stop (may be NULL)
 *  is set between two steps, and then ends with VSPH_EINTR, the folder
 *  unsealed; the next call on the same folder with the same parameters
 *  goes on from it, bitwise as if never stopped.
 *  @return VSPH_OK (an unstable run is a result), VSPH_EINVAL (bad
 *  parameters, nothing written), VSPH_EINTR (stopped at a checkpoint),
 *  VSPH_EIO, VSPH_ENOMEM. */
int vsph_sheartest_execute(struct vsph_params *prm, size_t nprof,
                           const char *dir, int cache, int quiet,
                           const volatile sig_atomic_t *stop, int *cached);

#endif /* VSPH_RUNS_SHEARTEST_H */
