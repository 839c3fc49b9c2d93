/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph tensors: F, G, N, M at a depth below the free surface (THEORY 2). */
#include "cmd_tensors.h"

#include <math.h>
#include <stdio.h>

#include "../analysis/moments.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/json.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "args.h"

/* One table row per non-negligible entry: value, and reference and gap. */
static void row(const char *label, double v, const double *ref) {
  if (!(fabs(v) > 1e-13 || (ref && fabs(*ref) > 1e-13))) return;
  printf("%-10s %22.14e", label, v);
  if (ref) printf(" %22.14e %12.3e", *ref, v - *ref);
  printf("\n");
}

static void print_table(const struct vsph_moments *m,
                        const struct vsph_moments *ref, const char *refname) {
  const int d = m->dim;
  printf("%-10s %22s", "entry", "value");
  if (ref) printf(" %22s %12s", refname, "gap");
  printf("\n");
  char lab[32];
  for (int i = 0; i < d; i++) {
    snprintf(lab, sizeof lab, "N_%d", i + 1);
    row(lab, m->N[i], ref ? &ref->N[i] : NULL);
  }
  for (int i = 0; i < d; i++)
    for (int j = 0; j < d; j++) {
      snprintf(lab, sizeof lab, "M_%d%d", i + 1, j + 1);
      row(lab, m->M[i][j], ref ? &ref->M[i][j] : NULL);
    }
  for (int i = 0; i < d; i++)
    for (int j = 0; j < d; j++)
      for (int l = 0; l < d; l++) {
        snprintf(lab, sizeof lab, "F_%d%d%d", i + 1, j + 1, l + 1);
        row(lab, m->F[i][j][l], ref ? &ref->F[i][j][l] : NULL);
      }
  for (int i = 0; i < d; i++)
    for (int j = 0; j < d; j++)
      for (int l = 0; l < d; l++)
        for (int q = 0; q < d; q++) {
          snprintf(lab, sizeof lab, "G_%d%d%d%d", i + 1, j + 1, l + 1, q + 1);
          row(lab, m->G[i][j][l][q], ref ? &ref->G[i][j][l][q] : NULL);
        }
  printf("(entries whose magnitude is below 1e-13 are not listed)\n");
}

/* the command's state */
struct work {
  struct vsph_moments_props mp;
  struct vsph_moments_result r;
};

static int init(void *w, struct vsph_params *prm) {
  return vsph_moments_props_init(&((struct work *)w)->mp, prm);
}

static int compute(void *w) {
  struct work *k = w;
  return vsph_moments_compute(&k->mp, &k->r);
}

static void *json(const void *w) {
  const struct work *k = w;
  return vsph_json_tensors(&k->mp, &k->r);
}

static int print(const void *w) {
  const struct vsph_moments_props *mp = &((const struct work *)w)->mp;
  const struct vsph_moments_result *r = &((const struct work *)w)->r;
  const int d = mp->dim;
  printf(
      "# vsph %s tensors: kernel %s, dim %d, depth %g h (kappa = %g), h = 1, "
      "n = +e_%d\n# C_F = %.14e   C_N = %.14e\n",
      VSPH_VERSION, mp->kernel->name, d, mp->depth, mp->kernel->kappa, d,
      r->C_F, r->C_N);
  if (mp->particles) {
    printf(
        "# particle sums on a %s lattice, h/dx = %g, %zu particles; gap = "
        "sum - quadrature\n",
        vsph_lattice_label(mp->lattice_kind, mp->perturb), mp->hdx,
        r->n_particles);
    print_table(&r->sum, &r->quad, "quadrature");
  } else if (r->have_theory) {
    printf("# quadrature against the theoretical %s-support values\n",
           mp->depth == 0.0 ? "half" : "full");
    print_table(&r->quad, &r->theory, "theory");
  } else {
    printf("# quadrature (no closed form at intermediate depth)\n");
    print_table(&r->quad, NULL, NULL);
  }
  return 0;
}

int vsph_cmd_tensors_main(int argc, char **argv) {
  static const struct vsph_args_analysis a = {
      "tensors",
      "[options]",
      "Kernel moment tensors F, G, N, M (THEORY section 2) for a point at a\n"
      "depth (units of h) below a planar free surface with outward normal\n"
      "n = +e_d, in units where h = 1, with the surface constants C_F and\n"
      "C_N; by quadrature, or by particle sums over a lattice beside the\n"
      "quadrature.",
      "JSON with keys kernel, dim, depth, method, F, G, N, M, C_F, C_N (and "
      "lattice, hdx, n_particles, quadrature, gap for particles)",
      "Tensors",
      vsph_moments_params,
      init,
      compute,
      json,
      print};
  struct work w;
  return vsph_args_analysis_main(&a, &w, argc, argv);
}
