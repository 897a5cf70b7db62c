/* test_cad.c -- `region N1, N2 [at ...]` (issue 13, part 2): the exact
 * stable and marginal sets in two parameters.  The formula recstab prints
 * is re-parsed here (FLINT's parser) and evaluated exactly at hundreds of
 * random rational points, and at points on the boundary curves, against
 * (a) a closed form derived by hand (each in the case file's comment):
 *   - Jury triangle of lambda^2 + a lambda + b: stable iff |b| < 1 and
 *     |a| < 1 + b; marginal on the edges except the corners (+-2, 1);
 *   - theta method (th, w), w > 0: stable iff th > 1/2, marginal iff th = 1/2;
 *   - Newmark gamma = 1/2 (b, w), w > 0 (Hughes ch. 9): never stable,
 *     marginal iff 4 + (4 b - 1) w^2 > 0;
 *   - two identical central-difference oscillators, y driving x with
 *     strength eps (eps, h), 0 < h < 1: det A = g^2 for every eps and A
 *     modulo g has rank 1 unless eps = 0 (a Jordan block): never stable,
 *     marginal iff eps = 0;
 * (b) the exact point verdict (`analyse stability` with both parameters set);
 * (c) QEPCAD B's answer to the same question (its input and output below:
 *     test_qepcad). */
#include "testutil.h"
#include <string.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpq_poly.h>
#include <arf.h>
#include <acb_poly.h>
#include <fmpq_vec.h>
#include "recstab/casefile.h"
#include "recstab/analysis.h"

typedef int (*closed_fn)(const fmpq_t x, const fmpq_t y);   /* 0 unstable, 1 marginal, 2 stable */

/* "POLY REL 0" at (x, y) with FLINT's parser in the variables (vx, vy) */
static int cond_holds(const char *cond, const char *vx, const char *vy, const fmpq_t x, const fmpq_t y)
{
    const char *vars[2];
    char poly[1024], rel[4];
    const char *sp = strrchr(cond, ' ');
    fmpq_mpoly_ctx_t ctx;
    fmpq_mpoly_t P;
    fmpq_t v;
    fmpq *pt[2];
    size_t n;
    int sg, h;
    vars[0] = vx; vars[1] = vy;
    assert_non_null(sp);
    assert_string_equal(sp, " 0");
    n = (size_t) (sp - cond);
    memcpy(poly, cond, n);
    poly[n] = '\0';
    sp = strrchr(poly, ' ');
    assert_non_null(sp);
    snprintf(rel, sizeof rel, "%s", sp + 1);
    poly[sp - poly] = '\0';
    fmpq_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpq_mpoly_init(P, ctx);
    fmpq_init(v);
    if (fmpq_mpoly_set_str_pretty(P, poly, vars, ctx) != 0) fail_msg("cannot parse '%s'", poly);
    pt[0] = (fmpq *) x; pt[1] = (fmpq *) y;
    assert_true(fmpq_mpoly_evaluate_all_fmpq(v, P, pt, ctx));
    sg = fmpq_sgn(v);
    if (strcmp(rel, ">") == 0) h = sg > 0;
    else if (strcmp(rel, ">=") == 0) h = sg >= 0;
    else if (strcmp(rel, "<") == 0) h = sg < 0;
    else if (strcmp(rel, "<=") == 0) h = sg <= 0;
    else if (strcmp(rel, "=") == 0) h = sg == 0;
    else if (strcmp(rel, "!=") == 0) h = sg != 0;
    else { fail_msg("relation '%s'", rel); h = 0; }
    fmpq_mpoly_clear(P, ctx);
    fmpq_mpoly_ctx_clear(ctx);
    fmpq_clear(v);
    return h;
}

static int dnf_holds(const json_t *dnf, const char *vx, const char *vy, const fmpq_t x, const fmpq_t y)
{
    size_t i, j;
    for (i = 0; i < json_array_size(dnf); i++) {
        const json_t *c = json_array_get(dnf, i);
        int all = 1;
        for (j = 0; j < json_array_size(c) && all; j++)
            all = cond_holds(json_string_value(json_array_get(c, j)), vx, vy, x, y);
        if (all) return 1;
    }
    return 0;
}

/* the exact point verdict: `analyse stability` with both parameters set */
static int point_verdict(const char *text, const char *vx, const char *vy, const fmpq_t x, const fmpq_t y)
{
    rs_case_t c;
    rs_error_t err;
    rs_options_t opt;
    json_t *doc = NULL;
    char set[256], *xs = fmpq_get_str(NULL, 10, x), *ys = fmpq_get_str(NULL, 10, y);
    const char *st;
    int outcome, k;
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    assert_int_equal(rs_case_parse_string(c, "point.case", text, strlen(text), err), RS_OK);
    rs_case_clear_requests(c);
    rs_case_add_request(c, "stability", "test", 1, 1);
    snprintf(set, sizeof set, "%s=%s", vx, xs);
    assert_int_equal(rs_case_set_value(c, set, err), RS_OK);
    snprintf(set, sizeof set, "%s=%s", vy, ys);
    assert_int_equal(rs_case_set_value(c, set, err), RS_OK);
    if (rs_analysis_run(&doc, &outcome, c, &opt, err) != RS_OK) fail_msg("point %s, %s: %s", xs, ys, err->msg);
    st = json_string_value(json_object_get(json_array_get(json_object_get(doc, "results"), 0), "status"));
    assert_non_null(st);
    k = strcmp(st, "stable") == 0 ? 2 : (strcmp(st, "marginal") == 0 ? 1 : 0);
    json_decref(doc);
    rs_case_clear(c);
    flint_free(xs);
    flint_free(ys);
    return k;
}

/* a rational in [lo, hi] with a denominator up to 60 */
static void rand_q(fmpq_t out, flint_rand_t st, slong lo, slong hi)
{
    slong den = 1 + (slong) n_randint(st, 60);
    slong num = lo * den + (slong) n_randint(st, (ulong) ((hi - lo) * den + 1));
    fmpq_set_si(out, num, (ulong) den);
}

/* the region of case file rel against the closed form at the points
 * (xs[i], ys[i]); every verdict check == the point verdict */
static void check_points(const json_t *o, const char *text, const fmpq *xs, const fmpq *ys, slong n, closed_fn cf,
                         int verdicts, const char *what)
{
    const json_t *pa = json_object_get(o, "params"), *fo = json_object_get(o, "formula");
    const char *vx = json_string_value(json_array_get(pa, 0)), *vy = json_string_value(json_array_get(pa, 1));
    slong i;
    for (i = 0; i < n; i++) {
        int want = cf(xs + i, ys + i), s = dnf_holds(json_object_get(fo, "stable"), vx, vy, xs + i, ys + i),
            m = dnf_holds(json_object_get(fo, "marginal"), vx, vy, xs + i, ys + i), got = s ? 2 : (m ? 1 : 0);
        if (s && m) fail_msg("%s: stable and marginal at once", what);
        if (got != want) {
            char *a = fmpq_get_str(NULL, 10, xs + i), *b = fmpq_get_str(NULL, 10, ys + i);
            fail_msg("%s: at (%s, %s) the formula says %d, the closed form %d", what, a, b, got, want);
        }
        if (verdicts && point_verdict(text, vx, vy, xs + i, ys + i) != want) {
            char *a = fmpq_get_str(NULL, 10, xs + i), *b = fmpq_get_str(NULL, 10, ys + i);
            fail_msg("%s: at (%s, %s) the point verdict differs from the closed form %d", what, a, b, want);
        }
    }
}

static const char *case_text(const char *rel)
{
    static char buf[8192];
    char path[1024];
    FILE *f;
    size_t n;
    snprintf(path, sizeof path, "%s/%s", RS_SOURCE_DIR, rel);
    f = fopen(path, "r");
    assert_non_null(f);
    n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    return buf;
}

