/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "rundir.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <zlib.h>

#include "../analysis/references.h"
#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../common/sysinfo.h"
#include "../io/csv.h"
#include "../io/files.h"
#include "../io/json.h"
#include "../io/vtk.h"
#include "../kernels/kernel.h"
#include "../solver/diagnostics.h"
#include "../solver/integrate.h"
#include "../solver/run.h"
#include "../solver/scene.h"
#include "../solver/viscous.h"
#include "folder.h"

/* ----------------------------------------------------------- the cache */

/* entries are {key, value} pairs: compare the keys */
static int by_key(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

char *vsph_rundir_key(const struct vsph_params *prm, const char *what) {
  const size_t n = vsph_params_count(prm);
  const char *(*kv)[2] = malloc((n ? n : 1) * sizeof *kv);
  if (!kv) {
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot list %zu parameters", n);
    return NULL;
  }
  for (size_t i = 0; i < n; i++) {
    int used;
    vsph_params_entry(prm, i, &kv[i][0], &kv[i][1], &used);
  }
  qsort(kv, n, sizeof *kv, by_key);
  char *key = NULL;
  size_t len = 0;
  FILE *f = open_memstream(&key, &len);
  if (!f) {
    free(kv);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__, "cannot build a key");
    return NULL;
  }
  fprintf(f, "vsph %s %s\n%s\n", VSPH_VERSION, vsph_source_hash_id, what);
  /* the checkpoints' interval changes when state is saved, never the
   * results: a run resumes whatever it is */
  for (size_t i = 0; i < n; i++)
    if (strcmp(kv[i][0], "Solver:checkpoint_s"))
      fprintf(f, "%s=%s\n", kv[i][0], kv[i][1]);
  free(kv);
  if (fclose(f) != 0) {
    free(key);
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__, "cannot build a key");
    return NULL;
  }
  return key;
}

int vsph_rundir_key_matches(const char *dir, const char *key) {
  return vsph_folder_verify(dir, NULL, key, NULL, NULL, 0) == 1;
}

/* Every parameter of the run, defaults filled in, section by section. */
static int write_used(struct vsph_params *prm, const char *dir) {
  FILE *f = vsph_files_open(dir, "used_parameters.yml");
  if (!f) return VSPH_EIO;
  fprintf(f, "# vsph %s: every parameter of this run, defaults filled in\n",
          VSPH_VERSION);
  const char *sections[2] = {"Solver", "Scene"};
  for (int s = 0; s < 2; s++) {
    fprintf(f, "%s:\n", sections[s]);
    const size_t len = strlen(sections[s]);
    for (size_t i = 0; i < vsph_params_count(prm); i++) {
      const char *k, *v;
      int used;
      vsph_params_entry(prm, i, &k, &v, &used);
      if (!strncmp(k, sections[s], len) && k[len] == ':')
        fprintf(f, "  %s: %s\n", k + len + 1, v);
    }
  }
  return vsph_files_close(f, dir, "used_parameters.yml");
}

/* run.json: the settings, the figures of the run and its status: ok,
 * unstable, interrupted, or error (a write failed: @p error says which). */
static int write_run_json(const struct vsph_run *run,
                          const struct vsph_rundir_opts *opts,
                          const struct vsph_rundir_result *res, double bytes,
                          const char *error, char **text) {
  const struct vsph_run_props *rp = &run->props;
  cJSON *o = cJSON_CreateObject();
  cJSON_AddStringToObject(o, "version", VSPH_VERSION);
  cJSON_AddStringToObject(o, "source_hash", vsph_source_hash_id);
  cJSON_AddStringToObject(o, "commit",
                          vsph_commit_id[0] ? vsph_commit_id : "unknown");
  cJSON_AddStringToObject(o, "build", vsph_sysinfo_build_isa());
  if (opts->command) cJSON_AddStringToObject(o, "command", opts->command);
  cJSON_AddStringToObject(o, "date", res->started);
  cJSON_AddStringToObject(o, "scene", run->scene.type->name);
  cJSON_AddStringToObject(o, "visc", vsph_run_method(rp));
  cJSON_AddStringToObject(o, "scheme",
                          vsph_equations_scheme_name(rp->scheme_kind));
  cJSON_AddStringToObject(o, "kernel", rp->ktype->name);
  cJSON_AddNumberToObject(o, "res", (double)rp->res);
  cJSON_AddNumberToObject(o, "n_particles", (double)res->n_particles);
  cJSON_AddNumberToObject(o, "h", res->h);
  cJSON_AddNumberToObject(o, "dx", res->dx);
  cJSON_AddNumberToObject(o, "c0", res->c0);
  cJSON_AddNumberToObject(o, "mu", res->mu);
  cJSON_AddNumberToObject(o, "U_max", run->scene.U_max);
  cJSON_AddNumberToObject(o, "t_end", run->t_end);
  cJSON_AddNumberToObject(o, "t", res->t);
  cJSON_AddNumberToObject(o, "steps", (double)res->steps);
  /* the threads its loops had: one inside another parallel region (the
   * report runs two at a time) */
  cJSON_AddNumberToObject(o, "threads",
                          omp_in_parallel() ? 1 : omp_get_max_threads());
  cJSON_AddNumberToObject(o, "wall_s", res->wall_s);
  /* the processes the wall time was spent in (1 + the times it resumed
   * from a checkpoint) */
  cJSON_AddNumberToObject(o, "wall_segments", (double)res->segments);
  /* a timing is read beside the machine's state: CPU time (all threads),
   * the load averages before and after, the OpenMP wait policy */
  vsph_json_number(o, "cpu_s", res->cpu_s);
  vsph_json_load(o, res->load[0], res->load[1]);
  vsph_json_number(o, "pairs_per_s",
                   res->wall_s > 0 ? res->pairs / res->wall_s : (double)NAN);
  vsph_json_number(o, "particle_steps_per_s",
                   res->wall_s > 0 ? (double)res->n_particles *
                                         (double)res->steps / res->wall_s
                                   : (double)NAN);
  cJSON_AddNumberToObject(o, "memory_bytes", bytes);
  /* the process's peak resident memory so far: the whole run's, for a
   * run that is the process's only job (vsph run) */
  cJSON_AddNumberToObject(o, "peak_rss_bytes", (double)vsph_sysinfo_peak_rss());
  cJSON_AddNumberToObject(o, "pvwf_fallback_particles",
                          (double)vsph_run_fallbacks(run));
  cJSON_AddStringToObject(o, "status",
                          error              ? "error"
                          : res->interrupted ? "interrupted"
                          : res->unstable    ? "unstable"
                                             : "ok");
  if (error) cJSON_AddStringToObject(o, "error", error);
  if (res->interrupted) cJSON_AddNumberToObject(o, "interrupted_time", res->t);
  if (res->unstable) {
    cJSON_AddNumberToObject(o, "unstable_time", res->unstable_time);
    cJSON_AddStringToObject(o, "unstable_reason", res->reason);
  }
  if (!text) return vsph_json_write(o, res->dir, "run.json");
  /* the text only: the caller seals the folder with it, then writes it */
  return (*text = vsph_json_text(o)) ? VSPH_OK : VSPH_ENOMEM;
}

