/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* Section 1 of the report: the moment tensors F, G, N, M (THEORY 2) for
 * every kernel, by quadrature against theory and by particle sums against
 * quadrature, with the surface constants C_F, C_N. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../analysis/moments.h"
#include "../common/consts.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/particles.h"
#include "report_parts.h"

/* The h/dx values of the particle sums. */
static const double HDX[3] = {VSPH_CONSTS_HDX, 2.0, 4.0};

/* Which row: kernel, dimension, support and method. */
struct row_id {
  const char *kernel;
  int dim;
  const char *support, *method;
};

/* Representative entries (n normal, t tangential) of a tensor set. */
static void entries(const struct vsph_moments *m, double e[8]) {
  const int n = m->dim - 1;
  e[0] = m->F[n][n][n];
  e[1] = m->F[n][0][0];
  e[2] = m->N[n];
  e[3] = m->G[n][n][n][n];
  e[4] = m->G[0][0][0][0];
  e[5] = m->G[0][0][n][n];
  e[6] = m->M[n][n];
  e[7] = m->M[0][0];
}

static double max4(const double g[4]) {
  return fmax(fmax(g[0], g[1]), fmax(g[2], g[3]));
}

/* One row of the entries table: values, and the largest entry gap to the
 * theoretical tensors (all entries, not only those shown). */
static void entries_row(FILE *csv, FILE *md, const struct row_id *id,
                        const struct vsph_moments *m,
                        const struct vsph_moments *th) {
  double e[8], g[4];
  entries(m, e);
  vsph_moments_gap(m, th, g);
  fprintf(csv, "%s,%d,%s,%s", id->kernel, id->dim, id->support, id->method);
  for (int k = 0; k < 8; k++) fprintf(csv, ",%.12e", e[k]);
  fprintf(csv, ",%.3e\n", max4(g));
  fprintf(md, "| %s | %d | %s | %s", id->kernel, id->dim, id->support,
          id->method);
  for (int k = 0; k < 8; k++) /* never "-0.00000" */
    fprintf(md, " | %.5f", vsph_consts_shown(e[k], 5e-6));
  fprintf(md, " | %.1e |\n", max4(g));
}

/* The tensors summed over a lattice patch of radius (kappa + 2/hdx) h at
 * depth `depth`, h = 1. */
static int lattice_sum(const struct vsph_kernel_type *k,
                       const struct vsph_lattice_props *lp, double hdx,
                       double depth, struct vsph_moments *sm, size_t *np) {
  struct vsph_particles *p = NULL;
  size_t c;
  int st = vsph_lattice_halfspace(lp, k->kappa + 2.0 / hdx, depth, &p, &c);
  if (!st) st = vsph_moments_sum(k, p, c, 1.0, sm);
  if (p && np) *np = p->n;
  vsph_particles_free(p);
  return st;
}

/* F, G, N, M entries beside theory: quadrature and particle sums (square
 * lattice, h/dx 4/3 and 4) for every kernel in 2-D and 3-D, half and full
 * support. */
static int tensor_entries(struct vsph_report *R) {
  FILE *csv = vsph_csv_open(R->dir, "tensor_entries.csv",
                            "kernel,dim,support,method,F_nnn,F_ntt,N_n,"
                            "G_nnnn,G_tttt,G_ttnn,M_nn,M_tt,"
                            "max_gap_to_theory");
  if (!csv) return VSPH_EIO;
  int st = vsph_report_doc_say(R, "tensors.entries");
  for (size_t ki = 0; ki < vsph_kernel_count() && !st; ki++) {
    const struct vsph_kernel_type *k = vsph_kernel_get(ki);
    for (int dim = 2; dim <= 3 && !st; dim++) {
      double C_F, C_N;
      if ((st = vsph_moments_constants(k, dim, 1e-12, R->wo, &C_F, &C_N)))
        break;
      for (int half = 1; half >= 0 && !st; half--) {
        const double depth = half ? 0.0 : k->kappa;
        struct row_id id = {k->name, dim, half ? "half" : "full", "theory"};
        struct vsph_moments th, q, sm;
        vsph_moments_theory(dim, half, C_F, C_N, &th);
        if ((st = vsph_moments_quadrature(k, dim, depth, 1e-10, R->wo, R->wi,
                                          &q)))
          break;
        entries_row(csv, R->md, &id, &th, &th);
        id.method = "quadrature";
        entries_row(csv, R->md, &id, &q, &th);
        const double hdxs[2] = {HDX[0], HDX[2]};
        for (int hi = 0; hi < 2 && !st; hi++) {
          struct vsph_lattice_props lp = {.dim = dim, .dx = 1.0 / hdxs[hi]};
          char meth[48];
          snprintf(meth, sizeof meth, "particles h/dx %.3g", hdxs[hi]);
          id.method = meth;
          if (!(st = lattice_sum(k, &lp, hdxs[hi], depth, &sm, NULL)))
            entries_row(csv, R->md, &id, &sm, &th);
        }
      }
    }
  }
  fprintf(R->md, "\n");
  if (st) {
    fclose(csv);
    return st;
  }
  return vsph_csv_close(csv, R->dir, "tensor_entries.csv");
}

/* Particle sums of one kernel, dimension and support against quadrature at
 * the node depth (q) and at the cell-face depth: tensors.csv rows, and the
 * 2-D Gaussian rows for the Markdown table into pm. */
