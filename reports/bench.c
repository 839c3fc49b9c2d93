/* `make bench`: timings of the quadrature, the particle sums, the viscous
 * operators and the solver. Timings live here, never in the tests. */
#include "bench.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/moments.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/equations.h"
#include "../solver/integrate.h"
#include "../solver/lattice.h"
#include "../solver/pair.h"
#include "../solver/particles.h"
#include "../solver/scene.h"
#include "../solver/viscous.h"

/* Best of `reps` wall times of fn(arg). */
static double best_of(int reps, void (*fn)(void *), void *arg) {
  double best = INFINITY;
  for (int r = 0; r < reps; r++) {
    const double t = omp_get_wtime();
    fn(arg);
    best = fmin(best, omp_get_wtime() - t);
  }
  return best;
}

struct quad_arg {
  const struct vsph_kernel_type *k;
  int dim;
  double depth;
  gsl_integration_workspace *wo, *wi;
};
static void quad_once(void *v) {
  struct quad_arg *a = v;
  struct vsph_moments m;
  vsph_moments_quadrature(a->k, a->dim, a->depth, 1e-10, a->wo, a->wi, &m);
}

struct sum_arg {
  struct vsph_particles *p;
  size_t c;
};
static void sum_once(void *v) {
  struct sum_arg *a = v;
  struct vsph_moments m;
  vsph_moments_sum(&vsph_gaussian_type, a->p, a->c, 1.0, &m);
}

struct visc_arg {
  struct vsph_viscous_props vp;
  struct vsph_particles *p;
  struct vsph_cells *c;
  struct vsph_viscous_ws *ws;
  double *f[3];
};
static void visc_once(void *v) {
  struct visc_arg *a = v;
  vsph_viscous_compute(&a->vp, a->p, a->c, a->ws, a->f, NULL);
}

struct solver_arg {
  struct vsph_integrate *s;
  struct vsph_equations_out out;
  double dt;
};
static void rhs_once(void *v) {
  struct solver_arg *a = v;
  vsph_equations_rhs(&a->s->props.eq, a->s->p, a->s->n_fluid, a->s->cells,
                     a->s->vws, &a->out);
}
static void step_once(void *v) {
  struct solver_arg *a = v;
  vsph_integrate_step(a->s, a->dt);
}

/* The stretching square at res across, formulation form, ready to step. */
static struct vsph_integrate *bench_run(int form, size_t res) {
  struct vsph_scene sc;
  struct vsph_particles *fluid = NULL;
  struct vsph_integrate_props ip;
  if (vsph_scene_init(&sc, &vsph_stretching_square_type, NULL) ||
      sc.type->init(&sc, res, &fluid) ||
      vsph_scene_integrate_props(&sc, form, &vsph_gaussian_type,
                                 VSPH_CONSTS_HDX * sc.ref_length / (double)res,
                                 &ip)) {
    vsph_particles_free(fluid);
    return NULL;
  }
  ip.cfl = 1.0;
  ip.rho_band = 1.0;
  return vsph_integrate_alloc(&ip, fluid);
}

