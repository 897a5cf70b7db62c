/* test_routh.c -- exact Routh arrays of q = bilinear(p): closed forms,
 * hand-computed arrays, every singular case, and the fraction-free
 * symbolic array. */
#include <string.h>
#include "testutil.h"
#include "closed_forms.h"
#include <flint/fmpz_poly.h>
#include <flint/fmpq.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/routh.h"
#include "recstab/bilinear.h"
#include "recstab/rootcount.h"


/* p whose bilinear transform is q up to a constant factor:
 * p(l) = B(q(-z))(-l), since B(B(f))(l) = (-2l)^n f(-1/l). */
static void poly_from_q(fmpz_poly_t p, slong deg, const long *q)
{
    slong i;
    poly_set(p, deg, q);
    for (i = 1; i < fmpz_poly_length(p); i += 2)
        fmpz_neg(p->coeffs + i, p->coeffs + i);
    rs_bilinear_fmpz_poly(p, p);
    for (i = 1; i < fmpz_poly_length(p); i += 2)
        fmpz_neg(p->coeffs + i, p->coeffs + i);
}

static slong count_events(const rs_routh_t r, rs_routh_event_kind_t kind)
{
    slong i, n = 0;
    for (i = 0; i < r->nevents; i++) {
        n += r->events[i].kind == kind;
        assert_non_null(r->events[i].text);
        assert_true(strlen(r->events[i].text) > 10);
    }
    return n;
}

static void row_equals(const rs_routh_t r, slong i, slong len, const long *v)
{
    slong j;
    assert_true(i < r->nrows);
    assert_int_equal(r->rowlen[i], len);
    for (j = 0; j < len; j++)
        assert_true(fmpq_equal_si(r->rows[i] + j, v[j]));
}

/* run the array; check in/on/out, max circle multiplicity and status */
static void run(rs_routh_t r, const fmpz_poly_t p, slong in, slong on,
                slong out, slong maxmult, rs_status_t status)
{
    rs_error_t err;
    rs_error_init(err);
    assert_int_equal(rs_routh_fmpz_poly(r, p, err), RS_OK);
    assert_int_equal(r->count->inside, in);
    assert_int_equal(r->count->on, on);
    assert_int_equal(r->count->outside, out);
    assert_int_equal(rs_rootcount_max_on_mult(r->count), maxmult);
    assert_int_equal(rs_rootcount_status(r->count), status);
}

/* Same closed forms as test_rootcount.c, roots worked out there:
 * {deg, coefficients highest first, in, on, out, at1, atm1, #mult-1 circle
 * roots, #mult-2 circle roots, status}. */

static void test_closed_forms(void **state)
{
    size_t i;
    (void) state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        const closed_case *c = cases + i;
        fmpz_poly_t p;
        rs_routh_t r;
        fmpz_poly_init(p);
        rs_routh_init(r);
        poly_set(p, c->deg, c->c);
        run(r, p, c->in, c->on, c->out, c->mult2 ? 2 : (c->mult1 ? 1 : 0), c->status);
        assert_int_equal(r->count->degree, c->deg);
        assert_int_equal(r->count->at_one, c->at1);
        assert_int_equal(r->count->at_minus_one, c->atm1);
        assert_int_equal(r->count->on_mult[1], c->mult1);
        assert_int_equal(r->count->on_mult[2], c->mult2);
        rs_routh_clear(r);
        fmpz_poly_clear(p);
    }
}

/* Regular arrays by hand.  Backward Euler w = 1: p = 2l^2 - 2l + 1,
 * q = 5z^2 + 2z + 1 (test_bilinear), rows [5 1] [2] [1]: no sign change.
 * Forward Euler w = 1/2: p = 4l^2 - 8l + 5, q = 4(1+z)^2 - 8(1-z^2)
 * + 5(1-z)^2 = 17z^2 - 2z + 1, rows [17 1] [-2] [1]: two sign changes. */
