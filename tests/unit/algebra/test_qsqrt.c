/* test_qsqrt.c -- src/algebra/qsqrt.c (exact arithmetic in Q(sqrt d)) and
 * the stability function of sdirk2 over Q(sqrt 2) (src/lower/methods.c),
 * every expected value derived independently here:
 *  - signs of x + y sqrt(d) near zero (99 - 70 sqrt 2 = 0.00505...: the
 *    continued fraction convergents of sqrt 2), checked against long double;
 *  - SDIRK2 (Alexander 1977; Hairer and Wanner, Solving ODEs II, IV.6),
 *    A = [g, 0; 1-g, g], b = [1-g, g], g = 1 - sqrt(2)/2.  By hand, with
 *    u = 1 - g z: stage 1 k1 = 1/u, stage 2 k2 = (1 + (1-g) z k1)/u, so
 *    R = 1 + z ((1-g) k1 + g k2) = (u^2 + z u + g(1-g) z^2)/u^2, and
 *    u^2 + z u = 1 + (1-2g) z + (g^2 - g) z^2, so the z^2 terms cancel:
 *    R = (1 + (1-2g) z)/(1 - g z)^2,
 *    1 - 2g = sqrt(2) - 1, g^2 = 3/2 - sqrt(2);
 *  - E(y) = |D(iy)|^2 - |N(iy)|^2 = (1 + g^2 y^2)^2 - 1 - (1-2g)^2 y^2
 *    = (4g - 2g^2 - 1) y^2 + g^4 y^4 = g^4 y^4 (g^2 - 2g + 1/2 = 0),
 *    g^4 = 17/4 - 3 sqrt 2: A-stable, L-stable (deg N < deg D);
 *  - the companion g = 1 + sqrt(2)/2: the same E = g^4 y^4 by the same
 *    identity, A- and L-stable;
 *  - the 2-stage SDIRK of order 3, A = [g, 0; 1-2g, g], b = [1/2, 1/2]:
 *    R = (1 + (1-2g) z + (g^2 - 2g + 1/2) z^2)/(1 - g z)^2 (by hand as
 *    above), A-stable for g = 1/2 + sqrt(3)/6 with R(inf) = 1 - sqrt 3 and
 *    not for g = 1/2 - sqrt(3)/6 (Hairer and Wanner II, IV.6, Crouzeix);
 *    the refutation's witness y is checked in double: |R(iy)| > 1;
 *  - stability intervals: SDIRK2 real (-inf, 0] (D - N = x (g^2 x - 1) > 0
 *    for x < 0, D + N = 2 + (1 - 4g) x + g^2 x^2 has no real root:
 *    discriminant (1 - 4g)^2 - 8 g^2 < 0), imaginary the whole axis
 *    (E = g^4 y^4); SDIRK3 with g = 1/2 - sqrt(3)/6: E = (g^4 - c^2) y^4,
 *    c = g^2 - 2g + 1/2, g^4 - c^2 = (2g - 1/2)(2g^2 - 2g + 1/2) < 0, so
 *    the imaginary interval is [0, 0]; its real interval is [-6 - 4 sqrt 3,
 *    0]: D - N = x ((2g - 1/2) x - 1) vanishes at 1/(2g - 1/2) = -6 - 4
 *    sqrt 3 (a root of x^2 + 12 x - 12), D + N has no real root;
 *  - stability at points: the verdict against a time-domain run of the
 *    SDIRK2 step on y' = z y in double complex arithmetic. */
#include "testutil.h"
#include <math.h>
#include <complex.h>
#include "algebra/qsqrt.h"
#include "lower/methods.h"

static void qd_set_str2(rs_qd_struct *a, const char *x, const char *y)
{
    assert_int_equal(fmpq_set_str(a->x, x, 10), 0);
    assert_int_equal(fmpq_set_str(a->y, y, 10), 0);
    fmpq_canonicalise(a->x);
    fmpq_canonicalise(a->y);
}

/* p0 + sqrt(d) p1 from "c0 c1 ..." strings of x and y parts, pairs "x:y" */
static void qdpoly_set(rs_qdpoly_t p, const char *s)
{
    char buf[64];
    slong k = 0;
    rs_qd_t c;
    rs_qd_init(c);
    fmpq_poly_zero(p->p0);
    fmpq_poly_zero(p->p1);
    while (*s) {
        size_t n = strcspn(s, " ");
        char *colon;
        memcpy(buf, s, n);
        buf[n] = '\0';
        colon = strchr(buf, ':');
        assert_non_null(colon);
        *colon = '\0';
        qd_set_str2(c, buf, colon + 1);
        rs_qdpoly_set_coeff(p, k++, c);
        s += n;
        while (*s == ' ') s++;
    }
    rs_qd_clear(c);
}

