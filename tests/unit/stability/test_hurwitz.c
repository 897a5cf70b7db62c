/* test_hurwitz.c -- cmocka tests for the hurwitz module.
 *
 * Expected values come from independent derivations stated in the comments:
 * hand expansions of small Hurwitz determinants, a Laplace (cofactor)
 * expansion computed here, and certified complex roots from Arb for the
 * numeric equivalence "all Lienard-Chipart conditions hold" <=> "all roots
 * in Re z < 0". */
#include "testutil.h"
#include <stdlib.h>
#include <string.h>
#include <pthread.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpq_mat.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include <fmpz_vec.h>
#include "recstab/hurwitz.h"

/* ------------------------------------------------------------------ */
/* helpers                                                             */

typedef struct {
    fmpz_mpoly_ctx_t ctx;
    const char **vars;
    slong nvars;
} tctx_struct;

static void
tctx_init(tctx_struct *t, const char **vars, slong nvars)
{
    fmpz_mpoly_ctx_init(t->ctx, nvars, ORD_LEX);
    t->vars = vars;
    t->nvars = nvars;
}

static void
tctx_clear(tctx_struct *t)
{
    fmpz_mpoly_ctx_clear(t->ctx);
}

static void
set_str(fmpz_mpoly_t p, const char *s, const tctx_struct *t)
{
    int r = fmpz_mpoly_set_str_pretty(p, s, t->vars, t->ctx);
    assert_int_equal(r, 0);
}

/* assert p == the polynomial written s */
static void
assert_poly_str(const fmpz_mpoly_t p, const char *s, const tctx_struct *t)
{
    fmpz_mpoly_t e;
    int eq;
    fmpz_mpoly_init(e, t->ctx);
    set_str(e, s, t);
    eq = fmpz_mpoly_equal(p, e, t->ctx);
    if (!eq) {
        char *got = fmpz_mpoly_get_str_pretty(p, t->vars, t->ctx);
        print_error("expected %s, got %s\n", s, got);
        flint_free(got);
    }
    fmpz_mpoly_clear(e, t->ctx);
    assert_true(eq);
}

static const rs_hurwitz_cond_struct *
find_cond(const rs_hurwitz_t h, const char *origin)
{
    slong i;
    for (i = 0; i < h->ncond; i++)
        if (strcmp(h->cond[i].origin, origin) == 0)
            return h->cond + i;
    return NULL;
}

/* index of the factor equal to +-s in c, or -1 */
static slong
find_factor(const rs_hurwitz_cond_struct *c, const char *s,
            const tctx_struct *t)
{
    fmpz_mpoly_t e, ne;
    slong i, r = -1;
    fmpz_mpoly_init(e, t->ctx);
    fmpz_mpoly_init(ne, t->ctx);
    set_str(e, s, t);
    fmpz_mpoly_neg(ne, e, t->ctx);
    for (i = 0; i < c->factors->num; i++)
        if (fmpz_mpoly_equal(c->factors->poly + i, e, t->ctx)
            || fmpz_mpoly_equal(c->factors->poly + i, ne, t->ctx))
            r = i;
    fmpz_mpoly_clear(e, t->ctx);
    fmpz_mpoly_clear(ne, t->ctx);
    return r;
}

/* Entry (i, j) (0-based) of the Hurwitz matrix, written independently of the
 * library: row i holds a_{n-1+i}, a_{n-3+i}, ... i.e. index n - 2j - 1 + i. */
static const fmpz_mpoly_struct *
hentry(const fmpz_mpoly_struct *a, slong n, slong i, slong j)
{
    slong idx = n - 2 * j - 1 + i;
    return (idx < 0 || idx > n) ? NULL : a + idx;
}

/* Laplace expansion along the first of the rows rows[0..m-1] restricted to
 * the columns cols[0..m-1]: an independent determinant. */
static void
laplace(fmpz_mpoly_t det, const fmpz_mpoly_struct *a, slong n,
        const slong *rows, const slong *cols, slong m,
        const fmpz_mpoly_ctx_t ctx)
{
    slong c, j, k;
    slong sub[16];
    fmpz_mpoly_t minor, t;

    if (m == 0) {
        fmpz_mpoly_one(det, ctx);
        return;
    }
    fmpz_mpoly_init(minor, ctx);
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_zero(det, ctx);
    for (c = 0; c < m; c++) {
        const fmpz_mpoly_struct *e = hentry(a, n, rows[0], cols[c]);
        if (e == NULL || fmpz_mpoly_is_zero(e, ctx))
            continue;
        for (j = 0, k = 0; j < m; j++)
            if (j != c)
                sub[k++] = cols[j];
        laplace(minor, a, n, rows + 1, sub, m - 1, ctx);
        fmpz_mpoly_mul(t, e, minor, ctx);
        if (c % 2)
            fmpz_mpoly_sub(det, det, t, ctx);
        else
            fmpz_mpoly_add(det, det, t, ctx);
    }
    fmpz_mpoly_clear(minor, ctx);
    fmpz_mpoly_clear(t, ctx);
}

static void
laplace_leading(fmpz_mpoly_t det, const fmpz_mpoly_struct *a, slong n,
                slong k, const fmpz_mpoly_ctx_t ctx)
{
    slong idx[16], i;
    for (i = 0; i < k; i++)
        idx[i] = i;
    laplace(det, a, n, idx, idx, k, ctx);
}

/* All minors of h against the Laplace expansion of its own coefficients. */
static void
check_minors_laplace(const rs_hurwitz_t h, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t d;
    slong k;
    fmpz_mpoly_init(d, ctx);
    for (k = 1; k <= h->n; k++) {
        laplace_leading(d, h->coeffs, h->n, k, ctx);
        assert_true(fmpz_mpoly_equal(d, h->minors + k - 1, ctx));
    }
    /* D_n = a_0 D_{n-1} (last column of H is (0, ..., 0, a_0)) */
    if (h->n >= 2) {
        fmpz_mpoly_mul(d, h->coeffs + 0, h->minors + h->n - 2, ctx);
        assert_true(fmpz_mpoly_equal(d, h->minors + h->n - 1, ctx));
    }
    fmpz_mpoly_clear(d, ctx);
}

/* Specialise the parameters at vals and compare every D_k of h with the
 * determinant of the numeric leading k x k Hurwitz submatrix (fmpz_mat_det,
 * independent of the module). */
static void
check_minors_at(const rs_hurwitz_t h, const slong *vals,
                const fmpz_mpoly_ctx_t ctx)
{
    slong nv = fmpz_mpoly_ctx_nvars(ctx), n = h->n, i, j, k;
    fmpz *v = _fmpz_vec_init(nv);
    fmpz *c = _fmpz_vec_init(n + 1);
    fmpz **vp = flint_malloc(nv * sizeof(fmpz *));
    fmpz_t d, e;
    fmpz_mat_t H;

    fmpz_init(d);
    fmpz_init(e);
    for (i = 0; i < nv; i++) {
        fmpz_set_si(v + i, vals[i]);
        vp[i] = v + i;
    }
    for (i = 0; i <= n; i++)
        assert_true(fmpz_mpoly_evaluate_all_fmpz(c + i, h->coeffs + i, vp,
                                                 ctx));
    for (k = 1; k <= n; k++) {
        fmpz_mat_init(H, k, k);
        for (i = 0; i < k; i++)
            for (j = 0; j < k; j++) {
                slong idx = n - 2 * j - 1 + i;
                if (idx >= 0 && idx <= n)
                    fmpz_set(fmpz_mat_entry(H, i, j), c + idx);
            }
        fmpz_mat_det(d, H);
        assert_true(fmpz_mpoly_evaluate_all_fmpz(e, h->minors + k - 1, vp,
                                                 ctx));
        assert_true(fmpz_equal(d, e));
        fmpz_mat_clear(H);
    }
    fmpz_clear(d);
    fmpz_clear(e);
    flint_free(vp);
    _fmpz_vec_clear(v, nv);
    _fmpz_vec_clear(c, n + 1);
}

static uint64_t rng_state = 0x9e3779b97f4a7c15ULL;

static uint64_t
rng_next(void)
{
    rng_state ^= rng_state << 13;
    rng_state ^= rng_state >> 7;
    rng_state ^= rng_state << 17;
    return rng_state;
}

static slong
rng_range(slong lo, slong hi)
{
    return lo + (slong) (rng_next() % (uint64_t) (hi - lo + 1));
}

/* ------------------------------------------------------------------ */
/* sign test                                                           */

static void
test_sign(void **state)
{
    /* variables: m > 0, k >= 0, w unknown */
    const char *vars[] = {"m", "k", "w"};
    rs_sign_t sign[] = {RS_SIGN_POSITIVE, RS_SIGN_NONNEGATIVE,
                        RS_SIGN_UNKNOWN};
    struct { const char *p; int s; } cases[] = {
        {"3", 1}, {"-2", -1}, {"0", 0},
        {"m", 1}, {"m + 1", 1}, {"k", 0}, {"k + 1", 1}, {"m*k", 0},
        {"m + k", 1}, {"m*k + m", 1}, {"w^2", 0}, {"w^2 + 1", 1},
        {"w^2*m + m", 1}, {"w^2*m", 0}, {"-w^2 - 1", -1}, {"-m - k", -1},
        {"w", 0}, {"w^3 + 1", 0}, {"m - 1", 0}, {"w*m + 1", 0},
        {"k^3 + 2*m^2", 1}, {"-k^2*w^4", 0},
    };
    tctx_struct t;
    fmpz_mpoly_t p;
    size_t i;
    (void) state;

    tctx_init(&t, vars, 3);
    fmpz_mpoly_init(p, t.ctx);
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        set_str(p, cases[i].p, &t);
        if (rs_hurwitz_sign(p, sign, t.ctx) != cases[i].s)
            print_error("sign(%s) != %d\n", cases[i].p, cases[i].s);
        assert_int_equal(rs_hurwitz_sign(p, sign, t.ctx), cases[i].s);
    }
    /* NULL sign array: every variable of unknown sign */
    set_str(p, "m + 1", &t);
    assert_int_equal(rs_hurwitz_sign(p, NULL, t.ctx), 0);
    set_str(p, "m^2 + 1", &t);
    assert_int_equal(rs_hurwitz_sign(p, NULL, t.ctx), 1);
    fmpz_mpoly_clear(p, t.ctx);
    tctx_clear(&t);
}

/* ------------------------------------------------------------------ */
/* symbolic coefficients                                               */

/* q = a2 z^2 + a1 z + a0, z in the middle of the variable list.
 * Hand: H = [[a1, 0], [a2, a0]], D_1 = a1, D_2 = a1 a0.
 * Textbook (a2 > 0): stable iff a1 > 0 and a0 > 0.  LC gives a_2, a_0, D_1. */
