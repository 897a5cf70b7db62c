/* scheme.c -- exact evaluation of the model's equations into the
 * lambda-matrix. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "recstab/scheme.h"
#include "util/qd.h"

/* Evaluation limits (lets are expanded where they are used, so a few short
 * lines can describe a huge tree): recursion depth, total nodes evaluated,
 * terms of any polynomial, total coefficient size of a product or power. */
#define RS_SCHEME_MAX_DEPTH 4000
#define RS_SCHEME_MAX_STEPS 1000000
#define RS_SCHEME_MAX_TERMS 100000
#define RS_SCHEME_MAX_BITS 536870912.0   /* 64 MB of coefficients (an upper bound is checked) */

/* A value during evaluation: (c[0] + sum_u c[1+u] lambda^low x_u) / den.
 * c[0] is the part without unknowns; den is in the parameters only. */
typedef struct {
    slong ns;                /* 1 + number of unknowns */
    fmpq_mpoly_struct *c;
    slong low;
    fmpq_mpoly_t den;
} lin_t;

typedef struct {
    const rs_scheme_struct *s;
    const rs_case_struct *c;
    int allow_lambda;        /* char / expect mode */
    int *visiting;           /* per let: cycle detection */
    rs_error_struct *err;
    /* non-zero assumptions collected (points into the scheme being built) */
    rs_scheme_struct *collect;
    slong depth, steps;      /* evaluation limits */
    slong ivar;              /* variable standing for the imaginary unit i, or -1 */
} ev_t;

static void lin_init(lin_t *v, slong ns, const fmpq_mpoly_ctx_t ctx)
{
    slong i;
    v->ns = ns;
    v->c = flint_malloc(ns * sizeof(fmpq_mpoly_struct));
    for (i = 0; i < ns; i++) fmpq_mpoly_init(v->c + i, ctx);
    v->low = 0;
    fmpq_mpoly_init(v->den, ctx);
    fmpq_mpoly_one(v->den, ctx);
}

static void lin_clear(lin_t *v, const fmpq_mpoly_ctx_t ctx)
{
    slong i;
    for (i = 0; i < v->ns; i++) fmpq_mpoly_clear(v->c + i, ctx);
    flint_free(v->c);
    fmpq_mpoly_clear(v->den, ctx);
}

static int lin_has_unknowns(const lin_t *v, const fmpq_mpoly_ctx_t ctx)
{
    slong i;
    for (i = 1; i < v->ns; i++)
        if (!fmpq_mpoly_is_zero(v->c + i, ctx)) return 1;
    return 0;
}

static int err_at(ev_t *x, const rs_expr_t *e, int code, const char *fmt, const char *a)
    __attribute__((format(printf, 4, 0)));
static int err_at(ev_t *x, const rs_expr_t *e, int code, const char *fmt, const char *a)
{
    return rs_error_set_at(x->err, code, rs_expr_file(e, x->c->path), e->line, e->col, fmt, a);
}

static void mul_lambda_pow(fmpq_mpoly_t p, slong k, const rs_scheme_struct *s)
{
    fmpq_mpoly_t g;
    if (k == 0 || fmpq_mpoly_is_zero(p, s->ctx)) return;
    fmpq_mpoly_init(g, s->ctx);
    fmpq_mpoly_gen(g, s->lambda_var, s->ctx);
    fmpq_mpoly_pow_ui(g, g, (ulong) k, s->ctx);
    fmpq_mpoly_mul(p, p, g, s->ctx);
    fmpq_mpoly_clear(g, s->ctx);
}

/* bring both to the same low (the smaller one) */
static void align_low(lin_t *a, lin_t *b, const rs_scheme_struct *s)
{
    slong i;
    if (a->low > b->low) { lin_t *t = a; a = b; b = t; }
    /* now a->low <= b->low: raise b's unknown slots */
    if (b->low != a->low) {
        for (i = 1; i < b->ns; i++) mul_lambda_pow(b->c + i, b->low - a->low, s);
        b->low = a->low;
    }
}

static int prod_check(ev_t *x, const rs_expr_t *e, const fmpq_mpoly_t a,
                      const fmpq_mpoly_t b, ulong k);

/* r = a +- b (r may not alias) */
static int lin_addsub(lin_t *r, lin_t *a, lin_t *b, int sub, ev_t *x, const rs_expr_t *e)
{
    const rs_scheme_struct *s = x->s;
    slong i;
    const fmpq_mpoly_ctx_struct *ctx = s->ctx;
    int a_unk = lin_has_unknowns(a, ctx), b_unk = lin_has_unknowns(b, ctx);
    if (a_unk && b_unk) align_low(a, b, s);
    r->low = a_unk ? a->low : b->low;
    if (fmpq_mpoly_equal(a->den, b->den, ctx)) {
        for (i = 0; i < r->ns; i++) {
            if (sub) fmpq_mpoly_sub(r->c + i, a->c + i, b->c + i, ctx);
            else fmpq_mpoly_add(r->c + i, a->c + i, b->c + i, ctx);
        }
        fmpq_mpoly_set(r->den, a->den, ctx);
    } else {
        fmpq_mpoly_t g, fa, fb, t;
        fmpq_mpoly_init(g, ctx); fmpq_mpoly_init(fa, ctx); fmpq_mpoly_init(fb, ctx);
        fmpq_mpoly_init(t, ctx);
        if (!fmpq_mpoly_gcd(g, a->den, b->den, ctx) || fmpq_mpoly_is_zero(g, ctx))
            fmpq_mpoly_one(g, ctx);
        fmpq_mpoly_divides(fa, b->den, g, ctx);   /* multiplier for a */
        fmpq_mpoly_divides(fb, a->den, g, ctx);   /* multiplier for b */
        for (i = 0; i < r->ns; i++) {
            if (prod_check(x, e, a->c + i, fa, 0) != RS_OK || prod_check(x, e, b->c + i, fb, 0) != RS_OK
                || prod_check(x, e, a->den, fa, 0) != RS_OK) {
                fmpq_mpoly_clear(g, ctx); fmpq_mpoly_clear(fa, ctx); fmpq_mpoly_clear(fb, ctx);
                fmpq_mpoly_clear(t, ctx);
                return x->err->code;
            }
            fmpq_mpoly_mul(t, a->c + i, fa, ctx);
            fmpq_mpoly_mul(r->c + i, b->c + i, fb, ctx);
            if (sub) fmpq_mpoly_sub(r->c + i, t, r->c + i, ctx);
            else fmpq_mpoly_add(r->c + i, t, r->c + i, ctx);
        }
        fmpq_mpoly_mul(r->den, a->den, fa, ctx);
        fmpq_mpoly_clear(g, ctx); fmpq_mpoly_clear(fa, ctx); fmpq_mpoly_clear(fb, ctx);
        fmpq_mpoly_clear(t, ctx);
    }
    return RS_OK;
}

/* bits of the largest coefficient of p (numerator and denominator) */
static double coeff_bits(const fmpq_mpoly_t p)
{
    slong zb = fmpz_mpoly_max_bits(p->zpoly);
    return (double) FLINT_ABS(zb) + (double) fmpz_bits(fmpq_numref(p->content))
           + (double) fmpz_bits(fmpq_denref(p->content));
}

/* Checks, before computing it, that a*b (k == 0) or a^k (k > 0) stays
 * within the degree, term and size limits; bounds are upper bounds. */
