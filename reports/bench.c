/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* `make bench`: timings of the quadrature, the particle sums, the viscous
 * operators and the solver. Timings live here, never in the tests. */
#include "bench.h"

#include <dirent.h>
#include <fcntl.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../analysis/moments.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../common/sysinfo.h"
#include "../io/json.h"
#include "../kernels/kernel.h"
#include "../runs/jobs.h"
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

/* Scene sc (the stretching square or the standing wave) at res across,
 * formulation form, delta-SPH coefficient delta (or contact SPH with the
 * scene's viscosity, its stress uncorrected, when contact), kernel k at
 * h/dx hdx, ready to step. */
static struct vsph_integrate *bench_run(const struct vsph_scene_type *type,
                                        int form, size_t res, double delta,
                                        int contact,
                                        const struct vsph_kernel_type *k,
                                        double hdx) {
  struct vsph_scene sc;
  struct vsph_particles *fluid = NULL;
  struct vsph_integrate_props ip;
  if (vsph_scene_init(&sc, type, NULL) || sc.type->init(&sc, res, &fluid) ||
      vsph_scene_integrate_props(&sc, form, k,
                                 hdx * sc.ref_length / (double)res, &ip)) {
    vsph_particles_free(fluid);
    return NULL;
  }
  ip.cfl = 1.0;
  ip.rho_band = 1.0;
  ip.eq.delta = delta;
  if (contact) {
    ip.eq.scheme = VSPH_EQUATIONS_CONTACT;
    ip.eq.nmat = 1;
    ip.eq.mat[0] = (struct vsph_equations_mat){
        .rho0 = ip.eq.rho0, .c0 = ip.eq.c0, .mu = ip.eq.visc.mu};
  }
  return vsph_integrate_alloc(&ip, fluid);
}

/* The bench's progress on stderr: a line per row measured, with the
 * time left: each section's rows left at that section's rate so far, or
 * before its first row at the prior (seconds a row, measured on the
 * project's 2-core machine at --size 200: quadrature 0.05, particle sums
 * 0.25, operators 0.4, solver 1.3). The table itself goes to its stream,
 * flushed row by row. */
enum { SEC_QUAD, SEC_SUMS, SEC_OPS, SEC_SOLVER, NSEC };
struct progress {
  double t0, t_row;              /* start; the last row's end */
  double rows[NSEC], done[NSEC]; /* each section's cost, and that done */
  double spent[NSEC];            /* each section's seconds so far */
  size_t nrow, nrows;            /* rows measured, of all */
  FILE *out;                     /* the table's stream */
};

/* A solver row's cost in units of MGF's force row (measured on the
 * project's machine, 2026-12-06, at load 5.8, one process, the row's
 * time over MGF's force row's: MEAF, delta and the gather 0.9-1.0,
 * PVWF's force 1.7-2.0, contact SPH's 2.0, the general loop's 2.1; the
 * step rows, with their two whole runs for the memory, 17.7 (square,
 * MGF), 21.5 (square, PVWF), 11.5 (standing wave)). */
static double row_cost(const char *what) {
  if (!strncmp(what, "step", 4))
    return strstr(what, "PVWF") ? 21.5 : strstr(what, "wave") ? 11.5 : 17.7;
  return strstr(what, "PVWF")      ? 1.9
         : strstr(what, "contact") ? 2.0
         : strstr(what, "general") ? 2.1
                                   : 1.0;
}

/* A progress line: @p cost of section @p sec done since the last line;
 * @p row 1 where a row ends, 0 for a part of one (a step row's memory
 * runs), said as "(part)". */
static void progress_line(struct progress *pg, int sec, const char *what,
                          double cost, int row) {
  static const double PRIOR[NSEC] = {0.05, 0.25, 0.4, 0.43};
  fflush(pg->out);
  const double now = omp_get_wtime();
  pg->done[sec] += cost;
  pg->spent[sec] += now - pg->t_row;
  pg->t_row = now;
  pg->nrow += (size_t)row;
  double left = 0.0;
  for (int k = 0; k < NSEC; k++) {
    const double rate = pg->done[k] > 0 ? pg->spent[k] / pg->done[k] : PRIOR[k];
    left += rate * (pg->rows[k] - pg->done[k]);
  }
  fprintf(stderr,
          "vsph bench: [%zu/%zu] %s%s, %.0f s elapsed, about %.0f s left\n",
          pg->nrow + (size_t)!row, pg->nrows, what, row ? "" : " (part)",
          now - pg->t0, left);
}

