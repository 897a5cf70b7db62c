/* test_signs.c -- symbolic conditions when the assumptions do not fix the
 * sign of the leading coefficient, roots at lambda = +-1 for every value,
 * exact region test points and the Routh array after a zero pivot
 * (issue 10, items 3, 4, 6).
 *
 * Expected values come from closed forms stated at each test (the root of a
 * linear polynomial, hand expansions of q(z)) and, for the property test,
 * from the exact root count at each point (Routh on q(z) and Schur-Cohn on
 * p(lambda), which agree with each other), never from the conditions under
 * test. */
#include "testutil.h"
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpq_poly.h>
#include <fmpq_vec.h>
#include "recstab/hurwitz.h"
#include "recstab/bilinear.h"
#include "recstab/routh.h"
#include "recstab/jury.h"

static const json_t *result(const json_t *doc, size_t i)
{
    return json_array_get(json_object_get(doc, "results"), i);
}

static const char *str(const json_t *o, const char *k)
{
    return json_string_value(json_object_get(o, k));
}

/* variables x0, x1, x2 (parameters) and lambda (index 3) */
static const char *VARS[] = {"x0", "x1", "x2", "lambda"};
#define NV 4
#define LV 3

/* branches for p (a polynomial in VARS) with the given signs */
static void branches(rs_hurwitz_or_t hb, const fmpz_mpoly_t p, const rs_sign_t *sign, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t q;
    rs_error_t err;
    rs_error_init(err);
    fmpz_mpoly_init(q, ctx);
    rs_bilinear_fmpz_mpoly(q, p, LV, ctx);
    assert_int_equal(rs_hurwitz_or_compute(hb, q, LV, fmpz_mpoly_degree_si(p, LV, ctx), sign, ctx, err), RS_OK);
    fmpz_mpoly_clear(q, ctx);
}

static int holds_at(const rs_hurwitz_or_t hb, const fmpz_mpoly_ctx_t ctx, slong a, ulong ad, slong b, ulong bd)
{
    fmpq *pt = _fmpq_vec_init(NV);
    fmpq *pp[NV];
    int i, h;
    for (i = 0; i < NV; i++) pp[i] = pt + i;
    fmpq_set_si(pt + 0, a, ad);
    fmpq_set_si(pt + 1, b, bd);
    h = rs_hurwitz_or_holds(hb, pp, ctx);
    _fmpq_vec_clear(pt, NV);
    return h;
}

/* b1*lambda + b0 (b1 = x0, b0 = x1): root -b0/b1, stable iff |b0| < |b1|.
 * Both branches are needed: b1 = -3, b0 = 2 is stable (root 2/3). */
