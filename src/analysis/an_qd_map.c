/* an_qd_map.c -- `map re(NAME) A B N, im(NAME) C D M` of a model over
 * Q(sqrt d) (rk sdirk2, sdirk3): the z-plane of one parameter, drawn by
 * an_complex.c's map (the same grid, table, JSON and locus) with p =
 * P0 + sqrt(d) P1 split here and each point decided over Q(sqrt d)(i) as
 * `stability` decides it there (rs_qdc_stable_checked: Schur-Cohn with
 * exact signs in Q(sqrt d) and the certified Arb roots, which must agree). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpq_vec.h>
#include <acb_poly.h>
#include "numeric/grid.h"
#include "analysis/an_qd.h"
#include "recstab/charpoly.h"
#include "analysis/sweep_impl.h"
#include "recstab/bilinear.h"
#include "recstab/ladder.h"
#include "recstab/radius.h"

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
        *code = sc == 1 ? RS_STATUS_STABLE : sc == 0 ? RS_STATUS_UNSTABLE : RS_SWEEP_UNDECIDED;
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

/* ---- sweep and map of real parameters over Q(sqrt d) ------------------------------ */

typedef struct {
    const rs_scheme_struct *s;
    fmpz_mpoly_t p0, p1;      /* p = p0 + sqrt(d) p1, every parameter but the axes set */
    slong n, d, naxes, var[2], K1, max_prec;
    int of;
    const fmpq *vals[2];
} qd_sweep_t;

/* the certified radius of p = re0 + sqrt(d) re1 (sqrt(d) a ball) into row;
 * it must agree with the exact verdict: stable needs rho < 1 possible,
 * unstable rho > 1 possible (RS_ERR_INCONSISTENT otherwise) */
static int qd_sweep_radius(rs_sweep_row_t *row, const fmpq_poly_t re0, const fmpq_poly_t re1, const qd_sweep_t *S,
                           rs_error_t err)
{
    rs_qdc_struct *c = rs_qdc_vec_init(S->n + 1);
    acb_poly_t p;
    rs_radius_t rr;
    slong k, prec = 128;
    int r;
    for (k = 0; k <= S->n; k++) {
        fmpq_poly_get_coeff_fmpq(c[k].re->x, re0, k);
        fmpq_poly_get_coeff_fmpq(c[k].re->y, re1, k);
    }
    acb_poly_init(p);
    rs_radius_init(rr);
    acb_poly_fit_length(p, S->n + 1);
    rs_qdc_vec_get_acb(p->coeffs, c, S->n + 1, S->d, prec);
    _acb_poly_set_length(p, S->n + 1);
    _acb_poly_normalise(p);
    r = rs_radius_acb_poly(rr, p, 15, S->max_prec, err);
    if (r == RS_OK) {
        row->d.rho_lower = rs_ladder_lower_d(rr->lower);
        row->d.rho_upper = rs_ladder_upper_d(rr->upper);
        row->d.isolated = rr->isolated;
        /* the doubles are rounded outward: a contradiction here is one of the exact bounds */
        if ((row->d.verdict == RS_STATUS_STABLE && row->d.rho_lower >= 1)
            || (row->d.verdict == RS_STATUS_UNSTABLE && row->d.rho_upper <= 1))
            r = rs_error_set(err, RS_ERR_INCONSISTENT, "over Q(sqrt %ld): the exact verdict is %s, the certified "
                             "radius [%g, %g]", (long) S->d, rs_sweep_verdict_name(row->d.verdict),
                             row->d.rho_lower, row->d.rho_upper);
    } else {
        /* the exact verdict stands; the radius is only what was certified (a root cluster: partial) */
        row->d.rho_lower = rr->partial ? rs_ladder_lower_d(rr->lower) : 0;
        row->d.rho_upper = rr->partial ? rs_ladder_upper_d(rr->upper) : INFINITY;
        r = RS_OK;
    }
    rs_radius_clear(rr);
    acb_poly_clear(p);
    rs_qdc_vec_clear(c, S->n + 1);
    return r;
}

/* the verdict at point idx (index j*K1 + i of a map): p0, p1 evaluated
 * exactly, the verdict by rs_an_qd_zplane_verdict's two routes, `of
 * radius` the certified radius beside it */