static json_t *region_of(const char *rel, int *outcome)
{
    json_t *doc = tu_run_case(rel, NULL, -1, outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
    assert_true(json_is_true(json_object_get(o, "formula_complete")));
    assert_int_equal(*outcome & RS_OUTCOME_INCONSISTENT, 0);
    /* the run-time cross-check agreed everywhere */
    assert_int_equal(json_integer_value(json_object_get(json_object_get(o, "cross_check"), "agree")),
                     json_integer_value(json_object_get(json_object_get(o, "cross_check"), "points")));
    return doc;
}

/* ---- Jury triangle --------------------------------------------------------- */

static int jury_closed(const fmpq_t a, const fmpq_t b)
{
    fmpq_t t, u;
    int k = 0;
    fmpq_init(t); fmpq_init(u);
    fmpq_add_si(t, b, 1);                 /* 1 + b */
    fmpq_abs(u, a);                       /* |a| */
    if (fmpq_cmp_si(b, 1) < 0 && fmpq_cmp_si(b, -1) > 0 && fmpq_cmp(u, t) < 0) k = 2;
    /* edges: b = 1 with |a| < 2 (a circle pair); |a| = 1 + b with -1 <= b < 1 (a root +-1, the other -+b) */
    else if (fmpq_cmp_si(b, 1) == 0 && fmpq_cmp_si(u, 2) < 0) k = 1;
    else if (fmpq_equal(u, t) && fmpq_cmp_si(b, -1) >= 0 && fmpq_cmp_si(b, 1) < 0) k = 1;
    fmpq_clear(t); fmpq_clear(u);
    return k;
}

/* 250 points in [-3, 3]^2, 150 on the edges' lines (marginal or not) */
static void jury_points(fmpq *xs, fmpq *ys, slong n, flint_rand_t st)
{
    slong i;
    for (i = 0; i < 250 && i < n; i++) { rand_q(xs + i, st, -3, 3); rand_q(ys + i, st, -3, 3); }
    for (; i < n; i++) {
        rand_q(ys + i, st, -2, 2);
        if (i % 3 == 0) { fmpq_add_si(xs + i, ys + i, 1); }                      /* a = 1 + b */
        else if (i % 3 == 1) { fmpq_add_si(xs + i, ys + i, 1); fmpq_neg(xs + i, xs + i); }   /* a = -1 - b */
        else { fmpq_set(xs + i, ys + i); fmpq_mul_si(xs + i, xs + i, 2); fmpq_set_si(ys + i, 1, 1); }  /* b = 1 */
    }
}

typedef void (*points_fn)(fmpq *xs, fmpq *ys, slong n, flint_rand_t st);

/* the case's region at n points against the closed form and the point
 * verdict; its boundary has nb polynomials (the first one: first) */
static void region_test(const char *rel, slong n, points_fn pts, closed_fn cf, size_t nb, const char *first)
{
    int outcome;
    json_t *doc = region_of(rel, &outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0), *b = json_object_get(o, "boundary");
    fmpq *xs = _fmpq_vec_init(n), *ys = _fmpq_vec_init(n);
    flint_rand_t st;
    flint_randinit(st);
    pts(xs, ys, n, st);
    check_points(o, case_text(rel), xs, ys, n, cf, 1, rel);
    assert_int_equal(json_array_size(b), nb);
    if (first != NULL) assert_string_equal(json_string_value(json_array_get(b, 0)), first);
    _fmpq_vec_clear(xs, n); _fmpq_vec_clear(ys, n);
    flint_randclear(st);
    json_decref(doc);
}

static void test_jury(void **state)
{
    (void) state;
    /* the boundary: the three edges (the discriminant a^2 - 4 b separates nothing) */
    region_test("cases/region2/jury-quadratic.case", 400, jury_points, jury_closed, 3, NULL);
}

/* ---- theta method ---------------------------------------------------------- */

static int theta_closed(const fmpq_t th, const fmpq_t w)
{
    fmpq_t h;
    int c;
    (void) w;
    fmpq_init(h);
    fmpq_set_si(h, 1, 2);
    c = fmpq_cmp(th, h);
    fmpq_clear(h);
    return c > 0 ? 2 : (c == 0 ? 1 : 0);
}

static void theta_points(fmpq *xs, fmpq *ys, slong n, flint_rand_t st)
{
    slong i;
    for (i = 0; i < n; i++) {
        if (i % 5 == 0) fmpq_set_si(xs + i, 1, 2); else rand_q(xs + i, st, -2, 3);
        do rand_q(ys + i, st, 0, 6); while (fmpq_sgn(ys + i) <= 0);
    }
}

static void test_theta(void **state)
{
    (void) state;
    region_test("cases/region2/theta-plane.case", 250, theta_points, theta_closed, 1, "2*th - 1");
}

/* ---- Newmark, gamma = 1/2 ---------------------------------------------------- */

static int newmark_closed(const fmpq_t b, const fmpq_t w)
{
    fmpq_t t, w2;
    int k;
    fmpq_init(t); fmpq_init(w2);
    fmpq_mul(w2, w, w);
    fmpq_mul_si(t, b, 4);
    fmpq_sub_si(t, t, 1);
    fmpq_mul(t, t, w2);
    fmpq_add_si(t, t, 4);                 /* 4 + (4 b - 1) w^2 */
    k = fmpq_sgn(t) > 0 ? 1 : 0;
    fmpq_clear(t); fmpq_clear(w2);
    return k;
}

static void newmark_points(fmpq *xs, fmpq *ys, slong n, flint_rand_t st)
{
    slong i;
    for (i = 0; i < n; i++) {
        rand_q(xs + i, st, -1, 1);
        if (i % 5 == 0) {
            /* on the curve: b = (w^2 - 4)/(4 w^2), w = 2 k (marginal fails exactly there) */
            fmpq_set_si(ys + i, 2 + (slong) n_randint(st, 5), 1);
            fmpq_mul(xs + i, ys + i, ys + i);
            fmpq_sub_si(xs + i, xs + i, 4);
            fmpq_div(xs + i, xs + i, ys + i);
            fmpq_div(xs + i, xs + i, ys + i);
            fmpq_div_2exp(xs + i, xs + i, 2);
        } else {
            do rand_q(ys + i, st, 0, 6); while (fmpq_sgn(ys + i) <= 0);
        }
    }
}

static void test_newmark(void **state)
{
    (void) state;
    /* never asymptotically stable: the stable formula is empty (checked by the points too) */
    region_test("cases/region2/newmark-beta-w.case", 250, newmark_points, newmark_closed, 1, "4*b*w^2 - w^2 + 4");
}

/* ---- driven oscillators: a Jordan block off the line eps = 0 ------------------ */

static int driven_closed(const fmpq_t eps, const fmpq_t h)
{
    (void) h;
    return fmpq_is_zero(eps) ? 1 : 0;
}

static void driven_points(fmpq *xs, fmpq *ys, slong n, flint_rand_t st)
{
    slong i;
    for (i = 0; i < n; i++) {
        if (i % 3 == 0) fmpq_zero(xs + i); else rand_q(xs + i, st, -2, 2);
        do rand_q(ys + i, st, 0, 1); while (fmpq_sgn(ys + i) <= 0 || fmpq_cmp_si(ys + i, 1) >= 0);
    }
}

static void test_driven(void **state)
{
    (void) state;
    /* no boundary: the stable set is empty (the marginal line lies between
     * two unstable sides) */
    region_test("cases/region2/driven-oscillators.case", 90, driven_points, driven_closed, 0, NULL);
}

/* ---- QEPCAD B ------------------------------------------------------------------
 * QEPCAD B 1.74 (Debian qepcad), run by hand on the inputs recstab writes
 * ("qepcad_input" of the region), `qepcad +N20000000 < INPUT`:
 *
 * Jury:   (a,b) 2 [ [ [ a + b + 1 > 0 /\ -2 b + 2 > 0 /\ -a + b + 1 > 0 /\ -2 b + 2 > 0 ] \/
 *                     [ -a - b - 1 > 0 /\ 2 b - 2 > 0 /\ a - b - 1 > 0 /\ 2 b - 2 > 0 ] ] ].
 *   -> b + a + 1 > 0 /\ b - 1 < 0 /\ b - a + 1 > 0
 * theta:  (th,w) 2 [ w > 0 /\ [ [ w^2 > 0 /\ 4 th w^2 - 2 w^2 > 0 /\ 4 th^2 w^2 - 4 th w^2 + w^2 + 4 > 0
 *                     /\ 4 th w^2 - 2 w^2 > 0 ] \/ [ -w^2 > 0 /\ ... ] ] ].
 *   -> 2 th - 1 > 0 /\ w > 0
 * Newmark (b, w), gamma = 1/2: -> FALSE (never asymptotically stable)
 *
 * recstab's stable formula must agree with these at every sampled point of
 * the domain (the answers QEPCAD gave, written in recstab's syntax). */
static void check_qepcad(const char *rel, const char *const *conds, size_t n, int never, slong xlo, slong xhi,
                         slong ylo, slong yhi)
{
    int outcome;
    json_t *doc = region_of(rel, &outcome), *qe = json_array(), *cj = json_array();
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0), *pa = json_object_get(o, "params");
    const char *vx = json_string_value(json_array_get(pa, 0)), *vy = json_string_value(json_array_get(pa, 1));
    flint_rand_t st;
    fmpq_t x, y;
    size_t i;
    flint_randinit(st);
    fmpq_init(x); fmpq_init(y);
    for (i = 0; i < n; i++) json_array_append_new(cj, json_string(conds[i]));
    if (!never) json_array_append_new(qe, cj); else json_decref(cj);
    for (i = 0; i < 300; i++) {
        rand_q(x, st, xlo, xhi);
        do rand_q(y, st, ylo, yhi); while (ylo == 0 && fmpq_sgn(y) <= 0);
        if (dnf_holds(json_object_get(json_object_get(o, "formula"), "stable"), vx, vy, x, y)
            != dnf_holds(qe, vx, vy, x, y)) {
            char *a = fmpq_get_str(NULL, 10, x), *b = fmpq_get_str(NULL, 10, y);
            fail_msg("%s: recstab and QEPCAD B differ at (%s, %s)", rel, a, b);
        }
    }
    fmpq_clear(x); fmpq_clear(y);
    flint_randclear(st);
    json_decref(qe);
    json_decref(doc);
}

