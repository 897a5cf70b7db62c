/* test_exact.c -- the exact analyses on the bundled cases, each expected
 * value from an independent derivation:
 *   - textbook regions from the closed forms of the moduli (forward Euler
 *     |lambda|^2 = 1 + w^2, backward Euler 1/(1 + w^2), trapezoid 1,
 *     central difference: roots e^{+-i theta}, 2 cos theta = 2 - w^2),
 *   - BDF2 spurious roots: rho(lambda) = (3 lambda - 1)(lambda - 1) at w = 0,
 *   - the Park counterexample: roots of the hand-derived polynomial isolated
 *     with Arb (arb_fmpz_poly_complex_roots), not with recstab's counters. */
#include "testutil.h"
#include <string.h>
#include <math.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpq_vec.h>
#include <arb_fmpz_poly.h>
#include <acb.h>
#include "recstab/casefile.h"
#include "recstab/scheme.h"
#include "recstab/report.h"
#include "recstab/analysis.h"
#include "recstab/jury.h"

static const json_t *result(const json_t *doc, size_t i)
{
    return json_array_get(json_object_get(doc, "results"), i);
}

static const char *str(const json_t *o, const char *k)
{
    return json_string_value(json_object_get(o, k));
}

/* one interval (lo, inf) with the given status */
static void expect_single_interval(const char *rel, const char *status)
{
    const char *req[] = {"region w"};
    int outcome;
    json_t *doc = tu_run_case(rel, req, 1, &outcome);
    const json_t *ivs = json_object_get(result(doc, 0), "intervals");
    assert_int_equal(json_array_size(ivs), 1);
    assert_string_equal(str(json_array_get(ivs, 0), "lo"), "0");
    assert_true(json_is_null(json_object_get(json_array_get(ivs, 0), "hi")));
    assert_false(json_is_true(json_object_get(json_array_get(ivs, 0), "lo_closed")));
    assert_string_equal(str(json_array_get(ivs, 0), "status"), status);
    json_decref(doc);
}

static void test_regions_textbook(void **state)
{
    (void) state;
    expect_single_interval("cases/textbook/forward-euler.case", "unstable");   /* 1 + w^2 > 1 */
    expect_single_interval("cases/textbook/backward-euler.case", "stable");    /* 1/(1 + w^2) < 1 */
    expect_single_interval("cases/textbook/trapezoidal.case", "marginal");     /* |lambda| = 1, simple */
    expect_single_interval("cases/textbook/bdf2.case", "stable");
}

/* central difference: 2 cos theta = 2 - w^2 has a solution iff 0 < w <= 2;
 * w = 2 gives theta = pi twice (double root -1), w > 2 a real root < -1. */
static void test_region_central_difference(void **state)
{
    const char *req[] = {"region w"};
    int outcome;
    json_t *doc;
    const json_t *ivs, *a, *b;
    (void) state;
    doc = tu_run_case("cases/textbook/central-difference.case", req, 1, &outcome);
    ivs = json_object_get(result(doc, 0), "intervals");
    assert_int_equal(json_array_size(ivs), 2);
    a = json_array_get(ivs, 0);
    b = json_array_get(ivs, 1);
    assert_string_equal(str(a, "lo"), "0");
    assert_string_equal(str(a, "hi"), "2");
    assert_false(json_is_true(json_object_get(a, "hi_closed")));
    assert_string_equal(str(a, "status"), "marginal");
    assert_string_equal(str(b, "lo"), "2");
    assert_true(json_is_true(json_object_get(b, "lo_closed")));
    assert_string_equal(str(b, "status"), "unstable");
    json_decref(doc);
}

/* BDF2 at w = 0: (3l^2 - 4l + 1)^2 = (3l - 1)^2 (l - 1)^2 -> 1 (x2), 1/3 (x2);
 * w -> inf: 4 w^2 l^4 dominates -> 0 (x4). */
static void test_limits_bdf2(void **state)
{
    const char *req[] = {"limit w -> 0", "limit w -> inf"};
    int outcome;
    json_t *doc;
    const json_t *r0, *r1;
    size_t i;
    int seen_third = 0, seen_one = 0;
    (void) state;
    doc = tu_run_case("cases/textbook/bdf2.case", req, 2, &outcome);
    r0 = json_object_get(result(doc, 0), "roots");
    for (i = 0; i < json_array_size(r0); i++) {
        const json_t *r = json_array_get(r0, i);
        if (strcmp(str(r, "value"), "1/3") == 0 && json_integer_value(json_object_get(r, "multiplicity")) == 2)
            seen_third = 1;
        if (strcmp(str(r, "value"), "1") == 0 && json_integer_value(json_object_get(r, "multiplicity")) == 2)
            seen_one = 1;
    }
    assert_true(seen_third && seen_one);
    r1 = result(doc, 1);
    assert_true(json_is_true(json_object_get(r1, "all_roots_to_zero")));
    json_decref(doc);
}

