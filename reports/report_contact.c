/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 11: contact (Godunov-type) SPH and its numerical viscosity
 * (Parshikov, Medin, Rublev & Dyachkov, Parshikov; docs/theory.md section 12):
 * the shear test at alpha = 0.5 with both kernels against the paper's
 * Table 1 and the lattice sums, the static-lattice limit, the velocity,
 * resolution and material dependence, fit (37) in alpha, the correcting
 * tensor (zeta) and the two-material shear against the exact solution;
 * their claims for the claims table. Each measurement is cached in
 * runs/contact-TAG (key.txt written last, as the run cache does). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/contact.h"
#include "../analysis/series.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/plot.h"
#include "../kernels/kernel.h"
#include "../runs/sheartest.h"
#include "../solver/materials.h"
#include "../solver/scene.h"
#include "report_parts.h"

/* One shear-test measurement. Lengths in m; Ly = Lz (the flow does not
 * depend on y or z, and the lattice is periodic there: any depth above
 * the kernel's reach gives the same numbers, checked by hand at 30, 40
 * and 80 nm). */
struct cspec {
  const char *tag;    /* runs/contact-TAG */
  const char *kernel; /* wendland2 or cubic */
  double alpha;       /* h = 2 alpha D0 */
  size_t res;         /* D0 = W/res */
  double W, L;        /* the paper's box, the depth Ly = Lz */
  double U0, t_end;   /* speed of each half, end time */
  const char *mat;    /* x > 0 */
  const char *left;   /* x < 0 ("same") */
  int viscous;        /* the physical viscosity */
  double zeta;        /* the correcting tensor */
  size_t nprof;       /* profile times t_end k/nprof */
};

/* the runs, by role */
enum {
  C_W,    /* lead, Wendland C2, alpha 0.5, +-500 m/s: Parshikov section 3 */
  C_B,    /* the same, cubic B-spline */
  C_WS,   /* Wendland, static lattice (U0 = 0.05 m/s) */
  C_BS,   /* B-spline, static lattice */
  C_W50,  /* Wendland at +-50 m/s */
  C_W20,  /* Wendland, D0 = 20 nm */
  C_A055, /* alpha sweep */
  C_A06,
  C_A075,
  C_A1,
  C_WATER, /* materials */
  C_AL,
  C_TU,
  C_Z0, /* lead with its viscosity, zeta = 0, 0.5, 1 */
  C_Z05,
  C_Z1,
  C_Z1L, /* zeta = 1 to 14 ns: self-similarity */
  C_BI1, /* paraffin | glycerol, zeta = 1 */
  C_BI0, /* zeta = 0 */
  C_QUICK,
  C_W5 = C_QUICK, /* FULL: D0 = 5 nm */
  NC
};

#define NM 1e-9
#define UM 1e-6
static const struct cspec CS[NC] = {
    [C_W] = {"w", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500, 4.5e-9, "lead",
             "same", 0, 0, 3},
    [C_B] = {"b", "cubic", 0.5, 80, 800 * NM, 30 * NM, 500, 4.5e-9, "lead",
             "same", 0, 0, 3},
    [C_WS] = {"w-static", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 0.05, 4.5e-9,
              "lead", "same", 0, 0, 1},
    [C_BS] = {"b-static", "cubic", 0.5, 80, 800 * NM, 30 * NM, 0.05, 4.5e-9,
              "lead", "same", 0, 0, 1},
    [C_W50] = {"w-u50", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 50, 4.5e-9,
               "lead", "same", 0, 0, 1},
    [C_W20] = {"w-d20", "wendland2", 0.5, 40, 800 * NM, 60 * NM, 500, 4.5e-9,
               "lead", "same", 0, 0, 1},
    [C_A055] = {"w-a055", "wendland2", 0.55, 80, 800 * NM, 30 * NM, 500, 4.5e-9,
                "lead", "same", 0, 0, 1},
    [C_A06] = {"w-a06", "wendland2", 0.6, 80, 800 * NM, 40 * NM, 500, 4.5e-9,
               "lead", "same", 0, 0, 1},
    [C_A075] = {"w-a075", "wendland2", 0.75, 40, 800 * NM, 80 * NM, 500, 4.5e-9,
                "lead", "same", 0, 0, 1},
    [C_A1] = {"w-a1", "wendland2", 1.0, 40, 800 * NM, 120 * NM, 500, 3e-9,
              "lead", "same", 0, 0, 1},
    [C_WATER] = {"w-water", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500,
                 4.5e-9, "water", "same", 0, 0, 1},
    [C_AL] = {"w-aluminium", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500,
              4.5e-9, "aluminium", "same", 0, 0, 1},
    [C_TU] = {"w-tungsten", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500,
              4.5e-9, "tungsten", "same", 0, 0, 1},
    [C_Z0] = {"w-visc-z0", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500, 4.5e-9,
              "lead", "same", 1, 0, 1},
    [C_Z05] = {"w-visc-z05", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500,
               4.5e-9, "lead", "same", 1, 0.5, 1},
    [C_Z1] = {"w-visc-z1", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500, 4.5e-9,
              "lead", "same", 1, 1, 1},
    [C_Z1L] = {"w-visc-z1-long", "wendland2", 0.5, 80, 800 * NM, 30 * NM, 500,
               14e-9, "lead", "same", 1, 1, 6},
    [C_BI1] = {"bimaterial-z1", "wendland2", 0.5, 60, 600 * UM, 30 * UM, 10,
               4e-6, "glycerol", "paraffin", 1, 1, 2},
    [C_BI0] = {"bimaterial-z0", "wendland2", 0.5, 60, 600 * UM, 30 * UM, 10,
               2e-6, "glycerol", "paraffin", 1, 0, 1},
    [C_W5] = {"w-d5", "wendland2", 0.5, 160, 800 * NM, 30 * NM, 500, 4.5e-9,
              "lead", "same", 0, 0, 1},
};
#undef NM
#undef UM

