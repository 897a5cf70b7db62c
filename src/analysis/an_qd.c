/* an_qd.c -- issue 15: the analyses of a model with coefficients in
 * Q(sqrt d) (rk sdirk2: gamma = 1 - sqrt(2)/2; model.h's qd).  The lowering
 * writes the true stage equations with sqrt(d) exact; the scheme evaluates
 * sqrt(d) as a variable reduced by sqrt(d)^2 = d, so the characteristic
 * polynomial is p = p0 + sqrt(d) p1 with p0, p1 in Z[params][lambda]
 * (lower/scheme.c, algebra/charpoly.c), whatever the coupling.  Then
 *  - charpoly: p0 + sqrt(d) p1, each lambda-coefficient written over Q(sqrt d);
 *  - stability at set (real or complex) values: p(lambda) over Q(sqrt d)(i),
 *    Schur-Cohn (exact signs in Q(sqrt d)) and the certified Arb roots must
 *    agree (exit 3); radius: the certified balls of the roots;
 *  - the test equation (one subsystem, one state y' = F): p = D lambda - N
 *    with R = N/D read from p is checked against the tableau's stability
 *    function (methods.c) composed with z = k*NAME (exit 3 when they differ);
 *    stability then also decides |D|^2 - |N|^2 in Q(sqrt d), astability runs
 *    the E-polynomial and the stability intervals (rs_qd_astab_decide,
 *    rs_qd_onestep_interval), checked against each other.
 *  - modes and simulate at set values (an_modes.c, an_simulate.c): the
 *    certified roots of p and the exact verdict from here
 *    (rs_an_qd_modes_roots, rs_an_qd_point).
 * Every other analysis is refused at its line (rs_an_qd_check). */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpq_vec.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include <acb.h>
#include "algebra/qsqrt.h"
#include "util/polyfmt.h"

static json_t *json_str_free(char *s)
{
    json_t *j = json_string(s);
    flint_free(s);
    return j;
}

char *rs_an_qd_over_str(slong d)
{
    char *s = flint_malloc(40);
    snprintf(s, 40, "Q(sqrt %ld)", (long) d);
    return s;
}

/* every complex set value is of the region's own parameters (and no `at`
 * gives another one) */
static int qd_csets_only(const rs_run_t *run, const rs_an_req_t *req)
{
    slong j;
    for (j = 0; j < run->c->ncsets; j++) {
        slong k = rs_case_param_index(run->c, run->c->csets[j].name);
        if (k != req->u.region.param && !(req->u.region.twod && k == req->u.region.param2)) return 0;
    }
    return 1;
}

/* the parameters with neither a real nor a complex set value */
static slong qd_nfree(const rs_run_t *run)
{
    slong k, j, n = 0;
    for (k = 0; k < run->c->nparams; k++) {
        int set = 0;
        for (j = 0; j < run->c->nsets; j++) set |= strcmp(run->c->sets[j].name, run->c->params[k].name) == 0;
        for (j = 0; j < run->c->ncsets; j++) set |= strcmp(run->c->csets[j].name, run->c->params[k].name) == 0;
        n += !set;
    }
    return n;
}

int rs_an_qd_check(rs_run_t *run, const rs_an_req_t *req)
{
    const char *n = req->def->name;
    if (run->m->qd == NULL) return RS_OK;
    if (strcmp(n, "charpoly") == 0 || strcmp(n, "stability") == 0 || strcmp(n, "astability") == 0
        || strcmp(n, "radius") == 0 || strcmp(n, "modes") == 0 || strcmp(n, "simulate") == 0)
        return RS_OK;
    /* the conditions over Q(sqrt d)[params] (an_qd_conds.c): real parameters */
    if ((strcmp(n, "jury") == 0 || strcmp(n, "hurwitz") == 0 || strcmp(n, "routh") == 0 || strcmp(n, "region") == 0
         || strcmp(n, "claim") == 0) && run->c->ncsets == 0)
        return RS_OK;
    /* at complex set values: the conditions over Q(sqrt d)(i)[params] (an_qd_complex.c) */
    if (strcmp(n, "jury") == 0 || strcmp(n, "hurwitz") == 0 || strcmp(n, "routh") == 0) return RS_OK;
    /* a region's own parameters keep no set value: a complex one there is
     * unused (decided once the request is parsed: rest set) */
    if (strcmp(n, "region") == 0 && (req->rest == NULL || (!req->u.region.forall && qd_csets_only(run, req))))
        return RS_OK;
    /* one real parameter's cells over Q(sqrt d)(i) (an_qd_complex.c's rs_an_qd_cx_fiber) */
    if (strcmp(n, "region") == 0 && !req->u.region.forall && !req->u.region.twod) return RS_OK;
    /* two real parameters' plane over Q(sqrt d)(i) (an_qd_cx2.c) */
    if (strcmp(n, "region") == 0 && !req->u.region.forall) return RS_OK;
    if (strcmp(n, "claim") == 0 && qd_nfree(run) <= 1) return RS_OK;
    /* the z-plane of one parameter, each point over Q(sqrt d)(i) (an_qd_map.c) */
    if ((strcmp(n, "bilinear") == 0 || strcmp(n, "sweep") == 0) && run->c->ncsets == 0) return RS_OK;   /* an_qd_map.c */
    /* the z-plane of one parameter, or two real parameters: each point over Q(sqrt d) (an_qd_map.c) */
    if (strcmp(n, "map") == 0 && run->c->ncsets == 0) return RS_OK;
    if (strcmp(n, "limit") == 0 && run->c->ncsets == 0) return RS_OK;   /* an_limit.c's qd_limit */
    {
        /* the message names the model's field and tableau */
        char msg[600];
        if (strcmp(n, "region") == 0 || strcmp(n, "claim") == 0)
            snprintf(msg, sizeof msg, "expected real set values: %s over Q(sqrt %ld) does not run at a complex set value "
                     "with two free parameters or for all (its cells would need Q(sqrt %ld)(i) in two parameters; "
                     "stability, radius, modes, simulate, jury, hurwitz and routh do, the last three with the "
                     "conditions over Q(sqrt %ld)(i)[params]; region NAME and claim do with one free real parameter, "
                     "region N1, N2 with two, region also when only its own parameters have complex values)", n,
                     (long) run->m->qd->d, (long) run->m->qd->d, (long) run->m->qd->d);
        else if (strcmp(n, "map") == 0 || strcmp(n, "sweep") == 0 || strcmp(n, "bilinear") == 0
                 || strcmp(n, "limit") == 0)
            snprintf(msg, sizeof msg, "expected real set values: %s over Q(sqrt %ld) (rk %s) runs without complex "
                     "set values only (it would need Q(sqrt %ld)(i) with the complex value substituted); at "
                     "complex set values stability, radius, modes, simulate, jury, hurwitz, routh, region NAME, "
                     "region N1, N2 and claim run", n, (long) run->m->qd->d, run->m->qd->tableau, (long) run->m->qd->d);
        else
            snprintf(msg, sizeof msg, "expected charpoly, stability, radius, astability, modes, simulate, jury, "
                     "hurwitz, routh, region, claim, bilinear, limit, sweep (of stability or radius) or map: %s is "
                     "not available for rk %s (its coefficients are in Q(sqrt %ld); expect is not done over "
                     "Q(sqrt %ld))", n, run->m->qd->tableau, (long) run->m->qd->d, (long) run->m->qd->d);
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
    }
}

