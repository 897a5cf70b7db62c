/* lower/cosim_model.h -- the co-simulation model (model kind RS_MODEL_COSIM;
 * design.md: A_i, B_i, C as linear forms in the parameters, built once per
 * run by rs_model_lower): every state equation, macro step and coupling
 * force evaluated once as num/den polynomials in an evaluation case whose
 * variables are the parameters, the states and the forces.  At a point only
 * numbers are substituted (rs_cosim_model_form_at); the numeric
 * co-simulation (cosim.h) is filled above this stage (analysis_cosim.c). */
#ifndef RECSTAB_LOWER_COSIM_MODEL_H
#define RECSTAB_LOWER_COSIM_MODEL_H

#include <flint/fmpq_mpoly.h>
#include "recstab/model.h"
#include "recstab/scheme.h"

struct rs_cosim_model_struct {
    rs_case_t tc;              /* the evaluation case */
    rs_model_t tm;             /* ... lowered */
    rs_scheme_t ts;            /* its context: the parameters, the states, the forces, lambda */
    slong nstate[2], n, nf;
    slong nforms;              /* n state rows, 2 macro steps, nf forces */
    fmpq_mpoly_struct *num, *den;
    int *second;               /* per state row: X'' = F's X (its derivative is the next state) */
    const rs_loc_t **loc;      /* where each form comes from (in the case) */
};

/* values substituted for parameters (the set values, or a map point's) */
typedef struct { const char *name; const fmpq *value; } rs_cosim_val_t;
typedef struct { slong n; rs_cosim_val_t *v; } rs_cosim_vals_t;

/* The forms of the case c (two subsystems integrated exactly); c must
 * outlive F.  Errors at the user's file:line:col. */
int rs_cosim_model_init(rs_cosim_model_struct *F, const rs_case_struct *c, rs_error_t err);
void rs_cosim_model_clear(rs_cosim_model_struct *F);

/* index of the form of subsystem a's macro step, of coupling force f */
static inline slong rs_cosim_model_step(const rs_cosim_model_struct *F, slong a) { return F->n + a; }
static inline slong rs_cosim_model_force(const rs_cosim_model_struct *F, slong f) { return F->n + 2 + f; }

/* out = form i at vals (num/den, every parameter substituted; error at the
 * form's place when a parameter stays symbolic or den vanishes).  Reads F
 * only: safe from several threads. */
int rs_cosim_model_form_at(fmpq_mpoly_t out, const rs_cosim_model_struct *F, slong i, const rs_case_struct *c,
                           const rs_cosim_vals_t *vals, rs_error_t err);

/* vals = the case's set values overridden by (names, values)[0 .. n)
 * (pointers into c, names and values; free vals->v with flint_free) */
void rs_cosim_vals_make(rs_cosim_vals_t *vals, const rs_case_struct *c, const char *const *names, const fmpq *values,
                        slong n);

#endif
