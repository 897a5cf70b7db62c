/* an_qd_complex.c -- issue 15: `jury`, `hurwitz` and `routh` of a model over
 * Q(sqrt d) (rk sdirk2, sdirk3, ...) at complex set values (`set z = -1/2 +
 * 3/2*i`), the other parameters real and set or free.  The arithmetic is the
 * composition of the two pieces already there: the scheme keeps sqrt(d) as a
 * real variable s (reduced by s^2 = d), the complex set values make p = re +
 * i im with re, im in Z[params, s][lambda] (complex_poly.c), and the Q(i)
 * conditions (stability/schur_complex.c, stability/routh_complex.c: I a
 * variable reduced by I^2 = -1) run on it with s one more real parameter.
 * Both are polynomial identities in the coefficients (Schur-Cohn divides
 * only by lambda; Bilharz's subresultants specialise), so reducing each
 * condition by s^2 = d gives the conditions at s = sqrt(d): c0 + sqrt(d) c1
 * > 0 with c0, c1 in Z[params], decided exactly (an_qd_conds.c's qc_add).
 *   jury    Schur-Cohn over Q(sqrt d)(i): delta_k = |a_k|^2 - |a_0|^2 > 0;
 *   hurwitz, routh  Bilharz on the bilinear image (the complex Routh-Hurwitz).
 * The other method's conditions are computed too: at admissible rational
 * points both must agree with each other and with the exact point verdict
 * (Schur-Cohn over Q(sqrt d)(i) against the certified Arb roots,
 * rs_qdc_stable_checked); any disagreement is exit 3.
 * `region NAME` and a claim with one free real parameter (rs_an_qd_cx_fiber)
 * feed both lists to an_qd_conds.c's cells (rs_an_qd_cx_cells). */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "algebra/qsqrt.h"
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"

static const char *const kind_name[3] = {"jury", "hurwitz", "routh"};

/* "Q(sqrt d)(i)" (flint_free it) */
static char *qdc_over_str(slong d)
{
    char *s = flint_malloc(48);
    snprintf(s, 48, "Q(sqrt %ld)(i)", (long) d);
    return s;
}

/* f as "(c0 + sqrt(d)*(c1))*lambda^k + ..." (each lambda-coefficient over
 * Q(sqrt d)[params]; flint_free it) */
static char *qdc_poly_str(const fmpz_mpoly_t f, slong n, const rs_scheme_struct *s, const char *var)
{
    fmpz_mpoly_t a, a0, a1;
    char *out = flint_malloc(1);
    size_t len = 0;
    slong k;
    out[0] = '\0';
    fmpz_mpoly_init(a, s->zctx); fmpz_mpoly_init(a0, s->zctx); fmpz_mpoly_init(a1, s->zctx);
    for (k = n; k >= 0; k--) {
        char *c;
        size_t m;
        rs_charpoly_coeff(a, f, k, s->lambda_var, s->zctx);
        if (fmpz_mpoly_is_zero(a, s->zctx)) continue;
        rs_charpoly_coeff(a0, a, 0, s->sqrt_var, s->zctx);
        rs_charpoly_coeff(a1, a, 1, s->sqrt_var, s->zctx);
        c = rs_an_qd_mpoly_str(a0, a1, s, 1);
        m = len + strlen(c) + strlen(var) + 40;   /* the capacity */
        out = flint_realloc(out, m);
        len += (size_t) snprintf(out + len, m - len, "%s(%s)%s%s", len > 0 ? " + " : "", c,
                                 k == 0 ? "" : "*", k == 0 ? "" : var);
        if (k > 1) len += (size_t) snprintf(out + len, m - len, "^%ld", (long) k);
        flint_free(c);
    }
    if (len == 0) {
        out = flint_realloc(out, 2);
        strcpy(out, "0");
    }
    fmpz_mpoly_clear(a, s->zctx); fmpz_mpoly_clear(a0, s->zctx); fmpz_mpoly_clear(a1, s->zctx);
    return out;
}

static json_t *qdc_poly_json(const fmpz_mpoly_t f, const rs_scheme_struct *s, const char *var)
{
    char *str = qdc_poly_str(f, fmpz_mpoly_degree_si(f, s->lambda_var, s->zctx), s, var);
    json_t *j = json_string(str);
    flint_free(str);
    return j;
}

