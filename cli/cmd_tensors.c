/* vsph tensors: F, G, N, M at a depth below the free surface (THEORY 2). */
#include "cmd_tensors.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../analysis/moments.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "args.h"
#include "writers.h"

static const char *const CMD = "tensors";

static void usage(FILE *f) {
  fputs(
      "usage: vsph tensors [--kernel NAME] [--dim D] [--depth DELTA]\n"
      "                    [--method quadrature|particles]\n"
      "                    [--lattice square|hex|perturbed] [--hdx R]\n"
      "                    [--perturb A] [--seed S] [--epsrel E] [--json]\n"
      "\n"
      "Kernel moment tensors F, G, N, M (THEORY.md section 2) for a point at\n"
      "depth DELTA (units of h) below a planar free surface with outward\n"
      "normal n = +e_d, in units where h = 1; with C_F and C_N.\n"
      "  --kernel   gaussian (default), cubic, quintic, wendland2, wendland4\n"
      "  --dim      1, 2 (default) or 3\n"
      "  --depth    0 = half support (default); >= kappa = full support\n"
      "  --method   quadrature (GSL, default) or particles (lattice sums;\n"
      "             prints the gap to quadrature)\n"
      "  --lattice  square (default), hex (2-D), perturbed (square lattice\n"
      "             shifted by up to A*dx per component, seeded)\n"
      "  --hdx      h/dx of the lattice (default 4/3; at most 256, 32 in\n"
      "             3-D)\n"
      "  --perturb  A for --lattice perturbed (default 0.1)\n"
      "  --seed     random seed (default 2385)\n"
      "  --epsrel   relative accuracy of the quadrature (default 1e-10)\n"
      "  --json     JSON with keys kernel, dim, depth, method, F, G, N, M,\n"
      "             C_F, C_N (and lattice, hdx, quadrature, gap for "
      "particles)\n",
      f);
}

static void print_table(const struct vsph_moments *m,
                        const struct vsph_moments *ref, const char *refname) {
  const int d = m->dim;
  printf("%-10s %22s", "entry", "value");
  if (ref) printf(" %22s %12s", refname, "gap");
  printf("\n");
#define ROW(label, v, r)                                \
  do {                                                  \
    if (fabs(v) > 1e-13 || (ref && fabs(r) > 1e-13)) {  \
      printf("%-10s %22.14e", label, v);                \
      if (ref) printf(" %22.14e %12.3e", r, (v) - (r)); \
      printf("\n");                                     \
    }                                                   \
  } while (0)
  char lab[32];
  for (int i = 0; i < d; i++) {
    snprintf(lab, sizeof lab, "N_%d", i + 1);
    ROW(lab, m->N[i], ref ? ref->N[i] : 0.0);
  }
  for (int i = 0; i < d; i++)
    for (int j = 0; j < d; j++) {
      snprintf(lab, sizeof lab, "M_%d%d", i + 1, j + 1);
      ROW(lab, m->M[i][j], ref ? ref->M[i][j] : 0.0);
    }
  for (int i = 0; i < d; i++)
    for (int j = 0; j < d; j++)
      for (int l = 0; l < d; l++) {
        snprintf(lab, sizeof lab, "F_%d%d%d", i + 1, j + 1, l + 1);
        ROW(lab, m->F[i][j][l], ref ? ref->F[i][j][l] : 0.0);
      }
  for (int i = 0; i < d; i++)
    for (int j = 0; j < d; j++)
      for (int l = 0; l < d; l++)
        for (int q = 0; q < d; q++) {
          snprintf(lab, sizeof lab, "G_%d%d%d%d", i + 1, j + 1, l + 1, q + 1);
          ROW(lab, m->G[i][j][l][q], ref ? ref->G[i][j][l][q] : 0.0);
        }
#undef ROW
  printf("(entries whose magnitude is below 1e-13 are not listed)\n");
}

