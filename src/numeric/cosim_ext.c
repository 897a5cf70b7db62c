/* cosim_ext.c -- the D-/I-extension couplings (reading and contract in
 * numeric/cosim_ext.h).
 *
 * Derivation.  Unknowns w = (z_N, u_{N+a}, u_{N+1}) (n + 2m); the samples
 * V_0 = u_N = C z_N, V_1 = u_{N+a}, V_2 = u_{N+1} are rows W_j w.  On each
 * piece of the interpolant (length h_p = frac_p H, local sigma in [0, 1])
 * u = sum_k c_k sigma^k with c_k = sum_j L_p[k][j] V_j.  Each subsystem is
 * augmented with the integral of its state (q' = z, q(T_N) = 0), so one
 * Van Loan exponential per piece (rs_cosim_exp_phi of the augmented model
 * at step h_p) gives both z and int z: y(end) = E_p y(start) + sum_k
 * Phi_k c_k.  Carried as a matrix Y acting on w, z*_{N+1} = Z w and
 * int z* = Q w.  The conditions R w = 0 (2m rows):
 *   g   = W_2 - C Z
 *   D:  (1/h_last) sum_k k c_k(last piece) - C (A Z + B W_2)
 *   I:  sum_p h_p sum_k c_k(p)/(k + 1) - C Q
 * Split R = [R_z | R_X]: X = -R_X^{-1} R_z z_N and M = Z_z - Z_X R_X^{-1} R_z. */
#include "numeric/cosim_ext.h"

int rs_cosim_ext_check(const rs_cosim_t cs, rs_error_t err)
{
    if (cs->ext == RS_COSIM_EXT_NONE) return RS_OK;
    if (cs->ext != RS_COSIM_EXT_D && cs->ext != RS_COSIM_EXT_I)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: unknown extension %d (D = %d, I = %d)", cs->ext,
                            RS_COSIM_EXT_D, RS_COSIM_EXT_I);
    if (cs->method != RS_COSIM_IMPLICIT)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: the D-/I-extension is a corrector: it needs the implicit "
                            "method%s", "");
    if (cs->order > RS_COSIM_EXT_MAX_ORDER)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: extension couplings are defined for K = 0, 1, 2 (got K = %ld)",
                            (long) cs->order);
    if (fmpq_sgn(cs->alpha_T) <= 0 || fmpq_cmp_si(cs->alpha_T, 1) >= 0)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: alpha_T must lie strictly between 0 and 1%s", "");
    return RS_OK;
}

/* the pieces of the interpolant for order K, sample point a: their length
 * fractions, degrees and coefficient maps L_p ((deg + 1) x 3, row k =
 * coefficient of sigma^k in terms of the samples V_0, V_1, V_2) */
