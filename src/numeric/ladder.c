/* ladder.c -- the per-point certified verdict ladder of sweeps and maps
 * (ladder.h): fast (double roots with a priori verified inclusion discs, or
 * Arb at 64 bits), prec128, prec256, then the injected exact rung. */
#include <math.h>
#include <stdlib.h>
#include <acb.h>
#include <acb_poly.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>
#include <fmpq.h>
#include "recstab/ladder.h"

/* the rs_status_t values (rootcount.h, a stage the numeric one does not include) */
enum { ST_STABLE = 0, ST_MARGINAL = 1, ST_UNSTABLE = 2 };

const char *const rs_sweep_level_names[6] = {"fast", "prec128", "prec256", "exact", "double", "certified"};

double rs_ladder_lower_d(const arb_t x)
{
    arf_t t;
    double d;
    arf_init(t);
    arb_get_lbound_arf(t, x, 64);
    d = arf_get_d(t, ARF_RND_DOWN);
    arf_clear(t);
    return d < 0 ? 0 : d;
}

double rs_ladder_upper_d(const arb_t x)
{
    arf_t t;
    double d;
    arf_init(t);
    arb_get_ubound_arf(t, x, 64);
    d = arf_get_d(t, ARF_RND_UP);
    arf_clear(t);
    return d;
}

/* Verdict from root inclusion discs (each holds >= 1 root; when all n are
 * pairwise disjoint, exactly one each).  Returns the verdict or -1. */
static int judge_discs(rs_sweep_point_t *pt, acb_srcptr roots, slong n, slong nisolated, slong prec)
{
    arb_t a, one;
    slong i;
    int all_in = (nisolated == n), any_out = 0;
    double lo = 0, hi = 0;
    arb_init(a);
    arb_init(one);
    arb_one(one);
    for (i = 0; i < n; i++) {
        double l, u;
        if (!acb_is_finite(roots + i)) { all_in = 0; continue; }
        acb_abs(a, roots + i, prec);
        if (!arb_lt(a, one)) all_in = 0;
        if (arb_gt(a, one)) any_out = 1;
        l = rs_ladder_lower_d(a);
        u = rs_ladder_upper_d(a);
        if (l > lo) lo = l;
        if (u > hi) hi = u;
    }
    arb_clear(a);
    arb_clear(one);
    if (lo > pt->rho_lower) pt->rho_lower = lo;
    if (nisolated == n) {
        pt->isolated = 1;
        pt->rho_lower = lo;
        pt->rho_upper = hi;
    }
    if (any_out) return ST_UNSTABLE;
    if (all_in) return ST_STABLE;
    return -1;
}

/* The same Newton inclusion (disc n|p(z)|/|p'(z)| around z holds a root) in
 * plain double arithmetic with a priori rounding-error bounds (IEEE binary64,
 * round to nearest; u = 2^-53): the computed Horner values of p and p' are
 * within (10n + 12) u S and (20n + 24) u S' of the exact ones, S = sum |a_k||z|^k,
 * S' = sum k|a_k||z|^(k-1) (Higham, ASNA 2nd ed., 5.1 and 3.6, with the
 * coefficient rounding 2u S included and a factor >= 2 of slack); every other
 * operation is given a relative 8u margin.  Any non-finite or subnormal
 * quantity returns -1 (undecided: the Arb check runs).  a[0..n] approximate
 * the exact coefficients 2^-shift q_k to 2u relative each. */
