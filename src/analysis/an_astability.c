/* an_astability.c -- `astability [NAME]`: the stability region of a method
 * on Dahlquist's test equation y' = z y, with NAME (the case's only free
 * parameter by default) taken as the complex number z h.  Exact throughout:
 *  - the real and the imaginary stability interval: the connected set of
 *    bounded points around z = 0 on each axis.  Its ends are among the
 *    critical values of the line z = s (or z = i s): q(i t, z(s)) = A + i B
 *    (q the bilinear transform of p, lambda = (1 + i t)/(1 - i t)) has a
 *    real root t where Res_t(A, B)(s) = 0; lambda = -1 (t = inf) and the
 *    leading coefficient add theirs.  Each cell is decided at a rational
 *    point by complex Schur-Cohn (cross-checked, stability/schur_complex.c)
 *    and by the Bilharz test on the bilinear transform (routh_complex.c);
 *  - A-stability: for p linear in z (multistep: z = -P0/P1 on the circle)
 *    the boundary locus Re z(t) = X(t)/W(t) must stay in Re z >= 0, and
 *    z = -1 be stable; for one-step methods (p = D(z) lambda - N(z)) the
 *    E-polynomial E(y) = |D(iy)|^2 - |N(iy)|^2 >= 0 and the poles in
 *    Re z > 0 (Hairer and Wanner, Solving ODEs II, IV.3).  Where both apply
 *    they must agree (exit 3), and so must the imaginary interval;
 *  - A(alpha) for p linear in z: tan(alpha) = min |Y/X| over the locus in
 *    Re z < 0, at a real root of Y' X - Y X' (an algebraic number); for a
 *    one-step method with real coefficients by the rays z = -s (1 - i u)
 *    (alpha_onestep: tan(alpha) a critical value of |N|^2 - |D|^2 on them),
 *    cross-checked with the E-polynomial's A-stability and with the locus;
 *  - A(alpha) and A-stability of any p over Q(i) (alpha_general), and a
 *    cross-check of the two routes above: on the rays z = -s (1 -+ i u) a
 *    root meets the circle only on curves in (s, u) (Res_t of the bilinear
 *    transform's parts), whose projection in s cuts u into cells decided
 *    exactly on rational points of one ray each;
 *  - the limit of max |lambda| as z -> inf (L-stability: 0). */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <arb.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_poly_factor.h>
#include "analysis/registry.h"
#include "analysis/an_region.h"
#include "stability/schur_complex.h"
#include "stability/routh_complex.h"
#include "util/polyfmt.h"
#include "analysis/an_qd.h"
#include "algebra/qsqrt.h"
#include "recstab/budget.h"

/* p = sum_k (C[k] + i Ci[k])(lambda) z^k: Ci is zero unless p is over Q(i)
 * (complex set values, or a `char` line with i) */
typedef struct {
    fmpz_poly_struct *C, *Ci;
    slong K;          /* degree in z */
    slong n;          /* degree in lambda */
} zpoly_t;





static int ralg_same(const rs_alg_t *a, const rs_alg_t *b)
{
    if (a->rational != b->rational) return 0;
    if (a->rational) return fmpq_equal(a->q, b->q);
    return a->idx == b->idx && fmpz_poly_equal(a->minpoly, b->minpoly);
}

static int ralg_cmp_mid(const void *x, const void *y)
{
    return arf_cmp(arb_midref(((const rs_alg_t *) x)->x), arb_midref(((const rs_alg_t *) y)->x));
}

/* sorted, duplicates removed, enclosures pairwise disjoint */
static void ralg_sort(rs_alg_t *a, slong *n)
{
    slong prec = 128, i, k;
    int ok = 0;
    if (*n == 0) return;   /* a may be NULL then (qsort must not see it) */
    while (!ok) {
        qsort(a, (size_t) *n, sizeof(rs_alg_t), ralg_cmp_mid);
        for (i = k = 0; i < *n; i++) {
            if (k > 0 && ralg_same(a + k - 1, a + i)) { rs_alg_clear(a + i); continue; }
            if (k != i) a[k] = a[i];
            k++;
        }
        *n = k;
        ok = 1;
        for (i = 0; i + 1 < *n; i++)
            if (arb_overlaps(a[i].x, a[i + 1].x)) ok = 0;
        if (!ok) {
            prec *= 2;
            for (i = 0; i < *n; i++) rs_alg_refine(a + i, prec);
        }
    }
}

/* the index of the first a[i] > 0 in the sorted a[0..n) (n if none) */
static slong first_positive(rs_alg_t *a, slong n, slong prec)
{
    slong i;
    for (i = 0; i < n; i++) {
        rs_alg_refine(a + i, prec);
        if (a[i].rational ? fmpq_sgn(a[i].q) > 0 : arb_is_positive(a[i].x)) break;
    }
    return i;
}

/* the rational with the smallest power-of-two denominator strictly between
 * the enclosures of a and b (disjoint; NULL: infinite); 0 when it fits */
static void rational_between(fmpq_t out, const rs_alg_t *a, const rs_alg_t *b)
{
    arf_t u, l;
    fmpq_t x, y;
    slong k;
    arf_init(u); arf_init(l); fmpq_init(x); fmpq_init(y);
    if (a != NULL) arb_get_ubound_arf(u, a->x, 128);
    if (b != NULL) arb_get_lbound_arf(l, b->x, 128);
    if (a != NULL) arf_get_fmpq(x, u);
    if (b != NULL) arf_get_fmpq(y, l);
    if ((a == NULL || fmpq_sgn(x) < 0) && (b == NULL || fmpq_sgn(y) > 0)) fmpq_zero(out);
    else if (a == NULL) { fmpz_fdiv_q(fmpq_numref(out), fmpq_numref(y), fmpq_denref(y)); fmpz_sub_ui(fmpq_numref(out), fmpq_numref(out), 1); fmpz_one(fmpq_denref(out)); }
    else if (b == NULL) { fmpz_fdiv_q(fmpq_numref(out), fmpq_numref(x), fmpq_denref(x)); fmpz_add_ui(fmpq_numref(out), fmpq_numref(out), 1); fmpz_one(fmpq_denref(out)); }
    else {
        for (k = 0; ; k++) {
            /* floor(x 2^k) + 1, over 2^k */
            fmpq_t c;
            fmpq_init(c);
            fmpq_mul_2exp(c, x, (ulong) k);
            fmpz_fdiv_q(fmpq_numref(out), fmpq_numref(c), fmpq_denref(c));
            fmpz_add_ui(fmpq_numref(out), fmpq_numref(out), 1);
            fmpz_one(fmpq_denref(out));
            fmpq_div_2exp(out, out, (ulong) k);
            fmpq_clear(c);
            if (fmpq_cmp(out, y) < 0) break;
        }
    }
    arf_clear(u); arf_clear(l); fmpq_clear(x); fmpq_clear(y);
}

/* JSON of an interval end: integers as numbers, other rationals and
 * algebraic numbers as {"exact", "approx"} (approx: certified digits). */
json_t *rs_an_alg_end_json(rs_alg_t *a, const char *var)
{
    json_t *o;
    char *s;
    if (a->rational && fmpz_is_one(fmpq_denref(a->q)) && fmpz_fits_si(fmpq_numref(a->q)))
        return json_integer((json_int_t) fmpz_get_si(fmpq_numref(a->q)));
    o = json_object();
    rs_alg_refine(a, 128);
    if (a->rational) {
        s = fmpq_get_str(NULL, 10, a->q);
        json_object_set_new(o, "exact", json_string(s));
        flint_free(s);
    } else {
        char *mp = rs_polyfmt_fmpz_poly(a->minpoly, var);
        char *buf = malloc(strlen(mp) + 64);
        sprintf(buf, "real root %ld (ascending) of %s", (long) a->idx + 1, mp);
        json_object_set_new(o, "exact", json_string(buf));
        json_object_set_new(o, "minpoly", json_string(mp));
        free(buf);
        free(mp);
    }
    json_object_set_new(o, "approx", json_real(arf_get_d(arb_midref(a->x), ARF_RND_NEAR)));
    s = rs_radius_arb_str(a->x, 20);
    json_object_set_new(o, "certified", json_string(s));
    flint_free(s);
    return o;
}

/* (re, im) = sum_k C[k] z0^k, z0 = zr + i zi */
static void eval_at(fmpq_poly_t re, fmpq_poly_t im, const zpoly_t *P, const fmpq_t zr, const fmpq_t zi)
{
    fmpq_t pr, pi, t;
    fmpq_poly_t c;
    slong k;
    fmpq_init(pr); fmpq_init(pi); fmpq_init(t);
    fmpq_poly_init(c);
    fmpq_one(pr);
    fmpq_poly_zero(re);
    fmpq_poly_zero(im);
    for (k = 0; k <= P->K; k++) {
        /* (C + i Ci)(pr + i pi) */
        fmpq_poly_set_fmpz_poly(c, P->C + k);
        fmpq_poly_scalar_mul_fmpq(c, c, pr);
        fmpq_poly_add(re, re, c);
        fmpq_poly_set_fmpz_poly(c, P->C + k);
        fmpq_poly_scalar_mul_fmpq(c, c, pi);
        fmpq_poly_add(im, im, c);
        fmpq_poly_set_fmpz_poly(c, P->Ci + k);
        fmpq_poly_scalar_mul_fmpq(c, c, pi);
        fmpq_poly_sub(re, re, c);
        fmpq_poly_set_fmpz_poly(c, P->Ci + k);
        fmpq_poly_scalar_mul_fmpq(c, c, pr);
        fmpq_poly_add(im, im, c);
        /* (pr + i pi) *= z0 */
        fmpq_mul(t, pr, zr);
        fmpq_submul(t, pi, zi);
        fmpq_mul(pi, pi, zr);
        fmpq_addmul(pi, pr, zi);
        fmpq_swap(pr, t);
    }
    fmpq_clear(pr); fmpq_clear(pi); fmpq_clear(t);
    fmpq_poly_clear(c);
}

/* c(i^e s) split: c(i^e s) = re(s) + i im(s) for a polynomial c in z */
static void split_line(fmpz_poly_t re, fmpz_poly_t im, const fmpz_poly_t c, int e)
{
    slong k;
    fmpz_poly_zero(re);
    fmpz_poly_zero(im);
    for (k = 0; k <= fmpz_poly_degree(c); k++) {
        slong r = (e * k) % 4;
        fmpz_poly_struct *dst = (r % 2 == 0) ? re : im;
        fmpz_t x;
        fmpz_init(x);
        fmpz_set(x, c->coeffs + k);
        if (r >= 2) fmpz_neg(x, x);
        fmpz_poly_set_coeff_fmpz(dst, k, x);
        fmpz_clear(x);
    }
}

/* (cr + i ci)(i^e s) = re(s) + i im(s) */
static void split_line_cx(fmpz_poly_t re, fmpz_poly_t im, const fmpz_poly_t cr, const fmpz_poly_t ci, int e)
{
    fmpz_poly_t a, b;
    fmpz_poly_init(a); fmpz_poly_init(b);
    split_line(re, im, cr, e);
    split_line(a, b, ci, e);
    fmpz_poly_sub(re, re, b);
    fmpz_poly_add(im, im, a);
    fmpz_poly_clear(a); fmpz_poly_clear(b);
}

/* the polynomial in z of coefficient j of lambda (j = -1: p at lambda = -1),
 * real and imaginary part */
static void zcoeff(fmpz_poly_t out, fmpz_poly_t outi, const zpoly_t *P, slong j)
{
    slong k;
    int part;
    fmpz_poly_zero(out);
    fmpz_poly_zero(outi);
    for (part = 0; part < 2; part++)
        for (k = 0; k <= P->K; k++) {
            const fmpz_poly_struct *c = (part ? P->Ci : P->C) + k;
            fmpz_t x;
            fmpz_init(x);
            if (j >= 0) fmpz_poly_get_coeff_fmpz(x, c, j);
            else fmpz_poly_evaluate_fmpz(x, c, (fmpz_t) {-1});
            fmpz_poly_set_coeff_fmpz(part ? outi : out, k, x);
            fmpz_clear(x);
        }
}

/* (1-w)^n c((1+w)/(1-w)) */
static void bilinear_n(fmpz_poly_t out, const fmpz_poly_t c, slong n)
{
    fmpz_poly_t a, b, t;
    slong j;
    fmpz_poly_init(a); fmpz_poly_init(b); fmpz_poly_init(t);
    fmpz_poly_zero(out);
    for (j = 0; j <= fmpz_poly_degree(c); j++) {
        fmpz_poly_zero(a); fmpz_poly_zero(b);
        fmpz_poly_set_coeff_si(a, 0, 1); fmpz_poly_set_coeff_si(a, 1, 1);
        fmpz_poly_set_coeff_si(b, 0, 1); fmpz_poly_set_coeff_si(b, 1, -1);
        fmpz_poly_pow(a, a, (ulong) j);
        fmpz_poly_pow(b, b, (ulong) (n - j));
        fmpz_poly_mul(t, a, b);
        fmpz_poly_scalar_mul_fmpz(t, t, c->coeffs + j);
        fmpz_poly_add(out, out, t);
    }
    fmpz_poly_clear(a); fmpz_poly_clear(b); fmpz_poly_clear(t);
}


/* out = the terms of R in variable v alone (all of R when it depends on no
 * other variable), as a univariate polynomial; ctx has at most 3 variables */
static void mpoly_univar(fmpz_poly_t out, const fmpz_mpoly_t R, slong v, const fmpz_mpoly_ctx_t ctx)
{
    slong i, j, nv = ctx->minfo->nvars;
    ulong e[3];
    fmpz_t c;
    fmpz_init(c);
    fmpz_poly_zero(out);
    for (i = 0; i < fmpz_mpoly_length(R, ctx); i++) {
        int other = 0;
        fmpz_mpoly_get_term_coeff_fmpz(c, R, i, ctx);
        fmpz_mpoly_get_term_exp_ui(e, R, i, ctx);
        for (j = 0; j < nv; j++) other |= j != v && e[j] != 0;
        if (!other) fmpz_poly_set_coeff_fmpz(out, (slong) e[v], c);
    }
    fmpz_clear(c);
}

