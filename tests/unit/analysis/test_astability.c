/* test_astability.c -- `analyse astability` on the bundled cases/complex/
 * cases, each expected value from a source in the literature and re-derived
 * here independently of recstab's exact code:
 *   - rk4: R(x) = 1 solved by bisection in double on the closed form of R,
 *     the imaginary end 2 sqrt 2 from |R(iy)|^2 = 1 - y^6/72 + y^8/576;
 *   - BDF3..6 A(alpha) (Hairer and Wanner, Solving ODEs II, Table V.2.3:
 *     86.03, 73.35, 51.84, 17.84 degrees) re-derived by a literal dense scan
 *     of the locus z(phi) = rho(e^{i phi})/sigma(e^{i phi}) in complex double,
 *     rho built here from its definition sum_j (1/j) nabla^j;
 *   - BDF1..6 zero-stable, BDF7 not (Hairer, Norsett, Wanner I, Theorem
 *     III.3.4): the roots of rho(lambda)/(lambda - 1) isolated with Arb;
 *   - Adams real intervals: z = rho(-1)/sigma(-1) by hand (case comments);
 *   - trapezoid / implicit midpoint R(inf) = -1, Radau IIA R(inf) = 0;
 *   - over Q(i) (complex set values, a char line with i): the theta method
 *     with complex weight a = alpha + i beta, whose region is
 *     2 Re z + (1 - 2 alpha)|z|^2 < 0 by expanding |R(z)| < 1 by hand (the
 *     case comment), checked again here on |R| in complex double; the
 *     rotated Euler root lambda = 1 + i z. */
#include "analysis/an_qd.h"   /* before cmocka: FLINT's headers */
#include "testutil.h"
#include <string.h>
#include <math.h>
#include <complex.h>
#include <arb_fmpz_poly.h>
#include <flint/fmpq_poly.h>
#include <acb.h>
#include "recstab/analysis.h"

#define PI_D 3.14159265358979323846

static json_t *run(const char *rel, json_t **res)
{
    int outcome;
    json_t *doc = tu_run_case(rel, NULL, -1, &outcome);
    *res = json_array_get(json_object_get(doc, "results"), 0);
    assert_string_equal(json_string_value(json_object_get(*res, "analysis")), "astability");
    return doc;
}

/* the evidence of the rays route (any p), NULL without one */
static const json_t *rays_evidence(const json_t *r)
{
    const json_t *ev = json_object_get(r, "evidence");
    size_t i;
    for (i = 0; i < json_array_size(ev); i++) {
        const char *route = json_string_value(json_object_get(json_array_get(ev, i), "route"));
        if (route != NULL && strncmp(route, "any method: rays", 16) == 0) return json_array_get(ev, i);
    }
    return NULL;
}

/* an interval end as a double: integers, "-inf"/"inf", {"approx"} */
static double end_value(const json_t *iv, size_t i)
{
    const json_t *e = json_array_get(iv, i);
    if (json_is_integer(e)) return (double) json_integer_value(e);
    if (json_is_string(e)) return json_string_value(e)[0] == '-' ? -INFINITY : INFINITY;
    assert_true(json_is_object(e));
    return json_real_value(json_object_get(e, "approx"));
}

static double rk4_R(double x) { return 1 + x + x * x / 2 + x * x * x / 6 + x * x * x * x / 24; }

static void test_rk4(void **state)
{
    json_t *r, *doc = run("cases/complex/rk4-astability.case", &r);
    const json_t *re = json_object_get(r, "real_interval"), *im = json_object_get(r, "imag_interval");
    double lo = -3, hi = -2.5, y;
    int k;
    (void) state;
    /* R(-3) > 1 > R(-2.5): bisection on R(x) - 1 */
    for (k = 0; k < 200; k++) {
        double m = (lo + hi) / 2;
        if (rk4_R(m) > 1) lo = m; else hi = m;
    }
    assert_true(fabs(end_value(re, 0) - lo) < 1e-12);
    assert_string_equal(json_string_value(json_object_get(json_array_get(re, 0), "minpoly")), "q^3 + 4*q^2 + 12*q + 24");
    assert_int_equal(json_integer_value(json_array_get(re, 1)), 0);
    /* |R(iy)|^2 - 1 = y^6 (y^2 - 8)/576 */
    y = sqrt(8.0);
    assert_true(fabs(end_value(im, 1) - y) < 1e-12);
    assert_true(fabs(end_value(im, 0) + y) < 1e-12);
    assert_string_equal(json_string_value(json_object_get(json_array_get(im, 1), "minpoly")), "q^2 - 8");
    assert_false(json_is_true(json_object_get(r, "a_stable")));
    assert_string_equal(json_string_value(json_object_get(r, "limit_at_infinity")), "inf");
    json_decref(doc);
}

