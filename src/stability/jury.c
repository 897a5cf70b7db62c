/* jury.c -- see include/recstab/jury.h
 *
 * p = lambda^z p0 with p0(0) != 0; the z roots at 0 are inside.
 * g = gcd(p0, p0*) holds every circle root of p0 with its full multiplicity
 * (for |r| = 1, r is a root of p0* exactly as often as conj(r) is a root of
 * p0) and, for each pair (r, 1/conj r), the smaller multiplicity of the two,
 * so h = p0 / g keeps only one side of each pair: gcd(h, h*) = 1.
 *
 * Schur-Cohn matrix of h = sum a_k lambda^k (degree d):
 *   S_jk = sum_{l=0}^{min(j,k)} (a_{d-j+l} a_{d-k+l} - a_{j-l} a_{k-l}),
 * non-singular iff gcd(h, h*) = 1; its number of positive eigenvalues is
 * the number of roots inside (d = 1: S = a_1^2 - a_0^2 > 0 iff |root| < 1).
 *
 * Classical table: f_{k+1} = a_0 f_k - a_n f_k* (degree drops), made
 * primitive.  delta_k = f_{k+1}(0) = a_0^2 - a_n^2; when every delta_k != 0,
 * Rouche on the circle gives in(f_k) = in(f_{k+1}) if delta_k > 0 and
 * deg f_k - in(f_{k+1}) if delta_k < 0.  That count is cross-checked. */
#include <math.h>
#include <string.h>
#include <flint/fmpz_mat.h>
#include <flint/fmpz_vec.h>
#include <flint/nmod.h>
#include <flint/fmpz_poly_factor.h>
#include <fmpz.h>
#include <fmpz_vec.h>
#include "recstab/budget.h"
#include "recstab/jury.h"

void rs_jury_init(rs_jury_t j)
{
    memset(j, 0, sizeof(rs_jury_struct));
    rs_rootcount_init(j->count);
}

void rs_jury_clear(rs_jury_t j)
{
    slong i;
    for (i = 0; i < j->nrows; i++)
        fmpz_poly_clear(j->rows + i);
    flint_free(j->rows);
    rs_rootcount_clear(j->count);
    memset(j, 0, sizeof(rs_jury_struct));
}

static void jury_push_row(rs_jury_t j, const fmpz_poly_t f)
{
    j->rows = flint_realloc(j->rows, (j->nrows + 1) * sizeof(fmpz_poly_struct));
    fmpz_poly_init(j->rows + j->nrows);
    fmpz_poly_set(j->rows + j->nrows, f);
    j->nrows++;
}

/* Classical table; returns 1 and sets *inside when regular, else 0 (rows
 * are dropped then, since a singular table explains nothing).
 *
 * Rouche only needs each row up to a positive factor.  The unreduced rows
 * F_{k+1} = F_k(0) F_k - lc(F_k) F_k* grow like 2^k; as in Bareiss'
 * elimination F_{k+1} is divisible by F_{k-1}(0) (k >= 2; Sylvester's
 * identity on the Schur-Cohn determinants), which keeps the entries at the
 * size of those determinants without taking a gcd per coefficient (the
 * contents cost most of the 20 s at degree 500 with 60-bit coefficients).
 * The division is checked, not assumed: a remainder (a defective step, where
 * the degree drops by more than one) falls back to the content. */
