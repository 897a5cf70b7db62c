/* cosim_fast.c -- see numeric/cosim_fast.h.  Why Gershgorin on the
 * diagonalised map: with V the double eigenvectors (an exact point matrix)
 * and W ~= V^{-1} in double, V^{-1} T V = W T V + F with F bounded through
 * E = I - W V (rs_cosim_fast_radius); V^{-1} T V is similar to every matrix
 * in T, so its Gershgorin discs (centre, radius the off-diagonal row sum
 * plus the centre's own uncertainty and the bound of F's row) contain every
 * eigenvalue, and a disc disjoint from all others contains exactly one.  For a well-conditioned diagonalisable
 * map the discs have radius ~1e-15 * cond(V): one O(d^3) pass at 64 bits,
 * no QR iteration and no precision doubling (what rs_cosim_radius spends its
 * time on, bench/README.md). */
#include <math.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <acb_mat.h>
#include <arb_poly.h>
#include "numeric/cosim_ball.h"
#include "numeric/cosim_fast.h"

/* T (ball) for the reduced realisation of cs at prec (rs_cosim_reduce drops
 * coupling directions that carry nothing, whose history slots would add
 * defective zero eigenvalues the discs cannot separate); the D-/I-extension
 * couplings have their own n x n map */
static int fast_transition(arb_mat_t T, const rs_cosim_t cs, slong prec, rs_error_t err)
{
    fmpq_mat_t P1, P2, Q;
    rs_cosim_ball_t b;
    slong rk = 0;
    int rc;
    if (cs->ext != RS_COSIM_EXT_NONE) {
        /* D-/I-extension: the n x n map of z_N (rs_cosim_transition -> cosim_ext.c), as rs_cosim_radius */
        arb_mat_clear(T);
        arb_mat_init(T, rs_cosim_transition_dim(cs), rs_cosim_transition_dim(cs));
        return rs_cosim_transition(T, cs, prec, err);
    }
    fmpq_mat_init(P1, 0, 0);
    fmpq_mat_init(P2, 0, 0);
    fmpq_mat_init(Q, 0, 0);
    rs_cosim_ball_init(b);
    rc = rs_cosim_reduce(P1, P2, Q, &rk, cs, err);
    if (rc == RS_OK) {
        rs_cosim_ball_set(b, cs, P1, P2, Q, rk, prec);
        arb_mat_clear(T);
        arb_mat_init(T, rs_cosim_ball_dim(b), rs_cosim_ball_dim(b));
        rc = rs_cosim_ball_transition(T, b, prec, err);
    }
    rs_cosim_ball_clear(b);
    fmpq_mat_clear(P1);
    fmpq_mat_clear(P2);
    fmpq_mat_clear(Q);
    return rc;
}

/* V (point, complex) = the double eigenvectors of mid(T), W ~= V^{-1}
 * (GSL, complex LU; skipped when W is NULL), E (when not NULL) the double
 * eigenvalues; 0 when GSL fails */
