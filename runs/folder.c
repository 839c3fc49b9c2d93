/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* F_OFD_SETLK: a lock of the open file, which closing another descriptor
 * of the same file (reading the lock file to judge it) does not drop */
#define _GNU_SOURCE
#include "folder.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include "../common/consts.h"
#include "../common/status.h"
#include "../io/files.h"
#include "../io/vtk.h"

/* ------------------------------------------------------------ the kinds */

static int ends_with(const char *s, const char *tail) {
  const size_t n = strlen(s), m = strlen(tail);
  return n > m && !strcmp(s + n - m, tail);
}

/* NAME.tmp, the atomic writers' temporary of an owned NAME */
static int tmp_of(const char *name, int (*owns)(const char *)) {
  char base[256];
  const size_t n = strlen(name);
  if (n < 5 || n - 4 >= sizeof base || !ends_with(name, ".tmp")) return 0;
  memcpy(base, name, n - 4);
  base[n - 4] = '\0';
  return owns(base) == VSPH_FOLDER_FILE;
}

/* .vsph-vtk-XXXXXX, a snapshot's scratch file (io/vtk.c, mkstemp's six
 * characters) left by a kill between its making and its unlinking where
 * the file system has no unnamed files: a temporary of a scene run */
static int scratch_of_vtk(const char *name) {
  const size_t p = strlen(VSPH_VTK_SCRATCH);
  return strlen(name) == p + 6 && !strncmp(name, VSPH_VTK_SCRATCH, p);
}

static int one_of(const char *name, const char *const *list) {
  for (; *list; list++)
    if (!strcmp(name, *list)) return 1;
  return 0;
}

static int owns_scene(const char *name) {
  static const char *const exact[] = {"run.json",       "energy.csv",
                                      "snapshots.pvd",  "profile.csv",
                                      "centreline.csv", "used_parameters.yml",
                                      "key.txt",        "checkpoint.bin",
                                      "probes.csv",     NULL};
  if (one_of(name, exact)) return VSPH_FOLDER_FILE;
  const size_t n = strlen(name);
  if (n == 13 && !strncmp(name, "snap_", 5) && ends_with(name, ".vtp") &&
      strspn(name + 5, "0123456789") == 4)
    return VSPH_FOLDER_FILE;
  if (n == 14 && !strncmp(name, "walls_", 6) && ends_with(name, ".vtp") &&
      strspn(name + 6, "0123456789") == 4)
    return VSPH_FOLDER_FILE;
  if (scratch_of_vtk(name)) return VSPH_FOLDER_FILE;
  return tmp_of(name, owns_scene) ? VSPH_FOLDER_FILE : VSPH_FOLDER_FOREIGN;
}

static int owns_shear(const char *name) {
  static const char *const exact[] = {"summary.csv", "profiles.csv", "key.txt",
                                      "checkpoint.bin", NULL};
  if (one_of(name, exact)) return VSPH_FOLDER_FILE;
  return tmp_of(name, owns_shear) ? VSPH_FOLDER_FILE : VSPH_FOLDER_FOREIGN;
}

/* A report: its text, tables, figures and their gnuplot scripts and
 * logs, its seal, its parts, its runs and its Slurm scripts. */
static int owns_report(const char *name) {
  static const char *const dirs[] = {"parts", "runs", "slurm", NULL};
  static const char *const ext[] = {".csv",  ".gp",   ".log", ".pdf",
                                    ".png",  ".svg",  ".md",  ".html",
                                    ".json", ".lock", ".tmp", NULL};
  if (one_of(name, dirs)) return VSPH_FOLDER_SUBDIR;
  if (!strcmp(name, "key.txt")) return VSPH_FOLDER_FILE; /* the seal */
  if (name[0] == '.') return VSPH_FOLDER_FOREIGN;
  for (const char *const *e = ext; *e; e++)
    if (ends_with(name, *e)) return VSPH_FOLDER_FILE;
  return VSPH_FOLDER_FOREIGN;
}

const struct vsph_folder_kind vsph_folder_scene_run = {"scene run", owns_scene};
const struct vsph_folder_kind vsph_folder_shear_test = {"shear test",
                                                        owns_shear};
const struct vsph_folder_kind vsph_folder_report = {"report", owns_report};

