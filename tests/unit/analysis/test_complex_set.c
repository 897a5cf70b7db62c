/* test_complex_set.c -- the analyses at complex set values that were refused
 * before (issue 15 §1): `region NAME` of a real parameter with p over Q(i).
 * Every expected interval is derived by hand in the comment beside it. */
#include "testutil.h"
#include <string.h>
#include <math.h>
#include "recstab/analysis.h"

static void check_region(const json_t *o, const struct tu_iv *want, size_t n, const char *what)
{
    const json_t *ivs = json_object_get(o, "intervals");
    size_t i;
    if (o == NULL) fail_msg("%s: no result", what);
    assert_string_equal(tu_str(o, "analysis"), "region");
    assert_string_equal(tu_str(o, "over"), "Q(i)");
    assert_true(json_integer_value(json_object_get(o, "cross_checked_samples")) > 0);
    if (json_array_size(ivs) != n) fail_msg("%s: %zu intervals, expected %zu", what, json_array_size(ivs), n);
    for (i = 0; i < n; i++) {
        const json_t *iv = json_array_get(ivs, i);
        tu_check_interval(iv, want + i, i, what);
    }
}

static json_t *run(const char *text, int *outcome)
{
    int code;
    json_t *doc = tu_run_text(text, NULL, outcome, &code);
    if (doc == NULL) fail_msg("case failed with code %d:\n%s", code, text);
    assert_int_equal(*outcome & RS_OUTCOME_INCONSISTENT, 0);
    return doc;
}

/* forward Euler lambda = 1 + h q at q = -1 + i: by hand |1 + h q|^2 =
 * (1 - h)^2 + h^2 = 1 - 2 h (1 - h): stable on (0, 1), on the circle at h = 0
 * and h = 1, outside beyond (h < 0 too: 1 - 2h(1 - h) > 1). */
static void test_region_euler(void **state)
{
    static const struct tu_iv want[] = {{"inf", 0, "0", 0, "unstable"}, {"0", 1, "0", 1, "marginal"},
                                     {"0", 0, "1", 0, "stable"}, {"1", 1, "1", 1, "marginal"},
                                     {"1", 0, "inf", 0, "unstable"}};
    int outcome;
    json_t *doc = run("param h q\nchar lambda - 1 - h*q\nset q = -1 + i\nanalyse region h\n", &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 5, "forward Euler at q = -1 + i");
    assert_string_equal(tu_str(json_object_get(tu_result(doc, 0), "substituted"), "q"), "-1+i");
    json_decref(doc);
}

/* leapfrog lambda^2 + 2 q a lambda - 1 at q = i: by the quadratic formula
 * lambda = -i a +- sqrt(1 - a^2); |a| < 1: two distinct roots of modulus 1
 * (a^2 + 1 - a^2); a = +-1: the double root -+i on the circle (unstable);
 * |a| > 1: -i (a +- sqrt(a^2 - 1)), one of modulus > 1. */
static void test_region_leapfrog(void **state)
{
    static const struct tu_iv want[] = {{"inf", 0, "-1", 1, "unstable"}, {"-1", 0, "1", 0, "marginal"},
                                     {"1", 1, "inf", 0, "unstable"}};
    int outcome;
    json_t *doc = run("param a q\nchar lambda^2 + 2*q*a*lambda - 1\nset q = i\nanalyse region a\n", &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 3, "leapfrog at q = i");
    json_decref(doc);
}

/* RK4 (the builder) on y' = q y at q = -1/2 + 3/2 i, step h >= 0:
 * lambda = R(h q), R(z) = 1 + z + z^2/2 + z^3/6 + z^4/24.  Expanding
 * Re R(h q)^2 + Im R(h q)^2 - 1 with exact fractions (Python's Fraction,
 * outside recstab) gives h g(h)/9216 with g = 625 h^7 - 1000 h^6 - 800 h^5
 * + 1440 h^4 + 384 h^3 - 1536 h^2 + 4608 h - 9216, irreducible, whose one
 * positive root is where |R| = 1: a double-precision bisection of
 * |R(h q)| = 1 (Python cmath) gives 1.7791064124296434.  g(0) < 0: stable
 * just right of 0; h = 0: lambda = 1, marginal. */
