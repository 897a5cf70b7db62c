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
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <fmpz_vec.h>
#include <ulong_extras.h>
#include <fmpq_vec.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include "analysis/registry.h"
#include "recstab/bilinear.h"
#include "recstab/hurwitz.h"
#include "stability/schur_complex.h"
#include "recstab/semisimple.h"
#include "analysis/an_region.h"
#include "algebra/mfactor.h"

/* ---- the projection -------------------------------------------------------- */

void rs_plist_init(rs_plist_t *l)
{
    memset(l, 0, sizeof *l);
}

void rs_plist_clear(rs_plist_t *l, const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    for (i = 0; i < l->n; i++) fmpz_mpoly_clear(l->p + i, ctx);
    flint_free(l->p);
    memset(l, 0, sizeof *l);
}

static void plist_push(rs_plist_t *l, const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx)
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

/* x_v = N(s)/D(s), N and D linear with integer coefficients and D > 0 for
 * s > 0: the map of s in (0, inf) onto v's interval (as the claim prover's) */
static int bound_map(fmpz_mpoly_t N, fmpz_mpoly_t D, slong v, const rs_bound_t *b, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t sv;
    fmpz_t t;
    if (!b->has_lo && !b->has_hi) return 0;
    fmpz_mpoly_init(sv, ctx);
    fmpz_init(t);
    fmpz_mpoly_gen(sv, v, ctx);
    if (b->has_lo && b->has_hi) {                 /* (lo + hi s)/(1 + s), lo = a/c, hi = e/f */
        fmpz_mul(t, fmpq_numref(b->hi), fmpq_denref(b->lo));
        fmpz_mpoly_scalar_mul_fmpz(N, sv, t, ctx);
        fmpz_mul(t, fmpq_numref(b->lo), fmpq_denref(b->hi));
        fmpz_mpoly_add_fmpz(N, N, t, ctx);
        fmpz_mul(t, fmpq_denref(b->lo), fmpq_denref(b->hi));
        fmpz_mpoly_add_si(D, sv, 1, ctx);
        fmpz_mpoly_scalar_mul_fmpz(D, D, t, ctx);
    } else if (b->has_lo) {                       /* lo + s = (a + c s)/c */
        fmpz_mpoly_scalar_mul_fmpz(N, sv, fmpq_denref(b->lo), ctx);
        fmpz_mpoly_add_fmpz(N, N, fmpq_numref(b->lo), ctx);
        fmpz_mpoly_set_fmpz(D, fmpq_denref(b->lo), ctx);
    } else {                                      /* hi - s = (e - f s)/f */
        fmpz_mpoly_scalar_mul_fmpz(N, sv, fmpq_denref(b->hi), ctx);
        fmpz_mpoly_neg(N, N, ctx);
        fmpz_mpoly_add_fmpz(N, N, fmpq_numref(b->hi), ctx);
        fmpz_mpoly_set_fmpz(D, fmpq_denref(b->hi), ctx);
    }
    fmpz_mpoly_clear(sv, ctx);
    fmpz_clear(t);
    return 1;
}

/* 1 when f has one sign and no zero on the domain b (tv's ends open: they
 * are cells of their own; the quantified parameters' closed ends
 * included): after mapping every interval onto s > 0, all coefficients of
 * one sign (positive on the open orthant) and the polynomial of the closed
 * faces' corner non-zero (every face between has a superset of its terms).
 * Such a factor cannot separate cells and is left out of the projection. */
