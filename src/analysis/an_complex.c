/* an_complex.c -- the analyses at complex set values (`set z = -1/2 +
 * 3/2*i`): p(lambda) evaluated exactly over Q(i) (the other parameters
 * substituted as usual), then
 *   charpoly   p over Q(i);
 *   bilinear   q(s) = (1 - s)^n p((1 + s)/(1 - s)) over Q(i);
 *   routh      the Bilharz chain of q (stability/routh_complex.c);
 *   stability  complex Schur-Cohn and Bilharz on q, cross-checked (exit 3);
 *   radius     certified: the roots of p conj(p) (same moduli as p's) by
 *              the real radius code, p's own roots by acb_poly_find_roots,
 *              checked against the exact counts.
 * and `map re(NAME) A B N, im(NAME) C D M`: the complex plane of one
 * parameter (the test equation's z), every point exact by the same pair,
 * with the boundary locus sampled for the plot; `region re(NAME), im(NAME)`:
 * its stable set exact (z = x + i y, the Schur-Cohn conditions of p over
 * Q(i)[x, y] decomposed by an_region_cad.c).
 * A `char` line with i (a real 2x2 block form in the scheme) is read back
 * as A + i B from its block; there `stability` with every parameter real
 * also runs the complex pair beside the real verdict (routh_complex.h). */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <acb_poly.h>
#include <arb_poly.h>
#include <fmpz_vec.h>
#include <fmpq_vec.h>
#include "recstab/budget.h"
#include "analysis/registry.h"
#include "analysis/sweep_impl.h"
#include "analysis/an_region.h"
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"
#include "recstab/radius.h"
#include "recstab/bilinear.h"
#include "analysis/an_qd.h"

int rs_an_complex_mode(const rs_run_t *run) { return run->c->ncsets > 0; }

/* "a+b*i", "b*i", "a" (malloc'd) */
char *rs_complex_str(const fmpq_t re, const fmpq_t im)
{
    char *a = fmpq_get_str(NULL, 10, re), *b;
    char *out;
    fmpq_t t;
    if (fmpq_is_zero(im)) {
        out = malloc(strlen(a) + 1);
        strcpy(out, a);
        flint_free(a);
        return out;
    }
    fmpq_init(t);
    fmpq_abs(t, im);
    b = fmpq_get_str(NULL, 10, t);
    out = malloc(strlen(a) + strlen(b) + 8);
    if (fmpq_is_zero(re))
        sprintf(out, "%s%s%si", fmpq_sgn(im) < 0 ? "-" : "", fmpq_is_one(t) ? "" : b, fmpq_is_one(t) ? "" : "*");
    else
        sprintf(out, "%s%s%s%si", a, fmpq_sgn(im) < 0 ? "-" : "+", fmpq_is_one(t) ? "" : b,
                fmpq_is_one(t) ? "" : "*");
    fmpq_clear(t);
    flint_free(a);
    flint_free(b);
    return out;
}

static json_t *cpoly_coeffs(const fmpq_poly_t re, const fmpq_poly_t im)
{
    json_t *arr = json_array();
    slong n = FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im)), k;
    fmpq_t a, b;
    fmpq_init(a); fmpq_init(b);
    for (k = 0; k <= n; k++) {
        char *c;
        fmpq_poly_get_coeff_fmpq(a, re, k);
        fmpq_poly_get_coeff_fmpq(b, im, k);
        c = rs_complex_str(a, b);
        json_array_append_new(arr, json_string(c));
        free(c);
    }
    fmpq_clear(a); fmpq_clear(b);
    return arr;
}

/* ---- p at the complex point --------------------------------------------------- */

typedef struct {
    rs_variant_t *v;
    fmpq_poly_t re, im;   /* p(lambda) over Q(i) */
    slong deg;            /* its degree over Q(params) (lower here: singular) */
    json_t *at;           /* {"z": "-1/2+3/2*i", ...} */
    int neg;              /* p negated for a positive leading coefficient (det = -content lambda^k p) */
} cpoint_t;

static void cpoint_clear(cpoint_t *cp)
{
    fmpq_poly_clear(cp->re);
    fmpq_poly_clear(cp->im);
    json_decref(cp->at);
}

/* the complex value of variable v (a parameter) or -1 when it has none */
static slong cset_of(const rs_run_t *run, slong v)
{
    slong k;
    if (v >= run->c->nparams) return -1;
    for (k = 0; k < run->c->ncsets; k++)
        if (strcmp(run->c->csets[k].name, run->c->params[v].name) == 0) return k;
    return -1;
}

/* (fr, fi) = the product of z_v^e_v over the parameters with complex
 * values; 0 when a parameter without a value occurs (*free_var: it) */
static int term_factor(fmpq_t fr, fmpq_t fi, slong *free_var, const rs_run_t *run, const slong *ex,
                       slong nvars, slong lv)
{
    slong v, k;
    fmpq_t t;
    fmpq_init(t);
    fmpq_one(fr);
    fmpq_zero(fi);
    for (v = 0; v < nvars; v++) {
        slong c;
        if (v == lv || ex[v] == 0) continue;
        c = cset_of(run, v);
        if (c < 0) { *free_var = v; fmpq_clear(t); return 0; }
        for (k = 0; k < ex[v]; k++) {
            /* (fr + i fi)(a + i b) */
            const fmpq *a = run->c->csets[c].re, *b = run->c->csets[c].im;
            fmpq_mul(t, fr, a);
            fmpq_submul(t, fi, b);
            fmpq_mul(fi, fi, a);
            fmpq_addmul(fi, fr, b);
            fmpq_swap(fr, t);
        }
    }
    fmpq_clear(t);
    return 1;
}

/* adds (c * i^ib) * factor * lambda^e to re + i im */
static void add_term(fmpq_poly_t re, fmpq_poly_t im, const fmpq_t c, int ib, const fmpq_t fr, const fmpq_t fi,
                     slong e)
{
    fmpq_t x, y, old;
    fmpq_init(x); fmpq_init(y); fmpq_init(old);
    fmpq_mul(x, c, fr);
    fmpq_mul(y, c, fi);
    if (ib) { fmpq_swap(x, y); fmpq_neg(x, x); }   /* times i */
    fmpq_poly_get_coeff_fmpq(old, re, e);
    fmpq_add(old, old, x);
    fmpq_poly_set_coeff_fmpq(re, e, old);
    fmpq_poly_get_coeff_fmpq(old, im, e);
    fmpq_add(old, old, y);
    fmpq_poly_set_coeff_fmpq(im, e, old);
    fmpq_clear(x); fmpq_clear(y); fmpq_clear(old);
}

/* an fmpq_mpoly (times i when ib) at the point, into re + i im; 0 when a
 * parameter without a value occurs */
static int eval_mpoly(fmpq_poly_t re, fmpq_poly_t im, slong *free_var, const rs_run_t *run,
                      const fmpq_mpoly_t p, int ib, const rs_scheme_struct *s)
{
    slong i, n = fmpq_mpoly_length(p, s->ctx);
    slong *ex = flint_malloc(s->nvars * sizeof(slong));
    fmpq_t c, fr, fi;
    int ok = 1;
    fmpq_init(c); fmpq_init(fr); fmpq_init(fi);
    for (i = 0; i < n && ok; i++) {
        fmpq_mpoly_get_term_coeff_fmpq(c, p, i, s->ctx);
        fmpq_mpoly_get_term_exp_si(ex, p, i, s->ctx);
        ok = term_factor(fr, fi, free_var, run, ex, s->nvars, s->lambda_var);
        if (ok) add_term(re, im, c, ib, fr, fi, ex[s->lambda_var]);
    }
    fmpq_clear(c); fmpq_clear(fr); fmpq_clear(fi);
    flint_free(ex);
    return ok;
}

static int eval_zpoly(fmpq_poly_t re, fmpq_poly_t im, slong *free_var, const rs_run_t *run,
                      const fmpz_mpoly_t p, const rs_scheme_struct *s)
{
    slong i, n = fmpz_mpoly_length(p, s->zctx);
    slong *ex = flint_malloc(s->nvars * sizeof(slong));
    fmpq_t c, fr, fi;
    int ok = 1;
    fmpq_init(c); fmpq_init(fr); fmpq_init(fi);
    for (i = 0; i < n && ok; i++) {
        fmpz_mpoly_get_term_coeff_fmpz(fmpq_numref(c), p, i, s->zctx);
        fmpz_one(fmpq_denref(c));
        fmpz_mpoly_get_term_exp_si(ex, p, i, s->zctx);
        ok = term_factor(fr, fi, free_var, run, ex, s->nvars, s->lambda_var);
        if (ok) add_term(re, im, c, 0, fr, fi, ex[s->lambda_var]);
    }
    fmpq_clear(c); fmpq_clear(fr); fmpq_clear(fi);
    flint_free(ex);
    return ok;
}

static int cpoint_get(cpoint_t *cp, rs_run_t *run, const rs_request_t *q, const char *what)
{
    rs_assign_t *a;
    slong n, k, free_var = -1;
    const rs_scheme_struct *s;
    int r, ok;
    fmpq_poly_init(cp->re);
    fmpq_poly_init(cp->im);
    cp->at = rs_run_cx_at(run);
    cp->deg = 0;
    cp->neg = 0;
    /* the real set values substituted; the complex ones stay symbolic */
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(&cp->v, run, a, n);
    rs_assign_free(a, n);
    if (r != RS_OK) return r;
    s = cp->v->s;
    if (s->complex_char) {
        /* the block [[A, -B], [B, A]] of p = A + i B */
        ok = eval_mpoly(cp->re, cp->im, &free_var, run, s->M + 0, 0, s)
             && eval_mpoly(cp->re, cp->im, &free_var, run, s->M + 2, 1, s);
        cp->deg = FLINT_MAX(fmpq_mpoly_degree_si(s->M + 0, s->lambda_var, s->ctx),
                            fmpq_mpoly_degree_si(s->M + 2, s->lambda_var, s->ctx));
    } else {
        ok = eval_zpoly(cp->re, cp->im, &free_var, run, cp->v->cp->p, s);
        cp->deg = fmpz_mpoly_degree_si(cp->v->cp->p, s->lambda_var, s->zctx);
    }
    if (!ok) {
        char msg[300];
        snprintf(msg, sizeof msg, "%s needs every parameter set to a number (real or complex); still symbolic: %s",
                 what, s->vars[free_var]);
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
    }
    /* a divisor the equations were multiplied through by must not vanish here */
    for (k = 0; k < s->nnonzero; k++) {
        fmpq_poly_t dr, di;
        fmpq_poly_init(dr); fmpq_poly_init(di);
        ok = eval_mpoly(dr, di, &free_var, run, s->nonzero + k, 0, s);
        if (ok && fmpq_poly_is_zero(dr) && fmpq_poly_is_zero(di)) {
            const rs_loc_t *l = s->nonzero_loc + k;
            char *vals = json_dumps(cp->at, JSON_COMPACT);
            r = rs_error_set_at(run->err, RS_ERR_INPUT, l->file ? l->file : run->c->path, l->line, l->col,
                                "expected values that keep every divisor non-zero, found %s, where the "
                                "equations were multiplied through assuming %s", vals, s->nonzero_text[k]);
            free(vals);
        }
        fmpq_poly_clear(dr); fmpq_poly_clear(di);
        if (r != RS_OK) return r;
    }
    if (fmpq_poly_is_zero(cp->re) && fmpq_poly_is_zero(cp->im))
        return rs_req_error(run, q, q->text, RS_ERR_MATH, "%s: the characteristic polynomial vanishes at the "
                            "complex set values", what);
    /* as the real path (rs_charpoly_normalise) and rs_run_cx_poly: the
     * leading coefficient's real part positive (its imaginary part when
     * the real part is zero) */
    {
        slong d = FLINT_MAX(fmpq_poly_degree(cp->re), fmpq_poly_degree(cp->im));
        fmpq_t c;
        fmpq_init(c);
        fmpq_poly_get_coeff_fmpq(c, cp->re, d);
        if (fmpq_is_zero(c)) fmpq_poly_get_coeff_fmpq(c, cp->im, d);
        cp->neg = fmpq_sgn(c) < 0;
        if (cp->neg) { fmpq_poly_neg(cp->re, cp->re); fmpq_poly_neg(cp->im, cp->im); }
        fmpq_clear(c);
    }
    return RS_OK;
}

