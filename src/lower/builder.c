/* builder.c -- subsystems, integrators and couplings lowered into unknowns
 * and difference equations (see builder.h).  The equations are built as
 * expression trees: the user's right-hand sides are copied with every name
 * resolved to a sequence, so each node keeps the user's file:line:col; the
 * nodes the integration formulas add carry the `integrate` statement's. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fmpq_vec.h>
#include "lower/builder.h"
#include "lower/lower.h"
#include "lower/methods.h"

#define MAX_STATES 64

typedef struct {
    const rs_case_struct *c;
    rs_model_struct *m;    /* receives the unknowns and equations */
    slong K;               /* iterations */
    int kind;              /* 0 monolithic, 1 jacobi, 2 gauss-seidel, 3 explicit, 4 implicit (order corder) */
    slong corder;
    slong *rank;           /* gauss-seidel: each subsystem's place in the order of integration */
    slong *vel;            /* per subsystem, per state: index of its velocity (pair) or -1 */
    int *pair;             /* per subsystem: integrator works on (x, v) pairs */
    rs_tableau_struct *tab; /* per subsystem: its Butcher tableau (rk), s = 0 otherwise */
    slong stage;           /* subst: own states at this Runge-Kutta stage (>= 0), */
    int mix;               /* or at the alpha methods' intermediate time (1) */
} gen_t;

/* where generated nodes point */
typedef struct { const char *file; int line, col; } pos_t;

static pos_t pos_of(const rs_loc_t *l) { pos_t p = {l->file, l->line, l->col}; return p; }
static pos_t pos_node(const rs_expr_t *e) { pos_t p = {e->file, e->line, e->col}; return p; }

static rs_expr_t *num(slong v, pos_t p) { return rs_expr_new_num(v, p.file, p.line, p.col); }
static rs_expr_t *op(rs_expr_kind_t k, rs_expr_t *a, rs_expr_t *b, pos_t p)
{
    return rs_expr_new_op(k, a, b, p.file, p.line, p.col);
}
static rs_expr_t *P(rs_expr_t *e) { return rs_expr_paren(e); }
static rs_expr_t *copy(const rs_expr_t *e) { return rs_expr_copy(e); }

/* NAME[n+shift] */
static rs_expr_t *seq(const char *name, slong shift, pos_t p)
{
    return rs_expr_new_name(name, 1, shift, p.file, p.line, p.col);
}

/* the unknown of state s in iterate j (the last iterate is s itself) */
static void var_name(char *buf, size_t len, const char *s, slong j, slong K)
{
    if (j == K) snprintf(buf, len, "%s", s);
    else snprintf(buf, len, "%s_it%ld", s, (long) j);
}

/* the unknown of the derivative of s in iterate j */
static void dvar_name(char *buf, size_t len, const char *s, slong j, slong K)
{
    if (j == K) snprintf(buf, len, "%s_dot", s);
    else snprintf(buf, len, "%s_dot_it%ld", s, (long) j);
}

static rs_expr_t *var(const char *s, slong j, slong K, slong shift, pos_t p)
{
    char b[96];
    var_name(b, sizeof b, s, j, K);
    return seq(b, shift, p);
}

static rs_expr_t *dvar(const char *s, slong j, slong K, slong shift, pos_t p)
{
    char b[96];
    dvar_name(b, sizeof b, s, j, K);
    return seq(b, shift, p);
}

/* s_dot[n+shift] */
static rs_expr_t *dot(const char *s, slong shift, pos_t p)
{
    char b[96];
    snprintf(b, sizeof b, "%s_dot", s);
    return seq(b, shift, p);
}

static slong sub_index(const rs_case_struct *c, const char *name)
{
    slong i;
    for (i = 0; i < c->nsubs; i++)
        if (strcmp(c->subs[i].name, name) == 0) return i;
    return -1;
}

static slong state_index(const rs_subsystem_t *s, const char *name)
{
    slong k;
    for (k = 0; k < s->nstates; k++)
        if (strcmp(s->states[k].name, name) == 0) return k;
    return -1;
}

static int find_state(const rs_case_struct *c, const char *name, slong *a, slong *k)
{
    slong i;
    for (i = 0; i < c->nsubs; i++)
        if ((*k = state_index(&c->subs[i], name)) >= 0) { *a = i; return 1; }
    return 0;
}

static int is_pos(const gen_t *g, slong a, slong k) { return g->pair[a] && g->vel[a * MAX_STATES + k] >= 0; }

/* state x is a position of a central-difference subsystem: its value at the
 * time of the equation of motion, x[n+1], was fixed by the step before (the
 * step that iterates a[n+1] and v[n+1] produces x[n+2]), so every iterate
 * reads the final x[n+1] */
static int cd_pos(const gen_t *g, const char *x)
{
    slong a, k;
    return find_state(g->c, x, &a, &k) && strcmp(g->c->subs[a].method, "central-difference") == 0 && is_pos(g, a, k);
}

/* binomial coefficients of the extrapolating polynomial through
 * n, n-1, ..., n-K evaluated at n+1: (-1)^i C(K+1, i+1) */
static slong extrap_coeff(slong K, slong i)
{
    slong r = 1, m;
    for (m = 1; m <= i + 1; m++) r = r * (K + 2 - m) / m;
    return (i % 2) ? -r : r;
}

/* partner state p (of subsystem b) as seen by subsystem a in iterate j:
 * Gauss-Seidel sees the new value of a subsystem integrated before a */
static rs_expr_t *partner(const gen_t *g, const char *p, slong a, slong b, slong j, pos_t at)
{
    int delayed;
    if (g->kind == 0) return var(p, j, g->K, 1, at);
    delayed = (g->kind == 1) || (g->kind == 2 && g->rank[b] > g->rank[a]);
    if (j == 0 && delayed) {
        slong K = g->c->extrapolate < 0 ? 0 : g->c->extrapolate, i;
        rs_expr_t *e;
        if (K == 0) return seq(p, 0, at);
        e = seq(p, 0, at);
        e->shift_signed = -1;   /* printed p[n-0], the first of p[n-i] */
        e = op(RS_EXPR_MUL, num(extrap_coeff(K, 0), at), e, at);
        for (i = 1; i <= K; i++) {
            slong cf = extrap_coeff(K, i);
            e = op(cf < 0 ? RS_EXPR_SUB : RS_EXPR_ADD, e,
                   op(RS_EXPR_MUL, num(cf < 0 ? -cf : cf, at), seq(p, -i, at), at), at);
        }
        return P(e);
    }
    if (cd_pos(g, p)) return seq(p, 1, at);
    if (j == 0) return var(p, 0, g->K, 1, at);
    return var(p, delayed ? j - 1 : j, g->K, 1, at);
}

static int is_method(const rs_subsystem_t *s, const char *m) { return strcmp(s->method, m) == 0; }

static int is_alpha(const rs_subsystem_t *s)
{
    return is_method(s, "hht") || is_method(s, "generalized-alpha") || is_method(s, "wbz");
}

