/* test_radius.c -- cmocka tests of the certified spectral radius.
 *
 * Every expected value comes from an independent closed form evaluated with
 * Arb at high precision (never from this module's own output):
 *   forward Euler   q^2 l^2 - 2q^2 l + (q^2+p^2),  w = p/q: roots 1 +- i w,
 *                   rho = sqrt(1+w^2)
 *   backward Euler  (q^2+p^2) l^2 - 2q^2 l + q^2: roots (1 +- i w)/(1+w^2),
 *                   rho = 1/sqrt(1+w^2)
 *   central diff.   q^2 l^2 - (2q^2-p^2) l + q^2, w < 2: product of the
 *                   conjugate roots is 1, rho = 1 exactly
 *   (3l-1)^2 (2l+1) rho = 1/2;  (10^10 l - (10^10-1))^6 (2l-1): 1 - 10^-10
 *   10^80 l^2 - 1   rho = 10^-40
 *   prod_{k=1..40} (41 l - k): 40/41;  prod_{k=0..39} (2^20 l - 2^k): 2^19
 *   lambda^n - c    every root has modulus c^(1/n)
 *   matrix recurrences: eigenvalues of a 2x2 matrix by the quadratic formula,
 *   and the determinant of a 2x2 polynomial matrix computed with fmpz_poly.
 */
#include "testutil.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <flint/fmpz.h>
#include <arb_fmpz_poly.h>
#include "recstab/radius.h"
#include "recstab/jury.h"
#include "recstab/routh.h"

typedef int (*radius_fn)(rs_radius_t, const fmpz_poly_t, slong, slong,
                         rs_error_t);

static slong truth_prec(slong digits)
{
    return (slong) (digits * 3.33 * 2) + 128;
}

/* rho contains truth, lower <= truth <= upper, 2 rad(rho) < 10^-d |truth|. */
static void check_radius(const rs_radius_t r, const arb_t truth, slong digits)
{
    arb_t w, tol, ten;
    slong prec = truth_prec(digits);

    arb_init(w);
    arb_init(tol);
    arb_init(ten);
    assert_true(arb_contains(r->rho, truth));
    assert_true(arb_le(r->lower, truth) || arb_contains(r->lower, truth));
    assert_true(arb_le(truth, r->upper) || arb_contains(r->upper, truth));
    arf_set_mag(arb_midref(w), arb_radref(r->rho));
    arb_mul_2exp_si(w, w, 1);
    arb_ui_pow_ui(ten, 10, digits, prec);
    arb_abs(tol, truth);
    arb_div(tol, tol, ten, prec);
    assert_true(arb_lt(w, tol));
    arb_clear(w);
    arb_clear(tol);
    arb_clear(ten);
}

static void run_check(radius_fn fn, const fmpz_poly_t p, const arb_t truth,
                      slong digits)
{
    rs_radius_t r;
    rs_error_t err;
    int rc;
    rs_radius_init(r);
    rs_error_init(err);
    rc = fn(r, p, digits, 0, err);
    if (rc != RS_OK)
        print_message("unexpected error: %s\n", err->msg);
    assert_int_equal(rc, RS_OK);
    assert_int_equal(r->nroots, fmpz_poly_degree(p));
    assert_int_equal(r->digits, digits);
    assert_true(r->prec >= 64);
    /* no runaway precision: a few doublings of the start at most */
    assert_true(r->prec <= 8 * ((slong) (digits * 3.33) + 64));
    check_radius(r, truth, digits);
    rs_radius_clear(r);
}

static const radius_fn all_fns[] = {
    rs_radius_fmpz_poly, rs_radius_fmpz_poly_find_roots,
    rs_radius_fmpz_poly_complex_roots, rs_radius_fmpz_poly_companion
};
#define NFNS ((int) (sizeof(all_fns) / sizeof(all_fns[0])))
static const slong all_digits[] = { 30, 100, 128 };

/* every route, every digit count (companion only at 30 digits above deg 12:
 * its QR step is the slow one). */
static void run_all(const fmpz_poly_t p, void (*truth_fn)(arb_t, slong))
{
    int i, j;
    arb_t truth;
    arb_init(truth);
    for (j = 0; j < 3; j++) {
        truth_fn(truth, truth_prec(all_digits[j]));
        for (i = 0; i < NFNS; i++) {
            if (all_fns[i] == rs_radius_fmpz_poly_companion &&
                fmpz_poly_degree(p) > 12 && all_digits[j] > 30)
                continue;
            run_check(all_fns[i], p, truth, all_digits[j]);
        }
    }
    arb_clear(truth);
}

static void set_quadratic(fmpz_poly_t p, slong a2, slong a1, slong a0)
{
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 2, a2);
    fmpz_poly_set_coeff_si(p, 1, a1);
    fmpz_poly_set_coeff_si(p, 0, a0);
}

/* w = W_P / W_Q, set by each test before run_all */
static slong W_P, W_Q;

static void truth_forward(arb_t t, slong prec)   /* sqrt(q^2+p^2)/q */
{
    arb_set_si(t, W_Q * W_Q + W_P * W_P);
    arb_sqrt(t, t, prec);
    arb_div_si(t, t, W_Q, prec);
}

static void truth_backward(arb_t t, slong prec)  /* q/sqrt(q^2+p^2) */
{
    arb_set_si(t, W_Q * W_Q + W_P * W_P);
    arb_rsqrt(t, t, prec);
    arb_mul_si(t, t, W_Q, prec);
}

static void truth_one(arb_t t, slong prec)
{
    (void) prec;
    arb_one(t);
}

static const slong ws[3][2] = { { 1, 2 }, { 1, 1 }, { 3, 1 } };

static void test_forward_euler(void **state)
{
    fmpz_poly_t p;
    int i;
    (void) state;
    fmpz_poly_init(p);
    for (i = 0; i < 3; i++) {
        W_P = ws[i][0];
        W_Q = ws[i][1];
        set_quadratic(p, W_Q * W_Q, -2 * W_Q * W_Q, W_Q * W_Q + W_P * W_P);
        run_all(p, truth_forward);
    }
    fmpz_poly_clear(p);
}

static void test_backward_euler(void **state)
{
    fmpz_poly_t p;
    int i;
    (void) state;
    fmpz_poly_init(p);
    for (i = 0; i < 3; i++) {
        W_P = ws[i][0];
        W_Q = ws[i][1];
        set_quadratic(p, W_Q * W_Q + W_P * W_P, -2 * W_Q * W_Q, W_Q * W_Q);
        run_all(p, truth_backward);
    }
    fmpz_poly_clear(p);
}

/* rho = 1 exactly: the interval contains 1 and is narrower than 10^-digits;
 * the numeric side can never say "< 1" or "> 1" (the exact side decides). */
static void test_central_difference(void **state)
{
    static const slong cw[3][2] = { { 1, 2 }, { 1, 1 }, { 3, 2 } };
    fmpz_poly_t p;
    int i;
    (void) state;
    fmpz_poly_init(p);
    for (i = 0; i < 3; i++) {
        slong a = cw[i][0], b = cw[i][1];
        set_quadratic(p, b * b, -(2 * b * b - a * a), b * b);
        run_all(p, truth_one);
    }
    fmpz_poly_clear(p);
}

