/* test_semisimple.c -- systems with repeated unit-circle roots, singular
 * steps and dead-beat schemes.  Expected values come from:
 *   - the Jordan structure planted by construction: A = U D V with U, V
 *     unimodular polynomial matrices (det +-1), so A(lambda0) and D(lambda0)
 *     have the same rank at every lambda0;
 *   - hand algebra written next to each case (the case files say it too);
 *   - a time-domain run of the leapfrog recurrence written out here in
 *     double precision (bounded at nu = 1/2, linear growth at nu = 1). */
#include "testutil.h"
#include <string.h>
#include <math.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly_mat.h>
#include "recstab/casefile.h"
#include "recstab/scheme.h"
#include "recstab/analysis.h"
#include "recstab/semisimple.h"

static const json_t *result(const json_t *doc, size_t i)
{
    return json_array_get(json_object_get(doc, "results"), i);
}

static const char *str(const json_t *o, const char *k)
{
    return json_string_value(json_object_get(o, k));
}

static json_t *run_text(const char *text, int *outcome)
{
    return tu_run_text(text, NULL, outcome, NULL);
}

static const char *status_of(const char *text)
{
    static char buf[32];
    int outcome;
    json_t *doc = run_text(text, &outcome);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    snprintf(buf, sizeof buf, "%s", str(result(doc, 0), "status"));
    json_decref(doc);
    return buf;
}

/* (lambda - 1) I: kernel 2 at lambda = 1 (semisimple); the Jordan block
 * [[lambda - 1, -1], [0, lambda - 1]]: rank 1 there (kernel 1 < 2). */
static void test_rank_mod(void **state)
{
    fmpq_poly_struct A[4];
    fmpz_poly_t f;
    int i;
    (void) state;
    for (i = 0; i < 4; i++) fmpq_poly_init(A + i);
    fmpz_poly_init(f);
    fmpz_poly_set_str(f, "2  -1 1");                /* lambda - 1 */
    fmpq_poly_set_str(A + 0, "2  -1 1");
    fmpq_poly_set_str(A + 3, "2  -1 1");
    assert_int_equal(rs_semisimple_rank_mod(A, 2, f), 0);
    fmpq_poly_set_si(A + 1, -1);
    assert_int_equal(rs_semisimple_rank_mod(A, 2, f), 1);
    /* modulo lambda^2 + 1: diag(lambda^2 + 1, lambda^2 + 1) has rank 0 over Q(i) */
    fmpz_poly_set_str(f, "3  1 0 1");
    fmpq_poly_set_str(A + 0, "3  1 0 1");
    fmpq_poly_set_str(A + 3, "3  1 0 1");
    fmpq_poly_zero(A + 1);
    assert_int_equal(rs_semisimple_rank_mod(A, 2, f), 0);
    for (i = 0; i < 4; i++) fmpq_poly_clear(A + i);
    fmpz_poly_clear(f);
}

/* The examples, by hand: the identity x[n+1] = x[n], y[n+1] = y[n]
 * is marginal (A(1) = 0, kernel 2); x[n+1] = x[n] + y[n] is a Jordan block. */
