/* run.c -- what the analyses share: variants (the scheme and its
 * characteristic polynomial with values substituted, cached per run), the
 * exact point verdict, conditions checked at sample points, the request's
 * text and places, and the JSON of numbers and polynomials. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <ctype.h>
#include <fmpq_vec.h>
#include <fmpz_vec.h>
#include "analysis/impl.h"
#include "analysis/registry.h"
#include "util/polyfmt.h"
#include "util/polytext.h"
#include "recstab/semisimple.h"
#include "recstab/routh.h"
#include "recstab/jury.h"
#include "recstab/positivity.h"

/* ---- variants: the scheme with some parameters substituted ------------- */

void rs_variant_free(rs_variant_t *v)
{
    if (v->have_cp) rs_charpoly_clear(v->cp, v->s);
    rs_scheme_clear(v->s);
    free(v->key);
    json_decref(v->assigned);
    json_decref(v->not_in_p);
    json_decref(v->valid_if);
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
            /* the error again: an analysis before may have cleared run->err */
            if (run->variants[i]->status != RS_OK) *run->err = run->variants[i]->err;
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
        if (r == RS_OK) {
            r = rs_charpoly_compute(v->cp, v->s, run->err);
            /* the generic det is not zero (have_sym): these values make it vanish */
            v->vanishes = r == RS_ERR_MATH && n > 0 && run->have_sym && fmpz_mpoly_is_zero(v->cp->p, v->s->zctx);
        }
        if (r == RS_OK && n == 0 && run->have_sym && run->deg_exact < 0)
            run->deg_exact = rs_charpoly_top_degree(v->cp);   /* nothing substituted: generic */
        if (r == RS_OK) r = rs_run_is_singular(&v->singular, run, rs_charpoly_top_degree(v->cp));
        if (r == RS_OK && !v->singular && rs_charpoly_top_degree(v->cp) < 1) {
            /* an equation that writes one shift only (x[n+1] = 0) holds from there on: x = 0 */
            int shifted = 0;
            for (i = 0; i < v->s->n && v->s->row_shift != NULL; i++) shifted |= v->s->row_shift[i] > 0;
            r = rs_error_set(run->err, RS_ERR_MATH, "the characteristic polynomial has no root (degree 0 "
                             "in lambda): the scheme has no dynamics%s", shifted ? " (an equation holds from the "
                             "lowest shift it writes: x[n+1] = 0 says x[n] = 0 for every n; the dead-beat "
                             "recurrence x[n+1] = 0 x[n] is written x[n+1] = 0*x[n])" : "");
        }
        if (r != RS_OK && run->err->file[0] == '\0') {
            /* point determinant failures at the equations */
            const rs_loc_t *l = run->m->neqs > 0 ? &run->m->eqs[0].loc : &run->c->charloc;
            char msg[RS_ERROR_MSG_LEN];
            snprintf(msg, sizeof msg, "%s%s%s", run->err->msg, n > 0 ? " at " : "", n > 0 ? key : "");
            rs_error_set_at(run->err, r, l->file ? l->file : run->c->path, l->line, l->col, "%s", msg);
        }
    }
    v->status = r;
    if (r != RS_OK) v->err = *run->err;
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
    for (i = 0; i < c->ncsets; i++) {
        char *v = rs_complex_str(c->csets[i].re, c->csets[i].im);
        json_object_set_new(sets, c->csets[i].name, json_string(v));
        free(v);
    }
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
                /* the verdict at the placeholders holds only where the content
                 * (p = content * p0) is not 0: at its zeros p vanishes */
                if (!fmpz_mpoly_is_fmpz(v->cp->param_content, s->zctx)) {
                    fmpz_mpoly_t kept;
                    fmpz_mpoly_init(kept, s->zctx);
                    w->valid_if = json_array();
                    rs_run_dead_beat_nonzero(kept, w->valid_if, run, v->s, v->cp->param_content);
                    fmpz_mpoly_clear(kept, s->zctx);
                    if (json_array_size(w->valid_if) == 0) {
                        json_decref(w->valid_if);
                        w->valid_if = NULL;
                    }
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
    if (v->valid_if != NULL) json_object_set_new(o, "valid_if", json_deep_copy(v->valid_if));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_object_set_new(o, "decided_by", json_string("exact"));
    json_array_append_new(run->results, o);
}

int rs_run_variant_or_vanishing(rs_variant_t **v, int *done, rs_run_t *run, const char *what, int numeric)
{
    int r = numeric ? rs_run_numeric_variant(run, v) : rs_run_default_variant(run, v);
    *done = 0;
    if (r != RS_OK && *v != NULL && (*v)->vanishes) {
        *done = 1;
        return rs_run_emit_vanishing(run, *v, what);
    }
    return r;
}

int rs_run_failed_or_vanishing(rs_run_t *run, int r, const rs_variant_t *v, const char *what)
{
    return (r != RS_OK && v != NULL && v->vanishes) ? rs_run_emit_vanishing(run, v, what) : r;
}

int rs_run_emit_vanishing(rs_run_t *run, const rs_variant_t *v, const char *what)
{
    json_t *o = json_object();
    rs_error_init(run->err);
    json_object_set_new(o, "analysis", json_string(what));
    json_object_set_new(o, "status", json_string(rs_status_name(RS_STATUS_SINGULAR)));
    json_object_set_new(o, "vanishes", json_true());
    if (strcmp(what, "hurwitz") == 0) json_object_set_new(o, "verdict", json_string("never stable"));
    json_object_set_new(o, "singular", json_string(
        "det A(lambda) vanishes identically at these values: every lambda is a root, the equations are "
        "dependent and define no recurrence; not stable"));
    rs_run_emit_exact(run, v, o);
    return RS_OK;
}