/* univariate in variable 1 (s) of ctx2, from an mpoly in s only */
static void mpoly_to_s(fmpz_poly_t out, const fmpz_mpoly_t R, const fmpz_mpoly_ctx_t ctx)
{
    mpoly_univar(out, R, 1, ctx);
}

/* The curves where a root of q(t) = A + i B (t = variable 0 of ctx, A and B
 * real, overwritten) is real, i.e. where a root of p lies on the unit
 * circle, into L (factored): Res_t(A, B); with a common factor G of A and B
 * (circle roots along the whole curve, e.g. A-stable methods on the
 * imaginary axis) also disc_t G and lc_t G, where they collide or drop;
 * with one part zero the discriminant of the other. */
static void circle_curves(rs_plist_t *L, fmpz_mpoly_t A, fmpz_mpoly_t B, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t G, R;
    slong v = 0;
    ulong e;
    fmpz_mpoly_init(G, ctx); fmpz_mpoly_init(R, ctx);
    if (!fmpz_mpoly_is_zero(A, ctx) && !fmpz_mpoly_is_zero(B, ctx)
        && fmpz_mpoly_gcd(G, A, B, ctx) && fmpz_mpoly_degree_si(G, 0, ctx) > 0) {
        fmpz_mpoly_divexact(A, A, G, ctx);
        fmpz_mpoly_divexact(B, B, G, ctx);
        if (fmpz_mpoly_degree_si(G, 0, ctx) >= 2 && fmpz_mpoly_discriminant(R, G, 0, ctx)) rs_plist_add(L, R, -1, NULL, ctx);
        e = (ulong) fmpz_mpoly_degree_si(G, 0, ctx);
        fmpz_mpoly_get_coeff_vars_ui(R, G, &v, &e, 1, ctx);
        rs_plist_add(L, R, -1, NULL, ctx);
    }
    if (fmpz_mpoly_is_zero(A, ctx) || fmpz_mpoly_is_zero(B, ctx)) {
        /* one part vanishes: its real t-roots are the other's; project with the discriminant */
        fmpz_mpoly_struct *X = fmpz_mpoly_is_zero(B, ctx) ? A : B;
        if (fmpz_mpoly_degree_si(X, 0, ctx) >= 1 && fmpz_mpoly_discriminant(R, X, 0, ctx)) rs_plist_add(L, R, -1, NULL, ctx);
    } else if (fmpz_mpoly_degree_si(A, 0, ctx) + fmpz_mpoly_degree_si(B, 0, ctx) >= 1
               && fmpz_mpoly_resultant(R, A, B, 0, ctx))
        rs_plist_add(L, R, -1, NULL, ctx);
    fmpz_mpoly_clear(G, ctx); fmpz_mpoly_clear(R, ctx);
}

/* The critical values on the line z = i^e s: where a root can reach the
 * unit circle or the leading coefficient vanish. */
