/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph dissipation: P = sum V_i u_i.(div V)_i against -int V:D and
 * -mu int |grad u|^2 (THEORY 4). */
#include "cmd_dissipation.h"

#include <stdio.h>

#include "../analysis/dissipation.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/json.h"
#include "../kernels/kernel.h"
#include "../solver/viscous.h"
#include "args.h"

/* the command's state */
struct work {
  struct vsph_dissipation_props dp;
  struct vsph_dissipation_result r;
};

static int init(void *w, struct vsph_params *prm) {
  return vsph_dissipation_props_init(&((struct work *)w)->dp, prm);
}

static int compute(void *w) {
  struct work *k = w;
  return vsph_dissipation_compute(&k->dp, &k->r);
}

static void *json(const void *w) {
  const struct work *k = w;
  return vsph_json_dissipation(&k->dp, &k->r);
}

static int print_table(const void *w) {
  const struct vsph_dissipation_props *dp = &((const struct work *)w)->dp;
  const struct vsph_dissipation_result *r = &((const struct work *)w)->r;
  printf(
      "# vsph %s dissipation: %s, field %s, %s, %zu across, h/dx = %g, "
      "kernel %s, mu = %g, perturbation %g dx\n",
      VSPH_VERSION, vsph_viscous_name(dp->form),
      vsph_fields_name(dp->field.kind), vsph_dissipation_shape_name(dp->shape),
      dp->nacross, dp->hdx, dp->kernel->name, dp->mu, dp->perturb);
  printf("particles          %zu (%zu with full support)\n", r->n_particles,
         r->n_interior);
  printf("P                  %.12e\n", r->P);
  printf("P (pairwise form)  %.12e\n", r->P_pair);
  printf("P_exact  -int V:D  %.12e\n", r->P_exact);
  printf("P_grad   -mu|gu|^2 %.12e\n", r->P_grad);
  printf("P_limit  (%-9s) %.12e\n",
         vsph_viscous_limit_name(vsph_viscous_types[dp->form]->limit),
         r->P_limit);
  printf("rel_error          %+.6e\n", r->rel_error);
  printf("  consistency      %+.6e\n", r->consistency_error);
  printf("  lattice (h/dx)   %+.6e\n", r->lattice_error);
  printf("  surface (h/L)    %+.6e\n", r->surface_error);
  printf("momentum residual  %.3e   angular %.3e\n", r->momentum, r->angular);
  return 0;
}

int vsph_cmd_dissipation_main(int argc, char **argv) {
  static const struct vsph_args_analysis a = {
      "dissipation",
      "[--formulation NAME] [--field NAME] [options]",
      "Discrete dissipation P = sum_i V_i u_i.(div V)_i of a formulation for\n"
      "an analytic 2-D field on a square (side 1 m) or a disc (diameter 1 m,\n"
      "concentric rings): rotation u = Omega(-y, x) (exact P = 0), strain\n"
      "u = A(x, -y) (exact -4 mu A^2 |S|), mixed = rotation + strain + a\n"
      "Taylor-Green cell; against P_exact = -int V:D dV and\n"
      "P_grad = -mu int |grad u|^2 dV (GSL quadrature). rel_error =\n"
      "(P - P_exact)/|P_exact| (P/|P_grad| when P_exact = 0), split into\n"
      "consistency (P_limit - P_exact: the form's continuum limit P_limit is\n"
      "P_exact for a stress form, P_grad for a pair form along the velocity\n"
      "difference (MEAF, ER), mu int u.lap u dV for a per-particle\n"
      "Laplacian (A, VISC-0x)), lattice (full-support particles against the\n"
      "limit: depends on h/dx only) and surface (the rest: shrinks like h/L)\n"
      "errors.",
      "JSON with keys P, P_exact, P_grad, P_limit, limit, rel_error, "
      "consistency_error, "
      "lattice_error, surface_error, P_pair, momentum, angular, "
      "n_particles, n_interior, h, dx, n_fallback",
      "Dissipation",
      vsph_dissipation_params,
      init,
      compute,
      json,
      print_table};
  struct work w;
  return vsph_args_analysis_main(&a, &w, argc, argv);
}