static void step(struct progress *pg, int sec, const char *what, double cost) {
  progress_line(pg, sec, what, cost, 1);
}

static int cmp_double(const void *a, const void *b) {
  const double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

void vsph_bench_fold(double *t, size_t n, double *best, double *median) {
  if (n == 0) {
    *best = *median = (double)NAN;
    return;
  }
  qsort(t, n, sizeof t[0], cmp_double);
  *best = t[0];
  *median = n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

/* Best and median of `reps` wall times of fn(arg): the best filters the
 * bursts of a shared machine (the rates are computed from it), the median
 * says what a run sees (under --busy, say). */
static double timed(int reps, void (*fn)(void *), void *arg, double *median) {
  double t[15];
  if (reps > 15) reps = 15;
  for (int r = 0; r < reps; r++) {
    const double t0 = omp_get_wtime();
    fn(arg);
    t[r] = omp_get_wtime() - t0;
  }
  qsort(t, (size_t)reps, sizeof t[0], cmp_double);
  *median = t[reps / 2];
  return t[0];
}

/* The peer's figures, measured side by side with vsph on the project's
 * first machine, a 2-core AMD EPYC Zen 5 KVM guest, not on the machine
 * that runs this bench: DualSPHysics v5.4 on the CPU (rebuilt from its sources;
 * pair physics in float, -O3 -ffast-math), 2-D standing wave, about 42k
 * particles and 45 neighbours, 1 thread, alternating runs at load 0.6-1.1
 * (issue 46's review, 2026-12: its force without delta-SPH, its whole solver,
 * and its memory per added particle; the force with delta-SPH from the speed
 * work's first sitting, docs/performance.md). Quoted, not measured here:
 * they sit beside our rows to compare, under a line that says so. */
static void print_peer(FILE *out) {
  fprintf(out,
          "# the peer's rows: DualSPHysics v5.4, one thread, as issue 46's "
          "review measured it on an AMD EPYC Zen 5 guest; quoted, not "
          "measured here\n"
          "%-30s %7s %3s %8s %8s %13s %15s %10s %6s\n"
          "%-30s %7s %3s %8s %8s %13s %15s %10s %6s\n"
          "%-30s %7s %3s %8s %8s %13s %15s %10s %6s\n",
          "peer: force, no delta", "42k", "1", "-", "-", "5.5-6.0e+07", "-",
          "-", "-", "peer: force, delta", "42k", "1", "-", "-", "4.4-4.9e+07",
          "-", "-", "-", "peer: whole solver (Sympl.)", "42k", "1", "-", "-",
          "-", "1.39e+06", "173", "-");
}

/* One measured row of the solver table. */
struct row {
  char what[40];
  size_t n;
  int thr;
  double best, med;     /* seconds: the best and the median time */
  double inter, pevals; /* directed interactions, particle-evaluations */
  double bytes;         /* peak bytes per particle (0: not measured) */
  double load;          /* the 1-minute load average after it */
};

/* The solver table's rows as a process measured them (or as K processes
 * did, folded). */
struct rows {
  struct row r[64];
  size_t n;
};

/* One row: what, N, threads, best and median ms, interactions/s and
 * particle-evaluations/s per core (from the best), bytes per particle (0:
 * not measured), load. */
static void print_row(FILE *out, const struct row *r) {
  char b[32] = "-";
  if (r->bytes > 0) snprintf(b, sizeof b, "%.0f", r->bytes);
  fprintf(out, "%-30s %7zu %3d %8.2f %8.2f %13.3e %15.3e %10s %6.2f\n", r->what,
          r->n, r->thr, 1e3 * r->best, 1e3 * r->med,
          r->inter / (r->best * r->thr), r->pevals / (r->best * r->thr), b,
          r->load);
}

/* The row as a CSV line (the columns of SOLVER_CSV). */
static const char SOLVER_CSV[] =
    "what,particles,threads,best_ms,median_ms,inter_per_s_core,"
    "pevals_per_s_core,bytes_per_particle,load_1min\n";
static void csv_row(FILE *out, const struct row *r) {
  char b[32] = ""; /* empty where not measured (a spreadsheet's blank) */
  if (r->bytes > 0) snprintf(b, sizeof b, "%.1f", r->bytes);
  fprintf(out, "\"%s\",%zu,%d,%.6f,%.6f,%.6e,%.6e,%s,%.2f\n", r->what, r->n,
          r->thr, 1e3 * r->best, 1e3 * r->med, r->inter / (r->best * r->thr),
          r->pevals / (r->best * r->thr), b, r->load);
}

/* Peak resident memory of a whole `vsph run` of (scene, form) at res
 * across for about three steps, in a process of its own (this program
 * started again, so nothing of the bench's own memory counts): its
 * run.json says peak_rss_bytes. 0 if it cannot be run. */
static double run_peak_rss(const struct vsph_scene_type *type, int form,
                           size_t res, size_t *n) {
  struct vsph_integrate *s =
      bench_run(type, form, res, 0.0, 0, &vsph_gaussian_type, VSPH_CONSTS_HDX);
  if (!s) return 0.0;
  /* the run takes the scene's own CFL, the bench's step CFL 1 */
  const double t_end =
      3.0 * vsph_integrate_dt(s) * (type->cfl > 1.0 ? type->cfl : 1.0);
  *n = s->n_fluid;
  vsph_integrate_free(s);
  return vsph_jobs_store_peak_rss(type->name, vsph_viscous_name(form), res,
                                  t_end);
}

/* A row's progress within it: the row's name and cost, and the share of
 * it said done so far (NULL pg: nothing said). */
struct bench_part {
  struct progress *pg;
  const char *what;
  double cost, said;
};

/* Part of a row done: its share @p upto of the row's cost in all. */
static void part_done(struct bench_part *bp, const char *part, double upto) {
  if (!bp || !bp->pg) return;
  char what[160];
  snprintf(what, sizeof what, "%s: %s", bp->what, part);
  progress_line(bp->pg, SEC_SOLVER, what, (upto - bp->said) * bp->cost, 0);
  bp->said = upto;
}

/* Peak memory per particle of a whole run: the difference of the peaks at
 * two sizes over the difference of their particle counts, so the
 * program's fixed part (code, libraries) cancels. 0 if not measured. */
static double peak_bytes_per_particle(const struct vsph_scene_type *type,
                                      int form, struct bench_part *bp) {
  size_t n1 = 0, n2 = 0;
  const double b1 = run_peak_rss(type, form, 100, &n1);
  part_done(bp, "its memory run at 100 across", 0.1);
  const double b2 = run_peak_rss(type, form, 400, &n2);
  part_done(bp, "its memory run at 400 across", 0.65);
  return b1 > 0 && b2 > b1 && n2 > n1 ? (b2 - b1) / (double)(n2 - n1) : 0.0;
}

/* K processes that only spin, to load the machine (--busy); each ends
 * itself after 20 minutes should the bench die first. */
static void busy_start(pid_t *pids, int k) {
  for (int i = 0; i < k; i++) {
    pids[i] = fork();
    if (pids[i] == 0) {
      alarm(1200);
      for (volatile unsigned long x = 0;; x++) {
      }
    }
  }
}
static void busy_stop(const pid_t *pids, int k) {
  for (int i = 0; i < k; i++)
    if (pids[i] > 0) {
      kill(pids[i], SIGKILL);
      waitpid(pids[i], NULL, 0);
    }
}

/* One case of the solver bench. */
struct bench_case {
  const char *what;
  const struct vsph_scene_type *type;
  int form;
  double delta;
  int step;    /* 0: one force evaluation, 1: one whole RK4 step */
  int contact; /* contact SPH instead of the viscous form */
  int gather;  /* the per-particle gather instead of the symmetric sweep */
  int cubic;   /* 1: the cubic B-spline at Basa's h/dx 1.5699 (a gather
                  of its own), 2: the same through the general loop */
};

/* The solver table's rows. */
static const struct bench_case SOLVER[] = {
    {.what = "force MGF",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MGF},
    {.what = "force MGF, gather",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MGF,
     .gather = 1},
    {.what = "force MGF + delta 0.1",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MGF,
     .delta = 0.1},
    {.what = "force MEAF",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MEAF},
    {.what = "force PVWF (2 passes)",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_PVWF},
    {.what = "force PVWF, gather",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_PVWF,
     .gather = 1},
    {.what = "force contact SPH",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MEAF,
     .contact = 1},
    {.what = "step MGF, stretching square",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MGF,
     .step = 1},
    {.what = "step PVWF, stretching square",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_PVWF,
     .step = 1},
    {.what = "step MGF, standing wave",
     .type = &vsph_standing_wave_type,
     .form = VSPH_VISCOUS_MGF,
     .step = 1},
    {.what = "force MGF, cubic",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MGF,
     .gather = 1,
     .cubic = 1},
    {.what = "force MGF, cubic, general",
     .type = &vsph_stretching_square_type,
     .form = VSPH_VISCOUS_MGF,
     .gather = 1,
     .cubic = 2},
};
#define SOLVER_CASES (sizeof SOLVER / sizeof SOLVER[0])

/* One case: its force evaluation or step timed on 1 and 2 threads. */
static int bench_case(struct rows *rw, const struct bench_case *bc, size_t res,
                      struct bench_part *bp) {
  struct solver_arg a = {
      .s = bench_run(bc->type, bc->form, res, bc->delta, bc->contact,
                     bc->cubic ? &vsph_cubic_type : &vsph_gaussian_type,
                     bc->cubic ? 1.5699 : VSPH_CONSTS_HDX)};
  if (!a.s) {
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the bench's run");
  }
  a.s->props.eq.loop_general = bc->cubic == 2;
  struct vsph_particles *p = a.s->p;
  a.dt = vsph_integrate_dt(a.s);
  vsph_integrate_step(a.s, a.dt); /* builds cells and ghosts, warms up */
  double *buf = malloc(3 * p->n * sizeof *buf);
  if (!buf) {
    vsph_integrate_free(a.s);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the bench's buffers");
  }
  a.out.sweep = bc->gather ? NULL : a.s->sweep;
  a.out.drho = buf;
  a.out.acc[0] = buf + p->n;
  a.out.acc[1] = buf + 2 * p->n;
  const size_t n = a.s->n_fluid;
  const double bytes = bc->step && bc->delta == 0.0
                           ? peak_bytes_per_particle(bc->type, bc->form, bp)
                           : 0.0;
  for (int thr = 1; thr <= 2; thr++) {
    omp_set_num_threads(thr);
    double t, med, inter;
    const double passes = vsph_viscous_passes(bc->form);
    if (bc->step) {
      t = timed(7, step_once, &a, &med);
      inter = passes * (double)a.s->interactions;
    } else {
      rhs_once(&a);
      inter = passes * (double)a.out.interactions;
      t = timed(15, rhs_once, &a, &med);
    }
    if (rw->n < sizeof rw->r / sizeof rw->r[0]) {
      struct row *r = &rw->r[rw->n++];
      double la[3];
      vsph_sysinfo_load(la);
      snprintf(r->what, sizeof r->what, "%s", bc->what);
      r->n = n;
      r->thr = thr;
      r->best = t;
      r->med = med;
      r->inter = inter;
      r->pevals = (bc->step ? 4.0 : 1.0) * (double)n;
      r->bytes = bytes;
      r->load = la[0];
    }
  }
  free(buf);
  vsph_integrate_free(a.s);
  return VSPH_OK;
}

/* The solver table measured in this process into @p rw. */
static int measure_solver(struct rows *rw, int busy, struct progress *pg) {
  /* the peer's size: 205^2 = 42025 particles */
  const size_t res = 205;
  pid_t pids[8] = {0};
  if (busy > 8) busy = 8;
  busy_start(pids, busy);
  int st = VSPH_OK;
  for (size_t c = 0; c < SOLVER_CASES && !st; c++) {
    struct bench_part bp = {
        .pg = pg, .what = SOLVER[c].what, .cost = row_cost(SOLVER[c].what)};
    st = bench_case(rw, &SOLVER[c], res, &bp);
    if (pg) step(pg, SEC_SOLVER, SOLVER[c].what, (1.0 - bp.said) * bp.cost);
  }
  busy_stop(pids, busy);
  omp_set_num_threads(2);
  return st;
}

/* The CPU's model name and its clock now (MHz), from /proc/cpuinfo
 * (the first processor's); "unknown" and 0 where it says none. */
static void cpu_model(char *name, size_t n, double *mhz) {
  snprintf(name, n, "unknown");
  *mhz = 0.0;
  FILE *f = fopen("/proc/cpuinfo", "r");
  if (!f) return;
  char line[512];
  int got = 0;
  while (got != 3 && fgets(line, sizeof line, f)) {
    const char *c = strchr(line, ':');
    if (!c) continue;
    if (!(got & 1) && !strncmp(line, "model name", 10)) {
      snprintf(name, n, "%s", c + 2);
      name[strcspn(name, "\n")] = '\0';
      got |= 1;
    } else if (!(got & 2) && !strncmp(line, "cpu MHz", 7)) {
      *mhz = strtod(c + 1, NULL);
      got |= 2;
    }
  }
  fclose(f);
}

/* Memory bandwidth of a triad a = b + s c over three arrays of 4 Mi
 * doubles each (96 MiB, beyond any cache), on @p thr threads: bytes
 * moved (three arrays, read, read, write) over the best of 5 times,
 * GB/s; 0 if the arrays cannot be had. */
static double triad_gbs(int thr) {
  const size_t n = (size_t)1 << 22;
  double *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b),
         *c = malloc(n * sizeof *c);
  double best = INFINITY;
  if (a && b && c) {
    omp_set_num_threads(thr);
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++) a[i] = 0.0, b[i] = 1.0, c[i] = 2.0;
    for (int r = 0; r < 5; r++) {
      const double t0 = omp_get_wtime();
#pragma omp parallel for schedule(static)
      for (size_t i = 0; i < n; i++) a[i] = b[i] + 0.5 * c[i];
      best = fmin(best, omp_get_wtime() - t0);
    }
    omp_set_num_threads(2);
  }
  const double sum = a ? a[n / 2] : 0.0; /* keep the stores */
  free(a);
  free(b);
  free(c);
  return isfinite(best) && sum > 0.0 ? 3.0 * (double)n * 8.0 / best / 1e9 : 0.0;
}

