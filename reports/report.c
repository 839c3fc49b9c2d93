/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's driver: its parts in order, their plans, their cache, the
 * claims each grades, the assembly of report.md and report.html,
 * baseline.csv and run.json. The parts write with report_doc.c and never
 * call back here. */
#include "report.h"

#include <cjson/cJSON.h>
#include <errno.h>
#include <fcntl.h>
#include <gsl/gsl_integration.h>
#include <math.h>
#include <omp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../common/sysinfo.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/json.h"
#include "../io/plot.h"
#include "../runs/folder.h"
#include "html.h"
#include "report_claims.h"
#include "report_parts.h"

struct part {
  const char *name;
  int (*fn)(struct vsph_report *);
  int (*plan)(struct vsph_report *); /* the runs it reads, or NULL */
  int cached; /* 1: skipped when its key matches (cheap, no runs) */
  const char *what;
  /* the claims it grades into the claims table, or NULL (graded by the
   * claims part, whatever parts are written: they read the part's runs
   * again, so the table is whole when the part comes from the cache) */
  int (*grade)(struct vsph_report *);
};

static int claims_plan(struct vsph_report *R);
static int claims_write(struct vsph_report *R);

/* convergence and speed read the ladders of the scenes on */
static int plan_ladders(struct vsph_report *R) {
  return vsph_report_runs_plan_ladders(&R->runs, 0);
}

static const struct part PARTS[] = {
    {.name = "tensors",
     .fn = vsph_report_tensors_write,
     .cached = 1,
     .what = "F, G, N, M against theory; particle sums; C_F, C_N"},
    {.name = "profiles",
     .fn = vsph_report_profiles_write,
     .cached = 1,
     .what = "the tensors against depth (figures)"},
    {.name = "scaling",
     .fn = vsph_report_scaling_write,
     .cached = 1,
     .what = "1/h surface scaling, slopes; interior convergence"},
    {.name = "dissipation",
     .fn = vsph_report_dissipation_write,
     .cached = 1,
     .what = "THEORY 4 dissipation integrals against resolution and h/dx"},
    {.name = "scenes",
     .fn = vsph_report_scenes_write,
     .plan = vsph_report_scenes_plan,
     .what = "the three scenes, each formulation, against the references"},
    {.name = "convergence",
     .fn = vsph_report_convergence_write,
     .plan = plan_ladders,
     .what = "error against resolution, fitted order"},
    {.name = "speed",
     .fn = vsph_report_speed_write,
     .plan = vsph_report_speed_plan,
     .what = "wall time against error; the time step's error against CFL"},
    {.name = "stability",
     .fn = vsph_report_stability_write,
     .plan = vsph_report_stability_plan,
     .what = "hard cases: PVWF, high Re, perturbed start, low c0, CFL"},
    {.name = "patch",
     .fn = vsph_report_patch_write,
     .cached = 1,
     .grade = vsph_report_patch_claims,
     .what = "Laplacian patch tests of VISC-01..04 beside Zheng et al. (2018)"},
    {.name = "channel",
     .fn = vsph_report_channel_write,
     .plan = vsph_report_channel_plan,
     .grade = vsph_report_channel_claims,
     .what = "internal flows (Poiseuille, Couette) and the other formulations"},
    {.name = "contact",
     .fn = vsph_report_contact_write,
     .plan = vsph_report_contact_plan,
     .grade = vsph_report_contact_claims,
     .what = "contact SPH: the numerical viscosity of its Riemann solver"},
    {.name = "choices",
     .fn = vsph_report_choices_write,
     .plan = vsph_report_choices_plan,
     .what = "the scheme's own choices isolated: the wave's start, steepness, "
             "delta-SPH, c0, time step; the two-pass null mode"},
    {.name = "claims",
     .fn = claims_write,
     .plan = claims_plan,
     .grade = vsph_report_claims_grade,
     .what = "the paper's claims beside our figures"},
};
#define NPARTS (sizeof PARTS / sizeof PARTS[0])
_Static_assert(NPARTS <= 8 * sizeof(unsigned long), "part mask too narrow");
_Static_assert(NPARTS <=
                   sizeof((struct vsph_report *)0)->asm_part / sizeof(double),
               "asm_part too short");

size_t vsph_report_part_count(void) { return NPARTS; }

/* The scenes' names are the ladders' (report_runs.c; the quick and the
 * FULL ladder name the same scenes in the same order, tests/check_report.c) */
const char *vsph_report_scene_name(size_t s) {
  return s < VSPH_REPORT_NSCENES ? vsph_report_runs_full_ladder((int)s)->scene
                                 : NULL;
}

const char *vsph_report_part_name(size_t p) {
  return p < NPARTS ? PARTS[p].name : NULL;
}

const char *vsph_report_part_what(size_t p) {
  return p < NPARTS ? PARTS[p].what : NULL;
}

int vsph_report_part_find(const char *name) {
  for (size_t p = 0; p < NPARTS; p++)
    if (!strcmp(PARTS[p].name, name)) return (int)p;
  return -1;
}

/* ---------------------------------------------------------------- claims */

/* The claims part reads what every grading part reads. */
static int claims_plan(struct vsph_report *R) {
  int st = vsph_report_claims_plan(R);
  for (size_t p = 0; p < NPARTS && !st; p++)
    if (PARTS[p].grade && PARTS[p].plan && PARTS[p].plan != claims_plan)
      st = PARTS[p].plan(R);
  return st;
}

