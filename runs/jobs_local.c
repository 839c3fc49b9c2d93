/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's missing runs in this process, a run per thread, with an
 * honest time left (the rates of the cached runs), and the budget's fit.
 * Part of the jobs module (runs/jobs.c). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/contact.h"
#include "../common/status.h"
#include "../io/json.h"
#include "jobs.h"
#include "jobs_internal.h"
#include "rundir.h"
#include "sheartest.h"

/* ------------------------------------------------------ the missing runs */

/* Run @p r's work: its pair interactions and a step's work beyond them
 * for each of its steps (VSPH_JOBS_STEP_WORK). */
static double work_of(const struct vsph_jobs_eta *r) {
  return r->per_step > 0.0 ? r->cost * (1.0 + VSPH_JOBS_STEP_WORK / r->per_step)
                           : r->cost;
}

/* Seconds per unit of work of the finished runs of @p family (all, when
 * NULL); 0 where none measured any. */
static double eta_rate(const struct vsph_jobs_eta *r, size_t n,
                       const char *family) {
  double work = 0.0, wall = 0.0;
  for (size_t k = 0; k < n; k++)
    if (r[k].state == VSPH_JOBS_ETA_DONE && r[k].cost > 0.0 &&
        (!family || !strcmp(r[k].family, family))) {
      work += work_of(&r[k]);
      wall += r[k].wall;
    }
  return work > 0.0 ? wall / work : 0.0;
}

double vsph_jobs_local_eta(const struct vsph_jobs_eta *r, size_t n,
                           size_t width) {
  const double all = eta_rate(r, n, NULL);
  if (all <= 0.0 || width < 1) return -1.0;
  double *lane = calloc(width, sizeof *lane); /* when each is free, from now */
  if (!lane) return -1.0;
  for (size_t k = 0; k < n; k++) {
    if (r[k].state == VSPH_JOBS_ETA_DONE) continue;
    const double own = eta_rate(r, n, r[k].family);
    double need = (own > 0.0 ? own : all) * work_of(&r[k]);
    if (r[k].state == VSPH_JOBS_ETA_RUNNING) need = fmax(need - r[k].wall, 0.0);
    size_t first = 0; /* the lane free first takes it */
    for (size_t i = 1; i < width; i++)
      if (lane[i] < lane[first]) first = i;
    lane[first] += need;
  }
  double left = 0.0;
  for (size_t i = 0; i < width; i++) left = fmax(left, lane[i]);
  free(lane);
  return left;
}

/* The cost a finished run actually had: its particles x neighbours x the
 * steps it took (run.json, or the shear test's summary.csv), which a run
 * stopped early (a stability map's) or whose time step changed makes
 * differ from the plan's estimate; the estimate where neither is read. */
double vsph_jobs_local_cost_taken(const struct vsph_jobs_job *j) {
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
  return steps > 0.0 ? j->particles * j->neighbours * steps
                     : vsph_jobs_cost_of(j);
}

