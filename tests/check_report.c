/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The report's frame: the claims table's verdict classes and their
 * tally (reports/report_claims.c), counted here independently of the
 * writer; the estimate of the time left (runs/jobs.c), worked
 * by hand. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../io/files.h"
#include "../io/json.h"
#include "../reports/bench.h"
#include "../reports/report.h"
#include "../reports/report_claims.h"
#include "../reports/report_parts.h"
#include "../reports/report_runs.h"
#include "../runs/folder.h"
#include "../runs/jobs_internal.h"
#include "../runs/shell.h"
#include "../solver/scene.h"
#include "../solver/viscous.h"
#include "check_suites.h"

/* The scenes' names: one list, the ladders'. The quick and the FULL
 * ladder name the same scenes in the same order, and each is a scene the
 * solver knows. */
START_TEST(test_scene_names) {
  struct vsph_report R;
  memset(&R, 0, sizeof R);
  R.runs.full = 1;
  for (int sc = 0; sc < VSPH_REPORT_NSCENES; sc++) {
    const char *q = vsph_report_runs_ladder(&R.runs, sc, 1)->scene;
    const char *f = vsph_report_runs_ladder(&R.runs, sc, 0)->scene;
    ck_assert_str_eq(q, f);
    ck_assert_str_eq(vsph_report_scene_name((size_t)sc), q);
    ck_assert_ptr_nonnull(vsph_scene_find(q));
  }
  ck_assert_ptr_null(vsph_report_scene_name(VSPH_REPORT_NSCENES));
}
END_TEST

/* Each verdict form the claims code writes falls in its class (the rule
 * of docs/theory.md section 13: "reproduced on a substitute" is its own
 * class, not "reproduced"). */
START_TEST(test_verdict_classes) {
  static const struct {
    const char *verdict;
    int cls;
  } cases[] = {
      {"reproduced (within 3 %)", VSPH_REPORT_REPRODUCED},
      {"reproduced at this resolution", VSPH_REPORT_REPRODUCED},
      {"reproduced on a substitute: Adami's walls", VSPH_REPORT_SUBSTITUTE},
      {"reproduced on a substitute", VSPH_REPORT_SUBSTITUTE},
      {"reproduced on a", VSPH_REPORT_REPRODUCED},
      {"partly: within 8 %", VSPH_REPORT_PARTLY},
      {"partly, at H/dx = 80: MEAF fails", VSPH_REPORT_PARTLY},
      {"not reproduced at H/dx = 80", VSPH_REPORT_DIFFERS},
      {"differs by construction", VSPH_REPORT_DIFFERS},
      {"differs: the reference differs by 6 points", VSPH_REPORT_DIFFERS},
      {"ranking reproduced", -1}, /* no class word first: refused */
      {"the reference differs", -1},
      {"not tested: the cavity needs wall particles", VSPH_REPORT_NOT_TESTED}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++)
    ck_assert_msg(vsph_report_doc_class(cases[k].verdict) == cases[k].cls,
                  "'%s' classed %d, not %d", cases[k].verdict,
                  vsph_report_doc_class(cases[k].verdict), cases[k].cls);
  /* the claims table takes no verdict without its class word first */
  struct vsph_report R;
  memset(&R, 0, sizeof R);
  vsph_test_silence();
  ck_assert_int_ne(
      vsph_report_doc_claim(&R, "c", "p", "o", "none", "ranking reproduced"),
      0);
  /* nor a row that says nothing of its set-up */
  ck_assert_int_ne(vsph_report_doc_claim(&R, "c", "p", "o", "", "reproduced"),
                   0);
  ck_assert_int_ne(vsph_report_doc_claim(&R, "c", "p", "o", NULL, "reproduced"),
                   0);
  /* nor one whose text would be cut short: its ours one character past
   * the table's room, then just within it (the row is taken) */
  char ours[sizeof R.claims->ours + 1];
  memset(ours, 'x', sizeof ours - 1);
  ours[sizeof ours - 1] = '\0';
  ck_assert_int_ne(vsph_report_doc_claim(&R, "c", "p", ours, "none", "partly"),
                   0);
  ck_assert_uint_eq(R.nclaims, 0);
  ours[sizeof ours - 2] = '\0';
  ck_assert_int_eq(vsph_report_doc_claim(&R, "c", "p", ours, "none", "partly"),
                   0);
  ck_assert_uint_eq(R.nclaims, 1);
  ck_assert_str_eq(R.claims[0].ours, ours);
  free(R.claims);
}
END_TEST

/* Count the occurrences of @p needle in @p hay. */
static size_t count(const char *hay, const char *needle) {
  size_t n = 0;
  for (const char *p = strstr(hay, needle); p; p = strstr(p + 1, needle)) n++;
  return n;
}

/* The tally line counts each class, and every row carries its class's
 * mark once, in the verdict cell, before the verdict's own words. */
/* A prose value too long for its room is refused, and the block that
 * uses it is not written with the cut text; a short one goes in whole. */