/* |q| as a tree: N or N/D */
static rs_expr_t *rat(const fmpq_t q, pos_t p)
{
    rs_expr_t *e = num(fmpz_get_si(fmpq_numref(q)), p);
    fmpz_abs(fmpq_numref(e->num), fmpq_numref(q));
    if (fmpz_is_one(fmpq_denref(q))) return e;
    return op(RS_EXPR_DIV, e, num(fmpz_get_si(fmpq_denref(q)), p), p);
}

/* sqrt(d) as a tree: the exact constant the scheme evaluates as its
 * variable s with s^2 = d (lower/scheme.c) */
static rs_expr_t *sqrt_tree(slong d, pos_t p)
{
    rs_expr_t *e = rs_expr_new_name("sqrt", 0, 0, p.file, p.line, p.col);
    e->kind = RS_EXPR_CALL;
    e->a = num(d, p);
    return e;
}

/* x + y sqrt(d), y != 0, as a tree "(x + y*sqrt(d))" (x = 0: "y*sqrt(d)", "(-y*sqrt(d))") */
static rs_expr_t *qd_tree(const fmpq_t x, const fmpq_t y, slong d, pos_t p)
{
    rs_expr_t *e = sqrt_tree(d, p);
    if (!fmpq_is_one(y) && !fmpq_is_pm1(y)) e = op(RS_EXPR_MUL, rat(y, p), e, p);
    if (fmpq_is_zero(x)) return fmpq_sgn(y) < 0 ? P(rs_expr_new_op(RS_EXPR_NEG, e, NULL, p.file, p.line, p.col)) : e;
    return P(op(fmpq_sgn(y) < 0 ? RS_EXPR_SUB : RS_EXPR_ADD,
                fmpq_sgn(x) < 0 ? rs_expr_new_op(RS_EXPR_NEG, rat(x, p), NULL, p.file, p.line, p.col) : rat(x, p),
                e, p));
}

/* sum (c[i] + c1[i] sqrt(d))*t[i] over the nonzero coefficients (c1 NULL:
 * rational; unit coefficients left out, signs as + and -); the terms t[i]
 * are consumed; NULL when every coefficient is zero */
static rs_expr_t *lincomb(const fmpq *c, const fmpq *c1, slong d, rs_expr_t **t, slong n, pos_t p)
{
    rs_expr_t *e = NULL, *x;
    slong i;
    for (i = 0; i < n; i++) {
        int irr = c1 != NULL && !fmpq_is_zero(c1 + i), neg = !irr && fmpq_sgn(c + i) < 0;
        if (fmpq_is_zero(c + i) && !irr) { rs_expr_free(t[i]); continue; }
        if (irr) x = op(RS_EXPR_MUL, qd_tree(c + i, c1 + i, d, p), t[i], p);
        else x = fmpq_is_one(c + i) || fmpq_is_pm1(c + i) ? t[i] : op(RS_EXPR_MUL, rat(c + i, p), t[i], p);
        if (e == NULL) e = neg ? rs_expr_new_op(RS_EXPR_NEG, x, NULL, p.file, p.line, p.col) : x;
        else e = op(neg ? RS_EXPR_SUB : RS_EXPR_ADD, e, x, p);
    }
    return e;
}

/* the unknown of stage i (from 1) of state s in iterate j: s_kI, s_kI_itJ */
static void stage_name(char *buf, size_t len, const char *s, slong i, slong j, slong K)
{
    if (j == K) snprintf(buf, len, "%s_k%ld", s, (long) i);
    else snprintf(buf, len, "%s_k%ld_it%ld", s, (long) i, (long) j);
}

static rs_expr_t *stage_var(const char *s, slong i, slong j, slong K, pos_t p)
{
    char b[96];
    stage_name(b, sizeof b, s, i, j, K);
    return seq(b, 1, p);
}

/* alpha_f of the alpha methods as a tree (NULL for wbz: 0) */
static rs_expr_t *alpha_f(const rs_subsystem_t *s, pos_t p)
{
    if (is_method(s, "hht")) return P(rs_expr_new_op(RS_EXPR_NEG, P(copy(s->arg1)), NULL, p.file, p.line, p.col));
    if (is_method(s, "generalized-alpha"))   /* rho/(rho + 1) */
        return P(op(RS_EXPR_DIV, P(copy(s->arg1)), P(op(RS_EXPR_ADD, P(copy(s->arg1)), num(1, p), p)), p));
    return NULL;
}

/* alpha_m of the alpha methods as a tree (NULL for hht: 0) */
static rs_expr_t *alpha_m(const rs_subsystem_t *s, pos_t p)
{
    if (is_method(s, "wbz")) return P(copy(s->arg1));
    if (is_method(s, "generalized-alpha"))   /* (2 rho - 1)/(rho + 1) */
        return P(op(RS_EXPR_DIV, P(op(RS_EXPR_SUB, op(RS_EXPR_MUL, num(2, p), P(copy(s->arg1)), p), num(1, p), p)),
                    P(op(RS_EXPR_ADD, P(copy(s->arg1)), num(1, p), p)), p));
    return NULL;
}

/* own state x of subsystem a in iterate j as subst sees it: x[n+1], a
 * Runge-Kutta stage value x[n] + (h)*(sum_l a_il x_kl[n+1]), or the alpha
 * methods' (1 - alpha_f)*x[n+1] + alpha_f*x[n] */
static rs_expr_t *own(const gen_t *g, slong a, const char *x, slong j, pos_t at)
{
    const rs_subsystem_t *s = &g->c->subs[a];
    if (g->stage >= 0) {
        const rs_tableau_struct *t = &g->tab[a];
        rs_expr_t *k[RS_METHODS_MAX_STAGES], *sum;
        slong l;
        pos_t p = pos_of(&s->intloc);
        for (l = 0; l < t->s; l++) k[l] = stage_var(x, l + 1, j, g->K, p);
        sum = lincomb(t->A + g->stage * t->s, t->A1 ? t->A1 + g->stage * t->s : NULL, t->d, k, t->s, p);
        if (sum == NULL) return seq(x, 0, at);
        return P(op(RS_EXPR_ADD, seq(x, 0, p), op(RS_EXPR_MUL, P(copy(s->step)), P(sum), p), p));
    }
    if (cd_pos(g, x)) return seq(x, 1, at);
    if (g->mix) {
        pos_t p = pos_of(&s->intloc);
        rs_expr_t *af = alpha_f(s, p);
        if (af == NULL) return var(x, j, g->K, 1, at);
        return P(op(RS_EXPR_ADD, op(RS_EXPR_MUL, P(op(RS_EXPR_SUB, num(1, p), af, p)), var(x, j, g->K, 1, p), p),
                    op(RS_EXPR_MUL, alpha_f(s, p), seq(x, 0, p), p), p));
    }
    return var(x, j, g->K, 1, at);
}

/* monolithic coupling: subsystem b integrated by the same method as a (the
 * same tableau, or the same alpha method and parameter), so that a
 * Runge-Kutta stage or an alpha method's intermediate time sees b's state
 * at that stage or time too; otherwise partners enter as the coupling says */
