/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* The CLI as a user meets it: every bad input is one line on stderr and
 * exit status 2, with nothing on stdout; --help works; JSON has the keys
 * the README promises. Runs the built binary ($VSPH_BIN). */
#include <cjson/cJSON.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "check_suites.h"

void vsph_test_slurp(const char *path, char *buf, size_t n) {
  FILE *f = fopen(path, "r");
  size_t got = f ? fread(buf, 1, n - 1, f) : 0;
  buf[got] = '\0';
  if (f) fclose(f);
}

void vsph_test_scratch(char *dir) { ck_assert_ptr_nonnull(mkdtemp(dir)); }

void vsph_test_rm_tree(const char *dir) {
  char cmd[600];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  ck_assert_int_eq(system(cmd), 0);
}

struct vsph_test_outcome *vsph_test_shell(const char *script) {
  static struct vsph_test_outcome o;
  ck_assert_msg(getenv("VSPH_BIN") != NULL,
                "VSPH_BIN is not set (run through make check)");
  char dir[] = "/tmp/vsph_cliXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  char cmd[4096], po[512], pe[512];
  snprintf(po, sizeof po, "%s/out", dir);
  snprintf(pe, sizeof pe, "%s/err", dir);
  snprintf(cmd, sizeof cmd, "( %s ) > %s 2> %s", script, po, pe);
  const int st = system(cmd);
  o.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  vsph_test_slurp(po, o.out, sizeof o.out);
  vsph_test_slurp(pe, o.err, sizeof o.err);
  o.err_lines = 0;
  for (const char *c = o.err; *c; c++) o.err_lines += *c == '\n';
  remove(po);
  remove(pe);
  rmdir(dir);
  return &o;
}

struct vsph_test_outcome *vsph_test_cli(const char *args) {
  char script[2048];
  snprintf(script, sizeof script, "exec \"$VSPH_BIN\" %s", args);
  return vsph_test_shell(script);
}

static const char *const bad_inputs[] = {
    "tensors --kernel gauss",
    "tensors --dim 4",
    "tensors --dim 0",
    "tensors --dim 2.5",
    "tensors --depth -0.5",
    "tensors --hdx 0",
    "tensors --hdx -1.2",
    "tensors --hdx abc",
    "tensors --method particles --dim 3 --hdx 1e6",
    "scaling --hdx 1e4",
    "tensors --depth 1.5x",
    "tensors --depth nan",
    "tensors --method sums",
    "tensors --lattice hex --dim 3 --method particles",
    "tensors --lattice triangle",
    "tensors --perturb 0.7 --lattice perturbed",
    "tensors --frobnicate",
    "tensors --kernel",
    "scaling --field shear",
    "scaling --field rotation --dim 1",
    "scaling --dim 7",
    "scaling --levels 1",
    "scaling --levels two",
    "scaling --hdx 0",
    "scaling --kernel nope",
    "dissipation --field strain --max-pairs 10",
    "dissipation --formulation sph --field strain",
    "dissipation --formulation mgf --field vortex",
    "dissipation --formulation mgf --field strain --shape circle",
    "dissipation --formulation mgf --field strain --res 1",
    "dissipation --formulation mgf --field strain --res -3",
    "dissipation --formulation mgf --field strain --hdx -1",
    "dissipation --formulation mgf --field strain --mu x",
    "report --only nothing",
    "report --bogus",
    "bench --size 3",
    "bench --size many",
    "bench --processes 0",
    "bench --processes 21",
    "bench --csv /nonexistent-dir/b.csv",
    "bench --csv ''",
    "bench --csv /tmp",
    "bench --csv /tmp/",
    "bench --csv /proc/vsph_never.csv",
    "bench --raw --processes 2",
    "bench --raw --csv /tmp/vsph_never.csv",
    "frobnicate",
    "run",
    "run nowhere",
    "run vortex-patch --visc sph",
    "run vortex-patch --kernel gauss",
    "run vortex-patch --res 2",
    "run vortex-patch --res ten",
    "run vortex-patch --cfl 0",
    "run vortex-patch --set nu=1",
    "run vortex-patch --set Scene:nu",
    "run vortex-patch --set Scene:bogus=1",
    "run vortex-patch --set Solver:bogus=1",
    "run vortex-patch --set Scene:R=-1",
    "run vortex-patch --set Scene:nu=abc",
    "run vortex-patch --params /nonexistent/p.yml",
    "run stretching-square --frobnicate 1",
    "scenes --bogus",
    /* issue 8: each of these ran (for ever, or with another value, or
     * with a NaN row, or exited 1) before bounds were checked */
    "run stretching-square --set Solver:snapshots=1e20",
    "run stretching-square --set Solver:hdx=1e-300",
    "run standing-wave --set Scene:Re=1e-300",
    "run vortex-patch --set Solver:seed=1e300",
    "run stretching-square --set Scene:poisson_grid=1e300",
    "run vortex-patch --threads 4294967296",
    "run stretching-square --set Scene:A0=0 --set Scene:nu=0",
    "run vortex-patch --set Scene:omega0=1e200",
    "run vortex-patch --set Solver:outputs=5",
    "run stretching-square --quiet extra",
    "report --only ''",
    "tensors --dim ' 2'",
    "tensors --depth 0x10",
    "tensors --hdx 1e-300",
    "dissipation --formulation mgf --field strain --hdx 1e6",
    /* issue 10 */
    "dissipation --formulation mgf --field rotation --angle 30",
    "dissipation --formulation mgf --field strain --angle 400",
    "run vortex-patch --set Scene:layout=hex",
    "run poiseuille --eos bogus",
    "run poiseuille --p0 125000",
    "run vortex-patch --eos gas",
    "run standing-wave --eos tait",
    "run poiseuille --reduce 2",
    "run poiseuille --correction first",
    "run poiseuille --visc takeda --correction shepard",
    "run poiseuille --visc er --zeta -1",
    "report --only scenes:nowhere",
    "report --only tensors:vortex-patch",
    /* issue 11 */
    "laplacian --form visc05",
    "laplacian --dim 4",
    "laplacian --perturb 0.6",
    "laplacian --field cubic",
    "laplacian --n 1",
    "laplacian --kernel spline",
    /* an --out that cannot be made: a file in the path */
    "run stretching-square --res 10 --t-end 0.01 --out /dev/null/r",
    "report --only patch --out /dev/null/r",
    /* issue 43: a finite-volume folder that is not one */
    "report --only patch --fv /nonexistent",
    "report --only patch --fv /etc/passwd",
    "",
};