static int sums_vs_quadrature(struct vsph_report *R, FILE *csv, FILE *pm,
                              const struct row_id *id,
                              const struct vsph_kernel_type *k, double depth,
                              const struct vsph_moments *q) {
  static const char *const meth[3] = {"square", "hex", "perturbed"};
  int st = VSPH_OK;
  for (int m = 0; m < 3 && !st; m++) {
    if (m == 1 && id->dim != 2) continue;
    for (int hi = 0; hi < 3 && !st; hi++) {
      struct vsph_lattice_props lp = {
          .dim = id->dim,
          .kind = m == 1 ? VSPH_LATTICE_HEX : VSPH_LATTICE_SQUARE,
          .dx = 1.0 / HDX[hi],
          .perturb = m == 2 ? 0.1 : 0.0,
          .seed = VSPH_CONSTS_SEED};
      struct vsph_moments s, qc;
      size_t np = 0;
      st = lattice_sum(k, &lp, HDX[hi], depth, &s, &np);
      /* the set's own free surface lies dx/2 above its top row */
      if (!st)
        st = vsph_moments_quadrature(k, id->dim, depth + 0.5 / HDX[hi], 1e-10,
                                     R->wo, R->wi, &qc);
      if (st) break;
      double g[4], gc[4];
      vsph_moments_gap(&s, q, g);
      vsph_moments_gap(&s, &qc, gc);
      fprintf(csv,
              "%s,%d,%s,%s,%.6f,%zu,%.3e,%.3e,%.3e,%.3e,%.3e,%.3e,%.3e,"
              "%.3e\n",
              id->kernel, id->dim, id->support, meth[m], HDX[hi], np, g[0],
              g[1], g[2], g[3], gc[0], gc[1], gc[2], gc[3]);
      if (pm)
        fprintf(pm, "| %s | %s | %.3f | %.2e | %.2e | %.2e | %.2e | %.2e |\n",
                id->support, meth[m], HDX[hi], g[0], g[1], g[2], g[3],
                max4(gc));
    }
  }
  return st;
}

int vsph_report_tensors_write(struct vsph_report *R) {
  FILE *csv = vsph_csv_open(
      R->dir, "tensors.csv",
      "kernel,dim,support,method,hdx,n_particles,gap_F,gap_G,gap_N,gap_M,"
      "cellface_gap_F,cellface_gap_G,cellface_gap_N,cellface_gap_M");
  FILE *cc = vsph_csv_open(R->dir, "constants.csv",
                           "kernel,dim,C_F,C_N,C_F_untruncated_gaussian,"
                           "C_N_untruncated_gaussian");
  char *pbuf = NULL;
  size_t plen = 0;
  FILE *pm = open_memstream(&pbuf, &plen); /* 2-D Gaussian rows, for md */
  int st = csv && cc && pm ? vsph_report_doc_say(R, "tensors.intro") : VSPH_EIO;
  for (size_t ki = 0; ki < vsph_kernel_count() && !st; ki++) {
    const struct vsph_kernel_type *k = vsph_kernel_get(ki);
    for (int dim = 1; dim <= 3 && !st; dim++) {
      double C_F, C_N, gmax[2] = {0, 0};
      if ((st = vsph_moments_constants(k, dim, 1e-12, R->wo, &C_F, &C_N)))
        break;
      const double K = vsph_kernel_mg_factor(dim);
      fprintf(cc, "%s,%d,%.14e,%.14e,", k->name, dim, C_F, C_N);
      if (dim == 1)
        fprintf(cc, ",\n");
      else /* Appendix B: the untruncated Gaussian's closed forms */
        fprintf(cc, "%.14e,%.14e\n",
                dim == 2 ? K / (3 * VSPH_SQRTPI) : K / (4 * VSPH_SQRTPI),
                2 / VSPH_SQRTPI);
      for (int half = 1; half >= 0 && !st; half--) {
        const double depth = half ? 0.0 : k->kappa;
        const struct row_id id = {k->name, dim, half ? "half" : "full", NULL};
        struct vsph_moments q, th;
        if ((st = vsph_moments_quadrature(k, dim, depth, 1e-10, R->wo, R->wi,
                                          &q)))
          break;
        vsph_moments_theory(dim, half, C_F, C_N, &th);
        double g[4];
        vsph_moments_gap(&q, &th, g);
        gmax[!half] = max4(g);
        fprintf(csv,
                "%s,%d,%s,quadrature-vs-theory,,,%.3e,%.3e,%.3e,%.3e,,,,\n",
                k->name, dim, id.support, g[0], g[1], g[2], g[3]);
        st = sums_vs_quadrature(R, csv, ki == 0 && dim == 2 ? pm : NULL, &id, k,
                                depth, &q);
      }
      fprintf(R->md, "| %s | %d | %.10f | %.10f | %.1e | %.1e |\n", k->name,
              dim, C_F, C_N, gmax[0], gmax[1]);
    }
  }
  if (pm) fclose(pm);
  if (!st) st = vsph_report_doc_say(R, "tensors.lattice");
  if (!st) {
    fwrite(pbuf, 1, plen, R->md);
    fprintf(R->md, "\n");
  }
  free(pbuf);
  if (st) {
    if (csv) fclose(csv);
    if (cc) fclose(cc);
    return st;
  }
  st = vsph_csv_close(csv, R->dir, "tensors.csv");
  const int c2 = vsph_csv_close(cc, R->dir, "constants.csv");
  if (!st) st = c2;
  return st ? st : tensor_entries(R);
}
