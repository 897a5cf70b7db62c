/* an_claim.c -- `claim stable|bounded|unstable [when ...]`: proved with a
 * re-checked certificate (positivity of the condition polynomials on the
 * set, Polya multipliers), refuted with an exact counterexample and the
 * exact verdict there, or undecided with what was tried. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <flint/fmpz_poly_factor.h>
#include <flint/fmpz_vec.h>
#include <fmpq_vec.h>
#include <mpfr.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include "analysis/registry.h"
#include "recstab/bilinear.h"
#include "recstab/jury.h"
#include "recstab/positivity.h"
#include "recstab/semisimple.h"
#include "util/polyfmt.h"
#include "analysis/an_region.h"
#include "analysis/an_qd.h"
#include "stability/routh_complex.h"
#include "algebra/mfactor.h"

/* ---- claim ------------------------------------------------------------------- */

static void z2q(fmpq_mpoly_t out, const fmpz_mpoly_t p, const rs_scheme_t s)
{
    slong i, len = fmpz_mpoly_length(p, s->zctx);
    ulong *e = flint_malloc(s->nvars * sizeof(ulong));
    fmpq_t c;
    fmpq_init(c);
    fmpq_mpoly_zero(out, s->ctx);
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_exp_ui(e, p, i, s->zctx);
        fmpz_set(fmpq_numref(c), p->coeffs + i);
        fmpz_one(fmpq_denref(c));
        fmpq_mpoly_push_term_fmpq_ui(out, c, e, s->ctx);
    }
    fmpq_mpoly_sort_terms(out, s->ctx);
    fmpq_mpoly_combine_like_terms(out, s->ctx);
    fmpq_clear(c);
    flint_free(e);
}

/* the substitution that maps s in [0, inf) onto the parameter's interval */
static void subst_poly(fmpq_mpoly_t out, const fmpq_mpoly_t P, slong v, const rs_bound_t *b,
                       const rs_scheme_t s)
{
    slong d = fmpq_mpoly_degree_si(P, v, s->ctx), k;
    fmpq_mpoly_t c, num, one_s, tmp, acc;
    fmpq_mpoly_init(c, s->ctx); fmpq_mpoly_init(num, s->ctx);
    fmpq_mpoly_init(one_s, s->ctx); fmpq_mpoly_init(tmp, s->ctx);
    fmpq_mpoly_init(acc, s->ctx);
    /* num = image of v times (1+s) for two-sided intervals */
    fmpq_mpoly_gen(num, v, s->ctx);
    if (b->has_lo && b->has_hi) {
        fmpq_mpoly_scalar_mul_fmpq(num, num, b->hi, s->ctx);
        fmpq_mpoly_add_fmpq(num, num, b->lo, s->ctx);            /* lo + hi s */
        fmpq_mpoly_gen(one_s, v, s->ctx);
        fmpq_mpoly_add_si(one_s, one_s, 1, s->ctx);              /* 1 + s */
    } else if (b->has_lo) {
        fmpq_mpoly_add_fmpq(num, num, b->lo, s->ctx);            /* lo + s */
        fmpq_mpoly_one(one_s, s->ctx);
    } else {
        fmpq_mpoly_neg(num, num, s->ctx);
        fmpq_mpoly_add_fmpq(num, num, b->hi, s->ctx);            /* hi - s */
        fmpq_mpoly_one(one_s, s->ctx);
    }
    fmpq_mpoly_zero(acc, s->ctx);
    for (k = 0; k <= d; k++) {
        ulong kk = (ulong) k;
        fmpq_mpoly_t pw;
        fmpq_mpoly_get_coeff_vars_ui(c, P, &v, &kk, 1, s->ctx);
        if (fmpq_mpoly_is_zero(c, s->ctx)) continue;
        fmpq_mpoly_init(pw, s->ctx);
        fmpq_mpoly_pow_ui(tmp, num, kk, s->ctx);
        fmpq_mpoly_pow_ui(pw, one_s, (ulong) (d - k), s->ctx);
        fmpq_mpoly_mul(tmp, tmp, pw, s->ctx);
        fmpq_mpoly_mul(tmp, tmp, c, s->ctx);
        fmpq_mpoly_add(acc, acc, tmp, s->ctx);
        fmpq_mpoly_clear(pw, s->ctx);
    }
    fmpq_mpoly_swap(out, acc, s->ctx);
    fmpq_mpoly_clear(c, s->ctx); fmpq_mpoly_clear(num, s->ctx);
    fmpq_mpoly_clear(one_s, s->ctx); fmpq_mpoly_clear(tmp, s->ctx);
    fmpq_mpoly_clear(acc, s->ctx);
}

/* State of one claim proof: the certificate so far, the random state of the
 * independent re-checks, and the first place a certificate failed (said in
 * the report of an undecided claim). */
#define CLAIM_MAX_HINTS 12

typedef struct {
    json_t *cert;
    flint_rand_t st;
    char fail[640];
    size_t fail_progress; /* certificate entries when it failed */
    int inconsistent;     /* two root counts of a one-variable condition disagreed */
    /* values where a one-variable condition is < 0 (rs_positivity_negative_points
     * mapped back from s): candidates for the counterexample search */
    fmpq hint[CLAIM_MAX_HINTS];
    slong hint_var[CLAIM_MAX_HINTS];
    slong nhints;
    /* the failed one-variable numerators, in order, whose negative points
     * become hints only when the hint search runs (cx_hints_resolve): most
     * failed proofs are settled by the plain search first */
    struct claim_pending_hint *pend;
    slong npend;
} claim_cx_t;

typedef struct claim_pending_hint {
    fmpz_poly_t u;          /* the numerator in s_v, made of positive content */
    slong v;
    rs_bound_t bv;          /* v's interval (its ends map s back to v) */
} claim_pending_hint_t;

static void cx_init(claim_cx_t *cx)
{
    slong i;
    memset(cx->fail, 0, sizeof cx->fail);
    cx->fail_progress = 0;
    cx->inconsistent = 0;
    cx->nhints = 0;
    cx->pend = NULL;
    cx->npend = 0;
    for (i = 0; i < CLAIM_MAX_HINTS; i++) fmpq_init(cx->hint + i);
    cx->cert = json_array();
    flint_randinit(cx->st);
}

static void cx_clear(claim_cx_t *cx)
{
    slong i;
    for (i = 0; i < CLAIM_MAX_HINTS; i++) fmpq_clear(cx->hint + i);
    for (i = 0; i < cx->npend; i++) {
        fmpz_poly_clear(cx->pend[i].u);
        fmpq_clear(cx->pend[i].bv.lo);
        fmpq_clear(cx->pend[i].bv.hi);
    }
    free(cx->pend);
    json_decref(cx->cert);
    flint_randclear(cx->st);
}

/* the one-variable numerator P (in s_v) is not positive: where it is < 0,
 * v's values are candidates of the hint search (kept for cx_hints_resolve) */
static void cx_add_hints(claim_cx_t *cx, const fmpq_mpoly_t P, slong v, const rs_bound_t *bv, const rs_scheme_t s)
{
    claim_pending_hint_t *h;
    cx->pend = realloc(cx->pend, (size_t) (cx->npend + 1) * sizeof(claim_pending_hint_t));
    h = cx->pend + cx->npend++;
    fmpz_poly_init(h->u);
    fmpz_mpoly_get_fmpz_poly(h->u, P->zpoly, v, s->ctx->zctx);
    if (fmpq_sgn(P->content) < 0) fmpz_poly_neg(h->u, h->u);
    h->v = v;
    h->bv = *bv;
    fmpq_init(h->bv.lo);
    fmpq_init(h->bv.hi);
    fmpq_set(h->bv.lo, bv->lo);
    fmpq_set(h->bv.hi, bv->hi);
}

/* the pending numerators' negative points (rs_positivity_negative_points on
 * the range s >= 0), mapped back to v, in the order they failed */
