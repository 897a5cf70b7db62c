/* stmt_builder.c -- the builder statements (syntax only; lowered by
 * src/lower/builder.c):
 *     subsystem NAME state X V ...      NAME' = EXPR, NAME'' = EXPR
 *     integrate NAME METHOD [ARG1 [ARG2]] STEP
 *     integrate NAME rk TABLEAU STEP      (a name, or [A11, A12; A21, A22 | b1, b2])
 *     integrate NAME adams-bashforth K STEP | adams-moulton K STEP | bdf K STEP
 *     integrate NAME hht ALPHA STEP | generalized-alpha RHO_INF STEP | wbz ALPHA STEP | leapfrog STEP
 *     couple jacobi | gauss-seidel S1 S2 ... Sn | monolithic | explicit order K
 *            | implicit order K [extension D | extension I [alpha_T = VALUE]]
 *     iterations K    extrapolate order K    coupling force NAME = EXPR */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include "parse.h"

static int at(rs_stmt_t *x, size_t i, const char *fmt, const char *a)
{
    return _rs_at_err(x, i, RS_ERR_INPUT, fmt, a);
}

int _rs_builder_is_keyword(const char *w)
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

/* text[i..] (the rest of the statement) as one expression */
static int rest_expr(rs_expr_t **e, rs_stmt_t *x, size_t i)
{
    rs_src_t sub = _rs_src_from(&x->src, i, NULL);
    return rs_expr_parse_all(e, &sub, x->err);
}

/* the token text[i .. i+n) as one expression */
static int token_expr(rs_expr_t **e, rs_stmt_t *x, size_t i, const char *tok)
{
    rs_src_t sub = _rs_src_from(&x->src, i, tok);
    return rs_expr_parse_all(e, &sub, x->err);
}

/* NAME' = EXPR or NAME'' = EXPR inside the last subsystem block (i at the first apostrophe) */
int _rs_st_state_equation(rs_stmt_t *x, const char *kw, size_t i)
{
    const char *t = x->src.text;
    rs_subsystem_t *s;
    rs_deq_t d;
    size_t name_at = i - strlen(kw);
    int r;
    if (x->c->nsubs == 0)
        return at(x, 0, "expected a `subsystem` statement before the state equation %s'", kw);
    s = &x->c->subs[x->c->nsubs - 1];
    memset(&d, 0, sizeof d);
    d.order = 1;
    i++;
    if (t[i] == '\'') { d.order = 2; i++; }
    _rs_skip_ws(t, &i);
    if (t[i] != '=') return at(x, i, "expected '=' after %s' in a state equation", kw);
    i++;
    _rs_skip_ws(t, &i);
    r = rest_expr(&d.rhs, x, i);
    if (r != RS_OK) return r;
    d.state = rs_strdup(kw);
    _rs_set_loc(x, &d.loc, name_at);
    RS_GROW(s->deqs, s->ndeqs);
    s->deqs[s->ndeqs++] = d;
    return RS_OK;
}

static int st_subsystem(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    char *name = _rs_read_token(t, &i), *w;
    rs_subsystem_t *s;
    if (name == NULL || !valid_ident(name)) {
        flint_free(name);
        return at(x, i, "expected a subsystem name, found '%s'", t + i);
    }
    if (sub_index(x->c, name) >= 0) {
        at(x, i, "subsystem '%s' is already declared", name);
        flint_free(name);
        return x->err->code;
    }
    w = _rs_read_token(t, &i);
    if (w == NULL || strcmp(w, "state") != 0) {
        flint_free(name); flint_free(w);
        return at(x, i, "expected 'state NAME ...' after the subsystem name, found '%s'", t + i);
    }
    flint_free(w);
    RS_GROW(x->c->subs, x->c->nsubs);
    s = &x->c->subs[x->c->nsubs++];
    memset(s, 0, sizeof *s);
    s->name = name;
    _rs_set_loc(x, &s->loc, 0);
    for (;;) {
        size_t p0;
        _rs_skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == '\0') break;
        p0 = i;
        w = _rs_read_token(t, &i);
        if (w == NULL || !valid_ident(w)) {
            flint_free(w);
            return at(x, p0, "expected a state name, found '%s'", t + p0);
        }
        RS_GROW(s->states, s->nstates);
        memset(&s->states[s->nstates], 0, sizeof(rs_name_t));
        s->states[s->nstates].name = w;
        _rs_set_loc(x, &s->states[s->nstates].loc, p0);
        s->nstates++;
    }
    if (s->nstates == 0) return at(x, i, "expected at least one state name%s", "");
    return RS_OK;
}

