/* an_complex_conds.c -- `hurwitz` and `jury` when p has coefficients in
 * Q(i): at complex set values (`set z = -1/2 + i/2`, the other parameters
 * real and set or free) or from a `char` line with i.  p = A + i B with
 * A, B in Z[real params][lambda]; then
 *   hurwitz  the Bilharz conditions of the bilinear image q(s)
 *            (stability/routh_complex.c, rs_routh_cx_conds),
 *   jury     the complex Schur-Cohn conditions of p itself
 *            (stability/schur_complex.c, rs_schur_cx_conds),
 * each a list of real polynomial conditions in the real parameters (the
 * real and imaginary parts already separated), factored, factors of one
 * sign under the assumptions dropped, and checked at admissible rational
 * points against the exact Q(i) verdict (complex Schur-Cohn and Bilharz on
 * the point's polynomial, which must agree): a disagreement is exit 3. */
#include <stdlib.h>
#include <string.h>
#include <fmpq_vec.h>
#include "analysis/registry.h"
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"

int rs_an_complex_conds_applies(rs_run_t *run)
{
    rs_variant_t *v;
    if (run->c->ncsets > 0) return 1;
    if (rs_run_default_variant(run, &v) != RS_OK) return 0;
    return v->s->complex_char;
}

/* 1 when f is a positive integer constant */
static int const_positive(const fmpz_mpoly_t f, const rs_scheme_struct *s)
{
    fmpz_t c;
    int pos;
    if (!fmpz_mpoly_is_fmpz(f, s->zctx)) return 0;
    fmpz_init(c);
    fmpz_mpoly_get_fmpz(c, f, s->zctx);
    pos = fmpz_sgn(c) > 0;
    fmpz_clear(c);
    return pos;
}

/* ---- p over Q(i)[real params] -------------------------------------------------- */

/* re + i im = p over Q(i)[real params] (rs_run_cx_poly); *n its degree in
 * lambda; errors at the request where p cannot be analysed */
static int cx_symbolic(fmpz_mpoly_t re, fmpz_mpoly_t im, slong *n, rs_variant_t **vp, rs_run_t *run,
                       const rs_an_req_t *req)
{
    const rs_scheme_struct *s;
    int r = rs_run_default_variant(run, vp);
    if (r != RS_OK) return r;
    s = (*vp)->s;
    rs_run_cx_poly_det(re, im, run, *vp);   /* with det's roots at 0 */
    *n = FLINT_MAX(fmpz_mpoly_degree_si(re, s->lambda_var, s->zctx), fmpz_mpoly_degree_si(im, s->lambda_var, s->zctx));
    if (*n < 0)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_MATH, "%s: the characteristic polynomial vanishes at "
                            "the complex set values", req->def->name);
    /* the degree over Q(params) (of the block form: twice p's) must survive */
    if ((*vp)->singular || (!s->complex_char && *n < rs_charpoly_top_degree((*vp)->cp)))
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s: the leading coefficient of p vanishes at "
                            "the set values: the implicit step cannot be solved there", req->def->name);
    if (*n < 1)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s: p has no root (degree 0 in lambda)",
                            req->def->name);
    return RS_OK;
}

/* ---- the conditions as text and as a test at a point ---------------------------- */

typedef struct {
    slong n;
    fmpz_mpoly_struct *poly;
    int *ne;                      /* poly != 0 (an even factor), else poly > 0 */
    const fmpz_mpoly_ctx_struct *ctx;
} cx_conds_t;

static void conds_push(cx_conds_t *c, const fmpz_mpoly_t p, int ne)
{
    c->poly = flint_realloc(c->poly, (size_t) (c->n + 1) * sizeof(fmpz_mpoly_struct));
    c->ne = flint_realloc(c->ne, (size_t) (c->n + 1) * sizeof(int));
    fmpz_mpoly_init(c->poly + c->n, c->ctx);
    fmpz_mpoly_set(c->poly + c->n, p, c->ctx);
    c->ne[c->n++] = ne;
}

static void conds_clear(cx_conds_t *c)
{
    slong i;
    for (i = 0; i < c->n; i++) fmpz_mpoly_clear(c->poly + i, c->ctx);
    flint_free(c->poly);
    flint_free(c->ne);
}

/* 1 when every condition holds at pt (strict: a zero fails), else 0 */
static int conds_hold(const cx_conds_t *c, fmpq *const *pt)
{
    slong i;
    for (i = 0; i < c->n; i++) {
        int sg = fmpz_mpoly_is_zero(c->poly + i, c->ctx) ? 0 : rs_hurwitz_sign_at(c->poly + i, pt, c->ctx);
        if (c->ne[i] ? sg == 0 : sg <= 0) return 0;
    }
    return 1;
}

