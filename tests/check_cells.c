/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../solver/cells.h"
#include "../solver/cells_internal.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/particles_internal.h"
#include "../solver/share_internal.h"
#include "check_suites.h"

static double total_volume(const struct vsph_particles *p) {
  double v = 0.0;
  for (size_t i = 0; i < p->n; i++) v += p->vol[i];
  return v;
}

/* Lattice sets carry exactly the volume of their shape. */
START_TEST(test_lattice_volumes) {
  struct vsph_lattice_props lp = {.dim = 2,
                                  .kind = VSPH_LATTICE_SQUARE,
                                  .dx = 0.1,
                                  .perturb = 0.2,
                                  .seed = 7};
  struct vsph_particles *p = NULL;
  ck_assert_int_eq(vsph_lattice_square(&lp, 1.2348, 37, &p), 0);
  ck_assert_uint_eq(p->n, 37 * 37);
  /* tol: 1369 additions of equal terms, rounding ~ 1e-13 relative */
  ck_assert_double_eq_tol(total_volume(p), 1.2348 * 1.2348, 1e-12);
  vsph_particles_free(p);
  ck_assert_int_eq(vsph_lattice_disc(&lp, 0.6180, 50, &p), 0);
  ck_assert_double_eq_tol(total_volume(p), VSPH_PI * 0.6180 * 0.6180, 1e-12);
  for (size_t i = 0; i < p->n; i++) /* ring particles stay near the disc */
    ck_assert_double_le(hypot(p->pos[0][i], p->pos[1][i]),
                        0.6180 + 0.3 * 0.6180 / 25);
  vsph_particles_free(p);
}
END_TEST

/* Cartesian disc: every node inside, the set symmetric (centroid at the
 * origin to rounding), and the volume within the band of cells the circle
 * cuts: |n dx^2 - pi R^2| <= 2 pi R sqrt(2) dx (each cut cell lies within
 * half a diagonal of the circle). */
START_TEST(test_disc_cartesian) {
  struct vsph_lattice_props lp = {.dim = 2};
  struct vsph_particles *p = NULL;
  const double R = 0.6180;
  const size_t nacross = 50;
  const double dx = 2 * R / (double)nacross;
  ck_assert_int_eq(vsph_lattice_disc_cartesian(&lp, R, nacross, &p), 0);
  double sx = 0, sy = 0;
  for (size_t i = 0; i < p->n; i++) {
    ck_assert_double_lt(hypot(p->pos[0][i], p->pos[1][i]), R);
    ck_assert_double_eq_tol(p->vol[i], dx * dx, 1e-15);
    sx += p->pos[0][i];
    sy += p->pos[1][i];
  }
  ck_assert_double_le(fabs(sx) + fabs(sy), 1e-12);
  ck_assert_double_le(fabs(total_volume(p) - VSPH_PI * R * R),
                      2 * VSPH_PI * R * sqrt(2.0) * dx);
  ck_assert_uint_gt(p->n, 0.9 * VSPH_PI * 25 * 25);
  vsph_particles_free(p);
  vsph_test_silence();
  ck_assert_int_ne(vsph_lattice_disc_cartesian(&lp, -1.0, 10, &p), 0);
}
END_TEST

/* Half-space patch: the centre is at the origin, nothing lies above the
 * depth plane, and the hexagonal lattice keeps the volume per particle. */
