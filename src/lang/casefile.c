/* casefile.c -- reading .case files into rs_case_t. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <unistd.h>
#include <sys/stat.h>
#include "recstab/casefile.h"
#include "lower/builder.h"
#include "lower/recurrence.h"

#define GROW(arr, n) ((arr) = flint_realloc((arr), ((n) + 1) * sizeof(*(arr))))

void rs_case_init(rs_case_t c)
{
    memset(c, 0, sizeof(rs_case_struct));
    c->extrapolate = -1;
}

static void loc_clear(rs_loc_t *l)
{
    flint_free(l->file);
    l->file = NULL;
}

void rs_cond_clear(rs_cond_t *cond)
{
    slong i;
    for (i = 0; i < 3; i++)
        rs_expr_free(cond->e[i]);
    flint_free(cond->text);
    loc_clear(&cond->loc);
    memset(cond, 0, sizeof(rs_cond_t));
}

void rs_case_clear_requests(rs_case_t c)
{
    slong i;
    for (i = 0; i < c->nrequests; i++) {
        flint_free(c->requests[i].text);
        loc_clear(&c->requests[i].loc);
    }
    flint_free(c->requests);
    c->requests = NULL;
    c->nrequests = 0;
}

void rs_case_clear(rs_case_t c)
{
    slong i;
    flint_free(c->path);
    flint_free(c->title);
    for (i = 0; i < c->nparams; i++) { flint_free(c->params[i].name); loc_clear(&c->params[i].loc); }
    flint_free(c->params);
    for (i = 0; i < c->nunknowns; i++) { flint_free(c->unknowns[i].name); loc_clear(&c->unknowns[i].loc); }
    flint_free(c->unknowns);
    for (i = 0; i < c->nassume; i++) rs_cond_clear(&c->assume[i]);
    flint_free(c->assume);
    for (i = 0; i < c->nlets; i++) {
        flint_free(c->lets[i].name); rs_expr_free(c->lets[i].e); loc_clear(&c->lets[i].loc);
        flint_free(c->lets[i].text);
    }
    flint_free(c->lets);
    for (i = 0; i < c->neqs; i++) {
        rs_expr_free(c->eqs[i].lhs); rs_expr_free(c->eqs[i].rhs); loc_clear(&c->eqs[i].loc);
        flint_free(c->eqs[i].text);
    }
    flint_free(c->eqs);
    rs_expr_free(c->charexpr);
    loc_clear(&c->charloc);
    for (i = 0; i < c->nsets; i++) {
        flint_free(c->sets[i].name); fmpq_clear(c->sets[i].value); loc_clear(&c->sets[i].loc);
    }
    flint_free(c->sets);
    rs_case_clear_requests(c);
    loc_clear(&c->unknown_loc);
    for (i = 0; i < c->nsubs; i++) {
        rs_subsystem_t *b = &c->subs[i];
        slong k;
        flint_free(b->name);
        for (k = 0; k < b->nstates; k++) flint_free(b->states[k]);
        flint_free(b->states);
        for (k = 0; k < b->ndeqs; k++) {
            flint_free(b->deqs[k].state); flint_free(b->deqs[k].rhs); loc_clear(&b->deqs[k].loc);
        }
        flint_free(b->deqs);
        loc_clear(&b->loc);
        flint_free(b->method); flint_free(b->arg1); flint_free(b->arg2); flint_free(b->step);
        loc_clear(&b->intloc);
    }
    flint_free(c->subs);
    flint_free(c->couple); flint_free(c->couple_first); flint_free(c->couple_second);
    loc_clear(&c->couple_loc);
    flint_free(c->force_name); flint_free(c->force_expr);
    loc_clear(&c->force_loc);
    for (i = 0; i < c->nmore_forces; i++) {
        flint_free(c->more_forces[i].name); flint_free(c->more_forces[i].expr);
        loc_clear(&c->more_forces[i].loc);
    }
    flint_free(c->more_forces);
    flint_free(c->emitted);
    flint_free(c->includes);
    for (i = 0; i < c->nrec; i++) {
        slong k;
        for (k = 0; k < c->rec[i].rows * c->rec[i].cols; k++) {
            rs_expr_free(c->rec[i].entries[k]);
            flint_free(c->rec[i].texts[k]);
        }
        flint_free(c->rec[i].entries);
        flint_free(c->rec[i].texts);
        loc_clear(&c->rec[i].loc);
    }
    flint_free(c->rec);
    memset(c, 0, sizeof(rs_case_struct));
}

slong rs_case_param_index(const rs_case_t c, const char *name)
{
    slong i;
    for (i = 0; i < c->nparams; i++)
        if (strcmp(c->params[i].name, name) == 0) return i;
    return -1;
}

slong rs_case_unknown_index(const rs_case_t c, const char *name)
{
    slong i;
    for (i = 0; i < c->nunknowns; i++)
        if (strcmp(c->unknowns[i].name, name) == 0) return i;
    return -1;
}

slong rs_case_let_index(const rs_case_t c, const char *name)
{
    slong i;
    for (i = 0; i < c->nlets; i++)
        if (strcmp(c->lets[i].name, name) == 0) return i;
    return -1;
}

int rs_name_is_reserved(const char *name)
{
    return strcmp(name, "lambda") == 0 || strcmp(name, "z") == 0 || strcmp(name, "n") == 0;
}

void rs_case_add_request(rs_case_t c, const char *text, const char *file, int line, int col)
{
    GROW(c->requests, c->nrequests);
    c->requests[c->nrequests].text = rs_strdup(text);
    c->requests[c->nrequests].loc.file = rs_strdup(file);
    c->requests[c->nrequests].loc.line = line;
    c->requests[c->nrequests].loc.col = col;
    c->nrequests++;
}

/* ---------- statement parsing ------------------------------------------ */

