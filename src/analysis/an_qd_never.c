/* an_qd_never.c -- issue 15: "never stable" over Q(sqrt d).  jury's and
 * hurwitz's conditions there are f = c0 + sqrt(d) c1 > 0 (c0, c1 in
 * Z[params]); over Q and Q(i) rs_run_conds_never proves a set of rational
 * conditions contradictory under the assume lines.  Here f > 0 is split by
 * the signs of its parts, N = c0^2 - d c1^2 its norm:
 *   c0 > 0, c1 > 0            (both parts positive),
 *   c0 > 0, N > 0             (c0 > sqrt(d) |c1|),
 *   c1 > 0, -N > 0            (sqrt(d) c1 > |c0|);
 * each case implies f > 0, and every point with f > 0 off the zero sets of
 * c1 and N (no interior: c1, N nonzero polynomials) is in one of them.  As
 * f > 0 is open, the conditions can all hold on the assume box iff they
 * hold at such a point, so they never all hold iff every choice of one case
 * per condition is contradictory (rs_run_conds_never: exact, no sampling).
 * A part that is zero leaves the other alone (c1 = 0: c0 > 0).  Up to
 * QD_NEVER_MAX_CASES choices; beyond, nothing is claimed. */
#include <string.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"

#define QD_NEVER_MAX_CASES 243

int rs_an_qd_conds_never(char **why, rs_run_t *run, const rs_an_qd_conds_t *q)
{
    const rs_scheme_struct *s = q->s;
    const fmpz_mpoly_ctx_struct *ctx = s->zctx;
    fmpz_mpoly_struct *norm = flint_malloc((size_t) (q->n + 1) * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_struct *cases = flint_malloc((size_t) (3 * q->n + 1) * 2 * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_struct *sel = flint_malloc((size_t) (2 * q->n + 1) * sizeof(fmpz_mpoly_struct));
    slong *ncase = flint_malloc((size_t) (q->n + 1) * sizeof(slong));
    slong i, total = 1, combo, m;
    int never = 0;
    char *first = NULL;
    /* cases[6 i + 2 j + {0, 1}]: case j of condition i, two conditions > 0
     * (the second a zero polynomial when there is one: left out below);
     * shallow copies of q's parts and the norms */
    for (i = 0; i < q->n; i++) {
        fmpz_mpoly_struct *c = cases + 6 * i;
        const fmpz_mpoly_struct *c0 = q->c0 + i, *c1 = q->c1 + i;
        fmpz_mpoly_init(norm + i, ctx);
        ncase[i] = 0;
        if (q->ne[i]) continue;   /* "!= 0": left out (a subset suffices) */
        if (fmpz_mpoly_is_zero(c1, ctx) || fmpz_mpoly_is_zero(c0, ctx)) {
            c[0] = fmpz_mpoly_is_zero(c1, ctx) ? *c0 : *c1;
            c[1] = norm[i];   /* zero */
            ncase[i] = 1;
        } else {
            rs_an_qd_mpoly_norm(norm + i, c0, c1, s);
            c[0] = *c0; c[1] = *c1;
            c[2] = *c0; c[3] = norm[i];
            ncase[i] = 3;
        }
        if (total <= QD_NEVER_MAX_CASES) total *= ncase[i];   /* ncase[i] >= 1 here */
    }
    /* -N for the third case (norm[i] kept for the second) */
    for (i = 0; i < q->n && total <= QD_NEVER_MAX_CASES; i++)
        if (ncase[i] == 3) {
            fmpz_mpoly_struct *c = cases + 6 * i;
            fmpz_mpoly_init(c + 5, ctx);
            fmpz_mpoly_neg(c + 5, norm + i, ctx);
            c[4] = *(q->c1 + i);
        }
    never = total <= QD_NEVER_MAX_CASES;
    for (combo = 0; never && combo < total; combo++) {
        slong rest = combo;
        char *w = NULL;
        m = 0;
        for (i = 0; i < q->n; i++) {
            slong j;
            if (ncase[i] == 0) continue;
            j = rest % ncase[i];
            rest /= ncase[i];
            sel[m++] = cases[6 * i + 2 * j];
            if (!fmpz_mpoly_is_zero(cases + 6 * i + 2 * j + 1, ctx)) sel[m++] = cases[6 * i + 2 * j + 1];
        }
        never = m > 0 && rs_run_conds_never(&w, run, sel, NULL, m, s);
        if (never && combo == 0) { first = w; w = NULL; }
        flint_free(w);
    }
    if (never)
        rs_str_catf(why, "over Q(sqrt %ld) each condition c0 + sqrt(d)*(c1) > 0 needs c0 > 0 and c1 > 0, or "
                 "c0 > 0 and c0^2 - d*c1^2 > 0, or c1 > 0 and d*c1^2 - c0^2 > 0; all %ld such cases are "
                 "contradictory (the first: %s)", (long) s->sqrt_d, (long) total, first ? first : "");
    flint_free(first);
    for (i = 0; i < q->n; i++) {
        if (ncase[i] == 3 && total <= QD_NEVER_MAX_CASES) fmpz_mpoly_clear(cases + 6 * i + 5, ctx);
        fmpz_mpoly_clear(norm + i, ctx);
    }
    flint_free(norm);
    flint_free(cases);
    flint_free(sel);
    flint_free(ncase);
    return never;
}