/* det = lambda^2 (2 lambda - 1)(lambda - 3) (charpoly.c divides lambda^2 out
 * of p): by hand 3 roots inside (two at 0, one 1/2), one outside (3); jury,
 * stability and routh counted p only (1 inside).  Over Q(i) at z = i,
 * lambda^2 (2 lambda - z)(lambda - 3): the roots 0, 0, i/2, 3 -- the same counts. */
static void test_counts_roots_at_zero(void **state)
{
    const char *texts[] = {
        "char lambda^2*(2*lambda - 1)*(lambda - 3)\nanalyse jury\nanalyse stability\nanalyse routh\n",
        "param z complex\nchar lambda^2*(2*lambda - z)*(lambda - 3)\nset z = i\n"
        "analyse jury\nanalyse stability\nanalyse routh\n"};
    size_t t, k;
    (void) state;
    for (t = 0; t < 2; t++) {
        int outcome;
        json_t *doc = tu_run_text(texts[t], NULL, &outcome, NULL);
        for (k = 0; k < 3; k++) {
            const json_t *r = result(doc, k);
            assert_string_equal(str(r, "status"), "unstable");
            assert_int_equal(json_integer_value(json_object_get(r, "inside")), 3);
            assert_int_equal(json_integer_value(json_object_get(r, "on")), 0);
            assert_int_equal(json_integer_value(json_object_get(r, "outside")), 1);
            assert_int_equal(json_integer_value(json_object_get(r, "degree")), 4);
        }
        /* the real counts name the multiplicity of lambda = 0 */
        if (t == 0) assert_int_equal(json_integer_value(json_object_get(result(doc, 1), "at_zero")), 2);
        json_decref(doc);
    }
}

static void test_claims_textbook(void **state)
{
    struct { const char *file, *claim, *status; } t[] = {
        {"cases/textbook/forward-euler.case", "claim unstable when w > 0", "proved"},
        {"cases/textbook/forward-euler.case", "claim bounded when w > 0", "refuted"},
        {"cases/textbook/backward-euler.case", "claim stable when w > 0", "proved"},
        {"cases/textbook/trapezoidal.case", "claim bounded when w > 0", "proved"},
        {"cases/textbook/trapezoidal.case", "claim stable when w > 0", "refuted"},
        {"cases/textbook/central-difference.case", "claim bounded when w < 2", "proved"},
        {"cases/textbook/central-difference.case", "claim bounded when w <= 2", "refuted"},
        {"cases/textbook/bdf2.case", "claim stable when w > 0", "proved"},
    };
    size_t i;
    (void) state;
    for (i = 0; i < sizeof t / sizeof t[0]; i++) {
        int outcome;
        json_t *doc = tu_run_case(t[i].file, &t[i].claim, 1, &outcome);
        const char *got = str(result(doc, 0), "status");
        if (strcmp(got, t[i].status) != 0)
            fail_msg("%s / %s: %s, expected %s", t[i].file, t[i].claim, got, t[i].status);
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        assert_int_equal(outcome & RS_OUTCOME_FAILED, strcmp(t[i].status, "refuted") == 0);
        json_decref(doc);
    }
}

/* Roots of the hand-derived Park polynomial (test_golden.c, case comment)
 *   p = A (4(l-1)^2 + wh^2 (l+1)^2) - 2 m muh wh^2 ((1+al) l - al)(l+1)^2,
 *   A = (3 + 2(1+m) muh) l^2 - 4 l + 1,
 * isolated by Arb (arb_fmpz_poly_complex_roots), independently of recstab's
 * counters: how many are certified strictly outside and strictly inside. */