static const char *const methods[] = {"euler-forward", "euler-backward", "trapezoidal", "theta", "bdf2", "bdf3",
                                      "central-difference", "newmark", "exact", "rk", "adams-bashforth",
                                      "adams-moulton", "bdf", "hht", "generalized-alpha", "wbz", "leapfrog", NULL};

static const char *const tableaux[] = {"euler", "heun", "midpoint", "rk4", "gauss2", "radau-iia2", "radau-iia3",
                                       "sdirk2", "sdirk3", "sdirk3-low", NULL};

#define MAX_STAGES 8

/* one rational entry of an inline tableau at t[*i], ended by ',', ';', '|', ']' or a blank */
static int tab_entry(rs_stmt_t *x, size_t *i, fmpq_t q)
{
    const char *t = x->src.text;
    char buf[64];
    size_t p0, n;
    _rs_skip_ws(t, i);
    p0 = *i;
    if (t[p0] == '\0') return at(x, p0, "expected ']' closing the tableau, found end of line%s", "");
    while (t[*i] && !strchr(",;|] \t", t[*i])) (*i)++;
    n = *i - p0;
    if (n > 0 && n < sizeof buf) {
        memcpy(buf, t + p0, n);
        buf[n] = '\0';
        if (strspn(buf, "-0123456789/") == n && isdigit((unsigned char) buf[n - 1]) && fmpq_set_str(q, buf, 10) == 0
            && !fmpz_is_zero(fmpq_denref(q))) {
            fmpq_canonicalise(q);
            return RS_OK;
        }
    }
    return at(x, p0, "expected a rational tableau entry (such as -1/12), found '%s'", t + p0);
}

/* [A11, A12; A21, A22 | b1, b2] at t[*i] (on '['): s rows of s entries, then s weights */
static int tab_inline(rs_stmt_t *x, rs_subsystem_t *s, size_t *i)
{
    const char *t = x->src.text;
    fmpq e[MAX_STAGES * MAX_STAGES + MAX_STAGES];
    slong n = 0, rows = 1, cols = 0, first = -1, k, st;
    int r = RS_OK, inb = 0;
    size_t p0 = *i;
    for (k = 0; k < MAX_STAGES * MAX_STAGES + MAX_STAGES; k++) fmpq_init(e + k);
    (*i)++;
    for (;;) {
        if (n == MAX_STAGES * MAX_STAGES + MAX_STAGES) { r = at(x, *i, "too many stages (limit 8)%s", ""); break; }
        if ((r = tab_entry(x, i, e + n)) != RS_OK) break;
        n++; cols++;
        _rs_skip_ws(t, i);
        if (t[*i] == ',') { (*i)++; continue; }
        if (t[*i] == ';' || t[*i] == '|' || t[*i] == ']') {
            if (!inb && first < 0) first = cols;
            if (!inb && cols != first) {
                r = at(x, *i, "expected as many entries in each row of the tableau as in the first, found '%s'", t + *i);
                break;
            }
            if (t[*i] == ']') break;
            if (inb) { r = at(x, *i, "expected ']' after the weights b, found '%s'", t + *i); break; }
            if (t[*i] == '|') inb = 1; else rows++;
            cols = 0;
            (*i)++;
            continue;
        }
        _rs_skip_ws(t, i);
        continue;   /* entries separated by blanks */
    }
    if (r == RS_OK) {
        (*i)++;
        st = cols;
        if (!inb || st != rows || first != st || st > MAX_STAGES)
            r = at(x, p0, "expected a square tableau [A | b] with s rows of s entries and s weights b%s", "");
    }
    if (r == RS_OK) {
        s->ntab = n;
        s->tab = _fmpq_vec_init(n);
        for (k = 0; k < n; k++) fmpq_set(s->tab + k, e + k);
    }
    for (k = 0; k < MAX_STAGES * MAX_STAGES + MAX_STAGES; k++) fmpq_clear(e + k);
    return r;
}

