/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "sheartest.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../analysis/contact.h"
#include "../common/status.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "folder.h"
#include "rundir.h"

void vsph_sheartest_progress(void *ctx, double t, double t_end, double wall) {
  (void)ctx;
  /* the time left at the rate so far (the step is near constant) */
  if (t > 0.0 && t_end > t)
    fprintf(stderr,
            "vsph contact: shear t = %.4g / %.4g s (%.0f%%), %.0f s elapsed, "
            "about %.0f s left\n",
            t, t_end, 100.0 * t / t_end, wall, wall * (t_end - t) / t);
  else
    fprintf(stderr, "vsph contact: shear t = %.4g / %.4g s, %.0f s elapsed\n",
            t, t_end, wall);
}

/* checkpoint.bin of a shear test: this line, the key's length and text,
 * then the state vsph_contact_shear_measure handed over. */
static const char SHEAR_CKPT[] = "vsph shear test checkpoint\n";

struct saver {
  const char *dir, *key;
};

/* The state written whole or not at all: a temporary, synced, renamed. */
static int save_state(void *ctx, const unsigned char *state, size_t len) {
  const struct saver *sv = ctx;
  char tmp[4200], path[4200];
  snprintf(tmp, sizeof tmp, "%s/checkpoint.bin.tmp", sv->dir);
  snprintf(path, sizeof path, "%s/checkpoint.bin", sv->dir);
  const uint64_t kl = strlen(sv->key);
  errno = 0;
  FILE *f = fopen(tmp, "wb");
  int ok = f &&
           fwrite(SHEAR_CKPT, 1, sizeof SHEAR_CKPT - 1, f) ==
               sizeof SHEAR_CKPT - 1 &&
           fwrite(&kl, sizeof kl, 1, f) == 1 &&
           fwrite(sv->key, 1, kl, f) == kl && fwrite(state, 1, len, f) == len &&
           fflush(f) == 0 && fsync(fileno(f)) == 0;
  if (f && fclose(f) != 0) ok = 0;
  ok = ok && rename(tmp, path) == 0;
  if (!ok) {
    const int e = errno;
    remove(tmp);
    VSPH_FAIL(VSPH_EIO, "cannot write %s: %s", path,
              e ? strerror(e) : "write error");
  }
  return VSPH_OK;
}

/* The state of DIR/checkpoint.bin when it was made with key @p key (its
 * bytes into *@p len; the caller frees the block returned, from which
 * *@p state points), else NULL with why into @p why ("" when there is
 * none). */
static unsigned char *read_state(const char *dir, const char *key,
                                 const unsigned char **state, size_t *len,
                                 char *why, size_t wlen) {
  char path[4200];
  snprintf(path, sizeof path, "%s/checkpoint.bin", dir);
  why[0] = '\0';
  size_t n = 0;
  unsigned char *b =
      access(path, F_OK) ? NULL : (unsigned char *)vsph_files_slurp(path, &n);
  if (!b) return NULL;
  const size_t hl = sizeof SHEAR_CKPT - 1;
  uint64_t kl = 0;
  if (n >= hl + sizeof kl) memcpy(&kl, b + hl, sizeof kl);
  if (n < hl + sizeof kl || memcmp(b, SHEAR_CKPT, hl) || kl != strlen(key) ||
      n < hl + sizeof kl + kl || memcmp(b + hl + sizeof kl, key, kl)) {
    snprintf(why, wlen, "it is not this test's, with these settings");
    free(b);
    return NULL;
  }
  *state = b + hl + sizeof kl + kl;
  *len = n - hl - sizeof kl - kl;
  return b;
}

int vsph_sheartest_execute(struct vsph_params *prm, size_t nprof,
                           const char *dir, int cache, int quiet,
                           const volatile sig_atomic_t *stop, int *cached) {
  *cached = 0;
  /* the parameters as given: before any is read */
  char what[64];
  snprintf(what, sizeof what, "contact %zu", nprof);
  char *key = vsph_rundir_key(prm, what);
  if (!key) return VSPH_ENOMEM;
  if (cache && vsph_folder_verify(dir, &vsph_folder_shear_test, key, NULL, NULL,
                                  0) == 1) {
    *cached = 1;
    free(key);
    return VSPH_OK;
  }
  /* the folder judged and claimed first: one that cannot be used is bad
   * input, found before the measurement rather than after it */
  struct vsph_folder fo;
  int st = vsph_folder_claim(&fo, dir, &vsph_folder_shear_test);
  if (st) {
    free(key);
    return st;
  }
  /* a checkpoint of this very test: go on from it */
  const unsigned char *state = NULL;
  size_t slen = 0;
  char why[160];
  unsigned char *ck = read_state(dir, key, &state, &slen, why, sizeof why);
  if (why[0]) /* said even when quiet: work may be lost */
    fprintf(stderr,
            "vsph contact: %s/checkpoint.bin is not used (%s): starting "
            "over\n",
            dir, why);
  else if (ck && !quiet)
    fprintf(stderr, "vsph contact: resuming from %s/checkpoint.bin\n", dir);
  struct saver sv = {dir, key};
  struct vsph_contact_shear cs = {
      .nprof = nprof,
      .progress = quiet ? NULL : vsph_sheartest_progress,
      .stop = stop,
      .save = save_state,
      .save_ctx = &sv,
      .resume = state,
      .resume_len = slen};
  st = vsph_contact_shear_measure(prm, &cs);
  free(ck);
  if (st == VSPH_EINTR) { /* stopped at its checkpoint: the folder kept */
    fprintf(stderr,
            "vsph contact: stopped at a checkpoint in %s; the same command "
            "again goes on from it\n",
            dir);
    vsph_folder_release(&fo);
    free(key);
    return st;
  }
  if (st == VSPH_EINVAL && !ck) /* refused: the folder as it was */
    vsph_folder_abandon(&fo);
  char *sum = NULL, *prof = NULL;
  if (!st && !((sum = vsph_sheartest_csv_summary(&cs)) &&
               (prof = vsph_sheartest_csv_profiles(&cs))))
    st = VSPH_ENOMEM;
  vsph_contact_shear_free(&cs);
  /* key.txt first (nothing may vouch for a half-written folder), the seal
   * last */
  if (!st) st = vsph_folder_clear(&fo, NULL);
  if (!st) st = vsph_files_write(dir, "summary.csv", sum);
  if (!st) st = vsph_files_write(dir, "profiles.csv", prof);
  if (!st) st = vsph_folder_seal(&fo, key, NULL);
  vsph_folder_release(&fo);
  free(sum);
  free(prof);
  free(key);
  return st;
}

