/* builder.c -- subsystems, integrators and couplings expanded into
 * difference equations (see builder.h). */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "lower/builder.h"

static void skip_ws(const char *t, size_t *i)
{
    while (t[*i] == ' ' || t[*i] == '\t') (*i)++;
}

/* a word: letters, digits, '_', '-', '.', '/' (method names, numbers) */
static char *read_token(const char *t, size_t *i)
{
    size_t j;
    skip_ws(t, i);
    j = *i;
    while (t[j] && t[j] != ' ' && t[j] != '\t' && t[j] != ',') j++;
    if (j == *i) return NULL;
    {
        char *s = rs_strndup(t + *i, j - *i);
        *i = j;
        return s;
    }
}

static int at(rs_error_t err, const rs_src_t *src, size_t i, const char *fmt, const char *a)
{
    int line, col;
    rs_src_pos(src, i, &line, &col);
    return rs_error_set_at(err, RS_ERR_INPUT, src->file, line, col, fmt, a);
}

static void set_loc(rs_loc_t *l, const rs_src_t *src, size_t i)
{
    l->file = rs_strdup(src->file);
    rs_src_pos(src, i, &l->line, &l->col);
}

int rs_builder_is_keyword(const char *w)
{
    return strcmp(w, "subsystem") == 0 || strcmp(w, "integrate") == 0 || strcmp(w, "couple") == 0
        || strcmp(w, "iterations") == 0 || strcmp(w, "extrapolate") == 0 || strcmp(w, "coupling") == 0;
}

static slong sub_index(const rs_case_struct *c, const char *name)
{
    slong i;
    for (i = 0; i < c->nsubs; i++)
        if (strcmp(c->subs[i].name, name) == 0) return i;
    return -1;
}

static int valid_ident(const char *s)
{
    if (!(isalpha((unsigned char) *s) || *s == '_')) return 0;
    for (; *s; s++)
        if (!(isalnum((unsigned char) *s) || *s == '_')) return 0;
    return 1;
}

static const char *const methods[] = {"euler-forward", "euler-backward", "trapezoidal", "theta", "bdf2", "bdf3",
                                      "central-difference", "newmark", "exact", NULL};

