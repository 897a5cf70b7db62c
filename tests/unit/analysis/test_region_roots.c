/* test_region_roots.c -- rs_region_real_roots (issue 13: the critical values
 * of `region` isolated exactly, instead of Arb's complex root finder).
 * Expectations, independent of the function:
 *   - closed forms: x^2 - 2 has the roots -sqrt(2), sqrt(2) (arb_sqrt_ui);
 *     9 x^2 + 12 x + 1 (a critical polynomial of HHT-alpha) has
 *     (-2 -+ sqrt(3)) / 3; x^3 - 2 has the one real root 2^(1/3)
 *     (arb_root_ui); 2^100 x^2 - 3 has +-sqrt(3) 2^-50 (a bound far below 1);
 *   - Arb's certified complex roots (arb_fmpz_poly_complex_roots, real roots
 *     first, ascending) of random irreducible polynomials of degree 2-9 with
 *     FLINT's real root count (fmpz_poly_num_real_roots): every enclosure
 *     must overlap Arb's, in the same order, and be 2^-(prec+2)-narrow. */
#include "testutil.h"
#include <acb.h>
#include <arb_fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include "analysis/an_region.h"

/* every ball of x narrow: rad <= 2^-(prec+2) |x| */
static int narrow(arb_srcptr x, slong n, slong prec)
{
    slong i;
    for (i = 0; i < n; i++)
        if (arb_rel_accuracy_bits(x + i) < prec + 1) return 0;
    return 1;
}

static void test_closed_forms(void **state)
{
    fmpz_poly_t g;
    arb_ptr x = _arb_vec_init(2);
    arb_t r, t;
    (void) state;
    fmpz_poly_init(g);
    arb_init(r); arb_init(t);

    fmpz_poly_set_str(g, "3  -2 0 1");              /* x^2 - 2 */
    assert_true(rs_region_real_roots(x, g, 2, 128));
    arb_sqrt_ui(r, 2, 200);
    assert_true(arb_overlaps(x + 1, r));
    arb_neg(r, r);
    assert_true(arb_overlaps(x + 0, r));
    assert_true(narrow(x, 2, 128));

    fmpz_poly_set_str(g, "3  1 12 9");              /* 9x^2 + 12x + 1 */
    assert_true(rs_region_real_roots(x, g, 2, 128));
    arb_sqrt_ui(t, 3, 200);
    arb_add_ui(r, t, 2, 200);
    arb_div_si(r, r, -3, 200);                      /* (-2 - sqrt 3)/3 */
    assert_true(arb_overlaps(x + 0, r));
    arb_sub_ui(r, t, 2, 200);
    arb_div_ui(r, r, 3, 200);                       /* (-2 + sqrt 3)/3 */
    assert_true(arb_overlaps(x + 1, r));
    assert_true(narrow(x, 2, 128));

    fmpz_poly_set_str(g, "4  -2 0 0 1");            /* x^3 - 2 */
    assert_true(rs_region_real_roots(x, g, 1, 128));
    arb_set_ui(t, 2);
    arb_root_ui(r, t, 3, 200);
    assert_true(arb_overlaps(x + 0, r));
    assert_true(narrow(x, 1, 128));

    fmpz_poly_zero(g);                              /* 2^100 x^2 - 3 */
    fmpz_poly_set_coeff_si(g, 0, -3);
    fmpz_poly_set_coeff_ui(g, 2, 1);
    fmpz_mul_2exp(g->coeffs + 2, g->coeffs + 2, 100);
    assert_true(rs_region_real_roots(x, g, 2, 128));
    arb_sqrt_ui(r, 3, 200);
    arb_mul_2exp_si(r, r, -50);
    assert_true(arb_overlaps(x + 1, r));
    assert_true(narrow(x, 2, 128));

    /* a wrong count is reported, not filled in */
    fmpz_poly_set_str(g, "3  -2 0 1");
    assert_false(rs_region_real_roots(x, g, 1, 128));

    _arb_vec_clear(x, 2);
    arb_clear(r); arb_clear(t);
    fmpz_poly_clear(g);
}

static void test_against_arb(void **state)
{
    flint_rand_t st;
    fmpz_poly_t f;
    fmpz_poly_factor_t fac;
    slong trial, checked = 0;
    (void) state;
    flint_randinit(st);
    fmpz_poly_init(f);
    for (trial = 0; trial < 300; trial++) {
        slong i;
        fmpz_poly_randtest_not_zero(f, st, 2 + n_randint(st, 8), 1 + n_randint(st, 60));
        fmpz_poly_factor_init(fac);
        fmpz_poly_factor(fac, f);
        for (i = 0; i < fac->num; i++) {
            const fmpz_poly_struct *g = fac->p + i;
            slong d = fmpz_poly_degree(g), nreal, k;
            slong prec = n_randint(st, 2) ? 128 : 64;
            acb_ptr z;
            arb_ptr x;
            if (d < 2) continue;
            nreal = fmpz_poly_num_real_roots(g);
            if (nreal == 0) continue;
            z = _acb_vec_init(d);
            x = _arb_vec_init(nreal);
            arb_fmpz_poly_complex_roots(z, g, 0, prec);
            assert_true(rs_region_real_roots(x, g, nreal, prec));
            for (k = 0; k < nreal; k++) {
                assert_true(arb_is_zero(acb_imagref(z + k)));
                assert_true(arb_overlaps(x + k, acb_realref(z + k)));
            }
            assert_true(narrow(x, nreal, prec));
            checked++;
            _acb_vec_clear(z, d);
            _arb_vec_clear(x, nreal);
        }
        fmpz_poly_factor_clear(fac);
    }
    assert_true(checked > 100);
    fmpz_poly_clear(f);
    flint_randclear(st);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_forms),
        cmocka_unit_test(test_against_arb),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