static int prod_check(ev_t *x, const rs_expr_t *e, const fmpq_mpoly_t a,
                      const fmpq_mpoly_t b, ulong k)
{
    const rs_scheme_struct *s = x->s;
    double la = (double) fmpq_mpoly_length(a, s->ctx), terms, dterms = 1.0, bits;
    slong v;
    if (la == 0.0 || (k == 0 && fmpq_mpoly_is_zero(b, s->ctx)) || k == 1)
        return RS_OK;
    for (v = 0; v < s->nvars; v++) {
        slong d = fmpq_mpoly_degree_si(a, v, s->ctx);
        double dd = k == 0 ? (double) d + (double) fmpq_mpoly_degree_si(b, v, s->ctx) : (double) d * (double) k;
        if (dd > RS_SCHEME_MAX_DEGREE)
            return rs_error_set_at(x->err, RS_ERR_LIMIT, rs_expr_file(e, x->c->path), e->line, e->col,
                                   "degree limit exceeded: degree %.0f in %s (limit %d per variable)",
                                   dd, s->vars[v], RS_SCHEME_MAX_DEGREE);
        dterms *= dd + 1.0;
    }
    if (k == 0) {
        terms = la * (double) fmpq_mpoly_length(b, s->ctx);
        bits = coeff_bits(a) + coeff_bits(b) + log2(la + 1.0);
    } else {
        /* terms of a^k: at most C(la - 1 + k, la - 1) */
        double c = 1.0, i;
        for (i = 1.0; i < la && c <= 1e30; i += 1.0)
            c = c * ((double) k + i) / i;
        terms = c;
        bits = (double) k * (coeff_bits(a) + log2(la + 1.0));
    }
    if (dterms < terms) terms = dterms;
    {
        /* monomials of at most the total degree of the result: C(D + nvars, nvars) */
        double D = (double) fmpq_mpoly_total_degree_si(a, s->ctx), simplex = 1.0;
        D = k == 0 ? D + (double) fmpq_mpoly_total_degree_si(b, s->ctx) : D * (double) k;
        for (v = 0; v < s->nvars; v++)
            simplex = simplex * (D + (double) (v + 1)) / (double) (v + 1);
        if (simplex < terms) terms = simplex;
    }
    /* the bound can be loose (the result is checked again once computed):
     * refuse only what is far beyond the limit */
    if (terms > 20.0 * RS_SCHEME_MAX_TERMS)
        return rs_error_set_at(x->err, RS_ERR_LIMIT, rs_expr_file(e, x->c->path), e->line, e->col,
                               "term limit exceeded: this %s could have %.0f terms (limit %d terms per polynomial)",
                               k == 0 ? "product" : "power", terms, RS_SCHEME_MAX_TERMS);
    if (terms * bits > RS_SCHEME_MAX_BITS)
        return rs_error_set_at(x->err, RS_ERR_LIMIT, rs_expr_file(e, x->c->path), e->line, e->col,
                               "size limit exceeded: this %s could need %.0f bits of coefficients (limit %.0f bits)",
                               k == 0 ? "product" : "power", terms * bits, RS_SCHEME_MAX_BITS);
    return RS_OK;
}

static int degree_ok(ev_t *x, const rs_expr_t *e, const fmpq_mpoly_t p)
{
    slong v;
    for (v = 0; v < x->s->nvars; v++) {
        slong d = fmpq_mpoly_degree_si(p, v, x->s->ctx);
        if (d > RS_SCHEME_MAX_DEGREE) {
            char msg[128];
            snprintf(msg, sizeof msg, "%ld in %s", (long) d, x->s->vars[v]);
            return err_at(x, e, RS_ERR_LIMIT,
                          "degree limit exceeded (%s; limit 4096 per variable)", msg);
        }
    }
    return RS_OK;
}

static void record_nonzero(ev_t *x, const fmpq_mpoly_t d, const char *file, int line, int col)
{
    rs_scheme_struct *s = x->collect;
    slong i;
    char *str, *txt;
    if (s == NULL || fmpq_mpoly_is_fmpq(d, s->ctx))
        return;
    for (i = 0; i < s->nnonzero; i++)
        if (fmpq_mpoly_equal(s->nonzero + i, d, s->ctx)) return;
    s->nonzero = flint_realloc(s->nonzero, (s->nnonzero + 1) * sizeof(fmpq_mpoly_struct));
    s->nonzero_text = flint_realloc(s->nonzero_text, (s->nnonzero + 1) * sizeof(char *));
    s->nonzero_loc = flint_realloc(s->nonzero_loc, (s->nnonzero + 1) * sizeof(rs_loc_t));
    s->nonzero_loc[s->nnonzero].file = (char *) file;
    s->nonzero_loc[s->nnonzero].line = line;
    s->nonzero_loc[s->nnonzero].col = col;
    fmpq_mpoly_init(s->nonzero + s->nnonzero, s->ctx);
    fmpq_mpoly_set(s->nonzero + s->nnonzero, d, s->ctx);
    str = fmpq_mpoly_get_str_pretty(d, (const char **) s->vars, s->ctx);
    txt = flint_malloc(strlen(str) + 8);
    sprintf(txt, "%s != 0", str);
    flint_free(str);
    s->nonzero_text[s->nnonzero] = txt;
    s->nnonzero++;
}

static int eval(lin_t *out, const rs_expr_t *e, ev_t *x);

/* index of the unknown (column) name of s, or -1 */
static slong unknown_index(const rs_scheme_struct *s, const char *name)
{
    slong i;
    for (i = 0; i < s->n; i++)
        if (strcmp(s->unknowns[i], name) == 0) return i;
    return -1;
}