static void truth_half(arb_t t, slong prec)
{
    (void) prec;
    arb_set_d(t, 0.5);
}

/* (3l-1)^2 (2l+1): the double root 1/3 is listed twice with mult 2. */
static void test_double_root(void **state)
{
    fmpz_poly_t p, f;
    rs_radius_t r;
    rs_error_t err;
    slong i, n13 = 0;
    arb_t third;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(f);
    set_quadratic(p, 9, -6, 1);
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 1, 2);
    fmpz_poly_set_coeff_si(f, 0, 1);
    fmpz_poly_mul(p, p, f);
    run_all(p, truth_half);

    rs_radius_init(r);
    rs_error_init(err);
    arb_init(third);
    arb_set_si(third, 1);
    arb_div_si(third, third, 3, 256);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 30, 0, err), RS_OK);
    assert_int_equal(r->nroots, 3);
    assert_true(r->isolated);
    for (i = 0; i < 3; i++) {
        if (arb_contains(acb_realref(r->roots + i), third)) {
            n13++;
            assert_int_equal(r->mult[i], 2);
        } else {
            assert_int_equal(r->mult[i], 1);
        }
    }
    assert_int_equal(n13, 2);
    arb_clear(third);
    rs_radius_clear(r);
    fmpz_poly_clear(f);
    fmpz_poly_clear(p);
}

/* (10^10 l - (10^10 - 1))^6 (2l - 1) */
static void make_cluster(fmpz_poly_t p)
{
    fmpz_poly_t f;
    fmpz_t t;
    fmpz_poly_init(f);
    fmpz_init(t);
    fmpz_set_ui(t, 10);
    fmpz_pow_ui(t, t, 10);
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_fmpz(f, 1, t);
    fmpz_sub_ui(t, t, 1);
    fmpz_neg(t, t);
    fmpz_poly_set_coeff_fmpz(f, 0, t);
    fmpz_poly_pow(p, f, 6);
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 1, 2);
    fmpz_poly_set_coeff_si(f, 0, -1);
    fmpz_poly_mul(p, p, f);
    fmpz_poly_clear(f);
    fmpz_clear(t);
}

static void truth_cluster(arb_t t, slong prec)  /* 1 - 10^-10 */
{
    arb_t e;
    arb_init(e);
    arb_ui_pow_ui(e, 10, 10, prec);
    arb_inv(e, e, prec);
    arb_one(t);
    arb_sub(t, t, e, prec);
    arb_clear(e);
}

static void test_cluster(void **state)
{
    fmpz_poly_t p;
    (void) state;
    fmpz_poly_init(p);
    make_cluster(p);
    run_all(p, truth_cluster);
    fmpz_poly_clear(p);
}

/* What the uncertified GSL baseline really does on the cluster: the
 * sixfold root 1 - 1e-10 splits into a ring of radius ~ (1e-16)^(1/6), so
 * rho_double is wrong at the 1e-3 level (measured: see the assertion). */
static void test_double_baseline_cluster(void **state)
{
    fmpz_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    double truth = 1.0 - 1e-10, e;
    (void) state;
    fmpz_poly_init(p);
    rs_radius_init(r);
    rs_error_init(err);
    make_cluster(p);
    assert_int_equal(rs_radius_double(r, p, err), RS_OK);
    assert_true(r->method_double);
    assert_int_equal(r->method, RS_RADIUS_METHOD_DOUBLE);
    assert_int_equal(r->nroots, 7);
    e = fabs(r->rho_double - truth);
    print_message("double baseline on the cluster: rho = %.17g, error %.3g\n",
                  r->rho_double, e);
    assert_true(e > 1e-6);      /* far off: certified route gives 30 digits */
    assert_true(e < 1e-1);
    /* no certificate claimed */
    assert_true(arb_is_zero(r->lower));
    assert_false(arb_is_finite(r->upper));
    rs_radius_clear(r);
    fmpz_poly_clear(p);
}

/* On the well-conditioned forward Euler the baseline is fine (~1e-15). */
static void test_double_baseline_easy(void **state)
{
    fmpz_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    rs_radius_init(r);
    rs_error_init(err);
    set_quadratic(p, 4, -8, 5);   /* w = 1/2: rho = sqrt(5)/2 */
    assert_int_equal(rs_radius_double(r, p, err), RS_OK);
    assert_true(fabs(r->rho_double - sqrt(5.0) / 2) < 1e-14);
    rs_radius_clear(r);
    fmpz_poly_clear(p);
}

static void truth_tiny(arb_t t, slong prec)  /* 10^-40 */
{
    arb_ui_pow_ui(t, 10, 40, prec);
    arb_inv(t, t, prec);
}

static void test_tiny_roots(void **state)
{
    fmpz_poly_t p;
    fmpz_t c;
    (void) state;
    fmpz_poly_init(p);
    fmpz_init(c);
    fmpz_set_ui(c, 10);
    fmpz_pow_ui(c, c, 80);
    fmpz_poly_set_coeff_fmpz(p, 2, c);
    fmpz_poly_set_coeff_si(p, 0, -1);
    run_all(p, truth_tiny);
    fmpz_clear(c);
    fmpz_poly_clear(p);
}

static void truth_40_41(arb_t t, slong prec)
{
    arb_set_si(t, 40);
    arb_div_si(t, t, 41, prec);
}

/* Wilkinson-like: 40 equispaced real roots k/41, badly conditioned. */
static void test_degree40_equispaced(void **state)
{
    fmpz_poly_t p, f;
    slong k;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(f);
    fmpz_poly_one(p);
    for (k = 1; k <= 40; k++) {
        fmpz_poly_zero(f);
        fmpz_poly_set_coeff_si(f, 1, 41);
        fmpz_poly_set_coeff_si(f, 0, -k);
        fmpz_poly_mul(p, p, f);
    }
    run_all(p, truth_40_41);
    fmpz_poly_clear(f);
    fmpz_poly_clear(p);
}

static void truth_2_19(arb_t t, slong prec)
{
    (void) prec;
    arb_one(t);
    arb_mul_2exp_si(t, t, 19);
}

/* Roots 2^-20 .. 2^19: monic coefficients span 2^-20 .. ~2^190 (checked). */
static void test_degree40_geometric(void **state)
{
    fmpz_poly_t p, f;
    fmpz_t c;
    slong k, lo = WORD_MAX, hi = 0, b;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(f);
    fmpz_init(c);
    fmpz_poly_one(p);
    for (k = 0; k < 40; k++) {
        fmpz_poly_zero(f);
        fmpz_one(c);
        fmpz_mul_2exp(c, c, 20);
        fmpz_poly_set_coeff_fmpz(f, 1, c);
        fmpz_one(c);
        fmpz_mul_2exp(c, c, k);
        fmpz_neg(c, c);
        fmpz_poly_set_coeff_fmpz(f, 0, c);
        fmpz_poly_mul(p, p, f);
    }
    /* coefficient magnitudes of the monic polynomial span > 10^+-30 */
    for (k = 0; k <= 40; k++) {
        b = fmpz_bits(p->coeffs + k);
        if (b < lo) lo = b;
        if (b > hi) hi = b;
    }
    assert_true((double) (hi - lo) * 0.30103 > 60.0);
    run_all(p, truth_2_19);
    fmpz_clear(c);
    fmpz_poly_clear(f);
    fmpz_poly_clear(p);
}