typedef struct {
    rs_case_struct *c;
    rs_src_t src;          /* current logical statement */
    rs_error_struct *err;
} ctx_t;

static void skip_ws(const char *t, size_t *i)
{
    while (t[*i] == ' ' || t[*i] == '\t' || t[*i] == '\r')
        (*i)++;
}

static int at_err(ctx_t *x, size_t i, int code, const char *fmt, const char *found)
{
    int line, col;
    rs_src_pos(&x->src, i, &line, &col);
    return rs_error_set_at(x->err, code, x->src.file, line, col, fmt, found);
}

static void describe(char *buf, size_t len, const char *t, size_t i)
{
    unsigned char ch = (unsigned char) t[i];
    if (ch == '\0')
        snprintf(buf, len, "end of line");
    else if (isalnum(ch) || ch == '_') {
        size_t j = i;
        while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
        snprintf(buf, len, "'%.*s'", (int) (j - i > 40 ? 40 : j - i), t + i);
    } else if (ch < 32 || ch >= 127)
        snprintf(buf, len, "byte 0x%02x", ch);
    else
        snprintf(buf, len, "'%c'", ch);
}

static int expect_err(ctx_t *x, size_t i, const char *expected)
{
    char found[64], msg[256];
    describe(found, sizeof found, x->src.text, i);
    snprintf(msg, sizeof msg, "expected %s, found %%s", expected);
    return at_err(x, i, RS_ERR_INPUT, msg, found);
}

static void set_loc(ctx_t *x, rs_loc_t *l, size_t i)
{
    l->file = rs_strdup(x->src.file);
    rs_src_pos(&x->src, i, &l->line, &l->col);
}

/* Reads an identifier at *i into a new string, or returns NULL. */
static char *read_ident(const char *t, size_t *i)
{
    size_t j = *i;
    if (!(isalpha((unsigned char) t[j]) || t[j] == '_'))
        return NULL;
    while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
    if (j - *i > 64)
        return NULL;
    {
        char *s = rs_strndup(t + *i, j - *i);
        *i = j;
        return s;
    }
}

