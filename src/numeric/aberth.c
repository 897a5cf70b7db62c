/* aberth.c -- Aberth-Ehrlich root approximations in hardware double,
 * started from Newton-polygon points (Bini 1996, "Numerical computation of
 * polynomial zeros by means of Aberth's method", Numer. Algorithms 13).
 * Uncertified: the caller certifies the result in Arb. */
/* before <complex.h>: FLINT's mpoly headers name parameters I */
#include "recstab/budget.h"
#include <complex.h>
#include <float.h>
#include <math.h>
#include <flint/fmpz.h>
#include "recstab/radius.h"

/* Bini's starting points: for each edge (i, j) of the upper convex hull of
 * (k, log|a_k|), j - i points on the circle of radius (|a_i|/|a_j|)^(1/(j-i))
 * (the moduli of that many roots are close to it), spread in angle. */
static void _rs_aberth_start(double complex *z, const double *a, slong d)
{
    slong *h = flint_malloc((d + 1) * sizeof(slong));
    double *y = flint_malloc((d + 1) * sizeof(double));
    slong nh = 0, i, k, idx = 0;

    for (i = 0; i <= d; i++) {
        if (a[i] == 0.0)
            continue;
        y[i] = log(fabs(a[i]));
        /* drop h[nh-1] while it lies on or below the chord h[nh-2] -> i */
        while (nh >= 2 && (y[h[nh - 1]] - y[h[nh - 2]]) * (double) (i - h[nh - 2])
                              <= (y[i] - y[h[nh - 2]]) * (double) (h[nh - 1] - h[nh - 2]))
            nh--;
        h[nh++] = i;
    }
    for (k = 0; k + 1 < nh; k++) {
        slong m = h[k + 1] - h[k];
        double r = exp((y[h[k]] - y[h[k + 1]]) / (double) m);
        for (i = 0; i < m; i++) {
            double t = 6.283185307179586 * ((double) i / (double) m + (double) h[k] / (double) d) + 0.4;
            z[idx++] = r * cexp(I * t);
        }
    }
    flint_free(h);
    flint_free(y);
}

/* Newton correction p(x)/p'(x) and whether |p(x)| is at the level of its
 * rounding error (a backward-stable root).  |x| > 1 evaluates the reversed
 * polynomial at 1/x so that x^d cannot overflow:
 * p(x) = x^d q(w), w = 1/x, p'/p = w (d - w q'(w)/q(w)). */
static double complex _rs_aberth_newton(int *conv, const double *a, slong d,
                                        double complex x)
{
    double complex p = 0, dp = 0, w;
    double s = 0, ax;
    slong i;

    if (cabs(x) <= 1.0) {
        ax = cabs(x);
        for (i = d; i >= 0; i--) {
            dp = dp * x + p;
            p = p * x + a[i];
            s = s * ax + fabs(a[i]);
        }
        *conv = cabs(p) <= 4.0 * DBL_EPSILON * (double) (d + 1) * s;
        return dp == 0 ? 0 : p / dp;
    }
    w = 1.0 / x;
    ax = cabs(w);
    for (i = 0; i <= d; i++) {
        dp = dp * w + p;
        p = p * w + a[i];
        s = s * ax + fabs(a[i]);
    }
    *conv = cabs(p) <= 4.0 * DBL_EPSILON * (double) (d + 1) * s;
    if (p == 0)
        return 0;
    return 1.0 / (w * ((double) d - w * dp / p));
}

int rs_radius_aberth_d(double *zr, const double *a, slong d, slong maxiter)
{
    double complex *z = flint_malloc(d * sizeof(double complex));
    char *done = flint_calloc(d, 1);
    slong it, i, j, left = d;
    int ok;

    _rs_aberth_start(z, a, d);
    for (it = 0; it < maxiter && left > 0; it++) {
        for (i = 0; i < d; i++) {
            double complex N, S = 0, c;
            int conv;
            if (done[i])
                continue;
            N = _rs_aberth_newton(&conv, a, d, z[i]);
            for (j = 0; j < d; j++)
                if (j != i)
                    S += 1.0 / (z[i] - z[j]);
            c = N / (1.0 - N * S);
            if (isfinite(creal(c)) && isfinite(cimag(c)))
                z[i] -= c;
            if (conv) {
                done[i] = 1;
                left--;
            }
        }
    }
    ok = left == 0;
    for (i = 0; i < d; i++) {
        zr[2 * i] = creal(z[i]);
        zr[2 * i + 1] = cimag(z[i]);
        if (!isfinite(zr[2 * i]) || !isfinite(zr[2 * i + 1]))
            ok = 0;
    }
    flint_free(z);
    flint_free(done);
    return ok ? (int) it : -1;
}

