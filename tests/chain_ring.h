/* chain_ring.h -- shared by tests/unit/stability/test_hurwitz_interp.c and
 * bench/chain_interp.c (issue 17): the N-mass chain over its small ring and
 * an independent reference for Hurwitz minors.
 *
 * chain_ring_coeffs: a_0..a_{2N} of q(z) = sum_j E_j (4 z^2 + 2 c z)^{N-j}
 * over Z[c, E_1..E_N] (E_0 = 1; derivation: bench/chain_minor_size.c), using
 * (4 z^2 + 2 c z)^e = sum_l binom(e, l) 4^l 2^{e-l} c^{e-l} z^{e+l}.
 *
 * chain_ring_bareiss: D_1..D_s, the leading minors of the Hurwitz matrix
 * (H_ij = a_{n-2j+i}, 1-based), by one fraction-free (Bareiss) elimination:
 * after step k the pivot M_kk is D_{k+1}, and every update divides exactly
 * by the pivot before.  Returns 0, or 1 if a pivot is zero or a division is
 * not exact (then the reference does not apply). */
#ifndef RS_TESTS_CHAIN_RING_H
#define RS_TESTS_CHAIN_RING_H

#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>

static void
chain_ring_coeffs(fmpz_mpoly_struct *a, slong N, const fmpz_mpoly_ctx_t ctx)
{
    slong j, l, v, n = 2 * N;
    fmpz_t b;
    ulong *ex = flint_calloc(N + 1, sizeof(ulong));
    fmpz_init(b);
    for (j = 0; j <= n; j++)
        fmpz_mpoly_zero(a + j, ctx);
    for (j = 0; j <= N; j++) {
        slong e = N - j;
        for (l = 0; l <= e; l++) {
            fmpz_bin_uiui(b, e, l);
            fmpz_mul_2exp(b, b, 2 * l + (e - l));
            for (v = 0; v <= N; v++)
                ex[v] = 0;
            ex[0] = e - l;
            if (j > 0)
                ex[j] = 1;
            fmpz_mpoly_push_term_fmpz_ui(a + e + l, b, ex, ctx);
        }
    }
    for (j = 0; j <= n; j++) {
        fmpz_mpoly_sort_terms(a + j, ctx);
        fmpz_mpoly_combine_like_terms(a + j, ctx);
    }
    fmpz_clear(b);
    flint_free(ex);
}

static int
chain_ring_bareiss(fmpz_mpoly_struct *D, const fmpz_mpoly_struct *a, slong n, slong s,
                   const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_struct *M = flint_malloc(s * s * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_t t, u, prev;
    slong i, j, k;
    int bad = 0;
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(u, ctx);
    fmpz_mpoly_init(prev, ctx);
    fmpz_mpoly_one(prev, ctx);
    for (i = 0; i < s; i++)
        for (j = 0; j < s; j++) {
            slong idx = n - (2 * (j + 1) - (i + 1));
            fmpz_mpoly_init(M + i * s + j, ctx);
            if (idx >= 0 && idx <= n)
                fmpz_mpoly_set(M + i * s + j, a + idx, ctx);
        }
    for (k = 0; k < s && !bad; k++) {
        fmpz_mpoly_set(D + k, M + k * s + k, ctx);
        if (k + 1 == s)
            break;
        if (fmpz_mpoly_is_zero(M + k * s + k, ctx))
            bad = 1;
        for (i = k + 1; i < s && !bad; i++)
            for (j = k + 1; j < s && !bad; j++) {
                fmpz_mpoly_mul(t, M + k * s + k, M + i * s + j, ctx);
                fmpz_mpoly_mul(u, M + i * s + k, M + k * s + j, ctx);
                fmpz_mpoly_sub(t, t, u, ctx);
                if (!fmpz_mpoly_divides(M + i * s + j, t, prev, ctx))
                    bad = 1;
            }
        fmpz_mpoly_set(prev, M + k * s + k, ctx);
    }
    for (i = 0; i < s * s; i++)
        fmpz_mpoly_clear(M + i, ctx);
    flint_free(M);
    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(u, ctx);
    fmpz_mpoly_clear(prev, ctx);
    return bad;
}

#endif
