/* an_limit.c -- `limit NAME -> 0|inf`: the limits of the roots with their
 * multiplicities (spurious roots, stiff decay). */
#include <stdlib.h>
#include <string.h>
#include <arb.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include <math.h>
#include <acb_poly.h>
#include <fmpq_poly.h>
#include "analysis/registry.h"
#include "stability/schur_complex.h"
#include "util/polyfmt.h"
#include "recstab/charpoly.h"
#include "recstab/radius.h"
#include "analysis/an_qd.h"

/* ---- limit ------------------------------------------------------------------- */

/* the root of the linear g, exactly, with multiplicity e */
static void rational_root_json(json_t *arr, const fmpz_poly_t g, slong e)
{
    fmpq_t x;
    fmpq_init(x);
    fmpq_set_fmpz_frac(x, g->coeffs + 0, g->coeffs + 1);
    fmpq_neg(x, x);
    json_array_append_new(arr, json_pack("{s:o,s:I,s:f}", "value", rs_json_fmpq(x), "multiplicity", (json_int_t) e,
                                         "abs", fabs(fmpq_get_d(x))));
    fmpq_clear(x);
}

/* root k of the minimal polynomial mp (its ball x) to 20 digits, multiplicity e */
static void algebraic_root_json(json_t *arr, const acb_t x, const char *mp, slong k, slong e, slong prec)
{
    char *re = arb_get_str(acb_realref(x), 20, ARB_STR_NO_RADIUS);
    char *im = arb_get_str(acb_imagref(x), 20, ARB_STR_NO_RADIUS);
    char *val = malloc(strlen(re) + strlen(im) + 8);
    arb_t ab;
    arb_init(ab);
    acb_abs(ab, x, prec);
    if (arb_is_zero(acb_imagref(x))) sprintf(val, "%s", re);
    else sprintf(val, "%s %s %si", re, im[0] == '-' ? "-" : "+", im[0] == '-' ? im + 1 : im);
    json_array_append_new(arr, json_pack("{s:s,s:s,s:I,s:I,s:f}", "value", val, "minpoly", mp, "root_index",
                                         (json_int_t) k, "multiplicity", (json_int_t) e, "abs",
                                         arf_get_d(arb_midref(ab), ARF_RND_NEAR)));
    arb_clear(ab);
    free(val);
    flint_free(re);
    flint_free(im);
}

/* the roots of f (with multiplicity) as JSON: rationals exactly, other
 * algebraic roots by minimal polynomial and a 20-digit value */
static void roots_json(json_t *arr, const fmpz_poly_t f)
{
    fmpz_poly_factor_t fac;
    slong i, k;
    if (fmpz_poly_degree(f) < 1) return;
    fmpz_poly_factor_init(fac);
    fmpz_poly_factor(fac, f);
    for (i = 0; i < fac->num; i++) {
        const fmpz_poly_struct *g = fac->p + i;
        slong d = fmpz_poly_degree(g), e = fac->exp[i];
        if (d < 1) continue;
        if (d == 1) rational_root_json(arr, g, e);
        else {
            acb_ptr r = _acb_vec_init(d);
            char *mp = rs_polyfmt_fmpz_poly(g, "lambda");
            rs_radius_complex_roots(r, g, 96);
            for (k = 0; k < d; k++) algebraic_root_json(arr, r + k, mp, k, e, 96);
            free(mp);
            _acb_vec_clear(r, d);
        }
    }
    fmpz_poly_factor_clear(fac);
}

/* o's "roots" (taken) and the summary: every finite limit root at 0 (stiff
 * decay) with none to infinity (k of them), and the largest modulus */
static void limit_summary(json_t *o, json_t *roots, slong k)
{
    size_t i;
    int all_zero = (k == 0);
    double maxabs = 0;
    json_object_set_new(o, "roots", roots);
    for (i = 0; i < json_array_size(roots); i++) {
        json_t *ab = json_object_get(json_array_get(roots, i), "abs");
        if (ab == NULL) { all_zero = 0; continue; }
        if (json_real_value(ab) != 0.0) all_zero = 0;
        if (json_real_value(ab) > maxabs) maxabs = json_real_value(ab);
    }
    json_object_set_new(o, "all_roots_to_zero", json_boolean(all_zero));
    json_object_set_new(o, "roots_to_infinity", json_integer(k));
    json_object_set_new(o, "max_abs", json_real(maxabs));
}

