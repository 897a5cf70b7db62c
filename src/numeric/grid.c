/* grid.c -- the points of sweeps and maps (grid.h): grid values as exact
 * rationals, the rows of a shard, and p evaluated exactly at grid points. */
#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>
#include <arb.h>
#include "numeric/grid.h"

void rs_grid_value(fmpq_t x, const fmpq_t A, const fmpq_t B, slong i, slong K, int logsp)
{
    if (K == 0 || i == 0) { fmpq_set(x, A); return; }
    if (i == K) { fmpq_set(x, B); return; }
    if (!logsp) {
        fmpq_t t;
        fmpz_t k;
        fmpq_init(t);
        fmpz_init_set_si(k, K);
        fmpq_sub(t, B, A);
        fmpq_mul_si(t, t, i);
        fmpq_div_fmpz(t, t, k);
        fmpq_add(x, A, t);
        fmpq_clear(t);
        fmpz_clear(k);
    } else {
        arb_t a, b;
        fmpq_t m, lo, hi, eps;
        slong prec = 128;
        arb_init(a); arb_init(b);
        fmpq_init(m); fmpq_init(lo); fmpq_init(hi); fmpq_init(eps);
        arb_set_fmpq(a, A, prec);
        arb_set_fmpq(b, B, prec);
        arb_div(b, b, a, prec);
        arb_log(b, b, prec);
        arb_mul_si(b, b, i, prec);
        arb_div_si(b, b, K, prec);
        arb_exp(b, b, prec);
        arb_mul(b, b, a, prec);
        arf_get_fmpq(m, arb_midref(b));
        fmpq_set_si(eps, 1, 1);
        fmpz_set_ui(fmpq_denref(eps), 10);
        fmpz_pow_ui(fmpq_denref(eps), fmpq_denref(eps), 13);
        fmpq_mul(eps, eps, m);
        fmpq_sub(lo, m, eps);
        fmpq_add(hi, m, eps);
        fmpq_simplest_between(x, lo, hi);
        arb_clear(a); arb_clear(b);
        fmpq_clear(m); fmpq_clear(lo); fmpq_clear(hi); fmpq_clear(eps);
    }
}

/* K points from A to B (K == 1: A) */
fmpq *rs_grid_axis(const fmpq_t A, const fmpq_t B, slong K)
{
    fmpq *x = _fmpq_vec_init(K);
    slong i;
    for (i = 0; i < K; i++) rs_grid_value(x + i, A, B, i, K - 1, 0);
    return x;
}

void rs_grid_shard_range(slong *lo, slong *hi, slong npoints, slong I, slong N)
{
    if (N < 1) N = 1;
    if (I < 1) I = 1;
    if (I > N) I = N;
    *lo = (I - 1) * (npoints / N) + ((I - 1) * (npoints % N)) / N;
    *hi = I * (npoints / N) + (I * (npoints % N)) / N;
}

void rs_grid_terms_init(rs_grid_terms_t *T, const fmpz_mpoly_t p, slong lv, slong v1, slong v2,
                        const fmpz_mpoly_ctx_t ctx)
{
    slong i, len = fmpz_mpoly_length(p, ctx);
    slong *e = flint_malloc(ctx->minfo->nvars * sizeof(slong));
    T->n = len;
    T->c = _fmpz_vec_init(len > 0 ? len : 1);
    T->el = flint_calloc(len + 1, sizeof(slong));
    T->e1 = flint_calloc(len + 1, sizeof(slong));
    T->e2 = flint_calloc(len + 1, sizeof(slong));
    T->dl = T->d1 = T->d2 = 0;
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_exp_si(e, p, i, ctx);
        fmpz_mpoly_get_term_coeff_fmpz(T->c + i, p, i, ctx);
        T->el[i] = lv >= 0 ? e[lv] : 0;
        T->e1[i] = e[v1];
        T->e2[i] = v2 >= 0 ? e[v2] : 0;
        if (T->el[i] > T->dl) T->dl = T->el[i];
        if (T->e1[i] > T->d1) T->d1 = T->e1[i];
        if (T->e2[i] > T->d2) T->d2 = T->e2[i];
    }
    flint_free(e);
}

void rs_grid_terms_clear(rs_grid_terms_t *T)
{
    _fmpz_vec_clear(T->c, T->n > 0 ? T->n : 1);
    flint_free(T->el);
    flint_free(T->e1);
    flint_free(T->e2);
}

/* U[g*(d+1) + e] = num_g^e den_g^(d-e) */
fmpz *rs_grid_powers(const fmpq *vals, slong nv, slong d)
{
    fmpz *U = _fmpz_vec_init(nv * (d + 1));
    slong g, e;
    fmpz_t t;
    fmpz_init(t);
    for (g = 0; g < nv; g++)
        for (e = 0; e <= d; e++) {
            fmpz_pow_ui(U + g * (d + 1) + e, fmpq_numref(vals + g), (ulong) e);
            fmpz_pow_ui(t, fmpq_denref(vals + g), (ulong) (d - e));
            fmpz_mul(U + g * (d + 1) + e, U + g * (d + 1) + e, t);
        }
    fmpz_clear(t);
    return U;
}

/* den1^d1 den2^d2 p(lambda; x1, x2) */
void rs_grid_terms_eval(fmpz_poly_t P, const rs_grid_terms_t *T, const fmpz *u1, const fmpz *u2)
{
    slong i;
    fmpz_t w;
    fmpz_init(w);
    fmpz_poly_zero(P);
    fmpz_poly_fit_length(P, T->dl + 1);
    _fmpz_vec_zero(P->coeffs, T->dl + 1);
    for (i = 0; i < T->n; i++) {
        if (u2 != NULL) {
            fmpz_mul(w, u1 + T->e1[i], u2 + T->e2[i]);
            fmpz_addmul(P->coeffs + T->el[i], T->c + i, w);
        } else {
            fmpz_addmul(P->coeffs + T->el[i], T->c + i, u1 + T->e1[i]);
        }
    }
    _fmpz_poly_set_length(P, T->dl + 1);
    _fmpz_poly_normalise(P);
    fmpz_clear(w);
}