static void cx_hints_resolve(claim_cx_t *cx)
{
    fmpq pts[4];
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t z;
    rs_sign_t sg = RS_SIGN_NONNEGATIVE;
    slong n, i, k;
    if (cx->npend == 0) return;
    for (i = 0; i < 4; i++) fmpq_init(pts + i);
    fmpz_mpoly_ctx_init(ctx, 1, ORD_LEX);
    fmpz_mpoly_init(z, ctx);
    for (k = 0; k < cx->npend && cx->nhints < CLAIM_MAX_HINTS; k++) {
        const rs_bound_t *bv = &cx->pend[k].bv;
        fmpz_mpoly_set_fmpz_poly(z, cx->pend[k].u, 0, ctx);
        n = rs_positivity_negative_points(pts, 4, z, &sg, ctx);
        for (i = 0; i < n && cx->nhints < CLAIM_MAX_HINTS; i++) {
            fmpq *h = cx->hint + cx->nhints;
            if (bv->has_lo && bv->has_hi) {              /* (lo + hi s) / (1 + s) */
                fmpq_t t;
                fmpq_init(t);
                fmpq_mul(h, bv->hi, pts + i);
                fmpq_add(h, h, bv->lo);
                fmpq_add_si(t, pts + i, 1);
                fmpq_div(h, h, t);
                fmpq_clear(t);
            } else if (bv->has_lo) {
                fmpq_add(h, bv->lo, pts + i);
            } else {
                fmpq_sub(h, bv->hi, pts + i);
            }
            cx->hint_var[cx->nhints++] = cx->pend[k].v;
        }
    }
    for (k = 0; k < cx->npend; k++) {
        fmpz_poly_clear(cx->pend[k].u);
        fmpq_clear(cx->pend[k].bv.lo);
        fmpq_clear(cx->pend[k].bv.hi);
    }
    cx->npend = 0;
    fmpz_mpoly_clear(z, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    for (i = 0; i < 4; i++) fmpq_clear(pts + i);
}


static void claim_fail(claim_cx_t *cx, const char *what, const fmpq_mpoly_t c, const rs_scheme_t s)
{
    char *cs;
    /* keep the failure of the attempt that got furthest */
    if (cx->fail[0] != '\0' && json_array_size(cx->cert) <= cx->fail_progress) return;
    cx->fail_progress = json_array_size(cx->cert);
    cs = c != NULL ? rs_polyfmt_fmpq_mpoly(c, (const char **) s->vars, s->ctx) : NULL;
    snprintf(cx->fail, sizeof cx->fail, "%s%s%s", cs != NULL ? cs : "", cs != NULL ? ": " : "", what);
    free(cs);
}

/* drop the entries a failed attempt added */
static void cert_truncate(claim_cx_t *cx, size_t n)
{
    while (json_array_size(cx->cert) > n) json_array_remove(cx->cert, json_array_size(cx->cert) - 1);
}

static void cert_note(claim_cx_t *cx, const char *text)
{
    json_array_append_new(cx->cert, json_pack("{s:s}", "text", text));
}

#define CLAIM_POLYA_MAX RS_POLYA_MAX_POWER   /* Polya multipliers tried (positivity.h) */

/* Certifies P > 0 for every s >= 0 (s_v > 0 where strict[v]).  A monomial
 * factor in strictly positive variables is divided out first: a condition
 * that vanishes at an open end of the interval (mapped to s_v = 0) has such
 * a factor, and the rest must be positive up to that end.  Then the one
 * positivity routine of the Hurwitz stage (positivity.c): all coefficients
 * of one sign with a monomial > 0, else Polya's multiplier (sum s_v)^N for a
 * form, (1 + sum s_v)^N otherwise, after each s_v's exponents are divided by
 * their gcd.  *mono is the monomial divided out ("" if none), *polya the N
 * used (0: coefficients alone). */
static int certify_nonneg(fmpq_mpoly_t P, const int *strict, const rs_scheme_t s, char **mono, slong *polya,
                          int *by_roots, int *inconsistent)
{
    fmpq_mpoly_t M;
    slong v;
    ulong *e = flint_malloc(s->nvars * sizeof(ulong));
    rs_sign_t *sg = flint_malloc(s->nvars * sizeof(rs_sign_t));
    int ok, any = 0;
    fmpq_mpoly_init(M, s->ctx);
    *mono = NULL;
    *polya = 0;
    fmpq_mpoly_term_content(M, P, s->ctx);
    if (!fmpq_mpoly_is_zero(M, s->ctx)) {
        fmpq_t one;
        fmpq_init(one);
        fmpq_one(one);
        fmpq_mpoly_get_term_exp_ui(e, M, 0, s->ctx);
        for (v = 0; v < s->nvars; v++) {
            if (!strict[v]) e[v] = 0;
            any |= e[v] > 0;
        }
        if (any) {
            fmpq_mpoly_zero(M, s->ctx);
            fmpq_mpoly_push_term_fmpq_ui(M, one, e, s->ctx);
            fmpq_mpoly_divides(P, P, M, s->ctx);
            *mono = calloc(1, 1);
            for (v = 0; v < s->nvars; v++) {
                size_t len;
                if (e[v] == 0) continue;
                len = strlen(*mono);
                *mono = realloc(*mono, len + strlen(s->vars[v]) + 32);
                sprintf(*mono + len, "%ss_%s", len ? "*" : "", s->vars[v]);
                if (e[v] > 1) sprintf(*mono + strlen(*mono), "^%lu", (unsigned long) e[v]);
            }
        }
        fmpq_clear(one);
    }
    /* P = content * zpoly: the sign of the integer part decides */
    for (v = 0; v < s->nvars; v++) sg[v] = strict[v] ? RS_SIGN_POSITIVE : RS_SIGN_NONNEGATIVE;
    ok = !fmpq_mpoly_is_zero(P, s->ctx)
         && fmpq_sgn(P->content) * rs_positivity_sign(P->zpoly, sg, s->ctx->zctx, polya) > 0;
    if (!ok || *polya < 0) *polya = 0;
    /* one variable left: exact, by its real roots (Polya's exponent for
     * 16 s^2 - 31 s + 16 is far past the cap) */
    *by_roots = 0;
    if (!ok && !fmpq_mpoly_is_zero(P, s->ctx)) {
        int inc = 0;
        ok = fmpq_sgn(P->content) * rs_positivity_sign_roots(P->zpoly, sg, s->ctx->zctx, &inc) > 0;
        *by_roots = ok;
        *inconsistent |= inc;
    }
    fmpq_mpoly_clear(M, s->ctx);
    flint_free(sg);
    flint_free(e);
    return ok;
}

/* Proves c > 0 on the box given by b (vars with no bound make it fail).
 * Appends the certificate to cx->cert.  Returns 1 proved, 0 not. */
static int prove_positive(const fmpq_mpoly_t c, const rs_bound_t *b, const rs_scheme_t s, claim_cx_t *cx,
                          int depth)
{
    fmpq_mpoly_t P;
    int *strict = flint_calloc(s->nvars, sizeof(int));
    json_t *sub = json_object();
    slong v, polya = 0, single = -1;
    int ok = 1, by_roots = 0;
    char buf[512], *mono = NULL;
    if (depth > 8) { flint_free(strict); json_decref(sub); return 0; }
    fmpq_mpoly_init(P, s->ctx);
    fmpq_mpoly_set(P, c, s->ctx);
    for (v = 0; v < s->nvars && ok; v++) {
        char *lo = NULL, *hi = NULL;
        if (v == s->lambda_var || fmpq_mpoly_degree_si(P, v, s->ctx) <= 0) continue;
        if (!b[v].has_lo && !b[v].has_hi) {
            snprintf(buf, sizeof buf, "%s has no bound in the claim or the assumptions", s->vars[v]);
            claim_fail(cx, buf, c, s);
            ok = 0;
            break;
        }
        if (b[v].has_lo) lo = fmpq_get_str(NULL, 10, b[v].lo);
        if (b[v].has_hi) hi = fmpq_get_str(NULL, 10, b[v].hi);
        {
            const char *sv = s->vars[v];
            int lo0 = lo != NULL && strcmp(lo, "0") == 0;
            if (b[v].has_lo && b[v].has_hi) {
                if (lo0) snprintf(buf, sizeof buf, "%s*s_%s/(1 + s_%s)", hi, sv, sv);
                else snprintf(buf, sizeof buf, "(%s + %s*s_%s)/(1 + s_%s)", lo, hi, sv, sv);
                strict[v] = !b[v].lo_closed;
            } else if (b[v].has_lo) {
                if (lo0) snprintf(buf, sizeof buf, "s_%s", sv);
                else snprintf(buf, sizeof buf, "%s + s_%s", lo, sv);
                strict[v] = !b[v].lo_closed;
            } else {
                snprintf(buf, sizeof buf, "%s - s_%s", hi, sv);
                strict[v] = !b[v].hi_closed;
            }
        }
        json_object_set_new(sub, s->vars[v], json_string(buf));
        flint_free(lo);
        flint_free(hi);
        subst_poly(P, P, v, b + v, s);
    }
    if (ok) {
        ok = certify_nonneg(P, strict, s, &mono, &polya, &by_roots, &cx->inconsistent);
        single = rs_positivity_single_var(P->zpoly, s->ctx->zctx);   /* P's one variable, if one */
        if (!ok && single >= 0 && !cx->inconsistent)
            cx_add_hints(cx, P, single, b + single, s);
        if (!ok) {
            snprintf(buf, sizeof buf, "after mapping the interval%s onto s >= 0 a coefficient stays negative "
                     "(monomial factors in s divided out, (1 + sum s)^N tried up to N = %d)%s",
                     json_object_size(sub) > 1 ? "s" : "", CLAIM_POLYA_MAX,
                     cx->inconsistent ? "; the Sturm and Arb root counts of the one-variable numerator disagree"
                     : single >= 0 ? "; the one-variable numerator has a real root there" : "");
            claim_fail(cx, buf, c, s);
        }
    }
    if (ok) {
        json_t *e = json_object();
        char *cs = rs_polyfmt_fmpq_mpoly(c, (const char **) s->vars, s->ctx);
        json_object_set_new(e, "condition", json_string(cs));
        json_object_set_new(e, "substitution", sub);
        json_object_set_new(e, "transformed_terms", json_integer(fmpq_mpoly_length(P, s->ctx)));
        if (by_roots) {
            /* the report prints "text"; the fields stay for JSON readers */
            char *ps = rs_polyfmt_fmpq_mpoly(P, (const char **) s->vars, s->ctx);
            slong sv = single;
            char *txt = malloc(strlen(cs) + strlen(ps) + 2 * strlen(s->vars[sv]) + 400);
            sprintf(txt, "%s > 0 since with %s = %s (%s) the numerator %s has no real root with s_%s %s 0 "
                    "(Sturm sequence, re-counted by certified isolation) and is positive there", cs,
                    s->vars[sv], json_string_value(json_object_get(sub, s->vars[sv])),
                    strict[sv] ? "s > 0" : "every s >= 0", ps, s->vars[sv], strict[sv] ? ">" : ">=");
            json_object_set_new(e, "text", json_string(txt));
            json_object_set_new(e, "no_real_root_on_range", json_true());
            json_object_set_new(e, "root_count", json_string("Sturm (FLINT) and certified isolation (Arb) agree: 0"));
            free(txt);
            free(ps);
        } else {
            json_object_set_new(e, "all_coefficients_nonnegative", json_true());
        }
        if (mono != NULL) json_object_set_new(e, "positive_factor", json_string(mono));
        if (polya > 0) json_object_set_new(e, "polya_power", json_integer(polya));
        json_array_append_new(cx->cert, e);
        free(cs);
        sub = NULL;
        /* a closed upper end of a two-sided interval is s = inf: check it too */
        for (v = 0; v < s->nvars && ok; v++) {
            if (v == s->lambda_var || fmpq_mpoly_degree_si(c, v, s->ctx) <= 0) continue;
            if (b[v].has_lo && b[v].has_hi && b[v].hi_closed) {
                fmpq_mpoly_t cv;
                fmpq_mpoly_init(cv, s->ctx);
                fmpq_mpoly_evaluate_one_fmpq(cv, c, v, b[v].hi, s->ctx);
                if (fmpq_mpoly_is_fmpq(cv, s->ctx)) {
                    fmpq_t k;
                    fmpq_init(k);
                    fmpq_mpoly_get_fmpq(k, cv, s->ctx);
                    ok = fmpq_sgn(k) > 0;
                    fmpq_clear(k);
                    if (!ok) claim_fail(cx, "not positive at the closed upper end", c, s);
                } else {
                    ok = prove_positive(cv, b, s, cx, depth + 1);
                }
                fmpq_mpoly_clear(cv, s->ctx);
            }
        }
    }
    free(mono);
    json_decref(sub);
    flint_free(strict);
    fmpq_mpoly_clear(P, s->ctx);
    return ok;
}
/* Independent re-check of a certificate entry: the transformed polynomial
 * is recomputed here by evaluating c at the image of random positive s
 * and comparing the sign (> 0) -- a separate code path from the symbolic
 * substitution. Returns 1 if every sample is positive. */
static int recheck_positive(const fmpq_mpoly_t c, const rs_bound_t *b, const rs_scheme_t s, flint_rand_t st)
{
    slong k, v;
    int ok = 1;
    fmpq *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc(s->nvars * sizeof(fmpq *));
    fmpq_t sv, val, one;
    fmpq_init(sv); fmpq_init(val); fmpq_init(one);
    fmpq_one(one);
    for (v = 0; v < s->nvars; v++) pp[v] = pt + v;
    for (k = 0; k < 16 && ok; k++) {
        for (v = 0; v < s->nvars; v++) {
            if (v == s->lambda_var) { fmpq_zero(pt + v); continue; }   /* no bounds entry for lambda */
            fmpq_set_si(sv, 1 + (slong) n_randint(st, 1000), 1 + n_randint(st, 50));
            if (b[v].has_lo && b[v].has_hi) {
                fmpq_t t;
                fmpq_init(t);
                fmpq_mul(t, b[v].hi, sv);
                fmpq_add(t, t, b[v].lo);
                fmpq_add(sv, sv, one);
                fmpq_div(pt + v, t, sv);
                fmpq_clear(t);
            } else if (b[v].has_lo) fmpq_add(pt + v, b[v].lo, sv);
            else if (b[v].has_hi) fmpq_sub(pt + v, b[v].hi, sv);
            else fmpq_set(pt + v, sv);
        }
        fmpq_mpoly_evaluate_all_fmpq(val, c, pp, s->ctx);
        if (fmpq_sgn(val) <= 0) ok = 0;
    }
    fmpq_clear(sv); fmpq_clear(val); fmpq_clear(one);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    return ok;
}


/* Proves cz > 0 (sg = 1), cz < 0 (sg = -1) or cz != 0 (sg = 0: either
 * sign) on the box; appends the certificate. */
static int prove_sign(const fmpz_mpoly_t cz, int sg, const rs_bound_t *b, const rs_scheme_t s, claim_cx_t *cx)
{
    fmpq_mpoly_t c;
    int ok = 0, k;
    fmpq_mpoly_init(c, s->ctx);
    z2q(c, cz, s);
    for (k = sg == 0 ? 0 : 1; k < 2 && !ok; k++) {
        if (sg < 0 || (sg == 0 && k == 1)) fmpq_mpoly_neg(c, c, s->ctx);
        if (fmpq_mpoly_is_fmpq(c, s->ctx)) {
            fmpq_t q;
            fmpq_init(q);
            fmpq_mpoly_get_fmpq(q, c, s->ctx);
            ok = sg == 0 ? !fmpq_is_zero(q) : fmpq_sgn(q) > 0;
            fmpq_clear(q);
            if (!ok && (sg != 0 || k == 1)) claim_fail(cx, "a constant of the wrong sign", c, s);
        } else {
            ok = prove_positive(c, b, s, cx, 0) && recheck_positive(c, b, s, cx->st);
        }
        if (sg < 0 || (sg == 0 && k == 1)) fmpq_mpoly_neg(c, c, s->ctx);
    }
    fmpq_mpoly_clear(c, s->ctx);
    return ok;
}

static int prove_nonzero(const fmpz_mpoly_t cz, const rs_bound_t *b, const rs_scheme_t s, claim_cx_t *cx)
{
    return prove_sign(cz, 0, b, s, cx);
}

/* A condition the Hurwitz stage found positive from the signs of its
 * factors alone: its own certificate on the set (a positive constant is
 * stated as such), marked with where it came from. */
static int prove_trivial(const rs_hurwitz_cond_struct *hc, const rs_bound_t *b, const rs_scheme_t s,
                         claim_cx_t *cx)
{
    size_t n0 = json_array_size(cx->cert), k;
    int ok;
    if (fmpz_mpoly_is_fmpz(hc->poly, s->zctx)) {
        char *cs = fmpz_get_str(NULL, 10, hc->poly->coeffs);
        ok = fmpz_mpoly_length(hc->poly, s->zctx) == 1 && fmpz_sgn(hc->poly->coeffs) > 0;
        json_array_append_new(cx->cert, json_pack("{s:s,s:s,s:b}", "condition", cs, "origin", hc->origin,
                                                  "positive_constant", ok));
        flint_free(cs);
        if (!ok) claim_fail(cx, "a condition the sign rule called positive is not a positive constant", NULL, s);
        return ok;
    }
    ok = prove_sign(hc->poly, 1, b, s, cx);
    for (k = n0; ok && k < json_array_size(cx->cert); k++) {
        json_t *e = json_array_get(cx->cert, k);
        json_object_set_new(e, "origin", json_string(hc->origin));
        json_object_set_new(e, "positive_by_factor_signs", json_true());
    }
    return ok;
}

/* Every Lienard-Chipart condition of h or of -h (z = variable zv) positive
 * on the box: h is Hurwitz-stable there.  Both signs are tried because the
 * sign of h's leading coefficient is not fixed by the claim (BDF2 on
 * y' = q y has q(z) = (2q - 8) z^2 + ..., negative for q < 0). */
static int prove_hurwitz_stable(rs_run_t *run, const fmpz_mpoly_t h, const rs_bound_t *b, const rs_scheme_t s,
                                claim_cx_t *cx)
{
    int *sign = rs_run_signs(run, s);
    int ok = 0, sg;
    slong i, k;
    size_t n0 = json_array_size(cx->cert);
    fmpz_mpoly_t hs;
    if (fmpz_mpoly_degree_si(h, s->lambda_var, s->zctx) < 1) {
        flint_free(sign);
        return prove_nonzero(h, b, s, cx);
    }
    fmpz_mpoly_init(hs, s->zctx);
    for (sg = 1; sg >= -1 && !ok; sg -= 2) {
        rs_hurwitz_t hw;
        if (sg > 0) fmpz_mpoly_set(hs, h, s->zctx);
        else fmpz_mpoly_neg(hs, h, s->zctx);
        rs_hurwitz_init(hw);
        ok = 1;
        if (rs_hurwitz_compute(hw, hs, s->lambda_var, (const rs_sign_t *) sign, s->zctx, run->err) != RS_OK) {
            rs_error_init(run->err);
            ok = 0;
        }
        for (i = 0; ok && i < hw->ncond; i++) {
            const rs_hurwitz_cond_struct *hc = hw->cond + i;
            if (hc->trivially_true) {
                /* positive by its factors' signs under the assumptions:
                 * certified on the set like any other, which checks that
                 * sign rule independently (not an empty certificate) */
                ok = prove_trivial(hc, b, s, cx);
                continue;
            }
            if (hc->trivially_false) { ok = 0; break; }
            ok = prove_sign(hc->reduced, 1, b, s, cx);
            for (k = 0; k < hc->factors->num && ok; k++)
                if (!hc->dropped[k] && hc->even[k]) ok = prove_nonzero(hc->factors->poly + k, b, s, cx);
        }
        rs_hurwitz_clear(hw, s->zctx);
        if (!ok) cert_truncate(cx, n0);
    }
    fmpz_mpoly_clear(hs, s->zctx);
    flint_free(sign);
    return ok;
}

/* g (degree dg >= 1 in u, the variable of lambda) has only simple negative
 * roots on the whole box: one sign of its coefficients (and a positive
 * discriminant for dg = 2); for dg > 2 by Hermite-Biehler. */
static int prove_negative_simple(rs_run_t *run, const fmpz_mpoly_t g, const rs_bound_t *b, const rs_scheme_t s,
                                 claim_cx_t *cx)
{
    slong lv = s->lambda_var, i, dg = fmpz_mpoly_degree_si(g, lv, s->zctx);
    ulong *e = flint_malloc(s->nvars * sizeof(ulong));
    fmpz_mpoly_t t;
    int ok = 1;
    fmpz_mpoly_init(t, s->zctx);
    if (dg == 1) {
        fmpz_mpoly_t a1, a0;
        size_t n0 = json_array_size(cx->cert);
        fmpz_mpoly_init(a1, s->zctx); fmpz_mpoly_init(a0, s->zctx);
        rs_charpoly_coeff(a1, g, 1, lv, s->zctx);
        rs_charpoly_coeff(a0, g, 0, lv, s->zctx);
        /* root u = -a0/a1 < 0: a0, a1 of one sign */
        ok = prove_sign(a1, 1, b, s, cx) && prove_sign(a0, 1, b, s, cx);
        if (!ok) {
            cert_truncate(cx, n0);
            ok = prove_sign(a1, -1, b, s, cx) && prove_sign(a0, -1, b, s, cx);
        }
        fmpz_mpoly_clear(a1, s->zctx); fmpz_mpoly_clear(a0, s->zctx);
    } else if (dg == 2) {
        fmpz_mpoly_t a2, a1, a0, d;
        size_t n0 = json_array_size(cx->cert);
        fmpz_mpoly_init(a2, s->zctx); fmpz_mpoly_init(a1, s->zctx);
        fmpz_mpoly_init(a0, s->zctx); fmpz_mpoly_init(d, s->zctx);
        rs_charpoly_coeff(a2, g, 2, lv, s->zctx);
        rs_charpoly_coeff(a1, g, 1, lv, s->zctx);
        rs_charpoly_coeff(a0, g, 0, lv, s->zctx);
        /* two simple negative roots in u: one sign for a2, a1, a0 and a1^2 - 4 a2 a0 > 0 */
        fmpz_mpoly_mul(d, a1, a1, s->zctx);
        fmpz_mpoly_mul(t, a2, a0, s->zctx);
        fmpz_mpoly_scalar_mul_si(t, t, 4, s->zctx);
        fmpz_mpoly_sub(d, d, t, s->zctx);
        ok = prove_sign(a2, 1, b, s, cx) && prove_sign(a1, 1, b, s, cx) && prove_sign(a0, 1, b, s, cx);
        if (!ok) {
            cert_truncate(cx, n0);
            ok = prove_sign(a2, -1, b, s, cx) && prove_sign(a1, -1, b, s, cx) && prove_sign(a0, -1, b, s, cx);
        }
        ok = ok && prove_sign(d, 1, b, s, cx);
        fmpz_mpoly_clear(a2, s->zctx); fmpz_mpoly_clear(a1, s->zctx);
        fmpz_mpoly_clear(a0, s->zctx); fmpz_mpoly_clear(d, s->zctx);
    } else {
        /* g has only simple negative roots iff P(z) = g(z^2) + z g'(z^2) is
         * Hurwitz-stable (Hermite-Biehler: the roots of g and g' are real,
         * negative, simple and interlace, as Rolle gives for g') */
        fmpz_mpoly_t P, gd;
        slong n = fmpz_mpoly_length(g, s->zctx);
        fmpz_mpoly_init(P, s->zctx);
        fmpz_mpoly_init(gd, s->zctx);
        fmpz_mpoly_derivative(gd, g, lv, s->zctx);
        for (i = 0; i < n; i++) {                           /* g(z^2) */
            fmpz_mpoly_get_term_exp_ui(e, g, i, s->zctx);
            e[lv] *= 2;
            fmpz_mpoly_push_term_fmpz_ui(P, g->coeffs + i, e, s->zctx);
        }
        n = fmpz_mpoly_length(gd, s->zctx);
        for (i = 0; i < n; i++) {                           /* z g'(z^2) */
            fmpz_mpoly_get_term_exp_ui(e, gd, i, s->zctx);
            e[lv] = 2 * e[lv] + 1;
            fmpz_mpoly_push_term_fmpz_ui(P, gd->coeffs + i, e, s->zctx);
        }
        fmpz_mpoly_sort_terms(P, s->zctx);
        fmpz_mpoly_combine_like_terms(P, s->zctx);
        cert_note(cx, "G = z^k g(z^2): g has simple negative roots because g(z^2) + z g'(z^2) is "
                      "Hurwitz-stable (Hermite-Biehler)");
        ok = prove_hurwitz_stable(run, P, b, s, cx);
        fmpz_mpoly_clear(P, s->zctx);
        fmpz_mpoly_clear(gd, s->zctx);
    }
    fmpz_mpoly_clear(t, s->zctx);
    flint_free(e);
    return ok;
}

/* Bounded (stable or marginal) on the whole box: q = G H with
 * G = gcd(q(z), q(-z)) (the roots symmetric about the origin, among them
 * every root on the imaginary axis), H Hurwitz-stable, and G = z^k g(z^2)
 * with k <= 1 and g of degree <= 2 in u = z^2 having simple negative roots
 * (so G's roots are simple and on the axis). */
static int prove_bounded(rs_run_t *run, const fmpz_mpoly_t p, const rs_scheme_t s, const rs_bound_t *b,
                         claim_cx_t *cx)
{
    slong lv = s->lambda_var, i, len, k = 0, dg;
    fmpz_mpoly_t q, qm, G, H, g, t, R;
    ulong *e = flint_malloc(s->nvars * sizeof(ulong));
    int ok = 1, split_m1 = 0;
    fmpz_t m1;
    fmpz_mpoly_init(q, s->zctx); fmpz_mpoly_init(qm, s->zctx);
    fmpz_mpoly_init(G, s->zctx); fmpz_mpoly_init(H, s->zctx);
    fmpz_mpoly_init(g, s->zctx); fmpz_mpoly_init(t, s->zctx);
    fmpz_mpoly_init(R, s->zctx);
    fmpz_init_set_si(m1, -1);
    /* lambda = -1 a root for every value (q(z) loses degree): simple in p, so
     * p = (lambda + 1) R with R(-1) != 0 on the set */
    fmpz_mpoly_set(R, p, s->zctx);
    fmpz_mpoly_evaluate_one_fmpz(t, R, lv, m1, s->zctx);
    if (fmpz_mpoly_is_zero(t, s->zctx)) {
        split_m1 = 1;
        fmpz_mpoly_gen(t, lv, s->zctx);
        fmpz_mpoly_add_si(t, t, 1, s->zctx);
        fmpz_mpoly_divides(R, R, t, s->zctx);
        fmpz_mpoly_evaluate_one_fmpz(t, R, lv, m1, s->zctx);
        ok = !fmpz_mpoly_is_zero(t, s->zctx) && prove_nonzero(t, b, s, cx);
        if (!ok) claim_fail(cx, "lambda = -1 is a repeated root for every value", NULL, s);
    }
    rs_bilinear_fmpz_mpoly(q, R, lv, s->zctx);
    if (ok && fmpz_mpoly_degree_si(q, lv, s->zctx) != fmpz_mpoly_degree_si(R, lv, s->zctx)) ok = 0;
    /* q(-z) */
    len = fmpz_mpoly_length(q, s->zctx);
    for (i = 0; ok && i < len; i++) {
        fmpz_t c;
        fmpz_init(c);
        fmpz_mpoly_get_term_exp_ui(e, q, i, s->zctx);
        fmpz_set(c, q->coeffs + i);
        if (e[lv] & 1) fmpz_neg(c, c);
        fmpz_mpoly_push_term_fmpz_ui(qm, c, e, s->zctx);
        fmpz_clear(c);
    }
    fmpz_mpoly_sort_terms(qm, s->zctx);
    if (ok && !fmpz_mpoly_gcd(G, q, qm, s->zctx)) ok = 0;
    /* nothing on the axis: use `stable`, unless lambda = -1 was split off
     * above (a simple root on the circle for every value, the rest stable:
     * marginal) */
    if (ok && fmpz_mpoly_degree_si(G, lv, s->zctx) < 1 && split_m1) {
        cert_note(cx, "p = (lambda + 1) R, R(-1) != 0 on the set: lambda = -1 is a simple circle root for every "
                      "value; bounded because R is stable there:");
        ok = prove_hurwitz_stable(run, q, b, s, cx);
        goto done;
    }
    if (ok && fmpz_mpoly_degree_si(G, lv, s->zctx) < 1) ok = 0;
    if (ok) ok = fmpz_mpoly_divides(H, q, G, s->zctx);
    if (ok) ok = prove_hurwitz_stable(run, H, b, s, cx);
    if (ok) {
        /* G = z^k G1, G1 even */
        k = rs_scheme_min_degree(G, lv, s->zctx);
        len = fmpz_mpoly_length(G, s->zctx);
        if (k > 1) ok = 0;                                          /* repeated lambda = 1 */
        for (i = 0; ok && i < len; i++) {
            fmpz_mpoly_get_term_exp_ui(e, G, i, s->zctx);
            if (((slong) e[lv] - k) & 1) ok = 0;
            e[lv] = (e[lv] - (ulong) k) / 2;
            fmpz_mpoly_push_term_fmpz_ui(g, G->coeffs + i, e, s->zctx);
        }
        fmpz_mpoly_sort_terms(g, s->zctx);
        fmpz_mpoly_combine_like_terms(g, s->zctx);
    }
    dg = fmpz_mpoly_degree_si(g, lv, s->zctx);
    if (ok && k == 1) {                                             /* simple root at lambda = 1 */
        fmpz_t zero;
        fmpz_init(zero);
        fmpz_mpoly_evaluate_one_fmpz(t, g, lv, zero, s->zctx);
        ok = prove_nonzero(t, b, s, cx);
        fmpz_clear(zero);
    }
    if (ok && dg >= 1) ok = prove_negative_simple(run, g, b, s, cx);
done:
    fmpz_mpoly_clear(q, s->zctx); fmpz_mpoly_clear(qm, s->zctx);
    fmpz_mpoly_clear(G, s->zctx); fmpz_mpoly_clear(H, s->zctx);
    fmpz_mpoly_clear(g, s->zctx); fmpz_mpoly_clear(t, s->zctx);
    fmpz_mpoly_clear(R, s->zctx);
    fmpz_clear(m1);
    flint_free(e);
    return ok;
}

/* Bounded for a system whose det p has repeated factors: when every repeated
 * factor f^e has dim ker A = e over Q(params)[lambda]/(f)
 * (rs_semisimple_generic), prove the squarefree part bounded (circle roots
 * simple at every point of the set, so the roots of distinct factors stay
 * apart and each circle root of f has multiplicity e in det) and the
 * lambda-free factors non-zero.  At a point the rank of A modulo f can only
 * drop, so dim ker >= e, and dim ker <= multiplicity = e: semisimple. */
static int prove_bounded_system(rs_run_t *run, const rs_variant_t *v, const rs_bound_t *b, claim_cx_t *cx)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_factor_t fac;
    fmpz_mpoly_t sqf, cont;
    slong k;
    int ok = 0, all = 0, repeated = 0;
    if (s->from_char) return 0;
    fmpz_mpoly_factor_init(fac, s->zctx);
    fmpz_mpoly_init(sqf, s->zctx);
    fmpz_mpoly_init(cont, s->zctx);
    fmpz_mpoly_one(sqf, s->zctx);
    fmpz_mpoly_one(cont, s->zctx);
    if (fmpz_mpoly_factor(fac, v->cp->p, s->zctx)) {
        for (k = 0; k < fac->num; k++) {
            if (fmpz_mpoly_degree_si(fac->poly + k, s->lambda_var, s->zctx) > 0) {
                fmpz_mpoly_mul(sqf, sqf, fac->poly + k, s->zctx);
                repeated |= fmpz_cmp_ui(fac->exp + k, 1) > 0;
            } else {
                fmpz_mpoly_mul(cont, cont, fac->poly + k, s->zctx);
            }
        }
        if (repeated && rs_semisimple_generic(&all, s, v->cp->p) != RS_OK) {
            rs_error_init(run->err);
            all = 0;
        }
        if (repeated && !all) claim_fail(cx, "a repeated factor of det A is not semisimple over Q(params)", NULL, s);
        if (repeated && all) {
            cert_note(cx, "every repeated factor f^e of det A has dim ker A = e over Q(params)[lambda]/(f) "
                          "(semisimple): bounded where the squarefree part is, with simple circle roots");
            ok = prove_bounded(run, sqf, s, b, cx) && prove_nonzero(cont, b, s, cx);
        }
    }
    fmpz_mpoly_factor_clear(fac, s->zctx);
    fmpz_mpoly_clear(sqf, s->zctx);
    fmpz_mpoly_clear(cont, s->zctx);
    return ok;
}

