/* SPDX-License-Identifier: MIT */
/*
 * Wavefront OBJ loader (host port). See zl_obj.h for what is accepted.
 *
 * The text is read into memory and scanned three times:
 *   1. encoding: a UTF-16 byte order mark or a NUL byte stops the load,
 *      with the line it is on (the statements read must be ASCII, checked
 *      per statement in pass 3; comments and ignored names may hold any
 *      bytes);
 *   2. counting: the v, vt and vn statements are counted, so that a face may
 *      refer to a vertex defined further down and every index is checked
 *      against the final counts the moment its line is parsed; errors are
 *      therefore reported at the first bad line, in file order;
 *   3. parsing: every line is checked and stored (positions in double).
 * Faces are triangulated at the end (they may refer to later vertices), then
 * positions are normalised if asked and converted to Q16.16.
 */
#include "zl_obj.h"
#include "zl_read_file.h"

#include <errno.h>
#include <limits.h>
#include <locale.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ utilities */

typedef struct {
    const char *s;
    size_t n;
} token;

/* Longest token quoted in a message. */
#define QUOTE_MAX 40
#define QUOTE(t)                                                                                   \
    (int)((t).n > QUOTE_MAX ? QUOTE_MAX : (t).n), (t).s, ((t).n > QUOTE_MAX ? "..." : "")

typedef struct {
    size_t first; /* index into parser.poly */
    size_t count; /* vertices of the face */
} face_rec;

typedef struct {
    const char *name;
    char *msg;
    size_t msg_size;
    int normalize;
    int texcoords; /* keep vt and split vertices by them */
    char decimal_point;
    unsigned long line;

    /* statements counted in the counting pass */
    size_t v_total, vt_total, vn_total;
    /* texture coordinates and normals seen so far in the parsing pass */
    size_t vt_seen, vn_seen;

    double *pos;  /* 3 per vertex, as written in the file */
    uint8_t *col; /* 3 per vertex */
    size_t v_count;
    size_t v_cap, col_cap; /* capacities, in elements (3 per vertex) */
    size_t colored;        /* vertices that had a colour */

    uint32_t *poly; /* face vertex indices, 0-based, all faces one after another */
    size_t poly_count, poly_cap;
    uint32_t *poly_vt; /* per face vertex: its vt index, or NO_VT */
    size_t poly_vt_cap;
    double *vt;     /* 2 per texture coordinate (u, v; v = 0 when absent) */
    size_t vt_cap;
    size_t corners_with_vt;
    uint32_t *poly_vn; /* per face vertex: its vn index, or NO_VT */
    size_t poly_vn_cap;
    double *vn;        /* 3 per normal, as written */
    size_t vn_cap;
    size_t corners_with_vn;
    face_rec *faces;
    size_t face_count, face_cap;
    size_t tri_total;
    size_t max_face; /* most vertices in one face */
} parser;

static zl_obj_status fail(parser *p, zl_obj_status s, const char *fmt, ...)
{
    if (p->msg != NULL && p->msg_size > 0) {
        int n = snprintf(p->msg, p->msg_size, "%s:%lu: ", p->name, p->line);
        if (n >= 0 && (size_t)n < p->msg_size) {
            va_list ap;
            va_start(ap, fmt);
            vsnprintf(p->msg + n, p->msg_size - (size_t)n, fmt, ap);
            va_end(ap);
        }
    }
    return s;
}

/* A message without a line number (I/O and memory). */
static void set_msg(char *msg, size_t msg_size, const char *fmt, ...)
{
    if (msg != NULL && msg_size > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, msg_size, fmt, ap);
        va_end(ap);
    }
}

static zl_obj_status out_of_memory(parser *p)
{
    return fail(p, ZL_OBJ_ERR_MEMORY, "out of memory");
}

/*
 * Make room for need elements of elem bytes in arr (capacity *cap, doubled
 * as needed). Returns the array, moved or not, or NULL when memory runs out
 * (arr is then still valid and *cap unchanged).
 */
static void *grow(void *arr, size_t *cap, size_t need, size_t elem)
{
    size_t ncap;
    void *na;
    if (need <= *cap)
        return arr;
    ncap = *cap ? *cap : 64;
    while (ncap < need) {
        if (ncap > ((size_t)-1) / 2 / elem)
            return NULL;
        ncap *= 2;
    }
    na = realloc(arr, ncap * elem);
    if (na != NULL)
        *cap = ncap;
    return na;
}

/* GROW(array, capacity, need): grow a parser array or fail the load. */
#define GROW(arr, cap, need)                                                                       \
    do {                                                                                           \
        void *grown_ = grow((arr), &(cap), (need), sizeof *(arr));                                 \
        if (grown_ == NULL)                                                                        \
            return out_of_memory(p);                                                               \
        (arr) = grown_;                                                                            \
    } while (0)

static int is_space(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n';
}

/* White space, or the backslash of a line continuation (a backslash right
 * before a line end, kept inside the joined line by next_line). */
static int is_space_at(const char *s, const char *end)
{
    return is_space(*s) || (*s == '\\' && s + 1 < end && (s[1] == '\n' || s[1] == '\r'));
}

static int is_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* Next whitespace-separated token of [*cur, end); 0 at the end of the line. */
static int next_token(const char **cur, const char *end, token *t)
{
    const char *s = *cur;
    while (s < end && is_space_at(s, end))
        s++;
    if (s == end) {
        *cur = s;
        return 0;
    }
    t->s = s;
    while (s < end && !is_space_at(s, end))
        s++;
    t->n = (size_t)(s - t->s);
    *cur = s;
    return 1;
}

static int tok_is(token t, const char *word)
{
    size_t n = strlen(word);
    return t.n == n && memcmp(t.s, word, n) == 0;
}

/* Length of the line end at buf[i] (LF, CR LF or a lone CR), 0 if none. */
static size_t line_end_at(const char *buf, size_t size, size_t i)
{
    if (buf[i] == '\n')
        return 1;
    if (buf[i] == '\r')
        return i + 1 < size && buf[i + 1] == '\n' ? 2 : 1;
    return 0;
}

/*
 * Next logical line of buf from *pos: [*line, *line + *len) without its
 * line end and any comment; *lines is the number of physical lines it
 * spans. A line ends at LF, CR LF or a lone CR (classic Mac files). A
 * backslash right before a line end, outside a comment, continues the line
 * on the next one (the OBJ specification's continuation): the backslash and
 * line end stay in the text and read as white space. Returns 0 at the end.
 */
static int next_line(const char *buf, size_t size, size_t *pos, const char **line, size_t *len,
                     unsigned long *lines)
{
    size_t i = *pos, end;
    const char *hash;
    int comment = 0;
    if (i >= size)
        return 0;
    *lines = 1;
    for (;;) {
        while (i < size && line_end_at(buf, size, i) == 0) {
            comment |= buf[i] == '#';
            i++;
        }
        end = i;
        if (i < size)
            i += line_end_at(buf, size, i);
        if (comment || end == *pos || buf[end - 1] != '\\' || i >= size)
            break;
        (*lines)++; /* continued */
    }
    *line = buf + *pos;
    *len = end - *pos;
    hash = (const char *)memchr(*line, '#', *len);
    if (hash != NULL)
        *len = (size_t)(hash - *line);
    *pos = i;
    return 1;
}

/* ------------------------------------------------------------- encoding */

/*
 * The file must be text: a UTF-16 byte order mark or a NUL byte stops the
 * load. Other bytes are not checked here: comments and the names of the
 * statements the loader ignores (g, o, usemtl, mtllib, ...) may hold any
 * encoding, Latin-1 included; the statements it reads must be ASCII
 * (check_ascii).
 */
