/* hurwitz_interp.c -- the Hurwitz minors by evaluation and interpolation
 * over a known support (issue 17).
 *
 * Why.  Over the small ring of hurwitz_subst.c (x, G_1..G_s) the chain's
 * minors are weighted-homogeneous (bench/README.md, h-chain15: weight 1 for
 * z and c, 2j for E_j, D_m of weight m(m+1)/2), so their terms lie in a
 * small set known in advance: 251 330 candidate monomials for N = 8's D_15.
 * The fraction-free recursion over that ring needed 2226 s for N = 8 (its
 * exact divisions of long multivariate polynomials); one value of every
 * minor mod p costs one n x n elimination, and T values at a geometric
 * sequence of points determine the T coefficients by a transposed
 * Vandermonde system, solved in quasi-linear time.
 *
 * How.  (1) Weights: integers w_v >= 1 and alpha, beta with every term of
 * A_i of weight alpha - beta i, found as the nullspace of the terms'
 * equations (only a one-dimensional nullspace is used).  The entry (i, j) of
 * H is A_{n-2j+i}, so every product in the leading m x m minor has weight
 * W_m = m (alpha - beta n) + beta m (m + 1) / 2.  (2) Support: with x_0 = 1,
 * the G-monomials g with w.g <= W_m, W_m - w.g divisible by w_0 and total
 * degree <= m * (largest G-degree of an A_i); x_0's exponent is restored
 * from the weight.  (3) Coefficient bound: a coefficient of D_m is a mean of
 * D_m over the torus |x| = 1, where Hadamard's inequality and |H_ij| <=
 * ||H_ij||_1 give |D_m| <= prod_i (sum_j ||H_ij||_1^2)^(1/2).  (4) For primes p until
 * their product exceeds twice the bound: random g_r, values at (g^t), t <
 * T_m, by elimination without row exchanges (D_k = product of pivots; a zero
 * pivot sends the rest to nmod_mat_det), monomial values m_u = g^u checked
 * distinct, then c_u = N(m_u) / Lambda'(m_u) with Lambda = prod (X - m_u)
 * and N from sum_t v_t y^t = sum_u c_u / (1 - m_u y); CRT, symmetric.
 * (5) Check: every minor is evaluated at one more random point modulo one
 * more prime and compared with the determinant there.
 *
 * Steps (1)-(4) make the result exact (the support is a superset by the
 * weights and degrees, the bound by (3), the system nonsingular by the
 * distinct m_u); (5) guards the code, not the mathematics. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <flint/flint.h>
#include <flint/fmpz.h>
#include <flint/fmpz_vec.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpq_mat.h>
#include <flint/fmpz_mat.h>
#include <flint/nmod.h>
#include <flint/nmod_mat.h>
#include <flint/nmod_poly.h>
#include <flint/nmod_vec.h>
#include <flint/ulong_extras.h>
#include "recstab/budget.h"
#include "stability/hurwitz_interp.h"

/* weights w[0..nv-1] >= 1, alpha, beta; 1 if found */
static int
_weights(slong *w, slong *alpha, slong *beta, const fmpz_mpoly_struct *A,
         slong n, const fmpz_mpoly_ctx_t ctx)
{
    slong nv = fmpz_mpoly_ctx_nvars(ctx), rows = 0, i, k, v, r, rank;
    slong *ex = flint_malloc(nv * sizeof(slong));
    fmpz_mat_t M, X;
    int ok = 0;

    for (i = 0; i <= n; i++)
        rows += fmpz_mpoly_length(A + i, ctx);
    if (rows == 0) {
        flint_free(ex);
        return 0;
    }
    /* unknowns w_0..w_{nv-1}, beta, alpha: w.e + beta i - alpha = 0 */
    fmpz_mat_init(M, rows, nv + 2);
    r = 0;
    for (i = 0; i <= n; i++)
        for (k = 0; k < fmpz_mpoly_length(A + i, ctx); k++, r++) {
            fmpz_mpoly_get_term_exp_si(ex, A + i, k, ctx);
            for (v = 0; v < nv; v++)
                fmpz_set_si(fmpz_mat_entry(M, r, v), ex[v]);
            fmpz_set_si(fmpz_mat_entry(M, r, nv), i);
            fmpz_set_si(fmpz_mat_entry(M, r, nv + 1), -1);
        }
    fmpz_mat_init(X, nv + 2, nv + 2);
    rank = fmpz_mat_nullspace(X, M);
    if (rank == 1) {
        fmpz_t g;
        fmpz_init(g);
        fmpz_zero(g);
        for (v = 0; v < nv + 2; v++)
            fmpz_gcd(g, g, fmpz_mat_entry(X, v, 0));
        if (fmpz_sgn(fmpz_mat_entry(X, 0, 0)) < 0)
            fmpz_neg(g, g);
        ok = !fmpz_is_zero(g);
        for (v = 0; ok && v < nv + 2; v++) {
            fmpz_t q;
            fmpz_init(q);
            fmpz_divexact(q, fmpz_mat_entry(X, v, 0), g);
            if (!fmpz_fits_si(q) || fmpz_bits(q) > 10)
                ok = 0;
            else if (v < nv)
                w[v] = fmpz_get_si(q);
            else if (v == nv)
                *beta = fmpz_get_si(q);
            else
                *alpha = fmpz_get_si(q);
            fmpz_clear(q);
        }
        for (v = 0; ok && v < nv; v++)
            if (w[v] < 1)
                ok = 0;
        fmpz_clear(g);
    }
    fmpz_mat_clear(X);
    fmpz_mat_clear(M);
    flint_free(ex);
    return ok;
}