typedef enum { CLAIM_STABLE, CLAIM_BOUNDED, CLAIM_UNSTABLE } claim_kind_t;

/* A singular point (the step cannot be solved) violates every kind of claim. */
static int violates(claim_kind_t k, rs_status_t st)
{
    if (st == RS_STATUS_SINGULAR) return 1;
    switch (k) {
    case CLAIM_STABLE: return st != RS_STATUS_STABLE;
    case CLAIM_BOUNDED: return st == RS_STATUS_UNSTABLE;
    case CLAIM_UNSTABLE: return st != RS_STATUS_UNSTABLE;
    }
    return 0;
}

/* The variant with every parameter the bounds fix (`set` values and claim
 * conditions NAME = VALUE) substituted, so that the proof works on the
 * polynomial of that subset (its factors, gcds and degree). */
/* a parameter with a complex set value (the claim runs over Q(i) there) */
static int param_is_cset(const rs_run_t *run, slong k)
{
    slong i;
    for (i = 0; i < run->c->ncsets; i++)
        if (strcmp(run->c->csets[i].name, run->c->params[k].name) == 0) return 1;
    return 0;
}

static int claim_variant(rs_variant_t **v, rs_run_t *run, const rs_bound_t *b)
{
    slong i, n = 0, na;
    rs_assign_t *extra = calloc((size_t) run->c->nparams + 1, sizeof(rs_assign_t)), *a;
    int r;
    for (i = 0; i < run->c->nparams; i++)
        if (b[i].fixed && !param_is_cset(run, i)) {   /* a complex value stays for rs_run_cx_poly */
            extra[n].name = run->c->params[i].name;
            extra[n].var = i;
            fmpq_init(extra[n].value);
            fmpq_set(extra[n].value, b[i].lo);
            n++;
        }
    rs_run_assignments(run, &a, &na, NULL, 0, extra, n);
    r = rs_run_variant(v, run, a, na);
    rs_assign_free(a, na);
    rs_assign_free(extra, n);
    return r;
}

static void bounds_copy(rs_bound_t *dst, const rs_bound_t *src, slong n)
{
    slong i;
    for (i = 0; i < n; i++) {
        dst[i].has_lo = src[i].has_lo; dst[i].has_hi = src[i].has_hi;
        dst[i].lo_closed = src[i].lo_closed; dst[i].hi_closed = src[i].hi_closed;
        dst[i].fixed = src[i].fixed;
        fmpq_set(dst[i].lo, src[i].lo);
        fmpq_set(dst[i].hi, src[i].hi);
    }
}

/* Rational values of variable i inside b (ends when closed) where p(1),
 * p(-1) or p's leading coefficient vanishes, as polynomials in i alone:
 * where roots reach lambda = +-1 or the step becomes singular.  Appended to
 * c[*n ..] up to cap. */
static void special_candidates(fmpq *c, slong *n, slong cap, const rs_variant_t *v, slong i, const rs_bound_t *b)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t e;
    fmpz_poly_t u;
    fmpz_poly_factor_t f;
    fmpz_t pm;
    fmpq_t r;
    slong k, w;
    fmpz_mpoly_init(e, s->zctx);
    fmpz_poly_init(u);
    fmpz_init(pm);
    fmpq_init(r);
    for (w = 0; w < 3; w++) {
        if (w < 2) {
            fmpz_set_si(pm, w == 0 ? 1 : -1);
            fmpz_mpoly_evaluate_one_fmpz(e, v->cp->p, s->lambda_var, pm, s->zctx);
        } else {
            rs_charpoly_coeff(e, v->cp->p, v->cp->degree, s->lambda_var, s->zctx);
        }
        if (fmpz_mpoly_is_zero(e, s->zctx) || !fmpz_mpoly_get_fmpz_poly(u, e, i, s->zctx)) continue;
        fmpz_poly_factor_init(f);
        fmpz_poly_factor(f, u);
        for (k = 0; k < f->num && *n < cap; k++) {
            if (fmpz_poly_degree(f->p + k) != 1) continue;
            fmpz_neg(fmpq_numref(r), f->p[k].coeffs);
            fmpz_set(fmpq_denref(r), f->p[k].coeffs + 1);
            fmpq_canonicalise(r);
            if (rs_bound_contains(b + i, r)) fmpq_set(c + (*n)++, r);
        }
        fmpz_poly_factor_clear(f);
    }
    fmpz_mpoly_clear(e, s->zctx);
    fmpz_poly_clear(u);
    fmpz_clear(pm);
    fmpq_clear(r);
}

static int param_is_set(const rs_run_t *run, slong k)
{
    slong i;
    for (i = 0; i < run->c->nsets; i++)
        if (strcmp(run->c->sets[i].name, run->c->params[k].name) == 0) return 1;
    return param_is_cset(run, k);
}

/* every Bilharz condition of p over Q(i)[real params] (rs_routh_cx_conds)
 * proved positive on the box: every root inside the unit circle there */
static int cx_bilharz_proof(rs_run_t *run, const rs_variant_t *v, const rs_bound_t *b, claim_cx_t *cx)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t re, im;
    rs_routh_cx_conds_t bc;
    slong n, k;
    int ok = 1;
    size_t n0 = json_array_size(cx->cert);
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    rs_routh_cx_conds_init(&bc, s->zctx);
    n = rs_run_cx_poly(re, im, run, v);
    if (n < 1 || (!s->complex_char && n < v->cp->degree) || v->singular
        || !rs_routh_cx_conds(&bc, re, im, s->lambda_var, s->zctx, RS_CHARPOLY_MAX_TERMS) || bc.ncond < n + 1) {
        claim_fail(cx, "p over Q(i) has no Bilharz conditions here (degree drop, a condition identically zero, or "
                   "too large)", NULL, NULL);
        ok = 0;
    } else {
        cert_note(cx, "p over Q(i) at the complex set values; every root inside iff each Bilharz condition of its "
                  "bilinear image is > 0 (hurwitz over Q(i)):");
        for (k = 0; k < bc.ncond && ok; k++) ok = prove_sign(bc.cond + k, 1, b, s, cx);
    }
    if (!ok) cert_truncate(cx, n0);
    rs_routh_cx_conds_clear(&bc, s->zctx);
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    return ok;
}

/* `claim unstable` over Q(i) with any number of real parameters: the
 * product of p's root moduli is |a0|/|an|, so |a0|^2 - |an|^2 > 0 on the box
 * puts a root outside the unit circle; |an|^2 > 0 keeps the step solvable */
static int cx_norm_unstable(rs_run_t *run, const rs_variant_t *v, const rs_bound_t *b, claim_cx_t *cx)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t re, im, t, u, c0, cn;
    slong n;
    int ok = 0;
    size_t n0 = json_array_size(cx->cert);
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx); fmpz_mpoly_init(t, s->zctx);
    fmpz_mpoly_init(u, s->zctx); fmpz_mpoly_init(c0, s->zctx); fmpz_mpoly_init(cn, s->zctx);
    n = rs_run_cx_poly(re, im, run, v);
    if (n >= 1 && !v->singular && (s->complex_char || n >= v->cp->degree)) {
        ulong e0 = 0, en = (ulong) n;
        slong lv = s->lambda_var;
        /* |a0|^2 and |an|^2 */
        fmpz_mpoly_get_coeff_vars_ui(t, re, &lv, &e0, 1, s->zctx);
        fmpz_mpoly_get_coeff_vars_ui(u, im, &lv, &e0, 1, s->zctx);
        fmpz_mpoly_mul(c0, t, t, s->zctx);
        fmpz_mpoly_mul(u, u, u, s->zctx);
        fmpz_mpoly_add(c0, c0, u, s->zctx);
        fmpz_mpoly_get_coeff_vars_ui(t, re, &lv, &en, 1, s->zctx);
        fmpz_mpoly_get_coeff_vars_ui(u, im, &lv, &en, 1, s->zctx);
        fmpz_mpoly_mul(cn, t, t, s->zctx);
        fmpz_mpoly_mul(u, u, u, s->zctx);
        fmpz_mpoly_add(cn, cn, u, s->zctx);
        cert_note(cx, "p over Q(i) at the complex set values: |a0|^2 > |an|^2 (the product of the root moduli "
                  "|a0/an| > 1, so a root lies outside the unit circle) and |an|^2 > 0 (the step is solvable):");
        fmpz_mpoly_sub(t, c0, cn, s->zctx);
        ok = prove_sign(t, 1, b, s, cx) && prove_sign(cn, 1, b, s, cx);
    } else {
        claim_fail(cx, "p over Q(i) drops degree here", NULL, NULL);
    }
    if (!ok) cert_truncate(cx, n0);
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx); fmpz_mpoly_clear(t, s->zctx);
    fmpz_mpoly_clear(u, s->zctx); fmpz_mpoly_clear(c0, s->zctx); fmpz_mpoly_clear(cn, s->zctx);
    (void) run;
    return ok;
}

/* A claim at complex set values with at most one real parameter t left in
 * p over Q(i): the exact point verdict, or the exact region of t on the set
 * (rs_an_region_cx_on: cells cut at the real roots of |p|^2's critical
 * polynomials, each decided at a rational sample by complex Schur-Cohn and
 * Bilharz and again by the real gcd route, irrational critical values over
 * Q(t0)); proved when every cell satisfies the claim. */
static int claim_prove_complex_region(rs_run_t *run, claim_kind_t kind, const rs_variant_t *v, const rs_bound_t *b,
                                      claim_cx_t *cx)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t re, im;
    slong k, tv = -1, nfree = 0;
    int ok = 0;
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    rs_run_cx_poly(re, im, run, v);
    for (k = 0; k < s->nvars; k++)
        if (k != s->lambda_var
            && (fmpz_mpoly_degree_si(re, k, s->zctx) > 0 || fmpz_mpoly_degree_si(im, k, s->zctx) > 0)) {
            tv = k;
            nfree++;
        }
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    if (nfree > 1) {
        /* no exact region in several real parameters over Q(i): a certificate on the whole box, else undecided */
        if (kind == CLAIM_BOUNDED && cx_bilharz_proof(run, v, b, cx)) {
            cert_note(cx, "every point stable, so bounded");
            ok = 1;
        } else if (kind == CLAIM_UNSTABLE) ok = cx_norm_unstable(run, v, b, cx);
        if (!ok)
            claim_fail(cx, kind == CLAIM_UNSTABLE
                       ? "over Q(i) with several real parameters free, `claim unstable` is proved by |a0|^2 > |an|^2 "
                         "on the set (a root outside); that sign was not proved here, and the exact region is of one "
                         "real parameter only"
                       : "over Q(i) with several real parameters free, `claim bounded` is proved by the Bilharz "
                         "conditions (every point stable); they were not proved positive on the set (e.g. marginal "
                         "points in it), and the exact region is of one real parameter only", NULL, NULL);
    } else if (nfree == 0) {
        rs_rootcount_t rc;
        rs_status_t st;
        if (rs_run_point_status(&st, rc, run, v, NULL, NULL, 0) == RS_OK) {
            char msg[200];
            ok = !violates(kind, st);
            snprintf(msg, sizeof msg, "p over Q(i) with every parameter fixed here: %s (the exact Q(i) verdict)",
                     rs_status_name(st));
            if (ok) cert_note(cx, msg);
            else claim_fail(cx, msg, NULL, NULL);
        } else {
            rs_error_init(run->err);
        }
        rs_rootcount_clear(rc);
    } else {
        json_t *o = NULL;
        int r = rs_an_region_cx_on(&o, run, v, tv, b + tv);
        if (r != RS_OK) {
            if (r == RS_ERR_INCONSISTENT) run->outcome |= RS_OUTCOME_INCONSISTENT;
            claim_fail(cx, run->err->msg, NULL, NULL);
            rs_error_init(run->err);
        } else {
            const json_t *ivs = json_object_get(o, "intervals"), *iv;
            size_t i;
            char msg[600];
            ok = json_array_size(ivs) > 0 && json_array_size(json_object_get(o, "undecided_points")) == 0;
            json_array_foreach(ivs, i, iv) {
                const char *stn = json_string_value(json_object_get(iv, "status"));
                if (stn == NULL || (kind == CLAIM_BOUNDED && strcmp(stn, "stable") != 0 && strcmp(stn, "marginal") != 0)
                    || (kind == CLAIM_UNSTABLE && strcmp(stn, "unstable") != 0)
                    || (kind == CLAIM_STABLE && strcmp(stn, "stable") != 0))
                    ok = 0;
            }
            snprintf(msg, sizeof msg, "p over Q(i) with only %s left: its exact region on the set, cells cut at the "
                     "real roots of the critical polynomials of |p|^2 (leading coefficient, lambda = +-1, D_{n-1} of "
                     "the bilinear image, discriminant), each cell decided at a rational sample by complex "
                     "Schur-Cohn and Bilharz and again by the real route gcd(Re p, Im p) |p/gcd|^2 (%lld samples), "
                     "irrational critical values over Q(t0): every cell %s", s->vars[tv],
                     (long long) json_integer_value(json_object_get(o, "cross_checked_samples")),
                     kind == CLAIM_UNSTABLE ? "unstable" : kind == CLAIM_STABLE ? "stable" : "stable or marginal");
            if (ok) json_array_append_new(cx->cert, json_pack("{s:s,s:O}", "text", msg, "region", ivs));
            else claim_fail(cx, "the exact region over Q(i) has a cell that violates the claim", NULL, NULL);
        }
        json_decref(o);
    }
    return ok;
}

