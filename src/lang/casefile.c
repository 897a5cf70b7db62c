/* casefile.c -- reading .case files into rs_case_t: logical lines
 * (continuations, comments), the statement keywords, include.  The builder
 * and recurrence statements are in stmt_builder.c and stmt_recurrence.c. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/stat.h>
#include "parse.h"

static int name_taken(const rs_case_struct *c, const char *name)
{
    return rs_case_param_index(c, name) >= 0 || rs_case_unknown_index(c, name) >= 0
        || rs_case_let_index(c, name) >= 0;
}

static int check_new_name(rs_stmt_t *x, size_t at, const char *name)
{
    if (rs_name_is_reserved(name)) {
        char fmt[96];
        /* the phrase is a fixed string of ours, so it can sit in the format */
        snprintf(fmt, sizeof fmt, "'%%s' is reserved (%s); choose another name", rs_name_reserved_why(name));
        return _rs_at_err(x, at, RS_ERR_INPUT, fmt, name);
    }
    if (name_taken(x->c, name))
        return _rs_at_err(x, at, RS_ERR_INPUT, "'%s' is already declared", name);
    if (x->c->nparams + x->c->nunknowns + x->c->nlets >= RS_CASE_MAX_NAMES)
        return _rs_at_err(x, at, RS_ERR_LIMIT, "too many names (limit %s)", "256");
    return RS_OK;
}

/* param / unknown: NAME [,] NAME ... */
static int st_names(rs_stmt_t *x, size_t i, int unknowns)
{
    const char *t = x->src.text;
    int count = 0;
    for (;;) {
        char *name;
        size_t at;
        _rs_skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == '\0') break;
        at = i;
        name = _rs_read_ident(t, &i);
        if (name == NULL)
            return _rs_name_err(x, at, unknowns ? "an unknown's name" : "a parameter name");
        {
            /* `param z complex`: the test equation's z may keep its name */
            size_t j = i;
            _rs_skip_ws(t, &j);
            if (!unknowns && strcmp(name, "z") == 0 && strncmp(t + j, "complex", 7) == 0
                && (t[j + 7] == '\0' || t[j + 7] == ',' || t[j + 7] == ' ' || t[j + 7] == '\t')) {
                if (name_taken(x->c, name)) {
                    flint_free(name);
                    return _rs_at_err(x, at, RS_ERR_INPUT, "'%s' is already declared", "z");
                }
            } else if (check_new_name(x, at, name) != RS_OK) {
                flint_free(name);
                return x->err->code;
            }
        }
        if (unknowns) {
            RS_GROW(x->c->unknowns, x->c->nunknowns);
            x->c->unknowns[x->c->nunknowns].name = name;
            _rs_set_loc(x, &x->c->unknowns[x->c->nunknowns].loc, at);
            x->c->nunknowns++;
        } else {
            size_t j = i;
            RS_GROW(x->c->params, x->c->nparams);
            x->c->params[x->c->nparams].name = name;
            _rs_set_loc(x, &x->c->params[x->c->nparams].loc, at);
            /* `param NAME angle`: a wave-number angle, rewritten exactly with
             * t = tan(NAME/2) wherever sin/cos of it appear (scheme.c) */
            _rs_skip_ws(t, &j);
            if (strncmp(t + j, "angle", 5) == 0 && (t[j + 5] == '\0' || t[j + 5] == ',' || t[j + 5] == ' '
                                                   || t[j + 5] == '\t')) {
                x->c->params[x->c->nparams].angle = 1;
                i = j + 5;
            } else if (strncmp(t + j, "complex", 7) == 0 && (t[j + 7] == '\0' || t[j + 7] == ',' || t[j + 7] == ' '
                                                            || t[j + 7] == '\t')) {
                /* `param NAME complex`: a complex parameter (analyses take Re and Im apart) */
                x->c->params[x->c->nparams].complex = 1;
                i = j + 7;
            }
            x->c->nparams++;
        }
        count++;
    }
    if (count == 0)
        return _rs_expect_err(x, i, unknowns ? "at least one unknown's name" : "at least one parameter name");
    return RS_OK;
}