static void test_region_rk4_irrational(void **state)
{
    static const struct tu_iv want[] = {{"0", 1, "0", 1, "marginal"}, {"0", 0, "algebraic", 0, "stable"},
                                     {"algebraic", 1, "algebraic", 1, "marginal"},
                                     {"algebraic", 0, "inf", 0, "unstable"}};
    int outcome;
    const json_t *iv;
    json_t *doc = run("param h q\nassume h >= 0\nsubsystem S state y\n  y' = q*y\nintegrate S rk rk4 h\n"
                      "set q = -1/2 + 3/2*i\nanalyse region h\n", &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 4, "rk4 at q = -1/2 + 3/2 i");
    iv = json_array_get(json_object_get(tu_result(doc, 0), "intervals"), 2);
    assert_true(fabs(json_real_value(json_object_get(iv, "lo_approx")) - 1.7791064124296434) < 1e-12);
    assert_string_equal(tu_str(json_object_get(iv, "lo"), "minpoly"),
                        "625*h^7 - 1000*h^6 - 800*h^5 + 1440*h^4 + 384*h^3 - 1536*h^2 + 4608*h - 9216");
    json_decref(doc);
}

/* p = (lambda - x)(lambda - i/2) at real x with the set value c = i/2:
 * gcd(Re p, Im p) = lambda - x is real (the real route's gcd step); the root
 * i/2 stays inside, so the status is that of lambda - x: stable on (-1, 1),
 * marginal at +-1, unstable beyond. */
static void test_region_real_factor(void **state)
{
    static const struct tu_iv want[] = {{"inf", 0, "-1", 0, "unstable"}, {"-1", 1, "-1", 1, "marginal"},
                                     {"-1", 0, "1", 0, "stable"}, {"1", 1, "1", 1, "marginal"},
                                     {"1", 0, "inf", 0, "unstable"}};
    int outcome;
    json_t *doc = run("param x c\nchar (lambda - x)*(lambda - c)\nset c = 1/2*i\nanalyse region x\n", &outcome);
    (void) state;
    check_region(tu_result(doc, 0), want, 5, "(lambda - x)(lambda - i/2)");
    json_decref(doc);
}

/* refused with a clear message: the region parameter itself complex, and a
 * parameter left symbolic */
static void test_region_refused(void **state)
{
    int outcome, code;
    json_t *doc = tu_run_text("param h q\nchar lambda - 1 - h*q\nset q = -1 + i\nanalyse region q\n", NULL,
                              &outcome, &code);
    (void) state;
    assert_null(doc);
    assert_int_equal(code, RS_ERR_INPUT);
    doc = tu_run_text("param h q w\nchar lambda - 1 - h*q*w\nset q = -1 + i\nanalyse region h\n", NULL, &outcome,
                      &code);
    assert_null(doc);
    assert_int_equal(code, RS_ERR_INPUT);
    /* for all and the plane: their projections take every parameter real */
    doc = tu_run_text("param h w q\nassume w > 0\nchar lambda - 1 - h*q*w\nset q = -1 + i\nanalyse region h for all\n",
                      NULL, &outcome, &code);
    assert_null(doc);
    assert_int_equal(code, RS_ERR_INPUT);
    doc = tu_run_text("param h w q\nchar lambda - 1 - h*q*w\nset q = -1 + i\nanalyse region h, w\n", NULL, &outcome,
                      &code);
    assert_null(doc);
    assert_int_equal(code, RS_ERR_INPUT);
    /* the plane of q while q has a value: the set value would be ignored */
    doc = tu_run_text("param q\nchar lambda - 1 - q\nset q = -1 + i\nanalyse map re(q) -2 0 3, im(q) -1 1 3\n", NULL,
                      &outcome, &code);
    assert_null(doc);
    assert_int_equal(code, RS_ERR_INPUT);
}

/* map over two real parameters at q = -1 + i: forward Euler lambda = 1 + h w q,
 * by hand |lambda|^2 = 1 - 2 u (1 - u) with u = h w: stable iff 0 < u < 1,
 * marginal at u = 0 and u = 1.  Grid h = 0, 1/2, 1, 3/2, 2 and w = 0, 1/2, 1:
 * w = 0: u = 0 five times (marginal); w = 1/2: u = 0, 1/4, 1/2, 3/4, 1 (M S S S
 * M); w = 1: u = 0, 1/2, 1, 3/2, 2 (M S M U U): stable 4, marginal 9, unstable 2. */