START_TEST(test_bad_input_one_line_exit_2) {
  struct vsph_test_outcome *o = vsph_test_cli(bad_inputs[_i]);
  ck_assert_msg(o->status == 2, "'%s' exited %d", bad_inputs[_i], o->status);
  ck_assert_msg(o->err_lines == 1, "'%s' wrote %d stderr lines: %s",
                bad_inputs[_i], o->err_lines, o->err);
  ck_assert_msg(o->out[0] == '\0', "'%s' wrote to stdout", bad_inputs[_i]);
  ck_assert_msg(strstr(o->err, "vsph") == o->err, "'%s': %s", bad_inputs[_i],
                o->err);
}
END_TEST

/* vsph report archive's inputs beside the report folder: a history
 * that is not a folder holding commits.tsv, and a reports/baseline.csv
 * that is not a regular file, are refused with one line and exit 2,
 * before the archive is made. */
START_TEST(test_archive_inputs) {
  static const char *const env[] = {
      "VSPH_ARCHIVE_HISTORY=/etc/passwd", "VSPH_ARCHIVE_HISTORY=/nonexistent",
      "VSPH_ARCHIVE_HISTORY=r", /* a folder without commits.tsv */
      "mkdir -p reports/baseline.csv &&",
      /* the archive inside the report's own folder */
      "mkdir -p r/runs/a && rmdir r/runs/a &&"};
  char dir[] = "/tmp/vsph_arinXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  char script[6000], path[600], bin[2048], cwd[1024];
  const char *vb = getenv("VSPH_BIN");
  ck_assert_ptr_nonnull(vb);
  ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
  snprintf(bin, sizeof bin, "%s%s%.1000s", vb[0] == '/' ? "" : cwd,
           vb[0] == '/' ? "" : "/", vb);
  snprintf(script, sizeof script,
           "cd %s && mkdir -p r/runs && %s exec %s report archive --out r %s",
           dir, env[_i], bin, _i == 4 ? "r/runs/a" : "a");
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 2 && o->err_lines == 1, "%s: exit %d: %s", env[_i],
                o->status, o->err);
  snprintf(path, sizeof path, "%s/%s", dir, _i == 4 ? "r/runs/a" : "a");
  struct stat sb;
  ck_assert_msg(stat(path, &sb) != 0, "%s: the archive was made", env[_i]);
  vsph_test_rm_tree(dir);
}
END_TEST

/* vsph report archive with nothing new to store leaves the archive as
 * it was, entries.md included (it once rewrote a judged entries.md,
 * "stands" to "unjudged" and its commit to "unknown", exit 0): a run
 * archived, a line added to entries.md by hand as the mark of an earlier
 * judgement, the same archive again: exit 0, "nothing new", entries.md
 * byte for byte and not written anew (the same inode and time). */