/* A name was expected at i: says so, or that the name there is too long. */
static int name_err(ctx_t *x, size_t i, const char *expected)
{
    const char *t = x->src.text;
    if (isalpha((unsigned char) t[i]) || t[i] == '_') {
        size_t j = i;
        int line, col;
        while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
        rs_src_pos(&x->src, i, &line, &col);
        return rs_error_set_at(x->err, RS_ERR_LIMIT, x->src.file, line, col,
                               "name too long: %zu characters (limit 64)", j - i);
    }
    return expect_err(x, i, expected);
}

static int name_taken(const rs_case_struct *c, const char *name)
{
    return rs_case_param_index(c, name) >= 0 || rs_case_unknown_index(c, name) >= 0
        || rs_case_let_index(c, name) >= 0;
}

static int check_new_name(ctx_t *x, size_t at, const char *name)
{
    if (rs_name_is_reserved(name))
        return at_err(x, at, RS_ERR_INPUT,
                      "'%s' is reserved (lambda, z and n have fixed meanings); choose another name", name);
    if (name_taken(x->c, name))
        return at_err(x, at, RS_ERR_INPUT, "'%s' is already declared", name);
    if (x->c->nparams + x->c->nunknowns + x->c->nlets >= RS_CASE_MAX_NAMES)
        return at_err(x, at, RS_ERR_LIMIT, "too many names (limit %s)", "256");
    return RS_OK;
}

/* param / unknown: NAME [,] NAME ... */
static int st_names(ctx_t *x, size_t i, int unknowns)
{
    const char *t = x->src.text;
    int count = 0;
    for (;;) {
        char *name;
        size_t at;
        skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == '\0') break;
        at = i;
        name = read_ident(t, &i);
        if (name == NULL)
            return name_err(x, at, unknowns ? "an unknown's name" : "a parameter name");
        if (check_new_name(x, at, name) != RS_OK) { flint_free(name); return x->err->code; }
        if (unknowns) {
            GROW(x->c->unknowns, x->c->nunknowns);
            x->c->unknowns[x->c->nunknowns].name = name;
            set_loc(x, &x->c->unknowns[x->c->nunknowns].loc, at);
            x->c->nunknowns++;
            if (x->c->unknown_loc.file == NULL) set_loc(x, &x->c->unknown_loc, at);
        } else {
            GROW(x->c->params, x->c->nparams);
            x->c->params[x->c->nparams].name = name;
            set_loc(x, &x->c->params[x->c->nparams].loc, at);
            x->c->nparams++;
        }
        count++;
    }
    if (count == 0)
        return expect_err(x, i, unknowns ? "at least one unknown's name" : "at least one parameter name");
    return RS_OK;
}

static int read_cmp(const char *t, size_t *i, rs_cmp_t *op)
{
    if (t[*i] == '<' && t[*i + 1] == '=') { *op = RS_CMP_LE; *i += 2; return 1; }
    if (t[*i] == '>' && t[*i + 1] == '=') { *op = RS_CMP_GE; *i += 2; return 1; }
    if (t[*i] == '!' && t[*i + 1] == '=') { *op = RS_CMP_NE; *i += 2; return 1; }
    if (t[*i] == '<') { *op = RS_CMP_LT; *i += 1; return 1; }
    if (t[*i] == '>') { *op = RS_CMP_GT; *i += 1; return 1; }
    if (t[*i] == '=' && t[*i + 1] == '=') { *op = RS_CMP_EQ; *i += 2; return 1; }
    if (t[*i] == '=') { *op = RS_CMP_EQ; *i += 1; return 1; }
    return 0;
}

