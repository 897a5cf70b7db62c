/* test_golden.c -- characteristic polynomials of the bundled cases against
 * closed forms derived independently (by hand, written out here as
 * products of the scheme's operators rho(lambda) and sigma(lambda)). */
#include "testutil.h"
#include <string.h>
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "recstab/charpoly.h"

/* Derives p from the case file and compares it with `closed` (a string in
 * the case's parameters and lambda), both normalised the same way. */
static void check_case(const char *rel, const char *closed, slong degree)
{
    char path[1024];
    rs_case_t c;
    rs_model_t m;
    rs_scheme_t s;
    rs_charpoly_t cp;
    rs_error_t err;
    fmpz_mpoly_t e;
    fmpq_t scale;
    snprintf(path, sizeof path, "%s/%s", RS_SOURCE_DIR, rel);
    rs_case_init(c);
    rs_model_init(m);
    rs_scheme_init(s);
    rs_error_init(err);
    if (rs_case_parse_file(c, path, err) != RS_OK || rs_model_lower(m, c, err) != RS_OK || rs_scheme_build(s, m, err) != RS_OK)
        fail_msg("%s: %s", rel, err->msg);
    rs_charpoly_init(cp, s);
    assert_int_equal(rs_charpoly_compute(cp, s, err), RS_OK);
    fmpz_mpoly_init(e, s->zctx);
    fmpq_init(scale);
    if (fmpz_mpoly_set_str_pretty(e, closed, (const char **) s->vars, s->zctx) != 0)
        fail_msg("bad closed form %s", closed);
    rs_charpoly_normalise(e, scale, s->lambda_var, s->zctx);
    if (!fmpz_mpoly_equal(e, cp->p, s->zctx)) {
        char *a = fmpz_mpoly_get_str_pretty(cp->p, (const char **) s->vars, s->zctx);
        char *b = fmpz_mpoly_get_str_pretty(e, (const char **) s->vars, s->zctx);
        fail_msg("%s:\n derived %s\n closed  %s", rel, a, b);
    }
    assert_int_equal(cp->degree, degree);
    fmpz_mpoly_clear(e, s->zctx);
    fmpq_clear(scale);
    rs_charpoly_clear(cp, s);
    rs_scheme_clear(s);
    rs_model_clear(m);
    rs_case_clear(c);
}

/* Forward Euler: R(z) = 1 + z; x' = v, v' = -w^2 x gives
 * (lambda - 1)^2 + w^2 (rho = lambda - 1, explicit sigma = 1). */
static void test_forward_euler(void **state)
{
    (void) state;
    check_case("cases/textbook/forward-euler.case", "(lambda-1)^2 + w^2", 2);
}

/* Backward Euler: rho = lambda - 1, sigma = lambda: rho^2 + w^2 sigma^2. */
static void test_backward_euler(void **state)
{
    (void) state;
    check_case("cases/textbook/backward-euler.case", "(lambda-1)^2 + w^2*lambda^2", 2);
}

/* Trapezoid: rho = lambda - 1, sigma = (lambda + 1)/2, times 4. */
static void test_trapezoidal(void **state)
{
    (void) state;
    check_case("cases/textbook/trapezoidal.case", "4*(lambda-1)^2 + w^2*(lambda+1)^2", 2);
}

/* BDF2: rho = 3 lambda^2 - 4 lambda + 1, sigma = 2 lambda^2. */
static void test_bdf2(void **state)
{
    (void) state;
    check_case("cases/textbook/bdf2.case", "(3*lambda^2-4*lambda+1)^2 + w^2*(2*lambda^2)^2", 4);
    check_case("cases/textbook/bdf2-park-eq8.case", "(3*lambda^2-4*lambda+1)^2 + w^2*(2*lambda^2)^2", 4);
}

/* Central difference: lambda - 2 + 1/lambda + w^2 = 0, times lambda. */
static void test_central_difference(void **state)
{
    (void) state;
    check_case("cases/textbook/central-difference.case", "lambda^2 - (2 - w^2)*lambda + 1", 2);
}

/* Park eq. (17), eliminated by hand (see the case file's comment):
 *   x = ((lambda+1)/(2(lambda-1)))^2 a from the two trapezoid rows,
 *   then the structure row and the Gear row give
 *   A (4(l-1)^2 + wh^2 (l+1)^2) - 2 m muh wh^2 ((1+alpha) l - alpha)(l+1)^2. */
static void test_park(void **state)
{
    (void) state;
    check_case("cases/park-staggered.case",
               "((3 + 2*(1+m)*muh)*lambda^2 - 4*lambda + 1)*(4*(lambda-1)^2 + wh^2*(lambda+1)^2)"
               " - 2*m*muh*wh^2*((1+alpha)*lambda - alpha)*(lambda+1)^2", 4);
}

/* Dahlquist's test equation y' = q y (q = h lambda_0 real), p = rho - q sigma:
 * BDF2 rho = 3l^2 - 4l + 1, sigma = 2l^2; two-step Adams-Moulton
 * (Hairer, Norsett, Wanner I, III.1) rho = 12(l^2 - l), sigma = 5l^2 + 8l - 1. */
static void test_dahlquist(void **state)
{
    (void) state;
    check_case("cases/textbook/bdf2-dahlquist.case", "(3 - 2*q)*lambda^2 - 4*lambda + 1", 2);
    check_case("cases/textbook/adams-moulton2.case", "(12 - 5*q)*lambda^2 - (12 + 8*q)*lambda + q", 2);
}

/* HHT-alpha, eliminated by hand in the case file's comment (times 4:
 * 4(1 - gamma) = 2 + 4 alpha, 4 gamma = 2 - 4 alpha, 4 beta = (1 - alpha)^2). */
static void test_hht(void **state)
{
    (void) state;
    check_case("cases/textbook/hht-alpha.case",
               "4*lambda*(lambda - 1)^2 + w^2*((1 + alpha)*lambda - alpha)*((2 + 4*alpha) + (2 - 4*alpha)*lambda"
               " + (2 - (1 - alpha)^2 + (1 - alpha)^2*lambda)*(lambda - 1))", 3);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forward_euler),
        cmocka_unit_test(test_backward_euler),
        cmocka_unit_test(test_trapezoidal),
        cmocka_unit_test(test_bdf2),
        cmocka_unit_test(test_central_difference),
        cmocka_unit_test(test_park),
        cmocka_unit_test(test_dahlquist),
        cmocka_unit_test(test_hht),
    };
    return cmocka_run_group_tests_name("golden", tests, NULL, NULL);
}
