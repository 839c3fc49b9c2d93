/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "particles.h"

#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "particles_internal.h"
#include "share_internal.h"

/* 64-byte aligned zeroed block; aligned_alloc needs a size multiple of 64. */
static void *alloc_aligned(size_t bytes) {
  const size_t sz = (bytes + 63) / 64 * 64;
  void *ptr = aligned_alloc(64, sz ? sz : 64);
  if (ptr) memset(ptr, 0, sz ? sz : 64);
  return ptr;
}

struct vsph_particles *vsph_particles_alloc(size_t cap, int dim) {
  if (dim < 1 || dim > 3) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "dimension %d outside 1-3", dim);
    return NULL;
  }
  struct vsph_particles *p = calloc(1, sizeof *p);
  if (!p) goto fail;
  p->dim = dim;
  p->cap = (cap + 7) / 8 * 8;
  if (p->cap == 0) p->cap = 8;
  const size_t nb = p->cap * sizeof(double);
  for (int k = 0; k < dim; k++) {
    if (!(p->pos[k] = alloc_aligned(nb))) goto fail;
    if (!(p->vel[k] = alloc_aligned(nb))) goto fail;
    if (!(p->acc[k] = alloc_aligned(nb))) goto fail;
  }
  if (!(p->m = alloc_aligned(nb)) || !(p->rho = alloc_aligned(nb)) ||
      !(p->vol = alloc_aligned(nb)) || !(p->p = alloc_aligned(nb)) ||
      !(p->drho = alloc_aligned(nb)) ||
      !(p->id = alloc_aligned(p->cap * sizeof(size_t))))
    goto fail;
  return p;
fail:
  vsph_particles_free(p);
  vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                     "cannot allocate %zu particles", cap);
  return NULL;
}

/* *field grown to cap elements of size sz, the first n kept. */
static int grow(void **field, size_t n, size_t cap, size_t sz) {
  void *q = alloc_aligned(cap * sz);
  if (!q) return 0;
  memcpy(q, *field, n * sz);
  free(*field);
  *field = q;
  return 1;
}

int vsph_particles_reserve(struct vsph_particles *p, size_t cap) {
  if (!p) VSPH_FAIL(VSPH_EINVAL, "vsph_particles_reserve: a NULL argument");
  if (cap <= p->cap) return VSPH_OK;
  cap = (cap + 7) / 8 * 8;
  int ok = 1;
  for (int k = 0; k < p->dim; k++) {
    ok = ok && grow((void **)&p->pos[k], p->n, cap, sizeof(double));
    ok = ok && grow((void **)&p->vel[k], p->n, cap, sizeof(double));
    ok = ok && grow((void **)&p->acc[k], p->n, cap, sizeof(double));
  }
  ok = ok && grow((void **)&p->m, p->n, cap, sizeof(double)) &&
       grow((void **)&p->rho, p->n, cap, sizeof(double)) &&
       grow((void **)&p->vol, p->n, cap, sizeof(double)) &&
       grow((void **)&p->p, p->n, cap, sizeof(double)) &&
       grow((void **)&p->drho, p->n, cap, sizeof(double)) &&
       (!p->e || grow((void **)&p->e, p->n, cap, sizeof(double))) &&
       (!p->de || grow((void **)&p->de, p->n, cap, sizeof(double))) &&
       (!p->mat || grow((void **)&p->mat, p->n, cap, 1)) &&
       grow((void **)&p->id, p->n, cap, sizeof(size_t));
  for (int k = 0; k < p->dim; k++) {
    ok = ok &&
         (!p->tvel[k] || grow((void **)&p->tvel[k], p->n, cap, sizeof(double)));
    ok = ok &&
         (!p->bacc[k] || grow((void **)&p->bacc[k], p->n, cap, sizeof(double)));
  }
  /* a field that could not grow keeps its old size: cap stays until all
   * have grown */
  if (!ok)
    VSPH_FAIL(VSPH_ENOMEM, "cannot grow a particle set to %zu particles", cap);
  p->cap = cap;
  return VSPH_OK;
}

int vsph_particles_energy_alloc(struct vsph_particles *p) {
  if (!p)
    VSPH_FAIL(VSPH_EINVAL, "vsph_particles_energy_alloc: a NULL argument");
  if (p->e && p->de) return VSPH_OK;
  const size_t nb = p->cap * sizeof(double);
  if ((!p->e && !(p->e = alloc_aligned(nb))) ||
      (!p->de && !(p->de = alloc_aligned(nb))))
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the energy of %zu particles",
              p->cap);
  return VSPH_OK;
}

int vsph_particles_tvf_alloc(struct vsph_particles *p) {
  if (!p) VSPH_FAIL(VSPH_EINVAL, "vsph_particles_tvf_alloc: a NULL argument");
  const size_t nb = p->cap * sizeof(double);
  for (int k = 0; k < p->dim; k++)
    if ((!p->tvel[k] && !(p->tvel[k] = alloc_aligned(nb))) ||
        (!p->bacc[k] && !(p->bacc[k] = alloc_aligned(nb))))
      VSPH_FAIL(VSPH_ENOMEM,
                "cannot allocate the transport velocity of %zu particles",
                p->cap);
  return VSPH_OK;
}

int vsph_particles_mat_alloc(struct vsph_particles *p) {
  if (!p) VSPH_FAIL(VSPH_EINVAL, "vsph_particles_mat_alloc: a NULL argument");
  if (p->mat) return VSPH_OK;
  if (!(p->mat = alloc_aligned(p->cap)))
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the materials of %zu particles",
              p->cap);
  memset(p->mat, 0, p->cap);
  return VSPH_OK;
}

