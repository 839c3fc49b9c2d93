/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_DIAGNOSTICS_H
#define VSPH_SOLVER_DIAGNOSTICS_H

#include <signal.h>
#include <stddef.h>

#include "../common/api.h"

struct vsph_particles;
struct vsph_kernel_type;
struct vsph_cells;

/** @file diagnostics.h
 *  @brief Per-particle fields for pictures and snapshots, not used by the
 *  time stepping: the SPH vorticity
 *    omega_i = sum_j V_j grad_i W_ij x (u_j - u_i),
 *  and the divergence of the position
 *    (div r)_i = sum_j V_j (r_j - r_i).grad_i W_ij,
 *  which is d inside the fluid (to the lattice error) and falls towards
 *  d/2 at a free surface, with the free-surface flag (div r)_i below a
 *  threshold (docs/theory.md section 5: 1.5 in 2-D, 2.4 in 3-D, as in Lee
 *  et al. 2008). Both sums run over the pair iterator of solver/pair.h,
 *  on a sorted copy of the set (or on the set as its own cell list sorted
 *  it), so the caller's particles are neither moved nor reordered (a run's
 *  results do not depend on whether it wrote snapshots); each particle's
 *  neighbours are summed in the order of their offsets, so the fields do
 *  not depend on the particles' order either. No I/O. A NULL argument is
 *  refused with VSPH_EINVAL (reported); vsph_diagnostics_free of NULL
 *  does nothing. */

/** Diagnostics of the particles with id < n, indexed by id. */
struct vsph_diagnostics {
  size_t n;            /*!< particles described */
  int dim;             /*!< 1, 2 or 3 */
  double *vort[3];     /*!< vorticity; 2-D: vort[2] only (the others
                            NULL); 1-D: none */
  double *divr;        /*!< div r */
  unsigned char *surf; /*!< 1: free surface (div r below the threshold) */
  double h;            /*!< the smoothing length they were computed with */
  int lent;            /*!< 1: divr and vort are the caller's (room of
                            vsph_diagnostics_compute_cells), not freed */
};

/** @brief The free-surface threshold on div r in @p dim dimensions (1-3;
 *  NaN for another). */
VSPH_API double vsph_diagnostics_surface_threshold(int dim);

/** @brief Compute the diagnostics of the particles of @p p whose id is
 *  below @p n (the fluid; the others, e.g. ghosts, count as neighbours),
 *  with kernel @p k and smoothing length @p h (m), into @p d (allocated
 *  here; free with vsph_diagnostics_free).
 *  Non-finite positions (a run stopped as unstable) give NaN fields.
 *  If @p stop is not NULL, *stop is checked first and before each cell:
 *  once it is set the sums are abandoned.
 *  @return VSPH_OK, VSPH_EINVAL (a NULL argument, h <= 0, or @p n above
 *  the set's particles), VSPH_EINTR (stopped through @p stop; @p d
 *  freed) or VSPH_ENOMEM. */
VSPH_API int vsph_diagnostics_compute(const struct vsph_particles *p, size_t n,
                                      const struct vsph_kernel_type *k,
                                      double h, struct vsph_diagnostics *d,
                                      const volatile sig_atomic_t *stop);

/** @brief vsph_diagnostics_compute of particles @p p that @p cells sorted
 *  (as an evaluation leaves an integrator's particles: its cell list for
 *  them, at a reach of at least the kernel's), with no copy and no cell
 *  list of its own. The same bits as vsph_diagnostics_compute: each
 *  particle's sums run over its neighbours in the order of their offsets,
 *  whatever the particles' order. With @p room not NULL, div r and the
 *  vorticity are written there, not allocated: room[0] div r, room[1]
 *  omega_z, and in 3-D room[2] and room[3] omega_x and omega_y, each of
 *  at least @p n doubles (a run's rates between two steps, which every
 *  evaluation writes before it reads them: vsph_run's `evaluated`).
 *  @return as vsph_diagnostics_compute, or VSPH_EINVAL (cells narrower
 *  than the kernel's reach, or not @p p's). */
VSPH_API int vsph_diagnostics_compute_cells(
    const struct vsph_particles *p, size_t n, const struct vsph_cells *cells,
    const struct vsph_kernel_type *k, double h, double *const room[4],
    struct vsph_diagnostics *d, const volatile sig_atomic_t *stop);

/** A probe's reading at a point. */
struct vsph_diagnostics_probe {
  double u[3]; /*!< velocity (m/s); 2-D: u[2] = 0 (NaN as the rest where
                    no particle is within reach) */
  double p;    /*!< pressure (Pa) */
  double rho;  /*!< density */
  double fill; /*!< sum_j V_j W(x - x_j): near 1 inside the fluid, about
                    1/2 at a free surface or a wall, 0 outside */
};

/** @brief Read the fluid (the particles of @p p whose id is below @p n)
 *  at @p x by the Shepard-normalised kernel interpolation
 *    f(x) = sum_j V_j f_j W(x - x_j) / sum_j V_j W(x - x_j)
 *  (kernel @p k, smoothing length @p h), every fluid particle visited in
 *  index order; a distance along an axis whose @p period[a] > 0 is taken
 *  to the nearest image. Where no particle is within reach, u, p and rho
 *  are NaN and fill 0.
 *  @return VSPH_OK, or VSPH_EINVAL for a NULL argument or h <= 0. */
VSPH_API int vsph_diagnostics_probe(const struct vsph_particles *p, size_t n,
                                    const struct vsph_kernel_type *k, double h,
                                    const double period[3], const double x[3],
                                    struct vsph_diagnostics_probe *out);

/** @brief Free the arrays of @p d (the struct itself is the caller's). */
VSPH_API void vsph_diagnostics_free(struct vsph_diagnostics *d);

#endif /* VSPH_SOLVER_DIAGNOSTICS_H */
