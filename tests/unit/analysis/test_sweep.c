/* test_sweep.c -- sweeps and maps against closed forms:
 *   - forward Euler: |lambda| = sqrt(1 + w^2) at every point, inside the
 *     certified [radius_lower, radius_upper] (evaluated with Arb from the
 *     point's exact rational, independently of recstab's root finders);
 *   - central difference: marginal for 0 < w < 2, unstable for w >= 2
 *     (double root -1 at w = 2), decided exactly;
 *   - the Schur stability triangle of lambda^2 - a lambda + b (stable iff
 *     |b| < 1 and |a| < 1 + b; its edges classified by hand) on a map that
 *     puts grid points exactly on the edges;
 *   - the Park map (alpha, m) at muh = wh = 1 against the closed-form
 *     condition -3 m^2 a^2 - 2 m^2 a + 5 m^2 - 9 m a^2 + m a + 20 m + 10 a + 20 > 0
 *     (at m = 1 it is -3 (4a^2 - 3a - 15), at m = 10 -30 (13a^2 + 6a - 24),
 *     the bounds the case file records);
 *   - log spacing: rational points within 1e-12 of A (B/A)^(i/K);
 *   - determinism: the same table with 1 and 2 threads; shards concatenate
 *     to the full table; the point limit. */
#include "testutil.h"
#include <string.h>
#include <stdlib.h>
#include <math.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include <arb.h>
#include <gsl/gsl_errno.h>
#include "recstab/casefile.h"
#include "recstab/scheme.h"
#include "recstab/analysis.h"
#include "recstab/sweep.h"

/* the case text with the requests req[] instead of its own, under options opt */
static json_t *run_text_opt(const char *text, const char *const *req, int nreq, const rs_options_t *opt, int *code)
{
    rs_case_t c;
    rs_error_t err;
    json_t *doc = NULL;
    int i, r;
    rs_case_init(c);
    rs_error_init(err);
    if (rs_case_parse_string(c, "test.case", text, strlen(text), err) != RS_OK) fail_msg("parse: %s", err->msg);
    rs_case_clear_requests(c);
    for (i = 0; i < nreq; i++) rs_case_add_request(c, req[i], "test", 1, 1);
    {
        int outcome;
        r = rs_analysis_run(&doc, &outcome, c, opt, err);
    }
    if (code) *code = r;
    else if (r != RS_OK) fail_msg("run: %s", err->msg);
    rs_case_clear(c);
    return doc;
}

static json_t *run_text(const char *text, const char *const *req, int nreq, int *code)
{
    rs_options_t opt;
    rs_options_default(&opt);
    return run_text_opt(text, req, nreq, &opt, code);
}

static json_t *run_file(const char *rel, const char *const *req, int nreq)
{
    char path[1024];
    FILE *f;
    char *buf;
    long n;
    json_t *doc;
    snprintf(path, sizeof path, "%s/%s", RS_SOURCE_DIR, rel);
    f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    buf = malloc((size_t) n + 1);
    assert_int_equal(fread(buf, 1, (size_t) n, f), (size_t) n);
    buf[n] = '\0';
    fclose(f);
    doc = run_text(buf, req, nreq, NULL);
    free(buf);
    return doc;
}

static const json_t *result(const json_t *doc, size_t i)
{
    return json_array_get(json_object_get(doc, "results"), i);
}

/* strsep is not POSIX */
static char *sep(char **p, const char *delim)
{
    char *s = *p, *e;
    if (s == NULL) return NULL;
    e = s + strcspn(s, delim);
    if (*e) { *e = '\0'; *p = e + 1; }
    else *p = NULL;
    return s;
}

/* the table's rows split into fields: rows[r][c] (strings into a copy) */
typedef struct {
    char *buf;
    size_t nrows, ncols;
    char ***cell;
} table_t;

static void table_parse(table_t *t, const char *text)
{
    char *p, *line;
    size_t cap = 16;
    t->buf = strdup(text);
    t->nrows = 0;
    t->ncols = 0;
    t->cell = malloc(cap * sizeof(char **));
    p = t->buf;
    line = sep(&p, "\n");            /* column header */
    for (; *line; line++) if (*line == ',') t->ncols++;
    t->ncols++;
    while ((line = sep(&p, "\n")) != NULL && *line) {
        size_t c = 0;
        char **row = malloc(t->ncols * sizeof(char *));
        char *f;
        while ((f = sep(&line, ",")) != NULL && c < t->ncols) row[c++] = f;
        while (c < t->ncols) row[c++] = "";
        if (t->nrows == cap) { cap *= 2; t->cell = realloc(t->cell, cap * sizeof(char **)); }
        t->cell[t->nrows++] = row;
    }
}