/* rho of BDFk (coefficient of lambda^j in rho[j]), from sum_{j=1..k} (1/j) nabla^j y[n+1] */
static void bdf_rho(fmpq_poly_t rho, int k)
{
    int j, m;
    fmpq_t c;
    fmpq_init(c);
    fmpq_poly_zero(rho);
    for (j = 1; j <= k; j++) {
        fmpz_t b;
        fmpz_init(b);
        for (m = 0; m <= j; m++) {
            fmpq_t old;
            fmpq_init(old);
            fmpz_bin_uiui(b, (ulong) j, (ulong) m);
            fmpq_set_fmpz_frac(c, b, (fmpz_t) {j});
            if (m % 2) fmpq_neg(c, c);
            fmpq_poly_get_coeff_fmpq(old, rho, k - m);
            fmpq_add(old, old, c);
            fmpq_poly_set_coeff_fmpq(rho, k - m, old);
            fmpq_clear(old);
        }
        fmpz_clear(b);
    }
    fmpq_clear(c);
}

/* alpha by a dense scan of the locus z = rho(e^{i phi}) / e^{i k phi} */
static double bdf_alpha_scan(int k)
{
    fmpq_poly_t rho;
    double c[8] = {0}, best = 90;
    long i, N = 400000;
    int j;
    fmpq_poly_init(rho);
    bdf_rho(rho, k);
    for (j = 0; j <= k; j++) {
        fmpq_t x;
        fmpq_init(x);
        fmpq_poly_get_coeff_fmpq(x, rho, j);
        c[j] = fmpq_get_d(x);
        fmpq_clear(x);
    }
    for (i = 1; i < N; i++) {
        double phi = PI_D * (double) i / (double) N;
        double complex l = cexp(I * phi), z = 0;
        for (j = k; j >= 0; j--) z = z * l + c[j];
        z /= cpow(l, k);
        if (creal(z) < 0) {
            double a = atan(fabs(cimag(z)) / -creal(z)) * 180 / PI_D;
            if (a < best) best = a;
        }
    }
    fmpq_poly_clear(rho);
    return best;
}

static void test_bdf_alpha(void **state)
{
    static const double table[] = {86.03, 73.35, 51.84, 17.84};   /* Hairer-Wanner II, Table V.2.3 */
    int k;
    (void) state;
    for (k = 3; k <= 6; k++) {
        char rel[80];
        json_t *r, *doc;
        double a, scan = bdf_alpha_scan(k);
        snprintf(rel, sizeof rel, "cases/complex/bdf%d-astability.case", k);
        doc = run(rel, &r);
        a = json_real_value(json_object_get(r, "alpha_degrees_approx"));
        assert_true(fabs(a - table[k - 3]) < 0.005);
        assert_true(fabs(a - scan) < 1e-4);
        assert_false(json_is_true(json_object_get(r, "a_stable")));
        assert_true(json_is_object(json_object_get(r, "alpha_degrees")));
        /* the rays route (any p) decided the same angle: the analysis
         * exits 3 otherwise, and says so in its evidence */
        assert_true(json_is_true(json_object_get(rays_evidence(r), "alpha_agrees")));
        assert_false(json_is_true(json_object_get(rays_evidence(r), "every_ray_inside")));
        json_decref(doc);
    }
}