static int st_assume(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    for (;;) {
        rs_cond_t cond;
        int r = rs_cond_parse(&cond, &x->src, &i, x->err);
        if (r != RS_OK)
            return r;
        RS_GROW(x->c->assume, x->c->nassume);
        x->c->assume[x->c->nassume++] = cond;
        _rs_skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == '\0') break;
        return _rs_expect_err(x, i, "',' or end of line after a condition");
    }
    return RS_OK;
}

static int st_let(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_expr_t *lhs = NULL, *e = NULL;
    size_t at;
    rs_let_t *l;
    int r;
    _rs_skip_ws(t, &i);
    at = i;
    r = rs_expr_parse(&lhs, &x->src, &i, x->err);
    if (r != RS_OK)
        return r;
    if (lhs->kind != RS_EXPR_NAME) {
        rs_expr_free(lhs);
        return _rs_expect_err(x, at, "a name (let NAME = EXPR or let NAME[n+K] = EXPR)");
    }
    if (check_new_name(x, at, lhs->name) != RS_OK) { rs_expr_free(lhs); return x->err->code; }
    _rs_skip_ws(t, &i);
    if (t[i] != '=') { rs_expr_free(lhs); return _rs_expect_err(x, i, "'=' after the name in let"); }
    i++;
    _rs_skip_ws(t, &i);
    {
        rs_src_t sub = x->src;
        r = rs_expr_parse(&e, &sub, &i, x->err);
    }
    if (r != RS_OK) { rs_expr_free(lhs); return r; }
    _rs_skip_ws(t, &i);
    if (t[i] != '\0') { rs_expr_free(lhs); rs_expr_free(e); return _rs_expect_err(x, i, "an operator or end of line"); }
    RS_GROW(x->c->lets, x->c->nlets);
    l = &x->c->lets[x->c->nlets++];
    l->name = lhs->name; lhs->name = NULL;
    l->shifted = lhs->shifted;
    l->shift = lhs->shift;
    l->e = e;
    _rs_set_loc(x, &l->loc, at);
    l->text = rs_strdup(t + at);
    rs_expr_free(lhs);
    return RS_OK;
}

static int st_eq(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_expr_t *lhs = NULL, *rhs = NULL;
    size_t at;
    rs_eq_t *q;
    int r;
    _rs_skip_ws(t, &i);
    at = i;
    r = rs_expr_parse(&lhs, &x->src, &i, x->err);
    if (r != RS_OK) return r;
    _rs_skip_ws(t, &i);
    if (t[i] == '=' && t[i + 1] == '=') {
        rs_expr_free(lhs);
        return _rs_at_err(x, i, RS_ERR_INPUT, "expected a single '=' in the equation (eq EXPR = EXPR), found %s", "'=='");
    }
    if (t[i] != '=') { rs_expr_free(lhs); return _rs_expect_err(x, i, "'=' in the equation (eq EXPR = EXPR)"); }
    i++;
    r = rs_expr_parse(&rhs, &x->src, &i, x->err);
    if (r != RS_OK) { rs_expr_free(lhs); return r; }
    _rs_skip_ws(t, &i);
    if (t[i] != '\0') { rs_expr_free(lhs); rs_expr_free(rhs); return _rs_expect_err(x, i, "an operator or end of line"); }
    RS_GROW(x->c->eqs, x->c->neqs);
    q = &x->c->eqs[x->c->neqs++];
    q->lhs = lhs; q->rhs = rhs;
    _rs_set_loc(x, &q->loc, at);
    q->text = rs_strdup(t + at);
    return RS_OK;
}

static int st_char(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_expr_t *e = NULL;
    size_t at;
    int r;
    _rs_skip_ws(t, &i);
    at = i;
    if (x->c->charexpr != NULL)
        return _rs_at_err(x, at, RS_ERR_INPUT, "a case has one char statement; this is a second one%s", "");
    r = rs_expr_parse(&e, &x->src, &i, x->err);
    if (r != RS_OK) return r;
    _rs_skip_ws(t, &i);
    if (t[i] == '=') {
        /* accept `char EXPR = 0` */
        size_t j = i + 1;
        _rs_skip_ws(t, &j);
        if (t[j] == '0') {
            size_t k = j + 1;
            _rs_skip_ws(t, &k);
            if (t[k] == '\0') i = k;
        }
    }
    if (t[i] != '\0') { rs_expr_free(e); return _rs_expect_err(x, i, "an operator or end of line"); }
    x->c->charexpr = e;
    _rs_set_loc(x, &x->c->charloc, at);
    return RS_OK;
}

