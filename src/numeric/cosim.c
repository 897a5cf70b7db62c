/* cosim.c -- see include/recstab/cosim.h.
 *
 * Derivation of the recurrences (checked against the seed, sect. 3.1),
 * for m coupling variables u (m = 1: the scalar force lambda_c).
 *
 * Exact integration of z' = A z + B u(t) over [T_N, T_N + H] with each
 * component u_c(T_N + s) = sum_j u_{j,c} L_j(s/H), L_j(tau) = sum_k l_{j,k}
 * tau^k, i.e. u(T_N + s) = sum_j L_j(s/H) u_j (u_j in R^m):
 *     z_{N+1} = E z_N + sum_j G_j u_j,  G_j = sum_k l_{j,k} Phi_k  (n x m).
 * A and B are block structured (subsystem i sees only A_i and its rows
 * B_i), so E and Phi are computed per subsystem and stacked.
 *
 * Explicit (step 1 only, eq. 10 and 16): nodes tau_j = -j carrying
 * u_{N-j} = C z_{N-j}, j = 0..K.  Degree K + 1 in the shift; for K = 2
 * that is the paper's four-term eq. (16).
 *
 * Implicit (steps 1-3, eq. 10-15):
 *   step 1 gives z^p_{N+1} and u^p = P^p(T_{N+1}) (componentwise) from the
 *     degree-K extrapolants P^p through (T_{N-j}, u_{N-j}), j = 0..K;
 *   step 2: z*_{N+1}(u*) uses the degree-K interpolants through
 *     (T_{N+1}, u*) and (T_{N+1-j}, u_{N+1-j}), j = 1..K:
 *         z* = E z_N + G*_0 u* + sum_{j>=1} G*_j u_{N+1-j},
 *     affine in u*, so the coupling conditions g(u*) = u* - C z*(u*) (eq. 12
 *     with this C; the printed eq. 12 has the same sign: lambda* - acc1 c1
 *     (x2 - x1) - adc1 d1 (v2 - v1); for the displacement variables of eq.
 *     8/9, g = x1~* - x1* etc., i.e. C_P z + D_P u with C_P = -C) are affine
 *     with the constant m x m Jacobian MATRIX J = dg/du* = I_m - C G*_0 (the
 *     paper's J_c, a scalar only for force/force).  The paper's g^p is g at
 *     the predictor.  The interpolant through (T_{N+1}, u^p), (T_N, u_N), ...,
 *     (T_{N-K+1}, ...) passes through K + 1 points of the degree-K
 *     polynomial P^p, hence IS P^p (componentwise), so z^p_{N+1} = z*(u^p)
 *     and g^p = g(u^p) exactly.  The linearised equations (13)
 *     g^p + J (u_{N+1} - u^p) = 0 are then the affine g itself: their
 *     solution (J invertible) is the exact root, g(u_{N+1}) = 0, and the
 *     predictor drops out of the recurrence;
 *   step 3 (eq. 14): z_{N+1} = z*(u_{N+1}), so u_{N+1} = C z_{N+1}:
 *     (I - G_0 C) z_{N+1} - (E + G_1 C) z_N - sum_{j>=2} G_j C z_{N+1-j} = 0,
 *     degree max(K, 1); for K = 2 the paper's three-term eq. (15).
 *   Solving for z_{N+1}: with J = I_m - C G_0, (I_n - G_0 C)^{-1} =
 *     I_n + G_0 J^{-1} C (Woodbury; det(I_n - G_0 C) = det J), so the
 *     one-step map is Top + G_0 J^{-1} (C Top), Top = [E + G_1 C | G_2 ...]:
 *     exactly "u_{N+1} = J^{-1} C (E z_N + sum_{j>=1} G_j u_{N+1-j})",
 *     the solution of the linear coupling conditions (I - C G_0) u_{N+1} =
 *     C (E z_N + ...), then z_{N+1} = E z_N + G_0 u_{N+1} + ....
 * The time-domain oracle in tests/unit/numeric/test_cosim.c runs steps 1-3 literally
 * (predictor, finite-difference Jacobian matrix column by column, Newton
 * step solving J delta = -g^p, corrector) for FF, FD and DD and agrees; it
 * also checks its finite-difference J against rs_cosim_recurrence's jacm.
 *
 * Radius: the one-step map (rs_cosim_transition) rather than the block
 * companion of the recurrence, whose extra eigenvalue 0 is defective
 * (Jordan chains through the delayed z_{N-j} that only enter via C z_{N-j}),
 * which forces the slower cluster route of rs_radius; and the map of the
 * reduced realisation (rs_cosim_reduce), for the same reason: DD's four
 * displacement inputs enter through a rank-2 B, and their histories would
 * add defective zero eigenvalues.  Both routes are exposed. */
#include <string.h>
#include <flint/fmpq_poly.h>
#include <acb_mat.h>
#include "recstab/budget.h"
#include "recstab/cosim.h"
#include "numeric/cosim_ball.h"
#include "numeric/cosim_ext.h"

/* ------------------------------------------------------------------ */
/* model                                                               */

static void _alloc_mats(rs_cosim_t cs, slong n1, slong n2, slong m)
{
    if (n1 < 0)
        n1 = 0;
    if (n2 < 0)
        n2 = 0;
    if (m < 1)
        m = 1;
    cs->n1 = n1;
    cs->n2 = n2;
    cs->m = m;
    fmpq_mat_init(cs->A1, n1, n1);
    fmpq_mat_init(cs->A2, n2, n2);
    fmpq_mat_init(cs->B1, n1, m);
    fmpq_mat_init(cs->B2, n2, m);
    fmpq_mat_init(cs->C, m, n1 + n2);
}

static void _free_mats(rs_cosim_t cs)
{
    fmpq_mat_clear(cs->A1);
    fmpq_mat_clear(cs->A2);
    fmpq_mat_clear(cs->B1);
    fmpq_mat_clear(cs->B2);
    fmpq_mat_clear(cs->C);
}

void rs_cosim_init(rs_cosim_t cs, slong n1, slong n2)
{
    rs_cosim_init_m(cs, n1, n2, 1);
}

void rs_cosim_init_m(rs_cosim_t cs, slong n1, slong n2, slong m)
{
    _alloc_mats(cs, n1, n2, m);
    fmpq_init(cs->H);
    fmpq_one(cs->H);
    cs->method = RS_COSIM_EXPLICIT;
    cs->order = 0;
    cs->ext = RS_COSIM_EXT_NONE;
    fmpq_init(cs->alpha_T);
    fmpq_set_si(cs->alpha_T, 1, 2);
}

void rs_cosim_clear(rs_cosim_t cs)
{
    _free_mats(cs);
    fmpq_clear(cs->H);
    fmpq_clear(cs->alpha_T);
}

