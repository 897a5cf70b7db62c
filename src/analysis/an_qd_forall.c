/* an_qd_forall.c -- issue 15 (issue 13 section 1 over Q(sqrt d)): `region
 * NAME for all [Q]` for a model whose p = p0 + sqrt(d) p1 has coefficients
 * in Q(sqrt d)[params] (rk sdirk2, sdirk3, sqrt tableaux), one quantified
 * or more quantified parameters Q1, ..., Qk.
 *
 * Projection: every condition of jury over Q(sqrt d)[NAME, Q] (Schur-Cohn,
 * c0 + sqrt(d) c1 > 0), p's leading coefficient and its discriminant are
 * replaced by their norms c0^2 - d c1^2 in Z[NAME, Q] (each vanishes wherever
 * its condition does, so the sign of the condition is constant where the
 * norm does not vanish: an over-approximation of the critical set, which is
 * safe), and the rational projection of an_region_forall.c
 * (rs_proj_eliminate: coefficients, discriminants, resultants, values at
 * the ends of Q's interval) eliminates Q.  Over an open cell of NAME the
 * norms are delineable, so "stable / bounded for every Q" is constant there.
 *
 * Cells: a rational sample t of each open cell and each rational critical
 * value are decided by the exact region of Q at NAME = t over Q(sqrt d)
 * (rs_an_qd_fiber: every cell of Q decided three ways, exit 3 on a
 * disagreement); an irrational critical value t0 by the fibre's own cut
 * points (the real roots of Res_t(minpoly t0, norm) in Q), each rational
 * sample and rational cut point decided over Q(t0, sqrt d) (an_qd_conds.c's
 * exact route); an irrational cut point of that fibre is not decided here,
 * and the point is reported undecided unless a counterexample was found.
 * Every verdict is cross-checked against the exact point verdict of the
 * default variant (p derived with every free parameter symbolic, then
 * evaluated) at sampled Q values: exit 3 on a disagreement.
 *
 * Several quantified parameters (issue 15): the same, one level per
 * parameter.  The norms are projected onto NAME by eliminating Qk, ...,
 * Q1; at a rational NAME = t the norms are substituted (a norm vanishing
 * identically there vanishes with its condition: t rational commutes with
 * conjugation) and the cells of Q1 "for every Q2, ..., Qk" computed the
 * same way, down to one quantified parameter (the exact fibre).  At an
 * irrational NAME = t0 the cut points of Q1 are the real roots of
 * Res_t(minpoly t0, P) for the projections P onto (NAME, Q1); rational
 * Q1 samples recurse over Q(t0, sqrt d); an irrational Q1 cut point with
 * further parameters left is undecided.  A claim `unstable` (kind 2) asks
 * "unstable at every point" instead of "stable for every point": the same
 * cells, the other quantifier. */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"

#define QF_MAX_FIELD_DEGREE 32

/* the verdict of one cell of NAME */
typedef struct {
    const char *status;     /* stable, marginal, unstable, singular, undecided */
    json_t *ev;
    int pt;
    rs_alg_t *lo, *hi;
} qf_cell_t;

typedef struct {
    rs_run_t *run;
    const rs_an_req_t *req;
    slong tv, qv;           /* qv = qvs[0] */
    const slong *qvs;       /* the quantified parameters, nq >= 1 */
    slong nq;
    int every_unstable;     /* claim unstable: "unstable at every point" */
    const rs_assign_t *ex;  /* outer parameters at rational values */
    slong nex;
    slong av2;              /* an outer quantified parameter at the irrational a2 (qf_algebraic), or -1 */
    rs_alg_t *a2;
    rs_bound_t *b;
    const rs_plist_t *norms;   /* in tv and qvs[] (ex substituted) */
    const rs_scheme_struct *s;
    slong *checked;         /* exact point verdicts compared (shared by every level) */
    int *bad;               /* a disagreement */
    rs_qd_signs_t **signs;  /* jury's conditions for the certified signs (made on first use) */
    int *signs_tried;
} qf_t;

static json_t *json_str_free(char *s)
{
    json_t *j = json_string(s);
    flint_free(s);
    return j;
}

/* the exact point verdict at (NAME = t, Q = q) of p derived with both
 * symbolic must say "stable" exactly when the fibre's cell says so */
static void qf_point_check(qf_t *F, const fmpq_t t, const fmpq_t q, const char *said)
{
    slong n = F->s->nvars, k;
    fmpq *pt = _fmpq_vec_init(n);
    fmpq **pp = flint_malloc((size_t) n * sizeof(fmpq *));
    int st;
    for (k = 0; k < n; k++) pp[k] = pt + k;
    for (k = 0; k < F->run->c->nsets; k++) {
        slong j = rs_case_param_index(F->run->c, F->run->c->sets[k].name);
        if (j >= 0 && j < n) fmpq_set(pt + j, F->run->c->sets[k].value);
    }
    for (k = 0; k < F->nex; k++) fmpq_set(pt + F->ex[k].var, F->ex[k].value);
    fmpq_set(pt + F->tv, t);
    fmpq_set(pt + F->qv, q);
    st = rs_an_qd_point_verdict(F->run, F->req, pp);
    if (st == -2 || (st >= 0 && (st == 1) != (strcmp(said, "stable") == 0))) *F->bad = 1;
    if (st >= 0) (*F->checked)++;
    _fmpq_vec_clear(pt, n);
    flint_free(pp);
}

/* a rational value inside the interval iv of the fibre's region (its ends
 * from the approximations: a dyadic midpoint, or an end -+ 1); 0 if none */
