/* an_region.c -- `region NAME [at P=V, ...]`: the exact set of NAME values
 * where the scheme is stable, marginal, unstable or singular, endpoints
 * exact (rational, or a real algebraic number whose status is decided in
 * Q[t]/(minpoly)); with other parameters symbolic, the conditions on NAME. */
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <arb.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>
#include <arb_poly.h>
#include <fmpq_vec.h>
#include "analysis/registry.h"
#include "analysis/an_region.h"
#include "analysis/an_qd.h"
#include "recstab/bilinear.h"
#include "recstab/semisimple.h"
#include "util/polyfmt.h"

/* "NAME=VALUE, NAME=VALUE" into assignments; *end is where parsing stopped */
static int parse_assignments(rs_run_t *run, const rs_request_t *q, const char *t, rs_assign_t **out,
                             slong *nout)
{
    rs_assign_t *a = NULL;
    slong n = 0;
    *out = NULL;
    *nout = 0;
    for (;;) {
        char name[80];
        const char *u = rs_req_read_name(t, name), *v;
        char *num;
        size_t len;
        slong idx;
        rs_error_t e2;
        int r;
        if (u == NULL) {
            /* the values parsed so far are freed too */
            r = rs_req_error(run, q, rs_req_skip_blanks(t), RS_ERR_INPUT, "expected NAME=VALUE after 'at', found '%s'", rs_req_skip_blanks(t));
            rs_assign_free(a, n);
            return r;
        }
        idx = rs_case_param_index(run->c, name);
        if (idx < 0) {
            r = rs_req_error(run, q, rs_req_skip_blanks(t), RS_ERR_INPUT, "'%s' is not a parameter", name);
            rs_assign_free(a, n);
            return r;
        }
        u = rs_req_skip_blanks(u);
        if (*u != '=') {
            r = rs_req_error(run, q, u, RS_ERR_INPUT, "expected '=' after the name, found '%s'", u);
            rs_assign_free(a, n);
            return r;
        }
        v = u + 1;
        len = strcspn(v, ",");
        num = malloc(len + 1);
        memcpy(num, v, len);
        num[len] = '\0';
        a = realloc(a, (size_t) (n + 1) * sizeof(rs_assign_t));
        a[n].name = run->c->params[idx].name;
        a[n].var = idx;
        fmpq_init(a[n].value);
        rs_error_init(e2);
        r = rs_expr_parse_number(a[n].value, num, e2);
        free(num);
        n++;
        if (r != RS_OK) {
            rs_assign_free(a, n);
            return rs_req_error(run, q, v, RS_ERR_INPUT, "expected a number: %s", e2->msg);
        }
        t = v + len;
        if (*t == ',') { t++; continue; }
        break;
    }
    *out = a;
    *nout = n;
    return RS_OK;
}

/* b^d p(lambda; a/b), d = deg_t p: an integer polynomial in lambda with the
 * same roots as p(lambda; t) at t = a/b. */
static void eval_at(fmpz_poly_t out, const fmpz_mpoly_t p, slong tv, const fmpq_t t, const rs_scheme_t s)
{
    slong d = fmpz_mpoly_degree_si(p, tv, s->zctx), j;
    fmpz_poly_t c;
    fmpz_t w, aj, bj;
    fmpz_poly_init(c);
    fmpz_init(w); fmpz_init(aj); fmpz_init(bj);
    fmpz_poly_zero(out);
    for (j = 0; j <= d; j++) {
        rs_run_coeff_in(c, p, tv, j, s);
        fmpz_pow_ui(aj, fmpq_numref(t), (ulong) j);
        fmpz_pow_ui(bj, fmpq_denref(t), (ulong) (d - j));
        fmpz_mul(w, aj, bj);
        fmpz_poly_scalar_mul_fmpz(c, c, w);
        fmpz_poly_add(out, out, c);
    }
    fmpz_poly_clear(c);
    fmpz_clear(w); fmpz_clear(aj); fmpz_clear(bj);
}

/* ---- real algebraic numbers ------------------------------------------------ */

#define CRIT_LC 1     /* leading coefficient in lambda: degree drop */
#define CRIT_PM1 2    /* p(1) or p(-1): a root at lambda = +-1 */
#define CRIT_D 4      /* D_{n-1} of q: a pair z, -z (circle pair or real pair) */
#define CRIT_DISC 8   /* discriminant: a repeated root */
#define CRIT_TOUCH (CRIT_LC | CRIT_PM1 | CRIT_D)

typedef rs_alg_t alg_t;

static void alg_init(alg_t *a)
{
    fmpz_poly_init(a->minpoly);
    fmpq_init(a->q);
    arb_init(a->x);
    a->idx = 0;
    a->rational = 0;
    a->prec = 0;
    a->boundary = 1;
}

static void alg_clear(alg_t *a)
{
    fmpz_poly_clear(a->minpoly);
    fmpq_clear(a->q);
    arb_clear(a->x);
}

/* recompute the enclosure to at least prec bits */
static void alg_refine(alg_t *a, slong prec)
{
    if (a->rational) {
        arb_set_fmpq(a->x, a->q, prec + 10);
        a->prec = prec;
        return;
    }
    if (a->prec >= prec) return;
    {
        slong d = fmpz_poly_degree(a->minpoly);
        acb_ptr r = _acb_vec_init(d);
        rs_radius_complex_roots(r, a->minpoly, prec);
        arb_set(a->x, acb_realref(r + a->idx));
        _acb_vec_clear(r, d);
        a->prec = prec;
    }
}

/* -1, 0, 1 (a and b are distinct unless they are the same root) */
static int alg_cmp(alg_t *a, alg_t *b)
{
    slong prec = 64;
    if (a->rational && b->rational) return fmpq_cmp(a->q, b->q);
    if (fmpz_poly_equal(a->minpoly, b->minpoly) && a->idx == b->idx) return 0;
    for (;;) {
        alg_refine(a, prec);
        alg_refine(b, prec);
        if (arb_lt(a->x, b->x)) return -1;
        if (arb_gt(a->x, b->x)) return 1;
        prec *= 2;
        if (prec > 1 << 20) return 0; /* cannot happen for distinct algebraic numbers */
    }
}

/* The 128-bit enclosures of the real roots of irreducible factors already
 * isolated in this region NAME for all (its two projections and the
 * neighbours' critical values meet the same factors again): set by
 * region_forall_object for its duration, NULL otherwise. */
typedef struct {
    fmpz_poly_struct *g;
    arb_ptr *x;
    slong *nreal;
    slong n;
} roots_memo_t;

static _Thread_local roots_memo_t *roots_memo = NULL;

static void roots_memo_clear(roots_memo_t *m)
{
    slong i;
    for (i = 0; i < m->n; i++) {
        fmpz_poly_clear(m->g + i);
        _arb_vec_clear(m->x[i], m->nreal[i]);
    }
    flint_free(m->g);
    flint_free(m->x);
    flint_free(m->nreal);
    memset(m, 0, sizeof *m);
}

/* ---- real roots of an irreducible polynomial, exactly (issue 13) ----------
 * The critical values of `region` are real roots of small integer
 * polynomials (degree 2-3 for HHT-alpha and Park); Arb's complex root finder
 * costs about 0.65 M instructions for each, even at low precision.  Here:
 * Descartes' rule of signs on dyadic intervals isolates them (the
 * Vincent-Collins-Akritas bisection), and bisection on exact integer signs
 * narrows each to relative width 2^-(prec+2).  g is irreducible of degree
 * >= 2, so no dyadic point is a root and every sign is non-zero. */

/* sign variations of (1+x)^d Q(1/(1+x)): the Descartes bound of Q on (0, 1) */
static slong descartes_01(const fmpz_poly_t Q, fmpz_poly_t t)
{
    slong i, v = 0, last = 0;
    fmpz one = 1;   /* a small fmpz */
    fmpz_poly_reverse(t, Q, fmpz_poly_length(Q));
    fmpz_poly_taylor_shift(t, t, &one);
    for (i = 0; i < fmpz_poly_length(t); i++) {
        int sg = fmpz_sgn(t->coeffs + i);
        if (sg == 0) continue;
        if (last != 0 && sg != last) v++;
        last = sg;
    }
    return v;
}

/* isolates the roots of Q on (0, 1), which is (k, k+1) 2^-j of P's (0, 1):
 * appends (k, j) of each isolating interval, ascending; 0 past the depth */
static int isolate_01(fmpz **ks, slong **js, slong *n, const fmpz_poly_t Q,
                      const fmpz_t k, slong j, fmpz_poly_t t)
{
    slong v = descartes_01(Q, t), d, i;
    fmpz_poly_t L, R;
    fmpz_t k2;
    fmpz one = 1;
    int ok;
    if (v == 0) return 1;
    if (v == 1) {
        *ks = flint_realloc(*ks, (size_t) (*n + 1) * sizeof(fmpz));
        *js = flint_realloc(*js, (size_t) (*n + 1) * sizeof(slong));
        fmpz_init_set((*ks) + *n, k);
        (*js)[*n] = j;
        (*n)++;
        return 1;
    }
    if (j > 2000) return 0;
    d = fmpz_poly_degree(Q);
    fmpz_poly_init(L); fmpz_poly_init(R); fmpz_init(k2);
    /* L(x) = 2^d Q(x/2) on the left half, R(x) = L(x + 1) on the right */
    fmpz_poly_set(L, Q);
    for (i = 0; i < d; i++) fmpz_mul_2exp(L->coeffs + i, L->coeffs + i, (ulong) (d - i));
    fmpz_poly_taylor_shift(R, L, &one);
    fmpz_mul_2exp(k2, k, 1);
    ok = isolate_01(ks, js, n, L, k2, j + 1, t);
    fmpz_add_ui(k2, k2, 1);
    if (ok) ok = isolate_01(ks, js, n, R, k2, j + 1, t);
    fmpz_poly_clear(L); fmpz_poly_clear(R); fmpz_clear(k2);
    return ok;
}

/* sign of g(m / 2^t), t >= 0: of sum c_i m^i 2^(t (d - i)) */
static int sign_at_dyadic(const fmpz_poly_t g, const fmpz_t m, slong t, fmpz_t acc, fmpz_t tmp)
{
    slong d = fmpz_poly_degree(g), i;
    fmpz_set(acc, g->coeffs + d);
    for (i = d - 1; i >= 0; i--) {
        fmpz_mul(acc, acc, m);
        fmpz_mul_2exp(tmp, g->coeffs + i, (ulong) (t * (d - i)));
        fmpz_add(acc, acc, tmp);
    }
    return fmpz_sgn(acc);
}

/* sign of g at the dyadic arf v */
static int sign_at_arf(const fmpz_poly_t g, const arf_t v, fmpz_t acc, fmpz_t tmp)
{
    fmpz_t m, e;
    int sg;
    fmpz_init(m); fmpz_init(e);
    arf_get_fmpz_2exp(m, e, v);
    if (fmpz_sgn(e) >= 0) {
        fmpz_mul_2exp(m, m, fmpz_get_ui(e));
        sg = sign_at_dyadic(g, m, 0, acc, tmp);
    } else {
        fmpz_neg(e, e);
        sg = sign_at_dyadic(g, m, fmpz_get_si(e), acc, tmp);
    }
    fmpz_clear(m); fmpz_clear(e);
    return sg;
}

/* exact bisection of (a, b) / 2^tt (g's sign sa at a) until b - a <= 2^-bits
 * min(|a|, |b|) with a, b of one sign; 0 if tt would pass maxtt first */
static int bisect_rel(const fmpz_poly_t g, fmpz_t a, fmpz_t b, slong *ptt, int sa, slong bits, slong maxtt,
                      fmpz_t m, fmpz_t acc, fmpz_t tmp)
{
    for (;;) {
        fmpz_sub(m, b, a);
        fmpz_mul_2exp(m, m, (ulong) bits);
        if (fmpz_sgn(a) == fmpz_sgn(b) && fmpz_sgn(a) != 0
            && fmpz_cmpabs(m, fmpz_cmpabs(a, b) < 0 ? a : b) <= 0)
            return 1;
        if (*ptt > maxtt) return 0;
        fmpz_mul_2exp(a, a, 1);
        fmpz_mul_2exp(b, b, 1);
        (*ptt)++;
        fmpz_add(m, a, b);
        fmpz_fdiv_q_2exp(m, m, 1);
        if (sign_at_dyadic(g, m, *ptt, acc, tmp) == sa) fmpz_swap(a, m);
        else fmpz_swap(b, m);
    }
}

/* x := a ball of relative radius <= 2^-(prec+2) around the one root of g in
 * (a, b) / 2^tt (sign sa at a), by bisection to 2^-24 and Newton's method
 * in Arb; 1 if two exact signs inside (a, b) confirm it, else 0 (a, b and
 * *tt narrowed to a smaller isolating interval, x untouched) */
static int newton_bracket(arb_t x, const fmpz_poly_t g, const fmpz_poly_t dg,
                          fmpz_t a, fmpz_t b, slong *ptt, int sa, slong prec,
                          fmpz_t acc, fmpz_t tmp)
{
    slong tt = *ptt;
    slong wp = prec + 40, it, e;
    arb_t y, dy, z;
    arf_t lo, hi, al, bl, dl;
    fmpz_t m, ex;
    int ok = 0;
    fmpz_init(m); fmpz_init(ex);
    /* exact bisection while b - a > 2^-24 min(|a|, |b|), at most 400 steps */
    bisect_rel(g, a, b, &tt, sa, 24, tt + 399, m, acc, tmp);
    *ptt = tt;   /* the caller's bisection goes on from (a, b) / 2^tt */
    arb_init(y); arb_init(dy); arb_init(z);
    arf_init(lo); arf_init(hi); arf_init(al); arf_init(bl); arf_init(dl);
    fmpz_set_si(ex, -tt);
    arf_set_fmpz_2exp(al, a, ex);
    arf_set_fmpz_2exp(bl, b, ex);
    arf_add(arb_midref(z), al, bl, ARF_PREC_EXACT, ARF_RND_DOWN);
    arf_mul_2exp_si(arb_midref(z), arb_midref(z), -1);
    for (it = 0; it < 12; it++) {
        arb_fmpz_poly_evaluate_arb(y, g, z, wp);
        arb_fmpz_poly_evaluate_arb(dy, dg, z, wp);
        if (arb_contains_zero(dy)) break;
        arb_div(y, y, dy, wp);
        arb_sub(z, z, y, wp);
        mag_zero(arb_radref(z));
        /* converged: the step is below 2^-(prec+8) |z| */
        if (arf_cmpabs_2exp_si(arb_midref(y), arf_abs_bound_lt_2exp_si(arb_midref(z)) - prec - 9) < 0)
            break;
    }
    if (!arf_is_zero(arb_midref(z)) && arf_is_finite(arb_midref(z))) {
        /* lo, hi = z -+ 2^(e - prec - 5), |z| < 2^e: width <= 2^-(prec+3) |z| */
        e = arf_abs_bound_lt_2exp_si(arb_midref(z));
        arf_one(dl);
        arf_mul_2exp_si(dl, dl, e - prec - 5);
        arf_sub(lo, arb_midref(z), dl, ARF_PREC_EXACT, ARF_RND_DOWN);
        arf_add(hi, arb_midref(z), dl, ARF_PREC_EXACT, ARF_RND_DOWN);
        if (arf_cmp(al, lo) <= 0 && arf_cmp(hi, bl) <= 0
            && arf_sgn(lo) == arf_sgn(hi)
            && sign_at_arf(g, lo, acc, tmp) == sa && sign_at_arf(g, hi, acc, tmp) == -sa) {
            arb_set_interval_arf(x, lo, hi, prec + 16);
            ok = 1;
        }
    }
    arb_clear(y); arb_clear(dy); arb_clear(z);
    arf_clear(lo); arf_clear(hi); arf_clear(al); arf_clear(bl); arf_clear(dl);
    fmpz_clear(m); fmpz_clear(ex);
    return ok;
}

