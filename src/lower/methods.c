/* methods.c -- exact coefficients of Runge-Kutta, Adams and BDF methods
 * (see methods.h).  Nothing is typed in but the Butcher tableaux: the
 * stability functions, the multistep coefficients and the rational
 * realizations are computed. */
#include <string.h>
#include <flint/fmpq_mat.h>
#include <fmpq_vec.h>
#include "lower/methods.h"
#include "util/qd.h"

void rs_tableau_init(rs_tableau_t t, slong s)
{
    t->s = s;
    t->A = _fmpq_vec_init(s * s);
    t->b = _fmpq_vec_init(s);
    t->d = 0;
    t->A1 = t->b1 = NULL;
}

void rs_tableau_clear(rs_tableau_t t)
{
    _fmpq_vec_clear(t->A, t->s * t->s);
    _fmpq_vec_clear(t->b, t->s);
    if (t->A1 != NULL) _fmpq_vec_clear(t->A1, t->s * t->s);
    if (t->b1 != NULL) _fmpq_vec_clear(t->b1, t->s);
}

/* x + y sqrt(d): the entries of the Gauss, Radau IIA(3) and SDIRK tableaux */
typedef rs_qd_struct qd_t;

static qd_t *qd_vec_init(slong n)
{
    qd_t *v = flint_malloc(n * sizeof(qd_t));
    slong i;
    for (i = 0; i < n; i++) rs_qd_init(v + i);
    return v;
}

static void qd_vec_clear(qd_t *v, slong n)
{
    slong i;
    for (i = 0; i < n; i++) rs_qd_clear(v + i);
    flint_free(v);
}

/* C = A B, s x s */
static void qd_mat_mul(qd_t *C, const qd_t *A, const qd_t *B, slong s, slong d)
{
    qd_t *T = qd_vec_init(s * s), p;
    slong i, j, k;
    fmpq_init(p.x); fmpq_init(p.y);
    for (i = 0; i < s; i++)
        for (j = 0; j < s; j++)
            for (k = 0; k < s; k++) {
                rs_qd_mul(&p, &A[i * s + k], &B[k * s + j], d);
                fmpq_add(T[i * s + j].x, T[i * s + j].x, p.x);
                fmpq_add(T[i * s + j].y, T[i * s + j].y, p.y);
            }
    for (i = 0; i < s * s; i++) { fmpq_swap(C[i].x, T[i].x); fmpq_swap(C[i].y, T[i].y); }
    fmpq_clear(p.x); fmpq_clear(p.y);
    qd_vec_clear(T, s * s);
}

/* mk[k] = b^T A^k 1 (k < s) and the elementary symmetric functions e[k]
 * (k <= s) of the eigenvalues of A, from the traces of A^k by Newton's
 * identities: det(I - zA) = sum (-1)^k e_k z^k */
static void qd_moments(qd_t *mk, qd_t *e, const qd_t *A, const qd_t *b, slong s, slong d)
{
    qd_t *P = qd_vec_init(s * s), *tr = qd_vec_init(s + 1), p;
    slong i, j, k;
    fmpq_init(p.x); fmpq_init(p.y);
    for (i = 0; i < s; i++) { fmpq_one(P[i * s + i].x); }   /* P = A^0 */
    for (k = 0; k <= s; k++) {
        if (k < s)
            for (i = 0; i < s; i++)
                for (j = 0; j < s; j++) {
                    rs_qd_mul(&p, &b[i], &P[i * s + j], d);
                    fmpq_add(mk[k].x, mk[k].x, p.x);
                    fmpq_add(mk[k].y, mk[k].y, p.y);
                }
        for (i = 0; i < s; i++) {
            fmpq_add(tr[k].x, tr[k].x, P[i * s + i].x);
            fmpq_add(tr[k].y, tr[k].y, P[i * s + i].y);
        }
        qd_mat_mul(P, P, A, s, d);
    }
    /* e_0 = 1, k e_k = sum_{i=1..k} (-1)^(i-1) e_{k-i} tr(A^i) */
    fmpq_one(e[0].x);
    for (k = 1; k <= s; k++) {
        for (i = 1; i <= k; i++) {
            rs_qd_mul(&p, &e[k - i], &tr[i], d);
            if (i % 2 == 0) { fmpq_neg(p.x, p.x); fmpq_neg(p.y, p.y); }
            fmpq_add(e[k].x, e[k].x, p.x);
            fmpq_add(e[k].y, e[k].y, p.y);
        }
        fmpq_div_fmpz(e[k].x, e[k].x, (fmpz_set_si(fmpq_numref(p.x), k), fmpq_numref(p.x)));
        fmpq_div_fmpz(e[k].y, e[k].y, fmpq_numref(p.x));
    }
    fmpq_clear(p.x); fmpq_clear(p.y);
    qd_vec_clear(P, s * s); qd_vec_clear(tr, s + 1);
}

