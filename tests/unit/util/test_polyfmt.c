/* test_polyfmt.c -- rs_polyfmt_fmpz_mpoly, the direct printer of issue 17,
 * against the route it replaced (FLINT's fmpz_mpoly_get_str_pretty, then
 * rs_polyfmt_spaced): random polynomials over every ordering, with units,
 * constants, huge coefficients and exponents; and strings written by hand. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <flint/fmpz_mpoly.h>
#include "util/polyfmt.h"

/* the reference: what rs_polyfmt_fmpz_mpoly returned before issue 17 */
static char *reference(const fmpz_mpoly_t p, const char **vars, const fmpz_mpoly_ctx_t ctx)
{
    char *s = fmpz_mpoly_get_str_pretty(p, vars, ctx);
    char *r = rs_polyfmt_spaced(s);
    flint_free(s);
    return r;
}

static void check_same(const fmpz_mpoly_t p, const char **vars, const fmpz_mpoly_ctx_t ctx)
{
    char *want = reference(p, vars, ctx), *got = rs_polyfmt_fmpz_mpoly(p, vars, ctx);
    assert_non_null(got);
    assert_string_equal(got, want);
    free(want);
    free(got);
}

/* 4000 random polynomials: 1-5 variables, each ordering, coefficients of
 * up to 200 bits (so both small and GMP coefficients, +-1 often enough:
 * coefficient bits 1-2), exponents up to 2^70 now and then (bits > 64:
 * the FLINT route) */
static void test_random_against_flint(void **state)
{
    static const char *names[] = {"m", "muh", "wh", "alpha", "lambda"};
    static const ordering_t ords[] = {ORD_LEX, ORD_DEGLEX, ORD_DEGREVLEX};
    flint_rand_t rs;
    slong it;
    (void) state;
    flint_randinit(rs);
    for (it = 0; it < 4000; it++) {
        slong nv = 1 + (slong) n_randint(rs, 5);
        fmpz_mpoly_ctx_t ctx;
        fmpz_mpoly_t p;
        slong len = (slong) n_randint(rs, 12);
        /* and now and then up to 1200 bits: the printer's own decimal
         * conversion stops at 16 limbs and hands longer ones to GMP */
        flint_bitcnt_t cb = (it % 4 == 0) ? 1 + n_randint(rs, 2)
                          : (it % 10 == 1) ? 1 + n_randint(rs, 1200) : 1 + n_randint(rs, 200);
        ulong eb = (it % 50 == 0) ? 70 : 1 + n_randint(rs, 8);
        fmpz_mpoly_ctx_init(ctx, nv, ords[it % 3]);
        fmpz_mpoly_init(p, ctx);
        fmpz_mpoly_randtest_bits(p, rs, len, cb, eb, ctx);
        if (it % 7 == 0) fmpz_mpoly_add_si(p, p, (it % 2) ? 1 : -1, ctx);   /* a unit constant term */
        check_same(p, names, ctx);
        if (it % 100 == 0) check_same(p, NULL, ctx);   /* x1, x2, ...: the FLINT route */
        fmpz_mpoly_clear(p, ctx);
        fmpz_mpoly_ctx_clear(ctx);
    }
    flint_randclear(rs);
}

/* Coefficients at the edges of the printer's 19-digit chunks (10^k - 1,
 * 10^k, 10^k + 1 for k = 17..80, chunks of zeros inside), 2^64 +- 1 and
 * the 16/17-limb boundary (2^1023, 2^1024 +- 1), either sign, against
 * FLINT's route. */