int rs_region_real_roots(arb_ptr x, const fmpz_poly_t g, slong nreal, slong prec)
{
    slong d = fmpz_poly_degree(g), e, i, s, n = 0, nneg = 0, *js = NULL;
    fmpz *ks = NULL;
    fmpz_poly_t P, t, dg;
    fmpz_t a, b, m, acc, tmp, k0;
    arf_t lo, hi;
    int ok = 1;
    /* Fujiwara: |root| <= 2 max_i |c_i / c_d|^(1/(d-i)) < 2^e, with
     * |c_i / c_d| < 2^(bits c_i - bits c_d + 1) (e may be negative) */
    e = WORD_MIN;
    for (i = 0; i < d; i++) {
        slong num = (slong) fmpz_bits(g->coeffs + i) - (slong) fmpz_bits(g->coeffs + d) + 1, q;
        if (fmpz_is_zero(g->coeffs + i)) continue;
        q = num >= 0 ? (num + (d - i) - 1) / (d - i) : -((-num) / (d - i));   /* ceil */
        if (q + 1 > e) e = q + 1;
    }
    fmpz_poly_init(P); fmpz_poly_init(t); fmpz_poly_init(dg);
    fmpz_poly_derivative(dg, g);
    fmpz_init(a); fmpz_init(b); fmpz_init(m); fmpz_init(acc); fmpz_init(tmp); fmpz_init(k0);
    arf_init(lo); arf_init(hi);
    /* negative roots first (s = -1), then positive: P(x) = g(s 2^e x) on (0, 1) */
    for (s = -1; s <= 1 && ok; s += 2) {
        fmpz_poly_set(P, g);   /* (times 2^(-e d) if e < 0) */
        for (i = 0; i <= d; i++) {
            fmpz_mul_2exp(P->coeffs + i, P->coeffs + i, (ulong) (e >= 0 ? e * i : -e * (d - i)));
            if (s < 0 && (i & 1)) fmpz_neg(P->coeffs + i, P->coeffs + i);
        }
        ok = isolate_01(&ks, &js, &n, P, k0, 0, t);
        if (s < 0) nneg = n;
    }
    ok = ok && n == nreal;
    for (i = 0; i < n && ok; i++) {
        /* the root in (a, b) / 2^tt: the interval (k, k+1) 2^(e-j), of -x
         * on the negative side; listed ascending (the negative side reversed) */
        slong r = i < nneg ? nneg - 1 - i : i, tt = js[r] - e;
        int sa;
        if (i < nneg) {
            fmpz_add_ui(a, ks + r, 1);
            fmpz_neg(a, a);
        } else {
            fmpz_set(a, ks + r);
        }
        fmpz_add_ui(b, a, 1);
        if (tt < 0) {
            fmpz_mul_2exp(a, a, (ulong) -tt);
            fmpz_mul_2exp(b, b, (ulong) -tt);
            tt = 0;
        }
        sa = sign_at_dyadic(g, a, tt, acc, tmp);
        /* bisection to 2^-24 relative, then Newton in Arb from the midpoint
         * and two exact signs around its result (the isolating interval
         * holds one root: a sign change inside it brackets that root); the
         * bisection to the end if they do not confirm it */
        if (newton_bracket(x + i, g, dg, a, b, &tt, sa, prec, acc, tmp))
            continue;
        /* until (b - a) 2^(prec+2) <= min(|a|, |b|) (a, b of one sign) */
        if (!bisect_rel(g, a, b, &tt, sa, prec + 2, 4 * prec + 4000, m, acc, tmp)) { ok = 0; break; }
        fmpz_set_si(tmp, -tt);
        arf_set_fmpz_2exp(lo, a, tmp);
        arf_set_fmpz_2exp(hi, b, tmp);
        arb_set_interval_arf(x + i, lo, hi, prec + 16);
    }
    for (i = 0; i < n; i++) fmpz_clear(ks + i);
    flint_free(ks); flint_free(js);
    fmpz_poly_clear(P); fmpz_poly_clear(t); fmpz_poly_clear(dg);
    fmpz_clear(a); fmpz_clear(b); fmpz_clear(m); fmpz_clear(acc); fmpz_clear(tmp); fmpz_clear(k0);
    arf_clear(lo); arf_clear(hi);
    return ok;
}

/* the real roots of the irreducible g (degree >= 2), nreal of them, as
 * alg_refine(., 128) would enclose each: from the memo, or computed (once
 * for all of them) and kept there */
static arb_srcptr roots_real(const fmpz_poly_t g, slong nreal, arb_ptr tmp)
{
    roots_memo_t *m = roots_memo;
    slong d = fmpz_poly_degree(g), i;
    acb_ptr r;
    arb_ptr x;
    if (m != NULL)
        for (i = 0; i < m->n; i++)
            if (m->nreal[i] == nreal && fmpz_poly_equal(m->g + i, g)) return m->x[i];
    r = NULL;
    if (m == NULL) {
        x = tmp;
    } else {
        m->g = flint_realloc(m->g, (size_t) (m->n + 1) * sizeof(fmpz_poly_struct));
        m->x = flint_realloc(m->x, (size_t) (m->n + 1) * sizeof(arb_ptr));
        m->nreal = flint_realloc(m->nreal, (size_t) (m->n + 1) * sizeof(slong));
        fmpz_poly_init(m->g + m->n);
        fmpz_poly_set(m->g + m->n, g);
        m->x[m->n] = x = _arb_vec_init(nreal);
        m->nreal[m->n] = nreal;
        m->n++;
    }
    /* exact isolation; Arb's complex roots (real ones first, ascending: the
     * same order) if it did not find FLINT's count of real roots */
    if (!rs_region_real_roots(x, g, nreal, 128)) {
        r = _acb_vec_init(d);
        rs_radius_complex_roots(r, g, 128);
        for (i = 0; i < nreal; i++) arb_set(x + i, acb_realref(r + i));
        _acb_vec_clear(r, d);
    }
    return x;
}

/* appends the real roots of f (any non-zero polynomial) as alg_t */
static void alg_roots_append(alg_t **list, slong *n, const fmpz_poly_t f, int boundary)
{
    fmpz_poly_factor_t fac;
    slong i, k, n0 = *n;
    if (fmpz_poly_degree(f) < 1) return;
    fmpz_poly_factor_init(fac);
    fmpz_poly_factor(fac, f);
    for (i = 0; i < fac->num; i++) {
        const fmpz_poly_struct *g = fac->p + i;
        slong d = fmpz_poly_degree(g), nreal;
        if (d < 1) continue;
        if (d == 1) {
            *list = realloc(*list, (size_t) (*n + 1) * sizeof(alg_t));
            alg_init(*list + *n);
            fmpz_poly_set((*list)[*n].minpoly, g);
            (*list)[*n].rational = 1;
            fmpq_set_fmpz_frac((*list)[*n].q, g->coeffs + 0, g->coeffs + 1);
            fmpq_neg((*list)[*n].q, (*list)[*n].q);
            alg_refine(*list + *n, 128);
            (*n)++;
            continue;
        }
        nreal = fmpz_poly_num_real_roots(g);
        if (nreal > 0) {
            /* the roots once per factor, each real one's enclosure as
             * alg_refine(., 128) would compute it (real roots first) */
            arb_ptr tmp = roots_memo == NULL ? _arb_vec_init(nreal) : NULL;
            arb_srcptr x = roots_real(g, nreal, tmp);
            for (k = 0; k < nreal; k++) {
                *list = realloc(*list, (size_t) (*n + 1) * sizeof(alg_t));
                alg_init(*list + *n);
                fmpz_poly_set((*list)[*n].minpoly, g);
                (*list)[*n].idx = k;
                arb_set((*list)[*n].x, x + k);
                (*list)[*n].prec = 128;
                (*n)++;
            }
            if (tmp != NULL) _arb_vec_clear(tmp, nreal);
        }
    }
    for (i = n0; i < *n; i++) (*list)[i].boundary = boundary;
    fmpz_poly_factor_clear(fac);
}

/* JSON form of an endpoint: "p/q" for rationals; for algebraic numbers an
 * object with the minimal polynomial, an isolating interval and 30 digits. */
static json_t *alg_json(alg_t *a, const char *var)
{
    char *mp, *s;
    json_t *o;
    arf_t lo, hi;
    fmpq_t ql, qh;
    if (a->rational) return rs_json_fmpq(a->q);
    alg_refine(a, 128);
    o = json_object();
    mp = rs_polyfmt_fmpz_poly(a->minpoly, var);
    json_object_set_new(o, "minpoly", json_string(mp));
    free(mp);
    json_object_set_new(o, "root_index", json_integer(a->idx));
    arf_init(lo); arf_init(hi);
    fmpq_init(ql); fmpq_init(qh);
    arb_get_lbound_arf(lo, a->x, 128);
    arb_get_ubound_arf(hi, a->x, 128);
    arf_get_fmpq(ql, lo);
    arf_get_fmpq(qh, hi);
    json_object_set_new(o, "interval", json_pack("[o,o]", rs_json_fmpq(ql), rs_json_fmpq(qh)));
    s = rs_radius_arb_str(a->x, 30);   /* certified digits only */
    json_object_set_new(o, "approx", json_string(s));
    flint_free(s);
    arf_clear(lo); arf_clear(hi);
    fmpq_clear(ql); fmpq_clear(qh);
    return o;
}

static double alg_double(alg_t *a)
{
    alg_refine(a, 64);
    return arf_get_d(arb_midref(a->x), ARF_RND_NEAR);
}

/* a rational strictly between a and b (a < b); NULL ends are infinite */
static void rational_between(fmpq_t out, alg_t *a, alg_t *b)
{
    if (a == NULL && b == NULL) { fmpq_zero(out); return; }
    if (b == NULL || a == NULL) {
        /* an integer beyond the end: past the rational end itself, or past
         * the far bound of the certified enclosure of an algebraic end (the
         * midpoint of a 64-bit ball of 2*10^40 is off by about 10^21) */
        alg_t *e = a ? a : b;
        fmpz_t f;
        arf_t bd;
        fmpz_init(f);
        arf_init(bd);
        if (e->rational) {
            if (a) { fmpz_fdiv_q(f, fmpq_numref(e->q), fmpq_denref(e->q)); fmpz_add_ui(f, f, 1); }
            else { fmpz_cdiv_q(f, fmpq_numref(e->q), fmpq_denref(e->q)); fmpz_sub_ui(f, f, 1); }
        } else {
            alg_refine(e, 64);
            if (a) { arb_get_ubound_arf(bd, e->x, 64); arf_get_fmpz(f, bd, ARF_RND_FLOOR); fmpz_add_ui(f, f, 1); }
            else { arb_get_lbound_arf(bd, e->x, 64); arf_get_fmpz(f, bd, ARF_RND_CEIL); fmpz_sub_ui(f, f, 1); }
        }
        fmpz_set(fmpq_numref(out), f);
        fmpz_one(fmpq_denref(out));
        arf_clear(bd);
        fmpz_clear(f);
        return;
    }
    {
        slong prec = 64;
        arf_t u, l;
        arf_init(u); arf_init(l);
        for (;;) {
            /* a < b are distinct, so this ends; the check bounds the cost */
            if (rs_budget_check(NULL, "the region") != RS_OK) break;
            alg_refine(a, prec);
            alg_refine(b, prec);
            arb_get_ubound_arf(u, a->x, prec);
            arb_get_lbound_arf(l, b->x, prec);
            if (arf_cmp(u, l) < 0) break;
            prec *= 2;
        }
        /* the simplest rational in (u, l): try small denominators first */
        {
            fmpq_t qu, ql, t;
            fmpz_t den;
            int found = 0;
            fmpq_init(qu); fmpq_init(ql); fmpq_init(t);
            fmpz_init(den);
            arf_get_fmpq(qu, u);
            arf_get_fmpq(ql, l);
            for (fmpz_one(den); !found && fmpz_cmp_ui(den, 1024) <= 0; fmpz_mul_ui(den, den, 2)) {
                fmpz_t k;
                fmpz_init(k);
                /* k = floor(qu * den) + 1 */
                fmpz_mul(k, fmpq_numref(qu), den);
                fmpz_fdiv_q(k, k, fmpq_denref(qu));
                fmpz_add_ui(k, k, 1);
                fmpq_set_fmpz_frac(t, k, den);
                if (fmpq_cmp(t, qu) > 0 && fmpq_cmp(t, ql) < 0) { fmpq_set(out, t); found = 1; }
                fmpz_clear(k);
            }
            if (!found) {
                fmpq_add(out, qu, ql);
                fmpq_div_2exp(out, out, 1);
            }
            fmpq_clear(qu); fmpq_clear(ql); fmpq_clear(t);
            fmpz_clear(den);
        }
        arf_clear(u); arf_clear(l);
    }
}

/* ---- status at an algebraic point, exactly ---------------------------------- */

/* Arithmetic in K = Q[t]/(m), m the minimal polynomial of the real algebraic
 * t0: an element is an fmpq_poly of degree < deg m; it is zero at t0 iff it
 * is the zero polynomial, so its sign at t0 is decided by refining Arb
 * enclosures of t0 until the value's ball excludes 0 (always terminates).
 * Polynomials in lambda over K are arrays of such elements, c[0..deg]. */
typedef struct {
    slong deg;             /* -1 for the zero polynomial */
    fmpq_poly_struct *c;   /* deg + 1 coefficients (capacity cap) */
    slong cap;
} kpoly_t;

static void kp_init(kpoly_t *a, slong cap)
{
    slong i;
    a->cap = cap > 0 ? cap : 1;
    a->deg = -1;
    a->c = flint_malloc(a->cap * sizeof(fmpq_poly_struct));
    for (i = 0; i < a->cap; i++) fmpq_poly_init(a->c + i);
}

static void kp_clear(kpoly_t *a)
{
    slong i;
    for (i = 0; i < a->cap; i++) fmpq_poly_clear(a->c + i);
    flint_free(a->c);
}

static void kp_normalise(kpoly_t *a)
{
    while (a->deg >= 0 && fmpq_poly_is_zero(a->c + a->deg)) a->deg--;
}

static void kp_set(kpoly_t *a, const kpoly_t *b)
{
    slong i;
    for (i = 0; i < a->cap; i++) {
        if (i <= b->deg) fmpq_poly_set(a->c + i, b->c + i);
        else fmpq_poly_zero(a->c + i);
    }
    a->deg = b->deg;
}

/* sign of x(t0), x reduced mod m */
static int k_sign(const fmpq_poly_t x, alg_t *t0)
{
    slong prec = 64;
    arb_poly_t ap;
    arb_t y;
    int s = 0;
    if (fmpq_poly_is_zero(x)) return 0;
    arb_poly_init(ap);
    arb_init(y);
    for (; s == 0; prec *= 2) {
        alg_refine(t0, prec);
        arb_poly_set_fmpq_poly(ap, x, prec);
        arb_poly_evaluate(y, ap, t0->x, prec);
        if (arb_is_positive(y)) s = 1;
        else if (arb_is_negative(y)) s = -1;
    }
    arb_poly_clear(ap);
    arb_clear(y);
    return s;
}

static void k_mul(fmpq_poly_t out, const fmpq_poly_t a, const fmpq_poly_t b, const fmpq_poly_t m)
{
    fmpq_poly_mul(out, a, b);
    fmpq_poly_rem(out, out, m);
}

/* 1/a in K (a != 0: gcd(a, m) = 1 as m is irreducible) */
static void k_inv(fmpq_poly_t out, const fmpq_poly_t a, const fmpq_poly_t m)
{
    fmpq_poly_t g, t;
    fmpq_poly_init(g);
    fmpq_poly_init(t);
    fmpq_poly_xgcd(g, out, t, a, m);
    fmpq_poly_clear(g);
    fmpq_poly_clear(t);
}

/* a = q b + r in K[lambda] (b != 0); q may be NULL */
static void kp_divrem(kpoly_t *q, kpoly_t *r, const kpoly_t *a, const kpoly_t *b, const fmpq_poly_t m)
{
    fmpq_poly_t inv, f, t;
    slong i, d;
    fmpq_poly_init(inv); fmpq_poly_init(f); fmpq_poly_init(t);
    kp_set(r, a);
    if (q != NULL) { for (i = 0; i < q->cap; i++) fmpq_poly_zero(q->c + i); q->deg = -1; }
    if (fmpq_poly_is_one(b->c + b->deg)) fmpq_poly_one(inv);   /* monic (kp_gcd's, x -+ 1) */
    else k_inv(inv, b->c + b->deg, m);
    while (r->deg >= b->deg) {
        d = r->deg - b->deg;
        k_mul(f, r->c + r->deg, inv, m);
        if (q != NULL) { fmpq_poly_set(q->c + d, f); if (q->deg < d) q->deg = d; }
        for (i = 0; i <= b->deg; i++) {
            k_mul(t, f, b->c + i, m);
            fmpq_poly_sub(r->c + i + d, r->c + i + d, t);
        }
        fmpq_poly_zero(r->c + r->deg);   /* exactly cancelled */
        kp_normalise(r);
    }
    fmpq_poly_clear(inv); fmpq_poly_clear(f); fmpq_poly_clear(t);
}

/* a /= its leading coefficient (a != 0).  Monic remainders keep the
 * coefficients in K to the size of subresultant quotients; the plain
 * remainder sequence squares them at every step (a degree-15 BDF2 region
 * spent 9 s in the inversions of swollen leading coefficients). */
static void kp_make_monic(kpoly_t *a, const fmpq_poly_t m)
{
    fmpq_poly_t inv;
    slong i;
    if (a->deg < 0) return;
    fmpq_poly_init(inv);
    k_inv(inv, a->c + a->deg, m);
    for (i = 0; i < a->deg; i++) k_mul(a->c + i, a->c + i, inv, m);
    fmpq_poly_one(a->c + a->deg);
    fmpq_poly_clear(inv);
}

static void kp_primitive(kpoly_t *a);

/* r = the pseudo-remainder lc(b)^e a mod b in K[lambda] (b != 0): no
 * inversion in K */
static void kp_prem(kpoly_t *r, const kpoly_t *a, const kpoly_t *b, const fmpq_poly_t m)
{
    fmpq_poly_t f, t;
    slong i, d;
    fmpq_poly_init(f); fmpq_poly_init(t);
    kp_set(r, a);
    while (r->deg >= b->deg) {
        d = r->deg - b->deg;
        fmpq_poly_set(f, r->c + r->deg);
        /* r = lc(b) r - lc(r) lambda^d b */
        for (i = 0; i < r->deg; i++) k_mul(r->c + i, r->c + i, b->c + b->deg, m);
        for (i = 0; i < b->deg; i++) {
            k_mul(t, f, b->c + i, m);
            fmpq_poly_sub(r->c + i + d, r->c + i + d, t);
        }
        fmpq_poly_zero(r->c + r->deg);   /* exactly cancelled */
        kp_normalise(r);
    }
    fmpq_poly_clear(f); fmpq_poly_clear(t);
}

/* g = gcd(a, b), monic (Euclid in K[lambda] with pseudo-remainders made
 * primitive over Q, one inversion at the end; not both zero) */
