/* charpoly.c -- fraction-free determinant and normalisation. */
#include <string.h>
#include <flint/fmpz_vec.h>
#include "recstab/budget.h"
#include "recstab/charpoly.h"

void rs_charpoly_init(rs_charpoly_t cp, const rs_scheme_t s)
{
    fmpz_mpoly_init(cp->p, s->zctx);
    fmpz_mpoly_init(cp->param_content, s->zctx);
    fmpq_init(cp->content);
    cp->degree = 0;
    cp->removed_lambda_power = 0;
}

void rs_charpoly_clear(rs_charpoly_t cp, const rs_scheme_t s)
{
    fmpz_mpoly_clear(cp->p, s->zctx);
    fmpz_mpoly_clear(cp->param_content, s->zctx);
    fmpq_clear(cp->content);
}

void rs_charpoly_fmpq_to_fmpz(fmpz_mpoly_t out, fmpq_t scale, const fmpq_mpoly_t q,
                              const fmpq_mpoly_ctx_t ctx)
{
    /* q = content * zpoly with zpoly primitive */
    fmpz_mpoly_set(out, q->zpoly, ctx->zctx);
    if (fmpq_is_zero(q->content))
        fmpq_one(scale);
    else
        fmpq_inv(scale, q->content);
}

void rs_charpoly_coeff(fmpz_mpoly_t c, const fmpz_mpoly_t p, slong k,
                       slong lambda_var, const fmpz_mpoly_ctx_t ctx)
{
    ulong kk = (ulong) k;
    fmpz_mpoly_get_coeff_vars_ui(c, p, &lambda_var, &kk, 1, ctx);
}

slong rs_charpoly_normalise(fmpz_mpoly_t q, fmpq_t scale, slong lambda_var,
                            const fmpz_mpoly_ctx_t ctx)
{
    slong k, d;
    fmpz_t g;
    fmpz_mpoly_t lc, m;
    if (fmpz_mpoly_is_zero(q, ctx))
        return 0;
    k = rs_scheme_min_degree(q, lambda_var, ctx);
    if (k > 0) {
        fmpz_mpoly_init(m, ctx);
        fmpz_mpoly_gen(m, lambda_var, ctx);
        fmpz_mpoly_pow_ui(m, m, (ulong) k, ctx);
        fmpz_mpoly_divexact(q, q, m, ctx);
        fmpz_mpoly_clear(m, ctx);
    }
    fmpz_init(g);
    _fmpz_vec_content(g, q->coeffs, q->length);
    d = fmpz_mpoly_degree_si(q, lambda_var, ctx);
    fmpz_mpoly_init(lc, ctx);
    rs_charpoly_coeff(lc, q, d, lambda_var, ctx);
    if (fmpz_sgn(lc->coeffs + 0) < 0)
        fmpz_neg(g, g);
    if (!fmpz_is_one(g))
        fmpz_mpoly_scalar_divexact_fmpz(q, q, g, ctx);
    if (scale != NULL)
        fmpq_mul_fmpz(scale, scale, g);
    fmpz_mpoly_clear(lc, ctx);
    fmpz_clear(g);
    return k;
}

/* Upper bound on the terms of a*b: the smallest of len(a)*len(b), the number
 * of monomials in the box of the summed degrees and the number of monomials
 * of at most the summed total degree. */
#define RS_CHARPOLY_RYSER_MAX 20   /* exact permanents of minors up to this size */

static double prod_terms_bound(const fmpz_mpoly_t a, const fmpz_mpoly_t b, const fmpz_mpoly_ctx_t ctx)
{
    double box = 1.0, pairs = (double) fmpz_mpoly_length(a, ctx) * (double) fmpz_mpoly_length(b, ctx);
    slong v;
    if (pairs == 0.0)
        return 0.0;
    double simplex = 1.0, D = (double) fmpz_mpoly_total_degree_si(a, ctx)
                              + (double) fmpz_mpoly_total_degree_si(b, ctx);
    for (v = 0; v < ctx->minfo->nvars; v++) {
        box *= (double) fmpz_mpoly_degree_si(a, v, ctx) + (double) fmpz_mpoly_degree_si(b, v, ctx) + 1.0;
        simplex = simplex * (D + (double) (v + 1)) / (double) (v + 1);   /* C(D + nvars, nvars) */
    }
    if (simplex < box) box = simplex;
    return box < pairs ? box : pairs;
}