static zl_obj_status check_encoding(parser *p, const unsigned char *b, size_t n, size_t *start)
{
    size_t i;
    *start = 0;
    p->line = 1;
    if (n >= 2 && ((b[0] == 0xFF && b[1] == 0xFE) || (b[0] == 0xFE && b[1] == 0xFF)))
        return fail(p, ZL_OBJ_ERR_PARSE,
                    "the file starts with a UTF-16 byte order mark; save it as UTF-8 or ASCII");
    if (n >= 3 && b[0] == 0xEF && b[1] == 0xBB && b[2] == 0xBF)
        *start = 3; /* UTF-8 byte order mark */
    for (i = *start; i < n;) {
        size_t end = line_end_at((const char *)b, n, i);
        if (end != 0) {
            p->line++;
            i += end;
            continue;
        }
        if (b[i] == 0)
            return fail(p, ZL_OBJ_ERR_PARSE,
                        "NUL byte: this is a binary or UTF-16 file, not ASCII or UTF-8 OBJ text");
        i++;
    }
    return ZL_OBJ_OK;
}

/* A statement the loader reads (v, vt, vn, f) is ASCII: numbers and indices. */
static zl_obj_status check_ascii(parser *p, const char *line, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++)
        if ((unsigned char)line[i] >= 0x80)
            return fail(p, ZL_OBJ_ERR_PARSE,
                        "byte 0x%02X: statements other than comments and ignored names must be ASCII",
                        (unsigned)(unsigned char)line[i]);
    return ZL_OBJ_OK;
}

/* -------------------------------------------------------------- numbers */

/* [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)? */
static int is_decimal(token t)
{
    size_t i = 0, int_digits = 0, frac_digits = 0;
    if (i < t.n && (t.s[i] == '+' || t.s[i] == '-'))
        i++;
    while (i < t.n && is_digit(t.s[i])) {
        i++;
        int_digits++;
    }
    if (i < t.n && t.s[i] == '.') {
        i++;
        while (i < t.n && is_digit(t.s[i])) {
            i++;
            frac_digits++;
        }
    }
    if (int_digits + frac_digits == 0)
        return 0;
    if (i < t.n && (t.s[i] == 'e' || t.s[i] == 'E')) {
        size_t exp_digits = 0;
        i++;
        if (i < t.n && (t.s[i] == '+' || t.s[i] == '-'))
            i++;
        while (i < t.n && is_digit(t.s[i])) {
            i++;
            exp_digits++;
        }
        if (exp_digits == 0)
            return 0;
    }
    return i == t.n;
}

static char lower(char c)
{
    return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
}

/* nan, inf, infinity (any case, optional sign, nan(...)): what strtod would
 * take for a non-finite value. */
static int is_nonfinite_word(token t)
{
    size_t i = 0;
    if (i < t.n && (t.s[i] == '+' || t.s[i] == '-'))
        i++;
    if (t.n - i >= 3) {
        char a = lower(t.s[i]), b = lower(t.s[i + 1]), c = lower(t.s[i + 2]);
        if ((a == 'n' && b == 'a' && c == 'n') || (a == 'i' && b == 'n' && c == 'f'))
            return 1;
    }
    return 0;
}

/* Parse a decimal number; the error messages name the token. */
static zl_obj_status parse_number(parser *p, token t, double *out)
{
    char buf[128];
    char *end;
    size_t i;
    double v;
    if (!is_decimal(t)) {
        if (is_nonfinite_word(t))
            return fail(p, ZL_OBJ_ERR_PARSE, "'%.*s%s' is not a finite number", QUOTE(t));
        return fail(p, ZL_OBJ_ERR_PARSE, "'%.*s%s' is not a number", QUOTE(t));
    }
    if (t.n >= sizeof buf)
        return fail(p, ZL_OBJ_ERR_PARSE, "number '%.*s%s' is longer than %u characters", QUOTE(t),
                    (unsigned)(sizeof buf - 1));
    /* strtod reads the locale's decimal point: give it that one. */
    for (i = 0; i < t.n; i++)
        buf[i] = t.s[i] == '.' ? p->decimal_point : t.s[i];
    buf[t.n] = '\0';
    errno = 0;
    v = strtod(buf, &end);
    if (end != buf + t.n)
        return fail(p, ZL_OBJ_ERR_PARSE, "'%.*s%s' is not a number", QUOTE(t));
    if (!isfinite(v))
        return fail(p, ZL_OBJ_ERR_PARSE, "'%.*s%s' is out of the range of a double", QUOTE(t));
    *out = v;
    return ZL_OBJ_OK;
}

/*
 * Parse a face index: [+-]? digits. Returns 1 and the value, saturated at
 * +-10^18 (far beyond any count), or 0 for a syntax error.
 */
static int parse_int(const char *s, size_t n, long long *out)
{
    size_t i = 0;
    int neg = 0;
    long long v = 0;
    const long long cap = 1000000000000000000LL;
    if (i < n && (s[i] == '+' || s[i] == '-')) {
        neg = s[i] == '-';
        i++;
    }
    if (i == n)
        return 0;
    for (; i < n; i++) {
        if (!is_digit(s[i]))
            return 0;
        if (v <= cap / 10)
            v = v * 10 + (s[i] - '0'); /* at most 10^18 + 9: no overflow */
        else
            v = cap;
    }
    if (v > cap)
        v = cap;
    *out = neg ? -v : v;
    return 1;
}

/* --------------------------------------------------------- the statements */

/* Statements of the OBJ format that a triangle mesh loader ignores. */
static const char *const ignored_statements[] = {
    "g",      "o",          "s",         "usemtl",   "mtllib",   "l",    "p",
    "vp",     "cstype",     "deg",       "bmat",     "step",     "curv", "curv2",
    "surf",   "parm",       "trim",      "hole",     "scrv",     "sp",   "end",
    "con",    "mg",         "bevel",     "c_interp", "d_interp", "lod",  "usemap",
    "maplib", "shadow_obj", "trace_obj", "ctech",    "stech",    NULL};

static int is_ignored(token t)
{
    size_t i;
    for (i = 0; ignored_statements[i] != NULL; i++)
        if (tok_is(t, ignored_statements[i]))
            return 1;
    return 0;
}

static zl_obj_status parse_vertex(parser *p, const char *cur, const char *end)
{
    double val[7];
    token t;
    size_t k = 0, i;
    zl_obj_status st;
    while (next_token(&cur, end, &t)) {
        double v = 0.0;
        if (k >= 3 && !is_decimal(t) && !is_nonfinite_word(t))
            return fail(p, ZL_OBJ_ERR_PARSE, "unexpected '%.*s%s' after the vertex coordinates",
                        QUOTE(t));
        st = parse_number(p, t, &v);
        if (st != ZL_OBJ_OK)
            return st;
        if (k < 7)
            val[k] = v;
        k++;
    }
    if (k < 3)
        return fail(p, ZL_OBJ_ERR_PARSE, "a vertex needs x y z; this one has %u number%s",
                    (unsigned)k, k == 1 ? "" : "s");
    if (k == 5 || k > 6)
        return fail(p, ZL_OBJ_ERR_PARSE,
                    "a vertex is x y z, x y z w or x y z r g b; this one has %lu numbers",
                    (unsigned long)k);
    if (p->v_count >= ZL_OBJ_MAX_VERTICES)
        return fail(p, ZL_OBJ_ERR_LIMIT,
                    "more than %u vertices: a zl_mesh indexes its vertices with uint16",
                    ZL_OBJ_MAX_VERTICES);
    if (!p->normalize) {
        for (i = 0; i < 3; i++) {
            double r = floor(val[i] * 65536.0 + 0.5);
            if (r < (double)INT32_MIN || r > (double)INT32_MAX)
                return fail(p, ZL_OBJ_ERR_PARSE,
                            "coordinate %g is outside the Q16.16 range -32768 .. 32767.99998 "
                            "(normalise the model)",
                            val[i]);
        }
    }
    GROW(p->pos, p->v_cap, 3 * (p->v_count + 1));
    GROW(p->col, p->col_cap, 3 * (p->v_count + 1));
    for (i = 0; i < 3; i++)
        p->pos[p->v_count * 3 + i] = val[i];
    if (k == 6) {
        for (i = 0; i < 3; i++) {
            double c = val[3 + i];
            c = c < 0.0 ? 0.0 : (c > 1.0 ? 1.0 : c);
            p->col[p->v_count * 3 + i] = (uint8_t)floor(c * 255.0 + 0.5);
        }
        p->colored++;
    } else {
        memset(p->col + p->v_count * 3, 0, 3);
    }
    p->v_count++;
    return ZL_OBJ_OK;
}