static int jury_table(rs_jury_t j, const fmpz_poly_t p, slong *inside, int keep)
{
    fmpz_poly_t f, fr, t;
    fmpz_t c, prev, r;
    slong k, in;
    int regular = 1;
    slong steps = 0;

    fmpz_poly_init(f);
    fmpz_poly_init(fr);
    fmpz_poly_init(t);
    fmpz_init(c);
    fmpz_init(prev);
    fmpz_init(r);
    fmpz_poly_set(f, p);
    jury_push_row(j, f);
    if (!keep) {
        /* the count needs the sign of each row's constant term and each
         * row's degree only: rows[k] keeps them (the rows themselves took
         * 350 MB at degree 500) */
        fmpz_poly_zero(j->rows + 0);
        fmpz_poly_set_coeff_si(j->rows + 0, fmpz_poly_degree(f), 1);
        fmpz_poly_set_coeff_si(j->rows + 0, 0, fmpz_sgn(f->coeffs + 0));
    }
    while (fmpz_poly_degree(f) > 0) {
        slong len = fmpz_poly_length(f), i;
        int exact = steps >= 2 && !fmpz_is_zero(prev) && !fmpz_is_pm1(prev);
        fmpz_poly_reverse(fr, f, len);
        fmpz_poly_scalar_mul_fmpz(t, f, f->coeffs + 0);
        fmpz_poly_scalar_submul_fmpz(t, fr, f->coeffs + len - 1);
        if (fmpz_poly_is_zero(t) || fmpz_is_zero(t->coeffs + 0)) {
            regular = 0;
            break;
        }
        /* the divisor of the next step is this row's constant term */
        fmpz_abs(c, f->coeffs + 0);
        if (exact) {
            slong tl = fmpz_poly_length(t);
            fmpz_poly_fit_length(f, tl);
            for (i = 0; exact && i < tl; i++) {
                fmpz_fdiv_qr(f->coeffs + i, r, t->coeffs + i, prev);
                exact = fmpz_is_zero(r);
            }
            for (i = tl; i < fmpz_poly_length(f); i++)
                fmpz_zero(f->coeffs + i);
            _fmpz_poly_set_length(f, tl);
        }
        if (!exact) {
            fmpz_poly_content(r, t);
            fmpz_abs(r, r);
            fmpz_poly_scalar_divexact_fmpz(f, t, r);
        }
        fmpz_swap(prev, c);
        steps++;
        if (!keep) {
            slong last = j->nrows;
            fmpz_poly_zero(t);
            jury_push_row(j, t);
            fmpz_poly_set_coeff_si(j->rows + last, fmpz_poly_degree(f), 1);
            fmpz_poly_set_coeff_si(j->rows + last, 0, fmpz_sgn(f->coeffs + 0));
            continue;
        }
        jury_push_row(j, f);
        /* the reported row is primitive (the recursion keeps f as is) up to
         * degree 64; above, the gcds would cost as much as the table
         * (21 s against 15 s at degree 500) for rows nobody reads */
        if (fmpz_poly_degree(p) <= 64)
            fmpz_poly_content(r, f);
        else
            fmpz_one(r);
        if (!fmpz_is_pm1(r)) {
            fmpz_abs(r, r);
            fmpz_poly_scalar_divexact_fmpz(j->rows + j->nrows - 1, f, r);
        }
    }
    if (regular) {
        /* bottom-up: the last row is a non-zero constant, no roots */
        in = 0;
        for (k = j->nrows - 2; k >= 0; k--) {
            if (fmpz_sgn(j->rows[k + 1].coeffs + 0) < 0)
                in = fmpz_poly_degree(j->rows + k) - in;
        }
        *inside = in;
    } else {
        for (k = 0; k < j->nrows; k++)
            fmpz_poly_clear(j->rows + k);
        flint_free(j->rows);
        j->rows = NULL;
        j->nrows = 0;
    }
    fmpz_poly_clear(f);
    fmpz_poly_clear(fr);
    fmpz_poly_clear(t);
    fmpz_clear(c);
    fmpz_clear(prev);
    fmpz_clear(r);
    return regular;
}

/* multiplicity of the root `root` (= +-1) of g; g is divided by it */
static slong jury_remove_unit_root(fmpz_poly_t g, slong root)
{
    fmpz_poly_t lin, qt;
    slong mult = 0;

    fmpz_poly_init(lin);
    fmpz_poly_init(qt);
    fmpz_poly_set_coeff_si(lin, 0, -root);
    fmpz_poly_set_coeff_si(lin, 1, 1);
    while (fmpz_poly_degree(g) > 0 && fmpz_poly_divides(qt, g, lin)) {
        fmpz_poly_swap(g, qt);
        mult++;
    }
    fmpz_poly_clear(lin);
    fmpz_poly_clear(qt);
    return mult;
}