/* ------------------------------------------------------------------ */
/* Aberth-Ehrlich in Arb midpoints at a precision per root, then one
 * certification by inclusion discs (MPSolve's plan, Bini-Robol 2014).
 *
 * Each root i carries its own working precision w_i.  The bits a step can
 * gain are limited by the evaluation of p at z_i, whose rounding error is
 * about 2^-w S_i (S_i = sum |a_k| |z_i|^k) against |p'(z_i)|: the loss
 * L_i = log2(S_i / (|z_i| |p'(z_i)|)) is measured at every step from the
 * ball p'(z_i), and a root is carried only to goal_i + L_i (+ guard) bits.
 * Well-separated roots stop after a step or two at about goal_i + 20 bits;
 * only the roots of a cluster (large L_i) pay high precision, and only
 * they: the precision is per root, not per polynomial.  The Aberth sum
 * S = sum_j 1/(z_i - z_j) is formed in double from double copies of the
 * other approximations (it only steers the step, N / (1 - N S); near
 * convergence N S -> 0), except for the terms of approximations closer
 * than 2^-40 |z_i|, which double cannot separate: those are taken in Arb.
 *
 * Certification: each midpoint m_i gets the disc of radius d |p(m_i) /
 * p'(m_i)| at precision w_i (_acb_poly_root_inclusion: holds at least one
 * root); d pairwise disjoint discs hold exactly one root each. */

static double _rs_ab_log2sum(const double *a, slong d, double complex x)
{
    double ax = cabs(x), s = 0, w;
    slong i;
    if (ax <= 1.0) {
        for (i = d; i >= 0; i--)
            s = s * ax + fabs(a[i]);
        return log2(s);
    }
    w = 1.0 / ax;
    for (i = 0; i <= d; i++)
        s = s * w + fabs(a[i]);
    return log2(s) + (double) d * log2(ax);
}

static double _rs_ab_log2mag(const acb_t x)
{
    mag_t m;
    double r;
    mag_init(m);
    acb_get_mag(m, x);
    r = mag_is_zero(m) ? -1e300 : mag_get_d_log2_approx(m);
    mag_clear(m);
    return r;
}

static double complex _rs_ab_get_d(const acb_t x)
{
    return arf_get_d(arb_midref(acb_realref(x)), ARF_RND_NEAR)
           + I * arf_get_d(arb_midref(acb_imagref(x)), ARF_RND_NEAR);
}

typedef struct {
    acb_poly_t P;        /* f, exact */
    slong d;
    acb_ptr z;           /* approximations (exact midpoints) */
    double complex *zd;  /* their double copies */
    double *logS;        /* log2 sum |a_k| |z_i|^k */
    slong *w;            /* working precision per root */
    slong *goal;         /* bits wanted per root */
    double *loss;        /* measured L_i */
    double *rel;         /* log2 of the last step relative to |z_i| */
    char *done;
    slong wcap;          /* no root goes beyond this */
    slong nnz;           /* > 0: evaluate term by term, exponents in nz */
    slong *nz;
} _rs_ab_struct;

/* Horner for y = p(x), dy = p'(x) with exact coefficients and exact x,
 * the rounding errors carried as DISC radii: multiplying a ball by x in
 * Arb's rectangular form grows its radius by (|Re x| + |Im x|) / |x|, up
 * to sqrt 2, per step -- about d/2 bits lost at degree d (measured: the
 * radius of p(x) at 128 bits was 2^11 at degree 500, 2^-117 at 256).  Here
 * each step works on midpoints, and the error bound is r <- r |x| + (the
 * new rounding error), which a disc obeys exactly. */
