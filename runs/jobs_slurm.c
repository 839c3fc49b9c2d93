/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's missing runs as one Slurm job array, with the assembly as
 * a job after it (vsph report submit). Part of the jobs module
 * (runs/jobs.c). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../io/files.h"
#include "../io/json.h"
#include "jobs.h"
#include "jobs_internal.h"
#include "shell.h"

/* *@p out: a new string of the printf-formatted text (caller frees).
 * 0, or 1 when it cannot be made. */
static int asprintf_like(char **out, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  const int n = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  *out = n >= 0 ? malloc((size_t)n + 1) : NULL;
  if (!*out) return 1;
  va_start(ap, fmt);
  vsnprintf(*out, (size_t)n + 1, fmt, ap);
  va_end(ap);
  return 0;
}

/* A Slurm time limit from an estimate in seconds: D-HH:MM:SS. */
static void slurm_time(double s, char *buf, size_t len) {
  const long t = (long)ceil(s);
  snprintf(buf, len, "%ld-%02ld:%02ld:%02ld", t / 86400, t / 3600 % 24,
           t / 60 % 60, t % 60);
}

/* The seconds sbatch has to answer before it is stopped (a controller
 * that hangs must not hang the report): VSPH_SBATCH_TIMEOUT, 1-3600, or
 * 120. */
static long sbatch_timeout(void) {
  const char *e = getenv("VSPH_SBATCH_TIMEOUT");
  char *end;
  const long t = e ? strtol(e, &end, 10) : 0;
  return e && *e && !*end && t >= 1 && t <= 3600 ? t : 120;
}

/* The job id that `sbatch --parsable` printed ("ID" or "ID;cluster"),
 * sbatch stopped (coreutils' timeout) if it does not answer in time. */
static int submit(const char *cmd, char *id, size_t len) {
  const long limit = sbatch_timeout();
  char *full = NULL;
  if (asprintf_like(&full, "timeout %ld %s", limit, cmd))
    VSPH_FAIL(VSPH_ENOMEM, "cannot build the sbatch command");
  FILE *p = popen(full, "r");
  free(full);
  if (!p) VSPH_FAIL(VSPH_EIO, "cannot run '%s': %s", cmd, strerror(errno));
  char line[256] = "";
  const int got = fgets(line, sizeof line, p) != NULL;
  const int rc = pclose(p);
  if (WIFEXITED(rc) && WEXITSTATUS(rc) == 124)
    VSPH_FAIL(VSPH_EIO,
              "sbatch did not answer within %ld s (is slurmctld up? "
              "VSPH_SBATCH_TIMEOUT sets the wait); nothing was submitted "
              "by this call",
              limit);
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
              "the folder '%s' holds a space, a quote or '%%', "
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
          "(written by vsph report submit)\n"
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
          "vsph report submit)\n"
          "#SBATCH --job-name=vsph-report\n"
          "#SBATCH --ntasks=1\n"
          "#SBATCH --cpus-per-task=%zu\n"
          "#SBATCH --mem=2048M\n"
          "#SBATCH --time=1:00:00\n"
          "#SBATCH --output=%s/assemble-%%j.log\n",
          VSPH_VERSION, s->threads, logs);
  if (s->partition) fprintf(f, "#SBATCH --partition=%s\n", s->partition);
  fprintf(f, "OMP_NUM_THREADS=%zu exec %s report assemble --out %s%s%s%s\n",
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

int vsph_jobs_slurm_submit(struct vsph_jobs *J,
                           const struct vsph_jobs_slurm *s) {
  struct vsph_jobs_job **order;
  const size_t m = vsph_jobs_local_missing(J, &order, 1);
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
    cost = fmax(cost, vsph_jobs_cost_of(order[k]));
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
