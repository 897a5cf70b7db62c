/* qsqrt.c -- exact arithmetic in Q(sqrt d) and the stability questions of
 * a one-step method whose stability function has coefficients there (see
 * qsqrt.h).  Every verdict comes from exact signs; Arb only isolates the
 * real roots of a rational polynomial (to choose rational samples between
 * them) and gives the second, independent answer of rs_qdc_roots_inside. */
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <flint/fmpz.h>
#include <flint/fmpq.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <mpfr.h>
#include <arb.h>
#include <acb.h>
#include <acb_poly.h>
#include <arb_fmpz_poly.h>
#include "algebra/qsqrt.h"

void rs_qdpoly_init(rs_qdpoly_t p) { fmpq_poly_init(p->p0); fmpq_poly_init(p->p1); }
void rs_qdpoly_clear(rs_qdpoly_t p) { fmpq_poly_clear(p->p0); fmpq_poly_clear(p->p1); }
slong rs_qdpoly_degree(const rs_qdpoly_t p) { return FLINT_MAX(fmpq_poly_degree(p->p0), fmpq_poly_degree(p->p1)); }

void rs_qdpoly_get_coeff(rs_qd_struct *c, const rs_qdpoly_t p, slong k)
{
    fmpq_poly_get_coeff_fmpq(c->x, p->p0, k);
    fmpq_poly_get_coeff_fmpq(c->y, p->p1, k);
}

void rs_qdpoly_set_coeff(rs_qdpoly_t p, slong k, const rs_qd_struct *c)
{
    fmpq_poly_set_coeff_fmpq(p->p0, k, c->x);
    fmpq_poly_set_coeff_fmpq(p->p1, k, c->y);
}

/* (a0 + s a1)(b0 + s b1) = a0 b0 + d a1 b1 + s (a0 b1 + a1 b0), s^2 = d */
void rs_qdpoly_mul(rs_qdpoly_t r, const rs_qdpoly_t a, const rs_qdpoly_t b, slong d)
{
    fmpq_poly_t x, y, t;
    fmpq_poly_init(x); fmpq_poly_init(y); fmpq_poly_init(t);
    fmpq_poly_mul(x, a->p0, b->p0);
    fmpq_poly_mul(t, a->p1, b->p1);
    fmpq_poly_scalar_mul_si(t, t, d);
    fmpq_poly_add(x, x, t);
    fmpq_poly_mul(y, a->p0, b->p1);
    fmpq_poly_mul(t, a->p1, b->p0);
    fmpq_poly_add(y, y, t);
    fmpq_poly_swap(r->p0, x);
    fmpq_poly_swap(r->p1, y);
    fmpq_poly_clear(x); fmpq_poly_clear(y); fmpq_poly_clear(t);
}

void rs_qdpoly_sub(rs_qdpoly_t r, const rs_qdpoly_t a, const rs_qdpoly_t b)
{
    fmpq_poly_sub(r->p0, a->p0, b->p0);
    fmpq_poly_sub(r->p1, a->p1, b->p1);
}

int rs_qdpoly_equal(const rs_qdpoly_t a, const rs_qdpoly_t b)
{
    return fmpq_poly_equal(a->p0, b->p0) && fmpq_poly_equal(a->p1, b->p1);
}

void rs_qdpoly_evaluate_fmpq(rs_qd_struct *v, const rs_qdpoly_t p, const fmpq_t t)
{
    fmpq_poly_evaluate_fmpq(v->x, p->p0, t);
    fmpq_poly_evaluate_fmpq(v->y, p->p1, t);
}

void rs_qdpoly_norm(fmpq_poly_t n, const rs_qdpoly_t p, slong d)
{
    fmpq_poly_t t;
    fmpq_poly_init(t);
    fmpq_poly_mul(n, p->p0, p->p0);
    fmpq_poly_mul(t, p->p1, p->p1);
    fmpq_poly_scalar_mul_si(t, t, d);
    fmpq_poly_sub(n, n, t);
    fmpq_poly_clear(t);
}