/* The 2-D MGF force evaluation's memory traffic per particle (bytes),
 * counted from its arrays (each streamed once an evaluation, the
 * neighbours' reads served by the cache, the cells being sorted): the
 * state read (r, u: 2d; rho, p, V, id), the pressure pass (m and rho
 * read, p and V written), the sweep's buffers (d + 1 doubles, 1.35
 * times for the blocks' overlap, written then read) and the rates
 * written (d + 1). */
static double mgf_bytes_per_particle(int d) {
  const double state = (2.0 * d + 4.0) * 8.0, pressure = 4.0 * 8.0;
  const double sweep = (d + 1.0) * 1.35 * 16.0, rates = (d + 1.0) * 8.0;
  return state + pressure + sweep + rates;
}

/* The folded table: every row with its best (over all processes) and
 * median (of the processes' bests), the peer's rows, the strong scaling
 * (1 thread against 2) and the weak-scaling estimate. */
static void print_solver(FILE *out, const struct rows *rw, int busy,
                         size_t procs) {
  char model[256];
  double mhz;
  cpu_model(model, sizeof model, &mhz);
  fprintf(out,
          "\n## solver against the peer: 2-D, 3h Gaussian, h/dx 4/3, about 45 "
          "neighbours, double precision; 15 force evaluations, 7 steps\n");
  fprintf(out, "# CPU %s, %.0f MHz now, %d threads available\n", model, mhz,
          omp_get_max_threads());
  if (busy)
    fprintf(out, "## with %d other busy processes on the machine (--busy)\n",
            busy);
  fprintf(out,
          "(inter/s/core: directed interactions per second per thread, PVWF's "
          "two passes both counted; p-evals/s/core: particles x force "
          "evaluations per second per thread, RK4 making 4 per step; "
          "B/particle: peak resident memory per particle of a whole run of "
          "about three steps with the run's 200 energy rows and 10 "
          "snapshots, from two sizes in child processes)\n");
  if (procs > 1)
    fprintf(out,
            "(%zu processes, one after another: best ms the best time of all "
            "of them, med ms the median of their best times; rates from the "
            "best; load: the largest 1-minute average seen, this bench "
            "included)\n",
            procs);
  else
    fprintf(out,
            "(one process: best and median of its repetitions, rates from the "
            "best; load: the 1-minute average, this bench included; make "
            "bench times 5 processes)\n");
  fprintf(out, "%-30s %7s %3s %8s %8s %13s %15s %10s %6s\n", "what", "N", "thr",
          "best ms", "med ms", "inter/s/core", "p-evals/s/core", "B/particle",
          "load");
  for (size_t k = 0; k < rw->n; k++) print_row(out, &rw->r[k]);
  print_peer(out);
  fprintf(out,
          "\n## strong scaling on this machine: the time on 1 thread over the "
          "time on 2 (2.00 is perfect; from medians it can pass 2.00 where "
          "a slow episode fell on the 1-thread rows)\n%-30s %10s %10s\n",
          "what", "from best", "from med");
  for (size_t k = 0; k + 1 < rw->n; k++) {
    const struct row *a = &rw->r[k], *b = &rw->r[k + 1];
    if (a->thr != 1 || b->thr != 2 || strcmp(a->what, b->what)) continue;
    fprintf(out, "%-30s %10.2f %10.2f\n", a->what, a->best / b->best,
            a->med / b->med);
  }
  const double bw1 = triad_gbs(1), bw2 = triad_gbs(2);
  const struct row *mgf = rw->n ? &rw->r[0] : NULL;
  const double bpp = mgf_bytes_per_particle(2);
  fprintf(out,
          "\n## weak scaling, an estimate: memory bandwidth (triad, best of "
          "5) %.1f GB/s on 1 thread, %.1f on 2\n",
          bw1, bw2);
  if (mgf && mgf->thr == 1 && bw2 > 0.0) {
    const double inter_pp = mgf->inter / (double)mgf->n;
    const double bpi = bpp / inter_pp;
    const double rate = mgf->inter / mgf->best; /* per core */
    const double need = rate * bpi / 1e9;       /* GB/s a core draws */
    fprintf(out,
            "# MGF's force evaluation moves about %.0f B a particle (its "
            "arrays streamed once: bench.c, mgf_bytes_per_particle), %.1f B a "
            "directed interaction at %.0f interactions a particle; at %.2e "
            "interactions/s a core draws %.2f GB/s, so a memory system of "
            "B GB/s feeds about B/%.2f cores before bandwidth binds (this "
            "machine's %.1f GB/s: %.0f cores); below that the work per "
            "core stays the same as cores and particles grow together\n",
            bpp, bpi, inter_pp, rate, need, need, bw2,
            need > 0.0 ? bw2 / need : 0.0);
  }
}