/* Permanent of the m x m non-negative matrix L (row stride ld, columns
 * cols[0..m-1]) by Ryser's formula, O(2^m m): the number of products in the
 * Leibniz expansion, an upper bound on the terms of the minor. */
static double permanent(const double *L, slong ld, const slong *rows, const slong *cols, slong m)
{
    long double total = 0, rowsum[RS_CHARPOLY_RYSER_MAX];
    ulong S, gray = 0;
    slong i;
    for (i = 0; i < m; i++) rowsum[i] = 0;
    for (S = 1; S < (UWORD(1) << m); S++) {
        /* Gray code: one column enters or leaves the subset */
        ulong g = S ^ (S >> 1), diff = g ^ gray;
        slong c = (slong) __builtin_ctzl(diff);
        long double prod = 1, sgn = ((m - (slong) __builtin_popcountl(g)) % 2) ? -1 : 1;
        int enter = (g & diff) != 0;
        gray = g;
        for (i = 0; i < m; i++) {
            rowsum[i] += (enter ? 1 : -1) * L[rows[i] * ld + cols[c]];
            prod *= rowsum[i];
        }
        total += sgn * prod;
    }
    return total > 0 ? (double) total : 0.0;
}

/* Before the elimination: the last Bareiss step multiplies two (n-1)-minors,
 * whose terms are at most the permanent of their term counts and at most
 * the monomials of their degrees.  Refused up front when that bound passes
 * the limit the loop below would stop at after the expensive steps (8
 * generic unknowns took 12 s and 580 MB to be refused). */
static int det_estimate(const fmpz_mpoly_struct *A, slong n, slong max_terms, const fmpz_mpoly_ctx_t ctx,
                        rs_error_t err)
{
    slong nv = ctx->minfo->nvars, v, i, j, k, D = 0;
    double box = 1.0, simplex = 1.0, worst = 0.0, bound, *L;
    slong rows[RS_CHARPOLY_RYSER_MAX], cols[RS_CHARPOLY_RYSER_MAX];
    if (n < 3) return RS_OK;
    /* degrees of an (n-1)-minor: at most the sum over rows of the row's largest degree */
    for (v = 0; v < nv; v++) {
        slong dv = 0;
        for (i = 0; i < n; i++) {
            slong m = 0;
            for (j = 0; j < n; j++) m = FLINT_MAX(m, fmpz_mpoly_degree_si(A + i * n + j, v, ctx));
            dv += m;
        }
        box *= 2.0 * (double) dv + 1.0;   /* a product of two minors */
    }
    for (i = 0; i < n; i++) {
        slong m = 0;
        for (j = 0; j < n; j++) m = FLINT_MAX(m, fmpz_mpoly_total_degree_si(A + i * n + j, ctx));
        D += m;
    }
    for (v = 0; v < nv; v++) simplex = simplex * (2.0 * (double) D + (double) (v + 1)) / (double) (v + 1);
    bound = FLINT_MIN(box, simplex);
    if (bound <= 50.0 * (double) max_terms || n - 1 > RS_CHARPOLY_RYSER_MAX) return RS_OK;
    L = flint_malloc(n * n * sizeof(double));
    for (i = 0; i < n * n; i++) L[i] = (double) fmpz_mpoly_length(A + i, ctx);
    for (i = 0; i < n; i++)
        for (j = 0; j < n; j++) {
            slong a = 0, b = 0;
            double p;
            if (L[i * n + j] == 0) continue;   /* the minor is not a pivot's partner */
            for (k = 0; k < n; k++) {
                if (k != i) rows[a++] = k;
                if (k != j) cols[b++] = k;
            }
            p = permanent(L, n, rows, cols, n - 1);
            worst = FLINT_MAX(worst, p);
        }
    flint_free(L);
    bound = FLINT_MIN(bound, worst * worst);
    if (bound > 50.0 * (double) max_terms)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "term limit exceeded: the determinant's intermediate products could have about %.3g "
                            "terms (estimated before the elimination from the matrix's shape and terms; limit %ld); "
                            "set more parameters to numbers", bound, (long) (50 * max_terms));
    return RS_OK;
}

