/* test_mfactor.c -- rs_mpoly_factor (the factorisation in the ring of the
 * variables that occur) against FLINT's fmpz_mpoly_factor in the whole
 * context: the same constant, factors, exponents, in the same order, for
 * random products of random factors in 1 to 3 of 5 variables (the shapes of
 * the Hurwitz conditions of a cell: one or two parameters left); and the
 * factorisation multiplies back to the input.  rs_fmpz_poly_squarefree_part
 * against square-free parts expanded by hand. */
#include "testutil.h"
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
#include <flint/fmpz_poly.h>
#include "algebra/mfactor.h"

static void random_in_vars(fmpz_mpoly_t f, const slong *use, slong nuse, flint_rand_t st,
                           const fmpz_mpoly_ctx_t ctx)
{
    slong nt = 1 + (slong) n_randint(st, 4), t, j, nv = ctx->minfo->nvars;
    ulong *e = flint_calloc(nv, sizeof(ulong));
    fmpz_t c;
    fmpz_init(c);
    fmpz_mpoly_zero(f, ctx);
    for (t = 0; t < nt; t++) {
        for (j = 0; j < nv; j++) e[j] = 0;
        for (j = 0; j < nuse; j++) e[use[j]] = n_randint(st, 3);
        fmpz_set_si(c, (slong) n_randint(st, 19) - 9);
        fmpz_mpoly_set_coeff_fmpz_ui(f, c, e, ctx);
    }
    fmpz_clear(c);
    flint_free(e);
}

static void test_same_as_flint(void **state)
{
    flint_rand_t st;
    fmpz_mpoly_ctx_t ctx;
    slong trial, checked = 0;
    (void) state;
    flint_randinit(st);
    fmpz_mpoly_ctx_init(ctx, 5, ORD_LEX);
    for (trial = 0; trial < 300; trial++) {
        slong use[3], nuse = 1 + (slong) n_randint(st, 3), j, nf = 1 + (slong) n_randint(st, 3);
        fmpz_mpoly_t f, g, prod;
        fmpz_mpoly_factor_t a, b;
        int oka, okb;
        for (j = 0; j < nuse; j++) use[j] = (slong) n_randint(st, 5);
        fmpz_mpoly_init(f, ctx); fmpz_mpoly_init(g, ctx); fmpz_mpoly_init(prod, ctx);
        fmpz_mpoly_factor_init(a, ctx); fmpz_mpoly_factor_init(b, ctx);
        fmpz_mpoly_one(f, ctx);
        for (j = 0; j < nf; j++) {          /* repeated factors sometimes */
            random_in_vars(g, use, nuse, st, ctx);
            fmpz_mpoly_mul(f, f, g, ctx);
            if (n_randint(st, 4) == 0) fmpz_mpoly_mul(f, f, g, ctx);
        }
        if (!fmpz_mpoly_is_zero(f, ctx)) {
            oka = fmpz_mpoly_factor(a, f, ctx);
            okb = rs_mpoly_factor(b, f, ctx);
            assert_int_equal(oka, okb);
            if (oka) {
                assert_true(fmpz_equal(a->constant, b->constant));
                assert_int_equal(a->num, b->num);
                for (j = 0; j < a->num; j++) {
                    assert_true(fmpz_mpoly_equal(a->poly + j, b->poly + j, ctx));
                    assert_true(fmpz_equal(a->exp + j, b->exp + j));
                }
                fmpz_mpoly_factor_expand(prod, b, ctx);
                assert_true(fmpz_mpoly_equal(prod, f, ctx));
                checked++;
            }
        }
        fmpz_mpoly_clear(f, ctx); fmpz_mpoly_clear(g, ctx); fmpz_mpoly_clear(prod, ctx);
        fmpz_mpoly_factor_clear(a, ctx); fmpz_mpoly_factor_clear(b, ctx);
    }
    assert_true(checked > 200);
    fmpz_mpoly_ctx_clear(ctx);
    flint_randclear(st);
}

