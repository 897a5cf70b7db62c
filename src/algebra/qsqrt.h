/* qsqrt.h -- exact arithmetic in Q(sqrt d) (d > 1 squarefree) for the
 * stability functions of Butcher tableaux with irrational entries (sdirk2:
 * gamma = 1 - sqrt(2)/2).  A number is x + y sqrt(d) with x, y rational, a
 * polynomial p0 + sqrt(d) p1 with p0, p1 in Q[t], a complex number
 * re + i im with re, im in Q(sqrt d).  Signs are exact (no rounding): the
 * sign of x + y sqrt(d) compares x^2 with d y^2; real roots of a polynomial
 * over Q(sqrt d) are among those of its norm p0^2 - d p1^2 in Q[t]. */
#ifndef RECSTAB_QSQRT_H
#define RECSTAB_QSQRT_H

#include <flint/flint.h>
#include <flint/fmpz.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_poly.h>
#include <mpfr.h>
#include <arb.h>
#include <acb.h>
#include "util/qd.h"

#ifdef __cplusplus
extern "C" {
#endif

/* p0 + sqrt(d) p1 */
typedef struct { fmpq_poly_struct p0[1], p1[1]; } rs_qdpoly_struct;
typedef rs_qdpoly_struct rs_qdpoly_t[1];

void rs_qdpoly_init(rs_qdpoly_t p);
void rs_qdpoly_clear(rs_qdpoly_t p);
slong rs_qdpoly_degree(const rs_qdpoly_t p);
void rs_qdpoly_get_coeff(rs_qd_struct *c, const rs_qdpoly_t p, slong k);
void rs_qdpoly_set_coeff(rs_qdpoly_t p, slong k, const rs_qd_struct *c);
void rs_qdpoly_mul(rs_qdpoly_t r, const rs_qdpoly_t a, const rs_qdpoly_t b, slong d);
void rs_qdpoly_sub(rs_qdpoly_t r, const rs_qdpoly_t a, const rs_qdpoly_t b);
int rs_qdpoly_equal(const rs_qdpoly_t a, const rs_qdpoly_t b);
void rs_qdpoly_evaluate_fmpq(rs_qd_struct *v, const rs_qdpoly_t p, const fmpq_t t);
/* the norm p0^2 - d p1^2 (zero only for p = 0) */
void rs_qdpoly_norm(fmpq_poly_t n, const rs_qdpoly_t p, slong d);
/* "c0 + c1*z + ..." with each coefficient written x + y*sqrt(d) */
char *rs_qdpoly_get_str(const rs_qdpoly_t p, slong d, const char *var);

/* p(t) >= 0 for every real t: p is decided exactly at a rational in each
 * cell between the real roots of its norm (certified with Arb, the cells'
 * ends never used as samples).  Returns 1, or 0 with *t0 a rational where
 * p < 0. */
int rs_qdpoly_nonneg_real(const rs_qdpoly_t p, slong d, fmpq_t t0);

/* every root of p (real coefficients in Q(sqrt d), deg >= 1) has negative
 * real part: Routh's array over Q(sqrt d) with exact signs (a zero in the
 * first column counts as not Hurwitz) */
int rs_qdpoly_hurwitz(const rs_qdpoly_t p, slong d);

/* |P(i y)|^2 = A(y)^2 + B(y)^2 for real y, P(i y) = A(y) + i B(y) */
void rs_qdpoly_abs2_imag_axis(rs_qdpoly_t r, const rs_qdpoly_t P, slong d);

/* complex re + i im over Q(sqrt d) */
typedef struct { rs_qd_struct re[1], im[1]; } rs_qdc_struct;

rs_qdc_struct *rs_qdc_vec_init(slong n);
void rs_qdc_vec_clear(rs_qdc_struct *v, slong n);
/* |c|^2 = re^2 + im^2 in Q(sqrt d) */
void rs_qdc_abs2(rs_qd_struct *r, const rs_qdc_struct *c, slong d);
/* v = P(zr + i zi) for rational zr, zi (Horner over Q(sqrt d)(i)) */
void rs_qdpoly_evaluate_cx(rs_qdc_struct *v, const rs_qdpoly_t P, const fmpq_t zr, const fmpq_t zi, slong d);

/* the coefficients (c[0..n]) of the polynomial in lambda, c[n] != 0, has
 * every root strictly inside the unit circle: Schur-Cohn's recursion
 * c' = (conj(c_n) p - c_0 p*)/lambda with the exact sign of
 * |c_n|^2 - |c_0|^2 in Q(sqrt d) at each step.  Returns 1 or 0. */
int rs_qdc_schur_stable(const rs_qdc_struct *c, slong n, slong d);
/* the same recursion counting: 1 and *inside (the roots in |lambda| < 1;
 * none on the circle then), or 0 when some |c_n|^2 - |c_0|^2 vanishes */
int rs_qdc_schur_count(slong *inside, const rs_qdc_struct *c, slong n, slong d);

/* the same question answered from certified root enclosures (Arb, sqrt d a
 * ball): 1 all |root| < 1, 0 some |root| > 1, -1 undecided at every
 * precision up to 4096 bits (a root on or too near the circle) */
int rs_qdc_roots_inside(const rs_qdc_struct *c, slong n, slong d);
/* rs_qdc_schur_stable and rs_qdc_roots_inside on the same polynomial,
 * which must agree: 1 stable (Schur-Cohn; no root certified outside), 0 a
 * root certified outside (Schur-Cohn not stable), -1 not stable by
 * Schur-Cohn with no root certified outside (a root on or too near the
 * circle: marginal and unstable not told apart), -2 they disagree (a bug:
 * the caller exits 3).  *ar (unless NULL): rs_qdc_roots_inside's answer */
int rs_qdc_stable_checked(int *ar, const rs_qdc_struct *c, slong n, slong d);
/* the roots' certified sides: *below with |root| < 1, *above with |root| > 1;
 * 1 when every root is on one side (none on or too near the circle) */
int rs_qdc_roots_count(slong *below, slong *above, const rs_qdc_struct *c, slong n, slong d);
/* the n roots of that polynomial as certified, isolated balls z[0..n) at
 * precision prec (sqrt d a ball): 1, or 0 when they are not isolated there
 * (a repeated root, or prec too low) */
int rs_qdc_roots(acb_ptr z, const rs_qdc_struct *c, slong n, slong d, slong prec);
/* c[0..len) as complex balls z[0..len) at precision prec (sqrt d a ball) */
void rs_qdc_vec_get_acb(acb_ptr z, const rs_qdc_struct *c, slong len, slong d, slong prec);

/* R = N/D (real coefficients in Q(sqrt d), lowest terms, D(0) != 0) as a
 * one-step method's stability function (Hairer and Wanner, Solving ODEs II,
 * IV.3): A-stable iff E(y) = |D(iy)|^2 - |N(iy)|^2 >= 0 for real y and D
 * has no root in Re z <= 0 (checked as D(-z) Hurwitz); L-stable iff
 * A-stable and deg N < deg D. */
typedef struct {
    int a_stable, l_stable;
    int poles_right;            /* every root of D in Re z > 0 */
    int e_nonneg;               /* E >= 0 on the real line */
    fmpq witness[1];            /* a rational y with E(y) < 0 (e_nonneg = 0) */
    rs_qdpoly_struct E[1];      /* E(y) */
    int r_inf_finite;           /* deg N <= deg D */
    rs_qd_struct r_inf[1];      /* R(inf) when finite */
} rs_qd_astab_struct;
typedef rs_qd_astab_struct rs_qd_astab_t[1];

void rs_qd_astab_init(rs_qd_astab_t a);
void rs_qd_astab_clear(rs_qd_astab_t a);
void rs_qd_astab_decide(rs_qd_astab_t a, const rs_qdpoly_t N, const rs_qdpoly_t D, slong d);

/* |R(z)| < 1 at z = zr + i zi (rationals, D(z) != 0), decided twice: by
 * Schur-Cohn on D(z) lambda - N(z) over Q(sqrt d)(i) and by the certified
 * root of that polynomial in Arb.  Returns 1 (stable), 0 (not strictly
 * stable), -2 when the two disagree (a bug: the caller exits 3), -1 when
 * D(z) = 0. */
int rs_qd_onestep_stable_at(const rs_qdpoly_t N, const rs_qdpoly_t D, slong d, const fmpq_t zr, const fmpq_t zi);

/* an end of a stability interval: infinite, or a real algebraic number
 * given exactly as the real root of the irreducible `minpoly` enclosed by
 * `x` (rational when minpoly has degree 1, then also in q) */
typedef struct {
    int inf;                    /* -1: -inf, 1: +inf, 0: finite */
    fmpz_poly_struct minpoly[1];
    arb_struct x[1];
    fmpq q[1];
} rs_qd_end_struct;

/* the stability interval of R = N/D around 0 on the real axis (imag = 0:
 * the connected set of real x with |R(x)| <= 1 that contains 0) or on the
 * imaginary axis (imag = 1: real y with |R(iy)| <= 1).  The ends are among
 * the real roots of the norm of D^2 - N^2 (of E(y) on the imaginary axis);
 * each cell between them is decided at a rational sample by the exact sign
 * over Q(sqrt d), a root between two bounded cells is bounded by continuity
 * and an end is closed (|R| = 1 there).  R(0) = 1 is assumed (consistent
 * methods), so 0 is an end or inside; returns 0, or -1 when |R(0)| > 1
 * (no interval). */
typedef struct {
    rs_qd_end_struct lo[1], hi[1];
} rs_qd_iv_struct;
typedef rs_qd_iv_struct rs_qd_iv_t[1];

void rs_qd_iv_init(rs_qd_iv_t iv);
void rs_qd_iv_clear(rs_qd_iv_t iv);
int rs_qd_onestep_interval(rs_qd_iv_t iv, const rs_qdpoly_t N, const rs_qdpoly_t D, slong d, int imag);
/* "-inf", "inf", a rational, or "root of MINPOLY in [lo, hi]" (flint_free it);
 * the JSON writes the object of rs_an_alg_end_json instead, this string only
 * when the enclosure does not single out one root */
char *rs_qd_end_get_str(const rs_qd_end_struct *e);

#ifdef __cplusplus
}
#endif
#endif