void rs_radius_horner2(acb_t y, acb_t dy, acb_srcptr a, slong len, const acb_t x, slong w)
{
    acb_t u, v;
    mag_t ru, rv, e, ax;
    slong k;
    acb_init(u);
    acb_init(v);
    mag_init(ru);
    mag_init(rv);
    mag_init(e);
    mag_init(ax);
    acb_get_mag(ax, x);
    acb_set(u, a + len - 1);
    acb_zero(v);
    for (k = len - 2; k >= 0; k--) {
        acb_mul(v, v, x, w);
        acb_add(v, v, u, w);
        mag_mul(rv, rv, ax);
        mag_add(rv, rv, ru);
        mag_add(e, arb_radref(acb_realref(v)), arb_radref(acb_imagref(v)));
        mag_add(rv, rv, e);
        acb_get_mid(v, v);
        acb_mul(u, u, x, w);
        acb_add(u, u, a + k, w);
        mag_mul(ru, ru, ax);
        mag_add(e, arb_radref(acb_realref(u)), arb_radref(acb_imagref(u)));
        mag_add(ru, ru, e);
        acb_get_mid(u, u);
    }
    acb_set(y, u);
    acb_add_error_mag(y, ru);
    acb_set(dy, v);
    acb_add_error_mag(dy, rv);
    acb_clear(u);
    acb_clear(v);
    mag_clear(ru);
    mag_clear(rv);
    mag_clear(e);
    mag_clear(ax);
}

/* y = p(x), dy = p'(x) at precision w.  A sparse p (lambda^n - c, few
 * terms) by powers between its terms, O(terms log d) products instead of
 * Horner's d: x p'(x) = sum k a_k x^k. */
static void _rs_ab_eval2(acb_t y, acb_t dy, const _rs_ab_struct *s, const acb_t x, slong w)
{
    acb_t pw, t;
    slong j, last = 0;
    if (s->nnz == 0) {
        rs_radius_horner2(y, dy, s->P->coeffs, s->d + 1, x, w);
        return;
    }
    acb_init(pw);
    acb_init(t);
    acb_one(pw);
    acb_zero(y);
    acb_zero(dy);
    for (j = 0; j < s->nnz; j++) {
        slong k = s->nz[j];
        if (k > last) {
            acb_pow_ui(t, x, (ulong) (k - last), w);
            acb_mul(pw, pw, t, w);
            last = k;
        }
        acb_mul(t, pw, s->P->coeffs + k, w);
        acb_add(y, y, t, w);
        acb_mul_ui(t, t, (ulong) k, w);
        acb_add(dy, dy, t, w);
    }
    acb_div(dy, dy, x, w);
    acb_clear(pw);
    acb_clear(t);
}

/* D = the box around m holding the disc of radius d |p(m) / p'(m)|, which
 * contains a root of p (the Newton inclusion of _acb_poly_root_inclusion). */
static void _rs_ab_disc(acb_t D, const _rs_ab_struct *s, const acb_t m, slong w)
{
    acb_t y, dy;
    mag_t r, l;
    acb_init(y);
    acb_init(dy);
    mag_init(r);
    mag_init(l);
    _rs_ab_eval2(y, dy, s, m, w);
    acb_get_mag(r, y);
    acb_get_mag_lower(l, dy);
    mag_div(r, r, l);
    mag_mul_ui(r, r, (ulong) s->d);
    acb_set(D, m);
    acb_get_mid(D, D);
    acb_add_error_mag(D, r);
    acb_clear(y);
    acb_clear(dy);
    mag_clear(r);
    mag_clear(l);
}

