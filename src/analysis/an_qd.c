/* an_qd.c -- issue 15: the analyses of a case whose one-state subsystem
 * y' = F is integrated by a tableau with R(z) not in Q(z) (rk sdirk2, R over
 * Q(sqrt 2); model.h's qd).  z = H*F is read exactly from the stand-in
 * equations' p = lambda - 1 - z and must be k*NAME for one parameter NAME;
 * R(k NAME) = N/D over Q(sqrt d) then gives
 *  - charpoly: p = D lambda - N, printed with sqrt(d) exactly;
 *  - stability at the set (real or complex) NAME: the sign of
 *    |D|^2 - |N|^2 in Q(sqrt d) decides, Schur-Cohn over Q(sqrt d)(i) and
 *    the certified Arb root (rs_qd_onestep_stable_at) must agree (exit 3);
 *  - astability: E-polynomial and poles (rs_qd_astab_decide), the real and
 *    imaginary intervals (rs_qd_onestep_interval), checked against each
 *    other (E >= 0 with the poles right iff the imaginary interval is the
 *    whole axis; A-stable implies (-inf, 0] and a stable z = -1).
 * Every other analysis is refused at its line (rs_an_qd_check). */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "algebra/qsqrt.h"

int rs_an_qd_check(rs_run_t *run, const rs_an_req_t *req)
{
    const char *n = req->def->name;
    if (run->m->qd == NULL) return RS_OK;
    if (strcmp(n, "charpoly") == 0 || strcmp(n, "stability") == 0 || strcmp(n, "astability") == 0) return RS_OK;
    return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT,
                        "expected charpoly, stability or astability: %s is not available for rk sdirk2 (its "
                        "R(z) has coefficients in Q(sqrt 2); only those three are decided over Q(sqrt 2))", n);
}

/* R(k t) = N/D in the parameter t: *par its index in the case */
typedef struct {
    slong d, par;
    fmpq_t k;
    rs_qdpoly_t N, D;
} qd_r_t;

static void qd_r_init(qd_r_t *R)
{
    R->d = 0;
    R->par = -1;
    fmpq_init(R->k);
    rs_qdpoly_init(R->N);
    rs_qdpoly_init(R->D);
}

static void qd_r_clear(qd_r_t *R)
{
    fmpq_clear(R->k);
    rs_qdpoly_clear(R->N);
    rs_qdpoly_clear(R->D);
}

/* z = H*F from the stand-in's p = a1 lambda + a0 (z = -(a0 + a1)/a1), which
 * must be k t for one parameter t and a rational k != 0; then N, D composed
 * with z = k t and checked coprime (their norms are) */