/* f > 0 into the lists: factored, the factors of one sign under the
 * assumptions dropped, even powers as "!= 0" (every factor when f is a sum
 * of squares, nz: then f > 0 iff f != 0); 1 when f is a positive constant
 * (always true) */
static int cond_add(cx_conds_t *jc, json_t *conds, json_t *dropped, const fmpz_mpoly_t f, const char *origin,
                    const int *sign, const rs_scheme_struct *s, int nz)
{
    fmpz_mpoly_factor_t fa;
    fmpz_mpoly_t kept;
    slong i, before = jc->n;
    int neg, always = 0;
    if (fmpz_mpoly_is_zero(f, s->zctx)) {
        rs_json_append_unique(conds, "0 > 0");
        conds_push(jc, f, 0);
        return 0;
    }
    fmpz_mpoly_factor_init(fa, s->zctx);
    fmpz_mpoly_init(kept, s->zctx);
    fmpz_mpoly_one(kept, s->zctx);
    if (!fmpz_mpoly_factor(fa, f, s->zctx)) {
        fmpz_mpoly_set(kept, f, s->zctx);   /* unfactored: the condition as it is */
        neg = 0;
    } else {
        neg = fmpz_sgn(fa->constant) < 0;
        for (i = 0; i < fa->num; i++) {
            int sg = rs_hurwitz_sign(fa->poly + i, (const rs_sign_t *) sign, s->zctx);
            slong e = fmpz_get_si(fa->exp + i);
            if (sg != 0) {
                if (sg < 0 && (e & 1)) neg = !neg;
                json_array_append_new(dropped, json_pack("{s:o,s:s,s:s}", "factor", rs_json_factor(fa->poly + i, s),
                                                         "from", origin, "reason",
                                                         "of one sign under the assumptions"));
                continue;
            }
            if ((e & 1) && !nz) fmpz_mpoly_mul(kept, kept, fa->poly + i, s->zctx);
            else {
                char *line = rs_cond_string(fa->poly + i, s, "!= 0");
                rs_json_append_unique(conds, line);
                conds_push(jc, fa->poly + i, 1);
                free(line);
            }
        }
    }
    if (neg && !nz) fmpz_mpoly_neg(kept, kept, s->zctx);
    if (fmpz_mpoly_is_one(kept, s->zctx)) {
        always = jc->n == before;
    } else {
        char *line = rs_cond_string(kept, s, "> 0");
        rs_json_append_unique(conds, line);
        conds_push(jc, kept, 0);
        free(line);
    }
    fmpz_mpoly_clear(kept, s->zctx);
    fmpz_mpoly_factor_clear(fa, s->zctx);
    return always;
}

#define CX_SAMPLE_POINTS 12

/* The conditions against the exact Q(i) verdict (complex Schur-Cohn and
 * Bilharz, rs_routh_complex_checked_status: RS_ERR_INCONSISTENT when those
 * two differ) at admissible rational points (rs_sample_pts_t); a
 * disagreement is recorded in o's "sample_check" and makes the run
 * inconsistent (exit 3). */
static int cx_sample_check(rs_run_t *run, const rs_variant_t *v, const fmpz_mpoly_t re, const fmpz_mpoly_t im,
                           slong n, const cx_conds_t *jc, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    rs_sample_pts_t P;
    slong nok = 0;
    fmpq_poly_t pr, pi;
    json_t *chk = json_object(), *bad = NULL;
    int r = RS_OK;
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    rs_sample_pts_init(&P, run, v, re, im, -1);
    while (nok < (P.nfree > 0 ? CX_SAMPLE_POINTS : 1) && r == RS_OK && bad == NULL && rs_sample_pts_next(&P)) {
        rs_status_t st;
        int says;
        rs_run_cx_eval(pr, re, P.pp, s);
        rs_run_cx_eval(pi, im, P.pp, s);
        if (fmpq_poly_is_zero(pr) && fmpq_poly_is_zero(pi)) continue;
        says = conds_hold(jc, P.pp);
        /* o says never (proved from the conditions): no point may be stable
         * (the conditions holding there is the same disagreement) */
        if (json_object_get(o, "never") != NULL) says = 0;
        r = rs_routh_complex_checked_status(&st, pr, pi, n, run->err);
        if (r != RS_OK) break;
        nok++;
        if ((st == RS_STATUS_STABLE) != (says == 1)) {
            bad = rs_sample_pts_json(&P);
            rs_run_sample_disagree(chk, bad, says, rs_status_name(st));
        }
    }
    rs_run_sample_check_set(run, o, chk, nok, bad == NULL, "exact verdict over Q(i) (complex Schur-Cohn and Bilharz "
                            "on the bilinear transform, which must agree) at rational points satisfying the "
                            "assumptions");
    rs_sample_pts_clear(&P);
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    return r;
}

