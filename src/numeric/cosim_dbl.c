/* cosim_dbl.c -- see numeric/cosim_dbl.h.  Error model (round to nearest,
 * u = 2^-53, eta = 2^-1074 the smallest subnormal): a computed dot product
 * of n terms is within gamma_n sum |a_k b_k| (+ n eta underflow) of the
 * exact one (Higham, Accuracy and Stability, 2nd ed., eq. (3.5)); a
 * computed sum of nonnegative terms underestimates the exact one by at most
 * the factor 1 - gamma_n.  Every radius below is therefore formed as
 * (computed bound) * (1 + slack) + eta-terms, slack >= 2 (n + 4) u, a
 * generous a priori factor (no rounding-mode switches: thread safe).  An
 * overflow or NaN anywhere ends in RS_ERR_UNDECIDED (checked at the end). */
#include <float.h>
#include <math.h>
#include <string.h>
#include "numeric/cosim_dbl.h"

#define U_ (0x1p-53)
#define ETA_ (DBL_TRUE_MIN)

/* the safety factor of a bound built from about n roundings */
static inline double up_(double x, slong n)
{
    return x * (1.0 + 4.0 * (double) (n + 4) * U_) + 4.0 * (double) (n + 2) * ETA_;
}

/* Scratch of a map point: the caller's stack array when n doubles fit (a
 * point of the bench maps needs a few hundred; no malloc per point and no
 * shared state between threads), else the heap. */
#define STK_ 2048
static double *scratch_get(double *stk, slong n)
{
    return n <= STK_ ? stk : flint_malloc((size_t) n * sizeof(double));
}

static void scratch_put(double *p, const double *stk)
{
    if (p != stk) flint_free(p);
}

/* ---- interval matrices: mid/rad arrays, row major ----------------------- */

/* C (r x c) = A (r x k) B (k x c); Ar or Br NULL: a point matrix.  C may not
 * alias A or B.  Per entry: mid = the computed dot product, rad = gamma_k
 * sum |a_il b_lj| (its rounding) + sum (|a| rb + ra (|b| + rb)) (the
 * inputs' radii), with the safety factor (the loops split by case so that
 * the compiler vectorises them: this is the hot spot of a map point). */
static void imul(double *restrict Cm, double *restrict Cr, const double *restrict Am, const double *restrict Ar,
                 const double *restrict Bm, const double *restrict Br, slong r, slong k, slong c)
{
    slong i, j, l;
    double g = 2.0 * (double) (k + 1) * U_;   /* >= gamma_k / (1 - gamma_k) */
    for (i = 0; i < r * c; i++) Cm[i] = Cr[i] = 0;
    for (i = 0; i < r; i++)
        for (l = 0; l < k; l++) {
            const double x = Am[i * k + l], ax = fabs(x), xr = Ar != NULL ? Ar[i * k + l] : 0;
            const double *restrict bm = Bm + l * c;
            double *restrict cm = Cm + i * c, *restrict cr = Cr + i * c;
            if (Br != NULL) {
                const double *restrict br = Br + l * c;
                for (j = 0; j < c; j++) {
                    double y = bm[j];
                    cm[j] += x * y;
                    cr[j] += g * fabs(x * y) + ax * br[j] + xr * (fabs(y) + br[j]);
                }
            } else
                for (j = 0; j < c; j++) {
                    double y = bm[j];
                    cm[j] += x * y;
                    cr[j] += g * fabs(x * y) + xr * fabs(y);
                }
        }
    for (i = 0; i < r * c; i++) Cr[i] = up_(Cr[i], 2 * k + 2);
}

/* C = A + s B (s = +-1), entrywise */
static void iadd(double *Cm, double *Cr, const double *Am, const double *Ar, const double *Bm, const double *Br,
                 slong len, double s)
{
    slong i;
    for (i = 0; i < len; i++) {
        double x = Am[i] + s * Bm[i];
        Cr[i] = up_(Ar[i] + Br[i] + U_ * fabs(x), 2);
        Cm[i] = x;
    }
}

/* C = a X, a = am +- ar an interval scalar (C may alias X) */
static void iscal(double *Cm, double *Cr, const double *Xm, const double *Xr, double am, double ar, slong len)
{
    slong i;
    for (i = 0; i < len; i++) {
        double x = am * Xm[i];
        Cr[i] = up_(fabs(am) * Xr[i] + ar * (fabs(Xm[i]) + Xr[i]) + U_ * fabs(x), 3);
        Cm[i] = x;
    }
}

/* an upper bound of the infinity norm of every matrix in (M, R), r x c */
static double inorm(const double *Mm, const double *Mr, slong r, slong c)
{
    slong i, j;
    double mx = 0;
    for (i = 0; i < r; i++) {
        double s = 0;
        for (j = 0; j < c; j++) s += fabs(Mm[i * c + j]) + (Mr != NULL ? Mr[i * c + j] : 0);
        s = up_(s, 2 * c);
        if (!(s <= mx)) mx = s;   /* NaN propagates */
    }
    return mx;
}

static int all_finite(const double *x, slong len)
{
    slong i;
    for (i = 0; i < len; i++)
        if (!isfinite(x[i])) return 0;
    return 1;
}

/* (Em, Er) = exp(X) for every X in (Xm, Xr), s x s: scaling so that
 * ||X / 2^j|| <= 1/2, the Taylor polynomial of degree N in interval
 * arithmetic, plus the remainder bound on every entry, then j squarings.
 * The polynomial by Paterson-Stockmeyer: the powers Y^2 .. Y^t (t =
 * ceil sqrt(N + 1)), blocks B_b = sum_a c_{bt+a} Y^a (c_i = 1/i! as
 * intervals), Horner in Z = Y^t: t - 1 + N/t products instead of N.
 * 0 on overflow / a norm too large. */