/* the bilinear variable: z, or s when a parameter is named z (param z complex) */
static const char *qvar(const rs_run_t *run) { return rs_case_param_index(run->c, "z") >= 0 ? "s" : "z"; }

static json_t *base_json(const char *name, const cpoint_t *cp)
{
    json_t *o = json_object();
    char *p = rs_cx_poly_str(cp->re, cp->im, "lambda");
    json_object_set_new(o, "analysis", json_string(name));
    json_object_set_new(o, "over", json_string("Q(i)"));
    json_object_set_new(o, "at", json_deep_copy(cp->at));
    json_object_set_new(o, "p", json_string(p));
    free(p);
    return o;
}

static void emit(rs_run_t *run, const cpoint_t *cp, json_t *o)
{
    json_object_set_new(o, "substituted", json_deep_copy(cp->v->assigned));
    json_object_set_new(o, "decided_by", json_string("exact"));
    json_array_append_new(run->results, o);
}

/* ---- the analyses --------------------------------------------------------------- */

int rs_an_complex_charpoly(rs_run_t *run, const rs_an_req_t *req)
{
    cpoint_t cp;
    json_t *o;
    int r = cpoint_get(&cp, run, req->q, "charpoly");
    if (r == RS_OK) {
        o = base_json("charpoly", &cp);
        json_object_set_new(o, "var", json_string("lambda"));
        json_object_set_new(o, "degree", json_integer(FLINT_MAX(fmpq_poly_degree(cp.re), fmpq_poly_degree(cp.im))));
        json_object_set_new(o, "coeffs", cpoly_coeffs(cp.re, cp.im));
        json_object_set_new(o, "poly", json_string(json_string_value(json_object_get(o, "p"))));
        /* the rational content split off the symbolic p (1 for a char line over Q(i)) */
        if (cp.v->s->complex_char) {
            json_object_set_new(o, "content", json_string(cp.neg ? "-1" : "1"));
        } else {
            fmpq_t c;
            fmpq_init(c);
            fmpq_set(c, cp.v->cp->content);
            if (cp.neg) fmpq_neg(c, c);
            json_object_set_new(o, "content", rs_json_fmpq(c));
            fmpq_clear(c);
            json_object_set_new(o, "removed_lambda_power", json_integer(cp.v->cp->removed_lambda_power));
        }
        emit(run, &cp, o);
    }
    cpoint_clear(&cp);
    return r;
}

int rs_an_complex_bilinear(rs_run_t *run, const rs_an_req_t *req)
{
    cpoint_t cp;
    json_t *o;
    int r = cpoint_get(&cp, run, req->q, "bilinear");
    if (r == RS_OK) {
        fmpq_poly_t qr, qi;
        slong n = FLINT_MAX(fmpq_poly_degree(cp.re), fmpq_poly_degree(cp.im)), d;
        char *str;
        fmpq_poly_init(qr); fmpq_poly_init(qi);
        rs_routh_complex_bilinear(qr, qi, cp.re, cp.im);
        d = FLINT_MAX(fmpq_poly_degree(qr), fmpq_poly_degree(qi));
        o = base_json("bilinear", &cp);
        json_object_set_new(o, "var", json_string(qvar(run)));
        json_object_set_new(o, "degree", json_integer(d));
        json_object_set_new(o, "coeffs", cpoly_coeffs(qr, qi));
        str = rs_cx_poly_str(qr, qi, qvar(run));
        json_object_set_new(o, "poly", json_string(str));
        free(str);
        json_object_set_new(o, "degree_drop", json_integer(n - d));
        {
            /* p(1) and p(-1) over Q(i) */
            fmpq_t a, b, one;
            int sg;
            fmpq_init(a); fmpq_init(b); fmpq_init(one);
            for (sg = 1; sg >= -1; sg -= 2) {
                fmpq_set_si(one, sg, 1);
                fmpq_poly_evaluate_fmpq(a, cp.re, one);
                fmpq_poly_evaluate_fmpq(b, cp.im, one);
                str = rs_complex_str(a, b);
                json_object_set_new(o, sg > 0 ? "p_at_1" : "p_at_minus_1", json_string(str));
                free(str);
            }
            fmpq_clear(a); fmpq_clear(b); fmpq_clear(one);
        }
        json_object_set_new(o, "zero_mult", json_integer(0));
        emit(run, &cp, o);
        fmpq_poly_clear(qr); fmpq_poly_clear(qi);
    }
    cpoint_clear(&cp);
    return r;
}

static json_t *chain_json(const rs_routh_complex_t t)
{
    json_t *arr = json_array();
    slong k;
    for (k = 0; k < t->len; k++) {
        char *str = fmpq_poly_get_str_pretty(t->chain + k, "w");
        json_array_append_new(arr, json_string(str));
        flint_free(str);
    }
    return arr;
}

/* the k roots at 0 charpoly.c divided out of a real det (a char line with
 * i keeps them in p): counted inside with p's */
static slong cpoint_zeros(const cpoint_t *cp)
{
    return cp->v->s->complex_char ? 0 : cp->v->cp->removed_lambda_power;
}

/* the counts of lambda over the unit circle from those of q over the
 * half-planes: inside = left, on = axis + degree drop (lambda = -1); the
 * roots at 0 divided out inside */
static void counts_json(json_t *o, const rs_routh_complex_t t, slong n, slong zeros)
{
    json_object_set_new(o, "degree", json_integer(n + zeros));
    json_object_set_new(o, "inside", json_integer(t->left + zeros));
    if (zeros > 0) json_object_set_new(o, "at_zero", json_integer(zeros));
    json_object_set_new(o, "on", json_integer(t->axis + (n - t->degree)));
    json_object_set_new(o, "outside", json_integer(t->right));
}

int rs_an_complex_routh(rs_run_t *run, const rs_an_req_t *req)
{
    cpoint_t cp;
    json_t *o;
    int r = cpoint_get(&cp, run, req->q, "routh");
    if (r == RS_OK) {
        fmpq_poly_t qr, qi;
        rs_routh_complex_t t;
        char *str;
        slong n = FLINT_MAX(fmpq_poly_degree(cp.re), fmpq_poly_degree(cp.im));
        fmpq_poly_init(qr); fmpq_poly_init(qi);
        rs_routh_complex_init(t);
        rs_status_t st;
        rs_routh_complex_bilinear(qr, qi, cp.re, cp.im);
        r = rs_routh_complex_status(&st, t, cp.re, cp.im, cp.v->singular ? n + 1 : cp.deg, run->err);
        o = base_json("routh", &cp);
        json_object_set_new(o, "status", json_string(rs_status_name(st)));
        json_object_set_new(o, "method", json_string(
            "Bilharz (generalised Routh-Hurwitz over Q(i)): q(i w) = A(w) + i B(w), the signed remainder "
            "chain of A/G and B/G (G = gcd(A, B): the roots on the axis and mirror pairs) counts the roots "
            "of q in Re z < 0 by its Cauchy index"));
        str = rs_cx_poly_str(qr, qi, qvar(run));
        json_object_set_new(o, "q", json_string(str));
        free(str);
        str = fmpq_poly_get_str_pretty(t->A, "w");
        json_object_set_new(o, "A", json_string(str));
        flint_free(str);
        str = fmpq_poly_get_str_pretty(t->B, "w");
        json_object_set_new(o, "B", json_string(str));
        flint_free(str);
        str = fmpq_poly_get_str_pretty(t->G, "w");
        json_object_set_new(o, "G", json_string(str));
        flint_free(str);
        json_object_set_new(o, "chain", chain_json(t));
        json_object_set_new(o, "left", json_integer(t->left));
        json_object_set_new(o, "right", json_integer(t->right));
        json_object_set_new(o, "axis", json_integer(t->axis));
        counts_json(o, t, n, cpoint_zeros(&cp));
        emit(run, &cp, o);
        rs_routh_complex_clear(t);
        fmpq_poly_clear(qr); fmpq_poly_clear(qi);
    }
    cpoint_clear(&cp);
    return r;
}

/* the exact verdict of p over Q(i) by both routes into o; *t the counts */
static int complex_verdict(rs_status_t *st, rs_routh_complex_t t, rs_run_t *run, const cpoint_t *cp, json_t *o)
{
    rs_status_t s1, s2;
    slong n = FLINT_MAX(fmpq_poly_degree(cp->re), fmpq_poly_degree(cp->im));
    /* the real set values already lower the degree over Q(params) */
    slong deg = cp->v->singular ? n + 1 : cp->deg;
    int r = rs_schur_complex_status(&s1, cp->re, cp->im, deg, run->err);
    if (r == RS_OK) r = rs_routh_complex_status(&s2, t, cp->re, cp->im, deg, run->err);
    if (r != RS_OK) return r;
    json_object_set_new(o, "methods", json_pack("[ss]", "schur-cohn over Q(i)", "bilharz (bilinear)"));
    json_object_set_new(o, "agree", json_boolean(s1 == s2));
    if (s1 != s2)
        return rs_error_set(run->err, RS_ERR_INCONSISTENT, "complex Schur-Cohn says %s, the Bilharz test on the "
                            "bilinear transform says %s", rs_status_name(s1), rs_status_name(s2));
    *st = s1;
    json_object_set_new(o, "status", json_string(rs_status_name(s1)));
    counts_json(o, t, n, cpoint_zeros(cp));
    if (s1 == RS_STATUS_SINGULAR)
        json_object_set_new(o, "singular", json_string("the leading coefficient of p vanishes at these values: "
                            "the step cannot be solved"));
    return RS_OK;
}

int rs_an_complex_stability(rs_run_t *run, const rs_an_req_t *req)
{
    cpoint_t cp;
    json_t *o = NULL;
    rs_routh_complex_t t;
    rs_status_t st;
    int r = cpoint_get(&cp, run, req->q, "stability");
    rs_routh_complex_init(t);
    if (r == RS_OK) {
        o = base_json("stability", &cp);
        r = complex_verdict(&st, t, run, &cp, o);
    }
    if (r == RS_OK) emit(run, &cp, o);
    else json_decref(o);
    rs_routh_complex_clear(t);
    cpoint_clear(&cp);
    return r;
}