/* ---- limit at complex set values ------------------------------------------------ */

/* the roots of c = cr + i ci over Q(i) with multiplicity: Yun's squarefree
 * decomposition over Q(i) (exact multiplicities), linear factors exactly,
 * the others as certified balls (20 digits; "abs" their modulus) */
static int cx_roots_json(json_t *arr, const fmpq_poly_t cr, const fmpq_poly_t ci, slong max_prec)
{
    rs_cx_sqfree_t f;
    slong k, j;
    int ok = 1;
    rs_cx_sqfree_init(&f);
    rs_schur_complex_sqfree(&f, cr, ci);
    for (k = 0; k < f.n; k++) {
        slong d = FLINT_MAX(fmpq_poly_degree(f.re + k), fmpq_poly_degree(f.im + k));
        if (d < 1) continue;
        {
            fmpq_t c0, c1;
            fmpq_init(c0); fmpq_init(c1);
            fmpq_poly_get_coeff_fmpq(c0, f.re + k, 0);
            fmpq_poly_get_coeff_fmpq(c1, f.im + k, 0);
            if (fmpq_is_zero(c0) && fmpq_is_zero(c1)) {   /* the root 0, exactly (at most once: squarefree) */
                json_array_append_new(arr, json_pack("{s:s,s:I,s:f}", "value", "0", "multiplicity",
                                                     (json_int_t) k + 1, "abs", 0.0));
                fmpq_poly_shift_right(f.re + k, f.re + k, 1);
                fmpq_poly_shift_right(f.im + k, f.im + k, 1);
                d--;
            }
            fmpq_clear(c0); fmpq_clear(c1);
        }
        if (d < 1) continue;
        if (d == 1) {   /* monic: lambda + b, the root -b */
            fmpq_t br, bi;
            char *val;
            fmpq_init(br); fmpq_init(bi);
            fmpq_poly_get_coeff_fmpq(br, f.re + k, 0);
            fmpq_poly_get_coeff_fmpq(bi, f.im + k, 0);
            fmpq_neg(br, br); fmpq_neg(bi, bi);
            val = rs_complex_str(br, bi);
            json_array_append_new(arr, json_pack("{s:s,s:I,s:f}", "value", val, "multiplicity", (json_int_t) k + 1,
                                                 "abs", sqrt(fmpq_get_d(br) * fmpq_get_d(br)
                                                             + fmpq_get_d(bi) * fmpq_get_d(bi))));
            free(val);
            fmpq_clear(br); fmpq_clear(bi);
        } else {
            acb_ptr r = _acb_vec_init(d);
            if (!rs_cx_isolate_sqfree(r, f.re + k, f.im + k, 70, 128, max_prec)) ok = 0;
            for (j = 0; j < d && ok; j++) {
                char *re = arb_get_str(acb_realref(r + j), 20, 0), *im = arb_get_str(acb_imagref(r + j), 20, 0);
                char *val = malloc(strlen(re) + strlen(im) + 8);
                arb_t ab;
                arb_init(ab);
                acb_abs(ab, r + j, 128);
                sprintf(val, "%s + (%s)i", re, im);
                json_array_append_new(arr, json_pack("{s:s,s:I,s:f}", "value", val, "multiplicity",
                                                     (json_int_t) k + 1, "abs",
                                                     arf_get_d(arb_midref(ab), ARF_RND_NEAR)));
                arb_clear(ab);
                free(val);
                flint_free(re);
                flint_free(im);
            }
            _acb_vec_clear(r, d);
        }
    }
    rs_cx_sqfree_clear(&f);
    return ok;
}

/* limit NAME -> 0|inf with p over Q(i) (complex set values): the lowest
 * (highest) coefficient in NAME of p = re + i im, a polynomial in lambda
 * over Q(i), and its roots */
