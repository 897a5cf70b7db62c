/* test_schur_complex.c -- Schur-Cohn over Q(i) (stability/schur_complex.c)
 * against hand examples and against Arb's certified roots of the complex
 * polynomial (acb_poly_find_roots, which certifies the roots it isolates;
 * exact Gaussian-rational coefficients), an independent root finder. */
#include "testutil.h"
#include <acb_poly.h>
#include <fmpz_vec.h>
#include "stability/schur_complex.h"

/* p from integer pairs (re, im) per coefficient, low degree first */
static void set_poly(fmpq_poly_t re, fmpq_poly_t im, const slong *c, slong n, slong den)
{
    slong k;
    fmpq_poly_zero(re);
    fmpq_poly_zero(im);
    for (k = 0; k < n; k++) {
        fmpq_t x;
        fmpq_init(x);
        fmpq_set_si(x, c[2 * k], (ulong) den);
        fmpq_poly_set_coeff_fmpq(re, k, x);
        fmpq_set_si(x, c[2 * k + 1], (ulong) den);
        fmpq_poly_set_coeff_fmpq(im, k, x);
        fmpq_clear(x);
    }
}

static rs_status_t status_of(const slong *c, slong n, slong den)
{
    fmpq_poly_t re, im;
    rs_status_t st;
    rs_error_t err;
    fmpq_poly_init(re); fmpq_poly_init(im);
    rs_error_init(err);
    set_poly(re, im, c, n, den);
    assert_int_equal(rs_schur_complex_status(&st, re, im, n - 1, err), RS_OK);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    return st;
}

static void test_hand(void **state)
{
    /* lambda - i/2: root i/2 inside */
    static const slong a[] = {0, -1, 2, 0};
    /* lambda^2 + 1: roots +-i on the circle, simple */
    static const slong b[] = {1, 0, 0, 0, 1, 0};
    /* (lambda - i)^2 = lambda^2 - 2i lambda - 1: a double root on the circle */
    static const slong c[] = {-1, 0, 0, -2, 1, 0};
    /* 5 lambda - (3 + 4i): root (3 + 4i)/5 on the circle (3^2 + 4^2 = 5^2) */
    static const slong d[] = {-3, -4, 5, 0};
    /* lambda - (1 + i)/2 * 3: |root| = 3/sqrt 2 > 1 */
    static const slong e[] = {-3, -3, 2, 0};
    /* the leapfrog polynomial lambda^2 + 2 i nu s lambda - 1 at nu s = 1/2:
     * roots -i/2 +- sqrt(3)/2, both on the circle, simple */
    static const slong f[] = {-1, 0, 0, 1, 1, 0};
    /* ... and at nu s = 2: roots i(-2 +- sqrt 3), one outside */
    static const slong g[] = {-1, 0, 0, 4, 1, 0};
    (void) state;
    assert_int_equal(status_of(a, 2, 2), RS_STATUS_STABLE);
    assert_int_equal(status_of(b, 3, 1), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(c, 3, 1), RS_STATUS_UNSTABLE);
    assert_int_equal(status_of(d, 2, 5), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(e, 2, 2), RS_STATUS_UNSTABLE);
    assert_int_equal(status_of(f, 3, 1), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(g, 3, 1), RS_STATUS_UNSTABLE);
}

/* all roots strictly inside by certified Arb roots: 1, 0 (one outside or
 * on), -1 (a ball meets the circle: not decided numerically) */
static int arb_inside(const fmpq_poly_t re, const fmpq_poly_t im)
{
    slong n = FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im)), k, prec;
    int res = -1;
    for (prec = 64; prec <= 1024 && res == -1; prec *= 2) {
        acb_poly_t p;
        acb_ptr r = _acb_vec_init(n);
        slong found;
        acb_poly_init(p);
        for (k = 0; k <= n; k++) {
            acb_t c;
            fmpq_t x;
            acb_init(c);
            fmpq_init(x);
            fmpq_poly_get_coeff_fmpq(x, re, k);
            arb_set_fmpq(acb_realref(c), x, prec);
            fmpq_poly_get_coeff_fmpq(x, im, k);
            arb_set_fmpq(acb_imagref(c), x, prec);
            acb_poly_set_coeff_acb(p, k, c);
            acb_clear(c);
            fmpq_clear(x);
        }
        found = acb_poly_find_roots(r, p, NULL, 0, prec);   /* the number of isolated (certified) roots */
        if (found == n) {
            arb_t ab, one;
            int all = 1, undecided = 0;
            arb_init(ab); arb_init(one);
            arb_one(one);
            for (k = 0; k < n; k++) {
                acb_abs(ab, r + k, prec);
                if (arb_lt(ab, one)) continue;
                all = 0;
                if (!arb_gt(ab, one)) undecided = 1;
            }
            res = all ? 1 : (undecided ? -1 : 0);
            arb_clear(ab); arb_clear(one);
        }
        acb_poly_clear(p);
        _acb_vec_clear(r, n);
    }
    return res;
}