/* An archive of runs: its index, its summary and its runs' folders. */
static int owns_archive(const char *name) {
  static const char *const files[] = {"index.tsv", "entries.md", "summary.md",
                                      "key.txt", NULL};
  if (!strcmp(name, "runs")) return VSPH_FOLDER_SUBDIR;
  if (one_of(name, files)) return VSPH_FOLDER_FILE;
  return tmp_of(name, owns_archive) ? VSPH_FOLDER_FILE : VSPH_FOLDER_FOREIGN;
}
const struct vsph_folder_kind vsph_folder_archive = {"run archive",
                                                     owns_archive};

/* ----------------------------------------------------------- judging */

static const char *type_of(mode_t m) {
  return S_ISDIR(m)    ? "a folder"
         : S_ISLNK(m)  ? "a symbolic link"
         : S_ISFIFO(m) ? "a FIFO"
         : S_ISSOCK(m) ? "a socket"
         : S_ISREG(m)  ? "a file"
                       : "a device";
}

/* The marker's text for @p kind. */
static void marker_text(const struct vsph_folder_kind *kind, char *buf,
                        size_t len) {
  snprintf(buf, len, "vsph %s folder\n", kind->name);
}

/* A lock file as vsph leaves it: a regular file of one link holding
 * nothing (made, not yet written) or a pid and a newline; anything else
 * (a user's file of that name) is not vsph's. (The lock is an open file
 * description's, F_OFD_SETLK, so reading the file here never drops this
 * process's own.) */
static int lock_file_ours(const char *path) {
  struct stat sb;
  if (lstat(path, &sb) != 0) return 1; /* absent */
  if (!S_ISREG(sb.st_mode) || sb.st_nlink != 1 || sb.st_size > 24) return 0;
  if (sb.st_size == 0) return 1;
  const int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return 0;
  char t[32];
  const ssize_t n = read(fd, t, sizeof t - 1);
  close(fd);
  if (n <= 1 || t[n - 1] != '\n') return n == 0;
  for (ssize_t k = 0; k < n - 1; k++)
    if (t[k] < '0' || t[k] > '9') return 0;
  return 1;
}

/* The pid a lock file names (-1: none). */
static long lock_pid(int fd) {
  char t[32];
  const ssize_t n = pread(fd, t, sizeof t - 1, 0);
  if (n <= 0) return -1;
  t[n] = '\0';
  char *end;
  const long pid = strtol(t, &end, 10);
  return end != t && *end == '\n' ? pid : -1;
}

