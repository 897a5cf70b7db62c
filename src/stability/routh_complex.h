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
#include <flint/fmpz_mpoly.h>
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

/* p's own root counts over Q(i) into rc (inside / on / outside the unit
 * circle, lambda = +-1 and the circle roots by multiplicity): Yun's
 * squarefree decomposition over Q(i), then the Bilharz count of each
 * factor's bilinear image. */
void rs_routh_complex_rootcount(rs_rootcount_t rc, const fmpq_poly_t re, const fmpq_poly_t im);

/* Both exact routes, Schur-Cohn over Q(i) and Bilharz on the bilinear
 * transform: the verdict when they agree, RS_ERR_INCONSISTENT when not. */
int rs_routh_complex_checked_status(rs_status_t *st, const fmpq_poly_t re, const fmpq_poly_t im,
                                    slong deg, rs_error_t err);

/* The Bilharz conditions with symbolic real parameters: p = re + i im with
 * re, im in Z[params][lambda] (lambda the variable lv of ctx, formal degree
 * n = the larger lambda-degree).  With q(s) = (1 - s)^n p((1 + s)/(1 - s)),
 * c = its s^n coefficient ((-1)^n p(-1)) and f(w) = conj(c) i^(-n) q(i w)
 * = P(w) + i Q(w) (P, Q real, P of degree n with leading coefficient
 * |c|^2, stored with w in lambda's slot), every root of p lies inside the
 * unit circle iff every cond[k] > 0, k = 0..n: cond[0] = |c|^2 (q keeps
 * degree n: lambda = -1 is no root) and cond[k] = (-1)^k lc(T_k), where
 * T_0 = P, T_1 = Q and T_(k+1) = -prem(T_(k-1), T_k) / lc(T_(k-1))^2
 * (1 for k = 1) is the fraction-free signed remainder chain of P and Q (the
 * subresultant chain: its leading coefficients are Bilharz's determinants up
 * to positive factors).  All roots of f in Im w > 0 (Re s < 0) iff the
 * Cauchy index Ind(Q/P) = -n iff that chain is regular with alternating
 * leading signs.  The divisions are exact (subresultants); a division that
 * is not (never expected) is skipped, which keeps every sign where the
 * earlier conditions hold.  ncond < n + 1 when a leading coefficient is
 * identically zero (cond[ncond - 1] = 0: never stable).  Returns 0 when p
 * has degree < 1 or an intermediate exceeds max_terms. */
typedef struct {
    slong n, ncond;
    fmpz_mpoly_struct *cond;
    fmpz_mpoly_t P, Q;
} rs_routh_cx_conds_t;

void rs_routh_cx_conds_init(rs_routh_cx_conds_t *c, const fmpz_mpoly_ctx_t ctx);
void rs_routh_cx_conds_clear(rs_routh_cx_conds_t *c, const fmpz_mpoly_ctx_t ctx);
int rs_routh_cx_conds(rs_routh_cx_conds_t *c, const fmpz_mpoly_t re, const fmpz_mpoly_t im, slong lv,
                      const fmpz_mpoly_ctx_t ctx, slong max_terms);

#endif
