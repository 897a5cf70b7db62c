/* cosim.h -- recurrence and certified spectral radius of the co-simulation
 * of two linear subsystems coupled through m coupling variables, with exact
 * (analytic) subsystem integration over each macro step, after Li, Meyer, Lu
 * and Schweizer, "Numerical stability of explicit and implicit co-simulation
 * methods" (seed: li-meyer-lu-schweizer-cosimulation-stability.md, sect. 2-3):
 * force/force (their eq. 7, m = 1), force/displacement (eq. 8) and
 * displacement/displacement (eq. 9) decompositions.
 *
 * Model.  Subsystem i = 1, 2 has state z_i (dimension n_i) and
 *     z_i' = A_i z_i + B_i u(t),
 * coupled only through the coupling variables u (m of them: coupling forces
 * and/or the partner's states seen as base-point excitation), whose coupling
 * conditions are u = C z with z = (z_1, z_2), C m x n, n = n_1 + n_2.  In
 * the stacked form z' = A z + B u, A = blockdiag(A_1, A_2), B = (B_1; B_2)
 * (n x m); subsystem i only sees its own rows B_i.  All of A_i, B_i, C and
 * the macro step H > 0 are exact rationals.  NOTE the sign convention: C
 * here is the matrix with u = C z; the paper writes g = C_P z + D_P u = 0
 * with D_P picking each u with +1, so its C_FF/C_FD/C_DD (eq. 7-9) are the
 * NEGATIVES of the corresponding rows of this C.  m = 1 is the original
 * scalar-force API (rs_cosim_init / rs_cosim_set_dims) and behaves exactly
 * as before.
 *
 * Scheme (K = approximation order of the coupling polynomials, 0..3; the
 * paper treats K = k = 2, eq. 10-16).  Per macro step [T_N, T_N + H], each
 * component of u separately:
 *   explicit: u is the degree-K polynomial through (T_{N-j}, u_{N-j}),
 *     j = 0..K (extrapolation, paper's step 1 only); both subsystems are
 *     integrated exactly; u_{N+1} = C z_{N+1}.
 *   implicit: predictor as above; then the degree-K polynomial through
 *     (T_{N+1}, u*), (T_{N+1-j}, u_{N+1-j}), j = 1..K (constant u* for
 *     K = 0); the coupling conditions g(u*) = u* - C z*_{N+1}(u*) = 0 are
 *     affine in u*, so one linearised Newton step from the predictor (eq. 13
 *     with the m x m Jacobian matrix J = dg/du* = I_m - C G_0) solves them
 *     exactly; corrector with the corrected u_{N+1} = C z_{N+1}.
 *     (Derivation in src/numeric/cosim.c.)
 * With E = e^{A H} (block diagonal) and the gains G_j = sum_k l_{j,k} Phi_k
 * (n x m), Phi_k = int_0^H e^{A (H - s)} B (s/H)^k ds (k = 0..K), l_{j,k}
 * the coefficients of the Lagrange basis polynomial of node j in
 * tau = (t - T_N)/H, the recurrences are
 *   explicit  z_{N+1} - (E + G_0 C) z_N - sum_{j=1..K} G_j C z_{N-j} = 0
 *             (degree K + 1 in the shift; the paper's eq. 16 for K = 2)
 *   implicit  (I - G_0 C) z_{N+1} - (E + G_1 C) z_N
 *             - sum_{j=2..K} G_j C z_{N+1-j} = 0
 *             (degree max(K, 1); eq. 15 for K = 2; G_1 := 0 when K = 0).
 * The implicit leading matrix I_n - G_0 C is invertible iff the Newton
 * Jacobian matrix J = I_m - C G_0 is (det(I_n - G_0 C) = det(I_m - C G_0)).
 * The recurrence depends on (B, C) only through the products G_j C, i.e.
 * through Phi_k(B) C; the radius route uses that (see rs_cosim_radius).
 *
 * Errors via rs_error_t; nothing is printed. */
#ifndef RECSTAB_COSIM_H
#define RECSTAB_COSIM_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_mat.h>
#include <arb.h>
#include <arb_mat.h>
#include "recstab/casefile.h"
#include "recstab/error.h"
#include "recstab/radius.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
    RS_COSIM_EXPLICIT = 0,
    RS_COSIM_IMPLICIT = 1
};

enum {
    RS_COSIM_EXT_NONE = 0,
    RS_COSIM_EXT_D = 1,   /* coupling condition and its derivative at T_{N+1} */
    RS_COSIM_EXT_I = 2    /* coupling condition at T_{N+1} and its integral over the macro step */
};

