/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
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

/* the command's state */
struct work {
  struct vsph_laplacian_props lp;
  struct vsph_laplacian_result r;
};

static int init(void *w, struct vsph_params *prm) {
  return vsph_laplacian_props_init(&((struct work *)w)->lp, prm);
}

static int compute(void *w) {
  struct work *k = w;
  return vsph_laplacian_patch(&k->lp, &k->r);
}

static void *json(const void *w) {
  const struct work *k = w;
  return vsph_json_laplacian(&k->lp, &k->r);
}

static int print_table(const void *w) {
  const struct vsph_laplacian_props *lp = &((const struct work *)w)->lp;
  const struct vsph_laplacian_result *r = &((const struct work *)w)->r;
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
  printf(
      "on the line x = %g   %.6e   eq. (21) times dx^2 over its %zu "
      "particles (%.6e with the exact denom.)\n",
      lp->line_x, r->err_line_literal, r->n_line, r->err_line_paper);
  return 0;
}

int vsph_cmd_laplacian_main(int argc, char **argv) {
  static const struct vsph_args_analysis a = {
      "laplacian",
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
      "JSON with keys form, field, kernel, dim, n, hdx, perturb, seed, eta, "
      "n_eval, n_total, dx, h, err_literal, err_exact, err_paper, abs_max, "
      "ref_max, line_x, n_line, err_line_literal, err_line_paper",
      "Laplacian",
      vsph_laplacian_params,
      init,
      compute,
      json,
      print_table};
  struct work w;
  return vsph_args_analysis_main(&a, &w, argc, argv);
}
