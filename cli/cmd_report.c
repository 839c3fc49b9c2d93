/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* vsph report: the main job (reports/report.c). */
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

/* A run archive given to --skip-archived or --beside, checked before
 * anything is written: a folder vsph wrote as an archive, and not where
 * the report writes. 0, or the exit status of a refusal (one line). */
static int archive_input(const char *opt, const char *adir, const char *out) {
  struct stat as;
  if (!*adir || strlen(adir) > 200 ||
      !only_of(adir,
               "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
               "0123456789._-/"))
    return vsph_args_fail(CMD,
                          "%s: '%.200s' is not a folder name of 1-200 "
                          "letters, digits, '.', '_', '-' or '/'",
                          opt, adir);
  if (stat(adir, &as) != 0 || !S_ISDIR(as.st_mode))
    return vsph_args_fail(CMD,
                          "%s: %.200s is not a folder (make archive makes "
                          "reports/full)",
                          opt, adir);
  if (inside(out, adir))
    return vsph_args_fail(CMD, "%s: --out %.200s lies inside the archive %s",
                          opt, out, adir);
  const int st = vsph_archive_check(adir);
  return st ? vsph_args_status_about(CMD, opt, st) : 0;
}

/* What a judge of the archive reads ($VSPH_ARCHIVE_HISTORY and
 * reports/baseline.csv), checked before anything is written: 0, or the
 * exit status of a refusal (one line said). */
static int judge_inputs(void) {
  const char *history = getenv("VSPH_ARCHIVE_HISTORY");
  struct stat hs;
  char tsv[600];
  snprintf(tsv, sizeof tsv, "%s/commits.tsv", history ? history : "");
  if (history && *history &&
      (strlen(history) > 400 || stat(history, &hs) != 0 ||
       !S_ISDIR(hs.st_mode) || stat(tsv, &hs) != 0 || !S_ISREG(hs.st_mode) ||
       hs.st_size > VSPH_ARCHIVE_READ_MAX))
    return vsph_args_fail(CMD,
                          "VSPH_ARCHIVE_HISTORY '%.400s' is not a folder "
                          "scripts/source-commits made (a commits.tsv of at "
                          "most 16 MiB in it)",
                          history);
  if (stat("reports/baseline.csv", &hs) == 0 &&
      (!S_ISREG(hs.st_mode) || hs.st_size > VSPH_ARCHIVE_READ_MAX))
    return vsph_args_fail(CMD,
                          "reports/baseline.csv is not a regular file of "
                          "at most 16 MiB");
  return 0;
}

/* What the command line asked for. */
struct opts {
  const char *dir, *only, *partition, *limit, *budget, *archive;
  const char *skip, *beside, *from, *fv;
  int full, plan, slurm, assemble;
  size_t jobs, threads;
  int pool, own_threads; /* --jobs, --threads given */
  double budget_s;       /* --budget in seconds (0: none) */
  const char *fv_dir;    /* the finite-volume references, or NULL */
};

/* The help's text: what the report writes, then each part. */
static void about_text(char *about, size_t size) {
  size_t len = (size_t)snprintf(
      about, size, "%s",
      "Run the suite and write to DIR: report.md, report.html\n"
      "(self-contained: figures embedded, as SVG), the CSV behind every\n"
      "table and figure, the figures (fig_*.png, .svg and .pdf beside\n"
      "their fig_*.gp gnuplot scripts), the solver runs (runs/),\n"
      "baseline.csv (the key figures of the quick ladder's coarsest runs)\n"
      "and run.json. Default fidelity is\n"
      "quick (minutes on 2 cores: reduced resolutions and end times, stated\n"
      "in the report). Runs are cached by version, source hash and\n"
      "settings, the analysis parts by version, source hash and fidelity:\n"
      "an unchanged input is never recomputed. Every part first lists the\n"
      "runs it reads (--plan prints them); the missing ones run here two at\n"
      "a time, or as N processes (--jobs N), or on Slurm (--slurm), then\n"
      "the report is assembled. A stopped report resumes: finished runs\n"
      "are cached, a half-written one is redone. Parts:");
  for (size_t p = 0; p < vsph_report_part_count() && len < size; p++)
    len += (size_t)snprintf(about + len, size - len, "\n  %-12s %s",
                            vsph_report_part_name(p), vsph_report_part_what(p));
}