static void test_qepcad(void **state)
{
    static const char *jury[] = {"b + a + 1 > 0", "b - 1 < 0", "b - a + 1 > 0"};
    static const char *theta[] = {"2*th - 1 > 0", "w > 0"};
    (void) state;
    check_qepcad("cases/region2/jury-quadratic.case", jury, 3, 0, -3, 3, -3, 3);
    check_qepcad("cases/region2/theta-plane.case", theta, 2, 0, -2, 3, 0, 6);
    check_qepcad("cases/region2/newmark-beta-w.case", NULL, 0, 1, -1, 1, 0, 6);
}

/* ---- the map draws only separating arcs (issue 13 part 3) ---------------------
 * On the Jury case the lines a + b + 1 = 0, a - b - 1 = 0, b = 1 go on
 * outside the triangle, where unstable meets unstable: those points must be
 * dropped, and every point kept must have the closed form's status differ
 * on its two sides (a step of 1e-6 across the scan direction). */
static void q_of_d(fmpq_t q, double d)
{
    arf_t a;
    arf_init(a);
    arf_set_d(a, d);
    arf_get_fmpq(q, a);
    arf_clear(a);
}

/* the closed form's statuses at (x, y) -+ 1e-6 in direction dir (0: x) differ */
static int separates(double x, double y, int dir)
{
    fmpq_t x0, y0, x1, y1, e;
    int d;
    fmpq_init(x0); fmpq_init(y0); fmpq_init(x1); fmpq_init(y1); fmpq_init(e);
    fmpq_set_si(e, 1, 1000000);
    q_of_d(x0, x); q_of_d(y0, y);
    fmpq_set(x1, x0); fmpq_set(y1, y0);
    if (dir == 0) { fmpq_sub(x0, x0, e); fmpq_add(x1, x1, e); } else { fmpq_sub(y0, y0, e); fmpq_add(y1, y1, e); }
    d = jury_closed(x0, y0) != jury_closed(x1, y1);
    fmpq_clear(x0); fmpq_clear(y0); fmpq_clear(x1); fmpq_clear(y1); fmpq_clear(e);
    return d;
}

static void test_map_arcs(void **state)
{
    int outcome;
    json_t *doc = tu_run_text("param a b\nchar lambda^2 + a*lambda + b\nanalyse map a -3 3 31, b -3 3 31\n", NULL,
                              &outcome, NULL);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0), *b = json_object_get(o, "boundary");
    const char *tab = json_string_value(json_object_get(o, "boundary_table")), *line;
    slong kept = 0;
    (void) state;
    assert_non_null(tab);
    assert_true(json_integer_value(json_object_get(b, "dropped_points")) > 0);
    for (line = strchr(tab, '\n') + 1; *line; line = strchr(line, '\n') + 1) {
        long c;
        double x, y;
        char scan[16];
        if (sscanf(line, "%ld,%lf,%lf,%15[a-z]", &c, &x, &y, scan) != 4) break;
        /* across the curve, in x or in y (a crossing of a row or a column is on the curve) */
        if (!separates(x, y, 0) && !separates(x, y, 1))
            fail_msg("boundary point (%g, %g) (%s) separates nothing", x, y, scan);
        kept++;
    }
    assert_true(kept > 0);
    json_decref(doc);
}

/* ---- corners over irrational values: lambda^2 + (a + b) lambda + a^2 - 1 -------
 * The closed form (derived by hand in cases/region2/sqrt2-quadratic.case from
 * Jury's triangle with c0 = a^2 - 1, c1 = a + b): stable iff 0 < a^2 < 2 and
 * |a + b| < a^2; marginal iff a^2 = 2 and |a + b| < 2, or |a + b| = a^2 < 2. */
static int sqrt2_closed(const fmpq_t a, const fmpq_t b)
{
    fmpq_t c0, c1;
    int k;
    fmpq_init(c0); fmpq_init(c1);
    fmpq_mul(c0, a, a);
    fmpq_sub_si(c0, c0, 1);
    fmpq_add(c1, a, b);
    k = jury_closed(c1, c0);
    fmpq_clear(c0); fmpq_clear(c1);
    return k;
}

/* 300 points in [-3, 3]^2, 100 on the lines a + b = +-a^2, 50 near a = +-sqrt 2 */
static void sqrt2_points(fmpq *xs, fmpq *ys, slong n, flint_rand_t st)
{
    slong i;
    for (i = 0; i < n; i++) {
        if (i < 300) { rand_q(xs + i, st, -3, 3); rand_q(ys + i, st, -3, 3); continue; }
        if (i < 400) {
            rand_q(xs + i, st, -2, 2);
            fmpq_mul(ys + i, xs + i, xs + i);               /* b = +-a^2 - a */
            if (i % 2) fmpq_neg(ys + i, ys + i);
            fmpq_sub(ys + i, ys + i, xs + i);
            continue;
        }
        /* 1.414 < sqrt 2 < 1.415: just inside and just outside the strip */
        fmpq_set_si(xs + i, (i % 2 ? 1414 : 1415) * (i % 4 < 2 ? 1 : -1), 1000);
        rand_q(ys + i, st, -4, 4);
    }
}

/* sign of u + v sqrt 2 (exact) */
static int sign_sqrt2(const fmpq_t u, const fmpq_t v)
{
    fmpq_t l, r;
    int su = fmpq_sgn(u), sv = fmpq_sgn(v), c;
    if (su == 0 || sv == 0 || su == sv) return su != 0 ? su : sv;
    fmpq_init(l); fmpq_init(r);
    fmpq_mul(l, u, u);
    fmpq_mul(r, v, v);
    fmpq_mul_si(r, r, 2);
    c = fmpq_cmp(l, r);                 /* |u| vs |v| sqrt 2 */
    fmpq_clear(l); fmpq_clear(r);
    return c > 0 ? su : (c < 0 ? sv : 0);
}