char *rs_cond_string(const fmpz_mpoly_t p, const rs_scheme_t s, const char *rel)
{
    char *ps = rs_polyfmt_fmpz_mpoly(p, (const char **) s->vars, s->zctx);
    char *line = malloc(strlen(ps) + strlen(rel) + 2);
    sprintf(line, "%s %s", ps, rel);
    free(ps);
    return line;
}

/* digits, " + - * ^" and the names: ASCII when every name is, and then
 * jansson's UTF-8 scan is skipped (a 60 MB string for D_11 of a 6-mass
 * chain, issue 17); the bytes are the same */
static int names_ascii(const rs_scheme_t s)
{
    slong k;
    for (k = 0; k < s->nvars; k++) {
        const unsigned char *c;
        for (c = (const unsigned char *) s->vars[k]; *c != '\0'; c++)
            if (*c >= 0x80) return 0;
    }
    return 1;
}

static json_t *json_text(const char *str, size_t len, int ascii)
{
    return ascii ? json_stringn_nocheck(str, len) : json_stringn(str, len);
}

json_t *rs_json_zpoly(const fmpz_mpoly_t p, const rs_scheme_t s)
{
    return rs_json_zpoly_line(p, s, NULL, NULL, NULL, NULL);
}

json_t *rs_json_zpoly_line(const fmpz_mpoly_t p, const rs_scheme_t s, const char *rel, json_t **line,
                           char **scratch, size_t *cap)
{
    char *own = NULL, **buf = scratch != NULL ? scratch : &own;
    size_t own_cap = 0, *bcap = scratch != NULL ? cap : &own_cap;
    json_t *j = NULL;
    int ascii = names_ascii(s);
    /* one printing for both strings: the text, then " rel" after it */
    char *tail = rel != NULL ? malloc(strlen(rel) + 2) : NULL;
    slong n;
    if (tail != NULL) sprintf(tail, " %s", rel);
    n = rs_polyfmt_fmpz_mpoly_into(buf, bcap, p, (const char **) s->vars, s->zctx, tail);
    if (n >= 0) {
        size_t t = tail != NULL ? strlen(tail) : 0;
        j = json_text(*buf, (size_t) n - t, ascii);
        if (line != NULL) *line = tail != NULL ? json_text(*buf, (size_t) n, ascii) : NULL;
    } else if (line != NULL) {
        *line = NULL;
    }
    free(tail);
    free(own);
    return j;
}

/* from this many terms on (some kilobytes of text) a polynomial waits for
 * the report; shorter ones, which the analyses and renderers may compare
 * as text ("0 > 0"), stay strings */
#define POLYTEXT_MIN_TERMS 64

json_t *rs_run_json_zpoly_line(const rs_run_t *run, fmpz_mpoly_t p, const rs_scheme_t s, const char *rel,
                               json_t **line, char **scratch, size_t *cap)
{
    if (run->opt->polytext == NULL || fmpz_mpoly_length(p, s->zctx) < POLYTEXT_MIN_TERMS || !names_ascii(s))
        return rs_json_zpoly_line(p, s, rel, line, scratch, cap);
    return rs_polytext_defer(run->opt->polytext, p, (const char *const *) s->vars, s->zctx, rel, line);
}

