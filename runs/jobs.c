/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's runs as jobs. Every part declares the runs it reads (its
 * plan) before any is run; the report then runs what is missing and
 * assembles. Three ways to run them: in this process, a run per thread (the
 * default); as child processes, N at a time (`--jobs N`); or as a Slurm
 * job array with the assembly after it (`vsph report submit`). A job is
 * one command (`vsph run ... --cache` or `vsph contact ... --cache`) whose
 * folder ends with key.txt (runs/rundir): the cache, and the proof that
 * the run ended, whichever way ran it. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "jobs.h"

#include <errno.h>
#include <stdlib.h>

#include "../analysis/contact.h"
#include "../common/status.h"
#include "../solver/run.h"
#include "folder.h"
#include "jobs_internal.h"
#include "rundir.h"
#include "sheartest.h"
#include "shell.h"

/* ----------------------------------------------------------------- jobs */

int vsph_jobs_defaults(int kind, const char *scene, struct vsph_params *prm) {
  if (!prm) VSPH_FAIL(VSPH_EINVAL, "vsph_jobs_defaults: a NULL argument");
  if (kind == VSPH_JOBS_SHEAR) return vsph_contact_defaults(prm);
  const struct vsph_scene_type *t = scene ? vsph_scene_find(scene) : NULL;
  if (kind != VSPH_JOBS_RUN || !t)
    VSPH_FAIL(VSPH_EINVAL,
              "vsph_jobs_defaults: no job of kind %d on scene '%s'", kind,
              scene ? scene : "(null)");
  return vsph_scene_solver_defaults(t, prm);
}

/* The parameters of @p j's settings, as given. */
static int params_of(const struct vsph_jobs_job *j, struct vsph_params **out) {
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate parameters");
  int st = VSPH_OK;
  for (size_t k = 0; k < j->nset && !st; k++)
    st = vsph_params_assign(prm, j->set[k]);
  /* the defaults the job's command adds, so that its key here is the one
   * the command writes */
  if (!st) st = vsph_jobs_defaults(j->kind, j->scene, prm);
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
int vsph_jobs_estimate(struct vsph_jobs_job *j) {
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
double vsph_jobs_cost_of(const struct vsph_jobs_job *j) {
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
  int st = vsph_jobs_estimate(j);
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
int vsph_jobs_execute(const struct vsph_jobs *J,
                      const struct vsph_jobs_job *j) {
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
    st = vsph_sheartest_execute(prm, j->nprof, j->dir, 1, 1, J->stop, &cached);
  }
  vsph_params_free(prm);
  return st;
}

const struct vsph_jobs_job *vsph_jobs_find(const struct vsph_jobs *P,
                                           const char *dir) {
  for (size_t k = 0; k < P->n; k++)
    if (!strcmp(P->job[k].dir, dir)) return &P->job[k];
  return NULL;
}

/* The folder a planned job's files are read from, and the key its seal
 * must hold for. */
const char *vsph_jobs_where_of(const struct vsph_jobs_job *p,
                               const char **key) {
  *key = p->from[0] ? p->from_key : p->key;
  return p->from[0] ? p->from : p->dir;
}

const char *vsph_jobs_where(const struct vsph_jobs *J, const char *dir) {
  const struct vsph_jobs_job *p = J->planned ? vsph_jobs_find(J, dir) : NULL;
  const char *key;
  return p ? vsph_jobs_where_of(p, &key) : dir;
}

int vsph_jobs_ready(const struct vsph_jobs *J, const struct vsph_jobs_job *j) {
  if (!J->planned) return j->cached ? VSPH_OK : vsph_jobs_execute(J, j);
  const struct vsph_jobs_job *p = vsph_jobs_find(J, j->dir);
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
    VSPH_FAIL(
        VSPH_EIO,
        "run %s is missing or unfinished (no matching key.txt): run the "
        "report's runs first (vsph report [--jobs N] or vsph report submit)",
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
      cost += vsph_jobs_cost_of(&P->job[k]);
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

void vsph_jobs_plan_free(struct vsph_jobs *J) {
  for (size_t k = 0; k < J->n; k++) vsph_jobs_free(&J->job[k]);
  free(J->job);
  J->job = NULL;
  J->n = J->cap = 0;
}
