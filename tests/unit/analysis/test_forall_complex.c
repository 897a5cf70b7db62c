/* test_forall_complex.c -- `region NAME for all` and claims on char lines
 * over Q(i) (issue 15 part 1, issue 13 part 1): the projection uses p's own
 * conditions (schur_complex.c's rs_schur_cx_conds), the cells are decided by
 * the claim machinery.  Expected ranges, each derived by hand (von Neumann
 * analysis of u_t + u_x = 0, nu = a dt/dx, theta = k dx; Strikwerda, Finite
 * Difference Schemes and PDEs, ch. 2; the case files' comments):
 *   - leapfrog, g^2 + 2 i nu sin(theta) g - 1 = 0: g = -i a +- sqrt(1 - a^2),
 *     a = nu sin(theta).  |a| < 1: two distinct roots with |g| = 1
 *     (|g|^2 = a^2 + 1 - a^2); |a| = 1: the double root g = -i a on the
 *     circle; |a| > 1: g = -i (a +- sqrt(a^2 - 1)), one root outside.  So for
 *     every theta: marginal (bounded, never stable) iff nu < 1, unstable for
 *     nu >= 1 (theta = pi/2 gives a = nu);
 *   - Lax-Wendroff, g = 1 - i nu sin(theta) - nu^2 (1 - cos theta):
 *     |g|^2 = 1 - 4 nu^2 (1 - nu^2) sin^4(theta/2): <= 1 for every theta iff
 *     nu <= 1, = 1 at theta = 0 (never stable): marginal on (0, 1], unstable
 *     beyond;
 *   - Lax-Friedrichs, g = cos(theta) - i nu sin(theta): |g|^2 = 1 - (1 - nu^2)
 *     sin^2(theta): marginal on (0, 1], unstable beyond;
 *   - upwind, g = 1 - nu + nu e^{-i theta}: |g|^2 = 1 - 2 nu (1 - nu)(1 -
 *     cos theta): marginal on (0, 1] (g = 1 at theta = 0), unstable beyond. */
#include "testutil.h"
#include <string.h>
#include "recstab/analysis.h"

/* the region's intervals are exactly want[0..n-1], each cell with its evidence */
static void check_region(const json_t *o, const struct tu_iv *want, size_t n, const char *what)
{
    const json_t *ivs = json_object_get(o, "intervals");
    size_t i;
    assert_string_equal(tu_str(o, "analysis"), "region");
    if (json_array_size(ivs) != n) fail_msg("%s: %zu intervals, expected %zu", what, json_array_size(ivs), n);
    for (i = 0; i < n; i++) {
        const json_t *iv = json_array_get(ivs, i), *e;
        size_t k;
        tu_check_interval(iv, want + i, i, what);
        json_array_foreach(json_object_get(iv, "evidence"), k, e) {
            if (strcmp(want[i].status, "unstable") == 0) {
                assert_non_null(json_object_get(e, "counterexample"));
                assert_string_equal(tu_str(json_object_get(e, "at_counterexample"), "status"), "unstable");
            } else {
                assert_true(json_is_true(json_object_get(e, "certificate_rechecked")));
                assert_true(json_array_size(json_object_get(e, "certificate")) > 0);
                assert_non_null(json_object_get(e, "not_stable_at"));      /* marginal: never stable */
            }
        }
    }
}

static void test_regions(void **state)
{
    static const char *req[] = {"region nu for all", "region nu for all [theta]"};
    static const struct tu_iv leapfrog[] = {{"0", 0, "1", 0, "marginal"}, {"1", 1, "inf", 0, "unstable"}};
    static const struct tu_iv closed1[] = {{"0", 0, "1", 1, "marginal"}, {"1", 0, "inf", 0, "unstable"}};
    static const char *files[] = {"cases/complex/leapfrog-cfl.case", "cases/complex/lax-wendroff-cfl.case",
                                  "cases/complex/lax-friedrichs-cfl.case", "cases/complex/upwind-cfl.case"};
    size_t f;
    (void) state;
    for (f = 0; f < 4; f++) {
        int outcome;
        json_t *doc = tu_run_case(files[f], req, 2, &outcome);
        check_region(tu_result(doc, 0), f == 0 ? leapfrog : closed1, 2, files[f]);
        check_region(tu_result(doc, 1), f == 0 ? leapfrog : closed1, 2, files[f]);
        assert_string_equal(tu_str(tu_result(doc, 0), "projection"), "full");
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        json_decref(doc);
    }
}

/* claims: proved iff the set lies inside the region (leapfrog's nu < 1
 * only through the region: its direct certificate search cannot close the
 * corner nu = 1, theta = pi/2 where the discriminant's infimum 0 is reached) */
