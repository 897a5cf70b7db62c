/* outer.c -- what the certified root balls of a radius say beyond rho.
 *
 * rs_radius_count_balls: the count of the verdict read off the balls.  At
 * degree 500 the exact Routh array costs 15-45 s while the balls are already
 * there; when each of them lies strictly inside or strictly outside the
 * unit circle they count the roots rigorously, and the caller checks that
 * count against Schur-Cohn (an exact method on other arithmetic). */
#include "recstab/budget.h"
#include "recstab/radius.h"

int rs_radius_count_balls(slong *inside, slong *outside, const rs_radius_t r, slong degree)
{
    slong i, in = 0, out = 0, prec = FLINT_MAX(r->prec, 64);
    arb_t a, one;
    int ok = 1;

    /* only isolating balls, one per root with multiplicity: a cluster ball
     * repeated k times would do as well, but is left to the exact side */
    if (!r->isolated || r->roots == NULL || r->nroots != degree || degree < 1)
        return 0;
    arb_init(a);
    arb_init(one);
    arb_one(one);
    for (i = 0; i < r->nroots && ok; i++) {
        /* at the ball's own precision: a refined ball (rs_radius_refine_circle)
         * may be finer than r->prec */
        acb_abs(a, r->roots + i, FLINT_MAX(prec, acb_bits(r->roots + i) + 32));
        if (arb_lt(a, one))
            in++;
        else if (arb_gt(a, one))
            out++;
        else
            ok = 0;   /* this ball meets the circle: the balls decide nothing */
    }
    arb_clear(a);
    arb_clear(one);
    if (!ok)
        return 0;
    *inside = in;
    *outside = out;
    return 1;
}

/* rs_radius_schur_count: the classical Schur-Cohn table
 *   f_{k+1} = f_k(0) f_k - lc(f_k) f_k*   (f_k* reversed at nominal degree)
 * in real balls.  Each row ball holds a positive multiple of the exact
 * integer row (the rescalings are exact powers of 2), so a constant term
 * certified non-zero has the exact row's sign.  When every one is, no root
 * lies on the circle (a circle root, or a pair r, 1/r, of f_k is one of
 * f_{k+1}, down to the non-zero constant) and Rouche on the circle gives
 * in(f_k) = in(f_{k+1}) if f_{k+1}(0) > 0, else deg f_k - in(f_{k+1})
 * (nominal degrees: a vanishing leading coefficient is a root at infinity,
 * outside, of f_k and one at 0, inside, of f_k*).  The same count as
 * jury.c's integer table, whose constant terms have the same signs.
 * The precision needed is the table's conditioning, not the coefficients'
 * size (Wilkinson-type degree 200, 1500-bit coefficients: 2048 bits, where
 * the exact minors need 10 769 word primes); a failed attempt says at which
 * row it lost the sign, and the next precision is extrapolated from it. */
static int schur_count_prec(slong *inside, slong *rows, const fmpz_poly_t p, slong prec, rs_error_t err)
{
    slong n = fmpz_poly_degree(p), m, i, e, in;
    arb_ptr f = _arb_vec_init(n + 1);
    arb_t u, v, sc, tl;
    signed char *neg = flint_calloc(n + 1, 1);
    int ok = 1, st = RS_OK;
    arb_init(u);
    arb_init(v);
    arb_init(sc);
    arb_init(tl);
    for (i = 0; i <= n; i++)
        arb_set_round_fmpz(f + i, p->coeffs + i, prec);
    *rows = 0;
    for (m = n; m >= 1 && ok; m--) {
        arb_set(sc, f + 0);
        arb_set(tl, f + m);
        /* (f_i, f_{m-i}) -> (sc f_i - tl f_{m-i}, sc f_{m-i} - tl f_i) in
         * place; f_m becomes 0 and is dropped */
        for (i = 0; 2 * i < m; i++) {
            arb_mul(u, sc, f + i, prec);
            arb_submul(u, tl, f + m - i, prec);
            arb_mul(v, sc, f + m - i, prec);
            arb_submul(v, tl, f + i, prec);
            arb_swap(f + i, u);
            arb_swap(f + m - i, v);
        }
        if (2 * i == m) {
            arb_sub(u, sc, tl, prec);
            arb_mul(f + i, f + i, u, prec);
        }
        if (arb_is_negative(f + 0))
            neg[m - 1] = 1;
        else if (!arb_is_positive(f + 0))
            ok = 0;              /* sign lost (or zero: singular, exact side) */
        if (!ok)
            break;
        (*rows)++;
        /* exact rescaling by 2^-e keeps the exponents small */
        e = arf_abs_bound_lt_2exp_si(arb_midref(f + 0));
        if (e != -ARF_PREC_EXACT && e != ARF_PREC_EXACT)
            for (i = 0; i < m; i++)
                arb_mul_2exp_si(f + i, f + i, -e);
        if ((m & 15) == 0 && (st = rs_budget_check(err, "the Schur-Cohn table in ball arithmetic")) != RS_OK)
            ok = 0;
    }
    if (ok) {
        /* bottom-up from the constant row (nominal degree 0, no root) */
        for (in = 0, m = 1; m <= n; m++)
            if (neg[m - 1])
                in = m - in;
        *inside = in;
    }
    _arb_vec_clear(f, n + 1);
    flint_free(neg);
    arb_clear(u);
    arb_clear(v);
    arb_clear(sc);
    arb_clear(tl);
    return st != RS_OK ? -1 : ok;
}

