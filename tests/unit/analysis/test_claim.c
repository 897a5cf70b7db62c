/* test_claim.c -- claims people write (issue 10, items 6 and 7), defaults,
 * parameters p does not depend on, and simulate's cross-check.  Expected
 * values, each derived independently of recstab:
 *   - BDF2 on y' = q y: p = (3 - 2q) l^2 - 4 l + 1 (rho - q sigma); its
 *     boundary locus q(theta) = (3 - 4e^{-i theta} + e^{-2 i theta})/2 meets
 *     the real axis at 0 and 4: stable for q < 0 and q > 4, unstable in
 *     (0, 4), singular at q = 3/2 where 3 - 2q = 0;
 *   - Adams-Moulton 2-step: p = (12 - 5q) l^2 - (12 + 8q) l + q, stability
 *     interval (-6, 0) (Hairer-Wanner II, V.1); p(-1) = -4q - 24, p(1) = -12q,
 *     at q = -6 p = 6 (7l - 1)(l + 1) and at q = 0 p = 12 l (l - 1): marginal;
 *     singular at q = 12/5;
 *   - HHT-alpha: unconditionally stable for alpha in [-1/3, 0) and the
 *     trapezoidal rule (|lambda| = 1) at alpha = 0 (Hilber, Hughes, Taylor
 *     1977); the characteristic polynomial is eliminated by hand in the case
 *     file (golden test in test_golden.c);
 *   - (q^2 - q + 2) l - (q^2 - q): stable iff q^2 - q + 1 > 0, always
 *     (discriminant -3); with q = s the numerator s^2 - s + 1 has a negative
 *     coefficient but (1 + s)(s^2 - s + 1) = s^3 + 1 does not (Polya, N = 1);
 *   - m x[n+1] = m x[n]/2: root 1/2 for every m != 0;
 *   - a Jordan block x[n+1] = x[n] + y[n], y[n+1] = y[n]: |z_n| ~ n, so the
 *     window estimate of simulate (log-norm averages centred near 3N/8 and
 *     7N/8) is log g ~ ln(7/3) / (N/2). */
#include "testutil.h"
#include <string.h>
#include <math.h>
#include "recstab/casefile.h"
#include "recstab/analysis.h"
#include "analysis/impl.h"
#include "recstab/rootcount.h"
#include <flint/fmpq_poly.h>

static const json_t *result(const json_t *doc, size_t i)
{
    return json_array_get(json_object_get(doc, "results"), i);
}

static const char *str(const json_t *o, const char *k)
{
    return json_string_value(json_object_get(o, k));
}

/* Runs a case given as text; returns the document (NULL on an error, with
 * *code the error code). */
static json_t *run_text(const char *text, int *outcome, int *code)
{
    return tu_run_text(text, NULL, outcome, code);
}

static json_t *run_ok(const char *text, int *outcome)
{
    int code;
    json_t *doc = run_text(text, outcome, &code);
    if (code != RS_OK || doc == NULL) fail_msg("unexpected error %d for:\n%s", code, text);
    return doc;
}

#define BDF2 "param q\nunknown y\neq 3*y[n+2] - 4*y[n+1] + y[n] = 2*q*y[n+2]\n"
#define CIRCLE3 "param q\nchar (lambda^2 + 1)*(lambda^2 + q*lambda + 1)*(lambda^2 - lambda + 1)\n"
#define AM2 "param q\nunknown y\neq 12*(y[n+2] - y[n+1]) = q*(5*y[n+2] + 8*y[n+1] - y[n])\n"

struct claim_case { const char *file, *text, *claim, *status; };

static void check_claims(const struct claim_case *t, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        int outcome;
        json_t *doc;
        const char *got;
        if (t[i].file != NULL) {
            doc = tu_run_case(t[i].file, &t[i].claim, 1, &outcome);
        } else {
            char buf[2048];
            snprintf(buf, sizeof buf, "%s%s\n", t[i].text, t[i].claim);
            doc = run_ok(buf, &outcome);
        }
        got = str(result(doc, 0), "status");
        if (got == NULL || strcmp(got, t[i].status) != 0)
            fail_msg("%s / %s: %s, expected %s", t[i].file ? t[i].file : t[i].text, t[i].claim, got, t[i].status);
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        assert_int_equal(outcome & RS_OUTCOME_FAILED, strcmp(t[i].status, "refuted") == 0);
        json_decref(doc);
    }
}