static void line_critical(rs_alg_t **crit, slong *ncrit, const zpoly_t *P, int e)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t A, B, T;
    rs_plist_t L;
    fmpz_poly_t cb, ci, re, im, u, g;
    slong k, a;
    int part;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(A, ctx); fmpz_mpoly_init(B, ctx); fmpz_mpoly_init(T, ctx);
    rs_plist_init(&L);
    fmpz_poly_init(cb); fmpz_poly_init(ci); fmpz_poly_init(re); fmpz_poly_init(im); fmpz_poly_init(u);
    fmpz_poly_init(g);
    /* q(i t, i^e s) = A + i B; the imaginary parts of p's coefficients turn by one more i */
    for (part = 0; part < 2; part++)
    for (k = 0; k <= P->K; k++) {
        bilinear_n(cb, (part ? P->Ci : P->C) + k, P->n);
        for (a = 0; a <= fmpz_poly_degree(cb); a++) {
            ulong ex[2];
            slong r = (a + e * k + part) % 4;
            fmpz_t c;
            fmpz_init(c);
            ex[0] = (ulong) a; ex[1] = (ulong) k;
            fmpz_set(c, cb->coeffs + a);
            if (r >= 2) fmpz_neg(c, c);
            fmpz_mpoly_set_coeff_fmpz_ui(T, c, ex, ctx);
            fmpz_mpoly_add((r % 2 == 0) ? A : B, (r % 2 == 0) ? A : B, T, ctx);
            fmpz_mpoly_zero(T, ctx);
            fmpz_clear(c);
        }
    }
    circle_curves(&L, A, B, ctx);
    for (k = 0; k < L.n; k++) {
        mpoly_to_s(u, L.p + k, ctx);
        rs_alg_roots_append(crit, ncrit, u, 0);
    }
    /* lambda = -1 (t = inf) and the leading coefficient: common real roots of both parts */
    for (k = 0; k < 2; k++) {
        zcoeff(cb, ci, P, k == 0 ? -1 : P->n);
        split_line_cx(re, im, cb, ci, e);
        fmpz_poly_gcd(g, re, im);
        if (!fmpz_poly_is_zero(g)) rs_alg_roots_append(crit, ncrit, g, 0);
    }
    fmpz_poly_clear(cb); fmpz_poly_clear(ci); fmpz_poly_clear(re); fmpz_poly_clear(im); fmpz_poly_clear(u); fmpz_poly_clear(g);
    rs_plist_clear(&L, ctx);
    fmpz_mpoly_clear(A, ctx); fmpz_mpoly_clear(B, ctx); fmpz_mpoly_clear(T, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

static int bounded(rs_status_t st) { return st == RS_STATUS_STABLE || st == RS_STATUS_MARGINAL; }

/* exact status at z = zr + i zi */
static int status_at(rs_status_t *st, const zpoly_t *P, const fmpq_t zr, const fmpq_t zi, rs_error_t err)
{
    fmpq_poly_t re, im;
    int r;
    fmpq_poly_init(re); fmpq_poly_init(im);
    eval_at(re, im, P, zr, zi);
    /* p vanishes identically at a zero of a factor common to its coefficients
     * (e.g. det(I - zA) of an RK tableau with a repeated stage): the step
     * cannot be solved there, singular (it was an exit 2) */
    if (fmpq_poly_is_zero(re) && fmpq_poly_is_zero(im)) {
        *st = RS_STATUS_SINGULAR;
        r = RS_OK;
    } else
    /* Schur-Cohn over Q(i) and Bilharz on the bilinear transform (exit 3 if
     * they differ; both say singular where the degree in lambda drops) */
    r = rs_routh_complex_checked_status(st, re, im, P->n, err);
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    return r;
}

/* exact status at z = i^e s0 */
static int status_line(rs_status_t *st, const zpoly_t *P, int e, const fmpq_t s0, rs_error_t err)
{
    fmpq_t zr, zi;
    int r;
    fmpq_init(zr); fmpq_init(zi);
    fmpq_set(e ? zi : zr, s0);
    r = status_at(st, P, zr, zi, err);
    fmpq_clear(zr); fmpq_clear(zi);
    return r;
}

/* 1 when the irreducible f divides both parts of (c + i ci)(i^e s) */
static int vanishes_at(const fmpz_poly_t c, const fmpz_poly_t ci, int e, const fmpz_poly_t f)
{
    fmpz_poly_t re, im, r;
    int z;
    fmpz_poly_init(re); fmpz_poly_init(im); fmpz_poly_init(r);
    split_line_cx(re, im, c, ci, e);
    fmpz_poly_gcd(r, re, im);
    fmpz_poly_gcd(r, r, f);
    z = fmpz_poly_degree(r) >= 1;
    fmpz_poly_clear(re); fmpz_poly_clear(im); fmpz_poly_clear(r);
    return z;
}

/* the discriminant of p in lambda, a polynomial in z over Q(i): computed in
 * Z[lambda, z, I] and reduced by I^2 = -1 (it is polynomial in the
 * coefficients); one root (n = 1) is never repeated */
static void zdisc(fmpz_poly_t dr, fmpz_poly_t di, const zpoly_t *P)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p, d;
    slong k, j, t;
    int part;
    fmpz_poly_zero(dr);
    fmpz_poly_zero(di);
    if (P->n == 1) { fmpz_poly_one(dr); return; }
    fmpz_mpoly_ctx_init(ctx, 3, ORD_LEX);
    fmpz_mpoly_init(p, ctx); fmpz_mpoly_init(d, ctx);
    for (part = 0; part < 2; part++)
        for (k = 0; k <= P->K; k++) {
            const fmpz_poly_struct *c = (part ? P->Ci : P->C) + k;
            for (j = 0; j <= fmpz_poly_degree(c); j++) {
                ulong ex[3];
                ex[0] = (ulong) j; ex[1] = (ulong) k; ex[2] = (ulong) part;
                if (!fmpz_is_zero(c->coeffs + j)) fmpz_mpoly_set_coeff_fmpz_ui(p, c->coeffs + j, ex, ctx);
            }
        }
    if (fmpz_mpoly_discriminant(d, p, 0, ctx))
        for (t = 0; t < fmpz_mpoly_length(d, ctx); t++) {
            ulong ex[3];
            fmpz_t c, o;
            fmpz_poly_struct *dst;
            fmpz_init(c); fmpz_init(o);
            fmpz_mpoly_get_term_coeff_fmpz(c, d, t, ctx);
            fmpz_mpoly_get_term_exp_ui(ex, d, t, ctx);
            if ((ex[2] % 4) >= 2) fmpz_neg(c, c);
            dst = (ex[2] % 2) ? di : dr;
            fmpz_poly_get_coeff_fmpz(o, dst, (slong) ex[1]);
            fmpz_add(o, o, c);
            fmpz_poly_set_coeff_fmpz(dst, (slong) ex[1], o);
            fmpz_clear(c); fmpz_clear(o);
        }
    fmpz_mpoly_clear(p, ctx); fmpz_mpoly_clear(d, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

/* An interval of the line: [lo, hi] with infinite ends NULL. */
typedef struct {
    int empty;
    rs_alg_t lo, hi;
    int lo_inf, hi_inf, lo_closed, hi_closed;
    int undecided;     /* an end whose closedness is not decided */
} line_iv_t;

/* The bounded component of z = i^e s containing s = 0. */
static int line_interval(line_iv_t *iv, const zpoly_t *P, const fmpz_poly_t disc, const fmpz_poly_t disci, int e,
                         rs_error_t err)
{
    rs_alg_t *crit = NULL;
    slong ncrit = 0, npc, i, j, start = -1;
    rs_status_t *pst;
    int *pdec, r = RS_OK;
    memset(iv, 0, sizeof *iv);
    rs_alg_init(&iv->lo);
    rs_alg_init(&iv->hi);
    line_critical(&crit, &ncrit, P, e);
    ralg_sort(crit, &ncrit);
    /* pieces: cell 0, point 0, cell 1, ..., cell ncrit */
    npc = 2 * ncrit + 1;
    pst = flint_calloc(npc, sizeof(rs_status_t));
    pdec = flint_calloc(npc, sizeof(int));
    for (i = 0; i < npc && r == RS_OK; i += 2) {
        fmpq_t x;
        fmpq_init(x);
        rational_between(x, i == 0 ? NULL : crit + i / 2 - 1, i / 2 == ncrit ? NULL : crit + i / 2);
        r = status_line(pst + i, P, e, x, err);
        if (r == RS_OK) r = rs_budget_check(err, "astability");
        pdec[i] = 1;
        if (fmpq_is_zero(x)) start = i;
        fmpq_clear(x);
    }
    for (i = 1; i < npc && r == RS_OK; i += 2) {
        rs_alg_t *c = crit + i / 2;
        if (c->rational) {
            r = status_line(pst + i, P, e, c->q, err);
            pdec[i] = 1;
            if (fmpq_is_zero(c->q)) start = i;
        } else {
            fmpz_poly_t lc, lci;
            fmpz_poly_init(lc); fmpz_poly_init(lci);
            zcoeff(lc, lci, P, P->n);
            if (vanishes_at(lc, lci, e, c->minpoly)) { pst[i] = RS_STATUS_SINGULAR; pdec[i] = 1; }
            else if ((bounded(pst[i - 1]) || bounded(pst[i + 1])) && !vanishes_at(disc, disci, e, c->minpoly)) {
                /* the limit of bounded roots, all simple there */
                pst[i] = RS_STATUS_MARGINAL; pdec[i] = 1;
            }
            fmpz_poly_clear(lc); fmpz_poly_clear(lci);
        }
    }
    if (r == RS_OK) {
        if (start < 0 || !pdec[start] || !bounded(pst[start])) iv->empty = 1;
        else {
            i = start;
            while (i > 0 && pdec[i - 1] && bounded(pst[i - 1])) i--;
            j = start;
            while (j + 1 < npc && pdec[j + 1] && bounded(pst[j + 1])) j++;
            iv->lo_inf = (i == 0);
            iv->hi_inf = (j == npc - 1);
            if (!iv->lo_inf) {
                slong c = (i % 2 == 1) ? i / 2 : i / 2 - 1;   /* point i itself, or the point before cell i */
                rs_alg_t *a = crit + c;
                iv->lo.rational = a->rational; fmpq_set(iv->lo.q, a->q); fmpz_poly_set(iv->lo.minpoly, a->minpoly);
                iv->lo.idx = a->idx; arb_set(iv->lo.x, a->x);
                iv->lo_closed = (i % 2 == 1);
                if (i % 2 == 0 && !pdec[i - 1]) iv->undecided = 1;
            }
            if (!iv->hi_inf) {
                slong c = j / 2;   /* point j, or the point after cell j */
                rs_alg_t *a = crit + c;
                iv->hi.rational = a->rational; fmpq_set(iv->hi.q, a->q); fmpz_poly_set(iv->hi.minpoly, a->minpoly);
                iv->hi.idx = a->idx; arb_set(iv->hi.x, a->x);
                iv->hi_closed = (j % 2 == 1);
                if (j % 2 == 0 && !pdec[j + 1]) iv->undecided = 1;
            }
        }
    }
    for (i = 0; i < ncrit; i++) rs_alg_clear(crit + i);
    free(crit);
    flint_free(pst);
    flint_free(pdec);
    return r;
}

static void line_iv_clear(line_iv_t *iv) { rs_alg_clear(&iv->lo); rs_alg_clear(&iv->hi); }

static json_t *line_iv_json(line_iv_t *iv, const char *var)
{
    if (iv->empty) return json_null();
    return json_pack("[o,o]", iv->lo_inf ? json_string("-inf") : rs_an_alg_end_json(&iv->lo, var),
                     iv->hi_inf ? json_string("inf") : rs_an_alg_end_json(&iv->hi, var));
}

static json_t *line_iv_detail(line_iv_t *iv)
{
    if (iv->empty) return json_pack("{s:b}", "empty", 1);
    return json_pack("{s:b,s:b,s:b}", "lo_closed", !iv->lo_inf && iv->lo_closed, "hi_closed",
                     !iv->hi_inf && iv->hi_closed, "ends_decided", !iv->undecided);
}

/* f >= 0 on the whole real line (f = 0 counts): f is decided at a rational
 * in each cell between its real roots.  Otherwise *t0 is a rational where
 * f < 0. */
static int nonneg_everywhere(const fmpz_poly_t f, fmpq_t t0)
{
    fmpz_poly_factor_t fac;
    rs_alg_t *rts = NULL;
    slong nr = 0, i;
    int ok = 1;
    if (fmpz_poly_is_zero(f)) return 1;
    fmpz_poly_factor_init(fac);
    fmpz_poly_factor(fac, f);
    /* every real root bounds a cell, so no sample is a root */
    for (i = 0; i < fac->num; i++) rs_alg_roots_append(&rts, &nr, fac->p + i, 0);
    ralg_sort(rts, &nr);
    /* sign in each cell between the odd roots */
    for (i = 0; i <= nr && ok; i++) {
        fmpz_t v;
        fmpq_t x, y;
        fmpz_init(v); fmpq_init(x); fmpq_init(y);
        rational_between(x, i == 0 ? NULL : rts + i - 1, i == nr ? NULL : rts + i);
        fmpz_poly_evaluate_fmpq(y, f, x);
        if (fmpq_sgn(y) < 0) { ok = 0; fmpq_set(t0, x); }
        fmpz_clear(v); fmpq_clear(x); fmpq_clear(y);
    }
    for (i = 0; i < nr; i++) rs_alg_clear(rts + i);
    free(rts);
    fmpz_poly_factor_clear(fac);
    return ok;
}

static char *poly_str(const fmpz_poly_t f, const char *var) { return rs_polyfmt_fmpz_poly(f, var); }

/* cr + i ci as text */
static char *cx_str(const fmpz_poly_t cr, const fmpz_poly_t ci, const char *var)
{
    fmpq_poly_t a, b;
    char *out;
    if (fmpz_poly_is_zero(ci)) return poly_str(cr, var);
    fmpq_poly_init(a); fmpq_poly_init(b);
    fmpq_poly_set_fmpz_poly(a, cr);
    fmpq_poly_set_fmpz_poly(b, ci);
    out = rs_cx_poly_str(a, b, var);
    fmpq_poly_clear(a); fmpq_poly_clear(b);
    return out;
}

/* p = sum_k (C[k] + i Ci[k]) z^k as text (malloc'd) */
static char *zpoly_str(const zpoly_t *P, const char *z)
{
    char *out = malloc(1), *t;
    slong k;
    out[0] = '\0';
    for (k = 0; k <= P->K; k++) {
        if (fmpz_poly_is_zero(P->C + k) && fmpz_poly_is_zero(P->Ci + k)) continue;
        t = cx_str(P->C + k, P->Ci + k, "lambda");
        out = realloc(out, strlen(out) + strlen(t) + strlen(z) + 40);
        sprintf(out + strlen(out), "%s(%s)", out[0] ? " + " : "", t);
        if (k >= 1) sprintf(out + strlen(out), "*%s", z);
        if (k >= 2) sprintf(out + strlen(out), "^%ld", (long) k);
        free(t);
    }
    return out;
}

/* z = -(a + i b)/(c + i d); 1 when c + i d != 0 and Re z < 0 */
static int cx_neg_ratio(fmpq_t zr, fmpq_t zi, const fmpz_t a, const fmpz_t b, const fmpz_t c, const fmpz_t d)
{
    fmpz_t n, m;
    int neg;
    if (fmpz_is_zero(c) && fmpz_is_zero(d)) return 0;
    fmpz_init(n); fmpz_init(m);
    /* -(a + i b)(c - i d)/(c^2 + d^2) */
    fmpz_mul(m, c, c);
    fmpz_addmul(m, d, d);
    fmpz_mul(n, a, c);
    fmpz_addmul(n, b, d);
    fmpz_neg(n, n);
    fmpq_set_fmpz_frac(zr, n, m);
    fmpz_mul(n, a, d);
    fmpz_submul(n, b, c);
    fmpq_set_fmpz_frac(zi, n, m);
    neg = fmpq_sgn(zr) < 0;
    fmpz_clear(n); fmpz_clear(m);
    return neg;
}

/* A(alpha) for p = P0 + z P1: alpha as a certified ball in degrees, its
 * exact description and the locus point; *alpha_zero when the locus meets
 * the negative real axis. */
static json_t *alpha_linear(const fmpz_poly_t X, const fmpz_poly_t Y, int *found, arb_t deg)
{
    fmpz_poly_t C, t1, t2;
    rs_alg_t *rts = NULL, *yr = NULL;
    slong nr = 0, ny = 0, i, best = -1, prec = 256;
    arb_t u, bu, xv, yv;
    json_t *o = NULL;
    fmpz_poly_init(C); fmpz_poly_init(t1); fmpz_poly_init(t2);
    arb_init(u); arb_init(bu); arb_init(xv); arb_init(yv);
    *found = 0;
    /* Y' X - Y X' */
    fmpz_poly_derivative(t1, Y);
    fmpz_poly_mul(t1, t1, X);
    fmpz_poly_derivative(t2, X);
    fmpz_poly_mul(t2, t2, Y);
    fmpz_poly_sub(C, t1, t2);
    /* the locus on the negative real axis: Y = 0 with X < 0 */
    if (!fmpz_poly_is_zero(Y)) rs_alg_roots_append(&yr, &ny, Y, 0);
    for (i = 0; i < ny; i++) {
        if (yr[i].rational) arb_set_fmpq(xv, yr[i].q, prec); else { rs_alg_refine(yr + i, prec); arb_set(xv, yr[i].x); }
        arb_fmpz_poly_evaluate_arb(xv, X, xv, prec);
        if (arb_is_negative(xv)) {
            *found = 1;
            arb_zero(deg);
            o = json_pack("{s:s,s:s}", "exact", "0", "reason", "the boundary locus crosses the negative real axis");
            goto done;
        }
    }
    if (!fmpz_poly_is_zero(C)) rs_alg_roots_append(&rts, &nr, C, 0);
    for (i = 0; i < nr; i++) {
        rs_alg_refine(rts + i, prec);
        arb_fmpz_poly_evaluate_arb(xv, X, rts[i].x, prec);
        if (!arb_is_negative(xv)) continue;
        arb_fmpz_poly_evaluate_arb(yv, Y, rts[i].x, prec);
        arb_div(u, yv, xv, prec);
        arb_abs(u, u);
        if (best < 0 || arb_lt(u, bu) || (!arb_gt(u, bu) && arf_cmp(arb_midref(u), arb_midref(bu)) < 0)) {
            best = i;
            arb_set(bu, u);
        }
    }
    if (best >= 0) {
        /* exact: u = |Y/X|(t*) is a root of Res_t(f(t), X(t) u -+ Y(t)) */
        fmpz_mpoly_ctx_t ctx;
        fmpz_mpoly_t F, L, R;
        fmpz_poly_t m, f;
        fmpz_poly_factor_t fac;
        char *ms = NULL, *buf;
        int neg;
        slong k;
        fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
        fmpz_mpoly_init(F, ctx); fmpz_mpoly_init(L, ctx); fmpz_mpoly_init(R, ctx);
        fmpz_poly_init(m); fmpz_poly_init(f);
        fmpz_poly_factor_init(fac);
        arb_fmpz_poly_evaluate_arb(yv, Y, rts[best].x, prec);
        arb_fmpz_poly_evaluate_arb(xv, X, rts[best].x, prec);
        arb_div(u, yv, xv, prec);
        neg = arb_is_negative(u);
        if (rts[best].rational) { fmpz_poly_set_coeff_fmpz(f, 1, fmpq_denref(rts[best].q)); fmpz_poly_set_coeff_fmpz(f, 0, fmpq_numref(rts[best].q)); fmpz_neg(f->coeffs, f->coeffs); }
        else fmpz_poly_set(f, rts[best].minpoly);
        for (k = 0; k <= fmpz_poly_degree(f); k++) {
            ulong ex[2] = {(ulong) k, 0};
            fmpz_mpoly_set_coeff_fmpz_ui(F, f->coeffs + k, ex, ctx);
        }
        /* X(t) u - s Y(t), s = -1 when Y/X < 0 (u = -Y/X) */
        for (k = 0; k <= fmpz_poly_degree(X); k++) {
            ulong ex[2] = {(ulong) k, 1};
            fmpz_mpoly_set_coeff_fmpz_ui(L, X->coeffs + k, ex, ctx);
        }
        for (k = 0; k <= fmpz_poly_degree(Y); k++) {
            ulong ex[2] = {(ulong) k, 0};
            fmpz_t c;
            fmpz_init(c);
            fmpz_set(c, Y->coeffs + k);
            if (!neg) fmpz_neg(c, c);
            fmpz_mpoly_set_coeff_fmpz_ui(L, c, ex, ctx);
            fmpz_clear(c);
        }
        if (fmpz_mpoly_resultant(R, F, L, 0, ctx)) {
            mpoly_to_s(m, R, ctx);
            if (fmpz_poly_degree(m) >= 1) {
                fmpz_poly_factor(fac, m);
                for (k = 0; k < fac->num; k++) {
                    arb_t val;
                    arb_init(val);
                    arb_fmpz_poly_evaluate_arb(val, fac->p + k, bu, prec);
                    if (arb_contains_zero(val) && ms == NULL) ms = poly_str(fac->p + k, "u");
                    arb_clear(val);
                }
            }
        }
        /* degrees = atan(u) 180 / pi */
        {
            arb_t pi;
            arb_init(pi);
            arb_atan(deg, bu, prec);
            arb_mul_ui(deg, deg, 180, prec);
            arb_const_pi(pi, prec);
            arb_div(deg, deg, pi, prec);
            arb_clear(pi);
        }
        *found = 1;
        buf = malloc((ms ? strlen(ms) : 0) + 200);
        sprintf(buf, "(180/pi) atan(u), u = tan(alpha) the root of %s near %.15g", ms ? ms : "(not found)",
                arf_get_d(arb_midref(bu), ARF_RND_NEAR));
        o = json_pack("{s:s}", "exact", buf);
        if (ms) json_object_set_new(o, "tan_alpha_minpoly", json_string(ms));
        json_object_set_new(o, "tan_alpha", json_real(arf_get_d(arb_midref(bu), ARF_RND_NEAR)));
        free(buf);
        free(ms);
        fmpz_poly_factor_clear(fac);
        fmpz_poly_clear(m); fmpz_poly_clear(f);
        fmpz_mpoly_clear(F, ctx); fmpz_mpoly_clear(L, ctx); fmpz_mpoly_clear(R, ctx);
        fmpz_mpoly_ctx_clear(ctx);
    }
done:
    for (i = 0; i < nr; i++) rs_alg_clear(rts + i);
    for (i = 0; i < ny; i++) rs_alg_clear(yr + i);
    free(rts); free(yr);
    fmpz_poly_clear(C); fmpz_poly_clear(t1); fmpz_poly_clear(t2);
    arb_clear(u); arb_clear(bu); arb_clear(xv); arb_clear(yv);
    return o;
}

/* a point of the open left half-plane near z0 where p is exactly unstable
 * (evidence against A-stability), or the boundary point z0 itself */
static json_t *lhp_evidence(const zpoly_t *P, const fmpq_t zr, const fmpq_t zi, rs_error_t err)
{
    static const slong dr[] = {0, -1, 1, 0, 0}, di[] = {0, 0, 0, -1, 1};
    slong k, j;
    for (j = 1; j <= 3; j++)
        for (k = 0; k < 5; k++) {
            fmpq_t a, b, eps;
            fmpq_poly_t re, im;
            rs_status_t st;
            json_t *o = NULL;
            fmpq_init(a); fmpq_init(b); fmpq_init(eps);
            fmpq_poly_init(re); fmpq_poly_init(im);
            fmpq_set_si(eps, 1, j == 1 ? 100 : j == 2 ? 10000 : 1000000);
            fmpq_set(a, zr); fmpq_set(b, zi);
            if (dr[k]) { fmpq_mul_si(eps, eps, dr[k]); fmpq_add(a, a, eps); }
            if (di[k]) { fmpq_mul_si(eps, eps, di[k]); fmpq_add(b, b, eps); }
            eval_at(re, im, P, a, b);
            if (fmpq_sgn(a) < 0 && rs_schur_complex_status(&st, re, im, P->n, err) == RS_OK
                && st == RS_STATUS_UNSTABLE)
                o = json_pack("{s:o,s:o,s:s}", "re", rs_json_fmpq(a), "im", rs_json_fmpq(b), "status", "unstable");
            fmpq_clear(a); fmpq_clear(b); fmpq_clear(eps);
            fmpq_poly_clear(re); fmpq_poly_clear(im);
            if (o != NULL) return o;
        }
    return json_pack("{s:o,s:o,s:s}", "re", rs_json_fmpq(zr), "im", rs_json_fmpq(zi), "status",
                     "a root on the unit circle at this point of Re z < 0 (boundary locus point)");
}

/* ---- A(alpha) of a one-step method ------------------------------------------- */

/* acc += f c(u) x^pre, c in Z[u], u the last variable of ctx, pre the
 * exponents of the others (ctx has at most three variables) */
static void last_addmul(fmpz_mpoly_t acc, const fmpz_poly_t c, const ulong *pre, const fmpz_t f,
                        const fmpz_mpoly_ctx_t ctx)
{
    slong j, nv = ctx->minfo->nvars;
    ulong ex[3];
    fmpz_t t;
    fmpz_mpoly_t m;
    fmpz_init(t);
    fmpz_mpoly_init(m, ctx);
    for (j = 0; j + 1 < nv; j++) ex[j] = pre[j];
    for (j = 0; j <= fmpz_poly_degree(c); j++) {
        ex[nv - 1] = (ulong) j;
        fmpz_mul(t, c->coeffs + j, f);
        if (fmpz_is_zero(t)) continue;
        fmpz_mpoly_set_coeff_fmpz_ui(m, t, ex, ctx);
        fmpz_mpoly_add(acc, acc, m, ctx);
        fmpz_mpoly_zero(m, ctx);
    }
    fmpz_clear(t);
    fmpz_mpoly_clear(m, ctx);
}

/* acc += c(u) s^k (c in Z[u]; ctx: s = variable 0, u = variable 1) */
static void su_addmul(fmpz_mpoly_t acc, const fmpz_poly_t c, slong k, const fmpz_t f, const fmpz_mpoly_ctx_t ctx)
{
    ulong pre[1];
    pre[0] = (ulong) k;
    last_addmul(acc, c, pre, f, ctx);
}

/* G(s, u) = |f(z)|^2 on the ray z = -s (1 - i u), f in Z[z]: with w = -1 + i u,
 * f(s w) = sum_k f_k s^k (A_k + i B_k)(u), w^k = A_k + i B_k */
static void ray_norm(fmpz_mpoly_t G, const fmpz_poly_t f, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_poly_t A, B, t, u;
    fmpz_mpoly_t re, im;
    slong k;
    fmpz_poly_init(A); fmpz_poly_init(B); fmpz_poly_init(t); fmpz_poly_init(u);
    fmpz_mpoly_init(re, ctx); fmpz_mpoly_init(im, ctx);
    fmpz_poly_one(A);
    fmpz_poly_set_coeff_si(u, 1, 1);
    for (k = 0; k <= fmpz_poly_degree(f); k++) {
        su_addmul(re, A, k, f->coeffs + k, ctx);
        su_addmul(im, B, k, f->coeffs + k, ctx);
        /* (A + i B)(-1 + i u) = (-A - u B) + i (u A - B) */
        fmpz_poly_mul(t, u, B);
        fmpz_poly_add(t, t, A);
        fmpz_poly_mul(A, u, A);
        fmpz_poly_sub(B, A, B);
        fmpz_poly_neg(A, t);
    }
    fmpz_mpoly_mul(G, re, re, ctx);
    fmpz_mpoly_mul(re, im, im, ctx);
    fmpz_mpoly_add(G, G, re, ctx);
    fmpz_poly_clear(A); fmpz_poly_clear(B); fmpz_poly_clear(t); fmpz_poly_clear(u);
    fmpz_mpoly_clear(re, ctx); fmpz_mpoly_clear(im, ctx);
}

/* out = the coefficient of s^k of H (a polynomial in u) */
static void su_coeff(fmpz_poly_t out, const fmpz_mpoly_t H, ulong k, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t c;
    slong v = 0;
    fmpz_mpoly_init(c, ctx);
    fmpz_mpoly_get_coeff_vars_ui(c, H, &v, &k, 1, ctx);
    mpoly_to_s(out, c, ctx);
    fmpz_mpoly_clear(c, ctx);
}

/* the JSON of alpha for tan(alpha) = a (a critical value of u), its ball in degrees */
static json_t *alpha_of_tan(arb_t deg, rs_alg_t *a, slong prec)
{
    fmpz_poly_t mp;
    char *ms, *buf;
    arb_t pi;
    json_t *o;
    arb_init(pi);
    fmpz_poly_init(mp);
    rs_alg_refine(a, prec);
    if (a->rational) {
        fmpz_poly_set_coeff_fmpz(mp, 1, fmpq_denref(a->q));
        fmpz_poly_set_coeff_fmpz(mp, 0, fmpq_numref(a->q));
        fmpz_neg(mp->coeffs, mp->coeffs);
    } else fmpz_poly_set(mp, a->minpoly);
    ms = poly_str(mp, "u");
    buf = malloc(strlen(ms) + 120);
    sprintf(buf, "(180/pi) atan(u), u = tan(alpha) the real root %ld (ascending) of %s",
            (long) (a->rational ? 0 : a->idx) + 1, ms);
    o = json_pack("{s:s,s:s,s:f}", "exact", buf, "tan_alpha_minpoly", ms, "tan_alpha",
                  arf_get_d(arb_midref(a->x), ARF_RND_NEAR));
    if (a->rational) json_object_set_new(o, "tan_alpha_exact", rs_json_fmpq(a->q));
    arb_atan(deg, a->x, prec);
    arb_mul_ui(deg, deg, 180, prec);
    arb_const_pi(pi, prec);
    arb_div(deg, deg, pi, prec);
    free(buf);
    free(ms);
    fmpz_poly_clear(mp);
    arb_clear(pi);
    return o;
}

/* acc += f c(u) s^ks t^kt in Z[t, s, u] */
static void tsu_addmul(fmpz_mpoly_t acc, const fmpz_poly_t c, ulong kt, ulong ks, const fmpz_t f,
                       const fmpz_mpoly_ctx_t ctx)
{
    ulong pre[2];
    pre[0] = kt; pre[1] = ks;
    last_addmul(acc, c, pre, f, ctx);
}

/* the ray of slope u0 of alpha_cells: *out 1 with a point z0 = zr + i zi on
 * it where |R| > 1 and the exact point verdict *st there, 0 when the ray
 * lies in the region */
typedef int (*ray_test_fn)(int *out, fmpq_t zr, fmpq_t zi, rs_status_t *st, const fmpq_t u0, void *data,
                           rs_error_t err);

/* w0 = 0 is z = 0 itself (H(0, u0) > 0: an inconsistent method): a point
 * 2^-t just off it where neg_at still holds, by continuity */
static void off_zero(fmpq_t w0, int (*neg_at)(const void *f, const fmpq_t w), const void *f)
{
    slong t;
    if (!fmpq_is_zero(w0)) return;
    for (t = 0; t < 200; t++) {
        fmpq_set_si(w0, 1, 1);
        fmpq_div_2exp(w0, w0, (ulong) t);
        if (neg_at(f, w0)) break;
    }
}

/* A(alpha) from the sorted critical values crit[0..ncrit) of u: the cells
 * of u > 0 between them, each decided by test at a rational u0; tan(alpha)
 * is the left end of the first cell with a point outside, whose point
 * verdict must not be bounded (exit 3).  *inside as alpha_onestep. */
static int alpha_cells(json_t **out, json_t **ev, arb_t deg, int *inside, rs_alg_t *crit, slong ncrit,
                       ray_test_fn test, void *data, const char *route, rs_error_t err)
{
    slong i, first, prec = 256;
    int r = RS_OK, o = 0;
    ralg_sort(crit, &ncrit);
    first = first_positive(crit, ncrit, prec);
    *inside = 1;
    for (i = first; i <= ncrit && *inside == 1 && r == RS_OK; i++) {
        fmpq_t u0, zr, zi;
        rs_status_t st = RS_STATUS_UNSTABLE;
        fmpq_init(u0); fmpq_init(zr); fmpq_init(zi);
        if (i == first) {
            /* between 0 and the first critical value */
            rs_alg_t zero;
            rs_alg_init(&zero);
            zero.rational = 1;
            fmpq_zero(zero.q);
            arb_zero(zero.x);
            rational_between(u0, &zero, i == ncrit ? NULL : crit + i);
            rs_alg_clear(&zero);
        } else rational_between(u0, crit + i - 1, i == ncrit ? NULL : crit + i);
        r = test(&o, zr, zi, &st, u0, data, err);
        if (r == RS_OK && o) {
            *inside = 0;
            if (st == RS_STATUS_STABLE || st == RS_STATUS_MARGINAL)
                r = rs_error_set(err, RS_ERR_INCONSISTENT, "astability: A(alpha) of the one-step method: |R| > 1 "
                                 "on the ray, yet the point verdict is %s", rs_status_name(st));
            if (r == RS_OK) {
                *ev = json_pack("{s:s,s:{s:o,s:o,s:s}}", "route", route, "first_point_outside", "re",
                                rs_json_fmpq(zr), "im", rs_json_fmpq(zi), "status", rs_status_name(st));
                if (i == first) {
                    *out = json_integer(0);
                    arb_zero(deg);
                } else {
                    /* as alpha_linear prints it: u = tan(alpha), its minimal polynomial */
                    *out = alpha_of_tan(deg, crit + i - 1, prec);
                }
            }
        }
        fmpq_clear(u0); fmpq_clear(zr); fmpq_clear(zi);
        if (r == RS_OK) r = rs_budget_check(err, "astability");
    }
    /* every ray inside: A-stable, alpha = 90 as the E-polynomial prints it */
    if (*inside == 1 && r == RS_OK) arb_set_ui(deg, 90);
    return r;
}

typedef struct {
    const fmpz_mpoly_struct *G;
    const fmpz_mpoly_ctx_struct *ctx;
    slong du;
    const zpoly_t *P;
} ray_q_t;

static int fmpz_poly_neg_at(const void *f, const fmpq_t w)
{
    fmpq_t y;
    int n;
    fmpq_init(y);
    fmpz_poly_evaluate_fmpq(y, (const fmpz_poly_struct *) f, w);
    n = fmpq_sgn(y) < 0;
    fmpq_clear(y);
    return n;
}

/* over Q: -H(w^2, u0) den^du >= 0 for every real w (nonneg_everywhere), the
 * point verdict by the checked complex Routh test */
static int ray_test_q(int *out, fmpq_t zr, fmpq_t zi, rs_status_t *st, const fmpq_t u0, void *data, rs_error_t err)
{
    ray_q_t *D = data;
    fmpz_poly_t f;
    fmpq_t w0;
    slong t;
    int r = RS_OK;
    fmpz_poly_init(f);
    fmpq_init(w0);
    for (t = 0; t < fmpz_mpoly_length(D->G, D->ctx); t++) {
        ulong ex[2];
        fmpz_t a, b;
        fmpz_init(a); fmpz_init(b);
        fmpz_mpoly_get_term_coeff_fmpz(a, D->G, t, D->ctx);
        fmpz_mpoly_get_term_exp_ui(ex, D->G, t, D->ctx);
        fmpz_pow_ui(b, fmpq_numref(u0), ex[1]);
        fmpz_mul(a, a, b);
        fmpz_pow_ui(b, fmpq_denref(u0), (ulong) D->du - ex[1]);
        fmpz_mul(a, a, b);
        fmpz_poly_get_coeff_fmpz(b, f, 2 * (slong) ex[0]);
        fmpz_sub(b, b, a);
        fmpz_poly_set_coeff_fmpz(f, 2 * (slong) ex[0], b);
        fmpz_clear(a); fmpz_clear(b);
    }
    *out = !nonneg_everywhere(f, w0);
    if (*out) {
        fmpq_poly_t re, im;
        off_zero(w0, fmpz_poly_neg_at, f);
        /* z0 = -w0^2 + i w0^2 u0 */
        fmpq_mul(zr, w0, w0);
        fmpq_mul(zi, zr, u0);
        fmpq_neg(zr, zr);
        fmpq_poly_init(re); fmpq_poly_init(im);
        eval_at(re, im, D->P, zr, zi);
        if (FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im)) < D->P->n) *st = RS_STATUS_SINGULAR;
        else r = rs_routh_complex_checked_status(st, re, im, D->P->n, err);
        fmpq_poly_clear(re); fmpq_poly_clear(im);
    }
    fmpz_poly_clear(f);
    fmpq_clear(w0);
    return r;
}

