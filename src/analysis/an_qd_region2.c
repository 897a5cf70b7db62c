/* an_qd_region2.c -- issue 15: `region N1, N2 [at P=V, ...]` over Q(sqrt d)
 * (rk sdirk2, sdirk3, ...: p = p0 + sqrt(d) p1 with p0, p1 in Z[N1, N2][lambda]).
 *
 * A root of p can reach the unit circle, or the step stop being solvable,
 * only where one of g = lc(p), p(1), p(-1), D_(n-1) of the bilinear image
 * (Orlando: a root pair z, -z there, every circle pair e^{+-i phi}),
 * disc_lambda(p) (a double root) vanishes; the first three and D_(n-1) are
 * in hurwitz's conditions b_n^k D_k > 0 (an_qd_conds.c), which are taken
 * whole.  Each g = g0 + sqrt(d) g1 lies in Q(sqrt d)[N1, N2], and its zero
 * set lies in that of its norm g0^2 - d g1^2 = g g^sigma in Z[N1, N2]
 * (sigma: sqrt(d) -> -sqrt(d)).  The rational CAD (an_region_cad.c) runs on
 * those norms: on each of its connected cells every g keeps one sign, so the
 * status is constant there and one sample decides the cell:
 *   - a rational sample three ways: Schur-Cohn over Q(sqrt d)(i) against the
 *     certified Arb roots (rs_qdc_stable_checked), region's exact route in
 *     Q(sqrt d) (rs_alg_status_coeffs: stable, marginal, unstable), and
 *     jury's conditions c0 + sqrt(d) c1 > 0 signed exactly (an_qd_conds.c);
 *   - an algebraic sample (N1, N2) = (A, B)(g) in the tower Q(g, sqrt d) =
 *     Q(h) (a primitive element, rs_alg_primitive) two ways: the exact
 *     route and jury's conditions signed in Q(h).
 * Any disagreement is exit 3.  The formula and the boundary are written in
 * the norms: exact, but a norm may have higher degree than the true boundary
 * curve (it also holds g^sigma's zero set; its arcs that separate nothing are
 * not in "boundary"). */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "analysis/an_region.h"
#include "algebra/qsqrt.h"

typedef struct {
    rs_run_t *run;
    const rs_scheme_struct *s;
    slong av, bv, n, d;
    fmpz_mpoly_struct *a0, *a1;          /* p's lambda^j coefficient a0[j] + sqrt(d) a1[j], j = 0..n */
    fmpz_mpoly_struct *c0, *c1;          /* jury: c0[k] + sqrt(d) c1[k] > 0 (ne[k]: != 0) */
    int *ne;
    slong nc;
    slong rational, algebraic, open;     /* samples decided three / two ways, left open */
    slong disagree;
} qr_t;

/* the status in Q(h) = Q[x]/(m) of p at N1 = Ah(h), N2 = Bh(h), sqrt(d) =
 * Sq(h) by the exact route, checked against jury's conditions signed in
 * Q(h): 1 decided, 0 not, -1 the two disagree (Q->disagree counted) */
