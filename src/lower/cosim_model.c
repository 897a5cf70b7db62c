/* cosim_model.c -- the co-simulation model (lower/cosim_model.h): the
 * linear forms of exactly integrated subsystems, built once per run from the
 * syntax tree (nothing re-parsed), and the substitution of numbers at a
 * point. */
#include <string.h>
#include "lower/cosim_model.h"

/* appends NAME as a parameter of the evaluation case (declared at loc) */
static int eval_param(rs_case_struct *tc, const char *name, const rs_loc_t *loc, rs_error_t err)
{
    rs_name_t *n;
    if (rs_case_param_index(tc, name) >= 0)
        return rs_error_set_at(err, RS_ERR_INPUT, loc->file, loc->line, loc->col, "'%s' is already declared", name);
    tc->params = flint_realloc(tc->params, (tc->nparams + 1) * sizeof(rs_name_t));
    n = &tc->params[tc->nparams++];
    memset(n, 0, sizeof *n);
    n->name = rs_strdup(name);
    n->loc.file = rs_strdup(loc->file);
    n->loc.line = loc->line;
    n->loc.col = loc->col;
    return RS_OK;
}

/* The evaluation case, built from the trees (nothing re-parsed): its
 * parameters are the parameters, the states and the forces; `char lambda`;
 * the case's unshifted lets (e.g. c1 = lr1^2 + li1^2 for maps over eigenvalues). */
static int eval_case(rs_case_struct *tc, const rs_case_struct *c, rs_error_t err)
{
    slong i, a, j;
    int r = RS_OK;
    tc->path = rs_strdup(c->path);
    for (i = 0; i < c->nparams && r == RS_OK; i++) r = eval_param(tc, c->params[i].name, &c->params[i].loc, err);
    for (a = 0; a < 2 && r == RS_OK; a++)
        for (j = 0; j < c->subs[a].nstates && r == RS_OK; j++)
            r = eval_param(tc, c->subs[a].states[j].name, &c->subs[a].states[j].loc, err);
    for (i = 0; i < c->nforces && r == RS_OK; i++) r = eval_param(tc, c->forces[i].name, &c->forces[i].loc, err);
    for (i = 0; i < c->nlets && r == RS_OK; i++) {
        rs_let_t *l;
        if (c->lets[i].shifted) continue;
        tc->lets = flint_realloc(tc->lets, (tc->nlets + 1) * sizeof(rs_let_t));
        l = &tc->lets[tc->nlets++];
        memset(l, 0, sizeof *l);
        l->name = rs_strdup(c->lets[i].name);
        l->e = rs_expr_copy(c->lets[i].e);
        l->text = rs_strdup(c->lets[i].text);
        l->loc.file = rs_strdup(c->lets[i].loc.file);
        l->loc.line = c->lets[i].loc.line;
        l->loc.col = c->lets[i].loc.col;
    }
    if (r == RS_OK) {
        tc->charexpr = rs_expr_new_name("lambda", 0, 0, NULL, 0, 0);
        tc->charloc.file = rs_strdup(c->path);
    }
    return r;
}

void rs_cosim_model_clear(rs_cosim_model_struct *F)
{
    slong i;
    for (i = 0; i < F->nforms; i++) {
        fmpq_mpoly_clear(F->num + i, F->ts->ctx);
        fmpq_mpoly_clear(F->den + i, F->ts->ctx);
    }
    flint_free(F->num);
    flint_free(F->den);
    flint_free(F->second);
    flint_free(F->loc);
    rs_scheme_clear(F->ts);
    rs_model_clear(F->tm);
    rs_case_clear(F->tc);
}

/* state row j of subsystem s: its equation (or *second for X of X'' = F) */
static int row_equation(const rs_deq_t **out, int *second, const rs_subsystem_t *s, slong j, rs_error_t err)
{
    const rs_deq_t *d = NULL;
    slong k;
    *second = 0;
    for (k = 0; k < s->ndeqs; k++)
        if (strcmp(s->deqs[k].state, s->states[j].name) == 0 && s->deqs[k].order == 1) d = &s->deqs[k];
    /* X'' = f: X' is the next state; that state's derivative is f */
    for (k = 0; k < s->ndeqs && d == NULL; k++)
        if (s->deqs[k].order == 2 && j > 0 && strcmp(s->deqs[k].state, s->states[j - 1].name) == 0) d = &s->deqs[k];
    for (k = 0; k < s->ndeqs; k++)
        if (s->deqs[k].order == 2 && strcmp(s->deqs[k].state, s->states[j].name) == 0) *second = 1;
    *out = d;
    if (*second) {
        if (j + 1 >= s->nstates)
            return rs_error_set_at(err, RS_ERR_INPUT, s->loc.file, s->loc.line, s->loc.col,
                                   "declare the velocity state after %s", s->states[j].name);
        return RS_OK;
    }
    if (d == NULL)
        return rs_error_set_at(err, RS_ERR_INPUT, s->loc.file, s->loc.line, s->loc.col,
                               "expected an equation %s' = ...", s->states[j].name);
    return RS_OK;
}