static slong pieces(fmpq *frac, slong *deg, fmpq_mat_struct *L, slong K, const fmpq_t a)
{
    fmpq_t t, u;
    fmpq_init(t);
    fmpq_init(u);
    if (K == 2) {
        /* Lagrange through tau = 0, a, 1:
         * l0 = (tau^2 - (1+a) tau + a)/a, l1 = (tau^2 - tau)/(a(a-1)), l2 = (tau^2 - a tau)/(1-a) */
        fmpq_one(frac);
        deg[0] = 2;
        fmpq_mat_init(L, 3, 3);
        fmpq_one(fmpq_mat_entry(L, 0, 0));
        fmpq_add_si(t, a, 1);
        fmpq_div(t, t, a);
        fmpq_neg(fmpq_mat_entry(L, 1, 0), t);                /* -(1+a)/a */
        fmpq_sub_si(u, a, 1);
        fmpq_mul(u, u, a);                                   /* a(a-1) */
        fmpq_inv(fmpq_mat_entry(L, 2, 1), u);                /* 1/(a(a-1)) */
        fmpq_neg(fmpq_mat_entry(L, 1, 1), fmpq_mat_entry(L, 2, 1));
        fmpq_inv(fmpq_mat_entry(L, 2, 0), a);                /* 1/a */
        fmpq_sub_si(u, a, 1);
        fmpq_neg(u, u);                                      /* 1 - a */
        fmpq_inv(fmpq_mat_entry(L, 2, 2), u);                /* 1/(1-a) */
        fmpq_div(t, a, u);
        fmpq_neg(fmpq_mat_entry(L, 1, 2), t);                /* -a/(1-a) */
        fmpq_clear(t);
        fmpq_clear(u);
        return 1;
    }
    fmpq_set(frac, a);
    fmpq_sub_si(frac + 1, a, 1);
    fmpq_neg(frac + 1, frac + 1);
    deg[0] = deg[1] = K;
    fmpq_mat_init(L, K + 1, 3);
    fmpq_mat_init(L + 1, K + 1, 3);
    if (K == 0) {
        /* hold from the right: u_{N+a} on the first piece, u_{N+1} on the second */
        fmpq_one(fmpq_mat_entry(L, 0, 1));
        fmpq_one(fmpq_mat_entry(L + 1, 0, 2));
    } else {
        /* V_0 + (V_1 - V_0) sigma, then V_1 + (V_2 - V_1) sigma */
        fmpq_one(fmpq_mat_entry(L, 0, 0));
        fmpq_set_si(fmpq_mat_entry(L, 1, 0), -1, 1);
        fmpq_one(fmpq_mat_entry(L, 1, 1));
        fmpq_one(fmpq_mat_entry(L + 1, 0, 1));
        fmpq_set_si(fmpq_mat_entry(L + 1, 1, 1), -1, 1);
        fmpq_one(fmpq_mat_entry(L + 1, 1, 2));
    }
    fmpq_clear(t);
    fmpq_clear(u);
    return 2;
}

/* augmented position of z_j and of its integral q_j: (z1, q1, z2, q2) */
static slong zi(const rs_cosim_ball_t b, slong j) { return j < b->n1 ? j : 2 * b->n1 + (j - b->n1); }
static slong qi(const rs_cosim_ball_t b, slong j) { return j < b->n1 ? b->n1 + j : 2 * b->n1 + b->n2 + (j - b->n1); }

/* subsystem i augmented with q' = z: [[A_i, 0], [I, 0]], [B_i; 0] */
static void augment(arb_mat_t Aa, arb_mat_t Ba, const arb_mat_t A, const arb_mat_t B)
{
    slong ni = arb_mat_nrows(A), r, c;
    for (r = 0; r < ni; r++) {
        for (c = 0; c < ni; c++) arb_set(arb_mat_entry(Aa, r, c), arb_mat_entry(A, r, c));
        for (c = 0; c < arb_mat_ncols(B); c++) arb_set(arb_mat_entry(Ba, r, c), arb_mat_entry(B, r, c));
        arb_one(arb_mat_entry(Aa, ni + r, r));
    }
}

/* Cw = sum_j L[k][j] W_j (m x nw): W_0 = [C 0 0], W_1 = [0 I 0], W_2 = [0 0 I] */
static void sample_rows(arb_mat_t Cw, const fmpq_mat_t L, slong k, const arb_mat_t Cb, slong n, slong m, slong prec)
{
    slong r, c;
    arb_t l;
    arb_init(l);
    arb_mat_zero(Cw);
    arb_set_fmpq(l, fmpq_mat_entry(L, k, 0), prec);
    for (r = 0; r < m; r++)
        for (c = 0; c < n; c++) arb_mul(arb_mat_entry(Cw, r, c), arb_mat_entry(Cb, r, c), l, prec);
    for (r = 0; r < m; r++) {
        arb_set_fmpq(arb_mat_entry(Cw, r, n + r), fmpq_mat_entry(L, k, 1), prec);
        arb_set_fmpq(arb_mat_entry(Cw, r, n + m + r), fmpq_mat_entry(L, k, 2), prec);
    }
    arb_clear(l);
}

