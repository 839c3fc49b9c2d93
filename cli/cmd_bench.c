/* vsph bench: timings of the analysis building blocks. Timings live here
 * and in `make bench`, never in the tests. */
#include "cmd_bench.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/moments.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../kernels/kernel.h"
#include "../solver/cells.h"
#include "../solver/equations.h"
#include "../solver/integrate.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "../solver/scene.h"
#include "../solver/viscous.h"
#include "args.h"

static const char *const CMD = "bench";

static void usage(FILE *f) {
  fputs(
      "usage: vsph bench [--size N] [--solver-only]\n\n"
      "Times (1) F, G, N, M by quadrature at one depth for every kernel in\n"
      "2-D and 3-D; (2) the particle sums against the number of particles;\n"
      "(3) each viscous operator on an N x N square (default N = 200) at\n"
      "h/dx = 4/3 with the 3h Gaussian, with 1 and 2 threads. An\n"
      "interaction is particle i gathering from one neighbour j within\n"
      "kappa h (each unique pair counts twice); PVWF makes two passes, so\n"
      "it does two interactions per pair per evaluation.\n"
      "(4) the solver on the stretching square (no walls) at about 1e4 and\n"
      "1e5 particles: one force evaluation (continuity, pressure, viscous;\n"
      "delta-SPH off) and one whole RK4 step, per formulation, with 1 and 2\n"
      "threads; interactions per second per core, particle-steps per second,\n"
      "memory per particle, and the cost per particle-step against N.\n"
      "--solver-only skips (1)-(3).\n",
      f);
}

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
  struct vsph_params *prm = vsph_params_alloc();
  struct vsph_scene sc;
  struct vsph_particles *fluid = NULL;
  struct vsph_integrate *s = NULL;
  struct vsph_integrate_props ip;
  if (prm && !vsph_scene_init(&sc, &vsph_stretching_square_type, prm) &&
      !sc.type->init(&sc, res, &fluid) &&
      !vsph_scene_integrate_props(&sc, form, &vsph_gaussian_type,
                                  4.0 / 3.0 * sc.ref_length / (double)res,
                                  &ip)) {
    ip.cfl = 1.0;
    ip.rho_band = 1.0;
    s = vsph_integrate_alloc(&ip, fluid);
  }
  vsph_params_free(prm);
  return s;
}

static int bench_solver(void) {
  const size_t sizes[2] = {100, 316};
  double per_ps[3][2];
  printf(
      "\n## solver: stretching square, h/dx 4/3, 3h Gaussian, best of "
      "15 (force) and 7 (step)\n");
  printf("%-5s %8s %11s %11s %13s %8s %11s %11s %13s %8s %9s\n", "form", "N",
         "rhs 1t ms", "rhs 2t ms", "inter/s/core", "speedup", "step 1t ms",
         "step 2t ms", "p-steps/s 2t", "speedup", "B/part");
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++)
    for (int z = 0; z < 2; z++) {
      struct solver_arg a = {.s = bench_run(form, sizes[z])};
      if (!a.s) return 1;
      struct vsph_particles *p = a.s->p;
      a.dt = vsph_integrate_dt(a.s);
      vsph_integrate_step(a.s, a.dt); /* builds cells, warms up */
      double *buf = malloc(3 * p->n * sizeof *buf);
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
      printf(
          "%-5s %8zu %11.3f %11.3f %13.3e %8.2f %11.3f %11.3f %13.3e %8.2f "
          "%9.0f\n",
          vsph_viscous_name(form), n, 1e3 * r1, 1e3 * r2,
          passes * (double)inter / r1, r1 / r2, 1e3 * s1, 1e3 * s2,
          (double)n / s2, s1 / s2,
          (double)vsph_integrate_bytes(a.s) / (double)n);
      free(buf);
      vsph_integrate_free(a.s);
    }
  printf("cost per particle-step, 1 thread, N = 1e5 over N = 1e4:");
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++)
    printf("  %s %.3f", vsph_viscous_name(form),
           per_ps[form][1] / per_ps[form][0]);
  printf(
      "\n(PVWF counts its two passes as two interactions per pair; "
      "inter/s/core is the 1-thread rate)\n");
  return 0;
}

static size_t count_interactions(const struct vsph_cells *c,
                                 const struct vsph_particles *p, double H) {
  size_t n = 0;
  for (size_t cell = 0; cell < c->ncells; cell++) {
    size_t lo[VSPH_CELLS_MAXRANGES], hi[VSPH_CELLS_MAXRANGES];
    const size_t nr = vsph_cells_ranges(c, cell, lo, hi);
    for (size_t i = c->start[cell]; i < c->start[cell] + c->count[cell]; i++)
      for (size_t r = 0; r < nr; r++)
        for (size_t j = lo[r]; j < hi[r]; j++) {
          const double dx = p->pos[0][j] - p->pos[0][i];
          const double dy = p->pos[1][j] - p->pos[1][i];
          n += j != i && dx * dx + dy * dy < H * H;
        }
  }
  return n;
}

