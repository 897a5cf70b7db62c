/* positivity.c -- one-sign tests for polynomials in the parameters under the
 * sign assumptions.  See include/recstab/positivity.h.
 *
 * Polya (1928; Hardy, Littlewood, Polya, Inequalities, sec. 2.24): a form F
 * strictly positive on the simplex x >= 0, sum x = 1 has (sum x)^m F with
 * all coefficients positive for m large enough.  We use only the easy
 * direction, which needs no hypothesis: if G = s^m f has every coefficient
 * >= 0 and a monomial > 0 under the assumptions, then f = G / s^m > 0 there,
 * because s > 0 there (s = 1 + sum x, or sum x when some variable of a
 * positive monomial is > 0).  Variables of unknown sign that occur only in
 * even powers become non-negative after exponent reduction (x^2 -> X). */
#include <stdlib.h>
#include <flint/fmpq.h>
#include <flint/fmpz_vec.h>
#include <ulong_extras.h>
#include <flint/fmpz_poly.h>
#include <mpfr.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include "recstab/positivity.h"
#include "algebra/mfactor.h"

/* Classify term i with its coefficient sign replaced by +1: 2 if the
 * monomial is > 0 under sign[], 1 if >= 0, 0 if neither. */
static int
_monomial_class(const fmpz_mpoly_t poly, slong i, const rs_sign_t *sign,
                const fmpz_mpoly_ctx_t ctx)
{
    slong v, nvars = fmpz_mpoly_ctx_nvars(ctx);
    int cls = 2;

    for (v = 0; v < nvars; v++) {
        ulong e = fmpz_mpoly_get_term_var_exp_ui(poly, i, v, ctx);
        rs_sign_t s = sign == NULL ? RS_SIGN_UNKNOWN : sign[v];
        if (e == 0 || s == RS_SIGN_POSITIVE)
            continue;
        if (s == RS_SIGN_NONNEGATIVE || (e % 2) == 0)
            cls = 1;    /* >= 0, but may vanish */
        else
            return 0;   /* odd power of a variable of unknown sign */
    }
    return cls;
}

int
rs_positivity_coeff_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                         const fmpz_mpoly_ctx_t ctx)
{
    slong i, len = fmpz_mpoly_length(poly, ctx);
    int csign = 0, strict = 0;

    if (len == 0 || !fmpz_mpoly_degrees_fit_si(poly, ctx))
        return 0;
    for (i = 0; i < len; i++) {
        int s = fmpz_sgn(poly->coeffs + i), cls;
        if (i == 0)
            csign = s;
        else if (s != csign)
            return 0;
        cls = _monomial_class(poly, i, sign, ctx);
        if (cls == 0)
            return 0;
        if (cls == 2)
            strict = 1;
    }
    return strict ? csign : 0;
}

/* r = poly with every exponent of variable v divided by g[v] (the gcd of
 * its exponents; 0 where v does not occur). */
static void
_reduce_exponents(fmpz_mpoly_t r, const fmpz_mpoly_t poly, const ulong *g,
                  const fmpz_mpoly_ctx_t ctx)
{
    slong i, v, nvars = fmpz_mpoly_ctx_nvars(ctx);
    ulong *e = flint_malloc(nvars * sizeof(ulong));

    fmpz_mpoly_zero(r, ctx);
    for (i = 0; i < fmpz_mpoly_length(poly, ctx); i++) {
        fmpz_mpoly_get_term_exp_ui(e, poly, i, ctx);
        for (v = 0; v < nvars; v++)
            if (g[v] > 1)
                e[v] /= g[v];
        fmpz_mpoly_push_term_fmpz_ui(r, poly->coeffs + i, e, ctx);
    }
    fmpz_mpoly_sort_terms(r, ctx);
    fmpz_mpoly_combine_like_terms(r, ctx);
    flint_free(e);
}

/* 1 if f has the sign target at the points with one variable 7 and the
 * others 1, and one variable 1 and the others 7; 0 otherwise. */