void rs_cosim_set_dims(rs_cosim_t cs, slong n1, slong n2)
{
    rs_cosim_set_dims_m(cs, n1, n2, 1);
}

void rs_cosim_set_dims_m(rs_cosim_t cs, slong n1, slong n2, slong m)
{
    _free_mats(cs);
    _alloc_mats(cs, n1, n2, m);
}

static int _shape_ok(const fmpq_mat_t M, slong r, slong c)
{
    return fmpq_mat_nrows(M) == r && fmpq_mat_ncols(M) == c;
}

int rs_cosim_check(const rs_cosim_t cs, rs_error_t err)
{
    slong n1 = cs->n1, n2 = cs->n2, m = cs->m;
    if (n1 < 1 || n2 < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: subsystem dimensions must be >= 1 (got "
                            "n1 = %ld, n2 = %ld)", (long) n1, (long) n2);
    if (n1 + n2 > RS_COSIM_MAX_DIM)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "cosim: n1 + n2 = %ld exceeds the limit %d",
                            (long) (n1 + n2), RS_COSIM_MAX_DIM);
    if (m < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: need at least one coupling variable "
                            "(m = %ld)", (long) m);
    if (m > RS_COSIM_MAX_INPUTS)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "cosim: m = %ld coupling variables exceed the "
                            "limit %d", (long) m, RS_COSIM_MAX_INPUTS);
    if (!_shape_ok(cs->A1, n1, n1) || !_shape_ok(cs->A2, n2, n2)
        || !_shape_ok(cs->B1, n1, m) || !_shape_ok(cs->B2, n2, m)
        || !_shape_ok(cs->C, m, n1 + n2))
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: matrix shapes do not match n1 = %ld, "
                            "n2 = %ld, m = %ld (A_i n_i x n_i, B_i n_i x m, "
                            "C m x n)", (long) n1, (long) n2, (long) m);
    if (fmpq_sgn(cs->H) <= 0)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: macro step H must be > 0");
    if (cs->method != RS_COSIM_EXPLICIT && cs->method != RS_COSIM_IMPLICIT)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: unknown method %d (explicit = %d, "
                            "implicit = %d)", cs->method, RS_COSIM_EXPLICIT,
                            RS_COSIM_IMPLICIT);
    if (cs->order < 0 || cs->order > RS_COSIM_MAX_ORDER)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: approximation order K = %ld outside "
                            "0..%d", (long) cs->order, RS_COSIM_MAX_ORDER);
    return rs_cosim_ext_check(cs, err);
}

/* Signs follow the printed equations of motion (2)/(4): the coupling force
 * lambda_c = cc (x2 - x1) + dc (v2 - v1) pulls mass 1 (+lambda_c/m1) towards
 * mass 2 and mass 2 (-lambda_c/m2) towards mass 1, so with positive
 * parameters the coupled oscillator is mechanically stable.  Against eq. (4):
 *   eq. (5): consistent (A_mono = A + B C reproduces it entry by entry; the
 *     extracted first row "0 1 0 0 0" has a stray fifth entry);
 *   eq. (7): B_FF consistent; C_FF = (acc1 c1, adc1 d1, -acc1 c1, -adc1 d1)
 *     is the negative of our C, consistent because g = C_FF z + D_FF u = 0
 *     means lambda_c = -C_FF z; D_FF is printed with 4 entries (0 0 0 1)
 *     although u has 5 (should be (0 0 0 0 1));
 *   eq. (8): consistent (B_FD row 4 = +acc1/am21 c1, +adc1/am21 d1 and the
 *     (alpha_c21 + alpha_cc1) diagonal match eq. 4); D_FD row 2 again has 4
 *     entries instead of 5;
 *   eq. (9): consistent in sign; A_DD rows 1/3 are printed 5 wide and B_DD
 *     row 1 6 wide (shape slips only);
 *   eq. (12): g = lambda* - acc1 c1 (x2* - x1*) - adc1 d1 (v2* - v1*),
 *     consistent with eq. (4) and with g = lambda - C z here.
 * No sign slip was found; only the shape slips above. */
int rs_cosim_li_ff(rs_cosim_t cs, const fmpq_t c1, const fmpq_t d1,
                   const fmpq_t am21, const fmpq_t ac21, const fmpq_t ad21,
                   const fmpq_t acc1, const fmpq_t adc1, rs_error_t err)
{
    fmpq_t t;
    if (fmpq_is_zero(am21))
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: Li model needs alpha_m21 = m2/m1 != 0");
    if (cs->n1 != 2 || cs->n2 != 2 || cs->m != 1)
        rs_cosim_set_dims(cs, 2, 2);
    else {
        fmpq_mat_zero(cs->A1);
        fmpq_mat_zero(cs->A2);
        fmpq_mat_zero(cs->B1);
        fmpq_mat_zero(cs->B2);
        fmpq_mat_zero(cs->C);
    }
    fmpq_init(t);
    /* subsystem 1: x1' = v1, v1' = -c1 x1 - d1 v1 + lambda_c */
    fmpq_one(fmpq_mat_entry(cs->A1, 0, 1));
    fmpq_neg(fmpq_mat_entry(cs->A1, 1, 0), c1);
    fmpq_neg(fmpq_mat_entry(cs->A1, 1, 1), d1);
    fmpq_one(fmpq_mat_entry(cs->B1, 1, 0));
    /* subsystem 2: v2' = -(ac21/am21) c1 x2 - (ad21/am21) d1 v2
     *                    - lambda_c / am21 */
    fmpq_one(fmpq_mat_entry(cs->A2, 0, 1));
    fmpq_div(t, ac21, am21);
    fmpq_mul(t, t, c1);
    fmpq_neg(fmpq_mat_entry(cs->A2, 1, 0), t);
    fmpq_div(t, ad21, am21);
    fmpq_mul(t, t, d1);
    fmpq_neg(fmpq_mat_entry(cs->A2, 1, 1), t);
    fmpq_inv(t, am21);
    fmpq_neg(fmpq_mat_entry(cs->B2, 1, 0), t);
    /* lambda_c = acc1 c1 (x2 - x1) + adc1 d1 (v2 - v1) */
    fmpq_mul(t, acc1, c1);
    fmpq_neg(fmpq_mat_entry(cs->C, 0, 0), t);
    fmpq_set(fmpq_mat_entry(cs->C, 0, 2), t);
    fmpq_mul(t, adc1, d1);
    fmpq_neg(fmpq_mat_entry(cs->C, 0, 1), t);
    fmpq_set(fmpq_mat_entry(cs->C, 0, 3), t);
    fmpq_clear(t);
    return RS_OK;
}

