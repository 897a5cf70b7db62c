/* an_qd_conds.c -- issue 15: `jury` and `hurwitz` of a model over
 * Q(sqrt d)[params] (rk sdirk2 in any scheme; model.h's qd).  p lives in the
 * scheme's zctx with sqrt(d) as a variable; every product is reduced by
 * sqrt(d)^2 = d (rs_scheme_reduce_sqrt), so each quantity is c0 + sqrt(d) c1
 * with c0, c1 in Z[params].  No division is needed:
 *   jury     Schur-Cohn without divisions, p_(k-1) = (a_k p_k - a_0 p_k*)/lambda
 *            (real coefficients: sqrt(d) is real), rows divided only by their
 *            content in Z[params] (a factor g scales delta by g^2);
 *            conditions delta_k = a_k^2 - a_0^2 > 0 (Schur 1917);
 *   hurwitz  q(z) = (z - 1)^n p((z + 1)/(z - 1)) = b_n z^n + ... + b_0, its
 *            Hurwitz minors D_k by cofactor expansion; with a leading
 *            coefficient of either sign, D_k(-q) = (-1)^k D_k(q), so every
 *            root of q in Re z < 0 iff b_n^k D_k > 0 for k = 1..n, i.e.
 *            b_n D_k > 0 (k odd), D_k > 0 (k even) and, as D_n = b_0 D_(n-1),
 *            b_n b_0 > 0 in place of the last (Hurwitz 1895).
 * Each condition c0 + sqrt(d) c1 > 0: the gcd of c0 and c1 in Z[params] is
 * factored (factors of one sign under the assumptions dropped, even powers as
 * "!= 0"), the rest printed as "c0 + sqrt(d)*(c1) > 0".  Both are checked at
 * admissible rational points against the exact point verdict over Q(sqrt d)
 * (Schur-Cohn with exact signs and the certified Arb roots, which must agree):
 * a disagreement is exit 3. */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "algebra/qsqrt.h"
#include "analysis/an_region.h"
#include "recstab/routh.h"

/* the conditions c0 + sqrt(d) c1 > 0 (ne: != 0; an_qd.h) */
typedef rs_an_qd_conds_t qc_t;

static void qc_push(qc_t *q, const fmpz_mpoly_t c0, const fmpz_mpoly_t c1, int ne)
{
    const fmpz_mpoly_ctx_struct *ctx = q->s->zctx;
    q->c0 = flint_realloc(q->c0, (size_t) (q->n + 1) * sizeof(fmpz_mpoly_struct));
    q->c1 = flint_realloc(q->c1, (size_t) (q->n + 1) * sizeof(fmpz_mpoly_struct));
    q->ne = flint_realloc(q->ne, (size_t) (q->n + 1) * sizeof(int));
    fmpz_mpoly_init(q->c0 + q->n, ctx);
    fmpz_mpoly_init(q->c1 + q->n, ctx);
    fmpz_mpoly_set(q->c0 + q->n, c0, ctx);
    fmpz_mpoly_set(q->c1 + q->n, c1, ctx);
    q->ne[q->n++] = ne;
}

static void qc_clear(qc_t *q)
{
    slong i;
    for (i = 0; i < q->n; i++) {
        fmpz_mpoly_clear(q->c0 + i, q->s->zctx);
        fmpz_mpoly_clear(q->c1 + i, q->s->zctx);
    }
    flint_free(q->c0);
    flint_free(q->c1);
    flint_free(q->ne);
}

/* a = a0 + sqrt(d) a1 */
static void qd_split(fmpz_mpoly_t a0, fmpz_mpoly_t a1, const fmpz_mpoly_t a, const rs_scheme_struct *s)
{
    rs_charpoly_coeff(a0, a, 0, s->sqrt_var, s->zctx);
    rs_charpoly_coeff(a1, a, 1, s->sqrt_var, s->zctx);
}

static void mul_red(fmpz_mpoly_t r, const fmpz_mpoly_t a, const fmpz_mpoly_t b, const rs_scheme_struct *s)
{
    fmpz_mpoly_mul(r, a, b, s->zctx);
    rs_scheme_reduce_sqrt(r, s);
}

/* "c0 + sqrt(d)*(c1)" of a (reduced) */
static json_t *qd_json(const fmpz_mpoly_t a, const rs_scheme_struct *s)
{
    fmpz_mpoly_t a0, a1;
    json_t *j;
    fmpz_mpoly_init(a0, s->zctx);
    fmpz_mpoly_init(a1, s->zctx);
    qd_split(a0, a1, a, s);
    {
        char *str = rs_an_qd_mpoly_str(a0, a1, s, 1);
        j = json_string(str);
        flint_free(str);
    }
    fmpz_mpoly_clear(a0, s->zctx);
    fmpz_mpoly_clear(a1, s->zctx);
    return j;
}

/* f > 0 into the lists (see the top); returns 1 when nothing is left to
 * hold (always true), -1 when f is a constant <= 0 (never), else 0 */
static int qc_add(qc_t *q, json_t *conds, json_t *parts, json_t *dropped, const fmpz_mpoly_t f, const char *origin,
                  const int *sign)
{
    const rs_scheme_struct *s = q->s;
    fmpz_mpoly_t f0, f1, g, kept;
    fmpz_mpoly_factor_t fa;
    rs_qd_t cv;
    slong i, before = q->n;
    int neg = 0, ret = 0, pos = 0;
    fmpz_mpoly_init(f0, s->zctx); fmpz_mpoly_init(f1, s->zctx);
    fmpz_mpoly_init(g, s->zctx); fmpz_mpoly_init(kept, s->zctx);
    fmpz_mpoly_factor_init(fa, s->zctx);
    qd_split(f0, f1, f, s);
    fmpz_mpoly_one(kept, s->zctx);
    if (!fmpz_mpoly_is_zero(f, s->zctx) && fmpz_mpoly_gcd(g, f0, f1, s->zctx) && fmpz_mpoly_factor(fa, g, s->zctx)) {
        fmpz_mpoly_divexact(f0, f0, g, s->zctx);
        fmpz_mpoly_divexact(f1, f1, g, s->zctx);
        neg = fmpz_sgn(fa->constant) < 0;
        for (i = 0; i < fa->num; i++) {
            int sg = rs_hurwitz_sign(fa->poly + i, (const rs_sign_t *) sign, s->zctx);
            int odd = (int) (fmpz_get_si(fa->exp + i) & 1);
            if (sg != 0) {
                if (sg < 0 && odd) neg = !neg;
                json_array_append_new(dropped, json_pack("{s:o,s:s,s:s}", "factor", rs_json_factor(fa->poly + i, s),
                                                         "from", origin, "reason", "of one sign under the assumptions"));
            } else if (odd) {
                fmpz_mpoly_mul(kept, kept, fa->poly + i, s->zctx);
            } else {
                char *line = rs_cond_string(fa->poly + i, s, "!= 0");
                fmpz_mpoly_zero(g, s->zctx);
                rs_json_append_unique(conds, line);
                qc_push(q, fa->poly + i, g, 1);
                free(line);
            }
        }
        fmpz_mpoly_mul(f0, f0, kept, s->zctx);
        fmpz_mpoly_mul(f1, f1, kept, s->zctx);
        if (neg) {
            fmpz_mpoly_neg(f0, f0, s->zctx);
            fmpz_mpoly_neg(f1, f1, s->zctx);
        }
    }
    rs_qd_init(cv);
    if (fmpz_mpoly_is_fmpz(f0, s->zctx) && fmpz_mpoly_is_fmpz(f1, s->zctx)) {
        fmpz_mpoly_get_fmpz(fmpq_numref(cv->x), f0, s->zctx);
        fmpz_mpoly_get_fmpz(fmpq_numref(cv->y), f1, s->zctx);
        pos = rs_qd_sgn(cv, s->sqrt_d) > 0;
        ret = pos ? (q->n == before) : -1;
    }
    if (!pos) {
        char *p = rs_an_qd_mpoly_str(f0, f1, s, 1), *line = malloc(strlen(p) + 8);
        sprintf(line, "%s > 0", p);
        rs_json_append_unique(conds, line);
        json_array_append_new(parts, json_pack("{s:s,s:o,s:o,s:s}", "origin", origin, "c0", rs_json_zpoly(f0, s),
                                               "c1", rs_json_zpoly(f1, s), "rel", ">"));
        qc_push(q, f0, f1, 0);
        free(line);
        flint_free(p);
    }
    rs_qd_clear(cv);
    fmpz_mpoly_factor_clear(fa, s->zctx);
    fmpz_mpoly_clear(f0, s->zctx); fmpz_mpoly_clear(f1, s->zctx);
    fmpz_mpoly_clear(g, s->zctx); fmpz_mpoly_clear(kept, s->zctx);
    return ret;
}

/* the value of a (no lambda) at pt */
static void qd_part_at(fmpq_t v, const fmpz_mpoly_t a, fmpq *const *pt, const rs_scheme_struct *s)
{
    fmpq_poly_t e;
    fmpq_poly_init(e);
    rs_run_cx_eval(e, a, pt, s);
    fmpq_poly_get_coeff_fmpq(v, e, 0);
    fmpq_poly_clear(e);
}

/* 1 when every condition holds at pt (strict), else 0 */
static int qc_hold(const qc_t *q, fmpq *const *pt)
{
    rs_qd_t v;
    slong i;
    int ok = !q->never;
    rs_qd_init(v);
    for (i = 0; i < q->n && ok; i++) {
        int sg;
        qd_part_at(v->x, q->c0 + i, pt, q->s);
        qd_part_at(v->y, q->c1 + i, pt, q->s);
        sg = rs_qd_sgn(v, q->s->sqrt_d);
        ok = q->ne[i] ? sg != 0 : sg > 0;
    }
    rs_qd_clear(v);
    return ok;
}

