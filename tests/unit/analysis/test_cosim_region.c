/* test_cosim_region.c -- region and claim of exactly integrated subsystems
 * (issue 14 part 1; src/analysis/an_cosim_region.c, src/numeric/cosim_ball.c).
 * Independent check: a literal time loop of the scheme, written here from
 * Li et al.'s definition (their eq. 3, 4, 7 and the explicit k = 0 step:
 * the coupling force lambda_c = acc1 c1 (x2 - x1) + adc1 d1 (v2 - v1) is
 * sampled at T_N and held constant while both subsystems are integrated
 * over the macro step H = 1 by classical RK4 with 200 substeps); its growth
 * rate per macro step on either side of each certified transition must be
 * below 1 on the stable side and above 1 on the unstable side.  It shares
 * no code with recstab (no exponentials, no eigenvalues). */
#include "testutil.h"
#include <math.h>
#include <string.h>
#include <stdlib.h>
#include <jansson.h>
#include "recstab/api.h"

#define CASE RS_SOURCE_DIR "/cases/li-explicit-k0.case"

/* the case's set values: c1 = 101/100, d1 = 1/5, all alphas 1 except acc1 */
typedef struct { double c1, d1, acc1, adc1; } model_t;

static void rhs(const model_t *m, const double *z, double lc, double *dz)
{
    dz[0] = z[1];
    dz[1] = -m->c1 * z[0] - m->d1 * z[1] + lc;
    dz[2] = z[3];
    dz[3] = -m->c1 * z[2] - m->d1 * z[3] - lc;
}

/* growth per macro step of the explicit k = 0 co-simulation, measured
 * between steps 1000 and 4000 (the in-phase mode e^{-d1/2} has died out) */
