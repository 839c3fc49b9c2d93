/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* libFuzzer target (make fuzz): the command-line parser with the options
 * of `vsph run` (the Solver table, files, --set), then the props it feeds.
 * The input is split into arguments at newlines. */
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../cli/args.h"
#include "../../common/params.h"
#include "../../common/status.h"
#include "../../solver/run.h"

static void silent(int status, const char *file, int line, const char *msg) {
  (void)status, (void)file, (void)line, (void)msg;
}

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv) {
  (void)argc, (void)argv;
  /* the usage text of --help and the one-line refusals are not the point */
  if (!freopen("/dev/null", "w", stdout)) return 1;
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > 4096) return 0;
  vsph_status_set_handler(silent);
  char *buf = malloc(size + 1);
  char *argv[64];
  int argc = 0;
  if (!buf) return 0;
  memcpy(buf, data, size);
  buf[size] = '\0';
  argv[argc++] = "run";
  for (char *c = buf; argc < 63;) {
    argv[argc++] = c;
    char *nl = strchr(c, '\n');
    if (!nl) break;
    *nl = '\0';
    c = nl + 1;
  }
  argv[argc] = NULL;
  const char *out = NULL;
  size_t threads = 0;
  int quiet = 0;
  const struct vsph_args_spec own[] = {
      {"--out", VSPH_ARGS_STRING, &out, "DIR", "output folder"},
      {"--threads", VSPH_ARGS_SIZE, &threads, "T", "threads"},
      {"--set", VSPH_ARGS_SET, NULL, "S:k=v", "one parameter"},
      {"--quiet", VSPH_ARGS_FLAG, &quiet, NULL, "quiet"}};
  size_t n;
  const struct vsph_params_spec *spec = vsph_run_params(&n);
  const struct vsph_args_section sec = {"Solver", spec, n};
  const struct vsph_args_cmd c = {
      "run", "SCENE [options]", "fuzz", own, 4, &sec, 1, NULL};
  struct vsph_params *prm = vsph_params_alloc();
  if (prm && vsph_args_parse(&c, argc, argv, prm) < 0) {
    struct vsph_run_props rp;
    (void)vsph_run_props_init(&rp, prm);
  }
  vsph_params_free(prm);
  free(buf);
  return 0;
}
