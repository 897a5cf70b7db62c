/* cosim_ball.c -- see numeric/cosim_ball.h.  The ball one-step map itself
 * is cosim.c's engine (rs_cosim_ball_transition); here the model's storage
 * and the Stein certificates. */
#include <math.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_complex_math.h>
#include <acb_mat.h>
#include "numeric/cosim_ball.h"

void rs_cosim_ball_init(rs_cosim_ball_t b)
{
    b->n1 = b->n2 = b->m = 0;
    arb_mat_init(b->A1, 0, 0);
    arb_mat_init(b->A2, 0, 0);
    arb_mat_init(b->B1, 0, 0);
    arb_mat_init(b->B2, 0, 0);
    arb_mat_init(b->C, 0, 0);
    arb_init(b->H);
    b->method = RS_COSIM_EXPLICIT;
    b->order = 0;
    b->ext = RS_COSIM_EXT_NONE;
    fmpq_init(b->alpha_T);
    fmpq_set_si(b->alpha_T, 1, 2);
}

void rs_cosim_ball_set_ext(rs_cosim_ball_t b, int ext, const fmpq_t alpha_T)
{
    b->ext = ext;
    if (alpha_T != NULL) fmpq_set(b->alpha_T, alpha_T);
    else fmpq_set_si(b->alpha_T, 1, 2);
}

void rs_cosim_ball_clear(rs_cosim_ball_t b)
{
    arb_mat_clear(b->A1);
    arb_mat_clear(b->A2);
    arb_mat_clear(b->B1);
    arb_mat_clear(b->B2);
    arb_mat_clear(b->C);
    arb_clear(b->H);
    fmpq_clear(b->alpha_T);
}

void rs_cosim_ball_set_dims(rs_cosim_ball_t b, slong n1, slong n2, slong m, int method, slong order)
{
    /* the matrices only: ext and alpha_T are kept */
    arb_mat_clear(b->A1);
    arb_mat_clear(b->A2);
    arb_mat_clear(b->B1);
    arb_mat_clear(b->B2);
    arb_mat_clear(b->C);
    b->n1 = n1;
    b->n2 = n2;
    b->m = m;
    arb_mat_init(b->A1, n1, n1);
    arb_mat_init(b->A2, n2, n2);
    arb_mat_init(b->B1, n1, m);
    arb_mat_init(b->B2, n2, m);
    arb_mat_init(b->C, m, n1 + n2);
    arb_zero(b->H);
    b->method = method;
    b->order = order;
}

void rs_cosim_ball_set(rs_cosim_ball_t b, const rs_cosim_t cs, const fmpq_mat_t B1, const fmpq_mat_t B2,
                       const fmpq_mat_t C, slong m, slong prec)
{
    rs_cosim_ball_set_dims(b, cs->n1, cs->n2, m, cs->method, cs->order);
    arb_mat_set_fmpq_mat(b->A1, cs->A1, prec);
    arb_mat_set_fmpq_mat(b->A2, cs->A2, prec);
    arb_mat_set_fmpq_mat(b->B1, B1, prec);
    arb_mat_set_fmpq_mat(b->B2, B2, prec);
    arb_mat_set_fmpq_mat(b->C, C, prec);
    arb_set_fmpq(b->H, cs->H, prec);
}

/* GSL double estimate of rho at the midpoint (-1 when not finite / QR fails) */
static double mid_rho(const arb_mat_t M)
{
    slong d = arb_mat_nrows(M), i, j;
    gsl_matrix *A = gsl_matrix_alloc((size_t) d, (size_t) d);
    gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t) d);
    gsl_eigen_nonsymm_workspace *w = gsl_eigen_nonsymm_alloc((size_t) d);
    double rho = -1;
    int ok = 1;
    for (i = 0; i < d; i++)
        for (j = 0; j < d; j++) {
            double x = arf_get_d(arb_midref(arb_mat_entry(M, i, j)), ARF_RND_NEAR);
            if (!isfinite(x)) ok = 0;
            gsl_matrix_set(A, (size_t) i, (size_t) j, x);
        }
    if (ok && gsl_eigen_nonsymm(A, ev, w) == 0) {
        rho = 0;
        for (i = 0; i < d; i++) {
            double a = gsl_complex_abs(gsl_vector_complex_get(ev, (size_t) i));
            if (a > rho) rho = a;
        }
    }
    gsl_eigen_nonsymm_free(w);
    gsl_vector_complex_free(ev);
    gsl_matrix_free(A);
    return rho;
}