static int same_method(const gen_t *g, slong a, slong b)
{
    const rs_subsystem_t *s = &g->c->subs[a], *t = &g->c->subs[b];
    slong i;
    if (g->kind != 0 || strcmp(s->method, t->method) != 0 || !rs_expr_equal(s->step, t->step)) return 0;
    if (is_alpha(s)) return rs_expr_equal(s->arg1, t->arg1);
    if (g->tab[a].s != g->tab[b].s || g->tab[a].d != g->tab[b].d) return 0;
    for (i = 0; i < g->tab[a].s * g->tab[a].s; i++)
        if (!fmpq_equal(g->tab[a].A + i, g->tab[b].A + i)
            || (g->tab[a].d && !fmpq_equal(g->tab[a].A1 + i, g->tab[b].A1 + i))) return 0;
    for (i = 0; i < g->tab[a].s; i++)
        if (!fmpq_equal(g->tab[a].b + i, g->tab[b].b + i)
            || (g->tab[a].d && !fmpq_equal(g->tab[a].b1 + i, g->tab[b].b1 + i))) return 0;
    return 1;
}

/* ---- couple explicit|implicit order K with integrators (Li et al.'s coupling) ----
 * Each coupling variable (a partner state used, or a `coupling force` as a
 * whole, own states included) is the degree-K polynomial in tau (the macro
 * step's time, t = t[n] + tau h) through its values at the nodes tau_j = -j
 * (explicit: extrapolation from n, n-1, ..., n-K) or 1 - j (implicit: the
 * new value u[n+1] = its expression at the new states, solved with the step,
 * then n, ..., n+1-K), evaluated where the integrator evaluates the
 * right-hand side: tau = 1 for the equation of motion at t[n+1], c_i for a
 * Runge-Kutta stage, 1 - alpha_f for the alpha methods. */

/* node j's shift */
static slong node_shift(const gen_t *g, slong j) { return g->kind == 4 ? 1 - j : -j; }

/* l_j(tau) = prod_{k != j} (tau - tau_k)/(tau_j - tau_k) as a tree; tau a
 * number (tq) or a tree (tt, copied) */
static rs_expr_t *basis(const gen_t *g, slong j, const fmpq_t tq, const rs_expr_t *tt, pos_t p)
{
    slong k, n = g->corder + 1;
    fmpq_t v, d;
    rs_expr_t *e = NULL;
    fmpq_init(v);
    fmpq_init(d);
    fmpq_one(v);
    for (k = 0; k < n; k++) {
        if (k == j) continue;
        fmpq_set_si(d, node_shift(g, j) - node_shift(g, k), 1);
        fmpq_inv(d, d);
        if (tt == NULL) {
            fmpq_t t;
            fmpq_init(t);
            fmpq_sub_si(t, tq, node_shift(g, k));
            fmpq_mul(v, v, t);
            fmpq_clear(t);
        } else {
            rs_expr_t *f = P(op(RS_EXPR_SUB, P(copy(tt)), num(node_shift(g, k), p), p));
            if (node_shift(g, k) < 0) f = P(op(RS_EXPR_ADD, P(copy(tt)), num(-node_shift(g, k), p), p));
            e = e == NULL ? f : op(RS_EXPR_MUL, e, f, p);
        }
        fmpq_mul(v, v, d);
    }
    if (e == NULL || !fmpq_is_one(v)) {
        rs_expr_t *c = rat(v, p);
        if (fmpq_sgn(v) < 0) c = P(rs_expr_new_op(RS_EXPR_NEG, c, NULL, p.file, p.line, p.col));
        e = e == NULL ? c : op(RS_EXPR_MUL, c, e, p);
    }
    fmpq_clear(v);
    fmpq_clear(d);
    return e;
}

/* a copy of e with every name resolved by leaf (its parentheses kept):
 * the one tree walk of subst and at_shift; NULL and err set on an error */
typedef rs_expr_t *(*leaf_fn)(const gen_t *g, slong a, slong j, const rs_expr_t *e, rs_error_t err);
static rs_expr_t *map_tree(const gen_t *g, slong a, slong j, const rs_expr_t *e, leaf_fn leaf, rs_error_t err)
{
    rs_expr_t *out;
    if (e->kind == RS_EXPR_NAME || e->kind == RS_EXPR_CALL) {
        if ((out = leaf(g, a, j, e, err)) != NULL) out->paren += e->paren;
        return out;
    }
    if (e->kind == RS_EXPR_NUM) return copy(e);
    out = rs_expr_new_op(e->kind, NULL, NULL, e->file, e->line, e->col);
    out->paren = e->paren;
    if ((out->a = map_tree(g, a, j, e->a, leaf, err)) == NULL
        || (e->b != NULL && (out->b = map_tree(g, a, j, e->b, leaf, err)) == NULL)) {
        rs_expr_free(out);
        return NULL;
    }
    return out;
}

/* a name of a coupling force at n + shift: states shifted, params and unshifted lets kept */
static rs_expr_t *shift_leaf(const gen_t *g, slong a, slong shift, const rs_expr_t *e, rs_error_t err)
{
    const rs_case_struct *c = g->c;
    slong sa, sk, li;
    pos_t at = pos_node(e);
    (void) a;
    if (e->kind == RS_EXPR_NAME && !e->shifted && find_state(c, e->name, &sa, &sk)) return seq(e->name, shift, at);
    if (e->kind == RS_EXPR_NAME && !e->shifted
        && (((li = rs_case_let_index(c, e->name)) >= 0 && !c->lets[li].shifted) || rs_case_param_index(c, e->name) >= 0))
        return rs_expr_new_name(e->name, 0, 0, at.file, at.line, at.col);
    rs_error_set_at(err, RS_ERR_INPUT, e->file, e->line, e->col,
                    "expected states, params and unshifted lets in a coupling force; found '%s'", e->name);
    return NULL;
}

/* a copy of the force expression e with every state at n + shift */
static rs_expr_t *at_shift(const gen_t *g, const rs_expr_t *e, slong shift, rs_error_t err)
{
    return map_tree(g, 0, shift, e, shift_leaf, err);
}

/* the coupling variable (partner state name, or force expression fe) as
 * subsystem a's right-hand side sees it now (g->stage, g->mix) */
static rs_expr_t *coupled(const gen_t *g, slong a, const char *name, const rs_expr_t *fe, pos_t at, rs_error_t err)
{
    const rs_subsystem_t *s = &g->c->subs[a];
    pos_t p = pos_of(&s->intloc);
    fmpq_t tq;
    rs_expr_t *tt = NULL, *e = NULL;
    slong j, i;
    fmpq_init(tq);
    fmpq_one(tq);
    if (g->stage >= 0) {   /* c_i = sum_l a_il (over Q(sqrt d): a tree) */
        const rs_tableau_struct *t = &g->tab[a];
        fmpq_t t1;
        fmpq_init(t1);
        fmpq_zero(tq);
        for (i = 0; i < t->s; i++) fmpq_add(tq, tq, t->A + g->stage * t->s + i);
        for (i = 0; t->d && i < t->s; i++) fmpq_add(t1, t1, t->A1 + g->stage * t->s + i);
        if (!fmpq_is_zero(t1)) tt = qd_tree(tq, t1, t->d, p);
        fmpq_clear(t1);
    } else if (g->mix && (tt = alpha_f(s, p)) != NULL) {
        tt = P(op(RS_EXPR_SUB, num(1, p), tt, p));
    }
    for (j = 0; j <= g->corder; j++) {
        rs_expr_t *v = fe ? at_shift(g, fe, node_shift(g, j), err) : seq(name, node_shift(g, j), at), *b, *t;
        if (v == NULL) { rs_expr_free(e); e = NULL; break; }
        b = basis(g, j, tq, tt, p);
        t = op(RS_EXPR_MUL, b, P(v), at);
        e = e == NULL ? t : op(RS_EXPR_ADD, e, t, at);
    }
    rs_expr_free(tt);
    fmpq_clear(tq);
    return e == NULL ? NULL : P(e);
}

