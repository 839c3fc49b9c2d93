/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 5 of the report: the three scenes with each formulation against
 * their references (THEORY 5-6): E_k, dE_k/dt, the decay error and the
 * energy-budget residual, and the vortex patch's u_theta(r) profiles. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/references.h"
#include "../analysis/series.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/plot.h"
#include "../io/vtk.h"
#include "../solver/scene.h"
#include "report_fv.h"
#include "report_parts.h"

#define NFORM VSPH_VISCOUS_PAPER_COUNT /* the free-surface study's three */

/* Snapshots of the vortex patch's ladder runs (report_runs.c keeps 4, plus
 * the one at t = 0). */
#define NSNAP 5

/* Per-run table for the figures: t, Ek, Eref, dEk/dt, dEk_ref, relative
 * error, |residual|, |P_visc|. */
static int write_derived(struct vsph_report *R, const char *name,
                         const struct vsph_jobs_run *r,
                         const struct vsph_report_richardson *rr) {
  FILE *f = vsph_csv_open(
      R->dir, name,
      "t,Ek,Ek_ref,dEk_dt,dEk_ref,rel_err,abs_residual,abs_P_visc,P_visc,"
      "dEm_ref,loss_ratio");
  if (!f) return VSPH_EIO;
  const double e0 = vsph_report_runs_eref(r, 0, rr);
  for (size_t k = 0; k < r->nrow; k++) {
    const double e = vsph_report_runs_eref(r, k, rr);
    /* the square's reference rate for t > 0 from the extrapolated curve */
    const double de = rr && k > 0
                          ? vsph_series_interp(rr->t, rr->dE, 101, r->t[k])
                          : r->dEkr[k];
    fprintf(f, "%.8g,%.10e,%.10e,%.10e,%.10e,%.6e,%.6e,%.6e,%.10e,%.10e,%.6e\n",
            r->t[k], r->Ek[k], e, r->dEk[k], de, r->Ek[k] / r->Ek[0] - e / e0,
            fabs(r->res_b[k]), fabs(r->Pv[k]), r->Pv[k], r->dEmr[k],
            vsph_report_runs_loss_ratio(r, k));
  }
  return vsph_csv_close(f, R->dir, name);
}

/* u_theta(r) of a vortex-patch snapshot (its particles read back from the
 * VTK file), binned in rings of width R/nbins, beside the Bessel series at
 * the snapshot's time. */
static int vortex_profile(struct vsph_report *R, const char *snap,
                          const char *out, size_t nbins,
                          const struct vsph_references_vortex *ref,
                          double *t_snap) {
  struct vsph_vtk_snapshot sn;
  int rd = vsph_vtk_read(snap, &sn);
  if (rd) return rd;
  if (sn.frame_bits && !(sn.frame_fields & VSPH_VTK_FRAME_VELOCITY)) {
    vsph_vtk_snapshot_free(&sn);
    VSPH_FAIL(VSPH_EIO, "%s is a frame without the velocities", snap);
  }
  *t_snap = sn.t;
  double *sum = calloc(2 * nbins, sizeof *sum), *cnt = sum + nbins;
  if (!sum) {
    vsph_vtk_snapshot_free(&sn);
    VSPH_FAIL(VSPH_ENOMEM, "cannot bin %s", snap);
  }
  const double R0 = ref->R;
  for (size_t i = 0; i < sn.n; i++) {
    const double u = sn.vel[3 * i], v = sn.vel[3 * i + 1];
    const double px = sn.pos[3 * i], py = sn.pos[3 * i + 1], r = hypot(px, py);
    if (!(r > 0 && r < R0)) continue; /* outside, or not finite */
    const size_t b = (size_t)(r / R0 * (double)nbins);
    if (b < nbins) {
      sum[b] += (px * v - py * u) / r; /* u_theta */
      cnt[b] += 1.0;
    }
  }
  vsph_vtk_snapshot_free(&sn);
  FILE *f = vsph_csv_open(R->dir, out, "r,u_theta_sph,u_theta_ref");
  int st = f ? VSPH_OK : VSPH_EIO;
  for (size_t b = 0; b < nbins && !st; b++) {
    if (cnt[b] == 0) continue;
    const double r = (b + 0.5) * R0 / (double)nbins;
    double w;
    vsph_references_vortex_eval(ref, r, *t_snap, &w, NULL);
    fprintf(f, "%.6f,%.8e,%.8e\n", r, sum[b] / cnt[b], w * r);
  }
  free(sum);
  return st ? st : vsph_csv_close(f, R->dir, out);
}

