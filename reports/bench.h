#ifndef VSPH_REPORTS_BENCH_H
#define VSPH_REPORTS_BENCH_H

#include <stddef.h>
#include <stdio.h>

/** @file bench.h
 *  @brief `make bench`: timings of the building blocks and of the solver
 *  (never in the tests). Each figure is the best of several repetitions
 *  (the minimum filters the noise of a shared machine), and the load
 *  average is printed beside the tables. */

/** What to time. */
struct vsph_bench_props {
  size_t size;     /*!< particles across the operator benchmark's square */
  int solver_only; /*!< 1: only the solver tables */
};

/** @brief Run the benchmarks and print their tables to @p out.
 *  @return VSPH_OK or the first failure. */
int vsph_bench_run(const struct vsph_bench_props *bp, FILE *out);

#endif /* VSPH_REPORTS_BENCH_H */