static int iv_sample(fmpq_t q, const json_t *iv)
{
    const json_t *lo = json_object_get(iv, "lo"), *hi = json_object_get(iv, "hi");
    double a = json_real_value(json_object_get(iv, "lo_approx")), c = json_real_value(json_object_get(iv, "hi_approx"));
    if (json_is_string(lo) && json_is_string(hi) && json_equal(lo, hi))
        return fmpq_set_str(q, json_string_value(lo), 10) == 0;
    if (json_is_null(lo) && json_is_null(hi)) { fmpq_zero(q); return 1; }
    if (json_is_null(lo)) a = c - 2;
    if (json_is_null(hi)) c = a + 2;
    if (!(c - a > 1e-9)) return 0;
    fmpz_set_d(fmpq_numref(q), (a + c) / 2 * 1048576.0);
    fmpz_one(fmpq_denref(q));
    fmpq_div_2exp(q, q, 20);
    return 1;
}

/* ex[] and var = t: the outer values of the next level (rs_assign_free) */
static rs_assign_t *qf_ex_push(const qf_t *F, slong var, const fmpq_t t)
{
    rs_assign_t *e = malloc((size_t) (F->nex + 1) * sizeof(rs_assign_t));
    slong k;
    for (k = 0; k <= F->nex; k++) {
        e[k].name = k < F->nex ? F->ex[k].name : F->run->c->params[var].name;
        e[k].var = k < F->nex ? F->ex[k].var : var;
        fmpq_init(e[k].value);
        fmpq_set(e[k].value, k < F->nex ? F->ex[k].value : t);
    }
    return e;
}

/* a counterexample names every outer parameter's value too */
static void qf_cx_complete(const qf_t *F, json_t *cx)
{
    slong k;
    for (k = 0; k < F->nex; k++)
        if (json_object_get(cx, F->ex[k].name) == NULL) json_object_set_new(cx, F->ex[k].name, rs_json_fmpq(F->ex[k].value));
    if (F->a2 != NULL && json_object_get(cx, F->run->c->params[F->av2].name) == NULL)
        json_object_set_new(cx, F->run->c->params[F->av2].name, rs_alg_json(F->a2, F->run->c->params[F->av2].name));
}

/* the status names as static strings (a cell outlives the JSON it was read from) */
static const char *qf_status_lit(const char *s)
{
    static const char *const names[] = {"stable", "marginal", "unstable", "singular", "not stable"};
    size_t k;
    for (k = 0; k < sizeof names / sizeof names[0]; k++)
        if (strcmp(s, names[k]) == 0) return names[k];
    return "undecided";
}

/* a cell's status meets the quantifier: stable or marginal (for every
 * point), unstable (at every point) */
static int qf_good(const qf_t *F, const char *st)
{
    return F->every_unstable ? strcmp(st, "unstable") == 0
                             : strcmp(st, "stable") == 0 || strcmp(st, "marginal") == 0;
}

/* the norms at var = t (denominators cleared) as the next level's, tv its parameter */
static void qf_norms_at(rs_plist_t *out, const qf_t *F, slong var, const fmpq_t t, slong tv)
{
    fmpz_mpoly_t u;
    slong i;
    fmpz_mpoly_init(u, F->s->zctx);
    for (i = 0; i < F->norms->n; i++) {
        rs_an_forall_subst(u, F->norms->p + i, var, t, F->s->zctx);
        rs_plist_add(out, u, tv, F->b, F->s->zctx);
    }
    fmpz_mpoly_clear(u, F->s->zctx);
}

/* the next level: var at t rational, the first remaining quantified
 * parameter the one whose cells are computed (tv kept when tv_kept) */
static void qf_next(qf_t *G, const qf_t *F, slong var, rs_assign_t *ee, const rs_plist_t *norms, int tv_kept)
{
    *G = *F;
    if (!tv_kept) G->tv = F->qvs[0];
    G->qvs = F->qvs + 1;
    G->nq = F->nq - 1;
    G->qv = G->nq > 0 ? G->qvs[0] : -1;
    G->ex = ee;
    G->nex = F->nex + 1;
    G->norms = norms;
    (void) var;
}

static int qf_cells(qf_t *F, rs_alg_t **critp, slong *ncritp, qf_cell_t **cellp, slong *ncellp);
static const char qf_by_signs[] = "the certified signs of jury's conditions over Q(sqrt d) at the point";
static void qf_cells_clear(rs_alg_t *crit, slong ncrit, qf_cell_t *cell, slong ncell);
static void qf_emit(json_t *o, qf_cell_t *cell, slong ncell, const char *name);

/* the cells of the next level (G: its parameter's cells for every value
 * of the rest) as one verdict: the first cell that fails the quantifier
 * gives the counterexample, else undecided when one is, else the best */
static void qf_combine(const qf_t *G, qf_cell_t *cell, slong ncell, const char **st, json_t **ev)
{
    const char *name = G->run->c->params[G->tv].name;
    slong i, marg = -1;
    int und = 0;
    json_t *sub = json_object();
    *ev = json_object();
    for (i = 0; i < ncell; i++) {
        if (strcmp(cell[i].status, "undecided") == 0) { und = 1; continue; }
        if (qf_good(G, cell[i].status)) {
            if (marg < 0 && strcmp(cell[i].status, "marginal") == 0) marg = i;
            continue;
        }
        *st = cell[i].status;
        json_object_set(*ev, "counterexample", json_object_get(cell[i].ev, "counterexample"));
        json_object_set(*ev, "at_counterexample", json_object_get(cell[i].ev, "at_counterexample"));
        break;
    }
    if (i == ncell) {
        *st = und ? "undecided" : G->every_unstable ? "unstable" : marg >= 0 ? "marginal" : "stable";
        if (und)
            json_object_set_new(*ev, "reason", json_string("a cell of the next quantified parameter is undecided; "
                                                           "no counterexample at the others"));
        else
            json_object_set_new(*ev, "certificate", json_pack("{s:s}", "text", G->every_unstable
                ? "every cell of the next quantified parameter is unstable at every point"
                : "every cell of the next quantified parameter is stable (or marginal) for every value of the rest"));
        if (!und && marg >= 0 && !G->every_unstable) {
            json_t *ns = json_object();
            json_object_set_new(ns, name, cell[marg].pt && !cell[marg].hi->rational
                                ? rs_alg_json(cell[marg].hi, name) : json_incref(json_object_get(cell[marg].ev, "sample")));
            json_object_set(ns, "then", json_object_get(cell[marg].ev, "not_stable_on"));
            json_object_set_new(*ev, "not_stable_on", ns);
        }
    }
    qf_emit(sub, cell, ncell, name);
    json_object_set_new(*ev, "cells_of", json_string(name));
    json_object_set(*ev, "cells", json_object_get(sub, "intervals"));
    json_decref(sub);
}