static slong force_index(const rs_case_struct *c, const char *name)
{
    slong i;
    for (i = 0; i < c->nforces; i++)
        if (strcmp(c->forces[i].name, name) == 0) return i;
    return -1;
}

/* a name of the right-hand side of subsystem a, iterate j, resolved to a
 * sequence (NULL and err set on an error, at the node) */
static rs_expr_t *subst_leaf(const gen_t *g, slong a, slong j, const rs_expr_t *e, rs_error_t err)
{
    const rs_case_struct *c = g->c;
    rs_expr_t *out;
    slong sa, sk, li;
    pos_t at = pos_node(e);
    if (e->kind == RS_EXPR_NAME && e->shifted) {
        rs_error_set_at(err, RS_ERR_INPUT, e->file, e->line, e->col,
                        "state equations are written without shifts; found '%s['", e->name);
        return NULL;
    }
    /* explicit/implicit coupling: partner states and forces are coupling variables */
    int pst = g->kind >= 3 && e->kind == RS_EXPR_NAME && find_state(c, e->name, &sa, &sk) && sa != a;
    slong fi = g->kind >= 3 && e->kind == RS_EXPR_NAME && !pst ? force_index(c, e->name) : -1;
    if (pst || fi >= 0) {
        out = coupled(g, a, e->name, pst ? NULL : c->forces[fi].e, at, err);
    } else if (e->kind == RS_EXPR_NAME && find_state(c, e->name, &sa, &sk))
        out = sa == a || ((g->stage >= 0 || g->mix) && same_method(g, a, sa)) ? own(g, sa, e->name, j, at)
            : partner(g, e->name, a, sa, j, at);
    else if (e->kind == RS_EXPR_NAME && (li = rs_case_let_index(c, e->name)) >= 0)
        out = c->lets[li].shifted ? seq(e->name, 1, at) : rs_expr_new_name(e->name, 0, 0, at.file, at.line, at.col);
    else if (e->kind == RS_EXPR_NAME && rs_case_param_index(c, e->name) >= 0)
        out = rs_expr_new_name(e->name, 0, 0, at.file, at.line, at.col);
    else {
        rs_error_set_at(err, RS_ERR_INPUT, e->file, e->line, e->col,
                        "unknown name '%s' in the state equation (expected a state, param or let)", e->name);
        return NULL;
    }
    return out;
}

/* a copy of the right-hand side e of subsystem a, iterate j, with every name
 * resolved to a sequence; NULL and err set on an error (at the node) */
static rs_expr_t *subst(const gen_t *g, slong a, slong j, const rs_expr_t *e, rs_error_t err)
{
    return map_tree(g, a, j, e, subst_leaf, err);
}

/* appends the generated equation lhs = rhs to the model */
static void add_eq(rs_model_struct *m, rs_expr_t *lhs, rs_expr_t *rhs, const rs_loc_t *loc)
{
    rs_lower_add_eq(m, lhs, rhs, loc, NULL);
}

int rs_builder_is_exact(const rs_case_t c)
{
    slong i;
    for (i = 0; i < c->nsubs; i++)
        if (c->subs[i].method && strcmp(c->subs[i].method, "exact") == 0) return 1;
    return 0;
}

static int err_at(rs_error_t err, int code, const rs_loc_t *l, int col, const char *fmt, const char *a)
{
    return rs_error_set_at(err, code, l->file, l->line, col > 0 ? col : l->col, fmt, a);
}

/* every subsystem integrated; exact integration all or nothing.  *exact: the
 * case is co-simulation (lowered by analysis_cosim.c, not into equations) */
static int check_subsystems(const rs_case_struct *c, int *exact, rs_error_t err)
{
    slong a;
    char msg[64];
    for (a = 0; a < c->nsubs; a++) {
        if (c->subs[a].method == NULL)
            return err_at(err, RS_ERR_INPUT, &c->subs[a].loc, 0, "expected `integrate %s METHOD STEP` for this subsystem",
                          c->subs[a].name);
        snprintf(msg, sizeof msg, "%d", MAX_STATES);
        if (c->subs[a].nstates > MAX_STATES)
            return err_at(err, RS_ERR_LIMIT, &c->subs[a].loc, 1, "too many states in one subsystem (limit %s)", msg);
    }
    *exact = rs_builder_is_exact(c);
    if (!*exact) return RS_OK;
    for (a = 0; a < c->nsubs; a++)
        if (strcmp(c->subs[a].method, "exact") != 0)
            return err_at(err, RS_ERR_INPUT, &c->subs[a].intloc, 0,
                          "exact integration is supported when every subsystem uses it (found %s)", c->subs[a].method);
    /* coupling forces are optional: displacement coupling uses the partner's states */
    if (c->couple == NULL || !(strcmp(c->couple, "explicit") == 0 || strcmp(c->couple, "implicit") == 0))
        return err_at(err, RS_ERR_INPUT, &c->subs[0].loc, 1,
                      "exact integration needs `couple explicit|implicit order K` (and the coupling: "
                      "`coupling force NAME = EXPR` lines and/or the partner's states)%s", "");
    return RS_OK;
}

static int coupling_kind(gen_t *g, const rs_case_struct *c, rs_error_t err)
{
    if (c->couple && (strcmp(c->couple, "explicit") == 0 || strcmp(c->couple, "implicit") == 0)) {
        g->kind = strcmp(c->couple, "explicit") == 0 ? 3 : 4;
        g->corder = c->couple_order;
        g->K = 0;
        if (c->couple_ext)
            return err_at(err, RS_ERR_INPUT, &c->couple_loc, 0, "the extension couplings are defined for subsystems "
                          "integrated exactly (`integrate S exact H`)%s", "");
        if (c->couple_order > RS_CASE_MAX_EXTRAPOLATE)
            return err_at(err, RS_ERR_INPUT, &c->couple_loc, 0, "coupling order too high (limit 6)%s", "");
        if (c->iterations > 0 || c->extrapolate >= 0)
            return err_at(err, RS_ERR_INPUT, &c->couple_loc, 0, "couple %s order K has its own polynomials: "
                          "`iterations` and `extrapolate` apply to jacobi and gauss-seidel", c->couple);
        return RS_OK;
    }
    if (c->nsubs == 1 || (c->couple && strcmp(c->couple, "monolithic") == 0)) g->kind = 0;
    else if (c->couple == NULL) {
        char msg[256];
        snprintf(msg, sizeof msg, "expected a `couple` statement (jacobi, gauss-seidel S1 S2, monolithic) for %ld "
                 "subsystems", (long) c->nsubs);
        return err_at(err, RS_ERR_INPUT, &c->subs[0].loc, 1, "%s", msg);
    } else if (strcmp(c->couple, "jacobi") == 0) g->kind = 1;
    else {
        slong i, b;
        char msg[160];
        g->kind = 2;
        for (i = 0; i < c->nsubs; i++) g->rank[i] = -1;
        for (i = 0; i < c->ncouple_seq; i++) {
            if ((b = sub_index(c, c->couple_seq[i])) < 0)
                return err_at(err, RS_ERR_INPUT, &c->couple_loc, 0, "gauss-seidel: '%s' is not a declared subsystem",
                              c->couple_seq[i]);
            if (g->rank[b] >= 0)
                return err_at(err, RS_ERR_INPUT, &c->couple_loc, 0, "gauss-seidel: subsystem '%s' is named twice",
                              c->couple_seq[i]);
            g->rank[b] = i;
        }
        for (i = 0; i < c->nsubs; i++)
            if (g->rank[i] < 0) {
                snprintf(msg, sizeof msg, "gauss-seidel names every subsystem in the order they are integrated "
                         "(%ld declared); missing: %s", (long) c->nsubs, c->subs[i].name);
                return err_at(err, RS_ERR_INPUT, &c->couple_loc, 0, "%s", msg);
            }
    }
    g->K = g->kind == 0 ? 0 : c->iterations;
    return RS_OK;
}