int rs_cond_parse(rs_cond_t *cond, const rs_src_t *src, size_t *pos, rs_error_t err)
{
    const char *t = src->text;
    size_t i = *pos, start;
    int r;
    memset(cond, 0, sizeof(rs_cond_t));
    skip_ws(t, &i);
    start = i;
    cond->loc.file = rs_strdup(src->file ? src->file : "");
    rs_src_pos(src, i, &cond->loc.line, &cond->loc.col);
    r = rs_expr_parse(&cond->e[0], src, &i, err);
    if (r != RS_OK) { rs_cond_clear(cond); return r; }
    cond->n = 1;
    while (cond->n < 3) {
        rs_cmp_t op;
        skip_ws(t, &i);
        if (!read_cmp(t, &i, &op))
            break;
        cond->op[cond->n - 1] = op;
        r = rs_expr_parse(&cond->e[cond->n], src, &i, err);
        if (r != RS_OK) { rs_cond_clear(cond); return r; }
        cond->n++;
    }
    if (cond->n < 2) {
        int line, col;
        char found[64];
        describe(found, sizeof found, t, i);
        rs_src_pos(src, i, &line, &col);
        rs_cond_clear(cond);
        return rs_error_set_at(err, RS_ERR_INPUT, src->file, line, col,
                               "expected a comparison (<, <=, >, >=, !=) in the condition, found %s", found);
    }
    {
        size_t end = i;
        while (end > start && (t[end - 1] == ' ' || t[end - 1] == '\t')) end--;
        cond->text = rs_strndup(t + start, end - start);
    }
    *pos = i;
    return RS_OK;
}

static int st_assume(ctx_t *x, size_t i)
{
    const char *t = x->src.text;
    for (;;) {
        rs_cond_t cond;
        int r = rs_cond_parse(&cond, &x->src, &i, x->err);
        if (r != RS_OK)
            return r;
        GROW(x->c->assume, x->c->nassume);
        x->c->assume[x->c->nassume++] = cond;
        skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == '\0') break;
        return expect_err(x, i, "',' or end of line after a condition");
    }
    return RS_OK;
}

static int st_let(ctx_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_expr_t *lhs = NULL, *e = NULL;
    size_t at;
    rs_let_t *l;
    int r;
    skip_ws(t, &i);
    at = i;
    r = rs_expr_parse(&lhs, &x->src, &i, x->err);
    if (r != RS_OK)
        return r;
    if (lhs->kind != RS_EXPR_NAME) {
        rs_expr_free(lhs);
        return expect_err(x, at, "a name (let NAME = EXPR or let NAME[n+K] = EXPR)");
    }
    if (check_new_name(x, at, lhs->name) != RS_OK) { rs_expr_free(lhs); return x->err->code; }
    skip_ws(t, &i);
    if (t[i] != '=') { rs_expr_free(lhs); return expect_err(x, i, "'=' after the name in let"); }
    i++;
    skip_ws(t, &i);
    {
        rs_src_t sub = x->src;
        r = rs_expr_parse(&e, &sub, &i, x->err);
    }
    if (r != RS_OK) { rs_expr_free(lhs); return r; }
    skip_ws(t, &i);
    if (t[i] != '\0') { rs_expr_free(lhs); rs_expr_free(e); return expect_err(x, i, "an operator or end of line"); }
    GROW(x->c->lets, x->c->nlets);
    l = &x->c->lets[x->c->nlets++];
    l->name = lhs->name; lhs->name = NULL;
    l->shifted = lhs->shifted;
    l->shift = lhs->shift;
    l->e = e;
    set_loc(x, &l->loc, at);
    l->text = rs_strdup(t + at);
    rs_expr_free(lhs);
    return RS_OK;
}

static int st_eq(ctx_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_expr_t *lhs = NULL, *rhs = NULL;
    size_t at;
    rs_eq_t *q;
    int r;
    skip_ws(t, &i);
    at = i;
    r = rs_expr_parse(&lhs, &x->src, &i, x->err);
    if (r != RS_OK) return r;
    skip_ws(t, &i);
    if (t[i] == '=' && t[i + 1] == '=') {
        rs_expr_free(lhs);
        return at_err(x, i, RS_ERR_INPUT, "expected a single '=' in the equation (eq EXPR = EXPR), found %s", "'=='");
    }
    if (t[i] != '=') { rs_expr_free(lhs); return expect_err(x, i, "'=' in the equation (eq EXPR = EXPR)"); }
    i++;
    r = rs_expr_parse(&rhs, &x->src, &i, x->err);
    if (r != RS_OK) { rs_expr_free(lhs); return r; }
    skip_ws(t, &i);
    if (t[i] != '\0') { rs_expr_free(lhs); rs_expr_free(rhs); return expect_err(x, i, "an operator or end of line"); }
    GROW(x->c->eqs, x->c->neqs);
    q = &x->c->eqs[x->c->neqs++];
    q->lhs = lhs; q->rhs = rhs;
    set_loc(x, &q->loc, at);
    q->text = rs_strdup(t + at);
    return RS_OK;
}