/* p = p0 + sqrt(d) p1 of the scheme, p0 and p1 in the scheme's zctx
 * without sqrt(d) */
typedef struct {
    fmpz_mpoly_t p0, p1;
    slong degree;
    slong zeros;      /* the roots at 0 the charpoly divided out (lambda^k) */
} qd_cp_t;

static int qd_cp_get(qd_cp_t *P, rs_run_t *run, const rs_request_t *q)
{
    const rs_scheme_struct *s = run->sym;
    rs_charpoly_t cp;
    int r;
    fmpz_mpoly_init(P->p0, s->zctx);
    fmpz_mpoly_init(P->p1, s->zctx);
    P->degree = 0;
    P->zeros = 0;
    if (!run->have_sym || s->sqrt_d <= 0)
        return rs_req_error(run, q, q->text, RS_ERR_INTERNAL, "no scheme over Q(sqrt d) for %s", run->m->qd->tableau);
    rs_charpoly_init(cp, s);
    r = rs_charpoly_compute(cp, s, run->err);
    if (r != RS_OK) r = rs_req_relocate(run, q, r, "charpoly");
    if (r == RS_OK) {
        rs_charpoly_coeff(P->p0, cp->p, 0, s->sqrt_var, s->zctx);
        rs_charpoly_coeff(P->p1, cp->p, 1, s->sqrt_var, s->zctx);
        P->degree = cp->degree;
        P->zeros = cp->removed_lambda_power;
    }
    rs_charpoly_clear(cp, s);
    return r;
}

static void qd_cp_clear(qd_cp_t *P, const rs_scheme_struct *s)
{
    fmpz_mpoly_clear(P->p0, s->zctx);
    fmpz_mpoly_clear(P->p1, s->zctx);
}

/* the coefficient of lambda^k of P as a polynomial in the one parameter
 * par over Q(sqrt d); 0 when another parameter appears */
static int qd_cp_coeff_uni(rs_qdpoly_t out, const qd_cp_t *P, slong k, slong par, const rs_scheme_struct *s)
{
    fmpz_mpoly_t c;
    ulong *ex = flint_malloc(s->nvars * sizeof(ulong));
    fmpq_t v;
    slong h, i, j;
    int ok = 1;
    fmpz_mpoly_init(c, s->zctx);
    fmpq_init(v);
    fmpq_poly_zero(out->p0);
    fmpq_poly_zero(out->p1);
    for (h = 0; h < 2; h++) {
        rs_charpoly_coeff(c, h ? P->p1 : P->p0, k, s->lambda_var, s->zctx);
        for (i = 0; i < fmpz_mpoly_length(c, s->zctx); i++) {
            fmpz_mpoly_get_term_exp_ui(ex, c, i, s->zctx);
            for (j = 0; j < s->nvars; j++)
                if (j != par && j != s->lambda_var && ex[j] != 0) ok = 0;
            fmpz_mpoly_get_term_coeff_fmpz(fmpq_numref(v), c, i, s->zctx);
            fmpz_one(fmpq_denref(v));
            fmpq_poly_set_coeff_fmpq(h ? out->p1 : out->p0, par >= 0 ? (slong) ex[par] : 0, v);
        }
    }
    fmpz_mpoly_clear(c, s->zctx);
    fmpq_clear(v);
    flint_free(ex);
    return ok;
}

/* the only parameter p depends on, -1 for none, -2 for several */
static slong qd_cp_param(const qd_cp_t *P, const rs_scheme_struct *s)
{
    slong j, par = -1;
    for (j = 0; j < s->lambda_var; j++)
        if (fmpz_mpoly_degree_si(P->p0, j, s->zctx) > 0 || fmpz_mpoly_degree_si(P->p1, j, s->zctx) > 0)
            par = par == -1 ? j : -2;
    return par;
}

/* Dahlquist's test equation: the case's only subsystem, one state y' = F,
 * nothing else (then p = D lambda - N with R = N/D) */
