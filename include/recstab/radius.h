/* radius.h -- certified spectral radius from companion-matrix eigenvalues.
 *
 * Exact-coefficient input is first made squarefree (FLINT), so every root of
 * each factor is simple and acb_mat_eig_simple can certify it; precision is
 * doubled from a cheap start until the radius interval is narrower than
 * 10^-digits relatively, up to a ceiling (RS_RADIUS_MAX_PREC_DEFAULT bits).
 *
 * Accuracy goal ("digits"): 2*rad(rho) <= 10^-digits * (lower bound of rho).
 * For exact (fmpz) input every root is nonzero after removing the lambda^k
 * factor, so the goal is always relative (rho == 0 exactly when p = c*lambda^k).
 * For ball input (acb_poly, matrix polynomials) a radius ball that still
 * contains 0 is accepted once 2*rad(rho) <= 10^-digits absolutely.
 *
 * Every function leaves r in a consistent state; on failure `partial` says
 * whether lower/upper/rho still hold a certified (but too wide) enclosure.
 * max_prec <= 0 means RS_RADIUS_MAX_PREC_DEFAULT; digits must be >= 1. */
#ifndef RECSTAB_RADIUS_H
#define RECSTAB_RADIUS_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include <arb.h>
#include <acb.h>
#include <acb_poly.h>
#include <acb_mat.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_RADIUS_MAX_PREC_DEFAULT 65536

/* Above this degree the high-degree paths run: Aberth seeds, the count of
 * the verdict from certified root balls cross-checked with Schur-Cohn
 * (rs_radius_count_balls), Routh as an integer PRS. */
#define RS_RADIUS_HIGH_DEGREE 64

typedef struct {
    arb_t lower;          /* certified: lower <= rho */
    arb_t upper;          /* certified: rho <= upper */
    arb_t rho;            /* ball containing rho */
    slong digits;         /* requested digits */
    slong prec;           /* working precision (bits) finally used */
    slong nroots;         /* number of roots (with multiplicity) */
    acb_ptr roots;        /* certified enclosures, with multiplicity */
    slong *mult;          /* multiplicity of each root entry (1 if squarefree) */
    int method_double;    /* 1 if computed by the uncertified GSL path */
    double rho_double;    /* the double-precision value (GSL path) */
    /* additions */
    int method;           /* RS_RADIUS_METHOD_* that produced the result */
    int isolated;         /* 1: every roots[] ball is a certified isolating
                             enclosure of one distinct root (of its squarefree
                             factor); 0: some balls are cluster enclosures
                             (acb_mat_eig_multiple: a ball repeated k times
                             contains exactly k roots) or a mere bound */
    int partial;          /* 1 after an error return when lower/upper/rho still
                             hold a certified enclosure, only wider than
                             requested (nroots is then 0) */
    slong nouter;         /* > 0: above degree 64 only this many roots, those
                             whose balls may hold the largest modulus, were
                             refined to the requested digits; the other balls
                             are certified and isolating but coarser (about 60
                             bits; rs_radius_aberth_certify, or
                             rs_radius_outer_refine on the fallback route).
                             0: every root */
} rs_radius_struct;
typedef rs_radius_struct rs_radius_t[1];

enum {
    RS_RADIUS_METHOD_NONE = 0,
    RS_RADIUS_METHOD_COMPANION = 1, /* companion matrix + eig_simple/multiple */
    RS_RADIUS_METHOD_COMPLEX_ROOTS = 2, /* arb_fmpz_poly_complex_roots */
    RS_RADIUS_METHOD_DOUBLE = 3,    /* GSL, uncertified */
    RS_RADIUS_METHOD_BOUND = 4,     /* only a global enclosure / norm bound */
    RS_RADIUS_METHOD_FIND_ROOTS = 5 /* GSL-seeded acb_poly_find_roots */
};

void rs_radius_init(rs_radius_t r);
void rs_radius_clear(rs_radius_t r);
void rs_radius_swap(rs_radius_t r, rs_radius_t s);

/* Certified spectral radius of the roots of p (deg p >= 1) to `digits`
 * relative digits, precision never above max_prec bits (RS_ERR_LIMIT with a
 * message naming the limit otherwise). */
int rs_radius_fmpz_poly(rs_radius_t r, const fmpz_poly_t p, slong digits,
                        slong max_prec, rs_error_t err);