static void test_identity_and_jordan(void **state)
{
    (void) state;
    assert_string_equal(status_of("unknown x y\neq x[n+1] = x[n]\neq y[n+1] = y[n]\nanalyse stability\n"),
                        "marginal");
    assert_string_equal(status_of("unknown x y\neq x[n+1] = x[n] + y[n]\neq y[n+1] = y[n]\n"
                                  "analyse stability\n"), "unstable");
    /* a `char` polynomial is a scalar recurrence: (lambda - 1)^2 grows */
    assert_string_equal(status_of("char (lambda - 1)^2\nanalyse stability\n"), "unstable");
    /* two identical uncoupled trapezoidal oscillators (w = 1/2): each mode
     * (1 + w^2/4) l^2 - 2 (1 - w^2/4) l + (1 + w^2/4) has simple roots on the
     * circle, det has them twice, each with a two-dimensional kernel */
    assert_string_equal(status_of(
        "unknown x1 v1 x2 v2\nlet w = 1/2\n"
        "eq x1[n+1] - x1[n] = (v1[n+1] + v1[n])/2\neq v1[n+1] - v1[n] = -w^2*(x1[n+1] + x1[n])/2\n"
        "eq x2[n+1] - x2[n] = (v2[n+1] + v2[n])/2\neq v2[n+1] - v2[n] = -w^2*(x2[n+1] + x2[n])/2\n"
        "analyse stability\n"), "marginal");
    /* ... and driving the second by the first's position at resonance makes
     * the double roots defective (forced response at the natural frequency) */
    assert_string_equal(status_of(
        "unknown x1 v1 x2 v2\nlet w = 1/2\n"
        "eq x1[n+1] - x1[n] = (v1[n+1] + v1[n])/2\neq v1[n+1] - v1[n] = -w^2*(x1[n+1] + x1[n])/2\n"
        "eq x2[n+1] - x2[n] = (v2[n+1] + v2[n])/2\n"
        "eq v2[n+1] - v2[n] = -w^2*(x2[n+1] + x2[n])/2 + (x1[n+1] + x1[n])/2\n"
        "analyse stability\n"), "unstable");
}

/* The leapfrog case: region marginal on (0, 1), unstable from 1 on (see the
 * case file's derivation). */
static void test_leapfrog_region(void **state)
{
    const char *req[] = {"region nu"};
    int outcome;
    json_t *doc = tu_run_case("cases/textbook/leapfrog-periodic8.case", req, 1, &outcome);
    const json_t *ivs = json_object_get(result(doc, 0), "intervals");
    const json_t *a = json_array_get(ivs, 0), *b = json_array_get(ivs, 1);
    (void) state;
    assert_string_equal(str(a, "status"), "marginal");
    assert_string_equal(str(a, "lo"), "0");
    assert_string_equal(str(a, "hi"), "1");
    assert_false(json_is_true(json_object_get(a, "hi_closed")));
    assert_string_equal(str(b, "status"), "unstable");
    assert_string_equal(str(b, "lo"), "1");
    assert_true(json_is_true(json_object_get(b, "lo_closed")));
    json_decref(doc);
}

/* The claims of the leapfrog case: bounded for nu < 1 (proved: the repeated
 * factors are semisimple over Q(nu)), not for nu <= 1 (nu = 1 is a Jordan
 * block), by the derivation in the case file. */
static void test_leapfrog_claims(void **state)
{
    int outcome;
    json_t *doc = tu_run_case("cases/textbook/leapfrog-periodic8.case", NULL, -1, &outcome);
    (void) state;
    assert_string_equal(str(result(doc, 1), "status"), "proved");
    assert_string_equal(str(result(doc, 2), "status"), "refuted");
    assert_string_equal(str(json_object_get(result(doc, 2), "counterexample"), "nu"), "1");
    assert_int_equal(outcome, RS_OUTCOME_FAILED);
    json_decref(doc);
}

/* Two identical trapezoidal oscillators coupled by kc >= 0: bounded for every
 * kc (the case file derives it); at kc = 0 the double circle roots are
 * semisimple. */
static void test_identical_oscillators(void **state)
{
    int outcome;
    json_t *doc = tu_run_case("cases/textbook/identical-oscillators-trapezoidal.case", NULL, -1, &outcome);
    (void) state;
    assert_string_equal(str(json_array_get(json_object_get(result(doc, 0), "intervals"), 0), "status"),
                        "marginal");
    assert_string_equal(str(result(doc, 1), "status"), "proved");
    json_decref(doc);
}

/* Time-domain oracle: the leapfrog recurrence stepped in double precision.
 * Returns max |u| over the last steps divided by max |u| of the start. */
static double leapfrog_growth(double nu, int steps)
{
    enum { N = 8 };
    double um[N], u[N], up[N], m0 = 0, m = 0;
    int j, n;
    for (j = 0; j < N; j++) {
        um[j] = sin(1.0 + 2.1 * j) + 0.3 * cos(0.7 * j * j);
        u[j] = cos(0.4 + 1.3 * j) - 0.2 * sin(1.1 * j);
        m0 = fmax(m0, fmax(fabs(um[j]), fabs(u[j])));
    }
    for (n = 0; n < steps; n++) {
        for (j = 0; j < N; j++) up[j] = um[j] - nu * (u[(j + 1) % N] - u[(j + N - 1) % N]);
        memcpy(um, u, sizeof u);
        memcpy(u, up, sizeof u);
        if (n > steps - 50)
            for (j = 0; j < N; j++) m = fmax(m, fabs(u[j]));
    }
    return m / m0;
}

