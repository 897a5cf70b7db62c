/* hurwitz_subst.h -- private: the Hurwitz minors over a smaller coefficient
 * ring (issue 17).  See hurwitz_subst.c. */
#ifndef RS_STABILITY_HURWITZ_SUBST_H
#define RS_STABILITY_HURWITZ_SUBST_H

#include <flint/fmpz_mpoly.h>

/* q's coefficients rewritten as a_i = (1/L) A_i(x_v, G_1..G_s), A_i over Z,
 * each G_r a polynomial in the original variables (a basis of the span of
 * the coefficients of the a_i with respect to one variable x_v). */
typedef struct {
    fmpz_mpoly_ctx_t gctx;          /* variables x_v, G_1..G_s */
    fmpz_mpoly_struct *A;           /* A_0..A_n in gctx */
    fmpz_mpoly_struct *img;         /* images of the gctx variables in ctx */
    fmpz_mpoly_struct **gens;       /* pointers to img (for compose) */
    fmpz_t L;                       /* common denominator, > 0 */
    slong n, s, var;
    int active;
    fmpz_mpoly_struct **pw;         /* pw[k][d] = img[k]^d, grown on demand
                                       (rs_hurwitz_subst_compose) */
    slong *npw;                     /* powers held per variable */
} rs_hurwitz_subst_struct;
typedef rs_hurwitz_subst_struct rs_hurwitz_subst_t[1];

void rs_hurwitz_subst_init(rs_hurwitz_subst_t hs);
void rs_hurwitz_subst_clear(rs_hurwitz_subst_t hs, const fmpz_mpoly_ctx_t ctx);

/* Looks for the reduction of a_0..a_n (in ctx) and keeps it (hs->active = 1)
 * when its estimated cost is lower than the direct one, or (force != 0)
 * whenever one exists: the rewrite is checked exactly (composed back and
 * compared). */
void rs_hurwitz_subst_find(rs_hurwitz_subst_t hs, const fmpz_mpoly_struct *a,
                           slong n, int force, const fmpz_mpoly_ctx_t ctx);

/* D = (1/L^m) Dg(x_v, G(x)): a minor D_m of the A_i as a minor of the a_i.
 * Returns 0 if the composition failed (exponent overflow). */
int rs_hurwitz_subst_back(fmpz_mpoly_t D, const fmpz_mpoly_t Dg, slong m,
                          rs_hurwitz_subst_t hs,
                          const fmpz_mpoly_ctx_t ctx);

/* A = B(x_v, G(x)) for B over gctx: Horner's scheme in a fixed variable
 * order with the powers of the images cached in hs (shared by every
 * composition of one route), or FLINT's fmpz_mpoly_compose_fmpz_mpoly when
 * rs_hurwitz_set_compose(0).  Returns 0 if the composition failed (exponent
 * overflow). */
int rs_hurwitz_subst_compose(fmpz_mpoly_t A, const fmpz_mpoly_t B,
                             rs_hurwitz_subst_t hs, const fmpz_mpoly_ctx_t ctx);

#endif
