/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph report: the main job (reports/report.c), and its verbs plan,
 * submit, assemble and archive. */
#define _XOPEN_SOURCE 700 /* realpath */
#include "cmd_report.h"

#include <errno.h>
#include <limits.h>
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../common/params.h"
#include "../common/status.h"
#include "../reports/report.h"
#include "../runs/archive.h"
#include "args.h"

static const char *const CMD = "report";

/* 1 if @p s is non-empty and every character is in @p ok. */
static int only_of(const char *s, const char *ok) {
  return *s && strspn(s, ok) == strlen(s);
}

/* 1 if an executable @p name is on PATH. */
static int on_path(const char *name) {
  const char *path = getenv("PATH");
  char dir[4096];
  for (const char *p = path ? path : ""; *p;) {
    const size_t n = strcspn(p, ":");
    if (n > 0 && n < sizeof dir - 64) {
      snprintf(dir, sizeof dir, "%.*s/%s", (int)n, p, name);
      if (access(dir, X_OK) == 0) return 1;
    }
    p += n + (p[n] == ':');
  }
  return 0;
}

/* The archive's entries.md, judged against the current FULL plan (as
 * @p jobs, planned for the report folder), the tree's reports/baseline.csv
 * (read from the current folder, where make archive runs) and the history
 * scripts/source-commits left in $VSPH_ARCHIVE_HISTORY. */
static int summarise(const struct vsph_jobs *jobs, const char *archive,
                     const char *commit) {
  const char *history = getenv("VSPH_ARCHIVE_HISTORY");
  struct stat sb;
  if (stat("reports/baseline.csv", &sb) != 0)
    fprintf(stderr,
            "vsph report: no reports/baseline.csv here: entries.md leaves the "
            "archive's entries unjudged (run it in the source tree's top "
            "folder, as make archive does)\n");
  const struct vsph_archive_judge base = {
      .history = history && *history ? history : NULL,
      .baseline = stat("reports/baseline.csv", &sb) == 0
                      ? "reports/baseline.csv"
                      : NULL,
      .commit = commit};
  struct vsph_archive_judge jd = {0};
  int st = vsph_report_plan_judge(jobs, &base, &jd);
  if (!st) st = vsph_archive_summarise(archive, &jd);
  vsph_report_plan_judge_free(&jd);
  return st;
}

/* The sealed runs of report folder @p dir stored in @p archive, with the
 * frames the FULL report's pictures and profiles read (the
 * VSPH_JOBS_FRAME_* runs of its plan, @p jobs). */
static int store(const char *dir, const struct vsph_jobs *jobs,
                 const char *archive, const char *commit,
                 struct vsph_archive_counts *n) {
  int st = VSPH_OK;
  const char **name = calloc(jobs->n ? jobs->n : 1, sizeof *name);
  unsigned *want = calloc(jobs->n ? jobs->n : 1, sizeof *want);
  struct vsph_archive_frames fr = {
      .name = name, .want = want, .bits = VSPH_ARCHIVE_FRAME_BITS};
  if (!name || !want) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot list the frames");
  }
  for (size_t k = 0; !st && k < jobs->n; k++)
    if (jobs->job[k].frames) {
      const char *slash = strrchr(jobs->job[k].dir, '/');
      name[fr.n] = slash ? slash + 1 : jobs->job[k].dir;
      want[fr.n++] = jobs->job[k].frames;
    }
  if (!st) st = vsph_archive_store_frames(dir, archive, commit, &fr, stderr, n);
  free(name);
  free(want);
  return st;
}

/* 1 if folder @p out (made or not) lies in folder @p dir or is it: the
 * canonical paths compared, @p out's deepest existing folder standing
 * for it. */
static int inside(const char *out, const char *dir) {
  char d[PATH_MAX], o[PATH_MAX], probe[PATH_MAX];
  if (!realpath(dir, d)) return 0;
  snprintf(probe, sizeof probe, "%s", out);
  while (!realpath(probe, o)) { /* up to the deepest existing folder */
    char *slash = strrchr(probe, '/');
    if (!slash || slash == probe) {
      if (!realpath(slash == probe ? "/" : ".", o)) return 0;
      break;
    }
    *slash = '\0';
  }
  const size_t n = strlen(d);
  return !strncmp(o, d, n) && (o[n] == '/' || o[n] == '\0');
}

/* A run archive given to --skip-archived, --from-archive or --beside,
 * checked before anything is written: a folder vsph wrote as an archive,
 * and not where the report writes. 0, or the exit status of a refusal
 * (one line, headed by @p cmd). */
static int archive_input(const char *cmd, const char *opt, const char *adir,
                         const char *out) {
  struct stat as;
  if (!*adir || strlen(adir) > 200 ||
      !only_of(adir,
               "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
               "0123456789._-/"))
    return vsph_args_fail(cmd,
                          "%s: '%.200s' is not a folder name of 1-200 "
                          "letters, digits, '.', '_', '-' or '/'",
                          opt, adir);
  if (stat(adir, &as) != 0 || !S_ISDIR(as.st_mode))
    return vsph_args_fail(cmd,
                          "%s: %.200s is not a folder (make archive makes "
                          "reports/full)",
                          opt, adir);
  if (inside(out, adir))
    return vsph_args_fail(cmd, "%s: --out %.200s lies inside the archive %s",
                          opt, out, adir);
  const int st = vsph_archive_check(adir);
  return st ? vsph_args_status_about(cmd, opt, st) : 0;
}

