#include "walls.h"

#include <stdlib.h>

#include "../common/status.h"
#include "particles.h"

struct vsph_walls_ghosts *vsph_walls_ghosts_alloc(size_t cap) {
  struct vsph_walls_ghosts *gh = calloc(1, sizeof *gh);
  if (gh) {
    gh->cap = cap;
    gh->src = malloc((cap ? cap : 1) * sizeof *gh->src);
    gh->mask = malloc((cap ? cap : 1) * sizeof *gh->mask);
  }
  if (!gh || !gh->src || !gh->mask) {
    vsph_walls_ghosts_free(gh);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate %zu ghosts", cap);
    return NULL;
  }
  return gh;
}

void vsph_walls_ghosts_free(struct vsph_walls_ghosts *gh) {
  if (!gh) return;
  free(gh->src);
  free(gh->mask);
  free(gh);
}

/* Copy source s into ghost slot i, mirrored across the planes in mask. */
static void mirror(const struct vsph_walls *w, struct vsph_particles *p,
                   size_t s, size_t i, unsigned mask) {
  const int d = p->dim;
  for (int k = 0; k < d; k++) {
    p->pos[k][i] = p->pos[k][s];
    p->vel[k][i] = w->noslip ? -p->vel[k][s] : p->vel[k][s];
  }
  for (int q = 0; q < w->n; q++) {
    if (!(mask & (1u << q))) continue;
    const int a = w->axis[q];
    p->pos[a][i] = 2.0 * w->pos[q] - p->pos[a][i];
    if (!w->noslip) p->vel[a][i] = -p->vel[a][i]; /* normal reversed */
  }
  double pr = w->c0 * w->c0 * (p->rho[s] - w->rho0);
  if (w->g != 0.0) pr += w->rho0 * w->g * (p->pos[d - 1][s] - p->pos[d - 1][i]);
  p->rho[i] = w->rho0 + pr / (w->c0 * w->c0);
  p->p[i] = pr;
  p->m[i] = p->m[s];
  p->vol[i] = p->m[i] / p->rho[i];
}

/* The planes within reach of fluid particle s, as a bit mask. */
static unsigned near_planes(const struct vsph_walls *w,
                            const struct vsph_particles *p, size_t s,
                            double reach) {
  unsigned near = 0;
  for (int q = 0; q < w->n; q++) {
    const double dist = w->side[q] * (p->pos[w->axis[q]][s] - w->pos[q]);
    if (dist < reach) near |= 1u << q;
  }
  return near;
}

size_t vsph_walls_count(const struct vsph_walls *w,
                        const struct vsph_particles *p, size_t n_fluid,
                        double reach) {
  size_t n = 0;
  for (size_t i = 0; i < p->n; i++)
    if (p->id[i] < n_fluid) /* a non-empty subset of the near planes each */
      n += (1u << __builtin_popcount(near_planes(w, p, i, reach))) - 1;
  return n;
}

int vsph_walls_generate(const struct vsph_walls *w, struct vsph_particles *p,
                        size_t n_fluid, double reach,
                        struct vsph_walls_ghosts *gh) {
  /* Compact: keep the fluid in its current order. */
  size_t n = 0;
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] >= n_fluid) continue;
    if (n != i) {
      for (int k = 0; k < p->dim; k++) {
        p->pos[k][n] = p->pos[k][i];
        p->vel[k][n] = p->vel[k][i];
        p->acc[k][n] = p->acc[k][i];
      }
      p->m[n] = p->m[i];
      p->rho[n] = p->rho[i];
      p->vol[n] = p->vol[i];
      p->p[n] = p->p[i];
      p->drho[n] = p->drho[i];
      p->id[n] = p->id[i];
    }
    n++;
  }
  p->n = n;
  gh->n = 0;
  for (size_t s = 0; s < n_fluid; s++) {
    const unsigned near = near_planes(w, p, s, reach);
    /* every non-empty subset of the near planes: images and corner images */
    for (unsigned mask = near; mask; mask = (mask - 1) & near) {
      if (gh->n >= gh->cap || p->n >= p->cap)
        VSPH_FAIL(VSPH_ENOMEM, "ghost capacity %zu exceeded", gh->cap);
      const size_t i = p->n++;
      gh->src[gh->n] = p->id[s];
      gh->mask[gh->n] = mask;
      p->id[i] = n_fluid + gh->n;
      gh->n++;
      mirror(w, p, s, i, mask);
    }
  }
  return VSPH_OK;
}

void vsph_walls_update(const struct vsph_walls *w, struct vsph_particles *p,
                       size_t n_fluid, const struct vsph_walls_ghosts *gh,
                       const size_t *where) {
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < p->n; i++) {
    if (p->id[i] < n_fluid) continue;
    const size_t g = p->id[i] - n_fluid;
    mirror(w, p, where[gh->src[g]], i, gh->mask[g]);
  }
}