/* lambda^3 (forward Euler w = 1): zero roots kept, exactly 0, mult 3. */
static void test_zero_roots(void **state)
{
    fmpz_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    slong i, nz = 0;
    (void) state;
    fmpz_poly_init(p);
    arb_init(truth);
    rs_radius_init(r);
    rs_error_init(err);
    set_quadratic(p, 1, -2, 2);
    fmpz_poly_shift_left(p, p, 3);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 30, 0, err), RS_OK);
    assert_int_equal(r->nroots, 5);
    for (i = 0; i < r->nroots; i++)
        if (acb_is_zero(r->roots + i)) {
            nz++;
            assert_int_equal(r->mult[i], 3);
        }
    assert_int_equal(nz, 3);
    arb_set_si(truth, 2);
    arb_sqrt(truth, truth, 256);
    check_radius(r, truth, 30);

    /* lambda^4 alone: rho = 0 exactly */
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 4, -7);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 30, 0, err), RS_OK);
    assert_true(arb_is_zero(r->rho));
    assert_true(arb_is_zero(r->upper));
    assert_int_equal(r->nroots, 4);
    rs_radius_clear(r);
    arb_clear(truth);
    fmpz_poly_clear(p);
}

/* The routes return overlapping intervals (they must: all are certified). */
static void test_routes_agree(void **state)
{
    fmpz_poly_t p;
    rs_radius_t r[NFNS];
    rs_error_t err;
    int i, j;
    static const slong c[13] = { 3, -7, 11, 2, -5, 13, -1, 4, 9, -6, 8, -2, 17 };
    (void) state;
    fmpz_poly_init(p);
    rs_error_init(err);
    for (i = 0; i < 13; i++)
        fmpz_poly_set_coeff_si(p, i, c[i]);
    for (i = 0; i < NFNS; i++) {
        rs_radius_init(r[i]);
        assert_int_equal(all_fns[i](r[i], p, 30, 0, err), RS_OK);
        assert_int_equal(r[i]->nroots, 12);
    }
    for (i = 0; i < NFNS; i++)
        for (j = 0; j < NFNS; j++)
            assert_true(arb_overlaps(r[i]->rho, r[j]->rho));
    assert_int_equal(r[1]->method, RS_RADIUS_METHOD_FIND_ROOTS);
    assert_int_equal(r[2]->method, RS_RADIUS_METHOD_COMPLEX_ROOTS);
    assert_int_equal(r[3]->method, RS_RADIUS_METHOD_COMPANION);
    for (i = 0; i < NFNS; i++)
        rs_radius_clear(r[i]);
    fmpz_poly_clear(p);
}

static void test_limit_and_input_errors(void **state)
{
    fmpz_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    (void) state;
    fmpz_poly_init(p);
    rs_radius_init(r);
    rs_error_init(err);
    arb_init(truth);
    set_quadratic(p, 1, -2, 2);   /* rho = sqrt 2 */
    assert_int_equal(rs_radius_fmpz_poly(r, p, 100, 128, err), RS_ERR_LIMIT);
    assert_non_null(strstr(err->msg, "precision limit 128 bits"));
    assert_non_null(strstr(err->msg, "--max-prec"));
    /* still a certified (wider) enclosure */
    assert_true(r->partial);
    arb_set_si(truth, 2);
    arb_sqrt(truth, truth, 512);
    assert_true(arb_contains(r->rho, truth));
    assert_int_equal(rs_radius_fmpz_poly_companion(r, p, 100, 128, err),
                     RS_ERR_LIMIT);

    fmpz_poly_set_si(p, 5);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 30, 0, err), RS_ERR_INPUT);
    assert_int_equal(rs_radius_double(r, p, err), RS_ERR_INPUT);
    set_quadratic(p, 1, -2, 2);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 0, 0, err), RS_ERR_INPUT);
    arb_clear(truth);
    rs_radius_clear(r);
    fmpz_poly_clear(p);
}

static void test_arb_str(void **state)
{
    arb_t x;
    char *s;
    (void) state;
    arb_init(x);
    arb_set_si(x, 2);
    arb_sqrt(x, x, 256);
    s = rs_radius_arb_str(x, 10);
    assert_string_equal(s, "1.414213562");
    flint_free(s);
    arb_clear(x);
}

/* ---- ball coefficients ---- */

static void test_acb_poly_exact_balls(void **state)
{
    acb_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    (void) state;
    acb_poly_init(p);
    rs_radius_init(r);
    rs_error_init(err);
    arb_init(truth);
    /* forward Euler w = 3: l^2 - 2 l + 10, times l^2 */
    acb_poly_set_coeff_si(p, 4, 1);
    acb_poly_set_coeff_si(p, 3, -2);
    acb_poly_set_coeff_si(p, 2, 10);
    assert_int_equal(rs_radius_acb_poly(r, p, 50, 0, err), RS_OK);
    assert_int_equal(r->nroots, 4);
    assert_true(acb_is_zero(r->roots + 0));
    assert_int_equal(r->mult[0], 2);
    arb_set_si(truth, 10);
    arb_sqrt(truth, truth, 512);
    check_radius(r, truth, 50);
    assert_true(r->isolated);
    arb_clear(truth);
    rs_radius_clear(r);
    acb_poly_clear(p);
}

/* Coefficients known to +-1e-60 only: 40 digits are fine, 100 are not. */
static void test_acb_poly_inexact(void **state)
{
    acb_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    mag_t e;
    (void) state;
    acb_poly_init(p);
    rs_radius_init(r);
    rs_error_init(err);
    arb_init(truth);
    mag_init(e);
    /* backward Euler w = 1: 2 l^2 - 2 l + 1, rho = 1/sqrt 2 */
    acb_poly_set_coeff_si(p, 2, 2);
    acb_poly_set_coeff_si(p, 1, -2);
    acb_poly_set_coeff_si(p, 0, 1);
    mag_set_d(e, 1e-60);
    mag_add(arb_radref(acb_realref(p->coeffs + 1)),
            arb_radref(acb_realref(p->coeffs + 1)), e);
    arb_set_si(truth, 2);
    arb_rsqrt(truth, truth, 512);
    assert_int_equal(rs_radius_acb_poly(r, p, 40, 0, err), RS_OK);
    check_radius(r, truth, 40);
    assert_int_equal(rs_radius_acb_poly(r, p, 100, 0, err), RS_ERR_UNDECIDED);
    assert_non_null(strstr(err->msg, "coefficient balls"));
    assert_true(r->partial);
    assert_true(arb_contains(r->rho, truth));
    assert_true(r->prec < 1024);   /* stopped early, not at 65536 bits */
    mag_clear(e);
    arb_clear(truth);
    rs_radius_clear(r);
    acb_poly_clear(p);
}

