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
#include "args.h"

static const char *const CMD = "tensors";

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

int vsph_cmd_tensors_main(int argc, char **argv) {
  int json = 0;
  const struct vsph_args_spec own[] = {
      {"--json", VSPH_ARGS_FLAG, &json, NULL,
       "JSON with keys kernel, dim, depth, method, F, G, N, M, C_F, C_N (and "
       "lattice, hdx, n_particles, quadrature, gap for particles)"}};
  size_t n;
  const struct vsph_params_spec *spec = vsph_moments_params(&n);
  const struct vsph_args_section sec = {"Tensors", spec, n};
  const struct vsph_args_cmd c = {
      CMD,
      "[options]",
      "Kernel moment tensors F, G, N, M (THEORY section 2) for a point at a\n"
      "depth (units of h) below a planar free surface with outward normal\n"
      "n = +e_d, in units where h = 1, with the surface constants C_F and\n"
      "C_N; by quadrature, or by particle sums over a lattice beside the\n"
      "quadrature.",
      own,
      1,
      &sec,
      1,
      NULL};
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return vsph_args_status(CMD, VSPH_ENOMEM);
  int rc = vsph_args_parse(&c, argc, argv, prm);
  struct vsph_moments_props mp;
  struct vsph_moments_result r;
  int st = rc < 0 ? vsph_moments_props_init(&mp, prm) : 0;
  vsph_params_free(prm);
  if (rc >= 0) return rc;
  if (!st) st = vsph_moments_compute(&mp, &r);
  if (st) return vsph_args_status(CMD, st);
  if (json) return vsph_args_json(CMD, vsph_json_tensors(&mp, &r));
  const int d = mp.dim;
  printf(
      "# vsph %s tensors: kernel %s, dim %d, depth %g h (kappa = %g), h = 1, "
      "n = +e_%d\n# C_F = %.14e   C_N = %.14e\n",
      VSPH_VERSION, mp.kernel->name, d, mp.depth, mp.kernel->kappa, d, r.C_F,
      r.C_N);
  if (mp.particles) {
    printf(
        "# particle sums on a %s lattice, h/dx = %g, %zu particles; gap = "
        "sum - quadrature\n",
        mp.lattice, mp.hdx, r.n_particles);
    print_table(&r.sum, &r.quad, "quadrature");
  } else if (r.have_theory) {
    printf("# quadrature against the theoretical %s-support values\n",
           mp.depth == 0.0 ? "half" : "full");
    print_table(&r.quad, &r.theory, "theory");
  } else {
    printf("# quadrature (no closed form at intermediate depth)\n");
    print_table(&r.quad, NULL, NULL);
  }
  return vsph_args_finish(CMD, 0);
}
