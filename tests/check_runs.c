/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The runs/ layer, one suite per module (rundir, folder, archive): the folder
 * contract (runs/folder: marker, lock, seal) and checkpoint and restart
 * (runs/rundir): a run stopped at any step and resumed ends bitwise the run
 * never stopped; a foreign, damaged or other settings' checkpoint is not used;
 * a folder that is not vsph's, or holds anything vsph does not write, is
 * refused untouched; a second writer is refused with the holder's pid; a seal
 * names the file that broke it. */
#include <check.h>
#include <cjson/cJSON.h>
#include <dirent.h>
#include <math.h>
#include <omp.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../common/sysinfo.h"
#include "../io/files.h"
#include "../io/vtk.h"
#include "../runs/archive.h"
#include "../runs/folder.h"
#include "../runs/jobs.h"
#include "../runs/rundir.h"
#include "../runs/sheartest.h"
#include "../solver/run.h"
#include "check_suites.h"

static int exists(const char *path) {
  struct stat sb;
  return lstat(path, &sb) == 0;
}

static void put(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fputs(text, f);
  ck_assert_int_eq(fclose(f), 0);
}

/* One run of @p scene with the "KEY=VALUE" settings @p set into @p dir,
 * stopped after @p stop_after steps (0: not), where @p stop_in says
 * (vsph_rundir_opts). */
static int run_in(const char *scene, const char *const *set, const char *dir,
                  size_t stop_after, unsigned stop_in,
                  struct vsph_rundir_result *res) {
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_ptr_nonnull(prm);
  for (size_t k = 0; set[k]; k++) {
    char kv[200];
    snprintf(kv, sizeof kv, "%s", set[k]);
    char *eq = strchr(kv, '=');
    ck_assert_ptr_nonnull(eq);
    *eq = '\0';
    ck_assert_int_eq(vsph_params_set(prm, kv, eq + 1), 0);
  }
  const struct vsph_rundir_opts o = {.dir = dir,
                                     .command = "test",
                                     .stop_after = stop_after,
                                     .stop_in = stop_in};
  const int st = vsph_rundir_execute(prm, scene, &o, res);
  vsph_params_free(prm);
  return st;
}

static int run(const char *scene, const char *const *set, const char *dir,
               size_t stop_after, struct vsph_rundir_result *res) {
  return run_in(scene, set, dir, stop_after, 0, res);
}

/* run.json's fields that are timings or the machine's state: the only
 * ones a resumed run may change */
static int timing(const char *k) {
  /* (and the date and command of the start: the two runs compared began
   * at different times, into different folders) */
  static const char *const t[] = {"date",
                                  "command",
                                  "wall_s",
                                  "cpu_s",
                                  "load_average_start",
                                  "load_average_end",
                                  "omp_wait_policy",
                                  "pairs_per_s",
                                  "particle_steps_per_s",
                                  "peak_rss_bytes",
                                  "wall_segments",
                                  NULL};
  for (size_t i = 0; t[i]; i++)
    if (!strcmp(k, t[i])) return 1;
  return 0;
}

/* Folders @p a and @p b hold the same run: every file byte for byte, but
 * run.json (every field but the timings) and key.txt (every line but
 * run.json's). */
static void same_run(const char *a, const char *b) {
  DIR *d = opendir(a);
  ck_assert_ptr_nonnull(d);
  size_t nfiles = 0;
  for (struct dirent *e; (e = readdir(d));) {
    const char *n = e->d_name;
    if (n[0] == '.') continue;
    char pa[700], pb[700];
    snprintf(pa, sizeof pa, "%s/%s", a, n);
    snprintf(pb, sizeof pb, "%s/%s", b, n);
    size_t la = 0, lb = 0;
    char *ta = vsph_files_slurp(pa, &la), *tb = vsph_files_slurp(pb, &lb);
    ck_assert_msg(ta && tb, "%s: missing in one folder", n);
    nfiles++;
    if (!strcmp(n, "run.json")) {
      cJSON *ja = cJSON_Parse(ta), *jb = cJSON_Parse(tb);
      ck_assert(ja && jb);
      ck_assert_int_eq(cJSON_GetArraySize(ja), cJSON_GetArraySize(jb));
      for (cJSON *x = ja->child; x; x = x->next) {
        if (timing(x->string)) continue;
        cJSON *y = cJSON_GetObjectItemCaseSensitive(jb, x->string);
        ck_assert_msg(y && cJSON_Compare(x, y, 1), "run.json: %s differs",
                      x->string);
      }
      cJSON_Delete(ja);
      cJSON_Delete(jb);
    } else if (!strcmp(n, "key.txt")) {
      char *ra = strstr(ta, "\nrun.json "), *rb = strstr(tb, "\nrun.json ");
      ck_assert(ra && rb);
      const char *ea = strchr(ra + 1, '\n'), *eb = strchr(rb + 1, '\n');
      ck_assert(ea && eb);
      *ra = *rb = '\0'; /* before run.json's line, and after it */
      ck_assert_str_eq(ta, tb);
      ck_assert_str_eq(ea, eb);
    } else {
      ck_assert_msg(la == lb && !memcmp(ta, tb, la), "%s differs", n);
    }
    free(ta);
    free(tb);
  }
  closedir(d);
  ck_assert_uint_ge(nfiles, 4);
  /* and b holds nothing a does not (a temporary, a stale file) */
  size_t nb = 0;
  d = opendir(b);
  ck_assert_ptr_nonnull(d);
  for (struct dirent *e; (e = readdir(d));) nb += e->d_name[0] != '.';
  closedir(d);
  ck_assert_uint_eq(nb, nfiles);
}

/* Runs that carry every kind of state across a step: mirror ghosts
 * (Poiseuille), wall particles and the transport velocity's kept rates
 * (cavity, tvf), a free surface under gravity (standing wave), PVWF's
 * two passes, the gas law's energy, contact SPH in 3-D, the leapfrog's
 * kept rates with XSPH on fixed wall particles (Vukcevic et al.'s set-up),
 * evolving wall particles' density. */
static const char *const POIS[] = {"Solver:res=8", "Solver:t_end=0.1",
                                   "Solver:outputs=30", NULL};
static const char *const TVF[] = {"Solver:res=8", "Solver:t_end=0.03",
                                  "Solver:tvf=1", NULL};
static const char *const WAVE[] = {
    "Solver:res=8",          "Solver:t_end=0.1",
    "Solver:probe_points=4", "Solver:probe_x0=0.5",
    "Solver:probe_y0=0.1",   "Solver:probe_x1=0.5",
    "Solver:probe_y1=-0.9",  NULL};
static const char *const PVWF[] = {"Solver:res=10", "Solver:t_end=0.2",
                                   "Solver:visc=pvwf", NULL};
static const char *const GAS[] = {"Solver:res=8", "Solver:t_end=0.1",
                                  "Solver:eos=gas", NULL};
static const char *const LEAP[] = {
    "Solver:res=12",         "Solver:t_end=0.1",           "Solver:outputs=30",
    "Solver:xsph=0.3",       "Solver:integrator=leapfrog", "Scene:walls=fixed",
    "Solver:eos=isothermal", "Solver:density=summation",   NULL};
static const char *const EVOLVE[] = {
    "Solver:res=8",         "Solver:t_end=0.1",
    "Solver:kernel=cubic",  "Solver:hdx=1.5699",
    "Solver:eos=tait",      "Solver:density=summation",
    "Scene:walls=evolving", NULL};
static const char *const CONTACT[] = {
    "Solver:scheme=contact", "Solver:kernel=wendland2",
    "Solver:alpha=0.5",      "Solver:res=8",
    "Scene:Ly=4e-7",         "Scene:Lz=4e-7",
    "Solver:t_end=1e-10",    NULL};
static const struct {
  const char *scene;
  const char *const *set;
} CASES[] = {{"poiseuille", POIS},    {"cavity", TVF},
             {"standing-wave", WAVE}, {"stretching-square", PVWF},
             {"poiseuille", GAS},     {"shear", CONTACT},
             {"poiseuille", LEAP},    {"cavity", EVOLVE}};

/* Stopped after 1, 2, 4, ... steps of each process (so between rows, at
 * rows and at snapshots) and resumed each time: bitwise the run never
 * stopped. */
START_TEST(test_restart_bitwise) {
  char dir[] = "/tmp/vsph_restartXXXXXX", a[300], b[300];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  snprintf(b, sizeof b, "%s/b", dir);
  struct vsph_rundir_result ra, rb;
  ck_assert_int_eq(run(CASES[_i].scene, CASES[_i].set, a, 0, &ra), 0);
  ck_assert_uint_ge(ra.steps, 4);
  int st, stops = 0;
  for (size_t k = 1; (st = run(CASES[_i].scene, CASES[_i].set, b, k, &rb));
       k *= 2) {
    ck_assert_int_eq(st, VSPH_EINTR);
    char ck[400];
    snprintf(ck, sizeof ck, "%s/checkpoint.bin", b);
    ck_assert(exists(ck));
    stops++;
  }
  ck_assert_int_ge(stops, 2);
  ck_assert_uint_eq(rb.segments, (size_t)stops + 1);
  ck_assert_uint_eq(rb.steps, ra.steps);
  same_run(a, b);
  char ck[400];
  snprintf(ck, sizeof ck, "%s/checkpoint.bin", b);
  ck_assert_msg(!exists(ck), "an ended run kept its checkpoint");
  vsph_test_rm_tree(dir);
}
END_TEST

static size_t count_lines(const char *dir, const char *name) {
  char path[400];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  size_t len = 0, n = 0;
  char *t = vsph_files_slurp(path, &len);
  ck_assert_ptr_nonnull(t);
  for (size_t k = 0; k < len; k++) n += t[k] == '\n';
  free(t);
  return n;
}

static size_t count_snapshots(const char *dir) {
  size_t n = 0;
  DIR *d = opendir(dir);
  ck_assert_ptr_nonnull(d);
  for (struct dirent *e; (e = readdir(d));)
    n += !strncmp(e->d_name, "snap_", 5);
  closedir(d);
  return n;
}

/* Stopped while an output is written (before its energy row; within a
 * snapshot's sums and compression), after 1, 2, 4, ... steps of each
 * process and at the very end: the output is not written, the checkpoint
 * keeps it due, and the resumed run writes it first: bitwise the run
 * never stopped. (A checkpoint that forgot what was due would lose a row
 * or a snapshot; one that remembered what was written would repeat it.) */
