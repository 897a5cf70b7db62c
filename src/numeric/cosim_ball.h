/* numeric/cosim_ball.h -- the co-simulation (cosim.h) with ball entries:
 * A_i, B_i, C and H as Arb balls, so that one evaluation of the one-step
 * map encloses the maps of EVERY model in a parameter box (the certified
 * region and claim of exactly integrated subsystems,
 * src/analysis/an_cosim_region.c), and the Stein certificates that decide
 * the spectral radius of every matrix in such a ball at once.  Private to
 * the library (not installed). */
#ifndef RECSTAB_NUMERIC_COSIM_BALL_H
#define RECSTAB_NUMERIC_COSIM_BALL_H

#include <arb_mat.h>
#include "recstab/cosim.h"

typedef struct {
    slong n1, n2, m;           /* as rs_cosim_struct (m >= 0 here) */
    arb_mat_t A1, A2, B1, B2, C;
    arb_t H;
    int method;
    slong order;
    int ext;                   /* RS_COSIM_EXT_* (NONE unless rs_cosim_ball_set_ext) */
    fmpq_t alpha_T;            /* the extension's sample point (default 1/2) */
} rs_cosim_ball_struct;
typedef rs_cosim_ball_struct rs_cosim_ball_t[1];

void rs_cosim_ball_init(rs_cosim_ball_t b);
void rs_cosim_ball_clear(rs_cosim_ball_t b);
/* b = cs with the coupling realisation (B1, B2, C, m) (cs's own or a
 * reduced one), rounded to prec (exact when representable). */
void rs_cosim_ball_set(rs_cosim_ball_t b, const rs_cosim_t cs, const fmpq_mat_t B1, const fmpq_mat_t B2,
                       const fmpq_mat_t C, slong m, slong prec);
/* Re-dimension (entries zero) and copy method/order from cs. */
void rs_cosim_ball_set_dims(rs_cosim_ball_t b, slong n1, slong n2, slong m, int method, slong order);
/* The D-/I-extension coupling (cosim_ext.h) for the ball model: ext and
 * alpha_T (NULL: 1/2).  rs_cosim_ball_set leaves ext NONE (its callers build
 * reduced realisations, which the extension map does not use). */
void rs_cosim_ball_set_ext(rs_cosim_ball_t b, int ext, const fmpq_t alpha_T);
/* n1 + n2 + history (the extension map: n1 + n2). */
slong rs_cosim_ball_dim(const rs_cosim_ball_t b);

/* E = e^{A H} and Phi of the ball model (rs_cosim_exp_phi's layout, m =
 * b->m, K = b->order), enclosing those of every model in b (cosim.c). */
void rs_cosim_ball_exp_phi(arb_mat_t E, arb_mat_t Phi, const rs_cosim_ball_t b, slong prec);

/* The one-step map (rs_cosim_transition) enclosing the maps of every model
 * in b (cosim.c; with an extension, rs_cosim_ext_ball_transition).  RS_ERR_UNDECIDED when the implicit Jacobian J is not
 * certified invertible over the ball, RS_ERR_MATH when it is exactly 0. */
int rs_cosim_ball_transition(arb_mat_t M, const rs_cosim_ball_t b, slong prec, rs_error_t err);

enum {
    RS_COSIM_BALL_UNDECIDED = 0,
    RS_COSIM_BALL_STABLE = 1,    /* rho(M) < 1 for every M in the ball */
    RS_COSIM_BALL_UNSTABLE = 2   /* rho(M) > 1 for every M in the ball */
};

/* A Stein certificate for every matrix in the ball M (dim d): a symmetric
 * point matrix P solving P - (M0/r)^T P (M0/r) = I approximately at the
 * midpoint M0, then, in ball arithmetic, D = P - (M/r)^T P (M/r) positive
 * definite (Cholesky) for every M in the ball.  Then M/r has no eigenvalue
 * on the unit circle, and (Stein) P > 0 iff rho(M/r) < 1: P > 0 certified
 * with r = 1 proves rho(M) < 1; a vector x with x^T P x < 0 certified with
 * r >= 1 proves rho(M) > r (if rho(M/r) < 1, P = sum (M/r)^{Tk} D (M/r)^k
 * would be positive definite; rho(M/r) = 1 is excluded by D > 0).  r = 1
 * first; if that fails and a GSL double estimate rho0 at the midpoint
 * (Arb QR at prec when within 1e-6 of 1) exceeds 1, r = (1 + rho0)/2
 * (eigenvalue pairs with lambda_i lambda_j = 1 make the r = 1 system
 * singular).  Everything else: undecided. */
int rs_cosim_ball_stein(const arb_mat_t M, slong prec);

#endif