static int iexp(double *Em, double *Er, const double *Xm, const double *Xr, slong s)
{
    slong len = s * s, i, k, N, j = 0, t, a, b, nb;
    double nu = inorm(Xm, Xr, s, s), sc, term, rem, cm[41], cr[41];
    double *buf, *Pm, *Pr, *Qm, *Qr, *Bm, *Br, *Wm, *Wr, *Ym[8], *Yr[8], stk[STK_];
    int ok = 1;
    if (!isfinite(nu)) return 0;
    while (nu > 0.5) {
        nu *= 0.5;   /* exact */
        if (++j > 200) return 0;
    }
    /* N: nu^{N+1} / (N+1)! below 2^-62 (term computed with upward slack) */
    term = nu;
    for (N = 1; N < 40; N++) {
        term = up_(term * nu / (double) (N + 1), 4);
        if (term < 0x1p-62) break;
    }
    /* remainder of every matrix Y with ||Y|| <= nu: term / (1 - nu / (N + 2)) */
    rem = up_(term / (1.0 - nu / (double) (N + 2)), 6);
    for (t = 1; t * t < N + 1; t++) {}
    /* c_i = 1/i!: the computed quotient within u of the exact one of the
     * previous interval's midpoint */
    cm[0] = 1;
    cr[0] = 0;
    for (i = 1; i <= N; i++) {
        cm[i] = cm[i - 1] / (double) i;
        cr[i] = up_(cr[i - 1] / (double) i + U_ * cm[i], 3);
    }
    buf = scratch_get(stk, (2 * (t + 1) + 8) * len);
    for (a = 0; a <= t; a++) {
        Ym[a] = buf + 2 * a * len;
        Yr[a] = Ym[a] + len;
    }
    Pm = buf + 2 * (t + 1) * len;
    Pr = Pm + len;
    Qm = Pr + len;
    Qr = Qm + len;
    Bm = Qr + len;
    Br = Bm + len;
    Wm = Br + len;
    Wr = Wm + len;
    sc = ldexp(1.0, (int) -j);
    for (i = 0; i < len; i++) {
        Ym[1][i] = Xm[i] * sc;
        Yr[1][i] = Xr[i] * sc + 2 * ETA_;   /* exact unless subnormal */
    }
    for (a = 2; a <= t; a++) imul(Ym[a], Yr[a], Ym[a - 1], Yr[a - 1], Ym[1], Yr[1], s, s, s);
    /* P = B_nb; for b = nb - 1 .. 0: P = P Z + B_b */
    nb = N / t;
    for (b = nb; b >= 0; b--) {
        /* B = sum_{a < t, bt + a <= N} c_{bt+a} Y^a */
        for (i = 0; i < len; i++) Bm[i] = Br[i] = 0;
        for (a = 1; a < t && b * t + a <= N; a++) {
            iscal(Wm, Wr, Ym[a], Yr[a], cm[b * t + a], cr[b * t + a], len);
            iadd(Bm, Br, Bm, Br, Wm, Wr, len, 1.0);
        }
        for (i = 0; i < s; i++) {
            double x = Bm[i * s + i] + cm[b * t];
            Br[i * s + i] = up_(Br[i * s + i] + cr[b * t] + U_ * fabs(x), 2);
            Bm[i * s + i] = x;
        }
        if (b == nb) {
            memcpy(Pm, Bm, len * sizeof(double));
            memcpy(Pr, Br, len * sizeof(double));
        } else {
            imul(Qm, Qr, Pm, Pr, Ym[t], Yr[t], s, s, s);
            iadd(Pm, Pr, Qm, Qr, Bm, Br, len, 1.0);
        }
    }
    for (i = 0; i < len; i++) Pr[i] = up_(Pr[i] + rem, 2);
    for (k = 0; k < j; k++) {
        imul(Qm, Qr, Pm, Pr, Pm, Pr, s, s, s);
        memcpy(Pm, Qm, len * sizeof(double));
        memcpy(Pr, Qr, len * sizeof(double));
    }
    memcpy(Em, Pm, len * sizeof(double));
    memcpy(Er, Pr, len * sizeof(double));
    ok = all_finite(Em, len) && all_finite(Er, len);
    scratch_put(buf, stk);
    return ok;
}

/* ---- the model ---------------------------------------------------------- */

void rs_cosim_dbl_init(rs_cosim_dbl_t d)
{
    memset(d, 0, sizeof *d);
}

void rs_cosim_dbl_clear(rs_cosim_dbl_t d)
{
    flint_free(d->A1m);
    memset(d, 0, sizeof *d);
}

slong rs_cosim_dbl_dim(const rs_cosim_dbl_t d)
{
    slong h = d->method == RS_COSIM_IMPLICIT ? (d->order > 1 ? d->order - 1 : 0) : d->order;
    return d->n1 + d->n2 + h * d->m;
}

int rs_dbl_set_fmpq(double *mid, double *rad, const fmpq_t x)
{
    arb_t t;
    arb_init(t);
    arb_set_fmpq(t, x, 53);
    *mid = arf_get_d(arb_midref(t), ARF_RND_NEAR);   /* exact: 53 bits */
    *rad = mag_get_d(arb_radref(t));                  /* an upper bound */
    arb_clear(t);
    return isfinite(*mid) && isfinite(*rad);
}

/* one zeroed block for the midpoints and radii of A1, A2, B, C (n1, n2, m set) */
static void dbl_alloc(rs_cosim_dbl_t d)
{
    slong n1 = d->n1, n2 = d->n2, n = n1 + n2, m = d->m, tot = 2 * (n1 * n1 + n2 * n2 + 2 * n * m);
    d->A1m = flint_calloc(tot > 0 ? tot : 1, sizeof(double));
    d->A1r = d->A1m + n1 * n1;
    d->A2m = d->A1r + n1 * n1;
    d->A2r = d->A2m + n2 * n2;
    d->Bm = d->A2r + n2 * n2;
    d->Br = d->Bm + n * m;
    d->Cm = d->Br + n * m;
    d->Cr = d->Cm + n * m;
}

int rs_cosim_dbl_set_dims(rs_cosim_dbl_t d, slong n1, slong n2, slong m, int method, slong order, rs_error_t err)
{
    slong j, k;
    fmpq_mat_t L;
    int rc;
    if (order < 0 || order > RS_COSIM_MAX_ORDER || n1 < 1 || n2 < 1 || m < 0)
        return rs_error_set(err, RS_ERR_INPUT, "cosim double: bad dimensions or order%s", "");
    rs_cosim_dbl_clear(d);
    d->n1 = n1;
    d->n2 = n2;
    d->m = m;
    d->method = method;
    d->order = order;
    dbl_alloc(d);
    d->Hm = 1;
    d->Hr = 0;
    fmpq_mat_init(L, order + 1, order + 1);
    rc = rs_cosim_lagrange(L, method, order, err);
    for (j = 0; rc == RS_OK && j <= order; j++)
        for (k = 0; k <= order; k++)
            rs_dbl_set_fmpq(d->Lm + j * (order + 1) + k, d->Lr + j * (order + 1) + k, fmpq_mat_entry(L, j, k));
    d->haveL = rc == RS_OK;
    fmpq_mat_clear(L);
    return rc;
}

void rs_cosim_dbl_set_like(rs_cosim_dbl_t d, const rs_cosim_dbl_t src)
{
    rs_cosim_dbl_clear(d);
    *d = *src;
    dbl_alloc(d);
}

static void set_block(double *Mm, double *Mr, const fmpq_mat_t X)
{
    slong i, j, c = fmpq_mat_ncols(X);
    for (i = 0; i < fmpq_mat_nrows(X); i++)
        for (j = 0; j < c; j++)
            rs_dbl_set_fmpq(Mm + i * c + j, Mr + i * c + j, fmpq_mat_entry(X, i, j));
}

int rs_cosim_dbl_set_cosim(rs_cosim_dbl_t d, const rs_cosim_t cs, rs_error_t err)
{
    slong n1 = cs->n1, n = cs->n1 + cs->n2, m = cs->m, i, j;
    int rc = rs_cosim_check(cs, err);
    if (rc == RS_OK && cs->ext != RS_COSIM_EXT_NONE)
        rc = rs_error_set(err, RS_ERR_INPUT, "cosim double: the D-/I-extension couplings are not covered%s", "");
    if (rc == RS_OK) rc = rs_cosim_dbl_set_dims(d, cs->n1, cs->n2, m, cs->method, cs->order, err);
    if (rc != RS_OK) return rc;
    set_block(d->A1m, d->A1r, cs->A1);
    set_block(d->A2m, d->A2r, cs->A2);
    set_block(d->Cm, d->Cr, cs->C);
    for (i = 0; i < n; i++)
        for (j = 0; j < m; j++)
            rs_dbl_set_fmpq(d->Bm + i * m + j, d->Br + i * m + j,
                            i < n1 ? fmpq_mat_entry(cs->B1, i, j) : fmpq_mat_entry(cs->B2, i - n1, j));
    rs_dbl_set_fmpq(&d->Hm, &d->Hr, cs->H);
    return RS_OK;
}