/* A double root with ball coefficients is never certifiable as simple:
 * (l - 1/2)^2 with +-1e-20 on the constant term.  Undecided, but the
 * reported enclosure still contains 1/2. */
static void test_acb_poly_multiple_root(void **state)
{
    acb_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    mag_t e;
    int rc;
    (void) state;
    acb_poly_init(p);
    rs_radius_init(r);
    rs_error_init(err);
    arb_init(truth);
    mag_init(e);
    acb_poly_set_coeff_si(p, 2, 4);
    acb_poly_set_coeff_si(p, 1, -4);
    acb_poly_set_coeff_si(p, 0, 1);
    mag_set_d(e, 1e-20);
    mag_add(arb_radref(acb_realref(p->coeffs + 0)),
            arb_radref(acb_realref(p->coeffs + 0)), e);
    arb_set_d(truth, 0.5);
    rc = rs_radius_acb_poly(r, p, 30, 0, err);
    print_message("ball double root: rc %d (%s)\n", rc, err->msg);
    assert_int_equal(rc, RS_ERR_UNDECIDED);
    /* confluent-Vandermonde cluster enclosure: ~ sqrt(1e-20 / 4) wide */
    assert_true(mag_cmp_2exp_si(arb_radref(r->rho), -30) < 0);
    assert_true(r->partial);
    assert_true(arb_contains(r->rho, truth));
    assert_true(arb_is_finite(r->upper));
    assert_true(r->prec < 1024);
    /* leading coefficient containing 0 */
    acb_poly_zero(p);
    acb_poly_set_coeff_si(p, 1, 1);
    acb_poly_set_coeff_si(p, 2, 0);
    mag_set_d(e, 1e-3);
    acb_poly_set_coeff_si(p, 2, 0);
    acb_poly_fit_length(p, 3);
    acb_zero(p->coeffs + 2);
    mag_set(arb_radref(acb_realref(p->coeffs + 2)), e);
    _acb_poly_set_length(p, 3);
    assert_int_equal(rs_radius_acb_poly(r, p, 30, 0, err), RS_ERR_UNDECIDED);
    mag_clear(e);
    arb_clear(truth);
    rs_radius_clear(r);
    acb_poly_clear(p);
}

/* Exact ball coefficients with a true double root (2l - 1)^2 (l + 1/4),
 * rho = 1/2.  Never simple; and (known limitation, measured) the cluster
 * certifier (acb_mat_eig_enclosure_rump with a confluent Vandermonde basis,
 * then Arb's eig_multiple_rump) does not contract when the 2-cluster is not
 * the whole spectrum, so the result is RS_ERR_UNDECIDED with the fallback
 * enclosure |det|^(1/3) <= rho <= max|E_i| + eps, which must contain 1/2. */
static void test_acb_poly_exact_double_root(void **state)
{
    acb_poly_t p, f;
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    int rc;
    (void) state;
    acb_poly_init(p);
    acb_poly_init(f);
    rs_radius_init(r);
    rs_error_init(err);
    arb_init(truth);
    acb_poly_set_coeff_si(p, 2, 4);
    acb_poly_set_coeff_si(p, 1, -4);
    acb_poly_set_coeff_si(p, 0, 1);
    acb_poly_set_coeff_si(f, 1, 4);
    acb_poly_set_coeff_si(f, 0, 1);
    acb_poly_mul(p, p, f, 64);
    arb_set_d(truth, 0.5);
    rc = rs_radius_acb_poly(r, p, 30, 512, err);
    if (rc == RS_OK) {            /* would be an improvement: still check */
        assert_false(r->isolated);
        check_radius(r, truth, 30);
    } else {
        assert_int_equal(rc, RS_ERR_UNDECIDED);
        assert_true(r->partial);
        assert_int_equal(r->nroots, 0);
        assert_true(arb_contains(r->rho, truth));
        assert_true(arb_is_finite(r->upper));
    }
    arb_clear(truth);
    rs_radius_clear(r);
    acb_poly_clear(f);
    acb_poly_clear(p);
}

/* ---- matrix recurrences ---- */

static void acb_mat_set_si4(acb_mat_t A, slong a, slong b, slong c, slong d)
{
    acb_set_si(acb_mat_entry(A, 0, 0), a);
    acb_set_si(acb_mat_entry(A, 0, 1), b);
    acb_set_si(acb_mat_entry(A, 1, 0), c);
    acb_set_si(acb_mat_entry(A, 1, 1), d);
}

/* z[n+1] = M z[n], M = [[1,2],[3,4]]: A_1 = I, A_0 = -M.  Eigenvalues
 * (5 +- sqrt 33)/2 (quadratic formula), det(l I - M) = l^2 - 5 l - 2. */
static void test_matrix_first_order(void **state)
{
    acb_mat_struct A[2];
    rs_radius_t r, s;
    rs_error_t err;
    arb_t truth;
    fmpz_poly_t d;
    (void) state;
    acb_mat_init(A + 0, 2, 2);
    acb_mat_init(A + 1, 2, 2);
    rs_radius_init(r);
    rs_radius_init(s);
    rs_error_init(err);
    arb_init(truth);
    fmpz_poly_init(d);
    acb_mat_set_si4(A + 0, -1, -2, -3, -4);
    acb_mat_one(A + 1);
    assert_int_equal(rs_radius_matrix_poly(r, A, 1, 30, 0, err), RS_OK);
    assert_int_equal(r->nroots, 2);
    arb_set_si(truth, 33);
    arb_sqrt(truth, truth, 512);
    arb_add_si(truth, truth, 5, 512);
    arb_mul_2exp_si(truth, truth, -1);
    check_radius(r, truth, 30);
    set_quadratic(d, 1, -5, -2);
    assert_int_equal(rs_radius_fmpz_poly(s, d, 30, 0, err), RS_OK);
    assert_true(arb_overlaps(r->rho, s->rho));
    fmpz_poly_clear(d);
    arb_clear(truth);
    rs_radius_clear(s);
    rs_radius_clear(r);
    acb_mat_clear(A + 1);
    acb_mat_clear(A + 0);
}

/* Second order: A2 l^2 + A1 l + A0 with a non-identity A2; compared with
 * the radius of det(A2 l^2 + A1 l + A0) formed with fmpz_poly arithmetic
 * (independent of the block companion construction). */
