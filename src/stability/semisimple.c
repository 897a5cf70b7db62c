/* semisimple.c -- exact semisimplicity of unit-circle eigenvalues (see
 * semisimple.h for the theorem). */
#include <stdlib.h>
#include <flint/fmpz_poly_factor.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
#include "recstab/semisimple.h"
#include "recstab/rootcount.h"
#include "recstab/charpoly.h"

void rs_semisimple_init(rs_semisimple_t ss)
{
    ss->nfactors = 0;
    ss->f = NULL;
    ss->system = 0;
    ss->all_semisimple = 1;
}

void rs_semisimple_clear(rs_semisimple_t ss)
{
    slong i;
    for (i = 0; i < ss->nfactors; i++)
        fmpz_poly_clear(ss->f[i].factor);
    flint_free(ss->f);
    rs_semisimple_init(ss);
}

/* Gaussian elimination over K = Q[lambda]/(f): f irreducible makes K a field,
 * so a non-zero residue is invertible (extended gcd with f). */
slong rs_semisimple_rank_mod(const fmpq_poly_struct *A, slong n, const fmpz_poly_t f)
{
    fmpq_poly_struct *a;
    fmpq_poly_t F, g, s, t, inv, c;
    slong i, j, col, rank = 0;
    if (n <= 0) return 0;
    a = flint_malloc(n * n * sizeof(fmpq_poly_struct));
    fmpq_poly_init(F); fmpq_poly_init(g); fmpq_poly_init(s); fmpq_poly_init(t);
    fmpq_poly_init(inv); fmpq_poly_init(c);
    fmpq_poly_set_fmpz_poly(F, f);
    for (i = 0; i < n * n; i++) {
        fmpq_poly_init(a + i);
        fmpq_poly_rem(a + i, A + i, F);
    }
    for (col = 0; col < n && rank < n; col++) {
        slong piv = -1;
        for (i = rank; i < n; i++)
            if (!fmpq_poly_is_zero(a + i * n + col)) { piv = i; break; }
        if (piv < 0) continue;
        if (piv != rank)
            for (j = 0; j < n; j++)
                fmpq_poly_swap(a + piv * n + j, a + rank * n + j);
        fmpq_poly_xgcd(g, s, t, a + rank * n + col, F);   /* g = 1 */
        fmpq_poly_div(inv, s, g);
        for (i = rank + 1; i < n; i++) {
            if (fmpq_poly_is_zero(a + i * n + col)) continue;
            fmpq_poly_mul(c, a + i * n + col, inv);
            fmpq_poly_rem(c, c, F);
            for (j = col; j < n; j++) {
                fmpq_poly_mul(t, c, a + rank * n + j);
                fmpq_poly_sub(a + i * n + j, a + i * n + j, t);
                fmpq_poly_rem(a + i * n + j, a + i * n + j, F);
            }
        }
        rank++;
    }
    for (i = 0; i < n * n; i++) fmpq_poly_clear(a + i);
    flint_free(a);
    fmpq_poly_clear(F); fmpq_poly_clear(g); fmpq_poly_clear(s); fmpq_poly_clear(t);
    fmpq_poly_clear(inv); fmpq_poly_clear(c);
    return rank;
}

int rs_semisimple_circle(rs_semisimple_t ss, const fmpq_poly_struct *A, slong n,
                         const fmpz_poly_t p, rs_error_t err)
{
    fmpz_poly_factor_t fac;
    slong i;
    int r = RS_OK;
    rs_semisimple_clear(ss);
    ss->system = (A != NULL && n >= 1);
    if (fmpz_poly_degree(p) < 1) return RS_OK;
    fmpz_poly_factor_init(fac);
    fmpz_poly_factor(fac, p);
    for (i = 0; i < fac->num && r == RS_OK; i++) {
        rs_rootcount_t rc;
        rs_circle_factor_struct *cf;
        rs_rootcount_init(rc);
        r = rs_rootcount_factor(rc, fac->p + i, err);
        if (r == RS_OK && rc->on > 0) {
            ss->f = flint_realloc(ss->f, (ss->nfactors + 1) * sizeof(rs_circle_factor_struct));
            cf = ss->f + ss->nfactors++;
            fmpz_poly_init(cf->factor);
            fmpz_poly_set(cf->factor, fac->p + i);
            cf->mult = fac->exp[i];
            cf->on = rc->on;
            if (cf->mult == 1)
                cf->kernel = 1;   /* 1 <= dim ker <= multiplicity */
            else if (ss->system)
                cf->kernel = n - rs_semisimple_rank_mod(A, n, cf->factor);
            else
                cf->kernel = 1;   /* scalar recurrence: one solution per root */
            /* A(alpha) is singular, and dim ker <= multiplicity always */
            if (cf->kernel < 1 || cf->kernel > cf->mult)
                r = rs_error_set(err, RS_ERR_INCONSISTENT, "semisimplicity test: dim ker A = %ld at a root "
                                 "of multiplicity %ld", (long) cf->kernel, (long) cf->mult);
            cf->semisimple = (cf->kernel == cf->mult);
            if (!cf->semisimple) ss->all_semisimple = 0;
        }
        rs_rootcount_clear(rc);
    }
    fmpz_poly_factor_clear(fac);
    return r;
}