/* What a judge of the archive reads ($VSPH_ARCHIVE_HISTORY and
 * reports/baseline.csv), checked before anything is written: 0, or the
 * exit status of a refusal (one line said). */
static int judge_inputs(const char *cmd) {
  const char *history = getenv("VSPH_ARCHIVE_HISTORY");
  struct stat hs;
  char tsv[600];
  snprintf(tsv, sizeof tsv, "%s/commits.tsv", history ? history : "");
  if (history && *history &&
      (strlen(history) > 400 || stat(history, &hs) != 0 ||
       !S_ISDIR(hs.st_mode) || stat(tsv, &hs) != 0 || !S_ISREG(hs.st_mode) ||
       hs.st_size > VSPH_ARCHIVE_READ_MAX))
    return vsph_args_fail(cmd,
                          "VSPH_ARCHIVE_HISTORY '%.400s' is not a folder "
                          "scripts/source-commits made (a commits.tsv of at "
                          "most 16 MiB in it)",
                          history);
  if (stat("reports/baseline.csv", &hs) == 0 &&
      (!S_ISREG(hs.st_mode) || hs.st_size > VSPH_ARCHIVE_READ_MAX))
    return vsph_args_fail(cmd,
                          "reports/baseline.csv is not a regular file of "
                          "at most 16 MiB");
  return 0;
}

/* What the command line asked for. */
struct opts {
  const char *cmd; /* "report" or "report VERB": its messages' head */
  const char *dir, *only, *partition, *limit, *budget, *archive;
  const char *skip, *beside, *from, *fv;
  int full;
  size_t jobs, threads;
  int pool, own_threads; /* --jobs, --threads given */
  double budget_s;       /* --budget in seconds (0: none) */
  const char *fv_dir;    /* the finite-volume references, or NULL */
};

/* The most options a verb takes. */
enum { OPTS_MAX = 16 };

/* The options every verb but archive takes, into @p t; their number. */
static size_t shared_options(struct opts *o, struct vsph_args_spec *t) {
  t[0] = (struct vsph_args_spec){.name = "--out",
                                 .kind = VSPH_ARGS_STRING,
                                 .dst = &o->dir,
                                 .value = "DIR",
                                 .help = "output folder (default reports/out)"};
  t[1] = (struct vsph_args_spec){
      .name = "--only",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->only,
      .value = "P[,P]",
      .help =
          "only these parts (Parts, above); report.md gathers every part "
          "present; PART:SCENE (scenes, convergence, speed) limits those "
          "parts to one scene, e.g. scenes:vortex-patch"};
  t[2] = (struct vsph_args_spec){
      .name = "--full",
      .kind = VSPH_ARGS_FLAG,
      .dst = &o->full,
      .help = "the paper's resolutions and end times (hours)"};
  t[3] = (struct vsph_args_spec){
      .name = "--fv",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->fv,
      .value = "FDIR",
      .help =
          "the committed finite-volume references the stretching square "
          "and the cavity are judged against (OpenFOAM runs that make "
          "reference made; reference/README.md): default reference/data "
          "when it is a folder here; none: without them (their rows say "
          "not tested)"};
  return 4;
}

/* --beside, which vsph report and vsph report assemble take. */
static struct vsph_args_spec beside_option(struct opts *o) {
  return (struct vsph_args_spec){
      .name = "--beside",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->beside,
      .value = "ADIR",
      .help =
          "the summary shows, beside the quick ladder's finest run of "
          "each scene and formulation, the run at the paper's resolution "
          "from the run archive ADIR (reports/full; make report gives "
          "it), with whether it stands (judged as vsph report archive's "
          "entries.md judges it); not with --full"};
}

/* vsph report's own options (the report made here) into @p t. */
static size_t make_options(struct opts *o, struct vsph_args_spec *t) {
  size_t n = shared_options(o, t);
  t[n++] = (struct vsph_args_spec){
      .name = "--jobs",
      .kind = VSPH_ARGS_SIZE,
      .dst = &o->jobs,
      .value = "N",
      .help =
          "run the missing runs as N child processes at a time (1-256), "
          "each `vsph run` or `vsph contact` with its log in "
          "DIR/runs/logs; a run that fails is listed in "
          "DIR/runs/failed.txt and the others go on; then assemble"};
  t[n++] = (struct vsph_args_spec){
      .name = "--threads",
      .kind = VSPH_ARGS_SIZE,
      .dst = &o->threads,
      .value = "T",
      .help =
          "with --jobs: threads of each run (default: cores / N, at "
          "least 1)"};
  t[n++] = (struct vsph_args_spec){
      .name = "--budget",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->budget,
      .value = "TIME",
      .help =
          "run only the missing runs that fit TIME of wall time (90s, "
          "150m, 2.5h; a plain number is seconds), the costliest first, "
          "at the rates the cached runs measured, niced, two at a time "
          "(or as --jobs says); when TIME is spent the runs stop at a "
          "checkpoint and the next --budget goes on from there; exit 0, "
          "and nothing is assembled (a FULL report fills over several "
          "sittings this way)"};
  t[n++] = (struct vsph_args_spec){
      .name = "--skip-archived",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->skip,
      .value = "ADIR",
      .help =
          "with --budget: leave out the runs that stand in the run "
          "archive ADIR (reports/full for the FULL report; judged as "
          "vsph report archive's entries.md judges them, from "
          "$VSPH_ARCHIVE_HISTORY and reports/baseline.csv), so a sitting "
          "goes on from the archive whatever build made it (make "
          "full-sitting)"};
  t[n++] = (struct vsph_args_spec){
      .name = "--from-archive",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->from,
      .value = "ADIR",
      .help =
          "each run DIR lacks that stands in the run archive ADIR "
          "(judged as for --skip-archived) is read from its entry there "
          "instead of run; the runs whose snapshots the report draws "
          "and, with its scenes part, its baseline rows' runs are still "
          "made here (make report gives it reports/full); not with "
          "--full (vsph report assemble --full reads the FULL report "
          "from the archive) or --budget"};
  t[n++] = beside_option(o);
  return n;
}

