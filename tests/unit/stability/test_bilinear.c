/* test_bilinear.c -- q(z) = (1-z)^n p((1+z)/(1-z)), univariate and
 * multivariate. */
#include "testutil.h"
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/bilinear.h"

static void poly_set(fmpz_poly_t p, slong deg, const long *c)
{
    slong i;
    fmpz_poly_zero(p);
    for (i = 0; i <= deg; i++)
        fmpz_poly_set_coeff_si(p, deg - i, c[i]);
}

/* Hand expansions:
 *  2l - 1      -> 2(1+z) - (1-z)               = 3z + 1
 *  l + 1       -> (1+z) + (1-z)                 = 2        (drop 1)
 *  l - 1       -> (1+z) - (1-z)                 = 2z       (z = 0 once)
 *  2l^2-2l+1   -> 2(1+z)^2 - 2(1-z^2) + (1-z)^2 = 5z^2 + 2z + 1
 *  (l+1)^2     -> ((1+z) + (1-z))^2             = 4        (drop 2)
 *  l^2 - 1     -> (1+z)^2 - (1-z)^2             = 4z       (drop 1, z once) */
static void test_hand_cases(void **state)
{
    static const struct { slong dp; long p[3]; slong dq; long q[3];
                          slong drop, zm; } c[] = {
        {1, {2, -1}, 1, {3, 1}, 0, 0},
        {1, {1, 1}, 0, {2}, 1, 0},
        {1, {1, -1}, 1, {2, 0}, 0, 1},
        {2, {2, -2, 1}, 2, {5, 2, 1}, 0, 0},
        {2, {1, 2, 1}, 0, {4}, 2, 0},
        {2, {1, 0, -1}, 1, {4, 0}, 1, 1},
    };
    size_t i;
    (void) state;
    for (i = 0; i < sizeof(c) / sizeof(c[0]); i++) {
        fmpz_poly_t p, q, want;
        fmpz_poly_init(p);
        fmpz_poly_init(q);
        fmpz_poly_init(want);
        poly_set(p, c[i].dp, c[i].p);
        poly_set(want, c[i].dq, c[i].q);
        rs_bilinear_fmpz_poly(q, p);
        assert_true(fmpz_poly_equal(q, want));
        assert_int_equal(rs_bilinear_degree_drop(p, q), c[i].drop);
        assert_int_equal(rs_bilinear_zero_mult(q), c[i].zm);
        rs_bilinear_fmpz_poly(p, p);         /* aliasing */
        assert_true(fmpz_poly_equal(p, want));
        fmpz_poly_clear(p);
        fmpz_poly_clear(q);
        fmpz_poly_clear(want);
    }
}

/* Applying the map twice: with z = (1+l)/(1-l), 1+z = 2/(1-l) and
 * 1-z = -2l/(1-l), so B(B(p))(l) = (-2l)^n p(-1/l) when deg B(p) = n, i.e.
 * (-2)^n times the reversal of p(-l).  Checked on random polynomials. */
static void test_involution(void **state)
{
    flint_rand_t st;
    slong it, i, n;
    (void) state;
    flint_randinit(st);
    for (it = 0; it < 200; it++) {
        fmpz_poly_t p, q, qq, want;
        fmpz_t s;
        fmpz_poly_init(p);
        fmpz_poly_init(q);
        fmpz_poly_init(qq);
        fmpz_poly_init(want);
        fmpz_init(s);
        fmpz_poly_randtest_not_zero(p, st, 1 + n_randint(st, 10), 20);
        n = fmpz_poly_degree(p);
        rs_bilinear_fmpz_poly(q, p);
        if (fmpz_poly_degree(q) == n) {
            rs_bilinear_fmpz_poly(qq, q);
            fmpz_poly_set(want, p);
            for (i = 1; i <= n; i += 2)
                fmpz_neg(want->coeffs + i, want->coeffs + i);
            fmpz_poly_reverse(want, want, n + 1);
            fmpz_set_si(s, -2);
            fmpz_pow_ui(s, s, (ulong) n);
            fmpz_poly_scalar_mul_fmpz(want, want, s);
            assert_true(fmpz_poly_equal(qq, want));
        }
        fmpz_poly_clear(p);
        fmpz_poly_clear(q);
        fmpz_poly_clear(qq);
        fmpz_poly_clear(want);
        fmpz_clear(s);
    }
    flint_randclear(st);
}

/* Forward Euler oscillator p = l^2 - 2l + 1 + w^2 (variables l, w):
 * q = (1+z)^2 - 2(1-z^2) + (1+w^2)(1-z)^2 = (4+w^2) z^2 - 2w^2 z + w^2
 * (hand expansion). */