int rs_builder_statement(rs_case_t c, const char *kw, const rs_src_t *src, size_t i, rs_error_t err)
{
    const char *t = src->text;
    if (t[i] == '\'') {
        /* NAME' = EXPR or NAME'' = EXPR inside the last subsystem block */
        rs_subsystem_t *s;
        rs_deq_t *d;
        int order = 1;
        size_t start;
        rs_expr_t *e = NULL;
        int r;
        if (c->nsubs == 0)
            return at(err, src, 0, "expected a `subsystem` statement before the state equation %s'", kw);
        s = &c->subs[c->nsubs - 1];
        i++;
        if (t[i] == '\'') { order = 2; i++; }
        skip_ws(t, &i);
        if (t[i] != '=') return at(err, src, i, "expected '=' after %s' in a state equation", kw);
        i++;
        skip_ws(t, &i);
        start = i;
        r = rs_expr_parse_all(&e, &(rs_src_t){src->file, t + start, 0, 0, src->linemap ? src->linemap + start : NULL,
                                             src->colmap ? src->colmap + start : NULL}, err);
        if (r != RS_OK) return r;
        rs_expr_free(e);
        s->deqs = flint_realloc(s->deqs, (s->ndeqs + 1) * sizeof(rs_deq_t));
        d = &s->deqs[s->ndeqs++];
        memset(d, 0, sizeof *d);
        d->state = rs_strdup(kw);
        d->order = order;
        d->rhs = rs_strdup(t + start);
        set_loc(&d->loc, src, 0);
        return RS_OK;
    }
    if (strcmp(kw, "subsystem") == 0) {
        char *name = read_token(t, &i), *w;
        rs_subsystem_t *s;
        if (name == NULL || !valid_ident(name)) {
            flint_free(name);
            return at(err, src, i, "expected a subsystem name, found '%s'", t + i);
        }
        if (sub_index(c, name) >= 0) {
            at(err, src, i, "subsystem '%s' is already declared", name);
            flint_free(name);
            return err->code;
        }
        w = read_token(t, &i);
        if (w == NULL || strcmp(w, "state") != 0) {
            flint_free(name); flint_free(w);
            return at(err, src, i, "expected 'state NAME ...' after the subsystem name, found '%s'", t + i);
        }
        flint_free(w);
        c->subs = flint_realloc(c->subs, (c->nsubs + 1) * sizeof(rs_subsystem_t));
        s = &c->subs[c->nsubs++];
        memset(s, 0, sizeof *s);
        s->name = name;
        set_loc(&s->loc, src, 0);
        for (;;) {
            size_t p0;
            skip_ws(t, &i);
            if (t[i] == ',') { i++; continue; }
            if (t[i] == '\0') break;
            p0 = i;
            w = read_token(t, &i);
            if (w == NULL || !valid_ident(w)) {
                flint_free(w);
                return at(err, src, p0, "expected a state name, found '%s'", t + p0);
            }
            s->states = flint_realloc(s->states, (s->nstates + 1) * sizeof(char *));
            s->states[s->nstates++] = w;
        }
        if (s->nstates == 0) return at(err, src, i, "expected at least one state name%s", "");
        return RS_OK;
    }
    if (strcmp(kw, "integrate") == 0) {
        size_t p0;
        char *name = read_token(t, &i), *m;
        slong k, idx;
        int known = 0;
        rs_subsystem_t *s;
        if (name == NULL || (idx = sub_index(c, name)) < 0) {
            at(err, src, i, "expected the name of a declared subsystem after integrate, found '%s'", name ? name : "");
            flint_free(name);
            return err->code;
        }
        flint_free(name);
        s = &c->subs[idx];
        if (s->method != NULL) return at(err, src, 0, "subsystem '%s' already has an integrator", s->name);
        p0 = i;
        m = read_token(t, &i);
        for (k = 0; m && methods[k]; k++) if (strcmp(m, methods[k]) == 0) known = 1;
        if (!known) {
            flint_free(m);
            skip_ws(t, &p0);
            return at(err, src, p0, "expected an integrator (euler-forward, euler-backward, trapezoidal, theta T, "
                      "bdf2, bdf3, central-difference, newmark B G, exact), found '%s'", t + p0);
        }
        s->method = m;
        set_loc(&s->intloc, src, p0);
        if (strcmp(m, "theta") == 0 || strcmp(m, "newmark") == 0) s->arg1 = read_token(t, &i);
        if (strcmp(m, "newmark") == 0) s->arg2 = read_token(t, &i);
        skip_ws(t, &i);
        if ((strcmp(m, "theta") == 0 && s->arg1 == NULL) || (strcmp(m, "newmark") == 0 && s->arg2 == NULL))
            return at(err, src, i, "expected the method's parameters, then the step, found '%s'", t + i);
        if (t[i] == '\0') return at(err, src, i, "expected the step (an expression such as h) after the method%s", "");
        s->step = rs_strdup(t + i);
        {
            /* the step must be an expression */
            rs_expr_t *e = NULL;
            rs_src_t sub = {src->file, t + i, 0, 0, src->linemap ? src->linemap + i : NULL,
                            src->colmap ? src->colmap + i : NULL};
            int r = rs_expr_parse_all(&e, &sub, err);
            rs_expr_free(e);
            if (r != RS_OK) return r;
        }
        return RS_OK;
    }
    if (strcmp(kw, "couple") == 0) {
        size_t p0;
        char *w;
        if (c->couple != NULL) return at(err, src, 0, "a case has one couple statement%s", "");
        skip_ws(t, &i);
        p0 = i;
        w = read_token(t, &i);
        set_loc(&c->couple_loc, src, p0);
        if (w && (strcmp(w, "jacobi") == 0 || strcmp(w, "monolithic") == 0)) {
            c->couple = w;
        } else if (w && strcmp(w, "gauss-seidel") == 0) {
            c->couple = w;
            c->couple_first = read_token(t, &i);
            c->couple_second = read_token(t, &i);
            if (c->couple_second == NULL)
                return at(err, src, i, "expected two subsystem names after gauss-seidel (the first is "
                          "integrated first), found '%s'", t + i);
        } else if (w && (strcmp(w, "explicit") == 0 || strcmp(w, "implicit") == 0)) {
            char *o = read_token(t, &i), *k;
            c->couple = w;
            k = read_token(t, &i);
            if (o == NULL || strcmp(o, "order") != 0 || k == NULL || strlen(k) > 2 || !isdigit((unsigned char) k[0])) {
                flint_free(o); flint_free(k);
                return at(err, src, i, "expected 'order K' (K = 0, 1, 2) after explicit/implicit%s", "");
            }
            c->couple_order = atol(k);
            flint_free(o); flint_free(k);
        } else {
            flint_free(w);
            return at(err, src, p0, "expected jacobi, gauss-seidel S1 S2, monolithic, explicit order K or "
                      "implicit order K, found '%s'", t + p0);
        }
        skip_ws(t, &i);
        if (t[i] != '\0') return at(err, src, i, "expected end of line, found '%s'", t + i);
        return RS_OK;
    }
    if (strcmp(kw, "iterations") == 0 || strcmp(kw, "extrapolate") == 0) {
        char *w;
        size_t p0;
        long k;
        if (strcmp(kw, "extrapolate") == 0) {
            w = read_token(t, &i);
            if (w == NULL || strcmp(w, "order") != 0) {
                flint_free(w);
                return at(err, src, i, "expected 'order K' after extrapolate%s", "");
            }
            flint_free(w);
        }
        skip_ws(t, &i);
        p0 = i;
        w = read_token(t, &i);
        if (w == NULL || strspn(w, "0123456789") != strlen(w) || strlen(w) > 3) {
            flint_free(w);
            return at(err, src, p0, "expected a small non-negative integer, found '%s'", t + p0);
        }
        k = atol(w);
        flint_free(w);
        if (strcmp(kw, "iterations") == 0) {
            if (k > RS_BUILDER_MAX_ITERATIONS) return at(err, src, p0, "too many iterations (limit 16)%s", "");
            c->iterations = k;
        } else {
            if (k > RS_BUILDER_MAX_ORDER) return at(err, src, p0, "extrapolation order too high (limit 6)%s", "");
            c->extrapolate = k;
        }
        return RS_OK;
    }
    if (strcmp(kw, "coupling") == 0) {
        char *w = read_token(t, &i), *name;
        size_t p0;
        if (w == NULL || strcmp(w, "force") != 0) {
            flint_free(w);
            return at(err, src, i, "expected 'coupling force NAME = EXPR'%s", "");
        }
        flint_free(w);
        skip_ws(t, &i);
        p0 = i;
        while (isalnum((unsigned char) t[i]) || t[i] == '_') i++;
        if (i == p0) return at(err, src, p0, "expected the force's name, found '%s'", t + p0);
        name = rs_strndup(t + p0, i - p0);
        {
            /* several coupling forces (vector coupling, src/analysis/analysis_cosim.c): the first in
             * force_name/force_expr/force_loc, the others in more_forces */
            slong k;
            int dup = c->force_name != NULL && strcmp(c->force_name, name) == 0;
            for (k = 0; k < c->nmore_forces; k++)
                if (strcmp(c->more_forces[k].name, name) == 0) dup = 1;
            if (dup) {
                int r = at(err, src, p0, "the coupling force '%s' is already defined", name);
                flint_free(name);
                return r;
            }
        }
        skip_ws(t, &i);
        if (t[i] != '=') { flint_free(name); return at(err, src, i, "expected '=' after the force's name%s", ""); }
        i++;
        skip_ws(t, &i);
        if (c->force_name == NULL) {
            c->force_name = name;
            c->force_expr = rs_strdup(t + i);
            set_loc(&c->force_loc, src, p0);
        } else {
            rs_force_t *f;
            c->more_forces = flint_realloc(c->more_forces, (c->nmore_forces + 1) * sizeof(rs_force_t));
            f = &c->more_forces[c->nmore_forces++];
            f->name = name;
            f->expr = rs_strdup(t + i);
            set_loc(&f->loc, src, p0);
        }
        return RS_OK;
    }
    return at(err, src, 0, "unknown builder statement '%s'", kw);
}