int vsph_folder_judge(const char *dir, const struct vsph_folder_kind *kind) {
  if (!dir[0]) VSPH_FAIL(VSPH_EINVAL, "the folder's name is empty");
  if (strlen(dir) > 3000)
    VSPH_FAIL(VSPH_EINVAL, "folder name too long: %.60s...", dir);
  struct stat sb;
  if (stat(dir, &sb) != 0) {
    if (errno == ENOENT) return VSPH_OK; /* to be made */
    VSPH_FAIL(VSPH_EINVAL, "%s: %s", dir, strerror(errno));
  }
  if (!S_ISDIR(sb.st_mode))
    VSPH_FAIL(VSPH_EINVAL, "%s exists and is %s, not a folder", dir,
              type_of(sb.st_mode));
  DIR *d = opendir(dir);
  if (!d) VSPH_FAIL(VSPH_EINVAL, "cannot read %s: %s", dir, strerror(errno));
  char path[4400], first[256] = "", bad[600] = "";
  int any = 0, marker = 0;
  for (struct dirent *e; (e = readdir(d));) {
    const char *n = e->d_name;
    if (!strcmp(n, ".") || !strcmp(n, "..")) continue;
    /* a lone lock as vsph leaves it: a writer's first step */
    snprintf(path, sizeof path, "%s/%s", dir, n);
    if (!strcmp(n, VSPH_FOLDER_LOCK) && lock_file_ours(path)) continue;
    if (!any++) snprintf(first, sizeof first, "%s", n);
    snprintf(path, sizeof path, "%s/%s", dir, n);
    struct stat eb;
    if (lstat(path, &eb) != 0) continue; /* gone meanwhile */
    const int want =
        !strcmp(n, VSPH_FOLDER_MARKER) || !strcmp(n, VSPH_FOLDER_LOCK)
            ? VSPH_FOLDER_FILE
            : kind->owns(n);
    if (!strcmp(n, VSPH_FOLDER_MARKER)) marker = S_ISREG(eb.st_mode);
    if (bad[0]) continue;
    if (want == VSPH_FOLDER_FOREIGN)
      snprintf(bad, sizeof bad, "%.200s, which vsph does not write there", n);
    else if (want == VSPH_FOLDER_FILE && !S_ISREG(eb.st_mode))
      snprintf(bad, sizeof bad, "%.200s, which is %s, not a regular file", n,
               type_of(eb.st_mode));
    else if (want == VSPH_FOLDER_SUBDIR && !S_ISDIR(eb.st_mode))
      snprintf(bad, sizeof bad, "%.200s, which is %s, not a folder", n,
               type_of(eb.st_mode));
  }
  closedir(d);
  if (!any) return VSPH_OK; /* empty: to be claimed */
  if (!marker)
    VSPH_FAIL(VSPH_EINVAL,
              "%s is not empty (it holds %.200s) and vsph did not make it "
              "(no %s): choose another folder",
              dir, first, VSPH_FOLDER_MARKER);
  snprintf(path, sizeof path, "%s/%s", dir, VSPH_FOLDER_MARKER);
  size_t len = 0;
  char *text = vsph_files_slurp(path, &len);
  char want[128];
  marker_text(kind, want, sizeof want);
  const int same = text && !strcmp(text, want);
  char other[64] = "";
  if (text && !same && !strncmp(text, "vsph ", 5))
    snprintf(other, sizeof other, "%.*s", (int)strcspn(text + 5, "\n"),
             text + 5);
  free(text);
  if (!same)
    VSPH_FAIL(VSPH_EINVAL, "%s is %s%s, not a vsph %s: choose another folder",
              dir, other[0] ? "a vsph " : "not a vsph folder",
              other[0] ? other : "", kind->name);
  if (bad[0])
    VSPH_FAIL(VSPH_EINVAL,
              "%s holds %s: move it or choose another folder (vsph changes "
              "nothing in it)",
              dir, bad);
  return VSPH_OK;
}

/* ------------------------------------------------------------ claiming */

/* Failures to make or write the folder itself are bad paths (exit 2):
 * nothing has been written. */
static int refused_path(const char *what, const char *path, int e) {
  const int bad = e == ENOTDIR || e == ENOENT || e == EACCES || e == EPERM ||
                  e == EROFS || e == ENAMETOOLONG || e == ELOOP ||
                  e == EISDIR || e == EEXIST;
  VSPH_FAIL(bad ? VSPH_EINVAL : VSPH_EIO, "cannot %s %s: %s", what, path,
            strerror(e));
}

static int lock(struct vsph_folder *f) {
  char path[4200];
  snprintf(path, sizeof path, "%s/%s", f->dir, VSPH_FOLDER_LOCK);
  if (!lock_file_ours(path))
    VSPH_FAIL(VSPH_EINVAL,
              "%s is not a lock file vsph wrote (a link, a folder, or "
              "someone's data): choose another folder",
              path);
  const int flags = O_RDWR | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK;
  int fd = open(path, flags | O_CREAT | O_EXCL, 0644);
  if (fd >= 0)
    f->made_lock = 1;
  else if (errno == EEXIST)
    fd = open(path, flags);
  if (fd < 0) return refused_path("write in", f->dir, errno);
  struct stat sb;
  if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_nlink != 1) {
    close(fd);
    VSPH_FAIL(VSPH_EINVAL, "%s is not a regular file of its own", path);
  }
  struct flock fl;
  memset(&fl, 0, sizeof fl);
  fl.l_type = F_WRLCK;
  fl.l_whence = SEEK_SET;
  if (fcntl(fd, F_OFD_SETLK, &fl) == 0) {
    f->fd = fd;
    char pid[32];
    const int n = snprintf(pid, sizeof pid, "%ld\n", (long)getpid());
    /* who holds it, for a person reading the folder (the lock itself is
     * what counts) */
    if (ftruncate(fd, 0) != 0 || pwrite(fd, pid, (size_t)n, 0) != n)
      return refused_path("write in", f->dir, errno);
    return VSPH_OK;
  }
  const int e = errno;
  const long pid = lock_pid(fd); /* its holder wrote it there */
  close(fd);
  if (e == EACCES || e == EAGAIN)
    VSPH_FAIL(VSPH_EINVAL,
              "%s is being written by process %ld (it holds %s): wait for it "
              "or choose another folder",
              f->dir, pid, VSPH_FOLDER_LOCK);
  VSPH_FAIL(VSPH_EIO, "cannot lock %s: %s", path, strerror(e));
}

