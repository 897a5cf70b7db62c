/* test_cosim_fast.c -- cmocka tests of the fast certified co-simulation
 * radius (numeric/cosim_fast.h), the route of maps `of radius`.
 *
 * Independent references only:
 *   - the full certified radius rs_cosim_radius (Arb QR + acb_mat_eig_simple
 *     with precision doubling, the route before the fast path) on a grid of
 *     Li et al. force/force models: the two enclosures must meet and the
 *     fast one must hold the reference midpoint up to the reference width;
 *   - the closed form of uncoupled oscillators x'' + d x' + c x = 0
 *     integrated exactly over H = 1: |e^{lambda}| = e^{-d/2} (underdamped),
 *     so rho = e^{-d/2} of the least damped subsystem;
 *   - two equal uncoupled subsystems: every eigenvalue double, so no disc
 *     can be isolated and the fast path must decline (the caller falls back).
 * The same references for rs_cosim_check_radius (the maps' cross-check). */
#include "testutil.h"
#include <string.h>
#include "recstab/cosim.h"
#include "numeric/cosim_fast.h"

static void set_li(rs_cosim_t cs, const char *c1, const char *d1, const char *ad21, const char *acc1,
                   const char *adc1, int method, slong order)
{
    const char *s[7] = { c1, d1, "1", "1", ad21, acc1, adc1 };
    fmpq_t v[7];
    rs_error_t err;
    int i;
    for (i = 0; i < 7; i++) {
        fmpq_init(v[i]);
        assert_int_equal(fmpq_set_str(v[i], s[i], 10), 0);
    }
    assert_int_equal(rs_cosim_li_ff(cs, v[0], v[1], v[2], v[3], v[4], v[5], v[6], err), RS_OK);
    cs->method = method;
    cs->order = order;
    for (i = 0; i < 7; i++) fmpq_clear(v[i]);
}

/* fast and full certified radius on a 6 x 5 grid (acc1, c1) of the Li
 * map (cases/li-explicit-k1.case's axes), explicit k = 1 and implicit k = 1 */
static void test_grid_vs_full(void **state)
{
    static const char *acc[6] = { "0", "1/2", "1", "3/2", "2", "3" };
    static const char *c1[5] = { "1/2", "3/4", "101/100", "3/2", "2" };
    rs_cosim_t cs;
    rs_radius_t f, g;
    rs_error_t err;
    arb_t w, lo, hi;
    int i, j, meth, fast_ok = 0, check_ok = 0, total = 0;
    (void) state;
    rs_cosim_init(cs, 2, 2);
    arb_init(w);
    arb_init(lo);
    arb_init(hi);
    for (meth = 0; meth < 2; meth++)
        for (i = 0; i < 6; i++)
            for (j = 0; j < 5; j++) {
                rs_radius_init(f);
                rs_radius_init(g);
                set_li(cs, c1[j], "1/5", "1", acc[i], "1", meth ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT, 1);
                assert_int_equal(rs_cosim_radius(g, cs, 6, 1024, err), RS_OK);
                total++;
                if (rs_cosim_fast_radius(f, cs, 64, err) == RS_OK) {
                    fast_ok++;
                    /* both certified: they meet */
                    assert_true(arb_le(f->lower, g->upper));
                    assert_true(arb_le(g->lower, f->upper));
                    assert_true(arb_le(f->lower, f->upper));
                    /* the reference midpoint within the fast interval, up to the reference width */
                    arb_sub(w, g->upper, g->lower, 128);
                    arb_sub(lo, f->lower, w, 128);
                    arb_add(hi, f->upper, w, 128);
                    assert_true(arf_cmp(arb_midref(g->rho), arb_midref(lo)) >= 0);
                    assert_true(arf_cmp(arb_midref(g->rho), arb_midref(hi)) <= 0);
                    /* at least the 6 digits of the full route (2^-20 relative) */
                    arb_sub(w, f->upper, f->lower, 128);
                    arb_mul_2exp_si(lo, f->lower, -20);
                    assert_true(arb_le(w, lo));
                }
                /* the maps' cross-check (van der Hoeven-Mourrain on the same
                 * ball map): certifies here, meets the full radius and holds
                 * its midpoint up to its width */
                rs_radius_clear(f);
                rs_radius_init(f);
                if (rs_cosim_check_radius(f, cs, 64, err) == RS_OK) {
                    check_ok++;
                    assert_true(arb_le(f->lower, g->upper));
                    assert_true(arb_le(g->lower, f->upper));
                    arb_sub(w, g->upper, g->lower, 128);
                    arb_sub(lo, f->lower, w, 128);
                    arb_add(hi, f->upper, w, 128);
                    assert_true(arf_cmp(arb_midref(g->rho), arb_midref(lo)) >= 0);
                    assert_true(arf_cmp(arb_midref(g->rho), arb_midref(hi)) <= 0);
                }
                rs_radius_clear(f);
                rs_radius_clear(g);
            }
    /* generic models: simple, separated eigenvalues everywhere on this grid */
    assert_int_equal(fast_ok, total);
    assert_int_equal(check_ok, total);
    arb_clear(w);
    arb_clear(lo);
    arb_clear(hi);
    rs_cosim_clear(cs);
}