/* label NAME = "TEXT": the axis and legend label of a parameter or table
 * column in plots (LaTeX notation allowed; \\ and \" stand for \ and ",
 * other backslashes are kept: "Re \Lambda_1" and "Re \\Lambda_1" are
 * the same label). */
static int st_label(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_case_struct *c = x->c;
    size_t at, k, n = 0;
    char *name, *text;
    slong j;
    _rs_skip_ws(t, &i);
    at = i;
    name = _rs_read_ident(t, &i);
    if (name == NULL) return _rs_name_err(x, at, "a parameter or column name (label NAME = \"TEXT\")");
    _rs_skip_ws(t, &i);
    if (t[i] != '=') { flint_free(name); return _rs_expect_err(x, i, "'=' after the name in label"); }
    i++;
    _rs_skip_ws(t, &i);
    if (t[i] != '"') { flint_free(name); return _rs_expect_err(x, i, "a quoted label text (label NAME = \"TEXT\")"); }
    text = flint_malloc(strlen(t + i) + 1);
    for (k = i + 1; t[k] != '\0' && t[k] != '"'; k++) {
        if (t[k] == '\\' && (t[k + 1] == '\\' || t[k + 1] == '"')) k++;
        text[n++] = t[k];
    }
    text[n] = '\0';
    if (t[k] != '"') {
        flint_free(name);
        flint_free(text);
        return _rs_expect_err(x, k, "'\"' closing the label text");
    }
    i = k + 1;
    _rs_skip_ws(t, &i);
    if (t[i] != '\0') { flint_free(name); flint_free(text); return _rs_expect_err(x, i, "end of line after the label"); }
    for (j = 0; j < c->nlabels; j++)
        if (strcmp(c->label_names[j], name) == 0) {
            /* a later label of the same name replaces the earlier one */
            flint_free(c->label_names[j]);
            flint_free(c->label_texts[j]);
            break;
        }
    if (j == c->nlabels) {
        RS_GROW(c->label_names, c->nlabels);
        RS_GROW(c->label_texts, c->nlabels);
        c->nlabels++;
    }
    c->label_names[j] = name;
    c->label_texts[j] = text;
    return RS_OK;
}

static int st_set(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    for (;;) {
        size_t at;
        char *name;
        rs_expr_t *e = NULL;
        fmpq_t v, w;
        int r, line, col;
        _rs_skip_ws(t, &i);
        at = i;
        name = _rs_read_ident(t, &i);
        if (name == NULL) return _rs_name_err(x, at, "a parameter name (set NAME = NUMBER)");
        if (rs_case_param_index(x->c, name) < 0) {
            _rs_at_err(x, at, RS_ERR_INPUT, "'%s' is not a parameter (declare it with `param` first)", name);
            flint_free(name);
            return x->err->code;
        }
        if (x->c->params[rs_case_param_index(x->c, name)].angle) {
            /* its exact variable is tan(NAME/2), so a number would be ambiguous */
            _rs_at_err(x, at, RS_ERR_INPUT, "'%s' is an angle parameter: it ranges over every angle "
                       "(write the value of sin/cos into the char line instead of set)", name);
            flint_free(name);
            return x->err->code;
        }
        _rs_skip_ws(t, &i);
        if (t[i] != '=') { flint_free(name); return _rs_expect_err(x, i, "'=' after the name in set"); }
        i++;
        r = rs_expr_parse(&e, &x->src, &i, x->err);
        if (r != RS_OK) { flint_free(name); return r; }
        fmpq_init(v);
        fmpq_init(w);
        /* i is the imaginary unit (a reserved name, never declared) */
        r = rs_expr_eval_const_complex(v, w, e, &x->src, x->err);
        rs_expr_free(e);
        if (r != RS_OK) { fmpq_clear(v); fmpq_clear(w); flint_free(name); return r; }
        rs_src_pos(&x->src, at, &line, &col);
        _rs_case_set_complex(x->c, name, v, w, x->src.file, line, col);
        fmpq_clear(v);
        fmpq_clear(w);
        flint_free(name);
        _rs_skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == '\0') break;
        return _rs_expect_err(x, i, "',' or end of line in set");
    }
    return RS_OK;
}