#define NO_VT 0xFFFFFFFFu

/* Whether a texture coordinate becomes a Q16.16 (zl_fixed) without clamping. */
static int tex_fits(double c)
{
    double r = floor(c * 65536.0 + 0.5);
    return r >= -2147483648.0 && r <= 2147483647.0;
}

/* vt (1 to 3 numbers: u and v kept) and vn (3 numbers: checked, counted). */
static zl_obj_status parse_attribute(parser *p, const char *cur, const char *end, int normal)
{
    token t;
    size_t k = 0;
    zl_obj_status st;
    double uv[3] = {0.0, 0.0, 0.0};
    while (next_token(&cur, end, &t)) {
        double v = 0.0;
        st = parse_number(p, t, &v);
        if (st != ZL_OBJ_OK)
            return st;
        if (k < 3)
            uv[k] = v;
        k++;
    }
    if (normal && k == 3) {
        GROW(p->vn, p->vn_cap, (p->vn_seen + 1) * 3);
        p->vn[p->vn_seen * 3] = uv[0];
        p->vn[p->vn_seen * 3 + 1] = uv[1];
        p->vn[p->vn_seen * 3 + 2] = uv[2];
    }
    if (!normal && k >= 1 && k <= 3 && (!tex_fits(uv[0]) || !tex_fits(1.0 - uv[1])))
        return fail(p, ZL_OBJ_ERR_LIMIT,
                    "texture coordinate (%g, %g) is outside what Q16.16 holds: u and 1 - v must lie "
                    "within -32768 .. 32767.99998",
                    uv[0], uv[1]);
    if (!normal && k >= 1 && k <= 3) {
        GROW(p->vt, p->vt_cap, (p->vt_seen + 1) * 2);
        p->vt[p->vt_seen * 2] = uv[0];
        p->vt[p->vt_seen * 2 + 1] = uv[1];
    }
    if (normal && k != 3)
        return fail(p, ZL_OBJ_ERR_PARSE, "a normal (vn) has 3 numbers; this one has %lu",
                    (unsigned long)k);
    if (!normal && (k < 1 || k > 3))
        return fail(p, ZL_OBJ_ERR_PARSE,
                    "a texture coordinate (vt) has 1 to 3 numbers; this one has %lu",
                    (unsigned long)k);
    if (normal)
        p->vn_seen++;
    else
        p->vt_seen++;
    return ZL_OBJ_OK;
}

/*
 * Resolve one index of a face vertex against `seen` items defined before
 * this line and `total` in the file. what/whats: singular and plural name.
 */
static zl_obj_status resolve_index(parser *p, token whole, const char *s, size_t n, size_t seen,
                                   size_t total, const char *what, const char *whats, size_t *out)
{
    long long v;
    if (!parse_int(s, n, &v))
        return fail(p, ZL_OBJ_ERR_PARSE,
                    "'%.*s%s' is not a face vertex: expected v, v/vt, v//vn or v/vt/vn with "
                    "integer indices",
                    QUOTE(whole));
    if (v == 0)
        return fail(p, ZL_OBJ_ERR_PARSE, "%s index 0 in '%.*s%s': OBJ indices start at 1", what,
                    QUOTE(whole));
    if (v > 0) {
        if ((unsigned long long)v > (unsigned long long)total)
            return fail(p, ZL_OBJ_ERR_PARSE,
                        "%s index %.*s in '%.*s%s' is out of range: the file has %lu %s", what,
                        (int)n, s, QUOTE(whole), (unsigned long)total, total == 1 ? what : whats);
        *out = (size_t)(v - 1);
    } else {
        if ((unsigned long long)(-v) > (unsigned long long)seen)
            return fail(p, ZL_OBJ_ERR_PARSE,
                        "relative %s index %.*s in '%.*s%s' is out of range: %lu %s defined "
                        "before this line",
                        what, (int)n, s, QUOTE(whole), (unsigned long)seen,
                        seen == 1 ? what : whats);
        *out = seen - (size_t)(-v);
    }
    return ZL_OBJ_OK;
}

/* Every corner of a face has a vt, or none has; the same for vn (a face
 * that mixes them has no defined attributes at some corners). */
static zl_obj_status check_corners_agree(parser *p, size_t first, size_t n)
{
    size_t c, with_vt = 0, with_vn = 0;
    for (c = first; c < first + n; c++) {
        with_vt += p->poly_vt[c] != NO_VT;
        with_vn += p->poly_vn[c] != NO_VT;
    }
    if (with_vt != 0 && with_vt != n)
        return fail(p, ZL_OBJ_ERR_PARSE,
                    "a face mixes corners with and without a texture coordinate (vt): %lu of %lu have one",
                    (unsigned long)with_vt, (unsigned long)n);
    if (with_vn != 0 && with_vn != n)
        return fail(p, ZL_OBJ_ERR_PARSE,
                    "a face mixes corners with and without a normal (vn): %lu of %lu have one",
                    (unsigned long)with_vn, (unsigned long)n);
    return ZL_OBJ_OK;
}

static zl_obj_status parse_face(parser *p, const char *cur, const char *end)
{
    token t;
    size_t n = 0, first = p->poly_count;
    zl_obj_status st;
    while (next_token(&cur, end, &t)) {
        const char *part[3];
        size_t plen[3], parts = 1, i;
        size_t idx = 0, vt_idx = NO_VT, vn_idx = NO_VT;
        part[0] = t.s;
        plen[0] = 0;
        for (i = 0; i < t.n; i++) {
            if (t.s[i] == '/') {
                if (parts == 3)
                    return fail(p, ZL_OBJ_ERR_PARSE,
                                "'%.*s%s' is not a face vertex: expected v, v/vt, v//vn or "
                                "v/vt/vn",
                                QUOTE(t));
                part[parts] = t.s + i + 1;
                plen[parts] = 0;
                parts++;
            } else {
                plen[parts - 1]++;
            }
        }
        /* v/ and v/vt/ and v// have an empty part that must not be */
        if (plen[0] == 0 || (parts == 2 && plen[1] == 0) || (parts == 3 && plen[2] == 0))
            return fail(p, ZL_OBJ_ERR_PARSE,
                        "'%.*s%s' is not a face vertex: expected v, v/vt, v//vn or v/vt/vn",
                        QUOTE(t));
        st = resolve_index(p, t, part[0], plen[0], p->v_count, p->v_total, "vertex", "vertices",
                           &idx);
        if (st != ZL_OBJ_OK)
            return st;
        if (parts >= 2 && plen[1] > 0) {
            st = resolve_index(p, t, part[1], plen[1], p->vt_seen, p->vt_total,
                               "texture coordinate", "texture coordinates", &vt_idx);
            if (st != ZL_OBJ_OK)
                return st;
            p->corners_with_vt++;
        }
        if (parts == 3) {
            st = resolve_index(p, t, part[2], plen[2], p->vn_seen, p->vn_total, "normal", "normals",
                               &vn_idx);
            if (st != ZL_OBJ_OK)
                return st;
            p->corners_with_vn++;
        }
        GROW(p->poly, p->poly_cap, p->poly_count + 1);
        GROW(p->poly_vn, p->poly_vn_cap, p->poly_count + 1);
        p->poly_vn[p->poly_count] = (uint32_t)vn_idx;
        GROW(p->poly_vt, p->poly_vt_cap, p->poly_count + 1);
        p->poly_vt[p->poly_count] = (uint32_t)vt_idx;
        p->poly[p->poly_count++] = (uint32_t)idx;
        n++;
    }
    if (n < 3)
        return fail(p, ZL_OBJ_ERR_PARSE, "a face needs at least 3 vertices; this one has %lu",
                    (unsigned long)n);
    st = check_corners_agree(p, first, n);
    if (st != ZL_OBJ_OK)
        return st;
    if (n - 2 > ZL_OBJ_MAX_TRIANGLES - p->tri_total)
        return fail(p, ZL_OBJ_ERR_LIMIT,
                    "more than %u triangles (a zl_mesh counts them in uint16): this face of %lu "
                    "vertices makes %lu",
                    ZL_OBJ_MAX_TRIANGLES, (unsigned long)n, (unsigned long)(p->tri_total + n - 2));
    GROW(p->faces, p->face_cap, p->face_count + 1);
    p->faces[p->face_count].first = first;
    p->faces[p->face_count].count = n;
    p->face_count++;
    p->tri_total += n - 2;
    if (n > p->max_face)
        p->max_face = n;
    return ZL_OBJ_OK;
}