static void test_linear_both_signs(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p;
    rs_hurwitz_or_t hb;
    slong a, b;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, NV, ORD_LEX);
    fmpz_mpoly_init(p, ctx);
    assert_int_equal(fmpz_mpoly_set_str_pretty(p, "x0*lambda + x1", VARS, ctx), 0);
    rs_hurwitz_or_init(hb);
    branches(hb, p, NULL, ctx);
    assert_int_equal(hb->nbranch, 2);
    for (a = -5; a <= 5; a++)
        for (b = -5; b <= 5; b++) {
            int want = labs(b) < labs(a);           /* |b0| < |b1| */
            int h = holds_at(hb, ctx, a, 1, b, 1);
            if (a == 0) continue;                   /* no step: degree drop */
            if (h < 0) { assert_true(labs(b) == labs(a)); continue; }  /* boundary |b0| = |b1| */
            assert_int_equal(h, want);
        }
    assert_int_equal(holds_at(hb, ctx, -3, 1, 2, 1), 1);
    /* b1 > 0 does not fix the sign of lc q = b1 - b0 (= -p(-1)): still two
     * branches, still exact */
    {
        rs_sign_t sign[NV] = {RS_SIGN_POSITIVE, RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN};
        branches(hb, p, sign, ctx);
        assert_int_equal(holds_at(hb, ctx, 3, 1, -2, 1), 1);
        assert_int_equal(holds_at(hb, ctx, 3, 1, 7, 2), 0);
        assert_int_equal(holds_at(hb, ctx, 3, 1, -7, 2), 0);
    }
    /* x0 lambda - x1 with x0, x1 > 0: lc q = x0 + x1 > 0, one branch;
     * root x1/x0, stable iff x1 < x0 */
    {
        rs_sign_t sign[NV] = {RS_SIGN_POSITIVE, RS_SIGN_POSITIVE, RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN};
        assert_int_equal(fmpz_mpoly_set_str_pretty(p, "x0*lambda - x1", VARS, ctx), 0);
        branches(hb, p, sign, ctx);
        assert_int_equal(hb->nbranch, 1);
        assert_int_equal(holds_at(hb, ctx, 3, 1, 2, 1), 1);
        assert_int_equal(holds_at(hb, ctx, 3, 1, 7, 2), 0);
    }
    rs_hurwitz_or_clear(hb, ctx);
    fmpz_mpoly_clear(p, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* (1 - q) lambda + (q + 1): |q + 1| < |1 - q| <=> 4q < 0, so stable iff
 * q < 0; at q = 1 the leading coefficient vanishes (no step). */
static void test_free_sign_lead(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p;
    rs_hurwitz_or_t hb;
    slong k;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, NV, ORD_LEX);
    fmpz_mpoly_init(p, ctx);
    /* the charpoly normalisation makes the lex-leading term positive:
     * (q - 1) lambda - (q + 1), the same roots */
    assert_int_equal(fmpz_mpoly_set_str_pretty(p, "x0*lambda - lambda - x0 - 1", VARS, ctx), 0);
    rs_hurwitz_or_init(hb);
    branches(hb, p, NULL, ctx);
    for (k = -20; k <= 20; k++) {
        int h = holds_at(hb, ctx, k, 4, 0, 1);
        if (k == 4 || k == 0) continue;   /* q = 1: no step; q = 0: root -1 */
        assert_int_equal(h, k < 0);
    }
    rs_hurwitz_or_clear(hb, ctx);
    fmpz_mpoly_clear(p, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* Roots at -1 or 1 for every value: (lambda + 1)^2 (2 lambda - 1) has
 * q(z) = 4 (z + 3) ... of degree 1 = 3 - 2; (lambda + 1)^2 has q = 4
 * (degree 0, no longer an error); (lambda - 1)(2 lambda + x0) has q(0) = p(1)
 * = 0 identically: z divides q. */
static void test_identically_on_circle(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p;
    rs_hurwitz_or_t hb;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, NV, ORD_LEX);
    fmpz_mpoly_init(p, ctx);
    rs_hurwitz_or_init(hb);
    assert_int_equal(fmpz_mpoly_set_str_pretty(p, "(lambda + 1)^2*(2*lambda - 1)", VARS, ctx), 0);
    branches(hb, p, NULL, ctx);
    assert_int_equal(hb->degree_drop, 2);
    assert_int_equal(hb->nbranch, 0);
    assert_int_equal(holds_at(hb, ctx, 0, 1, 0, 1), 0);
    assert_int_equal(fmpz_mpoly_set_str_pretty(p, "(lambda + 1)^2", VARS, ctx), 0);
    branches(hb, p, NULL, ctx);
    assert_int_equal(hb->degree_drop, 2);
    assert_int_equal(fmpz_mpoly_set_str_pretty(p, "(lambda - 1)*(2*lambda + x0)", VARS, ctx), 0);
    branches(hb, p, NULL, ctx);
    assert_int_equal(hb->degree_drop, 0);
    assert_int_equal(hb->zero_mult, 1);
    assert_int_equal(hb->nbranch, 0);
    rs_hurwitz_or_clear(hb, ctx);
    fmpz_mpoly_clear(p, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* p at the point pt (lambda entry ignored) as an integer polynomial */
static void eval_p(fmpz_poly_t u, const fmpz_mpoly_t p, fmpq *const *pt, const fmpz_mpoly_ctx_t ctx)
{
    slong j, d = fmpz_mpoly_degree_si(p, LV, ctx);
    fmpz_mpoly_t c;
    fmpq_poly_t f;
    fmpq_t x;
    fmpz_mpoly_init(c, ctx);
    fmpq_poly_init(f);
    fmpq_init(x);
    for (j = 0; j <= d; j++) {
        ulong e = (ulong) j;
        slong var = LV;
        fmpz_mpoly_get_coeff_vars_ui(c, p, &var, &e, 1, ctx);
        tu_eval_fmpz_mpoly(x, c, pt, ctx);
        fmpq_poly_set_coeff_fmpq(f, j, x);
    }
    fmpq_poly_get_numerator(u, f);
    fmpz_mpoly_clear(c, ctx);
    fmpq_poly_clear(f);
    fmpq_clear(x);
}

/* Property: random linear and quadratic p with coefficients affine in 1-3
 * free-sign parameters (some assumed positive), the conditions against the
 * exact verdict at 1000 random admissible points.  The verdict: Routh and
 * Schur-Cohn counts (they must agree), stable iff every root inside. */
static void test_property_random(void **state)
{
    fmpz_mpoly_ctx_t ctx;
    flint_rand_t st;
    slong npoints = 0, nstable = 0, nbranch2 = 0, trial;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, NV, ORD_LEX);
    flint_randinit(st);
    for (trial = 0; npoints < 1000; trial++) {
        slong deg = 1 + (slong) n_randint(st, 2), npar = 1 + (slong) n_randint(st, 3), j, v, k;
        rs_sign_t sign[NV] = {RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN};
        fmpz_mpoly_t p, t;
        rs_hurwitz_or_t hb;
        fmpz_mpoly_init(p, ctx);
        fmpz_mpoly_init(t, ctx);
        for (v = 0; v < npar; v++)
            if (n_randint(st, 3) == 0) sign[v] = RS_SIGN_POSITIVE;
        /* p = sum_j (c_j0 + sum_v c_jv x_v) lambda^j, c in [-3, 3] */
        for (j = 0; j <= deg; j++) {
            fmpz_mpoly_t c;
            fmpz_mpoly_init(c, ctx);
            fmpz_mpoly_set_si(c, (slong) n_randint(st, 7) - 3, ctx);
            for (v = 0; v < npar; v++) {
                fmpz_mpoly_gen(t, v, ctx);
                fmpz_mpoly_scalar_mul_si(t, t, (slong) n_randint(st, 7) - 3, ctx);
                fmpz_mpoly_add(c, c, t, ctx);
            }
            fmpz_mpoly_gen(t, LV, ctx);
            fmpz_mpoly_pow_ui(t, t, (ulong) j, ctx);
            fmpz_mpoly_mul(t, t, c, ctx);
            fmpz_mpoly_add(p, p, t, ctx);
            fmpz_mpoly_clear(c, ctx);
        }
        if (fmpz_mpoly_degree_si(p, LV, ctx) < 1) {
            fmpz_mpoly_clear(p, ctx);
            fmpz_mpoly_clear(t, ctx);
            continue;
        }
        rs_hurwitz_or_init(hb);
        branches(hb, p, sign, ctx);
        if (hb->nbranch == 2) nbranch2++;
        for (k = 0; k < 25; k++) {
            fmpq *pt = _fmpq_vec_init(NV);
            fmpq *pp[NV];
            fmpz_poly_t u;
            int h;
            for (v = 0; v < NV; v++) pp[v] = pt + v;
            for (v = 0; v < npar; v++) {
                /* a rational with numerator in [-12, 12], denominator 1..4 */
                fmpq_set_si(pt + v, (slong) n_randint(st, 25) - 12, 1 + n_randint(st, 4));
                if (sign[v] == RS_SIGN_POSITIVE) {
                    fmpq_abs(pt + v, pt + v);
                    if (fmpq_is_zero(pt + v)) fmpq_set_si(pt + v, 1, 7);
                }
            }
            fmpz_poly_init(u);
            eval_p(u, p, pp, ctx);
            h = rs_hurwitz_or_holds(hb, pp, ctx);
            if (fmpz_poly_degree(u) == fmpz_mpoly_degree_si(p, LV, ctx) && h >= 0) {
                rs_routh_t ro;
                rs_jury_t ju;
                rs_error_t err;
                int stable;
                rs_error_init(err);
                rs_routh_init(ro);
                rs_jury_init(ju);
                assert_int_equal(rs_routh_fmpz_poly(ro, u, err), RS_OK);
                assert_int_equal(rs_jury_fmpz_poly(ju, u, err), RS_OK);
                assert_true(rs_rootcount_equal(ro->count, ju->count));
                stable = rs_rootcount_status(ro->count) == RS_STATUS_STABLE;
                if (stable != h) {
                    char *ps = fmpz_mpoly_get_str_pretty(p, VARS, ctx);
                    char *us = fmpz_poly_get_str_pretty(u, "lambda");
                    fail_msg("p = %s at %s: conditions say %d, exact verdict %d", ps, us, h, stable);
                }
                nstable += stable;
                npoints++;
                rs_routh_clear(ro);
                rs_jury_clear(ju);
            }
            fmpz_poly_clear(u);
            _fmpq_vec_clear(pt, NV);
        }
        rs_hurwitz_or_clear(hb, ctx);
        fmpz_mpoly_clear(p, ctx);
        fmpz_mpoly_clear(t, ctx);
    }
    /* the sample exercises both outcomes and the two-branch case */
    assert_true(nstable > 50 && nstable < npoints - 50);
    assert_true(nbranch2 > 5);
    flint_randclear(st);
    fmpz_mpoly_ctx_clear(ctx);
}

/* The analyses on the bundled cases: branches in JSON, the sample check,
 * p(+-1) as stated, never-stable reasons, far region ends, Routh rows. */
static void test_cases(void **state)
{
    int outcome;
    json_t *doc;
    const json_t *o, *ivs;
    (void) state;

    /* b1 lambda + b0: two branches {b1 - b0 > 0, b1 + b0 > 0} or their
     * negatives (|b0| < |b1| with b1 of either sign); p(1) = b1 + b0 */
    doc = tu_run_case("cases/hard/free-sign-linear.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    o = result(doc, 0);
    assert_null(json_object_get(o, "conditions"));
    assert_int_equal(json_array_size(json_object_get(o, "branches")), 2);
    assert_string_equal(str(o, "p_at_1"), "b1 + b0");
    assert_string_equal(str(o, "p_at_minus_1"), "-b1 + b0");
    assert_true(json_is_true(json_object_get(json_object_get(o, "sample_check"), "agree")));
    assert_true(json_integer_value(json_object_get(json_object_get(o, "sample_check"), "points")) >= 5);
    assert_int_equal(json_array_size(json_object_get(result(doc, 2), "branches")), 2);
    json_decref(doc);

    /* (1 - q) lambda + (q + 1): stable iff q < 0; p(1) = 2, p(-1) = 2q as
     * written (the normalised polynomial has the opposite sign) */
    doc = tu_run_case("cases/hard/free-sign-lead.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    o = result(doc, 0);
    assert_string_equal(json_string_value(json_array_get(json_object_get(o, "conditions"), 0)), "-q > 0");
    assert_string_equal(str(o, "p_at_1"), "2");
    assert_string_equal(str(o, "p_at_minus_1"), "2*q");
    ivs = json_object_get(result(doc, 2), "intervals");
    assert_true(json_is_null(json_object_get(json_array_get(ivs, 0), "lo")));
    assert_string_equal(str(json_array_get(ivs, 0), "hi"), "0");
    assert_string_equal(str(json_array_get(ivs, 0), "status"), "stable");
    json_decref(doc);

    /* (lambda + 1)^2 (2 lambda - 1 + a): lambda = -1 twice for every a */
    doc = tu_run_case("cases/hard/root-at-minus-one.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    o = result(doc, 0);
    assert_string_equal(str(o, "verdict"), "never stable");
    assert_non_null(strstr(str(o, "never"), "lambda = -1"));
    json_decref(doc);
    /* a claim there is refuted (exit 1), not "proved" from the conditions of
     * the lower-degree q and then inconsistent (exit 3) */
    {
        const char *req[] = {"claim stable"};
        doc = tu_run_case("cases/hard/root-at-minus-one.case", req, 1, &outcome);
        assert_int_equal(outcome, RS_OUTCOME_FAILED);
        assert_string_equal(str(result(doc, 0), "status"), "refuted");
        json_decref(doc);
    }

    /* roots 1 - a/10^40, -1/2: stable exactly on (0, 2*10^40), unstable past */
    doc = tu_run_case("cases/hard/far-endpoint.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    ivs = json_object_get(result(doc, 0), "intervals");
    assert_int_equal(json_array_size(ivs), 5);
    assert_string_equal(str(json_array_get(ivs, 2), "status"), "stable");
    assert_string_equal(str(json_array_get(ivs, 2), "hi"), "20000000000000000000000000000000000000000");
    assert_string_equal(str(json_array_get(ivs, 4), "status"), "unstable");
    json_decref(doc);

    /* s^4 + s^3 + 3s^2 + 3s + 3: five rows z^4..z^0; eps column
     * 1, 1, eps, 3 - 3/eps, 3 (times 16): signs + + + - + */
    doc = tu_run_case("cases/hard/routh-zero-pivot.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    o = result(doc, 0);
    assert_int_equal(json_array_size(json_object_get(o, "rows")), 5);
    {
        static const int sg[5] = {1, 1, 1, -1, 1};
        size_t i;
        for (i = 0; i < 5; i++) {
            assert_int_equal(json_integer_value(json_array_get(json_object_get(o, "powers"), i)), 4 - (int) i);
            assert_int_equal(json_integer_value(json_array_get(json_object_get(o, "epsilon_signs"), i)), sg[i]);
        }
    }
    assert_string_equal(json_string_value(json_array_get(json_array_get(json_object_get(o, "rows"), 2), 0)),
                        "eps");
    assert_int_equal(json_integer_value(json_object_get(o, "outside")), 2);
    json_decref(doc);
}

/* Irrational region ends, decided exactly (closed forms in the case files):
 * (a^2 - 3) lambda^2 + lambda + 1/2 is singular at +-sqrt(3), unstable at
 * +-sqrt(7/2) (double root -1), marginal at +-sqrt(3/2) (roots 1, -1/3);
 * lambda^2 - (a^2 - 1) lambda + 1 is marginal exactly on (-sqrt 3, sqrt 3)
 * and unstable at the ends (double root 1). */
static void test_algebraic_points(void **state)
{
    int outcome;
    json_t *doc;
    const json_t *o, *ivs, *iv;
    size_t i;
    int nsing = 0, nmarg_pt = 0;
    (void) state;
    doc = tu_run_case("cases/hard/algebraic-singular.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    o = result(doc, 0);
    assert_int_equal(json_array_size(json_object_get(o, "undecided_points")), 0);
    ivs = json_object_get(o, "intervals");
    for (i = 0; i < json_array_size(ivs); i++) {
        iv = json_array_get(ivs, i);
        if (json_equal(json_object_get(iv, "lo"), json_object_get(iv, "hi"))) {
            const json_t *e = json_object_get(iv, "lo");
            const char *mp = json_string_value(json_object_get(e, "minpoly"));
            if (strcmp(str(iv, "status"), "singular") == 0) { nsing++; assert_string_equal(mp, "a^2 - 3"); }
            if (strcmp(str(iv, "status"), "marginal") == 0) { nmarg_pt++; assert_string_equal(mp, "2*a^2 - 3"); }
        }
        /* a^2 = 7/2 closes the unstable intervals: (-sqrt 3.5 .. -sqrt 3) */
        if (json_is_object(json_object_get(iv, "lo"))
            && strcmp(json_string_value(json_object_get(json_object_get(iv, "lo"), "minpoly")), "2*a^2 - 7") == 0)
            assert_true(json_is_true(json_object_get(iv, "lo_closed")) == (strcmp(str(iv, "status"), "unstable") == 0));
    }
    assert_int_equal(nsing, 2);
    assert_int_equal(nmarg_pt, 2);
    json_decref(doc);

    doc = tu_run_case("cases/hard/algebraic-double.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    ivs = json_object_get(result(doc, 0), "intervals");
    assert_int_equal(json_array_size(ivs), 3);
    assert_string_equal(str(json_array_get(ivs, 0), "status"), "unstable");
    assert_true(json_is_true(json_object_get(json_array_get(ivs, 0), "hi_closed")));
    assert_string_equal(str(json_array_get(ivs, 1), "status"), "marginal");
    assert_false(json_is_true(json_object_get(json_array_get(ivs, 1), "lo_closed")));
    assert_string_equal(str(json_array_get(ivs, 2), "status"), "unstable");
    assert_true(json_is_true(json_object_get(json_array_get(ivs, 2), "lo_closed")));
    json_decref(doc);
}

/* Systems at an algebraic point (closed forms in the case files): the
 * identity at lambda = 1 (a = +-sqrt 3) is marginal, a Jordan block there
 * unstable. */
static void test_algebraic_systems(void **state)
{
    int outcome;
    json_t *doc;
    const json_t *ivs;
    size_t i;
    int nmarg = 0;
    (void) state;
    doc = tu_run_case("cases/hard/algebraic-system-semisimple.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    ivs = json_object_get(result(doc, 0), "intervals");
    for (i = 0; i < json_array_size(ivs); i++) {
        const json_t *iv = json_array_get(ivs, i), *lo = json_object_get(iv, "lo");
        if (json_is_object(lo) && json_equal(lo, json_object_get(iv, "hi"))) {
            assert_string_equal(json_string_value(json_object_get(lo, "minpoly")), "a^2 - 3");
            assert_string_equal(str(iv, "status"), "marginal");
            nmarg++;
        }
    }
    assert_int_equal(nmarg, 2);
    json_decref(doc);
    doc = tu_run_case("cases/hard/algebraic-system-jordan.case", NULL, -1, &outcome);
    assert_int_equal(outcome, 0);
    ivs = json_object_get(result(doc, 0), "intervals");
    assert_int_equal(json_array_size(ivs), 5);
    assert_string_equal(str(json_array_get(ivs, 0), "status"), "unstable");
    assert_true(json_is_true(json_object_get(json_array_get(ivs, 0), "hi_closed")));
    assert_string_equal(str(json_array_get(ivs, 4), "status"), "unstable");
    assert_true(json_is_true(json_object_get(json_array_get(ivs, 4), "lo_closed")));
    json_decref(doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_linear_both_signs),
        cmocka_unit_test(test_free_sign_lead),
        cmocka_unit_test(test_identically_on_circle),
        cmocka_unit_test(test_property_random),
        cmocka_unit_test(test_cases),
        cmocka_unit_test(test_algebraic_points),
        cmocka_unit_test(test_algebraic_systems),
    };
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup_master();
    return r;
}