static int cx_limit(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    slong tv = req->u.limit.param, d, j, k, n;
    const char *name = run->c->params[tv].name, *keep[1];
    rs_assign_t *a = NULL;
    slong na = 0;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_t re, im;
    fmpz_poly_t cr, ci;
    fmpq_poly_t qr, qi;
    json_t *o, *roots, *sub;
    int r;
    keep[0] = name;
    for (k = 0; k < run->c->ncsets; k++)
        if (strcmp(run->c->csets[k].name, name) == 0)
            return rs_req_error(run, q, req->rest, RS_ERR_INPUT, "limit: '%s' has a complex set value: the limit is "
                                "taken in a parameter without one", name);
    rs_run_assignments(run, &a, &na, keep, 1, NULL, 0);
    v = NULL;
    r = rs_run_variant(&v, run, a, na);
    rs_assign_free(a, na);
    if (r != RS_OK) return rs_run_failed_or_vanishing(run, r, v, "limit");
    s = v->s;
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    n = rs_run_cx_poly_det(re, im, run, v);   /* det's roots at 0 stay at 0: listed */
    for (k = 0; k < s->nvars && r == RS_OK; k++) {
        char msg[300];
        if (k == s->lambda_var || k == tv) continue;
        if (fmpz_mpoly_degree_si(re, k, s->zctx) <= 0 && fmpz_mpoly_degree_si(im, k, s->zctx) <= 0) continue;
        snprintf(msg, sizeof msg, "limit needs every other parameter set to a number (real or complex); still "
                 "symbolic: %s", s->vars[k]);
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
    }
    if (r != RS_OK) {
        fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
        return r;
    }
    fmpz_poly_init(cr); fmpz_poly_init(ci);
    fmpq_poly_init(qr); fmpq_poly_init(qi);
    d = FLINT_MAX(fmpz_mpoly_degree_si(re, tv, s->zctx), fmpz_mpoly_degree_si(im, tv, s->zctx));
    if (req->u.limit.to_inf) {
        rs_run_coeff_in(cr, re, tv, d < 0 ? 0 : d, s);
        rs_run_coeff_in(ci, im, tv, d < 0 ? 0 : d, s);
    } else {
        for (j = 0; j <= d; j++) {
            rs_run_coeff_in(cr, re, tv, j, s);
            rs_run_coeff_in(ci, im, tv, j, s);
            if (!fmpz_poly_is_zero(cr) || !fmpz_poly_is_zero(ci)) break;
        }
    }
    fmpq_poly_set_fmpz_poly(qr, cr);
    fmpq_poly_set_fmpz_poly(qi, ci);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("limit"));
    json_object_set_new(o, "param", json_string(name));
    json_object_set_new(o, "to", json_string(req->u.limit.to_inf ? "inf" : "0"));
    json_object_set_new(o, "over", json_string("Q(i)"));
    {
        char *lp = rs_cx_poly_str(qr, qi, "lambda");
        json_object_set_new(o, "limit_poly", json_string(lp));
        free(lp);
    }
    roots = json_array();
    if (!fmpq_poly_is_zero(qr) || !fmpq_poly_is_zero(qi)) {
        if (!cx_roots_json(roots, qr, qi, run->opt->max_prec)) {
            char msg[200];
            snprintf(msg, sizeof msg, "limit: the roots of the limit polynomial were not isolated within %ld bits "
                     "(raise --max-prec)", (long) run->opt->max_prec);
            r = rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", msg);
        }
    }
    k = n - FLINT_MAX(fmpq_poly_degree(qr), fmpq_poly_degree(qi));
    if (k > 0) json_array_append_new(roots, json_pack("{s:s,s:I}", "value", "inf", "multiplicity", (json_int_t) k));
    limit_summary(o, roots, k);
    sub = json_deep_copy(v->assigned);
    json_object_update_new(sub, rs_run_cx_at(run));
    json_object_set_new(o, "substituted", sub);
    json_object_set_new(o, "decided_by", json_string("exact"));
    if (r == RS_OK) json_array_append_new(run->results, o);
    else json_decref(o);
    fmpz_poly_clear(cr); fmpz_poly_clear(ci);
    fmpq_poly_clear(qr); fmpq_poly_clear(qi);
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    return r;
}

/* ---- limit over Q(sqrt d) (rk sdirk2, sdirk3) ----------------------------------- */