/* the exact verdict at pt: 1 stable, 0 not (p's degree drops: singular),
 * -1 p vanishes there, -2 Schur-Cohn over Q(sqrt d) and the certified roots
 * disagree */
static int qd_point_stable(const fmpz_mpoly_t p0, const fmpz_mpoly_t p1, slong n, fmpq *const *pt,
                           const rs_scheme_struct *s)
{
    const fmpz_mpoly_struct *part[4] = {p0, p1, NULL, NULL};
    return rs_an_qd_parts_stable(part, n, pt, s);
}

#define QD_SAMPLE_POINTS 12

int rs_an_qd_conds_sample_check(rs_run_t *run, const rs_variant_t *v, const fmpz_mpoly_t a, const fmpz_mpoly_t b,
                                const fmpz_mpoly_struct *const *part, slong n, const qc_t *q, const qc_t *alt,
                                const char *field, const char *pair, const char *alt_method, json_t *o,
                                const rs_request_t *rq)
{
    rs_sample_pts_t P;
    slong nok = 0;
    json_t *chk = json_object(), *bad = NULL;
    int r = RS_OK;
    char *against = NULL;
    rs_sample_pts_init(&P, run, v, a, b, v->s->sqrt_var);
    while (nok < (P.nfree > 0 ? QD_SAMPLE_POINTS : 1) && r == RS_OK && bad == NULL && rs_sample_pts_next(&P)) {
        int says, st = rs_an_qd_parts_stable(part, n, P.pp, v->s);
        if (st == -1) continue;
        says = st == -2 ? 0 : qc_hold(q, P.pp);
        /* a second method's conditions must say the same */
        if (st == -2 || (alt != NULL && qc_hold(alt, P.pp) != says)) {
            char *msg = NULL;
            if (st == -2) rs_str_catf(&msg, "%s over %s: Schur-Cohn and the certified roots disagree at a sample "
                                      "point", rq->text, field);
            else rs_str_catf(&msg, "%s over %s: %s conditions disagree at a sample point", rq->text, field, pair);
            r = rs_req_error(run, rq, rq->text, RS_ERR_INCONSISTENT, "%s", msg);
            flint_free(msg);
            break;
        }
        nok++;
        if (st != says) {
            bad = rs_sample_pts_json(&P);
            rs_run_sample_disagree(chk, bad, says, st ? "stable" : "not stable");
        }
    }
    rs_str_catf(&against, "exact verdict over %s (Schur-Cohn with exact signs and the certified Arb roots, which "
                "must agree) at rational points satisfying the assumptions", field);
    rs_run_sample_check_set(run, o, chk, nok, bad == NULL, against);
    flint_free(against);
    if (alt != NULL)
        json_object_set_new(o, "cross_check", json_pack("{s:s,s:I,s:b}", "method", alt_method, "points",
                            (json_int_t) nok, "agree", r == RS_OK));
    rs_sample_pts_clear(&P);
    return r;
}

/* the shared start: the variant (set values substituted), p = p0 + sqrt(d)
 * p1, its lambda-coefficients a[0..n] (flint_free'd by qd_sym_clear) */
typedef struct {
    rs_variant_t *v;
    const rs_scheme_struct *s;
    slong n;
    fmpz_mpoly_t p0, p1;
    fmpz_mpoly_struct *a;
    int *sign;
    qc_t q;
    /* at complex set values (rs_an_qd_cx_cells): p = cx[0] + sqrt(d) cx[1]
     * + i (cx[2] + sqrt(d) cx[3]) and Bilharz's conditions alt; else NULL */
    const fmpz_mpoly_struct *const *cx;
    const qc_t *alt;
} qd_sym_t;

static int qd_sym_init(qd_sym_t *S, rs_run_t *run, const rs_an_req_t *req, rs_variant_t *v)
{
    const rs_scheme_struct *s;
    slong j;
    int r = RS_OK;
    S->v = v;
    if (v == NULL) r = rs_run_default_variant(run, &S->v);
    S->a = NULL;
    S->sign = NULL;
    S->cx = NULL;
    S->alt = NULL;
    if (r != RS_OK) return r;
    s = S->s = S->v->s;
    S->n = S->v->cp->degree;
    S->q.n = 0; S->q.c0 = S->q.c1 = NULL; S->q.ne = NULL; S->q.s = s; S->q.never = 0;
    fmpz_mpoly_init(S->p0, s->zctx);
    fmpz_mpoly_init(S->p1, s->zctx);
    qd_split(S->p0, S->p1, S->v->cp->p, s);
    S->a = flint_malloc((size_t) (S->n + 1) * sizeof(fmpz_mpoly_struct));
    for (j = 0; j <= S->n; j++) {
        fmpz_mpoly_init(S->a + j, s->zctx);
        rs_charpoly_coeff(S->a + j, S->v->cp->p, j, s->lambda_var, s->zctx);
    }
    S->sign = rs_run_signs(run, s);
    if (S->v->singular)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s: the leading coefficient of p vanishes at "
                            "the set values: the implicit step cannot be solved there", req->def->name);
    if (S->n < 1)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s: p has no root (degree 0 in lambda)",
                            req->def->name);
    return RS_OK;
}

static void qd_sym_clear(qd_sym_t *S, slong na)
{
    slong j;
    if (S->a == NULL) return;
    for (j = 0; j <= na; j++) fmpz_mpoly_clear(S->a + j, S->s->zctx);
    flint_free(S->a);
    flint_free(S->sign);
    qc_clear(&S->q);
    fmpz_mpoly_clear(S->p0, S->s->zctx);
    fmpz_mpoly_clear(S->p1, S->s->zctx);
}

/* the verdict, the sample check, the report */
static int qd_sym_finish(qd_sym_t *S, rs_run_t *run, const rs_an_req_t *req, json_t *o, json_t *conds,
                         json_t *parts, json_t *dropped, json_t *always, int never, const qc_t *alt)
{
    int r;
    char *why = NULL;
    /* a set that never holds under the assumptions (an_qd_never.c); the
     * sample check then expects no stable point */
    if (!never && S->q.n > 0 && rs_an_qd_conds_never(&why, run, &S->q)) {
        rs_str_catf(&why, "; never asymptotically stable");
        rs_json_set_never_conditions(o, why);
        never = S->q.never = 1;
    }
    flint_free(why);
    rs_an_qd_json_p(o, S->p0, S->p1, run);
    json_object_set_new(o, "degree", json_integer(S->n));
    json_object_set_new(o, "conditions", conds);
    json_object_set_new(o, "conditions_qd", parts);
    json_object_set_new(o, "dropped", dropped);
    json_object_set_new(o, "always_true", always);
    json_object_set_new(o, "verdict", json_string(never ? "never stable" : S->q.n == 0 ? "stable under the assumptions"
                                                  : "stable iff the conditions hold"));
    {
        const fmpz_mpoly_struct *part[4] = {S->p0, S->p1, NULL, NULL};
        r = rs_an_qd_conds_sample_check(run, S->v, S->p0, S->p1, part, S->n, &S->q, alt, "Q(sqrt d)",
                                        "the Routh and the Hurwitz", "hurwitz over Q(sqrt d): its conditions "
                                        "b_n^k D_k > 0 at the same sample points", o, req->q);
    }
    if (r == RS_OK) rs_run_emit_exact(run, S->v, o);
    else json_decref(o);
    return r;
}

/* a row's content in Z[params] divided out (both parts of every entry) */
static void qd_row_primitive(fmpz_mpoly_struct *b, slong m, const rs_scheme_struct *s)
{
    fmpz_mpoly_t g, h0, h1;
    slong j;
    fmpz_mpoly_init(g, s->zctx); fmpz_mpoly_init(h0, s->zctx); fmpz_mpoly_init(h1, s->zctx);
    for (j = 0; j < m; j++) {
        qd_split(h0, h1, b + j, s);
        if (!fmpz_mpoly_gcd(g, g, h0, s->zctx) || !fmpz_mpoly_gcd(g, g, h1, s->zctx)) {
            fmpz_mpoly_one(g, s->zctx);
            break;
        }
    }
    if (!fmpz_mpoly_is_zero(g, s->zctx) && !fmpz_mpoly_is_one(g, s->zctx))
        for (j = 0; j < m; j++) fmpz_mpoly_divexact(b + j, b + j, g, s->zctx);
    fmpz_mpoly_clear(g, s->zctx); fmpz_mpoly_clear(h0, s->zctx); fmpz_mpoly_clear(h1, s->zctx);
}

static int too_big(const fmpz_mpoly_t f, rs_run_t *run, const rs_scheme_struct *s, const char *what)
{
    if (fmpz_mpoly_length(f, s->zctx) <= RS_CHARPOLY_MAX_TERMS) return RS_OK;
    return rs_error_set(run->err, RS_ERR_LIMIT, "%s over Q(sqrt d): a condition has over %ld terms (limit)", what,
                        (long) RS_CHARPOLY_MAX_TERMS);
}

/* the Schur-Cohn table of S's p: its rows, the conditions delta_k > 0 into
 * S->q and the lists; *na: the last index of S->a still initialised */