static int qr_status_in(rs_status_t *st, qr_t *Q, const fmpq_poly_t Ah, const fmpq_poly_t Bh,
                        const fmpq_poly_t Sq, rs_alg_t *h)
{
    fmpq_poly_struct *c = flint_malloc((Q->n + 1) * sizeof(fmpq_poly_struct));
    fmpq_poly_t m, e0, e1;
    slong j;
    int dec, holds = 1;
    fmpq_poly_init(m); fmpq_poly_init(e0); fmpq_poly_init(e1);
    fmpq_poly_set_fmpz_poly(m, h->minpoly);
    for (j = 0; j <= Q->n + Q->nc; j++) {
        /* j <= n: p's coefficients; then the conditions */
        const fmpz_mpoly_struct *f0 = j <= Q->n ? Q->a0 + j : Q->c0 + (j - Q->n - 1);
        const fmpz_mpoly_struct *f1 = j <= Q->n ? Q->a1 + j : Q->c1 + (j - Q->n - 1);
        rs_region_eval_field(e0, f0, Q->av, Q->bv, Ah, Bh, m, Q->s->zctx);
        rs_region_eval_field(e1, f1, Q->av, Q->bv, Ah, Bh, m, Q->s->zctx);
        fmpq_poly_mul(e1, e1, Sq);
        fmpq_poly_add(e0, e0, e1);
        fmpq_poly_rem(e0, e0, m);
        if (j <= Q->n) {
            fmpq_poly_init(c + j);
            fmpq_poly_swap(c + j, e0);
        } else {
            int sg = rs_alg_sign(e0, h);
            if (Q->ne[j - Q->n - 1] ? sg == 0 : sg <= 0) holds = 0;
        }
    }
    if (fmpq_poly_is_zero(c + Q->n)) { *st = RS_STATUS_SINGULAR; dec = 1; }   /* no step: lc(p) = 0 here */
    else dec = rs_alg_status_coeffs(st, c, Q->n, h, Q->s);
    if (dec && (*st == RS_STATUS_STABLE) != holds) {
        Q->disagree++;
        Q->run->outcome |= RS_OUTCOME_INCONSISTENT;
        dec = -1;
    }
    for (j = 0; j <= Q->n; j++) fmpq_poly_clear(c + j);
    flint_free(c);
    fmpq_poly_clear(m); fmpq_poly_clear(e0); fmpq_poly_clear(e1);
    return dec;
}

/* sqrt(d) as the positive root of x^2 - d */
void rs_an_qd_sqrt_alg(rs_alg_t *sq, slong d)
{
    fmpz_poly_zero(sq->minpoly);
    fmpz_poly_set_coeff_si(sq->minpoly, 2, 1);
    fmpz_poly_set_coeff_si(sq->minpoly, 0, -d);
    sq->idx = 1;
    sq->rational = 0;
    sq->prec = 0;
    rs_alg_refine(sq, 128);
}

/* rs_region_qd_t's field: (A, B)(g) in the tower Q(g, sqrt d) = Q(h) */
static int qr_field(rs_status_t *st, const fmpq_poly_t A, const fmpq_poly_t B, rs_alg_t *g, void *arg)
{
    qr_t *Q = arg;
    rs_alg_t sq, h;
    fmpq_poly_t G, Sq, Ah, Bh, m;
    int dec = 0;
    rs_alg_init(&sq); rs_alg_init(&h);
    fmpq_poly_init(G); fmpq_poly_init(Sq); fmpq_poly_init(Ah); fmpq_poly_init(Bh); fmpq_poly_init(m);
    rs_an_qd_sqrt_alg(&sq, Q->d);
    if (rs_alg_primitive(&h, G, Sq, g, &sq)) {
        /* g = G(h): A(g), B(g) as polynomials in h */
        fmpq_poly_set_fmpz_poly(m, h.minpoly);
        fmpq_poly_compose(Ah, A, G);
        fmpq_poly_rem(Ah, Ah, m);
        fmpq_poly_compose(Bh, B, G);
        fmpq_poly_rem(Bh, Bh, m);
        dec = qr_status_in(st, Q, Ah, Bh, Sq, &h);
    }
    if (dec == 1) Q->algebraic++;
    else if (dec == 0) Q->open++;
    rs_alg_clear(&sq); rs_alg_clear(&h);
    fmpq_poly_clear(G); fmpq_poly_clear(Sq); fmpq_poly_clear(Ah); fmpq_poly_clear(Bh); fmpq_poly_clear(m);
    return dec == 1;
}

/* f (in N1, N2 only) at rational vals */
static void qr_eval(fmpq_t out, const fmpz_mpoly_t f, const qr_t *Q, const fmpq *vals)
{
    fmpq_poly_t A, B, m, e;
    fmpq_poly_init(A); fmpq_poly_init(B); fmpq_poly_init(m); fmpq_poly_init(e);
    fmpq_poly_set_fmpq(A, vals + 0);
    fmpq_poly_set_fmpq(B, vals + 1);
    fmpq_poly_set_coeff_si(m, 1, 1);   /* Q[x]/(x): the constants */
    rs_region_eval_field(e, f, Q->av, Q->bv, A, B, m, Q->s->zctx);
    fmpq_poly_get_coeff_fmpq(out, e, 0);
    fmpq_poly_clear(A); fmpq_poly_clear(B); fmpq_poly_clear(m); fmpq_poly_clear(e);
}