/* p's own roots as certified balls when acb_poly_find_roots isolates them
 * (p / lambda^z squarefree); NULL when it does not within the precision.
 * The roots at 0 first, exact: p's own z (its zero low coefficients) and
 * the k the caller divided out */
static json_t *croots_json(const fmpq_poly_t re0, const fmpq_poly_t im0, slong k, slong digits)
{
    slong n, z = 0, prec, j;
    json_t *out = NULL;
    fmpq_poly_t re, im;
    while (z <= FLINT_MAX(fmpq_poly_degree(re0), fmpq_poly_degree(im0))) {
        fmpq_t c;
        int zero;
        fmpq_init(c);
        fmpq_poly_get_coeff_fmpq(c, re0, z);
        zero = fmpq_is_zero(c);
        fmpq_poly_get_coeff_fmpq(c, im0, z);
        zero &= fmpq_is_zero(c);
        fmpq_clear(c);
        if (!zero) break;
        z++;
    }
    fmpq_poly_init(re); fmpq_poly_init(im);
    fmpq_poly_shift_right(re, re0, z);
    fmpq_poly_shift_right(im, im0, z);
    n = FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im));
    if (n <= 0) {
        out = json_array();
        rs_json_zero_roots(out, z + k, digits);
    }
    for (prec = 3.33 * digits + 64; prec <= 8 * (3.33 * digits + 64) && out == NULL; prec *= 2) {
        acb_poly_t p;
        acb_ptr rt = _acb_vec_init(n);
        acb_t c;
        fmpq_t x;
        acb_poly_init(p);
        acb_init(c);
        fmpq_init(x);
        for (j = 0; j <= n; j++) {
            fmpq_poly_get_coeff_fmpq(x, re, j);
            arb_set_fmpq(acb_realref(c), x, prec);
            fmpq_poly_get_coeff_fmpq(x, im, j);
            arb_set_fmpq(acb_imagref(c), x, prec);
            acb_poly_set_coeff_acb(p, j, c);
        }
        if (acb_poly_find_roots(rt, p, NULL, 0, prec) == n) {
            int fine = 1;
            for (j = 0; j < n; j++) fine &= acb_rel_accuracy_bits(rt + j) >= 3.33 * digits;
            if (fine) {
                out = json_array();
                rs_json_zero_roots(out, z + k, digits);
                for (j = 0; j < n; j++) {
                    json_t *e = rs_json_acb(rt + j, digits);
                    arb_t ab;
                    arb_init(ab);
                    acb_abs(ab, rt + j, prec);
                    json_object_set_new(e, "abs", rs_json_arb(ab, digits));
                    json_object_set_new(e, "multiplicity", json_integer(1));
                    arb_clear(ab);
                    json_array_append_new(out, e);
                }
            }
        }
        fmpq_clear(x);
        acb_clear(c);
        acb_poly_clear(p);
        _acb_vec_clear(rt, n);
    }
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    return out;
}

int rs_an_complex_char_roots(rs_run_t *run, const rs_an_req_t *req, json_t *o, slong digits)
{
    cpoint_t cp;
    int r = cpoint_get(&cp, run, req->q, "radius");
    if (r == RS_OK) {
        json_t *roots = croots_json(cp.re, cp.im, cpoint_zeros(&cp), digits);
        json_object_set_new(o, "roots", roots != NULL ? roots : json_null());
        json_object_set_new(o, "roots_of", json_string("p (the char line over Q(i)); rho certified from the real "
                                                       "block form's polynomial p conj(p), the same moduli"));
        if (roots == NULL)
            json_object_set_new(o, "roots_note", json_string("p has a repeated root: its roots are not isolated "
                                "(the radius above is certified from p conj(p))"));
        cpoint_clear(&cp);
    }
    return r;
}

int rs_an_complex_radius(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_optval_t *dg = rs_an_opt(req, "digits");
    slong digits = dg->at != NULL ? dg->num : run->opt->default_digits;
    cpoint_t cp;
    json_t *o = NULL, *roots;
    rs_routh_complex_t t;
    rs_radius_t rr;
    fmpz_poly_t N;
    rs_status_t st;
    int r, dead = 0;
    if (strcmp(rs_an_opt_choice(req, "method"), "certified") != 0)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT,
                            "radius at complex set values: only method=certified (found method=%s)",
                            rs_an_opt_choice(req, "method"));
    r = cpoint_get(&cp, run, req->q, "radius");
    rs_routh_complex_init(t);
    rs_radius_init(rr);
    fmpz_poly_init(N);
    if (r == RS_OK) {
        o = base_json("radius", &cp);
        rs_schur_complex_norm(N, cp.re, cp.im);
        if (fmpz_poly_degree(N) < 1 && cpoint_zeros(&cp) > 0 && !cp.v->singular) {
            /* det = c lambda^k (the k roots at 0 divided out): dead-beat, radius exactly 0, as over Q */
            rs_run_radius_dead_beat_json(o);
            rs_json_zero_roots(json_object_get(o, "roots"), cpoint_zeros(&cp), digits);
            json_object_set_new(o, "exact_status", json_string("stable"));
            json_object_set_new(o, "dead_beat", json_string(
                "det A = c*lambda^k: every root is 0 (dead-beat), spectral radius 0"));
            dead = 1;
        } else if (fmpz_poly_degree(N) < 1) {
            r = rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT,
                             "radius: p has no root at these values%s", "");
        } else {
            r = rs_radius_fmpz_poly(rr, N, digits, run->opt->max_prec, run->err);
        }
    }
    if (r == RS_OK && !dead) {
        const char *nv;
        int consistent = 1;
        json_object_set_new(o, "method", json_string(
            "the roots of p conj(p) (an integer polynomial, the roots of p and their conjugates: the same "
            "moduli), certified by the real radius code; p's own roots by acb_poly_find_roots"));
        rs_json_radius(o, rr, digits);
        roots = croots_json(cp.re, cp.im, cpoint_zeros(&cp), digits);
        json_object_set_new(o, "roots", roots != NULL ? roots : json_null());
        if (roots == NULL)
            json_object_set_new(o, "roots_note", json_string("p has a repeated root: its roots are not isolated "
                                "(the radius above is certified from p conj(p))"));
        r = complex_verdict(&st, t, run, &cp, o);
        if (r == RS_OK) {
            json_t *ex = json_object_get(o, "status");
            json_object_set(o, "exact_status", ex);
            json_object_del(o, "status");
            /* only certified comparisons: an interval containing 1 decides nothing */
            nv = rs_radius_verdict(rr);
            if (strcmp(nv, "stable") == 0 && st != RS_STATUS_STABLE) consistent = 0;
            if (strcmp(nv, "unstable") == 0 && t->right == 0) consistent = 0;
            json_object_set_new(o, "verdict_from_radius", json_string(strcmp(nv, "undecided") != 0 ? nv :
                "undecided numerically (the interval contains 1): the exact side decides"));
            json_object_set_new(o, "consistent", json_boolean(consistent));
            if (!consistent) run->outcome |= RS_OUTCOME_INCONSISTENT;
        }
    }
    if (r == RS_OK) emit(run, &cp, o);
    else {
        json_decref(o);
        r = rs_req_relocate(run, req->q, r, "radius");
    }
    fmpz_poly_clear(N);
    rs_radius_clear(rr);
    rs_routh_complex_clear(t);
    cpoint_clear(&cp);
    return r;
}

/* a `char` line over Q(i) with every parameter real and set: the complex
 * pair (Schur-Cohn over Q(i), Bilharz) beside the real verdict on the
 * block form; RS_ERR_INCONSISTENT when they differ */
/* The block form's roots are p's and conj(p)'s, which have the same moduli: its
 * counts must be twice p's (checked, exit 3 otherwise).  The report gives p's
 * own counts; the block form's stay under "block_form". */
static int char_counts_own(rs_run_t *run, json_t *o, const json_t *c)
{
    static const char *key[] = {"degree", "inside", "on", "outside"};
    static const char *moved[] = {"at_one", "at_minus_one", "on_multiplicities", "at_zero", "circle_roots"};
    json_t *b;
    int k;
    for (k = 0; k < 4; k++) {
        json_t *bo = json_object_get(o, key[k]), *pc = json_object_get(c, key[k]);
        if (!json_is_integer(bo) || !json_is_integer(pc)) return RS_OK;   /* no counts (singular) */
        if (json_integer_value(bo) != 2 * json_integer_value(pc))
            return rs_error_set(run->err, RS_ERR_INCONSISTENT, "the char line over Q(i): the real block form "
                                "counts %s %lld, not twice p's %lld", key[k], (long long) json_integer_value(bo),
                                (long long) json_integer_value(pc));
    }
    b = json_object();
    for (k = 0; k < 4; k++) {
        json_object_set(b, key[k], json_object_get(o, key[k]));
        json_object_set(o, key[k], json_object_get(c, key[k]));
    }
    for (k = 0; k < 5; k++) {
        json_t *x = json_object_get(o, moved[k]);
        if (x != NULL) { json_object_set(b, moved[k], x); json_object_del(o, moved[k]); }
    }
    json_object_set_new(o, "block_form", b);
    return RS_OK;
}

int rs_an_complex_char_check(rs_run_t *run, const rs_an_req_t *req, rs_status_t real_st, json_t *o)
{
    cpoint_t cp;
    rs_routh_complex_t t;
    rs_status_t st;
    json_t *c = json_object();
    int r = cpoint_get(&cp, run, req->q, "stability");
    rs_routh_complex_init(t);
    if (r == RS_OK) r = complex_verdict(&st, t, run, &cp, c);
    if (r == RS_OK) {
        char *p = rs_cx_poly_str(cp.re, cp.im, "lambda");
        json_object_set_new(c, "p", json_string(p));
        free(p);
        json_object_set_new(o, "complex_check", c);
        if (st != real_st)
            r = rs_error_set(run->err, RS_ERR_INCONSISTENT, "the char line over Q(i): the real block form says %s, "
                             "complex Schur-Cohn and Bilharz say %s", rs_status_name(real_st), rs_status_name(st));
        if (r == RS_OK) r = char_counts_own(run, o, c);
        c = NULL;
    }
    json_decref(c);
    rs_routh_complex_clear(t);
    cpoint_clear(&cp);
    return r;
}

/* ---- map re(NAME) A B N, im(NAME) C D M: the z-plane ------------------------------ */

/* the request: NAME's index, the ranges (exact), the grid */
typedef struct {
    slong param;
    fmpq_t lo[2], hi[2];
    slong n[2];
} cmap_req_t;

int rs_an_complex_map_is(const char *rest)
{
    while (*rest == ' ' || *rest == '\t') rest++;
    return strncmp(rest, "re(", 3) == 0;
}