char *rs_qdpoly_get_str(const rs_qdpoly_t p, slong d, const char *var)
{
    slong k, deg = rs_qdpoly_degree(p);
    size_t cap = 64, len = 0;
    char *out = flint_malloc(cap);
    rs_qd_t c;
    rs_qd_init(c);
    out[0] = '\0';
    for (k = 0; k <= deg; k++) {
        char *cs, term[64];
        size_t need;
        int paren, minus;
        rs_qdpoly_get_coeff(c, p, k);
        if (rs_qd_is_zero(c)) continue;
        cs = rs_qd_get_str(c, d);
        if (k == 0) term[0] = '\0';
        else if (k == 1) snprintf(term, sizeof term, "*%s", var);
        else snprintf(term, sizeof term, "*%s^%ld", var, (long) k);
        paren = k > 0 && !fmpq_is_zero(c->y) && !fmpq_is_zero(c->x);
        /* a lone negative part after the first term: " - 1/3*sqrt(3)*q", not " + -1/3..." */
        minus = len > 0 && !paren && cs[0] == '-';
        need = len + strlen(cs) + strlen(term) + 8;
        if (need > cap) { cap = 2 * need; out = flint_realloc(out, cap); }
        len += (size_t) snprintf(out + len, cap - len, "%s%s%s%s%s", len ? (minus ? " - " : " + ") : "",
                                 paren ? "(" : "", cs + minus, paren ? ")" : "", term);
        flint_free(cs);
    }
    if (len == 0) strcpy(out, "0");
    rs_qd_clear(c);
    return out;
}

/* a rational strictly between the enclosures hi-end of a and lo-end of b
 * (a NULL: below b; b NULL: above a; both NULL: 0) */
static void sample_between(fmpq_t q, const arb_t a, const arb_t b)
{
    arf_t u, l;
    fmpq_t t;
    arf_init(u); arf_init(l); fmpq_init(t);
    if (a) arb_get_ubound_arf(u, a, 64);
    if (b) arb_get_lbound_arf(l, b, 64);
    if (a && b) {
        arf_get_fmpq(q, u);
        arf_get_fmpq(t, l);
        fmpq_add(q, q, t);
        fmpq_div_2exp(q, q, 1);
    } else if (a) {
        arf_get_fmpq(q, u);
        fmpq_add_si(q, q, 1);
    } else if (b) {
        arf_get_fmpq(q, l);
        fmpq_sub_si(q, q, 1);
    } else {
        fmpq_zero(q);
    }
    arf_clear(u); arf_clear(l); fmpq_clear(t);
}

/* a real root of an irreducible factor */
typedef struct { slong f; arb_struct x[1]; } qroot_t;

static int qroot_cmp(const void *a, const void *b)
{
    return arf_cmp(arb_midref(((const qroot_t *) a)->x), arb_midref(((const qroot_t *) b)->x));
}

/* the real roots of the irreducible factors of f, sorted, pairwise disjoint */
static qroot_t *real_roots(slong *nr, const fmpz_poly_factor_t fac)
{
    qroot_t *r = NULL;
    slong prec, i, j, n = 0;
    int ok = 0;
    for (prec = 64; !ok; prec *= 2) {
        for (i = 0; i < n; i++) arb_clear(r[i].x);
        flint_free(r);
        r = NULL;
        n = 0;
        for (i = 0; i < fac->num; i++) {
            slong deg = fmpz_poly_degree(fac->p + i);
            acb_ptr z = _acb_vec_init(deg);
            arb_fmpz_poly_complex_roots(z, fac->p + i, 0, prec);
            for (j = 0; j < deg; j++) {
                if (!arb_is_zero(acb_imagref(z + j))) continue;
                r = flint_realloc(r, (n + 1) * sizeof(qroot_t));
                r[n].f = i;
                arb_init(r[n].x);
                arb_set(r[n].x, acb_realref(z + j));
                n++;
            }
            _acb_vec_clear(z, deg);
        }
        if (n > 0) qsort(r, (size_t) n, sizeof(qroot_t), qroot_cmp);
        ok = 1;
        for (i = 0; i + 1 < n; i++)
            if (arb_overlaps(r[i].x, r[i + 1].x)) ok = 0;
    }
    *nr = n;
    return r;
}