/* true claims whose conditions vanish at an open end of the set */
static void test_claim_open_ends(void **state)
{
    static const struct claim_case t[] = {
        {NULL, BDF2, "claim stable when q < 0", "proved"},
        {NULL, BDF2, "claim stable when q > 4", "proved"},
        {NULL, BDF2, "claim stable when q >= 4", "refuted"},          /* q = 4: root -1 */
        {NULL, AM2, "claim stable when -6 < q < 0", "proved"},
        {NULL, AM2, "claim stable when -6 <= q < 0", "refuted"},      /* q = -6: marginal */
        {NULL, AM2, "claim unstable when q < -6", "proved"},
        {"cases/textbook/newmark-average-acceleration.case", NULL, "claim bounded when w > 0", "proved"},
        {"cases/textbook/hht-alpha.case", NULL, "claim stable when -1/3 <= alpha < 0 and w > 0", "proved"},
    };
    (void) state;
    check_claims(t, sizeof t / sizeof t[0]);
}

/* NAME = VALUE substitutes; or; bounded over stable + marginal parts */
static void test_claim_sets(void **state)
{
    static const struct claim_case t[] = {
        {"cases/textbook/hht-alpha.case", NULL, "claim bounded when alpha = 0 and w > 0", "proved"},
        {"cases/textbook/hht-alpha.case", NULL, "claim stable when alpha = 0 and w > 0", "refuted"},
        {"cases/textbook/hht-alpha.case", NULL, "claim bounded when -1/3 <= alpha <= 0 and w > 0", "proved"},
        {"cases/textbook/hht-alpha.case", NULL, "claim stable when -1/3 <= alpha <= 0 and w > 0", "refuted"},
        {"cases/textbook/hht-alpha.case", NULL, "claim bounded when -1/3 <= alpha <= -1/5 or alpha = 0", "proved"},
        {NULL, AM2, "claim bounded when -6 <= q <= 0", "proved"},
        {NULL, AM2, "claim bounded when -6 <= q <= 0 or q = -7", "refuted"},
        {NULL, AM2, "claim unstable when q < -6 or 0 < q < 12/5", "proved"},
        {NULL, BDF2, "claim stable when q < 0 or q > 4", "proved"},
        {NULL, BDF2, "claim stable when q = -1", "proved"},
        /* root (1 - q^2)/(1 + q^2): |.| < 1 except lambda = 1 at q = 0 (inner split) */
        {NULL, "param q\nchar (1 + q^2)*lambda - (1 - q^2)\n", "claim bounded when -1 <= q <= 1", "proved"},
        {NULL, "param q\nchar (1 + q^2)*lambda - (1 - q^2)\n", "claim stable when -1 <= q <= 1", "refuted"},
        /* (l^2 + 1)(l^2 + q l + 1)(l^2 - l + 1): six circle roots for |q| < 2, the
         * middle pair e^{+-i theta}, 2 cos theta = -q, meets +-i at q = 0 and
         * e^{+-i pi/3} at q = -1 (double roots of a scalar recurrence) */
        {NULL, CIRCLE3, "claim bounded when 0 < q < 2", "proved"},
        {NULL, CIRCLE3, "claim bounded when -2 < q < -1", "proved"},
        {NULL, CIRCLE3, "claim bounded when -1/2 < q < 1/2", "refuted"},
        /* leapfrog on 8 points: modes l^2 + 2i nu sin(2 pi j/8) l - 1, all on the
         * circle and semisimple for 0 < nu < 1 (repeated factors j, 8 - j),
         * Jordan blocks at nu = 1 (test_semisimple) */
        {"cases/textbook/leapfrog-periodic8.case", NULL, "claim bounded when nu < 1", "proved"},
        {"cases/textbook/leapfrog-periodic8.case", NULL, "claim bounded when nu <= 1", "refuted"},
    };
    (void) state;
    check_claims(t, sizeof t / sizeof t[0]);
}

/* a singular point (leading coefficient of det zero) violates every claim */
static void test_claim_singular(void **state)
{
    static const struct claim_case t[] = {
        {NULL, BDF2, "claim unstable when 0 < q < 4", "refuted"},     /* at q = 3/2 */
        {NULL, BDF2, "claim unstable when 0 < q < 3/2 or 3/2 < q < 4", "proved"},
        {NULL, BDF2, "claim bounded when q = 3/2", "refuted"},
        {NULL, "param q\nunknown y\neq (1 - q)*y[n+1] = y[n]\n", "claim unstable when 0 < q < 2", "refuted"},
        {NULL, "param q\nunknown y\neq (1 - q)*y[n+1] = y[n]\n", "claim unstable when 0 < q < 1", "proved"},
    };
    int outcome;
    json_t *doc;
    const json_t *at;
    (void) state;
    check_claims(t, sizeof t / sizeof t[0]);
    doc = run_ok(BDF2 "claim unstable when 0 < q < 4\n", &outcome);
    at = json_object_get(result(doc, 0), "at_counterexample");
    assert_string_equal(str(at, "status"), "singular");
    assert_string_equal(str(json_object_get(result(doc, 0), "counterexample"), "q"), "3/2");
    json_decref(doc);
}