START_TEST(test_text_value_room) {
  static struct vsph_text_vars tv; /* 24 KiB: not on the stack */
  char big[sizeof tv.val[0] + 1], out[4096];
  memset(big, 'x', sizeof big - 1);
  big[sizeof big - 1] = '\0';
  vsph_text_clear(&tv);
  vsph_test_silence();
  ck_assert_int_ne(vsph_text_set(&tv, "swread", "%s", big), 0);
  ck_assert_int_ne(
      vsph_text_format(out, sizeof out, "channel.sweep_reading", &tv), 0);
  ck_assert_int_eq(vsph_text_set(&tv, "swread", "%s", "short"), 0);
  ck_assert_int_eq(
      vsph_text_format(out, sizeof out, "channel.sweep_reading", &tv), 0);
  ck_assert_str_eq(out, "Reading: short");
}
END_TEST

START_TEST(test_claims_tally) {
  static const char *const verdicts[] = {
      "reproduced (within 3 %)",   "reproduced at this resolution",
      "partly: see section 11",    "not reproduced at H/dx = 80",
      "differs: E is closer",      "reproduced on both layouts",
      "not tested: no run",        "reproduced on a substitute: 2-D",
      "reproduced on a substitute"};
  const size_t n = sizeof verdicts / sizeof verdicts[0];
  struct vsph_report R;
  memset(&R, 0, sizeof R);
  R.claim_see = "scenes";
  for (size_t k = 0; k < n; k++) {
    /* the second row is a claim the first screen names
     * (reports/text/claims.md, findings) */
    R.claim_name = k == 1 ? "paper.surface_slopes" : NULL;
    ck_assert_int_eq(vsph_report_doc_claim(
                         &R, k == 1 ? "the finding" : "a claim | with a bar",
                         "paper", "ours", "its set-up | differs", verdicts[k]),
                     0);
  }
  R.md = tmpfile();
  ck_assert_ptr_nonnull(R.md);
  ck_assert_int_eq(vsph_report_doc_claims_table(&R), 0);
  const long len = ftell(R.md);
  char *text = calloc((size_t)len + 1, 1);
  rewind(R.md);
  ck_assert_uint_eq(fread(text, 1, (size_t)len, R.md), (size_t)len);
  fclose(R.md);
  /* the tally, counted by hand from verdicts[] above: 3 reproduced,
   * 2 on a substitute, 1 partly, 2 differ, 1 not tested */
  ck_assert_msg(strstr(text, "**9 claims:**") != NULL, "%s", text);
  ck_assert_msg(strstr(text, "3 reproduced</span>") != NULL, "%s", text);
  ck_assert_msg(strstr(text, "2 reproduced on a substitute</span>") != NULL,
                "%s", text);
  ck_assert_msg(strstr(text, "1 partly</span>") != NULL, "%s", text);
  ck_assert_msg(strstr(text, "2 differs</span>") != NULL, "%s", text);
  ck_assert_msg(strstr(text, "1 not tested</span>") != NULL, "%s", text);
  /* one row per claim, its verdict marked once: the two tallies (the
   * first screen's and the table's) have one mark of each class each,
   * the finding one more (its "reproduced at this resolution"), the rows
   * the rest */
  ck_assert_uint_eq(count(text, "| a claim \\| with a bar |"), n - 1);
  ck_assert_uint_eq(count(text, "class=\"v v-rep\""), 2 + 1 + 3);
  ck_assert_uint_eq(count(text, "class=\"v v-sub\""), 2 + 2);
  /* the set-up column, its bar escaped, in every row */
  ck_assert_uint_eq(count(text, "| its set-up \\| differs |"), n);
  ck_assert_uint_eq(count(text, "class=\"v v-part\""), 2 + 1);
  ck_assert_uint_eq(count(text, "class=\"v v-diff\""), 2 + 2);
  ck_assert_uint_eq(count(text, "class=\"v v-none\""), 2 + 1);
  /* the first screen: between its marks, the finding with its verdict
   * and section, before the table */
  const char *f0 = strstr(text, "<!-- findings -->"),
             *f1 = strstr(text, "<!-- /findings -->");
  ck_assert_msg(f0 && f1 && f0 < f1, "%s", text);
  const char *fd = strstr(f0, "1. the finding: <span class=\"v v-rep\">");
  ck_assert_msg(fd && fd < f1 && strstr(fd, "at this resolution ([scenes]"),
                "%s", text);
  ck_assert_ptr_null(strstr(fd, "2. "));
  ck_assert(strstr(text, "differs</span> not reproduced at H/dx = 80 |"));
  /* the class's own word once: "reproduced (within 3 %)" -> the mark and
   * "(within 3 %)"; "partly: see ..." -> the mark and "see ..." */
  ck_assert_msg(strstr(text, "reproduced</span> (within 3 %) |"), "%s", text);
  ck_assert_msg(strstr(text, "partly</span> see section 11 |"), "%s", text);
  ck_assert_msg(strstr(text, "differs</span> E is closer |"), "%s", text);
  ck_assert_msg(strstr(text, "reproduced on a substitute</span> 2-D |"), "%s",
                text);
  free(text);
  free(R.claims);
}
END_TEST