static void add_request_at(rs_stmt_t *x, size_t i)
{
    int line, col;
    size_t end = strlen(x->src.text);
    char *txt;
    while (end > i && (x->src.text[end - 1] == ' ' || x->src.text[end - 1] == '\t')) end--;
    txt = rs_strndup(x->src.text + i, end - i);
    rs_src_pos(&x->src, i, &line, &col);
    rs_case_add_request(x->c, txt, x->src.file, line, col);
    flint_free(txt);
}

#define RS_STR_(x) #x
#define RS_STR(x) RS_STR_(x)

static int read_whole(char **out, size_t *outlen, const char *path, int regular_only, struct stat *st,
                      rs_error_t err);
static int parse_text(rs_parser_t *p, const char *path, const char *text, size_t len);

static slong include_find(const rs_parser_t *p, const struct stat *st)
{
    slong k;
    for (k = 0; k < p->nincludes; k++)
        if (p->includes[k].dev == st->st_dev && p->includes[k].ino == st->st_ino) return k;
    return -1;
}

static void include_add(rs_parser_t *p, const struct stat *st)
{
    RS_GROW(p->includes, p->nincludes);
    p->includes[p->nincludes].dev = st->st_dev;
    p->includes[p->nincludes].ino = st->st_ino;
    p->includes[p->nincludes].open = 1;
    p->nincludes++;
}

/* include FILE: relative to the including file's folder.  A file already
 * read in this parse (the same device and inode, whatever the path) is not
 * read again: its statements apply once, so mutual includes stay linear. */
static int st_include(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    const char *slash;
    char *path, *text = NULL;
    size_t len = 0, end;
    struct stat st;
    slong k;
    int r;
    _rs_skip_ws(t, &i);
    end = strlen(t);
    while (end > i && (t[end - 1] == ' ' || t[end - 1] == '\t')) end--;
    if (end == i) return _rs_expect_err(x, i, "a file name after include");
    if (x->p->include_depth >= 16)
        return _rs_at_err(x, i, RS_ERR_LIMIT, "includes nested too deeply (limit 16)%s", "");
    slash = strrchr(x->src.file, '/');
    if (t[i] == '/' || slash == NULL) {
        path = rs_strndup(t + i, end - i);
    } else {
        size_t d = (size_t) (slash - x->src.file) + 1;
        path = flint_malloc(d + (end - i) + 1);
        memcpy(path, x->src.file, d);
        memcpy(path + d, t + i, end - i);
        path[d + end - i] = '\0';
    }
    if (stat(path, &st) == 0 && (k = include_find(x->p, &st)) >= 0) {
        r = x->p->includes[k].open ? _rs_at_err(x, i, RS_ERR_INPUT, "include cycle: '%s' is still being read", path)
                                   : RS_OK;
        flint_free(path);
        return r;
    }
    if (x->p->nincludes > RS_CASE_MAX_INCLUDES) {
        flint_free(path);
        return _rs_at_err(x, i, RS_ERR_LIMIT, "more than " RS_STR(RS_CASE_MAX_INCLUDES) " files included%s", "");
    }
    r = read_whole(&text, &len, path, 1, &st, x->err);
    if (r == RS_OK && x->p->include_bytes + (slong) len > RS_CASE_MAX_INCLUDE_BYTES) {
        flint_free(text);
        flint_free(path);
        return _rs_at_err(x, i, RS_ERR_LIMIT, "included files over 16 MiB in all (the limit)%s", "");
    }
    if (r != RS_OK) {
        char msg[2 * RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "cannot include '%s': %s", path, x->err->msg);
        _rs_at_err(x, i, r == RS_ERR_LIMIT ? RS_ERR_LIMIT : RS_ERR_INPUT, "%s", msg);
        flint_free(path);
        return x->err->code;
    }
    x->p->include_bytes += (slong) len;
    include_add(x->p, &st);
    k = x->p->nincludes - 1;
    x->p->include_depth++;
    r = parse_text(x->p, path, text, len);
    x->p->include_depth--;
    x->p->includes[k].open = 0;
    flint_free(text);
    flint_free(path);
    return r;
}

