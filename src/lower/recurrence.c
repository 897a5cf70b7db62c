/* recurrence.c -- matrix recurrences given term by term in a case file. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include "lower/recurrence.h"

static int at(rs_error_t err, const rs_src_t *src, size_t i, const char *fmt, const char *a)
{
    int line, col;
    rs_src_pos(src, i, &line, &col);
    return rs_error_set_at(err, RS_ERR_INPUT, src->file, line, col, fmt, a);
}

int rs_recurrence_statement(rs_case_t c, const rs_src_t *src, size_t i, rs_error_t err)
{
    const char *t = src->text;
    rs_recterm_t term;
    slong k = 0, ncols = -1, col = 0, cap = 0, nent = 0;
    size_t p0;
    int r = RS_OK;
    memset(&term, 0, sizeof term);
    while (t[i] == ' ' || t[i] == '\t') i++;
    p0 = i;
    if (!isdigit((unsigned char) t[i])) return at(err, src, i, "expected the shift K in `recurrence K = [...]`, found '%s'", t + i);
    while (isdigit((unsigned char) t[i])) {
        k = 10 * k + (t[i] - '0');
        i++;
        if (k > 1000) return at(err, src, p0, "recurrence shift too large (limit 1000)%s", "");
    }
    while (t[i] == ' ' || t[i] == '\t') i++;
    if (t[i] != '=') return at(err, src, i, "expected '=' after the shift, found '%s'", t + i);
    i++;
    while (t[i] == ' ' || t[i] == '\t') i++;
    if (t[i] != '[') return at(err, src, i, "expected '[' to start the matrix, found '%s'", t + i);
    i++;
    term.k = k;
    term.rows = 1;
    {
        int line, cl;
        rs_src_pos(src, p0, &line, &cl);
        term.loc.file = rs_strndup(src->file, strlen(src->file));
        term.loc.line = line;
        term.loc.col = cl;
    }
    for (;;) {
        rs_expr_t *e = NULL;
        size_t s0, e1;
        while (t[i] == ' ' || t[i] == '\t') i++;
        s0 = i;
        r = rs_expr_parse(&e, src, &i, err);
        if (r != RS_OK) break;
        /* entries arrive in row-major order: append */
        if (nent + 1 > cap) {
            cap = 2 * cap + 4;
            term.entries = flint_realloc(term.entries, cap * sizeof(rs_expr_t *));
            term.texts = flint_realloc(term.texts, cap * sizeof(char *));
        }
        e1 = i;
        while (e1 > s0 && (t[e1 - 1] == ' ' || t[e1 - 1] == '\t')) e1--;
        term.entries[nent] = e;
        term.texts[nent] = rs_strndup(t + s0, e1 - s0);
        nent++;
        col++;
        while (t[i] == ' ' || t[i] == '\t') i++;
        if (t[i] == ',') { i++; continue; }
        if (t[i] == ';' || t[i] == ']') {
            if (ncols < 0) ncols = col;
            else if (col != ncols) { r = at(err, src, i, "expected rows of equal length in the matrix%s", ""); break; }
            col = 0;
            if (t[i] == ']') { i++; break; }
            i++;
            term.rows++;
            continue;
        }
        r = at(err, src, i, "expected ',', ';' or ']' in the matrix, found '%s'", t + i);
        break;
    }
    if (r == RS_OK) {
        while (t[i] == ' ' || t[i] == '\t') i++;
        if (t[i] != '\0') r = at(err, src, i, "expected end of line after the matrix, found '%s'", t + i);
    }
    term.cols = ncols < 0 ? 0 : ncols;
    if (r == RS_OK && (term.rows != term.cols || term.rows * term.cols != nent))
        r = at(err, src, p0, "expected a square matrix%s", "");
    if (r == RS_OK && term.rows > 256)
        r = at(err, src, p0, "matrix too large (limit 256 x 256)%s", "");
    if (r != RS_OK) {
        slong j;
        for (j = 0; j < nent; j++) { rs_expr_free(term.entries[j]); flint_free(term.texts[j]); }
        flint_free(term.entries);
        flint_free(term.texts);
        flint_free(term.loc.file);
        return r;
    }
    c->rec = flint_realloc(c->rec, (c->nrec + 1) * sizeof(rs_recterm_t));
    c->rec[c->nrec++] = term;
    return RS_OK;
}