/* The settings of a spec, "Section:key=value" each. */
static size_t settings(const struct cspec *c, char set[][96], size_t cap) {
  size_t n = 0;
#define ADD(...) \
  if (n < cap) snprintf(set[n++], 96, __VA_ARGS__)
  ADD("Solver:scheme=contact");
  ADD("Solver:kernel=%s", c->kernel);
  ADD("Solver:alpha=%.17g", c->alpha);
  ADD("Solver:res=%zu", c->res);
  ADD("Solver:zeta_num=%.17g", c->zeta);
  ADD("Scene:W=%.17g", c->W);
  ADD("Scene:Ly=%.17g", c->L);
  ADD("Scene:Lz=%.17g", c->L);
  ADD("Scene:U0=%.17g", c->U0);
  ADD("Scene:t_end=%.17g", c->t_end);
  ADD("Scene:material=%s", c->mat);
  ADD("Scene:left=%s", c->left);
  ADD("Scene:viscous=%d", c->viscous);
#undef ADD
  return n;
}

/* The job of measurement @p c: `vsph contact --out runs/contact-TAG`. */
static int cjob(const struct vsph_report *R, const struct cspec *c,
                struct vsph_jobs_job *j) {
  char set[16][96];
  const size_t n = settings(c, set, 16);
  return vsph_jobs_shear(&R->runs.jobs, c->tag, (const char(*)[96])set, n,
                         c->nprof, j);
}

/* All measurements, read back from the cache. */
struct cres {
  struct vsph_contact_shear r[NC];
  int nc; /* how many (quick: C_QUICK) */
};

static int cload(struct vsph_report *R, struct cres *cr) {
  cr->nc = R->runs.full ? NC : C_QUICK;
  int st = VSPH_OK;
  for (int k = 0; k < cr->nc && !st; k++) {
    struct vsph_jobs_job j;
    st = cjob(R, &CS[k], &j);
    if (!st) st = vsph_jobs_ready(&R->runs.jobs, &j);
    char path[700];
    if (!st)
      st = vsph_jobs_store_file(&R->runs.jobs, j.dir, "summary.csv", path,
                                sizeof path);
    vsph_jobs_free(&j);
    if (!st && vsph_sheartest_csv_load(path, &cr->r[k]))
      VSPH_FAIL(VSPH_EIO, "cannot read %s", path);
  }
  return st;
}

/* eta_num/(Z D0) of a measurement: the control surface's fit (the
 * paper's metric) at its last profile time; NaN if it stopped early. */
static double coef(const struct vsph_contact_shear *r) {
  if (!r->nt || !r->stable) return NAN;
  return r->nu_dy[r->nt - 1] / (r->c0 * r->D0);
}
static double coef_u(const struct vsph_contact_shear *r) {
  if (!r->nt || !r->stable) return NAN;
  return r->nu_u[r->nt - 1] / (r->c0 * r->D0);
}

static const struct vsph_material *mat(const char *name) {
  const struct vsph_material *m = NULL;
  vsph_materials_resolve(name, &m);
  return m;
}

/* The two-material profile's contact velocity fitted to the run's
 * profiles.csv (vsph_contact_bimaterial_fit), and the exact profile's
 * misfit; NaN where the table cannot be read. */
static double bimat_fit(const char *profiles, double t, double U0, double nuL,
                        double nuR, double W, double *rms_exact, double etaL,
                        double rhoL, double etaR, double rhoR) {
  struct vsph_csv *c = vsph_csv_read(profiles);
  *rms_exact = (double)NAN;
  if (!c) return (double)NAN;
  const double *tt = vsph_csv_column(c, "t"), *x = vsph_csv_column(c, "x"),
               *u = vsph_csv_column(c, "u");
  const double f = tt && x && u ? vsph_contact_bimaterial_fit(
                                      tt, x, u, c->nrow, t, U0, nuL, nuR, W,
                                      etaL, rhoL, etaR, rhoR, rms_exact)
                                : (double)NAN;
  vsph_csv_free(c);
  return f;
}

/* the numbers the tables, figures and claims share */
struct cnum {
  double klat_w, klat_b, flat_w, fit05;
  double paper_w, paper_b;        /* Table 1's means over 18 rows */
  double lead_w, lead_b;          /* Table 1's lead row */
  double eta_eff[3], eta_want[3]; /* zeta 0, 0.5, 1: mPa s */
  double ustar[2][2], rms[2][2];  /* bimaterial: [zeta 1, 0][t] */
  double ustar_exact[2];          /* (27): physical eta; eta + eta_num */
  double ss_spread[2];            /* self-similarity: nu spread (%) */
  double ss_lean[2]; /* its ratio's place, in logarithm, from 1 (the
                        paper's law) to the profile times' ratio (a layer
                        that does not spread as sqrt(t)) */
};