static void test_map(void **state)
{
    int outcome;
    json_t *doc = run("param h w q\nchar lambda - 1 - h*q*w\nset q = -1 + i\nanalyse map h 0 2 5, w 0 1 3\n",
                      &outcome);
    const json_t *o = tu_result(doc, 0), *vd = json_object_get(o, "verdicts");
    (void) state;
    assert_string_equal(tu_str(o, "analysis"), "map");
    assert_string_equal(tu_str(o, "over"), "Q(i)");
    assert_string_equal(tu_str(json_object_get(o, "complex"), "q"), "-1+i");
    assert_int_equal(json_integer_value(json_object_get(vd, "stable")), 4);
    assert_int_equal(json_integer_value(json_object_get(vd, "marginal")), 9);
    assert_int_equal(json_integer_value(json_object_get(vd, "unstable")), 2);
    assert_int_equal(json_integer_value(json_object_get(json_object_get(o, "cross_check"), "stride")), 1);
    json_decref(doc);
}

/* simulate at complex values: lambda = 1 + q, so x[n] = (1 + q)^n x[0]; by
 * hand |1 + q| = 1/2 at q = -1 + i/2, 1 at q = -1 + i, sqrt(5)/2 =
 * 1.1180339887... at q = -1/2 + i.  Leapfrog at a = 1 (q = i): p = (lambda +
 * i)^2 (quadratic formula), x[n] = (A + B n)(-i)^n grows linearly: unstable
 * with no root outside, the run's growth tends to 1 (consistent). */
static void test_simulate(void **state)
{
    static const struct { const char *q; double growth; const char *status; } t[] = {
        {"-1 + 1/2*i", 0.5, "stable"}, {"-1 + i", 1.0, "marginal"}, {"-1/2 + i", 1.1180339887498949, "unstable"}};
    char text[200];
    size_t i;
    int outcome;
    json_t *doc;
    const json_t *o;
    (void) state;
    for (i = 0; i < 3; i++) {
        snprintf(text, sizeof text, "param q\nchar lambda - 1 - q\nset q = %s\nanalyse simulate\n", t[i].q);
        doc = run(text, &outcome);
        o = tu_result(doc, 0);
        assert_string_equal(tu_str(o, "over"), "Q(i)");
        assert_true(fabs(json_real_value(json_object_get(o, "growth_approx")) - t[i].growth) < 1e-9);
        assert_string_equal(tu_str(json_object_get(o, "verdict"), "status"), t[i].status);
        assert_true(json_is_true(json_object_get(json_object_get(o, "check"), "consistent")));
        json_decref(doc);
    }
    doc = run("param a q\nchar lambda^2 + 2*q*a*lambda - 1\nset q = i\nset a = 1\nanalyse simulate\n", &outcome);
    o = tu_result(doc, 0);
    assert_string_equal(tu_str(json_object_get(o, "verdict"), "status"), "unstable");
    assert_int_equal(json_integer_value(json_object_get(json_object_get(o, "verdict"), "outside")), 0);
    assert_true(fabs(json_real_value(json_object_get(o, "growth_approx")) - 1.0) < 1e-2);
    assert_true(json_is_true(json_object_get(json_object_get(o, "check"), "consistent")));
    json_decref(doc);
}

/* limit at complex values.  Trapezoid on y' = q y: lambda = (1 + h q/2)/(1 -
 * h q/2), so by hand lambda -> 1 as h -> 0 and -> -1 as h -> inf (any q != 0).
 * p = lambda^3 - h q lambda^2 - lambda + h q (1 + i) at q = 1 + i: h -> 0 gives
 * lambda^3 - lambda (roots 0, 1, -1); h -> inf the coefficient of h,
 * -q lambda^2 + q (1 + i), so lambda^2 = 1 + i, |lambda| = 2^(1/4) =
 * 1.18920711500272..., and one root escapes (the degree drops 3 -> 2). */