START_TEST(test_halfspace) {
  for (int kind = 0; kind < VSPH_LATTICE_KIND_COUNT; kind++) {
    struct vsph_lattice_props lp = {.dim = 2, .kind = kind, .dx = 0.237};
    struct vsph_particles *p = NULL;
    size_t c;
    ck_assert_int_eq(vsph_lattice_halfspace(&lp, 3.0, 0.5, &p, &c), 0);
    ck_assert(p->pos[0][c] == 0.0 && p->pos[1][c] == 0.0);
    /* count the rows below the midpoint between rows 1 and 2 under the
     * centre, so the cut falls on cell boundaries */
    const double dy = kind == VSPH_LATTICE_HEX
                          ? 0.237 * sqrt(2.0 / sqrt(3.0)) * sqrt(3.0) / 2.0
                          : 0.237;
    const double cut = 1.5 * dy;
    size_t inside = 0;
    for (size_t i = 0; i < p->n; i++) {
      ck_assert_double_le(p->pos[1][i], 0.5);
      ck_assert_double_le(hypot(p->pos[0][i], p->pos[1][i]), 3.0 + 1e-12);
      if (hypot(p->pos[0][i], p->pos[1][i]) < 2.0 && p->pos[1][i] < -cut)
        inside++;
    }
    /* area of the segment {r < 2, y < -cut} against the particle volume;
     * tol 5 %: the circular edge cuts cells (perimeter 5 dx long) */
    const double seg = 4.0 * acos(cut / 2.0) - cut * sqrt(4.0 - cut * cut);
    ck_assert_double_eq_tol((double)inside * 0.237 * 0.237 / seg, 1.0, 0.05);
    vsph_particles_free(p);
  }
  vsph_test_silence();
  struct vsph_lattice_props bad = {
      .dim = 3, .kind = VSPH_LATTICE_HEX, .dx = 0.1};
  struct vsph_particles *p = NULL;
  size_t c;
  ck_assert_int_eq(vsph_lattice_halfspace(&bad, 1.0, 0.0, &p, &c), 1);
}
END_TEST

/* Cell list against the O(N^2) path: the same neighbour pairs. Counts the
 * pairs within the radius for every particle both ways (SWIFT test27cells). */
static void count_pairs(const struct vsph_cells *c,
                        const struct vsph_particles *p, double R, size_t *out) {
  for (size_t cell = 0; cell < c->ncells; cell++) {
    size_t lo[VSPH_CELLS_MAXRANGES], hi[VSPH_CELLS_MAXRANGES];
    const size_t nr = vsph_cells_ranges(c, cell, lo, hi);
    for (size_t i = c->start[cell]; i < c->start[cell] + c->count[cell]; i++) {
      size_t n = 0;
      for (size_t r = 0; r < nr; r++)
        for (size_t j = lo[r]; j < hi[r]; j++) {
          double s2 = 0.0;
          for (int k = 0; k < p->dim; k++) {
            const double d = p->pos[k][j] - p->pos[k][i];
            s2 += d * d;
          }
          n += j != i && s2 < R * R;
        }
      out[p->id[i]] = n;
    }
  }
}

START_TEST(test_cells_vs_direct) {
  for (int dim = 1; dim <= 3; dim++) {
    struct vsph_lattice_props lp = {.dim = dim,
                                    .kind = VSPH_LATTICE_SQUARE,
                                    .dx = 0.1,
                                    .perturb = 0.3,
                                    .seed = 11};
    struct vsph_particles *p = NULL;
    size_t c0;
    ck_assert_int_eq(vsph_lattice_halfspace(&lp, 1.1, 0.35, &p, &c0), 0);
    const double R = 0.2385;
    size_t *a = calloc(p->n, sizeof *a), *b = calloc(p->n, sizeof *b);
    struct vsph_cells *c = vsph_cells_alloc();
    ck_assert_int_eq(vsph_cells_build_direct(c, p), 0);
    count_pairs(c, p, R, a);
    ck_assert_int_eq(vsph_cells_build(c, p, R), 0);
    count_pairs(c, p, R, b);
    size_t total = 0;
    for (size_t i = 0; i < p->n; i++) {
      ck_assert_uint_eq(a[i], b[i]);
      total += a[i];
    }
    ck_assert_uint_gt(total, p->n); /* the test saw real neighbours */
    /* a cell the list does not have has no ranges (the next row's or
     * layer's would wrap round into the grid) */
    size_t lo[VSPH_CELLS_MAXRANGES], hi[VSPH_CELLS_MAXRANGES];
    ck_assert_uint_gt(vsph_cells_ranges(c, c->ncells / 2, lo, hi), 0);
    ck_assert_uint_eq(vsph_cells_ranges(c, c->ncells, lo, hi), 0);
    ck_assert_uint_eq(vsph_cells_ranges(c, c->ncells + c->nc[0], lo, hi), 0);
    /* sorted by cell: each cell's particles lie inside it */
    for (size_t cell = 0; cell < c->ncells; cell++)
      for (size_t i = c->start[cell]; i < c->start[cell] + c->count[cell];
           i++) {
        const size_t ix = (size_t)floor((p->pos[0][i] - c->lo[0]) / c->edge);
        ck_assert_uint_eq(ix < c->nc[0] ? ix : c->nc[0] - 1, cell % c->nc[0]);
      }
    vsph_cells_free(c);
    free(a);
    free(b);
    vsph_particles_free(p);
  }
}
END_TEST