static void numbers(const struct cres *cr, const struct vsph_jobs *J,
                    struct cnum *nb) {
  const struct vsph_kernel_type *w = vsph_kernel_find("wendland2"),
                                *b = vsph_kernel_find("cubic");
  nb->klat_w = vsph_contact_lattice_coef(w, 3, 0.5);
  nb->klat_b = vsph_contact_lattice_coef(b, 3, 0.5);
  nb->flat_w = vsph_contact_lattice_visc_factor(w, 3, 0.5);
  nb->fit05 = vsph_materials_eta_num_fit(0.5);
  nb->paper_w = 0.0894;
  nb->paper_b = 0.1078;
  const struct vsph_material *lead = mat("lead");
  const double zd = lead->rho0 * lead->c0 * VSPH_MATERIALS_D0;
  nb->lead_w = lead->eta_num_w / zd;
  nb->lead_b = lead->eta_num_b / zd;
  /* the correcting tensor: the measured eta of each zeta against the
   * dynamic numerical viscosity (C_W) plus f_lat (eta - zeta eta_num) */
  const int Z[3] = {C_Z0, C_Z05, C_Z1};
  const double zeta[3] = {0, 0.5, 1};
  for (int k = 0; k < 3; k++) {
    const struct vsph_contact_shear *r = &cr->r[Z[k]];
    nb->eta_eff[k] =
        r->nt && r->stable ? 1e3 * r->nu_dy[r->nt - 1] * r->rho0 : (double)NAN;
    nb->eta_want[k] =
        1e3 * vsph_contact_eta_model(coef(&cr->r[C_W]), r->rho0, r->c0, r->D0,
                                     nb->flat_w, lead->eta, zeta[k], nb->fit05);
  }
  /* self-similarity: the spread of nu over the profile times */
  const int S[2] = {C_W, C_Z1L};
  for (int k = 0; k < 2; k++)
    vsph_contact_self_similar(&cr->r[S[k]], &nb->ss_spread[k], &nb->ss_lean[k]);
  /* two materials: paraffin (x < 0, -U0) | glycerol (x > 0, +U0) */
  const struct vsph_material *pa = mat("paraffin"), *gl = mat("glycerol");
  for (int z = 0; z < 2; z++) {
    const int k = z ? C_BI0 : C_BI1;
    const struct vsph_contact_shear *r = &cr->r[k];
    const double D0 = r->D0 > 0 ? r->D0 : 1e-5;
    /* the viscosity each side carries: physical at zeta = 1, physical +
     * the numerical one (37) at zeta = 0 */
    const double eL = pa->eta + (z ? nb->fit05 * pa->rho0 * pa->c0 * D0 : 0),
                 eR = gl->eta + (z ? nb->fit05 * gl->rho0 * gl->c0 * D0 : 0);
    vsph_contact_bimaterial_u(1.0, 1.0, -1.0, eL, pa->rho0, 1.0, eR, gl->rho0,
                              &nb->ustar_exact[z]);
    char run[700], path[700] = "";
    snprintf(run, sizeof run, "%s/runs/contact-%s", J->dir, CS[k].tag);
    if (vsph_jobs_store_file(J, run, "profiles.csv", path, sizeof path))
      path[0] = '\0'; /* (reported) no fit */
    for (int q = 0; q < 2; q++) {
      nb->ustar[z][q] = nb->rms[z][q] = NAN;
      if (q >= (int)r->nt) continue;
      nb->ustar[z][q] =
          bimat_fit(path, r->t[q], r->U0, eL / pa->rho0, eR / gl->rho0, r->W,
                    &nb->rms[z][q], eL, pa->rho0, eR, gl->rho0);
    }
  }
}

/* ---------------------------------------------- cylinders (Parshikov §5.5) */

/* Glycerol, d = 1 mm, d/S = 0.5, Re = 0.005 (Parshikov Table 2's second case),
 * 2-D: uncorrected at 20 and 30 particles per diameter, corrected
 * (zeta = 1, eta_num the 2-D static lattice's, set by cyl_spec) at 20;
 * FULL adds 40 per diameter uncorrected. End times: about five e-folds of
 * the slowest mode, S^2/(4 pi^2 nu), for each run's viscosity. */
#define CYL_COMMON \
  "Solver:kernel=wendland2", "Solver:alpha=0.5", "Solver:outputs=50"
/* (the corrected runs, zeta > 0, take eta_num too: cyl_specs appends it) */
static const char *const CYL_Z0[] = {CYL_COMMON, NULL};
static const char *const CYL_Z1[] = {CYL_COMMON, "Solver:zeta_num=1", NULL};
static const char *const CYL_Z05[] = {CYL_COMMON, "Solver:zeta_num=0.5", NULL};
#define CYL_PARA "Scene:material=paraffin", "Scene:d=1e-4"
static const char *const CYL_P0[] = {CYL_COMMON, CYL_PARA, NULL};
static const char *const CYL_P1[] = {CYL_COMMON, CYL_PARA, "Solver:zeta_num=1",
                                     NULL};
#define CYL_03 "Scene:dS=0.3"
static const char *const CYL_G03[] = {CYL_COMMON, CYL_03, NULL};
enum {
  CY_Z0_40,
  CY_Z0_60,
  CY_Z05_40,
  CY_Z1_40,
  CY_P0_40,
  CY_P1_40,
  CY_QUICK,
  CY_Z0_80 = CY_QUICK,
  CY_G03_67,
  NCY
};
static const struct {
  size_t res;
  double t_end;
  const char *const *set;
  const char *tag;
  double zeta;
  const char *fluid; /* the table's label */
  double paper;      /* Parshikov Table 2: C_D^SPH / C_D,M as printed */
} CY[NCY] = {[CY_Z0_40] = {40, 1e-4, CYL_Z0, "z0", 0},
             [CY_Z0_60] = {60, 1.5e-4, CYL_Z0, "z0", 0},
             [CY_Z05_40] = {40, 2e-4, CYL_Z05, "z05", 0.5},
             [CY_P0_40] = {40, 1.5e-5, CYL_P0, "paraffin-z0", 0},
             [CY_P1_40] = {40, 6e-5, CYL_P1, "paraffin-z1", 1},
             [CY_G03_67] = {67, 4e-4, CYL_G03, "dS03-z0", 0},
             [CY_Z1_40] = {40, 5e-4, CYL_Z1, "z1", 1},
             [CY_Z0_80] = {80, 2e-4, CYL_Z0, "z0", 0}};

/* Which fluid and d/S each run has, and the paper's ratio beside it. */
static void cyl_case(int k, const char **fluid, double *dS, double *paper) {
  const int para = k == CY_P0_40 || k == CY_P1_40, s03 = k == CY_G03_67;
  *fluid = para ? "paraffin" : "glycerol";
  *dS = s03 ? 0.3 : 0.5;
  /* C_D^SPH/C_D,M of Parshikov's Table 2 as printed (its C_D,M: 20200, 8000) */
  static const double P[2][2] = {{68700.0 / 20200, 26900.0 / 20200},
                                 {50600.0 / 20200, 22800.0 / 20200}};
  *paper = s03 ? (CY[k].zeta > 0 ? 10500.0 / 8000 : 25900.0 / 8000)
           : CY[k].zeta == 0 || CY[k].zeta == 1 ? P[para][CY[k].zeta > 0]
                                                : (double)NAN;
}

struct cyl {
  int n;
  double ratio[NCY]; /* (F/(eta U))_SPH / eq. (39)'s */
  double drift[NCY]; /* relative change of U over the last tenth */
  double U[NCY];     /* superficial velocity (m/s) */
  int ok[NCY];
  double wall[NCY];
  double k2; /* the 2-D static lattice's eta_num/(Z D0) */
};

