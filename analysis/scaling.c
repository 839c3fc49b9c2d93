#include "scaling.h"

#include <gsl/gsl_fit.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/viscous.h"
#include "moments.h"

void vsph_scaling_props_init(struct vsph_scaling_props *sp) {
  memset(sp, 0, sizeof *sp);
  sp->lattice = VSPH_LATTICE_SQUARE;
  sp->seed = 2385;
  sp->levels = 5;
  sp->h0 = 0.1;
  sp->hdx = 4.0 / 3.0;
  sp->mu = 0.0137;
  sp->round_tol = 1e-9;
}

/* Evaluate the three formulations on patch p; values at particle `id0`. */
static int eval_forms(const struct vsph_scaling_props *sp,
                      struct vsph_particles *p, size_t id0, double h,
                      double vals[3][3], size_t *centre) {
  const int dim = p->dim;
  struct vsph_cells *cells = vsph_cells_alloc();
  struct vsph_viscous_ws *ws = vsph_viscous_ws_alloc(p->n, dim);
  double *buf = malloc(3 * p->n * sizeof *buf);
  int st = VSPH_OK;
  if (!cells || !ws || !buf) {
    st = VSPH_ENOMEM;
    goto done;
  }
  for (size_t i = 0; i < p->n; i++) {
    double x[3] = {0, 0, 0}, u[3], g[9];
    for (int k = 0; k < dim; k++) x[k] = p->pos[k][i];
    vsph_fields_eval(&sp->field, x, u, g);
    for (int k = 0; k < dim; k++) p->vel[k][i] = u[k];
  }
  if ((st = vsph_cells_build(cells, p, sp->kernel->kappa * h))) goto done;
  size_t c = 0;
  while (c < p->n && p->id[c] != id0) c++;
  *centre = c;
  double *f[3] = {buf, dim > 1 ? buf + p->n : NULL,
                  dim > 2 ? buf + 2 * p->n : NULL};
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++) {
    struct vsph_viscous_props vp;
    if ((st = vsph_viscous_props_init(&vp, form, sp->kernel, dim, h, sp->mu)))
      goto done;
    if ((st = vsph_viscous_compute(&vp, p, cells, ws, f, NULL))) goto done;
    for (int k = 0; k < 3; k++) vals[form][k] = k < dim ? f[k][c] : 0.0;
  }
done:
  free(buf);
  vsph_viscous_ws_free(ws);
  vsph_cells_free(cells);
  return st;
}

int vsph_scaling_surface(const struct vsph_scaling_props *sp,
                         struct vsph_scaling_result *res) {
  const int dim = sp->field.dim;
  if (sp->levels < 2 || sp->levels > VSPH_SCALING_MAXLEVELS)
    VSPH_FAIL(VSPH_EINVAL, "levels must lie in 2-%d, got %zu",
              VSPH_SCALING_MAXLEVELS, sp->levels);
  if (!(sp->hdx > 0.0) || !isfinite(sp->hdx))
    VSPH_FAIL(VSPH_EINVAL, "h/dx must be positive, got %g", sp->hdx);
  if (sp->field.kind != VSPH_FIELDS_STRAIN &&
      sp->field.kind != VSPH_FIELDS_ROTATION)
    VSPH_FAIL(VSPH_EINVAL, "the surface sweep takes strain or rotation");
  memset(res, 0, sizeof *res);
  res->levels = sp->levels;
  const double U = sp->field.kind == VSPH_FIELDS_STRAIN ? fabs(sp->field.A)
                                                        : fabs(sp->field.Omega);
  for (size_t l = 0; l < sp->levels; l++) {
    const double h = sp->h0 / pow(2.0, (double)l), dx = h / sp->hdx;
    struct vsph_lattice_props lp = {.dim = dim,
                                    .kind = sp->lattice,
                                    .dx = dx,
                                    .perturb = sp->perturb,
                                    .seed = sp->seed + l};
    struct vsph_particles *p = NULL;
    size_t centre;
    const double radius = 2.0 * sp->kernel->kappa * h + 2.0 * dx;
    int st = vsph_lattice_halfspace(&lp, radius, 0.0, &p, &centre);
    if (st) return st;
    struct vsph_moments mo;
    st = vsph_moments_sum(sp->kernel, p, centre, h, &mo);
    double vals[3][3];
    size_t c;
    if (!st) st = eval_forms(sp, p, p->id[centre], h, vals, &c);
    vsph_particles_free(p);
    if (st) return st;
    res->h[l] = h;
    res->hF[l] = h * mo.F[dim - 1][dim - 1][dim - 1];
    res->hN[l] = h * mo.N[dim - 1];
    for (int form = 0; form < 3; form++) {
      double t2 = 0.0, m2 = 0.0;
      for (int k = 0; k < dim; k++) {
        m2 += vals[form][k] * vals[form][k];
        if (k != dim - 1) t2 += vals[form][k] * vals[form][k];
      }
      res->normal[form][l] = vals[form][dim - 1];
      res->tangential[form][l] = sqrt(t2);
      res->magnitude[form][l] = sqrt(m2);
    }
  }
  /* Rounding level: the operator of a linear field scales as mu U / h, so
   * anything below round_tol times that at the finest h is noise, whose
   * slope would mean nothing. */
  const double hmin = res->h[sp->levels - 1];
  for (int form = 0; form < 3; form++) {
    double mx = 0.0;
    for (size_t l = 0; l < sp->levels; l++)
      mx = fmax(mx, res->magnitude[form][l]);
    res->rounding[form] = mx <= sp->round_tol * sp->mu * U / hmin;
    if (res->rounding[form]) {
      res->slope[form] = NAN;
      continue;
    }
    double lx[VSPH_SCALING_MAXLEVELS], ly[VSPH_SCALING_MAXLEVELS];
    for (size_t l = 0; l < sp->levels; l++) {
      lx[l] = log(res->h[l]);
      ly[l] = log(res->magnitude[form][l]);
    }
    double c0, c1, cov00, cov01, cov11, sumsq;
    gsl_fit_linear(lx, 1, ly, 1, sp->levels, &c0, &c1, &cov00, &cov01, &cov11,
                   &sumsq);
    res->slope[form] = c1;
  }
  return VSPH_OK;
}