START_TEST(test_cells_bad_input_refused) {
  vsph_test_silence();
  struct vsph_particles *p = vsph_particles_alloc(4, 2);
  p->n = 2;
  p->pos[0][1] = NAN;
  struct vsph_cells *c = vsph_cells_alloc();
  ck_assert_int_eq(vsph_cells_build(c, p, 0.0), 1);
  ck_assert_int_eq(vsph_cells_build(c, p, 0.5), 1); /* non-finite */
  vsph_cells_free(c);
  vsph_particles_free(p);
  ck_assert_ptr_null(vsph_particles_alloc(4, 4));
}
END_TEST

/* The build's refusal names the first particle (by index) whose position
 * is not finite, whatever the threads: three NaNs, two in the first
 * thread's share and one in the second's, on 1 and 2 threads; and the
 * same particles sort alike on both (the keys are computed in parallel,
 * counted in order). */
static char last_msg[256];
static void keep_msg(int status, const char *file, int line, const char *msg) {
  (void)status, (void)file, (void)line;
  snprintf(last_msg, sizeof last_msg, "%s", msg);
}
START_TEST(test_cells_first_bad_particle_named) {
  const size_t n = 100000;
  struct vsph_particles *p = vsph_particles_alloc(n, 2);
  ck_assert_ptr_nonnull(p);
  p->n = n;
  for (size_t i = 0; i < n; i++) {
    p->pos[0][i] = (double)(i % 316) * 0.01;
    p->pos[1][i] = (double)(i / 316) * 0.01;
    p->id[i] = i + 1000;
  }
  struct vsph_cells *c = vsph_cells_alloc();
  size_t order[2][64];
  for (int thr = 1; thr <= 2; thr++) {
    omp_set_num_threads(thr);
    struct vsph_particles *q = vsph_particles_alloc(n, 2);
    q->n = n;
    for (size_t i = 0; i < n; i++) {
      q->pos[0][i] = p->pos[0][n - 1 - i];
      q->pos[1][i] = p->pos[1][n - 1 - i];
      q->id[i] = p->id[n - 1 - i];
    }
    ck_assert_int_eq(vsph_cells_build(c, q, 0.03), 0);
    for (size_t k = 0; k < 64; k++) order[thr - 1][k] = q->id[k * 1531];
    /* the box, a lone extreme at either end of a share of any thread
     * count here (the grid's origin is the least position, exactly; an
     * axis past the dimension has origin 0) */
    const size_t at[4] = {0, n / 2 - 1, n / 2, n - 1};
    for (int e = 0; e < 4; e++) {
      const size_t a = at[e], b = at[(e + 2) % 4];
      const double xa = q->pos[0][a], ya = q->pos[1][a];
      const double xb = q->pos[0][b], yb = q->pos[1][b];
      q->pos[0][a] = -0.5, q->pos[1][a] = -0.25; /* the least */
      q->pos[0][b] = 4.0, q->pos[1][b] = 5.0;    /* the greatest */
      ck_assert_int_eq(vsph_cells_build(c, q, 0.03), 0);
      ck_assert_double_eq(c->lo[0], -0.5);
      ck_assert_double_eq(c->lo[1], -0.25);
      ck_assert_double_eq(c->lo[2], 0.0);
      ck_assert_uint_eq(c->nc[0], (size_t)floor(4.5 / c->edge) + 1);
      ck_assert_uint_eq(c->nc[1], (size_t)floor(5.25 / c->edge) + 1);
      for (size_t i = 0; i < n; i++) { /* back: the build moved them */
        if (q->pos[0][i] == -0.5) q->pos[0][i] = xa, q->pos[1][i] = ya;
        if (q->pos[0][i] == 4.0) q->pos[0][i] = xb, q->pos[1][i] = yb;
      }
    }
    vsph_particles_free(q);
  }
  for (size_t k = 0; k < 64; k++) ck_assert_uint_eq(order[0][k], order[1][k]);
  p->pos[1][10] = NAN;
  p->pos[1][3] = INFINITY;
  p->pos[1][70000] = NAN;
  vsph_status_handler_fn *old = vsph_status_set_handler(keep_msg);
  for (int thr = 1; thr <= 2; thr++) {
    omp_set_num_threads(thr);
    last_msg[0] = '\0';
    ck_assert_int_eq(vsph_cells_build(c, p, 0.03), VSPH_EINVAL);
    ck_assert_msg(strstr(last_msg, "particle 1003 has a non-finite position"),
                  "%d threads: %s", thr, last_msg);
    /* the failed build leaves an empty list, not the last one's cells */
    ck_assert_uint_eq(c->ncells, 0);
    ck_assert_uint_eq(c->nblk, 0);
    ck_assert_uint_ne(c->blk_n, n);
  }
  vsph_status_set_handler(old);
  vsph_cells_free(c);
  vsph_particles_free(p);
}
END_TEST