/* max |root| of rho(lambda)/(lambda - 1), certified by Arb */
static int bdf_zero_stable(int k)
{
    fmpq_poly_t rho, d, qq;
    fmpz_poly_t z;
    acb_ptr r;
    arb_t ab, one;
    slong i, n;
    int ok = 1;
    fmpq_poly_init(rho); fmpq_poly_init(d); fmpq_poly_init(qq);
    fmpz_poly_init(z);
    arb_init(ab); arb_init(one);
    bdf_rho(rho, k);
    fmpq_poly_set_coeff_si(d, 1, 1);
    fmpq_poly_set_coeff_si(d, 0, -1);
    fmpq_poly_div(qq, rho, d);
    fmpq_poly_get_numerator(z, qq);
    n = fmpz_poly_degree(z);
    r = _acb_vec_init(n);
    arb_fmpz_poly_complex_roots(r, z, 0, 128);
    arb_one(one);
    for (i = 0; i < n; i++) {
        acb_abs(ab, r + i, 128);
        if (!arb_lt(ab, one)) ok = 0;
    }
    _acb_vec_clear(r, n);
    arb_clear(ab); arb_clear(one);
    fmpq_poly_clear(rho); fmpq_poly_clear(d); fmpq_poly_clear(qq);
    fmpz_poly_clear(z);
    return ok;
}

static void test_bdf_zero_stability(void **state)
{
    int k;
    (void) state;
    for (k = 1; k <= 7; k++) {
        char rel[80];
        json_t *r, *doc;
        const json_t *re;
        snprintf(rel, sizeof rel, "cases/complex/bdf%d-astability.case", k);
        doc = run(rel, &r);
        re = json_object_get(r, "real_interval");
        assert_int_equal(bdf_zero_stable(k), k <= 6);
        if (k <= 6) {
            /* zero-stable, and the whole negative real axis (A(0) for every k <= 6) */
            assert_true(json_is_array(re));
            assert_true(end_value(re, 0) == -INFINITY);
            assert_int_equal(json_integer_value(json_array_get(re, 1)), 0);
            /* rho's spurious roots vanish as z -> inf: sigma = lambda^k */
            assert_int_equal(json_integer_value(json_object_get(r, "limit_at_infinity")), 0);
            assert_int_equal(json_is_true(json_object_get(r, "a_stable")), k <= 2);
            assert_int_equal(json_is_true(json_object_get(r, "l_stable")), k <= 2);
        } else {
            assert_true(json_is_null(re));
        }
        json_decref(doc);
    }
}

static void test_a_and_l_stability(void **state)
{
    static const struct { const char *rel; int limit; int l_stable; } c[] = {
        {"cases/complex/trapezoid-astability.case", 1, 0},          /* R(inf) = -1 */
        {"cases/complex/implicit-midpoint-astability.case", 1, 0},  /* the same R */
        {"cases/complex/radau-iia3-astability.case", 0, 1},         /* deg N < deg D */
    };
    size_t i;
    (void) state;
    for (i = 0; i < sizeof c / sizeof c[0]; i++) {
        json_t *r, *doc = run(c[i].rel, &r);
        const json_t *im = json_object_get(r, "imag_interval"), *re = json_object_get(r, "real_interval");
        assert_true(json_is_true(json_object_get(r, "a_stable")));
        assert_int_equal(json_integer_value(json_object_get(r, "limit_at_infinity")), c[i].limit);
        assert_int_equal(json_is_true(json_object_get(r, "l_stable")), c[i].l_stable);
        assert_int_equal(json_integer_value(json_object_get(r, "alpha_degrees")), 90);
        assert_true(end_value(im, 0) == -INFINITY && end_value(im, 1) == INFINITY);
        assert_true(end_value(re, 0) == -INFINITY);
        json_decref(doc);
    }
}

static void test_adams(void **state)
{
    json_t *r, *doc;
    const json_t *e;
    (void) state;
    doc = run("cases/complex/adams-astability.case", &r);
    assert_int_equal(json_integer_value(json_array_get(json_object_get(r, "real_interval"), 0)), -1);
    json_decref(doc);
    doc = run("cases/complex/adams-bashforth3-astability.case", &r);
    e = json_array_get(json_object_get(r, "real_interval"), 0);
    assert_string_equal(json_string_value(json_object_get(e, "exact")), "-6/11");
    json_decref(doc);
    doc = run("cases/complex/adams-moulton2-astability.case", &r);
    assert_int_equal(json_integer_value(json_array_get(json_object_get(r, "real_interval"), 0)), -6);
    /* (4 + sqrt 21)/5 */
    assert_true(fabs(json_real_value(json_object_get(json_object_get(r, "limit_at_infinity"), "approx"))
                     - (4 + sqrt(21.0)) / 5) < 1e-12);
    json_decref(doc);
}