static int double_eigvecs(acb_mat_t V, acb_mat_t W, acb_ptr E, const arb_mat_t T)
{
    slong d = arb_mat_nrows(T), i, j;
    gsl_matrix *A = gsl_matrix_alloc((size_t) d, (size_t) d);
    gsl_vector_complex *ev = gsl_vector_complex_alloc((size_t) d);
    gsl_matrix_complex *X = gsl_matrix_complex_alloc((size_t) d, (size_t) d);
    gsl_eigen_nonsymmv_workspace *w = gsl_eigen_nonsymmv_alloc((size_t) d);
    int ok = 1;
    for (i = 0; i < d; i++)
        for (j = 0; j < d; j++) {
            double x = arf_get_d(arb_midref(arb_mat_entry(T, i, j)), ARF_RND_NEAR);
            if (!isfinite(x)) ok = 0;
            gsl_matrix_set(A, (size_t) i, (size_t) j, x);
        }
    if (ok) ok = gsl_eigen_nonsymmv(A, ev, X, w) == GSL_SUCCESS;
    for (i = 0; ok && i < d; i++)
        for (j = 0; j < d; j++) {
            gsl_complex z = gsl_matrix_complex_get(X, (size_t) i, (size_t) j);
            if (!isfinite(GSL_REAL(z)) || !isfinite(GSL_IMAG(z))) ok = 0;
            acb_set_d_d(acb_mat_entry(V, i, j), GSL_REAL(z), GSL_IMAG(z));
        }
    for (i = 0; ok && E != NULL && i < d; i++) {
        gsl_complex z = gsl_vector_complex_get(ev, (size_t) i);
        if (!isfinite(GSL_REAL(z)) || !isfinite(GSL_IMAG(z))) ok = 0;
        acb_set_d_d(E + i, GSL_REAL(z), GSL_IMAG(z));
    }
    if (ok && W != NULL) {
        gsl_matrix_complex *Y = gsl_matrix_complex_alloc((size_t) d, (size_t) d);
        gsl_permutation *p = gsl_permutation_alloc((size_t) d);
        int sgn;
        ok = gsl_linalg_complex_LU_decomp(X, p, &sgn) == GSL_SUCCESS
             && gsl_linalg_complex_LU_invert(X, p, Y) == GSL_SUCCESS;
        for (i = 0; ok && i < d; i++)
            for (j = 0; j < d; j++) {
                gsl_complex z = gsl_matrix_complex_get(Y, (size_t) i, (size_t) j);
                if (!isfinite(GSL_REAL(z)) || !isfinite(GSL_IMAG(z))) ok = 0;
                acb_set_d_d(acb_mat_entry(W, i, j), GSL_REAL(z), GSL_IMAG(z));
            }
        gsl_permutation_free(p);
        gsl_matrix_complex_free(Y);
    }
    gsl_eigen_nonsymmv_free(w);
    gsl_matrix_complex_free(X);
    gsl_vector_complex_free(ev);
    gsl_matrix_free(A);
    return ok;
}

/* |c_i - c_j| > R_i + R_j certified: disc i and disc j are disjoint */
static int discs_apart(const acb_t ci, const arb_t Ri, const acb_t cj, const arb_t Rj, slong prec)
{
    acb_t t;
    arb_t a, s;
    int apart;
    acb_init(t);
    arb_init(a);
    arb_init(s);
    acb_sub(t, ci, cj, prec);
    acb_abs(a, t, prec);
    arb_add(s, Ri, Rj, prec);
    apart = arb_gt(a, s);
    acb_clear(t);
    arb_clear(a);
    arb_clear(s);
    return apart;
}

/* nrm = an upper bound of the infinity norm (max row sum of |a_ij|), a
 * point; mag arithmetic (upper bounds only), no square roots */
static void inf_norm(arb_t nrm, const acb_mat_t A)
{
    slong i, j;
    mag_t s, a, mx;
    mag_init(s);
    mag_init(a);
    mag_init(mx);
    for (i = 0; i < acb_mat_nrows(A); i++) {
        mag_zero(s);
        for (j = 0; j < acb_mat_ncols(A); j++) {
            acb_get_mag(a, acb_mat_entry(A, i, j));
            mag_add(s, s, a);
        }
        mag_max(mx, mx, s);
    }
    arf_set_mag(arb_midref(nrm), mx);
    mag_zero(arb_radref(nrm));
    mag_clear(s);
    mag_clear(a);
    mag_clear(mx);
}