static void park_roots(slong *outside, slong *inside, const fmpq_t m, const fmpq_t muh, const fmpq_t wh,
                       const fmpq_t al)
{
    fmpq_poly_t A, B, C, t, p;
    fmpq_t c;
    fmpz_poly_t pz;
    acb_ptr roots;
    slong i, d;
    arb_t ab, one;
    fmpq_poly_init(A); fmpq_poly_init(B); fmpq_poly_init(C); fmpq_poly_init(t); fmpq_poly_init(p);
    fmpq_init(c);
    fmpq_add_si(c, m, 1); fmpq_mul(c, c, muh); fmpq_mul_si(c, c, 2); fmpq_add_si(c, c, 3);
    fmpq_poly_set_coeff_fmpq(A, 2, c); fmpq_poly_set_coeff_si(A, 1, -4); fmpq_poly_set_coeff_si(A, 0, 1);
    fmpq_poly_set_str(t, "3  1 -2 1");                     /* (l-1)^2 */
    fmpq_poly_scalar_mul_si(B, t, 4);
    fmpq_poly_set_str(t, "3  1 2 1");                      /* (l+1)^2 */
    fmpq_mul(c, wh, wh);
    fmpq_poly_scalar_mul_fmpq(C, t, c);
    fmpq_poly_add(B, B, C);
    fmpq_poly_mul(p, A, B);
    fmpq_add_si(c, al, 1);
    fmpq_poly_zero(C);
    fmpq_poly_set_coeff_fmpq(C, 1, c);
    fmpq_neg(c, al);
    fmpq_poly_set_coeff_fmpq(C, 0, c);
    fmpq_poly_mul(C, C, t);
    fmpq_mul(c, m, muh); fmpq_mul(c, c, wh); fmpq_mul(c, c, wh); fmpq_mul_si(c, c, 2);
    fmpq_poly_scalar_mul_fmpq(C, C, c);
    fmpq_poly_sub(p, p, C);
    fmpz_poly_init(pz);
    fmpq_poly_get_numerator(pz, p);
    d = fmpz_poly_degree(pz);
    roots = _acb_vec_init(d);
    arb_fmpz_poly_complex_roots(roots, pz, 0, 128);
    arb_init(ab);
    arb_init(one);
    arb_one(one);
    *outside = *inside = 0;
    for (i = 0; i < d; i++) {
        acb_abs(ab, roots + i, 128);
        if (arb_gt(ab, one)) (*outside)++;
        if (arb_lt(ab, one)) (*inside)++;
    }
    arb_clear(ab);
    arb_clear(one);
    _acb_vec_clear(roots, d);
    fmpz_poly_clear(pz);
    fmpq_poly_clear(A); fmpq_poly_clear(B); fmpq_poly_clear(C); fmpq_poly_clear(t); fmpq_poly_clear(p);
    fmpq_clear(c);
}

/* The Park lecture's "alpha <= 2": recstab's counterexample, checked by
 * certified root isolation of the hand-derived polynomial. */
static void test_park_counterexample(void **state)
{
    const char *req[] = {"claim stable when alpha <= 2"};
    int outcome;
    json_t *doc;
    const json_t *ce;
    fmpq_t m, muh, wh, al;
    slong out, in;
    (void) state;
    doc = tu_run_case("cases/park-staggered.case", req, 1, &outcome);
    assert_string_equal(str(result(doc, 0), "status"), "refuted");
    assert_true(outcome & RS_OUTCOME_FAILED);
    ce = json_object_get(result(doc, 0), "counterexample");
    fmpq_init(m); fmpq_init(muh); fmpq_init(wh); fmpq_init(al);
    fmpq_set_str(m, str(ce, "m"), 10);
    fmpq_set_str(muh, str(ce, "muh"), 10);
    fmpq_set_str(wh, str(ce, "wh"), 10);
    fmpq_set_str(al, str(ce, "alpha"), 10);
    assert_true(fmpq_cmp_si(al, 2) <= 0 && fmpq_sgn(al) >= 0 && fmpq_sgn(m) > 0);
    park_roots(&out, &in, m, muh, wh, al);
    assert_true(out >= 1);     /* certified: a root strictly outside the circle */
    fmpq_clear(m); fmpq_clear(muh); fmpq_clear(wh); fmpq_clear(al);
    json_decref(doc);
}

/* alpha <= 1 is proved; the region at m = 10 ends at a root of the reported
 * minimal polynomial 13 alpha^2 + 6 alpha - 24 (about 1.1474): the
 * hand-derived polynomial has every root inside just below it and a root
 * outside just above it (Arb root isolation, independent of recstab). */