static void test_matrix_second_order(void **state)
{
    static const slong a[3][4] = { { 1, -1, 2, 3 }, { 0, 1, -5, 2 },
                                   { 3, 1, 0, 2 } };
    acb_mat_struct A[3];
    fmpz_poly_t e[4], t, u, d;
    rs_radius_t r, s;
    rs_error_t err;
    slong j, i;
    (void) state;
    rs_radius_init(r);
    rs_radius_init(s);
    rs_error_init(err);
    fmpz_poly_init(t);
    fmpz_poly_init(u);
    fmpz_poly_init(d);
    for (i = 0; i < 4; i++)
        fmpz_poly_init(e[i]);
    for (j = 0; j < 3; j++) {
        acb_mat_init(A + j, 2, 2);
        acb_mat_set_si4(A + j, a[j][0], a[j][1], a[j][2], a[j][3]);
        for (i = 0; i < 4; i++)
            fmpz_poly_set_coeff_si(e[i], j, a[j][i]);
    }
    fmpz_poly_mul(t, e[0], e[3]);
    fmpz_poly_mul(u, e[1], e[2]);
    fmpz_poly_sub(d, t, u);
    assert_int_equal(fmpz_poly_degree(d), 4);
    assert_int_equal(rs_radius_matrix_poly(r, A, 2, 30, 0, err), RS_OK);
    assert_int_equal(r->nroots, 4);
    assert_int_equal(rs_radius_fmpz_poly(s, d, 60, 0, err), RS_OK);
    /* s is much narrower: use it as the reference */
    check_radius(r, s->rho, 30);
    assert_true(arb_overlaps(r->rho, s->rho));

    /* singular leading matrix */
    acb_mat_set_si4(A + 2, 1, 2, 2, 4);
    assert_int_equal(rs_radius_matrix_poly(r, A, 2, 30, 0, err), RS_ERR_MATH);
    assert_non_null(strstr(err->msg, "singular"));
    assert_int_equal(rs_radius_matrix_poly(r, A, 0, 30, 0, err), RS_ERR_INPUT);

    for (j = 0; j < 3; j++)
        acb_mat_clear(A + j);
    for (i = 0; i < 4; i++)
        fmpz_poly_clear(e[i]);
    fmpz_poly_clear(t);
    fmpz_poly_clear(u);
    fmpz_poly_clear(d);
    rs_radius_clear(s);
    rs_radius_clear(r);
}

/* A dense degree-12 integer polynomial to 30 digits: the size the
 * performance target names.  Its time is measured in bench/ (bench_radius,
 * bench_accuracy.sh), not asserted here. */
static void test_dense_degree12(void **state)
{
    static const slong c[13] = { 3, -7, 11, 2, -5, 13, -1, 4, 9, -6, 8, -2, 17 };
    fmpz_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    int i;
    (void) state;
    fmpz_poly_init(p);
    rs_radius_init(r);
    rs_error_init(err);
    for (i = 0; i < 13; i++)
        fmpz_poly_set_coeff_si(p, i, c[i]);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 30, 0, err), RS_OK);
    rs_radius_clear(r);
    fmpz_poly_clear(p);
}

/* lambda^n - c: every root has modulus c^(1/n) (closed form), the n roots
 * c^(1/n) e^(2 pi i k/n) are spaced 2 c^(1/n) sin(pi/n) apart. */
static void test_aberth_binomial(void **state)
{
    static const slong nc[3][2] = { { 7, 3 }, { 150, 2 }, { 500, 5 } };
    int t;
    (void) state;
    for (t = 0; t < 3; t++) {
        slong n = nc[t][0], i, j;
        double *a = flint_calloc(n + 1, sizeof(double));
        double *z = flint_malloc(2 * n * sizeof(double));
        double rho = pow((double) nc[t][1], 1.0 / (double) n);
        double gap = 2 * rho * sin(3.141592653589793 / (double) n);
        a[0] = -(double) nc[t][1];
        a[n] = 1;
        assert_true(rs_radius_aberth_d(z, a, n, 100) >= 0);
        for (i = 0; i < n; i++) {
            assert_true(fabs(hypot(z[2 * i], z[2 * i + 1]) - rho) <= 1e-12 * rho);
            for (j = 0; j < i; j++) /* n distinct roots: each found once */
                assert_true(hypot(z[2 * i] - z[2 * j], z[2 * i + 1] - z[2 * j + 1]) > gap / 2);
        }
        flint_free(a);
        flint_free(z);
    }
}

/* lambda^200 - 3 and lambda^300 - 1/2 scaled (2 lambda^300 - 1): radius
 * 3^(1/200), 2^(-1/300) (closed forms, arb_root_ui), at 30 and 128 digits
 * (the second at 30 only) through the Aberth-seeded default route. */
static void test_high_degree_binomial(void **state)
{
    fmpz_poly_t p;
    arb_t truth;
    slong digits[2] = { 30, 128 }, k;
    (void) state;
    fmpz_poly_init(p);
    arb_init(truth);
    for (k = 0; k < 2; k++) {
        slong prec = truth_prec(digits[k]);
        fmpz_poly_zero(p);
        fmpz_poly_set_coeff_si(p, 0, -3);
        fmpz_poly_set_coeff_si(p, 200, 1);
        arb_set_ui(truth, 3);
        arb_root_ui(truth, truth, 200, prec);
        run_check(rs_radius_fmpz_poly, p, truth, digits[k]);
        if (k > 0) /* 128 digits at degree 300: a second, keep check fast */
            continue;
        fmpz_poly_zero(p);
        fmpz_poly_set_coeff_si(p, 0, -1);
        fmpz_poly_set_coeff_si(p, 300, 2);
        arb_set_ui(truth, 2);
        arb_root_ui(truth, truth, 300, prec);
        arb_inv(truth, truth, prec);
        run_check(rs_radius_fmpz_poly, p, truth, digits[k]);
    }
    arb_clear(truth);
    fmpz_poly_clear(p);
}

/* Degree 100, coefficients drawn uniformly from [-100, 100]
 * (bench/radius_highdeg.sh, mawk 1.3.4 srand(100)), c_0 first.  Reference radius
 * from mpmath 1.3.0 at 60 digits:
 *   mpmath.mp.dps = 60; r = mpmath.polyroots(c[::-1], maxsteps=400,
 *   extraprec=400); mpmath.nstr(max(abs(z) for z in r), 45)
 * = 1.27236328894060322414207260929988041492729486 (45 digits, +-1 in the
 * last); checked at 40 digits.  The same mpmath roots give the count: 60
 * of modulus < 1, 40 > 1 (the nearest modulus 8.98e-4 from 1:
 * sum(abs(z) < 1 for z in r), min(abs(abs(z) - 1) for z in r)); the three
 * high-degree counts are checked against it: the certified balls
 * (rs_radius_count_balls), Schur-Cohn by the minors modulo primes
 * (rs_jury_count_fmpz_poly, degree > 32) and Routh's integer PRS. */