/* mkdir -p, each folder made recorded (so a refusal can take it back). */
static int make_dirs(struct vsph_folder *f, const char *dir) {
  char buf[4096];
  snprintf(buf, sizeof buf, "%s", dir);
  const size_t n = strlen(buf);
  for (size_t k = 1; k <= n; k++) {
    if (buf[k] != '/' && buf[k] != '\0') continue;
    const char c = buf[k];
    buf[k] = '\0';
    if (mkdir(buf, 0777) == 0) {
      if (f->nmade < 8)
        snprintf(f->made[f->nmade++], sizeof f->made[0], "%s", buf);
    } else if (errno != EEXIST) {
      return refused_path("create", buf, errno);
    }
    buf[k] = c;
  }
  struct stat sb; /* there now: a folder, or a link to one */
  if (stat(dir, &sb) != 0 || !S_ISDIR(sb.st_mode))
    VSPH_FAIL(VSPH_EINVAL, "%s exists and is not a folder", dir);
  return VSPH_OK;
}

int vsph_folder_claim(struct vsph_folder *f, const char *dir,
                      const struct vsph_folder_kind *kind) {
  memset(f, 0, sizeof *f);
  f->fd = -1;
  f->kind = kind;
  int st = vsph_folder_judge(dir, kind);
  if (st) return st;
  snprintf(f->dir, sizeof f->dir, "%s", dir);
  if ((st = make_dirs(f, dir)) || (st = lock(f)) ||
      /* again under the lock: another writer may have been quicker */
      (st = vsph_folder_judge(dir, kind))) {
    vsph_folder_abandon(f);
    return st;
  }
  char path[4200], text[128];
  snprintf(path, sizeof path, "%s/%s", dir, VSPH_FOLDER_MARKER);
  if (access(path, F_OK) == 0) return VSPH_OK;
  marker_text(kind, text, sizeof text);
  if ((st = vsph_files_write(dir, VSPH_FOLDER_MARKER, text))) {
    vsph_folder_abandon(f);
    return st;
  }
  f->made_marker = 1;
  return VSPH_OK;
}

void vsph_folder_release(struct vsph_folder *f) {
  if (f->fd >= 0) close(f->fd);
  f->fd = -1;
  free(f->crcs);
  f->crcs = NULL;
  f->ncrcs = 0;
}

void vsph_folder_abandon(struct vsph_folder *f) {
  char path[4200];
  if (f->made_marker) {
    snprintf(path, sizeof path, "%s/%s", f->dir, VSPH_FOLDER_MARKER);
    remove(path);
  }
  if (f->made_lock) { /* while still locked: no other writer between */
    snprintf(path, sizeof path, "%s/%s", f->dir, VSPH_FOLDER_LOCK);
    remove(path);
  }
  vsph_folder_release(f);
  for (int k = f->nmade - 1; k >= 0; k--) /* innermost first, if empty */
    if (rmdir(f->made[k]) != 0) break;
  f->made_marker = f->made_lock = 0;
  f->nmade = 0;
}

/* ------------------------------------------------------- clear and seal */

static int skipped(const char *name, const char *const *skip) {
  return !strcmp(name, VSPH_FOLDER_MARKER) || !strcmp(name, VSPH_FOLDER_LOCK) ||
         (skip && one_of(name, skip));
}

static int is_tmp(const char *name) {
  return ends_with(name, ".tmp") || scratch_of_vtk(name);
}

/* Remove the regular files vsph writes in the claimed folder but the
 * marker, the lock and @p keep; only temporaries when @p tmp_only. */
