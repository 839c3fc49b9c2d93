/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's runs as jobs. Every part declares the runs it reads (its
 * plan) before any is run; the report then runs what is missing and
 * assembles. Three ways to run them: in this process, a run per thread (the
 * default); as child processes, N at a time (`--jobs N`); or as a Slurm
 * job array with the assembly after it (`--slurm`). A job is one command
 * (`vsph run ... --cache` or `vsph contact ... --cache`) whose folder ends
 * with key.txt (runs/rundir): the cache, and the proof that the run ended,
 * whichever way ran it. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "jobs.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../analysis/contact.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/shell.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/json.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "folder.h"
#include "rundir.h"
#include "sheartest.h"

extern char **environ; /* POSIX: the application declares it */

/* ----------------------------------------------------------------- jobs */

/* The parameters of @p j's settings, as given. */
static int params_of(const struct vsph_jobs_job *j, struct vsph_params **out) {
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate parameters");
  int st = VSPH_OK;
  for (size_t k = 0; k < j->nset && !st; k++)
    st = vsph_params_assign(prm, j->set[k]);
  /* the defaults the job's command adds (vsph run: the scene's Solver
   * defaults; vsph contact: the measurement's), so that its key here is
   * the one the command writes */
  if (!st && j->kind == VSPH_JOBS_SHEAR)
    st = vsph_contact_defaults(prm);
  else if (!st && vsph_scene_find(j->scene))
    st = vsph_scene_solver_defaults(vsph_scene_find(j->scene), prm);
  if (st) {
    vsph_params_free(prm);
    return st;
  }
  *out = prm;
  return VSPH_OK;
}

/* Its key (runs/rundir's, from the settings as given) and cache state. */
static int finish_job(struct vsph_jobs_job *j) {
  struct vsph_params *prm;
  int st = params_of(j, &prm);
  if (st) return st;
  char what[64];
  if (j->kind == VSPH_JOBS_RUN)
    snprintf(what, sizeof what, "scene %s", j->scene);
  else
    snprintf(what, sizeof what, "contact %zu", j->nprof);
  j->key = vsph_rundir_key(prm, what);
  vsph_params_free(prm);
  if (!j->key) return VSPH_ENOMEM;
  j->cached = vsph_rundir_key_matches(j->dir, j->key);
  return VSPH_OK;
}

void vsph_jobs_free(struct vsph_jobs_job *j) {
  free(j->key);
  free(j->from_key);
  j->key = j->from_key = NULL;
}

int vsph_jobs_run(const struct vsph_jobs *J, const struct vsph_jobs_spec *rs,
                  struct vsph_jobs_job *j) {
  if (!J->dir) VSPH_FAIL(VSPH_EINVAL, "the runs have no folder (a bug)");
  memset(j, 0, sizeof *j);
  j->kind = VSPH_JOBS_RUN;
  snprintf(j->scene, sizeof j->scene, "%s", rs->scene);
  snprintf(j->dir, sizeof j->dir, "%s/runs/%s-%s-%zu%s%s", J->dir, rs->scene,
           rs->visc, rs->res, rs->tag ? "-" : "", rs->tag ? rs->tag : "");
  size_t n = 0;
  /* "contact" names the scheme (contact SPH has no viscous form) */
  if (!strcmp(rs->visc, "contact"))
    snprintf(j->set[n++], 128, "Solver:scheme=contact");
  else
    snprintf(j->set[n++], 128, "Solver:visc=%s", rs->visc);
  snprintf(j->set[n++], 128, "Solver:res=%zu", rs->res);
  snprintf(j->set[n++], 128, "Solver:t_end=%.17g", rs->t_end);
  /* the ladders keep snapshots: the vortex patch's u_theta profiles and
   * the particle pictures of section 5 read them */
  snprintf(j->set[n++], 128, "Solver:snapshots=%d", rs->tag ? 0 : 4);
  for (size_t k = 0; rs->extra && rs->extra[k]; k++) {
    if (n == VSPH_JOBS_NSET)
      VSPH_FAIL(VSPH_EINVAL, "%s: more than %d settings", j->dir,
                VSPH_JOBS_NSET);
    snprintf(j->set[n++], 128, "%s", rs->extra[k]);
  }
  j->nset = n;
  const struct vsph_scene_type *t = vsph_scene_find(rs->scene);
  snprintf(j->family, sizeof j->family, "%s %s", rs->scene, rs->visc);
  snprintf(j->label, sizeof j->label, "%s %s %s/dx=%zu%s%s%s", rs->scene,
           rs->visc, t ? t->length_name : "res", rs->res, rs->tag ? " (" : "",
           rs->tag ? rs->tag : "", rs->tag ? ")" : "");
  return finish_job(j);
}

int vsph_jobs_shear(const struct vsph_jobs *J, const char *tag,
                    const char (*set)[96], size_t n, size_t nprof,
                    struct vsph_jobs_job *j) {
  if (!J->dir) VSPH_FAIL(VSPH_EINVAL, "the runs have no folder (a bug)");
  memset(j, 0, sizeof *j);
  j->kind = VSPH_JOBS_SHEAR;
  snprintf(j->scene, sizeof j->scene, "shear");
  snprintf(j->dir, sizeof j->dir, "%s/runs/contact-%s", J->dir, tag);
  if (n > VSPH_JOBS_NSET)
    VSPH_FAIL(VSPH_EINVAL, "%s: more than %d settings", j->dir, VSPH_JOBS_NSET);
  for (size_t k = 0; k < n; k++) snprintf(j->set[k], 128, "%s", set[k]);
  j->nset = n;
  j->nprof = nprof;
  snprintf(j->label, sizeof j->label, "shear test %s", tag);
  snprintf(j->family, sizeof j->family, "shear test");
  return finish_job(j);
}

/* The solver's estimate of @p j (particles, steps, memory). */
static int estimate(struct vsph_jobs_job *j) {
  struct vsph_params *prm;
  int st = params_of(j, &prm);
  if (st) return st;
  struct vsph_run_props rp;
  struct vsph_scene sc;
  struct vsph_run_estimate e = {0, 0, 0, 0};
  const struct vsph_scene_type *t = vsph_scene_find(j->scene);
  if (!t) {
    vsph_params_free(prm);
    VSPH_FAIL(VSPH_EINVAL, "%s: unknown scene '%s'", j->dir, j->scene);
  }
  st = vsph_run_props_init(&rp, prm);
  if (!st) st = vsph_scene_init(&sc, t, prm);
  if (!st) st = vsph_run_estimate(&rp, &sc, &e);
  vsph_params_free(prm);
  j->particles = e.particles;
  j->steps = e.steps;
  j->bytes = e.bytes;
  j->neighbours = e.neighbours;
  return st;
}

/* Pair interactions over the run: particles x neighbours x steps. */
static double cost_of(const struct vsph_jobs_job *j) {
  return j->particles * j->neighbours * j->steps;
}