static int
_positive_at_probes(const fmpz_mpoly_t f, int target, const fmpz_mpoly_ctx_t ctx)
{
    slong v, w, nvars = fmpz_mpoly_ctx_nvars(ctx);
    fmpz *pt = _fmpz_vec_init(nvars);
    fmpz_t ev;
    int ok = 1, hi;

    fmpz_init(ev);
    for (v = 0; v < nvars && ok; v++)
        for (hi = 0; hi < 2 && ok; hi++) {
            for (w = 0; w < nvars; w++)
                fmpz_set_ui(pt + w, ((w == v) == hi) ? 7 : 1);
            {
                fmpz *vals[64];
                fmpz **vp = nvars <= 64 ? vals : flint_malloc(nvars * sizeof(fmpz *));
                for (w = 0; w < nvars; w++)
                    vp[w] = pt + w;
                if (fmpz_mpoly_evaluate_all_fmpz(ev, f, vp, ctx)
                    && fmpz_sgn(ev) != target)
                    ok = 0;
                if (vp != vals)
                    flint_free(vp);
            }
        }
    fmpz_clear(ev);
    _fmpz_vec_clear(pt, nvars);
    return ok;
}

int
rs_positivity_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                   const fmpz_mpoly_ctx_t ctx, slong *power)
{
    slong i, v, m, nvars = fmpz_mpoly_ctx_nvars(ctx), len, deg = -1;
    ulong *g;
    rs_sign_t *sg;
    fmpz_mpoly_t f, s, x;
    fmpz_t sum;
    int res = 0, homogeneous = 1, target, ok = 1;

    if (power != NULL)
        *power = -1;
    res = rs_positivity_coeff_sign(poly, sign, ctx);
    if (res != 0) {
        if (power != NULL)
            *power = 0;
        return res;
    }
    len = fmpz_mpoly_length(poly, ctx);
    /* over the multiplier's term limit already: Polya would stop at its
     * first step, so neither it nor the probes before it (14 evaluations of
     * a 637 163-term minor of a 6-mass chain: 1.7 s, issue 17) are run */
    if (len < 2 || len > RS_POLYA_MAX_TERMS || !fmpz_mpoly_degrees_fit_si(poly, ctx))
        return 0;

    /* the sign Polya could prove: that of f at (1, ..., 1) */
    fmpz_init(sum);
    for (i = 0; i < len; i++)
        fmpz_add(sum, sum, poly->coeffs + i);
    target = fmpz_sgn(sum);
    fmpz_clear(sum);
    if (target == 0)
        return 0;

    g = flint_calloc(nvars, sizeof(ulong));
    sg = flint_malloc(nvars * sizeof(rs_sign_t));
    for (i = 0; i < len; i++)
        for (v = 0; v < nvars; v++)
            g[v] = n_gcd(g[v], fmpz_mpoly_get_term_var_exp_ui(poly, i, v, ctx));
    for (v = 0; v < nvars && ok; v++) {
        sg[v] = sign == NULL ? RS_SIGN_UNKNOWN : sign[v];
        if (g[v] == 0 || sg[v] != RS_SIGN_UNKNOWN)
            continue;
        if (g[v] % 2 == 0)
            sg[v] = RS_SIGN_NONNEGATIVE;   /* x^(2j) -> X^j, X >= 0 */
        else
            ok = 0;                        /* odd power of a free sign */
    }
    if (!ok) {
        flint_free(g);
        flint_free(sg);
        return 0;
    }

    fmpz_mpoly_init(f, ctx);
    fmpz_mpoly_init(s, ctx);
    fmpz_mpoly_init(x, ctx);
    _reduce_exponents(f, poly, g, ctx);
    /* cheap refutation before the expensive multiplier: a point with every
     * variable > 0 is admissible (X = x^2 > 0 for the free-sign ones), and
     * f of the wrong sign or zero there means no certificate exists; the
     * indefinite factors of the Park case ran Polya to its term limit */
    if (!_positive_at_probes(f, target, ctx)) {
        fmpz_mpoly_clear(f, ctx);
        fmpz_mpoly_clear(s, ctx);
        fmpz_mpoly_clear(x, ctx);
        flint_free(g);
        flint_free(sg);
        return 0;
    }
    for (i = 0; i < fmpz_mpoly_length(f, ctx); i++) {
        slong d = 0;
        for (v = 0; v < nvars; v++)
            d += fmpz_mpoly_get_term_var_exp_ui(f, i, v, ctx);
        if (deg >= 0 && d != deg)
            homogeneous = 0;
        deg = d;
    }
    /* s = sum of the variables that occur (+ 1 unless f is a form) */
    if (!homogeneous)
        fmpz_mpoly_one(s, ctx);
    for (v = 0; v < nvars; v++)
        if (g[v] != 0) {
            fmpz_mpoly_gen(x, v, ctx);
            fmpz_mpoly_add(s, s, x, ctx);
        }

    res = 0;
    for (m = 1; m <= RS_POLYA_MAX_POWER; m++) {
        fmpz_mpoly_mul(f, f, s, ctx);
        if (fmpz_mpoly_length(f, ctx) > RS_POLYA_MAX_TERMS)
            break;
        if (rs_positivity_coeff_sign(f, sg, ctx) == target) {
            res = target;
            if (power != NULL)
                *power = m;
            break;
        }
    }
    fmpz_mpoly_clear(f, ctx);
    fmpz_mpoly_clear(s, ctx);
    fmpz_mpoly_clear(x, ctx);
    flint_free(g);
    flint_free(sg);
    return res;
}