/* The time left of the report's runs, worked by hand, with a step's work
 * beyond its pairs S = VSPH_JOBS_STEP_WORK = 2e4 pair interactions. A
 * run's work is cost (1 + S/per_step): family A's two finished runs, cost
 * 2e4 at 2e4 a step (work 4e4) in 4 s and 4e4 at 4e4 a step (6e4) in 6 s,
 * 1e-4 s a unit; B's, 6e4 at 2e4 a step (three steps, 12e4) in 6 s, 5e-5;
 * C none: every finished run's 16 s over 22e4, 8e-4/11. */
START_TEST(test_time_left) {
  ck_assert_double_eq(VSPH_JOBS_STEP_WORK, 2e4); /* the figures below */
  enum { D = VSPH_JOBS_ETA_DONE, R = VSPH_JOBS_ETA_RUNNING };
  enum { W = VSPH_JOBS_ETA_WAITING };
  struct vsph_jobs_eta r[] = {
      {.cost = 2e4, .wall = 4, .state = D, .family = "A", .per_step = 2e4},
      {.cost = 4e4, .wall = 6, .state = D, .family = "A", .per_step = 4e4},
      {.cost = 6e4, .wall = 6, .state = D, .family = "B", .per_step = 2e4},
      /* two steps: 6e4 units at A's rate, 6 s, 1 s of them run */
      {.cost = 2e4, .wall = 1, .state = R, .family = "A", .per_step = 1e4},
      /* one step: 3e4 units at every run's rate, 24/11 s */
      {.cost = 1e4, .state = W, .family = "C", .per_step = 1e4},
      /* its steps not known: its pairs alone, 1e4 units, 1 s */
      {.cost = 1e4, .state = W, .family = "A", .per_step = 0},
      /* one step: 4e4 units at B's rate, 2 s */
      {.cost = 2e4, .state = W, .family = "B", .per_step = 2e4},
      /* failed: cost 0, measures nothing */
      {.cost = 0, .wall = 9, .state = D, .family = "C", .per_step = 1e4},
  };
  /* one lane: 5 + 24/11 + 1 + 2; two: the running run holds one (5 s),
   * C, A's and B's the other (24/11 + 3 s) */
  ck_assert_double_eq_tol(vsph_jobs_local_eta(r, 8, 1), 8 + 24.0 / 11, 1e-12);
  ck_assert_double_eq_tol(vsph_jobs_local_eta(r, 8, 2), 3 + 24.0 / 11, 1e-12);
  /* a running run past its estimate has nothing left, not less */
  r[3].wall = 9.0;
  ck_assert_double_eq_tol(vsph_jobs_local_eta(r, 8, 1), 3 + 24.0 / 11, 1e-12);
  /* the text: the work after the runs (a report's assembly, 30 s) is in
   * the time left, and said (the running run's time from its start 9 s
   * before now) */
  char buf[128];
  const double t1[8] = {0, 0, 0, 1.0, 0, 0, 0, 0};
  vsph_jobs_local_eta_text(r, t1, 8, 1, 10.0, 30.0, buf, sizeof buf);
  ck_assert_str_eq(buf, ", about 35 s left (30 s of them after the runs)");
  vsph_jobs_local_eta_text(r, t1, 8, 1, 10.0, 0.0, buf, sizeof buf);
  ck_assert_str_eq(buf, ", about 5 s left");
  /* nothing finished: no rate measured, no estimate */
  r[0].state = r[1].state = r[2].state = VSPH_JOBS_ETA_WAITING;
  ck_assert(vsph_jobs_local_eta(r, 8, 2) < 0.0);
}
END_TEST

/* The one shell-quoting rule (runs/shell.c) of the plan's commands,
 * the Slurm scripts and run.json's command: each case written out by hand
 * as POSIX sh reads it back. */
START_TEST(test_shell_quote) {
  static const char *const cases[][2] = {
      {"abc-1.5_x/y:z=w,@%+", "abc-1.5_x/y:z=w,@%+"},
      {"", "''"},
      {"a b", "'a b'"},
      {"quo'te", "'quo'\\''te'"},
      {"$HOME", "'$HOME'"},
      {"a\nb", "'a\nb'"}};
  char out[64];
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    const size_t n = vsph_shell_quote(cases[k][0], out, sizeof out);
    ck_assert_str_eq(out, cases[k][1]);
    ck_assert_uint_eq(n, strlen(cases[k][1]));
  }
  /* cut to fit, as snprintf: the length it needs, a NUL-terminated prefix */
  ck_assert_uint_eq(vsph_shell_quote("quo'te", out, 4), 11);
  ck_assert_str_eq(out, "'qu");
}
END_TEST