/* R = num/den from A, b over Q(sqrt d): den(z) = det(I - zA), num = den *
 * (1 + sum_k (b^T A^k 1) z^(k+1)) truncated at degree s (deg num <= s);
 * 0 when they are not rational (then num, den hold the rational parts) */
static int qd_stability(fmpq_poly_t num, fmpq_poly_t den, const qd_t *A, const qd_t *b, slong s, slong d)
{
    qd_t *mk = qd_vec_init(s), *e = qd_vec_init(s + 1);
    fmpq_poly_t ser, g;
    fmpq_t c;
    slong k;
    int rational = 1;
    qd_moments(mk, e, A, b, s, d);
    fmpq_init(c);
    fmpq_poly_zero(den);
    for (k = 0; k <= s; k++) {
        rational &= fmpq_is_zero(e[k].y);
        fmpq_set(c, e[k].x);
        if (k % 2) fmpq_neg(c, c);
        fmpq_poly_set_coeff_fmpq(den, k, c);
    }
    fmpq_poly_init(ser);
    fmpq_poly_init(g);
    fmpq_poly_set_coeff_si(ser, 0, 1);
    for (k = 0; k < s; k++) {
        rational &= fmpq_is_zero(mk[k].y);
        fmpq_poly_set_coeff_fmpq(ser, k + 1, mk[k].x);
    }
    fmpq_poly_mullow(num, den, ser, s + 1);
    fmpq_poly_gcd(g, num, den);
    fmpq_poly_div(num, num, g);
    fmpq_poly_div(den, den, g);
    fmpq_poly_get_coeff_fmpq(c, den, 0);
    fmpq_poly_scalar_div_fmpq(num, num, c);
    fmpq_poly_scalar_div_fmpq(den, den, c);
    fmpq_poly_clear(ser);
    fmpq_poly_clear(g);
    fmpq_clear(c);
    qd_vec_clear(mk, s); qd_vec_clear(e, s + 1);
    return rational;
}

void rs_tableau_stability(fmpq_poly_t num, fmpq_poly_t den, const rs_tableau_t t)
{
    qd_t *A = qd_vec_init(t->s * t->s), *b = qd_vec_init(t->s);
    slong i;
    for (i = 0; i < t->s * t->s; i++) fmpq_set(A[i].x, t->A + i);
    for (i = 0; i < t->s; i++) fmpq_set(b[i].x, t->b + i);
    qd_stability(num, den, A, b, t->s, 0);
    qd_vec_clear(A, t->s * t->s);
    qd_vec_clear(b, t->s);
}

/* The tableaux as written in Hairer and Wanner, Solving ODEs II, IV.5
 * (Tables 5.1, 5.5, 5.6) and IV.6 (SDIRK of order 2, gamma = 1 - sqrt(2)/2,
 * Alexander 1977; of order 3, gamma = (3 +- sqrt 3)/6); Hairer, Norsett, Wanner I, II.1 (explicit ones).  An
 * entry "X Y" is X + Y sqrt(d); the b row follows A. */
typedef struct { const char *name; slong s, d; const char *e[20]; } named_t;