/* v = A / B for the bound b (see positivity.h) with A, B in Z[v] (v now
 * standing for t), and t's sign into *ts; 0 if v keeps its own sign (no
 * bound, or only the bound v > 0 / v >= 0 that sign[] already says). */
static int
_interval_map(fmpz_mpoly_t A, fmpz_mpoly_t B, rs_sign_t *ts, const rs_bound_t *b,
              slong v, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t t;
    int lo = b->has_lo, hi = b->has_hi;

    if (!lo && !hi)
        return 0;
    if (lo && fmpq_is_zero(b->lo) && (!hi || b->hi_closed))
        return 0;   /* v = 0 + t: the sign test as it is */
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_gen(t, v, ctx);
    if (lo && hi && !b->hi_closed && fmpq_cmp(b->lo, b->hi) < 0) {
        /* (lo + hi t) / (1 + t) = (ln hd + hn ld t) / (ld hd (1 + t)) */
        fmpz_t c;
        fmpz_init(c);
        fmpz_mul(c, fmpq_numref(b->hi), fmpq_denref(b->lo));
        fmpz_mpoly_scalar_mul_fmpz(A, t, c, ctx);
        fmpz_mul(c, fmpq_numref(b->lo), fmpq_denref(b->hi));
        fmpz_mpoly_add_fmpz(A, A, c, ctx);
        fmpz_mul(c, fmpq_denref(b->lo), fmpq_denref(b->hi));
        fmpz_mpoly_add_ui(B, t, 1, ctx);
        fmpz_mpoly_scalar_mul_fmpz(B, B, c, ctx);
        fmpz_clear(c);
        *ts = b->lo_closed ? RS_SIGN_NONNEGATIVE : RS_SIGN_POSITIVE;
    } else if (lo) {
        /* lo + t = (ln + ld t) / ld */
        fmpz_mpoly_scalar_mul_fmpz(A, t, fmpq_denref(b->lo), ctx);
        fmpz_mpoly_add_fmpz(A, A, fmpq_numref(b->lo), ctx);
        fmpz_mpoly_set_fmpz(B, fmpq_denref(b->lo), ctx);
        *ts = b->lo_closed ? RS_SIGN_NONNEGATIVE : RS_SIGN_POSITIVE;
    } else {
        /* hi - t = (hn - hd t) / hd */
        fmpz_mpoly_scalar_mul_fmpz(A, t, fmpq_denref(b->hi), ctx);
        fmpz_mpoly_neg(A, A, ctx);
        fmpz_mpoly_add_fmpz(A, A, fmpq_numref(b->hi), ctx);
        fmpz_mpoly_set_fmpz(B, fmpq_denref(b->hi), ctx);
        *ts = b->hi_closed ? RS_SIGN_NONNEGATIVE : RS_SIGN_POSITIVE;
    }
    fmpz_mpoly_clear(t, ctx);
    return 1;
}