/* The vortex patch's u_theta(r) at its snapshot times against the Bessel
 * series, for formulation f: a figure whose Markdown goes to figs. */
static int vortex_profiles(struct vsph_report *R, FILE *figs, int f,
                           const struct vsph_jobs_run *run, size_t res) {
  struct vsph_scene scene;
  int st = vsph_scene_init(&scene, &vsph_vortex_patch_type, NULL);
  if (st) return st;
  const struct vsph_scene_vortex *vp = &scene.u.vortex;
  struct vsph_references_vortex *ref = vsph_references_vortex_alloc(
      vp->R, vp->l2, vp->a, vp->omega0, vp->nu, 200);
  if (!ref) return VSPH_ELIB;
  const char *form = vsph_viscous_name(f);
  char pname[64], title[200];
  snprintf(pname, sizeof pname, "fig_vortex_profiles_%s", form);
  snprintf(title, sizeof title,
           "Vortex patch, %s: u_θ(r) at five times (points) against "
           "the Bessel series (lines)",
           form);
  struct vsph_plot pl;
  vsph_plot_init(&pl, R->dir, pname, title, "radius r (m)",
                 "azimuthal velocity u_θ (m/s)");
  for (int k = 0; k < NSNAP && !st; k++) {
    char snap[700], name[32], file[96], tp[48], ts_[48], sp[48], ss[48];
    snprintf(name, sizeof name, "snap_%04d.vtp", k);
    if ((st = vsph_jobs_store_file(&R->runs.jobs, run->dir, name, snap,
                                   sizeof snap)))
      break;
    snprintf(file, sizeof file, "profile_%s_%d.csv", form, k);
    double ts = 0.0;
    st = vortex_profile(R, snap, file, res / 2, ref, &ts);
    snprintf(tp, sizeof tp, "SPH t = %.3g s", ts);
    snprintf(ts_, sizeof ts_, "series t = %.3g s", ts);
    /* one colour per time, points and line alike */
    snprintf(sp, sizeof sp, "points pt %d ps 0.9 lc %d",
             vsph_plot_point((size_t)k), k + 1);
    snprintf(ss, sizeof ss, "lines lw 1.5 lc %d", k + 1);
    if (!st) st = vsph_plot_add(&pl, file, "1:2", tp, sp);
    if (!st) st = vsph_plot_add(&pl, file, "1:3", ts_, ss);
  }
  vsph_references_vortex_free(ref);
  if (st) return st;
  FILE *md = R->md;
  R->md = figs;
  vsph_text_set(&R->tv, "title", "%s", title);
  st = vsph_report_doc_figure_say(R, &pl, "scenes.profile_caption");
  R->md = md;
  return st;
}

/* The particles of snapshot @p snap as a CSV for a picture: x, y,
 * pressure, vorticity (z), free-surface flag. Its time into @p t. */
static int particles_csv(struct vsph_report *R, const char *snap,
                         const char *out, double *t, double box[4]) {
  struct vsph_vtk_snapshot sn;
  int st = vsph_vtk_read(snap, &sn);
  if (st) return st;
  if (sn.frame_bits && !(sn.frame_fields & VSPH_VTK_FRAME_SCALARS)) {
    vsph_vtk_snapshot_free(&sn);
    VSPH_FAIL(VSPH_EIO, "%s is a frame without the pressure and vorticity",
              snap);
  }
  *t = sn.t;
  for (size_t i = 0; i < sn.n; i++) { /* the shared frame, NaN skipped */
    box[0] = fmin(box[0], sn.pos[3 * i]);
    box[1] = fmax(box[1], sn.pos[3 * i]);
    box[2] = fmin(box[2], sn.pos[3 * i + 1]);
    box[3] = fmax(box[3], sn.pos[3 * i + 1]);
  }
  FILE *f = vsph_csv_open(R->dir, out, "x,y,pressure,vorticity,free_surface");
  if (!f) {
    vsph_vtk_snapshot_free(&sn);
    return VSPH_EIO;
  }
  for (size_t i = 0; i < sn.n; i++)
    fprintf(f, "%.6g,%.6g,%.6g,%.6g,%d\n", sn.pos[3 * i], sn.pos[3 * i + 1],
            sn.p[i], sn.vort[3 * i + 2], sn.surf[i] != 0.0);
  vsph_vtk_snapshot_free(&sn);
  return vsph_csv_close(f, R->dir, out);
}

