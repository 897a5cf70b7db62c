/* hurwitz.c -- Hurwitz minors and Lienard-Chipart conditions, exactly.
 * See include/recstab/hurwitz.h.
 *
 * Conventions.  q = a_n z^n + ... + a_0.  The Hurwitz matrix H (n x n) has,
 * in row i and column j (1-based), the entry a_{n - (2j - i)} (zero outside
 * 0..n); so row 1 is a_{n-1}, a_{n-3}, ... and row 2 is a_n, a_{n-2}, ...
 * D_k is the leading principal k x k minor of H: D_1 = a_{n-1},
 * D_2 = a_{n-1} a_{n-2} - a_n a_{n-3}, ..., D_n = a_0 D_{n-1}.
 *
 * Lienard-Chipart (1914; Gantmacher, Theory of Matrices II, ch. XV sec. 13,
 * whose polynomial is written with the constant term last): with a_n > 0, all
 * roots have Re z < 0 iff
 *     a_0 > 0, a_2 > 0, a_4 > 0, ...     (constant term and every other one)
 *     D_{n-1} > 0, D_{n-3} > 0, ...      (down to D_1 or D_2; D_0 = 1)
 * (Any parity of minors may be paired with this set of coefficients; we use
 * the one that contains D_{n-1}.)  The conditions are produced in the order
 * a_n, a_0, a_2, ..., D_{n-1}, D_{n-3}, ...; a_n is listed once even when it
 * also belongs to the even-index coefficient list.
 *
 * Sign of a_n.  a_n is factored; if it is provably negative wherever it is
 * non-zero (every odd-exponent factor of provable sign, product negative),
 * q is negated (h->negated = 1) and the condition "a_n > 0" then only asks
 * for the even-exponent factors to be non-zero.  Otherwise a_n > 0 stays a
 * condition.
 *
 * Factor handling.  Each condition poly > 0 is factored as
 * c * prod f_i^{e_i}.  A factor f_i of provable sign s_i (rs_hurwitz_sign)
 * is dropped (dropped[i] = 1) and contributes s_i^{e_i} to the sign; by the
 * normalisation of FLINT's factors (positive leading coefficient) s_i is in
 * practice always +1.  A kept factor with even exponent (even[i] = 1) is >= 0
 * and only has to be non-zero.  A kept factor with odd exponent enters
 * `reduced` to the first power.  reduced = sgn(c) * prod s_i^{e_i} *
 * prod_{kept, odd} f_i, so that, wherever the kept even factors are
 * non-zero, poly > 0 iff reduced > 0. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <math.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mpoly_factor.h>
#include <flint/fmpz_vec.h>
#include <flint/fmpq_mat.h>
#include <fmpq_vec.h>
#include "algebra/mfactor.h"
#include "recstab/budget.h"
#include "recstab/hurwitz.h"
#include "recstab/positivity.h"
#include "stability/hurwitz_interp.h"
#include "stability/hurwitz_subst.h"
#include "util/polyfmt.h"

/* Degrees beyond this are refused (RS_ERR_LIMIT): the symbolic minors would
 * not be computable anyway. */
#define RS_HURWITZ_MAX_DEGREE 256

/* per-step share, seconds (rs_hurwitz_set_row_seconds); < 0: none set, then
 * the expansions are bounded by the expansion budget alone and the
 * factorisations by RS_HURWITZ_FACTOR_SHARE */
static double row_seconds = -1.0;

/* the factorisations' share when no row share is set (the share's default
 * before the expansion budget, issue 17) */
#define RS_HURWITZ_FACTOR_SHARE 2.0

/* expansion budget, seconds (rs_hurwitz_set_expand_seconds); < 0: the
 * default, RS_HURWITZ_EXPAND_SECONDS when no row share is set, none when
 * one is (so --row-share alone works as before) */
static double expand_seconds = -1.0;

double
rs_hurwitz_set_row_seconds(double seconds)
{
    double old = row_seconds;
    row_seconds = seconds;
    return old;
}

double
rs_hurwitz_set_expand_seconds(double seconds)
{
    double old = expand_seconds;
    expand_seconds = seconds;
    return old;
}

/* the share one expansion step (a Routh row, a composition) may take */
static double
_step_share(void)
{
    return row_seconds >= 0.0 ? row_seconds : HUGE_VAL;
}

/* the budget all expansion steps of one rs_hurwitz_compute* share */
static double
_expand_total(void)
{
    if (expand_seconds >= 0.0)
        return expand_seconds;
    return row_seconds >= 0.0 ? HUGE_VAL : RS_HURWITZ_EXPAND_SECONDS;
}

/* 1 if the expansion step what (of D_k) estimated at est seconds may be
 * taken: within the step share and, with the estimates of the steps taken
 * so far (hn->expand_estimate), within the expansion budget; then est is
 * added to hn->expand_estimate.  Otherwise 0 and which limit stopped it
 * into hn->stop_note.  Fixed formulas only, never the clock. */
static int
_step_fits(rs_hurwitz_struct *hn, const char *what, double est)
{
    double share = _step_share(), total = _expand_total();
    if (est > share) {
        snprintf(hn->stop_note, RS_HURWITZ_NOTE_LEN, "%s, estimated at %.3g s, is over the row share of %g s "
                 "(--row-share)", what, est, share);
        return 0;
    }
    if (hn->expand_estimate + est > total) {
        snprintf(hn->stop_note, RS_HURWITZ_NOTE_LEN, "%s, estimated at %.3g s, would bring the estimated "
                 "expansions to %.3g s, over the expansion budget of %g s (--expand-seconds)", what, est,
                 hn->expand_estimate + est, total);
        return 0;
    }
    hn->expand_estimate += est;
    return 1;
}

/* the not-expanded minors over the small ring up to this many candidate
 * terms (rs_hurwitz_set_small_terms) */
static slong small_terms = 300000;

slong
rs_hurwitz_set_small_terms(slong terms)
{
    slong old = small_terms;
    small_terms = terms;
    return old;
}

/* the substitution route: 0 never, 1 by its cost estimate, 2 whenever it
 * applies (rs_hurwitz_set_subst) */
static int subst_on = 1;

int
rs_hurwitz_set_subst(int on)
{
    int old = subst_on;
    subst_on = on;
    return old;
}

/* conditions of more terms are not given to fmpz_mpoly_factor
 * (rs_hurwitz_set_factor_terms) */
static slong factor_terms = 200000;

slong
rs_hurwitz_set_factor_terms(slong terms)
{
    slong old = factor_terms;
    factor_terms = terms;
    return old;
}

/* ------------------------------------------------------------------ */
/* sign test                                                           */

/* The coefficient test, then Polya's certificate (positivity.c): the
 * conditions of a chain of 3 masses are positive for all stiffnesses and
 * dampings > 0 but have negative coefficients (issue 17). */
int
rs_hurwitz_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                const fmpz_mpoly_ctx_t ctx)
{
    return rs_positivity_sign(poly, sign, ctx, NULL);
}

/* What the assumptions say of the variables: signs, and (may be NULL) the
 * intervals of the first nb variables for the interval mapping of
 * rs_positivity_sign_bounds. */
typedef struct {
    const rs_sign_t *sign;
    const rs_bound_t *b;
    slong nb;
} _assume_t;

static int
_sign(const fmpz_mpoly_t poly, const _assume_t *as, const fmpz_mpoly_ctx_t ctx)
{
    return rs_positivity_sign_bounds(poly, as->sign, as->b, as->nb, ctx, NULL);
}

/* ------------------------------------------------------------------ */
/* init / clear                                                        */

void
rs_hurwitz_init(rs_hurwitz_t h)
{
    h->n = 0;
    h->coeffs = NULL;
    h->minors = NULL;
    h->expanded = 0;
    h->ncond = 0;
    h->cond = NULL;
    h->negated = 0;
    h->route = 0;
    h->limit_note[0] = '\0';
    h->stop_note[0] = '\0';
    h->expand_estimate = 0.0;
    h->small_ctx = NULL;
    h->small = NULL;
    h->small_img = NULL;
    h->small_nvars = 0;
    fmpz_init(h->small_L);   /* an fmpz_t needs no clear while small */
}

static void
_small_clear(rs_hurwitz_t h, const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    if (h->small_ctx == NULL)
        return;
    for (i = 0; i < h->n; i++)
        fmpz_mpoly_clear(h->small + i, h->small_ctx);
    for (i = 0; i < h->small_nvars; i++)
        fmpz_mpoly_clear(h->small_img + i, ctx);
    flint_free(h->small);
    flint_free(h->small_img);
    fmpz_mpoly_ctx_clear(h->small_ctx);
    flint_free(h->small_ctx);
    fmpz_zero(h->small_L);
    h->small_ctx = NULL;
}

static void
_cond_clear(rs_hurwitz_cond_struct *c, const fmpz_mpoly_ctx_t ctx)
{
    if (!c->poly_shared)
        fmpz_mpoly_clear(c->poly, ctx);
    fmpz_mpoly_clear(c->reduced, ctx);
    fmpz_mpoly_factor_clear(c->factors, ctx);
    free(c->origin);
    free(c->dropped);
    free(c->even);
}

void
rs_hurwitz_clear(rs_hurwitz_t h, const fmpz_mpoly_ctx_t ctx)
{
    slong i;

    if (h->coeffs != NULL) {
        for (i = 0; i <= h->n; i++)
            fmpz_mpoly_clear(h->coeffs + i, ctx);
        flint_free(h->coeffs);
    }
    if (h->minors != NULL) {
        for (i = 0; i < h->n; i++)
            fmpz_mpoly_clear(h->minors + i, ctx);
        flint_free(h->minors);
    }
    for (i = 0; i < h->ncond; i++)
        _cond_clear(h->cond + i, ctx);
    flint_free(h->cond);
    _small_clear(h, ctx);
    fmpz_clear(h->small_L);
    rs_hurwitz_init(h);
}