static void test_leapfrog_time_domain(void **state)
{
    const char *lo = "title t\nparam nu\nunknown u0 u1 u2 u3 u4 u5 u6 u7\n"
        "eq u0[n+1] - u0[n-1] + nu*(u1[n] - u7[n]) = 0\neq u1[n+1] - u1[n-1] + nu*(u2[n] - u0[n]) = 0\n"
        "eq u2[n+1] - u2[n-1] + nu*(u3[n] - u1[n]) = 0\neq u3[n+1] - u3[n-1] + nu*(u4[n] - u2[n]) = 0\n"
        "eq u4[n+1] - u4[n-1] + nu*(u5[n] - u3[n]) = 0\neq u5[n+1] - u5[n-1] + nu*(u6[n] - u4[n]) = 0\n"
        "eq u6[n+1] - u6[n-1] + nu*(u7[n] - u5[n]) = 0\neq u7[n+1] - u7[n-1] + nu*(u0[n] - u6[n]) = 0\n";
    char text[2048];
    double g_half = leapfrog_growth(0.5, 4000), g_one = leapfrog_growth(1.0, 4000);
    (void) state;
    /* the oracle itself: bounded vs linear growth (a Jordan block) */
    assert_true(g_half < 10.0);
    assert_true(g_one > 100.0);
    snprintf(text, sizeof text, "%sset nu = 1/2\nanalyse stability\n", lo);
    assert_string_equal(status_of(text), "marginal");
    snprintf(text, sizeof text, "%sset nu = 1\nanalyse stability\n", lo);
    assert_string_equal(status_of(text), "unstable");
}

/* Backward Euler (1 - q) y[n+1] = y[n] at q = 1 and BDF2 in real form at
 * z = 3/2 (leading coefficient 1 - 2z/3 of (1 - 2z/3) l^2 - 4/3 l + 1/3):
 * the step cannot be solved there. */
static void test_singular(void **state)
{
    int outcome;
    json_t *doc;
    const json_t *ivs;
    size_t i;
    int seen = 0;
    (void) state;
    assert_string_equal(status_of("param q\nunknown y\neq (1 - q)*y[n+1] = y[n]\nset q = 1\nanalyse stability\n"),
                        "singular");
    assert_string_equal(status_of(
        "param x y\nunknown a b\n"
        "eq a[n+2] - 4/3*a[n+1] + 1/3*a[n] = 2/3*(x*a[n+2] - y*b[n+2])\n"
        "eq b[n+2] - 4/3*b[n+1] + 1/3*b[n] = 2/3*(x*b[n+2] + y*a[n+2])\n"
        "set x = 3/2, y = 0\nanalyse stability\n"), "singular");
    /* away from it BDF2 is fine: z = -1 gives roots of (5/3) l^2 - 4/3 l + 1/3
     * with product 1/5 and sum 4/5 (complex pair of modulus 1/sqrt 5): stable */
    assert_string_equal(status_of(
        "param x y\nunknown a b\n"
        "eq a[n+2] - 4/3*a[n+1] + 1/3*a[n] = 2/3*(x*a[n+2] - y*b[n+2])\n"
        "eq b[n+2] - 4/3*b[n+1] + 1/3*b[n] = 2/3*(x*b[n+2] + y*a[n+2])\n"
        "set x = -1, y = 0\nanalyse stability\n"), "stable");
    doc = tu_run_case("cases/textbook/backward-euler-singular.case", NULL, -1, &outcome);
    ivs = json_object_get(result(doc, 0), "intervals");
    for (i = 0; i < json_array_size(ivs); i++) {
        const json_t *iv = json_array_get(ivs, i);
        if (strcmp(str(iv, "status"), "singular") == 0) {
            assert_string_equal(str(iv, "lo"), "1");
            assert_string_equal(str(iv, "hi"), "1");
            seen++;
        }
    }
    assert_int_equal(seen, 1);
    json_decref(doc);
    /* a claim over a set containing q = 1 is refuted there */
    doc = run_text("param q\nunknown y\neq (1 - q)*y[n+1] = y[n]\nassume q >= 1, q <= 1\n"
                   "claim bounded when q = 1\n", &outcome);
    assert_string_equal(str(result(doc, 0), "status"), "refuted");
    json_decref(doc);
}

