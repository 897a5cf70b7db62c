/* bilinear.c -- see include/recstab/bilinear.h
 *
 * q(z) = sum_k p_k (1+z)^k (1-z)^(n-k), computed coefficientwise over Z:
 * no rational function is ever formed. */
#include "recstab/bilinear.h"
#include "recstab/budget.h"
#include <fmpz.h>

void rs_bilinear_fmpz_poly(fmpz_poly_t q, const fmpz_poly_t p)
{
    slong n = fmpz_poly_degree(p), k;
    fmpz_poly_struct *plus, *minus;
    fmpz_poly_t res, t;

    if (n < 0) {
        fmpz_poly_zero(q);
        return;
    }
    plus = flint_malloc((n + 1) * sizeof(fmpz_poly_struct));
    minus = flint_malloc((n + 1) * sizeof(fmpz_poly_struct));
    for (k = 0; k <= n; k++) {
        fmpz_poly_init(plus + k);
        fmpz_poly_init(minus + k);
    }
    /* plus[k] = (1+z)^k, minus[k] = (1-z)^k */
    fmpz_poly_one(plus + 0);
    fmpz_poly_one(minus + 0);
    for (k = 1; k <= n; k++) {
        fmpz_poly_shift_left(plus + k, plus + k - 1, 1);
        fmpz_poly_add(plus + k, plus + k, plus + k - 1);
        fmpz_poly_shift_left(minus + k, minus + k - 1, 1);
        fmpz_poly_sub(minus + k, minus + k - 1, minus + k);
    }

    fmpz_poly_init(res);
    fmpz_poly_init(t);
    for (k = 0; k <= n; k++) {
        if (fmpz_is_zero(p->coeffs + k))
            continue;
        fmpz_poly_mul(t, plus + k, minus + n - k);
        fmpz_poly_scalar_addmul_fmpz(res, t, p->coeffs + k);
    }
    fmpz_poly_swap(q, res);   /* q may alias p: written only now */

    fmpz_poly_clear(res);
    fmpz_poly_clear(t);
    for (k = 0; k <= n; k++) {
        fmpz_poly_clear(plus + k);
        fmpz_poly_clear(minus + k);
    }
    flint_free(plus);
    flint_free(minus);
}

void rs_bilinear_fmpz_mpoly(fmpz_mpoly_t q, const fmpz_mpoly_t p, slong var,
                            const fmpz_mpoly_ctx_t ctx)
{
    slong n = fmpz_mpoly_degree_si(p, var, ctx), k;
    fmpz_mpoly_t res, c, onep, onem, a, b, t;
    ulong e;

    if (n < 0) {
        fmpz_mpoly_zero(q, ctx);
        return;
    }
    fmpz_mpoly_init(res, ctx);
    fmpz_mpoly_init(c, ctx);
    fmpz_mpoly_init(onep, ctx);
    fmpz_mpoly_init(onem, ctx);
    fmpz_mpoly_init(a, ctx);
    fmpz_mpoly_init(b, ctx);
    fmpz_mpoly_init(t, ctx);

    fmpz_mpoly_gen(onep, var, ctx);
    fmpz_mpoly_neg(onem, onep, ctx);
    fmpz_mpoly_add_ui(onep, onep, 1, ctx);    /* 1 + z */
    fmpz_mpoly_add_ui(onem, onem, 1, ctx);    /* 1 - z */

    for (k = 0; k <= n; k++) {
        /* symbolic coefficients make each product large: stop with the
         * budget (its sticky state makes the caller's next check report) */
        if (rs_budget_check(NULL, "the bilinear transform") != RS_OK)
            break;
        e = (ulong) k;
        fmpz_mpoly_get_coeff_vars_ui(c, p, &var, &e, 1, ctx);
        if (fmpz_mpoly_is_zero(c, ctx))
            continue;
        fmpz_mpoly_pow_ui(a, onep, (ulong) k, ctx);
        fmpz_mpoly_pow_ui(b, onem, (ulong) (n - k), ctx);
        fmpz_mpoly_mul(t, a, b, ctx);
        fmpz_mpoly_mul(t, t, c, ctx);
        fmpz_mpoly_add(res, res, t, ctx);
    }
    fmpz_mpoly_swap(q, res, ctx);

    fmpz_mpoly_clear(res, ctx);
    fmpz_mpoly_clear(c, ctx);
    fmpz_mpoly_clear(onep, ctx);
    fmpz_mpoly_clear(onem, ctx);
    fmpz_mpoly_clear(a, ctx);
    fmpz_mpoly_clear(b, ctx);
    fmpz_mpoly_clear(t, ctx);
}

slong rs_bilinear_degree_drop(const fmpz_poly_t p, const fmpz_poly_t q)
{
    if (fmpz_poly_is_zero(p))
        return 0;
    return fmpz_poly_degree(p) - fmpz_poly_degree(q);
}

slong rs_bilinear_zero_mult(const fmpz_poly_t q)
{
    slong i, len = fmpz_poly_length(q);
    for (i = 0; i < len; i++)
        if (!fmpz_is_zero(q->coeffs + i))
            return i;
    return 0;  /* the zero polynomial: no meaningful multiplicity */
}
