/* test_ladder.c -- cmocka tests of the numeric stage's sweep machinery:
 * the per-point verdict ladder with an injected exact rung (ladder.h), the
 * grid (numeric/grid.h) and the point loop (numeric/engine.h).
 *
 * Expected values are derived by hand, never from the code under test:
 *   (2l - 1)(3l + 1)          roots 1/2, -1/3: stable, rho = 1/2, decided
 *                             numerically (the exact rung must not run)
 *   (l - 2)(l - 1/3)          rho = 2: unstable, numerically
 *   l^2 + 1                   roots +-i on the circle: no disc can exclude
 *                             the circle, so only the exact rung decides; the
 *                             stub reports the hand count inside 0, on 2,
 *                             outside 0 (marginal) and the ladder must pass
 *                             it through with rho = 1 exactly
 *   (l - 1)^2 (l + 1/2)       a double root at 1: the stub's count has
 *                             max_on_mult 2, so repeated_on is set
 *   3 l^4 (l - 1/5)           the lambda^4 factor is removed first: one root
 *                             1/5, decided exactly (degree 1), rho = 1/5
 *   grid: A + i (B - A)/K exactly; log spacing keeps the endpoints exact;
 *   shards: floor((I-1)P/N) .. floor(I P/N) partition [0, P).
 */
#include "testutil.h"
#include <math.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include <gsl/gsl_errno.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "recstab/ladder.h"
#include "numeric/grid.h"
#include "numeric/engine.h"

/* The injected exact rung: the hand count of the one polynomial a test
 * names (its primitive part), and how often it was asked. */
typedef struct {
    const char *poly;     /* fmpz_poly_set_str form of the primitive polynomial expected */
    rs_ladder_count_t count;
    int calls;
} stub_t;

static int stub_exact(rs_ladder_count_t *c, const fmpz_poly_t p, void *arg, rs_error_t err)
{
    stub_t *s = arg;
    fmpz_poly_t want;
    (void) err;
    s->calls++;
    fmpz_poly_init(want);
    fmpz_poly_set_str(want, s->poly);
    assert_true(fmpz_poly_equal(p, want));   /* the rung gets the primitive polynomial */
    fmpz_poly_clear(want);
    *c = s->count;
    return RS_OK;
}

static void decide(rs_sweep_point_t *pt, const char *poly, stub_t *s, int first_level)
{
    fmpz_poly_t p;
    rs_error_t err;
    fmpz_poly_init(p);
    rs_error_init(err);
    fmpz_poly_set_str(p, poly);
    assert_int_equal(rs_ladder_decide(pt, p, first_level, stub_exact, s, err), RS_OK);
    assert_int_equal(pt->status, RS_OK);
    fmpz_poly_clear(p);
}

static void test_ladder_numeric_levels(void **state)
{
    stub_t s = {"0", {0, 0, 0, 0, 0}, 0};
    rs_sweep_point_t pt;
    int lv;
    (void) state;
    /* (2l - 1)(3l + 1) = 6l^2 - l - 1 */
    for (lv = RS_LEVEL_FAST; lv <= RS_LEVEL_PREC256; lv++) {
        decide(&pt, "3  -1 -1 6", &s, lv);
        assert_int_equal(pt.verdict, 0);
        assert_int_equal(pt.level, lv);
        assert_true(pt.rho_lower <= 0.5 && 0.5 <= pt.rho_upper && pt.rho_upper < 1);
    }
    /* (l - 2)(3l - 1) = 3l^2 - 7l + 2 */
    decide(&pt, "3  2 -7 3", &s, RS_LEVEL_FAST);
    assert_int_equal(pt.verdict, 2);
    assert_true(pt.rho_lower <= 2 && 2 <= pt.rho_upper && pt.rho_lower > 1);
    assert_int_equal(s.calls, 0);
}

static void test_ladder_exact_rung(void **state)
{
    stub_t circle = {"3  1 0 1", {0, 2, 0, 1, 1}, 0};
    /* (l - 1)^2 (2l + 1) = 2l^3 - 3l^2 + 1 */
    stub_t twice = {"4  1 0 -3 2", {1, 2, 0, 2, 2}, 0};
    rs_sweep_point_t pt;
    (void) state;
    decide(&pt, "3  1 0 1", &circle, RS_LEVEL_FAST);
    assert_int_equal(circle.calls, 1);
    assert_int_equal(pt.verdict, 1);
    assert_int_equal(pt.level, RS_LEVEL_EXACT);
    assert_int_equal(pt.repeated_on, 0);
    assert_true(pt.rho_lower == 1.0 && pt.rho_upper == 1.0);
    /* the same polynomial times 3: the rung still gets the primitive part */
    decide(&pt, "3  3 0 3", &circle, RS_LEVEL_EXACT);
    assert_int_equal(circle.calls, 2);
    decide(&pt, "4  1 0 -3 2", &twice, RS_LEVEL_FAST);
    assert_int_equal(twice.calls, 1);
    assert_int_equal(pt.verdict, 2);
    assert_int_equal(pt.repeated_on, 1);
}