static int eval_name(lin_t *out, const rs_expr_t *e, ev_t *x)
{
    const rs_scheme_struct *s = x->s;
    slong k;
    if ((k = rs_case_param_index(x->c, e->name)) >= 0) {
        if (e->shifted)
            return err_at(x, e, RS_ERR_INPUT,
                          "shift on the parameter '%s': parameters are constant in n (only unknowns take [n+K])", e->name);
        fmpq_mpoly_gen(out->c + 0, k, s->ctx);
        return RS_OK;
    }
    if ((k = unknown_index(s, e->name)) >= 0) {
        if (x->allow_lambda)
            return err_at(x, e, RS_ERR_INPUT,
                          "the unknown '%s' cannot appear here (only parameters and lambda)", e->name);
        if (!e->shifted)
            return rs_error_set_at(x->err, RS_ERR_INPUT, rs_expr_file(e, x->c->path), e->line, e->col,
                                   "expected a shift after the unknown '%s', as in %s[n] or %s[n+1]",
                                   e->name, e->name, e->name);
        fmpq_mpoly_one(out->c + 1 + k, s->ctx);
        out->low = e->shift;
        return RS_OK;
    }
    if ((k = rs_case_let_index(x->c, e->name)) >= 0) {
        const rs_let_t *l = &x->c->lets[k];
        int r;
        if (l->shifted && !e->shifted)
            return rs_error_set_at(x->err, RS_ERR_INPUT, rs_expr_file(e, x->c->path), e->line, e->col,
                                   "'%s' is a derived sequence: expected a shift, as in %s[n+1]",
                                   e->name, e->name);
        if (!l->shifted && e->shifted)
            return err_at(x, e, RS_ERR_INPUT,
                          "shift on '%s', which is a named expression (let NAME = ...), not a sequence", e->name);
        if (x->visiting[k])
            return err_at(x, e, RS_ERR_INPUT, "'%s' is defined in terms of itself", e->name);
        x->visiting[k] = 1;
        r = eval(out, l->e, x);
        x->visiting[k] = 0;
        if (r != RS_OK) return r;
        if (l->shifted && lin_has_unknowns(out, s->ctx))
            out->low += e->shift - l->shift;
        return RS_OK;
    }
    if (x->ivar >= 0 && strcmp(e->name, "i") == 0) {
        /* the imaginary unit (a char line over Q(i)[params]; reduced by i^2 = -1 later) */
        if (e->shifted)
            return err_at(x, e, RS_ERR_INPUT, "shift on '%s' (the imaginary unit)", e->name);
        fmpq_mpoly_gen(out->c + 0, x->ivar, s->ctx);
        return RS_OK;
    }
    if (x->allow_lambda == 2 && strcmp(e->name, "z") == 0) {
        /* `expect bilinear`: z takes the place of lambda */
        if (e->shifted)
            return err_at(x, e, RS_ERR_INPUT, "shift on '%s'", e->name);
        fmpq_mpoly_gen(out->c + 0, s->lambda_var, s->ctx);
        return RS_OK;
    }
    if (x->allow_lambda == 2 && strcmp(e->name, "lambda") == 0)
        return err_at(x, e, RS_ERR_INPUT, "expected a polynomial in z here, found '%s'", e->name);
    if (strcmp(e->name, "lambda") == 0) {
        if (!x->allow_lambda)
            return err_at(x, e, RS_ERR_INPUT,
                          "'%s' is reserved: it appears only in char and expect lines (write x[n+1] for a shift)", e->name);
        if (e->shifted)
            return err_at(x, e, RS_ERR_INPUT, "shift on '%s'", e->name);
        fmpq_mpoly_gen(out->c + 0, s->lambda_var, s->ctx);
        return RS_OK;
    }
    if (rs_name_is_reserved(e->name))
        return err_at(x, e, RS_ERR_INPUT, "'%s' is reserved and has no value here", e->name);
    return err_at(x, e, RS_ERR_INPUT,
                  "unknown name '%s' (expected a declared param, unknown or let)", e->name);
}

static int const_integer(slong *k, const lin_t *v, const rs_expr_t *e, ev_t *x)
{
    fmpq_t q;
    const fmpq_mpoly_ctx_struct *ctx = x->s->ctx;
    if (lin_has_unknowns(v, ctx) || !fmpq_mpoly_is_fmpq(v->c + 0, ctx) || !fmpq_mpoly_is_fmpq(v->den, ctx))
        return err_at(x, e, RS_ERR_INPUT, "expected a constant integer power, found %s",
                      "an expression with names");
    fmpq_init(q);
    if (!fmpq_mpoly_is_zero(v->c + 0, ctx)) {
        fmpq_t d;
        fmpq_init(d);
        fmpq_mpoly_get_fmpq(q, v->c + 0, ctx);
        fmpq_mpoly_get_fmpq(d, v->den, ctx);
        fmpq_div(q, q, d);
        fmpq_clear(d);
    }
    if (!fmpz_is_one(fmpq_denref(q))) {
        fmpq_clear(q);
        return err_at(x, e, RS_ERR_INPUT, "expected an integer power, found %s", "a fraction");
    }
    if (fmpz_bits(fmpq_numref(q)) > 20 || fmpz_get_si(fmpq_numref(q)) > RS_EXPR_MAX_POW
        || fmpz_get_si(fmpq_numref(q)) < -RS_EXPR_MAX_POW) {
        fmpq_clear(q);
        return err_at(x, e, RS_ERR_LIMIT, "power too large (limit |k| <= %s)", "100000");
    }
    *k = fmpz_get_si(fmpq_numref(q));
    fmpq_clear(q);
    return RS_OK;
}

/* out = a / b with b free of unknowns (and of lambda). */
static int lin_div(lin_t *out, lin_t *a, lin_t *b, const rs_expr_t *e, ev_t *x)
{
    const rs_scheme_struct *s = x->s;
    slong i;
    if (lin_has_unknowns(b, s->ctx))
        return err_at(x, e, RS_ERR_INPUT, "division by an expression with unknowns%s (the scheme must be linear)", "");
    if (fmpq_mpoly_degree_si(b->c + 0, s->lambda_var, s->ctx) > 0)
        return err_at(x, e, RS_ERR_INPUT, "division by an expression in lambda%s; multiply through instead", "");
    if (fmpq_mpoly_is_zero(b->c + 0, s->ctx))
        return err_at(x, e, RS_ERR_INPUT, "division by zero%s", "");
    for (i = 0; i < out->ns; i++)
        if (prod_check(x, e, a->c + i, b->den, 0) != RS_OK) return x->err->code;
    if (prod_check(x, e, a->den, b->c + 0, 0) != RS_OK) return x->err->code;
    /* (a/da) / (b0/db) = (a*db) / (da*b0) */
    for (i = 0; i < out->ns; i++)
        fmpq_mpoly_mul(out->c + i, a->c + i, b->den, s->ctx);
    out->low = a->low;
    fmpq_mpoly_mul(out->den, a->den, b->c + 0, s->ctx);
    record_nonzero(x, b->c + 0, rs_expr_file(e, x->c->path), e->line, e->col);
    return RS_OK;
}

static int eval_node(lin_t *out, const rs_expr_t *e, ev_t *x);

/* sin(K*theta), cos(K*theta) for an angle parameter theta (its variable is
 * t = tan(theta/2)) and an integer K: cos(K theta) + i sin(K theta) =
 * (1 + i t)^(2K) / (1 + t^2)^K (de Moivre with e^(i theta) = (1 + i t)/(1 - i t)),
 * so both are exact rational functions of t over the positive (1 + t^2)^K. */
