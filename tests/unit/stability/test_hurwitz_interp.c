/* test_hurwitz_interp.c -- cmocka tests for hurwitz_interp.c (issue 17).
 *
 * Expected values: every leading minor of the Hurwitz matrix computed here
 * independently by fraction-free Gaussian elimination (Bareiss, tests/
 * chain_ring.h) over Z[x, G], compared term by term with the interpolated minors.  Inputs: the
 * N-mass chain q = sum_j E_j (4 z^2 + 2 c z)^{N-j} (bench/chain_minor_size.c
 * derives it) for N = 2..5, and random weighted-homogeneous polynomials
 * whose coefficients are of degree 2 and 3 in G (so the support bound's
 * degree factor is exercised). */
#include "testutil.h"
#include <stdlib.h>
#include <flint/fmpz.h>
#include <flint/fmpz_mpoly.h>
#include "stability/hurwitz_interp.h"
#include "chain_ring.h"

static void
compare(const fmpz_mpoly_struct *a, slong n, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_struct *D = flint_malloc(n * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_struct *R = flint_malloc(n * sizeof(fmpz_mpoly_struct));
    rs_error_t err;
    slong m;
    rs_error_init(err);
    for (m = 0; m < n; m++) {
        fmpz_mpoly_init(D + m, ctx);
        fmpz_mpoly_init(R + m, ctx);
    }
    assert_int_equal(rs_hurwitz_interp_minors(D, n, a, n, 1000000, err, ctx),
                     RS_HURWITZ_INTERP_OK);
    assert_int_equal(chain_ring_bareiss(R, a, n, n, ctx), 0);
    for (m = 0; m < n; m++) {
        assert_true(fmpz_mpoly_equal(D + m, R + m, ctx));
        fmpz_mpoly_clear(D + m, ctx);
        fmpz_mpoly_clear(R + m, ctx);
    }
    flint_free(D);
    flint_free(R);
    rs_error_clear(err);
}

static void
test_chain(void **state)
{
    slong N, i;
    (void) state;
    for (N = 2; N <= 5; N++) {
        fmpz_mpoly_ctx_t ctx;
        fmpz_mpoly_struct a[11];
        fmpz_mpoly_ctx_init(ctx, N + 1, ORD_LEX);
        for (i = 0; i <= 2 * N; i++)
            fmpz_mpoly_init(a + i, ctx);
        chain_ring_coeffs(a, N, ctx);
        compare(a, 2 * N, ctx);
        for (i = 0; i <= 2 * N; i++)
            fmpz_mpoly_clear(a + i, ctx);
        fmpz_mpoly_ctx_clear(ctx);
    }
}

/* x weight 1, y weight 2, u weight 3; a_i random of weight n - i + 2 */
static void
test_random_homogeneous(void **state)
{
    flint_rand_t st;
    slong n, r, i, e0, e1, e2;
    (void) state;
    flint_randinit(st);
    for (r = 0; r < 12; r++) {
        fmpz_mpoly_ctx_t ctx;
        fmpz_mpoly_struct a[8];
        n = 3 + r % 5;
        fmpz_mpoly_ctx_init(ctx, 3, ORD_LEX);
        for (i = 0; i <= n; i++) {
            slong W = n - i + 2;
            ulong ex[3];
            fmpz_mpoly_init(a + i, ctx);
            for (e2 = 0; 3 * e2 <= W; e2++)
                for (e1 = 0; 3 * e2 + 2 * e1 <= W; e1++) {
                    fmpz_t c;
                    e0 = W - 3 * e2 - 2 * e1;
                    if (n_randint(st, 3) == 0)
                        continue;
                    fmpz_init(c);
                    fmpz_randtest_not_zero(c, st, 40);
                    ex[0] = e0;
                    ex[1] = e1;
                    ex[2] = e2;
                    fmpz_mpoly_push_term_fmpz_ui(a + i, c, ex, ctx);
                    fmpz_clear(c);
                }
            /* keep every coefficient non-zero: x^W */
            if (fmpz_mpoly_is_zero(a + i, ctx)) {
                ex[0] = W;
                ex[1] = ex[2] = 0;
                fmpz_mpoly_push_term_ui_ui(a + i, 1, ex, ctx);
            }
            fmpz_mpoly_sort_terms(a + i, ctx);
            fmpz_mpoly_combine_like_terms(a + i, ctx);
        }
        compare(a, n, ctx);
        for (i = 0; i <= n; i++)
            fmpz_mpoly_clear(a + i, ctx);
        fmpz_mpoly_ctx_clear(ctx);
    }
    flint_randclear(st);
}

/* not weighted-homogeneous: refused, nothing computed */
static void
test_not_applicable(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_struct a[3], D[2];
    const char *v[] = {"x", "y"};
    rs_error_t err;
    slong i;
    (void) state;
    rs_error_init(err);
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    for (i = 0; i < 3; i++)
        fmpz_mpoly_init(a + i, ctx);
    for (i = 0; i < 2; i++)
        fmpz_mpoly_init(D + i, ctx);
    fmpz_mpoly_set_str_pretty(a + 0, "x + 1", v, ctx);
    fmpz_mpoly_set_str_pretty(a + 1, "y", v, ctx);
    fmpz_mpoly_set_str_pretty(a + 2, "1", v, ctx);
    assert_int_equal(rs_hurwitz_interp_minors(D, 2, a, 2, 1000, err, ctx),
                     RS_HURWITZ_INTERP_NA);
    for (i = 0; i < 3; i++)
        fmpz_mpoly_clear(a + i, ctx);
    for (i = 0; i < 2; i++)
        fmpz_mpoly_clear(D + i, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    rs_error_clear(err);
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain),
        cmocka_unit_test(test_random_homogeneous),
        cmocka_unit_test(test_not_applicable),
    };
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup_master();
    return r;
}
