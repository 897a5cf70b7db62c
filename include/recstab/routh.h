/* routh.h -- exact Routh arrays of the bilinear polynomial q(z).
 *
 * Numeric coefficients: rows of rationals, every singular case handled
 * exactly (no epsilon evaluated in floating point) and recorded as an event
 * so reports can explain it.  Symbolic coefficients: fraction-free rows of
 * polynomials in the parameters (generic case, valid where the pivots do not
 * vanish). */
#ifndef RECSTAB_ROUTH_H
#define RECSTAB_ROUTH_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpq.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_poly_q.h>
#include "recstab/error.h"
#include "recstab/rootcount.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    RS_ROUTH_EVENT_DEGREE_DROP = 0, /* deg q < deg p: roots at lambda = -1 */
    RS_ROUTH_EVENT_ZERO_AT_ORIGIN,  /* q(0) = 0: roots at lambda = 1 (z^k removed) */
    RS_ROUTH_EVENT_ZERO_PIVOT,      /* zero first-column entry, row not all zero */
    RS_ROUTH_EVENT_ZERO_ROW         /* whole row zero: auxiliary polynomial */
} rs_routh_event_kind_t;

typedef struct {
    rs_routh_event_kind_t kind;
    slong row;        /* index of the row concerned (0 = first row) */
    slong count;      /* degree drop / multiplicity / aux-poly degree */
    char *text;       /* one-sentence explanation for reports (malloc'd) */
} rs_routh_event_struct;

/* Numeric Routh array of q(z). */
typedef struct {
    slong nrows;
    slong *rowlen;          /* entries in each row */
    fmpq **rows;            /* rows[i][0..rowlen[i]-1] */
    slong nevents;
    rs_routh_event_struct *events;
    rs_rootcount_t count;   /* translated back to lambda: inside/on/outside */
    slong sign_changes;     /* roots of q with Re z > 0 (z^k removed): the
                               sign changes of the first column in the
                               regular case, and what an epsilon-completed
                               first column would show in singular ones */
    slong *rowpow;          /* nominal power of z of each row */
    /* After a zero pivot the generalised step skips powers; for display the
     * textbook array is also built exactly in Q(eps), each zero first entry
     * replaced by eps (a zero row by the derivative of the auxiliary
     * polynomial): neps = deg + 1 rows, one per power, else 0. */
    slong neps;
    slong *epslen;
    fmpz_poly_q_struct **eps;
    int *epssign;           /* sign of each first entry as eps -> 0+ */
} rs_routh_struct;

typedef rs_routh_struct rs_routh_t[1];

void rs_routh_init(rs_routh_t r);
void rs_routh_clear(rs_routh_t r);

/* Build the Routh array of q = bilinear(p) and count the roots of p inside,
 * on and outside the unit circle (with multiplicities of circle roots).
 * p is the characteristic polynomial in lambda (not q); p != 0. */
int rs_routh_fmpz_poly(rs_routh_t r, const fmpz_poly_t p, rs_error_t err);

/* The same count for a REGULAR array only, in integer arithmetic: the
 * fraction-free (Bareiss) rows, whose first entries are the Hurwitz minors,
 * with exact divisions and no gcds (src/stability/routh_int.c; degree 500:
 * about a second instead of a minute).  Fills rc (inside/outside) and
 * returns RS_OK; returns RS_ERR_UNDECIDED, rc untouched, when q = bilinear(p)
 * has a degree drop, q(0) = 0, a zero pivot or a zero row -- the caller then
 * runs rs_routh_fmpz_poly, which handles those exactly.  Budget stops are
 * returned as such. */
int rs_routh_int_count(rs_rootcount_t rc, const fmpz_poly_t p, rs_error_t err);

/* Generic fraction-free Routh array of a multivariate q (variable `var` is z).
 * rows[i] has rowlen[i] entries, polynomials in the parameters (z absent).
 * Row i >= 2 is T_i[j] = (T_{i-1}[0] T_{i-2}[j+1] - T_{i-2}[0] T_{i-1}[j+1])
 * divided exactly by the pivot T_{i-3}[0] (i >= 4; no division for i = 2, 3),
 * Bareiss-like, so no nested fractions appear: T_i = Delta_{i-1} r_i with r_i
 * the rational Routh row and Delta_k the Hurwitz minors (T_i[0] = Delta_i).
 * Returns RS_ERR_MATH if a pivot is identically zero (singular for all
 * parameter values; the caller should then specialise). */
typedef struct {
    slong nrows;
    slong *rowlen;
    fmpz_mpoly_struct **rows;
    slong zero_row;   /* row that vanished identically and was replaced by the
                         derivative of the auxiliary polynomial above it (-1: none);
                         rows after it are cross-multiplied without division */
} rs_routh_mpoly_struct;
typedef rs_routh_mpoly_struct rs_routh_mpoly_t[1];

void rs_routh_mpoly_init(rs_routh_mpoly_t r);
void rs_routh_mpoly_clear(rs_routh_mpoly_t r, const fmpz_mpoly_ctx_t ctx);
int rs_routh_mpoly(rs_routh_mpoly_t r, const fmpz_mpoly_t q, slong var,
                   const fmpz_mpoly_ctx_t ctx, rs_error_t err);

#ifdef __cplusplus
}
#endif
#endif
