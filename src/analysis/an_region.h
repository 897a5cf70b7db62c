/* an_region.h -- the projection used by `region NAME for all` (and by the
 * cylindrical decomposition of 2-D regions): sets of irreducible integer
 * polynomials in the scheme's variables and one elimination step. */
#ifndef RS_AN_REGION_H
#define RS_AN_REGION_H
#include "analysis/registry.h"

/* a set of irreducible polynomials, each up to sign once */
typedef struct {
    fmpz_mpoly_struct *p;
    slong n, cap;
} rs_plist_t;

void rs_plist_init(rs_plist_t *l);
void rs_plist_clear(rs_plist_t *l, const fmpz_mpoly_ctx_t ctx);
/* the irreducible non-constant factors of f; with dom != NULL (bounds of
 * every variable, dom[tv]'s ends taken open) only the factors that can
 * vanish on the domain */
void rs_plist_add(rs_plist_t *l, const fmpz_mpoly_t f, slong tv, const rs_bound_t *dom, const fmpz_mpoly_ctx_t ctx);
/* out += the projection of in with variable u (interval bu) eliminated:
 * leading coefficients (all coefficients where none has one sign on dom),
 * discriminants, pairwise resultants, values at bu's finite ends; u^g
 * deflated to u when u >= 0 and only powers of u^g occur; factors of one
 * sign on dom dropped.  Budget-checked: returns the budget's error. */
int rs_proj_eliminate(rs_plist_t *out, rs_run_t *run, const rs_plist_t *in, slong u, const rs_bound_t *bu,
                      slong tv, const rs_bound_t *dom, const fmpz_mpoly_ctx_t ctx);
#endif