int vsph_jobs_plan_add(struct vsph_jobs *J, struct vsph_jobs_job *j) {
  struct vsph_jobs *P = J;
  if (!P) {
    vsph_jobs_free(j);
    return VSPH_OK;
  }
  for (size_t k = 0; k < P->n; k++)
    if (!strcmp(P->job[k].dir, j->dir)) {
      const int same = !strcmp(P->job[k].key, j->key);
      P->job[k].here |= j->here;
      P->job[k].frames |= j->frames;
      vsph_jobs_free(j);
      if (same) return VSPH_OK;
      VSPH_FAIL(VSPH_EBUG,
                "two runs of the report share the folder %s with different "
                "settings (a bug in the report's specs)",
                P->job[k].dir);
    }
  int st = estimate(j);
  if (!st && P->n == P->cap) {
    const size_t cap = P->cap ? 2 * P->cap : 64;
    struct vsph_jobs_job *g = realloc(P->job, cap * sizeof *g);
    if (!g) {
      st = VSPH_ENOMEM;
      vsph_status_report(st, __FILE__, __LINE__, "cannot grow the plan");
    } else {
      P->job = g;
      P->cap = cap;
    }
  }
  if (st) {
    vsph_jobs_free(j);
    return st;
  }
  P->job[P->n++] = *j; /* the plan owns the key now */
  j->key = NULL;
  return VSPH_OK;
}

/* A solver run planned, marked `here` or not. */
static int plan_spec(struct vsph_jobs *J, const struct vsph_jobs_spec *rs,
                     int here, unsigned frames) {
  struct vsph_jobs_job j;
  const int st = vsph_jobs_run(J, rs, &j);
  if (st) {
    vsph_jobs_free(&j);
    return st;
  }
  j.here = here;
  j.frames = frames;
  return vsph_jobs_plan_add(J, &j);
}

int vsph_jobs_plan_run(struct vsph_jobs *J, const struct vsph_jobs_spec *rs) {
  return plan_spec(J, rs, 0, 0u);
}

int vsph_jobs_plan_here(struct vsph_jobs *J, const struct vsph_jobs_spec *rs) {
  return plan_spec(J, rs, 1, 0u);
}

int vsph_jobs_plan_frames(struct vsph_jobs *J, const struct vsph_jobs_spec *rs,
                          unsigned frames) {
  return plan_spec(J, rs, 1, frames);
}

/* Run @p j here: its folder ends with key.txt, or it failed. */
static int execute(const struct vsph_jobs *J, const struct vsph_jobs_job *j) {
  struct vsph_params *prm;
  int st = params_of(j, &prm);
  if (st) return st;
  char command[4096];
  vsph_jobs_command(j, "vsph", 0, command, sizeof command);
  if (j->kind == VSPH_JOBS_RUN) {
    const struct vsph_rundir_opts opts = {.dir = j->dir,
                                          .progress = NULL,
                                          .stop = J->stop,
                                          .command = command,
                                          .cache = 1};
    struct vsph_rundir_result res;
    st = vsph_rundir_execute(prm, j->scene, &opts, &res);
  } else {
    int cached;
    st = vsph_sheartest_execute(prm, j->nprof, j->dir, 1, 1, &cached);
  }
  vsph_params_free(prm);
  return st;
}

static const struct vsph_jobs_job *find(const struct vsph_jobs *P,
                                        const char *dir) {
  for (size_t k = 0; k < P->n; k++)
    if (!strcmp(P->job[k].dir, dir)) return &P->job[k];
  return NULL;
}

/* The folder a planned job's files are read from, and the key its seal
 * must hold for. */
static const char *where_of(const struct vsph_jobs_job *p, const char **key) {
  *key = p->from[0] ? p->from_key : p->key;
  return p->from[0] ? p->from : p->dir;
}

const char *vsph_jobs_where(const struct vsph_jobs *J, const char *dir) {
  const struct vsph_jobs_job *p = J->planned ? find(J, dir) : NULL;
  const char *key;
  return p ? where_of(p, &key) : dir;
}

int vsph_jobs_ready(const struct vsph_jobs *J, const struct vsph_jobs_job *j) {
  if (!J->planned) return j->cached ? VSPH_OK : execute(J, j);
  const struct vsph_jobs_job *p = find(J, j->dir);
  if (!p || strcmp(p->key, j->key))
    VSPH_FAIL(VSPH_EBUG,
              "the report reads %s, which no part's plan lists with these "
              "settings (a bug: the part's plan function misses it)",
              j->dir);
  if (p->from[0]) { /* an archive's entry: its own seal must still hold */
    char why[700] = "";
    if (vsph_folder_verify(p->from, NULL, p->from_key, NULL, why, sizeof why) !=
        1)
      VSPH_FAIL(VSPH_EIO, "archived run %s is no longer whole%s%s", p->from,
                why[0] ? ": " : "", why);
    return VSPH_OK;
  }
  if (!vsph_rundir_key_matches(p->dir, p->key))
    VSPH_FAIL(VSPH_EIO,
              "run %s is missing or unfinished (no matching key.txt): run the "
              "report's runs first (vsph report, --jobs N or --slurm)",
              p->dir);
  return VSPH_OK;
}

/* ------------------------------------------------------------- commands */

size_t vsph_jobs_argv(const struct vsph_jobs_job *j, const char *exe,
                      size_t threads, char buf[2][24], const char **argv,
                      size_t cap) {
  size_t n = 0;
#define ARG(s) \
  if (n + 1 < cap) argv[n++] = (s)
  ARG(exe);
  if (j->kind == VSPH_JOBS_RUN) {
    ARG("run");
    ARG(j->scene);
  } else {
    ARG("contact");
  }
  ARG("--out");
  ARG(j->dir);
  if (j->kind == VSPH_JOBS_SHEAR) {
    snprintf(buf[0], 24, "%zu", j->nprof);
    ARG("--profiles");
    ARG(buf[0]);
  }
  ARG("--cache");
  if (threads > 0) {
    snprintf(buf[1], 24, "%zu", threads);
    ARG("--quiet");
    ARG("--threads");
    ARG(buf[1]);
  }
  for (size_t k = 0; k < j->nset; k++) {
    ARG("--set");
    ARG(j->set[k]);
  }
#undef ARG
  argv[n] = NULL;
  return n;
}

void vsph_jobs_command(const struct vsph_jobs_job *j, const char *exe,
                       size_t threads, char *out, size_t len) {
  const char *argv[2 * VSPH_JOBS_NSET + 16];
  char buf[2][24];
  const size_t n =
      vsph_jobs_argv(j, exe, threads, buf, argv, sizeof argv / sizeof argv[0]);
  size_t w = 0;
  if (len) out[0] = '\0';
  for (size_t k = 0; k < n && w + 1 < len; k++) {
    if (k) out[w++] = ' ';
    w += vsph_shell_quote(argv[k], out + w, len - w);
  }
  if (w >= len && len) out[len - 1] = '\0';
}

int vsph_jobs_plan_print(const struct vsph_jobs *J, const char *exe, FILE *f) {
  const struct vsph_jobs *P = J;
  size_t missing = 0;
  double cost = 0.0;
  for (size_t k = 0; k < P->n; k++)
    if (!P->job[k].cached) {
      missing++;
      cost += cost_of(&P->job[k]);
    }
  fprintf(f,
          "# vsph %s report plan for %s (%s): %zu runs, %zu cached, %zu "
          "missing (%.3g pair interactions)\n"
          "# key: FNV-1a 64 of the run's key.txt (version, source hash, "
          "settings); neighbours: within the kernel's reach (each pass); "
          "steps: at t = 0's time step; memory: the solver's bound\n",
          VSPH_VERSION, J->dir, J->full ? "full" : "quick", P->n,
          P->n - missing, missing, cost);
  fprintf(f,
          "status\tfolder\tkey\tparticles\tneighbours\tsteps\tmemory_mib\t"
          "command\n");
  char *cmd = malloc(8192);
  if (!cmd) VSPH_FAIL(VSPH_ENOMEM, "cannot print the plan");
  for (int pass = 0; pass < 2; pass++)
    for (size_t k = 0; k < P->n; k++) {
      const struct vsph_jobs_job *j = &P->job[k];
      if (j->cached != pass) continue;
      vsph_jobs_command(j, exe, 0, cmd, 8192);
      fprintf(f, "%s\t%s\t%016llx\t%.0f\t%.1f\t%.0f\t%.1f\t%s\n",
              j->cached ? "cached" : "missing", j->dir,
              vsph_folder_fingerprint(j->key), j->particles, j->neighbours,
              j->steps, j->bytes / 1048576.0, cmd);
    }
  free(cmd);
  if (fflush(f) != 0 || ferror(f))
    VSPH_FAIL(VSPH_EIO, "cannot write the plan: %s", strerror(errno));
  return VSPH_OK;
}