/* Force/displacement and displacement/displacement models (eq. 8, 9).
 * Followed: the printed A_FD, B_FD, C_FD (with D_FD) and A_DD, B_DD, C_DD
 * (with D_DD), restricted to the components of the paper's u =
 * (x1~, v1~, x2~, v2~, lambda_c) that each decomposition uses (B_FD's
 * columns 3, 4 and B_DD's column 5 are zero), in the paper's order; our
 * C = -(C_P rows) since D_P picks each used u component with +1.
 * Signs against the physics (eq. 2/4): the coupling spring/damper pulls
 * mass 1 towards mass 2, so the own-state part of the coupling term enters
 * v1' as -acc1 c1 x1 - adc1 d1 v1 (A_DD row 2: -(1 + acc1) c1,
 * -(1 + adc1) d1) and the partner's part as +acc1 c1 x2~ + adc1 d1 v2~
 * (B_DD row 2); for mass 2 likewise with 1/am21 (A_FD = A_DD row 4,
 * B_FD = B_DD row 4: +acc1/am21 c1 x1~ + adc1/am21 d1 v1~).  Every printed
 * sign agrees; A + B C reproduces eq. (5) exactly for FF, FD and DD
 * (tests/unit/numeric/test_cosim.c), and eq. (5) is mechanically stable (its eigenvalues
 * have negative real parts at positive parameters; tested with GSL).
 * Slips found (shape only): D_FD row 2 has 4 entries (should be
 * (1 0 0 0 0)); A_DD rows 1 and 3 are printed 5 wide (the 4 x 4 rows are
 * (0 1 0 0) and (0 0 0 1)); B_DD rows 1 and 3 are printed 6 wide (zero rows
 * of length 5); also D_FF (eq. 7) has 4 entries instead of 5 (noted
 * above). */
static void _li_common(rs_cosim_t cs, slong m, const fmpq_t c1,
                       const fmpq_t d1, const fmpq_t am21, const fmpq_t ac21,
                       const fmpq_t ad21, const fmpq_t acc1,
                       const fmpq_t adc1, int dd)
{
    fmpq_t t, u;
    if (cs->n1 != 2 || cs->n2 != 2 || cs->m != m)
        rs_cosim_set_dims_m(cs, 2, 2, m);
    else {
        fmpq_mat_zero(cs->A1);
        fmpq_mat_zero(cs->A2);
        fmpq_mat_zero(cs->B1);
        fmpq_mat_zero(cs->B2);
        fmpq_mat_zero(cs->C);
    }
    fmpq_init(t);
    fmpq_init(u);
    /* subsystem 1: x1' = v1; v1' = -c1 x1 - d1 v1 (FD, + lambda_c) or
     * -(1 + acc1) c1 x1 - (1 + adc1) d1 v1 + acc1 c1 x2~ + adc1 d1 v2~ (DD) */
    fmpq_one(fmpq_mat_entry(cs->A1, 0, 1));
    fmpq_set(t, c1);
    if (dd) {
        fmpq_mul(u, acc1, c1);
        fmpq_add(t, t, u);
    }
    fmpq_neg(fmpq_mat_entry(cs->A1, 1, 0), t);
    fmpq_set(t, d1);
    if (dd) {
        fmpq_mul(u, adc1, d1);
        fmpq_add(t, t, u);
    }
    fmpq_neg(fmpq_mat_entry(cs->A1, 1, 1), t);
    /* subsystem 2 (FD and DD): x2' = v2;
     * v2' = -(ac21 + acc1)/am21 c1 x2 - (ad21 + adc1)/am21 d1 v2
     *       + acc1/am21 c1 x1~ + adc1/am21 d1 v1~ */
    fmpq_one(fmpq_mat_entry(cs->A2, 0, 1));
    fmpq_add(t, ac21, acc1);
    fmpq_div(t, t, am21);
    fmpq_mul(t, t, c1);
    fmpq_neg(fmpq_mat_entry(cs->A2, 1, 0), t);
    fmpq_add(t, ad21, adc1);
    fmpq_div(t, t, am21);
    fmpq_mul(t, t, d1);
    fmpq_neg(fmpq_mat_entry(cs->A2, 1, 1), t);
    /* u_0 = x1~, u_1 = v1~ (both models) */
    fmpq_div(t, acc1, am21);
    fmpq_mul(fmpq_mat_entry(cs->B2, 1, 0), t, c1);
    fmpq_div(t, adc1, am21);
    fmpq_mul(fmpq_mat_entry(cs->B2, 1, 1), t, d1);
    fmpq_one(fmpq_mat_entry(cs->C, 0, 0));
    fmpq_one(fmpq_mat_entry(cs->C, 1, 1));
    if (dd) {
        /* u_2 = x2~, u_3 = v2~ drive subsystem 1 */
        fmpq_mul(fmpq_mat_entry(cs->B1, 1, 2), acc1, c1);
        fmpq_mul(fmpq_mat_entry(cs->B1, 1, 3), adc1, d1);
        fmpq_one(fmpq_mat_entry(cs->C, 2, 2));
        fmpq_one(fmpq_mat_entry(cs->C, 3, 3));
    } else {
        /* u_2 = lambda_c = acc1 c1 (x2 - x1) + adc1 d1 (v2 - v1) drives
         * subsystem 1 with +1 (B_FD row 2) */
        fmpq_one(fmpq_mat_entry(cs->B1, 1, 2));
        fmpq_mul(t, acc1, c1);
        fmpq_neg(fmpq_mat_entry(cs->C, 2, 0), t);
        fmpq_set(fmpq_mat_entry(cs->C, 2, 2), t);
        fmpq_mul(t, adc1, d1);
        fmpq_neg(fmpq_mat_entry(cs->C, 2, 1), t);
        fmpq_set(fmpq_mat_entry(cs->C, 2, 3), t);
    }
    fmpq_clear(t);
    fmpq_clear(u);
}

int rs_cosim_li_fd(rs_cosim_t cs, const fmpq_t c1, const fmpq_t d1,
                   const fmpq_t am21, const fmpq_t ac21, const fmpq_t ad21,
                   const fmpq_t acc1, const fmpq_t adc1, rs_error_t err)
{
    if (fmpq_is_zero(am21))
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: Li model needs alpha_m21 = m2/m1 != 0");
    _li_common(cs, 3, c1, d1, am21, ac21, ad21, acc1, adc1, 0);
    return RS_OK;
}

int rs_cosim_li_dd(rs_cosim_t cs, const fmpq_t c1, const fmpq_t d1,
                   const fmpq_t am21, const fmpq_t ac21, const fmpq_t ad21,
                   const fmpq_t acc1, const fmpq_t adc1, rs_error_t err)
{
    if (fmpq_is_zero(am21))
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: Li model needs alpha_m21 = m2/m1 != 0");
    _li_common(cs, 4, c1, d1, am21, ac21, ad21, acc1, adc1, 1);
    return RS_OK;
}

