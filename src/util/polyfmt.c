/* polyfmt.c -- string forms of polynomials. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz.h>
#include <flint/mpoly.h>
#include "util/polyfmt.h"
#include "recstab/budget.h"

char *rs_polyfmt_spaced(const char *s)
{
    size_t n = strlen(s), i, j = 0;
    int depth = 0;
    char *out = malloc(3 * n + 1);
    for (i = 0; i < n; i++) {
        char ch = s[i];
        if (ch == '(') depth++;
        if (ch == ')') depth--;
        if ((ch == '+' || ch == '-') && i > 0 && depth == 0 && s[i - 1] != '^' && s[i - 1] != '('
            && s[i - 1] != '*' && s[i - 1] != '/' && s[i - 1] != ' ') {
            out[j++] = ' ';
            out[j++] = ch;
            out[j++] = ' ';
        } else {
            out[j++] = ch;
        }
    }
    out[j] = '\0';
    return out;
}

/* FLINT's pretty string then rs_polyfmt_spaced: the reference route, for
 * what the direct printer below does not handle */
static char *fmpz_mpoly_str_flint(const fmpz_mpoly_t p, const char **vars, const fmpz_mpoly_ctx_t ctx)
{
    char *s = fmpz_mpoly_get_str_pretty(p, vars, ctx);
    char *r = rs_polyfmt_spaced(s);
    flint_free(s);
    return r;
}

/* the decimal digits of u at out (no NUL); their number */
static size_t put_ulong(char *out, ulong u)
{
    char t[24];
    size_t n = 0, k;
    do { t[n++] = (char) ('0' + u % 10); u /= 10; } while (u != 0);
    for (k = 0; k < n; k++) out[k] = t[n - 1 - k];
    return n;
}

/* exactly 19 digits of u < 10^19, leading zeros kept */
static void put_19(char *out, ulong u)
{
    int k;
    for (k = 18; k >= 0; k--) {
        out[k] = (char) ('0' + u % 10);
        u /= 10;
    }
}

/* The decimal digits of |c| (a GMP integer) at out: chunks of 19 digits by
 * division by 10^19 (mpn_divrem_1), each chunk by word division.  The
 * coefficients of the chain's minors carry a content of 2^200 and more, and
 * fmpz_get_str (mpz_get_str: a temporary, its digit map, then our strlen and
 * memmove of the sign) was most of printing them (issue 17). */
static size_t put_mpz(char *out, const fmpz *c)
{
    const __mpz_struct *z = COEFF_TO_PTR(*c);
    mp_size_t n = FLINT_ABS(z->_mp_size);
    mp_limb_t t[16];
    ulong ch[20];   /* 16 limbs have at most 309 digits: 17 chunks */
    slong nch = 0, k;
    size_t len;
    if (n > 16) {
        /* long integers: GMP's subquadratic conversion */
        char *d = out;
        fmpz_get_str(d, 10, c);
        if (*d == '-') memmove(d, d + 1, strlen(d));
        return strlen(d);
    }
    mpn_copyi(t, z->_mp_d, n);
    while (n > 0) {
        ch[nch++] = mpn_divrem_1(t, 0, t, n, UWORD(10000000000000000000));
        while (n > 0 && t[n - 1] == 0) n--;
    }
    len = put_ulong(out, ch[nch - 1]);
    for (k = nch - 2; k >= 0; k--) {
        put_19(out + len, ch[k]);
        len += 19;
    }
    return len;
}

/* a name the spacing pass leaves alone: non-empty, none of ( ) + - ^ * / or
 * a blank (names are identifiers; this only guards the equivalence) */
static int plain_name(const char *v)
{
    return v != NULL && *v != '\0' && strpbrk(v, "()+-^*/ ") == NULL;
}

/* *buf (capacity *cap) grown to at least n bytes; 0, or -1 */
static int buf_fit(char **buf, size_t *cap, size_t n)
{
    char *b;
    if (*buf != NULL && *cap >= n) return 0;
    b = realloc(*buf, n);
    if (b == NULL) return -1;
    *buf = b;
    *cap = n;
    return 0;
}

/* the reference route's text and tail into *buf */
static slong flint_into(char **buf, size_t *cap, const fmpz_mpoly_t p, const char **vars,
                        const fmpz_mpoly_ctx_t ctx, const char *tail)
{
    char *r = fmpz_mpoly_str_flint(p, vars, ctx);
    size_t n = strlen(r), t = tail != NULL ? strlen(tail) : 0;
    if (buf_fit(buf, cap, n + t + 1) != 0) {
        free(r);
        return -1;
    }
    memcpy(*buf, r, n);
    if (t > 0) memcpy(*buf + n, tail, t);
    (*buf)[n + t] = '\0';
    free(r);
    return (slong) (n + t);
}

/* The string of fmpz_mpoly_get_str_pretty after rs_polyfmt_spaced, written
 * in one pass: FLINT's printer goes through flint_sprintf for every
 * coefficient, name and exponent, which was a sixth of the in-process Park
 * pipeline (issue 17).  Same text: terms in p's order, " + "/" - " between
 * them, a leading "-", coefficients +-1 left out (a constant term of +-1
 * printed as 1), "*" between factors, "NAME^E" for E > 1.
 * tests/unit/util/test_polyfmt.c compares it with FLINT's route. */