static void test_chunk_edges(void **state)
{
    static const char *names[] = {"m", "muh"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p;
    fmpz_t c, t;
    ulong e[2] = {1, 2};
    slong k, d;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(p, ctx);
    fmpz_init(c);
    fmpz_init(t);
    for (k = 17; k <= 80; k++)
        for (d = -1; d <= 1; d++) {
            fmpz_set_ui(c, 10);
            fmpz_pow_ui(c, c, (ulong) k);
            fmpz_add_si(c, c, d);
            fmpz_mpoly_zero(p, ctx);
            fmpz_mpoly_set_coeff_fmpz_ui(p, c, e, ctx);
            fmpz_neg(t, c);
            fmpz_mpoly_set_coeff_fmpz_ui(p, t, e + 1, ctx);
            check_same(p, names, ctx);
        }
    for (k = 0; k < 3; k++)
        for (d = -1; d <= 1; d++) {
            fmpz_one(c);
            fmpz_mul_2exp(c, c, k == 0 ? 64 : k == 1 ? 1023 : 1024);
            fmpz_add_si(c, c, d);
            fmpz_mpoly_set_fmpz(p, c, ctx);
            check_same(p, names, ctx);
            fmpz_mpoly_neg(p, p, ctx);
            check_same(p, names, ctx);
        }
    fmpz_clear(c);
    fmpz_clear(t);
    fmpz_mpoly_clear(p, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* Strings written out by hand for polynomials set from text. */
static void test_by_hand(void **state)
{
    static const char *names[] = {"m", "muh", "wh", "alpha"};
    static const char *odd[] = {"re(z)", "muh", "wh", "alpha"};   /* a name the fast path refuses */
    static const struct { const char *in, *out; } cases[] = {
        {"0", "0"},
        {"1", "1"},
        {"-1", "-1"},
        {"-m", "-m"},
        {"m - 1", "m - 1"},
        {"-2*m^2*muh + 3*alpha - 5", "-2*m^2*muh + 3*alpha - 5"},
        {"muh*wh^2 - wh + 1", "muh*wh^2 - wh + 1"},
        {"123456789012345678901234567890*m - 98765432109876543210987654321",
         "123456789012345678901234567890*m - 98765432109876543210987654321"},
        {"-123456789012345678901234567890*alpha^12", "-123456789012345678901234567890*alpha^12"},
    };
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p;
    size_t k;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 4, ORD_LEX);
    fmpz_mpoly_init(p, ctx);
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char *got;
        assert_int_equal(fmpz_mpoly_set_str_pretty(p, cases[k].in, names, ctx), 0);
        got = rs_polyfmt_fmpz_mpoly(p, names, ctx);
        assert_string_equal(got, cases[k].out);
        free(got);
        check_same(p, odd, ctx);
    }
    fmpz_mpoly_clear(p, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* rs_polyfmt_coeffs (issue 13: its own split for single-word exponents)
 * against FLINT's fmpz_mpoly_to_univar, the route it replaced, on 3000
 * random polynomials over every ordering (now and then times another
 * variable to the power 2^66: exponents past one word, the FLINT route),
 * each split variable; and independently: every c[e]
 * canonical (sorted, no zero terms, no x_var) and sum c[e]*x^e == p. */
static void test_coeffs_against_flint(void **state)
{
    static const ordering_t ords[] = {ORD_LEX, ORD_DEGLEX, ORD_DEGREVLEX};
    flint_rand_t rs;
    slong it;
    (void) state;
    flint_randinit(rs);
    for (it = 0; it < 3000; it++) {
        slong nv = 1 + (slong) n_randint(rs, 5), var = (slong) n_randint(rs, nv), d, e, k;
        fmpz_mpoly_ctx_t ctx;
        fmpz_mpoly_t p, sum, t;
        fmpz_mpoly_univar_t u;
        fmpz_mpoly_struct *c;
        fmpz_mpoly_ctx_init(ctx, nv, ords[it % 3]);
        fmpz_mpoly_init(p, ctx);
        fmpz_mpoly_init(sum, ctx);
        fmpz_mpoly_init(t, ctx);
        fmpz_mpoly_randtest_bits(p, rs, (slong) n_randint(rs, 30), 1 + n_randint(rs, 150),
                                 1 + n_randint(rs, 8), ctx);
        if (it % 25 == 0 && nv > 1) {
            fmpz_t big;
            fmpz_init(big);
            fmpz_one(big);
            fmpz_mul_2exp(big, big, 66);
            fmpz_mpoly_gen(t, (var + 1) % nv, ctx);
            fmpz_mpoly_pow_fmpz(t, t, big, ctx);
            fmpz_mpoly_mul(p, p, t, ctx);
            fmpz_mpoly_zero(t, ctx);
            fmpz_clear(big);
        }
        d = fmpz_mpoly_is_zero(p, ctx) ? 0 : fmpz_mpoly_degree_si(p, var, ctx);
        c = flint_malloc((d + 1) * sizeof(fmpz_mpoly_struct));
        for (e = 0; e <= d; e++) fmpz_mpoly_init(c + e, ctx);
        rs_polyfmt_coeffs(c, p, var, ctx);
        fmpz_mpoly_univar_init(u, ctx);
        fmpz_mpoly_to_univar(u, p, var, ctx);
        for (e = 0, k = fmpz_mpoly_univar_length(u, ctx) - 1; e <= d; e++) {
            assert_true(fmpz_mpoly_is_canonical(c + e, ctx));
            assert_true(fmpz_mpoly_degree_si(c + e, var, ctx) <= 0);
            if (k >= 0 && fmpz_mpoly_univar_get_term_exp_si(u, k, ctx) == e) {
                fmpz_mpoly_univar_get_term_coeff(t, u, k, ctx);
                assert_true(fmpz_mpoly_equal(c + e, t, ctx));
                k--;
            } else {
                assert_true(fmpz_mpoly_is_zero(c + e, ctx));
            }
            fmpz_mpoly_gen(t, var, ctx);
            fmpz_mpoly_pow_ui(t, t, (ulong) e, ctx);
            fmpz_mpoly_mul(t, t, c + e, ctx);
            fmpz_mpoly_add(sum, sum, t, ctx);
        }
        assert_int_equal(k, -1);
        assert_true(fmpz_mpoly_equal(sum, p, ctx));
        for (e = 0; e <= d; e++) fmpz_mpoly_clear(c + e, ctx);
        flint_free(c);
        fmpz_mpoly_univar_clear(u, ctx);
        fmpz_mpoly_clear(t, ctx);
        fmpz_mpoly_clear(sum, ctx);
        fmpz_mpoly_clear(p, ctx);
        fmpz_mpoly_ctx_clear(ctx);
    }
    flint_randclear(rs);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_against_flint),
        cmocka_unit_test(test_chunk_edges),
        cmocka_unit_test(test_by_hand),
        cmocka_unit_test(test_coeffs_against_flint),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
