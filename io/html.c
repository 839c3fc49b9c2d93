/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "html.h"

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../common/status.h"
#include "files.h"

static void base64(FILE *f, const unsigned char *d, size_t n) {
  static const char tb[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  for (size_t i = 0; i < n; i += 3) {
    const unsigned v = (unsigned)d[i] << 16 |
                       (i + 1 < n ? (unsigned)d[i + 1] << 8 : 0) |
                       (i + 2 < n ? d[i + 2] : 0);
    fputc(tb[v >> 18 & 63], f);
    fputc(tb[v >> 12 & 63], f);
    fputc(i + 1 < n ? tb[v >> 6 & 63] : '=', f);
    fputc(i + 2 < n ? tb[v & 63] : '=', f);
  }
}

int vsph_html_render(const char *dir, const char *md, const char *html,
                     const char *title) {
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", dir, md);
  size_t len;
  char *text = vsph_files_slurp(path, &len);
  if (!text) VSPH_FAIL(VSPH_EIO, "cannot read %s", path);
  cmark_gfm_core_extensions_ensure_registered();
  /* UNSAFE keeps the report's own anchors (<a id>) for its links; the
   * Markdown is vsph's own output, never a user's */
  cmark_parser *ps = cmark_parser_new(CMARK_OPT_DEFAULT | CMARK_OPT_UNSAFE);
  cmark_syntax_extension *table = cmark_find_syntax_extension("table");
  if (!ps || !table) {
    free(text);
    if (ps) cmark_parser_free(ps);
    VSPH_FAIL(VSPH_ENOMEM, "cannot start cmark-gfm");
  }
  cmark_parser_attach_syntax_extension(ps, table);
  cmark_parser_feed(ps, text, len);
  cmark_node *doc = cmark_parser_finish(ps);
  char *body = cmark_render_html(doc, CMARK_OPT_DEFAULT | CMARK_OPT_UNSAFE,
                                 cmark_parser_get_syntax_extensions(ps));
  cmark_node_free(doc);
  cmark_parser_free(ps);
  free(text);
  if (!body) VSPH_FAIL(VSPH_ENOMEM, "cmark-gfm rendered nothing");
  FILE *f = vsph_files_open(dir, html);
  if (!f) {
    free(body);
    return VSPH_EIO;
  }
  fprintf(f,
          "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\">\n"
          "<title>%s</title>\n<style>\n"
          "body{font-family:sans-serif;max-width:70em;margin:2em auto;"
          "padding:0 1em;line-height:1.45;color:#222}\n"
          "table{border-collapse:collapse;margin:1em 0;font-size:90%%}\n"
          /* prose left, numbers right: a column is right-aligned only
           * where its Markdown says so (---:), which cmark-gfm writes as
           * align="right" */
          "th,td{border:1px solid #bbb;padding:.25em .6em;text-align:left;"
          "vertical-align:top}\n"
          "th[align=right],td[align=right]{text-align:right}\n"
          "th[align=center],td[align=center]{text-align:center}\n"
          "th{background:#eee}\nimg{max-width:100%%;height:auto;border:1px "
          "solid #ddd}\n"
          "code{background:#f4f4f4}\n"
          /* the verdict classes of the claims table */
          ".v{display:inline-block;padding:0 .35em;border-radius:.25em;"
          "font-weight:bold;white-space:nowrap}\n"
          ".v-rep{background:#d4edda;color:#14532d}\n"
          ".v-sub{background:#d1ecf1;color:#0c5460}\n"
          ".v-part{background:#fff3cd;color:#7a4d00}\n"
          ".v-diff{background:#f8d7da;color:#842029}\n"
          ".v-none{background:#e2e3e5;color:#41464b}\n"
          "</style></head><body>\n",
          title);
  /* Copy the body, replacing src="X.png" or "X.svg" by an embedded data
   * URI (an <img> of SVG keeps the figure vector graphics). */
  const char *c = body;
  for (;;) {
    const char *m = strstr(c, "src=\"");
    if (!m) break;
    const char *q = strchr(m + 5, '"');
    if (!q) break;
    const size_t nlen = (size_t)(q - (m + 5));
    fwrite(c, 1, (size_t)(m - c), f);
    char name[512];
    snprintf(name, sizeof name, "%.*s", (int)(nlen < 500 ? nlen : 500), m + 5);
    size_t plen = 0;
    char *img = NULL;
    const char *mime = NULL;
    if (nlen > 4 && !strchr(name, ':')) {
      const char *ext = name + strlen(name) - 4;
      mime = !strcmp(ext, ".png")   ? "image/png"
             : !strcmp(ext, ".svg") ? "image/svg+xml"
                                    : NULL;
    }
    if (mime) {
      snprintf(path, sizeof path, "%s/%s", dir, name);
      img = vsph_files_slurp(path, &plen);
    }
    if (img) {
      fprintf(f, "src=\"data:%s;base64,", mime);
      base64(f, (const unsigned char *)img, plen);
      fputc('"', f);
      free(img);
    } else {
      fwrite(m, 1, (size_t)(q - m + 1), f);
    }
    c = q + 1;
  }
  fputs(c, f);
  fputs("</body></html>\n", f);
  free(body);
  return vsph_files_close(f, dir, html);
}