static void table_clear(table_t *t)
{
    size_t i;
    for (i = 0; i < t->nrows; i++) free(t->cell[i]);
    free(t->cell);
    free(t->buf);
}

static int col(const json_t *o, const char *name)
{
    const json_t *cols = json_object_get(o, "columns");
    size_t k;
    for (k = 0; k < json_array_size(cols); k++)
        if (strcmp(json_string_value(json_array_get(cols, k)), name) == 0) return (int) k;
    fail_msg("no column %s", name);
    return -1;
}

static void q_of(fmpq_t q, const char *s)
{
    assert_int_equal(fmpq_set_str(q, s, 10), 0);
    fmpq_canonicalise(q);
}

static void test_forward_euler_radius(void **state)
{
    const char *req[] = {"sweep w from 0 to 3 steps 30", "sweep w from 1/100 to 100 steps 20 log"};
    json_t *doc = run_file("cases/textbook/forward-euler.case", req, 2);
    int k;
    (void) state;
    for (k = 0; k < 2; k++) {
        const json_t *o = result(doc, (size_t) k);
        table_t t;
        size_t i;
        int cw = col(o, "w_exact"), clo = col(o, "radius_lower"), chi = col(o, "radius_upper"), cv = col(o, "verdict");
        fmpq_t w;
        arb_t rho, lo, hi;
        fmpq_init(w);
        arb_init(rho); arb_init(lo); arb_init(hi);
        table_parse(&t, json_string_value(json_object_get(o, "table")));
        assert_int_equal(t.nrows, k == 0 ? 31 : 21);
        assert_int_equal(json_integer_value(json_object_get(o, "points")), (json_int_t) t.nrows);
        for (i = 0; i < t.nrows; i++) {
            q_of(w, t.cell[i][cw]);
            /* sqrt(1 + w^2) from the exact point */
            arb_set_fmpq(rho, w, 256);
            arb_sqr(rho, rho, 256);
            arb_add_ui(rho, rho, 1, 256);
            arb_sqrt(rho, rho, 256);
            arb_set_d(lo, strtod(t.cell[i][clo], NULL));
            arb_set_d(hi, strtod(t.cell[i][chi], NULL));
            if (!(arb_le(lo, rho) && arb_le(rho, hi)))
                fail_msg("w = %s: sqrt(1+w^2) not in [%s, %s]", t.cell[i][cw], t.cell[i][clo], t.cell[i][chi]);
            /* the interval is narrow: 15 digits were asked */
            assert_true(strtod(t.cell[i][chi], NULL) - strtod(t.cell[i][clo], NULL) < 1e-12 * strtod(t.cell[i][chi], NULL));
            /* unstable everywhere (w = 0: double root 1) */
            assert_string_equal(t.cell[i][cv], "unstable");
        }
        table_clear(&t);
        fmpq_clear(w);
        arb_clear(rho); arb_clear(lo); arb_clear(hi);
    }
    json_decref(doc);
}

static void test_central_difference_verdicts(void **state)
{
    const char *req[] = {"sweep w from 0 to 4 steps 40 of stability", "sweep w from 0 to 4 steps 40"};
    json_t *doc = run_file("cases/textbook/central-difference.case", req, 2);
    int k;
    (void) state;
    for (k = 0; k < 2; k++) {
        const json_t *o = result(doc, (size_t) k);
        table_t t;
        size_t i;
        int cw = col(o, "w_exact"), cv = col(o, "verdict"), cd = col(o, "decided_by");
        fmpq_t w, two;
        fmpq_init(w);
        fmpq_init(two);
        fmpq_set_si(two, 2, 1);
        table_parse(&t, json_string_value(json_object_get(o, "table")));
        assert_int_equal(t.nrows, 41);
        for (i = 0; i < t.nrows; i++) {
            const char *want;
            q_of(w, t.cell[i][cw]);
            /* w = 0: double root 1 (unstable); 0 < w < 2 marginal; w >= 2 unstable */
            want = (fmpq_sgn(w) > 0 && fmpq_cmp(w, two) < 0) ? "marginal" : "unstable";
            if (strcmp(t.cell[i][cv], want) != 0) fail_msg("w = %s: %s, expected %s", t.cell[i][cw], t.cell[i][cv], want);
            /* roots on the circle are decided by the exact level only */
            if (strcmp(want, "marginal") == 0) assert_string_equal(t.cell[i][cd], "exact");
        }
        assert_int_equal(json_integer_value(json_object_get(json_object_get(o, "verdicts"), "marginal")), 19);
        table_clear(&t);
        fmpq_clear(w);
        fmpq_clear(two);
    }
    json_decref(doc);
}