/* Polya multiplier and the report of an undecided claim */
static void test_claim_certificates(void **state)
{
    int outcome;
    json_t *doc;
    const json_t *cert, *o;
    size_t i;
    slong polya = 0;
    (void) state;
    doc = run_ok("param q\nchar (q^2 - q + 2)*lambda - (q^2 - q)\nclaim stable when q > 0\n", &outcome);
    o = result(doc, 0);
    assert_string_equal(str(o, "status"), "proved");
    cert = json_object_get(o, "certificate");
    for (i = 0; i < json_array_size(cert); i++)
        if (json_integer_value(json_object_get(json_array_get(cert, i), "polya_power")) > 0)
            polya = json_integer_value(json_object_get(json_array_get(cert, i), "polya_power"));
    assert_int_equal(polya, 1);
    json_decref(doc);
    /* false at the singular point q = 12/5 (leading coefficient 12 - 5q):
     * found among the special points (roots of p(1), p(-1), the leading
     * coefficient) */
    doc = run_ok(AM2 "claim unstable when q > 0\n", &outcome);
    o = result(doc, 0);
    assert_string_equal(str(o, "status"), "refuted");
    assert_string_equal(str(json_object_get(o, "counterexample"), "q"), "12/5");
    json_decref(doc);
    /* false only at the irrational singular point q = sqrt(2) (leading
     * coefficient q^2 - 2): no rational counterexample, no certificate:
     * undecided, saying where the certificate failed */
    doc = run_ok("param q\nchar (q^2 - 2)*lambda + (q^2 + 3*q + 1)\nclaim unstable when 1 <= q <= 4\n", &outcome);
    o = result(doc, 0);
    assert_string_equal(str(o, "status"), "undecided");
    assert_non_null(str(o, "tried"));
    assert_non_null(strstr(str(o, "failed_at"), "q^2 - 2"));
    json_decref(doc);
}

/* parameters p does not depend on need no value */
static void test_not_in_p(void **state)
{
    int outcome, code;
    json_t *doc;
    const json_t *o;
    (void) state;
    doc = run_ok("param m c\nunknown x\neq m*x[n+1] = m*x[n]/2\nanalyse stability\nanalyse radius digits=10\n"
                 "analyse simulate steps=200\n", &outcome);
    o = result(doc, 0);
    assert_string_equal(str(o, "status"), "stable");
    assert_int_equal(json_array_size(json_object_get(o, "not_in_p")), 2);
    assert_string_equal(json_string_value(json_array_get(json_object_get(o, "not_in_p"), 0)), "m");
    assert_int_equal(json_object_size(json_object_get(o, "substituted")), 0);
    assert_non_null(json_object_get(result(doc, 1), "not_in_p"));
    /* radius 1/2 (the root of 2 lambda - 1) */
    assert_true(fabs(atof(str(result(doc, 2), "radius")) - 0.5) < 1e-12);
    assert_int_equal(outcome, RS_OUTCOME_OK);
    json_decref(doc);
    /* a parameter that does occur in p still needs a value */
    doc = run_text("param m\nunknown x\neq x[n+1] = m*x[n]\nanalyse stability\n", &outcome, &code);
    assert_null(doc);
    assert_int_equal(code, RS_ERR_INPUT);
}

/* a case with no analyse line */
static void test_defaults(void **state)
{
    int outcome, code;
    json_t *doc;
    const json_t *d, *o;
    (void) state;
    /* forward Euler on y' = -w y: p = lambda + w - 1, stable iff 0 < w < 2 */
    doc = run_ok("param w\nunknown x\neq x[n+1] = (1 - w)*x[n]\n", &outcome);
    d = json_object_get(doc, "default_analyses");
    assert_int_equal(json_array_size(d), 3);
    assert_string_equal(json_string_value(json_array_get(d, 1)), "hurwitz");
    assert_string_equal(json_string_value(json_array_get(d, 2)), "region w");
    o = json_object_get(result(doc, 2), "intervals");
    assert_string_equal(str(json_array_get(o, 2), "status"), "stable");
    assert_string_equal(str(json_array_get(o, 2), "lo"), "0");
    assert_string_equal(str(json_array_get(o, 2), "hi"), "2");
    json_decref(doc);
    /* two free parameters: no region */
    doc = run_ok("param w a\nunknown x\neq x[n+1] = (a - w)*x[n]\n", &outcome);
    assert_int_equal(json_array_size(json_object_get(doc, "default_analyses")), 2);
    json_decref(doc);
    /* every parameter set: stability (root 1/2) */
    doc = run_ok("param w\nunknown x\neq x[n+1] = (1 - w)*x[n]\nset w = 1/2\n", &outcome);
    assert_string_equal(json_string_value(json_array_get(json_object_get(doc, "default_analyses"), 1)),
                        "stability");
    assert_string_equal(str(result(doc, 1), "status"), "stable");
    json_decref(doc);
    /* identically zero determinant: bad input */
    doc = run_text("param w\nunknown x y\neq x[n+1] = w*y[n]\neq 2*x[n+1] = 2*w*y[n]\n", &outcome, &code);
    assert_null(doc);
    assert_int_equal(code, RS_ERR_MATH);   /* exit 2: tests/bad/default-zero-det */
}