/* A set of n particles, every array filled (tvel, bacc, e, de and mat
 * too) with values that name their particle: field a of particle i is
 * 1000 a + i + 0.25, its id 7 i + 3, its material i % 3. */
static struct vsph_particles *named_set(size_t n) {
  struct vsph_particles *p = vsph_particles_alloc(n, 2);
  ck_assert_ptr_nonnull(p);
  ck_assert_int_eq(vsph_particles_tvf_alloc(p), 0);
  ck_assert_int_eq(vsph_particles_energy_alloc(p), 0);
  ck_assert_int_eq(vsph_particles_mat_alloc(p), 0);
  p->n = n;
  double *f[VSPH_PARTICLES_DOUBLES];
  const int nd = vsph_particles_doubles(p, f);
  ck_assert_int_eq(nd, 2 * 5 + 7); /* every array a 2-D set can have */
  for (size_t i = 0; i < n; i++) {
    for (int a = 0; a < nd; a++) f[a][i] = 1000.0 * a + (double)i + 0.25;
    p->id[i] = 7 * i + 3;
    p->mat[i] = (unsigned char)(i % 3);
  }
  return p;
}

/* Particle k of @p p is particle old of named_set, every array. */
static void is_named(const struct vsph_particles *p, size_t k, size_t old) {
  double *f[VSPH_PARTICLES_DOUBLES];
  const int nd = vsph_particles_doubles(p, f);
  for (int a = 0; a < nd; a++)
    ck_assert_double_eq(f[a][k], 1000.0 * a + (double)old + 0.25);
  ck_assert_uint_eq(p->id[k], 7 * old + 3);
  ck_assert_uint_eq(p->mat[k], old % 3);
}

/* vsph_particles_move: each kept particle whole in its new place, the
 * others dropped, at 1 and 2 threads, above and below the size from which
 * it runs in parallel; the spare it hands back is a block of the set's
 * capacity none of the set's arrays uses (a second move through it, then
 * the set's and the spare's frees, run under the sanitizers' build). */