/* vsph report plan's options into @p t. */
static size_t plan_options(struct opts *o, struct vsph_args_spec *t) {
  return shared_options(o, t);
}

/* vsph report submit's options into @p t. */
static size_t submit_options(struct opts *o, struct vsph_args_spec *t) {
  size_t n = shared_options(o, t);
  t[n++] = (struct vsph_args_spec){
      .name = "--threads",
      .kind = VSPH_ARGS_SIZE,
      .dst = &o->threads,
      .value = "C",
      .help = "CPUs (and threads) of each array task (default 1)"};
  t[n++] = (struct vsph_args_spec){.name = "--partition",
                                   .kind = VSPH_ARGS_STRING,
                                   .dst = &o->partition,
                                   .value = "P",
                                   .help = "the Slurm partition"};
  t[n++] = (struct vsph_args_spec){
      .name = "--time",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->limit,
      .value = "T",
      .help =
          "each task's time limit in Slurm's form (MM, HH:MM:SS, "
          "D-HH:MM:SS; default: estimated from the largest run)"};
  return n;
}

/* vsph report assemble's options into @p t. */
static size_t assemble_options(struct opts *o, struct vsph_args_spec *t) {
  size_t n = shared_options(o, t);
  t[n++] = (struct vsph_args_spec){
      .name = "--from-archive",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->from,
      .value = "ADIR",
      .help =
          "each run DIR lacks that stands in the run archive ADIR "
          "(judged as vsph report archive's entries.md judges them, from "
          "$VSPH_ARCHIVE_HISTORY and reports/baseline.csv) is read from "
          "its entry there. With --full, ADIR/summary.md then gets the "
          "report's claims and convergence tables (make full-report), "
          "and a part that draws snapshots leaves out the pictures of a "
          "run read from the archive, which keeps none, and says so"};
  t[n++] = beside_option(o);
  return n;
}

/* vsph report archive's options into @p t. */
static size_t archive_options(struct opts *o, struct vsph_args_spec *t) {
  t[0] = (struct vsph_args_spec){
      .name = "--out",
      .kind = VSPH_ARGS_STRING,
      .dst = &o->dir,
      .value = "DIR",
      .help =
          "the report folder whose runs (DIR/runs) are stored (default "
          "reports/out)"};
  return 1;
}

/* Seconds of --budget into o->budget_s: 0, or a refusal's exit status. */
static int check_budget(struct opts *o) {
  if (o->budget) {
    char *end = NULL;
    errno = 0;
    const double v = strtod(o->budget, &end);
    const double unit = !strcmp(end, "") || !strcmp(end, "s") ? 1.0
                        : !strcmp(end, "m")                   ? 60.0
                        : !strcmp(end, "h")                   ? 3600.0
                                                              : -1.0;
    o->budget_s = v * unit;
    /* digits as people write them: no sign, blank, hex, inf or nan */
    const size_t plain = strspn(o->budget, "0123456789.eE+-");
    if (end == o->budget || errno || unit < 0.0 || !(o->budget_s >= 1.0) ||
        !strchr("0123456789.", o->budget[0]) || o->budget + plain < end ||
        o->budget_s > 30 * 86400.0)
      return vsph_args_fail(o->cmd,
                            "--budget '%.32s' is not a time from 1 s to 30 "
                            "days (e.g. 90s, 150m, 2.5h)",
                            o->budget);
  }
  return 0;
}

/* --threads within bounds, where given: 0, or a refusal's exit status. */
static int check_threads(const struct opts *o) {
  if (o->own_threads && (o->threads < 1 || o->threads > 1024))
    return vsph_args_fail(o->cmd, "--threads must lie in 1-1024, got %zu",
                          o->threads);
  return 0;
}

/* The run archives read (--skip-archived, --from-archive, --beside, where
 * given), each checked with what its judge reads: 0, or a refusal's exit
 * status. */
static int check_archives(const struct opts *o) {
  const char *opt[] = {"--skip-archived", "--from-archive", "--beside"};
  const char *adir[] = {o->skip, o->from, o->beside};
  for (size_t k = 0; k < 3; k++)
    if (adir[k]) {
      int bad = archive_input(o->cmd, opt[k], adir[k], o->dir);
      if (!bad) bad = judge_inputs(o->cmd);
      if (bad) return bad;
    }
  return 0;
}

/* The finite-volume references (o->fv_dir): a folder, or none. */
static int check_fv(struct opts *o) {
  struct stat fs;
  if (o->fv && strcmp(o->fv, "none")) {
    if (!*o->fv || strlen(o->fv) > 400 || stat(o->fv, &fs) != 0 ||
        !S_ISDIR(fs.st_mode))
      return vsph_args_fail(o->cmd, "--fv: '%.400s' is not a folder", o->fv);
    o->fv_dir = o->fv;
  } else if (!o->fv && stat("reference/data", &fs) == 0 && S_ISDIR(fs.st_mode))
    o->fv_dir = "reference/data";
  return 0;
}

