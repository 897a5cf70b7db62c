/* test_dblstr.c -- directed decimal strings of doubles without MPFR
 * (util/dblstr.h, issue 14 part 3).  Checked against MPFR's directed
 * conversion (mpfr_get_str, RNDD / RNDU / RNDN, the route of
 * numeric/radius.c) on 10^5 random intervals [lo, hi] and on hand-picked
 * edge cases (exact decimals, ties, decade boundaries):
 *   - rs_dblstr_round(lo, 17, down) and (hi, 17, up) print the same digits
 *     as MPFR, and the printed decimals, parsed back as exact rationals,
 *     are <= lo and >= hi, and one unit of the last digit further would not be;
 *   - rs_dblstr_interval(lo, hi, 17) prints the digits MPFR's nearest
 *     rounding of lo and hi agree on (same digit count rule as radius.c),
 *     and both lo and hi lie within half a unit of its last digit;
 *   - the formatting is the one of a formatter written here independently;
 *   - rs_dblstr_bounds (the three map cells from two conversions) prints
 *     the same three strings as the functions checked above.
 * The MPFR reference and the rational checks are this file's own code. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>
#include <mpfr.h>
#include <flint/fmpq.h>
#include <arf.h>
#include <arb.h>
#include "recstab/radius.h"
#include "util/dblstr.h"

/* ---- the independent reference ------------------------------------------ */

/* MPFR's n digits of x in rnd: digits (no sign) into D, exponent: 0.D 10^e */
static long ref_digits(char *D, int *neg, double x, int n, mpfr_rnd_t rnd)
{
    mpfr_t m;
    mpfr_exp_t e;
    char *s;
    mpfr_init2(m, 53);
    mpfr_set_d(m, x, MPFR_RNDN);   /* exact */
    s = mpfr_get_str(NULL, &e, 10, (size_t) n, m, rnd);
    *neg = s[0] == '-';
    strcpy(D, s + *neg);
    mpfr_free_str(s);
    mpfr_clear(m);
    return (long) e;
}

/* the printed form: fixed for -4 <= e <= k (value 0.D 10^e), else d.dde+X */
static void ref_format(char *out, int neg, const char *D0, long e, int trim)
{
    char D[64], digits[128];
    long k;
    strcpy(D, D0);
    k = (long) strlen(D);
    if (trim)
        while (k > 1 && D[k - 1] == '0') D[--k] = '\0';
    if (e >= -4 && e <= k) {
        if (e <= 0) snprintf(digits, sizeof digits, "0.%.*s%s", (int) -e, "0000", D);
        else if (e == k) snprintf(digits, sizeof digits, "%s", D);
        else snprintf(digits, sizeof digits, "%.*s.%s", (int) e, D, D + e);
    } else if (k > 1) snprintf(digits, sizeof digits, "%c.%se%+ld", D[0], D + 1, e - 1);
    else snprintf(digits, sizeof digits, "%ce%+ld", D[0], e - 1);
    sprintf(out, "%s%s", neg ? "-" : "", digits);
}

/* radius.c's rs_radius_arf_str by MPFR alone (FLOOR / CEIL / NEAR) */
static void ref_round(char *out, double x, int n, int dir)
{
    char Dd[64], Du[64], Dn[64];
    int neg, negu, negn;
    long ed = ref_digits(Dd, &neg, x, n, MPFR_RNDD), eu = ref_digits(Du, &negu, x, n, MPFR_RNDU);
    int exact = ed == eu && strcmp(Dd, Du) == 0;
    if (exact || dir < 0) ref_format(out, neg, Dd, ed, exact);
    else if (dir > 0) ref_format(out, negu, Du, eu, 0);
    else {
        long en = ref_digits(Dn, &negn, x, n, MPFR_RNDN);
        ref_format(out, negn, Dn, en, 0);
    }
}

/* radius.c's digit count of [lo, hi] (_rs_str_agree): from k0 down, the
 * first k at which MPFR's nearest roundings of lo and hi agree; 0 if none */