#define RS_COSIM_MAX_ORDER 3
#define RS_COSIM_EXT_MAX_ORDER 2
#define RS_COSIM_MAX_DIM 256   /* n_1 + n_2 limit */
#define RS_COSIM_MAX_INPUTS 64 /* m limit */

typedef struct {
    slong n1, n2;        /* subsystem state dimensions (>= 1) */
    slong m;             /* number of coupling variables (>= 1) */
    fmpq_mat_t A1, A2;   /* n_i x n_i */
    fmpq_mat_t B1, B2;   /* n_i x m */
    fmpq_mat_t C;        /* m x (n1 + n2): u = C z */
    fmpq_t H;            /* macro step, > 0 (default 1) */
    int method;          /* RS_COSIM_EXPLICIT (default) or RS_COSIM_IMPLICIT */
    slong order;         /* K in 0..RS_COSIM_MAX_ORDER (default 0) */
    int ext;             /* implicit only: RS_COSIM_EXT_NONE (default), _D, _I
                            (Li et al. sect. 3.2; reading in src/numeric/cosim_ext.h) */
    fmpq_t alpha_T;      /* the intermediate sampling point T_N + alpha_T H (default 1/2) */
} rs_cosim_struct;
typedef rs_cosim_struct rs_cosim_t[1];

/* All matrices zero with the given dimensions (n_i >= 0 accepted here; the
 * computing functions require n_i >= 1), H = 1, explicit, K = 0.
 * rs_cosim_init / rs_cosim_set_dims: one scalar coupling variable (m = 1);
 * the _m variants take m >= 1 (m < 1 is stored as 1). */
void rs_cosim_init(rs_cosim_t cs, slong n1, slong n2);
void rs_cosim_init_m(rs_cosim_t cs, slong n1, slong n2, slong m);
void rs_cosim_clear(rs_cosim_t cs);
/* Re-dimension (all matrices zeroed; H, method, order kept). */
void rs_cosim_set_dims(rs_cosim_t cs, slong n1, slong n2);
void rs_cosim_set_dims_m(rs_cosim_t cs, slong n1, slong n2, slong m);
/* RS_ERR_INPUT unless dimensions, shapes, H > 0, method and order are valid
 * (RS_ERR_LIMIT beyond RS_COSIM_MAX_DIM / RS_COSIM_MAX_INPUTS). */
int rs_cosim_check(const rs_cosim_t cs, rs_error_t err);

/* Li et al.'s dimensionless force/force test model (eq. 3, 4, 7): sets n1 =
 * n2 = 2, z = (x1, v1, x2, v2),
 *   A_1 = [[0, 1], [-c1, -d1]],  B_1 = (0, 1),
 *   A_2 = [[0, 1], [-ac21/am21 c1, -ad21/am21 d1]],  B_2 = (0, -1/am21),
 *   lambda_c = acc1 c1 (x2 - x1) + adc1 d1 (v2 - v1),
 *   i.e. C = (-acc1 c1, -adc1 d1, acc1 c1, adc1 d1);
 * m = 1; H, method and order are kept (H = 1 is the paper's dimensionless
 * step).  RS_ERR_INPUT if am21 = 0.  A_mono = blockdiag(A_1, A_2) + B C is then
 * exactly the paper's eq. (5) matrix (tested).
 * Note: when ac21 = ad21 = am21 (e.g. the paper's symmetric and unsymmetric
 * models, all alphas 1 or all 10) the in-phase motion x1 = x2, v1 = v2 has
 * lambda_c = 0 and is reproduced exactly by every scheme, so rho >=
 * e^{-d1/2} (underdamped) always; only the other mode feels the coupling. */
int rs_cosim_li_ff(rs_cosim_t cs, const fmpq_t c1, const fmpq_t d1,
                   const fmpq_t am21, const fmpq_t ac21, const fmpq_t ad21,
                   const fmpq_t acc1, const fmpq_t adc1, rs_error_t err);

