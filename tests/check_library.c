/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* libvsph as another code sees it: installed by scripts/install (make
 * check stages a copy in $VSPH_STAGE), examples/regression built against
 * it through pkg-config, shared and static, and run; the values it
 * prints held to the closed forms here. Also the install's refusals and
 * an uninstall that removes what the install made and nothing else. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <check.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/references.h"
#include "../common/consts.h"
#include "../runs/archive.h"
#include "check_suites.h"

/* What the example must print: the line's label, the value by closed
 * form, and the tolerance (the example's own, see its comments). */
struct expect_line {
  const char *what;
  double want;
  double tol;
};

static const struct expect_line EXPECT[] = {
    /* M = delta on the full support, delta/2 on the half (THEORY.md 2):
     * quadrature at relative 1e-10, tenfold */
    {"M_xx, full support", 1.0, 1e-9},
    {"M_yy, full support", 1.0, 1e-9},
    {"M_xx, half support", 0.5, 1e-9},
    {"M_yy, half support", 0.5, 1e-9},
    /* rigid rotation: MGF's du.x vanishes pair by pair, so P is rounding
     * against the shear's */
    {"MGF dissipation, rotation / shear's", 0.0, 1e-12},
    {"MGF dissipation, shear < 0", 1.0, 0.0},
    {"MGF pairwise = particle form, shear", 1.0, 1e-12},
    /* W = 1, nu = 0.1, U0 = 1, y = 0.3: the steady parabola
     * 1 - (yc/d)^2 = 1 - 0.16 at nu t/W^2 = 10 (the transient e^-247 of
     * it), rest and dU/dt = 2 nu U0/d^2 = 0.8 at t = 0; rounding */
    {"Poiseuille U, nu t/W^2 = 10", 0.84, 1e-14},
    {"Poiseuille U, t = 0", 0.0, 0.0},
    {"Poiseuille dU/dt, t = 0", 0.8, 1e-14},
};
#define NEXPECT (sizeof EXPECT / sizeof EXPECT[0])

/* Every expected line in the output @p out, each value within its
 * tolerance of the closed form, and no line marked FAIL. */
static void assert_lines(const char *out, const char *which) {
  ck_assert_msg(strstr(out, "FAIL") == NULL, "%s: a line failed:\n%s", which,
                out);
  for (size_t e = 0; e < NEXPECT; e++) {
    const char *at = strstr(out, EXPECT[e].what);
    ck_assert_msg(at != NULL, "%s printed no line '%s':\n%s", which,
                  EXPECT[e].what, out);
    double got = NAN;
    ck_assert_int_eq(sscanf(at + strlen(EXPECT[e].what), "%lf", &got), 1);
    ck_assert_msg(fabs(got - EXPECT[e].want) <= EXPECT[e].tol,
                  "%s: %s = %.17g, closed form %.17g (tolerance %g)", which,
                  EXPECT[e].what, got, EXPECT[e].want, EXPECT[e].tol);
  }
}

/* The staged install's absolute path (make -C moves elsewhere). */
static const char *staged(char *buf) {
  const char *stage = getenv("VSPH_STAGE");
  ck_assert_msg(stage && *stage,
                "VSPH_STAGE (a staged install, made by make check) unset");
  ck_assert_msg(realpath(stage, buf) != NULL, "VSPH_STAGE %s: no such folder",
                stage);
  return buf;
}

START_TEST(test_installed_example) {
  char sbuf[4096];
  const char *stage = staged(sbuf);
  char dir[] = "/tmp/vsph-lib-XXXXXX", script[6 * 4096];
  vsph_test_scratch(dir);
  snprintf(script, sizeof script,
           "PKG_CONFIG_PATH='%s/lib/pkgconfig' make -s -C examples/regression "
           "OUT='%s' 2>&1 && '%s/regression' && '%s/regression-static' && "
           "ldd '%s/regression' && echo static: && ldd '%s/regression-static'",
           stage, dir, dir, dir, dir, dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0, "example: exit %d\n%s\n%s", o->status, o->out,
                o->err);
  /* the shared run and the static run each print every line */
  const char *second = strstr(o->out, "# 0 failed");
  ck_assert_ptr_nonnull(second);
  second = strstr(second + 1, "# libvsph");
  ck_assert_msg(second != NULL, "the static build printed nothing:\n%s",
                o->out);
  char first[1 << 14];
  const size_t n1 = (size_t)(second - o->out) < sizeof first
                        ? (size_t)(second - o->out)
                        : sizeof first - 1;
  memcpy(first, o->out, n1);
  first[n1] = '\0';
  assert_lines(first, "shared");
  assert_lines(second, "static");
  /* the shared one loads the staged library (lib/libvsph.so.0, or the
   * copy the loader picks in lib/glibc-hwcaps/: test_installed_dispatch);
   * the static one none */
  char want[4096 + 64];
  snprintf(want, sizeof want, "libvsph.so.0 => %s/lib/", stage);
  const char *st = strstr(o->out, "static:");
  ck_assert_ptr_nonnull(st);
  const char *so = strstr(o->out, want);
  ck_assert_msg(so != NULL && so < st, "shared example not linked to %s:\n%s",
                want, o->out);
  ck_assert_msg(strstr(st, "libvsph") == NULL,
                "static example loads libvsph:\n%s", st);
  vsph_test_rm_tree(dir);
}
END_TEST