int rs_an_qd_test_equation(const rs_case_struct *c)
{
    return c->nsubs == 1 && c->subs[0].nstates == 1 && c->subs[0].ndeqs == 1 && c->subs[0].deqs[0].order == 1
           && c->neqs == 0 && c->charexpr == NULL && c->nrec == 0;
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

/* R = N/D read from p = a1 lambda + a0 of the test equation (D = a1/a1(0),
 * N = -a0/a1(0): D(0) = 1 as the tableau's), z = k t with k from N's
 * linear coefficient; then the tableau's R composed with z = k t must be
 * the same (two derivations: the stage equations' determinant and
 * methods.c's R = 1 + z b^T (I - zA)^-1 1; exit 3 when they differ) */
static int qd_r_get(qd_r_t *R, rs_run_t *run, const rs_request_t *q)
{
    const rs_scheme_struct *s = run->sym;
    const rs_model_qd_struct *qd = run->m->qd;
    qd_cp_t P;
    rs_qdpoly_t A1, A0, Nt, Dt;
    rs_qd_t c0, inv, t1, n1;
    fmpq_poly_t nn, nd, g;
    slong par = -1, k;
    int r;
    r = qd_cp_get(&P, run, q);
    rs_qdpoly_init(A1); rs_qdpoly_init(A0); rs_qdpoly_init(Nt); rs_qdpoly_init(Dt);
    rs_qd_init(c0); rs_qd_init(inv); rs_qd_init(t1); rs_qd_init(n1);
    if (r == RS_OK) {
        par = qd_cp_param(&P, s);
        if (!rs_an_qd_test_equation(run->c) || P.degree != 1 || par < 0 || !qd_cp_coeff_uni(A1, &P, 1, par, s)
            || !qd_cp_coeff_uni(A0, &P, 0, par, s))
            r = rs_req_error(run, q, q->text, RS_ERR_INPUT,
                             "expected y' = F*y with H*F = k*NAME for one parameter NAME (rk %s is analysed on "
                             "Dahlquist's test equation only)", qd->tableau);
    }
    if (r == RS_OK) {
        R->par = rs_case_param_index(run->c, s->vars[par]);
        R->d = qd->d;
        rs_qdpoly_get_coeff(c0, A1, 0);
        if (rs_qd_is_zero(c0)) r = RS_ERR_INCONSISTENT;
    }
    if (r == RS_OK) {
        rs_qd_inv(inv, c0, R->d);
        for (k = 0; k <= rs_qdpoly_degree(A1) || k <= rs_qdpoly_degree(A0); k++) {
            rs_qdpoly_get_coeff(t1, A1, k);
            rs_qd_mul(t1, t1, inv, R->d);
            rs_qdpoly_set_coeff(R->D, k, t1);
            rs_qdpoly_get_coeff(t1, A0, k);
            rs_qd_mul(t1, t1, inv, R->d);
            fmpq_neg(t1->x, t1->x);
            fmpq_neg(t1->y, t1->y);
            rs_qdpoly_set_coeff(R->N, k, t1);
        }
        /* k = N'(0)/N_tab'(0), rational */
        fmpq_poly_get_coeff_fmpq(n1->x, qd->n0, 1);
        fmpq_poly_get_coeff_fmpq(n1->y, qd->n1, 1);
        rs_qdpoly_get_coeff(t1, R->N, 1);
        if (rs_qd_is_zero(n1) || rs_qd_is_zero(t1)) r = RS_ERR_INCONSISTENT;
    }
    if (r == RS_OK) {
        rs_qd_inv(inv, n1, R->d);
        rs_qd_mul(t1, t1, inv, R->d);
        if (!fmpq_is_zero(t1->y)) r = RS_ERR_INCONSISTENT;
        fmpq_set(R->k, t1->x);
    }
    if (r == RS_OK) {
        fmpq_poly_rescale(Nt->p0, qd->n0, R->k);
        fmpq_poly_rescale(Nt->p1, qd->n1, R->k);
        fmpq_poly_rescale(Dt->p0, qd->d0, R->k);
        fmpq_poly_rescale(Dt->p1, qd->d1, R->k);
        if (!rs_qdpoly_equal(Nt, R->N) || !rs_qdpoly_equal(Dt, R->D)) r = RS_ERR_INCONSISTENT;
    }
    if (r == RS_ERR_INCONSISTENT)
        r = rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT,
                         "%s: R = N/D read from the stage equations' characteristic polynomial differs from the "
                         "tableau's stability function (internal inconsistency)", qd->tableau);
    if (r == RS_OK) {
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
    }
    rs_qdpoly_clear(A1); rs_qdpoly_clear(A0); rs_qdpoly_clear(Nt); rs_qdpoly_clear(Dt);
    rs_qd_clear(c0); rs_qd_clear(inv); rs_qd_clear(t1); rs_qd_clear(n1);
    qd_cp_clear(&P, s);
    return r;
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
    json_object_set_new(o, "over", json_str_free(rs_an_qd_over_str(R->d)));
    json_object_set_new(o, "z", json_string(z));
    snprintf(ks, sizeof ks, "rk %s", run->m->qd->tableau);
    json_object_set_new(o, "method", json_string(ks));
    json_object_set_new(o, "stability_function",
                        json_pack("{s:o,s:o}", "N", json_str_free(rs_qdpoly_get_str(R->N, R->d, name)),
                                  "D", json_str_free(rs_qdpoly_get_str(R->D, R->d, name))));
    flint_free(kq);
    flint_free(z);
}

/* ---- any scheme over Q(sqrt d): p = p0 + sqrt(d) p1 ---- */

char *rs_an_qd_mpoly_str(const fmpz_mpoly_t a0, const fmpz_mpoly_t a1, const rs_scheme_struct *s, int spaced)
{
    char *x, *y, *out;
    size_t len;
    if (spaced) {   /* as the rational conditions print (polyfmt.c) */
        char *u = rs_polyfmt_fmpz_mpoly(a0, (const char **) s->vars, s->zctx);
        char *v = rs_polyfmt_fmpz_mpoly(a1, (const char **) s->vars, s->zctx);
        x = flint_malloc(strlen(u) + 1); strcpy(x, u); free(u);
        y = flint_malloc(strlen(v) + 1); strcpy(y, v); free(v);
    } else {
        x = rs_scheme_zpoly_str(a0, s);
        y = rs_scheme_zpoly_str(a1, s);
    }
    len = strlen(x) + strlen(y) + 48;
    out = flint_malloc(len);
    if (fmpz_mpoly_is_zero(a1, s->zctx)) snprintf(out, len, "%s", x);
    else if (fmpz_mpoly_is_zero(a0, s->zctx)) snprintf(out, len, "sqrt(%ld)*(%s)", (long) s->sqrt_d, y);
    else snprintf(out, len, "%s + sqrt(%ld)*(%s)", x, (long) s->sqrt_d, y);
    flint_free(x);
    flint_free(y);
    return out;
}

/* the set value of parameter k (complex: im), 0 when it has none */
static int param_value(fmpq_t re, fmpq_t im, const rs_case_struct *c, slong k)
{
    slong j;
    const char *name = c->params[k].name;
    fmpq_zero(re);
    fmpq_zero(im);
    for (j = 0; j < c->nsets; j++)
        if (strcmp(c->sets[j].name, name) == 0) { fmpq_set(re, c->sets[j].value); return 1; }
    for (j = 0; j < c->ncsets; j++)
        if (strcmp(c->csets[j].name, name) == 0) { fmpq_set(re, c->csets[j].re); fmpq_set(im, c->csets[j].im); return 1; }
    return 0;
}

/* parameter k has a complex set value */
static int qd_is_cset(const rs_run_t *run, slong k)
{
    slong j;
    for (j = 0; j < run->c->ncsets; j++)
        if (strcmp(run->c->csets[j].name, run->c->params[k].name) == 0) return 1;
    return 0;
}

/* a (no lambda, no sqrt(d)) at the set values: the real ones here, the
 * complex ones by rs_cx_add_term (complex_poly.c) */