int rs_cosim_ext_transition(arb_mat_t M, const rs_cosim_t cs, slong prec, rs_error_t err)
{
    slong n = cs->n1 + cs->n2;
    rs_cosim_ball_t b;
    int rc = rs_cosim_check(cs, err);
    if (rc != RS_OK) return rc;
    if (cs->ext == RS_COSIM_EXT_NONE || arb_mat_nrows(M) != n || arb_mat_ncols(M) != n)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: extension transition needs an extension and an %ldx%ld matrix",
                            (long) n, (long) n);
    rs_cosim_ball_init(b);
    rs_cosim_ball_set(b, cs, cs->B1, cs->B2, cs->C, cs->m, prec);
    rs_cosim_ball_set_ext(b, cs->ext, cs->alpha_T);
    rc = rs_cosim_ext_ball_transition(M, b, prec, err);
    rs_cosim_ball_clear(b);
    return rc;
}

int rs_cosim_ext_ball_transition_naive(arb_mat_t M, const rs_cosim_ball_t cs, slong prec, rs_error_t err)
{
    slong n = cs->n1 + cs->n2, m = cs->m, nw = n + 2 * m, na = 2 * n, np, p, k, r, c;
    slong deg[2];
    fmpq frac[2];
    fmpq_mat_struct L[2];
    rs_cosim_ball_t aug;
    arb_mat_t Y, Y2, E, Phi, Cw, Pk, Cb, Ab, Bb, Z, Q, R, T, U, Rz, RX, S;
    arb_t f, hp;
    int rc = RS_OK;
    if (cs->ext == RS_COSIM_EXT_NONE || cs->method != RS_COSIM_IMPLICIT || cs->order < 0
        || cs->order > RS_COSIM_EXT_MAX_ORDER || fmpq_sgn(cs->alpha_T) <= 0 || fmpq_cmp_si(cs->alpha_T, 1) >= 0
        || arb_mat_nrows(M) != n || arb_mat_ncols(M) != n)
        return rs_error_set(err, RS_ERR_INPUT, "cosim: extension transition needs the implicit method with an "
                            "extension, K <= 2, 0 < alpha_T < 1 and an %ldx%ld matrix", (long) n, (long) n);
    fmpq_init(frac);
    fmpq_init(frac + 1);
    arb_init(hp);
    np = pieces(frac, deg, L, cs->order, cs->alpha_T);
    rs_cosim_ball_init(aug);
    rs_cosim_ball_set_dims(aug, 2 * cs->n1, 2 * cs->n2, m, RS_COSIM_IMPLICIT, 0);
    augment(aug->A1, aug->B1, cs->A1, cs->B1);
    augment(aug->A2, aug->B2, cs->A2, cs->B2);
    arb_mat_init(Y, na, nw);
    arb_mat_init(Y2, na, nw);
    arb_mat_init(E, na, na);
    arb_mat_init(Cw, m, nw);
    arb_mat_init(Pk, na, m);
    arb_mat_init(Cb, m, n);
    arb_mat_init(Ab, n, n);
    arb_mat_init(Bb, n, m);
    arb_mat_init(Z, n, nw);
    arb_mat_init(Q, n, nw);
    arb_mat_init(R, 2 * m, nw);
    arb_mat_init(T, n, nw);
    arb_mat_init(U, m, nw);
    arb_mat_init(Rz, 2 * m, n);
    arb_mat_init(RX, 2 * m, 2 * m);
    arb_mat_init(S, 2 * m, n);
    arb_init(f);
    arb_mat_set(Cb, cs->C);
    for (r = 0; r < n; r++) {
        slong a1 = r < cs->n1;
        for (c = 0; c < n; c++)
            if ((c < cs->n1) == a1)
                arb_set(arb_mat_entry(Ab, r, c), a1 ? arb_mat_entry(cs->A1, r, c)
                        : arb_mat_entry(cs->A2, r - cs->n1, c - cs->n1));
        for (c = 0; c < m; c++)
            arb_set(arb_mat_entry(Bb, r, c), a1 ? arb_mat_entry(cs->B1, r, c) : arb_mat_entry(cs->B2, r - cs->n1, c));
    }
    /* y(T_N) = (z_N, 0) */
    for (r = 0; r < n; r++) arb_one(arb_mat_entry(Y, zi(cs, r), r));
    for (p = 0; p < np && rc == RS_OK; p++) {
        /* h_p = frac_p H (a ball over a box) */
        arb_mul_fmpz(hp, cs->H, fmpq_numref(frac + p), prec);
        arb_div_fmpz(hp, hp, fmpq_denref(frac + p), prec);
        arb_set(aug->H, hp);
        aug->order = deg[p];
        arb_mat_init(Phi, na, m * (deg[p] + 1));
        rs_cosim_ball_exp_phi(E, Phi, aug, prec);
        if (!arb_mat_is_finite(E) || !arb_mat_is_finite(Phi))
            rc = rs_error_set(err, RS_ERR_UNDECIDED, "cosim: the extension's exponentials are not finite at %ld "
                              "bits", (long) prec);
        if (rc == RS_OK) {
            arb_mat_mul(Y2, E, Y, prec);
            for (k = 0; k <= deg[p]; k++) {
                for (r = 0; r < na; r++)
                    for (c = 0; c < m; c++) arb_set(arb_mat_entry(Pk, r, c), arb_mat_entry(Phi, r, k * m + c));
                sample_rows(Cw, L + p, k, Cb, n, m, prec);
                arb_mat_mul(Y, Pk, Cw, prec);
                arb_mat_add(Y2, Y2, Y, prec);
            }
            arb_mat_set(Y, Y2);
            /* the extension rows of the conditions from this piece */
            if (cs->ext == RS_COSIM_EXT_I)
                for (k = 0; k <= deg[p]; k++) {
                    /* h_p / (k + 1) * c_k */
                    sample_rows(Cw, L + p, k, Cb, n, m, prec);
                    arb_div_ui(f, hp, (ulong) (k + 1), prec);
                    for (r = 0; r < m; r++)
                        for (c = 0; c < nw; c++)
                            arb_addmul(arb_mat_entry(R, m + r, c), arb_mat_entry(Cw, r, c), f, prec);
                }
            else if (p == np - 1)
                for (k = 1; k <= deg[p]; k++) {
                    /* d/dt of c_k sigma^k at sigma = 1: k c_k / h_p */
                    sample_rows(Cw, L + p, k, Cb, n, m, prec);
                    arb_inv(f, hp, prec);
                    arb_mul_ui(f, f, (ulong) k, prec);
                    for (r = 0; r < m; r++)
                        for (c = 0; c < nw; c++)
                            arb_addmul(arb_mat_entry(R, m + r, c), arb_mat_entry(Cw, r, c), f, prec);
                }
        }
        arb_mat_clear(Phi);
    }
    if (rc == RS_OK) {
        for (r = 0; r < n; r++)
            for (c = 0; c < nw; c++) {
                arb_set(arb_mat_entry(Z, r, c), arb_mat_entry(Y, zi(cs, r), c));
                arb_set(arb_mat_entry(Q, r, c), arb_mat_entry(Y, qi(cs, r), c));
            }
        /* g = W_2 - C Z */
        arb_mat_mul(U, Cb, Z, prec);
        for (r = 0; r < m; r++) {
            for (c = 0; c < nw; c++) arb_neg(arb_mat_entry(R, r, c), arb_mat_entry(U, r, c));
            arb_add_ui(arb_mat_entry(R, r, n + m + r), arb_mat_entry(R, r, n + m + r), 1, prec);
        }
        if (cs->ext == RS_COSIM_EXT_I) {
            arb_mat_mul(U, Cb, Q, prec);                     /* - C int z */
        } else {
            arb_mat_mul(T, Ab, Z, prec);                     /* - C (A Z + B W_2) */
            for (r = 0; r < n; r++)
                for (c = 0; c < m; c++)
                    arb_add(arb_mat_entry(T, r, n + m + c), arb_mat_entry(T, r, n + m + c), arb_mat_entry(Bb, r, c),
                            prec);
            arb_mat_mul(U, Cb, T, prec);
        }
        for (r = 0; r < m; r++)
            for (c = 0; c < nw; c++)
                arb_sub(arb_mat_entry(R, m + r, c), arb_mat_entry(R, m + r, c), arb_mat_entry(U, r, c), prec);
        for (r = 0; r < 2 * m; r++) {
            for (c = 0; c < n; c++) arb_set(arb_mat_entry(Rz, r, c), arb_mat_entry(R, r, c));
            for (c = 0; c < 2 * m; c++) arb_set(arb_mat_entry(RX, r, c), arb_mat_entry(R, r, n + c));
        }
        if (!arb_mat_solve(S, RX, Rz, prec)) {
            arb_mat_det(f, RX, prec);
            rc = arb_is_zero(f) ? rs_error_set(err, RS_ERR_MATH, "cosim: the Jacobian of the extended coupling "
                                               "conditions is exactly singular: the corrector is undefined%s", "")
                 : rs_error_set(err, RS_ERR_UNDECIDED, "cosim: the Jacobian of the extended coupling conditions is "
                                "not certified invertible at %ld bits", (long) prec);
        }
    }
    if (rc == RS_OK) {
        /* M = Z_z - Z_X S */
        for (r = 0; r < n; r++)
            for (c = 0; c < n; c++) {
                arb_set(arb_mat_entry(M, r, c), arb_mat_entry(Z, r, c));
                for (k = 0; k < 2 * m; k++)
                    arb_submul(arb_mat_entry(M, r, c), arb_mat_entry(Z, r, n + k), arb_mat_entry(S, k, c), prec);
            }
    }
    for (p = 0; p < np; p++) fmpq_mat_clear(L + p);
    fmpq_clear(frac);
    fmpq_clear(frac + 1);
    rs_cosim_ball_clear(aug);
    arb_mat_clear(Y); arb_mat_clear(Y2); arb_mat_clear(E); arb_mat_clear(Cw); arb_mat_clear(Pk);
    arb_mat_clear(Cb); arb_mat_clear(Ab); arb_mat_clear(Bb); arb_mat_clear(Z); arb_mat_clear(Q);
    arb_mat_clear(R); arb_mat_clear(T); arb_mat_clear(U); arb_mat_clear(Rz); arb_mat_clear(RX);
    arb_mat_clear(S);
    arb_clear(f);
    arb_clear(hp);
    return rc;
}

