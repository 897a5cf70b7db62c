/* lower.h -- private helpers of the lowering stage (src/lower/): the
 * model's unknowns and equations are appended here. */
#ifndef RECSTAB_LOWER_LOWER_H
#define RECSTAB_LOWER_LOWER_H

#include "recstab/model.h"

/* dst = a copy of src (file duplicated). */
void rs_lower_loc_copy(rs_loc_t *dst, const rs_loc_t *src);

/* Appends the unknown name, declared at loc (copied). */
void rs_lower_add_unknown(rs_model_struct *m, const char *name, const rs_loc_t *loc);

/* Appends the equation lhs = rhs (the trees become the model's), at loc;
 * text is its source text, or NULL to print the trees. */
void rs_lower_add_eq(rs_model_struct *m, rs_expr_t *lhs, rs_expr_t *rhs, const rs_loc_t *loc, const char *text);

#endif
