/* test_forall.c -- `region NAME for all [P, ...]` (issue 13, part 1): the
 * NAME values stable (marginal) for every admissible value of the others.
 * Expected ranges, each derived independently of recstab:
 *   - theta method on the undamped oscillator (cases/forall/theta-oscillator.case):
 *     lambda = (1 + (1-th) i w)/(1 - th i w), |lambda|^2 = (1 + (1-th)^2 w^2)/(1 + th^2 w^2):
 *     for all w > 0 stable iff th > 1/2, marginal at th = 1/2, unstable below;
 *   - central difference, p = l^2 - (2 - w^2) l + 1 (Hughes, The Finite
 *     Element Method, ch. 9): marginal for 0 < w < 2, double root -1 at w = 2
 *     and a root below -1 beyond: unstable on [2, inf) (no other parameter:
 *     `for all` over nothing is the plain region);
 *   - Newmark on x'' = -w^2 x, h = 1 (Hughes ch. 9: unconditionally stable
 *     iff 2 beta >= gamma >= 1/2): at gamma = 1/2 marginal (|lambda| = 1) for
 *     every w iff beta >= 1/4; at gamma = 3/5 stable for every w iff beta >=
 *     3/10 (= gamma/2, numerical dissipation); for beta < 0 the leading
 *     coefficient 1 + beta w^2 vanishes at w^2 = -1/beta: singular there;
 *   - Park's staggered scheme (cases/park-staggered.case) at m = muh = 1, for
 *     all wh > 0: q(z) = (1-z)^4 p((1+z)/(1-z)) has, by hand from the case's
 *     p, coefficients a0..a4 = 8 W, 16 W (3 - alpha), 8 (2 alpha W + 7 W + 8),
 *     192, 192 (W = wh^2) and D3 = a3 a2 a1 - a3^2 a0 - a4 a1^2 =
 *     -24576 W (W (4 alpha^2 - 11 alpha - 3) + 8 alpha - 12): positive for
 *     every W > 0 iff 8 alpha - 12 <= 0 and (4 alpha + 1)(alpha - 3) <= 0, so
 *     stable for all wh iff 0 <= alpha <= 3/2 (alpha = 3/2: D3 = 258048 W^2 > 0);
 *   - Park at m = 1 for all muh, wh > 0, and for all m, muh, wh > 0: stable
 *     exactly on [0, 1] (Park's "alpha <= 1"), unstable beyond.  By hand
 *     (sympy, from the case's p; W = wh^2): q's coefficients are a0 = 8 W muh,
 *     a1 = 16 W (1 + muh + m muh - alpha m muh), a2 = 8 (2 W alpha m muh +
 *     2 W m muh + W muh + 4 W + 4 m muh + 4 muh), a3 = 64 (m muh + muh + 1),
 *     a4 = 32 (m muh + muh + 4); at alpha = 1 every coefficient and
 *     D3 = a3 a2 a1 - a3^2 a0 - a4 a1^2 = 8192 W m muh (4 W m muh^2 + 4 W m muh
 *     + 4 W muh^2 + 11 W muh + 7 W + 4 m muh + 4 muh + 4) are positive (the
 *     whole of [0, 1] stable is Park's bound, proved by `claim stable when
 *     alpha <= 1` with its re-checked certificate; only the end 1 is derived
 *     here by hand); at alpha = 1 + e, m = 1, D3 is a
 *     cubic in muh with leading coefficient -16384 W (W (3e^2 + e - 4) + 8 e),
 *     negative for small W: D3 < 0 for muh large, unstable for every
 *     alpha > 1, the bound reached only as muh -> inf;
 *   - two identical central-difference oscillators (h < 1, so each mode has
 *     h^2 w^2 < 4), y driving x with strength eps
 *     (cases/forall/driven-oscillators.case): det A = g^2, g = l^2 - (2 - h^2) l
 *     + 1, for every eps; A modulo g is [[0, -eps h^2 l], [0, 0]], of rank 1
 *     unless eps = 0: a Jordan block (x is driven at its own frequency and
 *     grows like n) for eps != 0, two decoupled bounded oscillators at eps = 0.
 *     So for all 0 < h < 1: unstable for eps < 0 and eps > 0, marginal at 0
 *     (the critical value comes only from the rank of A, not from det A);
 *   - the same oscillators coupled symmetrically (x'' = -x + eps y, y'' = -y +
 *     eps x): modes w^2 = 1 +- eps; bounded for every 0 < h < 1 iff both are in
 *     (0, 4) for h^2 w^2 (h^2 (1 + eps) < 4 holds for eps < 3) and 1 - eps > 0,
 *     1 + eps > 0; at eps = +-1 a zero mode (double root lambda = 1, a Jordan
 *     block: linear drift): marginal exactly on (-1, 1), unstable elsewhere;
 *     at eps = 0 det A = g^2 again but A = g I is semisimple. */
