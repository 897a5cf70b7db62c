/* case.c -- the case structure: init, clear (one per sub-structure),
 * look-ups, and the command line's additions (--set, --analyse). */
#include <stdio.h>
#include <string.h>
#include <fmpq_vec.h>
#include "parse.h"

void rs_case_init(rs_case_t c)
{
    memset(c, 0, sizeof(rs_case_struct));
    c->extrapolate = -1;
}

void rs_loc_clear(rs_loc_t *l)
{
    flint_free(l->file);
    l->file = NULL;
}

void rs_name_clear(rs_name_t *n)
{
    flint_free(n->name);
    rs_loc_clear(&n->loc);
    memset(n, 0, sizeof *n);
}

void rs_let_clear(rs_let_t *l)
{
    flint_free(l->name);
    rs_expr_free(l->e);
    rs_loc_clear(&l->loc);
    flint_free(l->text);
    memset(l, 0, sizeof *l);
}

void rs_eq_clear(rs_eq_t *q)
{
    rs_expr_free(q->lhs);
    rs_expr_free(q->rhs);
    rs_loc_clear(&q->loc);
    flint_free(q->text);
    memset(q, 0, sizeof *q);
}

void rs_set_clear(rs_set_t *s)
{
    flint_free(s->name);
    fmpq_clear(s->value);
    rs_loc_clear(&s->loc);
    memset(s, 0, sizeof *s);
}

void rs_cset_clear(rs_cset_t *s)
{
    flint_free(s->name);
    fmpq_clear(s->re);
    fmpq_clear(s->im);
    rs_loc_clear(&s->loc);
    memset(s, 0, sizeof *s);
}

void rs_request_clear(rs_request_t *q)
{
    flint_free(q->text);
    rs_loc_clear(&q->loc);
    memset(q, 0, sizeof *q);
}

void rs_recterm_clear(rs_recterm_t *t)
{
    slong k;
    for (k = 0; k < t->rows * t->cols; k++)
        rs_expr_free(t->entries[k]);
    flint_free(t->entries);
    rs_loc_clear(&t->loc);
    memset(t, 0, sizeof *t);
}

void rs_deq_clear(rs_deq_t *d)
{
    flint_free(d->state);
    rs_expr_free(d->rhs);
    rs_loc_clear(&d->loc);
    memset(d, 0, sizeof *d);
}

void rs_force_clear(rs_force_t *f)
{
    flint_free(f->name);
    rs_expr_free(f->e);
    rs_loc_clear(&f->loc);
    memset(f, 0, sizeof *f);
}

void rs_subsystem_clear(rs_subsystem_t *s)
{
    slong k;
    flint_free(s->name);
    rs_loc_clear(&s->loc);
    for (k = 0; k < s->nstates; k++) rs_name_clear(&s->states[k]);
    flint_free(s->states);
    for (k = 0; k < s->ndeqs; k++) rs_deq_clear(&s->deqs[k]);
    flint_free(s->deqs);
    flint_free(s->method);
    rs_expr_free(s->arg1);
    rs_expr_free(s->arg2);
    rs_expr_free(s->step);
    rs_loc_clear(&s->intloc);
    flint_free(s->tableau);
    if (s->tab) _fmpq_vec_clear(s->tab, s->ntab);
    memset(s, 0, sizeof *s);
}

void rs_case_clear_requests(rs_case_t c)
{
    slong i;
    for (i = 0; i < c->nrequests; i++) rs_request_clear(&c->requests[i]);
    flint_free(c->requests);
    c->requests = NULL;
    c->nrequests = 0;
}

/* clears arr[0..n) with clear, frees arr */
#define CLEAR_ALL(arr, n, clear) do { slong k_; for (k_ = 0; k_ < (n); k_++) clear(&(arr)[k_]); \
                                      flint_free(arr); } while (0)

void rs_case_clear(rs_case_t c)
{
    slong i;
    flint_free(c->path);
    flint_free(c->title);
    for (i = 0; i < c->nlabels; i++) { flint_free(c->label_names[i]); flint_free(c->label_texts[i]); }
    flint_free(c->label_names);
    flint_free(c->label_texts);
    CLEAR_ALL(c->params, c->nparams, rs_name_clear);
    CLEAR_ALL(c->unknowns, c->nunknowns, rs_name_clear);
    CLEAR_ALL(c->assume, c->nassume, rs_cond_clear);
    CLEAR_ALL(c->lets, c->nlets, rs_let_clear);
    CLEAR_ALL(c->eqs, c->neqs, rs_eq_clear);
    rs_expr_free(c->charexpr);
    rs_loc_clear(&c->charloc);
    CLEAR_ALL(c->sets, c->nsets, rs_set_clear);
    CLEAR_ALL(c->csets, c->ncsets, rs_cset_clear);
    rs_case_clear_requests(c);
    CLEAR_ALL(c->subs, c->nsubs, rs_subsystem_clear);
    flint_free(c->couple);
    flint_free(c->couple_first);
    flint_free(c->couple_second);
    for (i = 0; i < c->ncouple_seq; i++) flint_free(c->couple_seq[i]);
    flint_free(c->couple_seq);
    if (c->couple_alpha != NULL) { fmpq_clear(c->couple_alpha); flint_free(c->couple_alpha); }
    rs_loc_clear(&c->couple_loc);
    CLEAR_ALL(c->forces, c->nforces, rs_force_clear);
    CLEAR_ALL(c->rec, c->nrec, rs_recterm_clear);
    /* last: the trees above point at these names */
    for (i = 0; i < c->nfiles; i++) flint_free(c->files[i]);
    flint_free(c->files);
    memset(c, 0, sizeof(rs_case_struct));
}

