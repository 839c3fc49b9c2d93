/* Section 9 of the report: the paper's claims beside our figures, each with
 * a verdict. The analysis claims (THEORY 2-4) are recomputed here (they are
 * cheap), so the table is complete even when those parts come from the
 * cache; the scene claims read the runs of sections 5-8. */
#include "report_claims.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../analysis/dissipation.h"
#include "../analysis/scaling.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../kernels/kernel.h"
#include "../solver/scene.h"
#include "report.h"
#include "report_parts.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */
enum {
  MGF = VSPH_VISCOUS_MGF,
  MEAF = VSPH_VISCOUS_MEAF,
  PVWF = VSPH_VISCOUS_PVWF
};

static const char *yes_no(int ok, const char *yes, const char *no) {
  return ok ? yes : no;
}

/* ---------------------------------------------------- analysis (THEORY 2-4) */

static int scaling_claims(struct vsph_report *R) {
  double slope[2][NFORM];
  int round_[2][NFORM];
  for (int fk = 0; fk < 2; fk++) { /* rotation, strain */
    struct vsph_scaling_props sp;
    int st = vsph_scaling_props_init(&sp, NULL);
    if (!st) st = vsph_fields_props_init(&sp.field, fk, 2);
    struct vsph_scaling_result r;
    if (!st) st = vsph_scaling_surface(&sp, &r);
    if (st) return st;
    for (int f = 0; f < NFORM; f++) {
      slope[fk][f] = r.slope[f];
      round_[fk][f] = r.rounding[f];
    }
  }
  char ours[320];
  snprintf(ours, sizeof ours,
           "pure strain, 2-D, h/dx 4/3, h halved 4 times from 0.1: slopes "
           "MGF %.3f, MEAF %.3f, PVWF %.3f",
           slope[1][MGF], slope[1][MEAF], slope[1][PVWF]);
  int st = vsph_report_claim(
      R,
      "All three operators diverge like 1/h at the surface when n.D.n != 0 "
      "(App. B)",
      "slope -1", ours,
      "none (the paper's result is analytic; ours are particle sums, "
      "Gaussian kernel, h/dx 4/3)",
      yes_no(fabs(slope[1][MGF] + 1) < 0.01 &&
                 fabs(slope[1][MEAF] + 1) < 0.01 &&
                 fabs(slope[1][PVWF] + 1) < 0.01,
             "reproduced", "differs"));
  snprintf(ours, sizeof ours,
           "rigid rotation, same ladder: MGF %s, PVWF %s, MEAF slope %.3f "
           "(its term is tangential)",
           round_[0][MGF] ? "rounding level" : "grows",
           round_[0][PVWF] ? "rounding level" : "grows", slope[0][MEAF]);
  if (!st)
    st = vsph_report_claim(
        R,
        "Rigid rotation (n.D.n = 0): MGF and PVWF stay bounded, MEAF "
        "diverges like 1/h (App. B)",
        "MEAF ~ -mu C_N/h du/dn", ours, "none (as above)",
        yes_no(round_[0][MGF] && round_[0][PVWF] &&
                   fabs(slope[0][MEAF] + 1) < 0.01,
               "reproduced", "differs"));
  return st;
}

static int dissipation_claims(struct vsph_report *R) {
  struct vsph_dissipation_result d[4];
  static const int forms[4] = {MGF, MEAF, PVWF, MGF};
  static const int fields[4] = {VSPH_FIELDS_STRAIN, VSPH_FIELDS_ROTATION,
                                VSPH_FIELDS_STRAIN, VSPH_FIELDS_STRAIN};
  static const double hdxs[4] = {VSPH_CONSTS_HDX, VSPH_CONSTS_HDX,
                                 VSPH_CONSTS_HDX, 3.0};
  for (int k = 0; k < 4; k++) {
    struct vsph_dissipation_props dp;
    int st = vsph_dissipation_props_init(&dp, NULL);
    dp.form = forms[k];
    dp.nacross = 160;
    dp.hdx = hdxs[k];
    if (!st) st = vsph_fields_props_init(&dp.field, fields[k], 2);
    if (!st) st = vsph_dissipation_compute(&dp, &d[k]);
    if (st) return st;
  }
  char ours[320];
  snprintf(ours, sizeof ours,
           "square, 160 across: lattice error %+.2f %% at h/dx 4/3, %+.2f %% "
           "at h/dx 3; surface part %+.2f %% (falls like h/L)",
           100 * d[0].lattice_error, 100 * d[3].lattice_error,
           100 * d[0].surface_error);
  int st = vsph_report_claim(
      R,
      "MGF is globally consistent: P -> -int V:D despite the 1/h surface "
      "force (5.35)",
      "consistent up to O(h)", ours,
      "none (a property of the operator, measured on an analytic strain "
      "field: square of 160 across, h/dx 4/3 and 3)",
      "reproduced in the limit: the surface part vanishes with h/L and the "
      "lattice part with h/dx (docs/theory.md §4: about 6 % at h/dx 4/3)");
  snprintf(ours, sizeof ours,
           "rigid rotation, square, 160 across, h/dx 4/3: P/|P_grad| = %.3f",
           d[1].rel_error);
  if (!st)
    st = vsph_report_claim(
        R,
        "MEAF converges to -mu int |grad u|^2 and dissipates rigid rotation "
        "(5.36)",
        "wrong limit", ours, "none (as above)",
        yes_no(fabs(d[1].rel_error + 1) < 0.05, "reproduced", "differs"));
  snprintf(ours, sizeof ours,
           "pure strain, square, 160 across, h/dx 4/3: rel. error %.1e",
           d[2].rel_error);
  if (!st)
    st = vsph_report_claim(
        R,
        "PVWF's dissipation is -int V:D exactly at the discrete level (4.18)",
        "exact", ours, "none (as above)",
        yes_no(fabs(d[2].rel_error) < 1e-12, "reproduced", "differs"));
  return st;
}

