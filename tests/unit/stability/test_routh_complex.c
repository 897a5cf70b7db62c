/* test_routh_complex.c -- the Bilharz / generalised Routh-Hurwitz test over
 * Q(i) (stability/routh_complex.c): half-plane counts of polynomials built
 * from their roots by hand, the bilinear route against known unit-circle
 * cases, and random polynomials against Arb's certified complex roots
 * (acb_poly_find_roots, an independent root finder) and against complex
 * Schur-Cohn. */
#include "testutil.h"
#include <acb_poly.h>
#include "stability/routh_complex.h"
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

static void counts_of(const slong *c, slong n, slong want_left, slong want_right, slong want_axis, int want_rep)
{
    fmpq_poly_t re, im;
    rs_routh_complex_t t;
    fmpq_poly_init(re); fmpq_poly_init(im);
    rs_routh_complex_init(t);
    set_poly(re, im, c, n, 1);
    rs_routh_complex_count(t, re, im);
    assert_int_equal(t->degree, n - 1);
    assert_int_equal(t->left, want_left);
    assert_int_equal(t->right, want_right);
    assert_int_equal(t->axis, want_axis);
    assert_int_equal(t->axis_repeated, want_rep);
    rs_routh_complex_clear(t);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
}

/* Each polynomial is the product of its roots' factors, multiplied out by
 * hand (coefficients low degree first, pairs re, im). */
static void test_hand_counts(void **state)
{
    /* s + 1: root -1 */
    static const slong a[] = {1, 0, 1, 0};
    /* s - 1: root 1 */
    static const slong b[] = {-1, 0, 1, 0};
    /* (s - (-1 + 2i))(s - (-2 - i)) = s^2 + (3 - i) s + (-1 + 2i)(-2 - i)... :
     * sum of roots -3 + i, product (-1 + 2i)(-2 - i) = 2 + i - 4i - 2i^2 = 4 - 3i:
     * s^2 + (3 - i) s + (4 - 3i); both roots in Re s < 0 */
    static const slong c[] = {4, -3, 3, -1, 1, 0};
    /* (s - (1 + i))(s + 1) = s^2 + (1 - 1 - i) s - (1 + i) = s^2 - i s - 1 - i:
     * one root on each side */
    static const slong d[] = {-1, -1, 0, -1, 1, 0};
    /* (s - i)(s + 1) = s^2 + (1 - i) s - i: one root on the axis, one left */
    static const slong e[] = {0, -1, 1, -1, 1, 0};
    /* (s - i)^2 (s + 2) = (s^2 - 2i s - 1)(s + 2) = s^3 + (2 - 2i) s^2 + (-1 - 4i) s - 2:
     * a double root on the axis */
    static const slong f[] = {-2, 0, -1, -4, 2, -2, 1, 0};
    /* s^2 - 1: roots +-1, mirror images across the axis; q(i w) = -w^2 - 1 is
     * real, so gcd(A, B) = w^2 + 1 holds both (no real root: one per side) */
    static const slong g[] = {-1, 0, 0, 0, 1, 0};
    /* (s - (1 + i))(s - (-1 + i)) = s^2 - 2i s - 2: a mirror pair off the real axis */
    static const slong h[] = {-2, 0, 0, -2, 1, 0};
    /* s^2 + 1: roots +-i, both on the axis, simple */
    static const slong k[] = {1, 0, 0, 0, 1, 0};
    /* (s - 2i)(s + 3)(s - 5) = (s^2 - 2 s - 15)(s - 2i)
     * = s^3 + (-2 - 2i) s^2 + (-15 + 4i) s + 30i: one of each */
    static const slong l[] = {0, 30, -15, 4, -2, -2, 1, 0};
    /* i s + 1 (root s = i): the axis */
    static const slong m[] = {1, 0, 0, 1};
    (void) state;
    counts_of(a, 2, 1, 0, 0, 0);
    counts_of(b, 2, 0, 1, 0, 0);
    counts_of(c, 3, 2, 0, 0, 0);
    counts_of(d, 3, 1, 1, 0, 0);
    counts_of(e, 3, 1, 0, 1, 0);
    counts_of(f, 4, 1, 0, 2, 1);
    counts_of(g, 3, 1, 1, 0, 0);
    counts_of(h, 3, 1, 1, 0, 0);
    counts_of(k, 3, 0, 0, 2, 0);
    counts_of(l, 4, 1, 1, 1, 0);
    counts_of(m, 2, 0, 0, 1, 0);
}

