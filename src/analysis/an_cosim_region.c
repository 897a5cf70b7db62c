/* an_cosim_region.c -- region and claim for schemes whose subsystems are
 * integrated exactly (matrix exponentials: no exact side, so every verdict
 * here is a certificate over a whole parameter box, never a sample):
 *
 *   region NAME from A to B [digits=N]
 *   claim stable|bounded|unstable when A <= NAME <= B [and A2 <= NAME2 <= B2 ...]
 *
 * A box of parameter values is evaluated ONCE in ball arithmetic: the
 * linear forms of the model (lower/cosim_model.h) with the box's balls
 * substituted give A_i, B_i, C, H as balls containing the matrices of every
 * model in the box, and cosim.c's engine gives one ball one-step map M
 * containing all of theirs (arb_mat_exp encloses e^X for every X in the
 * ball).  A Stein certificate for the ball (rs_cosim_ball_stein) then proves
 * rho < 1 (or rho > 1) at every point of the box.  Boxes that certify
 * neither are bisected.
 *
 * region: the interval is bisected breadth first; what is left undecided
 * are runs of small boxes.  A run narrower than 10^-N between a stable and
 * an unstable run is a certified transition: every point outside it is
 * certified, so the stability boundary lies inside the run (its enclosure),
 * and no other crossing exists outside the enclosures.  Anything else (a
 * run wider than 10^-N when the level cap or budget is reached, a run
 * between two runs of the same verdict where rho touches 1, a run at an end
 * of [A, B]) is reported "unseparated", never guessed.
 *
 * claim: the box is bisected along its widest side; every sub-box certified
 * stable proves `claim stable`; a certified point (the exact model at a
 * rational point, rs_cosim_radius) refutes it; the first sub-box that is
 * still undecided at the depth limit is named.
 *
 * claim bounded: bounded also holds with rho = 1 when every unit-circle
 * eigenvalue is semisimple, which no ball certificate can show (rho = 1 is
 * not an open condition).  What is sound: proved when rho < 1 is certified
 * on every sub-box (then bounded holds); refuted by a certified point with
 * rho > 1 (checked at the centre of every undecided box); undecided, naming
 * the sub-box, when its centre's certified radius contains 1 (rho = 1 there
 * to 6 digits: no box around it certifies rho < 1, and whether the circle
 * eigenvalues are semisimple is not decided here) or the box limit is
 * reached. */
#include <string.h>
#include <stdlib.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpq_vec.h>
#include "analysis/impl.h"
#include "analysis/registry.h"
#include "lower/cosim_model.h"
#include "numeric/cosim_ball.h"
#include "recstab/budget.h"
#include "recstab/cosim.h"

#define BOX_MAX_AXES 8
#define REGION_MAX_UNDECIDED 1024   /* undecided boxes per bisection level */
#define CLAIM_MAX_BOXES 4096

typedef struct {
    slong naxes;
    char name[BOX_MAX_AXES][80];
    const char *at[BOX_MAX_AXES];   /* the name in the request text */
    fmpq_t lo[BOX_MAX_AXES], hi[BOX_MAX_AXES];
    slong digits;                   /* region */
    int unstable;                   /* claim: the claimed verdict is unstable */
    int bounded;                    /* claim bounded: proved where rho < 1 is certified */
} box_req_t;

static box_req_t *box_req_new(rs_an_req_t *req)
{
    box_req_t *b = calloc(1, sizeof *b);
    slong i;
    for (i = 0; i < BOX_MAX_AXES; i++) {
        fmpq_init(b->lo[i]);
        fmpq_init(b->hi[i]);
    }
    req->u.cosim = b;
    return b;
}

void rs_an_cosim_box_req_clear(rs_an_req_t *req)
{
    box_req_t *b = req->u.cosim;
    slong i;
    if (b == NULL) return;
    for (i = 0; i < BOX_MAX_AXES; i++) {
        fmpq_clear(b->lo[i]);
        fmpq_clear(b->hi[i]);
    }
    free(b);
    req->u.cosim = NULL;
}

/* ---- parsing ------------------------------------------------------------- */

/* the next white-space word of *p into w (at most size - 1 chars); its start in *at */
static int next_word(char *w, size_t size, const char **p, const char **at)
{
    size_t n;
    while (**p == ' ' || **p == '\t') (*p)++;
    n = strcspn(*p, " \t");
    *at = *p;
    if (n == 0 || n >= size) return 0;
    memcpy(w, *p, n);
    w[n] = '\0';
    *p += n;
    return 1;
}

static int parse_num(fmpq_t q, rs_run_t *run, const rs_request_t *q_, const char **p, const char *what)
{
    char w[128];
    const char *at;
    rs_error_t e;
    rs_error_init(e);
    if (!next_word(w, sizeof w, p, &at) || rs_expr_parse_number(q, w, e) != RS_OK)
        return rs_req_error(run, q_, at, RS_ERR_INPUT, what, *at ? at : "end of line");
    return RS_OK;
}