#include "testutil.h"
#include <string.h>
#include "recstab/casefile.h"
#include "recstab/analysis.h"

/* the region's intervals are exactly want[0..n-1], each with its evidence */
static void check_region(const json_t *o, const struct tu_iv *want, size_t n, const char *what)
{
    const json_t *ivs = json_object_get(o, "intervals");
    size_t i;
    if (json_array_size(ivs) != n) fail_msg("%s: %zu intervals, expected %zu", what, json_array_size(ivs), n);
    for (i = 0; i < n; i++) {
        const json_t *iv = json_array_get(ivs, i), *ev = json_object_get(iv, "evidence"), *e;
        size_t k;
        tu_check_interval(iv, want + i, i, what);
        /* every cell carries its evidence: a re-checked certificate, or a counterexample */
        assert_true(json_array_size(ev) > 0);
        json_array_foreach(ev, k, e) {
            if (strcmp(want[i].status, "unstable") == 0 || strcmp(want[i].status, "singular") == 0) {
                assert_non_null(json_object_get(e, "counterexample"));
                assert_string_equal(tu_str(json_object_get(e, "at_counterexample"), "status"), want[i].status);
            } else {
                assert_true(json_is_true(json_object_get(e, "certificate_rechecked")));
                /* real evidence, not an empty certificate (conditions positive by their
                 * factors' signs are certified on the set too) */
                assert_true(json_array_size(json_object_get(e, "certificate")) > 0);
            }
            if (strcmp(want[i].status, "marginal") == 0) assert_non_null(json_object_get(e, "not_stable_at"));
        }
    }
}

/* case text with --set values (NULL-terminated "NAME=VALUE" list); *code
 * the status (NULL: an error fails the test) */
static json_t *run_set(const char *text, const char *const *sets, int *outcome, int *code)
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
    for (; r == RS_OK && sets != NULL && *sets != NULL; sets++) r = rs_case_set_value(c, *sets, err);
    if (r == RS_OK) r = rs_analysis_run(&doc, outcome, c, &opt, err);
    rs_case_clear(c);
    if (code != NULL) *code = r;
    else if (r != RS_OK || doc == NULL) fail_msg("%s: %s", text, err->msg);
    return doc;
}

static json_t *run_ok(const char *text, int *outcome)
{
    return run_set(text, NULL, outcome, NULL);
}