static int eval_trig(lin_t *out, const rs_expr_t *e, ev_t *x)
{
    const rs_scheme_struct *s = x->s;
    const fmpq_mpoly_ctx_struct *ctx = s->ctx;
    lin_t a;
    slong v = -1, k = 0, K, j;
    int r, is_sin = strcmp(e->name, "sin") == 0;
    fmpq_t c;
    fmpz_t bin;
    lin_init(&a, out->ns, ctx);
    r = eval(&a, e->a, x);
    if (r == RS_OK && !lin_has_unknowns(&a, ctx) && fmpq_mpoly_is_zero(a.c + 0, ctx)) {
        /* sin(0) = 0, cos(0) = 1 */
        lin_clear(&a, ctx);
        if (is_sin) fmpq_mpoly_zero(out->c + 0, ctx);
        else fmpq_mpoly_one(out->c + 0, ctx);
        fmpq_mpoly_one(out->den, ctx);
        return RS_OK;
    }
    if (r == RS_OK) {
        /* the argument must be K * theta exactly */
        int ok = !lin_has_unknowns(&a, ctx) && fmpq_mpoly_is_fmpq(a.den, ctx)
                 && fmpq_mpoly_length(a.c + 0, ctx) == 1 && fmpq_mpoly_total_degree_si(a.c + 0, ctx) == 1;
        fmpq_init(c);
        if (ok) {
            fmpq_t d;
            for (j = 0; j < s->lambda_var; j++)
                if (fmpq_mpoly_degree_si(a.c + 0, j, ctx) == 1) v = j;
            ok = v >= 0 && x->c->params[v].angle;
            fmpq_init(d);
            fmpq_mpoly_get_term_coeff_fmpq(c, a.c + 0, 0, ctx);
            fmpq_mpoly_get_fmpq(d, a.den, ctx);
            fmpq_div(c, c, d);
            fmpq_clear(d);
            ok = ok && fmpz_is_one(fmpq_denref(c)) && fmpz_bits(fmpq_numref(c)) <= 10 && FLINT_ABS(fmpz_get_si(fmpq_numref(c))) <= 1000;
            if (ok) k = fmpz_get_si(fmpq_numref(c));
        }
        fmpq_clear(c);
        if (!ok)
            r = rs_error_set_at(x->err, RS_ERR_INPUT, rs_expr_file(e, x->c->path), e->a->line, e->a->col,
                                "expected an angle parameter (param NAME angle) or an integer multiple of one "
                                "(K*NAME, |K| <= 1000) inside %s(...)", e->name);
    }
    lin_clear(&a, ctx);
    if (r != RS_OK) return r;
    K = k < 0 ? -k : k;
    fmpq_init(c);
    fmpz_init(bin);
    fmpq_mpoly_zero(out->c + 0, ctx);
    for (j = 0; j <= 2 * K; j++) {
        /* (i t)^j = i^j t^j: even j feed cos with sign (-1)^(j/2), odd j feed sin with (-1)^((j-1)/2) */
        ulong *ex;
        if ((j & 1) != is_sin) continue;
        fmpz_bin_uiui(bin, (ulong) (2 * K), (ulong) j);
        if (((is_sin ? j - 1 : j) / 2) & 1) fmpz_neg(bin, bin);
        if (is_sin && k < 0) fmpz_neg(bin, bin);
        fmpq_set_fmpz(c, bin);
        ex = flint_calloc(s->nvars, sizeof(ulong));
        ex[v] = (ulong) j;
        {
            fmpq_mpoly_t term;
            fmpq_mpoly_init(term, ctx);
            fmpq_mpoly_set_coeff_fmpq_ui(term, c, ex, ctx);
            fmpq_mpoly_add(out->c + 0, out->c + 0, term, ctx);
            fmpq_mpoly_clear(term, ctx);
        }
        flint_free(ex);
    }
    {
        fmpq_mpoly_t one_t2;
        fmpq_mpoly_init(one_t2, ctx);
        fmpq_mpoly_gen(one_t2, v, ctx);
        fmpq_mpoly_mul(one_t2, one_t2, one_t2, ctx);
        fmpq_mpoly_add_si(one_t2, one_t2, 1, ctx);
        fmpq_mpoly_pow_ui(out->den, one_t2, (ulong) K, ctx);
        fmpq_mpoly_clear(one_t2, ctx);
    }
    fmpz_clear(bin);
    fmpq_clear(c);
    return RS_OK;
}

/* sqrt(d) of a model over Q(sqrt d): its variable (reduced by s^2 = d
 * where the entries are stored) */
static int eval_sqrt(lin_t *out, const rs_expr_t *e, ev_t *x)
{
    lin_t a;
    slong k = 0;
    int r;
    lin_init(&a, out->ns, x->s->ctx);
    r = eval(&a, e->a, x);
    if (r == RS_OK) r = const_integer(&k, &a, e, x);
    lin_clear(&a, x->s->ctx);
    if (r != RS_OK) return r;
    if (k != x->s->sqrt_d)
        return rs_error_set_at(x->err, RS_ERR_INPUT, rs_expr_file(e, x->c->path), e->line, e->col,
                               "expected sqrt(%ld) (the case's coefficients are in Q(sqrt %ld)), found another root",
                               (long) x->s->sqrt_d, (long) x->s->sqrt_d);
    fmpq_mpoly_gen(out->c + 0, x->s->sqrt_var, x->s->ctx);
    return RS_OK;
}

static int eval(lin_t *out, const rs_expr_t *e, ev_t *x)
{
    int r;
    slong i;
    if (++x->steps > RS_SCHEME_MAX_STEPS)
        return rs_error_set_at(x->err, RS_ERR_LIMIT, rs_expr_file(e, x->c->path), e->line, e->col,
                               "expression too large after expanding lets (limit %d operations)",
                               RS_SCHEME_MAX_STEPS);
    if (x->depth >= RS_SCHEME_MAX_DEPTH)
        return rs_error_set_at(x->err, RS_ERR_LIMIT, rs_expr_file(e, x->c->path), e->line, e->col,
                               "expression too deep after expanding lets (limit %d levels)",
                               RS_SCHEME_MAX_DEPTH);
    x->depth++;
    r = eval_node(out, e, x);
    x->depth--;
    for (i = 0; r == RS_OK && i <= out->ns; i++) {
        const fmpq_mpoly_struct *p = i < out->ns ? out->c + i : out->den;
        if (fmpq_mpoly_length(p, x->s->ctx) > RS_SCHEME_MAX_TERMS)
            r = rs_error_set_at(x->err, RS_ERR_LIMIT, rs_expr_file(e, x->c->path), e->line, e->col,
                                "term limit exceeded: %ld terms (limit %d terms per polynomial)",
                                (long) fmpq_mpoly_length(p, x->s->ctx), RS_SCHEME_MAX_TERMS);
    }
    return r;
}