static int bench_solver(FILE *out) {
  const size_t sizes[2] = {100, 316};
  double per_ps[3][2];
  fprintf(out,
          "\n## solver: stretching square, h/dx 4/3, 3h Gaussian, best of "
          "15 (force) and 7 (step)\n");
  fprintf(out, "%-5s %8s %11s %11s %13s %8s %11s %11s %13s %8s %9s\n", "form",
          "N", "rhs 1t ms", "rhs 2t ms", "inter/s/core", "speedup",
          "step 1t ms", "step 2t ms", "p-steps/s 2t", "speedup", "B/part");
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++)
    for (int z = 0; z < 2; z++) {
      struct solver_arg a = {.s = bench_run(form, sizes[z])};
      if (!a.s) return VSPH_ENOMEM;
      struct vsph_particles *p = a.s->p;
      a.dt = vsph_integrate_dt(a.s);
      vsph_integrate_step(a.s, a.dt); /* builds cells, warms up */
      double *buf = malloc(3 * p->n * sizeof *buf);
      if (!buf) {
        vsph_integrate_free(a.s);
        VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the bench's buffers");
      }
      a.out.drho = buf;
      a.out.acc[0] = buf + p->n;
      a.out.acc[1] = buf + 2 * p->n;
      omp_set_num_threads(1);
      rhs_once(&a);
      const size_t inter = a.out.interactions;
      /* best of 15 (force) and 7 (step): the minimum filters the noise of
       * a shared 2-core machine */
      const double r1 = best_of(15, rhs_once, &a);
      omp_set_num_threads(2);
      const double r2 = best_of(15, rhs_once, &a);
      omp_set_num_threads(1);
      const double s1 = best_of(7, step_once, &a);
      omp_set_num_threads(2);
      const double s2 = best_of(7, step_once, &a);
      const double passes = form == VSPH_VISCOUS_PVWF ? 2.0 : 1.0;
      const size_t n = a.s->n_fluid;
      per_ps[form][z] = s1 / (double)n;
      fprintf(out,
              "%-5s %8zu %11.3f %11.3f %13.3e %8.2f %11.3f %11.3f %13.3e %8.2f "
              "%9.0f\n",
              vsph_viscous_name(form), n, 1e3 * r1, 1e3 * r2,
              passes * (double)inter / r1, r1 / r2, 1e3 * s1, 1e3 * s2,
              (double)n / s2, s1 / s2,
              (double)vsph_integrate_bytes(a.s) / (double)n);
      free(buf);
      vsph_integrate_free(a.s);
    }
  fprintf(out, "cost per particle-step, 1 thread, N = 1e5 over N = 1e4:");
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++)
    fprintf(out, "  %s %.3f", vsph_viscous_name(form),
            per_ps[form][1] / per_ps[form][0]);
  fprintf(out,
          "\n(PVWF counts its two passes as two interactions per pair; "
          "inter/s/core is the 1-thread rate)\n");
  return 0;
}

/* Directed interactions (i gathering from j != i within kappa h) of one
 * pass, by the operators' own neighbour loop. */
static size_t count_interactions(const struct vsph_cells *c,
                                 const struct vsph_particles *p, double h) {
  struct vsph_pair_kernel pk;
  vsph_pair_kernel_init(&pk, &vsph_gaussian_type, p->dim, h);
  size_t n = 0;
  for (size_t cell = 0; cell < c->ncells; cell++) {
    struct vsph_pair_ranges rg;
    vsph_pair_ranges_cell(&rg, c, cell);
    for (size_t i = c->start[cell]; i < c->start[cell] + c->count[cell]; i++) {
      struct vsph_pair_iter it;
      struct vsph_pair_chunk b;
      vsph_pair_begin(&it, &pk, p, &rg, i);
      while (vsph_pair_gather(&it, p->dim, pk.dfq_id, &b)) n += b.m;
    }
  }
  return n;
}

/* The machine's load (the first three fields of /proc/loadavg). */
static void print_load(FILE *out) {
  FILE *f = fopen("/proc/loadavg", "r"); /* size 0 to stat: read a line */
  char line[128] = "";
  double a = NAN, b = NAN, c = NAN;
  if (f && fgets(line, sizeof line, f)) sscanf(line, "%lf %lf %lf", &a, &b, &c);
  if (f) fclose(f);
  fprintf(out, "# load average %.2f %.2f %.2f (1, 5, 15 min)\n", a, b, c);
}

static int bench_quadrature(FILE *out) {
  fprintf(out, "\n## F, G, N, M by quadrature (epsrel 1e-10), best of 5, ms\n");
  fprintf(out, "%-10s %4s %10s %10s %10s\n", "kernel", "dim", "depth 0",
          "depth 1.3", "depth k");
  struct quad_arg qa;
  qa.wo = gsl_integration_workspace_alloc(1000);
  qa.wi = gsl_integration_workspace_alloc(1000);
  if (!qa.wo || !qa.wi) {
    gsl_integration_workspace_free(qa.wo);
    gsl_integration_workspace_free(qa.wi);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate workspaces");
  }
  for (size_t ki = 0; ki < vsph_kernel_count(); ki++)
    for (int dim = 2; dim <= 3; dim++) {
      qa.k = vsph_kernel_get(ki);
      qa.dim = dim;
      fprintf(out, "%-10s %4d", qa.k->name, dim);
      const double depths[3] = {0.0, 1.3, qa.k->kappa};
      for (int d = 0; d < 3; d++) {
        qa.depth = depths[d];
        fprintf(out, " %10.3f", 1e3 * best_of(5, quad_once, &qa));
      }
      fprintf(out, "\n");
    }
  gsl_integration_workspace_free(qa.wo);
  gsl_integration_workspace_free(qa.wi);
  return VSPH_OK;
}

