/* routh_complex.c -- the generalised Routh-Hurwitz test (Bilharz) for
 * polynomials over Q(i), and through the bilinear transform a second exact
 * unit-circle test beside complex Schur-Cohn.
 *
 * With s = i w, q(i w) = A(w) + i B(w), A and B real.  A root s0 of q is
 * w0 = -i s0, and Re s0 < 0 exactly when Im w0 > 0.  A common factor
 * G = gcd(A, B) is real, so its roots are the real ones (q's roots on the
 * imaginary axis) and conjugate pairs (one in each half-plane).  The rest
 * Q1 = A1 + i B1 (A1 = A/G, B1 = B/G) has no real root, and the argument of
 * Q1(w) turns by pi (n_up - n_low) as w runs over the real line; read off
 * tan(arg) = B1/A1 that turn is -pi Ind(B1/A1) when deg A1 >= deg B1 and
 * pi Ind(A1/B1) otherwise (the argument at w = +-inf then lies off the
 * poles of the quotient).  The Cauchy index Ind(Q/P) is Var(-inf) - Var(+inf)
 * of the signed remainder sequence of P, Q (Basu, Pollack and Roy,
 * Algorithms in Real Algebraic Geometry, Theorem 2.58); that sequence is
 * the Routh array of the complex polynomial. */
#include <flint/fmpz_poly_factor.h>
#include <fmpq.h>
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"

void rs_routh_complex_init(rs_routh_complex_t t)
{
    t->degree = -1;
    t->left = t->right = t->axis = 0;
    t->axis_repeated = 0;
    fmpq_poly_init(t->A);
    fmpq_poly_init(t->B);
    fmpq_poly_init(t->G);
    t->len = 0;
    t->chain = NULL;
}

static void chain_free(rs_routh_complex_t t)
{
    slong k;
    for (k = 0; k < t->len; k++) fmpq_poly_clear(t->chain + k);
    flint_free(t->chain);
    t->chain = NULL;
    t->len = 0;
}

void rs_routh_complex_clear(rs_routh_complex_t t)
{
    chain_free(t);
    fmpq_poly_clear(t->A);
    fmpq_poly_clear(t->B);
    fmpq_poly_clear(t->G);
}

static slong cdeg(const fmpq_poly_t re, const fmpq_poly_t im)
{
    return FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im));
}

/* f divided by its (positive) content: same signs, smaller numbers */
static void positive_primitive(fmpq_poly_t f)
{
    fmpq_t c;
    if (fmpq_poly_is_zero(f)) return;
    fmpq_init(c);
    fmpq_poly_content(c, f);
    fmpq_abs(c, c);
    fmpq_poly_scalar_div_fmpq(f, f, c);
    fmpq_clear(c);
}

/* sign variations of the chain at +inf (at = 1) or -inf (at = -1) */
static slong variations(const fmpq_poly_struct *seq, slong len, int at)
{
    slong k, v = 0;
    int last = 0;
    for (k = 0; k < len; k++) {
        fmpq_t lc;
        int sg;
        fmpq_init(lc);
        fmpq_poly_get_coeff_fmpq(lc, seq + k, fmpq_poly_degree(seq + k));
        sg = fmpq_sgn(lc);
        fmpq_clear(lc);
        if (at < 0 && (fmpq_poly_degree(seq + k) & 1)) sg = -sg;
        if (sg == 0) continue;
        if (last != 0 && sg != last) v++;
        last = sg;
    }
    return v;
}

/* the real roots of G (with multiplicity) and whether one is repeated */
static slong real_roots_mult(int *repeated, const fmpq_poly_t G)
{
    fmpz_poly_t g;
    fmpz_poly_factor_t fac;
    slong k, n = 0;
    *repeated = 0;
    if (fmpq_poly_degree(G) < 1) return 0;
    fmpz_poly_init(g);
    fmpz_poly_factor_init(fac);
    fmpq_poly_get_numerator(g, G);
    fmpz_poly_factor_squarefree(fac, g);
    for (k = 0; k < fac->num; k++) {
        slong m = fmpz_poly_num_real_roots(fac->p + k);
        n += m * fac->exp[k];
        if (m > 0 && fac->exp[k] > 1) *repeated = 1;
    }
    fmpz_poly_factor_clear(fac);
    fmpz_poly_clear(g);
    return n;
}

