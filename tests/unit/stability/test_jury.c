/* test_jury.c -- exact Schur-Cohn test on p itself. */
#include "testutil.h"
#include "closed_forms.h"
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/jury.h"
#include "recstab/rootcount.h"
#include "recstab/routh.h"


/* Same closed forms as test_rootcount.c (roots worked out there):
 * {deg, coefficients highest first, in, on, out, at1, atm1, #simple circle
 * roots, #double circle roots, status}. */

static void test_closed_forms(void **state)
{
    size_t i;
    (void) state;
    for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
        const closed_case *c = cases + i;
        fmpz_poly_t p;
        rs_jury_t j;
        rs_error_t err;
        fmpz_poly_init(p);
        rs_jury_init(j);
        rs_error_init(err);
        poly_set(p, c->deg, c->c);
        assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
        assert_int_equal(j->count->degree, c->deg);
        assert_int_equal(j->count->inside, c->in);
        assert_int_equal(j->count->on, c->on);
        assert_int_equal(j->count->outside, c->out);
        assert_int_equal(j->count->at_one, c->at1);
        assert_int_equal(j->count->at_minus_one, c->atm1);
        assert_int_equal(j->count->on_mult[1], c->mult1);
        assert_int_equal(j->count->on_mult[2], c->mult2);
        assert_int_equal(rs_rootcount_status(j->count), c->status);
        rs_jury_clear(j);
        fmpz_poly_clear(p);
    }
}

/* Sign convention of the Schur-Cohn matrix, degree 2 (degree 1 is covered
 * by l - 1/2 and l - 2 above): (l - 1/2)^2 = (4l^2 - 4l + 1)/4 gives
 * S = [[15, -12], [-12, 15]], eigenvalues 3 and 27: two positive, two
 * inside.  (l - 1/2)(l - 3) -> 2l^2 - 7l + 3 gives S = [[-5, 7], [7, -5]],
 * eigenvalues 2 and -12: one inside, one outside.  (Hand computation.) */
static void test_sign_convention(void **state)
{
    static const long a[] = {4, -4, 1}, b[] = {2, -7, 3};
    fmpz_poly_t p;
    rs_jury_t j;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    rs_jury_init(j);
    poly_set(p, 2, a);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 2);
    assert_int_equal(j->gcd_degree, 0);
    poly_set(p, 2, b);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 1);
    assert_int_equal(j->count->outside, 1);
    rs_jury_clear(j);
    fmpz_poly_clear(p);
}

/* Classical table by hand.  f0 = 2l - 1: a0 = -1, a1 = 2,
 * f1 = a0 f0 - a1 f0* = -(2l - 1) - 2(2 - l) = -3, primitive -1;
 * delta = -3 < 0, so in(f0) = 1 - in(f1) = 1.
 * f0 = 2l^2 - l (root 0 and 1/2): f0* = 2 - l, f1 = 0 - 2(2 - l) =
 * 2l - 4 -> l - 2; f2 = -2(l - 2) - (1 - 2l) = 3 -> 1; in(f1) = 0 (delta > 0),
 * in(f0) = 2 - 0 = 2 (delta -4 < 0). */
static void test_table(void **state)
{
    static const long a[] = {2, -1}, b[] = {2, -1, 0}, b1[] = {1, -2};
    fmpz_poly_t p, w;
    rs_jury_t j;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(w);
    rs_jury_init(j);
    poly_set(p, 1, a);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->table_regular, 1);
    assert_int_equal(j->nrows, 2);
    assert_true(fmpz_poly_equal(j->rows + 0, p));
    fmpz_poly_set_si(w, -1);
    assert_true(fmpz_poly_equal(j->rows + 1, w));

    poly_set(p, 2, b);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->table_regular, 1);
    assert_int_equal(j->nrows, 3);
    poly_set(w, 1, b1);
    assert_true(fmpz_poly_equal(j->rows + 1, w));
    fmpz_poly_set_si(w, 1);
    assert_true(fmpz_poly_equal(j->rows + 2, w));
    assert_int_equal(j->count->inside, 2);
    rs_jury_clear(j);
    fmpz_poly_clear(p);
    fmpz_poly_clear(w);
}