int rs_semisimple_matrix(fmpq_poly_struct *A, const rs_scheme_t s, const slong *vars,
                         const fmpq *vals, slong nv)
{
    fmpq_mpoly_t e;
    slong i, k;
    int ok = 1;
    fmpq_mpoly_init(e, s->ctx);
    for (i = 0; i < s->n * s->n && ok; i++) {
        fmpq_mpoly_set(e, s->M + i, s->ctx);
        for (k = 0; k < nv; k++)
            fmpq_mpoly_evaluate_one_fmpq(e, e, vars[k], vals + k, s->ctx);
        ok = fmpq_mpoly_get_fmpq_poly(A + i, e, s->lambda_var, s->ctx);
    }
    fmpq_mpoly_clear(e, s->ctx);
    return ok;
}

int rs_semisimple_verdict(rs_status_t *st, rs_semisimple_t ss, const rs_scheme_struct *s,
                          const slong *vars, const fmpq *vals, slong nv, const fmpz_poly_t p,
                          const rs_rootcount_struct *rc, int list, rs_error_t err)
{
    int r = RS_OK, needed = rc->outside == 0 && rs_rootcount_max_on_mult(rc) > 1;
    *st = rs_rootcount_status(rc);
    rs_semisimple_clear(ss);
    if (rc->on == 0 || (!needed && !list)) return RS_OK;
    if (s == NULL || s->from_char || s->n < 1) {
        r = rs_semisimple_circle(ss, NULL, 0, p, err);
    } else {
        slong i, n = s->n;
        fmpq_poly_struct *A = flint_malloc(n * n * sizeof(fmpq_poly_struct));
        for (i = 0; i < n * n; i++) fmpq_poly_init(A + i);
        if (rs_semisimple_matrix(A, s, vars, vals, nv))
            r = rs_semisimple_circle(ss, A, n, p, err);
        else
            r = rs_error_set(err, RS_ERR_INTERNAL, "semisimplicity test: a parameter is still symbolic");
        for (i = 0; i < n * n; i++) fmpq_poly_clear(A + i);
        flint_free(A);
    }
    if (r == RS_OK) {
        /* the factorisation counts the circle roots a second time */
        slong i, on = 0;
        for (i = 0; i < ss->nfactors; i++) on += ss->f[i].on * ss->f[i].mult;
        if (on != rc->on)
            r = rs_error_set(err, RS_ERR_INCONSISTENT, "%ld roots on the circle by factorisation, %ld by the "
                             "exact count", (long) on, (long) rc->on);
    }
    if (r == RS_OK && needed)
        *st = ss->all_semisimple ? RS_STATUS_MARGINAL : RS_STATUS_UNSTABLE;
    return r;
}

/* a = prem(a, f) in lambda: lc(f)^k a reduced below deg_lambda f (f's leading
 * coefficient is a polynomial in the other variables). */