/* roots of g = gcd(p0, p0*): circle roots exactly, the rest split evenly */
static int jury_count_gcd(rs_rootcount_t rc, fmpz_poly_t g, rs_error_t err)
{
    slong a, b, i, deg, circle = 0;
    fmpz_poly_t F;
    fmpz_poly_factor_t fac;

    a = jury_remove_unit_root(g, 1);
    b = jury_remove_unit_root(g, -1);
    rc->at_one = a;
    rc->at_minus_one = b;
    rs_rootcount_add_on(rc, a, 1);
    rs_rootcount_add_on(rc, b, 1);
    deg = fmpz_poly_degree(g);
    if (deg <= 0)
        return RS_OK;
    /* g is self-reciprocal up to sign; without the roots +-1 it is
     * palindromic of even degree */
    if (fmpz_sgn(g->coeffs + deg) < 0)
        fmpz_poly_neg(g, g);
    for (i = 0; i <= deg; i++)
        if (deg % 2 != 0 || !fmpz_equal(g->coeffs + i, g->coeffs + deg - i))
            return rs_error_set(err, RS_ERR_INTERNAL,
                                "gcd(p, p*) without +-1 is not palindromic");

    fmpz_poly_init(F);
    fmpz_poly_factor_init(fac);
    rs_rootcount_reciprocal_to_x(F, g);
    /* a root x of F of multiplicity e in (-2, 2) is a conjugate pair of
     * circle roots of multiplicity e (x = +-2 excluded: g(+-1) != 0) */
    fmpz_poly_factor_squarefree(fac, F);
    for (i = 0; i < fac->num; i++) {
        slong k = rs_rootcount_real_roots_open(fac->p + i, -2, 2);
        rs_rootcount_add_on(rc, fac->exp[i], 2 * k);
        circle += 2 * k * fac->exp[i];
    }
    rc->inside += (deg - circle) / 2;
    rc->outside += (deg - circle) / 2;
    fmpz_poly_factor_clear(fac);
    fmpz_poly_clear(F);
    return RS_OK;
}

/* inertia of the Schur-Cohn matrix of h (gcd(h, h*) = 1) */
static int jury_count_schur_cohn(rs_rootcount_t rc, const fmpz_poly_t h,
                                 rs_error_t err)
{
    slong d = fmpz_poly_degree(h), i, k, l, var = 0;
    const fmpz *a = h->coeffs;
    fmpz_mat_t S;
    fmpz_poly_t cp;
    int last = 0;

    if (d <= 0)
        return RS_OK;
    {
        /* fmpz_mat_charpoly (multimodular, not interruptible) costs about
         * d^4 B / 64 word operations for entries of B bits; 1 ns each is
         * below the measured 2.6 ns (lambda^200 - 10^-1000: 440 s) */
        double B = 2.0 * (double) FLINT_ABS(_fmpz_vec_max_bits(a, d + 1)) + (double) FLINT_BIT_COUNT(d) + 1.0;
        double dd = (double) d;
        int r = rs_budget_estimate(err, "the Schur-Cohn matrix", 1e-9 * dd * dd * dd * dd * B / 64.0,
                                   2.0 * dd * dd * B / 8.0);
        if (r != RS_OK)
            return r;
    }
    fmpz_mat_init(S, d, d);
    fmpz_poly_init(cp);
    for (i = 0; i < d; i++)
        for (k = i; k < d; k++) {
            fmpz *e = fmpz_mat_entry(S, i, k);
            for (l = 0; l <= i; l++) {
                fmpz_addmul(e, a + d - i + l, a + d - k + l);
                fmpz_submul(e, a + i - l, a + k - l);
            }
            fmpz_set(fmpz_mat_entry(S, k, i), e);
        }
    fmpz_mat_charpoly(cp, S);
    /* real-rooted characteristic polynomial: Descartes' sign changes are
     * exactly the positive eigenvalues */
    if (fmpz_is_zero(cp->coeffs + 0)) {
        fmpz_mat_clear(S);
        fmpz_poly_clear(cp);
        return rs_error_set(err, RS_ERR_INTERNAL,
                            "Schur-Cohn matrix singular after gcd removal");
    }
    for (i = 0; i <= d; i++) {
        int s = fmpz_sgn(cp->coeffs + i);
        if (s != 0) {
            if (last != 0 && s != last)
                var++;
            last = s;
        }
    }
    rc->inside += var;
    rc->outside += d - var;
    fmpz_mat_clear(S);
    fmpz_poly_clear(cp);
    return RS_OK;
}