static rs_status_t status_of(const slong *c, slong n, slong den)
{
    fmpq_poly_t re, im;
    rs_status_t st, st2;
    rs_error_t err;
    fmpq_poly_init(re); fmpq_poly_init(im);
    rs_error_init(err);
    set_poly(re, im, c, n, den);
    assert_int_equal(rs_routh_complex_status(&st, NULL, re, im, n - 1, err), RS_OK);
    assert_int_equal(rs_routh_complex_checked_status(&st2, re, im, n - 1, err), RS_OK);
    assert_int_equal(st, st2);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    return st;
}

/* unit-circle cases through the bilinear transform (the same hand examples
 * as test_schur_complex.c, plus roots at lambda = -1, the degree drop) */
static void test_bilinear_status(void **state)
{
    static const slong a[] = {0, -1, 2, 0};            /* lambda - i/2: inside */
    static const slong b[] = {1, 0, 0, 0, 1, 0};        /* lambda^2 + 1: +-i simple */
    static const slong c[] = {-1, 0, 0, -2, 1, 0};      /* (lambda - i)^2: double on the circle */
    static const slong d[] = {-3, -4, 5, 0};            /* 5 lambda - (3 + 4i): on the circle */
    static const slong e[] = {-3, -3, 2, 0};            /* lambda - 3(1 + i)/2: outside */
    static const slong f[] = {1, 0, 1, 0};              /* lambda + 1: degree drop 1 */
    static const slong g[] = {1, 0, 2, 0, 1, 0};        /* (lambda + 1)^2: drop 2, repeated */
    /* BDF2 at z = -1/2 + 3/2 i: (3/2 - z) lambda^2 - 2 lambda + 1/2, times 2:
     * (4 - 3i) lambda^2 - 4 lambda + 1; roots (4 +- sqrt(16 - 4(4 - 3i)))/(2(4 - 3i))
     * = (2 +- sqrt(3i))/(4 - 3i), sqrt(3i) = sqrt(3/2)(1 + i); |4 - 3i| = 5,
     * |2 + sqrt(3/2)(1 + i)|^2 = (2 + 1.2247)^2 + 1.5 = 11.90 < 25 and
     * |2 - sqrt(3/2)(1 + i)|^2 = 0.6027 + 1.5 = 2.10 < 25: both inside */
    static const slong h[] = {1, 0, -4, 0, 4, -3};
    (void) state;
    assert_int_equal(status_of(a, 2, 2), RS_STATUS_STABLE);
    assert_int_equal(status_of(b, 3, 1), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(c, 3, 1), RS_STATUS_UNSTABLE);
    assert_int_equal(status_of(d, 2, 5), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(e, 2, 2), RS_STATUS_UNSTABLE);
    assert_int_equal(status_of(f, 2, 1), RS_STATUS_MARGINAL);
    assert_int_equal(status_of(g, 3, 1), RS_STATUS_UNSTABLE);
    assert_int_equal(status_of(h, 3, 1), RS_STATUS_STABLE);
}

/* the half-plane counts by certified Arb roots: 1 when every root's real
 * part has a decided sign or is exactly the axis (not decided: -1) */