/* rs_region_qd_t's point: the exact route and jury's conditions in
 * Q(sqrt d) (qr_status_in), and Schur-Cohn over Q(sqrt d)(i) with the
 * certified roots (rs_qdc_stable_checked): all must agree (exit 3) */
static int qr_point(rs_status_t *st, const fmpq *vals, void *arg)
{
    qr_t *Q = arg;
    rs_alg_t sq;
    fmpq_poly_t A, B, S;
    rs_qdc_struct *c = rs_qdc_vec_init(Q->n + 1);
    slong j, n;
    int dec, sc = 1, ok = 1;
    rs_alg_init(&sq);
    fmpq_poly_init(A); fmpq_poly_init(B); fmpq_poly_init(S);
    rs_an_qd_sqrt_alg(&sq, Q->d);
    fmpq_poly_set_fmpq(A, vals + 0);
    fmpq_poly_set_fmpq(B, vals + 1);
    fmpq_poly_set_coeff_si(S, 1, 1);
    dec = qr_status_in(st, Q, A, B, S, &sq);
    for (j = 0; j <= Q->n; j++) {
        qr_eval(c[j].re->x, Q->a0 + j, Q, vals);
        qr_eval(c[j].re->y, Q->a1 + j, Q, vals);
    }
    for (n = Q->n; n >= 0 && rs_qd_is_zero(c[n].re); n--) ;
    if (n == Q->n) {   /* lc(p) != 0 here (else singular, the step has no solution) */
        sc = rs_qdc_stable_checked(NULL, c, n, Q->d);
        /* 1 stable; 0 a root certified outside: unstable; -1 not stable */
        if (sc == -2 || (dec == 1 && ((*st == RS_STATUS_STABLE) != (sc == 1)
                                      || (sc == 0 && *st != RS_STATUS_UNSTABLE))))
            ok = 0;
    }
    rs_qdc_vec_clear(c, Q->n + 1);
    rs_alg_clear(&sq);
    fmpq_poly_clear(A); fmpq_poly_clear(B); fmpq_poly_clear(S);
    if (!ok || dec == -1) {
        char *x = fmpq_get_str(NULL, 10, vals + 0), *y = fmpq_get_str(NULL, 10, vals + 1);
        int r;
        Q->run->outcome |= RS_OUTCOME_INCONSISTENT;
        r = rs_error_set(Q->run->err, RS_ERR_INCONSISTENT, "region N1, N2 over Q(sqrt %ld): at (%s, %s) Schur-Cohn "
                         "over Q(sqrt d)(i), the certified roots, the exact route in Q(sqrt d) and jury's "
                         "conditions disagree (internal inconsistency)", (long) Q->d, x, y);
        flint_free(x);
        flint_free(y);
        return r;
    }
    if (dec == 1) { Q->rational++; return RS_OK; }
    if (sc == 1 || sc == 0) {
        /* the exact route left it open (a system's repeated circle root):
         * Schur-Cohn and the roots still tell stable and unstable */
        *st = sc == 1 ? RS_STATUS_STABLE : RS_STATUS_UNSTABLE;
        Q->rational++;
        return RS_OK;
    }
    {
        char *x = fmpq_get_str(NULL, 10, vals + 0), *y = fmpq_get_str(NULL, 10, vals + 1);
        int r = rs_error_set(Q->run->err, RS_ERR_UNDECIDED, "region N1, N2 over Q(sqrt %ld): at the sample (%s, %s) "
                             "a repeated root on the unit circle: marginal and unstable are not told apart there",
                             (long) Q->d, x, y);
        flint_free(x);
        flint_free(y);
        return r;
    }
}