/* The command line into @p o: -1 to go on, else the exit status (help,
 * a bad option). */
static int parse(struct opts *o, int argc, char **argv) {
  const struct vsph_args_spec own[] = {
      {"--out", VSPH_ARGS_STRING, &o->dir, "DIR",
       "output folder (default reports/out)"},
      {"--only", VSPH_ARGS_STRING, &o->only, "P[,P]",
       "only these parts (see below); report.md gathers every part "
       "present; PART:SCENE (scenes, convergence, speed) limits those parts "
       "to one scene, e.g. scenes:vortex-patch"},
      {"--full", VSPH_ARGS_FLAG, &o->full, NULL,
       "the paper's resolutions and end times (hours)"},
      {"--plan", VSPH_ARGS_FLAG, &o->plan, NULL,
       "print the runs the report needs, one per line (tab-separated: "
       "cached or missing, folder, key fingerprint, particles, neighbours, "
       "steps, memory in MiB, the exact command) and stop; writes nothing"},
      {"--jobs", VSPH_ARGS_SIZE, &o->jobs, "N",
       "run the missing runs as N child processes at a time (1-256), each "
       "`vsph run` or `vsph contact` with its log in DIR/runs/logs; a run "
       "that fails is listed in DIR/runs/failed.txt and the others go on; "
       "then assemble"},
      {"--threads", VSPH_ARGS_SIZE, &o->threads, "T",
       "threads of each run with --jobs (default: cores / N, at least 1) "
       "or CPUs per array task with --slurm (default 1)"},
      {"--slurm", VSPH_ARGS_FLAG, &o->slurm, NULL,
       "submit the missing runs as one Slurm job array (sbatch --array, one "
       "task per run, memory and time from the largest run's estimate) and "
       "the assembly as a job after it (afterany); DIR must be on a file "
       "system every node shares. Scripts, logs and job ids in DIR/slurm"},
      {"--partition", VSPH_ARGS_STRING, &o->partition, "P",
       "with --slurm: the partition"},
      {"--time", VSPH_ARGS_STRING, &o->limit, "T",
       "with --slurm: each task's time limit in Slurm's form (MM, HH:MM:SS, "
       "D-HH:MM:SS; default: estimated from the largest run)"},
      {"--assemble", VSPH_ARGS_FLAG, &o->assemble, NULL,
       "run nothing: assemble from the cached runs, naming any that is "
       "missing (the Slurm assembly job)"},
      {"--budget", VSPH_ARGS_STRING, &o->budget, "TIME",
       "run only the missing runs that fit TIME of wall time (90s, 150m, "
       "2.5h; a plain number is seconds), the costliest first, at the rates "
       "the cached runs measured, niced, two at a time (or as --jobs says); "
       "when TIME is spent the runs stop at a checkpoint and the next "
       "--budget goes on from there; exit 0, and nothing is assembled (a "
       "FULL report fills over several sittings this way)"},
      {"--skip-archived", VSPH_ARGS_STRING, &o->skip, "ADIR",
       "with --budget: leave out the runs that stand in the run archive "
       "ADIR (reports/full for the FULL report; judged as --archive's "
       "entries.md judges them, from $VSPH_ARCHIVE_HISTORY and "
       "reports/baseline.csv), so a sitting goes on from the archive "
       "whatever build made it (make full-sitting)"},
      {"--from-archive", VSPH_ARGS_STRING, &o->from, "ADIR",
       "each run DIR lacks that stands in the run archive ADIR (judged as "
       "for --skip-archived) is read from its entry there instead of run. "
       "With --full (and --assemble): then ADIR/summary.md gets the "
       "report's claims and convergence tables (make full-report), and a "
       "part that draws snapshots leaves out the pictures of a run read "
       "from the archive, which keeps none, and says so. A quick report "
       "(make report gives it reports/full) still makes the runs whose "
       "snapshots it draws and, with its scenes part, its baseline rows' "
       "runs"},
      {"--beside", VSPH_ARGS_STRING, &o->beside, "ADIR",
       "the summary shows, beside the quick ladder's finest run of each "
       "scene and formulation, the run at the paper's resolution from the "
       "run archive ADIR (reports/full; make report gives it), with "
       "whether it stands (judged as --archive's entries.md judges it)"},
      {"--fv", VSPH_ARGS_STRING, &o->fv, "FDIR",
       "the committed finite-volume references the stretching square and "
       "the cavity are judged against (OpenFOAM runs that make reference "
       "made; reference/README.md): default reference/data when it is a "
       "folder here; none: without them (their rows say not tested)"},
      {"--archive", VSPH_ARGS_STRING, &o->archive, "ADIR",
       "run nothing: store the sealed runs of DIR/runs in the run archive "
       "ADIR (reports/full for the FULL report): of each, what the parts "
       "read (energy.csv, run.json, profiles), not its snapshots, as a "
       "folder sealed under the run's own key (version, source hash, "
       "settings); runs already there are kept, unended ones are named and "
       "left out; then ADIR/index.tsv. The commit of entries made by this "
       "build's sources is $VSPH_COMMIT (make archive sets it)"}};
  char about[2048];
  about_text(about, sizeof about);
  const struct vsph_args_cmd c = {CMD,
                                  "[--out DIR] [--only PART[,PART...]] "
                                  "[--full] [--plan | --jobs N | --slurm "
                                  "[--partition P] [--time T] | --assemble] "
                                  "[--threads T] [--budget TIME "
                                  "[--skip-archived ADIR]] [--beside ADIR] "
                                  "[--from-archive ADIR] [--fv FDIR] "
                                  "| --archive ADIR",
                                  about,
                                  own,
                                  sizeof own / sizeof own[0],
                                  NULL,
                                  0,
                                  NULL};
  const int rc = vsph_args_parse(&c, argc, argv, NULL);
  if (rc >= 0) return vsph_args_finish(CMD, rc);
  /* given: an option named in argv (its value is then parsed and valid;
   * 0 is a value here, and refused) */
  for (int k = 1; k < argc; k++) {
    o->pool |= vsph_args_names(argv[k], "--jobs");
    o->own_threads |= vsph_args_names(argv[k], "--threads");
  }
  return -1;
}