static int statement(rs_stmt_t *x)
{
    const char *t = x->src.text;
    size_t i = 0, kw;
    char *word;
    int r = RS_OK;
    _rs_skip_ws(t, &i);
    if (t[i] == '\0')
        return RS_OK;
    kw = i;
    word = _rs_read_ident(t, &i);
    if (word == NULL)
        return _rs_expect_err(x, kw, "a statement keyword (title, param, assume, unknown, let, eq, char, set, label, analyse, expect, claim)");
    if (t[i] == '\'') {
        /* a state equation NAME' = EXPR of the current subsystem */
        r = _rs_st_state_equation(x, word, i);
        flint_free(word);
        return r;
    }
    if (t[i] != '\0' && t[i] != ' ' && t[i] != '\t') {
        flint_free(word);
        return _rs_expect_err(x, i, "a space after the statement keyword");
    }
    if (strcmp(word, "title") == 0) {
        size_t end = strlen(t);
        _rs_skip_ws(t, &i);
        while (end > i && (t[end - 1] == ' ' || t[end - 1] == '\t')) end--;
        flint_free(x->c->title);
        x->c->title = rs_strndup(t + i, end - i);
    } else if (strcmp(word, "param") == 0 || strcmp(word, "params") == 0) {
        r = st_names(x, i, 0);
    } else if (strcmp(word, "unknown") == 0 || strcmp(word, "unknowns") == 0) {
        r = st_names(x, i, 1);
    } else if (strcmp(word, "assume") == 0) {
        r = st_assume(x, i);
    } else if (strcmp(word, "let") == 0) {
        r = st_let(x, i);
    } else if (strcmp(word, "eq") == 0) {
        r = st_eq(x, i);
    } else if (strcmp(word, "char") == 0) {
        r = st_char(x, i);
    } else if (strcmp(word, "set") == 0) {
        r = st_set(x, i);
    } else if (strcmp(word, "label") == 0) {
        r = st_label(x, i);
    } else if (strcmp(word, "analyse") == 0 || strcmp(word, "analyze") == 0) {
        _rs_skip_ws(t, &i);
        if (t[i] == '\0')
            r = _rs_expect_err(x, i, "an analysis name after analyse (charpoly, bilinear, routh, ...)");
        else
            add_request_at(x, i);
    } else if (strcmp(word, "expect") == 0 || strcmp(word, "claim") == 0) {
        add_request_at(x, kw);
    } else if (_rs_builder_is_keyword(word)) {
        r = _rs_st_builder(x, word, i);
    } else if (strcmp(word, "include") == 0) {
        r = st_include(x, i);
    } else if (strcmp(word, "recurrence") == 0) {
        r = _rs_st_recurrence(x, i);
    } else {
        r = _rs_expect_err(x, kw, "a statement keyword (title, param, assume, unknown, let, eq, char, set, label, analyse, expect, claim)");
    }
    flint_free(word);
    return r;
}

/* Checks the bytes: no NUL, valid UTF-8.  Reports the first offence. */
static int check_bytes(const char *path, const char *text, size_t len, rs_error_t err)
{
    size_t i = 0;
    int line = 1, col = 1;
    while (i < len) {
        unsigned char ch = (unsigned char) text[i];
        size_t need = 0, k;
        if (ch == 0)
            return rs_error_set_at(err, RS_ERR_INPUT, path, line, col,
                                   "expected text, found a NUL byte (binary data?)");
        if (ch < 0x80) need = 0;
        else if ((ch & 0xe0) == 0xc0 && ch >= 0xc2) need = 1;
        else if ((ch & 0xf0) == 0xe0) need = 2;
        else if ((ch & 0xf8) == 0xf0 && ch <= 0xf4) need = 3;
        else
            return rs_error_set_at(err, RS_ERR_INPUT, path, line, col,
                                   "expected UTF-8 text, found byte 0x%02x", ch);
        for (k = 1; k <= need; k++)
            if (i + k >= len || ((unsigned char) text[i + k] & 0xc0) != 0x80)
                return rs_error_set_at(err, RS_ERR_INPUT, path, line, col,
                                       "expected UTF-8 text, found byte 0x%02x (truncated sequence)", ch);
        if (ch == '\n') { line++; col = 1; } else col++;
        i += need + 1;
    }
    return RS_OK;
}