/* uncoupled, sub 1: x'' + x'/5 + x = 0 (e^{-1/10}), sub 2 (ad21 = 3):
 * x'' + 3x'/5 + x = 0 (e^{-3/10}): rho = e^{-1/10} */
static void test_uncoupled_closed_form(void **state)
{
    rs_cosim_t cs;
    rs_radius_t f;
    rs_error_t err;
    arb_t t;
    (void) state;
    rs_cosim_init(cs, 2, 2);
    rs_radius_init(f);
    arb_init(t);
    set_li(cs, "1", "1/5", "3", "0", "0", RS_COSIM_EXPLICIT, 1);
    assert_int_equal(rs_cosim_fast_radius(f, cs, 64, err), RS_OK);
    arb_set_si(t, -1);
    arb_div_ui(t, t, 10, 256);
    arb_exp(t, t, 256);
    assert_true(arb_le(f->lower, t));
    assert_true(arb_ge(f->upper, t));
    assert_true(arb_contains(f->rho, t));
    /* the cross-check's radius too, within 2^-40 */
    rs_radius_clear(f);
    rs_radius_init(f);
    assert_int_equal(rs_cosim_check_radius(f, cs, 64, err), RS_OK);
    assert_true(arb_le(f->lower, t));
    assert_true(arb_ge(f->upper, t));
    arb_sub(t, f->upper, f->lower, 128);
    assert_true(arf_cmpabs_2exp_si(arb_midref(t), -40) < 0);
    arb_clear(t);
    rs_radius_clear(f);
    rs_cosim_clear(cs);
}

/* two equal uncoupled subsystems: double eigenvalues, the discs overlap */
static void test_double_eigenvalues_decline(void **state)
{
    rs_cosim_t cs;
    rs_radius_t f;
    rs_error_t err;
    (void) state;
    rs_cosim_init(cs, 2, 2);
    rs_radius_init(f);
    set_li(cs, "1", "1/5", "1", "0", "0", RS_COSIM_EXPLICIT, 1);
    assert_int_equal(rs_cosim_fast_radius(f, cs, 64, err), RS_ERR_UNDECIDED);
    /* not simple: van der Hoeven-Mourrain declines as well */
    assert_int_equal(rs_cosim_check_radius(f, cs, 64, err), RS_ERR_UNDECIDED);
    rs_radius_clear(f);
    rs_cosim_clear(cs);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grid_vs_full),
        cmocka_unit_test(test_uncoupled_closed_form),
        cmocka_unit_test(test_double_eigenvalues_decline),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
