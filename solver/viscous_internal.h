/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_VISCOUS_INTERNAL_H
#define VSPH_SOLVER_VISCOUS_INTERNAL_H

/* A formulation's specialised loops (struct vsph_viscous_loops, opaque in
 * viscous.h): vsph_viscous_compute's loop as a template (force_cell),
 * and VSPH_VISCOUS_LOOPS, which instantiates every specialised loop of a
 * family (the right-hand side's gathers and sweeps of
 * solver/equations_internal.h, and force_cell) with the family's pair
 * function, in the family's own file of solver/forms/. Within solver/
 * only. */

#include <math.h>
#include <stddef.h>

#include "../common/consts.h"
#include "../kernels/kernel.h"
#include "cells.h"
#include "equations_internal.h"
#include "pair.h"
#include "particles.h"
#include "viscous.h"

/* (div V)_i of particle i into out, by the pair function @p pair (NULL:
 * the particle's own force only); returns the pairwise dissipation
 * density. Shares per chunk in one vectorisable loop, then summed in
 * neighbour order (as the right-hand side's). */
VSPH_CONSTS_SPECIALISE double force_one(
    const struct vsph_viscous_loop *lp, const struct vsph_pair_kernel *pk,
    const struct vsph_particles *p, const struct vsph_pair_ranges *rg, size_t i,
    double *const out[3], const int dim, vsph_viscous_pair_fn *const pair,
    const int kid) {
  double acc[3] = {0, 0, 0}, Ai[9] = {0}, ui[3] = {0, 0, 0}, pd = 0.0;
  vsph_viscous_load_A(lp, i, Ai);
  for (int k = 0; k < dim; k++) ui[k] = p->vel[k][i];
  struct vsph_pair_iter it;
  struct vsph_pair_chunk b;
  vsph_pair_begin(&it, pk, p, rg, i);
  while (vsph_pair_gather(&it, dim, kid, &b)) {
    const size_t m = b.m;
    double fv[3][VSPH_PAIR_CHUNK_MAX], fd[VSPH_PAIR_CHUNK_MAX];
#pragma omp simd
    for (size_t q = 0; q < m; q++) {
      struct vsph_pair pr;
      vsph_pair_at(&b, q, dim, &pr);
      struct vsph_pair_vec du;
      double dux = 0.0;
      for (int k = 0; k < dim; k++) {
        du.v[k] = p->vel[k][pr.j] - ui[k];
        dux += du.v[k] * pr.x[k];
      }
      const struct vsph_pair_visc r =
          viscous_share(pair, lp, dim, &pr, du, dux, Ai);
      fd[q] = r.dens;
      for (int k = 0; k < dim; k++) fv[k][q] = r.f[k];
    }
    for (size_t q = 0; q < m; q++) {
      pd += fd[q];
      for (int k = 0; k < dim; k++) acc[k] += fv[k][q];
    }
  }
  vsph_viscous_own(lp, i, acc);
  for (int k = 0; k < dim; k++) out[k][i] = acc[k];
  return pd;
}

/* The particles of cell c (vsph_viscous_compute): (div V)_i into @p out
 * and, where @p dens is given, each one's dissipation density, the first
 * pass's @p first_dens where the form has one, else its pairwise one. */
VSPH_CONSTS_SPECIALISE void force_cell(
    const struct vsph_viscous_loop *lp, const struct vsph_pair_kernel *pk,
    const struct vsph_particles *p, const struct vsph_cells *cells, size_t c,
    double *const out[3], double *dens, const double *first_dens, const int dim,
    vsph_viscous_pair_fn *const pair, const int kid) {
  struct vsph_pair_ranges rg;
  vsph_pair_ranges_cell(&rg, cells, c);
  const size_t i0 = cells->start[c], i1 = i0 + cells->count[c];
  for (size_t i = i0; i < i1; i++) {
    const double pd = force_one(lp, pk, p, &rg, i, out, dim, pair, kid);
    if (dens) dens[i] = first_dens ? first_dens[i] : pd;
  }
}

/* One cell of vsph_viscous_compute, specialised. */
typedef void vsph_viscous_cell_fn(const struct vsph_viscous_loop *lp,
                                  const struct vsph_pair_kernel *pk,
                                  const struct vsph_particles *p,
                                  const struct vsph_cells *cells, size_t c,
                                  double *const out[3], double *dens,
                                  const double *first_dens);

