/* test_model.c -- lowering produces a model and leaves the case alone:
 *  - a deep print of the case (every field, every tree node with its
 *    position) is the same before and after rs_model_lower, for builder,
 *    recurrence, co-simulation and plain cases;
 *  - the model of a builder case lists the generated unknowns (builder.h:
 *    each state X and its derivative X_dot) at the user's declarations;
 *  - a recurrence with exp/sin entries is a recurrence model holding its
 *    terms, one with polynomial entries becomes equations whose
 *    lambda-matrix is A_1 lambda + A_0 (worked out by hand below). */
#include "testutil.h"
#include <stdarg.h>
#include <string.h>
#include <stdlib.h>
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "lower/recurrence.h"

/* the deep print goes to a memory stream (POSIX open_memstream) */
typedef struct { FILE *f; char *s; size_t len; } buf_t;

static void put(buf_t *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vfprintf(b->f, fmt, ap);
    va_end(ap);
}

static void put_loc(buf_t *b, const rs_loc_t *l)
{
    put(b, "@%s:%d:%d", l->file ? l->file : "-", l->line, l->col);
}

/* every node: kind, value, shift, parentheses, position */
static void put_expr(buf_t *b, const rs_expr_t *e)
{
    if (e == NULL) { put(b, "()"); return; }
    put(b, "(%d", (int) e->kind);
    if (e->kind == RS_EXPR_NUM) {
        char *q = fmpq_get_str(NULL, 10, e->num);
        put(b, " %s %s", q, e->lit ? e->lit : "-");
        flint_free(q);
    }
    if (e->name) put(b, " %s", e->name);
    put(b, " s%d,%ld,%d p%d @%s:%d:%d ", e->shifted, (long) e->shift, e->shift_signed, e->paren,
        e->file ? e->file : "-", e->line, e->col);
    put_expr(b, e->a);
    put_expr(b, e->b);
    put(b, ")");
}

static void put_name(buf_t *b, const rs_name_t *n)
{
    put(b, " %s", n->name);
    put_loc(b, &n->loc);
}

/* a deep print of every field of the case */
static char *case_dump(const rs_case_t c)
{
    buf_t b = {NULL, NULL, 0};
    b.f = open_memstream(&b.s, &b.len);
    slong i, k;
    put(&b, "path %s title %s\n", c->path, c->title ? c->title : "-");
    put(&b, "params %ld:", (long) c->nparams);
    for (i = 0; i < c->nparams; i++) put_name(&b, &c->params[i]);
    put(&b, "\nunknowns %ld:", (long) c->nunknowns);
    for (i = 0; i < c->nunknowns; i++) put_name(&b, &c->unknowns[i]);
    put(&b, "\nassume %ld\n", (long) c->nassume);
    for (i = 0; i < c->nassume; i++) {
        put(&b, " %s %ld", c->assume[i].text, (long) c->assume[i].n);
        put_loc(&b, &c->assume[i].loc);
        for (k = 0; k < c->assume[i].n; k++) put_expr(&b, c->assume[i].e[k]);
        for (k = 0; k + 1 < c->assume[i].n; k++) put(&b, " op%d", (int) c->assume[i].op[k]);
        put(&b, "\n");
    }
    put(&b, "lets %ld\n", (long) c->nlets);
    for (i = 0; i < c->nlets; i++) {
        put(&b, " %s %d %ld %s", c->lets[i].name, c->lets[i].shifted, (long) c->lets[i].shift, c->lets[i].text);
        put_loc(&b, &c->lets[i].loc);
        put_expr(&b, c->lets[i].e);
        put(&b, "\n");
    }
    put(&b, "eqs %ld\n", (long) c->neqs);
    for (i = 0; i < c->neqs; i++) {
        put(&b, " %s", c->eqs[i].text);
        put_loc(&b, &c->eqs[i].loc);
        put_expr(&b, c->eqs[i].lhs);
        put_expr(&b, c->eqs[i].rhs);
        put(&b, "\n");
    }
    put(&b, "char ");
    put_expr(&b, c->charexpr);
    put_loc(&b, &c->charloc);
    put(&b, "\nsets %ld:", (long) c->nsets);
    for (i = 0; i < c->nsets; i++) {
        char *q = fmpq_get_str(NULL, 10, c->sets[i].value);
        put(&b, " %s=%s", c->sets[i].name, q);
        put_loc(&b, &c->sets[i].loc);
        flint_free(q);
    }
    put(&b, "\nrequests %ld:", (long) c->nrequests);
    for (i = 0; i < c->nrequests; i++) {
        put(&b, " [%s]", c->requests[i].text);
        put_loc(&b, &c->requests[i].loc);
    }
    put(&b, "\nsubs %ld\n", (long) c->nsubs);
    for (i = 0; i < c->nsubs; i++) {
        const rs_subsystem_t *s = &c->subs[i];
        put(&b, " %s", s->name);
        put_loc(&b, &s->loc);
        put(&b, " states");
        for (k = 0; k < s->nstates; k++) put_name(&b, &s->states[k]);
        for (k = 0; k < s->ndeqs; k++) {
            put(&b, "\n  %s %d", s->deqs[k].state, s->deqs[k].order);
            put_loc(&b, &s->deqs[k].loc);
            put_expr(&b, s->deqs[k].rhs);
        }
        put(&b, "\n  integrate %s", s->method ? s->method : "-");
        put_loc(&b, &s->intloc);
        put_expr(&b, s->arg1);
        put_expr(&b, s->arg2);
        put_expr(&b, s->step);
        put(&b, "\n");
    }
    put(&b, "couple %s %s %s %ld", c->couple ? c->couple : "-", c->couple_first ? c->couple_first : "-",
        c->couple_second ? c->couple_second : "-", (long) c->couple_order);
    put_loc(&b, &c->couple_loc);
    put(&b, " iterations %ld extrapolate %ld\nforces %ld\n", (long) c->iterations, (long) c->extrapolate,
        (long) c->nforces);
    for (i = 0; i < c->nforces; i++) {
        put(&b, " %s", c->forces[i].name);
        put_loc(&b, &c->forces[i].loc);
        put_expr(&b, c->forces[i].e);
        put(&b, "\n");
    }
    put(&b, "rec %ld\n", (long) c->nrec);
    for (i = 0; i < c->nrec; i++) {
        put(&b, " %ld %ldx%ld", (long) c->rec[i].k, (long) c->rec[i].rows, (long) c->rec[i].cols);
        put_loc(&b, &c->rec[i].loc);
        for (k = 0; k < c->rec[i].rows * c->rec[i].cols; k++) put_expr(&b, c->rec[i].entries[k]);
        put(&b, "\n");
    }
    put(&b, "files %ld:", (long) c->nfiles);
    for (i = 0; i < c->nfiles; i++) put(&b, " %s", c->files[i]);
    put(&b, "\n");
    fclose(b.f);
    return b.s;
}

