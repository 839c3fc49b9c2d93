/* vsph report: the main job (reports/report.c). */
#include "cmd_report.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

#include "../common/params.h"
#include "../common/status.h"
#include "../reports/report.h"
#include "args.h"

static const char *const CMD = "report";

int vsph_cmd_report_main(int argc, char **argv) {
  const char *dir = "reports/out", *only = NULL;
  int full = 0;
  const struct vsph_args_spec own[] = {
      {"--out", VSPH_ARGS_STRING, &dir, "DIR",
       "output folder (default reports/out)"},
      {"--only", VSPH_ARGS_STRING, &only, "P[,P]",
       "only these parts (see below); report.md gathers every part "
       "present; PART:SCENE (scenes, convergence, speed) limits those parts "
       "to one scene, e.g. scenes:vortex-patch"},
      {"--full", VSPH_ARGS_FLAG, &full, NULL,
       "the paper's resolutions and end times (hours)"}};
  char about[2048];
  size_t len = (size_t)snprintf(
      about, sizeof about, "%s",
      "Run the suite and write to DIR: report.md, report.html\n"
      "(self-contained: figures embedded), the CSV behind every table and\n"
      "figure, the figures (fig_*.png beside their fig_*.gp gnuplot\n"
      "scripts), the solver runs (runs/), baseline.csv (the key figures of\n"
      "the quick ladder's coarsest runs) and run.json. Default fidelity is\n"
      "quick (minutes on 2 cores: reduced resolutions and end times, stated\n"
      "in the report). Runs are cached by version, source hash and\n"
      "settings, the analysis parts by version, source hash and fidelity:\n"
      "an unchanged input is never recomputed. Parts:");
  for (size_t p = 0; p < vsph_report_part_count() && len < sizeof about; p++)
    len += (size_t)snprintf(about + len, sizeof about - len, "\n  %-12s %s",
                            vsph_report_part_name(p), vsph_report_part_what(p));
  const struct vsph_args_cmd c = {CMD,
                                  "[--out DIR] [--only PART[,PART...]] "
                                  "[--full]",
                                  about,
                                  own,
                                  sizeof own / sizeof own[0],
                                  NULL,
                                  0,
                                  NULL};
  const int rc = vsph_args_parse(&c, argc, argv, NULL);
  if (rc >= 0) return vsph_args_finish(CMD, rc);
  struct vsph_report_props rp = {
      .dir = dir, .full = full, .parts = 0, .stop = NULL};
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
        rp.scenes |= 1u << s;
      }
      const int p = vsph_report_part_find(tok);
      if (p < 0)
        return vsph_args_fail(CMD, "unknown part '%s' (see --help)", tok);
      rp.parts |= 1ul << p;
    }
    if (!rp.parts)
      return vsph_args_fail(CMD, "--only names no part (see --help)");
  }
  /* SIGINT/SIGTERM: the run in progress stops after its step, uncached */
  const volatile sig_atomic_t *stop = rp.stop = vsph_args_catch_stop();
  const int st = vsph_report_write(&rp);
  if (st == VSPH_EINTR) {
    fprintf(stderr,
            "vsph report: interrupted by signal %d; finished runs "
            "are cached, rerun to go on\n",
            (int)*stop);
    return 128 + (int)*stop;
  }
  return st ? vsph_args_status(CMD, st) : vsph_args_finish(CMD, 0);
}