static int parse_name(box_req_t *b, slong i, rs_run_t *run, const rs_request_t *q, const char **p)
{
    const char *at;
    if (!next_word(b->name[i], sizeof b->name[i], p, &at) || rs_case_param_index(run->c, b->name[i]) < 0)
        return rs_req_error(run, q, at, RS_ERR_INPUT, "expected a parameter, found '%s'", *at ? at : "end of line");
    b->at[i] = at;
    return RS_OK;
}

static int expect_word(const char *word, rs_run_t *run, const rs_request_t *q, const char **p, const char *fmt)
{
    char w[64];
    const char *at;
    if (!next_word(w, sizeof w, p, &at) || strcmp(w, word) != 0)
        return rs_req_error(run, q, at, RS_ERR_INPUT, fmt, *at ? at : "end of line");
    return RS_OK;
}

int rs_an_cosim_region_parse(rs_an_req_t *req, rs_run_t *run)
{
    box_req_t *b = box_req_new(req);
    const rs_request_t *q = req->q;
    const char *p = req->rest;
    const rs_optval_t *o;
    int r;
    b->naxes = 1;
    r = parse_name(b, 0, run, q, &p);
    if (r == RS_OK) r = expect_word("from", run, q, &p, "expected 'region NAME from A to B [digits=N]', found '%s'");
    if (r == RS_OK) r = parse_num(b->lo[0], run, q, &p, "expected a number after 'from', found '%s'");
    if (r == RS_OK) r = expect_word("to", run, q, &p, "expected 'to B', found '%s'");
    if (r == RS_OK) r = parse_num(b->hi[0], run, q, &p, "expected a number after 'to', found '%s'");
    if (r == RS_OK && fmpq_cmp(b->lo[0], b->hi[0]) >= 0)
        r = rs_req_error(run, q, b->at[0], RS_ERR_INPUT, "expected A < B in '%s'", req->rest);
    /* [digits=N] after the interval (anything else there is an error) */
    if (r == RS_OK) r = rs_an_opts_parse(req, run, p);
    o = rs_an_opt(req, "digits");
    b->digits = o->at != NULL ? o->num : 15;
    return r;
}

/* claim stable|bounded|unstable when A <= NAME <= B [and ...] */
int rs_an_cosim_claim_parse(rs_an_req_t *req, rs_run_t *run)
{
    box_req_t *b = box_req_new(req);
    const rs_request_t *q = req->q;
    const char *p = req->rest, *at;
    char w[64];
    int r = RS_OK;
    if (!next_word(w, sizeof w, &p, &at)
        || (strcmp(w, "stable") != 0 && strcmp(w, "unstable") != 0 && strcmp(w, "bounded") != 0))
        return rs_req_error(run, q, at, RS_ERR_INPUT,
                            "exact (analytic) subsystem integration: expected 'claim stable|bounded|unstable when A <= "
                            "NAME <= B [and ...]', found '%s'", *at ? at : "end of line");
    b->unstable = strcmp(w, "unstable") == 0;
    b->bounded = strcmp(w, "bounded") == 0;
    r = expect_word("when", run, q, &p, "expected 'when A <= NAME <= B', found '%s'");
    while (r == RS_OK) {
        slong i = b->naxes;
        if (i == BOX_MAX_AXES)
            return rs_req_error(run, q, p, RS_ERR_LIMIT, "at most 8 parameter ranges, found '%s'", p);
        r = parse_num(b->lo[i], run, q, &p, "expected 'A <= NAME <= B' (A a number), found '%s'");
        if (r == RS_OK) r = expect_word("<=", run, q, &p, "expected '<=', found '%s'");
        if (r == RS_OK) r = parse_name(b, i, run, q, &p);
        if (r == RS_OK) r = expect_word("<=", run, q, &p, "expected '<=', found '%s'");
        if (r == RS_OK) r = parse_num(b->hi[i], run, q, &p, "expected 'A <= NAME <= B' (B a number), found '%s'");
        if (r == RS_OK && fmpq_cmp(b->lo[i], b->hi[i]) > 0)
            r = rs_req_error(run, q, b->at[i], RS_ERR_INPUT, "expected A <= B for '%s'", b->at[i]);
        if (r != RS_OK) break;
        b->naxes++;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '\0') break;
        r = expect_word("and", run, q, &p, "expected 'and' or the end of the claim, found '%s'");
    }
    return r;
}

/* ---- the ball model over a box -------------------------------------------- */

/* p at the variable values x[0 .. nvars) (balls) */
static void mpoly_eval_arb(arb_t res, const fmpq_mpoly_t p, arb_srcptr x, const fmpq_mpoly_ctx_t ctx, slong prec)
{
    slong i, v, nv = ctx->zctx->minfo->nvars, len = fmpq_mpoly_length(p, ctx);
    ulong *e = flint_malloc((nv + 1) * sizeof(ulong));
    fmpq_t c;
    arb_t t, u;
    fmpq_init(c);
    arb_init(t);
    arb_init(u);
    arb_zero(res);
    for (i = 0; i < len; i++) {
        fmpq_mpoly_get_term_coeff_fmpq(c, p, i, ctx);
        fmpq_mpoly_get_term_exp_ui(e, p, i, ctx);
        arb_set_fmpq(t, c, prec);
        for (v = 0; v < nv; v++)
            if (e[v]) {
                arb_pow_ui(u, x + v, e[v], prec);
                arb_mul(t, t, u, prec);
            }
        arb_add(res, res, t, prec);
    }
    arb_clear(t);
    arb_clear(u);
    fmpq_clear(c);
    flint_free(e);
}