static void test_claims(void **state)
{
    static const struct { const char *file, *claim, *status; } t[] = {
        {"cases/complex/leapfrog-cfl.case", "claim bounded when nu < 1", "proved"},
        {"cases/complex/leapfrog-cfl.case", "claim bounded when nu < 99/100", "proved"},
        {"cases/complex/leapfrog-cfl.case", "claim bounded when nu <= 1", "refuted"},
        {"cases/complex/leapfrog-cfl.case", "claim stable when nu < 1", "refuted"},
        {"cases/complex/lax-wendroff-cfl.case", "claim bounded when nu <= 1", "proved"},
        {"cases/complex/lax-wendroff-cfl.case", "claim bounded when nu <= 101/100", "refuted"},
        {"cases/complex/lax-friedrichs-cfl.case", "claim bounded when nu <= 1", "proved"},
        {"cases/complex/lax-friedrichs-cfl.case", "claim bounded when nu < 2", "refuted"},
        {"cases/complex/upwind-cfl.case", "claim bounded when nu <= 1", "proved"},
        {"cases/complex/upwind-cfl.case", "claim bounded when nu <= 11/10", "refuted"},
    };
    size_t i;
    (void) state;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        int outcome;
        json_t *doc = tu_run_case(t[i].file, &t[i].claim, 1, &outcome);
        const json_t *o = tu_result(doc, 0);
        if (tu_str(o, "status") == NULL || strcmp(tu_str(o, "status"), t[i].status) != 0)
            fail_msg("%s / %s: %s, expected %s", t[i].file, t[i].claim, tu_str(o, "status"), t[i].status);
        /* the region was computed and agrees (no "not made" any more) */
        assert_string_equal(tu_str(json_object_get(o, "cross_check"), "status"), "agrees");
        if (strcmp(t[i].status, "proved") == 0) {
            assert_true(json_is_true(json_object_get(o, "certificate_rechecked")));
            assert_true(json_array_size(json_object_get(o, "certificate")) > 0);
        } else {
            assert_non_null(json_object_get(o, "counterexample"));
        }
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        json_decref(doc);
    }
}

/* leapfrog's nu < 1 is proved by the region, the direct search alone fails;
 * nu <= 1 is refuted at the double root nu = 1, tan(theta/2) = 1 (theta =
 * pi/2: (lambda + i)^2) */
static void test_leapfrog(void **state)
{
    static const char *req[] = {"claim bounded when nu < 1", "claim bounded when nu <= 1"};
    int outcome;
    json_t *doc = tu_run_case("cases/complex/leapfrog-cfl.case", req, 2, &outcome);
    const json_t *a = tu_result(doc, 0), *b = tu_result(doc, 1);
    (void) state;
    assert_string_equal(tu_str(a, "status"), "proved");
    assert_string_equal(tu_str(a, "proved_by"), "region for all");
    assert_non_null(json_object_get(a, "direct_failed_at"));
    assert_string_equal(tu_str(b, "status"), "refuted");
    assert_string_equal(tu_str(json_object_get(b, "counterexample"), "nu"), "1");
    assert_string_equal(tu_str(json_object_get(b, "counterexample"), "theta"), "1");
    assert_string_equal(tu_str(json_object_get(b, "at_counterexample"), "status"), "unstable");
    /* p = (lambda + i)^2 there (by the quadratic formula: g = -i a +- sqrt(1 - a^2),
     * a = nu sin(theta) = 1): p's own counts over Q(i) (rs_run_point_status), 2 on
     * the circle as one double root -- not the 4 of the block form p conj(p) */
    {
        const json_t *at = json_object_get(b, "at_counterexample"), *m;
        assert_int_equal(json_integer_value(json_object_get(at, "on")), 2);
        assert_int_equal(json_integer_value(json_object_get(at, "degree")), 2);
        assert_null(json_object_get(at, "counts_of"));
        m = json_array_get(json_object_get(at, "on_multiplicities"), 0);
        assert_int_equal(json_integer_value(json_object_get(m, "multiplicity")), 2);
        assert_int_equal(json_integer_value(json_object_get(m, "roots")), 1);
    }
    assert_int_equal(outcome & RS_OUTCOME_FAILED, RS_OUTCOME_FAILED);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* still refused, with the reason: p = (lambda - 2)(2 lambda - 1)(lambda -
 * i x sin theta) shares the factor (lambda - 2)(2 lambda - 1) with p*
 * (Res(p, p*) = 0 identically) and is not self-inversive, so a root of the
 * last factor could cross the circle unseen by the conditions */
static void test_refused(void **state)
{
    int outcome, code;
    json_t *doc = tu_run_text("param x\nparam theta angle\nchar (lambda - 2)*(2*lambda - 1)*(lambda - i*x*sin(theta))\n"
                              "analyse region x for all\n", NULL, &outcome, &code);
    (void) state;
    assert_int_equal(code, RS_ERR_LIMIT);
    assert_null(doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_regions),
        cmocka_unit_test(test_claims),
        cmocka_unit_test(test_leapfrog),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
