/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_WALLS_INTERNAL_H
#define VSPH_SOLVER_WALLS_INTERNAL_H

/* The ghosts' making for a set the caller owns whole (the integrator's).
 * Within solver/ only. */

#include "particles.h"
#include "walls.h"

/* vsph_walls_generate whose compaction moves the set's own arrays
 * (vsph_particles_move) through @p perm (p->n entries) and the spare
 * block *@p spare (vsph_cells_lend gives both) instead of shifting every
 * array in place: the same particles in the same order. */
int vsph_walls_generate_moved(const struct vsph_walls *w,
                              struct vsph_particles *p, size_t n_fluid,
                              double reach, struct vsph_walls_ghosts *gh,
                              size_t *perm, void **spare);

#endif /* VSPH_SOLVER_WALLS_INTERNAL_H */
