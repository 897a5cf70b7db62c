/* radius.c -- certified spectral radius; see include/recstab/radius.h.
 *
 * Layout: small helpers (result bookkeeping, accuracy goal, precision
 * schedule), the eigenvalue certifier shared by all companion-matrix routes,
 * the exact fmpz routes (squarefree factors; companion or complex_roots), the
 * ball engine (acb_poly and matrix polynomials), and the GSL baseline. */
#include <math.h>
#include <string.h>
#include <mpfr.h> /* before Arb's headers: FLINT 3 declares arf_get_mpfr only after mpfr.h */
#include <flint/fmpz_poly_factor.h>
#include <arb_fmpz_poly.h>
#include <acb_mat.h>
#include <stdio.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>
#include "recstab/budget.h"
#include "recstab/radius.h"
#include "util/dblstr.h"

#define RS_LOG2_10 3.32192809488736234787
#define RS_RADIUS_MIN_PREC 16
#define RS_RADIUS_MAX_DIM 4096
#define RS_RADIUS_ABERTH_MIN_DEGREE 2  /* first degree of _rs_factor_roots_aberth */  /* largest companion / block companion size */

/* ------------------------------------------------------------------ */
/* result bookkeeping                                                  */

void rs_radius_init(rs_radius_t r)
{
    arb_init(r->lower);
    arb_init(r->upper);
    arb_init(r->rho);
    r->digits = 0;
    r->prec = 0;
    r->nroots = 0;
    r->roots = NULL;
    r->mult = NULL;
    r->method_double = 0;
    r->rho_double = 0.0;
    r->method = RS_RADIUS_METHOD_NONE;
    r->isolated = 0;
    r->partial = 0;
    r->nouter = 0;
}

static void _rs_radius_free_roots(rs_radius_t r)
{
    if (r->roots != NULL)
        _acb_vec_clear(r->roots, r->nroots);
    flint_free(r->mult);
    r->roots = NULL;
    r->mult = NULL;
    r->nroots = 0;
}

void rs_radius_clear(rs_radius_t r)
{
    _rs_radius_free_roots(r);
    arb_clear(r->lower);
    arb_clear(r->upper);
    arb_clear(r->rho);
}

void rs_radius_swap(rs_radius_t r, rs_radius_t s)
{
    rs_radius_struct t = *r;
    *r = *s;
    *s = t;
}

/* Forget any previous result: trivially true bounds 0 <= rho <= +inf. */
static void _rs_radius_reset(rs_radius_t r, slong digits)
{
    _rs_radius_free_roots(r);
    arb_zero(r->lower);
    arb_pos_inf(r->upper);
    arb_zero_pm_inf(r->rho);
    r->digits = digits;
    r->prec = 0;
    r->method_double = 0;
    r->rho_double = 0.0;
    r->method = RS_RADIUS_METHOD_NONE;
    r->isolated = 0;
    r->partial = 0;
    r->nouter = 0;
}

static void _rs_radius_alloc_roots(rs_radius_t r, slong n)
{
    _rs_radius_free_roots(r);
    if (n <= 0)
        return;
    r->roots = _acb_vec_init(n);
    r->mult = flint_malloc(n * sizeof(slong));
    r->nroots = n;
}

/* lower/upper from the ball r->rho (lower clamped at 0: rho >= 0). */
static void _rs_radius_set_bounds(rs_radius_t r)
{
    arf_t t;
    arf_init(t);
    arb_get_lbound_arf(t, r->rho, ARF_PREC_EXACT);
    if (arf_sgn(t) < 0)
        arf_zero(t);
    arb_set_arf(r->lower, t);
    arb_get_ubound_arf(t, r->rho, ARF_PREC_EXACT);
    arb_set_arf(r->upper, t);
    arf_clear(t);
}

/* Every root of sum a_j lambda^j (real balls, degree n) strictly inside
 * the unit circle: Schur's recursion p_{k-1} = (a_k p_k - a_0 p_k^*)/lambda
 * with a_k^2 - a_0^2 > 0 at every step (as kp_all_inside of an_region.c does exactly,
 * each sign certified on the balls, so it holds for the exact values
 * inside them); a repeated root inside does not stop it. */
int rs_radius_balls_inside(arb_srcptr c, slong n, slong prec)
{
    arb_ptr a = _arb_vec_init(n + 1), b = _arb_vec_init(n + 1);
    arb_t d, t;
    slong k, j;
    int ok = 1;
    arb_init(d); arb_init(t);
    _arb_vec_set(a, c, n + 1);
    for (k = n; k >= 1 && ok; k--) {
        arb_sqr(d, a + k, prec);
        arb_submul(d, a + 0, a + 0, prec);
        if (!arb_is_positive(d)) { ok = 0; break; }
        for (j = 0; j < k; j++) {
            arb_mul(b + j, a + k, a + j + 1, prec);
            arb_submul(b + j, a + 0, a + k - 1 - j, prec);
        }
        /* divided by d > 0: the signs stay, the sizes do not grow */
        for (j = 0; j < k; j++) arb_div(a + j, b + j, d, prec);
    }
    _arb_vec_clear(a, n + 1); _arb_vec_clear(b, n + 1);
    arb_clear(d); arb_clear(t);
    return ok;
}

/* rho = max_i |roots[i]|, a ball containing the true maximum modulus as
 * long as every root of p lies in some roots[i] and every roots[i] holds a
 * root (isolating or cluster enclosures both qualify). */
static void _rs_radius_rho_from_roots(rs_radius_t r, slong prec)
{
    rs_radius_set_rho(r, r->roots, r->nroots, prec);
}

void rs_radius_set_rho(rs_radius_t r, acb_srcptr roots, slong n, slong prec)
{
    arb_t t;
    slong i;
    arb_init(t);
    arb_zero(r->rho);
    for (i = 0; i < n; i++) {
        acb_abs(t, roots + i, prec);
        arb_max(r->rho, r->rho, t, prec);
    }
    arb_clear(t);
    _rs_radius_set_bounds(r);
}

/* Goal: 2 rad(rho) <= 10^-digits * lbound(rho).  When the ball contains 0
 * and allow_abs is set, 2 rad(rho) <= 10^-digits instead. */
static int _rs_radius_goal_met(const arb_t rho, slong digits, int allow_abs)
{
    arf_t w, lb;
    arb_t t, ten;
    int ok;

    if (arb_is_zero(rho))
        return 1;
    if (!arb_is_finite(rho))
        return 0;
    arf_init(w);
    arf_init(lb);
    arb_init(t);
    arb_init(ten);
    arf_set_mag(w, arb_radref(rho));
    arf_mul_2exp_si(w, w, 1);
    arb_get_lbound_arf(lb, rho, ARF_PREC_EXACT);
    if (arf_sgn(lb) <= 0) {
        if (!allow_abs) {
            ok = 0;
            goto cleanup;
        }
        arf_one(lb);
    }
    arb_ui_pow_ui(ten, 10, (ulong) digits, 64);
    arb_set_arf(t, lb);
    arb_div(t, t, ten, 64);
    arb_get_lbound_arf(lb, t, 64);
    ok = arf_cmp(w, lb) <= 0;
cleanup:
    arf_clear(w);
    arf_clear(lb);
    arb_clear(t);
    arb_clear(ten);
    return ok;
}

/* Decimal digits currently certified in rho (relative), for messages. */
static slong _rs_radius_digits_got(const arb_t rho)
{
    slong bits;
    if (arb_is_exact(rho))
        return WORD_MAX / 4;
    bits = arb_rel_accuracy_bits(rho);
    return bits <= 0 ? 0 : (slong) floor((double) bits / RS_LOG2_10);
}

static slong _rs_radius_bits_for(slong digits)
{
    return (slong) ceil((double) digits * RS_LOG2_10);
}

/* Validate digits/max_prec; normalise max_prec. */
static int _rs_radius_check_args(slong digits, slong *max_prec, rs_error_t err)
{
    if (digits < 1 || digits > 1000000)
        return rs_error_set(err, RS_ERR_INPUT,
                            "radius: digits must be in 1..1000000 (got %ld)",
                            (long) digits);
    if (*max_prec <= 0)
        *max_prec = RS_RADIUS_MAX_PREC_DEFAULT;
    if (*max_prec < RS_RADIUS_MIN_PREC)
        return rs_error_set(err, RS_ERR_INPUT,
                            "radius: max precision must be >= %d bits (got %ld)",
                            RS_RADIUS_MIN_PREC, (long) *max_prec);
    return RS_OK;
}

