/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#ifndef VSPH_REPORTS_HTML_H
#define VSPH_REPORTS_HTML_H

/** @file html.h
 *  @brief A Markdown report rendered to one self-contained HTML page with
 *  cmark-gfm (GitHub-flavoured tables), every local PNG or SVG embedded as
 *  a data URI (an SVG figure stays vector graphics) so the page can be
 *  mailed or archived alone. */

/** @brief Render DIR/MD to DIR/HTML (atomically) under @p title.
 *  @return VSPH_OK, VSPH_EIO or VSPH_ENOMEM. */
int vsph_html_render(const char *dir, const char *md, const char *html,
                     const char *title);

#endif /* VSPH_REPORTS_HTML_H */