/* the candidate support: exponent vectors of G (nv - 1 entries each) */
typedef struct {
    slong *e;       /* T * (nv - 1) */
    slong T, alloc, ng;
    slong nodes;    /* enumeration steps, bounded (weights of x_0 > 1 leave
                       leaves unused) */
} supp_t;

static void
_supp_push(supp_t *S, const slong *a)
{
    if (S->T == S->alloc) {
        S->alloc = FLINT_MAX(64, 2 * S->alloc);
        S->e = flint_realloc(S->e, S->alloc * S->ng * sizeof(slong));
    }
    memcpy(S->e + S->T * S->ng, a, S->ng * sizeof(slong));
    S->T++;
}

static int
_supp_enum(supp_t *S, slong *a, slong r, slong deg, slong wt, const slong *w,
           slong Tmax)
{
    slong k;
    if (++S->nodes > 50 * Tmax + 1000)
        return 0;
    if (r == S->ng) {
        if (wt % w[0] == 0)
            _supp_push(S, a);
        return S->T <= Tmax;
    }
    for (k = 0; k <= deg && k * w[r + 1] <= wt; k++) {
        a[r] = k;
        if (!_supp_enum(S, a, r + 1, deg - k, wt - k * w[r + 1], w, Tmax))
            return 0;
    }
    a[r] = 0;
    return 1;
}

/* the entry (i, j) of H (0-based): index n - (2(j+1) - (i+1)) or -1 */
static slong
_hidx(slong n, slong i, slong j)
{
    slong k = n - (2 * (j + 1) - (i + 1));
    return (k < 0 || k > n) ? -1 : k;
}

/* values of the leading minors D_1..D_mmax of H mod p, H given by its
 * coefficient values a[0..n] */
static void
_minors_mod(mp_limb_t *out, const mp_limb_t *a, slong n, slong mmax,
            nmod_mat_t H, nmod_t mod)
{
    slong i, j, k, l;
    mp_limb_t d = 1, inv, f;

    for (i = 0; i < mmax; i++)
        for (j = 0; j < mmax; j++) {
            k = _hidx(n, i, j);
            nmod_mat_entry(H, i, j) = k < 0 ? 0 : a[k];
        }
    for (k = 0; k < mmax; k++) {
        mp_limb_t piv = nmod_mat_entry(H, k, k);
        if (piv == 0) {
            /* the rest by determinants of the original leading blocks */
            nmod_mat_t B;
            for (l = k; l < mmax; l++) {
                nmod_mat_init(B, l + 1, l + 1, mod.n);
                for (i = 0; i <= l; i++)
                    for (j = 0; j <= l; j++) {
                        slong t = _hidx(n, i, j);
                        nmod_mat_entry(B, i, j) = t < 0 ? 0 : a[t];
                    }
                out[l] = nmod_mat_det(B);
                nmod_mat_clear(B);
            }
            return;
        }
        d = nmod_mul(d, piv, mod);
        out[k] = d;
        inv = n_invmod(piv, mod.n);
        for (i = k + 1; i < mmax; i++) {
            f = nmod_mul(nmod_mat_entry(H, i, k), inv, mod);
            if (f == 0)
                continue;
            for (j = k + 1; j < mmax; j++)
                nmod_mat_entry(H, i, j) = nmod_sub(nmod_mat_entry(H, i, j),
                    nmod_mul(f, nmod_mat_entry(H, k, j), mod), mod);
        }
    }
}