/* "A + i*(B)" of p = re + i im at lambda = x */
static json_t *cx_p_at(const fmpz_mpoly_t re, const fmpz_mpoly_t im, slong x, const rs_scheme_struct *s)
{
    fmpz_mpoly_t a, b;
    fmpz_t xx;
    char *sa, *sb, *out;
    json_t *j;
    fmpz_mpoly_init(a, s->zctx); fmpz_mpoly_init(b, s->zctx);
    fmpz_init_set_si(xx, x);
    fmpz_mpoly_evaluate_one_fmpz(a, re, s->lambda_var, xx, s->zctx);
    fmpz_mpoly_evaluate_one_fmpz(b, im, s->lambda_var, xx, s->zctx);
    sa = rs_scheme_zpoly_str(a, s);
    sb = rs_scheme_zpoly_str(b, s);
    out = malloc(strlen(sa) + strlen(sb) + 16);
    if (fmpz_mpoly_is_zero(b, s->zctx)) sprintf(out, "%s", sa);
    else if (fmpz_mpoly_is_zero(a, s->zctx)) sprintf(out, "i*(%s)", sb);
    else sprintf(out, "%s + i*(%s)", sa, sb);
    j = json_string(out);
    free(out);
    flint_free(sa);
    flint_free(sb);
    fmpz_clear(xx);
    fmpz_mpoly_clear(a, s->zctx); fmpz_mpoly_clear(b, s->zctx);
    return j;
}

/* One condition f > 0 named origin: raw entry, then the lists (cond_add);
 * f = 0 identically can never hold (*never) */
static void cond_entry(cx_conds_t *jc, json_t *raw, json_t *conds, json_t *dropped, json_t *always, int *never,
                       const fmpz_mpoly_t f, const char *origin, const int *sign, const rs_scheme_struct *s, int nz)
{
    json_array_append_new(raw, json_pack("{s:s,s:o}", "origin", origin, "poly", rs_json_zpoly(f, s)));
    if (fmpz_mpoly_is_zero(f, s->zctx)) *never = 1;
    if (cond_add(jc, conds, dropped, f, origin, sign, s, nz))
        json_array_append_new(always, json_string(origin));
}

/* 1 when a kept condition is a constant that is not positive: it fails
 * everywhere */
static int never_by_constant(const cx_conds_t *jc, const rs_scheme_struct *s)
{
    slong k;
    for (k = 0; k < jc->n; k++)
        if (!jc->ne[k] && fmpz_mpoly_is_fmpz(jc->poly + k, s->zctx) && !const_positive(jc->poly + k, s)) return 1;
    return 0;
}

/* the parts of the result both analyses share */
static json_t *cx_base(rs_run_t *run, const char *name, const fmpz_mpoly_t re, const fmpz_mpoly_t im,
                       const rs_scheme_struct *s)
{
    json_t *o = json_object();
    json_object_set_new(o, "analysis", json_string(name));
    json_object_set_new(o, "over", json_string("Q(i)"));
    json_object_set_new(o, "at", rs_run_cx_at(run));
    json_object_set_new(o, "p_re", rs_json_collected(re, s->lambda_var, s, "lambda"));
    json_object_set_new(o, "p_im", rs_json_collected(im, s->lambda_var, s, "lambda"));
    return o;
}