static int qd_jury_table(qd_sym_t *S, rs_run_t *run, json_t *rows, json_t *conds, json_t *parts, json_t *dropped,
                         json_t *always, int *never, slong *na)
{
    const rs_scheme_struct *s = S->s;
    fmpz_mpoly_t t, u, delta;
    slong k, j;
    int r = RS_OK;
    *na = S->n;
    fmpz_mpoly_init(t, s->zctx); fmpz_mpoly_init(u, s->zctx); fmpz_mpoly_init(delta, s->zctx);
    for (k = S->n; k >= 1 && r == RS_OK; k--) {
        json_t *row = json_array();
        char origin[32];
        fmpz_mpoly_struct *b;
        for (j = 0; j <= k; j++) json_array_append_new(row, qd_json(S->a + j, s));
        json_array_append_new(rows, row);
        mul_red(t, S->a + k, S->a + k, s);
        mul_red(u, S->a + 0, S->a + 0, s);
        fmpz_mpoly_sub(delta, t, u, s->zctx);
        r = too_big(delta, run, s, "jury");
        if (r == RS_OK) r = rs_budget_check(run->err, "the symbolic Schur-Cohn table over Q(sqrt d)");
        if (r != RS_OK) break;
        snprintf(origin, sizeof origin, "delta_%ld", (long) k);
        j = qc_add(&S->q, conds, parts, dropped, delta, origin, S->sign);
        if (j == 1) json_array_append_new(always, json_string(origin));
        if (j == -1) *never = 1;
        if (fmpz_mpoly_is_zero(delta, s->zctx)) break;   /* the recursion stops there */
        /* p_(k-1): coefficient j = a_k a_(j+1) - a_0 a_(k-1-j), j = 0..k-1 */
        b = flint_malloc((size_t) k * sizeof(fmpz_mpoly_struct));
        for (j = 0; j < k; j++) {
            fmpz_mpoly_init(b + j, s->zctx);
            mul_red(t, S->a + k, S->a + j + 1, s);
            mul_red(u, S->a + 0, S->a + k - 1 - j, s);
            fmpz_mpoly_sub(b + j, t, u, s->zctx);
        }
        qd_row_primitive(b, k, s);
        for (j = 0; j <= k; j++) fmpz_mpoly_clear(S->a + j, s->zctx);
        for (j = 0; j < k; j++) S->a[j] = b[j];
        flint_free(b);
        *na = k - 1;
    }
    fmpz_mpoly_clear(t, s->zctx); fmpz_mpoly_clear(u, s->zctx); fmpz_mpoly_clear(delta, s->zctx);
    return r;
}

static const char qd_jury_note[] =
    "Schur-Cohn reduction over Q(sqrt d)[params] without divisions, p_{k-1} = (lead p_k * p_k - p_k(0) p_k*)/"
    "lambda with sqrt(d)^2 = d after every product, each row divided by its content in Z[params]: all |lambda| "
    "< 1 iff every delta_k = lead^2 - const^2 > 0 (Schur 1917; sqrt(d) is real; strict inequalities, exact for "
    "every value; c0 + sqrt(d)*(c1) > 0 is decided exactly by comparing c0^2 with d*c1^2)";

int rs_an_qd_jury(rs_run_t *run, const rs_an_req_t *req)
{
    qd_sym_t S;
    json_t *o, *rows = json_array(), *conds = json_array(), *parts = json_array(), *dropped = json_array(),
           *always = json_array();
    slong na = -1;
    int r = qd_sym_init(&S, run, req, NULL), never = 0;
    if (r == RS_OK) r = qd_jury_table(&S, run, rows, conds, parts, dropped, always, &never, &na);
    else na = S.a != NULL ? S.n : -1;
    if (r != RS_OK) {
        json_decref(rows); json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
        qd_sym_clear(&S, na);
        return r;
    }
    o = json_object();
    json_object_set_new(o, "analysis", json_string("jury"));
    json_object_set_new(o, "method", json_string("Schur-Cohn (Jury) table over Q(sqrt d), symbolic"));
    json_object_set_new(o, "symbolic", json_true());
    json_object_set_new(o, "rows", rows);
    json_object_set_new(o, "note", json_string(qd_jury_note));
    r = qd_sym_finish(&S, run, req, o, conds, parts, dropped, always, never, NULL);
    qd_sym_clear(&S, na);
    return r;
}

/* det of the k x k matrix m[rows][cols] (row-major, stride w) by cofactor
 * expansion along the first row, reduced by sqrt(d)^2 = d; k <= 8 */