/* NAME = t rational: the exact region of Q there (bounded, kind 1; kind 2
 * for "unstable at every point"); the cell stable when every piece is,
 * marginal when every piece is bounded, unstable (singular) at the
 * fibre's first bad piece.  Two or more quantified parameters: the cells
 * of the first for every value of the others (qf_combine). */
static int qf_rational(qf_t *F, const fmpq_t t, const char **st, json_t **ev)
{
    rs_run_t *run = F->run;
    const char *nm = run->c->params[F->tv].name, *qn = run->c->params[F->qv].name;
    rs_assign_t *ee = qf_ex_push(F, F->tv, t);
    json_t *o, *counter = NULL, *reg, *iv;
    size_t i;
    int verdict = 0, all = 1, r;
    fmpq_t q;
    if (F->nq >= 2) {
        qf_t G;
        rs_plist_t l;
        rs_alg_t *crit = NULL;
        qf_cell_t *cell = NULL;
        slong ncrit = 0, ncell = 0;
        rs_plist_init(&l);
        qf_norms_at(&l, F, F->tv, t, F->qvs[0]);
        qf_next(&G, F, F->tv, ee, &l, 0);
        r = qf_cells(&G, &crit, &ncrit, &cell, &ncell);
        if (r == RS_OK) {
            qf_combine(&G, cell, ncell, st, ev);
            json_object_set_new(*ev, "sample", rs_json_fmpq(t));
        }
        qf_cells_clear(crit, ncrit, cell, ncell);
        rs_plist_clear(&l, F->s->zctx);
        rs_assign_free(ee, F->nex + 1);
        return r;
    }
    o = json_object();
    fmpq_init(q);
    r = rs_an_qd_fiber(&verdict, &counter, o, run, F->req, F->every_unstable ? 2 : 1, F->qv, F->b + F->qv, ee,
                       F->nex + 1);
    rs_assign_free(ee, F->nex + 1);
    *ev = json_object();
    if (r != RS_OK) {
        json_decref(o); json_decref(counter); fmpq_clear(q);
        return r;
    }
    reg = json_object_get(o, "region");
    json_array_foreach(reg, i, iv) {
        const char *s = json_string_value(json_object_get(iv, "status"));
        if (strcmp(s, "stable") != 0) all = 0;
        if (iv_sample(q, iv)) qf_point_check(F, t, q, s);
    }
    if (verdict == 1) {
        *st = F->every_unstable ? "unstable" : all ? "stable" : "marginal";
        json_object_set_new(*ev, "certificate", json_pack("{s:s,s:O}", "text", F->every_unstable
            ? "the exact region of the quantified parameter at this value is unstable on all of its domain" : all
            ? "the exact region of the quantified parameter at this value is stable on all of its domain"
            : "the exact region of the quantified parameter at this value is stable or marginal on all of its domain",
            "region", reg));
        if (!all && !F->every_unstable)
            json_array_foreach(reg, i, iv)
                if (strcmp(json_string_value(json_object_get(iv, "status")), "stable") != 0) {
                    json_object_set(*ev, "not_stable_on", iv);
                    break;
                }
    } else if (verdict == -1) {
        json_t *cx = json_object(), *at = json_object();
        const char *cs = qf_status_lit(json_string_value(json_object_get(counter, "status")));
        *st = F->every_unstable ? cs : strcmp(cs, "singular") == 0 ? "singular" : "unstable";
        json_object_set_new(cx, nm, rs_json_fmpq(t));
        json_object_set(cx, qn, json_object_get(counter, qn));
        if (json_object_get(counter, "exact") != NULL) json_object_set(cx, "exact", json_object_get(counter, "exact"));
        qf_cx_complete(F, cx);
        json_object_set_new(at, "status", json_string(cs));
        json_object_set_new(at, "decided_by", json_string("exact"));
        json_object_set_new(*ev, "counterexample", cx);
        json_object_set_new(*ev, "at_counterexample", at);
        json_object_set(*ev, "region_at_sample", reg);
    } else {
        *st = "undecided";
        json_object_set(*ev, "region_at_sample", reg);
    }
    json_object_set_new(*ev, "sample", rs_json_fmpq(t));
    json_decref(o);
    json_decref(counter);
    fmpq_clear(q);
    return RS_OK;
}

/* q's interval (the assumptions) contains the algebraic a (irrational) */
static int alg_inside(const rs_bound_t *b, rs_alg_t *a)
{
    arb_t e;
    int in = 1, k;
    if (a->rational) return rs_bound_contains(b, a->q);
    arb_init(e);
    rs_alg_refine(a, 256);
    for (k = 0; k < 2 && in; k++) {
        if (!(k == 0 ? b->has_lo : b->has_hi)) continue;
        arb_set_fmpq(e, k == 0 ? b->lo : b->hi, 256);
        /* an irrational a is never an end; undecidable at 256 bits: kept (one more cut point is safe) */
        if (k == 0 ? arb_lt(a->x, e) : arb_gt(a->x, e)) in = 0;
    }
    arb_clear(e);
    return in;
}

