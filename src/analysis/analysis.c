/* analysis.c -- dispatching the analyses a case asks for. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "recstab/analysis.h"
#include "analysis/impl.h"
#include "analysis/registry.h"
#include "util/polyfmt.h"
#include "recstab/bilinear.h"
#include "recstab/cond.h"
#include "lower/builder.h"
#include "recstab/radius.h"

void rs_options_default(rs_options_t *opt)
{
    opt->max_prec = 65536;
    opt->default_digits = 30;
    opt->with_scheme = 0;
    opt->time_limit = RS_BUDGET_TIME_DEFAULT;
    opt->time_spent = 0;
    opt->memory_limit = rs_budget_memory_default();
    rs_sweep_options_default(&opt->sweep);
}

/* ---- variants: the scheme with some parameters substituted ------------- */

static void variant_free(rs_variant_t *v)
{
    if (v->have_cp) rs_charpoly_clear(v->cp, v->s);
    rs_scheme_clear(v->s);
    free(v->key);
    json_decref(v->assigned);
    json_decref(v->not_in_p);
    free(v);
}

/* Builds the key "name=value;..." of an assignment list. */
static char *assign_key(const rs_assign_t *a, slong n)
{
    size_t cap = 16, len = 0;
    char *k = malloc(cap);
    slong i;
    k[0] = '\0';
    for (i = 0; i < n; i++) {
        char *v = fmpq_get_str(NULL, 10, a[i].value);
        size_t need = strlen(a[i].name) + strlen(v) + 3;
        if (len + need + 1 > cap) { cap = 2 * (len + need + 1); k = realloc(k, cap); }
        len += (size_t) sprintf(k + len, "%s=%s;", a[i].name, v);
        flint_free(v);
    }
    return k;
}

int rs_run_assignments(rs_run_t *run, rs_assign_t **out, slong *nout,
                       const char *const *keep, slong nkeep,
                       const rs_assign_t *extra, slong nextra)
{
    /* the case's set values, minus `keep`, overridden/extended by `extra`,
     * ordered by parameter index so the key is canonical */
    const rs_case_struct *c = run->c;
    slong i, j, n = 0;
    rs_assign_t *a = calloc((size_t) (c->nparams + 1), sizeof(rs_assign_t));
    for (i = 0; i < c->nparams; i++) {
        const char *name = c->params[i].name;
        const fmpq *val = NULL;
        int kept = 0;
        for (j = 0; j < nkeep; j++)
            if (strcmp(keep[j], name) == 0) kept = 1;
        for (j = 0; j < c->nsets; j++)
            if (strcmp(c->sets[j].name, name) == 0) val = c->sets[j].value;
        for (j = 0; j < nextra; j++)
            if (strcmp(extra[j].name, name) == 0) { val = extra[j].value; kept = 0; }
        if (val == NULL || kept) continue;
        a[n].name = name;
        a[n].var = i;
        fmpq_init(a[n].value);
        fmpq_set(a[n].value, val);
        n++;
    }
    *out = a;
    *nout = n;
    return RS_OK;
}

void rs_assign_free(rs_assign_t *a, slong n)
{
    slong i;
    for (i = 0; i < n; i++) fmpq_clear(a[i].value);
    free(a);
}

/* A value that makes a divisor of the equations zero is bad input: the
 * equations were multiplied through by it under the assumption that it is
 * not zero. */
static int check_divisors(rs_run_t *run, const rs_scheme_t s, const rs_assign_t *a, slong n)
{
    fmpq_mpoly_t d;
    slong i, k;
    int r = RS_OK;
    if (n == 0) return RS_OK;
    fmpq_mpoly_init(d, s->ctx);
    for (i = 0; i < s->nnonzero && r == RS_OK; i++) {
        fmpq_mpoly_set(d, s->nonzero + i, s->ctx);
        for (k = 0; k < n; k++)
            fmpq_mpoly_evaluate_one_fmpq(d, d, a[k].var, a[k].value, s->ctx);
        if (fmpq_mpoly_is_zero(d, s->ctx)) {
            const rs_loc_t *l = s->nonzero_loc + i;
            char vals[512] = "";
            size_t len = 0;
            for (k = 0; k < n && len + 1 < sizeof vals; k++) {
                char *str;
                if (fmpq_mpoly_degree_si(s->nonzero + i, a[k].var, s->ctx) <= 0) continue;
                str = fmpq_get_str(NULL, 10, a[k].value);
                len += (size_t) snprintf(vals + len, sizeof vals - len, "%s%s = %s", len ? ", " : "",
                                         a[k].name, str);
                flint_free(str);
            }
            r = rs_error_set_at(run->err, RS_ERR_INPUT, l->file ? l->file : run->c->path, l->line, l->col,
                                "expected values that keep every divisor non-zero, found %s, where the "
                                "equations were multiplied through assuming %s", vals, s->nonzero_text[i]);
        }
    }
    fmpq_mpoly_clear(d, s->ctx);
    return r;
}

slong rs_charpoly_top_degree(const rs_charpoly_t cp)
{
    return cp->degree + cp->removed_lambda_power;
}

/* An upper bound on the degree in lambda of det M: no term of the Leibniz
 * expansion exceeds the sum of the row maxima, nor that of the columns. */