/* ---- the centred (mean-value) form over a box ------------------------------
 * The naive ball map above loses every dependency between the entries (two
 * exponentials, a Jacobian inverse), so its width grows far faster than the
 * box.  Mean-value form over the entries e of (A1, A2, B1, B2, C) whose balls
 * are wide (the box's parameters; H and exact constants stay balls in every
 * evaluation): for each model x in b, with x' = x but the wide entries at
 * their midpoints, T(x) - T(x') = int_0^1 sum_e dT/de(x' + t (x - x'))
 * (x_e - mid_e) dt, so T(b) is enclosed in T(mid) + sum_e dT/de(b) [+-rad_e].
 * dT/de(b) comes from the same engine on the dual-number model: X + eps Y ->
 * [[X, Y], [0, X]] is an algebra homomorphism (products, inverses, solves,
 * exponentials and the Phi integrals all commute with it), so the map of the
 * 2n-state / 2m-variable model with A'' = [[A, dA], [0, A]] (per subsystem),
 * B'' = [[B, dB], [0, B]], C'' = [[C, dC], [0, C]] is [[T, dT], [0, T]] with
 * the states reordered per subsystem; dX = the unit matrix at e. */

/* position of global state j (n = n1 + n2) in the dual model: top or bottom copy */
static slong dual_top(const rs_cosim_ball_t b, slong j) { return j < b->n1 ? j : 2 * b->n1 + (j - b->n1); }
static slong dual_bot(const rs_cosim_ball_t b, slong j) { return j < b->n1 ? b->n1 + j : 2 * b->n1 + b->n2 + (j - b->n1); }