/* The cells of the real line cut by the real roots of g's norm (g != 0;
 * the sign of g is constant on each cell): fac its irreducible factors
 * (initialised here), *nr real roots returned sorted and disjoint; cell i
 * lies below root i, cell nr above the last.  cells_clear frees both. */
static qroot_t *norm_cells(slong *nr, fmpz_poly_factor_t fac, const rs_qdpoly_t g, slong d)
{
    fmpq_poly_t n;
    fmpz_poly_t f;
    qroot_t *r;
    fmpq_poly_init(n);
    fmpz_poly_init(f);
    fmpz_poly_factor_init(fac);
    rs_qdpoly_norm(n, g, d);
    fmpq_poly_get_numerator(f, n);
    fmpz_poly_factor(fac, f);
    r = real_roots(nr, fac);
    fmpq_poly_clear(n);
    fmpz_poly_clear(f);
    return r;
}

/* the exact sign of g at the rational sample x of cell i */
static int cell_sample(fmpq_t x, const rs_qdpoly_t g, slong d, const qroot_t *r, slong nr, slong i)
{
    rs_qd_t v;
    int sg;
    rs_qd_init(v);
    sample_between(x, i == 0 ? NULL : r[i - 1].x, i == nr ? NULL : r[i].x);
    rs_qdpoly_evaluate_fmpq(v, g, x);
    sg = rs_qd_sgn(v, d);
    rs_qd_clear(v);
    return sg;
}

static void cells_clear(qroot_t *r, slong nr, fmpz_poly_factor_t fac)
{
    slong i;
    for (i = 0; i < nr; i++) arb_clear(r[i].x);
    flint_free(r);
    fmpz_poly_factor_clear(fac);
}

int rs_qdpoly_nonneg_real(const rs_qdpoly_t p, slong d, fmpq_t t0)
{
    fmpz_poly_factor_t fac;
    fmpq_t x;
    qroot_t *r;
    slong nr, i;
    int ok = 1;
    if (rs_qdpoly_degree(p) < 0) return 1;
    fmpq_init(x);
    r = norm_cells(&nr, fac, p, d);
    for (i = 0; i <= nr && ok; i++)
        if (cell_sample(x, p, d, r, nr, i) < 0) { ok = 0; fmpq_set(t0, x); }
    cells_clear(r, nr, fac);
    fmpq_clear(x);
    return ok;
}

/* Routh's array: row k+2 = row k - (r_k[0]/r_{k+1}[0]) row k+1 shifted;
 * Hurwitz iff the first column (n + 1 entries) has no zero and no sign
 * change (Gantmacher, The Theory of Matrices II, XV.6) */
int rs_qdpoly_hurwitz(const rs_qdpoly_t p, slong d)
{
    slong n = rs_qdpoly_degree(p), w, i, k;
    rs_qd_struct *R;
    rs_qd_t q, t;
    int ok = 1, s0;
    if (n < 1) return 0;
    w = n / 2 + 1;
    R = flint_malloc((n + 1) * w * sizeof(rs_qd_struct));
    for (i = 0; i < (n + 1) * w; i++) rs_qd_init(R + i);
    rs_qd_init(q); rs_qd_init(t);
    /* row 0: a_n, a_{n-2}, ...; row 1: a_{n-1}, a_{n-3}, ... */
    for (i = 0; i < w; i++) {
        if (n - 2 * i >= 0) rs_qdpoly_get_coeff(R + i, p, n - 2 * i);
        if (n - 1 - 2 * i >= 0) rs_qdpoly_get_coeff(R + w + i, p, n - 1 - 2 * i);
    }
    s0 = rs_qd_sgn(R, d);
    for (k = 1; k <= n && ok; k++) {
        int s = rs_qd_sgn(R + k * w, d);
        if (s == 0 || s != s0) { ok = 0; break; }
        if (k + 1 > n) break;
        rs_qd_inv(q, R + k * w, d);
        rs_qd_mul(q, q, R + (k - 1) * w, d);
        for (i = 0; i + 1 < w; i++) {
            rs_qd_mul(t, q, R + k * w + i + 1, d);
            rs_qd_sub(R + (k + 1) * w + i, R + (k - 1) * w + i + 1, t);
        }
    }
    for (i = 0; i < (n + 1) * w; i++) rs_qd_clear(R + i);
    flint_free(R);
    rs_qd_clear(q); rs_qd_clear(t);
    return ok;
}