static void
test_degree2_symbolic(void **state)
{
    const char *vars[] = {"a0", "a1", "z", "a2"};
    rs_sign_t sign[] = {RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN,
                        RS_SIGN_UNKNOWN};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    slong i;
    (void) state;

    tctx_init(&t, vars, 4);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);
    set_str(q, "a2*z^2 + a1*z + a0", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 2, sign, t.ctx, err), RS_OK);
    assert_int_equal(h->n, 2);
    assert_int_equal(h->negated, 0);
    assert_poly_str(h->coeffs + 0, "a0", &t);
    assert_poly_str(h->coeffs + 1, "a1", &t);
    assert_poly_str(h->coeffs + 2, "a2", &t);
    assert_poly_str(h->minors + 0, "a1", &t);
    assert_poly_str(h->minors + 1, "a1*a0", &t);
    check_minors_laplace(h, t.ctx);

    assert_int_equal(h->ncond, 3);
    assert_string_equal(h->cond[0].origin, "a_2");
    assert_string_equal(h->cond[1].origin, "a_0");
    assert_string_equal(h->cond[2].origin, "D_1");
    assert_poly_str(h->cond[0].reduced, "a2", &t);
    assert_poly_str(h->cond[1].reduced, "a0", &t);
    assert_poly_str(h->cond[2].reduced, "a1", &t);
    for (i = 0; i < h->ncond; i++) {
        assert_int_equal(h->cond[i].trivially_true, 0);
        assert_int_equal(h->cond[i].trivially_false, 0);
        assert_int_equal(h->cond[i].factors->num, 1);
        assert_int_equal(h->cond[i].dropped[0], 0);
        assert_int_equal(h->cond[i].even[0], 0);
    }

    /* all coefficients positive by assumption: every condition holds */
    for (i = 0; i < 4; i++)
        sign[i] = RS_SIGN_POSITIVE;
    assert_int_equal(rs_hurwitz_compute(h, q, 2, sign, t.ctx, err), RS_OK);
    for (i = 0; i < h->ncond; i++) {
        assert_int_equal(h->cond[i].trivially_true, 1);
        assert_int_equal(h->cond[i].dropped[0], 1);
        assert_poly_str(h->cond[i].reduced, "1", &t);
    }

    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* q = a3 z^3 + a2 z^2 + a1 z + a0.  H = [[a2, a0, 0], [a3, a1, 0],
 * [0, a2, a0]].  Hand: D_2 = a2 a1 - a3 a0, D_3 = a0 D_2; the classical
 * cubic criterion is a_i > 0 and a2 a1 > a3 a0.  LC: a_3, a_0, a_2, D_2. */
static void
test_degree3_symbolic(void **state)
{
    const char *vars[] = {"z", "a0", "a1", "a2", "a3"};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    (void) state;

    tctx_init(&t, vars, 5);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);
    set_str(q, "a3*z^3 + a2*z^2 + a1*z + a0", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err), RS_OK);
    assert_int_equal(h->n, 3);
    assert_poly_str(h->minors + 0, "a2", &t);
    assert_poly_str(h->minors + 1, "a2*a1 - a3*a0", &t);
    assert_poly_str(h->minors + 2, "a0*a2*a1 - a3*a0^2", &t);
    check_minors_laplace(h, t.ctx);

    assert_int_equal(h->ncond, 4);
    assert_string_equal(h->cond[0].origin, "a_3");
    assert_string_equal(h->cond[1].origin, "a_0");
    assert_string_equal(h->cond[2].origin, "a_2");
    assert_string_equal(h->cond[3].origin, "D_2");
    assert_poly_str(h->cond[3].poly, "a2*a1 - a3*a0", &t);
    assert_poly_str(h->cond[3].reduced, "a2*a1 - a3*a0", &t);

    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* q = a4 z^4 + ... + a0.  H_3 = [[a3, a1, 0], [a4, a2, a0], [0, a3, a1]].
 * Hand (first row): a3 (a2 a1 - a0 a3) - a1 (a4 a1 - 0) = a3 a2 a1 - a3^2 a0
 * - a4 a1^2.  D_1 = a3, D_2 = a3 a2 - a4 a1.  LC: a_4, a_0, a_2, D_3, D_1. */
static void
test_degree4_symbolic(void **state)
{
    const char *vars[] = {"a0", "a1", "a2", "a3", "a4", "z"};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    (void) state;

    tctx_init(&t, vars, 6);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);
    set_str(q, "a4*z^4 + a3*z^3 + a2*z^2 + a1*z + a0", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 5, NULL, t.ctx, err), RS_OK);
    assert_poly_str(h->minors + 0, "a3", &t);
    assert_poly_str(h->minors + 1, "a3*a2 - a4*a1", &t);
    assert_poly_str(h->minors + 2, "a3*a2*a1 - a3^2*a0 - a4*a1^2", &t);
    check_minors_laplace(h, t.ctx);

    assert_int_equal(h->ncond, 5);
    assert_string_equal(h->cond[0].origin, "a_4");
    assert_string_equal(h->cond[1].origin, "a_0");
    assert_string_equal(h->cond[2].origin, "a_2");
    assert_string_equal(h->cond[3].origin, "D_3");
    assert_string_equal(h->cond[4].origin, "D_1");
    assert_poly_str(h->cond[3].poly, "a3*a2*a1 - a3^2*a0 - a4*a1^2", &t);

    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* Generic symbolic q of degree 1..7, with random subsets of coefficients set
 * to zero (forcing identically-zero pivots), z at a varying position: every
 * minor against the Laplace expansion. */
