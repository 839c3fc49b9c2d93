/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_H
#define VSPH_H

/** @file vsph.h
 *  @brief libvsph's front door: what another SPH code needs to use vsph's
 *  analysis and references inside its own regression tests, one include.
 *
 *  Installed as <vsph/vsph.h> (`make install`); compile and link with
 *  `pkg-config --cflags --libs vsph` (examples/regression shows a whole
 *  program). Every function returns a status (common/status.h) and never
 *  exits; errors go to a replaceable handler, vsph_status_set_handler.
 *
 *  - Kernels (kernels/kernel.h): the table of smoothing kernels, looked
 *    up by name (vsph_kernel_find), their shapes and derivatives.
 *  - Moment tensors (analysis/moments.h): F, G, N, M of a kernel on the
 *    full or half support at any depth, by quadrature
 *    (vsph_moments_quadrature) and by particle sums (vsph_moments_sum),
 *    and the theory's values (vsph_moments_theory).
 *  - Scaling (analysis/scaling.h): the 1/h truncation error of each
 *    viscous formulation at a free surface.
 *  - Dissipation (analysis/dissipation.h): P = sum_i V_i u_i.(div V)_i of
 *    any formulation for a particle set of yours
 *    (vsph_dissipation_particles), or for vsph's discs and squares
 *    against the exact integral (vsph_dissipation_compute).
 *  - Exact references (analysis/references.h): the vortex patch's Bessel
 *    series, the start-up Poiseuille and Couette series, Lighthill's
 *    damped standing wave, Ghia et al.'s cavity tables.
 *  - The solver's run driver (solver/run.h): a scene, a formulation and a
 *    time loop, vsph_run_alloc / vsph_run_iterate / vsph_run_row, with
 *    no file written.
 *
 *  The other public headers install beside this one, each included by
 *  name (docs/library.md): the integrator, the materials and the
 *  per-particle diagnostics (solver/), the energy-series measures,
 *  contact SPH's viscosity and the Laplacian patch test (analysis/), the
 *  writers and readers (io/: files, CSV, JSON, VTK, gnuplot figures) and
 *  the machine's facts beside a timing (common/sysinfo.h).
 *
 *  Names: every symbol starts with vsph_<module>_ (REBOUND's rule). */

/* C linkage for a C++ program; the includes are one block, which
 * clang-format sorts within it (a blank line apart from the guards) */
#ifdef __cplusplus
extern "C" {
#endif

#include "analysis/dissipation.h"
#include "analysis/fields.h"
#include "analysis/moments.h"
#include "analysis/references.h"
#include "analysis/scaling.h"
#include "common/consts.h"
#include "common/params.h"
#include "common/status.h"
#include "kernels/kernel.h"
#include "solver/cells.h"
#include "solver/lattice.h"
#include "solver/particles.h"
#include "solver/run.h"
#include "solver/scene.h"
#include "solver/viscous.h"

#ifdef __cplusplus
}
#endif

#endif /* VSPH_H */