/* the coefficient of variable v in form i at x, divided by the form's denominator */
static void form_coeff(arb_t out, const rs_cosim_model_struct *F, slong i, slong v, arb_srcptr x, slong prec)
{
    const fmpq_mpoly_ctx_struct *ctx = F->ts->ctx;
    fmpq_mpoly_t t;
    arb_t d;
    ulong one = 1;
    fmpq_mpoly_init(t, ctx);
    arb_init(d);
    if (v >= 0) fmpq_mpoly_get_coeff_vars_ui(t, F->num + i, &v, &one, 1, ctx);
    else fmpq_mpoly_set(t, F->num + i, ctx);
    if (fmpq_mpoly_is_zero(t, ctx)) arb_zero(out);
    else {
        mpoly_eval_arb(out, t, x, ctx, prec);
        mpoly_eval_arb(d, F->den + i, x, ctx, prec);
        arb_div(out, out, d, prec);
    }
    arb_clear(d);
    fmpq_mpoly_clear(t, ctx);
}

typedef struct {
    rs_run_t *run;
    const box_req_t *B;
    const rs_cosim_model_struct *F;
    slong prec;
    arb_ptr x;          /* every variable of the forms' context: set values, box balls, 0 */
    slong nx;
} box_ctx_t;

/* b = the model over the box lo[i] <= NAME_i <= hi[i]; the structure (which
 * partner states are coupling variables) as cosim_at in analysis_cosim.c,
 * from the entries that are not exactly zero over the box */
static void ball_at(rs_cosim_ball_t b, box_ctx_t *X, const fmpq *lo, const fmpq *hi)
{
    const rs_cosim_model_struct *F = X->F;
    const rs_case_struct *c = X->run->c;
    slong n = F->n, nf = F->nf, base = c->nparams, i, j, k, m = 0, prec = X->prec;
    slong n1 = F->nstate[0];
    slong *in_var = flint_malloc((n + nf + 1) * sizeof(slong));
    arb_mat_t W;
    arb_t t;
    arb_init(t);
    for (i = 0; i < X->B->naxes; i++) {
        slong v = rs_case_param_index(F->tc, X->B->name[i]);
        arb_set_fmpq(t, hi + i, prec);
        arb_set_fmpq(X->x + v, lo + i, prec);
        arb_union(X->x + v, X->x + v, t, prec);
    }
    arb_mat_init(W, n, n + nf);
    for (i = 0; i < n; i++) {
        if (F->second[i]) { arb_one(arb_mat_entry(W, i, i + 1)); continue; }
        for (j = 0; j < n + nf; j++) form_coeff(arb_mat_entry(W, i, j), F, i, base + j, X->x, prec);
    }
    for (j = 0; j < n; j++) {
        int own = j < n1 ? 0 : 1, used = 0;
        for (i = 0; i < n; i++)
            if ((i < n1 ? 0 : 1) != own && !arb_is_zero(arb_mat_entry(W, i, j))) used = 1;
        if (used) in_var[m++] = j;
    }
    for (i = 0; i < nf; i++) in_var[m++] = n + i;
    rs_cosim_ball_set_dims(b, n1, F->nstate[1], m > 0 ? m : 1,
                           strcmp(c->couple, "implicit") == 0 ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT, c->couple_order);
    /* the D-/I-extension (checked on the exact model by box_ctx_init): its n x n map over the ball */
    rs_cosim_ball_set_ext(b, c->couple_ext == 'D' ? RS_COSIM_EXT_D : c->couple_ext == 'I' ? RS_COSIM_EXT_I
                                                                                         : RS_COSIM_EXT_NONE,
                          c->couple_alpha);
    for (j = 0; j < n; j++) {
        slong ja = j < n1 ? 0 : 1, jl = j - (ja ? n1 : 0);
        arb_mat_struct *A = ja == 0 ? b->A1 : b->A2, *Bm = ja == 0 ? b->B1 : b->B2;
        for (k = 0; k < F->nstate[ja]; k++) arb_set(arb_mat_entry(A, jl, k), arb_mat_entry(W, j, (ja ? n1 : 0) + k));
        for (k = 0; k < m; k++) {
            slong v = in_var[k];
            if (v < n && (v < n1 ? 0 : 1) == ja) continue;
            arb_set(arb_mat_entry(Bm, jl, k), arb_mat_entry(W, j, v));
        }
    }
    for (i = 0; i < m; i++) {
        slong v = in_var[i];
        if (v < n) arb_one(arb_mat_entry(b->C, i, v));
        else
            for (j = 0; j < n; j++) form_coeff(arb_mat_entry(b->C, i, j), F, rs_cosim_model_force(F, v - n), base + j,
                                               X->x, prec);
    }
    form_coeff(b->H, F, rs_cosim_model_step(F, 0), -1, X->x, prec);
    arb_mat_clear(W);
    arb_clear(t);
    flint_free(in_var);
}