/* G := (G - T) / s^m, s^m (s = variable 0) the largest power dividing it:
 * H of the rays, both routes; its degree in s, -1 when G - T vanishes */
static slong ray_difference(fmpz_mpoly_t G, fmpz_mpoly_t T, const fmpz_mpoly_ctx_t ctx)
{
    slong m;
    fmpz_mpoly_sub(G, G, T, ctx);
    if (fmpz_mpoly_is_zero(G, ctx)) return -1;
    m = rs_scheme_min_degree(G, 0, ctx);
    fmpz_mpoly_gen(T, 0, ctx);
    fmpz_mpoly_pow_ui(T, T, (ulong) m, ctx);
    fmpz_mpoly_divexact(G, G, T, ctx);
    return fmpz_mpoly_degree_si(G, 0, ctx);
}

/* A(alpha) of a one-step method p = D(z) lambda - N(z), real coefficients.
 * On the ray z = -s (1 - i u), s > 0, |arg(-z)| = atan(u), and |R(z)| > 1
 * iff G(s, u) = |N|^2 - |D|^2 > 0; H = G / s^m (m its lowest power of s).
 * Whether the ray of u >= 0 has a point with H > 0 changes only at the real
 * roots of disc_s(H) (two roots in s meet), lc_s(H) (a root from s = inf)
 * and H(0, u) (a root from s = 0); each cell between them is decided at a
 * rational u0: the ray lies in the region iff -H(w^2, u0) >= 0 for every
 * real w (nonneg_everywhere, exact).  tan(alpha) is the left end of the
 * first cell with a point outside; that point z0 = -w0^2 (1 - i u0) is
 * re-checked by the exact point verdict (must not be stable: exit 3).
 * *inside: 1 no cell has a point outside (A-stable, *out NULL), 0 one has
 * (*out the angle), -1 the route does not apply (H's discriminant in s
 * vanishes identically). */
