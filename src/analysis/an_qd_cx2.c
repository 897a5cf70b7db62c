/* an_qd_cx2.c -- issue 15: `region N1, N2` of a model over Q(sqrt d) (rk
 * sdirk2, sdirk3, ...) at complex set values of other parameters: p = re +
 * i im over Q(sqrt d)(i)[N1, N2] (an_qd_complex.c builds it and both
 * condition lists: Schur-Cohn's delta_k > 0 and Bilharz's on the bilinear
 * image, each c0 + sqrt(d) c1 > 0 with c0, c1 in Z[N1, N2]).
 *
 * Every list's condition keeps its sign on a cell where its norm c0^2 - d
 * c1^2 and its parts c0, c1 keep theirs, and |a_n|^2 (zero exactly where
 * the step is singular) likewise; so the rational CAD (an_region_cad.c) on
 * those polynomials has a constant verdict on each cell: stable iff every
 * condition holds, and where no delta_k vanishes Schur-Cohn's recursion is
 * regular (no root on the circle), so not stable is unstable there.
 *   - a rational sample: both lists' exact signs in Q(sqrt d) and
 *     Schur-Cohn over Q(sqrt d)(i) with the certified Arb roots
 *     (rs_an_qd_parts_verdict);
 *   - an algebraic sample (N1, N2) = (A, B)(g): both lists' exact signs in
 *     the tower Q(g, sqrt d) = Q(h).
 * Where a delta_k vanishes a root is on the circle: with deg p = 1 (the
 * test equation) that root is simple, marginal; else the cell is left
 * undecided with why (unless a root is certified outside).
 * The lists disagreeing anywhere is exit 3. */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "analysis/an_region.h"

typedef struct {
    rs_run_t *run;
    const rs_scheme_struct *s;
    slong av, bv, n;
    const rs_an_qd_conds_t *L[2];        /* Schur-Cohn, Bilharz */
    const fmpz_mpoly_struct *const *part;
    fmpz_mpoly_t l0, l1;                 /* |a_n|^2 = l0 + sqrt(d) l1 */
    slong rational, algebraic, open, disagree;
} qx_t;

/* list m's conditions at h (e: c0 + sqrt(d) c1 in Q(h)): 1 all hold; *zero
 * set when one of them is 0 there */
static int qx_hold_in(int *zero, const qx_t *X, int m, const fmpq_poly_t Ah, const fmpq_poly_t Bh,
                      const fmpq_poly_t Sq, const fmpq_poly_t mp, rs_alg_t *h)
{
    const rs_an_qd_conds_t *q = X->L[m];
    fmpq_poly_t e0, e1;
    slong k;
    int holds = !q->never;
    *zero = 0;
    fmpq_poly_init(e0); fmpq_poly_init(e1);
    for (k = 0; k < q->n; k++) {
        int sg;
        rs_region_eval_field(e0, q->c0 + k, X->av, X->bv, Ah, Bh, mp, X->s->zctx);
        rs_region_eval_field(e1, q->c1 + k, X->av, X->bv, Ah, Bh, mp, X->s->zctx);
        fmpq_poly_mul(e1, e1, Sq);
        fmpq_poly_add(e0, e0, e1);
        fmpq_poly_rem(e0, e0, mp);
        sg = rs_alg_sign(e0, h);
        if (sg == 0) *zero = 1;
        if (q->ne[k] ? sg == 0 : sg <= 0) holds = 0;
    }
    fmpq_poly_clear(e0); fmpq_poly_clear(e1);
    return holds;
}

/* the status at (N1, N2) = (Ah, Bh)(h), sqrt(d) = Sq(h), in Q(h) by both
 * lists' exact signs: 1 decided, 0 not (a delta_k zero, deg p >= 2), -1
 * the lists disagree (counted, the run marked inconsistent) */
static int qx_status_in(rs_status_t *st, qx_t *X, const fmpq_poly_t Ah, const fmpq_poly_t Bh, const fmpq_poly_t Sq,
                        rs_alg_t *h)
{
    fmpq_poly_t mp, e0, e1;
    int z0, z1, h0, h1, dec = 0;
    fmpq_poly_init(mp); fmpq_poly_init(e0); fmpq_poly_init(e1);
    fmpq_poly_set_fmpz_poly(mp, h->minpoly);
    rs_region_eval_field(e0, X->l0, X->av, X->bv, Ah, Bh, mp, X->s->zctx);
    rs_region_eval_field(e1, X->l1, X->av, X->bv, Ah, Bh, mp, X->s->zctx);
    fmpq_poly_mul(e1, e1, Sq);
    fmpq_poly_add(e0, e0, e1);
    fmpq_poly_rem(e0, e0, mp);
    h0 = qx_hold_in(&z0, X, 0, Ah, Bh, Sq, mp, h);
    h1 = qx_hold_in(&z1, X, 1, Ah, Bh, Sq, mp, h);
    if (h0 != h1) {
        X->disagree++;
        X->run->outcome |= RS_OUTCOME_INCONSISTENT;
        dec = -1;
    } else if (rs_alg_sign(e0, h) == 0) {
        *st = RS_STATUS_SINGULAR;   /* a_n = 0: no step */
        dec = 1;
    } else if (h0 || !z0) {
        /* no delta_k zero: no root on the circle, not stable is unstable */
        *st = h0 ? RS_STATUS_STABLE : RS_STATUS_UNSTABLE;
        dec = 1;
    } else if (X->n == 1) {
        /* one root, |a_1|^2 - |a_0|^2 = 0: on the circle, simple */
        *st = RS_STATUS_MARGINAL;
        dec = 1;
    }
    fmpq_poly_clear(mp); fmpq_poly_clear(e0); fmpq_poly_clear(e1);
    return dec;
}