static void prem_lambda(fmpz_mpoly_t a, const fmpz_mpoly_t f, slong lv, const fmpz_mpoly_ctx_t ctx)
{
    slong df = fmpz_mpoly_degree_si(f, lv, ctx), da;
    fmpz_mpoly_t lf, la, t;
    ulong e;
    fmpz_mpoly_init(lf, ctx); fmpz_mpoly_init(la, ctx); fmpz_mpoly_init(t, ctx);
    e = (ulong) df;
    fmpz_mpoly_get_coeff_vars_ui(lf, f, &lv, &e, 1, ctx);
    while (!fmpz_mpoly_is_zero(a, ctx) && (da = fmpz_mpoly_degree_si(a, lv, ctx)) >= df) {
        ulong *ex = flint_calloc(ctx->minfo->nvars, sizeof(ulong));
        e = (ulong) da;
        fmpz_mpoly_get_coeff_vars_ui(la, a, &lv, &e, 1, ctx);
        ex[lv] = (ulong) (da - df);
        fmpz_mpoly_mul(a, a, lf, ctx);
        fmpz_mpoly_mul(t, la, f, ctx);
        {
            fmpz_mpoly_t m;
            fmpz_t one;
            fmpz_mpoly_init(m, ctx);
            fmpz_init_set_ui(one, 1);
            fmpz_mpoly_set_coeff_fmpz_ui(m, one, ex, ctx);   /* lambda^(da-df) */
            fmpz_mpoly_mul(t, t, m, ctx);
            fmpz_mpoly_clear(m, ctx);
            fmpz_clear(one);
        }
        fmpz_mpoly_sub(a, a, t, ctx);
        flint_free(ex);
    }
    fmpz_mpoly_clear(lf, ctx); fmpz_mpoly_clear(la, ctx); fmpz_mpoly_clear(t, ctx);
}

/* Where rank_generic puts its multipliers: univariate polynomials in tv
 * (u != NULL), or the polynomials themselves in every parameter (m != NULL). */
typedef struct {
    fmpz_poly_struct **u;
    slong *nu;
    fmpz_mpoly_struct **m;
    slong *nm;
    slong tv;
} drop_sink_t;

/* Appends R (if non-zero and non-constant; for u: a polynomial in tv only)
 * to the sink's list. */
static void push_tpoly(const drop_sink_t *out, const fmpz_mpoly_t R, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_poly_t u;
    if (out->m != NULL) {
        if (fmpz_mpoly_is_zero(R, ctx) || fmpz_mpoly_is_fmpz(R, ctx)) return;
        *out->m = flint_realloc(*out->m, (*out->nm + 1) * sizeof(fmpz_mpoly_struct));
        fmpz_mpoly_init(*out->m + *out->nm, ctx);
        fmpz_mpoly_set(*out->m + *out->nm, R, ctx);
        (*out->nm)++;
        return;
    }
    fmpz_poly_init(u);
    if (!fmpz_mpoly_is_zero(R, ctx) && fmpz_mpoly_get_fmpz_poly(u, R, out->tv, ctx) && fmpz_poly_degree(u) >= 1) {
        *out->u = flint_realloc(*out->u, (*out->nu + 1) * sizeof(fmpz_poly_struct));
        fmpz_poly_init(*out->u + *out->nu);
        fmpz_poly_swap(*out->u + *out->nu, u);
        (*out->nu)++;
    }
    fmpz_poly_clear(u);
}

/* The elimination multiplier m vanishes at a root of f for t where
 * Res_lambda(m, f)(t) = 0 (or lc(f)(t) = 0, recorded separately). */
static void push_multiplier(const drop_sink_t *out, const fmpz_mpoly_t m, const fmpz_mpoly_t f, slong lv,
                            const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t R;
    fmpz_mpoly_init(R, ctx);
    if (fmpz_mpoly_degree_si(m, lv, ctx) <= 0)
        fmpz_mpoly_set(R, m, ctx);
    else if (!fmpz_mpoly_resultant(R, m, f, lv, ctx))
        fmpz_mpoly_zero(R, ctx);
    push_tpoly(out, R, ctx);
    fmpz_mpoly_clear(R, ctx);
}

/* Fraction-free elimination of A modulo f (irreducible in Z[params, lambda],
 * positive degree in lambda) over the domain Z[params, lambda]/(f): a reduced
 * non-zero entry is non-zero in the fraction field Q(params)[lambda]/(f), so
 * the number of pivots is the rank over that field.  With out != NULL the
 * multipliers used (pivots, row contents, lc(f)) are turned into polynomials
 * in tv whose roots hold every value where the rank at a point can drop. */