/* the first m with the ball a^(m)(x) (a = a0 + e sqrt(d) a1, e = +-1, the
 * m-th derivatives in D0, D1) away from 0: an upper bound on x's
 * multiplicity as a root of a; top + 1 when none is */
static slong qd_first_nonzero(const fmpz_poly_struct *D0, const fmpz_poly_struct *D1, slong top, int e,
                              const acb_t x, const arb_t sd, slong prec)
{
    acb_poly_t P;
    acb_t y0, y1;
    slong m;
    acb_poly_init(P);
    acb_init(y0); acb_init(y1);
    for (m = 0; m <= top; m++) {
        acb_poly_set_fmpz_poly(P, D0 + m, prec);
        acb_poly_evaluate(y0, P, x, prec);
        acb_poly_set_fmpz_poly(P, D1 + m, prec);
        acb_poly_evaluate(y1, P, x, prec);
        acb_mul_arb(y1, y1, sd, prec);
        if (e > 0) acb_add(y0, y0, y1, prec);
        else acb_sub(y0, y0, y1, prec);
        if (!acb_contains_zero(y0)) break;
    }
    acb_poly_clear(P);
    acb_clear(y0); acb_clear(y1);
    return m;
}

/* the roots of L = c0 + sqrt(d) c1 with multiplicity into arr: the norm
 * N = c0^2 - d c1^2 factored over Q, N = L conj(L); a root x of a factor f^e
 * of N has mult_L(x) + mult_conj(L)(x) = e, and the first derivatives of L
 * and conj(L) certified non-zero at x's ball bound the two multiplicities
 * from above: when the bounds add up to e they are exact (else the
 * precision is doubled up to max_prec; 0 when that did not suffice) */
static int qd_roots_json(json_t *arr, const fmpz_poly_t c0, const fmpz_poly_t c1, slong d, slong max_prec)
{
    fmpz_poly_t N, t;
    fmpz_poly_factor_t fac;
    fmpz_poly_struct *D0, *D1;
    slong i, k, m, top = FLINT_MAX(fmpz_poly_degree(c0), fmpz_poly_degree(c1));
    int ok = 1;
    if (top < 1) return 1;
    fmpz_poly_init(N); fmpz_poly_init(t);
    fmpz_poly_mul(N, c0, c0);
    fmpz_poly_mul(t, c1, c1);
    fmpz_poly_scalar_mul_si(t, t, d);
    fmpz_poly_sub(N, N, t);
    D0 = flint_malloc((size_t) (2 * top + 2) * sizeof(fmpz_poly_struct));
    D1 = D0 + top + 1;
    for (m = 0; m <= top; m++) {   /* the derivatives of c0, c1 */
        fmpz_poly_init(D0 + m); fmpz_poly_init(D1 + m);
        if (m == 0) { fmpz_poly_set(D0, c0); fmpz_poly_set(D1, c1); }
        else { fmpz_poly_derivative(D0 + m, D0 + m - 1); fmpz_poly_derivative(D1 + m, D1 + m - 1); }
    }
    fmpz_poly_factor_init(fac);
    fmpz_poly_factor(fac, N);
    for (i = 0; i < fac->num && ok; i++) {
        const fmpz_poly_struct *g = fac->p + i;
        slong dg = fmpz_poly_degree(g), e = fac->exp[i];
        acb_ptr r;
        char *mp;
        if (dg < 1) continue;
        r = _acb_vec_init(dg);
        mp = rs_polyfmt_fmpz_poly(g, "lambda");
        for (k = 0; k < dg && ok; k++) {
            slong prec, a = 0, b = 0;
            for (prec = 96; prec <= FLINT_MAX(max_prec, 96); prec *= 2) {
                arb_t sd;
                arb_init(sd);
                arb_sqrt_ui(sd, (ulong) d, prec);
                rs_radius_complex_roots(r, g, prec);
                a = qd_first_nonzero(D0, D1, top, 1, r + k, sd, prec);
                b = qd_first_nonzero(D0, D1, top, -1, r + k, sd, prec);
                arb_clear(sd);
                if (a + b == e) break;
            }
            if (a + b != e) { ok = 0; break; }
            if (a == 0) continue;   /* a root of conj(L) only */
            /* a rational root (then a root of c0 and c1 both) exactly */
            if (dg == 1) rational_root_json(arr, g, a);
            else algebraic_root_json(arr, r + k, mp, k, a, prec);
        }
        free(mp);
        _acb_vec_clear(r, dg);
    }
    fmpz_poly_factor_clear(fac);
    for (m = 0; m <= top; m++) { fmpz_poly_clear(D0 + m); fmpz_poly_clear(D1 + m); }
    flint_free(D0);
    fmpz_poly_clear(N); fmpz_poly_clear(t);
    return ok;
}