static void test_park_proof_and_region(void **state)
{
    const char *req[] = {"claim stable when alpha <= 1", "region alpha at m=10, muh=1, wh=1"};
    int outcome;
    json_t *doc;
    const json_t *ivs, *hi;
    double x;
    fmpq_t m, one, al, eps;
    slong out, in;
    (void) state;
    doc = tu_run_case("cases/park-staggered.case", req, 2, &outcome);
    assert_string_equal(str(result(doc, 0), "status"), "proved");
    assert_true(json_is_true(json_object_get(result(doc, 0), "certificate_rechecked")));
    ivs = json_object_get(result(doc, 1), "intervals");
    assert_string_equal(str(json_array_get(ivs, 0), "status"), "stable");
    hi = json_object_get(json_array_get(ivs, 0), "hi");
    assert_string_equal(str(hi, "minpoly"), "13*alpha^2 + 6*alpha - 24");
    x = json_real_value(json_object_get(json_array_get(ivs, 0), "hi_approx"));
    assert_true(fabs(13 * x * x + 6 * x - 24) < 1e-9);
    fmpq_init(m); fmpq_init(one); fmpq_init(al); fmpq_init(eps);
    fmpq_set_si(m, 10, 1);
    fmpq_one(one);
    fmpq_set_si(eps, 1, 1000000);
    /* just outside the reported isolating interval on either side */
    fmpq_set_str(al, json_string_value(json_array_get(json_object_get(hi, "interval"), 0)), 10);
    fmpq_sub(al, al, eps);
    park_roots(&out, &in, m, one, one, al);
    assert_int_equal(in, 4);
    fmpq_set_str(al, json_string_value(json_array_get(json_object_get(hi, "interval"), 1)), 10);
    fmpq_add(al, al, eps);
    park_roots(&out, &in, m, one, one, al);
    assert_true(out >= 1);
    fmpq_clear(m); fmpq_clear(one); fmpq_clear(al); fmpq_clear(eps);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    json_decref(doc);
}

/* Printed eq. (23)/(24) differ from the scheme's bilinear polynomial. */
static void test_park_printed_bilinear(void **state)
{
    int outcome;
    json_t *doc;
    const char *req[] = {
        "expect bilinear 16*(2 + (1 + m)*muh)*z^4 + 16*(1 + 2*(1 + m)*muh)*z^3 + (wh^2*(8 + (4 + (6 + 2*alpha)*m)*muh) + 16*muh*(1 + m))*z^2 + 2*wh^2*(4 + (8 + 8*m - 4*alpha*m)*muh)*z + (4 + 2*m)*wh^2*muh",
        /* independent: q = (1-z)^4 p((1+z)/(1-z)) expanded by hand / SymPy, divided by 8 */
        "expect bilinear muh*wh^2 + z^4*(4*m*muh + 4*muh + 16) + z^3*(8*m*muh + 8*muh + 8) + z^2*(2*alpha*m*muh*wh^2 + 2*m*muh*wh^2 + 4*m*muh + muh*wh^2 + 4*muh + 4*wh^2) + z*(-2*alpha*m*muh*wh^2 + 2*m*muh*wh^2 + 2*muh*wh^2 + 2*wh^2)"};
    (void) state;
    doc = tu_run_case("cases/park-staggered.case", req, 2, &outcome);
    assert_string_equal(str(result(doc, 0), "status"), "different");
    assert_string_equal(str(result(doc, 1), "status"), "equal");  /* q/8 is q normalised */
    json_decref(doc);
}

/* Symbolic Schur-Cohn conditions on Park: at random rational points, "every
 * condition holds" must equal the exact verdict "stable" computed there by the
 * `stability` analysis (Routh and numeric Schur-Cohn), an independent path. */
