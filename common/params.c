/* Copyright (C) 2026 the vsph developers.
 * SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE). */
#include "params.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <yaml.h>

#include "status.h"

enum { KEY_MAX = 128, VALUE_MAX = 512 };

/* The largest parameter file read (bytes): parameter files are a few
 * hundred bytes; anything near this is a mistake, refused before parsing. */
static const long FILE_MAX = 1 << 20;

struct entry {
  char key[KEY_MAX];
  char value[VALUE_MAX];
  int used;
  int given;       /* 1: set or read from a file; 0: a default filled in */
  unsigned source; /* the vsph_params_read that stored it; 0: not a file */
};

/* Entries are allocated one by one, so a value pointer handed out by a
 * getter stays valid for the store's lifetime. An open-addressing hash
 * index over the entries keeps lookups O(1), so reading a file is linear
 * in its size. */
struct vsph_params {
  struct entry **e;  /* insertion order */
  size_t n, cap;     /* entries, allocated length of e */
  size_t *slot;      /* hash index: entry index + 1, 0 empty */
  size_t nslot;      /* a power of two, at least 2 n */
  unsigned nsources; /* files read so far */
};

struct vsph_params *vsph_params_alloc(void) {
  struct vsph_params *prm = calloc(1, sizeof *prm);
  if (!prm)
    vsph_status_report(VSPH_ENOMEM, __FILE__, __LINE__,
                       "cannot allocate a parameter store");
  return prm;
}

void vsph_params_free(struct vsph_params *prm) {
  if (!prm) return;
  for (size_t i = 0; i < prm->n; i++) free(prm->e[i]);
  free(prm->e);
  free(prm->slot);
  free(prm);
}

/* FNV-1a, 64 bit. */
static size_t hash(const char *key) {
  unsigned long long h = 1469598103934665603ull;
  for (const unsigned char *c = (const unsigned char *)key; *c; c++) {
    h ^= *c;
    h *= 1099511628211ull;
  }
  return (size_t)h;
}

/* The slot holding key, or the empty slot where it would go. */
static size_t probe(const struct vsph_params *prm, const char *key) {
  const size_t mask = prm->nslot - 1;
  size_t s = hash(key) & mask;
  while (prm->slot[s] && strcmp(prm->e[prm->slot[s] - 1]->key, key))
    s = (s + 1) & mask;
  return s;
}

static struct entry *find(const struct vsph_params *prm, const char *key) {
  if (prm->nslot == 0) return NULL;
  const size_t s = probe(prm, key);
  return prm->slot[s] ? prm->e[prm->slot[s] - 1] : NULL;
}

/* Double the hash index and re-insert every entry. */
static int grow_index(struct vsph_params *prm) {
  const size_t nslot = prm->nslot ? 2 * prm->nslot : 64;
  size_t *slot = calloc(nslot, sizeof *slot);
  if (!slot) VSPH_FAIL(VSPH_ENOMEM, "cannot grow the parameter store");
  free(prm->slot);
  prm->slot = slot;
  prm->nslot = nslot;
  for (size_t i = 0; i < prm->n; i++)
    prm->slot[probe(prm, prm->e[i]->key)] = i + 1;
  return VSPH_OK;
}

static int put(struct vsph_params *prm, const char *key, const char *value,
               int used, unsigned source) {
  if (strlen(key) >= KEY_MAX || strlen(value) >= VALUE_MAX)
    VSPH_FAIL(VSPH_EINVAL, "parameter '%.40s' or its value is too long", key);
  struct entry *e = find(prm, key);
  if (!e) {
    if (2 * (prm->n + 1) > prm->nslot) {
      const int st = grow_index(prm);
      if (st) return st;
    }
    if (prm->n == prm->cap) {
      const size_t cap = prm->cap ? 2 * prm->cap : 32;
      struct entry **ne = realloc(prm->e, cap * sizeof *ne);
      if (!ne) VSPH_FAIL(VSPH_ENOMEM, "cannot grow the parameter store");
      prm->e = ne;
      prm->cap = cap;
    }
    e = malloc(sizeof *e);
    if (!e) VSPH_FAIL(VSPH_ENOMEM, "cannot grow the parameter store");
    prm->slot[probe(prm, key)] = prm->n + 1;
    prm->e[prm->n++] = e;
    snprintf(e->key, KEY_MAX, "%s", key);
    e->used = 0;
    e->given = 0;
  }
  snprintf(e->value, VALUE_MAX, "%s", value);
  e->used |= used;
  e->given |= !used; /* the getters put defaults as used, and only those */
  e->source = source;
  return VSPH_OK;
}

