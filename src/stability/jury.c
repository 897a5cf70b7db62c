/* jury.c -- see include/recstab/jury.h
 *
 * p = lambda^z p0 with p0(0) != 0; the z roots at 0 are inside.
 * g = gcd(p0, p0*) holds every circle root of p0 with its full multiplicity
 * (for |r| = 1, r is a root of p0* exactly as often as conj(r) is a root of
 * p0) and, for each pair (r, 1/conj r), the smaller multiplicity of the two,
 * so h = p0 / g keeps only one side of each pair: gcd(h, h*) = 1.
 *
 * Schur-Cohn matrix of h = sum a_k lambda^k (degree d):
 *   S_jk = sum_{l=0}^{min(j,k)} (a_{d-j+l} a_{d-k+l} - a_{j-l} a_{k-l}),
 * non-singular iff gcd(h, h*) = 1; its number of positive eigenvalues is
 * the number of roots inside (d = 1: S = a_1^2 - a_0^2 > 0 iff |root| < 1).
 *
 * Classical table: f_{k+1} = a_0 f_k - a_n f_k* (degree drops), made
 * primitive.  delta_k = f_{k+1}(0) = a_0^2 - a_n^2; when every delta_k != 0,
 * Rouche on the circle gives in(f_k) = in(f_{k+1}) if delta_k > 0 and
 * deg f_k - in(f_{k+1}) if delta_k < 0.  That count is cross-checked. */
#include <string.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_poly_factor.h>
#include <fmpz.h>
#include <fmpz_vec.h>
#include "recstab/budget.h"
#include "recstab/jury.h"

void rs_jury_init(rs_jury_t j)
{
    memset(j, 0, sizeof(rs_jury_struct));
    rs_rootcount_init(j->count);
}

void rs_jury_clear(rs_jury_t j)
{
    slong i;
    for (i = 0; i < j->nrows; i++)
        fmpz_poly_clear(j->rows + i);
    flint_free(j->rows);
    rs_rootcount_clear(j->count);
    memset(j, 0, sizeof(rs_jury_struct));
}

static void jury_push_row(rs_jury_t j, const fmpz_poly_t f)
{
    j->rows = flint_realloc(j->rows, (j->nrows + 1) * sizeof(fmpz_poly_struct));
    fmpz_poly_init(j->rows + j->nrows);
    fmpz_poly_set(j->rows + j->nrows, f);
    j->nrows++;
}

/* Classical table; returns 1 and sets *inside when regular, else 0 (rows
 * are dropped then, since a singular table explains nothing).
 *
 * Rouche only needs each row up to a positive factor.  The unreduced rows
 * F_{k+1} = F_k(0) F_k - lc(F_k) F_k* grow like 2^k; as in Bareiss'
 * elimination F_{k+1} is divisible by F_{k-1}(0) (k >= 2; Sylvester's
 * identity on the Schur-Cohn determinants), which keeps the entries at the
 * size of those determinants without taking a gcd per coefficient (the
 * contents cost most of the 20 s at degree 500 with 60-bit coefficients).
 * The division is checked, not assumed: a remainder (a defective step, where
 * the degree drops by more than one) falls back to the content. */
static int jury_table(rs_jury_t j, const fmpz_poly_t p, slong *inside)
{
    fmpz_poly_t f, fr, t;
    fmpz_t c, prev, r;
    slong k, in;
    int regular = 1;
    slong steps = 0;

    fmpz_poly_init(f);
    fmpz_poly_init(fr);
    fmpz_poly_init(t);
    fmpz_init(c);
    fmpz_init(prev);
    fmpz_init(r);
    fmpz_poly_set(f, p);
    jury_push_row(j, f);
    while (fmpz_poly_degree(f) > 0) {
        slong len = fmpz_poly_length(f), i;
        int exact = steps >= 2 && !fmpz_is_zero(prev) && !fmpz_is_pm1(prev);
        fmpz_poly_reverse(fr, f, len);
        fmpz_poly_scalar_mul_fmpz(t, f, f->coeffs + 0);
        fmpz_poly_scalar_submul_fmpz(t, fr, f->coeffs + len - 1);
        if (fmpz_poly_is_zero(t) || fmpz_is_zero(t->coeffs + 0)) {
            regular = 0;
            break;
        }
        /* the divisor of the next step is this row's constant term */
        fmpz_abs(c, f->coeffs + 0);
        if (exact) {
            slong tl = fmpz_poly_length(t);
            fmpz_poly_fit_length(f, tl);
            for (i = 0; exact && i < tl; i++) {
                fmpz_fdiv_qr(f->coeffs + i, r, t->coeffs + i, prev);
                exact = fmpz_is_zero(r);
            }
            for (i = tl; i < fmpz_poly_length(f); i++)
                fmpz_zero(f->coeffs + i);
            _fmpz_poly_set_length(f, tl);
        }
        if (!exact) {
            fmpz_poly_content(r, t);
            fmpz_abs(r, r);
            fmpz_poly_scalar_divexact_fmpz(f, t, r);
        }
        fmpz_swap(prev, c);
        steps++;
        jury_push_row(j, f);
        /* the reported row is primitive (the recursion keeps f as is) up to
         * degree 64; above, the gcds would cost as much as the table
         * (21 s against 15 s at degree 500) for rows nobody reads */
        if (fmpz_poly_degree(p) <= 64)
            fmpz_poly_content(r, f);
        else
            fmpz_one(r);
        if (!fmpz_is_pm1(r)) {
            fmpz_abs(r, r);
            fmpz_poly_scalar_divexact_fmpz(j->rows + j->nrows - 1, f, r);
        }
    }
    if (regular) {
        /* bottom-up: the last row is a non-zero constant, no roots */
        in = 0;
        for (k = j->nrows - 2; k >= 0; k--) {
            if (fmpz_sgn(j->rows[k + 1].coeffs + 0) < 0)
                in = fmpz_poly_degree(j->rows + k) - in;
        }
        *inside = in;
    } else {
        for (k = 0; k < j->nrows; k++)
            fmpz_poly_clear(j->rows + k);
        flint_free(j->rows);
        j->rows = NULL;
        j->nrows = 0;
    }
    fmpz_poly_clear(f);
    fmpz_poly_clear(fr);
    fmpz_poly_clear(t);
    fmpz_clear(c);
    fmpz_clear(prev);
    fmpz_clear(r);
    return regular;
}

