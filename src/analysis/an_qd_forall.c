/* an_qd_forall.c -- issue 15 (issue 13 section 1 over Q(sqrt d)): `region
 * NAME for all [Q]` for a model whose p = p0 + sqrt(d) p1 has coefficients
 * in Q(sqrt d)[params] (rk sdirk2, sdirk3, sqrt tableaux), one quantified
 * parameter Q.
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
 * evaluated) at sampled Q values: exit 3 on a disagreement. */
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
    slong tv, qv;
    rs_bound_t *b;
    const rs_plist_t *norms;
    const rs_scheme_struct *s;
    slong checked;          /* exact point verdicts compared */
    int bad;                /* a disagreement */
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
    fmpq_set(pt + F->tv, t);
    fmpq_set(pt + F->qv, q);
    st = rs_an_qd_point_verdict(F->run, F->req, pp);
    if (st == -2 || (st >= 0 && (st == 1) != (strcmp(said, "stable") == 0))) F->bad = 1;
    if (st >= 0) F->checked++;
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

/* NAME = t rational: the exact region of Q there (bounded, kind 1); the
 * cell stable when every piece is, marginal when every piece is bounded,
 * unstable (singular) at the fibre's first bad piece */
static int qf_rational(qf_t *F, const fmpq_t t, const char **st, json_t **ev)
{
    rs_run_t *run = F->run;
    const char *nm = run->c->params[F->tv].name, *qn = run->c->params[F->qv].name;
    rs_assign_t e;
    json_t *o = json_object(), *counter = NULL, *reg, *iv;
    size_t i;
    int verdict = 0, all = 1, r;
    fmpq_t q;
    fmpq_init(q);
    e.name = nm;
    e.var = F->tv;
    fmpq_init(e.value);
    fmpq_set(e.value, t);
    r = rs_an_qd_fiber(&verdict, &counter, o, run, F->req, 1, F->qv, F->b + F->qv, &e, 1);
    fmpq_clear(e.value);
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
        *st = all ? "stable" : "marginal";
        json_object_set_new(*ev, "certificate", json_pack("{s:s,s:O}", "text", all
            ? "the exact region of the quantified parameter at this value is stable on all of its domain"
            : "the exact region of the quantified parameter at this value is stable or marginal on all of its domain",
            "region", reg));
        if (!all)
            json_array_foreach(reg, i, iv)
                if (strcmp(json_string_value(json_object_get(iv, "status")), "stable") != 0) {
                    json_object_set(*ev, "not_stable_on", iv);
                    break;
                }
    } else if (verdict == -1) {
        json_t *cx = json_object(), *at = json_object();
        const char *cs = json_string_value(json_object_get(counter, "status"));
        *st = strcmp(cs, "singular") == 0 ? "singular" : "unstable";
        json_object_set_new(cx, nm, rs_json_fmpq(t));
        json_object_set(cx, qn, json_object_get(counter, qn));
        if (json_object_get(counter, "exact") != NULL) json_object_set(cx, "exact", json_object_get(counter, "exact"));
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
 * algebraic number's object) as the evidence of an unstable point */
static json_t *qf_counter(const char **st, json_t **ev, rs_alg_t *t0, const char *nm, const char *qn, json_t *qj,
                          rs_status_t ps)
{
    json_t *cx = json_object();
    json_object_set_new(cx, nm, rs_alg_json(t0, nm));
    json_object_set_new(cx, qn, qj);
    *st = ps == RS_STATUS_SINGULAR ? "singular" : "unstable";
    *ev = json_object();
    json_object_set_new(*ev, "counterexample", cx);
    json_object_set_new(*ev, "at_counterexample", json_pack("{s:s,s:s}", "status", rs_status_name(ps),
                        "decided_by", "exact over Q(t0, sqrt d) (and q0 when irrational)"));
    return cx;
}

/* NAME = t0 irrational: the fibre's cut points in Q (the real roots of
 * Res_t(minpoly, norm) in Q's interval, its closed ends), the status at a
 * rational sample of each open piece and at each rational cut point over
 * Q(t0, sqrt d); an irrational cut point is left open (undecided unless
 * a counterexample is found) */
static int qf_algebraic(qf_t *F, rs_alg_t *t0, const char **st, json_t **ev)
{
    rs_run_t *run = F->run;
    const fmpz_mpoly_ctx_struct *ctx = F->s->zctx;
    const char *nm = run->c->params[F->tv].name, *qn = run->c->params[F->qv].name;
    const rs_bound_t *bq = F->b + F->qv;
    fmpz_mpoly_t mp, res;
    fmpz_poly_t u;
    rs_alg_t *crit = NULL;
    slong ncrit = 0, i, k, nopen = 0, nsamp = 0;
    int identically = 0, any_marg = 0, r = RS_OK;
    json_t *cx = NULL, *samples = json_array();
    fmpq_t q;
    fmpz_mpoly_init(mp, ctx); fmpz_mpoly_init(res, ctx);
    fmpz_poly_init(u);
    fmpq_init(q);
    fmpz_mpoly_set_fmpz_poly(mp, t0->minpoly, F->tv, ctx);
    for (i = 0; i < F->norms->n && !identically; i++) {
        const fmpz_mpoly_struct *f = F->norms->p + i;
        if (fmpz_mpoly_degree_si(f, F->qv, ctx) <= 0) continue;
        if (!fmpz_mpoly_resultant(res, f, mp, F->tv, ctx) || !fmpz_mpoly_get_fmpz_poly(u, res, F->qv, ctx)) {
            identically = 1;
            break;
        }
        if (fmpz_poly_is_zero(u)) identically = 1;   /* a norm vanishes on the whole fibre */
        else if (fmpz_poly_degree(u) > 0) rs_alg_roots_append(&crit, &ncrit, u, 1);
    }
    if (bq->has_lo) crit_push_fmpq(&crit, &ncrit, bq->lo);
    if (bq->has_hi) crit_push_fmpq(&crit, &ncrit, bq->hi);
    ncrit = alg_unique(crit, ncrit);
    for (i = 0; i <= ncrit && !identically && cx == NULL; i++) {
        rs_alg_t *lo = i > 0 ? crit + i - 1 : NULL, *hi = i < ncrit ? crit + i : NULL;
        for (k = 0; k < 2 && cx == NULL; k++) {
            rs_assign_t e;
            rs_status_t ps;
            int decided;
            if (k == 0) {
                rs_alg_between(q, lo, hi);
                if (!rs_bound_contains(bq, q)) continue;
            } else {
                if (hi == NULL || !alg_inside(bq, hi)) continue;
                if (!hi->rational) {
                    /* an irrational cut point q0: over Q(t0, sqrt d, q0) */
                    r = rs_budget_check(run->err, "region for all over Q(sqrt d)");
                    if (r != RS_OK) break;
                    /* Q(t0, sqrt d, q0) of degree up to 2 deg t0 deg q0: beyond QF_MAX_FIELD_DEGREE
                     * the primitive element's arithmetic is too slow to be worth it here */
                    decided = 2 * fmpz_poly_degree(t0->minpoly) * fmpz_poly_degree(hi->minpoly) <= QF_MAX_FIELD_DEGREE
                              && rs_an_qd_alg2_status(&ps, run, F->req, F->tv, t0, F->qv, hi);
                    nsamp++;
                    json_array_append_new(samples, json_pack("{s:o,s:s}", qn, rs_alg_json(hi, qn), "status",
                                                             decided ? rs_status_name(ps) : "undecided"));
                    if (!decided) { nopen++; continue; }
                    if (ps == RS_STATUS_MARGINAL) any_marg = 1;
                    if (ps == RS_STATUS_UNSTABLE || ps == RS_STATUS_SINGULAR)
                        cx = qf_counter(st, ev, t0, nm, qn, rs_alg_json(hi, qn), ps);
                    continue;
                }
                fmpq_set(q, hi->q);
            }
            r = rs_budget_check(run->err, "region for all over Q(sqrt d)");
            if (r != RS_OK) break;
            e.name = qn;
            e.var = F->qv;
            fmpq_init(e.value);
            fmpq_set(e.value, q);
            decided = rs_an_qd_alg_status(&ps, run, F->req, F->tv, t0, &e, 1);
            fmpq_clear(e.value);
            nsamp++;
            json_array_append_new(samples, json_pack("{s:o,s:s}", qn, rs_json_fmpq(q), "status",
                                                     decided ? rs_status_name(ps) : "undecided"));
            if (!decided) { nopen++; continue; }
            if (ps == RS_STATUS_MARGINAL) any_marg = 1;
            if (ps == RS_STATUS_UNSTABLE || ps == RS_STATUS_SINGULAR)
                cx = qf_counter(st, ev, t0, nm, qn, rs_json_fmpq(q), ps);
        }
    }
    if (cx == NULL && r == RS_OK) {
        *ev = json_object();
        if (identically || nopen > 0) {
            *st = "undecided";
            json_object_set_new(*ev, "reason", json_string(identically
                ? "a condition's norm vanishes on the whole fibre at this value: its cut points are not known"
                : "a sample or cut point of the fibre at this irrational value is undecided (a repeated non-real "
                  "circle root, no primitive element within the budget, or Q(t0, sqrt d, q0) of degree over 32); "
                  "no counterexample at the others"));
        } else {
            *st = any_marg ? "marginal" : "stable";
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
    fmpz_mpoly_clear(mp, ctx); fmpz_mpoly_clear(res, ctx);
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
            if (strcmp(cell[k].status, "undecided") == 0 && cell[k].pt)
                json_array_append_new(und, rs_alg_json(cell[k].hi, name));
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
    "... for all (coefficients, discriminants, resultants, values at the ends of the quantified interval; an "
    "over-approximation of the critical values); each rational sample decided by the exact region of the quantified "
    "parameter there over Q(sqrt d), each irrational critical value t0 by the fibre's cut points over Q(t0, sqrt d); "
    "every verdict cross-checked against the exact point verdict of p derived with both parameters symbolic";

/* the cells of NAME on F->b[tv] (every Q in F->b[qv]); *crit, *cell for
 * the caller to free (qf_cells_clear) */
static int qf_cells(qf_t *F, rs_alg_t **critp, slong *ncritp, qf_cell_t **cellp, slong *ncellp)
{
    rs_run_t *run = F->run;
    slong tv = F->tv, i, ncrit = 0, ncell = 0;
    rs_plist_t l, m;
    rs_alg_t *crit = NULL;
    qf_cell_t *cell;
    fmpq_t t;
    int r;
    rs_plist_init(&l);
    rs_plist_init(&m);
    fmpq_init(t);
    r = rs_an_qd_forall_norms(&l, &F->s, run, F->req, tv, F->b);
    if (r == RS_OK) r = rs_proj_eliminate(&m, run, &l, F->qv, F->b + F->qv, tv, F->b, F->s->zctx);
    F->norms = &l;
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
    for (i = 0; r == RS_OK && i <= ncrit && !F->bad; i++) {
        rs_alg_t *lo = i > 0 ? crit + i - 1 : NULL, *hi = i < ncrit ? crit + i : NULL;
        r = rs_budget_check(run->err, "region for all over Q(sqrt d)");
        if (r != RS_OK) break;
        rs_alg_between(t, lo, hi);
        if (rs_bound_contains(F->b + tv, t)) {
            cell[ncell].pt = 0; cell[ncell].lo = lo; cell[ncell].hi = hi;
            r = qf_rational(F, t, &cell[ncell].status, &cell[ncell].ev);
            ncell++;
        }
        if (r != RS_OK || hi == NULL || !alg_inside(F->b + tv, hi)) continue;
        cell[ncell].pt = 1; cell[ncell].lo = cell[ncell].hi = hi;
        if (hi->rational) r = qf_rational(F, hi->q, &cell[ncell].status, &cell[ncell].ev);
        else r = qf_algebraic(F, hi, &cell[ncell].status, &cell[ncell].ev);
        ncell++;
    }
    if (r == RS_OK && F->bad)
        r = rs_req_error(run, F->req->q, F->req->q->text, RS_ERR_INCONSISTENT, "region for all over Q(sqrt d): a "
                         "cell's verdict and the exact point verdict of p with both parameters symbolic disagree at a "
                         "sample (internal inconsistency)%s", "");
    if (F->s != NULL) { rs_plist_clear(&l, F->s->zctx); rs_plist_clear(&m, F->s->zctx); }
    F->norms = NULL;
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

static json_t *qf_for_all(const qf_t *F)
{
    json_t *fa = json_array();
    json_array_append_new(fa, json_string(F->run->c->params[F->qv].name));
    return fa;
}

int rs_an_qd_region_forall(rs_run_t *run, const rs_an_req_t *req)
{
    slong ncrit = 0, ncell = 0;
    const char *name = run->c->params[req->u.region.param].name;
    qf_t F;
    rs_alg_t *crit = NULL;
    qf_cell_t *cell = NULL;
    json_t *o;
    int r;
    if (req->u.region.nq != 1) {
        char msg[400];
        snprintf(msg, sizeof msg, "expected one quantified parameter: region NAME for all over Q(sqrt %ld) (rk %s) "
                 "quantifies exactly one (here %ld); set the others (set P = V) and it runs, or region NAME at P=V, "
                 "or jury, hurwitz and routh with all of them free", (long) run->m->qd->d, run->m->qd->tableau,
                 (long) req->u.region.nq);
        return rs_req_error(run, req->q, req->q->text, RS_ERR_INPUT, "%s", msg);
    }
    memset(&F, 0, sizeof F);
    F.run = run; F.req = req; F.tv = req->u.region.param; F.qv = req->u.region.qv[0];
    F.b = rs_run_bounds(run);
    r = qf_cells(&F, &crit, &ncrit, &cell, &ncell);
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("region"));
        json_object_set_new(o, "param", json_string(name));
        json_object_set_new(o, "over", json_str_free(rs_an_qd_over_str(run->m->qd->d)));
        qf_emit(o, cell, ncell, name);
        json_object_set_new(o, "critical_values", json_integer(ncrit));
        json_object_set_new(o, "for_all", qf_for_all(&F));
        json_object_set_new(o, "method", json_string(qf_method));
        json_object_set_new(o, "point_checks", json_pack("{s:I,s:b}", "points", (json_int_t) F.checked, "agree", 1));
        json_object_set_new(o, "decided_by", json_string("exact"));
        json_array_append_new(run->results, o);
    }
    qf_cells_clear(crit, ncrit, cell, ncell);
    rs_run_bounds_clear(F.b, run);
    return r;
}

int rs_an_qd_claim_forall(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                          slong tv, slong qv, const rs_bound_t *b)
{
    slong ncrit = 0, ncell = 0, i, k;
    const char *name = run->c->params[tv].name;
    qf_t F;
    rs_alg_t *crit = NULL;
    qf_cell_t *cell = NULL;
    json_t *ivs;
    int r;
    memset(&F, 0, sizeof F);
    F.run = run; F.req = req; F.tv = tv; F.qv = qv;
    F.b = rs_run_bounds(run);
    for (k = 0; k < 2; k++) {   /* the claim's box (its bounds with the assumptions) */
        rs_bound_t *d = F.b + (k ? qv : tv);
        const rs_bound_t *e = b + (k ? qv : tv);
        d->has_lo = e->has_lo; d->has_hi = e->has_hi; d->lo_closed = e->lo_closed; d->hi_closed = e->hi_closed;
        d->fixed = e->fixed;
        fmpq_set(d->lo, e->lo); fmpq_set(d->hi, e->hi);
    }
    *verdict = 1;
    *counter = NULL;
    r = qf_cells(&F, &crit, &ncrit, &cell, &ncell);
    for (i = 0; r == RS_OK && i < ncell && *counter == NULL; i++) {
        const char *st = cell[i].status;
        const json_t *cx = json_object_get(cell[i].ev, "counterexample");
        if (strcmp(st, "stable") == 0 || (kind == 1 && strcmp(st, "marginal") == 0)) continue;
        if (strcmp(st, "undecided") == 0) { *verdict = 0; continue; }
        *verdict = -1;
        *counter = cx != NULL ? json_deep_copy(cx) : json_object();
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
        json_object_set_new(o, "point_checks", json_pack("{s:I,s:b}", "points", (json_int_t) F.checked, "agree", 1));
        json_object_set_new(o, "cross_checked_samples", json_integer(F.checked));
        json_decref(ivs);
    }
    qf_cells_clear(crit, ncrit, cell, ncell);
    rs_run_bounds_clear(F.b, run);
    return r;
}