/* the name of a file read, kept by the case: expression nodes point at it */
static const char *intern_file(rs_case_struct *c, const char *path)
{
    RS_GROW(c->files, c->nfiles);
    c->files[c->nfiles] = rs_strdup(path);
    return c->files[c->nfiles++];
}

static int parse_text(rs_parser_t *p, const char *path, const char *text, size_t len)
{
    rs_error_struct *err = p->err;
    size_t i = 0;
    int lineno = 0, r = RS_OK;
    char *buf;
    int *lmap, *cmap;
    size_t blen = 0, cap;
    int stmt_line = 0;
    const char *file;

    if (len > (size_t) RS_CASE_MAX_BYTES)
        return rs_error_set_at(err, RS_ERR_LIMIT, path, 0, 0,
                               "file too large (%zu bytes; limit %ld bytes)", len, RS_CASE_MAX_BYTES);
    r = check_bytes(path, text, len, err);
    if (r != RS_OK)
        return r;
    file = intern_file(p->c, path);

    /* a statement is at most the text (a joined continuation's space
     * replaces its backslash) and RS_CASE_MAX_LINE: no 576 kB of buffers
     * (fresh pages, trimmed again on free) for a case of a few lines */
    cap = (len < (size_t) RS_CASE_MAX_LINE ? len : (size_t) RS_CASE_MAX_LINE) + 2;
    buf = flint_malloc(cap);
    lmap = flint_malloc(cap * sizeof(int));
    cmap = flint_malloc(cap * sizeof(int));

    while (i < len && r == RS_OK) {
        size_t s = i, ls = i, e, k, cend;
        int cont;
        lineno++;
        while (i < len && text[i] != '\n') i++;
        e = i;                     /* physical line is text[s..e) */
        if (i < len) i++;
        /* a continuation line's leading blanks collapse into the one space
         * that joined it */
        if (blen > 0)
            while (s < e && (text[s] == ' ' || text[s] == '\t')) s++;
        /* strip comment */
        cend = s;
        while (cend < e && text[cend] != '#') cend++;
        while (cend > s && (text[cend - 1] == ' ' || text[cend - 1] == '\t' || text[cend - 1] == '\r')) cend--;
        cont = (cend > s && text[cend - 1] == '\\');
        if (cont) cend--;
        if (blen == 0) stmt_line = lineno;
        if (blen + (cend - s) + 1 > (size_t) RS_CASE_MAX_LINE) {
            r = rs_error_set_at(err, RS_ERR_LIMIT, path, stmt_line, 1,
                                "statement too long (limit %d bytes)", RS_CASE_MAX_LINE);
            break;
        }
        for (k = s; k < cend; k++) {
            buf[blen] = text[k];
            lmap[blen] = lineno;
            cmap[blen] = (int) (k - ls) + 1;
            blen++;
        }
        if (cont) {
            buf[blen] = ' ';
            lmap[blen] = lineno;
            cmap[blen] = (int) (cend - ls) + 1;
            blen++;
            if (i < len)
                continue;
            r = rs_error_set_at(err, RS_ERR_INPUT, path, lineno, (int) (cend - ls) + 1,
                                "expected a line after the continuation '\\', found end of file");
            break;
        }
        buf[blen] = '\0';
        lmap[blen] = lineno;
        cmap[blen] = (int) (cend - ls) + 1;
        {
            rs_stmt_t x;
            x.p = p;
            x.c = p->c;
            x.err = err;
            x.src.file = file;
            x.src.text = buf;
            x.src.line = stmt_line;
            x.src.col = 1;
            x.src.linemap = lmap;
            x.src.colmap = cmap;
            r = statement(&x);
        }
        blen = 0;
    }
    flint_free(buf);
    flint_free(lmap);
    flint_free(cmap);
    return r;
}