int rs_an_complex_map_of(const char *rest, const char *name)
{
    size_t n = strlen(name);
    while (*rest == ' ' || *rest == '\t') rest++;
    if (strncmp(rest, "re(", 3) != 0) return 0;
    rest += 3;
    while (*rest == ' ' || *rest == '\t') rest++;
    if (strncmp(rest, name, n) != 0) return 0;
    rest += n;
    while (*rest == ' ' || *rest == '\t') rest++;
    return *rest == ')';
}

void rs_an_complex_map_clear(rs_an_req_t *req)
{
    cmap_req_t *m = req->u.sweep;
    if (m == NULL) return;
    fmpq_clear(m->lo[0]); fmpq_clear(m->lo[1]); fmpq_clear(m->hi[0]); fmpq_clear(m->hi[1]);
    free(m);
    req->u.sweep = NULL;
}

/* a count too large for a long (strtol clamps it) */
static int errno_range(const char *w)
{
    return strlen(w) > 18;
}

/* one whitespace-delimited word at *t (copied into w), *t moved past it */
static int read_word(char *w, size_t len, const char **t)
{
    size_t k = 0;
    while (**t == ' ' || **t == '\t') (*t)++;
    while (**t && **t != ' ' && **t != '\t' && **t != ',' && k + 1 < len) w[k++] = *(*t)++;
    w[k] = '\0';
    return k > 0;
}

/* One axis of the complex plane, `re(NAME)` (axis 0) or `im(NAME)` (axis 1,
 * the same parameter), at *t; *t moves past the ')'.  expect: the message
 * when the text is not of that form. */
static int cx_axis_read(rs_run_t *run, const rs_request_t *q, const char **tp, int axis, slong *param,
                        const char *expect)
{
    const char *t = *tp, *close;
    char name[80];
    size_t nl;
    while (*t == ' ' || *t == '\t') t++;
    if (strncmp(t, axis == 0 ? "re(" : "im(", 3) != 0 || (close = strchr(t + 3, ')')) == NULL || close == t + 3
        || (size_t) (close - t - 3) >= sizeof name)
        return rs_req_error(run, q, t, RS_ERR_INPUT, expect, t);
    nl = (size_t) (close - t - 3);
    memcpy(name, t + 3, nl);
    name[nl] = '\0';
    if (axis == 0) {
        *param = rs_case_param_index(run->c, name);
        if (*param < 0) return rs_req_error(run, q, t + 3, RS_ERR_INPUT, "'%s' is not a parameter", name);
    } else if (strcmp(name, run->c->params[*param].name) != 0) {
        return rs_req_error(run, q, t + 3, RS_ERR_INPUT, "expected the same parameter in re(...) and im(...), "
                            "found '%s'", name);
    }
    *tp = close + 1;
    return RS_OK;
}

int rs_an_complex_map_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *t = req->rest;
    cmap_req_t *m = calloc(1, sizeof *m);
    char w[128];
    int axis;
    fmpq_init(m->lo[0]); fmpq_init(m->lo[1]); fmpq_init(m->hi[0]); fmpq_init(m->hi[1]);
    req->u.sweep = m;
    m->param = -1;
    for (axis = 0; axis < 2; axis++) {
        rs_error_t e2;
        int k;
        int r = cx_axis_read(run, q, &t, axis, &m->param,
                             axis == 0 ? "expected re(NAME) A B N, im(NAME) C D M, found '%s'"
                                       : "expected im(NAME) C D M after the comma, found '%s'");
        if (r != RS_OK) return r;
        for (k = 0; k < 3; k++) {
            const char *wat;
            while (*t == ' ' || *t == '\t') t++;
            wat = t;
            if (!read_word(w, sizeof w, &t))
                return rs_req_error(run, q, wat, RS_ERR_INPUT, k < 2 ? "expected a range end (a rational number), "
                                    "found '%s'" : "expected the number of grid points, found '%s'", wat);
            rs_error_init(e2);
            if (k < 2) {
                if (rs_expr_parse_number(k == 0 ? m->lo[axis] : m->hi[axis], w, e2) != RS_OK)
                    return rs_req_error(run, q, wat, RS_ERR_INPUT, "expected a rational number, found '%s'", w);
            } else {
                char *end;
                long v = strtol(w, &end, 10);
                if (*end != '\0' || v < 1 || errno_range(w))
                    return rs_req_error(run, q, wat, RS_ERR_INPUT, "expected a number of grid points (a positive "
                                        "integer), found '%s'", w);
                m->n[axis] = v;
            }
        }
        while (*t == ' ' || *t == '\t') t++;
        if (axis == 0) {
            if (*t != ',') return rs_req_error(run, q, t, RS_ERR_INPUT, "expected ', im(NAME) C D M', found '%s'", t);
            t++;
        }
    }
    if (strncmp(t, "of", 2) == 0 && (t[2] == ' ' || t[2] == '\t')) {
        const char *wat;
        t += 2;
        while (*t == ' ' || *t == '\t') t++;
        wat = t;
        read_word(w, sizeof w, &t);
        if (strcmp(w, "stability") != 0)
            return rs_req_error(run, q, wat, RS_ERR_INPUT, "a map of the complex plane is of stability (exact per "
                                "point), found '%s'", wat);
        while (*t == ' ' || *t == '\t') t++;
    }
    if (*t != '\0') return rs_req_error(run, q, t, RS_ERR_INPUT, "expected end of line, found '%s'", t);
    /* the point limit of every map (--max-points); the budget decides the rest */
    {
        slong max = run->opt->sweep.max_points;
        if (m->n[0] > max || m->n[1] > max || m->n[0] > max / m->n[1]) {
            char desc[120];
            snprintf(desc, sizeof desc, "the map (%ld x %ld)", (long) m->n[0], (long) m->n[1]);
            return rs_sweep_limit_error(run, q, (double) m->n[0] * (double) m->n[1], desc);
        }
    }
    return RS_OK;
}

static void grid_value(fmpq_t x, const fmpq_t lo, const fmpq_t hi, slong k, slong n)
{
    if (n < 2) { fmpq_set(x, lo); return; }
    fmpq_sub(x, hi, lo);
    fmpq_mul_si(x, x, k);
    fmpz_mul_si(fmpq_denref(x), fmpq_denref(x), n - 1);
    fmpq_canonicalise(x);
    fmpq_add(x, x, lo);
}

/* p = sum_k (CR[k] + i CI[k]) z0^k at z0 = zr + i zi (CI NULL: real
 * coefficients) */
static void eval_coeffs(fmpq_poly_t re, fmpq_poly_t im, const fmpq_poly_struct *CR, const fmpq_poly_struct *CI,
                        slong K, const fmpq_t zr, const fmpq_t zi)
{
    fmpq_poly_t tr, ti, u;
    slong k;
    fmpq_poly_init(tr); fmpq_poly_init(ti); fmpq_poly_init(u);
    fmpq_poly_zero(re);
    fmpq_poly_zero(im);
    for (k = K; k >= 0; k--) {
        /* (re + i im)(zr + i zi) + C[k] (Horner) */
        fmpq_poly_scalar_mul_fmpq(tr, re, zr);
        fmpq_poly_scalar_mul_fmpq(u, im, zi);
        fmpq_poly_sub(tr, tr, u);
        fmpq_poly_scalar_mul_fmpq(ti, re, zi);
        fmpq_poly_scalar_mul_fmpq(u, im, zr);
        fmpq_poly_add(ti, ti, u);
        fmpq_poly_add(re, tr, CR + k);
        if (CI != NULL) fmpq_poly_add(im, ti, CI + k);
        else fmpq_poly_swap(im, ti);
    }
    fmpq_poly_clear(tr); fmpq_poly_clear(ti); fmpq_poly_clear(u);
}

/* the plane of NAME = x + i y: variables x = re(NAME), y = im(NAME),
 * lambda (xn, yn: 24 chars each; vars: 3 names), contexts initialised */
static void zplane_init(rs_scheme_struct *xs, char **vars, char *xn, char *yn, const char *name)
{
    snprintf(xn, 24, "re(%.16s)", name);
    snprintf(yn, 24, "im(%.16s)", name);
    vars[0] = xn; vars[1] = yn; vars[2] = (char *) "lambda";
    memset(xs, 0, sizeof *xs);
    fmpq_mpoly_ctx_init(xs->ctx, 3, ORD_LEX);
    fmpz_mpoly_ctx_init(xs->zctx, 3, ORD_LEX);
    xs->nvars = 3;
    xs->lambda_var = 2;
    xs->vars = vars;
}

static void zplane_clear(rs_scheme_struct *xs)
{
    fmpz_mpoly_ctx_clear(xs->zctx);
    fmpq_mpoly_ctx_clear(xs->ctx);
}

/* c * D as an integer polynomial (D a multiple of c's denominator) */
static void scaled_num(fmpz_poly_t out, const fmpq_poly_t c, const fmpz_t D)
{
    fmpz_t f;
    fmpz_init(f);
    fmpz_divexact(f, D, fmpq_poly_denref(c));
    fmpq_poly_get_numerator(out, c);
    fmpz_poly_scalar_mul_fmpz(out, out, f);
    fmpz_clear(f);
}

/* D p(x + i y) = re + i im in Z[x, y, lambda] (ctx: zplane_init's), D > 0
 * the common denominator of p = sum_k (CR_k + i CI_k)(lambda) NAME^k */
static void zplane_poly(fmpz_mpoly_t re, fmpz_mpoly_t im, const fmpq_poly_struct *CR, const fmpq_poly_struct *CI,
                        slong K, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t zr, zi, t, u, x, y;
    fmpz_poly_t c;
    fmpz_t D;
    slong k;
    fmpz_mpoly_init(zr, ctx); fmpz_mpoly_init(zi, ctx); fmpz_mpoly_init(t, ctx); fmpz_mpoly_init(u, ctx);
    fmpz_mpoly_init(x, ctx); fmpz_mpoly_init(y, ctx);
    fmpz_poly_init(c);
    fmpz_init(D);
    fmpz_mpoly_zero(re, ctx);
    fmpz_mpoly_zero(im, ctx);
    fmpz_mpoly_gen(x, 0, ctx);
    fmpz_mpoly_gen(y, 1, ctx);
    fmpz_mpoly_one(zr, ctx);
    fmpz_one(D);
    for (k = 0; k <= K; k++) {
        fmpz_lcm(D, D, fmpq_poly_denref(CR + k));
        if (CI != NULL) fmpz_lcm(D, D, fmpq_poly_denref(CI + k));
    }
    for (k = 0; k <= K; k++) {
        int part;
        for (part = 0; part < (CI != NULL ? 2 : 1); part++) {
            /* part 1: i CI_k (zr + i zi) = -CI_k zi + i CI_k zr */
            scaled_num(c, part == 0 ? CR + k : CI + k, D);
            fmpz_mpoly_set_fmpz_poly(t, c, 2, ctx);
            fmpz_mpoly_mul(u, t, part == 0 ? zr : zi, ctx);
            if (part == 0) fmpz_mpoly_add(re, re, u, ctx);
            else fmpz_mpoly_sub(re, re, u, ctx);
            fmpz_mpoly_mul(u, t, part == 0 ? zi : zr, ctx);
            fmpz_mpoly_add(im, im, u, ctx);
        }
        /* (zr + i zi)(x + i y) */
        fmpz_mpoly_mul(t, zr, x, ctx);
        fmpz_mpoly_mul(u, zi, y, ctx);
        fmpz_mpoly_sub(t, t, u, ctx);
        fmpz_mpoly_mul(u, zr, y, ctx);
        fmpz_mpoly_mul(zi, zi, x, ctx);
        fmpz_mpoly_add(zi, zi, u, ctx);
        fmpz_mpoly_swap(zr, t, ctx);
    }
    fmpz_mpoly_clear(zr, ctx); fmpz_mpoly_clear(zi, ctx); fmpz_mpoly_clear(t, ctx); fmpz_mpoly_clear(u, ctx);
    fmpz_mpoly_clear(x, ctx); fmpz_mpoly_clear(y, ctx);
    fmpz_poly_clear(c);
    fmpz_clear(D);
}

