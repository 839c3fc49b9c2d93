/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "json.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../analysis/dissipation.h"
#include "../analysis/laplacian.h"
#include "../analysis/moments.h"
#include "../analysis/scaling.h"
#include "../common/status.h"
#include "../common/sysinfo.h"
#include "../kernels/kernel.h"
#include "../solver/lattice.h"
#include "../solver/viscous.h"
#include "files.h"

/* A NULL argument refused: reported, and NULL for the caller to return. */
static cJSON *refused(const char *fn) {
  vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__, "%s: a NULL argument",
                     fn);
  return NULL;
}

cJSON *vsph_json_array(const double *v, size_t n) {
  if (!v && n) return refused("vsph_json_array");
  cJSON *a = cJSON_CreateArray();
  for (size_t i = 0; i < n; i++)
    cJSON_AddItemToArray(
        a, isfinite(v[i]) ? cJSON_CreateNumber(v[i]) : cJSON_CreateNull());
  return a;
}

void vsph_json_number(cJSON *obj, const char *key, double v) {
  if (!obj || !key) return;
  if (isfinite(v))
    cJSON_AddNumberToObject(obj, key, v);
  else
    cJSON_AddNullToObject(obj, key);
}

void vsph_json_load(cJSON *obj, const double start[3], const double end[3]) {
  if (!obj || !start || !end) return;
  const char *when[2] = {"load_average_start", "load_average_end"};
  const double *load[2] = {start, end};
  for (int w = 0; w < 2; w++) {
    cJSON *la = cJSON_AddArrayToObject(obj, when[w]);
    for (int k = 0; la && k < 3; k++)
      cJSON_AddItemToArray(la, isfinite(load[w][k])
                                   ? cJSON_CreateNumber(load[w][k])
                                   : cJSON_CreateNull());
  }
  char wp[128];
  cJSON_AddStringToObject(obj, "omp_wait_policy",
                          vsph_sysinfo_wait_policy(wp, sizeof wp));
}

void vsph_json_moments(cJSON *obj, const struct vsph_moments *m) {
  if (!obj || !m || m->dim < 1 || m->dim > 3) return;
  const int d = m->dim;
  cJSON *F = cJSON_CreateArray(), *G = cJSON_CreateArray();
  cJSON *M = cJSON_CreateArray();
  for (int i = 0; i < d; i++) {
    cJSON *Fi = cJSON_CreateArray(), *Gi = cJSON_CreateArray();
    cJSON_AddItemToArray(M, vsph_json_array(m->M[i], (size_t)d));
    for (int j = 0; j < d; j++) {
      cJSON *Gij = cJSON_CreateArray();
      cJSON_AddItemToArray(Fi, vsph_json_array(m->F[i][j], (size_t)d));
      for (int l = 0; l < d; l++)
        cJSON_AddItemToArray(Gij, vsph_json_array(m->G[i][j][l], (size_t)d));
      cJSON_AddItemToArray(Gi, Gij);
    }
    cJSON_AddItemToArray(F, Fi);
    cJSON_AddItemToArray(G, Gi);
  }
  cJSON_AddItemToObject(obj, "F", F);
  cJSON_AddItemToObject(obj, "G", G);
  cJSON_AddItemToObject(obj, "N", vsph_json_array(m->N, (size_t)d));
  cJSON_AddItemToObject(obj, "M", M);
}

int vsph_json_print(cJSON *obj) {
  if (!obj) VSPH_FAIL(VSPH_EINVAL, "vsph_json_print: a NULL argument");
  char *s = cJSON_Print(obj);
  cJSON_Delete(obj);
  if (!s) VSPH_FAIL(VSPH_ENOMEM, "cannot format JSON");
  const int bad = puts(s) < 0 || fflush(stdout) != 0;
  free(s);
  if (bad) VSPH_FAIL(VSPH_EIO, "cannot write to standard output");
  return VSPH_OK;
}

char *vsph_json_text(cJSON *obj) {
  if (!obj) return (char *)refused("vsph_json_text");
  char *s = cJSON_Print(obj);
  cJSON_Delete(obj);
  const size_t n = s ? strlen(s) : 0;
  char *t = s ? realloc(s, n + 2) : NULL;
  if (!t) {
    free(s);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__, "cannot format JSON");
    return NULL;
  }
  memcpy(t + n, "\n", 2);
  return t;
}