static void test_park_symbolic_jury(void **state)
{
    const char *req[] = {"jury"};
    int outcome, k, agree = 0;
    json_t *doc;
    const json_t *conds;
    const char *vars[] = {"m", "muh", "wh", "alpha", "lambda"};
    fmpz_mpoly_ctx_t ctx;
    flint_rand_t st;
    (void) state;
    doc = tu_run_case("cases/park-staggered.case", req, 1, &outcome);
    conds = json_object_get(result(doc, 0), "conditions");
    assert_true(json_array_size(conds) >= 1);
    fmpz_mpoly_ctx_init(ctx, 5, ORD_LEX);
    flint_randinit(st);
    for (k = 0; k < 40; k++) {
        char sets[4][64];
        fmpq pt[5];
        fmpq *pp[5];
        size_t i;
        int all = 1, v;
        const char *names[4] = {"m", "muh", "wh", "alpha"};
        const char *sreq[1];
        json_t *d2;
        for (v = 0; v < 5; v++) { fmpq_init(pt + v); pp[v] = pt + v; }
        for (v = 0; v < 4; v++) {
            slong num = 1 + (slong) n_randint(st, 40), den = 1 + (slong) n_randint(st, 8);
            if (v == 3) { num = (slong) n_randint(st, 25); den = 8; }
            fmpq_set_si(pt + v, num, (ulong) den);
            snprintf(sets[v], sizeof sets[v], "%s=%ld/%ld", names[v], (long) num, (long) den);
        }
        for (i = 0; i < json_array_size(conds); i++) {
            const char *c = json_string_value(json_array_get(conds, i));
            fmpz_mpoly_t pc;
            fmpq_t val;
            size_t len = strlen(c);
            int strict = strstr(c, " > 0") != NULL;
            char *cb = malloc(len + 1);
            {
                size_t q, w = 0, stop = len - (strict ? 4 : 5);
                for (q = 0; q < stop; q++)
                    if (c[q] != ' ') cb[w++] = c[q];
                cb[w] = '\0';
            }
            fmpz_mpoly_init(pc, ctx);
            fmpq_init(val);
            assert_int_equal(fmpz_mpoly_set_str_pretty(pc, cb, vars, ctx), 0);
            free(cb);
            tu_eval_fmpz_mpoly(val, pc, pp, ctx);
            if (strict ? fmpq_sgn(val) <= 0 : fmpq_is_zero(val)) all = 0;
            fmpz_mpoly_clear(pc, ctx);
            fmpq_clear(val);
        }
        /* the exact verdict at the point */
        {
            char path[1024];
            rs_case_t c;
            rs_error_t err;
            rs_options_t opt;
            int oc, v2;
            snprintf(path, sizeof path, "%s/cases/park-staggered.case", RS_SOURCE_DIR);
            rs_case_init(c);
            rs_error_init(err);
            rs_options_default(&opt);
            assert_int_equal(rs_case_parse_file(c, path, err), RS_OK);
            for (v2 = 0; v2 < 4; v2++) assert_int_equal(rs_case_set_value(c, sets[v2], err), RS_OK);
            rs_case_clear_requests(c);
            sreq[0] = "stability";
            rs_case_add_request(c, sreq[0], "test", 1, 1);
            assert_int_equal(rs_analysis_run(&d2, &oc, c, &opt, err), RS_OK);
            if ((strcmp(str(result(d2, 0), "status"), "stable") == 0) == all) agree++;
            else fail_msg("point %s %s %s %s: conditions %d, exact %s", sets[0], sets[1], sets[2], sets[3], all,
                          str(result(d2, 0), "status"));
            json_decref(d2);
            rs_case_clear(c);
        }
        for (v = 0; v < 5; v++) fmpq_clear(pt + v);
    }
    assert_int_equal(agree, 40);
    flint_randclear(st);
    fmpz_mpoly_ctx_clear(ctx);
    json_decref(doc);
}

/* Symbolic Jury conditions with an interval assumption (issue 17: the
 * interval mapping of rs_positivity_sign_bounds in `jury`).  Forward Euler on
 * y' = -y with step h: p = lambda - (1 - h), by hand delta_1 = 1 - (1 - h)^2
 * = -h (h - 2), so |root| = |1 - h| < 1 iff 0 < h < 2.  On 0 < h < 1 both
 * factors have one sign (h > 0, h - 2 < 0): no condition is left, stable.
 * On 2 < h < 3 both have one sign again (h > 0, h - 2 > 0): delta < 0
 * throughout, the condition "-1 > 0" (never stable; |1 - h| > 1 there).
 * On 1 < h < 3, h - 2 changes sign at 2: it must stay a condition (the
 * mapping may not drop an indefinite factor); with h > 0 only it stays too
 * (the sign test alone cannot bound h - 2). */
static void test_jury_interval_assumptions(void **state)
{
    static const struct { const char *assume; int nconds; const char *cond; int ndropped; } cases[] = {
        {"0 < h < 1", 0, NULL, 2},
        {"2 < h < 3", 1, "-1 > 0", 2},
        {"1 < h < 3", 1, "-h + 2 > 0", 1},
        {"h > 0", 1, "-h + 2 > 0", 1},
    };
    size_t k;
    (void) state;
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char text[256];
        int outcome = 0;
        json_t *doc;
        const json_t *o, *conds, *chk;
        snprintf(text, sizeof text, "param h\nassume %s\nunknown y\neq y[n+1] - y[n] = -h*y[n]\nanalyse jury\n",
                 cases[k].assume);
        doc = tu_run_text(text, NULL, &outcome, NULL);
        o = result(doc, 0);
        conds = json_object_get(o, "conditions");
        assert_int_equal(json_array_size(conds), cases[k].nconds);
        if (cases[k].cond != NULL) assert_string_equal(json_string_value(json_array_get(conds, 0)), cases[k].cond);
        assert_int_equal(json_array_size(json_object_get(o, "dropped")), cases[k].ndropped);
        /* and the conditions agree with the exact verdict at sample points */
        chk = json_object_get(o, "sample_check");
        assert_true(json_is_true(json_object_get(chk, "agree")));
        assert_true(json_integer_value(json_object_get(chk, "points")) > 0);
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        json_decref(doc);
    }
}

/* `jury` factors a large lead^2 - const^2 through its halves lead - const and
 * lead + const (issue 17).  Expected values: the same table with every delta
 * factored whole by FLINT, as recstab does below 20 000 terms; by unique
 * factorisation in Z[params] the factors of (a - b)(a + b) are those of
 * a - b and a + b together, so the conditions (kept products, "!= 0" lines)
 * and the dropped factors must be the same sets, and both runs must agree
 * with the exact point verdict at the sample points. */
