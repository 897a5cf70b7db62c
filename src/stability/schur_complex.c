/* schur_complex.c -- unit-circle tests for polynomials over Q(i): the
 * Schur-Cohn recursion on complex coefficients (Marden, Geometry of
 * Polynomials, Thm 43.1; Henrici, Applied and Computational Complex
 * Analysis I, 6.8) and the real route p conj(p), which must agree. */
#include <string.h>
#include <flint/fmpq.h>
#include "stability/schur_complex.h"
#include "util/qd.h"

static slong cdeg(const fmpq_poly_t re, const fmpq_poly_t im)
{
    return FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im));
}

/* |a_k|^2 */
static void cnorm2(fmpq_t out, const fmpq_poly_t re, const fmpq_poly_t im, slong k)
{
    fmpq_t x;
    fmpq_init(x);
    fmpq_poly_get_coeff_fmpq(out, re, k);
    fmpq_mul(out, out, out);
    fmpq_poly_get_coeff_fmpq(x, im, k);
    fmpq_addmul(out, x, x);
    fmpq_clear(x);
}

/* (or + i oi) = (cr + i ci) (pr + i pi) */
static void cscale(fmpq_poly_t or_, fmpq_poly_t oi, const fmpq_t cr, const fmpq_t ci,
                   const fmpq_poly_t pr, const fmpq_poly_t pi)
{
    fmpq_poly_t a, b;
    fmpq_poly_init(a); fmpq_poly_init(b);
    fmpq_poly_scalar_mul_fmpq(a, pr, cr);
    fmpq_poly_scalar_mul_fmpq(b, pi, ci);
    fmpq_poly_sub(a, a, b);
    fmpq_poly_scalar_mul_fmpq(b, pi, cr);
    fmpq_poly_scalar_mul_fmpq(oi, pr, ci);
    fmpq_poly_add(oi, oi, b);
    fmpq_poly_swap(or_, a);
    fmpq_poly_clear(a); fmpq_poly_clear(b);
}

int rs_schur_complex_inside(const fmpq_poly_t re, const fmpq_poly_t im)
{
    fmpq_poly_t pr, pi, sr, si, tr, ti;
    fmpq_t an, a0, cr, ci;
    slong n = cdeg(re, im);
    int ok = 1;
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    fmpq_poly_init(sr); fmpq_poly_init(si);
    fmpq_poly_init(tr); fmpq_poly_init(ti);
    fmpq_init(an); fmpq_init(a0); fmpq_init(cr); fmpq_init(ci);
    fmpq_poly_set(pr, re);
    fmpq_poly_set(pi, im);
    while (ok && n >= 1) {
        cnorm2(an, pr, pi, n);
        cnorm2(a0, pr, pi, 0);
        if (fmpq_cmp(an, a0) <= 0) { ok = 0; break; }   /* |prod roots| >= 1, or a root on the circle */
        /* p* = lambda^n conj(p(1/conj lambda)): reversed conjugate coefficients */
        fmpq_poly_reverse(sr, pr, n + 1);
        fmpq_poly_reverse(si, pi, n + 1);
        fmpq_poly_neg(si, si);
        /* conj(a_n) p - a_0 p*, then / lambda */
        fmpq_poly_get_coeff_fmpq(cr, pr, n);
        fmpq_poly_get_coeff_fmpq(ci, pi, n);
        fmpq_neg(ci, ci);
        cscale(tr, ti, cr, ci, pr, pi);
        fmpq_poly_get_coeff_fmpq(cr, pr, 0);
        fmpq_poly_get_coeff_fmpq(ci, pi, 0);
        cscale(sr, si, cr, ci, sr, si);
        fmpq_poly_sub(pr, tr, sr);
        fmpq_poly_sub(pi, ti, si);
        fmpq_poly_shift_right(pr, pr, 1);
        fmpq_poly_shift_right(pi, pi, 1);
        n--;
        /* the new leading coefficient is |a_n|^2 - |a_0|^2 > 0: scale it to 1 (keeps sizes small) */
        fmpq_sub(an, an, a0);
        fmpq_poly_scalar_div_fmpq(pr, pr, an);
        fmpq_poly_scalar_div_fmpq(pi, pi, an);
    }
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    fmpq_poly_clear(sr); fmpq_poly_clear(si);
    fmpq_poly_clear(tr); fmpq_poly_clear(ti);
    fmpq_clear(an); fmpq_clear(a0); fmpq_clear(cr); fmpq_clear(ci);
    return ok;
}