static int arb_counts(slong *left, slong *right, const fmpq_poly_t re, const fmpq_poly_t im)
{
    slong n = FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im)), k, prec;
    int res = -1;
    for (prec = 64; prec <= 1024 && res == -1; prec *= 2) {
        acb_poly_t p;
        acb_ptr r = _acb_vec_init(n);
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
        if (acb_poly_find_roots(r, p, NULL, 0, prec) == n) {
            res = 1;
            *left = *right = 0;
            for (k = 0; k < n; k++) {
                if (arb_is_negative(acb_realref(r + k))) (*left)++;
                else if (arb_is_positive(acb_realref(r + k))) (*right)++;
                else res = -1;
            }
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
        slong n = 1 + (slong) n_randint(rs, 6), k, left, right;
        slong c[14];
        rs_routh_complex_t rt;
        for (k = 0; k < 2 * (n + 1); k++) c[k] = (slong) n_randint(rs, 13) - 6;
        if (c[2 * n] == 0 && c[2 * n + 1] == 0) c[2 * n] = 7 + (slong) n_randint(rs, 8);   /* exact degree n */
        set_poly(re, im, c, n + 1, 1 + (slong) n_randint(rs, 4));
        rs_routh_complex_init(rt);
        rs_routh_complex_count(rt, re, im);
        assert_int_equal(rt->left + rt->right + rt->axis, n);
        if (arb_counts(&left, &right, re, im) == 1) {
            assert_int_equal(rt->axis, 0);
            assert_int_equal(rt->left, left);
            assert_int_equal(rt->right, right);
            compared++;
        }
        /* the unit-circle verdicts of both exact routes agree */
        {
            rs_status_t s1, s2;
            rs_error_t err;
            rs_error_init(err);
            assert_int_equal(rs_schur_complex_status(&s1, re, im, n, err), RS_OK);
            assert_int_equal(rs_routh_complex_status(&s2, NULL, re, im, n, err), RS_OK);
            assert_int_equal(s1, s2);
        }
        rs_routh_complex_clear(rt);
    }
    assert_true(compared > 300);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    flint_randclear(rs);
}


/* ---- the symbolic Bilharz conditions (rs_routh_cx_conds) beside complex
 * Schur-Cohn's (rs_schur_cx_conds), variables (a, lambda) ---------------------- */

static const char *cx_vars[] = {"a", "lambda"};

/* 1 when every condition is > 0 at a = x (lambda anything), else 0 */
static int bilharz_holds(const rs_routh_cx_conds_t *c, slong x, const fmpz_mpoly_ctx_t ctx)
{
    fmpz vals[2];
    fmpz_t v;
    slong k;
    int ok = c->ncond == c->n + 1;
    fmpz_init(v);
    vals[0] = x; vals[1] = 0;       /* small values: fmpz holds them directly */
    for (k = 0; k < c->ncond; k++) {
        fmpz *vp[2] = {vals + 0, vals + 1};
        fmpz_mpoly_evaluate_all_fmpz(v, c->cond + k, vp, ctx);
        if (fmpz_sgn(v) <= 0) ok = 0;
    }
    fmpz_clear(v);
    return ok;
}

static int schur_holds(const rs_schur_cx_conds_t *c, slong x, const fmpz_mpoly_ctx_t ctx)
{
    fmpz vals[2];
    fmpz_t v;
    slong k;
    int ok = 1;
    fmpz_init(v);
    vals[0] = x; vals[1] = 0;
    for (k = 0; k < c->ndelta; k++) {
        fmpz *vp[2] = {vals + 0, vals + 1};
        fmpz_mpoly_evaluate_all_fmpz(v, c->delta + k, vp, ctx);
        if (fmpz_sgn(v) <= 0) ok = 0;
    }
    fmpz_clear(v);
    return ok;
}

/* re + i im at a = num/den as polynomials in lambda */
static void eval_a(fmpq_poly_t out, const fmpz_mpoly_t p, slong num, slong den, const fmpz_mpoly_ctx_t ctx)
{
    slong len = fmpz_mpoly_length(p, ctx), i;
    ulong ex[2];
    fmpq_t c, x, old;
    fmpq_init(c); fmpq_init(x); fmpq_init(old);
    fmpq_poly_zero(out);
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_coeff_fmpz(fmpq_numref(c), p, i, ctx);
        fmpz_one(fmpq_denref(c));
        fmpz_mpoly_get_term_exp_ui(ex, p, i, ctx);
        fmpq_set_si(x, num, (ulong) den);
        fmpq_pow_si(x, x, (slong) ex[0]);
        fmpq_mul(c, c, x);
        fmpq_poly_get_coeff_fmpq(old, out, (slong) ex[1]);
        fmpq_add(old, old, c);
        fmpq_poly_set_coeff_fmpq(out, (slong) ex[1], old);
    }
    fmpq_clear(c); fmpq_clear(x); fmpq_clear(old);
}