static void test_theta(void **state)
{
    static const char *req[] = {"region th for all [w]", "region th for all", "claim stable when th > 1/2",
                                "claim stable when th > 2/5", "claim bounded when th >= 1/2"};
    static const struct tu_iv want[] = {{"inf", 0, "1/2", 0, "unstable"}, {"1/2", 1, "1/2", 1, "marginal"},
                                     {"1/2", 0, "inf", 0, "stable"}};
    int outcome;
    json_t *doc = tu_run_case("cases/forall/theta-oscillator.case", req, 5, &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 3, "theta for all [w]");
    check_region(tu_result(doc, 1), want, 3, "theta for all");
    assert_string_equal(json_string_value(json_array_get(json_object_get(tu_result(doc, 0), "for_all"), 0)), "w");
    /* claims agree with the region: inside proved, reaching outside refuted */
    assert_string_equal(tu_str(tu_result(doc, 2), "status"), "proved");
    assert_string_equal(tu_str(tu_result(doc, 3), "status"), "refuted");
    assert_string_equal(tu_str(tu_result(doc, 4), "status"), "proved");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

static void test_central_difference(void **state)
{
    static const struct tu_iv want[] = {{"0", 0, "2", 0, "marginal"}, {"2", 1, "inf", 0, "unstable"}};
    int outcome;
    json_t *doc = run_ok("param w\nassume w > 0\nunknown x\neq x[n+1] - 2*x[n] + x[n-1] + w^2*x[n] = 0\n"
                         "analyse region w for all\n", &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 2, "central difference");
    assert_int_equal(json_array_size(json_object_get(tu_result(doc, 0), "for_all")), 0);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

#define NEWMARK "param b g w\nassume w > 0\nsubsystem S state x v\n  x'' = -w^2*x\nintegrate S newmark b g 1\n"

static void test_newmark(void **state)
{
    static const struct tu_iv half[] = {{"inf", 0, "0", 0, "singular"}, {"0", 1, "1/4", 0, "unstable"},
                                     {"1/4", 1, "inf", 0, "marginal"}};
    static const struct tu_iv damped[] = {{"inf", 0, "0", 0, "singular"}, {"0", 1, "3/10", 0, "unstable"},
                                       {"3/10", 1, "inf", 0, "stable"}};
    int outcome;
    static const char *const g1[] = {"g=1/2", NULL}, *const g2[] = {"g=3/5", NULL};
    json_t *doc = run_set(NEWMARK "analyse region b for all [w]\n", g1, &outcome, NULL);
    (void) state;
    check_region(tu_result(doc, 0), half, 3, "newmark gamma = 1/2");
    json_decref(doc);
    doc = run_set(NEWMARK "analyse region b for all [w]\n", g2, &outcome, NULL);
    check_region(tu_result(doc, 0), damped, 3, "newmark gamma = 3/5");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* HHT-alpha with alpha left free (bench/bench_qepcad.sh's case, issue 13):
 * for all w > 0, unstable below -1/2, stable on [-1/2, 0), marginal at 0,
 * unstable above.  Derived apart from recstab: as w -> inf, p / w^2 ->
 * ((1 + alpha) lambda - alpha) (...), a root alpha / (1 + alpha), outside the
 * circle iff alpha < -1/2 (the end -1/2); alpha = 0 is the trapezoidal rule,
 * |lambda| = 1 (cases/textbook/hht-alpha.case); HHT 1977: stable on
 * [-1/3, 0); the rest numerically (mpmath.polyroots, w = 10^(k/20), k = -60..80:
 * max |lambda| = 1.0408 at alpha = -0.51, <= 1 + 2e-14 at -0.49, -0.45, -0.4,
 * -1/3, -0.2, -0.1, -0.01; 1.0202 at 0.01, 1.2222 at 0.1).  The full
 * projection has spurious critical values inside (-1/2, 0) (-1/3 and roots
 * of 4 a^2 + 6 a + 1 and 9 a^2 + 12 a + 1): their cells share one
 * certificate on an interval (proved_on), every one re-checked. */
static void test_hht_free(void **state)
{
    static const struct tu_iv want[] = {{"inf", 0, "-1/2", 0, "unstable"}, {"-1/2", 1, "0", 0, "stable"},
                                        {"0", 1, "0", 1, "marginal"}, {"0", 0, "inf", 0, "unstable"}};
    const json_t *ev, *e;
    size_t k, shared = 0;
    int outcome;
    json_t *doc = run_ok("param alpha w\nassume w > 0\nunknown d V A\nlet beta = (1 - alpha)^2/4\n"
                         "let gamma = 1/2 - alpha\n"
                         "eq A[n+1] + (1 + alpha)*w^2*d[n+1] - alpha*w^2*d[n] = 0\n"
                         "eq d[n+1] = d[n] + V[n] + (1/2 - beta)*A[n] + beta*A[n+1]\n"
                         "eq V[n+1] = V[n] + (1 - gamma)*A[n] + gamma*A[n+1]\n"
                         "analyse region alpha for all\n", &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 4, "hht-alpha, alpha free");
    ev = json_object_get(json_array_get(json_object_get(tu_result(doc, 0), "intervals"), 1), "evidence");
    /* open cells decided by the shared certificate (one proof per cell before) */
    json_array_foreach(ev, k, e)
        shared += json_object_get(e, "proved_on") != NULL && tu_str(e, "cell") != NULL
                  && strcmp(tu_str(e, "cell"), "interval") == 0;
    assert_true(shared >= 2);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

static void test_park(void **state)
{
    static const struct tu_iv want[] = {{"0", 1, "3/2", 1, "stable"}, {"3/2", 0, "inf", 0, "unstable"}};
    static const char *const sets[] = {"m=1", "muh=1", NULL};
    int outcome, code;
    json_t *doc;
    (void) state;
    doc = run_set("param m muh wh alpha\nassume m > 0, muh > 0, wh > 0, alpha >= 0\nunknown y x v a\n"
                      "let yp[n+1] = (1 + alpha)*y[n] - alpha*y[n-1]\n"
                      "eq 3*y[n+1] - 4*y[n] + y[n-1] + 2*(1 + m)*muh*y[n+1] + 2*wh^2*x[n+1] = 0\n"
                      "eq x[n+1] - x[n] = (v[n+1] + v[n])/2\neq v[n+1] - v[n] = (a[n+1] + a[n])/2\n"
                      "eq a[n+1] + wh^2*x[n+1] + m*muh*yp[n+1] = 0\n"
                      "analyse region alpha for all [wh]\n", sets, &outcome, &code);
    assert_int_equal(code, RS_OK);
    check_region(tu_result(doc, 0), want, 2, "park at m = muh = 1");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

#define PARK "param m muh wh alpha\nassume m > 0, muh > 0, wh > 0, alpha >= 0\nunknown y x v a\n" \
    "let yp[n+1] = (1 + alpha)*y[n] - alpha*y[n-1]\n" \
    "eq 3*y[n+1] - 4*y[n] + y[n-1] + 2*(1 + m)*muh*y[n+1] + 2*wh^2*x[n+1] = 0\n" \
    "eq x[n+1] - x[n] = (v[n+1] + v[n])/2\neq v[n+1] - v[n] = (a[n+1] + a[n])/2\n" \
    "eq a[n+1] + wh^2*x[n+1] + m*muh*yp[n+1] = 0\n"

/* Park for all of two and of all three others: alpha <= 1 exactly, every
 * cell decided (no undecided point), the unstable side reached only in the
 * limit m, muh -> inf (no counterexample at alpha = 1 itself) */
static void test_park_all(void **state)
{
    static const struct tu_iv want[] = {{"0", 1, "1", 1, "stable"}, {"1", 0, "inf", 0, "unstable"}};
    static const char *const m1[] = {"m=1", NULL};
    int outcome, code;
    json_t *doc;
    (void) state;
    doc = run_set(PARK "analyse region alpha for all [muh, wh]\n", m1, &outcome, &code);
    assert_int_equal(code, RS_OK);
    check_region(tu_result(doc, 0), want, 2, "park at m = 1, for all muh, wh");
    assert_int_equal(json_array_size(json_object_get(tu_result(doc, 0), "undecided_points")), 0);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
    doc = run_set(PARK "analyse region alpha for all\nclaim stable when alpha <= 1\nclaim stable when alpha <= 2\n",
                  NULL, &outcome, &code);
    assert_int_equal(code, RS_OK);
    check_region(tu_result(doc, 0), want, 2, "park for all m, muh, wh");
    assert_int_equal(json_array_size(json_object_get(tu_result(doc, 0), "for_all")), 3);
    /* the claims agree with the region */
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "proved");
    assert_string_equal(tu_str(tu_result(doc, 2), "status"), "refuted");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* Ends reached only in a limit of the quantified parameter, closedness
 * decided exactly.  By hand: (1 + w) x[n+1] = (1 + w - a w) x[n] has
 * lambda = 1 - a w/(1 + w); for w > 0, w/(1 + w) fills (0, 1), so
 * |lambda| < 1 for every w iff 0 < a w/(1 + w) < 2 for every w iff 0 < a <= 2
 * (at a = 2, lambda = (1 - w)/(1 + w) is inside for every w > 0: the end is
 * closed although lambda -> -1 as w -> inf); a = 0: lambda = 1 (marginal);
 * a > 2: lambda < -1 for w > 2/(a - 2); a < 0: lambda > 1.  Likewise
 * (1 + m) x[n+1] = (1 + m - a) x[n], lambda = 1 - a/(1 + m), a/(1 + m) fills
 * (0, a) for m > 0: the same range, its end 2 approached as m -> 0. */
static void test_limit_ends(void **state)
{
    static const struct tu_iv want[] = {{"inf", 0, "0", 0, "unstable"}, {"0", 1, "0", 1, "marginal"},
                                     {"0", 0, "2", 1, "stable"}, {"2", 0, "inf", 0, "unstable"}};
    int outcome;
    json_t *doc = run_ok("param a w\nassume w > 0\nunknown x\neq (1 + w)*x[n+1] = (1 + w - a*w)*x[n]\n"
                         "analyse region a for all [w]\n", &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 4, "w -> inf");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
    doc = run_ok("param a m\nassume m > 0\nunknown x\neq (1 + m)*x[n+1] = (1 + m - a)*x[n]\n"
                 "analyse region a for all [m]\n", &outcome);
    check_region(tu_result(doc, 0), want, 4, "m -> 0");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* ---- claims decided again by the region engine (issue 13 part 1) ----------
 * "cross_check" agrees with the claim's own verdict, and a failed claim's
 * "explanation" lists the region intervals inside the claim's set that are
 * not stable (bounded), with counterexamples, and the largest proved
 * sub-interval.  Expected ranges: those derived at the top of this file
 * (theta: stable iff th > 1/2, marginal at 1/2; central difference: marginal
 * on (0, 2), unstable on [2, inf); Park: stable exactly on [0, 1]). */

/* an interval object is lo..hi with the given closedness */
static void check_iv(const json_t *iv, const char *lo, int lc, const char *hi, int hc, const char *what)
{
    assert_non_null(iv);
    if (strcmp(tu_end(iv, "lo"), lo) != 0 || strcmp(tu_end(iv, "hi"), hi) != 0
        || json_is_true(json_object_get(iv, "lo_closed")) != lc || json_is_true(json_object_get(iv, "hi_closed")) != hc)
        fail_msg("%s: %s%s, %s%s, expected %s%s, %s%s", what, json_is_true(json_object_get(iv, "lo_closed")) ? "[" : "(",
                 tu_end(iv, "lo"), tu_end(iv, "hi"), json_is_true(json_object_get(iv, "hi_closed")) ? "]" : ")",
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
    assert_int_equal(fmpq_set_str(x, tu_str(cx, name), 10), 0);
    fmpq_set_str(a, lo, 10);
    assert_true(fmpq_cmp(x, a) >= 0);
    if (hi != NULL) {
        fmpq_set_str(a, hi, 10);
        assert_true(fmpq_cmp(x, a) <= 0);
    }
    assert_true(strcmp(tu_str(json_object_get(f, "at_counterexample"), "status"), "stable") != 0);
    fmpq_clear(x);
    fmpq_clear(a);
}

#define THETA "param th w\nassume w > 0\nunknown x v\neq x[n+1] - x[n] = th*v[n+1] + (1 - th)*v[n]\n" \
    "eq v[n+1] - v[n] = -w^2*(th*x[n+1] + (1 - th)*x[n])\n"

static void test_claim_theta(void **state)
{
    int outcome;
    const json_t *ex, *fl;
    json_t *doc = run_ok(THETA "claim stable when th > 2/5\nclaim bounded when th >= 2/5\n"
                                 "claim bounded when th >= 1/2\n", &outcome);
    (void) state;
    /* stable claim on (2/5, inf): unstable (2/5, 1/2), marginal {1/2}, proved (1/2, inf) */
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "refuted");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 0), "cross_check"), "status"), "agrees");
    ex = json_object_get(tu_result(doc, 0), "explanation");
    assert_string_equal(tu_str(ex, "param"), "th");
    check_iv(json_object_get(ex, "proved_part"), "1/2", 0, "inf", 0, "theta stable part");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 2);
    check_iv(json_array_get(fl, 0), "2/5", 0, "1/2", 0, "theta unstable part");
    assert_string_equal(tu_str(json_array_get(fl, 0), "status"), "unstable");
    check_cx(json_array_get(fl, 0), "th", "2/5", "1/2");
    check_iv(json_array_get(fl, 1), "1/2", 1, "1/2", 1, "theta marginal point");
    assert_string_equal(tu_str(json_array_get(fl, 1), "status"), "marginal");
    check_cx(json_array_get(fl, 1), "th", "1/2", "1/2");
    /* bounded claim on [2/5, inf): proved part [1/2, inf) (marginal point and stable side merged) */
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "refuted");
    ex = json_object_get(tu_result(doc, 1), "explanation");
    check_iv(json_object_get(ex, "proved_part"), "1/2", 1, "inf", 0, "theta bounded part");
    assert_int_equal(json_array_size(json_object_get(ex, "failing")), 1);
    check_iv(json_array_get(json_object_get(ex, "failing"), 0), "2/5", 1, "1/2", 0, "theta bounded failing");
    /* a true claim: proved, the region agrees, nothing to explain */
    assert_string_equal(tu_str(tu_result(doc, 2), "status"), "proved");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 2), "cross_check"), "status"), "agrees");
    assert_null(json_object_get(tu_result(doc, 2), "explanation"));
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