/* det A = lambda^2 (x[n+1] = y[n], y[n+1] = 0): stable, radius exactly 0. */
static void test_dead_beat(void **state)
{
    int outcome;
    json_t *doc = tu_run_case("cases/textbook/dead-beat.case", NULL, -1, &outcome);
    (void) state;
    assert_string_equal(str(result(doc, 0), "status"), "stable");
    assert_string_equal(str(result(doc, 1), "upper"), "0");
    assert_string_equal(str(result(doc, 1), "exact_status"), "stable");
    json_decref(doc);
}

/* A region whose Jordan structure changes where nothing in det A does:
 * x[n+1] = x[n] + c*y[n] has det (lambda - 1)^2 for every c, bounded only at
 * c = 0 (see the case file). */
static void test_rank_drop_region(void **state)
{
    int outcome;
    json_t *doc = tu_run_case("cases/textbook/jordan-vs-identity.case", NULL, -1, &outcome);
    const json_t *ivs = json_object_get(result(doc, 0), "intervals");
    (void) state;
    assert_int_equal(json_array_size(ivs), 3);
    assert_string_equal(str(json_array_get(ivs, 0), "status"), "unstable");
    assert_string_equal(str(json_array_get(ivs, 1), "status"), "marginal");
    assert_string_equal(str(json_array_get(ivs, 1), "lo"), "0");
    assert_string_equal(str(json_array_get(ivs, 2), "status"), "unstable");
    json_decref(doc);
}

/* ---- property: planted Jordan structure ---------------------------------- */

/* M = M * E with E = I + e*E_ij (i != j), e a random small polynomial:
 * column j += e * column i.  Unimodular, so ranks at every point stay. */
static void col_op(fmpz_poly_mat_t M, slong i, slong j, flint_rand_t st)
{
    fmpz_poly_t e, t;
    slong r;
    fmpz_poly_init(e);
    fmpz_poly_init(t);
    fmpz_poly_randtest(e, st, 1 + n_randint(st, 2), 3);
    for (r = 0; r < fmpz_poly_mat_nrows(M); r++) {
        fmpz_poly_mul(t, e, fmpz_poly_mat_entry(M, r, i));
        fmpz_poly_add(fmpz_poly_mat_entry(M, r, j), fmpz_poly_mat_entry(M, r, j), t);
    }
    fmpz_poly_clear(e);
    fmpz_poly_clear(t);
}

static void row_op(fmpz_poly_mat_t M, slong i, slong j, flint_rand_t st)
{
    fmpz_poly_t e, t;
    slong c;
    fmpz_poly_init(e);
    fmpz_poly_init(t);
    fmpz_poly_randtest(e, st, 1 + n_randint(st, 2), 3);
    for (c = 0; c < fmpz_poly_mat_ncols(M); c++) {
        fmpz_poly_mul(t, e, fmpz_poly_mat_entry(M, i, c));
        fmpz_poly_add(fmpz_poly_mat_entry(M, j, c), fmpz_poly_mat_entry(M, j, c), t);
    }
    fmpz_poly_clear(e);
    fmpz_poly_clear(t);
}

