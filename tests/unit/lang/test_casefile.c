/* test_casefile.c -- the case-file language: valid files and one test per
 * error class, each checking line, column and message. */
#include "testutil.h"
#include <stdlib.h>
#include <unistd.h>
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

/* node position: file, line, column (counted by hand in the text below) */
static void at_pos(const rs_expr_t *e, const char *file, int line, int col)
{
    assert_non_null(e);
    if (e->file == NULL || strcmp(e->file, file) != 0 || e->line != line || e->col != col)
        fail_msg("node at %s:%d:%d, expected %s:%d:%d", e->file ? e->file : "(none)", e->line, e->col, file, line,
                 col);
}

/* The typed syntax tree: every builder statement keeps its expressions as
 * trees whose nodes carry file:line:col, the coupling forces are one array,
 * and parsing does not lower (no unknown or equation is generated). */
static const char *builders =
    "param k, h, th\n"                                   /* 1 */
    "subsystem S1 state y v\n"                           /* 2 */
    "  y' = v\n"                                         /* 3 */
    "  v' = -k*y + f\n"                                  /* 4 */
    "integrate S1 theta th (h)\n"                        /* 5 */
    "subsystem S2 state z\n"                             /* 6 */
    "  z'' = -k*z\n"                                     /* 7 */
    "integrate S2 newmark 1/4 0.5 h\n"                   /* 8 */
    "couple explicit order 1\n"                          /* 9 */
    "coupling force f = k*(z - y)\n"                     /* 10 */
    "coupling force g = y\n"                             /* 11 */
    "recurrence 1 = [1, h; 0, 1]\n";                     /* 12 */

static void test_syntax_tree(void **state)
{
    rs_case_t c;
    rs_error_t err;
    const rs_subsystem_t *s;
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", builders, strlen(builders), err), RS_OK);
    assert_int_equal(c->nunknowns, 0);
    assert_int_equal(c->neqs, 0);
    assert_int_equal(c->nsubs, 2);
    s = &c->subs[0];
    assert_int_equal(s->nstates, 2);
    assert_string_equal(s->states[1].name, "v");
    assert_int_equal(s->states[1].loc.line, 2);
    assert_int_equal(s->states[1].loc.col, 22);
    assert_int_equal(s->ndeqs, 2);
    assert_string_equal(s->deqs[1].state, "v");
    assert_int_equal(s->deqs[1].loc.line, 4);
    assert_int_equal(s->deqs[1].loc.col, 3);
    /* -k*y + f: ADD at '+' (col 13), its operands MUL at '*' (col 10), f (col 15) */
    assert_int_equal(s->deqs[1].rhs->kind, RS_EXPR_ADD);
    at_pos(s->deqs[1].rhs, "t.case", 4, 13);
    at_pos(s->deqs[1].rhs->a, "t.case", 4, 10);
    at_pos(s->deqs[1].rhs->b, "t.case", 4, 15);
    assert_string_equal(s->method, "theta");
    at_pos(s->arg1, "t.case", 5, 20);
    assert_null(s->arg2);
    at_pos(s->step, "t.case", 5, 24);     /* h inside the parentheses */
    assert_int_equal(s->step->paren, 1);
    s = &c->subs[1];
    assert_int_equal(s->deqs[0].order, 2);
    at_pos(s->arg1, "t.case", 8, 23);     /* 1/4: the DIV node at '/' */
    assert_int_equal(s->arg1->kind, RS_EXPR_DIV);
    at_pos(s->arg2, "t.case", 8, 26);
    assert_string_equal(s->arg2->lit, "0.5");
    at_pos(s->step, "t.case", 8, 30);
    /* one array of coupling forces, in order */
    assert_int_equal(c->nforces, 2);
    assert_string_equal(c->forces[0].name, "f");
    assert_int_equal(c->forces[0].loc.col, 16);
    at_pos(c->forces[0].e, "t.case", 10, 21);
    assert_string_equal(c->forces[1].name, "g");
    at_pos(c->forces[1].e, "t.case", 11, 20);
    assert_int_equal(c->nrec, 1);
    at_pos(c->rec[0].entries[1], "t.case", 12, 20);
    rs_case_clear(c);
}

/* Statements read from an included file keep that file's positions. */
static void test_include_positions(void **state)
{
    rs_case_t c;
    rs_error_t err;
    char dir[] = "/tmp/rs-test-include-XXXXXX", path[128], inc[128];
    FILE *f;
    (void) state;
    assert_non_null(mkdtemp(dir));
    snprintf(path, sizeof path, "%s/main.case", dir);
    snprintf(inc, sizeof inc, "%s/part.inc", dir);
    f = fopen(inc, "w");
    fputs("# fragment\n\neq x[n+1] = a*x[n]\n", f);
    fclose(f);
    f = fopen(path, "w");
    fputs("param a\nunknown x\ninclude part.inc\n", f);
    fclose(f);
    rs_case_init(c);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_file(c, path, err), RS_OK);
    assert_int_equal(c->neqs, 1);
    assert_string_equal(c->eqs[0].loc.file, inc);
    assert_int_equal(c->eqs[0].loc.line, 3);
    at_pos(c->eqs[0].rhs, inc, 3, 14);    /* the '*' of a*x[n] */
    at_pos(c->eqs[0].lhs, inc, 3, 4);
    rs_case_clear(c);
    remove(inc);
    remove(path);
    rmdir(dir);
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
        cmocka_unit_test(test_syntax_tree),
        cmocka_unit_test(test_include_positions),
    };
    return cmocka_run_group_tests_name("casefile", tests, NULL, NULL);
}
