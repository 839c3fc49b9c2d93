/* vsph report: the main job. Runs the analysis (THEORY 2-4) and the scenes
 * (THEORY 5-6), and writes report.md, a self-contained report.html, the
 * CSV behind every table and figure, the figures (PNG, gnuplot scripts
 * beside them), baseline.csv and run.json into one folder. */
#include "cmd_report.h"

#include <gsl/gsl_integration.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "args.h"
#include "plot.h"
#include "report_internal.h"
#include "writers.h"

static const char *const CMD = "report";

struct part {
  const char *name;
  int (*fn)(struct vsph_report *);
  int cached; /* 1: skipped when its key matches (cheap, no runs) */
  const char *what;
};

static int claims_part(struct vsph_report *R);

static const struct part PARTS[] = {
    {"tensors", vsph_report_analysis_tensors, 1,
     "F, G, N, M against theory; particle sums; C_F, C_N"},
    {"profiles", vsph_report_analysis_profiles, 1,
     "the tensors against depth (figures)"},
    {"scaling", vsph_report_analysis_scaling, 1,
     "1/h surface scaling, slopes; interior convergence"},
    {"dissipation", vsph_report_analysis_dissipation, 1,
     "THEORY 4 dissipation integrals against resolution and h/dx"},
    {"scenes", vsph_report_scenes_scenes, 0,
     "the three scenes, each formulation, against the references"},
    {"convergence", vsph_report_scenes_convergence, 0,
     "error against resolution, fitted order"},
    {"speed", vsph_report_scenes_speed, 0, "wall time against error"},
    {"stability", vsph_report_scenes_stability, 0,
     "hard cases: PVWF, high Re, perturbed start, low c0, CFL"},
    {"claims", claims_part, 0, "the paper's claims beside our figures"},
};
#define NPARTS (sizeof PARTS / sizeof PARTS[0])

static void usage(FILE *f) {
  fputs(
      "usage: vsph report [--out DIR] [--only PART[,PART...]] [--full]\n"
      "\n"
      "Run the suite and write to DIR (default reports/out): report.md,\n"
      "report.html (self-contained: figures embedded), the CSV behind every\n"
      "table and figure, the figures (fig_*.png with their fig_*.gp\n"
      "gnuplot scripts), the solver runs (runs/), baseline.csv (the key\n"
      "figures of the quick ladder's coarsest runs) and run.json.\n"
      "Default fidelity is quick (about 10 minutes on 2 cores: reduced\n"
      "resolutions and end times, stated in the report); --full uses the\n"
      "paper's (hours). Runs are cached by version and settings, and the\n"
      "analysis parts by version and fidelity: an unchanged input is\n"
      "never recomputed. --only runs some parts; report.md gathers every\n"
      "part present. PARTS:\n",
      f);
  for (size_t p = 0; p < NPARTS; p++)
    fprintf(f, "  %-12s %s\n", PARTS[p].name, PARTS[p].what);
}

static int claims_part(struct vsph_report *R) {
  int st = vsph_report_analysis_claims(R);
  if (!st) st = vsph_report_scenes_claims(R);
  if (st) return st;
  fprintf(R->md,
          "## 9. The paper's claims beside our figures\n\n"
          "Claims of Colagrossi et al. (2011), sections IV-VI and "
          "appendices, as summarised in THEORY sections 2, 4 and 6, with "
          "the figure this report measured and a verdict.%s\n\n"
          "| claim | paper | ours | verdict |\n|---|---|---|---|\n",
          R->full ? ""
                  : " Quick fidelity: scene figures are at reduced "
                    "resolutions and end times.");
  for (size_t k = 0; k < R->nclaims; k++)
    fprintf(R->md, "| %s | %s | %s | %s |\n", R->claims[k][0], R->claims[k][1],
            R->claims[k][2], R->claims[k][3]);
  fprintf(R->md, "\n");
  return VSPH_OK;
}