static int remove_files(const struct vsph_folder *f, const char *const *keep,
                        int tmp_only) {
  DIR *d = opendir(f->dir);
  if (!d) VSPH_FAIL(VSPH_EIO, "cannot read %s: %s", f->dir, strerror(errno));
  int st = VSPH_OK;
  char path[4400];
  for (struct dirent *e; !st && (e = readdir(d));) {
    if (skipped(e->d_name, keep) || (tmp_only && !is_tmp(e->d_name)) ||
        f->kind->owns(e->d_name) != VSPH_FOLDER_FILE)
      continue;
    snprintf(path, sizeof path, "%s/%s", f->dir, e->d_name);
    if (remove(path) != 0 && errno != ENOENT) {
      vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot remove %s: %s",
                         path, strerror(errno));
      st = VSPH_EIO;
    }
  }
  closedir(d);
  return st;
}

int vsph_folder_clear(const struct vsph_folder *f, const char *const *keep) {
  char path[4400];
  static const char *const first[] = {"key.txt", "run.json"};
  for (int k = 0; k < 2; k++) {
    if (keep && one_of(first[k], keep)) continue;
    snprintf(path, sizeof path, "%s/%s", f->dir, first[k]);
    if (remove(path) != 0 && errno != ENOENT)
      VSPH_FAIL(VSPH_EIO, "cannot remove %s: %s", path, strerror(errno));
  }
  return remove_files(f, keep, 0);
}

/* A file's identity for the manifest's cache: a file written anew (by
 * rename, or in place) differs in one of these. */
struct vsph_folder_crc {
  char name[256];
  dev_t dev;
  ino_t ino;
  off_t size;
  struct timespec mtim, ctim;
  unsigned long crc;
};

static int same_file(const struct vsph_folder_crc *c, const struct stat *sb) {
  return c->dev == sb->st_dev && c->ino == sb->st_ino &&
         c->size == sb->st_size && c->mtim.tv_sec == sb->st_mtim.tv_sec &&
         c->mtim.tv_nsec == sb->st_mtim.tv_nsec &&
         c->ctim.tv_sec == sb->st_ctim.tv_sec &&
         c->ctim.tv_nsec == sb->st_ctim.tv_nsec;
}

/* The CRC-32 and size of regular file @p path, and its identity in @p sb,
 * read unless @p known (may be NULL) holds it for that identity. */
static int checksum(const char *path, const struct vsph_folder_crc *known,
                    unsigned long *crc, size_t *size, struct stat *sb) {
  const int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return VSPH_EIO;
  if (fstat(fd, sb) != 0 || !S_ISREG(sb->st_mode)) {
    close(fd);
    return VSPH_EIO;
  }
  if (known && same_file(known, sb)) {
    close(fd);
    *crc = known->crc;
    *size = (size_t)sb->st_size;
    return VSPH_OK;
  }
  uLong c = crc32(0L, Z_NULL, 0);
  size_t n = 0;
  unsigned char buf[1 << 16];
  for (;;) {
    const ssize_t r = read(fd, buf, sizeof buf);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      close(fd);
      return VSPH_EIO;
    }
    if (r == 0) break;
    c = crc32(c, buf, (uInt)r);
    n += (size_t)r;
  }
  close(fd);
  *crc = (unsigned long)c;
  *size = n;
  return VSPH_OK;
}

int vsph_folder_checksum(const char *path, unsigned long *crc, size_t *size) {
  struct stat sb;
  return checksum(path, NULL, crc, size, &sb);
}

/* Record that file @p name of @p f, as @p sb identifies it, has CRC-32
 * @p crc (the cache stays sorted by name). Best effort: a name too long
 * or no memory only means the file is read again. */
static void remember(struct vsph_folder *f, const char *name,
                     const struct stat *sb, unsigned long crc) {
  if (strlen(name) >= sizeof f->crcs->name) return;
  size_t k = 0;
  while (k < f->ncrcs && strcmp(f->crcs[k].name, name) < 0) k++;
  if (k == f->ncrcs || strcmp(f->crcs[k].name, name)) {
    struct vsph_folder_crc *c =
        realloc(f->crcs, (f->ncrcs + 1) * sizeof *f->crcs);
    if (!c) return;
    f->crcs = c;
    memmove(c + k + 1, c + k, (f->ncrcs - k) * sizeof *c);
    f->ncrcs++;
  }
  struct vsph_folder_crc *c = &f->crcs[k];
  snprintf(c->name, sizeof c->name, "%s", name);
  c->dev = sb->st_dev;
  c->ino = sb->st_ino;
  c->size = sb->st_size;
  c->mtim = sb->st_mtim;
  c->ctim = sb->st_ctim;
  c->crc = crc;
}

