/* test_builder.c -- the scheme builders against independent derivations:
 *  - identities, exact: monolithic + integrator X equals X written by hand on
 *    the coupled system; Jacobi/Gauss-Seidel with kc = dc = 0 factor into the
 *    two subsystems' polynomials; one iteration of Jacobi or Gauss-Seidel with
 *    forward Euler reproduces monolithic forward Euler (Olivier et al. 2019,
 *    section 12.3) -- and not with backward Euler;
 *  - the Park staggered procedure through the builders equals the
 *    hand-written case;
 *  - a time-domain oracle: each co-simulation scheme stepped directly by a
 *    loop written here (not through recstab's matrices), its growth per step
 *    matching recstab's certified radius to 6 digits. */
#include "testutil.h"
#include <math.h>
#include <string.h>
#include <stdlib.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "recstab/charpoly.h"
#include "recstab/radius.h"

static char *slurp(const char *rel)
{
    char path[1024];
    FILE *f;
    long n;
    char *s;
    snprintf(path, sizeof path, "%s/%s", RS_SOURCE_DIR, rel);
    f = fopen(path, "rb");
    if (!f) fail_msg("cannot open %s", path);
    fseek(f, 0, SEEK_END);
    n = ftell(f);
    fseek(f, 0, SEEK_SET);
    s = malloc((size_t) n + 1);
    if (fread(s, 1, (size_t) n, f) != (size_t) n) fail_msg("read %s", path);
    s[n] = '\0';
    fclose(f);
    return s;
}

/* The case text with `set` lines removed and extra text appended. */
static char *case_text(const char *rel, const char *extra)
{
    char *s = slurp(rel), *out = malloc(strlen(s) + strlen(extra) + 2), *p = s, *o = out;
    while (*p) {
        char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t) (nl - p + 1) : strlen(p);
        if (strncmp(p, "set ", 4) != 0) { memcpy(o, p, len); o += len; }
        p += len;
    }
    strcpy(o, extra);
    free(s);
    return out;
}

/* primitive part of the characteristic polynomial (parameter content removed) */
typedef struct { rs_case_t c; rs_model_t m; rs_scheme_t s; rs_charpoly_t cp; fmpz_mpoly_t prim; } pol_t;

static void pol_build(pol_t *P, const char *label, const char *text)
{
    rs_error_t err;
    rs_error_init(err);
    rs_case_init(P->c);
    rs_model_init(P->m);
    rs_scheme_init(P->s);
    if (rs_case_parse_string(P->c, label, text, strlen(text), err) != RS_OK || rs_model_lower(P->m, P->c, err) != RS_OK
        || rs_scheme_build(P->s, P->m, err) != RS_OK)
        fail_msg("%s: %s:%d:%d %s", label, err->file, err->line, err->col, err->msg);
    {
        slong i;
        for (i = 0; i < P->c->nsets; i++)
            rs_scheme_substitute(P->s, rs_case_param_index(P->c, P->c->sets[i].name), P->c->sets[i].value);
    }
    rs_charpoly_init(P->cp, P->s);
    if (rs_charpoly_compute(P->cp, P->s, err) != RS_OK) fail_msg("%s: %s", label, err->msg);
    fmpz_mpoly_init(P->prim, P->s->zctx);
    fmpz_mpoly_divexact(P->prim, P->cp->p, P->cp->param_content, P->s->zctx);
    rs_charpoly_normalise(P->prim, NULL, P->s->lambda_var, P->s->zctx);
}

static void pol_clear(pol_t *P)
{
    fmpz_mpoly_clear(P->prim, P->s->zctx);
    rs_charpoly_clear(P->cp, P->s);
    rs_scheme_clear(P->s);
    rs_model_clear(P->m);
    rs_case_clear(P->c);
}

/* the polynomial given as a string in the case's variables, normalised */
static int pol_equals(pol_t *P, const char *closed)
{
    fmpz_mpoly_t e;
    int eq;
    fmpz_mpoly_init(e, P->s->zctx);
    if (fmpz_mpoly_set_str_pretty(e, closed, (const char **) P->s->vars, P->s->zctx) != 0)
        fail_msg("bad polynomial %s", closed);
    {
        fmpz_mpoly_t g;
        slong v = P->s->lambda_var;
        fmpz_mpoly_init(g, P->s->zctx);
        fmpz_mpoly_content_vars(g, e, &v, 1, P->s->zctx);
        fmpz_mpoly_divexact(e, e, g, P->s->zctx);
        fmpz_mpoly_clear(g, P->s->zctx);
    }
    rs_charpoly_normalise(e, NULL, P->s->lambda_var, P->s->zctx);
    eq = fmpz_mpoly_equal(e, P->prim, P->s->zctx);
    if (!eq) {
        char *a = fmpz_mpoly_get_str_pretty(P->prim, (const char **) P->s->vars, P->s->zctx);
        print_message("derived %s\n", a);
        flint_free(a);
    }
    fmpz_mpoly_clear(e, P->s->zctx);
    return eq;
}