void rs_routh_complex_count(rs_routh_complex_t t, const fmpq_poly_t re, const fmpq_poly_t im)
{
    fmpq_poly_t A1, B1, r;
    fmpq_t a, b;
    slong k, n = cdeg(re, im), d, gdeg, greal, n1, cap;
    int swapped;
    chain_free(t);
    t->degree = n;
    t->left = t->right = t->axis = 0;
    t->axis_repeated = 0;
    fmpq_poly_zero(t->A);
    fmpq_poly_zero(t->B);
    fmpq_poly_zero(t->G);
    if (n < 0) return;
    fmpq_init(a); fmpq_init(b);
    /* q(i w): coefficient k times i^k */
    for (k = 0; k <= n; k++) {
        fmpq_poly_get_coeff_fmpq(a, re, k);
        fmpq_poly_get_coeff_fmpq(b, im, k);
        switch (k & 3) {
        case 0: break;
        case 1: fmpq_swap(a, b); fmpq_neg(a, a); break;          /* (a + ib) i = -b + ia */
        case 2: fmpq_neg(a, a); fmpq_neg(b, b); break;
        default: fmpq_swap(a, b); fmpq_neg(b, b); break;         /* (a + ib)(-i) = b - ia */
        }
        fmpq_poly_set_coeff_fmpq(t->A, k, a);
        fmpq_poly_set_coeff_fmpq(t->B, k, b);
    }
    fmpq_clear(a); fmpq_clear(b);
    fmpq_poly_gcd(t->G, t->A, t->B);   /* monic */
    gdeg = fmpq_poly_degree(t->G);
    greal = real_roots_mult(&t->axis_repeated, t->G);
    fmpq_poly_init(A1); fmpq_poly_init(B1); fmpq_poly_init(r);
    fmpq_poly_div(A1, t->A, t->G);
    fmpq_poly_div(B1, t->B, t->G);
    n1 = FLINT_MAX(fmpq_poly_degree(A1), fmpq_poly_degree(B1));
    swapped = fmpq_poly_degree(B1) > fmpq_poly_degree(A1);
    /* the chain P, Q, -rem(P, Q), ... with P the part of higher degree */
    cap = n1 + 2;
    t->chain = flint_malloc(cap * sizeof(fmpq_poly_struct));
    fmpq_poly_init(t->chain + 0);
    fmpq_poly_set(t->chain + 0, swapped ? B1 : A1);
    positive_primitive(t->chain + 0);
    t->len = 1;
    if (!fmpq_poly_is_zero(swapped ? A1 : B1)) {
        fmpq_poly_init(t->chain + 1);
        fmpq_poly_set(t->chain + 1, swapped ? A1 : B1);
        positive_primitive(t->chain + 1);
        t->len = 2;
        for (;;) {
            fmpq_poly_rem(r, t->chain + t->len - 2, t->chain + t->len - 1);
            if (fmpq_poly_is_zero(r)) break;
            fmpq_poly_neg(r, r);
            positive_primitive(r);
            if (t->len == cap) {
                cap *= 2;
                t->chain = flint_realloc(t->chain, cap * sizeof(fmpq_poly_struct));
            }
            fmpq_poly_init(t->chain + t->len);
            fmpq_poly_swap(t->chain + t->len, r);
            t->len++;
        }
    }
    /* n_up - n_low of Q1: -Ind(B1/A1), or Ind(A1/B1) when deg B1 > deg A1 */
    d = variations(t->chain, t->len, -1) - variations(t->chain, t->len, 1);
    if (!swapped) d = -d;
    t->left = (n1 + d) / 2 + (gdeg - greal) / 2;
    t->right = (n1 - d) / 2 + (gdeg - greal) / 2;
    t->axis = greal;
    fmpq_poly_clear(A1); fmpq_poly_clear(B1); fmpq_poly_clear(r);
}