static int st_char(ctx_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_expr_t *e = NULL;
    size_t at;
    int r;
    skip_ws(t, &i);
    at = i;
    if (x->c->charexpr != NULL)
        return at_err(x, at, RS_ERR_INPUT, "a case has one char statement; this is a second one%s", "");
    r = rs_expr_parse(&e, &x->src, &i, x->err);
    if (r != RS_OK) return r;
    skip_ws(t, &i);
    if (t[i] == '=') {
        /* accept `char EXPR = 0` */
        size_t j = i + 1;
        skip_ws(t, &j);
        if (t[j] == '0') {
            size_t k = j + 1;
            skip_ws(t, &k);
            if (t[k] == '\0') i = k;
        }
    }
    if (t[i] != '\0') { rs_expr_free(e); return expect_err(x, i, "an operator or end of line"); }
    x->c->charexpr = e;
    set_loc(x, &x->c->charloc, at);
    return RS_OK;
}

static int set_one(rs_case_struct *c, const char *name, const fmpq_t v, const char *file, int line, int col)
{
    slong k;
    for (k = 0; k < c->nsets; k++)
        if (strcmp(c->sets[k].name, name) == 0) {
            fmpq_set(c->sets[k].value, v);
            return RS_OK;
        }
    GROW(c->sets, c->nsets);
    c->sets[c->nsets].name = rs_strdup(name);
    fmpq_init(c->sets[c->nsets].value);
    fmpq_set(c->sets[c->nsets].value, v);
    c->sets[c->nsets].loc.file = rs_strdup(file);
    c->sets[c->nsets].loc.line = line;
    c->sets[c->nsets].loc.col = col;
    c->nsets++;
    return RS_OK;
}

static int st_set(ctx_t *x, size_t i)
{
    const char *t = x->src.text;
    for (;;) {
        size_t at;
        char *name;
        rs_expr_t *e = NULL;
        fmpq_t v;
        int r, line, col;
        skip_ws(t, &i);
        at = i;
        name = read_ident(t, &i);
        if (name == NULL) return name_err(x, at, "a parameter name (set NAME = NUMBER)");
        if (rs_case_param_index(x->c, name) < 0) {
            at_err(x, at, RS_ERR_INPUT, "'%s' is not a parameter (declare it with `param` first)", name);
            flint_free(name);
            return x->err->code;
        }
        skip_ws(t, &i);
        if (t[i] != '=') { flint_free(name); return expect_err(x, i, "'=' after the name in set"); }
        i++;
        r = rs_expr_parse(&e, &x->src, &i, x->err);
        if (r != RS_OK) { flint_free(name); return r; }
        fmpq_init(v);
        r = rs_expr_eval_const(v, e, &x->src, x->err);
        rs_expr_free(e);
        if (r != RS_OK) { fmpq_clear(v); flint_free(name); return r; }
        rs_src_pos(&x->src, at, &line, &col);
        set_one(x->c, name, v, x->src.file, line, col);
        fmpq_clear(v);
        flint_free(name);
        skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == '\0') break;
        return expect_err(x, i, "',' or end of line in set");
    }
    return RS_OK;
}

static void add_request_at(ctx_t *x, size_t i)
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

struct rs_include_struct {
    dev_t dev;
    ino_t ino;
    int open;   /* still being read: including it again is a cycle */
};

static int read_whole(char **out, size_t *outlen, const char *path, int regular_only, struct stat *st,
                      rs_error_t err);
static int parse_text(rs_case_t c, const char *path, const char *text, size_t len, rs_error_t err);