static void kp_gcd(kpoly_t *g, const kpoly_t *a, const kpoly_t *b, const fmpq_poly_t m)
{
    slong cap = FLINT_MAX(a->cap, b->cap);
    kpoly_t x, y, r;
    kp_init(&x, cap); kp_init(&y, cap); kp_init(&r, cap);
    kp_set(&x, a);
    kp_set(&y, b);
    kp_primitive(&x);
    kp_primitive(&y);
    while (y.deg >= 0) {
        /* coefficients in Q[t]/(m) can swell: stop with the budget (sticky:
         * rs_analysis_run reports it and discards the result) */
        if (rs_budget_check(NULL, "the status at an algebraic endpoint") != RS_OK) break;
        kp_prem(&r, &x, &y, m);
        kp_primitive(&r);
        kp_set(&x, &y);
        kp_set(&y, &r);
    }
    kp_make_monic(&x, m);
    kp_set(g, &x);
    kp_clear(&x); kp_clear(&y); kp_clear(&r);
}

/* a divided by the positive rational content of its coefficients (a != 0) */
static void kp_primitive(kpoly_t *a)
{
    fmpq_t c, g;
    slong i;
    fmpq_init(c); fmpq_init(g);
    for (i = 0; i <= a->deg; i++) {
        fmpq_poly_content(c, a->c + i);
        if (fmpq_is_zero(g)) fmpq_set(g, c);
        else if (!fmpq_is_zero(c)) fmpq_gcd(g, g, c);
    }
    if (!fmpq_is_zero(g) && !fmpq_is_one(g))
        for (i = 0; i <= a->deg; i++) fmpq_poly_scalar_div_fmpq(a->c + i, a->c + i, g);
    fmpq_clear(c); fmpq_clear(g);
}

/* every root strictly inside the unit circle: the Schur-Cohn recursion
 * p_{k-1} = (a_k p_k - a_0 p_k^*)/lambda with a_k^2 - a_0^2 > 0 at each
 * step (Schur 1917), signs at t0 exact */
static int kp_all_inside(const kpoly_t *p, const fmpq_poly_t m, alg_t *t0)
{
    kpoly_t a, b;
    fmpq_poly_t d, t, u;
    slong k, j;
    int ok = 1;
    kp_init(&a, p->deg + 1); kp_init(&b, p->deg + 1);
    fmpq_poly_init(d); fmpq_poly_init(t); fmpq_poly_init(u);
    kp_set(&a, p);
    for (k = a.deg; k >= 1 && ok && rs_budget_check(NULL, "the status at an algebraic endpoint") == RS_OK; k--) {
        k_mul(t, a.c + k, a.c + k, m);
        k_mul(u, a.c + 0, a.c + 0, m);
        fmpq_poly_sub(d, t, u);
        if (k_sign(d, t0) <= 0) { ok = 0; break; }
        /* b_j = a_k a_{j+1} - a_0 a_{k-1-j}, j = 0..k-1 */
        for (j = 0; j < k; j++) {
            k_mul(t, a.c + k, a.c + j + 1, m);
            k_mul(u, a.c + 0, a.c + k - 1 - j, m);
            fmpq_poly_sub(b.c + j, t, u);
        }
        for (j = k; j < b.cap; j++) fmpq_poly_zero(b.c + j);
        b.deg = k - 1;      /* lead b_{k-1} = a_k^2 - a_0^2 != 0 */
        /* dividing by a positive rational scales every later a_k^2 - a_0^2
         * by a positive square: the signs stay; the rational content keeps
         * the sizes down without an inversion in K (making b monic did,
         * issue 15: AB3's region spent a fifth of its time there) */
        kp_primitive(&b);
        kp_set(&a, &b);
    }
    kp_clear(&a); kp_clear(&b);
    fmpq_poly_clear(d); fmpq_poly_clear(t); fmpq_poly_clear(u);
    return ok;
}

/* multiplicity of the root x0 = +-1 of a (non-zero) in K[lambda] */
static slong kp_mult_pm1(const kpoly_t *a, slong x0, const fmpq_poly_t m)
{
    kpoly_t b, lin, r;
    slong k = 0;
    kp_init(&b, a->deg + 1); kp_init(&lin, 2); kp_init(&r, a->deg + 1);
    fmpq_poly_set_si(lin.c + 0, -x0);
    fmpq_poly_one(lin.c + 1);
    lin.deg = 1;
    kp_set(&b, a);
    while (b.deg >= 1) {
        kpoly_t q;
        kp_init(&q, b.deg + 1);
        kp_divrem(&q, &r, &b, &lin, m);
        if (r.deg >= 0) { kp_clear(&q); break; }
        kp_set(&b, &q);
        kp_clear(&q);
        k++;
    }
    kp_clear(&b); kp_clear(&lin); kp_clear(&r);
    return k;
}

/* A system at t0 whose circle roots are all on the circle, R = the repeated
 * part of gcd(p, p*): marginal iff each repeated root is semisimple.  Only
 * +-1 are judged (dim ker A(+-1; t0) by the rank over Q[t]/(minpoly)); a
 * repeated non-real circle root leaves *decided = 0. */
static rs_status_t semisimple_pm1(int *decided, const kpoly_t *P, const kpoly_t *R, const fmpz_mpoly_t p,
                                  slong tv, alg_t *t0, const fmpq_poly_t m, const rs_scheme_t s)
{
    slong x0, n = s->n, i, rest = R->deg;
    rs_status_t st = RS_STATUS_MARGINAL;
    fmpq_poly_struct *A = flint_malloc(n * n * sizeof(fmpq_poly_struct));
    fmpq_mpoly_t e;
    fmpq_t xv;
    (void) p;
    fmpq_mpoly_init(e, s->ctx);
    fmpq_init(xv);
    for (i = 0; i < n * n; i++) fmpq_poly_init(A + i);
    for (x0 = -1; x0 <= 1; x0 += 2) {
        slong k = kp_mult_pm1(R, x0, m), mult, rank;
        if (k == 0) continue;
        rest -= k;
        mult = kp_mult_pm1(P, x0, m);
        fmpq_set_si(xv, x0, 1);
        for (i = 0; i < n * n; i++) {
            fmpq_mpoly_evaluate_one_fmpq(e, s->M + i, s->lambda_var, xv, s->ctx);
            if (!fmpq_mpoly_get_fmpq_poly(A + i, e, tv, s->ctx)) { *decided = 0; goto done; }
        }
        rank = rs_semisimple_rank_mod(A, n, t0->minpoly);
        if (n - rank != mult) st = RS_STATUS_UNSTABLE;   /* a Jordan block at x0 */
    }
    if (rest > 0 && st != RS_STATUS_UNSTABLE) *decided = 0;   /* a repeated non-real circle root */
done:
    for (i = 0; i < n * n; i++) fmpq_poly_clear(A + i);
    flint_free(A);
    fmpq_mpoly_clear(e, s->ctx);
    fmpq_clear(xv);
    return st;
}

/* Status of p(lambda; t0), t0 an irrational real algebraic number, exactly:
 * singular where the leading coefficient vanishes; else with
 * g = gcd(p, p*) (every circle root, every pair r, 1/r; self-reciprocal):
 * stable iff p has all roots inside; unstable if p/g (no circle roots) has
 * a root outside or g is not squarefree (a repeated circle root or a
 * repeated pair); otherwise g has all roots on the circle,
 * simple, iff g' has all roots strictly inside (Cohn 1922 with
 * Gauss-Lucas): marginal, else a pair off the circle: unstable.  A system
 * with a repeated circle root: marginal iff semisimple (semisimple_pm1);
 * returns 0 (undecided) only for a repeated non-real circle root there. */
static int status_kp(rs_status_t *out, kpoly_t *P0, slong n, const fmpz_mpoly_t p, slong tv, alg_t *t0,
                     const fmpq_poly_t m, const rs_scheme_t s);
static int status_kp_mode(rs_status_t *out, kpoly_t *P0, slong n, const fmpz_mpoly_t p, slong tv, alg_t *t0,
                          const fmpq_poly_t m, const rs_scheme_t s, int scalar);

/* a = f as a polynomial in lambda over K = Q[t]/(m) (f in Z[t, lambda]
 * only), degree n */
static void kp_from_mpoly(kpoly_t *a, const fmpz_mpoly_t f, slong n, slong tv, const fmpq_poly_t m,
                          const rs_scheme_struct *s)
{
    slong j;
    fmpz_mpoly_struct *c = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    fmpz_poly_t u;
    fmpz_poly_init(u);
    for (j = 0; j <= n; j++) fmpz_mpoly_init(c + j, s->zctx);
    rs_polyfmt_coeffs(c, f, s->lambda_var, s->zctx);
    for (j = 0; j <= n; j++) {
        if (!fmpz_mpoly_get_fmpz_poly(u, c + j, tv, s->zctx)) fmpz_poly_zero(u);
        fmpq_poly_set_fmpz_poly(a->c + j, u);
        fmpq_poly_rem(a->c + j, a->c + j, m);
        fmpz_mpoly_clear(c + j, s->zctx);
    }
    flint_free(c);
    a->deg = n;
    kp_normalise(a);
    fmpz_poly_clear(u);
}

/* p(lambda; t0) over K = Q[t]/(m), m = t0's minimal polynomial: P and m
 * initialised here (cleared by the caller); returns p's degree in lambda */
static slong kp_at_algebraic(kpoly_t *P, fmpq_poly_t m, const fmpz_mpoly_t p, slong tv, const alg_t *t0,
                             const rs_scheme_t s)
{
    slong n = fmpz_mpoly_degree_si(p, s->lambda_var, s->zctx);
    fmpq_poly_init(m);
    fmpq_poly_set_fmpz_poly(m, t0->minpoly);
    kp_init(P, n + 1);
    kp_from_mpoly(P, p, n, tv, m, s);
    return n;
}

static int status_at_algebraic(rs_status_t *out, const fmpz_mpoly_t p, slong tv, alg_t *t0, const rs_scheme_t s)
{
    int decided;
    fmpq_poly_t m;
    kpoly_t P;
    slong n = kp_at_algebraic(&P, m, p, tv, t0, s);
    decided = status_kp(out, &P, n, p, tv, t0, m, s);
    kp_clear(&P);
    fmpq_poly_clear(m);
    return decided;
}

/* 1 when p(lambda; t0) is the zero polynomial (t0 a zero of p's content in
 * lambda), t0 an irrational real algebraic number */
static int vanishes_at_algebraic(const fmpz_mpoly_t p, slong tv, const alg_t *t0, const rs_scheme_t s)
{
    int z;
    fmpq_poly_t m;
    kpoly_t P;
    kp_at_algebraic(&P, m, p, tv, t0, s);
    z = P.deg < 0;
    kp_clear(&P);
    fmpq_poly_clear(m);
    return z;
}

/* the status of P0 = sum c_j lambda^j of formal degree n over K = Q[t]/(m);
 * p, tv: the scheme's polynomial with t0 for tv (the semisimplicity test of
 * a system's repeated circle root); p == NULL: that case left undecided */
static int status_kp(rs_status_t *out, kpoly_t *P0, slong n, const fmpz_mpoly_t p, slong tv, alg_t *t0,
                     const fmpq_poly_t m, const rs_scheme_t s)
{
    return status_kp_mode(out, P0, n, p, tv, t0, m, s, 0);
}

/* scalar: P0 is one scalar recurrence's polynomial (a repeated circle root
 * is unstable), whatever the scheme */
static int status_kp_mode(rs_status_t *out, kpoly_t *P0, slong n, const fmpz_mpoly_t p, slong tv, alg_t *t0,
                          const fmpq_poly_t m, const rs_scheme_t s, int scalar)
{
    int decided = 1;
    slong j;
    kpoly_t P, R, G, H, D;
    rs_status_t st;
    kp_init(&P, n + 1); kp_init(&R, n + 1); kp_init(&G, n + 1); kp_init(&H, n + 1); kp_init(&D, n + 1);
    for (j = 0; j <= n; j++) fmpq_poly_set(P.c + j, P0->c + j);
    P.deg = n;
    kp_normalise(&P);
    if (P.deg < n) {
        st = RS_STATUS_SINGULAR;     /* no step: the leading coefficient is 0 at t0 */
    } else {
        for (j = 0; j <= n; j++) fmpq_poly_set(R.c + j, P.c + n - j);
        R.deg = n;
        kp_normalise(&R);
        kp_gcd(&G, &P, &R, m);
        if (G.deg <= 0) {
            st = kp_all_inside(&P, m, t0) ? RS_STATUS_STABLE : RS_STATUS_UNSTABLE;
        } else {
            kp_divrem(&H, &R, &P, &G, m);
            st = RS_STATUS_UNSTABLE;
            if (kp_all_inside(&H, m, t0)) {
                for (j = 0; j < G.deg; j++) {             /* D = G' */
                    fmpq_poly_scalar_mul_si(D.c + j, G.c + j + 1, j + 1);
                }
                D.deg = G.deg - 1;
                kp_normalise(&D);
                kp_gcd(&R, &G, &D, m);
                if (R.deg == 0 && kp_all_inside(&D, m, t0)) {
                    st = RS_STATUS_MARGINAL;
                } else if (R.deg > 0 && !scalar && s->n >= 2 && !s->from_char) {
                    /* a repeated root of g: if every root of g is on the
                     * circle (its squarefree part G/R passes Cohn's test) a
                     * system may still be bounded: semisimple roots */
                    kp_divrem(&H, &D, &G, &R, m);
                    kp_set(&G, &H);
                    for (j = 0; j < G.deg; j++) fmpq_poly_scalar_mul_si(D.c + j, G.c + j + 1, j + 1);
                    for (j = G.deg; j < D.cap; j++) fmpq_poly_zero(D.c + j);
                    D.deg = G.deg - 1;
                    kp_normalise(&D);
                    if (kp_all_inside(&D, m, t0)) {
                        if (p != NULL) st = semisimple_pm1(&decided, &P, &R, p, tv, t0, m, s);
                        else decided = 0;
                    }
                }
            }
        }
    }
    *out = st;
    kp_clear(&P); kp_clear(&R); kp_clear(&G); kp_clear(&H); kp_clear(&D);
    return decided;
}

/* ---- region ------------------------------------------------------------------ */

/* univariate polynomial in variable tv from an mpoly in t only (else 0) */
static int to_upoly(fmpz_poly_t out, const fmpz_mpoly_t p, slong tv, const rs_scheme_t s)
{
    return fmpz_mpoly_get_fmpz_poly(out, p, tv, s->zctx);
}

typedef struct {
    int is_point;        /* a single value, or the open interval between */
    alg_t *lo, *hi;      /* NULL = infinite (intervals); for points lo == hi */
    int decided;         /* status known exactly */
    rs_status_t status;
    int vanishes;        /* a singular point where p vanishes identically */
    json_t *ev;          /* for all: the certificate or counterexample */
} piece_t;

/* The exact verdict of v at t (system-aware; "singular" where the degree in
 * lambda drops); RS_ERR_MATH when p vanishes identically at t. */
static int status_at(rs_status_t *st, rs_run_t *run, const rs_variant_t *v, slong tv, const fmpq_t t)
{
    rs_rootcount_t rc;
    int r = rs_run_point_status(st, rc, run, v, &tv, t, 1);
    rs_rootcount_clear(rc);
    if (r == RS_OK && *st == RS_STATUS_SINGULAR) {
        /* singular also where p vanishes identically: that one is an error
         * (evaluated only here, not at every point) */
        fmpz_poly_t u;
        fmpz_poly_init(u);
        eval_at(u, v->cp->p, tv, t, v->s);
        if (fmpz_poly_is_zero(u)) r = RS_ERR_MATH;
        fmpz_poly_clear(u);
    }
    return r;
}

static void sort_algs(alg_t *a, slong n)
{
    slong i, j;
    for (i = 1; i < n; i++)       /* insertion sort: n is small */
        for (j = i; j > 0 && alg_cmp(a + j - 1, a + j) > 0; j--) {
            alg_t t = a[j - 1];
            a[j - 1] = a[j];
            a[j] = t;
        }
}

/* region in one parameter when other parameters are still symbolic: the
 * conditions as functions of them (Hurwitz/Lienard-Chipart, factored). */
static int region_symbolic(rs_run_t *run, rs_variant_t *v, json_t *o)
{
    int verdict, r = rs_run_symbolic_conditions(run, v, o, &verdict);
    if (r == RS_OK) {
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "note", json_string(
            "other parameters are symbolic: stable iff every condition holds (Lienard-Chipart on the "
            "bilinear polynomial, factors positive under the assumptions dropped; an OR of branches where the "
            "sign of its leading coefficient is free); a region valid for all admissible values is what "
            "`claim stable when ...` proves or refutes"));
    }
    return r;
}

static int param_is_set(const rs_run_t *run, slong k)
{
    slong i;
    for (i = 0; i < run->c->nsets; i++)
        if (strcmp(run->c->sets[i].name, run->c->params[k].name) == 0) return 1;
    return 0;
}

/* a parse error at t: "expected WHAT, found 'text'" or "..., found end of line" */
static int forall_error(rs_run_t *run, const rs_request_t *q, const char *t, const char *what)
{
    char buf[200];
    if (*t == '\0') snprintf(buf, sizeof buf, "expected %s, found end of line", what);
    else snprintf(buf, sizeof buf, "expected %s, found '%.80s'", what, t);
    return rs_req_error(run, q, t, RS_ERR_INPUT, "%s", buf);
}

/* "all [P1, P2, ...]" after `region NAME for`: the quantified parameters (no
 * list: every parameter neither NAME nor set) */