/* The modes and the options that go with them. */
static int check_modes(const struct opts *o) {
  if (o->plan + o->slurm + o->assemble + o->pool > 1)
    return vsph_args_fail(CMD,
                          "--plan, --jobs, --slurm and --assemble exclude one "
                          "another");
  if (o->pool && (o->jobs < 1 || o->jobs > 256))
    return vsph_args_fail(CMD, "--jobs must lie in 1-256, got %zu", o->jobs);
  if (o->own_threads && (o->threads < 1 || o->threads > 1024))
    return vsph_args_fail(CMD, "--threads must lie in 1-1024, got %zu",
                          o->threads);
  if (o->own_threads && !o->pool && !o->slurm)
    return vsph_args_fail(CMD, "--threads needs --jobs or --slurm");
  if ((o->partition || o->limit) && !o->slurm)
    return vsph_args_fail(CMD, "--%s needs --slurm",
                          o->partition ? "partition" : "time");
  if (o->partition &&
      (strlen(o->partition) > 64 ||
       !only_of(o->partition,
                "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstu"
                "vwxyz0123456789_.-,")))
    return vsph_args_fail(CMD, "--partition '%.64s' is not a partition name",
                          o->partition);
  if (o->limit &&
      (strlen(o->limit) > 16 || !only_of(o->limit, "0123456789:-") ||
       !strchr("0123456789", o->limit[strlen(o->limit) - 1])))
    return vsph_args_fail(CMD,
                          "--time '%.16s' is not a Slurm time limit (MM, "
                          "HH:MM:SS or D-HH:MM:SS)",
                          o->limit);
  return 0;
}

