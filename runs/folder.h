/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_RUNS_FOLDER_H
#define VSPH_RUNS_FOLDER_H

#include <stddef.h>

/** @file folder.h
 *  @brief The one contract of every folder vsph writes (a scene run, a
 *  shear test, a report).
 *
 *  - **Marker.** A folder is vsph's only if it holds the marker
 *    `.vsph-folder`, which vsph alone writes and which names the kind of
 *    folder. A folder that is new or empty is claimed (the marker is
 *    written); one that is not empty and has no marker, or has another
 *    kind's marker, or holds anything vsph does not write, is refused
 *    before anything in it is touched.
 *  - **Lock.** A writer holds a lock (fcntl) on `.vsph-lock` while it
 *    works; a second writer is refused, naming the holder's pid. The
 *    system drops the lock when the holder dies.
 *  - **Seal.** A folder's `key.txt` is written last: the parameters as
 *    given (the cache key), then every file of the folder with its size
 *    and CRC-32. vsph_folder_verify checks them all: a truncated, edited,
 *    added or forged file breaks the seal, by name.
 *  - Every path vsph meets inside a folder must be a regular file (or,
 *    where a kind allows it, a folder): links, FIFOs, devices and sockets
 *    are refused. */

/** The marker and lock files' names. */
#define VSPH_FOLDER_MARKER ".vsph-folder"
#define VSPH_FOLDER_LOCK ".vsph-lock"

/** What a kind of folder holds: vsph_folder_kind::owns returns it for a
 *  name vsph writes there. */
enum vsph_folder_entry {
  VSPH_FOLDER_FOREIGN = 0, /*!< not vsph's */
  VSPH_FOLDER_FILE = 1,    /*!< a regular file vsph writes */
  VSPH_FOLDER_SUBDIR = 2   /*!< a folder vsph makes */
};

/** A kind of folder. */
struct vsph_folder_kind {
  const char *name; /*!< e.g. "scene run", written in the marker */
  /** vsph_folder_entry of @p name in such a folder */
  int (*owns)(const char *name);
};

/** The kinds vsph writes. */
extern const struct vsph_folder_kind vsph_folder_scene_run;
extern const struct vsph_folder_kind vsph_folder_shear_test;
extern const struct vsph_folder_kind vsph_folder_report;
extern const struct vsph_folder_kind vsph_folder_archive;

/** @brief FNV-1a 64 of @p s: the fingerprint of a key that the plan
 *  (runs/jobs) and the archive's index (runs/archive) print. */
unsigned long long vsph_folder_fingerprint(const char *s);

/** @brief The kind @p dir's marker names, or NULL (no marker, or not one
 *  of vsph's kinds). Never blocks: a marker that is not a regular file is
 *  not read. */
const struct vsph_folder_kind *vsph_folder_kind_of(const char *dir);

/** A claimed folder: the lock is held until vsph_folder_release. */
struct vsph_folder {
  char dir[4096];                      /*!< the folder */
  const struct vsph_folder_kind *kind; /*!< its kind */
  int fd;                              /*!< the lock file; -1: none */
  int made_marker;                     /*!< 1: the claim wrote the marker */
  int made_lock; /*!< 1: the claim created the lock file */
  int nmade;     /*!< folders the claim made (mkdir), outermost first */
  char made[8][4096];
  /** the CRC-32s vsph_folder_manifest computed, by file identity (inode,
   *  size, modification and change times): a file unchanged since is not
   *  read again. Freed by vsph_folder_release. */
  struct vsph_folder_crc *crcs;
  size_t ncrcs;
};

/** @brief Judge @p dir for a writer of kind @p kind without touching it:
 *  VSPH_OK if it is absent, empty, or a folder of that kind holding only
 *  what vsph writes there; else VSPH_EINVAL with one line naming what is
 *  wrong. Nothing is created. */
int vsph_folder_judge(const char *dir, const struct vsph_folder_kind *kind);

/** @brief Claim @p dir: judge it (vsph_folder_judge), create it if
 *  absent, take its lock, judge it again under the lock and write the
 *  marker if it is missing. Refusals (VSPH_EINVAL, exit 2) change
 *  nothing: a folder that cannot be made or written (no permission, a
 *  read-only file system) is refused too.
 *  @return VSPH_OK (release with vsph_folder_release), VSPH_EINVAL,
 *  VSPH_EIO. */
int vsph_folder_claim(struct vsph_folder *f, const char *dir,
                      const struct vsph_folder_kind *kind);