static int judge_double(rs_sweep_point_t *pt, const double *a, const double *z, slong n)
{
    const double u = 0x1p-53;
    double r[64], m[64], lo = 0, hi = 0;
    slong i, j, k;
    int all_in = 1, any_out = 0;
    if (n > 64) return -1;
    for (i = 0; i < n; i++) {
        double x = z[2 * i], y = z[2 * i + 1], pr = a[n], pi = 0, dr = 0, di = 0, az, S, Sd = 0, P, D, t;
        az = hypot(x, y);
        S = fabs(a[n]);
        for (k = n - 1; k >= 0; k--) {
            /* derivative first: d = d z + p */
            t = dr * x - di * y + pr;
            di = dr * y + di * x + pi;
            dr = t;
            t = pr * x - pi * y + a[k];
            pi = pr * y + pi * x;
            pr = t;
            Sd = Sd * az + S;
            S = S * az + fabs(a[k]);
        }
        if (!isfinite(pr) || !isfinite(pi) || !isfinite(dr) || !isfinite(di) || !isfinite(S) || !isfinite(Sd)
            || !(S > 0x1p-900) || !(az > 0x1p-400)) return -1;
        P = hypot(pr, pi) * (1 + 8 * u) + (10.0 * (double) n + 12) * u * S * (1 + 8 * u);
        D = hypot(dr, di) * (1 - 8 * u) - (20.0 * (double) n + 24) * u * Sd * (1 + 8 * u);
        if (!(D > 0x1p-900) || !isfinite(P)) return -1;
        r[i] = (double) n * P / D * (1 + 16 * u);
        m[i] = az;
        if (!isfinite(r[i])) return -1;
    }
    for (i = 0; i < n; i++)
        for (j = i + 1; j < n; j++)
            if (!(hypot(z[2 * i] - z[2 * j], z[2 * i + 1] - z[2 * j + 1]) * (1 - 16 * u) > (r[i] + r[j]) * (1 + 8 * u)))
                return -1;                      /* not isolated: let Arb try */
    for (i = 0; i < n; i++) {
        double up = (m[i] * (1 + 8 * u) + r[i]) * (1 + 8 * u), dn = (m[i] * (1 - 8 * u) - r[i]) * (1 - 8 * u);
        if (!(up < 1)) all_in = 0;
        if (dn > 1) any_out = 1;
        if (dn > lo) lo = dn;
        if (up > hi) hi = up;
    }
    pt->isolated = 1;
    pt->rho_lower = lo;
    pt->rho_upper = hi;
    if (any_out) return ST_UNSTABLE;
    if (all_in) return ST_STABLE;
    pt->isolated = 0;
    pt->rho_lower = 0;
    pt->rho_upper = INFINITY;
    return -1;
}


/* The exact rung: verdict and the radius bounds its counts imply. */
int rs_ladder_decide_exact(rs_sweep_point_t *pt, const fmpz_poly_t q, rs_ladder_exact_fn exact, void *arg,
                           rs_error_t err)
{
    fmpz_poly_t pp;
    rs_ladder_count_t c;
    int r;
    fmpz_poly_init(pp);
    fmpz_poly_primitive_part(pp, q);
    r = exact(&c, pp, arg, err);
    fmpz_poly_clear(pp);
    if (r != RS_OK) return r;
    pt->verdict = c.status;
    pt->repeated_on = (c.outside == 0 && c.max_on_mult > 1);
    pt->level = RS_LEVEL_EXACT;
    if (c.outside == 0 && c.on > 0) {
        pt->rho_lower = pt->rho_upper = 1.0;   /* exactly: the largest roots are on the circle */
        pt->isolated = 1;
    } else if (c.outside == 0) {
        if (pt->rho_upper > 1.0) pt->rho_upper = 1.0;
    } else if (pt->rho_lower < 1.0) {
        pt->rho_lower = 1.0;
    }
    return RS_OK;
}

/* Degree 0 (roots at 0 only) and 1 (the root -q0/q1, exactly): no ladder. */
static void decide_small(rs_sweep_point_t *pt, const fmpz_poly_t q)
{
    fmpq_t t;
    arb_t x;
    int c;
    pt->isolated = 1;
    if (fmpz_poly_degree(q) == 0) {
        pt->verdict = ST_STABLE;
        pt->rho_lower = pt->rho_upper = 0;
        return;
    }
    c = fmpz_cmpabs(q->coeffs + 0, q->coeffs + 1);
    fmpq_init(t);
    arb_init(x);
    fmpq_set_fmpz_frac(t, q->coeffs + 0, q->coeffs + 1);
    fmpq_abs(t, t);
    pt->verdict = c < 0 ? ST_STABLE : c == 0 ? ST_MARGINAL : ST_UNSTABLE;
    pt->level = RS_LEVEL_EXACT;
    arb_set_fmpq(x, t, 64);
    pt->rho_lower = rs_ladder_lower_d(x);
    pt->rho_upper = rs_ladder_upper_d(x);
    arb_clear(x);
    fmpq_clear(t);
}