static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(const char *const *) a, *(const char *const *) b);
}

static void jury_same_sets(const json_t *r1, const json_t *r2, const char *key, const char *field)
{
    const json_t *x = json_object_get(r1, key), *y = json_object_get(r2, key);
    size_t n = json_array_size(x), i;
    const char **u, **w;
    assert_int_equal(n, json_array_size(y));
    u = malloc((n + 1) * sizeof(char *));
    w = malloc((n + 1) * sizeof(char *));
    for (i = 0; i < n; i++) {
        const json_t *a = json_array_get(x, i), *b = json_array_get(y, i);
        if (field != NULL) { a = json_object_get(a, field); b = json_object_get(b, field); }
        u[i] = json_string_value(a);
        w[i] = json_string_value(b);
        assert_non_null(u[i]);
        assert_non_null(w[i]);
    }
    qsort(u, n, sizeof(char *), cmp_str);
    qsort(w, n, sizeof(char *), cmp_str);
    for (i = 0; i < n; i++) assert_string_equal(u[i], w[i]);
    free(u);
    free(w);
}

static void test_jury_factor_halves(void **state)
{
    static const char chain2[] =
        "param c k1 k2\nassume c > 0, k1 > 0, k2 > 0\nunknown x1 v1 a1 x2 v2 a2\n"
        "eq a1[n+1] + c*v1[n+1] + k1*x1[n+1] + k2*x1[n+1] - k2*x2[n+1] = 0\n"
        "eq x1[n+1] - x1[n] = (v1[n+1] + v1[n])/2\neq v1[n+1] - v1[n] = (a1[n+1] + a1[n])/2\n"
        "eq a2[n+1] + c*v2[n+1] + k2*x2[n+1] - k2*x1[n+1] = 0\n"
        "eq x2[n+1] - x2[n] = (v2[n+1] + v2[n])/2\neq v2[n+1] - v2[n] = (a2[n+1] + a2[n])/2\n"
        "analyse jury\n";
    const char *req[] = {"jury"};
    int k;
    (void) state;
    for (k = 0; k < 2; k++) {
        json_t *doc[2];
        const json_t *r[2];
        int outcome, code, h;
        for (h = 0; h < 2; h++) {
            slong old = rs_jury_set_factor_whole_terms(h ? 0 : 20000);
            doc[h] = k == 0 ? tu_run_case("cases/park-staggered.case", req, 1, &outcome)
                            : tu_run_text(chain2, NULL, &outcome, &code);
            rs_jury_set_factor_whole_terms(old);
            assert_non_null(doc[h]);
            r[h] = result(doc[h], 0);
            assert_true(json_is_true(json_object_get(r[h], "symbolic")));
            assert_true(json_is_true(json_object_get(json_object_get(r[h], "sample_check"), "agree")));
        }
        assert_true(json_equal(json_object_get(r[0], "rows"), json_object_get(r[1], "rows")));
        assert_true(json_array_size(json_object_get(r[0], "conditions"))
                    + json_array_size(json_object_get(r[0], "dropped")) >= 2);
        jury_same_sets(r[0], r[1], "conditions", NULL);
        jury_same_sets(r[0], r[1], "dropped", "factor");
        json_decref(doc[0]);
        json_decref(doc[1]);
    }
}

/* `jury` through the bilinear route (issue 17): forced on from the first row
 * (rs_jury_set_bilinear_terms(0)) against the Schur-Cohn table (the
 * threshold out of reach) on the 2- and 3-mass trapezoidal chains of
 * bench/make_chain_case.sh and on Park's staggered case.  The two routes
 * state different polynomials for the same region, so they are compared as
 * regions: at random rational points inside the assumptions each route's
 * conjunction is evaluated and set against the exact point verdict, the
 * integer Schur-Cohn count of p at the point (rs_jury_count_fmpz_poly on the
 * charpoly's own polynomial, no symbolic condition involved).  Expected: on
 * the chains every point is stable (the trapezoidal rule maps Re s < 0 into
 * |lambda| < 1 and the damped chain, c > 0, k_i > 0, has every mode in
 * Re s < 0), Park has stable and unstable points (its counterexample,
 * test_park_counterexample). */