/* One Aberth step on root i.  Returns 0 to give up (precision cap). */
static int _rs_ab_step(_rs_ab_struct *s, slong i)
{
    slong d = s->d, j, w = s->w[i], wmax, lg = (slong) ceil(log2((double) d + 1));
    acb_t y, dy, N, t, u;
    double complex S = 0;
    double rel, lz;
    int ok = 1;

    acb_init(y);
    acb_init(dy);
    acb_init(N);
    acb_init(t);
    acb_init(u);
    _rs_ab_eval2(y, dy, s, s->z + i, w);
    if (acb_contains_zero(dy)) {
        /* p' not even resolved: the root sits in a cluster finer than w */
        if (w >= s->wcap) { ok = 0; goto cleanup; }
        s->w[i] = FLINT_MIN(2 * w, s->wcap);
        goto cleanup;
    }
    lz = _rs_ab_log2mag(s->z + i);
    s->loss[i] = FLINT_MAX(0.0, s->logS[i] - _rs_ab_log2mag(dy) - lz);
    wmax = s->goal[i] + (slong) ceil(s->loss[i]) + 2 * lg + 16;
    if (wmax > s->wcap) { ok = 0; goto cleanup; }
    if (acb_contains_zero(y)) {
        /* p(z_i) is rounding noise at w: z_i is as good as w allows */
        if (w >= wmax) s->done[i] = 1;
        else s->w[i] = FLINT_MIN(FLINT_MAX(2 * w, 64), wmax);
        goto cleanup;
    }
    acb_div(N, y, dy, w);
    /* a root already within 2^-40 of its root and not in a cluster (small
     * loss) converges by Newton alone: the O(d) Aberth sum is skipped */
    for (j = 0; j < d && !(s->rel[i] < -40.0 && s->loss[i] < 20.0); j++) {
        double complex df;
        if (j == i) continue;
        df = s->zd[i] - s->zd[j];
        if (cabs(df) > ldexp(cabs(s->zd[i]), -40)) {
            S += 1.0 / df;
        } else {
            acb_sub(t, s->z + i, s->z + j, w);
            acb_inv(t, t, w);
            S += _rs_ab_get_d(t);
        }
    }
    /* c = N / (1 - N S) */
    acb_set_d_d(t, creal(S), cimag(S));
    acb_mul(u, N, t, w);
    acb_sub_ui(u, u, 1, w);
    acb_neg(u, u);
    acb_div(t, N, u, w);
    acb_get_mid(t, t);
    if (!acb_is_finite(t)) {
        /* far from a root (bad seeds: Wilkinson-type degree 100, whose double
         * Aberth seeds are garbage) N's ball is wide and 1 - N S may contain
         * 0: the step needs only midpoints; Newton's N when 1 - N S is 0 */
        acb_get_mid(N, N);
        acb_set_d_d(t, creal(S), cimag(S));
        acb_mul(u, N, t, w);
        acb_sub_ui(u, u, 1, w);
        acb_neg(u, u);
        acb_get_mid(u, u);
        if (acb_is_zero(u))
            acb_set(t, N);
        else
            acb_div(t, N, u, w);
        acb_get_mid(t, t);
    }
    if (!acb_is_finite(t)) { ok = 0; goto cleanup; }
    rel = _rs_ab_log2mag(t) - lz;
    s->rel[i] = rel;
    acb_sub(s->z + i, s->z + i, t, w);
    acb_get_mid(s->z + i, s->z + i);
    s->zd[i] = _rs_ab_get_d(s->z + i);
    /* quadratic convergence: about -2 rel bits are right after this step */
    if (-2.0 * rel >= (double) (s->goal[i] + lg + 24) && w >= wmax)
        s->done[i] = 1;
    else if (-rel > 8.0)
        s->w[i] = FLINT_MIN(wmax, FLINT_MAX(w, (slong) (-2.0 * rel) + (slong) ceil(s->loss[i]) + 32));
cleanup:
    acb_clear(y);
    acb_clear(dy);
    acb_clear(N);
    acb_clear(t);
    acb_clear(u);
    return ok;
}

/* Sweeps over the roots not done; 0 when some root gave up or the sweeps
 * ran out. */
static int _rs_ab_iterate(_rs_ab_struct *s, slong maxsweep)
{
    slong it, i, left;
    for (it = 0; it < maxsweep; it++) {
        if (rs_budget_exceeded())
            return 0;   /* the caller's loop reports the limit */
        left = 0;
        for (i = 0; i < s->d; i++) {
            if (s->done[i]) continue;
            if (!_rs_ab_step(s, i)) return 0;
            left += !s->done[i];
        }
        if (left == 0) return 1;
    }
    return 0;
}

/* Inclusion discs of the roots flagged in which (all when NULL) into D;
 * 1 when every disc is finite and no two of all d overlap. */
