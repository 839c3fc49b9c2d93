/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "args.h"

#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

#include "../common/params.h"
#include "../common/status.h"
#include "../io/json.h"

/* Most characters of a message printed: a value echoed in it (a scene
 * name of 100 000 characters) is cut, the cut marked. */
enum { SAY_MAX = 512 };

/* "vsph CMD: MSG" on one line of stderr: a control character of the
 * message (a newline in a value) is written as an escape (\n, \t, \xHH),
 * so one message is always one line, and the message is capped. */
static void say(const char *cmd, const char *msg) {
  fprintf(stderr, "vsph%s%s: ", *cmd ? " " : "", cmd);
  size_t n = 0;
  for (const unsigned char *c = (const unsigned char *)msg; *c; c++, n++) {
    if (n == SAY_MAX) {
      fputs("... (cut)", stderr);
      break;
    }
    if (*c == '\n')
      fputs("\\n", stderr);
    else if (*c == '\t')
      fputs("\\t", stderr);
    else if (*c < 0x20 || *c == 0x7f)
      fprintf(stderr, "\\x%02x", *c);
    else
      fputc(*c, stderr);
  }
  fputc('\n', stderr);
}

int vsph_args_names(const char *arg, const char *opt) {
  const size_t n = strlen(opt);
  return !strncmp(arg, opt, n) && (arg[n] == '\0' || arg[n] == '=');
}

int vsph_args_fail(const char *cmd, const char *fmt, ...) {
  char msg[2048];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  say(cmd, msg);
  return VSPH_ARGS_EXIT_USAGE;
}

/* --key-name for a table key key_name, and back. */
static void option_of(const char *key, char *buf, size_t n) {
  snprintf(buf, n, "--%s", key);
  for (char *c = buf + 2; *c; c++)
    if (*c == '_') *c = '-';
}

static const char *value_name(const struct vsph_params_spec *s) {
  return s->kind == VSPH_PARAMS_NAME  ? "NAME"
         : s->kind == VSPH_PARAMS_INT ? "N"
                                      : "X";
}

void vsph_args_usage(const struct vsph_args_cmd *c, FILE *f) {
  fprintf(f, "usage: vsph %s %s\n\n%s\n", c->name, c->synopsis, c->about);
  for (size_t s = 0; s < c->nsections; s++) {
    const struct vsph_args_section *sec = &c->sections[s];
    fprintf(f, "\n%s options (parameter section %s:; default in brackets):\n",
            c->name, sec->section);
    for (size_t k = 0; k < sec->n; k++) {
      char opt[64], def[64], lhs[96];
      option_of(sec->spec[k].key, opt, sizeof opt);
      vsph_params_spec_default(&sec->spec[k], def, sizeof def);
      snprintf(lhs, sizeof lhs, "%s %s", opt, value_name(&sec->spec[k]));
      fprintf(f, "  %-22s %s [%s]\n", lhs, sec->spec[k].help, def);
    }
  }
  if (c->nown) fprintf(f, "\nother options:\n");
  for (size_t k = 0; k < c->nown; k++) {
    char lhs[96];
    snprintf(lhs, sizeof lhs, "%s%s%s", c->own[k].name,
             c->own[k].value ? " " : "",
             c->own[k].value ? c->own[k].value : "");
    fprintf(f, "  %-22s %s\n", lhs, c->own[k].help);
  }
  fprintf(f, "  %-22s %s\n", "--help", "this text");
}

static int parse_size(const char *cmd, const char *opt, const char *s,
                      size_t *out) {
  char *end;
  errno = 0;
  if (s[0] < '0' || s[0] > '9')
    return vsph_args_fail(cmd, "%s: '%s' is not a non-negative integer", opt,
                          s);
  const unsigned long long v = strtoull(s, &end, 10);
  if (*end != '\0' || errno == ERANGE || v > (size_t)-1)
    return vsph_args_fail(cmd, "%s: '%s' is not a non-negative integer", opt,
                          s);
  *out = (size_t)v;
  return 0;
}

/* The section key behind option --name, as "Section:key", or 0. */
static int section_key(const struct vsph_args_cmd *c, const char *name,
                       char *key, size_t n) {
  for (size_t s = 0; s < c->nsections; s++)
    for (size_t k = 0; k < c->sections[s].n; k++) {
      char opt[64];
      option_of(c->sections[s].spec[k].key, opt, sizeof opt);
      if (!strcmp(opt, name)) {
        snprintf(key, n, "%s:%s", c->sections[s].section,
                 c->sections[s].spec[k].key);
        return 1;
      }
    }
  return 0;
}

/* "; did you mean --x?" into @p buf where an option of @p c is a slip
 * away from @p name (vsph_params_nearest), else empty. */