void rs_routh_complex_bilinear(fmpq_poly_t qre, fmpq_poly_t qim, const fmpq_poly_t re, const fmpq_poly_t im)
{
    slong n = cdeg(re, im), k;
    fmpq_poly_t up, dn, term, pw;
    fmpq_t c;
    fmpq_poly_zero(qre);
    fmpq_poly_zero(qim);
    if (n < 0) return;
    fmpq_poly_init(up); fmpq_poly_init(dn); fmpq_poly_init(term); fmpq_poly_init(pw);
    fmpq_init(c);
    fmpq_poly_set_str(up, "2  1 1");    /* 1 + s */
    fmpq_poly_set_str(dn, "2  1 -1");   /* 1 - s */
    for (k = 0; k <= n; k++) {
        /* (1 + s)^k (1 - s)^(n - k) */
        fmpq_poly_pow(term, up, (ulong) k);
        fmpq_poly_pow(pw, dn, (ulong) (n - k));
        fmpq_poly_mul(term, term, pw);
        fmpq_poly_get_coeff_fmpq(c, re, k);
        if (!fmpq_is_zero(c)) {
            fmpq_poly_scalar_mul_fmpq(pw, term, c);
            fmpq_poly_add(qre, qre, pw);
        }
        fmpq_poly_get_coeff_fmpq(c, im, k);
        if (!fmpq_is_zero(c)) {
            fmpq_poly_scalar_mul_fmpq(pw, term, c);
            fmpq_poly_add(qim, qim, pw);
        }
    }
    fmpq_clear(c);
    fmpq_poly_clear(up); fmpq_poly_clear(dn); fmpq_poly_clear(term); fmpq_poly_clear(pw);
}

int rs_routh_complex_status(rs_status_t *st, rs_routh_complex_t t, const fmpq_poly_t re,
                            const fmpq_poly_t im, slong deg, rs_error_t err)
{
    fmpq_poly_t qre, qim;
    rs_routh_complex_t own;
    slong n = cdeg(re, im), drop;
    if (n < 0) return rs_error_set(err, RS_ERR_MATH, "the characteristic polynomial vanishes identically");
    if (t == NULL) {
        rs_routh_complex_init(own);
        t = own;
    }
    fmpq_poly_init(qre); fmpq_poly_init(qim);
    rs_routh_complex_bilinear(qre, qim, re, im);
    rs_routh_complex_count(t, qre, qim);
    /* a root lambda = -1 of multiplicity m lowers the degree of q by m */
    drop = n - t->degree;
    if (n < deg) *st = RS_STATUS_SINGULAR;
    else if (t->right > 0) *st = RS_STATUS_UNSTABLE;
    else if (t->axis == 0 && drop == 0) *st = RS_STATUS_STABLE;
    else if (t->axis_repeated || drop > 1) *st = RS_STATUS_UNSTABLE;
    else *st = RS_STATUS_MARGINAL;
    fmpq_poly_clear(qre); fmpq_poly_clear(qim);
    if (t == own) rs_routh_complex_clear(own);
    return RS_OK;
}

/* the multiplicity of x (1 or -1) as a root of the squarefree a: 0 or 1 */
static int cx_root_at(const fmpq_poly_t re, const fmpq_poly_t im, slong x)
{
    fmpq_t a, b, t;
    int z;
    fmpq_init(a); fmpq_init(b); fmpq_init(t);
    fmpq_set_si(t, x, 1);
    fmpq_poly_evaluate_fmpq(a, re, t);
    fmpq_poly_evaluate_fmpq(b, im, t);
    z = fmpq_is_zero(a) && fmpq_is_zero(b);
    fmpq_clear(a); fmpq_clear(b); fmpq_clear(t);
    return z;
}

