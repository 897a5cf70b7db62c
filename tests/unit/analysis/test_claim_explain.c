/* test_claim_explain.c -- claims decided again by the for-all region engine
 * (issue 13 part 1): "cross_check" agrees with the claim's own verdict, and
 * a failed claim's "explanation" lists the region intervals inside the
 * claim's set that are not stable (bounded) with their counterexamples, and
 * the largest proved sub-interval.  Expected ranges, derived independently:
 *   - theta method on x'' = -w^2 x: |lambda|^2 = (1 + (1-th)^2 w^2)/(1 + th^2 w^2)
 *     (from lambda = (1 + (1-th) i w)/(1 - th i w)): for all w > 0 stable iff
 *     th > 1/2, |lambda| = 1 at th = 1/2, unstable below;
 *   - central difference p = l^2 - (2 - w^2) l + 1 (Hughes, The Finite
 *     Element Method, ch. 9): roots on the circle and simple for 0 < w < 2,
 *     double root -1 at w = 2, a root below -1 beyond;
 *   - Park's staggered scheme: stable for every m, muh, wh > 0 exactly for
 *     0 <= alpha <= 1 (the hand derivation in test_forall.c: at alpha = 1
 *     every coefficient and D3 of q(z) positive; at alpha = 1 + e the leading
 *     coefficient of D3 in muh is -16384 W (W (3e^2 + e - 4) + 8 e) < 0 for
 *     small W). */
#include "testutil.h"
#include <string.h>
#include "recstab/casefile.h"
#include "recstab/analysis.h"

static const char *str(const json_t *o, const char *k)
{
    return json_string_value(json_object_get(o, k));
}

static const char *end(const json_t *iv, const char *k)
{
    const json_t *e = json_object_get(iv, k);
    if (json_is_null(e)) return "inf";
    return json_is_string(e) ? json_string_value(e) : "algebraic";
}

static json_t *run_text(const char *text, int *outcome)
{
    rs_case_t c;
    rs_error_t err;
    rs_options_t opt;
    json_t *doc = NULL;
    int r;
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    r = rs_case_parse_string(c, "test.case", text, strlen(text), err);
    if (r == RS_OK) r = rs_analysis_run(&doc, outcome, c, &opt, err);
    rs_case_clear(c);
    if (r != RS_OK || doc == NULL) fail_msg("%s: %s", text, err->msg);
    return doc;
}

static const json_t *claim(const json_t *doc, size_t i)
{
    return json_array_get(json_object_get(doc, "results"), i);
}

/* an interval object is lo..hi with the given closedness */
static void check_iv(const json_t *iv, const char *lo, int lc, const char *hi, int hc, const char *what)
{
    assert_non_null(iv);
    if (strcmp(end(iv, "lo"), lo) != 0 || strcmp(end(iv, "hi"), hi) != 0
        || json_is_true(json_object_get(iv, "lo_closed")) != lc || json_is_true(json_object_get(iv, "hi_closed")) != hc)
        fail_msg("%s: %s%s, %s%s, expected %s%s, %s%s", what, json_is_true(json_object_get(iv, "lo_closed")) ? "[" : "(",
                 end(iv, "lo"), end(iv, "hi"), json_is_true(json_object_get(iv, "hi_closed")) ? "]" : ")",
                 lc ? "[" : "(", lo, hi, hc ? "]" : ")");
}

/* a failing interval's counterexample: NAME's value inside [lo, hi] (rational
 * ends, hi NULL: infinite) and an exact verdict that is not stable */
static void check_cx(const json_t *f, const char *name, const char *lo, const char *hi)
{
    const json_t *cx = json_object_get(f, "counterexample");
    fmpq_t x, a;
    assert_non_null(cx);
    fmpq_init(x);
    fmpq_init(a);
    assert_int_equal(fmpq_set_str(x, str(cx, name), 10), 0);
    fmpq_set_str(a, lo, 10);
    assert_true(fmpq_cmp(x, a) >= 0);
    if (hi != NULL) {
        fmpq_set_str(a, hi, 10);
        assert_true(fmpq_cmp(x, a) <= 0);
    }
    assert_true(strcmp(str(json_object_get(f, "at_counterexample"), "status"), "stable") != 0);
    fmpq_clear(x);
    fmpq_clear(a);
}

#define THETA "param th w\nassume w > 0\nunknown x v\neq x[n+1] - x[n] = th*v[n+1] + (1 - th)*v[n]\n" \
    "eq v[n+1] - v[n] = -w^2*(th*x[n+1] + (1 - th)*x[n])\n"