/* g = B^d f(A / B) in the variable v, d = deg_v f (Horner:
 * H = f_d, H = H A + f_e B^(d-e) for e = d-1..0); 0 if it grew past
 * RS_POLYA_MAX_TERMS. */
static int
_substitute(fmpz_mpoly_t g, const fmpz_mpoly_t f, slong v, const fmpz_mpoly_t A,
            const fmpz_mpoly_t B, const fmpz_mpoly_ctx_t ctx)
{
    slong d = fmpz_mpoly_degree_si(f, v, ctx), e;
    fmpz_mpoly_t h, fe, Bp;
    int ok = 1;

    fmpz_mpoly_init(h, ctx);
    fmpz_mpoly_init(fe, ctx);
    fmpz_mpoly_init(Bp, ctx);
    fmpz_mpoly_get_coeff_vars_ui(h, f, &v, (ulong *) &d, 1, ctx);
    fmpz_mpoly_one(Bp, ctx);
    for (e = d - 1; e >= 0 && ok; e--) {
        ulong ue = (ulong) e;
        fmpz_mpoly_mul(h, h, A, ctx);
        fmpz_mpoly_mul(Bp, Bp, B, ctx);
        fmpz_mpoly_get_coeff_vars_ui(fe, f, &v, &ue, 1, ctx);
        fmpz_mpoly_mul(fe, fe, Bp, ctx);
        fmpz_mpoly_add(h, h, fe, ctx);
        ok = fmpz_mpoly_length(h, ctx) <= RS_POLYA_MAX_TERMS;
    }
    fmpz_mpoly_swap(g, h, ctx);
    fmpz_mpoly_clear(h, ctx);
    fmpz_mpoly_clear(fe, ctx);
    fmpz_mpoly_clear(Bp, ctx);
    return ok;
}

int
rs_positivity_sign_bounds(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                          const rs_bound_t *b, slong nbounds,
                          const fmpz_mpoly_ctx_t ctx, slong *power)
{
    slong v, nvars = fmpz_mpoly_ctx_nvars(ctx);
    rs_sign_t *sg;
    fmpz_mpoly_t g, A, B;
    int res, mapped = 0, ok = 1;

    res = rs_positivity_sign(poly, sign, ctx, power);
    if (res != 0 || b == NULL || !fmpz_mpoly_degrees_fit_si(poly, ctx))
        return res;
    sg = flint_malloc(nvars * sizeof(rs_sign_t));
    fmpz_mpoly_init(g, ctx);
    fmpz_mpoly_init(A, ctx);
    fmpz_mpoly_init(B, ctx);
    fmpz_mpoly_set(g, poly, ctx);
    for (v = 0; v < nvars; v++)
        sg[v] = sign == NULL ? RS_SIGN_UNKNOWN : sign[v];
    for (v = 0; v < nvars && v < nbounds && ok; v++) {
        if (fmpz_mpoly_degree_si(g, v, ctx) <= 0
            || !_interval_map(A, B, sg + v, b + v, v, ctx))
            continue;
        ok = _substitute(g, g, v, A, B, ctx);
        mapped = 1;
    }
    if (ok && mapped)
        res = rs_positivity_sign(g, sg, ctx, power);
    fmpz_mpoly_clear(g, ctx);
    fmpz_mpoly_clear(A, ctx);
    fmpz_mpoly_clear(B, ctx);
    flint_free(sg);
    return res;
}