/* Working precision for the companion routes: below digits*log2(10) bits
 * the goal cannot be met, 32 guard bits absorb typical conditioning. */
static slong _rs_radius_start_prec(slong digits, slong max_prec)
{
    slong p = _rs_radius_bits_for(digits) + 32;
    if (p < 64)
        p = 64;
    return p > max_prec ? max_prec : p;
}

static int _rs_radius_limit_error(const rs_radius_t r, slong max_prec,
                                  rs_error_t err)
{
    return rs_error_set(err, RS_ERR_LIMIT,
        "radius: precision limit %ld bits reached before %ld digits were "
        "certified (have %ld); raise with --max-prec",
        (long) max_prec, (long) r->digits,
        (long) _rs_radius_digits_got(r->rho));
}

/* Keep the enclosure in rho but drop the roots: the error-return state. */
static void _rs_radius_keep_partial(rs_radius_t r)
{
    _rs_radius_free_roots(r);
    r->partial = arb_is_finite(r->rho);
}

/* ------------------------------------------------------------------ */
/* eigenvalue certification of one matrix                              */

enum { RS_EIG_FAIL = 0, RS_EIG_CLUSTER = 1, RS_EIG_SIMPLE = 2 };

static int _rs_radius_companion_clusters(acb_ptr E, const acb_mat_t C,
                                         acb_srcptr Eapp, slong prec);

/* Eapp, R: n-vector / n x n scratch, left holding the QR approximations.
 * companion: C has the acb_mat_companion layout (enables the confluent
 * Vandermonde cluster basis). */
static int _rs_radius_eig(acb_ptr E, acb_ptr Eapp, acb_mat_t R,
                          const acb_mat_t C, int companion, slong prec)
{
    slong n = acb_mat_nrows(C);
    if (n == 1) {
        acb_set(E, acb_mat_entry(C, 0, 0));
        acb_set(Eapp, E);
        acb_one(acb_mat_entry(R, 0, 0));
        return acb_is_finite(E) ? RS_EIG_SIMPLE : RS_EIG_FAIL;
    }
    acb_mat_approx_eig_qr(Eapp, NULL, R, C, NULL, 0, prec);
    if (acb_mat_eig_simple(E, NULL, NULL, C, Eapp, R, prec))
        return RS_EIG_SIMPLE;
    if (companion && _rs_radius_companion_clusters(E, C, Eapp, prec))
        return RS_EIG_CLUSTER;
    if (acb_mat_eig_multiple_rump(E, C, Eapp, R, prec))
        return RS_EIG_CLUSTER;
    return RS_EIG_FAIL;
}

/* Cluster enclosures for a COMPANION matrix C (acb_mat_companion layout:
 * ones on the superdiagonal, last row -p_j/p_n).  Arb's
 * acb_mat_eig_multiple_rump takes the cluster basis from the QR eigenvectors,
 * which are nearly parallel at a (near-)defective eigenvalue.  Here the
 * basis is the confluent Vandermonde block v(c), v'(c), .., v^(k-1)(c)/(k-1)!
 * with v(x) = (1, x, .., x^(n-1)): it spans the invariant subspace of a
 * k-fold root c exactly, and of a tight k-cluster approximately.  Each
 * cluster goes through acb_mat_eig_enclosure_rump (a ball that contains
 * exactly k eigenvalues); success needs finite, pairwise disjoint balls. */
static int _rs_radius_companion_clusters(acb_ptr E, const acb_mat_t C,
                                         acb_srcptr Eapp, slong prec)
{
    slong n = acb_mat_nrows(C), i, j, c, k, lvl, ncl, pos;
    slong *label = flint_malloc(n * sizeof(slong));
    acb_ptr F = _acb_vec_init(n);
    acb_t ctr, t;
    acb_mat_t X;
    mag_t escale, eps, m;
    int ok = 0;

    acb_init(ctr);
    acb_init(t);
    mag_init(escale);
    mag_init(eps);
    mag_init(m);
    mag_one(escale);
    for (i = 0; i < n; i++) {
        acb_get_mag(m, Eapp + i);
        mag_max(escale, escale, m);
    }
    for (lvl = 0; lvl < 4 && !ok; lvl++) {
        /* escale * 2^(-3p/4), 2^(-p/2), 2^(-p/4), 2^(-p/8) */
        static const int num[4] = { 3, 2, 1, 1 }, den[4] = { 4, 2, 4, 8 };
        mag_mul_2exp_si(eps, escale, -(prec * num[lvl]) / den[lvl]);
        /* single-linkage grouping */
        for (i = 0; i < n; i++)
            label[i] = i;
        for (i = 0; i < n; i++)
            for (j = 0; j < n; j++) {
                acb_sub(t, Eapp + i, Eapp + j, MAG_BITS);
                acb_get_mag(m, t);
                if (mag_cmp(m, eps) <= 0 && label[j] != label[i]) {
                    slong old = label[j], nw = label[i];
                    for (c = 0; c < n; c++)
                        if (label[c] == old)
                            label[c] = nw;
                }
            }
        ok = 1;
        ncl = 0;
        pos = 0;
        for (i = 0; i < n && ok; i++) {
            if (label[i] != i)
                continue;   /* i is not a cluster representative */
            k = 0;
            acb_zero(ctr);
            for (j = 0; j < n; j++)
                if (label[j] == i) {
                    acb_add(ctr, ctr, Eapp + j, prec);
                    k++;
                }
            acb_div_si(ctr, ctr, k, prec);
            acb_get_mid(ctr, ctr);
            acb_mat_init(X, n, k);
            for (j = 0; j < k; j++)       /* X[r][j] = binom(r,j) c^(r-j) */
                for (c = j; c < n; c++) {
                    fmpz_t b;
                    fmpz_init(b);
                    fmpz_bin_uiui(b, c, j);
                    acb_pow_ui(t, ctr, c - j, prec);
                    acb_mul_fmpz(acb_mat_entry(X, c, j), t, b, prec);
                    fmpz_clear(b);
                }
            acb_mat_eig_enclosure_rump(F + ncl, NULL, X, C, ctr, X, prec);
            acb_mat_clear(X);
            if (!acb_is_finite(F + ncl))
                ok = 0;
            for (j = 0; j < k; j++)
                acb_set(E + pos + j, F + ncl);
            pos += k;
            ncl++;
        }
        for (i = 0; i < ncl && ok; i++)
            for (j = i + 1; j < ncl && ok; j++)
                if (acb_overlaps(F + i, F + j))
                    ok = 0;
    }
    acb_clear(ctr);
    acb_clear(t);
    mag_clear(escale);
    mag_clear(eps);
    mag_clear(m);
    _acb_vec_clear(F, n);
    flint_free(label);
    return ok;
}

/* Number of entries of E[0..n) identical (as balls) to E[i]. */
static slong _rs_radius_cluster_size(acb_srcptr E, slong n, slong i)
{
    slong j, c = 0;
    for (j = 0; j < n; j++)
        c += acb_equal(E + i, E + j);
    return c;
}

/* ------------------------------------------------------------------ */
/* exact input: zero roots + squarefree factors                        */

typedef struct {
    slong nzero;             /* multiplicity of the root 0 */
    slong deg;               /* deg p */
    fmpz_poly_factor_t fac;  /* squarefree factors of p / lambda^nzero */
} _rs_sqf_struct;

static int _rs_sqf_init(_rs_sqf_struct *s, const fmpz_poly_t p, rs_error_t err)
{
    fmpz_poly_t q;
    slong i, total;

    fmpz_poly_factor_init(s->fac);
    s->deg = fmpz_poly_degree(p);
    if (s->deg < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "radius: polynomial degree must be >= 1 (got %ld)",
                            (long) s->deg);
    s->nzero = 0;
    while (fmpz_is_zero(p->coeffs + s->nzero))
        s->nzero++;
    fmpz_poly_init(q);
    fmpz_poly_shift_right(q, p, s->nzero);
    if (fmpz_poly_degree(q) > 0)
        fmpz_poly_factor_squarefree(s->fac, q);
    fmpz_poly_clear(q);
    total = s->nzero;
    for (i = 0; i < s->fac->num; i++)
        total += fmpz_poly_degree(s->fac->p + i) * s->fac->exp[i];
    if (total != s->deg)
        return rs_error_set(err, RS_ERR_INTERNAL,
                            "radius: squarefree factorisation lost roots "
                            "(%ld of %ld)", (long) total, (long) s->deg);
    return RS_OK;
}