static int eval_node(lin_t *out, const rs_expr_t *e, ev_t *x)
{
    const rs_scheme_struct *s = x->s;
    const fmpq_mpoly_ctx_struct *ctx = s->ctx;
    lin_t a, b;
    int r = RS_OK;
    slong i;
    switch (e->kind) {
    case RS_EXPR_NUM:
        fmpq_mpoly_set_fmpq(out->c + 0, e->num, ctx);
        return RS_OK;
    case RS_EXPR_NAME:
        return eval_name(out, e, x);
    case RS_EXPR_CALL:
        if (unknown_index(s, e->name) >= 0 || rs_case_let_index(x->c, e->name) >= 0
            || rs_case_param_index(x->c, e->name) >= 0)
            return err_at(x, e, RS_ERR_INPUT,
                          "expected a shift in square brackets after '%s', as in x[n+1], found '('", e->name);
        if (strcmp(e->name, "sin") == 0 || strcmp(e->name, "cos") == 0)
            return eval_trig(out, e, x);
        if (s->sqrt_d > 0 && strcmp(e->name, "sqrt") == 0)
            return eval_sqrt(out, e, x);
        return err_at(x, e, RS_ERR_INPUT,
                      "the function %s(...) is not polynomial: exact analyses need polynomial entries "
                      "(a numeric `recurrence` case allows it for radius)", e->name);
    default:
        break;
    }
    lin_init(&a, out->ns, ctx);
    lin_init(&b, out->ns, ctx);
    r = eval(&a, e->a, x);
    if (r == RS_OK && e->b != NULL)
        r = eval(&b, e->b, x);
    if (r != RS_OK) goto done;
    switch (e->kind) {
    case RS_EXPR_NEG:
        for (i = 0; i < out->ns; i++) fmpq_mpoly_neg(out->c + i, a.c + i, ctx);
        fmpq_mpoly_set(out->den, a.den, ctx);
        out->low = a.low;
        break;
    case RS_EXPR_ADD:
    case RS_EXPR_SUB:
        r = lin_addsub(out, &a, &b, e->kind == RS_EXPR_SUB, x, e);
        break;
    case RS_EXPR_MUL: {
        int au = lin_has_unknowns(&a, ctx), bu = lin_has_unknowns(&b, ctx);
        lin_t *u, *k;
        if (au && bu) {
            r = err_at(x, e, RS_ERR_INPUT, "product of two unknowns%s: the scheme must be linear", "");
            break;
        }
        u = au ? &a : &b;   /* the factor that may carry unknowns */
        k = au ? &b : &a;   /* the factor without unknowns */
        for (i = 0; i < out->ns && r == RS_OK; i++)
            r = prod_check(x, e, u->c + i, k->c + 0, 0);
        if (r == RS_OK) r = prod_check(x, e, a.den, b.den, 0);
        if (r != RS_OK) break;
        for (i = 0; i < out->ns; i++)
            fmpq_mpoly_mul(out->c + i, u->c + i, k->c + 0, ctx);
        fmpq_mpoly_mul(out->den, a.den, b.den, ctx);
        out->low = u->low;
        r = degree_ok(x, e, out->c + 0);
        break;
    }
    case RS_EXPR_DIV:
        r = lin_div(out, &a, &b, e, x);
        break;
    case RS_EXPR_POW: {
        slong k = 0;
        r = const_integer(&k, &b, e, x);
        if (r != RS_OK) break;
        if (lin_has_unknowns(&a, ctx)) {
            if (k != 1) {
                r = err_at(x, e, RS_ERR_INPUT, "power of an unknown%s: the scheme must be linear", "");
                break;
            }
            for (i = 0; i < out->ns; i++) fmpq_mpoly_set(out->c + i, a.c + i, ctx);
            fmpq_mpoly_set(out->den, a.den, ctx);
            out->low = a.low;
            break;
        }
        {
            slong v, kk = k < 0 ? -k : k;
            for (v = 0; v < s->nvars; v++) {
                slong d = fmpq_mpoly_degree_si(a.c + 0, v, ctx);
                slong dd = fmpq_mpoly_degree_si(a.den, v, ctx);
                if (dd > d) d = dd;
                if (d > 0 && kk > RS_SCHEME_MAX_DEGREE / d) {
                    r = err_at(x, e, RS_ERR_LIMIT,
                               "degree limit exceeded: this power has degree over 4096 in '%s' (limit 4096 per variable)", s->vars[v]);
                    break;
                }
            }
            if (r == RS_OK && kk > 1) r = prod_check(x, e, a.c + 0, NULL, (ulong) kk);
            if (r == RS_OK && kk > 1) r = prod_check(x, e, a.den, NULL, (ulong) kk);
            if (r != RS_OK) break;
            if (k < 0 && fmpq_mpoly_is_zero(a.c + 0, ctx)) {
                r = err_at(x, e, RS_ERR_INPUT, "division by zero (0 to a negative power)%s", "");
                break;
            }
            if (k >= 0) {
                fmpq_mpoly_pow_ui(out->c + 0, a.c + 0, (ulong) k, ctx);
                fmpq_mpoly_pow_ui(out->den, a.den, (ulong) k, ctx);
            } else {
                if (fmpq_mpoly_degree_si(a.c + 0, s->lambda_var, ctx) > 0) {
                    r = err_at(x, e, RS_ERR_INPUT, "negative power of an expression in lambda%s", "");
                    break;
                }
                fmpq_mpoly_pow_ui(out->c + 0, a.den, (ulong) kk, ctx);
                fmpq_mpoly_pow_ui(out->den, a.c + 0, (ulong) kk, ctx);
                record_nonzero(x, a.c + 0, rs_expr_file(e, x->c->path), e->line, e->col);
            }
        }
        break;
    }
    default:
        r = rs_error_set(x->err, RS_ERR_INTERNAL, "bad expression node");
    }
done:
    lin_clear(&a, ctx);
    lin_clear(&b, ctx);
    return r;
}

void rs_scheme_init(rs_scheme_t s)
{
    memset(s, 0, sizeof(rs_scheme_struct));
}

void rs_scheme_clear(rs_scheme_t s)
{
    slong i;
    if (s->vars == NULL)
        return;
    for (i = 0; i < s->n * s->n; i++) fmpq_mpoly_clear(s->M + i, s->ctx);
    flint_free(s->M);
    flint_free(s->row_shift);
    fmpq_mpoly_clear(s->charpoly, s->ctx);
    for (i = 0; i < s->nnonzero; i++) {
        fmpq_mpoly_clear(s->nonzero + i, s->ctx);
        flint_free(s->nonzero_text[i]);
    }
    flint_free(s->nonzero);
    flint_free(s->nonzero_text);
    flint_free(s->nonzero_loc);
    fmpq_mpoly_ctx_clear(s->ctx);
    fmpz_mpoly_ctx_clear(s->zctx);
    for (i = 0; i < s->nvars; i++) flint_free(s->vars[i]);
    flint_free(s->vars);
    for (i = 0; i < s->n; i++) flint_free(s->unknowns[i]);
    flint_free(s->unknowns);
    memset(s, 0, sizeof(rs_scheme_struct));
}

static void setup_ctx(rs_scheme_t s, const rs_case_t c, slong sqrt_d)
{
    slong i;
    s->nvars = c->nparams + 1 + (sqrt_d > 0);
    s->lambda_var = c->nparams;
    s->vars = flint_malloc(s->nvars * sizeof(char *));
    for (i = 0; i < c->nparams; i++) {
        s->vars[i] = flint_malloc(strlen(c->params[i].name) + 1);
        strcpy(s->vars[i], c->params[i].name);
    }
    s->vars[s->lambda_var] = flint_malloc(7);
    strcpy(s->vars[s->lambda_var], "lambda");
    s->sqrt_d = sqrt_d;
    s->sqrt_var = -1;
    if (sqrt_d > 0) {
        char b[40];
        snprintf(b, sizeof b, "sqrt(%ld)", (long) sqrt_d);
        s->sqrt_var = c->nparams + 1;
        s->vars[s->sqrt_var] = rs_strdup(b);
    }
    fmpq_mpoly_ctx_init(s->ctx, s->nvars, ORD_LEX);
    fmpz_mpoly_ctx_init(s->zctx, s->nvars, ORD_LEX);
    fmpq_mpoly_init(s->charpoly, s->ctx);
}

slong rs_scheme_min_degree(const fmpz_mpoly_t p, slong var, const fmpz_mpoly_ctx_t ctx)
{
    slong i, n = fmpz_mpoly_length(p, ctx), best = WORD_MAX;
    slong *exp = flint_malloc(ctx->minfo->nvars * sizeof(slong));
    for (i = 0; i < n; i++) {
        fmpz_mpoly_get_term_exp_si(exp, p, i, ctx);
        if (exp[var] < best) best = exp[var];
    }
    flint_free(exp);
    return n == 0 ? 0 : best;
}

static void ev_setup(ev_t *x, const rs_scheme_struct *s, const rs_case_struct *c, int allow_lambda,
                     rs_scheme_struct *collect, rs_error_struct *err)
{
    x->s = s;
    x->c = c;
    x->allow_lambda = allow_lambda;
    x->visiting = flint_calloc(c->nlets + 1, sizeof(int));
    x->err = err;
    x->collect = collect;
    x->depth = 0;
    x->steps = 0;
    x->ivar = -1;
}