static void test_theta(void **state)
{
    int outcome;
    const json_t *ex, *fl;
    json_t *doc = run_text(THETA "claim stable when th > 2/5\nclaim bounded when th >= 2/5\n"
                                 "claim bounded when th >= 1/2\n", &outcome);
    (void) state;
    /* stable claim on (2/5, inf): unstable (2/5, 1/2), marginal {1/2}, proved (1/2, inf) */
    assert_string_equal(str(claim(doc, 0), "status"), "refuted");
    assert_string_equal(str(json_object_get(claim(doc, 0), "cross_check"), "status"), "agrees");
    ex = json_object_get(claim(doc, 0), "explanation");
    assert_string_equal(str(ex, "param"), "th");
    check_iv(json_object_get(ex, "proved_part"), "1/2", 0, "inf", 0, "theta stable part");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 2);
    check_iv(json_array_get(fl, 0), "2/5", 0, "1/2", 0, "theta unstable part");
    assert_string_equal(str(json_array_get(fl, 0), "status"), "unstable");
    check_cx(json_array_get(fl, 0), "th", "2/5", "1/2");
    check_iv(json_array_get(fl, 1), "1/2", 1, "1/2", 1, "theta marginal point");
    assert_string_equal(str(json_array_get(fl, 1), "status"), "marginal");
    check_cx(json_array_get(fl, 1), "th", "1/2", "1/2");
    /* bounded claim on [2/5, inf): proved part [1/2, inf) (marginal point and stable side merged) */
    assert_string_equal(str(claim(doc, 1), "status"), "refuted");
    ex = json_object_get(claim(doc, 1), "explanation");
    check_iv(json_object_get(ex, "proved_part"), "1/2", 1, "inf", 0, "theta bounded part");
    assert_int_equal(json_array_size(json_object_get(ex, "failing")), 1);
    check_iv(json_array_get(json_object_get(ex, "failing"), 0), "2/5", 1, "1/2", 0, "theta bounded failing");
    /* a true claim: proved, the region agrees, nothing to explain */
    assert_string_equal(str(claim(doc, 2), "status"), "proved");
    assert_string_equal(str(json_object_get(claim(doc, 2), "cross_check"), "status"), "agrees");
    assert_null(json_object_get(claim(doc, 2), "explanation"));
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

static void test_central_difference(void **state)
{
    int outcome;
    const json_t *ex, *fl;
    json_t *doc = run_text("param w\nassume w > 0\nunknown x\neq x[n+1] - 2*x[n] + x[n-1] + w^2*x[n] = 0\n"
                           "claim bounded when w < 3\nclaim bounded when w < 2\nclaim stable when w < 1\n", &outcome);
    (void) state;
    assert_string_equal(str(claim(doc, 0), "status"), "refuted");
    ex = json_object_get(claim(doc, 0), "explanation");
    check_iv(json_object_get(ex, "proved_part"), "0", 0, "2", 0, "central difference bounded part");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 1);
    check_iv(json_array_get(fl, 0), "2", 1, "3", 0, "central difference failing");
    assert_string_equal(str(json_array_get(fl, 0), "status"), "unstable");
    check_cx(json_array_get(fl, 0), "w", "2", "3");
    assert_string_equal(str(claim(doc, 1), "status"), "proved");
    assert_string_equal(str(json_object_get(claim(doc, 1), "cross_check"), "status"), "agrees");
    /* never stable (|lambda| = 1): no proved part, the whole set marginal */
    assert_string_equal(str(claim(doc, 2), "status"), "refuted");
    ex = json_object_get(claim(doc, 2), "explanation");
    assert_true(json_is_null(json_object_get(ex, "proved_part")));
    check_iv(json_array_get(json_object_get(ex, "failing"), 0), "0", 0, "1", 0, "central difference marginal");
    assert_string_equal(str(json_array_get(json_object_get(ex, "failing"), 0), "status"), "marginal");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

#define PARK "param m muh wh alpha\nassume m > 0, muh > 0, wh > 0, alpha >= 0\nunknown y x v a\n" \
    "let yp[n+1] = (1 + alpha)*y[n] - alpha*y[n-1]\n" \
    "eq 3*y[n+1] - 4*y[n] + y[n-1] + 2*(1 + m)*muh*y[n+1] + 2*wh^2*x[n+1] = 0\n" \
    "eq x[n+1] - x[n] = (v[n+1] + v[n])/2\neq v[n+1] - v[n] = (a[n+1] + a[n])/2\n" \
    "eq a[n+1] + wh^2*x[n+1] + m*muh*yp[n+1] = 0\n"

/* Park's printed "alpha <= 2": proved on [0, 1], fails on (1, 2] */
static void test_park(void **state)
{
    int outcome;
    const json_t *ex, *fl;
    json_t *doc = run_text(PARK "claim stable when alpha <= 2\n", &outcome);
    (void) state;
    assert_string_equal(str(claim(doc, 0), "status"), "refuted");
    assert_string_equal(str(json_object_get(claim(doc, 0), "cross_check"), "status"), "agrees");
    ex = json_object_get(claim(doc, 0), "explanation");
    check_iv(json_object_get(ex, "proved_part"), "0", 1, "1", 1, "park proved part");
    assert_string_equal(str(json_object_get(ex, "proved_part"), "status"), "stable");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 1);
    check_iv(json_array_get(fl, 0), "1", 0, "2", 1, "park failing part");
    assert_string_equal(str(json_array_get(fl, 0), "status"), "unstable");
    check_cx(json_array_get(fl, 0), "alpha", "1", "2");
    assert_int_equal(json_array_size(json_object_get(ex, "for_all")), 3);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_theta),
        cmocka_unit_test(test_central_difference),
        cmocka_unit_test(test_park),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