/* ------------------------------------------------------ the missing runs */

double vsph_jobs_eta(const struct vsph_jobs_eta *r, size_t n, size_t width) {
  double cost_all = 0.0, wall_all = 0.0; /* every finished run */
  for (size_t k = 0; k < n; k++)
    if (r[k].state == VSPH_JOBS_ETA_DONE && r[k].cost > 0.0) {
      cost_all += r[k].cost;
      wall_all += r[k].wall;
    }
  if (cost_all <= 0.0 || width < 1) return -1.0;
  const size_t w = width;
  double *lane = calloc(w, sizeof *lane); /* when each is free, from now */
  if (!lane) return -1.0;
  for (size_t k = 0; k < n; k++) {
    if (r[k].state == VSPH_JOBS_ETA_DONE) continue;
    size_t last = n, prev = n; /* the family's last two finished runs */
    for (size_t i = 0; i < n; i++) {
      if (r[i].state != VSPH_JOBS_ETA_DONE || r[i].cost <= 0.0 ||
          strcmp(r[i].family, r[k].family))
        continue;
      if (last == n || r[i].ended > r[last].ended) {
        prev = last;
        last = i;
      } else if (prev == n || r[i].ended > r[prev].ended) {
        prev = i;
      }
    }
    double fixed = 0.0, rate = wall_all / cost_all;
    if (last < n) rate = r[last].wall / r[last].cost;
    if (prev < n && r[prev].cost != r[last].cost) {
      /* the line through the two: a fixed part and a rate, where both
       * come out non-negative */
      const double b =
          (r[last].wall - r[prev].wall) / (r[last].cost - r[prev].cost);
      const double a = r[last].wall - b * r[last].cost;
      if (b >= 0.0 && a >= 0.0) {
        fixed = a;
        rate = b;
      }
    }
    double need = fixed + rate * r[k].cost;
    if (r[k].state == VSPH_JOBS_ETA_RUNNING) need = fmax(need - r[k].wall, 0.0);
    size_t first = 0; /* the lane free first takes it */
    for (size_t i = 1; i < w; i++)
      if (lane[i] < lane[first]) first = i;
    lane[first] += need;
  }
  double left = 0.0;
  for (size_t i = 0; i < w; i++) left = fmax(left, lane[i]);
  free(lane);
  return left;
}

/* The cost a finished run actually had: its particles x neighbours x the
 * steps it took (run.json, or the shear test's summary.csv), which a run
 * stopped early (a stability map's) or whose time step changed makes
 * differ from the plan's estimate; the estimate where neither is read. */
static double cost_taken(const struct vsph_jobs_job *j) {
  char path[600];
  double steps = -1.0;
  if (j->kind == VSPH_JOBS_RUN) {
    snprintf(path, sizeof path, "%s/run.json", j->dir);
    cJSON *o = vsph_json_read(path);
    if (o) steps = vsph_json_get_number(o, "steps", -1.0);
    cJSON_Delete(o);
  } else {
    struct vsph_contact_shear cs;
    snprintf(path, sizeof path, "%s/summary.csv", j->dir);
    if (vsph_sheartest_csv_load(path, &cs) == VSPH_OK) steps = (double)cs.steps;
  }
  return steps > 0.0 ? j->particles * j->neighbours * steps : cost_of(j);
}

/* The missing jobs of the plan, the costliest first. */
static int by_cost(const void *a, const void *b) {
  const double x = cost_of(*(const struct vsph_jobs_job *const *)a),
               y = cost_of(*(const struct vsph_jobs_job *const *)b);
  return (x < y) - (x > y);
}
/* The wall time and cost (particles x neighbours x steps) each cached
 * solver run of @p J measured (run.json's wall_s and steps; 0 where none)
 * into @p wall, @p cost. */
static void measured(const struct vsph_jobs *J, double *wall, double *cost) {
  char path[600];
  for (size_t k = 0; k < J->n; k++) {
    const struct vsph_jobs_job *j = &J->job[k];
    wall[k] = cost[k] = 0.0;
    if (!j->cached || j->kind != VSPH_JOBS_RUN) continue;
    snprintf(path, sizeof path, "%s/run.json", j->dir);
    cJSON *o = vsph_json_read(path);
    const double w = o ? vsph_json_get_number(o, "wall_s", -1.0) : -1.0;
    const double n = o ? vsph_json_get_number(o, "steps", -1.0) : -1.0;
    cJSON_Delete(o);
    if (w > 0.0 && n > 0.0) {
      wall[k] = w;
      cost[k] = j->particles * j->neighbours * n;
    }
  }
}

/* Seconds per unit of cost of the runs of family @p family (all, when
 * NULL) from measured(); 0 when none measured one. */
static double rate_of(const struct vsph_jobs *J, const double *wall,
                      const double *cost, const char *family) {
  double w = 0.0, c = 0.0;
  for (size_t k = 0; k < J->n; k++)
    if (!family || !strcmp(J->job[k].family, family)) {
      w += wall[k];
      c += cost[k];
    }
  return c > 0.0 ? w / c : 0.0;
}

size_t vsph_jobs_fit(const double *t, size_t m, size_t lanes, double budget,
                     unsigned char *keep) {
  double *free_at = calloc(lanes ? lanes : 1, sizeof *free_at);
  size_t kept = 0;
  for (size_t k = 0; k < m; k++) {
    keep[k] = !free_at || lanes == 0; /* no lanes to lay out: all */
    if (keep[k]) {
      kept++;
      continue;
    }
    size_t lane = 0;
    for (size_t l = 1; l < lanes; l++)
      if (free_at[l] < free_at[lane]) lane = l;
    if (free_at[lane] + t[k] <= budget ||
        (t[k] > budget && free_at[lane] == 0.0)) {
      free_at[lane] += t[k];
      keep[k] = 1;
      kept++;
    }
  }
  free(free_at);
  return kept;
}

/* Of the missing runs @p order (costliest first), those that fit
 * J->budget_s on @p lanes lanes (vsph_jobs_fit), in the same order;
 * returns how many. Each run's time is its cost at its family's measured
 * rate, else all cached runs' rate. With no rate measured yet, every run
 * is kept, and the budget's clock alone stops them. */
