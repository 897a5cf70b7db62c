/* hurwitz_interp.h -- private: the Hurwitz minors by evaluation and
 * interpolation over a known support (issue 17).  See hurwitz_interp.c. */
#ifndef RS_STABILITY_HURWITZ_INTERP_H
#define RS_STABILITY_HURWITZ_INTERP_H

#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"

enum {
    RS_HURWITZ_INTERP_OK = 0,
    RS_HURWITZ_INTERP_NA,       /* no weights, or a support over max_terms */
    RS_HURWITZ_INTERP_BUDGET,   /* the budget ran out (err says which) */
    RS_HURWITZ_INTERP_CHECK     /* the final check disagreed (a bug) */
};

/* D[0..mmax-1] = the leading principal minors D_1..D_mmax of the Hurwitz
 * matrix of A_0 + A_1 z + ... + A_n z^n over ctx, exactly, when the A_i are
 * weighted-homogeneous (every variable of positive weight, A_i of weight
 * alpha - beta i) and every minor's candidate support has at most max_terms
 * monomials.  Variable 0 is the one set to 1 during the interpolation. */
int rs_hurwitz_interp_minors(fmpz_mpoly_struct *D, slong mmax,
                             const fmpz_mpoly_struct *A, slong n,
                             slong max_terms, rs_error_t err,
                             const fmpz_mpoly_ctx_t ctx);

#endif