void rs_run_polytext_keep(const rs_run_t *run)
{
    if (run->opt->polytext != NULL) rs_polytext_keep(run->opt->polytext);
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
    fmpz_mpoly_struct *c = flint_malloc((FLINT_MAX(d, 0) + 1) * sizeof(fmpz_mpoly_struct));
    for (k = 0; k <= d; k++) fmpz_mpoly_init(c + k, s->zctx);
    rs_polyfmt_coeffs(c, p, var, s->zctx);   /* one pass over p, not one per power */
    for (k = 0; k <= d; k++) {
        /* as rs_polyfmt_collected: large symbolic coefficients take seconds
         * (the degree-58 fuzz seed); the sticky budget makes the run report */
        if (rs_budget_check(NULL, "printing a polynomial") != RS_OK) break;
        json_array_append_new(arr, rs_json_zpoly(c + k, s));
    }
    for (k = 0; k <= d; k++) fmpz_mpoly_clear(c + k, s->zctx);
    flint_free(c);
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

rs_bound_t *rs_run_bounds(rs_run_t *run)
{
    const rs_case_struct *c = run->c;
    rs_bound_t *b = flint_malloc((c->nparams + 1) * sizeof(rs_bound_t));
    slong i;
    rs_bounds_init(b, c->nparams);
    for (i = 0; i < c->nassume; i++)
        rs_bounds_add(b, &c->assume[i], c, run->err);
    return b;
}

void rs_run_bounds_clear(rs_bound_t *b, rs_run_t *run)
{
    rs_bounds_clear(b, run->c->nparams);
    flint_free(b);
}

int *rs_run_signs(rs_run_t *run, const rs_scheme_t s)
{
    rs_bound_t *b = rs_run_bounds(run);
    int *sign = flint_calloc(s->nvars, sizeof(int));
    rs_bounds_signs(sign, b, run->c->nparams);
    rs_run_bounds_clear(b, run);
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

/* The variant with the case's set values substituted. */
int rs_run_default_variant(rs_run_t *run, rs_variant_t **v)
{
    rs_assign_t *a;
    slong n;
    int r;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(v, run, a, n);
    rs_assign_free(a, n);
    return r;
}

/* Comma-separated parameters still symbolic in p (malloc'd, "" if none). */
char *rs_run_free_params(const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    size_t cap = 16, len = 0;
    char *out = malloc(cap);
    slong i;
    out[0] = '\0';
    for (i = 0; i < s->nvars; i++) {
        size_t need;
        if (i == s->lambda_var || fmpz_mpoly_degree_si(v->cp->p, i, s->zctx) <= 0) continue;
        need = strlen(s->vars[i]) + 3;
        if (len + need + 1 > cap) { cap = 2 * (len + need + 1); out = realloc(out, cap); }
        len += (size_t) sprintf(out + len, "%s%s", len ? ", " : "", s->vars[i]);
    }
    return out;
}

/* the free parameters but tv (the analysis' own variable), as text */
static char *free_params_but(const rs_variant_t *v, slong tv)
{
    const rs_scheme_struct *s = v->s;
    size_t len = 0;
    char *out = malloc(1);
    slong i;
    out[0] = '\0';
    for (i = 0; i < s->nvars; i++) {
        if (i == s->lambda_var || i == tv || fmpz_mpoly_degree_si(v->cp->p, i, s->zctx) <= 0) continue;
        out = realloc(out, len + strlen(s->vars[i]) + 3);
        len += (size_t) sprintf(out + len, "%s%s", len ? ", " : "", s->vars[i]);
    }
    return out;
}

/* p as a univariate integer polynomial; error naming the free parameters
 * when some are still symbolic. */
int rs_run_numeric_poly(fmpz_poly_t p, rs_run_t *run, const rs_request_t *q,
                        const rs_variant_t *v, const char *what)
{
    if (!rs_charpoly_get_fmpz_poly(p, v->cp->p, v->s->lambda_var, v->s->zctx)) {
        char *fp = rs_run_free_params(v);
        char msg[512];
        snprintf(msg, sizeof msg, "%s needs every parameter set to a number; still symbolic: %s "
                 "(use set, --set, or region/claim for symbolic parameters)", what, fp);
        free(fp);
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
    }
    return RS_OK;
}

void rs_json_add_count(json_t *o, const rs_rootcount_t rc)
{
    json_t *m = json_array();
    slong k;
    json_object_set_new(o, "status", json_string(rs_status_name(rs_rootcount_status(rc))));
    json_object_set_new(o, "degree", json_integer(rc->degree));
    json_object_set_new(o, "inside", json_integer(rc->inside));
    json_object_set_new(o, "on", json_integer(rc->on));
    json_object_set_new(o, "outside", json_integer(rc->outside));
    json_object_set_new(o, "at_one", json_integer(rc->at_one));
    json_object_set_new(o, "at_minus_one", json_integer(rc->at_minus_one));
    for (k = 1; k < RS_ROOTCOUNT_MAXMULT; k++)
        if (rc->on_mult[k] > 0)
            json_array_append_new(m, json_pack("{s:I,s:I}", "multiplicity", (json_int_t) k,
                                               "roots", (json_int_t) rc->on_mult[k]));
    json_object_set_new(o, "on_multiplicities", m);
    if (rc->at_zero > 0) json_object_set_new(o, "at_zero", json_integer(rc->at_zero));
}

void rs_run_dead_beat_nonzero(fmpz_mpoly_t kept, json_t *conds, rs_run_t *run, const rs_scheme_t s,
                              const fmpz_mpoly_t c)
{
    const rs_case_struct *cs = run->c;
    rs_bound_t *bd = flint_malloc((cs->nparams + 1) * sizeof(rs_bound_t));
    int *sign = rs_run_signs(run, s);
    fmpz_mpoly_factor_t fa;
    slong i;
    rs_bounds_init(bd, cs->nparams);
    for (i = 0; i < cs->nassume; i++) rs_bounds_add(bd, &cs->assume[i], cs, run->err);
    fmpz_mpoly_one(kept, s->zctx);
    fmpz_mpoly_factor_init(fa, s->zctx);
    if (!fmpz_mpoly_factor(fa, c, s->zctx)) {
        fmpz_mpoly_factor_one(fa, s->zctx);   /* unfactored: c != 0 as it is */
        if (!fmpz_mpoly_is_fmpz(c, s->zctx)) fmpz_mpoly_factor_append_ui(fa, c, 1, s->zctx);
    }
    for (i = 0; i < fa->num; i++) {
        /* the sign test as jury's: of one sign (strictly) for every admissible value */
        if (rs_positivity_sign_bounds(fa->poly + i, (const rs_sign_t *) sign, bd, FLINT_MIN(cs->nparams, s->nvars),
                                      s->zctx, NULL) != 0)
            continue;
        {
            char *line = rs_cond_string(fa->poly + i, s, "!= 0");
            rs_json_append_unique(conds, line);
            free(line);
        }
        fmpz_mpoly_mul(kept, kept, fa->poly + i, s->zctx);
    }
    fmpz_mpoly_factor_clear(fa, s->zctx);
    flint_free(sign);
    rs_bounds_clear(bd, cs->nparams);
    flint_free(bd);
}

int rs_run_nonzero_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    return rs_hurwitz_sign_at((const fmpz_mpoly_struct *) data, pt, s->zctx) != 0;
}

void rs_json_zero_roots(json_t *roots, slong k, slong digits)
{
    slong i;
    acb_t z;
    acb_init(z);
    for (i = 0; i < k; i++) {
        json_t *e = rs_json_acb(z, digits);
        json_object_set_new(e, "abs", rs_json_arb(acb_realref(z), digits));
        json_object_set_new(e, "multiplicity", json_integer(k));
        json_array_append_new(roots, e);
    }
    acb_clear(z);
}

void rs_run_radius_dead_beat_json(json_t *o)
{
    json_object_set_new(o, "method", json_string("exact: det A = c*lambda^k, every root is 0"));
    json_object_set_new(o, "certified", json_true());
    json_object_set_new(o, "lower", json_string("0"));
    json_object_set_new(o, "upper", json_string("0"));
    json_object_set_new(o, "rho", json_string("0"));
    json_object_set_new(o, "roots", json_array());
}

void rs_run_count_zeros(rs_rootcount_t rc, const rs_variant_t *v, const fmpz_poly_t p)
{
    slong k = v->cp->removed_lambda_power, z = 0;
    if (p != NULL && !fmpz_poly_is_zero(p))
        while (z < fmpz_poly_length(p) && fmpz_is_zero(p->coeffs + z)) z++;
    rc->inside += k;
    rc->degree += k;
    rc->at_zero = k + z;
}

/* Which exact Schur-Cohn route counted (jury.c): the key
 * "schur_cohn_route" of radius and stability results. */
json_t *rs_json_jury_route(const rs_jury_t ju)
{
    const char *m = ju->route == RS_JURY_ROUTE_MODULAR ? "Schur-Cohn minors modulo primes (Hadamard bound, CRT)"
        : ju->route == RS_JURY_ROUTE_MATRIX ? "inertia of the Schur-Cohn matrix (signs of its characteristic polynomial)"
        : ju->route == RS_JURY_ROUTE_GCD ? "gcd(p, p*) only (no root left off the circle's pairs)"
        : "integer Schur-Cohn table";
    json_t *o = json_pack("{s:s}", "method", m);
    if (ju->route == RS_JURY_ROUTE_MODULAR)
        json_object_set_new(o, "primes", json_integer(ju->modular_primes));
    /* the circle roots and reciprocal pairs were split off first */
    if (ju->gcd_degree > 0)
        json_object_set_new(o, "gcd_degree", json_integer(ju->gcd_degree));
    return o;
}

/* The exact count of p by Routh (bilinear) and Schur-Cohn, which must agree:
 * a disagreement sets the inconsistency flag and says so in o. */
int rs_run_exact_count(rs_rootcount_t rc, rs_run_t *run, const fmpz_poly_t p, json_t *o)
{
    rs_routh_t ro;
    rs_jury_t ju;
    int r, agree = 1;
    if (fmpz_poly_degree(p) < 1) {
        /* det = c lambda^k: every root at 0 (dead-beat), nothing to count */
        rs_rootcount_init(rc);
        rc->degree = 0;
        if (o != NULL)
            json_object_set_new(o, "dead_beat", json_string(
                "det A = c*lambda^k: every root is 0 (dead-beat), spectral radius 0"));
        return RS_OK;
    }
    rs_routh_init(ro);
    rs_jury_init(ju);
    /* a regular array is counted in integers (routh_int.c), the same count
     * as the rational array's without its gcds: a minute against 14 s at
     * degree 500, 9.9 against 2.4 ms at Wilkinson-type degree 40; singular
     * arrays go to the exact generalised array */
    r = rs_routh_int_count(ro->count, p, run->err);
    if (r == RS_ERR_UNDECIDED) r = rs_routh_fmpz_poly(ro, p, run->err);
    if (r == RS_OK) r = rs_jury_count_fmpz_poly(ju, p, run->err);
    if (r == RS_OK) {
        agree = rs_rootcount_equal(ro->count, ju->count);
        *rc = *ro->count;
        if (!agree) {
            run->outcome |= RS_OUTCOME_INCONSISTENT;
            if (o != NULL) {
                json_t *d = json_object();
                rs_json_add_count(d, ju->count);
                json_object_set_new(o, "schur_cohn_count", d);
            }
        }
        if (o != NULL) {
            json_object_set_new(o, "methods", json_pack("[ss]", "routh (bilinear)", "schur-cohn"));
            json_object_set_new(o, "schur_cohn_route", rs_json_jury_route(ju));
            json_object_set_new(o, "agree", json_boolean(agree));
        }
    }
    rs_routh_clear(ro);
    rs_jury_clear(ju);
    return r;
}

static json_t *circle_roots_json(const rs_semisimple_t ss)
{
    json_t *arr = json_array();
    slong i;
    for (i = 0; i < ss->nfactors; i++) {
        const rs_circle_factor_struct *f = ss->f + i;
        char *str = rs_polyfmt_fmpz_poly(f->factor, "lambda");
        json_array_append_new(arr, json_pack("{s:s,s:I,s:I,s:I,s:b}", "factor", str,
                                             "multiplicity", (json_int_t) f->mult,
                                             "roots", (json_int_t) f->on,
                                             "kernel_dim", (json_int_t) f->kernel,
                                             "semisimple", f->semisimple));
        free(str);
    }
    return arr;
}

json_t *rs_run_point_json(const rs_run_t *run, fmpq *const *pt, slong n)
{
    json_t *o = json_object();
    slong k;
    for (k = 0; k < run->c->nparams && k < n; k++)
        json_object_set_new(o, run->c->params[k].name, rs_json_fmpq(pt[k]));
    return o;
}

void rs_json_set_singular_step(json_t *o)
{
    json_object_set_new(o, "status", json_string(rs_status_name(RS_STATUS_SINGULAR)));
    json_object_set_new(o, "singular", json_string(
        "the leading coefficient of det A(lambda) vanishes here: the implicit step cannot be solved "
        "(the counts are those of the reduced polynomial)"));
}

int rs_run_verdict(rs_status_t *st, rs_run_t *run, const rs_scheme_t s, const slong *vars,
                   const fmpq *vals, slong nv, const fmpz_poly_t p, const rs_rootcount_t rc,
                   int singular, json_t *o)
{
    rs_semisimple_t ss;
    int r = RS_OK;
    if (singular) {
        *st = RS_STATUS_SINGULAR;
        if (o != NULL) rs_json_set_singular_step(o);
        return RS_OK;
    }
    rs_semisimple_init(ss);
    r = rs_semisimple_verdict(st, ss, s, vars, vals, nv, p, rc, o != NULL, run->err);
    if (r == RS_OK && o != NULL && rc->on > 0) {
        json_object_set_new(o, "circle_roots", circle_roots_json(ss));
        json_object_set_new(o, "rule", json_string(ss->system ?
            "system: a circle root is bounded iff semisimple (dim ker A(lambda0) = its multiplicity in det A)" :
            "scalar recurrence: a repeated circle root is unstable"));
    }
    rs_semisimple_clear(ss);
    if (o != NULL && r == RS_OK)
        json_object_set_new(o, "status", json_string(rs_status_name(*st)));
    return r;
}

int rs_run_numeric_verdict(rs_run_t *run, const fmpz_poly_t p, const rs_rootcount_t rc, json_t *o)
{
    rs_variant_t *v;
    rs_status_t st;
    int r = rs_run_numeric_variant(run, &v);
    if (r == RS_OK) r = rs_run_verdict(&st, run, v->s, NULL, NULL, 0, p, rc, v->singular, o);
    return r;
}

int rs_run_point_admissible(const rs_condpoly_t *cps, slong ncps, fmpq *const *pp, const rs_scheme_t s)
{
    slong k;
    int ok = 1;
    for (k = 0; k < ncps && ok; k++) ok = rs_condpoly_holds(cps + k, pp, s) == 1;
    for (k = 0; k < s->nnonzero && ok; k++) {
        fmpq_t z;
        fmpq_init(z);
        fmpq_mpoly_evaluate_all_fmpq(z, s->nonzero + k, pp, s->ctx);
        ok = !fmpq_is_zero(z);
        fmpq_clear(z);
    }
    return ok;
}

int rs_run_charpoly_at(fmpq_poly_t w, const rs_variant_t *v, const slong *vars, const fmpq *vals, slong nv)
{
    const rs_scheme_struct *s = v->s;
    fmpq_mpoly_t q;
    slong k;
    int ok;
    fmpq_mpoly_init(q, s->ctx);
    fmpq_one(q->content);
    fmpz_mpoly_set(q->zpoly, v->cp->p, s->zctx);
    fmpq_mpoly_reduce(q, s->ctx);
    for (k = 0; k < nv; k++) {
        slong x = vars != NULL ? vars[k] : k;
        if (fmpz_mpoly_degree_si(v->cp->p, x, s->zctx) > 0)
            fmpq_mpoly_evaluate_one_fmpq(q, q, x, vals + k, s->ctx);
    }
    ok = fmpq_mpoly_get_fmpq_poly(w, q, s->lambda_var, s->ctx);
    fmpq_mpoly_clear(q, s->ctx);
    return ok;
}

int rs_run_point_status(rs_status_t *st, rs_rootcount_t rc, rs_run_t *run, const rs_variant_t *v,
                        const slong *vars, const fmpq *vals, slong nv)
{
    const rs_scheme_struct *s = v->s;
    fmpq_poly_t w;
    fmpz_poly_t u;
    int r = RS_OK;
    /* complex set values: p over Q(i) decides (complex_poly.c) */
    if (run->c->ncsets > 0) return rs_run_cx_point_status(st, rc, run, v, vars, vals, nv, -1);
    fmpq_poly_init(w);
    fmpz_poly_init(u);
    rs_rootcount_init(rc);
    if (!rs_run_charpoly_at(w, v, vars, vals, nv)) {
        r = rs_error_set(run->err, RS_ERR_INTERNAL, "point verdict: a parameter is still symbolic");
    } else if (v->singular || fmpq_poly_is_zero(w) || fmpq_poly_degree(w) < v->cp->degree) {
        /* the leading coefficient of det A vanishes here: no step can be solved */
        *st = RS_STATUS_SINGULAR;
    } else {
        fmpq_poly_get_numerator(u, w);
        fmpz_poly_primitive_part(u, u);
        r = rs_run_exact_count(rc, run, u, NULL);
        if (r == RS_OK) r = rs_run_verdict(st, run, s, vars, vals, nv, u, rc, 0, NULL);
        if (r == RS_OK) rs_run_count_zeros(rc, v, u);
        /* a char line over Q(i): p's own counts (not p conj(p)'s), its verdict
         * checked against the block form's */
        if (r == RS_OK && s->complex_char) r = rs_run_cx_point_status(st, rc, run, v, vars, vals, nv, (int) *st);
    }
    fmpz_poly_clear(u);
    fmpq_poly_clear(w);
    return r;
}

/* ---- conditions checked at sample points ----------------------------------- */

/* Candidate values of one parameter inside its assumed interval b: both
 * signs when the sign is free (a free-sign leading coefficient must meet
 * both branches), spread over bounded intervals. */
static slong sample_candidates(fmpq *c, const rs_bound_t *b)
{
    static const slong num[] = {1, 3, 1, 7, 2, 5, 1, 11, 9, 4};
    static const slong den[] = {2, 1, 3, 2, 1, 3, 1, 4, 7, 1};
    slong n = 0, i;
    fmpq_t t, w;
    fmpq_init(t);
    fmpq_init(w);
    if (b->fixed) {
        fmpq_set(c + n++, b->lo);
    } else if (b->has_lo && b->has_hi) {
        fmpq_sub(w, b->hi, b->lo);
        for (i = 1; i < 10; i++) {       /* lo + w*i/10, never an end */
            fmpq_mul_si(t, w, i);
            fmpz_mul_ui(fmpq_denref(t), fmpq_denref(t), 10);
            fmpq_canonicalise(t);
            fmpq_add(c + n++, b->lo, t);
        }
    } else {
        for (i = 0; i < 10; i++) {
            fmpq_set_si(t, num[i], (ulong) den[i]);
            if (b->has_lo) fmpq_add(c + n++, b->lo, t);
            else if (b->has_hi) fmpq_sub(c + n++, b->hi, t);
            else { if (i % 2) fmpq_neg(t, t); fmpq_set(c + n++, t); }
        }
    }
    fmpq_clear(t);
    fmpq_clear(w);
    return n;
}

/* p(lambda) at the rational point pp as an integer polynomial (denominators
 * cleared: same roots). */
static void p_at_point(fmpz_poly_t u, const rs_variant_t *v, fmpq *const *pp)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t c;
    fmpq_poly_t f;
    fmpq_t x;
    slong j;
    fmpz_mpoly_init(c, s->zctx);
    fmpq_poly_init(f);
    fmpq_init(x);
    for (j = 0; j <= v->cp->degree; j++) {
        rs_charpoly_coeff(c, v->cp->p, j, s->lambda_var, s->zctx);
        rs_hurwitz_eval(x, c, pp, s->zctx);
        fmpq_poly_set_coeff_fmpq(f, j, x);
    }
    fmpq_poly_get_numerator(u, f);
    fmpz_mpoly_clear(c, s->zctx);
    fmpq_poly_clear(f);
    fmpq_clear(x);
}