int vsph_params_set(struct vsph_params *prm, const char *key,
                    const char *value) {
  if (!prm || !key || !value)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_set: a NULL argument");
  const char *colon = strchr(key, ':');
  if (!colon || colon == key || colon[1] == '\0' || strchr(colon + 1, ':'))
    VSPH_FAIL(VSPH_EINVAL, "parameter '%s' is not of the form Section:key",
              key);
  return put(prm, key, value, 0, 0);
}

int vsph_params_assign(struct vsph_params *prm, const char *setting) {
  if (!prm || !setting)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_assign: a NULL argument");
  const char *eq = strchr(setting, '=');
  char key[2 * KEY_MAX + 2];
  if (!eq || (size_t)(eq - setting) >= sizeof key)
    VSPH_FAIL(VSPH_EINVAL,
              "setting '%.80s' is not of the form Section:key=value", setting);
  memcpy(key, setting, (size_t)(eq - setting));
  key[eq - setting] = '\0';
  return vsph_params_set(prm, key, eq + 1);
}

/* Store Section:key from file number `source`, refusing a key given twice
 * in that file; a key of an earlier file is overridden. */
static int store_once(struct vsph_params *prm, const char *path, size_t line,
                      const char *section, const char *key, const char *value,
                      unsigned source) {
  char full[2 * KEY_MAX + 2];
  snprintf(full, sizeof full, "%s:%s", section, key);
  const struct entry *e = find(prm, full);
  if (e && e->source == source)
    VSPH_FAIL(VSPH_EINVAL, "%s:%zu: '%.60s' given twice", path, line, full);
  return put(prm, full, value, 0, source);
}

/* libyaml event reader for the subset: root mapping of sections, each a
 * mapping of scalars or flow/block sequences of scalars. */
/* The walk of a parameter file's YAML events: where it is (depth 0 the
 * stream, 1 the top mapping, 2 a section's), the section and key being
 * read, and what it holds of a list. */
struct yaml_walk {
  struct vsph_params *prm;
  const char *path;
  unsigned source;
  int depth, docs, in_seq, have_key, done;
  char section[KEY_MAX], key[KEY_MAX], value[VALUE_MAX];
};

/* A scalar at line @p line: a section's name, a key, a value or a list's
 * item. */
static int on_scalar(struct yaml_walk *w, const yaml_event_t *ev, size_t line) {
  int st = VSPH_OK;
  const char *s = (const char *)ev->data.scalar.value;
  if (strlen(s) != ev->data.scalar.length) { /* "linear\0junk" */
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "%s:%zu: a value holds a NUL character", w->path, line);
    st = VSPH_EINVAL;
  } else if (ev->data.scalar.anchor) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "%s:%zu: anchors are not allowed", w->path, line);
    st = VSPH_EINVAL;
  } else if (w->in_seq) {
    const size_t vl = strlen(w->value);
    snprintf(w->value + vl, VALUE_MAX - vl, "%s%s", vl ? ", " : "", s);
  } else if ((!w->have_key || w->depth == 1) && strlen(s) >= KEY_MAX) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "%s:%zu: a name of %zu characters, '%.20s...' "
                       "(at most %d)",
                       w->path, line, strlen(s), s, KEY_MAX - 1);
    st = VSPH_EINVAL;
  } else if (w->depth == 1) { /* a section name, or a bare root key */
    if (w->have_key && !*s) {
      vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                         "%s:%zu: section '%.40s' has no keys (they go "
                         "on the lines below it, indented)",
                         w->path, line, w->key);
      st = VSPH_EINVAL;
    } else if (w->have_key) {
      vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                         "%s:%zu: '%.40s: %.40s%s' stands at the top "
                         "level: a setting goes inside a section (a "
                         "line 'Section:' of its own, the setting "
                         "indented below it)",
                         w->path, line, w->key, s, strlen(s) > 40 ? "..." : "");
      st = VSPH_EINVAL;
    }
    snprintf(w->key, sizeof w->key, "%s", s);
    w->have_key = 1;
  } else if (w->depth == 2 && !w->have_key) {
    snprintf(w->key, sizeof w->key, "%s", s);
    w->have_key = 1;
  } else if (w->depth == 2) {
    st = store_once(w->prm, w->path, line, w->section, w->key, s, w->source);
    w->have_key = 0;
  } else {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "%s:%zu: unexpected value '%s'", w->path, line, s);
    st = VSPH_EINVAL;
  }
  return st;
}