/* the verdict and, with no free parameter, the counts at the point */
static int cx_finish(rs_run_t *run, const rs_variant_t *v, const fmpz_mpoly_t re, const fmpz_mpoly_t im, slong n,
                     cx_conds_t *jc, int never, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    int r = RS_OK;
    char *why = NULL;
    /* a set that can never all hold, said as over Q (h-truth6: a planted root
     * outside times (lambda - a) printed "stable iff" conditions in a alone
     * without a common solution) */
    if (!never && jc->n > 0 && rs_run_conds_never(&why, run, jc->poly, jc->ne, jc->n, s)) {
        rs_str_catf(&why, "; never asymptotically stable");
        rs_json_set_never_conditions(o, why);
        never = 1;
    }
    flint_free(why);
    json_object_set_new(o, "verdict", json_string(never ? "never stable" : jc->n == 0 ? "stable under the assumptions"
                                                  : "stable iff the conditions hold"));
    if (rs_run_count_free(re, s, s->lambda_var) == 0 && rs_run_count_free(im, s, s->lambda_var) == 0) {
        fmpq_poly_t pr, pi;
        rs_routh_complex_t t;
        rs_status_t st;
        fmpq *pt = _fmpq_vec_init(s->nvars);
        fmpq **pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
        slong k;
        for (k = 0; k < s->nvars; k++) pp[k] = pt + k;
        fmpq_poly_init(pr); fmpq_poly_init(pi);
        rs_routh_complex_init(t);
        rs_run_cx_eval(pr, re, pp, s);
        rs_run_cx_eval(pi, im, pp, s);
        r = rs_routh_complex_status(&st, t, pr, pi, n, run->err);
        if (r == RS_OK) {
            json_object_set_new(o, "status", json_string(rs_status_name(st)));
            json_object_set_new(o, "degree", json_integer(n));
            json_object_set_new(o, "inside", json_integer(t->left));
            json_object_set_new(o, "on", json_integer(t->axis + (n - t->degree)));
            json_object_set_new(o, "outside", json_integer(t->right));
        }
        rs_routh_complex_clear(t);
        fmpq_poly_clear(pr); fmpq_poly_clear(pi);
        _fmpq_vec_clear(pt, s->nvars);
        flint_free(pp);
    }
    if (r == RS_OK) r = cx_sample_check(run, v, re, im, n, jc, o);
    return r;
}

/* ---- the analyses ------------------------------------------------------------- */

int rs_an_complex_hurwitz(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_t re, im;
    rs_routh_cx_conds_t bc;
    cx_conds_t jc;
    json_t *o = NULL, *conds, *dropped, *always, *raw;
    slong n = 0, k;
    int r, never = 0, *sign = NULL;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    rs_routh_cx_conds_init(&bc, s->zctx);
    jc.n = 0; jc.poly = NULL; jc.ne = NULL; jc.ctx = s->zctx;
    r = cx_symbolic(re, im, &n, &v, run, req);
    if (r == RS_OK && !rs_routh_cx_conds(&bc, re, im, s->lambda_var, s->zctx, RS_CHARPOLY_MAX_TERMS))
        r = rs_error_set(run->err, RS_ERR_LIMIT, "hurwitz over Q(i): a Bilharz condition has over %ld terms (limit)",
                         (long) RS_CHARPOLY_MAX_TERMS);
    if (r == RS_OK) {
        const char *zv = rs_case_param_index(run->c, "z") >= 0 ? "s" : "z";
        char buf[80];
        sign = rs_run_signs(run, s);
        o = cx_base(run, "hurwitz", re, im, s);
        json_object_set_new(o, "var", json_string(zv));
        json_object_set_new(o, "degree", json_integer(n));
        json_object_set_new(o, "method", json_string(
            "Bilharz (generalised Routh-Hurwitz over Q(i)) on q(s) = (1 - s)^n p((1 + s)/(1 - s)): with "
            "c = (-1)^n p(-1) the leading coefficient of q, conj(c) i^(-n) q(i w) = P(w) + i Q(w) (P, Q real); "
            "every root of q in Re s < 0 iff the Cauchy index of Q/P is -n iff the fraction-free signed "
            "remainder chain T_0 = P, T_1 = Q, T_(k+1) = -prem(T_(k-1), T_k)/lc(T_(k-1))^2 (subresultants) "
            "has (-1)^k lc(T_k) > 0 for k = 1..n; with |c|^2 > 0 (lambda = -1 no root) that is every "
            "|lambda| < 1"));
        json_object_set_new(o, "P", rs_json_collected(bc.P, s->lambda_var, s, "w"));
        json_object_set_new(o, "Q", rs_json_collected(bc.Q, s->lambda_var, s, "w"));
        json_object_set_new(o, "minors", json_array());
        conds = json_array();
        dropped = json_array();
        always = json_array();
        raw = json_array();
        for (k = 0; k < bc.ncond; k++) {
            if (k == 0) snprintf(buf, sizeof buf, "|c|^2");
            else snprintf(buf, sizeof buf, "%slc(T_%ld)", (k & 1) ? "-" : "", (long) k);
            cond_entry(&jc, raw, conds, dropped, always, &never, bc.cond + k, buf, sign, s, k == 0);
        }
        if (never_by_constant(&jc, s)) never = 1;
        json_object_set_new(o, "bilharz", raw);
        json_object_set_new(o, "conditions", conds);
        json_object_set_new(o, "nonzero", json_array());
        json_object_set_new(o, "dropped", dropped);
        json_object_set_new(o, "always_true", always);
        json_object_set_new(o, "p_at_1", cx_p_at(re, im, 1, s));
        json_object_set_new(o, "p_at_minus_1", cx_p_at(re, im, -1, s));
        r = cx_finish(run, v, re, im, n, &jc, never, o);
    }
    if (r == RS_OK) rs_run_emit_exact(run, v, o);
    else json_decref(o);
    flint_free(sign);
    conds_clear(&jc);
    rs_routh_cx_conds_clear(&bc, s->zctx);
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    return r;
}