static long double qd_ld(const rs_qd_struct *a, slong d)
{
    return (long double) fmpq_get_d(a->x) + (long double) fmpq_get_d(a->y) * sqrtl((long double) d);
}

static void test_sign(void **state)
{
    static const char *const v[][2] = {{"1", "-1/2"}, {"-3/2", "1"}, {"3", "-2"}, {"-7", "5"}, {"99", "-70"},
                                       {"-99", "70"}, {"0", "-1"}, {"-1", "0"}, {"0", "0"}, {"577", "-408"}};
    slong i;
    rs_qd_t a;
    (void) state;
    rs_qd_init(a);
    for (i = 0; i < (slong) (sizeof v / sizeof v[0]); i++) {
        long double x;
        qd_set_str2(a, v[i][0], v[i][1]);
        x = qd_ld(a, 2);
        assert_int_equal(rs_qd_sgn(a, 2), x > 0 ? 1 : x < 0 ? -1 : 0);
    }
    /* 1/(1 - sqrt(2)/2) = 2 + sqrt 2 */
    qd_set_str2(a, "1", "-1/2");
    rs_qd_inv(a, a, 2);
    assert_true(fmpq_equal_si(a->x, 2) && fmpq_equal_si(a->y, 1));
    rs_qd_clear(a);
}

static void test_sdirk2_R(void **state)
{
    rs_qdpoly_t N, D, eN, eD;
    slong d = -1;
    char *s;
    (void) state;
    rs_qdpoly_init(N); rs_qdpoly_init(D); rs_qdpoly_init(eN); rs_qdpoly_init(eD);
    assert_int_equal(rs_methods_rk_stability_named_qd(N->p0, N->p1, D->p0, D->p1, &d, "sdirk2"), 1);
    assert_int_equal(d, 2);
    /* N = 1 + (sqrt 2 - 1) z, D = 1 - 2g z + g^2 z^2 = 1 + (-2 + sqrt 2) z + (3/2 - sqrt 2) z^2 */
    qdpoly_set(eN, "1:0 -1:1");
    qdpoly_set(eD, "1:0 -2:1 3/2:-1");
    assert_true(rs_qdpoly_equal(N, eN));
    assert_true(rs_qdpoly_equal(D, eD));
    s = rs_qdpoly_get_str(N, 2, "z");
    assert_string_equal(s, "1 + (-1 + 1*sqrt(2))*z");
    flint_free(s);
    /* a lone negative part after the first term reads as a subtraction
     * (sdirk3's N = 1 - 1/3 sqrt(3) q + ..., by hand from its tableau) */
    qdpoly_set(eN, "1:0 0:-1/3 -1/6:-1/6");
    s = rs_qdpoly_get_str(eN, 3, "q");
    assert_string_equal(s, "1 - 1/3*sqrt(3)*q + (-1/6 - 1/6*sqrt(3))*q^2");
    flint_free(s);
    /* a rational tableau: y parts zero, the same R as the rational route (rk4: 1 + z + z^2/2 + ...) */
    assert_int_equal(rs_methods_rk_stability_named_qd(N->p0, N->p1, D->p0, D->p1, &d, "rk4"), 1);
    qdpoly_set(eN, "1:0 1:0 1/2:0 1/6:0 1/24:0");
    qdpoly_set(eD, "1:0");
    assert_true(rs_qdpoly_equal(N, eN));
    assert_true(rs_qdpoly_equal(D, eD));
    assert_int_equal(rs_methods_rk_stability_named_qd(N->p0, N->p1, D->p0, D->p1, &d, "nosuch"), 0);
    rs_qdpoly_clear(N); rs_qdpoly_clear(D); rs_qdpoly_clear(eN); rs_qdpoly_clear(eD);
}

