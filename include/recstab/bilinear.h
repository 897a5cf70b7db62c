/* bilinear.h -- the bilinear (Moebius) map lambda = (1+z)/(1-z).
 *
 * q(z) = (1-z)^n p((1+z)/(1-z)), n = deg p.  Roots |lambda| < 1 map to
 * Re z < 0, |lambda| = 1 to Re z = 0, lambda = 1 to z = 0 and lambda = -1 to
 * z = infinity, which shows as a drop of deg q below n. */
#ifndef RECSTAB_BILINEAR_H
#define RECSTAB_BILINEAR_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* q = (1-z)^n p((1+z)/(1-z)) with n = deg p; q may alias p. */
void rs_bilinear_fmpz_poly(fmpz_poly_t q, const fmpz_poly_t p);

/* Same for a multivariate p in which variable `var` is lambda; q uses the
 * same variable index for z.  n is the degree of p in var. */
void rs_bilinear_fmpz_mpoly(fmpz_mpoly_t q, const fmpz_mpoly_t p, slong var,
                            const fmpz_mpoly_ctx_t ctx);

/* degree drop n - deg q (= multiplicity of lambda = -1) and the
 * multiplicity of z = 0 in q (= multiplicity of lambda = 1). */
slong rs_bilinear_degree_drop(const fmpz_poly_t p, const fmpz_poly_t q);
slong rs_bilinear_zero_mult(const fmpz_poly_t q);

#ifdef __cplusplus
}
#endif
#endif