/* --budget into seconds (o->budget_s). */
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
      return vsph_args_fail(CMD,
                            "--budget '%.32s' is not a time from 1 s to 30 "
                            "days (e.g. 90s, 150m, 2.5h)",
                            o->budget);
    if (o->plan || o->slurm || o->assemble)
      return vsph_args_fail(CMD,
                            "--budget runs the runs here: not with --plan, "
                            "--slurm or --assemble");
  }
  return 0;
}

/* The run archives read, and the finite-volume references (o->fv_dir). */
static int check_archives(struct opts *o) {
  if (o->skip) {
    if (!o->budget)
      return vsph_args_fail(CMD, "--skip-archived needs --budget");
    int bad = archive_input("--skip-archived", o->skip, o->dir);
    if (!bad) bad = judge_inputs();
    if (bad) return bad;
  }
  if (o->from) {
    if (o->full ? !o->assemble : o->plan || o->budget || o->slurm)
      return vsph_args_fail(CMD,
                            "--from-archive reads runs from a run archive: "
                            "with --full only when assembling (--assemble); "
                            "a quick report not with --plan, --budget or "
                            "--slurm");
    int bad = archive_input("--from-archive", o->from, o->dir);
    if (!bad) bad = judge_inputs();
    if (bad) return bad;
  }
  if (o->beside) {
    if (o->full || o->plan || o->budget || o->slurm)
      return vsph_args_fail(CMD,
                            "--beside sets the FULL archive beside a quick "
                            "report: not with --full, --plan, --budget or "
                            "--slurm");
    int bad = archive_input("--beside", o->beside, o->dir);
    if (!bad) bad = judge_inputs();
    if (bad) return bad;
  }
  /* the finite-volume references: a folder, or none */
  struct stat fs;
  if (o->fv && strcmp(o->fv, "none")) {
    if (!*o->fv || strlen(o->fv) > 400 || stat(o->fv, &fs) != 0 ||
        !S_ISDIR(fs.st_mode))
      return vsph_args_fail(CMD, "--fv: '%.400s' is not a folder", o->fv);
    o->fv_dir = o->fv;
  } else if (!o->fv && stat("reference/data", &fs) == 0 && S_ISDIR(fs.st_mode))
    o->fv_dir = "reference/data";
  return 0;
}

/* --archive: the sealed runs of the output folder into the run archive,
 * then its summary; nothing is run. */
static int archive_main(const struct opts *o) {
  if (o->fv || o->beside || o->skip || o->from || o->plan || o->slurm ||
      o->assemble || o->pool || o->budget || o->only || o->full)
    return vsph_args_fail(CMD, "--archive runs nothing: it takes --out alone");
  if (!*o->archive || strlen(o->archive) > 400)
    return vsph_args_fail(CMD,
                          "--archive: a folder name of 1-400 "
                          "characters");
  /* the archive beside the report, never in it (its runs/ is what is
   * stored) nor around it */
  if (inside(o->archive, o->dir) || inside(o->dir, o->archive))
    return vsph_args_fail(CMD,
                          "--archive %.200s and the report folder %.200s lie "
                          "one inside the other: the archive goes beside it",
                          o->archive, o->dir);
  const char *commit = getenv("VSPH_COMMIT");
  if (commit && !*commit) commit = NULL; /* none known */
  if (commit &&
      (strlen(commit) > 64 || !only_of(commit,
                                       "0123456789abcdefghijklmnopqrstuvwxyz"
                                       "ABCDEFGHIJKLMNOPQRSTUVWXYZ._-")))
    return vsph_args_fail(CMD, "VSPH_COMMIT '%.64s' is not a commit id",
                          commit);
  /* what the summary reads, judged before anything is written */
  const int bad = judge_inputs();
  if (bad) return bad;
  struct vsph_jobs full_plan; /* the FULL plan: the frames and the judge */
  memset(&full_plan, 0, sizeof full_plan);
  struct vsph_archive_counts n;
  int st = vsph_report_plan_jobs(o->dir, 1, &full_plan);
  if (!st) st = store(o->dir, &full_plan, o->archive, commit, &n);
  if (st) {
    vsph_jobs_plan_free(&full_plan);
    return vsph_args_status(CMD, st);
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
    return vsph_args_finish(CMD, 0);
  }
  st = summarise(&full_plan, o->archive, commit);
  vsph_jobs_plan_free(&full_plan);
  if (st) return vsph_args_status(CMD, st);
  return vsph_args_finish(CMD, 0);
}