/* the Bilharz conditions of re + i im (strings in a, lambda) at integer a = x */
static int cx_stable_at(const char *sre, const char *sim, slong x, int *schur)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t re, im;
    rs_routh_cx_conds_t c;
    rs_schur_cx_conds_t sc;
    int ok;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(re, ctx); fmpz_mpoly_init(im, ctx);
    assert_int_equal(fmpz_mpoly_set_str_pretty(re, sre, cx_vars, ctx), 0);
    assert_int_equal(fmpz_mpoly_set_str_pretty(im, sim, cx_vars, ctx), 0);
    rs_routh_cx_conds_init(&c, ctx);
    rs_schur_cx_conds_init(&sc);
    assert_true(rs_routh_cx_conds(&c, re, im, 1, ctx, 100000));
    assert_true(rs_schur_cx_conds(&sc, re, im, 1, ctx));
    ok = bilharz_holds(&c, x, ctx);
    *schur = schur_holds(&sc, x, ctx);
    rs_schur_cx_conds_clear(&sc, ctx);
    rs_routh_cx_conds_clear(&c, ctx);
    fmpz_mpoly_clear(re, ctx); fmpz_mpoly_clear(im, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    return ok;
}

static void test_cx_conds_hand(void **state)
{
    int sc;
    (void) state;
    /* forward Euler at z = -1/2 + i/2: p = lambda - (1 + z), times 2:
     * (2 lambda - 1) - i; |1 + z|^2 = 1/4 + 1/4 = 1/2 < 1 by hand: stable */
    assert_int_equal(cx_stable_at("2*lambda - 1", "-1", 0, &sc), 1);
    assert_int_equal(sc, 1);
    /* z = -1/2 + i: |1 + z|^2 = 1/4 + 1 = 5/4 > 1: unstable */
    assert_int_equal(cx_stable_at("2*lambda - 1", "-2", 0, &sc), 0);
    assert_int_equal(sc, 0);
    /* forward Euler with step a at z = -1 + i: p = lambda - 1 - a z =
     * (lambda - 1 + a) - i a; |1 + a z|^2 = (1 - a)^2 + a^2 < 1 iff
     * 2 a (a - 1) < 0 iff 0 < a < 1 (by hand).  Integer a: none inside
     * (a = 0, 1 marginal); the factor 4 below puts 0 < a < 4 inside:
     * p = lambda - 1 - (a/4) z, times 4: (4 lambda - 4 + a) - i a */
    {
        static const slong xs[] = {-2, -1, 0, 1, 2, 3, 4, 5, 8};
        static const int want[] = {0, 0, 0, 1, 1, 1, 0, 0, 0};
        slong k;
        for (k = 0; k < 9; k++) {
            assert_int_equal(cx_stable_at("4*lambda - 4 + a", "-a", xs[k], &sc), want[k]);
            assert_int_equal(sc, want[k]);
        }
    }
    /* leapfrog g^2 + 2 i a g - 1: the product of the roots is -1, so never
     * all inside (|a| < 1: both on the circle, by the quadratic formula
     * g = -i a +- sqrt(1 - a^2)) */
    {
        slong x;
        for (x = -3; x <= 3; x++) {
            assert_int_equal(cx_stable_at("lambda^2 - 1", "2*a*lambda", x, &sc), 0);
            assert_int_equal(sc, 0);
        }
    }
    /* (lambda - i/2)(lambda + a/4): roots i/2 and -a/4, all inside iff
     * |a| < 4 (by hand); times 8: 8 lambda^2 + (2a - 4i) lambda - i a */
    {
        slong x;
        for (x = -6; x <= 6; x++) {
            assert_int_equal(cx_stable_at("8*lambda^2 + 2*a*lambda", "-4*lambda - a", x, &sc), x > -4 && x < 4);
            assert_int_equal(sc, x > -4 && x < 4);
        }
    }
}

