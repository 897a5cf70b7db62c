/* chain_minor_size.c -- issue 17: the size of the Hurwitz minors of the
 * N-mass chain (bench/make_chain_case.sh N), the largest D_{n-1} included,
 * without expanding the Routh rows in the stiffnesses.
 *
 * Derivation (by hand).  The trapezoidal rule maps s = (2/h)(lambda - 1) /
 * (lambda + 1), and lambda = (1 + z)/(1 - z) gives (lambda - 1)/(lambda + 1)
 * = z, so with h scaled into c and k_i, q(z) is (up to a constant) the
 * continuous characteristic polynomial det(s^2 I + c s I + K) at s = 2z:
 *     q(z) = r(w),  w = 4 z^2 + 2 c z,  r(w) = det(w I + K)
 *          = sum_j E_j w^{N-j},  E_0 = 1, E_j = e_j(K) (sums of principal
 *            j x j minors of the stiffness matrix K).
 * K is tridiagonal: K_ii = k_i + k_{i+1} (k_{N+1} = 0), K_{i,i+1} = -k_{i+1},
 * so r is the continuant f_i = (w + K_ii) f_{i-1} - k_i^2 f_{i-2}.
 *
 * Stage A: the fraction-free Routh recursion (as src/stability/hurwitz.c
 * runs it) on q with the E_j as independent variables (N + 1 variables c,
 * E_1..E_N): small.  Stage B: every D_m(c, E) composed with E_j(k) over Z
 * (fmpz_mpoly_compose_fmpz_mpoly): the minor as recstab states it, in
 * c, k_1..k_N.  Printed per minor: terms, bits of the largest coefficient
 * (of the primitive part), degree per variable, seconds of each stage.
 * Identity check: q_E(E(k)) equals the q of `recstab --analyse bilinear`
 * up to a constant (bench_routes.sh input on stdin, optional: the check is
 * done when stdin is not a terminal).
 *
 * Build: cc -O2 -I/usr/include/flint bench/chain_minor_size.c \
 *            -o build/chain_minor_size -lflint -lgmp -lm
 * Run:   build/chain_minor_size N [from_m] [stage-B limit s] [bound|homog]
 *
 * With the fourth argument "bound" (issue 17, h-chain13) stage B is not run:
 * for each D_m an upper bound on its terms in c, k_1..k_N is counted from its
 * terms in c, E alone.  E_j = e_j(K) is homogeneous of degree j in k, and
 * k_i occurs only in rows and columns i-1, i of K, so a principal minor has
 * degree <= 2 in k_i: the monomial c^a E^b expands into monomials c^a k^e
 * with |e| = w = sum_j j b_j and every e_i <= d = sum_j b_j min(j, 2) (and
 * <= w).  The bound is the sum over the distinct (a, w) of the number of
 * e in N parts of sum w with parts <= the largest d of that (a, w) (a
 * dynamic programme).  It ignores cancellation and the finer structure, so
 * it overestimates; its ratio to the true count where stage B runs (N <= 7)
 * says by how much.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_vec.h>

static double
now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void
primitive(fmpz_mpoly_struct *r, slong len, const fmpz_mpoly_ctx_t ctx)
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

/* number of e in N parts, each in 0..d, of sum w (doubles: up to 1e20) */
static double
count_box(slong N, slong w, slong d)
{
    double *c = calloc(w + 1, sizeof(double)), *c2 = calloc(w + 1, sizeof(double)), r;
    slong i, s, t;
    c[0] = 1.0;
    for (i = 0; i < N; i++) {
        for (s = 0; s <= w; s++) {
            c2[s] = 0.0;
            for (t = 0; t <= d && t <= s; t++)
                c2[s] += c[s - t];
        }
        memcpy(c, c2, (w + 1) * sizeof(double));
    }
    r = c[w];
    free(c);
    free(c2);
    return r;
}

/* the bound of the header comment for one minor in c, E_1..E_N (variable 0
 * z, 1 c, 1 + j E_j) */