/* Li et al.'s force/displacement test model (eq. 8): subsystem 1 is
 * force-driven, subsystem 2 a base-point excited oscillator carrying the
 * coupling spring/damper; m = 3, u = (x1~, v1~, lambda_c) (the used
 * components of the paper's u, in its order):
 *   A_1 = [[0, 1], [-c1, -d1]],
 *   A_2 = [[0, 1], [-(ac21 + acc1)/am21 c1, -(ad21 + adc1)/am21 d1]],
 *   B_1 = [[0, 0, 0], [0, 0, 1]],
 *   B_2 = [[0, 0, 0], [acc1/am21 c1, adc1/am21 d1, 0]],
 *   C   = [[1, 0, 0, 0], [0, 1, 0, 0],
 *          [-acc1 c1, -adc1 d1, acc1 c1, adc1 d1]]
 * (x1~ = x1, v1~ = v1, lambda_c = acc1 c1 (x2 - x1) + adc1 d1 (v2 - v1)).
 * Displacement/displacement (eq. 9): both subsystems base-point excited,
 * the coupling spring/damper duplicated; m = 4, u = (x1~, v1~, x2~, v2~):
 *   A_1 = [[0, 1], [-(1 + acc1) c1, -(1 + adc1) d1]],
 *   A_2 as for FD,
 *   B_1 = [[0, 0, 0, 0], [0, 0, acc1 c1, adc1 d1]],
 *   B_2 = [[0, 0, 0, 0], [acc1/am21 c1, adc1/am21 d1, 0, 0]],
 *   C   = I_4.
 * For both, A + B C is exactly eq. (5) (tested).  RS_ERR_INPUT if am21 = 0;
 * H, method and order are kept. */
int rs_cosim_li_fd(rs_cosim_t cs, const fmpq_t c1, const fmpq_t d1,
                   const fmpq_t am21, const fmpq_t ac21, const fmpq_t ad21,
                   const fmpq_t acc1, const fmpq_t adc1, rs_error_t err);
int rs_cosim_li_dd(rs_cosim_t cs, const fmpq_t c1, const fmpq_t d1,
                   const fmpq_t am21, const fmpq_t ac21, const fmpq_t ad21,
                   const fmpq_t acc1, const fmpq_t adc1, rs_error_t err);

/* Lagrange basis coefficients: L ((K+1) x (K+1), initialised by the caller)
 * gets L[j][m] = coefficient of tau^m in the basis polynomial of node j,
 * tau = (t - T_N)/H; nodes tau_j = -j (explicit) or 1 - j (implicit). */
int rs_cosim_lagrange(fmpq_mat_t L, int method, slong order, rs_error_t err);

/* E = e^{A H} (n x n, block diagonal) and Phi (n x (m (K+1)); column
 * k m + c = Phi_k e_c, the response to input c with profile tau^k), both from
 * one arb_mat_exp per subsystem of the Van Loan block matrix
 *     M_i = [[H A_i, H b_c1 e_0^T, ..., H b_cq e_0^T], [0, diag(N, ..., N)]]
 * (size n_i + q (K + 1)), b_c the nonzero columns of B_i (zero columns give
 * zero Phi), N the (K+1) x (K+1) nilpotent shift (N[r][r+1] = 1).  The
 * augmented system y' = M_i y in tau = t/H, y = (x, w^(c1), ...), has
 * w^(c)' = N w^(c), so w^(c)(0) = e_k (the others 0) gives w^(c)_0(tau) =
 * tau^k/k! and x(1) = int_0^1 e^{H A_i (1-tau)} H b_c tau^k/k! dtau =
 * Phi_k e_c / k!: exp(M_i) = [[e^{H A_i}, F], [0, *]] with Phi_k e_c =
 * k! F[:, chain(c) (K+1) + k].  For m = 1 the layout is the old one
 * (column k = Phi_k). */
int rs_cosim_exp_phi(arb_mat_t E, arb_mat_t Phi, const rs_cosim_t cs,
                     slong prec, rs_error_t err);

/* The gains G (n x (m (K+1))), columns j m .. j m + m - 1 = G_j =
 * sum_k l_{j,k} Phi_k. */
int rs_cosim_gains(arb_mat_t E, arb_mat_t G, const rs_cosim_t cs, slong prec,
                   rs_error_t err);

/* The recurrence sum_{j=0..k} A[j] z_{N+j} = 0 (A[k] the newest state). */
typedef struct {
    slong n;              /* n1 + n2 */
    slong k;              /* degree in the shift (K + 1 or max(K, 1)) */
    arb_mat_struct *A;    /* A[0..k], n x n; NULL before the first fill */
    arb_t jac;            /* implicit: det J, J = I_m - C G_0 (eq. 13);
                             explicit: 1 */
    arb_mat_t jacm;       /* implicit: the m x m Jacobian matrix J;
                             explicit: I_m */
    slong prec;           /* precision used */
} rs_cosim_rec_struct;
typedef rs_cosim_rec_struct rs_cosim_rec_t[1];