static int qd_r_get(qd_r_t *R, rs_run_t *run, const rs_request_t *q)
{
    const rs_scheme_struct *s = run->sym;
    const rs_model_qd_struct *qd = run->m->qd;
    rs_charpoly_t cp;
    fmpz_mpoly_t a0, a1;
    fmpz_t c;
    fmpq_poly_t nn, nd, g;
    slong j, var = -1;
    int r = RS_OK;
    if (!run->have_sym) return rs_req_error(run, q, q->text, RS_ERR_INTERNAL, "no scheme for %s", qd->tableau);
    rs_charpoly_init(cp, s);
    fmpz_mpoly_init(a0, s->zctx);
    fmpz_mpoly_init(a1, s->zctx);
    fmpz_init(c);
    r = rs_charpoly_compute(cp, s, run->err);
    if (r != RS_OK) r = rs_req_relocate(run, q, r, "charpoly");
    if (r == RS_OK && cp->degree != 1) r = RS_ERR_INPUT;
    if (r == RS_OK) {
        rs_charpoly_coeff(a1, cp->p, 1, s->lambda_var, s->zctx);
        rs_charpoly_coeff(a0, cp->p, 0, s->lambda_var, s->zctx);
        fmpz_mpoly_add(a0, a0, a1, s->zctx);   /* -z a1 */
        if (!fmpz_mpoly_is_fmpz(a1, s->zctx) || fmpz_mpoly_length(a0, s->zctx) != 1
            || fmpz_mpoly_total_degree_si(a0, s->zctx) != 1)
            r = RS_ERR_INPUT;
    }
    if (r == RS_OK) {
        for (j = 0; j < s->nvars; j++)
            if (fmpz_mpoly_degree_si(a0, j, s->zctx) == 1) var = j;
        R->par = var >= 0 && var != s->lambda_var ? rs_case_param_index(run->c, s->vars[var]) : -1;
        if (R->par < 0) r = RS_ERR_INPUT;
    }
    if (r == RS_OK) {
        fmpz_mpoly_get_term_coeff_fmpz(c, a0, 0, s->zctx);
        fmpz_neg(c, c);
        {
            fmpz_t den;
            fmpz_init(den);
            fmpz_mpoly_get_fmpz(den, a1, s->zctx);
            fmpq_set_fmpz_frac(R->k, c, den);   /* a1 != 0: p has degree 1 */
            fmpz_clear(den);
        }
    }
    if (r == RS_ERR_INPUT)
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT,
                         "expected y' = F*y with H*F = k*NAME for one parameter NAME (rk %s is analysed on "
                         "Dahlquist's test equation only)", qd->tableau);
    fmpz_mpoly_clear(a0, s->zctx);
    fmpz_mpoly_clear(a1, s->zctx);
    fmpz_clear(c);
    rs_charpoly_clear(cp, s);
    if (r != RS_OK) return r;
    R->d = qd->d;
    fmpq_poly_rescale(R->N->p0, qd->n0, R->k);
    fmpq_poly_rescale(R->N->p1, qd->n1, R->k);
    fmpq_poly_rescale(R->D->p0, qd->d0, R->k);
    fmpq_poly_rescale(R->D->p1, qd->d1, R->k);
    fmpq_poly_init(nn);
    fmpq_poly_init(nd);
    fmpq_poly_init(g);
    rs_qdpoly_norm(nn, R->N, R->d);
    rs_qdpoly_norm(nd, R->D, R->d);
    fmpq_poly_gcd(g, nn, nd);
    if (fmpq_poly_degree(g) > 0)   /* a common root of N and D is one of their norms */
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT,
                         "%s: N and D of R may share a root (their norms do); not supported", qd->tableau);
    fmpq_poly_clear(nn);
    fmpq_poly_clear(nd);
    fmpq_poly_clear(g);
    return r;
}

static json_t *json_str_free(char *s)
{
    json_t *j = json_string(s);
    flint_free(s);
    return j;
}

static char *over_str(slong d)
{
    char *s = flint_malloc(40);
    snprintf(s, 40, "Q(sqrt %ld)", (long) d);
    return s;
}

/* "(D)*lambda - (N)" in the parameter's name */
static char *p_str(const qd_r_t *R, const char *name)
{
    char *ds = rs_qdpoly_get_str(R->D, R->d, name), *ns = rs_qdpoly_get_str(R->N, R->d, name);
    size_t len = strlen(ds) + strlen(ns) + 32;
    char *out = flint_malloc(len);
    snprintf(out, len, "(%s)*lambda - (%s)", ds, ns);
    flint_free(ds);
    flint_free(ns);
    return out;
}

static void qd_common(json_t *o, const qd_r_t *R, rs_run_t *run)
{
    char ks[64], *kq = fmpq_get_str(NULL, 10, R->k);
    const char *name = run->c->params[R->par].name;
    char *z = flint_malloc(strlen(kq) + strlen(name) + 8);
    if (fmpq_is_one(R->k)) strcpy(z, name);
    else sprintf(z, "%s*%s", kq, name);
    json_object_set_new(o, "over", json_str_free(over_str(R->d)));
    json_object_set_new(o, "z", json_string(z));
    snprintf(ks, sizeof ks, "rk %s", run->m->qd->tableau);
    json_object_set_new(o, "method", json_string(ks));
    json_object_set_new(o, "stability_function",
                        json_pack("{s:o,s:o}", "N", json_str_free(rs_qdpoly_get_str(R->N, R->d, name)),
                                  "D", json_str_free(rs_qdpoly_get_str(R->D, R->d, name))));
    flint_free(kq);
    flint_free(z);
}