/* `claim stable` at complex set values: every Bilharz condition of p over
 * Q(i)[real params] (rs_routh_cx_conds) proved positive on the box, else
 * (and for bounded and unstable) the exact region of the one real parameter
 * left (claim_prove_complex_region) */
static int claim_prove_complex(rs_run_t *run, claim_kind_t kind, const rs_variant_t *v, const rs_bound_t *b,
                               claim_cx_t *cx)
{
    int ok;
    size_t n0 = json_array_size(cx->cert);
    if (kind != CLAIM_STABLE) return claim_prove_complex_region(run, kind, v, b, cx);
    ok = cx_bilharz_proof(run, v, b, cx);
    if (!ok) {
        ok = claim_prove_complex_region(run, kind, v, b, cx);
        if (!ok) cert_truncate(cx, n0);
    }
    return ok;
}

/* One certificate on the box, no subdivision. */
static int claim_prove_direct(rs_run_t *run, claim_kind_t kind, const rs_variant_t *v, const rs_bound_t *b,
                              claim_cx_t *cx)
{
    const rs_scheme_struct *s = v->s;
    slong lv = s->lambda_var, k;
    fmpz_mpoly_t qz, t;
    int ok = 0;
    size_t n0 = json_array_size(cx->cert);
    fmpz_mpoly_init(qz, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, lv, s->zctx);
    if (v->singular) {
        claim_fail(cx, "the leading coefficient of det A(lambda) vanishes here (singular step)", NULL, s);
    } else if (rs_run_count_free(v->cp->p, s, lv) == 0) {
        /* every parameter fixed on this part: the exact verdict is the certificate */
        rs_rootcount_t rc;
        rs_status_t stt;
        if (rs_run_point_status(&stt, rc, run, v, NULL, NULL, 0) == RS_OK) {
            char msg[300], pt[200] = "";
            const char *key;
            json_t *val;
            ok = !violates(kind, stt);
            json_object_foreach(v->assigned, key, val)
                if (!param_is_set(run, rs_case_param_index(run->c, key)))
                    snprintf(pt + strlen(pt), sizeof pt - strlen(pt), "%s%s = %s", pt[0] ? ", " : "", key,
                             json_string_value(val));
            /* every parameter set (or none declared): no point to name */
            snprintf(msg, sizeof msg, "%s%s%s%s (the exact point verdict)", pt[0] ? "at " : "", pt,
                     pt[0] ? ": " : "", rs_status_name(stt));
            if (ok) cert_note(cx, msg);
            else claim_fail(cx, msg, NULL, s);
        } else {
            rs_error_init(run->err);
        }
        rs_rootcount_clear(rc);
    } else if (kind != CLAIM_UNSTABLE) {
        /* a degree drop of q(z) for every parameter value is a root at lambda = -1
         * on the whole set: never stable */
        if (fmpz_mpoly_degree_si(qz, lv, s->zctx) == v->cp->degree)
            ok = prove_hurwitz_stable(run, qz, b, s, cx);
        else
            claim_fail(cx, "q(z) has lower degree than p for every value (a root at lambda = -1)", NULL, s);
        if (!ok && kind == CLAIM_BOUNDED) {
            cert_truncate(cx, n0);
            ok = prove_bounded(run, v->cp->p, s, b, cx);
            if (!ok) {
                cert_truncate(cx, n0);
                ok = prove_bounded_system(run, v, b, cx);
            }
        }
    } else {
        /* unstable: q has a coefficient of sign opposite to its leading one
         * (a root with Re z > 0, |lambda| > 1), and the step can be solved
         * (p's leading coefficient != 0: else the root may be lambda = inf) */
        fmpq_mpoly_t an, ak;
        slong n = fmpz_mpoly_degree_si(qz, lv, s->zctx);
        fmpq_mpoly_init(an, s->ctx);
        fmpq_mpoly_init(ak, s->ctx);
        rs_charpoly_coeff(t, qz, n, lv, s->zctx);
        z2q(an, t, s);
        for (k = 0; k < n && !ok; k++) {
            int sg;
            for (sg = 1; sg >= -1 && !ok; sg -= 2) {
                rs_charpoly_coeff(t, qz, k, lv, s->zctx);
                z2q(ak, t, s);
                if (sg > 0) fmpq_mpoly_neg(ak, ak, s->ctx);
                else fmpq_mpoly_neg(an, an, s->ctx);
                ok = prove_positive(an, b, s, cx, 0) && prove_positive(ak, b, s, cx, 0)
                     && recheck_positive(an, b, s, cx->st) && recheck_positive(ak, b, s, cx->st);
                if (sg < 0) fmpq_mpoly_neg(an, an, s->ctx);
                if (!ok) cert_truncate(cx, n0);
            }
        }
        if (ok) {
            rs_charpoly_coeff(t, v->cp->p, v->cp->degree, lv, s->zctx);
            ok = prove_nonzero(t, b, s, cx);
        }
        fmpq_mpoly_clear(an, s->ctx);
        fmpq_mpoly_clear(ak, s->ctx);
    }
    if (!ok) cert_truncate(cx, n0);
    fmpz_mpoly_clear(qz, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
    return ok;
}

#define CLAIM_SPLIT_DEPTH 2

/* A rational value strictly inside b where p(1) or p(-1) vanishes as a
 * polynomial in variable i alone (a root at lambda = 1 or -1 appears there:
 * typically an isolated marginal point inside a stable interval).  Returns 1
 * and sets r if there is one. */
static int claim_inner_split(fmpq_t r, const rs_variant_t *v, slong i, const rs_bound_t *b)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t e;
    fmpz_poly_t u;
    fmpz_poly_factor_t f;
    fmpz_t pm;
    slong k, sg;
    int found = 0;
    fmpz_mpoly_init(e, s->zctx);
    fmpz_poly_init(u);
    fmpz_init(pm);
    for (sg = 1; sg >= -1 && !found; sg -= 2) {
        fmpz_set_si(pm, sg);
        fmpz_mpoly_evaluate_one_fmpz(e, v->cp->p, s->lambda_var, pm, s->zctx);
        if (fmpz_mpoly_is_zero(e, s->zctx) || !fmpz_mpoly_get_fmpz_poly(u, e, i, s->zctx)) continue;
        fmpz_poly_factor_init(f);
        fmpz_poly_factor(f, u);
        for (k = 0; k < f->num && !found; k++) {
            if (fmpz_poly_degree(f->p + k) != 1) continue;
            fmpz_neg(fmpq_numref(r), f->p[k].coeffs);
            fmpz_set(fmpq_denref(r), f->p[k].coeffs + 1);
            fmpq_canonicalise(r);
            found = (!b[i].has_lo || fmpq_cmp(r, b[i].lo) > 0) && (!b[i].has_hi || fmpq_cmp(r, b[i].hi) < 0);
        }
        fmpz_poly_factor_clear(f);
    }
    fmpz_mpoly_clear(e, s->zctx);
    fmpz_poly_clear(u);
    fmpz_clear(pm);
    return found;
}

/* A certificate on the box, else the box split at a closed end of an
 * interval: the end point substituted (the polynomial there may factor
 * differently, e.g. HHT-alpha at alpha = 0 is the trapezoidal rule, marginal)
 * and the rest with that end open.  Both parts must be proved. */
static int claim_prove(rs_run_t *run, claim_kind_t kind, const rs_bound_t *b, claim_cx_t *cx, int depth,
                       int *split)
{
    rs_variant_t *v;
    slong i, np = run->c->nparams;
    int ok, side;
    size_t n0 = json_array_size(cx->cert);
    if (rs_budget_exceeded()) return 0;   /* rs_an_claim reports it */
    if (claim_variant(&v, run, b) != RS_OK) {
        rs_error_init(run->err);
        claim_fail(cx, "the characteristic polynomial could not be formed on this part", NULL, NULL);
        return 0;
    }
    if (run->c->ncsets > 0) return claim_prove_complex(run, kind, v, b, cx);
    ok = claim_prove_direct(run, kind, v, b, cx);
    for (i = 0; i < np && !ok && depth < CLAIM_SPLIT_DEPTH; i++) {
        if (b[i].fixed || fmpz_mpoly_degree_si(v->cp->p, i, v->s->zctx) <= 0) continue;
        for (side = 0; side < 2 && !ok; side++) {
            rs_bound_t *bo, *bf;
            char msg[256], *val;
            if (side == 0 ? !(b[i].has_lo && b[i].lo_closed) : !(b[i].has_hi && b[i].hi_closed)) continue;
            bo = flint_malloc(np * sizeof(rs_bound_t));
            bf = flint_malloc(np * sizeof(rs_bound_t));
            rs_bounds_init(bo, np);
            rs_bounds_init(bf, np);
            bounds_copy(bo, b, np);
            bounds_copy(bf, b, np);
            if (side == 0) bo[i].lo_closed = 0; else bo[i].hi_closed = 0;
            fmpq_set(bf[i].lo, side == 0 ? b[i].lo : b[i].hi);
            fmpq_set(bf[i].hi, bf[i].lo);
            bf[i].has_lo = bf[i].has_hi = bf[i].lo_closed = bf[i].hi_closed = bf[i].fixed = 1;
            val = fmpq_get_str(NULL, 10, bf[i].lo);
            snprintf(msg, sizeof msg, "split: %s = %s on its own (substituted), the rest with that end open",
                     run->c->params[i].name, val);
            flint_free(val);
            cert_note(cx, msg);
            ok = !rs_bound_empty(bo + i) && claim_prove(run, kind, bo, cx, depth + 1, split)
                 && claim_prove(run, kind, bf, cx, depth + 1, split);
            if (ok) *split = 1;
            else cert_truncate(cx, n0);
            rs_bounds_clear(bo, np);
            rs_bounds_clear(bf, np);
            flint_free(bo);
            flint_free(bf);
        }
    }
    /* else split at an inner point where lambda = +-1 becomes a root */
    for (i = 0; i < np && !ok && depth < CLAIM_SPLIT_DEPTH; i++) {
        rs_bound_t *bl, *br, *bf;
        fmpq_t rv;
        char msg[256], *val;
        if (b[i].fixed || fmpz_mpoly_degree_si(v->cp->p, i, v->s->zctx) <= 0) continue;
        fmpq_init(rv);
        if (!claim_inner_split(rv, v, i, b)) { fmpq_clear(rv); continue; }
        bl = flint_malloc(np * sizeof(rs_bound_t));
        br = flint_malloc(np * sizeof(rs_bound_t));
        bf = flint_malloc(np * sizeof(rs_bound_t));
        rs_bounds_init(bl, np); rs_bounds_init(br, np); rs_bounds_init(bf, np);
        bounds_copy(bl, b, np); bounds_copy(br, b, np); bounds_copy(bf, b, np);
        fmpq_set(bl[i].hi, rv); bl[i].has_hi = 1; bl[i].hi_closed = 0;
        fmpq_set(br[i].lo, rv); br[i].has_lo = 1; br[i].lo_closed = 0;
        fmpq_set(bf[i].lo, rv); fmpq_set(bf[i].hi, rv);
        bf[i].has_lo = bf[i].has_hi = bf[i].lo_closed = bf[i].hi_closed = bf[i].fixed = 1;
        val = fmpq_get_str(NULL, 10, rv);
        snprintf(msg, sizeof msg, "split: %s = %s (lambda = 1 or -1 a root there) on its own, below and above it",
                 run->c->params[i].name, val);
        flint_free(val);
        cert_note(cx, msg);
        ok = claim_prove(run, kind, bl, cx, depth + 1, split) && claim_prove(run, kind, bf, cx, depth + 1, split)
             && claim_prove(run, kind, br, cx, depth + 1, split);
        if (ok) *split = 1;
        else cert_truncate(cx, n0);
        rs_bounds_clear(bl, np); rs_bounds_clear(br, np); rs_bounds_clear(bf, np);
        flint_free(bl); flint_free(br); flint_free(bf);
        fmpq_clear(rv);
    }
    return ok;
}

/* candidate values of a parameter inside its bounds, simplest first */
static slong candidates(fmpq **out, const rs_bound_t *b)
{
    static const slong num[] = {1, 1, 1, 1, 1, 2, 5, 10, 100, 1000, 3, 1};
    static const slong den[] = {1000, 100, 10, 2, 1, 1, 1, 1, 1, 1, 2, 3};
    slong n = 0, i, cap = 40;
    fmpq *c = _fmpq_vec_init(cap);
    fmpq_t w, t;
    fmpq_init(w); fmpq_init(t);
    if (b->fixed) {
        fmpq_set(c + n++, b->lo);
    } else if (b->has_lo && b->has_hi) {
        fmpq_sub(w, b->hi, b->lo);
        if (b->lo_closed) fmpq_set(c + n++, b->lo);
        if (b->hi_closed) fmpq_set(c + n++, b->hi);
        for (i = 1; i < 8; i++) {
            fmpq_mul_si(t, w, i);
            fmpq_div_2exp(t, t, 3);
            fmpq_add(c + n++, b->lo, t);
        }
        {
            fmpz_t k;
            fmpz_init_set_ui(k, 1000);
            fmpq_div_fmpz(t, w, k);
            fmpz_clear(k);
        }
        fmpq_add(c + n++, b->lo, t);
        fmpq_sub(c + n++, b->hi, t);
    } else {
        if (b->has_lo && b->lo_closed) fmpq_set(c + n++, b->lo);
        if (b->has_hi && b->hi_closed) fmpq_set(c + n++, b->hi);
        for (i = 0; i < 12; i++) {
            fmpq_set_si(t, num[i], (ulong) den[i]);
            if (b->has_lo) fmpq_add(c + n++, b->lo, t);
            else if (b->has_hi) fmpq_sub(c + n++, b->hi, t);
            else { fmpq_set(c + n++, t); fmpq_neg(c + n++, t); }
        }
        if (!b->has_lo && !b->has_hi) fmpq_zero(c + n++);
    }
    fmpq_clear(w); fmpq_clear(t);
    *out = c;
    return n;
}

#define CLAIM_MAX_POINTS 2000

/* A claim's condition in disjunctive normal form: parts joined by `or`,
 * each a list of conditions joined by `and` or ','. */
typedef struct {
    slong nparts;
    slong *n;             /* conditions per part */
    rs_cond_t **conds;
} claim_dnf_t;

static void claim_dnf_clear(claim_dnf_t *d)
{
    slong i, j;
    for (i = 0; i < d->nparts; i++) {
        for (j = 0; j < d->n[i]; j++) rs_cond_clear(d->conds[i] + j);
        free(d->conds[i]);
    }
    free(d->conds);
    free(d->n);
    memset(d, 0, sizeof *d);
}

static int word_at(const char *t, const char *w)
{
    size_t n = strlen(w);
    return strncmp(t, w, n) == 0 && (t[n] == ' ' || t[n] == '\t' || t[n] == '\0');
}

static int claim_dnf_parse(claim_dnf_t *d, rs_run_t *run, const rs_request_t *q, const char *t)
{
    rs_src_t src;
    size_t pos;
    int r = RS_OK;
    memset(d, 0, sizeof *d);
    rs_req_src(&src, q);
    pos = (size_t) (t - q->text);
    d->nparts = 1;
    d->n = calloc(1, sizeof(slong));
    d->conds = calloc(1, sizeof(rs_cond_t *));
    for (;;) {
        rs_cond_t cd;
        slong p = d->nparts - 1;
        r = rs_cond_parse(&cd, &src, &pos, run->err);
        if (r != RS_OK) break;
        d->conds[p] = realloc(d->conds[p], (size_t) (d->n[p] + 1) * sizeof(rs_cond_t));
        d->conds[p][d->n[p]++] = cd;
        while (q->text[pos] == ' ' || q->text[pos] == '\t') pos++;
        if (q->text[pos] == '\0') break;
        if (word_at(q->text + pos, "and")) { pos += 3; continue; }
        if (q->text[pos] == ',') { pos++; continue; }
        if (word_at(q->text + pos, "or")) {
            pos += 2;
            d->n = realloc(d->n, (size_t) (d->nparts + 1) * sizeof(slong));
            d->conds = realloc(d->conds, (size_t) (d->nparts + 1) * sizeof(rs_cond_t *));
            d->n[d->nparts] = 0;
            d->conds[d->nparts++] = NULL;
            continue;
        }
        r = rs_req_error(run, q, q->text + pos, RS_ERR_INPUT,
                         "expected 'and', 'or', ',' or end of line after a condition, found '%s'", q->text + pos);
        break;
    }
    if (r != RS_OK) claim_dnf_clear(d);
    return r;
}