/* ---- expansion ---------------------------------------------------------------- */

typedef struct { char *s; size_t len, cap; } sb_t;

static void sb_add(sb_t *b, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void sb_add(sb_t *b, const char *fmt, ...)
{
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (b->len + (size_t) n + 1 > b->cap) {
        b->cap = 2 * (b->len + (size_t) n + 1);
        b->s = flint_realloc(b->s, b->cap);
    }
    va_start(ap, fmt);
    vsnprintf(b->s + b->len, (size_t) n + 1, fmt, ap);
    va_end(ap);
    b->len += (size_t) n;
}

typedef struct {
    const rs_case_struct *c;
    slong K;               /* iterations */
    int kind;              /* 0 monolithic, 1 jacobi, 2 gauss-seidel */
    slong first, second;   /* gauss-seidel order */
    slong *vel;            /* per subsystem, per state: index of its velocity (pair) or -1 */
    int *pair;             /* per subsystem: integrator works on (x, v) pairs */
} gen_t;

static int is_pos(const gen_t *g, slong a, slong k) { return g->pair[a] && g->vel[a * 64 + k] >= 0; }

static void var(sb_t *b, const char *s, slong j, slong K)
{
    if (j == K) sb_add(b, "%s", s);
    else sb_add(b, "%s_it%ld", s, (long) j);
}

static void dvar(sb_t *b, const char *s, slong j, slong K)
{
    if (j == K) sb_add(b, "%s_dot", s);
    else sb_add(b, "%s_dot_it%ld", s, (long) j);
}

static int find_state(const rs_case_struct *c, const char *name, slong *a, slong *k)
{
    slong i, j;
    for (i = 0; i < c->nsubs; i++)
        for (j = 0; j < c->subs[i].nstates; j++)
            if (strcmp(c->subs[i].states[j], name) == 0) { *a = i; *k = j; return 1; }
    return 0;
}

/* binomial coefficients of the extrapolating polynomial through
 * n, n-1, ..., n-K evaluated at n+1: (-1)^i C(K+1, i+1) */
static slong extrap_coeff(slong K, slong i)
{
    slong r = 1, m;
    for (m = 1; m <= i + 1; m++) r = r * (K + 2 - m) / m;
    return (i % 2) ? -r : r;
}

/* partner state p as seen by subsystem a in iterate j */
static void partner(sb_t *b, const gen_t *g, const char *p, slong a, slong j)
{
    int delayed;
    const rs_case_struct *c = g->c;
    if (g->kind == 0) { var(b, p, j, g->K); sb_add(b, "[n+1]"); return; }
    delayed = (g->kind == 1) || (g->kind == 2 && a == g->first);
    if (j == 0 && delayed) {
        slong K = c->extrapolate < 0 ? 0 : c->extrapolate, i;
        if (K == 0) { sb_add(b, "%s[n]", p); return; }
        sb_add(b, "(");
        for (i = 0; i <= K; i++) {
            slong cf = extrap_coeff(K, i);
            sb_add(b, "%s%ld*%s[n-%ld]", i == 0 ? "" : (cf < 0 ? " - " : " + "), (long) (cf < 0 && i > 0 ? -cf : cf),
                   p, (long) i);
        }
        sb_add(b, ")");
        return;
    }
    if (j == 0) { var(b, p, 0, g->K); sb_add(b, "[n+1]"); return; }
    var(b, p, delayed ? j - 1 : j, g->K);
    sb_add(b, "[n+1]");
}

/* rhs of subsystem a, iterate j, with every name resolved to a sequence */
static int subst(sb_t *b, const gen_t *g, slong a, slong j, const rs_deq_t *d, rs_error_t err)
{
    const rs_case_struct *c = g->c;
    const char *t = d->rhs;
    size_t i = 0;
    while (t[i]) {
        if (isalpha((unsigned char) t[i]) || t[i] == '_') {
            size_t k = i;
            char name[80];
            slong sa, sk, li;
            while (isalnum((unsigned char) t[k]) || t[k] == '_') k++;
            snprintf(name, sizeof name, "%.*s", (int) (k - i > 70 ? 70 : k - i), t + i);
            {
                size_t q = k;
                while (t[q] == ' ') q++;
                if (t[q] == '[')
                    return rs_error_set_at(err, RS_ERR_INPUT, d->loc.file, d->loc.line, d->loc.col,
                                           "state equations are written without shifts; found '%s['", name);
            }
            if (find_state(c, name, &sa, &sk)) {
                if (sa == a) { var(b, name, j, g->K); sb_add(b, "[n+1]"); }
                else partner(b, g, name, a, j);
            } else if ((li = rs_case_let_index(c, name)) >= 0) {
                if (c->lets[li].shifted) sb_add(b, "%s[n+1]", name);
                else sb_add(b, "%s", name);
            } else if (rs_case_param_index(c, name) >= 0) {
                sb_add(b, "%s", name);
            } else {
                return rs_error_set_at(err, RS_ERR_INPUT, d->loc.file, d->loc.line, d->loc.col,
                                       "unknown name '%s' in the state equation (expected a state, param or let)",
                                       name);
            }
            i = k;
        } else if (isdigit((unsigned char) t[i]) || t[i] == '.') {
            /* numbers (including exponents like 1e-3) pass through */
            size_t k = i;
            while (isalnum((unsigned char) t[k]) || t[k] == '.'
                   || ((t[k] == '-' || t[k] == '+') && k > i && (t[k - 1] == 'e' || t[k - 1] == 'E'))) k++;
            sb_add(b, "%.*s", (int) (k - i), t + i);
            i = k;
        } else {
            sb_add(b, "%c", t[i]);
            i++;
        }
    }
    return RS_OK;
}

int rs_builder_is_exact(const rs_case_t c)
{
    slong i;
    for (i = 0; i < c->nsubs; i++)
        if (c->subs[i].method && strcmp(c->subs[i].method, "exact") == 0) return 1;
    return 0;
}

int rs_builder_expand(rs_case_t c, rs_error_t err)
{
    gen_t g;
    sb_t b = {NULL, 0, 0}, unk = {NULL, 0, 0};
    slong a, k, j;
    int r = RS_OK;
    if (c->nsubs == 0) return RS_OK;
    memset(&g, 0, sizeof g);
    g.c = c;
    for (a = 0; a < c->nsubs; a++) {
        if (c->subs[a].method == NULL)
            return rs_error_set_at(err, RS_ERR_INPUT, c->subs[a].loc.file, c->subs[a].loc.line, c->subs[a].loc.col,
                                   "expected `integrate %s METHOD STEP` for this subsystem", c->subs[a].name);
        if (c->subs[a].nstates > 64)
            return rs_error_set_at(err, RS_ERR_LIMIT, c->subs[a].loc.file, c->subs[a].loc.line, 1,
                                   "too many states in one subsystem (limit %d)", 64);
    }
    if (rs_builder_is_exact(c)) {
        for (a = 0; a < c->nsubs; a++)
            if (strcmp(c->subs[a].method, "exact") != 0)
                return rs_error_set_at(err, RS_ERR_INPUT, c->subs[a].intloc.file, c->subs[a].intloc.line,
                                       c->subs[a].intloc.col,
                                       "exact integration is supported when every subsystem uses it (found %s)",
                                       c->subs[a].method);
        /* coupling forces are optional: displacement coupling uses the partner's states */
        if (c->couple == NULL || !(strcmp(c->couple, "explicit") == 0 || strcmp(c->couple, "implicit") == 0))
            return rs_error_set_at(err, RS_ERR_INPUT, c->subs[0].loc.file, c->subs[0].loc.line, 1,
                                   "exact integration needs `couple explicit|implicit order K` (and the coupling: "
                                   "`coupling force NAME = EXPR` lines and/or the partner's states)%s", "");
        c->emitted = rs_strdup("# exact (analytic) subsystem integration: a numeric matrix recurrence, built at "
                            "set values; only numeric analyses (radius) apply\n");
        return RS_OK;
    }
    if (c->couple && (strcmp(c->couple, "explicit") == 0 || strcmp(c->couple, "implicit") == 0))
        return rs_error_set_at(err, RS_ERR_INPUT, c->couple_loc.file, c->couple_loc.line, c->couple_loc.col,
                               "applied-force coupling (couple %s order K) needs `integrate ... exact`", c->couple);
    if (c->nsubs == 1 || (c->couple && strcmp(c->couple, "monolithic") == 0)) g.kind = 0;
    else if (c->couple == NULL)
        return rs_error_set_at(err, RS_ERR_INPUT, c->subs[0].loc.file, c->subs[0].loc.line, 1,
                               "expected a `couple` statement (jacobi, gauss-seidel S1 S2, monolithic) for %ld "
                               "subsystems", (long) c->nsubs);
    else if (strcmp(c->couple, "jacobi") == 0) g.kind = 1;
    else {
        g.kind = 2;
        g.first = sub_index(c, c->couple_first);
        g.second = sub_index(c, c->couple_second);
        if (g.first < 0 || g.second < 0 || g.first == g.second || c->nsubs != 2)
            return rs_error_set_at(err, RS_ERR_INPUT, c->couple_loc.file, c->couple_loc.line, c->couple_loc.col,
                                   "gauss-seidel needs the names of the two subsystems, found '%s'",
                                   c->couple_first ? c->couple_first : "");
    }
    g.K = g.kind == 0 ? 0 : c->iterations;
    g.vel = flint_malloc(c->nsubs * 64 * sizeof(slong));
    g.pair = flint_calloc(c->nsubs, sizeof(int));
    /* derivative equation of each state; second-order lines define x' = v */
    for (a = 0; a < c->nsubs && r == RS_OK; a++) {
        rs_subsystem_t *s = &c->subs[a];
        const char *m = s->method;
        g.pair[a] = strcmp(m, "newmark") == 0 || strcmp(m, "central-difference") == 0;
        for (k = 0; k < 64; k++) g.vel[a * 64 + k] = -1;
        for (j = 0; j < s->ndeqs; j++) {
            slong si = -1;
            for (k = 0; k < s->nstates; k++) if (strcmp(s->states[k], s->deqs[j].state) == 0) si = k;
            if (si < 0) {
                r = rs_error_set_at(err, RS_ERR_INPUT, s->deqs[j].loc.file, s->deqs[j].loc.line, 1,
                                    "'%s' is not a state of subsystem %s", s->deqs[j].state, s->name);
                break;
            }
            if (s->deqs[j].order == 2) {
                if (si + 1 >= s->nstates)
                    r = rs_error_set_at(err, RS_ERR_INPUT, s->deqs[j].loc.file, s->deqs[j].loc.line, 1,
                                        "declare the velocity state right after %s (subsystem ... state X V) "
                                        "for a second-order equation", s->deqs[j].state);
                else g.vel[a * 64 + si] = si + 1;
            }
        }
        /* first-order x' = v with v a state of the subsystem also makes a pair */
        for (j = 0; j < s->ndeqs && r == RS_OK; j++) {
            slong si = -1;
            if (s->deqs[j].order != 1) continue;
            for (k = 0; k < s->nstates; k++) if (strcmp(s->states[k], s->deqs[j].state) == 0) si = k;
            for (k = 0; k < s->nstates; k++) {
                const char *rh = s->deqs[j].rhs;
                while (*rh == ' ') rh++;
                if (strcmp(rh, s->states[k]) == 0 && k != si) g.vel[a * 64 + si] = k;
            }
        }
        if (g.pair[a]) {
            if (g.K > 0)
                r = rs_error_set_at(err, RS_ERR_INPUT, s->intloc.file, s->intloc.line, s->intloc.col,
                                    "iterations with %s are not supported", m);
            for (k = 0; k < s->nstates && r == RS_OK; k++) {
                int isvel = 0;
                slong q;
                for (q = 0; q < s->nstates; q++) if (g.vel[a * 64 + q] == k) isvel = 1;
                if (g.vel[a * 64 + k] < 0 && !isvel)
                    r = rs_error_set_at(err, RS_ERR_INPUT, s->intloc.file, s->intloc.line, s->intloc.col,
                                        "%s integrates (position, velocity) pairs: write X'' = ... or X' = V for "
                                        "every position (state %s)", m, s->states[k]);
            }
        }
    }
    /* unknowns */
    for (a = 0; a < c->nsubs && r == RS_OK; a++) {
        rs_subsystem_t *s = &c->subs[a];
        for (k = 0; k < s->nstates; k++) {
            slong jj;
            int pos = is_pos(&g, a, k);
            for (jj = 0; jj <= g.K; jj++) {
                sb_add(&unk, " ");
                var(&unk, s->states[k], jj, g.K);
                if (!pos) { sb_add(&unk, " "); dvar(&unk, s->states[k], jj, g.K); }
            }
        }
    }
    if (r == RS_OK) sb_add(&b, "unknown%s\n", unk.s);
    /* equations */
    for (a = 0; a < c->nsubs && r == RS_OK; a++) {
        rs_subsystem_t *s = &c->subs[a];
        const char *m = s->method, *h = s->step;
        for (j = 0; j <= g.K && r == RS_OK; j++) {
            for (k = 0; k < s->nstates && r == RS_OK; k++) {
                const char *x = s->states[k];
                const rs_deq_t *d = NULL;
                slong q;
                int pos = is_pos(&g, a, k);
                for (q = 0; q < s->ndeqs; q++)
                    if (strcmp(s->deqs[q].state, x) == 0 && s->deqs[q].order == 1) d = &s->deqs[q];
                /* the velocity of a second-order line gets that line */
                for (q = 0; q < s->nstates; q++)
                    if (g.vel[a * 64 + q] == k) {
                        slong e;
                        for (e = 0; e < s->ndeqs; e++)
                            if (s->deqs[e].order == 2 && strcmp(s->deqs[e].state, s->states[q]) == 0) d = &s->deqs[e];
                    }
                if (d == NULL && !(g.vel[a * 64 + k] >= 0)) {
                    r = rs_error_set_at(err, RS_ERR_INPUT, s->loc.file, s->loc.line, s->loc.col,
                                        "expected an equation %s' = ... in this subsystem", x);
                    break;
                }
                /* equation of motion at the new time */
                if (!pos) {
                    sb_add(&b, "eq ");
                    dvar(&b, x, j, g.K);
                    sb_add(&b, "[n+1] = ");
                    if (d == NULL) {
                        /* x' = v of a second-order line */
                        var(&b, s->states[g.vel[a * 64 + k]], j, g.K);
                        sb_add(&b, "[n+1]");
                    } else {
                        sb_add(&b, "(");
                        r = subst(&b, &g, a, j, d, err);
                        sb_add(&b, ")");
                    }
                    sb_add(&b, "\n");
                }
                if (r != RS_OK) break;
                /* integration formula */
                if (g.pair[a]) {
                    slong vk = g.vel[a * 64 + k];
                    const char *v;
                    if (vk < 0) continue;       /* velocities are handled with their position */
                    v = s->states[vk];
                    if (strcmp(m, "newmark") == 0) {
                        sb_add(&b, "eq %s[n+1] = %s[n] + (%s)*%s[n] + (%s)^2*((1/2 - (%s))*%s_dot[n] + (%s)*%s_dot[n+1])\n",
                               x, x, h, v, h, s->arg1, v, s->arg1, v);
                        sb_add(&b, "eq %s[n+1] = %s[n] + (%s)*((1 - (%s))*%s_dot[n] + (%s)*%s_dot[n+1])\n",
                               v, v, h, s->arg2, v, s->arg2, v);
                    } else {
                        sb_add(&b, "eq %s[n+1] - 2*%s[n] + %s[n-1] = (%s)^2*%s_dot[n]\n", x, x, x, h, v);
                        sb_add(&b, "eq 2*(%s)*%s[n] = %s[n+1] - %s[n-1]\n", h, v, x, x);
                    }
                    continue;
                }
                sb_add(&b, "eq ");
                var(&b, x, j, g.K);
                if (strcmp(m, "euler-forward") == 0)
                    sb_add(&b, "[n+1] - %s[n] = (%s)*%s_dot[n]\n", x, h, x);
                else if (strcmp(m, "euler-backward") == 0) {
                    sb_add(&b, "[n+1] - %s[n] = (%s)*", x, h);
                    dvar(&b, x, j, g.K);
                    sb_add(&b, "[n+1]\n");
                } else if (strcmp(m, "trapezoidal") == 0 || strcmp(m, "theta") == 0) {
                    const char *th = strcmp(m, "theta") == 0 ? s->arg1 : "1/2";
                    sb_add(&b, "[n+1] - %s[n] = (%s)*((1 - (%s))*%s_dot[n] + (%s)*", x, h, th, x, th);
                    dvar(&b, x, j, g.K);
                    sb_add(&b, "[n+1])\n");
                } else if (strcmp(m, "bdf2") == 0) {
                    sb_add(&b, "[n+1]*3 - 4*%s[n] + %s[n-1] = 2*(%s)*", x, x, h);
                    dvar(&b, x, j, g.K);
                    sb_add(&b, "[n+1]\n");
                } else if (strcmp(m, "bdf3") == 0) {
                    sb_add(&b, "[n+1]*11 - 18*%s[n] + 9*%s[n-1] - 2*%s[n-2] = 6*(%s)*", x, x, x, h);
                    dvar(&b, x, j, g.K);
                    sb_add(&b, "[n+1]\n");
                }
            }
        }
    }
    flint_free(g.vel);
    flint_free(g.pair);
    flint_free(unk.s);
    if (r == RS_OK) {
        char label[600];
        snprintf(label, sizeof label, "%s (equations generated by the builders; see --emit equations)", c->path);
        c->emitted = b.s;
        b.s = NULL;
        r = rs_case_parse_append(c, label, c->emitted, err);
    }
    flint_free(b.s);
    return r;
}