/* A process of this program measuring the solver table (bench
 * --solver-only --raw), its rows read from its output into @p rw;
 * VSPH_EIO if it cannot be run or says nothing readable. */
static int child_rows(int busy, struct rows *rw) {
  int fd[2];
  if (pipe(fd) != 0) VSPH_FAIL(VSPH_EIO, "cannot make a pipe for the bench");
  char b[16];
  snprintf(b, sizeof b, "%d", busy);
  const pid_t pid = fork();
  if (pid == 0) { /* the child: only exec (safe after fork in threads) */
    dup2(fd[1], 1);
    close(fd[0]);
    close(fd[1]);
    execl("/proc/self/exe", "vsph", "bench", "--solver-only", "--raw", "--busy",
          b, (char *)NULL);
    _exit(127);
  }
  close(fd[1]);
  FILE *f = pid > 0 ? fdopen(fd[0], "r") : NULL;
  rw->n = 0;
  char line[512];
  while (f && fgets(line, sizeof line, f)) {
    struct row r = {0};
    double ipc, pepc;
    if (line[0] != '"' || rw->n >= sizeof rw->r / sizeof rw->r[0]) continue;
    const char *q = strchr(line + 1, '"');
    if (!q || (size_t)(q - line - 1) >= sizeof r.what) continue;
    memcpy(r.what, line + 1, (size_t)(q - line - 1));
    /* the fields after the name, an empty bytes field meaning none */
    char *fld[8], *rest = (char *)q + 1;
    int nf = 0;
    for (char *t = rest; nf < 8 && (t = strchr(t, ','));) {
      *t++ = '\0';
      fld[nf++] = t;
    }
    if (nf != 8 || sscanf(fld[0], "%zu", &r.n) != 1 ||
        sscanf(fld[1], "%d", &r.thr) != 1 || r.thr < 1)
      continue;
    r.best = strtod(fld[2], NULL);
    r.med = strtod(fld[3], NULL);
    ipc = strtod(fld[4], NULL);
    pepc = strtod(fld[5], NULL);
    r.bytes = fld[6][0] ? strtod(fld[6], NULL) : 0.0;
    r.load = strtod(fld[7], NULL);
    if (!(r.best > 0.0 && r.med > 0.0)) continue;
    r.best *= 1e-3;
    r.med *= 1e-3;
    r.inter = ipc * r.best * r.thr;
    r.pevals = pepc * r.best * r.thr;
    rw->r[rw->n++] = r;
  }
  if (f)
    fclose(f);
  else
    close(fd[0]);
  int status = 1;
  if (pid > 0) waitpid(pid, &status, 0);
  if (pid <= 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || !rw->n)
    VSPH_FAIL(VSPH_EIO, "a bench process failed (exit status %d)",
              pid > 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1);
  return VSPH_OK;
}