START_TEST(test_archive_nothing_new) {
  char dir[] = "/tmp/vsph_arnnXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  char script[3000], path[600];
  snprintf(script, sizeof script,
           "B=$(realpath \"$VSPH_BIN\") && cd %s && mkdir -p r/runs && \"$B\" "
           "run stretching-square "
           "--res 10 --set Solver:t_end=0.01 --out r/runs/x > /dev/null && "
           "\"$B\" report archive --out r a 2> /dev/null && "
           "echo 'marked by an earlier judgement' >> a/entries.md",
           dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0, "exit %d: %s", o->status, o->err);
  snprintf(path, sizeof path, "%s/a/entries.md", dir);
  static char before[1 << 16], after[1 << 16];
  vsph_test_slurp(path, before, sizeof before);
  struct stat s0, s1;
  ck_assert_int_eq(stat(path, &s0), 0);
  snprintf(
      script, sizeof script,
      "B=$(realpath \"$VSPH_BIN\") && cd %s && \"$B\" report archive --out r a",
      dir);
  o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0 && strstr(o->err, "nothing new to store"),
                "exit %d: %s", o->status, o->err);
  vsph_test_slurp(path, after, sizeof after);
  ck_assert_str_eq(after, before);
  ck_assert_int_eq(stat(path, &s1), 0);
  ck_assert(s0.st_ino == s1.st_ino && s0.st_mtim.tv_sec == s1.st_mtim.tv_sec &&
            s0.st_mtim.tv_nsec == s1.st_mtim.tv_nsec);
  vsph_test_rm_tree(dir);
}
END_TEST

/* A report's --budget stops the shear tests too (it once ran one 56 s
 * past a 3 s budget): the contact part's 25 runs started at once (the
 * shear tests among them), a budget of 2 s: exit 0 and the budget said
 * spent, every shear test that started left with a checkpoint and no
 * result, and the report back well before a shear test's end (20 s: the
 * stop is seen between steps, each well under a second here; the rest is
 * slack for a loaded machine, inside the case's 30 s). */
START_TEST(test_budget_stops_shear) {
  char dir[] = "/tmp/vsph_bshXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  char script[3000];
  snprintf(script, sizeof script,
           "B=$(realpath \"$VSPH_BIN\") && cd %s && s=$(date +%%s) && \"$B\" "
           "report --only contact "
           "--jobs 25 --budget 2s --out r 2> log && cat log >&2 && echo wall "
           "$(($(date +%%s) - s)) && n=0 && for d in r/runs/contact-*; do "
           "[ -f \"$d/checkpoint.bin\" ] && [ ! -f \"$d/profiles.csv\" ] && "
           "n=$((n + 1)); done; echo stopped $n started $(grep -c 'started "
           "shear test' log)",
           dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0 && strstr(o->err, "the budget of 2 s is spent"),
                "exit %d: %s", o->status, o->err);
  long wall = -1, stopped = -1, started = -1;
  const char *w = strstr(o->out, "wall ");
  ck_assert_ptr_nonnull(w);
  ck_assert_int_eq(
      sscanf(w, "wall %ld\nstopped %ld started %ld", &wall, &stopped, &started),
      3);
  ck_assert_msg(wall <= 20, "the report took %ld s after a 2 s budget", wall);
  ck_assert_msg(started > 0 && stopped == started,
                "%ld of the %ld shear tests started stopped at a checkpoint",
                stopped, started);
  vsph_test_rm_tree(dir);
}
END_TEST

/* GNU's long options: --name=value is --name value (the same JSON, the
 * same run), a flag given a value is refused, and an option or a key a
 * slip away from a known one is named ("did you mean"), with the
 * section's keys listed for a key (common/params.c vsph_params_hint). */
START_TEST(test_gnu_options) {
  struct vsph_test_outcome *o =
      vsph_test_cli("tensors --kernel=wendland2 --dim=3 --json");
  ck_assert_msg(o->status == 0, "--opt=value: exit %d: %s", o->status, o->err);
  char a[1 << 16];
  snprintf(a, sizeof a, "%s", o->out);
  o = vsph_test_cli("tensors --kernel wendland2 --dim 3 --json");
  ck_assert_str_eq(a, o->out);
  static const struct {
    const char *args, *want;
  } bad[] = {
      {"run cavity --quiet=1", "--quiet takes no value"},
      {"run cavity --vsic mgf", "did you mean --visc?"},
      {"run cavity --vsic=mgf", "did you mean --visc?"},
      {"report --ony patch", "did you mean --only?"},
      {"run cavity --t-end 0.01 --set Solver:vsic=mgf --out /tmp/vsph-no",
       "did you mean Solver:visc? (the Solver keys: "},
      {"run cavity --t-end 0.01 --set Scene:Ree=100 --out /tmp/vsph-no",
       "did you mean Scene:Re? (the Scene keys: L, U, Re,"},
      {"run cavity --t-end 0.01 --set Solvr:cfl=1 --out /tmp/vsph-no",
       "did you mean Solver:cfl? (the sections: Solver, Scene)"},
      /* nothing near: no guess, the keys only */
      {"run cavity --t-end 0.01 --set Scene:zzzzzz=1 --out /tmp/vsph-no",
       "unknown parameter 'Scene:zzzzzz' (the Scene keys: "},
      {"run cavity --zzzzzz 1", "unknown option '--zzzzzz' (see --help)"},
  };
  for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
    o = vsph_test_cli(bad[k].args);
    ck_assert_msg(o->status == 2 && o->err_lines == 1 &&
                      strstr(o->err, bad[k].want) != NULL,
                  "'%s': exit %d, wanted '%s' in: %s", bad[k].args, o->status,
                  bad[k].want, o->err);
  }
  struct stat sb;
  ck_assert_msg(stat("/tmp/vsph-no", &sb) != 0, "a refused run wrote");
}
END_TEST