/* The installed libvsph.so exports what the installed headers declare
 * (marked VSPH_API, common/api.h; -fvisibility=hidden hides the rest):
 * every global symbol of libvsph.a that a header names is exported, and
 * every exported one is named by a header, so no helper and nothing of
 * the program's layers (runs/, reports/, cli/) leaks out; and where
 * doxygen built the installed reference manual (make doc), every exported
 * name has its place in it. OpenMP's named-critical locks
 * (.gomp_critical_*) are the compiler's. */
START_TEST(test_exports_match_headers) {
  char stage[PATH_MAX], script[3 * PATH_MAX], dir[] = "/tmp/vsph-exp-XXXXXX";
  staged(stage);
  vsph_test_scratch(dir);
  snprintf(script, sizeof script,
           "cd '%s' && syms() { nm --defined-only \"$@\" | awk '$2 ~ "
           "/^[TDRBV]$/ && $3 !~ /^\\.gomp/ { print $3 }' | sort -u; } && "
           "syms -D lib/libvsph.so > '%s/exported' && "
           "syms lib/libvsph.a | comm -23 - '%s/exported' > '%s/hidden' && "
           "wc -l < '%s/exported' && "
           "echo hidden but named: && "
           "grep -rowhFf '%s/hidden' include/vsph | sort -u; "
           "echo exported but not named: && "
           "grep -rowhFf '%s/exported' include/vsph | sort -u | "
           "comm -13 - '%s/exported'; echo not in the manual: && "
           "if command -v doxygen > /dev/null; then "
           "test -f share/doc/vsph/html/index.html || echo no index.html; "
           "grep -rowhFf '%s/exported' share/doc/vsph/html | sort -u | "
           "comm -13 - '%s/exported'; fi; echo end",
           stage, dir, dir, dir, dir, dir, dir, dir, dir, dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  int n = 0;
  ck_assert_msg(sscanf(o->out, "%d", &n) == 1, "no count: %s %s", o->out,
                o->err);
  /* and, where doxygen built the manual (scripts/install-deps installs
   * it), every exported name has its place in the installed manual */
  const char *want =
      "hidden but named:\nexported but not named:\nnot in "
      "the manual:\nend\n";
  const char *at = strstr(o->out, "hidden but named:");
  ck_assert_msg(at && !strcmp(at, want), "%s", o->out);
  /* the public interface of docs/library.md: ~190 names */
  ck_assert_int_gt(n, 150);
  vsph_test_rm_tree(dir);
}
END_TEST

/* Every installed header compiles alone, first in a C11 file built with
 * pkg-config's flags and warnings as errors: it includes what it uses,
 * and only installed headers (make public-check holds the source tree to
 * the same), so a program may include any one of them by itself, as the
 * program's own layers do; the formulations' pair terms (solver/forms/)
 * too, though solver/pair.h includes them after the pair's geometry. */
START_TEST(test_headers_stand_alone) {
  char stage[PATH_MAX], script[4 * PATH_MAX], dir[] = "/tmp/vsph-hdr-XXXXXX";
  staged(stage);
  vsph_test_scratch(dir);
  snprintf(script, sizeof script,
           "cd '%s/include' && n=0 && for h in $(find vsph -name '*.h' "
           "| sort); do printf '#include "
           "<%%s>\nint main(void) { return 0; "
           "}\n' \"$h\" > '%s/one.c' && ${CC:-cc} -std=c11 -Wall -Wextra "
           "-Wpedantic -Werror -fsyntax-only $(PKG_CONFIG_PATH='%s/lib/"
           "pkgconfig' pkg-config --cflags vsph) '%s/one.c' 2>&1 || echo "
           "\"not alone: $h\"; n=$((n + 1)); done; echo \"headers: $n\"",
           stage, dir, stage, dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0 && !strstr(o->out, "not alone"), "%s\n%s",
                o->out, o->err);
  int n = 0;
  const char *at = strstr(o->out, "headers: ");
  ck_assert_msg(at && sscanf(at, "headers: %d", &n) == 1, "%s", o->out);
  ck_assert_int_ge(n, 38); /* PUB_HDR's 38, the six forms among them */
  vsph_test_rm_tree(dir);
}
END_TEST

/* The build folder whose objects the install tests install: the one
 * make check built this runner and VSPH_BIN in (make BUILD=...), build/
 * where VSPH_BIN is not set; a shell prefix setting B. */
#define BUILD_DIR "B=$(dirname \"${VSPH_BIN:-build/vsph}\") && "

/* A bad PREFIX is refused with one line and exit 2, nothing written; an
 * uninstall removes the install's files and the folders it made, and
 * leaves a file it did not make (and the folder that holds it); a second
 * install over the first keeps the first's folders in its manifest. */
START_TEST(test_install_refusals) {
  char dir[] = "/tmp/vsph-inst-XXXXXX", script[4096];
  vsph_test_scratch(dir);
  static const char *const bad[] = {"relative/path", "/with space", "/quote'd"};
  for (size_t b = 0; b < 3; b++) {
    snprintf(script, sizeof script,
             BUILD_DIR "scripts/install '%s' \"%s\" 0.2.0 0 \"$B\" vsph.h", dir,
             bad[b]);
    struct vsph_test_outcome *o = vsph_test_shell(script);
    ck_assert_msg(o->status == 2 && o->err_lines == 1,
                  "PREFIX '%s': exit %d, %d lines: %s", bad[b], o->status,
                  o->err_lines, o->err);
  }
  snprintf(script, sizeof script, "find '%s' -mindepth 1 | wc -l", dir);
  ck_assert_str_eq(vsph_test_shell(script)->out, "0\n");
  /* install under DESTDIR = dir, a foreign file beside, uninstall */
  snprintf(script, sizeof script,
           BUILD_DIR
           "scripts/install '%s' /opt/v 0.2.0 0 \"$B\" vsph.h common/consts.h "
           "> /dev/null && echo mine > '%s/opt/v/lib/other.so' && "
           "test -L '%s/opt/v/lib/libvsph.so' && "
           "scripts/install '%s' /opt/v 0.2.0 0 \"$B\" vsph.h common/consts.h "
           "> /dev/null && "
           "scripts/install --uninstall '%s' /opt/v > /dev/null && "
           "cd '%s/opt/v' && find . -type f -o -type l -o -type d | sort",
           dir, dir, dir, dir, dir, dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0, "install/uninstall: %d %s", o->status, o->err);
  ck_assert_str_eq(o->out, ".\n./lib\n./lib/other.so\n");
  /* a file in the way that no install made: refused before anything is
   * written, the file kept */
  snprintf(script, sizeof script,
           BUILD_DIR
           "mkdir -p '%s/q/bin' && echo theirs > '%s/q/bin/vsph' && "
           "scripts/install '%s' /q 0.2.0 0 \"$B\" vsph.h; echo $?; "
           "cat '%s/q/bin/vsph'; find '%s/q' -type f | wc -l",
           dir, dir, dir, dir, dir);
  o = vsph_test_shell(script);
  ck_assert_str_eq(o->out, "2\ntheirs\n1\n");
  ck_assert_int_eq(o->err_lines, 1);
  /* a manifest line reached through a linked folder (it would delete
   * outside the install): refused before anything is removed */
  snprintf(script, sizeof script,
           BUILD_DIR
           "scripts/install '%s' /r 0.2.0 0 \"$B\" vsph.h > /dev/null && "
           "mkdir '%s/out' && echo theirs > '%s/out/f' && "
           "ln -s '%s/out' '%s/r/lib/ext' && "
           "echo lib/ext/f >> '%s/r/share/vsph/manifest' && "
           "{ scripts/install --uninstall '%s' /r; echo $?; } && "
           "cat '%s/out/f' && test -f '%s/r/bin/vsph' && echo kept",
           dir, dir, dir, dir, dir, dir, dir, dir, dir);
  o = vsph_test_shell(script);
  ck_assert_str_eq(o->out, "2\ntheirs\nkept\n");
  ck_assert_int_eq(o->err_lines, 1);
  /* no manifest, nothing to remove: refused, the foreign file kept */
  snprintf(script, sizeof script,
           "scripts/install --uninstall '%s' /opt/v; echo $?; "
           "cat '%s/opt/v/lib/other.so'",
           dir, dir);
  o = vsph_test_shell(script);
  ck_assert_str_eq(o->out, "2\nmine\n");
  ck_assert_int_eq(o->err_lines, 1);
  vsph_test_rm_tree(dir);
}
END_TEST

/* scripts/install-deps on a machine without Debian's package tools (a
 * cluster, another distribution): with the compiler, pkg-config's
 * libraries and gnuplot on PATH it passes without apt; lacking one it
 * refuses in one line naming it, exit 2; an optional group, which needs
 * Debian's packages, is refused likewise. */
START_TEST(test_deps_without_apt) {
  char dir[] = "/tmp/vsph-deps-XXXXXX", script[4096];
  vsph_test_scratch(dir);
  snprintf(script, sizeof script,
           "for c in sh cc pkg-config gnuplot grep id cat; do "
           "ln -s \"$(command -v $c)\" '%s'/$c || exit 1; done",
           dir);
  ck_assert_int_eq(vsph_test_shell(script)->status, 0);
  snprintf(script, sizeof script,
           "unset PKG_CONFIG_PATH; PATH='%s' sh scripts/install-deps", dir);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0 && o->err_lines == 0, "exit %d: %s", o->status,
                o->err);
  snprintf(script, sizeof script,
           "rm '%s/gnuplot' && PATH='%s' '%s/sh' scripts/install-deps", dir,
           dir, dir);
  o = vsph_test_shell(script);
  ck_assert_msg(o->status == 2 && o->err_lines == 1 &&
                    strstr(o->err, "no gnuplot") != NULL,
                "exit %d: %s", o->status, o->err);
  /* building and installing need no gnuplot and no Check (make, make lib,
   * make install: install-deps --build); Check is a library pkg-config
   * finds, so a PKG_CONFIG_PATH of a copy without check.pc hides it */
  snprintf(script, sizeof script,
           "mkdir '%s/pc' && for d in $(pkg-config --variable pc_path "
           "pkg-config | tr : ' '); do for f in \"$d\"/*.pc; do "
           "[ -f \"$f\" ] && ln -sf \"$f\" '%s/pc/'; done; done; "
           "rm -f '%s/pc/check.pc' && unset PKG_CONFIG_PATH && "
           "PKG_CONFIG_LIBDIR='%s/pc' PATH='%s' "
           "'%s/sh' scripts/install-deps --build && echo built && "
           "PKG_CONFIG_LIBDIR='%s/pc' PATH='%s' '%s/sh' scripts/install-deps",
           dir, dir, dir, dir, dir, dir, dir, dir, dir);
  o = vsph_test_shell(script);
  ck_assert_msg(o->status == 2 && strstr(o->out, "built") != NULL &&
                    o->err_lines == 1 &&
                    strstr(o->err, "pkg-config finds no check") != NULL,
                "exit %d: %s %s", o->status, o->out, o->err);
  snprintf(script, sizeof script, "PATH='%s' '%s/sh' scripts/install-deps fuzz",
           dir, dir);
  o = vsph_test_shell(script);
  ck_assert_msg(o->status == 2 && o->err_lines == 1, "exit %d: %s", o->status,
                o->err);
  /* a second group is read like the first: an unknown one refused in one
   * line naming it, before any probe or apt */
  o = vsph_test_shell("sh scripts/install-deps fuzz extra");
  ck_assert_msg(o->status == 2 && o->err_lines == 1 &&
                    strstr(o->err, "unknown group 'extra'") != NULL,
                "exit %d: %s", o->status, o->err);
  /* Debian's tools but packages missing, no root and no sudo: refused in
   * one line before any apt-get (a dpkg-query that finds nothing, an
   * apt-get that would fail the test, an id of 1000) */
  snprintf(script, sizeof script,
           "cd '%s' && printf '#!/bin/sh\\nexit 1\\n' > dpkg-query && "
           "printf '#!/bin/sh\\necho apt-get ran >&2\\n' > apt-get && "
           "rm id && printf '#!/bin/sh\\necho 1000\\n' > id && "
           "chmod +x dpkg-query apt-get id && cd - > /dev/null && "
           "PATH='%s' '%s/sh' scripts/install-deps",
           dir, dir, dir);
  o = vsph_test_shell(script);
  ck_assert_msg(o->status == 2 && o->err_lines == 1 &&
                    strstr(o->err, "neither root nor sudo") != NULL,
                "exit %d: %s", o->status, o->err);
  vsph_test_rm_tree(dir);
}
END_TEST