/* The solver table over @p procs processes (one after another), folded
 * into @p all: each row's best of all, the median of the processes'
 * bests, the largest load. */
static int measure_processes(size_t procs, int busy, struct rows *all) {
  struct rows *each = calloc(procs, sizeof *each);
  if (!each) VSPH_FAIL(VSPH_ENOMEM, "cannot hold %zu processes' rows", procs);
  const double t0 = omp_get_wtime();
  int st = VSPH_OK;
  for (size_t k = 0; k < procs && !st; k++) {
    st = child_rows(busy, &each[k]);
    if (!st && k > 0 && each[k].n != each[0].n)
      st = VSPH_EIO, vsph_status_report(st, __FILE__, __LINE__,
                                        "bench processes gave %zu and %zu rows",
                                        each[0].n, each[k].n);
    const double spent = omp_get_wtime() - t0;
    fprintf(stderr,
            "vsph bench: process %zu of %zu ended, %.0f s elapsed, about %.0f "
            "s left\n",
            k + 1, procs, spent,
            spent / (double)(k + 1) * (double)(procs - k - 1));
  }
  if (!st) {
    *all = each[0];
    double t[64];
    for (size_t r = 0; r < all->n; r++) {
      for (size_t k = 0; k < procs; k++) {
        const struct row *x = &each[k].r[r];
        t[k] = x->best;
        all->r[r].load = fmax(all->r[r].load, x->load);
        all->r[r].bytes = fmax(all->r[r].bytes, x->bytes);
      }
      vsph_bench_fold(t, procs, &all->r[r].best, &all->r[r].med);
    }
  }
  free(each);
  return st;
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

/* The machine's load and the OpenMP wait policy. */
static void print_load(FILE *out) {
  double la[3];
  char wp[128];
  vsph_sysinfo_load(la);
  fprintf(out,
          "# load average %.2f %.2f %.2f (1, 5, 15 min); OMP_WAIT_POLICY "
          "%s\n",
          la[0], la[1], la[2], vsph_sysinfo_wait_policy(wp, sizeof wp));
}

static int bench_quadrature(FILE *out, struct progress *pg) {
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
      step(pg, SEC_QUAD, "quadrature", 1.0);
    }
  gsl_integration_workspace_free(qa.wo);
  gsl_integration_workspace_free(qa.wi);
  return VSPH_OK;
}

