/* recurrence.h -- matrix recurrences A_K z[n+K] + ... + A_0 z[n] = 0 given
 * directly in a case file:
 *
 *     recurrence 1 = [1, 0; 0, 1]
 *     recurrence 0 = [-exp(-a*h), 0; -h*sin(w), -1/2]
 *
 * With polynomial entries the terms become ordinary equations (every exact
 * analysis applies).  Entries with functions (exp, log, sqrt, sin, cos, tan,
 * atan, sinh, cosh, tanh) or the constant pi are evaluated in Arb at the set
 * values, and only the certified numerics apply (block companion matrix). */
#ifndef RECSTAB_RECURRENCE_H
#define RECSTAB_RECURRENCE_H

#include <arb.h>
#include <acb_mat.h>
#include "recstab/error.h"
#include "recstab/casefile.h"
#include "recstab/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Lowering: checks the terms of the case m->c and, with polynomial entries,
 * appends the equivalent unknowns (z1, ..., zn unless declared) and
 * equations to m, built as trees from the entries; with non-polynomial
 * entries m becomes a recurrence model (its terms, n, K). */
int rs_recurrence_lower(rs_model_struct *m, rs_error_t err);

/* Entries with functions or pi: the numeric path only (no equations). */
int rs_recurrence_is_numeric(const rs_case_t c);

/* The matrices A[0..K] of a recurrence model (K = m->K; acb_mat
 * initialised here, n x n) at precision prec with the case's set values.
 * Returns RS_OK or an error naming an unset parameter. */
int rs_recurrence_matrices(acb_mat_struct **A, slong *K, const rs_model_t m, slong prec, rs_error_t err);

/* Evaluates an expression in ball arithmetic; names are looked up among the
 * case's parameters with set values (pi is the constant). */
int rs_recurrence_eval(arb_t out, const rs_expr_t *e, const rs_case_t c, slong prec, rs_error_t err);

#ifdef __cplusplus
}
#endif
#endif
