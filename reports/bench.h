/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_BENCH_H
#define VSPH_REPORTS_BENCH_H

#include <stddef.h>
#include <stdio.h>

/** @file bench.h
 *  @brief `make bench`: timings of the building blocks and of the solver
 *  (never in the tests). The building blocks: best of several repetitions
 *  (the minimum filters the noise of a shared machine); the solver: the
 *  median, with the load average beside each row. */

/** What to time. */
struct vsph_bench_props {
  size_t size;      /*!< particles across the operator benchmark's square */
  int solver_only;  /*!< 1: only the solver tables */
  int busy;         /*!< other busy processes to start beside the solver
                         table (0-8), to measure it under load */
  size_t processes; /*!< processes measuring the solver table, one after
                         another (1-20): its best and median over them */
  int raw;          /*!< 1: only the solver rows as CSV (a child of
                         processes > 1) */
  const char *csv;  /*!< if not NULL: the solver table as CSV here too */
};

/** @brief Run the benchmarks and print their tables to @p out.
 *  @return VSPH_OK or the first failure. */
int vsph_bench_run(const struct vsph_bench_props *bp, FILE *out);

/** @brief The fold of @p n processes' best times @p t (sorted in place)
 *  that `vsph bench --processes` reports: the best of all into *best and
 *  the median of the processes' bests into *median (the mean of the two
 *  middle ones for an even @p n); NaN for none. */
void vsph_bench_fold(double *t, size_t n, double *best, double *median);

#endif /* VSPH_REPORTS_BENCH_H */