static int sign_definite(const fmpz_mpoly_t f, slong tv, const rs_bound_t *b, const fmpz_mpoly_ctx_t ctx)
{
    slong nv = ctx->minfo->nvars, v, i, len;
    fmpz_mpoly_t P, N, D, c, acc, pw, t;
    int ok = 1, sg;
    if (fmpz_mpoly_is_fmpz(f, ctx)) return !fmpz_mpoly_is_zero(f, ctx);
    fmpz_mpoly_init(P, ctx); fmpz_mpoly_init(N, ctx); fmpz_mpoly_init(D, ctx);
    fmpz_mpoly_init(c, ctx); fmpz_mpoly_init(acc, ctx); fmpz_mpoly_init(pw, ctx); fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_set(P, f, ctx);
    for (v = 0; v < nv && ok; v++) {
        slong d = fmpz_mpoly_degree_si(P, v, ctx), k;
        if (d <= 0) continue;
        if (!bound_map(N, D, v, b + v, ctx) || fmpz_mpoly_length(P, ctx) > 4000) { ok = 0; break; }
        fmpz_mpoly_zero(acc, ctx);
        for (k = 0; k <= d; k++) {                /* sum c_k N^k D^(d-k) */
            ulong e = (ulong) k;
            fmpz_mpoly_get_coeff_vars_ui(c, P, &v, &e, 1, ctx);
            if (fmpz_mpoly_is_zero(c, ctx)) continue;
            fmpz_mpoly_pow_ui(t, N, e, ctx);
            fmpz_mpoly_pow_ui(pw, D, (ulong) (d - k), ctx);
            fmpz_mpoly_mul(t, t, pw, ctx);
            fmpz_mpoly_mul(t, t, c, ctx);
            fmpz_mpoly_add(acc, acc, t, ctx);
        }
        fmpz_mpoly_swap(P, acc, ctx);
    }
    len = fmpz_mpoly_length(P, ctx);
    sg = len > 0 ? fmpz_sgn(P->coeffs) : 0;
    for (i = 0; i < len && ok; i++) ok = fmpz_sgn(P->coeffs + i) == sg;
    ok = ok && sg != 0;
    /* the corner of the closed faces of the quantified parameters */
    for (v = 0; v < nv && ok; v++) {
        ulong e;
        if (v == tv || fmpz_mpoly_degree_si(f, v, ctx) <= 0) continue;
        if (b[v].has_lo && b[v].lo_closed) {
            e = 0;
        } else if (b[v].has_hi && b[v].hi_closed) {
            e = b[v].has_lo ? (ulong) fmpz_mpoly_degree_si(f, v, ctx) : 0;
        } else {
            continue;
        }
        fmpz_mpoly_get_coeff_vars_ui(c, P, &v, &e, 1, ctx);
        fmpz_mpoly_swap(P, c, ctx);
        ok = !fmpz_mpoly_is_zero(P, ctx);
    }
    fmpz_mpoly_clear(P, ctx); fmpz_mpoly_clear(N, ctx); fmpz_mpoly_clear(D, ctx);
    fmpz_mpoly_clear(c, ctx); fmpz_mpoly_clear(acc, ctx); fmpz_mpoly_clear(pw, ctx); fmpz_mpoly_clear(t, ctx);
    return ok;
}

typedef struct {
    const fmpz_mpoly_ctx_struct *ctx;
    fmpz_mpoly_struct *f;
    fmpz_mpoly_factor_struct *fac;
    int *ok;
    slong n;
    const rs_variant_t *lead_v;     /* q's leading coefficient of this variant ... */
    fmpz_mpoly_t lead;              /* ... (rs_an_forall_lead_nonzero) */
    fmpz_mpoly_struct *hq;          /* rs_hurwitz_memo_compute: q, ... */
    slong *hz;                      /* ... its z variable ... */
    rs_hurwitz_struct **hh;         /* ... and its Hurwitz data (each its own
                                       block: the pointers handed out stay
                                       valid when the memo grows) */
    slong nh;
} factor_memo_t;

static _Thread_local factor_memo_t *factor_memo = NULL;

void *rs_factor_memo_begin(const fmpz_mpoly_ctx_t ctx)
{
    factor_memo_t *m = flint_calloc(1, sizeof(factor_memo_t)), *outer = factor_memo;
    m->ctx = ctx;
    fmpz_mpoly_init(m->lead, ctx);
    factor_memo = m;
    return outer;
}

void rs_factor_memo_end(void *outer)
{
    factor_memo_t *m = factor_memo;
    slong i;
    factor_memo = outer;
    if (m == NULL) return;
    for (i = 0; i < m->n; i++) {
        fmpz_mpoly_clear(m->f + i, m->ctx);
        fmpz_mpoly_factor_clear(m->fac + i, m->ctx);
    }
    flint_free(m->f);
    flint_free(m->fac);
    flint_free(m->ok);
    for (i = 0; i < m->nh; i++) {
        fmpz_mpoly_clear(m->hq + i, m->ctx);
        rs_hurwitz_clear(m->hh[i], m->ctx);
        flint_free(m->hh[i]);
    }
    flint_free(m->hq);
    flint_free(m->hz);
    flint_free(m->hh);
    fmpz_mpoly_clear(m->lead, m->ctx);
    flint_free(m);
}

/* rs_hurwitz_compute(own, q, zvar, NULL, ctx, err), or its result for an
 * equal q kept in the memo (the same symbolic q meets the per-condition
 * projection, the full one and the pair crossings of region ... for all:
 * about 0.8 M instructions each on HHT-alpha); *hp points to own or to the
 * memo's copy (valid until rs_factor_memo_end).  Only successful results
 * are kept.  own must be initialised (and is cleared by the caller). */
