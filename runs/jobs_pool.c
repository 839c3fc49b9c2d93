/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's missing runs as child processes, N at a time (--jobs N),
 * each with its log; a failed run is recorded and the others go on. Part
 * of the jobs module (runs/jobs.c). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../common/status.h"
#include "../io/files.h"
#include "../io/json.h"
#include "jobs.h"
#include "jobs_internal.h"
#include "rundir.h"

extern char **environ; /* POSIX: the application declares it */

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

/* A pool's runs: the missing ones in @p order (@p m of them), each by its
 * index with its process id (0: not running), exit status, start time
 * (@p t1, from @p t0) and progress (@p eta); the next to start and the
 * counts running, ended and failed; stopping once a stop was passed on,
 * err: a run that could not be started. */
struct pool {
  struct vsph_jobs *J;
  const char *exe;
  size_t njobs, threads;
  struct vsph_jobs_job **order;
  size_t m;
  pid_t *pid;
  int *status;
  double *t1, t0;
  struct vsph_jobs_eta *eta;
  size_t next, running, done, nfailed;
  int stopping, err;
};

/* The next runs started while fewer than njobs run (none once stopping);
 * one that cannot start sets err and starts no more. */
static void pool_start(struct pool *P) {
  while (!P->stopping && P->next < P->m && P->running < P->njobs) {
    const size_t k = P->next;
    if ((P->pid[k] = spawn(P->J, P->order[k], P->exe, P->threads)) < 0) {
      P->err = VSPH_EIO; /* stop the others, as on a signal */
      P->pid[k] = 0;
      return;
    }
    P->t1[k] = omp_get_wtime();
    P->eta[k].state = VSPH_JOBS_ETA_RUNNING;
    fprintf(stderr, "  started %s, pid %ld (%.0f s elapsed)\n",
            P->order[k]->label, (long)P->pid[k], P->t1[k] - P->t0);
    P->running++;
    P->next++;
  }
}

/* At a failed start or a stop request, the stop passed on (once) to each
 * running run, which stops at a checkpoint. */
static void pool_pass_stop(struct pool *P) {
  if (P->stopping || !(P->err || (P->J->stop && *P->J->stop))) return;
  P->stopping = 1;
  fprintf(stderr,
          "vsph report: stopping; each running run stops at a "
          "checkpoint (uncached: the next report resumes it)\n");
  for (size_t k = 0; k < P->next; k++)
    if (P->pid[k] > 0) kill(P->pid[k], SIGTERM);
}

/* Run @p k ended with wait status @p ws: its status, whether it is cached
 * and its progress recorded, and a line said; a run that failed (not
 * stopped) is marked and counted. */
static void pool_ended(struct pool *P, size_t k, int ws) {
  struct vsph_jobs_job *j = P->order[k];
  P->pid[k] = 0;
  P->running--;
  P->done++;
  P->status[k] = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
  j->cached = P->status[k] == 0 && vsph_rundir_key_matches(j->dir, j->key);
  const double now = omp_get_wtime(), el = now - P->t0;
  P->eta[k].state = VSPH_JOBS_ETA_DONE; /* a failed run measures nothing */
  P->eta[k].wall = j->cached ? now - P->t1[k] : 0.0;
  P->eta[k].cost = j->cached ? vsph_jobs_local_cost_taken(j) : 0.0;
  if (j->cached) {
    char v[96], left[64];
    verdict(j, v, sizeof v);
    vsph_jobs_local_eta_text(P->eta, P->t1, P->m, P->njobs, now, P->J->after_s,
                             left, sizeof left);
    fprintf(stderr, "  [%zu/%zu] %s: %s, %.1f s; %.0f s elapsed%s\n", P->done,
            P->m, j->label, v, now - P->t1[k], el, left);
  } else if (!P->stopping) {
    char logf[700];
    log_path(P->J, j, logf, sizeof logf);
    j->failed = 1;
    P->nfailed++;
    fprintf(stderr,
            "  [%zu/%zu] %s: FAILED (exit status %d; see %s); the others "
            "go on\n",
            P->done, P->m, j->label, P->status[k], logf);
  }
}

int vsph_jobs_pool_run(struct vsph_jobs *J, const char *exe, size_t njobs,
                       size_t threads) {
  struct pool P = {.J = J, .exe = exe, .njobs = njobs, .threads = threads};
  const size_t m = P.m = vsph_jobs_local_missing(J, &P.order, njobs);
  if (m == (size_t)-1) VSPH_FAIL(VSPH_ENOMEM, "cannot order the runs");
  char logs[600];
  snprintf(logs, sizeof logs, "%s/runs/logs", J->dir);
  int st = vsph_files_mkdir(logs);
  P.pid = calloc(m ? m : 1, sizeof *P.pid);
  P.status = calloc(m ? m : 1, sizeof *P.status);
  P.t1 = calloc(m ? m : 1, sizeof *P.t1);
  P.eta = vsph_jobs_local_eta_start(P.order, m);
  if (!st && (!P.pid || !P.status || !P.t1 || !P.eta)) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot track %zu runs", m);
  }
  char na[96];
  vsph_jobs_local_archived_note(J, na, sizeof na);
  if (m && !st)
    fprintf(stderr,
            "vsph report: %zu of the %zu runs are not in the cache%s; "
            "running them as %zu processes of %zu threads (logs in %s)\n",
            m, J->n, na, njobs, threads, logs);
  P.t0 = omp_get_wtime();
  P.stopping = st != VSPH_OK;
  while (P.running > 0 || (P.next < m && !P.stopping)) {
    pool_start(&P);
    pool_pass_stop(&P);
    int ws;
    const pid_t w = waitpid(-1, &ws, WNOHANG);
    if (w == 0 || (w < 0 && errno == EINTR)) {
      const struct timespec ts = {0, 100000000}; /* 0.1 s */
      nanosleep(&ts, NULL);
      continue;
    }
    if (w < 0) break; /* no child left */
    size_t k = 0;
    while (k < P.next && P.pid[k] != w) k++;
    if (k == P.next) continue; /* not one of ours */
    pool_ended(&P, k, ws);
  }
  if (!st) st = record_failed(J, P.order, P.next, P.status);
  free(P.order);
  free(P.pid);
  free(P.status);
  free(P.t1);
  free(P.eta);
  if (st) return st;
  if (P.err) return P.err;
  if (P.stopping) return VSPH_EINTR;
  if (P.nfailed)
    VSPH_FAIL(VSPH_EFAIL,
              "%zu of %zu runs failed (listed in %s/runs/failed.txt with their "
              "logs); the report is not assembled: mend them and rerun, only "
              "they run again",
              P.nfailed, m, J->dir);
  return VSPH_OK;
}