/* Bounds of one part: assumptions, the part's conditions, set values. */
static void claim_bounds(rs_bound_t *b, rs_run_t *run, const rs_cond_t *conds, slong n)
{
    slong i;
    rs_bounds_init(b, run->c->nparams);
    for (i = 0; i < run->c->nassume; i++) rs_bounds_add(b, &run->c->assume[i], run->c, run->err);
    for (i = 0; i < n; i++) rs_bounds_add(b, conds + i, run->c, run->err);
    for (i = 0; i < run->c->nsets; i++) {
        slong k = rs_case_param_index(run->c, run->c->sets[i].name);
        b[k].has_lo = b[k].has_hi = b[k].lo_closed = b[k].hi_closed = b[k].fixed = 1;
        fmpq_set(b[k].lo, run->c->sets[i].value);
        fmpq_set(b[k].hi, run->c->sets[i].value);
    }
    /* a complex set value: fixed (no search over it; 0 is a placeholder, the
     * value itself is substituted over Q(i) by rs_run_cx_poly) */
    for (i = 0; i < run->c->ncsets; i++) {
        slong k = rs_case_param_index(run->c, run->c->csets[i].name);
        b[k].has_lo = b[k].has_hi = b[k].lo_closed = b[k].hi_closed = b[k].fixed = 1;
        fmpq_zero(b[k].lo);
        fmpq_zero(b[k].hi);
    }
}

/* 1 when the characteristic polynomial at the point has every root strictly
 * inside the unit circle (rs_jury_all_inside): the point is stable, so no
 * counterexample to a stable or bounded claim, and needs no exact verdict
 * (a small part of its cost).  0 when not, when the step is singular there,
 * or over Q(i): the exact verdict decides. */
static int point_surely_stable(const rs_run_t *run, const rs_variant_t *v, const slong *vars,
                               const fmpq *pt, slong n)
{
    fmpq_poly_t w;
    slong d;
    int ok = 0;
    if (run->c->ncsets > 0 || v->singular || v->s->complex_char) return 0;
    fmpq_poly_init(w);
    if (rs_run_charpoly_at(w, v, vars, pt, n) && (d = fmpq_poly_degree(w)) == v->cp->degree && d > 0)
        ok = rs_jury_all_inside(w->coeffs, d);
    fmpq_poly_clear(w);
    return ok;
}

/* Searches one part for a counterexample, exactly, on a deterministic set of
 * points.  On success *counter is {NAME: value} and *at the verdict there.
 * det_only: nothing is searched (*skipped = 1) when the points would be drawn
 * from st (too many candidates): a search made before the proof must not
 * change the random state the proof's re-checks use. */
static int claim_search(rs_run_t *run, claim_kind_t kind, const rs_bound_t *b, const rs_cond_t *conds,
                        slong nconds, flint_rand_t st, slong *ntried, json_t **counter, json_t **at,
                        int det_only, int *skipped, const claim_cx_t *hx)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    slong nparams = run->c->nparams, i, j, ncps = 0, ncand_total = 1;
    rs_condpoly_t *cps;
    fmpq **cand, *pt, **pp;
    slong *ncand, *vars;
    int r = claim_variant(&v, run, b);
    if (r != RS_OK) return r;
    s = v->s;
    cps = calloc((size_t) (run->c->nassume + nconds + 1), sizeof(rs_condpoly_t));
    for (i = 0; i < run->c->nassume && r == RS_OK; i++)
        r = rs_condpoly_compile(cps + ncps++, &run->c->assume[i], s, run->c, run->err);
    for (i = 0; i < nconds && r == RS_OK; i++)
        r = rs_condpoly_compile(cps + ncps++, conds + i, s, run->c, run->err);
    cand = calloc((size_t) nparams + 1, sizeof(fmpq *));
    ncand = calloc((size_t) nparams + 1, sizeof(slong));
    for (i = 0; i < nparams; i++) {
        ncand[i] = candidates(cand + i, b + i);
        if (!b[i].fixed) special_candidates(cand[i], ncand + i, 40, v, i, b);
        /* hints: the proof's one-variable conditions are < 0 there; first,
         * so that the deterministic enumeration reaches them */
        for (j = 0; hx != NULL && !b[i].fixed && j < hx->nhints && ncand[i] < 40; j++)
            if (hx->hint_var[j] == i && rs_bound_contains(b + i, hx->hint + j)) {
                fmpq_swap(cand[i] + ncand[i], cand[i]);
                fmpq_set(cand[i], hx->hint + j);
                ncand[i]++;
            }
        if (ncand_total < CLAIM_MAX_POINTS) ncand_total *= ncand[i] > 0 ? ncand[i] : 1;
    }
    pt = _fmpq_vec_init(s->nvars);
    pp = flint_malloc(s->nvars * sizeof(fmpq *));
    for (i = 0; i < s->nvars; i++) pp[i] = pt + i;
    vars = flint_malloc((nparams + 1) * sizeof(slong));
    for (i = 0; i < nparams; i++) vars[i] = i;
    if (skipped != NULL) *skipped = det_only && ncand_total >= CLAIM_MAX_POINTS;
    for (j = 0; r == RS_OK && !(det_only && ncand_total >= CLAIM_MAX_POINTS) && *counter == NULL && j < CLAIM_MAX_POINTS && j < ncand_total; j++) {
        slong k, rem = j;
        int ok = 1;
        if ((r = rs_budget_check(run->err, "the claim's search for a counterexample")) != RS_OK) break;
        for (k = 0; k < nparams; k++) {
            slong pick;
            if (ncand[k] == 0) { ok = 0; break; }
            if (ncand_total < CLAIM_MAX_POINTS) { pick = rem % ncand[k]; rem /= ncand[k]; }
            else pick = j < 1 ? 0 : (slong) n_randint(st, (ulong) ncand[k]);
            fmpq_set(pt + k, cand[k] + pick);
        }
        if (!ok) break;
        if (!rs_run_point_admissible(cps, ncps, pp, s)) continue;
        /* a point certified stable is no counterexample (counted as checked) */
        if (kind != CLAIM_UNSTABLE && point_surely_stable(run, v, vars, pt, nparams)) {
            (*ntried)++;
            continue;
        }
        {
            rs_rootcount_t rc;
            rs_status_t stp;
            (*ntried)++;
            /* system-aware, and "singular" where the step cannot be solved */
            r = rs_run_point_status(&stp, rc, run, v, vars, pt, nparams);
            if (r == RS_OK && stp == RS_STATUS_SINGULAR) {
                *at = json_pack("{s:s,s:s}", "status", rs_status_name(stp), "reason",
                                "the leading coefficient of det A(lambda) vanishes: the implicit step cannot "
                                "be solved");
            } else if (r == RS_OK && violates(kind, stp)) {
                *at = json_object();
                rs_json_add_count(*at, rc);
                json_object_set_new(*at, "status", json_string(rs_status_name(stp)));
            }
            rs_rootcount_clear(rc);
        }
        if (*at != NULL) {
            *counter = json_object();
            for (k = 0; k < nparams; k++)
                if (!param_is_set(run, k))
                    json_object_set_new(*counter, run->c->params[k].name, rs_json_fmpq(pt + k));
            json_object_set_new(*at, "decided_by", json_string("exact"));
        }
    }
    flint_free(vars);
    for (i = 0; i < nparams; i++) _fmpq_vec_clear(cand[i], 40);
    free(cand);
    free(ncand);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    for (i = 0; i < ncps; i++) rs_condpoly_clear(cps + i, s);
    free(cps);
    return r;
}

/* The parameter a one-part claim constrains by an interval: every comparison
 * NAME op CONST (not !=) on the same unset NAME; -1 otherwise. */
static slong claim_single_param(rs_run_t *run, const claim_dnf_t *d)
{
    slong tv = -1, j, k;
    rs_src_t src;
    memset(&src, 0, sizeof src);
    src.file = run->c->path;
    if (d->nparts != 1 || d->n[0] == 0) return -1;
    for (j = 0; j < d->n[0]; j++) {
        const rs_cond_t *cd = d->conds[0] + j;
        for (k = 0; k + 1 < cd->n; k++) {
            const rs_expr_t *l = cd->e[k], *rr = cd->e[k + 1], *nm = NULL, *cst = NULL;
            slong p;
            fmpq_t x;
            rs_error_t scratch;
            int ok;
            if (l->kind == RS_EXPR_NAME && !l->shifted) { nm = l; cst = rr; }
            else if (rr->kind == RS_EXPR_NAME && !rr->shifted) { nm = rr; cst = l; }
            if (nm == NULL || cd->op[k] == RS_CMP_NE) return -1;
            p = rs_case_param_index(run->c, nm->name);
            if (p < 0 || param_is_set(run, p) || (tv >= 0 && p != tv)) return -1;
            fmpq_init(x);
            rs_error_init(scratch);
            ok = rs_expr_eval_const(x, cst, &src, scratch) == RS_OK;
            fmpq_clear(x);
            if (!ok) return -1;
            tv = p;
        }
    }
    return tv;
}

/* 1 when e names the parameter name (a call's own name is a function) */
static int expr_mentions(const rs_expr_t *e, const char *name)
{
    if (e == NULL) return 0;
    if (e->kind == RS_EXPR_NAME && strcmp(e->name, name) == 0) return 1;
    return expr_mentions(e->a, name) || expr_mentions(e->b, name);
}

/* The parameter every comparison of cd bounds by a constant (NAME op CONST,
 * not !=, the same unset NAME); -1 otherwise. */
static slong cond_simple_param(rs_run_t *run, const rs_cond_t *cd)
{
    claim_dnf_t one;
    slong n = 1;
    rs_cond_t *c1 = (rs_cond_t *) cd;
    one.nparts = 1;
    one.n = &n;
    one.conds = &c1;
    return claim_single_param(run, &one);
}

static int region_good(claim_kind_t kind, const char *st)
{
    return st != NULL && (strcmp(st, "stable") == 0 || (kind == CLAIM_BOUNDED && strcmp(st, "marginal") == 0));
}

/* an interval end as text: "p/q", or ~approx for an algebraic one */
static void end_text(char *buf, size_t n, const json_t *iv, const char *key, const char *approx)
{
    const json_t *e = json_object_get(iv, key);
    if (json_is_string(e)) snprintf(buf, n, "%s", json_string_value(e));
    else if (json_is_null(e) || e == NULL) snprintf(buf, n, "%s", strcmp(key, "lo") == 0 ? "-inf" : "inf");
    else snprintf(buf, n, "~%.6g", json_real_value(json_object_get(iv, approx)));
}

static void interval_text(char *buf, size_t n, const json_t *iv)
{
    char lo[96], hi[96];
    end_text(lo, sizeof lo, iv, "lo", "lo_approx");
    end_text(hi, sizeof hi, iv, "hi", "hi_approx");
    if (json_is_true(json_object_get(iv, "lo_closed")) && json_is_true(json_object_get(iv, "hi_closed"))
        && strcmp(lo, hi) == 0)
        snprintf(buf, n, "{%s}", lo);
    else
        snprintf(buf, n, "%s%s, %s%s", json_is_true(json_object_get(iv, "lo_closed")) ? "[" : "(", lo, hi,
                 json_is_true(json_object_get(iv, "hi_closed")) ? "]" : ")");
}

/* length of an interval for "largest" (infinite ends: infinite) */
static double interval_length(const json_t *iv)
{
    const json_t *lo = json_object_get(iv, "lo_approx"), *hi = json_object_get(iv, "hi_approx");
    if (!json_is_number(lo) || !json_is_number(hi)) return HUGE_VAL;
    return json_number_value(hi) - json_number_value(lo);
}

/* An angle parameter's value in a counterexample is t = tan(NAME/2): say
 * which angle that is, exactly when it is a rational multiple of pi (for
 * rational t only t = 0, 1, -1: Niven), else as 2*atan(t).  NULL when the
 * counterexample has no angle parameter. */
static json_t *angle_note(rs_run_t *run, const json_t *cx)
{
    const char *key;
    json_t *val;
    char buf[600];
    size_t used = 0;
    buf[0] = '\0';
    json_object_foreach((json_t *) cx, key, val) {
        slong k = rs_case_param_index(run->c, key);
        const char *t = json_string_value(val), *exact = NULL;
        if (k < 0 || !run->c->params[k].angle || t == NULL) continue;
        if (strcmp(t, "0") == 0) exact = "0";
        else if (strcmp(t, "1") == 0) exact = "pi/2";
        else if (strcmp(t, "-1") == 0) exact = "-pi/2";
        used += (size_t) snprintf(buf + used, sizeof buf - used, "%s%s = 2*atan(%s)%s%s (t = tan(%s/2) = %s)",
                                  used > 0 ? "; " : "", key, t, exact ? " = " : "", exact ? exact : "", key, t);
        if (used >= sizeof buf) break;
    }
    return used > 0 ? json_string(buf) : NULL;
}

/* A claim its own certificate search left undecided, proved by the for-all
 * region of its single parameter on its set (issue 15): every cell of the
 * region good, each with a re-checked certificate (or an exact point
 * verdict for a rational point cell); the cells are uniform because no
 * critical value of the projection lies inside one.  1 when o was made
 * "proved" with the cells' certificates as its own. */
static int region_proof(rs_run_t *run, slong tv, claim_kind_t kind, const json_t *regs, json_t *o)
{
    const json_t *ivs, *iv, *e, *reg;
    json_t *cert = json_array();
    size_t i, k, j, p, nivs = 0;
    char buf[600], one[400];
    json_array_foreach(regs, p, reg) {      /* one region per part of the claim's set */
    ivs = json_object_get(reg, "intervals");
    nivs += json_array_size(ivs);
    snprintf(buf, sizeof buf, "by the for-all region of %s on the claim's set (%s projection, %lld critical "
             "values in the set; no cell contains one, so each is uniform and decided at one sample):", run->c->params[tv].name,
             json_string_value(json_object_get(reg, "projection")) ? json_string_value(json_object_get(reg, "projection")) : "the",
             (long long) json_integer_value(json_object_get(reg, "critical_values")));
    json_array_append_new(cert, json_pack("{s:s}", "text", buf));
    json_array_foreach(ivs, i, iv) {
        const char *ivst = json_string_value(json_object_get(iv, "status"));
        if (!region_good(kind, ivst)) { json_decref(cert); return 0; }
        json_array_foreach(json_object_get(iv, "evidence"), k, e) {
            const json_t *c = json_object_get(e, "certificate");
            const char *smp = json_string_value(json_object_get(e, "sample"));
            const char *cell = json_string_value(json_object_get(e, "cell"));
            if (json_array_size(c) == 0 || !json_is_true(json_object_get(e, "certificate_rechecked"))) {
                json_decref(cert);
                return 0;
            }
            interval_text(one, sizeof one, iv);
            snprintf(buf, sizeof buf, "%s %s in %s, sample %s = %s: %s for every value of the others, certificate:",
                     cell ? cell : "cell", run->c->params[tv].name, one, run->c->params[tv].name,
                     smp ? smp : "?", ivst);
            json_array_append_new(cert, json_pack("{s:s}", "text", buf));
            json_array_foreach(c, j, e) json_array_append(cert, (json_t *) e);
        }
    }
    }
    if (nivs == 0) { json_decref(cert); return 0; }   /* no cell: nothing proved */
    json_object_set_new(o, "status", json_string("proved"));
    json_object_set_new(o, "proved_by", json_string("region for all"));
    json_object_set_new(o, "certificate", cert);
    json_object_set_new(o, "certificate_rechecked", json_true());
    if (json_object_get(o, "failed_at") != NULL) {
        json_object_set(o, "direct_failed_at", json_object_get(o, "failed_at"));
        json_object_del(o, "failed_at");
    }
    return 1;
}

/* The for-all region of the claim's parameter on the claim's interval (issue
 * 13): cross-checks the claim's verdict (proved iff every interval is stable,
 * resp. stable or marginal) and explains a claim not proved: the intervals
 * that are not, with their counterexamples, and the largest proved one. */
/* The for-all region of tv on one part's interval, the part's conditions
 * without tv restricting the quantified parameters (added to the assume
 * lines while the region runs: its projection, proofs and counterexample
 * search all read them there). *reg NULL: an empty interval. */
static int claim_part_region(json_t **reg, rs_run_t *run, const rs_request_t *q, slong tv, const rs_cond_t *conds,
                             slong n)
{
    rs_case_struct *cm = (rs_case_struct *) run->c;   /* restored below */
    rs_cond_t *keep = cm->assume, *all;
    slong nkeep = cm->nassume, nparams = run->c->nparams, k, ne = 0;
    rs_bound_t *b = flint_malloc((nparams + 1) * sizeof(rs_bound_t));
    int r;
    *reg = NULL;
    claim_bounds(b, run, conds, n);
    all = malloc((size_t) (nkeep + n + 1) * sizeof(rs_cond_t));
    if (nkeep > 0) memcpy(all, keep, (size_t) nkeep * sizeof(rs_cond_t));
    for (k = 0; k < n; k++)
        if (cond_simple_param(run, conds + k) != tv) all[nkeep + ne++] = conds[k];   /* shallow: not freed */
    cm->assume = all;
    cm->nassume = nkeep + ne;
    r = rs_bound_empty(b + tv) ? RS_OK : rs_an_region_forall_on(reg, run, q, tv, b + tv);
    cm->assume = keep;
    cm->nassume = nkeep;
    free(all);
    rs_bounds_clear(b, nparams);
    flint_free(b);
    return r;
}