int rs_cosim_fast_radius(rs_radius_t r, const rs_cosim_t cs, slong prec, rs_error_t err)
{
    slong d, i, j;
    arb_mat_t T;
    acb_mat_t V, W, B, Tc;
    arb_ptr R, out, in;
    arb_t t, up, lo, e, f, half;
    int rc, ok;
    rc = rs_cosim_check(cs, err);
    if (rc != RS_OK) return rc;
    arb_mat_init(T, 0, 0);
    rc = fast_transition(T, cs, prec, err);
    if (rc != RS_OK) {
        arb_mat_clear(T);
        /* J not certified invertible at prec: the full radius raises prec */
        return rc;
    }
    d = arb_mat_nrows(T);
    if (d == 0 || !arb_mat_is_finite(T)) {
        arb_mat_clear(T);
        return rs_error_set(err, RS_ERR_UNDECIDED, "cosim fast radius: no finite one-step map at %ld bits", (long) prec);
    }
    acb_mat_init(V, d, d);
    acb_mat_init(W, d, d);
    acb_mat_init(B, d, d);
    acb_mat_init(Tc, d, d);
    R = _arb_vec_init(d);
    out = _arb_vec_init(d);
    in = _arb_vec_init(d);
    arb_init(t);
    arb_init(up);
    arb_init(lo);
    arb_init(e);
    arb_init(f);
    arb_init(half);
    arb_set_d(half, 0.5);
    /* B = W T V with W ~= V^{-1} (double): V^{-1} = (I - E)^{-1} W, E = I - W V,
     * so V^{-1} T V = B + F with |F|_inf <= e/(1 - e) |B|_inf, e = |E|_inf < 1
     * (Neumann series; no ball inverse, which cost more than the products) */
    ok = double_eigvecs(V, W, NULL, T);
    if (ok) {
        acb_mat_mul(B, W, V, prec);
        acb_mat_one(Tc);
        acb_mat_sub(B, Tc, B, prec);
        inf_norm(e, B);
        acb_mat_set_arb_mat(Tc, T);
        acb_mat_mul(B, W, Tc, prec);
        acb_mat_mul(B, B, V, prec);
        inf_norm(f, B);
        arb_sub_ui(t, e, 1, prec);
        arb_neg(t, t);
        ok = acb_mat_is_finite(B) && arb_is_positive(t) && arb_lt(e, half);
        /* f = e |B|_inf / (1 - e) */
        arb_mul(f, f, e, prec);
        arb_div(f, f, t, prec);
    }
    /* disc i: centre B_ii (a ball), radius R_i = sum_{j != i} |B_ij| + f
     * (f bounds row i of F, the diagonal shift included); |lambda| in
     * [|c_i| - R_i, |c_i| + R_i] for the eigenvalues in it */
    for (i = 0; ok && i < d; i++) {
        acb_ptr c = acb_mat_entry(B, i, i);
        mag_t m, sum;
        mag_init(m);
        mag_init(sum);
        /* R_i is only used through its upper bound: the row sum as a radius */
        arb_set(R + i, f);
        for (j = 0; j < d; j++) {
            if (j == i) continue;
            acb_get_mag(m, acb_mat_entry(B, i, j));
            mag_add(sum, sum, m);
        }
        arb_add_error_mag(R + i, sum);
        mag_clear(m);
        mag_clear(sum);
        /* the centre's ball is used as a ball below; its radius added again
         * to R_i only widens the discs (cheap margin) */
        arb_add_error_mag(R + i, arb_radref(acb_realref(c)));
        arb_add_error_mag(R + i, arb_radref(acb_imagref(c)));
        acb_abs(t, c, prec);
        arb_add(out + i, t, R + i, prec);
        arb_sub(in + i, t, R + i, prec);
    }
    if (ok) {
        /* upper: every eigenvalue lies in some disc; lower: a disc disjoint
         * from all others holds exactly one eigenvalue, so rho >= its inner
         * bound.  The dominant disc must be isolated (else the lower bound
         * could miss the dominant eigenvalue's cluster by its width). */
        slong top = 0;
        arf_t b;
        arf_init(b);
        arf_zero(arb_midref(up));
        for (i = 0; i < d; i++) {
            arb_get_ubound_arf(b, out + i, prec);
            if (i == 0 || arf_cmp(b, arb_midref(up)) > 0) { arf_set(arb_midref(up), b); top = i; }
        }
        mag_zero(arb_radref(up));
        for (j = 0; ok && j < d; j++)
            if (j != top && !discs_apart(acb_mat_entry(B, top, top), R + top, acb_mat_entry(B, j, j), R + j, prec))
                ok = 0;
        if (ok) {
            arb_get_lbound_arf(b, in + top, prec);
            if (arf_sgn(b) < 0) arf_zero(b);
            arb_set_arf(lo, b);
            /* the 6 digits of rs_cosim_radius's cells: wider -> its route */
            arb_sub(t, up, lo, prec);
            arb_mul_2exp_si(lo, lo, -20);
            if (!arb_le(t, lo)) ok = 0;
            arb_set_arf(lo, b);
        }
        arf_clear(b);
    }
    if (ok) {
        arb_set(r->lower, lo);
        arb_set(r->upper, up);
        arb_union(r->rho, lo, up, prec);
        r->prec = prec;
        r->nroots = 0;
        r->method_double = 0;
        r->isolated = 1;
        r->partial = 0;
        rc = RS_OK;
    } else
        rc = rs_error_set(err, RS_ERR_UNDECIDED,
                          "cosim fast radius: the dominant eigenvalue's disc is not isolated at %ld bits", (long) prec);
    arb_clear(t);
    arb_clear(up);
    arb_clear(lo);
    arb_clear(e);
    arb_clear(f);
    arb_clear(half);
    _arb_vec_clear(R, d);
    _arb_vec_clear(out, d);
    _arb_vec_clear(in, d);
    acb_mat_clear(V);
    acb_mat_clear(W);
    acb_mat_clear(B);
    acb_mat_clear(Tc);
    arb_mat_clear(T);
    return rc;
}