#define SAMPLE_POINTS 12
#define SAMPLE_TRIES 80

void rs_run_sample_disagree(json_t *chk, json_t *point, int says, const char *verdict)
{
    json_object_set_new(chk, "point", point);
    json_object_set_new(chk, "conditions_say", json_string(says ? "stable" : "not stable"));
    json_object_set_new(chk, "exact_verdict", json_string(verdict));
}

void rs_run_sample_check_set(rs_run_t *run, json_t *o, json_t *chk, slong points, int agree, const char *against)
{
    json_object_set_new(chk, "points", json_integer(points));
    json_object_set_new(chk, "agree", json_boolean(agree));
    json_object_set_new(chk, "against", json_string(against));
    json_object_set_new(o, "sample_check", chk);
    if (!agree) run->outcome |= RS_OUTCOME_INCONSISTENT;
}

void rs_sample_pts_init(rs_sample_pts_t *P, rs_run_t *run, const rs_variant_t *v, const fmpz_mpoly_t a,
                        const fmpz_mpoly_t b, slong skip)
{
    const rs_scheme_struct *s = P->s = v->s;
    const char *key;
    json_t *val;
    rs_error_t e2;
    slong k;
    P->nfree = P->ncp = P->j = 0;
    P->fv = flint_malloc((size_t) (s->nvars + 1) * sizeof(slong));
    P->cps = calloc((size_t) run->c->nassume + 1, sizeof(rs_condpoly_t));
    P->pt = _fmpq_vec_init(s->nvars);
    P->pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
    for (k = 0; k < s->nvars; k++) {
        P->pp[k] = P->pt + k;
        if (k != s->lambda_var && k != skip
            && (fmpz_mpoly_degree_si(a, k, s->zctx) > 0 || fmpz_mpoly_degree_si(b, k, s->zctx) > 0))
            P->fv[P->nfree++] = k;
    }
    rs_error_init(e2);
    for (k = 0; k < run->c->nassume; k++) {
        if (rs_condpoly_compile(P->cps + P->ncp, &run->c->assume[k], s, run->c, e2) != RS_OK) break;
        P->ncp++;
    }
    rs_error_clear(e2);
    json_object_foreach(v->assigned, key, val) {
        slong idx = rs_case_param_index(run->c, key);
        if (idx >= 0 && idx < s->nvars && fmpq_set_str(P->pt + idx, json_string_value(val), 10) == 0)
            fmpq_canonicalise(P->pt + idx);
    }
}