static void test_random_degree100(void **state)
{
    static const slong c[101] = {
        -37,-43,-52,-3,-25,-90,14,94,3,-14,-18,-70,17,26,23,-18,-79,75,-47,24,34
        ,-29,-59,7,-23,69,77,-8,30,55,-1,94,-89,48,-10,-13,58,-96,-19,-39,-10,63
        ,-9,-93,-11,-86,-10,10,89,43,-66,23,-86,-24,-71,-9,-55,-94,84,75,61,-18,
        69,72,-70,-42,-42,89,-38,39,-51,53,2,41,60,91,55,-51,0,43,92,35,-35,-95,
        -90,-5,-3,-45,1,-20,-70,-39,63,99,-67,93,-43,-8,81,19,-69
    };
    fmpz_poly_t p;
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    int i;
    (void) state;
    fmpz_poly_init(p);
    arb_init(truth);
    rs_radius_init(r);
    rs_error_init(err);
    for (i = 0; i <= 100; i++)
        fmpz_poly_set_coeff_si(p, i, c[i]);
    arb_set_str(truth, "1.27236328894060322414207260929988041492729486 +/- 2e-44", 200);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 40, 0, err), RS_OK);
    /* 40 digits at degree 100: only the outermost roots were refined
     * (rs_radius_outer_refine), the rest certified at about 60 bits */
    assert_true(r->nouter >= 1 && r->nouter < 25);
    assert_true(arb_overlaps(r->rho, truth));
    assert_true(arb_le(r->lower, r->upper));
    /* the certified interval is 40 digits wide at most and meets the
     * reference ball */
    assert_true(!arb_lt(r->upper, truth) && !arb_gt(r->lower, truth));
    {
        slong in, out;
        rs_jury_t j;
        rs_rootcount_t rc;
        assert_int_equal(rs_radius_count_balls(&in, &out, r, 100), 1);
        assert_int_equal(in, 60);
        assert_int_equal(out, 40);
        rs_jury_init(j);
        assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
        assert_int_equal(j->route, RS_JURY_ROUTE_MODULAR);
        assert_int_equal(j->count->inside, 60);
        assert_int_equal(j->count->outside, 40);
        rs_jury_clear(j);
        rs_rootcount_init(rc);
        assert_int_equal(rs_routh_int_count(rc, p, err), RS_OK);
        assert_int_equal(rc->inside, 60);
        assert_int_equal(rc->outside, 40);
        rs_rootcount_clear(rc);
    }
    rs_radius_clear(r);
    arb_clear(truth);
    fmpz_poly_clear(p);
}

/* rs_radius_count_balls on certified radii at degree 80: 2 lambda^80 - 1
 * has every root at 2^(-1/80) < 1 (closed form): 80 inside; lambda^80 - 3
 * at 3^(1/80) > 1: 80 outside; (lambda^80 - 3)(lambda - 1) has the root 1
 * on the circle, whose (exact, point) ball meets it: no count. */
static void test_count_balls(void **state)
{
    fmpz_poly_t p, f;
    rs_radius_t r;
    slong in, out;
    rs_error_t err;
    int k;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(f);
    rs_radius_init(r);
    rs_error_init(err);
    for (k = 0; k < 2; k++) {
        /* {c_0, c_80, inside}: 2 l^80 - 1, then l^80 - 3 */
        static const slong t[2][3] = { { -1, 2, 80 }, { -3, 1, 0 } };
        fmpz_poly_set_coeff_si(p, 0, t[k][0]);
        fmpz_poly_set_coeff_si(p, 80, t[k][1]);
        assert_int_equal(rs_radius_fmpz_poly(r, p, 15, 0, err), RS_OK);
        assert_int_equal(rs_radius_count_balls(&in, &out, r, 80), 1);
        assert_int_equal(in, t[k][2]);
        assert_int_equal(out, 80 - t[k][2]);
    }
    assert_int_equal(rs_radius_count_balls(&in, &out, r, 81), 0);   /* wrong degree */
    fmpz_poly_set_coeff_si(f, 0, -1);
    fmpz_poly_set_coeff_si(f, 1, 1);
    fmpz_poly_mul(p, p, f);
    assert_int_equal(rs_radius_fmpz_poly(r, p, 15, 0, err), RS_OK);
    assert_int_equal(rs_radius_count_balls(&in, &out, r, 81), 0);
    rs_radius_clear(r);
    fmpz_poly_clear(p);
    fmpz_poly_clear(f);
}

/* rs_radius_schur_count: the Schur-Cohn table in balls.  Expected counts
 * from closed forms (the roots are the factors' roots, by hand):
 * - Wilkinson-type prod_{k=1..70} (71 x - k): roots k/71, all 70 inside;
 *   its 280-bit coefficients need precision beyond the start (the loss
 *   grows along the rows), so the extrapolation step runs;
 * - (2x - 1)^20 (x - 3)^10 (x + 2)^5 (5x + 4): 21 inside (1/2 twenty times
 *   and -4/5), 15 outside; repeated roots off the circle leave the table
 *   regular;
 * - x (x - 2) (3x - 1)^2: 3 inside (0, 1/3 twice), 1 outside: p(0) = 0;
 * and the ones it must leave to the exact side: x^66 - 1 (circle roots:
 * the first row is zero), (x - 2)(2x - 1)(3x + 1) (the pair 2, 1/2 makes
 * gcd(p, p*) non-trivial, so some constant term is exactly 0).  Then 6
 * random polynomials of degree 65-90 (coefficients in [-2^20, 2^20],
 * flint_rand): the count equals the exact one of rs_jury_count_fmpz_poly
 * (modular minors or integer table), an independent exact method.  A flipped
 * Rouche rule (in = in instead of m - in) fails the first two cases. */
static void test_schur_count(void **state)
{
    fmpz_poly_t p, f;
    rs_error_t err;
    slong in = -1, bits = 0, k, t;
    int dec;
    flint_rand_t st;
    rs_jury_t ju;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(f);
    rs_error_init(err);
    fmpz_poly_one(p);
    for (k = 1; k <= 70; k++) {
        fmpz_poly_set_coeff_si(f, 1, 71);
        fmpz_poly_set_coeff_si(f, 0, -k);
        fmpz_poly_mul(p, p, f);
    }
    assert_int_equal(rs_radius_schur_count(&dec, &in, &bits, p, 1 << 16, err), RS_OK);
    assert_int_equal(dec, 1);
    assert_int_equal(in, 70);
    assert_true(bits > 128);
    /* max_prec below the start: nothing tried, undecided */
    assert_int_equal(rs_radius_schur_count(&dec, &in, &bits, p, 100, err), RS_OK);
    assert_int_equal(dec, 0);

    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 1, 2);
    fmpz_poly_set_coeff_si(f, 0, -1);
    fmpz_poly_pow(p, f, 20);
    fmpz_poly_set_coeff_si(f, 1, 1);
    fmpz_poly_set_coeff_si(f, 0, -3);
    fmpz_poly_pow(f, f, 10);
    fmpz_poly_mul(p, p, f);
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 1, 1);
    fmpz_poly_set_coeff_si(f, 0, 2);
    fmpz_poly_pow(f, f, 5);
    fmpz_poly_mul(p, p, f);
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 1, 5);
    fmpz_poly_set_coeff_si(f, 0, 4);
    fmpz_poly_mul(p, p, f);
    assert_int_equal(rs_radius_schur_count(&dec, &in, &bits, p, 1 << 16, err), RS_OK);
    assert_int_equal(dec, 1);
    assert_int_equal(in, 21);

    /* x (x - 2) (3x - 1)^2 = 9x^4 - 24x^3 + 13x^2 - 2x */
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 4, 9);
    fmpz_poly_set_coeff_si(p, 3, -24);
    fmpz_poly_set_coeff_si(p, 2, 13);
    fmpz_poly_set_coeff_si(p, 1, -2);
    assert_int_equal(rs_radius_schur_count(&dec, &in, &bits, p, 1 << 12, err), RS_OK);
    assert_int_equal(dec, 1);
    assert_int_equal(in, 3);

    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 66, 1);
    fmpz_poly_set_coeff_si(p, 0, -1);
    assert_int_equal(rs_radius_schur_count(&dec, &in, &bits, p, 1 << 12, err), RS_OK);
    assert_int_equal(dec, 0);
    /* (x - 2)(2x - 1)(3x + 1) = 6x^3 - 13x^2 + x + 2 */
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 3, 6);
    fmpz_poly_set_coeff_si(p, 2, -13);
    fmpz_poly_set_coeff_si(p, 1, 1);
    fmpz_poly_set_coeff_si(p, 0, 2);
    assert_int_equal(rs_radius_schur_count(&dec, &in, &bits, p, 1 << 12, err), RS_OK);
    assert_int_equal(dec, 0);

    flint_randinit(st);
    for (t = 0; t < 6; t++) {
        slong n = 65 + 5 * t;
        fmpz_poly_zero(p);
        for (k = 0; k <= n; k++)
            fmpz_poly_set_coeff_si(p, k, (slong) n_randint(st, (UWORD(1) << 21) + 1) - (WORD(1) << 20));
        if (fmpz_is_zero(p->coeffs + n) || fmpz_poly_degree(p) != n)
            fmpz_poly_set_coeff_si(p, n, 1);
        assert_int_equal(rs_radius_schur_count(&dec, &in, &bits, p, 1 << 14, err), RS_OK);
        assert_int_equal(dec, 1);
        rs_jury_init(ju);
        assert_int_equal(rs_jury_count_fmpz_poly(ju, p, err), RS_OK);
        assert_int_equal(ju->count->on, 0);
        assert_int_equal(in, ju->count->inside);
        rs_jury_clear(ju);
    }
    flint_randclear(st);
    fmpz_poly_clear(p);
    fmpz_poly_clear(f);
}