static int _rs_ab_discs(acb_ptr D, _rs_ab_struct *s, const char *which)
{
    slong d = s->d, i, j;
    for (i = 0; i < d; i++) {
        if (which != NULL && !which[i]) continue;
        _rs_ab_disc(D + i, s, s->z + i, s->w[i]);
        if (!acb_is_finite(D + i)) return 0;
    }
    for (i = 0; i < d; i++)
        for (j = i + 1; j < d; j++)
            if ((which == NULL || which[i] || which[j]) && acb_overlaps(D + i, D + j))
                return 0;
    return 1;
}

int rs_radius_aberth_certify(acb_ptr E, slong *wp, slong *nouter, const fmpz_poly_t f,
                             const double *a, const double *z0, slong prec, slong coarse)
{
    _rs_ab_struct s;
    slong d = fmpz_poly_degree(f), i, j, nref = 0;
    double lad, off;
    char *cand = NULL, *fresh = NULL;
    arb_t m;
    arf_t M, lb;
    int ok = 0;

    if (d < 2)
        return 0;
    acb_poly_init(s.P);
    acb_poly_set_fmpz_poly(s.P, f, fmpz_poly_max_bits(f) < 0 ? -fmpz_poly_max_bits(f) + 8
                                                             : fmpz_poly_max_bits(f) + 8);
    s.nz = flint_malloc((d + 1) * sizeof(slong));
    s.nnz = 0;
    for (i = 0; i <= d; i++)
        if (!fmpz_is_zero(f->coeffs + i)) s.nz[s.nnz++] = i;
    if (s.nnz * ((slong) FLINT_BIT_COUNT(d) + 2) > d)
        s.nnz = 0;   /* dense: Horner */
    s.d = d;
    s.z = _acb_vec_init(d);
    s.zd = flint_malloc(d * sizeof(double complex));
    s.logS = flint_malloc(d * sizeof(double));
    s.loss = flint_malloc(d * sizeof(double));
    s.rel = flint_calloc(d, sizeof(double));
    s.w = flint_malloc(d * sizeof(slong));
    s.goal = flint_malloc(d * sizeof(slong));
    s.done = flint_calloc(d, 1);
    s.wcap = 8 * prec + 4 * d + 256;
    arb_init(m);
    arf_init(M);
    arf_init(lb);
    coarse = (coarse > 0 && coarse < prec) ? coarse : prec;
    /* a is f scaled by a power of 2 (_rs_radius_to_double: coefficients
     * beyond 2^1000); the loss compares S with p' of f itself, so S is
     * taken back to f's scale (Wilkinson-type degree 200: 530 bits) */
    {
        slong e;
        double mc = fmpz_get_d_2exp(&e, f->coeffs + d);
        off = (double) e + log2(fabs(mc)) - log2(fabs(a[d]));
    }
    lad = log2(fabs(a[d])) + off;
    for (i = 0; i < d; i++) {
        s.zd[i] = z0[2 * i] + I * z0[2 * i + 1];
        if (!isfinite(creal(s.zd[i])) || !isfinite(cimag(s.zd[i])) || s.zd[i] == 0)
            goto cleanup;
        acb_set_d_d(s.z + i, z0[2 * i], z0[2 * i + 1]);
    }
    for (i = 0; i < d; i++) {
        double lp = lad;
        s.logS[i] = _rs_ab_log2sum(a, d, s.zd[i]) + off;
        /* |p'| at a root = |a_d| prod |z_i - z_j|: the starting loss */
        for (j = 0; j < d; j++)
            if (j != i) lp += log2(cabs(s.zd[i] - s.zd[j]) + 1e-300);
        s.loss[i] = FLINT_MAX(0.0, s.logS[i] - lp - log2(cabs(s.zd[i])));
        s.goal[i] = coarse;
        s.w[i] = FLINT_MIN(64 + (slong) ceil(s.loss[i]), s.wcap);
    }
    /* 128 sweeps: well-seeded roots stop after a few; Wilkinson-type
     * degree 100 needs about 80 from its double seeds (with 64 it fell back
     * to acb_poly_find_roots: 15 s against 0.3 s) */
    if (!_rs_ab_iterate(&s, 128) || !_rs_ab_discs(E, &s, NULL))
        goto cleanup;
    if (coarse < prec) {
        /* only the balls that may hold the largest modulus go on to prec;
         * repeat while a refined ball lets another one reach the top */
        cand = flint_calloc(d, 1);
        fresh = flint_calloc(d, 1);
        for (;;) {
            slong add = 0;
            arf_zero(M);
            for (i = 0; i < d; i++) {
                acb_abs(m, E + i, 2 * MAG_BITS);
                arb_get_lbound_arf(lb, m, 2 * MAG_BITS);
                if (arf_cmp(lb, M) > 0) arf_set(M, lb);
            }
            for (i = 0; i < d; i++) {
                acb_abs(m, E + i, 2 * MAG_BITS);
                arb_get_ubound_arf(lb, m, 2 * MAG_BITS);
                if (!cand[i] && arf_cmp(lb, M) >= 0) {
                    cand[i] = 2;   /* new */
                    s.goal[i] = prec;
                    s.done[i] = 0;
                    add++;
                }
            }
            if (add == 0) break;
            nref += add;
            if (!_rs_ab_iterate(&s, 64))
                goto cleanup;
            for (i = 0; i < d; i++) fresh[i] = cand[i] == 2;
            if (!_rs_ab_discs(E, &s, fresh))
                goto cleanup;
            for (i = 0; i < d; i++) cand[i] = cand[i] != 0;
        }
    }
    *wp = 0;
    for (i = 0; i < d; i++)
        *wp = FLINT_MAX(*wp, s.w[i]);
    *nouter = (coarse < prec && nref < d) ? nref : -1;
    ok = 1;
cleanup:
    acb_poly_clear(s.P);
    flint_free(s.nz);
    _acb_vec_clear(s.z, d);
    flint_free(s.zd);
    flint_free(s.logS);
    flint_free(s.loss);
    flint_free(s.rel);
    flint_free(s.w);
    flint_free(s.goal);
    flint_free(s.done);
    flint_free(cand);
    flint_free(fresh);
    arb_clear(m);
    arf_clear(M);
    arf_clear(lb);
    return ok;
}

