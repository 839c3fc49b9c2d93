/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* libFuzzer target (make fuzz): the run-folder contract (runs/folder,
 * runs/rundir). The input lays out a folder (entries with vsph's names and
 * others, as regular files, folders, FIFOs or symbolic links, a marker of
 * any kind or none, a key.txt and a checkpoint.bin of any bytes), then a
 * tiny run is asked to write into it. Whatever the folder held:
 *   - a refusal (exit 2's status) leaves every entry as it was, bytes and
 *     types alike;
 *   - a run that goes ahead ends with only vsph's files, run.json saying
 *     ok and a seal that holds;
 *   - nothing crashes, leaks or hangs (no FIFO is ever opened).
 * A broken invariant aborts, so libFuzzer keeps the input. */
#include <dirent.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../common/params.h"
#include "../../common/status.h"
#include "../../io/files.h"
#include "../../runs/folder.h"
#include "../../runs/rundir.h"

static void silent(int status, const char *file, int line, const char *msg) {
  (void)status, (void)file, (void)line, (void)msg;
}

static const char *const NAMES[] = {
    "run.json",       "energy.csv",          "profile.csv",    "snapshots.pvd",
    "snap_0000.vtp",  "snap_0003.vtp",       "centreline.csv", "key.txt",
    "checkpoint.bin", "used_parameters.yml", "summary.csv",    "notes.txt",
    ".vsph-folder",   ".vsph-lock",          "energy.csv.tmp", "data",
    "run.json.tmp",   "snap_12345.vtp"};
enum { NNAMES = sizeof NAMES / sizeof NAMES[0] };

static const char *const MARKERS[] = {"vsph scene run folder\n",
                                      "vsph shear test folder\n",
                                      "vsph report folder\n", "junk\n"};

/* The folder's entries: name, type and bytes, sorted by name. */
struct entry {
  char name[64];
  int type; /* 1 file, 2 folder, 3 FIFO, 4 link, 5 other */
  size_t len;
  unsigned char bytes[256];
};

static size_t listing(const char *dir, struct entry *e, size_t cap) {
  DIR *d = opendir(dir);
  size_t n = 0;
  for (struct dirent *de; d && (de = readdir(d)) && n < cap;) {
    if (!strcmp(de->d_name, ".") || !strcmp(de->d_name, "..")) continue;
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, de->d_name);
    struct stat sb;
    if (lstat(path, &sb) != 0) continue;
    memset(&e[n], 0, sizeof e[n]);
    snprintf(e[n].name, sizeof e[n].name, "%s", de->d_name);
    e[n].type = S_ISREG(sb.st_mode)    ? 1
                : S_ISDIR(sb.st_mode)  ? 2
                : S_ISFIFO(sb.st_mode) ? 3
                : S_ISLNK(sb.st_mode)  ? 4
                                       : 5;
    if (S_ISREG(sb.st_mode)) {
      FILE *f = fopen(path, "rb");
      if (f) {
        e[n].len = fread(e[n].bytes, 1, sizeof e[n].bytes, f);
        fclose(f);
      }
    }
    n++;
  }
  if (d) closedir(d);
  for (size_t i = 1; i < n; i++) /* sorted by name */
    for (size_t j = i; j > 0 && strcmp(e[j - 1].name, e[j].name) > 0; j--) {
      struct entry t = e[j];
      e[j] = e[j - 1];
      e[j - 1] = t;
    }
  return n;
}

static void rm_tree(const char *dir) {
  char cmd[600];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (system(cmd) != 0) abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size > 2048) return 0;
  vsph_status_set_handler(silent);
  char base[] = "/tmp/vsph-fuzz-folder-XXXXXX";
  if (!mkdtemp(base)) return 0;
  char dir[128];
  snprintf(dir, sizeof dir, "%s/r", base);
  size_t at = 0;
  /* byte 0: absent (0), empty, or entries */
  const int mode = size > 0 ? data[at++] % 3 : 0;
  if (mode > 0 && mkdir(dir, 0700) != 0) abort();
  while (mode == 2 && at + 3 <= size) {
    const unsigned name = data[at++] % NNAMES, type = data[at++] % 5;
    size_t len = data[at++] % 64;
    if (len > size - at) len = size - at;
    char path[256];
    snprintf(path, sizeof path, "%s/%s", dir, NAMES[name]);
    struct stat sb;
    if (lstat(path, &sb) == 0) { /* one entry a name (a FIFO would block
                                    the harness's own writer) */
      at += len;
      continue;
    }
    if (type == 0 || type == 4) { /* a file: bytes, or a marker */
      FILE *f = fopen(path, "wb");
      if (!f) continue;
      if (type == 4)
        fputs(MARKERS[len % 4], f);
      else
        fwrite(data + at, 1, len, f);
      fclose(f);
    } else if (type == 1) {
      mkdir(path, 0700);
    } else if (type == 2) {
      mkfifo(path, 0600);
    } else {
      char target[256];
      snprintf(target, sizeof target, "%s/%s", dir, NAMES[len % NNAMES]);
      if (symlink(target, path) != 0) continue;
    }
    at += len;
  }
  static struct entry before[32], after[32];
  const size_t nb = listing(dir, before, 32);
  struct vsph_params *prm = vsph_params_alloc();
  if (!prm) abort();
  vsph_params_set(prm, "Solver:res", "4");
  vsph_params_set(prm, "Solver:t_end", "0.002");
  vsph_params_set(prm, "Solver:outputs", "2");
  vsph_params_set(prm, "Solver:snapshots", "1");
  const struct vsph_rundir_opts o = {.dir = dir, .cache = (size & 1) != 0};
  struct vsph_rundir_result res;
  const int st = vsph_rundir_execute(prm, "poiseuille", &o, &res);
  vsph_params_free(prm);
  const size_t na = listing(dir, after, 32);
  if (st == VSPH_EINVAL) { /* refused: unchanged */
    if (na != nb) abort();
    for (size_t k = 0; k < na; k++)
      if (strcmp(before[k].name, after[k].name) ||
          before[k].type != after[k].type || before[k].len != after[k].len ||
          memcmp(before[k].bytes, after[k].bytes, before[k].len))
        abort();
  } else if (st == VSPH_OK) { /* written: only vsph's files, sealed ok */
    for (size_t k = 0; k < na; k++)
      if (after[k].type != 1 ||
          (strcmp(after[k].name, VSPH_FOLDER_MARKER) &&
           strcmp(after[k].name, VSPH_FOLDER_LOCK) &&
           vsph_folder_scene_run.owns(after[k].name) != VSPH_FOLDER_FILE))
        abort();
    char path[256];
    snprintf(path, sizeof path, "%s/run.json", dir);
    char *js = vsph_files_slurp(path, NULL);
    if (!js || !strstr(js, "\"status\":\t\"ok\"")) abort();
    free(js);
    snprintf(path, sizeof path, "%s/key.txt", dir);
    char *key = vsph_files_slurp(path, NULL);
    char *files = key ? strstr(key, "files:\n") : NULL;
    if (!files) abort();
    files[0] = '\0';
    if (vsph_folder_verify(dir, &vsph_folder_scene_run, key, NULL, NULL, 0) !=
        1)
      abort();
    free(key);
  } else {
    abort(); /* an I/O failure on /tmp, or a bug */
  }
  rm_tree(base);
  return 0;
}