static const named_t named[] = {
    {"euler", 1, 0, {"0 0", "1 0"}},
    {"heun", 2, 0, {"0 0", "0 0", "1 0", "0 0", "1/2 0", "1/2 0"}},
    {"midpoint", 2, 0, {"0 0", "0 0", "1/2 0", "0 0", "0 0", "1 0"}},
    {"rk4", 4, 0, {"0 0", "0 0", "0 0", "0 0", "1/2 0", "0 0", "0 0", "0 0", "0 0", "1/2 0", "0 0", "0 0",
                   "0 0", "0 0", "1 0", "0 0", "1/6 0", "1/3 0", "1/3 0", "1/6 0"}},
    {"gauss2", 2, 3, {"1/4 0", "1/4 -1/6", "1/4 1/6", "1/4 0", "1/2 0", "1/2 0"}},
    {"radau-iia2", 2, 0, {"5/12 0", "-1/12 0", "3/4 0", "1/4 0", "3/4 0", "1/4 0"}},
    {"radau-iia3", 3, 6, {"11/45 -7/360", "37/225 -169/1800", "-2/225 1/75", "37/225 169/1800", "11/45 7/360",
                          "-2/225 -1/75", "4/9 -1/36", "4/9 1/36", "1/9 0", "4/9 -1/36", "4/9 1/36", "1/9 0"}},
    {"sdirk2", 2, 2, {"1 -1/2", "0 0", "0 1/2", "1 -1/2", "0 1/2", "1 -1/2"}},
    /* the 2-stage SDIRK of order 3 (Norsett 1974, Crouzeix 1975; Hairer and
     * Wanner II, IV.6): A = [g, 0; 1 - 2g, g], b = [1/2, 1/2], g = (3 +- sqrt 3)/6;
     * A-stable only for the + sign (sdirk3), not for the - sign (sdirk3-low) */
    {"sdirk3", 2, 3, {"1/2 1/6", "0 0", "0 -1/3", "1/2 1/6", "1/2 0", "1/2 0"}},
    {"sdirk3-low", 2, 3, {"1/2 -1/6", "0 0", "0 1/3", "1/2 -1/6", "1/2 0", "1/2 0"}},
    {NULL, 0, 0, {NULL}}
};

static const named_t *find_named(const char *name)
{
    slong i;
    for (i = 0; named[i].name; i++)
        if (strcmp(named[i].name, name) == 0) return &named[i];
    return NULL;
}

static void qd_set_str(qd_t *q, const char *s)
{
    char buf[64];
    const char *sp = strchr(s, ' ');
    size_t n = (size_t) (sp - s);
    memcpy(buf, s, n);
    buf[n] = '\0';
    fmpq_set_str(q->x, buf, 10);
    fmpq_set_str(q->y, sp + 1, 10);
}

int rs_methods_rk_stability_named(fmpq_poly_t num, fmpq_poly_t den, const char *name)
{
    const named_t *t = find_named(name);
    qd_t *A, *b;
    slong i, s;
    if (t == NULL) return 0;
    s = t->s;
    A = qd_vec_init(s * s);
    b = qd_vec_init(s);
    for (i = 0; i < s * s; i++) qd_set_str(&A[i], t->e[i]);
    for (i = 0; i < s; i++) qd_set_str(&b[i], t->e[s * s + i]);
    i = qd_stability(num, den, A, b, s, t->d);
    qd_vec_clear(A, s * s);
    qd_vec_clear(b, s);
    return i ? 1 : -1;
}

