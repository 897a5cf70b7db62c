/* rootcount.c -- see include/recstab/rootcount.h
 *
 * The factorisation method: every irreducible factor f over Z is decided on
 * its own.  A factor with a root on the circle is self-reciprocal (its root
 * r and 1/conj(r) = conj(r) are both roots of the irreducible f, so f | f*),
 * hence exact algebra handles all circle roots and Arb only ever sees
 * factors whose roots stay away from the circle, where raising the
 * precision always terminates. */
#include <string.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <arb.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include "recstab/radius.h"
#include "recstab/budget.h"
#include "recstab/rootcount.h"

#define RS_ROOTCOUNT_MAX_PREC 65536

void rs_rootcount_init(rs_rootcount_t rc)
{
    memset(rc, 0, sizeof(rs_rootcount_struct));
}

void rs_rootcount_clear(rs_rootcount_t rc)
{
    (void) rc;
}

int rs_rootcount_equal(const rs_rootcount_t a, const rs_rootcount_t b)
{
    slong m;
    if (a->degree != b->degree || a->inside != b->inside || a->on != b->on
        || a->outside != b->outside || a->at_one != b->at_one
        || a->at_minus_one != b->at_minus_one)
        return 0;
    for (m = 0; m < RS_ROOTCOUNT_MAXMULT; m++)
        if (a->on_mult[m] != b->on_mult[m])
            return 0;
    return 1;
}

slong rs_rootcount_max_on_mult(const rs_rootcount_t rc)
{
    slong m;
    for (m = RS_ROOTCOUNT_MAXMULT - 1; m >= 1; m--)
        if (rc->on_mult[m] != 0)
            return m;
    return 0;
}

rs_status_t rs_rootcount_status(const rs_rootcount_t rc)
{
    if (rc->outside > 0 || rs_rootcount_max_on_mult(rc) > 1)
        return RS_STATUS_UNSTABLE;
    if (rc->on > 0)
        return RS_STATUS_MARGINAL;
    return RS_STATUS_STABLE;
}

const char *rs_status_name(rs_status_t s)
{
    switch (s) {
    case RS_STATUS_STABLE: return "stable";
    case RS_STATUS_MARGINAL: return "marginal";
    case RS_STATUS_UNSTABLE: return "unstable";
    case RS_STATUS_SINGULAR: return "singular";
    default: return "unknown";
    }
}

void rs_rootcount_add_on(rs_rootcount_struct *rc, slong mult, slong nroots)
{
    slong slot = FLINT_MIN(mult, RS_ROOTCOUNT_MAXMULT - 1);
    if (nroots <= 0 || mult <= 0)
        return;
    rc->on += mult * nroots;
    rc->on_mult[slot] += nroots;
}

void rs_rootcount_reciprocal_to_x(fmpz_poly_t F, const fmpz_poly_t g)
{
    /* lambda^-m g = c_m + sum_k c_{m+k} (lambda^k + lambda^-k), and
     * lambda^k + lambda^-k = D_k(x) with D_0 = 2, D_1 = x,
     * D_{k+1} = x D_k - D_{k-1}. */
    slong m = fmpz_poly_degree(g) / 2, k;
    fmpz_poly_t Dprev, D, Dnext, x, t;

    fmpz_poly_init(Dprev);
    fmpz_poly_init(D);
    fmpz_poly_init(Dnext);
    fmpz_poly_init(x);
    fmpz_poly_init(t);
    fmpz_poly_set_coeff_ui(x, 1, 1);
    fmpz_poly_set_ui(Dprev, 2);
    fmpz_poly_set(D, x);

    fmpz_poly_zero(F);
    fmpz_poly_set_coeff_fmpz(F, 0, g->coeffs + m);
    for (k = 1; k <= m; k++) {
        fmpz_poly_scalar_mul_fmpz(t, D, g->coeffs + m + k);
        fmpz_poly_add(F, F, t);
        fmpz_poly_mul(Dnext, x, D);
        fmpz_poly_sub(Dnext, Dnext, Dprev);
        fmpz_poly_swap(Dprev, D);
        fmpz_poly_swap(D, Dnext);
    }

    fmpz_poly_clear(Dprev);
    fmpz_poly_clear(D);
    fmpz_poly_clear(Dnext);
    fmpz_poly_clear(x);
    fmpz_poly_clear(t);
}