START_TEST(test_help_prints_usage) {
  const char *cmds[] = {"--help",         "tensors --help",
                        "scaling --help", "dissipation --help",
                        "report --help",  "bench --help"};
  for (size_t i = 0; i < sizeof cmds / sizeof cmds[0]; i++) {
    struct vsph_test_outcome *o = vsph_test_cli(cmds[i]);
    ck_assert_int_eq(o->status, 0);
    ck_assert_ptr_nonnull(strstr(o->out, "usage"));
  }
}
END_TEST

static cJSON *json_of(const char *args) {
  struct vsph_test_outcome *o = vsph_test_cli(args);
  ck_assert_msg(o->status == 0, "'%s' exited %d: %s", args, o->status, o->err);
  cJSON *j = cJSON_Parse(o->out);
  ck_assert_msg(j != NULL, "'%s' did not print JSON", args);
  return j;
}

/* A parameter file's shape mistakes, each named as what it is (they all
 * read "must sit inside a section" before): a section with no keys, a
 * section given a value, a setting at the top level, a name too long. */
START_TEST(test_params_file_messages) {
  static const struct {
    const char *text, *want;
  } c[] = {
      {"Solver:\\n", "section 'Solver' has no keys"},
      {"Solver: 8\\n", "'Solver: 8' stands at the top level"},
      {"cfl: 1\\n", "'cfl: 1' stands at the top level"},
      {NULL, "a name of 300 characters"}, /* Solver:, a key of 300 k */
  };
  char dir[] = "/tmp/vsph-yml-XXXXXX", script[2048], longkey[320];
  memcpy(longkey, "Solver:\\n  ", 11);
  memset(longkey + 11, 'k', 300);
  snprintf(longkey + 311, 9, ": 1\\n");
  vsph_test_scratch(dir);
  for (size_t k = 0; k < sizeof c / sizeof c[0]; k++) {
    snprintf(script, sizeof script,
             "printf '%%b' '%s' > '%s/p.yml' && \"$VSPH_BIN\" run cavity "
             "--params '%s/p.yml' --t-end 0.001 --out '%s/r'",
             c[k].text ? c[k].text : longkey, dir, dir, dir);
    struct vsph_test_outcome *o = vsph_test_shell(script);
    ck_assert_msg(o->status == 2 && o->err_lines == 1 &&
                      strstr(o->err, c[k].want) != NULL,
                  "'%s': exit %d, wanted '%s': %s", c[k].text, o->status,
                  c[k].want, o->err);
  }
  /* and on the command line: a --set key of 307 characters says its
   * length and the limit, not the whole of it */
  char set[400];
  memcpy(set, "run cavity --set Solver:", 24);
  memset(set + 24, 'k', 300);
  snprintf(set + 324, 40, "=1 --out %.20s", "/tmp/vsph_never_set");
  struct vsph_test_outcome *o = vsph_test_cli(set);
  ck_assert_msg(o->status == 2 &&
                    strstr(o->err, "a key of 307 characters (at most 255)") &&
                    strlen(o->err) < 200,
                "said: %s", o->err);
  char r[2100];
  snprintf(r, sizeof r, "%s/r", dir);
  struct stat sb;
  ck_assert_msg(stat(r, &sb) != 0, "a refused run wrote %s", r);
  vsph_test_rm_tree(dir);
}
END_TEST

/* vsph scaling's default table fits a terminal (a row per formulation,
 * not a column: it was 398 characters wide), its rows read back as the
 * JSON's figures (printed to 5 digits), and nothing prints as a negative
 * zero (MGF's normal component on rotation is an exact zero). */