/* run.json's command reads back, through a shell, as the arguments given:
 * an --out with a quote and a space (its quotes were unbalanced). */
START_TEST(test_command_reads_back) {
  const char *const dir = "/tmp/vsph_quo'te dir";
  struct vsph_test_outcome *o = vsph_test_cli(
      "run poiseuille --t-end 1e-9 --quiet --out \"/tmp/vsph_quo'te dir\"");
  ck_assert_msg(o->status == 0, "%s", o->err);
  char path[128];
  snprintf(path, sizeof path, "%s/run.json", dir);
  cJSON *js = vsph_json_read(path);
  ck_assert_ptr_nonnull(js);
  const cJSON *c = cJSON_GetObjectItemCaseSensitive(js, "command");
  ck_assert(cJSON_IsString(c));
  /* the shell splits it back: the 8th word is the folder */
  char script[512];
  snprintf(script, sizeof script, "eval \"set -- %s\"; printf '%%s' \"$8\"",
           c->valuestring);
  cJSON_Delete(js);
  FILE *p = fopen("/tmp/vsph_readback.sh", "w");
  ck_assert_ptr_nonnull(p);
  fputs(script, p);
  ck_assert_int_eq(fclose(p), 0);
  o = vsph_test_shell("sh /tmp/vsph_readback.sh");
  ck_assert_str_eq(o->out, dir);
  remove("/tmp/vsph_readback.sh");
  o = vsph_test_shell("rm -r \"/tmp/vsph_quo'te dir\"");
  ck_assert_int_eq(o->status, 0);
}
END_TEST

/* The table of vsph_report_claims_beside for R, quick runs @p run with
 * errors @p err, as text (free it). */
static char *beside_text(struct vsph_report *R,
                         struct vsph_jobs_run run[][VSPH_VISCOUS_PAPER_COUNT],
                         double err[][VSPH_VISCOUS_PAPER_COUNT]) {
  R->md = tmpfile();
  ck_assert_ptr_nonnull(R->md);
  ck_assert_int_eq(vsph_report_beside_prepare(R), 0);
  ck_assert_int_eq(
      vsph_report_claims_beside(
          R, (const struct vsph_jobs_run(*)[VSPH_VISCOUS_PAPER_COUNT])run,
          (const double(*)[VSPH_VISCOUS_PAPER_COUNT])err),
      0);
  vsph_report_beside_free(R);
  const long len = ftell(R->md);
  char *text = calloc((size_t)len + 1, 1);
  rewind(R->md);
  ck_assert_uint_eq(fread(text, 1, (size_t)len, R->md), (size_t)len);
  fclose(R->md);
  R->md = NULL;
  return text;
}

/* The summary's table of the paper's resolutions (report_claims.c): an
 * archived FULL run (the standing wave with MGF at H/dx = 240, sealed
 * under its FULL plan key, its energy table made by hand) is shown with
 * its figures, computed here by hand from its rows, and judged to stand
 * (made by these sources, its scene's rows in today's baseline); every
 * other scene and formulation says it is not archived yet; once the
 * baseline lacks its scene's rows (unjudged) it does not stand; once a
 * file of the entry changed after its seal it is not read at all. */