/* ---------------------------------------------------------- triangulation */

typedef struct {
    uint32_t code;
    size_t v;
} zkey;

typedef struct {
    double *x, *y;       /* the outline in its plane, counter-clockwise */
    size_t *prev, *next; /* the vertices not clipped yet, as a ring */
    /* Only reflex (or flat) vertices can block an ear. Small outlines keep
     * them in a list; large ones (more than ZORDER_MIN vertices) keep every
     * vertex in a list sorted by Morton (z-order) code, so an ear test only
     * visits the vertices whose codes lie in its bounding box's range. */
    unsigned char *reflex;
    size_t *rprev, *rnext;
    size_t rhead; /* first reflex vertex, NONE when there is none */
    int zmode;
    uint32_t *z;
    size_t *zprev, *znext;
    zkey *keys;
    double zminx, zminy, zscale;
} ear_work;

#define NONE ((size_t)-1)
#define ZORDER_MIN 64

/* Vertex visits allowed per face before the ear test stops looking for
 * blockers (only huge self-intersecting outlines get near it; the z-order
 * index keeps honest polygons of 65535 vertices far below it). */
#define EAR_BUDGET 200000000L

/* Twice the signed area of (a, b, c): > 0 when counter-clockwise. */
static double cross3(const ear_work *w, size_t a, size_t b, size_t c)
{
    return (w->x[b] - w->x[a]) * (w->y[c] - w->y[a]) - (w->y[b] - w->y[a]) * (w->x[c] - w->x[a]);
}

static double corner(const ear_work *w, size_t v)
{
    return cross3(w, w->prev[v], v, w->next[v]);
}

static int same_point(const ear_work *w, size_t a, size_t b)
{
    return w->x[a] == w->x[b] && w->y[a] == w->y[b];
}

static void reflex_remove(ear_work *w, size_t v)
{
    if (!w->reflex[v])
        return;
    w->reflex[v] = 0;
    if (w->zmode)
        return; /* no list: the flag is all */
    if (w->rprev[v] != NONE)
        w->rnext[w->rprev[v]] = w->rnext[v];
    else
        w->rhead = w->rnext[v];
    if (w->rnext[v] != NONE)
        w->rprev[w->rnext[v]] = w->rprev[v];
}

static void reflex_insert(ear_work *w, size_t v)
{
    if (w->reflex[v])
        return;
    w->reflex[v] = 1;
    if (w->zmode)
        return;
    w->rprev[v] = NONE;
    w->rnext[v] = w->rhead;
    if (w->rhead != NONE)
        w->rprev[w->rhead] = v;
    w->rhead = v;
}

/* Bring v's reflex flag up to date with its current neighbours. */
static void reflex_update(ear_work *w, size_t v)
{
    if (corner(w, v) <= 0.0)
        reflex_insert(w, v);
    else
        reflex_remove(w, v);
}

/* 15 bits of x spread to the even bits. */
static uint32_t spread15(uint32_t x)
{
    x &= 0x7FFFu;
    x = (x | (x << 8)) & 0x00FF00FFu;
    x = (x | (x << 4)) & 0x0F0F0F0Fu;
    x = (x | (x << 2)) & 0x33333333u;
    x = (x | (x << 1)) & 0x55555555u;
    return x;
}

static uint32_t quantise(double v)
{
    /* monotonic in v, so a bounding box maps onto a range of codes; NaN
     * (an overflowing box of coordinates near DBL_MAX) is not converted */
    return !(v > 0.0) ? 0u : (v >= 32767.0 ? 32767u : (uint32_t)v);
}

static uint32_t zcode(const ear_work *w, double x, double y)
{
    return spread15(quantise((x - w->zminx) * w->zscale)) |
           spread15(quantise((y - w->zminy) * w->zscale)) << 1;
}

static int zkey_cmp(const void *pa, const void *pb)
{
    const zkey *a = (const zkey *)pa, *b = (const zkey *)pb;
    if (a->code != b->code)
        return a->code < b->code ? -1 : 1;
    return a->v < b->v ? -1 : (a->v > b->v ? 1 : 0);
}

/* Sort the n vertices into the z-order list. */
static void zorder_build(ear_work *w, size_t n)
{
    double minx = w->x[0], maxx = w->x[0], miny = w->y[0], maxy = w->y[0], ext;
    size_t i;
    for (i = 1; i < n; i++) {
        minx = fmin(minx, w->x[i]);
        maxx = fmax(maxx, w->x[i]);
        miny = fmin(miny, w->y[i]);
        maxy = fmax(maxy, w->y[i]);
    }
    ext = fmax(maxx - minx, maxy - miny);
    w->zminx = minx;
    w->zminy = miny;
    w->zscale = ext > 0.0 ? 32767.0 / ext : 0.0;
    for (i = 0; i < n; i++) {
        w->z[i] = zcode(w, w->x[i], w->y[i]);
        w->keys[i].code = w->z[i];
        w->keys[i].v = i;
    }
    qsort(w->keys, n, sizeof(zkey), zkey_cmp);
    for (i = 0; i < n; i++) {
        size_t v = w->keys[i].v;
        w->zprev[v] = i > 0 ? w->keys[i - 1].v : NONE;
        w->znext[v] = i + 1 < n ? w->keys[i + 1].v : NONE;
    }
}

/* Does reflex vertex v block the ear (a, b, c) with bounding box bb? */
static int blocks(const ear_work *w, size_t v, size_t a, size_t b, size_t c, const double *bb)
{
    double px = w->x[v], py = w->y[v];
    if (!w->reflex[v] || v == a || v == c || px < bb[0] || px > bb[1] || py < bb[2] || py > bb[3])
        return 0;
    /* Points of the ear itself, repeated elsewhere in the outline (the seam
     * to a hole), touch the ear without blocking it. */
    if (same_point(w, v, a) || same_point(w, v, b) || same_point(w, v, c))
        return 0;
    /* inside or on an edge */
    return cross3(w, a, b, v) >= 0.0 && cross3(w, b, c, v) >= 0.0 && cross3(w, c, a, v) >= 0.0;
}