slong
rs_positivity_single_var(const fmpz_mpoly_t poly, const fmpz_mpoly_ctx_t ctx)
{
    slong v, nvars = fmpz_mpoly_ctx_nvars(ctx), w = -1;
    for (v = 0; v < nvars; v++)
        if (fmpz_mpoly_degree_si(poly, v, ctx) > 0) {
            if (w >= 0)
                return -1;
            w = v;
        }
    return w;
}

/* Real roots of the squarefree g (g(0) != 0) counted by certified
 * isolation (arb_fmpz_poly_complex_roots: disjoint enclosures, the real
 * roots first with an exactly zero imaginary part): *npos > 0, *nneg < 0;
 * 0 if the precision cap left a real root's sign open. */
static int _roots_arb(slong *nneg, slong *npos, const fmpz_poly_t g)
{
    slong n = fmpz_poly_degree(g), prec, i;
    acb_ptr r;
    int done = 0;
    *nneg = *npos = 0;
    if (n < 1)
        return 1;
    r = _acb_vec_init(n);
    for (prec = 64; prec <= 4096 && !done; prec *= 4) {
        done = 1;
        *nneg = *npos = 0;
        arb_fmpz_poly_complex_roots(r, g, 0, prec);
        for (i = 0; i < n && done; i++) {
            if (!acb_is_real(r + i))
                continue;
            if (arb_is_positive(acb_realref(r + i)))
                (*npos)++;
            else if (arb_is_negative(acb_realref(r + i)))
                (*nneg)++;
            else
                done = 0;
        }
    }
    _acb_vec_clear(r, n);
    return done;
}

int
rs_positivity_sign_roots(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                         const fmpz_mpoly_ctx_t ctx, int *inconsistent)
{
    slong v = rs_positivity_single_var(poly, ctx), k, nneg = 0, npos = 0, an = 0, ap = 0, n;
    rs_sign_t sv;
    fmpz_poly_t u, g;
    int res = 0;

    if (inconsistent != NULL)
        *inconsistent = 0;
    if (v < 0)
        return 0;
    sv = sign == NULL ? RS_SIGN_UNKNOWN : sign[v];
    fmpz_poly_init(u);
    fmpz_poly_init(g);
    if (!fmpz_mpoly_get_fmpz_poly(u, poly, v, ctx))
        goto done;
    /* u = x^k g, g(0) != 0: a root at 0 is admissible unless x > 0 */
    for (k = 0; k < u->length && fmpz_is_zero(u->coeffs + k); k++)
        ;
    if (k > 0 && sv != RS_SIGN_POSITIVE)
        goto done;
    fmpz_poly_shift_right(g, u, k);
    /* the squarefree part: the distinct roots are those of g */
    rs_fmpz_poly_squarefree_part(g, g);
    if (fmpz_poly_degree(g) >= 1)
        _fmpz_poly_num_real_roots_sturm(&nneg, &npos, g->coeffs, g->length);
    /* the second count (THE cross-check): certified isolation */
    if (!_roots_arb(&an, &ap, g))
        goto done;
    if (an != nneg || ap != npos) {
        if (inconsistent != NULL)
            *inconsistent = 1;
        goto done;
    }
    n = npos + (sv == RS_SIGN_UNKNOWN ? nneg : 0);
    /* no root on the range (connected): one sign there, that of x -> inf */
    if (n == 0)
        res = fmpz_sgn(u->coeffs + u->length - 1);
done:
    fmpz_poly_clear(u);
    fmpz_poly_clear(g);
    return res;
}

/* The real roots of the squarefree g (degree d >= 1), isolated: disjoint
 * balls in ascending order in re[0 .. nr - 1] (r, re of length d); the
 * number nr, or -1 when 1024 bits do not separate them.  *prec is the
 * precision that did (for the balls' ends). */