/* sorted, each value once */
static slong alg_unique(rs_alg_t *crit, slong n)
{
    slong i, m;
    rs_alg_sort(crit, n);
    for (i = m = 0; i < n; i++) {
        if (m > 0 && rs_alg_cmp(crit + m - 1, crit + i) == 0) { rs_alg_clear(crit + i); continue; }
        if (m != i) crit[m] = crit[i];
        m++;
    }
    return m;
}

/* the rational end e of an interval as a critical value */
static void crit_push_fmpq(rs_alg_t **crit, slong *n, const fmpq_t e)
{
    fmpz_poly_t nz;
    fmpz_poly_init(nz);
    fmpz_poly_set_coeff_fmpz(nz, 0, fmpq_numref(e));
    fmpz_poly_neg(nz, nz);
    fmpz_poly_set_coeff_fmpz(nz, 1, fmpq_denref(e));
    rs_alg_roots_append(crit, n, nz, 1);
    fmpz_poly_clear(nz);
}

/* the counterexample (NAME = t0 exact, Q = qj: a rational string or an
 * algebraic number's object, the outer values) as the evidence of a point
 * that fails the quantifier */
static json_t *qf_counter(const qf_t *F, const char **st, json_t **ev, rs_alg_t *t0, json_t *qj, rs_status_t ps)
{
    const char *nm = F->run->c->params[F->tv].name, *qn = F->run->c->params[F->qv].name;
    json_t *cx = json_object();
    json_object_set_new(cx, nm, rs_alg_json(t0, nm));
    json_object_set_new(cx, qn, qj);
    qf_cx_complete(F, cx);
    *st = F->every_unstable ? rs_status_name(ps) : ps == RS_STATUS_SINGULAR ? "singular" : "unstable";
    *ev = json_object();
    json_object_set_new(*ev, "counterexample", cx);
    json_object_set_new(*ev, "at_counterexample", json_pack("{s:s,s:s}", "status", rs_status_name(ps),
                        "decided_by", "exact over Q(t0, sqrt d) (and q0 when irrational)"));
    return cx;
}

/* the same from the next level's evidence sub when there is one (its
 * counterexample names every value); qj consumed */
static json_t *qf_sub_counter(const qf_t *F, const char **st, json_t **ev, json_t *sub, rs_alg_t *t0, json_t *qj,
                              rs_status_t ps)
{
    json_t *cx;
    if (sub == NULL || json_object_get(sub, "counterexample") == NULL) return qf_counter(F, st, ev, t0, qj, ps);
    json_decref(qj);
    *st = F->every_unstable ? rs_status_name(ps) : ps == RS_STATUS_SINGULAR ? "singular" : "unstable";
    *ev = json_object();
    cx = json_object_get(sub, "counterexample");
    json_object_set(*ev, "counterexample", cx);
    json_object_set(*ev, "at_counterexample", json_object_get(sub, "at_counterexample"));
    return cx;
}

/* a point's status by the certified signs of jury's conditions when the
 * exact route did not decide it (tv = t0, av2 = a2 if any, qv = q0 if
 * not NULL; ex[] rational) */
static int qf_signs(rs_status_t *ps, qf_t *F, rs_alg_t *t0, rs_alg_t *q0, const rs_assign_t *ex, slong nex)
{
    slong av[3], n = 0;
    rs_alg_t *a[3];
    if (!*F->signs_tried) {
        *F->signs_tried = 1;
        if (rs_qd_signs_init(F->signs, F->run, F->req) != RS_OK) {
            rs_qd_signs_clear(*F->signs);
            *F->signs = NULL;
            rs_error_init(F->run->err);
        }
    }
    av[n] = F->tv; a[n++] = t0;
    if (F->a2 != NULL) { av[n] = F->av2; a[n++] = F->a2; }
    if (q0 != NULL) { av[n] = F->qv; a[n++] = q0; }
    return rs_qd_signs_status(ps, *F->signs, F->run, ex, nex, av, a, n);
}

/* the exact route's status (decided) cross-checked against the certified
 * signs where both decide (a disagreement: *F->bad, exit 3), or the signs'
 * where the exact route did not (*by says so); returns decided */
static int qf_signs_check(rs_status_t *ps, const char **by, int decided, qf_t *F, rs_alg_t *t0, rs_alg_t *q0,
                          const rs_assign_t *ex, slong nex)
{
    rs_status_t sg;
    *by = NULL;
    /* the signs decide only stable and unstable: no check at a marginal or singular point */
    if (decided && *ps != RS_STATUS_STABLE && *ps != RS_STATUS_UNSTABLE) return 1;
    if (!qf_signs(&sg, F, t0, q0, ex, nex)) return decided;
    if (decided && sg != *ps) *F->bad = 1;
    if (!decided) { *ps = sg; *by = qf_by_signs; }
    return 1;
}

/* a sample of the fibre {Q: value, status} (value consumed), with the next
 * level's samples there when there is one; by: how when not exactly */
static void qf_sample_push(json_t *samples, json_t *val, const char *qn, const char *st, const json_t *sub,
                           const char *by)
{
    json_t *e = json_pack("{s:o,s:s}", qn, val, "status", st);
    if (by != NULL) json_object_set_new(e, "decided_by", json_string(by));
    if (sub != NULL && json_object_get(sub, "fibre_samples") != NULL)
        json_object_set(e, "fibre_samples", json_object_get(sub, "fibre_samples"));
    json_array_append_new(samples, e);
}

/* the norms projected onto tv and qvs[0..upto] (qvs[nq-1], ..., qvs[upto] eliminated), upto < nq */
static int qf_project(rs_plist_t *out, const qf_t *F, slong upto)
{
    const rs_plist_t *in = F->norms;
    rs_plist_t cur;
    slong i;
    int r = RS_OK;
    rs_plist_init(&cur);
    for (i = F->nq - 1; i >= upto && r == RS_OK; i--) {
        rs_plist_t m;
        rs_plist_init(&m);
        r = rs_proj_eliminate(&m, F->run, in, F->qvs[i], F->b + F->qvs[i], F->tv, F->b, F->s->zctx);
        rs_plist_clear(&cur, F->s->zctx);
        cur = m;
        in = &cur;
    }
    *out = cur;
    return r;
}