static int bench_sums(FILE *out, struct progress *pg) {
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
    step(pg, SEC_SUMS, "particle sums", 1.0);
  }
  return VSPH_OK;
}

static int bench_operators(FILE *out, size_t side, struct progress *pg) {
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
    const double passes = vsph_viscous_passes(form);
    omp_set_num_threads(1);
    const double t1 = best_of(5, visc_once, &va);
    omp_set_num_threads(2);
    const double t2 = best_of(5, visc_once, &va);
    fprintf(out, "%-6s %12.3f %12.3f %16.3e %9.2f\n", vsph_viscous_name(form),
            1e3 * t1, 1e3 * t2, passes * (double)inter / t1, t1 / t2);
    step(pg, SEC_OPS, vsph_viscous_name(form), 1.0);
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
  if (bp->processes < 1 || bp->processes > 20)
    VSPH_FAIL(VSPH_EINVAL, "the bench takes 1-20 processes, not %zu",
              bp->processes);
  struct rows *rw = calloc(1, sizeof *rw);
  if (!rw) VSPH_FAIL(VSPH_ENOMEM, "cannot hold the bench's rows");
  int st = VSPH_OK;
  if (bp->raw) { /* a child of --processes: the solver rows as CSV, its
                    progress on stderr */
    struct progress pg = {.t0 = omp_get_wtime(), .out = out};
    pg.t_row = pg.t0;
    for (size_t c = 0; c < SOLVER_CASES; c++)
      pg.rows[SEC_SOLVER] += row_cost(SOLVER[c].what);
    pg.nrows = SOLVER_CASES;
    st = measure_solver(rw, bp->busy, &pg);
    if (!st) {
      fputs(SOLVER_CSV, out);
      for (size_t k = 0; k < rw->n; k++) csv_row(out, &rw->r[k]);
    }
    free(rw);
    return st;
  }
  fprintf(out, "# vsph %s bench, %d threads available\n", VSPH_VERSION,
          omp_get_max_threads());
  print_load(out);
  struct progress pg = {.t0 = omp_get_wtime(), .out = out};
  pg.t_row = pg.t0;
  if (bp->processes == 1) {
    for (size_t c = 0; c < SOLVER_CASES; c++)
      pg.rows[SEC_SOLVER] += row_cost(SOLVER[c].what);
    pg.nrows = SOLVER_CASES;
  }
  if (!bp->solver_only) {
    pg.rows[SEC_QUAD] = 2.0 * (double)vsph_kernel_count();
    pg.rows[SEC_SUMS] = 4;
    pg.rows[SEC_OPS] = VSPH_VISCOUS_FORM_COUNT;
    pg.nrows += 2 * vsph_kernel_count() + 4 + VSPH_VISCOUS_FORM_COUNT;
  }
  if (pg.nrows) fprintf(stderr, "vsph bench: %zu rows to measure\n", pg.nrows);
  if (!bp->solver_only) {
    st = bench_quadrature(out, &pg);
    if (!st) st = bench_sums(out, &pg);
    if (!st) st = bench_operators(out, bp->size, &pg);
  }
  if (!st)
    st = bp->processes > 1 ? measure_processes(bp->processes, bp->busy, rw)
                           : measure_solver(rw, bp->busy, &pg);
  if (!st) print_solver(out, rw, bp->busy, bp->processes);
  if (!st && bp->csv) {
    FILE *f = fopen(bp->csv, "w");
    int ok = f != NULL;
    if (ok) {
      fputs(SOLVER_CSV, f);
      for (size_t k = 0; k < rw->n; k++) csv_row(f, &rw->r[k]);
      ok = !ferror(f);
    }
    if (f && fclose(f) != 0) ok = 0;
    if (!ok)
      st = VSPH_EIO,
      vsph_status_report(st, __FILE__, __LINE__, "cannot write %s", bp->csv);
  }
  if (!st) print_load(out);
  free(rw);
  return st;
}