/* P(iy) = sum c_k i^k y^k: A takes the even k with sign (-1)^(k/2), B the
 * odd k with (-1)^((k-1)/2) */
void rs_qdpoly_abs2_imag_axis(rs_qdpoly_t r, const rs_qdpoly_t P, slong d)
{
    rs_qdpoly_t A, B;
    rs_qd_t c;
    slong k;
    rs_qdpoly_init(A); rs_qdpoly_init(B);
    rs_qd_init(c);
    for (k = 0; k <= rs_qdpoly_degree(P); k++) {
        rs_qdpoly_get_coeff(c, P, k);
        if ((k / 2) % 2) { fmpq_neg(c->x, c->x); fmpq_neg(c->y, c->y); }
        rs_qdpoly_set_coeff(k % 2 ? B : A, k, c);
    }
    rs_qdpoly_mul(A, A, A, d);
    rs_qdpoly_mul(B, B, B, d);
    fmpq_poly_add(r->p0, A->p0, B->p0);
    fmpq_poly_add(r->p1, A->p1, B->p1);
    rs_qd_clear(c);
    rs_qdpoly_clear(A); rs_qdpoly_clear(B);
}

rs_qdc_struct *rs_qdc_vec_init(slong n)
{
    rs_qdc_struct *v = flint_malloc(FLINT_MAX(n, 1) * sizeof(rs_qdc_struct));
    slong i;
    for (i = 0; i < n; i++) { rs_qd_init(v[i].re); rs_qd_init(v[i].im); }
    return v;
}

void rs_qdc_vec_clear(rs_qdc_struct *v, slong n)
{
    slong i;
    for (i = 0; i < n; i++) { rs_qd_clear(v[i].re); rs_qd_clear(v[i].im); }
    flint_free(v);
}

/* r = conj(a) b - c conj(e), the Schur-Cohn combination */
static void qdc_comb(rs_qdc_struct *r, const rs_qdc_struct *a, const rs_qdc_struct *b, const rs_qdc_struct *c,
                     const rs_qdc_struct *e, slong d)
{
    rs_qd_t t, u, re, im;
    rs_qd_init(t); rs_qd_init(u); rs_qd_init(re); rs_qd_init(im);
    /* conj(a) b = (ar br + ai bi) + i (ar bi - ai br) */
    rs_qd_mul(re, a->re, b->re, d);
    rs_qd_mul(t, a->im, b->im, d);
    rs_qd_add(re, re, t);
    rs_qd_mul(im, a->re, b->im, d);
    rs_qd_mul(t, a->im, b->re, d);
    rs_qd_sub(im, im, t);
    /* c conj(e) = (cr er + ci ei) + i (ci er - cr ei) */
    rs_qd_mul(t, c->re, e->re, d);
    rs_qd_mul(u, c->im, e->im, d);
    rs_qd_add(t, t, u);
    rs_qd_sub(re, re, t);
    rs_qd_mul(t, c->im, e->re, d);
    rs_qd_mul(u, c->re, e->im, d);
    rs_qd_sub(t, t, u);
    rs_qd_sub(im, im, t);
    rs_qd_set(r->re, re);
    rs_qd_set(r->im, im);
    rs_qd_clear(t); rs_qd_clear(u); rs_qd_clear(re); rs_qd_clear(im);
}

/* |c|^2 in Q(sqrt d) */
void rs_qdc_abs2(rs_qd_struct *r, const rs_qdc_struct *c, slong d)
{
    rs_qd_t t;
    rs_qd_init(t);
    rs_qd_mul(r, c->re, c->re, d);
    rs_qd_mul(t, c->im, c->im, d);
    rs_qd_add(r, r, t);
    rs_qd_clear(t);
}