int rs_an_qd_parts_stable(const fmpz_mpoly_struct *const *part, slong n, fmpq *const *pt, const rs_scheme_struct *s)
{
    int sc = rs_an_qd_parts_verdict(part, n, pt, s);
    return sc == -4 ? -1 : sc == -2 ? -2 : sc == 1;   /* a degree drop, marginal or unstable: not stable */
}

int rs_an_qd_parts_verdict(const fmpz_mpoly_struct *const *part, slong n, fmpq *const *pt, const rs_scheme_struct *s)
{
    fmpq_poly_t e;
    rs_qdc_struct *c = rs_qdc_vec_init(n + 1);
    slong k, deg = -1;
    int sc = -4, j;
    fmpq_poly_init(e);
    for (j = 0; j < 4; j++) {
        if (part[j] == NULL) continue;
        rs_run_cx_eval(e, part[j], pt, s);
        deg = FLINT_MAX(deg, fmpq_poly_degree(e));
        for (k = 0; k <= n; k++) {
            rs_qd_struct *x = j < 2 ? c[k].re : c[k].im;
            fmpq_poly_get_coeff_fmpq((j & 1) ? x->y : x->x, e, k);
        }
    }
    /* x + sqrt(d) y = 0 only for x = y = 0: the degree over Q(sqrt d)(i) is deg */
    if (deg >= 0 && deg < n) sc = -3;
    else if (deg == n) sc = rs_qdc_stable_checked(NULL, c, n, s->sqrt_d);
    rs_qdc_vec_clear(c, n + 1);
    fmpq_poly_clear(e);
    return sc;
}

/* the parts re = q[0] + sqrt(d) q[1], im = q[2] + sqrt(d) q[3] (q[k]
 * without sqrt(d); initialised by the caller) as part[] */
static void qdc_parts(fmpz_mpoly_struct *q, const fmpz_mpoly_struct **part, const fmpz_mpoly_t re,
                      const fmpz_mpoly_t im, const rs_scheme_struct *s)
{
    int k;
    for (k = 0; k < 4; k++) {
        rs_charpoly_coeff(q + k, k < 2 ? re : im, k & 1, s->sqrt_var, s->zctx);
        part[k] = q + k;
    }
}

/* the two lists: Schur-Cohn's deltas (m = 0) and Bilharz's conditions (m = 1) */
typedef struct {
    rs_an_qd_conds_t q[2];   /* q[m].never: a condition is never true */
    json_t *raw[2], *conds[2], *parts[2], *dropped[2], *always[2];
} qdc_lists_t;

static void qdc_lists_init(qdc_lists_t *L, const rs_scheme_struct *s)
{
    int m;
    for (m = 0; m < 2; m++) {
        L->q[m].n = 0; L->q[m].c0 = L->q[m].c1 = NULL; L->q[m].ne = NULL; L->q[m].s = s; L->q[m].never = 0;
        L->raw[m] = json_array(); L->conds[m] = json_array(); L->parts[m] = json_array();
        L->dropped[m] = json_array(); L->always[m] = json_array();
    }
}

static void qdc_lists_clear(qdc_lists_t *L)
{
    int m;
    for (m = 0; m < 2; m++) {
        rs_an_qd_conds_clear(&L->q[m]);
        json_decref(L->raw[m]); json_decref(L->conds[m]); json_decref(L->parts[m]);
        json_decref(L->dropped[m]); json_decref(L->always[m]);
    }
}

/* f > 0 (f in Z[params, s], reduced here by s^2 = d) into list m */
static void qdc_add(qdc_lists_t *L, int m, fmpz_mpoly_t f, const char *origin, const int *sign,
                    const rs_scheme_struct *s)
{
    int a;
    rs_scheme_reduce_sqrt(f, s);
    json_array_append_new(L->raw[m], json_pack("{s:s,s:o}", "origin", origin, "poly", rs_json_zpoly(f, s)));
    if (fmpz_mpoly_is_zero(f, s->zctx)) {
        rs_json_append_unique(L->conds[m], "0 > 0");
        L->q[m].never = 1;
        return;
    }
    a = rs_an_qd_conds_add(&L->q[m], L->conds[m], L->parts[m], L->dropped[m], f, origin, sign);
    if (a == 1) json_array_append_new(L->always[m], json_string(origin));
    if (a == -1) L->q[m].never = 1;
}