/* ------------------------------------------------------------------ */
/* Lagrange coefficients                                               */

int rs_cosim_lagrange(fmpq_mat_t L, int method, slong order, rs_error_t err)
{
    slong K = order, j, i, m;
    fmpq_poly_t num, lin;
    fmpq_t den, d, tj, ti;

    if (K < 0 || K > RS_COSIM_MAX_ORDER)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: approximation order K = %ld outside 0..%d",
                            (long) K, RS_COSIM_MAX_ORDER);
    if (method != RS_COSIM_EXPLICIT && method != RS_COSIM_IMPLICIT)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: unknown method %d",
                            method);
    if (fmpq_mat_nrows(L) != K + 1 || fmpq_mat_ncols(L) != K + 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: Lagrange matrix must be %ldx%ld",
                            (long) (K + 1), (long) (K + 1));
    fmpq_poly_init(num);
    fmpq_poly_init(lin);
    fmpq_init(den);
    fmpq_init(d);
    fmpq_init(tj);
    fmpq_init(ti);
    for (j = 0; j <= K; j++) {
        /* node tau_j = -j (explicit) or 1 - j (implicit) */
        fmpq_set_si(tj, (method == RS_COSIM_IMPLICIT ? 1 : 0) - j, 1);
        fmpq_poly_one(num);
        fmpq_one(den);
        for (i = 0; i <= K; i++) {
            if (i == j)
                continue;
            fmpq_set_si(ti, (method == RS_COSIM_IMPLICIT ? 1 : 0) - i, 1);
            /* lin = tau - tau_i */
            fmpq_poly_zero(lin);
            fmpq_poly_set_coeff_si(lin, 1, 1);
            fmpq_neg(d, ti);
            fmpq_poly_set_coeff_fmpq(lin, 0, d);
            fmpq_poly_mul(num, num, lin);
            fmpq_sub(d, tj, ti);
            fmpq_mul(den, den, d);
        }
        fmpq_poly_scalar_div_fmpq(num, num, den);
        for (m = 0; m <= K; m++)
            fmpq_poly_get_coeff_fmpq(fmpq_mat_entry(L, j, m), num, m);
    }
    fmpq_poly_clear(num);
    fmpq_poly_clear(lin);
    fmpq_clear(den);
    fmpq_clear(d);
    fmpq_clear(tj);
    fmpq_clear(ti);
    return RS_OK;
}

/* ------------------------------------------------------------------ */
/* exponentials (Van Loan)                                              */

/* The exponentials work on a ball model (numeric/cosim_ball.h): the exact
 * model's own realisation or the reduced one of rs_cosim_reduce converted
 * at prec, or a model whose entries are balls over a parameter box (the
 * certified region and claim), so both share this one engine. */
static void _own_ball(rs_cosim_ball_t b, const rs_cosim_t cs, slong prec)
{
    rs_cosim_ball_set(b, cs, cs->B1, cs->B2, cs->C, cs->m, prec);
}

/* One subsystem: E_i into E at offset off, Phi_k e_c of subsystem i into
 * Phi rows off..off+ni-1, column k m + c (m = columns of Bi).  Only the
 * columns of Bi that are not exactly zero get a chain in the Van Loan
 * matrix; the others leave Phi zero (Phi must be zeroed by the caller). */
static void _exp_phi_sub(arb_mat_t E, arb_mat_t Phi, slong off,
                         const arb_mat_t Ai, const arb_mat_t Bi,
                         const arb_t H, slong K, slong prec)
{
    slong ni = arb_mat_nrows(Ai), m = arb_mat_ncols(Bi), q = 0, sz, r, c,
          k, ch;
    slong *cols = flint_malloc((m + 1) * sizeof(slong));
    arb_mat_t Ma, X;
    arb_t fact;

    for (c = 0; c < m; c++) {
        int nz = 0;
        for (r = 0; r < ni; r++)
            if (!arb_is_zero(arb_mat_entry(Bi, r, c)))
                nz = 1;
        if (nz)
            cols[q++] = c;
    }
    sz = ni + q * (K + 1);
    arb_mat_init(Ma, sz, sz);
    arb_mat_init(X, sz, sz);
    for (r = 0; r < ni; r++) {
        for (c = 0; c < ni; c++)
            arb_mul(arb_mat_entry(Ma, r, c), arb_mat_entry(Ai, r, c), H, prec);
        for (ch = 0; ch < q; ch++)
            arb_mul(arb_mat_entry(Ma, r, ni + ch * (K + 1)),
                    arb_mat_entry(Bi, r, cols[ch]), H, prec);
    }
    for (ch = 0; ch < q; ch++)
        for (r = 0; r < K; r++)
            arb_one(arb_mat_entry(Ma, ni + ch * (K + 1) + r,
                                  ni + ch * (K + 1) + r + 1));
    arb_mat_exp(X, Ma, prec);
    for (r = 0; r < ni; r++)
        for (c = 0; c < ni; c++)
            arb_set(arb_mat_entry(E, off + r, off + c), arb_mat_entry(X, r, c));
    arb_init(fact);
    arb_one(fact);
    for (k = 0; k <= K; k++) {
        if (k > 1)
            arb_mul_ui(fact, fact, (ulong) k, prec);
        for (ch = 0; ch < q; ch++)
            for (r = 0; r < ni; r++)
                arb_mul(arb_mat_entry(Phi, off + r, k * m + cols[ch]),
                        arb_mat_entry(X, r, ni + ch * (K + 1) + k), fact,
                        prec);
    }
    arb_clear(fact);
    arb_mat_clear(X);
    arb_mat_clear(Ma);
    flint_free(cols);
}

static void _exp_phi_r(arb_mat_t E, arb_mat_t Phi, const rs_cosim_ball_t b,
                       slong prec)
{
    arb_mat_zero(E);
    arb_mat_zero(Phi);
    _exp_phi_sub(E, Phi, 0, b->A1, b->B1, b->H, b->order, prec);
    _exp_phi_sub(E, Phi, b->n1, b->A2, b->B2, b->H, b->order, prec);
}

void rs_cosim_ball_exp_phi(arb_mat_t E, arb_mat_t Phi, const rs_cosim_ball_t b, slong prec)
{
    _exp_phi_r(E, Phi, b, prec);
}

/* The checks of the public E/Phi and E/G entry points: a valid cosim
 * and an n x n E beside an n x m(K+1) second matrix named xname. */
