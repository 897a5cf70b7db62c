/* builder.h -- scheme builders: subsystems with first-order (or
 * second-order) state equations, an integrator per subsystem and a coupling
 * procedure, expanded into ordinary unknowns and difference equations.
 *
 *     subsystem S1 state y1 v1          # a block: the lines NAME' = EXPR follow
 *       y1' = v1
 *       v1' = (-k1*y1 + kc*(y2 - y1))/m1
 *     integrate S1 euler-forward h      # euler-forward, euler-backward,
 *                                       # trapezoidal, theta T, bdf2, bdf3,
 *                                       # central-difference, newmark B G, exact,
 *                                       # rk TABLEAU, adams-bashforth K, adams-moulton K,
 *                                       # bdf K, leapfrog, hht A, generalized-alpha R, wbz A
 *     couple jacobi | couple gauss-seidel S1 S2 | couple monolithic
 *     iterations K                      # re-integrate with the previous iterate's inputs
 *     extrapolate order K               # inputs at t+h from the last K+1 macro values
 *     coupling force lc = EXPR          # applied-force coupling (exact integration; several allowed;
 *                                       # other subsystems' states may also be inputs: FD, DD)
 *     couple explicit order K | couple implicit order K
 *
 * Following Olivier et al. (2019), each subsystem state holds x and its
 * derivative: the equations of motion are imposed at the new time with the
 * partner's state at the old or the new time as the coupling order says,
 * and the integration formula links x and x' at the old and new times.
 * Names of other subsystems' states in an equation are its coupling inputs;
 * `let` sequences are evaluated at the time of the equation. */
#ifndef RECSTAB_BUILDER_H
#define RECSTAB_BUILDER_H

#include "recstab/error.h"
#include "recstab/casefile.h"
#include "recstab/model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Lowers the subsystems/integrators/couplings of the case m->c into
 * unknowns and equations appended to m, built as expression trees.  A
 * generated name the user declared is an error at the user's declaration.
 * No-op when the case has no subsystem; with exact integration it only
 * checks the statements and makes m a co-simulation model. */
int rs_builder_lower(rs_model_struct *m, rs_error_t err);

/* The case uses exact (analytic) integration: only numeric analyses apply. */
int rs_builder_is_exact(const rs_case_t c);

#ifdef __cplusplus
}
#endif
#endif