/* The runs' settings with eta_num the 2-D static lattice's: the caller
 * keeps them while it uses the specs that point into them. */
struct cyl_sets {
  char eta_num[64]; /* "Solver:eta_num=<the 2-D lattice sum>" */
  const char *set[NCY][8];
};

/* The cylinder runs (their number is returned) into @p rs, their
 * settings into @p cs: each run's of CY, then (zeta > 0) eta_num, the 2-D
 * static lattice's (@p k2). */
static int cyl_specs(const struct vsph_report *R, struct cyl_sets *cs,
                     struct vsph_jobs_spec rs[NCY], double *k2) {
  const struct vsph_kernel_type *w = vsph_kernel_find("wendland2");
  *k2 = vsph_contact_lattice_coef(w, 2, 0.5);
  snprintf(cs->eta_num, sizeof cs->eta_num, "Solver:eta_num=%.6f", *k2);
  const int n = R->runs.full ? NCY : CY_QUICK;
  for (int k = 0; k < n; k++) {
    size_t q = 0;
    for (; CY[k].set[q]; q++) cs->set[k][q] = CY[k].set[q];
    if (CY[k].zeta > 0) cs->set[k][q++] = cs->eta_num;
    cs->set[k][q] = NULL;
    rs[k] = (struct vsph_jobs_spec){"cylinders", "contact",  CY[k].res,
                                    CY[k].t_end, cs->set[k], CY[k].tag};
  }
  return n;
}

int vsph_report_contact_plan(struct vsph_report *R) {
  int st = VSPH_OK;
  for (int k = 0; k < (R->runs.full ? NC : C_QUICK) && !st; k++) {
    struct vsph_jobs_job j;
    if ((st = cjob(R, &CS[k], &j))) {
      vsph_jobs_free(&j);
      break;
    }
    st = vsph_jobs_plan_add(&R->runs.jobs, &j);
  }
  struct vsph_jobs_spec rs[NCY];
  double k2;
  struct cyl_sets cs;
  const int n = cyl_specs(R, &cs, rs, &k2);
  for (int k = 0; k < n && !st; k++)
    st = vsph_jobs_plan_run(&R->runs.jobs, &rs[k]);
  return st;
}

static int cyl_load(struct vsph_report *R, struct cyl *cy) {
  struct vsph_jobs_spec rs[NCY];
  struct cyl_sets cs;
  cy->n = cyl_specs(R, &cs, rs, &cy->k2);
  int st = VSPH_OK;
  for (int k = 0; k < cy->n && !st; k++) {
    /* the scene's derived values for the run's Scene: settings */
    struct vsph_params *prm = vsph_params_alloc();
    if (!prm) return VSPH_ENOMEM;
    for (size_t q = 0; CY[k].set[q] && !st; q++)
      if (!strncmp(CY[k].set[q], "Scene:", 6))
        st = vsph_params_assign(prm, CY[k].set[q]);
    struct vsph_scene sc;
    if (!st) st = vsph_scene_init(&sc, &vsph_cylinders_type, prm);
    vsph_params_free(prm);
    if (st) break;
    struct vsph_jobs_run r;
    if ((st = vsph_report_runs_get(&R->runs, &rs[k], &r))) break;
    const double *px = vsph_csv_column(r.energy, "Px");
    /* F/(eta U) against eq. (39)'s: the drive is eq. (39)'s at U_target */
    cy->ratio[k] =
        vsph_contact_drag_ratio(px, px ? r.nrow : 0, sc.rho0, sc.u.cyl.S,
                                sc.u.cyl.U, &cy->U[k], &cy->drift[k]);
    cy->ok[k] = r.ok;
    cy->wall[k] = r.wall_s;
    vsph_report_runs_free(&r);
  }
  return st;
}

/* The exact profiles the figures draw beside the runs' (x in nm or um,
 * u/U0): lead at 4.5 ns with the physical viscosity and with the
 * measured numerical one; the two materials at their profile times. */
static int exact_csv(struct vsph_report *R, const struct cres *cr,
                     const struct cnum *nb) {
  char *buf = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&buf, &len);
  if (!f) VSPH_FAIL(VSPH_ENOMEM, "cannot build contact_exact.csv");
  const struct vsph_material *lead = mat("lead"), *pa = mat("paraffin"),
                             *gl = mat("glycerol");
  const struct vsph_contact_shear *w = &cr->r[C_W], *bi = &cr->r[C_BI1];
  const double nu_num = coef(w) * w->c0 * w->D0;
  fprintf(f, "x_nm,u_phys,u_num,x_um,bi_t1,bi_t2\n");
  for (int k = 0; k <= 400; k++) {
    const double x = -400e-9 + 2e-9 * k, xb = -300e-6 + 1.5e-6 * k;
    const double t = 4.5e-9;
    fprintf(
        f, "%.6g,%.9g,%.9g,%.6g,%.9g,%.9g\n", x * 1e9,
        vsph_contact_shear_u(x, t, lead->eta / lead->rho0, 1.0, 800e-9),
        vsph_contact_shear_u(x, t, nu_num, 1.0, 800e-9), xb * 1e6,
        vsph_contact_bimaterial_u(xb, bi->nt > 0 ? bi->t[0] : 2e-6, -1, pa->eta,
                                  pa->rho0, 1, gl->eta, gl->rho0, NULL),
        vsph_contact_bimaterial_u(xb, bi->nt > 1 ? bi->t[1] : 4e-6, -1, pa->eta,
                                  pa->rho0, 1, gl->eta, gl->rho0, NULL));
  }
  (void)nb;
  if (fclose(f) || !buf) {
    free(buf);
    VSPH_FAIL(VSPH_ENOMEM, "cannot build contact_exact.csv");
  }
  const int st = vsph_files_write(R->dir, "contact_exact.csv", buf);
  free(buf);
  return st;
}