static int alpha_onestep(json_t **out, json_t **ev, arb_t deg, int *inside, const zpoly_t *P, const fmpz_poly_t D,
                         const fmpz_poly_t N, rs_error_t err)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t G, T;
    fmpz_poly_t c;
    rs_alg_t *crit = NULL;
    slong ncrit = 0, ds, i;
    int r = RS_OK;
    ray_q_t data;
    *out = NULL;
    *ev = NULL;
    *inside = -1;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(G, ctx); fmpz_mpoly_init(T, ctx);
    fmpz_poly_init(c);
    ray_norm(G, N, ctx);
    ray_norm(T, D, ctx);
    ds = ray_difference(G, T, ctx);
    if (ds < 0) goto done;
    /* the critical values of u: disc_s(H), lc_s(H), H(0, u) */
    for (i = 0; i < 3; i++) {
        if (i == 0) {
            if (ds < 2) continue;
            if (!fmpz_mpoly_discriminant(T, G, 0, ctx) || fmpz_mpoly_is_zero(T, ctx)) goto done;
            mpoly_to_s(c, T, ctx);
        } else su_coeff(c, G, i == 1 ? (ulong) ds : 0, ctx);
        rs_alg_roots_append(&crit, &ncrit, c, 0);   /* it factors c itself */
    }
    data.G = G;
    data.ctx = ctx;
    data.du = fmpz_mpoly_degree_si(G, 1, ctx);
    data.P = P;
    r = alpha_cells(out, ev, deg, inside, crit, ncrit, ray_test_q, &data,
                    "one-step method: rays z = -s (1 - i u), u = tan|arg(-z)|; |N|^2 - |D|^2 on them, its critical u "
                    "(discriminant and end coefficients in s), each cell between them decided exactly at a rational u",
                    err);
done:
    for (i = 0; i < ncrit; i++) rs_alg_clear(crit + i);
    free(crit);
    fmpz_poly_clear(c);
    fmpz_mpoly_clear(G, ctx); fmpz_mpoly_clear(T, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    return r;
}

/* ---- A(alpha) over Q(sqrt d): the same rays with G in Z[s, r, u], r = sqrt(d) ---- */

/* acc = |f(s w)|^2 on the ray w = -1 + i u, f = (f0 + r f1) (integer
 * coefficients), reduced by r^2 = d; ctx: s, r, u */
static void ray_norm_qd(fmpz_mpoly_t acc, const fmpz_poly_t f0, const fmpz_poly_t f1, slong d,
                        const fmpz_mpoly_ctx_t ctx)
{
    fmpz_poly_t A, B, t, u;
    fmpz_mpoly_t re, im;
    slong k, e;
    fmpz_poly_init(A); fmpz_poly_init(B); fmpz_poly_init(t); fmpz_poly_init(u);
    fmpz_mpoly_init(re, ctx); fmpz_mpoly_init(im, ctx);
    fmpz_poly_one(A);
    fmpz_poly_set_coeff_si(u, 1, 1);
    for (k = 0; k <= FLINT_MAX(fmpz_poly_degree(f0), fmpz_poly_degree(f1)); k++) {
        for (e = 0; e < 2; e++) {
            const fmpz_poly_struct *f = e ? f1 : f0;
            if (k > fmpz_poly_degree(f)) continue;
            tsu_addmul(re, A, (ulong) k, (ulong) e, f->coeffs + k, ctx);
            tsu_addmul(im, B, (ulong) k, (ulong) e, f->coeffs + k, ctx);
        }
        /* (A + i B)(-1 + i u) = (-A - u B) + i (u A - B) */
        fmpz_poly_mul(t, u, B);
        fmpz_poly_add(t, t, A);
        fmpz_poly_mul(A, u, A);
        fmpz_poly_sub(B, A, B);
        fmpz_poly_neg(A, t);
    }
    fmpz_mpoly_mul(acc, re, re, ctx);
    fmpz_mpoly_mul(re, im, im, ctx);
    fmpz_mpoly_add(acc, acc, re, ctx);
    rs_qd_mpoly_reduce(acc, 1, d, ctx);
    fmpz_poly_clear(A); fmpz_poly_clear(B); fmpz_poly_clear(t); fmpz_poly_clear(u);
    fmpz_mpoly_clear(re, ctx); fmpz_mpoly_clear(im, ctx);
}

/* the critical polynomial over Q of c0(u) + sqrt(d) c1(u) (c in Z[r, u] after
 * reduction, no s): its norm c0^2 - d c1^2, whose real roots hold c's */
static void qd_norm_u(fmpz_poly_t out, const fmpz_mpoly_t c, slong d, const fmpz_mpoly_ctx_t ctx)
{
    rs_qdpoly_t q;
    fmpq_poly_t n;
    fmpz_poly_t ck;
    fmpz_mpoly_t h;
    ulong k;
    slong v = 1;
    rs_qdpoly_init(q); fmpq_poly_init(n); fmpz_poly_init(ck);
    fmpz_mpoly_init(h, ctx);
    for (k = 0; k < 2; k++) {
        fmpz_mpoly_get_coeff_vars_ui(h, c, &v, &k, 1, ctx);
        mpoly_univar(ck, h, 2, ctx);
        fmpq_poly_set_fmpz_poly(k ? q->p1 : q->p0, ck);
    }
    rs_qdpoly_norm(n, q, d);
    fmpq_poly_get_numerator(out, n);   /* integer coefficients: n's denominator is 1 */
    rs_qdpoly_clear(q); fmpq_poly_clear(n); fmpz_poly_clear(ck);
    fmpz_mpoly_clear(h, ctx);
}

typedef struct {
    const fmpz_mpoly_struct *G;
    const fmpz_mpoly_ctx_struct *ctx;
    const rs_qdpoly_struct *N, *D;
    slong d;
} ray_qd_t;

typedef struct { const rs_qdpoly_struct *f; slong d; } qd_at_t;

static int qdpoly_neg_at(const void *f, const fmpq_t w)
{
    const qd_at_t *a = f;
    rs_qd_t v;
    int n;
    rs_qd_init(v);
    rs_qdpoly_evaluate_fmpq(v, a->f, w);
    n = rs_qd_sgn(v, a->d) < 0;
    rs_qd_clear(v);
    return n;
}

/* over Q(sqrt d): -H(w^2, u0) >= 0 for every real w (rs_qdpoly_nonneg_real),
 * the point verdict from |D(z0)|^2 - |N(z0)|^2 exactly, which must agree with
 * Schur-Cohn and the certified root (rs_qd_onestep_stable_at; exit 3) */
static int ray_test_qd(int *out, fmpq_t zr, fmpq_t zi, rs_status_t *st, const fmpq_t u0, void *data,
                       rs_error_t err)
{
    ray_qd_t *D = data;
    rs_qdpoly_t f;
    rs_qd_t c, v;
    fmpq_t w0, a;
    slong t;
    int r = RS_OK;
    rs_qdpoly_init(f);
    rs_qd_init(c); rs_qd_init(v);
    fmpq_init(w0); fmpq_init(a);
    for (t = 0; t < fmpz_mpoly_length(D->G, D->ctx); t++) {
        ulong ex[3];
        fmpz_t q;
        fmpz_init(q);
        fmpz_mpoly_get_term_coeff_fmpz(q, D->G, t, D->ctx);
        fmpz_mpoly_get_term_exp_ui(ex, D->G, t, D->ctx);
        fmpq_pow_si(a, u0, (slong) ex[2]);
        fmpq_mul_fmpz(a, a, q);
        rs_qdpoly_get_coeff(c, f, 2 * (slong) ex[0]);
        fmpq_sub(ex[1] ? c->y : c->x, ex[1] ? c->y : c->x, a);
        rs_qdpoly_set_coeff(f, 2 * (slong) ex[0], c);
        fmpz_clear(q);
    }
    *out = !rs_qdpoly_nonneg_real(f, D->d, w0);
    if (*out) {
        qd_at_t at;
        rs_qdc_struct *nd = rs_qdc_vec_init(2);
        int sg, sc;
        at.f = f;
        at.d = D->d;
        off_zero(w0, qdpoly_neg_at, &at);
        fmpq_mul(zr, w0, w0);
        fmpq_mul(zi, zr, u0);
        fmpq_neg(zr, zr);
        rs_qdpoly_evaluate_cx(nd, D->N, zr, zi, D->d);
        rs_qdpoly_evaluate_cx(nd + 1, D->D, zr, zi, D->d);
        rs_qdc_abs2(c, nd + 1, D->d);
        rs_qdc_abs2(v, nd, D->d);
        sg = rs_qd_is_zero(c) ? 2 : (rs_qd_sub(c, c, v), rs_qd_sgn(c, D->d));
        sc = rs_qd_onestep_stable_at(D->N, D->D, D->d, zr, zi);
        if (sc == -2 || (sg == 2) != (sc == -1) || (sg != 2 && (sg > 0) != (sc == 1)))
            r = rs_error_set(err, RS_ERR_INCONSISTENT, "astability over Q(sqrt d): |R|^2, Schur-Cohn and the "
                             "certified root disagree on the ray%s", "");
        *st = sg == 2 ? RS_STATUS_SINGULAR : sg > 0 ? RS_STATUS_STABLE : sg == 0 ? RS_STATUS_MARGINAL
            : RS_STATUS_UNSTABLE;
        rs_qdc_vec_clear(nd, 2);
    }
    rs_qdpoly_clear(f);
    rs_qd_clear(c); rs_qd_clear(v);
    fmpq_clear(w0); fmpq_clear(a);
    return r;
}

/* the common denominator's multiple of f0 + r f1 in Z[z] */
static void qd_scaled(fmpz_poly_t out, const fmpq_poly_t f, const fmpz_t den)
{
    fmpq_poly_t t;
    fmpq_poly_init(t);
    fmpq_poly_scalar_mul_fmpz(t, f, den);
    fmpq_poly_get_numerator(out, t);
    fmpq_poly_clear(t);
}

int rs_an_astability_alpha_qd(json_t **out, json_t **ev, arb_t deg, int *inside, const rs_qdpoly_t N,
                              const rs_qdpoly_t D, slong d, rs_error_t err)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t G, T, c;
    fmpz_poly_t f0, f1, cu;
    fmpz_t den;
    rs_alg_t *crit = NULL;
    slong ncrit = 0, ds, i, vs = 0;
    int r = RS_OK;
    ray_qd_t data;
    *out = NULL;
    *ev = NULL;
    *inside = -1;
    fmpz_mpoly_ctx_init(ctx, 3, ORD_LEX);
    fmpz_mpoly_init(G, ctx); fmpz_mpoly_init(T, ctx); fmpz_mpoly_init(c, ctx);
    fmpz_poly_init(f0); fmpz_poly_init(f1); fmpz_poly_init(cu);
    fmpz_init(den);
    /* one denominator for N and D: |R| does not change */
    fmpz_lcm(den, fmpq_poly_denref(N->p0), fmpq_poly_denref(N->p1));
    fmpz_lcm(den, den, fmpq_poly_denref(D->p0));
    fmpz_lcm(den, den, fmpq_poly_denref(D->p1));
    qd_scaled(f0, N->p0, den);
    qd_scaled(f1, N->p1, den);
    ray_norm_qd(G, f0, f1, d, ctx);
    qd_scaled(f0, D->p0, den);
    qd_scaled(f1, D->p1, den);
    ray_norm_qd(T, f0, f1, d, ctx);
    ds = ray_difference(G, T, ctx);
    if (ds < 0) goto done;
    /* the critical values of u as over Q, each from the norm of its
     * polynomial over Q(sqrt d) (the discriminant computed with r a
     * variable, then reduced: it is a polynomial in the coefficients) */
    for (i = 0; i < 3; i++) {
        if (i == 0) {
            if (ds < 2) continue;
            if (!fmpz_mpoly_discriminant(c, G, 0, ctx)) goto done;
            rs_qd_mpoly_reduce(c, 1, d, ctx);
            if (fmpz_mpoly_is_zero(c, ctx)) goto done;
        } else {
            ulong k = i == 1 ? (ulong) ds : 0;
            fmpz_mpoly_get_coeff_vars_ui(c, G, &vs, &k, 1, ctx);
        }
        qd_norm_u(cu, c, d, ctx);
        rs_alg_roots_append(&crit, &ncrit, cu, 0);
    }
    data.G = G;
    data.ctx = ctx;
    data.N = N;
    data.D = D;
    data.d = d;
    r = alpha_cells(out, ev, deg, inside, crit, ncrit, ray_test_qd, &data,
                    "one-step method over Q(sqrt d): rays z = -s (1 - i u), u = tan|arg(-z)|; |N|^2 - |D|^2 = G0 + "
                    "sqrt(d) G1 on them, its critical u (the real roots of the norms c0^2 - d c1^2 of the discriminant "
                    "and end coefficients in s), each cell between them decided exactly over Q(sqrt d) at a rational u",
                    err);
done:
    for (i = 0; i < ncrit; i++) rs_alg_clear(crit + i);
    free(crit);
    fmpz_poly_clear(f0); fmpz_poly_clear(f1); fmpz_poly_clear(cu);
    fmpz_clear(den);
    fmpz_mpoly_clear(G, ctx); fmpz_mpoly_clear(T, ctx); fmpz_mpoly_clear(c, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    return r;
}

/* ---- A(alpha) of any method: the rays against the boundary curves ------------- */

/* q(i t, z) = A + i B on the ray z = s w, w = -1 + i sg u (sg = +-1), q the
 * bilinear transform (1 - i t)^n p((1 + i t)/(1 - i t), z); ctx: t, s, u */
static void ray_bilinear(fmpz_mpoly_t A, fmpz_mpoly_t B, const zpoly_t *P, int sg, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_poly_t wr, wi, t, su, cb;
    fmpz_t c;
    slong k, a;
    int part;
    fmpz_poly_init(wr); fmpz_poly_init(wi); fmpz_poly_init(t); fmpz_poly_init(su); fmpz_poly_init(cb);
    fmpz_init(c);
    fmpz_mpoly_zero(A, ctx);
    fmpz_mpoly_zero(B, ctx);
    fmpz_poly_set_coeff_si(su, 1, sg);
    fmpz_poly_one(wr);
    for (k = 0; k <= P->K; k++) {
        for (part = 0; part < 2; part++) {
            bilinear_n(cb, (part ? P->Ci : P->C) + k, P->n);
            for (a = 0; a <= fmpz_poly_degree(cb); a++) {
                /* cb_a i^r (wr + i wi), r = a + part */
                slong r = (a + part) % 4;
                fmpz_set(c, cb->coeffs + a);
                if (r >= 2) fmpz_neg(c, c);
                if (r % 2 == 0) {
                    tsu_addmul(A, wr, (ulong) a, (ulong) k, c, ctx);
                    tsu_addmul(B, wi, (ulong) a, (ulong) k, c, ctx);
                } else {   /* i (wr + i wi) = -wi + i wr */
                    tsu_addmul(B, wr, (ulong) a, (ulong) k, c, ctx);
                    fmpz_neg(c, c);
                    tsu_addmul(A, wi, (ulong) a, (ulong) k, c, ctx);
                }
            }
        }
        /* (wr + i wi)(-1 + i sg u) = (-wr - sg u wi) + i (sg u wr - wi) */
        fmpz_poly_mul(t, su, wi);
        fmpz_poly_add(t, t, wr);
        fmpz_poly_mul(wr, su, wr);
        fmpz_poly_sub(wi, wr, wi);
        fmpz_poly_neg(wr, t);
    }
    fmpz_poly_clear(wr); fmpz_poly_clear(wi); fmpz_poly_clear(t); fmpz_poly_clear(su); fmpz_poly_clear(cb);
    fmpz_clear(c);
}

