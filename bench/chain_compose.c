/* chain_compose.c -- issue 17, h-chain15: the substitution route's
 * composition back into the parameters, recstab's cached Horner
 * (rs_hurwitz_set_compose(1), the default) against FLINT's
 * fmpz_mpoly_compose_fmpz_mpoly (rs_hurwitz_set_compose(0)), on the bilinear
 * q of the N-mass chain, q(z) = det(4 z^2 I + 2 c z I + K) (K tridiagonal,
 * K_ii = k_i + k_{i+1}, K_{i,i+1} = -k_{i+1}; bench/chain_minor_size.c
 * derives it), alternating the two, `rounds` times each.  Prints the CPU
 * seconds of each rs_hurwitz_compute_partial (minors, factors, positivity:
 * everything but the composition is the same work in both) and checks that
 * both give the same minors.
 *
 * Build: cc -O2 -Iinclude -Isrc -I/usr/include/flint bench/chain_compose.c \
 *          build/librecstab.a -o build/chain_compose -fopenmp -lflint-arb \
 *          -lflint -lgsl -lgslcblas -ljansson -lmpfr -lgmp -lm
 * Run:   build/chain_compose N [rounds] [expand-seconds]
 */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"
#include "recstab/hurwitz.h"

static double
cpu(void)
{
    return (double) clock() / CLOCKS_PER_SEC;
}

int
main(int argc, char **argv)
{
    slong N = argc > 1 ? atol(argv[1]) : 6, i, k, round;
    int rounds = argc > 2 ? atoi(argv[2]) : 2, same = 1;
    double expand = argc > 3 ? atof(argv[3]) : 1e9;
    const char *names[16];
    char buf[16][8], s[128];
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t q, f1, f2, f, t, w;
    rs_hurwitz_t h[2];
    rs_error_t err;

    if (N < 2 || N > 12)
        return 2;
    names[0] = "c";
    for (i = 1; i <= N; i++) {
        snprintf(buf[i], sizeof buf[i], "k%ld", (long) i);
        names[i] = buf[i];
    }
    names[N + 1] = "z";
    fmpz_mpoly_ctx_init(ctx, N + 2, ORD_LEX);
    fmpz_mpoly_init(q, ctx);
    fmpz_mpoly_init(f1, ctx);
    fmpz_mpoly_init(f2, ctx);
    fmpz_mpoly_init(f, ctx);
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(w, ctx);
    /* the continuant f_i = (w + K_ii) f_{i-1} - k_i^2 f_{i-2} */
    fmpz_mpoly_set_str_pretty(w, "4*z^2 + 2*c*z", names, ctx);
    fmpz_mpoly_one(f1, ctx);
    for (i = 1; i <= N; i++) {
        if (i < N)
            snprintf(s, sizeof s, "k%ld + k%ld", (long) i, (long) i + 1);
        else
            snprintf(s, sizeof s, "k%ld", (long) i);
        fmpz_mpoly_set_str_pretty(t, s, names, ctx);
        fmpz_mpoly_add(t, t, w, ctx);
        fmpz_mpoly_mul(f, t, f1, ctx);
        if (i > 1) {
            snprintf(s, sizeof s, "k%ld^2", (long) i);
            fmpz_mpoly_set_str_pretty(t, s, names, ctx);
            fmpz_mpoly_mul(t, t, f2, ctx);
            fmpz_mpoly_sub(f, f, t, ctx);
        }
        fmpz_mpoly_swap(f2, f1, ctx);
        fmpz_mpoly_swap(f1, f, ctx);
    }
    fmpz_mpoly_swap(q, f1, ctx);
    rs_error_init(err);
    rs_hurwitz_set_expand_seconds(expand);
    for (round = 0; round < rounds; round++) {
        for (k = 0; k < 2; k++) {
            double t0;
            int r;
            rs_hurwitz_init(h[k]);
            rs_hurwitz_set_compose((int) k);
            t0 = cpu();
            r = rs_hurwitz_compute_partial(h[k], q, N + 1, NULL, ctx, err);
            printf("N = %ld, %s: %.3f s CPU, status %d, route %d, D_1..D_%ld expanded\n", (long) N,
                   k ? "cached Horner" : "FLINT compose", cpu() - t0, r, h[k]->route,
                   (long) h[k]->expanded);
            fflush(stdout);
        }
        same = h[0]->expanded == h[1]->expanded;
        for (i = 0; same && i < h[0]->expanded; i++)
            same = fmpz_mpoly_equal(h[0]->minors + i, h[1]->minors + i, ctx);
        printf("minors %s\n", same ? "identical" : "DIFFER");
        for (k = 0; k < 2; k++)
            rs_hurwitz_clear(h[k], ctx);
    }
    rs_error_clear(err);
    fmpz_mpoly_clear(q, ctx);
    fmpz_mpoly_clear(f1, ctx);
    fmpz_mpoly_clear(f2, ctx);
    fmpz_mpoly_clear(f, ctx);
    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(w, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    return same ? 0 : 1;
}
