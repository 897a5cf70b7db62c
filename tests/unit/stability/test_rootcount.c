/* test_rootcount.c -- rs_rootcount_t helpers and rs_rootcount_factor on
 * polynomials whose roots are known in closed form. */
#include <string.h>
#include "testutil.h"
#include <flint/fmpz_poly.h>
#include "recstab/rootcount.h"

#include "closed_forms.h"

static void expect_case(rs_rootcount_t rc, const closed_case *c)
{
    rs_rootcount_init(rc);
    rc->degree = c->deg;
    rc->inside = c->in;
    rc->on = c->on;
    rc->outside = c->out;
    rc->at_one = c->at1;
    rc->at_minus_one = c->atm1;
    rc->on_mult[1] = c->mult1;
    rc->on_mult[2] = c->mult2;
}

static void test_closed_forms(void **state)
{
    size_t i;
    (void) state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        fmpz_poly_t p;
        rs_rootcount_t got, want;
        rs_error_t err;
        fmpz_poly_init(p);
        rs_error_init(err);
        poly_set(p, cases[i].deg, cases[i].c);
        expect_case(want, cases + i);
        assert_int_equal(rs_rootcount_factor(got, p, err), RS_OK);
        if (!rs_rootcount_equal(got, want))
            fail_msg("%s: in %ld on %ld out %ld", cases[i].name,
                     (long) got->inside, (long) got->on, (long) got->outside);
        assert_int_equal(rs_rootcount_status(got), cases[i].status);
        fmpz_poly_clear(p);
    }
}

/* Status rules from the header: outside or repeated circle root ->
 * unstable; simple circle roots only -> marginal. */
static void test_helpers(void **state)
{
    rs_rootcount_t a, b;
    (void) state;
    rs_rootcount_init(a);
    rs_rootcount_init(b);
    assert_true(rs_rootcount_equal(a, b));
    assert_int_equal(rs_rootcount_status(a), RS_STATUS_STABLE);
    assert_int_equal(rs_rootcount_max_on_mult(a), 0);
    rs_rootcount_add_on(a, 1, 2);
    assert_int_equal(a->on, 2);
    assert_int_equal(rs_rootcount_status(a), RS_STATUS_MARGINAL);
    assert_false(rs_rootcount_equal(a, b));
    rs_rootcount_add_on(a, 3, 1);
    assert_int_equal(a->on, 5);
    assert_int_equal(rs_rootcount_max_on_mult(a), 3);
    assert_int_equal(rs_rootcount_status(a), RS_STATUS_UNSTABLE);
    /* multiplicities beyond the table go to the last slot */
    rs_rootcount_add_on(b, 100, 1);
    assert_int_equal(b->on_mult[RS_ROOTCOUNT_MAXMULT - 1], 1);
    assert_int_equal(b->on, 100);
    assert_string_equal(rs_status_name(RS_STATUS_STABLE), "stable");
    assert_string_equal(rs_status_name(RS_STATUS_MARGINAL), "marginal");
    assert_string_equal(rs_status_name(RS_STATUS_UNSTABLE), "unstable");
    rs_rootcount_clear(a);
    rs_rootcount_clear(b);
}

/* lambda^-1 (lambda^2 - lambda + 1) = x - 1;
 * lambda^-2 (lambda^4 + 1) = x^2 - 2; lambda^-2 (l^4 + 3l^3 + 5l^2 + 3l + 1)
 * = (x^2 - 2) + 3x + 5 = x^2 + 3x + 3 (hand expansion). */
static void test_reciprocal_to_x(void **state)
{
    fmpz_poly_t g, F, want;
    static const long g1[] = {1, -1, 1}, g2[] = {1, 0, 0, 0, 1},
                      g3[] = {1, 3, 5, 3, 1}, w1[] = {1, -1}, w2[] = {1, 0, -2},
                      w3[] = {1, 3, 3};
    (void) state;
    fmpz_poly_init(g);
    fmpz_poly_init(F);
    fmpz_poly_init(want);
    poly_set(g, 2, g1);
    rs_rootcount_reciprocal_to_x(F, g);
    poly_set(want, 1, w1);
    assert_true(fmpz_poly_equal(F, want));
    poly_set(g, 4, g2);
    rs_rootcount_reciprocal_to_x(F, g);
    poly_set(want, 2, w2);
    assert_true(fmpz_poly_equal(F, want));
    poly_set(g, 4, g3);
    rs_rootcount_reciprocal_to_x(F, g);
    poly_set(want, 2, w3);
    assert_true(fmpz_poly_equal(F, want));
    fmpz_poly_clear(g);
    fmpz_poly_clear(F);
    fmpz_poly_clear(want);
}