static void test_mpoly_forward_euler(void **state)
{
    const char *vars[] = {"l", "w"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p, q, want;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(p, ctx);
    fmpz_mpoly_init(q, ctx);
    fmpz_mpoly_init(want, ctx);
    assert_int_equal(fmpz_mpoly_set_str_pretty(p, "l^2 - 2*l + 1 + w^2",
                                               vars, ctx), 0);
    assert_int_equal(fmpz_mpoly_set_str_pretty(want,
                     "(4 + w^2)*l^2 - 2*w^2*l + w^2", vars, ctx), 0);
    rs_bilinear_fmpz_mpoly(q, p, 0, ctx);
    assert_true(fmpz_mpoly_equal(q, want, ctx));
    rs_bilinear_fmpz_mpoly(p, p, 0, ctx);    /* aliasing */
    assert_true(fmpz_mpoly_equal(p, want, ctx));
    fmpz_mpoly_clear(p, ctx);
    fmpz_mpoly_clear(q, ctx);
    fmpz_mpoly_clear(want, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* The multivariate map agrees with the univariate one at integer parameter
 * values, for random p(w, l, v) with l in the middle (index 1), as long as
 * the specialisation keeps the degree in l. */
static void test_mpoly_matches_univariate(void **state)
{
    flint_rand_t st;
    fmpz_mpoly_ctx_t ctx;
    slong it, k;
    (void) state;
    flint_randinit(st);
    fmpz_mpoly_ctx_init(ctx, 3, ORD_DEGREVLEX);
    for (it = 0; it < 50; it++) {
        fmpz_mpoly_t p, q, pe, qe;
        fmpz_poly_t pu, qu, qw;
        fmpz vals[3];
        fmpz *vp[3];
        fmpz_mpoly_init(p, ctx);
        fmpz_mpoly_init(q, ctx);
        fmpz_mpoly_init(pe, ctx);
        fmpz_mpoly_init(qe, ctx);
        fmpz_poly_init(pu);
        fmpz_poly_init(qu);
        fmpz_poly_init(qw);
        fmpz_mpoly_randtest_bound(p, st, 12, 10, 5, ctx);
        rs_bilinear_fmpz_mpoly(q, p, 1, ctx);
        for (k = 0; k < 3; k++) {
            fmpz_init_set_si(vals + k, (slong) n_randint(st, 7) - 3);
            vp[k] = vals + k;
        }
        /* specialise w and v, keep l */
        fmpz_mpoly_set(pe, p, ctx);
        fmpz_mpoly_evaluate_one_fmpz(pe, pe, 0, vp[0], ctx);
        fmpz_mpoly_evaluate_one_fmpz(pe, pe, 2, vp[2], ctx);
        fmpz_mpoly_set(qe, q, ctx);
        fmpz_mpoly_evaluate_one_fmpz(qe, qe, 0, vp[0], ctx);
        fmpz_mpoly_evaluate_one_fmpz(qe, qe, 2, vp[2], ctx);
        if (fmpz_mpoly_degree_si(pe, 1, ctx) == fmpz_mpoly_degree_si(p, 1, ctx)) {
            assert_true(fmpz_mpoly_get_fmpz_poly(pu, pe, 1, ctx));
            assert_true(fmpz_mpoly_get_fmpz_poly(qw, qe, 1, ctx));
            rs_bilinear_fmpz_poly(qu, pu);
            assert_true(fmpz_poly_equal(qu, qw));
        }
        for (k = 0; k < 3; k++)
            fmpz_clear(vals + k);
        fmpz_mpoly_clear(p, ctx);
        fmpz_mpoly_clear(q, ctx);
        fmpz_mpoly_clear(pe, ctx);
        fmpz_mpoly_clear(qe, ctx);
        fmpz_poly_clear(pu);
        fmpz_poly_clear(qu);
        fmpz_poly_clear(qw);
    }
    fmpz_mpoly_ctx_clear(ctx);
    flint_randclear(st);
}

static void test_zero(void **state)
{
    fmpz_poly_t p, q;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(q);
    fmpz_poly_set_si(q, 5);
    rs_bilinear_fmpz_poly(q, p);
    assert_true(fmpz_poly_is_zero(q));
    assert_int_equal(rs_bilinear_zero_mult(q), 0);
    fmpz_poly_set_si(p, 3);                   /* constants map to themselves */
    rs_bilinear_fmpz_poly(q, p);
    assert_true(fmpz_poly_equal(q, p));
    fmpz_poly_clear(p);
    fmpz_poly_clear(q);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_cases),
        cmocka_unit_test(test_involution),
        cmocka_unit_test(test_mpoly_forward_euler),
        cmocka_unit_test(test_mpoly_matches_univariate),
        cmocka_unit_test(test_zero),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