static void test_limit(void **state)
{
    int outcome;
    json_t *doc = run("param h q\nsubsystem S state y\n  y' = q*y\nintegrate S trapezoidal h\nset q = -1 + i\n"
                      "analyse limit h -> inf\nanalyse limit h -> 0\n", &outcome);
    const json_t *o, *rts;
    (void) state;
    o = tu_result(doc, 0);
    assert_string_equal(tu_str(o, "over"), "Q(i)");
    rts = json_object_get(o, "roots");
    assert_int_equal(json_array_size(rts), 1);
    assert_string_equal(tu_str(json_array_get(rts, 0), "value"), "-1");
    rts = json_object_get(tu_result(doc, 1), "roots");
    assert_int_equal(json_array_size(rts), 1);
    assert_string_equal(tu_str(json_array_get(rts, 0), "value"), "1");
    json_decref(doc);
    doc = run("param h q\nchar lambda^3 - h*q*lambda^2 - lambda + h*q*(1 + i)\nset q = 1 + i\n"
              "analyse limit h -> inf\nanalyse limit h -> 0\n", &outcome);
    o = tu_result(doc, 0);
    assert_int_equal(json_integer_value(json_object_get(o, "roots_to_infinity")), 1);
    assert_true(fabs(json_real_value(json_object_get(o, "max_abs")) - 1.189207115002721) < 1e-12);
    o = tu_result(doc, 1);
    assert_string_equal(tu_str(o, "limit_poly"), "lambda^3 - lambda");
    assert_int_equal(json_array_size(json_object_get(o, "roots")), 3);
    assert_string_equal(tu_str(json_array_get(json_object_get(o, "roots"), 0), "value"), "0");
    assert_true(fabs(json_real_value(json_object_get(o, "max_abs")) - 1.0) < 1e-15);
    json_decref(doc);
}

/* expect at complex values: the printed polynomial is an identity in the
 * parameters, q compared as a symbol.  Forward Euler p = lambda - 1 - h q;
 * by hand q(z) = (1 - z) p((1 + z)/(1 - z)) = (1 + z) - (1 - z) - h q (1 - z)
 * = z (2 + h q) - h q; a wrong sign is "different" (exit 1). */
static void test_expect(void **state)
{
    int outcome;
    json_t *doc = run("param h q\nchar lambda - 1 - h*q\nset q = -1 + i\nexpect bilinear z*(2 + h*q) - h*q\n"
                      "expect charpoly lambda - 1 + h*q\n", &outcome);
    (void) state;
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "equal");
    assert_string_equal(json_string_value(json_array_get(json_object_get(tu_result(doc, 0), "kept_symbolic"), 0)), "q");
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "different");
    assert_int_equal(outcome & RS_OUTCOME_FAILED, RS_OUTCOME_FAILED);
    json_decref(doc);
}

/* expect with the imaginary unit: compared exactly over Q(i), the complex
 * set values substituted.  Forward Euler p = lambda - 1 - h q at q = -1 + i,
 * h = 1: by hand p = lambda - 1 - (-1 + i) = lambda - i, "equal"; i times
 * it, i lambda + 1, "proportional" with ratio i; lambda + i "different".
 * BDF2 at q = -1/2 + 3/2 i (bdf2-complex-point.case): 3 y[n+2] - 4 y[n+1] +
 * y[n] = 2 q y[n+2] gives p = (3 - 2q) lambda^2 - 4 lambda + 1 = (4 - 3i)
 * lambda^2 - 4 lambda + 1 by hand: "equal", as the real path calls p with a
 * positive leading term (at real q = -1/2: 4 lambda^2 - 4 lambda + 1 "equal");
 * charpoly over Q(i) prints p with that sign too (issue 15: normalised at
 * the source), so the negation is "proportional" with ratio -1; twice it
 * "proportional" with ratio 2 (not -2).  A char line with i: lambda - 1 -
 * i*h compared as printed, "equal". */