/* ------------------------------------------------------------------ */
/* determinants                                                        */

/* Entry (i, j), 0-based, of the Hurwitz matrix: a_{n - (2(j+1) - (i+1))}. */
static const fmpz_mpoly_struct *
_hurwitz_entry(const fmpz_mpoly_struct *a, slong n, slong i, slong j)
{
    slong idx = n - (2 * (j + 1) - (i + 1));
    if (idx < 0 || idx > n)
        return NULL;
    return a + idx;
}

static fmpz_mpoly_struct *
_mat_init(slong m, const fmpz_mpoly_struct *a, slong n,
          const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_struct *M = flint_malloc(m * m * sizeof(fmpz_mpoly_struct));
    slong i, j;

    for (i = 0; i < m; i++)
        for (j = 0; j < m; j++) {
            const fmpz_mpoly_struct *e = _hurwitz_entry(a, n, i, j);
            fmpz_mpoly_init(M + i * m + j, ctx);
            if (e != NULL)
                fmpz_mpoly_set(M + i * m + j, e, ctx);
        }
    return M;
}

static void
_mat_clear(fmpz_mpoly_struct *M, slong m, const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    for (i = 0; i < m * m; i++)
        fmpz_mpoly_clear(M + i, ctx);
    flint_free(M);
}

/* One Bareiss step on the m x m matrix M at pivot k with previous pivot
 * prev (NULL for 1): M[i][j] = (M[i][j] M[k][k] - M[i][k] M[k][j]) / prev
 * for i, j > k.  Returns 0 if an exact division fails (cannot happen for a
 * correct elimination). */
static int
_bareiss_step(fmpz_mpoly_struct *M, slong m, slong k,
              const fmpz_mpoly_struct *prev, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t t, u;
    slong i, j;
    int ok = 1;

    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(u, ctx);
    for (i = k + 1; i < m && ok; i++) {
        for (j = k + 1; j < m && ok; j++) {
            fmpz_mpoly_mul(t, M + i * m + j, M + k * m + k, ctx);
            fmpz_mpoly_mul(u, M + i * m + k, M + k * m + j, ctx);
            fmpz_mpoly_sub(t, t, u, ctx);
            if (prev == NULL)
                fmpz_mpoly_swap(M + i * m + j, t, ctx);
            else
                ok = fmpz_mpoly_divides(M + i * m + j, t, prev, ctx);
        }
        fmpz_mpoly_zero(M + i * m + k, ctx);
    }
    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(u, ctx);
    return ok;
}

/* det of the leading m x m submatrix of the Hurwitz matrix, by Bareiss with
 * row pivoting (rows exchanged only below the current pivot, which is the
 * same as permuting the rows at the start; the sign is tracked).  The pivot
 * chosen is the non-zero candidate with the fewest terms. */
static int
_leading_minor_pivoting(fmpz_mpoly_t det, const fmpz_mpoly_struct *a,
                        slong n, slong m, const fmpz_mpoly_ctx_t ctx,
                        rs_error_t err)
{
    fmpz_mpoly_struct *M = _mat_init(m, a, n, ctx);
    slong i, j, k;
    int neg = 0, ok = 1, zero = 0;

    for (k = 0; k < m - 1 && ok && !zero; k++) {
        slong best = -1;
        for (i = k; i < m; i++) {
            slong len = fmpz_mpoly_length(M + i * m + k, ctx);
            if (len > 0 && (best < 0
                    || len < fmpz_mpoly_length(M + best * m + k, ctx)))
                best = i;
        }
        if (best < 0) {
            zero = 1;
            break;
        }
        if (best != k) {
            for (j = 0; j < m; j++)
                fmpz_mpoly_swap(M + k * m + j, M + best * m + j, ctx);
            neg ^= 1;
        }
        ok = _bareiss_step(M, m, k, k == 0 ? NULL : M + (k - 1) * m + k - 1,
                           ctx);
        if (ok && rs_budget_check(err, "the Hurwitz minors") != RS_OK) {
            _mat_clear(M, m, ctx);
            return RS_ERR_LIMIT;
        }
    }

    if (!ok) {
        _mat_clear(M, m, ctx);
        return rs_error_set(err, RS_ERR_INTERNAL,
                            "hurwitz: inexact Bareiss division in D_%ld",
                            (long) m);
    }
    if (zero)
        fmpz_mpoly_zero(det, ctx);
    else if (neg)
        fmpz_mpoly_neg(det, M + (m - 1) * m + (m - 1), ctx);
    else
        fmpz_mpoly_set(det, M + (m - 1) * m + (m - 1), ctx);
    _mat_clear(M, m, ctx);
    return RS_OK;
}

/* rs_budget_mpoly_mul_seconds is FLINT's dense (array) multiplication;
 * when the product's box prod_v (deg_v a + deg_v b + 1) exceeds the term
 * pairs FLINT multiplies by a heap, about 30x dearer per pair (the chain's
 * rows over Z[c, E] with the exact division by D_{m-3}: 26-28x for rows
 * 11-13 of N = 7, 40-60x for the smaller rows 9-11 of N = 6; issue 17,
 * h-chain11).  A fixed model of term counts, degrees and coefficient sizes,
 * never the clock, so the same input expands the same minors at any load
 * and on any machine. */
#define HEAP_FACTOR 30.0

static double
_mul_estimate(const fmpz_mpoly_t a, const slong *da, const fmpz_mpoly_t b,
              const slong *db, slong nvars)
{
    double box = 1.0, pairs = (double) a->length * (double) b->length;
    slong v;
    if (pairs == 0.0)
        return 0.0;
    for (v = 0; v < nvars; v++)
        box *= (double) (FLINT_MAX(da[v], 0) + FLINT_MAX(db[v], 0) + 1);
    return rs_budget_mpoly_mul_seconds(a, b) * (box > pairs ? HEAP_FACTOR : 1.0);
}

/* Seconds for the products of one fraction-free Routh row (below); deg is
 * scratch for 2 len nvars degrees. */
static double
_row_estimate(const fmpz_mpoly_struct *r0, const fmpz_mpoly_struct *r1,
              slong len, slong *deg, const fmpz_mpoly_ctx_t ctx)
{
    double s = 0.0;
    slong j, nv = ctx->minfo->nvars;
    for (j = 0; j < len; j++) {
        fmpz_mpoly_degrees_si(deg + j * nv, r0 + j, ctx);
        fmpz_mpoly_degrees_si(deg + (len + j) * nv, r1 + j, ctx);
    }
    for (j = 0; j + 1 < len; j++)
        s += _mul_estimate(r1, deg + len * nv, r0 + j + 1, deg + (j + 1) * nv, nv)
             + _mul_estimate(r0, deg, r1 + j + 1, deg + (len + j + 1) * nv, nv);
    return s;
}

/* 1 if WHAT, estimated at seconds and bytes, fits what is left of the time
 * and memory budget; otherwise 0 and the budget's message (which limit, the
 * estimate) into note unless one is there already (rs_hurwitz_struct's
 * limit_note: only the budget, never the row share, depends on the clock). */
static int
_budget_fits(char *note, const char *what, double seconds, double bytes)
{
    rs_error_t e;
    int ok;
    rs_error_init(e);
    ok = rs_budget_estimate(e, what, seconds, bytes) == RS_OK;
    if (!ok && note != NULL && note[0] == '\0')
        snprintf(note, RS_HURWITZ_NOTE_LEN, "%s", e->msg);
    rs_error_clear(e);
    return ok;
}

/* Integer content of the row r[0..len-1] (1 for a zero row) into g. */
static void
_row_content(fmpz_t g, const fmpz_mpoly_struct *r, slong len)
{
    slong j;
    fmpz_zero(g);
    for (j = 0; j < len; j++)
        _fmpz_vec_content_chained(g, r[j].coeffs, r[j].length, g);
    if (fmpz_is_zero(g))
        fmpz_one(g);
}

/* r[j] /= g for the row r[0..len-1]; scale *= g. */
static void
_row_split_content(fmpz_mpoly_struct *r, slong len, fmpq_t scale,
                   const fmpz_mpoly_ctx_t ctx)
{
    fmpz_t g;
    slong j;
    fmpz_init(g);
    _row_content(g, r, len);
    if (!fmpz_is_one(g))
        for (j = 0; j < len; j++)
            fmpz_mpoly_scalar_divexact_fmpz(r + j, r + j, g, ctx);
    fmpq_mul_fmpz(scale, scale, g);
    fmpz_clear(g);
}

/* D = scale * r, where the product has integer coefficients. */
static void
_scaled_set(fmpz_mpoly_t D, const fmpz_mpoly_t r, const fmpq_t scale,
            const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_scalar_mul_fmpz(D, r, fmpq_numref(scale), ctx);
    fmpz_mpoly_scalar_divexact_fmpz(D, D, fmpq_denref(scale), ctx);
}

