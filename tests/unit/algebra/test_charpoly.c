/* test_charpoly.c -- the fraction-free determinant against an independent
 * evaluation: exact rational determinants (fmpq_mat_det, Gaussian
 * elimination over Q) of the matrix evaluated at random rational points. */
#include "testutil.h"
#include <string.h>
#include <flint/fmpq_mat.h>
#include <fmpq_vec.h>
#include "recstab/casefile.h"
#include "recstab/scheme.h"
#include "recstab/charpoly.h"

static void random_point(fmpq *pt, slong nvars, flint_rand_t st)
{
    slong v;
    for (v = 0; v < nvars; v++)
        fmpq_set_si(pt + v, (slong) n_randint(st, 41) - 20, 1 + n_randint(st, 9));
}

/* Random n x n matrices over Z[a, b, lambda], some entries zero so that
 * pivoting is exercised; compare det at 5 random points. */
static void test_random_det(void **state)
{
    flint_rand_t st;
    fmpz_mpoly_ctx_t ctx;
    slong trial;
    (void) state;
    flint_randinit(st);
    fmpz_mpoly_ctx_init(ctx, 3, ORD_LEX);
    for (trial = 0; trial < 60; trial++) {
        slong n = 1 + (slong) n_randint(st, 5), i, k;
        fmpz_mpoly_struct *A = flint_malloc(n * n * sizeof(fmpz_mpoly_struct));
        fmpz_mpoly_struct *B = flint_malloc(n * n * sizeof(fmpz_mpoly_struct));
        fmpz_mpoly_t det;
        rs_error_t err;
        rs_error_init(err);
        fmpz_mpoly_init(det, ctx);
        for (i = 0; i < n * n; i++) {
            fmpz_mpoly_init(A + i, ctx);
            fmpz_mpoly_init(B + i, ctx);
            if (n_randint(st, 3) != 0)
                fmpz_mpoly_randtest_bound(A + i, st, 4, 5, 3, ctx);
            fmpz_mpoly_set(B + i, A + i, ctx);
        }
        assert_int_equal(rs_charpoly_det(det, B, n, 1000000, ctx, err), RS_OK);
        for (k = 0; k < 5; k++) {
            fmpq pt[3];
            fmpq_t got;
            fmpq_mat_t M;
            fmpq_t want;
            slong v;
            fmpq *ptp[3];
            for (v = 0; v < 3; v++) { fmpq_init(pt + v); ptp[v] = pt + v; }
            random_point(pt, 3, st);
            fmpq_init(got); fmpq_init(want);
            fmpq_mat_init(M, n, n);
            for (i = 0; i < n * n; i++)
                tu_eval_fmpz_mpoly(fmpq_mat_entry(M, i / n, i % n), A + i, ptp, ctx);
            fmpq_mat_det(want, M);
            tu_eval_fmpz_mpoly(got, det, ptp, ctx);
            assert_true(fmpq_equal(got, want));
            fmpq_mat_clear(M);
            fmpq_clear(got); fmpq_clear(want);
            for (v = 0; v < 3; v++) fmpq_clear(pt + v);
        }
        for (i = 0; i < n * n; i++) { fmpz_mpoly_clear(A + i, ctx); fmpz_mpoly_clear(B + i, ctx); }
        flint_free(A); flint_free(B);
        fmpz_mpoly_clear(det, ctx);
    }
    fmpz_mpoly_ctx_clear(ctx);
    flint_randclear(st);
}

/* The whole pipeline on the Park case: det(M) = content * lambda^k * p at
 * random points, M evaluated entry by entry. */
static void test_pipeline_park(void **state)
{
    rs_case_t c;
    rs_model_t m;
    rs_scheme_t s;
    rs_charpoly_t cp;
    rs_error_t err;
    flint_rand_t st;
    slong k, i, n;
    (void) state;
    rs_case_init(c);
    rs_model_init(m);
    rs_scheme_init(s);
    rs_error_init(err);
    flint_randinit(st);
    assert_int_equal(rs_case_parse_file(c, RS_SOURCE_DIR "/cases/park-staggered.case", err), RS_OK);
    assert_int_equal(rs_model_lower(m, c, err), RS_OK);
    assert_int_equal(rs_scheme_build(s, m, err), RS_OK);
    rs_charpoly_init(cp, s);
    assert_int_equal(rs_charpoly_compute(cp, s, err), RS_OK);
    assert_int_equal(cp->degree, 4);
    n = s->n;
    for (k = 0; k < 10; k++) {
        fmpq *pt = _fmpq_vec_init(s->nvars);
        fmpq **ptp = flint_malloc(s->nvars * sizeof(fmpq *));
        fmpq_mat_t M;
        fmpq_t want, got, lam;
        random_point(pt, s->nvars, st);
        for (i = 0; i < s->nvars; i++) ptp[i] = pt + i;
        fmpq_mat_init(M, n, n);
        fmpq_init(want); fmpq_init(got); fmpq_init(lam);
        for (i = 0; i < n * n; i++)
            fmpq_mpoly_evaluate_all_fmpq(fmpq_mat_entry(M, i / n, i % n), s->M + i, ptp, s->ctx);
        fmpq_mat_det(want, M);
        tu_eval_fmpz_mpoly(got, cp->p, ptp, s->zctx);
        fmpq_pow_si(lam, pt + s->lambda_var, cp->removed_lambda_power);
        fmpq_mul(got, got, lam);
        fmpq_mul(got, got, cp->content);
        assert_true(fmpq_equal(got, want));
        fmpq_mat_clear(M);
        fmpq_clear(want); fmpq_clear(got); fmpq_clear(lam);
        _fmpq_vec_clear(pt, s->nvars);
        flint_free(ptp);
    }
    rs_charpoly_clear(cp, s);
    rs_scheme_clear(s);
    rs_model_clear(m);
    rs_case_clear(c);
    flint_randclear(st);
}

/* Normalisation: lambda^2 * (-6 lambda + 4) -> 3 lambda - 2, k = 2, scale -2. */
static void test_normalise(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t q, e;
    fmpq_t scale;
    const char *vars[] = {"lambda"};
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 1, ORD_LEX);
    fmpz_mpoly_init(q, ctx); fmpz_mpoly_init(e, ctx);
    fmpq_init(scale); fmpq_one(scale);
    fmpz_mpoly_set_str_pretty(q, "-6*lambda^3 + 4*lambda^2", vars, ctx);
    fmpz_mpoly_set_str_pretty(e, "3*lambda - 2", vars, ctx);
    assert_int_equal(rs_charpoly_normalise(q, scale, 0, ctx), 2);
    assert_true(fmpz_mpoly_equal(q, e, ctx));
    assert_int_equal(fmpz_get_si(fmpq_numref(scale)), -2);
    fmpz_mpoly_clear(q, ctx); fmpz_mpoly_clear(e, ctx);
    fmpq_clear(scale);
    fmpz_mpoly_ctx_clear(ctx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_det),
        cmocka_unit_test(test_pipeline_park),
        cmocka_unit_test(test_normalise),
    };
    return cmocka_run_group_tests_name("charpoly", tests, NULL, NULL);
}
