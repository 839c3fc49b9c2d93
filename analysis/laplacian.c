/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "laplacian.h"

#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/pair.h"
#include "../solver/particles.h"
#include "../solver/viscous.h"

static const char *const field_names[] = {"quartic", "quadratic", "linear"};
_Static_assert(sizeof field_names / sizeof field_names[0] ==
                   VSPH_LAPLACIAN_FIELD_COUNT,
               "field name table out of sync");

/* A Laplacian form is named by the viscous formulation that applies it
 * (its descriptor's lap): one list, vsph_viscous_types. */
const char *vsph_laplacian_form_name(int form) {
  for (int k = 0; k < VSPH_VISCOUS_FORM_COUNT; k++)
    if (form >= 0 && vsph_viscous_types[k]->lap == form)
      return vsph_viscous_types[k]->name;
  return "unknown";
}

int vsph_laplacian_form_find(const char *name) {
  if (!name) return -1;
  const int k = vsph_viscous_find(name);
  return k >= 0 ? vsph_viscous_types[k]->lap : -1;
}

const char *vsph_laplacian_field_name(int field) {
  return field >= 0 && field < VSPH_LAPLACIAN_FIELD_COUNT ? field_names[field]
                                                          : "unknown";
}

/* The "Laplacian" section as given. */
struct raw {
  char form[VSPH_PARAMS_NAME_MAX];
  char kernel[VSPH_PARAMS_NAME_MAX];
  char field[VSPH_PARAMS_NAME_MAX];
  size_t dim;
  size_t n;
  double hdx;
  double perturb;
  size_t seed;
  double eta;
  double line_x;
  double max_memory;
  double max_pairs;
};

#define P struct raw
static const struct vsph_params_spec LAPLACIAN[] = {
    VSPH_PARAMS_NAME_SPEC(P, form, "visc01",
                          "visc01 (hybrid), visc02 (direct), visc03 "
                          "(Schwaiger), visc04 (renormalised)"),
    VSPH_PARAMS_NAME_SPEC(P, kernel, "cubic",
                          "gaussian, cubic, quintic, wendland2, wendland4"),
    VSPH_PARAMS_NAME_SPEC(P, field, "quartic",
                          "quartic (x^4 + y^4, the paper's), quadratic or "
                          "linear"),
    VSPH_PARAMS_INT_SPEC(P, dim, 2, 2, 3, "dimension"),
    VSPH_PARAMS_INT_SPEC(P, n, 20, 2, 2000, "particles across the unit side"),
    VSPH_PARAMS_REAL_SPEC(P, hdx, 1.0, 0.5, 8.0, "h/dx"),
    VSPH_PARAMS_REAL_SPEC(P, perturb, 0.0, 0.0, 0.49,
                          "each coordinate shifted by up to this times dx"),
    VSPH_PARAMS_INT_SPEC(P, seed, VSPH_CONSTS_SEED, 0, 4294967295.0,
                         "seed of that shift (mt19937)"),
    VSPH_PARAMS_REAL_SPEC(P, eta, 0.0, 0.0, 1.0,
                          "regulariser eta/h of the hybrid forms"),
    VSPH_PARAMS_REAL_SPEC(P, line_x, 0.5, 0.0, 1.0,
                          "the line x = line_x whose particles the line "
                          "errors sample (the paper's Fig. 2: 0.5)"),
    VSPH_PARAMS_REAL_SPEC(P, max_memory, VSPH_CONSTS_MAX_MEMORY, 1e-3, 4096,
                          "refuse a set estimated to need more memory (GiB)"),
    VSPH_PARAMS_REAL_SPEC(P, max_pairs, VSPH_CONSTS_MAX_PAIRS, 1e3, 1e15,
                          "refuse a set estimated to need more neighbour "
                          "interactions (particles x neighbours; 1e9: about "
                          "40 s on one core)"),
};
#undef P

const struct vsph_params_spec *vsph_laplacian_params(size_t *n) {
  if (n) *n = sizeof LAPLACIAN / sizeof LAPLACIAN[0];
  return LAPLACIAN;
}