/* q's coefficients as doubles scaled by 2^-shift (the largest below 2^900)
 * into a[0..n], and GSL's roots into z; a GSL status. */
static int double_roots(double *a, double *z, const fmpz_poly_t q, slong n)
{
    slong i, maxbits = 0, shift;
    int st;
    gsl_poly_complex_workspace *w;
    for (i = 0; i <= n; i++) {
        slong b = (slong) fmpz_bits(q->coeffs + i);
        if (b > maxbits) maxbits = b;
    }
    shift = maxbits > 900 ? maxbits - 900 : 0;
    for (i = 0; i <= n; i++) {
        slong e;
        double m = fmpz_get_d_2exp(&e, q->coeffs + i);
        a[i] = (m == 0) ? 0.0 : ldexp(m, (int) (e - shift));
    }
    w = (a[n] != 0) ? gsl_poly_complex_workspace_alloc((size_t) n + 1) : NULL;
    st = (w == NULL) ? GSL_EFAILED : gsl_poly_complex_solve(a, (size_t) n + 1, w, z);
    if (w) gsl_poly_complex_workspace_free(w);
    return st;
}

/* benchmark baseline (RS_LEVEL_DOUBLE): max |root| vs 1, no certificate */
static void decide_double(rs_sweep_point_t *pt, const double *z, slong n)
{
    double rho = 0;
    slong i;
    for (i = 0; i < n; i++) {
        double m = hypot(z[2 * i], z[2 * i + 1]);
        if (m > rho) rho = m;
    }
    pt->verdict = rho < 1 - 1e-9 ? ST_STABLE : rho > 1 + 1e-9 ? ST_UNSTABLE : ST_MARGINAL;
    pt->level = RS_LEVEL_DOUBLE;
    pt->rho_lower = pt->rho_upper = rho;
    pt->isolated = 1;
}

/* Level fast: the double roots z of q (a: its scaled coefficients) verified
 * in double arithmetic, else by Arb at 64 bits; the verdict or -1, and the
 * roots as seeds for the next levels. */
static int decide_fast(rs_sweep_point_t *pt, acb_ptr seeds, const fmpz_poly_t q, const double *a, const double *z,
                       slong n)
{
    acb_ptr roots;
    acb_poly_t P;
    slong i, iso;
    int verdict;
    for (i = 0; i < 2 * n; i++) if (!isfinite(z[i])) return -2;
    for (i = 0; i <= n; i++)      /* a coefficient lost to underflow: no a priori bound */
        if (!fmpz_is_zero(q->coeffs + i) && !(fabs(a[i]) > 0x1p-1000)) return -2;
    pt->level = RS_LEVEL_FAST;
    if ((verdict = judge_double(pt, a, z, n)) >= 0) return verdict;
    roots = _acb_vec_init(n);
    acb_poly_init(P);
    for (i = 0; i < n; i++) {
        acb_set_d_d(roots + i, z[2 * i], z[2 * i + 1]);
        acb_set(seeds + i, roots + i);
    }
    acb_poly_set_fmpz_poly(P, q, 64);
    iso = _acb_poly_validate_roots(roots, P->coeffs, n + 1, 64);
    verdict = judge_discs(pt, roots, n, iso, 64);
    acb_poly_clear(P);
    _acb_vec_clear(roots, n);
    return verdict;
}

/* Levels prec128, prec256 (from first_level on): Arb's root finder seeded
 * with seeds (all zero: none); the verdict or -1. */