START_TEST(test_claims_beside) {
  char dir[] = "/tmp/vsph_besideXXXXXX", path[700], ar[600], rep[600],
       base[600];
  ck_assert_ptr_nonnull(mkdtemp(dir));
  snprintf(rep, sizeof rep, "%s/rep", dir);
  snprintf(ar, sizeof ar, "%s/ar", dir);
  struct vsph_jobs jobs;
  memset(&jobs, 0, sizeof jobs);
  ck_assert_int_eq(vsph_report_plan_jobs(rep, 1, &jobs), 0);
  const char *key = NULL;
  for (size_t k = 0; k < jobs.n; k++)
    if (!strcmp(strrchr(jobs.job[k].dir, '/') + 1, "standing-wave-mgf-240"))
      key = jobs.job[k].key;
  ck_assert_ptr_nonnull(key);
  snprintf(path, sizeof path, "%s/empty/runs", dir);
  ck_assert_int_eq(vsph_files_mkdir(path), 0);
  snprintf(path, sizeof path, "%s/empty", dir);
  struct vsph_archive_counts n;
  ck_assert_int_eq(vsph_archive_store(path, ar, NULL, NULL, &n), 0);
  snprintf(path, sizeof path, "%s/runs/standing-wave-mgf-240", ar);
  struct vsph_folder f;
  ck_assert_int_eq(vsph_folder_claim(&f, path, &vsph_folder_scene_run), 0);
  ck_assert_int_eq(
      vsph_files_write(path, "run.json",
                       "{\"scene\": \"standing-wave\", \"status\": \"ok\"}\n"),
      0);
  ck_assert_int_eq(
      vsph_files_write(path, "energy.csv",
                       "t,Ek,Ep,Ec,P_visc,residual,dEk_dt,Ek_ref,dEk_ref,"
                       "Em_ref,dEm_ref\n"
                       "0,2,1,0,-1,0,-1,2,-1,3,-1\n"
                       "4,1.5,0.9,0,-1,0,-1,1.8,-1,2.7,-1\n"
                       "8,1,0.8,0,-1,0,-1,1.2,-1,2.4,-1\n"),
      0);
  ck_assert_int_eq(vsph_folder_seal(&f, key, NULL), 0);
  vsph_folder_release(&f);
  vsph_jobs_plan_free(&jobs);
  snprintf(base, sizeof base, "%s/baseline.csv", dir);
  FILE *b = fopen(base, "w");
  ck_assert_ptr_nonnull(b);
  fputs("scene,visc\nstanding-wave,mgf\n", b);
  ck_assert_int_eq(fclose(b), 0);
  /* the quick runs: two rows each, all alike */
  static const double t[2] = {0, 3}, Ek[2] = {1, 0.5}, z[2] = {0, 0},
                      m1[2] = {-1, -1}, Em[2] = {1, 0.8};
  struct vsph_jobs_run run[VSPH_REPORT_NSCENES][VSPH_VISCOUS_PAPER_COUNT];
  double err[VSPH_REPORT_NSCENES][VSPH_VISCOUS_PAPER_COUNT];
  memset(run, 0, sizeof run);
  for (int sc = 0; sc < VSPH_REPORT_NSCENES; sc++)
    for (int k = 0; k < VSPH_VISCOUS_PAPER_COUNT; k++) {
      struct vsph_jobs_run *r = &run[sc][k];
      r->ok = 1;
      r->nrow = 2;
      r->t = t;
      r->Ek = r->Ekr = Ek;
      r->Ep = r->Ec = r->res_b = z;
      r->Pv = r->dEk = r->dEkr = r->dEmr = m1;
      r->Emr = Em;
      err[sc][k] = 0.0123;
    }
  run[2][1].ok = 0; /* the wave with MEAF stopped, as unstable, at 2.5 s */
  run[2][1].t_unstable = 2.5;
  const struct vsph_archive_judge jd = {.baseline = base};
  struct vsph_report R;
  memset(&R, 0, sizeof R);
  R.dir = rep;
  R.beside = ar;
  R.judge = &jd;
  for (int pass = 0; pass < 2; pass++) {
    char *text = beside_text(&R, run, err);
    /* by hand: energy lost by t = 8, (2 + 1 - 1 - 0.8)/2 = 0.6, over
     * Lighthill's 1 - 2.4/3 = 0.2: 3.000; the E_k error, the largest
     * |Ek/Ek(0) - Ek_ref/Ek_ref(0)|: |0.75 - 0.9| = 0.15 at t = 4. The
     * quick run's: (1 - 0.5)/1 over 1 - 0.8/1, 2.500; its error as given */
    ck_assert_msg(strstr(text,
                         "| standing-wave | MGF | H/dx = 40, t_end 3 s: "
                         "ok to t = 3 s; energy lost over Lighthill's "
                         "2.500, E_k error 1.23e-02 | H/dx = 240, "
                         "t_end 8 s: ok to t = 8 s; energy lost over "
                         "Lighthill's 3.000, E_k error 1.50e-01 |"),
                  "%s", text);
    ck_assert_msg(strstr(text, pass ? "1.50e-01 | unjudged (entries.md says "
                                      "why) |"
                                    : "1.50e-01 | yes |"),
                  "%s", text);
    ck_assert_msg(strstr(text, pass ? "Of the 9, 1 are archived and read: 0 "
                                      "still valid for this code, 0 not, 1 "
                                      "unjudged"
                                    : "Of the 9, 1 are archived and read: 1 "
                                      "still valid for this code, 0 not, 0 "
                                      "unjudged"),
                  "%s", text);
    ck_assert_uint_eq(count(text, "not archived yet | – |"), 8);
    /* a stopped run says how far it got; the square's t = 0 figure of
     * these rows, (-1 - (-1))/1, is exact: round-off */
    ck_assert_msg(strstr(text,
                         "| standing-wave | MEAF | H/dx = 40, t_end 3 "
                         "s: **unstable** at t = 2.5 s; figures by its "
                         "last row, t = 3 s (100 % of t_end);"),
                  "%s", text);
    ck_assert_uint_eq(count(text, "at t = 0: round-off |"), 3);
    free(text);
    /* today's baseline without the scene's rows: unjudged, so it does
     * not stand */
    b = fopen(base, "w");
    ck_assert_ptr_nonnull(b);
    fputs("scene,visc\nvortex-patch,mgf\n", b);
    ck_assert_int_eq(fclose(b), 0);
  }
  /* its energy.csv changed after the seal: not read, not counted */
  snprintf(path, sizeof path, "%s/runs/standing-wave-mgf-240/energy.csv", ar);
  b = fopen(path, "a");
  ck_assert_ptr_nonnull(b);
  fputs("9,9,9,0,-1,0,-1,9,-1,9,-1\n", b);
  ck_assert_int_eq(fclose(b), 0);
  char *text = beside_text(&R, run, err);
  ck_assert_msg(strstr(text,
                       "t_end 8 s: an entry whose seal does not hold: "
                       "not read | – |") &&
                    strstr(text, "Of the 9, 0 are archived and read") &&
                    strstr(text, "1 more entries are there but not read"),
                "%s", text);
  free(text);
  char cmd[700];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  ck_assert_int_eq(system(cmd), 0);
}
END_TEST

