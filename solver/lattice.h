/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_LATTICE_H
#define VSPH_SOLVER_LATTICE_H

#include <stddef.h>

#include "../common/api.h"

struct vsph_particles;

/** @file lattice.h
 *  @brief Particle sets on lattices: a half-space patch around one particle
 *  (for the moment tensors and the surface scaling), a square and a disc of
 *  concentric rings (for the dissipation integrals and the scenes). Every
 *  particle gets rho = 1, m = vol = its lattice volume, zero velocity.
 *  No I/O. */

/** Lattice arrangement. */
enum vsph_lattice_kind {
  VSPH_LATTICE_SQUARE = 0, /*!< square (1-D line, 3-D cubic) */
  VSPH_LATTICE_HEX,        /*!< hexagonal, 2-D only, rows parallel to x */
  VSPH_LATTICE_KIND_COUNT
};

/** How to lay the particles. */
struct vsph_lattice_props {
  int dim;                     /*!< 1, 2 or 3 */
  enum vsph_lattice_kind kind; /*!< arrangement */
  double dx;                   /*!< spacing: particle volume is dx^dim (m) */
  double perturb;              /*!< random shift amplitude, fraction of dx */
  unsigned long seed;          /*!< seed of the mt19937 generator */
};

/** @brief Name of a lattice kind ("square", "hex"). */
VSPH_API const char *vsph_lattice_name(int kind);

/** @brief What a lattice is called in outputs: "perturbed" when
 *  @p perturb > 0 (vsph_lattice_resolve's amplitude), else its kind's
 *  name. */
VSPH_API const char *vsph_lattice_label(int kind, double perturb);

/** @brief Kind called @p name, or -1. */
VSPH_API int vsph_lattice_find(const char *name);

/** @brief Resolve a lattice named @p name ("square", "hex" or "perturbed",
 *  the square lattice shifted by up to @p perturb dx per component) in
 *  dimension @p dim into a kind and a perturbation amplitude (0 unless
 *  perturbed). @return VSPH_OK or VSPH_EINVAL (unknown name, hex outside
 *  2-D, perturb outside [0, 0.5)). */
VSPH_API int vsph_lattice_resolve(const char *name, int dim, double perturb,
                                  int *kind, double *amp);

/** @brief Lattice nodes x with |x| <= radius and x_d <= depth (x_d the last
 *  coordinate), the origin being a node and particle @p centre. The centre
 *  is never perturbed; the others move by up to perturb*dx per component
 *  (uniform). Rows that lie exactly at x_d = depth are kept.
 *  @param lp the lattice (kind, dimension, spacing dx, perturbation).
 *  @param radius the ball's radius (m); @param depth the plane's x_d (m).
 *  @param out receives a new set (free with vsph_particles_free).
 *  @param centre receives the centre particle's index.
 *  @return VSPH_OK, VSPH_EINVAL (bad props), VSPH_ENOMEM. */
VSPH_API int vsph_lattice_halfspace(const struct vsph_lattice_props *lp,
                                    double radius, double depth,
                                    struct vsph_particles **out,
                                    size_t *centre);

/** @brief Shift every particle (except index @p skip; pass (size_t)-1 for
 *  none) by a uniform random amount in [-amp, amp] per component, from an
 *  mt19937 generator seeded with @p seed. @return VSPH_OK or VSPH_ENOMEM. */
VSPH_API int vsph_lattice_perturb(struct vsph_particles *p, double amp,
                                  unsigned long seed, size_t skip);

/** @brief Square (2-D) of side @p side centred at the origin with
 *  @p nacross particles along each edge at the cell centres (spacing
 *  side/nacross; lp->dx is ignored). */
VSPH_API int vsph_lattice_square(const struct vsph_lattice_props *lp,
                                 double side, size_t nacross,
                                 struct vsph_particles **out);

/** @brief Disc (2-D) of radius @p radius centred at the origin, made of
 *  nacross/2 concentric rings of width dr = 2R/nacross; ring k at radius
 *  (k + 1/2) dr holds round(2 pi r_k / dr) particles of equal volume, so
 *  the volumes add up to pi R^2 exactly. lp->dx is ignored. */
VSPH_API int vsph_lattice_disc(const struct vsph_lattice_props *lp,
                               double radius, size_t nacross,
                               struct vsph_particles **out);

/** @brief Disc (2-D) of radius @p radius cut from a square lattice of
 *  spacing dx = 2R/nacross: the nodes ((a + 1/2) dx - R, (b + 1/2) dx - R)
 *  with r < R, each of volume dx^2 (so the volumes add up to pi R^2 only
 *  to O(dx)). The layout whose lattice error converges for azimuthal
 *  shear (docs/theory.md, section 6). lp->dx is ignored. */
VSPH_API int vsph_lattice_disc_cartesian(const struct vsph_lattice_props *lp,
                                         double radius, size_t nacross,
                                         struct vsph_particles **out);

#endif /* VSPH_SOLVER_LATTICE_H */