/* the A_i's terms mod p, read once per prime: for A_i the terms
 * off[i]..off[i+1]-1, each a coefficient and its G-exponents */
typedef struct {
    slong *off, *ex, ng;
    mp_limb_t *c;
} terms_mod_t;

static void
_terms_mod_init(terms_mod_t *M, const fmpz_mpoly_struct *A, slong n,
                nmod_t mod, const fmpz_mpoly_ctx_t ctx)
{
    slong i, k, t = 0, nv = fmpz_mpoly_ctx_nvars(ctx);
    slong *e = flint_malloc(nv * sizeof(slong));
    M->ng = nv - 1;
    M->off = flint_malloc((n + 2) * sizeof(slong));
    M->off[0] = 0;
    for (i = 0; i <= n; i++)
        M->off[i + 1] = M->off[i] + fmpz_mpoly_length(A + i, ctx);
    M->c = flint_malloc(FLINT_MAX(1, M->off[n + 1]) * sizeof(mp_limb_t));
    M->ex = flint_malloc(FLINT_MAX(1, M->off[n + 1] * M->ng) * sizeof(slong));
    for (i = 0; i <= n; i++)
        for (k = 0; k < fmpz_mpoly_length(A + i, ctx); k++, t++) {
            M->c[t] = fmpz_fdiv_ui(A[i].coeffs + k, mod.n);
            fmpz_mpoly_get_term_exp_si(e, A + i, k, ctx);
            memcpy(M->ex + t * M->ng, e + 1, M->ng * sizeof(slong));
        }
    flint_free(e);
}

static void
_terms_mod_clear(terms_mod_t *M)
{
    flint_free(M->off);
    flint_free(M->c);
    flint_free(M->ex);
}

/* A_i at x_0 = 1, G = g (values mod p) */
static void
_coeffs_mod(mp_limb_t *a, const terms_mod_t *M, slong n, const mp_limb_t *g,
            nmod_t mod)
{
    slong i, t, v;
    for (i = 0; i <= n; i++) {
        mp_limb_t s = 0;
        for (t = M->off[i]; t < M->off[i + 1]; t++) {
            mp_limb_t x = M->c[t];
            const slong *e = M->ex + t * M->ng;
            for (v = 0; v < M->ng && x != 0; v++)
                if (e[v] == 1)
                    x = nmod_mul(x, g[v], mod);
                else if (e[v] > 1)
                    x = nmod_mul(x, n_powmod2_ui_preinv(g[v], e[v], mod.n,
                                                        mod.ninv), mod);
            s = nmod_add(s, x, mod);
        }
        a[i] = s;
    }
}

/* P at the point pt (all nv variables) mod p */
static mp_limb_t
_eval_mod(const fmpz_mpoly_t P, const mp_limb_t *pt, slong *ex, nmod_t mod,
          const fmpz_mpoly_ctx_t ctx)
{
    slong k, v, nv = fmpz_mpoly_ctx_nvars(ctx);
    mp_limb_t s = 0;
    for (k = 0; k < fmpz_mpoly_length(P, ctx); k++) {
        mp_limb_t t = fmpz_fdiv_ui(P->coeffs + k, mod.n);
        fmpz_mpoly_get_term_exp_si(ex, P, k, ctx);
        for (v = 0; v < nv && t != 0; v++)
            if (ex[v] != 0)
                t = nmod_mul(t, n_powmod2_ui_preinv(pt[v], ex[v], mod.n,
                                                    mod.ninv), mod);
        s = nmod_add(s, t, mod);
    }
    return s;
}

