/* an_qd_map.c -- `map re(NAME) A B N, im(NAME) C D M` of a model over
 * Q(sqrt d) (rk sdirk2, sdirk3): the z-plane of one parameter, drawn by
 * an_complex.c's map (the same grid, table, JSON and locus) with p =
 * P0 + sqrt(d) P1 split here and each point decided over Q(sqrt d)(i) as
 * `stability` decides it there (rs_qdc_stable_checked: Schur-Cohn with
 * exact signs in Q(sqrt d) and the certified Arb roots, which must agree). */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/an_qd.h"
#include "recstab/charpoly.h"
#include "analysis/sweep_impl.h"
#include "recstab/bilinear.h"

/* a JSON string of a flint-allocated text (freed) */
static json_t *json_string_free_flint(char *t)
{
    json_t *j = json_string(t);
    flint_free(t);
    return j;
}

int rs_an_qd_zplane_coeffs(fmpq_poly_struct **CR, fmpq_poly_struct **CS, slong *K, slong *n, const rs_variant_t *v,
                           slong param)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t part;
    slong k, j;
    *K = fmpz_mpoly_degree_si(v->cp->p, param, s->zctx);
    *n = fmpz_mpoly_degree_si(v->cp->p, s->lambda_var, s->zctx);
    *CR = flint_malloc((FLINT_MAX(*K, 0) + 1) * sizeof(fmpq_poly_struct));
    *CS = flint_malloc((FLINT_MAX(*K, 0) + 1) * sizeof(fmpq_poly_struct));
    for (k = 0; k <= FLINT_MAX(*K, 0); k++) {
        fmpq_poly_init(*CR + k);
        fmpq_poly_init(*CS + k);
    }
    fmpz_mpoly_init(part, s->zctx);
    for (j = 0; j < 2; j++) {
        /* p's part without sqrt(d) (j = 0) and its sqrt(d) part (j = 1) */
        rs_charpoly_coeff(part, v->cp->p, j, s->sqrt_var, s->zctx);
        for (k = 0; k <= *K; k++) {
            fmpz_poly_t c;
            fmpz_poly_init(c);
            rs_run_coeff_in(c, part, param, k, s);
            fmpq_poly_set_fmpz_poly((j == 0 ? *CR : *CS) + k, c);
            fmpz_poly_clear(c);
        }
    }
    fmpz_mpoly_clear(part, s->zctx);
    return 1;
}

int rs_an_qd_zplane_verdict(int *code, const fmpq_poly_t re0, const fmpq_poly_t im0, const fmpq_poly_t re1,
                            const fmpq_poly_t im1, slong n, slong d)
{
    const fmpq_poly_struct *e[4] = {re0, re1, im0, im1};
    rs_qdc_struct *c = rs_qdc_vec_init(n + 1);
    slong k, deg = -1;
    int j, sc = 1;
    for (j = 0; j < 4; j++) {
        deg = FLINT_MAX(deg, fmpq_poly_degree(e[j]));
        for (k = 0; k <= n; k++) {
            rs_qd_struct *x = j < 2 ? c[k].re : c[k].im;
            fmpq_poly_get_coeff_fmpq((j & 1) ? x->y : x->x, e[j], k);
        }
    }
    /* x + sqrt(d) y = 0 only for x = y = 0: the degree over Q(sqrt d)(i) is deg */
    if (deg < 0) *code = -1;                            /* p vanishes: undefined */
    else if (deg < n) *code = RS_STATUS_SINGULAR;       /* the step is not determined */
    else {
        sc = rs_qdc_stable_checked(NULL, c, n, d);
        /* -1: a root on or too near the circle, marginal and unstable not told apart */
        *code = sc == 1 ? RS_STATUS_STABLE : sc == 0 ? RS_STATUS_UNSTABLE : 4;
    }
    rs_qdc_vec_clear(c, n + 1);
    return sc == -2 ? RS_ERR_INCONSISTENT : RS_OK;
}

