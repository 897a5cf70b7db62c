/* qd.h -- numbers x + y sqrt(d) of Q(sqrt d), d > 1 squarefree: the exact
 * entries of the Gauss, Radau IIA(3) and SDIRK tableaux (lower/methods.c) and
 * the coefficients of their stability functions (algebra/qsqrt.c).  The sign
 * is exact: x^2 against d y^2. */
#ifndef RECSTAB_UTIL_QD_H
#define RECSTAB_UTIL_QD_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpz_mpoly.h>

#ifdef __cplusplus
extern "C" {
#endif

/* x + y sqrt(d) */
typedef struct { fmpq x[1], y[1]; } rs_qd_struct;
typedef rs_qd_struct rs_qd_t[1];

void rs_qd_init(rs_qd_struct *a);
void rs_qd_clear(rs_qd_struct *a);
void rs_qd_set(rs_qd_struct *r, const rs_qd_struct *a);
void rs_qd_set_fmpq(rs_qd_struct *r, const fmpq_t x, const fmpq_t y);
int rs_qd_is_zero(const rs_qd_struct *a);
void rs_qd_add(rs_qd_struct *r, const rs_qd_struct *a, const rs_qd_struct *b);
void rs_qd_sub(rs_qd_struct *r, const rs_qd_struct *a, const rs_qd_struct *b);
void rs_qd_mul(rs_qd_struct *r, const rs_qd_struct *a, const rs_qd_struct *b, slong d);
/* a != 0 */
void rs_qd_inv(rs_qd_struct *r, const rs_qd_struct *a, slong d);
/* the exact sign of x + y sqrt(d): -1, 0, 1 */
int rs_qd_sgn(const rs_qd_struct *a, slong d);
/* "x + y*sqrt(d)" (flint_free it) */
char *rs_qd_get_str(const rs_qd_struct *a, slong d);
/* p with variable v standing for sqrt(d): every term c v^e becomes
 * c d^(e/2) v^(e mod 2), so p = p0 + v p1 with p0, p1 free of v (any
 * d != 0: d = -1 reduces by the imaginary unit; d = 0 leaves p as it is) */
void rs_qd_mpoly_reduce(fmpz_mpoly_t p, slong v, slong d, const fmpz_mpoly_ctx_t ctx);

#ifdef __cplusplus
}
#endif

#endif