static void
test_minors_vs_laplace(void **state)
{
    const char *vars[] = {"c0", "c1", "c2", "c3", "c4", "c5", "c6", "c7",
                          "z"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t q, mono, g;
    rs_hurwitz_t h;
    rs_error_t err;
    slong n, trial, i, zvar, nvars = 9;
    (void) state;
    (void) vars;

    rs_error_init(err);
    rs_hurwitz_init(h);
    rng_state = 12345;
    fmpz_mpoly_ctx_init(ctx, nvars, ORD_DEGREVLEX);
    fmpz_mpoly_init(q, ctx);
    fmpz_mpoly_init(mono, ctx);
    fmpz_mpoly_init(g, ctx);
    for (n = 1; n <= 7; n++) {
        for (trial = 0; trial < (n <= 5 ? 12 : 4); trial++) {
            /* z is variable zvar; coefficient a_i is the generator i (or
             * i+1 after zvar) or zero */
            zvar = rng_range(0, nvars - 1 - (8 - n));
            fmpz_mpoly_zero(q, ctx);
            for (i = 0; i <= n; i++) {
                slong v = i < zvar ? i : i + 1;
                if (trial > 0 && i < n && rng_range(0, 2) == 0)
                    continue;                       /* a_i = 0 */
                fmpz_mpoly_gen(mono, v, ctx);
                fmpz_mpoly_gen(g, zvar, ctx);
                fmpz_mpoly_pow_ui(g, g, i, ctx);
                fmpz_mpoly_mul(mono, mono, g, ctx);
                if (rng_range(0, 1))
                    fmpz_mpoly_scalar_mul_si(mono, mono, rng_range(-3, 3) | 1,
                                             ctx);
                fmpz_mpoly_add(q, q, mono, ctx);
            }
            assert_int_equal(rs_hurwitz_compute(h, q, zvar, NULL, ctx, err),
                             RS_OK);
            assert_int_equal(h->n, n);
            check_minors_laplace(h, ctx);
        }
    }
    rs_hurwitz_clear(h, ctx);
    fmpz_mpoly_clear(q, ctx);
    fmpz_mpoly_clear(mono, ctx);
    fmpz_mpoly_clear(g, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* Degree 8..12 with two parameters and random zero coefficients (so that
 * the fraction-free Routh scheme stops early and the pivoting path takes
 * over): every minor at several integer points against fmpz_mat_det. */
static void
test_minors_large_sparse(void **state)
{
    const char *vars[] = {"x", "z", "y"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t q, mono;
    rs_hurwitz_t h;
    rs_error_t err;
    slong n, trial, i, p;
    ulong e[3];
    (void) state;
    (void) vars;

    rs_error_init(err);
    rs_hurwitz_init(h);
    rng_state = 777;
    fmpz_mpoly_ctx_init(ctx, 3, ORD_DEGREVLEX);
    fmpz_mpoly_init(q, ctx);
    fmpz_mpoly_init(mono, ctx);
    for (n = 8; n <= 12; n++) {
        for (trial = 0; trial < 4; trial++) {
            fmpz_mpoly_zero(q, ctx);
            for (i = 0; i <= n; i++) {
                if (i < n && i > 0 && rng_range(0, 3) == 0)
                    continue;
                /* a_i = c1 x^e1 y^f1 + c2 x^e2 y^f2 (small) */
                for (p = 0; p < 2; p++) {
                    fmpz_t c;
                    fmpz_init_set_si(c, rng_range(-3, 3));
                    e[0] = rng_range(0, 1);
                    e[1] = i;
                    e[2] = rng_range(0, 1);
                    fmpz_mpoly_zero(mono, ctx);
                    fmpz_mpoly_set_coeff_fmpz_ui(mono, c, e, ctx);
                    fmpz_mpoly_add(q, q, mono, ctx);
                    fmpz_clear(c);
                }
            }
            if (fmpz_mpoly_degree_si(q, 1, ctx) < 1)
                continue;
            assert_int_equal(rs_hurwitz_compute(h, q, 1, NULL, ctx, err),
                             RS_OK);
            for (p = 0; p < 3; p++) {
                slong vals[3];
                vals[0] = rng_range(-4, 4);
                vals[1] = 0;
                vals[2] = rng_range(-4, 4);
                check_minors_at(h, vals, ctx);
            }
        }
    }
    rs_hurwitz_clear(h, ctx);
    fmpz_mpoly_clear(q, ctx);
    fmpz_mpoly_clear(mono, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* Identically-zero pivots.
 * (a) q = z^4 + b z^2 + d z + c: a_3 = 0 so D_1 = 0.  H_3 = [[0, d, 0],
 *     [1, b, c], [0, 0, d]]; cofactor along row 1: -d (1*d - c*0) = -d^2;
 *     D_2 = 0*b - 1*d = -d; D_4 = c D_3 = -c d^2.
 * (b) q = z^4 + z^3 + x z^2 + x z + c: D_2 = 1*x - 1*x = 0, D_1 = 1,
 *     D_3 = a3 a2 a1 - a3^2 a0 - a4 a1^2 = x^2 - c - x^2 = -c, D_4 = -c^2.
 * (c) q = z^4 + b z^2 + c: rows 1 and 3 of H vanish, every minor is 0. */
static void
test_zero_pivot(void **state)
{
    const char *vars[] = {"b", "z", "c", "d", "x"};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    slong k;
    (void) state;

    tctx_init(&t, vars, 5);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);

    set_str(q, "z^4 + b*z^2 + d*z + c", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 1, NULL, t.ctx, err), RS_OK);
    assert_poly_str(h->minors + 0, "0", &t);
    assert_poly_str(h->minors + 1, "-d", &t);
    assert_poly_str(h->minors + 2, "-d^2", &t);
    assert_poly_str(h->minors + 3, "-c*d^2", &t);
    check_minors_laplace(h, t.ctx);
    /* D_3 = -d^2 > 0 is impossible; D_1 = 0 > 0 too */
    assert_int_equal(find_cond(h, "D_3")->trivially_false, 1);
    assert_int_equal(find_cond(h, "D_1")->trivially_false, 1);
    assert_poly_str(find_cond(h, "D_1")->reduced, "0", &t);
    assert_int_equal(find_cond(h, "D_3")->even[0], 1);
    assert_poly_str(find_cond(h, "D_3")->reduced, "-1", &t);

    set_str(q, "z^4 + z^3 + x*z^2 + x*z + c", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 1, NULL, t.ctx, err), RS_OK);
    assert_poly_str(h->minors + 0, "1", &t);
    assert_poly_str(h->minors + 1, "0", &t);
    assert_poly_str(h->minors + 2, "-c", &t);
    assert_poly_str(h->minors + 3, "-c^2", &t);
    check_minors_laplace(h, t.ctx);

    set_str(q, "z^4 + b*z^2 + c", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 1, NULL, t.ctx, err), RS_OK);
    for (k = 0; k < 4; k++)
        assert_true(fmpz_mpoly_is_zero(h->minors + k, t.ctx));

    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* ------------------------------------------------------------------ */
/* parameters with sign assumptions                                    */

/* q = (m+1) z^3 + 2(m+1) z^2 + w^2 z + k w^2, m > 0, k >= 0, w unknown.
 * a_3 = m+1 > 0, a_2 = 2(m+1) > 0: dropped, trivially true.
 * a_0 = k w^2: k kept (only k >= 0 known), w even (must be non-zero).
 * D_2 = a2 a1 - a3 a0 = 2(m+1) w^2 - (m+1) k w^2 = (m+1) w^2 (2 - k):
 * m+1 dropped, w even, reduced = 2 - k.  So: stable iff k > 0, w != 0,
 * k < 2 -- the expected region. */
static void
test_assumptions(void **state)
{
    const char *vars[] = {"m", "w", "z", "k"};
    rs_sign_t sign[] = {RS_SIGN_POSITIVE, RS_SIGN_UNKNOWN, RS_SIGN_UNKNOWN,
                        RS_SIGN_NONNEGATIVE};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    const rs_hurwitz_cond_struct *c;
    slong i;
    (void) state;

    tctx_init(&t, vars, 4);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);
    set_str(q, "(m+1)*z^3 + 2*(m+1)*z^2 + w^2*z + k*w^2", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 2, sign, t.ctx, err), RS_OK);
    assert_int_equal(h->negated, 0);
    assert_int_equal(h->ncond, 4);

    c = find_cond(h, "a_3");
    assert_non_null(c);
    assert_int_equal(c->trivially_true, 1);
    i = find_factor(c, "m + 1", &t);
    assert_true(i >= 0);
    assert_int_equal(c->dropped[i], 1);

    c = find_cond(h, "a_2");
    assert_int_equal(c->trivially_true, 1);

    c = find_cond(h, "a_0");
    assert_int_equal(c->trivially_true, 0);
    assert_int_equal(c->trivially_false, 0);
    assert_int_equal(c->factors->num, 2);
    i = find_factor(c, "w", &t);
    assert_true(i >= 0);
    assert_int_equal(c->even[i], 1);
    assert_int_equal(c->dropped[i], 0);
    i = find_factor(c, "k", &t);
    assert_true(i >= 0);
    assert_int_equal(c->even[i], 0);
    assert_int_equal(c->dropped[i], 0);
    assert_poly_str(c->reduced, "k", &t);

    c = find_cond(h, "D_2");
    assert_poly_str(c->poly, "(m+1)*w^2*(2-k)", &t);
    assert_int_equal(c->factors->num, 3);
    i = find_factor(c, "m + 1", &t);
    assert_true(i >= 0);
    assert_int_equal(c->dropped[i], 1);
    assert_int_equal(c->even[i], 0);
    i = find_factor(c, "w", &t);
    assert_true(i >= 0);
    assert_int_equal(c->dropped[i], 0);
    assert_int_equal(c->even[i], 1);
    i = find_factor(c, "k - 2", &t);
    assert_true(i >= 0);
    assert_int_equal(c->dropped[i], 0);
    assert_poly_str(c->reduced, "2 - k", &t);
    assert_int_equal(c->trivially_true, 0);
    assert_int_equal(c->trivially_false, 0);

    /* with w > 0 too, the w factors are dropped as well */
    sign[1] = RS_SIGN_POSITIVE;
    assert_int_equal(rs_hurwitz_compute(h, q, 2, sign, t.ctx, err), RS_OK);
    c = find_cond(h, "a_0");
    assert_int_equal(c->dropped[find_factor(c, "w", &t)], 1);
    assert_poly_str(c->reduced, "k", &t);
    c = find_cond(h, "D_2");
    assert_int_equal(c->dropped[find_factor(c, "w", &t)], 1);
    assert_poly_str(c->reduced, "2 - k", &t);

    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* Leading coefficient signs.
 * q = -(m+1) z^2 - z - 1, m > 0: a_2 provably negative, q is negated; then
 *   every condition is trivially true (a_2 = m+1, a_0 = 1, D_1 = 1).
 * q = -w^2 z^2 - 3 z - 2: a_2 = -w^2 < 0 wherever non-zero: negated, the a_2
 *   condition keeps the even factor w (non-zero).
 * q = x z + 1 (x unknown): not negated; conditions a_1: x > 0, a_0: 1 > 0. */
static void
test_leading_sign(void **state)
{
    const char *vars[] = {"z", "m", "w", "x"};
    rs_sign_t sign[] = {RS_SIGN_UNKNOWN, RS_SIGN_POSITIVE, RS_SIGN_UNKNOWN,
                        RS_SIGN_UNKNOWN};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    const rs_hurwitz_cond_struct *c;
    slong i;
    (void) state;

    tctx_init(&t, vars, 4);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);

    set_str(q, "-(m+1)*z^2 - z - 1", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, sign, t.ctx, err), RS_OK);
    assert_int_equal(h->negated, 1);
    assert_poly_str(h->coeffs + 2, "m + 1", &t);
    for (i = 0; i < h->ncond; i++)
        assert_int_equal(h->cond[i].trivially_true, 1);

    set_str(q, "-w^2*z^2 - 3*z - 2", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, sign, t.ctx, err), RS_OK);
    assert_int_equal(h->negated, 1);
    c = find_cond(h, "a_2");
    assert_int_equal(c->trivially_true, 0);
    assert_int_equal(c->trivially_false, 0);
    i = find_factor(c, "w", &t);
    assert_true(i >= 0);
    assert_int_equal(c->even[i], 1);
    assert_poly_str(c->reduced, "1", &t);
    assert_int_equal(find_cond(h, "a_0")->trivially_true, 1);
    assert_int_equal(find_cond(h, "D_1")->trivially_true, 1);

    set_str(q, "x*z + 1", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, sign, t.ctx, err), RS_OK);
    assert_int_equal(h->negated, 0);
    assert_int_equal(h->ncond, 2);
    assert_poly_str(find_cond(h, "a_1")->reduced, "x", &t);
    assert_int_equal(find_cond(h, "a_0")->trivially_true, 1);

    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* Numeric conditions: a negative constant, a zero condition, positive ones.
 * q = z^2 - z + 1: D_1 = -1 -> trivially false, reduced -1.
 * q = z^2 + z: a_0 = 0 -> trivially false, reduced 0 (root at z = 0).
 * q = 2 z^2 + 4 z + 6: all trivially true. */
static void
test_constants(void **state)
{
    const char *vars[] = {"z"};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    slong i;
    (void) state;

    tctx_init(&t, vars, 1);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);

    set_str(q, "z^2 - z + 1", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err), RS_OK);
    assert_int_equal(find_cond(h, "D_1")->trivially_false, 1);
    assert_int_equal(find_cond(h, "D_1")->trivially_true, 0);
    assert_poly_str(find_cond(h, "D_1")->reduced, "-1", &t);
    assert_int_equal(find_cond(h, "a_0")->trivially_true, 1);

    set_str(q, "z^2 + z", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err), RS_OK);
    assert_int_equal(find_cond(h, "a_0")->trivially_false, 1);
    assert_poly_str(find_cond(h, "a_0")->reduced, "0", &t);

    set_str(q, "2*z^2 + 4*z + 6", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err), RS_OK);
    for (i = 0; i < h->ncond; i++) {
        assert_int_equal(h->cond[i].trivially_true, 1);
        assert_int_equal(h->cond[i].trivially_false, 0);
    }

    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

static void
test_errors(void **state)
{
    const char *vars[] = {"z", "x"};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    (void) state;

    tctx_init(&t, vars, 2);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    rs_hurwitz_init(h);

    set_str(q, "z + x", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 2, NULL, t.ctx, err),
                     RS_ERR_INPUT);
    assert_int_equal(err->code, RS_ERR_INPUT);
    assert_int_equal(rs_hurwitz_compute(h, q, -1, NULL, t.ctx, err),
                     RS_ERR_INPUT);
    set_str(q, "x^2 + 1", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err),
                     RS_ERR_INPUT);
    assert_int_equal(h->ncond, 0);
    assert_null(h->coeffs);
    fmpz_mpoly_zero(q, t.ctx);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err),
                     RS_ERR_INPUT);
    /* a valid call after errors, then clear twice */
    set_str(q, "z + x", &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err), RS_OK);
    assert_int_equal(h->ncond, 2);
    rs_hurwitz_clear(h, t.ctx);
    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* ------------------------------------------------------------------ */
/* numeric equivalence with certified roots                            */

/* Exact: 1 if p has a root on the imaginary axis, i.e. Re p(iy) and
 * Im p(iy) have a common real root y (Sturm count of their gcd). */
static int
exact_axis_root(const fmpz_poly_t p)
{
    fmpz_poly_t re, im, g;
    slong i;
    int res;

    fmpz_poly_init(re);
    fmpz_poly_init(im);
    fmpz_poly_init(g);
    for (i = 0; i <= fmpz_poly_degree(p); i++) {
        /* a_i (iy)^i = a_i i^i y^i, i^i = 1, i, -1, -i */
        fmpz_t c;
        fmpz_init_set(c, p->coeffs + i);
        if ((i % 4) >= 2)
            fmpz_neg(c, c);
        if (i % 2 == 0)
            fmpz_poly_set_coeff_fmpz(re, i, c);
        else
            fmpz_poly_set_coeff_fmpz(im, i, c);
        fmpz_clear(c);
    }
    fmpz_poly_gcd(g, re, im);
    /* squarefree part of g (num_real_roots needs it) */
    fmpz_poly_derivative(re, g);
    fmpz_poly_gcd(im, g, re);
    fmpz_poly_div(g, g, im);
    res = fmpz_poly_degree(g) >= 1 && fmpz_poly_num_real_roots(g) > 0;
    fmpz_poly_clear(re);
    fmpz_poly_clear(im);
    fmpz_poly_clear(g);
    return res;
}