static int ref_agree(double lo, double hi, int n)
{
    arf_t a, b, w;
    long k, k0;
    arf_init(a);
    arf_init(b);
    arf_init(w);
    arf_set_d(a, lo);
    arf_set_d(b, hi);
    arf_sub(w, b, a, ARF_PREC_EXACT, ARF_RND_DOWN);
    if (arf_is_zero(w)) k0 = n;
    else k0 = (long) ((double) (arf_abs_bound_lt_2exp_si(a) - arf_abs_bound_lt_2exp_si(w)) * 0.30103) + 3;
    arf_clear(a);
    arf_clear(b);
    arf_clear(w);
    k0 = k0 < 1 ? 1 : k0 > n ? n : k0;
    for (k = k0; k >= 1; k--) {
        char D1[64], D2[64];
        int n1, n2;
        long e1 = ref_digits(D1, &n1, lo, (int) k, MPFR_RNDN), e2 = ref_digits(D2, &n2, hi, (int) k, MPFR_RNDN);
        if (e1 == e2 && n1 == n2 && strcmp(D1, D2) == 0) return (int) k;
    }
    return 0;
}

/* s as an exact rational q and its last digit's unit u (s plain decimal) */
static void dec_parse(fmpq_t q, fmpq_t u, const char *s)
{
    fmpz_t m, t;
    long frac = 0, ex = 0;
    int neg = 0, seen = 0;
    fmpz_init(m);
    fmpz_init(t);
    if (*s == '-') { neg = 1; s++; }
    for (; *s && *s != 'e'; s++) {
        if (*s == '.') { seen = 1; continue; }
        fmpz_mul_ui(m, m, 10);
        fmpz_add_ui(m, m, (ulong) (*s - '0'));
        if (seen) frac++;
    }
    if (*s == 'e') ex = strtol(s + 1, NULL, 10);
    ex -= frac;
    if (neg) fmpz_neg(m, m);
    fmpz_ui_pow_ui(t, 10, (ulong) (ex >= 0 ? ex : -ex));
    fmpq_one(u);
    if (ex >= 0) fmpz_set(fmpq_numref(u), t);
    else fmpz_set(fmpq_denref(u), t);
    fmpq_mul_fmpz(q, u, m);
    fmpz_clear(m);
    fmpz_clear(t);
}

static void dbl_fmpq(fmpq_t q, double x)
{
    arf_t a;
    fmpz_t m, e;
    arf_init(a);
    fmpz_init(m);
    fmpz_init(e);
    arf_set_d(a, x);
    arf_get_fmpz_2exp(m, e, a);
    fmpz_set(fmpq_numref(q), m);
    fmpz_one(fmpq_denref(q));
    if (fmpz_sgn(e) >= 0) fmpq_mul_2exp(q, q, fmpz_get_ui(e));
    else {
        fmpz_neg(e, e);
        fmpq_div_2exp(q, q, fmpz_get_ui(e));
    }
    arf_clear(a);
    fmpz_clear(m);
    fmpz_clear(e);
}

/* ---- the checks ------------------------------------------------------------ */

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static uint64_t rng(void)   /* xorshift64*: reproducible */
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return rng_state * 2685821657736338717ULL;
}

static double unif(void)
{
    return (double) (rng() >> 11) * 0x1p-53;
}

static long bounds_done, bounds_refused;

/* one interval: strings equal to the reference and outward by rationals;
 * returns how many of the three strings the double route printed */