/* One event of the file: the walk moved on, or a refusal reported. */
static int on_event(struct yaml_walk *w, const yaml_event_t *ev) {
  int st = VSPH_OK;
  const size_t line = ev->start_mark.line + 1;
  switch (ev->type) {
    case YAML_STREAM_END_EVENT:
      w->done = 1;
      break;
    case YAML_DOCUMENT_START_EVENT:
      if (++w->docs > 1) {
        vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                           "%s:%zu: several documents in one file", w->path,
                           line);
        st = VSPH_EINVAL;
      }
      break;
    case YAML_ALIAS_EVENT:
      vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                         "%s:%zu: aliases are not allowed", w->path, line);
      st = VSPH_EINVAL;
      break;
    case YAML_MAPPING_START_EVENT:
      if (ev->data.mapping_start.anchor || w->depth >= 2 || w->in_seq ||
          (w->depth == 1 && !w->have_key)) {
        vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                           "%s:%zu: only 'Section:' then 'key: value' "
                           "is allowed",
                           w->path, line);
        st = VSPH_EINVAL;
        break;
      }
      if (w->depth == 1) { /* the section's own mapping */
        snprintf(w->section, sizeof w->section, "%s", w->key);
        w->have_key = 0;
      }
      w->depth++;
      break;
    case YAML_MAPPING_END_EVENT:
      w->depth--;
      w->have_key = 0;
      break;
    case YAML_SEQUENCE_START_EVENT:
      if (w->depth != 2 || !w->have_key || w->in_seq ||
          ev->data.sequence_start.anchor) {
        vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                           "%s:%zu: a list must be the value of a key", w->path,
                           line);
        st = VSPH_EINVAL;
        break;
      }
      w->in_seq = 1;
      w->value[0] = '\0';
      break;
    case YAML_SEQUENCE_END_EVENT:
      w->in_seq = 0;
      st = store_once(w->prm, w->path, line, w->section, w->key, w->value,
                      w->source);
      w->have_key = 0;
      break;
    case YAML_SCALAR_EVENT:
      st = on_scalar(w, ev, line);
      break;
    default:
      break;
  }
  return st;
}

int vsph_params_read_string(struct vsph_params *prm, const char *text,
                            size_t len, const char *path) {
  if (!prm || !text || !path)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_read_string: a NULL argument");
  if (len > (size_t)FILE_MAX)
    VSPH_FAIL(VSPH_EINVAL, "%s: %zu bytes; a parameter file holds at most %ld",
              path, len, FILE_MAX);
  const unsigned source = ++prm->nsources;
  yaml_parser_t ps;
  if (!yaml_parser_initialize(&ps))
    VSPH_FAIL(VSPH_ENOMEM, "cannot start the YAML parser");
  yaml_parser_set_input_string(&ps, (const unsigned char *)text, len);
  struct yaml_walk w = {.prm = prm, .path = path, .source = source};
  int st = VSPH_OK;
  while (!w.done && !st) {
    yaml_event_t ev;
    if (!yaml_parser_parse(&ps, &ev)) {
      vsph_status_report(
          VSPH_EINVAL, __FILE__, __LINE__, "%s:%zu: malformed YAML: %s", path,
          ps.problem_mark.line + 1, ps.problem ? ps.problem : "parse error");
      st = VSPH_EINVAL;
      break;
    }
    st = on_event(&w, &ev);
    yaml_event_delete(&ev);
  }
  if (!st && w.depth == 1 && w.have_key) {
    vsph_status_report(VSPH_EINVAL, __FILE__, __LINE__,
                       "%s: section '%s' has no keys", path, w.key);
    st = VSPH_EINVAL;
  }
  yaml_parser_delete(&ps);
  return st;
}