static slong det_degree_bound(const rs_scheme_t s)
{
    slong i, j, rows = 0, cols = 0, n = s->n;
    for (i = 0; i < n; i++) {
        slong rm = 0, cm = 0;
        for (j = 0; j < n; j++) {
            rm = FLINT_MAX(rm, fmpq_mpoly_degree_si(s->M + i * n + j, s->lambda_var, s->ctx));
            cm = FLINT_MAX(cm, fmpq_mpoly_degree_si(s->M + j * n + i, s->lambda_var, s->ctx));
        }
        rows += rm;
        cols += cm;
    }
    return FLINT_MIN(rows, cols);
}

/* The step is singular where substituted values make the leading coefficient
 * of det A in lambda vanish: the top degree falls below the degree over
 * Q(params).  Every substituted degree bounds that degree from below and the
 * row/column maxima from above; only when neither settles it is the
 * symbolic determinant computed (once per run). */
int rs_run_is_singular(int *singular, rs_run_t *run, slong top)
{
    *singular = 0;
    if (!run->have_sym) return RS_OK;
    if (top > run->deg_lower) run->deg_lower = top;
    if (top < run->deg_lower) { *singular = 1; return RS_OK; }
    if (run->deg_exact < 0) {
        if (run->sym->from_char) {
            run->deg_exact = fmpq_mpoly_degree_si(run->sym->charpoly, run->sym->lambda_var, run->sym->ctx);
        } else if (top >= det_degree_bound(run->sym)) {
            run->deg_exact = top;
        } else {
            rs_variant_t *g;
            int r = rs_run_variant(&g, run, NULL, 0);   /* sets deg_exact */
            if (r != RS_OK) return r;
        }
    }
    *singular = (top < run->deg_exact);
    return RS_OK;
}

int rs_run_variant(rs_variant_t **out, rs_run_t *run, const rs_assign_t *a, slong n)
{
    char *key = assign_key(a, n);
    rs_variant_t *v;
    slong i;
    int r;
    for (i = 0; i < run->nvariants; i++)
        if (strcmp(run->variants[i]->key, key) == 0) {
            free(key);
            *out = run->variants[i];
            return run->variants[i]->status;
        }
    v = calloc(1, sizeof(rs_variant_t));
    v->key = key;
    rs_scheme_init(v->s);
    /* every variant starts from the symbolic scheme built once per run */
    if (run->have_sym) {
        rs_scheme_copy(v->s, run->sym);
        r = RS_OK;
    } else {
        r = rs_scheme_build(v->s, run->m, run->err);
    }
    v->assigned = json_object();
    if (r == RS_OK) {
        for (i = 0; i < n; i++) {
            char *val = fmpq_get_str(NULL, 10, a[i].value);
            rs_scheme_substitute(v->s, a[i].var, a[i].value);
            json_object_set_new(v->assigned, a[i].name, json_string(val));
            flint_free(val);
        }
        r = check_divisors(run, v->s, a, n);
        rs_charpoly_init(v->cp, v->s);
        v->have_cp = 1;
        if (r == RS_OK) r = rs_charpoly_compute(v->cp, v->s, run->err);
        if (r == RS_OK && n == 0 && run->have_sym && run->deg_exact < 0)
            run->deg_exact = rs_charpoly_top_degree(v->cp);   /* nothing substituted: generic */
        if (r == RS_OK) r = rs_run_is_singular(&v->singular, run, rs_charpoly_top_degree(v->cp));
        if (r == RS_OK && !v->singular && rs_charpoly_top_degree(v->cp) < 1)
            r = rs_error_set(run->err, RS_ERR_MATH, "the characteristic polynomial has no root (degree 0 "
                             "in lambda): the scheme has no dynamics");
        if (r != RS_OK && run->err->file[0] == '\0') {
            /* point determinant failures at the equations */
            const rs_loc_t *l = run->m->neqs > 0 ? &run->m->eqs[0].loc : &run->c->charloc;
            char msg[RS_ERROR_MSG_LEN];
            snprintf(msg, sizeof msg, "%s%s%s", run->err->msg, n > 0 ? " at " : "", n > 0 ? key : "");
            rs_error_set_at(run->err, r, l->file ? l->file : run->c->path, l->line, l->col, "%s", msg);
        }
    }
    v->status = r;
    run->variants = realloc(run->variants, (size_t) (run->nvariants + 1) * sizeof(rs_variant_t *));
    run->variants[run->nvariants++] = v;
    *out = v;
    return r;
}

/* ---- JSON helpers -------------------------------------------------------- */

json_t *rs_json_fmpq(const fmpq_t q)
{
    char *s = fmpq_get_str(NULL, 10, q);
    json_t *j = json_string(s);
    flint_free(s);
    return j;
}

json_t *rs_json_arb(const arb_t x, slong digits)
{
    char *s = rs_radius_arb_str(x, digits);
    json_t *j = json_string(s);
    flint_free(s);
    return j;
}

json_t *rs_json_sets(const rs_case_t c)
{
    json_t *sets = json_object();
    slong i;
    for (i = 0; i < c->nsets; i++)
        json_object_set_new(sets, c->sets[i].name, rs_json_fmpq(c->sets[i].value));
    return sets;
}

/* Digits for printing the bounds: digits + 5, or more when a bound is
 * certified on one side of 1 but that many digits would round it onto 1
 * (upper = 1 - 1e-40 prints as 1.0000 rounded up).  A bound b in (0.1, 10)
 * at n digits moves by < 10^(1-n) <= |b - 1| once n >= 2 - log10|b - 1|. */