/* The files written while the run goes on. */
struct outputs {
  const char *dir;
  struct vsph_folder *fo; /* the claimed folder */
  FILE *csv;
  FILE *profile; /* at each snapshot: channels' profile.csv, the cavity's
                    centreline.csv */
  const char *profile_name; /* which of the two */
  FILE *probes;             /* probes.csv, at each row (Solver:probe_*) */
  struct vsph_vtk_pvd pvd;
  size_t nsnap;
  char error[1200]; /* the write that failed, for run.json */
};

/* The live tables (energy.csv, profile.csv: flushed row by row, so a run
 * stopped early keeps what it wrote). A failed write is said once, in
 * o->error (for run.json) and on the status channel. */
static int live_failed(struct outputs *o, const char *name) {
  snprintf(o->error, sizeof o->error, "cannot write %s/%s: %s", o->dir, name,
           errno ? strerror(errno) : "write error");
  vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "%s", o->error);
  return VSPH_EIO;
}

/* A live table: new with its header (@p keep < 0), or a resumed run's,
 * cut back to the @p keep bytes its checkpoint saw written. */
static FILE *live_open(struct outputs *o, const char *name, const char *header,
                       long keep, int *st) {
  char path[4200];
  snprintf(path, sizeof path, "%s/%s", o->dir, name);
  errno = 0;
  FILE *f = NULL;
  if (keep < 0) {
    if ((f = fopen(path, "w"))) fputs(header, f);
  } else { /* a new file of the first bytes: a link to the old one keeps
              it whole */
    f = vsph_files_reopen(o->dir, name, keep);
  }
  if (!f) *st = live_failed(o, name);
  return f;
}

static int live_flush(struct outputs *o, FILE *f, const char *name) {
  return fflush(f) != 0 || ferror(f) ? live_failed(o, name) : VSPH_OK;
}

/* Close *f (if open); a failure counts only when nothing failed before. */
static int live_close(struct outputs *o, FILE **f, const char *name, int st) {
  if (!*f) return st;
  errno = 0;
  const int c = fclose(*f);
  *f = NULL;
  return !st && c != 0 ? live_failed(o, name) : st;
}

/* The probes at this row: one line each (t, probe, x, y, z, u, v, w, p,
 * rho, fill), read by vsph_diagnostics_probe. */
static int write_probes(struct outputs *o, const struct vsph_run *run,
                        double t) {
  const struct vsph_run_props *rp = &run->props;
  const struct vsph_integrate *s = run->integ;
  double period[3];
  for (int a = 0; a < 3; a++)
    period[a] = vsph_walls_period(&run->scene.walls, a);
  const size_t n = rp->probe_points;
  errno = 0;
  for (size_t k = 0; k < n; k++) {
    const double f = n > 1 ? (double)k / (double)(n - 1) : 0.0;
    const double x[3] = {rp->probe_x0 + f * (rp->probe_x1 - rp->probe_x0),
                         rp->probe_y0 + f * (rp->probe_y1 - rp->probe_y0),
                         rp->probe_z};
    struct vsph_diagnostics_probe r;
    const int st =
        vsph_diagnostics_probe(s->p, s->n_fluid, s->props.eq.visc.kernel,
                               s->props.eq.visc.h, period, x, &r);
    if (st) return st;
    fprintf(o->probes,
            "%.10g,%zu,%.10e,%.10e,%.10e,%.12e,%.12e,%.12e,%.12e,%.12e,"
            "%.6e\n",
            t, k, x[0], x[1], x[2], r.u[0], r.u[1], r.u[2], r.p, r.rho, r.fill);
  }
  return live_flush(o, o->probes, "probes.csv");
}

static int write_row(struct outputs *o, struct vsph_run *run,
                     struct vsph_references_scene *ref) {
  struct vsph_run_row row;
  double Er, dEr, Em, dEm;
  int st = vsph_run_row(run, &row);
  if (!st) st = vsph_references_scene_eval(ref, row.t, &Er, &dEr);
  if (!st) st = vsph_references_scene_mech(ref, row.t, &Em, &dEm);
  if (st) return st;
  const struct vsph_equations_energy *en = &row.en;
  const struct vsph_equations_budget *b = &row.b;
  struct vsph_references_profile_err pe;
  if (run->scene.type == &vsph_cavity_type)
    vsph_references_cavity_error(&run->scene, run->integ->p, run->n_fluid,
                                 run->props.ktype, run->h, &pe);
  else
    vsph_references_profile_error(&run->scene, run->integ->p, run->n_fluid,
                                  row.t, &pe);
  errno = 0;
  fprintf(o->csv,
          "%.10g,%.12e,%.12e,%.12e,%.12e,%.12e,%.6e,%.6e,%.6e,%.12e,"
          "%.12e,%.12e,%.12e,%.12e,%.12e,%.8e,%.8e,%.8e\n",
          row.t, en->Ek, en->Ep, en->Ec, b->P_visc, b->P_delta, b->residual,
          en->P[0], en->P[1], en->Lz, b->dEk, Er, dEr, Em, dEm, pe.rms,
          pe.rms_rel, pe.v_rms);
  st = live_flush(o, o->csv, "energy.csv");
  return st || !o->probes ? st : write_probes(o, run, row.t);
}