/* --only PART[,PART...] (PART:SCENE) into rp's parts and scenes. */
static int only_parts(const char *cmd, const char *only,
                      struct vsph_report_props *rp) {
  if (only) {
    char buf[256];
    if (strlen(only) >= sizeof buf)
      return vsph_args_fail(cmd, "--only: '%.40s...' is too long", only);
    snprintf(buf, sizeof buf, "%s", only);
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
      char *colon = strchr(tok, ':');
      if (colon) { /* PART:SCENE limits the scene-wise parts */
        *colon = '\0';
        size_t s = 0;
        while (vsph_report_scene_name(s) &&
               strcmp(vsph_report_scene_name(s), colon + 1))
          s++;
        if (!vsph_report_scene_name(s))
          return vsph_args_fail(cmd,
                                "unknown scene '%s' in --only (vortex-patch, "
                                "stretching-square, standing-wave)",
                                colon + 1);
        if (strcmp(tok, "scenes") && strcmp(tok, "convergence") &&
            strcmp(tok, "speed"))
          return vsph_args_fail(cmd,
                                "--only %s:%s: only scenes, convergence and "
                                "speed take a scene",
                                tok, colon + 1);
        rp->scenes |= 1u << s;
      }
      const int p = vsph_report_part_find(tok);
      if (p < 0)
        return vsph_args_fail(cmd, "unknown part '%s' (see --help)", tok);
      rp->parts |= 1ul << p;
    }
    if (!rp->parts)
      return vsph_args_fail(cmd, "--only names no part (see --help)");
  }
  return 0;
}

/* The report in @p mode, as the options say, once they are checked; its
 * exit status. */
static int run_report(const struct opts *o, struct vsph_report_props *rp,
                      enum vsph_report_mode mode) {
  /* vsph itself, for the child processes and the Slurm scripts */
  char exe[PATH_MAX];
  const ssize_t ne = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (ne <= 0) {
    fprintf(stderr, "vsph report: cannot find vsph itself (/proc/self/exe)\n");
    return vsph_args_status(o->cmd, VSPH_EIO);
  }
  exe[ne] = '\0';
  /* the install's x86-64-v3 copy, started by bin/vsph (cli/main.c): the
   * children and the Slurm scripts name bin/vsph, which chooses the copy
   * on each machine (a compute node may lack x86-64-v3) */
  static const char v3[] = "/libexec/vsph/x86-64-v3/vsph";
  const char *disp = getenv("VSPH_EXE");
  if ((size_t)ne > strlen(v3) && !strcmp(exe + ne - strlen(v3), v3) && disp &&
      disp[0] == '/' && strlen(disp) < sizeof exe && access(disp, X_OK) == 0)
    snprintf(exe, sizeof exe, "%s", disp);
  rp->exe = exe;
  rp->mode = mode;
  rp->plan_out = stdout;
  rp->jobs = mode == VSPH_REPORT_POOL ? o->jobs : 0;
  const size_t cores = (size_t)omp_get_num_procs();
  rp->threads = o->own_threads ? o->threads
                : mode == VSPH_REPORT_POOL
                    ? (cores / o->jobs > 0 ? cores / o->jobs : 1)
                    : 1;
  rp->partition = o->partition;
  rp->time = o->limit;
  rp->only = o->only;
  rp->budget_s = o->budget_s;
  struct stat bs;
  const char *history = getenv("VSPH_ARCHIVE_HISTORY");
  const struct vsph_archive_judge judge = {
      .history = history && *history ? history : NULL,
      .baseline = stat("reports/baseline.csv", &bs) == 0
                      ? "reports/baseline.csv"
                      : NULL,
      .commit = NULL};
  rp->skip_archive = o->skip;
  rp->from_archive = o->from;
  rp->beside = o->beside;
  rp->judge = &judge;
  rp->fv = o->fv_dir;
  /* SIGINT/SIGTERM: the runs in progress stop at a checkpoint, uncached */
  const volatile sig_atomic_t *stop = rp->stop = vsph_args_catch_stop();
  /* but for the runs (which stop after a checkpoint), a signal ends the
   * report at once: its parts and files are written whole or not at all,
   * and its seal is written last */
  rp->writing = vsph_args_quick_stop();
  if (o->budget_s > 0.0) { /* beside the user's own work: lowest priority */
    if (setpriority(PRIO_PROCESS, 0, 19) != 0) /* and its children's */
      fprintf(stderr, "vsph report: cannot lower the priority: %s\n",
              strerror(errno));
    if (vsph_args_stop_after(o->budget_s)) {
      fprintf(stderr, "vsph report: cannot set the budget's clock: %s\n",
              strerror(errno));
      return vsph_args_status(o->cmd, VSPH_EIO);
    }
  }
  const int st = vsph_report_write(rp);
  if (st == VSPH_EINTR && *stop == SIGALRM) {
    fprintf(stderr,
            "vsph report: the budget of %.0f s is spent; the runs in "
            "progress stopped at a checkpoint, and the next --budget goes on "
            "from there\n",
            o->budget_s);
    return vsph_args_finish(o->cmd, 0);
  }
  if (st == VSPH_EINTR) {
    fprintf(stderr,
            "vsph report: interrupted by signal %d; finished runs "
            "are cached, rerun to go on\n",
            (int)*stop);
    return 128 + (int)*stop;
  }
  return st ? vsph_args_status(o->cmd, st) : vsph_args_finish(o->cmd, 0);
}

