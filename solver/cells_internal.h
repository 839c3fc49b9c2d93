/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_CELLS_INTERNAL_H
#define VSPH_SOLVER_CELLS_INTERNAL_H

/* The cell list's build for a set the caller owns whole (the
 * integrator's): its particles moved by swapping arrays
 * (vsph_particles_move), and the cell list's scratch lent between builds.
 * Within solver/ only. */

#include "cells.h"
#include "particles.h"

/* Below this many particles the build's loops run on one thread (the
 * result is the same). */
#define VSPH_CELLS_PARALLEL 4096

/* vsph_cells_build for a set whose arrays are its own (from
 * vsph_particles_alloc and _reserve, nothing keeping a pointer to them
 * across the build): the same cells and the same order, the particles
 * moved without copying each array back. Afterwards, @p c's scratch
 * block is one of the set's former arrays. */
int vsph_cells_build_owned(struct vsph_cells *c, struct vsph_particles *p,
                           double radius);

/* The cell list's scratch between builds, for a move of @p p's particles
 * (vsph_particles_move): a permutation of p->cap entries into *@p perm,
 * and the spare block's pointer into *@p spare (the move updates it).
 * What they hold is the caller's until the next build. */
int vsph_cells_lend(struct vsph_cells *c, const struct vsph_particles *p,
                    size_t **perm, void ***spare);

#endif /* VSPH_SOLVER_CELLS_INTERNAL_H */