static size_t budget_fit(const struct vsph_jobs *J,
                         struct vsph_jobs_job **order, size_t m, size_t lanes) {
  double *t = calloc(m ? m : 1, sizeof *t);
  unsigned char *keep = malloc(m ? m : 1);
  double *wall = calloc(J->n ? J->n : 1, sizeof *wall);
  double *cost = calloc(J->n ? J->n : 1, sizeof *cost);
  if (wall && cost) measured(J, wall, cost);
  const double all = wall && cost ? rate_of(J, wall, cost, NULL) : 0.0;
  if (all <= 0.0 || !t || !keep) {
    free(t);
    free(keep);
    free(wall);
    free(cost);
    if (all <= 0.0 && m > 0)
      fprintf(stderr,
              "vsph report: budget %.0f s: no cached run has measured a rate "
              "yet; the %zu missing runs go costliest first until it is "
              "spent\n",
              J->budget_s, m);
    return m;
  }
  for (size_t k = 0; k < m; k++) {
    const double r = rate_of(J, wall, cost, order[k]->family);
    t[k] = cost_of(order[k]) * (r > 0.0 ? r : all);
  }
  const size_t kept = vsph_jobs_fit(t, m, lanes, J->budget_s, keep);
  size_t at = 0;
  for (size_t k = 0; k < m; k++)
    if (keep[k]) order[at++] = order[k];
  free(t);
  free(keep);
  free(wall);
  free(cost);
  fprintf(stderr,
          "vsph report: budget %.0f s: %zu of the %zu missing runs fit on "
          "%zu lanes (their times at the rates the cached runs measured), "
          "the costliest first; %zu are left for another sitting\n",
          J->budget_s, kept, m, lanes, m - kept);
  return kept;
}

/* ", N more stand in a run archive" when the plan has such runs, for the
 * progress's first line. */
static void archived_note(const struct vsph_jobs *J, char *buf, size_t len) {
  size_t na = 0;
  for (size_t k = 0; k < J->n; k++)
    na += J->job[k].archived && !J->job[k].cached;
  if (na)
    snprintf(buf, len, " (%zu more stand in the run archive and are not run)",
             na);
  else
    buf[0] = '\0';
}

/* The missing runs, costliest first; with a budget, those that fit it on
 * @p lanes lanes. */
static size_t missing(struct vsph_jobs *J, struct vsph_jobs_job ***out,
                      size_t lanes) {
  struct vsph_jobs *P = J;
  *out = malloc((P->n ? P->n : 1) * sizeof **out);
  if (!*out) return (size_t)-1;
  size_t m = 0;
  for (size_t k = 0; k < P->n; k++) {
    P->job[k].failed = 0;
    P->job[k].cached = vsph_rundir_key_matches(P->job[k].dir, P->job[k].key);
    if (!P->job[k].cached && !P->job[k].archived) (*out)[m++] = &P->job[k];
  }
  qsort(*out, m, sizeof **out, by_cost);
  return J->budget_s > 0.0 ? budget_fit(J, *out, m, lanes) : m;
}

/* The runs' states for the estimate of the time left, in @p order's
 * order (the order they start), or NULL. */
static struct vsph_jobs_eta *eta_start(struct vsph_jobs_job **order, size_t m) {
  struct vsph_jobs_eta *e = calloc(m ? m : 1, sizeof *e);
  for (size_t k = 0; e && k < m; k++) {
    e[k].cost = cost_of(order[k]);
    e[k].family = order[k]->family;
  }
  return e;
}

/* ", about N s left" from the runs' states at @p now (running runs'
 * times so far from their start times @p t1), or "" while no run has
 * finished: a rate is measured, never assumed. */
static void eta_text(struct vsph_jobs_eta *e, const double *t1, size_t m,
                     size_t width, double now, char *buf, size_t len) {
  buf[0] = '\0';
  if (!e) return;
  for (size_t k = 0; k < m; k++)
    if (e[k].state == VSPH_JOBS_ETA_RUNNING) e[k].wall = now - t1[k];
  const double left = vsph_jobs_eta(e, m, width);
  if (left >= 0.0) snprintf(buf, len, ", about %.0f s left", left);
}

int vsph_jobs_local(struct vsph_jobs *J, int width) {
  struct vsph_jobs_job **order;
  const size_t m = missing(J, &order, (size_t)width);
  if (m == (size_t)-1) VSPH_FAIL(VSPH_ENOMEM, "cannot order the runs");
  struct vsph_jobs_eta *eta = eta_start(order, m);
  double *t1 = calloc(m ? m : 1, sizeof *t1);
  char na[96];
  archived_note(J, na, sizeof na);
  if (m)
    fprintf(stderr,
            "vsph report: %zu of the %zu runs are not in the cache%s; "
            "running them here, %d at a time\n",
            m, J->n, na, width);
  const double t0 = omp_get_wtime();
  size_t started = 0, done = 0;
  int st = VSPH_OK;
  /* one run per thread, each run's own loops on one thread (nested
   * regions are inactive): the runs are independent, and a run's results
   * do not depend on its thread count, so this changes only the time */
#pragma omp parallel for schedule(dynamic, 1) num_threads(width)
  for (size_t k = 0; k < m; k++) {
    int failed;
    size_t me = 0;
#pragma omp critical(vsph_jobs_local)
    {
      failed = st;
      if (!failed) {
        me = ++started;
        if (t1) t1[k] = omp_get_wtime();
        if (eta) eta[k].state = VSPH_JOBS_ETA_RUNNING;
        fprintf(stderr, "  [%zu/%zu] %s: started (%.0f s elapsed)\n", me, m,
                order[k]->label, omp_get_wtime() - t0);
      }
    }
    if (failed) continue;
    omp_set_num_threads(1); /* this thread's nested regions: itself alone */
    const double t_start = omp_get_wtime();
    const int s = execute(J, order[k]);
#pragma omp critical(vsph_jobs_local)
    {
      if (s && !st) st = s;
      done++;
      const double now = omp_get_wtime();
      if (eta) { /* a failed run measures nothing */
        eta[k].state = VSPH_JOBS_ETA_DONE;
        eta[k].ended = now - t0;
        eta[k].wall = s ? 0.0 : now - t_start;
        eta[k].cost = s ? 0.0 : cost_taken(order[k]);
      }
      char left[64] = "";
      if (t1) eta_text(eta, t1, m, (size_t)width, now, left, sizeof left);
      if (s == VSPH_EINTR)
        fprintf(stderr,
                "  [%zu/%zu] %s: stopped at a checkpoint (the next report "
                "resumes it)\n",
                me, m, order[k]->label);
      else if (s)
        fprintf(stderr, "  [%zu/%zu] %s: failed\n", me, m, order[k]->label);
      else
        fprintf(stderr,
                "  [%zu/%zu] %s: done in %.1f s; %zu of %zu done, %.0f s "
                "elapsed%s\n",
                me, m, order[k]->label, now - t_start, done, m, now - t0, left);
    }
  }
  free(order);
  free(eta);
  free(t1);
  for (size_t k = 0; k < J->n; k++)
    J->job[k].cached = vsph_rundir_key_matches(J->job[k].dir, J->job[k].key);
  return st;
}

/* ------------------------------------------------------ the child pool */

/* runs/logs/NAME.log of a job: its folder's last component. */
static void log_path(const struct vsph_jobs *J, const struct vsph_jobs_job *j,
                     char *buf, size_t len) {
  const char *base = strrchr(j->dir, '/');
  snprintf(buf, len, "%s/runs/logs/%s.log", J->dir, base ? base + 1 : j->dir);
}

/* Start @p j as a child of @p exe with its output in its log. */
static pid_t spawn(const struct vsph_jobs *J, const struct vsph_jobs_job *j,
                   const char *exe, size_t threads) {
  const char *argv[2 * VSPH_JOBS_NSET + 16];
  char buf[2][24], logf[700];
  vsph_jobs_argv(j, exe, threads, buf, argv, sizeof argv / sizeof argv[0]);
  log_path(J, j, logf, sizeof logf);
  const int fd = open(logf, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) {
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot open %s: %s", logf,
                       strerror(errno));
    return -1;
  }
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) { /* the child: async-signal-safe calls only, then exec */
    /* it stops (after its step, uncached) if the report dies */
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(128 + SIGTERM);
    if (dup2(fd, 1) < 0 || dup2(fd, 2) < 0) _exit(127);
    close(fd);
    execve(exe, (char *const *)argv, environ);
    static const char msg[] = "vsph report: cannot start the run's command\n";
    ssize_t w = write(2, msg, sizeof msg - 1);
    (void)w;
    _exit(127);
  }
  close(fd);
  if (pid < 0)
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot fork: %s",
                       strerror(errno));
  return pid;
}