/* ---- the one-step map ---------------------------------------------------- */


slong rs_cosim_dbl_sub_len(const rs_cosim_dbl_t d, int s)
{
    slong ni = s ? d->n2 : d->n1;
    return 2 * (ni * ni + ni * d->m * (d->order + 1));
}

/* Subsystem s (A_s, its rows of B) into S: E_s (ni x ni), then the gain
 * columns Phi_k e_c (ni x m (K+1), column k m + c), midpoints then radii of
 * each.  Exactly zero columns of B (midpoint and radius 0) get no chain:
 * their Phi is 0. */
int rs_cosim_dbl_sub(double *S, const rs_cosim_dbl_t d, int s)
{
    slong m = d->m, K = d->order, w = m * (K + 1), ni = s ? d->n2 : d->n1, off = s ? d->n1 : 0, q = 0, sz, r, c, k,
          ch, colstk[64], *cols;
    const double *Aim = s ? d->A2m : d->A1m, *Air = s ? d->A2r : d->A1r;
    double *Em = S, *Er = Em + ni * ni, *Phm = Er + ni * ni, *Phr = Phm + ni * w, *Mm, *Mr, *Xm, *Xr, fact, stk[STK_];
    int ok;
    cols = m < 64 ? colstk : flint_malloc((m + 1) * sizeof(slong));
    for (c = 0; c < m; c++) {
        int nz = 0;
        for (r = 0; r < ni; r++)
            if (d->Bm[(off + r) * m + c] != 0 || d->Br[(off + r) * m + c] != 0) nz = 1;
        if (nz) cols[q++] = c;
    }
    sz = ni + q * (K + 1);
    Mm = scratch_get(stk, 4 * sz * sz);
    memset(Mm, 0, 2 * sz * sz * sizeof(double));
    Mr = Mm + sz * sz;
    Xm = Mr + sz * sz;
    Xr = Xm + sz * sz;
    /* Ma = [[A_i H, B_i H chains], [shift ones]] (interval H) */
    for (r = 0; r < ni; r++) {
        for (c = 0; c < ni; c++)
            iscal(Mm + r * sz + c, Mr + r * sz + c, Aim + r * ni + c, Air + r * ni + c, d->Hm, d->Hr, 1);
        for (ch = 0; ch < q; ch++)
            iscal(Mm + r * sz + ni + ch * (K + 1), Mr + r * sz + ni + ch * (K + 1), d->Bm + (off + r) * m + cols[ch],
                  d->Br + (off + r) * m + cols[ch], d->Hm, d->Hr, 1);
    }
    for (ch = 0; ch < q; ch++)
        for (r = 0; r < K; r++) Mm[(ni + ch * (K + 1) + r) * sz + ni + ch * (K + 1) + r + 1] = 1;
    ok = iexp(Xm, Xr, Mm, Mr, sz);
    for (r = 0; ok && r < ni; r++)
        for (c = 0; c < ni; c++) {
            Em[r * ni + c] = Xm[r * sz + c];
            Er[r * ni + c] = Xr[r * sz + c];
        }
    memset(Phm, 0, 2 * ni * w * sizeof(double));
    fact = 1;
    for (k = 0; ok && k <= K; k++) {
        if (k > 1) fact *= (double) k;   /* exact: k! <= 6 */
        for (ch = 0; ch < q; ch++)
            for (r = 0; r < ni; r++) {
                slong pi = r * w + k * m + cols[ch];
                iscal(Phm + pi, Phr + pi, Xm + r * sz + ni + ch * (K + 1) + k, Xr + r * sz + ni + ch * (K + 1) + k,
                      fact, 0, 1);
            }
    }
    scratch_put(Mm, stk);
    if (cols != colstk) flint_free(cols);
    return ok;
}

/* R ~= M^{-1} (m x m, point, Gauss-Jordan with partial pivoting); 0 if singular */
static int approx_inv(double *R, const double *M, slong m)
{
    slong i, j, k, p;
    double *A = flint_malloc(m * m * sizeof(double));
    int ok = 1;
    memcpy(A, M, m * m * sizeof(double));
    for (i = 0; i < m * m; i++) R[i] = 0;
    for (i = 0; i < m; i++) R[i * m + i] = 1;
    for (k = 0; k < m && ok; k++) {
        p = k;
        for (i = k + 1; i < m; i++)
            if (fabs(A[i * m + k]) > fabs(A[p * m + k])) p = i;
        if (A[p * m + k] == 0) { ok = 0; break; }
        for (j = 0; j < m; j++) {
            double t = A[k * m + j]; A[k * m + j] = A[p * m + j]; A[p * m + j] = t;
            t = R[k * m + j]; R[k * m + j] = R[p * m + j]; R[p * m + j] = t;
        }
        for (i = 0; i < m; i++) {
            double f;
            if (i == k) continue;
            f = A[i * m + k] / A[k * m + k];
            for (j = 0; j < m; j++) {
                A[i * m + j] -= f * A[k * m + j];
                R[i * m + j] -= f * R[k * m + j];
            }
        }
    }
    for (i = 0; ok && i < m; i++) {
        double f = A[i * m + i];
        for (j = 0; j < m; j++) R[i * m + j] /= f;
    }
    flint_free(A);
    return ok && all_finite(R, m * m);
}

int rs_cosim_dbl_transition(double *Tm, double *Tr, const rs_cosim_dbl_t d)
{
    return rs_cosim_dbl_transition_pre(Tm, Tr, d, NULL);
}