START_TEST(test_restart_within_outputs) {
  static const unsigned where[] = {VSPH_RUN_ROW, VSPH_RUN_SNAPSHOT};
  static const char *const SNAPS[] = {
      "Solver:res=8",          "Solver:t_end=0.1",
      "Solver:outputs=30",     "Solver:snapshots=10",
      "Solver:probe_points=2", "Solver:probe_x0=0.5",
      "Solver:probe_y0=0.25",  "Solver:probe_x1=0.5",
      "Solver:probe_y1=0.75",  NULL};
  char dir[] = "/tmp/vsph_withinXXXXXX", a[300], b[300], c[300];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  struct vsph_rundir_result ra, rb;
  ck_assert_int_eq(run("poiseuille", SNAPS, a, 0, &ra), 0);
  const size_t nsnap = count_snapshots(a);
  ck_assert_uint_eq(nsnap, 11); /* t = 0, 10 intervals (the end among them) */
  /* the probes: both at each energy row */
  ck_assert_uint_eq(count_lines(a, "probes.csv") - 1,
                    2 * (count_lines(a, "energy.csv") - 1));
  for (int w = 0; w < 2; w++) {
    snprintf(b, sizeof b, "%s/b%d", dir, w);
    int st, stops = 0;
    for (size_t k = 1; (st = run_in("poiseuille", SNAPS, b, k, where[w], &rb));
         k *= 2) {
      ck_assert_int_eq(st, VSPH_EINTR);
      ck_assert(rb.interrupted);
      stops++;
    }
    ck_assert_int_ge(stops, 2);
    same_run(a, b);
    /* at the very end: the last step done, its snapshot (or row) due */
    snprintf(c, sizeof c, "%s/c%d", dir, w);
    ck_assert_int_eq(run_in("poiseuille", SNAPS, c, ra.steps, where[w], &rb),
                     VSPH_EINTR);
    ck_assert_uint_eq(rb.steps, ra.steps);
    /* (a stop before the row keeps the snapshot due with it) */
    ck_assert_uint_eq(count_snapshots(c), nsnap - 1);
    ck_assert_int_eq(run("poiseuille", SNAPS, c, 0, &rb), 0);
    ck_assert_uint_eq(rb.segments, 2);
    same_run(a, c);
  }
  vsph_test_rm_tree(dir);
}
END_TEST

/* A checkpoint of other settings, or damaged, is not used: the run starts
 * over and ends as a fresh one. */
START_TEST(test_restart_refuses_foreign) {
  char dir[] = "/tmp/vsph_foreignXXXXXX", a[300], b[300], ck[400];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  snprintf(b, sizeof b, "%s/b", dir);
  snprintf(ck, sizeof ck, "%s/checkpoint.bin", b);
  struct vsph_rundir_result r;
  static const char *const other[] = {"Solver:res=8", "Solver:t_end=0.1",
                                      "Solver:outputs=30", "Solver:cfl=0.9",
                                      NULL};
  ck_assert_int_eq(run("poiseuille", POIS, a, 0, &r), 0);
  /* other settings (the cfl) */
  ck_assert_int_eq(run("poiseuille", other, b, 5, &r), VSPH_EINTR);
  ck_assert(exists(ck));
  ck_assert_int_eq(run("poiseuille", POIS, b, 0, &r), 0);
  ck_assert_uint_eq(r.segments, 1);
  same_run(a, b);
  /* the same settings, one byte of the state flipped */
  ck_assert_int_eq(run("poiseuille", POIS, b, 5, &r), VSPH_EINTR);
  size_t len = 0;
  char *bytes = vsph_files_slurp(ck, &len);
  ck_assert_ptr_nonnull(bytes);
  bytes[len / 2] ^= 0x10;
  FILE *f = fopen(ck, "wb");
  ck_assert_uint_eq(fwrite(bytes, 1, len, f), len);
  ck_assert_int_eq(fclose(f), 0);
  free(bytes);
  ck_assert_int_eq(run("poiseuille", POIS, b, 0, &r), 0);
  ck_assert_uint_eq(r.segments, 1);
  same_run(a, b);
  vsph_test_rm_tree(dir);
}
END_TEST

/* Killed outright (SIGKILL: no handler runs) with a checkpoint every step
 * (Solver:checkpoint_s tiny), the same command resumes from the last one
 * and ends bitwise as the run never stopped. */
START_TEST(test_restart_after_kill) {
  char dir[] = "/tmp/vsph_killXXXXXX", args[600], a[300], b[300];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  snprintf(b, sizeof b, "%s/b", dir);
  const char *run_args =
      "run vortex-patch --res 20 --t-end 1.5 --quiet "
      "--set Solver:checkpoint_s=1e-9";
  snprintf(args, sizeof args, "%s --out %s", run_args, a);
  ck_assert_int_eq(vsph_test_cli(args)->status, 0);
  const pid_t pid = fork();
  ck_assert_int_ge(pid, 0);
  if (pid == 0) {
    if (!freopen("/dev/null", "w", stderr)) _exit(126);
    execl(getenv("VSPH_BIN"), "vsph", "run", "vortex-patch", "--res", "20",
          "--t-end", "1.5", "--quiet", "--set", "Solver:checkpoint_s=1e-9",
          "--out", b, (char *)NULL);
    _exit(127);
  }
  /* kill it once it has saved a few steps (at most 20 s) */
  char energy[400];
  snprintf(energy, sizeof energy, "%s/energy.csv", b);
  for (int k = 0; k < 2000; k++) {
    struct stat sb;
    if (stat(energy, &sb) == 0 && sb.st_size > 2000) break;
    nanosleep(&(struct timespec){0, 10000000}, NULL);
  }
  kill(pid, SIGKILL);
  int ws;
  waitpid(pid, &ws, 0);
  ck_assert_msg(WIFSIGNALED(ws), "the run ended before it was killed");
  snprintf(args, sizeof args, "%s --out %s", run_args, b);
  struct vsph_test_outcome *o = vsph_test_cli(args);
  ck_assert_msg(o->status == 0, "%s", o->err);
  char js[4096];
  snprintf(energy, sizeof energy, "%s/run.json", b);
  vsph_test_slurp(energy, js, sizeof js);
  ck_assert_ptr_nonnull(strstr(js, "\"wall_segments\":\t2"));
  same_run(a, b);
  vsph_test_rm_tree(dir);
}
END_TEST

/* The marker: a folder that is not empty and has none is refused, each of
 * vsph's own names alone included; another kind's folder too; a refusal
 * changes nothing. */
START_TEST(test_folder_marker) {
  char dir[] = "/tmp/vsph_markerXXXXXX", sub[300], path[400], args[600];
  vsph_test_scratch(dir);
  static const char *const names[] = {
      "run.json",      "energy.csv",     "profile.csv", "snapshots.pvd",
      "snap_0000.vtp", "centreline.csv", "key.txt",     "summary.csv"};
  for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
    snprintf(sub, sizeof sub, "%s/f%zu", dir, k);
    ck_assert_int_eq(mkdir(sub, 0700), 0);
    snprintf(path, sizeof path, "%s/%s", sub, names[k]);
    put(path, "someone's\n");
    const char *const cmds[] = {
        "run poiseuille --res 8 --t-end 0.01 --out",
        "contact --scheme contact --kernel wendland2 --alpha 0.5 --res 8 "
        "--set Scene:Ly=4e-7 --set Scene:Lz=4e-7 --t-end 1e-10 --out"};
    for (int c = 0; c < 2; c++) {
      snprintf(args, sizeof args, "%s %s", cmds[c], sub);
      struct vsph_test_outcome *o = vsph_test_cli(args);
      ck_assert_msg(o->status == 2 && o->err_lines == 1, "'%s': %d %s", args,
                    o->status, o->err);
      ck_assert_msg(strstr(o->err, "vsph did not make it"), "%s", o->err);
      char text[32];
      vsph_test_slurp(path, text, sizeof text);
      ck_assert_str_eq(text, "someone's\n");
      /* nothing added: the folder holds the one file */
      DIR *d = opendir(sub);
      int n = 0;
      for (struct dirent *e; (e = readdir(d));) n += e->d_name[0] != '.';
      closedir(d);
      snprintf(path, sizeof path, "%s/%s", sub, VSPH_FOLDER_MARKER);
      ck_assert_int_eq(n, 1);
      ck_assert(!exists(path));
      snprintf(path, sizeof path, "%s/%s", sub, names[k]);
    }
  }
  /* a scene run's folder is not a shear test's, nor a report's */
  snprintf(sub, sizeof sub, "%s/run", dir);
  snprintf(args, sizeof args, "run poiseuille --res 8 --t-end 0.01 --out %s",
           sub);
  ck_assert_int_eq(vsph_test_cli(args)->status, 0);
  snprintf(args, sizeof args,
           "contact --scheme contact --kernel wendland2 --alpha 0.5 --res 8 "
           "--set Scene:Ly=4e-7 --set Scene:Lz=4e-7 --t-end 1e-10 --out %s",
           sub);
  struct vsph_test_outcome *o = vsph_test_cli(args);
  ck_assert_msg(o->status == 2 && strstr(o->err, "not a vsph shear test"),
                "%d %s", o->status, o->err);
  snprintf(args, sizeof args, "report --only tensors --out %s", sub);
  o = vsph_test_cli(args);
  ck_assert_msg(o->status == 2 && strstr(o->err, "not a vsph report"), "%d %s",
                o->status, o->err);
  /* a shear test's seal holds for its own kind: cached the second time */
  for (int k = 0; k < 2; k++) {
    snprintf(args, sizeof args,
             "contact --scheme contact --kernel wendland2 --alpha 0.5 --res 8 "
             "--set Scene:Ly=4e-7 --set Scene:Lz=4e-7 --t-end 1e-10 --cache "
             "--out %s/shear",
             dir);
    o = vsph_test_cli(args);
    ck_assert_int_eq(o->status, 0);
    ck_assert_msg((strstr(o->err, "is cached") != NULL) == k, "%d: %s", k,
                  o->err);
  }
  /* a FIFO with a vsph name in a run folder: refused, not opened */
  snprintf(path, sizeof path, "%s/profile.csv", sub);
  ck_assert_int_eq(remove(path), 0);
  ck_assert_int_eq(mkfifo(path, 0600), 0);
  snprintf(args, sizeof args, "run poiseuille --res 8 --t-end 0.01 --out %s",
           sub);
  o = vsph_test_cli(args);
  ck_assert_msg(o->status == 2 && strstr(o->err, "a FIFO"), "%d %s", o->status,
                o->err);
  /* key.txt a link to that FIFO: --cache neither hangs nor follows it */
  char key[400];
  snprintf(key, sizeof key, "%s/key.txt", sub);
  ck_assert_int_eq(remove(key), 0);
  ck_assert_int_eq(symlink(path, key), 0);
  snprintf(args, sizeof args,
           "run poiseuille --res 8 --t-end 0.01 --cache --out %s", sub);
  o = vsph_test_cli(args);
  ck_assert_msg(o->status == 2 && o->err_lines == 1, "%d %s", o->status,
                o->err);
  ck_assert_int_eq(remove(path), 0); /* the link alone, then */
  o = vsph_test_cli(args);
  ck_assert_msg(
      o->status == 2 && strstr(o->err, "key.txt, which is a symbolic"), "%d %s",
      o->status, o->err);
  vsph_test_rm_tree(dir);
}
END_TEST

