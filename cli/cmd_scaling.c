/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph scaling: h F, h N and the surface operators as h halves at fixed
 * h/dx (THEORY 2, "Truncation-error scaling"); interior convergence on a
 * quadratic field as h/dx grows. */
#include "cmd_scaling.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>

#include "../analysis/moments.h"
#include "../analysis/scaling.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/json.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "args.h"

/* the command's state: the surface scaling with the half-support
 * theory, or (the quadratic field) the interior convergence with its
 * log-log slopes against h/dx */
struct work {
  struct vsph_scaling_props sp;
  struct vsph_scaling_result r;
  double hF_th, hN_th; /* -2 C_F and -C_N: h F_ddd and h N_d, half support */
  struct vsph_scaling_interior in;
  size_t nin;           /* its levels */
  double s_mgf, s_meaf; /* its slopes */
};

static int init(void *w, struct vsph_params *prm) {
  return vsph_scaling_props_init(&((struct work *)w)->sp, prm);
}

static int compute(void *w) {
  struct work *k = w;
  const struct vsph_scaling_props *sp = &k->sp;
  if (sp->field.kind == VSPH_FIELDS_QUADRATIC) {
    const double *ladder;
    const size_t nl = vsph_scaling_hdx_ladder(&ladder);
    k->nin = sp->levels < nl ? sp->levels : nl;
    const int st = vsph_scaling_interior(sp, ladder, k->nin, &k->in);
    if (st) return st;
    /* the log-log slope of the error against h/dx */
    k->s_mgf = vsph_scaling_slope(k->in.hdx, k->in.mgf, k->nin);
    k->s_meaf = vsph_scaling_slope(k->in.hdx, k->in.meaf, k->nin);
    return VSPH_OK;
  }
  double C_F = NAN, C_N = NAN;
  int st = vsph_scaling_surface(sp, &k->r);
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
  if (!st)
    st = ws ? vsph_moments_constants(sp->kernel, sp->field.dim, 1e-10, ws, &C_F,
                                     &C_N)
            : VSPH_ENOMEM;
  gsl_integration_workspace_free(ws);
  /* Half-support theory: F_ddd = -C_F (1+1+1-1)/h = -2 C_F/h, N_d = -C_N/h */
  k->hF_th = -2 * C_F;
  k->hN_th = -C_N;
  return st;
}

static void *json(const void *w) {
  const struct work *k = w;
  if (k->sp.field.kind != VSPH_FIELDS_QUADRATIC)
    return vsph_json_scaling(&k->sp, &k->r, k->hF_th, k->hN_th);
  cJSON *o = cJSON_CreateObject();
  if (!o) return NULL;
  cJSON_AddStringToObject(o, "kernel", k->sp.kernel->name);
  cJSON_AddStringToObject(o, "field", "quadratic");
  cJSON_AddItemToObject(o, "hdx", vsph_json_array(k->in.hdx, k->nin));
  cJSON_AddItemToObject(o, "mgf", vsph_json_array(k->in.mgf, k->nin));
  cJSON_AddItemToObject(o, "meaf", vsph_json_array(k->in.meaf, k->nin));
  vsph_json_number(o, "slope_mgf", k->s_mgf);
  vsph_json_number(o, "slope_meaf", k->s_meaf);
  return o;
}

static void print_interior(const struct work *k) {
  printf(
      "# vsph %s scaling: interior, kernel %s, quadratic field, relative "
      "error against the continuous limit\n%8s %14s %14s\n",
      VSPH_VERSION, k->sp.kernel->name, "h/dx", "MGF", "MEAF");
  for (size_t i = 0; i < k->nin; i++)
    printf("%8.4f %14.6e %14.6e\n", k->in.hdx[i], k->in.mgf[i], k->in.meaf[i]);
  printf("# log-log slope against h/dx: MGF %.3f, MEAF %.3f\n", k->s_mgf,
         k->s_meaf);
}

static int print_table(const void *w) {
  const struct work *k = w;
  if (k->sp.field.kind == VSPH_FIELDS_QUADRATIC) {
    print_interior(k);
    return 0;
  }
  const struct vsph_scaling_props *sp = &k->sp;
  const struct vsph_scaling_result *r = &k->r;
  const double hF_th = k->hF_th, hN_th = k->hN_th;
  printf(
      "# vsph %s scaling: kernel %s, dim %d, field %s, %s lattice, h/dx = "
      "%g, mu = %g\n# half-support theory: h F_ddd = -2 C_F = %.6f, "
      "h N_d = -C_N = %.6f\n",
      VSPH_VERSION, sp->kernel->name, sp->field.dim,
      vsph_fields_name(sp->field.kind),
      vsph_lattice_label(sp->lattice, sp->perturb), sp->hdx, sp->mu, hF_th,
      hN_th);
  /* h F and h N per level; then a row per formulation (the table stays
   * narrow however many forms there are): its normal component at each
   * h, its magnitude at each h, and its slope */
  printf("%10s %11s %11s\n", "h", "hF_ddd", "hN_d");
  for (size_t l = 0; l < r->levels; l++)
    printf("%10.6f %11.6f %11.6f\n", r->h[l], r->hF[l], r->hN[l]);
  for (int part = 0; part < 2; part++) {
    printf("\n# %s of (div V)_i at each h%s\n%-10s",
           part ? "magnitude" : "normal component",
           part ? "; slope: log-log, of the magnitude against h" : "", "form");
    for (size_t l = 0; l < r->levels; l++) printf(" %11.4g", r->h[l]);
    printf(part ? "     slope\n" : "\n");
    for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
      printf("%-10s", vsph_viscous_name(f));
      for (size_t l = 0; l < r->levels; l++)
        printf(" %11.4e", vsph_consts_shown(
                              part ? r->magnitude[f][l] : r->normal[f][l], 0));
      if (part && r->rounding[f])
        printf("  rounding level (no growth)");
      else if (part)
        printf(" %9.4f", vsph_consts_shown(r->slope[f], 5e-5));
      printf("\n");
    }
  }
  return 0;
}

int vsph_cmd_scaling_main(int argc, char **argv) {
  static const struct vsph_args_analysis a = {
      "scaling",
      "[options]",
      "strain, rotation: at a surface particle (outward normal +e_d), with\n"
      "h/dx fixed and h halved from h0: h F_ddd, h N_d and each operator\n"
      "(div V)_i applied to u = A(x1 e1 - xd ed) (n.D.n != 0) or\n"
      "u = Omega(-xd e1 + x1 ed) (n.D.n = 0). Slopes are fitted on\n"
      "log|(div V)_i| against log h (the normal part leads for strain, the\n"
      "tangential part for MEAF on rotation); values at rounding level get\n"
      "no slope (null).\n"
      "quadratic (2-D): interior relative errors of MGF against\n"
      "mu(lap u + 2 grad div u) and MEAF against mu lap u for the first\n"
      "`levels` h/dx of 1, 4/3, 2, 3, 4, 6.",
      "JSON with keys h, hF, hN, one per formulation (normal components), "
      "*_tangential, *_magnitude, slope_*, rounding_*, hF_theory, "
      "hN_theory; quadratic: hdx, mgf, meaf, slope_mgf, slope_meaf",
      "Scaling",
      vsph_scaling_params,
      init,
      compute,
      json,
      print_table};
  struct work w;
  return vsph_args_analysis_main(&a, &w, argc, argv);
}