/* The claims table: the core paper's claims first (their own part), then
 * each part's in the report's order, tallied and tabled; then the FULL
 * runs beside the quick ones where an archive is given. */
static int claims_write(struct vsph_report *R) {
  R->nclaims = 0;
  int st = VSPH_OK;
  const int self = vsph_report_part_find("claims");
  if (PARTS[self].grade) st = PARTS[self].grade(R);
  for (size_t p = 0; p < NPARTS && !st; p++)
    if (PARTS[p].grade && (int)p != self) {
      R->claim_see = PARTS[p].name;
      st = PARTS[p].grade(R);
    }
  R->claim_see = NULL;
  if (!st) {
    vsph_text_set(&R->tv, "quick_note", "%s",
                  R->runs.full ? "" : vsph_text_get("claims.quick_note"));
    st = vsph_report_doc_say(R, "claims.head");
  }
  if (!st) st = vsph_report_doc_claims_table(R);
  if (!st && R->beside) st = vsph_report_claims_archived(R);
  return st;
}

int vsph_report_beside_prepare(struct vsph_report *R) {
  vsph_report_beside_free(R);
  int st = vsph_report_plan_jobs(R->dir, 1, &R->beside_jobs);
  if (!st)
    st = vsph_report_plan_judge(&R->beside_jobs, R->judge, &R->beside_jd);
  if (!st) {
    R->beside_stands = calloc(R->beside_jobs.n + 1, sizeof *R->beside_stands);
    if (!R->beside_stands) {
      st = VSPH_ENOMEM;
      vsph_status_report(st, __FILE__, __LINE__, "cannot list the FULL plan");
    }
  }
  if (!st)
    st = vsph_archive_standing(R->beside, &R->beside_jd, R->beside_stands);
  if (st) vsph_report_beside_free(R);
  return st;
}

void vsph_report_beside_free(struct vsph_report *R) {
  free(R->beside_stands);
  R->beside_stands = NULL;
  vsph_report_plan_judge_free(&R->beside_jd);
  vsph_jobs_plan_free(&R->beside_jobs);
  memset(&R->beside_jobs, 0, sizeof R->beside_jobs);
}

/* ---------------------------------------------------------------- driver */

static int write_baseline(struct vsph_report *R) {
  FILE *f = vsph_csv_open(R->dir, "baseline.csv",
                          "scene,visc,res,t_end,ek_final,diss0_or_uerr,stable");
  if (!f) return VSPH_EIO;
  int st = VSPH_OK;
  for (size_t i = 0; i < vsph_report_runs_baseline_count() && !st; i++) {
    struct vsph_report_baseline b;
    st = vsph_report_runs_baseline(&R->runs, i, &b);
    if (!st)
      fprintf(f, "%s,%s,%zu,%g,%.10e,%.10e,%d\n", b.scene, b.visc, b.res,
              b.t_end, b.ek_final, b.diss0, b.ok);
  }
  if (st) {
    vsph_files_discard(f, R->dir, "baseline.csv");
    return st;
  }
  return vsph_csv_close(f, R->dir, "baseline.csv");
}

/* Run part p into PARTS_DIR/NAME.md unless its cache key matches. */
static int run_part(struct vsph_report *R, size_t p, double left,
                    const char *parts_dir, const char *key, int *cached,
                    double *wall) {
  char md[96], kf[700];
  snprintf(md, sizeof md, "%s.md", PARTS[p].name);
  snprintf(kf, sizeof kf, "%s/%s.key", parts_dir, PARTS[p].name);
  /* a part's key: the report's, then its text's size and CRC-32, so a
   * cut, edited or missing NAME.md is made again */
  char mdpath[700], pkey[256] = "";
  snprintf(mdpath, sizeof mdpath, "%s/%s", parts_dir, md);
  unsigned long crc;
  size_t size;
  if (!vsph_folder_checksum(mdpath, &crc, &size))
    snprintf(pkey, sizeof pkey, "%s%s %zu %08lx\n", key, md, size, crc);
  if (PARTS[p].cached) {
    char *old = vsph_files_slurp(kf, NULL);
    const int hit = old && pkey[0] && !strcmp(old, pkey);
    free(old);
    if (hit) {
      *cached = 1;
      fprintf(stderr, "vsph report: %s (cached)\n", PARTS[p].name);
      return VSPH_OK;
    }
  }
  fprintf(stderr, "vsph report: %s ... (about %.0f s left)\n", PARTS[p].name,
          left);
  const double t = omp_get_wtime();
  remove(kf);
  R->md = vsph_files_open(parts_dir, md);
  if (!R->md) return VSPH_EIO;
  int st = PARTS[p].fn(R);
  if (st) {
    vsph_files_discard(R->md, parts_dir, md);
    R->md = NULL;
    return st;
  }
  st = vsph_files_close(R->md, parts_dir, md);
  R->md = NULL;
  if (!st && PARTS[p].cached) {
    char kname[96];
    snprintf(kname, sizeof kname, "%s.key", PARTS[p].name);
    if (vsph_folder_checksum(mdpath, &crc, &size))
      VSPH_FAIL(VSPH_EIO, "cannot read %s", mdpath);
    snprintf(pkey, sizeof pkey, "%s%s %zu %08lx\n", key, md, size, crc);
    st = vsph_files_write(parts_dir, kname, pkey);
  }
  *wall = omp_get_wtime() - t;
  return st;
}