/* the entry e of b: 0 A1, 1 A2, 2 B1, 3 B2, 4 C */
static arb_mat_struct *ball_mat(const rs_cosim_ball_t b, int which)
{
    const arb_mat_struct *t[5] = {b->A1, b->A2, b->B1, b->B2, b->C};
    return (arb_mat_struct *) t[which];
}

/* X'' = [[X, dX], [0, X]] with dX the unit matrix at (er, ec) when dir, else 0 */
static void dual_block(arb_mat_t X2, const arb_mat_t X, int dir, slong er, slong ec)
{
    slong R = arb_mat_nrows(X), C = arb_mat_ncols(X), r, c;
    for (r = 0; r < R; r++)
        for (c = 0; c < C; c++) {
            arb_set(arb_mat_entry(X2, r, c), arb_mat_entry(X, r, c));
            arb_set(arb_mat_entry(X2, R + r, C + c), arb_mat_entry(X, r, c));
        }
    if (dir) arb_one(arb_mat_entry(X2, er, C + ec));
}

/* d = the derivative of the map of b with respect to entry (which, er, ec), over b */
static int ext_dual(arb_mat_t d, const rs_cosim_ball_t b, int which, slong er, slong ec, slong prec, rs_error_t err)
{
    slong n = b->n1 + b->n2, m = b->m, r, c;
    rs_cosim_ball_t b2;
    arb_mat_t M2;
    int rc;
    rs_cosim_ball_init(b2);
    rs_cosim_ball_set_dims(b2, 2 * b->n1, 2 * b->n2, 2 * m, b->method, b->order);
    rs_cosim_ball_set_ext(b2, b->ext, b->alpha_T);
    arb_set(b2->H, b->H);
    dual_block(b2->A1, b->A1, which == 0, er, ec);
    dual_block(b2->A2, b->A2, which == 1, er, ec);
    dual_block(b2->B1, b->B1, which == 2, er, ec);
    dual_block(b2->B2, b->B2, which == 3, er, ec);
    /* C'' columns in the per-subsystem order of the states */
    for (r = 0; r < m; r++)
        for (c = 0; c < n; c++) {
            arb_set(arb_mat_entry(b2->C, r, dual_top(b, c)), arb_mat_entry(b->C, r, c));
            arb_set(arb_mat_entry(b2->C, m + r, dual_bot(b, c)), arb_mat_entry(b->C, r, c));
        }
    if (which == 4) arb_one(arb_mat_entry(b2->C, er, dual_bot(b, ec)));
    arb_mat_init(M2, 2 * n, 2 * n);
    rc = rs_cosim_ext_ball_transition_naive(M2, b2, prec, err);
    if (rc == RS_OK)
        for (r = 0; r < n; r++)
            for (c = 0; c < n; c++) arb_set(arb_mat_entry(d, r, c), arb_mat_entry(M2, dual_top(b, r), dual_bot(b, c)));
    arb_mat_clear(M2);
    rs_cosim_ball_clear(b2);
    return rc;
}