static slong radius_print_digits(const rs_radius_t rr, slong digits)
{
    slong n = digits + 5, k;
    arf_t d;
    arf_init(d);
    if (arb_is_finite(rr->upper) && arf_cmp_si(arb_midref(rr->upper), 1) < 0)
        arf_sub_ui(d, arb_midref(rr->upper), 1, ARF_PREC_EXACT, ARF_RND_DOWN);
    else if (arb_is_finite(rr->lower) && arf_cmp_si(arb_midref(rr->lower), 1) > 0)
        arf_sub_ui(d, arb_midref(rr->lower), 1, ARF_PREC_EXACT, ARF_RND_DOWN);
    if (!arf_is_zero(d)) {
        /* |d| >= 2^(E-1) with E = arf_abs_bound_lt_2exp_si(d) */
        k = (slong) ((double) (1 - arf_abs_bound_lt_2exp_si(d)) * 0.30103) + 3;
        if (k > n)
            n = FLINT_MIN(k, 4 * RS_DIGITS_MAX);
    }
    arf_clear(d);
    return n;
}

void rs_json_radius(json_t *o, const rs_radius_t rr, slong digits)
{
    slong n = radius_print_digits(rr, digits);
    char *lo = rs_radius_str_lower(rr->lower, n), *hi = rs_radius_str_upper(rr->upper, n);
    json_object_set_new(o, "certified", json_true());
    json_object_set_new(o, "lower", json_string(lo));
    json_object_set_new(o, "upper", json_string(hi));
    flint_free(lo);
    flint_free(hi);
    json_object_set_new(o, "rho", rs_json_arb(rr->rho, digits));
    json_object_set_new(o, "digits", json_integer(digits));
    json_object_set_new(o, "precision_bits", json_integer(rr->prec));
}

#define NOT_IN_P_KEY "|not_in_p"

/* 1 if the integer placeholder values a[0..n-1] keep the parameter content
 * and every non-zero assumption of s non-zero (other variables: 0; they do
 * not occur there) */
static int placeholders_ok(const rs_scheme_struct *s, const fmpz_mpoly_t content, const rs_assign_t *a, slong n)
{
    fmpq *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc(s->nvars * sizeof(fmpq *));
    fmpz *zt = _fmpz_vec_init(s->nvars);
    fmpz **zp = flint_malloc(s->nvars * sizeof(fmpz *));
    fmpq_t val;
    fmpz_t zv;
    slong i;
    int ok;
    fmpq_init(val);
    fmpz_init(zv);
    for (i = 0; i < s->nvars; i++) { pp[i] = pt + i; zp[i] = zt + i; }
    for (i = 0; i < n; i++) {
        fmpq_set(pt + a[i].var, a[i].value);
        fmpz_set(zt + a[i].var, fmpq_numref(a[i].value));
    }
    fmpz_mpoly_evaluate_all_fmpz(zv, content, zp, s->zctx);
    ok = !fmpz_is_zero(zv);
    for (i = 0; i < s->nnonzero && ok; i++) {
        fmpq_mpoly_evaluate_all_fmpq(val, s->nonzero + i, pp, s->ctx);
        ok = !fmpq_is_zero(val);
    }
    fmpq_clear(val);
    fmpz_clear(zv);
    _fmpq_vec_clear(pt, s->nvars);
    _fmpz_vec_clear(zt, s->nvars);
    flint_free(pp);
    flint_free(zp);
    return ok;
}

int rs_run_numeric_variant(rs_run_t *run, rs_variant_t **out)
{
    const rs_case_struct *c = run->c;
    rs_variant_t *v;
    rs_assign_t *a, *extra;
    slong i, n, nx = 0, j, lv;
    fmpz_mpoly_t P;
    const rs_scheme_struct *s;
    char *key;
    int r = rs_run_default_variant(run, &v), ok;
    static const slong tries[] = {1, 2, 3, 5, 7, 11, 13, -1};
    *out = v;
    if (r != RS_OK) return r;
    s = v->s;
    lv = s->lambda_var;
    fmpz_mpoly_init(P, s->zctx);
    /* p over its parameter content must be free of parameters */
    ok = fmpz_mpoly_divides(P, v->cp->p, v->cp->param_content, s->zctx);
    for (i = 0; ok && i < s->nvars; i++)
        if (i != lv && fmpz_mpoly_degree_si(P, i, s->zctx) > 0) ok = 0;
    fmpz_mpoly_clear(P, s->zctx);
    if (!ok) return RS_OK;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    extra = calloc((size_t) c->nparams + 1, sizeof(rs_assign_t));
    for (i = 0; i < c->nparams; i++) {
        int set = 0;
        for (j = 0; j < n; j++) set |= a[j].var == i;
        if (set) continue;
        extra[nx].name = c->params[i].name;
        extra[nx].var = i;
        fmpq_init(extra[nx].value);
        nx++;
    }
    rs_assign_free(a, n);
    if (nx == 0) { rs_assign_free(extra, nx); return RS_OK; }
    /* one value for all of them: the first of a few small integers that keeps
     * the content (p = content * p0) and the non-zero assumptions non-zero */
    ok = 0;
    for (j = 0; tries[j] > 0 && !ok; j++) {
        for (i = 0; i < nx; i++) fmpq_set_si(extra[i].value, tries[j], 1);
        ok = placeholders_ok(s, v->cp->param_content, extra, nx);
    }
    if (ok) {
        rs_run_assignments(run, &a, &n, NULL, 0, extra, nx);
        /* its own cache entry: the placeholders are not values the user gave */
        char *k0 = assign_key(a, n);
        key = malloc(strlen(k0) + sizeof NOT_IN_P_KEY);
        sprintf(key, "%s%s", k0, NOT_IN_P_KEY);
        free(k0);
        for (i = 0; i < run->nvariants; i++)
            if (strcmp(run->variants[i]->key, key) == 0) *out = run->variants[i];
        if (*out == v) {
            slong before = run->nvariants;
            r = rs_run_variant(out, run, a, n);
            if (run->nvariants > before) {
                rs_variant_t *w = *out;
                free(w->key);
                w->key = key;
                key = NULL;
                w->not_in_p = json_array();
                for (i = 0; i < nx; i++) {
                    json_array_append_new(w->not_in_p, json_string(extra[i].name));
                    json_object_del(w->assigned, extra[i].name);
                }
            }
        }
        free(key);
        rs_assign_free(a, n);
    }
    rs_assign_free(extra, nx);
    return r;
}

