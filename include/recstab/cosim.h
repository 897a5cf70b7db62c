/* cosim.h -- recurrence and certified spectral radius of the applied-force
 * (force/force) co-simulation of two linear subsystems with exact (analytic)
 * subsystem integration over each macro step, after Li, Meyer, Lu and
 * Schweizer, "Numerical stability of explicit and implicit co-simulation
 * methods" (seed: li-meyer-lu-schweizer-cosimulation-stability.md, sect. 2-3).
 *
 * Model.  Subsystem i = 1, 2 has state z_i (dimension n_i) and
 *     z_i' = A_i z_i + B_i lambda_c(t),
 * coupled only through the scalar coupling force lambda_c, whose constitutive
 * law (the coupling condition) is lambda_c = C z with z = (z_1, z_2), C a row
 * of length n = n_1 + n_2.  All of A_i, B_i, C and the macro step H > 0 are
 * exact rationals.  NOTE the sign convention: C here is the row with
 * lambda_c = C z; the paper writes g = C_FF z + D_FF u = 0 with D_FF picking
 * lambda_c, so its C_FF (eq. 7) is the NEGATIVE of this C.
 *
 * Scheme (K = approximation order of the coupling polynomial, 0..3; the
 * paper treats K = k = 2, eq. 10-16).  Per macro step [T_N, T_N + H]:
 *   explicit: lambda_c is the degree-K polynomial through (T_{N-j},
 *     lambda_{N-j}), j = 0..K (extrapolation, paper's step 1 only); both
 *     subsystems are integrated exactly; lambda_{N+1} = C z_{N+1}.
 *   implicit: predictor as above; then the degree-K polynomial through
 *     (T_{N+1}, lambda*), (T_{N+1-j}, lambda_{N+1-j}), j = 1..K (constant
 *     lambda* for K = 0); the coupling condition g(lambda*) = lambda* -
 *     C z*_{N+1}(lambda*) is affine in lambda*, so one linearised Newton
 *     step from the predictor (eq. 13) solves it exactly; corrector with the
 *     corrected lambda_{N+1} = C z_{N+1}.  (Derivation in src/cosim.c.)
 * With E = e^{A H} (block diagonal) and the gains G_j = sum_m l_{j,m} Phi_m,
 *     Phi_m = int_0^H e^{A (H - s)} B (s/H)^m ds       (n x 1, m = 0..K),
 * l_{j,m} the coefficients of the Lagrange basis polynomial of node j in
 * tau = (t - T_N)/H, the recurrences are
 *   explicit  z_{N+1} - (E + G_0 C) z_N - sum_{j=1..K} G_j C z_{N-j} = 0
 *             (degree K + 1 in the shift; the paper's eq. 16 for K = 2)
 *   implicit  (I - G_0 C) z_{N+1} - (E + G_1 C) z_N
 *             - sum_{j=2..K} G_j C z_{N+1-j} = 0
 *             (degree max(K, 1); eq. 15 for K = 2; G_1 := 0 when K = 0).
 * The implicit leading matrix I - G_0 C is invertible iff the scalar Newton
 * Jacobian J = dg/dlambda* = 1 - C G_0 (the paper's J_c) is nonzero.
 *
 * Errors via rs_error_t; nothing is printed. */
#ifndef RECSTAB_COSIM_H
#define RECSTAB_COSIM_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>
#include <arb.h>
#include <arb_mat.h>
#include "recstab/error.h"
#include "recstab/radius.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    RS_COSIM_EXPLICIT = 0,
    RS_COSIM_IMPLICIT = 1
};

#define RS_COSIM_MAX_ORDER 3
#define RS_COSIM_MAX_DIM 256   /* n_1 + n_2 limit */

typedef struct {
    slong n1, n2;        /* subsystem state dimensions (>= 1) */
    fmpq_mat_t A1, A2;   /* n_i x n_i */
    fmpq_mat_t B1, B2;   /* n_i x 1 */
    fmpq_mat_t C;        /* 1 x (n1 + n2): lambda_c = C z */
    fmpq_t H;            /* macro step, > 0 (default 1) */
    int method;          /* RS_COSIM_EXPLICIT (default) or RS_COSIM_IMPLICIT */
    slong order;         /* K in 0..RS_COSIM_MAX_ORDER (default 0) */
} rs_cosim_struct;
typedef rs_cosim_struct rs_cosim_t[1];