static const char qdc_note_jury[] =
    "Schur-Cohn over Q(sqrt d)(i) without divisions: p_(k-1) = (conj(a_k) p_k - a_0 p_k*)/lambda, p* = lambda^k "
    "conj(p(1/conj(lambda))), sqrt(d) real (s^2 = d and i^2 = -1 after every product); all |lambda| < 1 iff every "
    "delta_k = |a_k|^2 - |a_0|^2 > 0 (Marden, Geometry of Polynomials, Thm 43.1); c0 + sqrt(d)*(c1) > 0 decided "
    "exactly by comparing c0^2 with d*c1^2";
static const char qdc_note_bilharz[] =
    "Bilharz (generalised Routh-Hurwitz) over Q(sqrt d)(i) on q(s) = (1 - s)^n p((1 + s)/(1 - s)): with c = "
    "(-1)^n p(-1), conj(c) i^(-n) q(i w) = P(w) + i Q(w) (P, Q real, in Q(sqrt d)[params]); every |lambda| < 1 iff "
    "|c|^2 > 0 and the fraction-free signed remainder chain of P, Q (subresultants, polynomial in sqrt(d), then "
    "sqrt(d)^2 = d) has (-1)^k lc(T_k) > 0 for k = 1..n";

/* re + i im of v's p (sqrt(d) reduced; *np its degree), both condition
 * lists into L, sc's and bc's (initialised by the caller, who clears all) */
static int qdc_build(fmpz_mpoly_t re, fmpz_mpoly_t im, slong *np, rs_schur_cx_conds_t *sc, rs_routh_cx_conds_t *bc,
                     qdc_lists_t *L, int *sign, rs_run_t *run, const rs_an_req_t *req, const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    slong n, k;
    int r = RS_OK;
    char buf[80];
    if (v->singular)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s: the leading coefficient of p vanishes at "
                            "the set values: the implicit step cannot be solved there", req->def->name);
    /* the roots at 0 the charpoly divided out are inside: left out */
    rs_run_cx_poly(re, im, run, v);
    rs_scheme_reduce_sqrt(re, s);
    rs_scheme_reduce_sqrt(im, s);
    n = *np = FLINT_MAX(fmpz_mpoly_degree_si(re, s->lambda_var, s->zctx),
                        fmpz_mpoly_degree_si(im, s->lambda_var, s->zctx));
    if (n < 1) {
        snprintf(buf, sizeof buf, "%s", req->def->name);
        return rs_req_error(run, req->q, req->q->text, n < 0 ? RS_ERR_MATH : RS_ERR_INPUT, n < 0 ? "%s: the "
                            "characteristic polynomial vanishes at the complex set values" : "%s: p has no root "
                            "(degree 0 in lambda) at the complex set values", buf);
    }
    if (!rs_schur_cx_conds(sc, re, im, s->lambda_var, s->zctx)
        || !rs_routh_cx_conds(bc, re, im, s->lambda_var, s->zctx, RS_CHARPOLY_MAX_TERMS))
        r = rs_req_error(run, req->q, req->q->text, RS_ERR_LIMIT, "%s over Q(sqrt d)(i): a condition grew over the "
                         "term limit", req->def->name);
    if (r == RS_OK) r = rs_budget_check(run->err, "the conditions over Q(sqrt d)(i)");
    for (k = 0; r == RS_OK && k < sc->ndelta; k++) {
        snprintf(buf, sizeof buf, "delta_%ld", (long) (n - k));
        qdc_add(L, 0, sc->delta + k, buf, sign, s);
        if (fmpz_mpoly_is_zero(sc->delta + k, s->zctx)) break;   /* the recursion stops there */
    }
    for (k = 0; r == RS_OK && k < bc->ncond; k++) {
        if (k == 0) snprintf(buf, sizeof buf, "|c|^2");
        else snprintf(buf, sizeof buf, "%slc(T_%ld)", (k & 1) ? "-" : "", (long) k);
        qdc_add(L, 1, bc->cond + k, buf, sign, s);
    }
    return r;
}