int rs_hurwitz_memo_compute(const rs_hurwitz_struct **hp, rs_hurwitz_t own, const fmpz_mpoly_t q,
                            slong zvar, const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    factor_memo_t *m = factor_memo;
    slong i;
    int r;
    *hp = own;
    if (m == NULL || m->ctx != ctx) return rs_hurwitz_compute(own, q, zvar, NULL, ctx, err);
    for (i = 0; i < m->nh; i++)
        if (m->hz[i] == zvar && fmpz_mpoly_equal(m->hq + i, q, ctx)) {
            *hp = m->hh[i];
            return RS_OK;
        }
    m->hq = flint_realloc(m->hq, (size_t) (m->nh + 1) * sizeof(fmpz_mpoly_struct));
    m->hz = flint_realloc(m->hz, (size_t) (m->nh + 1) * sizeof(slong));
    m->hh = flint_realloc(m->hh, (size_t) (m->nh + 1) * sizeof(rs_hurwitz_struct *));
    m->hh[m->nh] = flint_malloc(sizeof(rs_hurwitz_struct));
    rs_hurwitz_init(m->hh[m->nh]);
    r = rs_hurwitz_compute(m->hh[m->nh], q, zvar, NULL, ctx, err);
    if (r != RS_OK) {
        rs_hurwitz_clear(m->hh[m->nh], ctx);
        flint_free(m->hh[m->nh]);
        return r;
    }
    fmpz_mpoly_init(m->hq + m->nh, ctx);
    fmpz_mpoly_set(m->hq + m->nh, q, ctx);
    m->hz[m->nh] = zvar;
    *hp = m->hh[m->nh];
    m->nh++;
    return RS_OK;
}

/* fmpz_mpoly_factor, or its result for an equal f kept in the memo */
int rs_factor_memo_factor(fmpz_mpoly_factor_t fac, const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx)
{
    factor_memo_t *m = factor_memo;
    slong i;
    int ok;
    if (m == NULL || m->ctx != ctx) return rs_mpoly_factor(fac, f, ctx);
    for (i = 0; i < m->n; i++)
        if (fmpz_mpoly_equal(m->f + i, f, ctx)) {
            if (m->ok[i]) fmpz_mpoly_factor_set(fac, m->fac + i, ctx);
            return m->ok[i];
        }
    ok = rs_mpoly_factor(fac, f, ctx);
    m->f = flint_realloc(m->f, (size_t) (m->n + 1) * sizeof(fmpz_mpoly_struct));
    m->fac = flint_realloc(m->fac, (size_t) (m->n + 1) * sizeof(fmpz_mpoly_factor_struct));
    m->ok = flint_realloc(m->ok, (size_t) (m->n + 1) * sizeof(int));
    fmpz_mpoly_init(m->f + m->n, ctx);
    fmpz_mpoly_set(m->f + m->n, f, ctx);
    fmpz_mpoly_factor_init(m->fac + m->n, ctx);
    if (ok) fmpz_mpoly_factor_set(m->fac + m->n, fac, ctx);
    m->ok[m->n] = ok;
    m->n++;
    return ok;
}

/* fac := the factorisation of f when f has one variable only (the
 * projection's last polynomials, in NAME): fmpz_poly_factor, without
 * fmpz_mpoly_factor's content and compression steps over the whole context
 * (about 0.2 M instructions a call on HHT-alpha's); the same factors, in
 * fmpz_poly_factor's order (a projection list's order does not matter: its
 * roots are sorted).  Returns 0 (fac untouched) for other f. */
static int factor_if_univariate(fmpz_mpoly_factor_t fac, const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx)
{
    slong nv = ctx->minfo->nvars, i, var = -1;
    slong *deg;
    fmpz_poly_t p;
    fmpz_poly_factor_t pf;
    if (!fmpz_mpoly_degrees_fit_si(f, ctx)) return 0;
    deg = flint_malloc(nv * sizeof(slong));
    fmpz_mpoly_degrees_si(deg, f, ctx);
    for (i = 0; i < nv; i++)
        if (deg[i] > 0) {
            if (var >= 0) { var = -2; break; }
            var = i;
        }
    flint_free(deg);
    if (var < 0) return 0;
    fmpz_poly_init(p);
    if (!fmpz_mpoly_get_fmpz_poly(p, f, var, ctx)) { fmpz_poly_clear(p); return 0; }
    fmpz_poly_factor_init(pf);
    fmpz_poly_factor(pf, p);
    fmpz_mpoly_factor_fit_length(fac, pf->num, ctx);
    fmpz_set(fac->constant, &pf->c);
    fmpz_one(fac->constant_den);
    for (i = 0; i < pf->num; i++) {
        fmpz_mpoly_set_fmpz_poly(fac->poly + i, pf->p + i, var, ctx);
        fmpz_set_si(fac->exp + i, pf->exp[i]);
    }
    fac->num = pf->num;
    fmpz_poly_factor_clear(pf);
    fmpz_poly_clear(p);
    return 1;
}

/* The irreducible non-constant factors of f (nothing for 0 or a constant);
 * with dom != NULL only those that can vanish on the domain dom. */