/* the curves in (s, u) where a root of p meets the unit circle on the rays:
 * Res_t(A, B), and with a common factor G of A and B (roots staying on the
 * circle) disc_t G and lc_t G; p(-1, z) = 0 (t = inf) from the t^n
 * coefficients of A and B */
static void ray_boundary(rs_plist_t *L, const fmpz_mpoly_t A0, const fmpz_mpoly_t B0, slong n,
                         const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t A, B, G, R, c1, c2;
    slong v = 0;
    ulong e;
    fmpz_mpoly_init(A, ctx); fmpz_mpoly_init(B, ctx); fmpz_mpoly_init(G, ctx);
    fmpz_mpoly_init(R, ctx); fmpz_mpoly_init(c1, ctx); fmpz_mpoly_init(c2, ctx);
    fmpz_mpoly_set(A, A0, ctx);
    fmpz_mpoly_set(B, B0, ctx);
    circle_curves(L, A, B, ctx);
    /* lambda = -1: both t^n coefficients vanish (a curve: their gcd; points: their resultant in s) */
    e = (ulong) n;
    fmpz_mpoly_get_coeff_vars_ui(c1, A0, &v, &e, 1, ctx);
    fmpz_mpoly_get_coeff_vars_ui(c2, B0, &v, &e, 1, ctx);
    if (fmpz_mpoly_is_zero(c1, ctx) || fmpz_mpoly_is_zero(c2, ctx)) rs_plist_add(L, fmpz_mpoly_is_zero(c1, ctx) ? c2 : c1, -1, NULL, ctx);
    else if (fmpz_mpoly_gcd(G, c1, c2, ctx)) {
        rs_plist_add(L, G, -1, NULL, ctx);
        fmpz_mpoly_divexact(c1, c1, G, ctx);
        fmpz_mpoly_divexact(c2, c2, G, ctx);
        if (fmpz_mpoly_degree_si(c1, 1, ctx) + fmpz_mpoly_degree_si(c2, 1, ctx) >= 1
            && fmpz_mpoly_resultant(R, c1, c2, 1, ctx)) rs_plist_add(L, R, -1, NULL, ctx);
    }
    fmpz_mpoly_clear(A, ctx); fmpz_mpoly_clear(B, ctx); fmpz_mpoly_clear(G, ctx);
    fmpz_mpoly_clear(R, ctx); fmpz_mpoly_clear(c1, ctx); fmpz_mpoly_clear(c2, ctx);
}

/* exact status at z = s0 (-1 + i sg u0), that point into (zr, zi) */
static int ray_status(rs_status_t *st, const zpoly_t *P, const fmpq_t s0, const fmpq_t u0, int sg, fmpq_t zr,
                      fmpq_t zi, rs_error_t err)
{
    fmpq_neg(zr, s0);
    fmpq_mul(zi, s0, u0);
    if (sg < 0) fmpq_neg(zi, zi);
    return status_at(st, P, zr, zi, err);
}

/* Is the ray u = u0 (z = s (-1 + i sg u0), s > 0) in the region?  The
 * status changes along it only at the positive roots in s of the curves
 * (cyl: those of degree >= 1 in s), so one rational s per interval between
 * them decides it.  *bad = 1 with (zr, zi) and *st a point that is not. */
static int ray_decide(int *bad, rs_status_t *st, fmpq_t zr, fmpq_t zi, const zpoly_t *P, const rs_plist_t *cyl,
                      const fmpq_t u0, int sg, const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    rs_alg_t *rts = NULL, zero;
    slong nr = 0, i, k;
    fmpz_mpoly_t f;
    fmpz_poly_t g;
    int r = RS_OK;
    fmpz_mpoly_init(f, ctx);
    fmpz_poly_init(g);
    rs_alg_init(&zero);
    zero.rational = 1;
    for (i = 0; i < cyl->n; i++) {
        rs_an_forall_subst(f, cyl->p + i, 2, u0, ctx);
        mpoly_univar(g, f, 1, ctx);
        rs_alg_roots_append(&rts, &nr, g, 0);
    }
    ralg_sort(rts, &nr);
    /* the positive roots only: samples from (0, first) on */
    k = first_positive(rts, nr, 128);
    *bad = 0;
    for (i = k; i <= nr && !*bad && r == RS_OK; i++) {
        fmpq_t s0;
        fmpq_init(s0);
        rational_between(s0, i == k ? &zero : rts + i - 1, i == nr ? NULL : rts + i);
        r = ray_status(st, P, s0, u0, sg, zr, zi, err);
        if (r == RS_OK && !bounded(*st)) *bad = 1;
        if (r == RS_OK) r = rs_budget_check(err, "astability");
        fmpq_clear(s0);
    }
    for (i = 0; i < nr; i++) rs_alg_clear(rts + i);
    free(rts);
    rs_alg_clear(&zero);
    fmpz_mpoly_clear(f, ctx);
    fmpz_poly_clear(g);
    return r;
}

/* A(alpha) of any p(lambda, z) over Q(i): on the rays z = s (-1 + i sg u),
 * s > 0, u >= 0 (sg = -1 too when a coefficient is not real: only then
 * need the region not be symmetric about the real axis), a root crosses the unit circle only on the curves of
 * ray_boundary; whether a ray has a point outside the region changes only
 * at the critical u of their projection in s (leading coefficients,
 * discriminants, pairwise resultants, values at s = 0: rs_proj_eliminate,
 * as in `region ... for all`).  Each u-cell is decided at a rational u0 by
 * ray_decide (exact statuses, complex Schur-Cohn checked by Bilharz).
 * tan(alpha) is the left end of the first cell with a point outside (0 if
 * it is the first), that point is the evidence.  The rays at the critical
 * values themselves lie in the closure of the cells' rays; a repeated root
 * on the circle at an isolated point there is not looked for.  *inside: 1
 * every ray of Re z < 0 in the region, 0 not (*out the angle). */
static int alpha_general(json_t **out, json_t **ev, arb_t deg, int *inside, const zpoly_t *P, rs_run_t *run)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t A, B;
    rs_bound_t dom[3];
    rs_alg_t best, zero;
    int sg, r = RS_OK, have = 0, first_cell = 0, cx = 0;
    slong ncells = 0, ncritall = 0, prec = 256, k;
    fmpq_t bzr, bzi;
    rs_status_t bst = RS_STATUS_STABLE;
    *out = NULL;
    *ev = NULL;
    *inside = 1;
    fmpz_mpoly_ctx_init(ctx, 3, ORD_LEX);
    fmpz_mpoly_init(A, ctx); fmpz_mpoly_init(B, ctx);
    rs_bounds_init(dom, 3);
    dom[1].has_lo = 1; fmpq_zero(dom[1].lo);              /* s > 0 */
    dom[2].has_lo = 1; dom[2].lo_closed = 1; fmpq_zero(dom[2].lo);   /* u >= 0 */
    rs_alg_init(&best); rs_alg_init(&zero);
    zero.rational = 1;
    fmpq_init(bzr); fmpq_init(bzi);
    for (k = 0; k <= P->K; k++) cx |= !fmpz_poly_is_zero(P->Ci + k);
    for (sg = 1; sg >= (cx ? -1 : 1) && r == RS_OK; sg -= 2) {
        rs_plist_t L, cyl, U;
        rs_alg_t *crit = NULL;
        slong ncrit = 0, i, first;
        rs_plist_init(&L); rs_plist_init(&cyl); rs_plist_init(&U);
        ray_bilinear(A, B, P, sg, ctx);
        ray_boundary(&L, A, B, P->n, ctx);
        /* curves in s (the factor s itself never vanishes on a ray); u-only factors are critical values */
        for (i = 0; i < L.n; i++) {
            fmpz_mpoly_struct *f = L.p + i;
            if (fmpz_mpoly_degree_si(f, 1, ctx) >= 1) {
                if (!(fmpz_mpoly_length(f, ctx) == 1 && fmpz_mpoly_total_degree_si(f, ctx) == 1))
                    rs_plist_add(&cyl, f, -1, NULL, ctx);
            } else rs_plist_add(&U, f, -1, NULL, ctx);
        }
        r = rs_proj_eliminate(&U, run, &cyl, 1, dom + 1, 2, dom, ctx);
        for (i = 0; i < U.n && r == RS_OK; i++) {
            fmpz_poly_t g;
            if (fmpz_mpoly_degree_si(U.p + i, 2, ctx) < 1 || fmpz_mpoly_degree_si(U.p + i, 1, ctx) > 0) continue;
            fmpz_poly_init(g);
            mpoly_univar(g, U.p + i, 2, ctx);
            rs_alg_roots_append(&crit, &ncrit, g, 0);
            fmpz_poly_clear(g);
        }
        ralg_sort(crit, &ncrit);
        first = first_positive(crit, ncrit, prec);
        ncritall += ncrit - first;
        for (i = first; i <= ncrit && r == RS_OK; i++) {
            fmpq_t u0, zr, zi;
            rs_status_t st;
            int bad;
            /* past the angle found on the other side: nothing smaller here */
            if (have && i > first && rs_alg_cmp(crit + i - 1, &best) >= 0) break;
            fmpq_init(u0); fmpq_init(zr); fmpq_init(zi);
            rational_between(u0, i == first ? &zero : crit + i - 1, i == ncrit ? NULL : crit + i);
            r = ray_decide(&bad, &st, zr, zi, P, &cyl, u0, sg, ctx, run->err);
            ncells++;
            if (r == RS_OK && bad) {
                *inside = 0;
                have = 1;
                fmpq_set(bzr, zr); fmpq_set(bzi, zi);
                bst = st;
                first_cell = (i == first);
                rs_alg_set(&best, first_cell ? &zero : crit + i - 1);
            }
            fmpq_clear(u0); fmpq_clear(zr); fmpq_clear(zi);
            if (r == RS_OK && bad) break;
        }
        for (i = 0; i < ncrit; i++) rs_alg_clear(crit + i);
        free(crit);
        rs_plist_clear(&L, ctx); rs_plist_clear(&cyl, ctx); rs_plist_clear(&U, ctx);
    }
    if (r == RS_OK) {
        const char *route = "any method: rays z = -s (1 - i u), u = tan|arg(-z)|; the curves in (s, u) where a root "
                            "meets the unit circle (resultant of the bilinear transform's real and imaginary parts "
                            "in t, lambda = -1), their critical u (projection in s), each u-cell decided exactly "
                            "at a rational u on rational points of its ray";
        *ev = json_pack("{s:s,s:I,s:I}", "route", route, "critical_u", (json_int_t) ncritall, "cells_decided",
                        (json_int_t) ncells);
        if (have) {
            json_object_set_new(*ev, "first_point_outside", json_pack("{s:o,s:o,s:s}", "re", rs_json_fmpq(bzr), "im",
                                rs_json_fmpq(bzi), "status", rs_status_name(bst)));
            if (first_cell) { *out = json_integer(0); arb_zero(deg); }
            else *out = alpha_of_tan(deg, &best, prec);
        } else arb_set_ui(deg, 90);
    }
    rs_alg_clear(&best); rs_alg_clear(&zero);
    fmpq_clear(bzr); fmpq_clear(bzi);
    rs_bounds_clear(dom, 3);
    fmpz_mpoly_clear(A, ctx); fmpz_mpoly_clear(B, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    return r;
}

/* alpha_degrees (exact), its approximation, its ball and its evidence into
 * o; the ball into have (the next route is compared with it) */
static void alpha_set(json_t *o, arb_t have, json_t *exact, const arb_t deg, json_t *evidence)
{
    char *ds = rs_radius_arb_str(deg, 15);
    json_object_set(o, "alpha_degrees", exact);
    json_object_set_new(o, "alpha_degrees_approx", json_real(arf_get_d(arb_midref(deg), ARF_RND_NEAR)));
    json_object_set_new(o, "alpha_degrees_certified", json_string(ds));
    if (evidence != NULL) json_object_set(o, "alpha_evidence", evidence);
    json_object_del(o, "alpha_note");
    arb_set(have, deg);
    flint_free(ds);
}

/* ---- request ------------------------------------------------------------------ */

int rs_an_astability_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *rest = rs_req_skip_blanks(req->rest), *t;
    char name[80];
    req->u.astab.param = -1;
    if (*rest == '\0') {
        if (run->c->nparams == 1) { req->u.astab.param = 0; return RS_OK; }
        {
            /* the one parameter declared complex (param z complex) */
            slong i, nc = 0, last = -1;
            for (i = 0; i < run->c->nparams; i++)
                if (run->c->params[i].complex) { nc++; last = i; }
            if (nc == 1) { req->u.astab.param = last; return RS_OK; }
        }
        {
            slong i, nfree = 0, last = -1;
            for (i = 0; i < run->c->nparams; i++) {
                slong k;
                int set = 0;
                for (k = 0; k < run->c->nsets; k++)
                    if (strcmp(run->c->sets[k].name, run->c->params[i].name) == 0) set = 1;
                if (!set) { nfree++; last = i; }
            }
            if (nfree == 1) { req->u.astab.param = last; return RS_OK; }
        }
        return rs_req_error(run, q, rest, RS_ERR_INPUT,
                            "expected the parameter that stands for z = h*lambda after astability%s", "");
    }
    t = rs_req_read_name(rest, name);
    if (t == NULL)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "expected a parameter name after astability, found '%s'", rest);
    req->u.astab.param = rs_case_param_index(run->c, name);
    if (req->u.astab.param < 0)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "'%s' is not a parameter", name);
    t = rs_req_skip_blanks(t);
    if (*t != '\0') return rs_req_error(run, q, t, RS_ERR_INPUT, "expected end of line, found '%s'", t);
    return RS_OK;
}

