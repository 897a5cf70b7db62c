/* polytext.c -- long polynomials held back from a document and printed only
 * when the report is written (issue 17): no jansson string of each printed
 * polynomial, no text of the polynomials a report never shows. */
#include <stdlib.h>
#include <string.h>
#include "polytext.h"
#include "polyfmt.h"

struct rs_polytext_poly_s {
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p;
    fmpz_mpoly_struct *borrowed;   /* the caller's until rs_polytext_keep, or NULL */
    char **vars;
    char *text;     /* printed, kept while writes are held */
    size_t cap;
    slong len;      /* -1: not printed */
    slong held;     /* writes still to come (rs_polytext_hold) */
    int plain;      /* no name needs a JSON escape, so neither does the text */
};

struct rs_polytext_ph_s {
    json_t *ph;       /* the registry's reference */
    const char *val;  /* its value */
    slong poly;
    char *tail;       /* " tail", or NULL */
};

void rs_polytext_init(rs_polytext_t pt)
{
    memset(pt, 0, sizeof(rs_polytext_struct));
}

static void poly_clear(struct rs_polytext_poly_s *q)
{
    fmpz_mpoly_ctx_struct *ctx = q->ctx;
    slong j;
    for (j = 0; j < ctx->minfo->nvars; j++) free(q->vars[j]);
    free(q->vars);
    free(q->text);
    fmpz_mpoly_clear(q->p, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

void rs_polytext_clear(rs_polytext_t pt)
{
    slong i;
    for (i = 0; i < pt->npoly; i++) poly_clear(pt->poly + i);
    for (i = 0; i < pt->nph; i++) {
        json_decref(pt->ph[i].ph);
        free(pt->ph[i].tail);
    }
    free(pt->poly);
    free(pt->ph);
    free(pt->scratch);
    rs_polytext_init(pt);
}

/* jansson's dump (no JSON_ENSURE_ASCII) writes these bytes verbatim */
static int json_plain(const char *s, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++) {
        unsigned char c = (unsigned char) s[i];
        if (c < 0x20 || c == '"' || c == '\\') return 0;
    }
    return 1;
}

static json_t *ph_new(rs_polytext_t pt, slong poly, const char *tail)
{
    struct rs_polytext_ph_s *e;
    char text[48];
    if (pt->nph == pt->alloc_ph) {
        pt->alloc_ph = 2 * pt->alloc_ph + 8;
        pt->ph = realloc(pt->ph, (size_t) pt->alloc_ph * sizeof(*pt->ph));
    }
    /* \001 first: the JSON dump sets such strings aside (driver.c) */
    snprintf(text, sizeof text, "\001poly %ld\001", (long) pt->nph);
    e = pt->ph + pt->nph;
    e->ph = json_string(text);
    e->val = json_string_value(e->ph);
    e->poly = poly;
    e->tail = NULL;
    if (tail != NULL) {
        e->tail = malloc(strlen(tail) + 2);
        sprintf(e->tail, " %s", tail);
    }
    pt->nph++;
    return json_incref(e->ph);
}

json_t *rs_polytext_defer(rs_polytext_t pt, fmpz_mpoly_t p, const char *const *vars,
                          const fmpz_mpoly_ctx_t ctx, const char *tail, json_t **line)
{
    struct rs_polytext_poly_s *q;
    slong i, j, nv = ctx->minfo->nvars;
    json_t *x;
    for (i = 0; i < pt->npoly && pt->poly[i].borrowed != p; i++) {}
    if (i == pt->npoly) {
        if (pt->npoly == pt->alloc_poly) {
            pt->alloc_poly = 2 * pt->alloc_poly + 8;
            pt->poly = realloc(pt->poly, (size_t) pt->alloc_poly * sizeof(*pt->poly));
        }
        q = pt->poly + pt->npoly;
        /* the same variables and order: p's exponent words are valid here */
        fmpz_mpoly_ctx_init(q->ctx, nv, ctx->minfo->ord);
        fmpz_mpoly_init(q->p, q->ctx);
        q->borrowed = p;
        q->vars = malloc((size_t) (nv + 1) * sizeof(char *));
        q->plain = 1;
        for (j = 0; j < nv; j++) {
            q->vars[j] = strdup(vars[j]);
            q->plain &= json_plain(vars[j], strlen(vars[j]));
        }
        q->text = NULL;
        q->cap = 0;
        q->len = -1;
        q->held = 0;
        pt->npoly++;
    }
    x = ph_new(pt, i, NULL);
    if (line != NULL) *line = tail != NULL ? ph_new(pt, i, tail) : NULL;
    return x;
}

void rs_polytext_keep(rs_polytext_t pt)
{
    slong i;
    for (i = 0; i < pt->npoly; i++) {
        struct rs_polytext_poly_s *q = pt->poly + i;
        if (q->borrowed == NULL) continue;
        fmpz_mpoly_swap(q->p, q->borrowed, q->ctx);
        q->borrowed = NULL;
    }
}

slong rs_polytext_find_value(const rs_polytext_t pt, const char *s)
{
    char *end;
    long k;
    if (pt == NULL || s == NULL || strncmp(s, "\001poly ", 6) != 0) return -1;
    k = strtol(s + 6, &end, 10);
    /* the pointer, not the text: a case's own string "\001poly 0\001" is text */
    return (k >= 0 && k < pt->nph && pt->ph[k].val == s) ? (slong) k : -1;
}

slong rs_polytext_find(const rs_polytext_t pt, const json_t *x)
{
    slong k;
    if (pt == NULL || !json_is_string(x)) return -1;
    k = rs_polytext_find_value(pt, json_string_value(x));
    return (k >= 0 && pt->ph[k].ph == x) ? k : -1;
}

void rs_polytext_hold(rs_polytext_t pt, slong k)
{
    pt->poly[pt->ph[k].poly].held++;
}

int rs_polytext_write(FILE *f, rs_polytext_t pt, slong k, int json)
{
    struct rs_polytext_ph_s *e = pt->ph + k;
    struct rs_polytext_poly_s *q = pt->poly + e->poly;
    const char *tail = e->tail != NULL ? e->tail : "";
    size_t tlen = strlen(tail);
    const fmpz_mpoly_struct *p = q->borrowed != NULL ? q->borrowed : q->p;
    char *text;
    slong n;
    if (q->held > 0 && q->len < 0) q->len = rs_polyfmt_fmpz_mpoly_into(&q->text, &q->cap, p,
                                                                        (const char **) q->vars, q->ctx, NULL);
    if (q->held > 0) {
        n = q->len;
        text = q->text;
    } else {
        n = rs_polyfmt_fmpz_mpoly_into(&pt->scratch, &pt->cap, p, (const char **) q->vars, q->ctx, NULL);
        text = pt->scratch;
    }
    if (n < 0) return -1;
    if (!json) {
        fwrite(text, 1, (size_t) n, f);
        fwrite(tail, 1, tlen, f);
    } else if (q->plain && json_plain(tail, tlen)) {
        /* digits, " + - * ^" and the names: nothing to escape */
        fputc('"', f);
        fwrite(text, 1, (size_t) n, f);
        fwrite(tail, 1, tlen, f);
        fputc('"', f);
    } else {
        /* names that need escapes (never recstab's identifiers): jansson's own dump */
        char *whole = malloc((size_t) n + tlen + 1), *d;
        json_t *str;
        memcpy(whole, text, (size_t) n);
        memcpy(whole + n, tail, tlen + 1);
        str = json_stringn(whole, (size_t) n + tlen);
        d = str != NULL ? json_dumps(str, JSON_ENCODE_ANY) : NULL;
        fputs(d != NULL ? d : "null", f);
        free(d);
        json_decref(str);
        free(whole);
    }
    if (q->held > 0 && --q->held == 0) {
        free(q->text);
        q->text = NULL;
        q->cap = 0;
        q->len = -1;
    }
    return 0;
}
