/* numeric/modes.h -- continuous-time modes of certified roots (private). */
#ifndef RECSTAB_NUMERIC_MODES_H
#define RECSTAB_NUMERIC_MODES_H

#include <arb.h>
#include <acb.h>
#include "recstab/radius.h"

/* Modes of the roots (the modes analysis and sweeps of modes).  principal:
 * for each reference frequency refs[k] (time step h) the root with Im >= 0
 * closest to exp(i refs[k] h) and its conjugate get k + 1, every other root 0
 * (spurious); rr->nroots entries.  continuous: for a nonzero root,
 * ln(root)/h = sigma + i omega (principal logarithm), mag = |ln(root)/h|
 * and the damping ratio zeta = -sigma/mag. */
void rs_modes_principal(int *principal, const rs_radius_t rr, const arb_t h, arb_srcptr refs,
                        slong nref, slong prec);
void rs_modes_continuous(arb_t sigma, arb_t omega, arb_t mag, arb_t zeta, const acb_t root, const arb_t h,
                         slong prec);

#endif
