/* cond.c -- parameter conditions: bounds and exact evaluation. */
#include <string.h>
#include "recstab/cond.h"

void rs_bounds_init(rs_bound_t *b, slong n)
{
    slong i;
    for (i = 0; i < n; i++) {
        memset(b + i, 0, sizeof(rs_bound_t));
        fmpq_init(b[i].lo);
        fmpq_init(b[i].hi);
    }
}

void rs_bounds_clear(rs_bound_t *b, slong n)
{
    slong i;
    for (i = 0; i < n; i++) {
        fmpq_clear(b[i].lo);
        fmpq_clear(b[i].hi);
    }
}

static rs_cmp_t flip(rs_cmp_t op)
{
    switch (op) {
    case RS_CMP_LT: return RS_CMP_GT;
    case RS_CMP_LE: return RS_CMP_GE;
    case RS_CMP_GT: return RS_CMP_LT;
    case RS_CMP_GE: return RS_CMP_LE;
    default: return op;
    }
}

static void tighten_lo(rs_bound_t *b, const fmpq_t v, int closed)
{
    int c = b->has_lo ? fmpq_cmp(v, b->lo) : 1;
    if (c > 0 || (c == 0 && !closed)) {
        fmpq_set(b->lo, v);
        b->lo_closed = closed;
        b->has_lo = 1;
    }
}

static void tighten_hi(rs_bound_t *b, const fmpq_t v, int closed)
{
    int c = b->has_hi ? fmpq_cmp(v, b->hi) : -1;
    if (c < 0 || (c == 0 && !closed)) {
        fmpq_set(b->hi, v);
        b->hi_closed = closed;
        b->has_hi = 1;
    }
}

/* NAME op value */
static void apply(rs_bound_t *b, rs_cmp_t op, const fmpq_t v)
{
    switch (op) {
    case RS_CMP_GT: tighten_lo(b, v, 0); break;
    case RS_CMP_GE: tighten_lo(b, v, 1); break;
    case RS_CMP_LT: tighten_hi(b, v, 0); break;
    case RS_CMP_LE: tighten_hi(b, v, 1); break;
    case RS_CMP_EQ: tighten_lo(b, v, 1); tighten_hi(b, v, 1); b->fixed = 1; break;
    default: break;
    }
}

int rs_bounds_add(rs_bound_t *b, const rs_cond_t *cond, const rs_case_t c, rs_error_t err)
{
    slong i;
    rs_src_t src;
    rs_error_t scratch;
    (void) err;
    memset(&src, 0, sizeof src);
    src.file = c->path;
    for (i = 0; i + 1 < cond->n; i++) {
        const rs_expr_t *l = cond->e[i], *r = cond->e[i + 1];
        rs_cmp_t op = cond->op[i];
        fmpq_t v;
        fmpq_init(v);
        rs_error_init(scratch);
        if (l->kind == RS_EXPR_NAME && !l->shifted && rs_case_param_index(c, l->name) >= 0
            && rs_expr_eval_const(v, r, &src, scratch) == RS_OK)
            apply(b + rs_case_param_index(c, l->name), op, v);
        else if (r->kind == RS_EXPR_NAME && !r->shifted && rs_case_param_index(c, r->name) >= 0
                 && rs_expr_eval_const(v, l, &src, scratch) == RS_OK)
            apply(b + rs_case_param_index(c, r->name), flip(op), v);
        fmpq_clear(v);
    }
    return RS_OK;
}

int rs_bound_empty(const rs_bound_t *b)
{
    int c;
    if (!b->has_lo || !b->has_hi) return 0;
    c = fmpq_cmp(b->lo, b->hi);
    return c > 0 || (c == 0 && !(b->lo_closed && b->hi_closed));
}

int rs_bound_contains(const rs_bound_t *b, const fmpq_t x)
{
    int cl = !b->has_lo ? 1 : fmpq_cmp(x, b->lo), ch = !b->has_hi ? -1 : fmpq_cmp(x, b->hi);
    return (cl > 0 || (cl == 0 && b->lo_closed)) && (ch < 0 || (ch == 0 && b->hi_closed));
}