char *rs_an_qd_fmpq_poly_str(const fmpq_poly_t a0, const fmpq_poly_t a1, slong d)
{
    char *s0 = fmpq_poly_get_str_pretty(a0, "lambda"), *s1 = fmpq_poly_get_str_pretty(a1, "lambda");
    size_t len = strlen(s0) + strlen(s1) + 40;
    char *out = malloc(len);
    if (fmpq_poly_is_zero(a1)) snprintf(out, len, "%s", s0);
    else if (fmpq_poly_is_zero(a0)) snprintf(out, len, "sqrt(%ld)*(%s)", (long) d, s1);
    else snprintf(out, len, "%s + sqrt(%ld)*(%s)", s0, (long) d, s1);
    flint_free(s0);
    flint_free(s1);
    return out;
}

void rs_an_qd_zplane_json(json_t *o, rs_run_t *run, slong undecided, slong checked)
{
    char over[60], m[80];
    slong d = run->m->qd->d;
    snprintf(over, sizeof over, "Q(sqrt %ld)(i)", (long) d);
    snprintf(m, sizeof m, "rk %s", run->m->qd->tableau);
    json_object_set_new(o, "over", json_string(over));
    json_object_set_new(o, "rk", json_string(m));
    json_object_set_new(json_object_get(o, "verdicts"), "undecided", json_integer(undecided));
    json_object_set_new(o, "methods", json_pack("[ss]", "schur-cohn over Q(sqrt d)(i), exact signs",
                                                "certified roots (Arb, sqrt d a ball)"));
    json_object_set_new(o, "cross_check", json_pack("{sIss}", "points", (json_int_t) checked, "method",
                        "every point by both: Schur-Cohn over Q(sqrt d)(i) stable iff every certified root is "
                        "inside, not stable iff a root is certified outside or not separated from the circle "
                        "(exit 3 on disagreement)"));
    if (undecided > 0)
        json_object_set_new(o, "note", json_string("undecided: not strictly stable (Schur-Cohn) with a root on or "
                            "too near the unit circle; marginal and unstable are not told apart over Q(sqrt d)"));
}

/* bilinear over Q(sqrt d): q(z) = (1 - z)^n p((1 + z)/(1 - z)) with
 * sqrt(d) a variable (p is linear in it, so q is), the real set values
 * substituted; JSON as over Q plus "over", "q0", "q1" (q = q0 + sqrt(d) q1)
 * and the coefficients as "c0 + sqrt(d)*(c1)" */
int rs_an_qd_bilinear(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_t qz, q0, q1, a0, a1;
    json_t *o, *co;
    slong d, lv, k;
    int r;
    (void) req;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    lv = s->lambda_var;
    fmpz_mpoly_init(qz, s->zctx); fmpz_mpoly_init(q0, s->zctx); fmpz_mpoly_init(q1, s->zctx);
    fmpz_mpoly_init(a0, s->zctx); fmpz_mpoly_init(a1, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, lv, s->zctx);
    rs_scheme_reduce_sqrt(qz, s);
    rs_charpoly_coeff(q0, qz, 0, s->sqrt_var, s->zctx);
    rs_charpoly_coeff(q1, qz, 1, s->sqrt_var, s->zctx);
    d = fmpz_mpoly_degree_si(qz, lv, s->zctx);
    co = json_array();
    for (k = 0; k <= d; k++) {
        rs_charpoly_coeff(a0, q0, k, lv, s->zctx);
        rs_charpoly_coeff(a1, q1, k, lv, s->zctx);
        json_array_append_new(co, json_string_free_flint(rs_an_qd_mpoly_str(a0, a1, s, 0)));
    }
    o = json_object();
    json_object_set_new(o, "analysis", json_string("bilinear"));
    json_object_set_new(o, "var", json_string("z"));
    json_object_set_new(o, "degree", json_integer(d));
    json_object_set_new(o, "coeffs", co);
    json_object_set_new(o, "poly", rs_json_collected(qz, lv, s, "z"));
    json_object_set_new(o, "degree_drop", json_integer(v->cp->degree - d));
    json_object_set_new(o, "zero_mult", json_integer(rs_scheme_min_degree(qz, lv, s->zctx)));
    json_object_set_new(o, "p_at_1", rs_json_p_at(v, 1));
    json_object_set_new(o, "p_at_minus_1", rs_json_p_at(v, -1));
    json_object_set_new(o, "over", json_string_free_flint(rs_an_qd_over_str(s->sqrt_d)));
    json_object_set_new(o, "q0", rs_json_collected(q0, lv, s, "z"));
    json_object_set_new(o, "q1", rs_json_collected(q1, lv, s, "z"));
    rs_run_emit_exact(run, v, o);
    fmpz_mpoly_clear(qz, s->zctx); fmpz_mpoly_clear(q0, s->zctx); fmpz_mpoly_clear(q1, s->zctx);
    fmpz_mpoly_clear(a0, s->zctx); fmpz_mpoly_clear(a1, s->zctx);
    return RS_OK;
}