static int
_cmp_limb(const void *x, const void *y)
{
    mp_limb_t a = *(const mp_limb_t *) x, b = *(const mp_limb_t *) y;
    return a < b ? -1 : a > b;
}

/* c_u from v_t = sum_u c_u m_u^t, t < T (the m_u distinct, nonzero):
 * c_u = N(m_u) / Lambda'(m_u), one subproduct tree for both */
static void
_tvander_solve(mp_limb_t *c, const mp_limb_t *mu, const mp_limb_t *v,
               slong T, nmod_t mod)
{
    nmod_poly_t Lam, Ls, V, Ns, Nn;
    mp_limb_t *en = flint_malloc(T * sizeof(mp_limb_t));
    mp_limb_t *wt = flint_malloc(T * sizeof(mp_limb_t));
    mp_ptr *tree = _nmod_poly_tree_alloc(T);
    slong u;

    nmod_poly_init(Lam, mod.n);
    nmod_poly_init(Ls, mod.n);
    nmod_poly_init(V, mod.n);
    nmod_poly_init(Ns, mod.n);
    nmod_poly_init(Nn, mod.n);
    _nmod_poly_tree_build(tree, mu, T, mod);
    _nmod_poly_interpolation_weights(wt, tree, T, mod);   /* 1/Lambda'(m_u) */
    nmod_poly_product_roots_nmod_vec(Lam, mu, T);
    nmod_poly_reverse(Ls, Lam, T + 1);          /* prod (1 - m_u y) */
    nmod_poly_fit_length(V, T);
    for (u = 0; u < T; u++)
        V->coeffs[u] = v[u];
    _nmod_poly_set_length(V, T);
    _nmod_poly_normalise(V);
    nmod_poly_mullow(Ns, Ls, V, T);
    nmod_poly_reverse(Nn, Ns, T);               /* N(X) = X^{T-1} Ns(1/X) */
    nmod_poly_fit_length(Nn, T);
    for (u = Nn->length; u < T; u++)
        Nn->coeffs[u] = 0;
    _nmod_poly_evaluate_nmod_vec_fast_precomp(en, Nn->coeffs, T, tree, T, mod);
    for (u = 0; u < T; u++)
        c[u] = nmod_mul(en[u], wt[u], mod);
    _nmod_poly_tree_free(tree, T);
    nmod_poly_clear(Lam);
    nmod_poly_clear(Ls);
    nmod_poly_clear(V);
    nmod_poly_clear(Ns);
    nmod_poly_clear(Nn);
    flint_free(en);
    flint_free(wt);
}

/* mu[u] = g^(support's u-th exponent) */
static void
_mono_values(mp_limb_t *mu, const supp_t *S, const mp_limb_t *g, nmod_t mod)
{
    slong u, k, ng = S->ng;
    for (u = 0; u < S->T; u++) {
        mp_limb_t x = 1;
        for (k = 0; k < ng; k++)
            if (S->e[u * ng + k])
                x = nmod_mul(x, n_powmod2_ui_preinv(g[k], S->e[u * ng + k],
                                                    mod.n, mod.ninv), mod);
        mu[u] = x;
    }
}

/* the residues mod p of every minor m with res[m] != NULL, from T_m values
 * at g^t for random g; 0, or 1 when the budget ran out, 2 when no points
 * with distinct monomial values were found */