int rs_cosim_dbl_transition_pre(double *Tm, double *Tr, const rs_cosim_dbl_t d, const double *const *pre)
{
    slong n = d->n1 + d->n2, m = d->m, K = d->order, w = m * (K + 1), dim = rs_cosim_dbl_dim(d), h, a, j, k, r, c, s,
          tot = 2 * n * n + 4 * n * w + 2 * n * dim + 2 * n * n + 2 + 2 * n * (m > 0 ? m : 1);
    double *Em, *Er, *Phm, *Phr, *Gm, *Gr, *Top, *Topr, *Xm, *Xr, *Ga, *Gar, stk[STK_];
    int ok = 1, impl = d->method == RS_COSIM_IMPLICIT;
    if (!d->haveL || !(d->Hm - d->Hr > 0)) return RS_ERR_UNDECIDED;
    a = impl ? 1 : 0;
    h = (dim - n) / (m > 0 ? m : 1);
    Em = scratch_get(stk, tot);
    memset(Em, 0, tot * sizeof(double));
    Er = Em + n * n;
    Phm = Er + n * n;
    Phr = Phm + n * w;
    Gm = Phr + n * w;
    Gr = Gm + n * w;
    Top = Gr + n * w;
    Topr = Top + n * dim;
    Xm = Topr + n * dim;
    Xr = Xm + n * n;
    Ga = Xr + n * n;
    Gar = Ga + n * (m > 0 ? m : 1);
    /* the subsystems' blocks: given (pre[s], rs_cosim_dbl_sub of this model) or computed here */
    for (s = 0; s < 2 && ok; s++) {
        slong ni = s ? d->n2 : d->n1, off = s ? d->n1 : 0, len = rs_cosim_dbl_sub_len(d, s);
        int own = pre == NULL || pre[s] == NULL;
        double sstk[STK_], *S = own ? scratch_get(sstk, len) : (double *) pre[s];
        const double *SEm = S, *SEr = SEm + ni * ni, *SPm = SEr + ni * ni, *SPr = SPm + ni * w;
        if (own) ok = rs_cosim_dbl_sub(S, d, (int) s);
        for (r = 0; ok && r < ni; r++) {
            memcpy(Em + (off + r) * n + off, SEm + r * ni, ni * sizeof(double));
            memcpy(Er + (off + r) * n + off, SEr + r * ni, ni * sizeof(double));
            memcpy(Phm + (off + r) * w, SPm + r * w, w * sizeof(double));
            memcpy(Phr + (off + r) * w, SPr + r * w, w * sizeof(double));
        }
        if (own) scratch_put(S, sstk);
    }
    /* G_j = sum_k l_{j,k} Phi_k (blocks of m columns) */
    for (j = 0; ok && j <= K; j++)
        for (k = 0; k <= K; k++) {
            double lm = d->Lm[j * (K + 1) + k], lr = d->Lr[j * (K + 1) + k];
            if (lm == 0 && lr == 0) continue;
            for (r = 0; r < n; r++)
                for (c = 0; c < m; c++) {
                    double tm, tr;
                    slong pk = r * w + k * m + c, pj = r * w + j * m + c;
                    iscal(&tm, &tr, Phm + pk, Phr + pk, lm, lr, 1);
                    iadd(Gm + pj, Gr + pj, Gm + pj, Gr + pj, &tm, &tr, 1, 1.0);
                }
        }
    /* Top = [E + G_a C | G_{a+1} ... G_K] (n x dim) */
    if (ok) {
        for (r = 0; r < n; r++)
            for (c = 0; c < n; c++) {
                Xm[r * n + c] = 0;
                Xr[r * n + c] = 0;
            }
        if (a <= K && m > 0) {
            for (r = 0; r < n; r++)
                for (c = 0; c < m; c++) {
                    Ga[r * m + c] = Gm[r * w + a * m + c];
                    Gar[r * m + c] = Gr[r * w + a * m + c];
                }
            imul(Xm, Xr, Ga, Gar, d->Cm, d->Cr, n, m, n);
        }
        for (r = 0; r < n; r++) {
            iadd(Top + r * dim, Topr + r * dim, Xm + r * n, Xr + r * n, Em + r * n, Er + r * n, n, 1.0);
            for (j = a + 1; j <= K; j++)
                for (c = 0; c < m; c++) {
                    Top[r * dim + n + (j - a - 1) * m + c] = Gm[r * w + j * m + c];
                    Topr[r * dim + n + (j - a - 1) * m + c] = Gr[r * w + j * m + c];
                }
        }
        if (impl && m > 0) {
            /* Top <- Top + G_0 J^{-1} (C Top), J = I_m - C G_0 (Woodbury, as
             * rs_cosim_ball_transition).  J^{-1} through R ~= mid(J)^{-1}:
             * with F = I - R J, ||F|| <= e < 1, Y = J^{-1} CX = Z + (I - F)^{-1} F Z
             * for Z = R CX, so column c of Y is Z's within e/(1-e) ||Z_c||. */
            double *Jm = flint_malloc((6 * m * m + 4 * m * dim) * sizeof(double)), *Jr = Jm + m * m, *R = Jr + m * m,
                   *Fm = R + m * m, *Fr = Fm + m * m, *Zero = Fr + m * m, *CXm = Zero + m * m, *CXr = CXm + m * dim,
                   *Zm = CXr + m * dim, *Zr = Zm + m * dim, e;
            for (r = 0; r < n; r++)
                for (c = 0; c < m; c++) {
                    Ga[r * m + c] = Gm[r * w + c];
                    Gar[r * m + c] = Gr[r * w + c];
                }
            imul(Jm, Jr, d->Cm, d->Cr, Ga, Gar, m, n, m);
            for (r = 0; r < m * m; r++) {
                Jm[r] = -Jm[r];
                Zero[r] = 0;
            }
            for (r = 0; r < m; r++) {
                double x = Jm[r * m + r] + 1.0;
                Jr[r * m + r] = up_(Jr[r * m + r] + U_ * fabs(x), 2);
                Jm[r * m + r] = x;
            }
            ok = approx_inv(R, Jm, m);
            if (ok) {
                imul(Fm, Fr, R, NULL, Jm, Jr, m, m, m);
                for (r = 0; r < m * m; r++) Fm[r] = -Fm[r];
                for (r = 0; r < m; r++) {
                    double x = Fm[r * m + r] + 1.0;
                    Fr[r * m + r] = up_(Fr[r * m + r] + U_ * fabs(x), 2);
                    Fm[r * m + r] = x;
                }
                e = inorm(Fm, Fr, m, m);
                ok = e < 0.5;
            }
            if (ok) {
                imul(CXm, CXr, d->Cm, d->Cr, Top, Topr, m, n, dim);
                imul(Zm, Zr, R, NULL, CXm, CXr, m, m, dim);
                for (c = 0; c < dim; c++) {
                    double zc = 0, add;
                    for (r = 0; r < m; r++) zc = fmax(zc, fabs(Zm[r * dim + c]) + Zr[r * dim + c]);
                    add = up_(up_(e / (1.0 - e), 3) * zc, 2);
                    for (r = 0; r < m; r++) Zr[r * dim + c] = up_(Zr[r * dim + c] + add, 2);
                }
                {
                    double *Sm = flint_malloc(2 * n * dim * sizeof(double)), *Sr = Sm + n * dim;
                    imul(Sm, Sr, Ga, Gar, Zm, Zr, n, m, dim);
                    iadd(Top, Topr, Top, Topr, Sm, Sr, n * dim, 1.0);
                    flint_free(Sm);
                }
            }
            flint_free(Jm);
        }
    }
    if (ok) {
        for (r = 0; r < dim * dim; r++) Tm[r] = Tr[r] = 0;
        memcpy(Tm, Top, n * dim * sizeof(double));
        memcpy(Tr, Topr, n * dim * sizeof(double));
        if (h > 0 && m > 0) {
            /* new u_N = C z_N, older u's shift down one slot */
            for (r = 0; r < m; r++)
                for (c = 0; c < n; c++) {
                    Tm[(n + r) * dim + c] = d->Cm[r * n + c];
                    Tr[(n + r) * dim + c] = d->Cr[r * n + c];
                }
            for (j = 1; j < h; j++)
                for (r = 0; r < m; r++) Tm[(n + j * m + r) * dim + n + (j - 1) * m + r] = 1;
        }
        ok = all_finite(Tm, dim * dim) && all_finite(Tr, dim * dim);
    }
    scratch_put(Em, stk);
    return ok ? RS_OK : RS_ERR_UNDECIDED;
}

/* ---- the certified radius ------------------------------------------------ */

/* (Wr, Wi) ~= (Vr + i Vi)^{-1}, d x d: Gauss-Jordan with partial pivoting
 * in complex double (an approximation: the certificate bounds I - W V);
 * 0 if a pivot vanishes.  A (2 d^2 scratch) is overwritten. */