/* The report's first screen into R->md: the question, then the tally and
 * the findings the claims part marked in @p claims (its text, or NULL;
 * they are cut from it, shown once), then the sources and how the runs
 * were made. */
static int first_screen(struct vsph_report *R, char *claims) {
  int st = vsph_report_doc_say(R, "report.question");
  char *f0 = claims ? strstr(claims, "<!-- findings -->") : NULL;
  char *f1 = f0 ? strstr(f0, "<!-- /findings -->") : NULL;
  if (!st && f0 && f1) {
    const char *body = f0 + strlen("<!-- findings -->\n");
    fprintf(R->md, "%.*s", (int)(f1 - body), body);
    memmove(f0, f1 + strlen("<!-- /findings -->\n"),
            strlen(f1 + strlen("<!-- /findings -->\n")) + 1);
  }
  if (!st) st = vsph_report_doc_say(R, "report.head_sources");
  /* the runs a quick report read from the archive: a paragraph of its own
   * (the archive's name is at most 200 characters); its values set just
   * before it (each block's are cleared after it) */
  vsph_text_set(&R->tv, "nread", "%zu", R->runs.from_archive);
  vsph_text_set(&R->tv, "nrun", "%zu", R->runs.jobs.n);
  vsph_text_set(&R->tv, "archive", "%s",
                R->runs.archive ? R->runs.archive : "");
  if (!st && !R->runs.full && R->runs.from_archive)
    st = vsph_report_doc_say(R, "report.quick_archive");
  vsph_text_clear(&R->tv);
  return st;
}

/* report.md from every part present, then report.html. */
static int assemble(struct vsph_report *R, const char *parts_dir,
                    unsigned long want, const int *cached, const double *wall,
                    const char *stamp) {
  FILE *md = vsph_files_open(R->dir, "report.md");
  if (!md) return VSPH_EIO;
  R->md = md;
  struct vsph_text_vars *tv = &R->tv;
  vsph_text_set(tv, "version", "%s", VSPH_VERSION);
  vsph_text_set(tv, "date", "%s", stamp);
  vsph_text_set(tv, "fidelity", "%s", R->runs.full ? "full" : "quick");
  vsph_text_set(tv, "cores", "%d", omp_get_num_procs());
  vsph_text_set(tv, "threads", "%d", omp_get_max_threads());
  vsph_text_set(tv, "quick_note", "%s",
                R->runs.full ? "" : vsph_text_get("report.quick_note"));
  int st = vsph_report_doc_say(R, "report.head");
  /* every part present, the claims first (the summary); a part's text
   * after its "<!-- appendix -->" mark goes to the appendices at the end */
  char *text[NPARTS] = {0};
  const char *appendix[NPARTS] = {0};
  for (size_t p = 0; p < NPARTS; p++) {
    char path[700];
    snprintf(path, sizeof path, "%s/%s.md", parts_dir, PARTS[p].name);
    if (!(text[p] = vsph_files_slurp(path, NULL))) continue;
    char *mark = strstr(text[p], "<!-- appendix -->");
    if (mark) {
      *mark = '\0';
      appendix[p] = mark + strlen("<!-- appendix -->");
    }
  }
  const int claims = vsph_report_part_find("claims");
  if (!st) st = first_screen(R, text[claims]);
  size_t order[NPARTS], n = 0;
  if (text[claims]) order[n++] = (size_t)claims;
  for (size_t p = 0; p < NPARTS; p++)
    if (text[p] && (int)p != claims) order[n++] = p;
  if (!st && n) { /* contents, from each part's first heading */
    fprintf(md, "**Contents**\n\n");
    for (size_t k = 0; k < n; k++) {
      const char *h = strstr(text[order[k]], "\n## ");
      h = h ? h + 4
            : (!strncmp(text[order[k]], "## ", 3) ? text[order[k]] + 3 : NULL);
      const int len = h ? (int)strcspn(h, "\n") : 0;
      fprintf(md, "- [%.*s](#sec-%s)\n", len, h ? h : "", PARTS[order[k]].name);
    }
    for (size_t p = 0; p < NPARTS; p++)
      if (appendix[p])
        fprintf(md, "- [Appendix: %s tables](#appendix-%s)\n", PARTS[p].name,
                PARTS[p].name);
    fprintf(md, "- [Run facts](#run-facts)\n\n");
  }
  for (size_t k = 0; k < n && !st; k++) {
    fprintf(md, "<a id=\"sec-%s\"></a>\n\n", PARTS[order[k]].name);
    fputs(text[order[k]], md);
  }
  for (size_t p = 0; p < NPARTS && !st; p++)
    if (appendix[p]) {
      fprintf(md, "<a id=\"appendix-%s\"></a>\n\n", PARTS[p].name);
      fputs(appendix[p], md);
    }
  for (size_t p = 0; p < NPARTS; p++) free(text[p]);
  if (!st) st = vsph_report_doc_say(R, "report.facts_head");
  for (size_t p = 0; p < NPARTS && !st; p++) {
    if (!(want >> p & 1)) continue;
    if (cached[p])
      fprintf(md, "| %s | cached |\n", PARTS[p].name);
    else
      fprintf(md, "| %s | %.1f |\n", PARTS[p].name, wall[p]);
  }
  /* the runs come before the parts, which only read them */
  if (!st)
    fprintf(md, "| the parts' runs (%zu of %zu made, by %s) | %.1f |\n",
            R->runs.made, R->runs.jobs.n, R->runs.made_by, R->runs.runs_wall);
  if (!st && R->runs.from_archive)
    fprintf(md,
            "| of them read from the run archive `%s` (each still standing "
            "for this code by the archive's rule; its wall time is in its "
            "entry) | %zu runs |\n",
            R->runs.archive, R->runs.from_archive);
  vsph_text_set(tv, "compiler", "%s", __VERSION__);
  vsph_sysinfo_load(R->load[1]);
  vsph_text_set(tv, "load_start", "%.2f %.2f %.2f", R->load[0][0],
                R->load[0][1], R->load[0][2]);
  vsph_text_set(tv, "load_end", "%.2f %.2f %.2f", R->load[1][0], R->load[1][1],
                R->load[1][2]);
  char wp[128];
  vsph_text_set(tv, "wait_policy", "%s",
                vsph_sysinfo_wait_policy(wp, sizeof wp));
  vsph_text_set(tv, "cpu", "%.0f", vsph_sysinfo_cpu_s());
  if (!st) st = vsph_report_doc_say(R, "report.facts_tail");
  R->md = NULL;
  if (st) {
    vsph_files_discard(md, R->dir, "report.md");
    return st;
  }
  if ((st = vsph_files_close(md, R->dir, "report.md"))) return st;
  return vsph_html_render(R->dir, "report.md", "report.html", "vsph report");
}