/* The two-pass forms' null mode (report_choices.c): the particle-scale
 * checkerboard has no gradient at an interior particle by either first
 * pass, so PVWF's and model B's dissipation of it is a surface share only:
 * the surface rows are 4n of the n^2 particles, so it halves as the square
 * is laid twice as fine (80 against 40 across: 0.5, within 10 % for the
 * corners' and the rows' own lattice effects, measured 0.498 and 0.498),
 * and at 40 across it is below 5 % of MEAF's (measured 2.8 % and 0.8 %:
 * the surface rows' share, about 4/40 of the particles, times how much
 * less they dissipate). MGF's over MEAF's is K/2 <cos^2> = 2
 * exactly: the field is along x, and the lattice's four-fold symmetry
 * makes the weighted mean of cos^2 one half (rounding: 1e-12). */
START_TEST(test_null_mode) {
  double q40, q80;
  const int forms[2] = {VSPH_VISCOUS_PVWF, vsph_viscous_find("twopass")};
  for (int k = 0; k < 2; k++) {
    ck_assert_int_eq(vsph_report_choices_null(40, forms[k], &q40), 0);
    ck_assert_int_eq(vsph_report_choices_null(80, forms[k], &q80), 0);
    ck_assert_double_lt(q40, 0.05);
    ck_assert_double_eq_tol(q80 / q40, 0.5, 0.05);
  }
  ck_assert_int_eq(vsph_report_choices_null(40, VSPH_VISCOUS_MGF, &q40), 0);
  ck_assert_double_eq_tol(q40, 2.0, 1e-12);
}
END_TEST

/* The tensors' table shows entries that vanish by symmetry as 0.00000,
 * never -0.00000 (quadrature and sums give them as tiny values of either
 * sign, vsph_consts_shown): the part made, every table cell read. */