/* --only PART[,PART...] (PART:SCENE) into rp's parts and scenes. */
static int only_parts(const char *only, struct vsph_report_props *rp) {
  if (only) {
    char buf[256];
    if (strlen(only) >= sizeof buf)
      return vsph_args_fail(CMD, "--only: '%.40s...' is too long", only);
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
          return vsph_args_fail(CMD,
                                "unknown scene '%s' in --only (vortex-patch, "
                                "stretching-square, standing-wave)",
                                colon + 1);
        if (strcmp(tok, "scenes") && strcmp(tok, "convergence") &&
            strcmp(tok, "speed"))
          return vsph_args_fail(CMD,
                                "--only %s:%s: only scenes, convergence and "
                                "speed take a scene",
                                tok, colon + 1);
        rp->scenes |= 1u << s;
      }
      const int p = vsph_report_part_find(tok);
      if (p < 0)
        return vsph_args_fail(CMD, "unknown part '%s' (see --help)", tok);
      rp->parts |= 1ul << p;
    }
    if (!rp->parts)
      return vsph_args_fail(CMD, "--only names no part (see --help)");
  }
  return 0;
}

/* The report itself, as the options say; its exit status. */
static int run_report(const struct opts *o, struct vsph_report_props *rp) {
  /* vsph itself, for the child processes and the Slurm scripts */
  char exe[PATH_MAX];
  const ssize_t ne = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (ne <= 0) {
    fprintf(stderr, "vsph report: cannot find vsph itself (/proc/self/exe)\n");
    return vsph_args_status(CMD, VSPH_EIO);
  }
  exe[ne] = '\0';
  rp->exe = exe;
  rp->mode = o->plan       ? VSPH_REPORT_PLAN
             : o->pool     ? VSPH_REPORT_POOL
             : o->slurm    ? VSPH_REPORT_SLURM
             : o->assemble ? VSPH_REPORT_ASSEMBLE
                           : VSPH_REPORT_LOCAL;
  rp->plan_out = stdout;
  rp->jobs = o->pool ? o->jobs : 0;
  const size_t cores = (size_t)omp_get_num_procs();
  rp->threads = o->own_threads ? o->threads
                : o->slurm     ? 1
                : o->pool      ? (cores / o->jobs > 0 ? cores / o->jobs : 1)
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
      return vsph_args_status(CMD, VSPH_EIO);
    }
  }
  const int st = vsph_report_write(rp);
  if (st == VSPH_EINTR && *stop == SIGALRM) {
    fprintf(stderr,
            "vsph report: the budget of %.0f s is spent; the runs in "
            "progress stopped at a checkpoint, and the next --budget goes on "
            "from there\n",
            o->budget_s);
    return vsph_args_finish(CMD, 0);
  }
  if (st == VSPH_EINTR) {
    fprintf(stderr,
            "vsph report: interrupted by signal %d; finished runs "
            "are cached, rerun to go on\n",
            (int)*stop);
    return 128 + (int)*stop;
  }
  return st ? vsph_args_status(CMD, st) : vsph_args_finish(CMD, 0);
}

int vsph_cmd_report_main(int argc, char **argv) {
  struct opts o = {.dir = "reports/out"};
  int rc = parse(&o, argc, argv);
  if (rc >= 0) return rc;
  if ((rc = check_modes(&o)) || (rc = check_budget(&o)) ||
      (rc = check_archives(&o)))
    return rc;
  if (o.archive) return archive_main(&o);
  if (o.slurm && !on_path("sbatch"))
    return vsph_args_fail(CMD,
                          "--slurm needs Slurm's sbatch on PATH, and it is "
                          "not there");
  if (strlen(o.dir) > 400)
    return vsph_args_fail(CMD, "--out: the folder's name is too long");
  struct vsph_report_props rp = {
      .dir = o.dir, .full = o.full, .parts = 0, .stop = NULL};
  if ((rc = only_parts(o.only, &rp))) return rc;
  return run_report(&o, &rp);
}