static double time_loop_growth(const model_t *m)
{
    double z[4] = {1.0, 0.3, -0.7, 0.2}, l1 = 0.0, h = 1.0 / 200;
    int N, s, i;
    for (N = 1; N <= 4000; N++) {
        double lc = m->acc1 * m->c1 * (z[2] - z[0]) + m->adc1 * m->d1 * (z[3] - z[1]), nrm = 0;
        for (s = 0; s < 200; s++) {
            double k1[4], k2[4], k3[4], k4[4], t[4];
            rhs(m, z, lc, k1);
            for (i = 0; i < 4; i++) t[i] = z[i] + 0.5 * h * k1[i];
            rhs(m, t, lc, k2);
            for (i = 0; i < 4; i++) t[i] = z[i] + 0.5 * h * k2[i];
            rhs(m, t, lc, k3);
            for (i = 0; i < 4; i++) t[i] = z[i] + h * k3[i];
            rhs(m, t, lc, k4);
            for (i = 0; i < 4; i++) z[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
        }
        for (i = 0; i < 4; i++) nrm += z[i] * z[i];
        if (N == 1000) l1 = 0.5 * log(nrm);
        if (N == 4000) return exp((0.5 * log(nrm) - l1) / 3000.0);
    }
    return 0;
}

static json_t *run_file(const char *file, const char *request, int *status)
{
    const char *an[2] = {request, NULL};
    char *text = NULL, *out = NULL;
    FILE *f = fopen(file, "r");
    long n;
    json_t *doc;
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    rewind(f);
    text = calloc((size_t) n + 1, 1);
    assert_true(fread(text, 1, (size_t) n, f) == (size_t) n);
    fclose(f);
    *status = rs_analyse_json_with(text, file, NULL, an, 0, 120, -1, &out);
    doc = json_loads(out, 0, NULL);
    rs_free(out);
    free(text);
    assert_non_null(doc);
    return doc;
}

static json_t *run(const char *request, int *status)
{
    return run_file(CASE, request, status);
}

/* the document is {"cases": [DOC]} (one shape for every run) */
static const json_t *first_result(const json_t *doc)
{
    return json_array_get(json_object_get(json_array_get(json_object_get(doc, "cases"), 0), "results"), 0);
}

static double encl(const json_t *t, size_t i)
{
    return atof(json_string_value(json_array_get(json_object_get(t, "enclosure"), i)));
}

static void test_region_transition(void **state)
{
    int status;
    json_t *doc = run("region acc1 from 1/10 to 2", &status);
    const json_t *o = first_result(doc), *tr = json_object_get(o, "transitions"), *t;
    model_t m = {1.01, 0.2, 0, 1};
    double lo, hi, g_below, g_above;
    (void) state;
    assert_int_equal(status, 0);
    assert_true(json_is_true(json_object_get(o, "certified")));
    assert_int_equal(json_array_size(tr), 1);
    assert_int_equal(json_array_size(json_object_get(o, "unseparated")), 0);
    t = json_array_get(tr, 0);
    assert_string_equal(json_string_value(json_object_get(t, "from")), "stable");
    assert_string_equal(json_string_value(json_object_get(t, "to")), "unstable");
    lo = encl(t, 0);
    hi = encl(t, 1);
    /* narrower than 10^-15 (digits=15), printed outward with 20 digits */
    assert_true(hi > lo && hi - lo < 1e-15);
    /* the intervals: [1/10, transition) stable, (transition, 2] unstable */
    assert_int_equal(json_array_size(json_object_get(o, "intervals")), 2);
    assert_non_null(json_object_get(json_array_get(json_object_get(o, "intervals"), 0), "hi_enclosure"));
    /* the time loop 1/100 on either side */
    m.acc1 = lo - 0.01;
    g_below = time_loop_growth(&m);
    m.acc1 = hi + 0.01;
    g_above = time_loop_growth(&m);
    print_message("transition in [%.17g, %.17g]; time loop growth %.6f below, %.6f above\n", lo, hi, g_below,
                  g_above);
    assert_true(g_below < 0.999);
    assert_true(g_above > 1.001);
    json_decref(doc);
}

/* digits=N is honoured (it was ignored: 15 always): the enclosure is
 * narrower than 10^-6 and contains the transition found with 15 digits */
static void test_region_digits(void **state)
{
    int status;
    json_t *doc = run("region acc1 from 1/10 to 2 digits=6", &status), *doc15;
    const json_t *o = first_result(doc), *t;
    double lo, hi, lo15, hi15;
    (void) state;
    assert_int_equal(status, 0);
    assert_int_equal(json_integer_value(json_object_get(o, "digits")), 6);
    t = json_array_get(json_object_get(o, "transitions"), 0);
    lo = encl(t, 0);
    hi = encl(t, 1);
    assert_true(hi > lo && hi - lo < 1e-6);
    doc15 = run("region acc1 from 1/10 to 2", &status);
    t = json_array_get(json_object_get(first_result(doc15), "transitions"), 0);
    lo15 = encl(t, 0);
    hi15 = encl(t, 1);
    assert_true(lo <= lo15 && hi15 <= hi);
    assert_true(json_integer_value(json_object_get(o, "boxes"))
                < json_integer_value(json_object_get(first_result(doc15), "boxes")));
    json_decref(doc);
    json_decref(doc15);
}

static void test_claims(void **state)
{
    int status;
    json_t *doc;
    const json_t *o, *cx;
    model_t m = {1.01, 0.2, 0, 1};
    (void) state;
    /* below the transition (time loop at the ends: decays) */
    doc = run("claim stable when 1/10 <= acc1 <= 1/2", &status);
    o = first_result(doc);
    assert_int_equal(status, 0);
    assert_string_equal(json_string_value(json_object_get(o, "status")), "proved");
    json_decref(doc);
    m.acc1 = 0.5;
    assert_true(time_loop_growth(&m) < 1);
    /* two parameters: a box in (acc1, adc1) */
    doc = run("claim stable when 1/5 <= acc1 <= 1/2 and 9/10 <= adc1 <= 11/10", &status);
    o = first_result(doc);
    assert_int_equal(status, 0);
    assert_string_equal(json_string_value(json_object_get(o, "status")), "proved");
    json_decref(doc);
    /* across the transition: refuted by a certified point the time loop confirms */
    doc = run("claim stable when 1/2 <= acc1 <= 7/10", &status);
    o = first_result(doc);
    assert_int_equal(status, 1);
    assert_string_equal(json_string_value(json_object_get(o, "status")), "refuted");
    cx = json_object_get(o, "counterexample");
    assert_non_null(cx);
    {
        const char *s = json_string_value(json_object_get(cx, "acc1"));
        long a, b;
        assert_int_equal(sscanf(s, "%ld/%ld", &a, &b), 2);
        m.acc1 = (double) a / (double) b;
        assert_true(m.acc1 > 0.598 && m.acc1 <= 0.7);
        assert_true(time_loop_growth(&m) > 1);
    }
    json_decref(doc);
    doc = run("claim unstable when 3/5 <= acc1 <= 2", &status);
    o = first_result(doc);
    assert_int_equal(status, 0);
    assert_string_equal(json_string_value(json_object_get(o, "status")), "proved");
    json_decref(doc);
}


/* claim bounded: proved where rho < 1 is certified on every sub-box (the
 * time loop decays at the box's end), refuted by a certified point rho > 1
 * (the time loop grows there), and undecided where rho = 1: two uncoupled
 * undamped oscillators (cases/cosim/undamped-bounded.case, k = 0) integrated
 * exactly are two rotations [[cos w, sin w/w], [-w sin w, cos w]] (closed
 * form): determinant cos^2 w + sin^2 w = 1 and |trace| = |2 cos w| < 2 for
 * w in [1/2, 1], so the eigenvalues e^{+-i w} lie ON the circle, distinct
 * within a block, semisimple: bounded, not stable -- neither "proved" (that
 * would need rho < 1) nor "refuted" (rho > 1 nowhere) is a sound answer. */
static void test_bounded(void **state)
{
    int status;
    json_t *doc;
    const json_t *o, *cx;
    model_t m = {1.01, 0.2, 0, 1};
    double w = 0.75, c = cos(w), sn = sin(w);
    (void) state;
    doc = run("claim bounded when 1/10 <= acc1 <= 1/2", &status);
    o = first_result(doc);
    assert_int_equal(status, 0);
    assert_string_equal(json_string_value(json_object_get(o, "claim")), "bounded");
    assert_string_equal(json_string_value(json_object_get(o, "status")), "proved");
    assert_non_null(json_object_get(o, "proved_by"));
    json_decref(doc);
    m.acc1 = 0.5;
    assert_true(time_loop_growth(&m) < 1);
    doc = run("claim bounded when 1/2 <= acc1 <= 7/10", &status);
    o = first_result(doc);
    assert_int_equal(status, 1);
    assert_string_equal(json_string_value(json_object_get(o, "status")), "refuted");
    cx = json_object_get(o, "counterexample");
    assert_non_null(cx);
    {
        long a, b;
        assert_int_equal(sscanf(json_string_value(json_object_get(cx, "acc1")), "%ld/%ld", &a, &b), 2);
        m.acc1 = (double) a / (double) b;
        /* rho = 1.00068 there (certified); the loop measures the growth over 3000 steps */
        assert_true(time_loop_growth(&m) > 1.0003);
    }
    json_decref(doc);
    doc = run_file(RS_SOURCE_DIR "/cases/cosim/undamped-bounded.case",
                   "claim bounded when 1/2 <= w <= 1 and 0 <= k <= 0", &status);
    o = first_result(doc);
    assert_int_equal(status, 1);
    assert_string_equal(json_string_value(json_object_get(o, "status")), "undecided");
    assert_non_null(json_object_get(o, "failed_at"));
    assert_non_null(strstr(json_string_value(json_object_get(o, "not_proved")), "rho < 1"));
    assert_null(json_object_get(o, "counterexample"));
    /* the closed form at the named centre w = 3/4: |lambda| = 1 exactly */
    assert_string_equal(json_string_value(json_object_get(json_object_get(o, "centre"), "w")), "3/4");
    assert_true(fabs(c * c + sn * sn - 1) < 1e-15 && fabs(2 * c) < 2);
    json_decref(doc);
}


/* sweep ... of modes (cases/cosim/undamped-sweep-modes.case): two undamped
 * oscillators x'' = -w^2 x, lc = k (x2 - x1) held over the macro step 1
 * (explicit order 0), k = 1/10.  Closed form, derived by hand: the in-phase
 * motion is exact, eigenvalues e^{+-i w}; the anti-phase y = x2 - x1 obeys
 * y'' = -w^2 y - 2 k y_N, so y_{N+1} = (cos w (1 + p) - p) y_N + sin w / w v_N,
 * v_{N+1} = -w (1 + p) sin w y_N + cos w v_N, p = 2k/w^2.  Every one of the
 * four eigenvalues must lie in a reported enclosure (15 digits), the radius
 * columns enclose max |mu|, and reference=w names the in-phase mode:
 * damping ratio 0, frequency error 0, omega = w. */
static void test_sweep_modes(void **state)
{
    int status;
    json_t *doc = run_file(RS_SOURCE_DIR "/cases/cosim/undamped-sweep-modes.case",
                           "sweep w from 1/2 to 1 steps 5 of modes reference=w", &status);
    const json_t *o = first_result(doc), *rows = json_object_get(o, "rows"), *cols = json_object_get(o, "columns");
    const json_t *eig = json_object_get(o, "eigenvalues");
    size_t i, j, c, ncol = json_array_size(cols), irad = 0, izeta = 0, ifreq = 0, iom = 0;
    (void) state;
    assert_int_equal(status, 0);
    assert_string_equal(json_string_value(json_object_get(o, "of")), "modes");
    assert_int_equal(json_array_size(rows), 6);
    assert_int_equal(json_array_size(eig), 6);
    for (c = 0; c < ncol; c++) {
        const char *n = json_string_value(json_array_get(cols, c));
        if (strcmp(n, "radius_upper") == 0) irad = c;
        if (strcmp(n, "damping_ratio_1") == 0) izeta = c;
        if (strcmp(n, "frequency_error_1") == 0) ifreq = c;
        if (strcmp(n, "omega_1") == 0) iom = c;
    }
    assert_true(irad > 0 && izeta > 0 && ifreq > 0 && iom > 0);
    for (i = 0; i < 6; i++) {
        const json_t *row = json_array_get(rows, i), *ev = json_array_get(eig, i);
        double w = 0.5 + 0.1 * (double) i, k = 0.1, p = 2 * k / (w * w);
        double a = cos(w) * (1 + p) - p, b = sin(w) / w, cc = -w * (1 + p) * sin(w), d = cos(w);
        double tr = a + d, det = a * d - b * cc, disc = tr * tr / 4 - det;
        double mre[4], mim[4], rho;
        assert_true(disc < 0);   /* a complex pair */
        mre[0] = mre[1] = tr / 2;
        mim[0] = sqrt(-disc);
        mim[1] = -mim[0];
        mre[2] = mre[3] = cos(w);
        mim[2] = sin(w);
        mim[3] = -sin(w);
        rho = sqrt(det);
        assert_int_equal(json_array_size(ev), 4);
        for (j = 0; j < 4; j++) {
            int found = 0;
            for (c = 0; c < 4; c++) {
                const json_t *e = json_array_get(ev, c);
                double re = atof(json_string_value(json_object_get(e, "re"))),
                       im = atof(json_string_value(json_object_get(e, "im")));
                if (hypot(re - mre[j], im - mim[j]) < 1e-12) found = 1;
            }
            if (!found) fail_msg("w = %g: closed-form eigenvalue %.15g%+.15gi not reported", w, mre[j], mim[j]);
        }
        assert_true(fabs(json_number_value(json_array_get(row, irad)) - rho) < 1e-12);
        assert_true(fabs(json_number_value(json_array_get(row, izeta))) < 1e-12);
        assert_true(fabs(json_number_value(json_array_get(row, ifreq))) < 1e-12);
        assert_true(fabs(json_number_value(json_array_get(row, iom)) - w) < 1e-12);
    }
    json_decref(doc);
}

static void test_errors(void **state)
{
    int status;
    json_t *doc;
    (void) state;
    doc = run("region nosuch from 0 to 1", &status);
    assert_int_equal(status, 2);
    assert_non_null(strstr(json_string_value(json_object_get(json_object_get(doc, "error"), "message")),
                           "expected a parameter"));
    json_decref(doc);
    doc = run("region acc1 from 1 to 1/2", &status);
    assert_int_equal(status, 2);
    json_decref(doc);
    doc = run("claim stable when acc1 <= 1", &status);
    assert_int_equal(status, 2);
    json_decref(doc);
    /* the text after the interval is options: unknown words are errors (they were ignored) */
    doc = run("region acc1 from 1/10 to 2 garbage", &status);
    assert_int_equal(status, 2);
    assert_non_null(strstr(json_string_value(json_object_get(json_object_get(doc, "error"), "message")),
                           "expected an option (digits=)"));
    json_decref(doc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_region_transition),
        cmocka_unit_test(test_region_digits),
        cmocka_unit_test(test_claims),
        cmocka_unit_test(test_bounded),
        cmocka_unit_test(test_sweep_modes),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