static void chain_text(char *buf, size_t len, int n, const char *an)
{
    size_t o = 0;
    int i;
    o += (size_t) snprintf(buf + o, len - o, "param c");
    for (i = 1; i <= n; i++) o += (size_t) snprintf(buf + o, len - o, " k%d", i);
    o += (size_t) snprintf(buf + o, len - o, "\nassume c > 0");
    for (i = 1; i <= n; i++) o += (size_t) snprintf(buf + o, len - o, ", k%d > 0", i);
    o += (size_t) snprintf(buf + o, len - o, "\nunknown");
    for (i = 1; i <= n; i++) o += (size_t) snprintf(buf + o, len - o, " x%d v%d a%d", i, i, i);
    o += (size_t) snprintf(buf + o, len - o, "\n");
    for (i = 1; i <= n; i++) {
        o += (size_t) snprintf(buf + o, len - o, "eq a%d[n+1] + c*v%d[n+1] + k%d*x%d[n+1]", i, i, i, i);
        if (i > 1) o += (size_t) snprintf(buf + o, len - o, " - k%d*x%d[n+1]", i, i - 1);
        if (i < n) o += (size_t) snprintf(buf + o, len - o, " + k%d*x%d[n+1] - k%d*x%d[n+1]", i + 1, i, i + 1, i + 1);
        o += (size_t) snprintf(buf + o, len - o, " = 0\neq x%d[n+1] - x%d[n] = (v%d[n+1] + v%d[n])/2\n"
                               "eq v%d[n+1] - v%d[n] = (a%d[n+1] + a%d[n])/2\n", i, i, i, i, i, i, i, i);
    }
    snprintf(buf + o, len - o, "analyse %s\n", an);
}

/* every "poly > 0" / "poly != 0" of conds at the point (vars: the params) */
static int conds_hold(const json_t *conds, const char **vars, const fmpq *pt, const fmpq_mpoly_ctx_t ctx)
{
    fmpq_mpoly_t f;
    fmpq_t val;
    fmpq *at[8];
    size_t i;
    int ok = 1;
    for (i = 0; i < 8 && i < (size_t) ctx->zctx->minfo->nvars; i++) at[i] = (fmpq *) pt + i;
    fmpq_mpoly_init(f, ctx);
    fmpq_init(val);
    for (i = 0; i < json_array_size(conds); i++) {
        char *line = strdup(json_string_value(json_array_get(conds, i))), *cut = strstr(line, " > 0");
        int ne = cut == NULL;
        if (ne) cut = strstr(line, " != 0");
        assert_non_null(cut);
        *cut = '\0';
        assert_int_equal(fmpq_mpoly_set_str_pretty(f, line, vars, ctx), 0);
        assert_true(fmpq_mpoly_evaluate_all_fmpq(val, f, at, ctx));
        free(line);
        if (ne ? fmpq_is_zero(val) : fmpq_sgn(val) <= 0) ok = 0;
    }
    fmpq_clear(val);
    fmpq_mpoly_clear(f, ctx);
    return ok;
}

/* The bilinear route's "never" (h-truth5): p = (lambda - 1)(lambda - a) has the
 * root 1 for every a (p(1) = 0 identically, by hand), so q(z) = (z - 1)^2
 * p((z + 1)/(z - 1)) has the factor z: never asymptotically stable.  Forced
 * onto the bilinear route, jury said "never" but printed no verdict line (the
 * table route and hurwitz say "never stable"). */
static void test_jury_bilinear_never(void **state)
{
    const char *text = "param a\nchar (lambda - 1)*(lambda - a)\nanalyse jury\nanalyse hurwitz\n";
    char *rep = NULL;
    size_t len = 0;
    FILE *f;
    json_t *doc;
    int outcome;
    slong old = rs_jury_set_bilinear_terms(0);
    (void) state;
    doc = tu_run_text(text, NULL, &outcome, NULL);
    rs_jury_set_bilinear_terms(old);
    assert_string_equal(str(result(doc, 0), "route"), "bilinear");
    assert_non_null(str(result(doc, 0), "never"));
    assert_string_equal(str(result(doc, 0), "verdict"), "never stable");
    assert_string_equal(str(result(doc, 1), "verdict"), "never stable");
    f = open_memstream(&rep, &len);
    rs_report_text(f, doc);
    fclose(f);
    /* one verdict line each: jury's and hurwitz's */
    assert_non_null(strstr(rep, "  verdict      never stable\n"));
    assert_non_null(strstr(strstr(rep, "  verdict      never stable\n") + 1, "  verdict      never stable\n"));
    free(rep);
    json_decref(doc);
}

