/* test_rounding.c -- every printed certified number holds (issue 10, item 5).
 *
 * Printed decimals are parsed back as exact rationals (dec_parse) and checked
 * against true values known in closed form, by exact rational arithmetic:
 *   - a*l^2 + b (a, b > 0): both roots have modulus sqrt(b/a), so rho^2 = b/a;
 *   - products of (a_i*l - b_i): rho = max |b_i/a_i|, a rational;
 *   - l^k - r: every root has modulus r^(1/k), so rho^k = r;
 *   - (a*l^2 + b*l + c)(d*l - e) with b^2 < 4ac (a planted complex pair of
 *     modulus sqrt(c/a)): rho^2 = max(c/a, (e/d)^2).
 * A bound L is honest iff L^m <= rho^m (m = 1, 2, k; L >= 0), U iff
 * rho^m <= U^m; a point estimate R with k certified digits iff
 * (R - h)^m <= rho^m <= (R + h)^m, h = half a unit of its last digit.
 * The same for the text report, the CSV columns of radius and modes sweeps
 * (modes of the trapezoidal rule: closed forms below), root enclosures
 * (midpoint +- radius), and the verdict of roots within 1e-40 of the circle
 * (10^40*l - (10^40 -+ 1): stable / unstable by hand, rho = 1 -+ 10^-40). */
#include "testutil.h"
#include <string.h>
#include <stdlib.h>
#include <arb.h>
#include <ulong_extras.h>
#include "recstab/casefile.h"
#include "recstab/analysis.h"
#include "recstab/radius.h"
#include "recstab/report.h"

/* s as an exact rational q, and h = half a unit of its last digit; 0 on
 * success, -1 if s is not a plain decimal ([m +/- r], inf, ...). */
static int dec_parse(fmpq_t q, fmpq_t h, const char *s)
{
    fmpz_t m, p;
    slong frac = 0, ex = 0, nd = 0;
    int neg = 0, seen_point = 0;
    const char *c = s;
    fmpz_init(m);
    fmpz_init(p);
    if (*c == '-') { neg = 1; c++; }
    for (; *c; c++) {
        if (*c >= '0' && *c <= '9') {
            fmpz_mul_ui(m, m, 10);
            fmpz_add_ui(m, m, (ulong) (*c - '0'));
            nd++;
            if (seen_point) frac++;
        } else if (*c == '.' && !seen_point) {
            seen_point = 1;
        } else if (*c == 'e' || *c == 'E') {
            char *end;
            ex = strtol(c + 1, &end, 10);
            if (*end != '\0' || end == c + 1) nd = 0;
            break;
        } else {
            nd = 0;
            break;
        }
    }
    if (nd == 0) { fmpz_clear(m); fmpz_clear(p); return -1; }
    if (neg) fmpz_neg(m, m);
    ex -= frac;                         /* value = m * 10^ex */
    fmpz_set_ui(p, 10);
    fmpz_pow_ui(p, p, (ulong) (ex < 0 ? -ex : ex));
    if (ex >= 0) { fmpz_mul(fmpq_numref(q), m, p); fmpz_one(fmpq_denref(q)); }
    else fmpq_set_fmpz_frac(q, m, p);
    /* h = 10^ex / 2 */
    fmpz_set_ui(p, 10);
    fmpz_pow_ui(p, p, (ulong) (ex < 0 ? -ex : ex));
    if (ex >= 0) { fmpz_set(fmpq_numref(h), p); fmpz_set_ui(fmpq_denref(h), 2); }
    else { fmpz_one(fmpq_numref(h)); fmpz_mul_ui(fmpq_denref(h), p, 2); }
    fmpq_canonicalise(h);
    fmpz_clear(m);
    fmpz_clear(p);
    return 0;
}

/* x^m for x >= 0 (negative x counts as 0: the bound is then trivially low) */
static void pow_clamped(fmpq_t y, const fmpq_t x, ulong m)
{
    if (fmpq_sgn(x) < 0) fmpq_zero(y);
    else fmpq_pow_si(y, x, (slong) m);
}