/* --------------------------------------------------- scenes (THEORY 5-6) */

/* The finest run of each scene and formulation, with its decay error. */
struct finest {
  struct vsph_jobs_run run[VSPH_REPORT_NSCENES][NFORM];
  double err[VSPH_REPORT_NSCENES][NFORM];
  struct vsph_report_ladder lr[VSPH_REPORT_NSCENES];
};

static int load_finest(struct vsph_report *R, struct finest *fi) {
  struct vsph_report_richardson rr;
  int st = vsph_report_runs_richardson(&R->runs, &rr);
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    for (int f = 0; f < NFORM && !st; f++) {
      const struct vsph_report_ladderdef *L =
          vsph_report_runs_ladder(&R->runs, sc, 0);
      struct vsph_jobs_spec rs = {L->scene,
                                  vsph_viscous_name(f),
                                  L->res[VSPH_REPORT_LADDER - 1],
                                  L->t_end,
                                  NULL,
                                  NULL};
      st = vsph_report_runs_get(&R->runs, &rs, &fi->run[sc][f]);
      if (!st)
        fi->err[sc][f] =
            vsph_report_runs_error(&fi->run[sc][f], sc == 1 ? &rr : NULL);
    }
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    st = vsph_report_runs_ladder_figures(&R->runs, sc, &fi->lr[sc]);
  return st;
}

/* PVWF's onset on the stretching square over the ladder (VI B), judged
 * at the finest resolution. */
static int square_onset_claim(struct vsph_report *R,
                              const struct vsph_report_ladder *lr,
                              const struct vsph_report_richardson *rr) {
  int st = VSPH_OK;
  char ours[320];
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 1, 0);
  int pv_unstable = 0;
  double tpv = INFINITY, on_lo = INFINITY, on_hi = -INFINITY;
  double on_fine = (double)NAN;
  for (int k = 0; k < VSPH_REPORT_LADDER && !st; k++) {
    if (!lr->ok[PVWF][k]) {
      pv_unstable++;
      tpv = fmin(tpv, lr->t_unstable[PVWF][k]);
    }
    struct vsph_jobs_spec spec = {L->scene, "pvwf", L->res[k],
                                  L->t_end, NULL,   NULL};
    struct vsph_jobs_run r;
    if ((st = vsph_report_runs_get(&R->runs, &spec, &r))) break;
    const double on = vsph_report_runs_onset(&r, rr, VSPH_REPORT_ONSET);
    vsph_report_runs_free(&r);
    if (isfinite(on)) {
      on_lo = fmin(on_lo, on);
      on_hi = fmax(on_hi, on);
    }
    on_fine = on; /* the finest last */
  }
  if (st) return st;
  snprintf(ours, sizeof ours,
           "L/dx %zu-%zu: dissipation departs from the reference by > %g %% "
           "at t A0 = %.2f-%.2f (onset); stopped by pairing in %d of %d "
           "runs, earliest at t A0 = %.2f",
           L->res[0], L->res[2], 100 * VSPH_REPORT_ONSET, on_lo, on_hi,
           pv_unstable, VSPH_REPORT_LADDER, pv_unstable ? tpv : (double)NAN);
  char verdict[256], setup[600];
  /* judged at the finest resolution: a coarse run departs early from its
   * own truncation error, not from pairing; the paper's "about 0.1" read
   * as 0.15 at most */
  if (!isfinite(on_fine))
    snprintf(verdict, sizeof verdict,
             "not reproduced at L/dx = %zu: no departure", L->res[2]);
  else if (on_fine < 0.15)
    snprintf(verdict, sizeof verdict,
             "reproduced on a substitute: at L/dx = %zu the dissipation "
             "departs at t A0 = %.2f, the run is stopped later",
             L->res[2], on_fine);
  else
    snprintf(verdict, sizeof verdict,
             "partly: PVWF departs and is stopped by pairing, but later "
             "than the paper's 0.1 (t A0 = %.2f at L/dx = %zu)",
             on_fine, L->res[2]);
  snprintf(setup, sizeof setup,
           "reference: MGF extrapolated in h and h/dx [reconstructed] (the "
           "paper's: a finite-volume solution); onset: first departure of "
           "dE_k/dt by > %g %% of the reference's [reconstructed: the paper "
           "reads it off its figure]; L/dx %zu-%zu (the paper's 320)",
           100 * VSPH_REPORT_ONSET, L->res[0], L->res[2]);
  st = vsph_report_claim(
      R, "PVWF on the stretching square becomes unstable (VI B)",
      "deviates after t A0 of about 0.1", ours, setup, verdict);
  return st;
}