/* rs_radius_aberth_certify itself (the first route), from the double seeds
 * of rs_radius_aberth_d, on the rows issue 18 found slow:
 * - a tight cluster: (10^12 (10x - 9)^4 - 1)(10^6 x^70 - 1), degree 74.
 *   Closed form: (10x - 9)^4 = 10^-12 gives x = 9/10 + 10^-4 w, w^4 = 1, so
 *   the largest modulus is 9/10 + 10^-4 = 9001/10000 (|9/10 +- 10^-4 i| is
 *   smaller), and 10^(-6/70) = 0.8209... < 0.9001 for the other 70 roots;
 * - Wilkinson-type prod_{k=1..40} (41 x - k): rho = 40/41 (closed form);
 * - 2 x^500 - 1: rho = 2^(-1/500) (closed form), sparse evaluation.
 * Each at 30 and 128 digits: certified (returns 1), rho from the balls
 * contains the closed form and is as narrow as asked. */
static void check_certify(const fmpz_poly_t p, const arb_t truth, slong digits)
{
    slong d = fmpz_poly_degree(p), i, w = 0, no = -1;
    slong prec = (slong) (digits * 3.3219280948873623) + 32;
    double *a = flint_malloc((d + 1) * sizeof(double));
    double *z = flint_malloc(2 * d * sizeof(double));
    acb_ptr E = _acb_vec_init(d);
    arb_t rho, t;
    arb_init(rho);
    arb_init(t);
    for (i = 0; i <= d; i++)
        a[i] = fmpz_get_d(p->coeffs + i);
    rs_radius_aberth_d(z, a, d, 100);   /* seeds, converged or not */
    assert_int_equal(rs_radius_aberth_certify(E, &w, &no, p, a, z, prec, d > 64 ? 64 : 0), 1);
    assert_true(w >= prec);
    arb_zero(rho);
    for (i = 0; i < d; i++) {
        acb_abs(t, E + i, w);
        arb_max(rho, rho, t, w);
    }
    assert_true(arb_contains(rho, truth));
    assert_true(arb_rel_accuracy_bits(rho) >= (slong) (digits * 3.32));
    _acb_vec_clear(E, d);
    arb_clear(rho);
    arb_clear(t);
    flint_free(a);
    flint_free(z);
}

static void test_aberth_certify_hard(void **state)
{
    fmpz_poly_t p, q;
    arb_t truth;
    slong digits[2] = { 30, 128 }, k, j;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(q);
    arb_init(truth);
    for (k = 0; k < 2; k++) {
        slong prec = truth_prec(digits[k]);
        /* cluster: (10^12 (10x - 9)^4 - 1)(10^6 x^70 - 1) */
        fmpz_poly_zero(p);
        fmpz_poly_set_coeff_si(p, 0, -9);
        fmpz_poly_set_coeff_si(p, 1, 10);
        fmpz_poly_pow(p, p, 4);
        fmpz_poly_scalar_mul_ui(p, p, 1000000);
        fmpz_poly_scalar_mul_ui(p, p, 1000000);
        fmpz_poly_zero(q);
        fmpz_poly_set_coeff_si(q, 0, -1);
        fmpz_poly_add(p, p, q);   /* p - 1: q = -1 */
        fmpz_poly_set_coeff_si(q, 70, 1000000);
        fmpz_poly_mul(p, p, q);
        arb_set_ui(truth, 9001);
        arb_div_ui(truth, truth, 10000, prec);
        check_certify(p, truth, digits[k]);
        /* Wilkinson-type, degree 40 */
        fmpz_poly_one(p);
        for (j = 1; j <= 40; j++) {
            fmpz_poly_zero(q);
            fmpz_poly_set_coeff_si(q, 0, -j);
            fmpz_poly_set_coeff_si(q, 1, 41);
            fmpz_poly_mul(p, p, q);
        }
        arb_set_ui(truth, 40);
        arb_div_ui(truth, truth, 41, prec);
        check_certify(p, truth, digits[k]);
        /* 2 x^500 - 1 */
        fmpz_poly_zero(p);
        fmpz_poly_set_coeff_si(p, 0, -1);
        fmpz_poly_set_coeff_si(p, 500, 2);
        arb_set_ui(truth, 2);
        arb_root_ui(truth, truth, 500, prec);
        arb_inv(truth, truth, prec);
        check_certify(p, truth, digits[k]);
    }
    arb_clear(truth);
    fmpz_poly_clear(p);
    fmpz_poly_clear(q);
}

static int cmp_double(const void *x, const void *y)
{
    double u = *(const double *) x, v = *(const double *) y;
    return (u > v) - (u < v);
}

/* Wilkinson-type prod_{k=1..160} (161 x - k): roots k/161 (closed form),
 * rho = 160/161.  Its coefficients reach 2^1173, beyond double: a is f
 * scaled by 2^-(maxbits - 1000) as _rs_radius_to_double does.  The double
 * Aberth seeds have no correct digit (the roots lose 300+ bits); the
 * secular-equation pass must bring every seed within 2^-40 of its own
 * k/161 (sorted real parts against k = 1..160, imaginary parts below
 * 2^-40), and the whole radius at 30 and 128 digits must contain 160/161
 * (before the pass this degree took minutes: Aberth on Arb from the double
 * seeds ran out of sweeps and acb_poly_find_roots took over).  A
 * well-conditioned polynomial (2 x^80 - 1) is left alone: 0, seeds
 * unchanged. */