void rs_schur_complex_norm(fmpz_poly_t P, const fmpq_poly_t re, const fmpq_poly_t im)
{
    fmpq_poly_t a, b;
    fmpq_poly_init(a); fmpq_poly_init(b);
    fmpq_poly_mul(a, re, re);
    fmpq_poly_mul(b, im, im);
    fmpq_poly_add(a, a, b);
    fmpq_poly_get_numerator(P, a);
    fmpz_poly_primitive_part(P, P);
    fmpq_poly_clear(a); fmpq_poly_clear(b);
}

/* (lr + i li) = 1 / (the leading coefficient of re + i im), which is non-zero */
static void cinv_lead(fmpq_t lr, fmpq_t li, const fmpq_poly_t re, const fmpq_poly_t im)
{
    slong n = cdeg(re, im);
    fmpq_t d;
    fmpq_init(d);
    fmpq_poly_get_coeff_fmpq(lr, re, n);
    fmpq_poly_get_coeff_fmpq(li, im, n);
    fmpq_mul(d, lr, lr);
    fmpq_addmul(d, li, li);
    fmpq_div(lr, lr, d);
    fmpq_div(li, li, d);
    fmpq_neg(li, li);
    fmpq_clear(d);
}

/* a = a mod b (b != 0) by exact long division over Q(i); the quotient is
 * added to q = qr + i qi when qr is not NULL */
static void cx_divrem(fmpq_poly_t qr, fmpq_poly_t qi, fmpq_poly_t ar, fmpq_poly_t ai,
                      const fmpq_poly_t br, const fmpq_poly_t bi)
{
    fmpq_poly_t tr, ti;
    fmpq_t lr, li, cr, ci, xr, xi;
    slong db = cdeg(br, bi);
    fmpq_poly_init(tr); fmpq_poly_init(ti);
    fmpq_init(lr); fmpq_init(li); fmpq_init(cr); fmpq_init(ci); fmpq_init(xr); fmpq_init(xi);
    cinv_lead(lr, li, br, bi);
    while (cdeg(ar, ai) >= db) {
        slong da = cdeg(ar, ai);
        /* c = lead(a) / lead(b), q += c x^(da - db), a -= c x^(da - db) b */
        fmpq_poly_get_coeff_fmpq(xr, ar, da);
        fmpq_poly_get_coeff_fmpq(xi, ai, da);
        fmpq_mul(cr, xr, lr); fmpq_submul(cr, xi, li);
        fmpq_mul(ci, xr, li); fmpq_addmul(ci, xi, lr);
        if (qr != NULL) {
            fmpq_poly_set_coeff_fmpq(qr, da - db, cr);
            fmpq_poly_set_coeff_fmpq(qi, da - db, ci);
        }
        cscale(tr, ti, cr, ci, br, bi);
        fmpq_poly_shift_left(tr, tr, da - db);
        fmpq_poly_shift_left(ti, ti, da - db);
        fmpq_poly_sub(ar, ar, tr);
        fmpq_poly_sub(ai, ai, ti);
        /* exact cancellation of the top coefficient */
        fmpq_poly_set_coeff_si(ar, da, 0);
        fmpq_poly_set_coeff_si(ai, da, 0);
    }
    fmpq_poly_clear(tr); fmpq_poly_clear(ti);
    fmpq_clear(lr); fmpq_clear(li); fmpq_clear(cr); fmpq_clear(ci); fmpq_clear(xr); fmpq_clear(xi);
}

void rs_schur_complex_gcd(fmpq_poly_t gre, fmpq_poly_t gim, const fmpq_poly_t are, const fmpq_poly_t aim,
                          const fmpq_poly_t bre, const fmpq_poly_t bim)
{
    fmpq_poly_t ar, ai, br, bi;
    fmpq_t lr, li;
    fmpq_poly_init(ar); fmpq_poly_init(ai); fmpq_poly_init(br); fmpq_poly_init(bi);
    fmpq_init(lr); fmpq_init(li);
    fmpq_poly_set(ar, are); fmpq_poly_set(ai, aim);
    fmpq_poly_set(br, bre); fmpq_poly_set(bi, bim);
    while (cdeg(br, bi) >= 0) {
        cx_divrem(NULL, NULL, ar, ai, br, bi);
        fmpq_poly_swap(ar, br); fmpq_poly_swap(ai, bi);
    }
    /* a is the gcd: make it monic */
    if (cdeg(ar, ai) >= 0) {
        cinv_lead(lr, li, ar, ai);
        cscale(ar, ai, lr, li, ar, ai);
    }
    fmpq_poly_swap(gre, ar); fmpq_poly_swap(gim, ai);
    fmpq_poly_clear(ar); fmpq_poly_clear(ai); fmpq_poly_clear(br); fmpq_poly_clear(bi);
    fmpq_clear(lr); fmpq_clear(li);
}