static int square_claims(struct vsph_report *R, const struct finest *fi) {
  const struct vsph_jobs_run *run = fi->run[1];
  const size_t rs = vsph_report_runs_ladder(&R->runs, 1, 0)->res[2];
  char ours[320];
  /* P/P_exact = 1 - d, with d = (P - P_exact)/|P_exact| and P_exact < 0 */
  const double d_m = vsph_report_runs_diss0(&run[MGF]);
  const double d_e = vsph_report_runs_diss0(&run[MEAF]);
  const double d_p = vsph_report_runs_diss0(&run[PVWF]);
  snprintf(ours, sizeof ours,
           "(P - P_exact)/|P_exact| at t = 0, L/dx = %zu: PVWF %+.1e, MGF "
           "%+.2f %% (negative: more dissipation than exact), MEAF at %.1f "
           "%% of exact",
           rs, d_p, 100 * d_m, 100 * (1 - d_e));
  char setup[600];
  snprintf(setup, sizeof setup,
           "t = 0 only, the discrete initial field (Poisson pressure by FFT); "
           "L/dx = %zu%s",
           rs,
           R->runs.full ? ""
                        : " (the paper's 320: the surface deficit "
                          "falls like h/L)");
  int st = vsph_report_claim(
      R, "Stretching square, initial dissipation error (VI B)",
      "PVWF 0.04 %, MGF about 5 %, MEAF about half", ours, setup,
      yes_no(fabs(d_p) < 4e-4 && fabs(1 - d_e - 0.5) < 0.1 && fabs(d_m) < 0.1,
             R->runs.full
                 ? "reproduced: PVWF exact, MEAF half; MGF's figure is its "
                   "lattice error (-6 %, section 4) less a surface deficit"
                 : "reproduced on a substitute: PVWF exact, MEAF half; MGF's "
                   "figure is its lattice error (-6 %, section 4) less a "
                   "surface deficit that falls like h/L",
             "differs"));
  const struct vsph_report_ladder *lr = &fi->lr[1];
  struct vsph_report_richardson rr;
  if (!st) st = vsph_report_runs_richardson(&R->runs, &rr);
  if (st) return st;
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 1, 0);
  st = square_onset_claim(R, lr, &rr);
  snprintf(ours, sizeof ours,
           "fitted order %.2f over L/dx %zu-%zu against MGF extrapolated "
           "in h and h/dx (h/dx 2 and 3, L/dx %zu-%zu)",
           vsph_scaling_slope(lr->dx[MGF], lr->err[MGF], VSPH_REPORT_LADDER),
           L->res[0], L->res[2], rr.res[0], rr.res[3]);
  const double order =
      vsph_scaling_slope(lr->dx[MGF], lr->err[MGF], VSPH_REPORT_LADDER);
  snprintf(setup, sizeof setup,
           "reference: MGF extrapolated in h and h/dx [reconstructed] (the "
           "paper's finite-volume solution is not available, so its 0.55 %% "
           "is not comparable); L/dx %zu-%zu (the paper's 320)",
           L->res[0], L->res[2]);
  if (!st)
    st = vsph_report_claim(
        R, "MGF converges linearly on the stretching square (VI B)",
        "0.55 % error at L/dx = 320 against a finite-volume solution", ours,
        setup,
        fabs(order - 1) < 0.3
            ? "partly: first order against a reference without MGF's "
              "h/dx = 4/3 lattice bias (the paper's finite-volume solution "
              "is not available here)"
            : "differs: not first order at these resolutions: MGF's lattice "
              "error at h/dx = 4/3 does not fall with h (section 4)");
  const double share_m = 1 - run[MGF].Ek[run[MGF].nrow - 1] / run[MGF].Ek[0];
  const double share_p = 1 - run[PVWF].Ek[run[PVWF].nrow - 1] / run[PVWF].Ek[0];
  const double share_r = 1 - rr.E[100] / rr.E[0];
  snprintf(ours, sizeof ours,
           "reference (MGF extrapolated in h and h/dx) %.0f %%; at L/dx = "
           "%zu: MGF %.0f %%, PVWF %.0f %%%s",
           100 * share_r, L->res[2], 100 * share_m, 100 * share_p,
           run[PVWF].ok ? "" : " (by t A0 = ");
  if (!run[PVWF].ok) { /* how far it got, in t A0 (t_end is t A0 = 1) */
    const size_t n = strlen(ours);
    snprintf(ours + n, sizeof ours - n, "%.3g: PVWF stopped, unstable)",
             run[PVWF].t_unstable / L->t_end);
  }
  if (!st)
    st = vsph_report_claim(
        R, "Stretching square: share of E_k dissipated by t A0 = 1 (VI B)",
        "about 80 %", ours,
        "the share is our reference's (MGF extrapolated in h and h/dx "
        "[reconstructed]), not a finite-volume solution's",
        yes_no(fabs(share_r - 0.8) < 0.05,
               "reproduced on a substitute: by the extrapolated reference "
               "(within 5 points)",
               "differs: the reference differs by more than 5 points"));
  return st;
}

