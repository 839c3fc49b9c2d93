/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_TEXT_H
#define VSPH_REPORTS_TEXT_H

#include <stddef.h>
#include <stdio.h>

/** @file text.h
 *  @brief The report's prose, kept as data: Markdown files under
 *  reports/text/, one per part, cut into named blocks by lines
 *  "<!-- @name -->" and compiled into the binary (scripts/embed-text). A
 *  block may hold placeholders {{key}} that the part fills with the figures
 *  it measured; a placeholder without a value is an error, so the prose and
 *  the code cannot drift apart silently. */

/** One block of prose: "part.name" and its Markdown. */
struct vsph_text_block {
  const char *name; /*!< "FILE.BLOCK" */
  const char *text; /*!< Markdown with {{key}} placeholders */
};

/** The blocks (generated). */
extern const struct vsph_text_block vsph_text_blocks[];
/** Their number (generated). */
extern const unsigned long vsph_text_nblocks;

/** Most values one block may use. */
#define VSPH_TEXT_MAXVARS 24

/** Values for the placeholders of one block. */
struct vsph_text_vars {
  size_t n;                             /*!< values set */
  char key[VSPH_TEXT_MAXVARS][32];      /*!< placeholder names */
  char val[VSPH_TEXT_MAXVARS][1024];    /*!< their text */
  unsigned char cut[VSPH_TEXT_MAXVARS]; /*!< 1: cut short (writing it fails) */
};

/** @brief No values. */
void vsph_text_clear(struct vsph_text_vars *tv);

/** @brief Set {{key}} to the printf-formatted text (a later set of the
 *  same key replaces it). @return VSPH_OK or VSPH_EINVAL (too many, or a
 *  text too long for the value, which then fails the block that uses
 *  it). */
int vsph_text_set(struct vsph_text_vars *tv, const char *key, const char *fmt,
                  ...);

/** @brief The block called @p name, or NULL. */
const char *vsph_text_get(const char *name);

/** @brief Write block @p name to @p out with its placeholders filled from
 *  @p tv (NULL: none). @return VSPH_OK, or VSPH_EINVAL (no such block, or a
 *  placeholder without a value: the message names it). */
int vsph_text_write(FILE *out, const char *name,
                    const struct vsph_text_vars *tv);

/** @brief Block @p name rendered into @p buf (at most @p len bytes,
 *  truncated if longer) without its trailing newlines: for text that sits
 *  inside a line, such as a caption. @return as vsph_text_write. */
int vsph_text_format(char *buf, size_t len, const char *name,
                     const struct vsph_text_vars *tv);

#endif /* VSPH_REPORTS_TEXT_H */