int rs_an_qd_cx_conds(rs_run_t *run, const rs_an_req_t *req, int kind)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_t re, im;
    fmpz_mpoly_struct q[4];
    const fmpz_mpoly_struct *part[4];
    rs_schur_cx_conds_t sc;
    rs_routh_cx_conds_t bc;
    qdc_lists_t L;
    json_t *o;
    slong n = 0, k;
    int r, m = kind == 0 ? 0 : 1, *sign;
    char *why = NULL, *over;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    for (k = 0; k < 4; k++) fmpz_mpoly_init(q + k, s->zctx);
    rs_schur_cx_conds_init(&sc);
    rs_routh_cx_conds_init(&bc, s->zctx);
    qdc_lists_init(&L, s);
    sign = rs_run_signs(run, s);
    r = qdc_build(re, im, &n, &sc, &bc, &L, sign, run, req, v);
    if (r != RS_OK) goto done;
    o = json_object();
    over = qdc_over_str(s->sqrt_d);
    json_object_set_new(o, "analysis", json_string(kind_name[kind]));
    json_object_set_new(o, "over", json_string(over));
    flint_free(over);
    json_object_set_new(o, "method", json_string(m == 0 ? "Schur-Cohn over Q(sqrt d)(i), symbolic"
                                                 : "Bilharz (complex Routh-Hurwitz) over Q(sqrt d)(i), symbolic"));
    json_object_set_new(o, "symbolic", json_true());
    json_object_set_new(o, "at", rs_run_cx_at(run));
    json_object_set_new(o, "p_re", qdc_poly_json(re, s, "lambda"));
    json_object_set_new(o, "p_im", qdc_poly_json(im, s, "lambda"));
    if (m == 1) {
        /* P + i Q = conj(c) i^(-n) q(i w), sqrt(d)^2 = d */
        rs_scheme_reduce_sqrt(bc.P, s);
        rs_scheme_reduce_sqrt(bc.Q, s);
        json_object_set_new(o, "var", json_string("z"));
        json_object_set_new(o, "P", qdc_poly_json(bc.P, s, "w"));
        json_object_set_new(o, "Q", qdc_poly_json(bc.Q, s, "w"));
    }
    json_object_set_new(o, "degree", json_integer(n));
    json_object_set_new(o, m == 0 ? "deltas" : "bilharz", json_incref(L.raw[m]));
    json_object_set_new(o, "conditions", json_incref(L.conds[m]));
    json_object_set_new(o, "conditions_qd", json_incref(L.parts[m]));
    json_object_set_new(o, "dropped", json_incref(L.dropped[m]));
    json_object_set_new(o, "always_true", json_incref(L.always[m]));
    json_object_set_new(o, "note", json_string(m == 0 ? qdc_note_jury : qdc_note_bilharz));
    /* never under the assumptions (an_qd_never.c): both lists say so, the
     * sample check then expects no stable point */
    if (!L.q[m].never && L.q[m].n > 0 && rs_an_qd_conds_never(&why, run, &L.q[m])) {
        rs_str_catf(&why, "; never asymptotically stable");
        rs_json_set_never_conditions(o, why);
        L.q[m].never = 1;
    }
    flint_free(why);
    why = NULL;
    json_object_set_new(o, "verdict", json_string(L.q[m].never ? "never stable" : L.q[m].n == 0
                                                  ? "stable under the assumptions" : "stable iff the conditions hold"));
    qdc_parts(q, part, re, im, s);
    r = rs_an_qd_conds_sample_check(run, v, re, im, part, n, &L.q[m], &L.q[1 - m], "Q(sqrt d)(i)",
                                    "the Schur-Cohn and the Bilharz", m == 0 ? "Bilharz (complex Routh-Hurwitz on "
                                    "the bilinear image) over Q(sqrt d)(i): its conditions at the same sample points"
                                    : "Schur-Cohn over Q(sqrt d)(i): its conditions delta_k > 0 at the same sample "
                                    "points", o, req->q);
    if (r == RS_OK) rs_run_emit_exact(run, v, o);
    else json_decref(o);
done:
    flint_free(sign);
    qdc_lists_clear(&L);
    rs_schur_cx_conds_clear(&sc, s->zctx);
    rs_routh_cx_conds_clear(&bc, s->zctx);
    for (k = 0; k < 4; k++) fmpz_mpoly_clear(q + k, s->zctx);
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    return r;
}