/* The lock: while one writer holds a folder, a second is refused naming
 * the holder's pid (here this process's), and changes nothing; once it is
 * released, the second runs. */
START_TEST(test_folder_lock) {
  char dir[] = "/tmp/vsph_lockXXXXXX", sub[300], args[600], pid[32];
  vsph_test_scratch(dir);
  snprintf(sub, sizeof sub, "%s/r", dir);
  struct vsph_folder f;
  ck_assert_int_eq(vsph_folder_claim(&f, sub, &vsph_folder_scene_run), 0);
  snprintf(args, sizeof args, "run poiseuille --res 8 --t-end 0.01 --out %s",
           sub);
  struct vsph_test_outcome *o = vsph_test_cli(args);
  snprintf(pid, sizeof pid, "process %ld", (long)getpid());
  ck_assert_msg(o->status == 2 && o->err_lines == 1 && strstr(o->err, pid),
                "%d %s", o->status, o->err);
  char path[400];
  snprintf(path, sizeof path, "%s/used_parameters.yml", sub);
  ck_assert(!exists(path));
  vsph_folder_release(&f);
  ck_assert_int_eq(vsph_test_cli(args)->status, 0);
  ck_assert(exists(path));
  vsph_test_rm_tree(dir);
}
END_TEST

/* The seal: a cut, edited, added or missing file breaks it by name; the
 * cache then runs again, and the run restores the seal. */
/* The manifest's line for file @p name of @p dir, read afresh. */
static void manifest_line(const char *dir, const char *name, char *line,
                          size_t len) {
  char path[400];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  unsigned long crc;
  size_t size;
  ck_assert_int_eq(vsph_folder_checksum(path, &crc, &size), 0);
  snprintf(line, len, "%s %zu %08lx\n", name, size, crc);
}

/* A checkpoint's manifest reads a file again only when it changed: the
 * same text from the cache as from the files; a file replaced (renamed
 * over, same size), rewritten in place or grown is read anew; one noted
 * (vsph_folder_note) is what a manifest would read. */
START_TEST(test_folder_manifest_cache) {
  char dir[] = "/tmp/vsph_manifestXXXXXX", sub[300], path[400], tmp[400];
  vsph_test_scratch(dir);
  snprintf(sub, sizeof sub, "%s/r", dir);
  struct vsph_folder f;
  ck_assert_int_eq(vsph_folder_claim(&f, sub, &vsph_folder_scene_run), 0);
  snprintf(path, sizeof path, "%s/snap_0000.vtp", sub);
  snprintf(tmp, sizeof tmp, "%s/snap_0000.vtp.tmp", sub);
  put(path, "first snapshot");
  char e[400], want[900];
  snprintf(e, sizeof e, "%s/energy.csv", sub);
  put(e, "t,Ek\n");
  for (int round = 0; round < 5; round++) {
    if (round == 1) { /* replaced, as vsph writes a snapshot: same size */
      put(tmp, "other snapshot");
      ck_assert_int_eq(rename(tmp, path), 0);
    } else if (round == 2) { /* rewritten in place, same size */
      nanosleep(&(struct timespec){0, 20000000}, NULL); /* a clock tick */
      put(path, "third snapshot");
    } else if (round == 3) { /* grown */
      put(e, "t,Ek\n0,1\n");
    } else if (round == 4) { /* replaced, then noted */
      put(tmp, "fifth snapshot");
      ck_assert_int_eq(rename(tmp, path), 0);
      ck_assert_int_eq(vsph_folder_note(&f, "snap_0000.vtp"), 0);
    }
    char a[400], b[400];
    manifest_line(sub, "energy.csv", a, sizeof a);
    manifest_line(sub, "snap_0000.vtp", b, sizeof b);
    snprintf(want, sizeof want, "%s%s", a, b);
    for (int again = 0; again < 2; again++) { /* the second from the cache */
      char *m = vsph_folder_manifest(&f, NULL);
      ck_assert_ptr_nonnull(m);
      ck_assert_str_eq(m, want);
      free(m);
    }
    ck_assert_uint_eq(f.ncrcs, 2);
  }
  vsph_folder_release(&f);
  ck_assert_ptr_null(f.crcs);
  vsph_test_rm_tree(dir);
}
END_TEST

/* Write text to dir/name (a test's own file). */
static void put_text(const char *dir, const char *name, const char *text) {
  char path[900];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fputs(text, f);
  ck_assert_int_eq(fclose(f), 0);
}

/* An archive entry of @p kind at @p dir sealed under @p key by hand,
 * holding run.json @p run (none when NULL): an entry of other sources. */
static void seal_kind(const char *dir, const struct vsph_folder_kind *kind,
                      const char *key, const char *run) {
  struct vsph_folder f;
  ck_assert_int_eq(vsph_folder_claim(&f, dir, kind), 0);
  if (run) ck_assert_int_eq(vsph_files_write(dir, "run.json", run), 0);
  ck_assert_int_eq(vsph_folder_seal(&f, key, NULL), 0);
  vsph_folder_release(&f);
}

/* A scene run's entry, as seal_kind. */
static void seal_entry(const char *dir, const char *key, const char *run) {
  seal_kind(dir, &vsph_folder_scene_run, key, run);
}

/* entries.md's row of entry @p name holds @p verdict (its last cell). */
static void assert_stands(const char *ar, const char *name,
                          const char *verdict) {
  char path[700], text[8192], row[64];
  snprintf(path, sizeof path, "%s/entries.md", ar);
  vsph_test_slurp(path, text, sizeof text);
  snprintf(row, sizeof row, "\n| %s |", name);
  const char *r = strstr(text, row);
  ck_assert_msg(r != NULL, "no row of %s in\n%s", name, text);
  const char *e = strchr(r + 1, '\n');
  char line[1024];
  snprintf(line, sizeof line, "%.*s", (int)(e ? e - r - 1 : 1000), r + 1);
  ck_assert_msg(strstr(line, verdict), "%s: want '%s' in\n%s", name, verdict,
                line);
}

/* vsph_archive_standing agrees, run by run of @p jd's plan, with
 * @p want (its vsph_archive_verdict: 1 stands, 0 stale, -1 unjudged,
 * -2 absent). */
static void assert_standing(const char *ar, const struct vsph_archive_judge *jd,
                            const int *want) {
  int got[8];
  ck_assert_uint_le(jd->nplan, 8);
  ck_assert_int_eq(vsph_archive_standing(ar, jd, got), 0);
  for (size_t k = 0; k < jd->nplan; k++)
    ck_assert_msg(got[k] == want[k], "%s: stands %d, want %d", jd->plan_name[k],
                  got[k], want[k]);
}

/* entries.md's rule, case by case (and vsph_archive_standing, the
 * budget's reading of it, run by run): an entry made by this build's sources
 * stands when the plan asks for it with its settings; one the plan does
 * not name, or names with other settings, does not; an entry of other
 * sources (a sealed folder under another source hash) is unjudged
 * without the history, stands when its commit's baseline rows of its
 * scene equal today's, and does not when they differ (another scene's
 * rows changing is not its concern). A shear test's entry (no run.json)
 * is judged by the shear scene's rows, its numerics. */