static void test_regular_arrays(void **state)
{
    static const long be[] = {2, -2, 1}, fe[] = {4, -8, 5};
    static const long r0[] = {5, 1}, r1[] = {2}, r2[] = {1};
    static const long f0[] = {17, 1}, f1[] = {-2}, f2[] = {1};
    fmpz_poly_t p;
    rs_routh_t r;
    (void) state;
    fmpz_poly_init(p);
    rs_routh_init(r);
    poly_set(p, 2, be);
    run(r, p, 2, 0, 0, 0, RS_STATUS_STABLE);
    assert_int_equal(r->nrows, 3);
    row_equals(r, 0, 2, r0);
    row_equals(r, 1, 1, r1);
    row_equals(r, 2, 1, r2);
    assert_int_equal(r->nevents, 0);
    assert_int_equal(r->sign_changes, 0);
    poly_set(p, 2, fe);
    run(r, p, 0, 0, 2, 0, RS_STATUS_UNSTABLE);   /* reuse without clear */
    row_equals(r, 0, 2, f0);
    row_equals(r, 1, 1, f1);
    row_equals(r, 2, 1, f2);
    assert_int_equal(r->sign_changes, 2);
    rs_routh_clear(r);
    fmpz_poly_clear(p);
}

/* Degree drop (roots at l = -1) and q(0) = 0 (roots at l = 1).
 * (l+1)(3l-1): q = 2(1+z)... degree 1 < 2, one event of count 1.
 * (l-1)^2 (l+1)^3 (2l-1): l = 1 twice, l = -1 three times, 1/2 inside;
 * from the construction. */
static void test_drop_and_origin(void **state)
{
    static const long a[] = {3, 2, -1};
    fmpz_poly_t p, t;
    rs_routh_t r;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(t);
    rs_routh_init(r);
    poly_set(p, 2, a);
    run(r, p, 1, 1, 0, 1, RS_STATUS_MARGINAL);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_DEGREE_DROP), 1);
    assert_int_equal(r->events[0].count, 1);

    fmpz_poly_set_coeff_si(t, 1, 1);
    fmpz_poly_set_coeff_si(t, 0, -1);
    fmpz_poly_pow(p, t, 2);
    fmpz_poly_set_coeff_si(t, 0, 1);
    fmpz_poly_pow(t, t, 3);
    fmpz_poly_mul(p, p, t);
    fmpz_poly_zero(t);
    fmpz_poly_set_coeff_si(t, 1, 2);
    fmpz_poly_set_coeff_si(t, 0, -1);
    fmpz_poly_mul(p, p, t);
    run(r, p, 1, 5, 0, 3, RS_STATUS_UNSTABLE);
    assert_int_equal(r->count->at_one, 2);
    assert_int_equal(r->count->at_minus_one, 3);
    assert_int_equal(r->count->on_mult[2], 1);
    assert_int_equal(r->count->on_mult[3], 1);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_DEGREE_DROP), 1);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_AT_ORIGIN), 1);
    rs_routh_clear(r);
    fmpz_poly_clear(p);
    fmpz_poly_clear(t);
}

/* Zero first-column entry in a non-zero row.
 * Ogata's epsilon example q = z^4 + z^3 + 2z^2 + 2z + 3: row 2 = [0 3];
 * the epsilon method shows two sign changes, so two roots Re z > 0
 * (K. Ogata, Modern Control Engineering, Routh's stability criterion,
 * special cases).  Nise's Example 6.2, q = z^5 + 2z^4 + 2z^3 + 4z^2 + 11z
 * + 10: zero in row 3 (row index 2 here), two right-half-plane roots
 * (N. Nise, Control Systems Engineering, Sec. 6.3).  Both agree with
 * rs_rootcount_factor. */
static void test_zero_pivot(void **state)
{
    static const long og[] = {1, 1, 2, 2, 3}, ni[] = {1, 2, 2, 4, 11, 10};
    fmpz_poly_t p;
    rs_routh_t r;
    rs_rootcount_t f;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    rs_routh_init(r);
    rs_error_init(err);

    poly_from_q(p, 4, og);
    run(r, p, 2, 0, 2, 0, RS_STATUS_UNSTABLE);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_PIVOT), 1);
    assert_true(fmpq_is_zero(r->rows[2] + 0));
    assert_false(fmpq_is_zero(r->rows[2] + 1));
    assert_int_equal(rs_rootcount_factor(f, p, err), RS_OK);
    assert_true(rs_rootcount_equal(f, r->count));

    poly_from_q(p, 5, ni);
    run(r, p, 3, 0, 2, 0, RS_STATUS_UNSTABLE);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_PIVOT), 1);
    assert_int_equal(rs_rootcount_factor(f, p, err), RS_OK);
    assert_true(rs_rootcount_equal(f, r->count));

    /* zero in row 1: q = z^3 + 0 z^2 + z + 1 -> row 1 = [0 1]; the cubic
     * z^3 + z + 1 has one real root (about -0.68) and a complex pair with
     * positive real part (sum of roots = 0), so 1 inside, 2 outside */
    {
        static const long c[] = {1, 0, 1, 1};
        poly_from_q(p, 3, c);
        run(r, p, 1, 0, 2, 0, RS_STATUS_UNSTABLE);
        assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_PIVOT), 1);
        assert_int_equal(r->events[0].row, 1);
    }
    rs_routh_clear(r);
    fmpz_poly_clear(p);
}