static void cx_eval(fmpq_t re, fmpq_t im, const fmpz_mpoly_t a, const fmpq *vr, const rs_run_t *run,
                    const rs_scheme_struct *s)
{
    slong *ex = flint_malloc(s->nvars * sizeof(slong)), i, j;
    fmpq_mpoly_t qr, qi;
    fmpq_t c, t;
    fmpq_mpoly_init(qr, s->ctx);
    fmpq_mpoly_init(qi, s->ctx);
    fmpq_init(c);
    fmpq_init(t);
    for (i = 0; i < fmpz_mpoly_length(a, s->zctx); i++) {
        fmpz_mpoly_get_term_coeff_fmpz(fmpq_numref(c), a, i, s->zctx);
        fmpz_one(fmpq_denref(c));
        fmpz_mpoly_get_term_exp_si(ex, a, i, s->zctx);
        for (j = 0; j < s->lambda_var; j++)
            if (ex[j] > 0 && !qd_is_cset(run, j)) {
                fmpq_pow_si(t, vr + j, ex[j]);
                fmpq_mul(c, c, t);
                ex[j] = 0;
            }
        rs_cx_add_term(qr, qi, c, 0, ex, run, s);
    }
    fmpq_mpoly_sort_terms(qr, s->ctx); fmpq_mpoly_combine_like_terms(qr, s->ctx);
    fmpq_mpoly_sort_terms(qi, s->ctx); fmpq_mpoly_combine_like_terms(qi, s->ctx);
    fmpq_mpoly_get_fmpq(re, qr, s->ctx);   /* constants: every parameter of p is set */
    fmpq_mpoly_get_fmpq(im, qi, s->ctx);
    fmpq_mpoly_clear(qr, s->ctx);
    fmpq_mpoly_clear(qi, s->ctx);
    fmpq_clear(c);
    fmpq_clear(t);
    flint_free(ex);
}

/* p at the set values: c[0..*n] over Q(sqrt d)(i), c[*n] != 0 (*n = -1:
 * p vanishes there); an input error when a parameter of p has no value */
static int qd_cp_at(rs_qdc_struct **c, slong *n, const qd_cp_t *P, rs_run_t *run, const rs_request_t *q)
{
    const rs_scheme_struct *s = run->sym;
    const rs_case_struct *cs = run->c;
    fmpq *vr = _fmpq_vec_init(s->nvars), *vi = _fmpq_vec_init(s->nvars);   /* vi: only whether set */
    fmpz_mpoly_t a;
    slong k, h;
    int r = RS_OK;
    *c = NULL;
    *n = -1;
    for (k = 0; k < s->lambda_var && r == RS_OK; k++)
        if (!param_value(vr + k, vi + k, cs, k)
            && (fmpz_mpoly_degree_si(P->p0, k, s->zctx) > 0 || fmpz_mpoly_degree_si(P->p1, k, s->zctx) > 0))
        {
            char msg[300];
            snprintf(msg, sizeof msg, "expected %s set to a number (set NAME = VALUE or --set): over Q(sqrt %ld) this "
                     "analysis decides one point", cs->params[k].name, (long) s->sqrt_d);
            r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
        }
    if (r == RS_OK) {
        fmpz_mpoly_init(a, s->zctx);
        *c = rs_qdc_vec_init(P->degree + 1);
        for (k = 0; k <= P->degree; k++)
            for (h = 0; h < 2; h++) {
                rs_charpoly_coeff(a, h ? P->p1 : P->p0, k, s->lambda_var, s->zctx);
                cx_eval(h ? (*c)[k].re->y : (*c)[k].re->x, h ? (*c)[k].im->y : (*c)[k].im->x, a, vr, run, s);
            }
        for (*n = P->degree; *n >= 0 && rs_qd_is_zero((*c)[*n].re) && rs_qd_is_zero((*c)[*n].im); (*n)--) ;
        fmpz_mpoly_clear(a, s->zctx);
    }
    _fmpq_vec_clear(vr, s->nvars);
    _fmpq_vec_clear(vi, s->nvars);
    return r;
}

/* the substituted p: "(c0) + (c1)*lambda + ..." with ck = x + y*sqrt(d) [+ i*(...)] */
static char *qdc_poly_str(const rs_qdc_struct *c, slong n, slong d)
{
    char *out = flint_malloc(1), *re, *im, *t;
    slong k;
    out[0] = '\0';
    for (k = 0; k <= n; k++) {
        size_t len;
        if (rs_qd_is_zero(c[k].re) && rs_qd_is_zero(c[k].im)) continue;
        re = rs_qd_get_str(c[k].re, d);
        im = rs_qd_get_str(c[k].im, d);
        len = strlen(out) + strlen(re) + strlen(im) + 64;
        t = flint_malloc(len);
        if (rs_qd_is_zero(c[k].im)) snprintf(t, len, "%s%s(%s)", out, out[0] ? " + " : "", re);
        else snprintf(t, len, "%s%s(%s + i*(%s))", out, out[0] ? " + " : "", re, im);
        if (k > 0) {
            size_t l2 = strlen(t) + 32;
            t = flint_realloc(t, l2);
            if (k == 1) strcat(t, "*lambda");
            else snprintf(t + strlen(t), 32, "*lambda^%ld", (long) k);
        }
        flint_free(out);
        flint_free(re);
        flint_free(im);
        out = t;
    }
    return out;
}

/* the set values of p's parameters as JSON */
static json_t *qd_substituted(const qd_cp_t *P, rs_run_t *run)
{
    const rs_scheme_struct *s = run->sym;
    json_t *sub = json_object();
    fmpq_t re, im;
    slong k;
    fmpq_init(re);
    fmpq_init(im);
    for (k = 0; k < s->lambda_var; k++) {
        if (!param_value(re, im, run->c, k)) continue;
        if (fmpz_mpoly_degree_si(P->p0, k, s->zctx) <= 0 && fmpz_mpoly_degree_si(P->p1, k, s->zctx) <= 0) continue;
        if (fmpq_is_zero(im)) json_object_set_new(sub, run->c->params[k].name, rs_json_fmpq(re));
        else {
            char *v = rs_complex_str(re, im);
            json_object_set_new(sub, run->c->params[k].name, json_string(v));
            free(v);
        }
    }
    fmpq_clear(re);
    fmpq_clear(im);
    return sub;
}