START_TEST(test_archive_summary) {
  char dir[] = "/tmp/vsph_archsumXXXXXX", rep[300], a[300], ar[300], z[400],
       hist[300], base[300], key[4096];
  vsph_test_scratch(dir);
  snprintf(rep, sizeof rep, "%s/rep", dir);
  snprintf(a, sizeof a, "%s/rep/runs/a", dir);
  snprintf(ar, sizeof ar, "%s/ar", dir);
  snprintf(hist, sizeof hist, "%s/hist", dir);
  static const char *const set[] = {"Solver:res=8", "Solver:t_end=0.02", NULL};
  struct vsph_rundir_result r;
  ck_assert_int_eq(run("poiseuille", set, a, 0, &r), 0);
  struct vsph_archive_counts n;
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  /* z: an entry sealed under another source hash, the same settings */
  char path[700];
  snprintf(path, sizeof path, "%s/key.txt", a);
  vsph_test_slurp(path, key, sizeof key);
  *strstr(key, "files:\n") = '\0';
  const char *settings = strchr(key, '\n') + 1;
  char zkey[4200];
  snprintf(zkey, sizeof zkey, "vsph %s 0123456789abcdef\n%s", VSPH_VERSION,
           settings);
  snprintf(z, sizeof z, "%s/runs/z", ar);
  /* its reason holds what would break a table row: escaped, blanked */
  seal_entry(z, zkey,
             "{\"scene\": \"poiseuille\", \"status\": \"ok\", \"t\": 0.02, "
             "\"t_end\": 0.02, \"unstable_reason\": \"a|b\\nc\", \"commit\": "
             "\"x|y\"}\n");
  /* z2: the same, its run.json naming a -dirty commit (whose baseline the
   * history cannot hold): judged by the commit its source hash names */
  char z2[400];
  snprintf(z2, sizeof z2, "%s/runs/z2", ar);
  seal_entry(z2, zkey,
             "{\"scene\": \"poiseuille\", \"status\": \"ok\", \"commit\": "
             "\"c0ffee-dirty\"}\n");
  /* an entry named with a tab (sealed by hand): index.tsv leaves it out,
   * entries.md blanks it */
  char zt[400];
  snprintf(zt, sizeof zt, "%s/runs/t\tx", ar);
  seal_entry(zt, zkey, NULL);
  /* s: a shear test's entry, no run.json */
  char s[400];
  snprintf(s, sizeof s, "%s/runs/s", ar);
  seal_kind(s, &vsph_folder_shear_test, zkey, NULL);
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  char index[4096];
  snprintf(path, sizeof path, "%s/index.tsv", ar);
  vsph_test_slurp(path, index, sizeof index);
  ck_assert_msg(strstr(index, "\na\t") && !strstr(index, "t\tx"), "%s", index);
  /* today's baseline: two scenes' rows */
  ck_assert_int_eq(mkdir(hist, 0755), 0);
  snprintf(base, sizeof base, "%s/baseline.csv", dir);
  static const char *const now =
      "scene,visc,res\npoiseuille,mgf,16\npoiseuille,pvwf,16\ncouette,mgf,"
      "16\nshear,contact,20\n";
  put_text(dir, "baseline.csv", now);
  /* (and "gone", which the plan names and the archive lacks) */
  const char *names[] = {"a", "z", "z2", "gone", "s"},
             *keys[] = {key, key, key, key, key};
  struct vsph_archive_judge jd = {
      .baseline = base, .nplan = 5, .plan_name = names, .plan_key = keys};
  ck_assert_int_eq(vsph_archive_summarise(ar, &jd), 0);
  assert_standing(ar, &jd, (const int[]){1, -1, -1, -2, -1});
  assert_stands(ar, "s", "unjudged: shear's rows");
  assert_stands(ar, "a", "| yes |");
  assert_stands(ar, "z", "unjudged");
  assert_stands(ar, "z", "(a\\|b c) |");
  assert_stands(ar, "t x", "no run of this name");
  /* the history: z's commit, its rows then equal today's (couette's
   * differ: not z's scene) */
  /* (a line without its tab, one with three fields and one of a longer
   * hash are skipped, not read across) */
  put_text(hist, "commits.tsv",
           "0123456789abcdef\nfedcba9876543210\tc0de\n0123456789abcdef0\tc1de\n"
           "0123456789abcdef\tbad\textra\n0123456789abcdef\tc0ffee\n");
  put_text(hist, "c0ffee.csv",
           "scene,visc,res\npoiseuille,mgf,16\npoiseuille,pvwf,16\ncouette,"
           "mgf,8\nshear,contact,20\n");
  jd.history = hist;
  ck_assert_int_eq(vsph_archive_summarise(ar, &jd), 0);
  assert_standing(ar, &jd, (const int[]){1, 1, 1, -2, 1});
  assert_stands(ar, "s", "| yes |");
  assert_stands(ar, "z", "| yes |");
  assert_stands(ar, "z", ", c0ffee |");
  assert_stands(ar, "z2", "| yes |");
  assert_stands(ar, "z2", ", c0ffee |");
  /* poiseuille's and shear's rows changed since c0ffee: z and s no
   * longer stand */
  put_text(hist, "c0ffee.csv",
           "scene,visc,res\npoiseuille,mgf,8\npoiseuille,pvwf,16\nshear,"
           "contact,40\n");
  ck_assert_int_eq(vsph_archive_summarise(ar, &jd), 0);
  assert_standing(ar, &jd, (const int[]){1, 0, 0, -2, 0});
  assert_stands(ar, "s", "no: shear's rows");
  assert_stands(ar, "z", "no: poiseuille's rows");
  assert_stands(ar, "a", "| yes |");
  /* rows with figures: rounding (1e-13 relative, a vectorised loop's
   * or another compiler's) keeps z standing; a move of 1e-5, beyond the
   * baseline's 1e-6, retires it, as a changed verdict does; a row more or
   * less does too */
  put_text(dir, "baseline.csv",
           "scene,visc,res,ek\npoiseuille,mgf,16,1.2345678901e-03,1\n"
           "poiseuille,pvwf,16,-7.5e-01,0\nshear,contact,20,2.5e+00,1\n");
  static const struct {
    const char *rows;
    int stands;
  } MOVED[] = {
      {"poiseuille,mgf,16,1.2345678901001e-03,1\npoiseuille,pvwf,16,"
       "-7.49999999999925e-01,0\n",
       1},
      {"poiseuille,mgf,16,1.2345802357e-03,1\npoiseuille,pvwf,16,-7.5e-01,"
       "0\n",
       0},
      {"poiseuille,mgf,16,1.2345678901e-03,1\npoiseuille,pvwf,16,-7.5e-01,"
       "1\n",
       0},
      {"poiseuille,mgf,16,1.2345678901e-03,1\n", 0}};
  for (size_t m = 0; m < sizeof MOVED / sizeof MOVED[0]; m++) {
    char then[512];
    snprintf(then, sizeof then, "scene,visc,res,ek\n%sshear,contact,20,2.5,1\n",
             MOVED[m].rows);
    put_text(hist, "c0ffee.csv", then);
    ck_assert_int_eq(vsph_archive_summarise(ar, &jd), 0);
    assert_stands(ar, "z",
                  MOVED[m].stands ? "| yes |" : "no: poiseuille's rows");
    assert_stands(ar, "s", "| yes |"); /* 2.5 and 2.5e+00: one number */
  }
  /* the plan: a under other settings, z not at all */
  char other[4200];
  snprintf(other, sizeof other, "vsph %s %s\nscene poiseuille\nSolver:res=9\n",
           VSPH_VERSION, vsph_source_hash_id);
  keys[0] = other;
  jd.nplan = 1;
  ck_assert_int_eq(vsph_archive_summarise(ar, &jd), 0);
  assert_standing(ar, &jd, (const int[]){0});
  assert_stands(ar, "a", "other settings");
  assert_stands(ar, "z", "no run of this name");
  /* the tally counts the plan's runs only */
  snprintf(path, sizeof path, "%s/entries.md", ar);
  char text[8192];
  vsph_test_slurp(path, text, sizeof text);
  ck_assert_msg(strstr(text, "\n1 of the 1 runs of the current FULL plan") &&
                    strstr(text, "beside entries the plan no longer names"),
                "%s", text);
  vsph_test_rm_tree(dir);
}
END_TEST

/* The run archive (runs/archive): of a report's runs/, each sealed run is
 * stored as a folder of its kind sealed under the run's own key, with its
 * tables byte for byte and without its snapshots; a run whose seal broke
 * is left out and named; storing again keeps what is there; a redone run
 * (another key) replaces its entry; index.tsv lists the entries with the
 * source hash that made them; a foreign folder is refused untouched. */
/* Entry NAME's frame of snapshot @p k in archive entry @p entry against
 * the run's snapshot in @p run: its fields, bits, time and positions
 * (each within the rounding's 2^-(bits+1) and single precision's 2^-24,
 * bounded by 2^-11 + 2^-23 at 10 bits: vsph_vtk_write_frame). */
static void frame_is(const char *run, const char *entry, int k,
                     unsigned fields) {
  char sp[700], fp[700];
  snprintf(sp, sizeof sp, "%s/snap_%04d.vtp", run, k);
  snprintf(fp, sizeof fp, "%s/snap_%04d.vtp", entry, k);
  if (!fields) {
    ck_assert_msg(!exists(fp), "%s", fp);
    return;
  }
  struct vsph_vtk_snapshot s, f;
  ck_assert_int_eq(vsph_vtk_read(sp, &s), 0);
  ck_assert_int_eq(vsph_vtk_read(fp, &f), 0);
  ck_assert_int_eq(f.frame_bits, VSPH_ARCHIVE_FRAME_BITS);
  ck_assert_uint_eq(f.frame_fields, fields);
  ck_assert_uint_eq(f.n, s.n);
  ck_assert(f.t == s.t);
  const double bound = ldexp(1.0, -(VSPH_ARCHIVE_FRAME_BITS + 1)) + 0x1p-23;
  for (size_t i = 0; i < 3 * s.n; i++)
    ck_assert(fabs(f.pos[i] - s.pos[i]) <= bound * fabs(s.pos[i]));
  vsph_vtk_snapshot_free(&s);
  vsph_vtk_snapshot_free(&f);
}

/* The frames an archive keeps of a run's snapshots, as a report's parts
 * ask (VSPH_JOBS_FRAME_*): the first's and the last's picture fields, or
 * every snapshot's velocities, nothing else; an entry stored before
 * without them is stored again, then kept; its seal lists them. */