int rs_scheme_eval_poly(fmpq_mpoly_t num, fmpq_mpoly_t den, const rs_scheme_t s,
                        const rs_case_t c, const rs_expr_t *e, int allow_lambda, rs_error_t err)
{
    ev_t x;
    lin_t v;
    int r;
    ev_setup(&x, s, c, allow_lambda, NULL, err);
    lin_init(&v, s->n + 1, s->ctx);
    r = eval(&v, e, &x);
    if (r == RS_OK && lin_has_unknowns(&v, s->ctx))
        r = rs_error_set_at(err, RS_ERR_INPUT, rs_expr_file(e, c->path), e->line, e->col,
                            "expected an expression without unknowns");
    if (r == RS_OK) {
        fmpq_mpoly_set(num, v.c + 0, s->ctx);
        fmpq_mpoly_set(den, v.den, s->ctx);
    }
    lin_clear(&v, s->ctx);
    flint_free(x.visiting);
    return r;
}

/* e evaluated over Q(i): in (s's variables, i), then reduced by i^2 = -1
 * into (re + i im)/den over s's context; a division by a complex expression
 * is an input error at (file, line, col) naming what was expected. */
static int eval_cx(fmpq_mpoly_t re, fmpq_mpoly_t im, fmpq_mpoly_t den, const rs_scheme_struct *s,
                   const rs_case_struct *c, const rs_expr_t *e, int allow_lambda, rs_error_struct *err,
                   const char *what, const char *file, int line, int col)
{
    rs_scheme_t s2;
    ev_t x;
    lin_t v;
    slong i, n, iv = s->nvars;
    int r;
    rs_scheme_init(s2);
    s2->nvars = s->nvars + 1;
    s2->lambda_var = s->lambda_var;
    s2->vars = flint_malloc(s2->nvars * sizeof(char *));
    for (i = 0; i < s->nvars; i++) s2->vars[i] = rs_strdup(s->vars[i]);
    s2->vars[iv] = rs_strdup("i");
    fmpq_mpoly_ctx_init(s2->ctx, s2->nvars, ORD_LEX);
    fmpz_mpoly_ctx_init(s2->zctx, s2->nvars, ORD_LEX);
    fmpq_mpoly_init(s2->charpoly, s2->ctx);
    ev_setup(&x, s2, c, allow_lambda, NULL, err);
    x.ivar = iv;
    lin_init(&v, 1, s2->ctx);
    r = eval(&v, e, &x);
    if (r == RS_OK && fmpq_mpoly_degree_si(v.den, iv, s2->ctx) > 0)
        r = rs_error_set_at(err, RS_ERR_INPUT, file, line, col, "expected %s without division by a complex "
                            "expression (multiply through by its conjugate)", what);
    if (r == RS_OK) {
        ulong *ex2 = flint_malloc(s2->nvars * sizeof(ulong));
        fmpq_mpoly_t term;
        fmpq_t q;
        int part;
        fmpq_init(q);
        fmpq_mpoly_init(term, s->ctx);
        fmpq_mpoly_zero(re, s->ctx);
        fmpq_mpoly_zero(im, s->ctx);
        fmpq_mpoly_zero(den, s->ctx);
        for (part = 0; part < 2; part++) {   /* the numerator, then the denominator (no i in it) */
            const fmpq_mpoly_struct *src = part ? v.den : v.c + 0;
            n = fmpq_mpoly_length(src, s2->ctx);
            for (i = 0; i < n; i++) {
                ulong ei;
                fmpq_mpoly_get_term_coeff_fmpq(q, src, i, s2->ctx);
                fmpq_mpoly_get_term_exp_ui(ex2, src, i, s2->ctx);
                ei = ex2[iv];
                if (ei & 2) fmpq_neg(q, q);
                fmpq_mpoly_set_coeff_fmpq_ui(term, q, ex2, s->ctx);   /* the first nvars exponents */
                if (part) fmpq_mpoly_add(den, den, term, s->ctx);
                else fmpq_mpoly_add((ei & 1) ? im : re, (ei & 1) ? im : re, term, s->ctx);
                fmpq_mpoly_zero(term, s->ctx);
            }
        }
        fmpq_mpoly_clear(term, s->ctx);
        fmpq_clear(q);
        flint_free(ex2);
    }
    lin_clear(&v, s2->ctx);
    flint_free(x.visiting);
    rs_scheme_clear(s2);
    return r;
}

int rs_scheme_eval_poly_cx(fmpq_mpoly_t re, fmpq_mpoly_t im, fmpq_mpoly_t den, const rs_scheme_t s,
                           const rs_case_t c, const rs_expr_t *e, int allow_lambda, rs_error_t err)
{
    return eval_cx(re, im, den, s, c, e, allow_lambda, err, "a polynomial", rs_expr_file(e, c->path),
                   e->line, e->col);
}

/* Divides out the factors 1 + t^2 of angle parameters (positive for every
 * real t), so they are not recorded as assumptions. */
static void strip_angle_den(fmpq_mpoly_t den, const rs_scheme_struct *s, const rs_case_struct *c)
{
    slong v;
    fmpq_mpoly_t f, q;
    fmpq_mpoly_init(f, s->ctx);
    fmpq_mpoly_init(q, s->ctx);
    for (v = 0; v < c->nparams; v++) {
        if (!c->params[v].angle) continue;
        fmpq_mpoly_gen(f, v, s->ctx);
        fmpq_mpoly_mul(f, f, f, s->ctx);
        fmpq_mpoly_add_si(f, f, 1, s->ctx);
        while (!fmpq_mpoly_is_fmpq(den, s->ctx) && fmpq_mpoly_divides(q, den, f, s->ctx))
            fmpq_mpoly_swap(den, q, s->ctx);
    }
    fmpq_mpoly_clear(f, s->ctx);
    fmpq_mpoly_clear(q, s->ctx);
}

/* does the name i (the imaginary unit: reserved) appear in e or in a let? */
static int uses_i(const rs_expr_t *e, const rs_case_struct *c)
{
    if (e == NULL) return 0;
    if (e->kind == RS_EXPR_NAME && strcmp(e->name, "i") == 0)
        return 1;
    return uses_i(e->a, c) || uses_i(e->b, c);
}

static int lets_use_i(const rs_case_struct *c)
{
    slong k;
    for (k = 0; k < c->nlets; k++)
        if (uses_i(c->lets[k].e, c)) return 1;
    return 0;
}

/* A `char` line with the imaginary unit: p = A + i B over Q[params][lambda]
 * becomes the real 2x2 lambda-matrix [[A, -B], [B, A]] (the real and
 * imaginary parts of the complex recurrence).  Its det is p conj(p) = A^2 + B^2
 * (the roots of p and their conjugates: same moduli), and unlike the scalar
 * p conj(p) it keeps p's Jordan structure (it is similar to diag(p, conj p)
 * over C), so a simple root of p on the circle that is also a root of conj(p)
 * (a real root, or a conjugate pair of roots of p) counts as semisimple, not
 * as a double root. */