static int parse_forall(rs_an_req_t *req, rs_run_t *run, const char *t)
{
    const rs_request_t *q = req->q;
    slong np = run->c->nparams, k, tv = req->u.region.param;
    char name[80];
    req->u.region.forall = 1;
    req->u.region.qv = flint_malloc((np + 1) * sizeof(slong));
    req->u.region.nq = 0;
    if (strncmp(t, "all", 3) != 0 || !(t[3] == ' ' || t[3] == '\t' || t[3] == '\0' || t[3] == '['))
        return forall_error(run, q, t, "'all' after 'for'");
    t = rs_req_skip_blanks(t + 3);
    if (*t == '\0') {
        for (k = 0; k < np; k++)
            if (k != tv && !param_is_set(run, k)) req->u.region.qv[req->u.region.nq++] = k;
        return RS_OK;
    }
    if (*t != '[')
        return forall_error(run, q, t, "'[' or end of line after 'for all'");
    t = rs_req_skip_blanks(t + 1);
    for (;;) {
        const char *u = rs_req_read_name(t, name);
        slong i;
        if (u == NULL)
            return forall_error(run, q, t, "a parameter name in 'for all [...]'");
        k = rs_case_param_index(run->c, name);
        if (k < 0) return rs_req_error(run, q, t, RS_ERR_INPUT, "'%s' is not a parameter", name);
        if (k == tv)
            return rs_req_error(run, q, t, RS_ERR_INPUT, "the region parameter '%s' cannot also be quantified", name);
        if (param_is_set(run, k))
            return rs_req_error(run, q, t, RS_ERR_INPUT, "'%s' is set to a value: it cannot be quantified", name);
        for (i = 0; i < req->u.region.nq; i++)
            if (req->u.region.qv[i] == k)
                return rs_req_error(run, q, t, RS_ERR_INPUT, "'%s' is quantified twice", name);
        req->u.region.qv[req->u.region.nq++] = k;
        t = rs_req_skip_blanks(u);
        if (*t == ',') { t = rs_req_skip_blanks(t + 1); continue; }
        if (*t == ']') break;
        return forall_error(run, q, t, "',' or ']' in 'for all [...]'");
    }
    t = rs_req_skip_blanks(t + 1);
    if (*t != '\0') return forall_error(run, q, t, "end of line after ']'");
    /* every parameter left symbolic must be quantified */
    for (k = 0; k < np; k++) {
        slong i;
        int in = k == tv || param_is_set(run, k);
        for (i = 0; i < run->c->ncsets && !in; i++)   /* a complex set value: refused later, by name */
            in = strcmp(run->c->csets[i].name, run->c->params[k].name) == 0;
        for (i = 0; i < req->u.region.nq && !in; i++) in = req->u.region.qv[i] == k;
        if (!in)
            return rs_req_error(run, q, req->rest, RS_ERR_INPUT,
                                "'%s' is neither set nor quantified: add it to 'for all [...]' or set it",
                                run->c->params[k].name);
    }
    return RS_OK;
}

/* region NAME [at P=V, ...]: the parameter and the values, checked up front */
int rs_an_region_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *rest = req->rest, *t;
    char name[80];
    slong i;
    int r;
    t = rs_req_read_name(rest, name);
    if (t == NULL)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "expected a parameter name after region, found '%s'", rest);
    req->u.region.param = rs_case_param_index(run->c, name);
    if (req->u.region.param < 0)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "'%s' is not a parameter", name);
    t = rs_req_skip_blanks(t);
    if (*t == ',') {
        /* region N1, N2: the exact set in the plane (an_region_cad.c) */
        const char *u = rs_req_skip_blanks(t + 1);
        t = rs_req_read_name(u, name);
        if (t == NULL)
            return rs_req_error(run, q, u, RS_ERR_INPUT, "expected a second parameter name after ',', found '%s'", u);
        req->u.region.param2 = rs_case_param_index(run->c, name);
        if (req->u.region.param2 < 0) return rs_req_error(run, q, u, RS_ERR_INPUT, "'%s' is not a parameter", name);
        if (req->u.region.param2 == req->u.region.param)
            return rs_req_error(run, q, u, RS_ERR_INPUT, "the two region parameters must differ ('%s' twice)", name);
        req->u.region.twod = 1;
        t = rs_req_skip_blanks(t);
        if (strncmp(t, "at", 2) == 0 && (t[2] == ' ' || t[2] == '\t')) {
            r = parse_assignments(run, q, t + 2, &req->u.region.at, &req->u.region.nat);
            if (r != RS_OK) return r;
        } else if (*t != '\0') {
            return rs_req_error(run, q, t, RS_ERR_INPUT, "expected 'at NAME=VALUE, ...' or end of line, found '%s'", t);
        }
        for (i = 0; i < req->u.region.nat; i++)
            if (req->u.region.at[i].var == req->u.region.param || req->u.region.at[i].var == req->u.region.param2)
                return rs_req_error(run, q, rest, RS_ERR_INPUT, "%s", "a region parameter is also given a value");
        return RS_OK;
    }
    if (strncmp(t, "at", 2) == 0 && (t[2] == ' ' || t[2] == '\t')) {
        r = parse_assignments(run, q, t + 2, &req->u.region.at, &req->u.region.nat);
        if (r != RS_OK) return r;
    } else if (strncmp(t, "for", 3) == 0 && (t[3] == ' ' || t[3] == '\t')) {
        return parse_forall(req, run, rs_req_skip_blanks(t + 3));
    } else if (*t != '\0') {
        return rs_req_error(run, q, t, RS_ERR_INPUT,
                            "expected 'at NAME=VALUE, ...', 'for all [NAME, ...]' or end of line, found '%s'", t);
    }
    for (i = 0; i < req->u.region.nat; i++)
        if (req->u.region.at[i].var == req->u.region.param)
            return rs_req_error(run, q, rest, RS_ERR_INPUT, "the region parameter '%s' is also given a value", name);
    return RS_OK;
}

/* The region of one parameter at numbers for the others: its domain, the
 * critical values (where a root can reach the circle or the degree drop),
 * the pieces between them and their exact statuses. */
typedef struct {
    rs_run_t *run;
    const rs_request_t *q;
    const char *rest, *name;
    const rs_variant_t *v;
    const rs_scheme_struct *s;
    slong tv;                   /* the parameter's variable */
    rs_bound_t *bounds;         /* from the assume lines */
    int have_lo, have_hi, single;
    alg_t lo_end, hi_end;
    fmpz_mpoly_t pt;            /* the part of p that depends on t */
    fmpz_mpoly_t sqf, sqf_t;    /* squarefree part of p; of its factors with t */
    int repeated_always;        /* the discriminant vanishes for every t */
    int d_always;               /* D_{n-1} of q vanishes for every t */
    alg_t *crit;
    slong ncrit;
    piece_t *pieces;
    slong npieces;
    int forall;                 /* region NAME for all [...] */
    const slong *qv;            /* ... over these parameters */
    slong nq;
    const char *projection;     /* which projection decided the cells */
    const rs_bound_t *dom_tv;   /* a claim's interval of t (replaces the assumed one) */
    int cx;                     /* complex set values: p = cre + i cim over Q(i)[t] */
    fmpz_mpoly_t cre, cim;
    const fmpz_mpoly_struct *pj;   /* the polynomial judged: v's p, or |p|^2 over Q(i) */
    fmpz_mpoly_t pabs;          /* |p|^2 = cre^2 + cim^2 (cx only) */
    slong ncx_checked;          /* samples decided by both Q(i) routes */
    struct forall_memo *memo;   /* for all: verdicts at samples, kept across the two projections */
    slong nmemo;
    struct point_crit_memo *pcm; /* for all: forall_point_crit's critical values per point */
    slong npcm;
    alg_t *pcrit;               /* for all, full projection: the per-condition one's critical values */
    slong npcrit;
} region_t;

/* The critical values of t with the quantified parameters at one point (a
 * counterexample, usually handed on from cell to cell: the same point
 * serves several irrational critical values) */
typedef struct point_crit_memo {
    char *key;                  /* the point's quantified values, "name=value;..." */
    int ok;
    alg_t *crit;
    slong ncrit;
} point_crit_memo_t;

/* One decision of region NAME for all at a rational sample (mode = the
 * search_first argument of rs_an_forall_cell) or on [t, hi] (mode = 10 +
 * kind of rs_an_forall_prove): a deterministic function of its arguments,
 * so the full projection, whose critical values include the per-condition
 * projection's, takes the verdicts of the cells both share instead of
 * deciding them again (the same evidence, copied). */
typedef struct forall_memo {
    fmpq_t t, hi;
    int mode;
    rs_status_t st;
    int decided;
    json_t *ev;
} forall_memo_t;

static forall_memo_t *memo_find(region_t *rg, const fmpq_t t, const fmpq_t hi, int mode)
{
    slong i;
    for (i = 0; i < rg->nmemo; i++) {
        forall_memo_t *m = rg->memo + i;
        if (m->mode == mode && fmpq_equal(m->t, t) && (hi == NULL || fmpq_equal(m->hi, hi))) return m;
    }
    return NULL;
}

/* a cell's evidence is kept by reference (copied on use): after the cell
 * only its "sample" is added, the same value again on reuse; a proof's
 * evidence is copied at once (the caller adds the interval's own keys) */
static void memo_add(region_t *rg, const fmpq_t t, const fmpq_t hi, int mode, rs_status_t st, int decided,
                     const json_t *ev)
{
    forall_memo_t *m;
    rg->memo = flint_realloc(rg->memo, (size_t) (rg->nmemo + 1) * sizeof(forall_memo_t));
    m = rg->memo + rg->nmemo++;
    fmpq_init(m->t);
    fmpq_init(m->hi);
    fmpq_set(m->t, t);
    if (hi != NULL) fmpq_set(m->hi, hi);
    m->mode = mode;
    m->st = st;
    m->decided = decided;
    m->ev = ev == NULL ? NULL : mode >= 10 ? json_deep_copy(ev) : json_incref((json_t *) ev);
}

static void memo_clear(region_t *rg)
{
    slong i;
    for (i = 0; i < rg->nmemo; i++) {
        fmpq_clear(rg->memo[i].t);
        fmpq_clear(rg->memo[i].hi);
        json_decref(rg->memo[i].ev);
    }
    flint_free(rg->memo);
    rg->memo = NULL;
    rg->nmemo = 0;
}

/* The squarefree parts of p (a system keeps repeated factors: identical
 * modes) and the values where a repeated factor's Jordan structure can
 * change: where the rank of A modulo it can drop. */
static void region_squarefree(region_t *rg)
{
    const rs_scheme_struct *s = rg->s;
    slong tv = rg->tv, ndrops = 0, k;
    fmpz_mpoly_factor_t fac;
    fmpz_poly_struct *drops = NULL;
    fmpz_mpoly_one(rg->sqf, s->zctx);
    fmpz_mpoly_one(rg->sqf_t, s->zctx);
    fmpz_mpoly_factor_init(fac, s->zctx);
    if (rs_factor_memo_factor(fac, rg->v->cp->p, s->zctx)) {
        for (k = 0; k < fac->num; k++) {
            fmpz_mpoly_struct *f = fac->poly + k;
            int has_l = fmpz_mpoly_degree_si(f, s->lambda_var, s->zctx) > 0;
            if (has_l) fmpz_mpoly_mul(rg->sqf, rg->sqf, f, s->zctx);
            if (fmpz_mpoly_degree_si(f, tv, s->zctx) > 0) fmpz_mpoly_mul(rg->sqf_t, rg->sqf_t, f, s->zctx);
            if (has_l && fmpz_cmp_ui(fac->exp + k, 2) >= 0)
                rs_semisimple_rank_drops(&drops, &ndrops, s, tv, f);
        }
    } else {
        fmpz_mpoly_set(rg->sqf, rg->pt, s->zctx);
        fmpz_mpoly_set(rg->sqf_t, rg->pt, s->zctx);
    }
    for (k = 0; k < ndrops; k++) {
        alg_roots_append(&rg->crit, &rg->ncrit, drops + k, CRIT_LC | CRIT_DISC);
        fmpz_poly_clear(drops + k);
    }
    flint_free(drops);
    fmpz_mpoly_factor_clear(fac, s->zctx);
}

/* A pair of roots crossing the circle elsewhere than +-1: the zeros of
 * D_{n-1} of q (or d_always when it vanishes for every t). */