/* Singular tables.  l^2 + 1: a0 = a2 -> delta = 0 at once; gcd(p, p*) = p.
 * (l - 2)^2 (2l - 1): gcd = (l - 2)(2l - 1) (degree 2), h = l - 2; the
 * construction gives 1 inside, 2 outside.
 * (l^2 + 1)^2 (l - 3)(2l - 1): repeated circle roots plus a non-reciprocal
 * part; +-i double, 1/2 inside, 3 outside (construction). */
static void test_singular(void **state)
{
    static const long a[] = {1, 0, 1}, b[] = {2, -9, 12, -4};
    fmpz_poly_t p, t;
    rs_jury_t j;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(t);
    rs_jury_init(j);
    poly_set(p, 2, a);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->table_regular, 0);
    assert_int_equal(j->gcd_degree, 2);

    poly_set(p, 3, b);          /* (l^2 - 4l + 4)(2l - 1) */
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->gcd_degree, 2);
    assert_int_equal(j->count->inside, 1);
    assert_int_equal(j->count->outside, 2);
    assert_int_equal(j->count->on, 0);

    poly_set(p, 2, a);
    fmpz_poly_pow(p, p, 2);
    fmpz_poly_set_coeff_si(t, 1, 1);
    fmpz_poly_set_coeff_si(t, 0, -3);
    fmpz_poly_mul(p, p, t);
    fmpz_poly_set_coeff_si(t, 1, 2);
    fmpz_poly_set_coeff_si(t, 0, -1);
    fmpz_poly_mul(p, p, t);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 1);
    assert_int_equal(j->count->outside, 1);
    assert_int_equal(j->count->on, 4);
    assert_int_equal(j->count->on_mult[2], 2);
    assert_int_equal(rs_rootcount_status(j->count), RS_STATUS_UNSTABLE);
    rs_jury_clear(j);
    fmpz_poly_clear(p);
    fmpz_poly_clear(t);
}

/* Extreme coefficients (issue 11: 440 s before): 10^1000 l^200 - 1 has all
 * 200 roots of modulus 10^-5; (l^2 + 1)(10^1000 l^198 - 1) adds the circle
 * pair +-i (by hand).  Both are counted by regular Jury tables (of p, and of
 * h = p / gcd(p, p*)) without the Schur-Cohn matrix. */
static void test_extreme_coefficients(void **state)
{
    fmpz_poly_t p, f;
    fmpz_t big;
    rs_jury_t j;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p); fmpz_poly_init(f);
    fmpz_init(big);
    fmpz_set_ui(big, 10);
    fmpz_pow_ui(big, big, 1000);
    rs_jury_init(j);
    rs_error_init(err);
    fmpz_poly_set_coeff_fmpz(p, 200, big);
    fmpz_poly_set_coeff_si(p, 0, -1);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 200);
    assert_int_equal(j->count->on, 0);
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_fmpz(p, 198, big);
    fmpz_poly_set_coeff_si(p, 0, -1);
    fmpz_poly_set_str(f, "3  1 0 1");
    fmpz_poly_mul(p, p, f);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 198);
    assert_int_equal(j->count->on, 2);
    assert_int_equal(j->count->outside, 0);
    rs_jury_clear(j);
    fmpz_poly_clear(p); fmpz_poly_clear(f);
    fmpz_clear(big);
}

static void test_zero_input(void **state)
{
    fmpz_poly_t p;
    rs_jury_t j;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    rs_jury_init(j);
    rs_error_init(err);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_ERR_INPUT);
    rs_jury_clear(j);
    fmpz_poly_clear(p);
}