START_TEST(test_scaling_table) {
  struct vsph_test_outcome *o = vsph_test_cli("scaling --field rotation");
  ck_assert_int_eq(o->status, 0);
  size_t width = 0;
  for (const char *l = o->out; *l;) {
    const size_t n = strcspn(l, "\n");
    width = n > width ? n : width;
    l += n + (l[n] == '\n');
  }
  ck_assert_msg(width <= 110, "a line of %zu characters", width);
  ck_assert_msg(strstr(o->out, "-0.0000e+00") == NULL &&
                    strstr(o->out, " -0.0000 ") == NULL,
                "a negative zero:\n%s", o->out);
  char out[1 << 16];
  snprintf(out, sizeof out, "%s", o->out);
  cJSON *j = json_of("scaling --field rotation --json");
  const char *row = strstr(out, "\nmeaf ");
  ck_assert_ptr_nonnull(row);
  double v[5];
  ck_assert_int_eq(sscanf(row, " meaf %lf %lf %lf %lf %lf", &v[0], &v[1], &v[2],
                          &v[3], &v[4]),
                   5);
  const cJSON *a = cJSON_GetObjectItemCaseSensitive(j, "meaf");
  ck_assert_int_eq(cJSON_GetArraySize(a), 5);
  for (int k = 0; k < 5; k++) {
    const double w = cJSON_GetArrayItem(a, k)->valuedouble;
    ck_assert_msg(fabs(v[k] - w) <= 5e-5 * fabs(w), "meaf[%d]: %g, JSON %g", k,
                  v[k], w);
  }
  cJSON_Delete(j);
}
END_TEST

/* JSON keys and shapes; values cross-checked against theory: at depth 0
 * N_d = -C_N and F_ddd = -2 C_F (tol: quadrature 1e-10). */
START_TEST(test_tensors_json_keys_and_identities) {
  cJSON *j = json_of("tensors --kernel wendland2 --dim 3 --json");
  const char *keys[] = {"kernel", "dim", "depth", "method", "F",
                        "G",      "N",   "M",     "C_F",    "C_N"};
  for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
    ck_assert_msg(cJSON_HasObjectItem(j, keys[i]), "missing %s", keys[i]);
  const double CF = cJSON_GetObjectItem(j, "C_F")->valuedouble;
  const double CN = cJSON_GetObjectItem(j, "C_N")->valuedouble;
  cJSON *F = cJSON_GetObjectItem(j, "F"), *G = cJSON_GetObjectItem(j, "G");
  ck_assert_int_eq(cJSON_GetArraySize(F), 3);
  ck_assert_int_eq(cJSON_GetArraySize(cJSON_GetArrayItem(
                       cJSON_GetArrayItem(cJSON_GetArrayItem(G, 0), 0), 0)),
                   3);
  const double F333 =
      cJSON_GetArrayItem(cJSON_GetArrayItem(cJSON_GetArrayItem(F, 2), 2), 2)
          ->valuedouble;
  ck_assert_double_eq_tol(F333, -2.0 * CF, 1e-9);
  const double N3 =
      cJSON_GetArrayItem(cJSON_GetObjectItem(j, "N"), 2)->valuedouble;
  ck_assert_double_eq_tol(N3, -CN, 1e-9);
  cJSON_Delete(j);

  j = json_of("scaling --field strain --levels 3 --json");
  const char *sk[] = {"h",    "hF",        "hN",         "mgf",       "meaf",
                      "pvwf", "slope_mgf", "slope_meaf", "slope_pvwf"};
  for (size_t i = 0; i < sizeof sk / sizeof sk[0]; i++)
    ck_assert_msg(cJSON_HasObjectItem(j, sk[i]), "missing %s", sk[i]);
  ck_assert_double_eq_tol(cJSON_GetObjectItem(j, "slope_mgf")->valuedouble,
                          -1.0, 1e-9);
  cJSON_Delete(j);

  j = json_of(
      "dissipation --formulation pvwf --field strain --shape disc "
      "--res 20 --json");
  const char *dk[] = {"P", "P_exact", "P_grad", "rel_error"};
  for (size_t i = 0; i < sizeof dk / sizeof dk[0]; i++)
    ck_assert_msg(cJSON_HasObjectItem(j, dk[i]), "missing %s", dk[i]);
  ck_assert_double_le(fabs(cJSON_GetObjectItem(j, "rel_error")->valuedouble),
                      1e-12);
  cJSON_Delete(j);
}
END_TEST

/* A short run writes every promised file; a run past the stability limit
 * (CFL 4, measured unstable within 8 steps) exits 0, keeps its output and
 * says "unstable" in run.json. Nothing is written for bad input. */