/* What every verb but archive does after its own checks: --fv, --out,
 * --only, then the report in @p mode. */
static int report(struct opts *o, enum vsph_report_mode mode) {
  int rc = check_fv(o);
  if (rc) return rc;
  if (strlen(o->dir) > 400)
    return vsph_args_fail(o->cmd, "--out: the folder's name is too long");
  struct vsph_report_props rp = {
      .dir = o->dir, .full = o->full, .parts = 0, .stop = NULL};
  if ((rc = only_parts(o->cmd, o->only, &rp))) return rc;
  return run_report(o, &rp, mode);
}

/* vsph report: the missing runs made here (two at a time, --jobs N at a
 * time, or those that fit --budget), then the report assembled. */
static int make_main(struct opts *o) {
  if (o->pool && (o->jobs < 1 || o->jobs > 256))
    return vsph_args_fail(o->cmd, "--jobs must lie in 1-256, got %zu", o->jobs);
  int rc = check_threads(o);
  if (rc) return rc;
  if (o->own_threads && !o->pool)
    return vsph_args_fail(o->cmd,
                          "--threads needs --jobs (a Slurm task's CPUs: "
                          "vsph report submit --threads)");
  if ((rc = check_budget(o))) return rc;
  if (o->skip && !o->budget)
    return vsph_args_fail(o->cmd, "--skip-archived needs --budget");
  if (o->from && (o->full || o->budget))
    return vsph_args_fail(o->cmd,
                          "--from-archive reads runs from a run archive: "
                          "not with --budget, nor with --full (the FULL "
                          "report from the archive is vsph report assemble "
                          "--full --from-archive ADIR)");
  if (o->beside && (o->full || o->budget))
    return vsph_args_fail(o->cmd,
                          "--beside sets the FULL archive beside a quick "
                          "report: not with --full or --budget");
  if ((rc = check_archives(o))) return rc;
  return report(o, o->pool ? VSPH_REPORT_POOL : VSPH_REPORT_LOCAL);
}

/* vsph report plan: the runs, one per line; nothing written. */
static int plan_main(struct opts *o) { return report(o, VSPH_REPORT_PLAN); }

/* vsph report submit: the missing runs as a Slurm job array, the assembly
 * as a job after it. */
static int submit_main(struct opts *o) {
  int rc = check_threads(o);
  if (rc) return rc;
  if (o->partition &&
      (strlen(o->partition) > 64 ||
       !only_of(o->partition,
                "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstu"
                "vwxyz0123456789_.-,")))
    return vsph_args_fail(o->cmd, "--partition '%.64s' is not a partition name",
                          o->partition);
  if (o->limit &&
      (strlen(o->limit) > 16 || !only_of(o->limit, "0123456789:-") ||
       !strchr("0123456789", o->limit[strlen(o->limit) - 1])))
    return vsph_args_fail(o->cmd,
                          "--time '%.16s' is not a Slurm time limit (MM, "
                          "HH:MM:SS or D-HH:MM:SS)",
                          o->limit);
  if (!on_path("sbatch"))
    return vsph_args_fail(o->cmd,
                          "Slurm's sbatch is needed on PATH, and it is not "
                          "there");
  return report(o, VSPH_REPORT_SLURM);
}

/* vsph report assemble: the report from the cached runs (and the archive's
 * with --from-archive); nothing run. */
static int assemble_main(struct opts *o) {
  if (o->beside && o->full)
    return vsph_args_fail(o->cmd,
                          "--beside sets the FULL archive beside a quick "
                          "report: not with --full");
  const int rc = check_archives(o);
  return rc ? rc : report(o, VSPH_REPORT_ASSEMBLE);
}

/* vsph report archive: the sealed runs of the report folder into the run
 * archive, then its summary; nothing is run. */
static int archive_main(struct opts *o) {
  if (!*o->archive || strlen(o->archive) > 400)
    return vsph_args_fail(o->cmd, "ADIR: a folder name of 1-400 characters");
  /* the archive beside the report, never in it (its runs/ is what is
   * stored) nor around it */
  if (inside(o->archive, o->dir) || inside(o->dir, o->archive))
    return vsph_args_fail(o->cmd,
                          "the archive %.200s and the report folder %.200s "
                          "lie one inside the other: the archive goes "
                          "beside it",
                          o->archive, o->dir);
  const char *commit = getenv("VSPH_COMMIT");
  if (commit && !*commit) commit = NULL; /* none known */
  if (commit &&
      (strlen(commit) > 64 || !only_of(commit,
                                       "0123456789abcdefghijklmnopqrstuvwxyz"
                                       "ABCDEFGHIJKLMNOPQRSTUVWXYZ._-")))
    return vsph_args_fail(o->cmd, "VSPH_COMMIT '%.64s' is not a commit id",
                          commit);
  /* what the summary reads, judged before anything is written */
  const int bad = judge_inputs(o->cmd);
  if (bad) return bad;
  struct vsph_jobs full_plan; /* the FULL plan: the frames and the judge */
  memset(&full_plan, 0, sizeof full_plan);
  struct vsph_archive_counts n;
  int st = vsph_report_plan_jobs(o->dir, 1, &full_plan);
  if (!st) st = store(o->dir, &full_plan, o->archive, commit, &n);
  if (st) {
    vsph_jobs_plan_free(&full_plan);
    return vsph_args_status(o->cmd, st);
  }
  fprintf(stderr,
          "vsph report: archived %zu runs of %s in %s (%zu already there, "
          "%zu left out: unended, damaged, oddly named or older than "
          "their entries, each said "
          "above)\n",
          n.stored, o->dir, o->archive, n.kept, n.skipped);
  /* nothing new: the archive stays as it was, its judgement included
   * (entries.md is judged anew by make archive, with the history) */
  if (n.stored == 0) {
    fprintf(stderr,
            "vsph report: nothing new to store: %s/index.tsv and "
            "entries.md left as they were\n",
            o->archive);
    vsph_jobs_plan_free(&full_plan);
    return vsph_args_finish(o->cmd, 0);
  }
  st = summarise(&full_plan, o->archive, commit);
  vsph_jobs_plan_free(&full_plan);
  if (st) return vsph_args_status(o->cmd, st);
  return vsph_args_finish(o->cmd, 0);
}