/* multiplicity of the root `root` (= +-1) of g; g is divided by it */
static slong jury_remove_unit_root(fmpz_poly_t g, slong root)
{
    fmpz_poly_t lin, qt;
    slong mult = 0;

    fmpz_poly_init(lin);
    fmpz_poly_init(qt);
    fmpz_poly_set_coeff_si(lin, 0, -root);
    fmpz_poly_set_coeff_si(lin, 1, 1);
    while (fmpz_poly_degree(g) > 0 && fmpz_poly_divides(qt, g, lin)) {
        fmpz_poly_swap(g, qt);
        mult++;
    }
    fmpz_poly_clear(lin);
    fmpz_poly_clear(qt);
    return mult;
}

/* roots of g = gcd(p0, p0*): circle roots exactly, the rest split evenly */
static int jury_count_gcd(rs_rootcount_t rc, fmpz_poly_t g, rs_error_t err)
{
    slong a, b, i, deg, circle = 0;
    fmpz_poly_t F;
    fmpz_poly_factor_t fac;

    a = jury_remove_unit_root(g, 1);
    b = jury_remove_unit_root(g, -1);
    rc->at_one = a;
    rc->at_minus_one = b;
    rs_rootcount_add_on(rc, a, 1);
    rs_rootcount_add_on(rc, b, 1);
    deg = fmpz_poly_degree(g);
    if (deg <= 0)
        return RS_OK;
    /* g is self-reciprocal up to sign; without the roots +-1 it is
     * palindromic of even degree */
    if (fmpz_sgn(g->coeffs + deg) < 0)
        fmpz_poly_neg(g, g);
    for (i = 0; i <= deg; i++)
        if (deg % 2 != 0 || !fmpz_equal(g->coeffs + i, g->coeffs + deg - i))
            return rs_error_set(err, RS_ERR_INTERNAL,
                                "gcd(p, p*) without +-1 is not palindromic");

    fmpz_poly_init(F);
    fmpz_poly_factor_init(fac);
    rs_rootcount_reciprocal_to_x(F, g);
    /* a root x of F of multiplicity e in (-2, 2) is a conjugate pair of
     * circle roots of multiplicity e (x = +-2 excluded: g(+-1) != 0) */
    fmpz_poly_factor_squarefree(fac, F);
    for (i = 0; i < fac->num; i++) {
        slong k = rs_rootcount_real_roots_open(fac->p + i, -2, 2);
        rs_rootcount_add_on(rc, fac->exp[i], 2 * k);
        circle += 2 * k * fac->exp[i];
    }
    rc->inside += (deg - circle) / 2;
    rc->outside += (deg - circle) / 2;
    fmpz_poly_factor_clear(fac);
    fmpz_poly_clear(F);
    return RS_OK;
}