static int write_run_json(const struct vsph_report *R, unsigned long want,
                          const int *cached, const double *wall,
                          const char *stamp, double total) {
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "version", VSPH_VERSION);
  cJSON_AddStringToObject(o, "source_hash", vsph_source_hash_id);
  cJSON_AddStringToObject(o, "commit",
                          vsph_commit_id[0] ? vsph_commit_id : "unknown");
  cJSON_AddStringToObject(o, "date", stamp);
  cJSON_AddStringToObject(o, "fidelity", R->runs.full ? "full" : "quick");
  cJSON_AddNumberToObject(o, "cores", omp_get_num_procs());
  cJSON_AddNumberToObject(o, "threads", omp_get_max_threads());
  cJSON_AddStringToObject(o, "compiler", __VERSION__);
  cJSON *w = cJSON_CreateObject();
  for (size_t p = 0; p < NPARTS; p++)
    if (want >> p & 1) {
      if (cached[p])
        cJSON_AddStringToObject(w, PARTS[p].name, "cached");
      else
        cJSON_AddNumberToObject(w, PARTS[p].name, wall[p]);
    }
  cJSON_AddItemToObject(o, "wall_s", w);
  cJSON_AddNumberToObject(o, "wall_total_s", total);
  /* how its runs were made: the plan's size and the way */
  cJSON_AddNumberToObject(o, "runs_planned", (double)R->runs.jobs.n);
  cJSON_AddNumberToObject(o, "runs_made", (double)R->runs.made);
  cJSON_AddStringToObject(o, "runs_by", R->runs.made_by);
  if (R->runs.from_archive) {
    cJSON_AddStringToObject(o, "runs_archive", R->runs.archive);
    cJSON_AddNumberToObject(o, "runs_from_archive",
                            (double)R->runs.from_archive);
  }
  cJSON_AddNumberToObject(o, "runs_wall_s", R->runs.runs_wall);
  vsph_json_number(o, "cpu_total_s", vsph_sysinfo_cpu_s());
  vsph_json_load(o, R->load[0], R->load[1]);
  return vsph_json_write(o, R->dir, "run.json");
}

/* Every run the parts of @p want read (and baseline.csv, which comes with
 * the scenes part on every scene). */
static int plan(struct vsph_report *R, unsigned long want) {
  int st = VSPH_OK;
  for (size_t p = 0; p < NPARTS && !st; p++)
    if ((want >> p & 1) && PARTS[p].plan) st = PARTS[p].plan(R);
  const int scenes = vsph_report_part_find("scenes");
  if (!st && (want >> scenes & 1) && !R->runs.scenes)
    st = vsph_report_runs_plan_baseline(&R->runs);
  return st;
}

/* One report at a time writes a folder, and only a folder that is new,
 * empty or a report's (runs/folder's contract): R->folder holds the claim
 * until the report is done (the system drops it if the process dies). */
static int lock_dir(struct vsph_report *R, const char *dir) {
  vsph_folder_release(&R->folder); /* Slurm's absolute path, then rp's */
  const int st = vsph_folder_claim(&R->folder, dir, &vsph_folder_report);
  /* the temporaries a report stopped by a signal left */
  return st ? st : vsph_folder_clear_tmp(&R->folder);
}

/* The report's end: its folder's claim dropped, its memory freed. */
static void report_free(struct vsph_report *R) {
  vsph_folder_release(&R->folder);
  free(R->fv);
  free(R);
}

/* The assembly's seconds when no earlier report says (measured on the
 * project's 2-core machine, load 1.5-2: the quick report's parts and
 * pages 18 s after its runs on a fresh machine and twice on a built tree,
 * the FULL report's assembly from the archive 210 s), shared evenly among
 * the parts wanted. */
#define ASM_PRIOR_QUICK 20.0
#define ASM_PRIOR_FULL 210.0