static slong _real_roots_sorted(arb_ptr re, slong *prec, acb_ptr r, const fmpz_poly_t g)
{
    slong d = fmpz_poly_degree(g), nr, i;
    for (*prec = 64; *prec <= 1024; *prec *= 4) {
        int sep = 1;
        arb_fmpz_poly_complex_roots(r, g, 0, *prec);   /* real roots first, ascending */
        for (nr = 0; nr < d && acb_is_real(r + nr); nr++)
            arb_set(re + nr, acb_realref(r + nr));
        for (i = 0; i + 1 < nr; i++)
            sep &= arb_lt(re + i, re + i + 1);
        if (sep)
            return nr;
    }
    return -1;
}

/* x := a rational in gap i (0 <= i <= nr, nr >= 1) of the isolated roots
 * re[0 .. nr - 1]: below the first, between re[i - 1] and re[i], above the last */
static void _gap_point(fmpq_t x, arb_srcptr re, slong nr, slong i, slong prec)
{
    arf_t a;
    fmpq_t y;
    arf_init(a);
    if (i == 0) {
        arb_get_lbound_arf(a, re, prec);
        arf_get_fmpq(x, a);
        fmpq_sub_si(x, x, 1);
    } else if (i == nr) {
        arb_get_ubound_arf(a, re + nr - 1, prec);
        arf_get_fmpq(x, a);
        fmpq_add_si(x, x, 1);
    } else {
        fmpq_init(y);
        arb_get_ubound_arf(a, re + i - 1, prec);
        arf_get_fmpq(x, a);
        arb_get_lbound_arf(a, re + i, prec);
        arf_get_fmpq(y, a);
        fmpq_add(x, x, y);
        fmpq_div_2exp(x, x, 1);
        fmpq_clear(y);
    }
    arf_clear(a);
}

slong
rs_positivity_negative_points(fmpq *pts, slong cap, const fmpz_mpoly_t poly, const rs_sign_t *sign,
                              const fmpz_mpoly_ctx_t ctx)
{
    slong v = rs_positivity_single_var(poly, ctx), n, i, nr = 0, npts = 0, prec;
    fmpz_poly_t u, g;
    acb_ptr r = NULL;
    arb_ptr re = NULL;
    fmpq_t x, y;
    int pos = sign != NULL && v >= 0 && (sign[v] == RS_SIGN_POSITIVE || sign[v] == RS_SIGN_NONNEGATIVE);

    if (v < 0 || cap <= 0)
        return 0;
    fmpz_poly_init(u);
    fmpz_poly_init(g);
    fmpq_init(x);
    fmpq_init(y);
    if (!fmpz_mpoly_get_fmpz_poly(u, poly, v, ctx) || fmpz_poly_degree(u) < 1)
        goto done;
    rs_fmpz_poly_squarefree_part(g, u);
    n = fmpz_poly_degree(g);
    r = _acb_vec_init(n);
    re = _arb_vec_init(n + 2);
    /* the real roots, isolated (disjoint balls, ascending) */
    nr = FLINT_MAX(_real_roots_sorted(re, &prec, r, g), 0);
    /* one rational in each gap between roots and beyond them: the points
     * where poly < 0 (exact evaluation) are kept */
    for (i = 0; i <= nr && npts < cap; i++) {
        if (nr == 0)
            fmpq_one(x);
        else
            _gap_point(x, re, nr, i, prec);
        if (pos && fmpq_sgn(x) <= 0)
            continue;
        fmpz_poly_evaluate_fmpq(y, u, x);
        if (fmpq_sgn(y) < 0)
            fmpq_set(pts + npts++, x);
    }
    if (npts == 0 && pos) {
        fmpq_one(x);
        fmpz_poly_evaluate_fmpq(y, u, x);
        if (fmpq_sgn(y) < 0)
            fmpq_set(pts + npts++, x);
    }
done:
    if (r != NULL) {
        _acb_vec_clear(r, fmpz_poly_degree(g));
        _arb_vec_clear(re, fmpz_poly_degree(g) + 2);
    }
    fmpz_poly_clear(u);
    fmpz_poly_clear(g);
    fmpq_clear(x);
    fmpq_clear(y);
    return npts;
}