int rs_an_astability(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const char *name = run->c->params[req->u.astab.param].name;
    slong tv = req->u.astab.param, k;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    zpoly_t P;
    line_iv_t riv, iiv;
    fmpz_poly_t disc, disci, lc;
    json_t *o, *ev;
    int r, lin_decided = 0, lin_astable = 0, one_decided = 0, one_astable = 0, a_stable = -1, cx;
    rs_status_t st_m1 = RS_STATUS_UNSTABLE;
    fmpq_t zr, zi;
    fmpz_mpoly_struct *pre = NULL, *pim = NULL;
    json_t *alpha_one = NULL, *alpha_ev = NULL;   /* A(alpha) by the rays of a one-step method, its evidence */
    arb_t alpha_one_deg;
    json_t *alpha_gen = NULL, *gen_ev = NULL;     /* A(alpha) by the rays against the boundary curves */
    arb_t gen_deg;
    arb_t set_deg;   /* the ball of the alpha_degrees in o, once set: the later routes must overlap it */
    int gen_inside = 0, axes;
    if (run->m->qd != NULL) return rs_an_qd_astability(run, req);   /* R over Q(sqrt d) */
    if (rs_an_complex_mode(run)) {
        /* complex set values stay symbolic in the variant; rs_run_cx_poly substitutes them over Q(i) */
        const char *keep[1];
        rs_assign_t *a = NULL;
        slong na = 0;
        for (k = 0; k < run->c->ncsets; k++)
            if (strcmp(run->c->csets[k].name, name) == 0)
                return rs_req_error(run, q, req->rest, RS_ERR_INPUT, "astability: '%s' has a complex set value: "
                                    "z is the parameter without one", name);
        keep[0] = name;
        rs_run_assignments(run, &a, &na, keep, 1, NULL, 0);
        r = rs_run_variant(&v, run, a, na);
        rs_assign_free(a, na);
    } else r = rs_run_variant_one_free(&v, run, q, req->rest, tv, "astability");
    if (r != RS_OK) return r;
    s = v->s;
    cx = rs_an_complex_mode(run) || s->complex_char;
    if (cx) {
        /* p = re + i im over Q(i): every parameter but z must be a number now */
        char msg[300];
        pre = flint_malloc(sizeof(fmpz_mpoly_struct));
        pim = flint_malloc(sizeof(fmpz_mpoly_struct));
        fmpz_mpoly_init(pre, s->zctx); fmpz_mpoly_init(pim, s->zctx);
        P.n = rs_run_cx_poly(pre, pim, run, v);
        msg[0] = '\0';
        for (k = 0; k < s->nvars; k++) {
            if (k == s->lambda_var || k == tv) continue;
            if (fmpz_mpoly_degree_si(pre, k, s->zctx) <= 0 && fmpz_mpoly_degree_si(pim, k, s->zctx) <= 0) continue;
            if (strlen(msg) + strlen(s->vars[k]) + 3 < sizeof msg)
                sprintf(msg + strlen(msg), "%s%s", msg[0] ? ", " : "", s->vars[k]);
        }
        if (msg[0]) {
            fmpz_mpoly_clear(pre, s->zctx); fmpz_mpoly_clear(pim, s->zctx);
            flint_free(pre); flint_free(pim);
            return rs_req_error(run, q, req->rest, RS_ERR_INPUT, "astability needs the other parameters set to "
                                "numbers (real or complex); still symbolic: %s", msg);
        }
        P.K = FLINT_MAX(fmpz_mpoly_degree_si(pre, tv, s->zctx), fmpz_mpoly_degree_si(pim, tv, s->zctx));
    } else {
        P.K = fmpz_mpoly_degree_si(v->cp->p, tv, s->zctx);
        P.n = fmpz_mpoly_degree_si(v->cp->p, s->lambda_var, s->zctx);
    }
    if (P.K < 1 || P.n < 1) {
        if (cx) {
            fmpz_mpoly_clear(pre, s->zctx); fmpz_mpoly_clear(pim, s->zctx);
            flint_free(pre); flint_free(pim);
        }
        return rs_req_error(run, q, req->rest, RS_ERR_INPUT,
                            "astability: the characteristic polynomial must depend on '%s' and on lambda", name);
    }
    P.C = flint_malloc((P.K + 1) * sizeof(fmpz_poly_struct));
    P.Ci = flint_malloc((P.K + 1) * sizeof(fmpz_poly_struct));
    for (k = 0; k <= P.K; k++) {
        fmpz_poly_init(P.C + k);
        fmpz_poly_init(P.Ci + k);
        rs_run_coeff_in(P.C + k, cx ? pre : v->cp->p, tv, k, s);
        if (cx) rs_run_coeff_in(P.Ci + k, pim, tv, k, s);
    }
    if (cx) {
        fmpz_mpoly_clear(pre, s->zctx); fmpz_mpoly_clear(pim, s->zctx);
        flint_free(pre); flint_free(pim);
    }
    fmpz_poly_init(disc); fmpz_poly_init(disci); fmpz_poly_init(lc);
    fmpq_init(zr); fmpq_init(zi);
    arb_init(alpha_one_deg);
    arb_init(gen_deg);
    arb_init(set_deg);
    zdisc(disc, disci, &P);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("astability"));
    json_object_set_new(o, "param", json_string(name));
    if (cx) json_object_set_new(o, "over", json_string("Q(i)"));
    r = line_interval(&riv, &P, disc, disci, 0, run->err);
    if (r == RS_OK) r = line_interval(&iiv, &P, disc, disci, 1, run->err);
    else rs_alg_init(&iiv.lo), rs_alg_init(&iiv.hi);
    if (r != RS_OK) goto out;
    json_object_set_new(o, "real_interval", line_iv_json(&riv, name));
    json_object_set_new(o, "imag_interval", line_iv_json(&iiv, name));
    json_object_set_new(o, "real_interval_detail", line_iv_detail(&riv));
    json_object_set_new(o, "imag_interval_detail", line_iv_detail(&iiv));
    fmpq_set_si(zr, -1, 1);
    r = status_line(&st_m1, &P, 0, zr, run->err);
    if (r != RS_OK) goto out;
    ev = json_array();
    /* route 1: p linear in z, the boundary locus z(t) = (X + i Y)/W */
    if (P.K == 1) {
        fmpz_poly_t q0, q1, a0, b0, a1, b1, X, Y, t1;
        fmpq_t t0, w;
        int xnonneg, infok = 1, lcok = 1;
        fmpz_poly_init(q0); fmpz_poly_init(q1); fmpz_poly_init(a0); fmpz_poly_init(b0);
        fmpz_poly_init(a1); fmpz_poly_init(b1); fmpz_poly_init(X); fmpz_poly_init(Y); fmpz_poly_init(t1);
        fmpq_init(t0); fmpq_init(w);
        bilinear_n(q0, P.C + 0, P.n);
        bilinear_n(q1, P.C + 1, P.n);
        bilinear_n(X, P.Ci + 0, P.n);
        bilinear_n(Y, P.Ci + 1, P.n);
        split_line_cx(a0, b0, q0, X, 1);
        split_line_cx(a1, b1, q1, Y, 1);
        fmpz_poly_mul(X, a0, a1);
        fmpz_poly_mul(t1, b0, b1);
        fmpz_poly_add(X, X, t1);
        fmpz_poly_neg(X, X);
        fmpz_poly_mul(Y, a0, b1);
        fmpz_poly_mul(t1, a1, b0);
        fmpz_poly_sub(Y, Y, t1);
        {
            char *p0 = cx_str(P.C + 0, P.Ci + 0, "lambda"), *p1 = cx_str(P.C + 1, P.Ci + 1, "lambda");
            char *buf = malloc(strlen(p0) + strlen(p1) + 120);
            sprintf(buf, "%s = -(%s)/(%s), lambda = exp(i*phi), 0 <= phi < 2*pi", name, p0, p1);
            json_object_set_new(o, "boundary_locus", json_string(buf));
            free(buf); free(p0); free(p1);
            p0 = poly_str(X, "t"); p1 = poly_str(Y, "t");
            json_object_set_new(o, "boundary_locus_t", json_pack("{s:s,s:s,s:s}", "t", "tan(phi/2)",
                                "re_numerator", p0, "im_numerator", p1));
            free(p0); free(p1);
        }
        /* lambda = -1 (t = inf): z_inf = -P0(-1)/P1(-1) must not lie in Re z < 0,
         * nor -lc(P0)/lc(P1), where the leading coefficient vanishes */
        {
            fmpz_t v0, v0i, v1, v1i;
            fmpz_init(v0); fmpz_init(v0i); fmpz_init(v1); fmpz_init(v1i);
            fmpz_poly_evaluate_fmpz(v0, P.C + 0, (fmpz_t) {-1});
            fmpz_poly_evaluate_fmpz(v0i, P.Ci + 0, (fmpz_t) {-1});
            fmpz_poly_evaluate_fmpz(v1, P.C + 1, (fmpz_t) {-1});
            fmpz_poly_evaluate_fmpz(v1i, P.Ci + 1, (fmpz_t) {-1});
            if (cx_neg_ratio(zr, zi, v0, v0i, v1, v1i)) infok = 0;
            fmpz_poly_get_coeff_fmpz(v0, P.C + 0, P.n);
            fmpz_poly_get_coeff_fmpz(v0i, P.Ci + 0, P.n);
            fmpz_poly_get_coeff_fmpz(v1, P.C + 1, P.n);
            fmpz_poly_get_coeff_fmpz(v1i, P.Ci + 1, P.n);
            if (cx_neg_ratio(w, t0, v0, v0i, v1, v1i)) lcok = 0;
            fmpz_clear(v0); fmpz_clear(v0i); fmpz_clear(v1); fmpz_clear(v1i);
        }
        xnonneg = nonneg_everywhere(X, t0);
        lin_decided = 1;
        lin_astable = xnonneg && infok && lcok && st_m1 == RS_STATUS_STABLE;
        {
            json_t *e = json_pack("{s:s,s:b,s:b,s:b,s:s}", "route", "boundary locus (p linear in z)",
                                  "re_locus_nonnegative", xnonneg, "lambda_minus_one_point_ok", infok,
                                  "leading_coefficient_zero_ok", lcok, "status_at_minus_one", rs_status_name(st_m1));
            if (!xnonneg) {
                /* z(t0) = (X + i Y)(t0) / W(t0), a boundary point with Re z < 0 */
                fmpq_t yv;
                fmpz_poly_t W;
                fmpq_init(yv);
                fmpz_poly_init(W);
                fmpz_poly_mul(W, a1, a1);
                fmpz_poly_mul(t1, b1, b1);
                fmpz_poly_add(W, W, t1);
                fmpz_poly_evaluate_fmpq(w, W, t0);
                fmpz_poly_evaluate_fmpq(zr, X, t0);
                fmpz_poly_evaluate_fmpq(yv, Y, t0);
                fmpq_div(zr, zr, w);
                fmpq_div(zi, yv, w);
                json_object_set_new(e, "t", rs_json_fmpq(t0));
                json_object_set_new(e, "counterexample", lhp_evidence(&P, zr, zi, run->err));
                fmpq_clear(yv);
                fmpz_poly_clear(W);
            } else if (!infok) {
                json_object_set_new(e, "counterexample", lhp_evidence(&P, zr, zi, run->err));
            }
            json_array_append_new(ev, e);
        }
        /* A(alpha) */
        if (st_m1 == RS_STATUS_STABLE) {
            if (lin_astable) {
                json_object_set_new(o, "alpha_degrees", json_integer(90));
                json_object_set_new(o, "alpha_degrees_approx", json_real(90.0));
                arb_set_ui(set_deg, 90);
            } else if (!infok || !lcok) {
                json_object_set_new(o, "alpha_degrees", json_integer(0));
                json_object_set_new(o, "alpha_degrees_approx", json_real(0.0));
                arb_zero(set_deg);
            } else {
                arb_t deg;
                int found;
                json_t *aj;
                arb_init(deg);
                aj = alpha_linear(X, Y, &found, deg);
                if (found && aj != NULL) {
                    char *ds = rs_radius_arb_str(deg, 15);
                    json_object_set_new(o, "alpha_degrees", aj);
                    json_object_set_new(o, "alpha_degrees_approx", json_real(arf_get_d(arb_midref(deg), ARF_RND_NEAR)));
                    json_object_set_new(o, "alpha_degrees_certified", json_string(ds));
                    arb_set(set_deg, deg);
                    flint_free(ds);
                } else {
                    json_decref(aj);
                    json_object_set_new(o, "alpha_degrees", json_null());
                    json_object_set_new(o, "alpha_degrees_approx", json_null());
                }
                arb_clear(deg);
            }
        } else {
            json_object_set_new(o, "alpha_degrees", json_null());
            json_object_set_new(o, "alpha_degrees_approx", json_null());
            json_object_set_new(o, "alpha_note", json_string("z = -1 is not stable: no sector |arg(-z)| < alpha lies in the region"));
        }
        fmpz_poly_clear(q0); fmpz_poly_clear(q1); fmpz_poly_clear(a0); fmpz_poly_clear(b0);
        fmpz_poly_clear(a1); fmpz_poly_clear(b1); fmpz_poly_clear(X); fmpz_poly_clear(Y); fmpz_poly_clear(t1);
        fmpq_clear(t0); fmpq_clear(w);
    } else {
        char *pp = cx ? zpoly_str(&P, name) : rs_polyfmt_fmpz_mpoly(v->cp->p, (const char **) s->vars, s->zctx);
        char *buf = malloc(strlen(pp) + 120);
        sprintf(buf, "p(lambda, %s) = 0 with lambda = exp(i*phi), p = %s", name, pp);
        json_object_set_new(o, "boundary_locus", json_string(buf));
        free(buf);
        free(pp);
    }
    /* route 2: one-step methods p = D(z) lambda - N(z): E(y) >= 0 and poles in Re z > 0 */
    if (P.n == 1) {
        fmpz_poly_t D, N, Di, Ni, dr, di, nr, ni, E, t1, Dt;
        fmpq_t y0;
        rs_rootcount_t rc;
        int enonneg, poles_ok = 1;
        fmpz_poly_init(D); fmpz_poly_init(N); fmpz_poly_init(dr); fmpz_poly_init(di); fmpz_poly_init(nr);
        fmpz_poly_init(ni); fmpz_poly_init(E); fmpz_poly_init(t1); fmpz_poly_init(Dt);
        fmpz_poly_init(Di); fmpz_poly_init(Ni);
        fmpq_init(y0);
        rs_rootcount_init(rc);
        zcoeff(D, Di, &P, 1);
        zcoeff(N, Ni, &P, 0);
        split_line_cx(dr, di, D, Di, 1);
        split_line_cx(nr, ni, N, Ni, 1);
        fmpz_poly_mul(E, dr, dr);
        fmpz_poly_mul(t1, di, di); fmpz_poly_add(E, E, t1);
        fmpz_poly_mul(t1, nr, nr); fmpz_poly_sub(E, E, t1);
        fmpz_poly_mul(t1, ni, ni); fmpz_poly_sub(E, E, t1);
        enonneg = nonneg_everywhere(E, y0);
        if (!fmpz_poly_is_zero(Di)) {
            /* D over Q(i): the same map, its image decided by complex Schur-Cohn and Bilharz */
            slong m = FLINT_MAX(fmpz_poly_degree(D), fmpz_poly_degree(Di));
            fmpq_poly_t ar, ai;
            rs_status_t dst;
            fmpq_poly_init(ar); fmpq_poly_init(ai);
            bilinear_n(Dt, D, m);
            fmpq_poly_set_fmpz_poly(ar, Dt);
            bilinear_n(Dt, Di, m);
            fmpq_poly_set_fmpz_poly(ai, Dt);
            if (m >= 1) {
                if (FLINT_MAX(fmpq_poly_degree(ar), fmpq_poly_degree(ai)) < m) poles_ok = 0;   /* a pole at z = -1 */
                else if ((r = rs_routh_complex_checked_status(&dst, ar, ai, m, run->err)) == RS_OK)
                    poles_ok = dst == RS_STATUS_STABLE;
            }
            fmpq_poly_clear(ar); fmpq_poly_clear(ai);
            if (r != RS_OK) goto one_out;
        } else if (fmpz_poly_degree(D) >= 1) {
            /* z in Re z > 0 <=> w = (z - 1)/(z + 1) inside the unit disc: D((1+w)/(1-w)) (1-w)^m */
            bilinear_n(Dt, D, fmpz_poly_degree(D));
            if (fmpz_poly_degree(Dt) < fmpz_poly_degree(D)) poles_ok = 0;   /* a pole at z = -1 */
            else if ((r = rs_rootcount_factor(rc, Dt, run->err)) != RS_OK) goto one_out;
            else poles_ok = rc->inside == rc->degree;
        }
        one_decided = 1;
        one_astable = enonneg && poles_ok;
        /* A(alpha) by the rays (real coefficients), cross-checked with A-stability */
        if (fmpz_poly_is_zero(Di) && fmpz_poly_is_zero(Ni)) {
            int inside;
            if ((r = alpha_onestep(&alpha_one, &alpha_ev, alpha_one_deg, &inside, &P, D, N, run->err)) != RS_OK) goto one_out;
            if (r == RS_OK && inside >= 0 && inside != one_astable) {
                r = rs_req_relocate(run, q, rs_error_set(run->err, RS_ERR_INCONSISTENT, "the E-polynomial and the "
                                    "rays of A(alpha) disagree on A-stability"), "astability");
                goto one_out;
            }
        }
        {
            char *es = poly_str(E, "y");
            json_t *e = json_pack("{s:s,s:s,s:b,s:b}", "route", "E-polynomial (one-step method)", "E", es,
                                  "E_nonnegative", enonneg, "poles_in_right_half_plane", poles_ok);
            free(es);
            if (!enonneg) json_object_set_new(e, "counterexample_imag", rs_json_fmpq(y0));
            json_array_append_new(ev, e);
        }
    one_out:
        rs_rootcount_clear(rc);
        fmpz_poly_clear(D); fmpz_poly_clear(N); fmpz_poly_clear(dr); fmpz_poly_clear(di); fmpz_poly_clear(nr);
        fmpz_poly_clear(ni); fmpz_poly_clear(E); fmpz_poly_clear(t1); fmpz_poly_clear(Dt);
        fmpz_poly_clear(Di); fmpz_poly_clear(Ni);
        fmpq_clear(y0);
        if (r != RS_OK) { json_decref(ev); goto out; }
    }
    if (lin_decided && one_decided && lin_astable != one_astable) {
        json_decref(ev);
        r = rs_req_relocate(run, q, rs_error_set(run->err, RS_ERR_INCONSISTENT,
                            "the boundary locus and the E-polynomial disagree on A-stability"), "astability");
        goto out;
    }
    /* route 3, any method: the rays of the open left half-plane (they need the whole negative real axis) */
    if (!riv.empty && riv.lo_inf) {
        if ((r = alpha_general(&alpha_gen, &gen_ev, gen_deg, &gen_inside, &P, run)) != RS_OK) {
            json_decref(ev);
            goto out;
        }
        json_object_set_new(gen_ev, "every_ray_inside", json_boolean(gen_inside));
        json_array_append(ev, gen_ev);
    }
    /* A-stable: the whole closed left half-plane is bounded, so are both axes' halves */
    axes = !iiv.empty && iiv.lo_inf && iiv.hi_inf && !riv.empty && riv.lo_inf;
    if (lin_decided || one_decided) {
        a_stable = lin_decided ? lin_astable : one_astable;
        if (a_stable && !axes) {
            json_decref(ev);
            r = rs_req_relocate(run, q, rs_error_set(run->err, RS_ERR_INCONSISTENT,
                                "A-stable by the boundary locus, yet an axis interval is bounded"), "astability");
            goto out;
        }
        if (gen_ev != NULL && a_stable != (gen_inside && axes)) {
            json_decref(ev);
            r = rs_req_relocate(run, q, rs_error_set(run->err, RS_ERR_INCONSISTENT, "A-stability: the rays of the "
                                "left half-plane disagree with the %s", lin_decided ? "boundary locus" : "E-polynomial"),
                                "astability");
            goto out;
        }
        json_object_set_new(o, "a_stable", json_boolean(a_stable));
    } else {
        /* the rays decide the open half-plane, the imaginary interval the axis */
        a_stable = gen_ev != NULL && gen_inside && axes;
        json_object_set_new(o, "a_stable", json_boolean(a_stable));
        if (!a_stable)
            json_object_set_new(o, "a_stable_note", json_string(gen_ev == NULL
                ? "not A-stable: the real interval does not reach -inf"
                : !gen_inside ? "not A-stable: a ray of Re z < 0 leaves the region (alpha_evidence)"
                : "not A-stable: the imaginary interval is not the whole axis"));
    }
    if (alpha_one != NULL) {
        json_t *have = json_object_get(o, "alpha_degrees");
        if (have == NULL || json_is_null(have)) {
            alpha_set(o, set_deg, alpha_one, alpha_one_deg, alpha_ev);
        } else if (!arb_overlaps(set_deg, alpha_one_deg)) {
            /* both routes (p linear in z and one-step): the angles must agree */
            json_decref(ev);
            r = rs_req_relocate(run, q, rs_error_set(run->err, RS_ERR_INCONSISTENT, "A(alpha): the boundary "
                                "locus and the rays of the one-step method disagree"), "astability");
            goto out;
        }
    }
    if (gen_ev != NULL) {
        json_t *have = json_object_get(o, "alpha_degrees");
        if (have == NULL || json_is_null(have)) {
            if (alpha_gen != NULL) alpha_set(o, set_deg, alpha_gen, gen_deg, gen_ev);
            else {
                json_object_set_new(o, "alpha_degrees", json_integer(90));
                json_object_set_new(o, "alpha_degrees_approx", json_real(90.0));
                json_object_set(o, "alpha_evidence", gen_ev);
                json_object_del(o, "alpha_note");
            }
        } else if (!arb_overlaps(set_deg, gen_deg)) {
            /* the general route against the boundary locus or the one-step rays */
            json_decref(ev);
            r = rs_req_relocate(run, q, rs_error_set(run->err, RS_ERR_INCONSISTENT, "A(alpha): the rays against the "
                                "boundary curves disagree with the %s", alpha_one != NULL && !lin_decided
                                ? "rays of the one-step method" : "boundary locus"), "astability");
            goto out;
        } else json_object_set_new(gen_ev, "alpha_agrees", json_true());
    }
    if (riv.empty || !riv.lo_inf) {
        /* A(alpha) for any alpha >= 0 needs the whole negative real axis (A(0), Widlund) */
        json_object_set_new(o, "alpha_degrees", json_null());
        json_object_set_new(o, "alpha_degrees_approx", json_null());
        json_object_set_new(o, "alpha_note", json_string(
            "not A(0)-stable: the real interval does not reach -inf, so no sector |arg(-z)| < alpha lies in the region"));
        json_object_del(o, "alpha_degrees_certified");
    }
    if (!json_object_get(o, "alpha_degrees")) {
        json_object_set_new(o, "alpha_degrees", a_stable == 1 ? json_integer(90) : json_null());
        json_object_set_new(o, "alpha_degrees_approx", a_stable == 1 ? json_real(90.0) : json_null());
        if (a_stable != 1)
            json_object_set_new(o, "alpha_note", json_string(
                "A(alpha) is computed for methods linear in z (multistep) and one-step methods with real "
                "coefficients; not for this one"));
    }
    json_object_set_new(o, "evidence", ev);
    /* z -> inf: the roots of the top coefficient in z; fewer than n: some go to infinity */
    {
        /* over Q(i): c conj(c) = C^2 + Ci^2 has c's roots and their conjugates, the same moduli */
        fmpz_poly_t c, ct;
        json_t *lim;
        int l0 = 0;
        fmpz_poly_init(c); fmpz_poly_init(ct);
        fmpz_poly_mul(c, P.C + P.K, P.C + P.K);
        fmpz_poly_mul(ct, P.Ci + P.K, P.Ci + P.K);
        fmpz_poly_add(c, c, ct);
        if (fmpz_poly_is_zero(P.Ci + P.K)) fmpz_poly_set(c, P.C + P.K);
        if (FLINT_MAX(fmpz_poly_degree(P.C + P.K), fmpz_poly_degree(P.Ci + P.K)) < P.n) lim = json_string("inf");
        else {
            fmpz_poly_factor_t fac;
            arb_t m, ab;
            slong i, j;
            int all_rational = 1;
            fmpq_t best, x;
            fmpz_poly_factor_init(fac);
            arb_init(m); arb_init(ab);
            fmpq_init(best); fmpq_init(x);
            fmpz_poly_factor(fac, c);
            arb_zero(m);
            for (i = 0; i < fac->num; i++) {
                const fmpz_poly_struct *g = fac->p + i;
                slong d = fmpz_poly_degree(g);
                if (d == 1) {
                    fmpq_set_fmpz_frac(x, g->coeffs + 0, g->coeffs + 1);
                    fmpq_abs(x, x);
                    if (fmpq_cmp(x, best) > 0) fmpq_set(best, x);
                    arb_set_fmpq(ab, x, 128);
                    arb_max(m, m, ab, 128);
                } else if (d > 1) {
                    acb_ptr rt = _acb_vec_init(d);
                    all_rational = 0;
                    arb_fmpz_poly_complex_roots(rt, g, 0, 128);
                    for (j = 0; j < d; j++) { acb_abs(ab, rt + j, 128); arb_max(m, m, ab, 128); }
                    _acb_vec_clear(rt, d);
                }
            }
            if (all_rational) {
                rs_alg_t a;
                rs_alg_init(&a);
                a.rational = 1;
                fmpq_set(a.q, best);
                lim = rs_an_alg_end_json(&a, "r");
                l0 = fmpq_is_zero(best);
                rs_alg_clear(&a);
            } else {
                char *cs = cx_str(P.C + P.K, P.Ci + P.K, "lambda"), *ms = rs_radius_arb_str(m, 20);
                char *buf = malloc(strlen(cs) + 40);
                sprintf(buf, "max |root| of %s", cs);
                lim = json_pack("{s:s,s:f,s:s}", "exact", buf, "approx", arf_get_d(arb_midref(m), ARF_RND_NEAR),
                                "certified", ms);
                free(buf); free(cs); flint_free(ms);
            }
            fmpz_poly_factor_clear(fac);
            arb_clear(m); arb_clear(ab);
            fmpq_clear(best); fmpq_clear(x);
        }
        json_object_set_new(o, "limit_at_infinity", lim);
        json_object_set_new(o, "l_stable", a_stable == -1 ? json_null() : json_boolean(a_stable == 1 && l0));
        fmpz_poly_clear(c); fmpz_poly_clear(ct);
    }
    rs_run_emit_exact(run, v, o);
    if (rs_an_complex_mode(run)) json_object_update_new(json_object_get(o, "substituted"), rs_run_cx_at(run));
    o = NULL;
out:
    json_decref(o);
    line_iv_clear(&riv);
    line_iv_clear(&iiv);
    for (k = 0; k <= P.K; k++) { fmpz_poly_clear(P.C + k); fmpz_poly_clear(P.Ci + k); }
    flint_free(P.C);
    flint_free(P.Ci);
    fmpz_poly_clear(disc); fmpz_poly_clear(disci); fmpz_poly_clear(lc);
    fmpq_clear(zr); fmpq_clear(zi);
    json_decref(alpha_one);
    json_decref(alpha_ev);
    arb_clear(alpha_one_deg);
    json_decref(alpha_gen);
    json_decref(gen_ev);
    arb_clear(gen_deg);
    arb_clear(set_deg);
    return r;
}