/* All matrices zero with the given dimensions (n_i >= 0 accepted here; the
 * computing functions require n_i >= 1), H = 1, explicit, K = 0. */
void rs_cosim_init(rs_cosim_t cs, slong n1, slong n2);
void rs_cosim_clear(rs_cosim_t cs);
/* Re-dimension (all matrices zeroed; H, method, order kept). */
void rs_cosim_set_dims(rs_cosim_t cs, slong n1, slong n2);
/* RS_ERR_INPUT unless dimensions, shapes, H > 0, method and order are valid. */
int rs_cosim_check(const rs_cosim_t cs, rs_error_t err);

/* Li et al.'s dimensionless force/force test model (eq. 3, 4, 7): sets n1 =
 * n2 = 2, z = (x1, v1, x2, v2),
 *   A_1 = [[0, 1], [-c1, -d1]],  B_1 = (0, 1),
 *   A_2 = [[0, 1], [-ac21/am21 c1, -ad21/am21 d1]],  B_2 = (0, -1/am21),
 *   lambda_c = acc1 c1 (x2 - x1) + adc1 d1 (v2 - v1),
 *   i.e. C = (-acc1 c1, -adc1 d1, acc1 c1, adc1 d1);
 * H, method and order are kept (H = 1 is the paper's dimensionless step).
 * RS_ERR_INPUT if am21 = 0.  A_mono = blockdiag(A_1, A_2) + B C is then
 * exactly the paper's eq. (5) matrix (tested).
 * Note: when ac21 = ad21 = am21 (e.g. the paper's symmetric and unsymmetric
 * models, all alphas 1 or all 10) the in-phase motion x1 = x2, v1 = v2 has
 * lambda_c = 0 and is reproduced exactly by every scheme, so rho >=
 * e^{-d1/2} (underdamped) always; only the other mode feels the coupling. */
int rs_cosim_li_ff(rs_cosim_t cs, const fmpq_t c1, const fmpq_t d1,
                   const fmpq_t am21, const fmpq_t ac21, const fmpq_t ad21,
                   const fmpq_t acc1, const fmpq_t adc1, rs_error_t err);

/* Lagrange basis coefficients: L ((K+1) x (K+1), initialised by the caller)
 * gets L[j][m] = coefficient of tau^m in the basis polynomial of node j,
 * tau = (t - T_N)/H; nodes tau_j = -j (explicit) or 1 - j (implicit). */
int rs_cosim_lagrange(fmpq_mat_t L, int method, slong order, rs_error_t err);

/* E = e^{A H} (n x n, block diagonal) and Phi (n x (K+1), column m = Phi_m),
 * both from one arb_mat_exp per subsystem of the Van Loan block matrix
 *     M_i = [[H A_i, H B_i e_0^T], [0, N]]     (size n_i + K + 1),
 * N the (K+1) x (K+1) nilpotent shift (N[r][r+1] = 1).  The augmented system
 * y' = M_i y in tau = t/H, y = (x, w), has w' = N w, so w(0) = e_m gives
 * w_0(tau) = tau^m/m! and x(1) = int_0^1 e^{H A_i (1-tau)} H B_i tau^m/m! dtau
 * = Phi_m/m!: exp(M_i) = [[e^{H A_i}, F], [0, e^N]] with Phi_m = m! F[:, m]. */
int rs_cosim_exp_phi(arb_mat_t E, arb_mat_t Phi, const rs_cosim_t cs,
                     slong prec, rs_error_t err);

/* The gains G (n x (K+1)), column j = G_j = sum_m l_{j,m} Phi_m. */
int rs_cosim_gains(arb_mat_t E, arb_mat_t G, const rs_cosim_t cs, slong prec,
                   rs_error_t err);