/* alpha, measured, fit (37), lattice sum: the figure's data. */
static int alpha_csv(struct vsph_report *R, const struct cres *cr) {
  static const int A[5] = {C_W, C_A055, C_A06, C_A075, C_A1};
  const struct vsph_kernel_type *w = vsph_kernel_find("wendland2");
  char buf[2048];
  int n = snprintf(buf, sizeof buf, "alpha,measured,fit37,lattice\n");
  for (int k = 0; k < 5; k++)
    n += snprintf(buf + n, sizeof buf - (size_t)n, "%g,%.6g,%.6g,%.6g\n",
                  CS[A[k]].alpha, coef(&cr->r[A[k]]),
                  vsph_materials_eta_num_fit(CS[A[k]].alpha),
                  vsph_contact_lattice_coef(w, 3, CS[A[k]].alpha));
  return vsph_files_write(R->dir, "contact_alpha.csv", buf);
}

/* Shear test @p tag's profiles.csv as gnuplot sees it from the report
 * folder (the test's folder, or its run archive's entry). */
static void profiles_file(const struct vsph_report *R, const char *tag,
                          char *buf, size_t len) {
  char run[700];
  snprintf(run, sizeof run, "%s/runs/contact-%s", R->runs.jobs.dir, tag);
  vsph_jobs_store_data_path(&R->runs.jobs, run, "profiles.csv", buf, len);
}

static int figures(struct vsph_report *R, const struct cres *cr) {
  struct vsph_plot pl;
  char file[300], using[200], label[128], style[96];
  /* Parshikov Fig. 6a: lead at 4.5 ns for each zeta, the exact profiles */
  vsph_plot_init(&pl, R->dir, "fig_contact_zeta",
                 "Lead shear layer at t = 4.5 ns: the correcting tensor",
                 "x (nm)", "u_y / U_0 (dimensionless)");
  static const int Z[3] = {C_Z0, C_Z05, C_Z1};
  int st = VSPH_OK;
  for (int k = 0; k < 3 && !st; k++) {
    profiles_file(R, CS[Z[k]].tag, file, sizeof file);
    snprintf(using, sizeof using, "(abs($2)<%g ? $2*1e9 : 1/0):($3/%g)",
             0.5 * CS[Z[k]].W, CS[Z[k]].U0);
    snprintf(label, sizeof label, "SPH, ζ = %g", CS[Z[k]].zeta);
    snprintf(style, sizeof style, "points pt %d ps 0.6 lc %d",
             vsph_plot_point((size_t)k), k + 1);
    st = vsph_plot_add(&pl, file, using, label, style);
  }
  if (!st)
    st = vsph_plot_add(&pl, "contact_exact.csv", "1:2",
                       "exact, η = 2.3 mPa s (physical)", "lines lw 2");
  if (!st)
    st = vsph_plot_add(&pl, "contact_exact.csv", "1:3",
                       "exact, the measured numerical η", "lines lw 2 dt 2");
  if (!st) st = vsph_report_doc_figure_say(R, &pl, "contact.fig_zeta");
  if (st) return st;
  /* Parshikov Fig. 6b: zeta = 1, self-similar in xi = x sqrt(t0/t) */
  vsph_plot_init(&pl, R->dir, "fig_contact_selfsim",
                 "Lead, ζ = 1: profiles against ξ = x (t_0/t)^{1/2}, "
                 "t_0 = 7 ns",
                 "ξ (nm)", "u_y / U_0 (dimensionless)");
  const struct vsph_contact_shear *L = &cr->r[C_Z1L];
  for (size_t q = 0; q < L->nt && !st; q++) {
    profiles_file(R, CS[C_Z1L].tag, file, sizeof file);
    snprintf(using, sizeof using,
             "(abs($1-%.9g)<%.3g && abs($2)<%g ? $2*1e9*sqrt(7e-9/$1) : "
             "1/0):($3/%g)",
             L->t[q], 1e-3 * L->t[q], 0.5 * CS[C_Z1L].W, CS[C_Z1L].U0);
    snprintf(label, sizeof label, "t = %.3g ns", 1e9 * L->t[q]);
    snprintf(style, sizeof style, "linespoints pt %d ps 0.5 lc %zu",
             vsph_plot_point(q), q + 1);
    st = vsph_plot_add(&pl, file, using, label, style);
  }
  if (!st) st = vsph_report_doc_figure_say(R, &pl, "contact.fig_selfsim");
  if (st) return st;
  /* Parshikov Fig. 4 / eq. (37): the coefficient against alpha */
  vsph_plot_init(&pl, R->dir, "fig_contact_alpha",
                 "Numerical viscosity of contact SPH against α (Wendland "
                 "C^2, lead)",
                 "α (dimensionless)", "η_{num} / (Z D_0) (dimensionless)");
  st = vsph_plot_add(&pl, "contact_alpha.csv", "1:2",
                     "measured (control surface, ±500 m/s)",
                     "linespoints pt 7 lw 2");
  if (!st)
    st = vsph_plot_add(&pl, "contact_alpha.csv", "1:3", "Parshikov fit (37)",
                       "lines lw 2 dt 2");
  if (!st)
    st = vsph_plot_add(&pl, "contact_alpha.csv", "1:4", "lattice sum (static)",
                       "linespoints pt 6 dt 3");
  if (!st) st = vsph_report_doc_figure_say(R, &pl, "contact.fig_alpha");
  if (st) return st;
  /* Parshikov Fig. 7: paraffin | glycerol */
  vsph_plot_init(&pl, R->dir, "fig_contact_bimaterial",
                 "Paraffin (x < 0) | glycerol (x > 0), ζ = 1", "x (μm)",
                 "u_y / U_0 (dimensionless)");
  const struct vsph_contact_shear *B = &cr->r[C_BI1];
  for (size_t q = 0; q < B->nt && q < 2 && !st; q++) {
    profiles_file(R, CS[C_BI1].tag, file, sizeof file);
    snprintf(using, sizeof using,
             "(abs($1-%.9g)<%.3g && abs($2)<3e-4 ? $2*1e6 : 1/0):($3/%g)",
             B->t[q], 1e-3 * B->t[q], CS[C_BI1].U0);
    snprintf(label, sizeof label, "SPH, t = %.3g μs", 1e6 * B->t[q]);
    /* one colour per time: the SPH points and the exact line */
    snprintf(style, sizeof style, "points pt %d ps 0.8 lc %zu",
             vsph_plot_point(q), q + 1);
    st = vsph_plot_add(&pl, file, using, label, style);
    snprintf(using, sizeof using, "4:%zu", 5 + q);
    snprintf(label, sizeof label, "exact (eq. 27), t = %.3g μs", 1e6 * B->t[q]);
    snprintf(style, sizeof style, "lines lw 2 lc %zu", q + 1);
    if (!st) st = vsph_plot_add(&pl, "contact_exact.csv", using, label, style);
  }
  if (!st) st = vsph_report_doc_figure_say(R, &pl, "contact.fig_bimaterial");
  return st;
}

