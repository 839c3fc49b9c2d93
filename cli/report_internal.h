#ifndef VSPH_CLI_REPORT_INTERNAL_H
#define VSPH_CLI_REPORT_INTERNAL_H

/* Internals shared by cmd_report.c, report_analysis.c and report_scenes.c;
 * never included from another folder. */

#include <gsl/gsl_integration.h>
#include <stddef.h>
#include <stdio.h>

/* The ladder of one scene: error and cost per formulation and resolution,
 * computed once per report invocation (report_scenes.c). */
struct vsph_report_ladder {
  double dx[3][3], err[3][3], wall[3][3], pairs[3][3];
  int ok[3][3];
  double t_unstable[3][3];
};

/** The report being written. */
struct vsph_report {
  const char *dir; /* output folder */
  int full;        /* 1: the paper's resolutions and end times */
  FILE *md;        /* the current part's Markdown */
  gsl_integration_workspace *wo, *wi;
  char claims[64][4][256]; /* claim, paper, ours, verdict */
  size_t nclaims;
  struct vsph_report_ladder ladder[3]; /* memo of the scene ladders */
  int have_ladder[3];
};

/* One run's figures, from the cache or a fresh run. */
struct vsph_report_run {
  char dir[512];     /* its output folder */
  int ok;            /* 1: finished, 0: stopped as unstable */
  double t_unstable; /* when, if unstable */
  char reason[160];
  double wall_s, pairs;
  size_t n, steps, res;
  /* from energy.csv */
  size_t nrow;
  double *t, *Ek, *Pv, *res_b, *dEk, *Ekr, *dEkr;
};

/* Add a row to the claims table (copied). */
void vsph_report_analysis_claim(struct vsph_report *R, const char *claim,
                                const char *paper, const char *ours,
                                const char *verdict);

/* Analysis parts (THEORY 2-4). */
int vsph_report_analysis_tensors(struct vsph_report *R);
int vsph_report_analysis_profiles(struct vsph_report *R);
int vsph_report_analysis_scaling(struct vsph_report *R);
int vsph_report_analysis_dissipation(struct vsph_report *R);
int vsph_report_analysis_claims(struct vsph_report *R);

/* Scene parts (THEORY 5-6). */
int vsph_report_scenes_scenes(struct vsph_report *R);
int vsph_report_scenes_convergence(struct vsph_report *R);
int vsph_report_scenes_speed(struct vsph_report *R);
int vsph_report_scenes_stability(struct vsph_report *R);
int vsph_report_scenes_claims(struct vsph_report *R);

/* A run through the cache: reuses DIR when its key (version and every
 * setting) matches, otherwise runs the solver. extra: "Section:key=value"
 * settings, NULL-terminated. */
int vsph_report_scenes_run(struct vsph_report *R, const char *scene,
                           const char *visc, size_t res, double t_end,
                           const char *const *extra, const char *tag,
                           struct vsph_report_run *out);
void vsph_report_scenes_run_free(struct vsph_report_run *r);

/* Baseline figures of the quick report's coarsest runs (tests reuse it):
 * for each scene and formulation, the final decay error E_k/E_k(0) -
 * E_ref/E_ref(0) (vortex, wave) or the final E_k/E_k(0) (square, no
 * reference for t > 0), the initial dissipation error and the stability
 * verdict. */
struct vsph_report_baseline {
  char scene[32], visc[8];
  size_t res;
  double t_end;
  double ek_final; /* see above */
  double diss0;    /* (P_visc(0) - dEk_ref(0)) / |dEk_ref(0)| */
  int ok;          /* stability verdict */
};
int vsph_report_scenes_baseline(struct vsph_report *R, size_t i,
                                struct vsph_report_baseline *b);
size_t vsph_report_scenes_baseline_count(void);

#endif /* VSPH_CLI_REPORT_INTERNAL_H */