/* Particle pictures of a scene (paper Figs. 2, 3, 6): the initial state
 * and each formulation's last state, coloured by pressure and by
 * vorticity. */
static int pictures(struct vsph_report *R, int sc, FILE *md,
                    const struct vsph_jobs_run run[NFORM]) {
  const char *scn = vsph_report_runs_ladder(&R->runs, sc, 0)->scene;
  struct vsph_plot_panel pn[NFORM + 1];
  double box[4] = {INFINITY, -INFINITY, INFINITY, -INFINITY};
  int st = VSPH_OK;
  for (int k = 0; k <= NFORM && !st; k++) {
    const int f = k ? k - 1 : 0;
    const int idx =
        k ? vsph_jobs_store_last_snapshot(&R->runs.jobs, run[f].dir) : 0;
    if (idx < 0) VSPH_FAIL(VSPH_EIO, "%s holds no snapshot", run[f].dir);
    char snap[700], name[32];
    snprintf(name, sizeof name, "snap_%04d.vtp", idx);
    if ((st = vsph_jobs_store_file(&R->runs.jobs, run[f].dir, name, snap,
                                   sizeof snap)))
      break;
    snprintf(pn[k].file, sizeof pn[k].file, "particles_%s_%s.csv", scn,
             k ? vsph_viscous_name(f) : "initial");
    double t = 0.0;
    st = particles_csv(R, snap, pn[k].file, &t, box);
    if (!k)
      snprintf(pn[k].title, sizeof pn[k].title, "t = 0 (every formulation)");
    else if (run[f].ok)
      snprintf(pn[k].title, sizeof pn[k].title, "%s, t = %.3g s",
               vsph_viscous_label(f), t);
    else
      snprintf(pn[k].title, sizeof pn[k].title,
               "%s, t = %.3g s (stopped: unstable)", vsph_viscous_label(f), t);
  }
  const double mx = 0.05 * (box[1] - box[0]), my = 0.05 * (box[3] - box[2]);
  box[0] -= mx, box[1] += mx, box[2] -= my, box[3] += my;
  static const char *const what[2] = {"pressure", "vorticity"};
  static const char *const unit[2] = {"p (Pa)", "ω (1/s)"};
  for (int w = 0; w < 2 && !st; w++) {
    char name[96], title[160];
    snprintf(name, sizeof name, "pic_%s_%s", scn, what[w]);
    snprintf(title, sizeof title, "%s: particles coloured by %s", scn, what[w]);
    double cb[4];
    st = vsph_plot_particles(R->dir, name, title, pn, NFORM + 1, w ? 4 : 3,
                             unit[w], w, box, cb);
    char scale[160];
    snprintf(scale, sizeof scale,
             "%s over every particle; %.1f %% of them lie beyond and take "
             "the end colours",
             cb[3] > 0.0 ? "± the 99th percentile of |ω|, a diverging scale"
                         : "the 1st to the 99th percentile, a sequential "
                           "scale",
             100.0 * cb[2]);
    if (!st)
      fprintf(md,
              "![%s](%s.png)\n\n*Figure: %s, one colour scale for every "
              "panel: %s from %.4g to %.4g %s (%s). "
              "Vector graphics: [%s.svg](%s.svg), [%s.pdf](%s.pdf) (this "
              "page embeds the PNG: an SVG of thousands of particles is "
              "megabytes). Data: `particles_%s_<form>.csv` (x, y, pressure, "
              "vorticity, free-surface flag), from the runs' snapshots "
              "(`runs/*/snap_*.vtp`).*\n\n",
              title, name, title, what[w], cb[0], cb[1], w ? "1/s" : "Pa",
              scale, name, name, name, name, scn);
  }
  return st;
}

/* The four figures of a scene: E_k, dE_k/dt, the decay error and the
 * budget residual, each with MGF, MEAF and PVWF. */