/* An undecided claim whose for-all region has a failing interval: that
 * interval's cell sample (a rational point) refutes it when, re-checked here,
 * the point satisfies the assumptions and a part of the claim's condition and
 * the exact point verdict violates the claim (the search's points can miss a
 * thin failing interval between an algebraic end and a rational bound).
 * 1 when refuted (status, counterexample and verdict put into o). */
static int claim_refute_from_region(rs_run_t *run, claim_kind_t kind, const claim_dnf_t *d, const json_t *failing,
                                    json_t *o)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    slong np = run->c->nparams, i, k, part;
    size_t fi;
    const json_t *f;
    int done = 0;
    if (rs_run_default_variant(run, &v) != RS_OK) { rs_error_init(run->err); return 0; }
    s = v->s;
    json_array_foreach(failing, fi, f) {
        const json_t *cx = json_object_get(f, "counterexample"), *val;
        const char *key;
        fmpq *pt, **pp, *vals;
        slong *vars, nv = 0;
        int ok = 1, inside = 0, r;
        if (done || !json_is_object(cx)) continue;
        pt = _fmpq_vec_init(s->nvars);
        vals = _fmpq_vec_init(np + 1);
        pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
        vars = flint_malloc((size_t) (np + 1) * sizeof(slong));
        for (i = 0; i < s->nvars; i++) pp[i] = pt + i;
        for (i = 0; i < run->c->nsets; i++) {
            k = rs_case_param_index(run->c, run->c->sets[i].name);
            if (k >= 0 && k < s->nvars) fmpq_set(pt + k, run->c->sets[i].value);
        }
        json_object_foreach((json_t *) cx, key, val) {
            k = rs_case_param_index(run->c, key);
            if (k < 0 || k >= s->nvars || param_is_set(run, k) || !json_is_string(val)
                || fmpq_set_str(pt + k, json_string_value(val), 10) != 0) { ok = 0; break; }
            fmpq_canonicalise(pt + k);
            vars[nv] = k;
            fmpq_set(vals + nv++, pt + k);
        }
        /* the assumptions and one part of the claim's condition hold there */
        for (part = 0; ok && part < d->nparts && !inside; part++) {
            rs_condpoly_t *cps = calloc((size_t) (run->c->nassume + d->n[part] + 1), sizeof(rs_condpoly_t));
            slong ncps = 0;
            r = RS_OK;
            for (i = 0; i < run->c->nassume && r == RS_OK; i++)
                if ((r = rs_condpoly_compile(cps + ncps, &run->c->assume[i], s, run->c, run->err)) == RS_OK) ncps++;
            for (i = 0; i < d->n[part] && r == RS_OK; i++)
                if ((r = rs_condpoly_compile(cps + ncps, d->conds[part] + i, s, run->c, run->err)) == RS_OK) ncps++;
            if (r == RS_OK) inside = rs_run_point_admissible(cps, ncps, pp, s);
            else rs_error_init(run->err);
            for (i = 0; i < ncps; i++) rs_condpoly_clear(cps + i, s);
            free(cps);
        }
        if (ok && inside) {
            rs_rootcount_t rc;
            rs_status_t st;
            rs_rootcount_init(rc);
            r = rs_run_point_status(&st, rc, run, v, vars, vals, nv);
            if (r == RS_OK && violates(kind, st)) {
                json_t *at = json_object();
                if (st != RS_STATUS_SINGULAR) rs_json_add_count(at, rc);
                json_object_set_new(at, "status", json_string(rs_status_name(st)));
                json_object_set_new(at, "decided_by", json_string("exact"));
                json_object_set_new(o, "status", json_string("refuted"));
                json_object_set(o, "counterexample", (json_t *) cx);
                json_object_set_new(o, "at_counterexample", at);
                json_object_set_new(o, "found_by", json_string(
                    "the for-all region: a failing interval's cell sample, re-checked (the assumptions and the "
                    "claim's condition hold there, the exact point verdict violates the claim)"));
                json_object_del(o, "failed_at");
                run->outcome |= RS_OUTCOME_FAILED;
                done = 1;
            } else if (r != RS_OK) {
                rs_error_init(run->err);
            }
            rs_rootcount_clear(rc);
        }
        _fmpq_vec_clear(pt, s->nvars);
        _fmpq_vec_clear(vals, np + 1);
        flint_free(pp);
        flint_free(vars);
    }
    return done;
}

/* An undecided claim over exactly two free parameters whose condition ties
 * them together (no for-all region): the plane's decomposition (the CAD of
 * `region N1, N2`) cut also by each part's comparisons, and every cell that
 * is not stable offers its rational sample as a counterexample, re-checked
 * exactly by claim_refute_from_region (the search's points can miss a thin
 * failing sliver).  1 when refuted. */
static int claim_refute_from_cad(rs_run_t *run, claim_kind_t kind, const claim_dnf_t *d, json_t *o)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    slong k, part, i, j, fv[2], nfree = 0;
    int done = 0;
    if (run->c->ncsets > 0 || rs_run_default_variant(run, &v) != RS_OK) { rs_error_init(run->err); return 0; }
    s = v->s;
    for (k = 0; k < run->c->nparams && k < s->nvars; k++)
        if (!param_is_set(run, k) && fmpz_mpoly_degree_si(v->cp->p, k, s->zctx) > 0) {
            if (nfree < 2) fv[nfree] = k;
            nfree++;
        }
    if (nfree != 2 || s->complex_char) return 0;
    for (part = 0; part < d->nparts && !done; part++) {
        fmpz_mpoly_struct *dom = flint_malloc((size_t) (2 * d->n[part] + 1) * sizeof(fmpz_mpoly_struct));
        int *closed = flint_malloc((size_t) (2 * d->n[part] + 1) * sizeof(int));
        slong ndom = 0;
        json_t *cells = NULL, *failing, *e;
        size_t ci;
        for (i = 0; i < d->n[part]; i++) {
            rs_condpoly_t cp;
            if (rs_condpoly_compile(&cp, d->conds[part] + i, s, run->c, run->err) != RS_OK) {
                rs_error_init(run->err);
                continue;
            }
            for (j = 0; j < cp.n; j++) {
                rs_cmp_t op = cp.op[j];
                int sg, other = 0;
                if (!fmpq_mpoly_is_fmpq(cp.den + j, s->ctx) || fmpq_mpoly_is_zero(cp.num + j, s->ctx)
                    || !(op == RS_CMP_LT || op == RS_CMP_LE || op == RS_CMP_GT || op == RS_CMP_GE))
                    continue;     /* not a side of the domain: the re-check still applies it */
                for (k = 0; k < s->nvars; k++)
                    if (k != fv[0] && k != fv[1] && fmpq_mpoly_degree_si(cp.num + j, k, s->ctx) > 0) other = 1;
                if (other) continue;
                /* lhs - rhs op 0 as g > 0 (>= 0), g an integer polynomial */
                sg = fmpq_sgn(cp.num[j].content) * fmpq_sgn(cp.den[j].content);
                if (op == RS_CMP_LT || op == RS_CMP_LE) sg = -sg;
                fmpz_mpoly_init(dom + ndom, s->zctx);
                fmpz_mpoly_set(dom + ndom, cp.num[j].zpoly, s->zctx);
                if (sg < 0) fmpz_mpoly_neg(dom + ndom, dom + ndom, s->zctx);
                closed[ndom++] = op == RS_CMP_LE || op == RS_CMP_GE;
            }
            rs_condpoly_clear(&cp, s);
        }
        if (rs_an_region_cad_cells(&cells, run, v, fv[0], fv[1], dom, closed, ndom) != RS_OK) rs_error_init(run->err);
        for (i = 0; i < ndom; i++) fmpz_mpoly_clear(dom + i, s->zctx);
        flint_free(dom);
        flint_free(closed);
        failing = json_array();
        json_array_foreach(cells, ci, e) {
            const char *st = json_string_value(json_object_get(e, "status"));
            json_t *a = json_object_get(e, run->c->params[fv[0]].name), *b = json_object_get(e, run->c->params[fv[1]].name);
            if (st == NULL || strcmp(st, "stable") == 0 || strcmp(st, "outside") == 0 || strcmp(st, "undecided") == 0
                || !json_is_string(a) || !json_is_string(b))
                continue;
            json_array_append_new(failing, json_pack("{s:{s:O,s:O}}", "counterexample",
                                                     run->c->params[fv[0]].name, a, run->c->params[fv[1]].name, b));
        }
        json_decref(cells);
        if (json_array_size(failing) > 0 && claim_refute_from_region(run, kind, d, failing, o)) {
            done = 1;
            json_object_set_new(o, "found_by", json_string(
                "the decomposition of the plane (the CAD of `region N1, N2`, cut also by the claim's condition): "
                "a cell's rational sample, re-checked (the assumptions and the claim's condition hold there, the "
                "exact point verdict violates the claim)"));
        }
        json_decref(failing);
    }
    return done;
}

static int claim_region_check(rs_run_t *run, const rs_request_t *q, claim_kind_t kind, const claim_dnf_t *d,
                              json_t *o)
{
    slong tv = -1, part, j;
    size_t i;
    const char *st = json_string_value(json_object_get(o, "status"));
    json_t *reg = NULL, *ivs, *iv, *failing, *best = NULL, *ex, *forall = NULL, *regs = NULL;
    int r = RS_OK, all_good = 1, some_bad = 0, nregions = 0;
    double best_len = -1;
    char buf[1200], one[400];
    const char *why = NULL;
    size_t used;
    if (kind == CLAIM_UNSTABLE || st == NULL) return RS_OK;
    /* the region is of real parameters only: not at complex set values */
    if (run->c->ncsets > 0) return RS_OK;
    /* the parameter: the first one a condition bounds by constants; every
     * other condition must leave it alone (it then restricts the quantified
     * parameters) */
    for (part = 0; part < d->nparts && tv < 0; part++)
        for (j = 0; j < d->n[part] && tv < 0; j++) tv = cond_simple_param(run, d->conds[part] + j);
    if (tv < 0) why = "no condition bounds one parameter by constants (NAME op CONST)";
    for (part = 0; part < d->nparts && why == NULL; part++)
        for (j = 0; j < d->n[part] && why == NULL; j++)
            if (cond_simple_param(run, d->conds[part] + j) != tv) {
                const rs_cond_t *cd = d->conds[part] + j;
                slong k;
                for (k = 0; k < cd->n; k++)
                    if (expr_mentions(cd->e[k], run->c->params[tv].name)) {
                        why = "a condition ties the claim's parameter to other parameters (the for-all region "
                              "quantifies the others over intervals)";
                        break;
                    }
            }
    if (why != NULL) {
        json_object_set_new(o, "cross_check", json_pack("{s:s,s:s}", "status", "not made", "reason", why));
        if (strcmp(st, "undecided") == 0) claim_refute_from_cad(run, kind, d, o);
        return RS_OK;
    }
    failing = json_array();
    regs = json_array();
    for (part = 0; part < d->nparts && r == RS_OK; part++) {
    r = claim_part_region(&reg, run, q, tv, d->conds[part], d->n[part]);
    if (r == RS_ERR_LIMIT) {        /* keep the claim's own verdict */
        json_object_set_new(o, "cross_check", json_pack("{s:s,s:s}", "status", "not made", "reason",
                                                         run->err->msg));
        rs_error_init(run->err);
        json_decref(failing);
        json_decref(best);
        json_decref(regs);
        return RS_OK;
    }
    if (r != RS_OK || reg == NULL) continue;
    ivs = json_object_get(reg, "intervals");
    json_array_foreach(ivs, i, iv) {
        const char *s = json_string_value(json_object_get(iv, "status"));
        if (region_good(kind, s)) {
            /* a run of adjacent good intervals (stable next to marginal for
             * `claim bounded`) is one proved part */
            json_t *run_iv = json_deep_copy(iv);
            size_t k;
            for (k = i + 1; k < json_array_size(ivs)
                            && region_good(kind, json_string_value(json_object_get(json_array_get(ivs, k), "status")));
                 k++) {
                const json_t *nx = json_array_get(ivs, k);
                json_object_set(run_iv, "hi", json_object_get(nx, "hi"));
                json_object_set(run_iv, "hi_closed", json_object_get(nx, "hi_closed"));
                json_object_set(run_iv, "hi_approx", json_object_get(nx, "hi_approx"));
                if (strcmp(json_string_value(json_object_get(nx, "status")), "stable") != 0)
                    json_object_set_new(run_iv, "status", json_string("marginal"));
            }
            i = k - 1;
            if (interval_length(run_iv) > best_len) {
                best_len = interval_length(run_iv);
                json_decref(best);
                best = run_iv;
            } else {
                json_decref(run_iv);
            }
            continue;
        }
        all_good = 0;
        if (s != NULL && strcmp(s, "undecided") == 0) continue;
        some_bad = 1;
        {
            json_t *f = json_object(), *ev, *e;
            size_t k;
            json_object_set(f, "lo", json_object_get(iv, "lo"));
            json_object_set(f, "hi", json_object_get(iv, "hi"));
            json_object_set(f, "lo_closed", json_object_get(iv, "lo_closed"));
            json_object_set(f, "hi_closed", json_object_get(iv, "hi_closed"));
            if (json_object_get(iv, "lo_approx") != NULL) json_object_set(f, "lo_approx", json_object_get(iv, "lo_approx"));
            if (json_object_get(iv, "hi_approx") != NULL) json_object_set(f, "hi_approx", json_object_get(iv, "hi_approx"));
            json_object_set(f, "status", json_object_get(iv, "status"));
            ev = json_object_get(iv, "evidence");
            json_array_foreach(ev, k, e) {      /* the first cell's counterexample */
                if (json_object_get(e, "counterexample") != NULL) {
                    json_object_set(f, "counterexample", json_object_get(e, "counterexample"));
                    json_object_set(f, "at_counterexample", json_object_get(e, "at_counterexample"));
                    break;
                }
                if (json_object_get(e, "not_stable_at") != NULL) {   /* marginal: bounded, not stable there */
                    json_object_set(f, "counterexample", json_object_get(e, "not_stable_at"));
                    json_object_set_new(f, "at_counterexample", json_pack("{s:s}", "status", "marginal"));
                    break;
                }
            }
            json_array_append_new(failing, f);
        }
    }
    if (forall == NULL) forall = json_deep_copy(json_object_get(reg, "for_all"));
    json_array_append_new(regs, reg);     /* kept for region_proof */
    reg = NULL;
    nregions++;
    }
    if (r != RS_OK || nregions == 0) {   /* an error, or every part's interval empty: no check */
        json_decref(failing);
        json_decref(best);
        json_decref(forall);
        json_decref(regs);
        return r;
    }
    if (strcmp(st, "undecided") == 0 && some_bad && claim_refute_from_region(run, kind, d, failing, o))
        st = "refuted";
    /* proved <=> inside the good part; undecided cells decide nothing */
    if (strcmp(st, "undecided") == 0 && all_good && region_proof(run, tv, kind, regs, o) == 1) {
        st = "proved";
        json_object_set_new(o, "cross_check", json_pack("{s:s,s:s}", "status", "agrees", "note",
            "proved by the for-all region (one certified sample per cell, no critical value inside a cell); "
            "the exact point verdicts of the search found no counterexample"));
    } else if ((strcmp(st, "proved") == 0 && some_bad) || (strcmp(st, "refuted") == 0 && all_good)) {
        snprintf(buf, sizeof buf, "the claim is %s but the for-all region of %s says %s", st,
                 run->c->params[tv].name, some_bad ? "it fails on part of the set" : "it holds on the whole set");
        json_object_set_new(o, "cross_check", json_pack("{s:s,s:s}", "status", "disagrees", "message", buf));
        json_object_set_new(o, "status", json_string("inconsistent"));
        run->outcome |= RS_OUTCOME_INCONSISTENT;
    } else {
        json_object_set_new(o, "cross_check", json_pack("{s:s}", "status",
                                                        all_good || some_bad ? "agrees" : "region undecided"));
    }
    if (strcmp(st, "proved") != 0 && json_array_size(failing) > 0) {
        ex = json_object();
        json_object_set_new(ex, "param", json_string(run->c->params[tv].name));
        json_object_set_new(ex, "failing", failing);
        failing = NULL;
        if (best != NULL) {
            json_t *pp = json_object();
            json_object_set(pp, "lo", json_object_get(best, "lo"));
            json_object_set(pp, "hi", json_object_get(best, "hi"));
            json_object_set(pp, "lo_closed", json_object_get(best, "lo_closed"));
            json_object_set(pp, "hi_closed", json_object_get(best, "hi_closed"));
            json_object_set(pp, "status", json_object_get(best, "status"));
            json_object_set_new(ex, "proved_part", pp);
            interval_text(one, sizeof one, best);
            snprintf(buf, sizeof buf, "holds for %s in %s", run->c->params[tv].name, one);
        } else {
            json_object_set_new(ex, "proved_part", json_null());
            snprintf(buf, sizeof buf, "holds on no interval of %s", run->c->params[tv].name);
        }
        json_array_foreach(json_object_get(ex, "failing"), i, iv) {
            used = strlen(buf);
            interval_text(one, sizeof one, iv);
            snprintf(buf + used, sizeof buf - used, "; %s on %s", json_string_value(json_object_get(iv, "status")),
                     one);
        }
        json_object_set_new(ex, "summary", json_string(buf));
        json_object_set_new(ex, "for_all", forall);
        forall = NULL;
        json_object_set_new(o, "explanation", ex);
    }
    json_decref(failing);
    json_decref(best);
    json_decref(forall);
    json_decref(regs);
    return RS_OK;
}