/* The boundary locus, sampled for the plot: for phi on a grid, the roots z
 * of p(exp(i phi), z) = 0 (for p linear in z: z = -C0/C1 at lambda =
 * exp(i phi)); "re,im,branch" rows in double, the exact parametrisation
 * beside it in the result.  A (NULL: every point drawn): the z-plane's
 * decomposition; a point on an arc that separates nothing (both sides
 * stable, or both not stable) is dropped; the counts into nd[0] (drawn),
 * nd[1] (dropped). */
static char *locus_table(const fmpq_poly_struct *CR, const fmpq_poly_struct *CI, const fmpq_poly_struct *CS,
                         slong d, slong K, slong nphi, const rs_region_arcs_t *A, slong *nd)
{
    size_t cap = 4096, len = 0;
    char *out = malloc(cap);
    slong j, k, prec = 128;
    nd[0] = nd[1] = 0;
    len += (size_t) snprintf(out, cap, "re,im,branch\n");
    for (j = 0; j <= nphi; j++) {
        acb_t lam, c, x;
        acb_poly_t pz;
        acb_ptr rt = _acb_vec_init(K);
        slong found;
        acb_init(lam); acb_init(c); acb_init(x);
        acb_poly_init(pz);
        /* lambda = exp(2 pi i j / nphi) */
        arb_set_si(acb_realref(x), 2 * j);
        arb_div_si(acb_realref(x), acb_realref(x), nphi, prec);
        arb_zero(acb_imagref(x));
        acb_exp_pi_i(lam, x, prec);
        for (k = 0; k <= K; k++) {
            acb_poly_t cp;
            acb_poly_init(cp);
            if (CI != NULL) acb_poly_set2_fmpq_poly(cp, CR + k, CI + k, prec);
            else acb_poly_set_fmpq_poly(cp, CR + k, prec);
            if (CS != NULL) {
                /* + sqrt(d) CS[k] (over Q(sqrt d)) */
                acb_poly_t sp;
                acb_poly_init(sp);
                acb_poly_set_fmpq_poly(sp, CS + k, prec);
                arb_sqrt_ui(acb_realref(x), (ulong) d, prec);
                arb_zero(acb_imagref(x));
                acb_poly_scalar_mul(sp, sp, x, prec);
                acb_poly_add(cp, cp, sp, prec);
                acb_poly_clear(sp);
            }
            acb_poly_evaluate(c, cp, lam, prec);
            acb_poly_set_coeff_acb(pz, k, c);
            acb_poly_clear(cp);
        }
        found = 0;
        if (acb_poly_degree(pz) == K && K >= 1) {
            if (K == 1) {
                acb_poly_get_coeff_acb(c, pz, 0);
                acb_poly_get_coeff_acb(x, pz, 1);
                acb_div(rt, c, x, prec);
                acb_neg(rt, rt);
                found = acb_is_finite(rt) ? 1 : 0;
            } else {
                found = acb_poly_find_roots(rt, pz, NULL, 0, prec);
            }
        }
        for (k = 0; k < found; k++) {
            double a = arf_get_d(arb_midref(acb_realref(rt + k)), ARF_RND_NEAR);
            double b = arf_get_d(arb_midref(acb_imagref(rt + k)), ARF_RND_NEAR);
            if (A != NULL && !rs_region_arcs_keep(A, NULL, a, b)) { nd[1]++; continue; }
            nd[0]++;
            if (len + 80 > cap) { cap *= 2; out = realloc(out, cap); }
            len += (size_t) snprintf(out + len, cap - len, "%.10g,%.10g,%ld\n", a, b, (long) k);
        }
        _acb_vec_clear(rt, K);
        acb_poly_clear(pz);
        acb_clear(lam); acb_clear(c); acb_clear(x);
    }
    return out;
}

/* p = sum_k (CR[k] + i CI[k]) NAME^k with CR[k], CI[k] in Q[lambda]
 * (*CI NULL for a polynomial over Q: the variant's p; else a char line
 * over Q(i), p = A + i B from its block), K its degree in NAME, *n in
 * lambda.  0 when a variable other than NAME and lambda occurs. */
static int zplane_coeffs(fmpq_poly_struct **CR, fmpq_poly_struct **CI, slong *K, slong *n, const rs_variant_t *v,
                         slong param)
{
    const rs_scheme_struct *s = v->s;
    slong k, part;
    if (!s->complex_char) {
        *K = fmpz_mpoly_degree_si(v->cp->p, param, s->zctx);
        *n = fmpz_mpoly_degree_si(v->cp->p, s->lambda_var, s->zctx);
        *CI = NULL;
        *CR = flint_malloc((FLINT_MAX(*K, 0) + 1) * sizeof(fmpq_poly_struct));
        for (k = 0; k <= FLINT_MAX(*K, 0); k++) {
            fmpz_poly_t c;
            fmpz_poly_init(c);
            fmpq_poly_init(*CR + k);
            if (k <= *K) rs_run_coeff_in(c, v->cp->p, param, k, s);
            fmpq_poly_set_fmpz_poly(*CR + k, c);
            fmpz_poly_clear(c);
        }
        return 1;
    }
    *K = FLINT_MAX(fmpq_mpoly_degree_si(s->M + 0, param, s->ctx), fmpq_mpoly_degree_si(s->M + 2, param, s->ctx));
    *n = FLINT_MAX(fmpq_mpoly_degree_si(s->M + 0, s->lambda_var, s->ctx),
                   fmpq_mpoly_degree_si(s->M + 2, s->lambda_var, s->ctx));
    *CR = flint_malloc((FLINT_MAX(*K, 0) + 1) * sizeof(fmpq_poly_struct));
    *CI = flint_malloc((FLINT_MAX(*K, 0) + 1) * sizeof(fmpq_poly_struct));
    for (k = 0; k <= FLINT_MAX(*K, 0); k++) {
        fmpq_poly_init(*CR + k);
        fmpq_poly_init(*CI + k);
    }
    /* the block [[A, -B], [B, A]]: A = M[0], B = M[2] */
    for (part = 0; part < 2; part++) {
        const fmpq_mpoly_struct *P = s->M + 2 * part;
        slong i, len = fmpq_mpoly_length(P, s->ctx), w;
        slong *ex = flint_malloc(s->nvars * sizeof(slong));
        fmpq_t c, old;
        fmpq_init(c); fmpq_init(old);
        for (i = 0; i < len; i++) {
            fmpq_poly_struct *dst;
            fmpq_mpoly_get_term_coeff_fmpq(c, P, i, s->ctx);
            fmpq_mpoly_get_term_exp_si(ex, P, i, s->ctx);
            for (w = 0; w < s->nvars; w++)
                if (w != param && w != s->lambda_var && ex[w] != 0) break;
            if (w < s->nvars) {
                fmpq_clear(c); fmpq_clear(old);
                flint_free(ex);
                return 0;
            }
            dst = (part == 0 ? *CR : *CI) + ex[param];
            fmpq_poly_get_coeff_fmpq(old, dst, ex[s->lambda_var]);
            fmpq_add(old, old, c);
            fmpq_poly_set_coeff_fmpq(dst, ex[s->lambda_var], old);
        }
        fmpq_clear(c); fmpq_clear(old);
        flint_free(ex);
    }
    return 1;
}

static void zplane_coeffs_clear(fmpq_poly_struct *CR, fmpq_poly_struct *CI, slong K)
{
    slong k;
    for (k = 0; k <= FLINT_MAX(K, 0); k++) {
        fmpq_poly_clear(CR + k);
        if (CI != NULL) fmpq_poly_clear(CI + k);
    }
    flint_free(CR);
    flint_free(CI);
}

/* The z-plane map as a model of the sweep engine: the verdict at grid
 * point idx = j*K1 + i, z = x[i] + i y[j], exact by complex Schur-Cohn and
 * Bilharz (cross-checked by rs_routh_complex_checked_status); at every
 * stride-th point also the certified side: the ladder (Arb roots first,
 * exact Routh/Schur-Cohn where they cannot decide) on p conj(p), whose
 * roots are p's and their conjugates: stable iff p is, and unstable when p
 * is (a root outside, or a repeated circle root, stays one); p marginal
 * may give N unstable (a circle root and its conjugate both roots of p). */
typedef struct {
    const fmpq_poly_struct *CR, *CI;
    const fmpq_poly_struct *CS;    /* over Q(sqrt d): the sqrt(d) parts (an_qd_map.c), else NULL */
    slong K, n, K1, stride, d;
    const fmpq *x, *y;
    const char *name;
} zmap_t;

static void zmap_point(rs_sweep_row_t *row, slong idx, void *model, rs_error_t err)
{
    const zmap_t *Z = model;
    slong i = idx % Z->K1, j = idx / Z->K1;
    fmpq_poly_t re, im;
    rs_status_t st = RS_STATUS_UNSTABLE;
    int r;
    int code = -1;
    fmpq_poly_init(re); fmpq_poly_init(im);
    eval_coeffs(re, im, Z->CR, Z->CI, Z->K, Z->x + i, Z->y + j);
    if (Z->CS != NULL) {
        /* over Q(sqrt d)(i): p = re + i im + sqrt(d) (re1 + i im1), both routes at every point */
        fmpq_poly_t re1, im1;
        fmpq_poly_init(re1); fmpq_poly_init(im1);
        eval_coeffs(re1, im1, Z->CS, NULL, Z->K, Z->x + i, Z->y + j);
        r = rs_an_qd_zplane_verdict(&code, re, im, re1, im1, Z->n, Z->d);
        if (r != RS_OK) rs_error_set(err, r, "Schur-Cohn over Q(sqrt %ld)(i) and the certified roots disagree",
                                     (long) Z->d);
        fmpq_poly_clear(re1); fmpq_poly_clear(im1);
        row->inside = 1;
    } else {
        r = rs_routh_complex_checked_status(&st, re, im, Z->n, err);
        code = (int) st;
        /* a singular point has no certified side (p conj(p) has lower degree) */
        row->inside = 0;
    }
    if (Z->CS == NULL && r == RS_OK && idx % Z->stride == 0 && st != RS_STATUS_SINGULAR) {
        r = rs_cx_norm_check(st, re, im, err);
        row->inside = 1;   /* here: cross-checked */
    }
    if (r != RS_OK) {
        char *zs = rs_complex_str(Z->x + i, Z->y + j), msg[RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "%s", err->msg);
        rs_error_set(err, r, "%s = %s: %s", Z->name, zs, msg);
        free(zs);
    }
    row->d.status = r;
    row->d.verdict = r == RS_OK ? code : -1;
    row->d.level = RS_LEVEL_EXACT;
    fmpq_poly_clear(re); fmpq_poly_clear(im);
}