int rs_an_complex_jury(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_t re, im;
    rs_schur_cx_conds_t sc;
    cx_conds_t jc;
    json_t *o = NULL, *conds, *dropped, *always, *raw;
    slong n = 0, k;
    int r, never = 0, *sign = NULL;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    rs_schur_cx_conds_init(&sc);
    jc.n = 0; jc.poly = NULL; jc.ne = NULL; jc.ctx = s->zctx;
    r = cx_symbolic(re, im, &n, &v, run, req);
    if (r == RS_OK && !rs_schur_cx_conds(&sc, re, im, s->lambda_var, s->zctx))
        r = rs_error_set(run->err, RS_ERR_LIMIT, "jury over Q(i): the Schur-Cohn recursion grew over %ld terms "
                         "(limit)", (long) 20000);
    if (r == RS_OK) {
        char buf[80];
        sign = rs_run_signs(run, s);
        o = cx_base(run, "jury", re, im, s);
        json_object_set_new(o, "method", json_string("Schur-Cohn over Q(i), symbolic"));
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "degree", json_integer(n));
        conds = json_array();
        dropped = json_array();
        always = json_array();
        raw = json_array();
        for (k = 0; k < sc.ndelta; k++) {
            snprintf(buf, sizeof buf, "delta_%ld", (long) (n - k));
            cond_entry(&jc, raw, conds, dropped, always, &never, sc.delta + k, buf, sign, s, 0);
            if (fmpz_mpoly_is_zero(sc.delta + k, s->zctx)) break;   /* the recursion stops there */
        }
        if (never_by_constant(&jc, s)) never = 1;
        json_object_set_new(o, "deltas", raw);
        json_object_set_new(o, "conditions", conds);
        json_object_set_new(o, "dropped", dropped);
        json_object_set_new(o, "always_true", always);
        json_object_set_new(o, "note", json_string(
            "Schur-Cohn over Q(i) without divisions: p_(k-1) = (conj(a_k) p_k - a_0 p_k*)/lambda, p* = lambda^k "
            "conj(p(1/conj(lambda))); all |lambda| < 1 iff every delta_k = |a_k|^2 - |a_0|^2 > 0 (Marden, Geometry "
            "of Polynomials, Thm 43.1; strict inequalities: exact for every value of the real parameters)"));
        r = cx_finish(run, v, re, im, n, &jc, never, o);
    }
    if (r == RS_OK) rs_run_emit_exact(run, v, o);
    else json_decref(o);
    flint_free(sign);
    conds_clear(&jc);
    rs_schur_cx_conds_clear(&sc, s->zctx);
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    return r;
}

/* ---- p at a point: every parameter a number ------------------------------------ */

int rs_an_complex_point_poly(fmpq_poly_t pr, fmpq_poly_t pi, json_t **at, rs_variant_t **vp, rs_run_t *run,
                             const rs_an_req_t *req)
{
    const rs_scheme_struct *s;
    fmpz_mpoly_t re, im;
    slong n = 0, k;
    int r = rs_run_default_variant(run, vp);
    if (r != RS_OK) return r;
    s = (*vp)->s;
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    r = cx_symbolic(re, im, &n, vp, run, req);
    for (k = 0; r == RS_OK && k < s->nvars; k++) {
        char msg[300];
        if (k == s->lambda_var
            || (fmpz_mpoly_degree_si(re, k, s->zctx) <= 0 && fmpz_mpoly_degree_si(im, k, s->zctx) <= 0))
            continue;
        snprintf(msg, sizeof msg, "%s needs every parameter set to a number (real or complex); still symbolic: %s",
                 req->def->name, s->vars[k]);
        r = rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
    }
    if (r == RS_OK) {
        fmpq *pt = _fmpq_vec_init(s->nvars);
        fmpq **pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
        for (k = 0; k < s->nvars; k++) pp[k] = pt + k;
        rs_run_cx_eval(pr, re, pp, s);
        rs_run_cx_eval(pi, im, pp, s);
        _fmpq_vec_clear(pt, s->nvars);
        flint_free(pp);
        *at = rs_run_cx_at(run);
    }
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    return r;
}