static void region_crit_pairs(region_t *rg, fmpz_poly_t u)
{
    const rs_scheme_struct *s = rg->s;
    slong lv = s->lambda_var, tv = rg->tv;
    rs_hurwitz_t hown;
    const rs_hurwitz_struct *h = hown;
    fmpz_mpoly_t qz;
    fmpz_mpoly_init(qz, s->zctx);
    rs_hurwitz_init(hown);
    rs_bilinear_fmpz_mpoly(qz, rg->sqf_t, lv, s->zctx);
    /* no sign information (NULL: all unknown); the same q as the for-all
     * projection's: kept in its memo when one is in force */
    if (fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 2
        && rs_hurwitz_memo_compute(&h, hown, qz, lv, s->zctx, rg->run->err) == RS_OK
        && h->n >= 2) {
        if (fmpz_mpoly_is_zero(h->minors + h->n - 2, s->zctx))
            rg->d_always = 1;   /* pairs z, -z for every value: circle roots may persist */
        else if (to_upoly(u, h->minors + h->n - 2, tv, s))
            alg_roots_append(&rg->crit, &rg->ncrit, u, CRIT_D);
    }
    rs_hurwitz_clear(hown, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
}

/* The critical values of t: the leading coefficient in lambda vanishes, a
 * root at lambda = 1 or -1, a pair crossing the circle, a collision. */
static void region_critical(region_t *rg)
{
    const rs_scheme_struct *s = rg->s;
    slong lv = s->lambda_var, tv = rg->tv, n = fmpz_mpoly_degree_si(rg->pt, lv, s->zctx);
    ulong nn = (ulong) n;
    fmpz_mpoly_t tmp;
    fmpz_poly_t u;
    fmpz_t pm;
    if (fmpz_mpoly_degree_si(rg->pt, tv, s->zctx) <= 0) return;
    fmpz_mpoly_init(tmp, s->zctx);
    fmpz_poly_init(u);
    fmpz_init(pm);
    /* leading coefficient in lambda */
    fmpz_mpoly_get_coeff_vars_ui(tmp, rg->pt, &lv, &nn, 1, s->zctx);
    if (to_upoly(u, tmp, tv, s)) alg_roots_append(&rg->crit, &rg->ncrit, u, CRIT_LC);
    /* roots at lambda = 1 and lambda = -1 */
    fmpz_set_si(pm, 1);
    fmpz_mpoly_evaluate_one_fmpz(tmp, rg->sqf_t, lv, pm, s->zctx);
    if (!fmpz_mpoly_is_zero(tmp, s->zctx) && to_upoly(u, tmp, tv, s)) alg_roots_append(&rg->crit, &rg->ncrit, u, CRIT_PM1);
    fmpz_set_si(pm, -1);
    fmpz_mpoly_evaluate_one_fmpz(tmp, rg->sqf_t, lv, pm, s->zctx);
    if (!fmpz_mpoly_is_zero(tmp, s->zctx) && to_upoly(u, tmp, tv, s)) alg_roots_append(&rg->crit, &rg->ncrit, u, CRIT_PM1);
    if (n >= 2) region_crit_pairs(rg, u);
    /* collisions (roots leaving the circle through a double root) */
    if (fmpz_mpoly_degree_si(rg->sqf, lv, s->zctx) >= 2) {
        if (!fmpz_mpoly_discriminant(tmp, rg->sqf, lv, s->zctx) || fmpz_mpoly_is_zero(tmp, s->zctx))
            rg->repeated_always = 1;
        else if (to_upoly(u, tmp, tv, s))
            alg_roots_append(&rg->crit, &rg->ncrit, u, rg->d_always ? (CRIT_DISC | CRIT_D) : CRIT_DISC);
    }
    fmpz_poly_clear(u);
    fmpz_clear(pm);
    fmpz_mpoly_clear(tmp, s->zctx);
}

/* Sorted, without duplicates (their reasons merged) and without values
 * outside the open domain. */
static void region_crit_prune(region_t *rg)
{
    slong i, k = 0;
    sort_algs(rg->crit, rg->ncrit);
    for (i = 0; i < rg->ncrit; i++) {
        alg_t *crit = rg->crit;
        int keepit = 1;
        if (k > 0 && alg_cmp(crit + k - 1, crit + i) == 0) {
            keepit = 0;
            crit[k - 1].boundary |= crit[i].boundary;
        }
        if (keepit && rg->have_lo && alg_cmp(crit + i, &rg->lo_end) <= 0) keepit = 0;
        if (keepit && rg->have_hi && alg_cmp(crit + i, &rg->hi_end) >= 0) keepit = 0;
        if (keepit) {
            if (k != i) { alg_t tt = crit[k]; crit[k] = crit[i]; crit[i] = tt; }
            k++;
        }
    }
    for (i = k; i < rg->ncrit; i++) alg_clear(rg->crit + i);
    rg->ncrit = k;
}

/* pieces: [lo], (lo, c1), c1, ..., (ck, hi), [hi] */
static void region_pieces(region_t *rg)
{
    const rs_bound_t *bt = rg->bounds + rg->tv;
    piece_t *pieces = calloc((size_t) (2 * rg->ncrit + 4), sizeof(piece_t));
    slong i, npieces = 0, ncrit = rg->ncrit;
    if (rg->have_lo && bt->lo_closed) {
        pieces[npieces].is_point = 1; pieces[npieces].lo = pieces[npieces].hi = &rg->lo_end; npieces++;
    }
    for (i = 0; i <= ncrit && !rg->single; i++) {
        pieces[npieces].is_point = 0;
        pieces[npieces].lo = (i == 0) ? (rg->have_lo ? &rg->lo_end : NULL) : rg->crit + i - 1;
        pieces[npieces].hi = (i == ncrit) ? (rg->have_hi ? &rg->hi_end : NULL) : rg->crit + i;
        npieces++;
        if (i < ncrit) {
            pieces[npieces].is_point = 1; pieces[npieces].lo = pieces[npieces].hi = rg->crit + i; npieces++;
        }
    }
    if (rg->have_hi && bt->hi_closed && !(rg->have_lo && fmpq_equal(bt->lo, bt->hi))) {
        pieces[npieces].is_point = 1; pieces[npieces].lo = pieces[npieces].hi = &rg->hi_end; npieces++;
    }
    rg->pieces = pieces;
    rg->npieces = npieces;
}

/* ---- complex set values: p = A + i B over Q(i)[t] ---------------------------- */

/* out = a b in K[lambda] (out distinct from a and b) */
static void kp_mul(kpoly_t *out, const kpoly_t *a, const kpoly_t *b, const fmpq_poly_t m)
{
    slong i, j;
    fmpq_poly_t t;
    fmpq_poly_init(t);
    for (i = 0; i < out->cap; i++) fmpq_poly_zero(out->c + i);
    out->deg = (a->deg < 0 || b->deg < 0) ? -1 : a->deg + b->deg;
    for (i = 0; i <= a->deg; i++)
        for (j = 0; j <= b->deg; j++) {
            k_mul(t, a->c + i, b->c + j, m);
            fmpq_poly_add(out->c + i + j, out->c + i + j, t);
        }
    kp_normalise(out);
    fmpq_poly_clear(t);
}

/* The status of p = A + i B at t0 (real algebraic, or rational with a
 * linear minpoly) with real arithmetic in K = Q(t0) only: G = gcd(A, B) is
 * gcd(p, conj p) (real); p1 = p/G = A1 + i B1 has no root in common with
 * conj(p1) (a common root would be one of A1 and B1).  T = G (A1^2 + B1^2)
 * has the roots of p and their conjugates; a circle root mu of T has the
 * multiplicity of mu or of conj(mu) in p (both circle roots), so T's scalar
 * status (a repeated circle root unstable) is p's.  Never undecided. */
static void status_cx_alg(rs_status_t *out, const region_t *rg, alg_t *t0)
{
    const rs_scheme_struct *s = rg->s;
    slong lv = s->lambda_var, n, cap;
    fmpq_poly_t m;
    kpoly_t A, B, G, A1, B1, T, U, R;
    n = FLINT_MAX(fmpz_mpoly_degree_si(rg->cre, lv, s->zctx), fmpz_mpoly_degree_si(rg->cim, lv, s->zctx));
    cap = 2 * n + 2;
    fmpq_poly_init(m);
    fmpq_poly_set_fmpz_poly(m, t0->minpoly);
    kp_init(&A, cap); kp_init(&B, cap); kp_init(&G, cap); kp_init(&A1, cap); kp_init(&B1, cap);
    kp_init(&T, cap); kp_init(&U, cap); kp_init(&R, cap);
    kp_from_mpoly(&A, rg->cre, n, rg->tv, m, s);
    kp_from_mpoly(&B, rg->cim, n, rg->tv, m, s);
    if (n < 0 || (A.deg < n && B.deg < n)) {
        *out = RS_STATUS_SINGULAR;      /* the leading coefficient vanishes at t0 */
    } else if (B.deg < 0) {
        status_kp_mode(out, &A, A.deg, NULL, rg->tv, t0, m, s, 1);   /* p real at t0 */
    } else if (A.deg < 0) {
        status_kp_mode(out, &B, B.deg, NULL, rg->tv, t0, m, s, 1);   /* p = i B */
    } else {
        kp_gcd(&G, &A, &B, m);
        kp_divrem(&A1, &R, &A, &G, m);
        kp_divrem(&B1, &R, &B, &G, m);
        kp_mul(&T, &A1, &A1, m);
        kp_mul(&U, &B1, &B1, m);
        {
            slong j;
            for (j = 0; j <= U.deg; j++) fmpq_poly_add(T.c + j, T.c + j, U.c + j);
            if (U.deg > T.deg) T.deg = U.deg;
            kp_normalise(&T);
        }
        kp_mul(&U, &G, &T, m);
        status_kp_mode(out, &U, U.deg, NULL, rg->tv, t0, m, s, 1);
    }
    kp_clear(&A); kp_clear(&B); kp_clear(&G); kp_clear(&A1); kp_clear(&B1);
    kp_clear(&T); kp_clear(&U); kp_clear(&R);
    fmpq_poly_clear(m);
}

/* Complex set values: p = cre + i cim in Z[t, lambda] (the values
 * substituted, every other parameter set), |p|^2 = cre^2 + cim^2 the real
 * polynomial whose critical values are cut: it has p's roots and their
 * conjugates (same moduli), so where its squarefree part keeps its roots
 * distinct, off +-1 and off the circle (the real region's critical values)
 * p's roots keep their multiplicities and sides: one status per cell. */
static int region_cx_prepare(region_t *rg)
{
    const rs_scheme_struct *s = rg->s;
    slong k, lv = s->lambda_var;
    fmpz_mpoly_t g, sq;
    fmpz_mpoly_factor_t fac;
    int r = RS_OK;
    rs_run_cx_poly(rg->cre, rg->cim, rg->run, rg->v);
    for (k = 0; k < s->nvars; k++) {
        if (k == lv || k == rg->tv) continue;
        if (fmpz_mpoly_degree_si(rg->cre, k, s->zctx) > 0 || fmpz_mpoly_degree_si(rg->cim, k, s->zctx) > 0)
        {
            char msg[RS_ERROR_MSG_LEN];
            snprintf(msg, sizeof msg, "region %s at complex set values needs every other parameter set: '%s' has "
                     "no value (set it, or give it with `at %s=VALUE`)", rg->name, s->vars[k], s->vars[k]);
            return rs_req_error(rg->run, rg->q, rg->rest, RS_ERR_INPUT, "%s", msg);
        }
    }
    rg->cx = 1;
    fmpz_mpoly_init(sq, s->zctx);
    fmpz_mpoly_init(g, s->zctx);
    fmpz_mpoly_mul(rg->pabs, rg->cre, rg->cre, s->zctx);
    fmpz_mpoly_mul(sq, rg->cim, rg->cim, s->zctx);
    fmpz_mpoly_add(rg->pabs, rg->pabs, sq, s->zctx);
    rg->pj = rg->pabs;
    if (fmpz_mpoly_is_zero(rg->pabs, s->zctx)) {
        r = rs_req_error(rg->run, rg->q, rg->rest, RS_ERR_MATH, "the characteristic polynomial vanishes "
                         "identically at the complex set values%s", "");
    } else {
        if (!fmpz_mpoly_content_vars(g, rg->pabs, &rg->tv, 1, s->zctx) || fmpz_mpoly_is_zero(g, s->zctx))
            fmpz_mpoly_one(g, s->zctx);
        fmpz_mpoly_divexact(rg->pt, rg->pabs, g, s->zctx);
        /* squarefree parts as region_squarefree, scalar (no Jordan structure) */
        fmpz_mpoly_one(rg->sqf, s->zctx);
        fmpz_mpoly_one(rg->sqf_t, s->zctx);
        fmpz_mpoly_factor_init(fac, s->zctx);
        if (fmpz_mpoly_factor(fac, rg->pabs, s->zctx)) {
            for (k = 0; k < fac->num; k++) {
                fmpz_mpoly_struct *f = fac->poly + k;
                if (fmpz_mpoly_degree_si(f, lv, s->zctx) > 0) fmpz_mpoly_mul(rg->sqf, rg->sqf, f, s->zctx);
                if (fmpz_mpoly_degree_si(f, rg->tv, s->zctx) > 0) fmpz_mpoly_mul(rg->sqf_t, rg->sqf_t, f, s->zctx);
            }
        } else {
            fmpz_mpoly_set(rg->sqf, rg->pt, s->zctx);
            fmpz_mpoly_set(rg->sqf_t, rg->pt, s->zctx);
        }
        fmpz_mpoly_factor_clear(fac, s->zctx);
    }
    fmpz_mpoly_clear(sq, s->zctx);
    fmpz_mpoly_clear(g, s->zctx);
    return r;
}

/* The Q(i) point verdict at the rational t = x (complex Schur-Cohn and
 * Bilharz, agreeing) checked against status_cx_alg over K = Q (the real
 * gcd route): a disagreement is exit 3. */
static int status_at_cx(rs_status_t *st, region_t *rg, const fmpq_t x)
{
    const rs_scheme_struct *s = rg->s;
    rs_rootcount_t rc;
    rs_status_t st2;
    alg_t a;
    slong tv = rg->tv;
    int r;
    fmpq_poly_t pr, pi;
    fmpq *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
    slong k;
    for (k = 0; k < s->nvars; k++) pp[k] = pt + k;
    fmpq_set(pt + tv, x);
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    rs_run_cx_eval(pr, rg->cre, pp, s);
    rs_run_cx_eval(pi, rg->cim, pp, s);
    r = (fmpq_poly_is_zero(pr) && fmpq_poly_is_zero(pi)) ? RS_ERR_MATH : RS_OK;
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    if (r != RS_OK) return r;
    r = rs_run_point_status(st, rc, rg->run, rg->v, &tv, x, 1);
    rs_rootcount_clear(rc);
    if (r != RS_OK) return r;
    alg_init(&a);
    a.rational = 1;
    fmpq_set(a.q, x);
    fmpz_poly_set_coeff_fmpz(a.minpoly, 1, fmpq_denref(x));   /* den t - num */
    fmpz_poly_set_coeff_fmpz(a.minpoly, 0, fmpq_numref(x));
    fmpz_neg(a.minpoly->coeffs + 0, a.minpoly->coeffs + 0);
    alg_refine(&a, 128);
    status_cx_alg(&st2, rg, &a);
    alg_clear(&a);
    if (st2 != *st) {
        char *xs = fmpq_get_str(NULL, 10, x);
        char msg[RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "region %s over Q(i) at %s = %s: complex Schur-Cohn and Bilharz say %s, the real "
                 "route (gcd(Re p, Im p), |p/gcd|^2) says %s", rg->name, rg->name, xs, rs_status_name(*st),
                 rs_status_name(st2));
        r = rs_req_error(rg->run, rg->q, rg->rest, RS_ERR_INCONSISTENT, "%s", msg);
        flint_free(xs);
    } else {
        rg->ncx_checked++;
    }
    return r;
}

/* decide each piece exactly at a rational point */
static int region_decide(region_t *rg)
{
    slong i;
    int r = RS_OK;
    for (i = 0; i < rg->npieces && r == RS_OK; i++) {
        piece_t *pc = rg->pieces + i;
        fmpq_t x;
        fmpq_init(x);
        if (pc->is_point && !pc->lo->rational && rg->cx) {
            status_cx_alg(&pc->status, rg, pc->lo);
            pc->decided = 1;
            /* |p|^2 = Re^2 + Im^2 vanishes at a real t iff p does */
            if (pc->status == RS_STATUS_SINGULAR)
                pc->vanishes = vanishes_at_algebraic(rg->pabs, rg->tv, pc->lo, rg->s);
        } else if (pc->is_point && !pc->lo->rational) {
            pc->decided = status_at_algebraic(&pc->status, rg->v->cp->p, rg->tv, pc->lo, rg->s);
            if (pc->decided && pc->status == RS_STATUS_SINGULAR)
                pc->vanishes = vanishes_at_algebraic(rg->v->cp->p, rg->tv, pc->lo, rg->s);
        } else {
            if (pc->is_point) fmpq_set(x, pc->lo->q);
            else rational_between(x, pc->lo, pc->hi);
            r = rg->cx ? status_at_cx(&pc->status, rg, x) : status_at(&pc->status, rg->run, rg->v, rg->tv, x);
            if (r == RS_ERR_MATH && pc->is_point) {
                /* p = 0 at a critical value (a zero of its content in
                 * lambda): a one-point interval of its own, not an error */
                pc->status = RS_STATUS_SINGULAR;
                pc->vanishes = 1;
                r = RS_OK;
            } else if (r == RS_ERR_MATH) {
                char *xs = fmpq_get_str(NULL, 10, x);
                r = rs_req_error(rg->run, rg->q, rg->rest, RS_ERR_MATH,
                                 "the characteristic polynomial vanishes identically at %s", xs);
                flint_free(xs);
            }
            pc->decided = 1;
        }
        fmpq_clear(x);
    }
    return r;
}

/* for all: the critical values of the projection (the whole parameter line
 * is one cell when there are none), each cell decided at a rational sample,
 * an irrational critical value left undecided */
static int region_forall_critical(region_t *rg, int *full)
{
    fmpz_poly_struct *u = NULL;
    slong nu = 0, k;
    int r = rs_an_forall_critical(&u, &nu, rg->run, rg->v, rg->tv, rg->qv, rg->nq, rg->bounds, full);
    for (k = 0; k < nu; k++) {
        if (r == RS_OK) alg_roots_append(&rg->crit, &rg->ncrit, u + k, CRIT_TOUCH);
        fmpz_poly_clear(u + k);
    }
    flint_free(u);
    return r;
}

/* p with the quantified parameters at the rational point pt ({NAME: value}):
 * a polynomial in lambda and t (0 when pt lacks one of them) */
static int forall_at_point(fmpz_mpoly_t f, region_t *rg, const json_t *pt)
{
    const rs_scheme_struct *s = rg->s;
    fmpz_mpoly_t g;
    fmpq_t x;
    slong k;
    fmpz_mpoly_init(g, s->zctx);
    fmpq_init(x);
    fmpz_mpoly_set(f, rg->v->cp->p, s->zctx);
    for (k = 0; k < rg->nq; k++) {
        const char *w = json_string_value(json_object_get(pt, rg->run->c->params[rg->qv[k]].name));
        if (w == NULL || fmpq_set_str(x, w, 10) != 0) break;
        fmpq_canonicalise(x);
        rs_an_forall_subst(g, f, rg->qv[k], x, s->zctx);
        fmpz_mpoly_swap(f, g, s->zctx);
    }
    fmpz_mpoly_clear(g, s->zctx);
    fmpq_clear(x);
    return k == rg->nq && !fmpz_mpoly_is_zero(f, s->zctx);
}

/* The exact verdict at t = c (irrational) and the quantified parameters at
 * the rational point pt (a neighbour's counterexample {NAME: value}). */
static int forall_status_at(rs_status_t *st, region_t *rg, alg_t *c, const json_t *pt)
{
    fmpz_mpoly_t f;
    int decided;
    fmpz_mpoly_init(f, rg->s->zctx);
    decided = forall_at_point(f, rg, pt) && status_at_algebraic(st, f, rg->tv, c, rg->s);
    fmpz_mpoly_clear(f, rg->s->zctx);
    return decided;
}

/* The values of t where, with the quantified parameters at pt, a root can
 * cross the circle or escape to infinity (p's leading coefficient, its
 * t-dependent factors at lambda = +-1 and their D_{n-1}) or p vanishes
 * (factors free of lambda): between two of them an unstable verdict at pt
 * persists (a root strictly outside stays outside).  0 when they are not
 * finitely many. */
static int forall_point_crit_compute(alg_t **crit, slong *ncrit, region_t *rg, const json_t *pt);

static void alg_copy(alg_t *d, const alg_t *a)
{
    fmpz_poly_set(d->minpoly, a->minpoly);
    fmpq_set(d->q, a->q);
    arb_set(d->x, a->x);
    d->idx = a->idx;
    d->rational = a->rational;
    d->prec = a->prec;
    d->boundary = a->boundary;
}

/* forall_point_crit_compute, once per point (its result depends on the
 * quantified values of pt only) */
static int forall_point_crit(alg_t **crit, slong *ncrit, region_t *rg, const json_t *pt)
{
    point_crit_memo_t *m = NULL;
    char *key = NULL;
    size_t len = 1;
    slong k;
    for (k = 0; k < rg->nq; k++) {
        const char *nm = rg->run->c->params[rg->qv[k]].name;
        const char *w = json_string_value(json_object_get(pt, nm));
        size_t add = strlen(nm) + (w != NULL ? strlen(w) : 1) + 2;
        key = realloc(key, len + add);
        if (k == 0) key[0] = '\0';
        strcat(key, nm); strcat(key, "="); strcat(key, w != NULL ? w : "?"); strcat(key, ";");
        len += add;
    }
    for (k = 0; key != NULL && k < rg->npcm; k++)
        if (strcmp(rg->pcm[k].key, key) == 0) m = rg->pcm + k;
    if (m == NULL) {
        alg_t *c = NULL;
        slong nc = 0;
        int ok = forall_point_crit_compute(&c, &nc, rg, pt);
        if (key == NULL) {           /* nothing quantified: nothing to share */
            *crit = c; *ncrit = nc;
            return ok;
        }
        rg->pcm = flint_realloc(rg->pcm, (size_t) (rg->npcm + 1) * sizeof(point_crit_memo_t));
        m = rg->pcm + rg->npcm++;
        m->key = key; key = NULL;
        m->ok = ok; m->crit = c; m->ncrit = nc;
    }
    free(key);
    *crit = NULL;
    *ncrit = 0;
    if (m->ncrit > 0) *crit = realloc(*crit, (size_t) m->ncrit * sizeof(alg_t));
    for (k = 0; k < m->ncrit; k++) {
        alg_init(*crit + k);
        alg_copy(*crit + k, m->crit + k);
    }
    *ncrit = m->ncrit;
    return m->ok;
}

static int forall_point_crit_compute(alg_t **crit, slong *ncrit, region_t *rg, const json_t *pt)
{
    const rs_scheme_struct *s = rg->s;
    slong lv = s->lambda_var, tv = rg->tv, k, n;
    fmpz_mpoly_t f, sq, t;
    fmpz_mpoly_factor_t fac;
    fmpz_poly_t u;
    fmpz_t pm;
    ulong nn;
    int ok;
    fmpz_mpoly_init(f, s->zctx); fmpz_mpoly_init(sq, s->zctx); fmpz_mpoly_init(t, s->zctx);
    fmpz_mpoly_factor_init(fac, s->zctx);
    fmpz_poly_init(u);
    fmpz_init(pm);
    ok = forall_at_point(f, rg, pt) && rs_factor_memo_factor(fac, f, s->zctx);
    fmpz_mpoly_one(sq, s->zctx);
    for (k = 0; ok && k < fac->num; k++) {
        const fmpz_mpoly_struct *g = fac->poly + k;
        if (fmpz_mpoly_degree_si(g, tv, s->zctx) <= 0) continue;
        if (fmpz_mpoly_degree_si(g, lv, s->zctx) > 0) fmpz_mpoly_mul(sq, sq, g, s->zctx);
        else if (to_upoly(u, g, tv, s)) alg_roots_append(crit, ncrit, u, CRIT_LC);
    }
    n = fmpz_mpoly_degree_si(f, lv, s->zctx);
    nn = (ulong) n;
    if (ok) {
        fmpz_mpoly_get_coeff_vars_ui(t, f, &lv, &nn, 1, s->zctx);
        if (to_upoly(u, t, tv, s)) alg_roots_append(crit, ncrit, u, CRIT_LC);
    }
    for (k = -1; ok && k <= 1 && fmpz_mpoly_degree_si(sq, lv, s->zctx) > 0; k += 2) {
        fmpz_set_si(pm, k);
        fmpz_mpoly_evaluate_one_fmpz(t, sq, lv, pm, s->zctx);
        if (!fmpz_mpoly_is_zero(t, s->zctx) && to_upoly(u, t, tv, s)) alg_roots_append(crit, ncrit, u, CRIT_PM1);
    }
    if (ok && fmpz_mpoly_degree_si(sq, lv, s->zctx) >= 2) {
        rs_hurwitz_t hown;
        const rs_hurwitz_struct *h = hown;
        rs_bilinear_fmpz_mpoly(t, sq, lv, s->zctx);
        rs_hurwitz_init(hown);
        ok = fmpz_mpoly_degree_si(t, lv, s->zctx) >= 2
             && rs_hurwitz_memo_compute(&h, hown, t, lv, s->zctx, rg->run->err) == RS_OK
             && h->n >= 2 && !fmpz_mpoly_is_zero(h->minors + h->n - 2, s->zctx);
        if (ok && to_upoly(u, h->minors + h->n - 2, tv, s)) alg_roots_append(crit, ncrit, u, CRIT_D);
        if (!ok) rs_error_init(rg->run->err);
        rs_hurwitz_clear(hown, s->zctx);
    }
    fmpz_mpoly_clear(f, s->zctx); fmpz_mpoly_clear(sq, s->zctx); fmpz_mpoly_clear(t, s->zctx);
    fmpz_mpoly_factor_clear(fac, s->zctx);
    fmpz_poly_clear(u);
    fmpz_clear(pm);
    return ok;
}

/* 1 when the verdict at the point pt (unstable at t = a) holds on the whole
 * closed range between a and b (b NULL: to infinity in direction dir):
 * no critical value of pt in it.  *stop: the first one met (NULL if none). */
static int forall_persists(region_t *rg, const json_t *pt, alg_t *a, alg_t *b, int dir, alg_t *stop)
{
    alg_t *crit = NULL;
    slong ncrit = 0, k;
    int ok = forall_point_crit(&crit, &ncrit, rg, pt), found = 0;
    for (k = 0; ok && k < ncrit; k++) {
        alg_t *e = crit + k;
        int beyond_a = dir > 0 ? alg_cmp(e, a) >= 0 : alg_cmp(e, a) <= 0;
        int before_b = b == NULL || (dir > 0 ? alg_cmp(e, b) <= 0 : alg_cmp(e, b) >= 0);
        if (!beyond_a || !before_b) continue;
        if (!found || (dir > 0 ? alg_cmp(e, stop) < 0 : alg_cmp(e, stop) > 0)) {
            fmpz_poly_set(stop->minpoly, e->minpoly);
            stop->idx = e->idx;
            stop->rational = e->rational;
            fmpq_set(stop->q, e->q);
            arb_set(stop->x, e->x);
            stop->prec = e->prec;
        }
        found = 1;
    }
    for (k = 0; k < ncrit; k++) alg_clear(crit + k);
    free(crit);
    return ok && !found;
}

/* An irrational critical value c between two decided cells: unstable (or
 * marginal) at the point when the exact verdict at c with the quantified
 * parameters at a neighbour's counterexample says so; stable (bounded) when
 * a certificate covers the closed rational interval between the neighbours'
 * samples, which contains c (algebraic = 0: only the latter). */
static int region_forall_irrational(region_t *rg, slong i, int algebraic)
{
    piece_t *pc = rg->pieces + i, *nb[2];
    rs_status_t st;
    slong k;
    int r = RS_OK;
    nb[0] = pc - 1;
    nb[1] = pc + 1;
    for (k = 0; k < 2 && !pc->decided; k++) {
        const json_t *cx;
        const char *smp;
        if (!nb[k]->decided || nb[k]->ev == NULL) continue;
        cx = json_object_get(nb[k]->ev, nb[k]->status == RS_STATUS_MARGINAL ? "not_stable_at" : "counterexample");
        smp = json_string_value(json_object_get(nb[k]->ev, "sample"));
        if (cx != NULL && smp != NULL && nb[k]->status == RS_STATUS_UNSTABLE) {
            /* the neighbour's counterexample stays unstable up to and past c */
            alg_t a, stop;
            int held;
            alg_init(&a); alg_init(&stop);
            a.rational = 1;
            fmpq_set_str(a.q, smp, 10);
            fmpq_canonicalise(a.q);
            alg_refine(&a, 128);
            held = forall_persists(rg, cx, &a, pc->lo, k == 0 ? 1 : -1, &stop);
            alg_clear(&a); alg_clear(&stop);
            if (held) {
                pc->decided = 1;
                pc->status = RS_STATUS_UNSTABLE;
                pc->ev = json_pack("{s:O,s:s,s:{s:s,s:s}}", "counterexample", cx, "note",
                    "the neighbouring cell's counterexample: with the other parameters there, no value of the "
                    "region parameter between its sample and this algebraic value lets a root cross the circle "
                    "or escape (exact critical values at that point), so it is unstable here too",
                    "at_counterexample", "status", "unstable", "decided_by", "exact");
                json_object_set_new(pc->ev, "sample_of_neighbour", json_string(smp));
                continue;
            }
        }
        if (!algebraic || cx == NULL || !forall_status_at(&st, rg, pc->lo, cx)) continue;
        if (st == RS_STATUS_UNSTABLE || st == RS_STATUS_SINGULAR) {
            pc->decided = 1;
            pc->status = st;
        } else if (st == RS_STATUS_MARGINAL && nb[0]->decided && nb[1]->decided
                   && nb[0]->status == RS_STATUS_MARGINAL && nb[1]->status == RS_STATUS_MARGINAL) {
            pc->status = RS_STATUS_MARGINAL;     /* bounded still to be proved */
        } else {
            continue;
        }
        pc->ev = json_object();
        json_object_set(pc->ev, st == RS_STATUS_MARGINAL ? "not_stable_at" : "counterexample", (json_t *) cx);
        json_object_set_new(pc->ev, "note", json_string(
            "the other parameters as given, the region parameter at this algebraic value: exact verdict in "
            "Q(value)"));
        json_object_set_new(pc->ev, "at_counterexample",
                            json_pack("{s:s,s:s}", "status", rs_status_name(st), "decided_by", "exact"));
    }
    if (!pc->decided && nb[0]->decided && nb[1]->decided && nb[0]->status == nb[1]->status
        && (nb[0]->status == RS_STATUS_STABLE || pc->status == RS_STATUS_MARGINAL)) {
        const char *a = json_string_value(json_object_get(nb[0]->ev, "sample"));
        const char *b = json_string_value(json_object_get(nb[1]->ev, "sample"));
        fmpq_t lo, hi;
        json_t *ev = NULL;
        int proved = 0;
        fmpq_init(lo); fmpq_init(hi);
        if (a != NULL && b != NULL && fmpq_set_str(lo, a, 10) == 0 && fmpq_set_str(hi, b, 10) == 0) {
            fmpq_canonicalise(lo); fmpq_canonicalise(hi);
            int mode = 10 + (nb[0]->status == RS_STATUS_STABLE ? 0 : 1);
            forall_memo_t *m = memo_find(rg, lo, hi, mode);
            if (m != NULL) {
                proved = m->decided;
                ev = m->ev != NULL ? json_deep_copy(m->ev) : NULL;
            } else {
                r = rs_an_forall_prove(&proved, &ev, rg->run, rg->tv, lo, hi, mode - 10);
                if (r == RS_OK) memo_add(rg, lo, hi, mode, RS_STATUS_STABLE, proved, ev);
            }
        }
        if (proved) {
            json_t *keep = pc->ev;
            pc->decided = 1;
            pc->status = nb[0]->status;
            pc->ev = ev;
            ev = NULL;
            json_object_set_new(pc->ev, "proved_on", json_pack("[s,s]", a, b));
            if (keep != NULL) json_object_update(pc->ev, keep);
            json_decref(keep);
        }
        json_decref(ev);
        fmpq_clear(lo); fmpq_clear(hi);
    }
    /* a stable neighbour: marginal at the point by continuity, simple roots
     * and a root +-1 there (an_claim.c, exact over Q(value), issue 13) */
    if (r == RS_OK && !pc->decided && algebraic
        && ((nb[0]->decided && nb[0]->status == RS_STATUS_STABLE)
            || (nb[1]->decided && nb[1]->status == RS_STATUS_STABLE))) {
        int dec = 0;
        json_t *ev = NULL;
        r = rs_an_forall_alg_marginal(&dec, &ev, rg->run, rg->v, rg->tv, pc->lo);
        if (r == RS_OK && dec) {
            json_decref(pc->ev);
            pc->ev = ev;
            ev = NULL;
            pc->decided = 1;
            pc->status = RS_STATUS_MARGINAL;
        } else if (r == RS_OK && ev != NULL) {
            /* undecided, with the disagreement of the two methods on record */
            if (pc->ev == NULL) pc->ev = json_object();
            json_object_update(pc->ev, ev);
        }
        json_decref(ev);
    }
    return r;
}

#define FORALL_MAX_ALG_DEGREE 8

/* The cell at tv = x unstable by the quantified values of the neighbouring
 * cell's counterexample: one exact point verdict instead of a proof attempt
 * and a search (the unstable side of a bound usually has one counterexample
 * that works throughout).  *ev stays NULL unless that point is admissible
 * (the assume lines) and unstable there. */
static int forall_neighbour_counter(json_t **ev, region_t *rg, const json_t *nev, const fmpq_t x)
{
    rs_run_t *run = rg->run;
    const rs_scheme_struct *s = rg->s;
    const json_t *cx = json_object_get(nev, "counterexample"), *val;
    const char *key;
    slong nv = 0, i, ncps = 0;
    slong *vars = flint_malloc((run->c->nparams + 1) * sizeof(slong));
    fmpq *vals = _fmpq_vec_init(run->c->nparams + 1), *pt = _fmpq_vec_init(s->nvars), **pp;
    rs_condpoly_t *cps = calloc((size_t) run->c->nassume + 1, sizeof(rs_condpoly_t));
    int r = RS_OK, ok = json_is_object(cx) && json_object_get(cx, run->c->params[rg->tv].name) != NULL;
    *ev = NULL;
    pp = flint_malloc(s->nvars * sizeof(fmpq *));
    for (i = 0; i < s->nvars; i++) pp[i] = pt + i;
    /* the set values (substituted in s already; the assume lines may name them) */
    json_object_foreach((json_t *) rg->v->assigned, key, val) {
        slong k = rs_case_param_index(run->c, key);
        if (k >= 0 && k < s->nvars && json_is_string(val)) fmpq_set_str(pt + k, json_string_value(val), 10);
    }
    json_object_foreach((json_t *) cx, key, val) {
        slong k = rs_case_param_index(run->c, key);
        if (!ok) break;
        if (k < 0 || k >= s->nvars || !json_is_string(val) || fmpq_set_str(vals + nv, json_string_value(val), 10) != 0) {
            ok = 0;
            break;
        }
        fmpq_canonicalise(vals + nv);
        if (k == rg->tv) fmpq_set(vals + nv, x);
        vars[nv] = k;
        fmpq_set(pt + k, vals + nv);
        nv++;
    }
    for (i = 0; ok && i < run->c->nassume && r == RS_OK; i++)
        r = rs_condpoly_compile(cps + ncps++, &run->c->assume[i], s, run->c, run->err);
    if (r != RS_OK) { rs_error_init(run->err); r = RS_OK; ok = 0; }
    if (ok && rs_run_point_admissible(cps, ncps, pp, s)) {
        rs_rootcount_t rc;
        rs_status_t st;
        r = rs_run_point_status(&st, rc, run, rg->v, vars, vals, nv);
        if (r == RS_OK && st == RS_STATUS_UNSTABLE) {
            json_t *at = json_object(), *c2 = json_object();
            rs_json_add_count(at, rc);
            json_object_set_new(at, "status", json_string(rs_status_name(st)));
            json_object_set_new(at, "decided_by", json_string("exact"));
            for (i = 0; i < nv; i++) json_object_set_new(c2, run->c->params[vars[i]].name, rs_json_fmpq(vals + i));
            *ev = json_pack("{s:o,s:o,s:I,s:s}", "counterexample", c2, "at_counterexample", at,
                            "points_checked", (json_int_t) 1, "found_by", "the neighbouring cell's counterexample");
        }
        rs_rootcount_clear(rc);
    }
    for (i = 0; i < ncps; i++) rs_condpoly_clear(cps + i, s);
    free(cps);
    flint_free(vars);
    _fmpq_vec_clear(vals, run->c->nparams + 1);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    return r;
}

/* rs_an_forall_cell at x, or its verdict of the first projection */
static int forall_cell_memo(rs_status_t *st, int *decided, json_t **ev, region_t *rg, const fmpq_t x, int mode)
{
    forall_memo_t *m = memo_find(rg, x, NULL, mode);
    int r = RS_OK;
    if (m != NULL) {
        *st = m->st;
        *decided = m->decided;
        *ev = m->ev != NULL ? json_deep_copy(m->ev) : NULL;
    } else {
        r = rs_an_forall_cell(st, decided, ev, rg->run, rg->tv, x, mode);
        if (r == RS_OK) memo_add(rg, x, NULL, mode, *st, *decided, *ev);
    }
    return r;
}

/* 1 when the per-condition projection cannot settle the cells, known before
 * they are decided: an interval whose sample has q's leading coefficient
 * vanishing somewhere on the quantified domain and that is decided neither
 * stable nor singular (region_forall_run's test after the decisions; the
 * status of a cell does not depend on the order of the work).  Only those
 * intervals are decided here; 0 (the cells decided in order, as before)
 * when none is known to fail. */
static int forall_unsettled_early(int *unsettled, region_t *rg)
{
    slong i;
    int r = RS_OK;
    *unsettled = 0;
    for (i = 0; i < rg->npieces && r == RS_OK && !*unsettled; i++) {
        piece_t *pc = rg->pieces + i;
        fmpq_t x;
        if (pc->is_point) continue;
        fmpq_init(x);
        rational_between(x, pc->lo, pc->hi);
        if (!rs_an_forall_lead_nonzero(rg->run, rg->v, rg->tv, x, rg->bounds)) {
            rs_status_t st = RS_STATUS_UNSTABLE;
            int decided = 0;
            json_t *ev = NULL;
            r = rs_budget_check(rg->run->err, "region ... for all (deciding its cells)");
            if (r == RS_OK) r = forall_cell_memo(&st, &decided, &ev, rg, x, -1);
            *unsettled = r == RS_OK && decided && st != RS_STATUS_STABLE && st != RS_STATUS_SINGULAR;
            json_decref(ev);
        }
        fmpq_clear(x);
    }
    return r;
}

/* 1 when the critical value a is one of the per-condition projection's */
static int forall_is_pcrit(region_t *rg, alg_t *a)
{
    slong k;
    for (k = 0; k < rg->npcrit; k++)
        if (alg_cmp(rg->pcrit + k, a) == 0) return 1;
    return 0;
}

/* Full projection, piece i (open) decided stable at its sample s1: the
 * pieces after it up to the last open piece j before the next critical
 * value of the per-condition projection (the discriminant and resultants
 * of the full projection put critical values inside stable intervals, where
 * nothing changes for stability) are stable when one certificate proves
 * stable for every t in [s1, sj] (sj: piece j's sample) and every admissible
 * value of the others; piece j is then stable at sj, hence on all of it (a
 * cell of the full projection).  One proof instead of one per piece; no
 * proof, nothing decided here. */
static int forall_merge_stable(region_t *rg, slong i)
{
    piece_t *pc = rg->pieces + i;
    slong j = i, k;
    fmpq_t lo, hi, x;
    json_t *ev = NULL;
    int proved = 0, r = RS_OK;
    const char *a;
    while (j + 2 < rg->npieces && rg->pieces[j + 1].is_point && !rg->pieces[j + 1].decided
           && !rg->pieces[j + 2].decided && !forall_is_pcrit(rg, rg->pieces[j + 1].lo))
        j += 2;
    if (j == i || rg->pieces[j].lo == NULL || rg->pieces[j].hi == NULL) return RS_OK;
    a = json_string_value(json_object_get(pc->ev, "sample"));
    fmpq_init(lo); fmpq_init(hi); fmpq_init(x);
    if (a != NULL && fmpq_set_str(lo, a, 10) == 0) {
        fmpq_canonicalise(lo);
        rational_between(hi, rg->pieces[j].lo, rg->pieces[j].hi);
        r = rs_budget_check(rg->run->err, "region ... for all (deciding its cells)");
        if (r == RS_OK) r = rs_an_forall_prove(&proved, &ev, rg->run, rg->tv, lo, hi, 0);
    }
    for (k = i + 1; proved && r == RS_OK && k <= j; k++) {
        piece_t *q = rg->pieces + k;
        q->decided = 1;
        q->status = RS_STATUS_STABLE;
        q->ev = json_deep_copy(ev);
        json_object_set_new(q->ev, "proved_on", json_pack("[s,o]", a, rs_json_fmpq(hi)));
        if (q->is_point && q->lo->rational) fmpq_set(x, q->lo->q);
        else if (!q->is_point) rational_between(x, q->lo, q->hi);
        if (!q->is_point || q->lo->rational) json_object_set_new(q->ev, "sample", rs_json_fmpq(x));
    }
    json_decref(ev);
    fmpq_clear(lo); fmpq_clear(hi); fmpq_clear(x);
    return r;
}

static int region_forall_decide(region_t *rg)
{
    slong i;
    int r = RS_OK;
    for (i = 0; i < rg->npieces && r == RS_OK; i++) {
        piece_t *pc = rg->pieces + i;
        fmpq_t x;
        if (pc->decided) continue;     /* forall_merge_stable */
        if (pc->is_point && !pc->lo->rational) { pc->decided = 0; continue; }
        fmpq_init(x);
        if (pc->is_point) fmpq_set(x, pc->lo->q);
        else rational_between(x, pc->lo, pc->hi);
        r = rs_budget_check(rg->run->err, "region ... for all (deciding its cells)");
        if (r == RS_OK && i > 0 && pc[-1].decided && pc[-1].status == RS_STATUS_UNSTABLE && pc[-1].ev != NULL) {
            r = forall_neighbour_counter(&pc->ev, rg, pc[-1].ev, x);
            if (r == RS_OK && pc->ev != NULL) {
                pc->decided = 1;
                pc->status = RS_STATUS_UNSTABLE;
                json_object_set_new(pc->ev, "sample", rs_json_fmpq(x));
                fmpq_clear(x);
                continue;
            }
        }
        if (r == RS_OK) {
            /* after an unstable cell the next one usually is unstable too:
             * look for its bad point before attempting a proof (else a
             * one-point probe guesses) */
            slong j = i - 1;
            int mode;
            while (j >= 0 && !rg->pieces[j].decided) j--;
            mode = j >= 0 && rg->pieces[j].status == RS_STATUS_UNSTABLE ? 1 : -1;
            r = forall_cell_memo(&pc->status, &pc->decided, &pc->ev, rg, x, mode);
        }
        if (pc->ev != NULL) json_object_set_new(pc->ev, "sample", rs_json_fmpq(x));
        fmpq_clear(x);
        if (r == RS_OK && rg->pcrit != NULL && !pc->is_point && pc->decided && pc->status == RS_STATUS_STABLE)
            r = forall_merge_stable(rg, i);
    }
    /* no verdict in Q[t]/(minpoly) at irrational values of high degree
     * (spurious ones of the projection mostly): its arithmetic grows fast;
     * the certificate over the rational interval around them still applies */
    for (i = 1; i + 1 < rg->npieces && r == RS_OK; i++)
        if (rg->pieces[i].is_point && !rg->pieces[i].lo->rational
            && (r = rs_budget_check(rg->run->err, "region ... for all (irrational critical values)")) == RS_OK)
            r = region_forall_irrational(rg, i, fmpz_poly_degree(rg->pieces[i].lo->minpoly) <= FORALL_MAX_ALG_DEGREE);
    return r;
}

/* The cells of the cheap projection (each condition on its own) decided;
 * where that projection does not settle a cell (an interval marginal for
 * all values, or unstable somewhere but not covered by exact
 * counterexamples) the full projection (every condition together, the
 * discriminant included) is made and the cells decided again. */
static int region_forall_run(region_t *rg)
{
    int full, r = RS_OK;
    slong k;
    for (full = 0; full < 2 && r == RS_OK; full++) {
        slong i;
        int settled = 1;
        int early = 0;
        r = region_forall_critical(rg, &full);
        if (r == RS_OK) {
            region_crit_prune(rg);
            region_pieces(rg);
            if (!full) r = forall_unsettled_early(&early, rg);
            if (r == RS_OK && !early) r = region_forall_decide(rg);
        }
        settled = !early;
        for (i = 0; i < rg->npieces && r == RS_OK && settled && !full; i++) {
            piece_t *pc = rg->pieces + i;
            fmpq_t x;
            if (pc->is_point || !pc->decided || pc->status == RS_STATUS_STABLE || pc->status == RS_STATUS_SINGULAR)
                continue;
            fmpq_init(x);
            rational_between(x, pc->lo, pc->hi);
            settled = rs_an_forall_lead_nonzero(rg->run, rg->v, rg->tv, x, rg->bounds);
            fmpq_clear(x);
        }
        if (r != RS_OK || settled || full) {
            rg->projection = full ? "full" : "per-condition";
            break;
        }
        rg->pcrit = rg->crit;          /* kept for forall_merge_stable */
        rg->npcrit = rg->ncrit;
        for (i = 0; i < rg->npieces; i++) json_decref(rg->pieces[i].ev);
        free(rg->pieces);
        rg->crit = NULL; rg->ncrit = 0; rg->pieces = NULL; rg->npieces = 0;
    }
    for (k = 0; k < rg->npcrit; k++) alg_clear(rg->pcrit + k);
    free(rg->pcrit);
    rg->pcrit = NULL; rg->npcrit = 0;
    return r;
}

/* Irrational critical values, decided exactly from what vanishes there:
 * - none of lc, p(+-1), D_{n-1}: no root on the circle (Orlando: a circle
 *   root other than +-1 makes D_{n-1} vanish) and no degree drop, so the
 *   status is that of both neighbours, which must agree;
 * - a stable neighbour, lc != 0, and p(+-1) = 0 or D_{n-1} = 0 but no
 *   repeated root (discriminant != 0): the limit of roots inside the disc
 *   leaves none outside, a pair z, -z of q cannot be real (one would be
 *   outside), so a root is on the circle and all are simple: marginal.
 * (The exact status above is checked against this continuity argument
 * wherever it applies: a disagreement is an inconsistency, exit 3.) */
static void region_check(region_t *rg)
{
    const rs_scheme_struct *s = rg->s;
    const piece_t *pieces = rg->pieces;
    slong i;
    for (i = 1; i + 1 < rg->npieces; i++) {
        const piece_t *pc = pieces + i;
        int fl;
        if (!pc->is_point || pc->lo->rational || !pc->decided) continue;
        fl = pc->lo->boundary;
        if (!(fl & CRIT_TOUCH)) {
            if (!pieces[i - 1].decided || !pieces[i + 1].decided
                || pieces[i - 1].status != pieces[i + 1].status
                || pc->status != pieces[i - 1].status)
                rg->run->outcome |= RS_OUTCOME_INCONSISTENT;
        } else if (!(fl & (CRIT_LC | CRIT_DISC)) && !rg->repeated_always
                   /* a repeated factor (a system's identical modes) may be a Jordan block */
                   && fmpz_mpoly_degree_si(rg->sqf, s->lambda_var, s->zctx)
                      == fmpz_mpoly_degree_si(rg->pj, s->lambda_var, s->zctx)
                   && ((pieces[i - 1].decided && pieces[i - 1].status == RS_STATUS_STABLE)
                       || (pieces[i + 1].decided && pieces[i + 1].status == RS_STATUS_STABLE))) {
            if (pc->status != RS_STATUS_MARGINAL)
                rg->run->outcome |= RS_OUTCOME_INCONSISTENT;
        }
    }
}

/* merge runs of decided pieces with equal status into intervals */
static void region_json(region_t *rg, json_t *o)
{
    const piece_t *pieces = rg->pieces;
    const char *name = rg->name;
    json_t *ivs = json_array(), *pts = json_array();
    slong i = 0, npieces = rg->npieces;
    while (i < npieces) {
        slong j = i;
        json_t *iv;
        alg_t *lo, *hi;
        if (!pieces[i].decided && rg->forall) {
            iv = json_object();
            json_object_set_new(iv, "lo", pieces[i].lo ? alg_json(pieces[i].lo, name) : json_null());
            json_object_set_new(iv, "hi", pieces[i].hi ? alg_json(pieces[i].hi, name) : json_null());
            json_object_set_new(iv, "lo_closed", json_boolean(pieces[i].is_point));
            json_object_set_new(iv, "hi_closed", json_boolean(pieces[i].is_point));
            json_object_set_new(iv, "status", json_string("undecided"));
            json_object_set_new(iv, "lo_approx", pieces[i].lo ? json_real(alg_double(pieces[i].lo)) : json_null());
            json_object_set_new(iv, "hi_approx", pieces[i].hi ? json_real(alg_double(pieces[i].hi)) : json_null());
            /* "o" steals the reference: the piece's own evidence is increfed, a new one is not leaked */
            json_object_set_new(iv, "evidence", json_pack("[o]", pieces[i].ev ? json_incref(pieces[i].ev)
                : json_pack("{s:s}", "failed_at", "an irrational critical value: the claim machinery needs a "
                            "rational value")));
            json_array_append_new(ivs, iv);
            if (pieces[i].is_point && pieces[i].lo != NULL) {
                /* the one-point interval is also an undecided point (issue 13) */
                json_t *pj = json_object();
                json_object_set_new(pj, "value", alg_json(pieces[i].lo, name));
                json_object_set_new(pj, "approx", json_real(alg_double(pieces[i].lo)));
                json_object_set_new(pj, "status", json_string("undecided"));
                json_object_set(pj, "evidence", json_object_get(iv, "evidence"));
                json_array_append_new(pts, pj);
            }
            i++;
            continue;
        }
        if (!pieces[i].decided) {
            json_t *pj = json_object();
            json_object_set_new(pj, "value", alg_json(pieces[i].lo, name));
            json_object_set_new(pj, "approx", json_real(alg_double(pieces[i].lo)));
            json_object_set_new(pj, "status", json_string("undecided"));
            json_object_set_new(pj, "note", json_string(
                "irrational algebraic point where a system has a repeated circle root: its semisimplicity "
                "(the rank of A there) is not decided; not stable, the intervals beside it are exact"));
            json_array_append_new(pts, pj);
            i++;
            continue;
        }
        while (j + 1 < npieces && pieces[j + 1].decided && pieces[j + 1].status == pieces[i].status) j++;
        iv = json_object();
        lo = pieces[i].lo;
        hi = pieces[j].hi;
        json_object_set_new(iv, "lo", lo ? alg_json(lo, name) : json_null());
        json_object_set_new(iv, "hi", hi ? alg_json(hi, name) : json_null());
        json_object_set_new(iv, "lo_closed", json_boolean(pieces[i].is_point));
        json_object_set_new(iv, "hi_closed", json_boolean(pieces[j].is_point));
        json_object_set_new(iv, "status", json_string(rs_status_name(pieces[i].status)));
        json_object_set_new(iv, "lo_approx", lo ? json_real(alg_double(lo)) : json_null());
        json_object_set_new(iv, "hi_approx", hi ? json_real(alg_double(hi)) : json_null());
        if (i == j && pieces[i].is_point && pieces[i].status == RS_STATUS_SINGULAR) {
            /* why singular: a degree drop, or no polynomial at all */
            json_object_set_new(iv, "vanishes", json_boolean(pieces[i].vanishes));
            json_object_set_new(iv, "note", json_string(pieces[i].vanishes
                ? "the characteristic polynomial vanishes identically here (a zero of its content in lambda): "
                  "every lambda is a root, no recurrence is defined; not stable"
                : "degree drop: the leading coefficient of det A(lambda) vanishes here, the implicit step "
                  "cannot be solved; not stable"));
        }
        if (rg->forall) {
            /* one certificate or counterexample per cell (open interval or point) */
            json_t *evs = json_array();
            slong k;
            for (k = i; k <= j; k++) {
                json_t *e = json_object();
                json_object_set_new(e, "cell", json_string(pieces[k].is_point ? "point" : "interval"));
                if (pieces[k].ev != NULL) json_object_update(e, pieces[k].ev);
                json_array_append_new(evs, e);
            }
            json_object_set_new(iv, "evidence", evs);
        }
        json_array_append_new(ivs, iv);
        i = j + 1;
    }
    json_object_set_new(o, "symbolic", json_false());
    json_object_set_new(o, "intervals", ivs);
    json_object_set_new(o, "undecided_points", pts);
    json_object_set_new(o, "critical_values", json_integer(rg->ncrit));
    json_object_set_new(o, "decided_by", json_string("exact"));
    if (rg->forall) {
        json_t *fa = json_array();
        slong k;
        for (k = 0; k < rg->nq; k++) json_array_append_new(fa, json_string(rg->run->c->params[rg->qv[k]].name));
        json_object_set_new(o, "for_all", fa);
        if (rg->projection != NULL) json_object_set_new(o, "projection", json_string(rg->projection));
    }
}

/* The domain of t from the assume lines (an error when it is empty). */
static int region_domain(region_t *rg)
{
    rs_run_t *run = rg->run;
    rs_bound_t *bt;
    slong i;
    rg->bounds = flint_malloc((run->c->nparams + 1) * sizeof(rs_bound_t));
    rs_bounds_init(rg->bounds, run->c->nparams);
    for (i = 0; i < run->c->nassume; i++) rs_bounds_add(rg->bounds, &run->c->assume[i], run->c, run->err);
    bt = rg->bounds + rg->tv;
    if (rg->dom_tv != NULL) {   /* a claim's set: the assumptions already in it */
        bt->has_lo = rg->dom_tv->has_lo; bt->has_hi = rg->dom_tv->has_hi;
        bt->lo_closed = rg->dom_tv->lo_closed; bt->hi_closed = rg->dom_tv->hi_closed;
        bt->fixed = rg->dom_tv->fixed;
        fmpq_set(bt->lo, rg->dom_tv->lo); fmpq_set(bt->hi, rg->dom_tv->hi);
    }
    if (rs_bound_empty(bt))
        return rs_req_error(run, rg->q, rg->rest, RS_ERR_INPUT,
                            "the assumptions are contradictory: no value of '%s' satisfies them", rg->name);
    /* assume NAME = c: the region is that one point, no interval */
    rg->single = bt->has_lo && bt->has_hi && fmpq_equal(bt->lo, bt->hi);
    rg->have_lo = bt->has_lo;
    rg->have_hi = bt->has_hi;
    if (rg->have_lo) { rg->lo_end.rational = 1; fmpq_set(rg->lo_end.q, bt->lo); alg_refine(&rg->lo_end, 128); }
    if (rg->have_hi) { rg->hi_end.rational = 1; fmpq_set(rg->hi_end.q, bt->hi); alg_refine(&rg->hi_end, 128); }
    return RS_OK;
}

/* a region over Q(i) from its domain to its checked pieces (the one-parameter
 * region at complex set values and the claim's region on a set) */
static int region_cx_run(region_t *rg)
{
    int r = region_domain(rg);
    if (r == RS_OK) r = region_cx_prepare(rg);
    if (r == RS_OK) {
        region_critical(rg);
        rs_error_init(rg->run->err);
        region_crit_prune(rg);
        region_pieces(rg);
        r = region_decide(rg);
    }
    if (r == RS_OK) region_check(rg);
    return r;
}

static void region_init(region_t *rg, rs_run_t *run, const rs_an_req_t *req, const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t g;
    memset(rg, 0, sizeof *rg);
    rg->run = run;
    rg->q = req->q;
    rg->rest = req->rest;
    rg->tv = req->u.region.param;
    rg->name = run->c->params[rg->tv].name;
    rg->v = v;
    rg->s = s;
    rg->forall = req->u.region.forall;
    rg->qv = req->u.region.qv;
    rg->nq = req->u.region.nq;
    alg_init(&rg->lo_end);
    alg_init(&rg->hi_end);
    fmpz_mpoly_init(rg->pt, s->zctx);
    fmpz_mpoly_init(rg->sqf, s->zctx);
    fmpz_mpoly_init(rg->sqf_t, s->zctx);
    fmpz_mpoly_init(rg->cre, s->zctx);
    fmpz_mpoly_init(rg->cim, s->zctx);
    fmpz_mpoly_init(rg->pabs, s->zctx);
    rg->pj = v->cp->p;
    /* the part of p that depends on t */
    fmpz_mpoly_init(g, s->zctx);
    if (!fmpz_mpoly_content_vars(g, v->cp->p, &rg->tv, 1, s->zctx) || fmpz_mpoly_is_zero(g, s->zctx))
        fmpz_mpoly_one(g, s->zctx);
    fmpz_mpoly_divexact(rg->pt, v->cp->p, g, s->zctx);
    fmpz_mpoly_clear(g, s->zctx);
}

static void region_clear(region_t *rg)
{
    const rs_scheme_struct *s = rg->s;
    slong i;
    for (i = 0; i < rg->ncrit; i++) alg_clear(rg->crit + i);
    free(rg->crit);
    for (i = 0; i < rg->npieces; i++) json_decref(rg->pieces[i].ev);
    free(rg->pieces);
    alg_clear(&rg->lo_end);
    alg_clear(&rg->hi_end);
    if (rg->bounds != NULL) {
        rs_bounds_clear(rg->bounds, rg->run->c->nparams);
        flint_free(rg->bounds);
    }
    fmpz_mpoly_clear(rg->pt, s->zctx);
    fmpz_mpoly_clear(rg->sqf, s->zctx);
    fmpz_mpoly_clear(rg->sqf_t, s->zctx);
    fmpz_mpoly_clear(rg->cre, s->zctx);
    fmpz_mpoly_clear(rg->cim, s->zctx);
    fmpz_mpoly_clear(rg->pabs, s->zctx);
    memo_clear(rg);
    for (i = 0; i < rg->npcm; i++) {
        slong k;
        for (k = 0; k < rg->pcm[i].ncrit; k++) alg_clear(rg->pcm[i].crit + k);
        free(rg->pcm[i].crit);
        free(rg->pcm[i].key);
    }
    flint_free(rg->pcm);
}

void rs_an_region_req_clear(rs_an_req_t *req)
{
    rs_assign_free(req->u.region.at, req->u.region.nat);
    flint_free(req->u.region.qv);
    req->u.region.qv = NULL;
}

/* region NAME for all: the intervals into o; dom_tv (or NULL) replaces
 * NAME's assumed interval */
static int region_forall_object(json_t *o, rs_run_t *run, const rs_an_req_t *req, const rs_variant_t *v,
                                const rs_bound_t *dom_tv)
{
    region_t rg;
    roots_memo_t memo, *outer = roots_memo;
    int r;
    /* a complex char line: the projection uses p's own conditions over Q(i)
     * (an_region_forall.c), the cells are decided by the claim machinery */
    void *outer_fac = rs_factor_memo_begin(v->s->zctx);
    memset(&memo, 0, sizeof memo);
    roots_memo = &memo;
    region_init(&rg, run, req, v);
    rg.dom_tv = dom_tv;
    json_object_set_new(o, "symbolic", json_false());
    r = region_domain(&rg);
    if (r == RS_OK) r = region_forall_run(&rg);
    if (r == RS_OK) region_json(&rg, o);
    region_clear(&rg);
    roots_memo = outer;
    roots_memo_clear(&memo);
    rs_factor_memo_end(outer_fac);
    return r;
}

int rs_an_region_forall_on(json_t **out, rs_run_t *run, const rs_request_t *q, slong tv, const rs_bound_t *dom_tv)
{
    slong np = run->c->nparams, k;
    rs_an_req_t req;
    rs_assign_t *a = NULL;
    slong na = 0;
    const char *keep[1];
    rs_variant_t *v;
    int r;
    memset(&req, 0, sizeof req);
    req.q = q;
    req.rest = q->text;
    req.u.region.param = tv;
    req.u.region.forall = 1;
    req.u.region.qv = flint_malloc((np + 1) * sizeof(slong));
    for (k = 0; k < np; k++)    /* as `for all` without a list */
        if (k != tv && !param_is_set(run, k)) req.u.region.qv[req.u.region.nq++] = k;
    keep[0] = run->c->params[tv].name;
    rs_run_assignments(run, &a, &na, keep, 1, NULL, 0);
    r = rs_run_variant(&v, run, a, na);
    rs_assign_free(a, na);
    *out = NULL;
    if (r == RS_OK) {
        *out = json_object();
        r = region_forall_object(*out, run, &req, v, dom_tv);
        if (r != RS_OK) { json_decref(*out); *out = NULL; }
    }
    flint_free(req.u.region.qv);
    return r;
}

int rs_an_region(rs_run_t *run, const rs_an_req_t *req)
{
    const char *name = run->c->params[req->u.region.param].name;
    rs_assign_t *a = NULL;
    slong na = 0;
    const char *keep[1];
    rs_variant_t *v;
    region_t rg;
    json_t *o;
    int r;

    if (run->m->qd != NULL && req->u.region.twod) return rs_an_qd_region2(run, req);   /* an_qd_region2.c */
    if (run->m->qd != NULL) return rs_an_qd_region(run, req);   /* over Q(sqrt d) (an_qd_conds.c) */
    if (req->u.region.twod) return rs_an_region_cad(run, req);
    keep[0] = name;
    rs_run_assignments(run, &a, &na, keep, 1, req->u.region.at, req->u.region.nat);
    r = rs_run_variant(&v, run, a, na);
    rs_assign_free(a, na);
    if (r != RS_OK) return r;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("region"));
    json_object_set_new(o, "param", json_string(name));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    if (req->u.region.forall) {
        r = region_forall_object(o, run, req, v, NULL);
        if (r == RS_OK) json_array_append_new(run->results, o);
        else json_decref(o);
        return r;
    }
    if (run->c->ncsets > 0) {
        /* complex set values: over Q(i), |p|^2 cut into cells */
        slong k;
        for (k = 0; k < run->c->ncsets; k++)
            if (strcmp(run->c->csets[k].name, name) == 0) {
                char msg[RS_ERROR_MSG_LEN];
                json_decref(o);
                snprintf(msg, sizeof msg, "region %s: '%s' has a complex set value; its plane is region re(%s), "
                         "im(%s) (without the set value)", name, name, name, name);
                return rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "%s", msg);
            }
        region_init(&rg, run, req, v);
        r = region_cx_run(&rg);
        if (r == RS_OK) {
            json_t *sub = json_object_get(o, "substituted");
            region_json(&rg, o);
            if (json_is_object(sub)) json_object_update_new(sub, rs_run_cx_at(run));
            json_object_set_new(o, "over", json_string("Q(i)"));
            json_object_set_new(o, "method", json_string(
                "cells cut at the real roots of the critical polynomials of |p|^2 = Re(p)^2 + Im(p)^2 (p's roots "
                "and their conjugates: leading coefficient, lambda = +-1, D_{n-1} of its bilinear image, "
                "discriminant); each rational sample decided by complex Schur-Cohn and Bilharz over Q(i) and "
                "by the real route gcd(Re p, Im p) |p/gcd|^2 (all must agree, else exit 3); irrational "
                "critical values by the real route over Q(t0)"));
            json_object_set_new(o, "cross_checked_samples", json_integer(rg.ncx_checked));
            json_array_append_new(run->results, o);
        } else {
            json_decref(o);
        }
        region_clear(&rg);
        return r;
    }
    if (rs_run_count_free(v->cp->p, v->s, req->u.region.param) > 0) {
        r = region_symbolic(run, v, o);
        if (r != RS_OK) { json_decref(o); return r; }
        json_object_set_new(o, "decided_by", json_string("exact"));
        json_array_append_new(run->results, o);
        return RS_OK;
    }
    region_init(&rg, run, req, v);
    r = region_domain(&rg);
    if (r == RS_OK) {
        region_squarefree(&rg);
        region_critical(&rg);
        rs_error_init(run->err);
        region_crit_prune(&rg);
        region_pieces(&rg);
        r = region_decide(&rg);
    }
    if (r == RS_OK) {
        region_check(&rg);
        region_json(&rg, o);
        json_array_append_new(run->results, o);
    } else {
        json_decref(o);
    }
    region_clear(&rg);
    return r;
}