/* Sturm counts: x^2 - 2 has roots +-1.414 (both in (-2, 2));
 * (x - 1)^2 (x - 5) has the distinct roots 1 and 5; x^2 + 1 none. */
static void test_sturm(void **state)
{
    fmpz_poly_t f;
    static const long f1[] = {1, 0, -2}, f2[] = {1, -7, 11, -5},
                      f3[] = {1, 0, 1};
    (void) state;
    fmpz_poly_init(f);
    poly_set(f, 2, f1);
    assert_int_equal(rs_rootcount_real_roots_open(f, -2, 2), 2);
    assert_int_equal(rs_rootcount_real_roots_open(f, 0, 2), 1);
    poly_set(f, 3, f2);
    assert_int_equal(rs_rootcount_real_roots_open(f, -2, 2), 1);
    assert_int_equal(rs_rootcount_real_roots_open(f, -2, 6), 2);
    poly_set(f, 2, f3);
    assert_int_equal(rs_rootcount_real_roots_open(f, -2, 2), 0);
    fmpz_poly_clear(f);
}

/* lambda^12 - 1: the 12 twelfth roots of unity, all simple, including +-1
 * (cyclotomic factors of degree 1, 1, 2, 2, 2, 4). */
static void test_roots_of_unity(void **state)
{
    fmpz_poly_t p;
    rs_rootcount_t rc;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_set_coeff_si(p, 12, 1);
    fmpz_poly_set_coeff_si(p, 0, -1);
    assert_int_equal(rs_rootcount_factor(rc, p, err), RS_OK);
    assert_int_equal(rc->on, 12);
    assert_int_equal(rc->on_mult[1], 12);
    assert_int_equal(rc->at_one, 1);
    assert_int_equal(rc->at_minus_one, 1);
    assert_int_equal(rs_rootcount_status(rc), RS_STATUS_MARGINAL);
    fmpz_poly_clear(p);
}

/* D^2 lambda^2 + (D^2 - 1), D = 10^20: roots +-i sqrt(1 - 1/D^2), inside by
 * 10^-40 (construction); irreducible and not self-reciprocal, so Arb must
 * raise its precision past 64 bits to decide.  Flipping to D^2 + 1 puts
 * them outside by the same margin. */
static void test_close_to_circle(void **state)
{
    fmpz_poly_t p;
    fmpz_t D2;
    rs_rootcount_t rc;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    fmpz_init(D2);
    fmpz_set_ui(D2, 10);
    fmpz_pow_ui(D2, D2, 40);
    fmpz_poly_set_coeff_fmpz(p, 2, D2);
    fmpz_sub_ui(D2, D2, 1);
    fmpz_poly_set_coeff_fmpz(p, 0, D2);
    assert_int_equal(rs_rootcount_factor(rc, p, err), RS_OK);
    assert_int_equal(rc->inside, 2);
    assert_int_equal(rc->on, 0);
    fmpz_add_ui(D2, D2, 2);
    fmpz_poly_set_coeff_fmpz(p, 0, D2);
    assert_int_equal(rs_rootcount_factor(rc, p, err), RS_OK);
    assert_int_equal(rc->outside, 2);
    fmpz_poly_clear(p);
    fmpz_clear(D2);
}

static void test_zero_poly(void **state)
{
    fmpz_poly_t p;
    rs_rootcount_t rc;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    rs_error_init(err);
    assert_int_equal(rs_rootcount_factor(rc, p, err), RS_ERR_INPUT);
    assert_int_equal(err->code, RS_ERR_INPUT);
    fmpz_poly_clear(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_forms),
        cmocka_unit_test(test_helpers),
        cmocka_unit_test(test_reciprocal_to_x),
        cmocka_unit_test(test_sturm),
        cmocka_unit_test(test_roots_of_unity),
        cmocka_unit_test(test_close_to_circle),
        cmocka_unit_test(test_zero_poly),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