/* random p with coefficients linear in a: the Bilharz conditions, the
 * complex Schur-Cohn conditions, numeric complex Schur-Cohn on p at the
 * point and Arb's certified roots (independent) all agree */
static void test_cx_conds_random(void **state)
{
    flint_rand_t rs;
    fmpz_mpoly_ctx_t ctx;
    slong t, compared = 0, stable = 0;
    (void) state;
    flint_randinit(rs);
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    for (t = 0; t < 120; t++) {
        slong n = 1 + (slong) n_randint(rs, 4), k, x;
        fmpz_mpoly_t re, im, term;
        rs_routh_cx_conds_t c;
        rs_schur_cx_conds_t sc;
        fmpz_mpoly_init(re, ctx); fmpz_mpoly_init(im, ctx); fmpz_mpoly_init(term, ctx);
        for (k = 0; k <= n; k++) {
            /* c_k = u + v a + i (w + y a); the leading one dominant so that
             * stable cases occur */
            char buf[160];
            slong u = (slong) n_randint(rs, 7) - 3, v = (slong) n_randint(rs, 3) - 1;
            slong w = (slong) n_randint(rs, 7) - 3, y = (slong) n_randint(rs, 3) - 1;
            if (k == n) u += 8 + (slong) n_randint(rs, 6);
            snprintf(buf, sizeof buf, "(%ld + %ld*a)*lambda^%ld", (long) u, (long) v, (long) k);
            fmpz_mpoly_set_str_pretty(term, buf, cx_vars, ctx);
            fmpz_mpoly_add(re, re, term, ctx);
            snprintf(buf, sizeof buf, "(%ld + %ld*a)*lambda^%ld", (long) w, (long) y, (long) k);
            fmpz_mpoly_set_str_pretty(term, buf, cx_vars, ctx);
            fmpz_mpoly_add(im, im, term, ctx);
        }
        rs_routh_cx_conds_init(&c, ctx);
        rs_schur_cx_conds_init(&sc);
        assert_true(rs_routh_cx_conds(&c, re, im, 1, ctx, 100000));
        assert_true(rs_schur_cx_conds(&sc, re, im, 1, ctx));
        for (x = -2; x <= 2; x++) {
            fmpq_poly_t pr, pi;
            slong l, r;
            int b = bilharz_holds(&c, x, ctx), s = schur_holds(&sc, x, ctx), num;
            fmpq_poly_init(pr); fmpq_poly_init(pi);
            eval_a(pr, re, x, 1, ctx);
            eval_a(pi, im, x, 1, ctx);
            num = FLINT_MAX(fmpq_poly_degree(pr), fmpq_poly_degree(pi)) == n && rs_schur_complex_inside(pr, pi);
            assert_int_equal(b, s);
            assert_int_equal(b, num);
            /* Arb: the roots of p(lambda) mapped to s = (lambda - 1)/(lambda + 1) are
             * those of q; all inside the circle iff all in Re s < 0 */
            if (FLINT_MAX(fmpq_poly_degree(pr), fmpq_poly_degree(pi)) == n) {
                fmpq_poly_t qr, qi;
                fmpq_poly_init(qr); fmpq_poly_init(qi);
                rs_routh_complex_bilinear(qr, qi, pr, pi);
                if (FLINT_MAX(fmpq_poly_degree(qr), fmpq_poly_degree(qi)) == n && arb_counts(&l, &r, qr, qi) == 1) {
                    assert_int_equal(b, l == n);
                    compared++;
                    stable += b;
                }
                fmpq_poly_clear(qr); fmpq_poly_clear(qi);
            }
            fmpq_poly_clear(pr); fmpq_poly_clear(pi);
        }
        rs_schur_cx_conds_clear(&sc, ctx);
        rs_routh_cx_conds_clear(&c, ctx);
        fmpz_mpoly_clear(re, ctx); fmpz_mpoly_clear(im, ctx); fmpz_mpoly_clear(term, ctx);
    }
    assert_true(compared > 400);
    assert_true(stable > 20);
    fmpz_mpoly_ctx_clear(ctx);
    flint_randclear(rs);
}