slong rs_polyfmt_fmpz_mpoly_into(char **buf, size_t *cap, const fmpz_mpoly_t p, const char **vars,
                                 const fmpz_mpoly_ctx_t ctx, const char *tail)
{
    slong len = p->length, nv = ctx->minfo->nvars, i, j;
    size_t bound = 2, vlen_sum = 0, off = 0, tlen = tail != NULL ? strlen(tail) : 0;
    size_t *vlen;
    ulong *e;
    char *out;

    if (vars == NULL || p->bits > FLINT_BITS)
        return flint_into(buf, cap, p, vars, ctx, tail);
    if (len == 0) {
        if (buf_fit(buf, cap, 2 + tlen) != 0) return -1;
        (*buf)[0] = '0';
        if (tlen > 0) memcpy(*buf + 1, tail, tlen);
        (*buf)[1 + tlen] = '\0';
        return (slong) (1 + tlen);
    }
    vlen = flint_malloc((nv + 1) * sizeof(size_t));
    for (j = 0; j < nv; j++) {
        if (!plain_name(vars[j])) {
            flint_free(vlen);
            return flint_into(buf, cap, p, vars, ctx, tail);
        }
        vlen[j] = strlen(vars[j]);
        vlen_sum += vlen[j] + 2 + 20;   /* "*NAME^" and up to 20 digits */
    }
    for (i = 0; i < len; i++)
        bound += fmpz_sizeinbase(p->coeffs + i, 10) + 2 + 3 + 1 + vlen_sum;
    if (buf_fit(buf, cap, bound + tlen) != 0) {
        flint_free(vlen);
        return -1;
    }
    out = *buf;
    e = flint_malloc((nv + 1) * sizeof(ulong));
    for (i = 0; i < len; i++) {
        const fmpz *c = p->coeffs + i;
        int neg = fmpz_sgn(c) < 0, unit = fmpz_is_pm1(c), first = 1, constant = 1;
        if (i > 0) {
            memcpy(out + off, neg ? " - " : " + ", 3);
            off += 3;
        } else if (neg) {
            out[off++] = '-';
        }
        if (!unit) {
            if (!COEFF_IS_MPZ(*c))
                off += put_ulong(out + off, FLINT_ABS(*c));
            else
                off += put_mpz(out + off, c);   /* the sign is written */
        }
        fmpz_mpoly_get_term_exp_ui(e, p, i, ctx);
        for (j = 0; j < nv; j++) {
            if (e[j] == 0) continue;
            constant = 0;
            if (!first || !unit) out[off++] = '*';
            memcpy(out + off, vars[j], vlen[j]);
            off += vlen[j];
            if (e[j] > 1) {
                out[off++] = '^';
                off += put_ulong(out + off, e[j]);
            }
            first = 0;
        }
        if (constant && unit) out[off++] = '1';
    }
    if (tlen > 0) memcpy(out + off, tail, tlen);
    off += tlen;
    out[off] = '\0';
    flint_free(vlen);
    flint_free(e);
    return (slong) off;
}

char *rs_polyfmt_fmpz_mpoly(const fmpz_mpoly_t p, const char **vars, const fmpz_mpoly_ctx_t ctx)
{
    char *buf = NULL;
    size_t cap = 0;
    if (rs_polyfmt_fmpz_mpoly_into(&buf, &cap, p, vars, ctx, NULL) < 0) {
        free(buf);
        return NULL;
    }
    return buf;
}

char *rs_polyfmt_fmpq_mpoly(const fmpq_mpoly_t p, const char **vars, const fmpq_mpoly_ctx_t ctx)
{
    char *s = fmpq_mpoly_get_str_pretty(p, vars, ctx);
    char *r = rs_polyfmt_spaced(s);
    flint_free(s);
    return r;
}

/* append helper */
typedef struct { char *s; size_t len, cap; } sbuf_t;

static void sb_add(sbuf_t *b, const char *t)
{
    size_t n = strlen(t);
    if (b->len + n + 1 > b->cap) {
        b->cap = 2 * (b->len + n + 1);
        b->s = realloc(b->s, b->cap);
    }
    memcpy(b->s + b->len, t, n + 1);
    b->len += n;
}

/* Single-word exponents: each term moved to c[e] with e*x_var taken off its
 * packed monomial.  Subtracting one monomial from terms that all contain it
 * keeps their order (monomial orders are translation invariant), so each
 * c[e] is canonical without a sort.  fmpz_mpoly_to_univar did the same
 * with an mpoly allocated per term group and a copy out: ~15 % of a
 * `region ... for all` run's instructions (issue 13). */