static int has_call(const rs_expr_t *e)
{
    if (e == NULL) return 0;
    if (e->kind == RS_EXPR_CALL) return 1;
    if (e->kind == RS_EXPR_NAME && strcmp(e->name, "pi") == 0) return 1;
    return has_call(e->a) || has_call(e->b);
}

int rs_recurrence_expand(rs_case_t c, rs_error_t err)
{
    slong n, i, j, t, u;
    int numeric = 0;
    char *buf = NULL;
    size_t len = 0;
    FILE *f;
    int r;
    if (c->nrec == 0) return RS_OK;
    n = c->rec[0].rows;
    for (t = 0; t < c->nrec; t++) {
        if (c->rec[t].rows != n)
            return rs_error_set_at(err, RS_ERR_INPUT, c->rec[t].loc.file, c->rec[t].loc.line, c->rec[t].loc.col,
                                   "expected %ld x %ld matrices in every recurrence term", (long) n, (long) n);
        for (u = 0; u < t; u++)
            if (c->rec[u].k == c->rec[t].k)
                return rs_error_set_at(err, RS_ERR_INPUT, c->rec[t].loc.file, c->rec[t].loc.line, c->rec[t].loc.col,
                                       "the shift %ld is given twice", (long) c->rec[t].k);
        for (i = 0; i < n * n; i++) if (has_call(c->rec[t].entries[i])) numeric = 1;
    }
    if (c->neqs > 0 || c->charexpr != NULL || c->nsubs > 0)
        return rs_error_set_at(err, RS_ERR_INPUT, c->rec[0].loc.file, c->rec[0].loc.line, c->rec[0].loc.col,
                               "a case gives either `recurrence` terms or equations/char/subsystems%s", "");
    if (c->nunknowns != 0 && c->nunknowns != n)
        return rs_error_set_at(err, RS_ERR_INPUT, c->rec[0].loc.file, c->rec[0].loc.line, c->rec[0].loc.col,
                               "expected %ld unknowns for the matrix size", (long) n);
    if (numeric) {
        c->numeric_recurrence = 1;
        return RS_OK;
    }
    f = open_memstream(&buf, &len);
    if (c->nunknowns == 0) {
        fprintf(f, "unknown");
        for (j = 0; j < n; j++) fprintf(f, " z%ld", (long) j + 1);
        fprintf(f, "\n");
    }
    for (i = 0; i < n; i++) {
        int first = 1;
        fprintf(f, "eq ");
        for (t = 0; t < c->nrec; t++)
            for (j = 0; j < n; j++) {
                const char *name = c->nunknowns ? c->unknowns[j].name : NULL;
                fprintf(f, "%s(%s)*", first ? "" : " + ", c->rec[t].texts[i * n + j]);
                if (name) fprintf(f, "%s[n+%ld]", name, (long) c->rec[t].k);
                else fprintf(f, "z%ld[n+%ld]", (long) j + 1, (long) c->rec[t].k);
                first = 0;
            }
        fprintf(f, " = 0\n");
    }
    fclose(f);
    {
        char label[600];
        snprintf(label, sizeof label, "%s (equations of the recurrence terms)", c->path);
        r = rs_case_parse_append(c, label, buf, err);
    }
    flint_free(c->emitted);
    c->emitted = flint_malloc(len + 1);
    memcpy(c->emitted, buf, len + 1);
    free(buf);
    return r;
}