/* a box coordinate: an entry wider than half the working precision (exact
 * constants rounded to prec are not, and stay balls in every evaluation) */
static int is_wide(const arb_t x, slong prec)
{
    return !mag_is_zero(arb_radref(x)) && arb_rel_accuracy_bits(x) < prec / 2;
}

int rs_cosim_ext_ball_transition_centred(arb_mat_t M, const rs_cosim_ball_t b, slong prec, rs_error_t err)
{
    slong n = b->n1 + b->n2, r, c, i, j, nd = 0;
    rs_cosim_ball_t bm;
    arb_mat_t D;
    arb_t dev;
    int which, rc;
    if (b->ext == RS_COSIM_EXT_NONE || arb_mat_nrows(M) != n || arb_mat_ncols(M) != n)
        return rs_cosim_ext_ball_transition_naive(M, b, prec, err);   /* its input error */
    /* the midpoint model: the wide entries at their midpoints */
    rs_cosim_ball_init(bm);
    rs_cosim_ball_set_dims(bm, b->n1, b->n2, b->m, b->method, b->order);
    rs_cosim_ball_set_ext(bm, b->ext, b->alpha_T);
    arb_set(bm->H, b->H);
    for (which = 0; which < 5; which++) {
        arb_mat_struct *X = ball_mat(b, which), *Y = ball_mat(bm, which);
        for (i = 0; i < arb_mat_nrows(X); i++)
            for (j = 0; j < arb_mat_ncols(X); j++) {
                arb_set(arb_mat_entry(Y, i, j), arb_mat_entry(X, i, j));
                if (is_wide(arb_mat_entry(X, i, j), prec)) {
                    mag_zero(arb_radref(arb_mat_entry(Y, i, j)));
                    nd++;
                }
            }
    }
    rc = rs_cosim_ext_ball_transition_naive(M, bm, prec, err);
    arb_mat_init(D, n, n);
    arb_init(dev);
    for (which = 0; which < 5 && rc == RS_OK && nd > 0; which++) {
        arb_mat_struct *X = ball_mat(b, which);
        for (i = 0; i < arb_mat_nrows(X) && rc == RS_OK; i++)
            for (j = 0; j < arb_mat_ncols(X) && rc == RS_OK; j++) {
                if (!is_wide(arb_mat_entry(X, i, j), prec)) continue;
                rc = ext_dual(D, b, which, i, j, prec, err);
                /* + dT/de(b) [+- rad_e] */
                arb_zero(dev);
                mag_set(arb_radref(dev), arb_radref(arb_mat_entry(X, i, j)));
                for (r = 0; r < n && rc == RS_OK; r++)
                    for (c = 0; c < n; c++)
                        arb_addmul(arb_mat_entry(M, r, c), arb_mat_entry(D, r, c), dev, prec);
            }
    }
    arb_clear(dev);
    arb_mat_clear(D);
    rs_cosim_ball_clear(bm);
    return rc;
}