/* Lowering reads the case only: the deep print is unchanged, and the model
 * has what the builders/recurrences generated (so the print would show it
 * had lowering appended to the case). */
static void test_lower_leaves_case(void **state)
{
    static const char *const rels[] = {
        "cases/olivier2019-J-ee-ee-iter1.case",       /* Jacobi, one iteration */
        "cases/li-fd-explicit-k1.case",               /* exact integration: co-simulation */
        "cases/textbook/newmark-average-acceleration.case",
        "cases/recurrence-forward-euler.case",        /* polynomial entries: equations */
        "cases/recurrence-exact-oscillator.case",     /* exp/sin entries: numeric */
        "cases/park-staggered.case",                  /* equations written by hand */
    };
    size_t i;
    (void) state;
    for (i = 0; i < sizeof rels / sizeof rels[0]; i++) {
        char path[1024], *before, *after;
        rs_case_t c;
        rs_model_t m;
        rs_error_t err;
        snprintf(path, sizeof path, "%s/%s", RS_SOURCE_DIR, rels[i]);
        rs_case_init(c);
        rs_model_init(m);
        rs_error_init(err);
        if (rs_case_parse_file(c, path, err) != RS_OK) fail_msg("%s: %s", rels[i], err->msg);
        before = case_dump(c);
        if (rs_model_lower(m, c, err) != RS_OK) fail_msg("%s: %s", rels[i], err->msg);
        after = case_dump(c);
        if (strcmp(before, after) != 0) fail_msg("%s: lowering changed the case:\n%s\n---\n%s", rels[i], before, after);
        assert_ptr_equal(m->c, c);
        if (c->nsubs > 0 && m->kind == RS_MODEL_EQUATIONS) assert_true(m->nunknowns > c->nunknowns);
        rs_model_clear(m);
        free(after);
        after = case_dump(c);
        assert_string_equal(after, before);
        free(before);
        free(after);
        rs_case_clear(c);
    }
}

/* The model of a one-subsystem forward-Euler case: x and v are not a
 * (position, velocity) pair for forward Euler, so each state has its
 * derivative unknown (builder.h): x x_dot v v_dot, in state order, each at
 * its state's declaration "subsystem S state x v" (line 2: x at column 19,
 * v at column 21, counted by hand); the four equations are all generated. */