static void test_random_vs_arb(void **state)
{
    flint_rand_t rs;
    fmpq_poly_t re, im;
    slong t, compared = 0;
    (void) state;
    flint_randinit(rs);
    fmpq_poly_init(re); fmpq_poly_init(im);
    for (t = 0; t < 400; t++) {
        slong n = 1 + (slong) n_randint(rs, 5), k;
        slong c[14];
        int want;
        for (k = 0; k < 2 * (n + 1); k++) c[k] = (slong) n_randint(rs, 13) - 6;
        if (c[2 * n] == 0 && c[2 * n + 1] == 0) c[2 * n] = 7 + (slong) n_randint(rs, 8);   /* exact degree n */
        set_poly(re, im, c, n + 1, 1 + (slong) n_randint(rs, 4));
        want = arb_inside(re, im);
        if (want < 0) continue;
        assert_int_equal(rs_schur_complex_inside(re, im), want);
        compared++;
    }
    assert_true(compared > 300);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    flint_randclear(rs);
}

/* ---- the symbolic conditions (rs_schur_cx_conds) --------------------------
 * Hand derivations (checked with sympy's resultant/discriminant):
 *   p = lambda^2 + i y lambda + x:  p* = x lambda^2 - i y lambda + 1,
 *   delta_2 = 1 - x^2, p_1 = (conj(1) p - x p*)/lambda = (1 - x^2) lambda
 *   + i y (1 + x), delta_1 = (1 - x^2)^2 - y^2 (1 + x)^2,
 *   Res(p, p*) = (x + 1)^2 (x - y - 1)(x + y - 1), disc = -y^2 - 4 x.
 *   Leapfrog with t = tan(theta/2): p = (1 + t^2) lambda^2 + 4 i nu t lambda
 *   - (1 + t^2) is self-inversive (p* = -p): both deltas and Res(p, p*)
 *   vanish identically, disc = 4 (1 + t^2)^2 - 16 nu^2 t^2, |a_2|^2 =
 *   (1 + t^2)^2. */
static void expect_poly(const fmpz_mpoly_t got, const char *want, const char **vars, const fmpz_mpoly_ctx_t ctx,
                        int up_to_sign)
{
    fmpz_mpoly_t e;
    fmpz_mpoly_init(e, ctx);
    assert_int_equal(fmpz_mpoly_set_str_pretty(e, want, vars, ctx), 0);
    if (!fmpz_mpoly_equal(e, got, ctx)) {
        fmpz_mpoly_neg(e, e, ctx);
        if (!up_to_sign || !fmpz_mpoly_equal(e, got, ctx)) {
            char *g = fmpz_mpoly_get_str_pretty(got, vars, ctx);
            fail_msg("got %s, expected %s%s", g, want, up_to_sign ? " (up to sign)" : "");
        }
    }
    fmpz_mpoly_clear(e, ctx);
}