/* ---- the regular table's signs modulo word-size primes ------------------
 *
 * With the divisors 1, 1, F_1(0), F_2(0), ... (signed) the table
 *   F_{k+1} = (F_k(0) F_k - lc(F_k) F_k*) / F_{k-1}(0)
 * (F_k of nominal degree n - k, F_k* its reversal at that degree) is a
 * polynomial identity over Z[a_0, ..., a_n], and F_k(0) = (-1)^k D_k with
 * D_k the leading principal minor of order k of the Schur-Cohn matrix S
 * (the header's S_jk): the Schur algorithm for S, whose displacement rank
 * is 2.  Proof (identities in the field Q(a_0..a_n), then specialised):
 *  (i) S = P^T P - Q^T Q with P, Q upper triangular Toeplitz, first rows
 *      x = (a_n, ..., a_1) and y = (a_0, ..., a_{n-1}); Z the down shift,
 *      S - Z S Z^T = x x^T - y y^T, and a matrix is fixed by this
 *      displacement (Z nilpotent).
 * (ii) With D_1 = S_00 = a_n^2 - a_0^2, u = a_n x - a_0 y, v = a_0 x - a_n y:
 *      u u^T - v v^T = D_1 (x x^T - y y^T) and v_0 = 0, so the Schur
 *      complement C of S_00 (Schur's algorithm, one hyperbolic step) has
 *      D_1 (C - Z C Z^T) = u' u'^T - v' v'^T, u' = u_0..u_{n-2},
 *      v' = v_1..v_{n-1}.  T f = a_0 f - a_n f* (degree n - 1) has
 *      coefficients c_i = a_0 a_i - a_n a_{n-i}, i.e. x(Tf) = v' and
 *      y(Tf) = -u': S(Tf) = -D_1 C.
 * (iii) Minors of a Schur complement: D_k(f) = D_1 det C[0..k-2], hence
 *      D_{k-1}(Tf) = -sigma^{k-2} D_k(f), sigma = F_1(0) = -D_1.
 * (iv) Induction on n: run the table on g = Tf = F_1 (divisors 1, 1,
 *      G_1(0), ...).  T is homogeneous of degree 2, so G_{k-1} =
 *      sigma^{k-2} F_k for k >= 2 (G_1 = F_2, G_2 = T F_2 = sigma F_3, and
 *      e_{k+1} = 2 e_k - e_{k-1} for the exponents); with the hypothesis
 *      G_{k-1}(0) = (-1)^{k-1} D_{k-1}(g) and (iii),
 *      F_k(0) = (-1)^{k-1} D_{k-1}(g) / sigma^{k-2} = (-1)^k D_k(f).
 * Only these rational identities are used below, at points where every
 * divisor is non-zero (checked); that the divisions are even exact over
 * Z[a] (the integer table relies on it, and checks each one) is Bareiss'
 * argument.  tests/unit/stability/test_jury.c checks both symbolically,
 * with independent a_i, for n = 2..6, and the counts at every point of its
 * property tests against the integer table and Routh.  Consequences:
 *  - modulo a prime where F_1(0) .. F_{n-2}(0) do not vanish, the same
 *    recursion in F_p gives the images of the integer F_k(0);
 *  - |S_jk| <= 2 |a|^2 (Cauchy-Schwarz on both sums), so Hadamard gives
 *    |D_k| <= (2 sqrt(k) |a|^2)^k: enough primes for every k;
 *  - when every D_k != 0, Jacobi's rule: the positive eigenvalues of S (the
 *    roots inside, Schur-Cohn-Fujiwara) are the sign permanences of
 *    1, D_1, ..., D_n.  This is the count; Rouche on the integer table
 *    gives the same (unit tests compare them).
 * One more prime than the bound needs re-checks every reconstructed D_k
 * (a failed identity or bound would be caught there with probability
 * 1 - 2^-61 per value): a mismatch is an error, never a count.
 * Cost: 2 n^2 word products per prime, n (2 log2 |a| + log2 n / 2 + 1)
 * / 61 primes, against n^2/2 products of up to that many bits in the
 * integer table (cluster-500: 1138 primes, 0.5 s against 15 s). */

