/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
/* realpath */
#define _XOPEN_SOURCE 700
#include "html.h"

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../common/status.h"
#include "../io/files.h"

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

/* ------------------------------------------------- mathematics as text */

/* Greek letters the report's prose spells out, as whole words. */
static const struct {
  const char *word, *utf8;
} GREEK[] = {{"alpha", "\u03b1"}, {"beta", "\u03b2"},  {"delta", "\u03b4"},
             {"eta", "\u03b7"},   {"theta", "\u03b8"}, {"lambda", "\u03bb"},
             {"mu", "\u03bc"},    {"nu", "\u03bd"},    {"xi", "\u03be"},
             {"rho", "\u03c1"},   {"sigma", "\u03c3"}, {"omega", "\u03c9"},
             {"zeta", "\u03b6"},  {"Omega", "\u03a9"}, {"kappa", "\u03ba"},
             {"pi", "\u03c0"},    {"pbar", "p\u0304"}};

/* Names that are signs only where a subscript follows (sum_j), not as
 * words ("the sum of"). */
static const struct {
  const char *word, *utf8;
} INDEXED[] = {{"sum", "\u03a3"}};

/* Signs the prose writes in ASCII. */
static const struct {
  const char *ascii, *utf8;
} SIGNS[] = {{"!=", "\u2260"},
             {"<=", "\u2264"},
             {">=", "\u2265"},
             {"+-", "\u00b1"},
             {"n.D.n", "n\u00b7D\u00b7n"},
             {"->", "\u2192"},
             {"sqrt(", "\u221a("},
             {"sqrt pi", "\u221a\u03c0"},
             {" -int ", " \u2212\u222b "}};

/* The bytes of the Greek letter in UTF-8 at @p c (two bytes, U+0391 to
 * U+03C9), 0 where there is none. */
static size_t utf8_letter(const char *c) {
  const unsigned char a = (unsigned char)c[0];
  if (a != 0xCE && a != 0xCF) return 0; /* c[1] read only after a lead */
  const unsigned char b = (unsigned char)c[1];
  return (a == 0xCE && b >= 0x91 && b <= 0xBF) ||
                 (a == 0xCF && b >= 0x80 && b <= 0x89)
             ? 2
             : 0;
}

static int word_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
         (c >= '0' && c <= '9') || c == '_';
}

/* @p s[0..n) HTML-escaped into @p m. */
static void escaped(FILE *m, const char *s, size_t n) {
  for (size_t k = 0; k < n; k++)
    if (s[k] == '&')
      fputs("&amp;", m);
    else if (s[k] == '<')
      fputs("&lt;", m);
    else if (s[k] == '>')
      fputs("&gt;", m);
    else
      fputc(s[k], m);
}

/* A word written out: a Greek letter's name as the letter, else itself. */
static void word_out(FILE *m, const char *w, size_t n) {
  for (size_t g = 0; g < sizeof GREEK / sizeof GREEK[0]; g++)
    if (strlen(GREEK[g].word) == n && !strncmp(GREEK[g].word, w, n)) {
      fputs(GREEK[g].utf8, m);
      return;
    }
  escaped(m, w, n);
}

/* At a '^' after a word, a bracket or a letter (c[-1]): the superscript
 * ^2, ^-1 (digits, signed), ^R, ^num (letters) or ^(i+j) (a short bracket
 * without spaces) set in @p m. @return the bytes it took, 0 for none. */
static size_t superscript(FILE *m, const char *c) {
  if (!(word_char(c[-1]) || c[-1] == ')' || c[-1] == '|' ||
        (unsigned char)c[-1] >= 0x80))
    return 0;
  const char *t = NULL;
  size_t tl = 0, n = 0;
  if (c[1] == '(') {
    size_t e = 2;
    while (e < 12 && c[e] && c[e] != ')' && c[e] != ' ') e++;
    if (c[e] == ')' && e > 2) t = c + 2, tl = e - 2, n = e + 1;
  } else {
    size_t e = 1 + (c[1] == '-' || c[1] == '+');
    const size_t d0 = e;
    while (c[e] >= '0' && c[e] <= '9') e++;
    if (e == 1)
      while ((c[e] >= 'a' && c[e] <= 'z') || (c[e] >= 'A' && c[e] <= 'Z')) e++;
    if (e > d0) t = c + 1, tl = e - 1, n = e;
  }
  if (!t) return 0;
  fputs("<sup>", m);
  escaped(m, t, tl);
  fputs("</sup>", m);
  return n;
}

/* A Greek letter written in UTF-8 with a subscript word (η_eff) set in
 * @p m. @return the bytes it took, 0 for none. */