/* "ok", or "unstable at t = T" from a run's run.json. */
static void verdict(const struct vsph_jobs_job *j, char *buf, size_t len) {
  snprintf(buf, len, "ok");
  if (j->kind != VSPH_JOBS_RUN) return;
  char path[600];
  snprintf(path, sizeof path, "%s/run.json", j->dir);
  cJSON *o = vsph_json_read(path);
  if (!o) return;
  const cJSON *s = cJSON_GetObjectItemCaseSensitive(o, "status");
  if (cJSON_IsString(s) && strcmp(s->valuestring, "ok"))
    snprintf(buf, len, "%s at t = %.4g s", s->valuestring,
             vsph_json_get_number(o, "unstable_time", (double)NAN));
  cJSON_Delete(o);
}

/* runs/failed.txt: the runs that did not end, with their logs (removed
 * when none failed). */
static int record_failed(const struct vsph_jobs *J,
                         struct vsph_jobs_job **order, size_t m,
                         const int *status) {
  char *text = NULL;
  size_t len = 0, nf = 0;
  FILE *f = open_memstream(&text, &len);
  if (!f) VSPH_FAIL(VSPH_ENOMEM, "cannot list the failed runs");
  fprintf(f,
          "# runs of the last vsph report that did not end: folder, "
          "exit status, log\n");
  for (size_t k = 0; k < m; k++)
    if (order[k]->failed) {
      char logf[700];
      log_path(J, order[k], logf, sizeof logf);
      fprintf(f, "%s\t%d\t%s\n", order[k]->dir, status[k], logf);
      nf++;
    }
  fclose(f);
  char dir[600], path[700];
  snprintf(dir, sizeof dir, "%s/runs", J->dir);
  snprintf(path, sizeof path, "%s/failed.txt", dir);
  int st = VSPH_OK;
  if (nf)
    st = vsph_files_write(dir, "failed.txt", text);
  else if (remove(path) != 0 && errno != ENOENT)
    st = VSPH_EIO;
  free(text);
  return st;
}

int vsph_jobs_pool(struct vsph_jobs *J, const char *exe, size_t njobs,
                   size_t threads) {
  struct vsph_jobs_job **order;
  const size_t m = missing(J, &order, njobs);
  if (m == (size_t)-1) VSPH_FAIL(VSPH_ENOMEM, "cannot order the runs");
  char logs[600];
  snprintf(logs, sizeof logs, "%s/runs/logs", J->dir);
  int st = vsph_files_mkdir(logs);
  pid_t *pid = calloc(m ? m : 1, sizeof *pid);
  int *status = calloc(m ? m : 1, sizeof *status);
  double *t1 = calloc(m ? m : 1, sizeof *t1);
  struct vsph_jobs_eta *eta = eta_start(order, m);
  if (!st && (!pid || !status || !t1 || !eta)) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot track %zu runs", m);
  }
  char na[96];
  archived_note(J, na, sizeof na);
  if (m && !st)
    fprintf(stderr,
            "vsph report: %zu of the %zu runs are not in the cache%s; "
            "running them as %zu processes of %zu threads (logs in %s)\n",
            m, J->n, na, njobs, threads, logs);
  const double t0 = omp_get_wtime();
  size_t next = 0, running = 0, done = 0, nfailed = 0;
  int stopping = st != VSPH_OK, err = VSPH_OK;
  while (running > 0 || (next < m && !stopping)) {
    while (!stopping && next < m && running < njobs) {
      if ((pid[next] = spawn(J, order[next], exe, threads)) < 0) {
        err = VSPH_EIO; /* stop the others, as on a signal */
        pid[next] = 0;
        break;
      }
      t1[next] = omp_get_wtime();
      eta[next].state = VSPH_JOBS_ETA_RUNNING;
      fprintf(stderr, "  [%zu/%zu] %s: started, pid %ld (%.0f s elapsed)\n",
              next + 1, m, order[next]->label, (long)pid[next], t1[next] - t0);
      running++;
      next++;
    }
    if (!stopping && (err || (J->stop && *J->stop))) { /* pass it on */
      stopping = 1;
      fprintf(stderr,
              "vsph report: stopping; each running run stops at a "
              "checkpoint (uncached: the next report resumes it)\n");
      for (size_t k = 0; k < next; k++)
        if (pid[k] > 0) kill(pid[k], SIGTERM);
    }
    int ws;
    const pid_t w = waitpid(-1, &ws, WNOHANG);
    if (w == 0 || (w < 0 && errno == EINTR)) {
      const struct timespec ts = {0, 100000000}; /* 0.1 s */
      nanosleep(&ts, NULL);
      continue;
    }
    if (w < 0) break; /* no child left */
    size_t k = 0;
    while (k < next && pid[k] != w) k++;
    if (k == next) continue; /* not one of ours */
    pid[k] = 0;
    running--;
    done++;
    status[k] = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
    order[k]->cached =
        status[k] == 0 && vsph_rundir_key_matches(order[k]->dir, order[k]->key);
    const double now = omp_get_wtime(), el = now - t0;
    eta[k].state = VSPH_JOBS_ETA_DONE; /* a failed run measures nothing */
    eta[k].ended = el;
    eta[k].wall = order[k]->cached ? now - t1[k] : 0.0;
    eta[k].cost = order[k]->cached ? cost_taken(order[k]) : 0.0;
    if (order[k]->cached) {
      char v[96], left[64];
      verdict(order[k], v, sizeof v);
      eta_text(eta, t1, m, njobs, now, left, sizeof left);
      fprintf(stderr,
              "  [%zu/%zu] %s: %s, %.1f s; %zu of %zu done, %.0f s "
              "elapsed%s\n",
              k + 1, m, order[k]->label, v, now - t1[k], done, m, el, left);
    } else if (!stopping) {
      char logf[700];
      log_path(J, order[k], logf, sizeof logf);
      order[k]->failed = 1;
      nfailed++;
      fprintf(stderr,
              "  [%zu/%zu] %s: FAILED (exit status %d; see %s); the others "
              "go on\n",
              k + 1, m, order[k]->label, status[k], logf);
    }
  }
  if (!st) st = record_failed(J, order, next, status);
  free(order);
  free(pid);
  free(status);
  free(t1);
  free(eta);
  if (st) return st;
  if (err) return err;
  if (stopping) return VSPH_EINTR;
  if (nfailed)
    VSPH_FAIL(VSPH_EFAIL,
              "%zu of %zu runs failed (listed in %s/runs/failed.txt with their "
              "logs); the report is not assembled: mend them and rerun, only "
              "they run again",
              nfailed, m, J->dir);
  return VSPH_OK;
}

/* ---------------------------------------------------------------- Slurm */

/* A Slurm time limit from an estimate in seconds: D-HH:MM:SS. */
static void slurm_time(double s, char *buf, size_t len) {
  const long t = (long)ceil(s);
  snprintf(buf, len, "%ld-%02ld:%02ld:%02ld", t / 86400, t / 3600 % 24,
           t / 60 % 60, t % 60);
}