/* |R(z)| of the theta method with complex weight a, in complex double */
static double theta_absR(double complex a, double complex z) { return cabs((1 + (1 - a) * z) / (1 - a * z)); }

static json_t *theta_text(const char *a, json_t **r)
{
    char text[300];
    int outcome;
    json_t *doc;
    snprintf(text, sizeof text, "param q\nparam a\nchar (1 - a*q)*lambda - (1 + (1 - a)*q)\nset a = %s\n"
             "analyse astability q\n", a);
    doc = tu_run_text(text, NULL, &outcome, NULL);
    *r = json_array_get(json_object_get(doc, "results"), 0);
    assert_string_equal(json_string_value(json_object_get(*r, "over")), "Q(i)");
    return doc;
}

static void test_complex_set(void **state)
{
    json_t *r, *doc;
    const json_t *re, *im;
    double x;
    (void) state;
    /* a = 1 + i/2: outside |z - 1| < 1, A-stable, |R(inf)| = 1/sqrt 5 */
    doc = run("cases/complex/theta-complex-astability.case", &r);
    re = json_object_get(r, "real_interval");
    im = json_object_get(r, "imag_interval");
    assert_string_equal(json_string_value(json_object_get(r, "over")), "Q(i)");
    assert_true(json_is_true(json_object_get(r, "a_stable")));
    assert_true(end_value(re, 0) == -INFINITY && end_value(re, 1) == 0);
    assert_true(end_value(im, 0) == -INFINITY && end_value(im, 1) == INFINITY);
    assert_true(fabs(json_real_value(json_object_get(json_object_get(r, "limit_at_infinity"), "approx"))
                     - 1 / sqrt(5.0)) < 1e-12);
    assert_true(fabs(theta_absR(1 + 0.5 * I, 1e9) - 1 / sqrt(5.0)) < 1e-6);
    assert_false(json_is_true(json_object_get(r, "l_stable")));
    /* just right of 0 on the real axis unstable, on the imaginary axis stable */
    assert_true(theta_absR(1 + 0.5 * I, 1e-3) > 1 && theta_absR(1 + 0.5 * I, 3 * I) < 1);
    json_decref(doc);
    /* a = 1/4 + i: 2x + |z|^2/2 < 0, the disc |z + 2| < 2: real [-4, 0], imaginary [0, 0] */
    doc = theta_text("1/4 + i", &r);
    re = json_object_get(r, "real_interval");
    im = json_object_get(r, "imag_interval");
    assert_int_equal(json_integer_value(json_array_get(re, 0)), -4);
    assert_int_equal(json_integer_value(json_array_get(re, 1)), 0);
    assert_int_equal(json_integer_value(json_array_get(im, 0)), 0);
    assert_int_equal(json_integer_value(json_array_get(im, 1)), 0);
    for (x = -3.99; x < 0; x += 0.01) assert_true(theta_absR(0.25 + I, x) < 1 + 1e-12);
    assert_true(theta_absR(0.25 + I, -4.01) > 1 && theta_absR(0.25 + I, 0.01 * I) > 1);
    assert_false(json_is_true(json_object_get(r, "a_stable")));
    assert_true(json_is_null(json_object_get(r, "alpha_degrees")));
    json_decref(doc);
    /* BDF3 on y' = a q y with |a| = 1, a = 3/5 + 4/5 i: the region of q is BDF3's turned by -arg a, so
     * its A(alpha) angle is BDF3's (the dense scan here) less arg a = atan2(4, 3), and the positive
     * imaginary axis (a i y has arg(-a i y) = -36.87 degrees) lies in it, the negative one not */
    {
        int outcome;
        doc = tu_run_text("param q\nparam a\nsubsystem S state y\n  y' = a*q*y\nintegrate S bdf 3 1\n"
                          "set a = 3/5 + 4/5*i\nanalyse astability q\n", NULL, &outcome, NULL);
        r = json_array_get(json_object_get(doc, "results"), 0);
        assert_true(fabs(json_real_value(json_object_get(r, "alpha_degrees_approx"))
                         - (bdf_alpha_scan(3) - atan2(4.0, 3.0) * 180 / PI_D)) < 1e-4);
        im = json_object_get(r, "imag_interval");
        assert_true(end_value(im, 0) == 0 && end_value(im, 1) == INFINITY);
        assert_false(json_is_true(json_object_get(r, "a_stable")));
        json_decref(doc);
    }
    /* a = 1/2 + i/4: 2 Re z < 0, exactly the left half-plane; |R(inf)| = |1 - a|/|a| = 1 */
    doc = theta_text("1/2 + i/4", &r);
    assert_true(json_is_true(json_object_get(r, "a_stable")));
    assert_int_equal(json_integer_value(json_object_get(r, "alpha_degrees")), 90);
    assert_true(fabs(json_real_value(json_object_get(json_object_get(r, "limit_at_infinity"), "approx")) - 1) < 1e-12);
    json_decref(doc);
}