/* ------------------------------------------------------------------ */
/* Seeds for ill-conditioned polynomials: Aberth on the secular equation
 * (MPSolve's secsolve, Bini-Robol 2014, "Solving secular and polynomial
 * equations: a multiprecision algorithm", J. Comput. Appl. Math. 272).
 *
 * Double Aberth on the monomial coefficients gives backward-stable roots
 * only: for Wilkinson-type prod ((d+1) x - k) they have no correct digit
 * (the roots lose 300-900 bits), and Aberth on Arb midpoints from them (or
 * from Bini's circle) needs about d sweeps at that precision: the roots
 * peel off the segment one by one (degree 200: 300 sweeps, then the
 * fallback: 250 s).  With nodes b_1..b_d (the current approximations),
 *   p(x) = -lc g(x) S(x),  g = prod (x - b_j),  S = sum a_j / (x - b_j) - 1,
 *   a_j = -p(b_j) / (lc prod_{k != j} (b_j - b_k)),
 * and the zeros of S are well conditioned once the nodes are near the
 * roots: only the a_j need p in high precision (one evaluation per node,
 * to 56 correct bits), the sweeps on S run in double, and each new set of
 * nodes (the sweeps' result) gains about 50 bits.  The result is used as
 * seeds only: rs_radius_aberth_certify certifies. */

static double complex _rs_sec_inv(double complex t)
{
    double r = creal(t), i = cimag(t), n = r * r + i * i;
    if (n > 1e-300 && n < 1e300)
        return (r - I * i) / n;
    return 1.0 / t;
}

/* how many roots lose more than 24 bits when p is evaluated in double
 * near the seeds: log2 (sum |a_k| |z|^k / (|z| |p'(z)|)) with |p'(z_i)| =
 * |a_d| prod |z_i - z_j| (the product of squares renormalised by frexp,
 * one log2 per root) */