/* The recurrence sum_{j=0..k} A[j] z_{N+j} = 0 (A[k] the newest state). */
typedef struct {
    slong n;              /* n1 + n2 */
    slong k;              /* degree in the shift (K + 1 or max(K, 1)) */
    arb_mat_struct *A;    /* A[0..k], n x n; NULL before the first fill */
    arb_t jac;            /* implicit: J = 1 - C G_0 (eq. 13); explicit: 1 */
    slong prec;           /* precision used */
} rs_cosim_rec_struct;
typedef rs_cosim_rec_struct rs_cosim_rec_t[1];

void rs_cosim_rec_init(rs_cosim_rec_t rec);
void rs_cosim_rec_clear(rs_cosim_rec_t rec);
/* Fill rec (explicit: A[k] = I; implicit: A[k] = I - G_0 C). */
int rs_cosim_recurrence(rs_cosim_rec_t rec, const rs_cosim_t cs, slong prec,
                        rs_error_t err);

/* One-step map of the minimal state
 *   explicit  s_N = (z_N, lambda_{N-1}, ..., lambda_{N-K})     (n + K)
 *   implicit  s_N = (z_N, lambda_{N-1}, ..., lambda_{N-K+1})   (n + max(K-1, 0))
 * (lambda_j = C z_j): s_{N+1} = M s_N.  Its nonzero eigenvalues are exactly
 * those of the recurrence's block companion (which adds only eigenvalue 0,
 * defective: n-1 directions of each delayed z_{N-j} are invisible through C).
 * RS_ERR_UNDECIDED if J = 1 - C G_0 is not certified nonzero at prec. */
int rs_cosim_transition(arb_mat_t M, const rs_cosim_t cs, slong prec,
                        rs_error_t err);

/* Certified spectral radius of the co-simulation recurrence to `digits`
 * digits (rs_radius contract: 2 rad(rho) <= 10^-digits * rho), via
 * rs_radius_matrix_poly on the minimal one-step map (k = 1, A[1] = I,
 * A[0] = -M).  The matrices are rebuilt at doubled precision while
 * rs_radius_matrix_poly reports that the coefficient balls are too wide
 * (RS_ERR_UNDECIDED) or J is not certified nonzero, up to max_prec bits
 * (<= 0: RS_RADIUS_MAX_PREC_DEFAULT).  RS_ERR_MATH if J = 0 exactly cannot be
 * excluded at max_prec (the implicit step is then undefined). */
int rs_cosim_radius(rs_radius_t r, const rs_cosim_t cs, slong digits,
                    slong max_prec, rs_error_t err);

/* The same radius from the full recurrence matrices A[0..k] via the block
 * companion of size k n (rs_radius_matrix_poly as is).  An independent
 * route for cross-checks, but of limited use: for k >= 2 (explicit K >= 1,
 * implicit K >= 2) the block companion has a DEFECTIVE eigenvalue 0 (the
 * delayed states z_{N-j} enter only through the scalar C z_{N-j}), which
 * neither acb_mat_eig_simple nor the cluster route certifies: it then
 * escalates to max_prec (seconds) and returns RS_ERR_UNDECIDED with only a
 * partial enclosure.  Certifies for k = 1 (explicit K = 0, implicit
 * K <= 1). */
int rs_cosim_radius_recurrence(rs_radius_t r, const rs_cosim_t cs,
                               slong digits, slong max_prec, rs_error_t err);

/* Monolithic reference: A_mono = blockdiag(A_1, A_2) + B C (exact, n x n,
 * B = (B_1; B_2)), its exact exponential e^{A_mono H} at prec, and the
 * certified spectral radius of that, which equals e^{H max Re eig(A_mono)}. */
int rs_cosim_monolithic_matrix(fmpq_mat_t Amono, const rs_cosim_t cs,
                               rs_error_t err);
int rs_cosim_monolithic(arb_mat_t Emono, const rs_cosim_t cs, slong prec,
                        rs_error_t err);
int rs_cosim_monolithic_radius(rs_radius_t r, const rs_cosim_t cs,
                               slong digits, slong max_prec, rs_error_t err);

#ifdef __cplusplus
}
#endif
#endif