static rs_status_t qf_status_of(const char *s)
{
    return strcmp(s, "stable") == 0 ? RS_STATUS_STABLE : strcmp(s, "marginal") == 0 ? RS_STATUS_MARGINAL
         : strcmp(s, "singular") == 0 ? RS_STATUS_SINGULAR : RS_STATUS_UNSTABLE;
}

/* NAME = t0 irrational: the fibre's cut points in Q (the real roots of
 * Res_t(minpoly, P) in Q's interval for the norms P projected onto (NAME,
 * Q), its closed ends), the status at a rational sample of each open piece
 * and at each rational cut point over Q(t0, sqrt d) (with further
 * quantified parameters: the same one level down at Q = q); an irrational
 * cut point over Q(t0, sqrt d, q0) when Q is the last, else left open
 * (undecided unless a counterexample is found) */
static int qf_algebraic(qf_t *F, rs_alg_t *t0, const char **st, json_t **ev)
{
    rs_run_t *run = F->run;
    const fmpz_mpoly_ctx_struct *ctx = F->s->zctx;
    const char *qn = run->c->params[F->qv].name;
    const rs_bound_t *bq = F->b + F->qv;
    fmpz_mpoly_t mp, mp2, res;
    fmpz_poly_t u;
    rs_plist_t pr;
    rs_alg_t *crit = NULL;
    slong ncrit = 0, i, k, nopen = 0, nsamp = 0;
    int identically = 0, any_marg = 0, r = RS_OK;
    json_t *cx = NULL, *samples = json_array();
    fmpq_t q;
    fmpz_mpoly_init(mp, ctx); fmpz_mpoly_init(mp2, ctx); fmpz_mpoly_init(res, ctx);
    fmpz_poly_init(u);
    fmpq_init(q);
    rs_plist_init(&pr);
    fmpz_mpoly_set_fmpz_poly(mp, t0->minpoly, F->tv, ctx);
    if (F->a2 != NULL) fmpz_mpoly_set_fmpz_poly(mp2, F->a2->minpoly, F->av2, ctx);
    if (F->nq >= 2) r = qf_project(&pr, F, 1);
    for (i = 0; r == RS_OK && i < (F->nq >= 2 ? pr.n : F->norms->n) && !identically; i++) {
        const fmpz_mpoly_struct *f = (F->nq >= 2 ? pr.p : F->norms->p) + i;
        if (fmpz_mpoly_degree_si(f, F->qv, ctx) <= 0) continue;
        if (!fmpz_mpoly_resultant(res, f, mp, F->tv, ctx)
            || (F->a2 != NULL && !fmpz_mpoly_resultant(res, res, mp2, F->av2, ctx))
            || !fmpz_mpoly_get_fmpz_poly(u, res, F->qv, ctx)) {
            identically = 1;
            break;
        }
        if (fmpz_poly_is_zero(u)) identically = 1;   /* a norm vanishes on the whole fibre */
        else if (fmpz_poly_degree(u) > 0) rs_alg_roots_append(&crit, &ncrit, u, 1);
    }
    if (bq->has_lo) crit_push_fmpq(&crit, &ncrit, bq->lo);
    if (bq->has_hi) crit_push_fmpq(&crit, &ncrit, bq->hi);
    ncrit = alg_unique(crit, ncrit);
    for (i = 0; i <= ncrit && r == RS_OK && !identically && cx == NULL; i++) {
        rs_alg_t *lo = i > 0 ? crit + i - 1 : NULL, *hi = i < ncrit ? crit + i : NULL;
        for (k = 0; k < 2 && cx == NULL; k++) {
            rs_assign_t *ee;
            rs_status_t ps = RS_STATUS_STABLE;
            json_t *sub = NULL;
            const char *by;
            int decided;
            if (k == 0) {
                rs_alg_between(q, lo, hi);
                if (!rs_bound_contains(bq, q)) continue;
            } else {
                if (hi == NULL || !alg_inside(bq, hi)) continue;
                if (!hi->rational) {
                    /* an irrational cut point q0: over Q(t0, sqrt d, q0) when Q is the last, or the next
                     * quantified parameter's fibre at (t0, q0); a third irrational value is not decided */
                    r = rs_budget_check(run->err, "region for all over Q(sqrt d)");
                    if (r != RS_OK) break;
                    /* Q(t0, sqrt d, q0) of degree up to 2 deg t0 deg q0: beyond QF_MAX_FIELD_DEGREE
                     * the primitive element's arithmetic is too slow to be worth it here */
                    decided = F->a2 == NULL
                              && 2 * fmpz_poly_degree(t0->minpoly) * fmpz_poly_degree(hi->minpoly) <= QF_MAX_FIELD_DEGREE;
                    if (decided && F->nq == 1) {
                        decided = rs_an_qd_alg2_status(&ps, run, F->req, F->tv, t0, F->qv, hi, F->ex, F->nex);
                    } else if (decided) {
                        qf_t G = *F;
                        const char *ss = "undecided";
                        G.qvs = F->qvs + 1; G.nq = F->nq - 1; G.qv = G.qvs[0];
                        G.av2 = F->qv; G.a2 = hi;
                        r = qf_algebraic(&G, t0, &ss, &sub);
                        decided = r == RS_OK && strcmp(ss, "undecided") != 0;
                        if (decided) ps = qf_status_of(ss);
                        if (r != RS_OK) { json_decref(sub); break; }
                    }
                    by = NULL;
                    if (sub == NULL) decided = qf_signs_check(&ps, &by, decided, F, t0, hi, F->ex, F->nex);
                    nsamp++;
                    qf_sample_push(samples, rs_alg_json(hi, qn), qn, decided ? rs_status_name(ps) : "undecided", sub, by);
                    if (decided && ps == RS_STATUS_MARGINAL) any_marg = 1;
                    if (decided && (F->every_unstable ? ps != RS_STATUS_UNSTABLE
                                                      : ps == RS_STATUS_UNSTABLE || ps == RS_STATUS_SINGULAR))
                        cx = qf_sub_counter(F, st, ev, sub, t0, rs_alg_json(hi, qn), ps);
                    if (!decided) nopen++;
                    json_decref(sub);
                    sub = NULL;
                    continue;
                }
                fmpq_set(q, hi->q);
            }
            r = rs_budget_check(run->err, "region for all over Q(sqrt d)");
            if (r != RS_OK) break;
            ee = qf_ex_push(F, F->qv, q);
            by = NULL;
            if (F->nq == 1) {
                decided = F->a2 == NULL ? rs_an_qd_alg_status(&ps, run, F->req, F->tv, t0, ee, F->nex + 1)
                        : rs_an_qd_alg2_status(&ps, run, F->req, F->tv, t0, F->av2, F->a2, ee, F->nex + 1);
                decided = qf_signs_check(&ps, &by, decided, F, t0, NULL, ee, F->nex + 1);
            } else {   /* Q = q: the next quantified parameter's fibre at t0 */
                qf_t G;
                rs_plist_t l;
                const char *ss = "undecided";
                rs_plist_init(&l);
                qf_norms_at(&l, F, F->qv, q, F->tv);
                qf_next(&G, F, F->qv, ee, &l, 1);
                r = qf_algebraic(&G, t0, &ss, &sub);
                rs_plist_clear(&l, ctx);
                decided = r == RS_OK && strcmp(ss, "undecided") != 0;
                if (decided) ps = qf_status_of(ss);
            }
            rs_assign_free(ee, F->nex + 1);
            if (r != RS_OK) { json_decref(sub); break; }
            nsamp++;
            qf_sample_push(samples, rs_json_fmpq(q), qn, decided ? rs_status_name(ps) : "undecided", sub, by);
            if (!decided) { nopen++; json_decref(sub); continue; }
            if (ps == RS_STATUS_MARGINAL) any_marg = 1;
            if (F->every_unstable ? ps != RS_STATUS_UNSTABLE : ps == RS_STATUS_UNSTABLE || ps == RS_STATUS_SINGULAR)
                cx = qf_sub_counter(F, st, ev, sub, t0, rs_json_fmpq(q), ps);
            json_decref(sub);
        }
    }
    if (cx == NULL && r == RS_OK) {
        *ev = json_object();
        if (identically || nopen > 0) {
            *st = "undecided";
            json_object_set_new(*ev, "reason", json_string(identically
                ? "a condition's norm vanishes on the whole fibre at this value: its cut points are not known"
                : "a sample or cut point of the fibre at this irrational value is undecided (a repeated non-real "
                  "circle root, no primitive element within the budget, Q(t0, sqrt d, q0) of degree over 32, or an "
                  "irrational cut point with further quantified parameters); no counterexample at the others"));
        } else {
            *st = F->every_unstable ? "unstable" : any_marg ? "marginal" : "stable";
            json_object_set_new(*ev, "certificate", json_pack("{s:s}", "text",
                "every piece of the fibre decided exactly: its open pieces at a rational sample over Q(t0, sqrt d) "
                "(no norm vanishes inside one, so each condition keeps its sign there), its cut points over "
                "Q(t0, sqrt d) or Q(t0, sqrt d, q0)"));
        }
    }
    if (r == RS_OK) {
        json_object_set_new(*ev, "fibre_samples", samples);
        json_object_set_new(*ev, "fibre_cut_points", json_integer(ncrit));
        samples = NULL;
    }
    json_decref(samples);
    for (i = 0; i < ncrit; i++) rs_alg_clear(crit + i);
    free(crit);
    rs_plist_clear(&pr, ctx);
    fmpz_mpoly_clear(mp, ctx); fmpz_mpoly_clear(mp2, ctx); fmpz_mpoly_clear(res, ctx);
    fmpz_poly_clear(u);
    fmpq_clear(q);
    return r;
}

