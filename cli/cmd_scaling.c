/* vsph scaling: h F, h N and the surface operators as h halves at fixed
 * h/dx (THEORY 2, "Truncation-error scaling"); interior convergence on a
 * quadratic field as h/dx grows. */
#include "cmd_scaling.h"

#include <gsl/gsl_fit.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../analysis/moments.h"
#include "../analysis/scaling.h"
#include "../common/consts.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/viscous.h"
#include "args.h"
#include "writers.h"

static const char *const CMD = "scaling";

/* Default h/dx ladder of the interior sweep. */
static const double HDX_LADDER[] = {1.0, 4.0 / 3.0, 2.0, 3.0, 4.0, 6.0};

static void usage(FILE *f) {
  fputs(
      "usage: vsph scaling [--kernel NAME] [--dim D]\n"
      "                    [--field strain|rotation|quadratic] [--levels L]\n"
      "                    [--hdx R] [--lattice square|hex|perturbed]\n"
      "                    [--perturb A] [--seed S] [--mu MU] [--json]\n"
      "\n"
      "strain, rotation: at a surface particle (outward normal +e_d), with\n"
      "h/dx fixed (default 4/3; at most 16, 4 in 3-D) and h halved L\n"
      "times from 0.1 (default L=5):\n"
      "h*F_ddd, h*N_d and each operator (div V)_i applied to u = A(x1 e1 -\n"
      "xd ed) (n.D.n != 0) or u = Omega(-xd e1 + x1 ed) (n.D.n = 0).\n"
      "Slopes are fitted on log|(div V)_i| against log h (the normal part\n"
      "leads for strain, the tangential part for MEAF on rotation); values\n"
      "at rounding level get no slope (null).\n"
      "quadratic (2-D): interior relative errors of MGF against\n"
      "mu(lap u + 2 grad div u) and MEAF against mu lap u for h/dx in\n"
      "1, 4/3, 2, 3, 4, 6 (the first L).\n"
      "JSON keys: h, hF, hN, mgf, meaf, pvwf (normal components),\n"
      "mgf_tangential..., mgf_magnitude..., slope_mgf, slope_meaf,\n"
      "slope_pvwf, hF_theory, hN_theory; quadratic: hdx, mgf, meaf,\n"
      "slope_mgf, slope_meaf (log error against log h/dx).\n",
      f);
}

static double fit_slope(const double *x, const double *y, size_t n) {
  double lx[VSPH_SCALING_MAXLEVELS], ly[VSPH_SCALING_MAXLEVELS];
  for (size_t i = 0; i < n; i++) {
    lx[i] = log(x[i]);
    ly[i] = log(y[i]);
  }
  double c0, c1, c00, c01, c11, ss;
  gsl_fit_linear(lx, 1, ly, 1, n, &c0, &c1, &c00, &c01, &c11, &ss);
  return c1;
}

static int run_interior(struct vsph_scaling_props *sp, size_t levels,
                        int json) {
  const size_t n = levels < 6 ? levels : 6;
  struct vsph_scaling_interior r;
  const int st = vsph_scaling_interior(sp, HDX_LADDER, n, &r);
  if (st) return vsph_args_status(CMD, st);
  const double s_mgf = fit_slope(r.hdx, r.mgf, n);
  const double s_meaf = fit_slope(r.hdx, r.meaf, n);
  if (json) {
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "kernel", sp->kernel->name);
    cJSON_AddStringToObject(o, "field", "quadratic");
    cJSON_AddItemToObject(o, "hdx", vsph_writers_array(r.hdx, n));
    cJSON_AddItemToObject(o, "mgf", vsph_writers_array(r.mgf, n));
    cJSON_AddItemToObject(o, "meaf", vsph_writers_array(r.meaf, n));
    vsph_writers_number(o, "slope_mgf", s_mgf);
    vsph_writers_number(o, "slope_meaf", s_meaf);
    return vsph_writers_print_json(o) ? 1 : 0;
  }
  printf(
      "# vsph %s scaling: interior, kernel %s, quadratic field, relative "
      "error against the continuous limit\n",
      VSPH_VERSION, sp->kernel->name);
  printf("%8s %14s %14s\n", "h/dx", "MGF", "MEAF");
  for (size_t i = 0; i < n; i++)
    printf("%8.4f %14.6e %14.6e\n", r.hdx[i], r.mgf[i], r.meaf[i]);
  printf("# log-log slope against h/dx: MGF %.3f, MEAF %.3f\n", s_mgf, s_meaf);
  return 0;
}