/* The installed library runs on any x86-64 (Makefile, "the library"):
 * where the build is for x86-64-v3, lib/libvsph.so.0 is the baseline's
 * (no VEX-encoded instruction, none of AVX's v-mnemonics) and
 * lib/glibc-hwcaps/x86-64-v3/ holds the v3 build's, which the loader
 * picks on this CPU when it has x86-64-v3; with the loader told to search
 * no deeper than x86-64-v2 (a CPU without AVX2), the example loads the
 * baseline's and prints every line right. */
START_TEST(test_installed_dispatch) {
  char sbuf[4096];
  const char *stage = staged(sbuf);
  char hw[4200];
  snprintf(hw, sizeof hw, "%s/lib/glibc-hwcaps/x86-64-v3/libvsph.so.0", stage);
  FILE *f = fopen(hw, "r");
  if (!f) { /* a build for another ARCH installs one copy, its own */
    printf("library: no x86-64-v3 copy staged (ARCH is not x86-64-v3)\n");
    return;
  }
  fclose(f);
  char dir[] = "/tmp/vsph-hwc-XXXXXX", script[6 * 4096];
  vsph_test_scratch(dir);
  const char *ld = "/lib64/ld-linux-x86-64.so.2";
  snprintf(script, sizeof script,
           "vex() { objdump -d \"$1\" | awk -F'\\t' '$3 ~ /^v/' | wc -l; } "
           "&& echo base $(vex '%s/lib/libvsph.so.0') v3 $(vex '%s') && "
           "PKG_CONFIG_PATH='%s/lib/pkgconfig' make -s -C examples/regression "
           "OUT='%s' 2>&1 && cd '%s' && "
           "{ %s --help | grep -q 'x86-64-v3 (supported' && echo cpu v3 || "
           "echo cpu older; } && "
           "LD_DEBUG=libs ./regression 2>&1 | grep 'calling init:.*libvsph' && "
           "echo masked: && LD_DEBUG=libs %s --glibc-hwcaps-mask x86-64-v2 "
           "./regression 2>&1",
           stage, hw, stage, dir, dir, ld, ld);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0, "exit %d\n%s\n%s", o->status, o->out, o->err);
  long base = -1, v3 = -1;
  ck_assert_int_eq(sscanf(o->out, "base %ld v3 %ld", &base, &v3), 2);
  ck_assert_msg(base == 0, "the baseline copy holds %ld AVX instructions",
                base);
  ck_assert_msg(v3 > 0, "the x86-64-v3 copy holds no AVX instruction");
  const char *masked = strstr(o->out, "masked:");
  ck_assert_ptr_nonnull(masked);
  char want[4300];
  if (strstr(o->out, "cpu v3")) {
    snprintf(want, sizeof want, "calling init: %s", hw);
    const char *at = strstr(o->out, want);
    ck_assert_msg(at && at < masked, "not the v3 copy:\n%s", o->out);
  }
  snprintf(want, sizeof want, "calling init: %s/lib/libvsph.so.0", stage);
  ck_assert_msg(strstr(masked, want) != NULL, "masked, not the baseline:\n%s",
                masked);
  assert_lines(masked, "baseline");
  vsph_test_rm_tree(dir);
}
END_TEST