/* the (position, velocity) pairs of subsystem a: X'' = F lines make X' = V
 * with V the next state; X' = V with V a state (compared as trees, so
 * X' = (V) too) pairs them as well */
static int find_pairs(gen_t *g, slong a, rs_error_t err)
{
    const rs_subsystem_t *s = &g->c->subs[a];
    slong *vel = g->vel + a * MAX_STATES, j, k, si;
    char msg[256];
    for (k = 0; k < MAX_STATES; k++) vel[k] = -1;
    g->pair[a] = strcmp(s->method, "newmark") == 0 || strcmp(s->method, "central-difference") == 0 || is_alpha(s);
    for (j = 0; j < s->ndeqs; j++) {
        const rs_deq_t *d = &s->deqs[j];
        if ((si = state_index(s, d->state)) < 0) {
            snprintf(msg, sizeof msg, "'%s' is not a state of subsystem %s", d->state, s->name);
            return err_at(err, RS_ERR_INPUT, &d->loc, 0, "%s", msg);
        }
        if (d->order == 2) {
            if (si + 1 >= s->nstates)
                return err_at(err, RS_ERR_INPUT, &d->loc, 0, "declare the velocity state right after %s (subsystem ... "
                              "state X V) for a second-order equation", d->state);
            vel[si] = si + 1;
        }
    }
    for (j = 0; j < s->ndeqs; j++) {
        const rs_expr_t *e = s->deqs[j].rhs;
        if (s->deqs[j].order != 1 || e->kind != RS_EXPR_NAME || e->shifted) continue;
        si = state_index(s, s->deqs[j].state);
        k = state_index(s, e->name);
        if (k >= 0 && k != si) vel[si] = k;
    }
    if (!g->pair[a]) return RS_OK;
    if (g->K > 0 && is_alpha(s))
        return err_at(err, RS_ERR_INPUT, &s->intloc, 0, "iterations with %s are not supported (where the iterates "
                      "enter its intermediate time t[n+1-alpha_f] is not defined by recstab)", s->method);
    for (k = 0; k < s->nstates; k++) {
        int isvel = 0;
        slong q;
        for (q = 0; q < s->nstates; q++) if (vel[q] == k) isvel = 1;
        if (vel[k] < 0 && !isvel) {
            snprintf(msg, sizeof msg, "%s integrates (position, velocity) pairs: write X'' = ... or X' = V for "
                     "every position (state %s)", s->method, s->states[k].name);
            return err_at(err, RS_ERR_INPUT, &s->intloc, 0, "%s", msg);
        }
    }
    return RS_OK;
}

/* the user's declaration of name (param, unknown or let), or NULL */
static const rs_loc_t *user_decl(const rs_case_struct *c, const char *name)
{
    slong i;
    if ((i = rs_case_param_index(c, name)) >= 0) return &c->params[i].loc;
    if ((i = rs_case_unknown_index(c, name)) >= 0) return &c->unknowns[i].loc;
    if ((i = rs_case_let_index(c, name)) >= 0) return &c->lets[i].loc;
    return NULL;
}

/* appends the generated unknown name (for state st of subsystem s) to the
 * model: an error at the user's declaration when the user took that name */
static int add_unknown(rs_model_struct *m, const rs_case_struct *c, const char *name, const rs_subsystem_t *s,
                       const rs_name_t *st, rs_error_t err)
{
    const rs_loc_t *u;
    if (rs_name_is_reserved(name))
        return rs_error_set_at(err, RS_ERR_INPUT, st->loc.file, st->loc.line, st->loc.col,
                               "'%s' is reserved (%s); choose another name", name, rs_name_reserved_why(name));
    if ((u = user_decl(c, name)) != NULL)
        return rs_error_set_at(err, RS_ERR_INPUT, u->file, u->line, u->col,
                               "'%s' is also a name the builders generate (for state %s of subsystem %s); choose "
                               "another name", name, st->name, s->name);
    if (rs_model_unknown_index(m, name) >= 0)   /* two subsystems with one state name */
        return err_at(err, RS_ERR_INPUT, &st->loc, 0, "'%s' is already declared", name);
    if (c->nparams + m->nunknowns + c->nlets >= RS_CASE_MAX_NAMES)
        return err_at(err, RS_ERR_LIMIT, &st->loc, 0, "too many names (limit %s)", "256");
    rs_lower_add_unknown(m, name, &st->loc);
    if (m->unknown_loc.file == NULL) rs_lower_loc_copy(&m->unknown_loc, &st->loc);
    return RS_OK;
}

/* every state (and the derivative of each state that is not a position of
 * a pair) in every iterate */
static int gen_unknowns(const gen_t *g, rs_error_t err)
{
    const rs_case_struct *c = g->c;
    slong a, k, j, i;
    char b[96];
    int r = RS_OK;
    for (a = 0; a < c->nsubs && r == RS_OK; a++) {
        const rs_subsystem_t *s = &c->subs[a];
        for (k = 0; k < s->nstates && r == RS_OK; k++)
            for (j = 0; j <= g->K && r == RS_OK; j++) {
                var_name(b, sizeof b, s->states[k].name, j, g->K);
                r = add_unknown(g->m, c, b, s, &s->states[k], err);
                if (r == RS_OK && !is_pos(g, a, k)) {
                    dvar_name(b, sizeof b, s->states[k].name, j, g->K);
                    r = add_unknown(g->m, c, b, s, &s->states[k], err);
                }
                for (i = 0; i < g->tab[a].s && r == RS_OK; i++) {
                    stage_name(b, sizeof b, s->states[k].name, i + 1, j, g->K);
                    r = add_unknown(g->m, c, b, s, &s->states[k], err);
                }
            }
    }
    return r;
}