/* The job id that `sbatch --parsable` printed ("ID" or "ID;cluster"). */
static int submit(const char *cmd, char *id, size_t len) {
  FILE *p = popen(cmd, "r");
  if (!p) VSPH_FAIL(VSPH_EIO, "cannot run '%s': %s", cmd, strerror(errno));
  char line[256] = "";
  const int got = fgets(line, sizeof line, p) != NULL;
  const int rc = pclose(p);
  line[strcspn(line, ";\n")] = '\0';
  if (!got || rc != 0 || !*line || strspn(line, "0123456789") != strlen(line))
    VSPH_FAIL(VSPH_EIO, "sbatch refused the job ('%s' answered '%s')", cmd,
              line);
  snprintf(id, len, "%.40s", line);
  return VSPH_OK;
}

/* The rate the time limit assumes, in estimated pair interactions
 * (particles x neighbours x steps, vsph_run_estimate) per second and
 * thread: a third of the slowest this machine made in the quick report's
 * 239 runs (2.6e6 to 4.7e8 per second, two runs at a time on 2 cores,
 * 2026-11-24; the slowest are the short channel runs, whose viscous time
 * step the estimate at t = 0 undercounts), so that a cluster's slower
 * core still fits. */
#define SLURM_RATE 1e6

int vsph_jobs_slurm_dir(const char *dir, char *abs, size_t len) {
  const int existed = access(dir, F_OK) == 0;
  int st = vsph_files_mkdir(dir);
  if (st) return st;
  char buf[PATH_MAX];
  if (!realpath(dir, buf))
    VSPH_FAIL(VSPH_EIO, "cannot resolve %s: %s", dir, strerror(errno));
  /* #SBATCH lines take no quotes, and % is Slurm's pattern sign */
  if (strpbrk(buf, " \t\n%'\"\\") || strlen(buf) >= len) {
    if (!existed) rmdir(dir);
    VSPH_FAIL(VSPH_EINVAL,
              "--slurm: the folder '%s' holds a space, a quote or '%%', "
              "which Slurm's #SBATCH lines cannot carry: choose another --out",
              buf);
  }
  snprintf(abs, len, "%s", buf);
  return VSPH_OK;
}

/* Minutes in a Slurm time limit (M, M:S, H:M:S, D-H, D-H:M, D-H:M:S; as
 * vsph report checks it); 0 if it is none of them. */
static double limit_minutes(const char *t) {
  double v[4] = {0};
  int n = 0, days = 0;
  const char *dash = strchr(t, '-');
  if (dash) {
    days = atoi(t);
    t = dash + 1;
  }
  for (char *end; n < 4 && *t; n++, t = *end == ':' ? end + 1 : end) {
    v[n] = strtod(t, &end);
    if (end == t) return 0.0;
  }
  double min = 0.0;
  if (dash) /* D-H, D-H:M, D-H:M:S */
    min = 60.0 * v[0] + (n > 1 ? v[1] : 0.0) + (n > 2 ? v[2] / 60.0 : 0.0);
  else if (n == 1) /* M */
    min = v[0];
  else if (n == 2) /* M:S */
    min = v[0] + v[1] / 60.0;
  else /* H:M:S */
    min = 60.0 * v[0] + v[1] + v[2] / 60.0;
  return 1440.0 * days + min;
}

/* The job array of the @p m runs of @p order: one task each, the
 * resources of the largest. A task that meets its time limit is sent
 * SIGTERM (Slurm's --signal, 2 minutes ahead where the limit is 10
 * minutes or more; else Slurm's own SIGTERM at the limit): it writes a
 * checkpoint and stops, and the next submission resumes it. */
static int array_script(const struct vsph_jobs_job *const *order, size_t m,
                        const struct vsph_jobs_slurm *s, const char *logs,
                        size_t mem_mib, const char *limit, char **text) {
  size_t len;
  char *cmd = malloc(8192);
  FILE *f = cmd ? open_memstream(text, &len) : NULL;
  if (!f) {
    free(cmd);
    VSPH_FAIL(VSPH_ENOMEM, "cannot write the job array");
  }
  fprintf(f,
          "#!/bin/sh\n"
          "# vsph %s: the report's missing runs, one array task each "
          "(written by vsph report --slurm)\n"
          "#SBATCH --job-name=vsph-runs\n"
          "#SBATCH --array=0-%zu\n"
          "#SBATCH --ntasks=1\n"
          "#SBATCH --cpus-per-task=%zu\n"
          "#SBATCH --mem=%zuM\n"
          "#SBATCH --time=%s\n"
          "#SBATCH --output=%s/task-%%A_%%a.log\n",
          VSPH_VERSION, m ? m - 1 : 0, s->threads, mem_mib, limit, logs);
  if (s->partition) fprintf(f, "#SBATCH --partition=%s\n", s->partition);
  /* B: to the batch shell, which is vsph (exec); Slurm may send it up to
   * a minute early */
  if (limit_minutes(limit) >= 10.0) fprintf(f, "#SBATCH --signal=B:TERM@120\n");
  fprintf(f, "case \"$SLURM_ARRAY_TASK_ID\" in\n");
  for (size_t k = 0; k < m; k++) {
    vsph_jobs_command(order[k], s->exe, s->threads, cmd, 8192);
    fprintf(f, "%zu) exec %s ;;\n", k, cmd);
  }
  fprintf(f,
          "*) echo \"no task $SLURM_ARRAY_TASK_ID\" >&2; exit 2 ;;\n"
          "esac\n");
  free(cmd);
  if (fclose(f) != 0) VSPH_FAIL(VSPH_ENOMEM, "cannot write the job array");
  return VSPH_OK;
}

/* The assembly: the same report again (--out, --full, --only), reading
 * the runs only. */
static int assembly_script(const struct vsph_jobs *J,
                           const struct vsph_jobs_slurm *s, const char *logs,
                           char **text) {
  char q[3][PATH_MAX + 64];
  vsph_shell_quote(s->exe, q[0], sizeof q[0]);
  vsph_shell_quote(J->dir, q[1], sizeof q[1]);
  vsph_shell_quote(s->only ? s->only : "", q[2], sizeof q[2]);
  size_t len;
  FILE *f = open_memstream(text, &len);
  if (!f) VSPH_FAIL(VSPH_ENOMEM, "cannot write the assembly");
  fprintf(f,
          "#!/bin/sh\n"
          "# vsph %s: the report's assembly after its runs (written by "
          "vsph report --slurm)\n"
          "#SBATCH --job-name=vsph-report\n"
          "#SBATCH --ntasks=1\n"
          "#SBATCH --cpus-per-task=%zu\n"
          "#SBATCH --mem=2048M\n"
          "#SBATCH --time=1:00:00\n"
          "#SBATCH --output=%s/assemble-%%j.log\n",
          VSPH_VERSION, s->threads, logs);
  if (s->partition) fprintf(f, "#SBATCH --partition=%s\n", s->partition);
  fprintf(f, "OMP_NUM_THREADS=%zu exec %s report --out %s%s%s%s --assemble\n",
          s->threads, q[0], q[1], J->full ? " --full" : "",
          s->only ? " --only " : "", s->only ? q[2] : "");
  if (fclose(f) != 0) VSPH_FAIL(VSPH_ENOMEM, "cannot write the assembly");
  return VSPH_OK;
}

/* Write a script (@p text, freed) into @p dir as @p name and its path,
 * quoted for a shell, into @p quoted. */