/* Schur-Cohn (Henrici, Applied and Computational Complex Analysis I, 6.8):
 * with delta = |c_n|^2 - |c_0|^2 != 0, q = (conj(c_n) p - c_0 p*)/lambda
 * (p*(lambda) = lambda^n conj(p(1/conj lambda))) has degree n - 1 and, by
 * Rouche on the circle (|p*| = |p| there), inside(p) = inside(q) + 1 if
 * delta > 0, inside(p) = outside(q) if delta < 0.  A root on the circle is
 * a root of every q, so it forces some delta = 0: returns 0 then (counts
 * not given), else 1 with *inside. */
int rs_qdc_schur_count(slong *inside, const rs_qdc_struct *c, slong n, slong d)
{
    rs_qdc_struct *a = rs_qdc_vec_init(n + 1), *b = rs_qdc_vec_init(n + 1);
    rs_qd_t x, y;
    slong k, m;
    int ok = 1, *sg = flint_malloc((n + 1) * sizeof(int));
    rs_qd_init(x); rs_qd_init(y);
    for (k = 0; k <= n; k++) { rs_qd_set(a[k].re, c[k].re); rs_qd_set(a[k].im, c[k].im); }
    for (m = n; m > 0 && ok; m--) {
        rs_qdc_abs2(x, a + m, d);
        rs_qdc_abs2(y, a, d);
        rs_qd_sub(x, x, y);
        sg[m] = rs_qd_sgn(x, d);
        if (sg[m] == 0) { ok = 0; break; }
        /* b_k = conj(a_m) a_{k+1} - a_0 conj(a_{m-1-k}), k = 0..m-1 */
        for (k = 0; k < m; k++) qdc_comb(b + k, a + m, a + k + 1, a, a + m - 1 - k, d);
        for (k = 0; k < m; k++) { rs_qd_set(a[k].re, b[k].re); rs_qd_set(a[k].im, b[k].im); }
    }
    /* from the constant up: inside of degree m from that of degree m - 1 */
    if (ok) {
        *inside = 0;
        for (m = 1; m <= n; m++) *inside = sg[m] > 0 ? *inside + 1 : (m - 1) - *inside;
    }
    flint_free(sg);
    rs_qd_clear(x); rs_qd_clear(y);
    rs_qdc_vec_clear(a, n + 1);
    rs_qdc_vec_clear(b, n + 1);
    return ok;
}

int rs_qdc_schur_stable(const rs_qdc_struct *c, slong n, slong d)
{
    slong in;
    /* every delta > 0 iff n inside (a delta < 0 leaves at most n - 1) */
    return rs_qdc_schur_count(&in, c, n, d) && in == n;
}

static void qd_arb(arb_t r, const rs_qd_struct *a, const arb_t sd, slong prec)
{
    arb_t t;
    arb_init(t);
    arb_set_fmpq(t, a->y, prec);
    arb_mul(t, t, sd, prec);
    arb_set_fmpq(r, a->x, prec);
    arb_add(r, r, t, prec);
    arb_clear(t);
}

void rs_qdc_vec_get_acb(acb_ptr z, const rs_qdc_struct *c, slong len, slong d, slong prec)
{
    arb_t sd;
    slong k;
    arb_init(sd);
    arb_sqrt_ui(sd, (ulong) d, prec);
    for (k = 0; k < len; k++) {
        qd_arb(acb_realref(z + k), c[k].re, sd, prec);
        qd_arb(acb_imagref(z + k), c[k].im, sd, prec);
    }
    arb_clear(sd);
}

int rs_qdc_roots(acb_ptr z, const rs_qdc_struct *c, slong n, slong d, slong prec)
{
    acb_poly_t p;
    int ok = 0;
    acb_poly_init(p);
    acb_poly_fit_length(p, n + 1);
    rs_qdc_vec_get_acb(p->coeffs, c, n + 1, d, prec);
    _acb_poly_set_length(p, n + 1);
    _acb_poly_normalise(p);
    if (acb_poly_degree(p) == n && !acb_contains_zero(p->coeffs + n)) {
        acb_poly_find_roots(z, p, NULL, 0, prec);
        ok = _acb_poly_validate_roots(z, p->coeffs, n + 1, prec) == n;
    }
    acb_poly_clear(p);
    return ok;
}