int rs_an_region_cx_on(json_t **out, rs_run_t *run, const rs_variant_t *v, slong tv, const rs_bound_t *dom_tv)
{
    char text[] = "region";
    rs_request_t dq;
    rs_an_req_t req;
    region_t rg;
    int r;
    memset(&dq, 0, sizeof dq);
    memset(&req, 0, sizeof req);
    dq.text = text;
    dq.loc.file = run->c->path;
    dq.loc.line = 1;
    dq.loc.col = 1;
    req.q = &dq;
    req.rest = dq.text;
    req.u.region.param = tv;
    *out = NULL;
    region_init(&rg, run, &req, v);
    rg.dom_tv = dom_tv;
    r = region_cx_run(&rg);
    if (r == RS_OK) {
        *out = json_object();
        region_json(&rg, *out);
        json_object_set_new(*out, "cross_checked_samples", json_integer(rg.ncx_checked));
    }
    region_clear(&rg);
    return r;
}

/* ---- shared with an_region_cad.c (an_region.h) ---------------------------- */

void rs_alg_init(rs_alg_t *a) { alg_init(a); }
void rs_alg_clear(rs_alg_t *a) { alg_clear(a); }
void rs_alg_set(rs_alg_t *d, const rs_alg_t *a) { alg_copy(d, a); }
void rs_alg_refine(rs_alg_t *a, slong prec) { alg_refine(a, prec); }
int rs_alg_cmp(rs_alg_t *a, rs_alg_t *b) { return alg_cmp(a, b); }
void rs_alg_roots_append(rs_alg_t **list, slong *n, const fmpz_poly_t f, int boundary)
{
    alg_roots_append(list, n, f, boundary);
}
void rs_alg_sort(rs_alg_t *a, slong n) { sort_algs(a, n); }
json_t *rs_alg_json(rs_alg_t *a, const char *var) { return alg_json(a, var); }
double rs_alg_double(rs_alg_t *a) { return alg_double(a); }
void rs_alg_between(fmpq_t out, rs_alg_t *a, rs_alg_t *b) { rational_between(out, a, b); }
int rs_alg_status(rs_status_t *out, const fmpz_mpoly_t p, slong tv, rs_alg_t *t0, const rs_scheme_t s)
{
    return status_at_algebraic(out, p, tv, t0, s);
}