/* The table of alpha = 0.5 with both kernels, beside Parshikov's Table 1. */
static void alpha05_rows(FILE *md, const struct cres *cr,
                         const struct cnum *nb) {
  fprintf(md,
          "| kernel | Parshikov Table 1, lead | Parshikov, 18 materials | "
          "lattice sum | "
          "measured, static lattice | measured, +-50 m/s | measured, +-500 "
          "m/s | the same, u_y fit |\n"
          "|:---|---:|---:|---:|---:|---:|---:|---:|\n");
  fprintf(md,
          "| Wendland C2 | %.4f | %.4f +- 0.002 | %.4f | %.4f | %.4f | %.4f | "
          "%.4f |\n",
          nb->lead_w, nb->paper_w, nb->klat_w, coef(&cr->r[C_WS]),
          coef(&cr->r[C_W50]), coef(&cr->r[C_W]), coef_u(&cr->r[C_W]));
  fprintf(md,
          "| cubic B-spline | %.4f | %.4f +- 0.001 | %.4f | %.4f | | %.4f | "
          "%.4f |\n\n",
          nb->lead_b, nb->paper_b, nb->klat_b, coef(&cr->r[C_BS]),
          coef(&cr->r[C_B]), coef_u(&cr->r[C_B]));
}

/* The table of the materials. */
static void materials_rows(FILE *md, const struct cres *cr) {
  fprintf(md,
          "| material | Z (MPa s/m) | Parshikov eta_num (mPa s) | measured "
          "(mPa s) | measured/Parshikov | measured / (Z D0) |\n"
          "|:---|---:|---:|---:|---:|---:|\n");
  static const int MAT[4] = {C_WATER, C_AL, C_TU, C_W};
  for (int k = 0; k < 4; k++) {
    const struct vsph_material *m = mat(CS[MAT[k]].mat);
    const struct vsph_contact_shear *r = &cr->r[MAT[k]];
    const double eta =
        r->nt ? 1e3 * r->nu_dy[r->nt - 1] * r->rho0 : (double)NAN;
    fprintf(md, "| %s | %.2f | %.3f | %.3f | %.3f | %.4f |\n", m->label,
            1e-6 * m->rho0 * m->c0, 1e3 * m->eta_num_w, eta,
            eta / (1e3 * m->eta_num_w), coef(r));
  }
  fprintf(md, "\n");
}

/* The table of alpha against the fit (37) and the lattice sum. */
static void alpha_rows(FILE *md, const struct cres *cr) {
  fprintf(md,
          "| alpha | D0 (nm) | measured | Parshikov fit (37) | measured/fit | "
          "lattice sum |\n|---:|---:|---:|---:|---:|---:|\n");
  static const int A[5] = {C_W, C_A055, C_A06, C_A075, C_A1};
  const struct vsph_kernel_type *wk = vsph_kernel_find("wendland2");
  for (int k = 0; k < 5; k++) {
    const double f = vsph_materials_eta_num_fit(CS[A[k]].alpha);
    fprintf(md, "| %g | %.0f | %.4f | %.4f | %.3f | %.4f |\n", CS[A[k]].alpha,
            1e9 * cr->r[A[k]].D0, coef(&cr->r[A[k]]), f, coef(&cr->r[A[k]]) / f,
            vsph_contact_lattice_coef(wk, 3, CS[A[k]].alpha));
  }
  fprintf(md, "\n");
}

/* The table of the correcting tensor. */
static void zeta_rows(FILE *md, const struct cnum *nb) {
  fprintf(md,
          "| zeta | measured eta_eff (mPa s) | Parshikov's expectation 2.3 + "
          "(1 - zeta) 19.2 | ours: measured eta_num + f_lat (eta - zeta "
          "eta_num^(37)) |\n|---:|---:|---:|---:|\n");
  for (int k = 0; k < 3; k++) {
    const double zeta = 0.5 * k;
    fprintf(md, "| %g | %.2f | %.1f | %.2f |\n", zeta, nb->eta_eff[k],
            2.3 + (1.0 - zeta) * 19.2, nb->eta_want[k]);
  }
  fprintf(md, "\n");
}

/* The table of two materials. */
static void bimat_rows(FILE *md, const struct cres *cr, const struct cnum *nb) {
  fprintf(md,
          "| run | t (us) | U*/U0 fitted | U*/U0 by eq. (27) | RMS of the "
          "exact profile / U0 |\n|:---|---:|---:|---:|---:|\n");
  for (int z = 0; z < 2; z++)
    for (int q = 0; q < 2; q++) {
      const struct vsph_contact_shear *r = &cr->r[z ? C_BI0 : C_BI1];
      if (q >= (int)r->nt) continue;
      fprintf(md, "| %s | %.1f | %.3f | %.3f | %.3f |\n",
              z ? "zeta = 0 (exact with eta + eta_num)"
                : "zeta = 1 (exact with the physical eta)",
              1e6 * r->t[q], nb->ustar[z][q], nb->ustar_exact[z],
              nb->rms[z][q]);
    }
  fprintf(md, "\n");
}