START_TEST(test_run_outputs) {
  char dir[] = "/tmp/vsph_runXXXXXX";
  ck_assert_ptr_nonnull(mkdtemp(dir));
  char args[512], path[600];
  snprintf(args, sizeof args,
           "run stretching-square --res 12 --t-end 0.02 --out %s/ok --set "
           "Solver:snapshots=2 --quiet",
           dir);
  struct vsph_test_outcome *o = vsph_test_cli(args);
  ck_assert_msg(o->status == 0, "run failed: %s", o->err);
  const char *files[] = {"energy.csv", "run.json", "used_parameters.yml",
                         "snap_0000.vtp", "snapshots.pvd"};
  for (size_t i = 0; i < sizeof files / sizeof files[0]; i++) {
    snprintf(path, sizeof path, "%s/ok/%s", dir, files[i]);
    ck_assert_msg(access(path, R_OK) == 0, "missing %s", files[i]);
  }
  snprintf(path, sizeof path, "%s/ok/energy.csv", dir);
  char head[512];
  vsph_test_slurp(path, head, sizeof head);
  ck_assert_msg(strncmp(head, "t,Ek,Ep,Ec,P_visc,", 18) == 0, "%s", head);
  ck_assert_ptr_nonnull(strstr(head, "residual,Px,Py,Lz"));
  ck_assert_ptr_nonnull(strstr(head, "Ek_ref,dEk_ref,Em_ref,dEm_ref"));
  snprintf(path, sizeof path, "%s/ok/run.json", dir);
  static char js[8192];
  vsph_test_slurp(path, js, sizeof js);
  cJSON *j = cJSON_Parse(js);
  ck_assert_ptr_nonnull(j);
  const char *keys[] = {"version",
                        "scene",
                        "visc",
                        "kernel",
                        "n_particles",
                        "steps",
                        "wall_s",
                        "cpu_s",
                        "load_average_start",
                        "load_average_end",
                        "peak_rss_bytes",
                        "pairs_per_s",
                        "status"};
  for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
    ck_assert_msg(cJSON_HasObjectItem(j, keys[i]), "missing %s", keys[i]);
  ck_assert_str_eq(cJSON_GetObjectItem(j, "status")->valuestring, "ok");
  ck_assert_int_eq(cJSON_GetObjectItem(j, "n_particles")->valueint, 144);
  /* the command line as given, and the start date (ISO 8601, UTC) */
  const cJSON *cline = cJSON_GetObjectItem(j, "command");
  ck_assert(cJSON_IsString(cline));
  ck_assert_msg(strstr(cline->valuestring,
                       "vsph run stretching-square --res "
                       "12 --t-end 0.02") != NULL,
                "%s", cline->valuestring);
  const cJSON *date = cJSON_GetObjectItem(j, "date");
  ck_assert(cJSON_IsString(date) && strlen(date->valuestring) == 20 &&
            date->valuestring[10] == 'T' && date->valuestring[19] == 'Z');
  /* the process's peak memory holds at least the integrator's buffers */
  ck_assert_double_ge(cJSON_GetObjectItem(j, "peak_rss_bytes")->valuedouble,
                      cJSON_GetObjectItem(j, "memory_bytes")->valuedouble);
  ck_assert_int_eq(
      cJSON_GetArraySize(cJSON_GetObjectItem(j, "load_average_start")), 3);
  cJSON_Delete(j);

  /* the OpenMP wait policy: a short spin unless the environment says
   * otherwise (vsph sets it and starts itself again before libgomp reads
   * it) */
  const char *policy[2][2] = {
      {"unset OMP_WAIT_POLICY GOMP_SPINCOUNT;", "GOMP_SPINCOUNT=1000"},
      {"unset GOMP_SPINCOUNT; export OMP_WAIT_POLICY=active;",
       "OMP_WAIT_POLICY=active"}};
  for (int k = 0; k < 2; k++) {
    char script[1024];
    snprintf(script, sizeof script,
             "%s exec \"$VSPH_BIN\" run stretching-square --res 8 --t-end "
             "0.005 --out %s/w%d --set Solver:snapshots=0 --quiet",
             policy[k][0], dir, k);
    o = vsph_test_shell(script);
    ck_assert_msg(o->status == 0, "run failed: %s", o->err);
    snprintf(path, sizeof path, "%s/w%d/run.json", dir, k);
    vsph_test_slurp(path, js, sizeof js);
    j = cJSON_Parse(js);
    ck_assert_ptr_nonnull(j);
    ck_assert_str_eq(cJSON_GetObjectItem(j, "omp_wait_policy")->valuestring,
                     policy[k][1]);
    cJSON_Delete(j);
  }

  snprintf(args, sizeof args,
           "run vortex-patch --res 16 --cfl 4 --t-end 10 --out %s/bad "
           "--quiet",
           dir);
  o = vsph_test_cli(args);
  ck_assert_int_eq(o->status, 0);
  ck_assert_ptr_nonnull(strstr(o->err, "unstable"));
  snprintf(path, sizeof path, "%s/bad/run.json", dir);
  vsph_test_slurp(path, js, sizeof js);
  j = cJSON_Parse(js);
  ck_assert_ptr_nonnull(j);
  ck_assert_str_eq(cJSON_GetObjectItem(j, "status")->valuestring, "unstable");
  ck_assert(cJSON_HasObjectItem(j, "unstable_time"));
  ck_assert(cJSON_HasObjectItem(j, "unstable_reason"));
  cJSON_Delete(j);
  snprintf(path, sizeof path, "%s/bad/energy.csv", dir);
  ck_assert_int_eq(access(path, R_OK), 0);

  snprintf(args, sizeof args, "run vortex-patch --set Scene:x=1 --out %s/no",
           dir);
  o = vsph_test_cli(args);
  ck_assert_int_eq(o->status, 2);
  snprintf(path, sizeof path, "%s/no", dir);
  ck_assert_int_ne(access(path, F_OK), 0); /* nothing written */
  char cmd[700];
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  ck_assert_int_eq(system(cmd), 0);
}
END_TEST