int rs_alg_sign(const fmpq_poly_t x, rs_alg_t *t0) { return k_sign(x, t0); }

int rs_alg_status_coeffs(rs_status_t *out, const fmpq_poly_struct *c, slong n, rs_alg_t *t0, const rs_scheme_t s)
{
    fmpq_poly_t m;
    kpoly_t P;
    slong j;
    int decided;
    fmpq_poly_init(m);
    fmpq_poly_set_fmpz_poly(m, t0->minpoly);
    kp_init(&P, n + 1);
    for (j = 0; j <= n; j++) fmpq_poly_rem(P.c + j, c + j, m);
    decided = status_kp(out, &P, n, NULL, -1, t0, m, s);
    kp_clear(&P);
    fmpq_poly_clear(m);
    return decided;
}

/* m_b(w - k x) in Z[x, w] (ctx: x = var 0, w = var 1) */
static void prim_shift(fmpz_mpoly_t out, const fmpz_poly_t mb, slong k, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_t lin, t;
    slong i;
    fmpz_mpoly_init(lin, ctx);
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_gen(lin, 0, ctx);
    fmpz_mpoly_scalar_mul_si(lin, lin, -k, ctx);
    fmpz_mpoly_gen(t, 1, ctx);
    fmpz_mpoly_add(lin, lin, t, ctx);
    fmpz_mpoly_zero(out, ctx);
    for (i = fmpz_poly_degree(mb); i >= 0; i--) {
        fmpz_mpoly_mul(out, out, lin, ctx);
        fmpz_mpoly_add_fmpz(out, out, mb->coeffs + i, ctx);
    }
    fmpz_mpoly_clear(lin, ctx);
    fmpz_mpoly_clear(t, ctx);
}