/* "POLY REL 0" at (s sqrt 2, y), exactly in Q(sqrt 2) */
static int cond_holds_sqrt2(const char *cond, int s, const fmpq_t y)
{
    const char *vars[2] = {"a", "b"};
    char poly[1024], rel[4];
    const char *sp = strrchr(cond, ' ');
    fmpq_mpoly_ctx_t ctx;
    fmpq_mpoly_t P;
    fmpq_poly_t u, m;
    fmpq_t c0, c1;
    size_t n;
    int sg, h;
    assert_non_null(sp);
    n = (size_t) (sp - cond);
    memcpy(poly, cond, n);
    poly[n] = '\0';
    sp = strrchr(poly, ' ');
    snprintf(rel, sizeof rel, "%s", sp + 1);
    poly[sp - poly] = '\0';
    fmpq_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpq_mpoly_init(P, ctx);
    fmpq_poly_init(u); fmpq_poly_init(m);
    fmpq_init(c0); fmpq_init(c1);
    if (fmpq_mpoly_set_str_pretty(P, poly, vars, ctx) != 0) fail_msg("cannot parse '%s'", poly);
    assert_true(fmpq_mpoly_evaluate_one_fmpq(P, P, 1, y, ctx));
    assert_true(fmpq_mpoly_get_fmpq_poly(u, P, 0, ctx));
    fmpq_poly_set_coeff_si(m, 2, 1);
    fmpq_poly_set_coeff_si(m, 0, -2);
    fmpq_poly_rem(u, u, m);                 /* u0 + u1 a, a = s sqrt 2 */
    fmpq_poly_get_coeff_fmpq(c0, u, 0);
    fmpq_poly_get_coeff_fmpq(c1, u, 1);
    if (s < 0) fmpq_neg(c1, c1);
    sg = sign_sqrt2(c0, c1);
    if (strcmp(rel, ">") == 0) h = sg > 0;
    else if (strcmp(rel, ">=") == 0) h = sg >= 0;
    else if (strcmp(rel, "<") == 0) h = sg < 0;
    else if (strcmp(rel, "<=") == 0) h = sg <= 0;
    else if (strcmp(rel, "=") == 0) h = sg == 0;
    else h = sg != 0;
    fmpq_mpoly_clear(P, ctx);
    fmpq_mpoly_ctx_clear(ctx);
    fmpq_poly_clear(u); fmpq_poly_clear(m);
    fmpq_clear(c0); fmpq_clear(c1);
    return h;
}

static int dnf_holds_sqrt2(const json_t *dnf, int s, const fmpq_t y)
{
    size_t i, j;
    for (i = 0; i < json_array_size(dnf); i++) {
        const json_t *c = json_array_get(dnf, i);
        int all = 1;
        for (j = 0; j < json_array_size(c) && all; j++)
            all = cond_holds_sqrt2(json_string_value(json_array_get(c, j)), s, y);
        if (all) return 1;
    }
    return 0;
}

static void test_irrational_lines(void **state)
{
    const char *rel = "cases/region2/sqrt2-quadratic.case";
    int outcome;
    json_t *doc;
    const json_t *o, *fo, *cells, *b;
    flint_rand_t st;
    fmpq_t y, t;
    slong i, nline = 0, nsec = 0;
    (void) state;
    /* formula_complete (no undecided cell) and the run-time cross-check: region_of */
    region_test(rel, 450, sqrt2_points, sqrt2_closed, 3, NULL);
    doc = region_of(rel, &outcome);
    o = json_array_get(json_object_get(doc, "results"), 0);
    fo = json_object_get(o, "formula");
    cells = json_object_get(o, "cells");
    b = json_object_get(o, "boundary");
    assert_int_equal(json_integer_value(json_object_get(o, "undecided_lines")), 0);
    /* a^2 - 2 separates (marginal on the lines, unstable beyond, stable inside) */
    assert_string_equal(json_string_value(json_array_get(b, 2)), "a^2 - 2");
    /* on the lines a = +-sqrt 2 exactly: marginal iff |a + b| < 2, i.e.
     * (a + b)^2 - 4 = b^2 + 2 a b - 2 < 0, sign of (b^2 - 2) + 2 s b sqrt 2 */
    flint_randinit(st);
    fmpq_init(y); fmpq_init(t);
    for (i = 0; i < 200; i++) {
        int s = i % 2 ? 1 : -1, want, got;
        fmpq_t u, v;
        rand_q(y, st, -5, 5);
        fmpq_init(u); fmpq_init(v);
        fmpq_mul(u, y, y);
        fmpq_sub_si(u, u, 2);
        fmpq_mul_si(v, y, 2 * s);
        want = sign_sqrt2(u, v) < 0 ? 1 : 0;
        got = dnf_holds_sqrt2(json_object_get(fo, "stable"), s, y) ? 2
              : (dnf_holds_sqrt2(json_object_get(fo, "marginal"), s, y) ? 1 : 0);
        if (got != want) {
            char *ys = fmpq_get_str(NULL, 10, y);
            fail_msg("at (%dsqrt2, %s) the formula says %d, the closed form %d", s, ys, got, want);
        }
        fmpq_clear(u); fmpq_clear(v);
    }
    /* the cells over the irrational lines: sectors as the closed form, the
     * four corners (sections: a + b = +-2 there) unstable */
    for (i = 0; i < (slong) json_array_size(cells); i++) {
        const json_t *e = json_array_get(cells, i), *ca = json_object_get(e, "a"), *cb = json_object_get(e, "b");
        const char *stc = json_string_value(json_object_get(e, "status"));
        if (json_is_string(ca)) continue;
        nline++;
        assert_string_equal(json_string_value(json_object_get(ca, "minpoly")), "a^2 - 2");
        if (!json_is_string(cb)) {
            nsec++;
            assert_string_equal(stc, "unstable");
        } else {
            int s = json_integer_value(json_object_get(ca, "root_index")) == 0 ? -1 : 1;
            fmpq_t u, v;
            fmpq_init(u); fmpq_init(v);
            assert_int_equal(fmpq_set_str(y, json_string_value(cb), 10), 0);
            fmpq_mul(u, y, y);
            fmpq_sub_si(u, u, 2);
            fmpq_mul_si(v, y, 2 * s);
            assert_string_equal(stc, sign_sqrt2(u, v) < 0 ? "marginal" : "unstable");
            fmpq_clear(u); fmpq_clear(v);
        }
    }
    assert_int_equal(nline, 10);
    assert_int_equal(nsec, 4);
    fmpq_clear(y); fmpq_clear(t);
    flint_randclear(st);
    json_decref(doc);
}

/* ---- lines over irrational alpha with big towers (Park, alpha x wh) --------- */

/* g = wh^2 (4 alpha + 1)(alpha - 3) + 4 (2 alpha - 3): stable iff g < 0,
 * marginal iff g = 0 (cases/region2/park-alpha-wh.case).  Independent of
 * the decomposition: for 0 <= alpha <= 3/2 g < 0 for every wh > 0, QEPCAD
 * B's answer "alpha >= 0 /\ 2 alpha - 3 <= 0" for all wh on recstab's
 * Routh-Hurwitz conditions (bench/README.md); every point below is also
 * checked against the exact point verdict (check_points). */
static int park_closed(const fmpq_t al, const fmpq_t wh)
{
    fmpq_t g, t, u;
    int k;
    fmpq_init(g); fmpq_init(t); fmpq_init(u);
    fmpq_mul_si(t, al, 4);
    fmpq_add_si(t, t, 1);
    fmpq_sub_si(u, al, 3);
    fmpq_mul(t, t, u);
    fmpq_mul(u, wh, wh);
    fmpq_mul(g, t, u);
    fmpq_mul_si(t, al, 8);
    fmpq_sub_si(t, t, 12);
    fmpq_add(g, g, t);
    k = fmpq_sgn(g) < 0 ? 2 : (fmpq_sgn(g) == 0 ? 1 : 0);
    fmpq_clear(g); fmpq_clear(t); fmpq_clear(u);
    return k;
}

/* 150 points in [0, 4] x (0, 4], 50 near the lines alpha = 0.1299 and
 * alpha = 3/2 */