/* Certified: 1 if all roots have Re z < 0, 0 if not, -1 if undecided.
 * Roots on the axis are found exactly; the others are decided by Arb's
 * certified root isolation on the squarefree part, with rising precision. */
static int
arb_all_left(const fmpz_poly_t p)
{
    fmpz_poly_t g, d, s;
    acb_ptr roots;
    slong i, deg, prec;
    int res = -1;

    if (exact_axis_root(p))
        return 0;
    fmpz_poly_init(g);
    fmpz_poly_init(d);
    fmpz_poly_init(s);
    fmpz_poly_derivative(d, p);
    fmpz_poly_gcd(g, p, d);
    fmpz_poly_div(s, p, g);          /* squarefree part, same roots */
    deg = fmpz_poly_degree(s);
    roots = _acb_vec_init(deg);
    for (prec = 64; prec <= 4096 && res < 0; prec *= 4) {
        arb_fmpz_poly_complex_roots(roots, s, 0, prec);
        res = 1;
        for (i = 0; i < deg; i++) {
            if (arb_is_positive(acb_realref(roots + i))) {
                res = 0;
                break;
            }
            if (!arb_is_negative(acb_realref(roots + i)))
                res = -1;
        }
    }
    _acb_vec_clear(roots, deg);
    fmpz_poly_clear(g);
    fmpz_poly_clear(d);
    fmpz_poly_clear(s);
    return res;
}

static void
mpoly_from_poly(fmpz_mpoly_t q, const fmpz_poly_t p, const fmpz_mpoly_ctx_t ctx)
{
    slong i;
    fmpz_mpoly_zero(q, ctx);
    for (i = 0; i <= fmpz_poly_degree(p); i++) {
        ulong e = i;
        fmpz_mpoly_set_coeff_fmpz_ui(q, p->coeffs + i, &e, ctx);
    }
}

/* Lienard-Chipart verdict of a numeric polynomial: all conditions are
 * constants, so each one is trivially true or trivially false. */
static int
lc_all_hold(const fmpz_poly_t p, const fmpz_mpoly_ctx_t ctx, int *rh_all)
{
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    slong i;
    int all = 1;

    fmpz_mpoly_init(q, ctx);
    rs_hurwitz_init(h);
    rs_error_init(err);
    mpoly_from_poly(q, p, ctx);
    assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, ctx, err), RS_OK);
    for (i = 0; i < h->ncond; i++) {
        assert_int_equal(h->cond[i].trivially_true,
                         !h->cond[i].trivially_false);
        all &= h->cond[i].trivially_true;
    }
    /* Routh-Hurwitz (a_n > 0 and all D_k > 0) must agree with LC */
    *rh_all = 1;
    for (i = 0; i < h->n; i++)
        if (fmpz_mpoly_is_zero(h->minors + i, ctx)
            || fmpz_sgn(fmpz_mpoly_term_coeff_ref(h->minors + i, 0, ctx)) <= 0)
            *rh_all = 0;
    check_minors_laplace(h, ctx);
    rs_hurwitz_clear(h, ctx);
    fmpz_mpoly_clear(q, ctx);
    return all;
}

static void
random_poly(fmpz_poly_t p, slong n)
{
    slong i, kind = rng_range(0, 2);

    fmpz_poly_zero(p);
    if (kind == 0) {
        /* plain random coefficients, mostly positive */
        for (i = 0; i <= n; i++)
            fmpz_poly_set_coeff_si(p, i, rng_range(-1, 9));
        if (fmpz_is_zero(p->coeffs + 0) && n > 0)
            fmpz_poly_set_coeff_si(p, 0, 1);
        fmpz_poly_set_coeff_si(p, n, rng_range(1, 4) * (rng_range(0, 3) ? 1 : -1));
    } else {
        /* product of linear and quadratic factors, mostly stable ones,
         * sometimes with roots on the imaginary axis or repeated */
        fmpz_poly_t f;
        slong d = 0;
        fmpz_poly_init(f);
        fmpz_poly_one(p);
        while (d < n) {
            fmpz_poly_zero(f);
            if (n - d >= 2 && rng_range(0, 1)) {
                fmpz_poly_set_coeff_si(f, 2, 1);
                fmpz_poly_set_coeff_si(f, 1, rng_range(kind == 1 ? -1 : 0, 4));
                fmpz_poly_set_coeff_si(f, 0, rng_range(kind == 1 ? -1 : 1, 6));
                d += 2;
            } else {
                fmpz_poly_set_coeff_si(f, 1, 1);
                fmpz_poly_set_coeff_si(f, 0, rng_range(kind == 1 ? -2 : 0, 5));
                d += 1;
            }
            fmpz_poly_mul(p, p, f);
        }
        if (rng_range(0, 3) == 0)
            fmpz_poly_neg(p, p);
        fmpz_poly_clear(f);
    }
}

static void
test_numeric_vs_roots(void **state)
{
    const char *vars[] = {"z"};
    tctx_struct t;
    fmpz_poly_t p;
    slong n, trial, stable = 0, unstable = 0, undecided = 0, wrong = 0;
    slong axis = 0;
    (void) state;

    rng_state = 20240601;
    tctx_init(&t, vars, 1);
    fmpz_poly_init(p);
    for (n = 1; n <= 8; n++) {
        for (trial = 0; trial < 150; trial++) {
            int lc, rh, roots;
            random_poly(p, n);
            assert_int_equal(fmpz_poly_degree(p), n);
            lc = lc_all_hold(p, t.ctx, &rh);
            assert_int_equal(lc, rh);
            roots = arb_all_left(p);
            axis += exact_axis_root(p);
            if (roots < 0) {
                undecided++;
                continue;
            }
            if (lc != roots) {
                char *s = fmpz_poly_get_str_pretty(p, "z");
                print_error("LC %d vs roots %d for %s\n", lc, roots, s);
                flint_free(s);
                wrong++;
            }
            if (roots)
                stable++;
            else
                unstable++;
        }
    }
    print_message("numeric: %ld stable, %ld unstable (%ld with axis roots), "
                  "%ld undecided\n", (long) stable, (long) unstable,
                  (long) axis, (long) undecided);
    assert_int_equal(wrong, 0);
    /* the sample must exercise both verdicts */
    assert_true(stable >= 200);
    assert_true(unstable >= 200);
    assert_int_equal(undecided, 0);
    assert_true(axis >= 50);
    fmpz_poly_clear(p);
    tctx_clear(&t);
}

/* Roots exactly on the imaginary axis (Arb cannot decide these; the exact
 * conditions must fail): z (z+2); (z^2+1)(z+1); (z^2+4)(z^2+z+1);
 * (z^2+1)^2 (z+3); z^3 + z. */