/** @brief Drop the lock (the lock file stays, as vsph's); idempotent. */
void vsph_folder_release(struct vsph_folder *f);

/** @brief Give the folder back as it was found, after a refusal that came
 *  only once it was claimed: the marker and the lock file go if the claim
 *  made them, and so do the folders it made (if empty), innermost first;
 *  nothing else is removed. Releases the lock. */
void vsph_folder_abandon(struct vsph_folder *f);

/** @brief Remove every file vsph writes in the claimed folder but the
 *  marker, the lock and the names in @p keep (NULL-terminated, may be
 *  NULL): key.txt first, then run.json, then the rest, so nothing can
 *  vouch for a half-cleared folder. Sub-folders are left alone.
 *  @return VSPH_OK or VSPH_EIO. */
int vsph_folder_clear(const struct vsph_folder *f, const char *const *keep);

/** @brief Seal the claimed folder: write key.txt (atomically) as @p key,
 *  a line "files:", then "NAME SIZE CRC32" for every regular file vsph
 *  writes there, sorted, but the marker, the lock, key.txt and the names
 *  in @p skip (NULL-terminated, may be NULL).
 *  @return VSPH_OK, VSPH_EIO (the file named), VSPH_ENOMEM. */
int vsph_folder_seal(const struct vsph_folder *f, const char *key,
                     const char *const *skip);

/** @brief The same, with file @p name (not yet written, or to be
 *  replaced) listed as holding @p content: write it after the seal, so
 *  that a process killed between the two leaves a broken seal rather than
 *  a file the seal does not vouch for. */
int vsph_folder_seal_with(const struct vsph_folder *f, const char *key,
                          const char *const *skip, const char *name,
                          const char *content);

/** @brief Does @p dir's seal hold for @p key? (@p kind NULL: the kind
 *  its marker names.) 1: key.txt's parameters are
 *  @p key and every file it lists has its size and CRC-32, and no other
 *  file vsph writes is there (the names in @p skip aside). 0: no seal or
 *  another key (a run not made, or made with other settings). -1: the
 *  key matches but a file is missing, changed or added: @p why (may be
 *  NULL) names it. Never reports; never blocks (non-regular files are
 *  not read). */
int vsph_folder_verify(const char *dir, const struct vsph_folder_kind *kind,
                       const char *key, const char *const *skip, char *why,
                       size_t len);

/** @brief The claimed folder's files as a checkpoint sees them: "NAME
 *  SIZE CRC32" lines, sorted, for every regular file vsph writes there
 *  but the marker, the lock, key.txt, temporaries and @p skip. A file
 *  whose inode, size and modification and change times (ns) are those of
 *  an earlier call is not read again (f->crcs): a run's snapshots are
 *  read once, not at every checkpoint. Caller frees; NULL (not reported)
 *  on failure. */
char *vsph_folder_manifest(struct vsph_folder *f, const char *const *skip);

/** @brief Does the claimed folder still hold what @p manifest lists? 1:
 *  every file is there with its size and CRC-32 (those named in @p grow
 *  may have grown since: their first SIZE bytes count) and no other file
 *  of vsph's (temporaries and @p skip aside); else -1 with what differs
 *  in @p why. The files it reads whole go to f->crcs. Never reports. */
int vsph_folder_manifest_holds(struct vsph_folder *f, const char *manifest,
                               const char *const *grow, const char *const *skip,
                               char *why, size_t wlen);

/** @brief Read file @p name of the claimed folder once, now (just after
 *  writing it, while the system still caches it), so that the manifests
 *  that follow do not read it again while it is unchanged.
 *  @return VSPH_OK, or VSPH_EIO (not reported) when it is not a regular
 *  file or cannot be read. */
int vsph_folder_note(struct vsph_folder *f, const char *name);

/** @brief Remove the temporaries (NAME.tmp of a name vsph writes) that a
 *  process killed while writing left in the claimed folder.
 *  @return VSPH_OK or VSPH_EIO. */
int vsph_folder_clear_tmp(const struct vsph_folder *f);

/** @brief The CRC-32 (zlib's) and size of regular file @p path.
 *  @return VSPH_OK, or VSPH_EIO (not reported) when it is not a regular
 *  file or cannot be read. */
int vsph_folder_checksum(const char *path, unsigned long *crc, size_t *size);

#endif /* VSPH_RUNS_FOLDER_H */