/* rk NAME | rk [...] */
static int rk_tableau(rs_stmt_t *x, rs_subsystem_t *s, size_t *i)
{
    const char *t = x->src.text;
    size_t p0;
    char *w;
    slong k;
    _rs_skip_ws(t, i);
    if (t[*i] == '[') return tab_inline(x, s, i);
    p0 = *i;
    w = _rs_read_token(t, i);
    for (k = 0; w && tableaux[k]; k++)
        if (strcmp(w, tableaux[k]) == 0) { s->tableau = w; return RS_OK; }
    flint_free(w);
    return at(x, p0, "expected a Butcher tableau (euler, heun, midpoint, rk4, gauss2, radau-iia2, radau-iia3, "
              "sdirk2, sdirk3, sdirk3-low, or [A11, A12; A21, A22 | b1, b2]), found '%s'", t + p0);
}

/* the K of adams-bashforth K, adams-moulton K (1..6) and bdf K (1..7: BDF7 shows the loss of zero-stability) */
static int step_count(rs_stmt_t *x, rs_subsystem_t *s, size_t *i)
{
    const char *t = x->src.text;
    slong hi = strcmp(s->method, "bdf") == 0 ? 7 : 6;
    size_t p0;
    char *w;
    _rs_skip_ws(t, i);
    p0 = *i;
    w = _rs_read_token(t, i);
    if (w == NULL || strlen(w) != 1 || w[0] < '1' || w[0] > '0' + hi) {
        flint_free(w);
        return at(x, p0, hi == 7 ? "expected the number of steps K = 1..7, found '%s'"
                  : "expected the number of steps K = 1..6, found '%s'", t + p0);
    }
    s->korder = w[0] - '0';
    flint_free(w);
    return RS_OK;
}

/* the method's parameter: a token read as an expression */
static int method_arg(rs_expr_t **e, rs_stmt_t *x, size_t *i)
{
    size_t p0;
    char *tok;
    int r;
    _rs_skip_ws(x->src.text, i);
    p0 = *i;
    tok = _rs_read_token(x->src.text, i);
    if (tok == NULL) return RS_OK;
    r = token_expr(e, x, p0, tok);
    flint_free(tok);
    return r;
}

static int st_integrate(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    size_t p0;
    char *name = _rs_read_token(t, &i), *m;
    slong k, idx;
    int known = 0, r = RS_OK, theta, newmark;
    rs_subsystem_t *s;
    if (name == NULL || (idx = sub_index(x->c, name)) < 0) {
        at(x, i, "expected the name of a declared subsystem after integrate, found '%s'", name ? name : "");
        flint_free(name);
        return x->err->code;
    }
    flint_free(name);
    s = &x->c->subs[idx];
    if (s->method != NULL) return at(x, 0, "subsystem '%s' already has an integrator", s->name);
    _rs_skip_ws(t, &i);
    p0 = i;
    m = _rs_read_token(t, &i);
    for (k = 0; m && methods[k]; k++) if (strcmp(m, methods[k]) == 0) known = 1;
    if (!known) {
        flint_free(m);
        return at(x, p0, "expected an integrator (euler-forward, euler-backward, trapezoidal, theta T, "
                  "bdf2, bdf3, central-difference, newmark B G, exact, rk TABLEAU, adams-bashforth K, "
                  "adams-moulton K, bdf K, hht ALPHA, generalized-alpha RHO_INF, wbz ALPHA, leapfrog), found '%s'",
                  t + p0);
    }
    s->method = m;
    _rs_set_loc(x, &s->intloc, p0);
    if (strcmp(m, "rk") == 0) r = rk_tableau(x, s, &i);
    else if (strcmp(m, "adams-bashforth") == 0 || strcmp(m, "adams-moulton") == 0 || strcmp(m, "bdf") == 0)
        r = step_count(x, s, &i);
    if (r != RS_OK) return r;
    theta = strcmp(m, "theta") == 0 || strcmp(m, "hht") == 0 || strcmp(m, "generalized-alpha") == 0
        || strcmp(m, "wbz") == 0;
    newmark = strcmp(m, "newmark") == 0;
    if (theta || newmark) r = method_arg(&s->arg1, x, &i);
    if (r == RS_OK && newmark) r = method_arg(&s->arg2, x, &i);
    if (r != RS_OK) return r;
    _rs_skip_ws(t, &i);
    if ((theta && s->arg1 == NULL) || (newmark && s->arg2 == NULL))
        return at(x, i, "expected the method's parameters, then the step, found '%s'", t + i);
    if (t[i] == '\0') return at(x, i, "expected the step (an expression such as h) after the method%s", "");
    return rest_expr(&s->step, x, i);
}

