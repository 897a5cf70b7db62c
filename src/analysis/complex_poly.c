/* complex_poly.c -- p with coefficients in Q(i), shared by the analyses
 * that run over Q(i) with real parameters left (hurwitz, jury, modes) and by
 * the point verdict of run.c: complex set values substituted into p (or a
 * `char` line with i read back from its real 2x2 block form [[A, -B], [B, A]]),
 * p = re + i im with re, im in Z[real params][lambda]. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <acb_poly.h>
#include <fmpq_vec.h>
#include <fmpz_vec.h>
#include "analysis/impl.h"
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"
#include "analysis/registry.h"
#include "analysis/sweep_impl.h"
#include "recstab/ladder.h"

/* the complex value of variable var (a parameter), or -1 */
static slong cset_of(const rs_run_t *run, slong var)
{
    slong k;
    if (var >= run->c->nparams) return -1;
    for (k = 0; k < run->c->ncsets; k++)
        if (strcmp(run->c->csets[k].name, run->c->params[var].name) == 0) return k;
    return -1;
}

/* adds c i^ib times the term with exponents ex to qr + i qi, the complex
 * set values substituted (their exponents zeroed); unsorted: the caller
 * sorts and combines */
void rs_cx_add_term(fmpq_mpoly_t qr, fmpq_mpoly_t qi, const fmpq_t c, int ib, slong *ex, const rs_run_t *run,
                     const rs_scheme_struct *s)
{
    fmpq_t fr, fi, t;
    slong v, k;
    ulong *ue = flint_malloc((size_t) s->nvars * sizeof(ulong));
    fmpq_init(fr); fmpq_init(fi); fmpq_init(t);
    fmpq_set(fr, c);
    for (v = 0; v < s->nvars; v++) {
        slong cs = v == s->lambda_var ? -1 : cset_of(run, v);
        if (cs >= 0) {
            const fmpq *a = run->c->csets[cs].re, *b = run->c->csets[cs].im;
            for (k = 0; k < ex[v]; k++) {   /* (fr + i fi)(a + i b) */
                fmpq_mul(t, fr, a);
                fmpq_submul(t, fi, b);
                fmpq_mul(fi, fi, a);
                fmpq_addmul(fi, fr, b);
                fmpq_swap(fr, t);
            }
            ex[v] = 0;
        }
        ue[v] = (ulong) ex[v];
    }
    if (ib) { fmpq_swap(fr, fi); fmpq_neg(fr, fr); }   /* times i */
    if (!fmpq_is_zero(fr)) fmpq_mpoly_push_term_fmpq_ui(qr, fr, ue, s->ctx);
    if (!fmpq_is_zero(fi)) fmpq_mpoly_push_term_fmpq_ui(qi, fi, ue, s->ctx);
    fmpq_clear(fr); fmpq_clear(fi); fmpq_clear(t);
    flint_free(ue);
}

