/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_POISSON_H
#define VSPH_SOLVER_POISSON_H

#include <stddef.h>

/** @file poisson.h
 *  @brief Dirichlet Poisson problem lap p = f on the square
 *  [-L/2, L/2]^2 by FFTW's 2-D sine transform (RODFT00) of the 5-point
 *  Laplacian, boundary data moved to the right-hand side. Used for the
 *  stretching square's initial pressure (THEORY 6.2). Opaque
 *  plan/execute/destroy object in the FFTW manner (STYLE B5). No I/O. */

/** Opaque solver: grid, boundary data, FFTW plan. */
struct vsph_poisson;

/** Boundary edges. */
enum vsph_poisson_edge {
  VSPH_POISSON_WEST = 0, /*!< x = -L/2 */
  VSPH_POISSON_EAST,     /*!< x = +L/2 */
  VSPH_POISSON_SOUTH,    /*!< y = -L/2 */
  VSPH_POISSON_NORTH,    /*!< y = +L/2 */
  VSPH_POISSON_EDGE_COUNT
};

/** Signature of the right-hand side or boundary data f(x, y). */
typedef double vsph_poisson_fn(double x, double y, void *ctx);

/** @brief Solver for @p n x @p n interior nodes on a square of side
 *  @p side (spacing side/(n+1)); plans with FFTW_ESTIMATE.
 *  @note Call outside parallel regions. NULL (after reporting) on failure.*/
struct vsph_poisson *vsph_poisson_alloc(size_t n, double side);

/** @brief Free; NULL is a no-op. */
void vsph_poisson_free(struct vsph_poisson *ps);

/** @brief Solve lap p = f inside with p = g on the boundary. f is sampled
 *  at the interior nodes, g at the boundary nodes, corners included (they
 *  enter only the interpolation; where the data jump at a corner, g decides
 *  the corner value).
 *  @return VSPH_OK or VSPH_EINVAL (non-finite data). */
int vsph_poisson_solve(struct vsph_poisson *ps, vsph_poisson_fn *f,
                       vsph_poisson_fn *g, void *ctx);

/** @brief The solution at node (i, j), 0 <= i, j <= n+1 (boundary ring
 *  included), at x = -L/2 + i h, y = -L/2 + j h. */
double vsph_poisson_node(const struct vsph_poisson *ps, size_t i, size_t j);

/** @brief Bilinear interpolation of the solution at (x, y), clamped to the
 *  square. */
double vsph_poisson_interp(const struct vsph_poisson *ps, double x, double y);

/** @brief Grid spacing side/(n+1). */
double vsph_poisson_spacing(const struct vsph_poisson *ps);

#endif /* VSPH_SOLVER_POISSON_H */
