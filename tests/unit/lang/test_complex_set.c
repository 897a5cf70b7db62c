/* test_complex_set.c -- complex set values (issue 15): `set NAME = A + B*i`
 * and --set NAME=A+B*i evaluated exactly over Q(i), kept apart from the
 * real values, a later value of either kind replacing the earlier one, and
 * i an ordinary name when the case declares one.  Expected values are
 * Gaussian-rational arithmetic done by hand in the comments. */
#include "testutil.h"
#include <string.h>
#include "recstab/casefile.h"

static const char *head = "param q r\nunknown x\neq x[n+1] = q*x[n] + r*x[n]\n";

static int parse(rs_case_t c, const char *tail, rs_error_t err)
{
    char text[512];
    snprintf(text, sizeof text, "%s%s", head, tail);
    rs_case_init(c);
    rs_error_init(err);
    return rs_case_parse_string(c, "t.case", text, strlen(text), err);
}

static void assert_cset(const rs_case_t c, slong k, const char *name, const char *re, const char *im)
{
    fmpq_t a, b;
    fmpq_init(a); fmpq_init(b);
    fmpq_set_str(a, re, 10);
    fmpq_set_str(b, im, 10);
    assert_string_equal(c->csets[k].name, name);
    assert_true(fmpq_equal(c->csets[k].re, a));
    assert_true(fmpq_equal(c->csets[k].im, b));
    fmpq_clear(a); fmpq_clear(b);
}

static void test_values(void **state)
{
    rs_case_t c;
    rs_error_t err;
    (void) state;
    /* -1/2 + 3/2 i as written */
    assert_int_equal(parse(c, "set q = -1/2 + 3/2*i\n", err), RS_OK);
    assert_int_equal(c->ncsets, 1);
    assert_int_equal(c->nsets, 0);
    assert_cset(c, 0, "q", "-1/2", "3/2");
    assert_int_equal(c->csets[0].loc.line, 4);
    assert_int_equal(c->csets[0].loc.col, 5);
    rs_case_clear(c);
    /* (1 + i)^2 = 2i; 2i/(1 - i) = 2i(1 + i)/2 = -1 + i; (2 - i)^-1 = (2 + i)/5 */
    assert_int_equal(parse(c, "set q = (1 + i)^2, r = 2*i/(1 - i)\nset q = (2 - i)^-1\n", err), RS_OK);
    assert_int_equal(c->ncsets, 2);
    assert_cset(c, 0, "q", "2/5", "1/5");
    assert_cset(c, 1, "r", "-1", "1");
    rs_case_clear(c);
    /* i*i = -1 is real: a real set value; a later complex one replaces it
     * and a later real one replaces that */
    assert_int_equal(parse(c, "set q = i*i\n", err), RS_OK);
    assert_int_equal(c->ncsets, 0);
    assert_int_equal(c->nsets, 1);
    assert_true(fmpq_equal_si(c->sets[0].value, -1));
    assert_int_equal(rs_case_set_value(c, "q=1-i", err), RS_OK);
    assert_int_equal(c->nsets, 0);
    assert_cset(c, 0, "q", "1", "-1");
    assert_int_equal(rs_case_set_value(c, "q=3/4", err), RS_OK);
    assert_int_equal(c->ncsets, 0);
    assert_int_equal(c->nsets, 1);
    rs_case_clear(c);
}

static void test_errors(void **state)
{
    rs_case_t c;
    rs_error_t err;
    (void) state;
    /* a complex exponent; division by 0 = (1 + i)(1 - i) - 2 */
    assert_int_equal(parse(c, "set q = 2^i\n", err), RS_ERR_INPUT);
    assert_int_equal(err->line, 4);
    rs_case_clear(c);
    assert_int_equal(parse(c, "set q = 1/((1 + i)*(1 - i) - 2)\n", err), RS_ERR_INPUT);
    assert_non_null(strstr(err->msg, "division by zero"));
    rs_case_clear(c);
    /* a case that declares i: i is that parameter's name, not a number */
    {
        const char *t = "param q i\nunknown x\neq x[n+1] = q*i*x[n]\nset q = 1 + i\n";
        rs_case_init(c);
        rs_error_init(err);
        assert_int_equal(rs_case_parse_string(c, "t.case", t, strlen(t), err), RS_ERR_INPUT);
        assert_non_null(strstr(err->msg, "'i'"));
        rs_case_clear(c);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_values),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
