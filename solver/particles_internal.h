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

/* Below this many particles a move runs on one thread: a parallel
 * region's wake-up costs more than it saves (the result is the same). */
#define VSPH_PARTICLES_MOVE_PARALLEL 4096

/* The blocks of 8 bytes a particle that vsph_particles_move swaps: from
 * the allocation the set's own arrays come from (64-byte aligned), of
 * @p cap entries; NULL on failure. */
void *vsph_particles_spare_alloc(size_t cap);

/* Move set @p p's particles so that new index k holds old index perm[k],
 * for k < @p n (n <= p->n: the others are dropped), and set p->n = n:
 * vsph_particles_permute without its copies back. Each array is gathered
 * into the spare block *@p spare (vsph_particles_spare_alloc(p->cap) or
 * one of the set's own arrays) and takes its place; the array it replaces
 * becomes the spare, so every array and the spare keep p->cap entries.
 * In parallel over the particles (each entry one move: the same result
 * for any thread count). The set's arrays must be its own (a set from
 * vsph_particles_alloc and _reserve), and nothing may keep a pointer to
 * them across the move. */
void vsph_particles_move(struct vsph_particles *p, const size_t *perm, size_t n,
                         void **spare);

#endif /* VSPH_SOLVER_PARTICLES_INTERNAL_H */
