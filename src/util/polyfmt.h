/* polyfmt.h -- polynomials as strings for people and for JSON. */
#ifndef RECSTAB_POLYFMT_H
#define RECSTAB_POLYFMT_H

#include <flint/flint.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpz_poly.h>

#ifdef __cplusplus
extern "C" {
#endif

/* FLINT's pretty string with spaces around top-level + and -, e.g.
 * "2*m^2*muh + 3/2*lambda - 5".  Returned strings are malloc'd: free(). */
char *rs_polyfmt_spaced(const char *flint_str);
char *rs_polyfmt_fmpz_mpoly(const fmpz_mpoly_t p, const char **vars,
                            const fmpz_mpoly_ctx_t ctx);
/* rs_polyfmt_fmpz_mpoly's text followed by tail (NULL: none) in *buf, which
 * is grown with realloc as needed (*cap its size; NULL and 0 at first, then
 * reusable for the next polynomial, free() at the end): the length written
 * (without the NUL), or -1 when memory ran out (*buf stays valid). */
slong rs_polyfmt_fmpz_mpoly_into(char **buf, size_t *cap, const fmpz_mpoly_t p, const char **vars,
                                 const fmpz_mpoly_ctx_t ctx, const char *tail);
char *rs_polyfmt_fmpq_mpoly(const fmpq_mpoly_t p, const char **vars,
                            const fmpq_mpoly_ctx_t ctx);
/* p collected by powers of `var`, highest first:
 * "(2*m + 3)*lambda^4 - 4*lambda^3 + ... " */
char *rs_polyfmt_collected(const fmpz_mpoly_t p, slong var, const char **vars,
                           const fmpz_mpoly_ctx_t ctx);
char *rs_polyfmt_fmpz_poly(const fmpz_poly_t p, const char *var);
/* The coefficients of p by powers of var, as rs_polyfmt_collected prints
 * them: c[e] (initialised by the caller, e = 0..deg_var p) gets the
 * coefficient of var^e (zero where p has none), in one pass over p's terms
 * (terms moved straight into c[e] for single-word exponents, else
 * fmpz_mpoly_to_univar; a coefficient extracted per power reads p once per
 * power: seconds for a dense degree-58 polynomial in 3 parameters). */
void rs_polyfmt_coeffs(fmpz_mpoly_struct *c, const fmpz_mpoly_t p, slong var, const fmpz_mpoly_ctx_t ctx);

#ifdef __cplusplus
}
#endif
#endif