slong rs_case_param_index(const rs_case_t c, const char *name)
{
    slong i;
    for (i = 0; i < c->nparams; i++)
        if (strcmp(c->params[i].name, name) == 0) return i;
    return -1;
}

slong rs_case_unknown_index(const rs_case_t c, const char *name)
{
    slong i;
    for (i = 0; i < c->nunknowns; i++)
        if (strcmp(c->unknowns[i].name, name) == 0) return i;
    return -1;
}

slong rs_case_let_index(const rs_case_t c, const char *name)
{
    slong i;
    for (i = 0; i < c->nlets; i++)
        if (strcmp(c->lets[i].name, name) == 0) return i;
    return -1;
}

int rs_name_is_reserved(const char *name)
{
    return rs_name_reserved_why(name) != NULL;
}

/* i is reserved too: a declared i silently changed what i means in a char,
 * expect or set line (the imaginary unit or the name), so it is refused */
const char *rs_name_reserved_why(const char *name)
{
    if (strcmp(name, "lambda") == 0 || strcmp(name, "z") == 0 || strcmp(name, "n") == 0)
        return "lambda, z and n have fixed meanings";
    if (strcmp(name, "i") == 0)
        return "i is the imaginary unit";
    return NULL;
}

void rs_case_add_request(rs_case_t c, const char *text, const char *file, int line, int col)
{
    RS_GROW(c->requests, c->nrequests);
    c->requests[c->nrequests].text = rs_strdup(text);
    c->requests[c->nrequests].loc.file = rs_strdup(file);
    c->requests[c->nrequests].loc.line = line;
    c->requests[c->nrequests].loc.col = col;
    c->nrequests++;
}

/* a value replaces the earlier one of the name, real or complex */
static void drop_set(rs_case_struct *c, const char *name, int complex)
{
    slong k;
    if (complex) {
        for (k = 0; k < c->nsets; k++)
            if (strcmp(c->sets[k].name, name) == 0) {
                rs_set_clear(c->sets + k);
                c->sets[k] = c->sets[--c->nsets];
                return;
            }
    } else {
        for (k = 0; k < c->ncsets; k++)
            if (strcmp(c->csets[k].name, name) == 0) {
                rs_cset_clear(c->csets + k);
                c->csets[k] = c->csets[--c->ncsets];
                return;
            }
    }
}

void _rs_case_set_one(rs_case_struct *c, const char *name, const fmpq_t v, const char *file, int line, int col)
{
    slong k;
    drop_set(c, name, 0);
    for (k = 0; k < c->nsets; k++)
        if (strcmp(c->sets[k].name, name) == 0) {
            fmpq_set(c->sets[k].value, v);
            return;
        }
    RS_GROW(c->sets, c->nsets);
    c->sets[c->nsets].name = rs_strdup(name);
    fmpq_init(c->sets[c->nsets].value);
    fmpq_set(c->sets[c->nsets].value, v);
    c->sets[c->nsets].loc.file = rs_strdup(file);
    c->sets[c->nsets].loc.line = line;
    c->sets[c->nsets].loc.col = col;
    c->nsets++;
}

void _rs_case_set_complex(rs_case_struct *c, const char *name, const fmpq_t re, const fmpq_t im,
                          const char *file, int line, int col)
{
    slong k;
    rs_cset_t *x;
    if (fmpq_is_zero(im)) { _rs_case_set_one(c, name, re, file, line, col); return; }
    drop_set(c, name, 1);
    for (k = 0; k < c->ncsets; k++)
        if (strcmp(c->csets[k].name, name) == 0) break;
    if (k == c->ncsets) {
        RS_GROW(c->csets, c->ncsets);
        x = c->csets + c->ncsets++;
        x->name = rs_strdup(name);
        fmpq_init(x->re);
        fmpq_init(x->im);
    } else {
        x = c->csets + k;
        rs_loc_clear(&x->loc);
    }
    fmpq_set(x->re, re);
    fmpq_set(x->im, im);
    x->loc.file = rs_strdup(file);
    x->loc.line = line;
    x->loc.col = col;
}

int rs_case_set_value(rs_case_t c, const char *assignment, rs_error_t err)
{
    const char *eq = strchr(assignment, '=');
    char *name;
    size_t n;
    fmpq_t v, w;
    int r;
    if (eq == NULL)
        return rs_error_set(err, RS_ERR_INPUT, "--set %s: expected NAME=VALUE", assignment);
    n = (size_t) (eq - assignment);
    while (n > 0 && assignment[n - 1] == ' ') n--;
    name = rs_strndup(assignment, n);
    if (rs_case_param_index(c, name) < 0) {
        r = rs_error_set(err, RS_ERR_INPUT, "--set %s: '%s' is not a parameter of %s", assignment, name, c->path);
        flint_free(name);
        return r;
    }
    fmpq_init(v);
    fmpq_init(w);
    /* i is the imaginary unit (a reserved name, never declared) */
    r = rs_expr_parse_complex(v, w, eq + 1, err);
    if (r != RS_OK) {
        char msg[RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "%s", err->msg);
        rs_error_set(err, RS_ERR_INPUT, "--set %s: %s", assignment, msg);
    } else {
        _rs_case_set_complex(c, name, v, w, "--set", 0, 0);
    }
    fmpq_clear(v);
    fmpq_clear(w);
    flint_free(name);
    return r;
}
