/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* libFuzzer target (make fuzz): the parameter file parser and the
 * parameter tables. Any input must end in a clean status: no crash, no
 * leak, no undefined behaviour, no hang. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "../../analysis/dissipation.h"
#include "../../common/params.h"
#include "../../common/status.h"
#include "../../solver/run.h"
#include "../../solver/scene.h"

static void silent(int status, const char *file, int line, const char *msg) {
  (void)status, (void)file, (void)line, (void)msg;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  vsph_status_set_handler(silent);
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) return 0;
  if (vsph_params_read_string(prm, (const char *)data, size, "fuzz") ==
      VSPH_OK) {
    /* every table reads its section: numbers parsed and bounded */
    struct vsph_run_props rp;
    (void)vsph_run_props_init(&rp, prm);
    struct vsph_dissipation_props dp;
    (void)vsph_dissipation_props_init(&dp, prm);
    for (size_t i = 0; i < vsph_scene_count(); i++) {
      const struct vsph_scene_type *t = vsph_scene_get(i);
      struct vsph_scene sc;
      memset(&sc, 0, sizeof sc);
      (void)vsph_params_load(prm, "Scene", t->params, t->nparams, &sc.u,
                             sizeof sc.u);
    }
    (void)vsph_params_unused(prm);
    for (size_t i = 0; i < vsph_params_count(prm); i++) {
      const char *k, *v;
      int used;
      vsph_params_entry(prm, i, &k, &v, &used);
    }
  }
  vsph_params_free(prm);
  return 0;
}