/* claim stable|bounded|unstable [when CONDITION ...]: the conditions parsed up front */
int rs_an_claim_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *rest = req->rest, *t;
    char kindw[80];
    claim_dnf_t *dnf;
    int r;
    t = rs_req_read_name(rest, kindw);
    if (t == NULL || !(strcmp(kindw, "stable") == 0 || strcmp(kindw, "bounded") == 0
                       || strcmp(kindw, "unstable") == 0))
        return rs_req_error(run, q, rest, RS_ERR_INPUT,
                            "expected stable, bounded or unstable after claim, found '%s'", rest);
    req->u.claim.kind = strcmp(kindw, "stable") == 0 ? CLAIM_STABLE : strcmp(kindw, "bounded") == 0 ? CLAIM_BOUNDED
                                                                                                   : CLAIM_UNSTABLE;
    t = rs_req_skip_blanks(t);
    dnf = calloc(1, sizeof(claim_dnf_t));
    req->u.claim.dnf = dnf;
    if (*t != '\0') {
        if (strncmp(t, "when", 4) != 0 || !(t[4] == ' ' || t[4] == '\t'))
            return rs_req_error(run, q, t, RS_ERR_INPUT, "expected 'when CONDITION' or end of line, found '%s'", t);
        slong i, j, k;
        r = claim_dnf_parse(dnf, run, q, t + 4);
        for (i = 0; r == RS_OK && i < dnf->nparts; i++)
            for (j = 0; r == RS_OK && j < dnf->n[i]; j++)
                for (k = 0; r == RS_OK && k < dnf->conds[i][j].n; k++) {
                    slong c;
                    r = rs_an_check_names(run, q, dnf->conds[i][j].e[k]);
                    /* at complex set values the sets are in the real parameters */
                    for (c = 0; r == RS_OK && c < run->c->ncsets; c++)
                        if (expr_mentions(dnf->conds[i][j].e[k], run->c->csets[c].name))
                            r = rs_req_error(run, q, rs_req_skip_blanks(t + 4), RS_ERR_INPUT,
                                             "expected conditions on real parameters, found '%s', which has a "
                                             "complex set value", run->c->csets[c].name);
                }
        if (r != RS_OK) return r;
    } else {
        dnf->nparts = 1;
        dnf->n = calloc(1, sizeof(slong));
        dnf->conds = calloc(1, sizeof(rs_cond_t *));
    }
    return RS_OK;
}

void rs_an_claim_req_clear(rs_an_req_t *req)
{
    if (req->u.claim.dnf != NULL) claim_dnf_clear(req->u.claim.dnf);
    free(req->u.claim.dnf);
    req->u.claim.dnf = NULL;
}

/* over Q(sqrt d) (rk sdirk2): the claim's sets boxes of the parameters
 * without a set value; each part decided on the exact region of the first
 * (one free parameter, an_qd_conds.c: every cell decided two or three
 * ways), or on its cells for every value of the others (an_qd_forall.c) */
static int claim_qd(rs_run_t *run, const rs_an_req_t *req, const char *kindw)
{
    const rs_request_t *q = req->q;
    const claim_dnf_t *d = req->u.claim.dnf;
    slong i, j, k, tv = -1, nfree = 0, nparams = run->c->nparams, *fv = flint_malloc((size_t) (nparams + 1) * sizeof(slong));
    rs_variant_t *v;
    json_t *o, *counter = NULL;
    int r, proved = 1;
    for (k = 0; k < nparams; k++) {
        int set = 0;
        for (j = 0; j < run->c->nsets; j++) set |= strcmp(run->c->sets[j].name, run->c->params[k].name) == 0;
        for (j = 0; j < run->c->ncsets; j++) set |= strcmp(run->c->csets[j].name, run->c->params[k].name) == 0;
        if (!set) fv[nfree++] = k;
    }
    tv = nfree > 0 ? fv[0] : -1;
    if (nfree < 1) {
        flint_free(fv);
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "expected a parameter without a set value: a claim over "
                            "Q(sqrt d) is decided on the exact region of its free parameters (stability gives the "
                            "verdict at the set values)%s", "");
    }
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) { flint_free(fv); return r; }
    /* every condition a bound on one free parameter (linear in it, nothing else) */
    for (i = 0; i < d->nparts && r == RS_OK; i++)
        for (j = 0; j < d->n[i] && r == RS_OK; j++) {
            rs_condpoly_t cp;
            r = rs_condpoly_compile(&cp, d->conds[i] + j, run->sym, run->c, run->err);
            if (r != RS_OK) break;
            for (k = 0; k < cp.n; k++) {
                slong td = fmpq_mpoly_total_degree_si(cp.num + k, run->sym->ctx), f;
                int one = 0;
                for (f = 0; f < nfree; f++) one |= fmpq_mpoly_degree_si(cp.num + k, fv[f], run->sym->ctx) == td;
                if (td > 1 || !fmpq_mpoly_is_fmpq(cp.den + k, run->sym->ctx) || !one) r = RS_ERR_INPUT;
            }
            rs_condpoly_clear(&cp, run->sym);
            if (r != RS_OK)
                r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "expected bounds on the free parameters (NAME < VALUE, "
                                 "A <= NAME <= B, joined by and, or): a claim over Q(sqrt d) is decided on exact "
                                 "regions, one parameter at a time (here %s)", run->c->params[tv].name);
        }
    if (r != RS_OK) { flint_free(fv); return r; }
    o = json_object();
    json_object_set_new(o, "analysis", json_string("claim"));
    json_object_set_new(o, "text", json_string(q->text));
    json_object_set_new(o, "claim", json_string(kindw));
    for (i = 0; i < d->nparts && r == RS_OK && counter == NULL; i++) {
        rs_bound_t *b = flint_malloc((nparams + 1) * sizeof(rs_bound_t));
        int vd = 1, kd = req->u.claim.kind == CLAIM_STABLE ? 0 : req->u.claim.kind == CLAIM_BOUNDED ? 1 : 2, empty = 0;
        claim_bounds(b, run, d->conds[i], d->n[i]);
        for (k = 0; k < nfree; k++) empty |= rs_bound_empty(b + fv[k]);
        if (!empty)
            r = nfree >= 2 ? rs_an_qd_claim_forall(&vd, &counter, o, run, req, kd, tv, fv + 1, nfree - 1, b)
                           : rs_an_qd_claim_part(&vd, &counter, o, run, req, kd, tv, b + tv);
        if (vd != 1) proved = 0;
        rs_bounds_clear(b, nparams);
        flint_free(b);
    }
    flint_free(fv);
    if (r != RS_OK) {
        json_decref(o);
        json_decref(counter);
        return r;
    }
    if (counter != NULL) {
        json_object_set_new(o, "status", json_string("refuted"));
        json_object_set_new(o, "counterexample", counter);
        run->outcome |= RS_OUTCOME_FAILED;
    } else {
        json_object_set_new(o, "status", json_string(proved ? "proved" : "undecided"));
    }
    {
        char *over = rs_an_qd_over_str(run->sym->sqrt_d), tried[1024];
        snprintf(tried, sizeof tried,
                 "the exact region over %s of the one free parameter on the claim's set (with two or more free "
                 "parameters: the first's cells of region ... for all on the claim's box, an_qd_forall.c, for a claim "
                 "unstable with the quantifier 'at every point'; region NAME's cells: "
                 "rational samples decided by the Schur-Cohn conditions, Schur-Cohn with certified roots and the "
                 "exact route over %s; algebraic critical values by exact signs in Q(t0, sqrt %ld) and the exact "
                 "route there, all agreeing): proved iff every cell meeting the set has the claimed status; refuted "
                 "at the first cell that does not, its point and exact status given",
                 over, over, (long) run->sym->sqrt_d);
        if (run->c->ncsets > 0) {
            /* at complex set values (an_qd_complex.c): both condition lists and the point verdict decide */
            snprintf(tried, sizeof tried, "the exact region over %s(i) of the one free parameter on the claim's set "
                     "(cells cut at the real roots of the norms of the Schur-Cohn and Bilharz conditions over "
                     "%s(i); rational samples decided by both lists and Schur-Cohn with certified roots, algebraic "
                     "cuts by both lists' exact signs, all agreeing): proved iff every cell meeting the set has the "
                     "claimed status; refuted at the first cell that does not", over, over);
            over = flint_realloc(over, strlen(over) + 4);
            strcat(over, "(i)");
            json_object_set_new(o, "at", rs_run_cx_at(run));
        }
        json_object_set_new(o, "over", json_string(over));
        json_object_set_new(o, "tried", json_string(tried));
        flint_free(over);
    }
    rs_run_emit_exact(run, v, o);
    return RS_OK;
}

int rs_an_claim(rs_run_t *run, const rs_an_req_t *req)
{
    static const char *const kind_words[] = {"stable", "bounded", "unstable"};
    const rs_request_t *q = req->q;
    const char *tried, *kindw;
    claim_kind_t kind = (claim_kind_t) req->u.claim.kind;
    rs_variant_t *v;
    const claim_dnf_t *d = req->u.claim.dnf;
    claim_dnf_t dnf = *d;
    slong i, nparams = run->c->nparams, ntried = 0;
    json_t *o, *counter = NULL, *at = NULL;
    int r = RS_OK, proved = 1, split = 0, inconsistent = 0;
    claim_cx_t cx;

    kindw = kind_words[kind == CLAIM_STABLE ? 0 : kind == CLAIM_BOUNDED ? 1 : 2];
    if (run->m->qd != NULL) return claim_qd(run, req, kindw);   /* over Q(sqrt d) */
    r = rs_run_default_variant(run, &v);
    /* every parameter set and det A = 0 there: a singular point, which
     * refutes every claim (as a degree drop does) */
    if (r != RS_OK && v != NULL && v->vanishes && (slong) json_object_size(v->assigned) == nparams) {
        rs_error_init(run->err);
        o = json_pack("{s:s,s:s,s:s,s:s,s:{},s:{s:s,s:b,s:s,s:s},s:i}", "analysis", "claim", "text", q->text,
                      "claim", kindw, "status", "refuted", "counterexample", "at_counterexample", "status",
                      "singular", "vanishes", 1, "reason", "det A(lambda) vanishes identically at these values: "
                      "the equations are dependent and define no recurrence", "decided_by", "exact",
                      "points_checked", 1);
        run->outcome |= RS_OUTCOME_FAILED;
        rs_run_emit_exact(run, v, o);
        return RS_OK;
    }
    if (r != RS_OK) return r;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("claim"));
    json_object_set_new(o, "text", json_string(q->text));
    json_object_set_new(o, "claim", json_string(kindw));
    cx_init(&cx);

    /* a union of sets: refuted by a point of any part, proved when every part is */
    for (i = 0; i < dnf.nparts && r == RS_OK && counter == NULL; i++) {
        rs_bound_t *b = flint_malloc((nparams + 1) * sizeof(rs_bound_t));
        claim_bounds(b, run, dnf.conds[i], dnf.n[i]);
        /* an empty part adds nothing to the union */
        {
            slong k;
            int empty = 0;
            for (k = 0; k < nparams; k++) empty |= rs_bound_empty(b + k);
            if (empty) cert_note(&cx, "an empty set (the bounds of a parameter exclude each other): nothing to prove");
            if (!empty) {
                r = claim_search(run, kind, b, dnf.conds[i], dnf.n[i], cx.st, &ntried, &counter, &at, 0, NULL, NULL);
                if (r == RS_OK && (counter != NULL || proved)) {
                    int pr;
                    if (dnf.nparts > 1) {
                        char msg[300];
                        snprintf(msg, sizeof msg, "part %ld of %ld (joined by or)", (long) i + 1,
                                 (long) dnf.nparts);
                        cert_note(&cx, msg);
                    }
                    /* proved on a part that has a counterexample: the certificate
                     * and the exact point verdict disagree */
                    pr = claim_prove(run, kind, b, &cx, 0, &split);
                    if (counter != NULL && pr) inconsistent = 1;
                    /* the failed proof's hints: points its one-variable conditions violate */
                    if (counter == NULL && !pr && (cx_hints_resolve(&cx), cx.nhints > 0))
                        r = claim_search(run, kind, b, dnf.conds[i], dnf.n[i], cx.st, &ntried, &counter, &at, 0,
                                         NULL, &cx);
                    proved = proved && pr;
                }
            }
        }
        rs_bounds_clear(b, nparams);
        flint_free(b);
    }
    if (r == RS_OK && rs_budget_exceeded()) r = rs_budget_error(run->err);
    if (cx.inconsistent) run->outcome |= RS_OUTCOME_INCONSISTENT;
    tried = kind == CLAIM_UNSTABLE
            ? "a coefficient of the bilinear polynomial q(z) of sign opposite to its leading one on the whole "
              "set (then a root has Re z > 0, |lambda| > 1) and p's leading coefficient non-zero; closed interval "
              "ends and inner points with a root at lambda = +-1 split off and substituted"
            : kind == CLAIM_STABLE
            ? "Lienard-Chipart conditions of q(z) or -q(z), each proved positive by mapping every parameter "
              "interval onto [0, inf), dividing out monomials that vanish at open ends, and checking "
              "coefficient signs (Polya multipliers (1 + sum s)^N); closed interval ends and inner points "
              "with a root at lambda = +-1 split off and substituted"
            : "stability as for `claim stable`; then q = G H with G = gcd(q(z), q(-z)): H Hurwitz-stable and "
              "G's roots simple on the imaginary axis (degree <= 2 in z^2); closed interval ends and inner "
              "points with a root at lambda = +-1 split off and substituted";
    if (run->c->ncsets > 0)
        tried = kind == CLAIM_STABLE
                ? "over Q(i) at the complex set values: every Bilharz condition of p's bilinear image (hurwitz over "
                  "Q(i)) proved positive on the set by mapping each parameter interval onto [0, inf) and checking "
                  "coefficient signs, else the exact region of the one real parameter left; counterexamples "
                  "searched with the exact Q(i) verdict"
                : "over Q(i) at the complex set values: with one real parameter left, its exact region on the set "
                  "(every cell must satisfy the claim); with more, bounded by the Bilharz conditions (every point "
                  "stable) and unstable by |a0|^2 > |an|^2 (a root outside), each proved on the set; "
                  "counterexamples searched with the exact Q(i) verdict";
    if (r == RS_OK) {
        if (inconsistent) {
            run->outcome |= RS_OUTCOME_INCONSISTENT;
            json_object_set_new(o, "status", json_string("inconsistent"));
            json_object_set_new(o, "counterexample", counter);
            json_object_set_new(o, "at_counterexample", at);
            counter = at = NULL;
        } else if (counter != NULL) {
            json_t *an = angle_note(run, counter);
            json_object_set_new(o, "status", json_string("refuted"));
            if (an != NULL) json_object_set_new(o, "angles", an);
            json_object_set_new(o, "counterexample", counter);
            json_object_set_new(o, "at_counterexample", at);
            counter = at = NULL;
            run->outcome |= RS_OUTCOME_FAILED;
        } else if (proved) {
            json_object_set_new(o, "status", json_string("proved"));
            json_object_set_new(o, "certificate", cx.cert);
            cx.cert = NULL;
            json_object_set_new(o, "certificate_rechecked", json_true());
            if (split) json_object_set_new(o, "split", json_true());
        } else {
            json_object_set_new(o, "status", json_string("undecided"));
            if (cx.fail[0] != '\0') json_object_set_new(o, "failed_at", json_string(cx.fail));
        }
        json_object_set_new(o, "points_checked", json_integer(ntried));
        json_object_set_new(o, "tried", json_string(tried));
        r = claim_region_check(run, q, kind, d, o);
    }
    if (r == RS_OK) {
        rs_run_emit_exact(run, v, o);
    } else {
        json_decref(o);
    }
    json_decref(counter);
    json_decref(at);
    cx_clear(&cx);
    return r;
}

/* One set for `region NAME for all`: b as claim_bounds makes it (NAME fixed
 * at a number).  Returns RS_OK and *verdict 1 proved (certificate in *ev),
 * -1 refuted (the counterexample and its exact verdict in *ev), 0 undecided
 * (where the proof stopped in *ev), 2 proved and refuted (inconsistent).
 * search: 0 the proof, then the search if it failed; 1 both; 2 the search
 * first (where its points are deterministic) and the proof only if it finds
 * nothing: the same answer as 0 without the failed proof attempt on a set
 * that is not good (the caller cross-checks the counterexample instead). */
