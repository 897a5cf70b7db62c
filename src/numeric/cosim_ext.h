/* numeric/cosim_ext.h -- Li, Meyer, Lu, Schweizer's extended implicit
 * co-simulation (seed li-meyer-lu-schweizer-cosimulation-stability.md,
 * sect. 3.2, eq. 17-23, Fig. 5 and 8): `couple implicit order K extension
 * D` and `... extension I [alpha_T = VALUE]`.  Private to the library.
 *
 * The paper does not print the extended polynomials; recstab's READING
 * (documented in README.md and the cases/cosim files):
 *  - per macro step [T_N, T_N + H] each coupling variable is sampled at
 *    T_N, T_{N+a} = T_N + a H and T_{N+1} (a = alpha_T in (0, 1); D uses
 *    the paper's a = 1/2);
 *  - u(t) on the step is the piecewise degree-K interpolant of those three
 *    samples: K = 0 piecewise constant (u_{N+a} on (T_N, T_{N+a}], u_{N+1}
 *    on (T_{N+a}, T_{N+1}], the hold of the direct implicit K = 0); K = 1
 *    piecewise linear through the three samples; K = 2 the quadratic
 *    through them;
 *  - u_N is the previous step's corrected value (= C z_N, the coupling
 *    condition holds there); the unknowns u*_{N+a}, u*_{N+1} (2 m values)
 *    are fixed by the m coupling conditions g = u*_{N+1} - C z*_{N+1} = 0
 *    together with
 *      D: g' = (d/dt) u*(T_{N+1}) - C (A z*_{N+1} + B u*_{N+1}) = 0
 *         (z*' from the subsystems' equations at T_{N+1}), or
 *      I: int_{T_N}^{T_{N+1}} (u*(t) - C z*(t)) dt = 0;
 *  - the conditions are affine in the unknowns, so the paper's linearised
 *    Newton step (eq. 21) from any predictor solves them exactly: the
 *    predictor (eq. 17) drops out of the linear analysis, and the corrector
 *    (eq. 22) gives z_{N+1} = M z_N with M n x n (no history is needed:
 *    the samples of the step only use u_N = C z_N).
 * The tests check M against a literal predictor / finite-difference
 * Jacobian / corrector time loop (tests/unit/numeric/test_cosim_ext.c). */
#ifndef RECSTAB_NUMERIC_COSIM_EXT_H
#define RECSTAB_NUMERIC_COSIM_EXT_H

#include "recstab/cosim.h"
#include "numeric/cosim_ball.h"

/* RS_ERR_INPUT unless cs->ext is none, or D/I with the implicit method,
 * K <= RS_COSIM_EXT_MAX_ORDER and 0 < alpha_T < 1 (cs itself checked by
 * rs_cosim_check, which calls this). */
int rs_cosim_ext_check(const rs_cosim_t cs, rs_error_t err);

/* M (n x n, n = n1 + n2): z_{N+1} = M z_N.  RS_ERR_MATH if the 2m x 2m
 * Jacobian of the extended conditions is exactly singular, RS_ERR_UNDECIDED
 * if it is not certified invertible at prec. */
int rs_cosim_ext_transition(arb_mat_t M, const rs_cosim_t cs, slong prec, rs_error_t err);

/* The same map for the ball model b (b->ext D or I, b->method implicit,
 * K <= 2, 0 < alpha_T < 1: the caller's checks): one evaluation encloses
 * the maps of every model in b (the certified region and claim over a
 * parameter box, src/analysis/an_cosim_region.c).  RS_ERR_UNDECIDED when
 * the 2m x 2m Jacobian is not certified invertible over the ball (then a
 * smaller box may certify), RS_ERR_MATH when it is exactly singular. */
int rs_cosim_ext_ball_transition(arb_mat_t M, const rs_cosim_ball_t b, slong prec, rs_error_t err);
/* Its two enclosures, which rs_cosim_ext_ball_transition intersects
 * entrywise.  _naive: one ball evaluation of the map (every dependency
 * lost: wide once the box is).  _centred: the mean-value form T(mid) +
 * sum_e dT/de(b) [+- rad_e] over the entries e of A1, A2, B1, B2, C wider
 * than prec/2 bits (the box's coordinates), dT/de from the dual-number
 * model (cosim_ext.c); width ~ |dT/de| rad_e + O(rad^2).  Same contract;
 * rs_cosim_ext_ball_transition returns RS_ERR_INCONSISTENT if the two are
 * disjoint somewhere (one of them is wrong). */
int rs_cosim_ext_ball_transition_naive(arb_mat_t M, const rs_cosim_ball_t b, slong prec, rs_error_t err);
int rs_cosim_ext_ball_transition_centred(arb_mat_t M, const rs_cosim_ball_t b, slong prec, rs_error_t err);

#endif