int rs_qdc_roots_count(slong *below, slong *above, const rs_qdc_struct *c, slong n, slong d)
{
    slong prec, k;
    *below = *above = 0;
    if (n < 1) return 1;
    for (prec = 64; prec <= 4096 && *below + *above < n; prec *= 2) {
        acb_ptr z = _acb_vec_init(n);
        arb_t m;
        *below = *above = 0;
        arb_init(m);
        if (rs_qdc_roots(z, c, n, d, prec))
            for (k = 0; k < n; k++) {
                acb_abs(m, z + k, prec);
                arb_sub_ui(m, m, 1, prec);
                if (arb_is_negative(m)) (*below)++;
                else if (arb_is_positive(m)) (*above)++;
            }
        _acb_vec_clear(z, n);
        arb_clear(m);
    }
    return *below + *above == n;
}

int rs_qdc_roots_inside(const rs_qdc_struct *c, slong n, slong d)
{
    slong below, above;
    rs_qdc_roots_count(&below, &above, c, n, d);
    return above > 0 ? 0 : below == n ? 1 : -1;
}

int rs_qdc_stable_checked(int *ar, const rs_qdc_struct *c, slong n, slong d)
{
    int sc = rs_qdc_schur_stable(c, n, d), a = rs_qdc_roots_inside(c, n, d);
    if (ar != NULL) *ar = a;
    if ((sc == 1 && a == 0) || (sc == 0 && a == 1)) return -2;
    return sc == 1 ? 1 : a == 0 ? 0 : -1;
}

void rs_qd_astab_init(rs_qd_astab_t a)
{
    memset(a, 0, sizeof(rs_qd_astab_struct));
    fmpq_init(a->witness);
    rs_qdpoly_init(a->E);
    rs_qd_init(a->r_inf);
}

void rs_qd_astab_clear(rs_qd_astab_t a)
{
    fmpq_clear(a->witness);
    rs_qdpoly_clear(a->E);
    rs_qd_clear(a->r_inf);
}

void rs_qd_astab_decide(rs_qd_astab_t a, const rs_qdpoly_t N, const rs_qdpoly_t D, slong d)
{
    rs_qdpoly_t M, Dm;
    rs_qd_t c, l;
    slong k, dn = rs_qdpoly_degree(N), dd = rs_qdpoly_degree(D);
    rs_qdpoly_init(M); rs_qdpoly_init(Dm);
    rs_qd_init(c); rs_qd_init(l);
    rs_qdpoly_abs2_imag_axis(a->E, D, d);
    rs_qdpoly_abs2_imag_axis(M, N, d);
    rs_qdpoly_sub(a->E, a->E, M);
    a->e_nonneg = rs_qdpoly_nonneg_real(a->E, d, a->witness);
    /* D(-z): roots of D in Re z > 0 iff D(-z) is Hurwitz (a constant D has none) */
    for (k = 0; k <= dd; k++) {
        rs_qdpoly_get_coeff(c, D, k);
        if (k % 2) { fmpq_neg(c->x, c->x); fmpq_neg(c->y, c->y); }
        rs_qdpoly_set_coeff(Dm, k, c);
    }
    a->poles_right = dd < 1 ? 1 : rs_qdpoly_hurwitz(Dm, d);
    a->a_stable = a->e_nonneg && a->poles_right;
    a->r_inf_finite = dn <= dd;
    fmpq_zero(a->r_inf->x); fmpq_zero(a->r_inf->y);
    if (dn == dd) {
        rs_qdpoly_get_coeff(c, N, dn);
        rs_qdpoly_get_coeff(l, D, dd);
        rs_qd_inv(l, l, d);
        rs_qd_mul(a->r_inf, c, l, d);
    }
    a->l_stable = a->a_stable && dn < dd;
    rs_qdpoly_clear(M); rs_qdpoly_clear(Dm);
    rs_qd_clear(c); rs_qd_clear(l);
}