/* Degree 65-200 (the exact-division table, rows not made primitive above
 * degree 64).  Independent routes: (1) the classical table with every row
 * made primitive, f_{k+1} = prim(f_k(0) f_k - lc(f_k) f_k*), computed here;
 * each stored row must be a positive multiple of it (Rouche needs no more);
 * (2) the count of rs_routh_int_count (Routh on the bilinear transform, a
 * different algorithm on a different polynomial). */
static void test_high_degree_property(void **state)
{
    fmpz_poly_t p, f, fr, t, a, b;
    fmpz_t c;
    flint_rand_t st;
    rs_jury_t j;
    rs_rootcount_t rc;
    rs_error_t err;
    slong it, k, checked = 0;
    (void) state;
    fmpz_poly_init(p); fmpz_poly_init(f); fmpz_poly_init(fr); fmpz_poly_init(t);
    fmpz_poly_init(a); fmpz_poly_init(b);
    fmpz_init(c);
    flint_randinit(st);
    for (it = 0; it < 8; it++) {
        slong d = 65 + (it * 135) / 7;
        do
            fmpz_poly_randtest(p, st, d + 1, 4 + 12 * (it % 3));
        while (fmpz_poly_degree(p) != d || fmpz_is_zero(p->coeffs));
        rs_jury_init(j);
        rs_error_init(err);
        assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
        if (j->table_regular) {
            fmpz_poly_set(f, p);
            for (k = 1; k < j->nrows; k++) {
                slong len = fmpz_poly_length(f);
                fmpz_poly_reverse(fr, f, len);
                fmpz_poly_scalar_mul_fmpz(t, f, f->coeffs + 0);
                fmpz_poly_scalar_submul_fmpz(t, fr, f->coeffs + len - 1);
                fmpz_poly_content(c, t);
                fmpz_poly_scalar_divexact_fmpz(f, t, c);
                fmpz_poly_content(c, j->rows + k);
                assert_true(fmpz_sgn(c) > 0);
                fmpz_poly_scalar_divexact_fmpz(a, j->rows + k, c);
                assert_true(fmpz_poly_equal(a, f));
            }
            assert_int_equal(fmpz_poly_degree(f), 0);
            checked++;
        }
        rs_rootcount_init(rc);
        if (rs_routh_int_count(rc, p, err) == RS_OK) {
            assert_int_equal(rc->inside, j->count->inside);
            assert_int_equal(rc->outside, j->count->outside);
        }
        rs_rootcount_clear(rc);
        rs_jury_clear(j);
    }
    assert_true(checked >= 6);
    /* closed form: (2l - 1)^40 (l - 3)^30, roots 1/2 (x40) inside, 3 (x30)
     * outside, none on the circle */
    fmpz_poly_set_coeff_si(a, 0, -1); fmpz_poly_set_coeff_si(a, 1, 2);
    fmpz_poly_truncate(a, 2);
    fmpz_poly_zero(b);
    fmpz_poly_set_coeff_si(b, 0, -3); fmpz_poly_set_coeff_si(b, 1, 1);
    fmpz_poly_pow(a, a, 40);
    fmpz_poly_pow(b, b, 30);
    fmpz_poly_mul(p, a, b);
    rs_jury_init(j);
    assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 40);
    assert_int_equal(j->count->on, 0);
    assert_int_equal(j->count->outside, 30);
    rs_jury_clear(j);
    flint_randclear(st);
    fmpz_clear(c);
    fmpz_poly_clear(p); fmpz_poly_clear(f); fmpz_poly_clear(fr); fmpz_poly_clear(t);
    fmpz_poly_clear(a); fmpz_poly_clear(b);
}


/* rs_jury_count_fmpz_poly: above degree 64 the minors' signs modulo primes
 * (jury.c).  Property: on random dense polynomials of degree 65-160 and 3-48
 * bit coefficients the count equals the integer table's (rs_jury_fmpz_poly,
 * Rouche on exactly divided rows) and Routh's on the bilinear transform
 * (rs_routh_int_count, another algorithm on another polynomial), and the
 * modular route is the one that ran. */