/* the boundary locus of p = a(l) z^2 + b(l) z + c(l), l = e^{i phi} (a dense
 * scan in complex double, both roots z of the quadratic): the least
 * |arg(-z)| in degrees over its points with Re z < 0 (*minre: the least
 * Re z).  Every boundary point of the region is on the locus, so the angle
 * is a lower bound of alpha. */
static double quad_locus_scan(void (*abc)(double complex *, double complex), double *minre)
{
    double best = 90, mr = INFINITY;
    long j, n = 200000;
    for (j = 1; j < n; j++) {
        double complex l = cexp(I * 2 * PI_D * (double) j / (double) n), c[3], d, z[2];
        int k;
        abc(c, l);
        d = csqrt(c[1] * c[1] - 4 * c[0] * c[2]);
        z[0] = (-c[1] + d) / (2 * c[0]);
        z[1] = (-c[1] - d) / (2 * c[0]);
        for (k = 0; k < 2; k++) {
            if (creal(z[k]) < mr) mr = creal(z[k]);
            if (creal(z[k]) < 0) best = fmin(best, atan(fabs(cimag(z[k]) / creal(z[k]))) * 180 / PI_D);
        }
    }
    *minre = mr;
    return best;
}

/* Enright k = 3 and k = 2 (case comments: the method's definition times
 * 1080 and 48, by hand), as a z^2 + b z + c */
static void enright3_abc(double complex *c, double complex l)
{
    c[0] = 114 * l * l * l;
    c[1] = -614 * l * l * l - 513 * l * l + 54 * l - 7;
    c[2] = 1080 * l * l * l - 1080 * l * l;
}

static void enright2_abc(double complex *c, double complex l)
{
    c[0] = 6 * l * l;
    c[1] = -29 * l * l - 20 * l + 1;
    c[2] = 48 * l * l - 48 * l;
}

/* p of degree 2 in z and 2 or 3 in lambda, and a one-step method over Q(i):
 * neither the boundary locus (linear in z) nor the one-step rays apply, the
 * rays route (any p) decides */