/* Fraction-free Routh scheme (the Hurwitz-structured form of Bareiss's
 * elimination).  Rows R_0 = (a_n, a_{n-2}, ...), R_1 = (a_{n-1}, a_{n-3},
 * ...), and for m >= 2
 *     R_m[j] = (R_{m-1}[0] R_{m-2}[j+1] - R_{m-2}[0] R_{m-1}[j+1]) / d_m,
 * d_m = D_{m-3} for m >= 4, d_2 = d_3 = 1.  Then R_m[0] = D_m.  (R_m is the
 * classical Routh row m scaled by D_{m-1}; its entries are bordered minors
 * of H, so the division is exact as an identity between polynomials in
 * independent a_i, and it stays exact after specialisation as long as the
 * divisor is not identically zero.)
 * Each row is stored as R_m = s_m S_m with s_m rational and S_m of integer
 * content 1: the products then run on S (for the bilinear q of a 5-mass
 * chain the contents are powers of 2 up to 2^135 on 160-bit coefficients,
 * issue 17), and S_m[j] = (S_{m-1}[0] S_{m-2}[j+1] - S_{m-2}[0]
 * S_{m-1}[j+1]) / pp(d_m) up to the integer content, exact over Z by
 * Gauss's lemma (pp: primitive part), with s_m = s_{m-1} s_{m-2} g /
 * cont(d_m) for the content g split off; D_m = s_m S_m[0] exactly.
 * Computes D_1..D_m (m < n) into D and
 * returns m; row n is never formed: its only entry D_n = a_0 D_{n-1} is one
 * cheap product, while the recursion's would be the largest of all (about
 * half the time for a 5-mass chain, issue 17).  It
 * stops before a division by an identically-zero D_{m-3}, or (which
 * should not happen) at an inexact division, or with *status = RS_ERR_LIMIT
 * (err untouched) when a row does not fit its share of the budget
 * (_row_estimate, rs_hurwitz_set_row_seconds; or what is left of the
 * budget: then its message goes into hn->limit_note; which step the share
 * stopped goes into hn->stop_note), or with the error of an
 * interrupted product. */
/* the substitution route's compositions, made as the rows come (below) */
typedef struct {
    fmpz_mpoly_struct *D;          /* the minors in the parameters */
    const fmpz_mpoly_struct *Dg;   /* the minors over the smaller ring */
    rs_hurwitz_subst_struct *hs;   /* its power cache grows */
    const fmpz_mpoly_ctx_struct *ctx;
    rs_hurwitz_struct *hn;
    slong done;                    /* D_1..D_done composed */
    int stopped;                   /* a composition did not fit: no more */
    int r;                         /* a composition's error, RS_OK */
} _compose_state;

static int _compose_upto(_compose_state *cs, slong k, rs_error_t err);