/* Whole zero row.  p = l^3 + l = l (l^2 + 1): q = (1+z)((1+z)^2 + (1-z)^2)
 * = 2(z^3 + z^2 + z + 1), rows [2 2] [2 2], row 2 zero: auxiliary 2z^2 + 2,
 * replaced by its derivative [4], then [2].  Roots 0, +-i. */
static void test_zero_row(void **state)
{
    static const long a[] = {1, 0, 1, 0}, r0[] = {2, 2}, r2[] = {4},
                      r3[] = {2}, b[] = {3, 10, 3};
    fmpz_poly_t p;
    rs_routh_t r;
    (void) state;
    fmpz_poly_init(p);
    rs_routh_init(r);
    poly_set(p, 3, a);
    run(r, p, 1, 2, 0, 1, RS_STATUS_MARGINAL);
    assert_int_equal(r->nrows, 4);
    row_equals(r, 0, 2, r0);
    row_equals(r, 1, 2, r0);
    row_equals(r, 2, 1, r2);
    row_equals(r, 3, 1, r3);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_ROW), 1);
    assert_int_equal(r->events[0].row, 2);
    assert_int_equal(r->events[0].count, 2);

    /* (l + 3)(3l + 1): roots -3, -1/3 map to z = 2, -2: a zero row whose
     * auxiliary polynomial has real roots +-2, nothing on the circle */
    poly_set(p, 2, b);
    run(r, p, 1, 0, 1, 0, RS_STATUS_UNSTABLE);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_ROW), 1);
    rs_routh_clear(r);
    fmpz_poly_clear(p);
}

/* Repeated zero rows: repeated imaginary-axis roots.  All from the
 * construction: l (l^2+1)^2 -> 0 inside, +-i double;
 * (l^2+1)^3 -> +-i triple (three zero rows, the first at row 1);
 * (l^2+1)^2 (l^2-l+1) -> +-i double, e^{+-i pi/3} simple. */
static void test_repeated_zero_rows(void **state)
{
    fmpz_poly_t p, s, t;
    rs_routh_t r;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(s);
    fmpz_poly_init(t);
    rs_routh_init(r);
    fmpz_poly_set_coeff_si(s, 2, 1);
    fmpz_poly_set_coeff_si(s, 0, 1);           /* l^2 + 1 */

    fmpz_poly_pow(p, s, 2);
    fmpz_poly_shift_left(p, p, 1);
    run(r, p, 1, 4, 0, 2, RS_STATUS_UNSTABLE);
    assert_int_equal(r->count->on_mult[2], 2);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_ROW), 2);

    fmpz_poly_pow(p, s, 3);
    run(r, p, 0, 6, 0, 3, RS_STATUS_UNSTABLE);
    assert_int_equal(r->count->on_mult[3], 2);
    assert_int_equal(count_events(r, RS_ROUTH_EVENT_ZERO_ROW), 3);
    assert_int_equal(r->events[0].row, 1);

    fmpz_poly_pow(p, s, 2);
    fmpz_poly_set_coeff_si(t, 2, 1);
    fmpz_poly_set_coeff_si(t, 1, -1);
    fmpz_poly_set_coeff_si(t, 0, 1);
    fmpz_poly_mul(p, p, t);
    run(r, p, 0, 6, 0, 2, RS_STATUS_UNSTABLE);
    assert_int_equal(r->count->on_mult[1], 2);
    assert_int_equal(r->count->on_mult[2], 2);
    assert_true(count_events(r, RS_ROUTH_EVENT_ZERO_ROW) >= 2);
    rs_routh_clear(r);
    fmpz_poly_clear(p);
    fmpz_poly_clear(s);
    fmpz_poly_clear(t);
}