/* |R(iy)| in double from N, D */
static double abs_R_iy(const rs_qdpoly_t N, const rs_qdpoly_t D, slong d, double y)
{
    double complex n = 0, m = 0, z = I * y, zk = 1;
    slong k;
    rs_qd_t c;
    rs_qd_init(c);
    for (k = 0; k <= FLINT_MAX(rs_qdpoly_degree(N), rs_qdpoly_degree(D)); k++, zk *= z) {
        rs_qdpoly_get_coeff(c, N, k);
        n += (double) qd_ld(c, d) * zk;
        rs_qdpoly_get_coeff(c, D, k);
        m += (double) qd_ld(c, d) * zk;
    }
    rs_qd_clear(c);
    return cabs(n / m);
}

static void test_astability(void **state)
{
    rs_qdpoly_t N, D, eE;
    rs_qd_astab_t a;
    slong d;
    (void) state;
    rs_qdpoly_init(N); rs_qdpoly_init(D); rs_qdpoly_init(eE);
    /* sdirk2 from the tableau */
    rs_methods_rk_stability_named_qd(N->p0, N->p1, D->p0, D->p1, &d, "sdirk2");
    rs_qd_astab_init(a);
    rs_qd_astab_decide(a, N, D, d);
    qdpoly_set(eE, "0:0 0:0 0:0 0:0 17/4:-3");
    assert_true(rs_qdpoly_equal(a->E, eE));
    assert_true(a->a_stable && a->l_stable && a->poles_right && a->e_nonneg);
    assert_true(a->r_inf_finite && rs_qd_is_zero(a->r_inf));
    rs_qd_astab_clear(a);

    /* companion g = 1 + sqrt(2)/2: N = 1 - (1 + sqrt 2) z, D = 1 - (2 + sqrt 2) z + (3/2 + sqrt 2) z^2,
     * E = g^4 y^4 = (17/4 + 3 sqrt 2) y^4 */
    qdpoly_set(N, "1:0 -1:-1");
    qdpoly_set(D, "1:0 -2:-1 3/2:1");
    rs_qd_astab_init(a);
    rs_qd_astab_decide(a, N, D, 2);
    qdpoly_set(eE, "0:0 0:0 0:0 0:0 17/4:3");
    assert_true(rs_qdpoly_equal(a->E, eE));
    assert_true(a->a_stable && a->l_stable);
    rs_qd_astab_clear(a);

    /* SDIRK3, g = 1/2 + sqrt(3)/6: 1 - 2g = -sqrt(3)/3, g^2 = 1/3 + sqrt(3)/6,
     * g^2 - 2g + 1/2 = -1/6 - sqrt(3)/6; A-stable, R(inf) = 1 - sqrt 3 */
    qdpoly_set(N, "1:0 0:-1/3 -1/6:-1/6");
    qdpoly_set(D, "1:0 -1:-1/3 1/3:1/6");
    rs_qd_astab_init(a);
    rs_qd_astab_decide(a, N, D, 3);
    assert_true(a->a_stable && !a->l_stable && a->r_inf_finite);
    assert_true(fmpq_equal_si(a->r_inf->x, 1) && fmpq_equal_si(a->r_inf->y, -1));
    rs_qd_astab_clear(a);

    /* g = 1/2 - sqrt(3)/6: not A-stable; the witness y has |R(iy)| > 1 */
    qdpoly_set(N, "1:0 0:1/3 -1/6:1/6");
    qdpoly_set(D, "1:0 -1:1/3 1/3:-1/6");
    rs_qd_astab_init(a);
    rs_qd_astab_decide(a, N, D, 3);
    assert_true(!a->a_stable && !a->e_nonneg && a->poles_right);
    assert_true(abs_R_iy(N, D, 3, fmpq_get_d(a->witness)) > 1.0);
    rs_qd_astab_clear(a);
    rs_qdpoly_clear(N); rs_qdpoly_clear(D); rs_qdpoly_clear(eE);
}