/* The installed program runs on any x86-64 (scripts/install, cli/main.c):
 * bin/vsph is the baseline's build, with no AVX instruction, and starts
 * libexec/vsph/x86-64-v3/vsph where the CPU has x86-64-v3 (--version and
 * run.json's "build" say which ran; a report's runs name bin/vsph);
 * VSPH_BASELINE keeps the baseline.
 * The two copies' stretching square (res 20, 112 steps) agree within the
 * archive's rule for a run that still stands (runs/archive.h: 1e-6
 * relative plus 1e-9; they differ in reduction widths, at about 3e-13):
 * E_k, E_c, P_visc at every row. */
START_TEST(test_installed_program) {
  char sbuf[4096];
  const char *stage = staged(sbuf);
  char v3[4200];
  snprintf(v3, sizeof v3, "%s/libexec/vsph/x86-64-v3/vsph", stage);
  FILE *f = fopen(v3, "r");
  if (!f) { /* a build for another ARCH installs one program, its own */
    printf("program: no x86-64-v3 copy staged (ARCH is not x86-64-v3)\n");
    return;
  }
  fclose(f);
  char dir[] = "/tmp/vsph-prog-XXXXXX", script[8 * 4096 + 1024];
  vsph_test_scratch(dir);
  snprintf(script, sizeof script,
           "command -v objdump > /dev/null && "
           "vex() { objdump -d \"$1\" | awk -F'\\t' '$3 ~ /^v/' | wc -l; } && "
           "echo base $(vex '%s/bin/vsph') && "
           "'%s/bin/vsph' --version && VSPH_BASELINE=1 '%s/bin/vsph' --version "
           "&& cd '%s' && '%s/bin/vsph' run stretching-square --res 20 --out a "
           "> /dev/null && VSPH_BASELINE=1 '%s/bin/vsph' run stretching-square "
           "--res 20 --out b > /dev/null && grep -h '\"build\"' a/run.json "
           "b/run.json && '%s/bin/vsph' report plan --only "
           "scenes:vortex-patch --out p 2> /dev/null | sed -n 4p",
           stage, stage, stage, dir, stage, stage, stage);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0, "exit %d\n%s\n%s", o->status, o->out, o->err);
  long base = -1;
  ck_assert_int_eq(sscanf(o->out, "base %ld", &base), 1);
  ck_assert_msg(base == 0, "the baseline program holds %ld AVX instructions",
                base);
  /* the CPU's level as the program reads it (cli/main.c) */
  __builtin_cpu_init();