static slong
_hurwitz_minors_routh(fmpz_mpoly_struct *D, const fmpz_mpoly_struct *a,
                      slong n, const fmpz_mpoly_ctx_t ctx, int *status,
                      rs_hurwitz_struct *hn, _compose_state *cs, rs_error_t err)
{
    slong len = n / 2 + 2, m, j, done;
    double est;
    char what[80];
    fmpz_mpoly_struct *R = flint_malloc(3 * len * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_struct *r0 = R, *r1 = R + len, *r2 = R + 2 * len, *tmp;
    fmpz_mpoly_t t, u, pd;
    fmpq_t s0, s1, s2;
    fmpz_t cd;
    int ok = 1;
    slong *deg = flint_malloc(2 * len * FLINT_MAX(ctx->minfo->nvars, 1) * sizeof(slong));

    for (j = 0; j < 3 * len; j++)
        fmpz_mpoly_init(R + j, ctx);
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(u, ctx);
    fmpz_mpoly_init(pd, ctx);
    fmpq_init(s0);
    fmpq_init(s1);
    fmpq_init(s2);
    fmpz_init(cd);
    for (j = 0; 2 * j <= n; j++)
        fmpz_mpoly_set(r0 + j, a + n - 2 * j, ctx);
    for (j = 0; 2 * j + 1 <= n; j++)
        fmpz_mpoly_set(r1 + j, a + n - 2 * j - 1, ctx);
    fmpz_mpoly_set(D + 0, r1 + 0, ctx);
    fmpq_one(s0);
    fmpq_one(s1);
    _row_split_content(r0, len, s0, ctx);
    _row_split_content(r1, len, s1, ctx);
    done = 1;

    for (m = 2; m < n; m++) {
        /* r0 = S_{m-2}, r1 = S_{m-1}; row m into r2 */
        const fmpz_mpoly_struct *d = (m >= 4) ? D + (m - 4) : NULL;
        if (d != NULL && fmpz_mpoly_is_zero(d, ctx))
            break;
        /* a row over its share (or what is left) is not formed: the
         * minors from D_m on stay unexpanded, honestly marked */
        est = _row_estimate(r0, r1, len, deg, ctx);
        snprintf(what, sizeof(what), "the fraction-free Routh row of D_%ld", (long) m);
        if (!_step_fits(hn, what, est)) {
            *status = RS_ERR_LIMIT;
            break;
        }
        if (!_budget_fits(hn->limit_note, "a row of the Hurwitz minors", est, 0.0)) {
            *status = RS_ERR_LIMIT;
            break;
        }
        fmpz_one(cd);
        if (d != NULL) {
            _fmpz_vec_content(cd, d->coeffs, d->length);
            fmpz_mpoly_scalar_divexact_fmpz(pd, d, cd, ctx);
        }
        for (j = 0; j + 1 < len && ok; j++) {
            /* one product can take seconds: stop between them */
            if ((*status = rs_budget_check(err, "the Hurwitz minors")) != RS_OK)
                break;
            fmpz_mpoly_mul(t, r1 + 0, r0 + j + 1, ctx);
            fmpz_mpoly_mul(u, r0 + 0, r1 + j + 1, ctx);
            fmpz_mpoly_sub(t, t, u, ctx);
            if (d == NULL)
                fmpz_mpoly_swap(r2 + j, t, ctx);
            else
                ok = fmpz_mpoly_divides(r2 + j, t, pd, ctx);
        }
        if (!ok || *status != RS_OK)
            break;
        fmpz_mpoly_zero(r2 + len - 1, ctx);
        fmpq_mul(s2, s0, s1);
        fmpq_div_fmpz(s2, s2, cd);
        _row_split_content(r2, len, s2, ctx);
        _scaled_set(D + m - 1, r2 + 0, s2, ctx);
        done = m;
        /* compose D_m right away: a row whose minor cannot be composed
         * within the budget is not worth forming (the N = 7 chain's row of
         * D_12 estimated at 2.7 s, its compositions stopping at D_9) */
        if (cs != NULL && (_compose_upto(cs, m, err) != RS_OK || cs->stopped)) {
            *status = RS_ERR_LIMIT;
            break;
        }
        tmp = r0; r0 = r1; r1 = r2; r2 = tmp;
        fmpq_swap(s0, s1);
        fmpq_swap(s1, s2);
    }

    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(u, ctx);
    fmpz_mpoly_clear(pd, ctx);
    fmpq_clear(s0);
    fmpq_clear(s1);
    fmpq_clear(s2);
    fmpz_clear(cd);
    for (j = 0; j < 3 * len; j++)
        fmpz_mpoly_clear(R + j, ctx);
    flint_free(R);
    flint_free(deg);
    return done;
}

/* All leading principal minors D_1..D_n into D[0..n-1]: the fraction-free
 * Routh scheme as far as it goes, then every further D_k (k < n) as its own
 * determinant with pivoting, and D_n = a_0 D_{n-1} (the last column of H is
 * (0, ..., 0, a_0)). */
static int
_hurwitz_minors_direct(fmpz_mpoly_struct *D, slong *expanded,
                const fmpz_mpoly_struct *a, slong n,
                const fmpz_mpoly_ctx_t ctx, rs_hurwitz_struct *hn,
                _compose_state *cs, rs_error_t err)
{
    int status = RS_OK;
    slong k = _hurwitz_minors_routh(D, a, n, ctx, &status, hn, cs, err);

    *expanded = k;
    if (status != RS_OK) {
        /* over the row share: keep D_1..D_k; a limit hit inside a row
         * (budget exceeded) stays an error */
        if (rs_budget_exceeded())
            return rs_budget_error(err);
        return RS_OK;
    }

    for (; k < n - 1; k++) {
        int r = _leading_minor_pivoting(D + k, a, n, k + 1, ctx, err);
        if (r != RS_OK)
            return r;
    }
    if (k == n - 1 && n >= 2)
        fmpz_mpoly_mul(D + n - 1, a + 0, D + n - 2, ctx);
    *expanded = n;
    return RS_OK;
}

/* D = (1/L^m) Dg(x_v, G(x)) (rs_hurwitz_subst_back), one power of x_v at a time: the G_r do not
 * contain x_v, so the slices are disjoint and the budget is checked between
 * them (one composition of D_11 of a 6-mass chain is 637 163 terms).  Each
 * composed slice's terms are moved into D with x_v^e put into their
 * exponents (the coefficients swapped, not copied) and D is sorted once:
 * multiplying each slice by x_v^e and adding the slices pairwise copied
 * every GMP coefficient about log2(slices) + 1 times (issue 17, h-chain8). */
static int
_subst_back(fmpz_mpoly_t D, const fmpz_mpoly_t Dg, slong m,
            rs_hurwitz_subst_t hs, const fmpz_mpoly_ctx_t ctx,
            rs_error_t err)
{
    slong e, d = fmpz_mpoly_degree_si(Dg, 0, hs->gctx), zero = 0, i;
    fmpz_mpoly_t sl, part;
    ulong *ex;
    int r = RS_OK;

    fmpz_t g;

    fmpz_mpoly_init(sl, hs->gctx);
    fmpz_mpoly_init(part, ctx);
    fmpz_init(g);
    ex = flint_malloc((ctx->minfo->nvars + 1) * sizeof(ulong));
    fmpz_mpoly_zero(D, ctx);
    /* composed from the primitive part and scaled once at the end: the
     * integer content (2^200 in D_11 of a 6-mass chain) would otherwise make
     * every coefficient of every slice a GMP integer */
    _fmpz_vec_content(g, Dg->coeffs, Dg->length);
    for (e = 0; e <= d && r == RS_OK; e++) {
        ulong ee = e;
        fmpz_mpoly_get_coeff_vars_ui(sl, Dg, &zero, &ee, 1, hs->gctx);
        if (!fmpz_is_zero(g))
            fmpz_mpoly_scalar_divexact_fmpz(sl, sl, g, hs->gctx);
        if (fmpz_mpoly_is_zero(sl, hs->gctx))
            continue;
        if (!rs_hurwitz_subst_compose(part, sl, hs, ctx)) {
            r = rs_error_set(err, RS_ERR_LIMIT,
                             "hurwitz: exponents too large composing D_%ld", (long) m);
            break;
        }
        for (i = 0; i < part->length; i++) {
            fmpz_mpoly_get_term_exp_ui(ex, part, i, ctx);
            ex[hs->var] += (ulong) e;   /* 0 before: the G_r lack x_v */
            fmpz_mpoly_push_term_ui_ui(D, 0, ex, ctx);
            fmpz_swap(D->coeffs + D->length - 1, part->coeffs + i);
        }
        r = rs_budget_check(err, "the composition of the Hurwitz minors");
    }
    if (r == RS_OK) {
        /* the slices are disjoint: sorting makes D canonical (combining
         * finds no like terms and is linear) */
        fmpz_mpoly_sort_terms(D, ctx);
        fmpz_mpoly_combine_like_terms(D, ctx);
        /* D = (g / L^m) sum of the slices, exact (rs_hurwitz_subst_back):
         * one pass over D's coefficients when L^m divides g (the chain:
         * L = 1) */
        fmpz_t Lm;
        fmpz_init(Lm);
        fmpz_pow_ui(Lm, hs->L, (ulong) m);
        if (fmpz_divisible(g, Lm)) {
            fmpz_divexact(g, g, Lm);
            fmpz_mpoly_scalar_mul_fmpz(D, D, g, ctx);
        } else {
            fmpz_mpoly_scalar_mul_fmpz(D, D, g, ctx);
            fmpz_mpoly_scalar_divexact_fmpz(D, D, Lm, ctx);
        }
        fmpz_clear(Lm);
    } else {
        fmpz_mpoly_zero(D, ctx);
    }
    flint_free(ex);
    fmpz_clear(g);
    fmpz_mpoly_clear(sl, hs->gctx);
    fmpz_mpoly_clear(part, ctx);
    return r;
}

/* CPU seconds of _subst_back producing terms terms: FLINT's Horner
 * composition grows a little faster than its output, 1.7e-7 terms^1.25
 * (fitted to D_8..D_11 of the 6-mass chain, 54 289 to 637 163 terms: 0.12,
 * 0.48, 1.61, 3.05 s measured at load 3; 0.14, 0.50, 1.49, 3.04 s by the
 * formula; issue 17, h-chain11).  A fixed function of the predicted size,
 * not a measured time (it was the last composition's CPU time times the
 * growth, so the set of expanded minors changed with the load). */
static double
_compose_estimate(double terms)
{
    return 1.7e-7 * pow(terms, 1.25);
}

/* Composes D_{cs->done + 1}..D_k (cs->Dg formed) back into the parameters
 * while each fits the row share, the expansion budget and what is left of
 * the budget; the first that does not sets cs->stopped (the later minors
 * stay unexpanded).  Errors of a composition go into cs->r (returned). */
static int
_compose_upto(_compose_state *cs, slong k, rs_error_t err)
{
    fmpz_mpoly_struct *D = cs->D;
    const fmpz_mpoly_struct *Dg = cs->Dg;
    rs_hurwitz_subst_struct *hs = cs->hs;
    const fmpz_mpoly_ctx_struct *ctx = cs->ctx;
    rs_hurwitz_struct *hn = cs->hn;
    slong i;

    for (i = cs->done; i < k && cs->r == RS_OK && !cs->stopped; i++) {
        /* the composition's cost from its predicted size (the output grows
         * about geometrically: D_9, D_10, D_11 of a 6-mass chain have
         * 147 694, 362 136, 637 163 terms); over the row share or the
         * budgets, this minor and the later ones stay unexpanded */
        if (i >= 2 && fmpz_mpoly_length(D + i - 2, ctx) > 0
            && fmpz_mpoly_length(Dg + i - 1, hs->gctx) > 0
            && fmpz_mpoly_length(Dg + i - 2, hs->gctx) > 0) {
            /* terms grow as in the small ring times the growth of the
             * expansion factor (terms after / before composing): 2.5 and
             * 1.9 predicted for D_10, D_11 of a 6-mass chain, 2.45 and 1.76
             * measured */
            double t1 = (double) fmpz_mpoly_length(D + i - 1, ctx);
            double t2 = (double) fmpz_mpoly_length(D + i - 2, ctx);
            double g0 = (double) fmpz_mpoly_length(Dg + i, hs->gctx);
            double g1 = (double) fmpz_mpoly_length(Dg + i - 1, hs->gctx);
            double g2 = (double) fmpz_mpoly_length(Dg + i - 2, hs->gctx);
            double g = (g0 / g1) * ((t1 / g1) / (t2 / g2));
            double bytes = g * t1 * (16.0 + (double) FLINT_ABS(fmpz_mpoly_max_bits(D + i - 1)) / 8.0);
            double est = _compose_estimate(FLINT_MAX(g, 1.0) * t1);
            char what[120];
            snprintf(what, sizeof(what), "the composition of D_%ld back into the parameters (about %.3g "
                     "terms predicted)", (long) (i + 1), FLINT_MAX(g, 1.0) * t1);
            if (!_step_fits(hn, what, est)) {
                cs->stopped = 1;
                break;
            }
            if (!_budget_fits(hn->limit_note, "the composition of a Hurwitz minor", est, bytes)) {
                hn->stop_note[0] = '\0';   /* the budget stopped it, not the model */
                cs->stopped = 1;
                break;
            }
        }
        cs->r = _subst_back(D + i, Dg + i, i + 1, hs, ctx, err);
        if (cs->r == RS_OK)
            cs->done = i + 1;
    }
    return cs->r;
}

/* The minors after D_expanded that the composition left out, exactly over
 * the small ring (hurwitz_interp.c) into hn->small; nothing when the
 * interpolation does not apply (no weights, a support over small_terms). */
static int
_small_minors(rs_hurwitz_struct *hn, slong expanded, rs_hurwitz_subst_t hs,
              slong n, const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    fmpz_mpoly_struct *Dg;
    slong i, nv = fmpz_mpoly_ctx_nvars(hs->gctx);
    int st;

    Dg = flint_malloc((n - 1) * sizeof(fmpz_mpoly_struct));
    for (i = 0; i < n - 1; i++)
        fmpz_mpoly_init(Dg + i, hs->gctx);
    st = rs_hurwitz_interp_minors(Dg, n - 1, hs->A, n, small_terms, err,
                                  hs->gctx);
    if (st == RS_HURWITZ_INTERP_OK) {
        hn->small_ctx = flint_malloc(sizeof(fmpz_mpoly_ctx_struct));
        fmpz_mpoly_ctx_init(hn->small_ctx, nv, hs->gctx->minfo->ord);
        hn->small = flint_malloc(n * sizeof(fmpz_mpoly_struct));
        for (i = 0; i < n; i++) {
            fmpz_mpoly_init(hn->small + i, hn->small_ctx);
            if (i >= expanded && i < n - 1)
                fmpz_mpoly_swap(hn->small + i, Dg + i, hn->small_ctx);
        }
        hn->small_nvars = nv;
        hn->small_img = flint_malloc(nv * sizeof(fmpz_mpoly_struct));
        for (i = 0; i < nv; i++) {
            fmpz_mpoly_init(hn->small_img + i, ctx);
            fmpz_mpoly_set(hn->small_img + i, hs->img + i, ctx);
        }
        fmpz_set(hn->small_L, hs->L);
    }
    for (i = 0; i < n - 1; i++)
        fmpz_mpoly_clear(Dg + i, hs->gctx);
    flint_free(Dg);
    if (st == RS_HURWITZ_INTERP_BUDGET)
        return RS_ERR_LIMIT;
    if (st == RS_HURWITZ_INTERP_CHECK)
        return rs_error_set(err, RS_ERR_INCONSISTENT, "hurwitz: the interpolated "
                            "minors over the small ring failed their check");
    return RS_OK;
}

/* All leading principal minors D_1..D_n into D[0..n-1] (*expanded of them;
 * the later ones zero and not expanded), over the smaller coefficient ring
 * of hurwitz_subst.c when its cost estimate is lower, otherwise directly.
 * On the substitution route each minor is composed back as soon as its row
 * is formed, so the expansion budget is spent in the order of the minors
 * and no row is formed whose minor could not be composed. */
static int
_hurwitz_minors(fmpz_mpoly_struct *D, slong *expanded, int *route,
                const fmpz_mpoly_struct *a, slong n,
                const fmpz_mpoly_ctx_t ctx, rs_hurwitz_struct *hn, rs_error_t err)
{
    rs_hurwitz_subst_t hs;
    fmpz_mpoly_struct *Dg;
    _compose_state cs;
    slong k, i;
    int r;

    rs_hurwitz_subst_init(hs);
    if (subst_on)
        rs_hurwitz_subst_find(hs, a, n, subst_on == 2, ctx);
    *route = hs->active;
    if (!hs->active) {
        rs_hurwitz_subst_clear(hs, ctx);
        return _hurwitz_minors_direct(D, expanded, a, n, ctx, hn, NULL, err);
    }
    Dg = flint_malloc(n * sizeof(fmpz_mpoly_struct));
    for (i = 0; i < n; i++)
        fmpz_mpoly_init(Dg + i, hs->gctx);
    cs.D = D;
    cs.Dg = Dg;
    cs.hs = hs;
    cs.ctx = ctx;
    cs.hn = hn;
    cs.done = 0;
    cs.stopped = 0;
    cs.r = RS_OK;
    r = _hurwitz_minors_direct(Dg, &k, hs->A, n, hs->gctx, hn, &cs, err);
    /* a composition's own error first (the rows then stopped quietly) */
    if (cs.r != RS_OK)
        r = cs.r;
    /* D_n = a_0 D_{n-1}: one product here, not a composition */
    if (k == n)
        k = n - 1;
    /* the minors the rows did not hand over (D_1, those after a zero
     * divisor) */
    if (r == RS_OK)
        r = _compose_upto(&cs, k, err);
    *expanded = cs.done;
    if (r == RS_OK && *expanded == n - 1) {
        fmpz_mpoly_mul(D + n - 1, a + 0, D + n - 2, ctx);
        *expanded = n;
    }
    if (r == RS_OK && *expanded < n - 1 && small_terms > 0)
        r = _small_minors(hn, *expanded, hs, n, ctx, err);
    for (i = 0; i < n; i++)
        fmpz_mpoly_clear(Dg + i, hs->gctx);
    flint_free(Dg);
    rs_hurwitz_subst_clear(hs, ctx);
    return r;
}

/* ------------------------------------------------------------------ */
/* conditions                                                          */

/* Sign of poly wherever its even-exponent factors of unknown sign are
 * non-zero, read off a factorisation: +1/-1 if every odd-exponent factor has
 * a provable sign, 0 otherwise (or if poly = 0). */
static int
_factored_sign(const fmpz_mpoly_factor_t f, const _assume_t *as,
               const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    int s = fmpz_sgn(f->constant);

    for (i = 0; i < f->num && s != 0; i++) {
        if (fmpz_is_even(f->exp + i))
            continue;
        s *= _sign(f->poly + i, as, ctx);
    }
    return s;
}

/* CPU seconds of fmpz_mpoly_factor on a condition of len terms: a power
 * law through the 6-mass chain's D_9 (147 694 terms, 0.22 s) and D_11
 * (637 163 terms, 2.68 s); it runs low on small ones (D_9 of N = 5, 21 964
 * terms: 0.065 s measured, 0.009 estimated), which then fit anyway. */
static double
_factor_estimate(slong len)
{
    return 0.22 * pow((double) len / 147694.0, 1.71);
}

/* The cheap steps of a factorisation of poly into f (issue 17): the integer
 * content (signed so that the rest has a positive leading coefficient, as
 * FLINT normalises), each parameter's smallest exponent, and each known
 * irreducible factor known[0..nknown-1] (the fully factored other
 * conditions) as often as it divides exactly; the cofactor last, exponent 1
 * (none when it is 1).  *whole = 1 when no cofactor is left.  The product is
 * poly exactly, so the condition stays the same; only the cofactor's
 * irreducibility and square-freeness are not known. */
static int
_factor_cheap(fmpz_mpoly_factor_t f, int *whole, const fmpz_mpoly_t poly,
              fmpz_mpoly_struct *const *known, slong nknown,
              const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    slong i, j, v, nvars = fmpz_mpoly_ctx_nvars(ctx), len = fmpz_mpoly_length(poly, ctx);
    ulong *mn, *e;
    fmpz_mpoly_t R, Q, x;
    int r = RS_OK, mono = 0;

    fmpz_mpoly_factor_one(f, ctx);
    *whole = 1;
    if (len == 0) {
        fmpz_zero(f->constant);
        return RS_OK;
    }
    fmpz_mpoly_init(R, ctx);
    fmpz_mpoly_init(Q, ctx);
    fmpz_mpoly_init(x, ctx);
    mn = flint_malloc(nvars * sizeof(ulong));
    e = flint_malloc(nvars * sizeof(ulong));

    _fmpz_vec_content(f->constant, poly->coeffs, len);
    if (fmpz_sgn(poly->coeffs + 0) < 0)
        fmpz_neg(f->constant, f->constant);
    fmpz_mpoly_scalar_divexact_fmpz(R, poly, f->constant, ctx);

    /* the parameters themselves: x_v^(smallest exponent of x_v) */
    fmpz_mpoly_get_term_exp_ui(mn, R, 0, ctx);
    for (i = 1; i < len; i++) {
        fmpz_mpoly_get_term_exp_ui(e, R, i, ctx);
        for (v = 0; v < nvars; v++)
            mn[v] = FLINT_MIN(mn[v], e[v]);
    }
    for (v = 0; v < nvars; v++)
        if (mn[v] > 0) {
            fmpz_mpoly_gen(x, v, ctx);
            fmpz_mpoly_factor_append_ui(f, x, mn[v], ctx);
            mono = 1;
        }
    if (mono) {
        /* R / prod x_v^mn_v term by term: the quotient of each term, in the
         * same order (a monomial order is compatible with multiplication),
         * coefficients moved; FLINT's heap division did the same at a
         * tenth of the 6-mass chain's conditions (issue 17) */
        fmpz_mpoly_fit_length_reset_bits(Q, len, R->bits, ctx);
        for (i = 0; i < len; i++) {
            fmpz_mpoly_get_term_exp_ui(e, R, i, ctx);
            for (v = 0; v < nvars; v++)
                e[v] -= mn[v];
            fmpz_mpoly_push_term_ui_ui(Q, 0, e, ctx);
            fmpz_swap(Q->coeffs + i, R->coeffs + i);
        }
        fmpz_mpoly_swap(R, Q, ctx);
        fmpz_mpoly_zero(Q, ctx);
    }

    /* factors shared with the other conditions: an exact division that fails
     * stops at the first remainder term, so a non-divisor costs little */
    for (i = 0; i < nknown && r == RS_OK; i++) {
        const fmpz_mpoly_struct *k = known[i];
        ulong cnt = 0;
        if (fmpz_mpoly_length(k, ctx) < 2
            || fmpz_mpoly_length(k, ctx) > fmpz_mpoly_length(R, ctx))
            continue;
        for (j = 0; j < i; j++)
            if (fmpz_mpoly_equal(known[j], k, ctx))
                break;
        if (j < i)
            continue;   /* the same factor twice in the list */
        while (fmpz_mpoly_length(k, ctx) <= fmpz_mpoly_length(R, ctx)
               && fmpz_mpoly_divides(Q, R, k, ctx)) {
            fmpz_mpoly_swap(R, Q, ctx);
            cnt++;
        }
        if (cnt > 0)
            fmpz_mpoly_factor_append_ui(f, k, cnt, ctx);
        r = rs_budget_check(err, "the factors of a Hurwitz condition");
    }
    if (r == RS_OK && !fmpz_mpoly_is_one(R, ctx)) {
        if (fmpz_mpoly_is_fmpz(R, ctx)) {
            fmpz_t t;   /* cannot happen (R primitive, leading coefficient > 0) */
            fmpz_init(t);
            fmpz_mpoly_get_fmpz(t, R, ctx);
            fmpz_mul(f->constant, f->constant, t);
            fmpz_clear(t);
        } else {
            fmpz_mpoly_factor_append_ui(f, R, 1, ctx);
            *whole = 0;
        }
    }
    flint_free(mn);
    flint_free(e);
    fmpz_mpoly_clear(R, ctx);
    fmpz_mpoly_clear(Q, ctx);
    fmpz_mpoly_clear(x, ctx);
    return r;
}

/* Factor c->poly (FLINT's full factorisation when it is worth it: at most
 * factor_terms terms and its estimate within the row share and the budget;
 * otherwise _factor_cheap with the known factors; pre, if not NULL, is the
 * factorisation already made, taken over) and derive dropped, even, reduced
 * and the trivial flags from it. */
static int
_cond_factor(rs_hurwitz_cond_struct *c, fmpz_mpoly_factor_t pre,
             fmpz_mpoly_struct *const *known, slong nknown,
             const _assume_t *as, const fmpz_mpoly_ctx_t ctx, char *note,
             rs_error_t err)
{
    slong i, num, kept = 0, kept_odd = 0, len = fmpz_mpoly_length(c->poly, ctx);
    int s, r = 1;

    c->factored = 1;
    if (pre != NULL) {
        fmpz_mpoly_factor_swap(c->factors, pre, ctx);
    } else if (len <= factor_terms && (len <= 64
               || (_factor_estimate(len) <= (row_seconds >= 0.0 ? row_seconds : RS_HURWITZ_FACTOR_SHARE)
               && _budget_fits(note, "the factorisation of a Hurwitz condition",
                               _factor_estimate(len), 0.0)))) {
    /* gcc 12 inlines this into _add_cond and then reports FLINT 3's array
       parameters as a 48-byte access to an 8-byte region (the struct member
       is a full fmpz_mpoly_factor_t): a false positive, silenced here only */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wstringop-overflow"
#endif
        r = rs_mpoly_factor(c->factors, c->poly, ctx);   /* = fmpz_mpoly_factor, in c->poly's own variables */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
    } else {
        int rc = _factor_cheap(c->factors, &c->factored, c->poly, known, nknown, ctx, err);
        if (rc != RS_OK)
            return rc;
    }
    if (!r)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "hurwitz: could not factor condition %s", c->origin);
    if (!fmpz_is_one(c->factors->constant_den))
        return rs_error_set(err, RS_ERR_INTERNAL,
                            "hurwitz: factorisation of %s has a denominator",
                            c->origin);

    num = c->factors->num;
    c->dropped = calloc(num > 0 ? num : 1, sizeof(int));
    c->even = calloc(num > 0 ? num : 1, sizeof(int));
    if (c->dropped == NULL || c->even == NULL)
        return rs_error_set(err, RS_ERR_LIMIT, "hurwitz: out of memory");

    s = fmpz_sgn(c->factors->constant);
    fmpz_mpoly_one(c->reduced, ctx);
    for (i = 0; i < num; i++) {
        const fmpz_mpoly_struct *f = c->factors->poly + i;
        int even = fmpz_is_even(c->factors->exp + i);
        int fs = _sign(f, as, ctx);

        c->even[i] = even;
        if (fs != 0) {
            c->dropped[i] = 1;
            if (!even && fs < 0)
                s = -s;
            continue;
        }
        kept++;
        if (!even) {
            /* the first one copied (1 * f is a pass of products) */
            if (kept_odd++ == 0)
                fmpz_mpoly_set(c->reduced, f, ctx);
            else
                fmpz_mpoly_mul(c->reduced, c->reduced, f, ctx);
        }
    }
    if (s < 0)
        fmpz_mpoly_neg(c->reduced, c->reduced, ctx);
    else if (s == 0)
        fmpz_mpoly_zero(c->reduced, ctx);

    c->trivially_true = (kept == 0 && s > 0);
    c->trivially_false = (kept_odd == 0 && s <= 0);
    return RS_OK;
}

