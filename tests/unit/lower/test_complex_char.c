/* test_complex_char.c -- `param NAME angle` (sin/cos of integer multiples
 * rewritten with t = tan(NAME/2)) and the imaginary unit in `char` lines
 * (lowered to the real 2x2 block form).  Independent derivations:
 *   - sin(K theta), cos(K theta): the derived rational function of t is
 *     evaluated in double at t = tan(theta/2) and compared with libm's
 *     sin/cos of K*theta;
 *   - leapfrog: det [[A, -B], [B, A]] = A^2 + B^2 written out by hand, with
 *     A = (1 + t^2)(lambda^2 - 1), B = 4 nu t lambda (sin = 2t/(1+t^2));
 *   - the CFL claims of leapfrog, upwind, Lax-Friedrichs and Lax-Wendroff
 *     from |g| by hand (see each case file's comment; Strikwerda, Finite
 *     Difference Schemes and PDEs, ch. 2): bounded iff nu <= 1 (leapfrog:
 *     nu < 1, the double root g = -i at nu = 1, theta = pi/2). */
#include "testutil.h"
#include <math.h>
#include <string.h>
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "recstab/charpoly.h"
#include "recstab/analysis.h"

/* builds the scheme of case text; returns the error code */
static int build(rs_case_t c, rs_model_t m, rs_scheme_t s, const char *text, rs_error_t err)
{
    int r = rs_case_parse_string(c, "test.case", text, strlen(text), err);
    if (r == RS_OK) r = rs_model_lower(m, c, err);
    if (r == RS_OK) r = rs_scheme_build(s, m, err);
    return r;
}

/* value in double of a polynomial in (theta, lambda) at theta = t, as the
 * coefficient of lambda^k */
static double coeff_at(const fmpq_mpoly_t p, slong k, double t, const rs_scheme_t s)
{
    slong i, n = fmpq_mpoly_length(p, s->ctx);
    ulong e[2];
    double sum = 0;
    fmpq_t q;
    fmpq_init(q);
    for (i = 0; i < n; i++) {
        fmpq_mpoly_get_term_exp_ui(e, p, i, s->ctx);
        if ((slong) e[1] != k) continue;
        fmpq_mpoly_get_term_coeff_fmpq(q, p, i, s->ctx);
        sum += fmpq_get_d(q) * pow(t, (double) e[0]);
    }
    fmpq_clear(q);
    return sum;
}

static void test_trig_multiples(void **state)
{
    static const double thetas[] = {0.3, 1.1, 2.0, -0.7, 3.0};
    int K, fn, j;
    (void) state;
    for (fn = 0; fn < 2; fn++) {
        for (K = -3; K <= 4; K++) {
            char text[200];
            rs_case_t c; rs_model_t m; rs_scheme_t s; rs_error_t err;
            rs_case_init(c); rs_model_init(m); rs_scheme_init(s); rs_error_init(err);
            snprintf(text, sizeof text, "param theta angle\nchar lambda - %s(%d*theta)\n", fn ? "sin" : "cos", K);
            if (build(c, m, s, text, err) != RS_OK) fail_msg("%s: %s", text, err->msg);
            assert_int_equal(s->n, 0);                 /* real: a scalar char line */
            for (j = 0; j < 5; j++) {
                double t = tan(thetas[j] / 2), c1 = coeff_at(s->charpoly, 1, t, s),
                       c0 = coeff_at(s->charpoly, 0, t, s);
                double want = fn ? sin(K * thetas[j]) : cos(K * thetas[j]);
                if (fabs(-c0 / c1 - want) > 1e-12)
                    fail_msg("%s at theta = %g: %.17g, expected %.17g", text, thetas[j], -c0 / c1, want);
            }
            rs_scheme_clear(s); rs_model_clear(m); rs_case_clear(c);
        }
    }
}

/* i*i = -1 by hand: the line is real, a scalar char line lambda + nu - 1 */
static void test_i_cancels(void **state)
{
    rs_case_t c; rs_model_t m; rs_scheme_t s; rs_error_t err;
    fmpq_mpoly_t e;
    (void) state;
    rs_case_init(c); rs_model_init(m); rs_scheme_init(s); rs_error_init(err);
    if (build(c, m, s, "param nu\nchar lambda - i*i*nu - 1\n", err) != RS_OK) fail_msg("%s", err->msg);
    assert_int_equal(s->n, 0);
    assert_int_equal(s->from_char, 1);
    fmpq_mpoly_init(e, s->ctx);
    assert_int_equal(fmpq_mpoly_set_str_pretty(e, "lambda + nu - 1", (const char **) s->vars, s->ctx), 0);
    assert_true(fmpq_mpoly_equal(e, s->charpoly, s->ctx));
    fmpq_mpoly_clear(e, s->ctx);
    rs_scheme_clear(s); rs_model_clear(m); rs_case_clear(c);
}