slong rs_run_cx_poly(fmpz_mpoly_t re, fmpz_mpoly_t im, const rs_run_t *run, const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    fmpq_mpoly_t qr, qi;
    slong *ex, i, len;
    fmpq_t c;
    fmpz_t d, g;
    fmpq_mpoly_init(qr, s->ctx); fmpq_mpoly_init(qi, s->ctx);
    fmpq_init(c);
    fmpz_init(d); fmpz_init(g);
    ex = flint_malloc((size_t) s->nvars * sizeof(slong));
    if (s->complex_char) {
        /* the block [[A, -B], [B, A]] of p = A + i B */
        int part;
        for (part = 0; part < 2; part++) {
            const fmpq_mpoly_struct *m = s->M + 2 * part;
            len = fmpq_mpoly_length(m, s->ctx);
            for (i = 0; i < len; i++) {
                fmpq_mpoly_get_term_coeff_fmpq(c, m, i, s->ctx);
                fmpq_mpoly_get_term_exp_si(ex, m, i, s->ctx);
                rs_cx_add_term(qr, qi, c, part, ex, run, s);
            }
        }
    } else {
        len = fmpz_mpoly_length(v->cp->p, s->zctx);
        for (i = 0; i < len; i++) {
            fmpz_mpoly_get_term_coeff_fmpz(fmpq_numref(c), v->cp->p, i, s->zctx);
            fmpz_one(fmpq_denref(c));
            fmpz_mpoly_get_term_exp_si(ex, v->cp->p, i, s->zctx);
            rs_cx_add_term(qr, qi, c, 0, ex, run, s);
        }
    }
    fmpq_mpoly_sort_terms(qr, s->ctx); fmpq_mpoly_combine_like_terms(qr, s->ctx);
    fmpq_mpoly_sort_terms(qi, s->ctx); fmpq_mpoly_combine_like_terms(qi, s->ctx);
    /* common denominator, then the common integer content */
    fmpz_lcm(d, fmpq_denref(qr->content), fmpq_denref(qi->content));
    fmpq_mpoly_scalar_mul_fmpz(qr, qr, d, s->ctx);
    fmpq_mpoly_scalar_mul_fmpz(qi, qi, d, s->ctx);
    fmpz_mpoly_scalar_mul_fmpz(re, qr->zpoly, fmpq_numref(qr->content), s->zctx);
    fmpz_mpoly_scalar_mul_fmpz(im, qi->zpoly, fmpq_numref(qi->content), s->zctx);
    _fmpz_vec_content(g, re->coeffs, re->length);
    _fmpz_vec_content(d, im->coeffs, im->length);
    fmpz_gcd(g, g, d);
    /* the sign of the real path (rs_charpoly_normalise): the first term of
     * the leading coefficient in lambda positive, of its real part (of its
     * imaginary part when the real part is zero); charpoly over Q(i) prints
     * p so (cpoint_get) */
    {
        slong n = FLINT_MAX(fmpz_mpoly_degree_si(re, s->lambda_var, s->zctx),
                            fmpz_mpoly_degree_si(im, s->lambda_var, s->zctx));
        fmpz_mpoly_t lc;
        fmpz_mpoly_init(lc, s->zctx);
        if (n >= 0) {
            rs_charpoly_coeff(lc, re, n, s->lambda_var, s->zctx);
            if (fmpz_mpoly_is_zero(lc, s->zctx)) rs_charpoly_coeff(lc, im, n, s->lambda_var, s->zctx);
            if (!fmpz_mpoly_is_zero(lc, s->zctx) && fmpz_sgn(lc->coeffs + 0) < 0) fmpz_neg(g, g);
        }
        fmpz_mpoly_clear(lc, s->zctx);
    }
    if (!fmpz_is_zero(g) && !fmpz_is_one(g)) {
        fmpz_mpoly_scalar_divexact_fmpz(re, re, g, s->zctx);
        fmpz_mpoly_scalar_divexact_fmpz(im, im, g, s->zctx);
    }
    flint_free(ex);
    fmpq_clear(c);
    fmpz_clear(d); fmpz_clear(g);
    fmpq_mpoly_clear(qr, s->ctx); fmpq_mpoly_clear(qi, s->ctx);
    return FLINT_MAX(fmpz_mpoly_degree_si(re, s->lambda_var, s->zctx),
                     fmpz_mpoly_degree_si(im, s->lambda_var, s->zctx));
}

slong rs_run_cx_poly_det(fmpz_mpoly_t re, fmpz_mpoly_t im, const rs_run_t *run, const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    slong n = rs_run_cx_poly(re, im, run, v), k = s->complex_char ? 0 : v->cp->removed_lambda_power;
    if (n >= 0 && k > 0) {
        fmpz_mpoly_t lk;
        fmpz_mpoly_init(lk, s->zctx);
        fmpz_mpoly_gen(lk, s->lambda_var, s->zctx);
        fmpz_mpoly_pow_ui(lk, lk, (ulong) k, s->zctx);
        fmpz_mpoly_mul(re, re, lk, s->zctx);
        fmpz_mpoly_mul(im, im, lk, s->zctx);
        fmpz_mpoly_clear(lk, s->zctx);
        n += k;
    }
    return n;
}

void rs_run_cx_eval(fmpq_poly_t out, const fmpz_mpoly_t p, fmpq *const *pt, const rs_scheme_struct *s)
{
    slong len = fmpz_mpoly_length(p, s->zctx), i, v;
    ulong *ex = flint_malloc((size_t) s->nvars * sizeof(ulong));
    fmpq_t c, x, old;
    fmpq_init(c); fmpq_init(x); fmpq_init(old);
    fmpq_poly_zero(out);
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_coeff_fmpz(fmpq_numref(c), p, i, s->zctx);
        fmpz_one(fmpq_denref(c));
        fmpz_mpoly_get_term_exp_ui(ex, p, i, s->zctx);
        for (v = 0; v < s->nvars; v++) {
            if (v == s->lambda_var || ex[v] == 0) continue;
            fmpq_pow_si(x, pt[v], (slong) ex[v]);
            fmpq_mul(c, c, x);
        }
        fmpq_poly_get_coeff_fmpq(old, out, (slong) ex[s->lambda_var]);
        fmpq_add(old, old, c);
        fmpq_poly_set_coeff_fmpq(out, (slong) ex[s->lambda_var], old);
    }
    fmpq_clear(c); fmpq_clear(x); fmpq_clear(old);
    flint_free(ex);
}