/* limit NAME -> 0|inf over Q(sqrt d) at real set values: p = p0 + sqrt(d) p1,
 * the lowest (highest) coefficient in NAME of both parts together, a
 * polynomial L = c0 + sqrt(d) c1 in lambda, and its roots (qd_roots_json) */
static int qd_limit(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    slong tv = req->u.limit.param, dd, j, k, dl, d;
    rs_variant_t *v = NULL;
    const rs_scheme_struct *s;
    fmpz_mpoly_t p0, p1;
    fmpz_poly_t c0, c1;
    fmpq_poly_t a0, a1;
    json_t *o, *roots;
    int r = rs_run_variant_one_free(&v, run, q, req->rest, tv, "limit");
    if (r != RS_OK) return rs_run_failed_or_vanishing(run, r, v, "limit");
    s = v->s;
    d = s->sqrt_d;
    fmpz_mpoly_init(p0, s->zctx); fmpz_mpoly_init(p1, s->zctx);
    fmpz_poly_init(c0); fmpz_poly_init(c1);
    fmpq_poly_init(a0); fmpq_poly_init(a1);
    rs_charpoly_coeff(p0, v->cp->p, 0, s->sqrt_var, s->zctx);
    rs_charpoly_coeff(p1, v->cp->p, 1, s->sqrt_var, s->zctx);
    dd = FLINT_MAX(fmpz_mpoly_degree_si(p0, tv, s->zctx), fmpz_mpoly_degree_si(p1, tv, s->zctx));
    for (j = req->u.limit.to_inf ? FLINT_MAX(dd, 0) : 0; j >= 0 && j <= FLINT_MAX(dd, 0);
         j += req->u.limit.to_inf ? -1 : 1) {
        rs_run_coeff_in(c0, p0, tv, j, s);
        rs_run_coeff_in(c1, p1, tv, j, s);
        if (!fmpz_poly_is_zero(c0) || !fmpz_poly_is_zero(c1)) break;
    }
    /* det = L lambda^k p: its k roots at 0 stay there for every value */
    fmpz_poly_shift_left(c0, c0, v->cp->removed_lambda_power);
    fmpz_poly_shift_left(c1, c1, v->cp->removed_lambda_power);
    dl = v->cp->degree + v->cp->removed_lambda_power;
    fmpq_poly_set_fmpz_poly(a0, c0);
    fmpq_poly_set_fmpz_poly(a1, c1);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("limit"));
    json_object_set_new(o, "param", json_string(run->c->params[tv].name));
    json_object_set_new(o, "to", json_string(req->u.limit.to_inf ? "inf" : "0"));
    {
        char *lp = rs_an_qd_fmpq_poly_str(a0, a1, d), *ov = rs_an_qd_over_str(d);
        json_object_set_new(o, "limit_poly", json_string(lp));
        json_object_set_new(o, "over", json_string(ov));
        free(lp);
        flint_free(ov);
    }
    json_object_set_new(o, "method", json_string(
        "the limit polynomial L = c0 + sqrt(d) c1; its roots from the norm c0^2 - d c1^2 factored over Q, each "
        "root's multiplicities in L and in its conjugate bounded by the first derivative certified non-zero "
        "there (Arb, sqrt d a ball) and fixed exactly by their sum, the norm's exponent"));
    roots = json_array();
    if (!qd_roots_json(roots, c0, c1, d, run->opt->max_prec)) {
        char msg[200];
        snprintf(msg, sizeof msg, "limit: the roots of the limit polynomial over Q(sqrt %ld) were not separated "
                 "from their conjugates within %ld bits (raise --max-prec)", (long) d, (long) run->opt->max_prec);
        r = rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", msg);
    }
    k = dl - FLINT_MAX(fmpz_poly_degree(c0), fmpz_poly_degree(c1));
    if (k > 0) json_array_append_new(roots, json_pack("{s:s,s:I}", "value", "inf", "multiplicity", (json_int_t) k));
    limit_summary(o, roots, k);
    if (r == RS_OK) rs_run_emit_exact(run, v, o);
    else json_decref(o);
    fmpz_mpoly_clear(p0, s->zctx); fmpz_mpoly_clear(p1, s->zctx);
    fmpz_poly_clear(c0); fmpz_poly_clear(c1);
    fmpq_poly_clear(a0); fmpq_poly_clear(a1);
    return r;
}