static int put_script(const char *dir, const char *name, char *text,
                      char *quoted, size_t len) {
  const int st = vsph_files_write(dir, name, text);
  free(text);
  char path[PATH_MAX + 64];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  vsph_shell_quote(path, quoted, len);
  return st;
}

/* submitted.json: the job ids and what was asked for. */
static int record_submission(const struct vsph_jobs *J, const char *dir,
                             const char *array_id, const char *asm_id,
                             const struct vsph_jobs_job *const *order, size_t m,
                             size_t threads, size_t mem_mib,
                             const char *limit) {
  cJSON *o = cJSON_CreateObject();
  const time_t now = time(NULL);
  char stamp[32];
  struct tm utc;
  strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", gmtime_r(&now, &utc));
  cJSON_AddStringToObject(o, "date", stamp);
  cJSON_AddStringToObject(o, "array_job", array_id);
  cJSON_AddStringToObject(o, "assembly_job", asm_id);
  cJSON_AddNumberToObject(o, "tasks", (double)m);
  cJSON_AddNumberToObject(o, "runs", (double)J->n);
  cJSON_AddNumberToObject(o, "cpus_per_task", (double)threads);
  cJSON_AddNumberToObject(o, "mem_mib", (double)mem_mib);
  cJSON_AddStringToObject(o, "time", limit);
  cJSON *t = cJSON_AddArrayToObject(o, "task_folders");
  for (size_t k = 0; k < m; k++)
    cJSON_AddItemToArray(t, cJSON_CreateString(order[k]->dir));
  return vsph_json_write(o, dir, "submitted.json");
}

int vsph_jobs_slurm(struct vsph_jobs *J, const struct vsph_jobs_slurm *s) {
  struct vsph_jobs_job **order;
  const size_t m = missing(J, &order, 1);
  if (m == (size_t)-1) VSPH_FAIL(VSPH_ENOMEM, "cannot order the runs");
  const struct vsph_jobs_job *const *jobs =
      (const struct vsph_jobs_job *const *)order;
  char dir[600], logs[700];
  snprintf(dir, sizeof dir, "%s/slurm", J->dir);
  snprintf(logs, sizeof logs, "%s/logs", dir);
  int st = vsph_files_mkdir(logs);
  double mem = 0.0, cost = 0.0;
  for (size_t k = 0; k < m; k++) {
    mem = fmax(mem, order[k]->bytes);
    cost = fmax(cost, cost_of(order[k]));
  }
  /* memory: the largest run's bound and 256 MiB for the program itself
   * (a quick-report run peaks at about 10 MB); time: the costliest run at
   * SLURM_RATE, at least 10 minutes */
  const size_t mem_mib = (size_t)ceil(mem / 1048576.0) + 256;
  char limit[40];
  if (s->time)
    snprintf(limit, sizeof limit, "%s", s->time);
  else
    slurm_time(fmax(600.0, cost / (SLURM_RATE * (double)s->threads)), limit,
               sizeof limit);
  char *text = NULL, script[2][PATH_MAX + 64], cmd[2 * PATH_MAX + 256];
  if (!st && !(st = array_script(jobs, m, s, logs, mem_mib, limit, &text)))
    st = put_script(dir, "runs.sbatch", text, script[0], sizeof script[0]);
  if (!st && !(st = assembly_script(J, s, logs, &text)))
    st = put_script(dir, "assemble.sbatch", text, script[1], sizeof script[1]);
  char array_id[64] = "", asm_id[64] = "";
  if (!st && m) {
    snprintf(cmd, sizeof cmd, "sbatch --parsable %s", script[0]);
    st = submit(cmd, array_id, sizeof array_id);
  }
  if (!st) {
    if (m)
      snprintf(cmd, sizeof cmd, "sbatch --parsable --dependency=afterany:%s %s",
               array_id, script[1]);
    else
      snprintf(cmd, sizeof cmd, "sbatch --parsable %s", script[1]);
    st = submit(cmd, asm_id, sizeof asm_id);
  }
  if (!st)
    st = record_submission(J, dir, array_id, asm_id, jobs, m, s->threads,
                           mem_mib, limit);
  if (!st) {
    if (m)
      printf(
          "vsph report: submitted %zu runs as array job %s (%zu CPUs, %zu "
          "MiB, %s each) and the assembly as job %s after it; %s must be "
          "on a file system every node shares\n",
          m, array_id, s->threads, mem_mib, limit, asm_id, J->dir);
    else
      printf(
          "vsph report: every run is cached; submitted the assembly as "
          "job %s\n",
          asm_id);
    fflush(stdout);
  }
  free(order);
  return st;
}

/* ------------------------------------------------------- reading runs */

void vsph_jobs_run_free(struct vsph_jobs_run *r) {
  vsph_csv_free(r->energy);
  r->energy = NULL;
}

/* energy.csv: the columns the parts read, by name. */
static int load_energy(struct vsph_jobs_run *r) {
  char path[600];
  snprintf(path, sizeof path, "%s/energy.csv", r->dir);
  r->energy = vsph_csv_read(path);
  if (!r->energy) return VSPH_EIO;
  const struct vsph_csv *e = r->energy;
  r->nrow = e->nrow;
  r->t = vsph_csv_column(e, "t");
  r->Ek = vsph_csv_column(e, "Ek");
  r->Pv = vsph_csv_column(e, "P_visc");
  r->res_b = vsph_csv_column(e, "residual");
  r->dEk = vsph_csv_column(e, "dEk_dt");
  r->Ekr = vsph_csv_column(e, "Ek_ref");
  r->dEkr = vsph_csv_column(e, "dEk_ref");
  r->Ep = vsph_csv_column(e, "Ep");
  r->Ec = vsph_csv_column(e, "Ec");
  r->Emr = vsph_csv_column(e, "Em_ref");
  r->dEmr = vsph_csv_column(e, "dEm_ref");
  if (!r->t || !r->Ek || !r->Pv || !r->res_b || !r->dEk || !r->Ekr ||
      !r->dEkr || !r->Ep || !r->Ec || !r->Emr || !r->dEmr || r->nrow == 0)
    VSPH_FAIL(VSPH_EIO, "%s lacks the columns of an energy table", path);
  return VSPH_OK;
}

/* A count from run.json; 0 unless it is a whole number that fits, so a
 * damaged file never reaches an undefined conversion. */
static size_t count_of(const cJSON *j, const char *key) {
  const double v = vsph_json_get_number(j, key, 0.0);
  return v >= 0.0 && v < 9007199254740992.0 ? (size_t)v : 0;
}

static int load_run_json(struct vsph_jobs_run *r) {
  char path[600];
  snprintf(path, sizeof path, "%s/run.json", r->dir);
  cJSON *j = vsph_json_read(path);
  if (!j) VSPH_FAIL(VSPH_EIO, "cannot read %s", path);
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(j, "status");
  r->ok = cJSON_IsString(v) && !strcmp(v->valuestring, "ok");
  r->t_unstable = vsph_json_get_number(j, "unstable_time", (double)NAN);
  v = cJSON_GetObjectItemCaseSensitive(j, "unstable_reason");
  snprintf(r->reason, sizeof r->reason, "%s",
           cJSON_IsString(v) ? v->valuestring : "");
  r->wall_s = vsph_json_get_number(j, "wall_s", (double)NAN);
  r->pairs = vsph_json_get_number(j, "pairs_per_s", 0.0) * r->wall_s;
  r->cpu_s = vsph_json_get_number(j, "cpu_s", (double)NAN);
  v = cJSON_GetObjectItemCaseSensitive(j, "load_average_start");
  const cJSON *l1 = cJSON_IsArray(v) ? cJSON_GetArrayItem(v, 0) : NULL;
  r->load = cJSON_IsNumber(l1) ? l1->valuedouble : (double)NAN;
  r->n = count_of(j, "n_particles");
  r->steps = count_of(j, "steps");
  r->res = count_of(j, "res");
  cJSON_Delete(j);
  return VSPH_OK;
}