static void test_rays_route(void **state)
{
    json_t *r, *doc;
    const json_t *a;
    double lo, minre, got;
    (void) state;
    /* Enright k = 3: the locus scan bounds alpha from below; the float ray
     * scan of tests/cli/alpha_rays_poly.py (87.88336280526764, bisection on
     * the rays with |root| <= 1 + 1e-9) from above */
    doc = run("cases/complex/enright3-astability.case", &r);
    lo = quad_locus_scan(enright3_abc, &minre);
    got = json_real_value(json_object_get(r, "alpha_degrees_approx"));
    assert_true(got > lo - 1e-8 && got < 87.88336280526764 + 1e-9);
    assert_false(json_is_true(json_object_get(r, "a_stable")));
    a = json_object_get(r, "alpha_degrees");
    assert_true(json_is_object(a) && json_is_string(json_object_get(a, "tan_alpha_minpoly")));
    assert_true(json_is_object(json_object_get(rays_evidence(r), "first_point_outside")));
    json_decref(doc);
    /* Enright k = 2: the locus stays in Re z >= 0, and at z = -1, p = 83 l^2 - 28 l - 1 has the roots
     * (14 +- sqrt 279)/83 = 0.370, -0.033 (by hand): the open left half-plane is one stable region */
    doc = run("cases/complex/enright2-astability.case", &r);
    quad_locus_scan(enright2_abc, &minre);
    assert_true(minre > -1e-12);
    assert_true(json_is_true(json_object_get(r, "a_stable")));
    assert_int_equal(json_integer_value(json_object_get(r, "alpha_degrees")), 90);
    assert_true(json_is_true(json_object_get(rays_evidence(r), "every_ray_inside")));
    /* p / z^2 -> 6 l^2: both roots -> 0 */
    assert_int_equal(json_integer_value(json_object_get(r, "limit_at_infinity")), 0);
    assert_true(json_is_true(json_object_get(r, "l_stable")));
    json_decref(doc);
    /* the DIRK of dirk-alpha45.case at w q, w = (24 + 7i)/25: tan(alpha) = tan(45 - atan(7/24)) = 17/31
     * (case comment, by hand); the first point outside lies on the side Im q < 0 */
    doc = run("cases/complex/dirk-rotated-alpha.case", &r);
    a = json_object_get(r, "alpha_degrees");
    assert_string_equal(json_string_value(json_object_get(a, "tan_alpha_exact")), "17/31");
    assert_true(fabs(json_real_value(json_object_get(r, "alpha_degrees_approx"))
                     - (45 - atan2(7.0, 24.0) * 180 / PI_D)) < 1e-12);
    assert_false(json_is_true(json_object_get(r, "a_stable")));
    assert_true(json_string_value(json_object_get(json_object_get(rays_evidence(r), "first_point_outside"), "im"))[0]
                == '-');
    json_decref(doc);
}

/* a char line with i, z declared complex: p = lambda - 1 - i z, the one root
 * lambda = 1 + i z; on z = x: |1 + i x| <= 1 iff x = 0; on z = i y:
 * |1 - y| <= 1 iff 0 <= y <= 2 */
static void test_complex_char(void **state)
{
    int outcome;
    json_t *doc = tu_run_text("param z complex\nchar lambda - 1 - i*z\nanalyse astability\n", NULL, &outcome, NULL);
    json_t *r = json_array_get(json_object_get(doc, "results"), 0);
    const json_t *re = json_object_get(r, "real_interval"), *im = json_object_get(r, "imag_interval");
    (void) state;
    assert_int_equal(json_integer_value(json_array_get(re, 0)), 0);
    assert_int_equal(json_integer_value(json_array_get(re, 1)), 0);
    assert_int_equal(json_integer_value(json_array_get(im, 0)), 0);
    assert_int_equal(json_integer_value(json_array_get(im, 1)), 2);
    assert_false(json_is_true(json_object_get(r, "a_stable")));
    assert_string_equal(json_string_value(json_object_get(r, "limit_at_infinity")), "inf");
    json_decref(doc);
}

/* A(alpha) over Q(sqrt d) (rs_an_astability_alpha_qd, the rays route):
 *  - the Pade (0, 3) approximation at sqrt(2) z, R = 1/(1 - sqrt2 z + z^2 -
 *    (sqrt2/3) z^3): z -> sqrt(2) z maps each ray onto itself, so alpha is
 *    that of 1/(1 - z + z^2/2 - z^3/6), 88.23015200721602..88.23015200721609
 *    degrees by a float ray scan (bisection on max_r |R(-r e^{i theta})| <= 1,
 *    tests/cli/alpha_sdirk3.py pade03, which also derives tan(alpha)'s
 *    minimal polynomial with sympy);
 *  - sdirk3 (gamma = (3 + sqrt 3)/6) A-stable (Hairer and Wanner II, IV.6):
 *    every ray inside; sdirk3-low: |R(inf)| = 1 + sqrt 3 > 1 (by hand, the
 *    case comment), so no sector lies in the region: alpha = 0. */