/* simulate against the exact verdict */
static void test_simulate_check(void **state)
{
    int outcome;
    json_t *doc;
    const json_t *o;
    double tau, lg, want = log(7.0 / 3.0) / 500.0;
    (void) state;
    doc = run_ok("unknown x y\neq x[n+1] = x[n] + y[n]\neq y[n+1] = y[n]\nanalyse simulate steps=1000\n", &outcome);
    o = result(doc, 0);
    lg = json_real_value(json_object_get(json_object_get(o, "check"), "log_growth"));
    /* polynomial growth n^1: within 5% of ln(7/3)/(N/2), below the threshold */
    assert_true(fabs(lg - want) < 0.05 * want);
    assert_true(json_is_true(json_object_get(json_object_get(o, "check"), "consistent")));
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
    /* the identity system: every state stays where it is, growth exactly 1;
     * marginal (semisimple double root 1) and consistent */
    doc = run_ok("unknown x y\neq x[n+1] = x[n]\neq y[n+1] = y[n]\nanalyse simulate steps=1000\n", &outcome);
    o = result(doc, 0);
    assert_true(fabs(json_real_value(json_object_get(json_object_get(o, "check"), "log_growth"))) < 1e-12);
    assert_string_equal(str(json_object_get(o, "verdict"), "status"), "marginal");
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
    /* the rule itself: tau = (d ln(7/3) + ln 1e6)/(N/2) */
    assert_null(rs_simulate_disagreement(&tau, RS_STATUS_MARGINAL, 0, want, 2, 1000));
    assert_true(fabs(tau - (2 * log(7.0 / 3.0) + log(1e6)) / 500.0) < 1e-15);
    assert_non_null(rs_simulate_disagreement(&tau, RS_STATUS_STABLE, 0, log(1.05), 2, 1000));
    assert_non_null(rs_simulate_disagreement(&tau, RS_STATUS_MARGINAL, 0, log(1.05), 2, 1000));
    assert_null(rs_simulate_disagreement(&tau, RS_STATUS_UNSTABLE, 1, log(1.05), 2, 1000));
    assert_non_null(rs_simulate_disagreement(&tau, RS_STATUS_UNSTABLE, 1, log(0.9), 2, 1000));
    /* unstable only through a defective circle root: not checked for decay */
    assert_null(rs_simulate_disagreement(&tau, RS_STATUS_UNSTABLE, 0, log(0.9), 2, 1000));
    /* too few steps to tell */
    assert_null(rs_simulate_disagreement(&tau, RS_STATUS_STABLE, 0, log(2.0), 2, 10));
}

/* exact verdict of p(lambda; q0) by factorisation (rs_rootcount_factor, not
 * the Routh / Schur-Cohn pair the claim uses); c[k][j]: coefficient of
 * q^j lambda^k; singular when the generic leading coefficient vanishes */
static rs_status_t point_status(const slong c[3][2], slong deg, const fmpq_t q0)
{
    fmpq_poly_t p;
    fmpz_poly_t z;
    fmpq_t a, t;
    rs_rootcount_t rc;
    rs_error_t err;
    rs_status_t st;
    slong k;
    fmpq_poly_init(p);
    fmpz_poly_init(z);
    fmpq_init(a);
    fmpq_init(t);
    for (k = 0; k <= deg; k++) {
        fmpq_mul_si(t, q0, c[k][1]);
        fmpq_add_si(a, t, c[k][0]);
        fmpq_poly_set_coeff_fmpq(p, k, a);
    }
    if (fmpq_poly_degree(p) < deg) {
        st = RS_STATUS_SINGULAR;
    } else {
        fmpq_poly_get_numerator(z, p);
        rs_rootcount_init(rc);
        rs_error_init(err);
        assert_int_equal(rs_rootcount_factor(rc, z, err), RS_OK);
        st = rs_rootcount_status(rc);
        rs_rootcount_clear(rc);
    }
    fmpq_poly_clear(p);
    fmpz_poly_clear(z);
    fmpq_clear(a);
    fmpq_clear(t);
    return st;
}

