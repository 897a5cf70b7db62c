/* an_qd_forall2.c -- issue 15: the status of a model over Q(sqrt d) at a
 * point with up to three irrational coordinates (region NAME for all with
 * several quantified parameters, an_qd_forall.c), where the exact route
 * over a primitive element of Q(t0, sqrt d, q0, ...) is out of reach.
 *
 * The jury conditions c0 + sqrt(d) c1 > 0 (!= 0) of the default variant
 * (every parameter symbolic: all |lambda| < 1 iff they hold where p's
 * leading coefficient does not vanish) and that leading coefficient are
 * evaluated in certified ball arithmetic at the point, the algebraic
 * coordinates refined up to 4096 bits: every condition's ball on its good
 * side -> stable; the leading coefficient away from 0 and every condition's
 * ball away from 0 with one on its bad side -> unstable (no delta_k = 0
 * leaves no root on the circle, as an_qd_conds.c's cells argue).  A ball
 * that keeps 0 (a condition that really vanishes there: the point lies on a
 * true boundary) leaves the point undecided.  This decides the spurious cut
 * points the norms bring (a root of the conjugate c0 - sqrt(d) c1 only, where
 * c0 + sqrt(d) c1 itself stays away from 0). */
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz_mpoly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"

struct rs_qd_signs_s {
    const rs_scheme_struct *s;
    fmpz_mpoly_struct *c0, *c1;
    int *ne;
    slong n;
    fmpz_mpoly_t lead;
};

int rs_qd_signs_init(rs_qd_signs_t **out, rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    rs_qd_signs_t *g;
    int r = rs_run_default_variant(run, &v);
    *out = NULL;
    if (r != RS_OK) return r;
    g = flint_calloc(1, sizeof(rs_qd_signs_t));
    g->s = v->s;
    r = rs_an_qd_jury_conds(&g->c0, &g->c1, &g->ne, &g->n, run, req, v, 0);
    fmpz_mpoly_init(g->lead, g->s->zctx);
    rs_charpoly_coeff(g->lead, v->cp->p, fmpz_mpoly_degree_si(v->cp->p, g->s->lambda_var, g->s->zctx),
                      g->s->lambda_var, g->s->zctx);
    *out = g;
    return r;
}

void rs_qd_signs_clear(rs_qd_signs_t *g)
{
    slong k;
    if (g == NULL) return;
    for (k = 0; k < g->n; k++) {
        fmpz_mpoly_clear(g->c0 + k, g->s->zctx);
        fmpz_mpoly_clear(g->c1 + k, g->s->zctx);
    }
    flint_free(g->c0);
    flint_free(g->c1);
    flint_free(g->ne);
    fmpz_mpoly_clear(g->lead, g->s->zctx);
    flint_free(g);
}

/* f at the point x[0..nvars) (balls), term by term */
static void signs_eval(arb_t res, const fmpz_mpoly_t f, arb_srcptr x, const fmpz_mpoly_ctx_t ctx, slong prec)
{
    slong nv = ctx->minfo->nvars, i, j, len = fmpz_mpoly_length(f, ctx);
    ulong *e = flint_malloc((size_t) nv * sizeof(ulong));
    arb_t t, u;
    arb_init(t); arb_init(u);
    arb_zero(res);
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_exp_ui(e, f, i, ctx);
        arb_set_round_fmpz(t, f->coeffs + i, prec);
        for (j = 0; j < nv; j++) {
            if (e[j] == 0) continue;
            arb_pow_ui(u, x + j, e[j], prec);
            arb_mul(t, t, u, prec);
        }
        arb_add(res, res, t, prec);
    }
    arb_clear(t); arb_clear(u);
    flint_free(e);
}

int rs_qd_signs_status(rs_status_t *st, rs_qd_signs_t *g, rs_run_t *run, const rs_assign_t *ex, slong nex,
                       const slong *av, rs_alg_t *const *a, slong na)
{
    const rs_scheme_struct *s;
    slong nv, k, prec;
    arb_ptr x;
    arb_t c, w;
    int decided = 0;
    if (g == NULL || g->n == 0) return 0;
    s = g->s;
    nv = s->zctx->minfo->nvars;
    x = _arb_vec_init(nv);
    arb_init(c); arb_init(w);
    for (prec = 128; prec <= 4096 && !decided; prec *= 4) {
        int ok = 1, zero = 0;
        for (k = 0; k < run->c->nsets; k++) {
            slong j = rs_case_param_index(run->c, run->c->sets[k].name);
            if (j >= 0 && j < nv) arb_set_fmpq(x + j, run->c->sets[k].value, prec);
        }
        for (k = 0; k < nex; k++) arb_set_fmpq(x + ex[k].var, ex[k].value, prec);
        for (k = 0; k < na; k++) {
            rs_alg_refine(a[k], prec + 32);
            arb_set(x + av[k], a[k]->x);
        }
        arb_sqrt_ui(x + s->sqrt_var, (ulong) s->sqrt_d, prec);
        signs_eval(c, g->lead, x, s->zctx, prec);
        if (arb_contains_zero(c)) continue;
        for (k = 0; k < g->n; k++) {
            signs_eval(c, g->c1 + k, x, s->zctx, prec);
            arb_mul(c, c, x + s->sqrt_var, prec);
            signs_eval(w, g->c0 + k, x, s->zctx, prec);
            arb_add(c, c, w, prec);
            if (arb_contains_zero(c)) { zero = 1; ok = 0; }
            else if (!g->ne[k] && !arb_is_positive(c)) ok = 0;
        }
        if (ok) { *st = RS_STATUS_STABLE; decided = 1; }
        else if (!zero) { *st = RS_STATUS_UNSTABLE; decided = 1; }
    }
    _arb_vec_clear(x, nv);
    arb_clear(c); arb_clear(w);
    return decided;
}