void rs_schur_complex_div(fmpq_poly_t qre, fmpq_poly_t qim, const fmpq_poly_t are, const fmpq_poly_t aim,
                          const fmpq_poly_t bre, const fmpq_poly_t bim)
{
    fmpq_poly_t ar, ai, qr, qi;
    fmpq_poly_init(ar); fmpq_poly_init(ai); fmpq_poly_init(qr); fmpq_poly_init(qi);
    fmpq_poly_set(ar, are); fmpq_poly_set(ai, aim);
    cx_divrem(qr, qi, ar, ai, bre, bim);
    fmpq_poly_swap(qre, qr); fmpq_poly_swap(qim, qi);
    fmpq_poly_clear(ar); fmpq_poly_clear(ai); fmpq_poly_clear(qr); fmpq_poly_clear(qi);
}

void rs_cx_sqfree_init(rs_cx_sqfree_t *f)
{
    f->n = 0;
    f->re = f->im = NULL;
}

void rs_cx_sqfree_clear(rs_cx_sqfree_t *f)
{
    slong k;
    for (k = 0; k < f->n; k++) {
        fmpq_poly_clear(f->re + k);
        fmpq_poly_clear(f->im + k);
    }
    flint_free(f->re);
    flint_free(f->im);
    rs_cx_sqfree_init(f);
}

void rs_schur_complex_sqfree(rs_cx_sqfree_t *f, const fmpq_poly_t re, const fmpq_poly_t im)
{
    fmpq_poly_t br, bi, dr, di, gr, gi, tr, ti;
    slong cap = FLINT_MAX(cdeg(re, im), 1);
    rs_cx_sqfree_clear(f);
    f->re = flint_malloc((size_t) cap * sizeof(fmpq_poly_struct));
    f->im = flint_malloc((size_t) cap * sizeof(fmpq_poly_struct));
    if (cdeg(re, im) < 1) return;
    fmpq_poly_init(br); fmpq_poly_init(bi); fmpq_poly_init(dr); fmpq_poly_init(di);
    fmpq_poly_init(gr); fmpq_poly_init(gi); fmpq_poly_init(tr); fmpq_poly_init(ti);
    /* g = gcd(p, p'), b = p/g, d = p'/g - b' */
    fmpq_poly_derivative(dr, re);
    fmpq_poly_derivative(di, im);
    rs_schur_complex_gcd(gr, gi, re, im, dr, di);
    rs_schur_complex_div(br, bi, re, im, gr, gi);
    rs_schur_complex_div(tr, ti, dr, di, gr, gi);
    fmpq_poly_derivative(dr, br);
    fmpq_poly_derivative(di, bi);
    fmpq_poly_sub(dr, tr, dr);
    fmpq_poly_sub(di, ti, di);
    while (cdeg(br, bi) >= 1 && f->n < cap) {
        /* a_k = gcd(b, d); b = b/a_k, d = d/a_k - b' */
        fmpq_poly_init(f->re + f->n);
        fmpq_poly_init(f->im + f->n);
        rs_schur_complex_gcd(f->re + f->n, f->im + f->n, br, bi, dr, di);
        rs_schur_complex_div(tr, ti, br, bi, f->re + f->n, f->im + f->n);
        fmpq_poly_swap(br, tr); fmpq_poly_swap(bi, ti);
        rs_schur_complex_div(tr, ti, dr, di, f->re + f->n, f->im + f->n);
        fmpq_poly_derivative(dr, br);
        fmpq_poly_derivative(di, bi);
        fmpq_poly_sub(dr, tr, dr);
        fmpq_poly_sub(di, ti, di);
        f->n++;
    }
    fmpq_poly_clear(br); fmpq_poly_clear(bi); fmpq_poly_clear(dr); fmpq_poly_clear(di);
    fmpq_poly_clear(gr); fmpq_poly_clear(gi); fmpq_poly_clear(tr); fmpq_poly_clear(ti);
}