static slong _rs_sec_lossy(const double *a, const double complex *z, slong d)
{
    double lad = log2(fabs(a[d]));
    slong i, j, n = 0;
    for (i = 0; i < d; i++) {
        double m = 1.0, lp;
        int e, ex = 0;
        for (j = 0; j < d; j++) {
            double dr = creal(z[i]) - creal(z[j]), di = cimag(z[i]) - cimag(z[j]);
            if (j == i) continue;
            m *= dr * dr + di * di;
            /* every 4 factors, so that roots up to about 2^60 apart stay
             * inside double; beyond, an overflow only skips this pass (a
             * heuristic trigger: the certification does not depend on it) */
            if ((j & 3) == 3) { m = frexp(m, &e); ex += e; }
        }
        m = frexp(m, &e);
        ex += e;
        lp = lad + 0.5 * (log2(m) + (double) ex);
        n += _rs_ab_log2sum(a, d, z[i]) - lp - log2(cabs(z[i]) + 1e-300) > 24.0;
    }
    return n;
}

/* a_i of the secular equation at the nodes b (exact doubles); w[i] is the
 * working precision of p(b_i), raised until 56 bits of it are right.
 * 0 when some a_i leaves the double range. */
static int _rs_sec_coeffs(double complex *ac, const acb_poly_t P, const double complex *b,
                          slong d, slong *w, slong wcap)
{
    acb_t y, dy, q, t;
    slong i, j;
    int ok = 1;
    acb_init(y);
    acb_init(dy);
    acb_init(q);
    acb_init(t);
    for (i = 0; i < d && ok; i++) {
        acb_set_d_d(t, creal(b[i]), cimag(b[i]));
        for (;;) {
            slong acc;
            rs_radius_horner2(y, dy, P->coeffs, d + 1, t, w[i]);
            acc = acb_rel_accuracy_bits(y);
            if ((acb_is_finite(y) && !acb_contains_zero(y) && acc >= 56) || w[i] >= wcap)
                break;
            if (acb_is_finite(y) && !acb_contains_zero(y) && acc > -w[i])
                w[i] = FLINT_MIN(wcap, w[i] + (56 - acc) + 16);
            else
                w[i] = FLINT_MIN(wcap, 2 * w[i]);
        }
        if (acb_is_finite(y) && acb_contains_zero(y))
            acb_zero(y);   /* b_i is a root as far as wcap tells: a_i = 0 */
        /* lc prod_{j != i} (b_i - b_j): exact differences of doubles */
        acb_set(q, P->coeffs + d);
        for (j = 0; j < d; j++) {
            if (j == i) continue;
            acb_set_d_d(dy, creal(b[i]), cimag(b[i]));
            acb_set_d_d(t, creal(b[j]), cimag(b[j]));
            acb_sub(t, dy, t, 64);
            acb_mul(q, q, t, 64);
            /* a seed needs no radius: rectangular balls would lose about
             * half a bit per product (d/2 over all) */
            acb_get_mid(q, q);
        }
        acb_get_mid(y, y);
        acb_div(y, y, q, 64);
        acb_neg(y, y);
        if (!acb_is_finite(y) || acb_contains_zero(q)) { ok = 0; break; }
        if (arf_cmpabs_2exp_si(arb_midref(acb_realref(y)), 1000) > 0 ||
            arf_cmpabs_2exp_si(arb_midref(acb_imagref(y)), 1000) > 0) { ok = 0; break; }
        ac[i] = _rs_ab_get_d(y);
    }
    acb_clear(y);
    acb_clear(dy);
    acb_clear(q);
    acb_clear(t);
    return ok;
}