/* c = P(zr + i zi), Horner over Q(sqrt d)(i) */
void rs_qdpoly_evaluate_cx(rs_qdc_struct *v, const rs_qdpoly_t P, const fmpq_t zr, const fmpq_t zi, slong d)
{
    rs_qdc_struct z[1];
    rs_qd_t a, t, u;
    slong k;
    rs_qd_init(z->re); rs_qd_init(z->im);
    rs_qd_init(a); rs_qd_init(t); rs_qd_init(u);
    fmpq_set(z->re->x, zr);
    fmpq_set(z->im->x, zi);
    fmpq_zero(v->re->x); fmpq_zero(v->re->y); fmpq_zero(v->im->x); fmpq_zero(v->im->y);
    for (k = rs_qdpoly_degree(P); k >= 0; k--) {
        /* v = v z + c_k */
        rs_qd_mul(t, v->re, z->re, d);
        rs_qd_mul(u, v->im, z->im, d);
        rs_qd_sub(a, t, u);
        rs_qd_mul(t, v->re, z->im, d);
        rs_qd_mul(u, v->im, z->re, d);
        rs_qd_add(v->im, t, u);
        rs_qdpoly_get_coeff(t, P, k);
        rs_qd_add(v->re, a, t);
    }
    rs_qd_clear(z->re); rs_qd_clear(z->im);
    rs_qd_clear(a); rs_qd_clear(t); rs_qd_clear(u);
}

int rs_qd_onestep_stable_at(const rs_qdpoly_t N, const rs_qdpoly_t D, slong d, const fmpq_t zr, const fmpq_t zi)
{
    rs_qdc_struct *c = rs_qdc_vec_init(2);
    rs_qd_t x;
    int s, r, res;
    rs_qd_init(x);
    /* D(z) lambda - N(z) */
    rs_qdpoly_evaluate_cx(c + 1, D, zr, zi, d);
    rs_qdpoly_evaluate_cx(c, N, zr, zi, d);
    fmpq_neg(c->re->x, c->re->x); fmpq_neg(c->re->y, c->re->y);
    fmpq_neg(c->im->x, c->im->x); fmpq_neg(c->im->y, c->im->y);
    if (rs_qd_is_zero(c[1].re) && rs_qd_is_zero(c[1].im)) {
        res = -1;
    } else {
        s = rs_qdc_schur_stable(c, 1, d);
        r = rs_qdc_roots_inside(c, 1, d);
        /* Arb cannot settle a root on the circle: then Schur must say 0 and
         * |N| = |D| exactly */
        if (r == -1) {
            rs_qdc_abs2(x, c + 1, d);
            {
                rs_qd_t y;
                rs_qd_init(y);
                rs_qdc_abs2(y, c, d);
                rs_qd_sub(x, x, y);
                rs_qd_clear(y);
            }
            res = (s == 0 && rs_qd_sgn(x, d) == 0) ? 0 : -2;
        } else {
            res = r == s ? s : -2;
        }
    }
    rs_qd_clear(x);
    rs_qdc_vec_clear(c, 2);
    return res;
}

void rs_qd_iv_init(rs_qd_iv_t iv)
{
    rs_qd_end_struct *e[2] = {iv->lo, iv->hi};
    int k;
    for (k = 0; k < 2; k++) {
        e[k]->inf = 0;
        fmpz_poly_init(e[k]->minpoly);
        arb_init(e[k]->x);
        fmpq_init(e[k]->q);
    }
}

void rs_qd_iv_clear(rs_qd_iv_t iv)
{
    rs_qd_end_struct *e[2] = {iv->lo, iv->hi};
    int k;
    for (k = 0; k < 2; k++) {
        fmpz_poly_clear(e[k]->minpoly);
        arb_clear(e[k]->x);
        fmpq_clear(e[k]->q);
    }
}