/* the cells merged into intervals of one status, rational region's shape */
static void qf_emit(json_t *o, qf_cell_t *cell, slong ncell, const char *name)
{
    json_t *ivs = json_array(), *und = json_array();
    slong i, j, k;
    for (i = 0; i < ncell; i = j + 1) {
        json_t *iv, *evs = json_array();
        for (j = i; j + 1 < ncell && strcmp(cell[j + 1].status, cell[i].status) == 0; j++) ;
        iv = rs_an_qd_interval_json(cell[i].lo, cell[j].hi, cell[i].pt, cell[j].pt, cell[i].status, name);
        for (k = i; k <= j; k++) {
            json_t *e = json_object();
            json_object_set_new(e, "cell", json_string(cell[k].pt ? "point" : "interval"));
            json_object_update(e, cell[k].ev);
            json_array_append_new(evs, e);
            if (strcmp(cell[k].status, "undecided") == 0 && cell[k].pt) {
                /* the rational path's shape (an_region.c): the renderer reads "value" */
                json_t *pj = json_object();
                json_object_set_new(pj, "value", rs_alg_json(cell[k].hi, name));
                json_object_set_new(pj, "approx", json_real(rs_alg_double(cell[k].hi)));
                json_object_set_new(pj, "status", json_string("undecided"));
                json_object_set(pj, "evidence", cell[k].ev);
                json_array_append_new(und, pj);
            }
        }
        json_object_set_new(iv, "evidence", evs);
        json_array_append_new(ivs, iv);
    }
    json_object_set_new(o, "symbolic", json_false());
    json_object_set_new(o, "intervals", ivs);
    json_object_set_new(o, "undecided_points", und);
}