/* [extension D | extension I [alpha_T = VALUE]] after `couple implicit order K`
 * (Li et al. sect. 3.2; the reading: src/numeric/cosim_ext.h) */
static int couple_extension(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_case_struct *c = x->c;
    size_t p0;
    char *w;
    rs_expr_t *e = NULL;
    int r;
    _rs_skip_ws(t, &i);
    if (t[i] == '\0') return RS_OK;
    p0 = i;
    w = _rs_read_token(t, &i);
    if (w == NULL || strcmp(w, "extension") != 0) {
        flint_free(w);
        return at(x, p0, "expected end of line or 'extension D|I', found '%s'", t + p0);
    }
    flint_free(w);
    if (strcmp(c->couple, "implicit") != 0)
        return at(x, p0, "the extension couplings correct an implicit step: write 'couple implicit order K "
                  "extension ...'%s", "");
    _rs_skip_ws(t, &i);
    p0 = i;
    w = _rs_read_token(t, &i);
    if (w == NULL || strlen(w) != 1 || (w[0] != 'D' && w[0] != 'I')) {
        flint_free(w);
        return at(x, p0, "expected D (derivative) or I (integral) after extension, found '%s'", t + p0);
    }
    c->couple_ext = w[0];
    flint_free(w);
    if (c->couple_order > 2)
        return at(x, p0, "expected 'order K' with K = 0, 1, 2 for the extension couplings%s", "");
    _rs_skip_ws(t, &i);
    if (t[i] == '\0') return RS_OK;
    p0 = i;
    w = _rs_read_ident(t, &i);
    if (w == NULL || strcmp(w, "alpha_T") != 0) {
        flint_free(w);
        return at(x, p0, "expected end of line or 'alpha_T = VALUE', found '%s'", t + p0);
    }
    flint_free(w);
    if (c->couple_ext != 'I')
        return at(x, p0, "alpha_T (the intermediate sampling point) is an option of extension I; extension D "
                  "samples at T_{N+1/2}%s", "");
    _rs_skip_ws(t, &i);
    if (t[i] != '=') return at(x, i, "expected '=' after alpha_T, found '%s'", t + i);
    i++;
    _rs_skip_ws(t, &i);
    p0 = i;
    r = rs_expr_parse(&e, &x->src, &i, x->err);
    if (r != RS_OK) return r;
    c->couple_alpha = flint_malloc(sizeof(fmpq));
    fmpq_init(c->couple_alpha);
    r = rs_expr_eval_const(c->couple_alpha, e, &x->src, x->err);
    rs_expr_free(e);
    if (r != RS_OK) return r;
    if (fmpq_sgn(c->couple_alpha) <= 0 || fmpq_cmp_si(c->couple_alpha, 1) >= 0)
        return at(x, p0, "expected alpha_T strictly between 0 and 1, found '%s'", t + p0);
    _rs_skip_ws(t, &i);
    if (t[i] != '\0') return at(x, i, "expected end of line, found '%s'", t + i);
    return RS_OK;
}

static int st_couple(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_case_struct *c = x->c;
    size_t p0;
    char *w;
    if (c->couple != NULL) return at(x, 0, "a case has one couple statement%s", "");
    _rs_skip_ws(t, &i);
    p0 = i;
    w = _rs_read_token(t, &i);
    _rs_set_loc(x, &c->couple_loc, p0);
    if (w && (strcmp(w, "jacobi") == 0 || strcmp(w, "monolithic") == 0)) {
        c->couple = w;
    } else if (w && strcmp(w, "gauss-seidel") == 0) {
        char *s;
        c->couple = w;
        /* S1 S2 ... Sn: the order in which the subsystems are integrated */
        for (;;) {
            _rs_skip_ws(t, &i);
            if ((s = _rs_read_token(t, &i)) == NULL) break;
            RS_GROW(c->couple_seq, c->ncouple_seq);
            c->couple_seq[c->ncouple_seq++] = s;
        }
        if (c->ncouple_seq < 2)
            return at(x, i, "expected the names of the subsystems after gauss-seidel, in the order they are "
                      "integrated (at least two), found '%s'", t + i);
        c->couple_first = rs_strdup(c->couple_seq[0]);
        c->couple_second = rs_strdup(c->couple_seq[1]);
    } else if (w && (strcmp(w, "explicit") == 0 || strcmp(w, "implicit") == 0)) {
        char *o = _rs_read_token(t, &i), *k;
        c->couple = w;
        k = _rs_read_token(t, &i);
        if (o == NULL || strcmp(o, "order") != 0 || k == NULL || strlen(k) > 2 || !isdigit((unsigned char) k[0])) {
            flint_free(o); flint_free(k);
            return at(x, i, "expected 'order K' (K = 0, 1, 2) after explicit/implicit%s", "");
        }
        c->couple_order = atol(k);
        flint_free(o); flint_free(k);
        return couple_extension(x, i);
    } else {
        flint_free(w);
        return at(x, p0, "expected jacobi, gauss-seidel S1 S2 ..., monolithic, explicit order K or "
                  "implicit order K, found '%s'", t + p0);
    }
    _rs_skip_ws(t, &i);
    if (t[i] != '\0') return at(x, i, "expected end of line, found '%s'", t + i);
    return RS_OK;
}