static void end_set(rs_qd_end_struct *e, const qroot_t *r, const fmpz_poly_factor_t fac)
{
    e->inf = 0;
    fmpz_poly_set(e->minpoly, fac->p + r->f);
    arb_set(e->x, r->x);
    if (fmpz_poly_degree(e->minpoly) == 1) {
        /* a1 x + a0 = 0 */
        fmpq_set_fmpz_frac(e->q, e->minpoly->coeffs, e->minpoly->coeffs + 1);
        fmpq_neg(e->q, e->q);
    }
}

int rs_qd_onestep_interval(rs_qd_iv_t iv, const rs_qdpoly_t N, const rs_qdpoly_t D, slong d, int imag)
{
    int res = 0;
    rs_qdpoly_t g, t;
    fmpz_poly_factor_t fac;
    qroot_t *r;
    slong nr, i, zero = -1, j, c;
    int *ok;
    rs_qdpoly_init(g); rs_qdpoly_init(t);
    if (imag) {
        rs_qdpoly_abs2_imag_axis(g, D, d);
        rs_qdpoly_abs2_imag_axis(t, N, d);
    } else {
        rs_qdpoly_mul(g, D, D, d);
        rs_qdpoly_mul(t, N, N, d);
    }
    rs_qdpoly_sub(g, g, t);
    /* g = 0: |R| = 1 on the whole line */
    if (rs_qdpoly_degree(g) < 0) {
        iv->lo->inf = -1;
        iv->hi->inf = 1;
    } else {
        fmpq_t x;
        r = norm_cells(&nr, fac, g, d);
        /* ok[i]: g >= 0 on the cell below root i (i = nr: above the last) */
        ok = flint_malloc((nr + 1) * sizeof(int));
        fmpq_init(x);
        for (i = 0; i <= nr; i++) ok[i] = cell_sample(x, g, d, r, nr, i) >= 0;
        fmpq_clear(x);
        for (i = 0; i < nr; i++)
            if (arb_contains_zero(r[i].x) && fmpz_is_zero(fac->p[r[i].f].coeffs)) zero = i;
        if (zero < 0) {
            /* 0 inside a cell (R(0) != 1): that cell, c, if bounded */
            for (c = 0; c < nr && arf_sgn(arb_midref(r[c].x)) < 0; c++) ;
            if (!ok[c]) res = -1;
            i = c - 1;
            j = c;
        } else {
            i = zero - 1;
            j = zero + 1;
            if (!ok[zero]) i = zero;       /* below 0 unbounded: lo = 0 */
            if (!ok[zero + 1]) j = zero;   /* above 0 unbounded: hi = 0 */
        }
        /* walk down while the cell below root i is bounded, up while the cell above root j is */
        if (i != zero) while (i >= 0 && ok[i]) i--;
        if (j != zero) while (j < nr && ok[j + 1]) j++;
        /* lo: root i (or -inf when i < 0); hi: root j (or +inf when j >= nr) */
        if (i < 0) iv->lo->inf = -1; else end_set(iv->lo, r + i, fac);
        if (j >= nr) iv->hi->inf = 1; else end_set(iv->hi, r + j, fac);
        cells_clear(r, nr, fac);
        flint_free(ok);
    }
    rs_qdpoly_clear(g); rs_qdpoly_clear(t);
    return res;
}

char *rs_qd_end_get_str(const rs_qd_end_struct *e)
{
    char *p, *lo, *hi, *out;
    arf_t a;
    if (e->inf) {
        out = flint_malloc(8);
        strcpy(out, e->inf < 0 ? "-inf" : "inf");
        return out;
    }
    if (fmpz_poly_degree(e->minpoly) == 1) return fmpq_get_str(NULL, 10, e->q);
    p = fmpz_poly_get_str_pretty(e->minpoly, "x");
    arf_init(a);
    arb_get_lbound_arf(a, e->x, 53);
    lo = arf_get_str(a, 17);
    arb_get_ubound_arf(a, e->x, 53);
    hi = arf_get_str(a, 17);
    out = flint_malloc(strlen(p) + strlen(lo) + strlen(hi) + 32);
    snprintf(out, strlen(p) + strlen(lo) + strlen(hi) + 32, "root of %s in [%s, %s]", p, lo, hi);
    flint_free(p); flint_free(lo); flint_free(hi);
    arf_clear(a);
    return out;
}