static slong include_find(const rs_case_t c, const struct stat *st)
{
    slong k;
    for (k = 0; k < c->nincludes; k++)
        if (c->includes[k].dev == st->st_dev && c->includes[k].ino == st->st_ino) return k;
    return -1;
}

static void include_add(rs_case_t c, const struct stat *st)
{
    GROW(c->includes, c->nincludes);
    c->includes[c->nincludes].dev = st->st_dev;
    c->includes[c->nincludes].ino = st->st_ino;
    c->includes[c->nincludes].open = 1;
    c->nincludes++;
}

/* include FILE: relative to the including file's folder.  A file already
 * read in this parse (the same device and inode, whatever the path) is not
 * read again: its statements apply once, so mutual includes stay linear. */
static int st_include(ctx_t *x, size_t i)
{
    const char *t = x->src.text;
    const char *slash;
    char *path, *text = NULL;
    size_t len = 0, end;
    struct stat st;
    slong k;
    int r;
    skip_ws(t, &i);
    end = strlen(t);
    while (end > i && (t[end - 1] == ' ' || t[end - 1] == '\t')) end--;
    if (end == i) return expect_err(x, i, "a file name after include");
    if (x->c->include_depth >= 16)
        return at_err(x, i, RS_ERR_LIMIT, "includes nested too deeply (limit 16)%s", "");
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
    if (stat(path, &st) == 0 && (k = include_find(x->c, &st)) >= 0) {
        r = x->c->includes[k].open ? at_err(x, i, RS_ERR_INPUT, "include cycle: '%s' is still being read", path)
                                   : RS_OK;
        flint_free(path);
        return r;
    }
    if (x->c->nincludes > RS_CASE_MAX_INCLUDES) {
        flint_free(path);
        return at_err(x, i, RS_ERR_LIMIT, "more than " RS_STR(RS_CASE_MAX_INCLUDES) " files included%s", "");
    }
    r = read_whole(&text, &len, path, 1, &st, x->err);
    if (r == RS_OK && x->c->include_bytes + (slong) len > RS_CASE_MAX_INCLUDE_BYTES) {
        flint_free(text);
        flint_free(path);
        return at_err(x, i, RS_ERR_LIMIT, "included files over 16 MiB in all (the limit)%s", "");
    }
    if (r != RS_OK) {
        char msg[2 * RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "cannot include '%s': %s", path, x->err->msg);
        at_err(x, i, r == RS_ERR_LIMIT ? RS_ERR_LIMIT : RS_ERR_INPUT, "%s", msg);
        flint_free(path);
        return x->err->code;
    }
    x->c->include_bytes += (slong) len;
    include_add(x->c, &st);
    k = x->c->nincludes - 1;
    x->c->include_depth++;
    r = parse_text(x->c, path, text, len, x->err);
    x->c->include_depth--;
    x->c->includes[k].open = 0;
    flint_free(text);
    flint_free(path);
    return r;
}

