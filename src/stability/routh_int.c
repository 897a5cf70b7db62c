/* routh_int.c -- the Routh count of a regular array in integer arithmetic
 * (see rs_routh_int_count in include/recstab/routh.h).
 *
 * The rational array of rs_routh_fmpz_poly keeps every row as a remainder
 * over Q: at degree 500 the gcds of its ever longer fractions take about a
 * minute.  Here the rows are integer vectors, T_0, T_1 = the two halves of
 * q, then
 *     U[j]    = T_{i-1}[0] T_{i-2}[j+1] - T_{i-2}[0] T_{i-1}[j+1]
 *     T_i     = U / content(U)
 * (a primitive PRS: each new row is made primitive by the gcd of its
 * entries, an exact division; no Bareiss division by an earlier pivot is
 * used).  T_i = c_i r_i with r_i the rational Routh row and c_i a nonzero
 * rational whose sign is tracked from the pivots, so the signs of r_i[0]
 * are known without fractions.  The textbook first column is
 * r_i[0] = Delta_i / Delta_{i-1} (Delta_i the Hurwitz minors): its sign
 * changes are the roots of q with Re z > 0, i.e. of p with |lambda| > 1.  Only the
 * regular case is done here (every Delta_i != 0, deg q = deg p, q(0) != 0):
 * anything else is left to the exact generalised array. */
#include <flint/fmpz_vec.h>
#include "recstab/budget.h"
#include "recstab/routh.h"
#include "recstab/bilinear.h"

int rs_routh_int_count(rs_rootcount_t rc, const fmpz_poly_t p, rs_error_t err)
{
    fmpz_poly_t q;
    fmpz *row[3], *t;
    fmpz_t u, v, g;
    slong n = fmpz_poly_degree(p), m, w, i, j, len[3], changes = 0;
    int status = RS_OK, last, sc[2] = { 1, 1 }, snew;

    if (n < 1)
        return RS_ERR_UNDECIDED;
    fmpz_poly_init(q);
    rs_bilinear_fmpz_poly(q, p);
    m = fmpz_poly_degree(q);
    if (m != n || fmpz_is_zero(q->coeffs + 0)) {
        fmpz_poly_clear(q);
        return RS_ERR_UNDECIDED;     /* roots at lambda = -1 or 1 */
    }
    w = m / 2 + 1;
    for (i = 0; i < 3; i++)
        row[i] = _fmpz_vec_init(w + 1);
    fmpz_init(u);
    fmpz_init(v);
    fmpz_init(g);
    /* row[0] = T_{i-1}, row[1] = T_i (entries z^N, z^(N-2), ...), with
     * T_k = c_k r_k, r_k the rational Routh row, sc[] = sign(c_{i-1}),
     * sign(c_i); T_0 = r_0 and T_1 = r_1 */
    len[0] = len[1] = 0;
    for (j = 0; m - 2 * j >= 0; j++)
        fmpz_set(row[0] + len[0]++, q->coeffs + m - 2 * j);
    for (j = 0; m - 1 - 2 * j >= 0; j++)
        fmpz_set(row[1] + len[1]++, q->coeffs + m - 1 - 2 * j);
    last = fmpz_sgn(row[0]);
    for (i = 1; i <= m; i++) {
        int si;
        if (fmpz_is_zero(row[1])) {
            status = RS_ERR_UNDECIDED;   /* zero pivot or zero row */
            break;
        }
        si = fmpz_sgn(row[1]) * sc[1];   /* sign of r_i[0] */
        if (si != last)
            changes++;
        last = si;
        if (i == m)
            break;
        if ((status = rs_budget_check(err, "the Routh array")) != RS_OK)
            break;
        /* U[j] = T_i[0] T_{i-1}[j+1] - T_{i-1}[0] T_i[j+1]
         *      = c_i c_{i-1} r_i[0] r_{i+1}[j]; T_{i+1} = U / content(U) */
        len[2] = len[0] - 1;
        for (j = 0; j < len[2]; j++) {
            fmpz_mul(row[2] + j, row[1], row[0] + j + 1);
            if (j + 1 < len[1]) {
                fmpz_mul(v, row[0], row[1] + j + 1);
                fmpz_sub(row[2] + j, row[2] + j, v);
            }
        }
        _fmpz_vec_content(g, row[2], len[2]);
        if (!fmpz_is_zero(g) && !fmpz_is_one(g))
            _fmpz_vec_scalar_divexact_fmpz(row[2], row[2], len[2], g);
        /* sign(c_{i+1}) = sign(c_i c_{i-1} r_i[0]) = sign(T_i[0]) sign(c_{i-1}) */
        snew = fmpz_sgn(row[1]) * sc[0];
        sc[0] = sc[1];
        sc[1] = snew;
        len[0] = len[1];
        len[1] = len[2];
        t = row[0]; row[0] = row[1]; row[1] = row[2]; row[2] = t;
    }
    if (status == RS_OK) {
        rs_rootcount_init(rc);
        rc->degree = n;
        rc->outside = changes;
        rc->inside = n - changes;
    }
    for (i = 0; i < 3; i++)
        _fmpz_vec_clear(row[i], w + 1);
    fmpz_clear(u);
    fmpz_clear(v);
    fmpz_clear(g);
    fmpz_poly_clear(q);
    return status;
}