/* Forward Euler on the coupled 2-mass system, written by hand:
 *   y[n+1] = y[n] + h v[n],  m v[n+1] = m v[n] + h F(y[n], v[n]). */
static const char *hand_fe =
    "param m1 m2 k1 k2 kc dc h\n"
    "unknown y1 v1 y2 v2\n"
    "eq y1[n+1] = y1[n] + h*v1[n]\n"
    "eq m1*v1[n+1] = m1*v1[n] + h*(-k1*y1[n] + kc*(y2[n] - y1[n]) + dc*(v2[n] - v1[n]))\n"
    "eq y2[n+1] = y2[n] + h*v2[n]\n"
    "eq m2*v2[n+1] = m2*v2[n] + h*(-k2*y2[n] - kc*(y2[n] - y1[n]) - dc*(v2[n] - v1[n]))\n";

static const char *hand_be =
    "param m1 m2 k1 k2 kc dc h\n"
    "unknown y1 v1 y2 v2\n"
    "eq y1[n+1] = y1[n] + h*v1[n+1]\n"
    "eq m1*v1[n+1] = m1*v1[n] + h*(-k1*y1[n+1] + kc*(y2[n+1] - y1[n+1]) + dc*(v2[n+1] - v1[n+1]))\n"
    "eq y2[n+1] = y2[n] + h*v2[n+1]\n"
    "eq m2*v2[n+1] = m2*v2[n] + h*(-k2*y2[n+1] - kc*(y2[n+1] - y1[n+1]) - dc*(v2[n+1] - v1[n+1]))\n";

static void same_poly(const char *rel_a, const char *text_b, int expect_equal)
{
    pol_t A, B;
    char *ta = case_text(rel_a, "");
    int eq;
    pol_build(&A, rel_a, ta);
    pol_build(&B, "hand", text_b);
    /* both contexts list m1 m2 k1 k2 kc dc h then lambda */
    eq = fmpz_mpoly_equal(A.prim, B.prim, A.s->zctx);
    if (eq != expect_equal) fail_msg("%s: equality %d, expected %d", rel_a, eq, expect_equal);
    pol_clear(&A);
    pol_clear(&B);
    free(ta);
}

static void test_monolithic_identity(void **state)
{
    (void) state;
    same_poly("cases/olivier2019-mono-ee-ee.case", hand_fe, 1);
    same_poly("cases/olivier2019-mono-ei-ei.case", hand_be, 1);
}

/* Olivier et al.: one iteration of J or GS with forward Euler is monolithic
 * forward Euler; recstab checks it exactly (and that it fails for backward
 * Euler, where the iteration does not converge in one step). */
static void test_one_iteration_forward_euler(void **state)
{
    (void) state;
    same_poly("cases/olivier2019-J-ee-ee-iter1.case", hand_fe, 1);
    same_poly("cases/olivier2019-GS12-ee-ee-iter1.case", hand_fe, 1);
    same_poly("cases/olivier2019-GS21-ee-ee-iter1.case", hand_fe, 1);
    same_poly("cases/olivier2019-J-ei-ei-iter1.case", hand_be, 0);
    same_poly("cases/olivier2019-J-ee-ee.case", hand_fe, 0);
}

/* kc = dc = 0: the subsystems decouple; with forward Euler each is
 * m (lambda - 1)^2 + h^2 k (Olivier's one-step formula adds no root). */
static void test_decoupled_factorises(void **state)
{
    const char *files[] = {"cases/olivier2019-J-ee-ee.case", "cases/olivier2019-GS12-ee-ee.case",
                           "cases/olivier2019-GS21-ee-ei.case", "cases/olivier2019-J-ei-ei.case"};
    const char *closed[] = {
        "(m1*(lambda-1)^2 + h^2*k1)*(m2*(lambda-1)^2 + h^2*k2)",
        "(m1*(lambda-1)^2 + h^2*k1)*(m2*(lambda-1)^2 + h^2*k2)",
        "(m1*(lambda-1)^2 + h^2*k1)*(m2*(lambda-1)^2 + h^2*k2*lambda^2)",
        "(m1*(lambda-1)^2 + h^2*k1*lambda^2)*(m2*(lambda-1)^2 + h^2*k2*lambda^2)"};
    size_t i;
    (void) state;
    for (i = 0; i < 4; i++) {
        pol_t P;
        char *t = case_text(files[i], "set kc = 0, dc = 0\n");
        pol_build(&P, files[i], t);
        if (!pol_equals(&P, closed[i])) fail_msg("%s does not factor as %s", files[i], closed[i]);
        pol_clear(&P);
        free(t);
    }
}