static void suggest(const struct vsph_args_cmd *c, const char *name, char *buf,
                    size_t n) {
  buf[0] = '\0';
  size_t m = c->nown;
  for (size_t s = 0; s < c->nsections; s++) m += c->sections[s].n;
  char(*opt)[64] = malloc(m * sizeof *opt + 1);
  const char **cand = malloc(m * sizeof *cand + 1);
  if (opt && cand) {
    size_t k = 0;
    for (size_t o = 0; o < c->nown; o++, k++)
      snprintf(opt[k], sizeof opt[k], "%s", c->own[o].name);
    for (size_t s = 0; s < c->nsections; s++)
      for (size_t e = 0; e < c->sections[s].n; e++, k++)
        option_of(c->sections[s].spec[e].key, opt[k], sizeof opt[k]);
    for (k = 0; k < m; k++) cand[k] = opt[k];
    const size_t at = vsph_params_nearest(name, cand, m);
    if (at < m) snprintf(buf, n, "; did you mean %s?", cand[at]);
  }
  free(opt);
  free(cand);
}

/* One pass over the line, doing only the options of kind `pass`
 * (PARAMS, then SET, then everything else). */
static int pass_over(const struct vsph_args_cmd *c, int argc, char **argv,
                     struct vsph_params *prm, int pass, int *given) {
  for (int i = 1; i < argc; i++) {
    /* --name=value is --name value (GNU's long options) */
    char name[64];
    const char *a = argv[i], *inl = NULL;
    const char *is = a[0] == '-' && a[1] == '-' ? strchr(a, '=') : NULL;
    if (is && (size_t)(is - a) < sizeof name) {
      memcpy(name, a, (size_t)(is - a));
      name[is - a] = '\0';
      a = name;
      inl = is + 1;
    }
    const struct vsph_args_spec *sp = NULL;
    for (size_t k = 0; k < c->nown && !sp; k++)
      if (!strcmp(a, c->own[k].name)) sp = &c->own[k];
    char key[128];
    const int is_key = !sp && section_key(c, a, key, sizeof key);
    if (!sp && !is_key) {
      char hint[128];
      suggest(c, a, hint, sizeof hint);
      return vsph_args_fail(c->name, "unknown option '%s'%s (see --help)", a,
                            hint);
    }
    if (sp && sp->kind == VSPH_ARGS_FLAG) {
      if (inl) return vsph_args_fail(c->name, "%s takes no value", a);
      if (pass == 2) *(int *)sp->dst = 1;
      continue;
    }
    if (!inl && i + 1 >= argc)
      return vsph_args_fail(c->name, "%s needs a value", a);
    /* an option where the value should be ("--probe-x0 --probe-y0 -0.5"):
     * the value is missing, not the next word unknown (a negative number
     * has one dash) */
    if (!inl && !strncmp(argv[i + 1], "--", 2) && argv[i + 1][2])
      return vsph_args_fail(c->name, "%s needs a value (got the option %s)", a,
                            argv[i + 1]);
    const char *v = inl ? inl : argv[++i];
    const int kind = sp ? (int)sp->kind : -1;
    /* no option of vsph means anything by an empty value: an empty --out
     * would name the current folder's parent chain (`/` for a report) */
    if (pass == 0 && kind == VSPH_ARGS_STRING && !*v)
      return vsph_args_fail(c->name, "%s: an empty value", a);
    if (pass == 0 && kind == VSPH_ARGS_PARAMS) {
      if (vsph_params_read(prm, v))
        return vsph_args_status(c->name, VSPH_EINVAL);
    } else if (pass == 1 && kind == VSPH_ARGS_SET) {
      const char *eq = strchr(v, '=');
      char k2[256];
      if (!eq)
        return vsph_args_fail(c->name,
                              "--set wants Section:key=value, got '%.80s%s'", v,
                              strlen(v) > 80 ? "..." : "");
      if ((size_t)(eq - v) >= sizeof k2)
        return vsph_args_fail(c->name,
                              "--set: a key of %zu characters (at most %zu): "
                              "'%.40s...'",
                              (size_t)(eq - v), sizeof k2 - 1, v);
      memcpy(k2, v, (size_t)(eq - v));
      k2[eq - v] = '\0';
      if (vsph_params_set(prm, k2, eq + 1))
        return vsph_args_status(c->name, VSPH_EINVAL);
    } else if (pass == 2 && is_key) {
      if (vsph_params_set(prm, key, v))
        return vsph_args_status(c->name, VSPH_EINVAL);
      for (size_t r = 0; c->required && c->required[r]; r++)
        if (!strcmp(c->required[r], strchr(key, ':') + 1)) given[r] = 1;
    } else if (pass == 2 && kind == VSPH_ARGS_STRING) {
      *(const char **)sp->dst = v;
    } else if (pass == 2 && kind == VSPH_ARGS_SIZE) {
      if (parse_size(c->name, a, v, sp->dst)) return VSPH_ARGS_EXIT_USAGE;
    }
  }
  return -1;
}