/* g = g0 + sqrt(d) g1 (reduced by sqrt(d)^2 = d; or g0 + sqrt(d) h1 when
 * h1 != NULL): its norm g0^2 - d g1^2 appended to crit, and with parts g0
 * and g1 too; 0 when g vanishes identically */
int rs_an_qd_push_norm(fmpz_mpoly_struct **crit, slong *ncrit, const fmpz_mpoly_t g, const fmpz_mpoly_struct *h1,
                       int parts, const rs_scheme_struct *s)
{
    fmpz_mpoly_t g0, g1, t;
    int nz;
    fmpz_mpoly_init(g0, s->zctx); fmpz_mpoly_init(g1, s->zctx); fmpz_mpoly_init(t, s->zctx);
    rs_charpoly_coeff(g0, g, 0, s->sqrt_var, s->zctx);
    rs_charpoly_coeff(g1, g, 1, s->sqrt_var, s->zctx);
    if (h1 != NULL) { fmpz_mpoly_set(g0, g, s->zctx); fmpz_mpoly_set(g1, h1, s->zctx); }
    rs_an_qd_mpoly_norm(t, g0, g1, s);
    nz = !fmpz_mpoly_is_zero(t, s->zctx);
    if (nz) {
        /* the norm, and g0, g1 themselves: with the three signs the sign of
         * g is known on every cell (a norm alone does not tell g's zero set
         * from g^sigma's, whose cells may then share signs) */
        *crit = flint_realloc(*crit, (*ncrit + 3) * sizeof(fmpz_mpoly_struct));
        fmpz_mpoly_init(*crit + *ncrit, s->zctx);
        fmpz_mpoly_swap(*crit + (*ncrit)++, t, s->zctx);
        if (parts && !fmpz_mpoly_is_zero(g1, s->zctx)) {
            fmpz_mpoly_init(*crit + *ncrit, s->zctx);
            fmpz_mpoly_swap(*crit + (*ncrit)++, g0, s->zctx);
            fmpz_mpoly_init(*crit + *ncrit, s->zctx);
            fmpz_mpoly_swap(*crit + (*ncrit)++, g1, s->zctx);
        }
    }
    fmpz_mpoly_clear(g0, s->zctx); fmpz_mpoly_clear(g1, s->zctx); fmpz_mpoly_clear(t, s->zctx);
    return nz;
}

/* the norms of lc(p), p(1), p(-1), disc_lambda(p) and of the conditions
 * c0[k] + sqrt(d) c1[k] (hurwitz's: b_n^k D_k, D_(n-1) vanishing where a
 * root pair reaches the circle) with c0[k], c1[k] themselves (their signs
 * fix the condition's sign: every cell is inside or outside the stable
 * set); RS_ERR_INPUT (message in *why) when p(1), p(-1) or the
 * discriminant vanishes for every (N1, N2) */
static int qr_critical(fmpz_mpoly_struct **crit, slong *ncrit, const char **why, const fmpz_mpoly_t p,
                       const fmpz_mpoly_struct *c0, const fmpz_mpoly_struct *c1, slong nc,
                       const rs_scheme_struct *s, slong n)
{
    const fmpz_mpoly_ctx_struct *ctx = s->zctx;
    slong lv = s->lambda_var, j;
    fmpz_mpoly_t g;
    fmpz_t x;
    fmpz_mpoly_init(g, ctx);
    fmpz_init(x);
    *why = NULL;
    rs_charpoly_coeff(g, p, n, lv, ctx);
    rs_an_qd_push_norm(crit, ncrit, g, NULL, 0, s);
    for (j = 1; j >= -1; j -= 2) {
        fmpz_set_si(x, j);
        fmpz_mpoly_evaluate_one_fmpz(g, p, lv, x, ctx);
        rs_scheme_reduce_sqrt(g, s);
        if (!rs_an_qd_push_norm(crit, ncrit, g, NULL, 0, s)) *why = j == 1 ? "lambda = 1 as a root for every value"
                                                                     : "lambda = -1 as a root for every value";
    }
    if (*why == NULL && n >= 2 && fmpz_mpoly_discriminant(g, p, lv, ctx)) {
        rs_scheme_reduce_sqrt(g, s);
        if (!rs_an_qd_push_norm(crit, ncrit, g, NULL, 0, s)) *why = "a repeated root for every value";
    }
    for (j = 0; j < nc; j++) rs_an_qd_push_norm(crit, ncrit, c0 + j, c1 + j, 1, s);
    fmpz_mpoly_clear(g, ctx);
    fmpz_clear(x);
    return *why != NULL ? RS_ERR_INPUT : RS_OK;
}