void vsph_particles_free(struct vsph_particles *p) {
  if (!p) return;
  for (int k = 0; k < 3; k++) {
    free(p->tvel[k]);
    free(p->bacc[k]);
    free(p->pos[k]);
    free(p->vel[k]);
    free(p->acc[k]);
  }
  free(p->m);
  free(p->rho);
  free(p->vol);
  free(p->p);
  free(p->drho);
  free(p->e);
  free(p->de);
  free(p->mat);
  free(p->id);
  free(p);
}

void vsph_particles_refresh_vol(struct vsph_particles *p) {
  if (!p) return;
  for (size_t i = 0; i < p->n; i++) p->vol[i] = p->m[i] / p->rho[i];
}

int vsph_particles_doubles(const struct vsph_particles *p,
                           double *f[VSPH_PARTICLES_DOUBLES]) {
  int nd = 0;
  for (int k = 0; k < p->dim; k++) {
    double *const v[5] = {p->pos[k], p->vel[k], p->acc[k], p->tvel[k],
                          p->bacc[k]};
    for (int a = 0; a < 5; a++)
      if (v[a]) f[nd++] = v[a];
  }
  double *const sc[7] = {p->m, p->rho, p->vol, p->p, p->drho, p->e, p->de};
  for (int a = 0; a < 7; a++)
    if (sc[a]) f[nd++] = sc[a];
  return nd;
}

static void permute_field(double *a, const size_t *perm, size_t n,
                          double *scratch) {
  for (size_t i = 0; i < n; i++) scratch[i] = a[perm[i]];
  memcpy(a, scratch, n * sizeof *a);
}

void vsph_particles_permute(struct vsph_particles *p, const size_t *perm,
                            double *scratch, size_t *iscratch) {
  if (!p || !perm || !scratch || !iscratch) return;
  const size_t n = p->n;
  /* every array the set has (a lean copy, the diagnostics', lacks some) */
  double *f[VSPH_PARTICLES_DOUBLES];
  const int nd = vsph_particles_doubles(p, f);
  for (int a = 0; a < nd; a++) permute_field(f[a], perm, n, scratch);
  if (p->mat) { /* bytes, through the index scratch */
    for (size_t i = 0; i < n; i++) iscratch[i] = p->mat[perm[i]];
    for (size_t i = 0; i < n; i++) p->mat[i] = (unsigned char)iscratch[i];
  }
  for (size_t i = 0; i < n; i++) iscratch[i] = p->id[perm[i]];
  memcpy(p->id, iscratch, n * sizeof *p->id);
}

void *vsph_particles_spare_alloc(size_t cap) {
  return alloc_aligned(cap * sizeof(double));
}

/* dst[k] = src[perm[k]] for k in [k0, k1): 8-byte entries (doubles or
 * indices), moved as bytes */
static void move8(void *restrict dst, const void *restrict src,
                  const size_t *perm, size_t k0, size_t k1) {
  unsigned char *const d = dst;
  const unsigned char *const s = src;
  for (size_t k = k0; k < k1; k++) memcpy(d + 8 * k, s + 8 * perm[k], 8);
}

void vsph_particles_move(struct vsph_particles *p, const size_t *perm, size_t n,
                         void **spare) {
  /* the 8-byte arrays by the address of their pointer: each is swapped
   * with the spare once its entries are moved */
  void **slot[VSPH_PARTICLES_DOUBLES + 1];
  int ns = 0;
  for (int k = 0; k < p->dim; k++) {
    double **const v[5] = {&p->pos[k], &p->vel[k], &p->acc[k], &p->tvel[k],
                           &p->bacc[k]};
    for (int a = 0; a < 5; a++)
      if (*v[a]) slot[ns++] = (void **)v[a];
  }
  double **const sc[7] = {&p->m,    &p->rho, &p->vol, &p->p,
                          &p->drho, &p->e,   &p->de};
  for (int a = 0; a < 7; a++)
    if (*sc[a]) slot[ns++] = (void **)sc[a];
  slot[ns++] = (void **)&p->id;
  /* where each array's entries go: the spare, then the array before it
   * (freed by its gather); every thread follows the same rotation in its
   * own copy, and the pointers are set once, after the last gather */
  void *to[VSPH_PARTICLES_DOUBLES + 1];
  void *free_block = *spare;
  for (int a = 0; a < ns; a++) {
    to[a] = free_block;
    free_block = *slot[a];
  }
  /* the bytes of mat go through the block left free and back */
  unsigned char *const mat = p->mat, *const b = free_block;
  if (n < VSPH_PARTICLES_MOVE_PARALLEL) { /* no region: its wake-up and
                                           * barriers cost more here */
    for (int a = 0; a < ns; a++) move8(to[a], *slot[a], perm, 0, n);
    if (mat) {
      for (size_t k = 0; k < n; k++) b[k] = mat[perm[k]];
      memcpy(mat, b, n);
    }
  } else {
#pragma omp parallel
    {
      size_t k0, k1;
      vsph_share_even(n, &k0, &k1);
      for (int a = 0; a < ns; a++) {
        /* each gather writes the block the one before it read */
        if (a > 0) {
#pragma omp barrier
        }
        move8(to[a], *slot[a], perm, k0, k1);
      }
      if (mat) {
#pragma omp barrier
        for (size_t k = k0; k < k1; k++) b[k] = mat[perm[k]];
#pragma omp barrier
        memcpy(mat + k0, b + k0, k1 - k0);
      }
    }
  }
  for (int a = 0; a < ns; a++) *slot[a] = to[a];
  *spare = free_block;
  p->n = n;
}