int rs_an_qd_cx_other(const rs_run_t *run, slong tv)
{
    slong j;
    for (j = 0; j < run->c->ncsets; j++)
        if (rs_case_param_index(run->c, run->c->csets[j].name) != tv) return 1;
    return 0;
}

/* the model at the case's real set values and extra[] with tv[0..ntv)
 * kept free: p = re + i im, both lists, parts and |a_n|^2 */
typedef struct {
    rs_variant_t *v;
    const rs_scheme_struct *s;
    slong n;
    fmpz_mpoly_t re, im, lead;
    fmpz_mpoly_struct q[4];
    const fmpz_mpoly_struct *part[4];
    rs_schur_cx_conds_t sc;
    rs_routh_cx_conds_t bc;
    qdc_lists_t L;
    int *sign;
} qdc_fix_t;

static int qdc_fix_init(qdc_fix_t *F, rs_run_t *run, const rs_an_req_t *req, const slong *tv, slong ntv,
                        const rs_assign_t *extra, slong nextra)
{
    const char *keep[2];
    rs_assign_t *as = NULL;
    slong nas = 0, k;
    const rs_scheme_struct *s;
    fmpz_mpoly_t x;
    int r;
    F->s = NULL;
    for (k = 0; k < ntv; k++) keep[k] = run->c->params[tv[k]].name;
    rs_run_assignments(run, &as, &nas, keep, ntv, extra, nextra);
    r = rs_run_variant(&F->v, run, as, nas);
    rs_assign_free(as, nas);
    if (r != RS_OK) return r;
    s = F->s = F->v->s;
    F->n = 0;
    fmpz_mpoly_init(F->re, s->zctx); fmpz_mpoly_init(F->im, s->zctx);
    fmpz_mpoly_init(F->lead, s->zctx); fmpz_mpoly_init(x, s->zctx);
    for (k = 0; k < 4; k++) fmpz_mpoly_init(F->q + k, s->zctx);
    rs_schur_cx_conds_init(&F->sc);
    rs_routh_cx_conds_init(&F->bc, s->zctx);
    qdc_lists_init(&F->L, s);
    F->sign = rs_run_signs(run, s);
    r = qdc_build(F->re, F->im, &F->n, &F->sc, &F->bc, &F->L, F->sign, run, req, F->v);
    for (k = 0; r == RS_OK && k < s->lambda_var; k++)
        if (k != tv[0] && (ntv < 2 || k != tv[1]) && k != s->sqrt_var
            && (fmpz_mpoly_degree_si(F->re, k, s->zctx) > 0 || fmpz_mpoly_degree_si(F->im, k, s->zctx) > 0)) {
            if (ntv == 1)
                r = rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "expected every real parameter but %s "
                                 "set: region and claim over Q(sqrt d)(i) are decided on the exact cells of one "
                                 "parameter (jury, hurwitz and routh give the conditions with more parameters free)",
                                 keep[0]);
            else
                r = rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "'%s' is symbolic: region N1, N2 over Q(sqrt "
                                 "d)(i) decides two parameters; set the others (jury, hurwitz and routh give the "
                                 "conditions with more parameters free)", s->vars[k]);
        }
    if (r == RS_OK) {
        /* |a_n|^2 = lr^2 + li^2: zero exactly where the step is singular */
        rs_charpoly_coeff(x, F->re, F->n, s->lambda_var, s->zctx);
        fmpz_mpoly_mul(F->lead, x, x, s->zctx);
        rs_charpoly_coeff(x, F->im, F->n, s->lambda_var, s->zctx);
        fmpz_mpoly_mul(x, x, x, s->zctx);
        fmpz_mpoly_add(F->lead, F->lead, x, s->zctx);
        rs_scheme_reduce_sqrt(F->lead, s);
        qdc_parts(F->q, F->part, F->re, F->im, s);
    }
    fmpz_mpoly_clear(x, s->zctx);
    return r;
}

static void qdc_fix_clear(qdc_fix_t *F)
{
    const rs_scheme_struct *s = F->s;
    slong k;
    if (s == NULL) return;
    flint_free(F->sign);
    qdc_lists_clear(&F->L);
    rs_schur_cx_conds_clear(&F->sc, s->zctx);
    rs_routh_cx_conds_clear(&F->bc, s->zctx);
    for (k = 0; k < 4; k++) fmpz_mpoly_clear(F->q + k, s->zctx);
    fmpz_mpoly_clear(F->re, s->zctx); fmpz_mpoly_clear(F->im, s->zctx);
    fmpz_mpoly_clear(F->lead, s->zctx);
}