int rs_sample_pts_next(rs_sample_pts_t *P)
{
    static const slong num[] = {1, 1, 2, 1, 3, -1, 5, -1, 7, 0, 13, -2, 1, 9, 10, -3, 99, 3};
    static const slong den[] = {2, 1, 1, 3, 2, 2, 1, 1, 10, 1, 10, 1, 7, 8, 1, 2, 100, 4};
    const slong nc = (slong) (sizeof num / sizeof num[0]);
    slong k;
    for (; P->j < RS_SAMPLE_PTS_TRIES; P->j++) {
        slong j = P->j;
        for (k = 0; k < P->nfree; k++) {
            slong i = (j * (2 * k + 1) + j / nc + 5 * k) % nc;
            fmpq_set_si(P->pt + P->fv[k], num[i], (ulong) den[i]);
        }
        if (rs_run_point_admissible(P->cps, P->ncp, P->pp, P->s)) {
            P->j++;
            return 1;
        }
    }
    return 0;
}

json_t *rs_sample_pts_json(const rs_sample_pts_t *P)
{
    json_t *o = json_object();
    slong k;
    for (k = 0; k < P->nfree; k++) json_object_set_new(o, P->s->vars[P->fv[k]], rs_json_fmpq(P->pt + P->fv[k]));
    return o;
}

