/* chain_interp.c -- issue 17: the N-mass chain's Hurwitz minors over the
 * small ring Z[c, E_1..E_N] by evaluation and interpolation
 * (src/stability/hurwitz_interp.c) against one fraction-free (Bareiss)
 * elimination of the same matrix over the same ring (its k-th pivot is D_k).
 *
 * q(z) = sum_j E_j (4 z^2 + 2 c z)^{N-j} (derivation: bench/chain_minor_size.c).
 *
 * Build: cc -O2 -Iinclude -Isrc -Itests -I/usr/include/flint bench/chain_interp.c \
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
#include "chain_ring.h"

static double
cpu(void)
{
    return (double) clock() / CLOCKS_PER_SEC;
}

int
main(int argc, char **argv)
{
    slong N = argc > 1 ? atol(argv[1]) : 6, n, m, i, k;
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
    chain_ring_coeffs(a, N, ctx);
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
        fmpz_mpoly_struct *R = flint_malloc(s * sizeof(fmpz_mpoly_struct));
        int same = 1;
        for (k = 0; k < s; k++)
            fmpz_mpoly_init(R + k, ctx);
        t0 = cpu();
        if (chain_ring_bareiss(R, a, n, s, ctx) != 0)
            same = 0;
        tb = cpu() - t0;
        for (k = 0; k < s; k++) {
            if (!fmpz_mpoly_equal(R + k, D + k, ctx))
                same = 0;
            fmpz_mpoly_clear(R + k, ctx);
        }
        flint_free(R);
        printf("Bareiss over Z[c, E]: %.2f CPU s; minors %s\n", tb,
               same ? "identical" : "DIFFER");
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