START_TEST(test_particles_move) {
  const size_t sizes[2] = {VSPH_PARTICLES_MOVE_PARALLEL / 4,
                           VSPH_PARTICLES_MOVE_PARALLEL + 1001};
  for (int z = 0; z < 2; z++)
    for (int thr = 1; thr <= 2; thr++) {
      omp_set_num_threads(thr);
      const size_t n = sizes[z];
      struct vsph_particles *p = named_set(n);
      void *spare = vsph_particles_spare_alloc(p->cap);
      size_t *perm = malloc(n * sizeof *perm), *was = malloc(n * sizeof *was);
      ck_assert_ptr_nonnull(spare);
      /* every third particle dropped, the rest in a scrambled order */
      size_t m = 0;
      for (size_t k = 0; k < n; k++) {
        const size_t i = (k * 7919) % n; /* n is no multiple of 7919 */
        if (i % 3 != 1) perm[m++] = i;
      }
      vsph_particles_move(p, perm, m, &spare);
      ck_assert_uint_eq(p->n, m);
      for (size_t k = 0; k < m; k++) is_named(p, k, perm[k]);
      for (size_t k = 0; k < m; k++) was[k] = perm[k];
      /* the spare is none of the set's arrays */
      double *f[VSPH_PARTICLES_DOUBLES];
      const int nd = vsph_particles_doubles(p, f);
      for (int a = 0; a < nd; a++) ck_assert_ptr_ne(spare, f[a]);
      ck_assert_ptr_ne(spare, p->id);
      /* again, reversed, through the spare handed back */
      for (size_t k = 0; k < m; k++) perm[k] = m - 1 - k;
      vsph_particles_move(p, perm, m, &spare);
      for (size_t k = 0; k < m; k++) is_named(p, k, was[m - 1 - k]);
      free(spare);
      free(perm);
      free(was);
      vsph_particles_free(p);
    }
}
END_TEST

/* A set of n particles on a scrambled lattice with every array named
 * (named_set), for the cell list's two builds. */
static struct vsph_particles *scrambled_set(size_t n, double shift) {
  struct vsph_particles *p = named_set(n);
  for (size_t i = 0; i < n; i++) {
    const size_t s = (i * 104729) % n; /* a scrambled order */
    p->pos[0][i] = 0.01 * (double)(s % 97) + shift * sin((double)i);
    p->pos[1][i] = 0.01 * (double)(s / 97) + shift * cos((double)i);
  }
  return p;
}

/* The cell list's counting sort, against its definition: every
 * particle lies in the cell whose run of slots holds it (its cell
 * recomputed here from its position, the grid's lo, edge and counts, as
 * keys() makes it), the runs in the cells' order, and within a cell the
 * particles in their order before the sort (stable: named_set's ids grow
 * with the index). At 1, 2 and 3 threads (the sort's shares of the
 * cells: one, even, and uneven), above the size from which it runs in
 * parallel, in three grids: cells of 4 to 9 particles, so that each
 * share's first cell and the cell before it hold two or more (checked);
 * a lattice spread over twice its span, with empty cells; and one cell,
 * fewer cells than threads. */
START_TEST(test_cells_sort_stable) {
  const size_t n = VSPH_CELLS_PARALLEL + 2345;
  const double radius[3] = {0.05, 0.025, 1e3};
  for (int g = 0; g < 3; g++)
    for (int thr = 1; thr <= 3; thr++) {
      omp_set_num_threads(thr);
      struct vsph_particles *p = scrambled_set(n, 0.0);
      if (g == 1) /* clusters and empty cells */
        for (size_t i = 0; i < n; i++)
          p->pos[0][i] *= 1.0 + (double)(i % 5 == 0);
      struct vsph_cells *c = vsph_cells_alloc();
      ck_assert_int_eq(vsph_cells_build(c, p, radius[g]), 0);
      size_t sum = 0, empty = 0;
      for (size_t q = 0; q < c->ncells; q++) {
        ck_assert_uint_eq(c->start[q], sum); /* the runs in order */
        sum += c->count[q];
        empty += c->count[q] == 0;
        for (size_t i = c->start[q]; i < c->start[q] + c->count[q]; i++) {
          size_t key = 0;
          for (int k = p->dim - 1; k >= 0; k--) {
            size_t ck = (size_t)floor((p->pos[k][i] - c->lo[k]) / c->edge);
            if (ck >= c->nc[k]) ck = c->nc[k] - 1;
            key = key * c->nc[k] + ck;
          }
          ck_assert_uint_eq(key, q);
          if (i > c->start[q]) ck_assert_uint_gt(p->id[i], p->id[i - 1]);
        }
      }
      ck_assert_uint_eq(sum, n);
      if (g == 0) /* the shares' first cells and those before them */
        for (size_t t = 1; t < (size_t)thr; t++) {
          const size_t q = c->ncells * t / (size_t)thr;
          ck_assert_uint_ge(c->count[q], 2);
          ck_assert_uint_ge(c->count[q - 1], 2);
        }
      if (g == 1) ck_assert_uint_gt(empty, 0);
      if (g == 2) ck_assert_uint_eq(c->ncells, 1);
      vsph_cells_free(c);
      vsph_particles_free(p);
    }
  omp_set_num_threads(2);
}
END_TEST

