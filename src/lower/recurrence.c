/* recurrence.c -- matrix recurrences given term by term in a case file. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "lower/recurrence.h"
#include "lower/lower.h"

static int has_call(const rs_expr_t *e)
{
    if (e == NULL) return 0;
    if (e->kind == RS_EXPR_CALL) return 1;
    if (e->kind == RS_EXPR_NAME && strcmp(e->name, "pi") == 0) return 1;
    return has_call(e->a) || has_call(e->b);
}

int rs_recurrence_is_numeric(const rs_case_t c)
{
    slong t, i;
    for (t = 0; t < c->nrec; t++)
        for (i = 0; i < c->rec[t].rows * c->rec[t].cols; i++)
            if (has_call(c->rec[t].entries[i])) return 1;
    return 0;
}

static int check_terms(const rs_case_t c, rs_error_t err)
{
    slong n = c->rec[0].rows, t, u;
    const rs_loc_t *l0 = &c->rec[0].loc;
    for (t = 0; t < c->nrec; t++) {
        const rs_loc_t *l = &c->rec[t].loc;
        if (c->rec[t].rows != n)
            return rs_error_set_at(err, RS_ERR_INPUT, l->file, l->line, l->col,
                                   "expected %ld x %ld matrices in every recurrence term", (long) n, (long) n);
        for (u = 0; u < t; u++)
            if (c->rec[u].k == c->rec[t].k)
                return rs_error_set_at(err, RS_ERR_INPUT, l->file, l->line, l->col,
                                       "the shift %ld is given twice", (long) c->rec[t].k);
    }
    if (c->neqs > 0 || c->charexpr != NULL || c->nsubs > 0)
        return rs_error_set_at(err, RS_ERR_INPUT, l0->file, l0->line, l0->col,
                               "a case gives either `recurrence` terms or equations/char/subsystems%s", "");
    if (c->nunknowns != 0 && c->nunknowns != n)
        return rs_error_set_at(err, RS_ERR_INPUT, l0->file, l0->line, l0->col,
                               "expected %ld unknowns for the matrix size", (long) n);
    return RS_OK;
}

/* the unknowns z1, ..., zn when the case declares none */
static int gen_unknowns(rs_model_struct *m, slong n, rs_error_t err)
{
    const rs_case_struct *c = m->c;
    const rs_loc_t *l = &c->rec[0].loc;
    slong j;
    for (j = 0; j < n; j++) {
        char b[32];
        slong u;
        snprintf(b, sizeof b, "z%ld", (long) j + 1);
        if ((u = rs_case_param_index(c, b)) >= 0 || (u = rs_case_let_index(c, b)) >= 0) {
            const rs_loc_t *d = rs_case_param_index(c, b) >= 0 ? &c->params[u].loc : &c->lets[u].loc;
            return rs_error_set_at(err, RS_ERR_INPUT, d->file, d->line, d->col,
                                   "'%s' is also the name of an unknown the recurrence terms generate; declare "
                                   "the unknowns with `unknown` or choose another name", b);
        }
        rs_lower_add_unknown(m, b, l);
    }
    return RS_OK;
}

/* row i: sum over the terms A_K and columns j of (A_K[i,j])*z_j[n+K] = 0 */
static void gen_row(rs_model_struct *m, slong n, slong i)
{
    const rs_case_struct *c = m->c;
    const rs_loc_t *l = &c->rec[0].loc;
    rs_expr_t *lhs = NULL;
    slong t, j;
    for (t = 0; t < c->nrec; t++)
        for (j = 0; j < n; j++) {
            const rs_loc_t *tl = &c->rec[t].loc;
            rs_expr_t *z = rs_expr_new_name(m->unknowns[j].name, 1, c->rec[t].k, tl->file, tl->line, tl->col), *term;
            z->shift_signed = 1;   /* printed z1[n+0] */
            term = rs_expr_new_op(RS_EXPR_MUL, rs_expr_paren(rs_expr_copy(c->rec[t].entries[i * n + j])), z, tl->file,
                                  tl->line, tl->col);
            lhs = lhs == NULL ? term : rs_expr_new_op(RS_EXPR_ADD, lhs, term, tl->file, tl->line, tl->col);
        }
    rs_lower_add_eq(m, lhs, rs_expr_new_num(0, l->file, l->line, l->col), l, NULL);
}

int rs_recurrence_lower(rs_model_struct *m, rs_error_t err)
{
    const rs_case_struct *c = m->c;
    slong n, i;
    int r;
    if (c->nrec == 0) return RS_OK;
    n = c->rec[0].rows;
    r = check_terms(c, err);
    if (r != RS_OK) return r;
    if (rs_recurrence_is_numeric(c)) {
        m->kind = RS_MODEL_RECURRENCE;
        m->nterms = c->nrec;
        m->terms = c->rec;
        m->n = n;
        for (i = 0; i < c->nrec; i++) if (c->rec[i].k > m->K) m->K = c->rec[i].k;
        return RS_OK;
    }
    if (c->nunknowns == 0) r = gen_unknowns(m, n, err);
    for (i = 0; i < n && r == RS_OK; i++) gen_row(m, n, i);
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
            return rs_error_set_at(err, RS_ERR_INPUT, rs_expr_file(e, c->path), e->line, e->col,
                                   "expected a parameter (or pi) in a recurrence entry, found '%s'", e->name);
        for (k = 0; k < c->nsets; k++)
            if (strcmp(c->sets[k].name, e->name) == 0) { arb_set_fmpq(out, c->sets[k].value, prec); return RS_OK; }
        return rs_error_set_at(err, RS_ERR_INPUT, rs_expr_file(e, c->path), e->line, e->col,
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
            if (arb_is_zero(b)) r = rs_error_set_at(err, RS_ERR_INPUT, rs_expr_file(e, c->path), e->line, e->col, "division by zero");
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
            else r = rs_error_set_at(err, RS_ERR_INPUT, rs_expr_file(e, c->path), e->line, e->col,
                                     "unknown function '%s' (expected exp, log, sqrt, sin, cos, tan, atan, sinh, "
                                     "cosh, tanh)", f);
            break;
        }
        default:
            r = rs_error_set(err, RS_ERR_INTERNAL, "bad expression node");
        }
        if (r == RS_OK && !arb_is_finite(out))
            r = rs_error_set_at(err, RS_ERR_INPUT, rs_expr_file(e, c->path), e->line, e->col,
                                "the value is not finite (outside the function's domain?)%s", "");
    }
    arb_clear(a);
    arb_clear(b);
    return r;
}

int rs_recurrence_matrices(acb_mat_struct **A, slong *K, const rs_model_t m, slong prec, rs_error_t err)
{
    slong n = m->n, t, i;
    int r = RS_OK;
    if (m->kind != RS_MODEL_RECURRENCE)
        return rs_error_set(err, RS_ERR_INTERNAL, "expected a recurrence model%s", "");
    *A = flint_malloc((m->K + 1) * sizeof(acb_mat_struct));
    for (i = 0; i <= m->K; i++) acb_mat_init(*A + i, n, n);
    for (t = 0; t < m->nterms && r == RS_OK; t++)
        for (i = 0; i < n * n && r == RS_OK; i++)
            r = rs_recurrence_eval(acb_realref(acb_mat_entry(*A + m->terms[t].k, i / n, i % n)), m->terms[t].entries[i],
                                   m->c, prec, err);
    *K = m->K;
    return r;
}