/* lower <= rho <= upper with rho^m = t exactly */
static void check_bounds(const char *lo, const char *hi, const fmpq_t t, ulong m, const char *what)
{
    fmpq_t L, U, h, y;
    fmpq_init(L); fmpq_init(U); fmpq_init(h); fmpq_init(y);
    if (dec_parse(L, h, lo) || dec_parse(U, h, hi)) fail_msg("%s: bounds [%s, %s] not decimals", what, lo, hi);
    pow_clamped(y, L, m);
    if (fmpq_cmp(y, t) > 0) fail_msg("%s: lower %s above the true value", what, lo);
    if (fmpq_sgn(U) < 0) fail_msg("%s: negative upper %s", what, hi);
    pow_clamped(y, U, m);
    if (fmpq_cmp(y, t) < 0) fail_msg("%s: upper %s below the true value", what, hi);
    fmpq_clear(L); fmpq_clear(U); fmpq_clear(h); fmpq_clear(y);
}

/* the point estimate s is within half a unit of its last digit of rho */
static void check_point(const char *s, const fmpq_t t, ulong m, const char *what)
{
    fmpq_t R, h, a, y;
    fmpq_init(R); fmpq_init(h); fmpq_init(a); fmpq_init(y);
    if (dec_parse(R, h, s)) fail_msg("%s: %s is not a decimal", what, s);
    fmpq_sub(a, R, h);
    pow_clamped(y, a, m);
    if (fmpq_cmp(y, t) > 0) fail_msg("%s: %s is above the true value by more than half a unit", what, s);
    fmpq_add(a, R, h);
    pow_clamped(y, a, m);
    if (fmpq_cmp(y, t) < 0) fail_msg("%s: %s is below the true value by more than half a unit", what, s);
    fmpq_clear(R); fmpq_clear(h); fmpq_clear(a); fmpq_clear(y);
}

static json_t *run_case(const char *text, slong max_prec, int *outcome)
{
    rs_options_t opt;
    rs_options_default(&opt);
    if (max_prec > 0) opt.max_prec = max_prec;
    return tu_run_text(text, &opt, outcome, NULL);
}

static const char *jget(const json_t *o, const char *k)
{
    const char *s = json_string_value(json_object_get(o, k));
    if (s == NULL) fail_msg("no string \"%s\"", k);
    return s;
}

/* The text report's radius block: rho, and the two certified bounds. */
typedef struct { char rho[512], lo[512], hi[512], from[256]; } text_radius_t;

static void text_radius(text_radius_t *t, const json_t *doc)
{
    char *buf = NULL, *p;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    rs_report_text(f, doc);
    fclose(f);
    t->rho[0] = t->lo[0] = t->hi[0] = t->from[0] = '\0';
    if ((p = strstr(buf, "\n  rho ")) != NULL) sscanf(p, " rho %511s", t->rho);
    if ((p = strstr(buf, "\n  certified    [")) != NULL) sscanf(p, " certified [%511[^,],", t->lo);
    if (p != NULL && (p = strchr(p + 1, '\n')) != NULL) sscanf(p, " %511[^]]]", t->hi);
    if ((p = strstr(buf, "\n  from radius  ")) != NULL) sscanf(p, " from radius %255s", t->from);
    free(buf);
}

/* Everything one radius result prints, against rho^m = t. */
static void check_radius_doc(const json_t *doc, const fmpq_t t, ulong m, const char *what, int text)
{
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
    const json_t *roots = json_object_get(o, "roots");
    size_t i;
    check_bounds(jget(o, "lower"), jget(o, "upper"), t, m, what);
    check_point(jget(o, "rho"), t, m, what);
    for (i = 0; i < json_array_size(roots); i++) {
        const json_t *z = json_array_get(roots, i);
        fmpq_t a, h, y;
        fmpq_init(a); fmpq_init(h); fmpq_init(y);
        /* |root| <= rho: its certified abs is below rho + half a unit */
        if (dec_parse(a, h, jget(z, "abs"))) fail_msg("%s: abs %s", what, jget(z, "abs"));
        fmpq_sub(a, a, h);
        pow_clamped(y, a, m);
        if (fmpq_cmp(y, t) > 0) fail_msg("%s: |root| %s above rho", what, jget(z, "abs"));
        fmpq_clear(a); fmpq_clear(h); fmpq_clear(y);
    }
    if (text) {
        text_radius_t tr;
        text_radius(&tr, doc);
        check_bounds(tr.lo, tr.hi, t, m, "text report");
        check_point(tr.rho, t, m, "text report");
        assert_true(strncmp(jget(o, "verdict_from_radius"), tr.from, strlen(tr.from)) == 0);
    }
}