void rs_bounds_signs(int *sign, const rs_bound_t *b, slong nparams)
{
    slong i;
    for (i = 0; i < nparams; i++) {
        int s = fmpq_sgn(b[i].lo);
        sign[i] = RS_SIGN_UNKNOWN;
        if (!b[i].has_lo) continue;
        if (s > 0 || (s == 0 && !b[i].lo_closed)) sign[i] = RS_SIGN_POSITIVE;
        else if (s == 0) sign[i] = RS_SIGN_NONNEGATIVE;
    }
}

int rs_condpoly_compile(rs_condpoly_t *cp, const rs_cond_t *cond, const rs_scheme_t s,
                        const rs_case_t c, rs_error_t err)
{
    slong i;
    int r = RS_OK;
    memset(cp, 0, sizeof *cp);
    cp->n = cond->n - 1;
    for (i = 0; i < cp->n; i++) {
        fmpq_mpoly_t ln, ld, rn, rd, t;
        fmpq_mpoly_init(cp->num + i, s->ctx);
        fmpq_mpoly_init(cp->den + i, s->ctx);
        fmpq_mpoly_init(ln, s->ctx); fmpq_mpoly_init(ld, s->ctx);
        fmpq_mpoly_init(rn, s->ctx); fmpq_mpoly_init(rd, s->ctx);
        fmpq_mpoly_init(t, s->ctx);
        if (r == RS_OK) r = rs_scheme_eval_poly(ln, ld, s, c, cond->e[i], 0, err);
        if (r == RS_OK) r = rs_scheme_eval_poly(rn, rd, s, c, cond->e[i + 1], 0, err);
        if (r == RS_OK) {
            /* ln/ld - rn/rd = (ln rd - rn ld) / (ld rd) */
            fmpq_mpoly_mul(cp->num + i, ln, rd, s->ctx);
            fmpq_mpoly_mul(t, rn, ld, s->ctx);
            fmpq_mpoly_sub(cp->num + i, cp->num + i, t, s->ctx);
            fmpq_mpoly_mul(cp->den + i, ld, rd, s->ctx);
        }
        cp->op[i] = cond->op[i];
        fmpq_mpoly_clear(ln, s->ctx); fmpq_mpoly_clear(ld, s->ctx);
        fmpq_mpoly_clear(rn, s->ctx); fmpq_mpoly_clear(rd, s->ctx);
        fmpq_mpoly_clear(t, s->ctx);
    }
    return r;
}

void rs_condpoly_clear(rs_condpoly_t *cp, const rs_scheme_t s)
{
    slong i;
    for (i = 0; i < cp->n; i++) {
        fmpq_mpoly_clear(cp->num + i, s->ctx);
        fmpq_mpoly_clear(cp->den + i, s->ctx);
    }
    cp->n = 0;
}

int rs_condpoly_holds(const rs_condpoly_t *cp, fmpq *const *vals, const rs_scheme_t s)
{
    slong i;
    int ok = 1;
    fmpq_t a, d;
    fmpq_init(a);
    fmpq_init(d);
    for (i = 0; i < cp->n && ok == 1; i++) {
        int sg;
        fmpq_mpoly_evaluate_all_fmpq(a, cp->num + i, (fmpq * const *) vals, s->ctx);
        fmpq_mpoly_evaluate_all_fmpq(d, cp->den + i, (fmpq * const *) vals, s->ctx);
        if (fmpq_is_zero(d)) { ok = -1; break; }
        sg = fmpq_sgn(a) * fmpq_sgn(d);
        switch (cp->op[i]) {
        case RS_CMP_LT: ok = sg < 0; break;
        case RS_CMP_LE: ok = sg <= 0; break;
        case RS_CMP_GT: ok = sg > 0; break;
        case RS_CMP_GE: ok = sg >= 0; break;
        case RS_CMP_NE: ok = sg != 0; break;
        case RS_CMP_EQ: ok = sg == 0; break;
        }
    }
    fmpq_clear(a);
    fmpq_clear(d);
    return ok;
}
