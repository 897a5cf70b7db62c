/* model.h -- lowering: the syntax tree of a case (casefile.h) becomes the
 * model the analyses work on.  The case is never modified: the unknowns and
 * equations the builders and recurrence terms stand for belong to the model.
 *
 * Three kinds of model:
 *   equations   unknowns and difference equations (or a `char` polynomial);
 *               the builders' integrators/couplings and recurrences with
 *               polynomial entries are lowered into this kind, as trees
 *   recurrence  a matrix recurrence A_K z[n+K] + ... + A_0 z[n] = 0 with
 *               non-polynomial entries (exp, sin, pi, ...): numeric only
 *   cosim       subsystems integrated exactly (co-simulation): numeric only;
 *               its linear forms (A_i, B_i, C in the parameters) are built
 *               once by rs_model_lower, a point substitutes numbers only */
#ifndef RECSTAB_MODEL_H
#define RECSTAB_MODEL_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include "recstab/error.h"
#include "recstab/casefile.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    RS_MODEL_EQUATIONS = 0,
    RS_MODEL_RECURRENCE,
    RS_MODEL_COSIM
} rs_model_kind_t;

/* the linear forms of a co-simulation (private: src/lower/cosim_model.h) */
typedef struct rs_cosim_model_struct rs_cosim_model_struct;

/* Issue 15: a subsystem integrated by a named tableau with irrational
 * entries whose R is not in Q(z) (rk sdirk2, entries in Q(sqrt d)).  Its
 * stage equations are among the model's equations with sqrt(d) written
 * exactly (the scheme reduces by sqrt(d)^2 = d: scheme.h's sqrt_d); qd
 * records d and the tableau's R = (n0 + sqrt(d) n1)/(d0 + sqrt(d) d1)
 * (methods.h), against which the test equation's R read from p is checked
 * (src/analysis/an_qd.c). */
typedef struct {
    slong d;
    fmpq_poly_struct n0[1], n1[1], d0[1], d1[1];
    char *tableau;              /* its name (owned) */
    rs_loc_t loc;               /* the integrate statement's METHOD */
} rs_model_qd_struct;

typedef struct {
    const rs_case_struct *c;    /* the case lowered (not owned; must outlive the model):
                                   params, lets, sets, `char`, path */
    rs_model_kind_t kind;
    /* equations: the user's unknowns, then the generated ones (named at the
     * user's statement they come from); owned copies */
    slong nunknowns;  rs_name_t *unknowns;
    slong nuser_unknowns;       /* unknowns[0 .. nuser_unknowns) are the user's */
    rs_loc_t unknown_loc;       /* the first unknown (the user's or a builder state) */
    /* the user's equations (copies), then the generated ones; every tree
     * node keeps the user's file:line:col */
    slong neqs;       rs_eq_t *eqs;
    slong nuser_eqs;            /* eqs[0 .. nuser_eqs) are the user's */
    /* the named expressions (the case's) */
    slong nlets;      const rs_let_t *lets;
    /* recurrence: the terms A_K z[n+K] (the case's), n x n, K the largest shift */
    slong nterms;     const rs_recterm_t *terms;
    slong n, K;
    /* cosim: the linear forms, or NULL with the error that building them
     * gave (reported by the analyses that need them, rs_model_cosim) */
    rs_cosim_model_struct *cosim;
    rs_error_t cosim_err;
    /* equations: R over Q(sqrt d) (see above), or NULL */
    rs_model_qd_struct *qd;
} rs_model_struct;
typedef rs_model_struct rs_model_t[1];

void rs_model_init(rs_model_t m);
void rs_model_clear(rs_model_t m);

/* Lowers the parsed case c into m (cleared first).  c is not modified and
 * must outlive m.  Errors name the user's file:line:col (a generated name
 * the user also declared: at the user's declaration). */
int rs_model_lower(rs_model_t m, const rs_case_t c, rs_error_t err);

/* The co-simulation forms of a model of kind RS_MODEL_COSIM (built by
 * rs_model_lower), or NULL with the error building them gave in err. */
const rs_cosim_model_struct *rs_model_cosim(const rs_model_t m, rs_error_t err);

/* Index of an unknown of the model by name, or -1. */
slong rs_model_unknown_index(const rs_model_t m, const char *name);

/* The generated unknowns and equations as case text, for the user to read
 * (--emit equations; flint_malloc'd), or NULL when lowering generated none. */
char *rs_model_emit_equations(const rs_model_t m);

#ifdef __cplusplus
}
#endif
#endif