static void test_nonneg_hurwitz(void **state)
{
    rs_qdpoly_t p;
    fmpq_t t;
    double x;
    (void) state;
    rs_qdpoly_init(p);
    fmpq_init(t);
    /* (y - sqrt 2)^2 = y^2 - 2 sqrt(2) y + 2: a double irrational root */
    qdpoly_set(p, "2:0 0:-2 1:0");
    assert_true(rs_qdpoly_nonneg_real(p, 2, t));
    /* minus 1/100: negative on (sqrt 2 - 1/10, sqrt 2 + 1/10) */
    qdpoly_set(p, "199/100:0 0:-2 1:0");
    assert_false(rs_qdpoly_nonneg_real(p, 2, t));
    x = fmpq_get_d(t);
    assert_true(fabs(x - sqrt(2.0)) < 0.1);
    /* (z + sqrt 2)(z + 1) = z^2 + (1 + sqrt 2) z + sqrt 2: Hurwitz */
    qdpoly_set(p, "0:1 1:1 1:0");
    assert_true(rs_qdpoly_hurwitz(p, 2));
    /* (z - (sqrt 2 - 1))(z + 3) = z^2 + (4 - sqrt 2) z - 3 sqrt 2 + 3: a root 0.414 > 0 */
    qdpoly_set(p, "3:-3 4:-1 1:0");
    assert_false(rs_qdpoly_hurwitz(p, 2));
    /* (z + 1)^3 + ... cubic (z + sqrt 2)^3 = z^3 + 3 sqrt2 z^2 + 6 z + 2 sqrt 2: Hurwitz;
     * (z - sqrt 2)(z^2 + z + 1): not */
    qdpoly_set(p, "0:2 6:0 0:3 1:0");
    assert_true(rs_qdpoly_hurwitz(p, 2));
    qdpoly_set(p, "0:-1 1:-1 1:-1 1:0");
    assert_false(rs_qdpoly_hurwitz(p, 2));
    fmpq_clear(t);
    rs_qdpoly_clear(p);
}

/* (lambda - r1)(lambda - r2) for r = a + i b, a, b in Q(sqrt 2) given as strings */
static void quad_from_roots(rs_qdc_struct *c, const char *r1[4], const char *r2[4])
{
    rs_qdc_struct *x = rs_qdc_vec_init(2);
    rs_qd_t t, u;
    rs_qd_init(t); rs_qd_init(u);
    qd_set_str2(x[0].re, r1[0], r1[1]); qd_set_str2(x[0].im, r1[2], r1[3]);
    qd_set_str2(x[1].re, r2[0], r2[1]); qd_set_str2(x[1].im, r2[2], r2[3]);
    /* c2 = 1, c1 = -(r1 + r2), c0 = r1 r2 */
    fmpq_one(c[2].re->x); fmpq_zero(c[2].re->y); fmpq_zero(c[2].im->x); fmpq_zero(c[2].im->y);
    rs_qd_add(c[1].re, x[0].re, x[1].re);
    rs_qd_add(c[1].im, x[0].im, x[1].im);
    fmpq_neg(c[1].re->x, c[1].re->x); fmpq_neg(c[1].re->y, c[1].re->y);
    fmpq_neg(c[1].im->x, c[1].im->x); fmpq_neg(c[1].im->y, c[1].im->y);
    rs_qd_mul(t, x[0].re, x[1].re, 2);
    rs_qd_mul(u, x[0].im, x[1].im, 2);
    rs_qd_sub(c[0].re, t, u);
    rs_qd_mul(t, x[0].re, x[1].im, 2);
    rs_qd_mul(u, x[0].im, x[1].re, 2);
    rs_qd_add(c[0].im, t, u);
    rs_qd_clear(t); rs_qd_clear(u);
    rs_qdc_vec_clear(x, 2);
}

static void test_schur(void **state)
{
    /* roots and |root| worked out: sqrt(2)/2 = 0.707, -1/2; sqrt 2 = 1.41;
     * i sqrt(2)/2 and 1/3 + i/2 (|.| = 0.601); 2/3 + (sqrt(2)/2) i: |.|^2 = 4/9 + 1/2 = 17/18 < 1;
     * 1/2 + (sqrt(2)/2 + 1/10) i: |.|^2 = 1/4 + 0.6514 = 0.9014 + ... = 0.9014 < 1... and
     * 3/5 + (sqrt 2 / 2 + 1/10) i: 0.36 + 0.6514 = 1.0114 > 1 */
    static const char *const R[][4] = {
        {"0", "1/2", "0", "0"}, {"-1/2", "0", "0", "0"}, {"0", "1", "0", "0"}, {"0", "0", "0", "1/2"},
        {"1/3", "0", "1/2", "0"}, {"2/3", "0", "0", "1/2"}, {"1/2", "0", "1/10", "1/2"}, {"3/5", "0", "1/10", "1/2"}};
    static const int pairs[][3] = {{0, 1, 1}, {0, 2, 0}, {3, 4, 1}, {5, 1, 1}, {6, 4, 1}, {7, 4, 0}, {2, 3, 0}};
    slong k;
    (void) state;
    for (k = 0; k < (slong) (sizeof pairs / sizeof pairs[0]); k++) {
        rs_qdc_struct *c = rs_qdc_vec_init(3);
        quad_from_roots(c, (const char **) R[pairs[k][0]], (const char **) R[pairs[k][1]]);
        assert_int_equal(rs_qdc_schur_stable(c, 2, 2), pairs[k][2]);
        assert_int_equal(rs_qdc_roots_inside(c, 2, 2), pairs[k][2]);
        {   /* both at once: 1 stable, 0 a root outside; ar as rs_qdc_roots_inside */
            int ar = -3;
            assert_int_equal(rs_qdc_stable_checked(&ar, c, 2, 2), pairs[k][2]);
            assert_int_equal(ar, pairs[k][2]);
        }
        rs_qdc_vec_clear(c, 3);
    }
    {   /* roots 1 (on the circle) and 1/2: Schur-Cohn not stable, no root
         * certified outside: -1 (marginal and unstable not told apart) */
        static const char *const one[4] = {"1", "0", "0", "0"};
        rs_qdc_struct *c = rs_qdc_vec_init(3);
        int ar = -3;
        quad_from_roots(c, (const char **) one, (const char **) R[0]);
        assert_int_equal(rs_qdc_stable_checked(&ar, c, 2, 2), -1);
        assert_int_equal(ar, -1);
        rs_qdc_vec_clear(c, 3);
    }
}