/* for 10*l^2 + 3 both bounds used to print as 0.547722557505166... (rounded to
 * nearest), which put sqrt(3/10) outside; the roots are +-i sqrt(3/10) */
static void test_sqrt_3_10(void **state)
{
    int outcome;
    json_t *doc = run_case("char 10*lambda^2 + 3\nanalyse radius\n", 0, &outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
    const json_t *roots = json_object_get(o, "roots");
    fmpq_t t, im, h, r, y;
    arf_t a;
    size_t i;
    (void) state;
    fmpq_init(t); fmpq_init(im); fmpq_init(h); fmpq_init(r); fmpq_init(y);
    arf_init(a);
    fmpq_set_si(t, 3, 10);
    assert_int_equal(outcome, RS_OUTCOME_OK);
    check_radius_doc(doc, t, 2, "10*l^2 + 3", 1);
    assert_int_equal(json_array_size(roots), 2);
    for (i = 0; i < 2; i++) {
        /* im +- radius contains +-sqrt(3/10); re +- radius contains 0 */
        const json_t *z = json_array_get(roots, i);
        arf_set_d(a, json_real_value(json_object_get(z, "radius")));
        arf_get_fmpq(r, a);
        assert_int_equal(dec_parse(im, h, jget(z, "re")), 0);
        fmpq_abs(im, im);
        assert_true(fmpq_cmp(im, r) <= 0);
        assert_int_equal(dec_parse(im, h, jget(z, "im")), 0);
        fmpq_abs(im, im);
        fmpq_sub(y, im, r);
        pow_clamped(y, y, 2);
        assert_true(fmpq_cmp(y, t) <= 0);
        fmpq_add(y, im, r);
        fmpq_mul(y, y, y);
        assert_true(fmpq_cmp(y, t) >= 0);
    }
    json_decref(doc);
    fmpq_clear(t); fmpq_clear(im); fmpq_clear(h); fmpq_clear(r); fmpq_clear(y);
    arf_clear(a);
}

/* 1000 random polynomials of the four families, random digits 3..40 */
static void test_random_families(void **state)
{
    flint_rand_t st;
    fmpq_t t, u;
    char text[1024], *p;
    int it, outcome;
    (void) state;
    flint_randinit(st);
    fmpq_init(t);
    fmpq_init(u);
    for (it = 0; it < 1000; it++) {
        int fam = it % 4, digits = 3 + (int) n_randint(st, 38);
        ulong m = 1;
        json_t *doc;
        p = text + sprintf(text, "char ");
        if (fam == 0) {                          /* a l^2 + b */
            ulong a = 1 + n_randint(st, 1000000), b = 1 + n_randint(st, 1000000);
            sprintf(p, "%lu*lambda^2 + %lu\n", a, b);
            fmpq_set_si(t, (slong) b, a);
            m = 2;
        } else if (fam == 1) {                   /* prod (a_i l - b_i) */
            int k, n = 1 + (int) n_randint(st, 4);
            fmpq_zero(t);
            for (k = 0; k < n; k++) {
                ulong a = 1 + n_randint(st, 1000);
                slong b = (slong) n_randint(st, 2000) - 1000;
                if (b == 0) b = 7;
                p += sprintf(p, "%s(%lu*lambda - (%ld))", k ? "*" : "", a, b);
                fmpq_set_si(u, b < 0 ? -b : b, a);
                if (fmpq_cmp(u, t) > 0) fmpq_set(t, u);
            }
            sprintf(p, "\n");
        } else if (fam == 2) {                   /* l^k - r */
            ulong k = 2 + n_randint(st, 5), r = 1 + n_randint(st, 1000000);
            sprintf(p, "lambda^%lu - %lu\n", k, r);
            fmpq_set_si(t, (slong) r, 1);
            m = k;
        } else {                                 /* planted complex pair and a real root */
            slong a = 1 + (slong) n_randint(st, 1000), c = 1 + (slong) n_randint(st, 1000), b, d, e;
            b = (slong) n_randint(st, 2 * (ulong) n_sqrt((ulong) (a * c)) + 1) - (slong) n_sqrt((ulong) (a * c));
            while (b * b >= 4 * a * c) b /= 2;
            d = 1 + (slong) n_randint(st, 1000);
            e = (slong) n_randint(st, 2000) - 1000;
            if (e == 0) e = 3;
            sprintf(p, "(%ld*lambda^2 + (%ld)*lambda + %ld)*(%ld*lambda - (%ld))\n", a, b, c, d, e);
            fmpq_set_si(t, c, (ulong) a);
            fmpq_set_si(u, e * e, (ulong) (d * d));
            if (fmpq_cmp(u, t) > 0) fmpq_set(t, u);
            m = 2;
        }
        p = text + strlen(text);
        sprintf(p, "analyse radius digits=%d\n", digits);
        doc = run_case(text, 0, &outcome);
        assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
        check_radius_doc(doc, t, m, text, it % 10 == 0);
        json_decref(doc);
    }
    assert_int_equal(it, 1000);
    fmpq_clear(t);
    fmpq_clear(u);
    flint_randclear(st);
}

/* 10^40*l - (10^40 -+ 1): the root 1 -+ 10^-40 is 40 digits from the circle,
 * 20 digits cannot see it: the numeric verdict is raised until certified
 * (stable / unstable, as the exact count says), no exit 3; with a precision
 * ceiling too low for it, the numeric side says undecided, still consistent. */
static void test_near_circle(void **state)
{
    static const char *const txt[2] = {"char 10^40*lambda - (10^40 - 1)\nanalyse radius digits=20\n",
                                       "char 10^40*lambda - (10^40 + 1)\nanalyse radius digits=20\n"};
    static const char *const want[2] = {"stable", "unstable"};
    int k, outcome;
    fmpq_t t;
    (void) state;
    fmpq_init(t);
    for (k = 0; k < 2; k++) {
        json_t *doc = run_case(txt[k], 0, &outcome);
        const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
        text_radius_t tr;
        fmpz_t ten40;
        fmpz_init(ten40);
        fmpz_set_ui(ten40, 10);
        fmpz_pow_ui(ten40, ten40, 40);
        fmpz_add_si(fmpq_numref(t), ten40, k == 0 ? -1 : 1);
        fmpz_set(fmpq_denref(t), ten40);
        fmpq_canonicalise(t);                    /* rho = (10^40 -+ 1) / 10^40 */
        assert_int_equal(outcome, RS_OUTCOME_OK);
        assert_string_equal(jget(o, "exact_status"), want[k]);
        assert_string_equal(jget(o, "verdict_from_radius"), want[k]);
        assert_true(json_is_true(json_object_get(o, "consistent")));
        check_radius_doc(doc, t, 1, txt[k], 1);
        /* the printed interval itself is on the right side of 1 */
        text_radius(&tr, doc);
        assert_string_equal(tr.from, want[k]);
        {
            fmpq_t b, h, one;
            fmpq_init(b); fmpq_init(h); fmpq_init(one);
            fmpq_one(one);
            assert_int_equal(dec_parse(b, h, k == 0 ? tr.hi : tr.lo), 0);
            assert_true(k == 0 ? fmpq_cmp(b, one) < 0 : fmpq_cmp(b, one) > 0);
            fmpq_clear(b); fmpq_clear(h); fmpq_clear(one);
        }
        json_decref(doc);
        /* 128 bits cannot separate 10^-40 at 20+ digits' accuracy: undecided */
        doc = run_case(txt[k], 128, &outcome);
        o = json_array_get(json_object_get(doc, "results"), 0);
        assert_int_equal(outcome, RS_OUTCOME_OK);
        assert_string_equal(jget(o, "exact_status"), want[k]);
        assert_true(strncmp(jget(o, "verdict_from_radius"), "undecided", 9) == 0);
        assert_true(json_is_true(json_object_get(o, "consistent")));
        check_radius_doc(doc, t, 1, txt[k], 1);
        text_radius(&tr, doc);
        assert_string_equal(tr.from, "undecided");
        json_decref(doc);
        fmpz_clear(ten40);
    }
    fmpq_clear(t);
}

/* A radius sweep of 10*l^2 + a: rho^2 = a/10 at each exact a. */
static void test_sweep_csv(void **state)
{
    int outcome;
    json_t *doc = run_case("param a\nchar 10*lambda^2 + a\nanalyse sweep a from 1 to 30 steps 29\n", 0, &outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
    char *tab = strdup(jget(o, "table")), *line, *save = NULL;
    int rows = 0;
    fmpq_t t;
    (void) state;
    fmpq_init(t);
    assert_int_equal(outcome, RS_OUTCOME_OK);
    line = strtok_r(tab, "\n", &save);
    /* the column order this test relies on */
    assert_string_equal(line, "index,a,a_exact,radius,radius_lower,radius_upper,verdict,code,decided_by");
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        char f[9][128];
        int n = sscanf(line, "%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],%127s",
                       f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8]);
        assert_int_equal(n, 9);
        assert_int_equal(fmpq_set_str(t, f[2], 10), 0);
        fmpq_canonicalise(t);
        fmpz_mul_ui(fmpq_denref(t), fmpq_denref(t), 10);
        fmpq_canonicalise(t);                    /* a/10 */
        check_bounds(f[4], f[5], t, 2, line);
        check_point(f[3], t, 2, line);
        rows++;
    }
    assert_int_equal(rows, 30);
    free(tab);
    fmpq_clear(t);
    json_decref(doc);
}