static void test_claim_central_difference(void **state)
{
    int outcome;
    const json_t *ex, *fl;
    json_t *doc = run_ok("param w\nassume w > 0\nunknown x\neq x[n+1] - 2*x[n] + x[n-1] + w^2*x[n] = 0\n"
                           "claim bounded when w < 3\nclaim bounded when w < 2\nclaim stable when w < 1\n", &outcome);
    (void) state;
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "refuted");
    ex = json_object_get(tu_result(doc, 0), "explanation");
    check_iv(json_object_get(ex, "proved_part"), "0", 0, "2", 0, "central difference bounded part");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 1);
    check_iv(json_array_get(fl, 0), "2", 1, "3", 0, "central difference failing");
    assert_string_equal(tu_str(json_array_get(fl, 0), "status"), "unstable");
    check_cx(json_array_get(fl, 0), "w", "2", "3");
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "proved");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 1), "cross_check"), "status"), "agrees");
    /* never stable (|lambda| = 1): no proved part, the whole set marginal */
    assert_string_equal(tu_str(tu_result(doc, 2), "status"), "refuted");
    ex = json_object_get(tu_result(doc, 2), "explanation");
    assert_true(json_is_null(json_object_get(ex, "proved_part")));
    check_iv(json_array_get(json_object_get(ex, "failing"), 0), "0", 0, "1", 0, "central difference marginal");
    assert_string_equal(tu_str(json_array_get(json_object_get(ex, "failing"), 0), "status"), "marginal");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* Claims of other forms are cross-checked too: `or` (each part's interval
 * against the region), and conditions on the quantified parameters (they
 * restrict the for-all).  Expected by hand: theta as above; the quadratic
 * lambda^2 + a lambda + b is stable iff |b| < 1 and |a| < 1 + b (Jury), so for
 * every b in (0, 1/2) iff |a| <= 1, and for a in (1, 5/4] some b in
 * (0, a - 1) there is unstable. */