int rs_charpoly_det(fmpz_mpoly_t det, fmpz_mpoly_struct *A, slong n,
                    slong max_terms, const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    slong i, j, k;
    int sign = 1;
    fmpz_mpoly_t prev, t;
    if (n == 0) {
        fmpz_mpoly_one(det, ctx);
        return RS_OK;
    }
    if (det_estimate(A, n, max_terms, ctx, err) != RS_OK)
        return RS_ERR_LIMIT;
    fmpz_mpoly_init(prev, ctx);
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_one(prev, ctx);
    for (k = 0; k < n - 1; k++) {
        /* pivot: the non-zero entry in column k with the fewest terms */
        slong best = -1;
        for (i = k; i < n; i++) {
            if (fmpz_mpoly_is_zero(A + i * n + k, ctx)) continue;
            if (best < 0 || fmpz_mpoly_length(A + i * n + k, ctx) < fmpz_mpoly_length(A + best * n + k, ctx))
                best = i;
        }
        if (best < 0) {
            fmpz_mpoly_zero(det, ctx);
            goto done;
        }
        if (best != k) {
            for (j = 0; j < n; j++)
                fmpz_mpoly_swap(A + k * n + j, A + best * n + j, ctx);
            sign = -sign;
        }
        for (i = k + 1; i < n; i++) {
            int rb = rs_budget_check(err, "the determinant");
            double sec;
            if (rb != RS_OK) {
                fmpz_mpoly_clear(prev, ctx); fmpz_mpoly_clear(t, ctx);
                return rb;
            }
            for (j = k + 1; j < n; j++) {
                fmpz_mpoly_struct *aij = A + i * n + j;
                double b1 = prod_terms_bound(A + k * n + k, aij, ctx);
                double b2 = prod_terms_bound(A + i * n + k, A + k * n + j, ctx);
                /* the products are divided by prev afterwards, so only refuse
                 * products far beyond the limit (they would exhaust memory) */
                if (b1 > 50.0 * (double) max_terms || b2 > 50.0 * (double) max_terms) {
                    fmpz_mpoly_clear(prev, ctx); fmpz_mpoly_clear(t, ctx);
                    return rs_error_set(err, RS_ERR_LIMIT,
                                        "term limit exceeded: an intermediate product of the determinant could "
                                        "have %.0f terms (limit %ld); set more parameters to numbers",
                                        b1 > b2 ? b1 : b2, (long) (50 * max_terms));
                }
                /* FLINT's products cannot be interrupted: refuse them when they would not
                 * fit into what is left of the time budget (a fuzzed degree-59 p conj(p));
                 * the clock is read only for products that could matter (> 10 ms) */
                sec = rs_budget_mpoly_mul_seconds(A + k * n + k, aij)
                      + rs_budget_mpoly_mul_seconds(A + i * n + k, A + k * n + j);
                rb = sec > 0.01 ? rs_budget_estimate(err, "the products of the determinant", sec, 0.0) : RS_OK;
                if (rb != RS_OK) {
                    fmpz_mpoly_clear(prev, ctx); fmpz_mpoly_clear(t, ctx);
                    return rb;
                }
                fmpz_mpoly_mul(t, A + k * n + k, aij, ctx);
                fmpz_mpoly_mul(aij, A + i * n + k, A + k * n + j, ctx);
                fmpz_mpoly_sub(aij, t, aij, ctx);
                if (!fmpz_mpoly_divides(aij, aij, prev, ctx)) {
                    fmpz_mpoly_clear(prev, ctx); fmpz_mpoly_clear(t, ctx);
                    return rs_error_set(err, RS_ERR_INTERNAL, "Bareiss division not exact");
                }
                if (fmpz_mpoly_length(aij, ctx) > max_terms) {
                    fmpz_mpoly_clear(prev, ctx); fmpz_mpoly_clear(t, ctx);
                    return rs_error_set(err, RS_ERR_LIMIT,
                                        "term limit exceeded: an intermediate determinant has %ld terms "
                                        "(limit %ld); set more parameters to numbers", 
                                        (long) fmpz_mpoly_length(aij, ctx), (long) max_terms);
                }
            }
            fmpz_mpoly_zero(A + i * n + k, ctx);
        }
        fmpz_mpoly_set(prev, A + k * n + k, ctx);
    }
    fmpz_mpoly_set(det, A + (n - 1) * n + (n - 1), ctx);
    if (sign < 0) fmpz_mpoly_neg(det, det, ctx);
done:
    fmpz_mpoly_clear(prev, ctx);
    fmpz_mpoly_clear(t, ctx);
    return RS_OK;
}

