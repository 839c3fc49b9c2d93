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
#include "../solver/lattice.h"
#include "../solver/particles.h"
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
  }
  vsph_status_set_handler(old);
  vsph_cells_free(c);
  vsph_particles_free(p);
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
  suite_add_tcase(s, tc);
  return s;
}