static void _rs_sqf_clear(_rs_sqf_struct *s)
{
    fmpz_poly_factor_clear(s->fac);
}

static int _rs_radius_to_double(double *a, const fmpz_poly_t q, rs_error_t err);
static int _rs_radius_gsl_solve(double *z, const double *a, slong d);

/* Enclosures of the roots of one squarefree factor f (deg d) into E at
 * precision *wp; *wp is raised to the highest working precision used.
 * *nouter: -1 when every ball is at that precision, else the number of
 * balls refined to it (rs_radius_outer_refine: the others are coarser). */
typedef int (*_rs_factor_roots_fn)(acb_ptr E, const fmpz_poly_t f, slong *wp, slong *nouter);

static int _rs_factor_roots_companion(acb_ptr E, const fmpz_poly_t f, slong *wp, slong *nouter)
{
    slong d = fmpz_poly_degree(f), prec = *wp;
    acb_poly_t P;
    acb_mat_t C, R;
    acb_ptr Eapp;
    int status;

    *nouter = -1;
    if (d == 1) { /* -f0/f1, no matrix needed */
        arb_fmpz_div_fmpz(acb_realref(E), f->coeffs, f->coeffs + 1, prec);
        arb_neg(acb_realref(E), acb_realref(E));
        arb_zero(acb_imagref(E));
        return RS_EIG_SIMPLE;
    }
    acb_poly_init(P);
    acb_mat_init(C, d, d);
    acb_mat_init(R, d, d);
    Eapp = _acb_vec_init(d);
    acb_poly_set_fmpz_poly(P, f, prec);
    acb_mat_companion(C, P, prec);
    status = _rs_radius_eig(E, Eapp, R, C, 1, prec);
    _acb_vec_clear(Eapp, d);
    acb_mat_clear(R);
    acb_mat_clear(C);
    acb_poly_clear(P);
    return status;
}

/* g(mu) = f(2^sc mu) up to a power of 2, with 2^sc about the geometric mean
 * of the root magnitudes (0 for moderate scales, |sc| < 32, so ordinary
 * results do not change): Durand-Kerner started near the unit circle
 * crawls for minutes on roots of magnitude 10^-600.  Roots of g times 2^sc
 * are the roots of f, exactly.  Returns sc. */
static slong _rs_radius_rescale(fmpz_poly_t g, const fmpz_poly_t f)
{
    slong n = fmpz_poly_degree(f), k = 0, sc, i;
    while (fmpz_is_zero(f->coeffs + k)) k++;
    sc = k < n ? ((slong) fmpz_bits(f->coeffs + k) - (slong) fmpz_bits(f->coeffs + n)) / (n - k) : 0;
    if (sc > -32 && sc < 32) sc = 0;
    fmpz_poly_fit_length(g, n + 1);
    /* sc > 0: coefficient i times 2^(sc i); sc < 0: times 2^(-sc (n - i)) */
    for (i = 0; i <= n; i++)
        fmpz_mul_2exp(g->coeffs + i, f->coeffs + i, (ulong) (sc > 0 ? sc * i : -sc * (n - i)));
    _fmpz_poly_set_length(g, n + 1);
    return sc;
}

/* The first route from degree RS_RADIUS_ABERTH_MIN_DEGREE: seeds in double
 * (Aberth from Newton-polygon points above degree 64, GSL's QR below, so
 * that the roots keep their order), then rs_radius_aberth_certify (Aberth
 * on Arb midpoints at a precision per root, inclusion discs).  Above
 * degree 64 and 160 bits, every root at 64 bits and only the possibly
 * largest ones at prec.  0: not certified, the caller goes on to
 * acb_poly_find_roots. */
static int _rs_factor_roots_aberth(acb_ptr E, const fmpz_poly_t f0, slong *wp, slong *nouter)
{
    slong d = fmpz_poly_degree(f0), sc, i, w = 0, no = -1;
    double *a = flint_malloc((d + 1) * sizeof(double));
    double *z = flint_malloc(2 * d * sizeof(double));
    fmpz_poly_t f;
    int ok = 0;

    fmpz_poly_init(f);
    sc = _rs_radius_rescale(f, f0);
    if (_rs_radius_to_double(a, f, NULL) == RS_OK && a[0] != 0.0 &&
        ((d > 64 && rs_radius_aberth_d(z, a, d, 100) >= 0) ||
         _rs_radius_gsl_solve(z, a, d) == GSL_SUCCESS ||
         rs_radius_aberth_d(z, a, d, 200) >= 0) &&
        /* ill-conditioned roots (Wilkinson-type, whose double seeds have no
         * correct digit): the secular equation's seeds; otherwise Aberth on
         * Arb needs about d sweeps at high precision (degree 200: 300
         * sweeps, then the fallback, 250 s).  Its result is only a seed:
         * on failure z stays as it was. */
        (d <= 64 || rs_radius_aberth_secular(z, f, a, 64) >= -1) &&
        rs_radius_aberth_certify(E, &w, &no, f, a, z, *wp,
                                 (d > RS_RADIUS_HIGH_DEGREE && *wp > 96) ? 64 : 0)) {
        for (i = 0; i < d && sc != 0; i++)
            acb_mul_2exp_si(E + i, E + i, sc);
        *wp = FLINT_MAX(*wp, w);
        *nouter = no;
        ok = 1;
    }
    fmpz_poly_clear(f);
    flint_free(a);
    flint_free(z);
    return ok;
}

/* acb_poly_find_roots seeded with the GSL double roots (when the
 * coefficients fit in double and GSL converges); certified when all d
 * output balls are isolated (then each holds exactly one root); otherwise
 * arb_fmpz_poly_complex_roots (certified, always isolates) at target prec. */