/* vsph_cells_build_owned: the same cells, the same order and every array
 * the same as vsph_cells_build, at 1 and 2 threads, on a first build and
 * on a second one after the particles moved (the scratch block then one
 * of the set's former arrays), and with a move through vsph_cells_lend in
 * between, as the integrator's ghosts do. */
START_TEST(test_cells_build_owned) {
  const size_t n = VSPH_CELLS_PARALLEL + 2345;
  for (int thr = 1; thr <= 2; thr++) {
    omp_set_num_threads(thr);
    struct vsph_particles *a = scrambled_set(n, 0.0),
                          *b = scrambled_set(n, 0.0);
    struct vsph_cells *ca = vsph_cells_alloc(), *cb = vsph_cells_alloc();
    for (int round = 0; round < 3; round++) {
      if (round > 0) /* the particles move: both sets alike */
        for (size_t i = 0; i < n; i++) {
          const double d = 0.003 * sin(0.37 * (double)(a->id[i] + round));
          a->pos[0][i] += d;
          b->pos[0][i] += d;
        }
      if (round == 2) { /* the lent scratch, then a move of b alone */
        size_t *perm;
        void **spare;
        ck_assert_int_eq(vsph_cells_lend(cb, b, &perm, &spare), 0);
        for (size_t k = 0; k < n; k++) perm[k] = n - 1 - k;
        vsph_particles_move(b, perm, n, spare);
        for (size_t k = 0; k < n; k++) perm[k] = n - 1 - k;
        vsph_particles_permute(a, perm, ca->dscratch, ca->iscratch);
      }
      ck_assert_int_eq(vsph_cells_build(ca, a, 0.025), 0);
      ck_assert_int_eq(vsph_cells_build_owned(cb, b, 0.025), 0);
      ck_assert_uint_eq(ca->ncells, cb->ncells);
      for (size_t c = 0; c < ca->ncells; c++) {
        ck_assert_uint_eq(ca->start[c], cb->start[c]);
        ck_assert_uint_eq(ca->count[c], cb->count[c]);
      }
      double *fa[VSPH_PARTICLES_DOUBLES], *fb[VSPH_PARTICLES_DOUBLES];
      const int nd = vsph_particles_doubles(a, fa);
      ck_assert_int_eq(vsph_particles_doubles(b, fb), nd);
      for (size_t i = 0; i < n; i++) {
        for (int q = 0; q < nd; q++)
          ck_assert_msg(memcmp(&fa[q][i], &fb[q][i], sizeof(double)) == 0,
                        "round %d, array %d, particle %zu", round, q, i);
        ck_assert_uint_eq(a->id[i], b->id[i]);
        ck_assert_uint_eq(a->mat[i], b->mat[i]);
      }
    }
    /* one cell list for two sets of other capacities in turn (its
     * scratch then sized anew for each: under the sanitizers' build an
     * overrun would show) */
    struct vsph_particles *small = scrambled_set(n / 3, 0.0),
                          *again = scrambled_set(n / 3, 0.0);
    ck_assert_int_eq(vsph_cells_build_owned(cb, small, 0.025), 0);
    ck_assert_int_eq(vsph_cells_build(ca, again, 0.025), 0);
    for (size_t i = 0; i < small->n; i++)
      ck_assert_uint_eq(small->id[i], again->id[i]);
    ck_assert_int_eq(vsph_cells_build_owned(cb, b, 0.025), 0);
    ck_assert_int_eq(vsph_cells_build(ca, a, 0.025), 0);
    for (size_t i = 0; i < n; i++) ck_assert_uint_eq(a->id[i], b->id[i]);
    vsph_particles_free(small);
    vsph_particles_free(again);
    vsph_cells_free(ca);
    vsph_cells_free(cb);
    vsph_particles_free(a);
    vsph_particles_free(b);
  }
}
END_TEST