#if defined(__clang__) || __GNUC__ < 12
  const int cpu_v3 =
      __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
      __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
#else
  const int cpu_v3 = __builtin_cpu_supports("x86-64-v3");
#endif
  const char *want = cpu_v3 ? "vsph " VSPH_VERSION
                              " (built for x86-64-v3)\n"
                              "vsph " VSPH_VERSION " (built for x86-64)\n"
                            : "vsph " VSPH_VERSION
                              " (built for x86-64)\n"
                              "vsph " VSPH_VERSION " (built for x86-64)\n";
  ck_assert_msg(strstr(o->out, want) != NULL, "want\n%s\ngot\n%s", want,
                o->out);
  const char *json = cpu_v3 ? "\t\"build\":\t\"x86-64-v3\",\n"
                              "\t\"build\":\t\"x86-64\",\n"
                            : "\t\"build\":\t\"x86-64\",\n"
                              "\t\"build\":\t\"x86-64\",\n";
  ck_assert_msg(strstr(o->out, json) != NULL, "run.json: %s", o->out);
  /* the report's children and Slurm scripts name bin/vsph, which chooses
   * the copy on each machine, never the copy that runs here */
  char cmd[4200];
  snprintf(cmd, sizeof cmd, "\t%s/bin/vsph run vortex-patch ", stage);
  ck_assert_msg(strstr(o->out, cmd) != NULL, "the plan's command: %s", o->out);
  /* the two runs' energy rows agree within the archive's rule */
  char pa[4200], pb[4200];
  snprintf(pa, sizeof pa, "%s/a/energy.csv", dir);
  snprintf(pb, sizeof pb, "%s/b/energy.csv", dir);
  FILE *fa = fopen(pa, "r"), *fb = fopen(pb, "r");
  ck_assert_ptr_nonnull(fa);
  ck_assert_ptr_nonnull(fb);
  char la[4096], lb[4096];
  int rows = 0;
  ck_assert_ptr_nonnull(fgets(la, sizeof la, fa)); /* the headers */
  ck_assert_ptr_nonnull(fgets(lb, sizeof lb, fb));
  ck_assert_str_eq(la, lb);
  while (fgets(la, sizeof la, fa)) {
    ck_assert_ptr_nonnull(fgets(lb, sizeof lb, fb));
    double a[5], b[5];
    ck_assert_int_eq(
        sscanf(la, "%lf,%lf,%lf,%lf,%lf", &a[0], &a[1], &a[2], &a[3], &a[4]),
        5);
    ck_assert_int_eq(
        sscanf(lb, "%lf,%lf,%lf,%lf,%lf", &b[0], &b[1], &b[2], &b[3], &b[4]),
        5);
    for (int k = 0; k < 5; k++) { /* t, E_k, E_p, E_c, P_visc */
      const double tol =
          VSPH_ARCHIVE_BASELINE_REL * fabs(a[k]) + VSPH_ARCHIVE_BASELINE_ABS;
      ck_assert_msg(fabs(a[k] - b[k]) <= tol,
                    "row %d column %d: %.15g against %.15g", rows, k, a[k],
                    b[k]);
    }
    rows++;
  }
  ck_assert_msg(rows > 100, "only %d energy rows", rows);
  fclose(fa);
  fclose(fb);
  vsph_test_rm_tree(dir);
}
END_TEST