/* The assembly's expected seconds into R->asm_part and R->asm_rest: from
 * the earlier report of this fidelity in R->dir (its run.json: each part's
 * wall time, the rest of its total after the runs), else the prior.
 * Returns the whole. */
static double assembly_estimate(struct vsph_report *R, unsigned long want) {
  char path[700];
  snprintf(path, sizeof path, "%s/run.json", R->dir);
  cJSON *o = vsph_json_read(path);
  const cJSON *fid = o ? cJSON_GetObjectItemCaseSensitive(o, "fidelity") : NULL;
  const cJSON *w = o ? cJSON_GetObjectItemCaseSensitive(o, "wall_s") : NULL;
  const int same = cJSON_IsString(fid) && cJSON_IsObject(w) &&
                   !strcmp(fid->valuestring, R->runs.full ? "full" : "quick");
  size_t nwant = 0;
  for (size_t p = 0; p < NPARTS; p++) nwant += want >> p & 1;
  const double prior =
      (R->runs.full ? ASM_PRIOR_FULL : ASM_PRIOR_QUICK) / (double)(nwant + 1);
  double parts = 0.0, total = 0.0;
  for (size_t p = 0; p < NPARTS; p++) {
    R->asm_part[p] = 0.0;
    if (!(want >> p & 1)) continue;
    const cJSON *x =
        same ? cJSON_GetObjectItemCaseSensitive(w, PARTS[p].name) : NULL;
    R->asm_part[p] = cJSON_IsNumber(x) && x->valuedouble >= 0.0
                         ? x->valuedouble
                         : prior; /* a cached part: as if made */
    parts += R->asm_part[p];
  }
  R->asm_rest = prior;
  if (same) { /* the total after the runs, less the parts: the pages */
    const double rest = vsph_json_get_number(o, "wall_total_s", NAN) -
                        vsph_json_get_number(o, "runs_wall_s", NAN) - parts;
    if (isfinite(rest) && rest >= 0.0) R->asm_rest = rest;
  }
  total = parts + R->asm_rest;
  cJSON_Delete(o);
  return total;
}

/* Run what the plan misses, as the mode says. */
static int run_missing(struct vsph_report *R,
                       const struct vsph_report_props *rp) {
  if (rp->mode == VSPH_REPORT_POOL)
    return vsph_jobs_pool_run(&R->runs.jobs, rp->exe, rp->jobs, rp->threads);
  return vsph_jobs_local_run(&R->runs.jobs, omp_get_max_threads());
}

/* The assembly alone: every run must be there (checked before anything
 * is written). */
static int all_cached(const struct vsph_report *R) {
  size_t m = 0, first = 0;
  for (size_t k = 0; k < R->runs.jobs.n; k++) /* as the plan found them */
    if (!R->runs.jobs.job[k].cached && !R->runs.jobs.job[k].from[0] && !m++)
      first = k;
  if (!m) return VSPH_OK;
  struct stat bs; /* the rule's rows of now: the source tree's top folder */
  if (R->runs.unjudged && stat("reports/baseline.csv", &bs) != 0)
    VSPH_FAIL(VSPH_EIO,
              "%zu of the %zu runs are missing, %zu of them unjudged in the "
              "archive %s: there is no reports/baseline.csv here, whose rows "
              "judge them (run it in the source tree's top folder, as make "
              "full-report does)",
              m, R->runs.jobs.n, R->runs.unjudged, R->runs.archive);
  if (R->runs.unjudged) /* an assembly from an archive without its history */
    VSPH_FAIL(VSPH_EIO,
              "%zu of the %zu runs are missing, %zu of them unjudged in the "
              "archive %s (their commit's baseline rows are not known: "
              "VSPH_ARCHIVE_HISTORY names scripts/source-commits' folder; "
              "make full-report sets it)",
              m, R->runs.jobs.n, R->runs.unjudged, R->runs.archive);
  /* a seal broken by a file: name it, in the archive's entry it would
   * have been read from, or in the report's own folder */
  const struct vsph_jobs_job *j = &R->runs.jobs.job[first];
  char why[700];
  const char *slash = strrchr(j->dir, '/');
  if (R->runs.archive &&
      vsph_archive_entry_damage(R->runs.archive, slash ? slash + 1 : j->dir,
                                why, sizeof why))
    VSPH_FAIL(VSPH_EIO,
              "%zu of the %zu runs are missing; the first, %s, has an entry "
              "in the archive %s whose seal is broken (%s): restore the "
              "entry (git checkout %s) or run it (vsph report --jobs N)",
              m, R->runs.jobs.n, slash ? slash + 1 : j->dir, R->runs.archive,
              why, R->runs.archive);
  if (vsph_folder_verify(j->dir,
                         j->kind == VSPH_JOBS_RUN ? &vsph_folder_scene_run
                                                  : &vsph_folder_shear_test,
                         j->key, NULL, why, sizeof why) < 0)
    VSPH_FAIL(VSPH_EIO,
              "%zu of the %zu runs are missing, unfinished or damaged (the "
              "first: %s): rerun them (vsph report --jobs N, or vsph report "
              "submit); only they run",
              m, R->runs.jobs.n, why);
  VSPH_FAIL(VSPH_EIO,
            "%zu of the %zu runs are missing or unfinished (the first: %s; "
            "a failed or cancelled task?): submit again (vsph report "
            "submit) or run them (vsph report --jobs N); only they run",
            m, R->runs.jobs.n, j->dir);
}