/* g *= den x - num for the end e = num/den: the end becomes a breakpoint */
static void _mul_end(fmpz_poly_t g, const fmpq_t e)
{
    fmpz_poly_t l;
    fmpz_poly_init(l);
    fmpz_poly_set_coeff_fmpz(l, 1, fmpq_denref(e));
    fmpz_poly_set_coeff_fmpz(l, 0, fmpq_numref(e));
    fmpz_neg(l->coeffs + 0, l->coeffs + 0);
    fmpz_poly_mul(g, g, l);
    fmpz_poly_clear(l);
}

int
rs_positivity_none_positive(const fmpz_mpoly_struct *const *poly, slong n, slong x, const rs_bound_t *b,
                            const fmpz_mpoly_ctx_t ctx)
{
    fmpz_poly_struct *u = flint_malloc((n + 1) * sizeof(fmpz_poly_struct));
    fmpz_poly_t g, sq;
    acb_ptr r = NULL;
    arb_ptr re = NULL;
    fmpq_t pt, y;
    slong i, j, d = 0, nr = 0, prec = 64;
    int res = 0, ok = 1;

    for (i = 0; i < n; i++)
        fmpz_poly_init(u + i);
    fmpz_poly_init(g);
    fmpz_poly_init(sq);
    fmpq_init(pt);
    fmpq_init(y);
    if (b != NULL && rs_bound_empty(b))
        goto done;   /* the assumptions' own contradiction: not ours to report */
    fmpz_poly_one(g);
    for (i = 0; i < n && ok; i++) {
        ok = fmpz_mpoly_get_fmpz_poly(u + i, poly[i], x, ctx) && !fmpz_poly_is_zero(u + i);
        if (ok && fmpz_poly_degree(u + i) >= 1) {
            rs_fmpz_poly_squarefree_part(sq, u + i);
            fmpz_poly_mul(g, g, sq);
        }
    }
    if (!ok)
        goto done;
    /* the interval's ends as breakpoints too: then the conditions' signs
     * are constant on each gap, and an open set meeting the interval meets
     * a gap inside it (a single point is tested as itself) */
    if (b != NULL && b->has_lo && b->has_hi && fmpq_equal(b->lo, b->hi)) {
        fmpq_set(pt, b->lo);
        nr = -1;
    } else {
        if (b != NULL && b->has_lo)
            _mul_end(g, b->lo);
        if (b != NULL && b->has_hi)
            _mul_end(g, b->hi);
        rs_fmpz_poly_squarefree_part(g, g);
        d = fmpz_poly_degree(g);
        if (d >= 1) {
            r = _acb_vec_init(d);
            re = _arb_vec_init(d);
            if ((nr = _real_roots_sorted(re, &prec, r, g)) < 0)
                goto done;
        }
    }
    /* one rational in each gap (or the single point): some admissible one
     * where every condition is > 0 (exact evaluation) decides "possible" */
    res = 1;
    for (i = (nr < 0 ? -1 : 0); i <= FLINT_MAX(nr, 0) && res; i++) {
        int all = 1;
        if (nr == 0)
            fmpq_zero(pt);
        else if (nr > 0)
            _gap_point(pt, re, nr, i, prec);   /* nr < 0: pt is the single point */
        if (b != NULL && !rs_bound_contains(b, pt))
            continue;
        for (j = 0; j < n && all; j++) {
            fmpz_poly_evaluate_fmpq(y, u + j, pt);
            all = fmpq_sgn(y) > 0;
        }
        if (all)
            res = 0;
        if (nr < 0)
            break;
    }
done:
    if (r != NULL) {
        _acb_vec_clear(r, d);
        _arb_vec_clear(re, d);
    }
    for (i = 0; i < n; i++)
        fmpz_poly_clear(u + i);
    flint_free(u);
    fmpz_poly_clear(g);
    fmpz_poly_clear(sq);
    fmpq_clear(pt);
    fmpq_clear(y);
    return res;
}