static void test_wilkinson_secular(void **state)
{
    const slong d = 160;
    fmpz_poly_t p, q;
    double *a = flint_malloc((d + 1) * sizeof(double));
    double *z = flint_malloc(2 * d * sizeof(double));
    double *z0 = flint_malloc(2 * d * sizeof(double));
    double *re = flint_malloc(d * sizeof(double));
    slong k, e, shift, dig[2] = { 30, 128 };
    rs_radius_t r;
    rs_error_t err;
    arb_t truth;
    int rounds;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(q);
    arb_init(truth);
    rs_radius_init(r);
    fmpz_poly_one(p);
    for (k = 1; k <= d; k++) {
        fmpz_poly_zero(q);
        fmpz_poly_set_coeff_si(q, 0, -k);
        fmpz_poly_set_coeff_si(q, 1, d + 1);
        fmpz_poly_mul(p, p, q);
    }
    shift = FLINT_ABS(fmpz_poly_max_bits(p)) - 1000;
    assert_true(shift > 0);
    for (k = 0; k <= d; k++) {
        double m = fmpz_get_d_2exp(&e, p->coeffs + k);
        a[k] = ldexp(m, (int) (e - shift));
    }
    rs_radius_aberth_d(z, a, d, 100);
    rounds = rs_radius_aberth_secular(z, p, a, 64);
    assert_true(rounds >= 1 && rounds <= 64);
    for (k = 0; k < d; k++) {
        re[k] = z[2 * k];
        assert_true(fabs(z[2 * k + 1]) < ldexp(1.0, -40));
    }
    qsort(re, (size_t) d, sizeof(double), cmp_double);
    for (k = 0; k < d; k++)
        assert_true(fabs(re[k] - (double) (k + 1) / (double) (d + 1)) < ldexp(1.0, -40));
    for (k = 0; k < 2; k++) {
        assert_int_equal(rs_radius_fmpz_poly(r, p, dig[k], 0, err), RS_OK);
        arb_set_ui(truth, (ulong) d);
        arb_div_ui(truth, truth, (ulong) d + 1, truth_prec(dig[k]));
        assert_true(arb_contains(r->rho, truth));
        assert_true(arb_rel_accuracy_bits(r->rho) >= (slong) (dig[k] * 3.32));
    }
    /* 2 x^80 - 1: seeds already good, nothing done */
    for (k = 0; k <= 80; k++)
        a[k] = 0.0;
    a[0] = -1.0;
    a[80] = 2.0;
    fmpz_poly_zero(q);
    fmpz_poly_set_coeff_si(q, 0, -1);
    fmpz_poly_set_coeff_si(q, 80, 2);
    rs_radius_aberth_d(z, a, 80, 100);
    memcpy(z0, z, 160 * sizeof(double));
    assert_int_equal(rs_radius_aberth_secular(z, q, a, 64), 0);
    assert_memory_equal(z, z0, 160 * sizeof(double));
    rs_radius_clear(r);
    arb_clear(truth);
    fmpz_poly_clear(p);
    fmpz_poly_clear(q);
    flint_free(a);
    flint_free(z);
    flint_free(z0);
    flint_free(re);
}

/* rs_radius_horner2 against the exact value: p = (x - 1)^3 (x^2 + 1) at
 * x = 3/4 + i/8 (exact dyadic), p and p' from the factored form in exact
 * rational arithmetic (Arb at 2000 bits: exact here); the balls at 64 bits
 * must contain them, and be narrow (the disc bound, 2^-50 relative). */
static void test_horner2(void **state)
{
    fmpz_poly_t p, q;
    acb_poly_t P;
    acb_t x, y, dy, t, u, v;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(q);
    acb_poly_init(P);
    acb_init(x); acb_init(y); acb_init(dy); acb_init(t); acb_init(u); acb_init(v);
    fmpz_poly_set_coeff_si(p, 0, -1);
    fmpz_poly_set_coeff_si(p, 1, 1);
    fmpz_poly_pow(p, p, 3);
    fmpz_poly_set_coeff_si(q, 0, 1);
    fmpz_poly_set_coeff_si(q, 2, 1);
    fmpz_poly_mul(p, p, q);
    acb_poly_set_fmpz_poly(P, p, 64);
    acb_set_d_d(x, 0.75, 0.125);
    rs_radius_horner2(y, dy, P->coeffs, 6, x, 64);
    /* exact: (x-1)^3 (x^2+1) and 3 (x-1)^2 (x^2+1) + 2x (x-1)^3 */
    acb_sub_ui(t, x, 1, 2000);
    acb_mul(u, x, x, 2000);
    acb_add_ui(u, u, 1, 2000);
    acb_pow_ui(v, t, 3, 2000);
    acb_mul(v, v, u, 2000);
    assert_true(acb_contains(y, v));
    acb_pow_ui(v, t, 2, 2000);
    acb_mul(v, v, u, 2000);
    acb_mul_ui(v, v, 3, 2000);
    acb_pow_ui(u, t, 3, 2000);
    acb_mul(u, u, x, 2000);
    acb_mul_2exp_si(u, u, 1);
    acb_add(v, v, u, 2000);
    assert_true(acb_contains(dy, v));
    assert_true(acb_rel_accuracy_bits(y) >= 50 && acb_rel_accuracy_bits(dy) >= 50);
    acb_clear(x); acb_clear(y); acb_clear(dy); acb_clear(t); acb_clear(u); acb_clear(v);
    acb_poly_clear(P);
    fmpz_poly_clear(p);
    fmpz_poly_clear(q);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forward_euler),
        cmocka_unit_test(test_backward_euler),
        cmocka_unit_test(test_central_difference),
        cmocka_unit_test(test_double_root),
        cmocka_unit_test(test_cluster),
        cmocka_unit_test(test_double_baseline_cluster),
        cmocka_unit_test(test_double_baseline_easy),
        cmocka_unit_test(test_tiny_roots),
        cmocka_unit_test(test_degree40_equispaced),
        cmocka_unit_test(test_degree40_geometric),
        cmocka_unit_test(test_zero_roots),
        cmocka_unit_test(test_routes_agree),
        cmocka_unit_test(test_limit_and_input_errors),
        cmocka_unit_test(test_arb_str),
        cmocka_unit_test(test_acb_poly_exact_balls),
        cmocka_unit_test(test_acb_poly_inexact),
        cmocka_unit_test(test_acb_poly_multiple_root),
        cmocka_unit_test(test_acb_poly_exact_double_root),
        cmocka_unit_test(test_matrix_first_order),
        cmocka_unit_test(test_matrix_second_order),
        cmocka_unit_test(test_dense_degree12),
        cmocka_unit_test(test_aberth_binomial),
        cmocka_unit_test(test_high_degree_binomial),
        cmocka_unit_test(test_random_degree100),
        cmocka_unit_test(test_count_balls),
        cmocka_unit_test(test_schur_count),
        cmocka_unit_test(test_aberth_certify_hard),
        cmocka_unit_test(test_wilkinson_secular),
        cmocka_unit_test(test_horner2),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