static void park_points(fmpq *xs, fmpq *ys, slong n, flint_rand_t st)
{
    slong i;
    for (i = 0; i < n; i++) {
        rand_q(ys + i, st, 0, 4);
        if (fmpq_is_zero(ys + i)) fmpq_set_si(ys + i, 1, 7);
        if (i < 150) { rand_q(xs + i, st, 0, 4); continue; }
        fmpq_set_si(xs + i, i % 2 ? 1299 : 1300, 10000);
        if (i % 4 >= 2) fmpq_set_si(xs + i, i % 2 ? 1499 : 1501, 1000);
    }
}

static void test_irrational_big_towers(void **state)
{
    const char *rel = "cases/region2/park-alpha-wh.case";
    int outcome;
    json_t *doc;
    const json_t *o, *cells;
    slong i, nline = 0, nballs = 0;
    (void) state;
    /* formula_complete and the run-time cross-check (region_of), the closed
     * form and the point verdict at 200 points */
    region_test(rel, 200, park_points, park_closed, 1, "4*wh^2*alpha^2 - 11*wh^2*alpha - 3*wh^2 + 8*alpha - 12");
    doc = region_of(rel, &outcome);
    o = json_array_get(json_object_get(doc, "results"), 0);
    cells = json_object_get(o, "cells");
    /* was 1 (the column over alpha = 0.1299 needed a tower of degree 4 * 24) */
    assert_int_equal(json_integer_value(json_object_get(o, "undecided_lines")), 0);
    for (i = 0; i < (slong) json_array_size(cells); i++) {
        const json_t *e = json_array_get(cells, i), *ca = json_object_get(e, "alpha"), *cb = json_object_get(e, "wh");
        const char *stc = json_string_value(json_object_get(e, "status"));
        if (json_is_string(ca)) continue;
        nline++;
        assert_string_not_equal(stc, "undecided");
        if (json_object_get(e, "decided_by") == NULL) continue;
        nballs++;
        /* the section at (0.1299..., 1.5915...) on the discriminant's curve:
         * p has a double root 0.4597 and a pair of modulus 0.8626 there
         * (Durand-Kerner in double precision on p(lambda) of the case's
         * comment, far from the circle): stable */
        assert_string_equal(json_string_value(json_object_get(ca, "minpoly")),
                            "112*alpha^4 - 744*alpha^3 + 1752*alpha^2 - 1116*alpha + 117");
        assert_int_equal(json_integer_value(json_object_get(ca, "root_index")), 0);
        assert_true(strncmp(json_string_value(json_object_get(cb, "approx")), "1.5915", 6) == 0);
        assert_string_equal(stc, "stable");
        assert_string_equal(json_string_value(json_object_get(e, "decided_by")), "root balls");
    }
    assert_true(nline > 0);
    assert_int_equal(nballs, 1);
    json_decref(doc);
}

/* ---- vertical arcs' sides proved; marginal-only curves ------------------- */

/* cases/region2/steep-wedge.case, by hand: p = (lambda - c1)(lambda - c2),
 * c1 = b - 10000 a, c2 = a + 1/2: stable iff |c1| < 1 and |c2| < 1;
 * marginal iff both <= 1 in modulus, one = 1, and not c1 = c2 (a double
 * root on the circle of a char line is unstable) */
static int wedge_closed(const fmpq_t a, const fmpq_t b)
{
    fmpq_t c1, c2;
    int k, in1, in2, on1, on2;
    fmpq_init(c1); fmpq_init(c2);
    fmpq_mul_si(c1, a, 10000);
    fmpq_sub(c1, b, c1);
    fmpq_set_si(c2, 1, 2);
    fmpq_add(c2, a, c2);
    in1 = fmpq_cmp_si(c1, 1) < 0 && fmpq_cmp_si(c1, -1) > 0;
    in2 = fmpq_cmp_si(c2, 1) < 0 && fmpq_cmp_si(c2, -1) > 0;
    on1 = fmpq_cmp_si(c1, 1) == 0 || fmpq_cmp_si(c1, -1) == 0;
    on2 = fmpq_cmp_si(c2, 1) == 0 || fmpq_cmp_si(c2, -1) == 0;
    if (in1 && in2) k = 2;
    else if ((in1 || on1) && (in2 || on2) && !(on1 && on2 && fmpq_equal(c1, c2))) k = 1;
    else k = 0;
    fmpq_clear(c1); fmpq_clear(c2);
    return k;
}

/* 100 points near the strip b = 10000 a + r, |r| <= 2; 60 on a = 1/2 and
 * a = -3/2; 40 on c1 = +-1 */
static void wedge_points(fmpq *xs, fmpq *ys, slong n, flint_rand_t st)
{
    slong i;
    fmpq_t r;
    fmpq_init(r);
    for (i = 0; i < n; i++) {
        rand_q(r, st, -2, 2);
        if (i < 100) rand_q(xs + i, st, -2, 1);
        else if (i < 160) fmpq_set_si(xs + i, i % 2 ? 1 : -3, 2);
        else { rand_q(xs + i, st, -2, 1); fmpq_set_si(r, i % 2 ? 1 : -1, 1); }
        fmpq_mul_si(ys + i, xs + i, 10000);
        fmpq_add(ys + i, ys + i, r);
    }
    fmpq_clear(r);
}

static void test_vertical_sides(void **state)
{
    const char *rel = "cases/region2/steep-wedge.case";
    int outcome, found = 0;
    json_t *doc;
    const json_t *o, *arcs, *b;
    size_t i;
    (void) state;
    region_test(rel, 200, wedge_points, wedge_closed, 4, NULL);
    doc = region_of(rel, &outcome);
    o = json_array_get(json_object_get(doc, "results"), 0);
    b = json_object_get(o, "boundary");
    arcs = json_object_get(o, "arcs");
    /* the lines a = 1/2 and a = -3/2 bound the strip (were missing: their
     * side points a0 -+ 1/1024 fell outside the 2/10000-wide strip) */
    for (i = 0; i < json_array_size(b); i++)
        found |= (strcmp(json_string_value(json_array_get(b, i)), "2*a - 1") == 0)
                 | (strcmp(json_string_value(json_array_get(b, i)), "2*a + 3") == 0) << 1;
    assert_int_equal(found, 3);
    found = 0;
    for (i = 0; i < json_array_size(arcs); i++) {
        const json_t *e = json_array_get(arcs, i);
        if (strcmp(json_string_value(json_object_get(e, "poly")), "2*a - 1") != 0) continue;
        /* left of a = 1/2 inside the strip: stable; right: c2 > 1 */
        assert_string_equal(json_string_value(json_object_get(e, "left")), "stable");
        assert_string_equal(json_string_value(json_object_get(e, "right")), "unstable");
        found++;
    }
    assert_int_equal(found, 1);
    assert_int_equal(json_array_size(json_object_get(o, "marginal_curves")), 0);
    json_decref(doc);
}

static void test_marginal_curves(void **state)
{
    int outcome;
    json_t *doc = region_of("cases/region2/driven-oscillators.case", &outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0), *m = json_object_get(o, "marginal_curves");
    const json_t *ma = json_object_get(o, "marginal_arcs");
    (void) state;
    /* by hand (the case's comment): marginal iff eps = 0, unstable on both
     * sides: no boundary of a stable set, but where the status changes */
    assert_int_equal(json_array_size(json_object_get(o, "boundary")), 0);
    assert_int_equal(json_array_size(m), 1);
    assert_string_equal(json_string_value(json_array_get(m, 0)), "eps");
    assert_true(json_array_size(ma) >= 1);
    assert_string_equal(json_string_value(json_object_get(json_array_get(ma, 0), "on")), "marginal");
    assert_string_equal(json_string_value(json_object_get(json_array_get(ma, 0), "sides")), "unstable");
    json_decref(doc);
}

/* ---- errors ------------------------------------------------------------------ */