/* the verdict certified over the box (RS_COSIM_BALL_*) */
static int box_verdict(box_ctx_t *X, const fmpq *lo, const fmpq *hi)
{
    rs_cosim_ball_t b;
    arb_mat_t M;
    rs_error_t e;
    int v = RS_COSIM_BALL_UNDECIDED;
    rs_cosim_ball_init(b);
    rs_error_init(e);
    ball_at(b, X, lo, hi);
    arb_mat_init(M, rs_cosim_ball_dim(b), rs_cosim_ball_dim(b));
    if (rs_cosim_ball_transition(M, b, X->prec, e) == RS_OK) v = rs_cosim_ball_stein(M, X->prec);
    else if (e->code == RS_ERR_INCONSISTENT && X->run->err->code == RS_OK)   /* two enclosures disjoint: exit 3 */
        rs_error_set(X->run->err, RS_ERR_INCONSISTENT, "%s", e->msg);
    arb_mat_clear(M);
    rs_cosim_ball_clear(b);
    return v;
}

/* X over the run; the exact model at the box's lower corner first, so that
 * the case's own errors (a parameter not set, an equation not linear, a
 * macro step that differs) are reported at their place */
static int box_ctx_init(box_ctx_t *X, rs_run_t *run, const box_req_t *B, slong prec)
{
    rs_cosim_vals_t vals;
    const char *names[BOX_MAX_AXES];
    rs_cosim_t cs;
    slong i;
    int r;
    X->run = run;
    X->B = B;
    X->prec = prec;
    X->x = NULL;
    X->F = rs_model_cosim(run->m, run->err);
    if (X->F == NULL) return run->err->code;
    for (i = 0; i < B->naxes; i++) names[i] = B->name[i];
    rs_cosim_init(cs, 1, 1);
    r = rs_run_cosim_at(cs, run, names, B->lo[0], B->naxes);
    rs_cosim_clear(cs);
    if (r != RS_OK) return r;
    X->nx = X->F->ts->nvars;
    X->x = _arb_vec_init(X->nx);
    rs_cosim_vals_make(&vals, run->c, NULL, NULL, 0);
    for (i = 0; i < vals.n; i++) arb_set_fmpq(X->x + rs_case_param_index(X->F->tc, vals.v[i].name), vals.v[i].value, prec);
    flint_free(vals.v);
    return RS_OK;
}

static void box_ctx_clear(box_ctx_t *X)
{
    if (X->x != NULL) _arb_vec_clear(X->x, X->nx);
}

/* the set values that stay fixed (the box's parameters vary) */
static json_t *sets_but_box(const rs_case_struct *c, const box_req_t *B)
{
    json_t *o = rs_json_sets(c);
    slong i;
    for (i = 0; i < B->naxes; i++) json_object_del(o, B->name[i]);
    return o;
}

/* ---- region --------------------------------------------------------------- */

typedef struct { fmpq_t lo, hi; int v; } seg_t;

static int seg_cmp(const void *a, const void *b)
{
    return fmpq_cmp(((const seg_t *) a)->lo, ((const seg_t *) b)->lo);
}

static const char *verdict_name(int v)
{
    return v == RS_COSIM_BALL_STABLE ? "stable" : v == RS_COSIM_BALL_UNSTABLE ? "unstable" : "undecided";
}

/* [lo, hi] printed outward with `digits` digits: [lower rounded down, upper rounded up] */
static json_t *enclosure_json(const fmpq_t lo, const fmpq_t hi, slong digits, slong prec)
{
    arb_t a;
    char *s1, *s2;
    json_t *o;
    arb_init(a);
    arb_set_fmpq(a, lo, prec);
    s1 = rs_radius_str_lower(a, digits);
    arb_set_fmpq(a, hi, prec);
    s2 = rs_radius_str_upper(a, digits);
    o = json_pack("[s,s]", s1, s2);
    flint_free(s1);
    flint_free(s2);
    arb_clear(a);
    return o;
}

static json_t *exact_json(const fmpq_t q)
{
    char *s = fmpq_get_str(NULL, 10, q);
    json_t *o = json_string(s);
    flint_free(s);
    return o;
}

/* the midpoint of [lo, hi] with only the digits the enclosure certifies */
static json_t *point_json(const fmpq_t lo, const fmpq_t hi, slong digits, slong prec)
{
    arb_t a, b;
    json_t *o;
    arb_init(a);
    arb_init(b);
    arb_set_fmpq(a, lo, prec);
    arb_set_fmpq(b, hi, prec);
    arb_union(a, a, b, prec);
    o = rs_json_arb(a, digits + 2);
    arb_clear(a);
    arb_clear(b);
    return o;
}

static int centre_verdict(int *v, json_t **at, rs_run_t *run, const box_req_t *B, const fmpq *lo, const fmpq *hi);
static int box_crosscheck(rs_run_t *run, const box_req_t *B, const fmpq *lo, const fmpq *hi, int v);