int vsph_cmd_scaling_main(int argc, char **argv) {
  const char *kname = "gaussian", *field = "strain", *lattice = "square";
  double dimf = 2, hdx = 4.0 / 3.0, perturb = 0.1, mu = 0.0137;
  size_t levels = 5, seed = 2385;
  int json = 0;
  const struct vsph_args_spec specs[] = {
      {"--kernel", VSPH_ARGS_STRING, &kname},
      {"--field", VSPH_ARGS_STRING, &field},
      {"--lattice", VSPH_ARGS_STRING, &lattice},
      {"--dim", VSPH_ARGS_DOUBLE, &dimf},
      {"--hdx", VSPH_ARGS_DOUBLE, &hdx},
      {"--perturb", VSPH_ARGS_DOUBLE, &perturb},
      {"--mu", VSPH_ARGS_DOUBLE, &mu},
      {"--levels", VSPH_ARGS_SIZE, &levels},
      {"--seed", VSPH_ARGS_SIZE, &seed},
      {"--json", VSPH_ARGS_FLAG, &json},
  };
  const int pr = vsph_args_parse(CMD, argc, argv, specs,
                                 sizeof specs / sizeof specs[0], usage);
  if (pr >= 0) return pr;
  const struct vsph_kernel_type *k = vsph_args_kernel(CMD, kname);
  if (!k) return 2;
  const int dim = vsph_args_dim(CMD, dimf);
  if (!dim) return 2;
  const int fk = vsph_fields_find(field);
  if (fk != VSPH_FIELDS_STRAIN && fk != VSPH_FIELDS_ROTATION &&
      fk != VSPH_FIELDS_QUADRATIC)
    return vsph_args_fail(CMD,
                          "unknown field '%s' (strain, rotation, "
                          "quadratic)",
                          field);
  if (fk == VSPH_FIELDS_ROTATION && dim < 2)
    return vsph_args_fail(CMD, "rotation needs --dim 2 or 3");
  if (fk == VSPH_FIELDS_QUADRATIC && dim != 2)
    return vsph_args_fail(CMD, "the quadratic field is 2-D (--dim 2)");
  if (!(hdx > 0)) return vsph_args_fail(CMD, "--hdx must be > 0, got %g", hdx);
  /* The surface patch has radius (2 kappa + 2/hdx) h, ~(6 hdx)^d particles
   * each with ~(3 hdx)^d neighbours: cost grows like hdx^(2d). These caps
   * keep one level within about 10 s on one core. */
  const double hdx_max = dim == 3 ? 4.0 : 16.0;
  if (hdx > hdx_max)
    return vsph_args_fail(CMD,
                          "--hdx above %g in %d-D would need too many "
                          "particles, got %g",
                          hdx_max, dim, hdx);
  if (!(mu > 0)) return vsph_args_fail(CMD, "--mu must be > 0, got %g", mu);
  if (levels < 2 || levels > VSPH_SCALING_MAXLEVELS)
    return vsph_args_fail(CMD, "--levels must lie in 2-%d, got %zu",
                          VSPH_SCALING_MAXLEVELS, levels);
  if (fk != VSPH_FIELDS_QUADRATIC && levels > 8)
    return vsph_args_fail(CMD,
                          "--levels above 8 gives h below 0.0004: "
                          "use at most 8");
  int kind;
  double amp;
  if (vsph_args_lattice(CMD, lattice, dim, perturb, &kind, &amp)) return 2;

  struct vsph_scaling_props sp;
  vsph_scaling_props_init(&sp);
  sp.kernel = k;
  sp.lattice = kind;
  sp.perturb = amp;
  sp.seed = seed;
  sp.levels = levels;
  sp.hdx = hdx;
  sp.mu = mu;
  int st = vsph_fields_props_init(&sp.field, fk, dim);
  if (st) return vsph_args_status(CMD, st);
  if (fk == VSPH_FIELDS_QUADRATIC) return run_interior(&sp, levels, json);

  struct vsph_scaling_result r;
  st = vsph_scaling_surface(&sp, &r);
  double C_F = NAN, C_N = NAN;
  gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
  if (!st) st = ws ? vsph_moments_constants(k, dim, 1e-10, ws, &C_F, &C_N) : 1;
  gsl_integration_workspace_free(ws);
  if (st) return vsph_args_status(CMD, st);
  /* Half-support theory: F_ddd = -C_F (1+1+1-1)/h = -2 C_F/h, N_d = -C_N/h */
  const double hF_th = -2.0 * C_F, hN_th = -C_N;
  const size_t L = r.levels;
  if (json) {
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "kernel", k->name);
    cJSON_AddNumberToObject(o, "dim", dim);
    cJSON_AddStringToObject(o, "field", field);
    cJSON_AddStringToObject(o, "lattice", lattice);
    cJSON_AddNumberToObject(o, "hdx", hdx);
    cJSON_AddNumberToObject(o, "mu", mu);
    cJSON_AddItemToObject(o, "h", vsph_writers_array(r.h, L));
    cJSON_AddItemToObject(o, "hF", vsph_writers_array(r.hF, L));
    cJSON_AddItemToObject(o, "hN", vsph_writers_array(r.hN, L));
    cJSON_AddNumberToObject(o, "hF_theory", hF_th);
    cJSON_AddNumberToObject(o, "hN_theory", hN_th);
    for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
      const char *nm = vsph_viscous_name(f);
      char key[64];
      cJSON_AddItemToObject(o, nm, vsph_writers_array(r.normal[f], L));
      snprintf(key, sizeof key, "%s_tangential", nm);
      cJSON_AddItemToObject(o, key, vsph_writers_array(r.tangential[f], L));
      snprintf(key, sizeof key, "%s_magnitude", nm);
      cJSON_AddItemToObject(o, key, vsph_writers_array(r.magnitude[f], L));
      snprintf(key, sizeof key, "slope_%s", nm);
      vsph_writers_number(o, key, r.slope[f]);
      snprintf(key, sizeof key, "rounding_%s", nm);
      cJSON_AddBoolToObject(o, key, r.rounding[f]);
    }
    return vsph_writers_print_json(o) ? 1 : 0;
  }
  printf(
      "# vsph %s scaling: kernel %s, dim %d, field %s, %s lattice, "
      "h/dx = %g, mu = %g\n",
      VSPH_VERSION, k->name, dim, field, lattice, hdx, mu);
  printf(
      "# half-support theory: h F_ddd = -2 C_F = %.6f, h N_d = -C_N = "
      "%.6f\n",
      hF_th, hN_th);
  printf("%10s %11s %11s %13s %13s %13s %13s %13s %13s\n", "h", "hF_ddd",
         "hN_d", "MGF.n", "MEAF.n", "PVWF.n", "|MGF|", "|MEAF|", "|PVWF|");
  for (size_t l = 0; l < L; l++)
    printf("%10.6f %11.6f %11.6f %13.5e %13.5e %13.5e %13.5e %13.5e %13.5e\n",
           r.h[l], r.hF[l], r.hN[l], r.normal[0][l], r.normal[1][l],
           r.normal[2][l], r.magnitude[0][l], r.magnitude[1][l],
           r.magnitude[2][l]);
  printf("# log-log slope of |(div V)_i| against h:");
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
    if (r.rounding[f])
      printf("  %s: rounding level (no growth)", vsph_viscous_name(f));
    else
      printf("  %s: %.4f", vsph_viscous_name(f), r.slope[f]);
  }
  printf("\n");
  return 0;
}
