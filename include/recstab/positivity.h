/* positivity.h -- sufficient tests that a polynomial in the parameters has
 * one strict sign wherever the sign assumptions (`assume` lines) allow.
 * Cheap tests first: every coefficient of one sign (monomials non-negative
 * under the assumptions); then a refutation at 2 n integer points with every
 * variable > 0 (a wrong sign there: no certificate can exist, 0 at once);
 * then Polya's certificate: (s)^m f with all
 * coefficients of one sign, s = x_1 + ... + x_k for a homogeneous f and
 * 1 + x_1 + ... + x_k otherwise, after each variable's exponents are divided
 * by their gcd (c^2 -> C makes the chain minors homogeneous, issue 17).
 * The tests are sufficient, never necessary: 0 means "not proved". */
#ifndef RECSTAB_POSITIVITY_H
#define RECSTAB_POSITIVITY_H

#include <flint/fmpz_mpoly.h>
#include <flint/fmpq.h>
#include "recstab/cond.h"   /* rs_sign_t */

#ifdef __cplusplus
extern "C" {
#endif

/* Largest Polya multiplier exponent m tried, and the largest number of terms
 * of (s)^m f kept before giving up (bounds the cost of the test to about
 * RS_POLYA_MAX_TERMS * nvars * RS_POLYA_MAX_POWER monomial operations). */
#define RS_POLYA_MAX_POWER 40
#define RS_POLYA_MAX_TERMS 60000

/* Coefficient test only: 1 if poly > 0 wherever sign[] allows (every
 * coefficient positive, every monomial >= 0 under sign[]: its variables
 * positive/non-negative, or of unknown sign in an even power; some monomial
 * > 0: all its variables positive), -1 if -poly passes, 0 otherwise (also
 * poly = 0).  sign may be NULL (all unknown). */
int rs_positivity_coeff_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                             const fmpz_mpoly_ctx_t ctx);

/* The coefficient test, then Polya's multiplier (above); *power, if not
 * NULL, receives the m that succeeded (0: the coefficient test; -1: not
 * proved).  Same return convention. */
int rs_positivity_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                       const fmpz_mpoly_ctx_t ctx, slong *power);

/* Interval mapping first (issue 17's cheap sufficient test for bounded
 * parameters): each variable v < nbounds with bounds b[v] other than
 * "v > 0" / "v >= 0" is replaced by a variable t >= 0 (t > 0 for an open
 * end) mapping [0, inf) onto a superset of its admissible interval:
 *     lo <(=) v <  hi:  v = (lo + hi t) / (1 + t)      (onto [lo, hi))
 *     lo <(=) v (<= hi): v = lo + t                    (a closed upper end is
 *                                                     not an image point)
 *     v <(=) hi:        v = hi - t
 * and G = B^d f(A / B) (v = A / B, B > 0, d = deg_v f) goes to
 * rs_positivity_sign with t's sign.  G > 0 for every admissible t implies
 * f > 0 for every admissible v, so the test stays sufficient.  Variables
 * without bounds, or >= nbounds, keep sign[v].  b may be NULL: then this is
 * rs_positivity_sign. */
int rs_positivity_sign_bounds(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                              const rs_bound_t *b, slong nbounds,
                              const fmpz_mpoly_ctx_t ctx, slong *power);

/* The index of the one variable poly has (degree > 0), -1 for none or
 * several. */
slong rs_positivity_single_var(const fmpz_mpoly_t poly, const fmpz_mpoly_ctx_t ctx);

/* Exact one-variable test (issue 13: 16 w^2 - 31 w + 16 > 0 for w >= 0 needs
 * a Polya exponent far past RS_POLYA_MAX_POWER): when poly has exactly one
 * variable x, 1 if poly > 0 on the range sign[x] gives (x > 0, x >= 0, or
 * every real x), -1 if < 0 there, 0 otherwise (a root on the range, or
 * several variables).  The distinct real roots of the squarefree part are
 * counted twice, by a Sturm sequence (FLINT) and by certified isolation
 * (Arb); no root on the connected range means the sign of x -> inf.  A
 * disagreement of the two counts sets *inconsistent (may be NULL) and
 * returns 0. */
int rs_positivity_sign_roots(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                             const fmpz_mpoly_ctx_t ctx, int *inconsistent);

/* Where rs_positivity_sign_roots fails for a root on the range: up to cap
 * rational values of the one variable, on its range, where poly < 0 (one in
 * each gap between real roots, each checked by exact evaluation), for a
 * search of counterexamples.  Returns how many were written to pts. */
slong rs_positivity_negative_points(fmpq *pts, slong cap, const fmpz_mpoly_t poly, const rs_sign_t *sign,
                                    const fmpz_mpoly_ctx_t ctx);

/* Exact emptiness of a set of one-variable conditions: 1 if no x allowed
 * by the bound b (NULL: every real x) makes every poly[i] > 0 (i < n, each
 * a polynomial in the variable x alone), 0 if some x does or if it is not
 * decided (a poly not in x alone, or the real roots not separated by the
 * precision cap).  The real roots of the conditions and the bound's ends
 * are isolated (Arb); each gap between them has one sign per condition, so
 * one rational point in each admissible gap, evaluated exactly, decides. */
int rs_positivity_none_positive(const fmpz_mpoly_struct *const *poly, slong n, slong x,
                                const rs_bound_t *b, const fmpz_mpoly_ctx_t ctx);

#ifdef __cplusplus
}
#endif
#endif