static void test_claim_forms(void **state)
{
    int outcome;
    const json_t *ex, *fl, *cx;
    fmpq_t x, lo, hi;
    json_t *doc = run_ok(THETA "claim stable when th > 1 or 1/2 < th < 3/4\nclaim stable when th > 1 or th < 1/4\n"
                                 "claim stable when th > w\n", &outcome);
    (void) state;
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "proved");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 0), "cross_check"), "status"), "agrees");
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "refuted");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 1), "cross_check"), "status"), "agrees");
    ex = json_object_get(tu_result(doc, 1), "explanation");
    check_iv(json_object_get(ex, "proved_part"), "1", 0, "inf", 0, "or: proved part");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 1);
    check_iv(json_array_get(fl, 0), "inf", 0, "1/4", 0, "or: failing part");   /* null lo: -inf */
    assert_string_equal(tu_str(json_array_get(fl, 0), "status"), "unstable");
    /* th tied to w: the region cannot say; the claim keeps its verdict */
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 2), "cross_check"), "status"), "not made");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);

    doc = run_ok("param a b\nchar lambda^2 + a*lambda + b\nclaim stable when -1 <= a <= 1, 0 < b < 1/2\n"
                 "claim stable when 0 <= a <= 5/4, 0 < b < 1/2\n", &outcome);
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "proved");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 0), "cross_check"), "status"), "agrees");
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "refuted");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 1), "cross_check"), "status"), "agrees");
    ex = json_object_get(tu_result(doc, 1), "explanation");
    /* without the restriction on b every a fails (b = 2): [0, 1] proves it was applied */
    check_iv(json_object_get(ex, "proved_part"), "0", 1, "1", 1, "restricted b: proved part");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 1);
    check_iv(json_array_get(fl, 0), "1", 0, "5/4", 1, "restricted b: failing part");
    check_cx(json_array_get(fl, 0), "a", "1", "5/4");
    /* the counterexample's b inside the claim's (0, 1/2) */
    cx = json_object_get(json_array_get(fl, 0), "counterexample");
    fmpq_init(x); fmpq_init(lo); fmpq_init(hi);
    assert_int_equal(fmpq_set_str(x, tu_str(cx, "b"), 10), 0);
    fmpq_set_si(hi, 1, 2);
    assert_true(fmpq_sgn(x) > 0 && fmpq_cmp(x, hi) < 0);
    fmpq_clear(x); fmpq_clear(lo); fmpq_clear(hi);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* Park's printed "alpha <= 2": proved on [0, 1], fails on (1, 2] */