void rs_run_emit_exact(rs_run_t *run, const rs_variant_t *v, json_t *o)
{
    if (v->not_in_p != NULL) json_object_set_new(o, "not_in_p", json_deep_copy(v->not_in_p));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_object_set_new(o, "decided_by", json_string("exact"));
    json_array_append_new(run->results, o);
}

char *rs_cond_string(const fmpz_mpoly_t p, const rs_scheme_t s, const char *rel)
{
    char *ps = rs_polyfmt_fmpz_mpoly(p, (const char **) s->vars, s->zctx);
    char *line = malloc(strlen(ps) + strlen(rel) + 2);
    sprintf(line, "%s %s", ps, rel);
    free(ps);
    return line;
}

json_t *rs_json_zpoly(const fmpz_mpoly_t p, const rs_scheme_t s)
{
    char *str = rs_polyfmt_fmpz_mpoly(p, (const char **) s->vars, s->zctx);
    json_t *j = json_string(str);
    free(str);
    return j;
}

json_t *rs_json_collected(const fmpz_mpoly_t p, slong var, const rs_scheme_t s, const char *varname)
{
    const char **vars = malloc((size_t) s->nvars * sizeof(char *));
    slong i;
    char *str;
    json_t *j;
    for (i = 0; i < s->nvars; i++) vars[i] = s->vars[i];
    vars[var] = varname;
    str = rs_polyfmt_collected(p, var, vars, s->zctx);
    j = json_string(str);
    free(str);
    free(vars);
    return j;
}

json_t *rs_json_coeffs(const fmpz_mpoly_t p, slong var, const rs_scheme_t s)
{
    json_t *arr = json_array();
    slong d = fmpz_mpoly_degree_si(p, var, s->zctx), k;
    fmpz_mpoly_t c;
    fmpz_mpoly_init(c, s->zctx);
    for (k = 0; k <= d; k++) {
        rs_charpoly_coeff(c, p, k, var, s->zctx);
        json_array_append_new(arr, rs_json_zpoly(c, s));
    }
    fmpz_mpoly_clear(c, s->zctx);
    return arr;
}

json_t *rs_json_nonzero(const rs_scheme_t s)
{
    json_t *arr = json_array();
    slong i;
    for (i = 0; i < s->nnonzero; i++) {
        char *t = rs_polyfmt_spaced(s->nonzero_text[i]);
        json_array_append_new(arr, json_string(t));
        free(t);
    }
    return arr;
}

int *rs_run_signs(rs_run_t *run, const rs_scheme_t s)
{
    const rs_case_struct *c = run->c;
    rs_bound_t *b = flint_malloc((c->nparams + 1) * sizeof(rs_bound_t));
    int *sign = flint_calloc(s->nvars, sizeof(int));
    slong i;
    rs_bounds_init(b, c->nparams);
    for (i = 0; i < c->nassume; i++)
        rs_bounds_add(b, &c->assume[i], c, run->err);
    rs_bounds_signs(sign, b, c->nparams);
    rs_bounds_clear(b, c->nparams);
    flint_free(b);
    return sign;
}

/* Request text helpers */
const char *rs_req_skip_word(const char *t)
{
    while (*t == ' ' || *t == '\t') t++;
    while (*t && !isspace((unsigned char) *t)) t++;
    while (*t == ' ' || *t == '\t') t++;
    return t;
}

int rs_req_error(rs_run_t *run, const rs_request_t *q, const char *at, int code, const char *fmt, const char *a)
{
    int col = q->loc.col + (int) (at - q->text);
    return rs_error_set_at(run->err, code, q->loc.file, q->loc.line, col > 0 ? col : 1, fmt, a);
}

int rs_req_relocate(rs_run_t *run, const rs_request_t *q, int code, const char *what)
{
    char msg[RS_ERROR_MSG_LEN + 64];
    if (run->err->file[0] != '\0') return code;
    snprintf(msg, sizeof msg, "%s: %s", what,
             run->err->msg[0] ? run->err->msg : "not certified within the precision limit");
    return rs_req_error(run, q, q->text, code, "%s", msg);
}