static void test_leapfrog_block_form(void **state)
{
    const char *text = "param nu\nparam theta angle\nchar lambda^2 + 2*i*nu*sin(theta)*lambda - 1\n";
    const char *hand = "((1 + theta^2)*(lambda^2 - 1))^2 + (4*nu*theta*lambda)^2";
    rs_case_t c; rs_model_t m; rs_scheme_t s; rs_error_t err;
    rs_charpoly_t cp;
    fmpz_mpoly_t e;
    fmpq_t scale;
    (void) state;
    rs_case_init(c); rs_model_init(m); rs_scheme_init(s); rs_error_init(err);
    if (build(c, m, s, text, err) != RS_OK) fail_msg("%s", err->msg);
    assert_int_equal(s->n, 2);
    assert_int_equal(s->complex_char, 1);
    assert_int_equal(s->nnonzero, 0);                  /* (1 + t^2) is not an assumption */
    rs_charpoly_init(cp, s);
    assert_int_equal(rs_charpoly_compute(cp, s, err), RS_OK);
    fmpz_mpoly_init(e, s->zctx);
    fmpq_init(scale);
    assert_int_equal(fmpz_mpoly_set_str_pretty(e, hand, (const char **) s->vars, s->zctx), 0);
    rs_charpoly_normalise(e, scale, s->lambda_var, s->zctx);
    assert_true(fmpz_mpoly_equal(e, cp->p, s->zctx));
    assert_int_equal(cp->degree, 4);
    fmpz_mpoly_clear(e, s->zctx);
    fmpq_clear(scale);
    rs_charpoly_clear(cp, s);
    rs_scheme_clear(s); rs_model_clear(m); rs_case_clear(c);
}

struct claim_case { const char *file, *claim, *status; };

static void test_cfl_claims(void **state)
{
    static const struct claim_case t[] = {
        {"cases/complex/leapfrog-cfl.case", "claim bounded when nu <= 1", "refuted"},
        {"cases/complex/leapfrog-cfl.case", "claim unstable when nu > 1", "refuted"},  /* small theta: |a| < 1 */
        {"cases/complex/upwind-cfl.case", "claim bounded when nu <= 1", "proved"},
        {"cases/complex/upwind-cfl.case", "claim bounded when nu <= 11/10", "refuted"},
        {"cases/complex/upwind-cfl.case", "claim stable when nu < 1", "refuted"},     /* g = 1 at theta = 0 */
        {"cases/complex/lax-friedrichs-cfl.case", "claim bounded when nu <= 1", "proved"},
        {"cases/complex/lax-wendroff-cfl.case", "claim bounded when nu <= 1", "proved"},
        {"cases/complex/lax-wendroff-cfl.case", "claim bounded when nu <= 2", "refuted"},
    };
    size_t i;
    (void) state;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        int outcome;
        json_t *doc = tu_run_case(t[i].file, &t[i].claim, 1, &outcome);
        const char *got = json_string_value(json_object_get(json_array_get(json_object_get(doc, "results"), 0), "status"));
        if (got == NULL || strcmp(got, t[i].status) != 0)
            fail_msg("%s / %s: %s, expected %s", t[i].file, t[i].claim, got ? got : "(none)", t[i].status);
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        json_decref(doc);
    }
}

/* the leapfrog counterexample is nu = 1, tan(theta/2) = 1 (theta = pi/2):
 * lambda^2 + 2 i lambda - 1 = (lambda + i)^2 */
static void test_leapfrog_counterexample(void **state)
{
    const char *claim = "claim bounded when nu <= 1";
    int outcome;
    json_t *doc = tu_run_case("cases/complex/leapfrog-cfl.case", &claim, 1, &outcome);
    char *s = json_dumps(doc, JSON_COMPACT);
    (void) state;
    assert_non_null(strstr(s, "\"nu\":\"1\""));
    assert_non_null(strstr(s, "\"theta\":\"1\""));
    free(s);
    json_decref(doc);
}

static void test_bad_input(void **state)
{
    static const struct { const char *text, *msg; } t[] = {
        {"param nu\nchar lambda - sin(nu)\n", "expected an angle parameter"},
        {"param theta angle\nchar lambda - sin(theta/2)\n", "expected an angle parameter"},
        {"param theta angle\nset theta = 1\nchar lambda - cos(theta)\n", "is an angle parameter"},
        {"param nu\nchar lambda - 1/(1 + i*nu)\n", "division by a complex expression"},
        {"param nu\nchar nu + i\n", "without lambda"},
    };
    size_t k;
    (void) state;
    for (k = 0; k < sizeof t / sizeof t[0]; k++) {
        rs_case_t c; rs_model_t m; rs_scheme_t s; rs_error_t err;
        rs_case_init(c); rs_model_init(m); rs_scheme_init(s); rs_error_init(err);
        assert_int_equal(build(c, m, s, t[k].text, err), RS_ERR_INPUT);
        if (strstr(err->msg, t[k].msg) == NULL) fail_msg("%s: %s", t[k].text, err->msg);
        assert_string_equal(err->file, "test.case");
        assert_true(err->line >= 2);
        rs_scheme_clear(s); rs_model_clear(m); rs_case_clear(c);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_trig_multiples),
        cmocka_unit_test(test_i_cancels),
        cmocka_unit_test(test_leapfrog_block_form),
        cmocka_unit_test(test_cfl_claims),
        cmocka_unit_test(test_leapfrog_counterexample),
        cmocka_unit_test(test_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