static void test_claim_park(void **state)
{
    int outcome;
    const json_t *ex, *fl;
    json_t *doc = run_ok(PARK "claim stable when alpha <= 2\n", &outcome);
    (void) state;
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "refuted");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 0), "cross_check"), "status"), "agrees");
    ex = json_object_get(tu_result(doc, 0), "explanation");
    check_iv(json_object_get(ex, "proved_part"), "0", 1, "1", 1, "park proved part");
    assert_string_equal(tu_str(json_object_get(ex, "proved_part"), "status"), "stable");
    fl = json_object_get(ex, "failing");
    assert_int_equal(json_array_size(fl), 1);
    check_iv(json_array_get(fl, 0), "1", 0, "2", 1, "park failing part");
    assert_string_equal(tu_str(json_array_get(fl, 0), "status"), "unstable");
    check_cx(json_array_get(fl, 0), "alpha", "1", "2");
    assert_int_equal(json_array_size(json_object_get(ex, "for_all")), 3);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* bad requests: a clear error, no result */
static void test_bad(void **state)
{
    static const char *bad[] = {
        "analyse region th for all [x]\n", "analyse region th for all [th]\n", "analyse region th for all [w\n",
        "analyse region th for all [w, w]\n", "analyse region th for every\n", "analyse region th for all w\n",
        "analyse region th for all [w] extra\n", "analyse region th for all []\n"};
    static const char *const setw[] = {"w=1", NULL};
    size_t i;
    (void) state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char buf[512];
        int outcome, code;
        json_t *doc;
        snprintf(buf, sizeof buf, "param th w\nassume w > 0\nunknown x\neq x[n+1] = x[n] - th*w*x[n]\n%s", bad[i]);
        doc = run_set(buf, NULL, &outcome, &code);
        if (code != RS_ERR_INPUT) fail_msg("%s: code %d, expected an input error", bad[i], code);
        json_decref(doc);
    }
    {   /* a quantified parameter that is set */
        int outcome, code;
        json_t *doc = run_set("param th w\nassume w > 0\nunknown x\neq x[n+1] = x[n] - th*w*x[n]\n"
                              "analyse region th for all [w]\n", setw, &outcome, &code);
        assert_int_equal(code, RS_ERR_INPUT);
        json_decref(doc);
    }
}