/* One shape's loops: the right-hand side's gather of a cell and its
 * symmetric sweep of a block. */
struct vsph_viscous_shape_loops {
  vsph_equations_cell_fn *cell;
  vsph_equations_sweep_fn *sweep;
};

/* A family's specialised loops, each with its pair functions inlined
 * (what a descriptor's loops field points at). The right-hand side
 * (equations.c) takes the one for the run's shape (any: every shape
 * without one of its own); vsph_viscous_compute takes force for the 2-D
 * Gaussian. */
struct vsph_viscous_loops {
  vsph_viscous_pair_fn *pair;     /* the pair function they inline (the
                                     descriptor's: tests/check_viscous.c) */
  vsph_viscous_pair_g_fn *pair_g; /* the corrected one (the descriptor's;
                                     NULL: not corrigible) */
  struct vsph_viscous_shape_loops gauss[2][2]; /* the 3h Gaussian,
                                                  [dim - 2][delta-SPH] */
  vsph_equations_cell_fn *tvf;   /* 2-D quintic spline with the transport
                                    velocity, no delta (NULL: none) */
  vsph_equations_cell_fn *cubic; /* 2-D cubic B-spline, no delta */
  vsph_equations_cell_fn *any;   /* any other shape (1-D, another kernel,
                                    the reduction, the corrections): the
                                    run's dimension, kernel and switches */
  vsph_viscous_cell_fn *force;   /* vsph_viscous_compute, 2-D Gaussian */
};

/* The parameters of a vsph_equations_cell_fn and of a
 * vsph_equations_sweep_fn. */
#define VSPH_VISCOUS_CELL_ARGS                                         \
  const struct vsph_equations_ctx *rc, const struct vsph_particles *p, \
      const struct vsph_cells *cells, size_t c, size_t n_fluid,        \
      struct vsph_equations_out *out, double *min_s2
#define VSPH_VISCOUS_SWEEP_ARGS                                        \
  const struct vsph_equations_ctx *rc, const struct vsph_particles *p, \
      const struct vsph_cells *cells, size_t n_fluid,                  \
      const struct vsph_equations_sweep *sw, size_t blk, int nf,       \
      double *min_s2

/* A gather (rhs_cell) @p fn for dimension D, kernel KID, delta switch
 * DELTA and transport velocity TVF, its pair function PAIR inlined. */
#define VSPH_VISCOUS_CELL(fn, PAIR, D, KID, DELTA, TVF)                   \
  static size_t fn(VSPH_VISCOUS_CELL_ARGS) {                              \
    return rhs_cell(rc, p, cells, c, n_fluid, out, min_s2, D, PAIR, NULL, \
                    DELTA, KID, 0, 0, TVF);                               \
  }

/* The gather @p fn for the run's shape (its dimension, kernel and
 * switches at run time), the pair functions PAIR and PAIR_G inlined. */
#define VSPH_VISCOUS_CELL_ANY(fn, PAIR, PAIR_G)                              \
  static size_t fn(VSPH_VISCOUS_CELL_ARGS) {                                 \
    return rhs_cell(rc, p, cells, c, n_fluid, out, min_s2, rc->pk.dim, PAIR, \
                    PAIR_G, rc->dhc > 0.0, rc->pk.dfq_id, rc->reduce,        \
                    rc->corr, rc->tvf);                                      \
  }

/* In a family's file, defined before its includes, where its 2-D
 * Gaussian sweep goes by cell groups in AVX-512 or AVX2 lanes on a CPU
 * that has them (vsph_sweep_x86_groups2_avx512, _avx2; within rounding):
 * its viscous term, VSPH_SWEEP_X86_BROOKSHAW_TERM (1, the Brookshaw
 * forms, solver/forms/brookshaw.c), VSPH_SWEEP_X86_MEAF_TERM (2, MEAF,
 * solver/forms/morris.c) or VSPH_SWEEP_X86_STRESS_TERM (3, the second
 * pass of PVWF and B, solver/forms/stress.c); 0 in every other
 * family's. */
#ifndef VSPH_VISCOUS_GROUPS
#define VSPH_VISCOUS_GROUPS 0
#endif