static void test_park_builders(void **state)
{
    pol_t A, B;
    char *ta = case_text("cases/park-staggered-builders.case", "");
    char *tb = case_text("cases/park-staggered.case", "");
    (void) state;
    pol_build(&A, "builders", ta);
    pol_build(&B, "hand", tb);
    assert_true(fmpz_mpoly_equal(A.prim, B.prim, A.s->zctx));
    pol_clear(&A);
    pol_clear(&B);
    free(ta);
    free(tb);
}

/* ---- time-domain oracle ----------------------------------------------------- */

typedef struct { long double m1, m2, k1, k2, kc, dc, h; } sys_t;

/* one subsystem step in Olivier's formulation: state (y, v, yd, vd) where
 * yd, vd are the derivatives imposed at the new time with the inputs (uy, uv) */
static void sub_step(long double *z, const long double *zold, int implicit, long double m, long double k,
                     long double kc, long double dc, long double h, long double uy, long double uv)
{
    /* F = -k y + kc (uy - y) + dc (uv - v): the same form for both subsystems
     * (uy, uv the partner's position and velocity) */
    if (!implicit) {
        z[0] = zold[0] + h * zold[2];
        z[1] = zold[1] + h * zold[3];
    } else {
        /* y = y0 + h v, v = v0 + h (-(k+kc) y + kc uy - dc v + dc uv)/m  -> 2x2 solve */
        long double a = (k + kc) / m, b = dc / m, r0 = zold[0], r1 = zold[1] + h * (kc * uy + dc * uv) / m;
        /* v (1 + h b + h^2 a) = r1 - h a r0 */
        long double v = (r1 - h * a * r0) / (1 + h * b + h * h * a);
        z[1] = v;
        z[0] = r0 + h * v;
    }
    z[2] = z[1];
    z[3] = (-k * z[0] + kc * (uy - z[0]) + dc * (uv - z[1])) / m;
}

/* coupling: 0 jacobi, 1 GS12, 2 GS21; iters extra iterations */
static long double oracle_growth(const sys_t *S, int impl1, int impl2, int coupling, int iters, long steps)
{
    long double z1[4], z2[4], n1[4], n2[4], p1[4], p2[4];
    long double sum_a = 0, sum_b = 0;
    long i, a1 = steps / 4 + 1, b1 = steps / 2, a2 = steps - steps / 4 + 1, b2 = steps;
    int j, it;
    unsigned long rnd = 12345;
    for (j = 0; j < 4; j++) {
        rnd = rnd * 6364136223846793005UL + 1442695040888963407UL;
        z1[j] = (long double) ((rnd >> 33) % 2001) / 1000.0L - 1;
        rnd = rnd * 6364136223846793005UL + 1442695040888963407UL;
        z2[j] = (long double) ((rnd >> 33) % 2001) / 1000.0L - 1;
    }
    /* consistent derivatives at the start */
    z1[2] = z1[1]; z1[3] = (-S->k1 * z1[0] + S->kc * (z2[0] - z1[0]) + S->dc * (z2[1] - z1[1])) / S->m1;
    z2[2] = z2[1]; z2[3] = (-S->k2 * z2[0] + S->kc * (z1[0] - z2[0]) + S->dc * (z1[1] - z2[1])) / S->m2;
    for (i = 1; i <= steps; i++) {
        long double nrm = 0;
        /* base step */
        if (coupling == 0) {
            sub_step(n1, z1, impl1, S->m1, S->k1, S->kc, S->dc, S->h, z2[0], z2[1]);
            sub_step(n2, z2, impl2, S->m2, S->k2, S->kc, S->dc, S->h, z1[0], z1[1]);
        } else if (coupling == 1) {
            sub_step(n1, z1, impl1, S->m1, S->k1, S->kc, S->dc, S->h, z2[0], z2[1]);
            sub_step(n2, z2, impl2, S->m2, S->k2, S->kc, S->dc, S->h, n1[0], n1[1]);
        } else {
            sub_step(n2, z2, impl2, S->m2, S->k2, S->kc, S->dc, S->h, z1[0], z1[1]);
            sub_step(n1, z1, impl1, S->m1, S->k1, S->kc, S->dc, S->h, n2[0], n2[1]);
        }
        for (it = 0; it < iters; it++) {
            memcpy(p1, n1, sizeof p1);
            memcpy(p2, n2, sizeof p2);
            if (coupling == 0) {
                sub_step(n1, z1, impl1, S->m1, S->k1, S->kc, S->dc, S->h, p2[0], p2[1]);
                sub_step(n2, z2, impl2, S->m2, S->k2, S->kc, S->dc, S->h, p1[0], p1[1]);
            } else if (coupling == 1) {
                sub_step(n1, z1, impl1, S->m1, S->k1, S->kc, S->dc, S->h, p2[0], p2[1]);
                sub_step(n2, z2, impl2, S->m2, S->k2, S->kc, S->dc, S->h, n1[0], n1[1]);
            } else {
                sub_step(n2, z2, impl2, S->m2, S->k2, S->kc, S->dc, S->h, p1[0], p1[1]);
                sub_step(n1, z1, impl1, S->m1, S->k1, S->kc, S->dc, S->h, n2[0], n2[1]);
            }
        }
        memcpy(z1, n1, sizeof z1);
        memcpy(z2, n2, sizeof z2);
        for (j = 0; j < 4; j++) nrm += z1[j] * z1[j] + z2[j] * z2[j];
        /* renormalise (linear scheme) and keep the log */
        {
            long double s = sqrtl(nrm), lg = logl(s);
            for (j = 0; j < 4; j++) { z1[j] /= s; z2[j] /= s; }
            /* cumulative log norm */
            static long double cum;
            if (i == 1) cum = 0;
            cum += lg;
            if (i >= a1 && i <= b1) sum_a += cum;
            if (i >= a2 && i <= b2) sum_b += cum;
        }
    }
    sum_a /= (long double) (b1 - a1 + 1);
    sum_b /= (long double) (b2 - a2 + 1);
    return expl((sum_b - sum_a) * 2 / (long double) ((a2 + b2) - (a1 + b1)));
}