static int vortex_claims(struct vsph_report *R, const struct finest *fi) {
  const double *err = fi->err[0];
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 0, 0);
  char ours[320], setup[600];
  /* the initial profile differs from the paper's whatever the resolution:
   * agreement is on a substitute */
  snprintf(setup, sizeof setup,
           "initial profile (6.39) [reconstructed]: Re 174 against the "
           "paper's 256; disc on rings [reconstructed: the layout is not "
           "stated]; R/dx = %zu to %g s%s",
           L->res[2], L->t_end,
           R->runs.full ? "" : " (the paper's 100 to 100 s)");
  snprintf(ours, sizeof ours,
           "max decay error on rings: MGF %.2e, PVWF %.2e, MEAF %.2e (R/dx "
           "= %zu, t_end %g s)",
           err[MGF], err[PVWF], err[MEAF], L->res[2], L->t_end);
  int st = vsph_report_claim(
      R,
      "Vortex patch: MGF and PVWF follow the reference, MEAF diverges (VI A)",
      "MGF, PVWF close to the analytical u_theta up to t = 100 s; MEAF "
      "departs quickly",
      ours, setup,
      yes_no(err[MEAF] > 3 * fmax(err[MGF], err[PVWF]),
             "reproduced on a substitute (the set-up column)",
             "differs at this resolution and end time"));
  snprintf(ours, sizeof ours, "PVWF %.3e vs MGF %.3e (rings, R/dx = %zu)",
           err[PVWF], err[MGF], L->res[2]);
  if (!st)
    st = vsph_report_claim(
        R, "Vortex patch: PVWF's E_k error is smaller than MGF's (VI A)", "yes",
        ours, setup,
        yes_no(err[PVWF] < err[MGF], "reproduced on a substitute",
               "not reproduced at this resolution"));
  /* MGF's initial dissipation error on both disc layouts (section 6) */
  struct vsph_report_layouts ly;
  if (!st) st = vsph_report_runs_layouts(&R->runs, &ly);
  if (!st) {
    double d0[2][VSPH_REPORT_LADDER], a0[2][VSPH_REPORT_LADDER];
    const double *dx = ly.dx;
    for (int l = 0; l < 2; l++)
      for (int k = 0; k < VSPH_REPORT_LADDER; k++) {
        d0[l][k] = ly.d0[l][MGF][k];
        a0[l][k] = fabs(d0[l][k]);
      }
    const double o_r = vsph_scaling_slope(dx, a0[0], VSPH_REPORT_LADDER);
    const double o_c = vsph_scaling_slope(dx, a0[1], VSPH_REPORT_LADDER);
    snprintf(ours, sizeof ours,
             "MGF initial dissipation error at R/dx %zu, %zu, %zu: rings "
             "%+.2f, %+.2f, %+.2f %% (order %.2f); Cartesian %+.2f, %+.2f, "
             "%+.2f %% (order %.2f)",
             L->res[0], L->res[1], L->res[2], 100 * d0[0][0], 100 * d0[0][1],
             100 * d0[0][2], o_r, 100 * d0[1][0], 100 * d0[1][1],
             100 * d0[1][2], o_c);
    char setup2[600];
    snprintf(setup2, sizeof setup2,
             "measure: MGF's initial dissipation error against resolution "
             "(the paper's: u_theta against the reference at R/dx = 100); "
             "initial profile (6.39) and both disc layouts [reconstructed]; "
             "R/dx %zu-%zu",
             L->res[0], L->res[2]);
    st = vsph_report_claim(
        R, "Vortex patch: MGF converges with resolution (VI A)",
        "MGF close to the reference at R/dx = 100 (layout not stated)", ours,
        setup2,
        o_c > 0.8 && o_c > o_r + 0.3
            ? "partly: MGF converges on a Cartesian disc; on rings its "
              "lattice error (shear at 45 degrees to the local lattice) slows "
              "it (section 4); another measure than the paper's"
        : o_c > 0.8 ? "partly: MGF converges on both layouts, by another "
                      "measure than the paper's"
                    : "not reproduced at these resolutions");
  }
  if (!st)
    st = vsph_report_claim(
        R, "Vortex patch: final rigid rotation omega_inf (VI A)",
        "0.2848 omega0, Re = 256 (the paper's own profile)",
        "0.2071 omega0, Re = 174 (our profile)",
        "initial profile (6.39) [reconstructed] (unreadable in the source)",
        "differs by construction: the initial profile (6.39) is unreadable "
        "in the source and [reconstructed] in docs/theory.md §6");
  return st;
}