/* the number of wide entries of b (the box's coordinates) */
static slong count_wide(const rs_cosim_ball_t b, slong prec)
{
    slong nd = 0, i, j;
    int which;
    for (which = 0; which < 5; which++) {
        arb_mat_struct *X = ball_mat(b, which);
        for (i = 0; i < arb_mat_nrows(X); i++)
            for (j = 0; j < arb_mat_ncols(X); j++) nd += is_wide(arb_mat_entry(X, i, j), prec);
    }
    return nd;
}

int rs_cosim_ext_ball_transition(arb_mat_t M, const rs_cosim_ball_t b, slong prec, rs_error_t err)
{
    slong n = b->n1 + b->n2, r, c;
    arb_mat_t Mc;
    rs_error_t e2;
    int rc = rs_cosim_ext_ball_transition_naive(M, b, prec, err);
    /* a point model (rs_cosim_ext_transition): nothing to centre */
    if (rc != RS_OK || count_wide(b, prec) == 0) return rc;
    /* both enclose the same maps: keep their intersection (the centred form
     * failing, e.g. a Jacobian not certified over the box, leaves the naive);
     * disjoint enclosures mean one of the two is wrong */
    arb_mat_init(Mc, n, n);
    rs_error_init(e2);
    if (rs_cosim_ext_ball_transition_centred(Mc, b, prec, e2) == RS_OK)
        for (r = 0; r < n && rc == RS_OK; r++)
            for (c = 0; c < n && rc == RS_OK; c++) {
                arb_ptr x = arb_mat_entry(M, r, c);
                arb_t t;
                arb_init(t);
                if (arb_intersection(t, x, arb_mat_entry(Mc, r, c), prec)) arb_swap(x, t);
                else rc = rs_error_set(err, RS_ERR_INCONSISTENT, "cosim: the naive and the centred enclosures of "
                                       "the extension's box map are disjoint at entry (%ld, %ld)", (long) r, (long) c);
                arb_clear(t);
            }
    arb_mat_clear(Mc);
    rs_error_clear(e2);
    return rc;
}
