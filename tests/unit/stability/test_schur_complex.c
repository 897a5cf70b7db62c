/* test_schur_complex.c -- Schur-Cohn over Q(i) (stability/schur_complex.c)
 * against hand examples and against Arb's certified roots of the complex
 * polynomial (acb_poly_find_roots, which certifies the roots it isolates;
 * exact Gaussian-rational coefficients), an independent root finder. */
#include "testutil.h"
#include <acb_poly.h>
#include "stability/schur_complex.h"

/* p from integer pairs (re, im) per coefficient, low degree first */
static void set_poly(fmpq_poly_t re, fmpq_poly_t im, const slong *c, slong n, slong den)
{
    slong k;
    fmpq_poly_zero(re);
    fmpq_poly_zero(im);
    for (k = 0; k < n; k++) {
        fmpq_t x;
        fmpq_init(x);
        fmpq_set_si(x, c[2 * k], (ulong) den);
        fmpq_poly_set_coeff_fmpq(re, k, x);
        fmpq_set_si(x, c[2 * k + 1], (ulong) den);
        fmpq_poly_set_coeff_fmpq(im, k, x);
        fmpq_clear(x);
    }
}

static rs_status_t status_of(const slong *c, slong n, slong den)
{
    fmpq_poly_t re, im;
    rs_status_t st;
    rs_error_t err;
    fmpq_poly_init(re); fmpq_poly_init(im);
    rs_error_init(err);
    set_poly(re, im, c, n, den);
    assert_int_equal(rs_schur_complex_status(&st, re, im, n - 1, err), RS_OK);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    return st;
}

static void test_hand(void **state)
{
    /* lambda - i/2: root i/2 inside */
    static const slong a[] = {0, -1, 2, 0};
    /* lambda^2 + 1: roots +-i on the circle, simple */
    static const slong b[] = {1, 0, 0, 0, 1, 0};
    /* (lambda - i)^2 = lambda^2 - 2i lambda - 1: a double root on the circle */
    static const slong c[] = {-1, 0, 0, -2, 1, 0};
    /* 5 lambda - (3 + 4i): root (3 + 4i)/5 on the circle (3^2 + 4^2 = 5^2) */
    static const slong d[] = {-3, -4, 5, 0};
    /* lambda - (1 + i)/2 * 3: |root| = 3/sqrt 2 > 1 */
    static const slong e[] = {-3, -3, 2, 0};
    /* the leapfrog polynomial lambda^2 + 2 i nu s lambda - 1 at nu s = 1/2:
     * roots -i/2 +- sqrt(3)/2, both on the circle, simple */
    static const slong f[] = {-1, 0, 0, 1, 1, 0};
    /* ... and at nu s = 2: roots i(-2 +- sqrt 3), one outside */
    static const slong g[] = {-1, 0, 0, 4, 1, 0};
    (void) state;
    assert_int_equal(status_of(a, 2, 2), RS_STATUS_STABLE);
    assert_int_equal(status_of(b, 3, 1), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(c, 3, 1), RS_STATUS_UNSTABLE);
    assert_int_equal(status_of(d, 2, 5), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(e, 2, 2), RS_STATUS_UNSTABLE);
    assert_int_equal(status_of(f, 3, 1), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(g, 3, 1), RS_STATUS_UNSTABLE);
}

/* all roots strictly inside by certified Arb roots: 1, 0 (one outside or
 * on), -1 (a ball meets the circle: not decided numerically) */
static int arb_inside(const fmpq_poly_t re, const fmpq_poly_t im)
{
    slong n = FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im)), k, prec;
    int res = -1;
    for (prec = 64; prec <= 1024 && res == -1; prec *= 2) {
        acb_poly_t p;
        acb_ptr r = _acb_vec_init(n);
        slong found;
        acb_poly_init(p);
        for (k = 0; k <= n; k++) {
            acb_t c;
            fmpq_t x;
            acb_init(c);
            fmpq_init(x);
            fmpq_poly_get_coeff_fmpq(x, re, k);
            arb_set_fmpq(acb_realref(c), x, prec);
            fmpq_poly_get_coeff_fmpq(x, im, k);
            arb_set_fmpq(acb_imagref(c), x, prec);
            acb_poly_set_coeff_acb(p, k, c);
            acb_clear(c);
            fmpq_clear(x);
        }
        found = acb_poly_find_roots(r, p, NULL, 0, prec);   /* the number of isolated (certified) roots */
        if (found == n) {
            arb_t ab, one;
            int all = 1, undecided = 0;
            arb_init(ab); arb_init(one);
            arb_one(one);
            for (k = 0; k < n; k++) {
                acb_abs(ab, r + k, prec);
                if (arb_lt(ab, one)) continue;
                all = 0;
                if (!arb_gt(ab, one)) undecided = 1;
            }
            res = all ? 1 : (undecided ? -1 : 0);
            arb_clear(ab); arb_clear(one);
        }
        acb_poly_clear(p);
        _acb_vec_clear(r, n);
    }
    return res;
}

static void test_random_vs_arb(void **state)
{
    flint_rand_t rs;
    fmpq_poly_t re, im;
    slong t, compared = 0;
    (void) state;
    flint_randinit(rs);
    fmpq_poly_init(re); fmpq_poly_init(im);
    for (t = 0; t < 400; t++) {
        slong n = 1 + (slong) n_randint(rs, 5), k;
        slong c[14];
        int want;
        for (k = 0; k < 2 * (n + 1); k++) c[k] = (slong) n_randint(rs, 13) - 6;
        if (c[2 * n] == 0 && c[2 * n + 1] == 0) c[2 * n] = 7 + (slong) n_randint(rs, 8);   /* exact degree n */
        set_poly(re, im, c, n + 1, 1 + (slong) n_randint(rs, 4));
        want = arb_inside(re, im);
        if (want < 0) continue;
        assert_int_equal(rs_schur_complex_inside(re, im), want);
        compared++;
    }
    assert_true(compared > 300);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    flint_randclear(rs);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand),
        cmocka_unit_test(test_random_vs_arb),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