static void qd_det(fmpz_mpoly_t d, const fmpz_mpoly_struct *m, slong w, const slong *rows, const slong *cols,
                   slong k, const rs_scheme_struct *s)
{
    fmpz_mpoly_t minor, t;
    slong sub[8], c, j, i;
    if (k == 1) {
        fmpz_mpoly_set(d, m + rows[0] * w + cols[0], s->zctx);
        return;
    }
    fmpz_mpoly_init(minor, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    fmpz_mpoly_zero(d, s->zctx);
    for (c = 0; c < k; c++) {
        const fmpz_mpoly_struct *e = m + rows[0] * w + cols[c];
        if (fmpz_mpoly_is_zero(e, s->zctx)) continue;
        for (j = 0, i = 0; j < k; j++)
            if (j != c) sub[i++] = cols[j];
        qd_det(minor, m, w, rows + 1, sub, k - 1, s);
        mul_red(t, e, minor, s);
        if (c & 1) fmpz_mpoly_sub(d, d, t, s->zctx);
        else fmpz_mpoly_add(d, d, t, s->zctx);
    }
    fmpz_mpoly_clear(minor, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
}

/* q(z) = sum_j a_j (z + 1)^j (z - 1)^(n - j), z in lambda's place (S's
 * a_j have sqrt(d) at most linearly, so q has too) */
static void qd_bilinear(fmpz_mpoly_t qz, const qd_sym_t *S)
{
    const rs_scheme_struct *s = S->s;
    fmpz_mpoly_t zp, zm, t, u;
    slong j;
    fmpz_mpoly_init(zp, s->zctx); fmpz_mpoly_init(zm, s->zctx);
    fmpz_mpoly_init(t, s->zctx); fmpz_mpoly_init(u, s->zctx);
    fmpz_mpoly_zero(qz, s->zctx);
    fmpz_mpoly_gen(zp, s->lambda_var, s->zctx);
    fmpz_mpoly_add_si(zp, zp, 1, s->zctx);
    fmpz_mpoly_gen(zm, s->lambda_var, s->zctx);
    fmpz_mpoly_sub_si(zm, zm, 1, s->zctx);
    for (j = 0; j <= S->n; j++) {
        fmpz_mpoly_pow_ui(t, zp, (ulong) j, s->zctx);
        fmpz_mpoly_pow_ui(u, zm, (ulong) (S->n - j), s->zctx);
        fmpz_mpoly_mul(t, t, u, s->zctx);
        fmpz_mpoly_mul(t, t, S->a + j, s->zctx);
        fmpz_mpoly_add(qz, qz, t, s->zctx);
    }
    fmpz_mpoly_clear(zp, s->zctx); fmpz_mpoly_clear(zm, s->zctx);
    fmpz_mpoly_clear(t, s->zctx); fmpz_mpoly_clear(u, s->zctx);
}

/* the Hurwitz minors of S's q into minors and the conditions b_n^k D_k > 0
 * into S->q and the lists (hurwitz; routh's cross-check) */
static int qd_hurwitz_conds(qd_sym_t *S, rs_run_t *run, json_t *minors, json_t *conds, json_t *parts,
                            json_t *dropped, json_t *always, int *never)
{
    const rs_scheme_struct *s = S->s;
    fmpz_mpoly_t qz, t, dk;
    fmpz_mpoly_struct *b, *H;
    slong n = S->n, k, j, idx[8];
    int r = RS_OK;
    fmpz_mpoly_init(qz, s->zctx); fmpz_mpoly_init(t, s->zctx); fmpz_mpoly_init(dk, s->zctx);
    qd_bilinear(qz, S);
    b = flint_malloc((size_t) (n + 1) * sizeof(fmpz_mpoly_struct));
    for (j = 0; j <= n; j++) {
        fmpz_mpoly_init(b + j, s->zctx);
        rs_charpoly_coeff(b + j, qz, j, s->lambda_var, s->zctx);
    }
    /* Hurwitz matrix H_(r,c) = a_(2c - r + 1) (0-based) with a_i = b_(n - i) */
    H = flint_malloc((size_t) (n * n) * sizeof(fmpz_mpoly_struct));
    for (j = 0; j < n * n; j++) {
        slong i = 2 * (j % n) - j / n + 1;
        fmpz_mpoly_init(H + j, s->zctx);
        if (i >= 0 && i <= n) fmpz_mpoly_set(H + j, b + n - i, s->zctx);
    }
    for (j = 0; j < n; j++) idx[j] = j;
    for (k = 1; k <= n && r == RS_OK; k++) {
        char origin[40];
        int a;
        qd_det(dk, H, n, idx, idx, k, s);
        json_array_append_new(minors, qd_json(dk, s));
        r = rs_budget_check(run->err, "the Hurwitz minors over Q(sqrt d)");
        if (r != RS_OK) break;
        /* b_n^k D_k > 0; the last as b_n b_0 > 0 (D_n = b_0 D_(n-1)) */
        if (k == n) {
            mul_red(t, b + n, b + 0, s);
            snprintf(origin, sizeof origin, "b_%ld*b_0", (long) n);
        } else if (k & 1) {
            mul_red(t, b + n, dk, s);
            snprintf(origin, sizeof origin, "b_%ld*D_%ld", (long) n, (long) k);
        } else {
            fmpz_mpoly_set(t, dk, s->zctx);
            snprintf(origin, sizeof origin, "D_%ld", (long) k);
        }
        r = too_big(t, run, s, "hurwitz");
        if (r != RS_OK) break;
        a = qc_add(&S->q, conds, parts, dropped, t, origin, S->sign);
        if (a == 1) json_array_append_new(always, json_string(origin));
        if (a == -1) *never = 1;
    }
    for (j = 0; j < n * n; j++) fmpz_mpoly_clear(H + j, s->zctx);
    for (j = 0; j <= n; j++) fmpz_mpoly_clear(b + j, s->zctx);
    flint_free(H);
    flint_free(b);
    fmpz_mpoly_clear(qz, s->zctx); fmpz_mpoly_clear(t, s->zctx); fmpz_mpoly_clear(dk, s->zctx);
    return r;
}

/* "p_at_1", "p_at_minus_1" */
static void qd_p_at_pm1(json_t *o, const qd_sym_t *S)
{
    const rs_scheme_struct *s = S->s;
    fmpz_mpoly_t t;
    slong k;
    fmpz_mpoly_init(t, s->zctx);
    for (k = 1; k >= -1; k -= 2) {
        fmpz_t x;
        fmpz_init_set_si(x, k);
        fmpz_mpoly_evaluate_one_fmpz(t, S->v->cp->p, s->lambda_var, x, s->zctx);
        json_object_set_new(o, k == 1 ? "p_at_1" : "p_at_minus_1", qd_json(t, s));
        fmpz_clear(x);
    }
    fmpz_mpoly_clear(t, s->zctx);
}

int rs_an_qd_hurwitz(rs_run_t *run, const rs_an_req_t *req)
{
    qd_sym_t S;
    json_t *o, *minors, *conds, *parts, *dropped, *always;
    int r = qd_sym_init(&S, run, req, NULL), never = 0;
    if (r == RS_OK && S.n > 8)
        r = rs_req_error(run, req->q, req->q->text, RS_ERR_LIMIT, "hurwitz over Q(sqrt d): degree over 8 in lambda "
                         "(the minors are expanded up to degree 8; jury answers the same question)%s", "");
    if (r != RS_OK) {
        qd_sym_clear(&S, S.a != NULL ? S.n : -1);
        return r;
    }
    o = json_object();
    minors = json_array(); conds = json_array(); parts = json_array(); dropped = json_array(); always = json_array();
    r = qd_hurwitz_conds(&S, run, minors, conds, parts, dropped, always, &never);
    json_object_set_new(o, "analysis", json_string("hurwitz"));
    json_object_set_new(o, "var", json_string("z"));
    json_object_set_new(o, "method", json_string(
        "Hurwitz minors over Q(sqrt d) of q(z) = (z - 1)^n p((z + 1)/(z - 1)) = b_n z^n + ... + b_0 (cofactor "
        "expansion, sqrt(d)^2 = d after every product): every |lambda| < 1 iff every root of q has Re z < 0 iff "
        "b_n^k D_k > 0 for k = 1..n (Hurwitz; D_k(-q) = (-1)^k D_k(q)), the last as b_n b_0 > 0 since D_n = b_0 "
        "D_(n-1)"));
    json_object_set_new(o, "minors", minors);
    json_object_set_new(o, "nonzero", json_array());
    qd_p_at_pm1(o, &S);
    if (r == RS_OK) r = qd_sym_finish(&S, run, req, o, conds, parts, dropped, always, never, NULL);
    else {
        json_decref(o); json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
    }
    qd_sym_clear(&S, S.n);
    return r;
}

/* routh over Q(sqrt d)[params]: the fraction-free Routh array of q
 * (rs_routh_mpoly with sqrt(d) one more variable: its exact divisions are
 * identities in the coefficients, so they stay exact; each entry reduced by
 * sqrt(d)^2 = d only for the report).  First column f_0 = r_0, f_k = r_1 ...
 * r_k (r the textbook column): every root of q in Re z < 0 iff every r_k has
 * r_0's sign, i.e. f_0 f_k > 0 (k odd), f_k > 0 (k even) -- the conditions,
 * checked at the sample points against the exact point verdict and against
 * Hurwitz's conditions b_n^k D_k > 0 (exit 3 on a disagreement). */
int rs_an_qd_routh(rs_run_t *run, const rs_an_req_t *req)
{
    qd_sym_t S, Hs;
    const rs_scheme_struct *s;
    rs_routh_mpoly_t rm;
    fmpz_mpoly_t qz, t, f0;
    json_t *o = NULL, *rows = NULL, *col, *conds, *parts, *dropped, *always;
    slong i, j;
    int r = qd_sym_init(&S, run, req, NULL), never = 0, hnever = 0;
    Hs.a = NULL;
    if (r == RS_OK && S.n > 8)
        r = rs_req_error(run, req->q, req->q->text, RS_ERR_LIMIT, "routh over Q(sqrt d): degree over 8 in lambda "
                         "(its Hurwitz cross-check expands the minors up to degree 8; jury answers the same "
                         "question)%s", "");
    if (r != RS_OK) {
        qd_sym_clear(&S, S.a != NULL ? S.n : -1);
        return r;
    }
    s = S.s;
    fmpz_mpoly_init(qz, s->zctx); fmpz_mpoly_init(t, s->zctx); fmpz_mpoly_init(f0, s->zctx);
    conds = json_array(); parts = json_array(); dropped = json_array(); always = json_array();
    col = json_array();
    qd_bilinear(qz, &S);
    rs_routh_mpoly_init(rm);
    r = rs_routh_mpoly(rm, qz, s->lambda_var, s->zctx, run->err);
    if (r == RS_ERR_MATH)
        r = rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "routh over Q(sqrt d): a pivot of the Routh array "
                         "vanishes for every parameter value; hurwitz and jury over Q(sqrt d) answer the same question "
                         "(%s)", "set the parameters for stability at a point");
    else if (r != RS_OK) r = rs_req_relocate(run, req->q, r, "routh");
    if (r == RS_OK && rm->zero_row >= 0)
        r = rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "routh over Q(sqrt d): row %s vanishes identically "
                         "(roots symmetric about z = 0 for every value: never asymptotically stable); hurwitz and jury "
                         "over Q(sqrt d) run on this case", "of the array");
    if (r == RS_OK) {
        rows = json_array();
        for (i = 0; i < rm->nrows && r == RS_OK; i++) {
            json_t *row = json_array();
            for (j = 0; j < rm->rowlen[i]; j++) {
                fmpz_mpoly_set(t, rm->rows[i] + j, s->zctx);
                rs_scheme_reduce_sqrt(t, s);
                json_array_append_new(row, qd_json(t, s));
                if (j > 0) continue;
                json_array_append_new(col, qd_json(t, s));
                if (fmpz_mpoly_is_zero(t, s->zctx))
                    r = rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "routh over Q(sqrt d): a first-column "
                                     "entry is 0 for every parameter value once sqrt(d)^2 = d; hurwitz and jury over "
                                     "Q(sqrt d) answer the same question%s", "");
            }
            json_array_append_new(rows, row);
            if (r != RS_OK) break;
            if (i == 0) { fmpz_mpoly_set(f0, t, s->zctx); continue; }
            /* f_0 f_k > 0 (k odd), f_k > 0 (k even) */
            {
                char origin[40];
                int a;
                fmpz_mpoly_set(t, rm->rows[i], s->zctx);
                rs_scheme_reduce_sqrt(t, s);
                if (i & 1) mul_red(t, f0, t, s);
                snprintf(origin, sizeof origin, i & 1 ? "f_0*f_%ld" : "f_%ld", (long) i);
                r = too_big(t, run, s, "routh");
                if (r != RS_OK) break;
                a = qc_add(&S.q, conds, parts, dropped, t, origin, S.sign);
                if (a == 1) json_array_append_new(always, json_string(origin));
                if (a == -1) never = 1;
            }
        }
    }
    if (r == RS_OK) {
        /* the second method: Hurwitz's conditions on the same p */
        json_t *m = json_array(), *c2 = json_array(), *p2 = json_array(), *d2 = json_array(), *a2 = json_array();
        r = qd_sym_init(&Hs, run, req, S.v);
        if (r == RS_OK) r = qd_hurwitz_conds(&Hs, run, m, c2, p2, d2, a2, &hnever);
        json_decref(m); json_decref(c2); json_decref(p2); json_decref(d2); json_decref(a2);
    }
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("routh"));
        json_object_set_new(o, "var", json_string("z"));
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "rows", rows);
        rows = NULL;
        json_object_set_new(o, "first_column", col);
        col = NULL;
        json_object_set_new(o, "note", json_string(
            "fraction-free rows over Q(sqrt d)[params] of q(z) = (z - 1)^n p((z + 1)/(z - 1)) (each divided exactly "
            "by the pivot three rows up, sqrt(d) kept as a variable there, then sqrt(d)^2 = d): first column "
            "f_0 = r_0, f_k = r_1 r_2 ... r_k (r the textbook column); all roots have Re z < 0 iff every r_k has the "
            "sign of r_0, i.e. f_0 f_k > 0 (k odd) and f_k > 0 (k even), the conditions"));
        qd_p_at_pm1(o, &S);
        r = qd_sym_finish(&S, run, req, o, conds, parts, dropped, always, never, &Hs.q);
        conds = parts = dropped = always = NULL;
    }
    json_decref(rows); json_decref(col);
    json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
    rs_routh_mpoly_clear(rm, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx); fmpz_mpoly_clear(t, s->zctx); fmpz_mpoly_clear(f0, s->zctx);
    if (Hs.a != NULL) qd_sym_clear(&Hs, Hs.n);
    qd_sym_clear(&S, S.n);
    return r;
}

/* ---- region NAME over Q(sqrt d) ---------------------------------------------- */

/* f (only variable tv: region's cells) as a polynomial in t */
static void qd_upoly1(fmpq_poly_t out, const fmpz_mpoly_t f, slong tv, const rs_scheme_struct *s)
{
    fmpz_poly_t u;
    fmpz_poly_init(u);
    if (!fmpz_mpoly_get_fmpz_poly(u, f, tv, s->zctx)) fmpz_poly_zero(u);   /* not reached: no other variable */
    fmpq_poly_set_fmpz_poly(out, u);
    fmpz_poly_clear(u);
}