static void test_builder_model(void **state)
{
    const char *text = "param w, h\n"
                       "subsystem S state x v\n"
                       "  x' = v\n"
                       "  v' = -w^2*x\n"
                       "integrate S euler-forward h\n";
    static const char *const names[] = {"x", "x_dot", "v", "v_dot"};
    static const int cols[] = {19, 19, 21, 21};
    rs_case_t c;
    rs_model_t m;
    rs_scheme_t s;
    rs_error_t err;
    char *emit;
    slong i;
    (void) state;
    rs_case_init(c);
    rs_model_init(m);
    rs_scheme_init(s);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", text, strlen(text), err), RS_OK);
    /* a model that was not lowered builds nothing */
    assert_int_equal(rs_scheme_build(s, m, err), RS_ERR_INTERNAL);
    assert_int_equal(rs_model_lower(m, c, err), RS_OK);
    assert_int_equal(m->kind, RS_MODEL_EQUATIONS);
    assert_int_equal(m->nuser_unknowns, 0);
    assert_int_equal(m->nunknowns, 4);
    for (i = 0; i < 4; i++) {
        assert_string_equal(m->unknowns[i].name, names[i]);
        assert_string_equal(m->unknowns[i].loc.file, "t.case");
        assert_int_equal(m->unknowns[i].loc.line, 2);
        assert_int_equal(m->unknowns[i].loc.col, cols[i]);
    }
    assert_int_equal(m->unknown_loc.line, 2);
    assert_int_equal(m->unknown_loc.col, 19);
    assert_int_equal(m->nuser_eqs, 0);
    assert_int_equal(m->neqs, 4);
    assert_int_equal(rs_model_unknown_index(m, "v_dot"), 3);
    assert_int_equal(rs_model_unknown_index(m, "w"), -1);
    emit = rs_model_emit_equations(m);
    assert_non_null(emit);
    assert_true(strncmp(emit, "unknown x x_dot v v_dot\neq ", 27) == 0);
    flint_free(emit);
    assert_int_equal(rs_scheme_build(s, m, err), RS_OK);
    assert_int_equal(s->n, 4);
    /* lowering again gives the same model (it starts from a cleared one) */
    assert_int_equal(rs_model_lower(m, c, err), RS_OK);
    assert_int_equal(m->nunknowns, 4);
    assert_int_equal(m->neqs, 4);
    rs_scheme_clear(s);
    rs_model_clear(m);
    rs_case_clear(c);
}

/* A user's name that a builder generates is an error at the user's
 * declaration (line 1), and the case still holds only what was written. */
static void test_builder_name_taken(void **state)
{
    const char *text = "param w, h, x_dot\n"
                       "subsystem S state x v\n"
                       "  x' = v\n"
                       "  v' = -w^2*x\n"
                       "integrate S euler-forward h\n";
    rs_case_t c;
    rs_model_t m;
    rs_error_t err;
    (void) state;
    rs_case_init(c);
    rs_model_init(m);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", text, strlen(text), err), RS_OK);
    assert_int_equal(rs_model_lower(m, c, err), RS_ERR_INPUT);
    assert_int_equal(err->line, 1);
    assert_int_equal(err->col, 13);
    assert_non_null(strstr(err->msg, "'x_dot' is also a name the builders generate"));
    assert_int_equal(c->nunknowns, 0);
    assert_int_equal(c->neqs, 0);
    rs_model_clear(m);
    rs_case_clear(c);
}

/* exp/sin entries: a recurrence model with the case's two terms, n = 2 and
 * K = 1; no unknowns or equations are made and nothing is emitted.  Its
 * matrices at a = 1, h = 1/2: A_1 = I, A_0 = [-e^{-1/2}, 0; -sin(1)/2, -1/2]
 * (the entries evaluated here with Arb's own functions). */