/* f = c * prod (a_k x + b_k)^e_k (lin[k] = {a_k, b_k, e_k}) */
static void poly_from_factors(fmpz_poly_t f, slong c, const slong (*lin)[3], slong n)
{
    fmpz_poly_t t;
    slong k;
    fmpz_poly_init(t);
    fmpz_poly_set_si(f, c);
    for (k = 0; k < n; k++) {
        fmpz_poly_zero(t);
        fmpz_poly_set_coeff_si(t, 1, lin[k][0]);
        fmpz_poly_set_coeff_si(t, 0, lin[k][1]);
        fmpz_poly_pow(t, t, (ulong) lin[k][2]);
        fmpz_poly_mul(f, f, t);
    }
    fmpz_poly_clear(t);
}

/* r's coefficients, constant first, equal want[0..len) */
static void assert_coeffs(const fmpz_poly_t r, const slong *want, slong len)
{
    slong k;
    assert_int_equal(fmpz_poly_length(r), len);
    for (k = 0; k < len; k++) assert_true(fmpz_equal_si(r->coeffs + k, want[k]));
}

static void test_squarefree_part(void **state)
{
    /* (x - 1)^2 (x + 2)^3 (2x + 1): by hand (x - 1)(x + 2) = x^2 + x - 2,
     * times (2x + 1): 2x^3 + x^2 + 2x^2 + x - 4x - 2 = 2x^3 + 3x^2 - 3x - 2 */
    static const slong f1[][3] = {{1, -1, 2}, {1, 2, 3}, {2, 1, 1}};
    static const slong w1[] = {-2, -3, 3, 2};
    /* x^3 (x^2 + 1)^2 is not a product of linear factors: built below;
     * its square-free part x (x^2 + 1) = x^3 + x */
    static const slong w3[] = {0, 1, 0, 1};
    /* 4x^2 - 4 = 4 (x - 1)(x + 1): square-free already, primitive x^2 - 1 */
    static const slong f4[][3] = {{1, -1, 1}, {1, 1, 1}};
    static const slong w4[] = {-1, 0, 1};
    fmpz_poly_t f, r, t;
    (void) state;
    fmpz_poly_init(f); fmpz_poly_init(r); fmpz_poly_init(t);
    poly_from_factors(f, 1, f1, 3);
    rs_fmpz_poly_squarefree_part(r, f);
    assert_coeffs(r, w1, 4);
    /* -6 times it: the content and the sign go, the same part (in place) */
    poly_from_factors(f, -6, f1, 3);
    rs_fmpz_poly_squarefree_part(f, f);
    assert_coeffs(f, w1, 4);
    fmpz_poly_set_coeff_si(t, 2, 1);
    fmpz_poly_set_coeff_si(t, 0, 1);          /* x^2 + 1 */
    fmpz_poly_pow(f, t, 2);
    fmpz_poly_shift_left(f, f, 3);            /* x^3 (x^2 + 1)^2 */
    rs_fmpz_poly_squarefree_part(r, f);
    assert_coeffs(r, w3, 4);
    poly_from_factors(f, 4, f4, 2);
    rs_fmpz_poly_squarefree_part(r, f);
    assert_coeffs(r, w4, 3);
    /* constants: 1 for -5 (no root), 0 for 0 */
    fmpz_poly_set_si(f, -5);
    rs_fmpz_poly_squarefree_part(r, f);
    assert_true(fmpz_poly_is_one(r));
    fmpz_poly_zero(f);
    rs_fmpz_poly_squarefree_part(r, f);
    assert_true(fmpz_poly_is_zero(r));
    fmpz_poly_clear(f); fmpz_poly_clear(r); fmpz_poly_clear(t);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_as_flint),
        cmocka_unit_test(test_squarefree_part),
    };
    int r = cmocka_run_group_tests_name("mfactor", tests, NULL, NULL);
    flint_cleanup_master();     /* FLINT's cache of integers, for leak checkers */
    return r;
}