static int build_char_complex(rs_scheme_t s, const rs_model_t m, rs_error_t err)
{
    const rs_case_struct *c = m->c;
    ev_t x;
    fmpq_mpoly_t A, B, den;
    slong i, np = c->nparams;
    int r;
    const char *file = c->charloc.file ? c->charloc.file : c->path;
    fmpq_mpoly_init(A, s->ctx); fmpq_mpoly_init(B, s->ctx); fmpq_mpoly_init(den, s->ctx);
    r = eval_cx(A, B, den, s, c, c->charexpr, 1, err, "a char line", file, c->charloc.line, c->charloc.col);
    if (r == RS_OK) {
        strip_angle_den(den, s, c);
        memset(&x, 0, sizeof x);
        x.collect = s;   /* record_nonzero reads only where to collect */
        record_nonzero(&x, den, file, c->charloc.line, c->charloc.col);
        if (fmpq_mpoly_is_zero(A, s->ctx) && fmpq_mpoly_is_zero(B, s->ctx))
            r = rs_error_set_at(err, RS_ERR_MATH, file, c->charloc.line, c->charloc.col,
                                "the characteristic polynomial is identically zero%s", "");
        else if (fmpq_mpoly_degree_si(A, np, s->ctx) < 1 && fmpq_mpoly_degree_si(B, np, s->ctx) < 1)
            r = rs_error_set_at(err, RS_ERR_INPUT, file, c->charloc.line, c->charloc.col,
                                "expected a polynomial in lambda, found one without lambda%s", "");
        if (fmpq_mpoly_is_zero(B, s->ctx)) {
            /* i cancelled: an ordinary real char line */
            fmpq_mpoly_set(s->charpoly, A, s->ctx);
            s->from_char = 1;
        } else {
            s->n = 2;
            s->unknowns = flint_malloc(2 * sizeof(char *));
            s->unknowns[0] = rs_strdup("re");
            s->unknowns[1] = rs_strdup("im");
            s->M = flint_malloc(4 * sizeof(fmpq_mpoly_struct));
            for (i = 0; i < 4; i++) fmpq_mpoly_init(s->M + i, s->ctx);
            fmpq_mpoly_set(s->M + 0, A, s->ctx);
            fmpq_mpoly_neg(s->M + 1, B, s->ctx);
            fmpq_mpoly_set(s->M + 2, B, s->ctx);
            fmpq_mpoly_set(s->M + 3, A, s->ctx);
            s->row_shift = flint_calloc(2, sizeof(slong));
            s->from_char = 0;
            s->complex_char = 1;
        }
    }
    fmpq_mpoly_clear(A, s->ctx); fmpq_mpoly_clear(B, s->ctx); fmpq_mpoly_clear(den, s->ctx);
    return r;
}

static int build_char(rs_scheme_t s, const rs_model_t m, rs_error_t err)
{
    const rs_case_struct *c = m->c;
    ev_t x;
    lin_t v;
    int r;
    if (m->neqs > 0 || m->nunknowns > 0)
        return rs_error_set_at(err, RS_ERR_INPUT, c->charloc.file ? c->charloc.file : c->path, c->charloc.line, c->charloc.col,
                               "a case gives either `char` or `unknown`/`eq` lines, not both");
    ev_setup(&x, s, c, 1, s, err);
    lin_init(&v, 1, s->ctx);
    r = eval(&v, c->charexpr, &x);
    if (r == RS_OK) {
        strip_angle_den(v.den, s, c);
        record_nonzero(&x, v.den, c->charloc.file ? c->charloc.file : c->path, c->charloc.line, c->charloc.col);
        fmpq_mpoly_set(s->charpoly, v.c + 0, s->ctx);
        if (fmpq_mpoly_is_zero(s->charpoly, s->ctx))
            r = rs_error_set_at(err, RS_ERR_MATH, c->charloc.file ? c->charloc.file : c->path, c->charloc.line, c->charloc.col,
                                "the characteristic polynomial is identically zero");
        else if (fmpq_mpoly_degree_si(s->charpoly, s->lambda_var, s->ctx) < 1)
            r = rs_error_set_at(err, RS_ERR_INPUT, c->charloc.file ? c->charloc.file : c->path, c->charloc.line, c->charloc.col,
                                "expected a polynomial in lambda, found one without lambda");
    }
    s->from_char = 1;
    lin_clear(&v, s->ctx);
    flint_free(x.visiting);
    return r;
}

/* The lowest shift at which e (plus off) writes an unknown, through lets; WORD_MAX
 * for none.  Zero coefficients count: (0)*x1[n] writes x1[n].  Walked after
 * eval succeeded on e, so lets are acyclic and the walk costs no more than eval. */
static slong written_low(const rs_expr_t *e, const ev_t *x, slong off)
{
    slong k, a, b;
    if (e == NULL) return WORD_MAX;
    if (e->kind == RS_EXPR_NAME) {
        if (unknown_index(x->s, e->name) >= 0)
            return e->shifted ? e->shift + off : WORD_MAX;
        if ((k = rs_case_let_index(x->c, e->name)) >= 0) {
            const rs_let_t *l = &x->c->lets[k];
            return written_low(l->e, x, off + (l->shifted ? e->shift - l->shift : 0));
        }
        return WORD_MAX;
    }
    a = written_low(e->a, x, off);
    b = written_low(e->b, x, off);
    return FLINT_MIN(a, b);
}