int rs_recurrence_eval(arb_t out, const rs_expr_t *e, const rs_case_t c, slong prec, rs_error_t err)
{
    arb_t a, b;
    int r = RS_OK;
    switch (e->kind) {
    case RS_EXPR_NUM:
        arb_set_fmpq(out, e->num, prec);
        return RS_OK;
    case RS_EXPR_NAME: {
        slong k;
        if (strcmp(e->name, "pi") == 0) { arb_const_pi(out, prec); return RS_OK; }
        k = rs_case_param_index(c, e->name);
        if (k < 0 || e->shifted)
            return rs_error_set_at(err, RS_ERR_INPUT, c->path, e->line, e->col,
                                   "expected a parameter (or pi) in a recurrence entry, found '%s'", e->name);
        for (k = 0; k < c->nsets; k++)
            if (strcmp(c->sets[k].name, e->name) == 0) { arb_set_fmpq(out, c->sets[k].value, prec); return RS_OK; }
        return rs_error_set_at(err, RS_ERR_INPUT, c->path, e->line, e->col,
                               "a numeric recurrence needs every parameter set; '%s' is not", e->name);
    }
    default:
        break;
    }
    arb_init(a);
    arb_init(b);
    r = rs_recurrence_eval(a, e->a, c, prec, err);
    if (r == RS_OK && e->b != NULL) r = rs_recurrence_eval(b, e->b, c, prec, err);
    if (r == RS_OK) {
        switch (e->kind) {
        case RS_EXPR_ADD: arb_add(out, a, b, prec); break;
        case RS_EXPR_SUB: arb_sub(out, a, b, prec); break;
        case RS_EXPR_MUL: arb_mul(out, a, b, prec); break;
        case RS_EXPR_DIV:
            if (arb_is_zero(b)) r = rs_error_set_at(err, RS_ERR_INPUT, c->path, e->line, e->col, "division by zero");
            else arb_div(out, a, b, prec);
            break;
        case RS_EXPR_POW: arb_pow(out, a, b, prec); break;
        case RS_EXPR_NEG: arb_neg(out, a); break;
        case RS_EXPR_CALL: {
            const char *f = e->name;
            if (strcmp(f, "exp") == 0) arb_exp(out, a, prec);
            else if (strcmp(f, "log") == 0) arb_log(out, a, prec);
            else if (strcmp(f, "sqrt") == 0) arb_sqrt(out, a, prec);
            else if (strcmp(f, "sin") == 0) arb_sin(out, a, prec);
            else if (strcmp(f, "cos") == 0) arb_cos(out, a, prec);
            else if (strcmp(f, "tan") == 0) arb_tan(out, a, prec);
            else if (strcmp(f, "atan") == 0) arb_atan(out, a, prec);
            else if (strcmp(f, "sinh") == 0) arb_sinh(out, a, prec);
            else if (strcmp(f, "cosh") == 0) arb_cosh(out, a, prec);
            else if (strcmp(f, "tanh") == 0) arb_tanh(out, a, prec);
            else r = rs_error_set_at(err, RS_ERR_INPUT, c->path, e->line, e->col,
                                     "unknown function '%s' (expected exp, log, sqrt, sin, cos, tan, atan, sinh, "
                                     "cosh, tanh)", f);
            break;
        }
        default:
            r = rs_error_set(err, RS_ERR_INTERNAL, "bad expression node");
        }
        if (r == RS_OK && !arb_is_finite(out))
            r = rs_error_set_at(err, RS_ERR_INPUT, c->path, e->line, e->col,
                                "the value is not finite (outside the function's domain?)%s", "");
    }
    arb_clear(a);
    arb_clear(b);
    return r;
}

int rs_recurrence_matrices(acb_mat_struct **A, slong *K, const rs_case_t c, slong prec, rs_error_t err)
{
    slong n = c->rec[0].rows, t, i, kmax = 0;
    int r = RS_OK;
    for (t = 0; t < c->nrec; t++) if (c->rec[t].k > kmax) kmax = c->rec[t].k;
    *A = flint_malloc((kmax + 1) * sizeof(acb_mat_struct));
    for (i = 0; i <= kmax; i++) acb_mat_init(*A + i, n, n);
    for (t = 0; t < c->nrec && r == RS_OK; t++)
        for (i = 0; i < n * n && r == RS_OK; i++)
            r = rs_recurrence_eval(acb_realref(acb_mat_entry(*A + c->rec[t].k, i / n, i % n)), c->rec[t].entries[i], c,
                                   prec, err);
    *K = kmax;
    return r;
}