int rs_methods_rk_stability_named_qd(fmpq_poly_t n0, fmpq_poly_t n1, fmpq_poly_t d0, fmpq_poly_t d1, slong *d,
                                     const char *name)
{
    const named_t *t = find_named(name);
    qd_t *A, *b, *mk, *e;
    fmpq_poly_t s0, s1, t0, t1, u;
    slong i, s;
    if (t == NULL) return 0;
    s = t->s;
    *d = t->d;
    A = qd_vec_init(s * s);
    b = qd_vec_init(s);
    mk = qd_vec_init(s);
    e = qd_vec_init(s + 1);
    for (i = 0; i < s * s; i++) qd_set_str(&A[i], t->e[i]);
    for (i = 0; i < s; i++) qd_set_str(&b[i], t->e[s * s + i]);
    qd_moments(mk, e, A, b, s, t->d);
    fmpq_poly_init(s0); fmpq_poly_init(s1); fmpq_poly_init(t0); fmpq_poly_init(t1); fmpq_poly_init(u);
    fmpq_poly_zero(d0);
    fmpq_poly_zero(d1);
    for (i = 0; i <= s; i++) {
        if (i % 2) { fmpq_neg(e[i].x, e[i].x); fmpq_neg(e[i].y, e[i].y); }
        fmpq_poly_set_coeff_fmpq(d0, i, e[i].x);
        fmpq_poly_set_coeff_fmpq(d1, i, e[i].y);
    }
    fmpq_poly_set_coeff_si(s0, 0, 1);
    for (i = 0; i < s; i++) {
        fmpq_poly_set_coeff_fmpq(s0, i + 1, mk[i].x);
        fmpq_poly_set_coeff_fmpq(s1, i + 1, mk[i].y);
    }
    /* (d0 + r d1)(s0 + r s1), r^2 = d, truncated at degree s */
    fmpq_poly_mullow(t0, d0, s0, s + 1);
    fmpq_poly_mullow(u, d1, s1, s + 1);
    fmpq_poly_scalar_mul_si(u, u, t->d);
    fmpq_poly_add(t0, t0, u);
    fmpq_poly_mullow(t1, d0, s1, s + 1);
    fmpq_poly_mullow(u, d1, s0, s + 1);
    fmpq_poly_add(t1, t1, u);
    fmpq_poly_swap(n0, t0);
    fmpq_poly_swap(n1, t1);
    fmpq_poly_clear(s0); fmpq_poly_clear(s1); fmpq_poly_clear(t0); fmpq_poly_clear(t1); fmpq_poly_clear(u);
    qd_vec_clear(A, s * s); qd_vec_clear(b, s); qd_vec_clear(mk, s); qd_vec_clear(e, s + 1);
    return 1;
}

void rs_tableau_realize(rs_tableau_t t, const fmpq_poly_t num, const fmpq_poly_t den)
{
    slong s = FLINT_MAX(1, FLINT_MAX(fmpq_poly_degree(num), fmpq_poly_degree(den))), i, j;
    fmpq_mat_t A, T, Ti, C;
    fmpq_t q, p;
    fmpq_init(q); fmpq_init(p);
    fmpq_mat_init(A, s, s); fmpq_mat_init(T, s, s); fmpq_mat_init(Ti, s, s); fmpq_mat_init(C, 1, s);
    /* companion of chi(w) = w^s den(1/w): b^T (wI - A)^-1 e_s = w^(s-1) N(1/w) / chi(w), N = (num - den)/z */
    for (i = 0; i + 1 < s; i++) fmpq_one(fmpq_mat_entry(A, i, i + 1));
    for (j = 0; j < s; j++) {
        fmpq_poly_get_coeff_fmpq(q, den, s - j);
        fmpq_neg(fmpq_mat_entry(A, s - 1, j), q);
        fmpq_poly_get_coeff_fmpq(p, num, s - j);
        fmpq_sub(fmpq_mat_entry(C, 0, j), p, q);
    }
    /* T e_s = 1: T = I + (1 - e_s) e_s^T, T^-1 = I - (1 - e_s) e_s^T */
    fmpq_mat_one(T);
    fmpq_mat_one(Ti);
    for (i = 0; i + 1 < s; i++) {
        fmpq_one(fmpq_mat_entry(T, i, s - 1));
        fmpq_set_si(fmpq_mat_entry(Ti, i, s - 1), -1, 1);
    }
    fmpq_mat_mul(A, T, A);
    fmpq_mat_mul(A, A, Ti);
    fmpq_mat_mul(C, C, Ti);
    rs_tableau_clear(t);
    rs_tableau_init(t, s);
    for (i = 0; i < s; i++) {
        fmpq_set(t->b + i, fmpq_mat_entry(C, 0, i));
        for (j = 0; j < s; j++) fmpq_set(t->A + i * s + j, fmpq_mat_entry(A, i, j));
    }
    fmpq_mat_clear(A); fmpq_mat_clear(T); fmpq_mat_clear(Ti); fmpq_mat_clear(C);
    fmpq_clear(q); fmpq_clear(p);
}