/* A channel's velocity profile at a snapshot: one row per row of
 * particles (res bins across the width), beside the series. */
static int write_profile(struct outputs *o, const struct vsph_run *run) {
  const size_t nb = run->props.res;
  double *buf = malloc(3 * nb * sizeof *buf);
  size_t *cnt = malloc(nb * sizeof *cnt);
  int st = buf && cnt ? VSPH_OK : VSPH_ENOMEM;
  if (!st)
    st = vsph_references_profile_bins(&run->scene, run->integ->p, run->n_fluid,
                                      run->integ->t, nb, buf, buf + nb,
                                      buf + 2 * nb, cnt);
  errno = 0;
  for (size_t k = 0; k < nb && !st; k++)
    fprintf(o->profile, "%.10g,%.10e,%.10e,%.10e,%zu\n", run->integ->t, buf[k],
            buf[nb + k], buf[2 * nb + k], cnt[k]);
  if (!st) st = live_flush(o, o->profile, o->profile_name);
  free(buf);
  free(cnt);
  return st;
}

/* The cavity's centrelines at a snapshot: u(y) on x = L/2 and v(x) on
 * y = L/2 (Shepard averages) at Ghia et al.'s 17 points of each, beside
 * their values (NaN where they have no table for the run's Re). */
static int write_centreline(struct outputs *o, const struct vsph_run *run) {
  const struct vsph_scene_cavity *cv = &run->scene.u.cavity;
  struct vsph_references_ghia g;
  const int have = vsph_references_ghia(cv->Re, &g);
  if (!have) vsph_references_ghia(100.0, &g); /* their points, no values */
  errno = 0;
  for (int line = 0; line < 2; line++)
    for (size_t q = 0; q < g.n; q++) {
      double sph, ref;
      const double s = vsph_references_cavity_point(
          cv, &g, line, q, run->integ->p, run->n_fluid, run->props.ktype,
          run->h, &sph, &ref);
      fprintf(o->profile, "%.10g,%s,%.10e,%.10e,%.10e\n", run->integ->t,
              line ? "v(x)" : "u(y)", s, sph, have ? ref : (double)NAN);
    }
  return live_flush(o, o->profile, o->profile_name);
}

/* A snapshot and its table rows; VSPH_EINTR, with nothing written, when
 * *stop is set during its sums or its compression. */
static int write_snapshot(struct outputs *o, struct vsph_run *run,
                          const volatile sig_atomic_t *stop) {
  char name[64];
  snprintf(name, sizeof name, "snap_%04zu.vtp", o->nsnap);
  const struct vsph_integrate *s = run->integ;
  struct vsph_diagnostics dg;
  const struct vsph_kernel_type *k = s->props.eq.visc.kernel;
  const double h = s->props.eq.visc.h;
  /* evaluated (as a snapshot nearly always is: a row or its own time's
   * evaluation), on the particles as they are, the sums into the rates
   * (free until the next step) and the file in the integrator's order;
   * else on a sorted copy: the same bits, the copy's memory (about 90 B
   * a particle) saved */
  struct vsph_particles *p = s->p;
  double *const room[4] = {p->acc[0], p->dim > 1 ? p->acc[1] : NULL,
                           p->dim > 2 ? p->acc[2] : NULL, p->drho};
  int st =
      run->evaluated
          ? vsph_diagnostics_compute_cells(p, s->n_fluid, s->cells, k, h,
                                           p->dim > 1 ? room : NULL, &dg, stop)
          : vsph_diagnostics_compute(p, s->n_fluid, k, h, &dg, stop);
  if (!st) {
    st = run->evaluated
             ? vsph_vtk_write_mapped(o->dir, name, p, s->n_fluid, s->where,
                                     s->t, &dg, stop)
             : vsph_vtk_write(o->dir, name, p, s->n_fluid, s->t, &dg, stop);
    vsph_diagnostics_free(&dg);
  }
  if (st == VSPH_EINTR) return st;
  if (!st) o->nsnap++;
  /* read once now, while cached, not at each checkpoint (best effort: a
   * checkpoint reads it if this fails) */
  if (!st) (void)vsph_folder_note(o->fo, name);
  if (!st) st = vsph_vtk_pvd_add(&o->pvd, s->t, name);
  /* the walls beside it (wall particles, ghosts, images), part 1 of the
   * same time in snapshots.pvd: a ParaView user sees the tank and the lid */
  if (!st && s->p->n > s->n_fluid) {
    char wname[64];
    snprintf(wname, sizeof wname, "walls_%04zu.vtp", o->nsnap - 1);
    st = vsph_vtk_write_walls(o->dir, wname, s->p, s->n_fluid,
                              vsph_integrate_wall_count(s), s->props.eq.visc.h,
                              s->t);
    if (!st) (void)vsph_folder_note(o->fo, wname);
    if (!st) st = vsph_vtk_pvd_add_part(&o->pvd, s->t, 1, wname);
  }
  if (!st && o->profile)
    st = run->scene.type == &vsph_cavity_type ? write_centreline(o, run)
                                              : write_profile(o, run);
  if (st)
    snprintf(o->error, sizeof o->error, "cannot write snapshot %s/%s", o->dir,
             name);
  return st;
}