int rs_an_claim_decide(int *verdict, json_t **ev, rs_run_t *run, int kind, const rs_bound_t *b, int search)
{
    claim_cx_t cx;
    json_t *counter = NULL, *at = NULL;
    slong ntried = 0;
    int r = RS_OK, split = 0, pr = 0, skipped = 1;
    cx_init(&cx);
    if (search == 2)
        r = claim_search(run, (claim_kind_t) kind, b, NULL, 0, cx.st, &ntried, &counter, &at, 1, &skipped, NULL);
    if (r == RS_OK && counter == NULL)
        pr = claim_prove(run, (claim_kind_t) kind, b, &cx, 0, &split);
    if (r == RS_OK && skipped && (!pr || search == 1))
        r = claim_search(run, (claim_kind_t) kind, b, NULL, 0, cx.st, &ntried, &counter, &at, 0, NULL, NULL);
    /* only then the failed proof's hints (the plain search's point, e.g. a
     * singular one, is kept where it finds one) */
    if (r == RS_OK && counter == NULL && !pr && (cx_hints_resolve(&cx), cx.nhints > 0))
        r = claim_search(run, (claim_kind_t) kind, b, NULL, 0, cx.st, &ntried, &counter, &at, 0, NULL, &cx);
    if (r == RS_OK && rs_budget_exceeded()) r = rs_budget_error(run->err);
    if (cx.inconsistent) run->outcome |= RS_OUTCOME_INCONSISTENT;
    *ev = NULL;
    *verdict = 0;
    if (r == RS_OK) {
        if (counter != NULL) {
            *verdict = pr ? 2 : -1;
            *ev = json_pack("{s:o,s:o,s:I}", "counterexample", counter, "at_counterexample", at,
                            "points_checked", (json_int_t) ntried);
            counter = at = NULL;
        } else if (pr) {
            *verdict = 1;
            *ev = json_pack("{s:o,s:b}", "certificate", cx.cert, "certificate_rechecked", 1);
            cx.cert = NULL;
        } else {
            *ev = json_pack("{s:s,s:I}", "failed_at", cx.fail[0] ? cx.fail : "no certificate found",
                            "points_checked", (json_int_t) ntried);
        }
    }
    json_decref(counter);
    json_decref(at);
    cx_clear(&cx);
    return r;
}

/* ---- irrational for-all points (issue 13) ----------------------------------- */

/* f(alpha, w0) as a complex ball: f in the variables tv and wv only */
static void alg_eval2(acb_t out, const fmpz_mpoly_t f, slong tv, slong wv, const acb_t al, const acb_t w0,
                      const rs_scheme_struct *s, slong prec)
{
    slong i, len = fmpz_mpoly_length(f, s->zctx);
    acb_t t, u;
    acb_init(t); acb_init(u);
    acb_zero(out);
    for (i = 0; i < len; i++) {
        acb_pow_ui(t, al, fmpz_mpoly_get_term_var_exp_ui(f, i, tv, s->zctx), prec);
        acb_pow_ui(u, w0, fmpz_mpoly_get_term_var_exp_ui(f, i, wv, s->zctx), prec);
        acb_mul(t, t, u, prec);
        acb_mul_fmpz(t, t, f->coeffs + i, prec);
        acb_add(out, out, t, prec);
    }
    acb_clear(t); acb_clear(u);
}

/* N(w) = Res_t(minpoly(t), f(t, w)) as an fmpz_poly in w; 0 on failure */
static int alg_norm(fmpz_poly_t N, const fmpz_mpoly_t f, const fmpz_poly_t m, slong tv, slong wv,
                    const rs_scheme_struct *s)
{
    fmpz_mpoly_t M, R;
    int ok;
    fmpz_mpoly_init(M, s->zctx);
    fmpz_mpoly_init(R, s->zctx);
    fmpz_mpoly_set_fmpz_poly(M, m, tv, s->zctx);
    ok = fmpz_mpoly_resultant(R, M, f, tv, s->zctx) && fmpz_mpoly_get_fmpz_poly(N, R, wv, s->zctx);
    fmpz_mpoly_clear(M, s->zctx);
    fmpz_mpoly_clear(R, s->zctx);
    return ok;
}

/* no w on the range makes f(alpha, w) = 0: its norm has no root there */
static int alg_nonzero_on(const fmpz_mpoly_t f, const fmpz_poly_t m, slong tv, slong wv, rs_sign_t sw,
                          const rs_scheme_struct *s, int *inconsistent)
{
    fmpz_poly_t N;
    fmpz_mpoly_t Nm;
    rs_sign_t *sg = flint_malloc(s->nvars * sizeof(rs_sign_t));
    slong k;
    int ok = 0, inc = 0;
    fmpz_poly_init(N);
    fmpz_mpoly_init(Nm, s->zctx);
    for (k = 0; k < s->nvars; k++) sg[k] = RS_SIGN_UNKNOWN;
    sg[wv] = sw;
    if (alg_norm(N, f, m, tv, wv, s) && !fmpz_poly_is_zero(N)) {
        if (fmpz_poly_degree(N) == 0) {
            ok = 1;
        } else {
            fmpz_mpoly_set_fmpz_poly(Nm, N, wv, s->zctx);
            ok = rs_positivity_sign_roots(Nm, sg, s->zctx, &inc) != 0;
            *inconsistent |= inc;
        }
    }
    fmpz_poly_clear(N);
    fmpz_mpoly_clear(Nm, s->zctx);
    flint_free(sg);
    return ok;
}

/* a w0 on the range with f(alpha, w0) = 0 exactly: a positive (resp. any
 * real) root of the norm where f at every other conjugate of alpha is
 * certified non-zero; its approximation into buf, its enclosure into w0 */
static int alg_zero_on(char *buf, size_t bufsz, acb_t w0, const fmpz_mpoly_t f, const fmpz_poly_t m, slong tv,
                       slong wv, rs_sign_t sw, rs_alg_t *a, const rs_scheme_struct *s)
{
    fmpz_poly_t N;
    slong nw, nm = fmpz_poly_degree(m), i, k, prec, ours;
    acb_ptr wr = NULL, ar;
    acb_t val;
    int found = 0;
    fmpz_poly_init(N);
    if (!alg_norm(N, f, m, tv, wv, s) || fmpz_poly_degree(N) < 1) {
        fmpz_poly_clear(N);
        return 0;
    }
    rs_fmpz_poly_squarefree_part(N, N);     /* simple roots, for the isolation */
    nw = fmpz_poly_degree(N);
    wr = _acb_vec_init(nw);
    ar = _acb_vec_init(nm);
    acb_init(val);
    for (prec = 64; prec <= 1024 && !found; prec *= 2) {
        arb_fmpz_poly_complex_roots(wr, N, 0, prec);
        arb_fmpz_poly_complex_roots(ar, m, 0, prec);
        rs_alg_refine(a, prec);
        /* alpha among the conjugates: the one real root meeting a's enclosure */
        ours = -1;
        for (k = 0; k < nm; k++)
            if (acb_is_real(ar + k) && arb_overlaps(acb_realref(ar + k), a->x)) {
                if (ours >= 0) { ours = -2; break; }
                ours = k;
            }
        if (ours < 0) continue;
        for (i = 0; i < nw && !found; i++) {
            int others = 1;
            if (!acb_is_real(wr + i)) continue;
            if (sw == RS_SIGN_POSITIVE && !arb_is_positive(acb_realref(wr + i))) continue;
            if (sw == RS_SIGN_NONNEGATIVE && !arb_is_nonnegative(acb_realref(wr + i))) continue;
            for (k = 0; k < nm && others; k++) {
                if (k == ours) continue;
                alg_eval2(val, f, tv, wv, ar + k, wr + i, s, prec);
                others = !acb_contains_zero(val);
            }
            if (others) {
                char *ws = arb_get_str(acb_realref(wr + i), 15, ARB_STR_NO_RADIUS);
                found = 1;
                snprintf(buf, bufsz, "%s", ws);
                acb_set(w0, wr + i);
                flint_free(ws);
            }
        }
    }
    acb_clear(val);
    _acb_vec_clear(wr, nw);
    _acb_vec_clear(ar, nm);
    fmpz_poly_clear(N);
    return found;
}

/* The second method for a marginal verdict (h-review): p(alpha, w, lambda)
 * as a polynomial in lambda with ball coefficients (alpha's enclosure
 * refined, w at each sample), its roots certified by acb_poly_find_roots.
 * The exact argument puts every root in the closed unit disc for every w on
 * the range, so a root ball certainly outside the circle (|root| > 1)
 * contradicts it.  Returns 0 on such a disagreement, else 1; *out says what
 * was checked (a sample whose roots are not isolated by 1024 bits checks
 * nothing and says so). */
static int alg_marginal_spot_check(json_t **out, const fmpz_mpoly_t p, slong tv, slong wv, rs_alg_t *a,
                                   acb_srcptr w, const char *const *wname, slong nw, const rs_scheme_struct *s)
{
    slong lv = s->lambda_var, n = fmpz_mpoly_degree_si(p, lv, s->zctx), i, j, prec, nout = 0, niso = 0;
    fmpz_mpoly_struct *cf = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    acb_ptr rt = _acb_vec_init(n);
    acb_poly_t P;
    acb_t al, c;
    arb_t m;
    arf_t ub, t;
    json_t *smp = json_array();
    for (j = 0; j <= n; j++) fmpz_mpoly_init(cf + j, s->zctx);
    rs_polyfmt_coeffs(cf, p, lv, s->zctx);   /* in tv and wv only (the caller's test) */
    acb_poly_init(P);
    acb_init(al); acb_init(c);
    arb_init(m);
    arf_init(ub); arf_init(t);
    for (i = 0; i < nw; i++) {
        slong outside = 0;
        int iso = 0;
        json_t *e;
        for (prec = 64; prec <= 1024 && !iso; prec *= 2) {
            rs_alg_refine(a, prec);
            acb_set_arb(al, a->x);
            acb_poly_zero(P);
            for (j = 0; j <= n; j++) {
                alg_eval2(c, cf + j, tv, wv, al, w + i, s, prec);
                acb_poly_set_coeff_acb(P, j, c);
            }
            if (acb_poly_length(P) != n + 1 || acb_contains_zero(P->coeffs + n)) continue;
            iso = acb_poly_find_roots(rt, P, NULL, 0, prec) == n;
            if (!iso) continue;
            arf_zero(ub);
            for (j = 0; j < n; j++) {
                acb_abs(m, rt + j, prec);
                arb_get_ubound_arf(t, m, prec);
                arf_max(ub, ub, t);
                arb_sub_ui(m, m, 1, prec);
                if (arb_is_positive(m)) outside++;
            }
        }
        e = json_pack("{s:s,s:b}", "value", wname[i], "roots_isolated", iso);
        if (iso) {
            niso++;
            nout += outside > 0;
            json_object_set_new(e, "roots_outside_circle", json_integer(outside));
            /* the largest |root|, rounded up */
            json_object_set_new(e, "abs_root_max_upper", json_real(arf_get_d(ub, ARF_RND_CEIL)));
        }
        json_array_append_new(smp, e);
    }
    *out = json_pack("{s:s,s:s,s:o,s:s}", "method",
                     "p's roots in lambda as certified balls (acb_poly_find_roots) at the root's enclosure and "
                     "sampled values of the quantified parameter: none may lie certainly outside the unit circle",
                     "param", s->vars[wv], "samples", smp, "result",
                     nout > 0 ? "disagree" : niso == nw ? "agree" : "agree where isolated");
    for (j = 0; j <= n; j++) fmpz_mpoly_clear(cf + j, s->zctx);
    flint_free(cf);
    _acb_vec_clear(rt, n);
    acb_poly_clear(P);
    acb_clear(al); acb_clear(c);
    arb_clear(m);
    arf_clear(ub); arf_clear(t);
    return nout == 0;
}

int rs_an_forall_alg_marginal(int *decided, json_t **ev, rs_run_t *run, const rs_variant_t *v, slong tv,
                              rs_alg_t *a)
{
    const rs_scheme_struct *s = v->s;
    const fmpz_mpoly_struct *p = v->cp->p;
    slong lv = s->lambda_var, k, wv = -1, np = run->c->nparams, n = v->cp->degree;
    rs_bound_t *b;
    rs_sign_t sw = RS_SIGN_UNKNOWN;
    fmpz_mpoly_t lc, disc, g;
    fmpz_t pm;
    char wbuf[2][80] = {"", ""};
    acb_ptr w0;
    json_t *cc = NULL;      /* the second method's check */
    int ok = 1, inc = 0, at[2] = {0, 0};
    *decided = 0;
    *ev = NULL;
    if (a->rational || v->singular || s->complex_char || n < 1) return RS_OK;
    for (k = 0; k < s->nvars; k++)
        if (k != lv && k != tv && fmpz_mpoly_degree_si(p, k, s->zctx) > 0) {
            if (wv >= 0) return RS_OK;     /* one quantified parameter only */
            wv = k;
        }
    if (wv < 0 || wv >= np) return RS_OK;
    /* w's range: w > 0, w >= 0 or every real (what the root tests take) */
    b = rs_run_bounds(run);
    if (!b[wv].has_lo && !b[wv].has_hi) sw = RS_SIGN_UNKNOWN;
    else if (b[wv].has_lo && !b[wv].has_hi && fmpq_is_zero(b[wv].lo))
        sw = b[wv].lo_closed ? RS_SIGN_NONNEGATIVE : RS_SIGN_POSITIVE;
    else ok = 0;
    /* an assume line tying w to another parameter is not a bound: not this test's business */
    for (k = 0; k < run->c->nassume && ok; k++) {
        const rs_cond_t *cd = &run->c->assume[k];
        slong j, q;
        int mw = 0, mo = 0;
        for (j = 0; j < cd->n; j++)
            for (q = 0; q < np; q++)
                if (expr_mentions(cd->e[j], run->c->params[q].name)) {
                    if (q == wv) mw = 1;
                    else mo = 1;
                }
        if (mw && mo) ok = 0;
    }
    rs_bounds_clear(b, np);
    flint_free(b);
    if (!ok) return RS_OK;
    fmpz_mpoly_init(lc, s->zctx);
    fmpz_mpoly_init(disc, s->zctx);
    fmpz_mpoly_init(g, s->zctx);
    fmpz_init(pm);
    w0 = _acb_vec_init(3);   /* w = 1, then the w found for lambda = 1, -1 */
    acb_one(w0);
    rs_charpoly_coeff(lc, p, n, lv, s->zctx);
    /* bounded: lc(alpha, w) != 0 and all roots simple for every w */
    ok = alg_nonzero_on(lc, a->minpoly, tv, wv, sw, s, &inc);
    if (ok && n >= 2)
        ok = fmpz_mpoly_discriminant(disc, p, lv, s->zctx)
             && alg_nonzero_on(disc, a->minpoly, tv, wv, sw, s, &inc);
    /* not stable: lambda = 1 or -1 a root at some w */
    for (k = 0; k < 2 && ok; k++) {
        fmpz_set_si(pm, k == 0 ? 1 : -1);
        fmpz_mpoly_evaluate_one_fmpz(g, p, lv, pm, s->zctx);
        at[k] = !fmpz_mpoly_is_zero(g, s->zctx)
                && alg_zero_on(wbuf[k], sizeof wbuf[k], w0 + 1 + k, g, a->minpoly, tv, wv, sw, a, s);
    }
    if (inc) run->outcome |= RS_OUTCOME_INCONSISTENT;
    if (ok && (at[0] || at[1]) && !inc) {
        const char *wn[3] = {"1", NULL, NULL};
        slong nw = 1;
        /* the second method at w = 1 and at the w where lambda = +-1 is a root */
        for (k = 0; k < 2; k++)
            if (at[k]) {
                acb_swap(w0 + nw, w0 + 1 + k);
                wn[nw++] = wbuf[k];
            }
        if (!alg_marginal_spot_check(&cc, p, tv, wv, a, w0, wn, nw, s)) {
            /* the two methods disagree (a bug): exit 3, the point left undecided */
            run->outcome |= RS_OUTCOME_INCONSISTENT;
            *ev = json_pack("{s:s,s:o}", "inconsistent",
                            "the exact marginal argument and the certified roots disagree", "cross_check", cc);
            cc = NULL;
            ok = 0;
        }
    }
    if (ok && (at[0] || at[1]) && !inc) {
        char *mp = fmpz_poly_get_str_pretty(a->minpoly, s->vars[tv]);
        char msg[900];
        *decided = 1;
        snprintf(msg, sizeof msg, "at %s = the root of %s: every root in the closed unit disc for every %s "
                 "(the limit of the stable neighbouring cell, p's leading coefficient non-zero); all roots simple "
                 "(Res_%s(%s, leading coefficient)%s have no root with %s %s: Sturm and Arb counts), so bounded; "
                 "lambda = %s is a root at %s = %s (a root of Res_%s(%s, p(%s)), the other conjugates certified "
                 "non-zero there): not stable", s->vars[tv], mp, s->vars[wv], s->vars[tv], mp,
                 n >= 2 ? " and the discriminant in lambda" : "", s->vars[wv],
                 sw == RS_SIGN_POSITIVE ? "> 0" : sw == RS_SIGN_NONNEGATIVE ? ">= 0" : "real",
                 at[0] ? "1" : "-1", s->vars[wv], at[0] ? wbuf[0] : wbuf[1], s->vars[tv], mp,
                 at[0] ? "lambda = 1" : "lambda = -1");
        *ev = json_pack("{s:s,s:s,s:s,s:o}", "certificate_algebraic", msg, "minpoly", mp, "decided_by", "exact",
                        "cross_check", cc);
        cc = NULL;
        flint_free(mp);
    }
    _acb_vec_clear(w0, 3);
    json_decref(cc);
    fmpz_mpoly_clear(lc, s->zctx);
    fmpz_mpoly_clear(disc, s->zctx);
    fmpz_mpoly_clear(g, s->zctx);
    fmpz_clear(pm);
    return RS_OK;
}
