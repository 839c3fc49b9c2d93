/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_WALLS_H
#define VSPH_SOLVER_WALLS_H

#include <stddef.h>

#include "../common/api.h"

struct vsph_particles;

/** @file walls.h
 *  @brief Planar walls by mirrored ghost particles ("ghost fluid", THEORY
 *  section 5) and periodic boundaries by image particles, only for scenes
 *  that declare them. A fluid particle within reach of a plane gets an
 *  image across it (and across every combination of the planes it is near,
 *  corners included). Periodic planes come in pairs on one axis: an image
 *  is shifted by the period and carries the source's state unchanged.
 *
 *  Mirror planes. Free slip: the normal velocity is reversed, the
 *  tangential kept. No slip, the tangential velocity of the ghost by one of
 *  two treatments (docs/theory.md, section 9):
 *  - mirroring, u_g = 2 u_w - u_s (odd reflection about the wall's
 *    velocity u_w);
 *  - linear extrapolation [reconstructed]: the wall shear rate is fitted
 *    to the fluid nearest the wall (within `band` of the wall and within
 *    `window` of the ghost along the wall, both h; weights falling
 *    linearly to zero in both directions, least squares through the wall
 *    velocity) and the ghost at depth d behind the wall
 *    gets u_w - gamma d: a constant shear into the wall, whatever the
 *    source's own value (Basa et al. 2009, Sec. 5.2); where no fluid
 *    particle is in that window, mirroring.
 *  The normal velocity is reversed in both; a ghost across two no-slip
 *  planes (a corner) is mirrored about the mean of their velocities.
 *  Density and pressure are mirrored, with the hydrostatic correction
 *  p_g = p_s + rho0 g (y_s - y_g) under gravity. Ghosts carry ids
 *  n_fluid + g. No I/O. */

/** At most this many planes (a periodic pair counts two). */
#define VSPH_WALLS_MAX 6

/** What a plane is. */
enum vsph_walls_kind {
  VSPH_WALLS_MIRROR = 0, /*!< a wall: mirrored ghosts */
  VSPH_WALLS_PERIODIC    /*!< one end of a periodic axis: shifted images */
};

/** How no-slip ghosts get their tangential velocity. */
enum vsph_walls_velocity {
  VSPH_WALLS_VEL_MIRROR = 0, /*!< u_g = 2 u_w - u_s */
  VSPH_WALLS_VEL_LINEAR,     /*!< u_g = u_w - gamma d, gamma fitted */
  VSPH_WALLS_VEL_COUNT
};

/** Fixed wall particles (solid != 0): how they get their state. */
enum vsph_walls_solid {
  VSPH_WALLS_GHOSTS = 0, /*!< none: mirrored ghosts per step */
  VSPH_WALLS_ADAMI,      /*!< Adami, Hu & Adams (2012): pressure and
                              velocity Shepard-averaged from the fluid,
                              each evaluation (the linear law) */
  VSPH_WALLS_EVOLVING,   /*!< Basa, Quinlan & Lastiwka (2009), cavity:
                              density by continuity (integrated), pressure
                              by the run's law, tangential velocity
                              extrapolated linearly into the wall */
  VSPH_WALLS_FIXED,      /*!< Vukcevic et al.: fixed particles at the
                              wall's own velocity, density summed as the
                              fluid's (or rho0), pressure by the run's law;
                              periodic axes allowed (the fluid imaged) */
  VSPH_WALLS_SOLID_COUNT
};

/** @brief Name of a wall-particle model ("ghosts", "adami", "evolving",
 *  "fixed"). */
VSPH_API const char *vsph_walls_solid_name(int s);

/** @brief Wall-particle model called @p name into @p s (adami, evolving,
 *  fixed).
 *  @return VSPH_OK, or VSPH_EINVAL naming the choices. */
VSPH_API int vsph_walls_solid_resolve(const char *name, int *s);