/* ------------------------------------------------------ checkpoints */

/* checkpoint.bin: MAGIC, the key's length and text, struct ckpt, the
 * run's packed state (vsph_run_pack), then the CRC-32 of all before it.
 * Written to a temporary, synced and renamed: a checkpoint is whole or
 * absent. */
static const char CKPT_MAGIC[16] = "vsph checkpoint";
enum { CKPT_VERSION = 5 };

/* the files a checkpoint saw, but itself and run.json (absent while a run
 * goes on) */
static const char *const CKPT_SKIP[] = {"checkpoint.bin", "run.json", NULL};

struct ckpt {
  uint64_t version;
  uint64_t csv, profile, pvd; /* the live files' lengths (bytes) */
  uint64_t probes;            /* probes.csv's (0: none) */
  uint64_t nsnap;             /* snapshots written */
  uint64_t segments;          /* processes so far */
  uint64_t state;             /* the packed state's length */
  uint64_t manifest;          /* the folder's list's length (bytes) */
  double wall_s, cpu_s;       /* spent so far */
  double bytes;               /* the buffers' bytes so far */
  char started[32];           /* the first start (UTC) */
};

static long tell(FILE *f) { return f ? ftell(f) : 0L; }

static int checkpoint_write(struct outputs *o, const struct vsph_run *run,
                            const char *key,
                            const struct vsph_rundir_result *res, double wall,
                            double cpu) {
  struct ckpt c;
  memset(&c, 0, sizeof c);
  c.version = CKPT_VERSION;
  c.csv = (uint64_t)tell(o->csv);
  c.profile = (uint64_t)tell(o->profile);
  c.pvd = (uint64_t)tell(o->pvd.f);
  c.probes = (uint64_t)tell(o->probes);
  c.nsnap = o->nsnap;
  c.segments = res->segments;
  c.state = vsph_run_pack(run, NULL);
  c.wall_s = wall;
  c.cpu_s = cpu;
  c.bytes = fmax(res->bytes_before, (double)vsph_run_bytes(run));
  /* every file so far, with its size and CRC: a resume goes on only in a
   * folder that still holds them */
  char *list = vsph_folder_manifest(o->fo, CKPT_SKIP);
  if (!list) {
    snprintf(o->error, sizeof o->error, "cannot list %s for a checkpoint",
             o->dir);
    VSPH_FAIL(VSPH_EIO, "%s", o->error);
  }
  c.manifest = strlen(list);
  memcpy(c.started, res->started, sizeof c.started);
  const uint64_t klen = strlen(key);
  const size_t len = sizeof CKPT_MAGIC + sizeof klen + klen + sizeof c +
                     c.state + c.manifest + sizeof(uint32_t);
  unsigned char *buf = malloc(len);
  if (!buf) {
    free(list);
    VSPH_FAIL(VSPH_ENOMEM, "cannot allocate a checkpoint of %zu bytes", len);
  }
  size_t at = 0;
  memcpy(buf + at, CKPT_MAGIC, sizeof CKPT_MAGIC), at += sizeof CKPT_MAGIC;
  memcpy(buf + at, &klen, sizeof klen), at += sizeof klen;
  memcpy(buf + at, key, klen), at += klen;
  memcpy(buf + at, &c, sizeof c), at += sizeof c;
  if (vsph_run_pack(run, buf + at) != c.state) {
    free(list);
    free(buf);
    snprintf(o->error, sizeof o->error,
             "cannot read back the state kept for a snapshot");
    VSPH_FAIL(VSPH_EIO, "%s", o->error);
  }
  at += c.state;
  memcpy(buf + at, list, c.manifest), at += c.manifest;
  free(list);
  const uint32_t crc = (uint32_t)crc32(crc32(0L, Z_NULL, 0), buf, (uInt)at);
  memcpy(buf + at, &crc, sizeof crc), at += sizeof crc;
  char tmp[700], path[700];
  snprintf(tmp, sizeof tmp, "%s/checkpoint.bin.tmp", o->dir);
  snprintf(path, sizeof path, "%s/checkpoint.bin", o->dir);
  errno = 0;
  FILE *f = fopen(tmp, "wb");
  int ok = f && fwrite(buf, 1, at, f) == at && fflush(f) == 0 &&
           fsync(fileno(f)) == 0;
  if (f && fclose(f) != 0) ok = 0;
  ok = ok && rename(tmp, path) == 0;
  free(buf);
  if (!ok) {
    const int e = errno;
    remove(tmp);
    snprintf(o->error, sizeof o->error, "cannot write %s: %s", path,
             e ? strerror(e) : "write error");
    VSPH_FAIL(VSPH_EIO, "%s", o->error);
  }
  return VSPH_OK;
}

/* A checkpoint to resume from: its header and state, if @p dir holds one
 * whole, made by these sources with these settings (@p key); else NULL,
 * with why in @p why when there was one ("" when none). Caller frees. */
static unsigned char *checkpoint_read(const char *dir, const char *key,
                                      struct ckpt *c, size_t *state_at,
                                      char *why, size_t wlen) {
  why[0] = '\0';
  char path[4300];
  snprintf(path, sizeof path, "%s/checkpoint.bin", dir);
  struct stat sb;
  if (lstat(path, &sb) != 0) return NULL;
  size_t len = 0;
  unsigned char *buf = (unsigned char *)vsph_files_slurp(path, &len);
  const size_t klen = strlen(key);
  uint64_t kl = 0;
  uint32_t crc = 0;
  const size_t fixed = sizeof CKPT_MAGIC + sizeof kl + sizeof *c + sizeof crc;
  if (!buf || len < fixed) {
    snprintf(why, wlen, "it cannot be read or is cut short");
  } else {
    memcpy(&crc, buf + len - sizeof crc, sizeof crc);
    memcpy(&kl, buf + sizeof CKPT_MAGIC, sizeof kl);
    if (memcmp(buf, CKPT_MAGIC, sizeof CKPT_MAGIC))
      snprintf(why, wlen, "it is not a vsph checkpoint");
    else if (crc != (uint32_t)crc32(crc32(0L, Z_NULL, 0), buf,
                                    (uInt)(len - sizeof crc)))
      snprintf(why, wlen, "it is damaged (its CRC-32 does not match)");
    else if (kl != klen || len < fixed + klen ||
             memcmp(buf + sizeof CKPT_MAGIC + sizeof kl, key, klen))
      snprintf(why, wlen,
               "it was made by other sources or with other settings");
    else {
      const size_t at = sizeof CKPT_MAGIC + sizeof kl + klen;
      memcpy(c, buf + at, sizeof *c);
      if (c->version != CKPT_VERSION ||
          c->state + c->manifest != len - fixed - klen)
        snprintf(why, wlen, "its layout is not this version's");
      *state_at = at + sizeof *c;
    }
  }
  if (why[0]) {
    free(buf);
    return NULL;
  }
  return buf;
}