static int scene_figures(struct vsph_report *R, int sc, char names[NFORM][96],
                         int square) {
  const char *scn = vsph_report_runs_ladder(&R->runs, sc, 0)->scene;
  /* The standing wave's dE_k/dt is dominated by the kinetic/potential
   * exchange: its figure shows the viscous power against the rate of
   * Lighthill's phase-free envelope instead, and the energy-budget ratio
   * follows (wave and vortex patch: the scenes with a reference for t > 0
   * of their own). */
  const int wave = sc == 2;
  static const char *const what[5] = {"Ek", "dEk", "err", "residual", "loss"};
  const char *const heading[5] = {
      "kinetic energy against the reference",
      wave ? "viscous power P_{visc} against Lighthill's −4 ν k^2 E"
           : "dissipation rate dE_k/dt against the reference",
      "error of the kinetic-energy decay", "energy-budget residual",
      "energy lost over the reference's loss"};
  const char *const ylab[5] = {
      "kinetic energy E_k (J per metre of depth)",
      wave ? "P_{visc} (W per metre of depth)"
           : "dE_k/dt (W per metre of depth)",
      "E_k/E_k(0) - E_{k,ref}/E_{k,ref}(0)",
      "|d(E_k+E_p+E_c)/dt - P_{visc}| (W/m)",
      "[E(0) - E(t)]/E_k(0) over 1 - E_{m,ref}(t)/E_{m,ref}(0)"};
  const char *const cols[5] = {"1:2", wave ? "1:9" : "1:4", "1:6", "1:7",
                               "1:11"};
  const char *const refcol[5] = {"1:3", wave ? "1:10" : "1:5", NULL, NULL,
                                 NULL};
  int st = VSPH_OK;
  for (int w = 0; w < (square ? 4 : 5) && !st; w++) {
    char pname[96], title[200];
    snprintf(pname, sizeof pname, "fig_%s_%s", scn, what[w]);
    snprintf(title, sizeof title, "%s: %s", scn, heading[w]);
    struct vsph_plot pl;
    vsph_plot_init(&pl, R->dir, pname, title, "time t (s)", ylab[w]);
    pl.logy = w == 3;
    for (int f = 0; f < NFORM && !st; f++) {
      char style[96];
      snprintf(style, sizeof style, "lines lw 2 %s",
               vsph_report_runs_colour(f));
      st = vsph_plot_add(&pl, names[f], cols[w], vsph_viscous_label(f), style);
    }
    if (!st && w == 4) /* the exact ratio */
      st = vsph_plot_add(&pl, names[0], "1:(1)", "exact (1)",
                         "lines dt 2 lw 2 lc 'black'");
    if (!st && refcol[w])
      st = vsph_plot_add(
          &pl, names[0], refcol[w],
          square ? "reference (MGF extrapolated in h and h/dx)" : "reference",
          "lines dt 2 lw 2 lc 'black'");
    if (!st && w == 3) /* the viscous power, for scale */
      st = vsph_plot_add(&pl, names[0], "1:8", "|P_{visc}| (MGF), for scale",
                         "lines dt 2 lw 2 lc 'black'");
    if (st) break;
    if ((st = vsph_plot_write(&pl))) break;
    char alt[256];
    vsph_plot_plain(alt, sizeof alt, title);
    fprintf(R->md, "![%s](%s.svg)\n\n", alt, pname);
  }
  return st;
}