int rs_an_cosim_region(rs_run_t *run, const rs_an_req_t *req)
{
    const box_req_t *B = req->u.cosim;
    slong digits = B->digits, prec = (slong) (2 * 3.33 * digits) + 64, nseg = 0, cap = 64, i, level, nundec = 0;
    seg_t *seg;
    box_ctx_t X;
    fmpq_t tol, w;
    int r, all_certified = 1;
    json_t *o, *ivs, *trans, *unsep;
    r = box_ctx_init(&X, run, B, prec);
    if (r != RS_OK) { box_ctx_clear(&X); return r; }
    fmpq_init(tol);
    fmpq_init(w);
    /* tol = 10^-digits: a transition's enclosure must be narrower */
    fmpz_one(fmpq_numref(tol));
    fmpz_set_ui(fmpq_denref(tol), 10);
    fmpz_pow_ui(fmpq_denref(tol), fmpq_denref(tol), (ulong) digits);
    seg = flint_malloc(cap * sizeof(seg_t));
    fmpq_init(seg[0].lo);
    fmpq_init(seg[0].hi);
    fmpq_set(seg[0].lo, B->lo[0]);
    fmpq_set(seg[0].hi, B->hi[0]);
    seg[0].v = -1;   /* not evaluated yet */
    nseg = 1;
    /* breadth first: evaluate the new boxes, split the undecided ones that are wider than tol/32 */
    for (level = 0; r == RS_OK; level++) {
        slong nnew = 0, n0 = nseg;
        nundec = 0;
        for (i = 0; i < n0 && r == RS_OK; i++) {
            if (seg[i].v >= 0) continue;
            if ((r = rs_budget_check(run->err, "the certified region")) != RS_OK) break;
            seg[i].v = box_verdict(&X, seg[i].lo, seg[i].hi);
            if (run->err->code != RS_OK) { r = run->err->code; break; }
            if (seg[i].v == RS_COSIM_BALL_UNDECIDED) nundec++;
        }
        if (r != RS_OK || nundec == 0 || nundec > REGION_MAX_UNDECIDED) break;
        for (i = 0; i < n0; i++) {
            if (seg[i].v != RS_COSIM_BALL_UNDECIDED) continue;
            fmpq_sub(w, seg[i].hi, seg[i].lo);
            /* boxes at distance d from a crossing certify once narrower than ~d/4: go to tol/32 */
            fmpq_mul_2exp(w, w, 5);
            if (fmpq_cmp(w, tol) <= 0) continue;
            if (nseg == cap) {
                cap *= 2;
                seg = flint_realloc(seg, cap * sizeof(seg_t));
            }
            fmpq_init(seg[nseg].lo);
            fmpq_init(seg[nseg].hi);
            fmpq_add(w, seg[i].lo, seg[i].hi);
            fmpq_div_2exp(w, w, 1);
            fmpq_set(seg[nseg].lo, w);
            fmpq_set(seg[nseg].hi, seg[i].hi);
            fmpq_set(seg[i].hi, w);
            seg[nseg].v = seg[i].v = -1;
            nseg++;
            nnew++;
        }
        if (nnew == 0) break;
        qsort(seg, (size_t) nseg, sizeof(seg_t), seg_cmp);
    }
    /* runs: maximal sequences of equal verdicts, in order */
    qsort(seg, (size_t) nseg, sizeof(seg_t), seg_cmp);
    for (i = 0; r == RS_OK && i < nseg;) {   /* every certified run checked at its middle box */
        slong e = i;
        while (e + 1 < nseg && seg[e + 1].v == seg[i].v) e++;
        if (seg[i].v != RS_COSIM_BALL_UNDECIDED)
            r = box_crosscheck(run, B, seg[(i + e) / 2].lo, seg[(i + e) / 2].hi, seg[i].v);
        i = e + 1;
    }
    o = json_object();
    ivs = json_array();
    trans = json_array();
    unsep = json_array();
    if (r == RS_OK) {
        slong a = 0, prev_run = -1;   /* prev_run: index of the first segment of the last certified run */
        json_t *cur = NULL;           /* the open certified interval */
        json_t *pending = NULL;       /* the enclosure that starts the next interval */
        while (a < nseg) {
            slong e = a;
            while (e + 1 < nseg && seg[e + 1].v == seg[a].v) e++;
            if (seg[a].v != RS_COSIM_BALL_UNDECIDED) {
                cur = json_object();
                if (pending != NULL) {
                    json_object_set(cur, "lo", json_object_get(pending, "at"));
                    json_object_set(cur, "lo_enclosure", json_object_get(pending, "enclosure"));
                    json_object_set_new(cur, "lo_approx", json_real(fmpq_get_d(seg[a].lo)));
                    json_decref(pending);
                    pending = NULL;
                } else if (a == 0) {
                    json_object_set_new(cur, "lo", exact_json(seg[a].lo));
                    json_object_set_new(cur, "lo_closed", json_true());
                    json_object_set_new(cur, "lo_approx", json_real(fmpq_get_d(seg[a].lo)));
                } else {
                    /* after an unseparated run: only the certified part */
                    json_object_set_new(cur, "lo", exact_json(seg[a].lo));
                    json_object_set_new(cur, "lo_closed", json_true());
                    json_object_set_new(cur, "lo_approx", json_real(fmpq_get_d(seg[a].lo)));
                }
                json_object_set_new(cur, "status", json_string(verdict_name(seg[a].v)));
                if (e == nseg - 1) {
                    json_object_set_new(cur, "hi", exact_json(seg[e].hi));
                    json_object_set_new(cur, "hi_closed", json_true());
                    json_object_set_new(cur, "hi_approx", json_real(fmpq_get_d(seg[e].hi)));
                    json_array_append_new(ivs, cur);
                    cur = NULL;
                }
                prev_run = a;
            } else {
                /* an undecided run [seg[a].lo, seg[e].hi] */
                int left = a > 0 ? seg[a - 1].v : -1, right = e + 1 < nseg ? seg[e + 1].v : -1;
                fmpq_sub(w, seg[e].hi, seg[a].lo);
                if (left >= 0 && right >= 0 && left != right && fmpq_cmp(w, tol) < 0 && cur != NULL) {
                    json_t *t = json_object();
                    json_object_set_new(t, "at", point_json(seg[a].lo, seg[e].hi, digits, prec));
                    json_object_set_new(t, "enclosure", enclosure_json(seg[a].lo, seg[e].hi, digits + 5, prec));
                    json_object_set_new(t, "from", json_string(verdict_name(left)));
                    json_object_set_new(t, "to", json_string(verdict_name(right)));
                    json_object_set_new(t, "certified", json_true());
                    json_object_set(cur, "hi", json_object_get(t, "at"));
                    json_object_set(cur, "hi_enclosure", json_object_get(t, "enclosure"));
                    json_object_set_new(cur, "hi_approx", json_real(fmpq_get_d(seg[e].hi)));
                    json_array_append_new(ivs, cur);
                    cur = NULL;
                    pending = json_incref(t);
                    json_array_append_new(trans, t);
                } else {
                    json_t *u = json_object();
                    all_certified = 0;
                    if (cur != NULL) {
                        json_object_set_new(cur, "hi", exact_json(seg[a].lo));
                        json_object_set_new(cur, "hi_closed", json_true());
                        json_object_set_new(cur, "hi_approx", json_real(fmpq_get_d(seg[a].lo)));
                        json_array_append_new(ivs, cur);
                        cur = NULL;
                    }
                    json_object_set_new(u, "lo", exact_json(seg[a].lo));
                    json_object_set_new(u, "hi", exact_json(seg[e].hi));
                    json_object_set_new(u, "enclosure", enclosure_json(seg[a].lo, seg[e].hi, digits + 5, prec));
                    json_object_set_new(u, "between", json_pack("[s,s]", left >= 0 ? verdict_name(left) : "end",
                                                                 right >= 0 ? verdict_name(right) : "end"));
                    json_object_set_new(u, "reason",
                                        json_string(fmpq_cmp(w, tol) >= 0
                                                    ? "no certificate on either side within the bisection limits "
                                                      "(rho may equal 1 there, or crossings are too close)"
                                                    : "rho reaches 1 without a certified change of verdict"));
                    json_array_append_new(unsep, u);
                }
            }
            a = e + 1;
        }
        (void) prev_run;
        if (pending != NULL) json_decref(pending);
        if (cur != NULL) json_decref(cur);
        json_object_set_new(o, "analysis", json_string("region"));
        json_object_set_new(o, "param", json_string(B->name[0]));
        json_object_set_new(o, "from", exact_json(B->lo[0]));
        json_object_set_new(o, "to", exact_json(B->hi[0]));
        json_object_set_new(o, "substituted", sets_but_box(run->c, B));
        json_object_set_new(o, "symbolic", json_false());
        json_object_set_new(o, "certified", json_boolean(all_certified));
        json_object_set_new(o, "digits", json_integer(digits));
        json_object_set_new(o, "intervals", ivs);
        json_object_set_new(o, "transitions", trans);
        json_object_set_new(o, "unseparated", unsep);
        json_object_set_new(o, "boxes", json_integer(nseg));
        json_object_set_new(o, "precision_bits", json_integer(prec));
        json_object_set_new(o, "method",
                            json_string("exact subsystem integration: ball one-step map over parameter boxes (Arb), "
                                        "Stein certificates, bisection"));
        json_object_set_new(o, "decided_by", json_string("certified"));
        json_array_append_new(run->results, o);
    } else {
        json_decref(ivs);
        json_decref(trans);
        json_decref(unsep);
        json_decref(o);
    }
    for (i = 0; i < nseg; i++) {
        fmpq_clear(seg[i].lo);
        fmpq_clear(seg[i].hi);
    }
    flint_free(seg);
    fmpq_clear(tol);
    fmpq_clear(w);
    box_ctx_clear(&X);
    return r;
}