static int check_interval(double lo, double hi, int n)
{
    char a[RS_DBLSTR_SIZE], b[RS_DBLSTR_SIZE], c[RS_DBLSTR_SIZE], r[128];
    fmpq_t q, u, x, t;
    int done = 0, k;
    fmpq_init(q);
    fmpq_init(u);
    fmpq_init(x);
    fmpq_init(t);
    /* |lo|, |hi| in [1e-13, 1e41): always the double route */
    assert_true(rs_dblstr_round(a, lo, n, -1) >= 0);
    {
        ref_round(r, lo, n, -1);
        if (strcmp(a, r) != 0) fail_msg("lower of %.17g at %d digits: '%s', MPFR '%s'", lo, n, a, r);
        dec_parse(q, u, a);
        dbl_fmpq(x, lo);
        assert_true(fmpq_cmp(q, x) <= 0);
        fmpq_add(t, q, u);
        assert_true(fmpq_cmp(t, x) > 0);   /* the best n-digit lower bound */
        done++;
    }
    assert_true(rs_dblstr_round(b, hi, n, 1) >= 0);
    {
        ref_round(r, hi, n, 1);
        if (strcmp(b, r) != 0) fail_msg("upper of %.17g at %d digits: '%s', MPFR '%s'", hi, n, b, r);
        dec_parse(q, u, b);
        dbl_fmpq(x, hi);
        assert_true(fmpq_cmp(q, x) >= 0);
        fmpq_sub(t, q, u);
        assert_true(fmpq_cmp(t, x) < 0);
        done++;
    }
    /* the interval: printed iff some digit is certain */
    k = ref_agree(lo, hi, n);
    if ((rs_dblstr_interval(c, lo, hi, n) >= 0) != (k > 0))
        fail_msg("[%.17g, %.17g] at %d digits: MPFR: %d digits, double route: %s", lo, hi, n, k, k ? "none" : c);
    if (k > 0) {
        ref_round(r, fabs(lo) <= fabs(hi) ? lo : hi, k, 0);
        if (strcmp(c, r) != 0) fail_msg("[%.17g, %.17g] at %d digits: '%s', MPFR '%s'", lo, hi, n, c, r);
        /* every point within half a unit of the last digit */
        dec_parse(q, u, c);
        fmpq_div_2exp(u, u, 1);
        dbl_fmpq(x, lo);
        fmpq_sub(t, q, x);
        fmpq_abs(t, t);
        assert_true(fmpq_cmp(t, u) <= 0);
        dbl_fmpq(x, hi);
        fmpq_sub(t, q, x);
        fmpq_abs(t, t);
        assert_true(fmpq_cmp(t, u) <= 0);
        done++;
    }
    /* the three cells at once (positive intervals): the same strings, or
     * -1 only when the interval has no certain digit */
    if (lo > 0) {
        char r1[RS_DBLSTR_SIZE], r2[RS_DBLSTR_SIZE], r3[RS_DBLSTR_SIZE];
        if (rs_dblstr_bounds(r1, r2, r3, lo, hi, n) == 0) {
            assert_true(k > 0);
            assert_string_equal(r1, c);
            assert_string_equal(r2, a);
            assert_string_equal(r3, b);
            bounds_done++;
        } else if (k > 0)
            bounds_refused++;
    }
    fmpq_clear(q);
    fmpq_clear(u);
    fmpq_clear(x);
    fmpq_clear(t);
    return done;
}

/* 10^5 random intervals: magnitudes 1e-13 .. 1e40 (the handled range;
 * radii of maps are about 1), both signs, relative widths 0 .. 1, 17
 * digits (the map cells) and 1 .. 16 */
static void test_random_intervals(void **state)
{
    long i, handled = 0;
    (void) state;
    for (i = 0; i < 100000; i++) {
        double lo = (1.0 + 9.0 * unif()) * pow(10.0, (double) ((long) (rng() % 54) - 13)), hi, w;
        int n = (rng() % 4) ? 17 : (int) (1 + rng() % 16), kind = (int) (rng() % 20);
        if (kind == 0) hi = lo;
        else if (kind == 1) hi = nextafter(lo, INFINITY);
        else {
            w = pow(10.0, -17.0 * unif());
            hi = lo * (1.0 + w);
        }
        if (rng() % 10 == 0) {
            w = -hi;
            hi = -lo;
            lo = w;
        }
        handled += check_interval(lo, hi, n);
    }
    /* every bound (2 x 10^5) and most intervals (widths below 10^-1, about
     * 16/17 of them, always have a certain digit) */
    assert_true(handled > 280000);
    /* rs_dblstr_bounds: every positive interval with a certain digit */
    assert_true(bounds_done > 75000);
    assert_int_equal(bounds_refused, 0);
}