/* below this the integer table is as fast (random-50: the same; Wilkinson
 * degree 20: 0.25 against 0.7 ms; degree 40: 12 against 5.9 ms) */
#define JURY_MODULAR_MIN_DEGREE 32
#define JURY_PRIME_BITS 61

/* F_1(0) .. F_n(0) modulo prime (r[0..n-1]); 0 when a divisor or a nominal
 * leading coefficient vanishes mod prime (a bad prime, a singular or a
 * defective table: the caller decides), else 1.  f: n + 1 words, w: 3n.
 * No inversion per step: the rows G_s = mu_s F_s are not divided,
 * G_s = G_{s-1}(0) G_{s-1} - lc(G_{s-1}) G_{s-1}*, so mu_s = mu_{s-1}^2 div_s
 * with div_s = F_{s-2}(0) = G_{s-2}(0) / mu_{s-2} (1 for s <= 2); mu_s is
 * kept as a fraction num/den and the nums are inverted together at the end
 * (one inversion per prime instead of one per row). */
static int jury_table_mod(mp_ptr r, mp_ptr f, mp_ptr w, const fmpz_poly_t p, mp_limb_t prime)
{
    slong n = fmpz_poly_degree(p), m, s, i;
    mp_ptr num = w, den = w + n, pre = w + 2 * n;
    mp_limb_t nprev = 1, dprev = 1, inv;
    nmod_t mod;
    nmod_init(&mod, prime);
    _fmpz_vec_get_nmod_vec(f, p->coeffs, n + 1, mod);
    for (s = 1, m = n; s <= n; s++, m--) {
        mp_limb_t sc = f[0], tl = f[m], scp, tlp, ns, ds;
        if (tl == 0 || (s >= 3 && r[s - 3] == 0))
            return 0;
        scp = n_mulmod_precomp_shoup(sc, prime);
        tlp = n_mulmod_precomp_shoup(tl, prime);
        /* (f_i, f_{m-i}) -> (sc f_i - tl f_{m-i}, sc f_{m-i} - tl f_i): in
         * place, pair by pair; f_m becomes 0 and is dropped */
        for (i = 0; 2 * i < m; i++) {
            mp_limb_t u = f[i], v = f[m - i];
            f[i] = nmod_sub(n_mulmod_shoup(sc, u, scp, prime), n_mulmod_shoup(tl, v, tlp, prime), mod);
            f[m - i] = nmod_sub(n_mulmod_shoup(sc, v, scp, prime), n_mulmod_shoup(tl, u, tlp, prime), mod);
        }
        if (2 * i == m)
            f[i] = n_mulmod2_preinv(f[i], nmod_sub(sc, tl, mod), prime, mod.ninv);
        r[s - 1] = f[0];                         /* G_s(0) for now */
        ns = n_mulmod2_preinv(nprev, nprev, prime, mod.ninv);
        ds = n_mulmod2_preinv(dprev, dprev, prime, mod.ninv);
        if (s >= 3) {
            ns = n_mulmod2_preinv(ns, n_mulmod2_preinv(r[s - 3], den[s - 3], prime, mod.ninv),
                                  prime, mod.ninv);
            ds = n_mulmod2_preinv(ds, num[s - 3], prime, mod.ninv);
        }
        num[s - 1] = nprev = ns;
        den[s - 1] = dprev = ds;
    }
    /* F_s(0) = G_s(0) den_s / num_s, the nums inverted in one batch */
    pre[0] = num[0];
    for (s = 1; s < n; s++)
        pre[s] = n_mulmod2_preinv(pre[s - 1], num[s], prime, mod.ninv);
    if (pre[n - 1] == 0)
        return 0;
    inv = n_invmod(pre[n - 1], prime);
    for (s = n - 1; s >= 0; s--) {
        mp_limb_t is = s > 0 ? n_mulmod2_preinv(inv, pre[s - 1], prime, mod.ninv) : inv;
        if (s > 0)
            inv = n_mulmod2_preinv(inv, num[s], prime, mod.ninv);
        r[s] = n_mulmod2_preinv(n_mulmod2_preinv(r[s], den[s], prime, mod.ninv), is, prime, mod.ninv);
    }
    return 1;
}