int rs_scheme_build(rs_scheme_t s, const rs_model_t m, rs_error_t err)
{
    const rs_case_struct *c = m->c;
    ev_t x;
    slong i, j, n = m->nunknowns;
    int r = RS_OK;
    rs_scheme_clear(s);
    if (c == NULL || m->kind != RS_MODEL_EQUATIONS)
        return rs_error_set(err, RS_ERR_INTERNAL, "the lambda-matrix is built from an equations model "
                            "(rs_model_lower)%s", "");
    setup_ctx(s, c, m->qd != NULL ? m->qd->d : 0);
    if (c->charexpr != NULL) {
        if (m->neqs > 0 || m->nunknowns > 0)
            return build_char(s, m, err);   /* reports the mix */
        return uses_i(c->charexpr, c) || lets_use_i(c) ? build_char_complex(s, m, err) : build_char(s, m, err);
    }
    if (n == 0)
        return rs_error_set_at(err, RS_ERR_INPUT, c->path, 1, 1,
                               "expected `unknown` and `eq` lines (or a `char` line), found none");
    if (n > RS_SCHEME_MAX_UNKNOWNS)
        return rs_error_set_at(err, RS_ERR_LIMIT, m->unknown_loc.file ? m->unknown_loc.file : c->path, m->unknown_loc.line, m->unknown_loc.col,
                               "too many unknowns (%ld; limit %d)", (long) n, RS_SCHEME_MAX_UNKNOWNS);
    if (m->neqs != n) {
        const rs_loc_t *l = m->neqs > n ? &m->eqs[n].loc : &m->unknown_loc;
        return rs_error_set_at(err, RS_ERR_INPUT, l->file, l->line, l->col,
                               "expected as many equations as unknowns (%ld unknowns), found %ld equations",
                               (long) n, (long) m->neqs);
    }
    s->n = n;
    s->unknowns = flint_malloc(n * sizeof(char *));
    for (i = 0; i < n; i++) s->unknowns[i] = rs_strdup(m->unknowns[i].name);
    s->M = flint_malloc(n * n * sizeof(fmpq_mpoly_struct));
    for (i = 0; i < n * n; i++) fmpq_mpoly_init(s->M + i, s->ctx);
    s->row_shift = flint_calloc(n, sizeof(slong));
    ev_setup(&x, s, c, 0, s, err);
    for (i = 0; i < n && r == RS_OK; i++) {
        lin_t lhs, rhs, v;
        const rs_eq_t *q = &m->eqs[i];
        slong rowmin = WORD_MAX;
        lin_init(&lhs, n + 1, s->ctx);
        lin_init(&rhs, n + 1, s->ctx);
        lin_init(&v, n + 1, s->ctx);
        r = eval(&lhs, q->lhs, &x);
        if (r == RS_OK) r = eval(&rhs, q->rhs, &x);
        if (r == RS_OK) r = lin_addsub(&v, &lhs, &rhs, 1, &x, q->lhs);
        if (r == RS_OK && !lin_has_unknowns(&v, s->ctx))
            r = rs_error_set_at(err, RS_ERR_INPUT, q->loc.file, q->loc.line, q->loc.col,
                                "expected an equation involving an unknown, found one without any "
                                "(after simplification)");
        if (r == RS_OK && !fmpq_mpoly_is_zero(v.c + 0, s->ctx))
            r = rs_error_set_at(err, RS_ERR_INPUT, q->loc.file, q->loc.line, q->loc.col,
                                "expected a homogeneous equation, found a term without unknowns "
                                "(stability concerns the homogeneous recurrence: drop forcing terms)");
        if (r == RS_OK && s->sqrt_d > 0 && fmpq_mpoly_degree_si(v.den, s->sqrt_var, s->ctx) > 0)
            r = rs_error_set_at(err, RS_ERR_INPUT, q->loc.file, q->loc.line, q->loc.col,
                                "expected no division by an expression with sqrt(%ld)", (long) s->sqrt_d);
        if (r == RS_OK) {
            record_nonzero(&x, v.den, q->loc.file ? q->loc.file : c->path, q->loc.line, q->loc.col);
            for (j = 0; j < n; j++)
                if (!fmpq_mpoly_is_zero(v.c + 1 + j, s->ctx)) {
                    slong low = v.low + rs_scheme_min_degree(v.c[1 + j].zpoly, s->lambda_var, s->ctx->zctx);
                    if (low < rowmin) rowmin = low;
                }
            /* an equation holds from the lowest shift it writes: x3[n+1] = 0*x1[n] + ... is a
             * zero row of x[n+1] = M x[n] (x3[0] free, a root at 0), not x3[n] = 0 */
            rowmin = FLINT_MIN(rowmin, FLINT_MIN(written_low(q->lhs, &x, 0), written_low(q->rhs, &x, 0)));
            s->row_shift[i] = rowmin;
            for (j = 0; j < n; j++) {
                fmpq_mpoly_struct *M = s->M + i * n + j;
                slong d = v.low - rowmin;
                fmpq_mpoly_set(M, v.c + 1 + j, s->ctx);
                if (s->sqrt_d > 0) {   /* p0 + sqrt(d) p1 */
                    rs_scheme_reduce_sqrt(M->zpoly, s);
                    fmpq_mpoly_reduce(M, s->ctx);
                }
                if (fmpq_mpoly_is_zero(M, s->ctx)) continue;
                if (d >= 0) {
                    mul_lambda_pow(M, d, s);
                } else {
                    fmpq_mpoly_t g;
                    fmpq_mpoly_init(g, s->ctx);
                    fmpq_mpoly_gen(g, s->lambda_var, s->ctx);
                    fmpq_mpoly_pow_ui(g, g, (ulong) (-d), s->ctx);
                    fmpq_mpoly_divides(M, M, g, s->ctx);
                    fmpq_mpoly_clear(g, s->ctx);
                }
                if (fmpq_mpoly_degree_si(M, s->lambda_var, s->ctx) > RS_SCHEME_MAX_DEGREE)
                    r = rs_error_set_at(err, RS_ERR_LIMIT, q->loc.file, q->loc.line, q->loc.col,
                                        "degree limit exceeded: shifts span %ld steps (limit %d)",
                                        (long) fmpq_mpoly_degree_si(M, s->lambda_var, s->ctx), RS_SCHEME_MAX_DEGREE);
            }
        }
        lin_clear(&lhs, s->ctx);
        lin_clear(&rhs, s->ctx);
        lin_clear(&v, s->ctx);
    }
    flint_free(x.visiting);
    return r;
}

void rs_scheme_copy(rs_scheme_t dst, const rs_scheme_t src)
{
    slong i;
    rs_scheme_clear(dst);
    dst->nvars = src->nvars;
    dst->lambda_var = src->lambda_var;
    dst->vars = flint_malloc(src->nvars * sizeof(char *));
    for (i = 0; i < src->nvars; i++) {
        dst->vars[i] = flint_malloc(strlen(src->vars[i]) + 1);
        strcpy(dst->vars[i], src->vars[i]);
    }
    fmpq_mpoly_ctx_init(dst->ctx, src->nvars, ORD_LEX);
    fmpz_mpoly_ctx_init(dst->zctx, src->nvars, ORD_LEX);
    fmpq_mpoly_init(dst->charpoly, dst->ctx);
    fmpq_mpoly_set(dst->charpoly, src->charpoly, dst->ctx);   /* equal contexts */
    dst->from_char = src->from_char;
    dst->sqrt_d = src->sqrt_d;
    dst->sqrt_var = src->sqrt_var;
    dst->complex_char = src->complex_char;
    dst->n = src->n;
    if (src->n > 0) {
        dst->unknowns = flint_malloc(src->n * sizeof(char *));
        for (i = 0; i < src->n; i++) dst->unknowns[i] = rs_strdup(src->unknowns[i]);
        dst->M = flint_malloc(src->n * src->n * sizeof(fmpq_mpoly_struct));
        for (i = 0; i < src->n * src->n; i++) {
            fmpq_mpoly_init(dst->M + i, dst->ctx);
            fmpq_mpoly_set(dst->M + i, src->M + i, dst->ctx);
        }
        dst->row_shift = flint_malloc(src->n * sizeof(slong));
        memcpy(dst->row_shift, src->row_shift, src->n * sizeof(slong));
    }
    dst->nnonzero = src->nnonzero;
    if (src->nnonzero > 0) {
        dst->nonzero = flint_malloc(src->nnonzero * sizeof(fmpq_mpoly_struct));
        dst->nonzero_text = flint_malloc(src->nnonzero * sizeof(char *));
        dst->nonzero_loc = flint_malloc(src->nnonzero * sizeof(rs_loc_t));
        memcpy(dst->nonzero_loc, src->nonzero_loc, src->nnonzero * sizeof(rs_loc_t));
        for (i = 0; i < src->nnonzero; i++) {
            fmpq_mpoly_init(dst->nonzero + i, dst->ctx);
            fmpq_mpoly_set(dst->nonzero + i, src->nonzero + i, dst->ctx);
            dst->nonzero_text[i] = flint_malloc(strlen(src->nonzero_text[i]) + 1);
            strcpy(dst->nonzero_text[i], src->nonzero_text[i]);
        }
    }
}

void rs_scheme_reduce_sqrt(fmpz_mpoly_t p, const rs_scheme_t s)
{
    rs_qd_mpoly_reduce(p, s->sqrt_var, s->sqrt_d, s->zctx);
}

void rs_scheme_substitute(rs_scheme_t s, slong var, const fmpq_t value)
{
    slong i;
    for (i = 0; i < s->n * s->n; i++)
        fmpq_mpoly_evaluate_one_fmpq(s->M + i, s->M + i, var, value, s->ctx);
    if (s->from_char)
        fmpq_mpoly_evaluate_one_fmpq(s->charpoly, s->charpoly, var, value, s->ctx);
}

char *rs_scheme_poly_str(const fmpq_mpoly_t p, const rs_scheme_t s)
{
    return fmpq_mpoly_get_str_pretty(p, (const char **) s->vars, s->ctx);
}

char *rs_scheme_zpoly_str(const fmpz_mpoly_t p, const rs_scheme_t s)
{
    return fmpz_mpoly_get_str_pretty(p, (const char **) s->vars, s->zctx);
}