/* scripts/fresh-check removes its fresh root only when nothing is
 * mounted in it, reading the mount table exactly for any path
 * (scripts/mounts.sh): tests/check_mounts.sh holds the functions to
 * hand-written tables for a path with a space and a newline (a bind
 * below it, the folder itself, a path that only starts like it, a
 * sibling), and prints a word for each expectation met. */
START_TEST(test_removal_waits_for_mounts) {
  struct vsph_test_outcome *o = vsph_test_shell("sh tests/check_mounts.sh");
  ck_assert_msg(o->status == 0, "exit %d: %s %s", o->status, o->out, o->err);
  ck_assert_str_eq(o->out,
                   "below\nprefix-not-below\nsibling-not-below\nitself\n"
                   "kept\nintact\nremoved\nescaped\n");
}
END_TEST

/* make check's two lanes (scripts/check-lanes) with a stand-in runner
 * (tests/check_lanes.sh), in a folder with a space and a newline: both
 * lanes run on one thread each, a lane's failure fails the whole, a
 * folder as the runner and a log the script did not write are refused
 * (exit 2), the log left as it was. */
START_TEST(test_check_lanes_script) {
  struct vsph_test_outcome *o = vsph_test_shell("sh tests/check_lanes.sh");
  ck_assert_msg(o->status == 0, "exit %d: %s %s", o->status, o->out, o->err);
  ck_assert_str_eq(o->out, "both\nfails\nno-folder\nkept\n");
}
END_TEST