/* Condition poly > 0 named letter_idx, not yet factored (_cond_factor). */
static int
_add_cond(rs_hurwitz_t h, const fmpz_mpoly_t poly, char letter, slong idx,
          const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    rs_hurwitz_cond_struct *c = h->cond + h->ncond;
    char origin[32];

    fmpz_mpoly_init(c->poly, ctx);
    fmpz_mpoly_init(c->reduced, ctx);
    fmpz_mpoly_factor_init(c->factors, ctx);
    c->origin = NULL;
    c->dropped = NULL;
    c->even = NULL;
    c->trivially_true = c->trivially_false = 0;
    c->factored = 1;
    c->minor = (letter == 'D') ? idx : 0;
    c->not_expanded = (letter == 'D' && idx > h->expanded);
    c->poly_shared = 0;
    h->ncond++;

    snprintf(origin, sizeof(origin), "%c_%ld", letter, (long) idx);
    c->origin = malloc(strlen(origin) + 1);
    if (c->origin == NULL)
        return rs_error_set(err, RS_ERR_LIMIT, "hurwitz: out of memory");
    strcpy(c->origin, origin);
    if (c->not_expanded) {
        /* nothing to factor: poly and reduced stay 0, no factors */
        c->dropped = calloc(1, sizeof(int));
        c->even = calloc(1, sizeof(int));
        if (c->dropped == NULL || c->even == NULL)
            return rs_error_set(err, RS_ERR_LIMIT, "hurwitz: out of memory");
        return RS_OK;
    }
    if (letter == 'D') {
        /* the minor itself, not a copy: D_11 of a 6-mass chain is 637 163
         * GMP coefficients (issue 17); the conditions only read it */
        fmpz_mpoly_clear(c->poly, ctx);
        *c->poly = *poly;
        c->poly_shared = 1;
    } else {
        fmpz_mpoly_set(c->poly, poly, ctx);
    }
    return RS_OK;
}

