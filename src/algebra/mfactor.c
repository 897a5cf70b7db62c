/* mfactor.c -- rs_mpoly_factor, rs_fmpz_poly_squarefree_part: see mfactor.h. */
#include <flint/flint.h>
#include <flint/fmpz.h>
#include "algebra/mfactor.h"

int rs_mpoly_factor(fmpz_mpoly_factor_t f, const fmpz_mpoly_t A, const fmpz_mpoly_ctx_t ctx)
{
    slong nv = ctx->minfo->nvars, k = 0, i;
    slong *deg, *to, *from;
    fmpz_mpoly_ctx_t c2;
    fmpz_mpoly_t B;
    fmpz_mpoly_factor_t g;
    int ok;
    if (nv <= 1 || fmpz_mpoly_length(A, ctx) <= 1 || !fmpz_mpoly_degrees_fit_si(A, ctx))
        return fmpz_mpoly_factor(f, A, ctx);
    deg = flint_malloc(3 * nv * sizeof(slong));
    to = deg + nv;
    from = deg + 2 * nv;
    fmpz_mpoly_degrees_si(deg, A, ctx);
    for (i = 0; i < nv; i++) {
        to[i] = deg[i] > 0 ? k : -1;      /* A's variable i -> B's */
        if (deg[i] > 0) from[k++] = i;    /* and back */
    }
    if (k == nv || k == 0) {
        flint_free(deg);
        return fmpz_mpoly_factor(f, A, ctx);
    }
    fmpz_mpoly_ctx_init(c2, k, ctx->minfo->ord);
    fmpz_mpoly_init(B, c2);
    fmpz_mpoly_factor_init(g, c2);
    fmpz_mpoly_compose_fmpz_mpoly_gen(B, A, to, ctx, c2);
    ok = fmpz_mpoly_factor(g, B, c2);
    if (ok) {
        fmpz_mpoly_factor_fit_length(f, g->num, ctx);
        fmpz_set(f->constant, g->constant);
        fmpz_set(f->constant_den, g->constant_den);
        for (i = 0; i < g->num; i++) {
            fmpz_mpoly_compose_fmpz_mpoly_gen(f->poly + i, g->poly + i, from, c2, ctx);
            fmpz_set(f->exp + i, g->exp + i);
        }
        f->num = g->num;
    }
    fmpz_mpoly_factor_clear(g, c2);
    fmpz_mpoly_clear(B, c2);
    fmpz_mpoly_ctx_clear(c2);
    flint_free(deg);
    return ok;
}

void rs_fmpz_poly_squarefree_part(fmpz_poly_t r, const fmpz_poly_t f)
{
    fmpz_poly_t d;
    if (fmpz_poly_degree(f) < 1) {
        if (fmpz_poly_is_zero(f)) fmpz_poly_zero(r);
        else fmpz_poly_one(r);
        return;
    }
    fmpz_poly_init(d);
    fmpz_poly_derivative(d, f);
    fmpz_poly_gcd(d, f, d);
    fmpz_poly_div(r, f, d);          /* exact: d divides f */
    fmpz_poly_primitive_part(r, r);  /* and the leading coefficient > 0 */
    fmpz_poly_clear(d);
}