/* vsph_share_next: every block once, whatever the blocks and the
 * threads (fewer blocks than threads, none, more threads than owners);
 * on one thread in order, the owners' runs one after the other. */
START_TEST(test_share_every_block_once) {
  const size_t counts[5] = {0, 1, 3, 32, 1001};
  for (int z = 0; z < 5; z++)
    for (int thr = 1; thr <= 3; thr++) {
      const size_t nblk = counts[z];
      omp_set_num_threads(thr);
      struct vsph_share sh;
      vsph_share_init(&sh, nblk);
      int *seen = calloc(nblk + 1, sizeof *seen), beyond = 0;
      size_t order[8], got = 0;
#pragma omp parallel /* asserted after the region, on this thread */
      for (size_t b; (b = vsph_share_next(&sh)) != SIZE_MAX;) {
        if (b >= nblk) {
#pragma omp atomic write
          beyond = 1;
          continue;
        }
#pragma omp atomic
        seen[b]++;
        if (thr == 1 && got < 8) order[got++] = b;
      }
      ck_assert_int_eq(beyond, 0);
      for (size_t b = 0; b < nblk; b++)
        ck_assert_msg(seen[b] == 1, "%zu blocks, %d threads: block %zu %d",
                      nblk, thr, b, seen[b]);
      if (thr == 1)
        for (size_t k = 0; k < got; k++) ck_assert_uint_eq(order[k], k);
      free(seen);
    }
  /* owners absent (the region has fewer threads than the share was
   * made for): the threads there take the absent owners' blocks */
  omp_set_num_threads(3);
  {
    struct vsph_share sh;
    vsph_share_init(&sh, 100);
    int seen[100] = {0};
#pragma omp parallel num_threads(1)
    for (size_t b; (b = vsph_share_next(&sh)) != SIZE_MAX;)
      if (b < 100) seen[b]++;
    for (size_t b = 0; b < 100; b++) ck_assert_int_eq(seen[b], 1);
  }
  /* more threads than owners: the rest take blocks as thieves */
  omp_set_num_threads(VSPH_SHARE_MAX + 3);
  struct vsph_share sh;
  vsph_share_init(&sh, 500);
  ck_assert_int_eq(sh.nt, VSPH_SHARE_MAX);
  int seen[500] = {0}, beyond = 0;
#pragma omp parallel
  for (size_t b; (b = vsph_share_next(&sh)) != SIZE_MAX;) {
    if (b >= 500) {
#pragma omp atomic write
      beyond = 1;
      continue;
    }
#pragma omp atomic
    seen[b]++;
  }
  ck_assert_int_eq(beyond, 0);
  for (size_t b = 0; b < 500; b++) ck_assert_int_eq(seen[b], 1);
  omp_set_num_threads(2);
}
END_TEST

Suite *vsph_cells_suite(void) {
  Suite *s = suite_create("cells");
  TCase *tc = tcase_create("core");
  tcase_add_test(tc, test_lattice_volumes);
  tcase_add_test(tc, test_halfspace);
  tcase_add_test(tc, test_disc_cartesian);
  tcase_add_test(tc, test_cells_vs_direct);
  tcase_add_test(tc, test_cells_bad_input_refused);
  tcase_add_test(tc, test_cells_first_bad_particle_named);
  tcase_add_test(tc, test_particles_move);
  tcase_add_test(tc, test_cells_sort_stable);
  tcase_add_test(tc, test_cells_build_owned);
  tcase_add_test(tc, test_share_every_block_once);
  suite_add_tcase(s, tc);
  return s;
}