int vsph_args_parse(const struct vsph_args_cmd *c, int argc, char **argv,
                    struct vsph_params *prm) {
  for (int i = 1; i < argc; i++)
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      vsph_args_usage(c, stdout);
      return 0;
    }
  int given[16] = {0};
  for (int pass = 0; pass < 3; pass++) {
    const int rc = pass_over(c, argc, argv, prm, pass, given);
    if (rc >= 0) return rc;
  }
  for (size_t r = 0; c->required && c->required[r]; r++)
    if (!given[r]) {
      char opt[64];
      option_of(c->required[r], opt, sizeof opt);
      return vsph_args_fail(c->name, "%s is required (see --help)", opt);
    }
  return -1;
}

/* The CLI keeps the first message of a failing call chain, so a command
 * prints one line however deep the failure was reported. The handler has
 * no context argument, so this is the CLI's one piece of global state (set
 * before any thread starts; STYLE B13). */
static char last_msg[1024];

static void cli_handler(int status, const char *file, int line,
                        const char *msg) {
  (void)status;
  (void)file;
  (void)line;
  if (last_msg[0] == '\0') snprintf(last_msg, sizeof last_msg, "%s", msg);
}

void vsph_args_install_handler(void) { vsph_status_set_handler(cli_handler); }

int vsph_args_status(const char *cmd, int status) {
  return vsph_args_status_about(cmd, NULL, status);
}

int vsph_args_status_about(const char *cmd, const char *what, int status) {
  char line[1200];
  snprintf(line, sizeof line, "%s%s%s", what ? what : "", what ? ": " : "",
           last_msg[0] ? last_msg : vsph_status_str(status));
  last_msg[0] = '\0';
  say(cmd, line);
  return status == VSPH_EINVAL ? VSPH_ARGS_EXIT_USAGE : 1;
}

int vsph_args_finish(const char *cmd, int rc) {
  errno = 0;
  if ((fflush(stdout) != 0 || ferror(stdout)) && rc == 0) {
    fprintf(stderr, "vsph %s: cannot write to standard output: %s\n", cmd,
            errno ? strerror(errno) : "write error");
    return 1;
  }
  return rc;
}

int vsph_args_json(const char *cmd, void *obj) {
  return vsph_args_finish(
      cmd, vsph_json_print(obj) ? vsph_args_status(cmd, VSPH_EIO) : 0);
}

int vsph_args_analysis_main(const struct vsph_args_analysis *a, void *work,
                            int argc, char **argv) {
  int json = 0;
  const struct vsph_args_spec own[] = {
      {"--json", VSPH_ARGS_FLAG, &json, NULL, a->json_keys}};
  size_t n;
  const struct vsph_params_spec *spec = a->params(&n);
  const struct vsph_args_section sec = {a->section, spec, n};
  const struct vsph_args_cmd c = {a->name, a->synopsis, a->about, own,
                                  1,       &sec,        1,        NULL};
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return vsph_args_status(a->name, VSPH_ENOMEM);
  const int rc = vsph_args_parse(&c, argc, argv, prm);
  int st = rc < 0 ? a->init(work, prm) : 0;
  vsph_params_free(prm);
  if (rc >= 0) return rc;
  if (!st) st = a->compute(work);
  if (st) return vsph_args_status(a->name, st);
  if (json) return vsph_args_json(a->name, a->json(work));
  return vsph_args_finish(a->name, a->print(work));
}

static volatile sig_atomic_t stop_signal, quick_armed, writing;
static void on_stop(int sig) {
  stop_signal = sig;
  /* nothing written yet: nothing to keep (a spent budget waits) */
  if (quick_armed && !writing && sig != SIGALRM) {
    static const char msg[] =
        "vsph: stopped by a signal (a file being written is left as its "
        ".tmp, never in place)\n";
    ssize_t w = write(2, msg, sizeof msg - 1);
    (void)w;
    _exit(128 + sig);
  }
}

volatile sig_atomic_t *vsph_args_quick_stop(void) {
  writing = 0;
  quick_armed = 1;
  return &writing;
}

int vsph_args_stop_after(double seconds) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop;
  sigemptyset(&sa.sa_mask);
  if (!(seconds > 0.0) || seconds > 1e9 || sigaction(SIGALRM, &sa, NULL))
    return -1;
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGALRM);
  pthread_sigmask(SIG_UNBLOCK, &set, NULL);
  struct itimerval it = {{0, 0}, {(time_t)seconds, 0}};
  it.it_value.tv_usec =
      (suseconds_t)((seconds - (double)(time_t)seconds) * 1e6);
  return setitimer(ITIMER_REAL, &it, NULL);
}

const volatile sig_atomic_t *vsph_args_catch_stop(void) {
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_stop;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);
  /* a process started with them blocked (the mask is inherited through
   * fork and exec) would never see them: the run went on deaf to its
   * stop, then ended "ok". Unblocked here, one already pending is caught
   * at once, before the run is set up. */
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  pthread_sigmask(SIG_UNBLOCK, &set, NULL);
  return &stop_signal;
}
