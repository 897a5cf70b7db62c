/* test_mfactor.c -- rs_mpoly_factor (the factorisation in the ring of the
 * variables that occur) against FLINT's fmpz_mpoly_factor in the whole
 * context: the same constant, factors, exponents, in the same order, for
 * random products of random factors in 1 to 3 of 5 variables (the shapes of
 * the Hurwitz conditions of a cell: one or two parameters left); and the
 * factorisation multiplies back to the input. */
#include "testutil.h"
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_as_flint),
    };
    int r = cmocka_run_group_tests_name("mfactor", tests, NULL, NULL);
    flint_cleanup_master();     /* FLINT's cache of integers, for leak checkers */
    return r;
}