void rs_sample_pts_clear(rs_sample_pts_t *P)
{
    slong k;
    for (k = 0; k < P->ncp; k++) rs_condpoly_clear(P->cps + k, P->s);
    free(P->cps);
    _fmpq_vec_clear(P->pt, P->s->nvars);
    flint_free(P->pp);
    flint_free(P->fv);
}

/* Checks conditions (holds(data, point) = 1 stable, 0 not, -1 on a boundary)
 * against the exact verdict (Routh and Schur-Cohn on p at the point) at a
 * few deterministic rational points that satisfy the assume lines and the
 * non-zero assumptions; points where p loses degree are skipped.  Adds
 * "sample_check" to o; a disagreement marks the run inconsistent (exit 3). */
int rs_run_sample_check(rs_run_t *run, const rs_variant_t *v, rs_holds_fn holds, const void *data, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    slong np = run->c->nparams, i, j, k, ncp = 0, nok = 0, maxpts = SAMPLE_POINTS;
    rs_bound_t *b = flint_malloc((np + 1) * sizeof(rs_bound_t));
    rs_condpoly_t *cps = calloc((size_t) run->c->nassume + 1, sizeof(rs_condpoly_t));
    fmpq *cand = _fmpq_vec_init(10 * (np + 1)), *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc(s->nvars * sizeof(fmpq *));
    slong *ncand = flint_calloc(np + 1, sizeof(slong));
    json_t *chk = json_object(), *bad = NULL;
    rs_error_t e2;
    const char *key;
    json_t *val;
    int r = RS_OK;

    rs_error_init(e2);
    rs_bounds_init(b, np);
    for (i = 0; i < run->c->nassume; i++) rs_bounds_add(b, &run->c->assume[i], run->c, e2);
    json_object_foreach(v->assigned, key, val) {      /* set values and `at` values */
        slong idx = rs_case_param_index(run->c, key);
        if (idx < 0 || fmpq_set_str(b[idx].lo, json_string_value(val), 10) != 0) continue;
        fmpq_canonicalise(b[idx].lo);
        fmpq_set(b[idx].hi, b[idx].lo);
        b[idx].fixed = b[idx].has_lo = b[idx].has_hi = b[idx].lo_closed = b[idx].hi_closed = 1;
    }
    for (i = 0; i < run->c->nassume; i++) {
        if (rs_condpoly_compile(cps + ncp, &run->c->assume[i], s, run->c, e2) != RS_OK) break;
        ncp++;
    }
    for (i = 0; i < s->nvars; i++) pp[i] = pt + i;
    for (k = 0; k < np; k++) ncand[k] = rs_bound_empty(b + k) ? 0 : sample_candidates(cand + 10 * k, b + k);
    {
        char *fp = rs_run_free_params(v);
        if (*fp == '\0') maxpts = 1;   /* nothing varies */
        free(fp);
    }
    for (j = 0; j < SAMPLE_TRIES && nok < maxpts && r == RS_OK && bad == NULL; j++) {
        int ok = 1, says;
        fmpz_poly_t u;
        for (k = 0; k < np && ok; k++) {
            if (ncand[k] == 0) { ok = 0; break; }
            /* a different stride per parameter: the points mix the candidates */
            fmpq_set(pt + k, cand + 10 * k + (j * (2 * k + 1) + j / ncand[k] + k) % ncand[k]);
        }
        if (!ok || !rs_run_point_admissible(cps, ncp, pp, s)) continue;
        fmpz_poly_init(u);
        p_at_point(u, v, pp);
        says = holds(data, pp, s);
        /* v->singular: the set values already dropped the degree, u's is v's */
        if (fmpz_poly_degree(u) == v->cp->degree && !v->singular && says >= 0) {
            rs_rootcount_t rc;
            rs_status_t st;
            rs_rootcount_init(rc);
            r = rs_run_exact_count(rc, run, u, NULL);
            rs_run_count_zeros(rc, v, u);
            st = rs_rootcount_status(rc);
            nok++;
            if (r == RS_OK && (st == RS_STATUS_STABLE) != (says == 1)) {
                bad = json_object();
                for (k = 0; k < np; k++)
                    if (fmpz_mpoly_degree_si(v->cp->p, k, s->zctx) > 0)
                        json_object_set_new(bad, run->c->params[k].name, rs_json_fmpq(pt + k));
                rs_run_sample_disagree(chk, bad, says, rs_status_name(st));
                rs_json_add_count(chk, rc);
            }
            rs_rootcount_clear(rc);
        } else if ((fmpz_poly_degree(u) < v->cp->degree || v->singular) && says >= 0) {
            nok += v->singular;
            if (says == 0) { fmpz_poly_clear(u); continue; }
            /* a degree drop (or p = 0) is singular, never stable: conditions
             * that hold there miss the leading coefficient's zero */
            bad = json_object();
            for (k = 0; k < np; k++)
                if (fmpz_mpoly_degree_si(v->cp->p, k, s->zctx) > 0)
                    json_object_set_new(bad, run->c->params[k].name, rs_json_fmpq(pt + k));
            rs_run_sample_disagree(chk, bad, says, fmpz_poly_is_zero(u) ? "singular (p = 0)" : "singular");
        }
        fmpz_poly_clear(u);
    }
    rs_run_sample_check_set(run, o, chk, nok, bad == NULL, "exact verdict (Routh and Schur-Cohn) at rational points "
                            "satisfying the assumptions");
    for (i = 0; i < ncp; i++) rs_condpoly_clear(cps + i, s);
    free(cps);
    rs_bounds_clear(b, np);
    flint_free(b);
    _fmpq_vec_clear(cand, 10 * (np + 1));
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    flint_free(ncand);
    return r;
}