/* One scene: its table, the per-run data, and its figures. */
static int scene(struct vsph_report *R, int sc) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, sc, 0);
  const size_t res = L->res[VSPH_REPORT_LADDER - 1];
  const int square = sc == 1;
  struct vsph_report_richardson rr;
  int st = square ? vsph_report_runs_richardson(&R->runs, &rr) : VSPH_OK;
  if (st) return st;
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  vsph_text_set(&R->tv, "res", "%zu", res);
  vsph_text_set(&R->tv, "t_end", "%g", L->t_end);
  if ((st = vsph_report_doc_say(R, "scenes.scene_head"))) return st;
  char names[NFORM][96];
  char *figbuf = NULL;
  size_t figlen = 0;
  FILE *figs = open_memstream(&figbuf, &figlen); /* after the table */
  if (!figs) VSPH_FAIL(VSPH_ENOMEM, "cannot buffer the figures");
  struct vsph_jobs_run runs[NFORM];
  memset(runs, 0, sizeof runs);
  int nosnap = -1; /* a formulation whose run has no snapshots */
  int framed = 0;  /* a run read from a run archive's frames */
  for (int f = 0; f < NFORM && !st; f++) {
    struct vsph_jobs_spec rs = {
        L->scene, vsph_viscous_name(f), res, L->t_end, NULL, NULL};
    struct vsph_jobs_run r;
    if ((st = vsph_report_runs_get(&R->runs, &rs, &r))) break;
    snprintf(runs[f].dir, sizeof runs[f].dir, "%s", r.dir);
    runs[f].ok = r.ok;
    snprintf(names[f], sizeof names[f], "scene_%s_%s.csv", L->scene,
             vsph_viscous_name(f));
    st = write_derived(R, names[f], &r, square ? &rr : NULL);
    char status[96];
    if (r.ok)
      snprintf(status, sizeof status, "ok");
    else
      snprintf(status, sizeof status, "unstable at t = %.3g s", r.t_unstable);
    const double loss = vsph_report_runs_loss_ratio(&r, r.nrow - 1);
    char lossb[32];
    if (isfinite(loss))
      snprintf(lossb, sizeof lossb, "%.3f", loss);
    else
      snprintf(lossb, sizeof lossb, "n/a");
    fprintf(R->md, "| %s | %zu | %s | %.3e | %.4f | %s | %+.3e | %.1f |\n",
            vsph_viscous_name(f), r.n, status,
            vsph_report_runs_error(&r, square ? &rr : NULL),
            r.Ek[r.nrow - 1] / r.Ek[0], lossb, vsph_report_runs_diss0(&r),
            r.wall_s);
    /* a run read from a run archive keeps only the frames the pictures
     * and profiles read (vsph_archive_store_frames), if any */
    const int here = !strcmp(vsph_jobs_where(&R->runs.jobs, r.dir), r.dir);
    const int snaps =
        here || (vsph_jobs_store_holds(&R->runs.jobs, r.dir, "snapshots.pvd") &&
                 vsph_jobs_store_last_snapshot(&R->runs.jobs, r.dir) >= 0);
    if (!snaps) nosnap = f;
    if (!here && snaps) framed = 1;
    if (!st && sc == 0 && snaps) st = vortex_profiles(R, figs, f, &r, res);
    vsph_report_runs_free(&r);
  }
  if (!st && nosnap < 0) st = pictures(R, sc, figs, runs);
  if (!st && nosnap >= 0)
    fprintf(figs,
            "*The particle pictures%s of this scene are left out: run `%s` "
            "is read from the run archive `%s`, which keeps no "
            "frames of its snapshots.*\n\n",
            sc == 0 ? " and the u_θ(r) profiles" : "", runs[nosnap].dir,
            R->runs.archive ? R->runs.archive : "?");
  fclose(figs);
  fprintf(R->md, "\n");
  if (!st && framed && nosnap < 0)
    fprintf(R->md,
            "*The particle pictures%s below are drawn from the run archive's "
            "frames of the snapshots they read: single precision rounded to "
            "%d mantissa bits, a relative error of at most 2^-%d.*\n\n",
            sc == 0 ? " and the u_θ(r) profiles" : "", VSPH_ARCHIVE_FRAME_BITS,
            VSPH_ARCHIVE_FRAME_BITS + 1);
  fwrite(figbuf, 1, figlen, R->md);
  free(figbuf);
  if (!st) st = scene_figures(R, sc, names, square);
  vsph_text_set(&R->tv, "scene", "%s", L->scene);
  vsph_text_set(&R->tv, "res", "%zu", res);
  if (!st) st = vsph_report_doc_say(R, "scenes.scene_tail");
  if (!st && square) st = vsph_report_fv_square(R);
  return st;
}

/* The standing wave inside the paper's range of steepness (eps < 0.01,
 * where potential theory and Lighthill's decay hold; the default 0.05 lies
 * outside it): the energy budget at eps = 0.005 and 0.01 beside 0.05, at
 * the ladder's middle resolution. */
