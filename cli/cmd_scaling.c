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

static const char *const CMD = "scaling";

static int run_interior(const struct vsph_scaling_props *sp, int json) {
  const double *ladder;
  const size_t nl = vsph_scaling_hdx_ladder(&ladder);
  const size_t n = sp->levels < nl ? sp->levels : nl;
  struct vsph_scaling_interior r;
  const int st = vsph_scaling_interior(sp, ladder, n, &r);
  if (st) return vsph_args_status(CMD, st);
  /* the log-log slope of the error against h/dx */
  const double s_mgf = vsph_scaling_slope(r.hdx, r.mgf, n);
  const double s_meaf = vsph_scaling_slope(r.hdx, r.meaf, n);
  if (json) {
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "kernel", sp->kernel->name);
    cJSON_AddStringToObject(o, "field", "quadratic");
    cJSON_AddItemToObject(o, "hdx", vsph_json_array(r.hdx, n));
    cJSON_AddItemToObject(o, "mgf", vsph_json_array(r.mgf, n));
    cJSON_AddItemToObject(o, "meaf", vsph_json_array(r.meaf, n));
    vsph_json_number(o, "slope_mgf", s_mgf);
    vsph_json_number(o, "slope_meaf", s_meaf);
    return vsph_json_print(o) ? vsph_args_status(CMD, VSPH_EIO) : 0;
  }
  printf(
      "# vsph %s scaling: interior, kernel %s, quadratic field, relative "
      "error against the continuous limit\n%8s %14s %14s\n",
      VSPH_VERSION, sp->kernel->name, "h/dx", "MGF", "MEAF");
  for (size_t i = 0; i < n; i++)
    printf("%8.4f %14.6e %14.6e\n", r.hdx[i], r.mgf[i], r.meaf[i]);
  printf("# log-log slope against h/dx: MGF %.3f, MEAF %.3f\n", s_mgf, s_meaf);
  return 0;
}

static void print_table(const struct vsph_scaling_props *sp,
                        const struct vsph_scaling_result *r, double hF_th,
                        double hN_th) {
  printf(
      "# vsph %s scaling: kernel %s, dim %d, field %s, %s lattice, h/dx = "
      "%g, mu = %g\n# half-support theory: h F_ddd = -2 C_F = %.6f, "
      "h N_d = -C_N = %.6f\n",
      VSPH_VERSION, sp->kernel->name, sp->field.dim,
      vsph_fields_name(sp->field.kind),
      sp->perturb > 0 ? "perturbed" : vsph_lattice_name(sp->lattice), sp->hdx,
      sp->mu, hF_th, hN_th);
  /* every formulation: its normal component, then its magnitude */
  printf("%10s %11s %11s", "h", "hF_ddd", "hN_d");
  char head[32];
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
    snprintf(head, sizeof head, "%s.n", vsph_viscous_name(f));
    printf(" %12s", head);
  }
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
    snprintf(head, sizeof head, "|%s|", vsph_viscous_name(f));
    printf(" %12s", head);
  }
  printf("\n");
  for (size_t l = 0; l < r->levels; l++) {
    printf("%10.6f %11.6f %11.6f", r->h[l], r->hF[l], r->hN[l]);
    for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++)
      printf(" %12.5e", r->normal[f][l]);
    for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++)
      printf(" %12.5e", r->magnitude[f][l]);
    printf("\n");
  }
  printf("# log-log slope of |(div V)_i| against h:");
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
    if (r->rounding[f])
      printf("  %s: rounding level (no growth)", vsph_viscous_name(f));
    else
      printf("  %s: %.4f", vsph_viscous_name(f), r->slope[f]);
  }
  printf("\n");
}

int vsph_cmd_scaling_main(int argc, char **argv) {
  int json = 0;
  const struct vsph_args_spec own[] = {
      {"--json", VSPH_ARGS_FLAG, &json, NULL,
       "JSON with keys h, hF, hN, one per formulation (normal components), "
       "*_tangential, *_magnitude, slope_*, rounding_*, hF_theory, "
       "hN_theory; quadratic: hdx, mgf, meaf, slope_mgf, slope_meaf"}};
  size_t n;
  const struct vsph_params_spec *spec = vsph_scaling_params(&n);
  const struct vsph_args_section sec = {"Scaling", spec, n};
  const struct vsph_args_cmd c = {
      CMD,
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
      own,
      1,
      &sec,
      1,
      NULL};
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return vsph_args_status(CMD, VSPH_ENOMEM);
  const int rc = vsph_args_parse(&c, argc, argv, prm);
  struct vsph_scaling_props sp;
  int st = rc < 0 ? vsph_scaling_props_init(&sp, prm) : 0;
  vsph_params_free(prm);
  if (rc >= 0) return rc;
  if (st) return vsph_args_status(CMD, st);
  if (sp.field.kind == VSPH_FIELDS_QUADRATIC)
    return vsph_args_finish(CMD, run_interior(&sp, json));
  struct vsph_scaling_result r;
  double C_F = NAN, C_N = NAN;
  st = vsph_scaling_surface(&sp, &r);
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
  if (!st)
    st = ws ? vsph_moments_constants(sp.kernel, sp.field.dim, 1e-10, ws, &C_F,
                                     &C_N)
            : VSPH_ENOMEM;
  gsl_integration_workspace_free(ws);
  if (st) return vsph_args_status(CMD, st);
  /* Half-support theory: F_ddd = -C_F (1+1+1-1)/h = -2 C_F/h, N_d = -C_N/h */
  if (json)
    return vsph_args_json(CMD, vsph_json_scaling(&sp, &r, -2 * C_F, -C_N));
  print_table(&sp, &r, -2 * C_F, -C_N);
  return vsph_args_finish(CMD, 0);
}