int vsph_jobs_load(const char *dir, struct vsph_jobs_run *out) {
  memset(out, 0, sizeof *out);
  if (strlen(dir) >= sizeof out->dir)
    VSPH_FAIL(VSPH_EINVAL, "%.60s...: the folder's name is too long", dir);
  snprintf(out->dir, sizeof out->dir, "%s", dir);
  int st = load_run_json(out);
  if (!st) st = load_energy(out);
  if (st) vsph_jobs_run_free(out); /* (a table read, its columns not) */
  return st;
}

int vsph_jobs_get(const struct vsph_jobs *J, const struct vsph_jobs_spec *rs,
                  struct vsph_jobs_run *out) {
  memset(out, 0, sizeof *out);
  struct vsph_jobs_job j;
  int st = vsph_jobs_run(J, rs, &j);
  snprintf(out->dir, sizeof out->dir, "%s", j.dir);
  if (!st) st = vsph_jobs_ready(J, &j);
  if (!st) st = vsph_jobs_load(vsph_jobs_where(J, j.dir), out);
  /* the parts name a run by its planned folder, wherever it was read */
  snprintf(out->dir, sizeof out->dir, "%s", j.dir);
  vsph_jobs_free(&j);
  return st;
}

/* Whether the seal (key.txt) of folder @p dir lists file @p name. */
static int seal_lists(const char *dir, const char *name) {
  char path[700], line[300];
  snprintf(path, sizeof path, "%s/key.txt", dir);
  char *seal = vsph_files_slurp(path, NULL);
  snprintf(line, sizeof line, "\n%s ", name);
  const int listed = seal && strstr(seal, line) != NULL;
  free(seal);
  return listed;
}

/* A planned (or, unplanned, any) sealed run in folder @p dir whose seal
 * lists @p name: its path. */
int vsph_jobs_file(const struct vsph_jobs *J, const char *dir, const char *name,
                   char *path, size_t len) {
  const struct vsph_jobs_job *j = J->planned ? find(J, dir) : NULL;
  if (J->planned && !j)
    VSPH_FAIL(VSPH_EINVAL, "run %s is not in the plan (a bug)", dir);
  const char *key = NULL;
  if (j) dir = where_of(j, &key);
  char why[700] = "";
  if (j && vsph_folder_verify(dir, NULL, key, NULL, why, sizeof why) != 1)
    VSPH_FAIL(VSPH_EIO, "run %s is not sealed%s%s", dir, why[0] ? ": " : "",
              why);
  if (!seal_lists(dir, name))
    VSPH_FAIL(VSPH_EIO, "run %s holds no %s under its seal", dir, name);
  snprintf(path, len, "%s/%s", dir, name);
  return VSPH_OK;
}

struct vsph_csv *vsph_jobs_table(const struct vsph_jobs *J, const char *dir,
                                 const char *name) {
  char path[700];
  if (vsph_jobs_file(J, dir, name, path, sizeof path)) return NULL;
  struct vsph_csv *c = vsph_csv_read(path);
  if (!c)
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot read %s", path);
  return c;
}

void vsph_jobs_plan_free(struct vsph_jobs *J) {
  for (size_t k = 0; k < J->n; k++) vsph_jobs_free(&J->job[k]);
  free(J->job);
  J->job = NULL;
  J->n = J->cap = 0;
}

int vsph_jobs_holds(const struct vsph_jobs *J, const char *dir,
                    const char *name) {
  return seal_lists(vsph_jobs_where(J, dir), name);
}

/* Folder @p a's path relative to folder @p b, both absolute as realpath
 * gives them, into @p buf: "../" for each of b's components below the
 * last folder their paths share (the last '/' of their common prefix),
 * then the rest of a. */
static void relative_path(const char *a, const char *b, char *buf, size_t len) {
  size_t c = 0;
  for (size_t k = 0; a[k] && a[k] == b[k]; k++)
    if (a[k] == '/') c = k;
  size_t n = 0;
  buf[0] = '\0';
  for (const char *s = b + c; *s; s++)
    if (*s == '/' && n + 4 < len)
      n += (size_t)snprintf(buf + n, len - n, "../");
  snprintf(buf + n, len - n, "%s", a[c] == '/' ? a + c + 1 : a + c);
}

void vsph_jobs_data_path(const struct vsph_jobs *J, const char *dir,
                         const char *name, char *buf, size_t len) {
  const char *where = vsph_jobs_where(J, dir);
  const char *base = strrchr(dir, '/');
  char ra[PATH_MAX], rb[PATH_MAX], rel[2 * PATH_MAX];
  if (!strcmp(where, dir) || !realpath(where, ra) || !realpath(J->dir, rb)) {
    snprintf(buf, len, "runs/%s/%s", base ? base + 1 : dir, name);
    return;
  }
  relative_path(ra, rb, rel, sizeof rel);
  snprintf(buf, len, "%s/%s", rel, name);
}

int vsph_jobs_last_snapshot(const struct vsph_jobs *J, const char *dir) {
  char path[700];
  if (vsph_jobs_file(J, dir, "snapshots.pvd", path, sizeof path)) return -1;
  snprintf(path, sizeof path, "%s/key.txt", vsph_jobs_where(J, dir));
  char *seal = vsph_files_slurp(path, NULL);
  int last = -1;
  for (const char *c = seal; c && (c = strstr(c, "\nsnap_")); c++) {
    int k;
    if (sscanf(c + 6, "%4d.vtp ", &k) == 1 && k > last) last = k;
  }
  free(seal);
  return last;
}

double vsph_jobs_peak_rss(const char *scene, const char *visc, size_t res,
                          double t_end) {
  char dir[] = "/tmp/vsph-bench-XXXXXX";
  if (!mkdtemp(dir)) return 0.0;
  char out[64], r[32], t[32];
  snprintf(out, sizeof out, "%s/run", dir);
  snprintf(r, sizeof r, "%zu", res);
  snprintf(t, sizeof t, "%.17g", t_end);
  const pid_t pid = fork();
  if (pid == 0) { /* the child: only exec (safe after fork in threads) */
    const int null = open("/dev/null", O_WRONLY);
    if (null >= 0) {
      dup2(null, 1);
      dup2(null, 2);
    }
    execl("/proc/self/exe", "vsph", "run", scene, "--visc", visc, "--res", r,
          "--t-end", t, "--outputs", "1", "--snapshots", "0", "--out", out,
          (char *)NULL);
    _exit(127);
  }
  int status = 1;
  if (pid > 0) waitpid(pid, &status, 0);
  double peak = 0.0;
  char path[96];
  snprintf(path, sizeof path, "%s/run.json", out);
  cJSON *j = pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0
                 ? vsph_json_read(path)
                 : NULL;
  if (j) peak = vsph_json_get_number(j, "peak_rss_bytes", 0.0);
  cJSON_Delete(j);
  /* the folder this made: the run's files, its marker and lock */
  DIR *d = opendir(out);
  for (struct dirent *e; d && (e = readdir(d));) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    char f[400];
    snprintf(f, sizeof f, "%s/%s", out, e->d_name);
    remove(f);
  }
  if (d) closedir(d);
  remove(out);
  remove(dir);
  return peak;
}