/* The table of the cylinder arrays. */
static void cyl_rows(FILE *md, const struct cyl *cy) {
  fprintf(md,
          "| fluid | d/S | particles per diameter | zeta | U/U_(39) | "
          "(F/(eta U)) / eq. (39)'s | change of U over the last tenth | "
          "Parshikov Table 2, C_D/C_D,M | run time (s) |\n"
          "|:---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int k = 0; k < cy->n; k++) {
    const char *fluid;
    double dS, paper;
    cyl_case(k, &fluid, &dS, &paper);
    char pp[32] = "";
    if (paper == paper) snprintf(pp, sizeof pp, "%.2f", paper);
    fprintf(md,
            "| %s | %g | %.0f | %g | %.3f | %.2f | %+.2f %% | %s | %.0f |\n",
            fluid, dS, CY[k].res * dS, CY[k].zeta, 1.0 / cy->ratio[k],
            cy->ratio[k], 100 * cy->drift[k], pp, cy->wall[k]);
  }
  fprintf(md, "\n");
}

/* The measurements and the numbers the part's tables and claims share. */
static int contact_load(struct vsph_report *R, struct cres *cr,
                        struct cnum *nb) {
  memset(cr, 0, sizeof *cr);
  const int st = cload(R, cr);
  if (!st) numbers(cr, &R->runs.jobs, nb);
  return st;
}

int vsph_report_contact_write(struct vsph_report *R) {
  struct cres cr;
  struct cnum nb;
  int st = contact_load(R, &cr, &nb);
  if (st) return st;
  struct vsph_text_vars *tv = &R->tv;
  if ((st = vsph_report_doc_say(R, "contact.intro"))) return st;
  /* Table: alpha = 0.5, both kernels */
  FILE *md = R->md;
  alpha05_rows(md, &cr, &nb);
  vsph_text_set(tv, "bw", "%.3f", coef(&cr.r[C_B]) / coef(&cr.r[C_W]));
  vsph_text_set(tv, "d20", "%.4f", coef(&cr.r[C_W20]));
  vsph_text_set(tv, "d10", "%.4f", coef(&cr.r[C_W]));
  vsph_text_set(tv, "wall", "%.1f", cr.r[C_W].wall_s);
  vsph_text_set(tv, "n", "%zu", cr.r[C_W].n);
  if ((st = vsph_report_doc_say(R, "contact.table_alpha05"))) return st;
  /* materials */
  materials_rows(md, &cr);
  if ((st = vsph_report_doc_say(R, "contact.table_materials"))) return st;
  /* alpha */
  if ((st = alpha_csv(R, &cr))) return st;
  alpha_rows(md, &cr);
  vsph_text_set(tv, "flat", "%.4f", nb.flat_w);
  if ((st = vsph_report_doc_say(R, "contact.table_fit"))) return st;
  if ((st = exact_csv(R, &cr, &nb))) return st;
  /* the correcting tensor */
  zeta_rows(md, &nb);
  vsph_text_set(tv, "ss0", "%.1f", nb.ss_spread[0]);
  vsph_text_set(tv, "ss1", "%.1f", nb.ss_spread[1]);
  if ((st = vsph_report_doc_say(R, "contact.table_zeta"))) return st;
  /* two materials */
  bimat_rows(md, &cr, &nb);
  if ((st = vsph_report_doc_say(R, "contact.table_bimaterial"))) return st;
  /* cylinders */
  struct cyl cy;
  memset(&cy, 0, sizeof cy);
  if ((st = cyl_load(R, &cy))) return st;
  vsph_text_set(tv, "k2", "%.4f", cy.k2);
  vsph_text_set(tv, "k39", "%.2f", vsph_materials_drag_row(0.5));
  vsph_text_set(tv, "ksa", "%.2f", vsph_materials_drag_square(0.5));
  if ((st = vsph_report_doc_say(R, "contact.cyl_head"))) return st;
  cyl_rows(md, &cy);
  vsph_text_set(tv, "lin", "%.1f",
                100 *
                    (cy.ratio[CY_Z05_40] -
                     0.5 * (cy.ratio[CY_Z0_40] + cy.ratio[CY_Z1_40])) /
                    (cy.ratio[CY_Z0_40] - cy.ratio[CY_Z1_40]));
  if ((st = vsph_report_doc_say(R, "contact.cyl_tail"))) return st;
  if ((st = figures(R, &cr))) return st;
  /* cost */
  double wall = 0;
  for (int k = 0; k < cr.nc; k++) wall += cr.r[k].wall_s;
  vsph_text_set(tv, "wall_all", "%.0f", wall);
  vsph_text_set(tv, "nruns", "%d", cr.nc);
  return vsph_report_doc_say(R, "contact.tail");
}

/* The shear test: the numerical viscosity, its independence of speed, material
 * and resolution, the fit (37) and self-similarity (Parshikov §3). */