/* The README's walkthrough, as a newcomer types it: step 1's command
 * (the run, its 11 snapshots, energy.csv's columns 2 and 12 being E_k and
 * Lighthill's reference, as step 3's gnuplot line plots them), and step
 * 5's program, taken from the README's C block, built against the staged
 * install through pkg-config and run: it prints the Poiseuille series'
 * value, held to this process's own (the same library, rounding). */
START_TEST(test_readme_walkthrough) {
  char sbuf[4096];
  const char *stage = staged(sbuf);
  static char readme[1 << 17];
  vsph_test_slurp("README.md", readme, sizeof readme);
  const char *cmd = strstr(readme, "    build/vsph run standing-wave ");
  ck_assert_msg(cmd != NULL, "README: no step 1 command");
  char line[256];
  const size_t n = strcspn(cmd + 4, "\n");
  ck_assert_uint_lt(n, sizeof line);
  memcpy(line, cmd + 4 + strlen("build/vsph"), n - strlen("build/vsph"));
  line[n - strlen("build/vsph")] = '\0';
  const char *c0 = strstr(readme, "```c\n"),
             *c1 = c0 ? strstr(c0 + 5, "```") : NULL;
  ck_assert_msg(c0 && c1, "README: no C block");
  char dir[] = "/tmp/vsph-readme-XXXXXX", path[200], script[3 * 4096 + 512];
  vsph_test_scratch(dir);
  snprintf(path, sizeof path, "%s/demo.c", dir);
  FILE *f = fopen(path, "w");
  ck_assert_ptr_nonnull(f);
  fwrite(c0 + 5, 1, (size_t)(c1 - c0 - 5), f);
  ck_assert_int_eq(fclose(f), 0);
  snprintf(script, sizeof script,
           "B=$(realpath \"$VSPH_BIN\") && cd '%s' && $B%s --quiet && "
           "ls wave/snap_*.vtp | wc -l && head -1 wave/energy.csv | cut -d, "
           "-f2,12 && export PKG_CONFIG_PATH='%s/lib/pkgconfig' && "
           "cc demo.c $(pkg-config --cflags --libs vsph) -o demo && "
           "LD_LIBRARY_PATH='%s/lib' ./demo",
           dir, line, stage, stage);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0, "exit %d\n%s\n%s", o->status, o->out, o->err);
  int snaps = 0;
  char cols[64];
  double u = NAN;
  ck_assert_msg(sscanf(o->out, "%d %63s u/U0 = %lf", &snaps, cols, &u) == 3,
                "%s", o->out);
  ck_assert_int_eq(snaps, 11);
  ck_assert_str_eq(cols, "Ek,Ek_ref");
  /* printed to 6 decimals */
  ck_assert_double_eq_tol(
      u, vsph_references_poiseuille(0.3, 1.0, 1.0, 0.1, 1.0, NULL), 5e-7);
  vsph_test_rm_tree(dir);
}
END_TEST