int vsph_report_plan_jobs(const char *dir, int full, struct vsph_jobs *jobs) {
  struct vsph_report *R = calloc(1, sizeof *R);
  if (!R) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the report");
  R->dir = R->runs.jobs.dir = dir;
  R->runs.full = R->runs.jobs.full = full;
  R->runs.jobs.planned = 1;
  const unsigned long all = (1ul << NPARTS) - 1;
  const int st = plan(R, all);
  if (st)
    vsph_jobs_plan_free(&R->runs.jobs);
  else
    *jobs = R->runs.jobs;
  free(R);
  return st;
}

int vsph_report_plan_judge(const struct vsph_jobs *jobs,
                           const struct vsph_archive_judge *base,
                           struct vsph_archive_judge *jd) {
  const char **names = calloc(jobs->n + 1, sizeof *names);
  const char **keys = calloc(jobs->n + 1, sizeof *keys);
  if (!names || !keys) {
    free(names);
    free(keys);
    VSPH_FAIL(VSPH_ENOMEM, "cannot list the plan");
  }
  for (size_t k = 0; k < jobs->n; k++) {
    const char *slash = strrchr(jobs->job[k].dir, '/');
    names[k] = slash ? slash + 1 : jobs->job[k].dir;
    keys[k] = jobs->job[k].key ? jobs->job[k].key : "";
  }
  *jd = *base;
  jd->nplan = jobs->n;
  jd->plan_name = names;
  jd->plan_key = keys;
  return VSPH_OK;
}

void vsph_report_plan_judge_free(struct vsph_archive_judge *jd) {
  free((void *)jd->plan_name);
  free((void *)jd->plan_key);
  jd->plan_name = jd->plan_key = NULL;
  jd->nplan = 0;
}

/* The planned runs that stand in rp->from_archive and are not cached:
 * read from their entries there. */
static int read_archived(struct vsph_report *R, const char *adir,
                         const int *stands) {
  for (size_t k = 0; k < R->runs.jobs.n; k++) {
    struct vsph_jobs_job *j = &R->runs.jobs.job[k];
    if (j->here && !R->runs.full) continue; /* a quick report makes it */
    R->runs.unjudged += !j->cached && stands[k] == VSPH_ARCHIVE_UNJUDGED;
    if (j->cached || stands[k] != VSPH_ARCHIVE_STANDS) continue;
    const char *slash = strrchr(j->dir, '/');
    if (!vsph_archive_entry(adir, slash ? slash + 1 : j->dir, j->from,
                            sizeof j->from, &j->from_key))
      VSPH_FAIL(VSPH_EIO, "cannot read the entry of %s in %s", j->dir, adir);
    R->runs.from_archive++;
  }
  R->runs.archive = adir;
  return VSPH_OK;
}

/* Mark the planned runs that stand in rp->skip_archive: they are not run
 * (a FULL sitting goes on from the archive, whatever build made it); or,
 * assembling from rp->from_archive, read them from there. */
static int mark_archived(struct vsph_report *R,
                         const struct vsph_report_props *rp) {
  struct vsph_archive_judge jd;
  int st = vsph_report_plan_judge(&R->runs.jobs, rp->judge, &jd);
  if (st) return st;
  int *stands = calloc(R->runs.jobs.n + 1, sizeof *stands);
  if (!stands) {
    vsph_report_plan_judge_free(&jd);
    VSPH_FAIL(VSPH_ENOMEM, "cannot list the plan");
  }
  const char *adir = rp->from_archive ? rp->from_archive : rp->skip_archive;
  st = vsph_archive_standing(adir, &jd, stands);
  for (size_t k = 0; !st && k < R->runs.jobs.n; k++)
    R->runs.jobs.job[k].archived = stands[k] == VSPH_ARCHIVE_STANDS &&
                                   !R->runs.jobs.job[k].cached &&
                                   (rp->full || !R->runs.jobs.job[k].here);
  if (!st && rp->from_archive) st = read_archived(R, adir, stands);
  free(stands);
  vsph_report_plan_judge_free(&jd);
  return st;
}

/* Before the parts: the folder locked and unsealed, then the missing
 * runs made (unless only assembling, which checks they are all cached). */
static int make_runs(struct vsph_report *R, const struct vsph_report_props *rp,
                     const char *parts_dir) {
  int st = VSPH_OK;
  if (rp->mode == VSPH_REPORT_ASSEMBLE) st = all_cached(R);
  if (!st) st = lock_dir(R, rp->dir);
  if (!st) st = vsph_files_mkdir(parts_dir);
  char seal_path[700]; /* nothing vouches for the folder while it changes */
  snprintf(seal_path, sizeof seal_path, "%s/key.txt", rp->dir);
  if (!st && remove(seal_path) != 0 && errno != ENOENT) {
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot remove %s: %s",
                       seal_path, strerror(errno));
    st = VSPH_EIO;
  }
  R->runs.made_by = rp->mode == VSPH_REPORT_POOL ? "child processes"
                    : rp->mode == VSPH_REPORT_ASSEMBLE
                        ? "nothing: assembly only"
                        : "this process";
  if (!st && rp->mode != VSPH_REPORT_ASSEMBLE) {
    for (size_t k = 0; k < R->runs.jobs.n; k++) /* not those read */
      R->runs.made +=
          !R->runs.jobs.job[k].cached && !R->runs.jobs.job[k].from[0];
    const double t_runs = omp_get_wtime();
    R->runs.jobs.after_s = R->asm_rest; /* the assembly: in the time left */
    for (size_t p = 0; p < NPARTS; p++) R->runs.jobs.after_s += R->asm_part[p];
    if (rp->writing) *rp->writing = 1; /* runs stop after a checkpoint */
    st = run_missing(R, rp);
    if (rp->writing) *rp->writing = 0; /* parts: a stop ends at once */
    R->runs.runs_wall = omp_get_wtime() - t_runs;
  }
  return st;
}