int rs_radius_schur_count(int *decided, slong *inside, slong *prec_used, const fmpz_poly_t p,
                          slong max_prec, rs_error_t err)
{
    slong n = fmpz_poly_degree(p), prec = 128, rows = 0, in = 0, next;
    int r;
    *decided = 0;
    *prec_used = 0;
    if (n < 1)
        return RS_OK;
    while (prec <= max_prec) {
        r = schur_count_prec(&in, &rows, p, prec, err);
        if (r < 0)
            return RS_ERR_LIMIT;
        if (r > 0) {
            *decided = 1;
            *inside = in;
            *prec_used = prec;
            return RS_OK;
        }
        if (rows == 0 && prec >= 512)
            break;   /* a first constant term that no precision separates: 0 */
        /* the loss grows about linearly along the rows (random degree 500:
         * rows 57, 120, 253, 472 of 500 at 128 .. 1024 bits): extrapolate */
        next = (slong) (1.3 * (double) prec * (double) n / (double) FLINT_MAX(rows, 1));
        next = FLINT_MAX(next, prec + prec / 2);
        prec = ((next + 63) / 64) * 64;
    }
    return RS_OK;
}

/* rs_radius_outer_refine: the radius needs only the roots of largest
 * modulus to the requested digits.  The caller has certified every root of
 * f at a low precision (isolating balls E); here the roots whose ball may
 * hold the largest modulus are refined by Newton's iteration on midpoints
 * at prec, and then all d balls are certified again, once, by Arb's
 * inclusion test at prec (_acb_poly_validate_roots: the other roots keep
 * their low-precision midpoints, so their balls stay coarse).  One O(d^2)
 * validation at prec replaces dozens of Durand-Kerner sweeps there. */
int rs_radius_outer_refine(acb_ptr E, slong *nouter, const fmpz_poly_t f, slong prec)
{
    slong d = fmpz_poly_degree(f), i, k, ncand = 0;
    char *cand = flint_calloc(d, 1);
    acb_ptr R = _acb_vec_init(d);
    acb_poly_t P;
    acb_t y, dy, c;
    arb_t a;
    arf_t M, lb, ub;
    mag_t mc, mr;
    int ok = 0;

    acb_poly_init(P);
    acb_init(y);
    acb_init(dy);
    acb_init(c);
    arb_init(a);
    arf_init(M);
    arf_init(lb);
    arf_init(ub);
    mag_init(mc);
    mag_init(mr);
    /* M = the largest lower bound of a modulus: a ball wholly below M
     * cannot hold the largest root */
    arf_zero(M);
    for (i = 0; i < d; i++) {
        acb_abs(a, E + i, MAG_BITS * 2);
        arb_get_lbound_arf(lb, a, MAG_BITS * 2);
        if (arf_cmp(lb, M) > 0)
            arf_set(M, lb);
    }
    for (i = 0; i < d; i++) {
        acb_abs(a, E + i, MAG_BITS * 2);
        arb_get_ubound_arf(ub, a, MAG_BITS * 2);
        cand[i] = arf_cmp(ub, M) >= 0;
        ncand += cand[i];
    }
    /* roots all on one circle (lambda^n - c): nothing to save */
    if (ncand > d / 4)
        goto cleanup;
    acb_poly_set_fmpz_poly(P, f, prec);
    for (i = 0; i < d; i++) {
        acb_get_mid(R + i, E + i);
        if (!cand[i])
            continue;
        /* quadratic convergence from ~60 correct bits: a few steps */
        for (k = 0; k < 24; k++) {
            _acb_poly_evaluate2(y, dy, P->coeffs, d + 1, R + i, prec);
            if (acb_contains_zero(dy))
                goto cleanup;
            acb_div(c, y, dy, prec);
            acb_get_mid(c, c);
            acb_sub(R + i, R + i, c, prec);
            acb_get_mid(R + i, R + i);
            /* stop once the step is below the last bits of R_i */
            acb_get_mag(mc, c);
            acb_get_mag_lower(mr, R + i);
            mag_mul_2exp_si(mr, mr, 16 - prec);
            if (mag_cmp(mc, mr) <= 0)
                break;
        }
    }
    if (_acb_poly_validate_roots(R, P->coeffs, d + 1, prec) != d)
        goto cleanup;
    /* the coarse balls must still lie below the refined ones */
    arf_zero(M);
    for (i = 0; i < d; i++) {
        acb_abs(a, R + i, prec);
        arb_get_lbound_arf(lb, a, prec);
        if (arf_cmp(lb, M) > 0)
            arf_set(M, lb);
    }
    k = 0;
    for (i = 0; i < d; i++) {
        acb_abs(a, R + i, prec);
        arb_get_ubound_arf(ub, a, prec);
        k += arf_cmp(ub, M) >= 0;
    }
    if (k > ncand)
        goto cleanup;
    _acb_vec_set(E, R, d);
    *nouter = ncand;
    ok = 1;
cleanup:
    acb_poly_clear(P);
    acb_clear(y);
    acb_clear(dy);
    acb_clear(c);
    arb_clear(a);
    arf_clear(M);
    arf_clear(lb);
    arf_clear(ub);
    mag_clear(mc);
    mag_clear(mr);
    _acb_vec_clear(R, d);
    flint_free(cand);
    return ok;
}