/* ---- numbers ---------------------------------------------------------------- */

/* A root enclosure as midpoint strings re, im and one radius covering the
 * ball and the rounding of both printed midpoints (rounded up to double). */
json_t *rs_json_acb(const acb_t z, slong digits)
{
    json_t *o = json_object();
    mag_t mr, mi;
    arf_t a;
    char *re, *im;
    mag_init(mr);
    mag_init(mi);
    arf_init(a);
    re = rs_radius_str_ball(mr, acb_realref(z), digits);
    im = rs_radius_str_ball(mi, acb_imagref(z), digits);
    json_object_set_new(o, "re", json_string(re));
    json_object_set_new(o, "im", json_string(im));
    mag_max(mr, mr, mi);
    arf_set_mag(a, mr);
    json_object_set_new(o, "radius", json_real(arf_get_d(a, ARF_RND_UP)));
    flint_free(re);
    flint_free(im);
    mag_clear(mr);
    mag_clear(mi);
    arf_clear(a);
    return o;
}

/* p(x) of the polynomial as stated, det = content * lambda^k * p: the
 * normalisation (content, its sign) undone. */
json_t *rs_json_p_at(const rs_variant_t *v, slong x)
{
    const rs_scheme_struct *s = v->s;
    fmpq_mpoly_t t;
    fmpz_t xx;
    char *str;
    json_t *j;
    fmpq_mpoly_init(t, s->ctx);
    fmpz_init_set_si(xx, x);
    fmpz_mpoly_evaluate_one_fmpz(t->zpoly, v->cp->p, s->lambda_var, xx, s->zctx);
    fmpq_set(t->content, v->cp->content);
    if (x < 0 && (v->cp->removed_lambda_power & 1)) fmpq_neg(t->content, t->content);
    fmpq_mpoly_reduce(t, s->ctx);
    str = rs_polyfmt_fmpq_mpoly(t, (const char **) s->vars, s->ctx);
    j = json_string(str);
    free(str);
    fmpz_clear(xx);
    fmpq_mpoly_clear(t, s->ctx);
    return j;
}