static void test_bad(void **state)
{
    static const char *bad[] = {"analyse region a, a\n", "analyse region a, zz\n", "analyse region a, b at a=1\n",
                                "analyse region a,\n", "analyse region a, b for all [c]\n",
                                "analyse region a, b\n" /* c symbolic */};
    size_t i;
    (void) state;
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char buf[512];
        int outcome, code;
        json_t *doc;
        snprintf(buf, sizeof buf, "param a b c\nchar lambda^2 + a*lambda + b + c\n%s", bad[i]);
        doc = tu_run_text(buf, NULL, &outcome, &code);
        if (code != RS_ERR_INPUT) fail_msg("%s: code %d, expected an input error", bad[i], code);
        json_decref(doc);
    }
    {   /* the third parameter set: fine */
        int outcome, code;
        json_t *doc = tu_run_text("param a b c\nchar lambda^2 + a*lambda + b + c\nanalyse region a, b at c=0\n",
                                  NULL, &outcome, &code);
        assert_int_equal(code, RS_OK);
        json_decref(doc);
    }
}

/* ---- region re(z), im(z): the plane of a complex parameter --------------- */

/* forward Euler: lambda = 1 + z, stable iff |1 + z| < 1, marginal iff
 * |1 + z| = 1 (one simple root), i.e. (x + 1)^2 + y^2 against 1 (by hand) */
static int euler_z(const fmpq_t x, const fmpq_t y)
{
    fmpq_t t, u;
    int k;
    fmpq_init(t); fmpq_init(u);
    fmpq_add_si(t, x, 1);
    fmpq_mul(t, t, t);
    fmpq_mul(u, y, y);
    fmpq_add(t, t, u);
    k = fmpq_cmp_si(t, 1);
    fmpq_clear(t); fmpq_clear(u);
    return k < 0 ? 2 : (k == 0 ? 1 : 0);
}

/* trapezoid: |2 + z| < |2 - z| iff x < 0, equal (the root on the circle,
 * simple) iff x = 0 (by hand) */
static int trap_z(const fmpq_t x, const fmpq_t y) { (void) y; return fmpq_sgn(x) < 0 ? 2 : (fmpq_is_zero(x) ? 1 : 0); }

/* leapfrog lambda^2 - 2 z lambda - 1: never stable, marginal iff x = 0 and
 * |y| < 1 (derived in cases/complex/leapfrog-zregion.case) */
static int leapfrog_z(const fmpq_t x, const fmpq_t y)
{
    return fmpq_is_zero(x) && fmpz_cmpabs(fmpq_numref(y), fmpq_denref(y)) < 0 ? 1 : 0;
}

/* the exact point verdict at z = x + i y (`set z = x+y*i`, stability) */
static int cx_point_verdict(const char *text, const fmpq_t x, const fmpq_t y)
{
    rs_case_t c;
    rs_error_t err;
    rs_options_t opt;
    json_t *doc = NULL;
    char set[300], *xs = fmpq_get_str(NULL, 10, x), *ys;
    const char *st;
    int outcome, k;
    fmpq_t ay;
    fmpq_init(ay);
    fmpq_abs(ay, y);
    ys = fmpq_get_str(NULL, 10, ay);
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    assert_int_equal(rs_case_parse_string(c, "point.case", text, strlen(text), err), RS_OK);
    rs_case_clear_requests(c);
    rs_case_add_request(c, "stability", "test", 1, 1);
    snprintf(set, sizeof set, "z=%s%s%s*i", xs, fmpq_sgn(y) < 0 ? "-" : "+", ys);
    assert_int_equal(rs_case_set_value(c, set, err), RS_OK);
    if (rs_analysis_run(&doc, &outcome, c, &opt, err) != RS_OK) fail_msg("point %s: %s", set, err->msg);
    st = json_string_value(json_object_get(json_array_get(json_object_get(doc, "results"), 0), "status"));
    assert_non_null(st);
    k = strcmp(st, "stable") == 0 ? 2 : (strcmp(st, "marginal") == 0 ? 1 : 0);
    json_decref(doc);
    rs_case_clear(c);
    flint_free(xs);
    flint_free(ys);
    fmpq_clear(ay);
    return k;
}

/* the stable and marginal formulas of region re(z), im(z) against the
 * closed form cf at 400 rational points: 250 anywhere, 75 on the circle
 * |1 + z| = 1, 75 on the imaginary axis; the exact point verdict at every
 * fifth point of the last 150 */