int vsph_cmd_bench_main(int argc, char **argv) {
  size_t side = 200;
  int solver_only = 0;
  const struct vsph_args_spec specs[] = {
      {"--size", VSPH_ARGS_SIZE, &side},
      {"--solver-only", VSPH_ARGS_FLAG, &solver_only},
  };
  const int pr = vsph_args_parse(CMD, argc, argv, specs, 2, usage);
  if (pr >= 0) return pr;
  if (side < 10 || side > 2000)
    return vsph_args_fail(CMD, "--size must lie in 10-2000, got %zu", side);
  printf("# vsph %s bench, %d threads available\n", VSPH_VERSION,
         omp_get_max_threads());
  if (solver_only) return bench_solver();
  printf("\n## F, G, N, M by quadrature (epsrel 1e-10), best of 5, ms\n");
  printf("%-10s %4s %10s %10s %10s\n", "kernel", "dim", "depth 0", "depth 1.3",
         "depth k");
  struct quad_arg qa;
  qa.wo = gsl_integration_workspace_alloc(1000);
  qa.wi = gsl_integration_workspace_alloc(1000);
  for (size_t ki = 0; ki < vsph_kernel_count(); ki++)
    for (int dim = 2; dim <= 3; dim++) {
      qa.k = vsph_kernel_get(ki);
      qa.dim = dim;
      printf("%-10s %4d", qa.k->name, dim);
      const double depths[3] = {0.0, 1.3, qa.k->kappa};
      for (int d = 0; d < 3; d++) {
        qa.depth = depths[d];
        printf(" %10.3f", 1e3 * best_of(5, quad_once, &qa));
      }
      printf("\n");
    }
  gsl_integration_workspace_free(qa.wo);
  gsl_integration_workspace_free(qa.wi);

  printf("\n## particle sums (3-D half space, 3h Gaussian), best of 5\n");
  printf("%8s %10s %12s %12s\n", "h/dx", "particles", "time (ms)",
         "ns/particle");
  for (double hdx = 2.0; hdx <= 16.0; hdx *= 2.0) {
    struct vsph_lattice_props lp = {.dim = 3, .dx = 1.0 / hdx};
    struct sum_arg sa;
    if (vsph_lattice_halfspace(&lp, 3.0 + 2.0 / hdx, 0.0, &sa.p, &sa.c))
      return vsph_args_status(CMD, 1);
    const double t = best_of(5, sum_once, &sa);
    printf("%8.1f %10zu %12.3f %12.2f\n", hdx, sa.p->n, 1e3 * t,
           1e9 * t / (double)sa.p->n);
    vsph_particles_free(sa.p);
  }

  printf("\n## viscous operators, %zu x %zu square, h/dx 4/3, best of 5\n",
         side, side);
  struct vsph_lattice_props lp = {.dim = 2};
  struct visc_arg va;
  if (vsph_lattice_square(&lp, 1.0, side, &va.p))
    return vsph_args_status(CMD, 1);
  const double dx = 1.0 / (double)side, h = 4.0 / 3.0 * dx;
  for (size_t i = 0; i < va.p->n; i++) { /* a smooth non-trivial field */
    va.p->vel[0][i] = sin(3.1 * va.p->pos[1][i]);
    va.p->vel[1][i] = cos(2.3 * va.p->pos[0][i]);
  }
  va.c = vsph_cells_alloc();
  va.ws = vsph_viscous_ws_alloc(va.p->n, 2);
  double *buf = malloc(2 * va.p->n * sizeof *buf);
  va.f[0] = buf;
  va.f[1] = buf + va.p->n;
  va.f[2] = NULL;
  vsph_cells_build(va.c, va.p, 3.0 * h);
  const size_t inter = count_interactions(va.c, va.p, 3.0 * h);
  printf("particles %zu, interactions per pass %zu (%.1f per particle)\n",
         va.p->n, inter, (double)inter / (double)va.p->n);
  printf("%-6s %12s %12s %16s %9s\n", "form", "1 thr (ms)", "2 thr (ms)",
         "inter/s/core (1)", "speed-up");
  for (int form = 0; form < VSPH_VISCOUS_FORM_COUNT; form++) {
    vsph_viscous_props_init(&va.vp, form, &vsph_gaussian_type, 2, h, 0.01);
    const double passes = form == VSPH_VISCOUS_PVWF ? 2.0 : 1.0;
    omp_set_num_threads(1);
    const double t1 = best_of(5, visc_once, &va);
    omp_set_num_threads(2);
    const double t2 = best_of(5, visc_once, &va);
    printf("%-6s %12.3f %12.3f %16.3e %9.2f\n", vsph_viscous_name(form),
           1e3 * t1, 1e3 * t2, passes * (double)inter / t1, t1 / t2);
  }
  free(buf);
  vsph_viscous_ws_free(va.ws);
  vsph_cells_free(va.c);
  vsph_particles_free(va.p);
  return bench_solver();
}