static int shear_claims(struct vsph_report *R, const struct cres *cr,
                        const struct cnum *nb, struct vsph_claim_vals *v) {
  const double w = coef(&cr->r[C_W]), b = coef(&cr->r[C_B]);
  vsph_claim_clear(v);
  vsph_claim_num(v, "w", w);
  vsph_claim_num(v, "b", b);
  vsph_claim_num(v, "paper_w", nb->paper_w);
  vsph_claim_num(v, "paper_b", nb->paper_b);
  vsph_claim_num(v, "lead_w", nb->lead_w);
  vsph_claim_num(v, "lead_b", nb->lead_b);
  vsph_claim_num(v, "ws", coef(&cr->r[C_WS]));
  vsph_claim_num(v, "bs", coef(&cr->r[C_BS]));
  vsph_claim_num(v, "klw", nb->klat_w);
  vsph_claim_num(v, "klb", nb->klat_b);
  int st = vsph_report_doc_grade(R, "claims/contact.eta_num", v);
  /* each material's eta_num/(Z D0) and Z_lead/Z, where eta_num
   * independent of Z would put it; the runs at 50 m/s and at 20 nm */
  static const struct {
    int run;
    const char *w, *zr;
  } MAT[3] = {{C_WATER, "w_water", "zr_water"},
              {C_AL, "w_al", "zr_al"},
              {C_TU, "w_tu", "zr_tu"}};
  const double z_lead = cr->r[C_W].rho0 * cr->r[C_W].c0;
  vsph_claim_clear(v);
  vsph_claim_num(v, "w", w);
  for (int k = 0; k < 3; k++) {
    const struct vsph_contact_shear *r = &cr->r[MAT[k].run];
    vsph_claim_num(v, MAT[k].w, coef(r));
    vsph_claim_num(v, MAT[k].zr, z_lead / (r->rho0 * r->c0));
  }
  vsph_claim_num(v, "w50", coef(&cr->r[C_W50]));
  vsph_claim_num(v, "w20", coef(&cr->r[C_W20]));
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.eta_linear", v);
  /* measured over (37) from the smallest alpha to the largest, and its
   * largest departure (whether it grows at every step: the block's tests) */
  static const int A[5] = {C_W, C_A055, C_A06, C_A075, C_A1};
  vsph_claim_clear(v);
  for (int k = 0; k < 5; k++) { /* measured, and (37)'s at its alpha */
    char key[2][4];
    snprintf(key[0], sizeof key[0], "m%d", k);
    snprintf(key[1], sizeof key[1], "f%d", k);
    vsph_claim_num(v, key[0], coef(&cr->r[A[k]]));
    vsph_claim_num(v, key[1], vsph_materials_eta_num_fit(CS[A[k]].alpha));
  }
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.eta_fit", v);
  vsph_claim_clear(v);
  vsph_claim_num(v, "ss0", nb->ss_spread[0]);
  vsph_claim_num(v, "ss1", nb->ss_spread[1]);
  vsph_claim_num(v, "lean0", nb->ss_lean[0]);
  vsph_claim_num(v, "lean1", nb->ss_lean[1]);
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.self_similar", v);
  return st;
}

/* The correcting tensor and two materials (Parshikov §4). */
static int zeta_claims(struct vsph_report *R, const struct cnum *nb,
                       struct vsph_claim_vals *v) {
  const double e1 = nb->eta_eff[2];
  vsph_claim_clear(v);
  vsph_claim_num(v, "e1", e1);
  vsph_claim_num(v, "e0", nb->eta_eff[0]);
  vsph_claim_num(v, "e05", nb->eta_eff[1]);
  int st = vsph_report_doc_grade(R, "claims/contact.zeta_one", v);
  /* U* = (e_R - e_L)/(e_R + e_L) with e = sqrt(rho eta) on each side
   * (U0 = 1, the sides at -1 and +1): the ratio a = e_R/e_L = (1 + U*)/
   * (1 - U*), so a fitted U* gives the viscosity ratio the particles
   * carry, glycerol's over paraffin's (a_fit/a_exact)^2 = 1 + vr times
   * eq. (27)'s (paraffin's over glycerol's: 1/(1 + vr)) */
  const double u0 = nb->ustar[0][0], ue = nb->ustar_exact[0];
  vsph_claim_clear(v);
  vsph_claim_num(v, "u0", u0);
  vsph_claim_num(v, "u1", nb->ustar[0][1]);
  vsph_claim_num(v, "ue", ue);
  vsph_claim_num(v, "rms", nb->rms[0][0]);
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.two_fluids", v);
  vsph_claim_clear(v);
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.drop", v);
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.momentum", v);
  return st;
}

/* The cylinder arrays' drag (Parshikov §5). */
static int cyl_claims(struct vsph_report *R, struct vsph_claim_vals *v) {
  struct cyl cy;
  memset(&cy, 0, sizeof cy);
  int st = cyl_load(R, &cy);
  if (st) return st;
  /* the FULL plan adds glycerol uncorrected at 40 per diameter and the
   * paper's third case, d/S = 0.3 (20 per diameter) */
  const int full = R->runs.full;
  vsph_claim_clear(v);
  vsph_claim_num(v, "z0", cy.ratio[CY_Z0_40]);
  vsph_claim_num(v, "z0_30", cy.ratio[CY_Z0_60]);
  vsph_claim_num(v, "z1", cy.ratio[CY_Z1_40]);
  vsph_claim_num(v, "p0", cy.ratio[CY_P0_40]);
  vsph_claim_num(v, "p1", cy.ratio[CY_P1_40]);
  vsph_claim_num(v, "fine", full ? cy.ratio[CY_Z0_80] : cy.ratio[CY_Z0_60]);
  vsph_claim_str(v, "fine_res", "%d", full ? 40 : 30);
  vsph_claim_str(v, "g40", "%s", "");
  vsph_claim_str(v, "g03", "%s", "");
  if (full) {
    vsph_claim_str(v, "g40", ", %.2f (40)", cy.ratio[CY_Z0_80]);
    vsph_claim_str(v, "g03",
                   "; d/S = 0.3 uncorrected %.2f (20 per diameter; the "
                   "paper's 3.24)",
                   cy.ratio[CY_G03_67]);
  }
  vsph_claim_str(v, "resolutions", "%s", full ? "20, 30 and 40" : "20 and 30");
  vsph_claim_str(v, "paper_res", "%s", full ? ", about 60 by its ratios" : "");
  st = vsph_report_doc_grade(R, "claims/contact.drag", v);
  /* the 2-D analogue: 1/U against zeta at 20 per diameter, linear? */
  vsph_claim_clear(v);
  vsph_claim_num(v, "u_z0", cy.U[CY_Z0_40]);
  vsph_claim_num(v, "u_z05", cy.U[CY_Z05_40]);
  vsph_claim_num(v, "u_z1", cy.U[CY_Z1_40]);
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.falling_ball", v);
  vsph_claim_clear(v);
  if (!st) st = vsph_report_doc_grade(R, "claims/contact.ball_consistent", v);
  return st;
}

int vsph_report_contact_claims(struct vsph_report *R) {
  struct cres cr;
  struct cnum nb;
  int st = contact_load(R, &cr, &nb);
  if (st) return st;
  struct vsph_claim_vals *v = malloc(sizeof *v);
  if (!v) VSPH_FAIL(VSPH_ENOMEM, "cannot grade the contact claims");
  if (!st) st = shear_claims(R, &cr, &nb, v);
  if (!st) st = zeta_claims(R, &nb, v);
  if (!st) st = cyl_claims(R, v);
  free(v);
  return st;
}
