#ifndef VSPH_SOLVER_WALLS_H
#define VSPH_SOLVER_WALLS_H

#include <stddef.h>

struct vsph_particles;

/** @file walls.h
 *  @brief Planar walls by mirrored ghost particles ("ghost fluid", THEORY
 *  section 5), only for scenes that declare walls. A fluid particle within
 *  reach of a wall gets an image across it (and across both walls near a
 *  corner). Free slip: the normal velocity is reversed, the tangential kept;
 *  no slip: the velocity is reversed. Density and pressure are mirrored,
 *  with the hydrostatic correction p_g = p_s + rho0 g (y_s - y_g) under
 *  gravity. Ghosts carry ids n_fluid + g. No I/O. */

/** At most this many planes. */
#define VSPH_WALLS_MAX 4

/** Wall set of a scene. */
struct vsph_walls {
  int n;                      /*!< number of planes */
  int axis[VSPH_WALLS_MAX];   /*!< axis normal to the plane */
  double pos[VSPH_WALLS_MAX]; /*!< plane coordinate (m) */
  int side[VSPH_WALLS_MAX];   /*!< +1: fluid at larger coordinate, -1 less */
  int noslip;                 /*!< 1: no slip, 0: free slip */
  double g;                   /*!< gravity along -e_d for the correction */
  double rho0, c0;            /*!< state equation for the ghost density */
};

/** Ghost bookkeeping, owned by the caller (sized by vsph_walls_count). */
struct vsph_walls_ghosts {
  size_t cap;     /*!< capacity */
  size_t n;       /*!< ghosts made by the last _generate */
  size_t *src;    /*!< source fluid id of ghost g */
  unsigned *mask; /*!< bit w set: mirrored across plane w */
};

/** @brief Ghost bookkeeping for up to @p cap ghosts. NULL on failure. */
struct vsph_walls_ghosts *vsph_walls_ghosts_alloc(size_t cap);

/** @brief Free; NULL is a no-op. */
void vsph_walls_ghosts_free(struct vsph_walls_ghosts *gh);

/** @brief How many ghosts vsph_walls_generate would make now. */
size_t vsph_walls_count(const struct vsph_walls *w,
                        const struct vsph_particles *p, size_t n_fluid,
                        double reach);

/** @brief Drop the ghosts (ids >= n_fluid) and append fresh images of
 *  every fluid particle within @p reach of a wall.
 *  @return VSPH_OK or VSPH_ENOMEM (particle or ghost capacity exceeded). */
int vsph_walls_generate(const struct vsph_walls *w, struct vsph_particles *p,
                        size_t n_fluid, double reach,
                        struct vsph_walls_ghosts *gh);

/** @brief Refresh every ghost from its source; @p where maps an id to its
 *  current index. */
void vsph_walls_update(const struct vsph_walls *w, struct vsph_particles *p,
                       size_t n_fluid, const struct vsph_walls_ghosts *gh,
                       const size_t *where);

#endif /* VSPH_SOLVER_WALLS_H */
