/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_COMMON_SCRATCH_H
#define VSPH_COMMON_SCRATCH_H

#include <stdio.h>

/** @file scratch.h
 *  @brief Scratch files: data written now and read back soon, kept out of
 *  memory (a snapshot's compressed arrays, the state a snapshot within a
 *  step waits in). */

/** @brief A new file in @p dir (NULL: TMPDIR, else /tmp), open for
 *  update, closed on exec, with no name (O_TMPFILE, where the system and
 *  the file system have it: nothing can stay behind, even after a kill);
 *  else named @p prefix and six random characters (mkstemp) and unlinked
 *  at once, so that nothing stays behind but after a kill between the
 *  two (a run's folder knows its snapshots' scratch name). Where the
 *  file system cannot unlink an open file: with @p kept not NULL, its name
 *  (malloc'd) goes there for the caller to remove after closing it (else
 *  *kept is NULL); with @p kept NULL, the file is removed and NULL
 *  returned.
 *  @return the file, or NULL (nothing left) where none can be made. */
FILE *vsph_scratch_open(const char *dir, const char *prefix, char **kept);

#endif /* VSPH_COMMON_SCRATCH_H */