static void test_count_modular_property(void **state)
{
    fmpz_poly_t p;
    flint_rand_t st;
    rs_jury_t j, jc;
    rs_rootcount_t rc;
    rs_error_t err;
    slong it, modular = 0;
    (void) state;
    fmpz_poly_init(p);
    flint_randinit(st);
    for (it = 0; it < 10; it++) {
        slong d = 65 + (it * 95) / 9;
        do
            fmpz_poly_randtest(p, st, d + 1, 3 + 5 * (it % 10));
        while (fmpz_poly_degree(p) != d || fmpz_is_zero(p->coeffs));
        rs_jury_init(j);
        rs_jury_init(jc);
        rs_error_init(err);
        assert_int_equal(rs_jury_fmpz_poly(j, p, err), RS_OK);
        assert_int_equal(rs_jury_count_fmpz_poly(jc, p, err), RS_OK);
        assert_true(rs_rootcount_equal(j->count, jc->count));
        assert_int_equal(j->table_regular, jc->table_regular);
        if (jc->modular_primes > 0)
            modular++;
        rs_rootcount_init(rc);
        if (rs_routh_int_count(rc, p, err) == RS_OK) {
            assert_int_equal(rc->inside, jc->count->inside);
            assert_int_equal(rc->outside, jc->count->outside);
        }
        rs_rootcount_clear(rc);
        rs_jury_clear(j);
        rs_jury_clear(jc);
    }
    assert_true(modular >= 8);
    flint_randclear(st);
    fmpz_poly_clear(p);
}

/* p = prod (c_i lambda - r_i)^e_i (and cyclotomic factors) counted by
 * construction: a root 1/2 or -1/3 inside, 3 or -2 outside, the roots of
 * Phi_7 (six primitive 7th roots of unity) and of lambda^2 + 1 on the
 * circle.  2 lambda^n - 1 (all n roots of modulus 2^(-1/n)) and
 * lambda^n - 2 (modulus 2^(1/n)): sparse, their table is defective modulo
 * the first prime and the integer table counts them. */
