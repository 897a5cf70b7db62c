/* mfactor.h -- FLINT's multivariate factorisation in the ring of the
 * variables a polynomial actually has (private to the library). */
#ifndef RECSTAB_MFACTOR_H
#define RECSTAB_MFACTOR_H
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
#include <flint/fmpz_poly.h>

/* fmpz_mpoly_factor(f, A, ctx), computed in a context of only the variables
 * that occur in A (same order, same ordering) and mapped back: the same
 * factors in the same order (FLINT's content step visits every variable of
 * the context, allocating per variable, so a condition in one parameter of
 * a five-variable context pays for five).  Returns FLINT's status. */
int rs_mpoly_factor(fmpz_mpoly_factor_t f, const fmpz_mpoly_t A, const fmpz_mpoly_ctx_t ctx);

/* r = the square-free part of f: f / gcd(f, f') made primitive with a
 * positive leading coefficient, so every distinct root of f once (root
 * isolation and Sturm counts want simple roots); 0 for f = 0, 1 for a
 * non-zero constant.  r may be f. */
void rs_fmpz_poly_squarefree_part(fmpz_poly_t r, const fmpz_poly_t f);

#endif