static void test_jury_bilinear_route(void **state)
{
    const char *req[] = {"jury"}, *creq[] = {"charpoly"};
    int t;
    flint_rand_t st;
    (void) state;
    flint_randinit(st);
    for (t = 0; t < 3; t++) {
        char text[4096];
        json_t *doc[2], *cdoc;
        const json_t *r[2], *params;
        const char *vars[8];
        fmpq_mpoly_ctx_t ctx;
        fmpq_mpoly_t p;
        fmpq *pt;
        slong np, i, j, nstable = 0, npts = 60;
        int outcome, h;
        for (h = 0; h < 2; h++) {
            slong old = rs_jury_set_bilinear_terms(h ? 0 : WORD(1) << 40);
            if (t < 2) chain_text(text, sizeof text, t + 2, "jury");
            doc[h] = t < 2 ? tu_run_text(text, NULL, &outcome, NULL)
                           : tu_run_case("cases/park-staggered.case", req, 1, &outcome);
            rs_jury_set_bilinear_terms(old);
            r[h] = result(doc[h], 0);
            assert_true(json_is_true(json_object_get(r[h], "symbolic")));
            assert_true(json_is_true(json_object_get(json_object_get(r[h], "sample_check"), "agree")));
        }
        assert_null(json_object_get(r[0], "route"));
        assert_string_equal(str(r[1], "route"), "bilinear");
        if (t < 2) chain_text(text, sizeof text, t + 2, "charpoly");
        cdoc = t < 2 ? tu_run_text(text, NULL, &outcome, NULL)
                     : tu_run_case("cases/park-staggered.case", creq, 1, &outcome);
        params = json_object_get(cdoc, "params");
        np = (slong) json_array_size(params);
        assert_true(np >= 1 && np < 7);
        for (i = 0; i < np; i++) vars[i] = json_string_value(json_array_get(params, i));
        vars[np] = "lambda";
        fmpq_mpoly_ctx_init(ctx, np + 1, ORD_LEX);
        fmpq_mpoly_init(p, ctx);
        assert_int_equal(fmpq_mpoly_set_str_pretty(p, str(result(cdoc, 0), "poly"), vars, ctx), 0);
        pt = _fmpq_vec_init(np + 1);
        for (j = 0; j < npts; j++) {
            fmpq_mpoly_t u;
            fmpq_poly_t up;
            fmpz_poly_t zp;
            rs_jury_t ju;
            rs_error_t err;
            int stable;
            /* positive rationals num/den, num 1..400, den 1..20: inside
             * every assumption (c, k_i > 0; m, muh, wh > 0, alpha >= 0) */
            for (i = 0; i < np; i++)
                fmpq_set_si(pt + i, 1 + (slong) n_randint(st, 400), 1 + n_randint(st, 20));
            fmpq_mpoly_init(u, ctx);
            fmpq_poly_init(up);
            fmpz_poly_init(zp);
            rs_jury_init(ju);
            rs_error_init(err);
            /* p at the point, a polynomial in lambda alone */
            for (i = 0; i < np; i++)
                assert_true(fmpq_mpoly_evaluate_one_fmpq(u, i == 0 ? p : u, i, pt + i, ctx));
            assert_true(fmpq_mpoly_get_fmpq_poly(up, u, np, ctx));
            fmpq_poly_get_numerator(zp, up);
            assert_int_equal(rs_jury_count_fmpz_poly(ju, zp, err), RS_OK);
            stable = ju->count->inside == fmpz_poly_degree(zp);
            nstable += stable;
            for (h = 0; h < 2; h++)
                assert_int_equal(conds_hold(json_object_get(r[h], "conditions"), vars, pt, ctx), stable);
            rs_jury_clear(ju);
            fmpz_poly_clear(zp);
            fmpq_poly_clear(up);
            fmpq_mpoly_clear(u, ctx);
        }
        if (t < 2) assert_int_equal(nstable, npts);
        else assert_true(nstable > 0 && nstable < npts);
        _fmpq_vec_clear(pt, np + 1);
        fmpq_mpoly_clear(p, ctx);
        fmpq_mpoly_ctx_clear(ctx);
        json_decref(cdoc);
        json_decref(doc[0]);
        json_decref(doc[1]);
    }
    flint_randclear(st);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_regions_textbook),
        cmocka_unit_test(test_region_central_difference),
        cmocka_unit_test(test_limits_bdf2),
        cmocka_unit_test(test_claims_textbook),
        cmocka_unit_test(test_park_counterexample),
        cmocka_unit_test(test_park_proof_and_region),
        cmocka_unit_test(test_park_printed_bilinear),
        cmocka_unit_test(test_park_symbolic_jury),
        cmocka_unit_test(test_jury_interval_assumptions),
        cmocka_unit_test(test_jury_factor_halves),
        cmocka_unit_test(test_jury_bilinear_route),
        cmocka_unit_test(test_jury_bilinear_never),
        cmocka_unit_test(test_counts_roots_at_zero),
    };
    return cmocka_run_group_tests_name("exact", tests, NULL, NULL);
}
