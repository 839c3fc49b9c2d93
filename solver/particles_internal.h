/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_SOLVER_PARTICLES_INTERNAL_H
#define VSPH_SOLVER_PARTICLES_INTERNAL_H

/* A set's per-particle arrays of doubles as one list, so that whatever
 * moves particles (vsph_particles_permute, the ghost walls' compaction in
 * solver/walls.c) moves the same fields. Within solver/ only. */

#include "particles.h"

/* The most double arrays a set holds: pos, vel, acc, tvel and bacc per
 * component, and m, rho, vol, p, drho, e and de. */
#define VSPH_PARTICLES_DOUBLES (5 * 3 + 7)

/* The double arrays set @p p has (those it lacks, NULL, left out; the
 * components below its dimension) into @p f. Returns how many. The bytes
 * of mat and the indices of id are not among them. */
int vsph_particles_doubles(const struct vsph_particles *p,
                           double *f[VSPH_PARTICLES_DOUBLES]);

#endif /* VSPH_SOLVER_PARTICLES_INTERNAL_H */