static int form_add(rs_cosim_model_struct *F, const rs_expr_t *e, const rs_loc_t *loc, rs_error_t err)
{
    slong i = F->nforms++;
    fmpq_mpoly_init(F->num + i, F->ts->ctx);
    fmpq_mpoly_init(F->den + i, F->ts->ctx);
    F->loc[i] = loc;
    if (e == NULL) { fmpq_mpoly_one(F->den + i, F->ts->ctx); return RS_OK; }
    return rs_scheme_eval_poly(F->num + i, F->den + i, F->ts, F->tc, e, 0, err);
}

int rs_cosim_model_init(rs_cosim_model_struct *F, const rs_case_struct *c, rs_error_t err)
{
    slong a, j, row = 0, i;
    int r;
    memset(F, 0, sizeof *F);
    rs_case_init(F->tc);
    rs_model_init(F->tm);
    rs_scheme_init(F->ts);
    if (c->nsubs != 2)
        return rs_error_set_at(err, RS_ERR_INPUT, c->path, 0, 0,
                               "exact integration with co-simulation coupling needs two subsystems (found %ld)",
                               (long) c->nsubs);
    r = eval_case(F->tc, c, err);
    if (r == RS_OK) r = rs_model_lower(F->tm, F->tc, err);
    if (r == RS_OK) r = rs_scheme_build(F->ts, F->tm, err);
    if (r != RS_OK) return r;
    F->nstate[0] = c->subs[0].nstates;
    F->nstate[1] = c->subs[1].nstates;
    F->n = F->nstate[0] + F->nstate[1];
    F->nf = c->nforces;
    F->num = flint_malloc((F->n + 2 + F->nf) * sizeof(fmpq_mpoly_struct));
    F->den = flint_malloc((F->n + 2 + F->nf) * sizeof(fmpq_mpoly_struct));
    F->loc = flint_malloc((F->n + 2 + F->nf) * sizeof(rs_loc_t *));
    F->second = flint_calloc(F->n, sizeof(int));
    for (a = 0; a < 2 && r == RS_OK; a++)
        for (j = 0; j < c->subs[a].nstates && r == RS_OK; j++, row++) {
            const rs_deq_t *d;
            r = row_equation(&d, &F->second[row], &c->subs[a], j, err);
            if (r == RS_OK) r = form_add(F, F->second[row] ? NULL : d->rhs, F->second[row] ? &c->subs[a].loc : &d->loc, err);
        }
    for (a = 0; a < 2 && r == RS_OK; a++) r = form_add(F, c->subs[a].step, &c->subs[a].intloc, err);
    for (i = 0; i < F->nf && r == RS_OK; i++) r = form_add(F, c->forces[i].e, &c->forces[i].loc, err);
    return r;
}

/* form i at the values: out = num/den with every parameter substituted */
int rs_cosim_model_form_at(fmpq_mpoly_t out, const rs_cosim_model_struct *F, slong i, const rs_case_struct *c,
                           const rs_cosim_vals_t *vals,
                   rs_error_t err)
{
    const rs_scheme_struct *ts = F->ts;
    const rs_loc_t *loc = F->loc[i];
    fmpq_mpoly_t den;
    slong k;
    int r = RS_OK;
    fmpq_mpoly_init(den, ts->ctx);
    fmpq_mpoly_set(out, F->num + i, ts->ctx);
    fmpq_mpoly_set(den, F->den + i, ts->ctx);
    for (k = 0; k < vals->n; k++) {
        slong v = rs_case_param_index(F->tc, vals->v[k].name);
        fmpq_mpoly_evaluate_one_fmpq(out, out, v, vals->v[k].value, ts->ctx);
        fmpq_mpoly_evaluate_one_fmpq(den, den, v, vals->v[k].value, ts->ctx);
    }
    for (k = 0; k < c->nparams; k++)
        if (fmpq_mpoly_degree_si(out, k, ts->ctx) > 0 || fmpq_mpoly_degree_si(den, k, ts->ctx) > 0)
            r = rs_error_set_at(err, RS_ERR_INPUT, loc->file, loc->line, loc->col,
                                "exact integration is numeric: set every parameter (still symbolic: %s)",
                                c->params[k].name);
    if (r == RS_OK) {
        fmpq_t d;
        fmpq_init(d);
        fmpq_mpoly_get_fmpq(d, den, ts->ctx);
        if (fmpq_is_zero(d))
            r = rs_error_set_at(err, RS_ERR_INPUT, loc->file, loc->line, loc->col, "division by zero%s", "");
        else
            fmpq_mpoly_scalar_div_fmpq(out, out, d, ts->ctx);
        fmpq_clear(d);
    }
    fmpq_mpoly_clear(den, ts->ctx);
    return r;
}


/* the case's set values, overridden by (names, values) */
void rs_cosim_vals_make(rs_cosim_vals_t *vals, const rs_case_struct *c, const char *const *names, const fmpq *values,
                        slong n)
{
    slong i, k;
    vals->v = flint_malloc((c->nsets + n + 1) * sizeof(rs_cosim_val_t));
    vals->n = 0;
    for (i = 0; i < c->nsets; i++) {
        int over = 0;
        for (k = 0; k < n; k++) if (strcmp(names[k], c->sets[i].name) == 0) over = 1;
        if (over) continue;
        vals->v[vals->n].name = c->sets[i].name;
        vals->v[vals->n].value = c->sets[i].value;
        vals->n++;
    }
    for (k = 0; k < n; k++) {
        vals->v[vals->n].name = names[k];
        vals->v[vals->n].value = values + k;
        vals->n++;
    }
}