/* Is b, between a and c, an ear of the (counter-clockwise) outline? */
static int is_ear(const ear_work *w, size_t a, size_t b, size_t c, long *budget)
{
    size_t v;
    double bb[4];
    if (cross3(w, a, b, c) <= 0.0)
        return 0; /* reflex or flat */
    if (*budget <= 0)
        return 1;
    bb[0] = fmin(w->x[a], fmin(w->x[b], w->x[c]));
    bb[1] = fmax(w->x[a], fmax(w->x[b], w->x[c]));
    bb[2] = fmin(w->y[a], fmin(w->y[b], w->y[c]));
    bb[3] = fmax(w->y[a], fmax(w->y[b], w->y[c]));
    /* Only a reflex (or flat) vertex can block: if any vertex lies in the
     * triangle, the one farthest from the diagonal ac does, and it is reflex. */
    if (w->zmode) {
        uint32_t zlo = zcode(w, bb[0], bb[2]), zhi = zcode(w, bb[1], bb[3]);
        for (v = w->zprev[b]; v != NONE && w->z[v] >= zlo; v = w->zprev[v]) {
            (*budget)--;
            if (blocks(w, v, a, b, c, bb))
                return 0;
        }
        for (v = w->znext[b]; v != NONE && w->z[v] <= zhi; v = w->znext[v]) {
            (*budget)--;
            if (blocks(w, v, a, b, c, bb))
                return 0;
        }
        return 1;
    }
    for (v = w->rhead; v != NONE; v = w->rnext[v]) {
        (*budget)--;
        if (blocks(w, v, a, b, c, bb))
            return 0;
    }
    return 1;
}

/* Remove v from the outline; its neighbours' corners change. */
static void clip_vertex(ear_work *w, size_t v)
{
    size_t a = w->prev[v], c = w->next[v];
    w->next[a] = c;
    w->prev[c] = a;
    reflex_remove(w, v);
    if (w->zmode) {
        if (w->zprev[v] != NONE)
            w->znext[w->zprev[v]] = w->znext[v];
        if (w->znext[v] != NONE)
            w->zprev[w->znext[v]] = w->zprev[v];
    }
    reflex_update(w, a);
    reflex_update(w, c);
}

/*
 * Triangulate the face poly[0..n-1] (0-based vertex indices into pos) into
 * out[0 .. 3 (n - 2) - 1], wound like the face.
 */
static void triangulate(const double *pos, const uint32_t *poly, size_t n, ear_work *w,
                        uint16_t *out)
{
    double nrm[3] = {0.0, 0.0, 0.0};
    size_t i, k, u, v, remaining, cur, stall, emitted = 0;
    long budget = EAR_BUDGET;
    double flip;

#define EMIT(a, b, c)                                                                              \
    do {                                                                                           \
        out[3 * emitted + 0] = (uint16_t)poly[a];                                                  \
        out[3 * emitted + 1] = (uint16_t)poly[b];                                                  \
        out[3 * emitted + 2] = (uint16_t)poly[c];                                                  \
        emitted++;                                                                                 \
    } while (0)

    if (n < 3) /* cannot happen: faces have 3 or more vertices */
        return;
    if (n == 3) {
        EMIT(0, 1, 2);
        return;
    }
    /* Newell normal: robust for concave and slightly non-planar polygons. */
    for (i = 0; i < n; i++) {
        const double *p = pos + 3 * (size_t)poly[i];
        const double *q = pos + 3 * (size_t)poly[(i + 1) % n];
        nrm[0] += (p[1] - q[1]) * (p[2] + q[2]);
        nrm[1] += (p[2] - q[2]) * (p[0] + q[0]);
        nrm[2] += (p[0] - q[0]) * (p[1] + q[1]);
    }
    /* Drop the dominant axis k; (u, v) = the next two axes in cyclic order,
     * in which the polygon's signed area is nrm[k] / 2. */
    k = 0;
    if (fabs(nrm[1]) > fabs(nrm[k]))
        k = 1;
    if (fabs(nrm[2]) > fabs(nrm[k]))
        k = 2;
    u = (k + 1) % 3;
    v = (k + 2) % 3;
    flip = nrm[k] < 0.0 ? -1.0 : 1.0; /* mirror clockwise outlines to counter-clockwise */
    {
        const double *o = pos + 3 * (size_t)poly[0];
        for (i = 0; i < n; i++) {
            const double *p = pos + 3 * (size_t)poly[i];
            w->x[i] = p[u] - o[u];
            w->y[i] = (p[v] - o[v]) * flip;
            w->prev[i] = (i + n - 1) % n;
            w->next[i] = (i + 1) % n;
            w->reflex[i] = 0;
        }
    }
    w->rhead = NONE;
    w->zmode = n > ZORDER_MIN;
    if (w->zmode)
        zorder_build(w, n);
    for (i = n; i-- > 0;)
        if (corner(w, i) <= 0.0)
            reflex_insert(w, i);

    remaining = n;
    cur = 0;
    stall = 0;
    while (remaining > 3) {
        size_t a = w->prev[cur], c = w->next[cur];
        if (is_ear(w, a, cur, c, &budget)) {
            EMIT(a, cur, c);
            clip_vertex(w, cur);
            remaining--;
            stall = 0;
            cur = w->next[c]; /* step past c: fewer slivers */
            continue;
        }
        cur = c;
        if (++stall < remaining)
            continue;
        /*
         * A full turn without an ear: the outline is degenerate. First drop
         * every flat vertex (collinear, a spike, a repeated point) as a
         * zero-area triangle; if there is none, clip a convex vertex even
         * though something blocks it, or else any vertex. Each turn clips at
         * least one vertex, so the loop ends.
         */
        {
            size_t count = remaining, j, vtx = cur, removed = 0;
            for (j = 0; j < count && remaining > 3; j++) {
                size_t nxt = w->next[vtx];
                if (corner(w, vtx) == 0.0) {
                    EMIT(w->prev[vtx], vtx, w->next[vtx]);
                    clip_vertex(w, vtx);
                    remaining--;
                    removed++;
                }
                vtx = nxt;
            }
            if (removed == 0) {
                size_t pick = cur;
                vtx = cur;
                for (j = 0; j < remaining; j++) {
                    if (corner(w, vtx) > 0.0) {
                        pick = vtx;
                        break;
                    }
                    vtx = w->next[vtx];
                }
                EMIT(w->prev[pick], pick, w->next[pick]);
                vtx = w->next[pick];
                clip_vertex(w, pick);
                remaining--;
            }
            cur = vtx;
            stall = 0;
        }
    }
    EMIT(w->prev[cur], cur, w->next[cur]);
#undef EMIT
}

/* ------------------------------------------------------------- the loader */

void zl_obj_options_default(zl_obj_options *opt)
{
    if (opt != NULL)
        opt->normalize = 0;
}

static void parser_free(parser *p)
{
    free(p->pos);
    free(p->col);
    free(p->poly);
    free(p->poly_vt);
    free(p->vt);
    free(p->poly_vn);
    free(p->vn);
    free(p->faces);
}