/* Three certified routes for exact input (same contract as
 * rs_radius_fmpz_poly).  All split off lambda^k exactly, factor the rest
 * squarefree (fmpz_poly_factor_squarefree), enclose the simple roots of each
 * factor (linear factors: -f0/f1 directly), list every root e times for a
 * factor of exponent e, and double the precision until the goal is met:
 * _find_roots: first rs_radius_aberth_certify (Aberth-Ehrlich on Arb
 *   midpoints at a precision per root, from GSL double seeds below degree 65
 *   and Aberth-in-double seeds from Newton-polygon points above; one
 *   inclusion disc per root; above degree 64 only the possibly largest
 *   roots to full precision).  When that does not certify:
 *   acb_poly_find_roots seeded with the GSL double roots; certified
 *   when all deg f output balls are isolated (Arb validates each ball with a
 *   root-inclusion test, disjoint balls => exactly one root each), at most
 *   32 iterations; when that does not isolate all roots (bad seeds) or
 *   leaves one with fewer than prec - 40 accurate bits (ill-conditioned), the
 *   factor goes to arb_fmpz_poly_complex_roots.  Start at
 *   ceil(digits*log2(10)) + 32 bits.  Above degree 64 the seeds come from
 *   rs_radius_aberth_d (GSL as fallback), Arb works at prec + d/2 and an
 *   evaluation-limited result is redone once at a precision covering the
 *   measured loss; r->prec reports the highest precision used.  The
 *   default route (fastest).
 * _companion: companion matrix (acb_mat_companion), acb_mat_approx_eig_qr,
 *   acb_mat_eig_simple (fallback acb_mat_eig_multiple_rump: cluster balls,
 *   isolated = 0), same start precision.  Slowest (the QR step dominates).
 * _complex_roots: arb_fmpz_poly_complex_roots with a target accuracy of
 *   ceil(digits*log2(10)) + 8 bits; max_prec caps that target (Arb raises its
 *   internal working precision itself, which terminates for squarefree
 *   input).  Independent cross-check.
 * Timings: bench/bench_radius.c. */
int rs_radius_fmpz_poly_find_roots(rs_radius_t r, const fmpz_poly_t p,
                                   slong digits, slong max_prec,
                                   rs_error_t err);
int rs_radius_fmpz_poly_companion(rs_radius_t r, const fmpz_poly_t p,
                                  slong digits, slong max_prec,
                                  rs_error_t err);
int rs_radius_fmpz_poly_complex_roots(rs_radius_t r, const fmpz_poly_t p,
                                      slong digits, slong max_prec,
                                      rs_error_t err);

/* Same for a polynomial with ball coefficients (from non-polynomial schemes,
 * e.g. matrix exponentials): certification needs simple roots; returns
 * RS_ERR_UNDECIDED if they cannot be isolated at max_prec. */
int rs_radius_acb_poly(rs_radius_t r, const acb_poly_t p, slong digits,
                       slong max_prec, rs_error_t err);
/* Details: exactly-zero low coefficients give exact zero roots; the rest goes
 * through companion matrix + acb_mat_approx_eig_qr + acb_mat_eig_simple.  If
 * that fails, acb_mat_eig_multiple_rump is tried: its cluster enclosures still
 * certify rho (each ball holds >= 1 root, their union holds all), so RS_OK is
 * returned with isolated = 0 when they meet the goal.  Otherwise precision is
 * doubled, up to max_prec or, for inexact coefficients accurate to A bits, up
 * to 2A + 128 bits (more cannot help), or until a doubling fails to halve the
 * width.  Then RS_ERR_UNDECIDED is returned and, when possible, partial = 1
 * with the best certified enclosure: from eig_multiple, else
 * upper = max|E_i| + eps (acb_mat_eig_global_enclosure), else Fujiwara's
 * bound, with lower = |p_0/p_d|^(1/d) (the geometric mean of the |roots|).
 * A multiple root of a ball polynomial can never be certified as simple. */

/* Spectral radius of the matrix recurrence
 *     A[k] z[n+k] + A[k-1] z[n+k-1] + ... + A[0] z[n] = 0
 * with A[0..k] square m x m ball matrices (k >= 1), i.e. of the roots of
 * det(sum_j A[j] lambda^j): eigenvalues of the (k*m) x (k*m) block companion
 * matrix [0 I 0 ..; ..; -A[k]^-1 A[0] ... -A[k]^-1 A[k-1]], certified as in
 * rs_radius_acb_poly (roots[] has k*m entries, mult[] counts identical cluster
 * balls).  A[k] must be invertible: RS_ERR_MATH if its determinant is exactly
 * zero or it cannot be inverted even at max_prec. */
int rs_radius_matrix_poly(rs_radius_t r, const acb_mat_struct *A, slong k,
                          slong digits, slong max_prec, rs_error_t err);