void rs_routh_complex_rootcount(rs_rootcount_t rc, const fmpq_poly_t re, const fmpq_poly_t im)
{
    rs_cx_sqfree_t f;
    fmpq_poly_t qr, qi;
    rs_routh_complex_t t;
    slong k;
    rs_rootcount_clear(rc);
    rs_rootcount_init(rc);
    rc->degree = cdeg(re, im);
    rs_cx_sqfree_init(&f);
    rs_schur_complex_sqfree(&f, re, im);
    fmpq_poly_init(qr); fmpq_poly_init(qi);
    rs_routh_complex_init(t);
    for (k = 1; k <= f.n; k++) {
        const fmpq_poly_struct *ar = f.re + k - 1, *ai = f.im + k - 1;
        slong d = cdeg(ar, ai), on;
        if (d < 1) continue;
        rs_routh_complex_bilinear(qr, qi, ar, ai);
        rs_routh_complex_count(t, qr, qi);
        /* a_k squarefree: Re s < 0 <-> inside; the axis and the degree drop (lambda = -1) <-> on */
        on = t->axis + (d - t->degree);
        rc->inside += k * t->left;
        rc->outside += k * t->right;
        if (on > 0) rs_rootcount_add_on(rc, k, on);
        if (cx_root_at(ar, ai, 1)) rc->at_one = k;
        if (cx_root_at(ar, ai, -1)) rc->at_minus_one = k;
    }
    rs_routh_complex_clear(t);
    fmpq_poly_clear(qr); fmpq_poly_clear(qi);
    rs_cx_sqfree_clear(&f);
}

int rs_routh_complex_checked_status(rs_status_t *st, const fmpq_poly_t re, const fmpq_poly_t im,
                                    slong deg, rs_error_t err)
{
    rs_status_t s1, s2;
    int r = rs_schur_complex_status(&s1, re, im, deg, err);
    if (r != RS_OK) return r;
    r = rs_routh_complex_status(&s2, NULL, re, im, deg, err);
    if (r != RS_OK) return r;
    if (s1 != s2)
        return rs_error_set(err, RS_ERR_INCONSISTENT, "complex Schur-Cohn says %s, the Bilharz test on the "
                            "bilinear transform says %s", rs_status_name(s1), rs_status_name(s2));
    *st = s1;
    return RS_OK;
}

/* ---- symbolic: the Bilharz conditions in real parameters -------------------- */

void rs_routh_cx_conds_init(rs_routh_cx_conds_t *c, const fmpz_mpoly_ctx_t ctx)
{
    c->n = c->ncond = 0;
    c->cond = NULL;
    fmpz_mpoly_init(c->P, ctx);
    fmpz_mpoly_init(c->Q, ctx);
}

void rs_routh_cx_conds_clear(rs_routh_cx_conds_t *c, const fmpz_mpoly_ctx_t ctx)
{
    slong k;
    for (k = 0; k < c->ncond; k++) fmpz_mpoly_clear(c->cond + k, ctx);
    flint_free(c->cond);
    c->cond = NULL;
    c->ncond = 0;
    fmpz_mpoly_clear(c->P, ctx);
    fmpz_mpoly_clear(c->Q, ctx);
}

static fmpz_mpoly_struct *mvec_init(slong n, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_struct *a = flint_malloc((size_t) (n + 1) * sizeof(fmpz_mpoly_struct));
    slong k;
    for (k = 0; k < n; k++) fmpz_mpoly_init(a + k, ctx);
    return a;
}

static void mvec_clear(fmpz_mpoly_struct *a, slong n, const fmpz_mpoly_ctx_t ctx)
{
    slong k;
    for (k = 0; k < n; k++) fmpz_mpoly_clear(a + k, ctx);
    flint_free(a);
}

/* sum a[k] w^k with w the variable lv */
static void mvec_collect(fmpz_mpoly_t out, const fmpz_mpoly_struct *a, slong n, slong lv,
                         const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t w, t;
    slong k;
    fmpz_mpoly_init(w, ctx); fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_zero(out, ctx);
    for (k = 0; k < n; k++) {
        fmpz_mpoly_gen(w, lv, ctx);
        fmpz_mpoly_pow_ui(w, w, (ulong) k, ctx);
        fmpz_mpoly_mul(t, a + k, w, ctx);
        fmpz_mpoly_add(out, out, t, ctx);
    }
    fmpz_mpoly_clear(w, ctx); fmpz_mpoly_clear(t, ctx);
}

static int mvec_too_large(const fmpz_mpoly_struct *a, slong n, const fmpz_mpoly_ctx_t ctx, slong max_terms)
{
    slong k;
    for (k = 0; k < n; k++) if (fmpz_mpoly_length(a + k, ctx) > max_terms) return 1;
    return 0;
}

