/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_PARTICLES_H
#define VSPH_SOLVER_PARTICLES_H

#include <stddef.h>

#include "../common/api.h"

/** @file particles.h
 *  @brief Particle state in structure-of-arrays form (STYLE B6). This module
 *  owns every particle array; cell lists and workspaces only index into it.
 *  Components k >= dim of the vector fields are NULL. No I/O. */

/** Particle set: one 64-byte aligned array per field, double throughout. */
struct vsph_particles {
  size_t n;           /*!< live particles */
  size_t cap;         /*!< allocated length, a multiple of 8 */
  int dim;            /*!< 1, 2 or 3 */
  double *pos[3];     /*!< pos[k][i]: coordinate k of particle i (m) */
  double *vel[3];     /*!< velocity (m/s) */
  double *acc[3];     /*!< acceleration or force density scratch */
  double *m;          /*!< mass (kg per unit depth in 2-D) */
  double *rho;        /*!< density (kg/m^d) */
  double *vol;        /*!< volume V = m/rho, refreshed by _refresh_vol */
  double *p;          /*!< pressure (Pa) */
  double *drho;       /*!< density rate (kg/m^d/s) */
  double *e;          /*!< specific internal energy (J/kg): NULL but for the
                           gas law (vsph_particles_energy_alloc) */
  double *de;         /*!< its rate (W/kg); NULL with e */
  double *tvel[3];    /*!< transport velocity (m/s): NULL but for the
                           transport-velocity scheme (vsph_particles_tvf_alloc) */
  double *bacc[3];    /*!< its background-pressure acceleration; NULL with
                           tvel */
  unsigned char *mat; /*!< material index into the run's table (contact
                           SPH with two materials): NULL but for such runs
                           (vsph_particles_mat_alloc); NULL means 0 */
  size_t *id;         /*!< original index; survives reordering */
};

/** @brief Allocate a set for up to @p cap particles in @p dim dimensions,
 *  all fields zero, n = 0. Returns NULL (after reporting) on failure. */
VSPH_API struct vsph_particles *vsph_particles_alloc(size_t cap, int dim);

/** @brief Room for at least @p cap particles, the n live ones kept (a
 *  smaller @p cap is a no-op). @return VSPH_OK or VSPH_ENOMEM (reported;
 *  the set is unchanged in size and still valid). */
VSPH_API int vsph_particles_reserve(struct vsph_particles *p, size_t cap);

/** @brief Give the set its energy fields e and de (zero), for the gas law:
 *  other runs carry neither. A no-op when present.
 *  @return VSPH_OK or VSPH_ENOMEM (reported). */
VSPH_API int vsph_particles_energy_alloc(struct vsph_particles *p);

/** @brief Allocate the transport-velocity scheme's fields tvel and bacc
 *  (zeroed), once. @return VSPH_OK or VSPH_ENOMEM. */
VSPH_API int vsph_particles_tvf_alloc(struct vsph_particles *p);

/** @brief Allocate the material index mat (zeroed: every particle of
 *  material 0), once. @return VSPH_OK or VSPH_ENOMEM. */
VSPH_API int vsph_particles_mat_alloc(struct vsph_particles *p);

/** @brief Free a set; NULL is a no-op. */
VSPH_API void vsph_particles_free(struct vsph_particles *p);

/** @brief Set vol[i] = m[i] / rho[i] for every live particle. */
VSPH_API void vsph_particles_refresh_vol(struct vsph_particles *p);

/** @brief Reorder every field so that new index i holds old index perm[i].
 *  @param p the particles; @param perm the order (n indices).
 *  @param scratch caller buffer of at least n doubles.
 *  @param iscratch caller buffer of at least n size_t. */
VSPH_API void vsph_particles_permute(struct vsph_particles *p,
                                     const size_t *perm, double *scratch,
                                     size_t *iscratch);

#endif /* VSPH_SOLVER_PARTICLES_H */