/* c0 + sqrt(d) c1 (only variable tv) as p0 + sqrt(d) p1 in Q[t] */
static void qd_upoly(rs_qdpoly_t out, const fmpz_mpoly_t c0, const fmpz_mpoly_t c1, slong tv,
                     const rs_scheme_struct *s)
{
    qd_upoly1(out->p0, c0, tv, s);
    qd_upoly1(out->p1, c1, tv, s);
}

/* the real roots of u's norm p0^2 - d p1^2 (every real root of u is one of
 * them) appended to the critical values */
static void qd_norm_roots(rs_alg_t **crit, slong *ncrit, const rs_qdpoly_t u, slong d)
{
    fmpq_poly_t nq;
    fmpz_poly_t nz;
    fmpq_poly_init(nq);
    fmpz_poly_init(nz);
    rs_qdpoly_norm(nq, u, d);
    fmpq_poly_get_numerator(nz, nq);
    rs_alg_roots_append(crit, ncrit, nz, 1);
    fmpq_poly_clear(nq);
    fmpz_poly_clear(nz);
}

/* the exact sign of u(t0) = p0(t0) + sqrt(d) p1(t0): the signs of p0, p1 at
 * t0 in Q(t0) = Q[t]/(minpoly) and, where they differ, the sign of the norm */
static int qd_alg_sign(const rs_qdpoly_t u, slong d, rs_alg_t *t0)
{
    fmpq_poly_t m, x;
    int s0, s1, sn;
    fmpq_poly_init(m); fmpq_poly_init(x);
    fmpq_poly_set_fmpz_poly(m, t0->minpoly);
    fmpq_poly_rem(x, u->p0, m); s0 = rs_alg_sign(x, t0);
    fmpq_poly_rem(x, u->p1, m); s1 = rs_alg_sign(x, t0);
    rs_qdpoly_norm(x, u, d);
    fmpq_poly_rem(x, x, m); sn = rs_alg_sign(x, t0);
    fmpq_poly_clear(m); fmpq_poly_clear(x);
    if (s1 == 0 || s0 == s1) return s0 != 0 ? s0 : s1;
    if (s0 == 0) return s1;
    return sn > 0 ? s0 : sn < 0 ? s1 : 0;   /* sn = 0: p0 = -sqrt(d) p1 exactly */
}

/* a cell of the line: a critical value (pt) or the open interval after it */
typedef struct {
    const char *status;
    int pt;
    rs_alg_t *lo, *hi;   /* NULL: infinite */
} qd_cell_t;

static json_t *qd_end_json(rs_alg_t *a, const char *var)
{
    return a == NULL ? json_null() : rs_alg_json(a, var);
}

static json_t *qd_end_approx(rs_alg_t *a)
{
    return a == NULL ? json_null() : json_real(rs_alg_double(a));
}

json_t *rs_an_qd_interval_json(rs_alg_t *lo, rs_alg_t *hi, int lo_closed, int hi_closed, const char *status,
                               const char *name)
{
    json_t *iv = json_object();
    json_object_set_new(iv, "lo", qd_end_json(lo, name));
    json_object_set_new(iv, "hi", qd_end_json(hi, name));
    json_object_set_new(iv, "lo_closed", json_boolean(lo_closed));
    json_object_set_new(iv, "hi_closed", json_boolean(hi_closed));
    json_object_set_new(iv, "status", json_string(status));
    json_object_set_new(iv, "lo_approx", qd_end_approx(lo));
    json_object_set_new(iv, "hi_approx", qd_end_approx(hi));
    return iv;
}

/* e := the rational q as a critical value */
static void qd_alg_set_fmpq(rs_alg_t *e, const fmpq_t q)
{
    fmpz_t c;
    fmpz_init(c);
    fmpz_neg(c, fmpq_numref(q));
    fmpz_poly_zero(e->minpoly);
    fmpz_poly_set_coeff_fmpz(e->minpoly, 1, fmpq_denref(q));
    fmpz_poly_set_coeff_fmpz(e->minpoly, 0, c);
    e->rational = 1;
    fmpq_set(e->q, q);
    e->prec = 0;
    rs_alg_refine(e, 128);
    fmpz_clear(c);
}

/* the critical value a inside the domain b (its ends by their closedness) */
static int qd_alg_in_bound(const rs_bound_t *b, rs_alg_t *a)
{
    rs_alg_t e;
    int in = 1;
    if (a->rational) return rs_bound_contains(b, a->q);
    rs_alg_init(&e);
    if (b->has_lo) {
        qd_alg_set_fmpq(&e, b->lo);
        in = rs_alg_cmp(a, &e) > 0;
    }
    if (b->has_hi && in) {
        qd_alg_set_fmpq(&e, b->hi);
        in = rs_alg_cmp(a, &e) < 0;
    }
    rs_alg_clear(&e);
    return in;
}

/* c_j (j <= n, initialised to 0) := p's lambda^j coefficient at tv = T,
 * qv = Q (qv < 0: p has no other parameter), sqrt(d) = R, elements of
 * Q[x]/(m) */
static void qd_coeffs_at(fmpq_poly_struct *c, const qd_sym_t *S, slong tv, const fmpq_poly_t T, slong qv,
                         const fmpq_poly_t Q, const fmpq_poly_t R, const fmpq_poly_t m)
{
    const rs_scheme_struct *s = S->s;
    fmpz_mpoly_t a, b;
    fmpq_poly_t x, y, qk;
    slong j, k, dq;
    int h;
    fmpz_mpoly_init(a, s->zctx); fmpz_mpoly_init(b, s->zctx);
    fmpq_poly_init(x); fmpq_poly_init(y); fmpq_poly_init(qk);
    for (j = 0; j <= S->n; j++)
        for (h = 0; h < 2; h++) {
            /* c_j += sum_k (p_h's lambda^j q^k coefficient)(T) Q^k R^h */
            rs_charpoly_coeff(a, h ? S->p1 : S->p0, j, s->lambda_var, s->zctx);
            dq = qv < 0 ? 0 : FLINT_MAX(fmpz_mpoly_degree_si(a, qv, s->zctx), 0);
            fmpq_poly_one(qk);
            for (k = 0; k <= dq; k++) {
                if (qv < 0) fmpz_mpoly_set(b, a, s->zctx);
                else rs_charpoly_coeff(b, a, k, qv, s->zctx);
                qd_upoly1(x, b, tv, s);
                fmpq_poly_compose(y, x, T);
                fmpq_poly_mul(y, y, qk);
                if (h) fmpq_poly_mul(y, y, R);
                fmpq_poly_rem(y, y, m);
                fmpq_poly_add(c + j, c + j, y);
                if (qv >= 0) { fmpq_poly_mul(qk, qk, Q); fmpq_poly_rem(qk, qk, m); }
            }
        }
    fmpq_poly_rem(c + S->n, c + S->n, m);
    fmpz_mpoly_clear(a, s->zctx); fmpz_mpoly_clear(b, s->zctx);
    fmpq_poly_clear(x); fmpq_poly_clear(y); fmpq_poly_clear(qk);
}

/* The exact status of p at tv = t0 (rational or not) over Q(t0, sqrt d) =
 * Q(gamma), gamma a primitive element (rs_alg_primitive), by the real
 * route of region (rs_alg_status_coeffs: Schur-Cohn and the circle's roots
 * in Q(gamma)); 0 when undecided there */
static int qd_exact_status(rs_status_t *st, const qd_sym_t *S, slong tv, rs_alg_t *t0)
{
    const rs_scheme_struct *s = S->s;
    rs_alg_t sq, g;
    fmpq_poly_t A, B, m, x, y;
    fmpq_poly_struct *c;
    fmpz_mpoly_t a;
    slong j, n = S->n;
    int decided = 0;
    if (S->cx != NULL) return 0;   /* the real route only: complex cells are decided by the two condition lists */
    rs_alg_init(&sq); rs_alg_init(&g);
    fmpq_poly_init(A); fmpq_poly_init(B); fmpq_poly_init(m); fmpq_poly_init(x); fmpq_poly_init(y);
    fmpz_mpoly_init(a, s->zctx);
    /* sqrt(d): the positive root of t^2 - d */
    fmpz_poly_set_coeff_si(sq.minpoly, 2, 1);
    fmpz_poly_set_coeff_si(sq.minpoly, 0, -s->sqrt_d);
    sq.idx = 1;
    rs_alg_refine(&sq, 128);
    c = flint_malloc((size_t) (n + 1) * sizeof(fmpq_poly_struct));
    for (j = 0; j <= n; j++) fmpq_poly_init(c + j);
    if (rs_alg_primitive(&g, A, B, t0, &sq)) {
        fmpq_poly_set_fmpz_poly(m, g.minpoly);
        qd_coeffs_at(c, S, tv, A, -1, NULL, B, m);
        decided = fmpq_poly_is_zero(c + n) ? (*st = RS_STATUS_SINGULAR, 1) : rs_alg_status_coeffs(st, c, n, &g, s);
    }
    for (j = 0; j <= n; j++) fmpq_poly_clear(c + j);
    flint_free(c);
    rs_alg_clear(&sq); rs_alg_clear(&g);
    fmpq_poly_clear(A); fmpq_poly_clear(B); fmpq_poly_clear(m); fmpq_poly_clear(x); fmpq_poly_clear(y);
    fmpz_mpoly_clear(a, s->zctx);
    return decided;
}

/* the status at the rational t: the exact point verdict over Q(sqrt d)
 * (Schur-Cohn and the certified roots), the conditions and the route over
 * Q(sqrt d) = Q(gamma) of qd_exact_status, which must agree (*bad) */