START_TEST(test_archive_frames) {
  char dir[] = "/tmp/vsph_framesXXXXXX", rep[300], a[300], ar[300], entry[400],
       path[800];
  vsph_test_scratch(dir);
  snprintf(rep, sizeof rep, "%s/rep", dir);
  snprintf(a, sizeof a, "%s/rep/runs/a", dir);
  snprintf(ar, sizeof ar, "%s/ar", dir);
  snprintf(entry, sizeof entry, "%s/runs/a", ar);
  static const char *const set[] = {"Solver:res=8", "Solver:t_end=0.02",
                                    "Solver:snapshots=3", NULL};
  struct vsph_rundir_result r;
  ck_assert_int_eq(run("poiseuille", set, a, 0, &r), 0);
  int last = -1; /* the run's last snapshot, found on disk */
  for (int k = 0; k < 100; k++) {
    snprintf(path, sizeof path, "%s/snap_%04d.vtp", a, k);
    if (exists(path)) last = k;
  }
  ck_assert_int_eq(last, 3); /* t = 0 and 3 more */
  struct vsph_archive_counts n;
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  for (int k = 0; k <= last; k++) frame_is(a, entry, k, 0u);
  static const char *const name[] = {"a", "nothing-of-that-name"};
  unsigned want[] = {VSPH_JOBS_FRAME_FIRST | VSPH_JOBS_FRAME_LAST,
                     VSPH_JOBS_FRAME_ALL};
  const struct vsph_archive_frames fr = {2, name, want,
                                         VSPH_ARCHIVE_FRAME_BITS};
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  for (int k = 0; k <= last; k++)
    frame_is(a, entry, k, k == 0 || k == last ? VSPH_VTK_FRAME_SCALARS : 0u);
  char key[4096], seal[4096];
  snprintf(path, sizeof path, "%s/key.txt", a);
  vsph_test_slurp(path, key, sizeof key);
  *strstr(key, "files:\n") = '\0';
  ck_assert_int_eq(
      vsph_folder_verify(entry, &vsph_folder_scene_run, key, NULL, NULL, 0), 1);
  snprintf(path, sizeof path, "%s/key.txt", entry);
  vsph_test_slurp(path, seal, sizeof seal);
  ck_assert_ptr_nonnull(strstr(seal, "\nsnap_0003.vtp "));
  ck_assert_ptr_null(strstr(seal, "\nsnap_0001.vtp "));
  /* ParaView's time series of the frames, each at its snapshot's time as
   * the run's own collection gives it */
  char pvd[4096], runpvd[4096], line[200];
  snprintf(path, sizeof path, "%s/snapshots.pvd", entry);
  vsph_test_slurp(path, pvd, sizeof pvd);
  snprintf(path, sizeof path, "%s/snapshots.pvd", a);
  vsph_test_slurp(path, runpvd, sizeof runpvd);
  for (int k = 0; k <= last; k++) {
    snprintf(line, sizeof line, "file=\"snap_%04d.vtp\"", k);
    const char *l = strstr(runpvd, line);
    ck_assert_ptr_nonnull(l);
    while (l > runpvd && l[-1] != '\n') l--;
    snprintf(line, sizeof line, "%.*s", (int)(strchr(l, '\n') - l), l);
    ck_assert_msg(!strstr(pvd, line) == !(k == 0 || k == last), "%s", line);
  }
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr, NULL, &n), 0);
  ck_assert_uint_eq(n.kept, 1);
  ck_assert_uint_eq(n.stored, 0);
  want[0] = VSPH_JOBS_FRAME_ALL | VSPH_JOBS_FRAME_LAST;
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  for (int k = 0; k <= last; k++)
    frame_is(
        a, entry, k,
        VSPH_VTK_FRAME_VELOCITY | (k == last ? VSPH_VTK_FRAME_SCALARS : 0u));
  /* the same snapshots with more fields, or at other bits: stored again */
  want[0] |= VSPH_JOBS_FRAME_FIRST;
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  frame_is(a, entry, 0, VSPH_VTK_FRAME_VELOCITY | VSPH_VTK_FRAME_SCALARS);
  struct vsph_archive_frames fr4 = fr;
  fr4.bits = 4;
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr4, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  {
    struct vsph_vtk_snapshot f;
    snprintf(path, sizeof path, "%s/snap_0001.vtp", entry);
    ck_assert_int_eq(vsph_vtk_read(path, &f), 0);
    ck_assert_int_eq(f.frame_bits, 4);
    vsph_vtk_snapshot_free(&f);
  }
  /* fewer snapshots asked: stored again, the others gone */
  want[0] = VSPH_JOBS_FRAME_FIRST | VSPH_JOBS_FRAME_LAST;
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  for (int k = 0; k <= last; k++)
    frame_is(a, entry, k, k == 0 || k == last ? VSPH_VTK_FRAME_SCALARS : 0u);
  want[0] = VSPH_JOBS_FRAME_FIRST; /* the first alone, unchanged */
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  for (int k = 0; k <= last; k++)
    frame_is(a, entry, k, k == 0 ? VSPH_VTK_FRAME_SCALARS : 0u);
  /* a run asking more frames than an entry holds (64: here 71, a
   * snapshot at each of 70 outputs over 0.4 s and t = 0) is left out,
   * said as such; the other runs are stored */
  char b[300];
  snprintf(b, sizeof b, "%s/rep/runs/b", dir);
  static const char *const many[] = {"Solver:res=8", "Solver:t_end=0.4",
                                     "Solver:snapshots=70", NULL};
  ck_assert_int_eq(run("poiseuille", many, b, 0, &r), 0);
  static const char *const name2[] = {"a", "b"};
  const unsigned want2[] = {VSPH_JOBS_FRAME_ALL, VSPH_JOBS_FRAME_ALL};
  const struct vsph_archive_frames fr2 = {2, name2, want2,
                                          VSPH_ARCHIVE_FRAME_BITS};
  char log[4096] = "";
  FILE *lf = fmemopen(log, sizeof log - 1, "w");
  ck_assert_ptr_nonnull(lf);
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr2, lf, &n), 0);
  fclose(lf);
  ck_assert_uint_eq(n.stored, 1);
  ck_assert_uint_eq(n.skipped, 1);
  ck_assert_msg(strstr(log,
                       "runs/b is not archived: more than 64 of its "
                       "snapshots are asked as frames"),
                "%s", log);
  snprintf(path, sizeof path, "%s/runs/b", ar);
  ck_assert(!exists(path));
  /* a run that began before the one an entry keeps does not replace it
   * (a stale report folder), said as such: run c, then a second later
   * c again with other settings in another report, stored first */
  char rep2[300], c1[300], c2[300], keyc[4096];
  snprintf(rep2, sizeof rep2, "%s/rep2", dir);
  snprintf(c1, sizeof c1, "%s/rep/runs/c", dir);
  snprintf(c2, sizeof c2, "%s/rep2/runs/c", dir);
  ck_assert_int_eq(run("poiseuille", set, c1, 0, &r), 0);
  sleep(1); /* run.json's date counts seconds */
  static const char *const set2[] = {"Solver:res=8", "Solver:t_end=0.03", NULL};
  ck_assert_int_eq(run("poiseuille", set2, c2, 0, &r), 0);
  ck_assert_int_eq(vsph_archive_store(rep2, ar, NULL, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  lf = fmemopen(log, sizeof log - 1, "w");
  ck_assert_ptr_nonnull(lf);
  ck_assert_int_eq(vsph_archive_store_frames(rep, ar, NULL, &fr, lf, &n), 0);
  fclose(lf);
  ck_assert_msg(strstr(log, "runs/c is not archived: it began ") &&
                    strstr(log, "which stays"),
                "%s", log);
  snprintf(path, sizeof path, "%s/key.txt", c2);
  vsph_test_slurp(path, keyc, sizeof keyc);
  *strstr(keyc, "files:\n") = '\0';
  snprintf(path, sizeof path, "%s/runs/c", ar);
  ck_assert_int_eq(
      vsph_folder_verify(path, &vsph_folder_scene_run, keyc, NULL, NULL, 0), 1);
  vsph_test_rm_tree(dir);
}
END_TEST

START_TEST(test_archive_store) {
  char dir[] = "/tmp/vsph_archiveXXXXXX", rep[300], a[300], b[300], ar[300],
       path[800], other[700];
  vsph_test_scratch(dir);
  snprintf(rep, sizeof rep, "%s/rep", dir);
  snprintf(a, sizeof a, "%s/rep/runs/a", dir);
  snprintf(b, sizeof b, "%s/rep/runs/b", dir);
  snprintf(ar, sizeof ar, "%s/ar", dir);
  static const char *const set[] = {"Solver:res=8", "Solver:t_end=0.02",
                                    "Solver:snapshots=2", NULL};
  static const char *const set2[] = {"Solver:res=8", "Solver:t_end=0.03",
                                     "Solver:snapshots=2", NULL};
  struct vsph_rundir_result r;
  ck_assert_int_eq(run("poiseuille", set, a, 0, &r), 0);
  ck_assert_int_eq(run("poiseuille", set, b, 0, &r), 0);
  snprintf(path, sizeof path, "%s/energy.csv", b);
  FILE *f = fopen(path, "a");
  ck_assert_ptr_nonnull(f);
  fputs("1,2\n", f); /* b's seal breaks */
  ck_assert_int_eq(fclose(f), 0);
  struct vsph_archive_counts n;
  ck_assert_int_eq(vsph_archive_store(rep, ar, "abc1234", NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  ck_assert_uint_eq(n.skipped, 1);
  /* the entry: sealed under a's key, its tables as they were, no
   * snapshots */
  char key[4096], entry[400], cmd[1200], key2[400];
  snprintf(path, sizeof path, "%s/key.txt", a);
  vsph_test_slurp(path, key, sizeof key);
  *strstr(key, "files:\n") = '\0';
  snprintf(entry, sizeof entry, "%s/runs/a", ar);
  ck_assert_int_eq(
      vsph_folder_verify(entry, &vsph_folder_scene_run, key, NULL, NULL, 0), 1);
  static const char *const same[] = {"energy.csv", "run.json", "profile.csv",
                                     "used_parameters.yml", NULL};
  for (size_t k = 0; same[k]; k++) {
    snprintf(path, sizeof path, "%s/%s", a, same[k]);
    snprintf(other, sizeof other, "%s/%s", entry, same[k]);
    size_t la = 0, lb = 0;
    char *ta = vsph_files_slurp(path, &la), *tb = vsph_files_slurp(other, &lb);
    ck_assert_msg(ta && tb && la == lb && !memcmp(ta, tb, la), "%s", same[k]);
    free(ta);
    free(tb);
  }
  snprintf(path, sizeof path, "%s/snap_0000.vtp", a);
  ck_assert(exists(path));
  snprintf(path, sizeof path, "%s/snap_0000.vtp", entry);
  ck_assert(!exists(path));
  snprintf(path, sizeof path, "%s/runs/b", ar);
  ck_assert(!exists(path));
  /* index.tsv: a alone, with this build's source hash and the commit it
   * recorded (run.json's; the caller's where the build knew none) */
  char index[4096], row[300];
  snprintf(path, sizeof path, "%s/index.tsv", ar);
  vsph_test_slurp(path, index, sizeof index);
  snprintf(row, sizeof row, "\na\tscene run\tok\t%s\t%s\t%s\t", VSPH_VERSION,
           vsph_source_hash_id, vsph_commit_id[0] ? vsph_commit_id : "abc1234");
  ck_assert_msg(strstr(index, row), "%s", index);
  ck_assert_ptr_null(strstr(index, "\nb\t"));
  /* again: kept, and with nothing new the index is left byte for byte as
   * it was (with no commit given, the row's commit once read "unknown");
   * then a redone with other settings replaces its entry */
  struct stat i0, i1;
  ck_assert_int_eq(stat(path, &i0), 0);
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  ck_assert_uint_eq(n.kept, 1);
  ck_assert_uint_eq(n.stored, 0);
  ck_assert_int_eq(stat(path, &i1), 0); /* not written anew */
  ck_assert(i0.st_ino == i1.st_ino && i0.st_mtim.tv_sec == i1.st_mtim.tv_sec &&
            i0.st_mtim.tv_nsec == i1.st_mtim.tv_nsec);
  char again[4096];
  vsph_test_slurp(path, again, sizeof again);
  ck_assert_str_eq(again, index);
  ck_assert_int_eq(run("poiseuille", set2, a, 0, &r), 0);
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 1);
  ck_assert_int_eq(
      vsph_folder_verify(entry, &vsph_folder_scene_run, key, NULL, NULL, 0), 0);
  /* no .new or .old left by the swap; one left by a stopped store goes */
  snprintf(path, sizeof path, "%s.new", entry);
  ck_assert(!exists(path));
  snprintf(path, sizeof path, "%s.old", entry);
  ck_assert(!exists(path));
  snprintf(cmd, sizeof cmd, "cp -a %s %s.new", entry, entry);
  ck_assert_int_eq(system(cmd), 0);
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  ck_assert(!exists(path));
  /* a run whose file is not as its seal lists it is left out, and the
   * entry it would replace stays whole */
  snprintf(key2, sizeof key2, "%s/key.txt", a);
  vsph_test_slurp(key2, key, sizeof key);
  *strstr(key, "files:\n") = '\0';
  ck_assert_int_eq(run("poiseuille", set, a, 0, &r), 0);
  snprintf(path, sizeof path, "%s/profile.csv", a);
  f = fopen(path, "r+");
  ck_assert_ptr_nonnull(f);
  fputc('#', f); /* same size, another CRC: the seal breaks */
  ck_assert_int_eq(fclose(f), 0);
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  ck_assert_uint_eq(n.stored, 0);
  ck_assert_int_eq(
      vsph_folder_verify(entry, &vsph_folder_scene_run, key, NULL, NULL, 0), 1);
  /* a run whose name a TSV field cannot hold is left out; every row of
   * the index has its 10 fields */
  snprintf(cmd, sizeof cmd, "cp -a %s \"%s/rep/runs/t$(printf '\\t')x\"", entry,
           dir);
  ck_assert_int_eq(system(cmd), 0);
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), 0);
  ck_assert_uint_ge(n.skipped, 2);
  snprintf(path, sizeof path, "%s/index.tsv", ar);
  vsph_test_slurp(path, index, sizeof index);
  for (char *line = strchr(index, '\n') + 1; *line;) {
    char *end = strchr(line, '\n');
    ck_assert_ptr_nonnull(end);
    size_t tabs = 0;
    for (char *q = line; q < end; q++) tabs += *q == '\t';
    ck_assert_uint_eq(tabs, 9);
    line = end + 1;
  }
  /* refused before anything is written: a link in the archive's runs/ (to
   * a run elsewhere, which stays whole), a foreign file in an entry */
  snprintf(other, sizeof other, "%s/victim", dir);
  ck_assert_int_eq(run("poiseuille", set, other, 0, &r), 0);
  snprintf(path, sizeof path, "%s/runs/zlink", ar);
  ck_assert_int_eq(symlink(other, path), 0);
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), VSPH_EINVAL);
  snprintf(path, sizeof path, "%s/snap_0000.vtp", other);
  ck_assert(exists(path));
  snprintf(path, sizeof path, "%s/runs/zlink", ar);
  ck_assert_int_eq(remove(path), 0);
  snprintf(path, sizeof path, "%s/notes.txt", entry);
  put(path, "mine");
  ck_assert_int_eq(vsph_archive_store(rep, ar, NULL, NULL, &n), VSPH_EINVAL);
  ck_assert(exists(path));
  /* a foreign folder is refused, untouched */
  snprintf(other, sizeof other, "%s/foreign", dir);
  ck_assert_int_eq(mkdir(other, 0755), 0);
  snprintf(path, sizeof path, "%s/mine.txt", other);
  put(path, "mine");
  ck_assert_int_eq(vsph_archive_store(rep, other, NULL, NULL, &n), VSPH_EINVAL);
  snprintf(path, sizeof path, "%s/runs", other);
  ck_assert(!exists(path));
  vsph_test_rm_tree(dir);
}
END_TEST