int vsph_scaling_interior(const struct vsph_scaling_props *sp,
                          const double *hdx, size_t n,
                          struct vsph_scaling_interior *res) {
  if (sp->field.kind != VSPH_FIELDS_QUADRATIC || sp->field.dim != 2)
    VSPH_FAIL(VSPH_EINVAL, "the interior sweep takes the 2-D quadratic field");
  if (n < 1 || n > VSPH_SCALING_MAXLEVELS)
    VSPH_FAIL(VSPH_EINVAL, "between 1 and %d h/dx values",
              VSPH_SCALING_MAXLEVELS);
  memset(res, 0, sizeof *res);
  res->n = n;
  const double h = sp->h0;
  double lap[3], gd[3];
  const double x0[3] = {0, 0, 0};
  vsph_fields_second(&sp->field, x0, lap, gd);
  double t_mgf[2], t_meaf[2];
  for (int k = 0; k < 2; k++) {
    t_mgf[k] = sp->mu * (lap[k] + 2.0 * gd[k]);
    t_meaf[k] = sp->mu * lap[k];
  }
  for (size_t l = 0; l < n; l++) {
    if (!(hdx[l] > 0.0)) VSPH_FAIL(VSPH_EINVAL, "h/dx must be positive");
    const double dx = h / hdx[l];
    struct vsph_lattice_props lp = {.dim = 2,
                                    .kind = sp->lattice,
                                    .dx = dx,
                                    .perturb = sp->perturb,
                                    .seed = sp->seed};
    struct vsph_particles *p = NULL;
    size_t centre, c;
    const double radius = sp->kernel->kappa * h + 2.0 * dx;
    int st = vsph_lattice_halfspace(&lp, radius, radius, &p, &centre);
    if (st) return st;
    double vals[3][3];
    st = eval_forms(sp, p, p->id[centre], h, vals, &c);
    vsph_particles_free(p);
    if (st) return st;
    res->hdx[l] = hdx[l];
    res->mgf[l] = hypot(vals[VSPH_VISCOUS_MGF][0] - t_mgf[0],
                        vals[VSPH_VISCOUS_MGF][1] - t_mgf[1]) /
                  hypot(t_mgf[0], t_mgf[1]);
    res->meaf[l] = hypot(vals[VSPH_VISCOUS_MEAF][0] - t_meaf[0],
                         vals[VSPH_VISCOUS_MEAF][1] - t_meaf[1]) /
                   hypot(t_meaf[0], t_meaf[1]);
  }
  return VSPH_OK;
}