static zl_obj_status parse_text(parser *p, const char *buf, size_t size)
{
    size_t pos, start;
    const char *line;
    size_t len, i;
    unsigned long lines, next_physical;
    zl_obj_status st;

    st = check_encoding(p, (const unsigned char *)buf, size, &start);
    if (st != ZL_OBJ_OK)
        return st;

    /* Counting pass. */
    for (pos = start; next_line(buf, size, &pos, &line, &len, &lines);) {
        const char *cur = line;
        token t;
        if (!next_token(&cur, line + len, &t))
            continue;
        if (tok_is(t, "v"))
            p->v_total++;
        else if (tok_is(t, "vt"))
            p->vt_total++;
        else if (tok_is(t, "vn"))
            p->vn_total++;
    }

    /* Parsing pass. */
    next_physical = 1;
    for (pos = start; next_line(buf, size, &pos, &line, &len, &lines);) {
        const char *cur = line, *end = line + len;
        token t;
        p->line = next_physical; /* errors name the line the statement starts on */
        next_physical += lines;
        if (!next_token(&cur, end, &t))
            continue; /* blank or a comment */
        if (is_ignored(t))
            continue;
        st = check_ascii(p, line, len);
        if (st != ZL_OBJ_OK)
            return st;
        if (tok_is(t, "v"))
            st = parse_vertex(p, cur, end);
        else if (tok_is(t, "f"))
            st = parse_face(p, cur, end);
        else if (tok_is(t, "vt"))
            st = parse_attribute(p, cur, end, 0);
        else if (tok_is(t, "vn"))
            st = parse_attribute(p, cur, end, 1);
        else
            st = fail(p, ZL_OBJ_ERR_PARSE, "unknown statement '%.*s%s'", QUOTE(t));
        if (st != ZL_OBJ_OK)
            return st;
    }
    if (p->face_count == 0) {
        /* Nothing but white space: empty. Else (comments, vertices): no faces,
         * reported at the last line. */
        for (i = start; i < size && (is_space(buf[i]) || buf[i] == '\n'); i++)
            ;
        if (i == size) {
            p->line = 1;
            return fail(p, ZL_OBJ_ERR_PARSE, "the file is empty");
        }
        return fail(p, ZL_OBJ_ERR_PARSE, "no faces (f lines) in the file");
    }
    return ZL_OBJ_OK;
}

static void ear_work_free(ear_work *w)
{
    free(w->x);
    free(w->y);
    free(w->prev);
    free(w->next);
    free(w->rprev);
    free(w->rnext);
    free(w->reflex);
    free(w->z);
    free(w->zprev);
    free(w->znext);
    free(w->keys);
}

/* Q16.16 of a texture coordinate, saturated. */
static zl_fixed tex_fixed(double c)
{
    double r = floor(c * 65536.0 + 0.5);
    return (zl_fixed)(r > 2147483647.0 ? 2147483647.0 : (r < -2147483648.0 ? -2147483648.0 : r));
}

/*
 * Texture coordinates per vertex: a position used with different vt (a
 * seam) becomes one vertex per (position, vt) pair, with the position (and
 * colour) copied. The triangles' corners are found back in their face by
 * position (the first corner with that position, for a face that repeats
 * one). Corners without vt get (0, 0). t = 1 - v: OBJ's v points up, a
 * texture's rows go down.
 */
static zl_obj_status split_by_vt(parser *p, zl_obj *obj)
{
    size_t nv = p->v_count, tri = 0, i, k, count = 0;
    size_t corners = p->tri_total * 3;
    long *head = (long *)malloc(nv * sizeof(long) + 1);
    long *next = (long *)malloc(corners * sizeof(long) + 1);
    uint32_t *key_vt = (uint32_t *)malloc(corners * sizeof(uint32_t) + 1);
    uint32_t *src = (uint32_t *)malloc(corners * sizeof(uint32_t) + 1); /* new vertex -> position */
    zl_fixed *pos, *uv;
    uint8_t *col = NULL;
    int16_t *nrm = NULL;
    if (head == NULL || next == NULL || key_vt == NULL || src == NULL) {
        free(head);
        free(next);
        free(key_vt);
        free(src);
        return out_of_memory(p);
    }
    for (i = 0; i < nv; i++)
        head[i] = -1;
    for (i = 0; i < p->face_count; i++) {
        const face_rec *f = &p->faces[i];
        size_t t;
        for (t = 0; t < f->count - 2; t++, tri++)
            for (k = 0; k < 3; k++) {
                uint16_t *ix = &obj->indices[tri * 3 + k];
                uint32_t vt = NO_VT;
                size_t c;
                long e;
                for (c = 0; c < f->count; c++)
                    if (p->poly[f->first + c] == *ix) {
                        vt = p->poly_vt[f->first + c];
                        break;
                    }
                /* *ix < nv (the parser checked every index), and head[0 .. nv)
                 * is set above: the analyser's path has nv == 0 with a face */
                /* NOLINTNEXTLINE(clang-analyzer-core.uninitialized.Assign) */
                for (e = head[*ix]; e >= 0 && key_vt[e] != vt; e = next[e])
                    ;
                if (e < 0) {
                    if (count >= ZL_OBJ_MAX_VERTICES) {
                        free(head);
                        free(next);
                        free(key_vt);
                        free(src);
                        return fail(p, ZL_OBJ_ERR_LIMIT,
                                    "more than %u vertices once vertices with several texture "
                                    "coordinates are split",
                                    ZL_OBJ_MAX_VERTICES);
                    }
                    e = (long)count++;
                    key_vt[e] = vt;
                    src[e] = *ix;
                    next[e] = head[*ix];
                    head[*ix] = e;
                }
                *ix = (uint16_t)e;
            }
    }
    pos = (zl_fixed *)malloc(count * 3 * sizeof(zl_fixed) + 1);
    uv = (zl_fixed *)malloc(count * 2 * sizeof(zl_fixed) + 1);
    if (obj->vertex_colors != NULL)
        col = (uint8_t *)malloc(count * 3 + 1);
    if (obj->normals != NULL)
        nrm = (int16_t *)malloc(count * 3 * sizeof(int16_t) + 1);
    if (pos == NULL || uv == NULL || (obj->vertex_colors != NULL && col == NULL) ||
        (obj->normals != NULL && nrm == NULL)) {
        free(pos);
        free(uv);
        free(col);
        free(nrm);
        free(head);
        free(next);
        free(key_vt);
        free(src);
        return out_of_memory(p);
    }
    for (i = 0; i < count; i++) {
        for (k = 0; k < 3; k++) {
            pos[i * 3 + k] = obj->positions[src[i] * 3 + k];
            if (col != NULL)
                col[i * 3 + k] = obj->vertex_colors[src[i] * 3 + k];
            if (nrm != NULL)
                nrm[i * 3 + k] = obj->normals[src[i] * 3 + k];
        }
        uv[i * 2] = key_vt[i] == NO_VT ? 0 : tex_fixed(p->vt[key_vt[i] * 2]);
        uv[i * 2 + 1] = key_vt[i] == NO_VT ? 0 : tex_fixed(1.0 - p->vt[key_vt[i] * 2 + 1]);
    }
    free(obj->positions);
    free(obj->vertex_colors);
    obj->positions = pos;
    obj->vertex_colors = col;
    if (nrm != NULL) {
        free(obj->normals);
        obj->normals = nrm;
    }
    obj->texcoords = uv;
    obj->vertex_count = (uint32_t)count;
    free(head);
    free(next);
    free(key_vt);
    free(src);
    return ZL_OBJ_OK;
}

/* (c - center) / half, within -1 .. 1: the difference is at most half in
 * magnitude (c lies in the box), so it is finite, and a division (not a
 * multiplication by an infinite 1 / half) stays finite for a denormal half. */
static double normalised(double c, double center, double half)
{
    double v = half > 0.0 ? (c - center) / half : 0.0;
    return v < -1.0 ? -1.0 : v > 1.0 ? 1.0 : v;
}

/* Q16.16, rounded to nearest (ties up), of a value checked to be in range;
 * clamped all the same, so that no input reaches an undefined conversion. */