int vsph_params_read(struct vsph_params *prm, const char *path) {
  /* a regular file only: opening a FIFO waits for a writer (forever), a
   * folder "holds" LONG_MAX bytes, a device never ends */
  struct stat sb;
  if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode))
    VSPH_FAIL(VSPH_EINVAL, "%s is %s, not a parameter file", path,
              S_ISDIR(sb.st_mode)    ? "a folder"
              : S_ISFIFO(sb.st_mode) ? "a FIFO"
              : S_ISSOCK(sb.st_mode) ? "a socket"
                                     : "a device");
  FILE *f = fopen(path, "rb");
  if (!f) VSPH_FAIL(VSPH_EIO, "cannot open '%s': %s", path, strerror(errno));
  /* refuse an oversized file before reading it (a pipe reports -1: read
   * up to the limit and one byte more) */
  long size = -1;
  if (fseek(f, 0, SEEK_END) == 0) size = ftell(f);
  if (size > FILE_MAX) {
    fclose(f);
    VSPH_FAIL(VSPH_EINVAL, "%s: %ld bytes; a parameter file holds at most %ld",
              path, size, FILE_MAX);
  }
  rewind(f);
  char *text = malloc((size_t)FILE_MAX + 2);
  if (!text) {
    fclose(f);
    VSPH_FAIL(VSPH_ENOMEM, "cannot read '%s'", path);
  }
  const size_t len = fread(text, 1, (size_t)FILE_MAX + 1, f);
  const int bad = ferror(f);
  fclose(f);
  int st;
  if (bad) {
    vsph_status_report(VSPH_EIO, __FILE__, __LINE__, "cannot read '%s'", path);
    st = VSPH_EIO;
  } else {
    st = vsph_params_read_string(prm, text, len, path);
  }
  free(text);
  return st;
}