/* lambda^2 - a lambda + b, classified by hand */
static const char *triangle(const fmpq_t a, const fmpq_t b)
{
    fmpq_t absa, absb, onepb, one;
    const char *v;
    int c1, c2;
    fmpq_init(absa); fmpq_init(absb); fmpq_init(onepb); fmpq_init(one);
    fmpq_abs(absa, a);
    fmpq_abs(absb, b);
    fmpq_one(one);
    fmpq_add(onepb, one, b);
    c1 = fmpq_cmp(absb, one);          /* |b| vs 1 */
    c2 = fmpq_cmp(absa, onepb);        /* |a| vs 1 + b */
    if (c1 < 0 && c2 < 0) v = "stable";
    else if (c1 < 0 && c2 == 0) v = "marginal";             /* a root at +-1, the other b inside */
    else if (fmpq_equal(b, one) && c2 < 0) v = "marginal";  /* e^{+-i theta}, distinct */
    else if (fmpq_cmp_si(b, -1) == 0 && fmpq_is_zero(a)) v = "marginal"; /* +1 and -1 */
    else v = "unstable";
    fmpq_clear(absa); fmpq_clear(absb); fmpq_clear(onepb); fmpq_clear(one);
    return v;
}

static void test_triangle_map(void **state)
{
    const char *text = "title triangle\nparam a b\nchar lambda^2 - a*lambda + b\n";
    const char *req[] = {"map a -3 3 25, b -2 2 17 of stability"};
    json_t *doc = run_text(text, req, 1, NULL);
    const json_t *o = result(doc, 0);
    table_t t;
    size_t i, nmarg = 0;
    int ca = col(o, "a_exact"), cb = col(o, "b_exact"), cv = col(o, "verdict");
    fmpq_t a, b;
    (void) state;
    fmpq_init(a);
    fmpq_init(b);
    table_parse(&t, json_string_value(json_object_get(o, "table")));
    assert_int_equal(t.nrows, 25 * 17);
    for (i = 0; i < t.nrows; i++) {
        const char *want;
        q_of(a, t.cell[i][ca]);
        q_of(b, t.cell[i][cb]);
        want = triangle(a, b);
        if (strcmp(want, "marginal") == 0) nmarg++;
        if (strcmp(t.cell[i][cv], want) != 0)
            fail_msg("a = %s, b = %s: %s, expected %s", t.cell[i][ca], t.cell[i][cb], t.cell[i][cv], want);
    }
    assert_true(nmarg > 10);
    assert_int_equal(json_integer_value(json_object_get(json_object_get(o, "verdicts"), "marginal")), (json_int_t) nmarg);
    /* every marginal point needed the exact level */
    assert_true(json_integer_value(json_object_get(json_object_get(o, "decided_by"), "exact")) >= (json_int_t) nmarg);
    /* the boundary overlay exists (a, b both symbolic) */
    assert_non_null(json_object_get(o, "boundary"));
    table_clear(&t);
    fmpq_clear(a);
    fmpq_clear(b);
    json_decref(doc);
}