int vsph_folder_note(struct vsph_folder *f, const char *name) {
  char path[4400];
  snprintf(path, sizeof path, "%s/%s", f->dir, name);
  unsigned long crc;
  size_t size;
  struct stat sb;
  const int st = checksum(path, NULL, &crc, &size, &sb);
  if (!st && (size_t)sb.st_size == size) remember(f, name, &sb, crc);
  return st;
}

static int by_name(const void *a, const void *b) {
  return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The regular files vsph writes in @p dir (kind's names), but the marker,
 * the lock, key.txt and @p skip, sorted; *n receives the count. NULL on
 * failure (not reported). */
static char **listing(const char *dir, const struct vsph_folder_kind *kind,
                      const char *const *skip, size_t *n) {
  DIR *d = opendir(dir);
  if (!d) return NULL;
  size_t cap = 16, m = 0;
  char **names = malloc(cap * sizeof *names);
  int ok = names != NULL;
  for (struct dirent *e; ok && (e = readdir(d));) {
    const char *nm = e->d_name;
    if (skipped(nm, skip) || !strcmp(nm, "key.txt") ||
        kind->owns(nm) != VSPH_FOLDER_FILE)
      continue;
    if (m == cap) {
      char **g = realloc(names, 2 * cap * sizeof *names);
      if (!g) {
        ok = 0;
        break;
      }
      names = g;
      cap *= 2;
    }
    if (!(names[m] = strdup(nm)))
      ok = 0;
    else
      m++;
  }
  closedir(d);
  if (!ok) {
    for (size_t k = 0; k < m; k++) free(names[k]);
    free(names);
    return NULL;
  }
  qsort(names, m, sizeof *names, by_name);
  *n = m;
  return names;
}

static void listing_free(char **names, size_t n) {
  for (size_t k = 0; names && k < n; k++) free(names[k]);
  free(names);
}

int vsph_folder_seal(const struct vsph_folder *f, const char *key,
                     const char *const *skip) {
  return vsph_folder_seal_with(f, key, skip, NULL, NULL);
}

int vsph_folder_seal_with(const struct vsph_folder *f, const char *key,
                          const char *const *skip, const char *name,
                          const char *content) {
  size_t n = 0;
  char **names = listing(f->dir, f->kind, skip, &n);
  if (!names) VSPH_FAIL(VSPH_EIO, "cannot list %s", f->dir);
  if (name) { /* the file still to come, in its sorted place */
    size_t k = 0;
    while (k < n && strcmp(names[k], name) < 0) k++;
    if (k == n || strcmp(names[k], name)) {
      char **g = realloc(names, (n + 1) * sizeof *names);
      char *dup = strdup(name);
      if (!g || !dup) {
        listing_free(g ? g : names, n);
        free(dup);
        VSPH_FAIL(VSPH_ENOMEM, "cannot list %s", f->dir);
      }
      names = g;
      memmove(names + k + 1, names + k, (n - k) * sizeof *names);
      names[k] = dup;
      n++;
    }
  }
  char *text = NULL;
  size_t len = 0;
  FILE *m = open_memstream(&text, &len);
  int st = m ? VSPH_OK : VSPH_ENOMEM;
  if (m) fprintf(m, "%sfiles:\n", key);
  char path[4400];
  for (size_t k = 0; k < n && !st; k++) {
    unsigned long crc;
    size_t size;
    snprintf(path, sizeof path, "%s/%s", f->dir, names[k]);
    if (name && !strcmp(names[k], name)) {
      size = strlen(content);
      crc = crc32(crc32(0L, Z_NULL, 0), (const Bytef *)content, (uInt)size);
      fprintf(m, "%s %zu %08lx\n", names[k], size, crc);
    } else if (vsph_folder_checksum(path, &crc, &size)) {
      vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot read %s", path);
      st = VSPH_EIO;
    } else {
      fprintf(m, "%s %zu %08lx\n", names[k], size, crc);
    }
  }
  listing_free(names, n);
  if (m && fclose(m) != 0 && !st) st = VSPH_ENOMEM;
  if (st == VSPH_ENOMEM)
    vsph_status_report(st, __FILE__, __LINE__, "cannot build %s/key.txt",
                       f->dir);
  if (!st) st = vsph_files_write(f->dir, "key.txt", text);
  free(text);
  return st;
}

__attribute__((format(printf, 3, 4))) static int say(char *why, size_t len,
                                                     const char *fmt, ...) {
  if (why && len) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(why, len, fmt, ap);
    va_end(ap);
  }
  return -1;
}

unsigned long long vsph_folder_fingerprint(const char *s) {
  unsigned long long h = 14695981039346656037ull;
  for (; *s; s++) h = (h ^ (unsigned char)*s) * 1099511628211ull;
  return h;
}

const struct vsph_folder_kind *vsph_folder_kind_of(const char *dir) {
  static const struct vsph_folder_kind *const kinds[] = {
      &vsph_folder_scene_run, &vsph_folder_shear_test, &vsph_folder_report,
      &vsph_folder_archive};
  char path[4400];
  snprintf(path, sizeof path, "%s/%s", dir, VSPH_FOLDER_MARKER);
  struct stat sb;
  if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode) || sb.st_size > 128)
    return NULL;
  const struct vsph_folder_kind *kind = NULL;
  char *mk = vsph_files_slurp(path, NULL);
  for (size_t k = 0; mk && k < sizeof kinds / sizeof *kinds && !kind; k++) {
    char want[128];
    marker_text(kinds[k], want, sizeof want);
    if (!strcmp(mk, want)) kind = kinds[k];
  }
  free(mk);
  return kind;
}