void rs_req_src(rs_src_t *src, const rs_request_t *q)
{
    memset(src, 0, sizeof *src);
    src->file = q->loc.file;
    src->text = q->text;
    src->line = q->loc.line;
    src->col = q->loc.col;
}

int rs_req_eval_points(fmpq *out, slong stride, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v,
                       const char *text, slong var, const fmpq *vals, slong npoints, const char **end)
{
    const fmpq_mpoly_ctx_struct *ctx = v->s->ctx;
    const char *what = var < 0 ? "expected a value of set parameters, found '%s'"
                               : "expected a value of set parameters and the swept one, found '%s'";
    rs_src_t src;
    rs_expr_t *e = NULL;
    fmpq_mpoly_t num, den, tn, td;
    rs_assign_t *a;
    size_t pos = (size_t) (text - q->text);
    slong i, n;
    fmpq_t b;
    int r;
    rs_req_src(&src, q);
    r = rs_expr_parse(&e, &src, &pos, run->err);
    if (r != RS_OK) return r;
    if (end != NULL) *end = q->text + pos;
    fmpq_mpoly_init(num, ctx);
    fmpq_mpoly_init(den, ctx);
    r = rs_scheme_eval_poly(num, den, v->s, run->c, e, 0, run->err);
    rs_expr_free(e);
    if (r != RS_OK) goto done;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    for (i = 0; i < n; i++) {
        if (a[i].var == var) continue;
        fmpq_mpoly_evaluate_one_fmpq(num, num, a[i].var, a[i].value, ctx);
        fmpq_mpoly_evaluate_one_fmpq(den, den, a[i].var, a[i].value, ctx);
    }
    rs_assign_free(a, n);
    fmpq_mpoly_init(tn, ctx);
    fmpq_mpoly_init(td, ctx);
    fmpq_init(b);
    for (i = 0; i < npoints && r == RS_OK; i++) {
        if (var >= 0) {
            fmpq_mpoly_evaluate_one_fmpq(tn, num, var, vals + i, ctx);
            fmpq_mpoly_evaluate_one_fmpq(td, den, var, vals + i, ctx);
        } else {
            fmpq_mpoly_set(tn, num, ctx);
            fmpq_mpoly_set(td, den, ctx);
        }
        if (!fmpq_mpoly_is_fmpq(tn, ctx) || !fmpq_mpoly_is_fmpq(td, ctx)) {
            r = rs_req_error(run, q, text, RS_ERR_INPUT, what, text);
        } else {
            fmpq_mpoly_get_fmpq(out + i * stride, tn, ctx);
            fmpq_mpoly_get_fmpq(b, td, ctx);
            if (fmpq_is_zero(b))
                r = rs_req_error(run, q, text, RS_ERR_MATH, "division by zero in '%s'", text);
            else fmpq_div(out + i * stride, out + i * stride, b);
        }
    }
    fmpq_clear(b);
    fmpq_mpoly_clear(tn, ctx);
    fmpq_mpoly_clear(td, ctx);
done:
    fmpq_mpoly_clear(num, ctx);
    fmpq_mpoly_clear(den, ctx);
    return r;
}

/* ---- charpoly ------------------------------------------------------------ */

json_t *rs_charpoly_json(const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    json_t *o = json_object();
    char *str;
    json_object_set_new(o, "analysis", json_string("charpoly"));
    json_object_set_new(o, "var", json_string("lambda"));
    json_object_set_new(o, "degree", json_integer(v->cp->degree));
    json_object_set_new(o, "coeffs", rs_json_coeffs(v->cp->p, s->lambda_var, s));
    json_object_set_new(o, "removed_lambda_power", json_integer(v->cp->removed_lambda_power));
    json_object_set_new(o, "content", rs_json_fmpq(v->cp->content));
    str = rs_polyfmt_collected(v->cp->p, s->lambda_var, (const char **) s->vars, s->zctx);
    json_object_set_new(o, "poly", json_string(str));
    free(str);
    if (!fmpz_mpoly_is_fmpz(v->cp->param_content, s->zctx))
        json_object_set_new(o, "param_content", rs_json_zpoly(v->cp->param_content, s));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_object_set_new(o, "nonzero_assumptions", rs_json_nonzero(s));
    json_object_set_new(o, "decided_by", json_string("exact"));
    return o;
}

int rs_an_charpoly(rs_run_t *run, const rs_an_req_t *req)
{
    rs_assign_t *a;
    slong n;
    rs_variant_t *v;
    int r;
    (void) req;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(&v, run, a, n);
    rs_assign_free(a, n);
    if (r != RS_OK) return r;
    json_array_append_new(run->results, rs_charpoly_json(v));
    return RS_OK;
}

/* ---- expect charpoly ----------------------------------------------------- */

/* Compare an expected polynomial (fmpq, in the variant's variables, values
 * substituted) with the derived one; fills status/difference into o. */