static int statement(ctx_t *x)
{
    const char *t = x->src.text;
    size_t i = 0, kw;
    char *word;
    int r = RS_OK;
    skip_ws(t, &i);
    if (t[i] == '\0')
        return RS_OK;
    kw = i;
    word = read_ident(t, &i);
    if (word == NULL)
        return expect_err(x, kw, "a statement keyword (title, param, assume, unknown, let, eq, char, set, analyse, expect, claim)");
    if (t[i] == '\'') {
        /* a state equation NAME' = EXPR of the current subsystem */
        r = rs_builder_statement(x->c, word, &x->src, i, x->err);
        flint_free(word);
        return r;
    }
    if (t[i] != '\0' && t[i] != ' ' && t[i] != '\t') {
        flint_free(word);
        return expect_err(x, i, "a space after the statement keyword");
    }
    if (strcmp(word, "title") == 0) {
        size_t end = strlen(t);
        skip_ws(t, &i);
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
    } else if (strcmp(word, "analyse") == 0 || strcmp(word, "analyze") == 0) {
        skip_ws(t, &i);
        if (t[i] == '\0')
            r = expect_err(x, i, "an analysis name after analyse (charpoly, bilinear, routh, ...)");
        else
            add_request_at(x, i);
    } else if (strcmp(word, "expect") == 0 || strcmp(word, "claim") == 0) {
        add_request_at(x, kw);
    } else if (rs_builder_is_keyword(word)) {
        r = rs_builder_statement(x->c, word, &x->src, i, x->err);
    } else if (strcmp(word, "include") == 0) {
        r = st_include(x, i);
    } else if (strcmp(word, "recurrence") == 0) {
        r = rs_recurrence_statement(x->c, &x->src, i, x->err);
    } else {
        r = expect_err(x, kw, "a statement keyword (title, param, assume, unknown, let, eq, char, set, analyse, expect, claim)");
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

static int parse_text(rs_case_t c, const char *path, const char *text, size_t len, rs_error_t err)
{
    size_t i = 0;
    int lineno = 0, r = RS_OK;
    char *buf;
    int *lmap, *cmap;
    size_t blen = 0;
    int stmt_line = 0;

    if (len > (size_t) RS_CASE_MAX_BYTES)
        return rs_error_set_at(err, RS_ERR_LIMIT, path, 0, 0,
                               "file too large (%zu bytes; limit %ld bytes)", len, RS_CASE_MAX_BYTES);
    r = check_bytes(path, text, len, err);
    if (r != RS_OK)
        return r;

    buf = flint_malloc(RS_CASE_MAX_LINE + 2);
    lmap = flint_malloc((RS_CASE_MAX_LINE + 2) * sizeof(int));
    cmap = flint_malloc((RS_CASE_MAX_LINE + 2) * sizeof(int));

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
            ctx_t x;
            x.c = c;
            x.err = err;
            x.src.file = path;
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

/* the top level: the case file's text, then the builders' expansion */
static int parse_top(rs_case_t c, const char *path, const char *text, size_t len, rs_error_t err)
{
    int r;
    flint_free(c->path);
    c->path = rs_strdup(path);
    r = parse_text(c, path, text, len, err);
    if (r == RS_OK && c->include_depth == 0)
        r = rs_builder_expand(c, err);
    if (r == RS_OK && c->include_depth == 0)
        r = rs_recurrence_expand(c, err);
    return r;
}

int rs_case_parse_string(rs_case_t c, const char *path, const char *text, size_t len, rs_error_t err)
{
    c->nincludes = 0;
    c->include_bytes = 0;
    return parse_top(c, path, text, len, err);
}

int rs_case_parse_append(rs_case_t c, const char *label, const char *text, rs_error_t err)
{
    return parse_text(c, label, text, strlen(text), err);
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
    c->nincludes = 0;
    c->include_bytes = 0;
    include_add(c, &st);   /* a fragment including the case file is a cycle */
    r = parse_top(c, path, text, len, err);
    flint_free(text);
    return r;
}

int rs_case_set_value(rs_case_t c, const char *assignment, rs_error_t err)
{
    const char *eq = strchr(assignment, '=');
    char *name;
    size_t n;
    fmpq_t v;
    int r;
    if (eq == NULL)
        return rs_error_set(err, RS_ERR_INPUT, "--set %s: expected NAME=VALUE", assignment);
    n = (size_t) (eq - assignment);
    while (n > 0 && assignment[n - 1] == ' ') n--;
    name = rs_strndup(assignment, n);
    if (rs_case_param_index(c, name) < 0) {
        r = rs_error_set(err, RS_ERR_INPUT, "--set %s: '%s' is not a parameter of %s", assignment, name, c->path);
        flint_free(name);
        return r;
    }
    fmpq_init(v);
    r = rs_expr_parse_number(v, eq + 1, err);
    if (r != RS_OK) {
        char msg[RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "%s", err->msg);
        rs_error_set(err, RS_ERR_INPUT, "--set %s: %s", assignment, msg);
    } else {
        set_one(c, name, v, "--set", 0, 0);
    }
    fmpq_clear(v);
    flint_free(name);
    return r;
}
