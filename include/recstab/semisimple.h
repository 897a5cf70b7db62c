/* semisimple.h -- are the unit-circle eigenvalues of a system semisimple?
 *
 * A system of difference equations A(lambda) x = 0 (A the n x n
 * lambda-matrix) stays bounded iff every root lambda0 of det A(lambda) has
 * |lambda0| <= 1 and every root ON the circle is semisimple:
 * dim ker A(lambda0) equals the multiplicity of lambda0 in det A (all its
 * partial multiplicities are 1; a defective root is a Jordan block and grows
 * like n^(m-1)).  A scalar recurrence (a `char` polynomial, or n = 1) has
 * dim ker = 1, so there a repeated circle root is always defective.
 *
 * For an irreducible factor f of det over Q, the rank of A(alpha) is the same
 * at every root alpha of f (the roots are Galois conjugates), so one exact
 * rank computation over the field Q[lambda]/(f) decides every root of f. */
#ifndef RECSTAB_SEMISIMPLE_H
#define RECSTAB_SEMISIMPLE_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"
#include "recstab/scheme.h"
#include "recstab/rootcount.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One irreducible factor of det with roots on the unit circle. */
typedef struct {
    fmpz_poly_t factor;   /* irreducible over Q, primitive */
    slong mult;           /* its exponent in det */
    slong on;             /* number of its (distinct) roots on the circle */
    slong kernel;         /* dim ker A(alpha) at each root alpha (mult when n == 0) */
    int semisimple;       /* kernel == mult */
} rs_circle_factor_struct;

typedef struct {
    slong nfactors;
    rs_circle_factor_struct *f;
    int system;           /* 1: judged with the lambda-matrix; 0: scalar rule */
    int all_semisimple;   /* every circle root semisimple */
} rs_semisimple_struct;

typedef rs_semisimple_struct rs_semisimple_t[1];

void rs_semisimple_init(rs_semisimple_t ss);
void rs_semisimple_clear(rs_semisimple_t ss);

/* Rank over the field Q[lambda]/(f) (f irreducible of degree >= 1) of the
 * n x n matrix A with entries in Q[lambda]. */
slong rs_semisimple_rank_mod(const fmpq_poly_struct *A, slong n, const fmpz_poly_t f);

/* The circle factors of p (non-zero, det A up to a constant and a power of
 * lambda) and, when A != NULL (n x n, n >= 1), whether each is semisimple;
 * A == NULL applies the scalar rule (repeated = defective). */
int rs_semisimple_circle(rs_semisimple_t ss, const fmpq_poly_struct *A, slong n,
                         const fmpz_poly_t p, rs_error_t err);

/* The lambda-matrix of s with every parameter already a number (or set
 * here: vars[i] = vals[i] for i < nv) as univariate polynomials in lambda:
 * A (n*n entries, initialised by the caller).  Returns 0 when a parameter
 * is still symbolic. */
int rs_semisimple_matrix(fmpq_poly_struct *A, const rs_scheme_t s, const slong *vars,
                         const fmpq *vals, slong nv);

/* The verdict at a point from the exact counts rc of p (det A up to a
 * constant and a power of lambda): with no root outside and a repeated
 * circle root, marginal iff every circle root is semisimple.  s is the scheme
 * whose lambda-matrix is judged (vars[i] = vals[i] substituted first); s ==
 * NULL or a `char` scheme: the scalar rule.  ss receives the circle factors
 * when the verdict needs them, or (list != 0) whenever a circle root exists;
 * their circle roots must add up to rc->on (RS_ERR_INCONSISTENT otherwise,
 * as when a kernel falls outside [1, multiplicity]).  Thread-safe. */
int rs_semisimple_verdict(rs_status_t *st, rs_semisimple_t ss, const rs_scheme_struct *s,
                          const slong *vars, const fmpq *vals, slong nv, const fmpz_poly_t p,
                          const rs_rootcount_struct *rc, int list, rs_error_t err);

/* With one parameter tv symbolic in s (every other one substituted): the
 * values of tv where the rank of A modulo the factor f (irreducible in
 * Q[tv, lambda], of positive degree in lambda) may fall below its rank over
 * Q(tv)[lambda]/(f): where some multiplier of a fraction-free elimination
 * modulo f vanishes at a root of f, or lc_lambda(f) vanishes.  Appends
 * univariate polynomials in tv (a superset of such values are their real
 * roots) to *out (flint_realloc'd, *nout entries, each initialised). */
int rs_semisimple_rank_drops(fmpz_poly_struct **out, slong *nout, const rs_scheme_t s, slong tv,
                             const fmpz_mpoly_t f);
/* The same multipliers with every parameter of s symbolic: polynomials in
 * the parameters (in s->zctx; each initialised, appended to *out,
 * flint_realloc'd) whose zero sets hold every point where the rank of A
 * modulo f can fall below its rank over Q(params)[lambda]/(f), i.e. where a
 * repeated root of f can become semisimple (the for-all projection). */
int rs_semisimple_rank_drops_mpoly(fmpz_mpoly_struct **out, slong *nout, const rs_scheme_t s,
                                   const fmpz_mpoly_t f);

/* Over Q(params): every repeated factor f^e of p (det A, the parameters of s
 * symbolic) has dim ker A = e over Q(params)[lambda]/(f).  Then at every
 * parameter value where f's roots stay simple and apart from the other
 * factors' roots (1 <= dim ker <= multiplicity, and the rank only drops at
 * special values) each root of f is semisimple.  *all = 0 for a `char`
 * scheme with a repeated factor. */
int rs_semisimple_generic(int *all, const rs_scheme_t s, const fmpz_mpoly_t p);

#ifdef __cplusplus
}
#endif

#endif