static size_t greek_sub(FILE *m, const char *c) {
  if (!utf8_letter(c) || c[2] != '_' || !word_char(c[3]) || c[3] == '_')
    return 0;
  size_t n = 3;
  while (word_char(c[n]) && c[n] != '_') n++;
  if (word_char(c[n]) || (c[n] == '.' && word_char(c[n + 1])))
    return 0; /* η_a_b, or a file's name: η_eff.csv */
  fwrite(c, 1, 2, m);
  fputs("<sub>", m);
  word_out(m, c + 3, n - 3);
  fputs("</sub>", m);
  return n;
}

/* Text @p s of the prose as HTML with its mathematics set: a word X_Y
 * (X one or two letters, a Greek letter's name, or sum; Y letters or
 * digits, or one Greek letter in UTF-8; one underscore) as X with Y
 * subscript, a Greek letter's name as the letter (pi, pbar too), a Greek
 * letter in UTF-8 with _Y likewise, superscripts (superscript()), and
 * !=, <=, >=, +-, ->, n.D.n, sqrt, -int as their signs; the rest
 * escaped. Returns 1 where anything was set. */
static int mathify(FILE *m, const char *s, const char *docs) {
  int any = 0;
  for (const char *c = s; *c;) {
    size_t g = 0; /* a sign first: n.D.n is one, not a word */
    while (g < sizeof SIGNS / sizeof SIGNS[0] &&
           strncmp(c, SIGNS[g].ascii, strlen(SIGNS[g].ascii)))
      g++;
    if (g < sizeof SIGNS / sizeof SIGNS[0]) {
      fputs(SIGNS[g].utf8, m);
      c += strlen(SIGNS[g].ascii);
      any = 1;
      continue;
    }
    /* docs/NAME.md: a link to the source tree's document (@p docs: its
     * folder from the page's, or NULL where there is none) */
    if (docs && !strncmp(c, "docs/", 5) && (c == s || !word_char(c[-1]))) {
      size_t n = 5;
      while (word_char(c[n]) || c[n] == '-') n++;
      if (n > 5 && !strncmp(c + n, ".md", 3)) {
        n += 3;
        fprintf(m, "<a href=\"%s/", docs);
        escaped(m, c + 5, n - 5);
        fputs("\">", m);
        escaped(m, c, n);
        fputs("</a>", m);
        any = 1;
        c += n;
        continue;
      }
    }
    if (word_char(*c) && (c == s || !word_char(c[-1]))) { /* a word */
      size_t n = 0;
      while (word_char(c[n])) n++;
      const char *us = memchr(c, '_', n);
      const size_t x = us ? (size_t)(us - c) : 0;
      int greek = 0; /* X a Greek letter's name (eta_num) */
      for (size_t q = 0; us && q < sizeof GREEK / sizeof GREEK[0]; q++)
        greek |= strlen(GREEK[q].word) == x && !strncmp(GREEK[q].word, c, x);
      const char *op = NULL; /* X a sign's name (sum_j) */
      for (size_t q = 0; us && q < sizeof INDEXED / sizeof INDEXED[0]; q++)
        if (strlen(INDEXED[q].word) == x && !strncmp(INDEXED[q].word, c, x))
          op = INDEXED[q].utf8;
      /* Y one letter written in UTF-8 (u_θ): the word ends at the '_' */
      const size_t u8 =
          us && x >= 1 && x <= 2 && n == x + 1 ? utf8_letter(c + n) : 0;
      const int sub = us && x >= 1 && (x <= 2 || greek || op) &&
                      (n - x - 1 >= 1 || u8) &&
                      !memchr(us + 1, '_', n - x - 1) &&
                      !(c[n] == '.' && word_char(c[n + 1])); /* file.ext */
      if (sub) {
        if (op)
          fputs(op, m);
        else
          word_out(m, c, x);
        fputs("<sub>", m);
        if (u8) {
          fwrite(c + n, 1, u8, m);
          n += u8;
        } else
          word_out(m, us + 1, n - x - 1);
        fputs("</sub>", m);
        any = 1;
      } else {
        const long before = ftell(m);
        word_out(m, c, n);
        any |= ftell(m) != before + (long)n;
      }
      c += n;
      continue;
    }
    size_t k = *c == '^' && c > s ? superscript(m, c) : 0;
    if (!k) k = greek_sub(m, c); /* η_eff */
    if (k) {
      any = 1;
      c += k;
      continue;
    }
    escaped(m, c, 1);
    c++;
  }
  return any;
}

/* The source tree's docs/ folder (the current folder's, where it holds
 * docs/theory.md) as a path from folder @p dir, into @p buf; NULL where
 * there is none. */
