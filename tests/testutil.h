/* testutil.h -- shared helpers for the cmocka suites. */
#ifndef RECSTAB_TESTUTIL_H
#define RECSTAB_TESTUTIL_H
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <flint/fmpq.h>
#include <flint/fmpz_mpoly.h>

#ifndef RS_SOURCE_DIR
#define RS_SOURCE_DIR "."
#endif

/* Evaluates an integer multivariate polynomial at a rational point, term by
 * term (an independent check of FLINT-based results). */
static inline void tu_eval_fmpz_mpoly(fmpq_t out, const fmpz_mpoly_t p, fmpq *const *pt,
                                      const fmpz_mpoly_ctx_t ctx)
{
    slong i, v, nv = ctx->minfo->nvars;
    slong *e = flint_malloc(nv * sizeof(slong));
    fmpq_t term, pw;
    fmpq_init(term);
    fmpq_init(pw);
    fmpq_zero(out);
    for (i = 0; i < fmpz_mpoly_length(p, ctx); i++) {
        fmpz_mpoly_get_term_exp_si(e, p, i, ctx);
        fmpq_one(term);
        fmpz_set(fmpq_numref(term), p->coeffs + i);
        for (v = 0; v < nv; v++) {
            fmpq_pow_si(pw, pt[v], e[v]);
            fmpq_mul(term, term, pw);
        }
        fmpq_add(out, out, term);
    }
    fmpq_clear(term);
    fmpq_clear(pw);
    flint_free(e);
}
#endif
