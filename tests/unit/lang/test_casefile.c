/* test_casefile.c -- the case-file language: valid files and one test per
 * error class, each checking line, column and message. */
#include "testutil.h"
#include <string.h>
#include "recstab/casefile.h"
#include "recstab/scheme.h"
#include "recstab/analysis.h"

/* Parse `text` and run its analyses; returns the error code (RS_OK if all
 * went through).  err receives the message. */
static int run_text(const char *text, rs_error_t err)
{
    rs_case_t c;
    rs_options_t opt;
    json_t *doc = NULL;
    int outcome, r;
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    r = rs_case_parse_string(c, "t.case", text, strlen(text), err);
    if (r == RS_OK) r = rs_case_lower(c, err);
    if (r == RS_OK)
        r = rs_analysis_run(&doc, &outcome, c, &opt, err);
    json_decref(doc);
    rs_case_clear(c);
    return r;
}

static void expect_error(const char *text, int line, int col, const char *needle)
{
    rs_error_t err;
    int r = run_text(text, err);
    if (r == RS_OK)
        fail_msg("no error for:\n%s", text);
    if (err->line != line || err->col != col || strstr(err->msg, needle) == NULL)
        fail_msg("got %s:%d:%d: %s\nexpected line %d col %d with '%s'", err->file, err->line,
                 err->col, err->msg, line, col, needle);
    assert_string_equal(err->file, "t.case");
}

static const char *valid =
    "# a comment\n"
    "title  Valid case   \n"
    "param w h   # trailing comment\n"
    "assume w > 0, 0 <= h <= 1/10\n"
    "unknown x V\n"
    "let k = w^2\n"
    "let Vp[n+1] = 2*V[n] - V[n-1]\n"
    "eq x[n+1] = x[n] + \\\n"
    "      Vp[n+1]\n"
    "eq V[n+1] = V[n] - k*x[n]\n"
    "set h = 0.1, w = 10^-2\n"
    "analyze charpoly\n"
    "expect charpoly lambda^2\n"
    "claim stable when w < 1\n";

static void test_valid(void **state)
{
    rs_case_t c;
    rs_error_t err;
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", valid, strlen(valid), err), RS_OK);
    assert_string_equal(c->title, "Valid case");
    assert_int_equal(c->nparams, 2);
    assert_int_equal(c->nunknowns, 2);
    assert_int_equal(c->nassume, 2);
    assert_int_equal(c->assume[1].n, 3);
    assert_int_equal(c->assume[1].op[0], RS_CMP_LE);
    assert_int_equal(c->nlets, 2);
    assert_int_equal(c->lets[1].shifted, 1);
    assert_int_equal(c->lets[1].shift, 1);
    assert_int_equal(c->neqs, 2);
    assert_int_equal(c->eqs[0].loc.line, 8);
    assert_int_equal(c->nsets, 2);
    {
        fmpq_t tenth;
        fmpq_init(tenth);
        fmpq_set_si(tenth, 1, 10);
        assert_true(fmpq_equal(c->sets[0].value, tenth));
        fmpq_clear(tenth);
    }
    assert_int_equal(c->nrequests, 3);
    assert_string_equal(c->requests[0].text, "charpoly");
    assert_string_equal(c->requests[1].text, "expect charpoly lambda^2");
    assert_int_equal(c->requests[2].loc.line, 14);
    rs_case_clear(c);
}

/* A continued line reports positions on its own physical line. */
static void test_continuation_position(void **state)
{
    (void) state;
    expect_error("param w\nunknown x\neq x[n+1] = \\\n   x[n] + q\n", 4, 11, "unknown name 'q'");
}

static void test_unknown_name(void **state)
{
    (void) state;
    expect_error("param w\nunknown x\neq x[n+1] = w*x[n] + foo*x[n]\nanalyse charpoly\n", 3, 22,
                 "unknown name 'foo'");
}

static void test_shift_on_parameter(void **state)
{
    (void) state;
    expect_error("param w\nunknown x\neq x[n+1] = w[n]*x[n]\n", 3, 13, "shift on the parameter 'w'");
}

static void test_non_integer_power(void **state)
{
    (void) state;
    expect_error("param w\nunknown x\neq x[n+1] = w^(1/2)*x[n]\n", 3, 14, "integer power");
    expect_error("param w\nunknown x\neq x[n+1] = w^w*x[n]\n", 3, 14, "constant integer power");
}

static void test_equation_count(void **state)
{
    (void) state;
    expect_error("param w\nunknown x y\neq x[n+1] = w*y[n]\n", 2, 9, "as many equations as unknowns");
    expect_error("param w\nunknown x\neq x[n+1] = w*x[n]\neq x[n+2] = x[n]\n", 4, 4,
                 "as many equations as unknowns");
}

static void test_equation_without_unknown(void **state)
{
    (void) state;
    expect_error("param w\nunknown x y\neq x[n+1] = y[n]\neq w = 2\n", 4, 4, "involving an unknown");
    expect_error("param w\nunknown x y\neq x[n+1] = y[n]\neq y[n] - y[n] = 0\n", 4, 4,
                 "involving an unknown");
}

static void test_singular_determinant(void **state)
{
    (void) state;
    expect_error("param w\nunknown x y\neq x[n+1] = y[n+1]\neq 2*x[n+1] = 2*y[n+1]\nanalyse charpoly\n",
                 3, 4, "identically zero");
}

