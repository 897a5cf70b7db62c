/* an_region_forall.c -- `region NAME for all [P1, ...]`: the NAME values
 * where the scheme is stable (bounded) for every admissible value of the
 * quantified parameters.  The conditions (coefficients and Hurwitz minors of
 * the bilinear polynomial, p's leading coefficient in lambda, its
 * discriminant) are projected onto NAME by eliminating the quantified
 * parameters one at a time (Collins' projection: every coefficient,
 * discriminant, pairwise resultant, and the values at the finite ends of
 * the parameter's interval); between two consecutive real zeros of the
 * projection the sign pattern of the conditions over the quantified box
 * does not change, so one rational sample per cell decides it, with the
 * claim machinery (a re-checked certificate, or an exact counterexample). */
#include <stdlib.h>
#include <string.h>
#include "analysis/registry.h"
#include "recstab/bilinear.h"
#include "recstab/hurwitz.h"

/* a set of irreducible polynomials, each up to sign once */
typedef struct {
    fmpz_mpoly_struct *p;
    slong n, cap;
} plist_t;

static void plist_init(plist_t *l)
{
    memset(l, 0, sizeof *l);
}

static void plist_clear(plist_t *l, const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    for (i = 0; i < l->n; i++) fmpz_mpoly_clear(l->p + i, ctx);
    flint_free(l->p);
    memset(l, 0, sizeof *l);
}

static void plist_push(plist_t *l, const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    for (i = 0; i < l->n; i++) {
        if (fmpz_mpoly_equal(l->p + i, f, ctx)) return;
    }
    if (l->n == l->cap) {
        l->cap = 2 * l->cap + 8;
        l->p = flint_realloc(l->p, (size_t) l->cap * sizeof(fmpz_mpoly_struct));
    }
    fmpz_mpoly_init(l->p + l->n, ctx);
    fmpz_mpoly_set(l->p + l->n, f, ctx);
    if (fmpz_sgn(l->p[l->n].coeffs) < 0) fmpz_mpoly_neg(l->p + l->n, l->p + l->n, ctx);
    for (i = 0; i < l->n; i++)        /* the negated copy of a known one */
        if (fmpz_mpoly_equal(l->p + i, l->p + l->n, ctx)) { fmpz_mpoly_clear(l->p + l->n, ctx); return; }
    l->n++;
}

/* the irreducible non-constant factors of f (nothing for 0 or a constant) */
static void plist_add(plist_t *l, const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_factor_t fac;
    slong k;
    if (fmpz_mpoly_is_zero(f, ctx) || fmpz_mpoly_is_fmpz(f, ctx)) return;
    fmpz_mpoly_factor_init(fac, ctx);
    if (fmpz_mpoly_factor_squarefree(fac, f, ctx) && fmpz_mpoly_factor(fac, f, ctx)) {
        for (k = 0; k < fac->num; k++)
            if (!fmpz_mpoly_is_fmpz(fac->poly + k, ctx)) plist_push(l, fac->poly + k, ctx);
    } else {
        plist_push(l, f, ctx);
    }
    fmpz_mpoly_factor_clear(fac, ctx);
}

/* b^d f(u = a/b), d = deg_u f: f at a rational value of u, denominators cleared */
void rs_an_forall_subst(fmpz_mpoly_t out, const fmpz_mpoly_t f, slong u, const fmpq_t x, const fmpz_mpoly_ctx_t ctx)
{
    slong d = fmpz_mpoly_degree_si(f, u, ctx), j;
    fmpz_mpoly_t c;
    fmpz_t w, aj, bj;
    fmpz_mpoly_init(c, ctx);
    fmpz_init(w); fmpz_init(aj); fmpz_init(bj);
    fmpz_mpoly_zero(out, ctx);
    for (j = 0; j <= d; j++) {
        ulong e = (ulong) j;
        fmpz_mpoly_get_coeff_vars_ui(c, f, &u, &e, 1, ctx);
        fmpz_pow_ui(aj, fmpq_numref(x), e);
        fmpz_pow_ui(bj, fmpq_denref(x), (ulong) (d - j));
        fmpz_mul(w, aj, bj);
        fmpz_mpoly_scalar_mul_fmpz(c, c, w, ctx);
        fmpz_mpoly_add(out, out, c, ctx);
    }
    fmpz_mpoly_clear(c, ctx);
    fmpz_clear(w); fmpz_clear(aj); fmpz_clear(bj);
}