int vsph_json_write(cJSON *obj, const char *dir, const char *name) {
  if (!obj || !dir || !name) {
    cJSON_Delete(obj);
    VSPH_FAIL(VSPH_EINVAL, "vsph_json_write: a NULL argument");
  }
  char *s = vsph_json_text(obj);
  if (!s) return VSPH_ENOMEM;
  const int st = vsph_files_write(dir, name, s);
  free(s);
  return st;
}

cJSON *vsph_json_read(const char *path) {
  if (!path) return NULL;
  char *text = vsph_files_slurp(path, NULL);
  cJSON *j = text ? cJSON_Parse(text) : NULL;
  free(text);
  return j;
}

double vsph_json_get_number(const cJSON *obj, const char *key, double def) {
  if (!obj || !key) return def;
  const cJSON *v = cJSON_GetObjectItemCaseSensitive(obj, key);
  return v && cJSON_IsNumber(v) ? v->valuedouble : def;
}

/* --------------------------------------- the analysis commands' results */

cJSON *vsph_json_tensors(const struct vsph_moments_props *mp,
                         const struct vsph_moments_result *r) {
  if (!mp || !r || !mp->kernel) return refused("vsph_json_tensors");
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "kernel", mp->kernel->name);
  cJSON_AddNumberToObject(o, "dim", mp->dim);
  cJSON_AddNumberToObject(o, "depth", mp->depth);
  cJSON_AddStringToObject(o, "method",
                          mp->particles ? "particles" : "quadrature");
  vsph_json_moments(o, mp->particles ? &r->sum : &r->quad);
  cJSON_AddNumberToObject(o, "C_F", r->C_F);
  cJSON_AddNumberToObject(o, "C_N", r->C_N);
  cJSON_AddNumberToObject(o, "kappa", mp->kernel->kappa);
  if (mp->particles) {
    cJSON_AddStringToObject(o, "lattice",
                            vsph_lattice_label(mp->lattice_kind, mp->perturb));
    cJSON_AddNumberToObject(o, "hdx", mp->hdx);
    if (mp->perturb > 0) {
      cJSON_AddNumberToObject(o, "perturb", mp->perturb);
      cJSON_AddNumberToObject(o, "seed", (double)mp->seed);
    }
    cJSON_AddNumberToObject(o, "n_particles", (double)r->n_particles);
    cJSON *q = cJSON_CreateObject();
    vsph_json_moments(q, &r->quad);
    cJSON_AddItemToObject(o, "quadrature", q);
    cJSON *g = cJSON_CreateObject();
    static const char *const names[4] = {"F", "G", "N", "M"};
    for (int k = 0; k < 4; k++) cJSON_AddNumberToObject(g, names[k], r->gap[k]);
    cJSON_AddItemToObject(o, "gap", g);
  }
  return o;
}

cJSON *vsph_json_scaling(const struct vsph_scaling_props *sp,
                         const struct vsph_scaling_result *r, double hF_th,
                         double hN_th) {
  if (!sp || !r || !sp->kernel) return refused("vsph_json_scaling");
  const size_t L = r->levels;
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "kernel", sp->kernel->name);
  cJSON_AddNumberToObject(o, "dim", sp->field.dim);
  cJSON_AddStringToObject(o, "field", vsph_fields_name(sp->field.kind));
  cJSON_AddStringToObject(o, "lattice",
                          vsph_lattice_label(sp->lattice, sp->perturb));
  cJSON_AddNumberToObject(o, "hdx", sp->hdx);
  cJSON_AddNumberToObject(o, "mu", sp->mu);
  cJSON_AddItemToObject(o, "h", vsph_json_array(r->h, L));
  cJSON_AddItemToObject(o, "hF", vsph_json_array(r->hF, L));
  cJSON_AddItemToObject(o, "hN", vsph_json_array(r->hN, L));
  cJSON_AddNumberToObject(o, "hF_theory", hF_th);
  cJSON_AddNumberToObject(o, "hN_theory", hN_th);
  for (int f = 0; f < VSPH_VISCOUS_FORM_COUNT; f++) {
    const char *nm = vsph_viscous_name(f);
    char key[64];
    cJSON_AddItemToObject(o, nm, vsph_json_array(r->normal[f], L));
    snprintf(key, sizeof key, "%s_tangential", nm);
    cJSON_AddItemToObject(o, key, vsph_json_array(r->tangential[f], L));
    snprintf(key, sizeof key, "%s_magnitude", nm);
    cJSON_AddItemToObject(o, key, vsph_json_array(r->magnitude[f], L));
    snprintf(key, sizeof key, "slope_%s", nm);
    vsph_json_number(o, key, r->slope[f]);
    snprintf(key, sizeof key, "rounding_%s", nm);
    cJSON_AddBoolToObject(o, key, r->rounding[f]);
  }
  return o;
}