static int _check_out(const arb_mat_t E, const arb_mat_t X, const char *xname,
                      const rs_cosim_t cs, rs_error_t err)
{
    slong n, w;
    int rc = rs_cosim_check(cs, err);
    if (rc != RS_OK)
        return rc;
    n = cs->n1 + cs->n2;
    w = cs->m * (cs->order + 1);
    if (arb_mat_nrows(E) != n || arb_mat_ncols(E) != n
        || arb_mat_nrows(X) != n || arb_mat_ncols(X) != w)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: E must be %ldx%ld and %s %ldx%ld",
                            (long) n, (long) n, xname, (long) n, (long) w);
    return RS_OK;
}

int rs_cosim_exp_phi(arb_mat_t E, arb_mat_t Phi, const rs_cosim_t cs,
                     slong prec, rs_error_t err)
{
    rs_cosim_ball_t b;
    int rc = _check_out(E, Phi, "Phi", cs, err);
    if (rc != RS_OK)
        return rc;
    rs_cosim_ball_init(b);
    _own_ball(b, cs, prec);
    _exp_phi_r(E, Phi, b, prec);
    rs_cosim_ball_clear(b);
    return RS_OK;
}

/* G_j = sum_k l_{j,k} Phi_k, blocks of m columns */
static int _gains_r(arb_mat_t E, arb_mat_t G, const rs_cosim_ball_t b,
                    slong prec, rs_error_t err)
{
    slong n = b->n1 + b->n2, K = b->order, m = b->m, j, k, r, c;
    fmpq_mat_t L;
    arb_mat_t Phi;
    arb_t t;
    int rc;
    fmpq_mat_init(L, K + 1, K + 1);
    arb_mat_init(Phi, n, m * (K + 1));
    arb_init(t);
    rc = rs_cosim_lagrange(L, b->method, K, err);
    if (rc == RS_OK) {
        _exp_phi_r(E, Phi, b, prec);
        arb_mat_zero(G);
        for (j = 0; j <= K; j++)
            for (k = 0; k <= K; k++) {
                const fmpq *l = fmpq_mat_entry(L, j, k);
                if (fmpq_is_zero(l))
                    continue;
                for (c = 0; c < m; c++)
                    for (r = 0; r < n; r++) {
                        arb_mul_fmpz(t, arb_mat_entry(Phi, r, k * m + c),
                                     fmpq_numref(l), prec);
                        arb_div_fmpz(t, t, fmpq_denref(l), prec);
                        arb_add(arb_mat_entry(G, r, j * m + c),
                                arb_mat_entry(G, r, j * m + c), t, prec);
                    }
            }
    }
    arb_clear(t);
    arb_mat_clear(Phi);
    fmpq_mat_clear(L);
    return rc;
}

int rs_cosim_gains(arb_mat_t E, arb_mat_t G, const rs_cosim_t cs, slong prec,
                   rs_error_t err)
{
    rs_cosim_ball_t b;
    int rc = _check_out(E, G, "G", cs, err);
    if (rc != RS_OK)
        return rc;
    rs_cosim_ball_init(b);
    _own_ball(b, cs, prec);
    rc = _gains_r(E, G, b, prec, err);
    rs_cosim_ball_clear(b);
    return rc;
}

/* ------------------------------------------------------------------ */
/* recurrence and one-step map                                         */

/* Out = G_j C (n x m times m x n) */
static void _outer(arb_mat_t Out, const arb_mat_t G, slong j,
                   const arb_mat_t Cb, slong prec)
{
    slong r, c, i, n = arb_mat_nrows(Out), m = arb_mat_nrows(Cb);
    for (r = 0; r < n; r++)
        for (c = 0; c < n; c++) {
            arb_zero(arb_mat_entry(Out, r, c));
            for (i = 0; i < m; i++)
                arb_addmul(arb_mat_entry(Out, r, c),
                           arb_mat_entry(G, r, j * m + i),
                           arb_mat_entry(Cb, i, c), prec);
        }
}

/* J = I_m - C G_0 (m x m) */
static void _jacobian(arb_mat_t J, const arb_mat_t G, const arb_mat_t Cb,
                      slong prec)
{
    slong r, c, i, n = arb_mat_nrows(G), m = arb_mat_nrows(Cb);
    for (r = 0; r < m; r++)
        for (c = 0; c < m; c++) {
            if (r == c)
                arb_one(arb_mat_entry(J, r, c));
            else
                arb_zero(arb_mat_entry(J, r, c));
            for (i = 0; i < n; i++)
                arb_submul(arb_mat_entry(J, r, c), arb_mat_entry(Cb, r, i),
                           arb_mat_entry(G, i, c), prec);
        }
}

void rs_cosim_rec_init(rs_cosim_rec_t rec)
{
    rec->n = 0;
    rec->k = -1;
    rec->A = NULL;
    arb_init(rec->jac);
    arb_mat_init(rec->jacm, 0, 0);
    rec->prec = 0;
}

static void _rec_free(rs_cosim_rec_t rec)
{
    slong j;
    if (rec->A != NULL) {
        for (j = 0; j <= rec->k; j++)
            arb_mat_clear(rec->A + j);
        flint_free(rec->A);
    }
    rec->A = NULL;
    rec->k = -1;
    rec->n = 0;
}

void rs_cosim_rec_clear(rs_cosim_rec_t rec)
{
    _rec_free(rec);
    arb_clear(rec->jac);
    arb_mat_clear(rec->jacm);
}