/* A sweep (sweep_block) @p fn for dimension D and delta switch DELTA, the
 * 3h Gaussian, its pair function PAIR inlined. */
#define VSPH_VISCOUS_SWEEP(fn, PAIR, D, DELTA)                                \
  static size_t fn(VSPH_VISCOUS_SWEEP_ARGS) {                                 \
    return sweep_block(rc, p, cells, n_fluid, sw, blk, nf, min_s2, D, PAIR,   \
                       DELTA, VSPH_KERNEL_DFQ_GAUSSIAN, VSPH_VISCOUS_GROUPS); \
  }

/* Every specialised loop of a family whose pair function is PAIR and
 * corrected pair function PAIR_G (NULL: not corrigible), both declared
 * VSPH_CONSTS_SPECIALISE so that they inline, as the static struct
 * vsph_viscous_loops @p name that its descriptors point at; TVF 1: with
 * the transport velocity's loop (the forms flagged VSPH_VISCOUS_TVF). A
 * function of its own each (not one big switch), so each is optimised on
 * its own. Used once per family, in its file of solver/forms/. */
#define VSPH_VISCOUS_LOOPS(name, PAIR, PAIR_G, TVF)                          \
  VSPH_VISCOUS_CELL(name##_g2, PAIR, 2, VSPH_KERNEL_DFQ_GAUSSIAN, 0, 0)      \
  VSPH_VISCOUS_CELL(name##_g2d, PAIR, 2, VSPH_KERNEL_DFQ_GAUSSIAN, 1, 0)     \
  VSPH_VISCOUS_CELL(name##_g3, PAIR, 3, VSPH_KERNEL_DFQ_GAUSSIAN, 0, 0)      \
  VSPH_VISCOUS_CELL(name##_g3d, PAIR, 3, VSPH_KERNEL_DFQ_GAUSSIAN, 1, 0)     \
  VSPH_VISCOUS_CELL(name##_tvf2, PAIR, 2, VSPH_KERNEL_DFQ_QUINTIC, 0, 1)     \
  VSPH_VISCOUS_CELL(name##_cubic2, PAIR, 2, VSPH_KERNEL_DFQ_CUBIC, 0, 0)     \
  VSPH_VISCOUS_CELL_ANY(name##_any, PAIR, PAIR_G)                            \
  VSPH_VISCOUS_SWEEP(name##_s2, PAIR, 2, 0)                                  \
  VSPH_VISCOUS_SWEEP(name##_s2d, PAIR, 2, 1)                                 \
  VSPH_VISCOUS_SWEEP(name##_s3, PAIR, 3, 0)                                  \
  VSPH_VISCOUS_SWEEP(name##_s3d, PAIR, 3, 1)                                 \
  static void name##_force2(                                                 \
      const struct vsph_viscous_loop *lp, const struct vsph_pair_kernel *pk, \
      const struct vsph_particles *p, const struct vsph_cells *cells,        \
      size_t c, double *const out[3], double *dens,                          \
      const double *first_dens) {                                            \
    force_cell(lp, pk, p, cells, c, out, dens, first_dens, 2, PAIR,          \
               VSPH_KERNEL_DFQ_GAUSSIAN);                                    \
  }                                                                          \
  static const struct vsph_viscous_loops name = {                            \
      .pair = PAIR,                                                          \
      .pair_g = PAIR_G,                                                      \
      .gauss = {{{name##_g2, name##_s2}, {name##_g2d, name##_s2d}},          \
                {{name##_g3, name##_s3}, {name##_g3d, name##_s3d}}},         \
      .tvf = (TVF) ? name##_tvf2 : NULL,                                     \
      .cubic = name##_cubic2,                                                \
      .any = name##_any,                                                     \
      .force = name##_force2};

/* vsph_viscous_pvwf_finish for particles @p i0 to @p i1 - 1, whose sums
 * lie in @p t, 2 d^2 a particle (B, then Mg: the first pass's sweep
 * buffer's row), the dimension a constant in 2-D (the same operations,
 * so the same bits); @p vp valid (the sweep's caller checked it) */
void vsph_viscous_pvwf_finish_rows(const struct vsph_viscous_props *vp,
                                   struct vsph_viscous_ws *ws, size_t i0,
                                   size_t i1, const double *t);

#endif /* VSPH_SOLVER_VISCOUS_INTERNAL_H */
