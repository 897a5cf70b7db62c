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
    /* the limit is what it says (h-truth5): 200 parentheses parse (1), 201 do not;
     * 100 failed before, each level counted twice */
    for (i = 0; i < 200; i++) buf[i] = '(';
    buf[200] = '1';
    for (i = 0; i < 200; i++) buf[201 + i] = ')';
    buf[401] = '\0';
    rs_error_init(err);
    assert_int_equal(rs_expr_parse_number(q, buf, err), RS_OK);
    assert_true(fmpq_is_one(q));
    memmove(buf + 1, buf, 402);
    buf[0] = '(';
    buf[402] = ')';
    buf[403] = '\0';
    rs_error_init(err);
    assert_int_equal(rs_expr_parse_number(q, buf, err), RS_ERR_LIMIT);
    fmpq_clear(q);
}

static rs_expr_t *parse(const char *s)
{
    rs_src_t src;
    rs_expr_t *e = NULL;
    rs_error_t err;
    memset(&src, 0, sizeof src);
    src.file = "t";
    src.text = s;
    src.line = 1;
    src.col = 1;
    rs_error_init(err);
    if (rs_expr_parse_all(&e, &src, err) != RS_OK) fail_msg("%s: %s", s, err->msg);
    return e;
}

/* Printing a parsed tree gives the text back when it is written in the
 * printer's spacing (the --emit equations output keeps the user's text so):
 * parentheses as written, number spellings, shifts. */
static void test_print_round_trip(void **state)
{
    const char *texts[] = {"-w^2*x", "(-k1*y1 + kc*(y2 - y1) + dc*(v2 - v1))/m1", "-(1 + acc1)*c1*x1 - d1*v1",
                           "x[n+1] - 2*x[n] + x[n-1]", "z1[n+0]", "y[n-0]", "((h))", "0.5*1e-3 - 1/4", "exp(-a*h)",
                           "2^-1", "a - (b - c)", "a/(b*c)", "(a^b)^c", NULL};
    size_t i;
    (void) state;
    for (i = 0; texts[i]; i++) {
        rs_expr_t *e = parse(texts[i]);
        char *p = rs_expr_str(e);
        assert_string_equal(p, texts[i]);
        flint_free(p);
        rs_expr_free(e);
    }
}

/* Trees built without parentheses get those the precedence needs: the
 * printed text parses back to the same tree. */
static void test_print_built(void **state)
{
    rs_expr_t *e = rs_expr_new_op(RS_EXPR_MUL, rs_expr_new_name("a", 0, 0, NULL, 0, 0),
                                  rs_expr_new_op(RS_EXPR_SUB, rs_expr_new_name("x", 1, 1, NULL, 0, 0),
                                                 rs_expr_new_num(2, NULL, 0, 0), NULL, 0, 0), NULL, 0, 0);
    char *p = rs_expr_str(e);
    rs_expr_t *back;
    (void) state;
    assert_string_equal(p, "a*(x[n+1] - 2)");
    back = parse(p);
    assert_true(rs_expr_equal(e, back));
    flint_free(p);
    rs_expr_free(e);
    rs_expr_free(back);
}

/* Structural equality ignores parentheses, spellings and positions. */
static void test_equal(void **state)
{
    const char *same[][2] = {{"(v)", "v"}, {"((a + b))*c", "(a + b)*c"}, {"0.50", "5e-1"}, {"x[n+0]", "x[n]"}};
    const char *differ[][2] = {{"v", "v[n]"}, {"a + b", "b + a"}, {"a - b - c", "a - (b - c)"}, {"sin(x)", "cos(x)"}};
    size_t i;
    (void) state;
    for (i = 0; i < 4; i++) {
        rs_expr_t *a = parse(same[i][0]), *b = parse(same[i][1]);
        rs_expr_t *c = parse(differ[i][0]), *d = parse(differ[i][1]);
        if (!rs_expr_equal(a, b)) fail_msg("%s != %s", same[i][0], same[i][1]);
        if (rs_expr_equal(c, d)) fail_msg("%s == %s", differ[i][0], differ[i][1]);
        rs_expr_free(a); rs_expr_free(b); rs_expr_free(c); rs_expr_free(d);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exact_numbers),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_shift_parse),
        cmocka_unit_test(test_depth_limit),
        cmocka_unit_test(test_print_round_trip),
        cmocka_unit_test(test_print_built),
        cmocka_unit_test(test_equal),
    };
    return cmocka_run_group_tests_name("expr", tests, NULL, NULL);
}