static int wave_claims(struct vsph_report *R, const struct finest *fi) {
  const struct vsph_report_ladder *lr = &fi->lr[2];
  char ours[320];
  int n = snprintf(
      ours, sizeof ours, "fitted orders MGF %.2f, MEAF %.2f, PVWF %.2f",
      vsph_scaling_slope(lr->dx[MGF], lr->err[MGF], VSPH_REPORT_LADDER),
      vsph_scaling_slope(lr->dx[MEAF], lr->err[MEAF], VSPH_REPORT_LADDER),
      vsph_scaling_slope(lr->dx[PVWF], lr->err[PVWF], VSPH_REPORT_LADDER));
  int stops = 0; /* runs that stopped: their errors up to the stop */
  for (int f = 0; f < NFORM; f++)
    for (int k = 0; k < VSPH_REPORT_LADDER; k++)
      if (!lr->ok[f][k] && n > 0 && (size_t)n < sizeof ours)
        n += snprintf(ours + n, sizeof ours - (size_t)n,
                      "%s%s at rung %d stopped at t = %.3g s",
                      stops++ ? ", " : "; ", vsph_viscous_label(f), k + 1,
                      lr->t_unstable[f][k]);
  if (stops && n > 0 && (size_t)n < sizeof ours)
    snprintf(ours + n, sizeof ours - (size_t)n, " (errors up to the stop)");
  const struct vsph_report_ladderdef *WL =
      vsph_report_runs_ladder(&R->runs, 2, 0);
  double omin = INFINITY;
  for (int f = 0; f < NFORM; f++)
    omin = fmin(omin,
                vsph_scaling_slope(lr->dx[f], lr->err[f], VSPH_REPORT_LADDER));
  char verdict0[256];
  snprintf(verdict0, sizeof verdict0, "%s at H/dx %zu-%zu, t_end %g s%s",
           stops         ? "differs: runs of the ladder stopped as unstable"
           : omin >= 0.8 ? "reproduced on a substitute (every order >= 0.8)"
                         : "not reproduced for every formulation (an order "
                           "below 0.8)",
           WL->res[0], WL->res[2], WL->t_end,
           R->runs.full ? "" : "; the paper's H/dx = 240 needs FULL=1");
  char setup[600];
  snprintf(setup, sizeof setup,
           "steepness eps = 0.05 [reconstructed] (illegible in the source, "
           "which bounds Lighthill's decay to eps < 0.01); free-slip bottom "
           "[reconstructed]; H/dx %zu-%zu to %g s%s",
           WL->res[0], WL->res[2], WL->t_end,
           R->runs.full ? "" : " (the paper's 240 to 8 s)");
  int st = vsph_report_claim(
      R, "Standing wave: all formulations converge linearly (VI C)",
      "converged at H/dx = 240", ours, setup, verdict0);
  /* Damping, the paper's way: the energy the wave has lost by t_end
   * against Lighthill's phase-free loss (report_runs.c); above 1 is too
   * much damping. The last E_k peak over Lighthill's value there is a
   * second measure: it also carries the phase of the exchange. */
  const struct vsph_jobs_run *w = fi->run[2];
  double loss[NFORM], ratio[NFORM], tpk = 0.0;
  for (int f = 0; f < NFORM; f++) {
    loss[f] = vsph_report_runs_loss_ratio(&w[f], w[f].nrow - 1);
    size_t pk = 0;
    for (size_t k = 1; k + 1 < w[f].nrow; k++)
      if (w[f].Ek[k] > w[f].Ek[k - 1] && w[f].Ek[k] >= w[f].Ek[k + 1]) pk = k;
    ratio[f] = pk ? (w[f].Ek[pk] / w[f].Ek[0]) / (w[f].Ekr[pk] / w[f].Ekr[0])
                  : (double)NAN;
    if (f == MGF) tpk = w[f].t[pk];
  }
  const size_t res = vsph_report_runs_ladder(&R->runs, 2, 0)->res[2];
  /* a run that stopped: its figures are by its last row, said */
  char stopped[160] = "";
  int first = -1;
  for (int f = 0, m = 0; f < NFORM; f++)
    if (!w[f].ok) {
      if (first < 0) first = f;
      m += snprintf(stopped + m, sizeof stopped - (size_t)m,
                    "; %s stopped (unstable) at t = %.3g s",
                    vsph_viscous_label(f), w[f].t_unstable);
    }
  snprintf(
      ours, sizeof ours,
      "energy lost by t = %g s over Lighthill's (H/dx = %zu): PVWF "
      "%.3f, MGF %.3f, MEAF %.3f (1 = exact, > 1 too much damping); "
      "second measure, last E_k peak (t = %.2f s) over Lighthill's: "
      "PVWF %.3f, MGF %.3f, MEAF %.3f%s%s",
      w[MGF].t[w[MGF].nrow - 1], res, loss[PVWF], loss[MGF], loss[MEAF], tpk,
      ratio[PVWF], ratio[MGF], ratio[MEAF], stopped,
      stopped[0] ? " (its figures by then; nan: no E_k peak by then)" : "");
  const double em = fabs(loss[MGF] - 1), ep = fabs(loss[PVWF] - 1);
  const double ee = fabs(loss[MEAF] - 1);
  char verdict[256];
  if (first >= 0) /* the damping over the whole run is not measured */
    snprintf(verdict, sizeof verdict,
             "differs at H/dx = %zu: %s stopped (unstable) at t = %.3g s of "
             "%g s",
             res, vsph_viscous_label(first), w[first].t_unstable, WL->t_end);
  else if (ee > 2 * fmax(em, ep) && ep < em)
    snprintf(verdict, sizeof verdict,
             loss[MGF] > 1
                 ? "partly, at H/dx = %zu: the ranking holds by the energy "
                   "budget (PVWF closest, then MGF, MEAF far off), but MGF "
                   "damps too much here, not too little"
                 : "reproduced on a substitute at H/dx = %zu by the energy "
                   "budget (PVWF closest, then MGF, MEAF far off); MGF damps "
                   "too little, as the paper says",
             res);
  else if (ee > 2 * fmax(em, ep))
    snprintf(verdict, sizeof verdict,
             "partly, at H/dx = %zu: MEAF fails, but MGF's budget is closer "
             "than PVWF's",
             res);
  else
    snprintf(verdict, sizeof verdict, "not reproduced at H/dx = %zu", res);
  if (!st)
    st = vsph_report_claim(
        R,
        "Standing wave: PVWF matches the decay best, MGF slightly "
        "under-predicts the damping, MEAF fails (VI C)",
        "PVWF best, MGF a little too little damping, MEAF wrong", ours, setup,
        verdict);
  return st;
}