START_TEST(test_tensor_table_no_negative_zero) {
  char dir[] = "/tmp/vsph-tens-XXXXXX", script[4096];
  vsph_test_scratch(dir);
  snprintf(script, sizeof script,
           "\"$VSPH_BIN\" report --only tensors --out '%s/r' > /dev/null && "
           "tr '|' '\\n' < '%s/r/parts/tensors.md' | sed 's/ //g' | "
           "grep -c '^0\\.00000$'; tr '|' '\\n' < '%s/r/parts/tensors.md' | "
           "sed 's/ //g' | grep -c '^-0\\.0*$'",
           dir, dir, dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  long zeros = -1, negative = -1;
  ck_assert_msg(sscanf(o->out, "%ld %ld", &zeros, &negative) == 2,
                "exit %d: %s %s", o->status, o->out, o->err);
  ck_assert_msg(zeros > 0, "no zero cell (the test would see nothing): %s",
                o->out);
  ck_assert_msg(negative == 0, "%ld cells show a negative zero", negative);
  vsph_test_rm_tree(dir);
}
END_TEST

/* Runs stopped as unstable are drawn hollow (issue 45's figure rule):
 * over each stopped point of MGF's curve (filled disc, pt 7) a white disc,
 * then the open circle (pt 6) in MGF's colour; a form whose marker is
 * open already (the seventh, pt 6) is ringed in black instead; one key
 * entry says what hollow means, however many forms have stopped runs.
 * Out of the key, the overlays are titled in the SVG by the hover text
 * given (what a pointer over them reads), none by gnuplot's
 * "fig_h_plot_K". */
START_TEST(test_hollow_stopped_runs) {
  char dir[] = "/tmp/vsph-hollow-XXXXXX", path[200];
  vsph_test_scratch(dir);
  ck_assert_int_eq(vsph_files_write(dir, "s.csv",
                                    "error,wall_s,stable\n1e-2,1,1\n"
                                    "1e-3,2,1\n1e-4,4,0\n"),
                   0);
  struct vsph_plot pl;
  vsph_plot_init(&pl, dir, "fig_h", "hollow", "error", "wall (s)");
  char style[96];
  int said = 0;
  for (int f = 0; f < 7; f += 6) {
    vsph_report_runs_style(style, sizeof style, f, "");
    ck_assert_int_eq(vsph_plot_add(&pl, "s.csv", "1:2", "form", style), 0);
    char hover[32];
    snprintf(hover, sizeof hover, "form %d: stopped", f);
    ck_assert_int_eq(vsph_report_runs_hollow(
                         &pl, "s.csv", "1:($3==0 ? $2 : 1/0)", f, hover, &said),
                     0);
  }
  ck_assert_int_eq(vsph_plot_write(&pl), 0);
  static char gp[1 << 15];
  snprintf(path, sizeof path, "%s/fig_h.gp", dir);
  vsph_test_slurp(path, gp, sizeof gp);
  ck_assert_int_eq(vsph_report_runs_point(0), 7);
  ck_assert_int_eq(vsph_report_runs_point(6), 6);
  static const char *const want[] = {
      "using 1:($3==0 ? $2 : 1/0) with points pt 7 ps 1.2 lc rgb 'white' "
      "title \"\"",
      "using 1:($3==0 ? $2 : 1/0) with points pt 6 lw 2 lc 1 title \"\"",
      "using 1:($3==0 ? $2 : 1/0) with points pt 6 ps 2.5 lw 2 lc rgb "
      "'black' title \"\""};
  for (size_t k = 0; k < sizeof want / sizeof want[0]; k++)
    ck_assert_msg(strstr(gp, want[k]) != NULL, "no '%s' in\n%s", want[k], gp);
  const char *key = strstr(gp, "hollow: stopped as unstable");
  ck_assert_ptr_nonnull(key);
  ck_assert_ptr_null(strstr(key + 1, "hollow: stopped as unstable"));
  /* curves 2 and 3 (white disc, open circle) form 0's, 6 (black ring)
   * form 6's; 1, 4 and 5 keyed */
  static char svg[1 << 16];
  snprintf(path, sizeof path, "%s/fig_h.svg", dir);
  vsph_test_slurp(path, svg, sizeof svg);
  static const char *const hover[] = {
      "<g id=\"fig_h_plot_2\" ><title>form 0: stopped</title>",
      "<g id=\"fig_h_plot_3\" ><title>form 0: stopped</title>",
      "<g id=\"fig_h_plot_6\" ><title>form 6: stopped</title>"};
  for (size_t k = 0; k < sizeof hover / sizeof hover[0]; k++)
    ck_assert_msg(strstr(svg, hover[k]) != NULL, "no '%s' in %s", hover[k],
                  path);
  ck_assert_ptr_null(strstr(svg, "<title>fig_h_plot_"));
  vsph_test_rm_tree(dir);
}
END_TEST

/* The points drawn in SVG group @p id of @p svg (each marker's
 * "translate(x,y)", up to the next curve's group), at most @p max into
 * @p at; returns how many. */
static size_t group_points(const char *svg, const char *id, char at[][40],
                           size_t max) {
  char open[96];
  snprintf(open, sizeof open, "<g id=\"%s\" >", id);
  const char *g = strstr(svg, open);
  ck_assert_msg(g != NULL, "no group %s", id);
  g += strlen(open);
  const char *end = strstr(g, "<g id=\"");
  size_t n = 0;
  for (const char *u = strstr(g, "<use "); u && (!end || u < end);
       u = strstr(u + 1, "<use ")) {
    const char *t = strstr(u, "translate(");
    ck_assert_ptr_nonnull(t);
    if (n < max) snprintf(at[n], sizeof at[n], "%.*s", (int)strcspn(t, ")"), t);
    n++;
  }
  return n;
}

/* A curve of successive differences (rung k against rung k - 1, on row
 * k) is hollow where either run of the pair stopped (issue 45 point 5):
 * with rung 2 of 0..4 stopped, the differences of rows 2 (against the
 * stopped rung) and 3 (from it), the second and third of the curve's
 * four, and no other; the error curve's hollow point alone at row 2; one
 * key entry for both. */
START_TEST(test_hollow_difference_pairs) {
  char dir[] = "/tmp/vsph-hollow-XXXXXX", path[200];
  vsph_test_scratch(dir);
  ck_assert_int_eq(vsph_files_write(dir, "c.csv",
                                    "dx,error,stable,difference\n"
                                    "0.1,0.1,1,nan\n0.05,0.05,1,0.04\n"
                                    "0.025,0.025,0,0.02\n0.0125,0.0125,1,0.01\n"
                                    "0.00625,0.006,1,0.005\n"),
                   0);
  struct vsph_plot pl;
  vsph_plot_init(&pl, dir, "fig_p", "pairs", "dx", "error");
  pl.logx = pl.logy = 1;
  char style[96];
  int said = 0;
  vsph_report_runs_style(style, sizeof style, 0, "");
  ck_assert_int_eq(vsph_plot_add(&pl, "c.csv", "1:2", "error", style), 0);
  vsph_report_runs_style(style, sizeof style, 0, " dt 2");
  ck_assert_int_eq(vsph_plot_add(&pl, "c.csv", "1:4", "difference", style), 0);
  ck_assert_int_eq(vsph_report_runs_hollow(&pl, "c.csv", "1:($3==0 ? $2 : 1/0)",
                                           0, "error stopped", &said),
                   0);
  ck_assert_int_eq(vsph_report_runs_hollow_pairs(&pl, "c.csv", 3, 4, 0,
                                                 "difference stopped", &said),
                   0);
  ck_assert_uint_eq(pl.n, 2 + 2 + 1 + 2); /* the key entry once */
  ck_assert_int_eq(vsph_plot_write(&pl), 0);
  static char svg[1 << 16];
  snprintf(path, sizeof path, "%s/fig_p.svg", dir);
  vsph_test_slurp(path, svg, sizeof svg);
  char line[8][40], open[8][40], disc[8][40];
  /* the difference curve: its four points, then its key sample */
  ck_assert_uint_eq(group_points(svg, "fig_p_plot_2", line, 8), 5);
  /* its hollow overlay (curves 6, white disc, and 7, open circle) */
  ck_assert_uint_eq(group_points(svg, "fig_p_plot_6", disc, 8), 2);
  ck_assert_uint_eq(group_points(svg, "fig_p_plot_7", open, 8), 2);
  for (int k = 0; k < 2; k++) {
    ck_assert_str_eq(disc[k], line[k + 1]);
    ck_assert_str_eq(open[k], line[k + 1]);
  }
  /* the error curve's: row 2 only */
  ck_assert_uint_eq(group_points(svg, "fig_p_plot_1", line, 8), 6);
  ck_assert_uint_eq(group_points(svg, "fig_p_plot_4", open, 8), 1);
  ck_assert_str_eq(open[0], line[2]);
  ck_assert_ptr_nonnull(strstr(svg, "<title>difference stopped</title>"));
  vsph_test_rm_tree(dir);
}
END_TEST

/* The kinetic energy's peak over its start (section 12's still tank):
 * a series that rises to 50 times its start at t = 2.5 and falls again
 * gives 50 and 2.5 exactly (a ratio of two stored doubles, 1 ulp); a
 * decaying one gives 1 at t = 0; equal peaks give the first. */
START_TEST(test_peak_ratio_and_time) {
  const double t[6] = {0.0, 1.0, 2.5, 3.0, 4.0, 5.0};
  const double up[6] = {2e-7, 1e-6, 1e-5, 4e-6, 1e-5, 3e-6};
  const double down[6] = {6e-7, 5e-7, 4e-7, 3e-7, 2e-7, 1e-7};
  double tp = NAN;
  ck_assert_double_eq_tol(vsph_report_choices_peak(t, up, 6, &tp), 50.0, 1e-13);
  ck_assert_double_eq(tp, 2.5);
  ck_assert_double_eq(vsph_report_choices_peak(t, down, 6, &tp), 1.0);
  ck_assert_double_eq(tp, 0.0);
  ck_assert_double_eq(vsph_report_choices_peak(t, up, 1, &tp), 1.0);
  ck_assert_double_eq(tp, 0.0);
}
END_TEST

/* `vsph bench --processes`'s fold of the processes' best times, worked
 * by hand: the best of all and the median of the bests, the mean of the
 * middle two for an even count, whatever the order they came in; NaN for
 * none. */
START_TEST(test_bench_fold) {
  double best, med;
  double odd[] = {9.5, 7.25, 8.0, 12.0, 7.5}; /* sorted: 7.25 7.5 8 9.5 12 */
  vsph_bench_fold(odd, 5, &best, &med);
  ck_assert(best == 7.25 && med == 8.0);
  double even[] = {4.0, 1.0, 3.0, 2.0}; /* middle two 2 and 3 */
  vsph_bench_fold(even, 4, &best, &med);
  ck_assert(best == 1.0 && med == 2.5);
  double one[] = {6.0};
  vsph_bench_fold(one, 1, &best, &med);
  ck_assert(best == 6.0 && med == 6.0);
  vsph_bench_fold(one, 0, &best, &med);
  ck_assert(isnan(best) && isnan(med));
}
END_TEST

Suite *vsph_report_suite(void) {
  Suite *s = suite_create("report");
  TCase *tc = tcase_create("frame");
  tcase_add_test(tc, test_verdict_classes);
  tcase_add_test(tc, test_scene_names);
  tcase_add_test(tc, test_claims_tally);
  tcase_add_test(tc, test_text_value_room);
  tcase_add_test(tc, test_claims_beside);
  tcase_add_test(tc, test_time_left);
  tcase_add_test(tc, test_shell_quote);
  tcase_add_test(tc, test_command_reads_back);
  tcase_add_test(tc, test_null_mode);
  tcase_add_test(tc, test_peak_ratio_and_time);
  tcase_add_test(tc, test_tensor_table_no_negative_zero);
  tcase_add_test(tc, test_hollow_stopped_runs);
  tcase_add_test(tc, test_hollow_difference_pairs);
  tcase_add_test(tc, test_bench_fold);
  suite_add_tcase(s, tc);
  return s;
}