/* rs_region_qd_t's field: (A, B)(g) in Q(g, sqrt d) = Q(h) by both lists */
static int qx_field(rs_status_t *st, const fmpq_poly_t A, const fmpq_poly_t B, rs_alg_t *g, void *arg)
{
    qx_t *X = arg;
    rs_alg_t sq, h;
    fmpq_poly_t G, Sq, Ah, Bh, mp;
    int dec = 0;
    rs_alg_init(&sq); rs_alg_init(&h);
    fmpq_poly_init(G); fmpq_poly_init(Sq); fmpq_poly_init(Ah); fmpq_poly_init(Bh); fmpq_poly_init(mp);
    rs_an_qd_sqrt_alg(&sq, X->s->sqrt_d);
    if (rs_alg_primitive(&h, G, Sq, g, &sq)) {
        fmpq_poly_set_fmpz_poly(mp, h.minpoly);
        fmpq_poly_compose(Ah, A, G);
        fmpq_poly_rem(Ah, Ah, mp);
        fmpq_poly_compose(Bh, B, G);
        fmpq_poly_rem(Bh, Bh, mp);
        dec = qx_status_in(st, X, Ah, Bh, Sq, &h);
    }
    if (dec == 1) X->algebraic++;
    else if (dec == 0) X->open++;
    rs_alg_clear(&sq); rs_alg_clear(&h);
    fmpq_poly_clear(G); fmpq_poly_clear(Sq); fmpq_poly_clear(Ah); fmpq_poly_clear(Bh); fmpq_poly_clear(mp);
    return dec == 1;
}

/* rs_region_qd_t's point: both lists' exact signs in Q(sqrt d) against the
 * exact point verdict (Schur-Cohn over Q(sqrt d)(i), the certified roots) */
static int qx_point(rs_status_t *st, const fmpq *vals, void *arg)
{
    qx_t *X = arg;
    const rs_scheme_struct *s = X->s;
    fmpq *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
    rs_alg_t sq;
    fmpq_poly_t A, B, S;
    slong k;
    int dec, vd, bad, r = RS_OK;
    char *msg = NULL, *x = fmpq_get_str(NULL, 10, vals + 0), *y = fmpq_get_str(NULL, 10, vals + 1);
    rs_alg_init(&sq);
    fmpq_poly_init(A); fmpq_poly_init(B); fmpq_poly_init(S);
    rs_an_qd_sqrt_alg(&sq, s->sqrt_d);
    fmpq_poly_set_fmpq(A, vals + 0);
    fmpq_poly_set_fmpq(B, vals + 1);
    fmpq_poly_set_coeff_si(S, 1, 1);
    dec = qx_status_in(st, X, A, B, S, &sq);
    for (k = 0; k < s->nvars; k++) pp[k] = pt + k;
    fmpq_set(pt + X->av, vals + 0);
    fmpq_set(pt + X->bv, vals + 1);
    /* 1 stable, 0 a root certified outside, -1 not stable (on or near the
     * circle), -2 its routes disagree, -3 / -4 singular */
    vd = rs_an_qd_parts_verdict(X->part, X->n, pp, s);
    bad = dec == -1 || vd == -2 || (dec == 1 && ((*st == RS_STATUS_STABLE) != (vd == 1)
                                                 || (*st == RS_STATUS_SINGULAR) != (vd < -2)
                                                 || (vd == 0 && *st != RS_STATUS_UNSTABLE)));
    if (bad) {
        X->run->outcome |= RS_OUTCOME_INCONSISTENT;
        rs_str_catf(&msg, "region N1, N2 over Q(sqrt %ld)(i): at (%s, %s) the Schur-Cohn and the Bilharz "
                    "conditions, Schur-Cohn over Q(sqrt d)(i) and the certified roots disagree (internal "
                    "inconsistency)", (long) s->sqrt_d, x, y);
        r = rs_error_set(X->run->err, RS_ERR_INCONSISTENT, "%s", msg);
    } else if (dec == 1 || vd == 0) {
        if (dec != 1) *st = RS_STATUS_UNSTABLE;   /* a delta_k zero, a root certified outside */
        X->rational++;
    } else {
        rs_str_catf(&msg, "region N1, N2 over Q(sqrt %ld)(i): at the sample (%s, %s) a root on or too near the "
                    "unit circle: marginal and unstable are not told apart there", (long) s->sqrt_d, x, y);
        r = rs_error_set(X->run->err, RS_ERR_UNDECIDED, "%s", msg);
    }
    flint_free(msg);
    flint_free(x);
    flint_free(y);
    rs_alg_clear(&sq);
    fmpq_poly_clear(A); fmpq_poly_clear(B); fmpq_poly_clear(S);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    return r;
}

