/* test_expr.c -- expression parser: exact numbers, precedence, errors. */
#include "testutil.h"
#include <string.h>
#include "recstab/expr.h"

static void num_is(const char *s, const char *expect)
{
    fmpq_t q, e;
    rs_error_t err;
    fmpq_init(q); fmpq_init(e);
    rs_error_init(err);
    assert_int_equal(rs_expr_parse_number(q, s, err), RS_OK);
    fmpq_set_str(e, expect, 10);
    if (!fmpq_equal(q, e)) {
        char *g = fmpq_get_str(NULL, 10, q);
        fail_msg("%s parsed as %s, expected %s", s, g, expect);
    }
    fmpq_clear(q); fmpq_clear(e);
}

/* Decimals are exact: 0.1 is 1/10, not the double nearest to it. */
static void test_exact_numbers(void **state)
{
    (void) state;
    num_is("0.1", "1/10");
    num_is("12", "12");
    num_is("3/2", "3/2");
    num_is("-2.5e-3", "-1/400");
    num_is("10^-40", "1/10000000000000000000000000000000000000000");
    num_is("1e3", "1000");
    num_is("2^10", "1024");
    num_is("-2^2", "-4");          /* unary minus binds weaker than ^ */
    num_is("2^-1", "1/2");
    num_is("(1+2)*3 - 4/8", "17/2");
    num_is("2^3^2", "512");        /* right associative */
}

static void err_is(const char *s, int col, const char *needle)
{
    fmpq_t q;
    rs_error_t err;
    fmpq_init(q);
    rs_error_init(err);
    assert_int_not_equal(rs_expr_parse_number(q, s, err), RS_OK);
    if (err->col != col)
        fail_msg("%s: error at column %d, expected %d (%s)", s, err->col, col, err->msg);
    if (strstr(err->msg, needle) == NULL)
        fail_msg("message '%s' lacks '%s'", err->msg, needle);
    fmpq_clear(q);
}

static void test_errors(void **state)
{
    (void) state;
    err_is("(1 + 2", 7, "expected ')'");
    err_is("1 +", 4, "expected an expression");
    err_is("2h", 2, "write 2*h");
    err_is("1 2", 3, "expected an operator");
    err_is("2^(1/2)", 2, "integer power");
    err_is("1/0", 2, "division by zero");
    err_is("x", 1, "expected a number");
    err_is("2^1000000", 2, "power too large");
}

static void test_shift_parse(void **state)
{
    rs_src_t src;
    rs_expr_t *e = NULL;
    rs_error_t err;
    (void) state;
    memset(&src, 0, sizeof src);
    src.file = "t"; src.text = "x[n-2] + y[n+10]"; src.line = 3; src.col = 5;
    rs_error_init(err);
    assert_int_equal(rs_expr_parse_all(&e, &src, err), RS_OK);
    assert_int_equal(e->kind, RS_EXPR_ADD);
    assert_string_equal(e->a->name, "x");
    assert_int_equal(e->a->shift, -2);
    assert_int_equal(e->b->shift, 10);
    assert_int_equal(e->b->col, 14);
    assert_int_equal(e->b->line, 3);
    rs_expr_free(e);
    src.text = "x[m+1]";
    assert_int_not_equal(rs_expr_parse_all(&e, &src, err), RS_OK);
    assert_non_null(strstr(err->msg, "'n' in a shift"));
    assert_int_equal(err->col, 7);
}

static void test_depth_limit(void **state)
{
    char buf[1000];
    int i;
    fmpq_t q;
    rs_error_t err;
    (void) state;
    for (i = 0; i < 400; i++) buf[i] = '(';
    buf[400] = '1';
    for (i = 0; i < 400; i++) buf[401 + i] = ')';
    buf[801] = '\0';
    fmpq_init(q);
    rs_error_init(err);
    assert_int_equal(rs_expr_parse_number(q, buf, err), RS_ERR_LIMIT);
    assert_non_null(strstr(err->msg, "nested too deeply"));
    fmpq_clear(q);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_numbers),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_shift_parse),
        cmocka_unit_test(test_depth_limit),
    };
    return cmocka_run_group_tests_name("expr", tests, NULL, NULL);
}