static void coeffs_split_sp(fmpz_mpoly_struct *c, const fmpz_mpoly_t p, slong var,
                            const fmpz_mpoly_ctx_t ctx)
{
    flint_bitcnt_t bits = p->bits;
    slong N = mpoly_words_per_exp_sp(bits, ctx->minfo), off, shift, i, e, emax = 0;
    ulong mask = (-UWORD(1)) >> (FLINT_BITS - bits);
    ulong *one = flint_malloc(2 * N * sizeof(ulong)), *pe = one + N;
    slong *pos;
    mpoly_gen_offset_shift_sp(&off, &shift, var, bits, ctx->minfo);
    mpoly_gen_monomial_sp(one, var, bits, ctx->minfo);
    for (i = 0; i < p->length; i++) {
        e = (slong) ((p->exps[N * i + off] >> shift) & mask);
        emax = FLINT_MAX(emax, e);
    }
    pos = flint_calloc(emax + 1, sizeof(slong));
    for (i = 0; i < p->length; i++)
        pos[(p->exps[N * i + off] >> shift) & mask]++;
    for (e = 0; e <= emax; e++) {
        if (pos[e] == 0) continue;
        _fmpz_mpoly_set_length(c + e, 0, ctx);
        fmpz_mpoly_fit_length_reset_bits(c + e, pos[e], bits, ctx);
        _fmpz_mpoly_set_length(c + e, pos[e], ctx);
        pos[e] = 0;
    }
    for (i = 0; i < p->length; i++) {
        fmpz_mpoly_struct *d;
        e = (slong) ((p->exps[N * i + off] >> shift) & mask);
        d = c + e;
        mpoly_monomial_mul_ui(pe, one, N, (ulong) e);
        mpoly_monomial_sub(d->exps + N * pos[e], p->exps + N * i, pe, N);
        fmpz_set(d->coeffs + pos[e], p->coeffs + i);
        pos[e]++;
    }
    flint_free(pos);
    flint_free(one);
}

void rs_polyfmt_coeffs(fmpz_mpoly_struct *c, const fmpz_mpoly_t p, slong var, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_univar_t u;
    slong k;
    if (p->bits <= FLINT_BITS) {
        coeffs_split_sp(c, p, var, ctx);
        return;
    }
    fmpz_mpoly_univar_init(u, ctx);
    fmpz_mpoly_to_univar(u, p, var, ctx);
    for (k = 0; k < fmpz_mpoly_univar_length(u, ctx); k++)
        fmpz_mpoly_univar_swap_term_coeff(c + fmpz_mpoly_univar_get_term_exp_si(u, k, ctx), u, k, ctx);
    fmpz_mpoly_univar_clear(u, ctx);
}

char *rs_polyfmt_collected(const fmpz_mpoly_t p, slong var, const char **vars,
                           const fmpz_mpoly_ctx_t ctx)
{
    sbuf_t b = {NULL, 0, 0};
    slong d = fmpz_mpoly_degree_si(p, var, ctx), k;
    fmpz_mpoly_t c;
    fmpz_mpoly_struct *cf;
    int first = 1;
    char pw[64];
    sb_add(&b, "");
    if (fmpz_mpoly_is_zero(p, ctx)) {
        sb_add(&b, "0");
        return b.s;
    }
    cf = flint_malloc((d + 1) * sizeof(fmpz_mpoly_struct));
    for (k = 0; k <= d; k++)
        fmpz_mpoly_init(cf + k, ctx);
    rs_polyfmt_coeffs(cf, p, var, ctx);
    fmpz_mpoly_init(c, ctx);
    for (k = d; k >= 0; k--) {
        char *cs;
        int neg = 0, single;
        /* decimal printing of large symbolic coefficients takes seconds:
         * stop with the budget (sticky: the run reports it, drops the text) */
        if (rs_budget_check(NULL, "printing a polynomial") != RS_OK) break;
        fmpz_mpoly_swap(c, cf + k, ctx);
        if (fmpz_mpoly_is_zero(c, ctx)) continue;
        single = (fmpz_mpoly_length(c, ctx) == 1);
        if (single && fmpz_sgn(c->coeffs + 0) < 0) {
            neg = 1;
            fmpz_mpoly_neg(c, c, ctx);
        }
        sb_add(&b, first ? (neg ? "-" : "") : (neg ? " - " : " + "));
        first = 0;
        if (k > 1) snprintf(pw, sizeof pw, "%s^%ld", vars[var], (long) k);
        else if (k == 1) snprintf(pw, sizeof pw, "%s", vars[var]);
        if (k > 0 && fmpz_mpoly_is_one(c, ctx)) {
            sb_add(&b, pw);
            continue;
        }
        cs = rs_polyfmt_fmpz_mpoly(c, vars, ctx);
        if (!single && k > 0) { sb_add(&b, "("); sb_add(&b, cs); sb_add(&b, ")"); }
        else sb_add(&b, cs);
        free(cs);
        if (k > 0) { sb_add(&b, "*"); sb_add(&b, pw); }
    }
    fmpz_mpoly_clear(c, ctx);
    for (k = 0; k <= d; k++)
        fmpz_mpoly_clear(cf + k, ctx);
    flint_free(cf);
    return b.s;
}

char *rs_polyfmt_fmpz_poly(const fmpz_poly_t p, const char *var)
{
    char *s = fmpz_poly_get_str_pretty(p, var);
    char *r = rs_polyfmt_spaced(s);
    flint_free(s);
    return r;
}