void rs_charpoly_row_to_fmpz(fmpz_mpoly_struct *out, fmpz_t L, const fmpq_mpoly_struct *row, slong n,
                             const fmpq_mpoly_ctx_t ctx)
{
    slong j;
    fmpz_t c;
    fmpz_init(c);
    fmpz_one(L);
    for (j = 0; j < n; j++)
        fmpz_lcm(L, L, fmpq_denref(row[j].content));
    for (j = 0; j < n; j++) {
        fmpz_divexact(c, L, fmpq_denref(row[j].content));
        fmpz_mul(c, c, fmpq_numref(row[j].content));
        fmpz_mpoly_scalar_mul_fmpz(out + j, row[j].zpoly, c, ctx->zctx);
    }
    fmpz_clear(c);
}

int rs_charpoly_compute(rs_charpoly_t cp, const rs_scheme_t s, rs_error_t err)
{
    const fmpz_mpoly_ctx_struct *zctx = s->zctx;
    fmpq_t scale;   /* det(M) = raw / scale */
    int r = RS_OK;
    fmpq_init(scale);
    fmpq_one(scale);
    if (s->from_char) {
        rs_charpoly_fmpq_to_fmpz(cp->p, scale, s->charpoly, s->ctx);
    } else {
        slong i, n = s->n;
        fmpz_mpoly_struct *A = flint_malloc(n * n * sizeof(fmpz_mpoly_struct));
        for (i = 0; i < n * n; i++) fmpz_mpoly_init(A + i, zctx);
        for (i = 0; i < n; i++) {
            fmpz_t L;
            fmpz_init(L);
            rs_charpoly_row_to_fmpz(A + i * n, L, s->M + i * n, n, s->ctx);
            fmpq_mul_fmpz(scale, scale, L);
            fmpz_clear(L);
        }
        r = rs_charpoly_det(cp->p, A, n, RS_CHARPOLY_MAX_TERMS, zctx, err);
        if (r == RS_OK) rs_scheme_reduce_sqrt(cp->p, s);   /* over Q(sqrt d): p0 + sqrt(d) p1 */
        for (i = 0; i < n * n; i++) fmpz_mpoly_clear(A + i, zctx);
        flint_free(A);
    }
    if (r == RS_OK && fmpz_mpoly_is_zero(cp->p, zctx))
        r = rs_error_set(err, RS_ERR_MATH,
                         "the determinant of the lambda-matrix is identically zero: the equations "
                         "are dependent (singular scheme)");
    if (r == RS_OK) {
        /* every analysis prints or transforms these coefficients: refuse a
         * polynomial whose decimal form alone would be tens of megabytes */
        slong i, len = fmpz_mpoly_length(cp->p, zctx);
        double bits = 0;
        for (i = 0; i < len; i++) bits += (double) fmpz_bits(cp->p->coeffs + i);
        if (bits > (double) RS_CHARPOLY_MAX_BITS)
            r = rs_error_set(err, RS_ERR_LIMIT, "the characteristic polynomial's coefficients hold %.0f bits in "
                             "all (limit %ld, about 20 million digits): give the parameters smaller values",
                             bits, (long) RS_CHARPOLY_MAX_BITS);
    }
    if (r == RS_OK) {
        fmpq_t g;
        fmpq_init(g);
        fmpq_one(g);
        cp->removed_lambda_power = rs_charpoly_normalise(cp->p, g, s->lambda_var, zctx);
        /* raw = g * p * lambda^k ; det = raw / scale */
        fmpq_div(cp->content, g, scale);
        cp->degree = fmpz_mpoly_degree_si(cp->p, s->lambda_var, zctx);
        {
            slong v = s->lambda_var;
            if (!fmpz_mpoly_content_vars(cp->param_content, cp->p, &v, 1, zctx))
                fmpz_mpoly_one(cp->param_content, zctx);
        }
        fmpq_clear(g);
    }
    fmpq_clear(scale);
    return r;
}

int rs_charpoly_get_fmpz_poly(fmpz_poly_t out, const fmpz_mpoly_t p, slong lambda_var,
                              const fmpz_mpoly_ctx_t ctx)
{
    slong v;
    for (v = 0; v < ctx->minfo->nvars; v++)
        if (v != lambda_var && fmpz_mpoly_degree_si(p, v, ctx) > 0)
            return 0;
    return fmpz_mpoly_get_fmpz_poly(out, p, lambda_var, ctx);
}