int rs_schur_complex_status(rs_status_t *st, const fmpq_poly_t re, const fmpq_poly_t im, slong deg,
                            rs_error_t err)
{
    fmpz_poly_t P;
    rs_rootcount_t rc;
    int inside, r;
    slong n = cdeg(re, im);
    if (n < 0) return rs_error_set(err, RS_ERR_MATH, "the characteristic polynomial vanishes identically");
    if (n < deg) { *st = RS_STATUS_SINGULAR; return RS_OK; }
    inside = rs_schur_complex_inside(re, im);
    fmpz_poly_init(P);
    rs_rootcount_init(rc);
    rs_schur_complex_norm(P, re, im);
    r = rs_rootcount_factor(rc, P, err);
    if (r == RS_OK && inside != (rc->inside == rc->degree))
        r = rs_error_set(err, RS_ERR_INCONSISTENT,
                         "complex Schur-Cohn and the count of p conj(p) disagree on 'all roots inside'");
    if (r == RS_OK) {
        if (inside) *st = RS_STATUS_STABLE;
        else if (rc->outside > 0) *st = RS_STATUS_UNSTABLE;
        else {
            /* all |lambda| <= 1, some on the circle: a repeated one is a root of gcd(p, p') */
            fmpq_poly_t dr, di, gr, gi;
            fmpz_poly_t G;
            rs_rootcount_t gc;
            fmpq_poly_init(dr); fmpq_poly_init(di); fmpq_poly_init(gr); fmpq_poly_init(gi);
            fmpz_poly_init(G);
            rs_rootcount_init(gc);
            fmpq_poly_derivative(dr, re);
            fmpq_poly_derivative(di, im);
            rs_schur_complex_gcd(gr, gi, re, im, dr, di);
            *st = RS_STATUS_MARGINAL;
            if (cdeg(gr, gi) >= 1) {
                rs_schur_complex_norm(G, gr, gi);
                r = rs_rootcount_factor(gc, G, err);
                if (r == RS_OK && gc->on > 0) *st = RS_STATUS_UNSTABLE;
            }
            rs_rootcount_clear(gc);
            fmpz_poly_clear(G);
            fmpq_poly_clear(dr); fmpq_poly_clear(di); fmpq_poly_clear(gr); fmpq_poly_clear(gi);
        }
    }
    rs_rootcount_clear(rc);
    fmpz_poly_clear(P);
    return r;
}

/* ---- symbolic: coefficients in Z[params] + i Z[params] ----------------------
 * p = re + I im lives in a context with one more variable I (the last),
 * reduced by I^2 = -1 after every product: then resultants, discriminants and
 * the Schur-Cohn recursion are FLINT's integer multivariate routines. */

/* I^e -> I^(e mod 2) with the sign of I^2 = -1: the Q(sqrt d) reduction with d = -1 */
static void cx_reduce(fmpz_mpoly_t f, slong iv, const fmpz_mpoly_ctx_t cx)
{
    rs_qd_mpoly_reduce(f, iv, -1, cx);
}

/* the complex conjugate of f (reduced): its odd powers of I negated; out may be f */
static void cx_conj(fmpz_mpoly_t out, const fmpz_mpoly_t f, slong iv, const fmpz_mpoly_ctx_t cx)
{
    fmpz_mpoly_t im, re, ig;
    ulong zero = 0, one = 1;
    fmpz_mpoly_init(im, cx); fmpz_mpoly_init(re, cx); fmpz_mpoly_init(ig, cx);
    fmpz_mpoly_get_coeff_vars_ui(im, f, &iv, &one, 1, cx);
    fmpz_mpoly_get_coeff_vars_ui(re, f, &iv, &zero, 1, cx);
    fmpz_mpoly_gen(ig, iv, cx);
    fmpz_mpoly_mul(im, im, ig, cx);
    fmpz_mpoly_sub(out, re, im, cx);
    fmpz_mpoly_clear(im, cx); fmpz_mpoly_clear(re, cx); fmpz_mpoly_clear(ig, cx);
}

/* the part free of I (e = 0) or the coefficient of I (e = 1), back in ctx */
static void cx_part(fmpz_mpoly_t out, const fmpz_mpoly_t f, slong iv, ulong e, const fmpz_mpoly_ctx_t cx,
                    const fmpz_mpoly_ctx_t ctx)
{
    slong nv = cx->minfo->nvars, k;
    slong *map = flint_malloc((size_t) nv * sizeof(slong));
    fmpz_mpoly_t a;
    fmpz_mpoly_init(a, cx);
    fmpz_mpoly_get_coeff_vars_ui(a, f, &iv, &e, 1, cx);
    for (k = 0; k < nv; k++) map[k] = k < iv ? k : 0;     /* I does not occur in a */
    fmpz_mpoly_compose_fmpz_mpoly_gen(out, a, map, cx, ctx);
    fmpz_mpoly_clear(a, cx);
    flint_free(map);
}