int rs_cosim_recurrence(rs_cosim_rec_t rec, const rs_cosim_t cs, slong prec,
                        rs_error_t err)
{
    slong n, K, k, j, m;
    arb_mat_t E, G, Cb, T;
    rs_cosim_ball_t b;
    int rc = rs_cosim_check(cs, err), impl;
    if (rc != RS_OK)
        return rc;
    if (cs->ext != RS_COSIM_EXT_NONE)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: the D-/I-extension couplings have a one-step map "
                            "(rs_cosim_transition), not the recurrence of eq. (15)");
    n = cs->n1 + cs->n2;
    K = cs->order;
    m = cs->m;
    impl = (cs->method == RS_COSIM_IMPLICIT);
    k = impl ? (K > 1 ? K : 1) : K + 1;
    _rec_free(rec);
    rec->n = n;
    rec->k = k;
    rec->prec = prec;
    rec->A = flint_malloc((k + 1) * sizeof(arb_mat_struct));
    for (j = 0; j <= k; j++) {
        arb_mat_init(rec->A + j, n, n);
    }
    arb_mat_clear(rec->jacm);
    arb_mat_init(rec->jacm, m, m);
    arb_mat_init(E, n, n);
    arb_mat_init(G, n, m * (K + 1));
    arb_mat_init(Cb, m, n);
    arb_mat_init(T, n, n);
    rs_cosim_ball_init(b);
    _own_ball(b, cs, prec);
    rc = _gains_r(E, G, b, prec, err);
    rs_cosim_ball_clear(b);
    if (rc != RS_OK)
        goto cleanup;
    arb_mat_set_fmpq_mat(Cb, cs->C, prec);
    if (!impl) {
        /* z_{N+1} - (E + G_0 C) z_N - sum_{j>=1} G_j C z_{N-j} = 0;
         * z_{N-j} sits at shift offset K - j. */
        arb_mat_one(rec->A + k);
        for (j = 0; j <= K; j++) {
            _outer(T, G, j, Cb, prec);
            if (j == 0)
                arb_mat_add(T, T, E, prec);
            arb_mat_neg(rec->A + (K - j), T);
        }
        arb_one(rec->jac);
        arb_mat_one(rec->jacm);
    } else {
        /* (I - G_0 C) z_{N+1} - (E + G_1 C) z_N - sum_{j>=2} G_j C z_{N+1-j};
         * z_{N+1-j} sits at offset k - j. */
        _outer(T, G, 0, Cb, prec);
        arb_mat_one(rec->A + k);
        arb_mat_sub(rec->A + k, rec->A + k, T, prec);
        arb_mat_neg(rec->A + (k - 1), E);
        for (j = 1; j <= K; j++) {
            _outer(T, G, j, Cb, prec);
            arb_mat_sub(rec->A + (k - j), rec->A + (k - j), T, prec);
        }
        _jacobian(rec->jacm, G, Cb, prec);
        arb_mat_det(rec->jac, rec->jacm, prec);
    }
cleanup:
    arb_mat_clear(E);
    arb_mat_clear(G);
    arb_mat_clear(Cb);
    arb_mat_clear(T);
    return rc;
}

static slong _hist_of(int method, slong K)
{
    return method == RS_COSIM_IMPLICIT ? (K > 1 ? K - 1 : 0) : K;
}

static slong _hist(const rs_cosim_t cs)
{
    return _hist_of(cs->method, cs->order);
}

slong rs_cosim_ball_dim(const rs_cosim_ball_t b)
{
    if (b->ext != RS_COSIM_EXT_NONE)   /* state z_N only (cosim_ext.h) */
        return b->n1 + b->n2;
    return b->n1 + b->n2 + _hist_of(b->method, b->order) * b->m;
}

slong rs_cosim_transition_dim(const rs_cosim_t cs)
{
    if (cs->ext != RS_COSIM_EXT_NONE)   /* state z_N only (cosim_ext.h) */
        return cs->n1 + cs->n2;
    return cs->n1 + cs->n2 + _hist(cs) * cs->m;
}

/* The one-step map of (z_N, u_{N-1}, ..., u_{N-h}) of the ball model b
 * (m = b->m >= 0; m = 0: M = E). */
int rs_cosim_ball_transition(arb_mat_t M, const rs_cosim_ball_t b, slong prec,
                             rs_error_t err)
{
    slong n, K, h, dim, a, j, r, c, m = b->m;
    arb_mat_t E, G, Cb, Top, CX, J, Y;
    int rc = RS_OK, impl;
    if (b->ext != RS_COSIM_EXT_NONE)
        return rs_cosim_ext_ball_transition(M, b, prec, err);
    n = b->n1 + b->n2;
    K = b->order;
    impl = (b->method == RS_COSIM_IMPLICIT);
    a = impl ? 1 : 0;              /* first gain acting on z_N */
    h = _hist_of(b->method, K);    /* u history length */
    dim = n + h * m;
    if (arb_mat_nrows(M) != dim || arb_mat_ncols(M) != dim)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: transition matrix must be %ldx%ld",
                            (long) dim, (long) dim);
    arb_mat_init(E, n, n);
    arb_mat_init(G, n, m * (K + 1));
    arb_mat_init(Cb, m, n);
    arb_mat_init(Top, n, dim);
    arb_mat_init(CX, m, dim);
    arb_mat_init(J, m, m);
    arb_mat_init(Y, m, dim);
    rc = _gains_r(E, G, b, prec, err);
    if (rc != RS_OK)
        goto cleanup;
    arb_mat_set(Cb, b->C);
    /* Top = [E + G_a C | G_{a+1} ... G_K]  (G_1 := 0 for implicit K = 0) */
    for (r = 0; r < n; r++) {
        for (c = 0; c < n; c++) {
            arb_zero(arb_mat_entry(Top, r, c));
            if (a <= K)
                for (j = 0; j < m; j++)
                    arb_addmul(arb_mat_entry(Top, r, c),
                               arb_mat_entry(G, r, a * m + j),
                               arb_mat_entry(Cb, j, c), prec);
            arb_add(arb_mat_entry(Top, r, c), arb_mat_entry(Top, r, c),
                    arb_mat_entry(E, r, c), prec);
        }
        for (j = a + 1; j <= K; j++)
            for (c = 0; c < m; c++)
                arb_set(arb_mat_entry(Top, r, n + (j - a - 1) * m + c),
                        arb_mat_entry(G, r, j * m + c));
    }
    if (impl && m > 0) {
        /* Top <- (I_n - G_0 C)^{-1} Top = Top + G_0 J^{-1} (C Top)
         * (Woodbury), J = I_m - C G_0 the Newton Jacobian matrix. */
        _jacobian(J, G, Cb, prec);
        arb_mat_mul(CX, Cb, Top, prec);
        if (!arb_mat_solve(Y, J, CX, prec)) {
            arb_t det;
            arb_init(det);
            arb_mat_det(det, J, prec);
            if (arb_is_zero(det))
                rc = rs_error_set(err, RS_ERR_MATH,
                                  "cosim: implicit coupling Jacobian "
                                  "J = I - C G_0 is exactly singular: the "
                                  "corrector is undefined");
            else
                rc = rs_error_set(err, RS_ERR_UNDECIDED,
                                  "cosim: implicit coupling Jacobian "
                                  "J = I - C G_0 not certified invertible at "
                                  "%ld bits", (long) prec);
            arb_clear(det);
            goto cleanup;
        }
        for (r = 0; r < n; r++)
            for (c = 0; c < dim; c++)
                for (j = 0; j < m; j++)
                    arb_addmul(arb_mat_entry(Top, r, c),
                               arb_mat_entry(G, r, j),
                               arb_mat_entry(Y, j, c), prec);
    }
    arb_mat_zero(M);
    for (r = 0; r < n; r++)
        for (c = 0; c < dim; c++)
            arb_set(arb_mat_entry(M, r, c), arb_mat_entry(Top, r, c));
    if (h > 0 && m > 0) {
        /* new u_N = C z_N, older u's shift down one slot */
        for (r = 0; r < m; r++)
            for (c = 0; c < n; c++)
                arb_set(arb_mat_entry(M, n + r, c), arb_mat_entry(Cb, r, c));
        for (j = 1; j < h; j++)
            for (r = 0; r < m; r++)
                arb_one(arb_mat_entry(M, n + j * m + r, n + (j - 1) * m + r));
    }