static int bench_sums(FILE *out) {
  fprintf(out, "\n## particle sums (3-D half space, 3h Gaussian), best of 5\n");
  fprintf(out, "%8s %10s %12s %12s\n", "h/dx", "particles", "time (ms)",
          "ns/particle");
  for (double hdx = 2.0; hdx <= 16.0; hdx *= 2.0) {
    struct vsph_lattice_props lp = {.dim = 3, .dx = 1.0 / hdx};
    struct sum_arg sa;
    const int st =
        vsph_lattice_halfspace(&lp, 3.0 + 2.0 / hdx, 0.0, &sa.p, &sa.c);
    if (st) return st;
    const double t = best_of(5, sum_once, &sa);
    fprintf(out, "%8.1f %10zu %12.3f %12.2f\n", hdx, sa.p->n, 1e3 * t,
            1e9 * t / (double)sa.p->n);
    vsph_particles_free(sa.p);
  }
  return VSPH_OK;
}

static int bench_operators(FILE *out, size_t side) {
  fprintf(out,
          "\n## viscous operators, %zu x %zu square, h/dx 4/3, best of 5\n",
          side, side);
  struct vsph_lattice_props lp = {.dim = 2};
  struct visc_arg va;
  int st = vsph_lattice_square(&lp, 1.0, side, &va.p);
  if (st) return st;
  const double dx = 1.0 / (double)side, h = VSPH_CONSTS_HDX * dx;
  for (size_t i = 0; i < va.p->n; i++) { /* a smooth non-trivial field */
    va.p->vel[0][i] = sin(3.1 * va.p->pos[1][i]);
    va.p->vel[1][i] = cos(2.3 * va.p->pos[0][i]);
  }
  va.c = vsph_cells_alloc();
  va.ws = vsph_viscous_ws_alloc(va.p->n, 2);
  double *buf = malloc(2 * va.p->n * sizeof *buf);
  if (!va.c || !va.ws || !buf) {
    st = VSPH_ENOMEM;
    goto done;
  }
  va.f[0] = buf;
  va.f[1] = buf + va.p->n;
  va.f[2] = NULL;
  if ((st = vsph_cells_build(va.c, va.p, 3.0 * h))) goto done;
  const size_t inter = count_interactions(va.c, va.p, h);
  fprintf(out, "particles %zu, interactions per pass %zu (%.1f per particle)\n",
          va.p->n, inter, (double)inter / (double)va.p->n);
  fprintf(out, "%-6s %12s %12s %16s %9s\n", "form", "1 thr (ms)", "2 thr (ms)",
          "inter/s/core (1)", "speed-up");
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT && !st; form++) {
    if ((st = vsph_viscous_props_init(&va.vp, form, &vsph_gaussian_type, 2, h,
                                      0.01)))
      break;
    const double passes = form == VSPH_VISCOUS_PVWF ? 2.0 : 1.0;
    omp_set_num_threads(1);
    const double t1 = best_of(5, visc_once, &va);
    omp_set_num_threads(2);
    const double t2 = best_of(5, visc_once, &va);
    fprintf(out, "%-6s %12.3f %12.3f %16.3e %9.2f\n", vsph_viscous_name(form),
            1e3 * t1, 1e3 * t2, passes * (double)inter / t1, t1 / t2);
  }
done:
  free(buf);
  vsph_viscous_ws_free(va.ws);
  vsph_cells_free(va.c);
  vsph_particles_free(va.p);
  return st;
}

int vsph_bench_run(const struct vsph_bench_props *bp, FILE *out) {
  if (bp->size < 10 || bp->size > 2000)
    VSPH_FAIL(VSPH_EINVAL,
              "the square must have 10-2000 particles across, "
              "got %zu",
              bp->size);
  fprintf(out, "# vsph %s bench, %d threads available\n", VSPH_VERSION,
          omp_get_max_threads());
  print_load(out);
  int st = VSPH_OK;
  if (!bp->solver_only) {
    st = bench_quadrature(out);
    if (!st) st = bench_sums(out);
    if (!st) st = bench_operators(out, bp->size);
  }
  if (!st) st = bench_solver(out);
  if (!st) print_load(out);
  return st;
}
