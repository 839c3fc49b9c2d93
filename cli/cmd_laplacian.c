/* vsph laplacian: the patch test of the four Laplacian forms of Zheng, Ma
 * & Shao (2018) (docs/theory.md section 7). */
#include "cmd_laplacian.h"

#include <stdio.h>

#include "../analysis/laplacian.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/json.h"
#include "../kernels/kernel.h"
#include "args.h"

static const char *const CMD = "laplacian";

static void print_table(const struct vsph_laplacian_props *lp,
                        const struct vsph_laplacian_result *r) {
  printf(
      "# vsph %s laplacian: %s, field %s, %d-D, %zu across, h/dx = %g, "
      "kernel %s, perturbation %g dx (seed %lu), eta/h = %g\n",
      VSPH_VERSION, vsph_laplacian_form_name(lp->form),
      vsph_laplacian_field_name(lp->field), lp->dim, lp->n, lp->hdx,
      lp->kernel->name, lp->perturb, lp->seed, lp->eta);
  printf("particles evaluated  %zu (%zu with the ghost padding)\n", r->n_eval,
         r->n_total);
  printf("err eq. (21)         %.6e   mean |num - exact|/|num|\n",
         r->err_literal);
  printf("err, exact denom.    %.6e   mean |num - exact|/|exact|\n",
         r->err_exact);
  printf("paper's scale        %.6e   the above times dx^2\n", r->err_paper);
  printf("max |num - exact|    %.6e   (max |exact| %.6e)\n", r->abs_max,
         r->ref_max);
}

int vsph_cmd_laplacian_main(int argc, char **argv) {
  int json = 0;
  const struct vsph_args_spec own[] = {
      {"--json", VSPH_ARGS_FLAG, &json, NULL,
       "JSON with keys form, field, kernel, dim, n, hdx, perturb, seed, eta, "
       "n_eval, n_total, dx, h, err_literal, err_exact, err_paper, abs_max, "
       "ref_max"}};
  size_t n;
  const struct vsph_params_spec *spec = vsph_laplacian_params(&n);
  const struct vsph_args_section sec = {"Laplacian", spec, n};
  const struct vsph_args_cmd c = {
      CMD,
      "[--form visc01|visc02|visc03|visc04] [options]",
      "The Laplacian patch test of Zheng, Ma & Shao (2018), Sec. 4: a form\n"
      "applied to a field sampled on n^d particles over the unit square\n"
      "(cube), cell-centred, optionally shifted per coordinate by up to\n"
      "perturb dx, padded with ghost particles carrying the field so that\n"
      "every evaluated particle has full support; against the exact\n"
      "Laplacian. Forms: visc01 hybrid (Brookshaw, Morris), visc02 direct\n"
      "(W'' - W'/r, scaled by 2/(d+2)), visc03 Schwaiger corrected, visc04\n"
      "Oger renormalised. Errors: eq. (21) (numerical denominator), the\n"
      "same with the exact denominator, and that times dx^2 (the scale of\n"
      "the paper's tables, docs/theory.md section 7).",
      own,
      1,
      &sec,
      1,
      NULL};
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return vsph_args_status(CMD, VSPH_ENOMEM);
  const int rc = vsph_args_parse(&c, argc, argv, prm);
  struct vsph_laplacian_props lp;
  int st = rc < 0 ? vsph_laplacian_props_init(&lp, prm) : 0;
  vsph_params_free(prm);
  if (rc >= 0) return rc;
  struct vsph_laplacian_result r;
  if (!st) st = vsph_laplacian_patch(&lp, &r);
  if (st) return vsph_args_status(CMD, st);
  if (json) return vsph_args_json(CMD, vsph_json_laplacian(&lp, &r));
  print_table(&lp, &r);
  return vsph_args_finish(CMD, 0);
}