void rs_an_qd_json_p(json_t *o, const fmpz_mpoly_t p0, const fmpz_mpoly_t p1, rs_run_t *run)
{
    char m[80];
    snprintf(m, sizeof m, "rk %s", run->m->qd->tableau);
    json_object_set_new(o, "over", json_str_free(rs_an_qd_over_str(run->sym->sqrt_d)));
    /* jury and hurwitz name their test in "method", the method in "rk" */
    json_object_set_new(o, json_object_get(o, "method") == NULL ? "method" : "rk", json_string(m));
    json_object_set_new(o, "p0", json_str_free(rs_scheme_zpoly_str(p0, run->sym)));
    json_object_set_new(o, "p1", json_str_free(rs_scheme_zpoly_str(p1, run->sym)));
}

static void qd_generic_common(json_t *o, const qd_cp_t *P, rs_run_t *run)
{
    rs_an_qd_json_p(o, P->p0, P->p1, run);
}

static int qd_generic_charpoly(rs_run_t *run, const rs_an_req_t *req, const qd_cp_t *P)
{
    const rs_scheme_struct *s = run->sym;
    json_t *o = json_object(), *co = json_array();
    fmpz_mpoly_t a0, a1;
    slong k;
    fmpz_mpoly_init(a0, s->zctx);
    fmpz_mpoly_init(a1, s->zctx);
    (void) req;
    for (k = 0; k <= P->degree; k++) {
        rs_charpoly_coeff(a0, P->p0, k, s->lambda_var, s->zctx);
        rs_charpoly_coeff(a1, P->p1, k, s->lambda_var, s->zctx);
        json_array_append_new(co, json_str_free(rs_an_qd_mpoly_str(a0, a1, s, 0)));
    }
    json_object_set_new(o, "analysis", json_string("charpoly"));
    json_object_set_new(o, "var", json_string("lambda"));
    json_object_set_new(o, "degree", json_integer(P->degree));
    json_object_set_new(o, "coeffs", co);
    json_object_set_new(o, "poly", json_str_free(rs_an_qd_mpoly_str(P->p0, P->p1, s, 0)));
    qd_generic_common(o, P, run);
    json_object_set_new(o, "substituted", json_object());
    json_object_set_new(o, "decided_by", json_string("exact"));
    json_array_append_new(run->results, o);
    fmpz_mpoly_clear(a0, s->zctx);
    fmpz_mpoly_clear(a1, s->zctx);
    return RS_OK;
}

/* the root counts of lambda^z0 p, p = c[0..n], as the rational path prints
 * them (z0 the power the charpoly divided out): the roots at 0 from z0 and
 * the trailing zero coefficients, counted inside; the others by the
 * counting Schur-Cohn recursion over Q(sqrt d)(i) (exact; none on the
 * circle when it is regular), cross-checked with the certified roots
 * (RS_ERR_INCONSISTENT when both decide and differ).  No counts when the
 * recursion meets a zero |c_n|^2 - |c_0|^2. */
static int qd_counts(json_t *o, const rs_qdc_struct *c, slong n, slong z0, slong d)
{
    slong z = 0, in, below, above;
    int cert;
    while (z < n && rs_qd_is_zero(c[z].re) && rs_qd_is_zero(c[z].im)) z++;
    if (!rs_qdc_schur_count(&in, c + z, n - z, d)) return RS_OK;
    cert = rs_qdc_roots_count(&below, &above, c + z, n - z, d);
    if (cert && below != in) return RS_ERR_INCONSISTENT;
    json_object_set_new(o, "inside", json_integer(in + z + z0));
    if (z + z0 > 0) json_object_set_new(o, "at_zero", json_integer(z + z0));
    json_object_set_new(o, "on", json_integer(0));
    json_object_set_new(o, "outside", json_integer(n - z - in));
    json_object_set_new(o, "counts_certified_roots", json_string(cert ? "agree" : "not separated from the circle"));
    return RS_OK;
}

/* stability at the set values: Schur-Cohn over Q(sqrt d)(i) with exact
 * signs and the certified Arb roots; they must agree (exit 3) */
static int qd_generic_stability(rs_run_t *run, const rs_an_req_t *req, const qd_cp_t *P)
{
    const rs_request_t *q = req->q;
    rs_qdc_struct *c;
    slong n, d = run->sym->sqrt_d;
    int r = qd_cp_at(&c, &n, P, run, q), sc = -1, ar = -1;
    const char *status;
    json_t *o;
    if (r != RS_OK) return r;
    if (n >= 1) {
        sc = rs_qdc_stable_checked(&ar, c, n, d);
        if (sc == -2) {
            rs_qdc_vec_clear(c, P->degree + 1);
            return rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT,
                                "stability over Q(sqrt d): Schur-Cohn over Q(sqrt d)(i) and the certified roots "
                                "disagree%s", "");
        }
    }
    /* n < 1: p is constant there (the new step is not determined): singular */
    status = n < 1 ? "singular" : sc == 1 ? "stable" : sc == 0 ? "unstable" : "undecided";
    o = json_object();
    json_object_set_new(o, "analysis", json_string("stability"));
    json_object_set_new(o, "status", json_string(status));
    if (n >= 1) json_object_set_new(o, "poly", json_str_free(qdc_poly_str(c, n, d)));
    json_object_set_new(o, "degree", json_integer(n < 0 ? 0 : n));
    qd_generic_common(o, P, run);
    if (n >= 1) {
        json_object_set_new(o, "schur_cohn_stable", json_boolean(sc == 1));
        json_object_set_new(o, "roots_certified", json_string(ar == 1 ? "all inside" : ar == 0 ? "one outside"
                                                              : "not separated from the circle"));
        json_object_set_new(o, "evidence", json_pack("[s,s]", "Schur-Cohn over Q(sqrt d)(i), exact signs",
                                                     "certified roots (Arb, sqrt d a ball)"));
    }
    if (n >= 1 && (r = qd_counts(o, c, n, P->zeros, d)) != RS_OK) {
        json_decref(o);
        rs_qdc_vec_clear(c, P->degree + 1);
        return rs_req_error(run, q, q->text, r, "stability over Q(sqrt d): the root counts of Schur-Cohn over "
                            "Q(sqrt d)(i) and of the certified roots disagree%s", "");
    }
    if (strcmp(status, "undecided") == 0)
        json_object_set_new(o, "note", json_string("not strictly stable (Schur-Cohn); a root on or too near the "
                                                   "unit circle: marginal and unstable are not told apart over "
                                                   "Q(sqrt d)"));
    json_object_set_new(o, "substituted", qd_substituted(P, run));
    json_object_set_new(o, "decided_by", json_string("exact"));
    json_array_append_new(run->results, o);
    rs_qdc_vec_clear(c, P->degree + 1);
    return RS_OK;
}