/* A resumed folder: key.txt and run.json go (nothing may vouch for it
 * while it runs), the live files must hold at least what the checkpoint
 * saw, and snapshots past it go. */
static int resume_dir(struct vsph_folder *fo, const struct ckpt *c,
                      const char *manifest, const char *profile_name, char *why,
                      size_t wlen) {
  char path[4300];
  static const char *const first[] = {"key.txt", "run.json"};
  for (int k = 0; k < 2; k++) {
    snprintf(path, sizeof path, "%s/%s", fo->dir, first[k]);
    if (remove(path) != 0 && errno != ENOENT)
      VSPH_FAIL(VSPH_EIO, "cannot remove %s: %s", path, strerror(errno));
  }
  for (uint64_t k = c->nsnap; k < 10000; k++) {
    int gone = 0; /* the snapshot and its walls, past the checkpoint's */
    for (int w = 0; w < 2; w++) {
      snprintf(path, sizeof path, "%s/%s_%04llu.vtp", fo->dir,
               w ? "walls" : "snap", (unsigned long long)k);
      if (remove(path) != 0) {
        if (errno == ENOENT) {
          gone += !w;
          continue;
        }
        VSPH_FAIL(VSPH_EIO, "cannot remove %s: %s", path, strerror(errno));
      }
    }
    if (gone) break;
  }
  /* every file as the checkpoint saw it (the live tables may have grown:
   * their first bytes count, the rest is cut), nothing else */
  const char *const grow[] = {"energy.csv", profile_name, "snapshots.pvd",
                              "probes.csv", NULL};
  if (vsph_folder_manifest_holds(fo, manifest, grow, CKPT_SKIP, why, wlen) != 1)
    return VSPH_EINVAL;
  return vsph_folder_clear_tmp(fo);
}

/* The time loop: rows and snapshots as the driver says they are due, each
 * bit of run->due cleared once its output is written; a checkpoint every
 * Solver:checkpoint_s of wall time and when stopped. A stop is seen
 * before each output, within a snapshot's sums and compression, between
 * the stages of a step and after it: the checkpoint then keeps the
 * outputs still due, and a resumed run writes them first. */
/* The CPU time a run spends: the process's when the run has it to itself;
 * inside an active parallel region (a report running several runs at once,
 * one per thread, their own regions nested and so inactive) the calling
 * thread's, since the process's clock counts the other runs too. */
static double run_cpu_s(void) {
  return omp_in_parallel() ? vsph_sysinfo_thread_cpu_s() : vsph_sysinfo_cpu_s();
}

static int time_loop(struct outputs *o, struct vsph_run *run,
                     struct vsph_references_scene *ref, const char *key,
                     const struct vsph_rundir_opts *opts,
                     struct vsph_rundir_result *res) {
  FILE *progress = opts->progress;
  /* on a terminal one line rewritten in place every 0.5 s; else (a log) a
   * line every 2 s */
  const int tty = progress && isatty(fileno(progress));
  const double every = tty ? 0.5 : 2.0;
  vsph_sysinfo_load(res->load[0]);
  const double t0 = omp_get_wtime(), c0 = run_cpu_s();
  const double wall0 = res->wall_s, cpu0 = res->cpu_s; /* earlier segments */
  const double sim0 = vsph_run_time(run);
  const size_t step0 = vsph_run_steps(run);
  double last = t0, saved = t0;
  const double ckpt_every = run->props.checkpoint_s;
  /* what stops the run: opts->stop (a signal), or in tests stop_after,
   * raised through a flag of its own where opts->stop_in says */
  volatile sig_atomic_t hook = 0;
  const volatile sig_atomic_t *stop = opts->stop_after ? &hook : opts->stop;
  run->integ->stop = stop; /* a long step stops between stages */
  int st = VSPH_OK;
  for (;;) {
    const int after =
        opts->stop_after && vsph_run_steps(run) - step0 >= opts->stop_after;
    if (after && (opts->stop_in & run->due & VSPH_RUN_ROW)) hook = 1;
    if ((run->due & VSPH_RUN_ROW) && !(stop && *stop)) {
      if ((st = write_row(o, run, ref))) break;
      run->due &= ~(unsigned)VSPH_RUN_ROW;
    }
    if (after && (opts->stop_in & run->due & VSPH_RUN_SNAPSHOT)) hook = 1;
    if (run->due & VSPH_RUN_SNAPSHOT) {
      /* stopped before or within it, nothing is written and it stays due */
      const int w = write_snapshot(o, run, stop);
      if (w == VSPH_OK) run->due &= ~(unsigned)VSPH_RUN_SNAPSHOT;
      if (w && w != VSPH_EINTR) {
        st = w;
        break;
      }
    }
    if (after && !opts->stop_in) hook = 1;
    const int stopped = stop && *stop;
    /* an ended run whose outputs are all written is done, stop or not */
    if (run->state != VSPH_RUN_RUNNING && !run->due) break;
    double now = omp_get_wtime();
    if (stopped || (ckpt_every > 0 && now - saved >= ckpt_every)) {
      saved = now;
      if ((st = checkpoint_write(o, run, key, res, wall0 + now - t0,
                                 cpu0 + run_cpu_s() - c0)))
        break;
    }
    if (stopped) { /* between steps, outputs maybe still due */
      res->interrupted = 1;
      break;
    }
    if ((st = vsph_run_iterate(run)) == VSPH_EINTR) {
      /* stopped within a step, which was put back: the state is the one
       * after the last step, whose outputs are written */
      st = checkpoint_write(o, run, key, res, wall0 + omp_get_wtime() - t0,
                            cpu0 + run_cpu_s() - c0);
      if (!st) res->interrupted = 1;
      break;
    }
    if (st) break;
    now = omp_get_wtime();
    if (progress && now - last > every) {
      last = now;
      const double t = vsph_run_time(run);
      const double frac = t / run->t_end;
      const double rate = (t - sim0) / (now - t0); /* this process's */
      fprintf(progress,
              "%svsph run: t = %.4g / %g (%.1f%%), step %zu, %.3g pairs/s, "
              "%.0f s elapsed, ETA %.0f s%s",
              tty ? "\r" : "", t, run->t_end, 100 * frac, vsph_run_steps(run),
              run->pairs / (wall0 + now - t0), wall0 + now - t0,
              rate > 0 ? (run->t_end - t) / rate : (double)INFINITY,
              tty ? "\033[K" : "\n");
      fflush(progress);
    }
  }
  run->integ->stop = opts->stop; /* the hook is gone with this frame */
  if (tty && last > t0) fprintf(progress, "\n");
  res->wall_s = wall0 + omp_get_wtime() - t0;
  res->cpu_s = cpu0 + run_cpu_s() - c0;
  vsph_sysinfo_load(res->load[1]);
  return st;
}