static void test_jordan(void **state)
{
    static const struct tu_iv driven[] = {{"inf", 0, "0", 0, "unstable"}, {"0", 1, "0", 1, "marginal"},
                                       {"0", 0, "inf", 0, "unstable"}};
    static const struct tu_iv coupled[] = {{"inf", 0, "-1", 1, "unstable"}, {"-1", 0, "1", 0, "marginal"},
                                        {"1", 1, "inf", 0, "unstable"}};
    int outcome;
    json_t *doc = tu_run_case("cases/forall/driven-oscillators.case", NULL, -1, &outcome);
    (void) state;
    check_region(tu_result(doc, 0), driven, 3, "driven oscillators");
    assert_string_equal(tu_str(tu_result(doc, 0), "projection"), "full");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
    doc = run_ok("param eps h\nassume 0 < h < 1\nunknown x y\n"
                 "eq x[n+1] - 2*x[n] + x[n-1] = h^2*(-x[n] + eps*y[n])\n"
                 "eq y[n+1] - 2*y[n] + y[n-1] = h^2*(-y[n] + eps*x[n])\n"
                 "analyse region eps for all [h]\n", &outcome);
    check_region(tu_result(doc, 0), coupled, 3, "coupled oscillators");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_theta),
        cmocka_unit_test(test_central_difference),
        cmocka_unit_test(test_newmark),
        cmocka_unit_test(test_park),
        cmocka_unit_test(test_hht_free),
        cmocka_unit_test(test_park_all),
        cmocka_unit_test(test_jordan),
        cmocka_unit_test(test_limit_ends),
        cmocka_unit_test(test_bad),
        cmocka_unit_test(test_claim_theta),
        cmocka_unit_test(test_claim_central_difference),
        cmocka_unit_test(test_claim_park),
        cmocka_unit_test(test_claim_forms),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