/* Uncertified double-precision baseline (GSL gsl_poly_complex_solve on the
 * coefficients rounded to double); fills rho_double and roots as exact
 * doubles (radius 0) and sets method_double.  Zero roots (lambda^k factor)
 * are split off exactly first.  Coefficients are scaled by a common power of
 * two when they would overflow; RS_ERR_LIMIT if a nonzero coefficient would
 * then underflow to 0.  rho is set to the point rho_double but is NOT
 * certified: lower = 0 and upper = +inf.  The GSL error handler is switched
 * off during the call and restored (not thread-safe). */
int rs_radius_double(rs_radius_t r, const fmpz_poly_t p, rs_error_t err);
/* r->rho = max |roots[i]| (a ball containing the largest modulus when every
 * eigenvalue lies in some roots[i]), r->lower / r->upper its bounds (lower
 * clamped at 0); the roots are not stored. */
void rs_radius_set_rho(rs_radius_t r, acb_srcptr roots, slong n, slong prec);
/* 1 when Schur's recursion on the real balls c[0..n] (c[n] the leading
 * coefficient) certifies every root of sum c_j lambda^j strictly inside the
 * unit circle, for every polynomial inside the balls (a repeated root inside
 * does not stop it); 0 when it cannot (a root on or outside the circle, or
 * balls too wide at prec). */
int rs_radius_balls_inside(arb_srcptr c, slong n, slong prec);

/* Uncertified approximations of the d roots of a[0] + ... + a[d] x^d
 * (double coefficients, a[0] != 0 != a[d]) into z (2d doubles: re, im):
 * Aberth-Ehrlich iterations in double (Gauss-Seidel updates) from Bini's
 * Newton-polygon starting points, at most maxiter sweeps; a root stops when
 * |p(z)| is within the rounding error of its evaluation.  Returns the sweeps
 * used, or -1 when some root did not get there (z is filled anyway).
 * src/numeric/aberth.c; the certified routes only use z as seeds. */
int rs_radius_aberth_d(double *z, const double *a, slong d, slong maxiter);

/* Certified isolating balls E of the d roots of f (squarefree, integer,
 * deg >= 2) from approximations z0 (2d doubles) and a (f in double, as for
 * rs_radius_aberth_d): Aberth-Ehrlich steps on Arb midpoints at a
 * precision per root (carried to the bits wanted plus that root's measured
 * evaluation loss, so that only ill-conditioned roots -- clusters -- pay
 * high precision), then one inclusion disc per root (d |p/p'| at the
 * midpoint), all pairwise disjoint.  Every root to prec bits; with
 * 0 < coarse < prec, all to coarse bits first and then only those whose
 * ball may hold the largest modulus to prec (*nouter = their number, else
 * -1).  *wp = the highest precision used.  Returns 1, or 0 (E undefined)
 * when the iteration does not settle or the discs overlap: the caller
 * falls back.  src/numeric/aberth.c. */
/* y = p(x), dy = p'(x) for exact coefficients a[0..len) and exact x, by
 * Horner at precision w with the rounding errors bounded as disc radii
 * (Arb's rectangular balls grow by up to sqrt 2 per Horner step: about
 * len/2 bits lost).  src/numeric/aberth.c. */
void rs_radius_horner2(acb_t y, acb_t dy, acb_srcptr a, slong len, const acb_t x, slong w);

/* Better seeds z (2d doubles, in place) for f (deg d >= 2, a = f in double
 * as above) when the double ones are poor (their estimated evaluation loss
 * above 24 bits: Wilkinson-type): Aberth in double on the secular equation
 * sum a_j / (x - b_j) = 1 with nodes b = the current approximations, whose
 * a_j take p(b_j) in Arb to 56 correct bits, renoded at most rounds times
 * (MPSolve's secsolve).  Uncertified.  Returns the rounds used (rounds + 1:
 * not settled to double, z still the last nodes), 0 when the seeds were
 * already good (z unchanged), -1 on failure (z unchanged).
 * src/numeric/aberth.c. */
int rs_radius_aberth_secular(double *z, const fmpz_poly_t f, const double *a, slong rounds);

int rs_radius_aberth_certify(acb_ptr E, slong *wp, slong *nouter, const fmpz_poly_t f,
                             const double *a, const double *z0, slong prec, slong coarse);

/* arb_fmpz_poly_complex_roots (f squarefree, same root order) solved on
 * f(2^s mu) when the roots' magnitudes are far from 1 (2^s their geometric
 * mean, |s| >= 32), which keeps extreme coefficients from taking hours. */
void rs_radius_complex_roots(acb_ptr roots, const fmpz_poly_t f, slong prec);