static int execute(struct vsph_params *prm, const struct vsph_scene_type *type,
                   const char *key, const struct vsph_rundir_opts *opts,
                   struct vsph_rundir_result *res);

int vsph_rundir_execute(struct vsph_params *prm, const char *scene,
                        const struct vsph_rundir_opts *opts,
                        struct vsph_rundir_result *res) {
  memset(res, 0, sizeof *res);
  const time_t now = time(NULL);
  struct tm utc;
  strftime(res->started, sizeof res->started, "%Y-%m-%dT%H:%M:%SZ",
           gmtime_r(&now, &utc));
  const struct vsph_scene_type *type = vsph_scene_find(scene);
  if (!type)
    VSPH_FAIL(VSPH_EINVAL, "unknown scene '%s' (see vsph scenes)", scene);
  /* the key: the parameters as given, before any is read. Every run
   * seals its folder with it; --cache also skips a run whose seal holds */
  char what[96];
  snprintf(what, sizeof what, "scene %s", type->name);
  char *key = vsph_rundir_key(prm, what);
  if (!key) return VSPH_ENOMEM;
  const int st = execute(prm, type, key, opts, res);
  free(key);
  return st;
}

/* Close the run's files and write run.json; an error (@p st) is recorded
 * in it. */
/* The memory the run's buffers hold: the largest over all its processes
 * (a buffer grows to the most it has needed, so a resumed run's is the
 * larger of the checkpoint's and its own). */
static double run_bytes(const struct vsph_run *run,
                        const struct vsph_rundir_result *res) {
  return fmax((double)vsph_run_bytes(run), res->bytes_before);
}

static int finish(struct outputs *o, struct vsph_run *run,
                  const struct vsph_rundir_opts *opts,
                  const struct vsph_rundir_result *res, int st, char **text) {
  st = live_close(o, &o->csv, "energy.csv", st);
  st = live_close(o, &o->profile, o->profile_name, st);
  st = live_close(o, &o->probes, "probes.csv", st);
  if (o->pvd.f) {
    const int c = vsph_vtk_pvd_close(&o->pvd);
    if (c && !o->error[0])
      snprintf(o->error, sizeof o->error, "cannot write %s/snapshots.pvd",
               res->dir);
    if (!st) st = c;
  }
  /* an ended run's run.json is written after its seal (the caller's):
   * here only its text; an error or an interruption is written at once */
  const int final = !st && !res->interrupted;
  const int js =
      write_run_json(run, opts, res, run_bytes(run, res),
                     st ? (o->error[0] ? o->error : "a write failed") : NULL,
                     final ? text : NULL);
  return st ? st : js;
}

/* The run laid out afresh (a checkpoint not used after all), with the
 * references of its own scene (they keep a pointer to it). */
static int relayout(const struct vsph_run_props *rp,
                    const struct vsph_scene *sc, struct vsph_run **run,
                    struct vsph_references_scene **ref) {
  vsph_references_scene_free(*ref);
  *ref = NULL;
  vsph_run_free(*run);
  *run = NULL;
  const int st = vsph_run_alloc(rp, sc, run);
  if (st) return st;
  if (!(*ref = vsph_references_scene_alloc(&(*run)->scene))) return VSPH_ELIB;
  return VSPH_OK;
}

/* The run resumed from this run's checkpoint in res->dir, where one fits
 * (its state into *@p run, the live files' lengths it saw into @p keep,
 * the segment count, times and start into @p res), else the folder
 * cleared to start afresh (@p keep left at -1); either way
 * used_parameters.yml written with this process's parameters. */