static int _rs_factor_roots_find(acb_ptr E, const fmpz_poly_t f0, slong *wp, slong *nouter)
{
    slong d = fmpz_poly_degree(f0), i, n, sc, prec = *wp;
    acb_poly_t P;
    acb_ptr init = NULL;
    double *a, *z;
    fmpz_poly_t f;

    *nouter = -1;
    if (d == 1)
        return _rs_factor_roots_companion(E, f0, wp, nouter);
    if (d >= RS_RADIUS_ABERTH_MIN_DEGREE && _rs_factor_roots_aberth(E, f0, wp, nouter))
        return RS_EIG_SIMPLE;
    if (rs_budget_exceeded())   /* no fallback past --time-limit: the loop reports it */
        return RS_EIG_FAIL;
    /* above degree 64 and well beyond 64 bits: every root at 64 bits (+ d/2,
     * below), then only the possibly largest ones to prec (outer.c); the
     * full route at prec when that does not certify */
    if (d > RS_RADIUS_HIGH_DEGREE && prec > 160) {
        slong w = 64, no;
        if (_rs_factor_roots_find(E, f0, &w, &no) == RS_EIG_SIMPLE &&
            rs_radius_outer_refine(E, nouter, f0, prec + d / 2)) {
            *wp = prec + d / 2;
            return RS_EIG_SIMPLE;
        }
    }
    /* Arb's Durand-Kerner + validation lose about d/2 bits at high degree
     * whatever the precision (measured: d = 100, 200, 300 lose 56, 106,
     * 152 bits; bench/README.md): working at prec + d/2 there certifies
     * in one pass instead of failing at prec and redoing all at 2 prec */
    if (d > 64)
        prec += d / 2;
    *wp = prec;
    fmpz_poly_init(f);
    sc = _rs_radius_rescale(f, f0);
    a = flint_malloc((d + 1) * sizeof(double));
    z = flint_malloc(2 * d * sizeof(double));
    /* seeds: from degree 65, Aberth in double (O(d^2) per sweep), else
     * GSL's companion QR (O(d^3); below 65 it is cheap, and keeping it
     * there keeps the printed roots and their order as they were); either
     * way Arb certifies below */
    if (_rs_radius_to_double(a, f, NULL) == RS_OK &&
        ((d > 64 && rs_radius_aberth_d(z, a, d, 100) >= 0) ||
         _rs_radius_gsl_solve(z, a, d) == GSL_SUCCESS)) {
        init = _acb_vec_init(d);
        for (i = 0; i < d; i++)
            acb_set_d_d(init + i, z[2 * i], z[2 * i + 1]);
    }
    acb_poly_init(P);
    acb_poly_set_fmpz_poly(P, f, prec);
    /* from good seeds Durand-Kerner converges quadratically: a few dozen
     * iterations suffice; bad seeds (e.g. Wilkinson-like clusters of real
     * roots, where GSL has no correct digit) get Arb's own start and more
     * iterations at the same precision.  Balls that are isolated are
     * certified whatever their width: the caller raises the precision (up
     * to its ceiling, never beyond: arb_fmpz_poly_complex_roots would raise
     * its own without bound on clusters like those at 10^-600 apart) until
     * the radius is narrow enough. */
    n = acb_poly_find_roots(E, P, init, 32, prec);
    if (n != d) {
        /* near a cluster the iteration converges linearly (about a bit per
         * step) until the precision resolves it: allow steps in proportion */
        n = acb_poly_find_roots(E, P, NULL, 8 * d + 100 + 2 * prec, prec);
    }
    {
        /* isolated but not accurate enough.  Either not converged (bad
         * seeds): restart from the midpoints, where the iteration converges
         * quadratically; or converged and the validation's evaluation
         * loses about the same number of bits at any precision (degree 200:
         * about 100 bits): restart once at a precision that covers that
         * loss instead of letting the caller double the whole computation.
         * Stop when a restart does not gain accuracy. */
        int round, raised = 0;
        slong acc, last = -1, p2 = prec;
        for (round = 0; round < 4 && n == d; round++) {
            acc = WORD_MAX;
            for (i = 0; i < d; i++)
                acc = FLINT_MIN(acc, acb_rel_accuracy_bits(E + i));
            if (acc >= prec - 40) break;
            if (last >= 0 && acc <= last) {
                if (raised || acc <= 0) break;
                p2 = FLINT_MIN(4 * prec, 2 * prec - 24 - acc);
                raised = 1;
            }
            last = acc;
            if (init == NULL) init = _acb_vec_init(d);
            for (i = 0; i < d; i++) acb_get_mid(init + i, E + i);
            if (p2 != prec) acb_poly_set_fmpz_poly(P, f, p2);
            *wp = p2;
            n = acb_poly_find_roots(E, P, init, 64, p2);
        }
    }
    if (sc != 0)
        for (i = 0; i < d; i++) acb_mul_2exp_si(E + i, E + i, sc);
    acb_poly_clear(P);
    fmpz_poly_clear(f);
    if (init != NULL)
        _acb_vec_clear(init, d);
    flint_free(a);
    flint_free(z);
    return n == d ? RS_EIG_SIMPLE : RS_EIG_FAIL;
}

static int _rs_factor_roots_arb(acb_ptr E, const fmpz_poly_t f, slong *wp, slong *nouter)
{
    *nouter = -1;
    rs_radius_complex_roots(E, f, *wp);
    return RS_EIG_SIMPLE;
}

/* The isolated balls E (one root each) of the squarefree factor f that meet
 * the real axis hold real roots when as many real roots exist (Sturm count,
 * exact): each real root lies in one of them and each holds one root.  Their
 * imaginary parts become exact zeros, so a real root reports Im = 0 (and its
 * continuous mode omega 0 or pi) instead of a ball such as 0e-45. */
static void _rs_roots_mark_real(acb_ptr E, const fmpz_poly_t f)
{
    slong d = fmpz_poly_degree(f), i, m = 0;
    /* the count costs about d^3 (degree 64: 10 ms, 500: 9 s): above 64 the
     * balls stay as they are (certified, printed rounded outward) */
    if (d > RS_RADIUS_HIGH_DEGREE)
        return;
    for (i = 0; i < d; i++)
        m += arb_contains_zero(acb_imagref(E + i));
    if (m == 0 || m != fmpz_poly_num_real_roots(f))
        return;
    for (i = 0; i < d; i++)
        if (arb_contains_zero(acb_imagref(E + i)))
            arb_zero(acb_imagref(E + i));
}

/* Fill r->roots at precision prec; returns the weakest status seen. */
static int _rs_sqf_roots(rs_radius_t r, const _rs_sqf_struct *s,
                         _rs_factor_roots_fn fn, slong prec)
{
    slong i, j, c, idx = 0, worst = RS_EIG_SIMPLE, full = s->nzero;
    int outer = 0;

    _rs_radius_alloc_roots(r, s->deg);
    for (i = 0; i < s->nzero; i++, idx++) {
        acb_zero(r->roots + idx);
        r->mult[idx] = s->nzero;
    }
    for (i = 0; i < s->fac->num; i++) {
        const fmpz_poly_struct *f = s->fac->p + i;
        slong d = fmpz_poly_degree(f), e = s->fac->exp[i];
        acb_ptr E = _acb_vec_init(d);
        slong w = prec;
        slong no = -1;
        int status = fn(E, f, &w, &no);
        if (w > r->prec)
            r->prec = w;
        outer |= no >= 0;
        full += (no >= 0 ? no : d) * e;
        if (status < worst)
            worst = status;
        if (status == RS_EIG_SIMPLE)
            _rs_roots_mark_real(E, f);
        if (status != RS_EIG_FAIL) {
            for (j = 0; j < d; j++)
                for (c = 0; c < e; c++, idx++) {
                    acb_set(r->roots + idx, E + j);
                    r->mult[idx] = e;
                }
        }
        _acb_vec_clear(E, d);
        if (status == RS_EIG_FAIL)
            break;
    }
    r->nouter = outer ? full : 0;
    return (int) worst;
}

/* Shared precision loop of the two exact routes.  prec0 is the first
 * precision handed to fn (a working precision or a target accuracy). */
static int _rs_radius_fmpz_loop(rs_radius_t r, const fmpz_poly_t p,
                                slong digits, slong max_prec,
                                _rs_factor_roots_fn fn, slong prec0,
                                int method, rs_error_t err)
{
    _rs_sqf_struct s;
    slong prec;
    int rc, status;

    rc = _rs_radius_check_args(digits, &max_prec, err);
    if (rc != RS_OK)
        return rc;
    _rs_radius_reset(r, digits);
    r->method = method;
    rc = _rs_sqf_init(&s, p, err);
    if (rc != RS_OK) {
        _rs_sqf_clear(&s);
        return rc;
    }
    prec = prec0 > max_prec ? max_prec : prec0;
    for (;;) {
        r->prec = prec;
        if ((rc = rs_budget_check(err, "the root refinement")) != RS_OK) break;
        status = _rs_sqf_roots(r, &s, fn, prec);
        if (status != RS_EIG_FAIL) {
            _rs_radius_rho_from_roots(r, prec);
            r->isolated = (status == RS_EIG_SIMPLE);
            if (_rs_radius_goal_met(r->rho, digits, 0)) {
                rc = RS_OK;
                break;
            }
        } else {
            _rs_radius_free_roots(r);
            arb_zero_pm_inf(r->rho);
            _rs_radius_set_bounds(r);
        }
        if (prec >= max_prec) {
            rc = _rs_radius_limit_error(r, max_prec, err);
            _rs_radius_keep_partial(r);
            break;
        }
        prec = (prec > max_prec / 2) ? max_prec : 2 * prec;
    }
    _rs_sqf_clear(&s);
    return rc;
}

int rs_radius_fmpz_poly_companion(rs_radius_t r, const fmpz_poly_t p,
                                  slong digits, slong max_prec,
                                  rs_error_t err)
{
    slong mp = max_prec <= 0 ? RS_RADIUS_MAX_PREC_DEFAULT : max_prec;
    return _rs_radius_fmpz_loop(r, p, digits, max_prec,
                                _rs_factor_roots_companion,
                                _rs_radius_start_prec(digits, mp),
                                RS_RADIUS_METHOD_COMPANION, err);
}