/* ------------------------------------- the paper's resolutions, archived */

/* Scene @p sc's figure of run @p r, as its claims measure it: the vortex
 * patch's largest E_k decay error against the Bessel series, the
 * stretching square's (P - P_exact)/|P_exact| at t = 0 (its E_k reference
 * is built from runs at the report's own fidelity), the wave's energy
 * lost by its last row over Lighthill's and its E_k error; @p err: the
 * error at hand, or NAN to compute it against the run's own reference;
 * @p t_end: the run's end time (a run that stopped says how far it got,
 * its figures being by its last row). */
static void scene_figure(char *buf, size_t len, int sc,
                         const struct vsph_jobs_run *r, double err,
                         double t_end) {
  char status[200];
  if (r->nrow < 2) { /* nothing to measure a decay or a loss on */
    snprintf(buf, len, "%zu row%s of energy.csv only: no figure", r->nrow,
             r->nrow == 1 ? "" : "s");
    return;
  }
  const double t1 = r->t[r->nrow - 1];
  if (r->ok)
    snprintf(status, sizeof status, "ok to t = %.4g s", t1);
  else
    snprintf(status, sizeof status,
             "**%s** at t = %.3g s; figures by its last row, t = %.3g s "
             "(%.0f %% of t_end)",
             isfinite(r->t_unstable) ? "unstable" : "stopped (no reason kept)",
             isfinite(r->t_unstable) ? r->t_unstable : t1, t1,
             100.0 * t1 / t_end);
  if (!isfinite(err) && sc != 1) err = vsph_report_runs_error(r, NULL);
  if (sc == 0) {
    snprintf(buf, len, "%s; E_k error %.2e", status, err);
  } else if (sc == 1) { /* PVWF's is exact on the square: round-off */
    const double d = vsph_report_runs_diss0(r);
    char dv[32];
    if (fabs(d) < 1e-10)
      snprintf(dv, sizeof dv, "round-off");
    else
      snprintf(dv, sizeof dv, "%+.2e", d);
    snprintf(buf, len, "%s; (P - P_exact)/\\|P_exact\\| at t = 0: %s", status,
             dv);
  } else {
    snprintf(buf, len, "%s; energy lost over Lighthill's %.3f, E_k error %.2e",
             status, vsph_report_runs_loss_ratio(r, r->nrow - 1), err);
  }
}