/* The options of vsph report and of each of its verbs, as the verbs'
 * contract has them (docs/usage.md): a '1' where the verb takes
 * REPORT_OPTS[k]. */
static const char *const REPORT_OPTS[] = {
    "--out",          "--only",    "--full",      "--fv",
    "--jobs",         "--threads", "--budget",    "--skip-archived",
    "--from-archive", "--beside",  "--partition", "--time"};
static const struct {
  const char *verb; /* "" for vsph report itself */
  const char *takes;
} REPORT_VERBS[] = {{"", "111111111100"},
                    {"plan", "111100000000"},
                    {"submit", "111101000011"},
                    {"assemble", "111100001100"},
                    {"archive", "100000000000"}};

/* The number of entries of folder @p dir (. and .. aside). */
static int entries_of(const char *dir) {
  char cmd[600];
  snprintf(cmd, sizeof cmd, "ls -A '%s' | wc -l", dir);
  return atoi(vsph_test_shell(cmd)->out);
}

/* vsph report's verbs (issue 44): each one's --help lists the options it
 * takes and no other, vsph report --help names every verb, and an option
 * a verb does not take is refused in one line naming the verb and those
 * that take it (exit 2), with nothing written. */
START_TEST(test_report_verbs) {
  const char *verb = REPORT_VERBS[_i].verb, *takes = REPORT_VERBS[_i].takes;
  const int adir = !strcmp(verb, "archive");
  char args[300], head[200], dir[] = "/tmp/vsph_verbXXXXXX";
  snprintf(args, sizeof args, "report %s --help", verb);
  struct vsph_test_outcome *o = vsph_test_cli(args);
  ck_assert_msg(o->status == 0, "'%s' exited %d", args, o->status);
  snprintf(head, sizeof head, "usage: vsph report %s%s", verb,
           *verb ? " " : "");
  ck_assert_msg(strstr(o->out, head) == o->out, "'%s': %.200s", args, o->out);
  for (size_t k = 0; k < sizeof REPORT_OPTS / sizeof REPORT_OPTS[0]; k++) {
    char line[64];
    snprintf(line, sizeof line, "\n  %s ", REPORT_OPTS[k]);
    ck_assert_msg((strstr(o->out, line) != NULL) == (takes[k] == '1'),
                  "'%s' %s %s", args, takes[k] == '1' ? "lacks" : "lists",
                  REPORT_OPTS[k]);
  }
  if (!*verb) /* vsph report's help names the verbs and their synopses */
    for (size_t v = 1; v < sizeof REPORT_VERBS / sizeof REPORT_VERBS[0]; v++) {
      char said[2][64];
      snprintf(said[0], sizeof said[0], "\n  %-10s ", REPORT_VERBS[v].verb);
      snprintf(said[1], sizeof said[1], "\n   or: vsph report %s [--out DIR]",
               REPORT_VERBS[v].verb);
      ck_assert_msg(strstr(o->out, said[0]) && strstr(o->out, said[1]),
                    "report --help lacks %s", REPORT_VERBS[v].verb);
    }
  /* each option it does not take: refused, in a folder that stays empty */
  vsph_test_scratch(dir);
  for (size_t k = 0; k < sizeof REPORT_OPTS / sizeof REPORT_OPTS[0]; k++) {
    if (takes[k] == '1') continue;
    char script[900];
    snprintf(script, sizeof script,
             "B=$(realpath \"$VSPH_BIN\") && cd %s && exec $B report %s "
             "%s%s --out r%s",
             dir, verb, REPORT_OPTS[k],
             strcmp(REPORT_OPTS[k], "--full") ? " 2" : "", adir ? " a" : "");
    o = vsph_test_shell(script);
    snprintf(head, sizeof head,
             "vsph report%s%s: %s is not an option of vsph report%s%s (",
             *verb ? " " : "", verb, REPORT_OPTS[k], *verb ? " " : "", verb);
    ck_assert_msg(o->status == 2 && o->err_lines == 1 && !o->out[0] &&
                      strstr(o->err, head) == o->err,
                  "'%s': exit %d: %s", script, o->status, o->err);
    ck_assert_msg(entries_of(dir) == 0, "'%s' wrote", script);
  }
  vsph_test_rm_tree(dir);
}
END_TEST