int vsph_laplacian_props_init(struct vsph_laplacian_props *lp,
                              struct vsph_params *prm) {
  struct raw r;
  if (!lp) VSPH_FAIL(VSPH_EINVAL, "vsph_laplacian_props_init: a NULL argument");
  memset(lp, 0, sizeof *lp);
  int st =
      vsph_params_load(prm, "Laplacian", LAPLACIAN,
                       sizeof LAPLACIAN / sizeof LAPLACIAN[0], &r, sizeof r);
  if (st) return st;
  if ((lp->form = vsph_laplacian_form_find(r.form)) < 0)
    VSPH_FAIL(VSPH_EINVAL,
              "unknown Laplacian form '%s' (visc01, visc02, visc03, visc04)",
              r.form);
  lp->field = -1;
  for (int k = 0; k < VSPH_LAPLACIAN_FIELD_COUNT; k++)
    if (!strcmp(field_names[k], r.field)) lp->field = k;
  if (lp->field < 0)
    VSPH_FAIL(VSPH_EINVAL, "unknown field '%s' (quartic, quadratic, linear)",
              r.field);
  if ((st = vsph_kernel_resolve(r.kernel, &lp->kernel))) return st;
  lp->dim = (int)r.dim;
  lp->n = r.n;
  lp->hdx = r.hdx;
  /* the lattice's nearest neighbours lie at dx: a support that does not
   * reach past them holds none (eq. 21 came out 3e14, its other measure
   * NaN) */
  if (lp->kernel && !(lp->kernel->kappa * lp->hdx > 1.0))
    VSPH_FAIL(VSPH_EINVAL,
              "Laplacian:hdx = %g: the %s kernel reaches %g h = %g dx, so its "
              "support holds no neighbour of the lattice; raise hdx above %g",
              lp->hdx, r.kernel, lp->kernel->kappa, lp->kernel->kappa * lp->hdx,
              1.0 / lp->kernel->kappa);
  lp->perturb = r.perturb;
  lp->seed = (unsigned long)r.seed;
  lp->eta = r.eta;
  lp->line_x = r.line_x;
  lp->max_memory = r.max_memory;
  lp->max_pairs = r.max_pairs;
  return VSPH_OK;
}

/* The field and its exact Laplacian at x. */
static double field(int kind, int dim, const double x[3], double *lap) {
  switch (kind) {
    case VSPH_LAPLACIAN_QUARTIC: {
      double f = 0.0, l = 0.0;
      for (int a = 0; a < dim; a++) {
        const double x2 = x[a] * x[a];
        f += x2 * x2;
        l += 12.0 * x2;
      }
      *lap = l;
      return f;
    }
    case VSPH_LAPLACIAN_QUADRATIC:
      *lap = 2.0 * (0.7 + 0.45) + (dim == 3 ? 1.8 : 0.0);
      return 0.7 * x[0] * x[0] - 1.3 * x[0] * x[1] + 0.45 * x[1] * x[1] +
             (dim == 3 ? 0.9 * x[2] * x[2] : 0.0);
    default:
      *lap = 0.0;
      return 1.2348 * x[0] - 0.8731 * x[1] + (dim == 3 ? 0.5 * x[2] : 0.0);
  }
}

/* The padded lattice: nodes (i + 1/2) dx - pad dx, i < n + 2 pad, per
 * axis, each coordinate shifted by U(-a, a) dx; id = the node's index. */
