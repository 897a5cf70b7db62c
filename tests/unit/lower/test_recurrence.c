/* test_recurrence.c -- `recurrence` terms: polynomial entries become
 * equations (the forward-Euler matrix gives (lambda - 1)^2 + w^2, its closed
 * form); entries with exp/sin/cos go the numeric path, and the certified
 * radius of the exactly integrated damped oscillator contains e^{-zeta w h}
 * (both eigenvalues of e^{A h} have that modulus), computed here with Arb. */
#include "testutil.h"
#include <string.h>
#include <arb.h>
#include "recstab/casefile.h"
#include "recstab/scheme.h"
#include "recstab/analysis.h"

static void test_polynomial_entries(void **state)
{
    const char *req[] = {"charpoly"};
    int outcome;
    json_t *doc = tu_run_case("cases/recurrence-forward-euler.case", req, 1, &outcome);
    json_t *r = json_array_get(json_object_get(doc, "results"), 0);
    (void) state;
    /* 4 l^2 - 8 l + 5 = 4 ((l - 1)^2 + 1/4) at w = 1/2 */
    assert_string_equal(json_string_value(json_array_get(json_object_get(r, "coeffs"), 0)), "5");
    assert_string_equal(json_string_value(json_array_get(json_object_get(r, "coeffs"), 1)), "-8");
    assert_string_equal(json_string_value(json_array_get(json_object_get(r, "coeffs"), 2)), "4");
    json_decref(doc);
}

static void test_numeric_entries(void **state)
{
    const char *req[] = {"radius digits=40"};
    int outcome;
    json_t *doc = tu_run_case("cases/recurrence-exact-oscillator.case", req, 1, &outcome);
    json_t *r = json_array_get(json_object_get(doc, "results"), 0);
    arb_t lo, hi, e;
    (void) state;
    arb_init(lo); arb_init(hi); arb_init(e);
    arb_set_str(lo, json_string_value(json_object_get(r, "lower")), 300);
    arb_set_str(hi, json_string_value(json_object_get(r, "upper")), 300);
    arb_set_si(e, -1);
    arb_div_si(e, e, 10, 300);
    arb_exp(e, e, 300);                         /* e^{-zeta w h} = e^{-1/10} */
    arb_sub(lo, e, lo, 300);                    /* >= -(rounding of the printed bound) */
    arb_sub(hi, hi, e, 300);
    assert_true(arf_cmpabs_2exp_si(arb_midref(lo), -120) < 0 || arf_sgn(arb_midref(lo)) > 0);
    assert_true(arf_cmpabs_2exp_si(arb_midref(hi), -120) < 0 || arf_sgn(arb_midref(hi)) > 0);
    assert_string_equal(json_string_value(json_object_get(r, "status")), "stable");
    arb_clear(lo); arb_clear(hi); arb_clear(e);
    json_decref(doc);
}

static void test_errors(void **state)
{
    rs_case_t c;
    rs_error_t err;
    const char *bad1 = "recurrence 1 = [1, 0; 0]\n";
    const char *bad2 = "param a\nrecurrence 1 = [1]\nrecurrence 0 = [exp(a)]\nanalyse radius\n";
    rs_options_t opt;
    json_t *doc = NULL;
    int outcome;
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", bad1, strlen(bad1), err), RS_ERR_INPUT);
    assert_non_null(strstr(err->msg, "rows of equal length"));
    rs_case_clear(c);
    rs_case_init(c);
    rs_options_default(&opt);
    assert_int_equal(rs_case_parse_string(c, "t.case", bad2, strlen(bad2), err), RS_OK);
    assert_int_not_equal(rs_analysis_run(&doc, &outcome, c, &opt, err), RS_OK);
    assert_non_null(strstr(err->msg, "'a' is not"));
    rs_case_clear(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_polynomial_entries),
        cmocka_unit_test(test_numeric_entries),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests_name("recurrence", tests, NULL, NULL);
}
