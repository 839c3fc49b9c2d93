/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "files.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../common/status.h"

/* Longest path the writers build. */
enum { PATH_MAX_LEN = 4096 };

FILE *vsph_files_open(const char *dir, const char *name) {
  if (!dir || !name) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "vsph_files_open: a NULL argument");
    return NULL;
  }
  char path[PATH_MAX_LEN];
  snprintf(path, sizeof path, "%s/%s.tmp", dir, name);
  FILE *f = fopen(path, "w");
  if (!f)
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot write %s: %s",
                       path, strerror(errno));
  return f;
}

int vsph_files_close(FILE *f, const char *dir, const char *name) {
  if (!f || !dir || !name) {
    if (f) fclose(f);
    VSPH_FAIL(VSPH_EINVAL, "vsph_files_close: a NULL argument");
  }
  char tmp[PATH_MAX_LEN], path[PATH_MAX_LEN];
  snprintf(tmp, sizeof tmp, "%s/%s.tmp", dir, name);
  snprintf(path, sizeof path, "%s/%s", dir, name);
  errno = 0;
  const int bad = ferror(f);
  const int closed = fclose(f);
  if (bad || closed != 0 || rename(tmp, path) != 0) {
    const int err = errno;
    remove(tmp);
    VSPH_FAIL(VSPH_EIO, "cannot write %s: %s", path,
              err ? strerror(err) : "write error");
  }
  return VSPH_OK;
}

void vsph_files_discard(FILE *f, const char *dir, const char *name) {
  if (f) fclose(f);
  if (!dir || !name) return;
  char tmp[PATH_MAX_LEN];
  snprintf(tmp, sizeof tmp, "%s/%s.tmp", dir, name);
  remove(tmp);
}

int vsph_files_write(const char *dir, const char *name, const char *text) {
  if (!dir || !name || !text)
    VSPH_FAIL(VSPH_EINVAL, "vsph_files_write: a NULL argument");
  FILE *f = vsph_files_open(dir, name);
  if (!f) return VSPH_EIO;
  fputs(text, f);
  return vsph_files_close(f, dir, name);
}

/* A folder that cannot be made where it was asked for (a file in the
 * path, no such parent, no permission, a read-only file system) is a bad
 * path: VSPH_EINVAL (exit 2); a device that fails (full, I/O): VSPH_EIO. */
static int mkdir_failed(const char *path) {
  const int e = errno;
  const int bad = e == ENOTDIR || e == ENOENT || e == EACCES || e == EPERM ||
                  e == EROFS || e == ENAMETOOLONG || e == ELOOP;
  VSPH_FAIL(bad ? VSPH_EINVAL : VSPH_EIO, "cannot create %s: %s", path,
            strerror(e));
}

int vsph_files_mkdir(const char *dir) {
  char buf[PATH_MAX_LEN];
  if (!dir) VSPH_FAIL(VSPH_EINVAL, "vsph_files_mkdir: a NULL argument");
  if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf)
    VSPH_FAIL(VSPH_EINVAL, "folder name too long: %.60s...", dir);
  for (char *c = buf + 1; *c; c++) {
    if (*c != '/') continue;
    *c = '\0';
    if (mkdir(buf, 0777) != 0 && errno != EEXIST) return mkdir_failed(buf);
    *c = '/';
  }
  if (mkdir(buf, 0777) != 0 && errno != EEXIST) return mkdir_failed(buf);
  struct stat sb; /* there already: a folder, or a link to one */
  if (stat(buf, &sb) != 0 || !S_ISDIR(sb.st_mode))
    VSPH_FAIL(VSPH_EINVAL, "%s exists and is not a folder", buf);
  return VSPH_OK;
}

int vsph_files_target(const char *path) {
  struct stat sb;
  if (!path) VSPH_FAIL(VSPH_EINVAL, "vsph_files_target: a NULL argument");
  if (lstat(path, &sb) != 0) {
    if (errno == ENOENT) return VSPH_OK; /* nothing there yet */
    VSPH_FAIL(VSPH_EINVAL, "%s: %s", path, strerror(errno));
  }
  if (S_ISREG(sb.st_mode)) return VSPH_OK;
  const char *what = S_ISDIR(sb.st_mode)    ? "a folder"
                     : S_ISLNK(sb.st_mode)  ? "a symbolic link"
                     : S_ISFIFO(sb.st_mode) ? "a FIFO"
                     : S_ISSOCK(sb.st_mode) ? "a socket"
                                            : "a device";
  VSPH_FAIL(VSPH_EINVAL,
            "%s is %s, not a regular file: vsph replaces only regular files",
            path, what);
}

char *vsph_files_slurp(const char *path, size_t *len) {
  /* a regular file only: a FIFO or a device would block or never end */
  if (!path) return NULL;
  const int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  struct stat sb;
  if (fd < 0) return NULL;
  if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
    close(fd);
    return NULL;
  }
  FILE *f = fdopen(fd, "rb");
  if (!f) {
    close(fd);
    return NULL;
  }
  char *b = NULL;
  long n = -1;
  if (fseek(f, 0, SEEK_END) == 0) n = ftell(f);
  if (n >= 0 && fseek(f, 0, SEEK_SET) == 0) b = malloc((size_t)n + 1);
  if (b && fread(b, 1, (size_t)n, f) != (size_t)n) {
    free(b);
    b = NULL;
  }
  fclose(f);
  if (!b) return NULL;
  b[n] = '\0';
  if (len) *len = (size_t)n;
  return b;
}

FILE *vsph_files_reopen(const char *dir, const char *name, long keep) {
  char path[PATH_MAX_LEN], tmp[PATH_MAX_LEN];
  if (!dir || !name) {
    errno = EINVAL;
    return NULL;
  }
  snprintf(path, sizeof path, "%s/%s", dir, name);
  snprintf(tmp, sizeof tmp, "%s/%s.tmp", dir, name);
  const int fd = open(path, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return NULL;
  struct stat sb;
  FILE *in = NULL;
  if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode) || keep < 0 ||
      sb.st_size < (off_t)keep || !(in = fdopen(fd, "rb"))) {
    close(fd);
    errno = EINVAL;
    return NULL;
  }
  FILE *out = fopen(tmp, "wb");
  char buf[1 << 16];
  long left = keep;
  while (out && left > 0) {
    const size_t want = left < (long)sizeof buf ? (size_t)left : sizeof buf;
    const size_t got = fread(buf, 1, want, in);
    if (got == 0 || fwrite(buf, 1, got, out) != got) break;
    left -= (long)got;
  }
  fclose(in);
  int ok = out != NULL && left == 0;
  if (out && fclose(out) != 0) ok = 0;
  if (!ok || rename(tmp, path) != 0) {
    const int e = errno ? errno : EIO;
    remove(tmp);
    errno = e;
    return NULL;
  }
  return fopen(path, "a");
}