/* printed - h <= T <= printed + h for a ball T known to 256 bits */
static void check_point_arb(const char *s, const arb_t T, const char *what)
{
    fmpq_t R, h, a;
    arb_t b;
    fmpq_init(R); fmpq_init(h); fmpq_init(a);
    arb_init(b);
    if (dec_parse(R, h, s)) fail_msg("%s: %s is not a decimal", what, s);
    fmpq_sub(a, R, h);
    arb_set_fmpq(b, a, 256);
    if (!arb_le(b, T)) fail_msg("%s: %s is above the true value by more than half a unit", what, s);
    fmpq_add(a, R, h);
    arb_set_fmpq(b, a, 256);
    if (!arb_le(T, b)) fail_msg("%s: %s is below the true value by more than half a unit", what, s);
    fmpq_clear(R); fmpq_clear(h); fmpq_clear(a);
    arb_clear(b);
}

/* A modes sweep of the trapezoidal rule on x'' = -w^2 x (h = 1): p =
 * (l - 1)^2 + (w^2/4)(l + 1)^2, roots (1 +- i w/2)/(1 -+ i w/2) on the
 * circle, so ln(lambda) = +-2i atan(w/2): damping ratio 0, omega =
 * 2 atan(w/2), frequency error (omega - w)/w (Arb at 256 bits from the
 * exact w of each row). */