static int decide_arb(rs_sweep_point_t *pt, acb_ptr seeds, const fmpz_poly_t q, slong n, int first_level)
{
    acb_ptr roots = _acb_vec_init(n);
    acb_poly_t P;
    slong i, prec;
    int verdict = -1;
    acb_poly_init(P);
    for (prec = 128; verdict < 0 && prec <= 256; prec *= 2) {
        slong iso, allzero = 1;
        if ((prec == 128 && first_level > RS_LEVEL_PREC128) || (prec == 256 && first_level > RS_LEVEL_PREC256))
            continue;
        for (i = 0; i < n; i++) if (!acb_is_zero(seeds + i)) allzero = 0;
        acb_poly_set_fmpz_poly(P, q, prec);
        iso = acb_poly_find_roots(roots, P, allzero ? NULL : seeds, 2 * prec, prec);
        pt->rho_lower = 0;
        verdict = judge_discs(pt, roots, n, iso, prec);
        pt->level = prec == 128 ? RS_LEVEL_PREC128 : RS_LEVEL_PREC256;
        for (i = 0; i < n; i++) {
            acb_set(seeds + i, roots + i);
            mag_zero(arb_radref(acb_realref(seeds + i)));
            mag_zero(arb_radref(acb_imagref(seeds + i)));
        }
    }
    acb_poly_clear(P);
    _acb_vec_clear(roots, n);
    return verdict;
}

/* The ladder on q = p / lambda^v (degree n >= 2). */
static int decide_ladder(rs_sweep_point_t *pt, const fmpz_poly_t q, slong n, int first_level,
                         rs_ladder_exact_fn exact, void *arg, rs_error_t err)
{
    double *a = malloc((size_t) (n + 1) * sizeof(double)), *z = malloc((size_t) (2 * n) * sizeof(double));
    acb_ptr seeds = _acb_vec_init(n);
    slong i;
    int verdict = -1, r = RS_OK, st = double_roots(a, z, q, n);
    if (st == GSL_SUCCESS && first_level == RS_LEVEL_DOUBLE) {
        decide_double(pt, z, n);
        goto done;
    }
    if (st == GSL_SUCCESS && first_level > RS_LEVEL_FAST) {
        for (i = 0; i < n; i++) acb_set_d_d(seeds + i, z[2 * i], z[2 * i + 1]);
    } else if (st == GSL_SUCCESS) {
        verdict = decide_fast(pt, seeds, q, a, z, n);
        if (verdict == -2) st = GSL_EFAILED, verdict = -1;
    }
    if (st != GSL_SUCCESS)
        for (i = 0; i < n; i++) acb_zero(seeds + i);
    if (verdict < 0) verdict = decide_arb(pt, seeds, q, n, first_level);
    if (verdict >= 0) pt->verdict = verdict;
    else r = rs_ladder_decide_exact(pt, q, exact, arg, err);   /* the exact test always decides */
done:
    _acb_vec_clear(seeds, n);
    free(a);
    free(z);
    return r;
}

int rs_ladder_decide(rs_sweep_point_t *pt, const fmpz_poly_t p, int first_level, rs_ladder_exact_fn exact,
                     void *arg, rs_error_t err)
{
    fmpz_poly_t q;
    slong v = 0;
    int r = RS_OK;
    pt->status = RS_OK;
    pt->verdict = -1;
    pt->level = RS_LEVEL_FAST;
    pt->isolated = 0;
    pt->rho_lower = 0;
    pt->rho_upper = INFINITY;
    pt->repeated_on = 0;
    if (fmpz_poly_is_zero(p)) return RS_OK;        /* the scheme is singular here */
    while (fmpz_is_zero(p->coeffs + v)) v++;
    fmpz_poly_init(q);
    fmpz_poly_shift_right(q, p, v);
    if (fmpz_poly_degree(q) <= 1) decide_small(pt, q);
    else r = decide_ladder(pt, q, fmpz_poly_degree(q), first_level, exact, arg, err);
    fmpz_poly_clear(q);
    pt->status = r;
    return r;
}