int rs_cosim_check_radius(rs_radius_t r, const rs_cosim_t cs, slong prec, rs_error_t err)
{
    slong d, i;
    arb_mat_t T;
    acb_mat_t V, Tc;
    acb_ptr E, Ec;
    int rc, ok;
    rc = rs_cosim_check(cs, err);
    if (rc != RS_OK) return rc;
    arb_mat_init(T, 0, 0);
    rc = fast_transition(T, cs, prec, err);
    d = arb_mat_nrows(T);
    if (rc != RS_OK || d == 0 || !arb_mat_is_finite(T)) {
        arb_mat_clear(T);
        return rc != RS_OK ? rc : rs_error_set(err, RS_ERR_UNDECIDED, "cosim check radius: no finite one-step map%s", "");
    }
    acb_mat_init(V, d, d);
    acb_mat_init(Tc, d, d);
    E = _acb_vec_init(d);
    Ec = _acb_vec_init(d);
    ok = double_eigvecs(V, NULL, E, T);
    if (ok) {
        acb_mat_set_arb_mat(Tc, T);
        ok = acb_mat_eig_simple_vdhoeven_mourrain(Ec, NULL, NULL, Tc, E, V, prec);
    }
    for (i = 0; ok && i < d; i++)
        if (!acb_is_finite(Ec + i)) ok = 0;
    if (ok) {
        /* rho = max |lambda_i|: its bounds from every eigenvalue's ball */
        rs_radius_set_rho(r, Ec, d, prec);
        r->prec = prec;
        r->nroots = 0;
        r->method_double = 0;
        r->isolated = 1;
        r->partial = 0;
        rc = RS_OK;
    } else
        rc = rs_error_set(err, RS_ERR_UNDECIDED, "cosim check radius: eigenvalues not certified simple at %ld bits",
                          (long) prec);
    _acb_vec_clear(E, d);
    _acb_vec_clear(Ec, d);
    acb_mat_clear(V);
    acb_mat_clear(Tc);
    arb_mat_clear(T);
    return rc;
}

int rs_cosim_check_inside(int *where, const rs_cosim_t cs, slong maxprec, rs_error_t err)
{
    arb_mat_t T;
    arb_poly_t P;
    arb_t a;
    slong prec, d;
    int rc = rs_cosim_check(cs, err);
    *where = 0;
    if (rc != RS_OK) return rc;
    arb_mat_init(T, 0, 0);
    arb_poly_init(P);
    arb_init(a);
    for (prec = 128; rc == RS_OK && *where == 0 && prec <= maxprec; prec *= 2) {
        rc = fast_transition(T, cs, prec, err);
        d = arb_mat_nrows(T);
        if (rc != RS_OK || d == 0 || !arb_mat_is_finite(T)) break;
        arb_mat_charpoly(P, T, prec);   /* monic, degree d */
        if (arb_poly_length(P) != d + 1) continue;
        if (rs_radius_balls_inside(P->coeffs, d, prec)) *where = 1;
        else {
            arb_abs(a, P->coeffs + 0);
            if (arb_gt(a, P->coeffs + d)) *where = -1;
        }
    }
    arb_clear(a);
    arb_poly_clear(P);
    arb_mat_clear(T);
    return rc;
}