static zl_fixed to_q16(double c)
{
    double r = floor(c * 65536.0 + 0.5);
    if (!(r >= -2147483648.0))
        return INT32_MIN; /* also NaN, which the checks before exclude */
    return r > 2147483647.0 ? INT32_MAX : (zl_fixed)r;
}

/* A unit vector as Q14 int16 (16384 = 1.0), rounded; zero stays zero. */
static void normal_q14(const double *v, int16_t *out)
{
    double len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    int k;
    for (k = 0; k < 3; k++)
        out[k] = (int16_t)(len > 0.0 ? floor(v[k] / len * 16384.0 + 0.5) : 0.0);
}

/*
 * Per-vertex normals from the faces' vn: a vertex gets the normalised sum
 * of the unit vn of every face corner that uses it (one vn per vertex, the
 * usual smooth export, gives exactly that vn; vertices are not split by vn,
 * so a hard edge is smoothed). A vertex without a vn corner gets (0, 0, 0).
 * Normalising the model (a uniform scale) leaves normals unchanged.
 */
static zl_obj_status normals_from_vn(parser *p, zl_obj *obj)
{
    size_t nv = p->v_count, c, i;
    double *acc = (double *)calloc(nv * 3 + 1, sizeof(double));
    obj->normals = (int16_t *)malloc(nv * 3 * sizeof(int16_t) + 1);
    if (acc == NULL || obj->normals == NULL) {
        free(acc);
        return out_of_memory(p);
    }
    for (c = 0; c < p->poly_count; c++) {
        uint32_t n = p->poly_vn[c];
        const double *v;
        double len;
        if (n == NO_VT)
            continue;
        v = &p->vn[n * 3u];
        len = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (len > 0.0)
            for (i = 0; i < 3; i++)
                acc[p->poly[c] * 3u + i] += v[i] / len;
    }
    for (i = 0; i < nv; i++)
        normal_q14(&acc[i * 3], &obj->normals[i * 3]);
    free(acc);
    return ZL_OBJ_OK;
}

/* Move the parsed data into *obj: normalise, convert, triangulate. */
static zl_obj_status build(parser *p, zl_obj *obj)
{
    size_t i, j, t = 0;
    ear_work w;
    double scale = 1.0, center[3] = {0.0, 0.0, 0.0};

    memset(&w, 0, sizeof w);
    obj->positions = (zl_fixed *)malloc(p->v_count * 3 * sizeof(zl_fixed) + 1);
    /* zeroed: every entry is written by triangulate(), and the analysers
     * need not prove it */
    obj->indices = (uint16_t *)calloc(p->tri_total * 3 + 1, sizeof(uint16_t));
    w.x = (double *)malloc(p->max_face * sizeof(double));
    w.y = (double *)malloc(p->max_face * sizeof(double));
    w.prev = (size_t *)malloc(p->max_face * sizeof(size_t));
    w.next = (size_t *)malloc(p->max_face * sizeof(size_t));
    w.rprev = (size_t *)malloc(p->max_face * sizeof(size_t));
    w.rnext = (size_t *)malloc(p->max_face * sizeof(size_t));
    w.reflex = (unsigned char *)malloc(p->max_face);
    if (p->max_face > ZORDER_MIN) {
        w.z = (uint32_t *)malloc(p->max_face * sizeof(uint32_t));
        w.zprev = (size_t *)malloc(p->max_face * sizeof(size_t));
        w.znext = (size_t *)malloc(p->max_face * sizeof(size_t));
        w.keys = (zkey *)malloc(p->max_face * sizeof(zkey));
    }
    if (obj->positions == NULL || obj->indices == NULL || w.x == NULL || w.y == NULL ||
        w.prev == NULL || w.next == NULL || w.rprev == NULL || w.rnext == NULL ||
        w.reflex == NULL ||
        (p->max_face > ZORDER_MIN &&
         (w.z == NULL || w.zprev == NULL || w.znext == NULL || w.keys == NULL))) {
        ear_work_free(&w);
        return out_of_memory(p);
    }

    for (j = 0; j < 3; j++) {
        obj->bbox_min[j] = p->v_count ? p->pos[j] : 0.0;
        obj->bbox_max[j] = obj->bbox_min[j];
    }
    for (i = 0; i < p->v_count; i++)
        for (j = 0; j < 3; j++) {
            double c = p->pos[3 * i + j];
            if (c < obj->bbox_min[j])
                obj->bbox_min[j] = c;
            if (c > obj->bbox_max[j])
                obj->bbox_max[j] = c;
        }
    if (p->normalize) {
        /* Halves first: max - min and min + max can overflow near DBL_MAX,
         * and 2 / extent is infinite for a denormal extent; half-extents
         * and the centre of halves are finite for every finite input. */
        double half = 0.0;
        for (j = 0; j < 3; j++) {
            double h = 0.5 * obj->bbox_max[j] - 0.5 * obj->bbox_min[j];
            center[j] = 0.5 * obj->bbox_min[j] + 0.5 * obj->bbox_max[j];
            if (h > half)
                half = h;
        }
        /* A single point stays a point, at the origin. 1 / half may be
         * infinite for a denormal extent: obj->scale is informative only,
         * the positions divide by half. */
        scale = half > 0.0 ? 1.0 / half : 1.0;
        for (i = 0; i < 3 * p->v_count; i++)
            obj->positions[i] = to_q16(normalised(p->pos[i], center[i % 3], half));
    } else {
        for (i = 0; i < 3 * p->v_count; i++)
            obj->positions[i] = to_q16(p->pos[i]); /* range checked while parsing */
    }
    for (j = 0; j < 3; j++)
        obj->center[j] = center[j];
    obj->scale = scale;

    for (i = 0; i < p->face_count; i++) {
        const face_rec *f = &p->faces[i];
        triangulate(p->pos, p->poly + f->first, f->count, &w, obj->indices + 3 * t);
        t += f->count - 2;
    }
    ear_work_free(&w);

    if (p->colored == p->v_count && p->v_count > 0) {
        obj->vertex_colors = p->col;
        p->col = NULL; /* handed over */
    }
    obj->vertex_count = (uint32_t)p->v_count;
    if (p->corners_with_vn > 0) {
        zl_obj_status st = normals_from_vn(p, obj);
        if (st != ZL_OBJ_OK)
            return st;
    }
    if (p->texcoords && p->corners_with_vt > 0) {
        zl_obj_status st = split_by_vt(p, obj);
        if (st != ZL_OBJ_OK)
            return st;
    }
    obj->triangle_count = (uint32_t)p->tri_total;
    obj->face_count = (uint32_t)p->face_count;
    return ZL_OBJ_OK;
}

static zl_obj_status load_mem(zl_obj *obj, const char *data, size_t size, const char *name,
                              const zl_obj_options *opt, int texcoords, char *msg, size_t msg_size)
{
    parser p;
    zl_obj_status st;
    if (msg != NULL && msg_size > 0)
        msg[0] = '\0';
    if (obj == NULL || (data == NULL && size > 0)) {
        set_msg(msg, msg_size, "zl_obj_load_mem: NULL argument");
        return ZL_OBJ_ERR_ARG;
    }
    memset(obj, 0, sizeof *obj);
    memset(&p, 0, sizeof p);
    p.name = name != NULL ? name : "(memory)";
    p.msg = msg;
    p.msg_size = msg_size;
    p.normalize = opt != NULL ? opt->normalize : 0;
    p.texcoords = texcoords;
    {
        const struct lconv *lc = localeconv();
        p.decimal_point = (lc != NULL && lc->decimal_point != NULL &&
                           lc->decimal_point[0] != '\0' && lc->decimal_point[1] == '\0')
                              ? lc->decimal_point[0]
                              : '.';
    }
    st = parse_text(&p, data != NULL ? data : "", size);
    if (st == ZL_OBJ_OK)
        st = build(&p, obj);
    parser_free(&p);
    if (st != ZL_OBJ_OK)
        zl_obj_free(obj);
    return st;
}