/* The verbs: vsph report itself, then the words after it. */
enum verb_id { VERB_MAKE, VERB_PLAN, VERB_SUBMIT, VERB_ASSEMBLE, VERB_ARCHIVE };

/* A verb: its word, its old spelling, its help and options, its body. */
struct verb {
  const char *name;     /* the word after vsph report (NULL: none) */
  const char *cmd;      /* "report VERB": its messages' and usage's head */
  const char *alias;    /* its old spelling, an option of vsph report */
  const char *synopsis; /* what follows "usage: vsph report VERB" */
  const char *what;     /* its line in vsph report --help */
  const char *about;    /* its help's paragraph */
  int adir;             /* 1: it takes one run archive ADIR */
  size_t (*options)(struct opts *o, struct vsph_args_spec *t);
  int (*main)(struct opts *o);
};

static const struct verb VERBS[] = {
    [VERB_MAKE] =
        {.name = NULL,
         .cmd = "report",
         .synopsis = "[--out DIR] [--only PART[,PART...]] [--full] "
                     "[--fv FDIR] [--jobs N [--threads T]] [--budget TIME "
                     "[--skip-archived ADIR]] [--from-archive ADIR] "
                     "[--beside ADIR]",
         .about =
             "Run the suite and write to DIR: report.md, report.html\n"
             "(self-contained: figures embedded, as SVG), the CSV behind "
             "every\ntable and figure, the figures (fig_*.png, .svg and .pdf "
             "beside\ntheir fig_*.gp gnuplot scripts), the solver runs "
             "(runs/),\nbaseline.csv (the key figures of the quick ladder's "
             "coarsest runs)\nand run.json. Default fidelity is\nquick "
             "(minutes on 2 cores: reduced resolutions and end times, "
             "stated\nin the report). Runs are cached by version, source "
             "hash and\nsettings, the analysis parts by version, source hash "
             "and fidelity:\nan unchanged input is never recomputed. Every "
             "part first lists the\nruns it reads (vsph report plan prints "
             "them); the missing ones run\nhere two at a time, or as N "
             "processes (--jobs N), or on Slurm\n(vsph report submit), then "
             "the report is assembled. A stopped\nreport resumes: finished "
             "runs are cached, a half-written one is\nredone.",
         .options = make_options,
         .main = make_main},
    [VERB_PLAN] =
        {.name = "plan",
         .cmd = "report plan",
         .alias = "--plan",
         .synopsis = "[--out DIR] [--only PART[,PART...]] [--full] "
                     "[--fv FDIR]",
         .what = "print the runs the report needs, one per line; writes "
                 "nothing",
         .about = "Print the runs the report needs, one per line, and stop; "
                  "writes nothing.\nTab-separated: cached or missing, "
                  "folder, key fingerprint, particles,\nneighbours, steps, "
                  "memory in MiB, the exact command. The old\nspelling "
                  "vsph report --plan is this verb.",
         .options = plan_options,
         .main = plan_main},
    [VERB_SUBMIT] =
        {.name = "submit",
         .cmd = "report submit",
         .alias = "--slurm",
         .synopsis = "[--out DIR] [--only PART[,PART...]] [--full] "
                     "[--fv FDIR] [--threads C] [--partition P] [--time T]",
         .what = "submit the missing runs to Slurm as a job array, the "
                 "assembly after it",
         .about = "Submit the missing runs as one Slurm job array (sbatch "
                  "--array, one task\nper run, memory and time from the "
                  "largest run's estimate) and the\nassembly (vsph report "
                  "assemble) as a job after it (afterany). DIR\nmust be on a "
                  "file system every node shares. Scripts, logs and job\nids "
                  "in DIR/slurm. The old spelling vsph report --slurm is "
                  "this verb.",
         .options = submit_options,
         .main = submit_main},
    [VERB_ASSEMBLE] =
        {.name = "assemble",
         .cmd = "report assemble",
         .alias = "--assemble",
         .synopsis = "[--out DIR] [--only PART[,PART...]] [--full] "
                     "[--fv FDIR] [--from-archive ADIR] [--beside ADIR]",
         .what = "run nothing: assemble from the cached runs",
         .about = "Run nothing: assemble the report from the cached runs "
                  "(and those of a\nrun archive, --from-archive), naming any "
                  "that is missing (the Slurm\nassembly job). The old "
                  "spelling vsph report --assemble is this verb.",
         .options = assemble_options,
         .main = assemble_main},
    [VERB_ARCHIVE] = {
        .name = "archive",
        .cmd = "report archive",
        .alias = "--archive",
        .synopsis = "[--out DIR] ADIR",
        .what = "run nothing: store DIR's sealed runs in the run archive "
                "ADIR",
        .about = "Run nothing: store the sealed runs of DIR/runs in the run "
                 "archive ADIR\n(reports/full for the FULL report): of "
                 "each, what the parts read\n(energy.csv, run.json, "
                 "profiles), not its snapshots, as a folder sealed\nunder "
                 "the run's own key (version, source hash, settings); runs "
                 "already\nthere are kept, unended ones are named and left "
                 "out; then\nADIR/index.tsv and ADIR/entries.md. The commit "
                 "of entries made by this\nbuild's sources is $VSPH_COMMIT "
                 "(make archive sets it). The old\nspelling vsph report "
                 "--archive ADIR is this verb.",
        .adir = 1,
        .options = archive_options,
        .main = archive_main}};
