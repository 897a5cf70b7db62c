/* positivity.c -- one-sign tests for polynomials in the parameters under the
 * sign assumptions.  See include/recstab/positivity.h.
 *
 * Polya (1928; Hardy, Littlewood, Polya, Inequalities, sec. 2.24): a form F
 * strictly positive on the simplex x >= 0, sum x = 1 has (sum x)^m F with
 * all coefficients positive for m large enough.  We use only the easy
 * direction, which needs no hypothesis: if G = s^m f has every coefficient
 * >= 0 and a monomial > 0 under the assumptions, then f = G / s^m > 0 there,
 * because s > 0 there (s = 1 + sum x, or sum x when some variable of a
 * positive monomial is > 0).  Variables of unknown sign that occur only in
 * even powers become non-negative after exponent reduction (x^2 -> X). */
#include <stdlib.h>
#include "recstab/positivity.h"

/* Classify term i with its coefficient sign replaced by +1: 2 if the
 * monomial is > 0 under sign[], 1 if >= 0, 0 if neither. */
static int
_monomial_class(const fmpz_mpoly_t poly, slong i, const rs_sign_t *sign,
                const fmpz_mpoly_ctx_t ctx)
{
    slong v, nvars = fmpz_mpoly_ctx_nvars(ctx);
    int cls = 2;

    for (v = 0; v < nvars; v++) {
        ulong e = fmpz_mpoly_get_term_var_exp_ui(poly, i, v, ctx);
        rs_sign_t s = sign == NULL ? RS_SIGN_UNKNOWN : sign[v];
        if (e == 0 || s == RS_SIGN_POSITIVE)
            continue;
        if (s == RS_SIGN_NONNEGATIVE || (e % 2) == 0)
            cls = 1;    /* >= 0, but may vanish */
        else
            return 0;   /* odd power of a variable of unknown sign */
    }
    return cls;
}

int
rs_positivity_coeff_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                         const fmpz_mpoly_ctx_t ctx)
{
    slong i, len = fmpz_mpoly_length(poly, ctx);
    int csign = 0, strict = 0;

    if (len == 0 || !fmpz_mpoly_degrees_fit_si(poly, ctx))
        return 0;
    for (i = 0; i < len; i++) {
        int s = fmpz_sgn(poly->coeffs + i), cls;
        if (i == 0)
            csign = s;
        else if (s != csign)
            return 0;
        cls = _monomial_class(poly, i, sign, ctx);
        if (cls == 0)
            return 0;
        if (cls == 2)
            strict = 1;
    }
    return strict ? csign : 0;
}

/* r = poly with every exponent of variable v divided by g[v] (the gcd of
 * its exponents; 0 where v does not occur). */
static void
_reduce_exponents(fmpz_mpoly_t r, const fmpz_mpoly_t poly, const ulong *g,
                  const fmpz_mpoly_ctx_t ctx)
{
    slong i, v, nvars = fmpz_mpoly_ctx_nvars(ctx);
    ulong *e = flint_malloc(nvars * sizeof(ulong));

    fmpz_mpoly_zero(r, ctx);
    for (i = 0; i < fmpz_mpoly_length(poly, ctx); i++) {
        fmpz_mpoly_get_term_exp_ui(e, poly, i, ctx);
        for (v = 0; v < nvars; v++)
            if (g[v] > 1)
                e[v] /= g[v];
        fmpz_mpoly_push_term_fmpz_ui(r, poly->coeffs + i, e, ctx);
    }
    fmpz_mpoly_sort_terms(r, ctx);
    fmpz_mpoly_combine_like_terms(r, ctx);
    flint_free(e);
}

int
rs_positivity_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                   const fmpz_mpoly_ctx_t ctx, slong *power)
{
    slong i, v, m, nvars = fmpz_mpoly_ctx_nvars(ctx), len, deg = -1;
    ulong *g;
    rs_sign_t *sg;
    fmpz_mpoly_t f, s, x;
    fmpz_t sum;
    int res = 0, homogeneous = 1, target, ok = 1;

    if (power != NULL)
        *power = -1;
    res = rs_positivity_coeff_sign(poly, sign, ctx);
    if (res != 0) {
        if (power != NULL)
            *power = 0;
        return res;
    }
    len = fmpz_mpoly_length(poly, ctx);
    if (len < 2 || !fmpz_mpoly_degrees_fit_si(poly, ctx))
        return 0;

    /* the sign Polya could prove: that of f at (1, ..., 1) */
    fmpz_init(sum);
    for (i = 0; i < len; i++)
        fmpz_add(sum, sum, poly->coeffs + i);
    target = fmpz_sgn(sum);
    fmpz_clear(sum);
    if (target == 0)
        return 0;

    g = flint_calloc(nvars, sizeof(ulong));
    sg = flint_malloc(nvars * sizeof(rs_sign_t));
    for (i = 0; i < len; i++)
        for (v = 0; v < nvars; v++)
            g[v] = n_gcd(g[v], fmpz_mpoly_get_term_var_exp_ui(poly, i, v, ctx));
    for (v = 0; v < nvars && ok; v++) {
        sg[v] = sign == NULL ? RS_SIGN_UNKNOWN : sign[v];
        if (g[v] == 0 || sg[v] != RS_SIGN_UNKNOWN)
            continue;
        if (g[v] % 2 == 0)
            sg[v] = RS_SIGN_NONNEGATIVE;   /* x^(2j) -> X^j, X >= 0 */
        else
            ok = 0;                        /* odd power of a free sign */
    }
    if (!ok) {
        flint_free(g);
        flint_free(sg);
        return 0;
    }

    fmpz_mpoly_init(f, ctx);
    fmpz_mpoly_init(s, ctx);
    fmpz_mpoly_init(x, ctx);
    _reduce_exponents(f, poly, g, ctx);
    for (i = 0; i < fmpz_mpoly_length(f, ctx); i++) {
        slong d = 0;
        for (v = 0; v < nvars; v++)
            d += fmpz_mpoly_get_term_var_exp_ui(f, i, v, ctx);
        if (deg >= 0 && d != deg)
            homogeneous = 0;
        deg = d;
    }
    /* s = sum of the variables that occur (+ 1 unless f is a form) */
    if (!homogeneous)
        fmpz_mpoly_one(s, ctx);
    for (v = 0; v < nvars; v++)
        if (g[v] != 0) {
            fmpz_mpoly_gen(x, v, ctx);
            fmpz_mpoly_add(s, s, x, ctx);
        }

    res = 0;
    for (m = 1; m <= RS_POLYA_MAX_POWER; m++) {
        fmpz_mpoly_mul(f, f, s, ctx);
        if (fmpz_mpoly_length(f, ctx) > RS_POLYA_MAX_TERMS)
            break;
        if (rs_positivity_coeff_sign(f, sg, ctx) == target) {
            res = target;
            if (power != NULL)
                *power = m;
            break;
        }
    }
    fmpz_mpoly_clear(f, ctx);
    fmpz_mpoly_clear(s, ctx);
    fmpz_mpoly_clear(x, ctx);
    flint_free(g);
    flint_free(sg);
    return res;
}