static void test_count_modular_closed_forms(void **state)
{
    fmpz_poly_t p, t;
    rs_jury_t j;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    fmpz_poly_init(t);
    rs_jury_init(j);
    rs_error_init(err);
    /* (2l - 1)^50 (l - 3)^30 (l + 2)^20: 50 in, 50 out, regular */
    fmpz_poly_set_str(p, "2  -1 2");
    fmpz_poly_pow(p, p, 50);
    fmpz_poly_set_str(t, "2  -3 1");
    fmpz_poly_pow(t, t, 30);
    fmpz_poly_mul(p, p, t);
    fmpz_poly_set_str(t, "2  2 1");
    fmpz_poly_pow(t, t, 20);
    fmpz_poly_mul(p, p, t);
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 50);
    assert_int_equal(j->count->on, 0);
    assert_int_equal(j->count->outside, 50);
    assert_true(j->modular_primes > 0);
    assert_int_equal(j->route, RS_JURY_ROUTE_MODULAR);
    /* (3l + 1)^70 Phi_7(l): 70 in, 6 simple on; gcd(p, p*) = Phi_7, the
     * table of p is singular and h = (3l + 1)^70 (degree 70) goes modular */
    fmpz_poly_set_str(p, "2  1 3");
    fmpz_poly_pow(p, p, 70);
    fmpz_poly_set_str(t, "7  1 1 1 1 1 1 1");
    fmpz_poly_mul(p, p, t);
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 70);
    assert_int_equal(j->count->on, 6);
    assert_int_equal(j->count->on_mult[1], 6);
    assert_int_equal(j->count->outside, 0);
    assert_int_equal(j->table_regular, 0);
    assert_int_equal(j->route, RS_JURY_ROUTE_MODULAR);   /* h's table */
    assert_int_equal(j->gcd_degree, 6);
    /* (2l - 1)^40 (l + 2)^30 (l^2 + 1)^2: 40 in, +-i double, 30 out */
    fmpz_poly_set_str(p, "2  -1 2");
    fmpz_poly_pow(p, p, 40);
    fmpz_poly_set_str(t, "2  2 1");
    fmpz_poly_pow(t, t, 30);
    fmpz_poly_mul(p, p, t);
    fmpz_poly_set_str(t, "3  1 0 1");
    fmpz_poly_pow(t, t, 2);
    fmpz_poly_mul(p, p, t);
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 40);
    assert_int_equal(j->count->on, 4);
    assert_int_equal(j->count->on_mult[2], 2);
    assert_int_equal(j->count->outside, 30);
    assert_int_equal(rs_rootcount_status(j->count), RS_STATUS_UNSTABLE);
    /* 2 l^300 - 1: 300 in; l^300 - 2: 300 out; both by the integer table */
    fmpz_poly_zero(p);
    fmpz_poly_set_coeff_si(p, 300, 2);
    fmpz_poly_set_coeff_si(p, 0, -1);
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 300);
    assert_int_equal(j->modular_primes, 0);
    fmpz_poly_set_coeff_si(p, 300, 1);
    fmpz_poly_set_coeff_si(p, 0, -2);
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->outside, 300);
    assert_int_equal(j->modular_primes, 0);
    /* (l - 2) (2l - 1)^80 (l^80 + 2)... kept small: l^1 shift (a root at
     * 0) on a dense regular part: (2l - 1)^45 (l - 3)^30 l^2: 47 in, 30 out */
    fmpz_poly_set_str(p, "2  -1 2");
    fmpz_poly_pow(p, p, 45);
    fmpz_poly_set_str(t, "2  -3 1");
    fmpz_poly_pow(t, t, 30);
    fmpz_poly_mul(p, p, t);
    fmpz_poly_shift_left(p, p, 2);
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 47);
    assert_int_equal(j->count->outside, 30);
    assert_int_equal(j->count->on, 0);
    rs_jury_clear(j);
    fmpz_poly_clear(p);
    fmpz_poly_clear(t);
}

/* The two identities under the modular count (jury.c, proved there from the
 * displacement structure of the Schur-Cohn matrix S): with the divisors
 * 1, 1, F_1(0), F_2(0), ... every division of the table
 *   F_s = (F_{s-1}(0) F_{s-1} - lc(F_{s-1}) F_{s-1}*) / F_{s-3}(0)
 * is exact over Z[a_0, ..., a_n], and F_k(0) = (-1)^k D_k with D_k the
 * leading principal minor of order k of S.  Checked here symbolically, with
 * the a_i independent variables, for n = 2..6 (n = 7 takes 10 s, too slow
 * for the suite).  The D_k come from Bareiss' fraction-free elimination of S
 * (its k-th pivot is D_k by Sylvester's identity; every division checked
 * exact), an algorithm independent of the table. */
