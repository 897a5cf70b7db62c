/* lower.c -- the lowering entry: syntax tree -> model (model.h).  The
 * user's unknowns and equations are copied into the model, the builders and
 * the recurrence terms add theirs (expression trees); the case is only
 * read, and nothing is re-parsed. */
#include <stdio.h>
#include <string.h>
#include "recstab/model.h"
#include "lower/lower.h"
#include "lower/builder.h"
#include "lower/recurrence.h"
#include "lower/cosim_model.h"

void rs_model_init(rs_model_t m)
{
    memset(m, 0, sizeof(rs_model_struct));
}

void rs_model_clear(rs_model_t m)
{
    slong i;
    for (i = 0; i < m->nunknowns; i++) rs_name_clear(&m->unknowns[i]);
    flint_free(m->unknowns);
    for (i = 0; i < m->neqs; i++) rs_eq_clear(&m->eqs[i]);
    flint_free(m->eqs);
    if (m->cosim != NULL) rs_cosim_model_clear(m->cosim);
    flint_free(m->cosim);
    if (m->qd != NULL) {
        fmpq_poly_clear(m->qd->n0);
        fmpq_poly_clear(m->qd->n1);
        fmpq_poly_clear(m->qd->d0);
        fmpq_poly_clear(m->qd->d1);
        flint_free(m->qd->tableau);
        rs_loc_clear(&m->qd->loc);
        flint_free(m->qd);
    }
    rs_loc_clear(&m->unknown_loc);
    memset(m, 0, sizeof(rs_model_struct));
}

void rs_lower_loc_copy(rs_loc_t *dst, const rs_loc_t *src)
{
    dst->file = src->file != NULL ? rs_strdup(src->file) : NULL;
    dst->line = src->line;
    dst->col = src->col;
}

void rs_lower_add_unknown(rs_model_struct *m, const char *name, const rs_loc_t *loc)
{
    rs_name_t *u;
    m->unknowns = flint_realloc(m->unknowns, (m->nunknowns + 1) * sizeof(rs_name_t));
    u = &m->unknowns[m->nunknowns++];
    u->name = rs_strdup(name);
    rs_lower_loc_copy(&u->loc, loc);
}

void rs_lower_add_eq(rs_model_struct *m, rs_expr_t *lhs, rs_expr_t *rhs, const rs_loc_t *loc, const char *text)
{
    rs_eq_t *q;
    m->eqs = flint_realloc(m->eqs, (m->neqs + 1) * sizeof(rs_eq_t));
    q = &m->eqs[m->neqs++];
    q->lhs = lhs;
    q->rhs = rhs;
    rs_lower_loc_copy(&q->loc, loc);
    q->text = text != NULL ? rs_strdup(text) : rs_expr_eq_str(lhs, rhs);
}

int rs_model_lower(rs_model_t m, const rs_case_t c, rs_error_t err)
{
    slong i;
    int r;
    rs_model_clear(m);
    m->c = c;
    m->nlets = c->nlets;
    m->lets = c->lets;
    for (i = 0; i < c->nunknowns; i++) rs_lower_add_unknown(m, c->unknowns[i].name, &c->unknowns[i].loc);
    m->nuser_unknowns = m->nunknowns;
    if (c->nunknowns > 0) rs_lower_loc_copy(&m->unknown_loc, &c->unknowns[0].loc);
    for (i = 0; i < c->neqs; i++)
        rs_lower_add_eq(m, rs_expr_copy(c->eqs[i].lhs), rs_expr_copy(c->eqs[i].rhs), &c->eqs[i].loc, c->eqs[i].text);
    m->nuser_eqs = m->neqs;
    r = rs_builder_lower(m, err);
    if (r == RS_OK) r = rs_recurrence_lower(m, err);
    if (r == RS_OK && m->kind == RS_MODEL_COSIM) {
        /* an error here is the analyses' that need the forms (radius, map),
         * not the lowering's: --emit equations still works */
        m->cosim = flint_malloc(sizeof(rs_cosim_model_struct));
        if (rs_cosim_model_init(m->cosim, c, m->cosim_err) != RS_OK) {
            rs_cosim_model_clear(m->cosim);
            flint_free(m->cosim);
            m->cosim = NULL;
        }
    }
    return r;
}

const rs_cosim_model_struct *rs_model_cosim(const rs_model_t m, rs_error_t err)
{
    if (m->cosim == NULL) *err = *m->cosim_err;
    return m->cosim;
}

slong rs_model_unknown_index(const rs_model_t m, const char *name)
{
    slong i;
    for (i = 0; i < m->nunknowns; i++)
        if (strcmp(m->unknowns[i].name, name) == 0) return i;
    return -1;
}

typedef struct { char *s; size_t len; } cat_t;

static void cat(cat_t *b, const char *a)
{
    size_t n = strlen(a);
    b->s = flint_realloc(b->s, b->len + n + 1);
    memcpy(b->s + b->len, a, n + 1);
    b->len += n;
}

char *rs_model_emit_equations(const rs_model_t m)
{
    cat_t b = {NULL, 0};
    slong i;
    if (m->kind == RS_MODEL_COSIM)
        return rs_strdup("# exact (analytic) subsystem integration: a numeric matrix recurrence, built at "
                         "set values; only numeric analyses (radius) apply\n");
    if (m->nunknowns == m->nuser_unknowns && m->neqs == m->nuser_eqs) return NULL;
    cat(&b, "");
    if (m->qd != NULL) {
        cat(&b, "# rk ");
        cat(&b, m->qd->tableau);
        {
            /* the field's own d (Gauss and Radau IIA(3) would carry sqrt 3, sqrt 6) */
            char buf[160];
            snprintf(buf, sizeof buf, ": coefficients in Q(sqrt %ld), sqrt(%ld) exact (the analyses reduce by "
                     "sqrt(%ld)^2 = %ld)\n", (long) m->qd->d, (long) m->qd->d, (long) m->qd->d, (long) m->qd->d);
            cat(&b, buf);
        }
    }
    for (i = m->nuser_unknowns; i < m->nunknowns; i++) {
        cat(&b, i == m->nuser_unknowns ? "unknown " : " ");
        cat(&b, m->unknowns[i].name);
    }
    if (m->nunknowns > m->nuser_unknowns) cat(&b, "\n");
    for (i = m->nuser_eqs; i < m->neqs; i++) {
        cat(&b, "eq ");
        cat(&b, m->eqs[i].text);
        cat(&b, "\n");
    }
    return b.s;
}