enum { NVERBS = sizeof VERBS / sizeof VERBS[0] };
_Static_assert(NVERBS == VERB_ARCHIVE + 1, "the verbs' table out of sync");

/* The help's text of verb @p v: its paragraph, then (vsph report itself)
 * the verbs, then (a verb that takes --only) the parts. */
static void about_text(const struct verb *v, char *about, size_t size) {
  size_t len = (size_t)snprintf(about, size, "%s", v->about);
  if (v == &VERBS[VERB_MAKE]) {
    len += (size_t)snprintf(about + len, size - len,
                            "\n\nverbs (vsph report VERB --help for each):");
    for (size_t w = 1; w < NVERBS && len < size; w++)
      len += (size_t)snprintf(about + len, size - len, "\n  %-10s %s",
                              VERBS[w].name, VERBS[w].what);
    if (len < size)
      len += (size_t)snprintf(about + len, size - len,
                              "\nThe old spellings --plan, --slurm, "
                              "--assemble and --archive ADIR are\nthese "
                              "verbs.");
  }
  if (!v->adir && len < size) {
    len += (size_t)snprintf(about + len, size - len, "\n\nParts:");
    for (size_t p = 0; p < vsph_report_part_count() && len < size; p++)
      len +=
          (size_t)snprintf(about + len, size - len, "\n  %-12s %s",
                           vsph_report_part_name(p), vsph_report_part_what(p));
  }
}

/* The synopsis of verb @p v; vsph report's names every verb's too. */
static void synopsis_text(const struct verb *v, char *text, size_t size) {
  size_t len = (size_t)snprintf(text, size, "%s", v->synopsis);
  for (size_t w = 1; v == &VERBS[VERB_MAKE] && w < NVERBS && len < size; w++)
    len += (size_t)snprintf(text + len, size - len, "\n   or: vsph %s %s",
                            VERBS[w].cmd, VERBS[w].synopsis);
}

/* The option named by word @p arg ("--name" or "--name=value") in @p t
 * (@p n options), or NULL. */
static const struct vsph_args_spec *find_option(const struct vsph_args_spec *t,
                                                size_t n, const char *arg) {
  for (size_t k = 0; k < n; k++)
    if (vsph_args_names(arg, t[k].name)) return &t[k];
  return NULL;
}

/* An option on verb @p v's command line that another verb takes, or the
 * old spelling of a verb: one line naming them (exit 2); else 0. */
static int foreign(const struct verb *v, int argc, char **argv) {
  struct opts none = {0};
  struct vsph_args_spec own[OPTS_MAX], other[OPTS_MAX];
  const size_t n = v->options(&none, own);
  for (int k = 1; k < argc; k++) {
    if (strncmp(argv[k], "--", 2) || find_option(own, n, argv[k])) continue;
    size_t by[NVERBS], m = 0; /* the verbs that take it */
    for (size_t w = 0; w < NVERBS; w++) {
      if (VERBS[w].alias && vsph_args_names(argv[k], VERBS[w].alias))
        return vsph_args_fail(v->cmd,
                              !VERBS[w].adir && strchr(argv[k], '=')
                                  ? "%s takes no value"
                                  : "%s is the verb vsph %s: one verb at a "
                                    "time",
                              VERBS[w].alias, VERBS[w].cmd);
      if (&VERBS[w] != v &&
          find_option(other, VERBS[w].options(&none, other), argv[k]))
        by[m++] = w;
    }
    char who[512];
    size_t len = 0;
    for (size_t i = 0; i < m && len < sizeof who; i++)
      len += (size_t)snprintf(who + len, sizeof who - len, "%svsph %s",
                              i == 0      ? ""
                              : i + 1 < m ? ", "
                                          : " and ",
                              VERBS[by[i]].cmd);
    if (m)
      return vsph_args_fail(v->cmd,
                            "%.*s is not an option of vsph %s (%s %s it)",
                            (int)strcspn(argv[k], "="), argv[k], v->cmd, who,
                            m > 1 ? "take" : "takes");
  }
  return 0;
}