static void qr_conds_clear(fmpz_mpoly_struct *c0, fmpz_mpoly_struct *c1, int *ne, slong n, const rs_scheme_struct *s)
{
    slong i;
    for (i = 0; i < n; i++) {
        fmpz_mpoly_clear(c0 + i, s->zctx);
        fmpz_mpoly_clear(c1 + i, s->zctx);
    }
    flint_free(c0);
    flint_free(c1);
    flint_free(ne);
}

static const char qr_method[] =
    "cylindrical algebraic decomposition of the plane (Collins) over Q(sqrt d): the critical polynomials g = "
    "g0 + sqrt(d) g1 of p over Q(sqrt d)[N1, N2] (leading coefficient, p(1), p(-1), the discriminant, and "
    "hurwitz's conditions b_n^k D_k with their parts g0, g1, whose signs fix g's) replaced by their norms "
    "g0^2 - d g1^2 in Z[N1, N2] (every real zero of g is one of its norm's), their projection onto the first parameter, one verdict per cell over Q(sqrt d): a rational sample "
    "by Schur-Cohn over Q(sqrt d)(i) with the certified Arb roots, the exact route in Q(sqrt d) and jury's "
    "conditions; an algebraic one by the exact route and jury's conditions in the tower Q(N1, N2, sqrt d) "
    "(a primitive element); all must agree, else exit 3";

static const char qr_check[] =
    "the formula re-parsed from its text and evaluated exactly at random rational points of the domain, against "
    "the exact point verdict over Q(sqrt d) (Schur-Cohn over Q(sqrt d)(i), certified roots, the exact route and "
    "jury's conditions)";