/* A budgeted sitting's end: what is cached, archived and left. */
static void say_left(const struct vsph_report *R,
                     const struct vsph_report_props *rp, int st) {
  size_t left = 0, kept = 0;
  for (size_t k = 0; k < R->runs.jobs.n; k++) {
    kept += (size_t)R->runs.jobs.job[k].archived;
    left += !R->runs.jobs.job[k].cached && !R->runs.jobs.job[k].archived;
  }
  if (st == VSPH_OK || st == VSPH_EINTR)
    fprintf(stderr,
            "vsph report: %zu of the %zu runs are cached, %zu stand in "
            "%s (not run again), %zu missing or unfinished (%.0f s of "
            "runs); not assembled\n",
            R->runs.jobs.n - left - kept, R->runs.jobs.n, kept,
            rp->skip_archive ? rp->skip_archive : "no archive", left,
            R->runs.runs_wall);
}

/* The seal, last (runs/folder): the report's key, then each file of the
 * folder's top with its size and CRC-32. */
static int seal(struct vsph_report *R, unsigned long want) {
  char seal[256];
  size_t len = (size_t)snprintf(
      seal, sizeof seal, "vsph %s %s\nreport %s:", VSPH_VERSION,
      vsph_source_hash_id, R->runs.full ? "full" : "quick");
  for (size_t p = 0; p < NPARTS && len < sizeof seal - 40; p++)
    if (want >> p & 1)
      len +=
          (size_t)snprintf(seal + len, sizeof seal - len, " %s", PARTS[p].name);
  snprintf(seal + len, sizeof seal - len, "\n");
  return vsph_folder_seal(&R->folder, seal, NULL);
}

/* Part @p name's text (before its appendix) into @p m without its
 * figures (the image lines and their captions: the pictures stay in the
 * report); 0 when the part is not there. */
static int copy_tables(FILE *m, const char *parts_dir, const char *name) {
  char path[700];
  snprintf(path, sizeof path, "%s/%s.md", parts_dir, name);
  char *text = vsph_files_slurp(path, NULL);
  if (!text) return 0;
  char *mark = strstr(text, "<!-- appendix -->");
  if (mark) *mark = '\0';
  for (char *line = text; *line;) {
    char *end = strchr(line, '\n');
    const size_t n = end ? (size_t)(end - line) + 1 : strlen(line);
    if (strncmp(line, "![", 2) && strncmp(line, "*Figure", 7))
      fwrite(line, 1, n, m);
    line += n;
  }
  fputs("\n", m);
  free(text);
  return 1;
}

/* The archive's summary.md (an assembly from it): the FULL report's
 * claims and convergence tables, and what made them. */
static int archive_summary(const struct vsph_report *R, const char *parts_dir,
                           const char *stamp) {
  char *text = NULL;
  size_t len = 0;
  FILE *m = open_memstream(&text, &len);
  if (!m) VSPH_FAIL(VSPH_ENOMEM, "cannot build the archive's summary");
  fprintf(m,
          "# The FULL report at the papers' resolutions: its claims and "
          "convergence tables\n\n"
          "Assembled %s by `vsph report assemble --full --from-archive "
          "%s` (vsph %s, source hash %s, commit %s): %zu runs, %zu of them "
          "read from this archive's entries (each still standing for this "
          "code by the rule of `entries.md`, which names the build that made "
          "it), the other %zu cached in `%s` by this build. The whole report, "
          "with every part and figure, is `%s/report.html`; it is not kept "
          "here. A verdict below is at the papers' resolutions and end times "
          "where the FULL plan has them (the report's section on each "
          "scene says which).\n\n",
          stamp, R->runs.archive, VSPH_VERSION, vsph_source_hash_id,
          vsph_commit_id[0] ? vsph_commit_id : "unknown", R->runs.jobs.n,
          R->runs.from_archive, R->runs.jobs.n - R->runs.from_archive, R->dir,
          R->dir);
  const int claims = copy_tables(m, parts_dir, "claims");
  const int conv = copy_tables(m, parts_dir, "convergence");
  if (fclose(m) != 0) {
    free(text);
    VSPH_FAIL(VSPH_ENOMEM, "cannot build the archive's summary");
  }
  int st = VSPH_OK;
  if (claims || conv) st = vsph_archive_write_summary(R->runs.archive, text);
  free(text);
  if (!st && (claims || conv))
    fprintf(stderr, "vsph report: wrote %s/summary.md\n", R->runs.archive);
  return st;
}

