/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_IO_FILES_H
#define VSPH_IO_FILES_H

#include <stddef.h>
#include <stdio.h>

#include "../common/api.h"

/** @file files.h
 *  @brief Files as vsph writes them: each result file is written to a
 *  temporary name and renamed into place when complete, so a reader never
 *  sees half a file; folders are created with their parents; whole files
 *  are read back for the report. The lowest layer of io/: every other
 *  writer goes through it. A NULL argument is refused: VSPH_EINVAL
 *  where a status is returned, else NULL (reported where the function
 *  reports its failures), or nothing. */

/** @brief Open DIR/NAME.tmp for writing; NULL after reporting on failure.
 *  @note Pair it with vsph_files_close, which renames it to DIR/NAME. */
VSPH_API FILE *vsph_files_open(const char *dir, const char *name);

/** @brief Close a file from vsph_files_open and rename it into place,
 *  checking the stream's error flag and fclose first.
 *  @return VSPH_OK, or VSPH_EIO (the temporary is removed; the message
 *  names the file). */
VSPH_API int vsph_files_close(FILE *f, const char *dir, const char *name);

/** @brief Close a file from vsph_files_open without keeping it (after a
 *  failure elsewhere): the temporary is removed. */
VSPH_API void vsph_files_discard(FILE *f, const char *dir, const char *name);

/** @brief Write @p text to DIR/NAME atomically. @return VSPH_OK or
 *  VSPH_EIO. */
VSPH_API int vsph_files_write(const char *dir, const char *name,
                              const char *text);

/** @brief Create directory @p dir and its parents. @return VSPH_OK,
 *  VSPH_EINVAL (a path that cannot be made: a file in it, no such parent,
 *  no permission, read-only), VSPH_EIO (the device failed). */
VSPH_API int vsph_files_mkdir(const char *dir);

/** @brief May vsph write the file @p path (by a temporary and a rename)?
 *  Only where nothing is there yet or a regular file is: a device, FIFO,
 *  socket, folder or symbolic link there would be replaced by the rename
 *  (as root, /dev/full became a regular file), so it is refused.
 *  @return VSPH_OK, or VSPH_EINVAL (reported, naming the path and what is
 *  there). */
VSPH_API int vsph_files_target(const char *path);

/** @brief Replace regular file DIR/NAME by a new file (a temporary and a
 *  rename: a new inode, so a hard link to the old one keeps it) holding
 *  its first @p keep bytes, and open that for appending.
 *  @return the stream, or NULL (errno set) when it is shorter than
 *  @p keep, not a regular file, or cannot be written. */
VSPH_API FILE *vsph_files_reopen(const char *dir, const char *name, long keep);

/** @brief A whole file as a NUL-terminated string (caller frees), its
 *  length in @p len if not NULL; NULL if it cannot be read (not reported:
 *  a missing cache file is normal). */
VSPH_API char *vsph_files_slurp(const char *path, size_t *len);

#endif /* VSPH_IO_FILES_H */