typedef struct {
    const zmap_t *Z;
    slong checked;
} zmap_put_t;

/* index,i,j,re(NAME),im(NAME),re(NAME)_exact,im(NAME)_exact,verdict,code,decided_by */
static void zmap_put(FILE *f, const rs_sweep_row_t *rows, slong lo, slong hi, void *arg)
{
    zmap_put_t *a = arg;
    const zmap_t *Z = a->Z;
    slong idx;
    for (idx = lo; idx < hi; idx++) {
        const rs_sweep_row_t *w = rows + (idx - lo);
        const fmpq *x = Z->x + idx % Z->K1, *y = Z->y + idx / Z->K1;
        char *xs = fmpq_get_str(NULL, 10, x), *ys = fmpq_get_str(NULL, 10, y);
        fprintf(f, "%ld,%ld,%ld,%.17g,%.17g,%s,%s,%s,%d,exact\n", (long) idx, (long) (idx % Z->K1),
                (long) (idx / Z->K1), fmpq_get_d(x), fmpq_get_d(y), xs, ys, rs_sweep_verdict_name(w->d.verdict),
                w->d.verdict);
        flint_free(xs);
        flint_free(ys);
        a->checked += w->inside;
    }
}

typedef struct {
    const fmpq_poly_struct *CR, *CI;   /* CI NULL: real coefficients */
    slong K, n;
    rs_run_t *run;
} cregion_pt_t;

/* the decomposition of the z-plane for the map's locus (region re(z),
 * im(z)'s conditions, stable / not stable only); A NULL when it failed */
typedef struct {
    rs_scheme_struct xs;
    char *vars[3], xn[24], yn[24];
    fmpz_mpoly_t re, im;
    rs_schur_cx_conds_t cc;
    rs_region_cx_t cx;
    cregion_pt_t pt;
    rs_region_arcs_t *A;
} zarcs_t;
static int zarcs_init(zarcs_t *Z, rs_run_t *run, const fmpq_poly_struct *CR, const fmpq_poly_struct *CI, slong K,
                      slong n, const char *name);
static void zarcs_clear(zarcs_t *Z);

int rs_an_complex_map(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const cmap_req_t *m = req->u.sweep;
    const char *name = run->c->params[m->param].name;
    rs_variant_t *v;
    fmpq_poly_struct *CR = NULL, *CI = NULL, *CS = NULL;
    fmpq *xs[2] = {NULL, NULL};
    slong K = 0, n = 0, k, npoints = m->n[0] * m->n[1], cap = run->opt->sweep.json_rows;
    char pre[16], pim[16], what[64], desc[200], header[160];
    rs_sweep_model_t model;
    rs_sweep_table_t T;
    zmap_t Z;
    zmap_put_t put;
    json_t *o;
    double t0 = rs_sweep_now();
    int r = rs_run_variant_one_free(&v, run, q, req->rest, m->param, "map");
    if (r != RS_OK) return r;
    if (v->s->sqrt_d > 0) rs_an_qd_zplane_coeffs(&CR, &CS, &K, &n, v, m->param);   /* over Q(sqrt d) */
    else if (!zplane_coeffs(&CR, &CI, &K, &n, v, m->param)) {
        char msg[300];
        snprintf(msg, sizeof msg, "map re(%s), im(%s): the char line depends on a parameter other than %s", name,
                 name, name);
        r = rs_req_error(run, q, req->rest, RS_ERR_INPUT, "%s", msg);
    }
    else if (K < 1 || n < 1)
        r = rs_req_error(run, q, req->rest, RS_ERR_INPUT, "map re(%s), im(%s): the characteristic polynomial must "
                         "depend on the parameter and on lambda", name);
    else
        r = rs_sweep_estimate_map(run, q, (double) npoints);
    if (r != RS_OK) {
        zplane_coeffs_clear(CR, CI != NULL ? CI : CS, K);
        return r;
    }
    for (k = 0; k < 2; k++) {
        slong i;
        xs[k] = _fmpq_vec_init(m->n[k]);
        for (i = 0; i < m->n[k]; i++) grid_value(xs[k] + i, m->lo[k], m->hi[k], i, m->n[k]);
    }
    snprintf(pre, sizeof pre, "re(%.10s)", name);
    snprintf(pim, sizeof pim, "im(%.10s)", name);
    snprintf(what, sizeof what, "map %s,%s", pre, pim);
    snprintf(desc, sizeof desc, "index = j*%ld + i of %s[i], %s[j]", (long) m->n[0], pre, pim);
    snprintf(header, sizeof header, "index,i,j,%s,%s,%s_exact,%s_exact,verdict,code,decided_by\n", pre, pim, pre, pim);
    Z.CR = CR;
    Z.CI = CI;
    Z.CS = CS;
    Z.d = v->s->sqrt_d;
    Z.K = K;
    Z.n = n;
    Z.K1 = m->n[0];
    /* the certified side at about 256 points spread over the grid */
    Z.stride = npoints > 256 ? (npoints + 255) / 256 : 1;
    Z.x = xs[0];
    Z.y = xs[1];
    Z.name = name;
    model.point = zmap_point;
    model.model = &Z;
    model.serial = 0;
    put.Z = &Z;
    put.checked = 0;
    r = rs_sweep_map_table(&T, run, q, &model, npoints, what, desc, header, zmap_put, &put);
    if (r == RS_OK) {
        slong nrow = T.hi - T.lo;
        zarcs_t Za;
        slong nd[2];
        rs_error_struct saved = *run->err;
        char *loc;
        /* only the locus arcs that separate stable from not stable are drawn */
        /* (over Q(sqrt d) there is no decomposition of the plane: every locus point is drawn) */
        if (CS != NULL) Za.A = NULL;
        else if (zarcs_init(&Za, run, CR, CI, K, n, name) != RS_OK) *run->err = saved;
        loc = locus_table(CR, CI, CS, Z.d, K, 720, Za.A, nd);
        json_t *ranges = json_array(), *real = json_pack("[ii]", 3, 4);
        o = json_object();
        json_object_set_new(o, "analysis", json_string("map"));
        json_object_set_new(o, "params", json_pack("[ss]", pre, pim));
        for (k = 0; k < 2; k++) {
            char *a = fmpq_get_str(NULL, 10, m->lo[k]), *b = fmpq_get_str(NULL, 10, m->hi[k]);
            json_array_append_new(ranges, json_pack("[ssI]", a, b, (json_int_t) m->n[k]));
            flint_free(a); flint_free(b);
        }
        json_object_set_new(o, "ranges", ranges);
        /* the plot keeps to the grid (the locus may leave it) */
        json_object_set_new(o, "plot_ranges", json_pack("[[ff][ff]]", fmpq_get_d(m->lo[0]), fmpq_get_d(m->hi[0]),
                            fmpq_get_d(m->lo[1]), fmpq_get_d(m->hi[1])));
        json_object_set_new(o, "grid", json_pack("[II]", (json_int_t) m->n[0], (json_int_t) m->n[1]));
        json_object_set_new(o, "of", json_string("stability"));
        json_object_set_new(o, "complex_plane", json_string(name));
        json_object_set_new(o, "points", json_integer(npoints));
        json_object_set_new(o, "computed", json_integer(nrow));
        if (run->opt->sweep.shard_count > 1) rs_sweep_json_shard(o, run, npoints, T.lo, T.hi);
        json_object_set_new(o, "verdicts", json_pack("{sIsIsIsI}", "stable", (json_int_t) T.verdicts[0], "marginal",
                            (json_int_t) T.verdicts[1], "unstable", (json_int_t) T.verdicts[2], "singular",
                            (json_int_t) T.verdicts[4]));
        json_object_set_new(o, "decided_by", json_pack("{sI}", "exact", (json_int_t) nrow));
        if (CS != NULL) rs_an_qd_zplane_json(o, run, T.verdicts[5], put.checked);
        else {
        json_object_set_new(o, "methods", json_pack("[ss]", "schur-cohn over Q(i)", "bilharz (bilinear)"));
        json_object_set_new(o, "cross_check", json_pack("{sIss}", "points", (json_int_t) put.checked, "method",
                            "the certified ladder (Arb roots, exact where they cannot decide) on p conj(p) at every "
                            "point of a sample of about 256: stable iff the exact verdict is, unstable where it is"));
        }
        json_object_set_new(o, "seconds", json_real(rs_sweep_now() - t0));
        json_object_set_new(o, "csv", json_null());
        if (K == 1) {
            char *p0, *p1, *buf;
            if (CS != NULL) {
                p0 = rs_an_qd_fmpq_poly_str(CR + 0, CS + 0, Z.d);
                p1 = rs_an_qd_fmpq_poly_str(CR + 1, CS + 1, Z.d);
            } else if (CI != NULL) {
                p0 = rs_cx_poly_str(CR + 0, CI + 0, "lambda");
                p1 = rs_cx_poly_str(CR + 1, CI + 1, "lambda");
            } else {
                p0 = fmpq_poly_get_str_pretty(CR + 0, "lambda");
                p1 = fmpq_poly_get_str_pretty(CR + 1, "lambda");
            }
            buf = malloc(strlen(p0) + strlen(p1) + 120);
            sprintf(buf, "%s = -(%s)/(%s), lambda = exp(i*phi), 0 <= phi < 2*pi", name, p0, p1);
            json_object_set_new(o, "boundary_locus", json_string(buf));
            free(buf);
            if (CI != NULL || CS != NULL) { free(p0); free(p1); }
            else { flint_free(p0); flint_free(p1); }
        } else {
            char buf[200];
            snprintf(buf, sizeof buf, "the roots %s of p(exp(i*phi), %s) = 0, 0 <= phi < 2*pi", name, name);
            json_object_set_new(o, "boundary_locus", json_string(buf));
        }
        json_object_set_new(o, "locus_note", json_string("locus_table: the exact parametrisation evaluated in "
                            "floating point at 721 angles (for the plot); the verdicts are exact"));
        json_object_set_new(o, "locus_points", json_pack("{s:I,s:I,s:s}", "drawn", (json_int_t) nd[0], "dropped",
            (json_int_t) nd[1], "method", CS != NULL
            ? "every sampled locus point is drawn: over Q(sqrt d) the z-plane is not decomposed, so arcs "
              "separating nothing are included"
            : Za.A != NULL
            ? "a sampled locus point is drawn iff its arc in the decomposition of the z-plane by the Schur-Cohn "
              "conditions over Q(i)[re, im] (stable iff all > 0) has cells of different exact verdicts on its two "
              "sides (each decided at a rational sample by Schur-Cohn over Q(i) and Bilharz)"
            : "every sampled locus point is drawn: the decomposition of the z-plane did not complete, so arcs "
              "separating nothing are included"));
        if (CS == NULL) zarcs_clear(&Za);
        json_object_set_new(o, "locus_table", json_string(loc));
        free(loc);
        json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
        json_object_set_new(o, "text", json_string(q->text));
        json_object_set_new(o, "columns", json_pack("[sssssssssss]", "index", "i", "j", pre, pim, "", "", "verdict",
                            "code", "decided_by", ""));
        {
            /* the exact columns' names */
            char a[32], b[32];
            snprintf(a, sizeof a, "%s_exact", pre);
            snprintf(b, sizeof b, "%s_exact", pim);
            json_array_set_new(json_object_get(o, "columns"), 5, json_string(a));
            json_array_set_new(json_object_get(o, "columns"), 6, json_string(b));
            json_array_remove(json_object_get(o, "columns"), 10);
        }
        /* the coordinates are reals in the JSON rows, as they always were */
        if (T.text != NULL) {
            json_object_set_new(o, "table", json_string(T.text));
            rs_sweep_json_rows_typed(o, "rows", T.text, cap, real);
        } else {
            json_object_set_new(o, "table_spool", json_integer(T.spool));
            json_object_set_new(o, "rows", json_pack("{sIsIsO}", "spool", (json_int_t) T.spool, "count",
                                (json_int_t) (cap >= 0 && nrow > cap ? cap : nrow), "real", real));
            if (cap >= 0 && nrow > cap) json_object_set_new(o, "rows_omitted", json_integer(nrow - cap));
        }
        json_decref(real);
        json_array_append_new(run->results, o);
    }
    rs_sweep_table_clear(&T);
    for (k = 0; k < 2; k++) _fmpq_vec_clear(xs[k], m->n[k]);
    zplane_coeffs_clear(CR, CI != NULL ? CI : CS, K);
    return r;
}