/* Coefficients a_0..a_n of q in z, negated when a_n is provably negative
 * (wherever non-zero). */
static int
_hurwitz_coeffs(rs_hurwitz_t h, fmpz_mpoly_factor_t f, const fmpz_mpoly_t q,
                slong zvar, const _assume_t *as, const fmpz_mpoly_ctx_t ctx,
                rs_error_t err)
{
    slong i, n = h->n;
    int s;

    /* every coefficient in one pass over q's terms (tests/fuzz/regress) */
    h->coeffs = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    for (i = 0; i <= n; i++)
        fmpz_mpoly_init(h->coeffs + i, ctx);
    rs_polyfmt_coeffs(h->coeffs, q, zvar, ctx);
    if (rs_budget_check(err, "the Hurwitz conditions") != RS_OK)
        return RS_ERR_LIMIT;

    if (!fmpz_mpoly_factor(f, h->coeffs + n, ctx))
        return rs_error_set(err, RS_ERR_LIMIT,
                            "hurwitz: could not factor the leading coefficient");
    s = _factored_sign(f, as, ctx);

    if (s < 0) {
        h->negated = 1;
        fmpz_neg(f->constant, f->constant);   /* now that of -a_n */
        for (i = 0; i <= n; i++)
            fmpz_mpoly_neg(h->coeffs + i, h->coeffs + i, ctx);
    }
    return RS_OK;
}

/* Factor the conditions from the smallest to the largest, so that the
 * factors of the small ones (a_n, a_0, a_2, ..., the lower minors) are known
 * to the cheap steps of the large ones; a_n's factorisation anf (made for
 * its sign) is taken over. */
static int
_hurwitz_conditions(rs_hurwitz_t h, fmpz_mpoly_factor_t anf, const _assume_t *as,
                    const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    slong n = h->n, k, i, j, maxc = n + 2, nknown = 0, maxknown = 0;
    slong *order;
    fmpz_mpoly_struct **known = NULL;
    int r;

    h->cond = flint_malloc(maxc * sizeof(rs_hurwitz_cond_struct));

    r = _add_cond(h, h->coeffs + n, 'a', n, ctx, err);
    for (k = 0; k < n && r == RS_OK; k += 2)
        r = _add_cond(h, h->coeffs + k, 'a', k, ctx, err);
    for (k = n - 1; k >= 1 && r == RS_OK; k -= 2)
        r = _add_cond(h, h->minors + (k - 1), 'D', k, ctx, err);
    if (r != RS_OK)
        return r;

    order = flint_malloc(h->ncond * sizeof(slong));
    for (i = 0; i < h->ncond; i++)
        order[i] = i;
    for (i = 1; i < h->ncond; i++)   /* insertion sort by length, stable */
        for (j = i; j > 0 && fmpz_mpoly_length(h->cond[order[j - 1]].poly, ctx)
                              > fmpz_mpoly_length(h->cond[order[j]].poly, ctx); j--) {
            slong t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
        }
    for (i = 0; i < h->ncond && r == RS_OK; i++) {
        rs_hurwitz_cond_struct *c = h->cond + order[i];
        if (c->not_expanded)
            continue;
        r = _cond_factor(c, order[i] == 0 ? anf : NULL, known, nknown, as, ctx,
                         h->limit_note, err);
        if (r != RS_OK || !c->factored)
            continue;
        if (nknown + c->factors->num > maxknown) {
            maxknown = 2 * (nknown + c->factors->num);
            known = flint_realloc(known, maxknown * sizeof(fmpz_mpoly_struct *));
        }
        for (k = 0; k < c->factors->num; k++)
            known[nknown++] = c->factors->poly + k;
    }
    flint_free(order);
    flint_free(known);
    return r;
}

/* Validate q and zvar; the degree of q in z into *n.  (The degree is taken
 * term by term: after reading the number of variables, the inline
 * fmpz_mpoly_degree_si makes GCC 12 with -fsanitize=undefined report a
 * spurious -Wstringop-overread.) */
static int
_hurwitz_degree(slong *n, const fmpz_mpoly_t q, slong zvar,
                const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    slong i, nvars;

    if (fmpz_mpoly_is_zero(q, ctx))
        return rs_error_set(err, RS_ERR_INPUT,
                            "hurwitz: the polynomial is zero");
    if (!fmpz_mpoly_degrees_fit_si(q, ctx))
        return rs_error_set(err, RS_ERR_LIMIT,
                            "hurwitz: exponents too large");
    nvars = fmpz_mpoly_ctx_nvars(ctx);
    if (zvar < 0 || zvar >= nvars)
        return rs_error_set(err, RS_ERR_INPUT,
                            "hurwitz: variable index %ld out of range 0..%ld",
                            (long) zvar, (long) nvars - 1);
    *n = 0;
    for (i = 0; i < fmpz_mpoly_length(q, ctx); i++) {
        slong e = fmpz_mpoly_get_term_var_exp_si(q, i, zvar, ctx);
        if (e > *n)
            *n = e;
    }
    if (*n < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "hurwitz: the polynomial has degree 0 in z");
    if (*n > RS_HURWITZ_MAX_DEGREE)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "hurwitz: degree %ld exceeds the limit %d",
                            (long) *n, RS_HURWITZ_MAX_DEGREE);
    return RS_OK;
}

int
rs_hurwitz_compute_partial(rs_hurwitz_t h, const fmpz_mpoly_t q, slong zvar,
                           const rs_sign_t *sign, const fmpz_mpoly_ctx_t ctx,
                           rs_error_t err)
{
    return rs_hurwitz_compute_partial_bounds(h, q, zvar, sign, NULL, 0, ctx, err);
}

