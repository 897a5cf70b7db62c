/* numeric/grid.h -- the points of sweeps and maps (private). */
#ifndef RECSTAB_NUMERIC_GRID_H
#define RECSTAB_NUMERIC_GRID_H

#include <flint/fmpq.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_mpoly.h>

/* Grid value i of K+1 points from A to B; log spacing: the simplest rational
 * within 1e-13 relative of A*(B/A)^(i/K) (endpoints exact). */
void rs_grid_value(fmpq_t x, const fmpq_t A, const fmpq_t B, slong i, slong K, int logsp);
/* K points from A to B, linear (K == 1: A); _fmpq_vec_clear(x, K). */
fmpq *rs_grid_axis(const fmpq_t A, const fmpq_t B, slong K);
/* The rows of shard I/N (1-based) of npoints points: the contiguous block
 * [*lo, *hi) with lo = floor((I-1)*P/N), hi = floor(I*P/N). */
void rs_grid_shard_range(slong *lo, slong *hi, slong npoints, slong I, slong N);

/* p(lambda; x1, x2) as a list of terms for exact evaluation at grid points:
 * variable lv (lambda; -1: none), v1 and v2 (-1: none) of p. */
typedef struct {
    slong n;          /* terms */
    fmpz *c;
    slong *el, *e1, *e2;
    slong dl, d1, d2; /* degrees in lambda, param 1, param 2 */
} rs_grid_terms_t;
void rs_grid_terms_init(rs_grid_terms_t *T, const fmpz_mpoly_t p, slong lv, slong v1, slong v2,
                        const fmpz_mpoly_ctx_t ctx);
void rs_grid_terms_clear(rs_grid_terms_t *T);
/* U[g*(d+1) + e] = num_g^e den_g^(d-e) for the nv values; _fmpz_vec_clear(U, nv*(d+1)) */
fmpz *rs_grid_powers(const fmpq *vals, slong nv, slong d);
/* P = den1^d1 den2^d2 p(lambda; x1, x2) from the power rows u1, u2 (NULL: one variable) */
void rs_grid_terms_eval(fmpz_poly_t P, const rs_grid_terms_t *T, const fmpz *u1, const fmpz *u2);

#endif