int vsph_report_claims_beside(struct vsph_report *R,
                              const struct vsph_jobs_run run[][NFORM],
                              const double err[][NFORM]) {
  /* the FULL plan, each run's verdict in the archive */
  struct vsph_jobs jobs;
  memset(&jobs, 0, sizeof jobs);
  struct vsph_archive_judge jd = {0};
  int st = vsph_report_plan_jobs(R->dir, 1, &jobs);
  if (!st) st = vsph_report_plan_judge(&jobs, R->judge, &jd);
  int *stands = st ? NULL : calloc(jobs.n + 1, sizeof *stands);
  if (!st && !stands) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot list the FULL plan");
  }
  if (!st) st = vsph_archive_standing(R->beside, &jd, stands);
  const char *const *names = jd.plan_name;
  const size_t n = jd.nplan;
  size_t held = 0, stand = 0, unjudged = 0, stale = 0, unreadable = 0;
  char *rows = NULL;
  size_t rlen = 0;
  FILE *m = st ? NULL : open_memstream(&rows, &rlen);
  if (!st && !m) st = VSPH_ENOMEM;
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    for (int f = 0; f < NFORM && !st; f++) {
      const struct vsph_report_ladderdef *Q =
          vsph_report_runs_ladder(&R->runs, sc, 1);
      const struct vsph_report_ladderdef *F = vsph_report_runs_full_ladder(sc);
      const struct vsph_scene_type *t = vsph_scene_find(F->scene);
      const char *dx = t ? t->length_name : "res";
      char name[128], dir[700], quick[320], full[320] = "not archived yet";
      snprintf(name, sizeof name, "%s-%s-%zu", F->scene, vsph_viscous_name(f),
               F->res[VSPH_REPORT_LADDER - 1]);
      scene_figure(quick, sizeof quick, sc, &run[sc][f], err[sc][f], Q->t_end);
      const char *judged = "–";
      snprintf(dir, sizeof dir, "%s/runs/%s", R->beside, name);
      size_t k = 0;
      while (k < n && strcmp(names[k], name)) k++;
      const int v = k < n ? stands[k] : VSPH_ARCHIVE_ABSENT;
      struct vsph_jobs_run r;
      if (v == VSPH_ARCHIVE_ABSENT && access(dir, F_OK) == 0) {
        /* there, but not whole: not read (entries.md leaves it out) */
        snprintf(full, sizeof full,
                 "an entry whose seal does not hold: not read");
        unreadable++;
      } else if (v != VSPH_ARCHIVE_ABSENT && vsph_jobs_load(dir, &r)) {
        /* whole, but not tables this build reads (said on stderr) */
        vsph_jobs_run_free(&r);
        snprintf(full, sizeof full, "its tables cannot be read (see stderr)");
        unreadable++;
      } else if (v != VSPH_ARCHIVE_ABSENT) {
        held++;
        scene_figure(full, sizeof full, sc, &r, (double)NAN, F->t_end);
        vsph_jobs_run_free(&r);
        stand += v == VSPH_ARCHIVE_STANDS;
        unjudged += v == VSPH_ARCHIVE_UNJUDGED;
        stale += v == VSPH_ARCHIVE_STALE;
        judged = v == VSPH_ARCHIVE_STANDS     ? "yes"
                 : v == VSPH_ARCHIVE_UNJUDGED ? "unjudged (entries.md says why)"
                                              : "no (entries.md says why)";
      }
      fprintf(m,
              "| %s | %s | %s/dx = %zu, t_end %g s: %s | %s/dx = %zu, "
              "t_end %g s: %s | %s |\n",
              F->scene, vsph_viscous_label(f), dx,
              Q->res[VSPH_REPORT_LADDER - 1], Q->t_end, quick, dx,
              F->res[VSPH_REPORT_LADDER - 1], F->t_end, full, judged);
    }
  if (m && fclose(m) != 0 && !st) st = VSPH_ENOMEM;
  free(stands);
  vsph_report_plan_judge_free(&jd);
  vsph_jobs_plan_free(&jobs);
  if (!st) {
    vsph_text_set(&R->tv, "archive", "%s", R->beside);
    vsph_text_set(&R->tv, "held", "%zu", held);
    vsph_text_set(&R->tv, "stand", "%zu", stand);
    vsph_text_set(&R->tv, "unjudged", "%zu", unjudged);
    vsph_text_set(&R->tv, "stale", "%zu", stale);
    vsph_text_set(&R->tv, "unreadable", "%zu", unreadable);
    vsph_text_set(&R->tv, "total", "%d", VSPH_REPORT_NSCENES * NFORM);
    st = vsph_report_say(R, "claims.archive_head");
  }
  if (!st) {
    fputs(rows, R->md);
    fputc('\n', R->md);
  }
  free(rows);
  if (st) return st;
  return ferror(R->md) ? VSPH_EIO : VSPH_OK;
}

int vsph_report_claims_plan(struct vsph_report *R) {
  /* every scene, whatever the filter, and the runs of sections 10, 11 */
  int st = vsph_report_runs_plan_ladders(&R->runs, 1);
  if (!st) st = vsph_report_channel_plan(R);
  if (!st) st = vsph_report_contact_plan(R);
  return st;
}

