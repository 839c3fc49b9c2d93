/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "archive.h"

#include <cjson/cJSON.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <zlib.h>

#include "../common/consts.h"
#include "../common/params.h"
#include "../common/status.h"
#include "../io/files.h"
#include "../io/json.h"
#include "../io/vtk.h"
#include "folder.h"
#include "jobs.h"

/* A run's file the archive keeps: all but snapshots, their index and a
 * checkpoint (bulk, and not what the report's parts read). */
static int kept_file(const char *name) {
  return strncmp(name, "snap_", 5) && strncmp(name, "walls_", 6) &&
         strcmp(name, "snapshots.pvd") && strncmp(name, "checkpoint.bin", 14);
}

/* A name the index can hold as one TSV field: printable ASCII, no blank. */
static int plain_name(const char *s) {
  for (; *s; s++)
    if ((unsigned char)*s < 0x21 || (unsigned char)*s > 0x7e) return 0;
  return 1;
}

/* The key part of folder @p dir's key.txt (all before "files:\n") into
 * *key and its files section into *files (one allocation: free *key), or
 * VSPH_EIO. */
static int key_of(const char *dir, char **key, const char **files) {
  char path[4400];
  snprintf(path, sizeof path, "%s/key.txt", dir);
  struct stat sb;
  *key = NULL;
  if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return VSPH_EIO;
  char *text = vsph_files_slurp(path, NULL);
  char *f = text ? strstr(text, "files:\n") : NULL;
  if (!f || (f != text && f[-1] != '\n')) {
    free(text);
    return VSPH_EIO;
  }
  *f = '\0';
  *key = text;
  *files = f + 7;
  return VSPH_OK;
}

/* A folder's kind when it is a run's or an archive entry's (a real
 * folder, not a link), else NULL. */
static const struct vsph_folder_kind *entry_kind(const char *dir) {
  struct stat sb;
  if (lstat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode)) return NULL;
  const struct vsph_folder_kind *k = vsph_folder_kind_of(dir);
  return k == &vsph_folder_scene_run || k == &vsph_folder_shear_test ? k : NULL;
}

/* The files of an entry, read from its run's folder as its key.txt lists
 * them (the kept ones), each checked against its listed size and CRC-32:
 * what is written is what the seal vouched for. */
struct copy {
  size_t n;
  char name[32][256];
  char *text[32];
  size_t nframe; /* the snapshots kept as frames, with their fields */
  char frame[64][32];
  unsigned fields[64];
};

/* The VSPH_JOBS_FRAME_* @p fr asks for run @p name (0: none). */
static unsigned frames_wanted(const struct vsph_archive_frames *fr,
                              const char *name) {
  for (size_t k = 0; fr && k < fr->n; k++)
    if (!strcmp(fr->name[k], name)) return fr->want[k];
  return 0u;
}

/* Snapshot NNNN of "snap_NNNN.vtp" (a name of exactly that form), or -1. */
static int snap_index(const char *name) {
  int k, used = 0;
  if (strncmp(name, "snap_", 5) || strlen(name) != 13 ||
      sscanf(name, "snap_%4d.vtp%n", &k, &used) != 1 || used != 13 || k < 0)
    return -1;
  return k;
}

/* The frame fields (VSPH_VTK_FRAME_*) snapshot @p k of @p last keeps
 * for @p want (VSPH_JOBS_FRAME_*). */
static unsigned frame_fields(unsigned want, int k, int last) {
  unsigned f = 0u;
  if ((want & VSPH_JOBS_FRAME_FIRST) && k == 0) f |= VSPH_VTK_FRAME_SCALARS;
  if ((want & VSPH_JOBS_FRAME_LAST) && k == last) f |= VSPH_VTK_FRAME_SCALARS;
  if (want & VSPH_JOBS_FRAME_ALL) f |= VSPH_VTK_FRAME_VELOCITY;
  return f;
}

static void copy_free(struct copy *c) {
  for (size_t k = 0; k < c->n; k++) free(c->text[k]);
  c->n = 0;
  c->nframe = 0;
}

/* The snapshots a seal's list of files @p files names (NULL: none), and
 * the last of them into *last (-1: none). */
static size_t listed_snapshots(const char *files, int *last) {
  size_t n = 0;
  *last = -1;
  for (const char *line = files; line && *line;) {
    const char *end = strchr(line, '\n');
    char name[256];
    const int k = sscanf(line, "%255s", name) == 1 ? snap_index(name) : -1;
    if (k >= 0) {
      n++;
      *last = k > *last ? k : *last;
    }
    line = end ? end + 1 : NULL;
  }
  return n;
}

/* 1 when every kept file of @p src was read as listed in @p files, and
 * each snapshot @p want asks for found as listed (its frame is made as
 * the entry is stored); 0 with why otherwise. */