int rs_radius_aberth_secular(double *zr, const fmpz_poly_t f, const double *a, slong rounds)
{
    slong d = fmpz_poly_degree(f), i, j, k, r, it, bits = FLINT_ABS(fmpz_poly_max_bits(f));
    slong maxsweep = 32, wcap = 16 * (bits + d) + 1024;
    double complex *b, *x, *ac, *cprev;
    slong *w;
    char *done;
    acb_poly_t P;
    int res = -1, restarted = 0;

    if (d < 2)
        return -1;
    b = flint_malloc(d * sizeof(double complex));
    x = flint_malloc(d * sizeof(double complex));
    ac = flint_malloc(d * sizeof(double complex));
    cprev = flint_malloc(d * sizeof(double complex));
    w = flint_malloc(d * sizeof(slong));
    done = flint_malloc(d);
    acb_poly_init(P);
    for (i = 0; i < d; i++) {
        b[i] = zr[2 * i] + I * zr[2 * i + 1];
        if (!isfinite(creal(b[i])) || !isfinite(cimag(b[i])))
            goto cleanup;
        w[i] = 128;
    }
    /* seeds as good as double for most roots (a cluster of a few is left
     * to the per-root precision of rs_radius_aberth_certify): nothing to
     * gain (clustered degree 500: 0.28 s, 0.51 with this pass) */
    if (_rs_sec_lossy(a, b, d) <= d / 8) {
        res = 0;
        goto cleanup;
    }
    acb_poly_set_fmpz_poly(P, f, bits + 8);
    for (r = 1; r <= rounds; r++) {
        double moved = 0.0;
        if (rs_budget_exceeded())
            goto cleanup;
        for (i = 0; i < d; i++)
            for (j = i + 1; j < d; j++)
                if (b[i] == b[j])
                    b[j] += ldexp(cabs(b[j]) + 1e-300, -30) * I;   /* distinct nodes */
        if (!_rs_sec_coeffs(ac, P, b, d, w, wcap)) {
            /* far from the roots p(b_i) dwarfs lc prod (b_i - b_j) (a_i
             * beyond double): once, restart from Bini's circles, where
             * p(b_i) / lc is about the nodes' own product */
            if (r > 1)
                break;   /* the last nodes are still the best seeds */
            if (restarted)
                goto cleanup;
            restarted = 1;
            _rs_aberth_start(b, a, d);
            if (!_rs_sec_coeffs(ac, P, b, d, w, wcap))
                goto cleanup;
        }
        for (i = 0; i < d; i++) {
            x[i] = b[i];
            cprev[i] = 0;
            done[i] = 0;
        }
        for (it = 0; it < maxsweep; it++) {
            slong left = 0;
            for (k = 0; k < d; k++) {
                double complex A = 0, s1 = 0, s2 = 0, B = 0, h, T, dT, L, N, c, u;
                if (done[k]) continue;
                for (j = 0; j < d; j++) {
                    if (j == k) continue;
                    u = _rs_sec_inv(x[k] - b[j]);
                    A += u;
                    s1 += ac[j] * u;
                    s2 += ac[j] * u * u;
                    B += _rs_sec_inv(x[k] - x[j]);
                }
                h = x[k] - b[k];
                T = ac[k] + h * (s1 - 1.0);
                if (T == 0) { done[k] = 1; continue; }
                dT = (s1 - 1.0) - h * s2;
                L = A + dT / T;   /* p'/p at x_k */
                N = 1.0 / L;
                c = N / (1.0 - N * B);
                if (!isfinite(creal(c)) || !isfinite(cimag(c))) { done[k] = 1; continue; }
                x[k] -= c;
                /* converged to double, or stalled at the noise of S */
                if (cabs(c) <= ldexp(cabs(x[k]), -48) ||
                    (cprev[k] != 0 && cabs(c) > 0.5 * cabs(cprev[k]) &&
                     cabs(c) < ldexp(cabs(x[k]), -16)))
                    done[k] = 1;
                else
                    left++;
                cprev[k] = c;
            }
            if (left == 0) break;
        }
        for (i = 0; i < d; i++) {
            if (!isfinite(creal(x[i])) || !isfinite(cimag(x[i])))
                goto cleanup;
            moved = FLINT_MAX(moved, cabs(x[i] - b[i]) / (cabs(b[i]) + 1e-300));
            b[i] = x[i];
        }
        if (moved <= ldexp(1.0, -24)) {
            res = (int) r;
            break;
        }
    }
    for (i = 0; i < d; i++) {
        zr[2 * i] = creal(b[i]);
        zr[2 * i + 1] = cimag(b[i]);
    }
    if (res < 0)
        res = (int) rounds + 1;   /* not settled: the nodes are still better seeds */
cleanup:
    flint_free(b);
    flint_free(x);
    flint_free(ac);
    flint_free(cprev);
    flint_free(w);
    flint_free(done);
    acb_poly_clear(P);
    return res;
}