static int jury_identities_hold(slong n)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_struct *F, *G, *P, *M;
    fmpz_mpoly_t t, u, piv;
    slong s, i, j, k, l, m;
    int ok = 1;
    fmpz_mpoly_ctx_init(ctx, n + 1, ORD_DEGREVLEX);
    F = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    G = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    P = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    M = flint_malloc(n * n * sizeof(fmpz_mpoly_struct));
    for (i = 0; i <= n; i++) {
        fmpz_mpoly_init(F + i, ctx);
        fmpz_mpoly_init(G + i, ctx);
        fmpz_mpoly_init(P + i, ctx);
        fmpz_mpoly_gen(F + i, i, ctx);           /* a_i */
    }
    for (i = 0; i < n * n; i++)
        fmpz_mpoly_init(M + i, ctx);
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(u, ctx);
    fmpz_mpoly_init(piv, ctx);
    /* S_jk = sum_{l <= min(j,k)} a_{n-j+l} a_{n-k+l} - a_{j-l} a_{k-l} */
    for (j = 0; j < n; j++)
        for (k = 0; k < n; k++)
            for (l = 0; l <= FLINT_MIN(j, k); l++) {
                fmpz_mpoly_mul(t, F + n - j + l, F + n - k + l, ctx);
                fmpz_mpoly_add(M + j * n + k, M + j * n + k, t, ctx);
                fmpz_mpoly_mul(t, F + j - l, F + k - l, ctx);
                fmpz_mpoly_sub(M + j * n + k, M + j * n + k, t, ctx);
            }
    /* the table at nominal degrees m = n - s + 1 -> n - s */
    for (s = 1, m = n; s <= n && ok; s++, m--) {
        for (i = 0; i < m; i++) {
            fmpz_mpoly_mul(t, F + 0, F + i, ctx);
            fmpz_mpoly_mul(u, F + m, F + m - i, ctx);
            fmpz_mpoly_sub(G + i, t, u, ctx);
            if (s >= 3 && !fmpz_mpoly_divides(G + i, G + i, P + s - 3, ctx))
                ok = 0;
        }
        for (i = 0; i < m; i++)
            fmpz_mpoly_swap(F + i, G + i, ctx);
        fmpz_mpoly_zero(F + m, ctx);
        fmpz_mpoly_set(P + s - 1, F + 0, ctx);  /* F_s(0) */
    }
    /* Bareiss on S: pivot k is D_{k+1}; F_{k+1}(0) = (-1)^(k+1) D_{k+1} */
    fmpz_mpoly_one(piv, ctx);
    for (k = 0; k < n && ok; k++) {
        if (k % 2 == 0)
            fmpz_mpoly_neg(t, M + k * n + k, ctx);
        else
            fmpz_mpoly_set(t, M + k * n + k, ctx);
        if (!fmpz_mpoly_equal(t, P + k, ctx))
            ok = 0;
        for (i = k + 1; i < n && ok; i++)
            for (j = k + 1; j < n && ok; j++) {
                fmpz_mpoly_mul(t, M + k * n + k, M + i * n + j, ctx);
                fmpz_mpoly_mul(u, M + i * n + k, M + k * n + j, ctx);
                fmpz_mpoly_sub(t, t, u, ctx);
                if (!fmpz_mpoly_divides(M + i * n + j, t, piv, ctx))
                    ok = 0;
            }
        fmpz_mpoly_set(piv, M + k * n + k, ctx);
    }
    for (i = 0; i <= n; i++) {
        fmpz_mpoly_clear(F + i, ctx);
        fmpz_mpoly_clear(G + i, ctx);
        fmpz_mpoly_clear(P + i, ctx);
    }
    for (i = 0; i < n * n; i++)
        fmpz_mpoly_clear(M + i, ctx);
    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(u, ctx);
    fmpz_mpoly_clear(piv, ctx);
    flint_free(F);
    flint_free(G);
    flint_free(P);
    flint_free(M);
    fmpz_mpoly_ctx_clear(ctx);
    return ok;
}

static void test_count_identities_symbolic(void **state)
{
    slong n;
    (void) state;
    for (n = 2; n <= 6; n++)
        assert_true(jury_identities_hold(n));
}

/* Which route counted (rs_jury_t.route, reported as "schur_cohn_route"):
 * lambda^2 + 3 lambda - 1 (roots (-3 +- sqrt 13) / 2: 0.30 inside, -3.30
 * outside) has a singular table (|a_0| = |a_2|) and gcd(p, p*) = 1 (p + p*
 * = 6 lambda shares no root with p): the Schur-Cohn matrix counts;
 * lambda^2 + 1 (+-i) leaves nothing off gcd(p, p*) = p. */