/* exact decimals (trimmed), ties to even, decade boundaries, powers of 2 */
static void test_edges(void **state)
{
    static const double xs[] = {0.5, 0.25, 0.125, 0.0625, 1.0, 2.0, 10.0, 100.0, 1e22, 0.75, 123456789.0, 9.5,
                                99.5, 0.95, 2.5, 1e-5, 1.5e-5, 0.1, 0.3, 1.0 / 3.0, 0.9048374180359595,
                                0.99999999999999989, 1.0000000000000002, 9.9999999999999982, 1e16, 99999999999999984.0,
                                4503599627370496.0, 0x1p-40, 0x1p100, 12345.678};
    char s[RS_DBLSTR_SIZE], r[128];
    size_t i;
    int n;
    (void) state;
    for (i = 0; i < sizeof xs / sizeof xs[0]; i++)
        for (n = 1; n <= 17; n++) {
            check_interval(xs[i], xs[i], n);
            check_interval(nextafter(xs[i], 0), xs[i], n);
            check_interval(xs[i], nextafter(xs[i], INFINITY), n);
            check_interval(-xs[i], -xs[i], n);
            /* to nearest, as rs_radius_arf_str(ARF_RND_NEAR) */
            assert_true(rs_dblstr_round(s, xs[i], n, 0) >= 0);
            ref_round(r, xs[i], n, 0);
            assert_string_equal(s, r);
        }
    /* by hand: 0.125 to 2 digits is a tie -> 0.12 (even); 0.5 exact; 1/3 */
    assert_true(rs_dblstr_round(s, 0.125, 2, 0) >= 0);
    assert_string_equal(s, "0.12");
    assert_true(rs_dblstr_round(s, 0.5, 17, -1) >= 0);
    assert_string_equal(s, "0.5");
    assert_true(rs_dblstr_round(s, 1.0 / 3.0, 17, 1) >= 0);
    /* 1/3 in double = 0.333333333333333314829616256247... (exact expansion) */
    assert_string_equal(s, "0.33333333333333332");
    assert_true(rs_dblstr_round(s, 1.0 / 3.0, 17, -1) >= 0);
    assert_string_equal(s, "0.33333333333333331");
    assert_true(rs_dblstr_round(s, 1e22, 17, -1) >= 0);
    assert_string_equal(s, "1e+22");
    /* not handled: 0, inf, nan, out of range, no certain digit */
    assert_int_equal(rs_dblstr_round(s, 0.0, 5, 1), -1);
    assert_int_equal(rs_dblstr_round(s, INFINITY, 5, 1), -1);
    assert_int_equal(rs_dblstr_round(s, NAN, 5, 1), -1);
    assert_int_equal(rs_dblstr_round(s, 1e-300, 17, 1), -1);
    assert_int_equal(rs_dblstr_interval(s, 1.0, 3.0, 17), -1);
    assert_int_equal(rs_dblstr_interval(s, -1.0, 3.0, 17), -1);
}

/* the radius printers take the double route for doubles and print what
 * MPFR prints (radius.c dispatches; wider balls keep the MPFR route) */
static void test_radius_printers(void **state)
{
    arb_t x;
    char *s, r[128];
    long i;
    (void) state;
    arb_init(x);
    for (i = 0; i < 2000; i++) {
        double v = (1.0 + 9.0 * unif()) * pow(10.0, (double) ((long) (rng() % 20) - 10));
        arb_set_d(x, v);
        s = rs_radius_str_lower(x, 17);
        ref_round(r, v, 17, -1);
        assert_string_equal(s, r);
        flint_free(s);
        s = rs_radius_str_upper(x, 17);
        ref_round(r, v, 17, 1);
        assert_string_equal(s, r);
        flint_free(s);
    }
    arb_clear(x);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_intervals),
        cmocka_unit_test(test_edges),
        cmocka_unit_test(test_radius_printers),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