int rs_run_cx_point_status(rs_status_t *st, rs_rootcount_t rc, rs_run_t *run, const rs_variant_t *v,
                           const slong *vars, const fmpq *vals, slong nv, int real_st)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t re, im;
    fmpq_poly_t pr, pi;
    fmpq *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
    slong n, k;
    rs_status_t s1;
    int r = RS_OK;
    fmpz_mpoly_init(re, s->zctx); fmpz_mpoly_init(im, s->zctx);
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    for (k = 0; k < s->nvars; k++) pp[k] = pt + k;
    for (k = 0; k < nv; k++) fmpq_set(pt + vars[k], vals + k);
    n = rs_run_cx_poly_det(re, im, run, v);   /* the counts of det: its roots at 0 too */
    rs_run_cx_eval(pr, re, pp, s);
    rs_run_cx_eval(pi, im, pp, s);
    rs_rootcount_clear(rc);
    rs_rootcount_init(rc);
    if (v->singular || n < 1 || FLINT_MAX(fmpq_poly_degree(pr), fmpq_poly_degree(pi)) < n
        || (!s->complex_char && n < rs_charpoly_top_degree(v->cp))) {
        /* the leading coefficient of p vanishes here: no step can be solved */
        *st = RS_STATUS_SINGULAR;
    } else {
        r = rs_routh_complex_checked_status(&s1, pr, pi, n, run->err);
        if (r == RS_OK) {
            rs_routh_complex_rootcount(rc, pr, pi);
            if (rs_rootcount_status(rc) != s1)
                r = rs_error_set(run->err, RS_ERR_INCONSISTENT, "over Q(i): complex Schur-Cohn and Bilharz say %s, "
                                 "p's root counts say %s", rs_status_name(s1), rs_status_name(rs_rootcount_status(rc)));
            else if (real_st >= 0 && (rs_status_t) real_st != s1)
                r = rs_error_set(run->err, RS_ERR_INCONSISTENT, "the char line over Q(i): the real block form says "
                                 "%s, complex Schur-Cohn and Bilharz say %s", rs_status_name((rs_status_t) real_st),
                                 rs_status_name(s1));
            else *st = s1;
        }
    }
    fmpz_mpoly_clear(re, s->zctx); fmpz_mpoly_clear(im, s->zctx);
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    return r;
}

/* ---- roots, text and the certified cross-check of p over Q(i) ----------------- */

static slong cx_deg(const fmpq_poly_t re, const fmpq_poly_t im)
{
    return FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im));
}

int rs_cx_isolate_sqfree(acb_ptr out, const fmpq_poly_t ar, const fmpq_poly_t ai, slong bits, slong prec0,
                         slong max_prec)
{
    slong d = cx_deg(ar, ai), k, prec;
    int done = 0;
    /* a root at 0 (once: a is squarefree) is exact; Arb's ball around it has no
     * relative accuracy at any precision, so it is split off first */
    if (d >= 1 && (fmpq_poly_is_zero(ar) || fmpz_is_zero(ar->coeffs))
        && (fmpq_poly_is_zero(ai) || fmpz_is_zero(ai->coeffs))) {
        fmpq_poly_t sr, si;
        fmpq_poly_init(sr);
        fmpq_poly_init(si);
        fmpq_poly_shift_right(sr, ar, 1);
        fmpq_poly_shift_right(si, ai, 1);
        acb_zero(out);
        done = d == 1 || rs_cx_isolate_sqfree(out + 1, sr, si, bits, prec0, max_prec);
        fmpq_poly_clear(sr);
        fmpq_poly_clear(si);
        return done;
    }
    for (prec = prec0; prec <= max_prec && !done; prec *= 2) {
        acb_poly_t p;
        acb_t c;
        fmpq_t x;
        acb_poly_init(p);
        acb_init(c);
        fmpq_init(x);
        for (k = 0; k <= d; k++) {
            fmpq_poly_get_coeff_fmpq(x, ar, k);
            arb_set_fmpq(acb_realref(c), x, prec);
            fmpq_poly_get_coeff_fmpq(x, ai, k);
            arb_set_fmpq(acb_imagref(c), x, prec);
            acb_poly_set_coeff_acb(p, k, c);
        }
        if (acb_poly_find_roots(out, p, NULL, 0, prec) == d) {
            done = 1;
            for (k = 0; k < d; k++)
                if (!acb_is_exact(out + k) && acb_rel_accuracy_bits(out + k) < bits) done = 0;
        }
        fmpq_clear(x);
        acb_clear(c);
        acb_poly_clear(p);
    }
    return done;
}