int rs_radius_fmpz_poly_complex_roots(rs_radius_t r, const fmpz_poly_t p,
                                      slong digits, slong max_prec,
                                      rs_error_t err)
{
    return _rs_radius_fmpz_loop(r, p, digits, max_prec, _rs_factor_roots_arb,
                                _rs_radius_bits_for(digits) + 8,
                                RS_RADIUS_METHOD_COMPLEX_ROOTS, err);
}

int rs_radius_fmpz_poly_find_roots(rs_radius_t r, const fmpz_poly_t p,
                                   slong digits, slong max_prec,
                                   rs_error_t err)
{
    slong mp = max_prec <= 0 ? RS_RADIUS_MAX_PREC_DEFAULT : max_prec;
    return _rs_radius_fmpz_loop(r, p, digits, max_prec, _rs_factor_roots_find,
                                _rs_radius_start_prec(digits, mp),
                                RS_RADIUS_METHOD_FIND_ROOTS, err);
}

int rs_radius_fmpz_poly(rs_radius_t r, const fmpz_poly_t p, slong digits,
                        slong max_prec, rs_error_t err)
{
    return rs_radius_fmpz_poly_find_roots(r, p, digits, max_prec, err);
}

/* ------------------------------------------------------------------ */
/* ball input: one (block) companion matrix per precision              */

/* Builds the matrix at prec.  Returns RS_OK, RS_ERR_UNDECIDED to ask for a
 * higher precision (only when !last), or a final error code. */
typedef int (*_rs_build_fn)(acb_mat_t C, const void *data, slong prec,
                            int last, rs_error_t err);

/* Certified enclosure of rho when the eigenvalues could not be certified:
 * upper = min(||C||_inf, max|Eapp_i| + eps) (eps: acb_mat_eig_global_enclosure,
 * every eigenvalue lies within eps of some Eapp_i), lower = |det C|^(1/n). */
static void _rs_radius_bound(arb_t rho, const acb_mat_t C, acb_srcptr Eapp,
                             const acb_mat_t R, slong prec)
{
    slong i, n = acb_mat_nrows(C);
    mag_t u, eps, t;
    acb_t det;
    arb_t lo;
    arf_t l, h;

    mag_init(u);
    mag_init(eps);
    mag_init(t);
    acb_init(det);
    arb_init(lo);
    arf_init(l);
    arf_init(h);

    acb_mat_bound_inf_norm(u, C);
    acb_mat_eig_global_enclosure(eps, C, Eapp, R, prec);
    if (mag_is_finite(eps)) {
        mag_zero(t);
        for (i = 0; i < n; i++) {
            mag_t a;
            mag_init(a);
            acb_get_mag(a, Eapp + i);
            mag_max(t, t, a);
            mag_clear(a);
        }
        mag_add(t, t, eps);
        mag_min(u, u, t);
    }
    acb_mat_det(det, C, prec);
    acb_abs(lo, det, prec);
    arb_root_ui(lo, lo, n, prec);
    arb_get_lbound_arf(l, lo, prec);
    if (arf_sgn(l) < 0 || !arf_is_finite(l))
        arf_zero(l);
    arf_set_mag(h, u);
    if (arf_cmp(l, h) > 0)   /* cannot happen for a valid enclosure */
        arf_set(l, h);
    arb_set_interval_arf(rho, l, h, prec);

    mag_clear(u);
    mag_clear(eps);
    mag_clear(t);
    acb_clear(det);
    arb_clear(lo);
    arf_clear(l);
    arf_clear(h);
}

/* Width of a ball as a double (inf when not finite), for comparisons. */
static double _rs_radius_width(const arb_t x)
{
    if (!arb_is_finite(x))
        return HUGE_VAL;
    return 2.0 * mag_get_d(arb_radref(x));
}

static void _rs_radius_fill_eig(rs_radius_t r, slong nzero, acb_srcptr E,
                                slong n, int status)
{
    slong i;
    _rs_radius_alloc_roots(r, nzero + n);
    for (i = 0; i < nzero; i++) {
        acb_zero(r->roots + i);
        r->mult[i] = nzero;
    }
    for (i = 0; i < n; i++) {
        acb_set(r->roots + nzero + i, E + i);
        r->mult[nzero + i] = (status == RS_EIG_SIMPLE)
                                 ? 1 : _rs_radius_cluster_size(E, n, i);
    }
}

static int _rs_build_companion(acb_mat_t C, const void *data, slong prec,
                               int last, rs_error_t err);

/* Adaptive loop: n = matrix size, nzero = exact zero roots put in front.
 * cap_prec: precision beyond which the input balls make raising useless. */
static int _rs_radius_ball_engine(rs_radius_t r, slong n, slong nzero,
                                  _rs_build_fn build, const void *data,
                                  slong digits, slong max_prec, slong cap_prec,
                                  rs_error_t err)
{
    acb_mat_t C, R;
    acb_ptr E, Eapp;
    arb_t best;
    slong prec, stop;
    double width, prev_width = HUGE_VAL;
    int rc = RS_OK, status, ever_certified = 0, stagnated = 0, last;

    stop = cap_prec < max_prec ? cap_prec : max_prec;
    prec = _rs_radius_start_prec(digits, stop);
    acb_mat_init(C, n, n);
    acb_mat_init(R, n, n);
    E = _acb_vec_init(n);
    Eapp = _acb_vec_init(n);
    arb_init(best);
    arb_zero_pm_inf(best);

    for (;;) {
        last = (prec >= stop);
        r->prec = prec;
        if ((rc = rs_budget_check(err, "the eigenvalue refinement")) != RS_OK) goto cleanup;
        rc = build(C, data, prec, last, err);
        if (rc == RS_ERR_UNDECIDED && !last) {
            prec = (prec > stop / 2) ? stop : 2 * prec;
            continue;
        }
        if (rc != RS_OK)
            goto cleanup;
        status = _rs_radius_eig(E, Eapp, R, C, build == _rs_build_companion,
                                prec);
        if (status != RS_EIG_FAIL) {
            ever_certified = 1;
            _rs_radius_fill_eig(r, nzero, E, n, status);
            _rs_radius_rho_from_roots(r, prec);
            r->isolated = (status == RS_EIG_SIMPLE);
            r->method = RS_RADIUS_METHOD_COMPANION;
            if (_rs_radius_goal_met(r->rho, digits, 1)) {
                rc = RS_OK;
                goto cleanup;
            }
            width = _rs_radius_width(r->rho);
            if (width < HUGE_VAL && width > 0.5 * prev_width)
                stagnated = 1;   /* doubling did not help: input-limited */
            prev_width = width;
            if (width < _rs_radius_width(best))
                arb_set(best, r->rho);
        } else {
            prev_width = HUGE_VAL;
            _rs_radius_bound(r->rho, C, Eapp, R, prec);
            if (_rs_radius_width(r->rho) < _rs_radius_width(best))
                arb_set(best, r->rho);
        }
        if (last || stagnated)
            break;
        prec = (prec > stop / 2) ? stop : 2 * prec;
    }

    /* failure: report the best certified enclosure seen */
    arb_set(r->rho, best);
    _rs_radius_set_bounds(r);
    _rs_radius_keep_partial(r);
    if (!ever_certified)
        r->method = RS_RADIUS_METHOD_BOUND;
    r->isolated = 0;
    if (ever_certified && !stagnated && stop == max_prec) {
        rc = _rs_radius_limit_error(r, max_prec, err);
    } else if (ever_certified) {
        rc = rs_error_set(err, RS_ERR_UNDECIDED,
            "radius: the coefficient balls allow only ~%ld of the %ld "
            "digits requested (stopped at %ld bits)",
            (long) _rs_radius_digits_got(r->rho), (long) digits, (long) prec);
    } else {
        char *lo = rs_radius_str_lower(r->lower, 10);
        char *hi = rs_radius_str_upper(r->upper, 10);
        rc = rs_error_set(err, RS_ERR_UNDECIDED,
            "radius: eigenvalues could not be isolated at %ld bits (multiple "
            "root or cluster within the coefficient balls%s); only "
            "%s <= rho <= %s is certified", (long) prec,
            stop == max_prec ? "; precision limit reached, raise with "
                               "--max-prec" : "", lo, hi);
        flint_free(lo);
        flint_free(hi);
    }

cleanup:
    arb_clear(best);
    _acb_vec_clear(Eapp, n);
    _acb_vec_clear(E, n);
    acb_mat_clear(R);
    acb_mat_clear(C);
    return rc;
}