int vsph_folder_verify(const char *dir, const struct vsph_folder_kind *kind,
                       const char *key, const char *const *skip, char *why,
                       size_t len) {
  if (why && len) why[0] = '\0';
  char path[4400];
  snprintf(path, sizeof path, "%s/%s", dir, VSPH_FOLDER_MARKER);
  struct stat sb;
  if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return 0;
  if (!kind && !(kind = vsph_folder_kind_of(dir))) return 0;
  snprintf(path, sizeof path, "%s/key.txt", dir);
  if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) return 0;
  char *text = vsph_files_slurp(path, NULL);
  if (!text) return 0;
  const size_t kl = strlen(key);
  if (strncmp(text, key, kl) || strncmp(text + kl, "files:\n", 7)) {
    free(text);
    return 0;
  }
  size_t n = 0;
  char **names = listing(dir, kind, skip, &n);
  int res = names ? 1 : say(why, len, "cannot list %s", dir);
  size_t k = 0;
  for (char *line = text + kl + 7; res == 1 && *line;) {
    char *end = strchr(line, '\n');
    if (!end) {
      res = say(why, len, "%s/key.txt is cut short", dir);
      break;
    }
    *end = '\0';
    char name[256];
    size_t size;
    unsigned long crc;
    int used = 0;
    if (sscanf(line, "%255s %zu %lx%n", name, &size, &crc, &used) != 3 ||
        line[used] != '\0') {
      res = say(why, len, "%s/key.txt has a damaged line", dir);
      break;
    }
    if (k >= n || strcmp(names[k], name)) {
      res = k >= n || strcmp(names[k], name) > 0
                ? say(why, len, "%s/%s is missing", dir, name)
                : say(why, len, "%s/%s is not in the folder's key", dir,
                      names[k]);
      break;
    }
    unsigned long c2;
    size_t s2;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (vsph_folder_checksum(path, &c2, &s2))
      res = say(why, len, "%s/%s cannot be read as a regular file", dir, name);
    else if (s2 != size || c2 != crc)
      res = say(why, len,
                "%s/%s differs from the folder's key (changed or cut "
                "short since it was written)",
                dir, name);
    k++;
    line = end + 1;
  }
  if (res == 1 && k < n)
    res = say(why, len, "%s/%s is not in the folder's key", dir, names[k]);
  listing_free(names, n);
  free(text);
  return res;
}

/* ------------------------------------------------------------ manifests */