static void
print_bound(const fmpz_mpoly_t Dm, slong N, const fmpz_mpoly_ctx_t ec)
{
    slong len = fmpz_mpoly_length(Dm, ec), i, j, amax = 0, wmax = 0;
    ulong *ex = flint_malloc((N + 2) * sizeof(ulong));
    slong *best;
    double total = 0.0;
    for (i = 0; i < len; i++) {
        slong w = 0;
        fmpz_mpoly_get_term_exp_ui(ex, Dm, i, ec);
        for (j = 1; j <= N; j++)
            w += j * (slong) ex[1 + j];
        amax = FLINT_MAX(amax, (slong) ex[1]);
        wmax = FLINT_MAX(wmax, w);
    }
    best = calloc((amax + 1) * (wmax + 1), sizeof(slong));
    for (i = 0; i < (amax + 1) * (wmax + 1); i++)
        best[i] = -1;
    for (i = 0; i < len; i++) {
        slong w = 0, d = 0;
        fmpz_mpoly_get_term_exp_ui(ex, Dm, i, ec);
        for (j = 1; j <= N; j++) {
            w += j * (slong) ex[1 + j];
            d += FLINT_MIN(j, 2) * (slong) ex[1 + j];
        }
        d = FLINT_MIN(d, w);
        if (d > best[ex[1] * (wmax + 1) + w])
            best[ex[1] * (wmax + 1) + w] = d;
    }
    for (i = 0; i < (amax + 1) * (wmax + 1); i++)
        if (best[i] >= 0)
            total += count_box(N, i % (wmax + 1), best[i]);
    printf("bound N = %ld: %ld terms in c, E; at most %.4g terms in c, k (deg c %ld, k-degree %ld)\n",
           (long) N, (long) len, total, (long) amax, (long) wmax);
    free(best);
    flint_free(ex);
}