/* iterations K / extrapolate order K */
static int st_count(rs_stmt_t *x, const char *kw, size_t i)
{
    const char *t = x->src.text;
    char *w;
    size_t p0;
    long k;
    if (strcmp(kw, "extrapolate") == 0) {
        w = _rs_read_token(t, &i);
        if (w == NULL || strcmp(w, "order") != 0) {
            flint_free(w);
            return at(x, i, "expected 'order K' after extrapolate%s", "");
        }
        flint_free(w);
    }
    _rs_skip_ws(t, &i);
    p0 = i;
    w = _rs_read_token(t, &i);
    if (w == NULL || strspn(w, "0123456789") != strlen(w) || strlen(w) > 3) {
        flint_free(w);
        return at(x, p0, "expected a small non-negative integer, found '%s'", t + p0);
    }
    k = atol(w);
    flint_free(w);
    if (strcmp(kw, "iterations") == 0) {
        if (k > RS_CASE_MAX_ITERATIONS) return at(x, p0, "too many iterations (limit 16)%s", "");
        x->c->iterations = k;
    } else {
        if (k > RS_CASE_MAX_EXTRAPOLATE) return at(x, p0, "extrapolation order too high (limit 6)%s", "");
        x->c->extrapolate = k;
    }
    return RS_OK;
}

/* coupling force NAME = EXPR (several: vector coupling, src/analysis/analysis_cosim.c) */
static int st_force(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_case_struct *c = x->c;
    char *w = _rs_read_token(t, &i);
    rs_force_t f;
    size_t p0;
    slong k;
    int r;
    if (w == NULL || strcmp(w, "force") != 0) {
        flint_free(w);
        return at(x, i, "expected 'coupling force NAME = EXPR'%s", "");
    }
    flint_free(w);
    _rs_skip_ws(t, &i);
    p0 = i;
    while (isalnum((unsigned char) t[i]) || t[i] == '_') i++;
    if (i == p0) return at(x, p0, "expected the force's name, found '%s'", t + p0);
    memset(&f, 0, sizeof f);
    f.name = rs_strndup(t + p0, i - p0);
    for (k = 0; k < c->nforces; k++)
        if (strcmp(c->forces[k].name, f.name) == 0) {
            r = at(x, p0, "the coupling force '%s' is already defined", f.name);
            rs_force_clear(&f);
            return r;
        }
    _rs_skip_ws(t, &i);
    if (t[i] != '=') { rs_force_clear(&f); return at(x, i, "expected '=' after the force's name%s", ""); }
    i++;
    _rs_skip_ws(t, &i);
    r = rest_expr(&f.e, x, i);
    if (r != RS_OK) { rs_force_clear(&f); return r; }
    _rs_set_loc(x, &f.loc, p0);
    RS_GROW(c->forces, c->nforces);
    c->forces[c->nforces++] = f;
    return RS_OK;
}

int _rs_st_builder(rs_stmt_t *x, const char *kw, size_t i)
{
    if (strcmp(kw, "subsystem") == 0) return st_subsystem(x, i);
    if (strcmp(kw, "integrate") == 0) return st_integrate(x, i);
    if (strcmp(kw, "couple") == 0) return st_couple(x, i);
    if (strcmp(kw, "iterations") == 0 || strcmp(kw, "extrapolate") == 0) return st_count(x, kw, i);
    if (strcmp(kw, "coupling") == 0) return st_force(x, i);
    return at(x, 0, "unknown builder statement '%s'", kw);
}