static int lattice(const struct vsph_laplacian_props *lp, size_t pad,
                   struct vsph_particles **out) {
  const int dim = lp->dim;
  const size_t m = lp->n + 2 * pad;
  size_t total = 1;
  for (int a = 0; a < dim; a++) total *= m;
  const double dx = 1.0 / (double)lp->n;
  /* about 20 doubles per particle (particles, cells, scratch) */
  const double gib = (double)total * 20.0 * 8.0 / 1073741824.0;
  if (!(gib <= lp->max_memory))
    VSPH_FAIL(VSPH_EINVAL,
              "the patch needs about %.3g GiB, above Laplacian:max_memory = "
              "%g GiB: lower n or raise max_memory",
              gib, lp->max_memory);
  struct vsph_particles *p = vsph_particles_alloc(total, dim);
  gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
  if (!p || !rng) {
    vsph_particles_free(p);
    gsl_rng_free(rng);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a patch of %zu particles", total);
  }
  gsl_rng_set(rng, lp->seed);
  for (size_t k = 0; k < total; k++) {
    size_t rest = k;
    for (int a = 0; a < dim; a++) {
      const size_t i = rest % m;
      rest /= m;
      double x = ((double)i + 0.5 - (double)pad) * dx;
      if (lp->perturb > 0.0)
        x += lp->perturb * dx * (2.0 * gsl_rng_uniform(rng) - 1.0);
      p->pos[a][k] = x;
    }
    p->m[k] = p->vol[k] = pow(dx, dim);
    p->rho[k] = 1.0;
    p->id[k] = k;
  }
  p->n = total;
  gsl_rng_free(rng);
  *out = p;
  return VSPH_OK;
}

/* 1 if node id (of the padded lattice) lies in the unit square. */
static int inside(size_t id, int dim, size_t n, size_t pad) {
  const size_t m = n + 2 * pad;
  for (int a = 0; a < dim; a++, id /= m)
    if (id % m < pad || id % m >= pad + n) return 0;
  return 1;
}

/* The patch's cost refused before anything is laid out: every evaluated
 * particle gathers from the lattice points within its support, the ball
 * of radius kappa hdx in units of dx; more than Laplacian:max_pairs
 * interactions is VSPH_EINVAL. */
static int check_cost(const struct vsph_laplacian_props *lp) {
  const int dim = lp->dim;
  const double r = lp->kernel->kappa * lp->hdx;
  const double nb =
      dim == 2 ? VSPH_PI * r * r : 4.0 / 3.0 * VSPH_PI * r * r * r;
  const double ne = pow((double)lp->n, dim), pairs = ne * nb;
  if (!(pairs <= lp->max_pairs))
    VSPH_FAIL(VSPH_EINVAL,
              "the patch needs about %.3g neighbour interactions (%.3g "
              "particles x %.3g neighbours), more than Laplacian:max_pairs = "
              "%g: lower n or hdx, or raise max_pairs",
              pairs, ne, nb, lp->max_pairs);
  return VSPH_OK;
}

/* The Laplacian of the field @p f (set on every particle of @p p) at each
 * particle inside the unit square (of the lattice padded by @p pad), by
 * the formulation lp->form, against the exact one: err[4 i .. 4 i + 3] =
 * 1 (evaluated), |error|, |numerical|, |exact|; zero elsewhere. */
static void patch_errors(const struct vsph_laplacian_props *lp,
                         const struct vsph_particles *p,
                         const struct vsph_cells *cells, size_t pad, double h,
                         const double *f, double *err) {
  const int dim = lp->dim;
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, lp->kernel, dim, h);
  const double eta2 = lp->eta * lp->eta * h * h;
  const double *const fields[3] = {f, NULL, NULL};
  /* gather: particle i writes only err[4 i .. 4 i + 3] */
#pragma omp parallel for schedule(dynamic, 16)
  for (size_t c = 0; c < cells->ncells; c++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, cells, c);
    for (size_t i = cells->start[c]; i < cells->start[c] + cells->count[c];
         i++) {
      if (!inside(p->id[i], dim, lp->n, pad)) continue;
      double num[3];
      vsph_viscous_laplacians(&pk, lp->kernel, h, eta2, 1e-12, lp->form, p, &rg,
                              i, 1, fields, num);
      double x[3] = {0, 0, 0}, exact;
      for (int a = 0; a < dim; a++) x[a] = p->pos[a][i];
      field(lp->field, dim, x, &exact);
      err[4 * i] = 1.0;
      err[4 * i + 1] = fabs(num[0] - exact);
      err[4 * i + 2] = fabs(num[0]);
      err[4 * i + 3] = fabs(exact);
    }
  }
}