/* The count of a regular table from the minors' signs.  Sets *regular to
 * 1 and *inside, or *regular to 0 when this route cannot decide (a table
 * that is singular or defective modulo the first prime, or more than a few
 * bad primes): the integer table then runs. */
static int jury_count_modular(slong *inside, int *regular, slong *nprimes,
                              const fmpz_poly_t p, rs_error_t err)
{
    slong n = fmpz_poly_degree(p), k, j, np, ncomb, bad = 0, in = 0;
    slong *need;
    fmpz_t a2, x;
    double lb;
    mp_ptr primes, res, f, r, w;
    mp_limb_t q;
    fmpz_comb_struct *comb;
    fmpz_comb_temp_struct *tmp;
    slong *csize;
    int st = RS_OK, prev;

    *regular = 0;
    *nprimes = 0;
    fmpz_init(a2);
    fmpz_init(x);
    _fmpz_vec_dot(a2, p->coeffs, p->coeffs, n + 1);
    lb = (double) fmpz_bits(a2);               /* |a|^2 < 2^lb */
    need = flint_malloc(n * sizeof(slong));
    for (k = 1; k <= n; k++) {
        /* bits of (2 sqrt(k) |a|^2)^k, plus 2 for rounding and the sign */
        double bits = (double) k * (1.0 + 0.5 * log2((double) k) + lb) + 2.0;
        need[k - 1] = (slong) ceil(bits / JURY_PRIME_BITS) + 1;
    }
    np = need[n - 1] + 1;                      /* + the check prime */
    {
        double dn = (double) n;
        st = rs_budget_estimate(err, "the Schur-Cohn minors modulo primes",
                                2e-9 * (double) np * dn * dn, 8.0 * (double) np * (dn + 2.0));
    }
    if (st != RS_OK) {
        flint_free(need);
        fmpz_clear(a2);
        fmpz_clear(x);
        return st;
    }
    primes = flint_malloc(np * sizeof(mp_limb_t));
    res = flint_malloc(np * n * sizeof(mp_limb_t));   /* res[k * np + j] */
    f = flint_malloc((n + 1) * sizeof(mp_limb_t));
    r = flint_malloc(n * sizeof(mp_limb_t));
    w = flint_malloc(3 * n * sizeof(mp_limb_t));
    q = UWORD(1) << (JURY_PRIME_BITS - 1);
    for (j = 0; j < np && st == RS_OK; ) {
        q = n_nextprime(q, 1);
        if (!jury_table_mod(r, f, w, p, q)) {
            /* the first prime sees a singular or defective table as it is
             * over Z (barring a 2^-61 chance): the integer table, which
             * follows actual degrees, is the cheaper route then */
            if (j == 0 || ++bad > 4)
                break;
            continue;
        }
        primes[j] = q;
        for (k = 0; k < n; k++)
            res[k * np + j] = r[k];
        j++;
        if (j % 64 == 0)
            st = rs_budget_check(err, "the Schur-Cohn minors modulo primes");
    }
    flint_free(f);
    flint_free(r);
    flint_free(w);
    if (st != RS_OK || j < np) {
        flint_free(primes);
        flint_free(res);
        flint_free(need);
        fmpz_clear(a2);
        fmpz_clear(x);
        return st;
    }
    /* combs of the first 8, 16, ... primes (and of all but the check
     * prime): each D_k is rebuilt with the smallest that covers it */
    ncomb = 0;
    csize = flint_malloc(64 * sizeof(slong));
    for (k = 8; k < np - 1; k *= 2)
        csize[ncomb++] = k;
    csize[ncomb++] = np - 1;
    comb = flint_malloc(ncomb * sizeof(fmpz_comb_struct));
    tmp = flint_malloc(ncomb * sizeof(fmpz_comb_temp_struct));
    for (k = 0; k < ncomb; k++) {
        fmpz_comb_init(comb + k, primes, csize[k]);
        fmpz_comb_temp_init(tmp + k, comb + k);
    }
    prev = 1;                                  /* sign of D_0 = 1 */
    for (k = 1; k <= n && st == RS_OK; k++) {
        slong c = 0;
        int sg;
        while (csize[c] < need[k - 1])
            c++;
        fmpz_multi_CRT_ui(x, res + (k - 1) * np, comb + c, tmp + c, 1);
        if (fmpz_fdiv_ui(x, primes[np - 1]) != res[(k - 1) * np + np - 1]) {
            st = rs_error_set(err, RS_ERR_INTERNAL,
                              "Schur-Cohn minor D_%ld fails the check prime", (long) k);
            break;
        }
        sg = fmpz_sgn(x);
        if (sg == 0)                           /* singular: the integer table */
            break;
        if (k % 2 == 1)
            sg = -sg;                          /* D_k = (-1)^k F_k(0) */
        if (sg == prev)
            in++;
        prev = sg;
    }
    if (st == RS_OK && k > n) {
        *regular = 1;
        *inside = in;
        *nprimes = np;
    }
    for (k = 0; k < ncomb; k++) {
        fmpz_comb_temp_clear(tmp + k);
        fmpz_comb_clear(comb + k);
    }
    flint_free(comb);
    flint_free(tmp);
    flint_free(csize);
    flint_free(primes);
    flint_free(res);
    flint_free(need);
    fmpz_clear(a2);
    fmpz_clear(x);
    return st;
}