/** Wall set of a scene. */
struct vsph_walls {
  int n;                        /*!< number of planes */
  int axis[VSPH_WALLS_MAX];     /*!< axis normal to the plane */
  double pos[VSPH_WALLS_MAX];   /*!< plane coordinate (m) */
  int side[VSPH_WALLS_MAX];     /*!< +1: fluid at larger coordinate, -1 less */
  int kind[VSPH_WALLS_MAX];     /*!< vsph_walls_kind */
  double uw[VSPH_WALLS_MAX][3]; /*!< wall velocity (tangential; m/s) */
  int noslip;                   /*!< 1: no slip, 0: free slip */
  int velocity;                 /*!< vsph_walls_velocity (no slip) */
  double band;                  /*!< linear: the nearest row, depth (m) */
  double window;                /*!< linear: half-width along the wall (m) */
  double g;                     /*!< gravity along -e_d for the correction */
  int solid;       /*!< vsph_walls_solid: non-zero, fixed wall particles outside
                        a box of mirror planes, not mirrored ghosts */
  double dx;       /*!< solid: their lattice spacing, the fluid's (m); set by
                        the integrator from the fluid's volume */
  double rho0, c0; /*!< state equation for the ghost density */
};

/** Ghost bookkeeping, owned by the caller (sized by vsph_walls_count). */
struct vsph_walls_ghosts {
  size_t cap;     /*!< capacity */
  size_t n;       /*!< ghosts made by the last _generate */
  size_t *src;    /*!< source fluid id of ghost g */
  unsigned *mask; /*!< bit w set: imaged across plane w */
  /* linear extrapolation only: the nearest rows, refreshed per update */
  double *band; /*!< per entry: coordinates (3), shear terms (3), depth */
  size_t nband[VSPH_WALLS_MAX];  /*!< entries of plane w */
  size_t bstart[VSPH_WALLS_MAX]; /*!< first entry of plane w */
  /* the entries of each plane binned along its first tangential axis, in
   * bins at least `window` wide, so that a ghost's fit visits the three
   * bins around it instead of the whole row (the same entries in the
   * same order: the same bits) */
  size_t *bent;                  /*!< each plane's entries (from 0), bin
                                      by bin, ascending within a bin */
  size_t *bfirst;                /*!< per bin: its first slot in bent */
  size_t boff[VSPH_WALLS_MAX];   /*!< plane w's first bin in bfirst */
  size_t nbin[VSPH_WALLS_MAX];   /*!< plane w's bins; 0: not binned */
  int baxis[VSPH_WALLS_MAX];     /*!< the binned axis */
  double bx0[VSPH_WALLS_MAX];    /*!< its origin (m) */
  double bwidth[VSPH_WALLS_MAX]; /*!< the bins' width (m) */
  double bper[VSPH_WALLS_MAX];   /*!< its period (m); 0: not periodic */
  size_t keep; /*!< fixed wall particles (ids n_fluid .. n_fluid + keep - 1)
                    kept by _generate; the ghosts' ids follow them. With
                    a solid set only its periodic planes image the fluid */
};

/** @brief Name of a wall-velocity treatment ("mirror", "linear"). */
VSPH_API const char *vsph_walls_velocity_name(int v);

/** @brief Treatment called @p name into @p v.
 *  @return VSPH_OK, or VSPH_EINVAL naming the choices. */
VSPH_API int vsph_walls_velocity_resolve(const char *name, int *v);

/** @brief Append a periodic pair on @p axis: images across [lo, hi).
 *  @return VSPH_OK or VSPH_EINVAL (no room, hi <= lo). */
VSPH_API int vsph_walls_add_periodic(struct vsph_walls *w, int axis, double lo,
                                     double hi);

/** @brief The period of @p axis (m), or 0 if it is not periodic. */
VSPH_API double vsph_walls_period(const struct vsph_walls *w, int axis);

/** @brief Bring every fluid particle (id < n_fluid) back into the periodic
 *  range of each periodic axis. */
VSPH_API void vsph_walls_wrap(const struct vsph_walls *w,
                              struct vsph_particles *p, size_t n_fluid);

/** @brief Ghost bookkeeping for up to @p cap ghosts of wall set @p w (the
 *  nearest-row scratch only for linear extrapolation). NULL on failure. */
VSPH_API struct vsph_walls_ghosts *vsph_walls_ghosts_alloc(
    const struct vsph_walls *w, size_t cap);