/* inertia of the Schur-Cohn matrix of h (gcd(h, h*) = 1) */
static int jury_count_schur_cohn(rs_rootcount_t rc, const fmpz_poly_t h,
                                 rs_error_t err)
{
    slong d = fmpz_poly_degree(h), i, k, l, var = 0;
    const fmpz *a = h->coeffs;
    fmpz_mat_t S;
    fmpz_poly_t cp;
    int last = 0;

    if (d <= 0)
        return RS_OK;
    {
        /* fmpz_mat_charpoly (multimodular, not interruptible) costs about
         * d^4 B / 64 word operations for entries of B bits; 1 ns each is
         * below the measured 2.6 ns (lambda^200 - 10^-1000: 440 s) */
        double B = 2.0 * (double) FLINT_ABS(_fmpz_vec_max_bits(a, d + 1)) + (double) FLINT_BIT_COUNT(d) + 1.0;
        double dd = (double) d;
        int r = rs_budget_estimate(err, "the Schur-Cohn matrix", 1e-9 * dd * dd * dd * dd * B / 64.0,
                                   2.0 * dd * dd * B / 8.0);
        if (r != RS_OK)
            return r;
    }
    fmpz_mat_init(S, d, d);
    fmpz_poly_init(cp);
    for (i = 0; i < d; i++)
        for (k = i; k < d; k++) {
            fmpz *e = fmpz_mat_entry(S, i, k);
            for (l = 0; l <= i; l++) {
                fmpz_addmul(e, a + d - i + l, a + d - k + l);
                fmpz_submul(e, a + i - l, a + k - l);
            }
            fmpz_set(fmpz_mat_entry(S, k, i), e);
        }
    fmpz_mat_charpoly(cp, S);
    /* real-rooted characteristic polynomial: Descartes' sign changes are
     * exactly the positive eigenvalues */
    if (fmpz_is_zero(cp->coeffs + 0)) {
        fmpz_mat_clear(S);
        fmpz_poly_clear(cp);
        return rs_error_set(err, RS_ERR_INTERNAL,
                            "Schur-Cohn matrix singular after gcd removal");
    }
    for (i = 0; i <= d; i++) {
        int s = fmpz_sgn(cp->coeffs + i);
        if (s != 0) {
            if (last != 0 && s != last)
                var++;
            last = s;
        }
    }
    rc->inside += var;
    rc->outside += d - var;
    fmpz_mat_clear(S);
    fmpz_poly_clear(cp);
    return RS_OK;
}

int rs_jury_fmpz_poly(rs_jury_t j, const fmpz_poly_t p, rs_error_t err)
{
    fmpz_poly_t p0, rev, g, h;
    slong z = 0, tin = 0;
    int status;

    rs_jury_clear(j);
    rs_jury_init(j);
    if (fmpz_poly_is_zero(p))
        return rs_error_set(err, RS_ERR_INPUT,
                            "Schur-Cohn test of the zero polynomial");
    j->count->degree = fmpz_poly_degree(p);
    j->table_regular = jury_table(j, p, &tin);

    while (fmpz_is_zero(p->coeffs + z))
        z++;
    fmpz_poly_init(p0);
    fmpz_poly_init(rev);
    fmpz_poly_init(g);
    fmpz_poly_init(h);
    fmpz_poly_shift_right(p0, p, z);
    fmpz_poly_reverse(rev, p0, fmpz_poly_length(p0));
    fmpz_poly_gcd(g, p0, rev);
    j->gcd_degree = fmpz_poly_degree(g);
    if (!fmpz_poly_divides(h, p0, g))
        status = rs_error_set(err, RS_ERR_INTERNAL, "gcd does not divide p");
    else
        status = jury_count_gcd(j->count, g, err);
    j->count->inside += z;
    if (status == RS_OK && j->table_regular && j->gcd_degree == 0) {
        /* no circle root and a regular table: Rouche's count is exact and
         * the Schur-Cohn matrix (d^4 B word operations) adds nothing; the
         * independent count is Routh's on the bilinear transform */
        j->count->inside = tin;
        j->count->outside = j->count->degree - tin;
    } else if (status == RS_OK) {
        /* the circle part is counted from g; h = p0/g has none, and when
         * its own table is regular Rouche counts it without the matrix */
        rs_jury_t th;
        slong hin = 0;
        rs_jury_init(th);
        if (fmpz_poly_degree(h) >= 1 && jury_table(th, h, &hin)) {
            j->count->inside += hin;
            j->count->outside += fmpz_poly_degree(h) - hin;
        } else {
            status = jury_count_schur_cohn(j->count, h, err);
        }
        rs_jury_clear(th);
    }
    if (status == RS_OK && j->table_regular && tin != j->count->inside)
        status = rs_error_set(err, RS_ERR_INCONSISTENT,
            "Schur-Cohn table gives %ld roots inside, the Schur-Cohn matrix "
            "%ld", tin, j->count->inside);
    if (status == RS_OK && j->count->inside + j->count->on
                           + j->count->outside != j->count->degree)
        status = rs_error_set(err, RS_ERR_INTERNAL,
                              "Schur-Cohn count does not add up to the degree");
    fmpz_poly_clear(p0);
    fmpz_poly_clear(rev);
    fmpz_poly_clear(g);
    fmpz_poly_clear(h);
    return status;
}