/* limit NAME -> 0|inf */
int rs_an_limit_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *rest = req->rest, *t;
    char name[80];
    t = rs_req_read_name(rest, name);
    if (t == NULL)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "expected a parameter name after limit, found '%s'", rest);
    req->u.limit.param = rs_case_param_index(run->c, name);
    if (req->u.limit.param < 0)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "'%s' is not a parameter", name);
    t = rs_req_skip_blanks(t);
    if (strncmp(t, "->", 2) != 0)
        return rs_req_error(run, q, t, RS_ERR_INPUT, "expected '-> 0' or '-> inf' after the name, found '%s'", t);
    t = rs_req_skip_blanks(t + 2);
    if (strcmp(t, "0") == 0) req->u.limit.to_inf = 0;
    else if (strcmp(t, "inf") == 0 || strcmp(t, "infinity") == 0 || strcmp(t, "oo") == 0) req->u.limit.to_inf = 1;
    else return rs_req_error(run, q, t, RS_ERR_INPUT, "expected 0 or inf, found '%s'", t);
    return RS_OK;
}

int rs_an_limit(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const char *rest = req->rest;
    const char *name = run->c->params[req->u.limit.param].name;
    slong tv = req->u.limit.param, d, k, j, dl;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    int to_inf = req->u.limit.to_inf, r;
    fmpz_poly_t c;
    json_t *o, *roots;
    if (run->c->ncsets > 0) return cx_limit(run, req);
    if (run->m->qd != NULL) return qd_limit(run, req);   /* over Q(sqrt d) at real set values */
    v = NULL;
    r = rs_run_variant_one_free(&v, run, q, rest, tv, "limit");
    /* det A identically 0 in lambda and the limit parameter at the others' set values */
    if (r != RS_OK) return rs_run_failed_or_vanishing(run, r, v, "limit");
    s = v->s;
    d = fmpz_mpoly_degree_si(v->cp->p, tv, s->zctx);
    dl = v->cp->degree;
    fmpz_poly_init(c);
    /* t -> 0: the lowest non-zero coefficient in t; t -> inf: the highest */
    if (to_inf) {
        rs_run_coeff_in(c, v->cp->p, tv, d < 0 ? 0 : d, s);
    } else {
        for (j = 0; j <= d; j++) {
            rs_run_coeff_in(c, v->cp->p, tv, j, s);
            if (!fmpz_poly_is_zero(c)) break;
        }
    }
    /* det = c lambda^k p: its k roots at 0 stay there for every value */
    fmpz_poly_shift_left(c, c, v->cp->removed_lambda_power);
    dl += v->cp->removed_lambda_power;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("limit"));
    json_object_set_new(o, "param", json_string(name));
    json_object_set_new(o, "to", json_string(to_inf ? "inf" : "0"));
    {
        char *lp = rs_polyfmt_fmpz_poly(c, "lambda");
        json_object_set_new(o, "limit_poly", json_string(lp));
        free(lp);
    }
    roots = json_array();
    roots_json(roots, c);
    k = dl - fmpz_poly_degree(c);
    if (k > 0)
        json_array_append_new(roots, json_pack("{s:s,s:I}", "value", "inf", "multiplicity", (json_int_t) k));
    limit_summary(o, roots, k);
    rs_run_emit_exact(run, v, o);
    fmpz_poly_clear(c);
    return RS_OK;
}