static void test_nonlinear(void **state)
{
    (void) state;
    expect_error("unknown x\neq x[n+1] = x[n]*x[n]\n", 2, 17, "product of two unknowns");
    expect_error("unknown x\neq x[n+1] = 1/x[n]\n", 2, 14, "division by an expression with unknowns");
}

static void test_inhomogeneous(void **state)
{
    (void) state;
    expect_error("unknown x\neq x[n+1] = x[n] + 1\n", 2, 4, "homogeneous");
}

static void test_reserved_and_duplicates(void **state)
{
    (void) state;
    expect_error("param lambda\n", 1, 7, "reserved");
    expect_error("param a\nunknown a\n", 2, 9, "already declared");
    expect_error("unknown x\neq x[n+1] = lambda*x[n]\n", 2, 13, "reserved");
}

static void test_syntax(void **state)
{
    (void) state;
    expect_error("param w\nunknown x\neq x[n+1] = (w*x[n]\n", 3, 20, "expected ')'");
    expect_error("frobnicate w\n", 1, 1, "statement keyword");
    expect_error("unknown x\neq x[n+1] x[n]\n", 2, 11, "'='");
    expect_error("unknown x\neq x(n+1) = x[n]\n", 2, 4, "square brackets");
    expect_error("unknown x\neq x[n+1] = x\n", 2, 13, "expected a shift");
}

static void test_set_errors(void **state)
{
    (void) state;
    expect_error("param w\nset h = 1\n", 2, 5, "'h' is not a parameter");
    expect_error("param w\nset w = 1/0\n", 2, 10, "division by zero");
    expect_error("param w\nset w = abc\n", 2, 9, "expected a number");
}

static void test_unknown_analysis(void **state)
{
    (void) state;
    expect_error("unknown x\neq x[n+1] = x[n]/2\nanalyse frobnicate\n", 3, 9, "expected an analysis");
}

static void test_bytes(void **state)
{
    rs_case_t c;
    rs_error_t err;
    const char bad[] = "param w\nunknown x\xff\n";
    const char nul[] = "param w\0x\n";
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", bad, sizeof bad - 1, err), RS_ERR_INPUT);
    assert_int_equal(err->line, 2);
    assert_int_equal(err->col, 10);
    assert_non_null(strstr(err->msg, "UTF-8"));
    rs_case_clear(c);
    rs_case_init(c);
    assert_int_equal(rs_case_parse_string(c, "t.case", nul, sizeof nul - 1, err), RS_ERR_INPUT);
    assert_non_null(strstr(err->msg, "NUL"));
    rs_case_clear(c);
}

static void test_set_value_cli(void **state)
{
    rs_case_t c;
    rs_error_t err;
    const char *t = "param w\n";
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", t, strlen(t), err), RS_OK);
    assert_int_equal(rs_case_set_value(c, "w=0.25", err), RS_OK);
    assert_int_equal(c->nsets, 1);
    assert_int_equal(rs_case_set_value(c, "q=1", err), RS_ERR_INPUT);
    assert_non_null(strstr(err->msg, "'q' is not a parameter"));
    rs_case_clear(c);
}

static void test_division_assumption(void **state)
{
    rs_case_t c;
    rs_error_t err;
    rs_options_t opt;
    json_t *doc = NULL;
    int outcome;
    const char *t = "param m k\nunknown x\neq x[n+1] = x[n] - k/m*x[n]\nanalyse charpoly\n";
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    assert_int_equal(rs_case_parse_string(c, "t.case", t, strlen(t), err), RS_OK);
    assert_int_equal(rs_analysis_run(&doc, &outcome, c, &opt, err), RS_OK);
    {
        json_t *r0 = json_array_get(json_object_get(doc, "results"), 0);
        json_t *nz = json_object_get(r0, "nonzero_assumptions");
        assert_int_equal(json_array_size(nz), 1);
        assert_string_equal(json_string_value(json_array_get(nz, 0)), "m != 0");
        /* m x[n+1] - (m - k) x[n]: coefficients "-m + k" and "m" */
        assert_string_equal(json_string_value(json_array_get(json_object_get(r0, "coeffs"), 1)), "m");
    }
    json_decref(doc);
    rs_case_clear(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_valid),
        cmocka_unit_test(test_continuation_position),
        cmocka_unit_test(test_unknown_name),
        cmocka_unit_test(test_shift_on_parameter),
        cmocka_unit_test(test_non_integer_power),
        cmocka_unit_test(test_equation_count),
        cmocka_unit_test(test_equation_without_unknown),
        cmocka_unit_test(test_singular_determinant),
        cmocka_unit_test(test_nonlinear),
        cmocka_unit_test(test_inhomogeneous),
        cmocka_unit_test(test_reserved_and_duplicates),
        cmocka_unit_test(test_syntax),
        cmocka_unit_test(test_set_errors),
        cmocka_unit_test(test_unknown_analysis),
        cmocka_unit_test(test_bytes),
        cmocka_unit_test(test_set_value_cli),
        cmocka_unit_test(test_division_assumption),
    };
    return cmocka_run_group_tests_name("casefile", tests, NULL, NULL);
}