/* z[0..n): the roots of c[0..n] as isolated balls of digits relative
 * digits, the first precision from 3.33 digits + 64 bits doubling up to
 * max_prec that gives them; rr's rho, prec and digits from them; 0 when
 * none does (a repeated root) */
static int qd_roots_cert(rs_radius_t rr, acb_ptr z, const rs_qdc_struct *c, slong n, slong d, slong digits,
                         slong max_prec)
{
    slong prec, k;
    int ok = 0;
    for (prec = 3.33 * digits + 64; prec <= max_prec && !ok; prec *= 2) {
        ok = rs_qdc_roots(z, c, n, d, prec);
        for (k = 0; ok && k < n; k++) ok = acb_rel_accuracy_bits(z + k) >= 3.33 * digits;
        if (ok) {
            rs_radius_set_rho(rr, z, n, prec);
            rr->prec = prec;
            rr->digits = digits;
        }
    }
    return ok;
}

int rs_an_qd_radius(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_optval_t *dg = rs_an_opt(req, "digits");
    slong digits = dg->at != NULL ? dg->num : run->opt->default_digits, n = -1, k, d;
    rs_qdc_struct *c = NULL;
    qd_cp_t P;
    int r = qd_cp_get(&P, run, q), ok = 0, sc = 0;
    d = run->sym->sqrt_d;
    if (r == RS_OK) r = qd_cp_at(&c, &n, &P, run, q);
    if (r == RS_OK && n < 1)
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "radius: p has no root at these values%s", "");
    if (r == RS_OK) {
        rs_radius_t rr;
        acb_ptr z = _acb_vec_init(n);
        rs_radius_init(rr);
        ok = qd_roots_cert(rr, z, c, n, d, digits, run->opt->max_prec);
        if (!ok) {
            r = rs_req_error(run, q, q->text, RS_ERR_LIMIT, "radius over Q(sqrt d): the roots are not isolated up "
                             "to max-prec (a repeated root?)%s", "");
        } else {
            json_t *o = json_object(), *roots = json_array();
            const char *nv = rs_radius_verdict(rr);
            sc = rs_qdc_schur_stable(c, n, d);
            qd_generic_common(o, &P, run);
            json_object_set_new(o, "analysis", json_string("radius"));
            json_object_set_new(o, "method", json_string("the roots of p over Q(sqrt d)(i) as certified isolated "
                                                         "balls (acb_poly_find_roots, validated; sqrt d a ball)"));
            rs_json_radius(o, rr, digits);
            for (k = 0; k < n; k++) {
                json_t *zj = rs_json_acb(z + k, digits);
                arb_t ab;
                arb_init(ab);
                acb_abs(ab, z + k, rr->prec);
                json_object_set_new(zj, "abs", rs_json_arb(ab, digits));
                arb_clear(ab);
                json_array_append_new(roots, zj);
            }
            json_object_set_new(o, "roots", roots);
            json_object_set_new(o, "exact_status", json_string(sc == 1 ? "stable" : "not strictly stable"));
            json_object_set_new(o, "verdict_from_radius", json_string(strcmp(nv, "undecided") != 0 ? nv :
                "undecided numerically (the interval contains 1): the exact side decides"));
            /* certified comparisons only: upper < 1 needs Schur-Cohn stable, lower > 1 needs it not */
            json_object_set_new(o, "consistent", json_boolean(!((strcmp(nv, "stable") == 0 && sc != 1)
                                                                || (strcmp(nv, "unstable") == 0 && sc == 1))));
            if ((strcmp(nv, "stable") == 0 && sc != 1) || (strcmp(nv, "unstable") == 0 && sc == 1)) {
                json_decref(o);
                r = rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT, "radius over Q(sqrt d): the certified "
                                 "radius and Schur-Cohn disagree%s", "");
            } else {
                json_object_set_new(o, "substituted", qd_substituted(&P, run));
                json_object_set_new(o, "decided_by", json_string("numeric"));
                json_array_append_new(run->results, o);
            }
        }
        _acb_vec_clear(z, n);
        rs_radius_clear(rr);
    }
    if (c != NULL) rs_qdc_vec_clear(c, P.degree + 1);
    qd_cp_clear(&P, run->sym);
    return r;
}

/* the test equation's path (R = N/D) when the case is one, else the generic one */
static int qd_onestep(rs_run_t *run, const rs_request_t *q, qd_cp_t *P, int *r)
{
    *r = qd_cp_get(P, run, q);
    return *r == RS_OK && rs_an_qd_test_equation(run->c) && P->degree == 1 && qd_cp_param(P, run->sym) >= 0;
}