char *vsph_folder_manifest(struct vsph_folder *f, const char *const *skip) {
  size_t n = 0;
  char **names = listing(f->dir, f->kind, skip, &n);
  if (!names) return NULL;
  char *text = NULL;
  size_t len = 0;
  FILE *m = open_memstream(&text, &len);
  /* this listing's identities replace the cache (sorted by name, as the
   * listing is, and as the old one was) */
  struct vsph_folder_crc *now = calloc(n ? n : 1, sizeof *now);
  size_t nnow = 0, old = 0;
  int ok = m != NULL && now != NULL;
  char path[4400];
  for (size_t k = 0; k < n && ok; k++) {
    if (is_tmp(names[k])) continue;
    const int keep = strlen(names[k]) < sizeof now->name;
    while (old < f->ncrcs && strcmp(f->crcs[old].name, names[k]) < 0) old++;
    const struct vsph_folder_crc *known =
        old < f->ncrcs && !strcmp(f->crcs[old].name, names[k]) ? &f->crcs[old]
                                                               : NULL;
    unsigned long crc;
    size_t size;
    struct stat sb;
    snprintf(path, sizeof path, "%s/%s", f->dir, names[k]);
    ok = !checksum(path, known, &crc, &size, &sb);
    if (!ok) break;
    fprintf(m, "%s %zu %08lx\n", names[k], size, crc);
    /* a file still being written (its size not the one read) is not
     * remembered */
    if (!keep || (size_t)sb.st_size != size) continue;
    now[nnow++] = (struct vsph_folder_crc){.dev = sb.st_dev,
                                           .ino = sb.st_ino,
                                           .size = sb.st_size,
                                           .mtim = sb.st_mtim,
                                           .ctim = sb.st_ctim,
                                           .crc = crc};
    snprintf(now[nnow - 1].name, sizeof now->name, "%s", names[k]);
  }
  listing_free(names, n);
  if (ok) {
    free(f->crcs);
    f->crcs = now;
    f->ncrcs = nnow;
  } else {
    free(now);
  }
  if (m && fclose(m) != 0) ok = 0;
  if (!ok) {
    free(text);
    return NULL;
  }
  return text;
}

/* CRC-32 of the first @p len bytes of regular file @p path. */
static int crc_prefix(const char *path, size_t len, unsigned long *crc) {
  const int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return VSPH_EIO;
  struct stat sb;
  if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode) || (size_t)sb.st_size < len) {
    close(fd);
    return VSPH_EIO;
  }
  uLong c = crc32(0L, Z_NULL, 0);
  unsigned char buf[1 << 16];
  for (size_t done = 0; done < len;) {
    const size_t want = len - done < sizeof buf ? len - done : sizeof buf;
    const ssize_t r = read(fd, buf, want);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) {
      close(fd);
      return VSPH_EIO;
    }
    c = crc32(c, buf, (uInt)r);
    done += (size_t)r;
  }
  close(fd);
  *crc = (unsigned long)c;
  return VSPH_OK;
}

int vsph_folder_manifest_holds(struct vsph_folder *f, const char *manifest,
                               const char *const *grow, const char *const *skip,
                               char *why, size_t wlen) {
  size_t n = 0;
  char **names = listing(f->dir, f->kind, skip, &n);
  if (!names) return say(why, wlen, "cannot list %s", f->dir);
  int res = 1;
  size_t listed = 0;
  char path[4400];
  for (const char *line = manifest; res == 1 && *line;) {
    const char *end = strchr(line, '\n');
    char name[256];
    size_t size;
    unsigned long crc, c2;
    int used = 0;
    if (!end ||
        sscanf(line, "%255s %zu %lx%n", name, &size, &crc, &used) != 3 ||
        line + used != end) {
      res = say(why, wlen, "its list of files is damaged");
      break;
    }
    listed++;
    snprintf(path, sizeof path, "%s/%s", f->dir, name);
    struct stat sb;
    const int may_grow = grow && one_of(name, grow);
    if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode))
      res = say(why, wlen, "%s is missing", name);
    else if ((size_t)sb.st_size != size && !may_grow)
      res = say(why, wlen, "%s changed size", name);
    else if (crc_prefix(path, size, &c2) || c2 != crc)
      res = say(why, wlen, "%s changed since the checkpoint", name);
    else if ((size_t)sb.st_size == size) /* read whole: not again */
      remember(f, name, &sb, crc);
    line = end + 1;
  }
  /* nothing else of vsph's but temporaries */
  size_t present = 0;
  for (size_t k = 0; k < n; k++) present += !is_tmp(names[k]);
  if (res == 1 && present != listed)
    res = say(why, wlen, "it holds files the checkpoint did not see");
  listing_free(names, n);
  return res;
}

int vsph_folder_clear_tmp(const struct vsph_folder *f) {
  return remove_files(f, NULL, 1);
}