static void test_recurrence_model(void **state)
{
    const char *text = "param a, h\n"
                       "recurrence 1 = [1, 0; 0, 1]\n"
                       "recurrence 0 = [-exp(-a*h), 0; -h*sin(a), -1/2]\n"
                       "set a = 1, h = 1/2\n";
    rs_case_t c;
    rs_model_t m;
    rs_error_t err;
    acb_mat_struct *A = NULL;
    slong K = -1, i;
    arb_t want;
    (void) state;
    rs_case_init(c);
    rs_model_init(m);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", text, strlen(text), err), RS_OK);
    assert_int_equal(rs_model_lower(m, c, err), RS_OK);
    assert_int_equal(m->kind, RS_MODEL_RECURRENCE);
    assert_int_equal(m->nterms, 2);
    assert_ptr_equal(m->terms, c->rec);
    assert_int_equal(m->n, 2);
    assert_int_equal(m->K, 1);
    assert_int_equal(m->nunknowns, 0);
    assert_int_equal(m->neqs, 0);
    assert_null(rs_model_emit_equations(m));
    assert_int_equal(rs_recurrence_matrices(&A, &K, m, 128, err), RS_OK);
    assert_int_equal(K, 1);
    for (i = 0; i < 4; i++)                       /* A_1 = I, exactly */
        assert_true(i % 3 == 0 ? acb_is_one(acb_mat_entry(A + 1, i / 2, i % 2))
                               : acb_is_zero(acb_mat_entry(A + 1, i / 2, i % 2)));
    arb_init(want);
    arb_set_si(want, -1);
    arb_mul_2exp_si(want, want, -1);
    arb_exp(want, want, 128);
    arb_neg(want, want);                          /* -e^{-1/2} */
    assert_true(arb_overlaps(acb_realref(acb_mat_entry(A + 0, 0, 0)), want));
    arb_set_si(want, 1);
    arb_sin(want, want, 128);
    arb_mul_2exp_si(want, want, -1);
    arb_neg(want, want);                          /* -sin(1)/2 */
    assert_true(arb_overlaps(acb_realref(acb_mat_entry(A + 0, 1, 0)), want));
    assert_false(arb_overlaps(acb_realref(acb_mat_entry(A + 0, 0, 0)), want));
    assert_true(acb_is_zero(acb_mat_entry(A + 0, 0, 1)));
    arb_set_si(want, -1);
    arb_mul_2exp_si(want, want, -1);
    assert_true(arb_equal(acb_realref(acb_mat_entry(A + 0, 1, 1)), want));
    arb_clear(want);
    for (i = 0; i <= K; i++) acb_mat_clear(A + i);
    flint_free(A);
    rs_model_clear(m);
    rs_case_clear(c);
}

/* Polynomial entries: the model has z1, z2 (at the first term's shift,
 * line 2 column 12) and two equations; the lambda-matrix is
 * A_1 lambda + A_0 = [lambda - 1, -w; w, lambda - 1] (x[n+k] -> lambda^k). */
static void test_polynomial_recurrence_model(void **state)
{
    const char *text = "param w\n"
                       "recurrence 1 = [1, 0; 0, 1]\n"
                       "recurrence 0 = [-1, -w; w, -1]\n";
    static const char *const want[] = {"lambda - 1", "-w", "w", "lambda - 1"};
    rs_case_t c;
    rs_model_t m;
    rs_scheme_t s;
    rs_error_t err;
    slong i;
    (void) state;
    rs_case_init(c);
    rs_model_init(m);
    rs_scheme_init(s);
    rs_error_init(err);
    assert_int_equal(rs_case_parse_string(c, "t.case", text, strlen(text), err), RS_OK);
    assert_int_equal(rs_model_lower(m, c, err), RS_OK);
    assert_int_equal(m->kind, RS_MODEL_EQUATIONS);
    assert_int_equal(m->nunknowns, 2);
    assert_string_equal(m->unknowns[0].name, "z1");
    assert_string_equal(m->unknowns[1].name, "z2");
    assert_int_equal(m->unknowns[1].loc.line, 2);
    assert_int_equal(m->unknowns[1].loc.col, 12);
    assert_int_equal(m->neqs, 2);
    assert_int_equal(rs_scheme_build(s, m, err), RS_OK);
    assert_int_equal(s->n, 2);
    for (i = 0; i < 4; i++) {
        fmpq_mpoly_t p;
        fmpq_mpoly_init(p, s->ctx);
        assert_int_equal(fmpq_mpoly_set_str_pretty(p, want[i], (const char **) s->vars, s->ctx), 0);
        assert_true(fmpq_mpoly_equal(p, s->M + i, s->ctx));
        fmpq_mpoly_clear(p, s->ctx);
    }
    rs_scheme_clear(s);
    rs_model_clear(m);
    rs_case_clear(c);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lower_leaves_case),
        cmocka_unit_test(test_builder_model),
        cmocka_unit_test(test_builder_name_taken),
        cmocka_unit_test(test_recurrence_model),
        cmocka_unit_test(test_polynomial_recurrence_model),
    };
    return cmocka_run_group_tests_name("model", tests, NULL, NULL);
}