static int
_one_prime(mp_limb_t **res, mp_limb_t p, ulong seed,
           const fmpz_mpoly_struct *A, slong n, slong mmax, const supp_t *S,
           slong ng, slong Tmax, const fmpz_mpoly_ctx_t ctx)
{
    mp_limb_t *a, *g, *gp, *mins, *mu, **val;
    slong m, k, u, t;
    int tries, status = 0;
    flint_rand_t st;
    terms_mod_t TM;
    nmod_mat_t H;
    nmod_t mod;

    nmod_init(&mod, p);
    flint_randinit(st);
    flint_randseed(st, 12345 + 7919 * seed, 777 + seed);
    a = flint_malloc((n + 1) * sizeof(mp_limb_t));
    g = flint_malloc(ng * sizeof(mp_limb_t));
    gp = flint_malloc(ng * sizeof(mp_limb_t));
    mins = flint_malloc(n * sizeof(mp_limb_t));
    mu = flint_malloc(Tmax * sizeof(mp_limb_t));
    val = flint_calloc(mmax + 1, sizeof(mp_limb_t *));
    for (m = 1; m <= mmax; m++)
        if (res[m] != NULL)
            val[m] = flint_malloc(S[m].T * sizeof(mp_limb_t));

    /* points g with distinct monomial values on every support */
    for (tries = 0; tries < 8; tries++) {
        int distinct = 1;
        for (k = 0; k < ng; k++)
            g[k] = 2 + n_randint(st, p - 3);
        for (m = 1; m <= mmax && distinct; m++) {
            if (res[m] == NULL)
                continue;
            _mono_values(mu, S + m, g, mod);
            qsort(mu, S[m].T, sizeof(mp_limb_t), _cmp_limb);
            for (u = 1; u < S[m].T; u++)
                if (mu[u] == mu[u - 1])
                    distinct = 0;
        }
        if (distinct)
            break;
    }
    if (tries == 8)
        status = 2;

    if (status == 0) {
        nmod_mat_init(H, mmax, mmax, p);
        _terms_mod_init(&TM, A, n, mod, ctx);
        for (k = 0; k < ng; k++)
            gp[k] = 1;
        for (t = 0; t < Tmax; t++) {
            if ((t & 1023) == 1023 && rs_budget_exceeded()) {
                status = 1;
                break;
            }
            _coeffs_mod(a, &TM, n, gp, mod);
            _minors_mod(mins, a, n, mmax, H, mod);
            for (m = 1; m <= mmax; m++)
                if (val[m] != NULL && t < S[m].T)
                    val[m][t] = mins[m - 1];
            for (k = 0; k < ng; k++)
                gp[k] = nmod_mul(gp[k], g[k], mod);
        }
        nmod_mat_clear(H);
        _terms_mod_clear(&TM);
    }
    for (m = 1; m <= mmax && status == 0; m++) {
        if (res[m] == NULL)
            continue;
        if (rs_budget_exceeded()) {
            status = 1;
            break;
        }
        _mono_values(mu, S + m, g, mod);
        _tvander_solve(res[m], mu, val[m], S[m].T, mod);
    }
    for (m = 1; m <= mmax; m++)
        flint_free(val[m]);
    flint_free(val);
    flint_free(a);
    flint_free(g);
    flint_free(gp);
    flint_free(mins);
    flint_free(mu);
    flint_randclear(st);
    return status;
}