/* property: Schur-Cohn over Q(sqrt 2)(i) and the certified Arb roots agree
 * on random polynomials of degree 1..5 with small coefficients x + y sqrt 2
 * (both real and imaginary parts random); undecided Arb (a root on the
 * circle) must come with a Schur "not stable" */
static void test_schur_random(void **state)
{
    flint_rand_t st;
    slong it, n, k, agree = 0, stable = 0;
    (void) state;
    flint_randinit(st);
    for (it = 0; it < 300; it++) {
        rs_qdc_struct *c;
        int s, r;
        n = 1 + (slong) n_randint(st, 5);
        c = rs_qdc_vec_init(n + 1);
        for (k = 0; k <= n; k++) {
            fmpq_set_si(c[k].re->x, (slong) n_randint(st, 9) - 4, 1 + n_randint(st, 4));
            fmpq_set_si(c[k].re->y, (slong) n_randint(st, 5) - 2, 1 + n_randint(st, 4));
            if (n_randint(st, 2)) {
                fmpq_set_si(c[k].im->x, (slong) n_randint(st, 5) - 2, 1 + n_randint(st, 4));
                fmpq_set_si(c[k].im->y, (slong) n_randint(st, 3) - 1, 1 + n_randint(st, 4));
            }
        }
        /* a dominant leading coefficient makes stable cases common */
        fmpq_set_si(c[n].re->x, 4 + (slong) n_randint(st, 8), 1);
        s = rs_qdc_schur_stable(c, n, 2);
        r = rs_qdc_roots_inside(c, n, 2);
        if (r == -1) assert_int_equal(s, 0);
        else { assert_int_equal(s, r); agree++; }
        assert_int_equal(rs_qdc_stable_checked(NULL, c, n, 2), r == -1 ? -1 : s);
        stable += s;
        rs_qdc_vec_clear(c, n + 1);
    }
    assert_true(agree > 250 && stable > 20 && stable < agree);
    flint_randclear(st);
}

/* one SDIRK2 step on y' = z y, h = 1, y0 = 1, in double complex:
 * k1 = z (1 + g k1), k2 = z (1 + (1-g) k1 + g k2), y1 = 1 + (1-g) k1 + g k2 */
static double complex sdirk2_step(double complex z)
{
    double g = 1.0 - sqrt(2.0) / 2.0;
    double complex k1 = z / (1.0 - g * z), k2 = z * (1.0 + (1.0 - g) * k1) / (1.0 - g * z);
    return 1.0 + (1.0 - g) * k1 + g * k2;
}