void rs_compare_poly(json_t *o, const fmpq_mpoly_t expected, const fmpz_mpoly_t derived,
                     const fmpz_mpoly_t derived_raw, slong var, const rs_scheme_t s,
                     const char *varname)
{
    fmpz_mpoly_t e, d;
    fmpq_t scale;
    const char *status;
    fmpz_mpoly_init(e, s->zctx);
    fmpz_mpoly_init(d, s->zctx);
    fmpq_init(scale);
    rs_charpoly_fmpq_to_fmpz(e, scale, expected, s->ctx);
    if (fmpq_is_one(scale) && fmpz_mpoly_equal(e, derived_raw, s->zctx))
        status = "equal";
    else if (fmpq_is_one(scale) && fmpz_mpoly_equal(e, derived, s->zctx))
        status = "equal";
    else {
        fmpq_t g;
        fmpq_init(g);
        rs_charpoly_normalise(e, g, var, s->zctx);
        fmpq_clear(g);
        status = fmpz_mpoly_equal(e, derived, s->zctx) ? "proportional" : "different";
    }
    json_object_set_new(o, "status", json_string(status));
    if (strcmp(status, "different") == 0) {
        fmpz_mpoly_sub(d, e, derived, s->zctx);
        json_object_set_new(o, "difference", rs_json_collected(d, var, s, varname));
        json_object_set_new(o, "expected_normalised", rs_json_collected(e, var, s, varname));
        json_object_set_new(o, "derived", rs_json_collected(derived, var, s, varname));
        {
            /* is the printed one a multiple of ours by a parameter factor? */
            fmpz_mpoly_t qt;
            fmpz_mpoly_init(qt, s->zctx);
            if (fmpz_mpoly_divides(qt, e, derived, s->zctx) && fmpz_mpoly_degree_si(qt, var, s->zctx) == 0)
                json_object_set_new(o, "ratio", rs_json_zpoly(qt, s));
            fmpz_mpoly_clear(qt, s->zctx);
        }
    } else {
        json_object_set_new(o, "difference", json_string("0"));
    }
    fmpz_mpoly_clear(e, s->zctx);
    fmpz_mpoly_clear(d, s->zctx);
    fmpq_clear(scale);
}

/* expect charpoly|bilinear POLY: the polynomial parsed up front */
int rs_an_expect_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *what = req->rest;
    rs_src_t src;
    size_t pos;
    int r;
    if (strncmp(what, "charpoly", 8) == 0 && (what[8] == ' ' || what[8] == '\t'))
        req->u.expect.bilinear = 0;
    else if (strncmp(what, "bilinear", 8) == 0 && (what[8] == ' ' || what[8] == '\t'))
        req->u.expect.bilinear = 1;
    else
        return rs_req_error(run, q, what, RS_ERR_INPUT,
                            "expected 'charpoly' or 'bilinear' followed by a polynomial, found '%s'", what);
    rs_req_src(&src, q);
    pos = (size_t) (rs_req_skip_word(what) - q->text);
    r = rs_expr_parse(&req->u.expect.poly, &src, &pos, run->err);
    if (r == RS_OK && q->text[pos] != '\0')
        return rs_req_error(run, q, q->text + pos, RS_ERR_INPUT,
                            "expected an operator or end of line, found '%s'", q->text + pos);
    if (r == RS_OK) r = rs_an_check_names(run, q, req->u.expect.poly);
    return r;
}

int rs_an_expect(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    int bil = req->u.expect.bilinear;
    rs_assign_t *a;
    slong n, i;
    rs_variant_t *v;
    fmpq_mpoly_t num, den;
    json_t *o;
    int r;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(&v, run, a, n);
    if (r != RS_OK) { rs_assign_free(a, n); return r; }
    fmpq_mpoly_init(num, v->s->ctx);
    fmpq_mpoly_init(den, v->s->ctx);
    r = rs_scheme_eval_poly(num, den, v->s, run->c, req->u.expect.poly, bil ? 2 : 1, run->err);
    if (r == RS_OK) {
        const fmpz_mpoly_ctx_struct *zctx = v->s->zctx;
        fmpz_mpoly_t raw, norm;
        for (i = 0; i < n; i++)
            fmpq_mpoly_evaluate_one_fmpq(num, num, a[i].var, a[i].value, v->s->ctx);
        fmpz_mpoly_init(raw, zctx);
        fmpz_mpoly_init(norm, zctx);
        if (bil) {
            /* q itself is "equal"; its normalised form for "proportional" */
            rs_bilinear_fmpz_mpoly(raw, v->cp->p, v->s->lambda_var, zctx);
            fmpz_mpoly_set(norm, raw, zctx);
            rs_charpoly_normalise(norm, NULL, v->s->lambda_var, zctx);
        } else {
            /* the raw determinant lambda^k * p, for "equal" */
            fmpz_mpoly_gen(raw, v->s->lambda_var, zctx);
            fmpz_mpoly_pow_ui(raw, raw, (ulong) v->cp->removed_lambda_power, zctx);
            fmpz_mpoly_mul(raw, v->cp->p, raw, zctx);
            fmpz_mpoly_set(norm, v->cp->p, zctx);
        }
        o = json_object();
        json_object_set_new(o, "analysis", json_string("expect"));
        json_object_set_new(o, "of", json_string(bil ? "bilinear" : "charpoly"));
        json_object_set_new(o, "text", json_string(q->text));
        if (fmpq_mpoly_is_zero(num, v->s->ctx)) {
            json_object_set_new(o, "status", json_string("different"));
            json_object_set_new(o, "difference", rs_json_zpoly(norm, v->s));
        } else {
            rs_compare_poly(o, num, norm, raw, v->s->lambda_var, v->s, bil ? "z" : "lambda");
        }
        json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
        if (strcmp(json_string_value(json_object_get(o, "status")), "different") == 0)
            run->outcome |= RS_OUTCOME_FAILED;
        json_array_append_new(run->results, o);
        fmpz_mpoly_clear(raw, zctx);
        fmpz_mpoly_clear(norm, zctx);
    }
    fmpq_mpoly_clear(num, v->s->ctx);
    fmpq_mpoly_clear(den, v->s->ctx);
    rs_assign_free(a, n);
    return r;
}