int rs_an_qd_charpoly(rs_run_t *run, const rs_an_req_t *req)
{
    qd_r_t R;
    json_t *o;
    int r;
    qd_r_init(&R);
    r = qd_r_get(&R, run, req->q);
    if (r == RS_OK) {
        json_t *co = json_array();
        o = json_object();
        json_object_set_new(o, "analysis", json_string("charpoly"));
        json_object_set_new(o, "var", json_string("lambda"));
        json_object_set_new(o, "degree", json_integer(1));
        /* coefficients of lambda^0, lambda^1: -N and D */
        {
            rs_qdpoly_t mN;
            rs_qdpoly_init(mN);
            fmpq_poly_neg(mN->p0, R.N->p0);
            fmpq_poly_neg(mN->p1, R.N->p1);
            json_array_append_new(co, json_str_free(rs_qdpoly_get_str(mN, R.d, run->c->params[R.par].name)));
            rs_qdpoly_clear(mN);
        }
        json_array_append_new(co, json_str_free(rs_qdpoly_get_str(R.D, R.d, run->c->params[R.par].name)));
        json_object_set_new(o, "coeffs", co);
        json_object_set_new(o, "poly", json_str_free(p_str(&R, run->c->params[R.par].name)));
        qd_common(o, &R, run);
        json_object_set_new(o, "substituted", json_object());
        json_object_set_new(o, "decided_by", json_string("exact"));
        json_array_append_new(run->results, o);
    }
    qd_r_clear(&R);
    return r;
}

int rs_an_qd_stability(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_case_struct *c = run->c;
    qd_r_t R;
    fmpq_t zr, zi;
    slong k;
    int r, found = 0;
    qd_r_init(&R);
    fmpq_init(zr);
    fmpq_init(zi);
    r = qd_r_get(&R, run, q);
    if (r == RS_OK) {
        const char *name = c->params[R.par].name;
        for (k = 0; k < c->nsets; k++)
            if (strcmp(c->sets[k].name, name) == 0) { fmpq_set(zr, c->sets[k].value); found = 1; }
        for (k = 0; k < c->ncsets; k++)
            if (strcmp(c->csets[k].name, name) == 0) { fmpq_set(zr, c->csets[k].re); fmpq_set(zi, c->csets[k].im); found = 1; }
        if (!found)
            r = rs_req_error(run, q, q->text, RS_ERR_INPUT,
                             "expected %s set to a number (set NAME = VALUE or --set): stability decides one point", name);
    }
    if (r == RS_OK) {
        rs_qdc_struct *nd = rs_qdc_vec_init(2);   /* N(z), D(z) */
        rs_qd_t n2, d2, diff, ratio;
        int sg, sc;
        const char *status;
        json_t *o = json_object(), *sub = json_object();
        rs_qd_init(n2); rs_qd_init(d2); rs_qd_init(diff); rs_qd_init(ratio);
        rs_qdpoly_evaluate_cx(nd, R.N, zr, zi, R.d);
        rs_qdpoly_evaluate_cx(nd + 1, R.D, zr, zi, R.d);
        rs_qdc_abs2(n2, nd, R.d);
        rs_qdc_abs2(d2, nd + 1, R.d);
        rs_qd_sub(diff, d2, n2);
        sg = rs_qd_is_zero(d2) ? 2 : rs_qd_sgn(diff, R.d);
        sc = rs_qd_onestep_stable_at(R.N, R.D, R.d, zr, zi);
        /* the exact modulus against Schur-Cohn and the Arb root */
        if (sc == -2 || (sg == 2) != (sc == -1) || (sg != 2 && (sg > 0) != (sc == 1))) {
            json_decref(o);
            json_decref(sub);
            r = rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT,
                             "stability over Q(sqrt d): |R|^2 in Q(sqrt d), Schur-Cohn over Q(sqrt d)(i) and the "
                             "certified root disagree%s", "");
        } else {
            status = sg == 2 ? "singular" : sg > 0 ? "stable" : sg == 0 ? "marginal" : "unstable";
            json_object_set_new(o, "analysis", json_string("stability"));
            json_object_set_new(o, "status", json_string(status));
            if (sg != 2) {
                rs_qd_inv(ratio, d2, R.d);
                rs_qd_mul(ratio, ratio, n2, R.d);
                json_object_set_new(o, "abs_R_squared", json_str_free(rs_qd_get_str(ratio, R.d)));
            }
            json_object_set_new(o, "poly", json_str_free(p_str(&R, c->params[R.par].name)));
            qd_common(o, &R, run);
            json_object_set_new(o, "evidence",
                                json_pack("[s,s,s]", "|D(z)|^2 - |N(z)|^2 exactly in Q(sqrt d)",
                                          "Schur-Cohn over Q(sqrt d)(i) on D(z) lambda - N(z)",
                                          "certified root (Arb)"));
            {
                char *vs;
                if (fmpq_is_zero(zi)) {
                    json_object_set_new(sub, c->params[R.par].name, rs_json_fmpq(zr));
                } else {
                    vs = rs_complex_str(zr, zi);
                    json_object_set_new(sub, c->params[R.par].name, json_string(vs));
                    free(vs);
                }
            }
            json_object_set_new(o, "substituted", sub);
            json_object_set_new(o, "decided_by", json_string("exact"));
            json_array_append_new(run->results, o);
        }
        rs_qdc_vec_clear(nd, 2);
        rs_qd_clear(n2); rs_qd_clear(d2); rs_qd_clear(diff); rs_qd_clear(ratio);
    }
    fmpq_clear(zr);
    fmpq_clear(zi);
    qd_r_clear(&R);
    return r;
}