static void test_expect_i(void **state)
{
    int outcome, code;
    json_t *doc = run("param h q\nchar lambda - 1 - h*q\nset q = -1 + i\nset h = 1\nexpect charpoly lambda - i\n"
                      "expect charpoly i*lambda + 1\nexpect charpoly lambda + i\n", &outcome);
    (void) state;
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "equal");
    assert_string_equal(tu_str(tu_result(doc, 0), "over"), "Q(i)");
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "proportional");
    assert_string_equal(tu_str(tu_result(doc, 1), "ratio"), "i");
    assert_string_equal(tu_str(tu_result(doc, 2), "status"), "different");
    assert_int_equal(outcome & RS_OUTCOME_FAILED, RS_OUTCOME_FAILED);
    json_decref(doc);
    doc = run("param q\nsubsystem S state y\n  y' = q*y\nintegrate S bdf 2 1\nset q = -1/2 + 3/2*i\n"
              "expect charpoly (4 - 3*i)*lambda^2 - 4*lambda + 1\nexpect charpoly (-4 + 3*i)*lambda^2 + 4*lambda - 1\n"
              "expect charpoly (8 - 6*i)*lambda^2 - 8*lambda + 2\n", &outcome);
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "equal");
    assert_string_equal(tu_str(tu_result(doc, 1), "status"), "proportional");
    assert_string_equal(tu_str(tu_result(doc, 1), "ratio"), "-1");
    assert_string_equal(tu_str(tu_result(doc, 2), "status"), "proportional");
    assert_string_equal(tu_str(tu_result(doc, 2), "ratio"), "2");
    assert_int_equal(outcome & RS_OUTCOME_FAILED, 0);
    json_decref(doc);
    doc = run("param q\nsubsystem S state y\n  y' = q*y\nintegrate S bdf 2 1\nset q = -1/2\n"
              "expect charpoly 4*lambda^2 - 4*lambda + 1\n", &outcome);
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "equal");
    json_decref(doc);
    doc = run("param h\nchar lambda - 1 - i*h\nexpect charpoly lambda - 1 - i*h\n", &outcome);
    assert_string_equal(tu_str(tu_result(doc, 0), "status"), "equal");
    json_decref(doc);
    /* bilinear with i is refused (exit 2) */
    doc = tu_run_text("param h\nchar lambda - 1 - h\nexpect bilinear z - i*h\n", NULL, &outcome, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    assert_null(doc);
}

/* sweep of modes at complex values: the trapezoid on y' = q w y at q = i,
 * w = 2: lambda = (1 + i h)/(1 - i h), by hand |lambda| = 1 and arg lambda =
 * 2 atan(h), so omega = 2 atan(h)/h (h = 1: pi/2), damping 0, frequency
 * error (omega - 2)/2. */
static void test_sweep_modes(void **state)
{
    int outcome;
    json_t *doc = run("param h w q\nsubsystem S state y\n  y' = q*w*y\nintegrate S trapezoidal h\nset q = i\n"
                      "set w = 2\nanalyse sweep h from 1/10 to 1 steps 3 of modes h=h reference=2\n", &outcome);
    const json_t *o = tu_result(doc, 0), *cols = json_object_get(o, "columns"), *rows = json_object_get(o, "rows");
    size_t k, iom = 0, ifr = 0, ih = 0;
    (void) state;
    assert_string_equal(tu_str(o, "over"), "Q(i)");
    for (k = 0; k < json_array_size(cols); k++) {
        const char *c = json_string_value(json_array_get(cols, k));
        if (strcmp(c, "omega_1") == 0) iom = k;
        if (strcmp(c, "frequency_error_1") == 0) ifr = k;
        if (strcmp(c, "h") == 0) ih = k;
    }
    assert_true(iom > 0 && ifr > 0 && ih > 0);
    assert_int_equal(json_array_size(rows), 4);
    for (k = 0; k < 4; k++) {
        const json_t *row = json_array_get(rows, k);
        double h = json_number_value(json_array_get(row, ih)), om = 2 * atan(h) / h;
        assert_true(fabs(json_number_value(json_array_get(row, iom)) - om) < 1e-12);
        assert_true(fabs(json_number_value(json_array_get(row, ifr)) - (om - 2) / 2) < 1e-12);
    }
    json_decref(doc);
}