static void test_planted_property(void **state)
{
    /* circle factors: lambda - 1, lambda + 1, lambda^2 + 1, lambda^2 - lambda + 1 */
    const char *circ[] = {"2  -1 1", "2  1 1", "3  1 0 1", "3  1 -1 1"};
    flint_rand_t st;
    int iter, agree = 0;
    (void) state;
    flint_randinit(st);
    for (iter = 0; iter < 300; iter++) {
        slong n = 2 + (slong) n_randint(st, 3), i, k;
        int semisimple = (int) n_randint(st, 2);
        fmpz_poly_mat_t D;
        fmpz_poly_t f, inner, det;
        fmpq_poly_struct *A;
        rs_semisimple_t ss;
        rs_error_t err;
        fmpz_poly_init(f);
        fmpz_poly_init(inner);
        fmpz_poly_init(det);
        fmpz_poly_set_str(f, circ[n_randint(st, 4)]);
        fmpz_poly_set_str(inner, "2  1 3");          /* 3 lambda + 1: root -1/3 inside */
        fmpz_poly_mat_init(D, n, n);
        /* Smith-like diagonal: semisimple diag(f, f, inner, 1...) or Jordan
         * diag(1, f^2, inner, 1...): det = f^2 * inner either way */
        for (i = 0; i < n; i++) fmpz_poly_one(fmpz_poly_mat_entry(D, i, i));
        if (semisimple) {
            fmpz_poly_set(fmpz_poly_mat_entry(D, 0, 0), f);
            fmpz_poly_set(fmpz_poly_mat_entry(D, 1, 1), f);
        } else {
            fmpz_poly_mul(fmpz_poly_mat_entry(D, 1, 1), f, f);
        }
        if (n > 2) fmpz_poly_set(fmpz_poly_mat_entry(D, 2, 2), inner);
        else fmpz_poly_mul(fmpz_poly_mat_entry(D, 1, 1), fmpz_poly_mat_entry(D, 1, 1), inner);
        for (k = 0; k < 2 * n; k++) {
            slong a = (slong) n_randint(st, (ulong) n), b = (slong) n_randint(st, (ulong) n - 1);
            if (b >= a) b++;
            if (n_randint(st, 2)) row_op(D, a, b, st); else col_op(D, a, b, st);
        }
        fmpz_poly_mat_det(det, D);
        A = flint_malloc(n * n * sizeof(fmpq_poly_struct));
        for (i = 0; i < n * n; i++) {
            fmpq_poly_init(A + i);
            fmpq_poly_set_fmpz_poly(A + i, fmpz_poly_mat_entry(D, i / n, i % n));
        }
        rs_semisimple_init(ss);
        rs_error_init(err);
        assert_int_equal(rs_semisimple_circle(ss, A, n, det, err), RS_OK);
        assert_int_equal(ss->nfactors, 1);          /* only f reaches the circle */
        assert_int_equal(ss->f[0].mult, 2);
        agree += (ss->all_semisimple == semisimple);
        assert_int_equal(ss->all_semisimple, semisimple);
        rs_semisimple_clear(ss);
        for (i = 0; i < n * n; i++) fmpq_poly_clear(A + i);
        flint_free(A);
        fmpz_poly_mat_clear(D);
        fmpz_poly_clear(f);
        fmpz_poly_clear(inner);
        fmpz_poly_clear(det);
    }
    assert_int_equal(agree, 300);
    flint_randclear(st);
}

/* A value that zeroes a divisor is bad input (exit 2 in the CLI; here the
 * run returns an error). */
static void test_divisor_zero(void **state)
{
    rs_case_t c;
    rs_error_t err;
    rs_options_t opt;
    json_t *doc = NULL;
    int outcome;
    const char *text = "param y\nunknown x\neq x[n+1] = x[n]/y\nset y = 0\nanalyse stability\n";
    (void) state;
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    assert_int_equal(rs_case_parse_string(c, "t.case", text, strlen(text), err), RS_OK);
    assert_int_equal(rs_analysis_run(&doc, &outcome, c, &opt, err), RS_ERR_INPUT);
    assert_non_null(strstr(err->msg, "y != 0"));
    rs_case_clear(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rank_mod),
        cmocka_unit_test(test_identity_and_jordan),
        cmocka_unit_test(test_leapfrog_region),
        cmocka_unit_test(test_leapfrog_time_domain),
        cmocka_unit_test(test_leapfrog_claims),
        cmocka_unit_test(test_identical_oscillators),
        cmocka_unit_test(test_singular),
        cmocka_unit_test(test_dead_beat),
        cmocka_unit_test(test_rank_drop_region),
        cmocka_unit_test(test_planted_property),
        cmocka_unit_test(test_divisor_zero),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