/* ---- sweep NAME ... of stability over Q(sqrt d) ---------------------------------- */

typedef struct {
    fmpq_poly_struct *CR, *CS;
    slong K, n, d;
    const fmpq *vals;
} qd_sweep_t;

/* the verdict at vals[idx]: p = sum_k (CR[k] + sqrt(d) CS[k]) x^k, real */
static void qd_sweep_point(rs_sweep_row_t *row, slong idx, void *model, rs_error_t err)
{
    const qd_sweep_t *S = model;
    fmpq_poly_t re0, re1, zero;
    slong k;
    int r, code = -1;
    fmpq_poly_init(re0); fmpq_poly_init(re1); fmpq_poly_init(zero);
    for (k = S->K; k >= 0; k--) {   /* Horner in the swept value */
        fmpq_poly_scalar_mul_fmpq(re0, re0, S->vals + idx);
        fmpq_poly_add(re0, re0, S->CR + k);
        fmpq_poly_scalar_mul_fmpq(re1, re1, S->vals + idx);
        fmpq_poly_add(re1, re1, S->CS + k);
    }
    r = rs_an_qd_zplane_verdict(&code, re0, zero, re1, zero, S->n, S->d);
    if (r != RS_OK) rs_error_set(err, r, "Schur-Cohn over Q(sqrt %ld)(i) and the certified roots disagree",
                                 (long) S->d);
    row->d.status = r;
    row->d.verdict = r == RS_OK ? code : -1;
    row->d.level = RS_LEVEL_EXACT;
    row->inside = -1;   /* no counts: the verdict's two routes only */
    fmpq_poly_clear(re0); fmpq_poly_clear(re1); fmpq_poly_clear(zero);
}

int rs_an_qd_sweep_model(rs_sweep_model_t *m, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v,
                         slong var, const fmpq *vals)
{
    qd_sweep_t *S = calloc(1, sizeof *S);
    m->model = S;
    m->point = qd_sweep_point;
    m->serial = 0;
    S->vals = vals;
    S->d = v->s->sqrt_d;
    rs_an_qd_zplane_coeffs(&S->CR, &S->CS, &S->K, &S->n, v, var);
    if (rs_run_count_free(v->cp->p, v->s, var) > 0)
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "sweep over Q(sqrt d) needs the other parameters set "
                            "to numbers%s", "");
    if (S->n < 1)
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "sweep: the characteristic polynomial must depend on "
                            "lambda%s", "");
    return RS_OK;
}

void rs_an_qd_sweep_model_free(rs_sweep_model_t *m)
{
    qd_sweep_t *S = m->model;
    slong k;
    if (S == NULL) return;
    for (k = 0; k <= FLINT_MAX(S->K, 0); k++) {
        fmpq_poly_clear(S->CR + k);
        fmpq_poly_clear(S->CS + k);
    }
    flint_free(S->CR);
    flint_free(S->CS);
    free(S);
    m->model = NULL;
}

void rs_an_qd_sweep_json(json_t *o, rs_run_t *run, const json_t *verdicts)
{
    char m[80];
    snprintf(m, sizeof m, "rk %s", run->m->qd->tableau);
    json_object_set_new(o, "over", json_string_free_flint(rs_an_qd_over_str(run->m->qd->d)));
    json_object_set_new(o, "rk", json_string(m));
    json_object_set_new(o, "method", json_string(
        "p over Q(sqrt d) at each point: Schur-Cohn over Q(sqrt d)(i) with exact signs and the certified roots "
        "(Arb, sqrt d a ball), which must agree at every point (exit 3 otherwise); undecided: a root on or too "
        "near the circle, marginal and unstable not told apart over Q(sqrt d)"));
    (void) verdicts;
}
