/* numeric/cosim_forms.h -- the co-simulation model of a sweep or map as
 * numeric forms (issue 14 part 3): once per run, the lowered forms
 * (lower/cosim_model.h) with every parameter that is not an axis
 * substituted, each entry of A_i, B_i and C a polynomial in the axis values
 * over a common denominator per equation, its coefficients rounded to
 * interval doubles; at a point only those polynomials are evaluated in
 * interval double (no fmpq_mpoly), giving the model of cosim_dbl.h.  The
 * coupling variables are the run's generic ones (a partner state whose
 * coefficient is not the zero polynomial, then every force): where one
 * vanishes at a point its entries are intervals containing 0, the same
 * recurrence (rs_cosim_dbl_radius's spectrum differs from the point's own
 * realisation only by zero eigenvalues).  Private (not installed). */
#ifndef RECSTAB_NUMERIC_COSIM_FORMS_H
#define RECSTAB_NUMERIC_COSIM_FORMS_H

#include "lower/cosim_model.h"
#include "numeric/cosim_dbl.h"

typedef struct rs_cosim_nforms_struct rs_cosim_nforms_struct;

/* NULL when the run's model is outside the numeric forms (an extension
 * coupling, a parameter other than the axes left symbolic, a form not
 * linear in the states and forces, a macro step depending on the axes or
 * differing between the subsystems, no coupling variable): the caller
 * builds the exact model at every point as before. */
rs_cosim_nforms_struct *rs_cosim_nforms_new(const rs_cosim_model_struct *F, const rs_case_struct *c,
                                            const char *const *axis, slong naxes);
void rs_cosim_nforms_free(rs_cosim_nforms_struct *N);

/* d = the model at the axis values x[0 .. naxes) (d initialised; its
 * storage re-used between calls).  0 when a denominator's interval
 * contains 0 or a value is not finite: the caller takes the exact route. */
int rs_cosim_nforms_at(rs_cosim_dbl_t d, const rs_cosim_nforms_struct *N, const fmpq *x);

/* the axes (bit k: axis k) that subsystem s's rows (A_s, B_s) depend on:
 * along the others rs_cosim_nforms_at gives them the same doubles */
unsigned rs_cosim_nforms_sub_axes(const rs_cosim_nforms_struct *N, int s);

#endif