/* The missing jobs of the plan, the costliest first. */
static int by_cost(const void *a, const void *b) {
  const double x = vsph_jobs_cost_of(*(const struct vsph_jobs_job *const *)a),
               y = vsph_jobs_cost_of(*(const struct vsph_jobs_job *const *)b);
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

size_t vsph_jobs_local_fit(const double *t, size_t m, size_t lanes,
                           double budget, unsigned char *keep) {
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
 * J->budget_s on @p lanes lanes (vsph_jobs_local_fit), in the same order;
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
    t[k] = vsph_jobs_cost_of(order[k]) * (r > 0.0 ? r : all);
  }
  const size_t kept = vsph_jobs_local_fit(t, m, lanes, J->budget_s, keep);
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
void vsph_jobs_local_archived_note(const struct vsph_jobs *J, char *buf,
                                   size_t len) {
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
size_t vsph_jobs_local_missing(struct vsph_jobs *J, struct vsph_jobs_job ***out,
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
struct vsph_jobs_eta *vsph_jobs_local_eta_start(struct vsph_jobs_job **order,
                                                size_t m) {
  struct vsph_jobs_eta *e = calloc(m ? m : 1, sizeof *e);
  for (size_t k = 0; e && k < m; k++) {
    e[k].cost = vsph_jobs_cost_of(order[k]);
    e[k].family = order[k]->family;
    e[k].per_step = order[k]->particles * order[k]->neighbours;
  }
  return e;
}

/* ", about N s left" from the runs' states at @p now (running runs'
 * times so far from their start times @p t1), or "" while no run has
 * finished: a rate is measured, never assumed. */
void vsph_jobs_local_eta_text(struct vsph_jobs_eta *e, const double *t1,
                              size_t m, size_t width, double now, double after,
                              char *buf, size_t len) {
  buf[0] = '\0';
  if (!e) return;
  for (size_t k = 0; k < m; k++)
    if (e[k].state == VSPH_JOBS_ETA_RUNNING) e[k].wall = now - t1[k];
  const double left = vsph_jobs_local_eta(e, m, width);
  if (left >= 0.0 && after > 0.0)
    snprintf(buf, len, ", about %.0f s left (%.0f s of them after the runs)",
             left + after, after);
  else if (left >= 0.0)
    snprintf(buf, len, ", about %.0f s left", left);
}

int vsph_jobs_local_run(struct vsph_jobs *J, int width) {
  struct vsph_jobs_job **order;
  const size_t m = vsph_jobs_local_missing(J, &order, (size_t)width);
  if (m == (size_t)-1) VSPH_FAIL(VSPH_ENOMEM, "cannot order the runs");
  struct vsph_jobs_eta *eta = vsph_jobs_local_eta_start(order, m);
  double *t1 = calloc(m ? m : 1, sizeof *t1);
  char na[96];
  vsph_jobs_local_archived_note(J, na, sizeof na);
  if (m)
    fprintf(stderr,
            "vsph report: %zu of the %zu runs are not in the cache%s; "
            "running them here, %d at a time\n",
            m, J->n, na, width);
  const double t0 = omp_get_wtime();
  size_t done = 0;
  int st = VSPH_OK;
  /* one run per thread, each run's own loops on one thread (nested
   * regions are inactive): the runs are independent, and a run's results
   * do not depend on its thread count, so this changes only the time */
#pragma omp parallel for schedule(dynamic, 1) num_threads(width)
  for (size_t k = 0; k < m; k++) {
    int failed;
#pragma omp critical(vsph_jobs_local_progress)
    {
      failed = st;
      if (!failed) {
        if (t1) t1[k] = omp_get_wtime();
        if (eta) eta[k].state = VSPH_JOBS_ETA_RUNNING;
        fprintf(stderr, "  started %s (%.0f s elapsed)\n", order[k]->label,
                omp_get_wtime() - t0);
      }
    }
    if (failed) continue;
    omp_set_num_threads(1); /* this thread's nested regions: itself alone */
    const double t_start = omp_get_wtime();
    const int s = vsph_jobs_execute(J, order[k]);
#pragma omp critical(vsph_jobs_local_progress)
    {
      if (s && !st) st = s;
      done++;
      const double now = omp_get_wtime();
      if (eta) { /* a failed run measures nothing */
        eta[k].state = VSPH_JOBS_ETA_DONE;
        eta[k].wall = s ? 0.0 : now - t_start;
        eta[k].cost = s ? 0.0 : vsph_jobs_local_cost_taken(order[k]);
      }
      char left[64] = "";
      if (t1)
        vsph_jobs_local_eta_text(eta, t1, m, (size_t)width, now, J->after_s,
                                 left, sizeof left);
      /* one counter: the runs ended so far, of all */
      if (s == VSPH_EINTR)
        fprintf(stderr,
                "  [%zu/%zu] %s: stopped at a checkpoint (the next report "
                "resumes it)\n",
                done, m, order[k]->label);
      else if (s)
        fprintf(stderr, "  [%zu/%zu] %s: failed\n", done, m, order[k]->label);
      else
        fprintf(stderr, "  [%zu/%zu] %s: done in %.1f s; %.0f s elapsed%s\n",
                done, m, order[k]->label, now - t_start, now - t0, left);
    }
  }
  free(order);
  free(eta);
  free(t1);
  for (size_t k = 0; k < J->n; k++)
    J->job[k].cached = vsph_rundir_key_matches(J->job[k].dir, J->job[k].key);
  return st;
}