/* The parts, then report.md and report.html, run.json and the seal. */
static int write_parts(struct vsph_report *R, unsigned long want,
                       const char *parts_dir, double t_all) {
  int st = VSPH_OK;
  R->wo = gsl_integration_workspace_alloc(1000);
  R->wi = gsl_integration_workspace_alloc(1000);
  if (!R->wo || !R->wi) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot allocate workspaces");
  }
  double wall[NPARTS] = {0};
  int cached[NPARTS] = {0};
  char key[128];
  snprintf(key, sizeof key, "vsph %s %s, %s\n", VSPH_VERSION,
           vsph_source_hash_id, R->runs.full ? "full" : "quick");
  const int claims = vsph_report_part_find("claims");
  if (!st && R->beside && (want >> claims & 1))
    st = vsph_report_beside_prepare(R);
  for (size_t p = 0; p < NPARTS && !st; p++)
    if (want >> p & 1) {
      double left = R->asm_rest; /* this part's and the later ones' */
      for (size_t q = p; q < NPARTS; q++) left += R->asm_part[q];
      st = run_part(R, p, left, parts_dir, key, &cached[p], &wall[p]);
    }
  vsph_report_beside_free(R);
  /* the baseline comes with the scenes part (its coarsest runs) */
  const int scenes = vsph_report_part_find("scenes");
  if (!st && (want >> scenes & 1) && !R->runs.scenes) st = write_baseline(R);
  const time_t now = time(NULL);
  char stamp[64];
  strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
  if (!st) st = assemble(R, parts_dir, want, cached, wall, stamp);
  if (!st)
    st = write_run_json(R, want, cached, wall, stamp, omp_get_wtime() - t_all);
  if (!st) st = seal(R, want);
  if (!st)
    fprintf(stderr,
            "vsph report: wrote %s/report.md and report.html (%.0f s)\n",
            R->dir, omp_get_wtime() - t_all);
  if (!st && R->runs.archive && R->runs.full)
    st = archive_summary(R, parts_dir, stamp);
  return st;
}

int vsph_report_write(const struct vsph_report_props *rp) {
  const unsigned long all = (1ul << NPARTS) - 1;
  const unsigned long want = rp->parts ? rp->parts & all : all;
  char parts_dir[600];
  snprintf(parts_dir, sizeof parts_dir, "%s/parts", rp->dir);
  struct vsph_report *R = calloc(1, sizeof *R);
  if (!R) VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the report");
  R->folder.fd = -1; /* no claim yet */
  R->dir = rp->dir;
  R->runs.full = rp->full;
  R->runs.scenes = rp->scenes;
  R->runs.stop = rp->stop;
  R->beside = rp->beside;
  R->judge = rp->judge;
  const double t_all = omp_get_wtime();
  vsph_sysinfo_load(R->load[0]);
  /* the finite-volume references first: a damaged file stops the report
   * before it writes anything */
  R->fv = malloc(sizeof *R->fv);
  if (!R->fv) {
    free(R);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate the finite-volume references");
  }
  int st = vsph_fvref_read(rp->fv, R->fv);
  if (st) {
    report_free(R);
    return st;
  }
  char why[512];
  if (vsph_fvref_check(R->fv, why, sizeof why)) {
    /* held to what is known of them exactly (make check does the same):
     * a reference that fails is not graded against */
    fprintf(stderr,
            "vsph report: the finite-volume references in %s fail their own "
            "checks (%s): the rows that need them say not tested\n",
            rp->fv, why);
    R->fv->sq.ok = R->fv->cav[0].ok = R->fv->cav[1].ok = 0;
  }
  char absdir[600];
  if (rp->mode == VSPH_REPORT_SLURM) { /* every path absolute */
    st = vsph_jobs_slurm_dir(rp->dir, absdir, sizeof absdir);
    R->dir = absdir;
  }
  R->runs.jobs.dir = R->dir;
  R->runs.jobs.full = R->runs.full;
  R->runs.jobs.stop = R->runs.stop;
  R->runs.jobs.planned = 1;
  R->runs.jobs.budget_s = rp->budget_s;
  if (!st) st = plan(R, want);
  if (!st && (rp->skip_archive || rp->from_archive)) st = mark_archived(R, rp);
  if (!st && rp->mode == VSPH_REPORT_PLAN) { /* writes nothing */
    st = vsph_jobs_plan_print(&R->runs.jobs, rp->exe ? rp->exe : "vsph",
                              rp->plan_out);
    vsph_jobs_plan_free(&R->runs.jobs);
    report_free(R);
    return st;
  }
  if (!st && rp->mode == VSPH_REPORT_SLURM) st = lock_dir(R, R->dir);
  if (!st && rp->mode == VSPH_REPORT_SLURM) {
    const struct vsph_jobs_slurm s = {rp->exe, rp->partition, rp->time,
                                      rp->threads, rp->only};
    st = vsph_jobs_slurm_submit(&R->runs.jobs, &s);
    vsph_jobs_plan_free(&R->runs.jobs);
    report_free(R);
    return st;
  }
  if (!st) assembly_estimate(R, want); /* before run.json is replaced */
  if (!st) st = make_runs(R, rp, parts_dir);
  if (rp->budget_s > 0.0) { /* runs only: say what is left */
    say_left(R, rp, st);
    vsph_jobs_plan_free(&R->runs.jobs);
    report_free(R);
    return st;
  }
  if (!st) st = write_parts(R, want, parts_dir, t_all);
  gsl_integration_workspace_free(R->wo);
  gsl_integration_workspace_free(R->wi);
  free(R->claims);
  vsph_jobs_plan_free(&R->runs.jobs);
  report_free(R);
  return st;
}
