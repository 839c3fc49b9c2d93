/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The runs read back: their tables, files and folders. Part of the jobs
 * module (runs/jobs.c). */
#define _XOPEN_SOURCE 700 /* realpath */
#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/json.h"
#include "folder.h"
#include "jobs.h"
#include "jobs_internal.h"

void vsph_jobs_store_run_free(struct vsph_jobs_run *r) {
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

int vsph_jobs_store_load(const char *dir, struct vsph_jobs_run *out) {
  memset(out, 0, sizeof *out);
  if (strlen(dir) >= sizeof out->dir)
    VSPH_FAIL(VSPH_EINVAL, "%.60s...: the folder's name is too long", dir);
  snprintf(out->dir, sizeof out->dir, "%s", dir);
  int st = load_run_json(out);
  if (!st) st = load_energy(out);
  if (st) vsph_jobs_store_run_free(out); /* (a table read, its columns not) */
  return st;
}

int vsph_jobs_store_get(const struct vsph_jobs *J,
                        const struct vsph_jobs_spec *rs,
                        struct vsph_jobs_run *out) {
  memset(out, 0, sizeof *out);
  struct vsph_jobs_job j;
  int st = vsph_jobs_run(J, rs, &j);
  snprintf(out->dir, sizeof out->dir, "%s", j.dir);
  if (!st) st = vsph_jobs_ready(J, &j);
  if (!st) st = vsph_jobs_store_load(vsph_jobs_where(J, j.dir), out);
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
int vsph_jobs_store_file(const struct vsph_jobs *J, const char *dir,
                         const char *name, char *path, size_t len) {
  const struct vsph_jobs_job *j = J->planned ? vsph_jobs_find(J, dir) : NULL;
  if (J->planned && !j)
    VSPH_FAIL(VSPH_EINVAL, "run %s is not in the plan (a bug)", dir);
  const char *key = NULL;
  if (j) dir = vsph_jobs_where_of(j, &key);
  char why[700] = "";
  if (j && vsph_folder_verify(dir, NULL, key, NULL, why, sizeof why) != 1)
    VSPH_FAIL(VSPH_EIO, "run %s is not sealed%s%s", dir, why[0] ? ": " : "",
              why);
  if (!seal_lists(dir, name))
    VSPH_FAIL(VSPH_EIO, "run %s holds no %s under its seal", dir, name);
  snprintf(path, len, "%s/%s", dir, name);
  return VSPH_OK;
}

struct vsph_csv *vsph_jobs_store_table(const struct vsph_jobs *J,
                                       const char *dir, const char *name) {
  char path[700];
  if (vsph_jobs_store_file(J, dir, name, path, sizeof path)) return NULL;
  struct vsph_csv *c = vsph_csv_read(path);
  if (!c)
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot read %s", path);
  return c;
}

int vsph_jobs_store_holds(const struct vsph_jobs *J, const char *dir,
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

void vsph_jobs_store_data_path(const struct vsph_jobs *J, const char *dir,
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

int vsph_jobs_store_last_snapshot(const struct vsph_jobs *J, const char *dir) {
  char path[700];
  if (vsph_jobs_store_file(J, dir, "snapshots.pvd", path, sizeof path))
    return -1;
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

double vsph_jobs_store_peak_rss(const char *scene, const char *visc, size_t res,
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
          "--t-end", t, "--out", out, (char *)NULL);
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