void rs_plist_add(rs_plist_t *l, const fmpz_mpoly_t f, slong tv, const rs_bound_t *dom, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_factor_t fac;
    slong k;
    if (fmpz_mpoly_is_zero(f, ctx) || fmpz_mpoly_is_fmpz(f, ctx)) return;
    fmpz_mpoly_factor_init(fac, ctx);
    if (factor_if_univariate(fac, f, ctx) || rs_factor_memo_factor(fac, f, ctx)) {
        for (k = 0; k < fac->num; k++)
            if (!fmpz_mpoly_is_fmpz(fac->poly + k, ctx) && (dom == NULL || !sign_definite(fac->poly + k, tv, dom, ctx)))
                plist_push(l, fac->poly + k, ctx);
    } else if (dom == NULL || !sign_definite(f, tv, dom, ctx)) {
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

/* u -> u^(1/g) where every exponent of u in l is a multiple g > 1 and u >= 0
 * on its interval (a homeomorphism of [0, inf): the same cells, smaller
 * degrees); the interval's ends are raised to the power g in *bd. */
static void deflate(rs_plist_t *l, slong u, rs_bound_t *bd, const fmpz_mpoly_ctx_t ctx)
{
    slong nv = ctx->minfo->nvars, i, j;
    fmpz *shift = _fmpz_vec_init(nv), *stride = _fmpz_vec_init(nv), *one = _fmpz_vec_init(nv);
    ulong g = 0;
    for (i = 0; i < l->n; i++) {
        slong len = fmpz_mpoly_length(l->p + i, ctx);
        ulong *e = flint_malloc(nv * sizeof(ulong));
        for (j = 0; j < len; j++) {
            fmpz_mpoly_get_term_exp_ui(e, l->p + i, j, ctx);
            g = n_gcd(g, e[u]);
        }
        flint_free(e);
    }
    if (g > 1 && bd->has_lo && fmpq_sgn(bd->lo) >= 0) {
        for (j = 0; j < nv; j++) fmpz_one(stride + j);
        fmpz_set_ui(stride + u, g);
        for (i = 0; i < l->n; i++) fmpz_mpoly_deflate(l->p + i, l->p + i, shift, stride, ctx);
        fmpq_pow_si(bd->lo, bd->lo, (slong) g);
        if (bd->has_hi) fmpq_pow_si(bd->hi, bd->hi, (slong) g);
    }
    _fmpz_vec_clear(shift, nv); _fmpz_vec_clear(stride, nv); _fmpz_vec_clear(one, nv);
}

/* One projection step (McCallum's, with Brown's reduction): the polynomials
 * of l with u eliminated -- the leading coefficient (roots escaping to
 * infinity), the other coefficients only where no coefficient has one sign
 * on the domain (where f could vanish identically), the discriminant, the
 * pairwise resultants, and the values at the finite ends of u's interval.
 * Factors of one sign on the domain dom are left out. */
int rs_proj_eliminate(rs_plist_t *out, rs_run_t *run, const rs_plist_t *in, slong u, const rs_bound_t *bu,
                      slong tv, const rs_bound_t *dom, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t t;
    rs_plist_t l;
    rs_bound_t bd;
    slong i, j, k;
    int r = RS_OK;
    rs_plist_init(&l);
    for (i = 0; i < in->n; i++) plist_push(&l, in->p + i, ctx);
    rs_bounds_init(&bd, 1);
    bd.has_lo = bu->has_lo; bd.has_hi = bu->has_hi; bd.lo_closed = bu->lo_closed; bd.hi_closed = bu->hi_closed;
    fmpq_set(bd.lo, bu->lo); fmpq_set(bd.hi, bu->hi);
    deflate(&l, u, &bd, ctx);
    fmpz_mpoly_init(t, ctx);
    for (i = 0; i < l.n && r == RS_OK; i++) {
        const fmpz_mpoly_struct *f = l.p + i;
        slong d = fmpz_mpoly_degree_si(f, u, ctx);
        int definite = 0;
        r = rs_budget_check(run->err, "the projection of region ... for all");
        if (d <= 0) { rs_plist_add(out, f, tv, dom, ctx); continue; }
        for (k = d; k >= 0 && !definite; k--) {
            ulong e = (ulong) k;
            fmpz_mpoly_get_coeff_vars_ui(t, f, &u, &e, 1, ctx);
            definite = !fmpz_mpoly_is_zero(t, ctx) && sign_definite(t, tv, dom, ctx);
        }
        for (k = d; k >= 0; k--) {                 /* behaviour at infinity and where f vanishes in u */
            ulong e = (ulong) k;
            fmpz_mpoly_get_coeff_vars_ui(t, f, &u, &e, 1, ctx);
            rs_plist_add(out, t, tv, dom, ctx);
            if (definite) break;
        }
        if (d >= 2 && fmpz_mpoly_discriminant(t, f, u, ctx)) rs_plist_add(out, t, tv, dom, ctx);
        if (bd.has_lo) { rs_an_forall_subst(t, f, u, bd.lo, ctx); rs_plist_add(out, t, tv, dom, ctx); }
        if (bd.has_hi) { rs_an_forall_subst(t, f, u, bd.hi, ctx); rs_plist_add(out, t, tv, dom, ctx); }
        for (j = i + 1; j < l.n && r == RS_OK; j++) {
            if (fmpz_mpoly_degree_si(l.p + j, u, ctx) <= 0) continue;
            r = rs_budget_check(run->err, "the projection of region ... for all");
            if (r == RS_OK && fmpz_mpoly_resultant(t, f, l.p + j, u, ctx)) rs_plist_add(out, t, tv, dom, ctx);
        }
    }
    fmpz_mpoly_clear(t, ctx);
    rs_plist_clear(&l, ctx);
    rs_bounds_clear(&bd, 1);
    return r;
}

/* A char line over Q(i), p = A + i B (the block form's M = [A -B; B A]):
 * its own conditions, all in one group (full projection), since det M =
 * p conj(p) has the wrong scalar semantics (p's simple circle roots z and
 * conj(p)'s 1/z meet as a double root of det M): |a_n|^2 (degree drop), the
 * Schur-Cohn deltas over Q(i) (stability is their conjunction), Res(p, p*)
 * (a root on the circle), |disc p|^2 (a repeated root: the bounded/unbounded
 * boundary on the circle).  On a cell of the decomposition they are
 * sign-invariant: with Res(p, p*) != 0 as a polynomial no root meets the
 * circle inside an open cell (and a second root reaching it on a curve
 * Res = 0 is a singular point or a crossing of two branches, a critical
 * value); with Res = 0 identically and p self-inversive the roots are
 * symmetric about the circle and one leaves it only by meeting another
 * (disc p = 0).  So the status is constant on the cell, and one sample of
 * NAME per cell decides "for all". */
static int forall_conditions_complex(rs_plist_t **groups, slong *ng, rs_run_t *run, const rs_variant_t *v,
                                     slong tv, const rs_bound_t *dom)
{
    const rs_scheme_struct *s = v->s;
    const fmpq_mpoly_struct *A = s->M + 0, *B = s->M + 2;
    fmpz_mpoly_t a, b, t;
    fmpz_t w;
    rs_schur_cx_conds_t c;
    rs_plist_t *g;
    slong k;
    int ok;
    fmpz_mpoly_init(a, s->zctx); fmpz_mpoly_init(b, s->zctx); fmpz_mpoly_init(t, s->zctx);
    fmpz_init(w);
    /* A + i B times den(c_A) den(c_B) > 0, integer coefficients */
    fmpz_mul(w, fmpq_numref(A->content), fmpq_denref(B->content));
    fmpz_mpoly_scalar_mul_fmpz(a, A->zpoly, w, s->zctx);
    fmpz_mul(w, fmpq_numref(B->content), fmpq_denref(A->content));
    fmpz_mpoly_scalar_mul_fmpz(b, B->zpoly, w, s->zctx);
    rs_schur_cx_conds_init(&c);
    ok = rs_schur_cx_conds(&c, a, b, s->lambda_var, s->zctx);
    /* Res(p, p*) = 0 identically: p and p* share a factor.  Handled when p
     * is self-inversive (its roots symmetric about the circle: a circle root
     * leaves it only by meeting another, where disc p = 0, and a repeated
     * root or a pair z, 1/conj z off the circle is unbounded either way);
     * otherwise a root could cross the circle where nothing here vanishes */
    if (ok && fmpz_mpoly_is_zero(c.res, s->zctx) && !c.self_inversive) ok = -1;
    g = flint_malloc(sizeof(rs_plist_t));
    rs_plist_init(g);
    if (ok == 1) {
        rs_plist_add(g, c.lead, tv, dom, s->zctx);
        for (k = 0; k < c.ndelta; k++) rs_plist_add(g, c.delta + k, tv, dom, s->zctx);
        rs_plist_add(g, c.res, tv, dom, s->zctx);
        fmpz_mpoly_mul(t, c.disc_re, c.disc_re, s->zctx);
        fmpz_mpoly_mul(a, c.disc_im, c.disc_im, s->zctx);
        fmpz_mpoly_add(t, t, a, s->zctx);
        rs_plist_add(g, t, tv, dom, s->zctx);
    }
    rs_schur_cx_conds_clear(&c, s->zctx);
    fmpz_mpoly_clear(a, s->zctx); fmpz_mpoly_clear(b, s->zctx); fmpz_mpoly_clear(t, s->zctx);
    fmpz_clear(w);
    *groups = g;
    *ng = 1;
    if (ok == 0)
        return rs_error_set(run->err, RS_ERR_LIMIT, "region for all: the Schur-Cohn conditions over Q(i) of this "
                            "complex char line grow too large");
    if (ok < 0)
        return rs_error_set(run->err, RS_ERR_LIMIT, "region for all: not available for a complex char line whose p "
                            "shares a factor with p* = lambda^n conj(p(1/conj lambda)) without being self-inversive "
                            "(Res(p, p*) = 0 identically: root crossings of the circle are not seen)");
    return RS_OK;
}

/* The groups of conditions, each projected on its own.  full = 0: what
 * "stable for every value" and "singular for some value" depend on: p's
 * leading coefficient in lambda (one group) and each coefficient and
 * Hurwitz minor of q(z) = (1-z)^n p((1+z)/(1-z)) (one group each):
 * stability is their conjunction (a_i, Delta_k of one sign), and for all
 * x (A and B) = (for all x A) and (for all x B), so each truth value
 * changes only at the critical values of its own polynomial.  full = 1:
 * one group with all of them and the discriminant of p's squarefree part
 * (collisions on the circle), with every pairwise resultant: what the
 * bounded/unbounded distinction needs. */
static int forall_conditions(rs_plist_t **groups, slong *ng, rs_run_t *run, const rs_variant_t *v, slong tv,
                             const rs_bound_t *dom, int *full)
{
    const rs_scheme_struct *s = v->s;
    slong lv = s->lambda_var, n = fmpz_mpoly_degree_si(v->cp->p, lv, s->zctx), k, ngr;
    ulong nn = (ulong) n;
    fmpz_mpoly_t sqf, qz, t;
    fmpz_mpoly_factor_t fac;
    fmpz_mpoly_struct *drops = NULL;
    slong ndrops = 0;
    rs_hurwitz_t hown;
    const rs_hurwitz_struct *h = hown;
    rs_plist_t *g;
    int r = RS_OK;
    if (s->complex_char) {
        *full = 1;
        return forall_conditions_complex(groups, ng, run, v, tv, dom);
    }
    fmpz_mpoly_init(sqf, s->zctx);
    fmpz_mpoly_init(qz, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    fmpz_mpoly_one(sqf, s->zctx);
    fmpz_mpoly_factor_init(fac, s->zctx);
    if (rs_factor_memo_factor(fac, v->cp->p, s->zctx)) {
        for (k = 0; k < fac->num; k++)
            if (fmpz_mpoly_degree_si(fac->poly + k, lv, s->zctx) > 0) {
                fmpz_mpoly_mul(sqf, sqf, fac->poly + k, s->zctx);
                /* a repeated factor f^e of det A: a circle root of f is
                 * bounded iff dim ker A = e there, which changes only where
                 * the rank of A modulo f drops (two identical oscillators,
                 * one driving the other: a Jordan block except where the
                 * coupling vanishes).  Those polynomials join the full
                 * projection, with the discriminant and the resultants. */
                if (fmpz_cmp_ui(fac->exp + k, 2) >= 0 && !s->from_char && s->n >= 1) {
                    *full = 1;
                    rs_semisimple_rank_drops_mpoly(&drops, &ndrops, s, fac->poly + k);
                }
            }
    } else {
        fmpz_mpoly_set(sqf, v->cp->p, s->zctx);
    }
    fmpz_mpoly_factor_clear(fac, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, sqf, lv, s->zctx);
    rs_hurwitz_init(hown);
    if (fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 1) r = rs_hurwitz_memo_compute(&h, hown, qz, lv, s->zctx, run->err);
    /* a condition that vanishes identically: the per-condition argument
     * (a strictly unstable open set makes some condition negative) fails */
    for (k = 0; r == RS_OK && !*full && fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 1 && k <= h->n; k++)
        if (fmpz_mpoly_is_zero(h->coeffs + k, s->zctx) || (k < h->n && fmpz_mpoly_is_zero(h->minors + k, s->zctx)))
            *full = 1;
    ngr = *full ? 1 : 1 + (h->n + 1) + h->n;
    g = flint_malloc((size_t) ngr * sizeof(rs_plist_t));
    for (k = 0; k < ngr; k++) rs_plist_init(g + k);
    fmpz_mpoly_get_coeff_vars_ui(t, v->cp->p, &lv, &nn, 1, s->zctx);
    rs_plist_add(g, t, tv, dom, s->zctx);
    if (*full && fmpz_mpoly_degree_si(sqf, lv, s->zctx) >= 2 && fmpz_mpoly_discriminant(t, sqf, lv, s->zctx))
        rs_plist_add(g, t, tv, dom, s->zctx);
    for (k = 0; r == RS_OK && fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 1 && k <= h->n; k++)
        rs_plist_add(g + (*full ? 0 : 1 + k), h->coeffs + k, tv, dom, s->zctx);
    for (k = 0; r == RS_OK && fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 1 && k < h->n; k++)
        rs_plist_add(g + (*full ? 0 : 2 + h->n + k), h->minors + k, tv, dom, s->zctx);
    for (k = 0; k < ndrops; k++) {
        rs_plist_add(g, drops + k, tv, dom, s->zctx);
        fmpz_mpoly_clear(drops + k, s->zctx);
    }
    flint_free(drops);
    rs_hurwitz_clear(hown, s->zctx);
    fmpz_mpoly_clear(sqf, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
    *groups = g;
    *ng = ngr;
    return r;
}

int rs_an_forall_critical(fmpz_poly_struct **out, slong *nout, rs_run_t *run, const rs_variant_t *v, slong tv,
                          const slong *qv, slong nq, const rs_bound_t *b, int *full)
{
    const fmpz_mpoly_ctx_struct *ctx = v->s->zctx;
    rs_plist_t *g = NULL, all;
    slong i, k, ng = 0;
    int r;
    r = forall_conditions(&g, &ng, run, v, tv, b, full);
    rs_plist_init(&all);
    for (k = 0; k < ng; k++) {
        rs_plist_t l = g[k], m;
        for (i = 0; i < nq && r == RS_OK; i++) {
            rs_plist_init(&m);
            r = rs_proj_eliminate(&m, run, &l, qv[i], b + qv[i], tv, b, ctx);
            rs_plist_clear(&l, ctx);
            l = m;
        }
        for (i = 0; i < l.n; i++) plist_push(&all, l.p + i, ctx);
        rs_plist_clear(&l, ctx);
    }
    flint_free(g);
    for (i = 0; i < all.n && r == RS_OK; i++) {
        fmpz_poly_t u;
        if (fmpz_mpoly_degree_si(all.p + i, tv, ctx) <= 0) continue;
        fmpz_poly_init(u);
        if (fmpz_mpoly_get_fmpz_poly(u, all.p + i, tv, ctx)) {
            *out = flint_realloc(*out, (size_t) (*nout + 1) * sizeof(fmpz_poly_struct));
            fmpz_poly_init(*out + *nout);
            fmpz_poly_swap(*out + *nout, u);
            (*nout)++;
        }
        fmpz_poly_clear(u);
    }
    rs_plist_clear(&all, ctx);
    return r;
}

int rs_an_forall_lead_nonzero(rs_run_t *run, const rs_variant_t *v, slong tv, const fmpq_t t, const rs_bound_t *b)
{
    const rs_scheme_struct *s = v->s;
    slong lv = s->lambda_var, n;
    fmpz_mpoly_t qz, a, at;
    int ok;
    (void) run;
    fmpz_mpoly_init(qz, s->zctx);
    fmpz_mpoly_init(a, s->zctx);
    fmpz_mpoly_init(at, s->zctx);
    if (factor_memo != NULL && factor_memo->ctx == s->zctx && factor_memo->lead_v == v) {
        fmpz_mpoly_set(a, factor_memo->lead, s->zctx);   /* the same variant: derived once per run */
    } else {
        rs_bilinear_fmpz_mpoly(qz, v->cp->p, lv, s->zctx);
        n = fmpz_mpoly_degree_si(v->cp->p, lv, s->zctx);
        rs_charpoly_coeff(a, qz, n, lv, s->zctx);
        if (factor_memo != NULL && factor_memo->ctx == s->zctx) {
            fmpz_mpoly_set(factor_memo->lead, a, s->zctx);
            factor_memo->lead_v = v;
        }
    }
    rs_an_forall_subst(at, a, tv, t, s->zctx);
    ok = !fmpz_mpoly_is_zero(at, s->zctx) && sign_definite(at, tv, b, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    fmpz_mpoly_clear(a, s->zctx);
    fmpz_mpoly_clear(at, s->zctx);
    return ok;
}

/* The exact verdict at the counterexample, recomputed on another route: the
 * characteristic polynomial derived once per run with only the case's set
 * values substituted (the run's cached variant), every other parameter
 * substituted at the point, Routh and Schur-Cohn counted on it (the
 * search's verdict came from the cell's own variant, derived with NAME
 * substituted first).  It must violate what the search said it violates. */
static int forall_recheck(int *agrees, rs_run_t *run, const json_t *ev)
{
    const json_t *cx = json_object_get(ev, "counterexample");
    const char *said = json_string_value(json_object_get(json_object_get(ev, "at_counterexample"), "status"));
    const char *key;
    json_t *val;
    slong np = run->c->nparams, n = 0, na = 0;
    slong *vars = flint_malloc((np + 1) * sizeof(slong));
    fmpq *vals = _fmpq_vec_init(np + 1);
    rs_assign_t *a = NULL;
    rs_variant_t *v;
    rs_status_t st;
    rs_rootcount_t rc;
    int r, ok = 1;
    json_object_foreach((json_t *) cx, key, val) {
        slong k = rs_case_param_index(run->c, key);
        if (k < 0 || !json_is_string(val) || fmpq_set_str(vals + n, json_string_value(val), 10) != 0) {
            ok = 0;
            break;
        }
        fmpq_canonicalise(vals + n);
        vars[n++] = k;
    }
    rs_run_assignments(run, &a, &na, NULL, 0, NULL, 0);
    r = rs_run_variant(&v, run, a, na);
    *agrees = 0;
    if (r == RS_OK && ok) {
        r = rs_run_point_status(&st, rc, run, v, vars, vals, n);
        if (r == RS_OK) *agrees = said != NULL && strcmp(said, rs_status_name(st)) == 0;
        rs_rootcount_clear(rc);
    }
    rs_assign_free(a, na);
    flint_free(vars);
    _fmpq_vec_clear(vals, np + 1);
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
    rs_bound_t *b = rs_run_bounds(run);
    slong i;
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

/* 1 when the real polynomial c[0..n] (c[n] != 0) has every root strictly
 * inside the unit circle by the Schur-Cohn recursion in double precision:
 * |c_n| > |c_0| and the same for (c_n p - c_0 p*)/lambda.  A guess only
 * (rounding can flip a borderline answer); it never decides a verdict. */
static int schur_double_stable(double *c, double *d, slong n)
{
    slong k;
    while (n > 0) {
        double m = 0;
        if (!(fabs(c[n]) > fabs(c[0]))) return 0;
        for (k = 0; k < n; k++) d[k] = c[n] * c[k + 1] - c[0] * c[n - 1 - k];
        n--;
        for (k = 0; k <= n; k++) m = fmax(m, fabs(d[k]));
        if (!(m > 0) || !isfinite(m)) return 0;
        for (k = 0; k <= n; k++) c[k] = d[k] / m;
    }
    return 1;
}

/* 1 when the scheme looks not stable at tv = t with every other free
 * parameter at one simple admissible value of its interval b (the midpoint,
 * an end plus or minus 1, or 1): the characteristic polynomial derived once
 * per run (the set values substituted) evaluated there, its roots located in
 * double precision.  A cheap guess of the cell's status that only orders the
 * work (search or proof first), never evidence; 0 when the point is not
 * admissible. */
static int forall_probe_bad(rs_run_t *run, slong tv, const fmpq_t t, const rs_bound_t *b)
{
    slong np = run->c->nparams, na = 0, ncps = 0, k;
    rs_assign_t *a = NULL;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpq *pt, **pp;
    rs_condpoly_t *cps;
    int r, bad = 0;
    rs_run_assignments(run, &a, &na, NULL, 0, NULL, 0);
    r = rs_run_variant(&v, run, a, na);
    rs_assign_free(a, na);
    if (r != RS_OK || v->singular || v->s->complex_char) { rs_error_init(run->err); return 0; }
    s = v->s;
    pt = _fmpq_vec_init(s->nvars);
    pp = flint_malloc(s->nvars * sizeof(fmpq *));
    cps = calloc((size_t) run->c->nassume + 1, sizeof(rs_condpoly_t));
    for (k = 0; k < s->nvars; k++) pp[k] = pt + k;
    for (k = 0; k < np && k < s->nvars; k++) {
        const rs_bound_t *bk = b + k;
        if (k == tv) fmpq_set(pt + k, t);
        else if (bk->fixed) fmpq_set(pt + k, bk->lo);
        else if (bk->has_lo && bk->has_hi) { fmpq_add(pt + k, bk->lo, bk->hi); fmpq_div_2exp(pt + k, pt + k, 1); }
        else if (bk->has_lo) fmpq_add_si(pt + k, bk->lo, 1);
        else if (bk->has_hi) fmpq_sub_si(pt + k, bk->hi, 1);
        else fmpq_one(pt + k);
    }
    for (k = 0; r == RS_OK && k < run->c->nassume; k++)
        r = rs_condpoly_compile(cps + ncps++, &run->c->assume[k], s, run->c, run->err);
    if (r == RS_OK && rs_run_point_admissible(cps, ncps, pp, s)) {
        fmpq_poly_t w;
        fmpz_poly_t u;
        fmpq_poly_init(w);
        fmpz_poly_init(u);
        if (rs_run_charpoly_at(w, v, NULL, pt, np < s->nvars ? np : s->nvars)) {
            slong n = fmpq_poly_degree(w);
            if (n < v->cp->degree) {
                bad = 1;                              /* singular there */
            } else {
                double *c = flint_malloc(2 * (n + 1) * sizeof(double));
                fmpq_poly_get_numerator(u, w);
                for (k = 0; k <= n; k++) c[k] = fmpz_get_d(u->coeffs + k);
                bad = !schur_double_stable(c, c + n + 1, n);
                flint_free(c);
            }
        }
        fmpq_poly_clear(w);
        fmpz_poly_clear(u);
    }
    if (r != RS_OK) rs_error_init(run->err);
    for (k = 0; k < ncps; k++) rs_condpoly_clear(cps + k, s);
    free(cps);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    return bad;
}

/* The cell at tv = t: stable for all (a certificate), else a point that is
 * not stable; marginal if bounded is proved, unstable at a counterexample.
 * search_first (1: the caller expects a bad cell, after an unstable one; -1:
 * no guess, the cell probed at one point, forall_probe_bad): the
 * deterministic search for a point that is not stable runs before the proof,
 * which is then not attempted when it finds one (same answer, same evidence;
 * the point is re-checked by forall_recheck as every counterexample is). */
int rs_an_forall_cell(rs_status_t *st, int *decided, json_t **ev, rs_run_t *run, slong tv, const fmpq_t t,
                      int search_first)
{
    slong np = run->c->nparams;
    rs_bound_t *b = forall_bounds(run, tv, t, t);
    json_t *e1 = NULL, *e2 = NULL;
    int vs = 0, vb = 0, agrees = 1, r;
    *decided = 0;
    *ev = NULL;
    if (search_first < 0) search_first = forall_probe_bad(run, tv, t, b);
    r = rs_an_claim_decide(&vs, &e1, run, 0, b, search_first ? 2 : 0);
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