/* Newmark's update of the pair (x, v) of iterate j (of K) with parameter trees B, G (consumed) */
static void newmark_update(rs_model_struct *m, const rs_subsystem_t *s, const char *x, const char *v, rs_expr_t *B,
                           rs_expr_t *G, slong j, slong K, pos_t p)
{
    const rs_expr_t *h = s->step;
    rs_expr_t *acc = P(op(RS_EXPR_ADD,
                          op(RS_EXPR_MUL, P(op(RS_EXPR_SUB, op(RS_EXPR_DIV, num(1, p), num(2, p), p), P(copy(B)), p)),
                             dot(v, 0, p), p),
                          op(RS_EXPR_MUL, P(B), dvar(v, j, K, 1, p), p), p));
    add_eq(m, var(x, j, K, 1, p),
           op(RS_EXPR_ADD, op(RS_EXPR_ADD, seq(x, 0, p), op(RS_EXPR_MUL, P(copy(h)), seq(v, 0, p), p), p),
              op(RS_EXPR_MUL, op(RS_EXPR_POW, P(copy(h)), num(2, p), p), acc, p), p), &s->intloc);
    acc = P(op(RS_EXPR_ADD, op(RS_EXPR_MUL, P(op(RS_EXPR_SUB, num(1, p), P(copy(G)), p)), dot(v, 0, p), p),
               op(RS_EXPR_MUL, P(G), dvar(v, j, K, 1, p), p), p));
    add_eq(m, var(v, j, K, 1, p), op(RS_EXPR_ADD, seq(v, 0, p), op(RS_EXPR_MUL, P(copy(h)), acc, p), p), &s->intloc);
}

/* the integration formula of a (position x, velocity v) pair in iterate j (of K) */
static void pair_formula(rs_model_struct *m, const rs_subsystem_t *s, const char *x, const char *v, slong j, slong K)
{
    pos_t p = pos_of(&s->intloc);
    const rs_expr_t *h = s->step;
    if (is_alpha(s)) {
        /* Newmark's update with gamma = 1/2 - alpha_m + alpha_f, beta = (1 - alpha_m + alpha_f)^2/4 */
        rs_expr_t *G = op(RS_EXPR_DIV, num(1, p), num(2, p), p), *B = num(1, p), *am = alpha_m(s, p), *af = alpha_f(s, p);
        if (am) { G = op(RS_EXPR_SUB, G, am, p); B = op(RS_EXPR_SUB, B, alpha_m(s, p), p); }
        if (af) { G = op(RS_EXPR_ADD, G, af, p); B = op(RS_EXPR_ADD, B, alpha_f(s, p), p); }
        B = op(RS_EXPR_DIV, op(RS_EXPR_POW, P(B), num(2, p), p), num(4, p), p);
        newmark_update(m, s, x, v, B, G, j, K, p);
    } else if (strcmp(s->method, "newmark") == 0) {
        /* X[n+1] = x[n] + (h)*v[n] + (h)^2*((1/2 - (B))*v_dot[n] + (B)*V_dot[n+1]),
         * V[n+1] = v[n] + (h)*((1 - (G))*v_dot[n] + (G)*V_dot[n+1]); X, V the iterate's */
        rs_expr_t *acc = P(op(RS_EXPR_ADD,
                              op(RS_EXPR_MUL, P(op(RS_EXPR_SUB, op(RS_EXPR_DIV, num(1, p), num(2, p), p), P(copy(s->arg1)), p)),
                                 dot(v, 0, p), p),
                              op(RS_EXPR_MUL, P(copy(s->arg1)), dvar(v, j, K, 1, p), p), p));
        add_eq(m, var(x, j, K, 1, p),
               op(RS_EXPR_ADD, op(RS_EXPR_ADD, seq(x, 0, p), op(RS_EXPR_MUL, P(copy(h)), seq(v, 0, p), p), p),
                  op(RS_EXPR_MUL, op(RS_EXPR_POW, P(copy(h)), num(2, p), p), acc, p), p), &s->intloc);
        acc = P(op(RS_EXPR_ADD, op(RS_EXPR_MUL, P(op(RS_EXPR_SUB, num(1, p), P(copy(s->arg2)), p)), dot(v, 0, p), p),
                   op(RS_EXPR_MUL, P(copy(s->arg2)), dvar(v, j, K, 1, p), p), p));
        add_eq(m, var(v, j, K, 1, p), op(RS_EXPR_ADD, seq(v, 0, p), op(RS_EXPR_MUL, P(copy(h)), acc, p), p), &s->intloc);
    } else {
        /* central difference: X[n+1] - 2*x[n] + x[n-1] = (h)^2*V_dot[n], 2*(h)*V[n] = X[n+1] - x[n-1].
         * The step producing x[n+1] solves for x[n+1], v[n] and a[n] = v_dot[n] together (a[n]
         * depends on v[n] through damping or a velocity coupling), so these are the iterate's
         * unknowns X, V, V_dot; x[n] and x[n-1] are final (see cd_pos) */
        add_eq(m, op(RS_EXPR_ADD, op(RS_EXPR_SUB, var(x, j, K, 1, p), op(RS_EXPR_MUL, num(2, p), seq(x, 0, p), p), p),
                     seq(x, -1, p), p),
               op(RS_EXPR_MUL, op(RS_EXPR_POW, P(copy(h)), num(2, p), p), dvar(v, j, K, 0, p), p), &s->intloc);
        add_eq(m, op(RS_EXPR_MUL, op(RS_EXPR_MUL, num(2, p), P(copy(h)), p), var(v, j, K, 0, p), p),
               op(RS_EXPR_SUB, var(x, j, K, 1, p), seq(x, -1, p), p), &s->intloc);
    }
}

/* D*(X[n+1] - x[n]) = (h)*(...) or sum c_i x[n+1-i] = D*(h)*DX[n+1] with
 * integer coefficients (D clears the denominators) for rk (the stages
 * b_i x_ki[n+1]), adams-bashforth K (x_dot[n-i]), adams-moulton K (DX[n+1],
 * x_dot[n+1-i]) and bdf K; X, DX and h are consumed */
