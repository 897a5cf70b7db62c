/* qd.c -- numbers x + y sqrt(d) of Q(sqrt d) (see qd.h). */
#include <stdio.h>
#include <string.h>
#include "util/qd.h"

void rs_qd_init(rs_qd_struct *a) { fmpq_init(a->x); fmpq_init(a->y); }
void rs_qd_clear(rs_qd_struct *a) { fmpq_clear(a->x); fmpq_clear(a->y); }
void rs_qd_set(rs_qd_struct *r, const rs_qd_struct *a) { fmpq_set(r->x, a->x); fmpq_set(r->y, a->y); }
void rs_qd_set_fmpq(rs_qd_struct *r, const fmpq_t x, const fmpq_t y) { fmpq_set(r->x, x); fmpq_set(r->y, y); }
int rs_qd_is_zero(const rs_qd_struct *a) { return fmpq_is_zero(a->x) && fmpq_is_zero(a->y); }

void rs_qd_add(rs_qd_struct *r, const rs_qd_struct *a, const rs_qd_struct *b)
{
    fmpq_add(r->x, a->x, b->x);
    fmpq_add(r->y, a->y, b->y);
}

void rs_qd_sub(rs_qd_struct *r, const rs_qd_struct *a, const rs_qd_struct *b)
{
    fmpq_sub(r->x, a->x, b->x);
    fmpq_sub(r->y, a->y, b->y);
}

void rs_qd_mul(rs_qd_struct *r, const rs_qd_struct *a, const rs_qd_struct *b, slong d)
{
    fmpq_t x, y, t;
    fmpq_init(x); fmpq_init(y); fmpq_init(t);
    fmpq_mul(x, a->x, b->x);
    fmpq_mul(t, a->y, b->y);
    fmpq_mul_si(t, t, d);
    fmpq_add(x, x, t);
    fmpq_mul(y, a->x, b->y);
    fmpq_addmul(y, a->y, b->x);
    fmpq_swap(r->x, x);
    fmpq_swap(r->y, y);
    fmpq_clear(x); fmpq_clear(y); fmpq_clear(t);
}

/* (x - y sqrt d)/(x^2 - d y^2): the norm is nonzero for a != 0 (d not a square) */
void rs_qd_inv(rs_qd_struct *r, const rs_qd_struct *a, slong d)
{
    fmpq_t n, t;
    fmpq_init(n); fmpq_init(t);
    fmpq_mul(n, a->x, a->x);
    fmpq_mul(t, a->y, a->y);
    fmpq_mul_si(t, t, d);
    fmpq_sub(n, n, t);
    fmpq_div(r->x, a->x, n);
    fmpq_div(r->y, a->y, n);
    fmpq_neg(r->y, r->y);
    fmpq_clear(n); fmpq_clear(t);
}

/* sign(x + y sqrt d): equal signs decide; otherwise the larger of x^2 and
 * d y^2 gives its term's sign (they are never equal: d is not a square) */
int rs_qd_sgn(const rs_qd_struct *a, slong d)
{
    int sx = fmpq_sgn(a->x), sy = fmpq_sgn(a->y), c;
    fmpq_t u, v;
    if (sy == 0) return sx;
    if (sx == 0 || sx == sy) return sy;
    fmpq_init(u); fmpq_init(v);
    fmpq_mul(u, a->x, a->x);
    fmpq_mul(v, a->y, a->y);
    fmpq_mul_si(v, v, d);
    c = fmpq_cmp(u, v);
    fmpq_clear(u); fmpq_clear(v);
    return c > 0 ? sx : sy;
}

char *rs_qd_get_str(const rs_qd_struct *a, slong d)
{
    char *xs = fmpq_get_str(NULL, 10, a->x), *ys, *out;
    size_t n;
    if (fmpq_is_zero(a->y)) return xs;
    ys = fmpq_get_str(NULL, 10, a->y);
    n = strlen(xs) + strlen(ys) + 48;
    out = flint_malloc(n);
    if (fmpq_is_zero(a->x))
        snprintf(out, n, "%s*sqrt(%ld)", ys, (long) d);
    else if (fmpq_sgn(a->y) < 0)
        snprintf(out, n, "%s - %s*sqrt(%ld)", xs, ys + 1, (long) d);
    else
        snprintf(out, n, "%s + %s*sqrt(%ld)", xs, ys, (long) d);
    flint_free(xs);
    flint_free(ys);
    return out;
}


void rs_qd_mpoly_reduce(fmpz_mpoly_t p, slong v, slong d, const fmpz_mpoly_ctx_t ctx)
{
    slong i, n;
    ulong *ex;
    fmpz_t c, dk;
    fmpz_mpoly_t r;
    if (d == 0 || fmpz_mpoly_degree_si(p, v, ctx) < 2) return;
    ex = flint_malloc(ctx->minfo->nvars * sizeof(ulong));
    fmpz_init(c);
    fmpz_init(dk);
    fmpz_mpoly_init(r, ctx);
    n = fmpz_mpoly_length(p, ctx);
    for (i = 0; i < n; i++) {   /* c s^e -> c d^(e/2) s^(e mod 2) */
        fmpz_mpoly_get_term_coeff_fmpz(c, p, i, ctx);
        fmpz_mpoly_get_term_exp_ui(ex, p, i, ctx);
        fmpz_set_si(dk, d);
        fmpz_pow_ui(dk, dk, ex[v] / 2);
        fmpz_mul(c, c, dk);
        ex[v] %= 2;
        fmpz_mpoly_push_term_fmpz_ui(r, c, ex, ctx);
    }
    fmpz_mpoly_sort_terms(r, ctx);
    fmpz_mpoly_combine_like_terms(r, ctx);
    fmpz_mpoly_swap(p, r, ctx);
    fmpz_mpoly_clear(r, ctx);
    fmpz_clear(c);
    fmpz_clear(dk);
    flint_free(ex);
}