static int cinv(double *Wr, double *Wi, const double *Vr, const double *Vi, double *Ar, slong d)
{
    double *Ai = Ar + d * d;
    slong i, j, k, p;
    memcpy(Ar, Vr, d * d * sizeof(double));
    memcpy(Ai, Vi, d * d * sizeof(double));
    for (i = 0; i < d * d; i++) Wr[i] = Wi[i] = 0;
    for (i = 0; i < d; i++) Wr[i * d + i] = 1;
    for (k = 0; k < d; k++) {
        double best = 0, pr, pi, den;
        p = -1;
        for (i = k; i < d; i++) {
            double a = fabs(Ar[i * d + k]) + fabs(Ai[i * d + k]);
            if (a > best) { best = a; p = i; }
        }
        if (p < 0) return 0;
        if (p != k)
            for (j = 0; j < d; j++) {
                double t;
                t = Ar[k * d + j]; Ar[k * d + j] = Ar[p * d + j]; Ar[p * d + j] = t;
                t = Ai[k * d + j]; Ai[k * d + j] = Ai[p * d + j]; Ai[p * d + j] = t;
                t = Wr[k * d + j]; Wr[k * d + j] = Wr[p * d + j]; Wr[p * d + j] = t;
                t = Wi[k * d + j]; Wi[k * d + j] = Wi[p * d + j]; Wi[p * d + j] = t;
            }
        /* row k /= pivot */
        den = Ar[k * d + k] * Ar[k * d + k] + Ai[k * d + k] * Ai[k * d + k];
        pr = Ar[k * d + k] / den;
        pi = -Ai[k * d + k] / den;
        for (j = 0; j < d; j++) {
            double xr = Ar[k * d + j], xi = Ai[k * d + j], yr = Wr[k * d + j], yi = Wi[k * d + j];
            Ar[k * d + j] = xr * pr - xi * pi;
            Ai[k * d + j] = xr * pi + xi * pr;
            Wr[k * d + j] = yr * pr - yi * pi;
            Wi[k * d + j] = yr * pi + yi * pr;
        }
        for (i = 0; i < d; i++) {
            double fr, fi;
            if (i == k) continue;
            fr = Ar[i * d + k];
            fi = Ai[i * d + k];
            if (fr == 0 && fi == 0) continue;
            for (j = 0; j < d; j++) {
                Ar[i * d + j] -= fr * Ar[k * d + j] - fi * Ai[k * d + j];
                Ai[i * d + j] -= fr * Ai[k * d + j] + fi * Ar[k * d + j];
                Wr[i * d + j] -= fr * Wr[k * d + j] - fi * Wi[k * d + j];
                Wi[i * d + j] -= fr * Wi[k * d + j] + fi * Wr[k * d + j];
            }
        }
    }
    return all_finite(Wr, d * d) && all_finite(Wi, d * d);
}

/* ---- eigenvectors in double ----------------------------------------------
 * A map point's one-step map is small (5 x 5 for Li's k = 1): GSL's general
 * eigenvector solver (balancing, Schur vectors, its allocations) cost more
 * than the certificate.  Here: Householder Hessenberg form, Francis
 * double-shift QR on the active window for the eigenvalues only (Golub & Van
 * Loan, Matrix Computations, 4th ed., Alg. 7.4.2 and 7.5.1), then each
 * eigenvector by two steps of inverse iteration on the complex LU of
 * T - lambda I (one per conjugate pair).  All of it is an approximation:
 * the certificate below bounds I - W V and W T V whatever V is. */

#define H_(i, j) A[(i) * d + (j)]

/* (I - beta v v^T) u = alpha e_1 for u of length len (2 or 3); 0 when u = 0 */
static int house(double *v, double *beta, const double *u, int len)
{
    double nrm = 0, vv = 0;
    int i;
    for (i = 0; i < len; i++) nrm += u[i] * u[i];
    if (!(nrm > 0)) return 0;
    nrm = sqrt(nrm);
    for (i = 0; i < len; i++) v[i] = u[i];
    v[0] -= u[0] > 0 ? -nrm : nrm;
    for (i = 0; i < len; i++) vv += v[i] * v[i];
    if (!(vv > 0)) return 0;
    *beta = 2.0 / vv;
    return 1;
}

/* A (d x d, row major) to upper Hessenberg form by Householder similarities
 * (v: d scratch) */
static void hessenberg(double *A, slong d, double *v)
{
    slong k, i, j;
    for (k = 0; k + 2 < d; k++) {
        slong len = d - k - 1;
        double nrm = 0, alpha, vv = 0, beta;
        for (i = 0; i < len; i++) {
            v[i] = H_(k + 1 + i, k);
            nrm += v[i] * v[i];
        }
        if (!(nrm > 0)) continue;
        nrm = sqrt(nrm);
        alpha = v[0] > 0 ? -nrm : nrm;
        v[0] -= alpha;
        for (i = 0; i < len; i++) vv += v[i] * v[i];
        if (!(vv > 0)) continue;
        beta = 2.0 / vv;
        for (j = k + 1; j < d; j++) {
            double t = 0;
            for (i = 0; i < len; i++) t += v[i] * H_(k + 1 + i, j);
            t *= beta;
            for (i = 0; i < len; i++) H_(k + 1 + i, j) -= t * v[i];
        }
        H_(k + 1, k) = alpha;   /* the reflected column, exactly */
        for (i = 1; i < len; i++) H_(k + 1 + i, k) = 0;
        for (i = 0; i < d; i++) {
            double t = 0, *row = A + i * d + k + 1;
            for (j = 0; j < len; j++) t += row[j] * v[j];
            t *= beta;
            for (j = 0; j < len; j++) row[j] -= t * v[j];
        }
    }
}

/* the eigenvalues (wr + i wi) of the Hessenberg matrix A (overwritten):
 * a conjugate pair at k, k + 1 with wi[k] > 0; 0 when QR does not converge */