static const char qf_method[] =
    "the norms c0^2 - d c1^2 of jury's Schur-Cohn conditions c0 + sqrt(d) c1 > 0 over Q(sqrt d)[params], of p's "
    "leading coefficient and of its discriminant, projected onto the parameter by the rational projection of region "
    "... for all (coefficients, discriminants, resultants, values at the ends of the quantified interval, one "
    "quantified parameter at a time; an over-approximation of the critical values); each rational sample decided by "
    "the exact region of the last quantified parameter there over Q(sqrt d) (with several, the cells of the first "
    "for every value of the others, the same way one level down), each irrational critical value t0 by the fibre's "
    "cut points over Q(t0, sqrt d); every verdict cross-checked against the exact point verdict of p derived with "
    "every parameter symbolic";

/* the cells of F->tv on F->b[tv] (every value of the quantified ones in
 * their boxes), F->norms given; *crit, *cell for the caller to free
 * (qf_cells_clear) */
static int qf_cells(qf_t *F, rs_alg_t **critp, slong *ncritp, qf_cell_t **cellp, slong *ncellp)
{
    rs_run_t *run = F->run;
    slong tv = F->tv, i, ncrit = 0, ncell = 0;
    rs_plist_t m;
    rs_alg_t *crit = NULL;
    qf_cell_t *cell;
    fmpq_t t;
    int r;
    fmpq_init(t);
    r = qf_project(&m, F, 0);
    for (i = 0; r == RS_OK && i < m.n; i++) {
        fmpz_poly_t u;
        if (fmpz_mpoly_degree_si(m.p + i, tv, F->s->zctx) <= 0) continue;
        fmpz_poly_init(u);
        if (fmpz_mpoly_get_fmpz_poly(u, m.p + i, tv, F->s->zctx)) rs_alg_roots_append(&crit, &ncrit, u, 1);
        fmpz_poly_clear(u);
    }
    if (F->b[tv].has_lo) crit_push_fmpq(&crit, &ncrit, F->b[tv].lo);
    if (F->b[tv].has_hi) crit_push_fmpq(&crit, &ncrit, F->b[tv].hi);
    ncrit = alg_unique(crit, ncrit);
    cell = flint_malloc((size_t) (2 * ncrit + 1) * sizeof(qf_cell_t));
    for (i = 0; r == RS_OK && i <= ncrit && !*F->bad; i++) {
        rs_alg_t *lo = i > 0 ? crit + i - 1 : NULL, *hi = i < ncrit ? crit + i : NULL;
        r = rs_budget_check(run->err, "region for all over Q(sqrt d)");
        if (r != RS_OK) break;
        rs_alg_between(t, lo, hi);
        if (rs_bound_contains(F->b + tv, t)) {
            cell[ncell].pt = 0; cell[ncell].lo = lo; cell[ncell].hi = hi; cell[ncell].ev = NULL;
            r = qf_rational(F, t, &cell[ncell].status, &cell[ncell].ev);
            ncell++;
        }
        if (r != RS_OK || hi == NULL || !alg_inside(F->b + tv, hi)) continue;
        cell[ncell].pt = 1; cell[ncell].lo = cell[ncell].hi = hi; cell[ncell].ev = NULL;
        if (hi->rational) r = qf_rational(F, hi->q, &cell[ncell].status, &cell[ncell].ev);
        else r = qf_algebraic(F, hi, &cell[ncell].status, &cell[ncell].ev);
        ncell++;
    }
    rs_plist_clear(&m, F->s->zctx);
    fmpq_clear(t);
    *critp = crit; *ncritp = ncrit; *cellp = cell; *ncellp = ncell;
    return r;
}

static void qf_cells_clear(rs_alg_t *crit, slong ncrit, qf_cell_t *cell, slong ncell)
{
    slong i;
    for (i = 0; i < ncell; i++) json_decref(cell[i].ev);
    flint_free(cell);
    for (i = 0; i < ncrit; i++) rs_alg_clear(crit + i);
    free(crit);
}

/* the top level: the norms of the default variant, then the cells; a
 * disagreement with an exact point verdict anywhere below is exit 3 */
static int qf_cells_top(qf_t *F, rs_alg_t **critp, slong *ncritp, qf_cell_t **cellp, slong *ncellp)
{
    rs_plist_t l;
    int r;
    rs_plist_init(&l);
    *critp = NULL; *ncritp = 0; *cellp = NULL; *ncellp = 0;
    r = rs_an_qd_forall_norms(&l, &F->s, F->run, F->req, F->tv, F->b);
    F->norms = &l;
    if (r == RS_OK) r = qf_cells(F, critp, ncritp, cellp, ncellp);
    if (r == RS_OK && *F->bad)
        r = rs_req_error(F->run, F->req->q, F->req->q->text, RS_ERR_INCONSISTENT, "region for all over Q(sqrt d): "
                         "a cell's verdict and the exact point verdict of p with every parameter symbolic disagree at "
                         "a sample (internal inconsistency)%s", "");
    if (F->s != NULL) rs_plist_clear(&l, F->s->zctx);
    F->norms = NULL;
    return r;
}

static json_t *qf_for_all(const qf_t *F)
{
    json_t *fa = json_array();
    slong k;
    for (k = 0; k < F->nq; k++) json_array_append_new(fa, json_string(F->run->c->params[F->qvs[k]].name));
    return fa;
}

static void qf_init(qf_t *F, slong *checked, int *bad, rs_qd_signs_t **signs, int *tried, rs_run_t *run,
                    const rs_an_req_t *req, slong tv, const slong *qvs, slong nq)
{
    memset(F, 0, sizeof *F);
    F->signs = signs; F->signs_tried = tried;
    *signs = NULL; *tried = 0;
    F->run = run; F->req = req; F->tv = tv; F->qvs = qvs; F->nq = nq; F->qv = qvs[0];
    F->checked = checked; F->bad = bad;
    F->av2 = -1;
    *checked = 0; *bad = 0;
    F->b = rs_run_bounds(run);
}