static void test_alpha_qd(void **state)
{
    rs_qdpoly_t N, D;
    rs_qd_t c;
    json_t *out, *ev, *doc, *r;
    arb_t deg;
    int inside;
    rs_error_t err;
    double got;
    (void) state;
    rs_qdpoly_init(N); rs_qdpoly_init(D);
    rs_qd_init(c);
    arb_init(deg);
    rs_error_init(err);
    fmpq_set_si(c->x, 1, 1);
    rs_qdpoly_set_coeff(N, 0, c);
    rs_qdpoly_set_coeff(D, 0, c);
    fmpq_set_si(c->x, 0, 1); fmpq_set_si(c->y, -1, 1);
    rs_qdpoly_set_coeff(D, 1, c);
    fmpq_set_si(c->x, 1, 1); fmpq_set_si(c->y, 0, 1);
    rs_qdpoly_set_coeff(D, 2, c);
    fmpq_set_si(c->x, 0, 1); fmpq_set_si(c->y, -1, 3);
    rs_qdpoly_set_coeff(D, 3, c);
    assert_int_equal(rs_an_astability_alpha_qd(&out, &ev, deg, &inside, N, D, 2, err), RS_OK);
    assert_int_equal(inside, 0);
    got = arf_get_d(arb_midref(deg), ARF_RND_NEAR);
    assert_true(got > 88.23015200721602 - 1e-7 && got < 88.23015200721609 + 1e-7);
    /* tan(alpha)'s minimal polynomial: the factor of disc_s(|N|^2 - |D|^2 on the rays of the rational
     * Pade (0, 3)) with that root, derived by sympy in tests/cli/alpha_sdirk3.py pade03 */
    assert_string_equal(json_string_value(json_object_get(out, "tan_alpha_minpoly")),
                        "81*u^14 - 84830*u^12 - 6537*u^10 - 129912*u^8 - 78065*u^6 - 39990*u^4 - 6711*u^2 - 340");
    assert_string_equal(json_string_value(json_object_get(json_object_get(ev, "first_point_outside"), "status")),
                        "unstable");
    json_decref(out);
    json_decref(ev);
    rs_qdpoly_clear(N); rs_qdpoly_clear(D);
    rs_qd_clear(c);
    arb_clear(deg);
    rs_error_clear(err);
    doc = run("cases/complex/sdirk3-astability.case", &r);
    assert_true(json_is_true(json_object_get(r, "a_stable")));
    assert_int_equal(json_integer_value(json_object_get(r, "alpha_degrees")), 90);
    assert_true(json_is_true(json_object_get(json_array_get(json_object_get(r, "evidence"), 1), "every_ray_inside")));
    json_decref(doc);
    doc = run("cases/complex/sdirk3-low-astability.case", &r);
    assert_false(json_is_true(json_object_get(r, "a_stable")));
    assert_int_equal(json_integer_value(json_object_get(r, "alpha_degrees")), 0);
    json_decref(doc);
}

/* bad requests: exit-2 style errors */
static void test_errors(void **state)
{
    int code, outcome;
    json_t *doc;
    (void) state;
    doc = tu_run_text("param q\nparam w\nchar lambda - 1 - q*w\nanalyse astability\n", NULL, &outcome, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    assert_null(doc);
    doc = tu_run_text("param q\nparam w\nchar lambda - 1 - q*w\nanalyse astability q\n", NULL, &outcome, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    assert_null(doc);
    doc = tu_run_text("param q\nchar lambda - 1 - q\nanalyse astability r\n", NULL, &outcome, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    assert_null(doc);
    /* over Q(i): z itself set to a complex value, and a free real parameter besides z */
    doc = tu_run_text("param q\nchar lambda - 1 - q\nset q = i\nanalyse astability q\n", NULL, &outcome, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    assert_null(doc);
    doc = tu_run_text("param q\nparam a\nparam b\nchar lambda - 1 - a*q - b\nset a = i\nanalyse astability q\n",
                      NULL, &outcome, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    assert_null(doc);
    /* forward Euler from a char line: the disc |1 + z| <= 1, real [-2, 0] */
    doc = tu_run_text("param q\nchar lambda - 1 - q\nanalyse astability\n", NULL, &outcome, NULL);
    assert_int_equal(json_integer_value(json_array_get(json_object_get(json_array_get(json_object_get(doc, "results"), 0),
                                                                       "real_interval"), 0)), -2);
    json_decref(doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rk4),
        cmocka_unit_test(test_bdf_alpha),
        cmocka_unit_test(test_bdf_zero_stability),
        cmocka_unit_test(test_a_and_l_stability),
        cmocka_unit_test(test_adams),
        cmocka_unit_test(test_complex_set),
        cmocka_unit_test(test_complex_char),
        cmocka_unit_test(test_rays_route),
        cmocka_unit_test(test_alpha_qd),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
