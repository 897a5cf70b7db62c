/* bench_routh_routes.c -- issue 17: the cost of the Hurwitz minors of one
 * q(z) by three exact routes, to decide which one recstab should use.
 *
 *   (Z)   the fraction-free Routh recursion over Z[params] as recstab runs it
 *         (src/stability/hurwitz.c: rows kept integer-primitive, exact
 *         division by the primitive part of D_{m-3});
 *   (p)   the same recursion over Z/p[params] for one word prime p: the cost
 *         of ONE image of the multi-modular route (CRT needs at least
 *         bits(D_k) / 62 of them, bits measured from (Z));
 *   (pt)  the recursion over Z/p with every parameter evaluated: the cost of
 *         one probe of an interpolation route, times the number of probes a
 *         dense interpolation needs, prod over v of (deg_v D_k + 1), and the
 *         number a sparse (Zippel/Ben-Or-Tiwari) one needs, about
 *         terms(D_k) * (nvars + 1).
 * Input (stdin): first line the parameter names separated by blanks, then
 * a_0, ..., a_n one per line (FLINT's pretty syntax; produce it with
 * bench/bench_routes.sh).  Stops after the row whose (Z) time exceeds
 * BENCH_ROW_LIMIT seconds (argv[1], default 60).
 *
 * "est s" is recstab's estimate of the row (src/util/budget.c,
 * rs_budget_mpoly_mul_seconds summed over the row's products, as
 * hurwitz.c's _row_estimate), "Z cpu s" the process CPU seconds (clock())
 * of the Z route, to calibrate the estimate on a loaded machine.
 *
 * Build (after make all):
 *   cc -O2 -Iinclude -Isrc -I/usr/include/flint bench/bench_routh_routes.c \
 *      src/util/budget.c src/util/error.c -o build/bench_routh_routes -lflint -lgmp -lm
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <flint/fmpz_mpoly.h>
#include <flint/nmod_mpoly.h>
#include <flint/fmpz_vec.h>
#include <flint/ulong_extras.h>
#include "recstab/budget.h"

#define MAXV 32
#define MAXN 64

static double
now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void
z_primitive(fmpz_mpoly_struct *r, slong len, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_t g;
    slong j;
    fmpz_init(g);
    for (j = 0; j < len; j++)
        _fmpz_vec_content_chained(g, r[j].coeffs, r[j].length, g);
    if (!fmpz_is_zero(g) && !fmpz_is_one(g))
        for (j = 0; j < len; j++)
            fmpz_mpoly_scalar_divexact_fmpz(r + j, r + j, g, ctx);
    fmpz_clear(g);
}

int
main(int argc, char **argv)
{
    static char line[1 << 20];
    char *names[MAXV], *tok;
    const char *cnames[MAXV];
    char *coef[MAXN + 1];
    slong nv = 0, n = -1, len, m, j, v;
    double limit = argc > 1 ? atof(argv[1]) : 60.0;
    mp_limb_t p = n_nextprime(UWORD(1) << 62, 1);
    fmpz_mpoly_ctx_t zc;
    nmod_mpoly_ctx_t pc;
    fmpz_mpoly_struct *R[MAXN + 1];
    nmod_mpoly_struct *P[MAXN + 1];
    mp_limb_t *S[MAXN + 1], pt[MAXV];
    flint_rand_t st;

    if (fgets(line, sizeof line, stdin) == NULL)
        return 2;
    for (tok = strtok(line, " \n"); tok != NULL && nv < MAXV; tok = strtok(NULL, " \n"))
        names[nv++] = strdup(tok);
    for (v = 0; v < nv; v++)
        cnames[v] = names[v];
    while (n < MAXN && fgets(line, sizeof line, stdin) != NULL) {
        line[strcspn(line, "\n")] = 0;
        if (line[0] != 0)
            coef[++n] = strdup(line);
    }
    if (n < 2)
        return 2;
    len = n / 2 + 2;
    fmpz_mpoly_ctx_init(zc, nv, ORD_LEX);
    nmod_mpoly_ctx_init(pc, nv, ORD_LEX, p);
    flint_randinit(st);
    for (v = 0; v < nv; v++)
        pt[v] = n_randint(st, p);
    for (m = 0; m < n; m++) {
        R[m] = flint_malloc(len * sizeof(fmpz_mpoly_struct));
        P[m] = flint_malloc(len * sizeof(nmod_mpoly_struct));
        S[m] = flint_calloc(len, sizeof(mp_limb_t));
        for (j = 0; j < len; j++) {
            fmpz_mpoly_init(R[m] + j, zc);
            nmod_mpoly_init(P[m] + j, pc);
        }
    }
    /* rows 0 and 1 from the coefficients a_n, a_{n-2}, ... / a_{n-1}, ... */
    for (j = 0; 2 * j <= n; j++)
        fmpz_mpoly_set_str_pretty(R[0] + j, coef[n - 2 * j], cnames, zc);
    for (j = 0; 2 * j + 1 <= n; j++)
        fmpz_mpoly_set_str_pretty(R[1] + j, coef[n - 2 * j - 1], cnames, zc);
    for (m = 0; m < 2; m++) {
        z_primitive(R[m], len, zc);
        for (j = 0; j < len; j++) {
            char *str = fmpz_mpoly_get_str_pretty(R[m] + j, cnames, zc);
            nmod_mpoly_set_str_pretty(P[m] + j, str, cnames, pc);
            flint_free(str);
            S[m][j] = nmod_mpoly_evaluate_all_ui(P[m] + j, pt, pc);
        }
    }
    printf("prime p = %lu, degree n = %ld, %ld parameters\n", (unsigned long) p,
           (long) n, (long) nv);
    printf("%-4s %9s %6s %8s %10s %10s %10s %10s %11s %12s %14s %12s\n", "D_m", "terms", "bits",
           "images", "Z s", "Z cpu s", "est s", "one p s", "p route s", "point us", "dense probes",
           "sparse probes");
    for (m = 2; m < n; m++) {
        fmpz_mpoly_t t, u, pd;
        nmod_mpoly_t tp, up;
        fmpz_t cd;
        double t0, tz, tzc, tpp, tpt, dense = 1.0, est = 0.0;
        clock_t c0;
        slong bits, k, reps = 0;
        int ok = 1;

        fmpz_mpoly_init(t, zc);
        fmpz_mpoly_init(u, zc);
        fmpz_mpoly_init(pd, zc);
        nmod_mpoly_init(tp, pc);
        nmod_mpoly_init(up, pc);
        fmpz_init(cd);
        if (m >= 4) {
            _fmpz_vec_content(cd, R[m - 3][0].coeffs, R[m - 3][0].length);
            fmpz_mpoly_scalar_divexact_fmpz(pd, R[m - 3] + 0, cd, zc);
        }
        for (j = 0; j + 1 < len; j++)
            est += rs_budget_mpoly_mul_seconds(R[m - 1] + 0, R[m - 2] + j + 1)
                   + rs_budget_mpoly_mul_seconds(R[m - 2] + 0, R[m - 1] + j + 1);
        t0 = now();
        c0 = clock();
        for (j = 0; j + 1 < len && ok; j++) {
            fmpz_mpoly_mul(t, R[m - 1] + 0, R[m - 2] + j + 1, zc);
            fmpz_mpoly_mul(u, R[m - 2] + 0, R[m - 1] + j + 1, zc);
            fmpz_mpoly_sub(t, t, u, zc);
            if (m >= 4)
                ok = fmpz_mpoly_divides(R[m] + j, t, pd, zc);
            else
                fmpz_mpoly_swap(R[m] + j, t, zc);
        }
        z_primitive(R[m], len, zc);
        tz = now() - t0;
        tzc = (double) (clock() - c0) / CLOCKS_PER_SEC;
        t0 = now();
        for (j = 0; j + 1 < len && ok; j++) {
            nmod_mpoly_mul(tp, P[m - 1] + 0, P[m - 2] + j + 1, pc);
            nmod_mpoly_mul(up, P[m - 2] + 0, P[m - 1] + j + 1, pc);
            nmod_mpoly_sub(tp, tp, up, pc);
            if (m >= 4)
                ok = nmod_mpoly_divides(P[m] + j, tp, P[m - 3] + 0, pc);
            else
                nmod_mpoly_swap(P[m] + j, tp, pc);
        }
        tpp = now() - t0;
        /* one probe: the whole recursion up to row m with numbers mod p,
         * repeated for a measurable time */
        t0 = now();
        do {
            slong r;
            for (r = 2; r <= m; r++)
                for (j = 0; j + 1 < len; j++) {
                    mp_limb_t a = nmod_mul(S[r - 1][0], S[r - 2][j + 1], pc->mod);
                    mp_limb_t b = nmod_mul(S[r - 2][0], S[r - 1][j + 1], pc->mod);
                    a = nmod_sub(a, b, pc->mod);
                    if (r >= 4 && S[r - 3][0] != 0)
                        a = nmod_mul(a, n_invmod(S[r - 3][0], p), pc->mod);
                    S[r][j] = a;
                }
            reps++;
        } while (now() - t0 < 0.01);
        tpt = (now() - t0) / reps;
        if (!ok) {
            printf("D_%ld: inexact division\n", (long) m);
            return 1;
        }
        bits = FLINT_ABS(fmpz_mpoly_max_bits(R[m] + 0));
        for (v = 0; v < nv; v++) {
            slong d = fmpz_mpoly_degree_si(R[m] + 0, v, zc);
            dense *= (double) (d + 1);
        }
        k = bits / 62 + 1;
        printf("D_%-2ld %9ld %6ld %8ld %10.3f %10.3f %10.3f %10.3f %11.3f %12.3f %14.3g %12.3g\n",
               (long) m, (long) fmpz_mpoly_length(R[m] + 0, zc), (long) bits,
               (long) k, tz, tzc, est, tpp, tpp * k, tpt * 1e6, dense,
               (double) fmpz_mpoly_length(R[m] + 0, zc) * (nv + 1));
        fflush(stdout);
        fmpz_mpoly_clear(t, zc);
        fmpz_mpoly_clear(u, zc);
        fmpz_mpoly_clear(pd, zc);
        nmod_mpoly_clear(tp, pc);
        nmod_mpoly_clear(up, pc);
        fmpz_clear(cd);
        if (tzc > limit)
            break;
    }
    return 0;
}