static json_t *end_json(const rs_qd_end_struct *e)
{
    if (e->inf) return json_string(e->inf < 0 ? "-inf" : "inf");
    if (fmpz_poly_degree(e->minpoly) == 1) {
        if (fmpz_is_one(fmpq_denref(e->q)) && fmpz_fits_si(fmpq_numref(e->q)))
            return json_integer(fmpz_get_si(fmpq_numref(e->q)));
        return rs_json_fmpq(e->q);
    }
    return json_str_free(rs_qd_end_get_str(e));
}

static json_t *iv_detail(const rs_qd_iv_struct *iv)
{
    /* finite ends are closed: |R| = 1 there (rs_qd_onestep_interval) */
    return json_pack("{s:b,s:b,s:b}", "lo_closed", iv->lo->inf == 0, "hi_closed", iv->hi->inf == 0,
                     "ends_decided", 1);
}

int rs_an_qd_astability(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_case_struct *c = run->c;
    qd_r_t R;
    rs_qd_astab_t a;
    rs_qd_iv_t riv, iiv;
    int r, rr = 0, ri = 0;
    slong k;
    qd_r_init(&R);
    rs_qd_astab_init(a);
    rs_qd_iv_init(riv);
    rs_qd_iv_init(iiv);
    r = qd_r_get(&R, run, q);
    if (r == RS_OK && req->u.astab.param != R.par)
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "expected astability %s (z = H*F is a multiple of it)",
                         c->params[R.par].name);
    for (k = 0; r == RS_OK && k < c->nsets + c->ncsets; k++)
        if (strcmp(k < c->nsets ? c->sets[k].name : c->csets[k - c->nsets].name, c->params[R.par].name) == 0)
            r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "expected %s not set: astability treats it as z",
                             c->params[R.par].name);
    if (r == RS_OK) {
        rs_qd_astab_decide(a, R.N, R.D, R.d);
        rr = rs_qd_onestep_interval(riv, R.N, R.D, R.d, 0);
        ri = rs_qd_onestep_interval(iiv, R.N, R.D, R.d, 1);
        /* E >= 0 with the poles right iff |R(iy)| <= 1 on the whole imaginary
         * axis; A-stable: (-inf, 0] inside the real interval and z = -1 stable */
        if (rr != 0 || ri != 0
            || (a->poles_right && a->e_nonneg != (iiv->lo->inf < 0 && iiv->hi->inf > 0))
            || (a->a_stable && riv->lo->inf != -1))
            r = RS_ERR_INCONSISTENT;
        if (r == RS_OK && a->a_stable) {
            fmpq_t m1, z0;
            fmpq_init(m1);
            fmpq_init(z0);
            fmpq_set_si(m1, -1, 1);
            if (rs_qd_onestep_stable_at(R.N, R.D, R.d, m1, z0) != 1) r = RS_ERR_INCONSISTENT;
            fmpq_clear(m1);
            fmpq_clear(z0);
        }
        if (r != RS_OK)
            r = rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT,
                             "astability over Q(sqrt d): the E-polynomial and the stability intervals disagree%s", "");
    }
    if (r == RS_OK) {
        const char *name = c->params[R.par].name;
        json_t *o = json_object();
        char *ps = p_str(&R, name), *loc;
        json_object_set_new(o, "analysis", json_string("astability"));
        json_object_set_new(o, "param", json_string(name));
        json_object_set_new(o, "real_interval", json_pack("[o,o]", end_json(riv->lo), end_json(riv->hi)));
        json_object_set_new(o, "imag_interval", json_pack("[o,o]", end_json(iiv->lo), end_json(iiv->hi)));
        json_object_set_new(o, "real_interval_detail", iv_detail(riv));
        json_object_set_new(o, "imag_interval_detail", iv_detail(iiv));
        loc = flint_malloc(strlen(ps) + strlen(name) + 64);
        sprintf(loc, "p(lambda, %s) = 0 with lambda = exp(i*phi), p = %s", name, ps);
        json_object_set_new(o, "boundary_locus", json_str_free(loc));
        json_object_set_new(o, "a_stable", json_boolean(a->a_stable));
        /* A(alpha) is computed for p linear in z only; A-stable is A(90) */
        json_object_set_new(o, "alpha_degrees", a->a_stable ? json_integer(90) : json_null());
        json_object_set_new(o, "alpha_degrees_approx", a->a_stable ? json_real(90.0) : json_null());
        if (!a->a_stable)
            json_object_set_new(o, "note", json_string("alpha of A(alpha) is not computed over Q(sqrt d)"));
        {
            json_t *e = json_pack("{s:s,s:o,s:b,s:b}", "route", "E-polynomial (one-step method) over Q(sqrt d)",
                                  "E", json_str_free(rs_qdpoly_get_str(a->E, R.d, "y")), "E_nonnegative",
                                  a->e_nonneg, "poles_in_right_half_plane", a->poles_right);
            if (!a->e_nonneg) json_object_set_new(e, "E_negative_at", rs_json_fmpq(a->witness));
            json_object_set_new(o, "evidence", json_pack("[o]", e));
        }
        if (a->r_inf_finite) {
            rs_qd_t ab;
            rs_qd_init(ab);
            rs_qd_set(ab, a->r_inf);
            if (rs_qd_sgn(ab, R.d) < 0) { fmpq_neg(ab->x, ab->x); fmpq_neg(ab->y, ab->y); }
            if (fmpq_is_zero(ab->y) && fmpz_is_one(fmpq_denref(ab->x)) && fmpz_fits_si(fmpq_numref(ab->x)))
                json_object_set_new(o, "limit_at_infinity", json_integer(fmpz_get_si(fmpq_numref(ab->x))));
            else
                json_object_set_new(o, "limit_at_infinity", json_str_free(rs_qd_get_str(ab, R.d)));
            rs_qd_clear(ab);
        } else {
            json_object_set_new(o, "limit_at_infinity", json_string("inf"));
        }
        json_object_set_new(o, "l_stable", json_boolean(a->l_stable));
        qd_common(o, &R, run);
        json_object_set_new(o, "substituted", json_object());
        json_object_set_new(o, "decided_by", json_string("exact"));
        json_array_append_new(run->results, o);
        flint_free(ps);
    }
    rs_qd_iv_clear(riv);
    rs_qd_iv_clear(iiv);
    rs_qd_astab_clear(a);
    qd_r_clear(&R);
    return r;
}
