/* polyfmt.c -- string forms of polynomials. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
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

/* a name the spacing pass leaves alone: non-empty, none of ( ) + - ^ * / or
 * a blank (names are identifiers; this only guards the equivalence) */
static int plain_name(const char *v)
{
    return v != NULL && *v != '\0' && strpbrk(v, "()+-^*/ ") == NULL;
}

/* The string of fmpz_mpoly_get_str_pretty after rs_polyfmt_spaced, written
 * in one pass: FLINT's printer goes through flint_sprintf for every
 * coefficient, name and exponent, which was a sixth of the in-process Park
 * pipeline (issue 17).  Same text: terms in p's order, " + "/" - " between
 * them, a leading "-", coefficients +-1 left out (a constant term of +-1
 * printed as 1), "*" between factors, "NAME^E" for E > 1.
 * tests/unit/util/test_polyfmt.c compares it with FLINT's route. */
char *rs_polyfmt_fmpz_mpoly(const fmpz_mpoly_t p, const char **vars, const fmpz_mpoly_ctx_t ctx)
{
    slong len = p->length, nv = ctx->minfo->nvars, i, j;
    size_t bound = 2, vlen_sum = 0, off = 0;
    size_t *vlen;
    ulong *e;
    char *out;

    if (vars == NULL || p->bits > FLINT_BITS)
        return fmpz_mpoly_str_flint(p, vars, ctx);
    if (len == 0) {
        out = malloc(2);
        if (out != NULL) strcpy(out, "0");
        return out;
    }
    vlen = flint_malloc((nv + 1) * sizeof(size_t));
    for (j = 0; j < nv; j++) {
        if (!plain_name(vars[j])) {
            flint_free(vlen);
            return fmpz_mpoly_str_flint(p, vars, ctx);
        }
        vlen[j] = strlen(vars[j]);
        vlen_sum += vlen[j] + 2 + 20;   /* "*NAME^" and up to 20 digits */
    }
    for (i = 0; i < len; i++)
        bound += fmpz_sizeinbase(p->coeffs + i, 10) + 2 + 3 + 1 + vlen_sum;
    out = malloc(bound);
    e = flint_malloc((nv + 1) * sizeof(ulong));
    if (out == NULL) {
        flint_free(vlen);
        flint_free(e);
        return NULL;
    }
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
            if (!COEFF_IS_MPZ(*c)) {
                off += put_ulong(out + off, FLINT_ABS(*c));
            } else {
                char *d = out + off;
                fmpz_get_str(d, 10, c);
                if (neg) memmove(d, d + 1, strlen(d));   /* the sign is written */
                off += strlen(d);
            }
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
    out[off] = '\0';
    flint_free(vlen);
    flint_free(e);
    return out;
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

void rs_polyfmt_coeffs(fmpz_mpoly_struct *c, const fmpz_mpoly_t p, slong var, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_univar_t u;
    slong k;
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