/* Precision beyond which inexact input cannot yield more: 2A + 128 where A
 * is the best relative accuracy (bits) among the inexact entries. */
static slong _rs_radius_cap(acb_srcptr v, slong len, slong max_prec)
{
    slong i, acc = WORD_MIN, a;
    int inexact = 0;
    for (i = 0; i < len; i++) {
        if (acb_is_exact(v + i))
            continue;
        inexact = 1;
        a = acb_rel_accuracy_bits(v + i);
        if (a > acc)
            acc = a;
    }
    if (!inexact)
        return max_prec;
    if (acc < 0)
        acc = 0;
    if (acc > max_prec)
        return max_prec;
    a = 2 * acc + 128;
    return a > max_prec ? max_prec : a;
}

static int _rs_build_companion(acb_mat_t C, const void *data, slong prec,
                               int last, rs_error_t err)
{
    (void) last;
    (void) err;
    acb_mat_companion(C, (const acb_poly_struct *) data, prec);
    return RS_OK;
}

int rs_radius_acb_poly(rs_radius_t r, const acb_poly_t p, slong digits,
                       slong max_prec, rs_error_t err)
{
    slong len = acb_poly_length(p), nzero = 0, d, cap;
    acb_poly_t q;
    int rc;

    rc = _rs_radius_check_args(digits, &max_prec, err);
    if (rc != RS_OK)
        return rc;
    _rs_radius_reset(r, digits);
    if (len < 2)
        return rs_error_set(err, RS_ERR_INPUT,
                            "radius: polynomial degree must be >= 1 (got %ld)",
                            (long) len - 1);
    if (!acb_is_finite(p->coeffs + len - 1) ||
        acb_contains_zero(p->coeffs + len - 1))
        return rs_error_set(err, RS_ERR_UNDECIDED,
                            "radius: leading coefficient ball contains 0 (or "
                            "is not finite): the degree is undetermined");
    while (acb_is_zero(p->coeffs + nzero))
        nzero++;
    d = len - 1 - nzero;
    if (d > RS_RADIUS_MAX_DIM)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "radius: degree %ld exceeds the limit %d", (long) d,
                            RS_RADIUS_MAX_DIM);
    if (d == 0) { /* c * lambda^nzero */
        _rs_radius_fill_eig(r, nzero, NULL, 0, RS_EIG_SIMPLE);
        _rs_radius_rho_from_roots(r, 64);
        r->method = RS_RADIUS_METHOD_COMPANION;
        r->isolated = 1;
        return RS_OK;
    }
    acb_poly_init(q);
    acb_poly_shift_right(q, p, nzero);
    cap = _rs_radius_cap(q->coeffs, d + 1, max_prec);
    rc = _rs_radius_ball_engine(r, d, nzero, _rs_build_companion, q, digits,
                                max_prec, cap, err);
    acb_poly_clear(q);
    return rc;
}

typedef struct {
    const acb_mat_struct *A;
    slong k;
    slong m;
} _rs_matpoly_struct;

/* Block companion [0 I ..; ..; -A_k^-1 A_0 .. -A_k^-1 A_{k-1}]. */
static int _rs_build_block_companion(acb_mat_t C, const void *data, slong prec,
                                     int last, rs_error_t err)
{
    const _rs_matpoly_struct *mp = data;
    slong k = mp->k, m = mp->m, b, i, j;
    acb_mat_t Ainv, T;
    int rc = RS_OK;

    acb_mat_init(Ainv, m, m);
    acb_mat_init(T, m, m);
    if (!acb_mat_inv(Ainv, mp->A + k, prec)) {
        acb_t det;
        acb_init(det);
        acb_mat_det(det, mp->A + k, prec);
        if (acb_is_zero(det))
            rc = rs_error_set(err, RS_ERR_MATH,
                              "radius: leading matrix A[%ld] is singular "
                              "(det = 0): the recurrence does not determine "
                              "z[n+%ld]", (long) k, (long) k);
        else if (last)
            rc = rs_error_set(err, RS_ERR_MATH,
                              "radius: leading matrix A[%ld] could not be "
                              "certified invertible at %ld bits (singular or "
                              "nearly so)", (long) k, (long) prec);
        else
            rc = RS_ERR_UNDECIDED;
        acb_clear(det);
        goto cleanup;
    }
    acb_mat_zero(C);
    for (b = 0; b + 1 < k; b++)
        for (i = 0; i < m; i++)
            acb_one(acb_mat_entry(C, b * m + i, (b + 1) * m + i));
    for (b = 0; b < k; b++) {
        acb_mat_mul(T, Ainv, mp->A + b, prec);
        for (i = 0; i < m; i++)
            for (j = 0; j < m; j++)
                acb_neg(acb_mat_entry(C, (k - 1) * m + i, b * m + j),
                        acb_mat_entry(T, i, j));
    }
cleanup:
    acb_mat_clear(T);
    acb_mat_clear(Ainv);
    return rc;
}

int rs_radius_matrix_poly(rs_radius_t r, const acb_mat_struct *A, slong k,
                          slong digits, slong max_prec, rs_error_t err)
{
    _rs_matpoly_struct mp;
    slong j, i, m, cap;
    int rc;

    rc = _rs_radius_check_args(digits, &max_prec, err);
    if (rc != RS_OK)
        return rc;
    _rs_radius_reset(r, digits);
    if (A == NULL || k < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "radius: matrix recurrence needs A[0..k], k >= 1");
    m = acb_mat_nrows(A);
    for (j = 0; j <= k; j++)
        if (acb_mat_nrows(A + j) != m || acb_mat_ncols(A + j) != m)
            return rs_error_set(err, RS_ERR_INPUT,
                                "radius: A[%ld] is %ldx%ld, expected %ldx%ld",
                                (long) j, (long) acb_mat_nrows(A + j),
                                (long) acb_mat_ncols(A + j), (long) m, (long) m);
    if (m < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "radius: empty coefficient matrices");
    if (k * m > RS_RADIUS_MAX_DIM)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "radius: block companion size %ld exceeds the "
                            "limit %d", (long) (k * m), RS_RADIUS_MAX_DIM);
    cap = max_prec;
    for (j = 0; j <= k; j++)
        for (i = 0; i < m; i++) {
            slong c = _rs_radius_cap(A[j].rows[i], m, max_prec);
            if (j == 0 && i == 0)
                cap = c;
            else if (c > cap)
                cap = c;
        }
    mp.A = A;
    mp.k = k;
    mp.m = m;
    return _rs_radius_ball_engine(r, k * m, 0, _rs_build_block_companion, &mp,
                                  digits, max_prec, cap, err);
}

/* ------------------------------------------------------------------ */
/* uncertified GSL baseline                                            */

/* a[0..len) = coefficients of q as doubles, scaled by a common 2^-shift so
 * that the largest fits; RS_ERR_LIMIT if another would leave the normal
 * double range. */
static int _rs_radius_to_double(double *a, const fmpz_poly_t q, rs_error_t err)
{
    slong i, len = fmpz_poly_length(q), maxe = WORD_MIN, shift = 0, e;
    for (i = 0; i < len; i++) {
        if (fmpz_is_zero(q->coeffs + i))
            continue;
        fmpz_get_d_2exp(&e, q->coeffs + i);
        if (e > maxe)
            maxe = e;
    }
    if (maxe > 1000)
        shift = maxe - 1000;
    for (i = 0; i < len; i++) {
        double m;
        if (fmpz_is_zero(q->coeffs + i)) {
            a[i] = 0.0;
            continue;
        }
        m = fmpz_get_d_2exp(&e, q->coeffs + i);
        if (e - shift < -1020)
            return rs_error_set(err, RS_ERR_LIMIT,
                                "radius (double): coefficient of lambda^%ld "
                                "underflows double after scaling by 2^-%ld "
                                "(coefficients span more than 2^2020)",
                                (long) i, (long) shift);
        a[i] = ldexp(m, (int) (e - shift));
    }
    return RS_OK;
}