START_TEST(test_folder_seal) {
  char dir[] = "/tmp/vsph_sealXXXXXX", sub[300], path[400], args[600];
  vsph_test_scratch(dir);
  snprintf(sub, sizeof sub, "%s/r", dir);
  struct vsph_rundir_result r;
  static const char *const set[] = {"Solver:res=8", "Solver:t_end=0.02", NULL};
  ck_assert_int_eq(run("poiseuille", set, sub, 0, &r), 0);
  char key[4096];
  snprintf(path, sizeof path, "%s/key.txt", sub);
  vsph_test_slurp(path, key, sizeof key);
  /* the parameters' key (vsph_rundir_key's) is what precedes "files:" */
  char *files = strstr(key, "files:\n");
  ck_assert_ptr_nonnull(files);
  files[0] = '\0';
  const char *k0 = key;
  char why[600];
  ck_assert_int_eq(vsph_folder_verify(sub, &vsph_folder_scene_run, k0, NULL,
                                      why, sizeof why),
                   1);
  /* another key: no seal of that run (0), not a damaged one */
  ck_assert_int_eq(vsph_folder_verify(sub, &vsph_folder_scene_run, "vsph x\n",
                                      NULL, why, sizeof why),
                   0);
  struct {
    const char *name, *how, *said;
  } cases[] = {{"energy.csv", "cut", "energy.csv differs"},
               {"profile.csv", "edit", "profile.csv differs"},
               /* (a run of 10 snapshots writes snap_0000..0010) */
               {"snap_0099.vtp", "add", "snap_0099.vtp is not in"},
               {"snap_0001.vtp", "remove", "snap_0001.vtp is missing"}};
  for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
    ck_assert_int_eq(run("poiseuille", set, sub, 0, &r), 0);
    snprintf(path, sizeof path, "%s/%s", sub, cases[c].name);
    if (!strcmp(cases[c].how, "cut")) {
      ck_assert_int_eq(truncate(path, 100), 0);
    } else if (!strcmp(cases[c].how, "edit")) {
      FILE *f = fopen(path, "r+");
      ck_assert_ptr_nonnull(f);
      fseek(f, 40, SEEK_SET);
      const int ch = fgetc(f);
      fseek(f, 40, SEEK_SET);
      fputc(ch == '9' ? '8' : '9', f);
      ck_assert_int_eq(fclose(f), 0);
    } else if (!strcmp(cases[c].how, "add")) {
      put(path, "forged\n");
    } else {
      ck_assert_int_eq(remove(path), 0);
    }
    ck_assert_int_eq(vsph_folder_verify(sub, &vsph_folder_scene_run, k0, NULL,
                                        why, sizeof why),
                     -1);
    ck_assert_msg(strstr(why, cases[c].said), "%s: %s", cases[c].name, why);
    /* --cache redoes the run, which seals it again */
    snprintf(args, sizeof args,
             "run poiseuille --res 8 --t-end 0.02 --cache --quiet --out %s",
             sub);
    struct vsph_test_outcome *o = vsph_test_cli(args);
    ck_assert_int_eq(o->status, 0);
    ck_assert_int_eq(vsph_folder_verify(sub, &vsph_folder_scene_run, k0, NULL,
                                        why, sizeof why),
                     1);
  }
  vsph_test_rm_tree(dir);
}
END_TEST

/* A Slurm task that meets its time limit gets SIGTERM ahead of it
 * (--signal=B:TERM@120, where the limit is 10 minutes or more: Slurm may
 * send it a minute early) and checkpoints; with a shorter limit, Slurm's
 * own SIGTERM at the limit. A stand-in sbatch takes the scripts. */
START_TEST(test_slurm_signal) {
  char dir[] = "/tmp/vsph_slurmXXXXXX", fake[300], args[900], path[400];
  vsph_test_scratch(dir);
  snprintf(fake, sizeof fake, "%s/sbatch", dir);
  put(fake, "#!/bin/sh\necho 4242\n");
  ck_assert_int_eq(chmod(fake, 0700), 0);
  static const struct {
    const char *limit;
    int signal;
  } cases[] = {{"30:00", 1},  {"10", 1},  {"9:59", 0},
               {"0-0:09", 0}, {"1-0", 1}, {"2:00:00", 1}};
  for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
    snprintf(args, sizeof args,
             "PATH='%s':\"$PATH\" exec \"$VSPH_BIN\" report submit --only "
             "stability --time %s --out %s/r%zu",
             dir, cases[k].limit, dir, k);
    struct vsph_test_outcome *o = vsph_test_shell(args);
    ck_assert_msg(o->status == 0, "%s: %s", args, o->err);
    char text[1 << 15];
    snprintf(path, sizeof path, "%s/r%zu/slurm/runs.sbatch", dir, k);
    vsph_test_slurp(path, text, sizeof text);
    ck_assert_ptr_nonnull(strstr(text, "#SBATCH --array"));
    ck_assert_msg((strstr(text, "#SBATCH --signal=B:TERM@120\n") != NULL) ==
                      cases[k].signal,
                  "--time %s", cases[k].limit);
    /* the assembly after them is the verb, with the report's parts */
    snprintf(path, sizeof path, "%s/r%zu/slurm/assemble.sbatch", dir, k);
    vsph_test_slurp(path, text, sizeof text);
    ck_assert_msg(strstr(text, " report assemble --out ") &&
                      strstr(text, " --only stability\n"),
                  "%s", text);
  }
  /* an sbatch that hangs is stopped after VSPH_SBATCH_TIMEOUT seconds:
   * the report refuses in one line saying so, and ends */
  put(fake, "#!/bin/sh\nsleep 30\necho 4243\n");
  snprintf(args, sizeof args,
           "PATH='%s':\"$PATH\" VSPH_SBATCH_TIMEOUT=1 exec \"$VSPH_BIN\" "
           "report submit --only stability --out %s/hang",
           dir, dir);
  const double t0 = (double)time(NULL);
  struct vsph_test_outcome *o = vsph_test_shell(args);
  ck_assert_msg(o->status == 1 && o->err_lines == 1 &&
                    strstr(o->err, "did not answer within 1 s"),
                "%d: %s", o->status, o->err);
  ck_assert_msg((double)time(NULL) - t0 < 20, "the report waited for sbatch");
  vsph_test_rm_tree(dir);
}
END_TEST

/* A report's folder is sealed too: its seal holds after the report, a
 * changed report.md breaks it by name, and the next report (the folder
 * is a report's) replaces it. */
START_TEST(test_report_seal) {
  char dir[] = "/tmp/vsph_repsealXXXXXX", out[300], path[400], args[600];
  vsph_test_scratch(dir);
  snprintf(out, sizeof out, "%s/rep", dir);
  snprintf(args, sizeof args, "report --only tensors --out %s", out);
  for (int pass = 0; pass < 2; pass++) {
    ck_assert_int_eq(vsph_test_cli(args)->status, 0);
    char key[1 << 14];
    snprintf(path, sizeof path, "%s/key.txt", out);
    vsph_test_slurp(path, key, sizeof key);
    char *files = strstr(key, "files:\n");
    ck_assert_ptr_nonnull(files);
    ck_assert_ptr_nonnull(strstr(files, "\nreport.md "));
    files[0] = '\0';
    char why[600];
    ck_assert_int_eq(vsph_folder_verify(out, &vsph_folder_report, key, NULL,
                                        why, sizeof why),
                     1);
    snprintf(path, sizeof path, "%s/report.md", out);
    FILE *f = fopen(path, "a");
    ck_assert_ptr_nonnull(f);
    fputs("edited\n", f);
    ck_assert_int_eq(fclose(f), 0);
    ck_assert_int_eq(vsph_folder_verify(out, &vsph_folder_report, key, NULL,
                                        why, sizeof why),
                     -1);
    ck_assert_msg(strstr(why, "report.md differs") != NULL, "%s", why);
  }
  vsph_test_rm_tree(dir);
}
END_TEST

/* What a hostile pass found (issue 23's review): a resume checks every
 * file the checkpoint saw (a snapshot removed, energy.csv edited in
 * place at the same size, a stale temporary) and starts over rather than
 * seal a mixture; the parameters file is this process's. */