int
main(int argc, char **argv)
{
    slong N = argc > 1 ? atol(argv[1]) : 6;
    slong from = argc > 2 ? atol(argv[2]) : 1;
    double limit = argc > 3 ? atof(argv[3]) : 1e9;
    slong n = 2 * N, len = n / 2 + 2, i, j, m;
    fmpz_mpoly_ctx_t ec, kc;       /* (z, c, E_1..E_N) and (c, k_1..k_N) */
    fmpz_mpoly_t q, w, wp, t, u, pd;
    fmpz_mpoly_struct *a, *Ek, *f, **R, *D, *img;
    fmpz_mpoly_struct **gen;
    fmpz_t cd;
    double t0;

    if (N < 1 || N > 12)
        return 2;
    fmpz_mpoly_ctx_init(ec, N + 2, ORD_LEX);
    fmpz_mpoly_ctx_init(kc, N + 1, ORD_LEX);
    fmpz_mpoly_init(q, ec);
    fmpz_mpoly_init(w, ec);
    fmpz_mpoly_init(wp, ec);
    fmpz_mpoly_init(t, ec);
    fmpz_mpoly_init(u, ec);
    fmpz_mpoly_init(pd, ec);
    fmpz_init(cd);

    /* q_E(z) = sum_j E_j w^{N-j}, variables 0 = z, 1 = c, 1 + j = E_j */
    fmpz_mpoly_gen(w, 0, ec);
    fmpz_mpoly_mul(w, w, w, ec);
    fmpz_mpoly_scalar_mul_si(w, w, 4, ec);
    fmpz_mpoly_gen(t, 0, ec);
    fmpz_mpoly_gen(u, 1, ec);
    fmpz_mpoly_mul(t, t, u, ec);
    fmpz_mpoly_scalar_mul_si(t, t, 2, ec);
    fmpz_mpoly_add(w, w, t, ec);
    fmpz_mpoly_one(wp, ec);
    for (j = N; j >= 0; j--) {          /* wp = w^{N-j} */
        if (j == 0)
            fmpz_mpoly_one(t, ec);
        else
            fmpz_mpoly_gen(t, 1 + j, ec);
        fmpz_mpoly_mul(t, t, wp, ec);
        fmpz_mpoly_add(q, q, t, ec);
        fmpz_mpoly_mul(wp, wp, w, ec);
    }
    a = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    for (i = 0; i <= n; i++) {
        slong zv = 0;
        ulong e = i;
        fmpz_mpoly_init(a + i, ec);
        fmpz_mpoly_get_coeff_vars_ui(a + i, q, &zv, &e, 1, ec);
    }

    /* E_j(k) from the continuant; kc variables 0 = c, i = k_i */
    {
        /* f_i as polynomials in w over Z[k]: coefficient arrays */
        fmpz_mpoly_struct *fm1, *fm2, *fc, *tmp;
        fmpz_mpoly_t kii, ki2, s;
        slong d;
        fm2 = flint_malloc((N + 1) * sizeof(fmpz_mpoly_struct));
        fm1 = flint_malloc((N + 1) * sizeof(fmpz_mpoly_struct));
        fc = flint_malloc((N + 1) * sizeof(fmpz_mpoly_struct));
        for (d = 0; d <= N; d++) {
            fmpz_mpoly_init(fm2 + d, kc);
            fmpz_mpoly_init(fm1 + d, kc);
            fmpz_mpoly_init(fc + d, kc);
        }
        fmpz_mpoly_init(kii, kc);
        fmpz_mpoly_init(ki2, kc);
        fmpz_mpoly_init(s, kc);
        fmpz_mpoly_one(fm1 + 0, kc);     /* f_0 = 1 (coefficient of w^0) */
        /* f_{-1} = 0 */
        for (i = 1; i <= N; i++) {
            fmpz_mpoly_gen(kii, i, kc);
            if (i < N) {
                fmpz_mpoly_gen(s, i + 1, kc);
                fmpz_mpoly_add(kii, kii, s, kc);
            }
            fmpz_mpoly_gen(ki2, i, kc);
            fmpz_mpoly_mul(ki2, ki2, ki2, kc);
            /* fc[d] = fm1[d-1] + kii fm1[d] - (i > 1 ? k_i^2 fm2[d] : 0) */
            for (d = 0; d <= N; d++) {
                fmpz_mpoly_mul(fc + d, kii, fm1 + d, kc);
                if (d > 0)
                    fmpz_mpoly_add(fc + d, fc + d, fm1 + d - 1, kc);
                if (i > 1) {
                    fmpz_mpoly_mul(s, ki2, fm2 + d, kc);
                    fmpz_mpoly_sub(fc + d, fc + d, s, kc);
                }
            }
            tmp = fm2; fm2 = fm1; fm1 = fc; fc = tmp;
        }
        /* r(w) = sum_d fm1[d] w^d, E_j = coefficient of w^{N-j} */
        Ek = flint_malloc((N + 1) * sizeof(fmpz_mpoly_struct));
        for (j = 0; j <= N; j++) {
            fmpz_mpoly_init(Ek + j, kc);
            fmpz_mpoly_set(Ek + j, fm1 + N - j, kc);
        }
        for (d = 0; d <= N; d++) {
            fmpz_mpoly_clear(fm2 + d, kc);
            fmpz_mpoly_clear(fm1 + d, kc);
            fmpz_mpoly_clear(fc + d, kc);
        }
        flint_free(fm2); flint_free(fm1); flint_free(fc);
        fmpz_mpoly_clear(kii, kc);
        fmpz_mpoly_clear(ki2, kc);
        fmpz_mpoly_clear(s, kc);
    }
    printf("N = %ld: E_j(k) terms:", (long) N);
    for (j = 1; j <= N; j++)
        printf(" %ld", (long) fmpz_mpoly_length(Ek + j, kc));
    printf("\n");

    /* generators of the substitution (z, c, E_1..E_N) -> (c, k) */
    gen = flint_malloc((N + 2) * sizeof(fmpz_mpoly_struct *));
    f = flint_malloc(2 * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_init(f + 0, kc);     /* z -> 0 (unused by the minors) */
    fmpz_mpoly_init(f + 1, kc);
    fmpz_mpoly_gen(f + 1, 0, kc);   /* c -> c */
    gen[0] = f + 0;
    gen[1] = f + 1;
    for (j = 1; j <= N; j++)
        gen[1 + j] = Ek + j;

    /* stage A: Routh rows over Z[c, E] */
    R = flint_malloc(n * sizeof(fmpz_mpoly_struct *));
    D = flint_malloc(n * sizeof(fmpz_mpoly_struct));
    for (m = 0; m < n; m++) {
        R[m] = flint_malloc(len * sizeof(fmpz_mpoly_struct));
        for (j = 0; j < len; j++)
            fmpz_mpoly_init(R[m] + j, ec);
        fmpz_mpoly_init(D + m, ec);
    }
    for (j = 0; 2 * j <= n; j++)
        fmpz_mpoly_set(R[0] + j, a + n - 2 * j, ec);
    for (j = 0; 2 * j + 1 <= n; j++)
        fmpz_mpoly_set(R[1] + j, a + n - 2 * j - 1, ec);
    primitive(R[0], len, ec);
    primitive(R[1], len, ec);
    fmpz_mpoly_set(D + 1, R[1] + 0, ec);
    t0 = now();
    for (m = 2; m < n; m++) {
        if (m >= 4) {
            _fmpz_vec_content(cd, R[m - 3][0].coeffs, R[m - 3][0].length);
            fmpz_mpoly_scalar_divexact_fmpz(pd, R[m - 3] + 0, cd, ec);
        }
        for (j = 0; j + 1 < len; j++) {
            fmpz_mpoly_mul(t, R[m - 1] + 0, R[m - 2] + j + 1, ec);
            fmpz_mpoly_mul(u, R[m - 2] + 0, R[m - 1] + j + 1, ec);
            fmpz_mpoly_sub(t, t, u, ec);
            if (m >= 4) {
                if (!fmpz_mpoly_divides(R[m] + j, t, pd, ec)) {
                    printf("inexact division in row %ld\n", (long) m);
                    return 1;
                }
            } else
                fmpz_mpoly_swap(R[m] + j, t, ec);
        }
        primitive(R[m], len, ec);
        fmpz_mpoly_set(D + m, R[m] + 0, ec);
    }
    printf("stage A (Routh over Z[c, E_1..E_%ld]): %.3f s\n", (long) N, now() - t0);
    printf("%-5s %8s %10s %6s %10s %8s  %s\n", "D_m", "E-terms", "terms", "bits",
           "compose s", "tdeg", "deg c, k_1..k_N");

    /* "homog" (issue 17, h-chain15): the weight of every term of D_m with
     * weight 1 for c and 2j for E_j; q = sum_j E_j w^{N-j} has weight 2N
     * (w = 4 z^2 + 2 c z weight 2, z weight 1), so a_i has weight 2N - i,
     * H_ij = a_{n-2j+i} weight 2j - i and D_m weight m(m+1)/2: one value
     * per minor expected */
    if (argc > 4 && strcmp(argv[4], "homog") == 0) {
        for (m = from; m < n; m++) {
            slong ti, wmin = WORD_MAX, wmax = -1;
            ulong ex[16];
            for (ti = 0; ti < D[m].length; ti++) {
                slong wt;
                fmpz_mpoly_get_term_exp_ui(ex, D + m, ti, ec);
                wt = (slong) ex[1];
                for (j = 1; j <= N; j++)
                    wt += 2 * j * (slong) ex[1 + j];
                wmin = FLINT_MIN(wmin, wt);
                wmax = FLINT_MAX(wmax, wt);
            }
            printf("D_%ld: %ld terms, weight (c 1, E_j 2j) from %ld to %ld\n", (long) m,
                   (long) D[m].length, (long) wmin, (long) wmax);
        }
        return 0;
    }
    if (argc > 4 && strcmp(argv[4], "bound") == 0) {
        for (m = from; m < n; m++)
            print_bound(D + m, N, ec);
        return 0;
    }
    img = flint_malloc(sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_init(img, kc);
    for (m = from; m < n; m++) {
        slong v, bits, tdeg;
        double tb;
        fmpz_t g;
        t0 = now();
        if (!fmpz_mpoly_compose_fmpz_mpoly(img, D + m, gen, ec, kc)) {
            printf("D_%ld: compose failed\n", (long) m);
            continue;
        }
        tb = now() - t0;
        fmpz_init(g);
        _fmpz_vec_content(g, img->coeffs, img->length);
        if (!fmpz_is_zero(g))
            fmpz_mpoly_scalar_divexact_fmpz(img, img, g, kc);
        fmpz_clear(g);
        bits = FLINT_ABS(fmpz_mpoly_max_bits(img));
        tdeg = fmpz_mpoly_total_degree_si(img, kc);
        printf("D_%-3ld %8ld %10ld %6ld %10.3f %8ld  ", (long) m,
               (long) fmpz_mpoly_length(D + m, ec), (long) fmpz_mpoly_length(img, kc),
               (long) bits, tb, (long) tdeg);
        for (v = 0; v <= N; v++)
            printf("%ld%s", (long) fmpz_mpoly_degree_si(img, v, kc), v < N ? "," : "\n");
        fflush(stdout);
        if (tb > limit)
            break;
    }
    return 0;
}