int vsph_cmd_tensors_main(int argc, char **argv) {
  const char *kname = "gaussian", *method = "quadrature", *lattice = "square";
  double dimf = 2, depth = 0.0, hdx = 4.0 / 3.0, perturb = 0.1, epsrel = 1e-10;
  size_t seed = 2385;
  int json = 0;
  const struct vsph_args_spec specs[] = {
      {"--kernel", VSPH_ARGS_STRING, &kname},
      {"--method", VSPH_ARGS_STRING, &method},
      {"--lattice", VSPH_ARGS_STRING, &lattice},
      {"--dim", VSPH_ARGS_DOUBLE, &dimf},
      {"--depth", VSPH_ARGS_DOUBLE, &depth},
      {"--hdx", VSPH_ARGS_DOUBLE, &hdx},
      {"--perturb", VSPH_ARGS_DOUBLE, &perturb},
      {"--epsrel", VSPH_ARGS_DOUBLE, &epsrel},
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
  if (depth < 0)
    return vsph_args_fail(CMD, "--depth must be >= 0, got %g", depth);
  if (!(hdx > 0)) return vsph_args_fail(CMD, "--hdx must be > 0, got %g", hdx);
  /* A patch of radius (kappa + 2/hdx) h holds ~(kappa hdx)^d particles:
   * cap it at a few million. */
  const double hdx_max = dim == 3 ? 32.0 : 256.0;
  if (hdx > hdx_max)
    return vsph_args_fail(CMD,
                          "--hdx above %g in %d-D would need too many "
                          "particles, got %g",
                          hdx_max, dim, hdx);
  if (!(epsrel >= 1e-13 && epsrel < 1))
    return vsph_args_fail(CMD, "--epsrel must lie in [1e-13, 1), got %g",
                          epsrel);
  const int particles = !strcmp(method, "particles");
  if (!particles && strcmp(method, "quadrature"))
    return vsph_args_fail(CMD, "unknown method '%s'", method);
  int kind;
  double amp;
  if (vsph_args_lattice(CMD, lattice, dim, perturb, &kind, &amp)) return 2;
  const int perturbed = amp > 0.0;

  gsl_integration_workspace *wo = gsl_integration_workspace_alloc(1000);
  gsl_integration_workspace *wi = gsl_integration_workspace_alloc(1000);
  struct vsph_moments quad, sum;
  double C_F = 0, C_N = 0;
  size_t npart = 0;
  int st = (!wo || !wi) ? VSPH_ENOMEM : VSPH_OK;
  if (!st) st = vsph_moments_quadrature(k, dim, depth, epsrel, wo, wi, &quad);
  if (!st) st = vsph_moments_constants(k, dim, epsrel, wo, &C_F, &C_N);
  if (!st && particles) {
    struct vsph_lattice_props lp = {.dim = dim,
                                    .kind = kind,
                                    .dx = 1.0 / hdx,
                                    .perturb = amp,
                                    .seed = seed};
    struct vsph_particles *p = NULL;
    size_t centre;
    st = vsph_lattice_halfspace(&lp, k->kappa + 2.0 / hdx, depth, &p, &centre);
    if (!st) st = vsph_moments_sum(k, p, centre, 1.0, &sum);
    if (p) npart = p->n;
    vsph_particles_free(p);
  }
  gsl_integration_workspace_free(wo);
  gsl_integration_workspace_free(wi);
  if (st) return vsph_args_status(CMD, st);

  const struct vsph_moments *main_m = particles ? &sum : &quad;
  if (json) {
    cJSON *o = cJSON_CreateObject();
    cJSON_AddStringToObject(o, "kernel", k->name);
    cJSON_AddNumberToObject(o, "dim", dim);
    cJSON_AddNumberToObject(o, "depth", depth);
    cJSON_AddStringToObject(o, "method", method);
    vsph_writers_moments(o, main_m);
    cJSON_AddNumberToObject(o, "C_F", C_F);
    cJSON_AddNumberToObject(o, "C_N", C_N);
    cJSON_AddNumberToObject(o, "kappa", k->kappa);
    if (particles) {
      cJSON_AddStringToObject(o, "lattice", lattice);
      cJSON_AddNumberToObject(o, "hdx", hdx);
      if (perturbed) {
        cJSON_AddNumberToObject(o, "perturb", perturb);
        cJSON_AddNumberToObject(o, "seed", (double)seed);
      }
      cJSON_AddNumberToObject(o, "n_particles", (double)npart);
      cJSON *q = cJSON_CreateObject();
      vsph_writers_moments(q, &quad);
      cJSON_AddItemToObject(o, "quadrature", q);
      double gap[4];
      vsph_moments_gap(&sum, &quad, gap);
      cJSON *g = cJSON_CreateObject();
      cJSON_AddNumberToObject(g, "F", gap[0]);
      cJSON_AddNumberToObject(g, "G", gap[1]);
      cJSON_AddNumberToObject(g, "N", gap[2]);
      cJSON_AddNumberToObject(g, "M", gap[3]);
      cJSON_AddItemToObject(o, "gap", g);
    }
    return vsph_writers_print_json(o) ? 1 : 0;
  }
  printf(
      "# vsph %s tensors: kernel %s, dim %d, depth %g h (kappa = %g), "
      "h = 1, n = +e_%d\n",
      VSPH_VERSION, k->name, dim, depth, k->kappa, dim);
  printf("# C_F = %.14e   C_N = %.14e\n", C_F, C_N);
  if (particles) {
    printf(
        "# particle sums on a %s lattice, h/dx = %g, %zu particles; "
        "gap = sum - quadrature\n",
        lattice, hdx, npart);
    print_table(&sum, &quad, "quadrature");
  } else {
    struct vsph_moments th;
    const int half = depth == 0.0, full = depth >= k->kappa;
    if (half || full) {
      vsph_moments_theory(dim, half, C_F, C_N, &th);
      printf("# quadrature against the theoretical %s-support values\n",
             half ? "half" : "full");
      print_table(&quad, &th, "theory");
    } else {
      printf("# quadrature (no closed form at intermediate depth)\n");
      print_table(&quad, NULL, NULL);
    }
  }
  return 0;
}