static int hqr(double *wr, double *wi, double *A, slong d)
{
    slong hi = d - 1, l, k, i, j, iter = 0, total = 0;
    double nrm = 0;
    for (i = 0; i < d * d; i++) nrm = fmax(nrm, fabs(A[i]));
    if (!isfinite(nrm)) return 0;
    while (hi >= 0) {
        double sh, tt, x, y, z, u[3], v[3], beta;
        for (l = hi; l > 0; l--) {
            double sc = fabs(H_(l - 1, l - 1)) + fabs(H_(l, l));
            if (sc == 0) sc = nrm;
            if (fabs(H_(l, l - 1)) <= DBL_EPSILON * sc) {
                H_(l, l - 1) = 0;
                break;
            }
        }
        if (l == hi) {
            wr[hi] = H_(hi, hi);
            wi[hi] = 0;
            hi--;
            iter = 0;
            continue;
        }
        if (l == hi - 1) {
            double p = 0.5 * (H_(hi - 1, hi - 1) - H_(hi, hi)), w = H_(hi, hi - 1) * H_(hi - 1, hi), q = p * p + w;
            x = H_(hi, hi);
            z = sqrt(fabs(q));
            if (q >= 0) {
                z = p >= 0 ? p + z : p - z;
                wr[hi - 1] = wr[hi] = x + z;
                if (z != 0) wr[hi] = x - w / z;
                wi[hi - 1] = wi[hi] = 0;
            } else {
                wr[hi - 1] = wr[hi] = x + p;
                wi[hi - 1] = z;
                wi[hi] = -z;
            }
            hi -= 2;
            iter = 0;
            continue;
        }
        if (++iter > 60 || ++total > 60 * d) return 0;
        if (iter % 10 == 0) {
            /* exceptional shift (LAPACK dlahqr) after 10 and 20 steps without deflation */
            double e = fabs(H_(hi, hi - 1)) + fabs(H_(hi - 1, hi - 2)), h11 = 0.75 * e + H_(hi, hi), h12 = -0.4375 * e;
            sh = 2 * h11;
            tt = h11 * h11 - h12 * e;
        } else {
            sh = H_(hi - 1, hi - 1) + H_(hi, hi);
            tt = H_(hi - 1, hi - 1) * H_(hi, hi) - H_(hi - 1, hi) * H_(hi, hi - 1);
        }
        /* the first column of (H - s1)(H - s2) on the window [l, hi], chased down */
        x = H_(l, l) * H_(l, l) + H_(l, l + 1) * H_(l + 1, l) - sh * H_(l, l) + tt;
        y = H_(l + 1, l) * (H_(l, l) + H_(l + 1, l + 1) - sh);
        z = H_(l + 1, l) * H_(l + 2, l + 1);
        for (k = l; k <= hi - 2; k++) {
            slong q = k > l ? k - 1 : l, rmax = k + 3 < hi ? k + 3 : hi;
            u[0] = x;
            u[1] = y;
            u[2] = z;
            if (house(v, &beta, u, 3)) {
                for (j = q; j <= hi; j++) {
                    double t = beta * (v[0] * H_(k, j) + v[1] * H_(k + 1, j) + v[2] * H_(k + 2, j));
                    H_(k, j) -= t * v[0];
                    H_(k + 1, j) -= t * v[1];
                    H_(k + 2, j) -= t * v[2];
                }
                for (i = l; i <= rmax; i++) {
                    double t = beta * (H_(i, k) * v[0] + H_(i, k + 1) * v[1] + H_(i, k + 2) * v[2]);
                    H_(i, k) -= t * v[0];
                    H_(i, k + 1) -= t * v[1];
                    H_(i, k + 2) -= t * v[2];
                }
            }
            x = H_(k + 1, k);
            y = H_(k + 2, k);
            if (k < hi - 2) z = H_(k + 3, k);
        }
        u[0] = x;
        u[1] = y;
        if (house(v, &beta, u, 2)) {
            k = hi - 1;
            for (j = hi - 2; j <= hi; j++) {
                double t = beta * (v[0] * H_(k, j) + v[1] * H_(k + 1, j));
                H_(k, j) -= t * v[0];
                H_(k + 1, j) -= t * v[1];
            }
            for (i = l; i <= hi; i++) {
                double t = beta * (H_(i, k) * v[0] + H_(i, k + 1) * v[1]);
                H_(i, k) -= t * v[0];
                H_(i, k + 1) -= t * v[1];
            }
        }
        if (!isfinite(H_(hi, hi)) || !isfinite(H_(hi, hi - 1))) return 0;
    }
    return 1;
}

#undef H_

/* column col of (Vr, Vi) = an eigenvector of T for lambda = lr + i li: two
 * steps of inverse iteration on the LU of T - lambda I with partial
 * pivoting (a pivot below tiny replaced by tiny), the first from U x = b
 * (b varied with col, so that a repeated eigenvalue gets other vectors),
 * scaled to max |re| + |im| = 1.  Scratch: 2 d^2 + 2 d doubles, d slongs. */
static int invit(double *Vr, double *Vi, slong col, const double *T, slong d, double lr, double li, double tiny,
                 double *Ar, slong *piv)
{
    double *Ai = Ar + d * d, *xr = Ai + d * d, *xi = xr + d, mx;
    slong i, j, k, p, step;
    for (i = 0; i < d * d; i++) {
        Ar[i] = T[i];
        Ai[i] = 0;
    }
    for (i = 0; i < d; i++) {
        Ar[i * d + i] -= lr;
        Ai[i * d + i] = -li;
    }
    for (k = 0; k < d; k++) {
        double best = -1, pr, pi, den, ir, ii;
        p = k;
        for (i = k; i < d; i++) {
            double a = fabs(Ar[i * d + k]) + fabs(Ai[i * d + k]);
            if (a > best) { best = a; p = i; }
        }
        piv[k] = p;
        if (p != k)
            for (j = 0; j < d; j++) {
                double t;
                t = Ar[k * d + j]; Ar[k * d + j] = Ar[p * d + j]; Ar[p * d + j] = t;
                t = Ai[k * d + j]; Ai[k * d + j] = Ai[p * d + j]; Ai[p * d + j] = t;
            }
        if (!(best >= tiny)) {
            Ar[k * d + k] = tiny;
            Ai[k * d + k] = 0;
        }
        pr = Ar[k * d + k];
        pi = Ai[k * d + k];
        den = pr * pr + pi * pi;
        ir = pr / den;
        ii = -pi / den;
        for (i = k + 1; i < d; i++) {
            double fr = Ar[i * d + k] * ir - Ai[i * d + k] * ii, fi = Ar[i * d + k] * ii + Ai[i * d + k] * ir;
            Ar[i * d + k] = fr;
            Ai[i * d + k] = fi;
            if (fr == 0 && fi == 0) continue;
            for (j = k + 1; j < d; j++) {
                Ar[i * d + j] -= fr * Ar[k * d + j] - fi * Ai[k * d + j];
                Ai[i * d + j] -= fr * Ai[k * d + j] + fi * Ar[k * d + j];
            }
        }
    }
    for (i = 0; i < d; i++) {
        xr[i] = 1.0 + (double) ((i * 7 + col * 3) % 11) / 16.0;
        xi[i] = 0;
    }
    for (step = 0; step < 2; step++) {
        if (step > 0) {
            /* P and L of the LU (unit lower triangle) */
            for (k = 0; k < d; k++) {
                double t;
                p = piv[k];
                t = xr[k]; xr[k] = xr[p]; xr[p] = t;
                t = xi[k]; xi[k] = xi[p]; xi[p] = t;
            }
            for (i = 1; i < d; i++)
                for (j = 0; j < i; j++) {
                    xr[i] -= Ar[i * d + j] * xr[j] - Ai[i * d + j] * xi[j];
                    xi[i] -= Ar[i * d + j] * xi[j] + Ai[i * d + j] * xr[j];
                }
        }
        for (i = d - 1; i >= 0; i--) {
            double sr = xr[i], si = xi[i], pr = Ar[i * d + i], pi = Ai[i * d + i], den = pr * pr + pi * pi;
            for (j = i + 1; j < d; j++) {
                sr -= Ar[i * d + j] * xr[j] - Ai[i * d + j] * xi[j];
                si -= Ar[i * d + j] * xi[j] + Ai[i * d + j] * xr[j];
            }
            xr[i] = (sr * pr + si * pi) / den;
            xi[i] = (si * pr - sr * pi) / den;
        }
        mx = 0;
        for (i = 0; i < d; i++) mx = fmax(mx, fabs(xr[i]) + fabs(xi[i]));
        if (!(mx > 0) || !isfinite(mx)) return 0;
        for (i = 0; i < d; i++) {
            xr[i] /= mx;
            xi[i] /= mx;
        }
    }
    for (i = 0; i < d; i++) {
        Vr[i * d + col] = xr[i];
        Vi[i * d + col] = xi[i];
    }
    return 1;
}