/* rs_radius_refine_circle: a ball of 64 bits meets the circle when its root
 * lies within about 2^-64 of it; the exact Routh count then cost 14 s at
 * degree 500.  Newton and one inclusion disc per such root at a higher
 * precision (O(d) each) usually separate it.  A new disc inside the old
 * isolating ball holds the same (only) root, so isolation is kept. */
int rs_radius_refine_circle(rs_radius_t r, const fmpz_poly_t p, slong max_prec)
{
    slong d = fmpz_poly_degree(p), i, k, w;
    acb_poly_t P;
    acb_t z, y, dy, c, D;
    arb_t a, one;
    mag_t m, l;
    int ok = 1;

    if (!r->isolated || r->roots == NULL || r->nroots != d || d < 1 || r->mult == NULL)
        return 0;
    for (i = 0; i < d; i++)
        if (r->mult[i] != 1)
            return 0;
    acb_poly_init(P);
    acb_init(z);
    acb_init(y);
    acb_init(dy);
    acb_init(c);
    acb_init(D);
    arb_init(a);
    arb_init(one);
    mag_init(m);
    mag_init(l);
    arb_one(one);
    /* exact coefficients: the error bound of rs_radius_horner2 needs them */
    acb_poly_set_fmpz_poly(P, p, FLINT_ABS(fmpz_poly_max_bits(p)) + 8);
    for (i = 0; i < d && ok; i++) {
        acb_abs(a, r->roots + i, FLINT_MAX(r->prec, 64));
        if (arb_lt(a, one) || arb_gt(a, one))
            continue;
        acb_get_mid(z, r->roots + i);
        ok = 0;
        for (w = 2 * FLINT_MAX(r->prec, 64); w <= max_prec && !ok; w *= 2) {
            for (k = 0; k < 8; k++) {   /* quadratic: a few steps per level */
                rs_radius_horner2(y, dy, P->coeffs, d + 1, z, w);
                if (acb_contains_zero(dy) || acb_contains_zero(y))
                    break;
                acb_div(c, y, dy, w);
                acb_get_mid(c, c);
                acb_sub(z, z, c, w);
                acb_get_mid(z, z);
            }
            rs_radius_horner2(y, dy, P->coeffs, d + 1, z, w);
            if (acb_contains_zero(dy))
                continue;
            acb_get_mag(m, y);
            acb_get_mag_lower(l, dy);
            mag_div(m, m, l);
            mag_mul_ui(m, m, (ulong) d);
            acb_set(D, z);
            acb_add_error_mag(D, m);
            if (!acb_contains(r->roots + i, D))
                continue;
            acb_abs(a, D, w);
            if (arb_lt(a, one) || arb_gt(a, one)) {
                acb_set(r->roots + i, D);
                ok = 1;
            }
        }
    }
    acb_poly_clear(P);
    acb_clear(z);
    acb_clear(y);
    acb_clear(dy);
    acb_clear(c);
    acb_clear(D);
    arb_clear(a);
    arb_clear(one);
    mag_clear(m);
    mag_clear(l);
    return ok;
}