/* claims bounded / unstable at complex values through the exact region.
 * Leapfrog lambda^2 + 2 q a lambda - 1 at q = i: by the quadratic formula
 * lambda = -i a +- sqrt(1 - a^2): |a| < 1 two distinct roots on the circle
 * (bounded), |a| = 1 the double root -+i (unstable), |a| > 1 a root of
 * modulus |a| + sqrt(a^2 - 1) > 1 (unstable).  So bounded on -1 < a < 1 and
 * unstable on a >= 1 are proved; unstable on a >= 1/2 and bounded on
 * a <= 1 are false (a = 1/2 marginal; a = 1 unstable). */
static void test_claims(void **state)
{
    static const struct { const char *claim, *status; } t[] = {
        {"claim bounded when -1 < a < 1", "proved"}, {"claim unstable when a >= 1", "proved"},
        {"claim unstable when a >= 1/2", "refuted"}, {"claim bounded when 0 <= a <= 1", "refuted"}};
    char text[300];
    size_t i;
    int outcome;
    (void) state;
    for (i = 0; i < 4; i++) {
        json_t *doc;
        const json_t *o;
        snprintf(text, sizeof text, "param a q\nchar lambda^2 + 2*q*a*lambda - 1\nset q = i\n%s\n", t[i].claim);
        doc = run(text, &outcome);
        o = tu_result(doc, 0);
        if (strcmp(tu_str(o, "status"), t[i].status) != 0)
            fail_msg("%s: %s, expected %s (%s)", t[i].claim, tu_str(o, "status"), t[i].status, tu_str(o, "failed_at"));
        if (strcmp(t[i].status, "proved") == 0)
            assert_non_null(json_object_get(json_array_get(json_object_get(o, "certificate"), 0), "region"));
        json_decref(doc);
    }
}

/* claims in two real parameters at q = -1 + i: forward Euler lambda = 1 + h w q,
 * by hand lambda = (1 - u) + i u with u = h w, |lambda|^2 - 1 = 2u(u - 1):
 * stable for 0 < u < 1 (so bounded on 0 < h, w < 1: the Bilharz conditions),
 * unstable for u > 1 (on h > 2, w > 1: |a0|^2 - |an|^2 = 2u(u - 1) > 0),
 * unstable at h = 7/4, w = 5/8 inside 0 < h < 2, 0 < w < 1 (u = 35/32).  On
 * the closed box 0 < h, w <= 1 bounded holds (u = 1 marginal), but neither
 * certificate applies: undecided, with the reason. */
static void test_claims_two_params(void **state)
{
    static const struct { const char *claim, *status; } t[] = {
        {"claim bounded when 0 < h < 1, 0 < w < 1", "proved"}, {"claim unstable when h > 2, w > 1", "proved"},
        {"claim bounded when 0 < h < 2, 0 < w < 1", "refuted"}, {"claim unstable when h > 1/2, w > 1", "refuted"},
        {"claim bounded when 0 < h <= 1, 0 < w <= 1", "undecided"}};
    char text[300];
    size_t i;
    int outcome;
    (void) state;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        json_t *doc;
        const json_t *o;
        snprintf(text, sizeof text, "param h w q\nchar lambda - 1 - h*w*q\nset q = -1 + i\n%s\n", t[i].claim);
        doc = run(text, &outcome);
        o = tu_result(doc, 0);
        if (strcmp(tu_str(o, "status"), t[i].status) != 0)
            fail_msg("%s: %s, expected %s (%s)", t[i].claim, tu_str(o, "status"), t[i].status, tu_str(o, "failed_at"));
        if (strcmp(t[i].status, "undecided") == 0) assert_non_null(json_object_get(o, "failed_at"));
        json_decref(doc);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_region_euler),
        cmocka_unit_test(test_region_leapfrog),
        cmocka_unit_test(test_region_rk4_irrational),
        cmocka_unit_test(test_region_real_factor),
        cmocka_unit_test(test_region_refused),
        cmocka_unit_test(test_map),
        cmocka_unit_test(test_simulate),
        cmocka_unit_test(test_limit),
        cmocka_unit_test(test_expect),
        cmocka_unit_test(test_expect_i),
        cmocka_unit_test(test_sweep_modes),
        cmocka_unit_test(test_claims),
        cmocka_unit_test(test_claims_two_params),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