static void push_cond(rs_routh_cx_conds_t *c, const fmpz_mpoly_t f, int neg, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_init(c->cond + c->ncond, ctx);
    if (neg) fmpz_mpoly_neg(c->cond + c->ncond, f, ctx);
    else fmpz_mpoly_set(c->cond + c->ncond, f, ctx);
    c->ncond++;
}

int rs_routh_cx_conds(rs_routh_cx_conds_t *c, const fmpz_mpoly_t re, const fmpz_mpoly_t im, slong lv,
                      const fmpz_mpoly_ctx_t ctx, slong max_terms)
{
    slong n = FLINT_MAX(fmpz_mpoly_degree_si(re, lv, ctx), fmpz_mpoly_degree_si(im, lv, ctx)), k, j;
    fmpz_mpoly_struct *ar, *ai, *fr, *fi, *A, *B, *R;
    fmpz_mpoly_t t, u, cr, ci, lb, la, beta;
    fmpz_poly_t up, dn, m1, m2;
    int ok = 1;
    if (n < 1) return 0;
    c->n = n;
    c->cond = flint_malloc((size_t) (n + 1) * sizeof(fmpz_mpoly_struct));
    ar = mvec_init(n + 1, ctx); ai = mvec_init(n + 1, ctx);
    fr = mvec_init(n + 1, ctx); fi = mvec_init(n + 1, ctx);
    fmpz_mpoly_init(t, ctx); fmpz_mpoly_init(u, ctx); fmpz_mpoly_init(cr, ctx); fmpz_mpoly_init(ci, ctx);
    fmpz_mpoly_init(lb, ctx); fmpz_mpoly_init(la, ctx); fmpz_mpoly_init(beta, ctx);
    fmpz_poly_init(up); fmpz_poly_init(dn); fmpz_poly_init(m1); fmpz_poly_init(m2);
    for (k = 0; k <= n; k++) {
        ulong e = (ulong) k;
        fmpz_mpoly_get_coeff_vars_ui(ar + k, re, &lv, &e, 1, ctx);
        fmpz_mpoly_get_coeff_vars_ui(ai + k, im, &lv, &e, 1, ctx);
    }
    /* q_j = sum_k c_k [s^j] (1 + s)^k (1 - s)^(n - k), into fr/fi */
    fmpz_poly_set_coeff_si(up, 0, 1); fmpz_poly_set_coeff_si(up, 1, 1);
    fmpz_poly_set_coeff_si(dn, 0, 1); fmpz_poly_set_coeff_si(dn, 1, -1);
    for (k = 0; k <= n; k++) {
        fmpz_poly_pow(m1, up, (ulong) k);
        fmpz_poly_pow(m2, dn, (ulong) (n - k));
        fmpz_poly_mul(m1, m1, m2);
        for (j = 0; j <= n; j++) {
            const fmpz *b = fmpz_poly_get_coeff_ptr(m1, j);
            if (b == NULL || fmpz_is_zero(b)) continue;
            fmpz_mpoly_scalar_mul_fmpz(t, ar + k, b, ctx);
            fmpz_mpoly_add(fr + j, fr + j, t, ctx);
            fmpz_mpoly_scalar_mul_fmpz(t, ai + k, b, ctx);
            fmpz_mpoly_add(fi + j, fi + j, t, ctx);
        }
    }
    /* f_j = q_j i^(j - n) */
    for (j = 0; j <= n; j++) {
        switch ((unsigned) ((j - n) % 4 + 4) % 4) {
        case 0: break;
        case 1: fmpz_mpoly_swap(fr + j, fi + j, ctx); fmpz_mpoly_neg(fr + j, fr + j, ctx); break;
        case 2: fmpz_mpoly_neg(fr + j, fr + j, ctx); fmpz_mpoly_neg(fi + j, fi + j, ctx); break;
        default: fmpz_mpoly_swap(fr + j, fi + j, ctx); fmpz_mpoly_neg(fi + j, fi + j, ctx); break;
        }
    }
    /* times conj(c), c = f_n: P_j = cr fr_j + ci fi_j, Q_j = cr fi_j - ci fr_j */
    fmpz_mpoly_set(cr, fr + n, ctx);
    fmpz_mpoly_set(ci, fi + n, ctx);
    A = mvec_init(n + 1, ctx);
    B = mvec_init(n + 1, ctx);
    R = mvec_init(n + 1, ctx);
    for (j = 0; j <= n; j++) {
        fmpz_mpoly_mul(A + j, cr, fr + j, ctx);
        fmpz_mpoly_mul(t, ci, fi + j, ctx);
        fmpz_mpoly_add(A + j, A + j, t, ctx);
        fmpz_mpoly_mul(B + j, cr, fi + j, ctx);
        fmpz_mpoly_mul(t, ci, fr + j, ctx);
        fmpz_mpoly_sub(B + j, B + j, t, ctx);
    }
    mvec_collect(c->P, A, n + 1, lv, ctx);
    mvec_collect(c->Q, B, n, lv, ctx);     /* B_n = 0 */
    push_cond(c, A + n, 0, ctx);
    if (fmpz_mpoly_is_zero(A + n, ctx)) goto done;
    /* the chain: A = T_(k-1) (formal degree m = n - k + 1), B = T_k (m - 1) */
    fmpz_mpoly_one(beta, ctx);
    for (k = 1; k <= n && ok; k++) {
        slong m = n - k + 1;
        fmpz_mpoly_set(lb, B + m - 1, ctx);
        push_cond(c, lb, k & 1, ctx);
        if (fmpz_mpoly_is_zero(lb, ctx) || k == n) break;
        fmpz_mpoly_set(la, A + m, ctx);
        /* R1 = lb A - la w B (degree m - 1), then R2 = lb R1 - R1_(m-1) B (m - 2) */
        for (j = 0; j <= m - 1; j++) {
            fmpz_mpoly_mul(R + j, lb, A + j, ctx);
            if (j >= 1) {
                fmpz_mpoly_mul(t, la, B + j - 1, ctx);
                fmpz_mpoly_sub(R + j, R + j, t, ctx);
            }
        }
        fmpz_mpoly_set(u, R + m - 1, ctx);
        for (j = 0; j <= m - 2; j++) {
            fmpz_mpoly_mul(R + j, lb, R + j, ctx);
            fmpz_mpoly_mul(t, u, B + j, ctx);
            fmpz_mpoly_sub(R + j, R + j, t, ctx);
            fmpz_mpoly_neg(R + j, R + j, ctx);
        }
        /* / lc(T_(k-1))^2 (k >= 2): exact for the subresultant chain */
        if (k >= 2) {
            fmpz_mpoly_mul(beta, la, la, ctx);
            for (j = 0; j <= m - 2 && ok; j++) ok = fmpz_mpoly_divides(t, R + j, beta, ctx);
            if (ok) for (j = 0; j <= m - 2; j++) fmpz_mpoly_divides(R + j, R + j, beta, ctx);
            ok = 1;
        }
        if (mvec_too_large(R, m - 1, ctx, max_terms)) { ok = 0; break; }
        /* shift: A <- B, B <- R */
        for (j = 0; j <= n; j++) {
            fmpz_mpoly_swap(A + j, B + j, ctx);
            fmpz_mpoly_swap(B + j, R + j, ctx);
            fmpz_mpoly_zero(R + j, ctx);
        }
        for (j = m - 1; j <= n; j++) fmpz_mpoly_zero(B + j, ctx);
    }
done:
    mvec_clear(ar, n + 1, ctx); mvec_clear(ai, n + 1, ctx);
    mvec_clear(fr, n + 1, ctx); mvec_clear(fi, n + 1, ctx);
    mvec_clear(A, n + 1, ctx); mvec_clear(B, n + 1, ctx); mvec_clear(R, n + 1, ctx);
    fmpz_mpoly_clear(t, ctx); fmpz_mpoly_clear(u, ctx); fmpz_mpoly_clear(cr, ctx); fmpz_mpoly_clear(ci, ctx);
    fmpz_mpoly_clear(lb, ctx); fmpz_mpoly_clear(la, ctx); fmpz_mpoly_clear(beta, ctx);
    fmpz_poly_clear(up); fmpz_poly_clear(dn); fmpz_poly_clear(m1); fmpz_poly_clear(m2);
    return ok;
}