int
rs_hurwitz_compute_partial_bounds(rs_hurwitz_t h, const fmpz_mpoly_t q, slong zvar,
                                  const rs_sign_t *sign, const rs_bound_t *bounds,
                                  slong nbounds, const fmpz_mpoly_ctx_t ctx,
                                  rs_error_t err)
{
    slong i, n = 0;
    int r;
    _assume_t as;
    fmpz_mpoly_factor_t anf;

    as.sign = sign;
    as.b = bounds;
    as.nb = bounds == NULL ? 0 : nbounds;

    rs_hurwitz_clear(h, ctx);
    /* a budget already spent (e.g. inside the bilinear transform that made
     * q, which stops early and leaves the report to the next check) */
    if ((r = rs_budget_check(err, "the Hurwitz conditions")) != RS_OK)
        return r;
    r = _hurwitz_degree(&n, q, zvar, ctx, err);
    if (r != RS_OK)
        return r;

    h->n = n;
    fmpz_mpoly_factor_init(anf, ctx);
    r = _hurwitz_coeffs(h, anf, q, zvar, &as, ctx, err);
    if (r == RS_OK) {
        h->minors = flint_malloc(n * sizeof(fmpz_mpoly_struct));
        for (i = 0; i < n; i++)
            fmpz_mpoly_init(h->minors + i, ctx);
        r = _hurwitz_minors(h->minors, &h->expanded, &h->route, h->coeffs,
                            n, ctx, h, err);
    }
    if (r == RS_OK)
        r = _hurwitz_conditions(h, anf, &as, ctx, err);
    fmpz_mpoly_factor_clear(anf, ctx);
    if (r != RS_OK)
        rs_hurwitz_clear(h, ctx);
    return r;
}

/* Callers that use the minors as polynomials (critical values, projections,
 * certificates) need every one of them: a minor left unexpanded is a limit. */
int
rs_hurwitz_compute(rs_hurwitz_t h, const fmpz_mpoly_t q, slong zvar,
                   const rs_sign_t *sign, const fmpz_mpoly_ctx_t ctx,
                   rs_error_t err)
{
    int r = rs_hurwitz_compute_partial(h, q, zvar, sign, ctx, err);
    if (r == RS_OK && h->expanded < h->n) {
        slong k = h->expanded + 1;
        char why[RS_HURWITZ_NOTE_LEN];
        snprintf(why, sizeof(why), "%s", h->stop_note[0] != '\0' ? h->stop_note : h->limit_note);
        rs_hurwitz_clear(h, ctx);
        return rs_error_set(err, RS_ERR_LIMIT,
                            "the Hurwitz minor D_%ld was not expanded (%s); this analysis needs every minor as "
                            "a polynomial (`hurwitz` reports the unexpanded minors instead)", (long) k, why);
    }
    return r;
}

/* ------------------------------------------------------------------ */
/* branches: every sign of a_n                                         */

void
rs_hurwitz_or_init(rs_hurwitz_or_t hb)
{
    hb->nbranch = 0;
    rs_hurwitz_init(hb->branch + 0);
    rs_hurwitz_init(hb->branch + 1);
    hb->alive[0] = hb->alive[1] = 0;
    hb->degree_drop = 0;
    hb->zero_mult = 0;
}

void
rs_hurwitz_or_clear(rs_hurwitz_or_t hb, const fmpz_mpoly_ctx_t ctx)
{
    rs_hurwitz_clear(hb->branch + 0, ctx);
    rs_hurwitz_clear(hb->branch + 1, ctx);
    rs_hurwitz_or_init(hb);
}

static int
_branch_alive(const rs_hurwitz_t h)
{
    slong i;
    for (i = 0; i < h->ncond; i++)
        if (h->cond[i].trivially_false)
            return 0;
    return 1;
}

int
rs_hurwitz_or_compute(rs_hurwitz_or_t hb, const fmpz_mpoly_t q, slong zvar,
                      slong degree, const rs_sign_t *sign,
                      const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    return rs_hurwitz_or_compute_bounds(hb, q, zvar, degree, sign, NULL, 0, ctx, err);
}

int
rs_hurwitz_or_compute_bounds(rs_hurwitz_or_t hb, const fmpz_mpoly_t q, slong zvar,
                             slong degree, const rs_sign_t *sign,
                             const rs_bound_t *bounds, slong nbounds,
                             const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    slong i, n = 0, lo = WORD_MAX;
    int r;

    rs_hurwitz_or_clear(hb, ctx);
    if (!fmpz_mpoly_is_zero(q, ctx) && fmpz_mpoly_degrees_fit_si(q, ctx)
        && zvar >= 0 && zvar < fmpz_mpoly_ctx_nvars(ctx)) {
        for (i = 0; i < fmpz_mpoly_length(q, ctx); i++) {
            slong e = fmpz_mpoly_get_term_var_exp_si(q, i, zvar, ctx);
            n = FLINT_MAX(n, e);
            lo = FLINT_MIN(lo, e);
        }
        /* q(z) = (1 - z)^degree p((1 + z)/(1 - z)) has degree < degree
         * exactly when p(-1) = 0, and q(0) = p(1) */
        if (n < degree) {
            hb->degree_drop = degree - n;
            return RS_OK;
        }
        if (lo > 0) {
            hb->zero_mult = lo;
            return RS_OK;
        }
    }
    r = rs_hurwitz_compute_partial_bounds(hb->branch + 0, q, zvar, sign, bounds, nbounds,
                                          ctx, err);
    if (r != RS_OK)
        return r;
    hb->nbranch = 1;
    if (!hb->branch[0].negated && !hb->branch[0].cond[0].trivially_true) {
        fmpz_mpoly_t mq;
        fmpz_mpoly_init(mq, ctx);
        fmpz_mpoly_neg(mq, q, ctx);
        r = rs_hurwitz_compute_partial_bounds(hb->branch + 1, mq, zvar, sign, bounds,
                                              nbounds, ctx, err);
        fmpz_mpoly_clear(mq, ctx);
        if (r != RS_OK) {
            rs_hurwitz_or_clear(hb, ctx);
            return r;
        }
        hb->branch[1].negated = 1;
        hb->nbranch = 2;
    }
    for (i = 0; i < hb->nbranch; i++)
        hb->alive[i] = _branch_alive(hb->branch + i);
    if (hb->nbranch == 2 && !hb->alive[1]) {
        rs_hurwitz_clear(hb->branch + 1, ctx);
        hb->nbranch = 1;
    } else if (hb->nbranch == 2 && !hb->alive[0]) {
        rs_hurwitz_struct t = hb->branch[0];
        hb->branch[0] = hb->branch[1];
        hb->branch[1] = t;
        rs_hurwitz_clear(hb->branch + 1, ctx);
        hb->alive[0] = 1;
        hb->alive[1] = 0;
        hb->nbranch = 1;
    }
    return RS_OK;
}

/* poly at the rational point, over Z: with n_v / d_v the value of x_v and
 * g_v its degree, S = sum c prod n_v^e_v d_v^(g_v - e_v) from tables of
 * those powers, out = S / prod d_v^g_v (one canonicalisation; the sample
 * checks of the 637 163-term minors of a 6-mass chain spent 3 s in fmpq
 * powers and products per term, issue 17). */
void
rs_hurwitz_eval(fmpq_t out, const fmpz_mpoly_t poly, fmpq *const *vals,
                const fmpz_mpoly_ctx_t ctx)
{
    slong i, v, nvars = fmpz_mpoly_ctx_nvars(ctx), len = fmpz_mpoly_length(poly, ctx);
    slong *deg, *off, total = 0;
    ulong *e;
    fmpz *tab;
    fmpz_t t;

    if (len == 0) {
        fmpq_zero(out);
        return;
    }
    deg = flint_malloc(nvars * sizeof(slong));
    off = flint_malloc(nvars * sizeof(slong));
    e = flint_malloc(nvars * sizeof(ulong));
    fmpz_mpoly_degrees_si(deg, poly, ctx);
    for (v = 0; v < nvars; v++) {
        off[v] = total;
        total += FLINT_MAX(deg[v], 0) + 1;
    }
    tab = _fmpz_vec_init(total);
    fmpz_init(t);
    /* tab[off_v + e] = n_v^e d_v^(g_v - e) */
    for (v = 0; v < nvars; v++) {
        slong g = FLINT_MAX(deg[v], 0), k;
        fmpz_one(tab + off[v] + g);
        for (k = g - 1; k >= 0; k--)
            fmpz_mul(tab + off[v] + k, tab + off[v] + k + 1, fmpq_denref(vals[v]));
        fmpz_one(t);
        for (k = 1; k <= g; k++) {
            fmpz_mul(t, t, fmpq_numref(vals[v]));
            fmpz_mul(tab + off[v] + k, tab + off[v] + k, t);
        }
    }
    fmpz_zero(fmpq_numref(out));
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_exp_ui(e, poly, i, ctx);
        fmpz_set(t, poly->coeffs + i);
        for (v = 0; v < nvars; v++)
            if (deg[v] > 0)
                fmpz_mul(t, t, tab + off[v] + e[v]);
        fmpz_add(fmpq_numref(out), fmpq_numref(out), t);
    }
    fmpz_one(fmpq_denref(out));
    for (v = 0; v < nvars; v++)
        if (deg[v] > 0) {
            fmpz_pow_ui(t, fmpq_denref(vals[v]), (ulong) deg[v]);
            fmpz_mul(fmpq_denref(out), fmpq_denref(out), t);
        }
    fmpq_canonicalise(out);
    fmpz_clear(t);
    _fmpz_vec_clear(tab, total);
    flint_free(deg);
    flint_free(off);
    flint_free(e);
}