static void test_symbolic_hand(void **state)
{
    const char *v1[] = {"x", "y", "lambda"}, *v2[] = {"nu", "t", "lambda"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t re, im;
    rs_schur_cx_conds_t c;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 3, ORD_LEX);
    fmpz_mpoly_init(re, ctx); fmpz_mpoly_init(im, ctx);
    fmpz_mpoly_set_str_pretty(re, "lambda^2 + x", v1, ctx);
    fmpz_mpoly_set_str_pretty(im, "y*lambda", v1, ctx);
    rs_schur_cx_conds_init(&c);
    assert_int_equal(rs_schur_cx_conds(&c, re, im, 2, ctx), 1);
    assert_int_equal(c.ndelta, 2);
    expect_poly(c.lead, "1", v1, ctx, 0);
    expect_poly(c.delta + 0, "1 - x^2", v1, ctx, 0);
    expect_poly(c.delta + 1, "(1 - x^2)^2 - y^2*(1 + x)^2", v1, ctx, 0);
    expect_poly(c.res, "(x + 1)^2*(x - y - 1)*(x + y - 1)", v1, ctx, 1);
    expect_poly(c.disc_re, "-y^2 - 4*x", v1, ctx, 0);
    assert_true(fmpz_mpoly_is_zero(c.disc_im, ctx));
    assert_int_equal(c.self_inversive, 0);              /* p* != c p: x lambda^2 vs lambda^2 */
    rs_schur_cx_conds_clear(&c, ctx);
    /* leapfrog */
    fmpz_mpoly_set_str_pretty(re, "(1 + t^2)*lambda^2 - (1 + t^2)", v2, ctx);
    fmpz_mpoly_set_str_pretty(im, "4*nu*t*lambda", v2, ctx);
    rs_schur_cx_conds_init(&c);
    assert_int_equal(rs_schur_cx_conds(&c, re, im, 2, ctx), 1);
    expect_poly(c.lead, "(1 + t^2)^2", v2, ctx, 0);
    assert_true(fmpz_mpoly_is_zero(c.delta + 0, ctx));
    assert_true(fmpz_mpoly_is_zero(c.delta + 1, ctx));
    assert_true(fmpz_mpoly_is_zero(c.res, ctx));
    expect_poly(c.disc_re, "4*(1 + t^2)^2 - 16*nu^2*t^2", v2, ctx, 0);
    assert_true(fmpz_mpoly_is_zero(c.disc_im, ctx));
    assert_int_equal(c.self_inversive, 1);              /* p* = -p */
    rs_schur_cx_conds_clear(&c, ctx);
    fmpz_mpoly_clear(re, ctx); fmpz_mpoly_clear(im, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* Property: for random p(lambda; x) over Z[i][x] (x in one random
 * coefficient), at integer x every delta > 0 iff the numeric Schur-Cohn
 * (itself checked against Arb above) says all roots inside; and at such an
 * x where the delta conditions fail the verdict is not stable. */
static void test_symbolic_random(void **state)
{
    const char *vars[] = {"x", "lambda"};
    flint_rand_t rs;
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t re, im, t;
    fmpq_poly_t pr, pi;
    slong trial, inside_seen = 0, outside_seen = 0;
    (void) state;
    flint_randinit(rs);
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(re, ctx); fmpz_mpoly_init(im, ctx); fmpz_mpoly_init(t, ctx);
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    for (trial = 0; trial < 60; trial++) {
        slong n = 1 + (slong) n_randint(rs, 3), k, j = (slong) n_randint(rs, (ulong) n), xv;
        rs_schur_cx_conds_t c;
        fmpz_mpoly_zero(re, ctx);
        fmpz_mpoly_zero(im, ctx);
        for (k = 0; k <= n; k++) {
            char buf[200];
            slong a = k == n ? 8 + (slong) n_randint(rs, 4) : (slong) n_randint(rs, 7) - 3;
            slong b = (slong) n_randint(rs, 7) - 3;
            snprintf(buf, sizeof buf, "(%ld%s)*lambda^%ld", (long) a, k == j ? " + x" : "", (long) k);
            fmpz_mpoly_set_str_pretty(t, buf, vars, ctx);
            fmpz_mpoly_add(re, re, t, ctx);
            snprintf(buf, sizeof buf, "(%ld)*lambda^%ld", (long) b, (long) k);
            fmpz_mpoly_set_str_pretty(t, buf, vars, ctx);
            fmpz_mpoly_add(im, im, t, ctx);
        }
        rs_schur_cx_conds_init(&c);
        assert_int_equal(rs_schur_cx_conds(&c, re, im, 1, ctx), 1);
        for (xv = -12; xv <= 12; xv += 3) {
            fmpz_t X, val;
            fmpz *vals, *pt[2];
            int all = 1, want;
            fmpz_init_set_si(X, xv);
            fmpz_init(val);
            vals = _fmpz_vec_init(2);
            fmpz_set(vals + 0, X);
            pt[0] = vals + 0;
            pt[1] = vals + 1;
            for (k = 0; k < c.ndelta; k++) {
                fmpz_mpoly_evaluate_all_fmpz(val, c.delta + k, pt, ctx);
                all = all && fmpz_sgn(val) > 0;
            }
            /* p at x = xv as fmpq_polys */
            fmpq_poly_zero(pr); fmpq_poly_zero(pi);
            for (k = 0; k <= n; k++) {
                ulong e = (ulong) k;
                slong lv = 1;
                fmpz_mpoly_get_coeff_vars_ui(t, re, &lv, &e, 1, ctx);
                fmpz_mpoly_evaluate_all_fmpz(val, t, pt, ctx);
                fmpq_poly_set_coeff_fmpz(pr, k, val);
                fmpz_mpoly_get_coeff_vars_ui(t, im, &lv, &e, 1, ctx);
                fmpz_mpoly_evaluate_all_fmpz(val, t, pt, ctx);
                fmpq_poly_set_coeff_fmpz(pi, k, val);
            }
            want = rs_schur_complex_inside(pr, pi);
            if (all != want) fail_msg("trial %ld, x = %ld: deltas say %d, Schur-Cohn at the point %d", (long) trial,
                                      (long) xv, all, want);
            if (want) inside_seen++; else outside_seen++;
            _fmpz_vec_clear(vals, 2);
            fmpz_clear(X); fmpz_clear(val);
        }
        rs_schur_cx_conds_clear(&c, ctx);
    }
    assert_true(inside_seen > 10 && outside_seen > 10);
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    fmpz_mpoly_clear(re, ctx); fmpz_mpoly_clear(im, ctx); fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    flint_randclear(rs);
}

/* rs_schur_complex_div: products multiplied out by hand, divided back */
static void test_div(void **state)
{
    /* (lambda - i)(lambda + 2) = lambda^2 + (2 - i) lambda - 2i */
    static const slong a[] = {0, -2, 2, -1, 1, 0};
    static const slong b[] = {0, -1, 1, 0};          /* lambda - i */
    static const slong q[] = {2, 0, 1, 0};           /* lambda + 2 */
    /* (2i lambda + 1)(lambda - 1/2) = 2i lambda^2 + (1 - i) lambda - 1/2, times 2:
     * 4i lambda^2 + (2 - 2i) lambda - 1, divided by 2i lambda + 1: 2 lambda - 1 */
    static const slong c[] = {-1, 0, 2, -2, 0, 4};
    static const slong d[] = {1, 0, 0, 2};
    static const slong e[] = {-1, 0, 2, 0};
    fmpq_poly_t ar, ai, br, bi, qr, qi, wr, wi;
    (void) state;
    fmpq_poly_init(ar); fmpq_poly_init(ai); fmpq_poly_init(br); fmpq_poly_init(bi);
    fmpq_poly_init(qr); fmpq_poly_init(qi); fmpq_poly_init(wr); fmpq_poly_init(wi);
    set_poly(ar, ai, a, 3, 1);
    set_poly(br, bi, b, 2, 1);
    set_poly(wr, wi, q, 2, 1);
    rs_schur_complex_div(qr, qi, ar, ai, br, bi);
    assert_true(fmpq_poly_equal(qr, wr) && fmpq_poly_equal(qi, wi));
    set_poly(ar, ai, c, 3, 1);
    set_poly(br, bi, d, 2, 1);
    set_poly(wr, wi, e, 2, 1);
    rs_schur_complex_div(qr, qi, ar, ai, br, bi);
    assert_true(fmpq_poly_equal(qr, wr) && fmpq_poly_equal(qi, wi));
    fmpq_poly_clear(ar); fmpq_poly_clear(ai); fmpq_poly_clear(br); fmpq_poly_clear(bi);
    fmpq_poly_clear(qr); fmpq_poly_clear(qi); fmpq_poly_clear(wr); fmpq_poly_clear(wi);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand),
        cmocka_unit_test(test_random_vs_arb),
        cmocka_unit_test(test_symbolic_hand),
        cmocka_unit_test(test_symbolic_random),
        cmocka_unit_test(test_div),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