static void multistep_formula(rs_model_struct *mod, const gen_t *g, const rs_subsystem_t *s, const char *x, slong j,
                              rs_expr_t *X, rs_expr_t *DX, rs_expr_t *h, pos_t p)
{
    const char *m = s->method;
    slong k = s->korder, n, i, a = s - g->c->subs;
    fmpq *c = _fmpq_vec_init(RS_METHODS_MAX_STAGES + 2), *c1 = NULL;   /* c + sqrt(d) c1 */
    slong d = 0;
    rs_expr_t *t[RS_METHODS_MAX_STAGES + 2], *lhs, *rhs;
    fmpz_t D;
    fmpz_init(D);
    if (strcmp(m, "rk") == 0) {
        n = g->tab[a].s;
        for (i = 0; i < n; i++) fmpq_set(c + i, g->tab[a].b + i);
        for (i = 0; i < n; i++) t[i] = stage_var(x, i + 1, j, g->K, p);
        if ((d = g->tab[a].d) != 0) {
            c1 = _fmpq_vec_init(n);
            for (i = 0; i < n; i++) fmpq_set(c1 + i, g->tab[a].b1 + i);
        }
    } else if (strcmp(m, "bdf") == 0) {
        n = k + 1;
        rs_methods_bdf(c, k);
        t[0] = X;
        for (i = 1; i < n; i++) t[i] = seq(x, 1 - i, p);
    } else {
        int implicit = strcmp(m, "adams-moulton") == 0;
        n = implicit ? k + 1 : k;
        rs_methods_adams(c, k, implicit);
        for (i = 0; i < n; i++) t[i] = implicit && i == 0 ? DX : dot(x, implicit ? 1 - i : -i, p);
    }
    fmpz_one(D);
    for (i = 0; i < n; i++) fmpz_lcm(D, D, fmpq_denref(c + i));
    for (i = 0; c1 != NULL && i < n; i++) fmpz_lcm(D, D, fmpq_denref(c1 + i));
    for (i = 0; i < n; i++) fmpq_mul_fmpz(c + i, c + i, D);
    for (i = 0; c1 != NULL && i < n; i++) fmpq_mul_fmpz(c1 + i, c1 + i, D);
    if (strcmp(m, "bdf") == 0) {
        lhs = lincomb(c, NULL, 0, t, n, p);
        rhs = op(RS_EXPR_MUL, h, DX, p);
        if (!fmpz_is_one(D)) rhs = op(RS_EXPR_MUL, num(fmpz_get_si(D), p), rhs, p);
    } else {
        lhs = op(RS_EXPR_SUB, X, seq(x, 0, p), p);
        if (!fmpz_is_one(D)) lhs = op(RS_EXPR_MUL, num(fmpz_get_si(D), p), P(lhs), p);
        rhs = op(RS_EXPR_MUL, h, P(lincomb(c, c1, d, t, n, p)), p);
        if (strcmp(m, "adams-bashforth") == 0 || strcmp(m, "rk") == 0) rs_expr_free(DX);
    }
    add_eq(mod, lhs, rhs, &s->intloc);
    _fmpq_vec_clear(c, RS_METHODS_MAX_STAGES + 2);
    if (c1 != NULL) _fmpq_vec_clear(c1, n);
    fmpz_clear(D);
}

/* the one-step integration formula of state x in iterate j:
 * X[n+1] - x[n] = ... with X the iterate's unknown, DX its derivative */
static void formula(rs_model_struct *mod, const gen_t *g, const rs_subsystem_t *s, const char *x, slong j)
{
    pos_t p = pos_of(&s->intloc);
    const char *m = s->method;
    rs_expr_t *X = var(x, j, g->K, 1, p), *DX = dvar(x, j, g->K, 1, p), *h = P(copy(s->step));
    if (strcmp(m, "euler-forward") == 0 || strcmp(m, "euler-backward") == 0) {
        if (strcmp(m, "euler-forward") == 0) { rs_expr_free(DX); DX = dot(x, 0, p); }
        add_eq(mod, op(RS_EXPR_SUB, X, seq(x, 0, p), p), op(RS_EXPR_MUL, h, DX, p), &s->intloc);
    } else if (strcmp(m, "trapezoidal") == 0 || strcmp(m, "theta") == 0) {
        /* (h)*((1 - (T))*x_dot[n] + (T)*DX[n+1]), T = 1/2 for the trapezoidal rule */
        rs_expr_t *T1, *T2;
        if (strcmp(m, "theta") == 0) { T1 = copy(s->arg1); T2 = copy(s->arg1); }
        else { T1 = op(RS_EXPR_DIV, num(1, p), num(2, p), p); T2 = op(RS_EXPR_DIV, num(1, p), num(2, p), p); }
        add_eq(mod, op(RS_EXPR_SUB, X, seq(x, 0, p), p),
               op(RS_EXPR_MUL, h, P(op(RS_EXPR_ADD, op(RS_EXPR_MUL, P(op(RS_EXPR_SUB, num(1, p), P(T1), p)), dot(x, 0, p), p),
                                       op(RS_EXPR_MUL, P(T2), DX, p), p)), p), &s->intloc);
    } else if (strcmp(m, "bdf2") == 0) {
        /* X[n+1]*3 - 4*x[n] + x[n-1] = 2*(h)*DX[n+1] */
        add_eq(mod, op(RS_EXPR_ADD, op(RS_EXPR_SUB, op(RS_EXPR_MUL, X, num(3, p), p),
                                     op(RS_EXPR_MUL, num(4, p), seq(x, 0, p), p), p), seq(x, -1, p), p),
               op(RS_EXPR_MUL, op(RS_EXPR_MUL, num(2, p), h, p), DX, p), &s->intloc);
    } else if (strcmp(m, "leapfrog") == 0) {
        /* X[n+1] - x[n-1] = 2*(h)*x_dot[n] */
        rs_expr_free(DX);
        add_eq(mod, op(RS_EXPR_SUB, X, seq(x, -1, p), p), op(RS_EXPR_MUL, op(RS_EXPR_MUL, num(2, p), h, p), dot(x, 0, p), p),
               &s->intloc);
    } else if (strcmp(m, "rk") == 0 || strncmp(m, "adams-", 6) == 0 || strcmp(m, "bdf") == 0) {
        multistep_formula(mod, g, s, x, j, X, DX, h, p);
    } else {
        /* bdf3: X[n+1]*11 - 18*x[n] + 9*x[n-1] - 2*x[n-2] = 6*(h)*DX[n+1] */
        rs_expr_t *l = op(RS_EXPR_SUB, op(RS_EXPR_MUL, X, num(11, p), p), op(RS_EXPR_MUL, num(18, p), seq(x, 0, p), p), p);
        l = op(RS_EXPR_ADD, l, op(RS_EXPR_MUL, num(9, p), seq(x, -1, p), p), p);
        l = op(RS_EXPR_SUB, l, op(RS_EXPR_MUL, num(2, p), seq(x, -2, p), p), p);
        add_eq(mod, l, op(RS_EXPR_MUL, op(RS_EXPR_MUL, num(6, p), h, p), DX, p), &s->intloc);
    }
}

/* the state equation giving the derivative of state k (that of X'' = F
 * for the velocity of X), or NULL */
static const rs_deq_t *deq_of(const gen_t *g, slong a, slong k)
{
    const rs_subsystem_t *s = &g->c->subs[a];
    const rs_deq_t *d = NULL;
    slong q, e;
    for (q = 0; q < s->ndeqs; q++)
        if (strcmp(s->deqs[q].state, s->states[k].name) == 0 && s->deqs[q].order == 1) d = &s->deqs[q];
    for (q = 0; q < s->nstates; q++)
        if (g->vel[a * MAX_STATES + q] == k)
            for (e = 0; e < s->ndeqs; e++)
                if (s->deqs[e].order == 2 && strcmp(s->deqs[e].state, s->states[q].name) == 0) d = &s->deqs[e];
    return d;
}