/* ---- claim ---------------------------------------------------------------- */

static json_t *box_json(const box_req_t *B, fmpq *const *lo, fmpq *const *hi, slong k)
{
    json_t *o = json_object();
    slong i;
    for (i = 0; i < B->naxes; i++) {
        json_t *a = json_array();
        json_array_append_new(a, exact_json(lo[k] + i));
        json_array_append_new(a, exact_json(hi[k] + i));
        json_object_set_new(o, B->name[i], a);
    }
    return o;
}

/* the certified verdict of the exact model at the box's centre (6 digits) */
static int centre_verdict(int *v, json_t **at, rs_run_t *run, const box_req_t *B, const fmpq *lo, const fmpq *hi)
{
    const char *names[BOX_MAX_AXES];
    fmpq *c = _fmpq_vec_init(B->naxes);
    rs_cosim_t cs;
    rs_radius_t rr;
    slong i;
    int r;
    *v = RS_COSIM_BALL_UNDECIDED;
    *at = json_object();
    for (i = 0; i < B->naxes; i++) {
        names[i] = B->name[i];
        fmpq_add(c + i, lo + i, hi + i);
        fmpq_div_2exp(c + i, c + i, 1);
        json_object_set_new(*at, B->name[i], exact_json(c + i));
    }
    rs_cosim_init(cs, 1, 1);
    rs_radius_init(rr);
    r = rs_run_cosim_at(cs, run, names, c, B->naxes);
    if (r == RS_OK) {
        rs_error_t e;
        rs_error_init(e);
        int rc = rs_cosim_radius(rr, cs, 6, 1024, e);
        /* RS_ERR_UNDECIDED (eigenvalues not isolated, e.g. equal subsystems): the
         * enclosure certified so far still decides when it excludes 1 */
        if (rc == RS_OK || (rc == RS_ERR_UNDECIDED && arb_is_finite(rr->lower) && arb_is_finite(rr->upper))) {
            arb_t one;
            char *sl = rs_radius_str_lower(rr->lower, 8), *su = rs_radius_str_upper(rr->upper, 8);
            arb_init(one);
            arb_one(one);
            *v = arb_lt(rr->upper, one) ? RS_COSIM_BALL_STABLE : arb_gt(rr->lower, one) ? RS_COSIM_BALL_UNSTABLE
                                                                                      : RS_COSIM_BALL_UNDECIDED;
            if (rc == RS_OK) json_object_set_new(*at, "rho", rs_json_arb(rr->rho, 6));
            else json_object_set_new(*at, "rho", json_pack("[s,s]", sl, su));
            flint_free(sl);
            flint_free(su);
            arb_clear(one);
        }
    }
    rs_radius_clear(rr);
    rs_cosim_clear(cs);
    _fmpq_vec_clear(c, B->naxes);
    return r;
}