int rs_an_qd_region_forall(rs_run_t *run, const rs_an_req_t *req)
{
    slong ncrit = 0, ncell = 0, checked;
    const char *name = run->c->params[req->u.region.param].name;
    qf_t F;
    rs_alg_t *crit = NULL;
    qf_cell_t *cell = NULL;
    json_t *o;
    rs_qd_signs_t *signs;
    int r, bad, tried;
    if (req->u.region.nq < 1)
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "expected a parameter to quantify: region %s "
                            "for all over Q(sqrt d) has no other free parameter (region NAME alone gives its exact "
                            "region)", name);
    qf_init(&F, &checked, &bad, &signs, &tried, run, req, req->u.region.param, req->u.region.qv, req->u.region.nq);
    r = qf_cells_top(&F, &crit, &ncrit, &cell, &ncell);
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("region"));
        json_object_set_new(o, "param", json_string(name));
        json_object_set_new(o, "over", json_str_free(rs_an_qd_over_str(run->m->qd->d)));
        qf_emit(o, cell, ncell, name);
        json_object_set_new(o, "critical_values", json_integer(ncrit));
        json_object_set_new(o, "for_all", qf_for_all(&F));
        json_object_set_new(o, "method", json_string(qf_method));
        json_object_set_new(o, "point_checks", json_pack("{s:I,s:b}", "points", (json_int_t) checked, "agree", 1));
        json_object_set_new(o, "decided_by", json_string("exact"));
        json_array_append_new(run->results, o);
    }
    qf_cells_clear(crit, ncrit, cell, ncell);
    rs_qd_signs_clear(signs);
    rs_run_bounds_clear(F.b, run);
    return r;
}

/* a counterexample as a claim over Q(sqrt d) gives it (an_qd_conds.c's
 * one-parameter claims): each algebraic value by its digits, exactly which
 * root of which polynomial in "exact" */
static json_t *qf_claim_point(const json_t *cx)
{
    json_t *out = json_object(), *v;
    const char *k;
    char *ex = NULL;
    json_object_foreach((json_t *) cx, k, v) {
        if (json_is_object(v) && json_object_get(v, "minpoly") != NULL) {
            char buf[600];
            snprintf(buf, sizeof buf, "%s%s%s: root %ld (from below, 0-based) of %s", ex != NULL ? ex : "",
                     ex != NULL ? "; " : "", k, (long) json_integer_value(json_object_get(v, "root_index")),
                     json_string_value(json_object_get(v, "minpoly")));
            free(ex);
            ex = strdup(buf);
            json_object_set(out, k, json_object_get(v, "approx"));
        } else if (strcmp(k, "exact") != 0) {
            json_object_set(out, k, v);
        }
    }
    if (ex != NULL) json_object_set_new(out, "exact", json_string(ex));
    else if (json_object_get(cx, "exact") != NULL) json_object_set(out, "exact", json_object_get(cx, "exact"));
    free(ex);
    return out;
}

int rs_an_qd_claim_forall(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                          slong tv, const slong *qvs, slong nq, const rs_bound_t *b)
{
    slong ncrit = 0, ncell = 0, i, k, checked;
    const char *name = run->c->params[tv].name;
    qf_t F;
    rs_alg_t *crit = NULL;
    qf_cell_t *cell = NULL;
    json_t *ivs;
    rs_qd_signs_t *signs;
    int r, bad, tried;
    qf_init(&F, &checked, &bad, &signs, &tried, run, req, tv, qvs, nq);
    F.every_unstable = kind == 2;
    for (k = 0; k <= nq; k++) {   /* the claim's box (its bounds with the assumptions) */
        slong v = k < nq ? qvs[k] : tv;
        rs_bound_t *d = F.b + v;
        const rs_bound_t *e = b + v;
        d->has_lo = e->has_lo; d->has_hi = e->has_hi; d->lo_closed = e->lo_closed; d->hi_closed = e->hi_closed;
        d->fixed = e->fixed;
        fmpq_set(d->lo, e->lo); fmpq_set(d->hi, e->hi);
    }
    *verdict = 1;
    *counter = NULL;
    r = qf_cells_top(&F, &crit, &ncrit, &cell, &ncell);
    for (i = 0; r == RS_OK && i < ncell && *counter == NULL; i++) {
        const char *st = cell[i].status;
        const json_t *cx = json_object_get(cell[i].ev, "counterexample");
        if (kind == 2 ? strcmp(st, "unstable") == 0
                      : strcmp(st, "stable") == 0 || (kind == 1 && strcmp(st, "marginal") == 0)) continue;
        if (strcmp(st, "undecided") == 0) { *verdict = 0; continue; }
        *verdict = -1;
        *counter = cx != NULL ? qf_claim_point(cx) : json_object();
        if (cx == NULL) {   /* marginal against a stable claim: the sample and the fibre's piece not stable */
            json_object_set(*counter, name, cell[i].pt && !cell[i].hi->rational
                            ? json_object_get(cell[i].ev, "fibre_samples") : json_object_get(cell[i].ev, "sample"));
            json_object_set(*counter, "not_stable_on", json_object_get(cell[i].ev, "not_stable_on"));
        }
        json_object_set_new(*counter, "status", json_string(st));
    }
    if (r == RS_OK) {
        ivs = json_object();
        qf_emit(ivs, cell, ncell, name);
        json_object_set(o, "region", json_object_get(ivs, "intervals"));
        json_object_set_new(o, "for_all", qf_for_all(&F));
        json_object_set_new(o, "point_checks", json_pack("{s:I,s:b}", "points", (json_int_t) checked, "agree", 1));
        json_object_set_new(o, "cross_checked_samples", json_integer(checked));
        json_decref(ivs);
    }
    qf_cells_clear(crit, ncrit, cell, ncell);
    rs_qd_signs_clear(signs);
    rs_run_bounds_clear(F.b, run);
    return r;
}