START_TEST(test_resume_checks_files) {
  char dir[] = "/tmp/vsph_resumeXXXXXX", a[300], b[300], path[400];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  snprintf(b, sizeof b, "%s/b", dir);
  struct vsph_rundir_result r;
  ck_assert_int_eq(run("poiseuille", POIS, a, 0, &r), 0);
  char backup[400], before[8192], after[8192];
  snprintf(backup, sizeof backup, "%s/energy-backup.csv", dir);
  for (int c = 0; c < 4; c++) {
    ck_assert_int_eq(run("poiseuille", POIS, b, 10, &r), VSPH_EINTR);
    if (c == 0) { /* a snapshot gone */
      snprintf(path, sizeof path, "%s/snap_0001.vtp", b);
      ck_assert_int_eq(remove(path), 0);
    } else if (c == 1) { /* one digit of a row changed, the size kept */
      snprintf(path, sizeof path, "%s/energy.csv", b);
      FILE *f = fopen(path, "r+");
      ck_assert_ptr_nonnull(f);
      fseek(f, 120, SEEK_SET);
      const int ch = fgetc(f);
      fseek(f, 120, SEEK_SET);
      fputc(ch == '1' ? '2' : '1', f);
      ck_assert_int_eq(fclose(f), 0);
    } else if (c == 2) { /* temporaries left by a killed writer: removed,
                            not sealed (a snapshot's scratch file, where
                            the file system has no unnamed files, killed
                            between mkstemp and unlink) */
      snprintf(path, sizeof path, "%s/checkpoint.bin.tmp", b);
      put(path, "half a checkpoint");
      snprintf(path, sizeof path, "%s/.vsph-vtk-a1B2c3", b);
      put(path, "a snapshot's compressed arrays");
    } else { /* a hard link kept of energy.csv: the resume leaves it be */
      snprintf(path, sizeof path, "%s/energy.csv", b);
      ck_assert_int_eq(link(path, backup), 0);
      vsph_test_slurp(backup, before, sizeof before);
    }
    ck_assert_int_eq(run("poiseuille", POIS, b, 0, &r), 0);
    ck_assert_msg(r.segments == (c >= 2 ? 2u : 1u), "case %d: %zu", c,
                  r.segments); /* cases 0, 1: started over */
    snprintf(path, sizeof path, "%s/.vsph-vtk-a1B2c3", b);
    ck_assert_int_ne(access(path, F_OK), 0); /* the stale scratch removed */
    if (c == 3) {
      vsph_test_slurp(backup, after, sizeof after);
      ck_assert_str_eq(before, after);
    }

    same_run(a, b);
  }
  vsph_test_rm_tree(dir);
}
END_TEST

/* Paths a refusal must leave as they were: a name too long for the run's
 * folder (it was cut, and the run went into another folder), folders of
 * the path made before the refusal, and another kind's folder reached
 * through "..": its marker and lock stay. */
START_TEST(test_refusal_leaves_paths) {
  char dir[] = "/tmp/vsph_pathsXXXXXX", args[1600], path[1200];
  vsph_test_scratch(dir);
  char long_name[700];
  memset(long_name, 'x', 600);
  long_name[600] = '\0';
  snprintf(args, sizeof args,
           "run poiseuille --res 8 --t-end 0.01 --quiet --out %s/new/%s", dir,
           long_name);
  struct vsph_test_outcome *o = vsph_test_cli(args);
  ck_assert_msg(o->status == 2 && strstr(o->err, "too long"), "%d %s",
                o->status, o->err);
  snprintf(path, sizeof path, "%s/new", dir);
  ck_assert(!exists(path));
  /* a name no file system takes: the folders made on the way go again */
  char deep[400];
  memset(deep, 'y', 300);
  deep[300] = '\0';
  snprintf(args, sizeof args,
           "contact --scheme contact --kernel wendland2 --alpha 0.5 --res 8 "
           "--set Scene:Ly=4e-7 --set Scene:Lz=4e-7 --t-end 1e-10 --out "
           "%s/new2/%s",
           dir, deep);
  o = vsph_test_cli(args);
  ck_assert_msg(o->status == 2, "%d %s", o->status, o->err);
  snprintf(path, sizeof path, "%s/new2", dir);
  ck_assert(!exists(path));
  /* a shear test's folder reached through a new folder and ".." */
  snprintf(args, sizeof args,
           "contact --scheme contact --kernel wendland2 --alpha 0.5 --res 8 "
           "--set Scene:Ly=4e-7 --set Scene:Lz=4e-7 --t-end 1e-10 --out "
           "%s/sh",
           dir);
  ck_assert_int_eq(vsph_test_cli(args)->status, 0);
  snprintf(args, sizeof args,
           "run poiseuille --res 8 --t-end 0.01 --quiet --out %s/sh/newdir/..",
           dir);
  o = vsph_test_cli(args);
  ck_assert_msg(o->status == 2 && strstr(o->err, "shear test"), "%d %s",
                o->status, o->err);
  snprintf(path, sizeof path, "%s/sh/%s", dir, VSPH_FOLDER_MARKER);
  ck_assert(exists(path));
  snprintf(path, sizeof path, "%s/sh/%s", dir, VSPH_FOLDER_LOCK);
  ck_assert(exists(path));
  snprintf(path, sizeof path, "%s/sh/newdir", dir);
  ck_assert(!exists(path));
  /* a lock file that is a folder, or shares its inode, or a user's own
   * small file of that name alone in a folder (it was taken over as a
   * lone lock before): refused, exit 2, the file untouched */
  for (int k = 0; k < 3; k++) {
    char sub[300], lock[400], victim[400];
    snprintf(sub, sizeof sub, "%s/l%d", dir, k);
    ck_assert_int_eq(mkdir(sub, 0700), 0);
    snprintf(lock, sizeof lock, "%s/%s", sub, VSPH_FOLDER_LOCK);
    snprintf(victim, sizeof victim, "%s/victim%d", dir, k);
    put(victim, "keep me\n");
    if (k == 0)
      ck_assert_int_eq(mkdir(lock, 0700), 0);
    else if (k == 1)
      ck_assert_int_eq(link(victim, lock), 0);
    else
      put(lock, "keep me\n"), snprintf(victim, sizeof victim, "%s", lock);
    snprintf(args, sizeof args,
             "run poiseuille --res 8 --t-end 0.01 --quiet --out %s", sub);
    o = vsph_test_cli(args);
    ck_assert_msg(o->status == 2 && o->err_lines == 1, "%d %s", o->status,
                  o->err);
    char text[32];
    vsph_test_slurp(victim, text, sizeof text);
    ck_assert_str_eq(text, "keep me\n");
  }
  /* a lone lock as a killed vsph leaves it (its pid): claimed */
  char sub[300], lock[400];
  snprintf(sub, sizeof sub, "%s/stale", dir);
  ck_assert_int_eq(mkdir(sub, 0700), 0);
  snprintf(lock, sizeof lock, "%s/%s", sub, VSPH_FOLDER_LOCK);
  put(lock, "999999\n");
  snprintf(args, sizeof args,
           "run poiseuille --res 8 --t-end 0.01 --quiet --out %s", sub);
  o = vsph_test_cli(args);
  ck_assert_msg(o->status == 0, "a stale lock: %d %s", o->status, o->err);
  vsph_test_rm_tree(dir);
}
END_TEST

/* The shear test checkpoints and resumes as a run does: stopped after its
 * first step (the stop seen between steps), it leaves checkpoint.bin and
 * no seal, exit VSPH_EINTR; the same call again goes on from it and ends
 * with profiles.csv byte for byte the uninterrupted test's and summary.csv
 * the same but for its wall-time column; a checkpoint of other settings is
 * not used. */
static struct vsph_params *shear_params(const char *res) {
  struct vsph_params *prm = vsph_params_alloc();
  ck_assert_ptr_nonnull(prm);
  const char *set[] = {"Scene:Ly=1.6e-7", "Scene:Lz=1.6e-7",
                       "Solver:t_end=4e-10", res};
  for (size_t k = 0; k < 4; k++)
    ck_assert_int_eq(vsph_params_assign(prm, set[k]), 0);
  ck_assert_int_eq(vsph_jobs_defaults(VSPH_JOBS_SHEAR, NULL, prm), 0);
  return prm;
}

/* summary.csv's text without its wall_s column (the 14th). */
static void summary_sans_wall(const char *dir, char *out, size_t n) {
  char path[400], text[8192];
  snprintf(path, sizeof path, "%s/summary.csv", dir);
  vsph_test_slurp(path, text, sizeof text);
  size_t o = 0;
  int col = 1;
  for (const char *c = text; *c && o + 1 < n; c++) {
    if (*c == '\n') col = 0;
    if (*c == ',' || *c == '\n') col++;
    if (col != 14) out[o++] = *c;
  }
  out[o] = '\0';
}

START_TEST(test_shear_checkpoint) {
  char dir[] = "/tmp/vsph_shckXXXXXX", a[300], b[300];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  snprintf(b, sizeof b, "%s/b", dir);
  int cached;
  struct vsph_params *prm = shear_params("Solver:res=16");
  ck_assert_int_eq(vsph_sheartest_execute(prm, 2, a, 0, 1, NULL, &cached), 0);
  vsph_params_free(prm);
  volatile sig_atomic_t stop = SIGTERM;
  prm = shear_params("Solver:res=16");
  ck_assert_int_eq(vsph_sheartest_execute(prm, 2, b, 0, 1, &stop, &cached),
                   VSPH_EINTR);
  vsph_params_free(prm);
  char path[400];
  snprintf(path, sizeof path, "%s/checkpoint.bin", b);
  ck_assert(exists(path));
  snprintf(path, sizeof path, "%s/key.txt", b);
  ck_assert(!exists(path));
  stop = 0;
  prm = shear_params("Solver:res=16");
  ck_assert_int_eq(vsph_sheartest_execute(prm, 2, b, 0, 1, &stop, &cached), 0);
  vsph_params_free(prm);
  snprintf(path, sizeof path, "%s/checkpoint.bin", b);
  ck_assert(!exists(path));
  static char pa[1 << 16], pb[1 << 16];
  snprintf(path, sizeof path, "%s/profiles.csv", a);
  vsph_test_slurp(path, pa, sizeof pa);
  snprintf(path, sizeof path, "%s/profiles.csv", b);
  vsph_test_slurp(path, pb, sizeof pb);
  ck_assert_str_eq(pa, pb);
  summary_sans_wall(a, pa, sizeof pa);
  summary_sans_wall(b, pb, sizeof pb);
  ck_assert_str_eq(pa, pb);
  /* stopped again, then asked with other settings: not used, said */
  stop = SIGTERM;
  prm = shear_params("Solver:res=16");
  snprintf(path, sizeof path, "%s/c", dir);
  ck_assert_int_eq(vsph_sheartest_execute(prm, 2, path, 0, 1, &stop, &cached),
                   VSPH_EINTR);
  vsph_params_free(prm);
  stop = 0;
  prm = shear_params("Solver:res=18");
  ck_assert_int_eq(vsph_sheartest_execute(prm, 2, path, 0, 1, &stop, &cached),
                   0);
  vsph_params_free(prm);
  vsph_test_rm_tree(dir);
}
END_TEST