/* the top level: the case file's text (syntax only; rs_model_lower gives it meaning) */
static int parse_top(rs_case_t c, const char *path, const char *text, size_t len, const struct stat *st,
                     rs_error_t err)
{
    rs_parser_t p;
    int r;
    memset(&p, 0, sizeof p);
    p.c = c;
    p.err = err;
    if (st != NULL) include_add(&p, st);   /* a fragment including the case file is a cycle */
    flint_free(c->path);
    c->path = rs_strdup(path);
    r = parse_text(&p, path, text, len);
    flint_free(p.includes);
    return r;
}

int rs_case_parse_string(rs_case_t c, const char *path, const char *text, size_t len, rs_error_t err)
{
    /* text named after a file (the API's source name): that file including
     * itself is a cycle, as when the file is read */
    struct stat st;
    int named = path != NULL && stat(path, &st) == 0 && S_ISREG(st.st_mode);
    return parse_top(c, path, text, len, named ? &st : NULL, err);
}

/* Reads path ("-": stdin) whole into a NUL-terminated buffer; *st
 * describes it.  regular_only (include): FIFOs, devices and folders are
 * refused, opened without blocking so that a FIFO cannot hang the parse. */
static int read_whole(char **out, size_t *outlen, const char *path, int regular_only, struct stat *st,
                      rs_error_t err)
{
    FILE *f;
    char *text = NULL;
    size_t len = 0, cap = 0;
    int is_stdin = (strcmp(path, "-") == 0) && !regular_only;
    int fd = is_stdin ? 0 : open(path, O_RDONLY | (regular_only ? O_NONBLOCK : 0));
    *out = NULL;
    if (fd < 0)
        return rs_error_set_at(err, RS_ERR_IO, path, 0, 0, "cannot open: %s", strerror(errno));
    if (fstat(fd, st) != 0 || (regular_only && !S_ISREG(st->st_mode))) {
        const char *kind = S_ISDIR(st->st_mode) ? "a folder" : S_ISFIFO(st->st_mode) ? "a FIFO"
                         : S_ISCHR(st->st_mode) || S_ISBLK(st->st_mode) ? "a device" : "not a regular file";
        close(fd);
        return rs_error_set_at(err, RS_ERR_INPUT, path, 0, 0, "expected a regular file, found %s", kind);
    }
    f = is_stdin ? stdin : fdopen(fd, "rb");
    if (f == NULL) {
        close(fd);
        return rs_error_set_at(err, RS_ERR_IO, path, 0, 0, "cannot open: %s", strerror(errno));
    }
    for (;;) {
        size_t got;
        if (len + 65536 + 1 > cap) {
            cap = cap ? 2 * cap : 131072;
            text = flint_realloc(text, cap);
        }
        got = fread(text + len, 1, cap - len - 1, f);
        len += got;
        if (len > (size_t) RS_CASE_MAX_BYTES) {
            if (!is_stdin) fclose(f);
            flint_free(text);
            return rs_error_set_at(err, RS_ERR_LIMIT, path, 0, 0,
                                   "file too large (over the limit of %ld bytes)", RS_CASE_MAX_BYTES);
        }
        if (got == 0) break;
    }
    if (ferror(f)) {
        if (!is_stdin) fclose(f);
        flint_free(text);
        return rs_error_set_at(err, RS_ERR_IO, path, 0, 0, "read error");
    }
    if (!is_stdin) fclose(f);
    text[len] = '\0';
    *out = text;
    *outlen = len;
    return RS_OK;
}

int rs_case_parse_file(rs_case_t c, const char *path, rs_error_t err)
{
    char *text;
    size_t len;
    struct stat st;
    int r = read_whole(&text, &len, path, 0, &st, err);
    if (r != RS_OK) return r;
    r = parse_top(c, path, text, len, &st, err);
    flint_free(text);
    return r;
}