static const char *docs_from(const char *dir, char *buf, size_t len) {
  char d[PATH_MAX], t[PATH_MAX];
  struct stat sb;
  if (stat("docs/theory.md", &sb) != 0 || !realpath(dir, d) ||
      !realpath("docs", t))
    return NULL;
  size_t k = 0, common = 0; /* the longest common run of whole folders */
  while (d[k] && d[k] == t[k]) {
    if (d[k] == '/') common = k;
    k++;
  }
  if (!d[k] && t[k] == '/') common = k;
  size_t at = 0;
  for (const char *c = d + common; *c && at < len; c++) /* up from dir */
    if (*c == '/') at += (size_t)snprintf(buf + at, len - at, "../");
  if (at < len) snprintf(buf + at, len - at, "%s", t + common + 1);
  return at < len && strlen(buf) < len - 1 ? buf : NULL;
}

/* Every text node of @p doc (never code, a link's target or raw HTML) with
 * its mathematics set (mathify), as inline HTML in its place. */
static int set_mathematics(cmark_node *doc, const char *docs) {
  size_t n = 0, cap = 0;
  cmark_node **text = NULL;
  cmark_iter *it = cmark_iter_new(doc);
  if (!it) return VSPH_ENOMEM;
  for (cmark_event_type ev; (ev = cmark_iter_next(it)) != CMARK_EVENT_DONE;) {
    cmark_node *nd = cmark_iter_get_node(it);
    if (ev != CMARK_EVENT_ENTER || cmark_node_get_type(nd) != CMARK_NODE_TEXT)
      continue;
    if (n == cap) {
      cap = cap ? 2 * cap : 256;
      cmark_node **t = realloc(text, cap * sizeof *t);
      if (!t) {
        free(text);
        cmark_iter_free(it);
        return VSPH_ENOMEM;
      }
      text = t;
    }
    text[n++] = nd;
  }
  cmark_iter_free(it);
  int st = VSPH_OK;
  for (size_t k = 0; k < n && !st; k++) {
    const char *lit = cmark_node_get_literal(text[k]);
    int in_link = 0; /* never a link inside a link's text */
    for (cmark_node *up = cmark_node_parent(text[k]); up && !in_link;
         up = cmark_node_parent(up))
      in_link = cmark_node_get_type(up) == CMARK_NODE_LINK;
    char *html = NULL;
    size_t len = 0;
    FILE *m = lit ? open_memstream(&html, &len) : NULL;
    if (!m) continue;
    const int any = mathify(m, lit, in_link ? NULL : docs);
    if (fclose(m) != 0) {
      st = VSPH_ENOMEM;
    } else if (any) {
      cmark_node *h = cmark_node_new(CMARK_NODE_HTML_INLINE);
      if (!h || !cmark_node_set_literal(h, html) ||
          !cmark_node_insert_before(text[k], h)) {
        if (h) cmark_node_free(h);
        st = VSPH_ENOMEM;
      } else {
        cmark_node_free(text[k]); /* unlinks it */
      }
    }
    free(html);
  }
  free(text);
  return st;
}

/* Markdown file @p md of folder @p dir as the body of an HTML page, with
 * its mathematics set, into *@p body (the caller frees it). */
static int render_body(const char *dir, const char *md, char **body) {
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
  char docs[4096];
  if (doc && set_mathematics(doc, docs_from(dir, docs, sizeof docs))) {
    cmark_node_free(doc);
    cmark_parser_free(ps);
    free(text);
    VSPH_FAIL(VSPH_ENOMEM, "cannot set the report's mathematics");
  }
  *body = cmark_render_html(doc, CMARK_OPT_DEFAULT | CMARK_OPT_UNSAFE,
                            cmark_parser_get_syntax_extensions(ps));
  cmark_node_free(doc);
  cmark_parser_free(ps);
  free(text);
  if (!*body) VSPH_FAIL(VSPH_ENOMEM, "cmark-gfm rendered nothing");
  return VSPH_OK;
}

/* The page's head into @p f, titled @p title, with its style sheet. */
static void write_head(FILE *f, const char *title) {
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
          /* a figure (SVG) across the column: its text at the body's size
           * (io/plot.c sets it two points up for this) */
          "img[src^=\"data:image/svg\"]{width:100%%}\n"
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
}

/* HTML @p body copied into @p f, each figure of folder @p dir it shows
 * (PNG or SVG) embedded. */
static void write_body(FILE *f, const char *dir, const char *body) {
  /* src="X.png" or "X.svg" replaced by an embedded data URI (an <img> of
   * SVG keeps the figure vector graphics) */
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
      char path[1024];
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
}

int vsph_html_render(const char *dir, const char *md, const char *html,
                     const char *title) {
  char *body = NULL;
  const int st = render_body(dir, md, &body);
  if (st) return st;
  FILE *f = vsph_files_open(dir, html);
  if (!f) {
    free(body);
    return VSPH_EIO;
  }
  write_head(f, title);
  write_body(f, dir, body);
  fputs("</body></html>\n", f);
  free(body);
  return vsph_files_close(f, dir, html);
}
