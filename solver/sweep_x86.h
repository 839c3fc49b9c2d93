/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The symmetric sweep's scatter of j's shares with AVX2, chosen at
 * run time where vsph_pair_kernel::simd is 1 or 2, and the 2-D sweep by
 * cell groups of the Brookshaw forms, MEAF and the stress forms' second
 * pass, and of the stress forms' first pass, built for AVX-512 (where it
 * is 2) and for AVX2 (where it is 1) (solver/sweep_x86.c); the library's
 * own, not installed. */
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

struct vsph_equations_ctx;
struct vsph_pair_kernel;
struct vsph_particles;
struct vsph_cells;
struct vsph_equations_sweep;

/* The pair terms the sweep by cell groups has (@p visc below, and the
 * values of VSPH_VISCOUS_GROUPS in a family's file,
 * solver/viscous_internal.h): Brookshaw's, -K mu F du.x / (s^2 + eta^2) x
 * (MGF, VI, Cleary; vsph_pair_mgf), MEAF's, -2 mu F du (vsph_pair_meaf),
 * and the stress forms' second pass, -F (A_i + A_j) x (PVWF and B;
 * vsph_pair_pvwf_force, A = T L from the first pass, rc->vl.A) */
#define VSPH_SWEEP_X86_BROOKSHAW_TERM 1
#define VSPH_SWEEP_X86_MEAF_TERM 2
#define VSPH_SWEEP_X86_STRESS_TERM 3

/* sweep_block for a form whose viscous term is @p visc (above) in 2-D
 * with the 3h Gaussian, with delta-SPH (@p delta 1: a fourth field) or
 * without, not the parts (solver/equations_internal.h), built for
 * AVX-512: a cell's receivers, eight at a time, against whole vectors of
 * eight consecutive candidates of its ranges, each pair's kernel and
 * terms in the lanes, the lanes outside the support masked
 * (solver/sweep_x86.c says how). Its results are within rounding of the
 * four-lane loops', not their bits (fused multiply-adds, eight-lane sums,
 * j's shares summed over a group first; the same bits on 1 and 2
 * threads, as every loop of the sweep); the interactions and the closest
 * pair are the same. Defined only where VSPH_SWEEP_X86_GROUPS is 1;
 * call it only there, and where vsph_pair_x86_simd() returns 2
 * (sweep_block does). */
size_t vsph_sweep_x86_groups2_avx512(const struct vsph_equations_ctx *rc,
                                     const struct vsph_particles *p,
                                     const struct vsph_cells *cells,
                                     size_t n_fluid,
                                     const struct vsph_equations_sweep *sw,
                                     size_t blk, int delta, int visc,
                                     double *min_s2);

/* The same with AVX2 and FMA, vectors of four candidates (the group still
 * eight receivers), the lanes outside the support cleared by an and:
 * within rounding of the four-lane loops and of the AVX-512 sweep, not
 * their bits. Defined only where VSPH_SWEEP_X86_GROUPS is 1; call it
 * only there, and where vsph_pair_x86_simd() returns 1 or more
 * (sweep_block calls it where it returns 1). */
size_t vsph_sweep_x86_groups2_avx2(const struct vsph_equations_ctx *rc,
                                   const struct vsph_particles *p,
                                   const struct vsph_cells *cells,
                                   size_t n_fluid,
                                   const struct vsph_equations_sweep *sw,
                                   size_t blk, int delta, int visc,
                                   double *min_s2);

/* PVWF's (model B's) first pass, one block, in 2-D with the 3h Gaussian
 * (grad_block, solver/equations.c: each pair's terms -F x (x) x and
 * -F du (x) x of B and Mg, i's times V_j and j's times V_i, into the
 * block's buffer of eight fields a particle, every particle a receiver),
 * by cell groups as vsph_sweep_x86_groups2_avx512 walks them, for
 * AVX-512 (_avx512) and for AVX2 and FMA (_avx2): within rounding of the
 * portable loops and of each other, not their bits; the same bits on 1
 * and 2 threads. Defined only where VSPH_SWEEP_X86_GROUPS is 1; call
 * them only there, and where vsph_pair_x86_simd() returns 2 (_avx512) or
 * 1 or more (_avx2) (grad_sweep does). */
void vsph_sweep_x86_grad2_avx512(const struct vsph_pair_kernel *pk,
                                 const struct vsph_particles *p,
                                 const struct vsph_cells *cells,
                                 const struct vsph_equations_sweep *sw,
                                 size_t blk);
void vsph_sweep_x86_grad2_avx2(const struct vsph_pair_kernel *pk,
                               const struct vsph_particles *p,
                               const struct vsph_cells *cells,
                               const struct vsph_equations_sweep *sw,
                               size_t blk);

/* The sweeps' exponential: y[k] = e^{-x[k]}, 0 <= x[k] <= 700, for
 * k < n, eight at a time (expneg8) or four (expneg4), for its test. The
 * same conditions as vsph_sweep_x86_groups2_avx512 (expneg8) and
 * _avx2 (expneg4). */
void vsph_sweep_x86_expneg8(const double *x, double *y, size_t n);
void vsph_sweep_x86_expneg4(const double *x, double *y, size_t n);

/* The sweeps' adds of j's shares (for their test): entry q[nf l + a] gets
 * field a of particle l, f[a][l], for l < @p nl and a < @p nf (3 or 4),
 * one add each; q[nf nl] on is not touched. addj8: nl 1 to 8 (f[a] eight
 * entries each), the conditions of vsph_sweep_x86_groups2_avx512;
 * addj4: nl 1 to 4 (four entries each), those of _avx2. */
void vsph_sweep_x86_addj8(double *q, int nf, const double *const f[4],
                          size_t nl);
void vsph_sweep_x86_addj4(double *q, int nf, const double *const f[4],
                          size_t nl);

#if defined(__x86_64__) && defined(__LP64__) && defined(__GNUC__) && \
    !defined(__clang__) && defined(__AVX2__) && defined(__FMA__)
/* 1 where solver/sweep_x86.c builds the AVX-512 and AVX2 sweeps by cell
 * groups: GCC in a build for AVX2 and FMA (x86-64-v3: the program's and
 * the installed x86-64-v3 copy's, which run only on a CPU that has both),
 * LP64 as VSPH_PAIR_X86 needs. Only GCC because every build and
 * test here uses it: clang, which builds only the fuzzers here, would
 * take the code (target attributes, no pragma), but nothing runs it
 * there. */
#define VSPH_SWEEP_X86_GROUPS 1
#else
#define VSPH_SWEEP_X86_GROUPS 0
#endif

#endif /* VSPH_SOLVER_SWEEP_X86_H */