cJSON *vsph_json_dissipation(const struct vsph_dissipation_props *dp,
                             const struct vsph_dissipation_result *r) {
  if (!dp || !r || !dp->kernel || dp->form < 0 ||
      dp->form >= VSPH_VISCOUS_FORM_COUNT)
    return refused("vsph_json_dissipation");
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "formulation", vsph_viscous_name(dp->form));
  cJSON_AddStringToObject(o, "field", vsph_fields_name(dp->field.kind));
  cJSON_AddStringToObject(o, "shape", vsph_dissipation_shape_name(dp->shape));
  cJSON_AddStringToObject(o, "kernel", dp->kernel->name);
  cJSON_AddNumberToObject(o, "res", (double)dp->nacross);
  cJSON_AddNumberToObject(o, "hdx", dp->hdx);
  cJSON_AddNumberToObject(o, "mu", dp->mu);
  cJSON_AddNumberToObject(o, "perturb", dp->perturb);
  cJSON_AddNumberToObject(o, "n_particles", (double)r->n_particles);
  cJSON_AddNumberToObject(o, "n_interior", (double)r->n_interior);
  cJSON_AddNumberToObject(o, "h", r->h);
  cJSON_AddNumberToObject(o, "dx", r->dx);
  cJSON_AddNumberToObject(o, "P", r->P);
  cJSON_AddNumberToObject(o, "P_pair", r->P_pair);
  cJSON_AddNumberToObject(o, "P_exact", r->P_exact);
  cJSON_AddNumberToObject(o, "P_grad", r->P_grad);
  cJSON_AddNumberToObject(o, "P_limit", r->P_limit);
  cJSON_AddStringToObject(
      o, "limit", vsph_viscous_limit_name(vsph_viscous_types[dp->form]->limit));
  cJSON_AddNumberToObject(o, "rel_error", r->rel_error);
  cJSON_AddNumberToObject(o, "consistency_error", r->consistency_error);
  vsph_json_number(o, "lattice_error", r->lattice_error);
  vsph_json_number(o, "surface_error", r->surface_error);
  cJSON_AddNumberToObject(o, "momentum", r->momentum);
  cJSON_AddNumberToObject(o, "angular", r->angular);
  cJSON_AddNumberToObject(o, "n_fallback", (double)r->n_fallback);
  return o;
}

cJSON *vsph_json_laplacian(const struct vsph_laplacian_props *lp,
                           const struct vsph_laplacian_result *r) {
  if (!lp || !r || !lp->kernel) return refused("vsph_json_laplacian");
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "form", vsph_laplacian_form_name(lp->form));
  cJSON_AddStringToObject(o, "field", vsph_laplacian_field_name(lp->field));
  cJSON_AddStringToObject(o, "kernel", lp->kernel->name);
  cJSON_AddNumberToObject(o, "dim", lp->dim);
  cJSON_AddNumberToObject(o, "n", (double)lp->n);
  cJSON_AddNumberToObject(o, "hdx", lp->hdx);
  cJSON_AddNumberToObject(o, "perturb", lp->perturb);
  cJSON_AddNumberToObject(o, "seed", (double)lp->seed);
  cJSON_AddNumberToObject(o, "eta", lp->eta);
  cJSON_AddNumberToObject(o, "n_eval", (double)r->n_eval);
  cJSON_AddNumberToObject(o, "n_total", (double)r->n_total);
  cJSON_AddNumberToObject(o, "dx", r->dx);
  cJSON_AddNumberToObject(o, "h", r->h);
  vsph_json_number(o, "err_literal", r->err_literal);
  vsph_json_number(o, "err_exact", r->err_exact);
  vsph_json_number(o, "err_paper", r->err_paper);
  cJSON_AddNumberToObject(o, "abs_max", r->abs_max);
  cJSON_AddNumberToObject(o, "ref_max", r->ref_max);
  cJSON_AddNumberToObject(o, "line_x", lp->line_x);
  cJSON_AddNumberToObject(o, "n_line", (double)r->n_line);
  vsph_json_number(o, "err_line_literal", r->err_line_literal);
  vsph_json_number(o, "err_line_paper", r->err_line_paper);
  return o;
}