static void test_ladder_small_degrees(void **state)
{
    stub_t s = {"0", {0, 0, 0, 0, 0}, 0};
    rs_sweep_point_t pt;
    (void) state;
    /* 3 l^4 (l - 1/5) = 15 l^5 - 3 l^4 */
    decide(&pt, "6  0 0 0 0 -3 15", &s, RS_LEVEL_FAST);
    assert_int_equal(pt.verdict, 0);
    assert_int_equal(pt.level, RS_LEVEL_EXACT);
    assert_true(pt.rho_lower <= 0.2 && 0.2 <= pt.rho_upper && pt.rho_upper - pt.rho_lower < 1e-15);
    /* 7 l^3: every root at 0 */
    decide(&pt, "4  0 0 0 7", &s, RS_LEVEL_FAST);
    assert_int_equal(pt.verdict, 0);
    assert_true(pt.rho_lower == 0 && pt.rho_upper == 0);
    /* p == 0: undefined */
    decide(&pt, "0", &s, RS_LEVEL_FAST);
    assert_int_equal(pt.verdict, -1);
    assert_int_equal(s.calls, 0);
}

static void test_grid(void **state)
{
    fmpq_t A, B, x, want;
    fmpq *ax;
    slong i, lo, hi, prev, N, I;
    (void) state;
    fmpq_init(A); fmpq_init(B); fmpq_init(x); fmpq_init(want);
    fmpq_set_si(A, -1, 3);
    fmpq_set_si(B, 2, 1);
    for (i = 0; i <= 7; i++) {
        /* -1/3 + i (7/3)/7 = (i - 1)/3 */
        rs_grid_value(x, A, B, i, 7, 0);
        fmpq_set_si(want, i - 1, 3);
        assert_true(fmpq_equal(x, want));
    }
    ax = rs_grid_axis(A, B, 8);
    for (i = 0; i < 8; i++) {
        fmpq_set_si(want, i - 1, 3);
        assert_true(fmpq_equal(ax + i, want));
    }
    _fmpq_vec_clear(ax, 8);
    /* log spacing from 1/1000 to 10: endpoints exact, the middle 10^(-1) within 1e-13 relative */
    fmpq_set_si(A, 1, 1000);
    fmpq_set_si(B, 10, 1);
    rs_grid_value(x, A, B, 0, 4, 1);
    assert_true(fmpq_equal(x, A));
    rs_grid_value(x, A, B, 4, 4, 1);
    assert_true(fmpq_equal(x, B));
    rs_grid_value(x, A, B, 2, 4, 1);
    assert_true(fabs(fmpq_get_d(x) / 0.1 - 1) <= 1.1e-13);
    /* shards partition [0, P) in order */
    for (N = 1; N <= 7; N++) {
        prev = 0;
        for (I = 1; I <= N; I++) {
            rs_grid_shard_range(&lo, &hi, 23, I, N);
            assert_int_equal(lo, prev);
            assert_int_equal(lo, (I - 1) * 23 / N);
            assert_int_equal(hi, I * 23 / N);
            prev = hi;
        }
        assert_int_equal(prev, 23);
    }
    fmpq_clear(A); fmpq_clear(B); fmpq_clear(x); fmpq_clear(want);
}

/* the point callback of the engine test: idx^2 + arg's offset */
static void square_point(void *pt, slong idx, void *arg)
{
    *(slong *) pt = idx * idx + *(const slong *) arg;
}

static void test_engine(void **state)
{
    slong pts[40], off = 5, k;
    rs_engine_t e;
    int serial;
    (void) state;
    memset(&e, 0, sizeof e);
    e.point = square_point;
    e.arg = &off;
    e.what = "test";
#ifdef _OPENMP
    omp_set_num_threads(2);
#endif
    for (serial = 0; serial <= 1; serial++) {
        e.serial = serial;
        for (k = 0; k < 40; k++) pts[k] = -1;
        /* points [10, 50): pts[k] is point 10 + k */
        rs_engine_run(pts, sizeof(slong), 10, 50, &e);
        for (k = 0; k < 40; k++) assert_int_equal(pts[k], (10 + k) * (10 + k) + 5);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ladder_numeric_levels),
        cmocka_unit_test(test_ladder_exact_rung),
        cmocka_unit_test(test_ladder_small_degrees),
        cmocka_unit_test(test_grid),
        cmocka_unit_test(test_engine),
    };
    gsl_set_error_handler_off();   /* once, as the recstab command does (sweep.h) */
    return cmocka_run_group_tests(tests, NULL, NULL);
}