static void test_count_routes(void **state)
{
    fmpz_poly_t p;
    rs_jury_t j;
    rs_error_t err;
    (void) state;
    fmpz_poly_init(p);
    rs_jury_init(j);
    rs_error_init(err);
    fmpz_poly_set_str(p, "3  -1 3 1");
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 1);
    assert_int_equal(j->count->outside, 1);
    assert_int_equal(j->route, RS_JURY_ROUTE_MATRIX);
    assert_int_equal(j->gcd_degree, 0);
    fmpz_poly_set_str(p, "3  1 0 1");
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->on, 2);
    assert_int_equal(j->route, RS_JURY_ROUTE_GCD);
    assert_int_equal(j->gcd_degree, 2);
    /* 2 lambda - 1 (regular, degree 1 < 33): the integer table */
    fmpz_poly_set_str(p, "2  -1 2");
    assert_int_equal(rs_jury_count_fmpz_poly(j, p, err), RS_OK);
    assert_int_equal(j->count->inside, 1);
    assert_int_equal(j->route, RS_JURY_ROUTE_TABLE);
    rs_jury_clear(j);
    fmpz_poly_clear(p);
}

/* rs_jury_all_inside against planted roots: products of k x - m (root m/k)
 * and k x^2 + m (roots of modulus sqrt|m/k|), all inside iff every |m| < |k|
 * (by construction, not from another Schur-Cohn route); plus hand cases:
 * x^2 + 1 (on the circle), 2 x - 1 inside, x - 2 outside, x^3 (roots at 0) */
static void test_all_inside(void **state)
{
    flint_rand_t st;
    fmpz_poly_t p, f;
    slong t, i;
    (void) state;
    flint_randinit(st);
    fmpz_poly_init(p);
    fmpz_poly_init(f);
    fmpz_poly_set_str(p, "3  1 0 1");
    assert_false(rs_jury_all_inside(p->coeffs, 2));
    fmpz_poly_set_str(p, "2  -1 2");
    assert_true(rs_jury_all_inside(p->coeffs, 1));
    fmpz_poly_set_str(p, "2  -2 1");
    assert_false(rs_jury_all_inside(p->coeffs, 1));
    fmpz_poly_set_str(p, "4  0 0 0 1");
    assert_true(rs_jury_all_inside(p->coeffs, 3));
    for (t = 0; t < 400; t++) {
        int want = 1;
        fmpz_poly_one(p);
        for (i = 0; i < 1 + (slong) n_randint(st, 6); i++) {
            slong k = 1 + (slong) n_randint(st, 9), m = (slong) n_randint(st, 19) - 9;
            if (n_randint(st, 8) == 0) m = k;      /* on the circle now and then */
            want &= FLINT_ABS(m) < k;
            fmpz_poly_zero(f);
            if (n_randint(st, 2)) {
                fmpz_poly_set_coeff_si(f, 1, k);
                fmpz_poly_set_coeff_si(f, 0, -m);
            } else {
                fmpz_poly_set_coeff_si(f, 2, k);
                fmpz_poly_set_coeff_si(f, 0, m);
            }
            fmpz_poly_mul(p, p, f);
        }
        assert_int_equal(rs_jury_all_inside(p->coeffs, fmpz_poly_degree(p)), want);
    }
    fmpz_poly_clear(p);
    fmpz_poly_clear(f);
    flint_randclear(st);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_forms),
        cmocka_unit_test(test_sign_convention),
        cmocka_unit_test(test_table),
        cmocka_unit_test(test_singular),
        cmocka_unit_test(test_extreme_coefficients),
        cmocka_unit_test(test_zero_input),
        cmocka_unit_test(test_high_degree_property),
        cmocka_unit_test(test_count_modular_property),
        cmocka_unit_test(test_count_modular_closed_forms),
        cmocka_unit_test(test_count_identities_symbolic),
        cmocka_unit_test(test_count_routes),
        cmocka_unit_test(test_all_inside),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