cleanup:
    arb_mat_clear(E);
    arb_mat_clear(G);
    arb_mat_clear(Cb);
    arb_mat_clear(Top);
    arb_mat_clear(CX);
    arb_mat_clear(J);
    arb_mat_clear(Y);
    return rc;
}

int rs_cosim_transition(arb_mat_t M, const rs_cosim_t cs, slong prec,
                        rs_error_t err)
{
    rs_cosim_ball_t b;
    int rc = rs_cosim_check(cs, err);
    if (rc != RS_OK)
        return rc;
    if (cs->ext != RS_COSIM_EXT_NONE)
        return rs_cosim_ext_transition(M, cs, prec, err);
    rs_cosim_ball_init(b);
    _own_ball(b, cs, prec);
    rc = rs_cosim_ball_transition(M, b, prec, err);
    rs_cosim_ball_clear(b);
    return rc;
}

int rs_cosim_reduce(fmpq_mat_t P1, fmpq_mat_t P2, fmpq_mat_t Q, slong *rank,
                    const rs_cosim_t cs, rs_error_t err)
{
    slong n1, n, m, r, c, i, rk, *piv;
    fmpq_mat_t B, BC, R;
    int rc = rs_cosim_check(cs, err);
    if (rc != RS_OK)
        return rc;
    n1 = cs->n1;
    n = n1 + cs->n2;
    m = cs->m;
    fmpq_mat_init(B, n, m);
    fmpq_mat_init(BC, n, n);
    fmpq_mat_init(R, n, n);
    for (r = 0; r < n; r++)
        for (c = 0; c < m; c++)
            fmpq_set(fmpq_mat_entry(B, r, c),
                     r < n1 ? fmpq_mat_entry(cs->B1, r, c)
                            : fmpq_mat_entry(cs->B2, r - n1, c));
    fmpq_mat_mul(BC, B, cs->C);
    rk = fmpq_mat_rref(R, BC);
    fmpq_mat_clear(P1);
    fmpq_mat_clear(P2);
    fmpq_mat_clear(Q);
    fmpq_mat_init(P1, n1, rk);
    fmpq_mat_init(P2, n - n1, rk);
    fmpq_mat_init(Q, rk, n);
    if (rk == m) {
        /* rank(B C) = m forces rank B = rank C = m: (B, C) is already a
         * rank factorisation */
        fmpq_mat_set(P1, cs->B1);
        fmpq_mat_set(P2, cs->B2);
        fmpq_mat_set(Q, cs->C);
    } else {
        /* B C = (B C)[:, pivots] R[0..rk-1, :] */
        piv = flint_malloc((rk + 1) * sizeof(slong));
        for (i = 0, c = 0; i < rk; i++) {
            while (fmpq_is_zero(fmpq_mat_entry(R, i, c)))
                c++;
            piv[i] = c;
        }
        for (i = 0; i < rk; i++) {
            for (r = 0; r < n; r++)
                fmpq_set(r < n1 ? fmpq_mat_entry(P1, r, i)
                                : fmpq_mat_entry(P2, r - n1, i),
                         fmpq_mat_entry(BC, r, piv[i]));
            for (c = 0; c < n; c++)
                fmpq_set(fmpq_mat_entry(Q, i, c), fmpq_mat_entry(R, i, c));
        }
        flint_free(piv);
    }
    *rank = rk;
    fmpq_mat_clear(B);
    fmpq_mat_clear(BC);
    fmpq_mat_clear(R);
    return RS_OK;
}

/* ------------------------------------------------------------------ */
/* monolithic reference                                                */

int rs_cosim_monolithic_matrix(fmpq_mat_t Amono, const rs_cosim_t cs,
                               rs_error_t err)
{
    slong n1, n, r, c, i;
    fmpq_t t;
    int rc = rs_cosim_check(cs, err);
    if (rc != RS_OK)
        return rc;
    n1 = cs->n1;
    n = n1 + cs->n2;
    if (fmpq_mat_nrows(Amono) != n || fmpq_mat_ncols(Amono) != n)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: A_mono must be %ldx%ld", (long) n,
                            (long) n);
    fmpq_init(t);
    fmpq_mat_zero(Amono);
    for (r = 0; r < n; r++) {
        for (c = 0; c < n; c++) {
            fmpq *e = fmpq_mat_entry(Amono, r, c);
            for (i = 0; i < cs->m; i++) {
                const fmpq *b = (r < n1) ? fmpq_mat_entry(cs->B1, r, i)
                                         : fmpq_mat_entry(cs->B2, r - n1, i);
                fmpq_mul(t, b, fmpq_mat_entry(cs->C, i, c));
                fmpq_add(e, e, t);
            }
            if (r < n1 && c < n1)
                fmpq_add(e, e, fmpq_mat_entry(cs->A1, r, c));
            else if (r >= n1 && c >= n1)
                fmpq_add(e, e, fmpq_mat_entry(cs->A2, r - n1, c - n1));
        }
    }
    fmpq_clear(t);
    return RS_OK;
}

int rs_cosim_monolithic(arb_mat_t Emono, const rs_cosim_t cs, slong prec,
                        rs_error_t err)
{
    slong n;
    fmpq_mat_t Am;
    arb_mat_t Ab;
    int rc = rs_cosim_check(cs, err);
    if (rc != RS_OK)
        return rc;
    n = cs->n1 + cs->n2;
    if (arb_mat_nrows(Emono) != n || arb_mat_ncols(Emono) != n)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: e^{A_mono H} must be %ldx%ld", (long) n,
                            (long) n);
    fmpq_mat_init(Am, n, n);
    arb_mat_init(Ab, n, n);
    rc = rs_cosim_monolithic_matrix(Am, cs, err);
    if (rc == RS_OK) {
        fmpq_mat_scalar_mul_fmpq(Am, Am, cs->H);
        arb_mat_set_fmpq_mat(Ab, Am, prec);
        arb_mat_exp(Emono, Ab, prec);
    }
    arb_mat_clear(Ab);
    fmpq_mat_clear(Am);
    return rc;
}

/* ------------------------------------------------------------------ */
/* certified radius with adaptive precision                            */

enum { _ROUTE_TRANSITION, _ROUTE_RECURRENCE, _ROUTE_MONO };