static void test_zero_input(void **state)
{
    fmpz_poly_t p;
    rs_routh_t r;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    rs_routh_init(r);
    rs_error_init(err);
    assert_int_equal(rs_routh_fmpz_poly(r, p, err), RS_ERR_INPUT);
    rs_routh_clear(r);
    fmpz_poly_clear(p);
}

/* ---- symbolic array ------------------------------------------------- */

/* Forward Euler: q = (4+w^2) z^2 - 2w^2 z + w^2 (test_bilinear).
 * Fraction-free rows: [4+w^2, w^2], [-2w^2], [(-2w^2)(w^2) - 0] =
 * [-2w^4] = Delta_1 * r_2 with r_2 = w^2 (textbook row). */
static void test_mpoly_forward_euler(void **state)
{
    const char *vars[] = {"z", "w"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t q, e;
    rs_routh_mpoly_t r;
    rs_error_t err;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(q, ctx);
    fmpz_mpoly_init(e, ctx);
    rs_routh_mpoly_init(r);
    rs_error_init(err);
    fmpz_mpoly_set_str_pretty(q, "(4+w^2)*z^2 - 2*w^2*z + w^2", vars, ctx);
    assert_int_equal(rs_routh_mpoly(r, q, 0, ctx, err), RS_OK);
    assert_int_equal(r->nrows, 3);
    assert_int_equal(r->rowlen[0], 2);
    fmpz_mpoly_set_str_pretty(e, "4+w^2", vars, ctx);
    assert_true(fmpz_mpoly_equal(r->rows[0] + 0, e, ctx));
    fmpz_mpoly_set_str_pretty(e, "w^2", vars, ctx);
    assert_true(fmpz_mpoly_equal(r->rows[0] + 1, e, ctx));
    fmpz_mpoly_set_str_pretty(e, "-2*w^2", vars, ctx);
    assert_true(fmpz_mpoly_equal(r->rows[1] + 0, e, ctx));
    fmpz_mpoly_set_str_pretty(e, "-2*w^4", vars, ctx);
    assert_true(fmpz_mpoly_equal(r->rows[2] + 0, e, ctx));
    rs_routh_mpoly_clear(r, ctx);
    fmpz_mpoly_clear(q, ctx);
    fmpz_mpoly_clear(e, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* Textbook rational Routh rows of a numeric polynomial (coefficients c,
 * highest first), for comparison; returns 0 on a zero pivot. */
static int textbook_routh(fmpq **rows, slong m, const fmpz *c)
{
    slong i, j, len;
    fmpq_t t, u;
    fmpq_init(t);
    fmpq_init(u);
    for (i = 0; i <= m; i++)
        for (j = 0; j < (m - i) / 2 + 1; j++)
            fmpq_zero(rows[i] + j);
    for (j = 0; 2 * j <= m; j++)
        fmpz_set(fmpq_numref(rows[0] + j), c + 2 * j);
    for (j = 0; 2 * j + 1 <= m; j++)
        fmpz_set(fmpq_numref(rows[1] + j), c + 2 * j + 1);
    for (i = 2; i <= m; i++) {
        if (fmpq_is_zero(rows[i - 1] + 0)) {
            fmpq_clear(t);
            fmpq_clear(u);
            return 0;
        }
        len = (m - i) / 2 + 1;
        for (j = 0; j < len; j++) {
            /* r_i[j] = r_{i-2}[j+1] - r_{i-2}[0] r_{i-1}[j+1] / r_{i-1}[0] */
            fmpq_set(t, rows[i - 2] + j + 1);
            if (j + 1 < (m - i + 1) / 2 + 1) {
                fmpq_mul(u, rows[i - 2] + 0, rows[i - 1] + j + 1);
                fmpq_div(u, u, rows[i - 1] + 0);
                fmpq_sub(t, t, u);
            }
            fmpq_set(rows[i] + j, t);
        }
    }
    fmpq_clear(t);
    fmpq_clear(u);
    return 1;
}

/* Generic q of degree 7 in z with random polynomial coefficients in (a, b):
 * the divisions by the pivot of row i-3 must be exact (else the function
 * fails), and at random integer points the fraction-free rows must equal
 * T_0 = r_0, T_1 = r_1, T_i = T_{i-1}[0] r_i with r the textbook rows. */
static void test_mpoly_vs_rational(void **state)
{
    const slong m = 7;
    flint_rand_t st;
    fmpz_mpoly_ctx_t ctx;
    slong it, i, j, pt, checked = 0;
    fmpz_t one;
    (void) state;
    fmpz_init_set_ui(one, 1);
    flint_randinit(st);
    fmpz_mpoly_ctx_init(ctx, 3, ORD_DEGREVLEX);
    for (it = 0; it < 10; it++) {
        fmpz_mpoly_t q, c, zk;
        rs_routh_mpoly_t r;
        rs_error_t err;
        fmpz coef[8];
        fmpq *rows[8];

        fmpz_mpoly_init(q, ctx);
        fmpz_mpoly_init(c, ctx);
        fmpz_mpoly_init(zk, ctx);
        rs_routh_mpoly_init(r);
        rs_error_init(err);
        for (i = 0; i <= m; i++) {
            fmpz_mpoly_randtest_bound(c, st, 3, 4, 2, ctx);
            /* drop z from the coefficient: evaluate z (index 0) at 1 */
            fmpz_mpoly_evaluate_one_fmpz(c, c, 0, one, ctx);
            if (i == 0)   /* c^2 + 1: a leading coefficient never zero */
                fmpz_mpoly_mul(c, c, c, ctx);
            if (i == 0 || fmpz_mpoly_is_zero(c, ctx))
                fmpz_mpoly_add_ui(c, c, 1 + i, ctx);
            fmpz_mpoly_gen(zk, 0, ctx);
            fmpz_mpoly_pow_ui(zk, zk, (ulong) (m - i), ctx);
            fmpz_mpoly_mul(zk, zk, c, ctx);
            fmpz_mpoly_add(q, q, zk, ctx);
        }
        assert_int_equal(rs_routh_mpoly(r, q, 0, ctx, err), RS_OK);
        assert_int_equal(r->nrows, m + 1);

        for (i = 0; i <= m; i++) {
            rows[i] = flint_malloc(((m - i) / 2 + 1) * sizeof(fmpq));
            for (j = 0; j < (m - i) / 2 + 1; j++)
                fmpq_init(rows[i] + j);
            fmpz_init(coef + i);
        }
        for (pt = 0; pt < 5; pt++) {
            fmpz vals[3];
            fmpz *vp[3];
            fmpz_t ev;
            fmpq_t want;
            fmpz_init(ev);
            fmpq_init(want);
            for (i = 0; i < 3; i++) {
                fmpz_init_set_si(vals + i, (slong) n_randint(st, 11) - 5);
                vp[i] = vals + i;
            }
            for (i = 0; i <= m; i++) {
                ulong e = (ulong) (m - i);
                slong var = 0;
                fmpz_mpoly_get_coeff_vars_ui(c, q, &var, &e, 1, ctx);
                fmpz_mpoly_evaluate_all_fmpz(coef + i, c, vp, ctx);
            }
            if (!fmpz_is_zero(coef + 0) && textbook_routh(rows, m, coef)) {
                checked++;
                for (i = 0; i <= m; i++)
                    for (j = 0; j < (m - i) / 2 + 1; j++) {
                        fmpq_set(want, rows[i] + j);
                        if (i >= 2) {
                            fmpz_mpoly_evaluate_all_fmpz(ev, r->rows[i - 1],
                                                         vp, ctx);
                            fmpq_mul_fmpz(want, want, ev);
                        }
                        fmpz_mpoly_evaluate_all_fmpz(ev, r->rows[i] + j, vp, ctx);
                        assert_true(fmpz_is_one(fmpq_denref(want)));
                        assert_true(fmpz_equal(ev, fmpq_numref(want)));
                    }
            }
            for (i = 0; i < 3; i++)
                fmpz_clear(vals + i);
            fmpz_clear(ev);
            fmpq_clear(want);
        }
        for (i = 0; i <= m; i++) {
            for (j = 0; j < (m - i) / 2 + 1; j++)
                fmpq_clear(rows[i] + j);
            flint_free(rows[i]);
            fmpz_clear(coef + i);
        }
        rs_routh_mpoly_clear(r, ctx);
        fmpz_mpoly_clear(q, ctx);
        fmpz_mpoly_clear(c, ctx);
        fmpz_mpoly_clear(zk, ctx);
    }
    assert_true(checked > 10);
    fmpz_clear(one);
    fmpz_mpoly_ctx_clear(ctx);
    flint_randclear(st);
}

/* q = z^3 + w z + 1: row 1 = [0, w] starts with an identically zero pivot */
static void test_mpoly_singular(void **state)
{
    const char *vars[] = {"z", "w"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t q;
    rs_routh_mpoly_t r;
    rs_error_t err;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(q, ctx);
    rs_routh_mpoly_init(r);
    rs_error_init(err);
    fmpz_mpoly_set_str_pretty(q, "z^3 + w*z + 1", vars, ctx);
    assert_int_equal(rs_routh_mpoly(r, q, 0, ctx, err), RS_ERR_MATH);
    assert_int_equal(err->code, RS_ERR_MATH);
    rs_routh_mpoly_clear(r, ctx);
    fmpz_mpoly_clear(q, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* rs_routh_int_count.  Closed form: p = (2 l + 5)(l - 3) prod_{k=1..30}
 * (31 l - k) has the roots k/31 (inside), 3 and -5/2 (outside): 30 in, 2
 * out, and its array is regular (no circle roots, q(0) != 0).  Then the
 * rational generalised array (an independent code path: remainders over Q,
 * Sturm signs) on random polynomials: equal counts wherever the integer
 * array is regular, and a singular one is refused, not miscounted. */
static void test_int_count(void **state)
{
    fmpz_poly_t p, f;
    rs_rootcount_t rc;
    rs_routh_t r;
    rs_error_t err;
    flint_rand_t st;
    slong k, it, regular = 0;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(f);
    rs_error_init(err);
    fmpz_poly_set_coeff_si(p, 0, 5);
    fmpz_poly_set_coeff_si(p, 1, 2);
    fmpz_poly_set_coeff_si(f, 0, -3);
    fmpz_poly_set_coeff_si(f, 1, 1);
    fmpz_poly_mul(p, p, f);
    for (k = 1; k <= 30; k++) {
        fmpz_poly_set_coeff_si(f, 0, -k);
        fmpz_poly_set_coeff_si(f, 1, 31);
        fmpz_poly_mul(p, p, f);
    }
    assert_int_equal(rs_routh_int_count(rc, p, err), RS_OK);
    assert_int_equal(rc->degree, 32);
    assert_int_equal(rc->inside, 30);
    assert_int_equal(rc->outside, 2);
    assert_int_equal(rc->on, 0);
    /* lambda^2 - 1: roots +-1, q(0) = 0 and a degree drop: refused */
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 0, -1);
    fmpz_poly_set_coeff_si(f, 2, 1);
    assert_int_equal(rs_routh_int_count(rc, f, err), RS_ERR_UNDECIDED);
    /* lambda^2 + 1: roots +-i on the circle, a zero row: refused */
    fmpz_poly_set_coeff_si(f, 0, 1);
    assert_int_equal(rs_routh_int_count(rc, f, err), RS_ERR_UNDECIDED);
    flint_randinit(st);
    for (it = 0; it < 200; it++) {
        slong d = 1 + it % 40;
        do
            fmpz_poly_randtest(p, st, d + 1, 3 + it % 6);
        while (fmpz_poly_degree(p) < 1);
        if (rs_routh_int_count(rc, p, err) != RS_OK)
            continue;
        regular++;
        rs_routh_init(r);
        assert_int_equal(rs_routh_fmpz_poly(r, p, err), RS_OK);
        assert_int_equal(r->count->on, 0);
        assert_int_equal(rc->inside, r->count->inside);
        assert_int_equal(rc->outside, r->count->outside);
        rs_routh_clear(r);
    }
    assert_true(regular >= 100);
    flint_randclear(st);
    fmpz_poly_clear(p);
    fmpz_poly_clear(f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_forms),
        cmocka_unit_test(test_regular_arrays),
        cmocka_unit_test(test_drop_and_origin),
        cmocka_unit_test(test_zero_pivot),
        cmocka_unit_test(test_zero_row),
        cmocka_unit_test(test_repeated_zero_rows),
        cmocka_unit_test(test_zero_input),
        cmocka_unit_test(test_mpoly_forward_euler),
        cmocka_unit_test(test_mpoly_vs_rational),
        cmocka_unit_test(test_mpoly_singular),
        cmocka_unit_test(test_int_count),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