/* sign variations of a Sturm sequence evaluated at the integer a */
static slong sturm_variations(fmpq_poly_struct *seq, slong len, slong a)
{
    fmpz_t x;
    fmpq_t v;
    slong i, var = 0;
    int s, last = 0;

    fmpz_init_set_si(x, a);
    fmpq_init(v);
    for (i = 0; i < len; i++) {
        fmpq_poly_evaluate_fmpz(v, seq + i, x);
        s = fmpq_sgn(v);
        if (s != 0) {
            if (last != 0 && s != last)
                var++;
            last = s;
        }
    }
    fmpz_clear(x);
    fmpq_clear(v);
    return var;
}

slong rs_rootcount_real_roots_open(const fmpz_poly_t f, slong a, slong b)
{
    slong deg = fmpz_poly_degree(f), len = 0, i, res;
    fmpq_poly_struct *seq;

    if (deg <= 0)
        return 0;
    seq = flint_malloc((deg + 2) * sizeof(fmpq_poly_struct));
    for (i = 0; i < deg + 2; i++)
        fmpq_poly_init(seq + i);

    /* f, f', -rem(...): the chain ends at gcd(f, f'), which only rescales
     * every term by a common non-zero value at a and b. */
    fmpq_poly_set_fmpz_poly(seq + 0, f);
    fmpq_poly_derivative(seq + 1, seq + 0);
    len = 2;
    while (!fmpq_poly_is_zero(seq + len - 1) && len < deg + 2) {
        fmpq_poly_rem(seq + len, seq + len - 2, seq + len - 1);
        fmpq_poly_neg(seq + len, seq + len);
        len++;
    }
    res = sturm_variations(seq, len, a) - sturm_variations(seq, len, b);

    for (i = 0; i < deg + 2; i++)
        fmpq_poly_clear(seq + i);
    flint_free(seq);
    return res;
}

/* (a lambda + b)^e */
static void count_linear(rs_rootcount_t rc, const fmpz_poly_t f, slong e)
{
    const fmpz *b = f->coeffs, *a = f->coeffs + 1;
    int c = fmpz_cmpabs(b, a);

    if (c < 0)
        rc->inside += e;
    else if (c > 0)
        rc->outside += e;
    else if (fmpz_sgn(a) != fmpz_sgn(b)) {  /* root -b/a = 1 */
        rc->at_one += e;
        rs_rootcount_add_on(rc, e, 1);
    } else {
        rc->at_minus_one += e;
        rs_rootcount_add_on(rc, e, 1);
    }
}

/* irreducible palindromic f of even degree >= 2, exponent e */
static void count_reciprocal(rs_rootcount_t rc, const fmpz_poly_t f, slong e)
{
    slong deg = fmpz_poly_degree(f), pairs, rest;
    fmpz_poly_t F;

    fmpz_poly_init(F);
    rs_rootcount_reciprocal_to_x(F, f);
    /* F(+-2) != 0 because f(+-1) != 0 (f irreducible of degree >= 2);
     * each real root x in (-2, 2) is a conjugate pair on the circle, every
     * other root x gives a pair (r, 1/r) with |r| != 1. */
    pairs = rs_rootcount_real_roots_open(F, -2, 2);
    rs_rootcount_add_on(rc, e, 2 * pairs);
    rest = deg - 2 * pairs;
    rc->inside += e * (rest / 2);
    rc->outside += e * (rest / 2);
    fmpz_poly_clear(F);
}