/* The conditions whose signs decide the verdict: p's leading coefficient in
 * lambda, the discriminant of its squarefree part (collisions), and the
 * coefficients and Hurwitz minors of q(z) = (1-z)^n p((1+z)/(1-z)) (roots
 * crossing the circle; a_0, a_n: roots at lambda = 1, -1). */
static int forall_conditions(plist_t *l, rs_run_t *run, const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    slong lv = s->lambda_var, n = fmpz_mpoly_degree_si(v->cp->p, lv, s->zctx), k;
    ulong nn = (ulong) n;
    fmpz_mpoly_t sqf, qz, t;
    fmpz_mpoly_factor_t fac;
    rs_hurwitz_t h;
    int r = RS_OK;
    fmpz_mpoly_init(sqf, s->zctx);
    fmpz_mpoly_init(qz, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    fmpz_mpoly_get_coeff_vars_ui(t, v->cp->p, &lv, &nn, 1, s->zctx);
    plist_add(l, t, s->zctx);
    fmpz_mpoly_one(sqf, s->zctx);
    fmpz_mpoly_factor_init(fac, s->zctx);
    if (fmpz_mpoly_factor(fac, v->cp->p, s->zctx)) {
        for (k = 0; k < fac->num; k++)
            if (fmpz_mpoly_degree_si(fac->poly + k, lv, s->zctx) > 0)
                fmpz_mpoly_mul(sqf, sqf, fac->poly + k, s->zctx);
    } else {
        fmpz_mpoly_set(sqf, v->cp->p, s->zctx);
    }
    fmpz_mpoly_factor_clear(fac, s->zctx);
    if (fmpz_mpoly_degree_si(sqf, lv, s->zctx) >= 2 && fmpz_mpoly_discriminant(t, sqf, lv, s->zctx))
        plist_add(l, t, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, sqf, lv, s->zctx);
    rs_hurwitz_init(h);
    if (fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 1) {
        r = rs_hurwitz_compute(h, qz, lv, NULL, s->zctx, run->err);
        for (k = 0; r == RS_OK && k <= h->n; k++) plist_add(l, h->coeffs + k, s->zctx);
        for (k = 0; r == RS_OK && k < h->n; k++) plist_add(l, h->minors + k, s->zctx);
    }
    rs_hurwitz_clear(h, s->zctx);
    fmpz_mpoly_clear(sqf, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
    return r;
}

/* One projection step: the polynomials of l with u eliminated. */
static int forall_project(plist_t *out, rs_run_t *run, const plist_t *l, slong u, const rs_bound_t *bu,
                          const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t t;
    slong i, j, k;
    int r = RS_OK;
    fmpz_mpoly_init(t, ctx);
    for (i = 0; i < l->n && r == RS_OK; i++) {
        const fmpz_mpoly_struct *f = l->p + i;
        slong d = fmpz_mpoly_degree_si(f, u, ctx);
        r = rs_budget_check(run->err, "the projection of region ... for all");
        if (d <= 0) { plist_add(out, f, ctx); continue; }
        for (k = 0; k <= d; k++) {                 /* behaviour at infinity and where f vanishes in u */
            ulong e = (ulong) k;
            fmpz_mpoly_get_coeff_vars_ui(t, f, &u, &e, 1, ctx);
            plist_add(out, t, ctx);
        }
        if (d >= 2 && fmpz_mpoly_discriminant(t, f, u, ctx)) plist_add(out, t, ctx);
        if (bu->has_lo) { rs_an_forall_subst(t, f, u, bu->lo, ctx); plist_add(out, t, ctx); }
        if (bu->has_hi) { rs_an_forall_subst(t, f, u, bu->hi, ctx); plist_add(out, t, ctx); }
        for (j = i + 1; j < l->n && r == RS_OK; j++) {
            if (fmpz_mpoly_degree_si(l->p + j, u, ctx) <= 0) continue;
            r = rs_budget_check(run->err, "the projection of region ... for all");
            if (r == RS_OK && fmpz_mpoly_resultant(t, f, l->p + j, u, ctx)) plist_add(out, t, ctx);
        }
    }
    fmpz_mpoly_clear(t, ctx);
    return r;
}

int rs_an_forall_critical(fmpz_poly_struct **out, slong *nout, rs_run_t *run, const rs_variant_t *v, slong tv,
                          const slong *qv, slong nq, const rs_bound_t *b)
{
    const fmpz_mpoly_ctx_struct *ctx = v->s->zctx;
    plist_t l, m;
    slong i;
    int r;
    plist_init(&l);
    r = forall_conditions(&l, run, v);
    for (i = 0; i < nq && r == RS_OK; i++) {
        plist_init(&m);
        r = forall_project(&m, run, &l, qv[i], b + qv[i], ctx);
        plist_clear(&l, ctx);
        l = m;
    }
    for (i = 0; i < l.n && r == RS_OK; i++) {
        fmpz_poly_t u;
        if (fmpz_mpoly_degree_si(l.p + i, tv, ctx) <= 0) continue;
        fmpz_poly_init(u);
        if (fmpz_mpoly_get_fmpz_poly(u, l.p + i, tv, ctx)) {
            *out = flint_realloc(*out, (size_t) (*nout + 1) * sizeof(fmpz_poly_struct));
            fmpz_poly_init(*out + *nout);
            fmpz_poly_swap(*out + *nout, u);
            (*nout)++;
        }
        fmpz_poly_clear(u);
    }
    plist_clear(&l, ctx);
    return r;
}

/* The exact verdict at the counterexample, recomputed from scratch with every
 * parameter substituted: it must violate what the search said it violates. */
static int forall_recheck(int *agrees, rs_run_t *run, const json_t *ev)
{
    const json_t *cx = json_object_get(ev, "counterexample");
    const char *said = json_string_value(json_object_get(json_object_get(ev, "at_counterexample"), "status"));
    const char *key;
    json_t *val;
    rs_assign_t *extra = calloc((size_t) run->c->nparams + 1, sizeof(rs_assign_t)), *a = NULL;
    slong n = 0, na = 0;
    rs_variant_t *v;
    rs_status_t st;
    rs_rootcount_t rc;
    int r;
    json_object_foreach((json_t *) cx, key, val) {
        extra[n].var = rs_case_param_index(run->c, key);
        extra[n].name = run->c->params[extra[n].var].name;
        fmpq_init(extra[n].value);
        fmpq_set_str(extra[n].value, json_string_value(val), 10);
        n++;
    }
    rs_run_assignments(run, &a, &na, NULL, 0, extra, n);
    r = rs_run_variant(&v, run, a, na);
    if (r == RS_OK) {
        r = rs_run_point_status(&st, rc, run, v, NULL, NULL, 0);
        if (r == RS_OK) *agrees = said != NULL && strcmp(said, rs_status_name(st)) == 0;
        rs_rootcount_clear(rc);
    }
    rs_assign_free(a, na);
    rs_assign_free(extra, n);
    return r;
}

static rs_status_t status_named(const json_t *ev)
{
    const char *w = json_string_value(json_object_get(json_object_get(ev, "at_counterexample"), "status"));
    if (w != NULL && strcmp(w, "singular") == 0) return RS_STATUS_SINGULAR;
    if (w != NULL && strcmp(w, "marginal") == 0) return RS_STATUS_MARGINAL;
    return RS_STATUS_UNSTABLE;
}

/* the set of a cell: the assumptions, the set values, tv in [lo, hi] */
static rs_bound_t *forall_bounds(rs_run_t *run, slong tv, const fmpq_t lo, const fmpq_t hi)
{
    slong np = run->c->nparams, i;
    rs_bound_t *b = flint_malloc((np + 1) * sizeof(rs_bound_t));
    rs_bounds_init(b, np);
    for (i = 0; i < run->c->nassume; i++) rs_bounds_add(b, &run->c->assume[i], run->c, run->err);
    for (i = 0; i < run->c->nsets; i++) {
        slong k = rs_case_param_index(run->c, run->c->sets[i].name);
        b[k].has_lo = b[k].has_hi = b[k].lo_closed = b[k].hi_closed = b[k].fixed = 1;
        fmpq_set(b[k].lo, run->c->sets[i].value);
        fmpq_set(b[k].hi, run->c->sets[i].value);
    }
    b[tv].has_lo = b[tv].has_hi = b[tv].lo_closed = b[tv].hi_closed = 1;
    b[tv].fixed = fmpq_equal(lo, hi);
    fmpq_set(b[tv].lo, lo);
    fmpq_set(b[tv].hi, hi);
    return b;
}

/* A certificate that the scheme is stable (kind 0) or bounded (kind 1) for
 * tv in [lo, hi] and every admissible value of the others: *proved. */
int rs_an_forall_prove(int *proved, json_t **ev, rs_run_t *run, slong tv, const fmpq_t lo, const fmpq_t hi, int kind)
{
    slong np = run->c->nparams;
    rs_bound_t *b = forall_bounds(run, tv, lo, hi);
    int v = 0, r = rs_an_claim_decide(&v, ev, run, kind, b, 0);
    *proved = r == RS_OK && v == 1;
    if (r == RS_OK && v == 2) run->outcome |= RS_OUTCOME_INCONSISTENT;
    rs_bounds_clear(b, np);
    flint_free(b);
    return r;
}

/* The cell at tv = t: stable for all (a certificate), else a point that is
 * not stable; marginal if bounded is proved, unstable at a counterexample. */
int rs_an_forall_cell(rs_status_t *st, int *decided, json_t **ev, rs_run_t *run, slong tv, const fmpq_t t)
{
    slong np = run->c->nparams;
    rs_bound_t *b = forall_bounds(run, tv, t, t);
    json_t *e1 = NULL, *e2 = NULL;
    int vs = 0, vb = 0, agrees = 1, r;
    *decided = 0;
    *ev = NULL;
    r = rs_an_claim_decide(&vs, &e1, run, 0, b, 0);
    if (r == RS_OK && vs == 1) {
        *decided = 1; *st = RS_STATUS_STABLE; *ev = e1; e1 = NULL;
    } else if (r == RS_OK && vs == -1) {
        r = forall_recheck(&agrees, run, e1);
        *st = status_named(e1);
        if (r == RS_OK && *st != RS_STATUS_MARGINAL) {
            *decided = 1; *ev = e1; e1 = NULL;
        } else if (r == RS_OK) {
            /* a marginal point: bounded for all, or an unbounded point elsewhere */
            r = rs_an_claim_decide(&vb, &e2, run, 1, b, 0);
            if (r == RS_OK && vb == -1) r = forall_recheck(&agrees, run, e2);
            if (r == RS_OK && (vb == 1 || vb == -1)) {
                *decided = 1;
                *st = vb == 1 ? RS_STATUS_MARGINAL : status_named(e2);
                *ev = e2; e2 = NULL;
                if (vb == 1) json_object_set(*ev, "not_stable_at", json_object_get(e1, "counterexample"));
            } else if (r == RS_OK) {
                *ev = e2; e2 = NULL;
            }
            if (vb == 2) agrees = 0;
        }
    } else if (r == RS_OK) {
        *ev = e1; e1 = NULL;
        if (vs == 2) agrees = 0;
    }
    if (!agrees) run->outcome |= RS_OUTCOME_INCONSISTENT;
    json_decref(e1);
    json_decref(e2);
    rs_bounds_clear(b, np);
    flint_free(b);
    return r;
}