/* V (complex point, re/im arrays) = double eigenvectors of T, W ~= V^{-1}
 * (cinv); cj[k] = 1 where column k is exactly the conjugate of column
 * k - 1 (a pair), the other columns' eigenvalues real and the columns
 * exactly real; scratch: 4 d^2 + 6 d doubles; 0 when either fails */
static int eigvecs(double *Vr, double *Vi, double *Wr, double *Wi, unsigned char *cj, const double *T, slong d,
                   double *scratch)
{
    double *A = scratch, *wr = A + d * d, *wi = wr + d, *v = wi + d, *lu = v + d, tn = 0;
    slong pstk[64], *piv = d <= 64 ? pstk : flint_malloc(d * sizeof(slong)), k, i;
    int ok;
    memcpy(A, T, d * d * sizeof(double));
    for (i = 0; i < d * d; i++) tn = fmax(tn, fabs(T[i]));
    hessenberg(A, d, v);
    ok = tn > 0 && hqr(wr, wi, A, d);
    tn *= (double) d * DBL_EPSILON;
    for (k = 0; ok && k < d; k++) {
        cj[k] = 0;
        if (wi[k] < 0) {
            /* hqr puts a pair at k - 1, k */
            ok = k > 0 && wi[k - 1] == -wi[k] && wr[k - 1] == wr[k];
            for (i = 0; ok && i < d; i++) {   /* the conjugate pair's vector */
                Vr[i * d + k] = Vr[i * d + k - 1];
                Vi[i * d + k] = -Vi[i * d + k - 1];
            }
            cj[k] = 1;
            continue;
        }
        if (wi[k] > 0) ok = k + 1 < d && wi[k + 1] == -wi[k] && wr[k + 1] == wr[k];
        if (ok) ok = invit(Vr, Vi, k, T, d, wr[k], wi[k], tn, lu, piv);
        for (i = 0; ok && wi[k] == 0 && i < d; i++) Vi[i * d + k] = 0;   /* real: the LU kept it real */
    }
    if (piv != pstk) flint_free(piv);
    return ok && cinv(Wr, Wi, Vr, Vi, scratch, d);
}

/* (Cr, Ci) = (Ar + i Ai)(Br + i Bi), intervals, A r x k, B k x c; radii
 * NULL = point; work: 4 r c */
static void icmul(double *Crm, double *Crr, double *Cim, double *Cir, const double *Arm, const double *Arr,
                  const double *Aim, const double *Air, const double *Brm, const double *Brr, const double *Bim,
                  const double *Bir, slong r, slong k, slong c, double *work)
{
    slong len = r * c;
    double *P1m = work, *P1r = P1m + len, *P2m = P1r + len, *P2r = P2m + len;
    imul(P1m, P1r, Arm, Arr, Brm, Brr, r, k, c);
    imul(P2m, P2r, Aim, Air, Bim, Bir, r, k, c);
    iadd(Crm, Crr, P1m, P1r, P2m, P2r, len, -1.0);
    imul(P1m, P1r, Arm, Arr, Bim, Bir, r, k, c);
    imul(P2m, P2r, Aim, Air, Brm, Brr, r, k, c);
    iadd(Cim, Cir, P1m, P1r, P2m, P2r, len, 1.0);
}

/* row k of (Mrm, Mrr, Mim, Mir), d x d, from row i of the nr x d (Rrm, ...);
 * conj: the conjugate with columns j and part(j) swapped */
static void put_row(double *Mrm, double *Mrr, double *Mim, double *Mir, slong k, const double *Rrm, const double *Rrr,
                    const double *Rim, const double *Rir, slong i, const slong *part, int conj, slong d)
{
    slong j;
    for (j = 0; j < d; j++) {
        slong jj = conj ? part[j] : j;
        Mrm[k * d + j] = Rrm[i * d + jj];
        Mrr[k * d + j] = Rrr[i * d + jj];
        Mim[k * d + j] = conj ? -Rim[i * d + jj] : Rim[i * d + jj];
        Mir[k * d + j] = Rir[i * d + jj];
    }
}

/* an upper bound of |z| for every z in the complex interval: |re| + |im|
 * (at most sqrt 2 above |z|, no hypot call: these are the small
 * off-diagonal entries and the norms) */
static double cabs_up(double re, double rr, double im, double ir)
{
    return up_(fabs(re) + rr + fabs(im) + ir, 4);
}

int rs_cosim_dbl_radius(rs_radius_t r, const rs_cosim_dbl_t d)
{
    return rs_cosim_dbl_radius_pre(r, d, NULL);
}