static double recstab_radius(const char *rel, const char *sets)
{
    pol_t P;
    char *t = case_text(rel, sets);
    fmpz_poly_t u;
    rs_radius_t rr;
    rs_error_t err;
    double rho;
    pol_build(&P, rel, t);
    fmpz_poly_init(u);
    assert_true(rs_charpoly_get_fmpz_poly(u, P.cp->p, P.s->lambda_var, P.s->zctx));
    rs_radius_init(rr);
    rs_error_init(err);
    assert_int_equal(rs_radius_fmpz_poly(rr, u, 15, 4096, err), RS_OK);
    rho = arf_get_d(arb_midref(rr->rho), ARF_RND_NEAR);
    rs_radius_clear(rr);
    fmpz_poly_clear(u);
    pol_clear(&P);
    free(t);
    return rho;
}

static void test_time_domain_oracle(void **state)
{
    struct { const char *file; int i1, i2, cpl, it; } sch[] = {
        {"cases/olivier2019-J-ee-ee.case", 0, 0, 0, 0},
        {"cases/olivier2019-GS12-ee-ee.case", 0, 0, 1, 0},
        {"cases/olivier2019-GS21-ee-ei.case", 0, 1, 2, 0},
        {"cases/olivier2019-J-ei-ei.case", 1, 1, 0, 0},
        {"cases/olivier2019-GS12-ei-ei.case", 1, 1, 1, 0},
        {"cases/olivier2019-J-ee-ei-iter1.case", 0, 1, 0, 1},
        {"cases/olivier2019-GS12-ei-ei-iter1.case", 1, 1, 1, 1},
    };
    struct { const char *set; sys_t S; } pts[] = {
        {"set m1 = 1, m2 = 1, k1 = 1, k2 = 1, kc = 10, dc = 0, h = 1/10\n", {1, 1, 1, 1, 10, 0, 0.1L}},
        {"set m1 = 1, m2 = 2, k1 = 1, k2 = 3, kc = 1, dc = 1/5, h = 1/20\n", {1, 2, 1, 3, 1, 0.2L, 0.05L}},
        {"set m1 = 2, m2 = 1, k1 = 1, k2 = 1, kc = 10, dc = 1/2, h = 1/4\n", {2, 1, 1, 1, 10, 0.5L, 0.25L}},
    };
    size_t i, k;
    (void) state;
    for (i = 0; i < sizeof sch / sizeof sch[0]; i++)
        for (k = 0; k < sizeof pts / sizeof pts[0]; k++) {
            double rho = recstab_radius(sch[i].file, pts[k].set);
            long double g = oracle_growth(&pts[k].S, sch[i].i1, sch[i].i2, sch[i].cpl, sch[i].it, 40000);
            double rel = fabs((double) g - rho) / rho;
            if (rel > 1e-6)
                fail_msg("%s at %s: time-domain growth %.12Lf, certified radius %.12f (rel %.2e)", sch[i].file,
                         pts[k].set, g, rho, rel);
        }
}