/* The old spellings of the verbs (--plan, --slurm, --assemble, --archive
 * ADIR among vsph report's options, as the Makefile, scripts and the
 * FULL archive's texts wrote them) are the verbs: the same bytes out, the
 * same files, the same refusals. A stand-in sbatch takes the Slurm
 * scripts. */
START_TEST(test_report_aliases) {
  char dir[] = "/tmp/vsph_aliasXXXXXX", script[2000];
  vsph_test_scratch(dir);
  static const char *const pairs[][2] = {
      {"plan --only contact --out r", "--only contact --plan --out r"},
      {"plan --full --only scenes --out r",
       "--full --plan --only scenes --out r"},
      {"assemble --only stability --out r",
       "--assemble --only stability --out r"},
      {"submit --only stability --out s", "--slurm --only stability --out s"},
      {"archive --out e a", "--out e --archive a"},
      {"archive --out e a", "--archive=a --out e"},
      /* refusals: the same line */
      {"archive --out e e/runs/a", "--out e --archive e/runs/a"},
      {"plan --jobs 2", "--plan --jobs 2"},
      {"submit --time 1h", "--slurm --time 1h"},
      {"assemble --budget 1h", "--budget 1h --assemble"}};
  char ref[3][1 << 16], *file[3] = {"s/slurm/runs.sbatch",
                                    "s/slurm/assemble.sbatch", "a/index.tsv"};
  for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; k++) {
    struct vsph_test_outcome was;
    for (int old = 0; old < 2; old++) {
      snprintf(script, sizeof script,
               "B=$(realpath \"$VSPH_BIN\") && cd %s && rm -rf r s a && "
               "mkdir -p e/runs && printf '#!/bin/sh\\necho 4242\\n' > sbatch "
               "&& chmod +x sbatch && PATH=\"$PWD:$PATH\" $B report %s",
               dir, pairs[k][old]);
      struct vsph_test_outcome *o = vsph_test_shell(script);
      for (int f = 0; f < 3; f++) {
        char path[700], got[1 << 16];
        snprintf(path, sizeof path, "%s/%s", dir, file[f]);
        vsph_test_slurp(path, old ? got : ref[f], sizeof got);
        ck_assert_msg(!old || !strcmp(got, ref[f]), "'%s': %s differs",
                      pairs[k][1], file[f]);
      }
      if (!old) {
        was = *o;
        continue;
      }
      ck_assert_msg(o->status == was.status && !strcmp(o->out, was.out) &&
                        !strcmp(o->err, was.err),
                    "'%s' (exit %d: %s) is not '%s' (exit %d: %s)", pairs[k][1],
                    o->status, o->err, pairs[k][0], was.status, was.err);
    }
    ck_assert_msg(k < 6 ? was.status <= 1 : was.status == 2, "'%s': exit %d",
                  pairs[k][0], was.status);
  }
  vsph_test_rm_tree(dir);
}
END_TEST

Suite *vsph_cli_suite(void) {
  Suite *s = suite_create("cli");
  TCase *tc = tcase_create("errors");
  tcase_set_timeout(tc, 30);
  tcase_add_loop_test(tc, test_archive_inputs, 0, 5);
  tcase_add_test(tc, test_archive_nothing_new);
  tcase_add_test(tc, test_budget_stops_shear);
  tcase_add_loop_test(tc, test_bad_input_one_line_exit_2, 0,
                      (int)(sizeof bad_inputs / sizeof bad_inputs[0]));
  tcase_add_test(tc, test_help_prints_usage);
  tcase_add_test(tc, test_scaling_table);
  tcase_add_test(tc, test_gnu_options);
  tcase_add_test(tc, test_params_file_messages);
  tcase_add_test(tc, test_tensors_json_keys_and_identities);
  tcase_add_test(tc, test_run_outputs);
  tcase_add_loop_test(tc, test_report_verbs, 0,
                      (int)(sizeof REPORT_VERBS / sizeof REPORT_VERBS[0]));
  tcase_add_test(tc, test_report_aliases);
  suite_add_tcase(s, tc);
  return s;
}