int
rs_hurwitz_interp_minors(fmpz_mpoly_struct *D, slong mmax,
                         const fmpz_mpoly_struct *A, slong n,
                         slong max_terms, rs_error_t err,
                         const fmpz_mpoly_ctx_t ctx)
{
    slong nv = fmpz_mpoly_ctx_nvars(ctx), ng = nv - 1, *w, alpha = 0, beta = 0;
    slong m, i, j, k, u, Tmax = 0, dG = 0, *ex, *Wm;
    supp_t *S = NULL;
    fmpz *bound = NULL, **coef = NULL;
    fmpz_t modulus, tmp;
    mp_limb_t p = UWORD(1) << (FLINT_BITS - 2), *primes, ***res, *mins;
    slong *need, np = 0;
    int *pst, status = RS_HURWITZ_INTERP_NA;
    flint_rand_t st;
    nmod_mat_t H;

    if (mmax < 1 || mmax > n || ng < 1)
        return RS_HURWITZ_INTERP_NA;
    w = flint_malloc(nv * sizeof(slong));
    ex = flint_malloc(nv * sizeof(slong));
    if (!_weights(w, &alpha, &beta, A, n, ctx)) {
        flint_free(w);
        flint_free(ex);
        return RS_HURWITZ_INTERP_NA;
    }
    for (i = 0; i <= n; i++)
        for (k = 0; k < fmpz_mpoly_length(A + i, ctx); k++) {
            slong dd = 0, v;
            fmpz_mpoly_get_term_exp_si(ex, A + i, k, ctx);
            for (v = 1; v < nv; v++)
                dd += ex[v];
            dG = FLINT_MAX(dG, dd);
        }

    /* supports and bounds */
    S = flint_calloc(mmax + 1, sizeof(supp_t));
    Wm = flint_malloc((mmax + 1) * sizeof(slong));
    bound = _fmpz_vec_init(mmax + 1);
    for (m = 1; m <= mmax; m++) {
        slong *av = flint_calloc(ng, sizeof(slong));
        Wm[m] = m * (alpha - beta * n) + beta * m * (m + 1) / 2;
        S[m].ng = ng;
        if (Wm[m] < 0 || !_supp_enum(S + m, av, 0, m * dG, Wm[m], w,
                                     max_terms)) {
            flint_free(av);
            goto cleanup_na;
        }
        flint_free(av);
        Tmax = FLINT_MAX(Tmax, S[m].T);
        /* bound + m = 4 prod_i sum_j ||H_ij||_1^2 >= (2 |coefficient|)^2 */
        fmpz_one(bound + m);
        for (i = 0; i < m; i++) {
            fmpz_t rs, nrm;
            fmpz_init(rs);
            fmpz_init(nrm);
            for (j = 0; j < m; j++) {
                k = _hidx(n, i, j);
                if (k < 0)
                    continue;
                fmpz_zero(nrm);
                for (u = 0; u < fmpz_mpoly_length(A + k, ctx); u++) {
                    if (fmpz_sgn(A[k].coeffs + u) > 0)
                        fmpz_add(nrm, nrm, A[k].coeffs + u);
                    else
                        fmpz_sub(nrm, nrm, A[k].coeffs + u);
                }
                fmpz_addmul(rs, nrm, nrm);
            }
            fmpz_mul(bound + m, bound + m, rs);
            fmpz_clear(rs);
            fmpz_clear(nrm);
        }
        fmpz_mul_2exp(bound + m, bound + m, 2);
    }
    if (rs_budget_check(err, "the Hurwitz minors by interpolation") != RS_OK) {
        status = RS_HURWITZ_INTERP_BUDGET;
        goto cleanup_na;
    }
    /* the cost before the work (measured on the chains: an elimination
     * about 3 ns per mmax^3 / 3 step, a transposed Vandermonde solve 2.6e-5 s
     * per point at 38 760 points, per prime): over 300 CPU s or what is left
     * of the budget, not attempted (the minors stay decided by determinants
     * at points, as without this route) */
    {
        double ent = 0, solve = 0, npr = 0, sec, bytes;
        for (m = 1; m <= mmax; m++) {
            ent += (double) S[m].T * ng;
            solve += (double) S[m].T * 2.6e-5 * log((double) S[m].T + 2.0) / 10.565;
            npr = FLINT_MAX(npr, (double) ((fmpz_bits(bound + m) / 2 + 1) / (FLINT_BITS - 2) + 1));
        }
        sec = npr * ((double) Tmax * (1e-9 * mmax * mmax * mmax + 5e-8 * (n + 1)) + solve);
        bytes = 8.0 * ent + 8.0 * npr * (ent / FLINT_MAX(ng, 1)) * 2.0 + 64.0 * Tmax;
        if (ent > 4e7 || sec > 300.0
            || rs_budget_estimate(NULL, "the Hurwitz minors by interpolation", sec, bytes) != RS_OK)
            goto cleanup_na;
    }

    /* primes above 2^62, as many as the largest bound of each minor asks:
     * modulus^2 > bound + m */
    need = flint_calloc(mmax + 1, sizeof(slong));
    for (m = 1; m <= mmax; m++) {
        need[m] = (fmpz_bits(bound + m) / 2 + 1) / (FLINT_BITS - 2) + 1;
        np = FLINT_MAX(np, need[m]);
    }
    primes = flint_malloc((np + 1) * sizeof(mp_limb_t));
    for (i = 0; i <= np; i++)
        primes[i] = p = n_nextprime(p, 1);
    res = flint_malloc(np * sizeof(mp_limb_t **));
    pst = flint_calloc(np, sizeof(int));
    for (i = 0; i < np; i++) {
        res[i] = flint_calloc(mmax + 1, sizeof(mp_limb_t *));
        for (m = 1; m <= mmax; m++)
            if (i < need[m])
                res[i][m] = flint_malloc(S[m].T * sizeof(mp_limb_t));
    }
    /* the primes are independent: one per thread (the bench's 2 cores) */
#pragma omp parallel for schedule(dynamic, 1)
    for (i = 0; i < np; i++)
        pst[i] = _one_prime(res[i], primes[i], (ulong) i, A, n, mmax, S, ng,
                            Tmax, ctx);
    status = RS_HURWITZ_INTERP_OK;
    for (i = 0; i < np; i++)
        if (pst[i] == 1)
            status = RS_HURWITZ_INTERP_BUDGET;
        else if (pst[i] == 2 && status == RS_HURWITZ_INTERP_OK)
            status = RS_HURWITZ_INTERP_NA;
    if (status == RS_HURWITZ_INTERP_BUDGET)
        rs_budget_check(err, "the Hurwitz minors by interpolation");

    /* CRT, symmetric residues */
    coef = flint_malloc((mmax + 1) * sizeof(fmpz *));
    fmpz_init(modulus);
    fmpz_init(tmp);
    for (m = 1; m <= mmax; m++) {
        coef[m] = _fmpz_vec_init(S[m].T);
        if (status != RS_HURWITZ_INTERP_OK)
            continue;
        fmpz_one(modulus);
        for (i = 0; i < need[m]; i++) {
            for (u = 0; u < S[m].T; u++) {
                fmpz_set(tmp, coef[m] + u);
                fmpz_CRT_ui(coef[m] + u, tmp, modulus, res[i][m][u], primes[i], 1);
            }
            fmpz_mul_ui(modulus, modulus, primes[i]);
        }
    }
    mins = flint_malloc(n * sizeof(mp_limb_t));
    flint_randinit(st);
    p = primes[np];

    if (status == RS_HURWITZ_INTERP_OK) {
        ulong *uex = flint_malloc(nv * sizeof(ulong));
        for (m = 1; m <= mmax; m++) {
            fmpz_mpoly_zero(D + m - 1, ctx);
            for (u = 0; u < S[m].T; u++) {
                slong wt = 0;
                if (fmpz_is_zero(coef[m] + u))
                    continue;
                for (k = 0; k < ng; k++) {
                    uex[k + 1] = S[m].e[u * ng + k];
                    wt += w[k + 1] * S[m].e[u * ng + k];
                }
                uex[0] = (Wm[m] - wt) / w[0];
                fmpz_mpoly_push_term_fmpz_ui(D + m - 1, coef[m] + u, uex, ctx);
            }
            fmpz_mpoly_sort_terms(D + m - 1, ctx);
            fmpz_mpoly_combine_like_terms(D + m - 1, ctx);
        }
        flint_free(uex);
        /* (5): one more prime, one random point with a random x_0 */
        {
            mp_limb_t q = p, *pt = flint_malloc(nv * sizeof(mp_limb_t));
            mp_limb_t *av = flint_malloc((n + 1) * sizeof(mp_limb_t));
            nmod_t mq;
            nmod_init(&mq, q);
            for (k = 0; k < nv; k++)
                pt[k] = 1 + n_randint(st, q - 1);
            for (i = 0; i <= n; i++)
                av[i] = _eval_mod(A + i, pt, ex, mq, ctx);
            nmod_mat_init(H, mmax, mmax, q);
            _minors_mod(mins, av, n, mmax, H, mq);
            nmod_mat_clear(H);
            for (m = 1; m <= mmax; m++)
                if (_eval_mod(D + m - 1, pt, ex, mq, ctx) != mins[m - 1])
                    status = RS_HURWITZ_INTERP_CHECK;
            flint_free(pt);
            flint_free(av);
        }
    }

    fmpz_clear(modulus);
    fmpz_clear(tmp);
    flint_randclear(st);
    for (m = 1; m <= mmax; m++)
        _fmpz_vec_clear(coef[m], S[m].T);
    for (i = 0; i < np; i++) {
        for (m = 1; m <= mmax; m++)
            flint_free(res[i][m]);
        flint_free(res[i]);
    }
    flint_free(res);
    flint_free(pst);
    flint_free(primes);
    flint_free(need);
    flint_free(coef);
    flint_free(mins);
    goto cleanup;

cleanup_na:
cleanup:
    for (m = 1; m <= mmax; m++)
        flint_free(S[m].e);
    flint_free(S);
    flint_free(Wm);
    _fmpz_vec_clear(bound, mmax + 1);
    flint_free(w);
    flint_free(ex);
    return status;
}