int rs_tableau_named(rs_tableau_t t, const char *name)
{
    const named_t *n = find_named(name);
    slong i;
    if (n == NULL) return 0;
    if (n->d != 0) {
        fmpq_poly_t num, den;
        fmpq_poly_init(num); fmpq_poly_init(den);
        i = rs_methods_rk_stability_named(num, den, name);
        if (i == 1) rs_tableau_realize(t, num, den);
        fmpq_poly_clear(num); fmpq_poly_clear(den);
        return i;
    }
    rs_tableau_clear(t);
    rs_tableau_init(t, n->s);
    for (i = 0; i < n->s * n->s + n->s; i++) {
        qd_t q;
        fmpq_init(q.x); fmpq_init(q.y);
        qd_set_str(&q, n->e[i]);
        fmpq_set(i < n->s * n->s ? t->A + i : t->b + (i - n->s * n->s), q.x);
        fmpq_clear(q.x); fmpq_clear(q.y);
    }
    return 1;
}

int rs_tableau_named_qd(rs_tableau_t t, const char *name)
{
    const named_t *n = find_named(name);
    slong i, ss;
    if (n == NULL) return 0;
    ss = n->s * n->s;
    rs_tableau_clear(t);
    rs_tableau_init(t, n->s);
    t->d = n->d;
    if (n->d != 0) {
        t->A1 = _fmpq_vec_init(ss);
        t->b1 = _fmpq_vec_init(n->s);
    }
    for (i = 0; i < ss + n->s; i++) {
        qd_t q;
        fmpq_init(q.x); fmpq_init(q.y);
        qd_set_str(&q, n->e[i]);
        fmpq_set(i < ss ? t->A + i : t->b + (i - ss), q.x);
        if (n->d != 0) fmpq_set(i < ss ? t->A1 + i : t->b1 + (i - ss), q.y);
        fmpq_clear(q.x); fmpq_clear(q.y);
    }
    return 1;
}

/* the Lagrange basis polynomial of node j among the nodes t_m = t0 - m, m = 0..n-1 */
static void lagrange(fmpq_poly_t L, slong j, slong t0, slong n)
{
    fmpq_poly_t f;
    fmpq_t c;
    slong m;
    fmpq_poly_init(f);
    fmpq_init(c);
    fmpq_poly_one(L);
    fmpq_one(c);
    for (m = 0; m < n; m++) {
        if (m == j) continue;
        fmpq_poly_zero(f);
        fmpq_poly_set_coeff_si(f, 1, 1);
        fmpq_poly_set_coeff_si(f, 0, -(t0 - m));
        fmpq_poly_mul(L, L, f);
        fmpq_mul_si(c, c, (t0 - j) - (t0 - m));
    }
    fmpq_poly_scalar_div_fmpq(L, L, c);
    fmpq_poly_clear(f);
    fmpq_clear(c);
}

void rs_methods_adams(fmpq *beta, slong k, int implicit)
{
    fmpq_poly_t L;
    fmpq_t one;
    slong j, n = implicit ? k + 1 : k;
    fmpq_poly_init(L);
    fmpq_init(one);
    fmpq_one(one);
    for (j = 0; j < n; j++) {
        lagrange(L, j, implicit ? 1 : 0, n);
        fmpq_poly_integral(L, L);
        fmpq_poly_evaluate_fmpq(beta + j, L, one);
    }
    fmpq_poly_clear(L);
    fmpq_clear(one);
}

void rs_methods_bdf(fmpq *alpha, slong k)
{
    fmpq_poly_t L;
    fmpq_t one;
    slong j;
    fmpq_poly_init(L);
    fmpq_init(one);
    fmpq_one(one);
    for (j = 0; j <= k; j++) {
        lagrange(L, j, 1, k + 1);
        fmpq_poly_derivative(L, L);
        fmpq_poly_evaluate_fmpq(alpha + j, L, one);
    }
    fmpq_poly_clear(L);
    fmpq_clear(one);
}
