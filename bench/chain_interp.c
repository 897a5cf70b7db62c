/* chain_interp.c -- issue 17: the N-mass chain's Hurwitz minors over the
 * small ring Z[c, E_1..E_N] by evaluation and interpolation
 * (src/stability/hurwitz_interp.c) against one fraction-free (Bareiss)
 * elimination of the same matrix over the same ring (its k-th pivot is D_k).
 *
 * q(z) = sum_j E_j (4 z^2 + 2 c z)^{N-j} (derivation: bench/chain_minor_size.c).
 *
 * Build: cc -O2 -Iinclude -Isrc -I/usr/include/flint bench/chain_interp.c \
 *            build/librecstab.a -o build/chain_interp -fopenmp -lflint-arb \
 *            -lflint -lgsl -lgslcblas -ljansson -lmpfr -lgmp -lm
 * Run:   build/chain_interp N [bareiss]
 * Prints per minor D_m: terms; the CPU seconds of each route; with "bareiss"
 * also that both routes give equal polynomials. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"
#include "stability/hurwitz_interp.h"

static double
cpu(void)
{
    return (double) clock() / CLOCKS_PER_SEC;
}

static void
chain_coeffs(fmpz_mpoly_struct *a, slong N, const fmpz_mpoly_ctx_t ctx)
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

int
main(int argc, char **argv)
{
    slong N = argc > 1 ? atol(argv[1]) : 6, n, m, i, j, k;
    int bareiss = argc > 2 && strcmp(argv[2], "bareiss") == 0, r;
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_struct *a, *D;
    rs_error_t err;
    double t0, ti, tb = 0;

    if (N < 1 || N > 12)
        return 2;
    n = 2 * N;
    fmpz_mpoly_ctx_init(ctx, N + 1, ORD_LEX);
    a = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    D = flint_malloc(n * sizeof(fmpz_mpoly_struct));
    for (i = 0; i <= n; i++)
        fmpz_mpoly_init(a + i, ctx);
    for (i = 0; i < n; i++)
        fmpz_mpoly_init(D + i, ctx);
    chain_coeffs(a, N, ctx);
    rs_error_init(err);

    t0 = cpu();
    r = rs_hurwitz_interp_minors(D, n - 1, a, n, 10000000, err, ctx);
    ti = cpu() - t0;
    printf("N = %ld: interpolation status %d, %.2f CPU s for D_1..D_%ld\n",
           (long) N, r, ti, (long) (n - 1));
    for (m = 1; m < n; m++)
        printf("  D_%ld: %ld terms, max coefficient %ld bits\n", (long) m,
               (long) fmpz_mpoly_length(D + m - 1, ctx),
               (long) FLINT_ABS(fmpz_mpoly_max_bits(D + m - 1)));

    if (bareiss) {
        slong s = n - 1;
        fmpz_mpoly_struct *M = flint_malloc(s * s * sizeof(fmpz_mpoly_struct));
        fmpz_mpoly_t t, u, prev;
        int same = 1;
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
        t0 = cpu();
        for (k = 0; k < s; k++) {
            if (!fmpz_mpoly_equal(M + k * s + k, D + k, ctx))
                same = 0;
            if (k + 1 == s)
                break;
            for (i = k + 1; i < s; i++)
                for (j = k + 1; j < s; j++) {
                    fmpz_mpoly_mul(t, M + k * s + k, M + i * s + j, ctx);
                    fmpz_mpoly_mul(u, M + i * s + k, M + k * s + j, ctx);
                    fmpz_mpoly_sub(t, t, u, ctx);
                    if (!fmpz_mpoly_divides(M + i * s + j, t, prev, ctx))
                        same = 0;
                }
            fmpz_mpoly_set(prev, M + k * s + k, ctx);
        }
        tb = cpu() - t0;
        printf("Bareiss over Z[c, E]: %.2f CPU s; minors %s\n", tb,
               same ? "identical" : "DIFFER");
        for (i = 0; i < s * s; i++)
            fmpz_mpoly_clear(M + i, ctx);
        flint_free(M);
        fmpz_mpoly_clear(t, ctx);
        fmpz_mpoly_clear(u, ctx);
        fmpz_mpoly_clear(prev, ctx);
        if (!same)
            return 1;
    }
    for (i = 0; i <= n; i++)
        fmpz_mpoly_clear(a + i, ctx);
    for (i = 0; i < n; i++)
        fmpz_mpoly_clear(D + i, ctx);
    flint_free(a);
    flint_free(D);
    fmpz_mpoly_ctx_clear(ctx);
    rs_error_clear(err);
    return r == RS_HURWITZ_INTERP_OK ? 0 : 1;
}