int rs_an_qd_cx_fiber(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                      slong tv, const rs_bound_t *dom, const rs_assign_t *extra, slong nextra)
{
    qdc_fix_t F;
    int r, vd = 0;
    json_t *ce = NULL;
    if (verdict == NULL) verdict = &vd;
    if (counter == NULL) counter = &ce;
    *verdict = 0;
    *counter = NULL;
    /* the case's real set values and extra[] (region's `at`), tv kept free */
    r = qdc_fix_init(&F, run, req, &tv, 1, extra, nextra);
    if (r == RS_OK) {
        const rs_scheme_struct *s = F.s;
        json_t *oo = kind < 0 ? json_object() : o;
        r = rs_an_qd_cx_cells(oo, run, req->q, tv, &F.L.q[0], &F.L.q[1], F.part, F.n, F.lead, dom, kind, verdict,
                              counter);
        if (r == RS_OK && kind < 0) {
            char *over = qdc_over_str(s->sqrt_d);
            json_object_set_new(oo, "analysis", json_string("region"));
            json_object_set_new(oo, "param", json_string(run->c->params[tv].name));
            json_object_set_new(oo, "over", json_string(over));
            flint_free(over);
            json_object_set_new(oo, "at", rs_run_cx_at(run));
            json_object_set_new(oo, "p_re", qdc_poly_json(F.re, s, "lambda"));
            json_object_set_new(oo, "p_im", qdc_poly_json(F.im, s, "lambda"));
            json_object_set_new(oo, "conditions", json_incref(F.L.conds[0]));
            json_object_set_new(oo, "conditions_bilharz", json_incref(F.L.conds[1]));
            json_object_set_new(oo, "dropped", json_incref(F.L.dropped[0]));
            json_object_set_new(oo, "method", json_string(
                "cells cut at the real roots of the norms c0^2 - d c1^2 of the Schur-Cohn conditions over "
                "Q(sqrt d)(i) (jury's, delta_k = |a_k|^2 - |a_0|^2 > 0), of the Bilharz conditions (hurwitz's) and "
                "of |a_n|^2, and at the assumptions' ends; each rational sample decided three ways: both condition "
                "lists' exact signs and Schur-Cohn over Q(sqrt d)(i) with the certified Arb roots (unstable: a root "
                "certified outside; not stable: marginal and unstable not told apart); each irrational cut t0 by "
                "both lists' exact signs in Q(t0, sqrt d) (no delta_k zero there: no root on the circle, so not "
                "stable is unstable); all must agree, else exit 3"));
            rs_run_emit_exact(run, F.v, oo);
        } else if (kind < 0) {
            json_decref(oo);
        }
    }
    json_decref(ce);
    qdc_fix_clear(&F);
    return r;
}

int rs_an_qd_cx_region2(rs_run_t *run, const rs_an_req_t *req)
{
    qdc_fix_t F;
    slong tv[2];
    int r;
    tv[0] = req->u.region.param;
    tv[1] = req->u.region.param2;
    r = qdc_fix_init(&F, run, req, tv, 2, req->u.region.at, req->u.region.nat);
    if (r == RS_OK) {
        json_t *ex = json_object();
        char *over = qdc_over_str(F.s->sqrt_d);
        json_object_set_new(ex, "over", json_string(over));
        flint_free(over);
        json_object_set_new(ex, "at", rs_run_cx_at(run));
        json_object_set_new(ex, "p_re", qdc_poly_json(F.re, F.s, "lambda"));
        json_object_set_new(ex, "p_im", qdc_poly_json(F.im, F.s, "lambda"));
        json_object_set_new(ex, "conditions", json_incref(F.L.conds[0]));
        json_object_set_new(ex, "conditions_bilharz", json_incref(F.L.conds[1]));
        json_object_set_new(ex, "dropped", json_incref(F.L.dropped[0]));
        r = rs_an_qd_cx_plane(run, req, F.v, tv, &F.L.q[0], &F.L.q[1], F.part, F.n, F.lead, ex);
        json_decref(ex);
    }
    qdc_fix_clear(&F);
    return r;
}