static int write_baseline(struct vsph_report *R) {
  FILE *f = vsph_writers_open(R->dir, "baseline.csv");
  if (!f) return VSPH_EIO;
  fprintf(f, "scene,visc,res,t_end,ek_final,diss0,stable\n");
  int st = VSPH_OK;
  for (size_t i = 0; i < vsph_report_scenes_baseline_count() && !st; i++) {
    struct vsph_report_baseline b;
    st = vsph_report_scenes_baseline(R, i, &b);
    if (!st)
      fprintf(f, "%s,%s,%zu,%g,%.10e,%.10e,%d\n", b.scene, b.visc, b.res,
              b.t_end, b.ek_final, b.diss0, b.ok);
  }
  const int c = vsph_writers_close(f, R->dir, "baseline.csv");
  return st ? st : c;
}

int vsph_cmd_report_main(int argc, char **argv) {
  const char *dir = "reports/out", *only = NULL;
  int full = 0;
  const struct vsph_args_spec specs[] = {
      {"--out", VSPH_ARGS_STRING, &dir},
      {"--only", VSPH_ARGS_STRING, &only},
      {"--full", VSPH_ARGS_FLAG, &full},
  };
  const int pr = vsph_args_parse(CMD, argc, argv, specs,
                                 sizeof specs / sizeof specs[0], usage);
  if (pr >= 0) return pr;
  int want[NPARTS];
  for (size_t p = 0; p < NPARTS; p++) want[p] = !only;
  if (only) {
    char buf[256];
    snprintf(buf, sizeof buf, "%s", only);
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
      size_t p = 0;
      while (p < NPARTS && strcmp(tok, PARTS[p].name)) p++;
      if (p == NPARTS)
        return vsph_args_fail(CMD, "unknown part '%s' (see --help)", tok);
      want[p] = 1;
    }
  }
  char parts_dir[600];
  snprintf(parts_dir, sizeof parts_dir, "%s/parts", dir);
  if (vsph_writers_mkdir(parts_dir)) return vsph_args_status(CMD, VSPH_EIO);
  struct vsph_report *R = calloc(1, sizeof *R);
  if (!R) return vsph_args_status(CMD, VSPH_ENOMEM);
  R->dir = dir;
  R->full = full;
  R->wo = gsl_integration_workspace_alloc(1000);
  R->wi = gsl_integration_workspace_alloc(1000);
  const double t_all = omp_get_wtime();
  double wall[NPARTS] = {0};
  int cached[NPARTS] = {0}, st = VSPH_OK;
  char key[128];
  snprintf(key, sizeof key, "vsph %s %s, %s\n", VSPH_VERSION,
           vsph_source_hash_id, full ? "full" : "quick");
  for (size_t p = 0; p < NPARTS && !st; p++) {
    if (!want[p]) continue;
    char md[96], kf[640];
    snprintf(md, sizeof md, "%s.md", PARTS[p].name);
    snprintf(kf, sizeof kf, "%s/%s.key", parts_dir, PARTS[p].name);
    if (PARTS[p].cached) {
      char *old = vsph_writers_slurp(kf, NULL);
      const int hit = old && !strcmp(old, key);
      free(old);
      if (hit) {
        cached[p] = 1;
        fprintf(stderr, "vsph report: %s (cached)\n", PARTS[p].name);
        continue;
      }
    }
    fprintf(stderr, "vsph report: %s ...\n", PARTS[p].name);
    const double t = omp_get_wtime();
    remove(kf);
    R->md = vsph_writers_open(parts_dir, md);
    if (!R->md) {
      st = VSPH_EIO;
      break;
    }
    st = PARTS[p].fn(R);
    if (st) {
      fclose(R->md);
      break;
    }
    st = vsph_writers_close(R->md, parts_dir, md);
    if (!st && PARTS[p].cached) {
      FILE *f = fopen(kf, "w");
      if (f) {
        fputs(key, f);
        fclose(f);
      }
    }
    wall[p] = omp_get_wtime() - t;
  }
  /* the baseline comes with the scenes part (its coarsest runs) */
  for (size_t p = 0; p < NPARTS && !st; p++)
    if (want[p] && PARTS[p].fn == vsph_report_scenes_scenes)
      st = write_baseline(R);
  gsl_integration_workspace_free(R->wo);
  gsl_integration_workspace_free(R->wi);
  free(R);
  if (st) return vsph_args_status(CMD, st);

  /* Assemble report.md from every part present. */
  const time_t now = time(NULL);
  char stamp[64];
  strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", gmtime(&now));
  FILE *md = vsph_writers_open(dir, "report.md");
  if (!md) return vsph_args_status(CMD, VSPH_EIO);
  fprintf(md,
          "# vsph report: viscous SPH formulations at a free surface\n\n"
          "vsph %s, %s, %s fidelity, %d cores, %d OpenMP threads. It "
          "computes what Colagrossi, Antuono, Souto-Iglesias and Le Touze, "
          "*Theoretical analysis and numerical verification of the "
          "consistency of viscous SPH formulations in simulating free-surface "
          "flows*, Phys. Rev. E 84, 026705 (2011), derives and measures: the "
          "kernel moment tensors that decide the consistency of the viscous "
          "operators MGF (Monaghan-Gingold), MEAF (Morris-Fox-Zhu) and PVWF "
          "(principle of virtual work) at a free surface, their 1/h "
          "truncation error there, their dissipation, and three free-surface "
          "flows. Every table and figure has its data in a CSV file in this "
          "folder; the mathematics and the reconstructed choices are in "
          "THEORY.md.%s\n\n"
          "Sections: 1 moment tensors, 2 profiles, 3 scaling, 4 dissipation "
          "integrals, 5 scenes, 6 convergence, 7 speed against error, 8 "
          "stability, 9 claims, run facts.\n\n",
          VSPH_VERSION, stamp, full ? "full" : "quick", omp_get_num_procs(),
          omp_get_max_threads(),
          full ? ""
               : " **Quick fidelity**: the scenes run at reduced resolutions "
                 "and end times (stated in each section); `make report "
                 "FULL=1` runs the paper's.");
  for (size_t p = 0; p < NPARTS; p++) {
    char path[700];
    snprintf(path, sizeof path, "%s/%s.md", parts_dir, PARTS[p].name);
    char *text = vsph_writers_slurp(path, NULL);
    if (text) {
      fputs(text, md);
      free(text);
    }
  }
  fprintf(md, "## Run facts\n\n| part | wall time this run (s) |\n|---|---|\n");
  for (size_t p = 0; p < NPARTS; p++) {
    if (!want[p]) continue;
    if (cached[p])
      fprintf(md, "| %s | cached |\n", PARTS[p].name);
    else
      fprintf(md, "| %s | %.1f |\n", PARTS[p].name, wall[p]);
  }
  fprintf(md,
          "\nCompiler: gcc %s. Kernel: renormalised 3h Gaussian, h/dx = 4/3, "
          "RK4 at CFL 1, delta-SPH off, unless stated. Each run's parameters "
          "are in runs/*/used_parameters.yml and runs/*/run.json.\n",
          __VERSION__);
  if (vsph_writers_close(md, dir, "report.md"))
    return vsph_args_status(CMD, VSPH_EIO);
  if (vsph_plot_html(dir, "report.md", "report.html", "vsph report"))
    return vsph_args_status(CMD, VSPH_EIO);
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "version", VSPH_VERSION);
  cJSON_AddStringToObject(o, "source_hash", vsph_source_hash_id);
  cJSON_AddStringToObject(o, "date", stamp);
  cJSON_AddStringToObject(o, "fidelity", full ? "full" : "quick");
  cJSON_AddNumberToObject(o, "cores", omp_get_num_procs());
  cJSON_AddNumberToObject(o, "threads", omp_get_max_threads());
  cJSON_AddStringToObject(o, "compiler", __VERSION__);
  cJSON *w = cJSON_CreateObject();
  for (size_t p = 0; p < NPARTS; p++)
    if (want[p]) {
      if (cached[p])
        cJSON_AddStringToObject(w, PARTS[p].name, "cached");
      else
        cJSON_AddNumberToObject(w, PARTS[p].name, wall[p]);
    }
  cJSON_AddItemToObject(o, "wall_s", w);
  cJSON_AddNumberToObject(o, "wall_total_s", omp_get_wtime() - t_all);
  if (vsph_writers_json_file(o, dir, "run.json"))
    return vsph_args_status(CMD, VSPH_EIO);
  fprintf(stderr, "vsph report: wrote %s/report.md and report.html (%.0f s)\n",
          dir, omp_get_wtime() - t_all);
  return 0;
}