char *vsph_sheartest_csv_profiles(const struct vsph_contact_shear *cs) {
  char *buf = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&buf, &len);
  if (!f) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot build the shear profiles");
    return NULL;
  }
  fprintf(f, "t,x,u,u_fit,dy,dy_fit\n");
  for (size_t k = 0; k < cs->nt; k++)
    for (size_t b = 0; b < cs->nbins; b++)
      fprintf(
          f, "%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n", cs->t[k], cs->x[b], cs->u[k][b],
          vsph_contact_shear_u(cs->x[b], cs->t[k], cs->nu_u[k], cs->U0, cs->W),
          cs->dy[k][b],
          vsph_contact_shear_dy(cs->x[b], cs->t[k], cs->nu_dy[k], cs->U0,
                                cs->W));
  if (fclose(f) || !buf) {
    free(buf);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot build the shear profiles");
    return NULL;
  }
  return buf;
}

char *vsph_sheartest_csv_summary(const struct vsph_contact_shear *cs) {
  char *buf = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&buf, &len);
  if (!f) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot build the shear summary");
    return NULL;
  }
  fprintf(f,
          "t,nu_u,rms_u,nu_dy,rms_dy,n,D0,W,U0,rho0,c0,t_end,steps,wall_s,"
          "stable,t_stop\n");
  /* a run stopped before its first profile still leaves its facts */
  const size_t rows = cs->nt ? cs->nt : 1;
  for (size_t k = 0; k < rows; k++)
    fprintf(f,
            "%.9e,%.9e,%.6e,%.9e,%.6e,%zu,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%zu,"
            "%.3f,%d,%.9e\n",
            cs->nt ? cs->t[k] : (double)NAN, cs->nt ? cs->nu_u[k] : (double)NAN,
            cs->nt ? cs->rms_u[k] : (double)NAN,
            cs->nt ? cs->nu_dy[k] : (double)NAN,
            cs->nt ? cs->rms_dy[k] : (double)NAN, cs->n, cs->D0, cs->W, cs->U0,
            cs->rho0, cs->c0, cs->t_end, cs->steps, cs->wall_s, cs->stable,
            cs->t_stop);
  if (fclose(f) || !buf) {
    free(buf);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot build the shear summary");
    return NULL;
  }
  return buf;
}

int vsph_sheartest_csv_load(const char *path, struct vsph_contact_shear *cs) {
  memset(cs, 0, sizeof *cs);
  FILE *probe = fopen(path, "r");
  if (!probe) return VSPH_EIO;
  fclose(probe);
  struct vsph_csv *t = vsph_csv_read(path);
  if (!t) return VSPH_EIO;
  static const char *const NAMES[] = {
      "t",  "nu_u", "rms_u", "nu_dy", "rms_dy", "n",      "D0",     "W",
      "U0", "rho0", "c0",    "t_end", "steps",  "wall_s", "stable", "t_stop"};
  const double *c[16];
  int ok = t->nrow >= 1 && t->nrow <= 8;
  for (int k = 0; k < 16 && ok; k++)
    ok = (c[k] = vsph_csv_column(t, NAMES[k])) != NULL;
  if (!ok) {
    vsph_csv_free(t);
    return VSPH_EIO;
  }
  cs->nt = c[0][0] == c[0][0] ? t->nrow : 0; /* NaN: no profile reached */
  for (size_t k = 0; k < cs->nt; k++) {
    cs->t[k] = c[0][k];
    cs->nu_u[k] = c[1][k];
    cs->rms_u[k] = c[2][k];
    cs->nu_dy[k] = c[3][k];
    cs->rms_dy[k] = c[4][k];
  }
  cs->n = (size_t)c[5][0];
  cs->D0 = c[6][0];
  cs->W = c[7][0];
  cs->U0 = c[8][0];
  cs->rho0 = c[9][0];
  cs->c0 = c[10][0];
  cs->t_end = c[11][0];
  cs->steps = (size_t)c[12][0];
  cs->wall_s = c[13][0];
  cs->stable = (int)c[14][0];
  cs->t_stop = c[15][0];
  vsph_csv_free(t);
  return VSPH_OK;
}