static int resume_or_start(struct vsph_folder *fo, struct outputs *o,
                           struct vsph_params *prm, const char *key,
                           const struct vsph_run_props *rp,
                           const struct vsph_scene *sc, struct vsph_run **run,
                           struct vsph_references_scene **ref, FILE *progress,
                           struct vsph_rundir_result *res, long keep[4]) {
  int st = VSPH_OK;
  /* a checkpoint of this very run: resume from it */
  struct ckpt c;
  size_t state_at = 0;
  char why[200];
  unsigned char *ck =
      checkpoint_read(res->dir, key, &c, &state_at, why, sizeof why);
  if (ck && (st = vsph_run_unpack(*run, ck + state_at, (size_t)c.state))) {
    /* not this run's after all: lay it out afresh */
    snprintf(why, sizeof why, "its state does not fit this run");
    free(ck);
    ck = NULL;
    if ((st = relayout(rp, sc, run, ref))) return st;
  }
  char *manifest =
      ck ? strndup((const char *)ck + state_at + c.state, (size_t)c.manifest)
         : NULL;
  const int moved =
      ck && (!manifest ||
             resume_dir(fo, &c, manifest, o->profile_name, why, sizeof why));
  if (ck && !manifest) snprintf(why, sizeof why, "out of memory");
  free(manifest);
  if (moved) {
    free(ck); /* (the run's state was restored: lay it out afresh) */
    ck = NULL;
    if ((st = relayout(rp, sc, run, ref))) return st;
  }
  if (why[0]) /* said even when quiet: an hour's work may be lost */
    fprintf(progress ? progress : stderr,
            "vsph run: %s/checkpoint.bin is not used (%s): "
            "starting over\n",
            res->dir, why);
  if (ck) {
    keep[0] = (long)c.csv;
    keep[1] = (long)c.profile;
    keep[2] = (long)c.pvd;
    keep[3] = (long)c.probes;
    o->nsnap = (size_t)c.nsnap;
    res->segments = (size_t)c.segments + 1;
    res->wall_s = c.wall_s;
    res->cpu_s = c.cpu_s;
    res->bytes_before = c.bytes;
    memcpy(res->started, c.started, sizeof res->started);
    res->started[sizeof res->started - 1] = '\0';
    free(ck);
    /* the parameters of this process (Solver:checkpoint_s may differ) */
    return write_used(prm, res->dir);
  } else {
    res->segments = 1;
    if ((st = vsph_folder_clear(fo, NULL))) return st;
    return write_used(prm, res->dir);
  }
}

/* The run's end, as its outcome @p st says: its figures into @p res, its
 * checkpoint gone (an ended run), run.json sealed and written (a lost
 * write never ends as "ok"), and a line said. Returns the status. */
static int end_run(struct outputs *o, struct vsph_folder *fo,
                   struct vsph_run *run, const char *key,
                   const struct vsph_rundir_opts *opts,
                   struct vsph_rundir_result *res, int st) {
  FILE *progress = opts->progress;
  res->unstable = run->state == VSPH_RUN_UNSTABLE;
  res->unstable_time = run->t_unstable;
  snprintf(res->reason, sizeof res->reason, "%s", run->reason);
  res->steps = vsph_run_steps(run);
  res->t = vsph_run_time(run);
  res->pairs = run->pairs;
  /* an ended run: its checkpoint (and any temporary left by a process
   * killed while writing one) goes before anything can call it ok */
  char path[700];
  static const char *const gone[] = {"checkpoint.bin", "checkpoint.bin.tmp"};
  for (int k = 0; k < 2 && !st && !res->interrupted; k++) {
    snprintf(path, sizeof path, "%s/%s", res->dir, gone[k]);
    if (remove(path) != 0 && errno != ENOENT) {
      snprintf(o->error, sizeof o->error, "cannot remove %s: %s", path,
               strerror(errno));
      vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "%s", o->error);
      st = VSPH_EIO;
    }
  }
  /* run.json: its status says what became of the run, and a lost write
   * never ends as "ok". An ended run's is sealed first and written after
   * (a process killed between the two leaves a broken seal and no
   * run.json, never an "ok" the seal does not vouch for) */
  char *json = NULL;
  st = finish(o, run, opts, res, st, &json);
  if (!st && res->interrupted) st = VSPH_EINTR;
  if (!st && json &&
      (st = vsph_folder_seal_with(fo, key, NULL, "run.json", json))) {
    snprintf(o->error, sizeof o->error, "cannot seal %s (key.txt)", res->dir);
    /* unsealed: say so if the disk still lets us (never "ok") */
    write_run_json(run, opts, res, run_bytes(run, res), o->error, NULL);
  }
  if (!st && json) st = vsph_files_write(res->dir, "run.json", json);
  free(json);
  if (!st && progress) {
    if (res->unstable)
      fprintf(progress,
              "vsph run: unstable at t = %.6g: %s (output kept in %s)\n",
              res->unstable_time, res->reason, res->dir);
    else
      fprintf(progress, "vsph run: done, %zu steps in %.2f s (%.3g pairs/s)\n",
              res->steps, res->wall_s, res->pairs / res->wall_s);
  }
  return st;
}

/* The run's props and scene read from @p prm into @p rp and @p sc; an
 * unknown parameter is refused (VSPH_EINVAL, with a hint). */
static int read_settings(struct vsph_params *prm,
                         const struct vsph_scene_type *type,
                         struct vsph_run_props *rp, struct vsph_scene *sc) {
  int st = vsph_run_props_for_scene(rp, type, prm);
  if (!st) st = vsph_scene_init(sc, type, prm);
  if (st) return st;
  const char *unused = vsph_params_unused(prm);
  if (unused) {
    char hint[1024];
    vsph_params_hint(prm, unused, hint, sizeof hint);
    VSPH_FAIL(VSPH_EINVAL, "unknown parameter '%s'%s", unused, hint);
  }
  return VSPH_OK;
}

/* The run's folder into res->dir: --out's (opts->dir), or
 * vsph-out/SCENE-METHOD-RES; a name too long is refused (VSPH_EINVAL). */