/* The README walkthrough's steps 3 and 4 as a newcomer types them: step
 * 3's gnuplot line, taken from the README, draws wave/Ek.png from step
 * 1's run; step 4: a report figure's script (here each of the profiles
 * part.s, made in two seconds) redraws its PNG, SVG and PDF from the CSVs
 * beside it, after they were removed. */
START_TEST(test_readme_steps_3_4) {
  static char readme[1 << 17];
  vsph_test_slurp("README.md", readme, sizeof readme);
  const char *g = strstr(readme, "    gnuplot -e \"");
  ck_assert_msg(g != NULL, "README: no step 3 gnuplot line");
  char line[1024];
  const size_t n = strcspn(g + 4, "\n");
  ck_assert_uint_lt(n, sizeof line);
  memcpy(line, g + 4, n);
  line[n] = '\0';
  ck_assert_msg(strstr(readme, "gnuplot fig_standing-wave_Ek.gp") != NULL,
                "README: no step 4 command");
  char dir[] = "/tmp/vsph-steps-XXXXXX", script[4096 + 1024];
  vsph_test_scratch(dir);
  snprintf(script, sizeof script,
           "B=$(realpath \"$VSPH_BIN\") && cd '%s' && \"$B\" run standing-wave "
           "--res 12 --t-end 0.4 "
           "--out wave --quiet && %s && od -An -c -N4 wave/Ek.png | tr -d ' ' "
           "&& \"$B\" report --only profiles --out r > /dev/null 2>&1 && "
           "cd r && n=0 && for f in fig_*.gp; do b=${f%%.gp}; "
           "rm -f \"$b.png\" \"$b.svg\" \"$b.pdf\" && gnuplot \"$f\" && "
           "[ -s \"$b.png\" ] && [ -s \"$b.svg\" ] && [ -s \"$b.pdf\" ] && "
           "n=$((n + 1)); done && echo redrawn $n of $(ls fig_*.gp | wc -l)",
           dir, line);
  struct vsph_test_outcome *o = vsph_test_shell(script);
  ck_assert_msg(o->status == 0, "exit %d\n%s\n%s", o->status, o->out, o->err);
  ck_assert_msg(strstr(o->out, "211PNG") != NULL, "no PNG: %s", o->out);
  long redrawn = -1, scripts = -1;
  const char *r = strstr(o->out, "redrawn ");
  ck_assert_ptr_nonnull(r);
  ck_assert_int_eq(sscanf(r, "redrawn %ld of %ld", &redrawn, &scripts), 2);
  ck_assert_msg(scripts >= 2 && redrawn == scripts,
                "%ld of %ld figures redrawn", redrawn, scripts);
  vsph_test_rm_tree(dir);
}
END_TEST

Suite *vsph_library_suite(void) {
  Suite *s = suite_create("library");
  TCase *tc = tcase_create("install");
  tcase_set_timeout(tc, 120);
  tcase_add_test(tc, test_installed_example);
  tcase_add_test(tc, test_installed_dispatch);
  tcase_add_test(tc, test_installed_program);
  tcase_add_test(tc, test_readme_walkthrough);
  tcase_add_test(tc, test_readme_steps_3_4);
  tcase_add_test(tc, test_exports_match_headers);
  tcase_add_test(tc, test_headers_stand_alone);
  tcase_add_test(tc, test_install_refusals);
  tcase_add_test(tc, test_deps_without_apt);
  tcase_add_test(tc, test_removal_waits_for_mounts);
  tcase_add_test(tc, test_check_lanes_script);
  suite_add_tcase(s, tc);
  return s;
}