/* Printing certified numbers.  Every function returns a decimal string
 * (malloc'd; free with flint_free) of at most n >= 1 significant digits
 * ("0", "inf", "-inf", "nan" for those values), fixed notation or d.ddde+X;
 * trailing zeros are dropped only when the decimal is exact.  The decimal
 * conversion itself is directed (mpfr_get_str), so a printed bound holds.
 *
 * rs_radius_str_lower: a decimal <= every point of x (lower bound rounded
 *   down); rs_radius_str_upper: >= every point (upper bound rounded up).
 * rs_radius_arf_str: x itself rounded in direction rnd (ARF_RND_FLOOR,
 *   CEIL, DOWN = toward 0, UP = away from 0, NEAR).
 * rs_radius_arb_str: the point estimate with only certified digits: the
 *   longest k <= n such that every point of x rounds (to nearest) to the
 *   same k-digit decimal, which is printed; so |true - printed| <= half a
 *   unit of its last digit.  (arb_get_str with ARB_STR_NO_RADIUS only
 *   promises the midpoint to +-1 unit of the last digit, which can put
 *   the true value outside.)  A ball around 0 prints as "0eX": every point
 *   is within 10^X / 2 of 0.  When not even one digit is certain otherwise
 *   (x wider than its magnitude), Arb's "[m +/- r]" (arb_get_str), whose
 *   ball contains x.
 * rs_radius_interval_str: the same for the interval [lo, hi].
 * rs_radius_str_ball: the midpoint rounded to n digits, and in rad the
 *   radius of x plus a bound on that rounding: printed +- rad contains x. */
char *rs_radius_str_lower(const arb_t x, slong n);
char *rs_radius_str_upper(const arb_t x, slong n);
char *rs_radius_arf_str(const arf_t x, slong n, arf_rnd_t rnd);
char *rs_radius_arb_str(const arb_t x, slong n);
char *rs_radius_interval_str(const arf_t lo, const arf_t hi, slong n);
char *rs_radius_str_ball(mag_t rad, const arb_t x, slong n);

/* Count of the roots inside / outside the unit circle read off r's balls
 * (src/numeric/outer.c): returns 1 and sets *inside, *outside (nothing on
 * the circle) when r holds `degree` isolating balls (isolated = 1) each
 * strictly inside or strictly outside |lambda| = 1; else 0 (untouched):
 * some ball meets the circle, and an exact count must decide. */
int rs_radius_count_balls(slong *inside, slong *outside, const rs_radius_t r, slong degree);

/* The number of roots of p inside the unit circle by the Schur-Cohn table
 * f_{k+1} = f_k(0) f_k - lc(f_k) f_k* in ball arithmetic (src/numeric/
 * outer.c): independent of any root ball, rigorous (each row's constant
 * sign certified; all non-zero means no root on the circle, so inside +
 * outside = deg p).  The precision starts at 128 bits and is raised from
 * where the signs were lost, up to max_prec.  RS_OK with *decided = 1,
 * *inside and *prec_used (bits), or *decided = 0 (a sign not certified
 * within max_prec, or the table is singular: an exact count must decide);
 * RS_ERR_LIMIT when the budget ran out (err says so). */
int rs_radius_schur_count(int *decided, slong *inside, slong *prec_used, const fmpz_poly_t p,
                          slong max_prec, rs_error_t err);

/* E: the deg f certified isolating balls of the roots of f (squarefree),
 * from a low precision.  Refines those that may be of largest modulus to
 * prec bits (Newton on midpoints), then certifies all deg f balls once at
 * prec (_acb_poly_validate_roots).  Returns 1 with E replaced and *nouter
 * = the number refined when every ball is isolating and the coarse ones
 * still lie below the refined ones; else 0, E unchanged (also when more
 * than a quarter of the roots are candidates: nothing to save). */
int rs_radius_outer_refine(acb_ptr E, slong *nouter, const fmpz_poly_t f, slong prec);

/* The balls of r (isolating, of the squarefree p: every mult 1, nroots =
 * deg p) that meet the unit circle are refined -- Newton on the midpoint,
 * a new inclusion disc d |p/p'| at doubling precision up to max_prec, kept
 * only when inside the old ball (so it holds the same root) -- until they
 * lie off the circle.  rho, lower, upper are not touched.  Returns 1 when
 * afterwards no ball meets the circle (rs_radius_count_balls then
 * counts), else 0.  A root ON the circle never separates: the exact count
 * decides then.  src/numeric/outer.c. */
int rs_radius_refine_circle(rs_radius_t r, const fmpz_poly_t p, slong max_prec);

/* "stable" (upper < 1), "unstable" (lower > 1) or "undecided". */
const char *rs_radius_verdict(const rs_radius_t rr);

#ifdef __cplusplus
}
#endif
#endif