int rs_cosim_dbl_radius_pre(rs_radius_t r, const rs_cosim_dbl_t d, const double *const *pre)
{
    slong dim = rs_cosim_dbl_dim(d), len = dim * dim, i, j, top = 0;
    double *buf, *Tm, *Tr, *Vr, *Vi, *Wr, *Wi, *Xrm, *Xrr, *Xim, *Xir, *Brm, *Brr, *Bim, *Bir, *Erm, *Err, *Eim, *Eir,
        *work, *R, *out, *in, e, f, up, lo, stk[STK_], *WRr, *WRi, *VRr, *VRi, *Q;
    slong istk[2 * 64], *rep, *part, nr = 0, k;
    unsigned char cstk[64], *cj;
    int ok;
    if (dim < 1) return RS_ERR_UNDECIDED;
    /* every array is written before it is read (X's and the rows' every
     * entry by the pairs below); point factors pass NULL radii; 20 len for
     * T .. E, work: 5 len + 5 dim (eigvecs: 3 len + 5 dim, icmul: 4 len),
     * R, out, in: 3 dim, WR, VR: 4 len, Q: 12 len */
    buf = scratch_get(stk, 41 * len + 8 * dim);
    rep = dim <= 64 ? istk : flint_malloc(2 * dim * sizeof(slong));
    part = rep + dim;
    cj = dim <= 64 ? cstk : flint_malloc(dim);
    Tm = buf; Tr = Tm + len; Vr = Tr + len; Vi = Vr + len; Wr = Vi + len; Wi = Wr + len;
    Xrm = Wi + len; Xrr = Xrm + len; Xim = Xrr + len; Xir = Xim + len;
    Brm = Xir + len; Brr = Brm + len; Bim = Brr + len; Bir = Bim + len;
    Erm = Bir + len; Err = Erm + len; Eim = Err + len; Eir = Eim + len;
    work = Eir + len;
    R = work + 5 * len + 5 * dim;
    out = R + dim;
    in = out + dim;
    WRr = in + dim; WRi = WRr + len; VRr = WRi + len; VRi = VRr + len;
    Q = VRi + len;   /* 12 len: the computed rows of E and B, T V's computed columns */
    ok = rs_cosim_dbl_transition_pre(Tm, Tr, d, pre) == RS_OK && eigvecs(Vr, Vi, Wr, Wi, cj, Tm, dim, work);
    if (ok) {
        /* Conjugate pairs: with W's row k + 1 set to the conjugate of row k
         * (cj[k + 1]: V's column k + 1 is column k's conjugate, the other
         * columns real), row k + 1 of W V and of W T V (T real) is row k's
         * conjugate with columns j and part(j) swapped, for every T in the
         * interval: only the rows rep[] (nr of them) are multiplied, and of
         * T V only the columns rep[] (the others conjugates). */
        double *ERm = Q, *ERr = ERm + len, *EIm = ERr + len, *EIr = EIm + len, *BRm = EIr + len, *BRr = BRm + len,
               *BIm = BRr + len, *BIr = BIm + len, *XRm = BIr + len, *XRr = XRm + len, *XIm = XRr + len,
               *XIr = XIm + len;
        for (k = 0; k < dim; k++) {
            part[k] = k + 1 < dim && cj[k + 1] ? k + 1 : cj[k] ? k - 1 : k;
            if (cj[k])
                for (j = 0; j < dim; j++) {
                    Wr[k * dim + j] = Wr[(k - 1) * dim + j];
                    Wi[k * dim + j] = -Wi[(k - 1) * dim + j];
                }
            else
                rep[nr++] = k;
        }
        for (i = 0; i < nr; i++) {
            memcpy(WRr + i * dim, Wr + rep[i] * dim, dim * sizeof(double));
            memcpy(WRi + i * dim, Wi + rep[i] * dim, dim * sizeof(double));
        }
        for (i = 0; i < dim; i++)
            for (j = 0; j < nr; j++) {
                VRr[i * nr + j] = Vr[i * dim + rep[j]];
                VRi[i * nr + j] = Vi[i * dim + rep[j]];
            }
        /* W V, rows rep[] (point W, V); then E = I - W V */
        icmul(ERm, ERr, EIm, EIr, WRr, NULL, WRi, NULL, Vr, NULL, Vi, NULL, nr, dim, dim, work);
        for (i = 0; i < nr; i++) {
            put_row(Erm, Err, Eim, Eir, rep[i], ERm, ERr, EIm, EIr, i, part, 0, dim);
            if (part[rep[i]] != rep[i]) put_row(Erm, Err, Eim, Eir, part[rep[i]], ERm, ERr, EIm, EIr, i, part, 1, dim);
        }
        for (i = 0; i < len; i++) {
            Erm[i] = -Erm[i];
            Eim[i] = -Eim[i];
        }
        for (i = 0; i < dim; i++) {
            double x = Erm[i * dim + i] + 1.0;
            Err[i * dim + i] = up_(Err[i * dim + i] + U_ * fabs(x), 2);
            Erm[i * dim + i] = x;
        }
        /* X = T V (interval real times point complex): columns rep[], the
         * others their conjugates; B = W X, rows rep[] */
        imul(XRm, XRr, Tm, Tr, VRr, NULL, dim, dim, nr);
        imul(XIm, XIr, Tm, Tr, VRi, NULL, dim, dim, nr);
        for (i = 0; i < dim; i++)
            for (j = 0; j < nr; j++) {
                slong c = rep[j], p = part[c];
                Xrm[i * dim + c] = XRm[i * nr + j];
                Xrr[i * dim + c] = XRr[i * nr + j];
                Xim[i * dim + c] = XIm[i * nr + j];
                Xir[i * dim + c] = XIr[i * nr + j];
                if (p != c) {
                    Xrm[i * dim + p] = XRm[i * nr + j];
                    Xrr[i * dim + p] = XRr[i * nr + j];
                    Xim[i * dim + p] = -XIm[i * nr + j];
                    Xir[i * dim + p] = XIr[i * nr + j];
                }
            }
        icmul(BRm, BRr, BIm, BIr, WRr, NULL, WRi, NULL, Xrm, Xrr, Xim, Xir, nr, dim, dim, work);
        for (i = 0; i < nr; i++) {
            put_row(Brm, Brr, Bim, Bir, rep[i], BRm, BRr, BIm, BIr, i, part, 0, dim);
            if (part[rep[i]] != rep[i]) put_row(Brm, Brr, Bim, Bir, part[rep[i]], BRm, BRr, BIm, BIr, i, part, 1, dim);
        }
        /* e = ||E||, f = e/(1 - e) ||B|| bounds the rows of V^{-1} T V - B
         * (cosim_fast.c: Neumann series of (I - E)^{-1}) */
        e = 0;
        f = 0;
        for (i = 0; i < dim; i++) {
            double se = 0, sb = 0;
            for (j = 0; j < dim; j++) {
                se += cabs_up(Erm[i * dim + j], Err[i * dim + j], Eim[i * dim + j], Eir[i * dim + j]);
                sb += cabs_up(Brm[i * dim + j], Brr[i * dim + j], Bim[i * dim + j], Bir[i * dim + j]);
            }
            e = fmax(e, up_(se, 2 * dim));
            f = fmax(f, up_(sb, 2 * dim));
        }
        ok = all_finite(Brm, len) && all_finite(Brr, len) && all_finite(Bim, len) && all_finite(Bir, len)
             && e < 0.5;
        f = up_(up_(f * e, 2) / (1.0 - e), 4);
    }
    /* disc i: centre mid B_ii, radius R_i = the off-diagonal row sum + f +
     * the centre's own radii; |lambda| in [in_i, out_i] */
    for (i = 0; ok && i < dim; i++) {
        double s = f + Brr[i * dim + i] + Bir[i * dim + i], h;
        for (j = 0; j < dim; j++)
            if (j != i) s += cabs_up(Brm[i * dim + j], Brr[i * dim + j], Bim[i * dim + j], Bir[i * dim + j]);
        R[i] = up_(s, 2 * dim + 2);
        h = hypot(Brm[i * dim + i], Bim[i * dim + i]);   /* glibc: within 1 ulp */
        out[i] = up_(h * (1.0 + 4 * U_) + R[i], 2);
        in[i] = (h * (1.0 - 4 * U_) - R[i]) * (1.0 - 4 * U_);
        if (!(in[i] > 0)) in[i] = 0;
        if (!isfinite(out[i]) || !isfinite(R[i])) ok = 0;
    }
    if (ok) {
        up = out[0];
        for (i = 1; i < dim; i++)
            if (out[i] > up) { up = out[i]; top = i; }
        for (j = 0; ok && j < dim; j++) {
            double dist, need;
            if (j == top) continue;
            dist = hypot(Brm[top * dim + top] - Brm[j * dim + j], Bim[top * dim + top] - Bim[j * dim + j]);
            need = up_(R[top] + R[j], 2);
            if (!(dist * (1.0 - 8 * U_) > need)) ok = 0;
        }
        lo = in[top];
        /* the 6 digits of rs_cosim_radius's cells: wider -> its route */
        if (ok && !(up - lo <= ldexp(lo, -20))) ok = 0;
    }
    if (ok) {
        arb_set_d(r->lower, lo);
        arb_set_d(r->upper, up);
        arb_union(r->rho, r->lower, r->upper, 64);
        r->prec = 53;
        r->nroots = 0;
        r->method_double = 0;
        r->isolated = 1;
        r->partial = 0;
    }
    if (rep != istk) flint_free(rep);
    if (cj != cstk) flint_free(cj);
    scratch_put(buf, stk);
    return ok ? RS_OK : RS_ERR_UNDECIDED;
}