/* ---- request words and parameters (region, limit, claim) -------------------------------------------------------- */

const char *rs_req_skip_blanks(const char *t)
{
    while (*t == ' ' || *t == '\t') t++;
    return t;
}

/* reads an identifier into buf (<= 64 chars); returns pointer after it or NULL */
const char *rs_req_read_name(const char *t, char *buf)
{
    size_t n = 0;
    t = rs_req_skip_blanks(t);
    if (!((*t >= 'a' && *t <= 'z') || (*t >= 'A' && *t <= 'Z') || *t == '_'))
        return NULL;
    while (((*t >= 'a' && *t <= 'z') || (*t >= 'A' && *t <= 'Z') || (*t >= '0' && *t <= '9') || *t == '_')
           && n < 64)
        buf[n++] = *t++;
    buf[n] = '\0';
    return t;
}

/* variables of p other than lambda that still occur */
slong rs_run_count_free(const fmpz_mpoly_t p, const rs_scheme_t s, slong except)
{
    slong v, n = 0;
    for (v = 0; v < s->nvars; v++)
        if (v != s->lambda_var && v != except && !(s->sqrt_d > 0 && v == s->sqrt_var)   /* sqrt(d): a number */
            && fmpz_mpoly_degree_si(p, v, s->zctx) > 0) n++;
    return n;
}

/* c_j(lambda): coefficient of t^j of p (no other free variable), as a
 * univariate polynomial in lambda. */
void rs_run_coeff_in(fmpz_poly_t out, const fmpz_mpoly_t p, slong tv, slong j, const rs_scheme_t s)
{
    fmpz_mpoly_t c;
    ulong jj = (ulong) j;
    fmpz_mpoly_init(c, s->zctx);
    fmpz_mpoly_get_coeff_vars_ui(c, p, &tv, &jj, 1, s->zctx);
    if (!fmpz_mpoly_get_fmpz_poly(out, c, s->lambda_var, s->zctx))
        fmpz_poly_zero(out);
    fmpz_mpoly_clear(c, s->zctx);
}

/* ---- typed requests: names and options ----------------------------------------------------------------- */

const rs_expr_t *rs_an_undeclared_name(const rs_expr_t *e, const rs_model_t m)
{
    const rs_expr_t *u;
    if (e == NULL) return NULL;
    if (e->kind == RS_EXPR_NAME)
        return (rs_case_param_index(m->c, e->name) < 0 && rs_model_unknown_index(m, e->name) < 0
                && rs_case_let_index(m->c, e->name) < 0 && !rs_name_is_reserved(e->name)) ? e : NULL;
    if ((u = rs_an_undeclared_name(e->a, m)) != NULL) return u;
    return rs_an_undeclared_name(e->b, m);
}

int rs_an_check_names(rs_run_t *run, const rs_request_t *q, const rs_expr_t *e)
{
    const rs_expr_t *u = rs_an_undeclared_name(e, run->m);
    if (u == NULL) return RS_OK;
    return rs_error_set_at(run->err, RS_ERR_INPUT, q->loc.file, u->line, u->col,
                           "unknown name '%s' (expected a declared param, unknown or let)", u->name);
}

const rs_optval_t *rs_an_opt(const rs_an_req_t *req, const char *key)
{
    static const rs_optval_t absent;
    slong k;
    for (k = 0; req->def->opts != NULL && req->def->opts[k].key != NULL; k++)
        if (strcmp(req->def->opts[k].key, key) == 0) return req->opt + k;
    return &absent;
}

const char *rs_an_opt_choice(const rs_an_req_t *req, const char *key)
{
    slong k;
    for (k = 0; req->def->opts != NULL && req->def->opts[k].key != NULL; k++)
        if (strcmp(req->def->opts[k].key, key) == 0)
            return req->def->opts[k].choices[req->opt[k].at != NULL ? req->opt[k].num : 0];
    return NULL;
}

/* The variant at the case's set values with parameter tv kept symbolic; an
 * input error at `at` naming `what` when another parameter is still free. */
int rs_run_variant_one_free(rs_variant_t **v, rs_run_t *run, const rs_request_t *q, const char *at, slong tv,
                            const char *what)
{
    const char *keep[1];
    rs_assign_t *a;
    slong na;
    int r;
    keep[0] = run->c->params[tv].name;
    rs_run_assignments(run, &a, &na, keep, 1, NULL, 0);
    r = rs_run_variant(v, run, a, na);
    rs_assign_free(a, na);
    if (r != RS_OK) return r;
    if (rs_run_count_free((*v)->cp->p, (*v)->s, tv) > 0) {
        char *fp = free_params_but(*v, tv);
        char msg[400];
        snprintf(msg, sizeof msg, "%s needs the other parameters set to numbers; still symbolic: %s", what, fp);
        free(fp);
        return rs_req_error(run, q, at, RS_ERR_INPUT, "%s", msg);
    }
    return RS_OK;
}