/* `vsph run OUT ...` started in the background, its stderr to null. */
static pid_t spawn_run(const char *const *args) {
  const pid_t pid = fork();
  ck_assert_int_ge(pid, 0);
  if (pid == 0) {
    if (!freopen("/dev/null", "w", stderr)) _exit(126);
    execv(getenv("VSPH_BIN"), (char *const *)args);
    _exit(127);
  }
  return pid;
}

static int wait_status(pid_t pid) {
  int ws;
  ck_assert_int_eq(waitpid(pid, &ws, 0), pid);
  return WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + WTERMSIG(ws);
}

/* SIGTERM wherever it lands (between steps, within one, at an output),
 * again and again until the run ends: bitwise the run never stopped. The
 * signals come after 8-30 % of the uninterrupted run's wall time T (at
 * least 30 ms), so at least two land before the end unless the machine
 * runs the stopped runs over twice as fast as it ran the first (a fixed
 * 0.1-0.35 s let a fast machine finish at the second try: T was 0.5 s;
 * a fresh check's first run under a load of 4 that then fell stopped only
 * once): such a round is made again from nothing with half the delays.
 * A step here takes milliseconds: most signals land within a step, which
 * is put back as it began (from the state it started from, after its
 * wrap and sort: solver/integrate's put_back). */
START_TEST(test_restart_any_signal) {
  char dir[] = "/tmp/vsph_anysigXXXXXX", a[300], b[300], args[600];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  snprintf(b, sizeof b, "%s/b", dir);
  /* the vortex patch (a free surface); Poiseuille (periodic images and
   * mirror ghosts: a put-back step's positions are wrapped, its ghosts
   * made again); the standing wave (walls and gravity) */
  static const char *const CASE[][3] = {{"vortex-patch", "60", "0.5"},
                                        {"poiseuille", "20", "0.2"},
                                        {"standing-wave", "30", "1"}};
  const char *const *c = CASE[_i];
  snprintf(args, sizeof args,
           "run %s --res %s --t-end %s --snapshots 3 --quiet --out %s", c[0],
           c[1], c[2], a);
  struct timespec t0, t1;
  clock_gettime(CLOCK_MONOTONIC, &t0);
  ck_assert_int_eq(vsph_test_cli(args)->status, 0);
  clock_gettime(CLOCK_MONOTONIC, &t1);
  const double T_ms = 1e3 * (double)(t1.tv_sec - t0.tv_sec) +
                      1e-6 * (double)(t1.tv_nsec - t0.tv_nsec);
  const char *const run_b[] = {
      "vsph",        "run", c[0],      "--res", c[1], "--t-end", c[2],
      "--snapshots", "3",   "--quiet", "--out", b,    NULL};
  int rc = -1, stops = 0;
  srand(2385); /* the same fractions every time */
  /* a round that ends after fewer than two stops (the machine ran the
   * stopped runs much faster than the first: a load that fell) proves
   * too little: it is made again from nothing with half the delays, at
   * most four times */
  double scale = 1.0;
  for (int round = 0; round < 5 && stops < 2; round++, scale *= 0.5) {
    if (round) {
      vsph_test_rm_tree(b);
      rc = -1;
      stops = 0;
    }
    for (int k = 0; k < 60 && rc != 0; k++) {
      const pid_t pid = spawn_run(run_b);
      const double u = (double)rand() / ((double)RAND_MAX + 1.0);
      const long ms =
          (long)fmax(30.0 * scale, scale * T_ms * (0.08 + 0.22 * u));
      nanosleep(&(struct timespec){ms / 1000, (ms % 1000) * 1000000L}, NULL);
      kill(pid, SIGTERM);
      rc = wait_status(pid);
      ck_assert_msg(rc == 0 || rc == 128 + SIGTERM, "exit %d", rc);
      stops += rc != 0;
    }
    ck_assert_int_eq(rc, 0);
  }
  ck_assert_int_ge(stops, 2);
  same_run(a, b);
  vsph_test_rm_tree(dir);
}
END_TEST

/* A signal during a long set-up (a million particles: seconds of layout
 * and Poisson solve) ends vsph at once, with one line: nothing had been
 * written, and nothing is. */
START_TEST(test_stop_during_setup) {
  char dir[] = "/tmp/vsph_setupXXXXXX", out[300];
  vsph_test_scratch(dir);
  snprintf(out, sizeof out, "%s/big", dir);
  const char *const run_big[] = {"vsph",  "run",     "stretching-square",
                                 "--res", "1000",    "--t-end",
                                 "1e-9",  "--quiet", "--out",
                                 out,     NULL};
  const pid_t pid = spawn_run(run_big);
  nanosleep(&(struct timespec){0, 300000000L}, NULL);
  kill(pid, SIGTERM);
  ck_assert_int_eq(wait_status(pid), 128 + SIGTERM);
  ck_assert_msg(!exists(out), "the stopped set-up wrote %s", out);
  vsph_test_rm_tree(dir);
}
END_TEST

/* A report's parts (no runs) stop at once on a signal: exit 143, no
 * seal, nothing half written in place; the next report removes the
 * temporaries and completes. */
START_TEST(test_report_stops_at_once) {
  char dir[] = "/tmp/vsph_repstopXXXXXX", out[300], path[400];
  vsph_test_scratch(dir);
  snprintf(out, sizeof out, "%s/rep", dir);
  const char *const rep[] = {"vsph",  "report", "--only", "profiles",
                             "--out", out,      NULL};
  const pid_t pid = spawn_run(rep);
  nanosleep(&(struct timespec){0, 300000000L}, NULL);
  kill(pid, SIGTERM);
  ck_assert_int_eq(wait_status(pid), 128 + SIGTERM);
  snprintf(path, sizeof path, "%s/key.txt", out);
  ck_assert(!exists(path));
  snprintf(path, sizeof path, "%s/report.md", out);
  ck_assert(!exists(path));
  char args[600];
  snprintf(args, sizeof args, "report --only profiles --out %s", out);
  ck_assert_int_eq(vsph_test_cli(args)->status, 0);
  DIR *d = opendir(out);
  ck_assert_ptr_nonnull(d);
  for (struct dirent *e; (e = readdir(d));) {
    const size_t n = strlen(e->d_name);
    ck_assert_msg(n < 4 || strcmp(e->d_name + n - 4, ".tmp"), "%s left",
                  e->d_name);
  }
  closedir(d);
  vsph_test_rm_tree(dir);
}
END_TEST

/* A run made as one of several in a process, one per thread of an active
 * parallel region (a report's lanes), counts its own CPU time, not the
 * process's: here its neighbour thread spins for as long as it runs. One
 * thread cannot spend more CPU time than wall time; the 5 % and 10 ms
 * allow for the two clocks being read a few calls apart and their
 * granularity. Counting the process's clock instead gives the run about
 * wall_s + spun, which the spin's own minimum (a tenth of the wall time,
 * below the share it gets even beside a make -j2) puts outside that. */
START_TEST(test_cpu_own_lane) {
  static const char *const LONG[] = {"Solver:res=16", "Solver:t_end=0.5", NULL};
  char dir[] = "/tmp/vsph_laneXXXXXX", a[300];
  vsph_test_scratch(dir);
  snprintf(a, sizeof a, "%s/a", dir);
  struct vsph_rundir_result r;
  int st = -1, done = 0, threads = 0;
  double spun = 0.0;
#pragma omp parallel num_threads(2) shared(st, done, spun, threads, r)
  {
#pragma omp single nowait
    threads = omp_get_num_threads();
    if (omp_get_thread_num() == 0) {
      omp_set_num_threads(1); /* as a report's lane: its loops on itself */
      st = run("poiseuille", LONG, a, 0, &r);
#pragma omp atomic write
      done = 1;
    } else {
      const double c0 = vsph_sysinfo_thread_cpu_s();
      for (int d = 0; !d;) {
#pragma omp atomic read
        d = done;
      }
      spun = vsph_sysinfo_thread_cpu_s() - c0;
    }
  }
  ck_assert_int_eq(threads, 2);
  ck_assert_int_eq(st, 0);
  ck_assert_msg(spun > 0.1 * r.wall_s, "the neighbour spun %g s in %g s", spun,
                r.wall_s);
  ck_assert_msg(r.cpu_s > 0.0 && r.cpu_s <= 1.05 * r.wall_s + 0.01,
                "one thread's run: %g s of CPU in %g s", r.cpu_s, r.wall_s);
  vsph_test_rm_tree(dir);
}
END_TEST

/* runs/rundir.c: restart byte for byte, after a kill or any signal, a
 * stop during set-up, a report stopped at once, a run's CPU lane. */
Suite *vsph_rundir_suite(void) {
  Suite *s = suite_create("rundir");
  TCase *tc = tcase_create("restart");
  tcase_set_timeout(tc, 60);
  tcase_add_loop_test(tc, test_restart_bitwise, 0,
                      (int)(sizeof CASES / sizeof CASES[0]));
  tcase_add_test(tc, test_restart_within_outputs);
  tcase_add_test(tc, test_restart_refuses_foreign);
  tcase_add_test(tc, test_restart_after_kill);
  tcase_add_test(tc, test_resume_checks_files);
  tcase_add_loop_test(tc, test_restart_any_signal, 0, 3);
  tcase_add_test(tc, test_stop_during_setup);
  tcase_add_test(tc, test_report_stops_at_once);
  tcase_add_test(tc, test_cpu_own_lane);
  suite_add_tcase(s, tc);
  return s;
}

/* runs/folder.c: the folder contract (marker, lock, seal, manifest cache),
 * a report's seal, a Slurm task's signal, the paths a refusal leaves. */
Suite *vsph_folder_suite(void) {
  Suite *s = suite_create("folder");
  TCase *tf = tcase_create("contract");
  tcase_set_timeout(tf, 60);
  tcase_add_test(tf, test_folder_marker);
  tcase_add_test(tf, test_folder_lock);
  tcase_add_test(tf, test_folder_seal);
  tcase_add_test(tf, test_folder_manifest_cache);
  tcase_add_test(tf, test_slurm_signal);
  tcase_add_test(tf, test_shear_checkpoint);
  tcase_add_test(tf, test_report_seal);
  tcase_add_test(tf, test_refusal_leaves_paths);
  suite_add_tcase(s, tf);
  return s;
}

/* runs/archive.c: storing sealed runs, their frames, the summary. */
Suite *vsph_archive_suite(void) {
  Suite *s = suite_create("archive");
  TCase *tc = tcase_create("store");
  tcase_set_timeout(tc, 60);
  tcase_add_test(tc, test_archive_store);
  tcase_add_test(tc, test_archive_frames);
  tcase_add_test(tc, test_archive_summary);
  suite_add_tcase(s, tc);
  return s;
}