static void test_park_map(void **state)
{
    const char *req[] = {"map alpha 0 3 31, m 1/2 20 14"};
    json_t *doc;
    const json_t *o;
    table_t t;
    size_t i;
    int ca, cm, cv;
    fmpq_t a, m, v, s;
    char *txt;
    (void) state;
    {
        char path[1024];
        FILE *f;
        long n;
        snprintf(path, sizeof path, "%s/cases/park-staggered.case", RS_SOURCE_DIR);
        f = fopen(path, "rb");
        assert_non_null(f);
        fseek(f, 0, SEEK_END);
        n = ftell(f);
        fseek(f, 0, SEEK_SET);
        txt = malloc((size_t) n + 40);
        assert_int_equal(fread(txt, 1, (size_t) n, f), (size_t) n);
        txt[n] = '\0';
        fclose(f);
        strcat(txt, "\nset muh = 1, wh = 1\n");
    }
    doc = run_text(txt, req, 1, NULL);
    free(txt);
    o = result(doc, 0);
    ca = col(o, "alpha_exact");
    cm = col(o, "m_exact");
    cv = col(o, "verdict");
    fmpq_init(a); fmpq_init(m); fmpq_init(v); fmpq_init(s);
    table_parse(&t, json_string_value(json_object_get(o, "table")));
    assert_int_equal(t.nrows, 31 * 14);
    for (i = 0; i < t.nrows; i++) {
        /* -3 m^2 a^2 - 2 m^2 a + 5 m^2 - 9 m a^2 + m a + 20 m + 10 a + 20 */
        static const int cf[][3] = {{-3, 2, 2}, {-2, 2, 1}, {5, 2, 0}, {-9, 1, 2}, {1, 1, 1}, {20, 1, 0},
                                    {10, 0, 1}, {20, 0, 0}};
        size_t k;
        int sg;
        const char *want;
        q_of(a, t.cell[i][ca]);
        q_of(m, t.cell[i][cm]);
        fmpq_zero(v);
        for (k = 0; k < 8; k++) {
            fmpq_t pa, pm;
            fmpq_init(pa); fmpq_init(pm);
            fmpq_pow_si(pm, m, cf[k][1]);
            fmpq_pow_si(pa, a, cf[k][2]);
            fmpq_mul(s, pm, pa);
            fmpq_mul_si(s, s, cf[k][0]);
            fmpq_add(v, v, s);
            fmpq_clear(pa); fmpq_clear(pm);
        }
        sg = fmpq_sgn(v);
        want = sg > 0 ? "stable" : sg < 0 ? "unstable" : NULL;
        if (want != NULL && strcmp(t.cell[i][cv], want) != 0)
            fail_msg("alpha = %s, m = %s: %s, expected %s", t.cell[i][ca], t.cell[i][cm], t.cell[i][cv], want);
    }
    table_clear(&t);
    fmpq_clear(a); fmpq_clear(m); fmpq_clear(v); fmpq_clear(s);
    json_decref(doc);
}

static void test_log_points(void **state)
{
    const char *req[] = {"sweep w from 1/1000 to 10 steps 17 log of stability"};
    json_t *doc = run_file("cases/textbook/backward-euler.case", req, 1);
    const json_t *o = result(doc, 0);
    table_t t;
    size_t i;
    int cw = col(o, "w_exact");
    (void) state;
    table_parse(&t, json_string_value(json_object_get(o, "table")));
    assert_int_equal(t.nrows, 18);
    for (i = 0; i < t.nrows; i++) {
        fmpq_t w;
        double want = 1e-3 * pow(1e4, (double) i / 17.0), got;
        fmpq_init(w);
        q_of(w, t.cell[i][cw]);
        got = fmpq_get_d(w);
        assert_true(fabs(got - want) <= 1e-12 * want);
        assert_string_equal(t.cell[i][3], "stable");
        fmpq_clear(w);
    }
    assert_string_equal(t.cell[0][cw], "1/1000");
    assert_string_equal(t.cell[17][cw], "10");
    table_clear(&t);
    json_decref(doc);
}

static char *park_table(int threads, slong shard, slong nshards)
{
    const char *text = "param a b c\nchar (lambda^2 - a*lambda + b)*(lambda^2 + c*lambda/2 + a*b/3) - lambda/7\n"
                       "set c = 1/3\n";
    const char *req[] = {"map a -2 2 23, b -1 1 19"};
    rs_options_t opt;
    json_t *doc;
    char *out;
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void) threads;
#endif
    rs_options_default(&opt);
    opt.sweep.shard_index = shard;
    opt.sweep.shard_count = nshards;
    doc = run_text_opt(text, req, 1, &opt, NULL);
    out = strdup(json_string_value(json_object_get(result(doc, 0), "table")));
    json_decref(doc);
    return out;
}

