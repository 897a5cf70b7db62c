/* rootcount.h -- where the roots of a polynomial lie relative to the unit
 * circle, and the three-valued stability verdict built from that.
 *
 * rs_rootcount_t is the common result of every exact counting method
 * (Routh on the bilinear transform, Schur-Cohn on p itself, exact
 * factorisation + certified isolation), so they can be compared field by
 * field.  All counts are with multiplicity. */
#ifndef RECSTAB_ROOTCOUNT_H
#define RECSTAB_ROOTCOUNT_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    RS_STATUS_STABLE = 0,   /* every root |lambda| < 1 */
    RS_STATUS_MARGINAL = 1, /* none outside, every root on the circle simple */
    RS_STATUS_UNSTABLE = 2, /* a root outside, or a defective root on the circle */
    RS_STATUS_SINGULAR = 3  /* the step cannot be solved: the leading coefficient
                               of det A(lambda) vanishes at this point (degree drop) */
} rs_status_t;

#define RS_ROOTCOUNT_MAXMULT 64

typedef struct {
    slong degree;        /* degree of the polynomial counted */
    slong inside;        /* |lambda| < 1 (roots at 0 included) */
    slong on;            /* |lambda| = 1 */
    slong outside;       /* |lambda| > 1 */
    slong at_one;        /* multiplicity of lambda = 1 */
    slong at_minus_one;  /* multiplicity of lambda = -1 */
    /* on_mult[m] = number of DISTINCT unit-circle roots of multiplicity m
     * (m = 1 .. RS_ROOTCOUNT_MAXMULT-1; larger multiplicities go into the
     * last slot). sum over m of m*on_mult[m] == on. */
    slong on_mult[RS_ROOTCOUNT_MAXMULT];
    /* multiplicity of lambda = 0 (counted in inside), set by the analyses
     * for det A = c lambda^k p: the k roots at 0 divided out of p and p's
     * own; the counting methods leave it 0 and rs_rootcount_equal skips it */
    slong at_zero;
} rs_rootcount_struct;

typedef rs_rootcount_struct rs_rootcount_t[1];

void rs_rootcount_init(rs_rootcount_t rc);
void rs_rootcount_clear(rs_rootcount_t rc);
/* 1 if all fields are equal */
int rs_rootcount_equal(const rs_rootcount_t a, const rs_rootcount_t b);
/* largest multiplicity of a unit-circle root, 0 if none */
slong rs_rootcount_max_on_mult(const rs_rootcount_t rc);
rs_status_t rs_rootcount_status(const rs_rootcount_t rc);
const char *rs_status_name(rs_status_t s); /* "stable", "marginal", "unstable" */

/* Exact count by factorisation over Q: squarefree decomposition, then for
 * each irreducible factor: self-reciprocal factors have their unit-circle
 * roots counted exactly (x = lambda + 1/lambda, real roots in [-2, 2] by
 * Sturm sequences) and the rest split evenly; non-self-reciprocal factors
 * have no root on the circle, so certified isolation (Arb) decides each root,
 * raising precision until every ball excludes the circle.
 * p must be non-zero.  Returns RS_OK or an error code. */
int rs_rootcount_factor(rs_rootcount_t rc, const fmpz_poly_t p, rs_error_t err);

/* Helpers shared by the exact counting modules (rootcount, jury). */

/* Record nroots distinct unit-circle roots of multiplicity mult: adds to
 * on and on_mult (not to at_one / at_minus_one). */
void rs_rootcount_add_on(rs_rootcount_struct *rc, slong mult, slong nroots);

/* g palindromic of even degree 2m (g = lambda^(2m) g(1/lambda)):
 * sets F of degree m with g(lambda) = lambda^m F(lambda + 1/lambda). */
void rs_rootcount_reciprocal_to_x(fmpz_poly_t F, const fmpz_poly_t g);

/* Number of distinct real roots of f != 0 in the open interval (a, b), by a
 * Sturm sequence over Q.  Requires f(a) != 0 and f(b) != 0. */
slong rs_rootcount_real_roots_open(const fmpz_poly_t f, slong a, slong b);

#ifdef __cplusplus
}
#endif
#endif