zl_obj_status zl_obj_load_mem(zl_obj *obj, const char *data, size_t size, const char *name,
                              const zl_obj_options *opt, char *msg, size_t msg_size)
{
    return load_mem(obj, data, size, name, opt, 0, msg, msg_size);
}

zl_obj_status zl_obj_load_mem_tex(zl_obj *obj, const char *data, size_t size, const char *name,
                                  const zl_obj_options *opt, char *msg, size_t msg_size)
{
    return load_mem(obj, data, size, name, opt, 1, msg, msg_size);
}

static zl_obj_status load_file(zl_obj *obj, const char *path, const zl_obj_options *opt, int texcoords,
                               char *msg, size_t msg_size)
{
    char *buf;
    size_t size;
    zl_read_status rs;
    zl_obj_status st;
    if (msg != NULL && msg_size > 0)
        msg[0] = '\0';
    if (obj == NULL || path == NULL) {
        set_msg(msg, msg_size, "zl_obj_load_file: NULL argument");
        return ZL_OBJ_ERR_ARG;
    }
    memset(obj, 0, sizeof *obj);
    rs = zl_read_file(path, &buf, &size, msg, msg_size);
    if (rs != ZL_READ_OK)
        return rs == ZL_READ_ERR_MEMORY ? ZL_OBJ_ERR_MEMORY : ZL_OBJ_ERR_IO;
    st = load_mem(obj, buf, size, path, opt, texcoords, msg, msg_size);
    free(buf);
    return st;
}

zl_obj_status zl_obj_load_file(zl_obj *obj, const char *path, const zl_obj_options *opt, char *msg,
                               size_t msg_size)
{
    return load_file(obj, path, opt, 0, msg, msg_size);
}

zl_obj_status zl_obj_load_file_tex(zl_obj *obj, const char *path, const zl_obj_options *opt, char *msg,
                                   size_t msg_size)
{
    return load_file(obj, path, opt, 1, msg, msg_size);
}

void zl_obj_free(zl_obj *obj)
{
    if (obj == NULL)
        return;
    free(obj->positions);
    free(obj->indices);
    free(obj->vertex_colors);
    free(obj->texcoords);
    free(obj->normals);
    memset(obj, 0, sizeof *obj);
}

zl_mesh zl_obj_mesh(const zl_obj *obj)
{
    zl_mesh m;
    memset(&m, 0, sizeof m);
    if (obj == NULL)
        return m;
    m.positions = obj->positions;
    m.indices = obj->indices;
    m.vertex_colors = obj->vertex_colors;
    m.face_colors = NULL;
    m.vertex_count = (uint16_t)obj->vertex_count;
    m.triangle_count = (uint16_t)obj->triangle_count;
    return m;
}

const char *zl_obj_status_name(zl_obj_status s)
{
    switch (s) {
    case ZL_OBJ_OK:
        return "ok";
    case ZL_OBJ_ERR_IO:
        return "I/O error";
    case ZL_OBJ_ERR_PARSE:
        return "malformed OBJ";
    case ZL_OBJ_ERR_LIMIT:
        return "too large for a zl_mesh";
    case ZL_OBJ_ERR_MEMORY:
        return "out of memory";
    case ZL_OBJ_ERR_ARG:
        return "bad argument";
    }
    return "unknown status";
}

/* Position of vertex v as doubles. */
static void vertex_pos(const zl_obj *obj, uint32_t v, double *out)
{
    int k;
    for (k = 0; k < 3; k++)
        out[k] = obj->positions[v * 3u + (unsigned)k] / 65536.0;
}

/* A vertex's position and index, sorted to find vertices at one position. */
typedef struct {
    zl_fixed p[3];
    uint32_t i;
} pos_key;

static int pos_cmp(const void *pa, const void *pb)
{
    const pos_key *a = (const pos_key *)pa, *b = (const pos_key *)pb;
    int k;
    for (k = 0; k < 3; k++)
        if (a->p[k] != b->p[k])
            return a->p[k] < b->p[k] ? -1 : 1;
    return a->i < b->i ? -1 : (a->i > b->i ? 1 : 0);
}

zl_obj_status zl_obj_compute_normals(zl_obj *obj, zl_obj_normal_weight weight)
{
    uint32_t nv, t, i, k;
    double *acc;
    pos_key *order;
    int16_t *out;
    if (obj == NULL || obj->positions == NULL || (weight != ZL_OBJ_NORMALS_AREA && weight != ZL_OBJ_NORMALS_ANGLE))
        return ZL_OBJ_ERR_ARG;
    nv = obj->vertex_count;
    acc = (double *)calloc((size_t)nv * 3 + 1, sizeof(double));
    order = (pos_key *)malloc((size_t)nv * sizeof(pos_key) + 1);
    out = (int16_t *)malloc((size_t)nv * 3 * sizeof(int16_t) + 1);
    if (acc == NULL || order == NULL || out == NULL) {
        free(acc);
        free(order);
        free(out);
        return ZL_OBJ_ERR_MEMORY;
    }
    for (t = 0; t < obj->triangle_count; t++) {
        const uint16_t *ix = &obj->indices[t * 3u];
        double p[3][3], e1[3], e2[3], n[3], len;
        for (k = 0; k < 3; k++)
            vertex_pos(obj, ix[k], p[k]);
        for (k = 0; k < 3; k++) {
            e1[k] = p[1][k] - p[0][k];
            e2[k] = p[2][k] - p[0][k];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len == 0.0)
            continue; /* zero area: no direction */
        for (k = 0; k < 3; k++) {
            double w = 1.0; /* area: the cross product's length is twice the area */
            unsigned j;
            if (weight == ZL_OBJ_NORMALS_ANGLE) {
                /* the corner's angle, with the unit normal */
                const double *a = p[k], *b = p[(k + 1) % 3], *c = p[(k + 2) % 3];
                double u[3], v[3], uu = 0, vv = 0, uv = 0, cs;
                for (j = 0; j < 3; j++) {
                    u[j] = b[j] - a[j];
                    v[j] = c[j] - a[j];
                    uu += u[j] * u[j];
                    vv += v[j] * v[j];
                    uv += u[j] * v[j];
                }
                cs = uu > 0 && vv > 0 ? uv / sqrt(uu * vv) : 1.0;
                w = acos(cs < -1.0 ? -1.0 : (cs > 1.0 ? 1.0 : cs)) / len;
            }
            for (j = 0; j < 3; j++)
                acc[ix[k] * 3u + j] += n[j] * w;
        }
    }
    /* Vertices at one position (split at texture seams, or repeated in the
     * file) share the sum, so seams do not show in the lighting. */
    for (i = 0; i < nv; i++) {
        for (k = 0; k < 3; k++)
            order[i].p[k] = obj->positions[i * 3u + k];
        order[i].i = i;
    }
    qsort(order, nv, sizeof order[0], pos_cmp);
    for (i = 0; i < nv;) {
        uint32_t j = i, m;
        double sum[3] = {0.0, 0.0, 0.0};
        int16_t q[3];
        while (j < nv && memcmp(order[j].p, order[i].p, sizeof order[i].p) == 0) {
            for (k = 0; k < 3; k++)
                sum[k] += acc[order[j].i * 3u + k];
            j++;
        }
        normal_q14(sum, q);
        for (m = i; m < j; m++)
            for (k = 0; k < 3; k++)
                out[order[m].i * 3u + k] = q[k];
        i = j;
    }
    free(acc);
    free(order);
    free(obj->normals);
    obj->normals = out;
    return ZL_OBJ_OK;
}