static int copy_read(const char *src, const char *files, unsigned want,
                     const struct vsph_folder_kind *kind, struct copy *c,
                     char *why, size_t wlen) {
  c->n = 0;
  c->nframe = 0;
  int last = -1;
  if (want) listed_snapshots(files, &last);
  for (const char *line = files; *line;) {
    const char *end = strchr(line, '\n');
    char name[256];
    size_t size;
    unsigned long crc;
    int used = 0;
    if (!end ||
        sscanf(line, "%255s %zu %lx%n", name, &size, &crc, &used) != 3 ||
        line + used != end) {
      snprintf(why, wlen, "its key.txt's list of files is damaged");
      return 0;
    }
    line = end + 1;
    const int snap = want ? snap_index(name) : -1;
    const unsigned ff = snap >= 0 ? frame_fields(want, snap, last) : 0u;
    if (ff) { /* a frame's snapshot: as its seal lists it (binary) */
      char path[4700];
      snprintf(path, sizeof path, "%s/%s", src, name);
      size_t len = 0;
      char *bytes = vsph_files_slurp(path, &len);
      const int ok =
          bytes && len == size &&
          crc32(crc32(0L, Z_NULL, 0), (const Bytef *)bytes, (uInt)len) == crc;
      free(bytes);
      if (!ok) {
        snprintf(why, wlen, "%.255s is not as its seal lists it", name);
        return 0;
      }
      if (c->nframe == sizeof c->frame / sizeof *c->frame) {
        snprintf(why, wlen,
                 "more than %zu of its snapshots are asked as frames",
                 sizeof c->frame / sizeof *c->frame);
        return 0;
      }
      struct vsph_vtk_snapshot s; /* readable as a frame's source */
      const int rd = vsph_vtk_read(path, &s);
      const int framed = !rd && s.frame_bits;
      vsph_vtk_snapshot_free(&s);
      if (rd || framed) {
        snprintf(why, wlen, "%.255s cannot be read as a snapshot", name);
        return 0;
      }
      snprintf(c->frame[c->nframe], sizeof c->frame[c->nframe], "%s", name);
      c->fields[c->nframe++] = ff;
      continue;
    }
    if (!kept_file(name) || kind->owns(name) != VSPH_FOLDER_FILE) continue;
    if (c->n == sizeof c->text / sizeof *c->text) {
      snprintf(why, wlen, "its key.txt lists too many files");
      return 0;
    }
    char path[4700];
    snprintf(path, sizeof path, "%s/%s", src, name);
    size_t len = 0;
    char *text = vsph_files_slurp(path, &len);
    if (!text || len != size || strlen(text) != len ||
        crc32(crc32(0L, Z_NULL, 0), (const Bytef *)text, (uInt)len) != crc) {
      free(text);
      snprintf(why, wlen, "%.255s is not as its seal lists it", name);
      return 0;
    }
    snprintf(c->name[c->n], sizeof c->name[c->n], "%s", name);
    c->text[c->n++] = text;
  }
  return 1;
}

/* Remove archive entry @p dir (a folder of @p kind that vsph wrote): its
 * files, marker and lock, then the folder. */
static int remove_entry(const char *dir, const struct vsph_folder_kind *kind) {
  if (!kind) VSPH_FAIL(VSPH_EIO, "%s is not an archive entry", dir);
  struct vsph_folder f;
  int st = vsph_folder_claim(&f, dir, kind);
  if (st) return st;
  st = vsph_folder_clear(&f, NULL);
  char path[4400];
  for (int k = 0; k < 2 && !st; k++) {
    snprintf(path, sizeof path, "%s/%s", dir,
             k ? VSPH_FOLDER_LOCK : VSPH_FOLDER_MARKER);
    if (remove(path) != 0 && errno != ENOENT) st = VSPH_EIO;
  }
  vsph_folder_release(&f);
  if (!st && rmdir(dir) != 0) st = VSPH_EIO;
  if (st) VSPH_FAIL(VSPH_EIO, "cannot remove the old entry %s", dir);
  return VSPH_OK;
}

/* Entry @p dst of the run read into @p c, sealed under @p key: built
 * beside it as DST.new, then swapped in; the old one, if any, goes only
 * once the new one is whole and in place. */
static int store_one(const char *dst, const char *key,
                     const struct vsph_folder_kind *kind, const struct copy *c,
                     const char *src, int bits) {
  char fresh[4500], old[4500];
  snprintf(fresh, sizeof fresh, "%s.new", dst);
  snprintf(old, sizeof old, "%s.old", dst);
  struct vsph_folder f;
  int st = vsph_folder_claim(&f, fresh, kind);
  if (st) return st;
  for (size_t k = 0; k < c->n && !st; k++)
    st = vsph_files_write(fresh, c->name[k], c->text[k]);
  /* the frames, and their snapshots.pvd: ParaView's time series, and
   * where a report finds them */
  struct vsph_vtk_pvd pvd = {0};
  if (!st && c->nframe) st = vsph_vtk_pvd_open(&pvd, fresh);
  for (size_t k = 0; k < c->nframe && !st; k++) {
    char path[4500];
    snprintf(path, sizeof path, "%s/%s", src, c->frame[k]);
    struct vsph_vtk_snapshot s;
    st = vsph_vtk_read(path, &s);
    if (!st)
      st = vsph_vtk_write_frame(fresh, c->frame[k], &s, bits, c->fields[k]);
    if (!st) st = vsph_vtk_pvd_add(&pvd, s.t, c->frame[k]);
    vsph_vtk_snapshot_free(&s);
  }
  const int pst = vsph_vtk_pvd_close(&pvd);
  if (!st) st = pst;
  if (!st) st = vsph_folder_seal(&f, key, NULL);
  vsph_folder_release(&f);
  if (st) return st;
  const struct vsph_folder_kind *was = entry_kind(dst);
  if (was && rename(dst, old) != 0)
    VSPH_FAIL(VSPH_EIO, "cannot move %s aside: %s", dst, strerror(errno));
  if (rename(fresh, dst) != 0)
    VSPH_FAIL(VSPH_EIO, "cannot move %s into place: %s", fresh,
              strerror(errno));
  return was ? remove_entry(old, was) : VSPH_OK;
}