/** @brief Free; NULL is a no-op. */
VSPH_API void vsph_walls_ghosts_free(struct vsph_walls_ghosts *gh);

/** @brief How many ghosts vsph_walls_generate would make now. */
VSPH_API size_t vsph_walls_count(const struct vsph_walls *w,
                                 const struct vsph_particles *p, size_t n_fluid,
                                 double reach);

/** @brief Drop the ghosts (ids >= n_fluid) and append fresh images of
 *  every fluid particle within @p reach of a plane. The particles kept
 *  close up in their order, each with every field the set has.
 *  @return VSPH_OK or VSPH_ENOMEM (particle or ghost capacity exceeded). */
VSPH_API int vsph_walls_generate(const struct vsph_walls *w,
                                 struct vsph_particles *p, size_t n_fluid,
                                 double reach, struct vsph_walls_ghosts *gh);

/** @brief Refresh every ghost from its source. @p where maps every id of
 *  the set, the ghosts' included (every id below n_fluid + gh->keep +
 *  gh->n), to its current index, as the set stands now (after the last
 *  vsph_walls_generate and any reordering since); a ghost whose entry
 *  names a slot that does not hold it is not refreshed. */
VSPH_API void vsph_walls_update(const struct vsph_walls *w,
                                struct vsph_particles *p, size_t n_fluid,
                                struct vsph_walls_ghosts *gh,
                                const size_t *where);

/* Fixed wall particles (Adami, Hu & Adams 2012; docs/theory.md section 9).
 * The planes of a solid wall set bound a box, two per axis: the fluid's
 * lattice, spacing dx at (i + 1/2) dx from the box's low corner, continued
 * outward by ceil(reach/dx) layers, every lattice point outside the box a
 * wall particle (corners included), laid once; the equations give them
 * their state from the fluid each evaluation
 * (vsph_equations_walls_adami). */

/** @brief How many wall particles vsph_walls_solid_generate lays, or 0 when
 *  the planes do not bound a box in @p dim dimensions. */
VSPH_API size_t vsph_walls_solid_count(const struct vsph_walls *w, int dim,
                                       double dx, double reach);

/** @brief Append the wall particles (ids n_fluid + g, mass rho0 dx^d, at
 *  rest, density rho0) behind the fluid.
 *  @return VSPH_OK, VSPH_EINVAL (no box) or VSPH_ENOMEM (capacity). */
VSPH_API int vsph_walls_solid_generate(const struct vsph_walls *w,
                                       struct vsph_particles *p, size_t n_fluid,
                                       double dx, double reach);

/** @brief Prescribed velocity @p u of the wall particle at @p x: that of
 *  the first moving plane (in the set's order) it lies behind, else 0. A
 *  particle behind a moving plane moves with it, corners included, as in
 *  Adami et al. (2013)'s cavity [reconstructed]. */
VSPH_API void vsph_walls_solid_velocity(const struct vsph_walls *w, int dim,
                                        const double x[3], double u[3]);

/** @brief Velocities of evolving wall particles (VSPH_WALLS_EVOLVING,
 *  Basa et al. 2009: "tangential velocities extrapolated normally to the
 *  wall"), [reconstructed] as the channels' linear extrapolation: a wall
 *  particle behind one plane at depth d gets the tangential velocity
 *  u_w - gamma d, gamma fitted to the fluid's nearest rows within the
 *  window along the wall (vsph_walls_generate's fit), and the normal
 *  velocity the prescribed (0: a plane moves along itself); one behind
 *  two planes (a corner), or with no fluid in its
 *  window, its prescribed velocity (vsph_walls_solid_velocity). @p gh
 *  holds the rows' scratch (vsph_walls_ghosts_alloc with the linear
 *  velocity, capacity at least w->n n_fluid: a particle can lie in every
 *  plane's rows). Serial rows, then each wall
 *  particle by itself: the same for any thread count. */
VSPH_API void vsph_walls_solid_extrapolate(const struct vsph_walls *w,
                                           struct vsph_particles *p,
                                           size_t n_fluid,
                                           struct vsph_walls_ghosts *gh);

#endif /* VSPH_SOLVER_WALLS_H */