static void
test_numeric_axis_roots(void **state)
{
    const char *vars[] = {"z"};
    const char *polys[] = {"z^2 + 2*z", "z^3 + z^2 + z + 1",
                           "z^4 + z^3 + 5*z^2 + 4*z + 4",
                           "(z^2+1)^2*(z+3)", "z^3 + z"};
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t h;
    rs_error_t err;
    size_t j;
    slong i;
    (void) state;

    tctx_init(&t, vars, 1);
    fmpz_mpoly_init(q, t.ctx);
    rs_hurwitz_init(h);
    rs_error_init(err);
    for (j = 0; j < sizeof(polys) / sizeof(polys[0]); j++) {
        int all = 1;
        set_str(q, polys[j], &t);
        assert_int_equal(rs_hurwitz_compute(h, q, 0, NULL, t.ctx, err), RS_OK);
        for (i = 0; i < h->ncond; i++)
            all &= h->cond[i].trivially_true;
        assert_int_equal(all, 0);
    }
    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* A degree-12 symbolic case for speed and consistency: q = product of
 * (z^2 + b z + c) and (z + d) factors; D_12 = a_0 D_11, and every minor
 * specialised at integer points equals the numeric determinant (Laplace of
 * size 12 being too slow). */
static void
test_degree12(void **state)
{
    const char *vars[] = {"b", "c", "d", "z"};
    rs_sign_t sign[] = {RS_SIGN_POSITIVE, RS_SIGN_POSITIVE, RS_SIGN_POSITIVE,
                        RS_SIGN_UNKNOWN};
    tctx_struct t;
    fmpz_mpoly_t q, d;
    rs_hurwitz_t h;
    rs_error_t err;
    (void) state;

    tctx_init(&t, vars, 4);
    fmpz_mpoly_init(q, t.ctx);
    fmpz_mpoly_init(d, t.ctx);
    rs_hurwitz_init(h);
    rs_error_init(err);
    set_str(q, "(z^2 + b*z + c)^3*(z + d)^2*(z^2 + z + 2)*(z^2 + 3*z + 1)",
            &t);
    assert_int_equal(rs_hurwitz_compute(h, q, 3, sign, t.ctx, err), RS_OK);
    assert_int_equal(h->n, 12);
    fmpz_mpoly_mul(d, h->coeffs + 0, h->minors + 10, t.ctx);
    assert_true(fmpz_mpoly_equal(d, h->minors + 11, t.ctx));
    {
        slong vals[][4] = {{1, 2, 3, 0}, {-2, 5, 1, 0}, {3, -1, -4, 0},
                           {0, 0, 7, 0}, {2, 1, 0, 0}};
        slong i;
        for (i = 0; i < 5; i++)
            check_minors_at(h, vals[i], t.ctx);
    }
    /* all coefficients are sums of positive terms: trivially true */
    assert_int_equal(find_cond(h, "a_0")->trivially_true, 1);
    assert_int_equal(find_cond(h, "a_12")->trivially_true, 1);
    /* (z + d)^2 (z^2+bz+c)^3 ... is stable for b, c, d > 0, so D_11 > 0
     * must hold on the whole positive orthant; in particular it is not
     * trivially false */
    assert_int_equal(find_cond(h, "D_11")->trivially_false, 0);
    rs_hurwitz_clear(h, t.ctx);
    fmpz_mpoly_clear(q, t.ctx);
    fmpz_mpoly_clear(d, t.ctx);
    tctx_clear(&t);
}

/* ------------------------------------------------------------------ */
/* the N-mass chain of issue 17                                        */

/* det of the m x m matrix M (row-major) by cofactor expansion along the
 * first row: independent of the module's Routh/Bareiss routes. */
static void
mpoly_det(fmpz_mpoly_t det, const fmpz_mpoly_struct *M, slong m,
          const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_struct *S;
    fmpz_mpoly_t minor, t;
    slong c, i, j, k;

    if (m == 1) {
        fmpz_mpoly_set(det, M, ctx);
        return;
    }
    S = flint_malloc((m - 1) * (m - 1) * sizeof(fmpz_mpoly_struct));
    for (i = 0; i < (m - 1) * (m - 1); i++)
        fmpz_mpoly_init(S + i, ctx);
    fmpz_mpoly_init(minor, ctx);
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_zero(det, ctx);
    for (c = 0; c < m; c++) {
        if (fmpz_mpoly_is_zero(M + c, ctx))
            continue;
        for (i = 1; i < m; i++)
            for (j = 0, k = 0; j < m; j++)
                if (j != c)
                    fmpz_mpoly_set(S + (i - 1) * (m - 1) + k++, M + i * m + j,
                                   ctx);
        mpoly_det(minor, S, m - 1, ctx);
        fmpz_mpoly_mul(t, M + c, minor, ctx);
        if (c % 2)
            fmpz_mpoly_sub(det, det, t, ctx);
        else
            fmpz_mpoly_add(det, det, t, ctx);
    }
    for (i = 0; i < (m - 1) * (m - 1); i++)
        fmpz_mpoly_clear(S + i, ctx);
    flint_free(S);
    fmpz_mpoly_clear(minor, ctx);
    fmpz_mpoly_clear(t, ctx);
}

/* Variables c, k1..kN, z (z last).  The chain of bench/make_chain_case.sh:
 * unit masses, x'' + c x' + K x = 0 with K the stiffness matrix (spring i
 * between masses i-1 and i, mass 0 the wall): K_ii = k_i + k_{i+1} (no
 * k_{N+1}), K_{i,i+1} = K_{i+1,i} = -k_{i+1}.  The trapezoidal rule
 * (lambda - 1) x = (lambda + 1) v / 2, the same for v and a, under
 * lambda = (1+z)/(1-z) gives v = 2z x, a = 2z v (by hand), so
 * q(z) = det(4 z^2 I + 2 c z I + K) up to a constant factor. */
static void
chain_q(fmpz_mpoly_t q, slong N, const tctx_struct *t)
{
    fmpz_mpoly_struct *M = flint_malloc(N * N * sizeof(fmpz_mpoly_struct));
    char buf[128];
    slong i, j;

    for (i = 0; i < N; i++)
        for (j = 0; j < N; j++) {
            fmpz_mpoly_init(M + i * N + j, t->ctx);
            if (i == j && i + 1 < N)
                snprintf(buf, sizeof(buf), "4*z^2 + 2*c*z + k%ld + k%ld",
                         (long) i + 1, (long) i + 2);
            else if (i == j)
                snprintf(buf, sizeof(buf), "4*z^2 + 2*c*z + k%ld",
                         (long) i + 1);
            else if (j == i + 1 || i == j + 1)
                snprintf(buf, sizeof(buf), "-k%ld",
                         (long) (i > j ? i : j) + 1);
            else
                continue;
            set_str(M + i * N + j, buf, t);
        }
    mpoly_det(q, M, N, t->ctx);
    for (i = 0; i < N * N; i++)
        fmpz_mpoly_clear(M + i, t->ctx);
    flint_free(M);
}

/* Exact verdict at a point: the chain is modally decoupled into
 * 4 z^2 + 2 c z + mu for the eigenvalues mu of the symmetric K, whose roots
 * have Re z < 0 iff c > 0 and mu > 0; so stable iff c > 0 and K is positive
 * definite, i.e. (Sylvester) every leading principal minor of K is > 0,
 * computed here with fmpq_mat_det.  Returns 1 stable, 0 not, -1 on the
 * boundary (c = 0 or a minor 0). */
static int
chain_verdict(fmpq *const *vals, slong N)
{
    fmpq_mat_t K;
    fmpq_t d;
    slong i, m;
    int r = 1;

    if (fmpq_sgn(vals[0]) == 0)
        return -1;
    if (fmpq_sgn(vals[0]) < 0)
        r = 0;
    fmpq_init(d);
    for (m = 1; m <= N && r != -1; m++) {
        fmpq_mat_init(K, m, m);
        for (i = 0; i < m; i++) {
            fmpq_set(fmpq_mat_entry(K, i, i), vals[1 + i]);
            if (i + 1 < N)
                fmpq_add(fmpq_mat_entry(K, i, i), fmpq_mat_entry(K, i, i),
                         vals[2 + i]);
            if (i + 1 < m) {
                fmpq_neg(fmpq_mat_entry(K, i, i + 1), vals[2 + i]);
                fmpq_neg(fmpq_mat_entry(K, i + 1, i), vals[2 + i]);
            }
        }
        fmpq_mat_det(d, K);
        if (fmpq_sgn(d) == 0)
            r = -1;
        else if (fmpq_sgn(d) < 0 && r == 1)
            r = 0;
        fmpq_mat_clear(K);
    }
    fmpq_clear(d);
    return r;
}

/* Chains of 2 and 3 masses: every minor against the Laplace expansion (the
 * module's route, Routh rows up to n-1 and D_n = a_0 D_{n-1}, against an
 * independent determinant), and the stated conditions (no sign
 * assumptions: both branches) at random rational points against the
 * exact modal verdict above. */
/* a point of nv rational coordinates, each its own fmpq */
static fmpq **
point_new(slong nv)
{
    fmpq **vals = flint_malloc(nv * sizeof(fmpq *));
    slong i;
    for (i = 0; i < nv; i++) {
        vals[i] = flint_malloc(sizeof(fmpq));
        fmpq_init(vals[i]);
    }
    return vals;
}

static void
point_free(fmpq **vals, slong nv)
{
    slong i;
    for (i = 0; i < nv; i++) {
        fmpq_clear(vals[i]);
        flint_free(vals[i]);
    }
    flint_free(vals);
}

static void
test_chain(void **state)
{
    const char *vars3[] = {"c", "k1", "k2", "k3", "z"};
    const char *vars2[] = {"c", "k1", "k2", "z"};
    slong N;
    (void) state;

    rng_state = 1717;
    for (N = 2; N <= 3; N++) {
        tctx_struct t;
        fmpz_mpoly_t q;
        rs_hurwitz_or_t hb;
        rs_error_t err;
        fmpq **vals;
        slong nv = N + 2, i, trial, agree = 0, stable = 0, b;

        tctx_init(&t, N == 2 ? vars2 : vars3, nv);
        fmpz_mpoly_init(q, t.ctx);
        rs_hurwitz_or_init(hb);
        rs_error_init(err);
        chain_q(q, N, &t);
        assert_int_equal(rs_hurwitz_or_compute(hb, q, nv - 1, 2 * N, NULL,
                                               t.ctx, err), RS_OK);
        for (b = 0; b < hb->nbranch; b++) {
            assert_int_equal(hb->branch[b].n, 2 * N);
            check_minors_laplace(hb->branch + b, t.ctx);
        }
        vals = point_new(nv);
        for (trial = 0; trial < 200; trial++) {
            int want, got;
            /* mostly positive values, some negative (K indefinite or
             * c < 0): both verdicts occur */
            for (i = 0; i + 1 < nv; i++)
                fmpq_set_si(vals[i], rng_range(-3, 12) | 1, rng_range(1, 5));
            want = chain_verdict(vals, N);
            got = rs_hurwitz_or_holds(hb, vals, t.ctx);
            if (want < 0 || got < 0)
                continue;
            assert_int_equal(got, want);
            /* Hurwitz's full criterion at the point (every D_k of the
             * rational matrix, no stated condition used) against the same
             * modal verdict */
            assert_int_equal(rs_hurwitz_or_full_at(hb, vals, t.ctx), want);
            agree++;
            stable += want;
        }
        print_message("N=%ld: %ld points, %ld stable\n", (long) N, (long) agree, (long) stable);
        assert_true(agree >= 150);
        assert_true(stable >= 30 && agree - stable >= 30);
        point_free(vals, nv);
        rs_hurwitz_or_clear(hb, t.ctx);
        fmpz_mpoly_clear(q, t.ctx);
        tctx_clear(&t);
    }
}

/* Chains of 2..4 masses under the case's assumptions c, k_i > 0, where the
 * modal argument above (c > 0 and K positive definite: K is a Jacobi matrix
 * with all leading minors prod k_1.. > 0 for k > 0) makes every chain
 * stable, so every Hurwitz minor is > 0 (Hurwitz's criterion).  The factors
 * dropped as positive (coefficient test, then Polya in positivity.c) must
 * leave conditions that hold at every positive point; for N = 2 every
 * condition is proved, and for N = 3 Polya proves D_3 (a positive-definite
 * quadratic form in c^2, k1, k2, k3 with negative coefficients, which the
 * coefficient test alone cannot). */
static void
test_chain_positive(void **state)
{
    const char *vars4[] = {"c", "k1", "k2", "k3", "k4", "z"};
    slong N;
    (void) state;

    rng_state = 4242;
    for (N = 2; N <= 4; N++) {
        tctx_struct t;
        fmpz_mpoly_t q;
        rs_hurwitz_or_t hb;
        rs_error_t err;
        rs_sign_t sign[6];
        fmpq **vals;
        slong nv = N + 2, i, trial, ntrue = 0;
        const char *vn[6];

        for (i = 0; i + 1 < nv; i++) {
            vn[i] = vars4[i];
            sign[i] = RS_SIGN_POSITIVE;
        }
        vn[nv - 1] = "z";
        sign[nv - 1] = RS_SIGN_UNKNOWN;
        tctx_init(&t, vn, nv);
        fmpz_mpoly_init(q, t.ctx);
        rs_hurwitz_or_init(hb);
        rs_error_init(err);
        chain_q(q, N, &t);
        assert_int_equal(rs_hurwitz_or_compute(hb, q, nv - 1, 2 * N, sign,
                                               t.ctx, err), RS_OK);
        assert_int_equal(hb->nbranch, 1);
        for (i = 0; i < hb->branch[0].ncond; i++) {
            const rs_hurwitz_cond_struct *c = hb->branch[0].cond + i;
            ntrue += c->trivially_true;
            if (N == 3 && strcmp(c->origin, "D_3") == 0)
                assert_true(c->trivially_true);
        }
        print_message("N=%ld: %ld of %ld conditions proved\n", (long) N,
                      (long) ntrue, (long) hb->branch[0].ncond);
        if (N == 2)
            assert_int_equal(ntrue, hb->branch[0].ncond);
        vals = point_new(nv);
        for (trial = 0; trial < 40; trial++) {
            for (i = 0; i + 1 < nv; i++)
                fmpq_set_si(vals[i], rng_range(1, 40), rng_range(1, 7));
            assert_int_equal(chain_verdict(vals, N), 1);
            assert_int_equal(rs_hurwitz_or_holds(hb, vals, t.ctx), 1);
        }
        point_free(vals, nv);
        rs_hurwitz_or_clear(hb, t.ctx);
        fmpz_mpoly_clear(q, t.ctx);
        tctx_clear(&t);
    }
}

/* Issue 17: with a tiny per-row share of the budget the Routh recursion
 * stops after D_1 and the later minors stay "not expanded"; their sign at a
 * rational point then comes from the rational Hurwitz determinant there
 * (rs_hurwitz_minor_sign_at).  Independent check: the fully expanded minors
 * (fraction-free Routh rows over Z[c, k], themselves checked against Laplace
 * expansions in test_chain) evaluated at the same points, for the 3- and
 * 4-mass chains (chain_q), and the verdicts of both conditions sets agree. */
static void
test_chain_not_expanded(void **state)
{
    const char *vars4[] = {"c", "k1", "k2", "k3", "k4", "z"};
    const char *vars3[] = {"c", "k1", "k2", "k3", "z"};
    slong N;
    (void) state;

    rng_state = 4242;
    for (N = 3; N <= 4; N++) {
        tctx_struct t;
        fmpz_mpoly_t q;
        rs_hurwitz_or_t full, part;
        rs_error_t err;
        fmpq **vals;
        slong nv = N + 2, i, k, trial, unexp = 0;
        double old;

        tctx_init(&t, N == 3 ? vars3 : vars4, nv);
        fmpz_mpoly_init(q, t.ctx);
        rs_hurwitz_or_init(full);
        rs_hurwitz_or_init(part);
        rs_error_init(err);
        chain_q(q, N, &t);
        assert_int_equal(rs_hurwitz_or_compute(full, q, nv - 1, 2 * N, NULL,
                                               t.ctx, err), RS_OK);
        old = rs_hurwitz_set_row_seconds(0.0);
        assert_int_equal(rs_hurwitz_or_compute(part, q, nv - 1, 2 * N, NULL,
                                               t.ctx, err), RS_OK);
        {
            /* the strict entry (regions, claims, map boundaries use the minors
             * as polynomials) refuses instead of handing out zero minors */
            rs_hurwitz_t strict;
            rs_error_t e2;
            rs_hurwitz_init(strict);
            rs_error_init(e2);
            assert_int_equal(rs_hurwitz_compute(strict, q, nv - 1, NULL, t.ctx, e2), RS_ERR_LIMIT);
            assert_non_null(strstr(e2->msg, "not expanded"));
            rs_hurwitz_clear(strict, t.ctx);
            rs_error_clear(e2);
        }
        rs_hurwitz_set_row_seconds(old);
        assert_int_equal(full->nbranch, part->nbranch);
        assert_int_equal(full->branch[0].expanded, 2 * N);
        assert_int_equal(part->branch[0].expanded, 1);
        for (i = 0; i < part->branch[0].ncond; i++)
            unexp += part->branch[0].cond[i].not_expanded;
        assert_true(unexp >= N - 1);   /* D_{2N-1}, D_{2N-3}, ..., D_3 */

        vals = point_new(nv);
        for (trial = 0; trial < 40; trial++) {
            for (i = 0; i + 1 < nv; i++)
                fmpq_set_si(vals[i], rng_range(-3, 12) | 1, rng_range(1, 5));
            for (k = 2; k <= 2 * N; k++)
                assert_int_equal(
                    rs_hurwitz_minor_sign_at(part->branch + 0, k, vals, t.ctx),
                    rs_hurwitz_sign_at(full->branch[0].minors + k - 1, vals,
                                       t.ctx));
            assert_int_equal(rs_hurwitz_or_holds(part, vals, t.ctx),
                             rs_hurwitz_or_holds(full, vals, t.ctx));
        }
        point_free(vals, nv);
        rs_hurwitz_or_clear(full, t.ctx);
        rs_hurwitz_or_clear(part, t.ctx);
        rs_error_clear(err);
        fmpz_mpoly_clear(q, t.ctx);
        tctx_clear(&t);
    }
}

/* Issue 17, h-chain11: which minors get expanded is decided by a fixed cost
 * model (term counts, degrees, coefficient sizes), never by the clock.  The
 * 5-mass chain with a row share (0.005 s) that the model's estimates cross
 * part-way (so some minors are expanded and some not) is computed three
 * times: alone, and twice while a second thread of this process burns CPU.
 * clock() counts the CPU time of every thread, so a decision taken from
 * measured CPU time (as the composition's was: the last composition's CPU
 * seconds times the growth) would see every step about twice as dear
 * under the burner; the expanded set, the minors and the conditions must be
 * identical.  Independent check of the expanded minors: equal to those of
 * the run with the default share (every minor, itself checked against
 * fmpz_mat_det in test_chain_routes). */
static volatile int burn_stop;

static void *
burn(void *arg)
{
    volatile double x = 1.0;
    (void) arg;
    while (!burn_stop)
        x = x * 1.0000001 + 1e-9;
    return NULL;
}

/* the chain's minors, alone or while a second thread burns CPU (clock()
 * counts every thread: a timed decision would see each step dearer) */
static void compute_beside_burner(rs_hurwitz_t h, const fmpz_mpoly_t q, slong zv, const fmpz_mpoly_ctx_t ctx,
                                  rs_error_t err, int burner)
{
    pthread_t th;
    rs_hurwitz_init(h);
    burn_stop = 0;
    if (burner) assert_int_equal(pthread_create(&th, NULL, burn, NULL), 0);
    assert_int_equal(rs_hurwitz_compute_partial(h, q, zv, NULL, ctx, err), RS_OK);
    if (burner) {
        burn_stop = 1;
        pthread_join(th, NULL);
    }
}

static void
test_chain_reproducible(void **state)
{
    const char *vars[] = {"c", "k1", "k2", "k3", "k4", "k5", "z"};
    const slong N = 5, nv = 7;
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t full, h[3];
    rs_error_t err;
    slong i, k, run;
    double old;
    (void) state;

    tctx_init(&t, vars, nv);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    chain_q(q, N, &t);
    rs_hurwitz_init(full);
    assert_int_equal(rs_hurwitz_compute_partial(full, q, nv - 1, NULL, t.ctx, err), RS_OK);
    assert_int_equal(full->expanded, 2 * N);
    old = rs_hurwitz_set_row_seconds(0.005);
    for (run = 0; run < 3; run++) {
        compute_beside_burner(h[run], q, nv - 1, t.ctx, err, run > 0);
    }
    rs_hurwitz_set_row_seconds(old);
    /* the share cuts part-way: the test means something */
    assert_true(h[0]->expanded > 2 && h[0]->expanded < 2 * N);
    assert_non_null(strstr(h[0]->stop_note, "over the row share of 0.005 s"));
    for (run = 1; run < 3; run++) {
        assert_int_equal(h[run]->expanded, h[0]->expanded);
        assert_int_equal(h[run]->ncond, h[0]->ncond);
        assert_string_equal(h[run]->limit_note, "");
        /* the step the share stopped, with its (deterministic) estimate */
        assert_string_equal(h[run]->stop_note, h[0]->stop_note);
        for (i = 0; i < h[0]->ncond; i++) {
            assert_int_equal(h[run]->cond[i].not_expanded, h[0]->cond[i].not_expanded);
            assert_int_equal(h[run]->cond[i].factored, h[0]->cond[i].factored);
            assert_true(fmpz_mpoly_equal(h[run]->cond[i].reduced, h[0]->cond[i].reduced, t.ctx));
        }
    }
    for (k = 0; k < h[0]->expanded; k++)
        assert_true(fmpz_mpoly_equal(h[0]->minors + k, full->minors + k, t.ctx));
    for (run = 0; run < 3; run++)
        rs_hurwitz_clear(h[run], t.ctx);
    rs_hurwitz_clear(full, t.ctx);
    rs_error_clear(err);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* Issue 17, h-chain13: the expansion budget bounds the cost model's
 * estimates of all expansion steps together, not each step.  The 5-mass
 * chain under the default budget expands every minor; its model total T
 * (h->expand_estimate, fixed formulas) is the sum of its steps, the last
 * the composition of D_9 (D_10 = a_0 D_9 is a product, not a step).  With
 * the budget just under T every single step still fits (each is well under
 * T) but the sum does not: D_9 (and so D_10) must stay unexpanded, the
 * stop note names the budget, and D_1..D_8 equal the full run's (an
 * independent run, the minors themselves checked in test_chain_routes).
 * Run a second time beside a CPU burner (see test_chain_reproducible): the
 * same.  A row share set alone turns the default budget off (as before the
 * budget existed); a budget set explicitly applies beside the share. */
static void
test_chain_expand_budget(void **state)
{
    const char *vars[] = {"c", "k1", "k2", "k3", "k4", "k5", "z"};
    const slong N = 5, nv = 7;
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t full, h[3];
    rs_error_t err;
    slong k, run;
    double old_e, old_r, T;
    slong e2;
    char want[64];
    (void) state;

    tctx_init(&t, vars, nv);
    fmpz_mpoly_init(q, t.ctx);
    rs_error_init(err);
    chain_q(q, N, &t);
    rs_hurwitz_init(full);
    assert_int_equal(rs_hurwitz_compute_partial(full, q, nv - 1, NULL, t.ctx, err), RS_OK);
    assert_int_equal(full->expanded, 2 * N);
    T = full->expand_estimate;
    assert_true(T > 0.0 && T <= RS_HURWITZ_EXPAND_SECONDS);
    old_e = rs_hurwitz_set_expand_seconds(0.999 * T);
    for (run = 0; run < 2; run++) {
        compute_beside_burner(h[run], q, nv - 1, t.ctx, err, run > 0);
    }
    assert_int_equal(h[0]->expanded, 2 * N - 2);
    assert_true(h[0]->expand_estimate <= 0.999 * T);
    snprintf(want, sizeof(want), "over the expansion budget of %g s", 0.999 * T);
    assert_non_null(strstr(h[0]->stop_note, "the composition of D_9"));
    assert_non_null(strstr(h[0]->stop_note, want));
    assert_int_equal(h[1]->expanded, h[0]->expanded);
    assert_string_equal(h[1]->stop_note, h[0]->stop_note);
    for (k = 0; k < h[0]->expanded; k++) {
        assert_true(fmpz_mpoly_equal(h[0]->minors + k, full->minors + k, t.ctx));
        assert_true(fmpz_mpoly_equal(h[1]->minors + k, full->minors + k, t.ctx));
    }
    /* a share and a budget given: the budget still cuts (every step is
     * under the share of T) */
    old_r = rs_hurwitz_set_row_seconds(T);
    rs_hurwitz_init(h[2]);
    assert_int_equal(rs_hurwitz_compute_partial(h[2], q, nv - 1, NULL, t.ctx, err), RS_OK);
    e2 = h[2]->expanded;
    rs_hurwitz_clear(h[2], t.ctx);
    /* the share alone: the default budget is off, the share (T, over every
     * step) cuts nothing */
    rs_hurwitz_set_expand_seconds(-1.0);
    rs_hurwitz_init(h[2]);
    assert_int_equal(rs_hurwitz_compute_partial(h[2], q, nv - 1, NULL, t.ctx, err), RS_OK);
    rs_hurwitz_set_row_seconds(old_r);
    rs_hurwitz_set_expand_seconds(old_e);
    assert_int_equal(e2, 2 * N - 2);
    assert_int_equal(h[2]->expanded, 2 * N);
    assert_string_equal(h[2]->stop_note, "");
    for (run = 0; run < 3; run++)
        rs_hurwitz_clear(h[run], t.ctx);
    rs_hurwitz_clear(full, t.ctx);
    rs_error_clear(err);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* The substitution route (hurwitz_subst.c, issue 17) against the direct
 * fraction-free Routh route: for the 2-, 3- and 4-mass chains both must give
 * the same polynomials D_1..D_n (the direct route is itself checked against
 * Laplace expansions above); for the 5-mass chain (the direct route takes
 * about 1 s there) every D_k at integer points against fmpz_mat_det of the
 * numeric Hurwitz matrix (check_minors_at). */
static void
test_chain_routes(void **state)
{
    const char *vars[] = {"c", "k1", "k2", "k3", "k4", "k5", "z"};
    slong N;
    (void) state;

    rng_state = 1717;
    for (N = 2; N <= 5; N++) {
        const char *v[8];
        tctx_struct t;
        fmpz_mpoly_t q;
        rs_hurwitz_t hs, hd;
        rs_error_t err;
        slong nv = N + 2, i, k;
        int old;

        for (i = 0; i + 1 < nv; i++)
            v[i] = vars[i];
        v[nv - 1] = "z";
        tctx_init(&t, v, nv);
        fmpz_mpoly_init(q, t.ctx);
        rs_hurwitz_init(hs);
        rs_hurwitz_init(hd);
        rs_error_init(err);
        chain_q(q, N, &t);
        /* the cost estimate takes the route from N = 4 on; forced below */
        old = rs_hurwitz_set_subst(N <= 3 ? 2 : 1);
        assert_int_equal(rs_hurwitz_compute(hs, q, nv - 1, NULL, t.ctx, err), RS_OK);
        rs_hurwitz_set_subst(old);
        assert_int_equal(hs->route, 1);
        assert_int_equal(hs->expanded, 2 * N);
        if (N <= 4) {
            old = rs_hurwitz_set_subst(0);
            assert_int_equal(rs_hurwitz_compute(hd, q, nv - 1, NULL, t.ctx, err), RS_OK);
            rs_hurwitz_set_subst(old);
            assert_int_equal(hd->route, 0);
            for (k = 0; k < 2 * N; k++)
                assert_true(fmpz_mpoly_equal(hs->minors + k, hd->minors + k, t.ctx));
        } else {
            slong vals[8], trial;
            for (trial = 0; trial < 4; trial++) {
                for (i = 0; i < nv; i++)
                    vals[i] = rng_range(-9, 9);
                check_minors_at(hs, vals, t.ctx);
            }
        }
        rs_hurwitz_clear(hs, t.ctx);
        rs_hurwitz_clear(hd, t.ctx);
        rs_error_clear(err);
        fmpz_mpoly_clear(q, t.ctx);
        tctx_clear(&t);
    }
}

/* Budgeted factoring (issue 17): the 4- and 5-mass chains' conditions with
 * FLINT's full factorisation (the default at this size) and with only the
 * cheap steps (rs_hurwitz_set_factor_terms(0): content, monomial factors,
 * trial division by the other conditions' factors, the cofactor "not
 * factored").  Each factorisation multiplies back to its condition exactly;
 * the cheap one flags at least one condition (the D_k with a cofactor of
 * many terms); and at 120 random rational points of mixed signs both sets of
 * conditions give the exact modal verdict of chain_verdict (independent of
 * Hurwitz: c > 0 and K positive definite by Sylvester's minors). */
static void
test_chain_unfactored(void **state)
{
    const char *vars[] = {"c", "k1", "k2", "k3", "k4", "k5", "z"};
    slong N;
    (void) state;

    rng_state = 4242;
    for (N = 4; N <= 5; N++) {
        const char *v[8];
        tctx_struct t;
        fmpz_mpoly_t q, prod, fe;
        rs_hurwitz_or_t hf, hc;
        rs_error_t err;
        fmpq **vals;
        slong nv = N + 2, i, k, b, trial, agree = 0, stable = 0, flagged = 0;
        slong old;

        for (i = 0; i + 1 < nv; i++)
            v[i] = vars[i];
        v[nv - 1] = "z";
        tctx_init(&t, v, nv);
        fmpz_mpoly_init(q, t.ctx);
        fmpz_mpoly_init(prod, t.ctx);
        fmpz_mpoly_init(fe, t.ctx);
        rs_hurwitz_or_init(hf);
        rs_hurwitz_or_init(hc);
        rs_error_init(err);
        chain_q(q, N, &t);
        assert_int_equal(rs_hurwitz_or_compute(hf, q, nv - 1, 2 * N, NULL, t.ctx, err), RS_OK);
        old = rs_hurwitz_set_factor_terms(0);
        assert_int_equal(rs_hurwitz_or_compute(hc, q, nv - 1, 2 * N, NULL, t.ctx, err), RS_OK);
        rs_hurwitz_set_factor_terms(old);
        assert_int_equal(hf->nbranch, hc->nbranch);
        for (b = 0; b < hc->nbranch; b++)
            for (i = 0; i < hc->branch[b].ncond; i++) {
                const rs_hurwitz_cond_struct *cf = hf->branch[b].cond + i;
                const rs_hurwitz_cond_struct *cc = hc->branch[b].cond + i;
                assert_true(cf->factored);
                assert_true(fmpz_mpoly_equal(cf->poly, cc->poly, t.ctx));
                flagged += !cc->factored;
                /* constant * prod factor^exp == poly */
                fmpz_mpoly_set_fmpz(prod, cc->factors->constant, t.ctx);
                for (k = 0; k < cc->factors->num; k++) {
                    fmpz_mpoly_pow_fmpz(fe, cc->factors->poly + k, cc->factors->exp + k, t.ctx);
                    fmpz_mpoly_mul(prod, prod, fe, t.ctx);
                }
                assert_true(fmpz_mpoly_equal(prod, cc->poly, t.ctx));
            }
        assert_true(flagged >= 1);
        vals = point_new(nv);
        for (trial = 0; trial < 120; trial++) {
            int want, gf, gc;
            for (i = 0; i + 1 < nv; i++)
                fmpq_set_si(vals[i], rng_range(-3, 12) | 1, rng_range(1, 5));
            want = chain_verdict(vals, N);
            gf = rs_hurwitz_or_holds(hf, vals, t.ctx);
            gc = rs_hurwitz_or_holds(hc, vals, t.ctx);
            if (want < 0 || gf < 0 || gc < 0)
                continue;
            assert_int_equal(gf, want);
            assert_int_equal(gc, want);
            agree++;
            stable += want;
        }
        print_message("N=%ld: %ld flagged, %ld points, %ld stable\n", (long) N, (long) flagged,
                      (long) agree, (long) stable);
        assert_true(agree >= 90);
        assert_true(stable >= 15 && agree - stable >= 15);
        point_free(vals, nv);
        rs_hurwitz_or_clear(hf, t.ctx);
        rs_hurwitz_or_clear(hc, t.ctx);
        rs_error_clear(err);
        fmpz_mpoly_clear(q, t.ctx);
        fmpz_mpoly_clear(prod, t.ctx);
        fmpz_mpoly_clear(fe, t.ctx);
        tctx_clear(&t);
    }
}

/* The composition back (rs_hurwitz_set_compose, issue 17, h-chain15): the
 * cached Horner of hurwitz_subst.c (default) and FLINT's
 * fmpz_mpoly_compose_fmpz_mpoly give the same minors, term for term, on the
 * 2- to 5-mass chains (every minor, forced onto the substitution route) and
 * on test_subst_rational's q (common denominator 2, a constant basis
 * element).  FLINT's composition is the independent derivation here; the
 * chains' minors are also checked against the direct route and fmpz_mat_det
 * in test_chain_routes. */
static void
test_subst_compose(void **state)
{
    const char *vars[] = {"c", "k1", "k2", "k3", "k4", "k5", "z"};
    const char *rv[] = {"t", "x", "y", "z"};
    slong N, k;
    int old, oldc;
    (void) state;

    for (N = 2; N <= 6; N++) {
        const char *v[8];
        tctx_struct t;
        fmpz_mpoly_t q;
        rs_hurwitz_t hc, hf;
        rs_error_t err;
        slong nv, i;
        char buf[512];

        if (N <= 5) {
            nv = N + 2;
            for (i = 0; i + 1 < nv; i++)
                v[i] = vars[i];
            v[nv - 1] = "z";
            tctx_init(&t, v, nv);
        } else {
            nv = 4;
            tctx_init(&t, rv, nv);
        }
        fmpz_mpoly_init(q, t.ctx);
        if (N <= 5)
            chain_q(q, N, &t);
        else {
            const char *E1 = "(x^2 + x*y + y^2 + x + y)", *E2 = "(x*y^3 + 2*x^3 - y + 7)";
            snprintf(buf, sizeof buf,
                     "4*z^4 + (2*t*%s + 1)*z^3 + (3*%s + t^2*%s + 5)*z^2 + (t*%s)*z + 5*t*%s",
                     E1, E1, E2, E2, E2);
            set_str(q, buf, &t);
        }
        rs_hurwitz_init(hc);
        rs_hurwitz_init(hf);
        rs_error_init(err);
        old = rs_hurwitz_set_subst(2);
        oldc = rs_hurwitz_set_compose(1);
        assert_int_equal(rs_hurwitz_compute(hc, q, nv - 1, NULL, t.ctx, err), RS_OK);
        rs_hurwitz_set_compose(0);
        assert_int_equal(rs_hurwitz_compute(hf, q, nv - 1, NULL, t.ctx, err), RS_OK);
        rs_hurwitz_set_compose(oldc);
        rs_hurwitz_set_subst(old);
        assert_int_equal(hc->route, 1);
        assert_int_equal(hf->route, 1);
        assert_int_equal(hc->expanded, hc->n);
        assert_int_equal(hf->expanded, hf->n);
        for (k = 0; k < hc->n; k++)
            assert_true(fmpz_mpoly_equal(hc->minors + k, hf->minors + k, t.ctx));
        rs_hurwitz_clear(hc, t.ctx);
        rs_hurwitz_clear(hf, t.ctx);
        rs_error_clear(err);
        fmpz_mpoly_clear(q, t.ctx);
        tctx_clear(&t);
    }
}

/* The substitution route on a non-chain q whose coefficients with respect
 * to t are 2 E1, 3 E1 (= 3/2 of the first: common denominator L = 2), the
 * constant 1 (kept as a number) and E2: the route is taken and its minors
 * equal the Laplace expansions of q's own coefficients (check_minors_laplace)
 * and those of the direct route. */
static void
test_subst_rational(void **state)
{
    const char *vars[] = {"t", "x", "y", "z"};
    const char *E1 = "(x^2 + x*y + y^2 + x + y)", *E2 = "(x*y^3 + 2*x^3 - y + 7)";
    char buf[512];
    tctx_struct t;
    fmpz_mpoly_t q;
    rs_hurwitz_t hs, hd;
    rs_error_t err;
    slong k;
    int old;
    (void) state;

    tctx_init(&t, vars, 4);
    fmpz_mpoly_init(q, t.ctx);
    snprintf(buf, sizeof buf,
             "4*z^4 + (2*t*%s + 1)*z^3 + (3*%s + t^2*%s + 5)*z^2 + (t*%s)*z + 5*t*%s",
             E1, E1, E2, E2, E2);
    set_str(q, buf, &t);
    rs_hurwitz_init(hs);
    rs_hurwitz_init(hd);
    rs_error_init(err);
    assert_int_equal(rs_hurwitz_compute(hs, q, 3, NULL, t.ctx, err), RS_OK);
    assert_int_equal(hs->route, 1);
    check_minors_laplace(hs, t.ctx);
    old = rs_hurwitz_set_subst(0);
    assert_int_equal(rs_hurwitz_compute(hd, q, 3, NULL, t.ctx, err), RS_OK);
    rs_hurwitz_set_subst(old);
    assert_int_equal(hd->route, 0);
    for (k = 0; k < 4; k++)
        assert_true(fmpz_mpoly_equal(hs->minors + k, hd->minors + k, t.ctx));
    rs_hurwitz_clear(hs, t.ctx);
    rs_hurwitz_clear(hd, t.ctx);
    rs_error_clear(err);
    fmpz_mpoly_clear(q, t.ctx);
    tctx_clear(&t);
}

/* rs_hurwitz_sign_at decides most points from doubles with a certified error
 * bound and falls back to the exact sum (rs_hurwitz_eval) otherwise: its sign
 * must be the sign of the exact value everywhere.  (1) Random polynomials
 * with coefficients up to 2^300 at random rational points, against
 * fmpq_sgn of rs_hurwitz_eval.  (2) Cancellation the doubles cannot resolve,
 * with the signs by hand: (x - y)^20 at x = y (0), at x = y + 10^-6 (> 0:
 * 10^-120, while its terms are up to C(20,10) (7/3)^20 in size);
 * (x - y)^21 at x = y - 10^-6 (< 0); 10^120 (x - y)^20 - 1 at
 * x - y = 10^-6 (exactly 0); x^2 - 2 y^2 at x = 99 10^300, y = 70 10^300 + 1
 * (10^600 - 280 10^300 - 2 > 0) and y = 70 10^300 + 10^298
 * (10^600 (9801 - 2 70.01^2) = -1.8002 10^600 < 0): beyond the doubles'
 * exponent range. */
static void
test_sign_filter(void **state)
{
    const char *vars[] = {"x", "y", "z"};
    tctx_struct t;
    fmpz_mpoly_t p;
    fmpq_t x, y, z, val;
    fmpq *pt[3];
    flint_rand_t rs;
    slong it, k;
    (void) state;

    tctx_init(&t, vars, 3);
    fmpz_mpoly_init(p, t.ctx);
    fmpq_init(x); fmpq_init(y); fmpq_init(z); fmpq_init(val);
    pt[0] = x; pt[1] = y; pt[2] = z;
    flint_randinit(rs);
    for (it = 0; it < 600; it++) {
        fmpz_mpoly_randtest_bound(p, rs, n_randint(rs, 40) + 1, it % 3 == 0 ? 300 : 40,
                                  n_randint(rs, 12) + 1, t.ctx);
        for (k = 0; k < 3; k++) {
            fmpz_randtest(fmpq_numref(pt[k]), rs, n_randint(rs, 40) + 1);
            fmpz_randtest_not_zero(fmpq_denref(pt[k]), rs, n_randint(rs, 40) + 1);
            fmpz_abs(fmpq_denref(pt[k]), fmpq_denref(pt[k]));
            fmpq_canonicalise(pt[k]);
        }
        rs_hurwitz_eval(val, p, pt, t.ctx);
        assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), fmpq_sgn(val));
    }
    fmpq_set_si(z, 3, 1);
    set_str(p, "(x - y)^20", &t);
    fmpq_set_si(x, 7, 3);
    fmpq_set_si(y, 7, 3);
    assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), 0);
    fmpq_set_str(x, "7000003/3000000", 10);          /* y + 10^-6 */
    assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), 1);
    set_str(p, "(x - y)^21", &t);
    fmpq_set_str(x, "6999997/3000000", 10);          /* y - 10^-6 */
    assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), -1);
    set_str(p, "1000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000*(x - y)^20 - 1", &t);
    fmpq_set_str(x, "7000003/3000000", 10);          /* 10^120 10^-120 - 1 = 0 */
    assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), 0);
    set_str(p, "x^2 - 2*y^2", &t);
    fmpz_set_ui(fmpq_numref(x), 10);
    fmpz_pow_ui(fmpq_numref(x), fmpq_numref(x), 300);
    fmpz_mul_ui(fmpq_numref(y), fmpq_numref(x), 70);
    fmpz_mul_ui(fmpq_numref(x), fmpq_numref(x), 99);
    fmpz_one(fmpq_denref(x));
    fmpz_one(fmpq_denref(y));
    assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), 1);   /* exactly 10^600 */
    fmpz_add_ui(fmpq_numref(y), fmpq_numref(y), 1);
    assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), 1);
    fmpz_set_ui(fmpq_numref(y), 10);
    fmpz_pow_ui(fmpq_numref(y), fmpq_numref(y), 298);
    fmpz_mul_ui(fmpq_numref(y), fmpq_numref(y), 7001);   /* 70 10^300 + 10^298 */
    assert_int_equal(rs_hurwitz_sign_at(p, pt, t.ctx), -1);
    flint_randclear(rs);
    fmpq_clear(x); fmpq_clear(y); fmpq_clear(z); fmpq_clear(val);
    fmpz_mpoly_clear(p, t.ctx);
    tctx_clear(&t);
}