static const char *qd_status_at(int *bad, qd_sym_t *S, fmpq **pp, slong tv, const fmpq_t t)
{
    rs_alg_t e;
    rs_status_t ex = RS_STATUS_UNSTABLE;
    int st, says, decided;
    fmpq_set(pp[tv], t);
    if (S->cx != NULL) {
        /* over Q(sqrt d)(i): Schur-Cohn's and Bilharz's conditions and the point verdict */
        st = rs_an_qd_parts_verdict(S->cx, S->n, pp, S->s);
        says = qc_hold(&S->q, pp);
        *bad = st == -2 || qc_hold(S->alt, pp) != says || (st >= -1 && (st == 1) != says) || (st < -2 && says);
        return st < -2 ? "singular" : st == 1 ? "stable" : st == 0 ? "unstable" : "not stable";
    }
    st = qd_point_stable(S->p0, S->p1, S->n, pp, S->s);
    says = qc_hold(&S->q, pp);
    rs_alg_init(&e);
    qd_alg_set_fmpq(&e, t);
    decided = qd_exact_status(&ex, S, tv, &e);
    rs_alg_clear(&e);
    *bad = st == -2 || (st >= 0 && st != says) || (decided && (ex == RS_STATUS_STABLE) != (st == 1));
    if (st == -1) return "singular";   /* p vanishes identically there */
    if (!decided) return st == 1 ? "stable" : "not stable";
    return rs_status_name(ex);
}

/* The line of tv cut at the real roots of the conditions' norms, of the
 * leading coefficient's norm and at the domain's ends; each open cell
 * decided at a rational sample twice (conditions and point verdict), each
 * critical value by the conditions' exact signs in Q(t0, sqrt d) (and twice
 * when rational); equal neighbours merged into the intervals */
/* kind >= 0 (a claim: 0 stable, 1 bounded, 2 unstable, on the domain dom):
 * *verdict 1 every cell satisfies it, -1 one does not (*counter its point:
 * a rational sample, or an algebraic critical value), 0 undecided ("not
 * stable" cells); the intervals go to o's "region" */
static int qd_region_cells(json_t *o, qd_sym_t *S, rs_run_t *run, const rs_request_t *rq, slong tv,
                           const fmpz_mpoly_t lead, const rs_bound_t *dom, int kind, int *verdict, json_t **counter)
{
    const rs_scheme_struct *s = S->s;
    const char *name = run->c->params[tv].name;
    rs_bound_t *bd = rs_run_bounds(run);
    rs_alg_t *crit = NULL;
    qd_cell_t *cell;
    slong nalt = S->alt != NULL ? S->alt->n : 0;
    rs_qdpoly_struct *cu = flint_malloc((size_t) (S->q.n + nalt + 1) * sizeof(rs_qdpoly_struct));
    rs_qdpoly_t lu;
    fmpz_poly_t nz;
    fmpz_mpoly_t h0, h1;
    fmpq *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
    fmpq_t t;
    fmpq *samp;
    json_t *ivs = json_array();
    slong ncrit = 0, m, i, k, ncell = 0, checked = 0;
    int r = RS_OK, bad = 0;
    fmpz_poly_init(nz);
    rs_qdpoly_init(lu);
    fmpz_mpoly_init(h0, s->zctx); fmpz_mpoly_init(h1, s->zctx);
    fmpq_init(t);
    for (k = 0; k < s->nvars; k++) pp[k] = pt + k;
    rs_error_init(run->err);
    if (dom != NULL) {   /* the claim's set (with the assumptions already in it) */
        bd[tv].has_lo = dom->has_lo; bd[tv].has_hi = dom->has_hi;
        bd[tv].lo_closed = dom->lo_closed; bd[tv].hi_closed = dom->hi_closed;
        fmpq_set(bd[tv].lo, dom->lo); fmpq_set(bd[tv].hi, dom->hi);
    }
    if (verdict != NULL) *verdict = 1;
    if (counter != NULL) *counter = NULL;
    /* the critical polynomials: the conditions (in t once, for the signs
     * at the critical values too) and the leading coefficient */
    for (i = 0; i < S->q.n + nalt; i++) {
        const qc_t *q = i < S->q.n ? &S->q : S->alt;
        slong j = i < S->q.n ? i : i - S->q.n;
        rs_qdpoly_init(cu + i);
        qd_upoly(cu + i, q->c0 + j, q->c1 + j, tv, s);
        qd_norm_roots(&crit, &ncrit, cu + i, s->sqrt_d);
    }
    qd_split(h0, h1, lead, s);
    qd_upoly(lu, h0, h1, tv, s);
    qd_norm_roots(&crit, &ncrit, lu, s->sqrt_d);
    for (k = 0; k < 2; k++) {
        int has = k == 0 ? bd[tv].has_lo : bd[tv].has_hi;
        const fmpq *e = k == 0 ? bd[tv].lo : bd[tv].hi;
        if (!has) continue;
        fmpz_poly_zero(nz);   /* den*t - num */
        fmpz_poly_set_coeff_fmpz(nz, 0, fmpq_numref(e));
        fmpz_poly_neg(nz, nz);
        fmpz_poly_set_coeff_fmpz(nz, 1, fmpq_denref(e));
        rs_alg_roots_append(&crit, &ncrit, nz, 1);
    }
    rs_alg_sort(crit, ncrit);
    for (i = m = 0; i < ncrit; i++) {   /* each value once */
        if (m > 0 && rs_alg_cmp(crit + m - 1, crit + i) == 0) { rs_alg_clear(crit + i); continue; }
        if (m != i) crit[m] = crit[i];
        m++;
    }
    ncrit = m;
    cell = flint_malloc((size_t) (2 * ncrit + 1) * sizeof(qd_cell_t));
    samp = _fmpq_vec_init(2 * ncrit + 1);
    for (i = 0; i <= ncrit && r == RS_OK && !bad; i++) {
        rs_alg_t *lo = i > 0 ? crit + i - 1 : NULL, *hi = i < ncrit ? crit + i : NULL;
        r = rs_budget_check(run->err, "region over Q(sqrt d)");
        if (r != RS_OK) break;
        rs_alg_between(t, lo, hi);
        if (rs_bound_contains(bd + tv, t)) {
            cell[ncell].pt = 0; cell[ncell].lo = lo; cell[ncell].hi = hi;
            fmpq_set(samp + ncell, t);
            cell[ncell++].status = qd_status_at(&bad, S, pp, tv, t);
            checked++;
        }
        if (hi == NULL || !qd_alg_in_bound(bd + tv, hi)) continue;
        cell[ncell].pt = 1; cell[ncell].lo = cell[ncell].hi = hi;
        if (hi->rational) {
            fmpq_set(samp + ncell, hi->q);
            cell[ncell++].status = qd_status_at(&bad, S, pp, tv, hi->q);
            checked++;
        } else {
            /* the conditions' exact signs at t0 against the route over Q(t0, sqrt d) */
            rs_status_t ex;
            int ok = !S->q.never, okalt = 1, zero = 0, decided = qd_exact_status(&ex, S, tv, hi);
            for (k = 0; k < S->q.n + nalt; k++) {
                int sg = qd_alg_sign(cu + k, s->sqrt_d, hi);
                int ne = k < S->q.n ? S->q.ne[k] : S->alt->ne[k - S->q.n];
                if (k < S->q.n && sg == 0) zero = 1;
                if (ne ? sg == 0 : sg <= 0) *(k < S->q.n ? &ok : &okalt) = 0;
            }
            if (decided && (ex == RS_STATUS_STABLE) != ok) bad = 1;
            if (S->alt != NULL && (S->alt->never ? 0 : okalt) != ok) bad = 1;   /* Bilharz's signs there */
            /* undecided there: every delta_k != 0 leaves no root on the circle (a
             * circle root of p is one of p* and of every row), so not stable is unstable */
            cell[ncell++].status = decided ? rs_status_name(ex) : ok ? "stable"
                                 : qd_alg_sign(lu, s->sqrt_d, hi) == 0 ? "singular" : zero ? "not stable"
                                 : "unstable";
            checked += decided;
        }
    }
    if (r == RS_OK && bad)
        r = rs_req_error(run, rq, rq->text, RS_ERR_INCONSISTENT, "region over Q(sqrt d): the conditions, "
                         "Schur-Cohn and the certified roots disagree at a sample (internal inconsistency)%s", "");
    for (i = 0; r == RS_OK && i < ncell; ) {
        /* merge the run of cells of one status */
        slong j = i;
        json_t *iv;
        while (j + 1 < ncell && strcmp(cell[j + 1].status, cell[i].status) == 0) j++;
        iv = rs_an_qd_interval_json(cell[i].lo, cell[j].hi, cell[i].pt, cell[j].pt, cell[i].status, name);
        json_array_append_new(ivs, iv);
        i = j + 1;
    }
    for (i = 0; r == RS_OK && kind >= 0 && i < ncell && *verdict != -1; i++) {
        /* the claim, cell by cell: the first bad one is the counterexample */
        const char *st = cell[i].status;
        int good = kind == 0 ? strcmp(st, "stable") == 0
                 : kind == 1 ? strcmp(st, "stable") == 0 || strcmp(st, "marginal") == 0 : strcmp(st, "unstable") == 0;
        if (good) continue;
        if (strcmp(st, "not stable") == 0 && kind != 0) { *verdict = 0; continue; }
        *verdict = -1;
        *counter = json_object();
        if (cell[i].pt && !cell[i].hi->rational) {
            /* an algebraic point: its certified digits, and exactly which root of which polynomial */
            json_t *aj = rs_alg_json(cell[i].hi, name);
            char ex[400];
            snprintf(ex, sizeof ex, "root %ld (from below, 0-based) of %s", (long) cell[i].hi->idx,
                     json_string_value(json_object_get(aj, "minpoly")));
            json_object_set_new(*counter, name, json_incref(json_object_get(aj, "approx")));
            json_object_set_new(*counter, "exact", json_string(ex));
            json_decref(aj);
        } else {
            json_object_set_new(*counter, name, rs_json_fmpq(samp + i));
        }
        json_object_set_new(*counter, "status", json_string(st));
    }
    if (r == RS_OK && kind >= 0) {
        json_object_set_new(o, "region", ivs);
        json_object_set_new(o, "cross_checked_samples", json_integer(checked));
    } else if (r == RS_OK) {
        json_object_set_new(o, "symbolic", json_false());
        json_object_set_new(o, "intervals", ivs);
        json_object_set_new(o, "undecided_points", json_array());
        json_object_set_new(o, "critical_values", json_integer(ncrit));
        json_object_set_new(o, "cross_checked_samples", json_integer(checked));
    } else {
        json_decref(ivs);
    }
    for (i = 0; i < ncrit; i++) rs_alg_clear(crit + i);
    free(crit);
    flint_free(cell);
    _fmpq_vec_clear(samp, 2 * ncrit + 1);
    rs_run_bounds_clear(bd, run);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    fmpq_clear(t);
    for (i = 0; i < S->q.n + nalt; i++) rs_qdpoly_clear(cu + i);
    flint_free(cu);
    rs_qdpoly_clear(lu);
    fmpz_poly_clear(nz);
    fmpz_mpoly_clear(h0, s->zctx); fmpz_mpoly_clear(h1, s->zctx);
    return r;
}