static void zregion_check(const char *rel, closed_fn cf)
{
    int outcome;
    json_t *doc = region_of(rel, &outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
    const json_t *fo = json_object_get(o, "formula");
    flint_rand_t st;
    fmpq *xs = _fmpq_vec_init(400), *ys = _fmpq_vec_init(400);
    fmpq_t t;
    slong i, n = 0;
    assert_string_equal(json_string_value(json_array_get(json_object_get(o, "params"), 0)), "re(z)");
    assert_string_equal(json_string_value(json_array_get(json_object_get(o, "params"), 1)), "im(z)");
    assert_true(json_is_array(json_object_get(fo, "marginal")));
    assert_true(json_is_true(json_object_get(o, "marginal_complete")));
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    flint_randinit(st);
    fmpq_init(t);
    for (i = 0; i < 400; i++) {
        fmpq *x = xs + i, *y = ys + i;
        if (i < 250) {
            rand_q(x, st, -3, 1);
            rand_q(y, st, -2, 2);
        } else if (i < 325) {
            /* on the circle |1 + z| = 1: (1 - t^2, 2 t)/(1 + t^2) - (1, 0) (rational points) */
            rand_q(t, st, -4, 4);
            fmpq_mul(x, t, t);
            fmpq_add_si(y, x, 1);
            fmpq_neg(x, x);
            fmpq_add_si(x, x, 1);
            fmpq_div(x, x, y);
            fmpq_sub_si(x, x, 1);
            fmpq_mul_si(t, t, 2);
            fmpq_div(y, t, y);
        } else {
            /* on the imaginary axis, |y| = 1 now and then */
            fmpq_zero(x);
            if (i % 10 == 0) fmpq_set_si(y, i % 20 == 0 ? 1 : -1, 1);
            else rand_q(y, st, -2, 2);
        }
    }
    check_points(o, case_text(rel), xs, ys, 400, cf, 0, rel);
    for (i = 250; i < 400; i += 5, n++)
        if (cx_point_verdict(case_text(rel), xs + i, ys + i) != cf(xs + i, ys + i)) {
            char *a = fmpq_get_str(NULL, 10, xs + i), *b = fmpq_get_str(NULL, 10, ys + i);
            fail_msg("%s: at z = %s + (%s) i the point verdict differs from the closed form", rel, a, b);
        }
    assert_int_equal(n, 30);
    _fmpq_vec_clear(xs, 400);
    _fmpq_vec_clear(ys, 400);
    fmpq_clear(t);
    flint_randclear(st);
    json_decref(doc);
}

/* a char line with i, lambda - 1 - i z: the root 1 - y + i x, stable iff
 * x^2 + y^2 - 2 y < 0, marginal iff = 0 (by hand, in the case file) */
static int rotated_z(const fmpq_t x, const fmpq_t y)
{
    fmpq_t t, u;
    int k;
    fmpq_init(t); fmpq_init(u);
    fmpq_mul(t, x, x);
    fmpq_mul(u, y, y);
    fmpq_add(t, t, u);
    fmpq_mul_si(u, y, 2);
    fmpq_sub(t, t, u);
    k = fmpq_sgn(t);
    fmpq_clear(t); fmpq_clear(u);
    return k < 0 ? 2 : (k == 0 ? 1 : 0);
}

static void test_zregion(void **state)
{
    (void) state;
    zregion_check("cases/complex/forward-euler-zregion.case", euler_z);
    zregion_check("cases/complex/trapezoid-zregion.case", trap_z);
    zregion_check("cases/complex/leapfrog-zregion.case", leapfrog_z);
    zregion_check("cases/complex/rotated-euler-zregion.case", rotated_z);
}

/* The cells on x = x0, y = +-sqrt(num/den) that the norm p conj(p) alone left
 * open (marginal_undecided_cells 2 before the rotated norms), decided now:
 * each must be not_stable, and a root of p of modulus > 1 there, certified
 * by Arb from p's coefficients (a route independent of the decomposition:
 * acb_poly_find_roots on p at the Arb ball of z), must exist.  p is given by
 * its coefficients c_k = a_k + b_k z (k = 0..3, lambda^k). */
static void open_cells_check(const char *method, const char *x0, slong num, slong den, const char *minpoly,
                             const slong *a, const slong *b, slong scale, slong open)
{
    char text[400];
    int outcome, code, found = 0;
    json_t *doc;
    const json_t *o, *cells;
    size_t i;
    snprintf(text, sizeof text, "param z complex\nsubsystem S state y\n  y' = z*y\nintegrate S %s 1\n"
             "analyse region re(z), im(z)\n", method);
    doc = tu_run_text(text, NULL, &outcome, &code);
    assert_int_equal(code, RS_OK);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    o = json_array_get(json_object_get(doc, "results"), 0);
    /* open: the circle-locus cells whose marginal-or-unstable question is
     * left open (counted, never guessed) */
    assert_int_equal(json_integer_value(json_object_get(o, "marginal_undecided_cells")), open);
    cells = json_object_get(o, "cells");
    for (i = 0; i < json_array_size(cells); i++) {
        const json_t *e = json_array_get(cells, i), *im = json_object_get(e, "im(z)");
        const char *re = json_string_value(json_object_get(e, "re(z)"));
        if (re == NULL || strcmp(re, x0) != 0 || !json_is_object(im)
            || strcmp(json_string_value(json_object_get(im, "minpoly")), minpoly) != 0) continue;
        found++;
        assert_string_equal(json_string_value(json_object_get(e, "status")), "not_stable");
    }
    assert_int_equal(found, 2);
    {
        slong prec = 128, k, n;
        int outside = 0, sg;
        fmpq_t q;
        acb_t z, c;
        acb_poly_t p;
        acb_ptr rt = _acb_vec_init(3);
        fmpq_init(q);
        acb_init(z); acb_init(c);
        acb_poly_init(p);
        for (sg = -1; sg <= 1; sg += 2) {
            assert_int_equal(fmpq_set_str(q, x0, 10), 0);
            arb_set_fmpq(acb_realref(z), q, prec);
            arb_set_si(acb_imagref(z), num);
            arb_div_si(acb_imagref(z), acb_imagref(z), den, prec);
            arb_sqrt(acb_imagref(z), acb_imagref(z), prec);
            if (sg < 0) arb_neg(acb_imagref(z), acb_imagref(z));
            for (k = 0; k <= 3; k++) {
                acb_mul_si(c, z, b[k], prec);
                acb_add_si(c, c, a[k], prec);
                acb_div_si(c, c, scale, prec);
                acb_poly_set_coeff_acb(p, k, c);
            }
            n = acb_poly_find_roots(rt, p, NULL, 0, prec);
            assert_int_equal(n, 3);
            for (k = 0; k < 3; k++) {
                arb_t m;
                arb_init(m);
                acb_abs(m, rt + k, prec);
                arb_sub_si(m, m, 1, prec);
                outside += arb_is_positive(m);
                arb_clear(m);
            }
        }
        assert_int_equal(outside, 2);   /* one root outside at each of the two points */
        _acb_vec_clear(rt, 3);
        acb_poly_clear(p);
        acb_clear(z); acb_clear(c);
        fmpq_clear(q);
    }
    json_decref(doc);
}

/* lambda^2 + c lambda + 1, c = z^3 - 2 z: never stable, marginal iff c is
 * real with |c| < 2 (cases/complex/conjugate-pair-zregion.case, by hand) */
static int conjpair_z(const fmpq_t x, const fmpq_t y)
{
    fmpq_t cr, ci, t;
    int k;
    fmpq_init(cr); fmpq_init(ci); fmpq_init(t);
    /* Re c = x^3 - 3 x y^2 - 2 x, Im c = 3 x^2 y - y^3 - 2 y */
    fmpq_mul(cr, x, x);
    fmpq_mul(t, y, y);
    fmpq_mul_si(t, t, 3);
    fmpq_sub(cr, cr, t);
    fmpq_sub_si(cr, cr, 2);
    fmpq_mul(cr, cr, x);
    fmpq_mul(ci, x, x);
    fmpq_mul_si(ci, ci, 3);
    fmpq_mul(t, y, y);
    fmpq_sub(ci, ci, t);
    fmpq_sub_si(ci, ci, 2);
    fmpq_mul(ci, ci, y);
    fmpq_abs(cr, cr);
    k = fmpq_is_zero(ci) && fmpq_cmp_si(cr, 2) < 0;
    fmpq_clear(cr); fmpq_clear(ci); fmpq_clear(t);
    return k;
}

/* the marginal hyperbola 3 x^2 - y^2 = 2 reached only through irrational
 * samples: both formulas against the closed form at 300 rational points
 * (100 anywhere, 100 on the real axis, 100 on the hyperbola: the line
 * through (1, 1) of slope t meets it again at x = 1 + u, y = 1 + t u,
 * u = (2 t - 6)/(3 - t^2)), the point verdict at every tenth */
static void test_zregion_conjugate_pair(void **state)
{
    const char *rel = "cases/complex/conjugate-pair-zregion.case";
    int outcome;
    json_t *doc = tu_run_case(rel, NULL, -1, &outcome);
    const json_t *o = json_array_get(json_object_get(doc, "results"), 0);
    flint_rand_t st;
    fmpq *xs = _fmpq_vec_init(300), *ys = _fmpq_vec_init(300);
    fmpq_t t, u;
    slong i, hyp = 0, marg = 0;
    (void) state;
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    assert_int_equal(json_integer_value(json_object_get(o, "marginal_undecided_cells")), 0);
    flint_randinit(st);
    fmpq_init(t); fmpq_init(u);
    for (i = 0; i < 300; i++) {
        fmpq *x = xs + i, *y = ys + i;
        if (i < 100) {
            rand_q(x, st, -2, 2);
            rand_q(y, st, -2, 2);
        } else if (i < 200) {
            rand_q(x, st, -2, 2);
            fmpq_zero(y);
        } else {
            do rand_q(t, st, -4, 4); while (fmpq_cmp_si(t, 3) == 0);
            fmpq_mul(u, t, t);
            fmpq_neg(u, u);
            fmpq_add_si(u, u, 3);            /* 3 - t^2 != 0: t rational */
            fmpq_mul_si(x, t, 2);
            fmpq_sub_si(x, x, 6);
            fmpq_div(u, x, u);
            fmpq_add_si(x, u, 1);
            fmpq_mul(y, t, u);
            fmpq_add_si(y, y, 1);
            hyp++;
        }
        marg += conjpair_z(xs + i, ys + i) == 1 && i >= 200;
    }
    assert_int_equal(hyp, 100);
    assert_true(marg >= 10);   /* the hyperbola's marginal arcs are hit, not only its unstable parts */
    check_points(o, case_text(rel), xs, ys, 300, conjpair_z, 0, rel);
    for (i = 0; i < 300; i += 10)
        if (cx_point_verdict(case_text(rel), xs + i, ys + i) != conjpair_z(xs + i, ys + i)) {
            char *a = fmpq_get_str(NULL, 10, xs + i), *b = fmpq_get_str(NULL, 10, ys + i);
            fail_msg("%s: at z = %s + (%s) i the point verdict differs from the closed form", rel, a, b);
        }
    _fmpq_vec_clear(xs, 300);
    _fmpq_vec_clear(ys, 300);
    fmpq_clear(t); fmpq_clear(u);
    flint_randclear(st);
    json_decref(doc);
}

static void test_zregion_open_cells(void **state)
{
    (void) state;
    /* BDF3 on y' = z y, h = 1: (11/6 - z) lambda^3 - 3 lambda^2 + 3/2 lambda - 1/3
     * (times 6); at z = 25/24 +- i sqrt(15)/8 the root moduli are 0.3564, 0.3592,
     * 2.8059 (mpmath polyroots, 40 digits) */
    open_cells_check("bdf 3", "25/24", 15, 64, "64*im(z)^2 - 15", (slong[]) {-2, 9, -18, 11},
                     (slong[]) {0, 0, 0, -6}, 6, 0);
    /* AB3: lambda^3 - lambda^2 - z (23 lambda^2 - 16 lambda + 5)/12 (times 12); at
     * z = 288/1495 +- i sqrt(1567536/2235025) the moduli are 0.3581, 0.6851, 1.4597 */
    open_cells_check("adams-bashforth 3", "288/1495", 1567536, 2235025, "2235025*im(z)^2 - 1567536",
                     (slong[]) {0, 0, -12, 12}, (slong[]) {-5, 16, -23, 0}, 12, 8);
    /* (AB3's 8 open cells: sections decided not stable by their signs whose
     * field Q(alpha, beta) has degree 48, or over lines of degree 11; they
     * were undecided cells before, outside the count) */
}

/* a coordinate of a cell as a ball: a rational, or the JSON interval of an
 * algebraic one after checking that its minimal polynomial changes sign
 * across it (exact, FLINT's parser on the printed polynomial) */
static void coord_ball(arb_t out, const json_t *v, const char *var, slong prec)
{
    fmpq_t q, lo, hi, vl, vh;
    fmpq_init(q); fmpq_init(lo); fmpq_init(hi); fmpq_init(vl); fmpq_init(vh);
    if (json_is_string(v)) {
        assert_int_equal(fmpq_set_str(q, json_string_value(v), 10), 0);
        fmpq_canonicalise(q);
        arb_set_fmpq(out, q, prec);
    } else {
        const char *vars[1];
        fmpq_mpoly_ctx_t ctx;
        fmpq_mpoly_t P;
        fmpq *pt[1];
        arb_t b;
        const json_t *iv = json_object_get(v, "interval");
        vars[0] = var;
        assert_non_null(iv);
        assert_int_equal(fmpq_set_str(lo, json_string_value(json_array_get(iv, 0)), 10), 0);
        assert_int_equal(fmpq_set_str(hi, json_string_value(json_array_get(iv, 1)), 10), 0);
        fmpq_canonicalise(lo); fmpq_canonicalise(hi);
        fmpq_mpoly_ctx_init(ctx, 1, ORD_LEX);
        fmpq_mpoly_init(P, ctx);
        if (fmpq_mpoly_set_str_pretty(P, json_string_value(json_object_get(v, "minpoly")), vars, ctx) != 0)
            fail_msg("cannot parse %s", json_string_value(json_object_get(v, "minpoly")));
        pt[0] = lo;
        assert_true(fmpq_mpoly_evaluate_all_fmpq(vl, P, pt, ctx));
        pt[0] = hi;
        assert_true(fmpq_mpoly_evaluate_all_fmpq(vh, P, pt, ctx));
        assert_true(fmpq_sgn(vl) * fmpq_sgn(vh) < 0);   /* a root in [lo, hi] */
        arb_init(b);
        arb_set_fmpq(out, lo, prec);
        arb_set_fmpq(b, hi, prec);
        arb_union(out, out, b, prec);
        arb_clear(b);
        fmpq_mpoly_clear(P, ctx);
        fmpq_mpoly_ctx_clear(ctx);
    }
    fmpq_clear(q); fmpq_clear(lo); fmpq_clear(hi); fmpq_clear(vl); fmpq_clear(vh);
}

/* Every decided cell over an irrational re(z) (the sections the signs and
 * the relative fields now decide; before they were undecided lines) against
 * Arb root balls of p itself at the cell's sample, p = sum_k sum_j
 * cf[k][j] z^j lambda^k written out by hand from the method (independent
 * of recstab's lowering): stable needs every root ball strictly inside;
 * marginal a root ball meeting the circle and none strictly outside; not
 * stable a root ball not strictly inside.  Returns the number checked. */
static slong sections_check(const char *method, slong n, slong zd, const slong *cf, slong min_checked)
{
    char text[400];
    int outcome, code;
    json_t *doc;
    const json_t *o, *cells;
    size_t i;
    slong prec = 256, checked = 0, k, j;
    acb_t z, c, zp;
    acb_poly_t p;
    acb_ptr rt = _acb_vec_init(n);
    arb_t m;
    snprintf(text, sizeof text, "param z complex\nsubsystem S state y\n  y' = z*y\nintegrate S %s 1\n"
             "analyse region re(z), im(z)\n", method);
    doc = tu_run_text(text, NULL, &outcome, &code);
    assert_int_equal(code, RS_OK);
    assert_int_equal(outcome & RS_OUTCOME_INCONSISTENT, 0);
    o = json_array_get(json_object_get(doc, "results"), 0);
    assert_true(json_is_true(json_object_get(o, "formula_complete")));
    assert_int_equal(json_integer_value(json_object_get(o, "undecided_lines")), 0);
    cells = json_object_get(o, "cells");
    acb_init(z); acb_init(c); acb_init(zp); arb_init(m);
    acb_poly_init(p);
    for (i = 0; i < json_array_size(cells); i++) {
        const json_t *e = json_array_get(cells, i), *xr = json_object_get(e, "re(z)"), *yi = json_object_get(e, "im(z)");
        const char *st = json_string_value(json_object_get(e, "status"));
        slong in = 0, out = 0, on = 0, nr;
        if (!json_is_object(xr) || yi == NULL || json_is_null(yi) || strcmp(st, "outside") == 0) continue;
        assert_string_not_equal(st, "undecided");
        coord_ball(acb_realref(z), xr, "re(z)", prec);
        coord_ball(acb_imagref(z), yi, "im(z)", prec);
        acb_poly_zero(p);
        for (k = 0; k <= n; k++) {
            acb_zero(c);
            acb_one(zp);
            for (j = 0; j <= zd; j++) {
                acb_addmul_si(c, zp, cf[k * (zd + 1) + j], prec);
                acb_mul(zp, zp, z, prec);
            }
            acb_poly_set_coeff_acb(p, k, c);
        }
        nr = acb_poly_find_roots(rt, p, NULL, 0, prec);
        assert_int_equal(nr, n);
        for (k = 0; k < n; k++) {
            acb_abs(m, rt + k, prec);
            arb_sub_si(m, m, 1, prec);
            if (arb_is_negative(m)) in++;
            else if (arb_is_positive(m)) out++;
            else on++;
        }
        if (strcmp(st, "stable") == 0) assert_int_equal(in, n);
        else if (strcmp(st, "marginal") == 0) { assert_int_equal(out, 0); assert_true(on >= 1); }
        else assert_true(in < n);
        checked++;
    }
    assert_true(checked >= min_checked);
    acb_clear(z); acb_clear(c); acb_clear(zp); arb_clear(m);
    acb_poly_clear(p);
    _acb_vec_clear(rt, n);
    json_decref(doc);
    return checked;
}

static void test_zregion_sections(void **state)
{
    /* RK4: p = 24 lambda - (24 + 24 z + 12 z^2 + 4 z^3 + z^4) (24 R(z), Hairer-
     * Wanner IV.2); before: 34 undecided section cells, 0 now */
    static const slong rk4[] = {-24, -24, -12, -4, -1, 24, 0, 0, 0, 0};
    /* BDF3 (times 6): (11 - 6 z) lambda^3 - 18 lambda^2 + 9 lambda - 2; before: 8 */
    static const slong bdf3[] = {-2, 0, 9, 0, -18, 0, 11, -6};
    (void) state;
    sections_check("rk rk4", 1, 4, rk4, 34);
    sections_check("bdf 3", 3, 1, bdf3, 8);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_jury),
        cmocka_unit_test(test_theta),
        cmocka_unit_test(test_newmark),
        cmocka_unit_test(test_driven),
        cmocka_unit_test(test_irrational_lines),
        cmocka_unit_test(test_irrational_big_towers),
        cmocka_unit_test(test_vertical_sides),
        cmocka_unit_test(test_marginal_curves),
        cmocka_unit_test(test_qepcad),
        cmocka_unit_test(test_map_arcs),
        cmocka_unit_test(test_bad),
        cmocka_unit_test(test_zregion),
        cmocka_unit_test(test_zregion_open_cells),
        cmocka_unit_test(test_zregion_conjugate_pair),
        cmocka_unit_test(test_zregion_sections),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