/* issue 17: minors left unexpanded on the substitution route are formed
 * over the small ring by interpolation (h->small); composed back with the
 * definitions and divided by L^k they must equal the minors the full
 * expansion forms by the fraction-free recursion (an independent route). */
static void
test_small_ring(void **state)
{
    const char *vars[] = {"c", "k1", "k2", "k3", "k4", "k5", "z"};
    slong N;
    (void) state;

    for (N = 3; N <= 5; N++) {
        const char *v[8];
        tctx_struct t;
        fmpz_mpoly_t q, P;
        rs_hurwitz_t full, part;
        rs_error_t err;
        slong nv = N + 2, i, k, formed = 0;
        double old;
        int olds;
        fmpz_mpoly_struct **gens;
        fmpz_t Lk;

        for (i = 0; i + 1 < nv; i++)
            v[i] = vars[i];
        v[nv - 1] = "z";
        tctx_init(&t, v, nv);
        fmpz_mpoly_init(q, t.ctx);
        fmpz_mpoly_init(P, t.ctx);
        fmpz_init(Lk);
        rs_hurwitz_init(full);
        rs_hurwitz_init(part);
        rs_error_init(err);
        chain_q(q, N, &t);
        assert_int_equal(rs_hurwitz_compute(full, q, nv - 1, NULL, t.ctx, err), RS_OK);
        olds = rs_hurwitz_set_subst(2);
        old = rs_hurwitz_set_row_seconds(0.0);
        assert_int_equal(rs_hurwitz_compute_partial(part, q, nv - 1, NULL, t.ctx, err), RS_OK);
        rs_hurwitz_set_row_seconds(old);
        rs_hurwitz_set_subst(olds);
        assert_int_equal(part->route, 1);
        assert_true(part->expanded < 2 * N - 1);
        assert_non_null(part->small_ctx);
        gens = flint_malloc(part->small_nvars * sizeof(fmpz_mpoly_struct *));
        for (i = 0; i < part->small_nvars; i++)
            gens[i] = part->small_img + i;
        for (k = part->expanded + 1; k <= 2 * N - 1; k++) {
            assert_false(fmpz_mpoly_is_zero(part->small + k - 1, part->small_ctx));
            assert_int_equal(fmpz_mpoly_compose_fmpz_mpoly(P, part->small + k - 1, gens,
                                                           part->small_ctx, t.ctx), 1);
            fmpz_pow_ui(Lk, part->small_L, k);
            assert_true(fmpz_mpoly_scalar_divides_fmpz(P, P, Lk, t.ctx));
            assert_true(fmpz_mpoly_equal(P, full->minors + k - 1, t.ctx));
            formed++;
        }
        assert_true(formed >= 1);
        flint_free(gens);
        rs_hurwitz_clear(full, t.ctx);
        rs_hurwitz_clear(part, t.ctx);
        fmpz_mpoly_clear(q, t.ctx);
        fmpz_mpoly_clear(P, t.ctx);
        fmpz_clear(Lk);
        rs_error_clear(err);
        tctx_clear(&t);
    }
}

int
main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sign),
        cmocka_unit_test(test_degree2_symbolic),
        cmocka_unit_test(test_degree3_symbolic),
        cmocka_unit_test(test_degree4_symbolic),
        cmocka_unit_test(test_minors_vs_laplace),
        cmocka_unit_test(test_minors_large_sparse),
        cmocka_unit_test(test_zero_pivot),
        cmocka_unit_test(test_assumptions),
        cmocka_unit_test(test_leading_sign),
        cmocka_unit_test(test_constants),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_numeric_vs_roots),
        cmocka_unit_test(test_numeric_axis_roots),
        cmocka_unit_test(test_degree12),
        cmocka_unit_test(test_chain),
        cmocka_unit_test(test_chain_positive),
        cmocka_unit_test(test_chain_not_expanded),
        cmocka_unit_test(test_chain_reproducible),
        cmocka_unit_test(test_chain_expand_budget),
        cmocka_unit_test(test_chain_routes),
        cmocka_unit_test(test_subst_rational),
        cmocka_unit_test(test_subst_compose),
        cmocka_unit_test(test_small_ring),
        cmocka_unit_test(test_chain_unfactored),
        cmocka_unit_test(test_sign_filter),
    };
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup_master();
    return r;
}