int rs_an_qd_region(rs_run_t *run, const rs_an_req_t *req)
{
    slong tv = req->u.region.param, na = -1, k;
    const char *keep[1];
    rs_assign_t *as = NULL;
    slong nas = 0;
    rs_variant_t *v;
    qd_sym_t S;
    json_t *o, *rows, *conds, *parts, *dropped, *always;
    fmpz_mpoly_t lead;
    int r, never = 0, others = 0;
    /* region N1, N2 goes to an_qd_region2.c before this (an_region.c) */
    if (req->u.region.forall) return rs_an_qd_region_forall(run, req);   /* an_qd_forall.c */
    if (rs_an_qd_cx_other(run, tv))   /* complex set values of other parameters: over Q(sqrt d)(i) */
        return rs_an_qd_cx_fiber(NULL, NULL, NULL, run, req, -1, tv, NULL, req->u.region.at, req->u.region.nat);
    rows = json_array(); conds = json_array(); parts = json_array(); dropped = json_array(); always = json_array();
    keep[0] = run->c->params[tv].name;
    rs_run_assignments(run, &as, &nas, keep, 1, req->u.region.at, req->u.region.nat);
    r = rs_run_variant(&v, run, as, nas);
    rs_assign_free(as, nas);
    if (r == RS_OK) r = qd_sym_init(&S, run, req, v);
    else S.a = NULL;
    if (r == RS_OK) {
        fmpz_mpoly_init(lead, S.s->zctx);
        fmpz_mpoly_set(lead, S.a + S.n, S.s->zctx);
        r = qd_jury_table(&S, run, rows, conds, parts, dropped, always, &never, &na);
    } else {
        na = S.a != NULL ? S.n : -1;
    }
    if (r != RS_OK) {
        json_decref(rows); json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
        if (S.a != NULL) fmpz_mpoly_clear(lead, S.s->zctx);
        qd_sym_clear(&S, na);
        return r;
    }
    json_decref(rows);
    for (k = 0; k < S.s->lambda_var; k++)
        if (k != tv && (fmpz_mpoly_degree_si(S.p0, k, S.s->zctx) > 0 || fmpz_mpoly_degree_si(S.p1, k, S.s->zctx) > 0))
            others = 1;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("region"));
    json_object_set_new(o, "param", json_string(keep[0]));
    if (others) {
        /* other parameters free: the conditions on all of them (jury's) */
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "note", json_string(qd_jury_note));
        r = qd_sym_finish(&S, run, req, o, conds, parts, dropped, always, never, NULL);
    } else {
        r = qd_region_cells(o, &S, run, req->q, tv, lead, NULL, -1, NULL, NULL);
        if (r == RS_OK) {
            rs_an_qd_json_p(o, S.p0, S.p1, run);
            json_object_set_new(o, "method", json_string(
                "cells cut at the real roots of the norms c0^2 - d c1^2 of the Schur-Cohn conditions c0 + sqrt(d) c1 "
                "> 0 over Q(sqrt d) (jury's) and of the leading coefficient, and at the assumptions' ends; each "
                "rational sample decided three ways: the conditions' exact signs, Schur-Cohn over Q(sqrt d) with the "
                "certified roots, and region's exact route over Q(sqrt d) = Q(gamma) (stable, marginal, unstable); "
                "each irrational critical value t0 by the conditions' exact signs in Q(t0, sqrt d) (signs of c0, c1 "
                "in Q[t]/(minpoly), then of the norm) and by the exact route over Q(t0, sqrt d) = Q(gamma) (a "
                "primitive element); all must agree, else exit 3"));
            json_object_set_new(o, "dropped", dropped);
            json_decref(conds); json_decref(parts); json_decref(always);
            rs_run_emit_exact(run, S.v, o);
        } else {
            json_decref(o); json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
        }
    }
    fmpz_mpoly_clear(lead, S.s->zctx);
    qd_sym_clear(&S, na);
    return r;
}

int rs_an_qd_cx_cells(json_t *o, rs_run_t *run, const rs_request_t *rq, slong tv, const rs_an_qd_conds_t *q,
                      const rs_an_qd_conds_t *alt, const fmpz_mpoly_struct *const *part, slong n,
                      const fmpz_mpoly_t lead, const rs_bound_t *dom, int kind, int *verdict, json_t **counter)
{
    qd_sym_t S;
    memset(&S, 0, sizeof S);
    S.s = q->s;
    S.n = n;
    S.q = *q;   /* read only: not cleared here */
    S.cx = part;
    S.alt = alt;
    return qd_region_cells(o, &S, run, rq, tv, lead, dom, kind, verdict, counter);
}

int rs_an_qd_claim_part(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                        slong tv, const rs_bound_t *dom)
{
    return rs_an_qd_fiber(verdict, counter, o, run, req, kind, tv, dom, NULL, 0);
}

int rs_an_qd_fiber(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                   slong tv, const rs_bound_t *dom, const rs_assign_t *extra, slong nextra)
{
    qd_sym_t S;
    json_t *rows, *conds, *parts, *dropped, *always;
    fmpz_mpoly_t lead;
    slong na = -1, k;
    rs_variant_t *v = NULL;
    int r = RS_OK, never = 0;
    if (rs_an_qd_cx_other(run, tv))   /* over Q(sqrt d)(i) (an_qd_complex.c) */
        return rs_an_qd_cx_fiber(verdict, counter, o, run, req, kind, tv, dom, extra, nextra);
    rows = json_array(); conds = json_array(); parts = json_array(); dropped = json_array(); always = json_array();
    if (nextra > 0) {   /* the case's set values and extra[], tv kept free */
        const char *keep[1];
        rs_assign_t *as = NULL;
        slong nas = 0;
        keep[0] = run->c->params[tv].name;
        rs_run_assignments(run, &as, &nas, keep, 1, extra, nextra);
        r = rs_run_variant(&v, run, as, nas);
        rs_assign_free(as, nas);
    }
    if (r == RS_OK) r = qd_sym_init(&S, run, req, v);
    else S.a = NULL;
    *verdict = 0;
    *counter = NULL;
    if (r == RS_OK) {
        fmpz_mpoly_init(lead, S.s->zctx);
        fmpz_mpoly_set(lead, S.a + S.n, S.s->zctx);
        r = qd_jury_table(&S, run, rows, conds, parts, dropped, always, &never, &na);
        for (k = 0; r == RS_OK && k < S.s->lambda_var; k++)
            if (k != tv && (fmpz_mpoly_degree_si(S.p0, k, S.s->zctx) > 0 || fmpz_mpoly_degree_si(S.p1, k, S.s->zctx) > 0))
                r = rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "expected every parameter but %s set: a "
                                 "claim over Q(sqrt d) is decided on the exact region of one parameter (jury, "
                                 "hurwitz and routh give the conditions with more parameters free)",
                                 run->c->params[tv].name);
        if (r == RS_OK) r = qd_region_cells(o, &S, run, req->q, tv, lead, dom, kind, verdict, counter);
        fmpz_mpoly_clear(lead, S.s->zctx);
    } else {
        na = S.a != NULL ? S.n : -1;
    }
    json_decref(rows); json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
    qd_sym_clear(&S, na);
    return r;
}

/* ---- the pieces of region NAME for all over Q(sqrt d) (an_qd_forall.c) ---- */

/* the norm c0^2 - d c1^2 of c0 + sqrt(d) c1 into l (it vanishes wherever
 * c0 + sqrt(d) c1 does) */
void rs_an_qd_mpoly_norm(fmpz_mpoly_t n, const fmpz_mpoly_t c0, const fmpz_mpoly_t c1, const rs_scheme_struct *s)
{
    fmpz_mpoly_t u;
    fmpz_mpoly_init(u, s->zctx);
    fmpz_mpoly_mul(u, c1, c1, s->zctx);
    fmpz_mpoly_scalar_mul_si(u, u, s->sqrt_d, s->zctx);
    fmpz_mpoly_mul(n, c0, c0, s->zctx);
    fmpz_mpoly_sub(n, n, u, s->zctx);
    fmpz_mpoly_clear(u, s->zctx);
}