int vsph_params_parse_number(const char *s, double *out) {
  if (!s || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_parse_number: a NULL argument");
  /* [+-] digits [. digits] [(e|E) [+-] digits], at least one digit */
  const char *c = s;
  if (*c == '+' || *c == '-') c++;
  size_t digits = 0;
  while (*c >= '0' && *c <= '9') c++, digits++;
  if (*c == '.') {
    c++;
    while (*c >= '0' && *c <= '9') c++, digits++;
  }
  if (digits == 0) return VSPH_EINVAL;
  if (*c == 'e' || *c == 'E') {
    c++;
    if (*c == '+' || *c == '-') c++;
    if (!(*c >= '0' && *c <= '9')) return VSPH_EINVAL;
    while (*c >= '0' && *c <= '9') c++;
  }
  if (*c != '\0') return VSPH_EINVAL;
  errno = 0;
  const double v = strtod(s, NULL);
  if (errno == ERANGE || !isfinite(v)) return VSPH_EINVAL;
  *out = v;
  return VSPH_OK;
}

static int parse_number(const char *key, const char *s, double *out) {
  if (vsph_params_parse_number(s, out))
    VSPH_FAIL(VSPH_EINVAL, "parameter %s: '%s' is not a finite decimal number",
              key, s);
  return VSPH_OK;
}

int vsph_params_get_double(struct vsph_params *prm, const char *key,
                           double *out) {
  if (!prm || !key || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_get_double: a NULL argument");
  struct entry *e = find(prm, key);
  if (!e) VSPH_FAIL(VSPH_EINVAL, "parameter %s is required", key);
  e->used = 1;
  return parse_number(key, e->value, out);
}

int vsph_params_get_double_or(struct vsph_params *prm, const char *key,
                              double def, double *out) {
  if (!prm || !key || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_get_double_or: a NULL argument");
  struct entry *e = find(prm, key);
  if (e) {
    e->used = 1;
    return parse_number(key, e->value, out);
  }
  char buf[64];
  snprintf(buf, sizeof buf, "%.17g", def);
  *out = def;
  return put(prm, key, buf, 1, 0);
}

int vsph_params_get_string_or(struct vsph_params *prm, const char *key,
                              const char *def, const char **out) {
  if (!prm || !key || !def || !out)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_get_string_or: a NULL argument");
  struct entry *e = find(prm, key);
  if (!e) {
    const int st = put(prm, key, def, 1, 0);
    if (st) return st;
    e = find(prm, key);
  }
  e->used = 1;
  *out = e->value;
  return VSPH_OK;
}

const char *vsph_params_unused(const struct vsph_params *prm) {
  if (!prm) return NULL;
  for (size_t i = 0; i < prm->n; i++)
    if (!prm->e[i]->used) return prm->e[i]->key;
  return NULL;
}

size_t vsph_params_count(const struct vsph_params *prm) {
  return prm ? prm->n : 0;
}

/* The edit distance of @p a and @p b (optimal string alignment: a swap of
 * two neighbours is one step), letters compared without case, for words of
 * at most KEY_MAX characters (longer ones: KEY_MAX). */
static size_t distance(const char *a, const char *b) {
  const size_t na = strlen(a), nb = strlen(b);
  if (na >= KEY_MAX || nb >= KEY_MAX) return KEY_MAX;
  size_t d[3][KEY_MAX + 1]; /* rows i-2, i-1, i (mod 3) */
  for (size_t j = 0; j <= nb; j++) d[0][j] = j;
  for (size_t i = 1; i <= na; i++) {
    size_t *r = d[i % 3], *p = d[(i + 2) % 3], *q = d[(i + 1) % 3];
    r[0] = i;
    for (size_t j = 1; j <= nb; j++) {
      const int same =
          tolower((unsigned char)a[i - 1]) == tolower((unsigned char)b[j - 1]);
      size_t v = p[j - 1] + !same;
      if (p[j] + 1 < v) v = p[j] + 1;
      if (r[j - 1] + 1 < v) v = r[j - 1] + 1;
      if (i > 1 && j > 1 &&
          tolower((unsigned char)a[i - 1]) ==
              tolower((unsigned char)b[j - 2]) &&
          tolower((unsigned char)a[i - 2]) ==
              tolower((unsigned char)b[j - 1]) &&
          q[j - 2] + 1 < v)
        v = q[j - 2] + 1;
      r[j] = v;
    }
  }
  return d[na % 3][nb];
}

size_t vsph_params_nearest(const char *word, const char *const *cand,
                           size_t n) {
  if (!word || !cand) return n;
  const size_t len = strlen(word);
  const size_t slip = len <= 4 ? 1 : len <= 8 ? 2 : 3;
  size_t best = n, bd = slip + 1;
  for (size_t i = 0; i < n; i++) {
    if (!cand[i]) continue;
    const size_t d = distance(word, cand[i]);
    if (d < bd) bd = d, best = i;
  }
  return best;
}

/* The section of key @p k ("Section:key"): its length, 0 for none. */
static size_t section_len(const char *k) {
  const char *c = strchr(k, ':');
  return c ? (size_t)(c - k) : 0;
}

void vsph_params_hint(const struct vsph_params *prm, const char *key, char *buf,
                      size_t len) {
  if (!buf || len == 0) return;
  buf[0] = '\0';
  if (!prm || !key || prm->n == 0) return;
  const char **cand = malloc(prm->n * sizeof *cand);
  if (!cand) return;
  size_t n = 0;
  for (size_t i = 0; i < prm->n; i++)
    if (strcmp(prm->e[i]->key, key)) cand[n++] = prm->e[i]->key;
  size_t at = 0;
  const size_t k = vsph_params_nearest(key, cand, n);
  if (k < n) at = (size_t)snprintf(buf, len, "; did you mean %s?", cand[k]);
  /* the keys of key's section, or the sections where it names none known */
  const size_t sl = section_len(key);
  size_t shown = 0;
  for (size_t i = 0; i < n; i++)
    shown += section_len(cand[i]) == sl && !strncmp(cand[i], key, sl);
  if (shown && at < len)
    at +=
        (size_t)snprintf(buf + at, len - at, " (the %.*s keys:", (int)sl, key);
  else if (at < len)
    at += (size_t)snprintf(buf + at, len - at, " (the sections:");
  for (size_t i = 0, m = 0; i < n && at < len; i++) {
    const size_t ci = section_len(cand[i]);
    if (shown && !(ci == sl && !strncmp(cand[i], key, sl))) continue;
    if (!shown) { /* a section once, where it first appears */
      size_t e = 0;
      while (e < i &&
             !(section_len(cand[e]) == ci && !strncmp(cand[e], cand[i], ci)))
        e++;
      if (e < i) continue;
    }
    at += (size_t)snprintf(buf + at, len - at, "%s %.*s", m++ ? "," : "",
                           shown ? (int)strlen(cand[i] + ci + 1) : (int)ci,
                           shown ? cand[i] + ci + 1 : cand[i]);
  }
  if (at < len) snprintf(buf + at, len - at, ")");
  if (at >= len && len > 4) memcpy(buf + len - 5, "...)", 5);
  free(cand);
}

int vsph_params_given(const struct vsph_params *prm, const char *key) {
  const struct entry *e = prm ? find(prm, key) : NULL;
  return e && e->given;
}

void vsph_params_entry(const struct vsph_params *prm, size_t i,
                       const char **key, const char **value, int *used) {
  if (!prm || !key || !value || !used) return;
  *key = prm->e[i]->key;
  *value = prm->e[i]->value;
  *used = prm->e[i]->used;
}

/* ------------------------------------------------------- parameter tables */

const struct vsph_params_spec *vsph_params_spec_find(
    const struct vsph_params_spec *spec, size_t n, const char *key) {
  if (!spec) return NULL;
  for (size_t i = 0; i < n; i++)
    if (!strcmp(spec[i].key, key)) return &spec[i];
  return NULL;
}

void vsph_params_spec_default(const struct vsph_params_spec *s, char *buf,
                              size_t len) {
  if (!s || !buf) return;
  if (s->kind == VSPH_PARAMS_NAME)
    snprintf(buf, len, "%s", s->word);
  else if (s->kind == VSPH_PARAMS_INT)
    snprintf(buf, len, "%.0f", s->def);
  else /* the shortest text that reads back as the same double */
    for (int digits = 15; digits <= 17; digits++) {
      snprintf(buf, len, "%.*g", digits, s->def);
      if (strtod(buf, NULL) == s->def) break;
    }
}

/* One entry: its text (given, or the default), checked and stored. */
static int load_one(struct vsph_params *prm, const char *section,
                    const struct vsph_params_spec *s, char *base) {
  char key[KEY_MAX], def[64];
  snprintf(key, sizeof key, "%s:%s", section, s->key);
  vsph_params_spec_default(s, def, sizeof def);
  const char *text = def;
  if (prm) {
    struct entry *e = find(prm, key);
    if (e) {
      e->used = 1;
      text = e->value;
    } else {
      const int st = put(prm, key, def, 1, 0);
      if (st) return st;
    }
  }
  if (s->kind == VSPH_PARAMS_NAME) {
    if (strlen(text) >= VSPH_PARAMS_NAME_MAX || text[0] == '\0')
      VSPH_FAIL(VSPH_EINVAL, "%s: '%.40s' is not a name of 1-%d characters",
                key, text, VSPH_PARAMS_NAME_MAX - 1);
    snprintf(base + s->offset, VSPH_PARAMS_NAME_MAX, "%s", text);
    return VSPH_OK;
  }
  double v;
  if (vsph_params_parse_number(text, &v))
    VSPH_FAIL(VSPH_EINVAL, "%s: '%.40s' is not a finite decimal number", key,
              text);
  if (!(v >= s->lo && v <= s->hi))
    VSPH_FAIL(VSPH_EINVAL, "%s must lie in [%g, %g], got %.6g", key, s->lo,
              s->hi, v);
  if (s->kind == VSPH_PARAMS_INT) {
    if (v != floor(v))
      VSPH_FAIL(VSPH_EINVAL, "%s must be a whole number, got %.6g", key, v);
    const size_t iv = (size_t)v; /* in bounds, so the cast is defined */
    memcpy(base + s->offset, &iv, sizeof iv);
  } else {
    memcpy(base + s->offset, &v, sizeof v);
  }
  return VSPH_OK;
}

int vsph_params_load(struct vsph_params *prm, const char *section,
                     const struct vsph_params_spec *spec, size_t n, void *props,
                     size_t size) {
  if (!section || !spec || !props)
    VSPH_FAIL(VSPH_EINVAL, "vsph_params_load: a NULL argument");
  for (size_t i = 0; i < n; i++) { /* every field within the struct first */
    const size_t w = spec[i].kind == VSPH_PARAMS_NAME  ? VSPH_PARAMS_NAME_MAX
                     : spec[i].kind == VSPH_PARAMS_INT ? sizeof(size_t)
                                                       : sizeof(double);
    if (spec[i].offset > size || w > size - spec[i].offset)
      VSPH_FAIL(VSPH_EINVAL,
                "vsph_params_load: %s:%.40s lies beyond the %zu-byte struct "
                "(offset %zu)",
                section, spec[i].key ? spec[i].key : "(null)", size,
                spec[i].offset);
  }
  for (size_t i = 0; i < n; i++) {
    const int st = load_one(prm, section, &spec[i], props);
    if (st) return st;
  }
  return VSPH_OK;
}