/* The sign of S = sum c prod n_v^e_v d_v^(g_v - e_v) (rs_hurwitz_eval: poly
 * at the point times prod d_v^g_v > 0) from doubles, certified, or 0 when the
 * doubles cannot tell.  Every factor is an integer of at most 1000 bits
 * converted with relative error <= 2^-52 (fmpz_get_d truncates), so every
 * product is 0 or >= 1 in magnitude (no underflow; overflow shows as inf or
 * NaN and gives 0).  With K = 3 nvars + 2, a term's product is within
 * K 2^-53 (1 + 1e-3) of its value, and recursive summation of len terms adds
 * gamma_len sum |terms| (Higham, Accuracy and Stability, sec. 4.2), so
 * |s - S| <= 2 (len + K) 2^-53 a, a the computed sum of |terms|, while
 * (len + K) 2^-53 < 1e-3; the test uses twice that.  The exact sums of the
 * 637 163-term conditions of a 6-mass chain at its 12 sample points were a
 * tenth of the run (issue 17); this decides them at a few ns a term. */
static int
_sign_filter(const fmpz_mpoly_t poly, fmpq *const *vals,
             const fmpz_mpoly_ctx_t ctx)
{
    slong i, v, nvars = fmpz_mpoly_ctx_nvars(ctx), len = fmpz_mpoly_length(poly, ctx);
    slong *deg, *off, total = 0;
    ulong *e;
    double *tab, s = 0.0, a = 0.0, err;
    fmpz_t t, w;
    int ok = 1, res = 0;

    if (len == 0 || (double) (len + 3 * nvars + 2) * 0x1p-53 >= 1e-3
        || FLINT_ABS(fmpz_mpoly_max_bits(poly)) > 1000)
        return 0;
    deg = flint_malloc(nvars * sizeof(slong));
    off = flint_malloc(nvars * sizeof(slong));
    e = flint_malloc((nvars + 1) * sizeof(ulong));
    fmpz_mpoly_degrees_si(deg, poly, ctx);
    for (v = 0; v < nvars; v++) {
        off[v] = total;
        total += FLINT_MAX(deg[v], 0) + 1;
    }
    tab = flint_malloc(total * sizeof(double));
    fmpz_init(t);
    fmpz_init(w);
    /* tab[off_v + k] ~ n_v^k d_v^(g_v - k), from the exact integer */
    for (v = 0; v < nvars && ok; v++) {
        slong g = FLINT_MAX(deg[v], 0), k;
        for (k = 0; k <= g && ok; k++) {
            fmpz_pow_ui(t, fmpq_numref(vals[v]), (ulong) k);
            fmpz_pow_ui(w, fmpq_denref(vals[v]), (ulong) (g - k));
            fmpz_mul(t, t, w);
            if (fmpz_bits(t) > 1000)
                ok = 0;
            else
                tab[off[v] + k] = fmpz_get_d(t);
        }
    }
    for (i = 0; i < len && ok; i++) {
        double p = fmpz_get_d(poly->coeffs + i);
        fmpz_mpoly_get_term_exp_ui(e, poly, i, ctx);
        for (v = 0; v < nvars; v++)
            if (deg[v] > 0)
                p *= tab[off[v] + e[v]];
        s += p;
        a += fabs(p);
    }
    err = 4.0 * (double) (len + 3 * nvars + 2) * 0x1p-53 * a;
    if (ok && isfinite(s) && isfinite(a) && isfinite(err) && fabs(s) > err)
        res = s > 0 ? 1 : -1;
    fmpz_clear(t);
    fmpz_clear(w);
    flint_free(tab);
    flint_free(deg);
    flint_free(off);
    flint_free(e);
    return res;
}

int
rs_hurwitz_sign_at(const fmpz_mpoly_t poly, fmpq *const *vals,
                   const fmpz_mpoly_ctx_t ctx)
{
    fmpq_t x;
    int s = _sign_filter(poly, vals, ctx);

    if (s != 0)
        return s;
    fmpq_init(x);
    rs_hurwitz_eval(x, poly, vals, ctx);
    s = fmpq_sgn(x);
    fmpq_clear(x);
    return s;
}

int
rs_hurwitz_minor_sign_at(const rs_hurwitz_t h, slong k, fmpq *const *vals,
                         const fmpz_mpoly_ctx_t ctx)
{
    fmpq_mat_t H;
    fmpq *a;
    fmpq_t det;
    slong i, j;
    int s;

    if (k < 1 || k > h->n)
        return 0;
    /* the stated condition: the small ring's minor (L^k > 0), when formed */
    if (h->small_ctx != NULL && !fmpz_mpoly_is_zero(h->small + k - 1, h->small_ctx)) {
        fmpq *g = _fmpq_vec_init(h->small_nvars);
        fmpq **gp = flint_malloc(h->small_nvars * sizeof(fmpq *));
        fmpq_t x;
        fmpq_init(x);
        for (i = 0; i < h->small_nvars; i++) {
            rs_hurwitz_eval(g + i, h->small_img + i, vals, ctx);
            gp[i] = g + i;
        }
        rs_hurwitz_eval(x, h->small + k - 1, gp, h->small_ctx);
        s = fmpq_sgn(x);
        fmpq_clear(x);
        flint_free(gp);
        _fmpq_vec_clear(g, h->small_nvars);
        return s;
    }
    a = _fmpq_vec_init(h->n + 1);
    for (i = 0; i <= h->n; i++)
        rs_hurwitz_eval(a + i, h->coeffs + i, vals, ctx);
    fmpq_mat_init(H, k, k);
    for (i = 0; i < k; i++)
        for (j = 0; j < k; j++) {
            slong idx = h->n - (2 * (j + 1) - (i + 1));
            if (idx >= 0 && idx <= h->n)
                fmpq_set(fmpq_mat_entry(H, i, j), a + idx);
        }
    fmpq_init(det);
    fmpq_mat_det(det, H);
    s = fmpq_sgn(det);
    fmpq_clear(det);
    fmpq_mat_clear(H);
    _fmpq_vec_clear(a, h->n + 1);
    return s;
}

/* 1 / 0 as the stated conditions of h hold at vals, -1 if one vanishes */
static int
_branch_holds(const rs_hurwitz_t h, fmpq *const *vals,
              const fmpz_mpoly_ctx_t ctx)
{
    slong i, k;
    int ok = 1;

    for (i = 0; i < h->ncond; i++) {
        const rs_hurwitz_cond_struct *c = h->cond + i;
        int s;
        if (c->trivially_true)
            continue;
        s = c->not_expanded ? rs_hurwitz_minor_sign_at(h, c->minor, vals, ctx)
                            : rs_hurwitz_sign_at(c->reduced, vals, ctx);
        if (s == 0)
            return -1;
        if (s < 0)
            ok = 0;
        for (k = 0; k < c->factors->num; k++)
            if (!c->dropped[k] && c->even[k]
                && rs_hurwitz_sign_at(c->factors->poly + k, vals, ctx) == 0)
                return -1;
    }
    return ok;
}

int
rs_hurwitz_or_holds(const rs_hurwitz_or_t hb, fmpq *const *vals,
                    const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    int res = 0;

    for (i = 0; i < hb->nbranch; i++) {
        int b;
        if (!hb->alive[i])
            continue;
        b = _branch_holds(hb->branch + i, vals, ctx);
        if (b < 0)
            return -1;
        if (b > 0)
            res = 1;
    }
    return res;
}

/* Hurwitz's own criterion at the point (Gantmacher XV sec. 6): with
 * a_n > 0, stable iff D_1, ..., D_n > 0.  Gaussian elimination on the
 * rational Hurwitz matrix without row exchanges: D_k = D_{k-1} pivot_k,
 * so all D_k > 0 iff every pivot is > 0 (a zero pivot is D_k = 0: not
 * stable).  Only the coefficients of branch 0 are used (branch 1 is its
 * negation): none of the stated conditions, factors or minors. */
int
rs_hurwitz_or_full_at(const rs_hurwitz_or_t hb, fmpq *const *vals,
                      const fmpz_mpoly_ctx_t ctx)
{
    const rs_hurwitz_struct *h;
    fmpq_mat_t H;
    fmpq *a;
    fmpq_t f, t;
    slong i, j, k, n;
    int res = 1;

    if (hb->nbranch < 1)
        return 0;   /* lambda = -1 or 1 a root for every value */
    h = hb->branch + 0;
    n = h->n;
    a = _fmpq_vec_init(n + 1);
    for (i = 0; i <= n; i++)
        rs_hurwitz_eval(a + i, h->coeffs + i, vals, ctx);
    if (fmpq_is_zero(a + n)) {
        _fmpq_vec_clear(a, n + 1);
        return -1;
    }
    if (fmpq_sgn(a + n) < 0)
        for (i = 0; i <= n; i++)
            fmpq_neg(a + i, a + i);
    fmpq_mat_init(H, n, n);
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            slong idx = n - (2 * (j + 1) - (i + 1));
            if (idx >= 0 && idx <= n)
                fmpq_set(fmpq_mat_entry(H, i, j), a + idx);
        }
    fmpq_init(f);
    fmpq_init(t);
    for (k = 0; k < n && res; k++) {
        if (fmpq_sgn(fmpq_mat_entry(H, k, k)) <= 0) {
            res = 0;
            break;
        }
        for (i = k + 1; i < n; i++) {
            if (fmpq_is_zero(fmpq_mat_entry(H, i, k)))
                continue;
            fmpq_div(f, fmpq_mat_entry(H, i, k), fmpq_mat_entry(H, k, k));
            for (j = k; j < n; j++) {
                fmpq_mul(t, f, fmpq_mat_entry(H, k, j));
                fmpq_sub(fmpq_mat_entry(H, i, j), fmpq_mat_entry(H, i, j), t);
            }
        }
    }
    fmpq_clear(f);
    fmpq_clear(t);
    fmpq_mat_clear(H);
    _fmpq_vec_clear(a, n + 1);
    return res;
}