static void test_determinism_and_shards(void **state)
{
    char *t1 = park_table(1, 1, 1), *t2 = park_table(2, 1, 1), *s1, *s2, *s3, *cat;
    size_t n;
    (void) state;
    assert_string_equal(t1, t2);
    s1 = park_table(2, 1, 3);
    s2 = park_table(2, 2, 3);
    s3 = park_table(1, 3, 3);
    /* shards: the same column header, rows concatenate to the full table */
    n = strlen(s1) + strlen(s2) + strlen(s3) + 1;
    cat = malloc(n);
    strcpy(cat, s1);
    strcat(cat, strchr(s2, '\n') + 1);
    strcat(cat, strchr(s3, '\n') + 1);
    assert_string_equal(cat, t1);
    free(t1); free(t2); free(s1); free(s2); free(s3); free(cat);
}

static void test_limits_and_errors(void **state)
{
    const char *text = "param a b\nchar lambda^2 - a*lambda + b\n";
    const char *big[] = {"map a 0 1 2001, b 0 1 2001"};
    const char *bad1[] = {"sweep a from 0 to 1 steps 10"};    /* b still symbolic */
    const char *bad2[] = {"sweep q from 0 to 1 steps 10"};
    const char *bad3[] = {"map a 0 1 10, b 0 1 10 of modes"};
    int code;
    json_t *doc;
    (void) state;
    doc = run_text(text, big, 1, &code);
    assert_int_equal(code, RS_ERR_LIMIT);
    assert_null(doc);
    doc = run_text(text, bad1, 1, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    doc = run_text(text, bad2, 1, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    doc = run_text(text, bad3, 1, &code);
    assert_int_equal(code, RS_ERR_INPUT);
    {
        /* a nonzero polynomial's verdict through the library entry point */
        rs_sweep_point_t pt;
        rs_error_t err;
        fmpz_poly_t p;
        fmpz_poly_init(p);
        rs_error_init(err);
        fmpz_poly_set_str(p, "3  2 0 1");          /* lambda^2 + 2: |lambda| = sqrt 2 */
        assert_int_equal(rs_sweep_decide(&pt, p, err), RS_OK);
        assert_int_equal(pt.verdict, 2);
        assert_true(pt.rho_lower <= sqrt(2.0) && sqrt(2.0) <= pt.rho_upper);
        fmpz_poly_set_str(p, "3  1 0 1");          /* lambda^2 + 1: marginal, exactly */
        assert_int_equal(rs_sweep_decide(&pt, p, err), RS_OK);
        assert_int_equal(pt.verdict, 1);
        assert_int_equal(pt.level, RS_LEVEL_EXACT);
        assert_true(pt.rho_lower == 1.0 && pt.rho_upper == 1.0);
        fmpz_poly_clear(p);
    }
}

static void test_modes_sweep(void **state)
{
    /* trapezoidal rule: |lambda| = 1 (damping 0), omega h = 2 atan(w/2) */
    const char *req[] = {"sweep w from 1/10 to 2 steps 19 of modes reference=w"};
    json_t *doc = run_file("cases/textbook/trapezoidal.case", req, 1);
    const json_t *o = result(doc, 0);
    table_t t;
    size_t i;
    int cw = col(o, "w_exact"), cd = col(o, "damping_ratio_1"), cf = col(o, "frequency_error_1");
    (void) state;
    table_parse(&t, json_string_value(json_object_get(o, "table")));
    for (i = 0; i < t.nrows; i++) {
        fmpq_t w;
        double wd, fe;
        fmpq_init(w);
        q_of(w, t.cell[i][cw]);
        wd = fmpq_get_d(w);
        fe = (2 * atan(wd / 2) - wd) / wd;
        assert_true(fabs(strtod(t.cell[i][cd], NULL)) < 1e-12);
        assert_true(fabs(strtod(t.cell[i][cf], NULL) - fe) < 1e-12);
        fmpq_clear(w);
    }
    table_clear(&t);
    json_decref(doc);
}

int main(void)
{
    gsl_set_error_handler_off();   /* once, as the recstab command does (sweep.h) */
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_forward_euler_radius),
        cmocka_unit_test(test_central_difference_verdicts),
        cmocka_unit_test(test_triangle_map),
        cmocka_unit_test(test_park_map),
        cmocka_unit_test(test_log_points),
        cmocka_unit_test(test_determinism_and_shards),
        cmocka_unit_test(test_limits_and_errors),
        cmocka_unit_test(test_modes_sweep),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