static void eps_specs(const struct vsph_report *R,
                      struct vsph_jobs_spec specs[3 * NFORM]) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 2, 0);
  static const char *const extra[3][2] = {
      {"Scene:eps=0.005", NULL}, {"Scene:eps=0.01", NULL}, {NULL, NULL}};
  static const char *const tag[3] = {"eps0.005", "eps0.01", NULL};
  for (int e = 0; e < 3; e++)
    for (int f = 0; f < NFORM; f++) {
      const struct vsph_jobs_spec s = {
          L->scene, vsph_viscous_name(f),    L->res[1],
          L->t_end, e < 2 ? extra[e] : NULL, tag[e]};
      specs[e * NFORM + f] = s;
    }
}

int vsph_report_scenes_plan(struct vsph_report *R) {
  int st = vsph_report_runs_plan_ladders(&R->runs, 0);
  if (!st && vsph_report_scene_on(&R->runs, 1)) st = vsph_report_fv_plan(R);
  if (vsph_report_scene_on(&R->runs, 2)) {
    struct vsph_jobs_spec specs[3 * NFORM];
    eps_specs(R, specs);
    for (int k = 0; k < 3 * NFORM && !st; k++)
      st = vsph_jobs_plan_run(&R->runs.jobs, &specs[k]);
  }
  return st;
}

static int wave_eps(struct vsph_report *R) {
  const struct vsph_report_ladderdef *L =
      vsph_report_runs_ladder(&R->runs, 2, 0);
  static const char *const eps[3] = {"0.005", "0.01", "0.05"};
  struct vsph_jobs_spec specs[3 * NFORM];
  eps_specs(R, specs);
  int st = VSPH_OK;
  vsph_text_set(&R->tv, "res", "%zu", L->res[1]);
  vsph_text_set(&R->tv, "t_end", "%g", L->t_end);
  if (!st) st = vsph_report_doc_say(R, "scenes.eps_head");
  for (int e = 0; e < 3 && !st; e++) {
    fprintf(R->md, "| %s |", eps[e]);
    for (int f = 0; f < NFORM && !st; f++) {
      struct vsph_jobs_run r;
      if ((st = vsph_report_runs_get(&R->runs, &specs[e * NFORM + f], &r)))
        break;
      const double loss = vsph_report_runs_loss_ratio(&r, r.nrow - 1);
      const double visc = vsph_report_runs_visc_loss_ratio(&r, r.nrow - 1);
      if (r.ok)
        fprintf(R->md, " %.3f (viscous %.3f) |", loss, visc);
      else
        fprintf(R->md, " unstable at t = %.3g s |", r.t_unstable);
      vsph_report_runs_free(&r);
    }
    fprintf(R->md, "\n");
  }
  if (!st) fprintf(R->md, "\n");
  return st;
}

int vsph_report_scenes_write(struct vsph_report *R) {
  vsph_text_set(&R->tv, "quick_note", "%s",
                R->runs.full ? "" : vsph_text_get("scenes.quick_note"));
  int st = VSPH_OK;
  struct vsph_report_richardson rr;
  if (vsph_report_scene_on(&R->runs, 1)) {
    st = vsph_report_runs_richardson(&R->runs, &rr);
    vsph_text_set(&R->tv, "ref_res",
                  "L/dx = %zu and %zu at h/dx = 2, %zu and %zu at h/dx = 3",
                  rr.res[0], rr.res[1], rr.res[2], rr.res[3]);
    vsph_text_set(&R->tv, "ref_eps", "%+.2f %% and %+.2f %%", 100 * rr.eps[0],
                  100 * rr.eps[1]);
    vsph_text_set(&R->tv, "ref_corr", "%.2f", 100 * rr.correction);
    vsph_text_set(&R->tv, "ref_d0", "%+.2f", 100 * rr.diss0);
  } else {
    vsph_text_set(&R->tv, "ref_res", "see the report with the square");
    vsph_text_set(&R->tv, "ref_eps", "n/a");
    vsph_text_set(&R->tv, "ref_corr", "n/a");
    vsph_text_set(&R->tv, "ref_d0", "n/a");
  }
  if (!st) st = vsph_report_doc_say(R, "scenes.intro");
  for (int sc = 0; sc < VSPH_REPORT_NSCENES && !st; sc++)
    if (vsph_report_scene_on(&R->runs, sc)) st = scene(R, sc);
  if (!st && vsph_report_scene_on(&R->runs, 2)) st = wave_eps(R);
  return st;
}
