/* stmt_recurrence.c -- `recurrence K = [e11, e12; e21, e22]` (syntax only;
 * lowered by src/lower/recurrence.c). */
#include <ctype.h>
#include <string.h>
#include "parse.h"

static int at(rs_stmt_t *x, size_t i, const char *fmt, const char *a)
{
    return _rs_at_err(x, i, RS_ERR_INPUT, fmt, a);
}

/* the rows of the matrix from text[*i] (after '['), row-major into term */
static int matrix_rows(rs_stmt_t *x, size_t *pi, rs_recterm_t *term, slong *nent)
{
    const char *t = x->src.text;
    size_t i = *pi;
    slong ncols = -1, col = 0, cap = 0;
    int r = RS_OK;
    term->rows = 1;
    for (;;) {
        rs_expr_t *e = NULL;
        _rs_skip_ws(t, &i);
        r = rs_expr_parse(&e, &x->src, &i, x->err);
        if (r != RS_OK) break;
        if (*nent + 1 > cap) {
            cap = 2 * cap + 4;
            term->entries = flint_realloc(term->entries, cap * sizeof(rs_expr_t *));
        }
        term->entries[(*nent)++] = e;
        col++;
        _rs_skip_ws(t, &i);
        if (t[i] == ',') { i++; continue; }
        if (t[i] == ';' || t[i] == ']') {
            if (ncols < 0) ncols = col;
            else if (col != ncols) { r = at(x, i, "expected rows of equal length in the matrix%s", ""); break; }
            col = 0;
            if (t[i] == ']') { i++; break; }
            i++;
            term->rows++;
            continue;
        }
        r = at(x, i, "expected ',', ';' or ']' in the matrix, found '%s'", t + i);
        break;
    }
    term->cols = ncols < 0 ? 0 : ncols;
    *pi = i;
    return r;
}

int _rs_st_recurrence(rs_stmt_t *x, size_t i)
{
    const char *t = x->src.text;
    rs_recterm_t term;
    slong k = 0, nent = 0, j;
    size_t p0;
    int r;
    memset(&term, 0, sizeof term);
    _rs_skip_ws(t, &i);
    p0 = i;
    if (!isdigit((unsigned char) t[i])) return at(x, i, "expected the shift K in `recurrence K = [...]`, found '%s'", t + i);
    while (isdigit((unsigned char) t[i])) {
        k = 10 * k + (t[i] - '0');
        i++;
        if (k > 1000) return at(x, p0, "recurrence shift too large (limit 1000)%s", "");
    }
    _rs_skip_ws(t, &i);
    if (t[i] != '=') return at(x, i, "expected '=' after the shift, found '%s'", t + i);
    i++;
    _rs_skip_ws(t, &i);
    if (t[i] != '[') return at(x, i, "expected '[' to start the matrix, found '%s'", t + i);
    i++;
    term.k = k;
    _rs_set_loc(x, &term.loc, p0);
    r = matrix_rows(x, &i, &term, &nent);
    if (r == RS_OK) {
        _rs_skip_ws(t, &i);
        if (t[i] != '\0') r = at(x, i, "expected end of line after the matrix, found '%s'", t + i);
    }
    if (r == RS_OK && (term.rows != term.cols || term.rows * term.cols != nent))
        r = at(x, p0, "expected a square matrix%s", "");
    if (r == RS_OK && term.rows > 256)
        r = at(x, p0, "matrix too large (limit 256 x 256)%s", "");
    if (r != RS_OK) {
        for (j = 0; j < nent; j++) rs_expr_free(term.entries[j]);
        flint_free(term.entries);
        rs_loc_clear(&term.loc);
        return r;
    }
    RS_GROW(x->c->rec, x->c->nrec);
    x->c->rec[x->c->nrec++] = term;
    return RS_OK;
}