static void qd_norm_add(rs_plist_t *l, const fmpz_mpoly_t c0, const fmpz_mpoly_t c1, slong tv, const rs_bound_t *dom,
                        const rs_scheme_struct *s)
{
    fmpz_mpoly_t t;
    fmpz_mpoly_init(t, s->zctx);
    rs_an_qd_mpoly_norm(t, c0, c1, s);
    rs_plist_add(l, t, tv, dom, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
}

/* the same for a (reduced: sqrt(d) at most linearly) */
static void qd_norm_add_split(rs_plist_t *l, const fmpz_mpoly_t a, slong tv, const rs_bound_t *dom,
                              const rs_scheme_struct *s)
{
    fmpz_mpoly_t a0, a1;
    fmpz_mpoly_init(a0, s->zctx); fmpz_mpoly_init(a1, s->zctx);
    qd_split(a0, a1, a, s);
    qd_norm_add(l, a0, a1, tv, dom, s);
    fmpz_mpoly_clear(a0, s->zctx); fmpz_mpoly_clear(a1, s->zctx);
}

int rs_an_qd_forall_norms(rs_plist_t *l, const rs_scheme_struct **sp, rs_run_t *run, const rs_an_req_t *req,
                          slong tv, const rs_bound_t *dom)
{
    qd_sym_t S;
    json_t *rows = json_array(), *conds = json_array(), *parts = json_array(), *dropped = json_array(),
           *always = json_array();
    fmpz_mpoly_t t;
    slong na = -1, i;
    int r = qd_sym_init(&S, run, req, NULL), never = 0;
    if (r == RS_OK) {
        *sp = S.s;
        fmpz_mpoly_init(t, S.s->zctx);
        /* the leading coefficient (singular) and the discriminant (a repeated
         * circle root: marginal against unstable) before the table consumes S.a */
        qd_norm_add_split(l, S.a + S.n, tv, dom, S.s);
        if (S.n >= 2 && fmpz_mpoly_discriminant(t, S.v->cp->p, S.s->lambda_var, S.s->zctx)) {
            rs_scheme_reduce_sqrt(t, S.s);
            qd_norm_add_split(l, t, tv, dom, S.s);
        }
        r = qd_jury_table(&S, run, rows, conds, parts, dropped, always, &never, &na);
        for (i = 0; r == RS_OK && i < S.q.n; i++) qd_norm_add(l, S.q.c0 + i, S.q.c1 + i, tv, dom, S.s);
        fmpz_mpoly_clear(t, S.s->zctx);
    } else {
        na = S.a != NULL ? S.n : -1;
    }
    json_decref(rows); json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
    qd_sym_clear(&S, na);
    return r;
}

int rs_an_qd_jury_conds(fmpz_mpoly_struct **c0, fmpz_mpoly_struct **c1, int **ne, slong *n, rs_run_t *run,
                        const rs_an_req_t *req, rs_variant_t *v, int hurwitz)
{
    qd_sym_t S;
    json_t *rows = json_array(), *conds = json_array(), *parts = json_array(), *dropped = json_array(),
           *always = json_array();
    slong na = -1;
    int r = qd_sym_init(&S, run, req, v), never = 0;
    *c0 = *c1 = NULL;
    *ne = NULL;
    *n = 0;
    if (r == RS_OK && hurwitz && S.n <= 8) {
        na = S.n;
        r = qd_hurwitz_conds(&S, run, rows, conds, parts, dropped, always, &never);
    } else if (r == RS_OK) {
        r = qd_jury_table(&S, run, rows, conds, parts, dropped, always, &never, &na);
    } else {
        na = S.a != NULL ? S.n : -1;
    }
    if (r == RS_OK) {
        /* handed over: qd_sym_clear then frees nothing of them */
        *c0 = S.q.c0; *c1 = S.q.c1; *ne = S.q.ne; *n = S.q.n;
        S.q.c0 = S.q.c1 = NULL; S.q.ne = NULL; S.q.n = 0;
    }
    json_decref(rows); json_decref(conds); json_decref(parts); json_decref(dropped); json_decref(always);
    qd_sym_clear(&S, na);
    return r;
}

int rs_an_qd_point_verdict(rs_run_t *run, const rs_an_req_t *req, fmpq *const *pt)
{
    qd_sym_t S;
    int r = qd_sym_init(&S, run, req, NULL), st = -3;
    if (r == RS_OK) st = qd_point_stable(S.p0, S.p1, S.n, pt, S.s);
    else rs_error_init(run->err);
    qd_sym_clear(&S, S.a != NULL ? S.n : -1);
    return st;
}

/* the variant at the set values and extra[], tv (and qv >= 0) kept free */
static int qd_variant_keeping(rs_variant_t **v, rs_run_t *run, slong tv, slong qv, const rs_assign_t *extra,
                              slong nextra)
{
    const char *keep[2];
    rs_assign_t *as = NULL;
    slong nas = 0;
    int r;
    keep[0] = run->c->params[tv].name;
    if (qv >= 0) keep[1] = run->c->params[qv].name;
    rs_run_assignments(run, &as, &nas, keep, qv >= 0 ? 2 : 1, extra, nextra);
    r = rs_run_variant(v, run, as, nas);
    rs_assign_free(as, nas);
    return r;
}

int rs_an_qd_alg_status(rs_status_t *st, rs_run_t *run, const rs_an_req_t *req, slong tv, rs_alg_t *t0,
                        const rs_assign_t *extra, slong nextra)
{
    rs_variant_t *v;
    qd_sym_t S;
    int r = qd_variant_keeping(&v, run, tv, -1, extra, nextra), decided = 0;
    S.a = NULL;
    if (r == RS_OK) r = qd_sym_init(&S, run, req, v);
    if (r == RS_OK) decided = qd_exact_status(st, &S, tv, t0);
    else if (S.a != NULL && S.v->singular) { *st = RS_STATUS_SINGULAR; decided = 1; }
    rs_error_init(run->err);
    if (S.a != NULL) qd_sym_clear(&S, S.n);
    return decided;
}

int rs_an_qd_alg2_status(rs_status_t *st, rs_run_t *run, const rs_an_req_t *req, slong tv, rs_alg_t *t0, slong qv,
                         rs_alg_t *q0, const rs_assign_t *extra, slong nextra)
{
    qd_sym_t S;
    rs_alg_t sq, g1, g2;
    fmpq_poly_t A1, B1, A2, B2, T, R, m;
    fmpq_poly_struct *c = NULL;
    rs_variant_t *v = NULL;
    slong j;
    int r = RS_OK, decided = 0;
    if (nextra > 0) r = qd_variant_keeping(&v, run, tv, qv, extra, nextra);
    S.a = NULL;
    if (r == RS_OK) r = qd_sym_init(&S, run, req, v);
    if (r != RS_OK) {
        /* the leading coefficient vanishing for every tv, qv at extra[]: singular */
        decided = S.a != NULL && S.v->singular;
        if (decided) *st = RS_STATUS_SINGULAR;
        rs_error_init(run->err);
        qd_sym_clear(&S, S.a != NULL ? S.n : -1);
        return decided;
    }
    rs_alg_init(&sq); rs_alg_init(&g1); rs_alg_init(&g2);
    fmpq_poly_init(A1); fmpq_poly_init(B1); fmpq_poly_init(A2); fmpq_poly_init(B2);
    fmpq_poly_init(T); fmpq_poly_init(R); fmpq_poly_init(m);
    fmpz_poly_set_coeff_si(sq.minpoly, 2, 1);
    fmpz_poly_set_coeff_si(sq.minpoly, 0, -S.s->sqrt_d);
    sq.idx = 1;
    rs_alg_refine(&sq, 128);
    /* Q(t0, sqrt d) = Q(g1), then Q(g1, q0) = Q(g2): t0 = A1(A2(g2)),
     * sqrt(d) = B1(A2(g2)), q0 = B2(g2) */
    if (rs_alg_primitive(&g1, A1, B1, t0, &sq) && rs_alg_primitive(&g2, A2, B2, &g1, q0)) {
        fmpq_poly_set_fmpz_poly(m, g2.minpoly);
        fmpq_poly_compose(T, A1, A2); fmpq_poly_rem(T, T, m);
        fmpq_poly_compose(R, B1, A2); fmpq_poly_rem(R, R, m);
        c = flint_malloc((size_t) (S.n + 1) * sizeof(fmpq_poly_struct));
        for (j = 0; j <= S.n; j++) fmpq_poly_init(c + j);
        qd_coeffs_at(c, &S, tv, T, qv, B2, R, m);
        decided = fmpq_poly_is_zero(c + S.n) ? (*st = RS_STATUS_SINGULAR, 1)
                : rs_alg_status_coeffs(st, c, S.n, &g2, S.s);
        for (j = 0; j <= S.n; j++) fmpq_poly_clear(c + j);
        flint_free(c);
    }
    rs_alg_clear(&sq); rs_alg_clear(&g1); rs_alg_clear(&g2);
    fmpq_poly_clear(A1); fmpq_poly_clear(B1); fmpq_poly_clear(A2); fmpq_poly_clear(B2);
    fmpq_poly_clear(T); fmpq_poly_clear(R); fmpq_poly_clear(m);
    qd_sym_clear(&S, S.n);
    return decided;
}

/* qc_add, qc_hold and qc_clear for the conditions over Q(sqrt d)(i) (an_qd_complex.c) */
int rs_an_qd_conds_add(rs_an_qd_conds_t *q, json_t *conds, json_t *parts, json_t *dropped, const fmpz_mpoly_t f,
                       const char *origin, const int *sign)
{
    return qc_add(q, conds, parts, dropped, f, origin, sign);
}

int rs_an_qd_conds_hold(const rs_an_qd_conds_t *q, fmpq *const *pt) { return qc_hold(q, pt); }

void rs_an_qd_conds_clear(rs_an_qd_conds_t *q) { qc_clear(q); }