/* Newmark pairs are found on trees: x' = (v) gives the same equations as
 * x' = v (issue 12: the text comparison rejected it), and with beta = 1/4,
 * gamma = 1/2, h = 1 the characteristic polynomial is the closed form of
 * Hughes (The Finite Element Method, ch. 9; cases/textbook/newmark-average-
 * acceleration.case): (4 + w^2) lambda^2 - (8 - 2 w^2) lambda + (4 + w^2). */
static void test_newmark_pairs_structural(void **state)
{
    const char *plain = "param w\nsubsystem S state x v\n  x' = v\n  v' = -w^2*x\nintegrate S newmark 1/4 1/2 1\n";
    const char *paren = "param w\nsubsystem S state x v\n  x' = (v)\n  v' = -w^2*x\nintegrate S newmark 1/4 1/2 1\n";
    pol_t A, B;
    slong i;
    (void) state;
    pol_build(&A, "plain", plain);
    pol_build(&B, "paren", paren);
    assert_int_equal(A.m->neqs, B.m->neqs);
    assert_int_equal(A.m->nuser_eqs, 0);          /* all generated */
    for (i = 0; i < A.m->neqs; i++) {
        assert_true(rs_expr_equal(A.m->eqs[i].lhs, B.m->eqs[i].lhs));
        assert_true(rs_expr_equal(A.m->eqs[i].rhs, B.m->eqs[i].rhs));
    }
    assert_true(pol_equals(&B, "(4 + w^2)*lambda^2 - (8 - 2*w^2)*lambda + (4 + w^2)"));
    pol_clear(&A);
    pol_clear(&B);
}

/* The generated equations are trees whose nodes point at the user's text:
 * the equation of motion's right-hand side at the state equation (line 4),
 * the integration formula at the `integrate` statement (line 5, the method's
 * column 13); the step h keeps its own position (line 5, column 28). */
static void test_generated_positions(void **state)
{
    const char *text = "param w, h\n"
                       "subsystem S state x v\n"
                       "  x' = v\n"
                       "  v' = -w^2*x\n"
                       "integrate S euler-forward h\n";
    pol_t A;
    const rs_eq_t *motion = NULL, *formula = NULL;
    slong i;
    char *t;
    (void) state;
    pol_build(&A, "t.case", text);
    for (i = 0; i < A.m->neqs; i++) {
        t = A.m->eqs[i].text;
        if (strncmp(t, "v_dot[n+1] = ", 13) == 0) motion = &A.m->eqs[i];
        if (strncmp(t, "v[n+1] - v[n] = ", 16) == 0) formula = &A.m->eqs[i];
    }
    assert_non_null(motion);
    assert_non_null(formula);
    assert_string_equal(motion->text, "v_dot[n+1] = (-w^2*x[n+1])");
    assert_string_equal(formula->text, "v[n+1] - v[n] = (h)*v_dot[n]");
    /* -w^2*x: MUL at '*' (column 12); x became x[n+1] at column 13 */
    assert_string_equal(motion->rhs->file, "t.case");
    assert_int_equal(motion->rhs->line, 4);
    assert_int_equal(motion->rhs->col, 12);
    assert_int_equal(motion->rhs->b->col, 13);
    assert_int_equal(motion->rhs->b->shift, 1);
    assert_int_equal(formula->lhs->line, 5);
    assert_int_equal(formula->lhs->col, 13);
    assert_int_equal(formula->rhs->a->line, 5);   /* (h) */
    assert_int_equal(formula->rhs->a->col, 27);
    assert_int_equal(A.m->nunknowns, 4);          /* x x_dot v v_dot, all generated */
    assert_int_equal(A.m->nuser_unknowns, 0);
    assert_int_equal(A.c->nunknowns, 0);          /* the case holds syntax only */
    assert_int_equal(A.c->neqs, 0);
    pol_clear(&A);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_monolithic_identity),
        cmocka_unit_test(test_one_iteration_forward_euler),
        cmocka_unit_test(test_decoupled_factorises),
        cmocka_unit_test(test_park_builders),
        cmocka_unit_test(test_newmark_pairs_structural),
        cmocka_unit_test(test_generated_positions),
        cmocka_unit_test(test_time_domain_oracle),
    };
    return cmocka_run_group_tests_name("builder", tests, NULL, NULL);
}
