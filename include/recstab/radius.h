/* radius.h -- certified spectral radius from companion-matrix eigenvalues.
 *
 * Exact-coefficient input is first made squarefree (FLINT), so every root of
 * each factor is simple and acb_mat_eig_simple can certify it; precision is
 * doubled from a cheap start until the radius interval is narrower than
 * 10^-digits relatively, up to a ceiling (RS_RADIUS_MAX_PREC_DEFAULT bits). */
#ifndef RECSTAB_RADIUS_H
#define RECSTAB_RADIUS_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include <arb.h>
#include <acb.h>
#include <acb_poly.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_RADIUS_MAX_PREC_DEFAULT 65536

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
} rs_radius_struct;
typedef rs_radius_struct rs_radius_t[1];

void rs_radius_init(rs_radius_t r);
void rs_radius_clear(rs_radius_t r);

/* Certified spectral radius of the roots of p (deg p >= 1) to `digits`
 * relative digits, precision never above max_prec bits (RS_ERR_LIMIT with a
 * message naming the limit otherwise). */
int rs_radius_fmpz_poly(rs_radius_t r, const fmpz_poly_t p, slong digits,
                        slong max_prec, rs_error_t err);

/* Same for a polynomial with ball coefficients (from non-polynomial schemes,
 * e.g. matrix exponentials): certification needs simple roots; returns
 * RS_ERR_UNDECIDED if they cannot be isolated at max_prec. */
int rs_radius_acb_poly(rs_radius_t r, const acb_poly_t p, slong digits,
                       slong max_prec, rs_error_t err);

/* Uncertified double-precision baseline (GSL gsl_poly_complex_solve on the
 * coefficients rounded to double); fills rho_double and roots as exact
 * doubles (radius 0) and sets method_double. */
int rs_radius_double(rs_radius_t r, const fmpz_poly_t p, rs_error_t err);

/* Decimal string of an arb to n digits (malloc'd, caller frees with flint_free). */
char *rs_radius_arb_str(const arb_t x, slong n);

#ifdef __cplusplus
}
#endif
#endif