/* The regular table's count of p: modulo primes above degree 32 when no
 * row is kept, else (or when that route cannot decide) the integer table. */
static int jury_table_count(rs_jury_t j, const fmpz_poly_t p, slong *inside, int *regular,
                            int keep, rs_error_t err)
{
    int st;
    *regular = 0;
    if (!keep && fmpz_poly_degree(p) > JURY_MODULAR_MIN_DEGREE) {
        st = jury_count_modular(inside, regular, &j->modular_primes, p, err);
        if (st != RS_OK)
            return st;
    }
    if (!*regular)
        *regular = jury_table(j, p, inside, keep);
    return RS_OK;
}

static int jury_run(rs_jury_t j, const fmpz_poly_t p, int keep, rs_error_t err)
{
    fmpz_poly_t p0, rev, g, h;
    slong z = 0, tin = 0;
    int status;

    rs_jury_clear(j);
    rs_jury_init(j);
    if (fmpz_poly_is_zero(p))
        return rs_error_set(err, RS_ERR_INPUT,
                            "Schur-Cohn test of the zero polynomial");
    j->count->degree = fmpz_poly_degree(p);
    status = jury_table_count(j, p, &tin, &j->table_regular, keep, err);
    if (status != RS_OK)
        return status;

    while (fmpz_is_zero(p->coeffs + z))
        z++;
    fmpz_poly_init(p0);
    fmpz_poly_init(rev);
    fmpz_poly_init(g);
    fmpz_poly_init(h);
    fmpz_poly_shift_right(p0, p, z);
    fmpz_poly_reverse(rev, p0, fmpz_poly_length(p0));
    fmpz_poly_gcd(g, p0, rev);
    j->gcd_degree = fmpz_poly_degree(g);
    if (!fmpz_poly_divides(h, p0, g))
        status = rs_error_set(err, RS_ERR_INTERNAL, "gcd does not divide p");
    else
        status = jury_count_gcd(j->count, g, err);
    j->count->inside += z;
    if (status == RS_OK && j->table_regular && j->gcd_degree == 0) {
        /* no circle root and a regular table: Rouche's count is exact and
         * the Schur-Cohn matrix (d^4 B word operations) adds nothing; the
         * independent count is Routh's on the bilinear transform */
        j->count->inside = tin;
        j->count->outside = j->count->degree - tin;
        j->route = j->modular_primes > 0 ? RS_JURY_ROUTE_MODULAR : RS_JURY_ROUTE_TABLE;
    } else if (status == RS_OK) {
        /* the circle part is counted from g; h = p0/g has none, and when
         * its own table is regular Rouche counts it without the matrix */
        rs_jury_t th;
        slong hin = 0;
        int hreg = 0;
        rs_jury_init(th);
        if (fmpz_poly_degree(h) >= 1)
            status = jury_table_count(th, h, &hin, &hreg, keep, err);
        /* the route reported is h's (p's own table was singular) */
        j->modular_primes = 0;
        if (status == RS_OK && hreg) {
            j->count->inside += hin;
            j->count->outside += fmpz_poly_degree(h) - hin;
            j->modular_primes = th->modular_primes;
            j->route = th->modular_primes > 0 ? RS_JURY_ROUTE_MODULAR : RS_JURY_ROUTE_TABLE;
        } else if (status == RS_OK && fmpz_poly_degree(h) >= 1) {
            status = jury_count_schur_cohn(j->count, h, err);
            j->route = RS_JURY_ROUTE_MATRIX;
        } else {
            j->route = RS_JURY_ROUTE_GCD;
        }
        rs_jury_clear(th);
    }
    if (status == RS_OK && j->table_regular && tin != j->count->inside)
        status = rs_error_set(err, RS_ERR_INCONSISTENT,
            "Schur-Cohn table gives %ld roots inside, the Schur-Cohn matrix "
            "%ld", tin, j->count->inside);
    if (status == RS_OK && j->count->inside + j->count->on
                           + j->count->outside != j->count->degree)
        status = rs_error_set(err, RS_ERR_INTERNAL,
                              "Schur-Cohn count does not add up to the degree");
    fmpz_poly_clear(p0);
    fmpz_poly_clear(rev);
    fmpz_poly_clear(g);
    fmpz_poly_clear(h);
    return status;
}