/* The errors @p err of the particles of @p p (spacing @p dx) reduced into
 * @p res in index order (reproducible for any thread count); the line: the
 * lattice column(s) within dx/2 of x = line_x, each particle judged by
 * where it sits, so a shift of up to perturb dx widens the band by as much
 * (the nearest one or two columns). */
static void patch_reduce(const struct vsph_laplacian_props *lp,
                         const struct vsph_particles *p, const double *err,
                         double dx, struct vsph_laplacian_result *res) {
  const double band = (0.5 + lp->perturb) * dx * (1.0 + 1e-9);
  double lit = 0.0, ex = 0.0, llit = 0.0, lex = 0.0;
  for (size_t i = 0; i < p->n; i++) {
    if (err[4 * i] == 0.0) continue;
    res->n_eval++;
    const double d = err[4 * i + 1];
    const double a = err[4 * i + 2] > 0.0 ? d / err[4 * i + 2] : 0.0;
    const double b = err[4 * i + 3] > 0.0 ? d / err[4 * i + 3] : 0.0;
    lit += a;
    ex += b;
    if (fabs(p->pos[0][i] - lp->line_x) <= band) {
      res->n_line++;
      llit += a;
      lex += b;
    }
    res->abs_max = fmax(res->abs_max, d);
    res->ref_max = fmax(res->ref_max, err[4 * i + 3]);
  }
  res->err_line_literal =
      res->n_line ? llit / (double)res->n_line * dx * dx : (double)NAN;
  res->err_line_paper =
      res->n_line ? lex / (double)res->n_line * dx * dx : (double)NAN;
  res->n_total = p->n;
  res->dx = dx;
  res->err_literal = lit / (double)res->n_eval;
  res->err_exact = ex / (double)res->n_eval;
  res->err_paper = res->err_exact * dx * dx;
}

int vsph_laplacian_patch(const struct vsph_laplacian_props *lp,
                         struct vsph_laplacian_result *res) {
  if (!lp || !res || !lp->kernel)
    VSPH_FAIL(VSPH_EINVAL, "vsph_laplacian_patch: a NULL argument");
  memset(res, 0, sizeof *res);
  const int dim = lp->dim;
  if (dim < 2 || dim > 3) VSPH_FAIL(VSPH_EINVAL, "the patch is 2-D or 3-D");
  if (lp->n < 2 || !(lp->hdx > 0.0) || lp->field < 0 ||
      lp->field >= VSPH_LAPLACIAN_FIELD_COUNT ||
      !strcmp(vsph_laplacian_form_name(lp->form), "unknown"))
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_laplacian_patch: n >= 2, h/dx > 0, a field and a form "
              "of their lists");
  const double dx = 1.0 / (double)lp->n, h = lp->hdx * dx;
  const double kap = lp->kernel->kappa;
  /* ghosts: every evaluated particle (shifted by < dx/2) has full
   * support, kappa h + dx/2 + the shift of its neighbours */
  const size_t pad = (size_t)ceil(kap * lp->hdx) + 2;
  int st = check_cost(lp);
  if (st) return st;
  struct vsph_particles *p = NULL;
  if ((st = lattice(lp, pad, &p))) return st;
  struct vsph_cells *cells = vsph_cells_alloc();
  if (!cells) st = VSPH_ENOMEM;
  if (!st) st = vsph_cells_build(cells, p, kap * h);
  double *f = st ? NULL : malloc(p->n * sizeof *f);
  double *err = st ? NULL : calloc(4 * p->n, sizeof *err);
  if (!st && (!f || !err)) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot allocate the patch");
  }
  if (!st) {
    for (size_t i = 0; i < p->n; i++) {
      double x[3] = {0, 0, 0}, l;
      for (int a = 0; a < dim; a++) x[a] = p->pos[a][i];
      f[i] = field(lp->field, dim, x, &l);
    }
    patch_errors(lp, p, cells, pad, h, f, err);
    patch_reduce(lp, p, err, dx, res);
    res->h = h;
  }
  free(f);
  free(err);
  vsph_cells_free(cells);
  vsph_particles_free(p);
  return st;
}