int rs_cx_roots(rs_radius_t rr, const fmpq_poly_t pr, const fmpq_poly_t pi, slong bits, slong prec0, slong max_prec)
{
    slong n = cx_deg(pr, pi), k, at = 0, j, m;
    rs_cx_sqfree_t f;
    int ok = 1;
    rs_cx_sqfree_init(&f);
    rs_schur_complex_sqfree(&f, pr, pi);
    rr->nroots = n;
    rr->roots = _acb_vec_init(n);
    rr->mult = flint_malloc((size_t) (n + 1) * sizeof(slong));
    rr->isolated = 1;
    for (k = 1; k <= f.n && ok; k++) {
        slong da = cx_deg(f.re + k - 1, f.im + k - 1);
        if (da < 1) continue;
        if (at + k * da > n || !rs_cx_isolate_sqfree(rr->roots + at, f.re + k - 1, f.im + k - 1, bits, prec0,
                                                     max_prec)) {
            ok = 0;
            break;
        }
        /* each root k times (from the top: the sources below are not yet overwritten) */
        for (j = da - 1; j >= 0; j--)
            for (m = 0; m < k; m++) {
                acb_set(rr->roots + at + j * k + m, rr->roots + at + j);
                rr->mult[at + j * k + m] = k;
            }
        at += k * da;
    }
    rs_cx_sqfree_clear(&f);
    return ok ? (at == n ? 1 : -1) : 0;
}

char *rs_cx_poly_str(const fmpq_poly_t re, const fmpq_poly_t im, const char *var)
{
    slong n = cx_deg(re, im), k;
    size_t cap = 64, len = 0;
    char *out = malloc(cap);
    fmpq_t a, b;
    fmpq_init(a);
    fmpq_init(b);
    out[0] = '\0';
    for (k = n; k >= 0; k--) {
        char *c, pw[64];
        int paren, neg = 0;
        size_t need;
        fmpq_poly_get_coeff_fmpq(a, re, k);
        fmpq_poly_get_coeff_fmpq(b, im, k);
        if (fmpq_is_zero(a) && fmpq_is_zero(b)) continue;
        paren = !fmpq_is_zero(a) && !fmpq_is_zero(b);
        /* one part: print its sign as the term's */
        if (!paren && (fmpq_sgn(a) < 0 || fmpq_sgn(b) < 0)) { neg = 1; fmpq_neg(a, a); fmpq_neg(b, b); }
        c = rs_complex_str(a, b);
        if (k == 0) pw[0] = '\0';
        else if (k == 1) snprintf(pw, sizeof pw, "%s", var);
        else snprintf(pw, sizeof pw, "%s^%ld", var, (long) k);
        need = len + strlen(c) + strlen(pw) + 16;
        if (need > cap) { cap = 2 * need; out = realloc(out, cap); }
        if (len > 0) len += (size_t) sprintf(out + len, " %s ", neg ? "-" : "+");
        else if (neg) len += (size_t) sprintf(out + len, "-");
        if (k > 0 && !paren && fmpq_is_zero(b) && fmpq_is_one(a))
            len += (size_t) sprintf(out + len, "%s", pw);
        else if (k > 0 && !paren && fmpq_is_zero(a) && fmpq_is_one(b))
            len += (size_t) sprintf(out + len, "i*%s", pw);
        else
            len += (size_t) sprintf(out + len, "%s%s%s%s%s", paren ? "(" : "", c, paren ? ")" : "",
                                    k > 0 ? "*" : "", pw);
        free(c);
    }
    if (len == 0) strcpy(out, "0");
    fmpq_clear(a);
    fmpq_clear(b);
    return out;
}

int rs_cx_norm_check(rs_status_t st, const fmpq_poly_t re, const fmpq_poly_t im, rs_error_t err)
{
    fmpz_poly_t N;
    rs_sweep_point_t pt;
    int r;
    fmpz_poly_init(N);
    memset(&pt, 0, sizeof pt);
    rs_schur_complex_norm(N, re, im);
    r = rs_sweep_decide(&pt, N, err);
    if (r == RS_OK && (pt.verdict < 0 || (st == RS_STATUS_STABLE) != (pt.verdict == RS_STATUS_STABLE)
                       || (st == RS_STATUS_UNSTABLE && pt.verdict != RS_STATUS_UNSTABLE)))
        r = rs_error_set(err, RS_ERR_INCONSISTENT, "the exact verdict over Q(i) is %s, the certified verdict of "
                         "p conj(p) (%s rung) is %s", rs_status_name(st), rs_sweep_level_names[pt.level],
                         rs_sweep_verdict_name(pt.verdict));
    fmpz_poly_clear(N);
    return r;
}

json_t *rs_run_cx_at(const rs_run_t *run)
{
    json_t *at = json_object();
    slong k;
    for (k = 0; k < run->c->ncsets; k++) {
        char *str = rs_complex_str(run->c->csets[k].re, run->c->csets[k].im);
        json_object_set_new(at, run->c->csets[k].name, json_string(str));
        free(str);
    }
    return at;
}