int rs_an_qd_charpoly(rs_run_t *run, const rs_an_req_t *req)
{
    qd_r_t R;
    json_t *o;
    int r;
    {
        qd_cp_t P;
        int one = qd_onestep(run, req->q, &P, &r);
        if (r == RS_OK && !one) r = qd_generic_charpoly(run, req, &P);
        qd_cp_clear(&P, run->sym);
        if (r != RS_OK || !one) return r;
    }
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

/* stability with a free parameter: as over Q (stability_real), refused at
 * its line naming the symbolic parameters and what decides them over
 * Q(sqrt d)[params] (Q(sqrt d)(i) at complex set values) */
static int qd_stability_unset(rs_run_t *run, const rs_request_t *q, const qd_cp_t *P)
{
    const rs_scheme_struct *s = run->sym;
    fmpq_t re, im;
    char *fp = NULL, *msg = NULL;
    slong k;
    int r = RS_OK;
    fmpq_init(re); fmpq_init(im);
    for (k = 0; k < s->lambda_var; k++)
        if (!param_value(re, im, run->c, k)
            && (fmpz_mpoly_degree_si(P->p0, k, s->zctx) > 0 || fmpz_mpoly_degree_si(P->p1, k, s->zctx) > 0))
            rs_str_catf(&fp, "%s%s", fp == NULL ? "" : ", ", run->c->params[k].name);
    if (fp != NULL) {
        rs_str_catf(&msg, "stability needs every parameter set to a number; still symbolic: %s (use set, --set, or "
                    "jury, hurwitz, routh for the conditions over Q(sqrt %ld)%s[params], region/claim for symbolic "
                    "parameters)", fp, (long) s->sqrt_d, run->c->ncsets > 0 ? "(i)" : "");
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
    }
    flint_free(fp);
    flint_free(msg);
    fmpq_clear(re); fmpq_clear(im);
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
    {
        qd_cp_t P;
        int one = qd_onestep(run, q, &P, &r);
        if (r == RS_OK) r = qd_stability_unset(run, q, &P);
        if (r == RS_OK && !one) r = qd_generic_stability(run, req, &P);
        qd_cp_clear(&P, run->sym);
        if (r != RS_OK || !one) return r;
    }
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

/* an end in the shape astability writes over Q and Q(i) (the issue's
 * interface): the irrational end becomes the real root of its minimal
 * polynomial whose isolating ball meets e's enclosure */
static json_t *end_json(const rs_qd_end_struct *e, const char *var)
{
    rs_alg_t *roots = NULL;
    slong n = 0, i, hit = -1, nhit = 0;
    json_t *o;
    if (e->inf) return json_string(e->inf < 0 ? "-inf" : "inf");
    if (fmpz_poly_degree(e->minpoly) == 1) {
        if (fmpz_is_one(fmpq_denref(e->q)) && fmpz_fits_si(fmpq_numref(e->q)))
            return json_integer(fmpz_get_si(fmpq_numref(e->q)));
        return rs_json_fmpq(e->q);
    }
    rs_alg_roots_append(&roots, &n, e->minpoly, 0);
    rs_alg_sort(roots, n);
    for (i = 0; i < n; i++) {
        rs_alg_refine(roots + i, 128);
        if (arb_overlaps(roots[i].x, e->x)) { hit = i; nhit++; }
    }
    /* e's ball is certified, the roots' balls disjoint: one meets it unless
     * e's ball is wider than the gap between two roots */
    o = nhit == 1 ? rs_an_alg_end_json(roots + hit, var) : json_str_free(rs_qd_end_get_str(e));
    for (i = 0; i < n; i++) rs_alg_clear(roots + i);
    free(roots);   /* rs_alg_roots_append reallocs */
    return o;
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
    int r, rr = 0, ri = 0, alpha_inside = -1;
    json_t *alpha_out = NULL, *alpha_ev = NULL;
    arb_t alpha_deg;
    slong k;
    arb_init(alpha_deg);
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
        r = rs_an_astability_alpha_qd(&alpha_out, &alpha_ev, alpha_deg, &alpha_inside, R.N, R.D, R.d, run->err);
        if (r != RS_OK) r = rs_req_relocate(run, q, r, "astability");
        /* the rays against the E-polynomial: A-stable iff every ray is inside
         * (the open left half-plane; poles right) */
        else if (alpha_inside >= 0 && (alpha_inside == 1) != (a->a_stable != 0))
            r = rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT, "astability over Q(sqrt d): the rays and the "
                             "E-polynomial disagree on A-stability (the E-polynomial says %s)",
                             a->a_stable ? "A-stable" : "not A-stable");
    }
    if (r == RS_OK) {
        const char *name = c->params[R.par].name;
        json_t *o = json_object();
        char *ps = p_str(&R, name), *loc;
        json_object_set_new(o, "analysis", json_string("astability"));
        json_object_set_new(o, "param", json_string(name));
        json_object_set_new(o, "real_interval", json_pack("[o,o]", end_json(riv->lo, name), end_json(riv->hi, name)));
        json_object_set_new(o, "imag_interval", json_pack("[o,o]", end_json(iiv->lo, name), end_json(iiv->hi, name)));
        json_object_set_new(o, "real_interval_detail", iv_detail(riv));
        json_object_set_new(o, "imag_interval_detail", iv_detail(iiv));
        loc = flint_malloc(strlen(ps) + strlen(name) + 64);
        sprintf(loc, "p(lambda, %s) = 0 with lambda = exp(i*phi), p = %s", name, ps);
        json_object_set_new(o, "boundary_locus", json_str_free(loc));
        json_object_set_new(o, "a_stable", json_boolean(a->a_stable));
        /* A(alpha) by the rays (A-stable is A(90)), the second route to A-stability */
        if (alpha_out != NULL) {
            char *ds = rs_radius_arb_str(alpha_deg, 15);
            json_object_set_new(o, "alpha_degrees", alpha_out);
            json_object_set_new(o, "alpha_degrees_certified", json_string(ds));
            flint_free(ds);
            alpha_out = NULL;
        } else {
            json_object_set_new(o, "alpha_degrees", alpha_inside == 1 ? json_integer(90) : json_null());
        }
        json_object_set_new(o, "alpha_degrees_approx", alpha_inside >= 0 ?
                            json_real(arf_get_d(arb_midref(alpha_deg), ARF_RND_NEAR)) : json_null());
        if (alpha_inside < 0)
            json_object_set_new(o, "note", json_string("alpha of A(alpha): the rays route does not apply "
                                                       "(|N|^2 - |D|^2 has a vanishing discriminant on the rays)"));
        {
            json_t *e = json_pack("{s:s,s:o,s:b,s:b}", "route", "E-polynomial (one-step method) over Q(sqrt d)",
                                  "E", json_str_free(rs_qdpoly_get_str(a->E, R.d, "y")), "E_nonnegative",
                                  a->e_nonneg, "poles_in_right_half_plane", a->poles_right);
            if (!a->e_nonneg) json_object_set_new(e, "E_negative_at", rs_json_fmpq(a->witness));
            if (alpha_ev == NULL && alpha_inside == 1)
                alpha_ev = json_pack("{s:s,s:b}", "route", "one-step method over Q(sqrt d): rays z = -s (1 - i u), "
                                     "every cell of u decided exactly", "every_ray_inside", 1);
            json_object_set_new(o, "evidence", alpha_ev != NULL ? json_pack("[o,o]", e, alpha_ev) : json_pack("[o]", e));
            alpha_ev = NULL;
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
    json_decref(alpha_out);
    json_decref(alpha_ev);
    arb_clear(alpha_deg);
    return r;
}

/* ---- modes and simulate at the set values (an_modes.c, an_simulate.c) ------------------- */

/* the exact verdict at the set values from c[0..n] (n >= 1): stable by
 * Schur-Cohn over Q(sqrt d)(i), unstable when a root is certified outside;
 * the counts from the counting recursion (the roots at 0 z0 inside).  0
 * when neither decides (a root on or too near the circle: marginal and
 * unstable are not told apart) or the counts are not available, -2 when
 * Schur-Cohn and the certified roots disagree (exit 3) */
static int qd_verdict(rs_status_t *st, rs_rootcount_t rc, const rs_qdc_struct *c, slong n, slong z0, slong d)
{
    slong z = 0, in;
    int sc = rs_qdc_stable_checked(NULL, c, n, d);
    if (sc < 0) return sc == -2 ? -2 : 0;
    while (z < n && rs_qd_is_zero(c[z].re) && rs_qd_is_zero(c[z].im)) z++;
    if (!rs_qdc_schur_count(&in, c + z, n - z, d)) return 0;
    rc->degree = n + z0;
    rc->inside = in + z + z0;
    rc->at_zero = z + z0;
    rc->on = 0;
    rc->outside = n - z - in;
    *st = sc == 1 ? RS_STATUS_STABLE : RS_STATUS_UNSTABLE;
    return 1;
}

int rs_an_qd_point(acb_ptr *z, slong *n, int *decided, rs_status_t *st, rs_rootcount_t rc, json_t *o,
                   rs_run_t *run, const rs_request_t *q, slong prec)
{
    rs_qdc_struct *c = NULL;
    slong d = run->sym->sqrt_d;
    qd_cp_t P;
    int r = qd_cp_get(&P, run, q);
    *z = NULL;
    *n = -1;
    *decided = 0;
    if (r == RS_OK) r = qd_cp_at(&c, n, &P, run, q);
    if (r == RS_OK && *n < 1)
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "p has degree %s in lambda at these values over Q(sqrt d): "
                         "no root and no recurrence", *n < 0 ? "-inf (it vanishes)" : "0");
    if (r == RS_OK) {
        *z = _acb_vec_init(*n + 1);
        rs_qdc_vec_get_acb(*z, c, *n + 1, d, prec);
        *decided = qd_verdict(st, rc, c, *n, P.zeros, d);
        if (*decided == -2) {
            *decided = 0;
            r = rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT, "over Q(sqrt d): Schur-Cohn over Q(sqrt d)(i) "
                             "and the certified roots disagree at these values%s", "");
        }
        qd_generic_common(o, &P, run);
        {   /* the certified spectral radius beside the measured growth */
            rs_radius_t rr;
            acb_ptr w = _acb_vec_init(*n);
            rs_radius_init(rr);
            if (qd_roots_cert(rr, w, c, *n, d, 15, run->opt->max_prec))
                json_object_set_new(o, "radius", rs_json_arb(rr->rho, 15));
            rs_radius_clear(rr);
            _acb_vec_clear(w, *n);
        }
        json_object_set_new(o, "poly", json_str_free(qdc_poly_str(c, *n, d)));
        json_object_set_new(o, "at_zero_divided_out", json_integer(P.zeros));
        json_object_set_new(o, "substituted", qd_substituted(&P, run));
    }
    if (c != NULL) rs_qdc_vec_clear(c, P.degree + 1);
    qd_cp_clear(&P, run->sym);
    return r;
}