/* ---- region re(NAME), im(NAME): the exact stable set in the z-plane ------------- */

int rs_an_complex_region_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *t = req->rest;
    cmap_req_t *m = calloc(1, sizeof *m);
    int axis;
    fmpq_init(m->lo[0]); fmpq_init(m->lo[1]); fmpq_init(m->hi[0]); fmpq_init(m->hi[1]);
    req->u.sweep = m;
    m->param = -1;
    for (axis = 0; axis < 2; axis++) {
        int r = cx_axis_read(run, q, &t, axis, &m->param,
                             axis == 0 ? "expected region re(NAME), im(NAME), found '%s'"
                                       : "expected im(NAME) after the comma, found '%s'");
        if (r != RS_OK) return r;
        while (*t == ' ' || *t == '\t') t++;
        if (axis == 0) {
            if (*t != ',') return rs_req_error(run, q, t, RS_ERR_INPUT, "expected ', im(NAME)', found '%s'", t);
            t++;
        }
    }
    if (*t != '\0') return rs_req_error(run, q, t, RS_ERR_INPUT, "expected end of line, found '%s'", t);
    return RS_OK;
}

/* the exact point verdict at z = x + i y: Schur-Cohn over Q(i) and Bilharz */
static int cregion_status(rs_status_t *st, const fmpq_t x, const fmpq_t y, void *arg)
{
    const cregion_pt_t *a = arg;
    fmpq_poly_t re, im;
    int r;
    fmpq_poly_init(re); fmpq_poly_init(im);
    eval_coeffs(re, im, a->CR, a->CI, a->K, x, y);
    r = rs_routh_complex_checked_status(st, re, im, a->n, a->run->err);
    if (r == RS_ERR_INCONSISTENT) a->run->outcome |= RS_OUTCOME_INCONSISTENT;
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    return r;
}

static int zarcs_init(zarcs_t *Z, rs_run_t *run, const fmpq_poly_struct *CR, const fmpq_poly_struct *CI, slong K,
                      slong n, const char *name)
{
    slong gmap[3] = {0, 1, 2};
    int r;
    zplane_init(&Z->xs, Z->vars, Z->xn, Z->yn, name);
    fmpz_mpoly_init(Z->re, Z->xs.zctx); fmpz_mpoly_init(Z->im, Z->xs.zctx);
    zplane_poly(Z->re, Z->im, CR, CI, K, Z->xs.zctx);
    rs_schur_cx_conds_init(&Z->cc);
    Z->A = NULL;
    if (!rs_schur_cx_conds(&Z->cc, Z->re, Z->im, 2, Z->xs.zctx)) return RS_ERR_LIMIT;
    Z->pt.CR = CR;
    Z->pt.CI = CI;
    Z->pt.K = K;
    Z->pt.n = n;
    Z->pt.run = run;
    memset(&Z->cx, 0, sizeof Z->cx);
    Z->cx.s = &Z->xs;
    Z->cx.lead = Z->cc.lead;
    Z->cx.delta = Z->cc.delta;
    Z->cx.ndelta = Z->cc.ndelta;
    Z->cx.status = cregion_status;
    Z->cx.arg = &Z->pt;
    Z->cx.name = name;
    r = rs_region_arcs_new_cx(&Z->A, run, &Z->cx, Z->xs.zctx, gmap, 3);
    if (r != RS_OK) Z->A = NULL;
    return r;
}

static void zarcs_clear(zarcs_t *Z)
{
    rs_region_arcs_free(Z->A);
    rs_schur_cx_conds_clear(&Z->cc, Z->xs.zctx);
    fmpz_mpoly_clear(Z->re, Z->xs.zctx); fmpz_mpoly_clear(Z->im, Z->xs.zctx);
    zplane_clear(&Z->xs);
}

/* ---- the marginal set: where a root can reach the circle or double ------------ */

/* In Z[x, y, lambda, I, w] (ctx4) i is the variable I, reduced by I^2 = -1
 * afterwards: the resultants and discriminants of polynomials over
 * Q(i)[x, y] are those over Z[x, y, I] mapped by I -> i.  (re, im) = f
 * reduced, moved to ctx3 (x, y, lambda). */
enum { C4_X = 0, C4_Y = 1, C4_L = 2, C4_I = 3, C4_W = 4 };

static void c4_split(fmpz_mpoly_t re, fmpz_mpoly_t im, const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx4,
                     const fmpz_mpoly_ctx_t ctx3)
{
    slong d = fmpz_mpoly_degree_si(f, C4_I, ctx4), k;
    slong gen[5] = {0, 1, 2, 2, 2};   /* I is gone; lambda or w (one of them, the other of degree 0) -> 2 */
    fmpz_mpoly_t a, b, t;
    fmpz_mpoly_init(a, ctx4); fmpz_mpoly_init(b, ctx4); fmpz_mpoly_init(t, ctx4);
    for (k = 0; k <= d; k++) {
        ulong e = (ulong) k;
        slong v = C4_I;
        fmpz_mpoly_get_coeff_vars_ui(t, f, &v, &e, 1, ctx4);
        /* I^k = (-1)^(k/2) I^(k mod 2) */
        if ((k / 2) % 2) fmpz_mpoly_neg(t, t, ctx4);
        fmpz_mpoly_add(k % 2 ? b : a, k % 2 ? b : a, t, ctx4);
    }
    fmpz_mpoly_compose_fmpz_mpoly_gen(re, a, gen, ctx4, ctx3);
    fmpz_mpoly_compose_fmpz_mpoly_gen(im, b, gen, ctx4, ctx3);
    fmpz_mpoly_clear(a, ctx4); fmpz_mpoly_clear(b, ctx4); fmpz_mpoly_clear(t, ctx4);
}

/* the points where a = b = 0 (a, b in Z[x, y]): into u, v the curve a and
 * the lines Res_y(a, b)(x) (b when that resultant is unusable: a or b free
 * of y, a common factor) */
static void zregion_points(fmpz_mpoly_t u, fmpz_mpoly_t v, const fmpz_mpoly_t a, const fmpz_mpoly_t b,
                           const fmpz_mpoly_ctx_t ctx3)
{
    if (fmpz_mpoly_is_zero(a, ctx3) || fmpz_mpoly_is_zero(b, ctx3)) {
        fmpz_mpoly_set(u, a, ctx3);
        fmpz_mpoly_set(v, b, ctx3);
        return;
    }
    fmpz_mpoly_set(u, a, ctx3);
    if (fmpz_mpoly_degree_si(a, 1, ctx3) < 1 || fmpz_mpoly_degree_si(b, 1, ctx3) < 1
        || !fmpz_mpoly_resultant(v, a, b, 1, ctx3) || fmpz_mpoly_is_zero(v, ctx3))
        fmpz_mpoly_set(v, b, ctx3);
}

/* The polynomials in (x, y) of p = re + i im whose zero sets contain every
 * point where the roots' relation to the circle or their multiplicity can
 * change (into E[0 .. *ne), at most 5, initialised in ctx3):
 *   Res_w(A, B) where q(i w) = A(w) + i B(w), q the bilinear transform
 *   (Bilharz): a root on the circle other than -1 is a real common root w;
 *   p(-1) = 0: the root -1 (q's degree drops there);
 *   disc_lambda(p) = 0: a double root.
 * The last two hold at points only (Re = Im = 0): each is cut out by the
 * curve Re = 0 and the vertical lines Res_y(Re, Im)(x) = 0 through those
 * points (zregion_points), not by the two curves Re = 0, Im = 0 whose
 * every crossing and fold made columns and cells that decide nothing
 * (AB3: 957 cells).  Where Re f != 0 or Res_y(Re, Im) != 0, f != 0.
 * 0 when Res_w(A, B) vanishes identically (A, B share a factor in w). */
