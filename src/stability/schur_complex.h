/* schur_complex.h -- unit-circle root location for polynomials with
 * Gaussian-rational coefficients p = re + i im (re, im in Q[lambda]): the
 * Schur-Cohn recursion on the complex coefficients directly, cross-checked
 * against the exact count of the real polynomial p * conj(p) = re^2 + im^2
 * (same root moduli).  Private to the library (used by analysis/an_astability.c). */
#ifndef RECSTAB_SCHUR_COMPLEX_H
#define RECSTAB_SCHUR_COMPLEX_H

#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"
#include "recstab/rootcount.h"

/* 1 when every root of re + i im lies strictly inside the unit circle
 * (Schur-Cohn: |a_n| > |a_0| and the reduced polynomial
 * (conj(a_n) p - a_0 p*)/lambda again), else 0.  p must not be zero. */
int rs_schur_complex_inside(const fmpq_poly_t re, const fmpq_poly_t im);

/* P = re^2 + im^2 = p conj(p) as a primitive integer polynomial. */
void rs_schur_complex_norm(fmpz_poly_t P, const fmpq_poly_t re, const fmpq_poly_t im);

/* g = gcd(a, b) over Q(i) (monic; zero when both are zero). */
void rs_schur_complex_gcd(fmpq_poly_t gre, fmpq_poly_t gim, const fmpq_poly_t are, const fmpq_poly_t aim,
                          const fmpq_poly_t bre, const fmpq_poly_t bim);

/* q = the quotient of a by b over Q(i) (b not zero; the remainder dropped). */
void rs_schur_complex_div(fmpq_poly_t qre, fmpq_poly_t qim, const fmpq_poly_t are, const fmpq_poly_t aim,
                          const fmpq_poly_t bre, const fmpq_poly_t bim);

/* Yun's squarefree decomposition over Q(i): p = c prod_k a_k^k (k = 1..n),
 * a_k monic, squarefree, pairwise coprime (1 when absent). */
typedef struct {
    slong n;
    fmpq_poly_struct *re, *im;   /* a_(k+1) = re[k] + i im[k] */
} rs_cx_sqfree_t;
void rs_cx_sqfree_init(rs_cx_sqfree_t *f);
void rs_cx_sqfree_clear(rs_cx_sqfree_t *f);
void rs_schur_complex_sqfree(rs_cx_sqfree_t *f, const fmpq_poly_t re, const fmpq_poly_t im);

/* The exact verdict of the scalar recurrence with characteristic polynomial
 * re + i im: stable (Schur-Cohn, cross-checked against the count of
 * p conj(p): RS_ERR_INCONSISTENT when they disagree), unstable (a root
 * outside, or a repeated root on the circle: gcd(p, p') has one) or
 * marginal.  deg is the degree p must have: a lower one is "singular". */
int rs_schur_complex_status(rs_status_t *st, const fmpq_poly_t re, const fmpq_poly_t im, slong deg,
                            rs_error_t err);

/* The real conditions of p = re + i im (re, im in Z[params, lambda],
 * lambda the variable lv of ctx) whose zeros bound the parameter cells where
 * p's root count inside / on / outside the circle and the multiplicity of its
 * roots are constant: lead = |a_n|^2 (degree drop), delta[k] the k-th
 * Schur-Cohn leading coefficient |a_m|^2 - |a_0|^2 of the division-free
 * recursion (all roots inside iff every delta > 0), res = Res(p, p*)
 * (p* = lambda^n conj(p(1/conj lambda)): real, zero when a root is on the
 * circle), disc_re + i disc_im = the discriminant of p (a repeated root);
 * self_inversive: a_n p* = conj(a_0) p (roots symmetric about the circle). */
typedef struct {
    int have;
    int self_inversive;
    slong ndelta;
    fmpz_mpoly_struct *delta;
    fmpz_mpoly_t lead, res, disc_re, disc_im;
} rs_schur_cx_conds_t;

void rs_schur_cx_conds_init(rs_schur_cx_conds_t *c);
void rs_schur_cx_conds_clear(rs_schur_cx_conds_t *c, const fmpz_mpoly_ctx_t ctx);
/* 0 when p has degree < 1 in lambda or the recursion grows too large */
int rs_schur_cx_conds(rs_schur_cx_conds_t *c, const fmpz_mpoly_t re, const fmpz_mpoly_t im, slong lv,
                      const fmpz_mpoly_ctx_t ctx);

#endif