/* gamma = beta + k alpha for the first k in 1, -1, 2, -2, ... with
 * Q(gamma) = Q(alpha, beta): gamma's minimal polynomial is a factor of
 * Res_x(m_a(x), m_b(w - k x)) (the root whose enclosure meets beta + k
 * alpha's), and k separates iff gcd(m_a(x), m_b(gamma - k x)) over
 * Q(gamma) is linear (only x = alpha is common): then alpha = A(gamma) from
 * that gcd and beta = gamma - k alpha. */
int rs_alg_primitive(rs_alg_t *gamma, fmpq_poly_t A, fmpq_poly_t B, rs_alg_t *alpha, rs_alg_t *beta)
{
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t ma, mb, res;
    fmpz_poly_t u;
    slong t, k, i;
    int ok = 0;
    if (alpha->rational || beta->rational) {
        /* the field is the other one's */
        alg_t *g = alpha->rational ? beta : alpha;
        fmpz_poly_set(gamma->minpoly, g->minpoly);
        gamma->idx = g->idx;
        gamma->rational = g->rational;
        fmpq_set(gamma->q, g->q);
        gamma->prec = 0;
        alg_refine(gamma, 128);
        if (g->rational) { fmpq_poly_set_fmpq(A, alpha->q); fmpq_poly_set_fmpq(B, beta->q); return 1; }
        fmpq_poly_zero(A); fmpq_poly_zero(B);
        if (alpha->rational) { fmpq_poly_set_fmpq(A, alpha->q); fmpq_poly_set_coeff_si(B, 1, 1); }
        else { fmpq_poly_set_fmpq(B, beta->q); fmpq_poly_set_coeff_si(A, 1, 1); }
        return 1;
    }
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(ma, ctx); fmpz_mpoly_init(mb, ctx); fmpz_mpoly_init(res, ctx);
    fmpz_poly_init(u);
    fmpz_mpoly_set_fmpz_poly(ma, alpha->minpoly, 0, ctx);
    for (t = 0; t < 12 && !ok; t++) {
        alg_t *roots = NULL;
        slong nroots = 0, hit = -1, prec;
        k = t % 2 == 0 ? t / 2 + 1 : -(t / 2 + 1);
        if (rs_budget_check(NULL, "a primitive element") != RS_OK) break;
        prim_shift(mb, beta->minpoly, k, ctx);
        if (!fmpz_mpoly_resultant(res, ma, mb, 0, ctx) || !fmpz_mpoly_get_fmpz_poly(u, res, 1, ctx)
            || fmpz_poly_degree(u) < 1)
            continue;
        alg_roots_append(&roots, &nroots, u, 0);
        /* the root of the resultant that is beta + k alpha (distinct roots:
         * refining separates them, exactly one is gamma) */
        for (prec = 64; prec < (1L << 16) && hit < 0; prec *= 2) {
            arb_t g;
            slong nhit = 0;
            arb_init(g);
            alg_refine(alpha, prec);
            alg_refine(beta, prec);
            arb_mul_si(g, alpha->x, k, prec);
            arb_add(g, g, beta->x, prec);
            for (i = 0; i < nroots; i++) {
                alg_refine(roots + i, prec);
                if (arb_overlaps(g, roots[i].x)) { nhit++; hit = i; }
            }
            if (nhit != 1) hit = -1;
            arb_clear(g);
        }
        if (hit >= 0) {
            /* gcd(m_a(x), m_b(gamma - k x)) in Q(gamma)[x] */
            kpoly_t P, Q, G;
            fmpq_poly_t m, z, lin;
            slong da = fmpz_poly_degree(alpha->minpoly), db = fmpz_poly_degree(beta->minpoly);
            fmpq_poly_init(m); fmpq_poly_init(z); fmpq_poly_init(lin);
            fmpq_poly_set_fmpz_poly(m, roots[hit].minpoly);
            kp_init(&P, da + 1); kp_init(&Q, db + 1); kp_init(&G, FLINT_MAX(da, db) + 1);
            for (i = 0; i <= da; i++) fmpq_poly_set_fmpz(P.c + i, alpha->minpoly->coeffs + i);
            P.deg = da;
            {
                /* Horner in x with coefficients in Q(gamma): lin = gamma - k x */
                kpoly_t acc, nx;
                slong j;
                kp_init(&acc, db + 1); kp_init(&nx, db + 1);
                fmpq_poly_set_coeff_si(z, 1, 1);
                fmpq_poly_rem(z, z, m);
                for (i = db; i >= 0; i--) {
                    /* acc = acc * (z - k x) + c_i */
                    for (j = 0; j < nx.cap; j++) fmpq_poly_zero(nx.c + j);
                    for (j = 0; j <= acc.deg; j++) {
                        fmpq_poly_mul(lin, acc.c + j, z);
                        fmpq_poly_add(nx.c + j, nx.c + j, lin);
                        fmpq_poly_scalar_mul_si(lin, acc.c + j, -k);
                        fmpq_poly_add(nx.c + j + 1, nx.c + j + 1, lin);
                    }
                    for (j = 0; j < nx.cap; j++) fmpq_poly_rem(nx.c + j, nx.c + j, m);
                    fmpq_poly_set_fmpz(lin, beta->minpoly->coeffs + i);
                    fmpq_poly_add(nx.c + 0, nx.c + 0, lin);
                    nx.deg = nx.cap - 1;
                    kp_normalise(&nx);
                    kp_set(&acc, &nx);
                }
                kp_set(&Q, &acc);
                kp_clear(&acc); kp_clear(&nx);
            }
            kp_gcd(&G, &P, &Q, m);
            if (G.deg == 1) {
                /* monic: x + g0, alpha = -g0; beta = gamma - k alpha */
                fmpq_poly_neg(A, G.c + 0);
                fmpq_poly_scalar_mul_si(B, A, -k);
                fmpq_poly_add(B, B, z);
                fmpq_poly_rem(B, B, m);
                fmpz_poly_set(gamma->minpoly, roots[hit].minpoly);
                gamma->idx = roots[hit].idx;
                gamma->rational = roots[hit].rational;
                fmpq_set(gamma->q, roots[hit].q);
                arb_set(gamma->x, roots[hit].x);
                gamma->prec = roots[hit].prec;
                ok = 1;
            }
            kp_clear(&P); kp_clear(&Q); kp_clear(&G);
            fmpq_poly_clear(m); fmpq_poly_clear(z); fmpq_poly_clear(lin);
        }
        for (i = 0; i < nroots; i++) alg_clear(roots + i);
        free(roots);
    }
    fmpz_mpoly_clear(ma, ctx); fmpz_mpoly_clear(mb, ctx); fmpz_mpoly_clear(res, ctx);
    fmpz_mpoly_ctx_clear(ctx);
    fmpz_poly_clear(u);
    return ok;
}