/* irreducible f without roots on the circle: certified isolation */
static int count_isolated(rs_rootcount_t rc, const fmpz_poly_t f, slong e,
                          rs_error_t err)
{
    slong deg = fmpz_poly_degree(f), prec, i, in = 0, out = 0;
    acb_ptr roots = _acb_vec_init(deg);
    arb_t r;
    int done = 0, status = RS_OK;

    arb_init(r);
    for (prec = 64; prec <= RS_ROOTCOUNT_MAX_PREC && !done; prec *= 2) {
        if ((status = rs_budget_check(err, "the root isolation")) != RS_OK) break;
        rs_radius_complex_roots(roots, f, prec);
        in = out = 0;
        for (i = 0; i < deg; i++) {
            acb_abs(r, roots + i, prec);
            arb_sub_ui(r, r, 1, prec);
            if (arb_is_negative(r))
                in++;
            else if (arb_is_positive(r))
                out++;
        }
        done = (in + out == deg);
    }
    arb_clear(r);
    _acb_vec_clear(roots, deg);
    if (status != RS_OK)
        return status;
    if (!done && deg == 2) {
        /* roots closer to the circle than 2^-65536 (e.g. |z|^2 = 1 + 10^-199998):
         * a quadratic a x^2 + b x + c is decided exactly -- a complex pair has
         * |r|^2 = c/a, real roots are counted in (-1, 1) by Sturm (f(+-1) != 0) */
        fmpz_t d, t;
        fmpz_init(d);
        fmpz_init(t);
        fmpz_mul(d, f->coeffs + 1, f->coeffs + 1);
        fmpz_mul(t, f->coeffs + 0, f->coeffs + 2);
        fmpz_submul_ui(d, t, 4);
        if (fmpz_sgn(d) < 0) {
            in = fmpz_cmpabs(f->coeffs + 0, f->coeffs + 2) < 0 ? 2 : 0;
        } else {
            in = rs_rootcount_real_roots_open(f, -1, 1);
        }
        out = 2 - in;
        done = 1;
        fmpz_clear(d);
        fmpz_clear(t);
    }
    if (!done)
        return rs_error_set(err, RS_ERR_UNDECIDED,
            "root isolation of a degree %ld factor did not separate its "
            "roots from the unit circle at %d bits", deg,
            RS_ROOTCOUNT_MAX_PREC);
    rc->inside += e * in;
    rc->outside += e * out;
    return RS_OK;
}

static int is_palindromic(const fmpz_poly_t f)
{
    slong n = fmpz_poly_degree(f), i;
    for (i = 0; i <= n / 2; i++)
        if (!fmpz_equal(f->coeffs + i, f->coeffs + n - i))
            return 0;
    return 1;
}

int rs_rootcount_factor(rs_rootcount_t rc, const fmpz_poly_t p, rs_error_t err)
{
    fmpz_poly_factor_t fac;
    slong i, deg;
    int status = RS_OK;

    if (fmpz_poly_is_zero(p))
        return rs_error_set(err, RS_ERR_INPUT,
                            "cannot count the roots of the zero polynomial");
    rs_rootcount_init(rc);
    rc->degree = fmpz_poly_degree(p);
    if (rc->degree == 0)
        return RS_OK;

    fmpz_poly_factor_init(fac);
    fmpz_poly_factor(fac, p);
    for (i = 0; i < fac->num && status == RS_OK; i++) {
        const fmpz_poly_struct *f = fac->p + i;
        slong e = fac->exp[i];
        deg = fmpz_poly_degree(f);
        if (deg == 1)
            count_linear(rc, f, e);
        else if (deg % 2 == 0 && is_palindromic(f))
            count_reciprocal(rc, f, e);
        else /* not self-reciprocal (anti-palindromic ones are reducible) */
            status = count_isolated(rc, f, e, err);
    }
    fmpz_poly_factor_clear(fac);
    if (status == RS_OK
        && rc->inside + rc->on + rc->outside != rc->degree)
        status = rs_error_set(err, RS_ERR_INTERNAL,
                              "factor count %ld + %ld + %ld != degree %ld",
                              rc->inside, rc->on, rc->outside, rc->degree);
    return status;
}
