/* routh_complex.h -- half-plane root location for polynomials with
 * Gaussian-rational coefficients q = re + i im (re, im in Q[s]): the
 * generalised Routh-Hurwitz test of Bilharz (the Routh chain of q(i w) =
 * A(w) + i B(w) is the signed remainder sequence of A and B, a Sturm chain
 * whose Cauchy index counts the roots in each half-plane), with the
 * singular cases handled exactly: a common factor G = gcd(A, B) holds the
 * roots on the imaginary axis (its real roots) and conjugate pairs
 * w0, conj(w0) (one root on each side).  The bilinear route
 * lambda = (1 + s)/(1 - s) makes it a second exact test of the unit circle,
 * cross-checked against complex Schur-Cohn (schur_complex.h).
 * Private to the library. */
#ifndef RECSTAB_ROUTH_COMPLEX_H
#define RECSTAB_ROUTH_COMPLEX_H

#include <flint/fmpq_poly.h>
#include "recstab/error.h"
#include "recstab/rootcount.h"

typedef struct {
    slong degree;               /* degree of q over Q(i) (-1: q = 0) */
    slong left, right, axis;    /* roots with Re s < 0, > 0, = 0 (with multiplicity) */
    int axis_repeated;          /* an imaginary-axis root of multiplicity >= 2 */
    fmpq_poly_t A, B;           /* q(i w) = A(w) + i B(w) */
    fmpq_poly_t G;              /* gcd(A, B), monic (1 when coprime) */
    slong len;                  /* the chain: signed remainder sequence of A/G, B/G */
    fmpq_poly_struct *chain;    /* (or B/G, A/G when deg B > deg A), each scaled by a positive number */
} rs_routh_complex_struct;
typedef rs_routh_complex_struct rs_routh_complex_t[1];

void rs_routh_complex_init(rs_routh_complex_t t);
void rs_routh_complex_clear(rs_routh_complex_t t);

/* The half-plane counts of q = re + i im (not both zero). */
void rs_routh_complex_count(rs_routh_complex_t t, const fmpq_poly_t re, const fmpq_poly_t im);

/* q(s) = (1 - s)^n p((1 + s)/(1 - s)), n = deg p over Q(i), on both parts. */
void rs_routh_complex_bilinear(fmpq_poly_t qre, fmpq_poly_t qim, const fmpq_poly_t re, const fmpq_poly_t im);

/* The verdict of the scalar recurrence with characteristic polynomial
 * re + i im by the bilinear route alone: inside <-> Re s < 0, lambda = -1
 * <-> the degree drop of q.  Stable, unstable (a root outside, or a repeated
 * one on the circle), marginal; singular when deg p < deg.  t (may be NULL)
 * receives the counts of q. */
int rs_routh_complex_status(rs_status_t *st, rs_routh_complex_t t, const fmpq_poly_t re,
                            const fmpq_poly_t im, slong deg, rs_error_t err);

/* Both exact routes, Schur-Cohn over Q(i) and Bilharz on the bilinear
 * transform: the verdict when they agree, RS_ERR_INCONSISTENT when not. */
int rs_routh_complex_checked_status(rs_status_t *st, const fmpq_poly_t re, const fmpq_poly_t im,
                                    slong deg, rs_error_t err);

#endif
