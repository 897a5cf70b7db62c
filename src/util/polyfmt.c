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

char *rs_polyfmt_fmpz_mpoly(const fmpz_mpoly_t p, const char **vars, const fmpz_mpoly_ctx_t ctx)
{
    char *s = fmpz_mpoly_get_str_pretty(p, vars, ctx);
    char *r = rs_polyfmt_spaced(s);
    flint_free(s);
    return r;
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

char *rs_polyfmt_collected(const fmpz_mpoly_t p, slong var, const char **vars,
                           const fmpz_mpoly_ctx_t ctx)
{
    sbuf_t b = {NULL, 0, 0};
    slong d = fmpz_mpoly_degree_si(p, var, ctx), k;
    fmpz_mpoly_t c;
    int first = 1;
    char pw[64];
    sb_add(&b, "");
    if (fmpz_mpoly_is_zero(p, ctx)) {
        sb_add(&b, "0");
        return b.s;
    }
    fmpz_mpoly_init(c, ctx);
    for (k = d; k >= 0; k--) {
        ulong kk = (ulong) k;
        char *cs;
        int neg = 0, single;
        /* decimal printing of large symbolic coefficients takes seconds:
         * stop with the budget (sticky: the run reports it, drops the text) */
        if (rs_budget_check(NULL, "printing a polynomial") != RS_OK) break;
        fmpz_mpoly_get_coeff_vars_ui(c, p, &var, &kk, 1, ctx);
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
    return b.s;
}

char *rs_polyfmt_fmpz_poly(const fmpz_poly_t p, const char *var)
{
    char *s = fmpz_poly_get_str_pretty(p, var);
    char *r = rs_polyfmt_spaced(s);
    flint_free(s);
    return r;
}