static const char qx_method[] =
    "cylindrical algebraic decomposition of the plane (Collins) over Q(sqrt d)(i): the Schur-Cohn conditions over "
    "Q(sqrt d)(i) (jury's, delta_k = |a_k|^2 - |a_0|^2 > 0), the Bilharz conditions (hurwitz's) and |a_n|^2, each "
    "g = g0 + sqrt(d) g1, replaced by their norms g0^2 - d g1^2 and parts g0, g1 in Z[N1, N2], their projection "
    "onto the first parameter; one verdict per cell: a rational sample three ways (both lists' exact signs and "
    "Schur-Cohn over Q(sqrt d)(i) with the certified Arb roots; a root on or near the circle: undecided), an "
    "algebraic one by both lists' exact signs in the tower Q(N1, N2, sqrt d) (no delta_k zero there: no root on "
    "the circle, so not stable is unstable); all must agree, else exit 3";

static const char qx_check[] =
    "the formula re-parsed from its text and evaluated exactly at random rational points of the domain, against "
    "the exact point verdict over Q(sqrt d)(i) (both condition lists, Schur-Cohn over Q(sqrt d)(i) and the "
    "certified roots)";

int rs_an_qd_cx_plane(rs_run_t *run, const rs_an_req_t *req, const rs_variant_t *v, const slong *tv,
                      const rs_an_qd_conds_t *q, const rs_an_qd_conds_t *alt, const fmpz_mpoly_struct *const *part,
                      slong n, const fmpz_mpoly_t lead, json_t *ex)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_struct *crit = NULL;
    slong ncrit = 0, k;
    int m, r;
    qx_t X;
    rs_region_qd_t hook;
    memset(&X, 0, sizeof X);
    memset(&hook, 0, sizeof hook);
    X.run = run;
    X.s = s;
    X.av = tv[0];
    X.bv = tv[1];
    X.n = n;
    X.L[0] = q;
    X.L[1] = alt;
    X.part = part;
    fmpz_mpoly_init(X.l0, s->zctx); fmpz_mpoly_init(X.l1, s->zctx);
    rs_charpoly_coeff(X.l0, lead, 0, s->sqrt_var, s->zctx);
    rs_charpoly_coeff(X.l1, lead, 1, s->sqrt_var, s->zctx);
    rs_an_qd_push_norm(&crit, &ncrit, lead, NULL, 1, s);
    for (m = 0; m < 2; m++)
        for (k = 0; k < X.L[m]->n; k++)
            rs_an_qd_push_norm(&crit, &ncrit, X.L[m]->c0 + k, X.L[m]->c1 + k, 1, s);
    hook.crit = crit;
    hook.ncrit = ncrit;
    hook.point = qx_point;
    hook.field = qx_field;
    hook.arg = &X;
    hook.method = qx_method;
    hook.check_method = qx_check;
    hook.complex_p = 1;
    {
        slong before = (slong) json_array_size(run->results);
        r = rs_an_region_cad_qd(run, v, X.av, X.bv, &hook);
        if (r == RS_ERR_INPUT && run->err->msg[0] == '\0')   /* the plane's only input error */
            r = rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "%s", "the assumptions are contradictory");
        else if (r != RS_OK) r = rs_req_relocate(run, req->q, r, "region");
        if (r == RS_OK && (slong) json_array_size(run->results) == before + 1) {
            json_t *o = json_array_get(run->results, before), *sub = json_object_get(o, "substituted");
            json_object_update(o, ex);
            if (json_is_object(sub)) json_object_update_new(sub, rs_run_cx_at(run));
            json_object_set_new(o, "norm_note", json_string(
                "norms over Q(sqrt d) as in region N1, N2 with real set values: exact, the curves of both "
                "conjugates, so possibly of higher degree than the true boundary"));
            json_object_set_new(o, "samples_cross_checked", json_pack("{s:I,s:I,s:I,s:I}", "rational_three_ways",
                                (json_int_t) X.rational, "algebraic_two_ways", (json_int_t) X.algebraic,
                                "open", (json_int_t) X.open, "disagree", (json_int_t) X.disagree));
        }
        if (r == RS_OK && X.disagree > 0) {
            char *msg = NULL;
            rs_str_catf(&msg, "region N1, N2 over Q(sqrt %ld)(i): the Schur-Cohn and the Bilharz conditions "
                        "disagree at %ld algebraic sample(s) (internal inconsistency)", (long) s->sqrt_d,
                        (long) X.disagree);
            r = rs_req_error(run, req->q, req->rest, RS_ERR_INCONSISTENT, "%s", msg);
            flint_free(msg);
        }
    }
    for (k = 0; k < ncrit; k++) fmpz_mpoly_clear(crit + k, s->zctx);
    flint_free(crit);
    fmpz_mpoly_clear(X.l0, s->zctx); fmpz_mpoly_clear(X.l1, s->zctx);
    return r;
}