int rs_an_qd_modes_roots(rs_radius_t rr, json_t *o, rs_run_t *run, const rs_request_t *q, slong digits)
{
    rs_qdc_struct *c = NULL;
    slong d = run->sym->sqrt_d, n = -1, k, in = 0, out = 0;
    rs_rootcount_t rc;
    rs_status_t st;
    qd_cp_t P;
    int r = qd_cp_get(&P, run, q), decided = 0;
    rs_rootcount_init(rc);
    if (r == RS_OK) r = qd_cp_at(&c, &n, &P, run, q);
    if (r == RS_OK && n < 1)
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "modes: p has no root at these values%s", "");
    if (r == RS_OK) {
        /* lambda^zeros p: the roots at 0 the charpoly divided out are modes
         * too (no continuous equivalent), as on the rational path */
        acb_ptr z = _acb_vec_init(n + P.zeros);
        if (!qd_roots_cert(rr, z + P.zeros, c, n, d, digits, run->opt->max_prec)) {
            _acb_vec_clear(z, n + P.zeros);
            r = rs_req_error(run, q, q->text, RS_ERR_LIMIT, "modes over Q(sqrt d): the roots are not isolated up "
                             "to max-prec (a repeated root?)%s", "");
        } else {
            rr->roots = z;
            rr->nroots = n + P.zeros;
            rr->mult = flint_malloc(rr->nroots * sizeof(slong));
            for (k = 0; k < rr->nroots; k++) rr->mult[k] = 1;
            decided = qd_verdict(&st, rc, c, n, P.zeros, d);
            if (decided == -2) {
                decided = 0;
                r = rs_req_error(run, q, q->text, RS_ERR_INCONSISTENT, "modes over Q(sqrt d): Schur-Cohn over "
                                 "Q(sqrt d)(i) and the certified roots disagree%s", "");
            }
            /* the certified moduli against the exact counts: a root
             * certified inside (outside) needs one counted there */
            for (k = 0; k < rr->nroots; k++) {
                arb_t m, one;
                arb_init(m);
                arb_init(one);
                arb_one(one);
                acb_abs(m, z + k, rr->prec);
                if (arb_lt(m, one)) in++;
                else if (arb_gt(m, one)) out++;
                arb_clear(m);
                arb_clear(one);
            }
            qd_generic_common(o, &P, run);
            json_object_set_new(o, "poly", json_str_free(qdc_poly_str(c, n, d)));
            if (decided) {
                int agree = in <= rc->inside && out <= rc->outside;
                json_object_set_new(o, "exact_check", json_pack("{s:s,s:I,s:I,s:I,s:I,s:I,s:I,s:b}", "status",
                                    rs_status_name(st), "inside", (json_int_t) rc->inside, "on", (json_int_t) 0,
                                    "outside",
                                    (json_int_t) rc->outside, "certified_inside", (json_int_t) in,
                                    "certified_outside", (json_int_t) out, "modulus_undecided",
                                    (json_int_t) (rr->nroots - in - out), "agree", agree));
                if (!agree) run->outcome |= RS_OUTCOME_INCONSISTENT;
            } else {
                json_object_set_new(o, "exact_check", json_pack("{s:s}", "status", "undecided"));
            }
            json_object_set_new(o, "substituted", qd_substituted(&P, run));
        }
    }
    rs_rootcount_clear(rc);
    if (c != NULL) rs_qdc_vec_clear(c, P.degree + 1);
    qd_cp_clear(&P, run->sym);
    return r;
}