/* A[0] = -M, A[1] = I (M is negated in place) */
static void _set_poly(acb_mat_struct **A, slong *k, slong *cnt, arb_mat_t M)
{
    slong dim = arb_mat_nrows(M);
    arb_mat_neg(M, M);
    *A = flint_malloc(2 * sizeof(acb_mat_struct));
    acb_mat_init(*A, dim, dim);
    acb_mat_init(*A + 1, dim, dim);
    acb_mat_set_arb_mat(*A, M);
    acb_mat_one(*A + 1);
    *k = 1;
    *cnt = 2;
}

/* Build the acb matrix polynomial A[0..*k] for the route at prec.
 * *A is (re)allocated; *k and *cnt updated. */
static int _build(acb_mat_struct **A, slong *k, slong *cnt, int route,
                  const rs_cosim_t cs, slong prec, rs_error_t err)
{
    slong j, dim, n = cs->n1 + cs->n2;
    int rc = RS_OK;

    for (j = 0; j < *cnt; j++)
        acb_mat_clear(*A + j);
    flint_free(*A);
    *A = NULL;
    *cnt = 0;
    if (route == _ROUTE_RECURRENCE) {
        rs_cosim_rec_t rec;
        rs_cosim_rec_init(rec);
        rc = rs_cosim_recurrence(rec, cs, prec, err);
        if (rc == RS_OK && cs->method == RS_COSIM_IMPLICIT
            && arb_contains_zero(rec->jac))
            rc = arb_is_zero(rec->jac)
                     ? rs_error_set(err, RS_ERR_MATH,
                                    "cosim: implicit coupling Jacobian "
                                    "det(I - C G_0) is exactly 0")
                     : rs_error_set(err, RS_ERR_UNDECIDED,
                                    "cosim: implicit coupling Jacobian not "
                                    "certified nonzero at %ld bits",
                                    (long) prec);
        if (rc == RS_OK) {
            *A = flint_malloc((rec->k + 1) * sizeof(acb_mat_struct));
            for (j = 0; j <= rec->k; j++) {
                acb_mat_init(*A + j, n, n);
                acb_mat_set_arb_mat(*A + j, rec->A + j);
            }
            *k = rec->k;
            *cnt = rec->k + 1;
        }
        rs_cosim_rec_clear(rec);
        return rc;
    }
    if (route == _ROUTE_TRANSITION && cs->ext != RS_COSIM_EXT_NONE) {
        /* D-/I-extension: the n x n one-step map of z_N (cosim_ext.c) */
        arb_mat_t M;
        arb_mat_init(M, n, n);
        rc = rs_cosim_ext_transition(M, cs, prec, err);
        if (rc == RS_OK)
            _set_poly(A, k, cnt, M);
        arb_mat_clear(M);
        return rc;
    }
    if (route == _ROUTE_TRANSITION) {
        /* the reduced realisation (rs_cosim_reduce) */
        fmpq_mat_t P1, P2, Q;
        rs_cosim_ball_t b;
        arb_mat_t M;
        slong rk = 0;
        fmpq_mat_init(P1, 0, 0);
        fmpq_mat_init(P2, 0, 0);
        fmpq_mat_init(Q, 0, 0);
        rc = rs_cosim_reduce(P1, P2, Q, &rk, cs, err);
        if (rc == RS_OK) {
            rs_cosim_ball_init(b);
            rs_cosim_ball_set(b, cs, P1, P2, Q, rk, prec);
            dim = n + _hist(cs) * rk;
            arb_mat_init(M, dim, dim);
            rc = rs_cosim_ball_transition(M, b, prec, err);
            if (rc == RS_OK)
                _set_poly(A, k, cnt, M);
            arb_mat_clear(M);
            rs_cosim_ball_clear(b);
        }
        fmpq_mat_clear(P1);
        fmpq_mat_clear(P2);
        fmpq_mat_clear(Q);
        return rc;
    }
    {
        arb_mat_t M;
        dim = n;
        arb_mat_init(M, dim, dim);
        rc = rs_cosim_monolithic(M, cs, prec, err);
        if (rc == RS_OK)
            _set_poly(A, k, cnt, M);
        arb_mat_clear(M);
    }
    return rc;
}

static int _radius(rs_radius_t r, const rs_cosim_t cs, int route,
                   slong digits, slong max_prec, rs_error_t err)
{
    acb_mat_struct *A = NULL;
    slong k = 0, cnt = 0, prec, j;
    int rc = rs_cosim_check(cs, err);

    if (rc != RS_OK)
        return rc;
    if (digits < 1)
        return rs_error_set(err, RS_ERR_INPUT,
                            "cosim: digits must be >= 1 (got %ld)",
                            (long) digits);
    if (max_prec <= 0)
        max_prec = RS_RADIUS_MAX_PREC_DEFAULT;
    /* input accuracy: the requested digits plus a margin for the loss in
     * the exponential and the eigenvalue condition; doubled on demand */
    prec = (slong) (digits * 3.3219280948873623) + 64;
    if (prec > max_prec)
        prec = max_prec;
    for (;;) {
        int retry;
        if ((rc = rs_budget_check(err, "the co-simulation radius")) != RS_OK) break;
        rc = _build(&A, &k, &cnt, route, cs, prec, err);
        if (rc == RS_OK) {
            rc = rs_radius_matrix_poly(r, A, k, digits, max_prec, err);
            /* RS_ERR_MATH there: leading matrix (I - G_0 C) not certified
             * invertible at this input accuracy; exact singularity was
             * already excluded through J, so sharper input can help */
            retry = (rc == RS_ERR_UNDECIDED || rc == RS_ERR_MATH);
        } else {
            /* J not certified nonzero at this precision: retry; J == 0
             * exactly or bad input: final */
            retry = (rc == RS_ERR_UNDECIDED);
        }
        if (!retry || prec >= max_prec)
            break;
        prec = (prec > max_prec / 2) ? max_prec : 2 * prec;
    }
    for (j = 0; j < cnt; j++)
        acb_mat_clear(A + j);
    flint_free(A);
    return rc;
}

int rs_cosim_radius(rs_radius_t r, const rs_cosim_t cs, slong digits,
                    slong max_prec, rs_error_t err)
{
    return _radius(r, cs, _ROUTE_TRANSITION, digits, max_prec, err);
}

int rs_cosim_radius_recurrence(rs_radius_t r, const rs_cosim_t cs,
                               slong digits, slong max_prec, rs_error_t err)
{
    return _radius(r, cs, _ROUTE_RECURRENCE, digits, max_prec, err);
}

int rs_cosim_monolithic_radius(rs_radius_t r, const rs_cosim_t cs,
                               slong digits, slong max_prec, rs_error_t err)
{
    return _radius(r, cs, _ROUTE_MONO, digits, max_prec, err);
}