/* GSL companion-QR roots of a[0..d] (d >= 1, a[d] != 0) into z[0..2d);
 * GSL's error handler is off (rs_gsl_quiet).  Returns a GSL status. */
static int _rs_radius_gsl_solve(double *z, const double *a, slong d)
{
    gsl_poly_complex_workspace *w;
    int st;

    if (a[d] == 0.0)
        return GSL_EINVAL;
    if (d == 1) {
        z[0] = -a[0] / a[1];
        z[1] = 0.0;
        return GSL_SUCCESS;
    }
    /* GSL's handler off once for the process (error.h), not swapped per
     * call: a saved and restored handler races between threads */
    rs_gsl_quiet();
    w = gsl_poly_complex_workspace_alloc(d + 1);
    st = (w == NULL) ? GSL_ENOMEM : gsl_poly_complex_solve(a, d + 1, w, z);
    if (w != NULL)
        gsl_poly_complex_workspace_free(w);
    return st;
}

int rs_radius_double(rs_radius_t r, const fmpz_poly_t p, rs_error_t err)
{
    slong deg = fmpz_poly_degree(p), nzero = 0, d, i;
    fmpz_poly_t q;
    double *a = NULL, *z = NULL, rho = 0.0;
    int rc = RS_OK;

    _rs_radius_reset(r, 0);
    if (deg < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "radius: polynomial degree must be >= 1 (got %ld)",
                            (long) deg);
    while (fmpz_is_zero(p->coeffs + nzero))
        nzero++;
    d = deg - nzero;
    fmpz_poly_init(q);
    fmpz_poly_shift_right(q, p, nzero);
    a = flint_malloc((d + 1) * sizeof(double));
    z = flint_malloc((2 * d + 2) * sizeof(double));
    rc = _rs_radius_to_double(a, q, err);
    if (rc != RS_OK)
        goto cleanup;
    if (d >= 1) {
        int st = _rs_radius_gsl_solve(z, a, d);
        if (st != GSL_SUCCESS) {
            rc = rs_error_set(err, RS_ERR_UNDECIDED,
                              "radius (double): gsl_poly_complex_solve failed: "
                              "%s", gsl_strerror(st));
            goto cleanup;
        }
    }
    _rs_radius_alloc_roots(r, deg);
    for (i = 0; i < nzero; i++) {
        acb_zero(r->roots + i);
        r->mult[i] = nzero;
    }
    for (i = 0; i < d; i++) {
        double m = hypot(z[2 * i], z[2 * i + 1]);
        acb_set_d_d(r->roots + nzero + i, z[2 * i], z[2 * i + 1]);
        r->mult[nzero + i] = 1;
        if (m > rho)
            rho = m;
    }
    r->rho_double = rho;
    r->method_double = 1;
    r->method = RS_RADIUS_METHOD_DOUBLE;
    r->prec = 53;
    arb_set_d(r->rho, rho);   /* a point, NOT a certified ball */
    arb_zero(r->lower);
    arb_pos_inf(r->upper);
cleanup:
    flint_free(a);
    flint_free(z);
    fmpz_poly_clear(q);
    return rc;
}

/* ------------------------------------------------------------------ */
/* printing certified numbers: directed decimal conversion             */

/* Exponents beyond this (in bits) are not handed to MPFR, whose default
 * exponent range is about 2^30 (the range is global state: left alone). */
#define RS_STR_MAX_EXP (WORD(1) << 26)

/* Decimal text of sign * 0.D * 10^e (D = the digits, k of them).  Fixed
 * notation when -4 <= e <= k, else d.ddde+X; trim drops trailing zeros
 * (only when the decimal is exact, so that no shown zero is a claim).
 * One formatter with the double route (util/dblstr.c). */
static char *_rs_str_format(int neg, const char *D, slong e, int trim)
{
    slong k = (slong) strlen(D);
    char *out = flint_malloc(k + 48 + (e < 0 ? -e : 0));
    rs_dblstr_format(out, neg, D, (long) k, (long) e, trim);
    return out;
}

/* x as a double when that is exact and of moderate exponent (the double
 * route of util/dblstr.c applies), else 0 */
static int _rs_str_dbl(double *d, const arf_t x)
{
    if (arf_bits(x) > 53 || arf_cmpabs_2exp_si(x, 1000) >= 0 || arf_cmpabs_2exp_si(x, -1000) <= 0)
        return 0;
    *d = arf_get_d(x, ARF_RND_NEAR);   /* exact */
    return 1;
}

/* x rounded to n significant decimal digits in direction rnd (MPFR_RNDD,
 * RNDU, RNDN, RNDZ) as digits D (malloc'd, no sign) and exponent e:
 * |x| ~ 0.D * 10^e.  x must be finite, nonzero and of moderate exponent. */
static char *_rs_str_digits(slong *e, int *neg, const arf_t x, slong n,
                            mpfr_rnd_t rnd)
{
    mpfr_t m;
    mpfr_exp_t ex;
    char *s, *D;
    mpfr_init2(m, FLINT_MAX(arf_bits(x), 2));
    arf_get_mpfr(m, x, MPFR_RNDN);           /* exact: enough bits */
    s = mpfr_get_str(NULL, &ex, 10, (size_t) n, m, rnd);
    *neg = (s[0] == '-');
    D = flint_malloc(strlen(s) + 1);
    strcpy(D, s + *neg);
    mpfr_free_str(s);
    mpfr_clear(m);
    *e = (slong) ex;
    return D;
}

static int _rs_str_in_range(const arf_t x)
{
    return arf_cmpabs_2exp_si(x, RS_STR_MAX_EXP) < 0 &&
           arf_cmpabs_2exp_si(x, -RS_STR_MAX_EXP) > 0;
}

static char *_rs_str_dup(const char *s)
{
    char *t = flint_malloc(strlen(s) + 1);
    strcpy(t, s);
    return t;
}

char *rs_radius_arf_str(const arf_t x, slong n, arf_rnd_t rnd)
{
    mpfr_rnd_t m = rnd == ARF_RND_FLOOR ? MPFR_RNDD : rnd == ARF_RND_CEIL ? MPFR_RNDU
                 : rnd == ARF_RND_DOWN ? MPFR_RNDZ : rnd == ARF_RND_UP ? MPFR_RNDA
                 : MPFR_RNDN;
    slong e, ed;
    int neg, negd, exact;
    char *D, *Dd, *s;

    n = n < 1 ? 1 : n;
    if (arf_is_zero(x))
        return _rs_str_dup("0");
    if (arf_is_nan(x))
        return _rs_str_dup("nan");
    if (arf_is_pos_inf(x))
        return _rs_str_dup("inf");
    if (arf_is_neg_inf(x))
        return _rs_str_dup("-inf");
    if (!_rs_str_in_range(x)) {
        /* weak but true directed bounds; no nearest value is offered */
        int big = arf_cmpabs_2exp_si(x, 0) > 0, pos = arf_sgn(x) > 0;
        if (m == MPFR_RNDD)
            return _rs_str_dup(pos ? (big ? "1" : "0") : "-inf");
        if (m == MPFR_RNDU)
            return _rs_str_dup(pos ? "inf" : (big ? "-1" : "0"));
        {
            arb_t b;
            arb_init(b);
            arb_set_arf(b, x);
            s = arb_get_str(b, n, 0);
            arb_clear(b);
            return s;
        }
    }
    {   /* a double: digits by printf, the direction certified exactly
         * (util/dblstr.c; the same string as below, without MPFR) */
        double xd;
        char b[RS_DBLSTR_SIZE];
        int pos = arf_sgn(x) > 0,
            dir = m == MPFR_RNDD ? -1 : m == MPFR_RNDU ? 1 : m == MPFR_RNDZ ? (pos ? -1 : 1)
                : m == MPFR_RNDA ? (pos ? 1 : -1) : 0;
        if (n <= 17 && _rs_str_dbl(&xd, x) && rs_dblstr_round(b, xd, (int) n, dir) >= 0)
            return _rs_str_dup(b);
    }
    /* the n-digit decimal is exact iff rounding down and up agree */
    D = _rs_str_digits(&e, &neg, x, n, MPFR_RNDD);
    Dd = _rs_str_digits(&ed, &negd, x, n, MPFR_RNDU);
    exact = (e == ed && strcmp(D, Dd) == 0);
    if (!exact && m != MPFR_RNDD) {
        flint_free(D);
        D = (m == MPFR_RNDU) ? Dd : _rs_str_digits(&e, &neg, x, n, m);
        if (m == MPFR_RNDU) {
            e = ed;
            Dd = NULL;
        }
    }
    s = _rs_str_format(neg, D, e, exact);
    flint_free(D);
    flint_free(Dd);
    return s;
}