int vsph_report_claims_write(struct vsph_report *R) {
  R->nclaims = 0;
  R->claim_see = "scaling";
  int st = scaling_claims(R);
  R->claim_see = "dissipation";
  if (!st) st = dissipation_claims(R);
  struct finest fi;
  memset(&fi, 0, sizeof fi);
  if (!st) st = load_finest(R, &fi);
  R->claim_see = "scenes";
  if (!st) st = square_claims(R, &fi);
  R->claim_see = "convergence";
  if (!st) st = vortex_claims(R, &fi);
  R->claim_see = "scenes";
  if (!st) st = wave_claims(R, &fi);
  R->claim_see = "patch";
  if (!st) st = vsph_report_patch_claims(R);
  R->claim_see = "channel";
  if (!st) st = vsph_report_channel_claims(R);
  R->claim_see = "contact";
  if (!st) st = vsph_report_contact_claims(R);
  R->claim_see = NULL;
  if (!st) {
    vsph_text_set(&R->tv, "quick_note", "%s",
                  R->runs.full ? "" : vsph_text_get("claims.quick_note"));
    st = vsph_report_say(R, "claims.head");
  }
  if (!st) st = vsph_report_claims_table(R);
  if (!st && R->beside) /* (C11 adds const to arrays of arrays by cast) */
    st = vsph_report_claims_beside(R,
                                   (const struct vsph_jobs_run(*)[NFORM])fi.run,
                                   (const double(*)[NFORM])fi.err);
  for (int sc = 0; sc < VSPH_REPORT_NSCENES; sc++)
    for (int f = 0; f < NFORM; f++) vsph_report_runs_free(&fi.run[sc][f]);
  return st;
}

/* The verdict classes: the word each verdict is marked with, the symbol
 * beside it (for Markdown readers without the HTML's colours) and the CSS
 * class of report.html's style. */
static const struct {
  const char *word, *symbol, *css;
} VERDICT[VSPH_REPORT_NVERDICTS] = {
    [VSPH_REPORT_REPRODUCED] = {"reproduced", "\u2714", "v-rep"},
    [VSPH_REPORT_SUBSTITUTE] = {"reproduced on a substitute", "\u2713",
                                "v-sub"},
    [VSPH_REPORT_PARTLY] = {"partly", "\u25d0", "v-part"},
    [VSPH_REPORT_DIFFERS] = {"differs", "\u2718", "v-diff"},
    [VSPH_REPORT_NOT_TESTED] = {"not tested", "\u2013", "v-none"}};

int vsph_report_claims_class(const char *verdict) {
  if (!strncmp(verdict, "not tested", 10)) return VSPH_REPORT_NOT_TESTED;
  if (!strncmp(verdict, "partly", 6)) return VSPH_REPORT_PARTLY;
  if (!strncmp(verdict, "reproduced on a substitute", 26))
    return VSPH_REPORT_SUBSTITUTE;
  if (!strncmp(verdict, "reproduced", 10)) return VSPH_REPORT_REPRODUCED;
  if (!strncmp(verdict, "differs", 7) ||
      !strncmp(verdict, "not reproduced", 14))
    return VSPH_REPORT_DIFFERS;
  return -1;
}

int vsph_report_claims_table(struct vsph_report *R) {
  size_t tally[VSPH_REPORT_NVERDICTS] = {0};
  for (size_t k = 0; k < R->nclaims; k++)
    tally[vsph_report_claims_class(R->claims[k].verdict)]++;
  fprintf(R->md, "**%zu claims:**", R->nclaims);
  for (int v = 0; v < VSPH_REPORT_NVERDICTS; v++)
    fprintf(R->md, "%s <span class=\"v %s\">%s %zu %s</span>", v ? "," : "",
            VERDICT[v].css, VERDICT[v].symbol, tally[v], VERDICT[v].word);
  fprintf(R->md, ".\n\n");
  const int st = vsph_report_say(R, "claims.table_head");
  if (st) return st;
  for (size_t k = 0; k < R->nclaims; k++) {
    const char *cell[5] = {R->claims[k].claim, R->claims[k].paper,
                           R->claims[k].ours, R->claims[k].setup,
                           R->claims[k].verdict};
    for (int c = 0; c < 5; c++) { /* a '|' inside a cell is escaped */
      fputs("| ", R->md);
      const char *text = cell[c];
      if (c == 4) { /* the verdict: its class marked, then the rest of its
                     * words (the class's own word once, not twice) */
        const int v = vsph_report_claims_class(text);
        fprintf(R->md, "<span class=\"v %s\">%s %s</span> ", VERDICT[v].css,
                VERDICT[v].symbol, VERDICT[v].word);
        const size_t w = strlen(VERDICT[v].word);
        if (!strncmp(text, VERDICT[v].word, w)) {
          text += w;
          text += strspn(text, ":, ");
        }
      }
      for (const char *s = text; *s; s++) {
        if (*s == '|') fputc('\\', R->md);
        fputc(*s, R->md);
      }
      fputc(' ', R->md);
    }
    fprintf(R->md, "| [%s](#sec-%s) |\n", R->claims[k].see, R->claims[k].see);
  }
  fprintf(R->md, "\n");
  return ferror(R->md) ? VSPH_EIO : VSPH_OK;
}