static int kind_violated(int kind, rs_status_t st)
{
    if (st == RS_STATUS_SINGULAR) return 1;
    return kind == 0 ? st != RS_STATUS_STABLE : kind == 1 ? st == RS_STATUS_UNSTABLE : st != RS_STATUS_UNSTABLE;
}

/* Property: random p = sum (c_k0 + c_k1 q) lambda^k (degree <= 2), random
 * intervals and kinds.  A proved claim holds at 40 rational points of the set
 * (ends included when closed); a refuted claim's counterexample lies in the
 * set and violates it -- both by an independent exact count. */
static void test_claim_property(void **state)
{
    static const char *const kinds[] = {"stable", "bounded", "unstable"};
    flint_rand_t st;
    slong iter, nproved = 0, nrefuted = 0;
    (void) state;
    flint_randinit(st);
    for (iter = 0; iter < 300; iter++) {
        slong c[3][2], k, j, deg = 1 + (slong) n_randint(st, 2), lo, hi, i;
        int kind = (int) n_randint(st, 3), loc = (int) n_randint(st, 2), hic = (int) n_randint(st, 2);
        int outcome, code;
        char text[512];
        json_t *doc;
        const char *status;
        fmpq_t q0, L, H;
        for (k = 0; k <= 2; k++)
            for (j = 0; j < 2; j++) c[k][j] = k <= deg ? (slong) n_randint(st, 7) - 3 : 0;
        if (c[deg][0] == 0 && c[deg][1] == 0) continue;
        lo = (slong) n_randint(st, 9) - 6;
        hi = lo + 1 + (slong) n_randint(st, 5);
        snprintf(text, sizeof text, "param q\nchar (%ld + %ld*q)*lambda^2 + (%ld + %ld*q)*lambda + (%ld + %ld*q)\n"
                 "claim %s when %ld %s q %s %ld\n", c[2][0], c[2][1], c[1][0], c[1][1], c[0][0], c[0][1],
                 kinds[kind], lo, loc ? "<=" : "<", hic ? "<=" : "<", hi);
        doc = run_text(text, &outcome, &code);
        if (doc == NULL) continue;   /* e.g. p without lambda */
        status = str(result(doc, 0), "status");
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        fmpq_init(q0); fmpq_init(L); fmpq_init(H);
        fmpq_set_si(L, lo, 1);
        fmpq_set_si(H, hi, 1);
        if (strcmp(status, "proved") == 0) {
            nproved++;
            for (i = 0; i < 40; i++) {
                /* q0 = L + (H - L) i/39, ends only when closed */
                fmpq_set_si(q0, lo * 39 + (hi - lo) * i, 39);
                if ((i == 0 && !loc) || (i == 39 && !hic)) continue;
                if (kind_violated(kind, point_status((const slong (*)[2]) c, deg, q0)))
                    fail_msg("proved but violated at point %ld of 40: %s", i, text);
            }
        } else if (strcmp(status, "refuted") == 0) {
            const char *cq = str(json_object_get(result(doc, 0), "counterexample"), "q");
            nrefuted++;
            assert_int_equal(fmpq_set_str(q0, cq, 10), 0);
            assert_true(fmpq_cmp(q0, L) > 0 || (loc && fmpq_equal(q0, L)));
            assert_true(fmpq_cmp(q0, H) < 0 || (hic && fmpq_equal(q0, H)));
            if (!kind_violated(kind, point_status((const slong (*)[2]) c, deg, q0)))
                fail_msg("refuted at q = %s but holds there: %s", cq, text);
        }
        fmpq_clear(q0); fmpq_clear(L); fmpq_clear(H);
        json_decref(doc);
    }
    /* the sample exercises both outcomes */
    assert_true(nproved > 20 && nrefuted > 20);
    flint_randclear(st);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_claim_open_ends),
        cmocka_unit_test(test_claim_sets),
        cmocka_unit_test(test_claim_singular),
        cmocka_unit_test(test_claim_certificates),
        cmocka_unit_test(test_not_in_p),
        cmocka_unit_test(test_defaults),
        cmocka_unit_test(test_simulate_check),
        cmocka_unit_test(test_claim_property),
    };
    return cmocka_run_group_tests_name("claim", tests, NULL, NULL);
}