void rs_schur_cx_conds_init(rs_schur_cx_conds_t *c)
{
    memset(c, 0, sizeof *c);
}

void rs_schur_cx_conds_clear(rs_schur_cx_conds_t *c, const fmpz_mpoly_ctx_t ctx)
{
    slong k;
    if (c->ndelta > 0 || c->have) {
        for (k = 0; k < c->ndelta; k++) fmpz_mpoly_clear(c->delta + k, ctx);
        fmpz_mpoly_clear(c->lead, ctx);
        fmpz_mpoly_clear(c->disc_re, ctx);
        fmpz_mpoly_clear(c->disc_im, ctx);
        fmpz_mpoly_clear(c->res, ctx);
    }
    flint_free(c->delta);
    memset(c, 0, sizeof *c);
}

int rs_schur_cx_conds(rs_schur_cx_conds_t *c, const fmpz_mpoly_t re, const fmpz_mpoly_t im, slong lv,
                      const fmpz_mpoly_ctx_t ctx)
{
    slong nv = ctx->minfo->nvars, iv = nv, n, k, j;
    slong *emb = flint_malloc((size_t) nv * sizeof(slong));
    fmpz_mpoly_ctx_t cx;
    fmpz_mpoly_t p, ps, an, a0, t, u, ig, lam;
    int ok = 1;
    n = FLINT_MAX(fmpz_mpoly_degree_si(re, lv, ctx), fmpz_mpoly_degree_si(im, lv, ctx));
    if (n < 1) { flint_free(emb); return 0; }
    fmpz_mpoly_ctx_init(cx, nv + 1, ORD_LEX);
    for (k = 0; k < nv; k++) emb[k] = k;
    fmpz_mpoly_init(p, cx); fmpz_mpoly_init(ps, cx); fmpz_mpoly_init(an, cx); fmpz_mpoly_init(a0, cx);
    fmpz_mpoly_init(t, cx); fmpz_mpoly_init(u, cx); fmpz_mpoly_init(ig, cx); fmpz_mpoly_init(lam, cx);
    fmpz_mpoly_gen(ig, iv, cx);
    fmpz_mpoly_gen(lam, lv, cx);
    fmpz_mpoly_compose_fmpz_mpoly_gen(p, re, emb, ctx, cx);
    fmpz_mpoly_compose_fmpz_mpoly_gen(t, im, emb, ctx, cx);
    fmpz_mpoly_mul(t, t, ig, cx);
    fmpz_mpoly_add(p, p, t, cx);
    c->have = 1;
    c->ndelta = n;
    c->delta = flint_malloc((size_t) n * sizeof(fmpz_mpoly_struct));
    for (k = 0; k < n; k++) fmpz_mpoly_init(c->delta + k, ctx);
    fmpz_mpoly_init(c->lead, ctx); fmpz_mpoly_init(c->disc_re, ctx);
    fmpz_mpoly_init(c->disc_im, ctx); fmpz_mpoly_init(c->res, ctx);
    /* |a_n|^2 */
    {
        ulong e = (ulong) n;
        fmpz_mpoly_get_coeff_vars_ui(an, p, &lv, &e, 1, cx);
        cx_conj(t, an, iv, cx);
        fmpz_mpoly_mul(t, t, an, cx);
        cx_reduce(t, iv, cx);
        cx_part(c->lead, t, iv, 0, cx, ctx);
    }
    /* p* = lambda^n conj(p(1/conj lambda)), the resultant of p and p*
     * (real: prod |a_n|^2 (1 - |z_i|^2) prod_{i<j} |1 - z_i conj z_j|^2, zero
     * when a root is on the circle) and the discriminant of p */
    fmpz_mpoly_zero(ps, cx);
    for (k = 0; k <= n; k++) {
        ulong e = (ulong) (n - k);
        fmpz_mpoly_get_coeff_vars_ui(t, p, &lv, &e, 1, cx);
        cx_conj(t, t, iv, cx);
        fmpz_mpoly_pow_ui(u, lam, (ulong) k, cx);
        fmpz_mpoly_mul(t, t, u, cx);
        fmpz_mpoly_add(ps, ps, t, cx);
    }
    {   /* self-inversive: a_n p* = conj(a_0) p */
        ulong z = 0;
        fmpz_mpoly_get_coeff_vars_ui(a0, p, &lv, &z, 1, cx);
        cx_conj(a0, a0, iv, cx);
        fmpz_mpoly_mul(t, an, ps, cx);
        fmpz_mpoly_mul(u, a0, p, cx);
        fmpz_mpoly_sub(t, t, u, cx);
        cx_reduce(t, iv, cx);
        c->self_inversive = fmpz_mpoly_is_zero(t, cx);
    }
    if (fmpz_mpoly_degree_si(ps, lv, cx) >= 1 && fmpz_mpoly_resultant(t, p, ps, lv, cx)) {
        cx_reduce(t, iv, cx);
        cx_part(c->res, t, iv, 0, cx, ctx);
        cx_part(c->disc_im, t, iv, 1, cx, ctx);
        /* real by the product above when deg p* = n; otherwise (a_0 = 0)
         * FLINT's resultant has a complex factor a_n^(n - deg p*): |Res|^2,
         * the same zeros */
        if (!fmpz_mpoly_is_zero(c->disc_im, ctx)) {
            fmpz_mpoly_mul(c->res, c->res, c->res, ctx);
            fmpz_mpoly_mul(c->disc_im, c->disc_im, c->disc_im, ctx);
            fmpz_mpoly_add(c->res, c->res, c->disc_im, ctx);
        }
        fmpz_mpoly_zero(c->disc_im, ctx);
    }
    if (ok && n >= 2 && fmpz_mpoly_discriminant(t, p, lv, cx)) {
        cx_reduce(t, iv, cx);
        cx_part(c->disc_re, t, iv, 0, cx, ctx);
        cx_part(c->disc_im, t, iv, 1, cx, ctx);
    }
    /* Schur-Cohn without divisions: p_{k-1} = (conj(a_k) p_k - a_0 p_k*)/lambda,
     * delta_k = |a_k|^2 - |a_0|^2 its leading coefficient; all roots inside
     * iff every delta_k > 0 (Marden, Thm 43.1) */
    for (k = n; ok && k >= 1; k--) {
        ulong e = (ulong) k, z = 0;
        fmpz_mpoly_get_coeff_vars_ui(an, p, &lv, &e, 1, cx);
        fmpz_mpoly_get_coeff_vars_ui(a0, p, &lv, &z, 1, cx);
        fmpz_mpoly_zero(ps, cx);
        for (j = 0; j <= k; j++) {
            ulong f = (ulong) (k - j);
            fmpz_mpoly_get_coeff_vars_ui(t, p, &lv, &f, 1, cx);
            cx_conj(t, t, iv, cx);
            fmpz_mpoly_pow_ui(u, lam, (ulong) j, cx);
            fmpz_mpoly_mul(t, t, u, cx);
            fmpz_mpoly_add(ps, ps, t, cx);
        }
        cx_conj(t, an, iv, cx);
        fmpz_mpoly_mul(t, t, an, cx);
        cx_conj(u, a0, iv, cx);
        fmpz_mpoly_mul(u, u, a0, cx);
        fmpz_mpoly_sub(t, t, u, cx);
        cx_reduce(t, iv, cx);
        cx_part(c->delta + (n - k), t, iv, 0, cx, ctx);
        if (k == 1) break;
        if (fmpz_mpoly_length(p, cx) > 20000) { ok = 0; break; }     /* too large: not handled */
        cx_conj(t, an, iv, cx);
        fmpz_mpoly_mul(t, t, p, cx);
        fmpz_mpoly_mul(u, a0, ps, cx);
        fmpz_mpoly_sub(t, t, u, cx);
        cx_reduce(t, iv, cx);
        ok = fmpz_mpoly_is_zero(t, cx) || fmpz_mpoly_divides(p, t, lam, cx);
        if (fmpz_mpoly_is_zero(t, cx)) fmpz_mpoly_zero(p, cx);
    }
    fmpz_mpoly_clear(p, cx); fmpz_mpoly_clear(ps, cx); fmpz_mpoly_clear(an, cx); fmpz_mpoly_clear(a0, cx);
    fmpz_mpoly_clear(t, cx); fmpz_mpoly_clear(u, cx); fmpz_mpoly_clear(ig, cx); fmpz_mpoly_clear(lam, cx);
    fmpz_mpoly_ctx_clear(cx);
    flint_free(emb);
    return ok;
}