int rs_an_qd_region2(rs_run_t *run, const rs_an_req_t *req)
{
    const char *why = NULL;
    char msg[400];
    slong i, ncrit = 0;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_struct *crit = NULL;
    qr_t Q;
    fmpz_mpoly_struct *h0 = NULL, *h1 = NULL;
    int *hne = NULL, r;
    slong nh = 0;
    memset(&Q, 0, sizeof Q);
    for (i = 0; i < run->c->ncsets; i++) {
        slong k = rs_case_param_index(run->c, run->c->csets[i].name);
        if (k != req->u.region.param && k != req->u.region.param2)
            return rs_an_qd_cx_region2(run, req);   /* over Q(sqrt d)(i) (an_qd_cx2.c) */
    }
    r = rs_region2_variant(&v, run, req);
    if (r != RS_OK) return r;
    s = v->s;
    Q.run = run;
    Q.s = s;
    Q.av = req->u.region.param;
    Q.bv = req->u.region.param2;
    Q.d = s->sqrt_d;
    Q.n = v->cp->degree;
    if (Q.n < 1)
        return rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "%s", "region N1, N2 over Q(sqrt d): p has no "
                            "root (degree 0 in lambda)");
    r = rs_an_qd_jury_conds(&Q.c0, &Q.c1, &Q.ne, &Q.nc, run, req, v, 0);
    if (r == RS_OK) r = rs_an_qd_jury_conds(&h0, &h1, &hne, &nh, run, req, v, 1);
    if (r != RS_OK) {
        qr_conds_clear(Q.c0, Q.c1, Q.ne, Q.nc, s);
        return r;
    }
    Q.a0 = flint_malloc((Q.n + 1) * sizeof(fmpz_mpoly_struct));
    Q.a1 = flint_malloc((Q.n + 1) * sizeof(fmpz_mpoly_struct));
    for (i = 0; i <= Q.n; i++) {
        fmpz_mpoly_t t;
        fmpz_mpoly_init(t, s->zctx);
        fmpz_mpoly_init(Q.a0 + i, s->zctx);
        fmpz_mpoly_init(Q.a1 + i, s->zctx);
        rs_charpoly_coeff(t, v->cp->p, i, s->lambda_var, s->zctx);
        rs_charpoly_coeff(Q.a0 + i, t, 0, s->sqrt_var, s->zctx);
        rs_charpoly_coeff(Q.a1 + i, t, 1, s->sqrt_var, s->zctx);
        fmpz_mpoly_clear(t, s->zctx);
    }
    r = qr_critical(&crit, &ncrit, &why, v->cp->p, h0, h1, nh, s, Q.n);
    if (r != RS_OK) {
        snprintf(msg, sizeof msg, "region N1, N2 over Q(sqrt %ld): p has %s; the region needs a status that "
                 "changes only on curves (jury and hurwitz give the conditions)", (long) Q.d, why);
        r = rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "%s", msg);
    }
    if (r == RS_OK) {
        rs_region_qd_t hook;
        slong before = (slong) json_array_size(run->results);
        hook.crit = crit;
        hook.ncrit = ncrit;
        hook.point = qr_point;
        hook.field = qr_field;
        hook.arg = &Q;
        hook.method = qr_method;
        hook.check_method = qr_check;
        hook.complex_p = 0;
        r = rs_an_region_cad_qd(run, v, Q.av, Q.bv, &hook);
        if (r == RS_ERR_INPUT && run->err->msg[0] == '\0')   /* the plane's only input error */
            r = rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "%s", "the assumptions are contradictory");
        else if (r != RS_OK) r = rs_req_relocate(run, req->q, r, "region");
        if (r == RS_OK && (slong) json_array_size(run->results) == before + 1) {
            json_t *o = json_array_get(run->results, before);
            fmpz_mpoly_t p0, p1;
            fmpz_mpoly_init(p0, s->zctx);
            fmpz_mpoly_init(p1, s->zctx);
            rs_charpoly_coeff(p0, v->cp->p, 0, s->sqrt_var, s->zctx);
            rs_charpoly_coeff(p1, v->cp->p, 1, s->sqrt_var, s->zctx);
            rs_an_qd_json_p(o, p0, p1, run);
            json_object_set_new(o, "norm_note", json_string(
                "the formula's, boundary's and projection's polynomials are norms g0^2 - d g1^2 of polynomials "
                "over Q(sqrt d): exact, but possibly of higher degree than the true boundary curve (a norm also "
                "vanishes on its conjugate's curve; such arcs separate nothing and are left out of boundary)"));
            json_object_set_new(o, "samples_cross_checked", json_pack("{s:I,s:I,s:I,s:I}", "rational_three_ways",
                                (json_int_t) Q.rational, "algebraic_two_ways", (json_int_t) Q.algebraic,
                                "open", (json_int_t) Q.open, "disagree", (json_int_t) Q.disagree));
            fmpz_mpoly_clear(p0, s->zctx);
            fmpz_mpoly_clear(p1, s->zctx);
        }
        if (r == RS_OK && Q.disagree > 0) {
            snprintf(msg, sizeof msg, "region N1, N2 over Q(sqrt %ld): the exact route and jury's conditions "
                     "disagree at %ld algebraic sample(s) (internal inconsistency)", (long) Q.d, (long) Q.disagree);
            r = rs_req_error(run, req->q, req->rest, RS_ERR_INCONSISTENT, "%s", msg);
        }
    }
    for (i = 0; i < ncrit; i++) fmpz_mpoly_clear(crit + i, s->zctx);
    flint_free(crit);
    for (i = 0; i <= Q.n; i++) {
        fmpz_mpoly_clear(Q.a0 + i, s->zctx);
        fmpz_mpoly_clear(Q.a1 + i, s->zctx);
    }
    flint_free(Q.a0);
    flint_free(Q.a1);
    qr_conds_clear(Q.c0, Q.c1, Q.ne, Q.nc, s);
    qr_conds_clear(h0, h1, hne, nh, s);
    return r;
}