/* The second method (exit 3 on disagreement): a verdict certified over a box
 * by its Stein certificate against the certified eigenvalues (rs_cosim_radius)
 * of the exact model at the box's centre. */
static int box_crosscheck(rs_run_t *run, const box_req_t *B, const fmpq *lo, const fmpq *hi, int v)
{
    int pv, r;
    json_t *at;
    r = centre_verdict(&pv, &at, run, B, lo, hi);
    json_decref(at);
    if (r == RS_OK && pv != RS_COSIM_BALL_UNDECIDED && pv != v)
        r = rs_error_set(run->err, RS_ERR_INCONSISTENT,
                         "co-simulation: the Stein certificate over a box (%s) and the certified eigenvalues at "
                         "its centre (%s) disagree", verdict_name(v), verdict_name(pv));
    return r;
}

int rs_an_cosim_claim(rs_run_t *run, const rs_an_req_t *req)
{
    const box_req_t *B = req->u.cosim;
    slong prec = 128, n = 1, cap = 64, done = 0, i, d = B->naxes;
    int want = B->unstable ? RS_COSIM_BALL_UNSTABLE : RS_COSIM_BALL_STABLE, r, status = 0;   /* 0 proved */
    fmpq **lo, **hi;
    box_ctx_t X;
    json_t *o, *fail = NULL, *counter = NULL, *reason = NULL;
    r = box_ctx_init(&X, run, B, prec);
    if (r != RS_OK) { box_ctx_clear(&X); return r; }
    lo = flint_malloc(cap * sizeof(fmpq *));
    hi = flint_malloc(cap * sizeof(fmpq *));
    lo[0] = _fmpq_vec_init(d);
    hi[0] = _fmpq_vec_init(d);
    for (i = 0; i < d; i++) {
        fmpq_set(lo[0] + i, B->lo[i]);
        fmpq_set(hi[0] + i, B->hi[i]);
    }
    /* a stack of boxes still to certify */
    while (n > 0 && r == RS_OK) {
        slong k = n - 1, widest = 0;
        int v;
        fmpq_t wd, wmax;
        if ((r = rs_budget_check(run->err, "the claim")) != RS_OK) break;
        v = box_verdict(&X, lo[k], hi[k]);
        if (run->err->code != RS_OK) { r = run->err->code; break; }
        done++;
        if (v == want) {
            _fmpq_vec_clear(lo[k], d);
            _fmpq_vec_clear(hi[k], d);
            n--;
            continue;
        }
        if (B->bounded && v == RS_COSIM_BALL_UNDECIDED && done < CLAIM_MAX_BOXES) {
            /* the centre decides early: rho > 1 refutes, rho = 1 to 6 digits stops (see the top) */
            int pv;
            json_t *at;
            r = centre_verdict(&pv, &at, run, B, lo[k], hi[k]);
            if (r != RS_OK) { json_decref(at); break; }
            if (pv == RS_COSIM_BALL_UNSTABLE) {
                status = 1;
                counter = at;
                break;
            }
            if (pv == RS_COSIM_BALL_UNDECIDED) {
                status = 2;
                fail = box_json(B, lo, hi, k);
                reason = json_pack("{s:s,s:o}", "not_proved",
                                   "rho < 1 on this sub-box: the certified enclosure of rho at its centre contains 1 "
                                   "(asked to 6 digits), so no sub-box around it certifies rho < 1; boundedness with "
                                   "rho = 1 (semisimple unit-circle eigenvalues) is not decided by ball certificates",
                                   "centre", at);
                break;
            }
            json_decref(at);
        }
        if (v != RS_COSIM_BALL_UNDECIDED || done >= CLAIM_MAX_BOXES) {
            /* the opposite verdict certified over a box, or no more boxes: a certified point decides or not */
            int pv;
            json_t *at;
            r = centre_verdict(&pv, &at, run, B, lo[k], hi[k]);
            if (r == RS_OK && v != RS_COSIM_BALL_UNDECIDED && pv != RS_COSIM_BALL_UNDECIDED && pv != v)
                /* the second method: the box's Stein verdict against the centre's eigenvalues */
                r = rs_error_set(run->err, RS_ERR_INCONSISTENT,
                                 "co-simulation: the Stein certificate over a box (%s) and the certified eigenvalues "
                                 "at its centre (%s) disagree", verdict_name(v), verdict_name(pv));
            if (r != RS_OK) {
                json_decref(at);
                break;
            }
            if (pv != RS_COSIM_BALL_UNDECIDED && pv != want) {
                status = 1;
                counter = at;
            } else {
                json_decref(at);
                status = 2;
                fail = box_json(B, lo, hi, k);
                if (B->bounded)
                    reason = json_pack("{s:s}", "not_proved",
                                       v == RS_COSIM_BALL_UNSTABLE
                                           ? "this sub-box is certified rho > 1 but its centre's radius does not "
                                             "exclude 1"
                                           : "rho < 1 on this sub-box: not certified within the box limit (4096 "
                                             "sub-boxes)");
            }
            break;
        }
        /* split along the widest side */
        fmpq_init(wd);
        fmpq_init(wmax);
        for (i = 0; i < d; i++) {
            fmpq_sub(wd, hi[k] + i, lo[k] + i);
            if (fmpq_cmp(wd, wmax) > 0) { fmpq_set(wmax, wd); widest = i; }
        }
        if (n == cap) {
            cap *= 2;
            lo = flint_realloc(lo, cap * sizeof(fmpq *));
            hi = flint_realloc(hi, cap * sizeof(fmpq *));
        }
        lo[n] = _fmpq_vec_init(d);
        hi[n] = _fmpq_vec_init(d);
        for (i = 0; i < d; i++) {
            fmpq_set(lo[n] + i, lo[k] + i);
            fmpq_set(hi[n] + i, hi[k] + i);
        }
        fmpq_add(wd, lo[k] + widest, hi[k] + widest);
        fmpq_div_2exp(wd, wd, 1);
        fmpq_set(hi[k] + widest, wd);
        fmpq_set(lo[n] + widest, wd);
        n++;
        fmpq_clear(wd);
        fmpq_clear(wmax);
    }
    if (r == RS_OK && status == 0) {   /* proved over every sub-box: the centre's eigenvalues agree */
        fmpq *blo = _fmpq_vec_init(d), *bhi = _fmpq_vec_init(d);
        for (i = 0; i < d; i++) {
            fmpq_set(blo + i, B->lo[i]);
            fmpq_set(bhi + i, B->hi[i]);
        }
        r = box_crosscheck(run, B, blo, bhi, want);
        _fmpq_vec_clear(blo, d);
        _fmpq_vec_clear(bhi, d);
    }
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("claim"));
        json_object_set_new(o, "text", json_string(req->q->text));
        json_object_set_new(o, "claim", json_string(B->unstable ? "unstable" : B->bounded ? "bounded" : "stable"));
        json_object_set_new(o, "status", json_string(status == 0 ? "proved" : status == 1 ? "refuted" : "undecided"));
        json_object_set_new(o, "boxes_checked", json_integer(done));
        if (status == 0)
            json_object_set_new(o, "certificate",
                                json_pack("{s:s,s:I}", "kind",
                                          "Stein: P - M^T P M > 0 over the ball one-step map of every sub-box",
                                          "boxes", (json_int_t) done));
        if (counter != NULL) json_object_set_new(o, "counterexample", counter);
        if (fail != NULL) json_object_set_new(o, "failed_at", fail);
        if (reason != NULL) json_object_update(o, reason);
        if (status == 0 && B->bounded)
            json_object_set_new(o, "proved_by", json_string("rho < 1 certified on every sub-box (stable, hence bounded)"));
        json_object_set_new(o, "substituted", sets_but_box(run->c, B));
        json_object_set_new(o, "decided_by", json_string("certified"));
        json_array_append_new(run->results, o);
        if (status != 0) run->outcome |= RS_OUTCOME_FAILED;
    } else {
        if (counter != NULL) json_decref(counter);
        if (fail != NULL) json_decref(fail);
    }
    if (reason != NULL) json_decref(reason);
    for (i = 0; i < n; i++) {
        _fmpq_vec_clear(lo[i], d);
        _fmpq_vec_clear(hi[i], d);
    }
    flint_free(lo);
    flint_free(hi);
    box_ctx_clear(&X);
    return r;
}
