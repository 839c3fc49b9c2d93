/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* O_TMPFILE (Linux): a file with no name, none left by a kill */
#define _GNU_SOURCE 1
#include "scratch.h"

#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

FILE *vsph_scratch_open(const char *dir, const char *prefix, char **kept) {
  if (kept) *kept = NULL;
  if (!dir) dir = getenv("TMPDIR");
  if (!dir || !*dir) dir = "/tmp";
  if (!prefix) prefix = "vsph-";
#ifdef O_TMPFILE
  { /* no name at any moment: a process killed at any point leaves none */
    const int tfd = open(dir, O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    FILE *t = tfd >= 0 ? fdopen(tfd, "w+b") : NULL;
    if (t) return t;
    if (tfd >= 0) close(tfd);
  } /* a file system without it: a name, unlinked at once */
#endif
  const size_t nd = strlen(dir), np = strlen(prefix);
  char *path = malloc(nd + np + 8);
  if (!path) return NULL;
  memcpy(path, dir, nd);
  path[nd] = '/';
  memcpy(path + nd + 1, prefix, np);
  memcpy(path + nd + 1 + np, "XXXXXX", 7);
  const int fd = mkstemp(path);
  FILE *f = NULL;
  if (fd >= 0) {
    (void)fcntl(fd, F_SETFD, FD_CLOEXEC); /* not a child's to hold */
    f = fdopen(fd, "w+b");
    if (!f) close(fd);
  }
  if (fd >= 0 && (!f || unlink(path) != 0)) {
    if (f && kept) { /* cannot unlink while open: the caller removes it */
      *kept = path;
      return f;
    }
    if (f) fclose(f);
    unlink(path);
    f = NULL;
  }
  free(path);
  return f;
}