/* The equations as written and the lambda-matrix (set values substituted),
 * for derivations. */
static json_t *scheme_json(rs_run_t *run)
{
    const rs_case_struct *c = run->c;
    rs_assign_t *a;
    slong n, i, j;
    rs_variant_t *v;
    json_t *o = json_object(), *eqs = json_array(), *lets = json_array(), *M = json_array();
    if (rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0), rs_run_variant(&v, run, a, n) != RS_OK) {
        rs_assign_free(a, n);
        json_decref(o); json_decref(eqs); json_decref(lets); json_decref(M);
        return NULL;
    }
    rs_assign_free(a, n);
    for (i = 0; i < run->m->neqs; i++) json_array_append_new(eqs, json_string(run->m->eqs[i].text ? run->m->eqs[i].text : ""));
    for (i = 0; i < c->nlets; i++) json_array_append_new(lets, json_string(c->lets[i].text ? c->lets[i].text : ""));
    for (i = 0; i < v->s->n; i++) {
        json_t *row = json_array();
        for (j = 0; j < v->s->n; j++) {
            char *str = rs_polyfmt_fmpq_mpoly(v->s->M + i * v->s->n + j, (const char **) v->s->vars, v->s->ctx);
            json_array_append_new(row, json_string(str));
            free(str);
        }
        json_array_append_new(M, row);
    }
    json_object_set_new(o, "equations", eqs);
    json_object_set_new(o, "lets", lets);
    json_object_set_new(o, "matrix", M);
    if (v->s->from_char) {
        char *str = rs_polyfmt_fmpq_mpoly(v->s->charpoly, (const char **) v->s->vars, v->s->ctx);
        json_object_set_new(o, "char", json_string(str));
        free(str);
    }
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_object_set_new(o, "nonzero_assumptions", rs_json_nonzero(v->s));
    {
        json_t *as = json_array();
        for (i = 0; i < c->nassume; i++) json_array_append_new(as, json_string(c->assume[i].text));
        json_object_set_new(o, "assume", as);
    }
    return o;
}

static int check_assumptions(const rs_case_t c, const rs_model_t m, rs_error_t err)
{
    slong i, k;
    for (i = 0; i < c->nassume; i++)
        for (k = 0; k < c->assume[i].n; k++) {
            const rs_expr_t *u = rs_an_undeclared_name(c->assume[i].e[k], m);
            if (u != NULL)
                return rs_error_set_at(err, RS_ERR_INPUT, c->assume[i].loc.file ? c->assume[i].loc.file : c->path,
                                       u->line, u->col,
                                       "unknown name '%s' in an assume line (expected a declared param, unknown or let)",
                                       u->name);
        }
    return RS_OK;
}

static void free_requests(rs_request_t *q, slong n)
{
    slong i;
    for (i = 0; i < n; i++) {
        flint_free(q[i].text);
        flint_free(q[i].loc.file);
    }
    free(q);
}

/* The analyses of a case without `analyse`, `expect` or `claim` lines:
 * charpoly and stability when p depends on no unset parameter; else
 * charpoly, hurwitz and, with one free parameter, its region.  Numeric
 * cases (exp/sin recurrences, exact integration): stability.  An
 * identically zero determinant is the usual error. */
static int default_requests(rs_run_t *run, rs_request_t **out, slong *nout)
{
    const rs_case_struct *c = run->c;
    const rs_loc_t *at = run->m->neqs > 0 ? &run->m->eqs[0].loc : c->charexpr != NULL ? &c->charloc : NULL;
    const char *names[3];
    char region[80 + RS_CASE_MAX_NAMES];
    slong n = 0, i, nfree = 0, last = -1;
    rs_variant_t *v;
    int r;
    *out = NULL;
    *nout = 0;
    if (rs_model_kind(c) != RS_MODEL_EQUATIONS) {
        names[n++] = "stability";
    } else {
        r = rs_run_numeric_variant(run, &v);
        if (r != RS_OK) return r;
        for (i = 0; i < v->s->nvars; i++)
            if (i != v->s->lambda_var && fmpz_mpoly_degree_si(v->cp->p, i, v->s->zctx) > 0) {
                nfree++;
                last = i;
            }
        names[n++] = "charpoly";
        if (nfree == 0) {
            names[n++] = "stability";
        } else {
            names[n++] = "hurwitz";
            if (nfree == 1) {
                snprintf(region, sizeof region, "region %s", v->s->vars[last]);
                names[n++] = region;
            }
        }
    }
    *out = calloc((size_t) n, sizeof(rs_request_t));
    for (i = 0; i < n; i++) {
        (*out)[i].text = rs_strdup(names[i]);
        (*out)[i].loc.file = rs_strdup(at != NULL && at->file != NULL ? at->file : c->path);
        (*out)[i].loc.line = at != NULL ? at->line : 1;
        (*out)[i].loc.col = at != NULL ? at->col : 1;
    }
    *nout = n;
    return RS_OK;
}

/* Parses every request against the registry (*out: nq typed requests) before
 * any runs: the first bad one is the error. */