static void test_modes_csv(void **state)
{
    static const char *const text =
        "param w\nassume w > 0\nunknown x V\neq x[n+1] - x[n] = (V[n+1] + V[n])/2\n"
        "eq V[n+1] - V[n] = -w^2*(x[n+1] + x[n])/2\n"
        "analyse sweep w from 1/10 to 2 steps 19 of modes reference=w\n";
    int outcome, rows = 0;
    json_t *doc = run_case(text, 0, &outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
    char *tab = strdup(jget(o, "table")), *line, *save = NULL;
    fmpq_t w;
    arb_t om, fe, zero;
    (void) state;
    fmpq_init(w);
    arb_init(om); arb_init(fe); arb_init(zero);
    assert_int_equal(outcome, RS_OUTCOME_OK);
    line = strtok_r(tab, "\n", &save);
    assert_string_equal(line, "index,w,w_exact,radius,radius_lower,radius_upper,verdict,code,decided_by,"
                              "damping_ratio_1,frequency_error_1,omega_1");
    while ((line = strtok_r(NULL, "\n", &save)) != NULL) {
        char f[12][128];
        int n = sscanf(line, "%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],%127[^,],"
                       "%127[^,],%127[^,],%127[^,],%127s", f[0], f[1], f[2], f[3], f[4], f[5], f[6], f[7], f[8],
                       f[9], f[10], f[11]);
        assert_int_equal(n, 12);
        assert_int_equal(fmpq_set_str(w, f[2], 10), 0);
        fmpq_canonicalise(w);
        arb_set_fmpq(om, w, 256);
        arb_mul_2exp_si(om, om, -1);
        arb_atan(om, om, 256);
        arb_mul_2exp_si(om, om, 1);               /* 2 atan(w/2) */
        arb_set_fmpq(fe, w, 256);
        arb_sub(fe, om, fe, 256);
        arb_div_fmpz(fe, fe, fmpq_numref(w), 256);
        arb_mul_fmpz(fe, fe, fmpq_denref(w), 256);  /* (omega - w)/w */
        check_point_arb(f[9], zero, line);
        check_point_arb(f[10], fe, line);
        check_point_arb(f[11], om, line);
        rows++;
    }
    assert_int_equal(rows, 20);
    free(tab);
    fmpq_clear(w);
    arb_clear(om); arb_clear(fe); arb_clear(zero);
    json_decref(doc);
}

/* The printing helpers on values whose decimals are known by hand. */
static void test_helpers(void **state)
{
    arb_t x;
    arf_t lo, hi;
    char *s;
    (void) state;
    arb_init(x);
    arf_init(lo);
    arf_init(hi);
    arb_set_si(x, 2);
    arb_sqrt(x, x, 256);                         /* sqrt(2) = 1.41421356237309504880... */
    s = rs_radius_str_lower(x, 10); assert_string_equal(s, "1.414213562"); flint_free(s);
    s = rs_radius_str_upper(x, 10); assert_string_equal(s, "1.414213563"); flint_free(s);
    s = rs_radius_arb_str(x, 12); assert_string_equal(s, "1.41421356237"); flint_free(s);
    arb_set_d(x, 0.5);                           /* exact: no spurious zeros */
    s = rs_radius_str_lower(x, 30); assert_string_equal(s, "0.5"); flint_free(s);
    arb_set_si(x, -1);
    arb_div_ui(x, x, 3, 256);                    /* -1/3 */
    s = rs_radius_str_lower(x, 5); assert_string_equal(s, "-0.33334"); flint_free(s);
    s = rs_radius_str_upper(x, 5); assert_string_equal(s, "-0.33333"); flint_free(s);
    /* [0.1449, 0.1451]: 0.145 at 3 digits; [0.1449, 0.1551] rounds to 0.1
     * and 0.2 at one digit: nothing certain */
    arf_set_d(lo, 0.1449); arf_set_d(hi, 0.1451);
    s = rs_radius_interval_str(lo, hi, 15); assert_string_equal(s, "0.145"); flint_free(s);
    arf_set_d(hi, 0.1551);
    s = rs_radius_interval_str(lo, hi, 15); assert_int_equal(s[0], '['); flint_free(s);
    /* around 0: [-3e-20, 1e-20] is within 10^-19 / 2 of 0 (and 6e-20 needs
     * 10^-19: 2 * 3e-20 <= 10^-19) */
    arf_set_d(lo, -3e-20); arf_set_d(hi, 1e-20);
    s = rs_radius_interval_str(lo, hi, 15); assert_string_equal(s, "0e-19"); flint_free(s);
    /* 1e-50 and 1e50 in scientific notation, directed */
    arb_set_ui(x, 10);
    arb_pow_ui(x, x, 50, 256);
    s = rs_radius_str_upper(x, 3); assert_string_equal(s, "1e+50"); flint_free(s);
    arb_inv(x, x, 256);
    s = rs_radius_str_lower(x, 3); assert_string_equal(s, "9.99e-51"); flint_free(s);
    arb_clear(x);
    arf_clear(lo);
    arf_clear(hi);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_helpers),
        cmocka_unit_test(test_sqrt_3_10),
        cmocka_unit_test(test_near_circle),
        cmocka_unit_test(test_sweep_csv),
        cmocka_unit_test(test_modes_csv),
        cmocka_unit_test(test_random_families),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