int rs_jury_fmpz_poly(rs_jury_t j, const fmpz_poly_t p, rs_error_t err)
{
    return jury_run(j, p, 1, err);
}

int rs_jury_count_fmpz_poly(rs_jury_t j, const fmpz_poly_t p, rs_error_t err)
{
    return jury_run(j, p, 0, err);
}

/* see jury.h; the symbolic table's two thresholds, read by an_jury.c
 * (issue 17): factoring a delta through its halves, and the bilinear route */
enum { JURY_WHOLE, JURY_BILINEAR };
static slong jury_terms[2] = {20000, 20000};

static slong jury_terms_swap(int which, slong terms)
{
    slong old = jury_terms[which];
    jury_terms[which] = terms;
    return old;
}

slong rs_jury_set_factor_whole_terms(slong terms)
{
    return jury_terms_swap(JURY_WHOLE, terms);
}

slong rs_jury_factor_whole_terms(void)
{
    return jury_terms[JURY_WHOLE];
}

slong rs_jury_set_bilinear_terms(slong terms)
{
    return jury_terms_swap(JURY_BILINEAR, terms);
}

slong rs_jury_bilinear_terms(void)
{
    return jury_terms[JURY_BILINEAR];
}

int rs_jury_all_inside(const fmpz *c0, slong n)
{
    const slong len = 2 * (n + 1);   /* n counts down below */
    fmpz *c = _fmpz_vec_init(len), *d = c + n + 1;
    fmpz_t g;
    slong k;
    int ok = n >= 1;
    fmpz_init(g);
    _fmpz_vec_set(c, c0, n + 1);
    for (; n > 0 && ok; n--) {
        ok = fmpz_cmpabs(c + n, c + 0) > 0;
        for (k = 0; k < n && ok; k++) {
            fmpz_mul(d + k, c + n, c + k + 1);
            fmpz_submul(d + k, c + 0, c + n - 1 - k);
        }
        _fmpz_vec_content(g, d, n);
        if (ok && !fmpz_is_zero(g)) _fmpz_vec_scalar_divexact_fmpz(c, d, n, g);
        else ok = 0;
    }
    fmpz_clear(g);
    _fmpz_vec_clear(c, len);
    return ok;
}
