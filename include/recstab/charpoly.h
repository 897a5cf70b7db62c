/* charpoly.h -- the exact characteristic polynomial p(lambda; params).
 *
 * p = det of the lambda-matrix, computed fraction-free (Bareiss with exact
 * division and row pivoting) over Z[params, lambda].  The factor lambda^k
 * (roots at 0) and the rational content are split off and reported:
 *     det(M) = content * lambda^k * p,
 * p with coprime integer coefficients and a positive leading coefficient in
 * lambda (sign of its leading term in the lexicographic order). */
#ifndef RECSTAB_CHARPOLY_H
#define RECSTAB_CHARPOLY_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpq_mpoly.h>
#include "recstab/error.h"
#include "recstab/scheme.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_CHARPOLY_MAX_TERMS 2000000  /* terms in any intermediate polynomial */
#define RS_CHARPOLY_MAX_BITS (1L << 26) /* bits of all coefficients of p (about 20 million digits) */

typedef struct {
    fmpz_mpoly_t p;               /* in the scheme's zctx */
    slong degree;                 /* degree in lambda */
    slong removed_lambda_power;   /* k */
    fmpq_t content;
    fmpz_mpoly_t param_content;   /* gcd of the lambda-coefficients (info only) */
} rs_charpoly_struct;
typedef rs_charpoly_struct rs_charpoly_t[1];

void rs_charpoly_init(rs_charpoly_t cp, const rs_scheme_t s);
void rs_charpoly_clear(rs_charpoly_t cp, const rs_scheme_t s);

/* Determinant of the scheme's lambda-matrix (or its `char` polynomial),
 * normalised as above.  RS_ERR_MATH if identically zero. */
int rs_charpoly_compute(rs_charpoly_t cp, const rs_scheme_t s, rs_error_t err);

/* Fraction-free determinant of an n x n matrix over Z[vars] (row pivoting,
 * exact division).  A is destroyed.  RS_ERR_LIMIT past max_terms. */
int rs_charpoly_det(fmpz_mpoly_t det, fmpz_mpoly_struct *A, slong n,
                    slong max_terms, const fmpz_mpoly_ctx_t ctx, rs_error_t err);

/* Normalise q in place: remove lambda^k, divide by the integer content,
 * make the leading coefficient in lambda positive.  Returns k; the factor
 * divided out (with sign) is multiplied into `scale` if non-NULL. */
slong rs_charpoly_normalise(fmpz_mpoly_t q, fmpq_t scale, slong lambda_var,
                            const fmpz_mpoly_ctx_t ctx);

/* Coefficient of lambda^k of p (a polynomial in the parameters). */
void rs_charpoly_coeff(fmpz_mpoly_t c, const fmpz_mpoly_t p, slong k,
                       slong lambda_var, const fmpz_mpoly_ctx_t ctx);

/* If p involves no parameter, its univariate form in lambda; returns 0 when
 * some parameter is still symbolic. */
int rs_charpoly_get_fmpz_poly(fmpz_poly_t out, const fmpz_mpoly_t p,
                              slong lambda_var, const fmpz_mpoly_ctx_t ctx);

/* A row of n rational polynomials as integer ones: out[j] = L * row[j], L
 * the lcm of their denominators (out initialised in ctx->zctx). */
void rs_charpoly_row_to_fmpz(fmpz_mpoly_struct *out, fmpz_t L, const fmpq_mpoly_struct *row, slong n,
                             const fmpq_mpoly_ctx_t ctx);
/* Scales an fmpq_mpoly to a primitive fmpz_mpoly: q = a / scale. */
void rs_charpoly_fmpq_to_fmpz(fmpz_mpoly_t out, fmpq_t scale, const fmpq_mpoly_t q,
                              const fmpq_mpoly_ctx_t ctx);

#ifdef __cplusplus
}
#endif
#endif
