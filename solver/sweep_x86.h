/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The symmetric sweep's scatter of j's shares with AVX2, chosen at
 * run time where vsph_pair_kernel::simd is 1 or 2 (solver/sweep_x86.c); the
 * library's own, not installed. */
#ifndef VSPH_SOLVER_SWEEP_X86_H
#define VSPH_SOLVER_SWEEP_X86_H

#include <stddef.h>

/* Add the @p nf (3 or 4) fields of the @p m pairs' shares to their
 * receivers, as sweep_add does (solver/equations_internal.h): the share of
 * field a of pair k is js[a * stride + k], its receiver's entry
 * buf + (jj[k] - lo) * nf. Each entry gets one add a pair, a lane each, so
 * the same bits as the scalar loop (the receivers of one chunk are
 * distinct). Call only where vsph_pair_x86_simd() returns 1 or 2; the library's
 * baseline copy (no AVX2 in its build) has it abort. */
void vsph_sweep_x86_add_avx2(double *buf, size_t lo, int nf, const size_t *jj,
                             size_t m, const double *js, size_t stride);

/* The same for eight fields, each share times @p v first: entry
 * buf + (jj[k] - lo) * 8 gets v * u[a * stride + k] in field a, as PVWF's
 * first pass (grad_block, solver/equations.c) adds j's shares in 2-D. */
void vsph_sweep_x86_add8_avx2(double *buf, size_t lo, const size_t *jj,
                              size_t m, const double *u, size_t stride,
                              double v);

#endif /* VSPH_SOLVER_SWEEP_X86_H */