static void test_stable_at(void **state)
{
    /* z = zr + i zi; the expected verdicts are those of the time-domain run,
     * z = 0 (|R| = 1 exactly, not strictly stable) by hand */
    static const char *const Z[][2] = {{"-1", "0"}, {"1/2", "0"}, {"5", "0"}, {"10", "0"}, {"20", "0"},
                                       {"-1", "5"}, {"0", "3"}, {"1/10", "3"}, {"-1/1000", "1/1000"}, {"7/2", "0"}};
    rs_qdpoly_t N, D;
    slong d, k;
    fmpq_t zr, zi;
    (void) state;
    rs_qdpoly_init(N); rs_qdpoly_init(D);
    fmpq_init(zr); fmpq_init(zi);
    rs_methods_rk_stability_named_qd(N->p0, N->p1, D->p0, D->p1, &d, "sdirk2");
    for (k = 0; k < (slong) (sizeof Z / sizeof Z[0]); k++) {
        double complex y;
        fmpq_set_str(zr, Z[k][0], 10); fmpq_canonicalise(zr);
        fmpq_set_str(zi, Z[k][1], 10); fmpq_canonicalise(zi);
        y = sdirk2_step(fmpq_get_d(zr) + I * fmpq_get_d(zi));
        assert_true(fabs(cabs(y) - 1.0) > 1e-9);
        assert_int_equal(rs_qd_onestep_stable_at(N, D, d, zr, zi), cabs(y) < 1.0);
    }
    fmpq_zero(zr); fmpq_zero(zi);
    assert_int_equal(rs_qd_onestep_stable_at(N, D, d, zr, zi), 0);
    /* z = 1/g = 2 + sqrt 2 is a pole: not a rational point; D(z) != 0 at every rational z */
    fmpq_clear(zr); fmpq_clear(zi);
    rs_qdpoly_clear(N); rs_qdpoly_clear(D);
}

/* x lies in the enclosure's double bounds (widened by 1e-12) */
static int encloses_d(const arb_t b, double x)
{
    arb_t t, u;
    int ok;
    arb_init(t); arb_init(u);
    arb_set(t, b);
    arb_add_error_2exp_si(t, -40);
    arb_set_d(u, x);
    ok = arb_contains(t, u);
    arb_clear(t); arb_clear(u);
    return ok;
}

static void test_intervals(void **state)
{
    rs_qdpoly_t N, D;
    rs_qd_iv_t iv;
    slong d;
    fmpz_poly_t m;
    char *s;
    (void) state;
    rs_qdpoly_init(N); rs_qdpoly_init(D);
    fmpz_poly_init(m);
    rs_methods_rk_stability_named_qd(N->p0, N->p1, D->p0, D->p1, &d, "sdirk2");
    rs_qd_iv_init(iv);
    assert_int_equal(rs_qd_onestep_interval(iv, N, D, d, 0), 0);
    assert_int_equal(iv->lo->inf, -1);
    assert_int_equal(iv->hi->inf, 0);
    assert_true(fmpq_is_zero(iv->hi->q));
    assert_int_equal(rs_qd_onestep_interval(iv, N, D, d, 1), 0);
    assert_true(iv->lo->inf == -1 && iv->hi->inf == 1);
    rs_qd_iv_clear(iv);

    qdpoly_set(N, "1:0 0:1/3 -1/6:1/6");
    qdpoly_set(D, "1:0 -1:1/3 1/3:-1/6");
    rs_qd_iv_init(iv);
    assert_int_equal(rs_qd_onestep_interval(iv, N, D, 3, 1), 0);
    assert_true(iv->lo->inf == 0 && iv->hi->inf == 0 && fmpq_is_zero(iv->lo->q) && fmpq_is_zero(iv->hi->q));
    assert_int_equal(rs_qd_onestep_interval(iv, N, D, 3, 0), 0);
    assert_true(iv->lo->inf == 0 && iv->hi->inf == 0 && fmpq_is_zero(iv->hi->q));
    fmpz_poly_set_str(m, "3  -12 12 1");
    if (fmpz_sgn(iv->lo->minpoly->coeffs + 2) < 0) fmpz_poly_neg(m, m);
    assert_true(fmpz_poly_equal(iv->lo->minpoly, m));
    assert_true(encloses_d(iv->lo->x, -6.0 - 4.0 * sqrt(3.0)));
    s = rs_qd_end_get_str(iv->lo);
    assert_non_null(strstr(s, "root of x^2+12*x-12"));
    flint_free(s);
    rs_qd_iv_clear(iv);
    fmpz_poly_clear(m);
    rs_qdpoly_clear(N); rs_qdpoly_clear(D);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sign),
        cmocka_unit_test(test_sdirk2_R),
        cmocka_unit_test(test_astability),
        cmocka_unit_test(test_nonneg_hurwitz),
        cmocka_unit_test(test_schur),
        cmocka_unit_test(test_schur_random),
        cmocka_unit_test(test_stable_at),
        cmocka_unit_test(test_intervals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
