/* cond.h -- conditions on parameters (`assume` lines, claim conditions):
 * simple bounds per parameter, and exact evaluation at a rational point. */
#ifndef RECSTAB_COND_H
#define RECSTAB_COND_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_mpoly.h>
#include "recstab/error.h"
#include "recstab/casefile.h"
#include "recstab/scheme.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What is known of the sign of each variable (from `assume` lines). */
typedef enum {
    RS_SIGN_UNKNOWN = 0,
    RS_SIGN_POSITIVE = 1,    /* v > 0 */
    RS_SIGN_NONNEGATIVE = 2  /* v >= 0 */
} rs_sign_t;


/* Interval of one parameter implied by the simple conditions NAME op CONST
 * (lower/upper ends; an end is absent when has_lo/has_hi is 0). */
typedef struct {
    int has_lo, has_hi;
    int lo_closed, hi_closed;
    fmpq_t lo, hi;
    int fixed;          /* NAME = CONST */
} rs_bound_t;

/* A condition compiled to polynomials: each comparison of the chain as
 * lhs - rhs (times a positive common denominator) `op` 0. */
typedef struct {
    slong n;                    /* comparisons (1 or 2) */
    fmpq_mpoly_struct num[2];   /* lhs - rhs, numerator */
    fmpq_mpoly_struct den[2];   /* its denominator (params only) */
    rs_cmp_t op[2];
} rs_condpoly_t;

void rs_bounds_init(rs_bound_t *b, slong n);
void rs_bounds_clear(rs_bound_t *b, slong n);

/* Tightens the bounds b[0..nparams-1] with the simple parts of cond. */
int rs_bounds_add(rs_bound_t *b, const rs_cond_t *cond, const rs_case_t c,
                  rs_error_t err);
/* 1 if the interval is empty. */
int rs_bound_empty(const rs_bound_t *b);
/* 1 if x lies in the interval (an end only when it is closed). */
int rs_bound_contains(const rs_bound_t *b, const fmpq_t x);

int rs_condpoly_compile(rs_condpoly_t *cp, const rs_cond_t *cond,
                        const rs_scheme_t s, const rs_case_t c, rs_error_t err);
void rs_condpoly_clear(rs_condpoly_t *cp, const rs_scheme_t s);
/* Exact truth value at a point (vals[v] for every parameter variable v);
 * returns 1 true, 0 false, -1 undefined (a denominator vanishes). */
int rs_condpoly_holds(const rs_condpoly_t *cp, fmpq *const *vals,
                      const rs_scheme_t s);

/* "positive" > "nonnegative" > "unknown" sign of each scheme variable from the
 * bounds (RS_SIGN_* values above). */
void rs_bounds_signs(int *sign, const rs_bound_t *b, slong nparams);

#ifdef __cplusplus
}
#endif
#endif