static slong rank_generic(const drop_sink_t *out, const rs_scheme_t s, const fmpz_mpoly_t f)
{
    const fmpz_mpoly_ctx_struct *ctx = s->zctx;
    slong n = s->n, lv = s->lambda_var, i, j, col, rank = 0;
    fmpz_mpoly_struct *a;
    fmpz_mpoly_t t, g, lf;
    ulong e;
    a = flint_malloc(n * n * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_init(t, ctx); fmpz_mpoly_init(g, ctx); fmpz_mpoly_init(lf, ctx);
    e = (ulong) fmpz_mpoly_degree_si(f, lv, ctx);
    fmpz_mpoly_get_coeff_vars_ui(lf, f, &lv, &e, 1, ctx);
    if (out != NULL) push_tpoly(out, lf, ctx);
    for (i = 0; i < n * n; i++) fmpz_mpoly_init(a + i, ctx);
    for (i = 0; i < n; i++) {
        /* row i over Z (scaled by a unit), reduced modulo f */
        fmpz_t L;
        fmpz_init(L);
        rs_charpoly_row_to_fmpz(a + i * n, L, s->M + i * n, n, s->ctx);
        for (j = 0; j < n; j++) prem_lambda(a + i * n + j, f, lv, ctx);
        fmpz_clear(L);
    }
    for (col = 0; col < n && rank < n; col++) {
        slong piv = -1;
        for (i = rank; i < n; i++)
            if (!fmpz_mpoly_is_zero(a + i * n + col, ctx)) { piv = i; break; }
        if (piv < 0) continue;
        if (piv != rank)
            for (j = 0; j < n; j++) fmpz_mpoly_swap(a + piv * n + j, a + rank * n + j, ctx);
        if (out != NULL) push_multiplier(out, a + rank * n + col, f, lv, ctx);
        for (i = rank + 1; i < n; i++) {
            if (fmpz_mpoly_is_zero(a + i * n + col, ctx)) continue;
            fmpz_mpoly_set(g, a + i * n + col, ctx);
            for (j = col; j < n; j++) {
                fmpz_mpoly_mul(a + i * n + j, a + i * n + j, a + rank * n + col, ctx);
                fmpz_mpoly_mul(t, g, a + rank * n + j, ctx);
                fmpz_mpoly_sub(a + i * n + j, a + i * n + j, t, ctx);
                prem_lambda(a + i * n + j, f, lv, ctx);
            }
            /* keep sizes down: divide the row by the gcd of its entries
             * (a multiplier too: it may vanish at special values) */
            fmpz_mpoly_zero(g, ctx);
            for (j = col; j < n; j++) fmpz_mpoly_gcd(g, g, a + i * n + j, ctx);
            if (!fmpz_mpoly_is_zero(g, ctx) && !fmpz_mpoly_is_fmpz(g, ctx)) {
                for (j = col; j < n; j++) fmpz_mpoly_divexact(a + i * n + j, a + i * n + j, g, ctx);
                if (out != NULL) push_multiplier(out, g, f, lv, ctx);
            }
        }
        rank++;
    }
    for (i = 0; i < n * n; i++) fmpz_mpoly_clear(a + i, ctx);
    flint_free(a);
    fmpz_mpoly_clear(t, ctx); fmpz_mpoly_clear(g, ctx); fmpz_mpoly_clear(lf, ctx);
    return rank;
}

int rs_semisimple_rank_drops(fmpz_poly_struct **out, slong *nout, const rs_scheme_t s, slong tv,
                             const fmpz_mpoly_t f)
{
    drop_sink_t sink = {out, nout, NULL, NULL, tv};
    if (s->n < 1 || s->from_char) return RS_OK;
    rank_generic(&sink, s, f);
    return RS_OK;
}

int rs_semisimple_rank_drops_mpoly(fmpz_mpoly_struct **out, slong *nout, const rs_scheme_t s,
                                   const fmpz_mpoly_t f)
{
    drop_sink_t sink = {NULL, NULL, out, nout, -1};
    if (s->n < 1 || s->from_char) return RS_OK;
    rank_generic(&sink, s, f);
    return RS_OK;
}

int rs_semisimple_generic(int *all, const rs_scheme_t s, const fmpz_mpoly_t p)
{
    fmpz_mpoly_factor_t fac;
    slong k;
    *all = 1;
    fmpz_mpoly_factor_init(fac, s->zctx);
    if (!fmpz_mpoly_factor(fac, p, s->zctx)) {
        fmpz_mpoly_factor_clear(fac, s->zctx);
        return RS_ERR_LIMIT;
    }
    for (k = 0; k < fac->num && *all; k++) {
        fmpz_mpoly_struct *f = fac->poly + k;
        slong e;
        if (fmpz_mpoly_degree_si(f, s->lambda_var, s->zctx) < 1 || fmpz_cmp_ui(fac->exp + k, 2) < 0) continue;
        e = fmpz_get_si(fac->exp + k);
        if (s->from_char || s->n < 1 || s->n - rank_generic(NULL, s, f) != e) *all = 0;
    }
    fmpz_mpoly_factor_clear(fac, s->zctx);
    return RS_OK;
}