/* x = K^{-1} rhs in double (GSL LU): the fast path's Stein system (d^2 unknowns) */
static int solve_double(arb_mat_t x, const arb_mat_t K, const arb_mat_t rhs)
{
    slong n = arb_mat_nrows(K), i, j;
    gsl_matrix *A = gsl_matrix_alloc((size_t) n, (size_t) n);
    gsl_vector *b = gsl_vector_alloc((size_t) n), *y = gsl_vector_alloc((size_t) n);
    gsl_permutation *p = gsl_permutation_alloc((size_t) n);
    int sgn, ok;
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++)
            gsl_matrix_set(A, (size_t) i, (size_t) j, arf_get_d(arb_midref(arb_mat_entry(K, i, j)), ARF_RND_NEAR));
        gsl_vector_set(b, (size_t) i, arf_get_d(arb_midref(arb_mat_entry(rhs, i, 0)), ARF_RND_NEAR));
    }
    ok = gsl_linalg_LU_decomp(A, p, &sgn) == 0 && gsl_linalg_LU_solve(A, p, b, y) == 0;
    for (i = 0; ok && i < n; i++) {
        double v = gsl_vector_get(y, (size_t) i);
        if (!isfinite(v)) ok = 0;
        else arb_set_d(arb_mat_entry(x, i, 0), v);
    }
    gsl_permutation_free(p);
    gsl_vector_free(y);
    gsl_vector_free(b);
    gsl_matrix_free(A);
    return ok;
}

/* P (point, symmetric) with P - N0^T P N0 ~= I, N0 the midpoint of N: the
 * Kronecker system (I - N0^T (x) N0^T) vec P = vec I, floating point at prec
 * (only D > 0 below is certified, so P needs no error bound) */
static int stein_solve(arb_mat_t P, const arb_mat_t N, slong prec)
{
    slong d = arb_mat_nrows(N), d2 = d * d, i, j, k, l;
    arb_mat_t K, rhs, x;
    int ok;
    arb_mat_init(K, d2, d2);
    arb_mat_init(rhs, d2, 1);
    arb_mat_init(x, d2, 1);
    /* vec(N0^T P N0) = (N0^T (x) N0^T) vec P, column-major vec */
    for (i = 0; i < d; i++)
        for (j = 0; j < d; j++)
            for (k = 0; k < d; k++)
                for (l = 0; l < d; l++) {
                    arb_ptr e = arb_mat_entry(K, i * d + k, j * d + l);
                    arf_mul(arb_midref(e), arb_midref(arb_mat_entry(N, j, i)), arb_midref(arb_mat_entry(N, l, k)),
                            prec, ARF_RND_NEAR);
                    mag_zero(arb_radref(e));
                    arb_neg(e, e);
                    if (i == j && k == l) arb_add_ui(e, e, 1, prec);
                }
    for (i = 0; i < d; i++) arb_one(arb_mat_entry(rhs, i * d + i, 0));
    ok = prec <= 64 ? solve_double(x, K, rhs) : arb_mat_approx_solve(x, K, rhs, prec);
    for (i = 0; ok && i < d; i++)
        for (k = 0; k < d; k++) {
            /* vec index i*d + k holds P[k][i]; symmetrise to an exact point matrix */
            arb_ptr e = arb_mat_entry(P, k, i);
            arb_add(e, arb_mat_entry(x, i * d + k, 0), arb_mat_entry(x, k * d + i, 0), prec);
            arb_mul_2exp_si(e, e, -1);
            mag_zero(arb_radref(e));
            if (!arb_is_finite(e)) ok = 0;
        }
    arb_mat_clear(K);
    arb_mat_clear(rhs);
    arb_mat_clear(x);
    return ok;
}

/* some x with x^T P x < 0 certified (x: eigenvector of P's least eigenvalue, double) */
static int has_negative_direction(const arb_mat_t P, slong prec)
{
    slong d = arb_mat_nrows(P), i, j;
    gsl_matrix *A = gsl_matrix_alloc((size_t) d, (size_t) d), *V = gsl_matrix_alloc((size_t) d, (size_t) d);
    gsl_vector *ev = gsl_vector_alloc((size_t) d);
    gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc((size_t) d);
    int neg = 0;
    for (i = 0; i < d; i++)
        for (j = 0; j < d; j++)
            gsl_matrix_set(A, (size_t) i, (size_t) j, arf_get_d(arb_midref(arb_mat_entry(P, i, j)), ARF_RND_NEAR));
    if (gsl_eigen_symmv(A, ev, V, w) == 0) {
        size_t imin = gsl_vector_min_index(ev);
        arb_mat_t x, Px, q;
        arb_mat_init(x, d, 1);
        arb_mat_init(Px, d, 1);
        arb_mat_init(q, 1, 1);
        for (i = 0; i < d; i++) arb_set_d(arb_mat_entry(x, i, 0), gsl_matrix_get(V, (size_t) i, imin));
        arb_mat_mul(Px, P, x, prec);
        for (i = 0; i < d; i++) arb_addmul(arb_mat_entry(q, 0, 0), arb_mat_entry(x, i, 0), arb_mat_entry(Px, i, 0), prec);
        neg = arb_is_negative(arb_mat_entry(q, 0, 0));
        arb_mat_clear(x);
        arb_mat_clear(Px);
        arb_mat_clear(q);
    }
    gsl_eigen_symmv_free(w);
    gsl_vector_free(ev);
    gsl_matrix_free(V);
    gsl_matrix_free(A);
    return neg;
}