char *rs_radius_str_lower(const arb_t x, slong n)
{
    arf_t t;
    char *s;
    arf_init(t);
    arb_get_lbound_arf(t, x, ARF_PREC_EXACT);
    s = rs_radius_arf_str(t, n, ARF_RND_FLOOR);
    arf_clear(t);
    return s;
}

char *rs_radius_str_upper(const arb_t x, slong n)
{
    arf_t t;
    char *s;
    arf_init(t);
    arb_get_ubound_arf(t, x, ARF_PREC_EXACT);
    s = rs_radius_arf_str(t, n, ARF_RND_CEIL);
    arf_clear(t);
    return s;
}

/* Largest k <= n with lo and hi rounding to the same k-digit decimal (then,
 * rounding being monotone, so does every point between), else 0. */
static slong _rs_str_agree(const arf_t lo, const arf_t hi, slong n)
{
    arf_t w;
    slong k, k0, e1, e2;
    int n1, n2, same = 0;
    char *D1, *D2;

    /* the width w = hi - lo decides k within a digit or two:
     * start at ~ log10(|lo| / w) + 2 */
    arf_init(w);
    arf_sub(w, hi, lo, ARF_PREC_EXACT, ARF_RND_DOWN);
    if (arf_is_zero(w))
        k0 = n;
    else
        k0 = (slong) ((double) (arf_abs_bound_lt_2exp_si(lo) -
                                arf_abs_bound_lt_2exp_si(w)) * 0.30103) + 3;
    arf_clear(w);
    k0 = FLINT_MIN(FLINT_MAX(k0, 1), n);
    for (k = k0; k >= 1 && !same; k--) {
        D1 = _rs_str_digits(&e1, &n1, lo, k, MPFR_RNDN);
        D2 = _rs_str_digits(&e2, &n2, hi, k, MPFR_RNDN);
        same = (e1 == e2 && n1 == n2 && strcmp(D1, D2) == 0);
        flint_free(D1);
        flint_free(D2);
    }
    return same ? k + 1 : 0;
}

char *rs_radius_interval_str(const arf_t lo, const arf_t hi, slong n)
{
    slong k;
    n = n < 1 ? 1 : n;
    if (arf_is_nan(lo) || arf_is_nan(hi) || arf_cmp(lo, hi) > 0)
        return _rs_str_dup("nan");
    if (arf_equal(lo, hi) && (arf_is_zero(lo) || arf_is_inf(lo)))
        return rs_radius_arf_str(lo, n, ARF_RND_NEAR);
    {   /* doubles: util/dblstr.c (the same string as below, without MPFR) */
        double a, b;
        char buf[RS_DBLSTR_SIZE];
        if (n <= 17 && _rs_str_dbl(&a, lo) && _rs_str_dbl(&b, hi) && rs_dblstr_interval(buf, a, b, (int) n) >= 0)
            return _rs_str_dup(buf);
    }
    if (arf_sgn(lo) * arf_sgn(hi) > 0 && !arf_is_inf(lo) && !arf_is_inf(hi) &&
        _rs_str_in_range(lo) && _rs_str_in_range(hi)) {
        k = _rs_str_agree(lo, hi, n);
        if (k > 0)   /* exact when lo == hi is a k-digit decimal */
            return rs_radius_arf_str(arf_cmpabs(lo, hi) <= 0 ? lo : hi, k,
                                     ARF_RND_NEAR);
    } else if (arf_sgn(lo) <= 0 && arf_sgn(hi) >= 0 && arf_is_finite(lo) &&
               arf_is_finite(hi) && _rs_str_in_range(arf_cmpabs(lo, hi) >= 0 ? lo : hi)) {
        /* around 0: "0eX" with max(|lo|, |hi|) <= 10^X / 2, i.e. every value
         * rounds to 0 at the digit 10^X (Arb prints such balls alike) */
        arf_t m;
        slong e;
        int neg;
        char *D, buf[48];
        arf_init(m);
        arf_abs(m, arf_cmpabs(lo, hi) >= 0 ? lo : hi);
        arf_mul_2exp_si(m, m, 1);
        D = _rs_str_digits(&e, &neg, m, 1, MPFR_RNDU);   /* 2m <= 10^e */
        snprintf(buf, sizeof buf, "0e%+ld", (long) e);
        flint_free(D);
        arf_clear(m);
        return _rs_str_dup(buf);
    }
    {   /* not one digit is certain: Arb's own [mid +/- rad], which parses
         * back (arb_set_str) to a ball containing the interval */
        arb_t b;
        char *s;
        arb_init(b);
        arb_set_interval_arf(b, lo, hi, ARF_PREC_EXACT);
        s = arb_get_str(b, 5, 0);
        arb_clear(b);
        return s;
    }
}

char *rs_radius_arb_str(const arb_t x, slong n)
{
    arf_t lo, hi;
    char *s;
    arf_init(lo);
    arf_init(hi);
    arb_get_lbound_arf(lo, x, ARF_PREC_EXACT);
    arb_get_ubound_arf(hi, x, ARF_PREC_EXACT);
    s = rs_radius_interval_str(lo, hi, n);
    arf_clear(lo);
    arf_clear(hi);
    return s;
}

char *rs_radius_str_ball(mag_t rad, const arb_t x, slong n)
{
    slong e;
    int neg;
    char *D;
    mag_t u;
    n = n < 1 ? 1 : n;
    mag_set(rad, arb_radref(x));
    if (arf_is_zero(arb_midref(x)) || !arf_is_finite(arb_midref(x)))
        return rs_radius_arf_str(arb_midref(x), n, ARF_RND_NEAR);
    mag_init(u);
    if (!_rs_str_in_range(arb_midref(x))) {
        /* printed as 0: the whole midpoint joins the radius */
        arf_get_mag(u, arb_midref(x));
        mag_add(rad, rad, u);
        mag_clear(u);
        return _rs_str_dup("0");
    }
    /* |mid - printed| <= 10^(e - n), one unit of the last digit */
    D = _rs_str_digits(&e, &neg, arb_midref(x), n, MPFR_RNDN);
    flint_free(D);
    if (e >= n) {
        mag_set_ui(u, 10);
        mag_pow_ui(u, u, (ulong) (e - n));
    } else {
        mag_t t;
        mag_init(t);
        mag_set_ui_lower(t, 10);
        mag_pow_ui_lower(t, t, (ulong) (n - e));
        mag_one(u);
        mag_div(u, u, t);       /* rounded up */
        mag_clear(t);
    }
    mag_add(rad, rad, u);
    mag_clear(u);
    return rs_radius_arf_str(arb_midref(x), n, ARF_RND_NEAR);
}

/* Root magnitudes far from 1 (w = 10^600: |lambda| ~ 10^-600) make
 * Durand-Kerner, started on the unit circle, crawl for minutes to hours:
 * solve g(mu) = f(2^s mu) instead, 2^s the geometric mean of the non-zero
 * roots' magnitudes, and scale the roots back exactly.  Moderate scales
 * (|s| < 32) are left alone so that ordinary results do not change. */
void rs_radius_complex_roots(acb_ptr roots, const fmpz_poly_t f, slong prec)
{
    slong n = fmpz_poly_degree(f), s, i;
    fmpz_poly_t g;
    if (n < 1) return;
    fmpz_poly_init(g);
    s = _rs_radius_rescale(g, f);
    arb_fmpz_poly_complex_roots(roots, g, 0, prec);
    for (i = 0; i < n; i++)
        acb_mul_2exp_si(roots + i, roots + i, s);
    fmpz_poly_clear(g);
}

const char *rs_radius_verdict(const rs_radius_t rr)
{
    arb_t one;
    const char *v;
    arb_init(one);
    arb_one(one);
    v = arb_lt(rr->upper, one) ? "stable" : arb_gt(rr->lower, one) ? "unstable" : "undecided";
    arb_clear(one);
    return v;
}