/* the equations of subsystem a in iterate j */
static int gen_equations(gen_t *g, slong a, slong j, rs_error_t err)
{
    const rs_case_struct *c = g->c;
    const rs_subsystem_t *s = &c->subs[a];
    slong k, vk, i;
    for (k = 0; k < s->nstates; k++) {
        const char *x = s->states[k].name;
        const rs_deq_t *d = deq_of(g, a, k);
        vk = g->vel[a * MAX_STATES + k];
        if (d == NULL && vk < 0)
            return err_at(err, RS_ERR_INPUT, &s->loc, 0, "expected an equation %s' = ... in this subsystem", x);
        /* equation of motion at the new time */
        if (!is_pos(g, a, k)) {
            rs_expr_t *rhs, *lhs = dvar(x, j, g->K, 1, d ? pos_of(&d->loc) : pos_of(&s->loc)), *am;
            if (d == NULL) {   /* x' = v of a second-order line */
                rhs = var(s->states[vk].name, j, g->K, 1, pos_of(&s->loc));
            } else {
                g->mix = is_alpha(s);   /* the alpha methods: F at (1 - alpha_f) t[n+1] + alpha_f t[n] */
                rhs = subst(g, a, j, d->rhs, err);
                g->mix = 0;
                if (rhs == NULL) { rs_expr_free(lhs); return err->code; }
                P(rhs);
            }
            if (is_alpha(s) && (am = alpha_m(s, pos_of(&s->intloc))) != NULL) {
                /* (1 - alpha_m)*x_dot[n+1] + alpha_m*x_dot[n] */
                pos_t p = pos_of(&s->intloc);
                lhs = op(RS_EXPR_ADD, op(RS_EXPR_MUL, P(op(RS_EXPR_SUB, num(1, p), am, p)), lhs, p),
                         op(RS_EXPR_MUL, alpha_m(s, p), dot(x, 0, p), p), p);
            }
            add_eq(g->m, lhs, rhs, d ? &d->loc : &s->loc);
            /* Runge-Kutta stages: x_ki[n+1] = f at the stage values */
            for (i = 0; i < g->tab[a].s; i++) {
                g->stage = i;   /* x' = v of a second-order line: v's stage value */
                rhs = d ? subst(g, a, j, d->rhs, err) : own(g, a, s->states[vk].name, j, pos_of(&s->loc));
                g->stage = -1;
                if (rhs == NULL) return err->code;
                add_eq(g->m, stage_var(x, i + 1, j, g->K, d ? pos_of(&d->loc) : pos_of(&s->loc)), rhs->paren ? rhs : P(rhs),
                       d ? &d->loc : &s->loc);
            }
        }
        if (g->pair[a]) {
            if (vk >= 0) pair_formula(g->m, s, x, s->states[vk].name, j, g->K);   /* velocities go with their position */
        } else {
            formula(g->m, g, s, x, j);
        }
    }
    return RS_OK;
}

/* A tableau whose R is not in Q(z) (sdirk2): its stage equations are
 * written with the exact constant sqrt(d) (qd_tree), which the scheme
 * evaluates as a variable s reduced by s^2 = d, so the characteristic
 * polynomial is p0 + sqrt(d) p1 (lower/scheme.c, algebra/charpoly.c) and
 * the analyses run over Q(sqrt d) (analysis/an_qd.c).  model.h's qd records
 * d and R = N/D of the tableau (the cross-check on the test equation).  One
 * d per case: two different irrational fields are refused. */
static int tableau_qd(rs_tableau_struct *t, rs_model_struct *m, const rs_subsystem_t *s, rs_error_t err)
{
    rs_model_qd_struct *qd;
    slong d;
    rs_tableau_named_qd(t, s->tableau);
    if (m->qd != NULL) {
        if (m->qd->d == t->d) return RS_OK;
        return err_at(err, RS_ERR_INPUT, &s->intloc, 0, "expected one irrational field per case: %s has "
                      "entries in another Q(sqrt d) than an earlier tableau", s->tableau);
    }
    qd = flint_calloc(1, sizeof *qd);
    fmpq_poly_init(qd->n0);
    fmpq_poly_init(qd->n1);
    fmpq_poly_init(qd->d0);
    fmpq_poly_init(qd->d1);
    rs_lower_loc_copy(&qd->loc, &s->intloc);
    qd->tableau = flint_malloc(strlen(s->tableau) + 1);
    strcpy(qd->tableau, s->tableau);
    m->qd = qd;   /* cleared with the model from here on */
    if (!rs_methods_rk_stability_named_qd(qd->n0, qd->n1, qd->d0, qd->d1, &d, s->tableau) || d < 2 || d != t->d)
        return err_at(err, RS_ERR_INTERNAL, &s->intloc, 0, "no stability function over Q(sqrt d) for %s",
                      s->tableau);
    qd->d = d;
    return RS_OK;
}

/* the Butcher tableau of subsystem s (none: 0 stages) */
static int tableau_of(rs_tableau_struct *t, rs_model_struct *m, const rs_subsystem_t *s, rs_error_t err)
{
    slong n, i;
    rs_tableau_init(t, 0);
    if (strcmp(s->method, "rk") != 0) return RS_OK;
    if (s->tableau) {
        if (rs_tableau_named(t, s->tableau) == 1) return RS_OK;
        return tableau_qd(t, m, s, err);
    }
    for (n = 1; n * n + n < s->ntab; n++) ;
    rs_tableau_clear(t);
    rs_tableau_init(t, n);
    for (i = 0; i < n * n; i++) fmpq_set(t->A + i, s->tab + i);
    for (i = 0; i < n; i++) fmpq_set(t->b + i, s->tab + n * n + i);
    return RS_OK;
}

int rs_builder_lower(rs_model_struct *m, rs_error_t err)
{
    const rs_case_struct *c = m->c;
    gen_t g;
    slong a, j;
    int r, exact;
    if (c->nsubs == 0) return RS_OK;
    r = check_subsystems(c, &exact, err);
    if (r == RS_OK && exact) m->kind = RS_MODEL_COSIM;
    if (r != RS_OK || exact) return r;
    memset(&g, 0, sizeof g);
    g.c = c;
    g.m = m;
    g.stage = -1;
    g.rank = flint_malloc(c->nsubs * sizeof(slong));
    r = coupling_kind(&g, c, err);
    if (r != RS_OK) { flint_free(g.rank); return r; }
    g.vel = flint_malloc(c->nsubs * MAX_STATES * sizeof(slong));
    g.pair = flint_calloc(c->nsubs, sizeof(int));
    g.tab = flint_calloc(c->nsubs, sizeof(rs_tableau_struct));
    for (a = 0; a < c->nsubs; a++) rs_tableau_init(&g.tab[a], 0);
    for (a = 0; a < c->nsubs && r == RS_OK; a++) {
        rs_tableau_clear(&g.tab[a]);
        r = tableau_of(&g.tab[a], m, &c->subs[a], err);
    }
    for (a = 0; a < c->nsubs && r == RS_OK; a++)
        r = find_pairs(&g, a, err);
    if (r == RS_OK) r = gen_unknowns(&g, err);
    for (a = 0; a < c->nsubs && r == RS_OK; a++)
        for (j = 0; j <= g.K && r == RS_OK; j++)
            r = gen_equations(&g, a, j, err);
    for (a = 0; a < c->nsubs; a++) rs_tableau_clear(&g.tab[a]);
    flint_free(g.tab);
    flint_free(g.vel);
    flint_free(g.pair);
    flint_free(g.rank);
    return r;
}