static int by_name(const void *a, const void *b) {
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The sub-folders of @p dir, sorted (NULL-terminated; caller frees each
 * and the list), or NULL. */
static char **subdirs(const char *dir, size_t *n) {
  *n = 0;
  DIR *d = opendir(dir);
  if (!d) return NULL;
  size_t cap = 16;
  char **v = malloc(cap * sizeof *v);
  for (struct dirent *e; v && (e = readdir(d));) {
    if (e->d_name[0] == '.') continue;
    char path[4400];
    snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
    struct stat sb;
    if (lstat(path, &sb) != 0 || !S_ISDIR(sb.st_mode)) continue;
    if (*n + 1 >= cap) {
      char **w = realloc(v, 2 * cap * sizeof *v);
      if (!w) break;
      v = w;
      cap *= 2;
    }
    if (!(v[*n] = strdup(e->d_name))) break;
    (*n)++;
  }
  closedir(d);
  if (v) {
    qsort(v, *n, sizeof *v, by_name);
    v[*n] = NULL;
  }
  return v;
}

static void free_list(char **v, size_t n) {
  for (size_t k = 0; v && k < n; k++) free(v[k]);
  free(v);
}

/* A whole entry of the archive's runs/ folder, read for the index and
 * the summary: its kind, its key (free it), the version and source hash
 * its key names, its settings, and its run.json (cJSON_Delete it; NULL
 * when unreadable). */
struct entry {
  const struct vsph_folder_kind *kind;
  char *key;
  char version[32], hash[64];
  const char *settings;
  cJSON *run;
};

/* Entry @p name of @p runs into @p e; 0 when it is not (or no longer) a
 * whole entry, its seal not holding. */
static int entry_read(const char *runs, const char *name, struct entry *e) {
  char dir[4400], path[4500];
  snprintf(dir, sizeof dir, "%s/%s", runs, name);
  memset(e, 0, sizeof *e);
  const char *files;
  e->kind = entry_kind(dir);
  if (!e->kind || key_of(dir, &e->key, &files) ||
      vsph_folder_verify(dir, e->kind, e->key, NULL, NULL, 0) != 1) {
    free(e->key);
    e->key = NULL;
    return 0;
  }
  snprintf(e->version, sizeof e->version, "?");
  snprintf(e->hash, sizeof e->hash, "?");
  sscanf(e->key, "vsph %31s %63s", e->version, e->hash);
  const char *nl = strchr(e->key, '\n');
  e->settings = nl ? nl + 1 : "";
  snprintf(path, sizeof path, "%s/run.json", dir);
  e->run = vsph_json_read(path);
  return 1;
}

static void entry_free(struct entry *e) {
  free(e->key);
  cJSON_Delete(e->run);
}

/* index.tsv of the archive's entries. */
static int write_index(const char *archive, const char *runs,
                       const char *commit) {
  size_t n = 0;
  char **names = subdirs(runs, &n);
  if (!names) VSPH_FAIL(VSPH_EIO, "cannot list %s", runs);
  char *text = NULL;
  size_t len = 0;
  FILE *m = open_memstream(&text, &len);
  if (!m) {
    free_list(names, n);
    VSPH_FAIL(VSPH_ENOMEM, "cannot build %s/index.tsv", archive);
  }
  fprintf(m,
          "# vsph %s run archive: each entry runs/NAME is sealed (key.txt) "
          "under the key of the run it keeps\n"
          "name\tkind\tstatus\tversion\tsource_hash\tcommit\tsettings\twall_"
          "s\tsteps\tparticles\n",
          VSPH_VERSION);
  for (size_t k = 0; k < n; k++) {
    struct entry en;
    /* a whole entry whose name a TSV field can hold (as the store asks) */
    if (!plain_name(names[k]) || !entry_read(runs, names[k], &en)) continue;
    const struct vsph_folder_kind *kind = en.kind;
    const char *const version = en.version, *const hash = en.hash;
    cJSON *o = en.run;
    const cJSON *s = o ? cJSON_GetObjectItemCaseSensitive(o, "status") : NULL;
    /* the commit the run recorded, else the caller's for this build's */
    const cJSON *c = o ? cJSON_GetObjectItemCaseSensitive(o, "commit") : NULL;
    const char *made =
        cJSON_IsString(c) && c->valuestring[0] &&
                strcmp(c->valuestring, "unknown") &&
                strlen(c->valuestring) <= 64 && plain_name(c->valuestring)
            ? c->valuestring
        : commit && !strcmp(hash, vsph_source_hash_id) ? commit
                                                       : "unknown";
    fprintf(
        m, "%s\t%s\t%s\t%s\t%s\t%s\t%016llx\t%.6g\t%.0f\t%.0f\n", names[k],
        kind->name,
        cJSON_IsString(s) && plain_name(s->valuestring) ? s->valuestring : "?",
        version, hash, made, vsph_folder_fingerprint(en.settings),
        o ? vsph_json_get_number(o, "wall_s", NAN) : (double)NAN,
        o ? vsph_json_get_number(o, "steps", NAN) : (double)NAN,
        o ? vsph_json_get_number(o, "n_particles", NAN) : (double)NAN);
    entry_free(&en);
  }
  free_list(names, n);
  if (fclose(m) != 0) {
    free(text);
    VSPH_FAIL(VSPH_ENOMEM, "cannot build %s/index.tsv", archive);
  }
  const int st = vsph_files_write(archive, "index.tsv", text);
  free(text);
  return st;
}

/* Judge archive @p archive before anything is written: its top, and each
 * entry of its runs/ a real folder of a run's kind that vsph wrote, with
 * nothing else in it (or the .new or .old of an interrupted store). */
static int judge(const char *archive, const char *runs) {
  int st = vsph_folder_judge(archive, &vsph_folder_archive);
  struct stat sb;
  if (st || lstat(runs, &sb) != 0) return st;
  if (!S_ISDIR(sb.st_mode))
    VSPH_FAIL(VSPH_EINVAL, "%s is not a folder (a link?): not an archive's",
              runs);
  DIR *d = opendir(runs);
  if (!d) VSPH_FAIL(VSPH_EINVAL, "cannot read %s: %s", runs, strerror(errno));
  char bad[600] = "";
  for (struct dirent *e; !bad[0] && (e = readdir(d));) {
    if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
    char path[4500];
    snprintf(path, sizeof path, "%s/%s", runs, e->d_name);
    const struct vsph_folder_kind *k = entry_kind(path);
    if (!k || vsph_folder_judge(path, k) != VSPH_OK)
      snprintf(bad, sizeof bad, "%.300s", path);
  }
  closedir(d);
  if (bad[0])
    VSPH_FAIL(VSPH_EINVAL,
              "%s is not an archive entry vsph wrote (a run's folder with "
              "nothing else in it): nothing was archived",
              bad);
  return VSPH_OK;
}

/* Remove what a store stopped midway left: DST.new and DST.old entries. */
static int clear_leftovers(const char *runs) {
  size_t n = 0;
  char **names = subdirs(runs, &n);
  if (!names) VSPH_FAIL(VSPH_EIO, "cannot list %s", runs);
  int st = VSPH_OK;
  for (size_t k = 0; k < n && !st; k++) {
    const size_t l = strlen(names[k]);
    if (l > 4 && (!strcmp(names[k] + l - 4, ".new") ||
                  !strcmp(names[k] + l - 4, ".old"))) {
      char path[4500];
      snprintf(path, sizeof path, "%s/%s", runs, names[k]);
      st = remove_entry(path, entry_kind(path));
    }
  }
  free_list(names, n);
  return st;
}

/* 1 when entry @p dst holds a frame of every snapshot @p c lists, at
 * @p bits with the fields asked, and no other snapshot. */
static int holds_frames(const char *dst, const struct copy *c, int bits,
                        const char *files) {
  for (size_t k = 0; k < c->nframe; k++) {
    char path[4500];
    snprintf(path, sizeof path, "%s/%s", dst, c->frame[k]);
    struct stat sb;
    if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return 0;
    struct vsph_vtk_snapshot s;
    if (vsph_vtk_read(path, &s)) return 0;
    const int same = s.frame_bits == bits && s.frame_fields == c->fields[k];
    vsph_vtk_snapshot_free(&s);
    if (!same) return 0;
  }
  int last;
  return listed_snapshots(files, &last) == c->nframe; /* and no others */
}

/* Run folder @p dir's start (run.json's date, ISO 8601 UTC, so that two
 * compare as strings) into @p buf; "" when it has none (a shear test). */
static void run_date(const char *dir, char *buf, size_t len) {
  char path[4500];
  snprintf(path, sizeof path, "%s/run.json", dir);
  cJSON *o = vsph_json_read(path);
  const cJSON *d = o ? cJSON_GetObjectItemCaseSensitive(o, "date") : NULL;
  snprintf(buf, len, "%s", cJSON_IsString(d) ? d->valuestring : "");
  cJSON_Delete(o);
}

int vsph_archive_store(const char *report, const char *archive,
                       const char *commit, FILE *progress,
                       struct vsph_archive_counts *counts) {
  return vsph_archive_store_frames(report, archive, commit, NULL, progress,
                                   counts);
}

int vsph_archive_store_frames(const char *report, const char *archive,
                              const char *commit,
                              const struct vsph_archive_frames *frames,
                              FILE *progress,
                              struct vsph_archive_counts *counts) {
  memset(counts, 0, sizeof *counts);
  char src_runs[4200], runs[4200];
  snprintf(src_runs, sizeof src_runs, "%s/runs", report);
  snprintf(runs, sizeof runs, "%s/runs", archive);
  struct stat sb;
  if (lstat(src_runs, &sb) != 0 || !S_ISDIR(sb.st_mode))
    VSPH_FAIL(VSPH_EINVAL, "%s is not a report's runs folder", src_runs);
  int st = judge(archive, runs);
  if (st) return st;
  struct vsph_folder top;
  if ((st = vsph_folder_claim(&top, archive, &vsph_folder_archive))) return st;
  st = judge(archive, runs); /* again, under the lock */
  if (!st) st = vsph_files_mkdir(runs);
  if (!st) st = clear_leftovers(runs);
  size_t n = 0;
  char **names = st ? NULL : subdirs(src_runs, &n);
  if (!st && !names) {
    st = VSPH_EIO;
    vsph_status_report(st, __FILE__, __LINE__, "cannot list %s", src_runs);
  }
  struct copy *c = st ? NULL : calloc(1, sizeof *c);
  if (!st && !c) {
    st = VSPH_ENOMEM;
    vsph_status_report(st, __FILE__, __LINE__, "cannot allocate a copy");
  }
  for (size_t k = 0; k < n && !st; k++) {
    char src[4400], dst[4400];
    snprintf(src, sizeof src, "%s/%s", src_runs, names[k]);
    snprintf(dst, sizeof dst, "%s/%s", runs, names[k]);
    const struct vsph_folder_kind *kind = entry_kind(src);
    if (!kind) continue; /* logs/, or not a run */
    char *key = NULL;
    const char *files = NULL;
    char why[600] = "";
    if (!plain_name(names[k]) || strlen(names[k]) > 200)
      snprintf(why, sizeof why,
               "its name is not plain printable ASCII of at most 200 "
               "characters");
    else if (key_of(src, &key, &files) ||
             vsph_folder_verify(src, kind, key, NULL, why, sizeof why) != 1) {
      if (!why[0]) snprintf(why, sizeof why, "it has not ended (no seal)");
    } else if (copy_read(src, files, frames_wanted(frames, names[k]), kind, c,
                         why, sizeof why)) {
      char *dkey = NULL;
      const char *dfiles = NULL;
      const int same = vsph_folder_verify(dst, kind, key, NULL, NULL, 0) == 1 &&
                       !key_of(dst, &dkey, &dfiles) &&
                       holds_frames(dst, c, frames ? frames->bits : 0, dfiles);
      free(dkey);
      char was[64] = "", now[64] = ""; /* an entry of a later run stays */
      if (!same && entry_kind(dst)) {
        run_date(dst, was, sizeof was);
        run_date(src, now, sizeof now);
      }
      if (same)
        counts->kept++;
      else if (was[0] && now[0] && strcmp(now, was) < 0)
        snprintf(why, sizeof why,
                 "it began %s, before the run its archive entry keeps (%s), "
                 "which stays",
                 now, was);
      else if (!(st = store_one(dst, key, kind, c, src,
                                frames ? frames->bits : 0)))
        counts->stored++;
    }
    copy_free(c);
    if (why[0]) {
      counts->skipped++;
      if (progress)
        fprintf(progress, "vsph report: %s is not archived: %s\n", src, why);
    }
    free(key);
  }
  free(c);
  /* the index anew only when an entry changed (or there is none): a store
   * with nothing new leaves the archive as it was, byte for byte */
  char ipath[4400];
  snprintf(ipath, sizeof ipath, "%s/index.tsv", archive);
  struct stat ib;
  if (!st && (counts->stored > 0 || stat(ipath, &ib) != 0))
    st = write_index(archive, runs, commit);
  free_list(names, n);
  vsph_folder_release(&top);
  return st;
}

/* ------------------------------------------------------------ summary */

/* The next line of baseline.csv text from *@p at whose first field is
 * @p scene, into *@p line and *@p len, *@p at moved past it; 0 when
 * there is none. */
static int next_row(const char **at, const char *scene, const char **line,
                    size_t *len) {
  const size_t sl = strlen(scene);
  for (const char *l = *at; l && *l;) {
    const char *e = strchr(l, '\n');
    const size_t n = e ? (size_t)(e - l) : strlen(l);
    *at = l + n + (e != NULL);
    if (n > sl && !strncmp(l, scene, sl) && l[sl] == ',') {
      *line = l;
      *len = n;
      return 1;
    }
    l = *at;
  }
  return 0;
}

/* Whether fields @p a and @p b (@p na, @p nb bytes) agree: as numbers
 * within the baseline's tolerance, 1e-6 relative plus 1e-9 absolute
 * (tests/check_baseline.c holds the code to it), where both are numbers;
 * else as text. */
static int field_agrees(const char *a, size_t na, const char *b, size_t nb) {
  char fa[64], fb[64];
  double x, y;
  if (na < sizeof fa && nb < sizeof fb) {
    memcpy(fa, a, na), fa[na] = '\0';
    memcpy(fb, b, nb), fb[nb] = '\0';
    if (!vsph_params_parse_number(fa, &x) && !vsph_params_parse_number(fb, &y))
      return fabs(x - y) <=
             VSPH_ARCHIVE_BASELINE_REL * fabs(y) + VSPH_ARCHIVE_BASELINE_ABS;
  }
  return na == nb && !memcmp(a, b, na);
}

/* Whether two baseline.csv rows agree field by field (field_agrees). */
static int row_agrees(const char *a, size_t na, const char *b, size_t nb) {
  for (;;) {
    const char *ea = memchr(a, ',', na), *eb = memchr(b, ',', nb);
    const size_t fa = ea ? (size_t)(ea - a) : na,
                 fb = eb ? (size_t)(eb - b) : nb;
    if (!field_agrees(a, fa, b, fb) || !ea != !eb) return 0;
    if (!ea) return 1;
    a += fa + 1, na -= fa + 1;
    b += fb + 1, nb -= fb + 1;
  }
}

/* @p scene's rows of baseline.csv texts @p then and @p now: -1 when
 * @p now has none, -2 when @p then has none (or is NULL), else 1 when
 * they agree row by row (the same rows in the same order, row_agrees)
 * and 0 when they do not. */
static int scene_rows_agree(const char *then, const char *now,
                            const char *scene) {
  const char *an = now, *at = then, *ln, *lt;
  size_t nn, nt;
  if (!now || !next_row(&an, scene, &ln, &nn)) return -1;
  if (!then || !next_row(&at, scene, &lt, &nt)) return -2;
  for (;;) {
    if (!row_agrees(lt, nt, ln, nn)) return 0;
    const int more_t = next_row(&at, scene, &lt, &nt);
    const int more_n = next_row(&an, scene, &ln, &nn);
    if (more_t != more_n) return 0;
    if (!more_n) return 1;
  }
}

/* Whether @p s can stand for a commit, scene or status in entries.md:
 * 1-63 letters, digits, '.', '_' or '-' (nothing a table cell breaks
 * on). */
static int id_name(const char *s) {
  const size_t n = strlen(s);
  if (n < 1 || n > 63) return 0;
  for (; *s; s++)
    if (!strchr("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                "0123456789._-",
                *s))
      return 0;
  return 1;
}

/* @p s as text of a Markdown table cell into @p m: '|' escaped, line
 * breaks and other control characters as blanks. */
static void md_cell(FILE *m, const char *s) {
  for (; *s; s++) {
    if (*s == '|') fputc('\\', m);
    fputc((unsigned char)*s < 0x20 ? ' ' : *s, m);
  }
}

/* The text of regular file @p path when it is one of at most
 * VSPH_ARCHIVE_READ_MAX bytes (links followed), else NULL: the history's
 * and the baseline's files are small, and an odd one (a FIFO, a device,
 * a huge file) is not waited for or read whole. */
static char *read_small(const char *path) {
  struct stat sb;
  if (stat(path, &sb) != 0 || !S_ISREG(sb.st_mode) ||
      sb.st_size > VSPH_ARCHIVE_READ_MAX)
    return NULL;
  return vsph_files_slurp(path, NULL);
}

/* The commit whose sources hash to @p hash in commits.tsv text @p tsv
 * into @p out (NUL when not found): lines of exactly two tab-separated
 * fields, the second a commit id (id_name); any other line is skipped. */
static void commit_of(const char *tsv, const char *hash, char *out,
                      size_t size) {
  out[0] = '\0';
  const size_t hl = strlen(hash);
  for (const char *l = tsv; l && *l;) {
    const size_t n = strcspn(l, "\n");
    const char *tab = memchr(l, '\t', n);
    if (tab && (size_t)(tab - l) == hl && !strncmp(l, hash, hl)) {
      const size_t cl = n - (size_t)(tab - l) - 1;
      char c[64];
      if (cl < sizeof c && !memchr(tab + 1, '\t', cl)) {
        memcpy(c, tab + 1, cl);
        c[cl] = '\0';
        if (id_name(c)) {
          snprintf(out, size, "%s", c);
          return;
        }
      }
    }
    l += n + (l[n] == '\n');
  }
}

/* The history's baseline.csv of commit @p commit, or NULL. */
static char *baseline_then(const char *history, const char *commit) {
  if (!history || !commit[0]) return NULL;
  char path[4400];
  snprintf(path, sizeof path, "%s/%s.csv", history, commit);
  return read_small(path);
}

/* Whether entry @p name of settings @p settings stands, as the rule says,
 * into @p why. */
static void judge_entry(const struct vsph_archive_judge *jd, const char *name,
                        const char *settings, const char *scene,
                        const char *hash, const char *commit,
                        const char *then_text, const char *now, char *why,
                        size_t size) {
  size_t k = 0;
  while (k < jd->nplan && strcmp(jd->plan_name[k], name)) k++;
  if (k == jd->nplan) {
    snprintf(why, size, "no: the current FULL plan has no run of this name");
    return;
  }
  const char *ps = strchr(jd->plan_key[k], '\n');
  if (!ps || strcmp(ps + 1, settings)) {
    snprintf(why, size,
             "no: the current FULL plan runs it with other settings");
    return;
  }
  const char *then = then_text                            ? then_text
                     : !strcmp(hash, vsph_source_hash_id) ? now
                                                          : NULL;
  const int agree = scene_rows_agree(then, now, scene);
  if (agree == -1)
    snprintf(why, size,
             "unjudged: the current reports/baseline.csv has no rows of %s",
             scene);
  else if (agree == -2)
    snprintf(why, size,
             "unjudged: %s's rows of reports/baseline.csv at %s are not "
             "known (make archive reads them from git)",
             scene, commit[0] ? commit : "its commit");
  else if (!agree)
    snprintf(why, size,
             "no: %s's rows of reports/baseline.csv moved beyond their "
             "tolerance since",
             scene);
  else
    snprintf(why, size, "yes");
}

/* Whether whole entry @p en (named @p name) stands, as the rule says,
 * into @p why ("yes" when it does), and the commit that made it into
 * @p commit (NUL when not known): run.json's (a -dirty one has no
 * baseline of its own in the history), the caller's for this build's
 * sources, or the one the history's commits.tsv (@p tsv) names for its
 * source hash. @p now: the current baseline.csv's text, or NULL. */
static void entry_verdict(const struct vsph_archive_judge *jd, const char *tsv,
                          const char *now, const char *name,
                          const struct entry *en, char *commit, size_t clen,
                          char *why, size_t wlen) {
  const cJSON *o = en->run;
  const cJSON *sc = o ? cJSON_GetObjectItemCaseSensitive(o, "scene") : NULL;
  const cJSON *c = o ? cJSON_GetObjectItemCaseSensitive(o, "commit") : NULL;
  commit[0] = '\0';
  if (cJSON_IsString(c) && id_name(c->valuestring) &&
      strcmp(c->valuestring, "unknown"))
    snprintf(commit, clen, "%s", c->valuestring);
  else if (jd->commit && !strcmp(en->hash, vsph_source_hash_id))
    snprintf(commit, clen, "%s", jd->commit);
  char *then = baseline_then(jd->history, commit);
  if (!then) {
    char h[64];
    commit_of(tsv, en->hash, h, sizeof h);
    if (h[0]) {
      snprintf(commit, clen, "%s", h);
      then = baseline_then(jd->history, commit);
    }
  }
  /* a shear test (vsph contact) is the shear scene under contact SPH
   * (analysis/contact), the numerics the baseline's shear rows pin; its
   * folder has no run.json to name it */
  const char *scene = en->kind == &vsph_folder_shear_test ? "shear"
                      : cJSON_IsString(sc) && id_name(sc->valuestring)
                          ? sc->valuestring
                          : "?";
  judge_entry(jd, name, en->settings, scene, en->hash, commit, then, now, why,
              wlen);
  free(then);
}

/* The current baseline's text and the history's commits.tsv of @p jd
 * (each NULL when absent or not a small regular file). */
static void judge_inputs(const struct vsph_archive_judge *jd, char **now,
                         char **tsv) {
  *now = jd->baseline ? read_small(jd->baseline) : NULL;
  *tsv = NULL;
  if (jd->history) {
    char path[4400];
    snprintf(path, sizeof path, "%s/commits.tsv", jd->history);
    *tsv = read_small(path);
  }
}

int vsph_archive_entry(const char *archive, const char *name, char *dir,
                       size_t len, char **key) {
  *key = NULL;
  char runs[4200];
  snprintf(runs, sizeof runs, "%s/runs", archive);
  struct entry en;
  if (!plain_name(name) || strchr(name, '/') || !entry_read(runs, name, &en))
    return 0;
  const int fits = (size_t)snprintf(dir, len, "%s/%s", runs, name) < len;
  if (fits) {
    *key = en.key; /* (entry_free would free it) */
    en.key = NULL;
  }
  entry_free(&en);
  return fits;
}

int vsph_archive_entry_damage(const char *archive, const char *name, char *why,
                              size_t len) {
  if (!archive || !name || !why || len == 0) return 0;
  why[0] = '\0';
  if (!plain_name(name) || strchr(name, '/')) return 0;
  char dir[4400];
  snprintf(dir, sizeof dir, "%s/runs/%s", archive, name);
  char *key = NULL;
  const char *files = NULL;
  if (key_of(dir, &key, &files)) return 0; /* no entry (or no seal) */
  const int v = vsph_folder_verify(dir, NULL, key, NULL, why, len);
  free(key);
  return v < 0;
}

/* Archive @p archive judged, claimed into @p top, and judged again under
 * the claim (its runs/ folder into @p runs); nothing held on failure. */
static int claim_judged(const char *archive, char runs[4200],
                        struct vsph_folder *top) {
  snprintf(runs, 4200, "%s/runs", archive);
  int st = judge(archive, runs);
  if (st) return st;
  if ((st = vsph_folder_claim(top, archive, &vsph_folder_archive))) return st;
  if ((st = judge(archive, runs))) vsph_folder_release(top);
  return st;
}

int vsph_archive_write_summary(const char *archive, const char *text) {
  char runs[4200];
  struct vsph_folder top;
  int st = claim_judged(archive, runs, &top);
  if (st) return st;
  st = vsph_files_write(archive, "summary.md", text);
  vsph_folder_release(&top);
  return st;
}

int vsph_archive_check(const char *archive) {
  char runs[4200];
  snprintf(runs, sizeof runs, "%s/runs", archive);
  return judge(archive, runs);
}

int vsph_archive_standing(const char *archive,
                          const struct vsph_archive_judge *jd, int *stands) {
  for (size_t k = 0; k < jd->nplan; k++) stands[k] = VSPH_ARCHIVE_ABSENT;
  struct stat sb;
  if (lstat(archive, &sb) != 0 && errno == ENOENT) return VSPH_OK;
  char runs[4200];
  snprintf(runs, sizeof runs, "%s/runs", archive);
  int st = judge(archive, runs);
  if (st) return st;
  char *now, *tsv;
  judge_inputs(jd, &now, &tsv);
  for (size_t k = 0; k < jd->nplan; k++) {
    struct entry en;
    if (!plain_name(jd->plan_name[k]) ||
        !entry_read(runs, jd->plan_name[k], &en))
      continue;
    char commit[64], why[400];
    entry_verdict(jd, tsv, now, jd->plan_name[k], &en, commit, sizeof commit,
                  why, sizeof why);
    stands[k] = !strcmp(why, "yes")            ? VSPH_ARCHIVE_STANDS
                : !strncmp(why, "unjudged", 8) ? VSPH_ARCHIVE_UNJUDGED
                                               : VSPH_ARCHIVE_STALE;
    entry_free(&en);
  }
  free(now);
  free(tsv);
  return VSPH_OK;
}

/* The head of the archive's entries.md into @p m: what it is, when an
 * archived run stands, and the table's header. */
static void summary_head(FILE *m, const struct vsph_archive_judge *jd) {
  fprintf(m,
          "# The FULL run archive\n\n"
          "Written by `vsph report archive` (vsph %s, source hash %s, "
          "commit %s). Each entry `runs/NAME` keeps what the report's parts "
          "read of one run of `vsph report --full`, sealed under the key of "
          "the run it keeps; `index.tsv` lists them.\n\n"
          "## When an archived run still stands\n\n"
          "An archived run stands for the current code when (1) the current "
          "FULL plan asks for a run of its name with its settings, and (2) "
          "its scene's rows of `reports/baseline.csv` agree now with those at "
          "the commit that made it, within their tolerance: each number "
          "within 10^-6 of today's, relative, plus 10^-9 absolute, the "
          "same rows in the same order. `tests/check_baseline.c` holds "
          "those rows (the quick ladder's coarsest runs of each scene and "
          "formulation) to the code at that tolerance, so a change to a "
          "scene's numerics moves them beyond it, and the runs it made "
          "before no longer stand; rounding (another compiler, a "
          "vectorised loop, another machine) moves them far less, and they "
          "stand. A run whose commit or rows then are not known is "
          "unjudged.\n\n",
          VSPH_VERSION, vsph_source_hash_id,
          jd->commit ? jd->commit : "unknown");
  fprintf(m,
          "| run | particles | t reached / t_end (s) | status | steps | wall "
          "(s) | source hash, commit | stands |\n"
          "|---|---:|---|---|---:|---:|---|---|\n");
}

/* The archive's entries summed up: those that stand; those of the current
 * plan, with their wall time; those the plan no longer names. */
struct summary_tally {
  size_t stands, total, others;
  double wall;
};

/* The table's row of entry @p name of @p runs into @p m (none where it is
 * not a whole entry), judged against @p jd (with @p tsv and @p now, see
 * judge_inputs) and counted into @p ty. */
static void summary_row(FILE *m, const struct vsph_archive_judge *jd,
                        const char *tsv, const char *now, const char *runs,
                        const char *name, struct summary_tally *ty) {
  struct entry en;
  if (!entry_read(runs, name, &en)) return;
  const char *const hash = en.hash;
  cJSON *o = en.run;
  const cJSON *s = o ? cJSON_GetObjectItemCaseSensitive(o, "status") : NULL;
  const cJSON *r =
      o ? cJSON_GetObjectItemCaseSensitive(o, "unstable_reason") : NULL;
  char commit[64], why[400];
  entry_verdict(jd, tsv, now, name, &en, commit, sizeof commit, why,
                sizeof why);
  const char *status =
      cJSON_IsString(s) && id_name(s->valuestring) ? s->valuestring : "?";
  fputs("| ", m);
  md_cell(m, name);
  fprintf(m, " | %.0f | %.4g / %.4g | %s",
          vsph_json_get_number(o, "n_particles", NAN),
          vsph_json_get_number(o, "t", NAN),
          vsph_json_get_number(o, "t_end", NAN), status);
  if (cJSON_IsString(r)) {
    fputs(" (", m);
    md_cell(m, r->valuestring);
    fputs(")", m);
  }
  fprintf(m, " | %.0f | %.0f | ", vsph_json_get_number(o, "steps", NAN),
          vsph_json_get_number(o, "wall_s", NAN));
  md_cell(m, hash);
  fprintf(m, ", %s | %s |\n", commit[0] ? commit : "unknown", why);
  ty->stands += !strcmp(why, "yes");
  size_t q = 0; /* the plan's runs only in the tally */
  while (q < jd->nplan && strcmp(jd->plan_name[q], name)) q++;
  if (q < jd->nplan) {
    ty->total++;
    ty->wall += vsph_json_get_number(o, "wall_s", 0.0);
  }
  ty->others += q == jd->nplan;
  entry_free(&en);
}

int vsph_archive_summarise(const char *archive,
                           const struct vsph_archive_judge *jd) {
  char runs[4200];
  struct vsph_folder top;
  int st = claim_judged(archive, runs, &top);
  if (st) return st;
  size_t n = 0;
  char **names = subdirs(runs, &n);
  char *now, *tsv;
  judge_inputs(jd, &now, &tsv);
  char *text = NULL;
  size_t len = 0;
  FILE *m = names ? open_memstream(&text, &len) : NULL;
  if (!m) {
    free_list(names, n);
    free(now);
    free(tsv);
    vsph_folder_release(&top);
    VSPH_FAIL(VSPH_EIO, "cannot list or summarise %s", runs);
  }
  summary_head(m, jd);
  struct summary_tally ty = {0, 0, 0, 0.0};
  for (size_t k = 0; k < n; k++)
    summary_row(m, jd, tsv, now, runs, names[k], &ty);
  fprintf(m,
          "\n%zu of the %zu runs of the current FULL plan are archived "
          "(%.0f s of runs)%s; %zu entries stand. The claims table and the "
          "convergence tables at the paper's resolutions are in summary.md, "
          "which the FULL report's assembly from this archive writes (`make "
          "full-report`: `vsph report assemble --full --from-archive`) "
          "when every run it reads stands here.\n",
          ty.total, jd->nplan, ty.wall,
          ty.others ? ", beside entries the plan no longer names" : "",
          ty.stands);
  free_list(names, n);
  free(now);
  free(tsv);
  if (fclose(m) != 0) {
    free(text);
    vsph_folder_release(&top);
    VSPH_FAIL(VSPH_ENOMEM, "cannot build %s/entries.md", archive);
  }
  st = vsph_files_write(archive, "entries.md", text);
  free(text);
  vsph_folder_release(&top);
  return st;
}