/* The verb of the command line, its words into @p words (the verb's name,
 * or "report", first; *n of them): argv[1] when it is no option; else an
 * old spelling among the options (--plan, --slurm, --assemble, --archive
 * ADIR), each of its words left out (ADIR stays, as the verb's argument);
 * else vsph report itself. NULL after a refusal, its exit status in
 * *rc. */
static const struct verb *route(int argc, char **argv, char **words, int *n,
                                int *rc) {
  const struct verb *v = &VERBS[VERB_MAKE];
  if (argc > 1 && argv[1][0] != '-') {
    const char *name[NVERBS - 1];
    for (size_t w = 1; w < NVERBS; w++) name[w - 1] = VERBS[w].name;
    size_t w = 1;
    while (w < NVERBS && strcmp(argv[1], VERBS[w].name)) w++;
    if (w == NVERBS) {
      const size_t near = vsph_params_nearest(argv[1], name, NVERBS - 1);
      char hint[64] = "";
      if (near < NVERBS - 1)
        snprintf(hint, sizeof hint, "; did you mean %s?", name[near]);
      *rc = vsph_args_fail(CMD,
                           "'%s' is not a verb of vsph report (plan, submit, "
                           "assemble, archive)%s (see vsph report --help)",
                           argv[1], hint);
      return NULL;
    }
    *n = argc - 1;
    memcpy(words, argv + 1, (size_t)*n * sizeof *words);
    return &VERBS[w];
  }
  for (int k = 1; k < argc && v == &VERBS[VERB_MAKE]; k++)
    for (size_t w = 1; w < NVERBS; w++)
      if (vsph_args_names(argv[k], VERBS[w].alias) &&
          (VERBS[w].adir || !strcmp(argv[k], VERBS[w].alias)))
        v = &VERBS[w];
  words[0] = argv[0];
  *n = 1;
  const size_t len = v->alias ? strlen(v->alias) : 0;
  for (int k = 1; k < argc; k++)
    if (v->adir && vsph_args_names(argv[k], v->alias) && argv[k][len])
      words[(*n)++] = argv[k] + len + 1; /* --archive=ADIR: ADIR */
    else if (!v->alias || strcmp(argv[k], v->alias))
      words[(*n)++] = argv[k];
  return v;
}

/* Verb @p v's words (its name first) into @p o: -1 to go on, else the exit
 * status (help, a bad option, a word astray). */
static int parse(const struct verb *v, struct opts *o, int argc, char **argv) {
  struct vsph_args_spec own[OPTS_MAX];
  const size_t n = v->options(o, own);
  int help = 0;
  for (int k = 1; k < argc; k++)
    help |= !strcmp(argv[k], "--help") || !strcmp(argv[k], "-h");
  int rc = help ? 0 : foreign(v, argc, argv);
  if (rc) return rc;
  /* the options with their values apart from the other words (ADIR) */
  char **opt = malloc((size_t)argc * sizeof *opt);
  const char **rest = malloc((size_t)argc * sizeof *rest);
  if (!opt || !rest) {
    free(opt);
    free(rest);
    return vsph_args_status(v->cmd, VSPH_ENOMEM);
  }
  int nopt = 1, nrest = 0;
  opt[0] = argv[0];
  for (int k = 1; k < argc; k++) {
    const struct vsph_args_spec *s = find_option(own, n, argv[k]);
    if (argv[k][0] != '-' || !argv[k][1])
      rest[nrest++] = argv[k];
    else
      opt[nopt++] = argv[k];
    if (s && s->kind != VSPH_ARGS_FLAG && !strchr(argv[k], '=') && k + 1 < argc)
      opt[nopt++] = argv[++k]; /* its value */
  }
  char about[4096], synopsis[1024];
  about_text(v, about, sizeof about);
  synopsis_text(v, synopsis, sizeof synopsis);
  const struct vsph_args_cmd c = {.name = v->cmd,
                                  .synopsis = synopsis,
                                  .about = about,
                                  .own = own,
                                  .nown = n};
  rc = vsph_args_parse(&c, nopt, opt, NULL);
  if (rc < 0 && nrest > v->adir) /* GNU's words for a word astray */
    rc = vsph_args_fail(v->cmd, "extra operand '%s'%s (see --help)",
                        rest[v->adir], v->adir ? ": one run archive ADIR" : "");
  else if (rc < 0 && nrest < v->adir)
    rc = vsph_args_fail(v->cmd,
                        "missing operand: the run archive ADIR (see "
                        "--help)");
  if (rc < 0 && v->adir) o->archive = rest[0];
  /* given: an option named on the line (its value then parsed and valid;
   * 0 is a value here, and refused) */
  for (int k = 1; rc < 0 && k < nopt; k++) {
    o->pool |= vsph_args_names(opt[k], "--jobs");
    o->own_threads |= vsph_args_names(opt[k], "--threads");
  }
  free(opt);
  free(rest);
  return rc >= 0 ? vsph_args_finish(v->cmd, rc) : -1;
}

int vsph_cmd_report_main(int argc, char **argv) {
  char **words = malloc((size_t)argc * sizeof *words);
  if (!words) return vsph_args_status(CMD, VSPH_ENOMEM);
  int n = 0, rc = -1;
  const struct verb *v = route(argc, argv, words, &n, &rc);
  struct opts o = {.cmd = v ? v->cmd : CMD, .dir = "reports/out"};
  if (v) rc = parse(v, &o, n, words);
  if (v && rc < 0) rc = v->main(&o);
  free(words);
  return rc;
}
