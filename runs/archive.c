#include "archive.h"

#include <cjson/cJSON.h>
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../io/files.h"
#include "../io/json.h"
#include "folder.h"

/* A run's file the archive keeps: all but snapshots, their index and a
 * checkpoint (bulk, and not what the report's parts read). */
static int kept_file(const char *name) {
  return strncmp(name, "snap_", 5) && strcmp(name, "snapshots.pvd") &&
         strncmp(name, "checkpoint.bin", 14);
}

/* The key part of folder @p dir's key.txt (all before "files:\n"), or
 * NULL. Caller frees. */
static char *key_of(const char *dir) {
  char path[4400];
  snprintf(path, sizeof path, "%s/key.txt", dir);
  struct stat sb;
  if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return NULL;
  char *text = vsph_files_slurp(path, NULL);
  char *files = text ? strstr(text, "files:\n") : NULL;
  if (!files || (files != text && files[-1] != '\n')) {
    free(text);
    return NULL;
  }
  *files = '\0';
  return text;
}

/* Copy run folder @p src (sealed under @p key, of @p kind) into entry
 * @p dst: claimed, cleared, the kept files written, then sealed. */
static int store_one(const char *src, const char *dst, const char *key,
                     const struct vsph_folder_kind *kind) {
  struct vsph_folder f;
  int st = vsph_folder_claim(&f, dst, kind);
  if (st) return st;
  st = vsph_folder_clear(&f, NULL);
  DIR *d = st ? NULL : opendir(src);
  if (!st && !d) {
    st = VSPH_EIO;
    vsph_status_report(st, __FILE__, __LINE__, "cannot list %s: %s", src,
                       strerror(errno));
  }
  for (struct dirent *e; !st && d && (e = readdir(d));) {
    const char *n = e->d_name;
    if (n[0] == '.' || !strcmp(n, "key.txt") || !kept_file(n) ||
        kind->owns(n) != VSPH_FOLDER_FILE)
      continue;
    char path[4700];
    snprintf(path, sizeof path, "%s/%s", src, n);
    size_t len = 0;
    char *text = vsph_files_slurp(path, &len);
    if (!text || strlen(text) != len) { /* text files only, whole */
      free(text);
      st = VSPH_EIO;
      vsph_status_report(st, __FILE__, __LINE__, "cannot read %s as text",
                         path);
      break;
    }
    st = vsph_files_write(dst, n, text);
    free(text);
  }
  if (!st) st = vsph_folder_seal(&f, key, NULL);
  if (d) closedir(d);
  vsph_folder_release(&f);
  return st;
}

/* FNV-1a 64 of @p s. */
static unsigned long long fnv1a(const char *s) {
  unsigned long long h = 1469598103934665603ull;
  for (; *s; s++) h = (h ^ (unsigned char)*s) * 1099511628211ull;
  return h;
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
    char dir[4400];
    snprintf(dir, sizeof dir, "%s/%s", runs, names[k]);
    const struct vsph_folder_kind *kind = vsph_folder_kind_of(dir);
    char *key = kind ? key_of(dir) : NULL;
    if (!key || vsph_folder_verify(dir, kind, key, NULL, NULL, 0) != 1) {
      free(key);
      continue; /* not (or no longer) a whole entry */
    }
    char version[32] = "?", hash[64] = "?";
    sscanf(key, "vsph %31s %63s", version, hash);
    const char *settings = strchr(key, '\n');
    char path[4500];
    snprintf(path, sizeof path, "%s/run.json", dir);
    cJSON *o = vsph_json_read(path);
    const cJSON *s = o ? cJSON_GetObjectItemCaseSensitive(o, "status") : NULL;
    /* the commit the run recorded, else the caller's for this build's */
    const cJSON *c = o ? cJSON_GetObjectItemCaseSensitive(o, "commit") : NULL;
    const char *made = cJSON_IsString(c) && c->valuestring[0] &&
                               strcmp(c->valuestring, "unknown")
                           ? c->valuestring
                       : commit && !strcmp(hash, vsph_source_hash_id)
                           ? commit
                           : "unknown";
    fprintf(m, "%s\t%s\t%s\t%s\t%s\t%s\t%016llx\t%.6g\t%.0f\t%.0f\n", names[k],
            kind->name, cJSON_IsString(s) ? s->valuestring : "ok", version,
            hash, made, fnv1a(settings ? settings + 1 : ""),
            o ? vsph_json_get_number(o, "wall_s", NAN) : (double)NAN,
            o ? vsph_json_get_number(o, "steps", NAN) : (double)NAN,
            o ? vsph_json_get_number(o, "n_particles", NAN) : (double)NAN);
    cJSON_Delete(o);
    free(key);
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

int vsph_archive_store(const char *report, const char *archive,
                       const char *commit, FILE *progress,
                       struct vsph_archive_counts *counts) {
  memset(counts, 0, sizeof *counts);
  char src_runs[4200], runs[4200];
  snprintf(src_runs, sizeof src_runs, "%s/runs", report);
  snprintf(runs, sizeof runs, "%s/runs", archive);
  struct stat sb;
  if (lstat(src_runs, &sb) != 0 || !S_ISDIR(sb.st_mode))
    VSPH_FAIL(VSPH_EINVAL, "%s is not a report's runs folder", src_runs);
  struct vsph_folder top;
  int st = vsph_folder_claim(&top, archive, &vsph_folder_archive);
  if (st) return st;
  st = vsph_files_mkdir(runs);
  size_t n = 0;
  char **names = st ? NULL : subdirs(src_runs, &n);
  if (!st && !names) {
    st = VSPH_EIO;
    vsph_status_report(st, __FILE__, __LINE__, "cannot list %s", src_runs);
  }
  for (size_t k = 0; k < n && !st; k++) {
    char src[4400], dst[4400];
    snprintf(src, sizeof src, "%s/%s", src_runs, names[k]);
    snprintf(dst, sizeof dst, "%s/%s", runs, names[k]);
    const struct vsph_folder_kind *kind = vsph_folder_kind_of(src);
    if (kind != &vsph_folder_scene_run && kind != &vsph_folder_shear_test)
      continue; /* logs/, or not a run */
    char *key = key_of(src);
    char why[600] = "";
    if (!key ||
        vsph_folder_verify(src, kind, key, NULL, why, sizeof why) != 1) {
      counts->skipped++;
      if (progress)
        fprintf(progress, "vsph report: %s is not archived: %s\n", src,
                why[0] ? why : "its run has not ended (no seal)");
    } else if (vsph_folder_verify(dst, kind, key, NULL, NULL, 0) == 1) {
      counts->kept++;
    } else if (!(st = store_one(src, dst, key, kind))) {
      counts->stored++;
    }
    free(key);
  }
  if (!st) st = write_index(archive, runs, commit);
  free_list(names, n);
  vsph_folder_release(&top);
  return st;
}