void rs_cosim_rec_init(rs_cosim_rec_t rec);
void rs_cosim_rec_clear(rs_cosim_rec_t rec);
/* Fill rec (explicit: A[k] = I; implicit: A[k] = I - G_0 C). */
int rs_cosim_recurrence(rs_cosim_rec_t rec, const rs_cosim_t cs, slong prec,
                        rs_error_t err);

/* One-step map of the state
 *   explicit  s_N = (z_N, u_{N-1}, ..., u_{N-K})     (n + K m)
 *   implicit  s_N = (z_N, u_{N-1}, ..., u_{N-K+1})   (n + max(K-1, 0) m)
 * (u_j = C z_j): s_{N+1} = M s_N.  Its nonzero eigenvalues are exactly
 * those of the recurrence's block companion (which adds only eigenvalue 0,
 * defective: directions of each delayed z_{N-j} invisible through C).
 * rs_cosim_transition_dim gives the size.  RS_ERR_UNDECIDED if J =
 * I_m - C G_0 is not certified invertible at prec; RS_ERR_MATH if det J is
 * exactly 0. */
slong rs_cosim_transition_dim(const rs_cosim_t cs);
int rs_cosim_transition(arb_mat_t M, const rs_cosim_t cs, slong prec,
                        rs_error_t err);

/* The coupling realisation actually needed: the recurrence depends on
 * (B, C) only through Phi_k(B) C (Phi_k is linear in B), so any exact rank
 * factorisation B C = P Q (P n x r, Q r x n, r = rank(B C)) gives the same
 * recurrence with r coupling variables w = Q z: B u_extrap(t) =
 * sum_j L_j(t) B C z_{N-j} = P w_extrap(t) (the polynomials are linear in
 * the node values), G'_0 Q = G_0 C, and for the implicit step
 * det(I_r - Q G'_0) = det(I_n - G'_0 Q) = det(I_n - G_0 C).  With r = m (B full column rank and
 * C full row rank, e.g. every m = 1 coupling) P = B, Q = C themselves;
 * otherwise P = the pivot columns of B C, Q = the nonzero rows of its
 * reduced row echelon form.  Sets *r and (re-dimensioned) P1 (n1 x r),
 * P2 (n2 x r), Q (r x n).  FD (m = 3) and DD (m = 4) both have r = 2. */
int rs_cosim_reduce(fmpq_mat_t P1, fmpq_mat_t P2, fmpq_mat_t Q, slong *r,
                    const rs_cosim_t cs, rs_error_t err);

/* Certified spectral radius of the co-simulation recurrence to `digits`
 * digits (rs_radius contract: 2 rad(rho) <= 10^-digits * rho), via
 * rs_radius_matrix_poly on the one-step map (k = 1, A[1] = I, A[0] = -M)
 * of the reduced realisation (rs_cosim_reduce: state (z_N, w history),
 * size n + h r; the unreduced map would add defective zero eigenvalues,
 * e.g. DD's 4 inputs through a rank-2 B, which only the slow cluster route
 * of rs_radius certifies).  The matrices are rebuilt at doubled precision while
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
 * K <= 1) when I - G_0 C and the zero structure allow. */
int rs_cosim_radius_recurrence(rs_radius_t r, const rs_cosim_t cs,
                               slong digits, slong max_prec, rs_error_t err);

/* Monolithic reference: A_mono = blockdiag(A_1, A_2) + B C (exact, n x n,
 * B = (B_1; B_2); the coupling conditions imposed continuously), its exact exponential e^{A_mono H} at prec, and the
 * certified spectral radius of that, which equals e^{H max Re eig(A_mono)}. */
int rs_cosim_monolithic_matrix(fmpq_mat_t Amono, const rs_cosim_t cs,
                               rs_error_t err);
int rs_cosim_monolithic(arb_mat_t Emono, const rs_cosim_t cs, slong prec,
                        rs_error_t err);
int rs_cosim_monolithic_radius(rs_radius_t r, const rs_cosim_t cs,
                               slong digits, slong max_prec, rs_error_t err);

/* A case with two subsystems integrated `exact` (src/analysis/analysis_cosim.c):
 * A_i from each subsystem's equations in its own states; coupling
 * variables u = (the partner states the equations use, in state order,
 * C row = e_state: displacement coupling / base-point excitation; then
 * every `coupling force NAME = EXPR` in declaration order, C row = EXPR's
 * coefficients in the states), B_i = the equations' coefficients of them;
 * H from `integrate S exact H`, method and K from `couple ... order K`.
 * Every parameter must be set (set values). */
int rs_cosim_from_case(rs_cosim_t cs, const rs_case_t c, rs_error_t err);

#ifdef __cplusplus
}
#endif
#endif