static int zregion_extra(fmpz_mpoly_struct *E, slong *ne, const fmpz_mpoly_t re, const fmpz_mpoly_t im,
                         const fmpz_mpoly_ctx_t ctx3)
{
    fmpz_mpoly_ctx_t ctx4;
    fmpz_mpoly_t P, Q, t, A, B, sub[5];
    slong up[5] = {C4_X, C4_Y, C4_L, 0, 0}, k;
    fmpz_t m1;
    int ok = 1;
    fmpz_mpoly_ctx_init(ctx4, 5, ORD_LEX);
    fmpz_mpoly_init(P, ctx4); fmpz_mpoly_init(Q, ctx4); fmpz_mpoly_init(t, ctx4);
    fmpz_mpoly_init(A, ctx3); fmpz_mpoly_init(B, ctx3);
    fmpz_init(m1);
    /* P = re + I im in ctx4 */
    fmpz_mpoly_compose_fmpz_mpoly_gen(P, re, up, ctx3, ctx4);
    fmpz_mpoly_compose_fmpz_mpoly_gen(t, im, up, ctx3, ctx4);
    fmpz_mpoly_gen(Q, C4_I, ctx4);
    fmpz_mpoly_mul(t, t, Q, ctx4);
    fmpz_mpoly_add(P, P, t, ctx4);
    *ne = 0;
    /* q(s) at s = I w: lambda -> I w after the bilinear map */
    rs_bilinear_fmpz_mpoly(Q, P, C4_L, ctx4);
    for (k = 0; k < 5; k++) {
        fmpz_mpoly_init(sub[k], ctx4);
        fmpz_mpoly_gen(sub[k], k, ctx4);
    }
    fmpz_mpoly_gen(t, C4_W, ctx4);
    fmpz_mpoly_mul(sub[C4_L], sub[C4_I], t, ctx4);
    {
        fmpz_mpoly_struct *vals[5];
        for (k = 0; k < 5; k++) vals[k] = sub[k];
        ok = fmpz_mpoly_compose_fmpz_mpoly(t, Q, vals, ctx4, ctx4);
    }
    for (k = 0; k < 5; k++) fmpz_mpoly_clear(sub[k], ctx4);
    if (ok) {
        /* A + I B with w as the variable (c4_split puts w in lambda's place) */
        c4_split(A, B, t, ctx4, ctx3);
        fmpz_mpoly_init(E + 0, ctx3);
        ok = !fmpz_mpoly_is_zero(A, ctx3) && !fmpz_mpoly_is_zero(B, ctx3)
             && fmpz_mpoly_resultant(E + 0, A, B, 2, ctx3) && !fmpz_mpoly_is_zero(E + 0, ctx3);
        *ne = 1;
    }
    if (ok) {
        /* p(-1) */
        fmpz_set_si(m1, -1);
        fmpz_mpoly_init(E + 1, ctx3);
        fmpz_mpoly_init(E + 2, ctx3);
        fmpz_mpoly_evaluate_one_fmpz(A, re, 2, m1, ctx3);
        fmpz_mpoly_evaluate_one_fmpz(B, im, 2, m1, ctx3);
        zregion_points(E + 1, E + 2, A, B, ctx3);
        *ne = 3;
        /* disc_lambda(p) */
        if (fmpz_mpoly_degree_si(P, C4_L, ctx4) >= 2 && fmpz_mpoly_discriminant(t, P, C4_L, ctx4)) {
            fmpz_mpoly_init(E + 3, ctx3);
            fmpz_mpoly_init(E + 4, ctx3);
            c4_split(A, B, t, ctx4, ctx3);
            zregion_points(E + 3, E + 4, A, B, ctx3);
            *ne = 5;
        }
    }
    fmpz_clear(m1);
    fmpz_mpoly_clear(A, ctx3); fmpz_mpoly_clear(B, ctx3);
    fmpz_mpoly_clear(P, ctx4); fmpz_mpoly_clear(Q, ctx4); fmpz_mpoly_clear(t, ctx4);
    fmpz_mpoly_ctx_clear(ctx4);
    return ok;
}

/* norms[k] = |c^n p(rho_k lambda)|^2 / content, k = 0 .. cnt-1, for p =
 * re + i im of degree n in lambda (variable lv), rho_0 = 1 and rho_k =
 * (a + b i)/c with a = (k+1)^2 - 1, b = 2(k+1), c = (k+1)^2 + 1 (|rho| = 1,
 * argument 2 atan(1/(k+1)) strictly decreasing in (0, pi/2): the rho_k^2
 * are distinct).  The roots of norms[k] are p's divided by rho_k and their
 * conjugates (an_region.h: rs_region_cx_t). */
static void zregion_norms(fmpz_mpoly_struct *norms, slong cnt, const fmpz_mpoly_t re, const fmpz_mpoly_t im,
                          slong lv, const fmpz_mpoly_ctx_t ctx)
{
    slong n = FLINT_MAX(fmpz_mpoly_degree_si(re, lv, ctx), fmpz_mpoly_degree_si(im, lv, ctx)), k, j;
    fmpz_mpoly_t Fr, Fi, rj, ij, t, u, L;
    fmpz_t a, b, c, ur, ui, w, cpow;
    fmpz_mpoly_init(Fr, ctx); fmpz_mpoly_init(Fi, ctx); fmpz_mpoly_init(rj, ctx); fmpz_mpoly_init(ij, ctx);
    fmpz_mpoly_init(t, ctx); fmpz_mpoly_init(u, ctx); fmpz_mpoly_init(L, ctx);
    fmpz_init(a); fmpz_init(b); fmpz_init(c); fmpz_init(ur); fmpz_init(ui); fmpz_init(w); fmpz_init(cpow);
    for (k = 0; k < cnt; k++) {
        fmpz_mpoly_init(norms + k, ctx);
        if (k == 0) { fmpz_one(a); fmpz_zero(b); fmpz_one(c); }
        else { fmpz_set_si(a, (k + 1) * (k + 1) - 1); fmpz_set_si(b, 2 * (k + 1)); fmpz_set_si(c, (k + 1) * (k + 1) + 1); }
        fmpz_mpoly_zero(Fr, ctx);
        fmpz_mpoly_zero(Fi, ctx);
        /* (ur + i ui) = (a + b i)^j, times c^(n - j) */
        fmpz_one(ur); fmpz_zero(ui);
        fmpz_mpoly_one(L, ctx);
        for (j = 0; j <= n; j++) {
            ulong e = (ulong) j;
            fmpz_pow_ui(cpow, c, (ulong) (n - j));
            fmpz_mpoly_get_coeff_vars_ui(rj, re, &lv, &e, 1, ctx);
            fmpz_mpoly_get_coeff_vars_ui(ij, im, &lv, &e, 1, ctx);
            fmpz_mpoly_mul(rj, rj, L, ctx);
            fmpz_mpoly_mul(ij, ij, L, ctx);
            fmpz_mpoly_scalar_mul_fmpz(rj, rj, cpow, ctx);
            fmpz_mpoly_scalar_mul_fmpz(ij, ij, cpow, ctx);
            /* (rj + i ij)(ur + i ui) */
            fmpz_mpoly_scalar_mul_fmpz(t, rj, ur, ctx);
            fmpz_mpoly_scalar_mul_fmpz(u, ij, ui, ctx);
            fmpz_mpoly_sub(t, t, u, ctx);
            fmpz_mpoly_add(Fr, Fr, t, ctx);
            fmpz_mpoly_scalar_mul_fmpz(t, rj, ui, ctx);
            fmpz_mpoly_scalar_mul_fmpz(u, ij, ur, ctx);
            fmpz_mpoly_add(t, t, u, ctx);
            fmpz_mpoly_add(Fi, Fi, t, ctx);
            /* next power of a + b i and of lambda */
            fmpz_mul(w, ur, a);
            fmpz_submul(w, ui, b);
            fmpz_mul(ui, ui, a);
            fmpz_addmul(ui, ur, b);
            fmpz_swap(ur, w);
            fmpz_mpoly_gen(t, lv, ctx);
            fmpz_mpoly_mul(L, L, t, ctx);
        }
        fmpz_mpoly_mul(norms + k, Fr, Fr, ctx);
        fmpz_mpoly_mul(t, Fi, Fi, ctx);
        fmpz_mpoly_add(norms + k, norms + k, t, ctx);
        if (!fmpz_mpoly_is_zero(norms + k, ctx)) {
            _fmpz_vec_content(w, norms[k].coeffs, norms[k].length);
            fmpz_mpoly_scalar_divexact_fmpz(norms + k, norms + k, w, ctx);
        }
    }
    fmpz_mpoly_clear(Fr, ctx); fmpz_mpoly_clear(Fi, ctx); fmpz_mpoly_clear(rj, ctx); fmpz_mpoly_clear(ij, ctx);
    fmpz_mpoly_clear(t, ctx); fmpz_mpoly_clear(u, ctx); fmpz_mpoly_clear(L, ctx);
    fmpz_clear(a); fmpz_clear(b); fmpz_clear(c); fmpz_clear(ur); fmpz_clear(ui); fmpz_clear(w); fmpz_clear(cpow);
}

int rs_an_complex_region(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const cmap_req_t *m = req->u.sweep;
    const char *name = run->c->params[m->param].name;
    char xn[24], yn[24];
    char *vars[3];
    rs_variant_t *v;
    rs_scheme_struct xs;
    fmpq_poly_struct *CR = NULL, *CI = NULL;
    fmpz_mpoly_t re, im;
    fmpz_mpoly_struct E[5], *NR = NULL;
    slong ne = 0, nn = 0;
    rs_schur_cx_conds_t cc;
    rs_region_cx_t cx;
    cregion_pt_t pt;
    slong K = 0, n = 0, k;
    int r = rs_run_variant_one_free(&v, run, q, req->rest, m->param, "region");
    if (r != RS_OK) return r;
    /* p = sum_k (CR_k + i CI_k)(lambda) NAME^k (CI NULL: real coefficients;
     * a char line with i: p = A + i B from its block) */
    if (!zplane_coeffs(&CR, &CI, &K, &n, v, m->param)) {
        char msg[300];
        snprintf(msg, sizeof msg, "region re(%s), im(%s): the char line depends on a parameter other than %s", name,
                 name, name);
        zplane_coeffs_clear(CR, CI, K);
        return rs_req_error(run, q, req->rest, RS_ERR_INPUT, "%s", msg);
    }
    if (K < 1 || n < 1) {
        zplane_coeffs_clear(CR, CI, K);
        return rs_req_error(run, q, req->rest, RS_ERR_INPUT, "region re(%s), im(%s): the characteristic polynomial "
                            "must depend on the parameter and on lambda", name);
    }
    zplane_init(&xs, vars, xn, yn, name);
    fmpz_mpoly_init(re, xs.zctx); fmpz_mpoly_init(im, xs.zctx);
    zplane_poly(re, im, CR, CI, K, xs.zctx);
    rs_schur_cx_conds_init(&cc);
    if (!rs_schur_cx_conds(&cc, re, im, 2, xs.zctx)) {
        r = rs_budget_check(run->err, "region re(z), im(z) (Schur-Cohn conditions)");
        if (r == RS_OK)
            r = rs_req_error(run, q, req->rest, RS_ERR_LIMIT, "region re(%s), im(...): the Schur-Cohn conditions over "
                             "Q(i) grow too large", name);
    } else {
        pt.CR = CR;
        pt.CI = CI;
        pt.K = K;
        pt.n = n;
        pt.run = run;
        memset(&cx, 0, sizeof cx);
        /* the marginal set: the circle locus beside the conditions, and the
         * norms |p(rho lambda)|^2 for the exact verdicts at algebraic samples */
        if (zregion_extra(E, &ne, re, im, xs.zctx)) {
            nn = n * (n + 1) / 2 + 1;
            NR = flint_malloc(nn * sizeof(fmpz_mpoly_struct));
            zregion_norms(NR, nn, re, im, 2, xs.zctx);
            cx.extra = E;
            cx.nextra = ne;
            cx.norm = NR;
            cx.nnorm = nn;
        }
        cx.s = &xs;
        cx.lead = cc.lead;
        cx.delta = cc.delta;
        cx.ndelta = cc.ndelta;
        cx.status = cregion_status;
        cx.arg = &pt;
        cx.name = name;
        cx.substituted = v->assigned;
        r = rs_an_region_cad_cx(run, &cx);
    }
    rs_schur_cx_conds_clear(&cc, xs.zctx);
    for (k = 0; k < ne; k++) fmpz_mpoly_clear(E + k, xs.zctx);
    for (k = 0; k < nn; k++) fmpz_mpoly_clear(NR + k, xs.zctx);
    flint_free(NR);
    zplane_coeffs_clear(CR, CI, K);
    fmpz_mpoly_clear(re, xs.zctx); fmpz_mpoly_clear(im, xs.zctx);
    zplane_clear(&xs);
    return r;
}