static void qd_sweep_point(rs_sweep_row_t *row, slong idx, void *model, rs_error_t err)
{
    const qd_sweep_t *S = model;
    fmpq *x = _fmpq_vec_init(S->s->nvars);
    fmpq **pt = flint_malloc((size_t) S->s->nvars * sizeof(fmpq *));
    fmpq_poly_t re0, re1, zero;
    slong k;
    int r, code = -1;
    memset(row, 0, sizeof *row);
    row->inside = row->on = row->outside = -1;   /* no counts: the verdict's two routes only */
    row->d.rho_lower = 0;
    row->d.rho_upper = INFINITY;
    row->d.level = RS_LEVEL_EXACT;
    for (k = 0; k < S->s->nvars; k++) pt[k] = x + k;
    if (S->naxes == 1) fmpq_set(x + S->var[0], S->vals[0] + idx);
    else {
        fmpq_set(x + S->var[0], S->vals[0] + idx % S->K1);
        fmpq_set(x + S->var[1], S->vals[1] + idx / S->K1);
    }
    fmpq_poly_init(re0); fmpq_poly_init(re1); fmpq_poly_init(zero);
    rs_run_cx_eval(re0, S->p0, pt, S->s);
    rs_run_cx_eval(re1, S->p1, pt, S->s);
    r = rs_an_qd_zplane_verdict(&code, re0, zero, re1, zero, S->n, S->d);
    if (r != RS_OK) rs_error_set(err, r, "Schur-Cohn over Q(sqrt %ld)(i) and the certified roots disagree",
                                 (long) S->d);
    row->d.status = r;
    row->d.verdict = r == RS_OK ? code : -1;
    if (r == RS_OK && S->of == RS_SWEEP_OF_RADIUS && code >= 0 && code != RS_STATUS_SINGULAR) {
        r = qd_sweep_radius(row, re0, re1, S, err);
        row->d.status = r;
        if (r != RS_OK) row->d.verdict = -1;
    }
    fmpq_poly_clear(re0); fmpq_poly_clear(re1); fmpq_poly_clear(zero);
    _fmpq_vec_clear(x, S->s->nvars);
    flint_free(pt);
}

int rs_an_qd_sweep_model(rs_sweep_model_t *m, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                         const rs_variant_t *v, const fmpq *const *vals)
{
    qd_sweep_t *S = calloc(1, sizeof *S);
    const rs_scheme_struct *s = v->s;
    slong k, nfree;
    m->model = S;
    m->point = qd_sweep_point;
    m->serial = 0;
    S->s = s;
    S->d = s->sqrt_d;
    S->of = R->of;
    S->naxes = R->naxes;
    S->K1 = R->axis[0].count;
    S->max_prec = run->opt->max_prec;
    fmpz_mpoly_init(S->p0, s->zctx);
    fmpz_mpoly_init(S->p1, s->zctx);
    rs_charpoly_coeff(S->p0, v->cp->p, 0, s->sqrt_var, s->zctx);
    rs_charpoly_coeff(S->p1, v->cp->p, 1, s->sqrt_var, s->zctx);
    S->n = fmpz_mpoly_degree_si(v->cp->p, s->lambda_var, s->zctx);
    for (k = 0; k < R->naxes; k++) {
        S->var[k] = R->axis[k].var;
        S->vals[k] = vals[k];
    }
    nfree = rs_run_count_free(v->cp->p, s, S->var[0]);
    if (R->naxes == 2 && fmpz_mpoly_degree_si(v->cp->p, S->var[1], s->zctx) > 0) nfree--;
    if (nfree > 0)
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s over Q(sqrt d) needs the other parameters set "
                            "to numbers", R->naxes == 1 ? "sweep" : "map");
    if (S->n < 1)
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s: the characteristic polynomial must depend on "
                            "lambda", R->naxes == 1 ? "sweep" : "map");
    return RS_OK;
}

void rs_an_qd_sweep_model_free(rs_sweep_model_t *m)
{
    qd_sweep_t *S = m->model;
    if (S == NULL) return;
    fmpz_mpoly_clear(S->p0, S->s->zctx);
    fmpz_mpoly_clear(S->p1, S->s->zctx);
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
    if (strcmp(json_string_value(json_object_get(o, "of")) ? json_string_value(json_object_get(o, "of")) : "", "radius")
        == 0)
        json_object_set_new(o, "radius_method", json_string(
            "the spectral radius of p = p0 + sqrt(d) p1 from its certified roots (Arb, sqrt d a ball), printed "
            "rounded outward; it must agree with the exact verdict (stable: lower end < 1, unstable: upper end "
            "> 1; exit 3 otherwise)"));
    (void) verdicts;
}

/* ---- map N1 ..., N2 ... of two real parameters over Q(sqrt d) --------------------- */

typedef struct {
    rs_run_t *run;
    const rs_an_req_t *req;
    rs_variant_t *v;
    const rs_sweep_request_t *R;
    fmpq *const *xs;
} qd_deco_t;

/* the map's "over", "rk", "method", and where p depends on both axes the
 * boundary: the norms c0^2 - d c1^2 of jury's conditions c0 + sqrt(d) c1
 * over Q(sqrt d)[N1, N2] and of the leading coefficient (the norm vanishes
 * where the condition or its conjugate does: a superset of the boundary) */