static int name_folder(const struct vsph_scene_type *type,
                       const struct vsph_run_props *rp,
                       const struct vsph_rundir_opts *opts,
                       struct vsph_rundir_result *res) {
  if (opts->dir && strlen(opts->dir) >= sizeof res->dir - 64)
    VSPH_FAIL(VSPH_EINVAL,
              "--out: the folder's name is too long (%zu characters; at most "
              "%zu)",
              strlen(opts->dir), sizeof res->dir - 65);
  if (opts->dir)
    snprintf(res->dir, sizeof res->dir, "%s", opts->dir);
  else
    snprintf(res->dir, sizeof res->dir, "vsph-out/%s-%s-%zu", type->name,
             vsph_run_method(rp), rp->res);
  return VSPH_OK;
}

/* The live outputs of @p o opened: energy.csv, snapshots.pvd (with
 * snapshots), the profile (@p with_profile: the cavity's centreline.csv,
 * a channel's profile.csv) and probes.csv (with probes); each new, or a
 * resumed run's cut back to the bytes @p keep its checkpoint saw (energy,
 * profile, pvd, probes). */
static int open_live(struct outputs *o, const struct vsph_run_props *rp,
                     int cavity, int with_profile, const long keep[4]) {
  int st = VSPH_OK;
  o->csv = live_open(o, "energy.csv",
                     "t,Ek,Ep,Ec,P_visc,P_delta,residual,Px,Py,Lz,dEk_dt,"
                     "Ek_ref,dEk_ref,Em_ref,dEm_ref,u_err,u_err_rel,v_rms\n",
                     keep[0], &st);
  if (st) return st;
  if (rp->snapshots > 0 &&
      (st = keep[0] < 0 ? vsph_vtk_pvd_open(&o->pvd, o->dir)
                        : vsph_vtk_pvd_reopen(&o->pvd, o->dir, keep[2])))
    return st;
  if (with_profile &&
      !(o->profile =
            live_open(o, o->profile_name,
                      cavity ? "t,line,s,vel,vel_ghia\n" : "t,y,u,u_ref,n\n",
                      keep[1], &st)))
    return st;
  if (rp->probe_points > 0 &&
      !(o->probes = live_open(
            o, "probes.csv", "t,probe,x,y,z,u,v,w,p,rho,fill\n", keep[3], &st)))
    return st;
  return st;
}

/* The run's figures into @p res, and its first lines said on @p progress
 * (if any): what runs, and from where a resumed run goes on. */
static void say_start(FILE *progress, const struct vsph_scene_type *type,
                      const struct vsph_run_props *rp,
                      const struct vsph_run *run, int resumed,
                      struct vsph_rundir_result *res) {
  res->n_particles = run->n_fluid;
  res->h = run->h;
  res->dx = run->dx;
  res->c0 = run->scene.c0;
  res->mu = run->scene.mu;
  if (!progress) return;
  fprintf(progress,
          "vsph run: %s, %s, %s, %zu particles, h = %.4g, c0 = %.4g, "
          "t_end = %g -> %s\n",
          type->name, vsph_run_method(rp), rp->ktype->name, run->n_fluid,
          run->h, run->scene.c0, run->t_end, res->dir);
  if (resumed)
    fprintf(progress,
            "vsph run: resuming from its checkpoint at t = %.6g, step %zu "
            "(process %zu of this run)\n",
            vsph_run_time(run), vsph_run_steps(run), res->segments);
}

static int execute(struct vsph_params *prm, const struct vsph_scene_type *type,
                   const char *key, const struct vsph_rundir_opts *opts,
                   struct vsph_rundir_result *res) {
  struct vsph_run_props rp;
  struct vsph_scene sc;
  int st = read_settings(prm, type, &rp, &sc);
  if (!st) st = name_folder(type, &rp, opts, res);
  if (st) return st;
  if (opts->cache && vsph_rundir_key_matches(res->dir, key)) {
    res->cached = 1;
    if (opts->progress)
      fprintf(opts->progress,
              "vsph run: %s is cached (its key.txt holds): not run again\n",
              res->dir);
    return VSPH_OK;
  }
  /* the folder judged before the run is laid out: a refusal is quick */
  if ((st = vsph_folder_judge(res->dir, &vsph_folder_scene_run))) return st;
  struct vsph_run *run = NULL;
  if ((st = vsph_run_alloc(&rp, &sc, &run))) return st;
  struct vsph_references_scene *ref = vsph_references_scene_alloc(&run->scene);
  if (!ref) {
    vsph_run_free(run);
    return VSPH_ELIB;
  }
  /* Only now, with every input checked, claim the folder (a lock, and a
   * folder that is new, empty or this kind's: a refused run changes
   * nothing) */
  struct vsph_folder fo = {.fd = -1};
  struct outputs o = {.dir = res->dir, .fo = &fo};
  if (opts->writing) *opts->writing = 1; /* from here a stop keeps data */
  if ((st = vsph_folder_claim(&fo, res->dir, &vsph_folder_scene_run)))
    goto done;
  const int cavity = type == &vsph_cavity_type;
  o.profile_name = cavity ? "centreline.csv" : "profile.csv";
  const int with_profile =
      rp.snapshots > 0 && (cavity || vsph_scene_is_channel(type));
  long keep[4] = {-1, -1, -1, -1};
  FILE *progress = opts->progress;
  if ((st = resume_or_start(&fo, &o, prm, key, &rp, &sc, &run, &ref, progress,
                            res, keep)))
    goto done;
  if ((st = open_live(&o, &rp, cavity, with_profile, keep))) goto done;
  say_start(progress, type, &rp, run, keep[0] >= 0, res);
  st = time_loop(&o, run, ref, key, opts, res);
  st = end_run(&o, &fo, run, key, opts, res, st);
done:
  if (o.csv) fclose(o.csv);
  if (o.profile) fclose(o.profile);
  if (o.probes) fclose(o.probes);
  if (o.pvd.f) fclose(o.pvd.f);
  vsph_folder_release(&fo);
  vsph_references_scene_free(ref);
  vsph_run_free(run);
  return st;
}