/* rho0 at prec (acb_mat_approx_eig_qr at the midpoint) when the double
 * estimate is too close to 1 for r = (1 + rho0)/2 to separate in double */
static void mid_rho_prec(arf_t rho, const arb_mat_t M, slong prec)
{
    slong d = arb_mat_nrows(M), i;
    acb_mat_t A;
    acb_ptr E;
    arf_t t;
    acb_mat_init(A, d, d);
    E = _acb_vec_init(d);
    arf_init(t);
    acb_mat_set_arb_mat(A, M);
    acb_mat_get_mid(A, A);
    acb_mat_approx_eig_qr(E, NULL, NULL, A, NULL, 0, prec);
    arf_zero(rho);
    for (i = 0; i < d; i++) {
        arb_t a;
        arb_init(a);
        acb_get_mid(E + i, E + i);
        acb_abs(a, E + i, prec);
        arf_set(t, arb_midref(a));
        if (arf_cmp(t, rho) > 0) arf_set(rho, t);
        arb_clear(a);
    }
    arf_clear(t);
    _acb_vec_clear(E, d);
    acb_mat_clear(A);
}

/* The certificate for M/r: want = RS_COSIM_BALL_STABLE or _UNSTABLE, or
 * _UNDECIDED for either (only sound with r = 1: P > 0 proves rho < 1, a
 * negative direction rho > 1, since D > 0 excludes the unit circle). */
static int stein_try(const arb_mat_t M, const arb_t r, int want, slong prec)
{
    slong d = arb_mat_nrows(M);
    int verdict = RS_COSIM_BALL_UNDECIDED;
    arb_mat_t N, P, T, D, L;
    arb_mat_init(N, d, d);
    arb_mat_init(P, d, d);
    arb_mat_init(T, d, d);
    arb_mat_init(D, d, d);
    arb_mat_init(L, d, d);
    arb_mat_scalar_div_arb(N, M, r, prec);
    if (stein_solve(P, N, prec)) {
        arb_mat_mul(T, P, N, prec);
        arb_mat_transpose(D, N);
        arb_mat_mul(L, D, T, prec);
        arb_mat_sub(D, P, L, prec);
        if (arb_mat_cho(L, D, prec)) {
            if (want != RS_COSIM_BALL_UNSTABLE && arb_mat_cho(T, P, prec)) verdict = RS_COSIM_BALL_STABLE;
            else if (want != RS_COSIM_BALL_STABLE && has_negative_direction(P, prec))
                verdict = RS_COSIM_BALL_UNSTABLE;
        }
    }
    arb_mat_clear(N);
    arb_mat_clear(P);
    arb_mat_clear(T);
    arb_mat_clear(D);
    arb_mat_clear(L);
    return verdict;
}

int rs_cosim_ball_stein(const arb_mat_t M, slong prec)
{
    double rho0;
    int verdict, want;
    arb_t r;
    if (arb_mat_nrows(M) == 0 || !arb_mat_is_finite(M)) return RS_COSIM_BALL_UNDECIDED;
    /* r = 1 first: no eigenvalue estimate needed when it certifies */
    arb_init(r);
    arb_one(r);
    verdict = stein_try(M, r, RS_COSIM_BALL_UNDECIDED, prec);
    if (verdict != RS_COSIM_BALL_UNDECIDED) {
        arb_clear(r);
        return verdict;
    }
    /* else scale by r = (1 + rho0)/2 when unstable (reciprocal eigenvalue
     * pairs make the r = 1 system singular), from an estimate rho0 */
    rho0 = mid_rho(M);
    if (!(rho0 >= 0)) {
        arb_clear(r);
        return RS_COSIM_BALL_UNDECIDED;
    }
    if (fabs(rho0 - 1.0) < 1e-6 && prec > 53) {
        arf_t rp;
        arf_init(rp);
        mid_rho_prec(rp, M, prec);
        arf_sub_ui(rp, rp, 1, prec, ARF_RND_NEAR);
        want = arf_sgn(rp) < 0 ? RS_COSIM_BALL_STABLE : arf_sgn(rp) > 0 ? RS_COSIM_BALL_UNSTABLE
                                                                           : RS_COSIM_BALL_UNDECIDED;
        /* r = 1 + (rho0 - 1)/2 */
        arf_mul_2exp_si(rp, rp, -1);
        arf_add_ui(arb_midref(r), rp, 1, prec, ARF_RND_NEAR);
        arf_clear(rp);
    } else {
        want = rho0 < 1 ? RS_COSIM_BALL_STABLE : rho0 > 1 ? RS_COSIM_BALL_UNSTABLE : RS_COSIM_BALL_UNDECIDED;
        arb_set_d(r, 0.5 * (1.0 + rho0));
    }
    /* stable: r = 1 was tried */
    verdict = want == RS_COSIM_BALL_UNSTABLE ? stein_try(M, r, want, prec) : RS_COSIM_BALL_UNDECIDED;
    arb_clear(r);
    return verdict;
}