static void qd_map_decorate(json_t *o, void *arg)
{
    qd_deco_t *D = arg;
    const rs_scheme_struct *s = D->v->s;
    const rs_sweep_axis_t *X = D->R->axis;
    rs_error_struct saved = *D->run->err;
    fmpz_mpoly_struct *c0 = NULL, *c1 = NULL, *g;
    fmpz_mpoly_t a, a0, a1;
    char **org;
    int *ne = NULL;
    slong n = 0, k, ng;
    rs_an_qd_sweep_json(o, D->run, NULL);
    if (fmpz_mpoly_degree_si(D->v->cp->p, X[0].var, s->zctx) <= 0
        || fmpz_mpoly_degree_si(D->v->cp->p, X[1].var, s->zctx) <= 0)
        return;
    if (rs_an_qd_jury_conds(&c0, &c1, &ne, &n, D->run, D->req, D->v, 0) != RS_OK) {
        json_object_set_new(o, "boundary_note", json_string(D->run->err->msg));
        *D->run->err = saved;
        return;
    }
    g = flint_malloc((size_t) (n + 1) * sizeof(fmpz_mpoly_struct));
    org = flint_malloc((size_t) (n + 1) * sizeof(char *));
    fmpz_mpoly_init(a, s->zctx); fmpz_mpoly_init(a0, s->zctx); fmpz_mpoly_init(a1, s->zctx);
    rs_charpoly_coeff(a, D->v->cp->p, fmpz_mpoly_degree_si(D->v->cp->p, s->lambda_var, s->zctx), s->lambda_var,
                      s->zctx);
    rs_charpoly_coeff(a0, a, 0, s->sqrt_var, s->zctx);
    rs_charpoly_coeff(a1, a, 1, s->sqrt_var, s->zctx);
    fmpz_mpoly_init(g, s->zctx);
    rs_an_qd_mpoly_norm(g, a0, a1, s);
    org[0] = strdup("norm of the leading coefficient a_n");
    for (k = 0, ng = 1; k < n; k++, ng++) {
        char buf[96];
        fmpz_mpoly_init(g + ng, s->zctx);
        rs_an_qd_mpoly_norm(g + ng, c0 + k, c1 + k, s);
        snprintf(buf, sizeof buf, "norm of jury's condition %ld, Schur-Cohn over Q(sqrt %ld)", (long) k + 1,
                 (long) s->sqrt_d);
        org[ng] = strdup(buf);
    }
    rs_an_map_boundary_factors(o, D->run, D->v, D->R, D->xs, g, org, ng,
        "zero sets of the irreducible factors of the norms c0^2 - d c1^2 of jury's conditions c0 + sqrt(d) c1 > 0 "
        "over Q(sqrt d)[N1, N2] and of the leading coefficient: exact signs at the grid points, a crossing "
        "between two neighbours of a row (column) placed by linear interpolation; a norm also vanishes where "
        "the conjugate condition does, and every factor is drawn, so curves separating nothing are included");
    for (k = 0; k < ng; k++) {
        fmpz_mpoly_clear(g + k, s->zctx);
        free(org[k]);
    }
    for (k = 0; k < n; k++) {
        fmpz_mpoly_clear(c0 + k, s->zctx);
        fmpz_mpoly_clear(c1 + k, s->zctx);
    }
    flint_free(c0); flint_free(c1); flint_free(ne); flint_free(g); flint_free(org);
    fmpz_mpoly_clear(a, s->zctx); fmpz_mpoly_clear(a0, s->zctx); fmpz_mpoly_clear(a1, s->zctx);
}

int rs_an_qd_map(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_sweep_request_t *R = (const rs_sweep_request_t *) req->u.sweep;
    const rs_sweep_axis_t *X = R->axis;
    rs_variant_t *v;
    rs_sweep_model_t m;
    fmpq *xs[2];
    qd_deco_t D;
    double t0 = rs_sweep_now();
    int r = R->of != RS_SWEEP_OF_MODES ? rs_sweep_estimate_map(run, req->q, (double) X[0].count * (double) X[1].count)
            : rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "over Q(sqrt d) a map is `of stability` or `of "
                           "radius`%s", "");
    if (r == RS_OK) r = rs_sweep_variant(&v, run, R);
    if (r != RS_OK) return r;
    xs[0] = rs_grid_axis(X[0].from, X[0].to, X[0].count);
    xs[1] = rs_grid_axis(X[1].from, X[1].to, X[1].count);
    m.model = NULL;
    r = rs_an_qd_sweep_model(&m, run, req->q, R, v, (const fmpq *const *) xs);
    if (r == RS_OK) {
        D.run = run;
        D.req = req;
        D.v = v;
        D.R = R;
        D.xs = xs;
        r = rs_sweep_map_finish(run, req->q, R, &m, (const fmpq *const *) xs, t0, qd_map_decorate, &D);
    }
    rs_an_qd_sweep_model_free(&m);
    _fmpq_vec_clear(xs[0], X[0].count);
    _fmpq_vec_clear(xs[1], X[1].count);
    return r;
}