static int parse_requests(rs_an_req_t **out, rs_run_t *run, const rs_request_t *q, slong nq)
{
    slong i;
    int r = RS_OK;
    *out = calloc((size_t) nq + 1, sizeof(rs_an_req_t));
    for (i = 0; i < nq && r == RS_OK; i++) r = rs_an_req_parse(*out + i, run, q + i);
    return r;
}

static void clear_requests(rs_an_req_t *req, slong n)
{
    slong i;
    for (i = 0; req != NULL && i < n; i++) rs_an_req_clear(req + i);
    free(req);
}

/* Runs the parsed requests in order, each checked against the budget;
 * `relocate`: a limit error without a place is put at its request (the
 * case's own requests, not the defaults). */
static int run_requests(rs_run_t *run, const rs_an_req_t *req, slong n, int relocate)
{
    slong i;
    int r = RS_OK;
    for (i = 0; i < n && r == RS_OK; i++) {
        r = rs_an_req_run(run, req + i);
        /* a loop stopped by the budget may have ended in another error or in
         * a partial result: the budget's message is the one to report, at
         * the request that ran out */
        if (rs_budget_exceeded()) r = rs_budget_error(run->err);
        if (relocate && r == RS_ERR_LIMIT && run->err->line == 0) {
            char msg[RS_ERROR_MSG_LEN];
            snprintf(msg, sizeof msg, "%s", run->err->msg);
            r = rs_req_error(run, req[i].q, req[i].q->text, r, "%s", msg);
        }
    }
    return r;
}

static void run_clear(rs_run_t *run)
{
    slong i;
    for (i = 0; i < run->nvariants; i++) variant_free(run->variants[i]);
    free(run->variants);
    rs_scheme_clear(run->sym);
    json_decref(run->results);
}

/* The case's document around the results (takes run->results). */
static json_t *case_doc(rs_run_t *run, const rs_request_t *defaults, slong ndefaults)
{
    const rs_case_struct *c = run->c;
    json_t *d = json_object(), *arr;
    slong i;
    char *shown = rs_utf8_escape(c->path);   /* json_string refuses invalid UTF-8 */
    json_object_set_new(d, "case", json_string(shown));
    flint_free(shown);
    json_object_set_new(d, "title", c->title ? json_string(c->title) : json_null());
    arr = json_array();
    for (i = 0; i < c->nparams; i++) json_array_append_new(arr, json_string(c->params[i].name));
    json_object_set_new(d, "params", arr);
    arr = json_array();
    for (i = 0; i < run->m->nunknowns; i++) json_array_append_new(arr, json_string(run->m->unknowns[i].name));
    json_object_set_new(d, "unknowns", arr);
    json_object_set_new(d, "set", rs_json_sets(c));
    if (ndefaults > 0) {
        arr = json_array();
        for (i = 0; i < ndefaults; i++) json_array_append_new(arr, json_string(defaults[i].text));
        json_object_set_new(d, "default_analyses", arr);
    }
    if (run->opt->with_scheme && rs_model_kind(c) == RS_MODEL_EQUATIONS) {
        json_t *sc = scheme_json(run);
        if (sc == NULL) {
            json_decref(d);
            return NULL;
        }
        json_object_set_new(d, "scheme", sc);
    }
    json_object_set_new(d, "results", run->results);
    run->results = NULL;
    return d;
}

int rs_analysis_run(json_t **doc, int *outcome, const rs_case_t c,
                    const rs_options_t *opt, rs_error_t err)
{
    rs_run_t run;
    slong ndefaults = 0, nreq = 0;
    rs_request_t *defaults = NULL;
    rs_model_t m;
    rs_an_req_t *req = NULL;
    int r = RS_OK;
    memset(&run, 0, sizeof run);
    rs_model_init(m);
    run.c = c;
    run.m = m;
    run.opt = opt;
    run.err = err;
    run.results = json_array();
    run.deg_lower = -1;
    run.deg_exact = -1;
    *doc = NULL;
    *outcome = RS_OUTCOME_OK;
    rs_budget_start(opt->time_limit, opt->time_spent, opt->memory_limit);
    /* an error in the equations must surface even when no analysis asks */
    rs_scheme_init(run.sym);
    r = rs_model_lower(m, c, err);
    if (r == RS_OK) r = check_assumptions(c, m, err);
    if (r == RS_OK && rs_model_kind(c) == RS_MODEL_EQUATIONS) {
        r = rs_scheme_build(run.sym, m, err);
        run.have_sym = (r == RS_OK);
    }
    if (r == RS_OK && c->nrequests == 0) r = default_requests(&run, &defaults, &ndefaults);
    if (r == RS_OK) {
        nreq = c->nrequests > 0 ? c->nrequests : ndefaults;
        r = parse_requests(&req, &run, c->nrequests > 0 ? c->requests : defaults, nreq);
    }
    if (r == RS_OK) r = run_requests(&run, req, nreq, c->nrequests > 0);
    if (r == RS_OK && rs_budget_exceeded()) r = rs_budget_error(err);
    rs_budget_stop();
    clear_requests(req, nreq);
    if (r == RS_OK) {
        *doc = case_doc(&run, defaults, ndefaults);
        if (*doc == NULL) r = err->code ? err->code : RS_ERR_INTERNAL;
    }
    free_requests(defaults, ndefaults);
    if (r == RS_OK) *outcome = run.outcome;
    run_clear(&run);
    rs_model_clear(m);
    return r;
}