/* (ar + i ai) *= (br + i bi) */
static void cmul(fmpq_poly_t ar, fmpq_poly_t ai, const fmpq_poly_t br, const fmpq_poly_t bi)
{
    fmpq_poly_t x, y, t;
    fmpq_poly_init(x); fmpq_poly_init(y); fmpq_poly_init(t);
    fmpq_poly_mul(x, ar, br);
    fmpq_poly_mul(t, ai, bi);
    fmpq_poly_sub(x, x, t);
    fmpq_poly_mul(y, ar, bi);
    fmpq_poly_mul(t, ai, br);
    fmpq_poly_add(y, y, t);
    fmpq_poly_swap(ar, x); fmpq_poly_swap(ai, y);
    fmpq_poly_clear(x); fmpq_poly_clear(y); fmpq_poly_clear(t);
}

/* p's own counts over Q(i) from its roots chosen by hand: p = prod (lambda - r) */
static void test_rootcount(void **state)
{
    /* roots (re, im) over den 2: -i twice, 1/2, 2 */
    static const slong r1[][2] = {{0, -2}, {0, -2}, {1, 0}, {4, 0}};
    /* 1 once, -1 three times, i/2 once */
    static const slong r2[][2] = {{2, 0}, {-2, 0}, {-2, 0}, {-2, 0}, {0, 1}};
    const slong (*rs[2])[2] = {r1, r2};
    const slong nr[2] = {4, 5};
    slong t, k;
    (void) state;
    for (t = 0; t < 2; t++) {
        fmpq_poly_t pr, pi, fr, fi;
        rs_rootcount_t rc;
        fmpq_t x;
        fmpq_poly_init(pr); fmpq_poly_init(pi); fmpq_poly_init(fr); fmpq_poly_init(fi);
        fmpq_init(x);
        fmpq_poly_one(pr);
        for (k = 0; k < nr[t]; k++) {
            fmpq_poly_zero(fr); fmpq_poly_zero(fi);
            fmpq_poly_set_coeff_si(fr, 1, 1);
            fmpq_set_si(x, -rs[t][k][0], 2);
            fmpq_poly_set_coeff_fmpq(fr, 0, x);
            fmpq_set_si(x, -rs[t][k][1], 2);
            fmpq_poly_set_coeff_fmpq(fi, 0, x);
            cmul(pr, pi, fr, fi);
        }
        rs_rootcount_init(rc);
        rs_routh_complex_rootcount(rc, pr, pi);
        assert_int_equal(rc->degree, nr[t]);
        if (t == 0) {
            /* -i double on the circle, 1/2 inside, 2 outside: unstable (defective) */
            assert_int_equal(rc->inside, 1);
            assert_int_equal(rc->on, 2);
            assert_int_equal(rc->outside, 1);
            assert_int_equal(rc->on_mult[2], 1);
            assert_int_equal(rc->at_one + rc->at_minus_one, 0);
        } else {
            /* 1 simple, -1 triple, i/2 inside */
            assert_int_equal(rc->inside, 1);
            assert_int_equal(rc->on, 4);
            assert_int_equal(rc->outside, 0);
            assert_int_equal(rc->on_mult[1], 1);
            assert_int_equal(rc->on_mult[3], 1);
            assert_int_equal(rc->at_one, 1);
            assert_int_equal(rc->at_minus_one, 3);
        }
        assert_int_equal(rs_rootcount_status(rc), RS_STATUS_UNSTABLE);
        rs_rootcount_clear(rc);
        fmpq_clear(x);
        fmpq_poly_clear(pr); fmpq_poly_clear(pi); fmpq_poly_clear(fr); fmpq_poly_clear(fi);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_counts),
        cmocka_unit_test(test_bilinear_status),
        cmocka_unit_test(test_random_vs_arb),
        cmocka_unit_test(test_cx_conds_hand),
        cmocka_unit_test(test_cx_conds_random),
        cmocka_unit_test(test_rootcount),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
