/* numeric/cosim_dbl.h -- the co-simulation's one-step map and its certified
 * spectral radius in hardware double with rigorous error bounds (issue 14
 * part 3, maps `of radius`): midpoint-radius interval matrices of doubles
 * (Rump: every product's rounding error bounded a priori through
 * gamma_n = n u / (1 - n u), u = 2^-53, with a safety factor, round to
 * nearest only, no fesetround), the exponentials of the Van Loan matrices
 * by scaling and squaring of a Taylor polynomial whose remainder
 * ||Y||^{N+1}/(N+1)! / (1 - ||Y||/(N+2)) is added to every entry, then
 * cosim_fast.c's Gershgorin certificate on W T V, also in interval double
 * (V from a Hessenberg QR and inverse iteration, no GSL).
 * Every enclosure holds for the exact map; where the bounds are too wide to
 * decide, RS_ERR_UNDECIDED and the caller takes the Arb route
 * (rs_cosim_fast_radius, then rs_cosim_radius).  Private (not installed). */
#ifndef RECSTAB_NUMERIC_COSIM_DBL_H
#define RECSTAB_NUMERIC_COSIM_DBL_H

#include <arb_mat.h>
#include "recstab/cosim.h"
#include "recstab/radius.h"

/* the model in interval double: entry k of a matrix is mid[k] +- rad[k]
 * (row major); A_1, A_2 square, B = (B_1; B_2) n x m, C m x n, H > 0 */
typedef struct {
    slong n1, n2, m;
    int method;                /* RS_COSIM_EXPLICIT / RS_COSIM_IMPLICIT */
    slong order;               /* K */
    double *A1m, *A1r, *A2m, *A2r, *Bm, *Br, *Cm, *Cr;
    double Hm, Hr;
    double Lm[(RS_COSIM_MAX_ORDER + 1) * (RS_COSIM_MAX_ORDER + 1)], Lr[(RS_COSIM_MAX_ORDER + 1) * (RS_COSIM_MAX_ORDER + 1)];
    int haveL;                 /* L = Lagrange coefficients (rs_cosim_lagrange) of (method, order) set */
} rs_cosim_dbl_struct;
typedef rs_cosim_dbl_struct rs_cosim_dbl_t[1];

void rs_cosim_dbl_init(rs_cosim_dbl_t d);
void rs_cosim_dbl_clear(rs_cosim_dbl_t d);
/* dimensions (entries zero), method and order; the Lagrange coefficients
 * are computed here once (not per point); RS_ERR_INPUT for a bad order */
int rs_cosim_dbl_set_dims(rs_cosim_dbl_t d, slong n1, slong n2, slong m, int method, slong order, rs_error_t err);
/* d = src's dimensions, method, order, H and Lagrange coefficients, its
 * matrices zero (no rs_cosim_lagrange per point) */
void rs_cosim_dbl_set_like(rs_cosim_dbl_t d, const rs_cosim_dbl_t src);
/* the exact model cs (no D-/I-extension) rounded to interval doubles */
int rs_cosim_dbl_set_cosim(rs_cosim_dbl_t d, const rs_cosim_t cs, rs_error_t err);
/* x (fmpq) as an interval double (mid, rad); 0 when not finite */
int rs_dbl_set_fmpq(double *mid, double *rad, const fmpq_t x);

slong rs_cosim_dbl_dim(const rs_cosim_dbl_t d);
/* T (dim x dim, arrays of dim^2) encloses the exact one-step map (the map
 * of rs_cosim_ball_transition for the realisation (B, C) of d, for every
 * model inside d's intervals).  RS_ERR_UNDECIDED when a bound overflows or
 * the implicit Jacobian is not certified invertible. */
int rs_cosim_dbl_transition(double *Tm, double *Tr, const rs_cosim_dbl_t d);
/* The part of the map subsystem s (0, 1) alone sets: its exponential E_s
 * (n_s x n_s) and gain columns Phi (n_s x m (K + 1)), midpoints then radii,
 * rs_cosim_dbl_sub_len(d, s) doubles; 0 on overflow.  A map whose axes leave
 * A_s and B_s unchanged along a row computes it once per row value
 * (analysis_cosim.c): the same doubles as at every point. */
slong rs_cosim_dbl_sub_len(const rs_cosim_dbl_t d, int s);
int rs_cosim_dbl_sub(double *S, const rs_cosim_dbl_t d, int s);
/* as rs_cosim_dbl_transition with pre[s] (when pre and pre[s] are not NULL)
 * the block rs_cosim_dbl_sub gives for a model with d's A_s, B_s and H */
int rs_cosim_dbl_transition_pre(double *Tm, double *Tr, const rs_cosim_dbl_t d, const double *const *pre);
/* r->lower <= rho(T) <= r->upper, T the exact one-step map of every model
 * in d; RS_ERR_UNDECIDED as rs_cosim_fast_radius (dominant disc not
 * isolated, enclosure wider than 2^-20 relative, or a failure above). */
int rs_cosim_dbl_radius(rs_radius_t r, const rs_cosim_dbl_t d);
int rs_cosim_dbl_radius_pre(rs_radius_t r, const rs_cosim_dbl_t d, const double *const *pre);

#endif
