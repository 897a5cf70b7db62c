/* an_region_cad.c -- `region N1, N2 [at P=V, ...]`: the exact stable and
 * marginal sets in the (N1, N2) plane by a cylindrical algebraic
 * decomposition (Collins 1975; the 2-D projection of lc, discriminant and
 * resultants suffices: over an open interval of N1 where none vanishes the
 * roots in N2 of every polynomial are continuous and distinct).
 *
 *   1. the critical polynomials in (N1, N2): where a root can reach the
 *      circle or the degree drops (lc in lambda, p(1), p(-1), D_{n-1} of
 *      the bilinear q, the discriminant), factored; the assume lines' ends;
 *   2. projection onto N1: leading coefficients, discriminants, pairwise
 *      resultants in N2; their real roots cut the N1 axis into columns;
 *   3. in each column the roots in N2 cut it into cells; each cell's
 *      status is decided exactly at its sample (rational: the point
 *      verdict; algebraic N2: in Q(N2)[lambda]; over an irrational N1 =
 *      alpha: in Q(alpha) at rational N2, in Q(alpha, beta) = Q(gamma) by a
 *      primitive element at a section N2 = beta);
 *   4. the formula: an OR of ANDs of sign conditions of the polynomials,
 *      built from the cells' sign vectors (Hong's solution formula
 *      construction, simplified greedily while no cell of another status
 *      satisfies it), re-parsed and checked at random rational points
 *      against the exact point verdict (exit 3 on disagreement);
 *   5. the boundary: the polynomials with at least one arc whose two sides
 *      have different statuses (a vertical arc's side points proved to lie
 *      in its adjacent cells, cad_side_proved); apart from it the curves
 *      marginal between two sides of one other status (marginal_curves).
 *
 * Limit: two parameters; every other one must be set (`at` or `set`).
 * Over an irrational N1 = alpha, a section whose tower Q(alpha, beta) has
 * degree > 12 (24 in the plane of a complex parameter) gets its signs from
 * the norms Res(m_alpha, f_k) and balls (cad_sign_norm, exact), its status
 * from root balls where no root is on the circle (cad_status_balls,
 * certified; real parameters only) and otherwise from the tower up to
 * degree 64.  In the plane of a complex parameter the status follows from
 * the signs alone (cx_section_signs), checked against root balls; on the
 * circle locus marginal or unstable comes from the norms in Q(beta) when
 * alpha lies in it, without the full tower (cx_marginal_rel).  Left undecided (counted in "undecided_lines";
 * "formula_complete" false): a column when deg alpha > 8 or a sign the
 * balls do not separate, a cell when none of those decides it or a system
 * has a repeated circle root there. */
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>
#include <flint/fmpz_mpoly_factor.h>
#include <flint/fmpq_mpoly.h>
#include <flint/fmpz_poly.h>
#include <arb_fmpz_poly.h>
#include <acb_poly.h>
#include <gsl/gsl_poly.h>
#include <fmpq_vec.h>
#include "analysis/an_region.h"
#include "recstab/bilinear.h"
#include "recstab/hurwitz.h"
#include "recstab/semisimple.h"
#include "recstab/radius.h"
#include "util/polyfmt.h"
#include "algebra/mfactor.h"

#define CAD_CHECK_POINTS 64
/* deg alpha * deg beta above this: a column over an irrational alpha with a
 * section there is left undecided (the primitive element's resultant and the
 * gcd over Q(gamma) grow with it: Park's (alpha, m) plane has degree-6 alphas) */
#define CAD_MAX_TOWER_DEGREE 12
/* above cad_max_tower the signs come from norms and the status from
 * root balls; a cell inside the domain that the balls leave open (a root on
 * the circle) still gets its tower up to this degree (Park's (alpha, muh)
 * plane: four cells of degrees 18 to 50, about 5 s of the 9 s all its
 * towers took) */
#define CAD_MAX_TOWER_DEGREE_CELL 64
#define CAD_MAX_TOWER_DEGREE_CX 24
/* complex plane, a circle-locus section above that cap: the marginal test
 * in Q(beta) = Q(alpha, beta) without the full tower (cx_marginal_rel) up to
 * this degree (RK4's fields of degree 32 and 36: 0.05 s each; AB3's of
 * degree 48: over 60 s each) */
#define CAD_MAX_MARGINAL_FIELD 36
/* and at most this sum of deg(beta)^2 over the cells tried per region
 * (deterministic, unlike a time share; RK4's 14 cells: 9512, about 0.5 s;
 * all of BDF4's took 30 s); the cells after it are counted open, the note
 * says so */
#define CAD_MARGINAL_REL_COST 16384
/* deg alpha above this: the column is not decided at all */
#define CAD_MAX_LINE_DEGREE 8
/* the plane of a complex parameter: its sections are decided by signs
 * (cx_section_signs), so a column costs the norms only (AB3's three lines
 * of degree 11) */
#define CAD_MAX_LINE_DEGREE_CX 12

enum { K_BOUNDARY = 0, K_DOMAIN = 1, K_PROJ = 2 };

typedef struct {
    int dim;                 /* 0, 1, 2 */
    slong col;               /* column (its index in the N1 decomposition) */
    int decided, outside;
    rs_status_t st;
    signed char *sg;         /* sign of each polynomial */
    json_t *a, *b;           /* the sample */
    slong sec;               /* for sections: the polynomials vanishing (first index) */
    int balls;               /* status decided by root balls (no tower: cad_status_balls) */
    const char *why;         /* undecided: the reason (a static string) */
} cell_t;

typedef struct {
    rs_run_t *run;
    const rs_variant_t *v;
    const rs_scheme_struct *s;
    slong av, bv;
    const char *an, *bn;
    rs_bound_t *bounds;
    fmpz_mpoly_struct *f;    /* the polynomials (kind: K_*) */
    int *kind;
    int *closed;             /* K_DOMAIN: the end is included */
    slong nf;
    rs_alg_t *crit;          /* N1 critical values, sorted */
    slong ncrit;
    cell_t *cells;
    slong ncells;
    slong undecided_lines;
    double blo, bhi;         /* the span of N2 roots seen (for random points) */
    const rs_region_cx_t *cx; /* region re(z), im(z): given conditions, stable / not stable */
    slong nb;                /* length of bounds */
    slong marginal_undecided; /* complex mode: circle-locus cells norm's verdict leaves open */
    slong rel_cost;           /* sum of deg(field)^2 over the cells cx_marginal_rel tried */
    slong rel_skipped;        /* cells it left open once that share was spent */
    /* complex mode: lead, delta[0..ndelta), extra[0..nextra) as products of
     * the listed polynomials (cx_fac_build): their signs at a cell follow
     * from the cell's sign vector, with no field arithmetic */
    struct cx_fac_struct *fac;
    slong nfac;
    const rs_region_qd_t *qd;  /* over Q(sqrt d): given critical polynomials, statuses by callbacks */
} cad_t;

/* P = sgn * prod f[idx[j]]^exp[j] times a positive constant (zero: sgn 0) */
typedef struct cx_fac_struct {
    slong n, *idx, *exp;
    int sgn, ok;
} cx_fac_t;

/* the plane of a complex parameter allows a larger tower: its sections are
 * few per line (BDF3: 4 -> 2 undecided lines, RK4 10 -> 9, AB3 28 -> 26 at
 * about +0.1 .. 0.3 s CPU; 36 cost AB3 4.5 s for 7 more lines) */
static slong cad_max_tower(const cad_t *c)
{
    return c->cx != NULL ? CAD_MAX_TOWER_DEGREE_CX : CAD_MAX_TOWER_DEGREE;
}

/* complex mode (region re(z), im(z)): a point's signs of lead and the
 * Schur-Cohn deltas say stable (all > 0) or not; pt: where they are taken */
typedef struct {
    const fmpq *a0, *b0;     /* rational coordinates (or NULL) */
    rs_alg_t *al, *be;       /* algebraic ones */
    const fmpq_poly_struct *A, *B, *m;   /* a tower Q(gamma): (A, B)(gamma) */
    rs_alg_t *g;
} cx_pt_t;

static void cad_eval_field(fmpq_poly_t out, const cad_t *c, const fmpz_mpoly_t f, const fmpq_poly_t A,
                           const fmpq_poly_t B, const fmpq_poly_t m);
static int upoly_sign_at(const fmpz_poly_t g, rs_alg_t *b);

static int cx_sign(const cad_t *c, const fmpz_mpoly_t f, const cx_pt_t *pt)
{
    const fmpz_mpoly_ctx_struct *ctx = c->s->zctx;
    fmpz_mpoly_t t;
    fmpz_poly_t u;
    int sg;
    if (pt->g != NULL) {
        fmpq_poly_t v;
        fmpq_poly_init(v);
        cad_eval_field(v, c, f, pt->A, pt->B, pt->m);
        sg = rs_alg_sign(v, pt->g);
        fmpq_poly_clear(v);
        return sg;
    }
    fmpz_mpoly_init(t, ctx);
    fmpz_poly_init(u);
    if (pt->a0 != NULL && pt->b0 != NULL) {
        fmpz_mpoly_t w;
        fmpz_mpoly_init(w, ctx);
        rs_an_forall_subst(w, f, c->av, pt->a0, ctx);   /* not in place: out is zeroed first */
        rs_an_forall_subst(t, w, c->bv, pt->b0, ctx);
        fmpz_mpoly_clear(w, ctx);
        sg = fmpz_mpoly_is_zero(t, ctx) ? 0 : fmpz_sgn(t->coeffs + 0);
    } else {
        rs_alg_t *x = pt->a0 != NULL ? pt->be : pt->al;
        rs_an_forall_subst(t, f, pt->a0 != NULL ? c->av : c->bv, pt->a0 != NULL ? pt->a0 : pt->b0, ctx);
        if (!fmpz_mpoly_get_fmpz_poly(u, t, pt->a0 != NULL ? c->bv : c->av, ctx)) fmpz_poly_zero(u);
        sg = upoly_sign_at(u, x);
    }
    fmpz_mpoly_clear(t, ctx);
    fmpz_poly_clear(u);
    return sg;
}

static rs_status_t cx_status(const cad_t *c, const cx_pt_t *pt)
{
    slong k;
    if (cx_sign(c, c->cx->lead, pt) <= 0) return RS_STATUS_UNSTABLE;
    for (k = 0; k < c->cx->ndelta; k++)
        if (cx_sign(c, c->cx->delta + k, pt) <= 0) return RS_STATUS_UNSTABLE;
    return RS_STATUS_STABLE;
}

/* the exact point verdict at rational (N1, N2); in complex mode the Q(i)
 * verdict collapsed to stable / not stable (UNSTABLE) */
static int cad_point_status(rs_status_t *st, const cad_t *c, fmpq *vals)
{
    rs_rootcount_t rc;
    int r;
    if (c->qd != NULL) return c->qd->point(st, vals, c->qd->arg);
    if (c->cx != NULL) {
        r = c->cx->status(st, vals + 0, vals + 1, c->cx->arg);
        if (r == RS_OK && *st != RS_STATUS_STABLE && !(c->cx->norm != NULL && *st == RS_STATUS_MARGINAL))
            *st = RS_STATUS_UNSTABLE;
        return r;
    }
    rs_rootcount_init(rc);
    r = rs_run_point_status(st, rc, c->run, c->v, (slong[]) {c->av, c->bv}, vals, 2);
    rs_rootcount_clear(rc);
    return r;
}

/* over Q(sqrt d): the status at (a0, x) (a0 != NULL) or (x, b0), x
 * algebraic, by the caller's field verdict in Q(x) */
static int qd_line_status(rs_status_t *st, const cad_t *c, const fmpq *a0, const fmpq *b0, rs_alg_t *x)
{
    fmpq_poly_t A, B;
    int dec;
    fmpq_poly_init(A); fmpq_poly_init(B);
    if (a0 != NULL) { fmpq_poly_set_fmpq(A, a0); fmpq_poly_set_coeff_si(B, 1, 1); }
    else { fmpq_poly_set_coeff_si(A, 1, 1); fmpq_poly_set_fmpq(B, b0); }
    dec = c->qd->field(st, A, B, x, c->qd->arg);
    fmpq_poly_clear(A); fmpq_poly_clear(B);
    return dec;
}

/* complex mode at a rational sample: the sign verdict, checked against
 * the point verdict over Q(i) (two methods: exit 3 when they differ) */
static int cx_rational(rs_status_t *st, cad_t *c, fmpq *vals)
{
    cx_pt_t pt = {vals + 0, vals + 1, NULL, NULL, NULL, NULL, NULL, NULL};
    rs_status_t ps;
    int r = cad_point_status(&ps, c, vals);
    if (r != RS_OK) return r;
    *st = cx_status(c, &pt);
    if ((*st == RS_STATUS_STABLE) != (ps == RS_STATUS_STABLE)) {
        char *a = fmpq_get_str(NULL, 10, vals + 0), *b = fmpq_get_str(NULL, 10, vals + 1);
        c->run->outcome |= RS_OUTCOME_INCONSISTENT;
        r = rs_error_set(c->run->err, RS_ERR_INCONSISTENT, "region re(%s), im(%s): at (%s, %s) the Schur-Cohn "
                         "conditions say %s, the point verdict over Q(i) %s", c->cx->name, c->cx->name, a, b,
                         *st == RS_STATUS_STABLE ? "stable" : "not stable", ps == RS_STATUS_STABLE ? "stable" : "not stable");
        flint_free(a);
        flint_free(b);
    }
    if (r == RS_OK && ps == RS_STATUS_MARGINAL) *st = RS_STATUS_MARGINAL;
    return r;
}

/* a rational sample's cell decided; over Q(sqrt d) a sample the point
 * verdict leaves open (RS_ERR_UNDECIDED: a repeated root on the circle,
 * marginal or unstable by the matrix only) keeps its cell undecided with
 * the reason, as the irrational columns do, and the run goes on */
/* over Q(sqrt d)(i) (an_qd_cx2.c): why a cell stays undecided */
#define CAD_QDC_WHY "a root on (or, at a rational sample, too near) the unit circle with degree >= 2 over " \
    "Q(sqrt d)(i): a Schur-Cohn condition is zero, marginal and unstable are not told apart"

static int cad_sample_status(cell_t *e, cad_t *c, fmpq *vals)
{
    int r = c->cx != NULL ? cx_rational(&e->st, c, vals) : cad_point_status(&e->st, c, vals);
    e->decided = r == RS_OK;
    if (r == RS_ERR_UNDECIDED && c->qd != NULL) {
        e->why = c->qd->complex_p ? CAD_QDC_WHY
                 : "a repeated root on the unit circle at the rational sample: marginal and unstable are not told "
                   "apart over Q(sqrt d) (Schur-Cohn and the roots see only that no root is outside)";
        rs_error_init(c->run->err);
        r = RS_OK;
    }
    return r;
}

/* the status of N (a polynomial in lambda over Z[N1, N2]) at the point
 * (A, B)(gamma) of the tower Q(gamma) = Q[x]/(m), g its algebraic number:
 * exact (rs_alg_status_coeffs); 0 when undecided */
static int cad_status_field(rs_status_t *st, const cad_t *c, const fmpz_mpoly_t N, const fmpq_poly_t A,
                            const fmpq_poly_t B, const fmpq_poly_t m, rs_alg_t *g)
{
    const rs_scheme_struct *s = c->s;
    slong n = fmpz_mpoly_degree_si(N, s->lambda_var, s->zctx), j;
    fmpz_mpoly_struct *cf = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    fmpq_poly_struct *pc = flint_malloc((n + 1) * sizeof(fmpq_poly_struct));
    int dec;
    for (j = 0; j <= n; j++) fmpz_mpoly_init(cf + j, s->zctx);
    rs_polyfmt_coeffs(cf, N, s->lambda_var, s->zctx);
    for (j = 0; j <= n; j++) {
        fmpq_poly_init(pc + j);
        cad_eval_field(pc + j, c, cf + j, A, B, m);
    }
    dec = rs_alg_status_coeffs(st, pc, n, g, s);
    for (j = 0; j <= n; j++) {
        fmpq_poly_clear(pc + j);
        fmpz_mpoly_clear(cf + j, s->zctx);
    }
    flint_free(pc);
    flint_free(cf);
    return dec;
}

/* the status of one norm (a polynomial in Z[x, y, lambda]) at the
 * algebraic sample pt; 0 when undecided */
static int cx_norm_status(rs_status_t *nst, cad_t *c, const fmpz_mpoly_t N, const cx_pt_t *pt)
{
    const rs_scheme_struct *s = c->s;
    const fmpz_mpoly_ctx_struct *ctx = s->zctx;
    fmpz_mpoly_t t;
    int dec;
    fmpz_mpoly_init(t, ctx);
    if (pt->g != NULL) {
        dec = cad_status_field(nst, c, N, pt->A, pt->B, pt->m, pt->g);
    } else if (pt->a0 != NULL) {
        rs_an_forall_subst(t, N, c->av, pt->a0, ctx);
        dec = rs_alg_status(nst, t, c->bv, pt->be, s);
    } else {
        rs_an_forall_subst(t, N, c->bv, pt->b0, ctx);
        dec = rs_alg_status(nst, t, c->av, pt->al, s);
    }
    fmpz_mpoly_clear(t, ctx);
    return dec;
}

/* complex mode with the marginal set: a not-stable cell e at the algebraic
 * sample pt.  Off the circle locus (extra[0] != 0 and p(-1) != 0: no root
 * on the circle) it is unstable; on it, the norms N_k = |p(rho_k lambda)|^2
 * (|rho_k| = 1, rho_0 = 1, distinct rho_k^2) decide exactly in the
 * sample's field.  N_k's roots are p's rotated by 1/rho_k and their
 * conjugates: the same moduli and multiplicities.  N_k marginal makes p
 * marginal; stable contradicts the signs (exit 3); unstable is p's (a root
 * outside, a repeated circle root) or a coincidence w_j/rho = conj(w_l/rho)
 * of two circle roots of p, i.e. rho^2 = w_j w_l: at most n(n+1)/2 values
 * of rho^2, so with nnorm > n(n+1)/2 norms all unstable, p is unstable. */
static void cx_marginal_at(cad_t *c, cell_t *e, const cx_pt_t *pt)
{
    const rs_region_cx_t *X = c->cx;
    rs_status_t nst = RS_STATUS_UNSTABLE;
    slong k, nn = FLINT_MAX(X->nnorm, 1), n;
    int dec = 0;
    if (X->norm == NULL || e->st == RS_STATUS_STABLE) return;
    n = fmpz_mpoly_degree_si(X->norm, c->s->lambda_var, c->s->zctx) / 2;
    if (cx_sign(c, X->extra + 0, pt) != 0
        && (X->nextra < 3 || cx_sign(c, X->extra + 1, pt) != 0 || cx_sign(c, X->extra + 2, pt) != 0))
        return;
    for (k = 0; k < nn; k++) {
        dec = cx_norm_status(&nst, c, X->norm + k, pt);
        if (!dec || nst != RS_STATUS_UNSTABLE) break;
    }
    if (dec && nst == RS_STATUS_MARGINAL) e->st = RS_STATUS_MARGINAL;
    else if (dec && nst == RS_STATUS_STABLE) c->run->outcome |= RS_OUTCOME_INCONSISTENT;
    else if (dec && nst == RS_STATUS_UNSTABLE && nn > n * (n + 1) / 2) return;   /* every rotation: p's own */
    else c->marginal_undecided++;
}

static const char *cad_st_name(const cad_t *c, rs_status_t st)
{
    return c->cx != NULL && st != RS_STATUS_STABLE && !(c->cx->norm != NULL && st == RS_STATUS_MARGINAL)
           ? "not_stable" : rs_status_name(st);
}

/* appends h (taken: swapped out) */
static void cad_push(cad_t *c, fmpz_mpoly_t h, int kind, int closed)
{
    c->f = flint_realloc(c->f, (c->nf + 1) * sizeof(fmpz_mpoly_struct));
    c->kind = flint_realloc(c->kind, (c->nf + 1) * sizeof(int));
    c->closed = flint_realloc(c->closed, (c->nf + 1) * sizeof(int));
    fmpz_mpoly_init(c->f + c->nf, c->s->zctx);
    fmpz_mpoly_swap(c->f + c->nf, h, c->s->zctx);
    c->kind[c->nf] = kind;
    c->closed[c->nf] = closed;
    c->nf++;
}

/* f with a positive leading coefficient, unless already listed */
static void cad_add(cad_t *c, const fmpz_mpoly_t g, int kind, int closed)
{
    slong i;
    fmpz_mpoly_t h;
    if (fmpz_mpoly_is_fmpz(g, c->s->zctx)) return;
    fmpz_mpoly_init(h, c->s->zctx);
    fmpz_mpoly_set(h, g, c->s->zctx);
    if (fmpz_sgn(h->coeffs + 0) < 0) fmpz_mpoly_neg(h, h, c->s->zctx);
    for (i = 0; i < c->nf; i++)
        if (fmpz_mpoly_equal(c->f + i, h, c->s->zctx) && (kind != K_DOMAIN || c->kind[i] != K_DOMAIN)) {
            fmpz_mpoly_clear(h, c->s->zctx);
            return;
        }
    cad_push(c, h, kind, closed);
    fmpz_mpoly_clear(h, c->s->zctx);
}

/* the irreducible factors of g (non-constant) */
static void cad_add_factors(cad_t *c, const fmpz_mpoly_t g, int kind)
{
    fmpz_mpoly_factor_t fac;
    slong k;
    if (fmpz_mpoly_is_zero(g, c->s->zctx)) return;
    fmpz_mpoly_factor_init(fac, c->s->zctx);
    if (fmpz_mpoly_factor(fac, g, c->s->zctx)) {
        for (k = 0; k < fac->num; k++) cad_add(c, fac->poly + k, kind, 0);
    } else {
        cad_add(c, g, kind, 0);
    }
    fmpz_mpoly_factor_clear(fac, c->s->zctx);
}

/* x - e (lower end) or e - x (upper end), times the denominator of e */
static void cad_add_end(cad_t *c, slong var, const fmpq_t e, int upper, int closed)
{
    fmpz_mpoly_t g, t;
    fmpz_mpoly_init(g, c->s->zctx);
    fmpz_mpoly_init(t, c->s->zctx);
    fmpz_mpoly_gen(g, var, c->s->zctx);
    fmpz_mpoly_scalar_mul_fmpz(g, g, fmpq_denref(e), c->s->zctx);
    fmpz_mpoly_set_fmpz(t, fmpq_numref(e), c->s->zctx);
    fmpz_mpoly_sub(g, g, t, c->s->zctx);
    if (upper) fmpz_mpoly_neg(g, g, c->s->zctx);
    /* not through cad_add: the sign (inside: > 0) matters here */
    cad_push(c, g, K_DOMAIN, closed);
    fmpz_mpoly_clear(g, c->s->zctx);
    fmpz_mpoly_clear(t, c->s->zctx);
}

/* P's factorisation in terms of the listed polynomials (those cad_add_factors
 * pushed for it: the same factors, up to sign) */
static void cx_fac_one(cx_fac_t *F, const cad_t *c, const fmpz_mpoly_t P)
{
    const fmpz_mpoly_ctx_struct *ctx = c->s->zctx;
    fmpz_mpoly_factor_t fac;
    fmpz_mpoly_t h;
    slong k, j;
    memset(F, 0, sizeof *F);
    if (fmpz_mpoly_is_zero(P, ctx)) { F->ok = 1; return; }
    fmpz_mpoly_factor_init(fac, ctx);
    fmpz_mpoly_init(h, ctx);
    if (fmpz_mpoly_factor(fac, P, ctx)) {
        F->ok = 1;
        F->sgn = fmpz_sgn(fac->constant);
        F->idx = flint_malloc((fac->num + 1) * sizeof(slong));
        F->exp = flint_malloc((fac->num + 1) * sizeof(slong));
        for (k = 0; k < fac->num && F->ok; k++) {
            int neg = 0;
            if (fmpz_mpoly_is_fmpz(fac->poly + k, ctx)) {
                /* a constant factor (content): its sign to the power */
                if (fmpz_sgn(fac->poly[k].coeffs + 0) < 0 && fmpz_is_odd(fac->exp + k)) F->sgn = -F->sgn;
                continue;
            }
            fmpz_mpoly_neg(h, fac->poly + k, ctx);
            for (j = 0; j < c->nf; j++) {
                if (c->kind[j] == K_DOMAIN) continue;
                if (fmpz_mpoly_equal(c->f + j, fac->poly + k, ctx)) break;
                if (fmpz_mpoly_equal(c->f + j, h, ctx)) { neg = 1; break; }
            }
            if (j == c->nf) { F->ok = 0; break; }
            if (neg && fmpz_is_odd(fac->exp + k)) F->sgn = -F->sgn;
            F->idx[F->n] = j;
            F->exp[F->n++] = fmpz_get_si(fac->exp + k);
        }
    }
    fmpz_mpoly_factor_clear(fac, ctx);
    fmpz_mpoly_clear(h, ctx);
}

static void cx_fac_build(cad_t *c)
{
    const rs_region_cx_t *X = c->cx;
    slong k, nx = X->norm != NULL ? X->nextra : 0;
    c->nfac = 1 + X->ndelta + nx;
    c->fac = flint_calloc(c->nfac, sizeof(cx_fac_t));
    cx_fac_one(c->fac + 0, c, X->lead);
    for (k = 0; k < X->ndelta; k++) cx_fac_one(c->fac + 1 + k, c, X->delta + k);
    for (k = 0; k < nx; k++) cx_fac_one(c->fac + 1 + X->ndelta + k, c, X->extra + k);
}

/* the sign of listed product F at a cell of signs sg; 2 when unknown */
static int cx_fac_sign(const cx_fac_t *F, const signed char *sg)
{
    slong j;
    int s;
    if (!F->ok) return 2;
    s = F->sgn;
    for (j = 0; j < F->n && s != 0; j++)
        if (sg[F->idx[j]] == 0) s = 0;
        else if (sg[F->idx[j]] < 0 && F->exp[j] % 2 == 1) s = -s;
    return s;
}

/* complex mode from a cell's signs alone: stable iff lead and every delta
 * > 0 (cx_status's rule); *on: the sample lies on the circle locus (the
 * rule of cx_marginal_at).  0 when a factorisation is missing. */
static int cx_status_sg(rs_status_t *st, int *on, const cad_t *c, const signed char *sg)
{
    const rs_region_cx_t *X = c->cx;
    slong k;
    int e0, e1, e2;
    if (c->fac == NULL) return 0;
    for (k = 0; k < 1 + X->ndelta; k++) if (cx_fac_sign(c->fac + k, sg) == 2) return 0;
    *st = RS_STATUS_STABLE;
    for (k = 0; k < 1 + X->ndelta; k++)
        if (cx_fac_sign(c->fac + k, sg) <= 0) { *st = RS_STATUS_UNSTABLE; break; }
    *on = 0;
    if (X->norm == NULL) return 1;
    e0 = cx_fac_sign(c->fac + 1 + X->ndelta, sg);
    e1 = X->nextra >= 3 ? cx_fac_sign(c->fac + 2 + X->ndelta, sg) : 1;
    e2 = X->nextra >= 3 ? cx_fac_sign(c->fac + 3 + X->ndelta, sg) : 1;
    if (e0 == 2 || e1 == 2 || e2 == 2) return 0;
    *on = e0 == 0 || (X->nextra >= 3 && e1 == 0 && e2 == 0);
    return 1;
}

/* the domain from the assume lines */
static void cad_add_domain(cad_t *c)
{
    slong k;
    for (k = 0; k < 2; k++) {
        slong var = k == 0 ? c->av : c->bv;
        const rs_bound_t *b = c->bounds + var;
        if (b->has_lo) cad_add_end(c, var, b->lo, 0, b->lo_closed);
        if (b->has_hi) cad_add_end(c, var, b->hi, 1, b->hi_closed);
    }
}

/* step 1: where the status can change (as region NAME's critical values) */
static int cad_critical(cad_t *c)
{
    const rs_scheme_struct *s = c->s;
    slong lv = s->lambda_var, n = c->cx != NULL ? 0 : fmpz_mpoly_degree_si(c->v->cp->p, lv, s->zctx), k;
    ulong nn = (ulong) n;
    fmpz_mpoly_t sqf, t;
    fmpz_mpoly_factor_t fac;
    fmpz_t pm;
    int r = RS_OK;
    if (c->qd != NULL) {
        /* over Q(sqrt d): the caller's norms, then the domain */
        for (k = 0; k < c->qd->ncrit; k++) cad_add_factors(c, c->qd->crit + k, K_BOUNDARY);
        cad_add_domain(c);
        return rs_budget_check(c->run->err, "region N1, N2 over Q(sqrt d) (critical polynomials)");
    }
    if (c->cx != NULL) {
        /* the given conditions: lead and the Schur-Cohn deltas */
        cad_add_factors(c, c->cx->lead, K_BOUNDARY);
        for (k = 0; k < c->cx->ndelta; k++) cad_add_factors(c, c->cx->delta + k, K_BOUNDARY);
        /* the marginal set: where a root reaches the circle or doubles */
        for (k = 0; k < c->cx->nextra && c->cx->norm != NULL; k++) cad_add_factors(c, c->cx->extra + k, K_PROJ);
        cx_fac_build(c);
        return rs_budget_check(c->run->err, "region re(z), im(z) (critical polynomials)");
    }
    fmpz_mpoly_init(sqf, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    fmpz_init(pm);
    fmpz_mpoly_one(sqf, s->zctx);
    fmpz_mpoly_factor_init(fac, s->zctx);
    if (fmpz_mpoly_factor(fac, c->v->cp->p, s->zctx)) {
        for (k = 0; k < fac->num; k++) {
            if (fmpz_mpoly_degree_si(fac->poly + k, lv, s->zctx) <= 0) continue;
            fmpz_mpoly_mul(sqf, sqf, fac->poly + k, s->zctx);
            /* a repeated factor f^e of det A: its circle roots are bounded
             * iff dim ker A = e, which changes only where the rank of A
             * modulo f drops (not seen by det A: a Jordan block except on
             * such a curve) */
            if (fmpz_cmp_ui(fac->exp + k, 2) >= 0 && !s->from_char && s->n >= 1) {
                fmpz_mpoly_struct *drops = NULL;
                slong nd = 0, j;
                rs_semisimple_rank_drops_mpoly(&drops, &nd, s, fac->poly + k);
                for (j = 0; j < nd; j++) {
                    cad_add_factors(c, drops + j, K_BOUNDARY);
                    fmpz_mpoly_clear(drops + j, s->zctx);
                }
                flint_free(drops);
            }
        }
    } else {
        fmpz_mpoly_set(sqf, c->v->cp->p, s->zctx);
    }
    fmpz_mpoly_factor_clear(fac, s->zctx);
    fmpz_mpoly_get_coeff_vars_ui(t, c->v->cp->p, &lv, &nn, 1, s->zctx);
    cad_add_factors(c, t, K_BOUNDARY);
    for (k = -1; k <= 1; k += 2) {
        fmpz_set_si(pm, k);
        fmpz_mpoly_evaluate_one_fmpz(t, sqf, lv, pm, s->zctx);
        cad_add_factors(c, t, K_BOUNDARY);
    }
    if (n >= 2) {
        rs_hurwitz_t h;
        fmpz_mpoly_t qz;
        int *sign = flint_calloc(s->nvars, sizeof(int));
        fmpz_mpoly_init(qz, s->zctx);
        rs_hurwitz_init(h);
        rs_bilinear_fmpz_mpoly(qz, sqf, lv, s->zctx);
        if (fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 2
            && rs_hurwitz_compute(h, qz, lv, (const rs_sign_t *) sign, s->zctx, c->run->err) == RS_OK && h->n >= 2)
            cad_add_factors(c, h->minors + h->n - 2, K_BOUNDARY);
        rs_error_init(c->run->err);
        rs_hurwitz_clear(h, s->zctx);
        fmpz_mpoly_clear(qz, s->zctx);
        flint_free(sign);
        if (fmpz_mpoly_degree_si(sqf, lv, s->zctx) >= 2 && fmpz_mpoly_discriminant(t, sqf, lv, s->zctx))
            cad_add_factors(c, t, K_BOUNDARY);
    }
    cad_add_domain(c);
    r = rs_budget_check(c->run->err, "region N1, N2 (critical polynomials)");
    fmpz_mpoly_clear(sqf, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
    fmpz_clear(pm);
    return r;
}

/* step 2: the projection onto N1 and its real roots */
static int cad_project(cad_t *c)
{
    const rs_scheme_struct *s = c->s;
    slong i, j, nf0 = c->nf, bv = c->bv;
    fmpz_mpoly_t t;
    fmpz_poly_t u;
    int r = RS_OK;
    fmpz_mpoly_init(t, s->zctx);
    fmpz_poly_init(u);
    for (i = 0; i < nf0 && r == RS_OK; i++) {
        slong d = fmpz_mpoly_degree_si(c->f + i, bv, s->zctx);
        ulong dd = (ulong) d;
        if (d <= 0) continue;
        fmpz_mpoly_get_coeff_vars_ui(t, c->f + i, &bv, &dd, 1, s->zctx);
        cad_add_factors(c, t, K_PROJ);
        if (d >= 2 && fmpz_mpoly_discriminant(t, c->f + i, bv, s->zctx)) cad_add_factors(c, t, K_PROJ);
        for (j = i + 1; j < nf0 && r == RS_OK; j++) {
            if (fmpz_mpoly_degree_si(c->f + j, bv, s->zctx) <= 0) continue;
            r = rs_budget_check(c->run->err, "region N1, N2 (projection)");
            if (r == RS_OK && fmpz_mpoly_resultant(t, c->f + i, c->f + j, bv, s->zctx)) cad_add_factors(c, t, K_PROJ);
        }
    }
    /* every polynomial in N1 alone cuts the axis */
    for (i = 0; i < c->nf && r == RS_OK; i++) {
        if (fmpz_mpoly_degree_si(c->f + i, bv, s->zctx) > 0) continue;
        if (fmpz_mpoly_get_fmpz_poly(u, c->f + i, c->av, s->zctx)) rs_alg_roots_append(&c->crit, &c->ncrit, u, 0);
    }
    rs_alg_sort(c->crit, c->ncrit);
    for (i = 0, j = 0; i < c->ncrit; i++) {
        if (j > 0 && rs_alg_cmp(c->crit + j - 1, c->crit + i) == 0) { rs_alg_clear(c->crit + i); continue; }
        if (j != i) c->crit[j] = c->crit[i];
        j++;
    }
    c->ncrit = j;
    fmpz_mpoly_clear(t, s->zctx);
    fmpz_poly_clear(u);
    return r;
}

/* sign of g at the algebraic b (exact: 0 iff its minimal polynomial divides g) */
static int upoly_sign_at(const fmpz_poly_t g, rs_alg_t *b)
{
    fmpz_poly_t rem;
    arb_t y;
    slong prec;
    int sg = 0;
    if (b->rational) {
        fmpq_t y2;
        fmpq_init(y2);
        fmpz_poly_evaluate_fmpq(y2, g, b->q);
        sg = fmpq_sgn(y2);
        fmpq_clear(y2);
        return sg;
    }
    fmpz_poly_init(rem);
    fmpz_poly_pseudo_rem_cohen(rem, g, b->minpoly);
    if (fmpz_poly_is_zero(rem)) { fmpz_poly_clear(rem); return 0; }
    fmpz_poly_clear(rem);
    arb_init(y);
    for (prec = 64; sg == 0 && prec < (1L << 20); prec *= 2) {
        rs_alg_refine(b, prec);
        arb_fmpz_poly_evaluate_arb(y, g, b->x, prec);
        if (arb_is_positive(y)) sg = 1;
        else if (arb_is_negative(y)) sg = -1;
    }
    arb_clear(y);
    return sg;
}

/* the domain polynomials' signs say whether a sample is admissible */
static int cad_outside(const cad_t *c, const signed char *sg)
{
    slong k;
    for (k = 0; k < c->nf; k++)
        if (c->kind[k] == K_DOMAIN && (sg[k] < 0 || (sg[k] == 0 && !c->closed[k]))) return 1;
    return 0;
}

static cell_t *cad_new_cell(cad_t *c, int dim, slong col)
{
    cell_t *e;
    c->cells = flint_realloc(c->cells, (c->ncells + 1) * sizeof(cell_t));
    e = c->cells + c->ncells++;
    memset(e, 0, sizeof *e);
    e->dim = dim;
    e->col = col;
    e->sec = -1;
    e->sg = flint_calloc(c->nf, 1);
    return e;
}

/* step 3 for one column N1 = a0 (rational); sector: the column is 2-D */
static int cad_column(cad_t *c, const fmpq_t a0, int sector, slong col)
{
    const rs_scheme_struct *s = c->s;
    fmpz_poly_struct *g = flint_malloc(c->nf * sizeof(fmpz_poly_struct));
    rs_alg_t *roots = NULL;
    slong nroots = 0, i, k, j;
    fmpz_mpoly_t t, pa;
    fmpq vals[2];
    int r = RS_OK;
    fmpz_mpoly_init(t, s->zctx);
    fmpz_mpoly_init(pa, s->zctx);
    fmpq_init(vals + 0); fmpq_init(vals + 1);
    fmpq_set(vals + 0, a0);
    for (k = 0; k < c->nf; k++) {
        fmpz_poly_init(g + k);
        rs_an_forall_subst(t, c->f + k, c->av, a0, s->zctx);
        if (!fmpz_mpoly_get_fmpz_poly(g + k, t, c->bv, s->zctx)) fmpz_poly_zero(g + k);
        if (fmpz_poly_degree(g + k) >= 1) rs_alg_roots_append(&roots, &nroots, g + k, 0);
    }
    rs_alg_sort(roots, nroots);
    for (i = 0, j = 0; i < nroots; i++) {
        if (j > 0 && rs_alg_cmp(roots + j - 1, roots + i) == 0) { rs_alg_clear(roots + i); continue; }
        if (j != i) roots[j] = roots[i];
        j++;
    }
    nroots = j;
    if (nroots > 0) {
        double lo = rs_alg_double(roots), hi = rs_alg_double(roots + nroots - 1);
        if (lo < c->blo) c->blo = lo;
        if (hi > c->bhi) c->bhi = hi;
    }
    if (c->cx == NULL && c->qd == NULL) rs_an_forall_subst(pa, c->v->cp->p, c->av, a0, s->zctx);
    /* cells from below: sector, root, sector, ..., sector */
    for (i = 0; i <= 2 * nroots && r == RS_OK; i++) {
        int on_root = i % 2 == 1;
        rs_alg_t *lo = i / 2 > 0 || on_root ? roots + (on_root ? i / 2 : i / 2 - 1) : NULL;
        rs_alg_t *hi = (i / 2 < nroots) ? roots + i / 2 : NULL;
        cell_t *e = cad_new_cell(c, (sector ? 1 : 0) + (on_root ? 0 : 1), col);
        rs_alg_t bs;
        rs_alg_init(&bs);
        r = rs_budget_check(c->run->err, "region N1, N2 (cells)");
        if (on_root) {
            rs_alg_t *rt = roots + i / 2;
            for (k = 0; k < c->nf; k++) e->sg[k] = (signed char) upoly_sign_at(g + k, rt);
            e->b = rs_alg_json(rt, c->bn);
            for (k = 0; k < c->nf && e->sec < 0; k++) if (e->sg[k] == 0 && !fmpz_poly_is_zero(g + k)) e->sec = k;
            e->outside = cad_outside(c, e->sg);
            if (!e->outside && r == RS_OK) {
                if (rt->rational) {
                    fmpq_set(vals + 1, rt->q);
                    r = cad_sample_status(e, c, vals);
                } else if (c->cx != NULL) {
                    cx_pt_t pt = {a0, NULL, NULL, rt, NULL, NULL, NULL, NULL};
                    e->st = cx_status(c, &pt);
                    cx_marginal_at(c, e, &pt);
                    e->decided = 1;
                } else if (c->qd != NULL) {
                    e->decided = qd_line_status(&e->st, c, a0, NULL, rt);
                } else if (!fmpz_mpoly_is_zero(pa, s->zctx)) {
                    e->decided = rs_alg_status(&e->st, pa, c->bv, rt, s);
                }
            }
        } else {
            bs.rational = 1;
            rs_alg_between(bs.q, lo, hi);
            for (k = 0; k < c->nf; k++) e->sg[k] = (signed char) upoly_sign_at(g + k, &bs);
            e->b = rs_json_fmpq(bs.q);
            e->outside = cad_outside(c, e->sg);
            if (!e->outside && r == RS_OK) {
                fmpq_set(vals + 1, bs.q);
                r = cad_sample_status(e, c, vals);
            }
        }
        e->a = rs_json_fmpq(a0);
        (void) hi;
        rs_alg_clear(&bs);
    }
    for (k = 0; k < c->nf; k++) fmpz_poly_clear(g + k);
    flint_free(g);
    for (i = 0; i < nroots; i++) rs_alg_clear(roots + i);
    free(roots);
    fmpz_mpoly_clear(t, s->zctx);
    fmpz_mpoly_clear(pa, s->zctx);
    fmpq_clear(vals + 0); fmpq_clear(vals + 1);
    return r;
}

/* f (in N1, N2 only) at (A(gamma), B(gamma)) in Q(gamma) = Q[z]/(m) */
static void cad_eval_field(fmpq_poly_t out, const cad_t *c, const fmpz_mpoly_t f, const fmpq_poly_t A,
                           const fmpq_poly_t B, const fmpq_poly_t m)
{
    rs_region_eval_field(out, f, c->av, c->bv, A, B, m, c->s->zctx);
}

void rs_region_eval_field(fmpq_poly_t out, const fmpz_mpoly_t f, slong av, slong bv, const fmpq_poly_t A,
                          const fmpq_poly_t B, const fmpq_poly_t m, const fmpz_mpoly_ctx_t ctx)
{
    slong da = fmpz_mpoly_degree_si(f, av, ctx), db = fmpz_mpoly_degree_si(f, bv, ctx), i;
    fmpq_poly_struct *pa = flint_malloc((FLINT_MAX(da, 0) + 1) * sizeof(fmpq_poly_struct));
    fmpq_poly_struct *pb = flint_malloc((FLINT_MAX(db, 0) + 1) * sizeof(fmpq_poly_struct));
    fmpq_poly_t t;
    fmpz_t cf;
    fmpq_poly_init(t);
    fmpz_init(cf);
    for (i = 0; i <= FLINT_MAX(da, 0); i++) {
        fmpq_poly_init(pa + i);
        if (i == 0) fmpq_poly_one(pa); else { fmpq_poly_mul(pa + i, pa + i - 1, A); fmpq_poly_rem(pa + i, pa + i, m); }
    }
    for (i = 0; i <= FLINT_MAX(db, 0); i++) {
        fmpq_poly_init(pb + i);
        if (i == 0) fmpq_poly_one(pb); else { fmpq_poly_mul(pb + i, pb + i - 1, B); fmpq_poly_rem(pb + i, pb + i, m); }
    }
    fmpq_poly_zero(out);
    for (i = 0; i < fmpz_mpoly_length(f, ctx); i++) {
        slong ea = fmpz_mpoly_get_term_var_exp_si(f, i, av, ctx);
        slong eb = fmpz_mpoly_get_term_var_exp_si(f, i, bv, ctx);
        fmpz_mpoly_get_term_coeff_fmpz(cf, f, i, ctx);
        fmpq_poly_mul(t, pa + ea, pb + eb);
        fmpq_poly_scalar_mul_fmpz(t, t, cf);
        fmpq_poly_add(out, out, t);
    }
    fmpq_poly_rem(out, out, m);
    for (i = 0; i <= FLINT_MAX(da, 0); i++) fmpq_poly_clear(pa + i);
    for (i = 0; i <= FLINT_MAX(db, 0); i++) fmpq_poly_clear(pb + i);
    flint_free(pa);
    flint_free(pb);
    fmpq_poly_clear(t);
    fmpz_clear(cf);
}

/* 1 when f(alpha, beta) may vanish: its Arb enclosure still contains 0 at
 * 256 bits (exactly zero or very small: decided in the tower then) */
static int cad_may_vanish(const cad_t *c, const fmpz_mpoly_t f, rs_alg_t *al, rs_alg_t *be)
{
    slong prec, i;
    int may = 1;
    arb_t y, t, u;
    fmpz_t cf;
    arb_init(y); arb_init(t); arb_init(u);
    fmpz_init(cf);
    for (prec = 64; prec <= 256 && may; prec *= 2) {
        rs_alg_refine(al, prec);
        rs_alg_refine(be, prec);
        arb_zero(y);
        for (i = 0; i < fmpz_mpoly_length(f, c->s->zctx); i++) {
            fmpz_mpoly_get_term_coeff_fmpz(cf, f, i, c->s->zctx);
            arb_pow_ui(t, al->x, (ulong) fmpz_mpoly_get_term_var_exp_si(f, i, c->av, c->s->zctx), prec);
            arb_pow_ui(u, be->x, (ulong) fmpz_mpoly_get_term_var_exp_si(f, i, c->bv, c->s->zctx), prec);
            arb_mul(t, t, u, prec);
            arb_addmul_fmpz(y, t, cf, prec);
        }
        may = arb_contains_zero(y);
    }
    arb_clear(y); arb_clear(t); arb_clear(u);
    fmpz_clear(cf);
    return may;
}

/* the signs at (alpha, b0), b0 rational, and the status there (exact in
 * Q(alpha)); returns the status's decidedness */
static int cad_alg_rational(cad_t *c, cell_t *e, rs_alg_t *al, const fmpq_t b0)
{
    const rs_scheme_struct *s = c->s;
    fmpz_mpoly_t t;
    fmpz_poly_t u;
    slong k;
    int dec = 0;
    fmpz_mpoly_init(t, s->zctx);
    fmpz_poly_init(u);
    for (k = 0; k < c->nf; k++) {
        rs_an_forall_subst(t, c->f + k, c->bv, b0, s->zctx);
        if (!fmpz_mpoly_get_fmpz_poly(u, t, c->av, s->zctx)) fmpz_poly_zero(u);
        e->sg[k] = (signed char) upoly_sign_at(u, al);
    }
    e->outside = cad_outside(c, e->sg);
    if (!e->outside && c->cx != NULL) {
        cx_pt_t pt = {NULL, b0, al, NULL, NULL, NULL, NULL, NULL};
        e->st = cx_status(c, &pt);
        cx_marginal_at(c, e, &pt);
        dec = 1;
    } else if (!e->outside && c->qd != NULL) {
        dec = qd_line_status(&e->st, c, NULL, b0, al);
    } else if (!e->outside) {
        rs_an_forall_subst(t, c->v->cp->p, c->bv, b0, s->zctx);
        if (!fmpz_mpoly_is_zero(t, s->zctx)) dec = rs_alg_status(&e->st, t, c->av, al, s);
    }
    fmpz_mpoly_clear(t, s->zctx);
    fmpz_poly_clear(u);
    return dec;
}

/* f(x, y) in ball arithmetic (terms summed as cad_may_vanish does) */
static void cad_eval_acb(acb_t out, const cad_t *c, const fmpz_mpoly_t f, const acb_t x, const acb_t y, slong prec)
{
    slong i;
    acb_t t, u;
    fmpz_t cf;
    acb_init(t); acb_init(u);
    fmpz_init(cf);
    acb_zero(out);
    for (i = 0; i < fmpz_mpoly_length(f, c->s->zctx); i++) {
        fmpz_mpoly_get_term_coeff_fmpz(cf, f, i, c->s->zctx);
        acb_pow_ui(t, x, (ulong) fmpz_mpoly_get_term_var_exp_si(f, i, c->av, c->s->zctx), prec);
        acb_pow_ui(u, y, (ulong) fmpz_mpoly_get_term_var_exp_si(f, i, c->bv, c->s->zctx), prec);
        acb_mul(t, t, u, prec);
        if (c->qd != NULL) {
            /* over Q(sqrt d): p's sqrt(d) is a variable of the scheme */
            slong e = fmpz_mpoly_get_term_var_exp_si(f, i, c->s->sqrt_var, c->s->zctx);
            if (e > 0) {
                acb_set_si(u, c->s->sqrt_d);
                acb_sqrt(u, u, prec);
                acb_pow_ui(u, u, (ulong) e, prec);
                acb_mul(t, t, u, prec);
            }
        }
        acb_addmul_fmpz(out, t, cf, prec);
    }
    acb_clear(t); acb_clear(u);
    fmpz_clear(cf);
}

/* The sign of f(alpha, beta) without a tower (the tower's degree is over
 * CAD_MAX_TOWER_DEGREE).  u = Res_x(m_alpha, f) = lc^d prod_i f(alpha_i, y)
 * over the conjugates alpha_i, so the multiplicity e of m_beta in u is the
 * sum over i of beta's multiplicity mu_i as a root of f(alpha_i, y).  With
 * balls: mu_i = 0 where f(alpha_i, beta) excludes 0; elsewhere mu_i <= j_i,
 * the first order of y-derivative whose ball excludes 0.  When those j_i
 * sum to e, every mu_i = j_i >= 1: f(alpha_i, beta) = 0 exactly for them
 * (a fold of the curve, a double root in y, included), zero iff alpha is
 * one of them.  Nonzero signs by refining the real enclosures.  Returns 0
 * when the balls do not separate by 4096 bits. */
static int cad_sign_norm(int *sg, const cad_t *c, const fmpz_mpoly_t f, const fmpz_poly_t u, rs_alg_t *al,
                         rs_alg_t *be)
{
    const fmpz_mpoly_ctx_struct *ctx = c->s->zctx;
    slong da = fmpz_poly_degree(al->minpoly), e = 0, prec, i, j;
    int done = 0, zero = 0;
    fmpz_poly_t q, r;
    fmpz_mpoly_struct *df;
    acb_ptr ra = _acb_vec_init(da);
    acb_t y, v;
    fmpz_poly_init(q); fmpz_poly_init(r);
    acb_init(y); acb_init(v);
    fmpz_poly_set(r, u);
    while (!fmpz_poly_is_zero(r) && fmpz_poly_divides(q, r, be->minpoly)) { e++; fmpz_poly_swap(q, r); }
    /* df[j] = the j-th y-derivative, j = 0..e */
    df = flint_malloc((e + 1) * sizeof(fmpz_mpoly_struct));
    for (j = 0; j <= e; j++) {
        fmpz_mpoly_init(df + j, ctx);
        if (j == 0) fmpz_mpoly_set(df, f, ctx);
        else fmpz_mpoly_derivative(df + j, df + j - 1, c->bv, ctx);
    }
    if (e == 0) done = 1;   /* no conjugate vanishes: f(alpha, beta) != 0 */
    for (prec = 64; !done && prec <= 4096; prec *= 2) {
        slong sum = 0, ok = 1, self = 0;
        rs_radius_complex_roots(ra, al->minpoly, prec);
        rs_alg_refine(be, prec);
        acb_set_arb(y, be->x);
        for (i = 0; i < da && ok; i++) {
            cad_eval_acb(v, c, f, ra + i, y, prec);
            if (!acb_contains_zero(v)) continue;
            for (j = 1; j <= e; j++) {
                cad_eval_acb(v, c, df + j, ra + i, y, prec);
                if (!acb_contains_zero(v)) break;
            }
            if (j > e) ok = 0;
            sum += j;
            if (i == al->idx) self = 1;
        }
        if (ok && sum == e) { done = 1; zero = self; }
    }
    *sg = 0;
    if (done && !zero) {
        /* f(alpha, beta) != 0: refine until the real ball has a sign */
        for (prec = 64; *sg == 0 && prec <= (1L << 16); prec *= 2) {
            acb_t x;
            acb_init(x);
            rs_alg_refine(al, prec);
            rs_alg_refine(be, prec);
            acb_set_arb(x, al->x);
            acb_set_arb(y, be->x);
            cad_eval_acb(v, c, f, x, y, prec);
            if (arb_is_positive(acb_realref(v))) *sg = 1;
            else if (arb_is_negative(acb_realref(v))) *sg = -1;
            acb_clear(x);
        }
        if (*sg == 0) done = 0;
    }
    for (j = 0; j <= e; j++) fmpz_mpoly_clear(df + j, ctx);
    flint_free(df);
    _acb_vec_clear(ra, da);
    acb_clear(y); acb_clear(v);
    fmpz_poly_clear(q); fmpz_poly_clear(r);
    return done;
}

/* The status at (alpha, beta) without a tower, where balls decide it (p's
 * coefficients as real balls at the refined enclosures, leading one
 * excluding 0): stable when Schur's recursion certifies every root inside
 * (rs_radius_balls_inside); unstable when |a_0| > |a_n| (the product of the
 * roots' moduli exceeds 1) or acb_poly_find_roots isolates every root and
 * one ball lies strictly outside.  A root on the circle (marginal or not)
 * is never decided here: returns 0 then (after 2048 bits). */
static int cad_status_balls(rs_status_t *st, const cad_t *c, const fmpz_mpoly_t p, rs_alg_t *al, rs_alg_t *be,
                            slong maxprec)
{
    const rs_scheme_struct *s = c->s;
    slong lv = s->lambda_var, n = fmpz_mpoly_degree_si(p, lv, s->zctx), j, prec;
    fmpz_mpoly_struct *cf = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    acb_poly_t P;
    acb_ptr rt = _acb_vec_init(FLINT_MAX(n, 1));
    acb_t x, y, v;
    arb_t a, b;
    arb_ptr re = _arb_vec_init(n + 1);
    int dec = 0;
    for (j = 0; j <= n; j++) fmpz_mpoly_init(cf + j, s->zctx);
    rs_polyfmt_coeffs(cf, p, lv, s->zctx);   /* once, not per precision */
    arb_init(b);
    acb_poly_init(P);
    acb_init(x); acb_init(y); acb_init(v);
    arb_init(a);
    for (prec = 128; !dec && n >= 1 && prec <= maxprec; prec *= 2) {
        slong in = 0, out = 0;
        int by_coeffs = 0;
        rs_alg_refine(al, prec);
        rs_alg_refine(be, prec);
        acb_set_arb(x, al->x);
        acb_set_arb(y, be->x);
        acb_poly_zero(P);
        for (j = 0; j <= n; j++) {
            cad_eval_acb(v, c, cf + j, x, y, prec);
            acb_poly_set_coeff_acb(P, j, v);
        }
        if (acb_poly_length(P) != n + 1 || acb_contains_zero(P->coeffs + n)) continue;
        for (j = 0; j <= n; j++) arb_set(re + j, acb_realref(P->coeffs + j));
        /* the coefficient rules: Schur's recursion on balls, |a_0| > |a_n| */
        if (rs_radius_balls_inside(re, n, prec)) { *st = RS_STATUS_STABLE; by_coeffs = 1; }
        arb_abs(a, re + 0);
        arb_abs(b, re + n);
        if (!by_coeffs && arb_gt(a, b)) { *st = RS_STATUS_UNSTABLE; by_coeffs = 1; }
        /* the root balls: a verdict of their own, and the second method for
         * the coefficient rules' (a disagreement is a bug: exit 3, the cell
         * left undecided) */
        if (acb_poly_find_roots(rt, P, NULL, 0, prec) == n) {
            for (j = 0; j < n; j++) {
                acb_abs(a, rt + j, prec);
                arb_sub_ui(a, a, 1, prec);
                if (arb_is_negative(a)) in++;
                else if (arb_is_positive(a)) out++;
            }
            if (out > 0 || in == n) {
                rs_status_t rst = out > 0 ? RS_STATUS_UNSTABLE : RS_STATUS_STABLE;
                if (by_coeffs && rst != *st) {
                    c->run->outcome |= RS_OUTCOME_INCONSISTENT;
                    break;
                }
                *st = rst;
                dec = 1;
            }
            /* else a ball meets the circle: refined, then left undecided */
        }
        if (by_coeffs) dec = 1;
    }
    for (j = 0; j <= n; j++) fmpz_mpoly_clear(cf + j, s->zctx);
    flint_free(cf);
    acb_poly_clear(P);
    _acb_vec_clear(rt, FLINT_MAX(n, 1));
    acb_clear(x); acb_clear(y); acb_clear(v);
    arb_clear(a); arb_clear(b);
    _arb_vec_clear(re, n + 1);
    return dec;
}

/* ---- polynomials over a number field (cx_marginal_rel) -------------------
 * A polynomial over K = Q[t]/(M) (M irreducible) is an array of fmpq_polys
 * reduced mod M, a length (leading coefficient nonzero). */

static slong nfp_trim(fmpq_poly_struct *a, slong len)
{
    while (len > 0 && fmpq_poly_is_zero(a + len - 1)) len--;
    return len;
}

/* a := a / lc(a) (len >= 1) */
static void nfp_monic(fmpq_poly_struct *a, slong len, const fmpq_poly_t M)
{
    fmpq_poly_t g, s, t;
    slong j;
    fmpq_poly_init(g); fmpq_poly_init(s); fmpq_poly_init(t);
    fmpq_poly_xgcd(g, s, t, a + len - 1, M);   /* s lc + t M = 1 */
    for (j = 0; j < len - 1; j++) { fmpq_poly_mul(a + j, a + j, s); fmpq_poly_rem(a + j, a + j, M); }
    fmpq_poly_one(a + len - 1);
    fmpq_poly_clear(g); fmpq_poly_clear(s); fmpq_poly_clear(t);
}

/* a := a mod b (b monic, lb >= 1); the new length */
static slong nfp_rem(fmpq_poly_struct *a, slong la, const fmpq_poly_struct *b, slong lb, const fmpq_poly_t M)
{
    fmpq_poly_t q, t;
    slong i, j;
    fmpq_poly_init(q); fmpq_poly_init(t);
    for (i = la - 1; i >= lb - 1; i--) {
        if (fmpq_poly_is_zero(a + i)) continue;
        fmpq_poly_set(q, a + i);
        for (j = 0; j < lb; j++) {
            fmpq_poly_mul(t, q, b + j);
            fmpq_poly_sub(a + i - lb + 1 + j, a + i - lb + 1 + j, t);
            fmpq_poly_rem(a + i - lb + 1 + j, a + i - lb + 1 + j, M);
        }
    }
    fmpq_poly_clear(q); fmpq_poly_clear(t);
    return nfp_trim(a, FLINT_MIN(la, lb - 1));
}

/* a := gcd(a, b) monic (b destroyed); the length (1: a unit; -1: the
 * budget ran out) */
static slong nfp_gcd(fmpq_poly_struct *a, slong la, fmpq_poly_struct *b, slong lb, const fmpq_poly_t M)
{
    la = nfp_trim(a, la);
    lb = nfp_trim(b, lb);
    while (lb > 0) {
        slong j;
        if (rs_budget_check(NULL, "a gcd over a number field") != RS_OK) return -1;
        nfp_monic(b, lb, M);
        la = nfp_rem(a, la, b, lb, M);
        for (j = 0; j < FLINT_MAX(la, lb); j++) fmpq_poly_swap(a + j, b + j);
        j = la; la = lb; lb = j;
    }
    if (la > 0) nfp_monic(a, la, M);
    return la;
}

/* f (in N1, N2) as a polynomial in variable pv over Q(t) = Q[t]/(M), t
 * the other variable: out[0..deg] (deg_pv f + 1 entries, initialised); the
 * length */
static slong nfp_from_mpoly(fmpq_poly_struct *out, const cad_t *c, const fmpz_mpoly_t f, slong pv,
                            const fmpq_poly_t M)
{
    const fmpz_mpoly_ctx_struct *ctx = c->s->zctx;
    slong fv = pv == c->bv ? c->av : c->bv, d = fmpz_mpoly_degree_si(f, pv, ctx), i;
    fmpz_t cf;
    fmpz_init(cf);
    for (i = 0; i <= d; i++) fmpq_poly_zero(out + i);
    for (i = 0; i < fmpz_mpoly_length(f, ctx); i++) {
        slong ea = fmpz_mpoly_get_term_var_exp_si(f, i, fv, ctx), eb = fmpz_mpoly_get_term_var_exp_si(f, i, pv, ctx);
        fmpz_t old;
        fmpz_init(old);
        fmpz_mpoly_get_term_coeff_fmpz(cf, f, i, ctx);
        fmpq_poly_get_coeff_fmpz(old, out + eb, ea);  /* out + eb is not yet reduced: numerators exact */
        fmpz_add(old, old, cf);
        fmpq_poly_set_coeff_fmpz(out + eb, ea, old);
        fmpz_clear(old);
    }
    for (i = 0; i <= d; i++) fmpq_poly_rem(out + i, out + i, M);
    fmpz_clear(cf);
    return nfp_trim(out, d + 1);
}

/* complex mode, a circle-locus cell (alpha, beta) whose tower
 * deg alpha * deg beta is above the cap: the field Q(alpha, beta) is often
 * just Q(beta) (the plane is symmetric in N2: beta^2 in Q(alpha) makes it
 * 2 deg alpha, not 2 deg alpha^2).  alpha lies in Q(beta) when the gcd over
 * Q(beta) of m_alpha(x) and the f_k(x, beta) vanishing at the cell is
 * linear (only x = alpha is common): alpha = A(beta).  Then cx_marginal_at
 * decides with the norms in Q(beta).  0: not done (deg beta above
 * CAD_MAX_MARGINAL_FIELD, alpha not found in Q(beta), the budget). */
static int cx_marginal_rel(cad_t *c, cell_t *e, rs_alg_t *al, rs_alg_t *be)
{
    const fmpz_mpoly_ctx_struct *ctx = c->s->zctx;
    slong da = fmpz_poly_degree(al->minpoly), db = fmpz_poly_degree(be->minpoly), k, j;
    int ok = 0;
    if (al->rational || be->rational) return 0;   /* the tower path had it */
    /* a line above CAD_MAX_LINE_DEGREE (AB3's of degree 11): its gcds over
     * Q(beta) took 6 s; the cells stay counted as open */
    if (da > CAD_MAX_LINE_DEGREE) return 0;
    if (db <= CAD_MAX_MARGINAL_FIELD) {
        /* Q(beta) first (k = 0): alpha lies in it when the gcd over Q(beta)
         * of m_alpha(x) and the f_k(x, beta) vanishing here is linear (only
         * x = alpha is common); the plane's sections mostly have it */
        slong dx = da, lp = da + 1, lq;
        fmpq_poly_struct *P, *Q;
        fmpq_poly_t Mb;
        for (k = 0; k < c->nf; k++) dx = FLINT_MAX(dx, fmpz_mpoly_degree_si(c->f + k, c->av, ctx));
        P = flint_malloc((dx + 1) * sizeof(fmpq_poly_struct));
        Q = flint_malloc((dx + 1) * sizeof(fmpq_poly_struct));
        for (j = 0; j <= dx; j++) { fmpq_poly_init(P + j); fmpq_poly_init(Q + j); }
        fmpq_poly_init(Mb);
        fmpq_poly_set_fmpz_poly(Mb, be->minpoly);
        for (j = 0; j <= da; j++) fmpq_poly_set_fmpz(P + j, al->minpoly->coeffs + j);
        for (k = 0; k < c->nf && lp > 2; k++) {
            if (e->sg[k] != 0 || fmpz_mpoly_degree_si(c->f + k, c->av, ctx) <= 0) continue;
            lq = nfp_from_mpoly(Q, c, c->f + k, c->av, Mb);
            if (lq > 0) lp = nfp_gcd(P, lp, Q, lq, Mb);
        }
        if (lp == 2) {
            /* x + p0: alpha = -p0(beta), beta = beta */
            fmpq_poly_t A, B;
            cx_pt_t pt = {NULL, NULL, NULL, NULL, NULL, NULL, NULL, NULL};
            fmpq_poly_init(A); fmpq_poly_init(B);
            fmpq_poly_neg(A, P + 0);
            fmpq_poly_set_coeff_si(B, 1, 1);
            fmpq_poly_rem(B, B, Mb);
            pt.A = A; pt.B = B; pt.m = Mb; pt.g = be;
            cx_marginal_at(c, e, &pt);
            ok = 1;
            fmpq_poly_clear(A); fmpq_poly_clear(B);
        }
        for (j = 0; j <= dx; j++) { fmpq_poly_clear(P + j); fmpq_poly_clear(Q + j); }
        flint_free(P); flint_free(Q);
        fmpq_poly_clear(Mb);
    }
    return ok;
}

/* complex mode, a section cell (alpha, beta) whose tower is above the cap:
 * the status from the cell's exact signs (cx_status_sg: lead and the deltas
 * are products of listed polynomials, whose signs cad_sign_norm gave),
 * checked against root balls of p conj(p) where they decide (every root
 * strictly inside, or one strictly outside; a disagreement is exit 3 and
 * the cell left undecided).  On the circle locus a not-stable cell is
 * unstable when a ball lies strictly outside; otherwise marginal or
 * unstable is decided by the norms in Q(beta) (cx_marginal_rel). */
static void cx_section_signs(cad_t *c, cell_t *e, rs_alg_t *al, rs_alg_t *be)
{
    const rs_region_cx_t *X = c->cx;
    rs_status_t st, bst = RS_STATUS_MARGINAL;
    int on = 0, bdec = 0;
    if (!cx_status_sg(&st, &on, c, e->sg)) {
        e->why = "a critical polynomial not a product of the listed ones (complex plane)";
        return;
    }
    /* on the locus a circle root keeps the balls open: 256 bits suffice to
     * see a root outside (off it they decide at 128 unless near the circle) */
    if (X->norm != NULL) bdec = cad_status_balls(&bst, c, X->norm + 0, al, be, on ? 256 : 1024);
    if (bdec && (bst == RS_STATUS_STABLE) != (st == RS_STATUS_STABLE)) {
        c->run->outcome |= RS_OUTCOME_INCONSISTENT;
        e->why = "the signs and the root balls disagree";
        return;
    }
    e->st = st;
    e->decided = 1;
    if (st == RS_STATUS_STABLE || !on || X->norm == NULL) return;
    if (bdec && bst == RS_STATUS_UNSTABLE) { e->balls = 1; return; }   /* a root strictly outside */
    {
        slong db = fmpz_poly_degree(be->minpoly);
        if (c->rel_cost + db * db > CAD_MARGINAL_REL_COST) {
            c->rel_skipped++;
            c->marginal_undecided++;
            return;
        }
        c->rel_cost += db * db;
    }
    if (!cx_marginal_rel(c, e, al, be)) c->marginal_undecided++;
}

/* step 3 for a column over an irrational N1 = alpha (a two-level tower):
 * the candidate N2 values are the real roots of Res_{N1}(m_alpha, f_k)
 * (the norms of f_k(alpha, N2)); a candidate beta is a section where some
 * f_k(alpha, N2) not identically 0 vanishes, decided exactly in
 * Q(alpha, beta) = Q(gamma) (rs_alg_primitive).  Sectors between have
 * rational N2 samples, decided in Q(alpha). */
static int cad_column_alg(cad_t *c, rs_alg_t *al, slong col)
{
    const rs_scheme_struct *s = c->s;
    slong lv = s->lambda_var, n = c->cx != NULL ? 0 : fmpz_mpoly_degree_si(c->v->cp->p, lv, s->zctx);
    rs_alg_t *cand = NULL;
    slong ncand = 0, i, j, k, nsec = 0, *sec = NULL;
    signed char **sgs = NULL;
    int *zero_line = flint_calloc(c->nf, sizeof(int)), r = RS_OK, too_big = 0, tower;
    fmpz_mpoly_t ma, t;
    fmpz_poly_t u;
    fmpq_poly_t m, A, B, v;
    fmpq_poly_struct *pc = flint_malloc((n + 1) * sizeof(fmpq_poly_struct));
    fmpz_poly_struct *norms = flint_malloc(c->nf * sizeof(fmpz_poly_struct));
    fmpz_mpoly_init(ma, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    fmpz_poly_init(u);
    fmpq_poly_init(m); fmpq_poly_init(A); fmpq_poly_init(B); fmpq_poly_init(v);
    for (j = 0; j <= n; j++) fmpq_poly_init(pc + j);
    fmpz_mpoly_set_fmpz_poly(ma, al->minpoly, c->av, s->zctx);
    for (k = 0; k < c->nf; k++) fmpz_poly_init(norms + k);
    for (k = 0; k < c->nf && r == RS_OK; k++) {
        slong d = fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx);
        if (d <= 0) continue;
        r = rs_budget_check(c->run->err, "region N1, N2 (irrational columns)");
        if (r == RS_OK && fmpz_mpoly_resultant(t, ma, c->f + k, c->av, s->zctx)
            && fmpz_mpoly_get_fmpz_poly(u, t, c->bv, s->zctx)) {
            if (fmpz_poly_is_zero(u)) zero_line[k] = 1;   /* m_alpha divides f_k */
            else rs_alg_roots_append(&cand, &ncand, u, 0);
            fmpz_poly_set(norms + k, u);
        }
    }
    rs_alg_sort(cand, ncand);
    for (i = 0, j = 0; i < ncand; i++) {
        if (j > 0 && rs_alg_cmp(cand + j - 1, cand + i) == 0) { rs_alg_clear(cand + i); continue; }
        if (j != i) cand[j] = cand[i];
        j++;
    }
    ncand = j;
    /* which candidates are sections, and their signs (exact in Q(gamma)) */
    sec = flint_malloc((ncand + 1) * sizeof(slong));
    sgs = flint_calloc(ncand + 1, sizeof(signed char *));
    for (i = 0; i < ncand && r == RS_OK; i++) {
        rs_alg_t g;
        int is_sec = 0;
        r = rs_budget_check(c->run->err, "region N1, N2 (irrational columns)");
        if (r != RS_OK) break;
        sgs[i] = flint_calloc(c->nf, 1);
        /* not a section of this line (no f_k(alpha, .) vanishes at beta,
         * certified by Arb): no tower needed */
        for (k = 0; k < c->nf && !is_sec; k++)
            if (!zero_line[k] && fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx) > 0)
                is_sec = cad_may_vanish(c, c->f + k, al, cand + i);
        if (!is_sec) { rs_alg_clear(cand + i); continue; }
        is_sec = 0;
        /* the tower's degree bounds the cost (resultants and gcds over
         * Q(gamma)); above it the signs come from the norms (cad_sign_norm)
         * and the status from root balls where they decide it */
        tower = fmpz_poly_degree(al->minpoly) * fmpz_poly_degree(cand[i].minpoly) <= cad_max_tower(c);
        rs_alg_init(&g);
        if (tower && !rs_alg_primitive(&g, A, B, al, cand + i)) {
            rs_alg_clear(&g);
            r = rs_budget_check(c->run->err, "region N1, N2 (irrational columns)");
            if (r == RS_OK) r = RS_ERR_MATH;
            break;
        }
        if (tower) fmpq_poly_set_fmpz_poly(m, g.minpoly);
        for (k = 0; k < c->nf; k++) {
            int sk = 0;
            if (tower) {
                cad_eval_field(v, c, c->f + k, A, B, m);
                sk = rs_alg_sign(v, &g);
            } else if (zero_line[k]) {
                sk = 0;
            } else if (fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx) <= 0) {
                if (!fmpz_mpoly_get_fmpz_poly(u, c->f + k, c->av, s->zctx)) fmpz_poly_zero(u);
                sk = upoly_sign_at(u, al);
            } else if (!cad_sign_norm(&sk, c, c->f + k, norms + k, al, cand + i)) {
                break;
            }
            sgs[i][k] = (signed char) sk;
            if (sgs[i][k] == 0 && !zero_line[k] && fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx) > 0) is_sec = 1;
        }
        if (k < c->nf) {
            /* a sign the balls did not separate: the column as before */
            rs_alg_clear(&g);
            too_big = 1;
            break;
        }
        if (is_sec) {
            cell_t *e = cad_new_cell(c, 0, col);   /* placed below, in order */
            memcpy(e->sg, sgs[i], c->nf);
            for (k = 0; k < c->nf && e->sec < 0; k++)
                if (e->sg[k] == 0 && !zero_line[k] && fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx) > 0) e->sec = k;
            e->a = rs_alg_json(al, c->an);
            e->b = rs_alg_json(cand + i, c->bn);
            e->outside = cad_outside(c, e->sg);
            if (!e->outside && !tower && c->cx != NULL) {
                cx_section_signs(c, e, al, cand + i);
            } else if (!e->outside && !tower) {
                /* no tower: balls decide stable / unstable; a root on the
                 * circle needs the tower after all, when it is not too big */
                /* over Q(sqrt d) the exact tower first (its verdict is
                 * cross-checked by jury's conditions), the balls after */
                int qt = c->qd != NULL
                         && fmpz_poly_degree(al->minpoly) * fmpz_poly_degree(cand[i].minpoly) <= CAD_MAX_TOWER_DEGREE_CELL
                         && rs_alg_primitive(&g, A, B, al, cand + i);
                e->decided = qt && c->qd->field(&e->st, A, B, &g, c->qd->arg);
                if (!e->decided) {
                    e->decided = c->cx == NULL && (c->qd == NULL || !c->qd->complex_p)
                                 && cad_status_balls(&e->st, c, c->v->cp->p, al, cand + i, 2048);
                    e->balls = e->decided;
                }
                if (!e->decided && c->cx == NULL && c->qd == NULL
                    && fmpz_poly_degree(al->minpoly) * fmpz_poly_degree(cand[i].minpoly) <= CAD_MAX_TOWER_DEGREE_CELL
                    && rs_alg_primitive(&g, A, B, al, cand + i)) {
                    fmpq_poly_set_fmpz_poly(m, g.minpoly);
                    e->decided = cad_status_field(&e->st, c, c->v->cp->p, A, B, m, &g);
                }
                if (!e->decided)
                    e->why = c->cx != NULL ? "a section whose tower is above the cap (complex plane)"
                             : c->qd != NULL && c->qd->complex_p ? "a section whose tower over Q(sqrt d)(i) is "
                               "above 64 (no ball route for p over Q(sqrt d)(i))"
                             : "a section with a root on the circle, tower above 64";
                r = rs_budget_check(c->run->err, "region N1, N2 (irrational columns)");
            } else if (!e->outside && c->cx != NULL) {
                cx_pt_t pt = {NULL, NULL, NULL, NULL, A, B, m, &g};
                e->st = cx_status(c, &pt);
                cx_marginal_at(c, e, &pt);
                e->decided = 1;
            } else if (!e->outside && c->qd != NULL) {
                e->decided = c->qd->field(&e->st, A, B, &g, c->qd->arg);
                if (!e->decided && c->qd->complex_p) e->why = CAD_QDC_WHY;
            } else if (!e->outside) {
                e->decided = cad_status_field(&e->st, c, c->v->cp->p, A, B, m, &g);
            }
            sec[nsec] = c->ncells - 1;
            cand[nsec++] = cand[i];   /* the sections first, in order (i >= nsec - 1) */
        } else {
            rs_alg_clear(cand + i);
        }
        rs_alg_clear(&g);
    }
    for (j = i; j < ncand; j++) rs_alg_clear(cand + j);   /* not reached: a budget stop or too big */
    if (r == RS_OK && too_big) {
        /* the column is left undecided as a whole (one cell, N2 null) */
        cell_t *e;
        for (i = 0; i < nsec; i++) {
            cell_t *x = c->cells + sec[i];
            flint_free(x->sg);
            json_decref(x->a);
            json_decref(x->b);
            rs_alg_clear(cand + i);
        }
        c->ncells -= nsec;
        e = cad_new_cell(c, 1, col);
        e->a = rs_alg_json(al, c->an);
        e->b = json_null();
        e->why = "a sign the norms and balls did not separate";
        c->undecided_lines++;
    } else if (r == RS_OK) {
        /* interleave: sector, section, ..., sector (the sections were made
         * in increasing order; move them after their sectors) */
        cell_t *secs = flint_malloc((nsec + 1) * sizeof(cell_t));
        for (i = 0; i < nsec; i++) secs[i] = c->cells[sec[i]];
        c->ncells -= nsec;
        for (i = 0; i <= nsec && r == RS_OK; i++) {
            fmpq_t b0;
            cell_t *e;
            fmpq_init(b0);
            rs_alg_between(b0, i > 0 ? cand + i - 1 : NULL, i < nsec ? cand + i : NULL);
            e = cad_new_cell(c, 1, col);
            e->a = rs_alg_json(al, c->an);
            e->b = rs_json_fmpq(b0);
            e->decided = cad_alg_rational(c, e, al, b0);
            if (!e->outside && !e->decided) c->undecided_lines++;
            if (nsec > 0 && i < nsec) {
                e = cad_new_cell(c, 0, col);
                flint_free(e->sg);
                *e = secs[i];
                if (!e->outside && !e->decided) c->undecided_lines++;
            }
            fmpq_clear(b0);
            r = rs_budget_check(c->run->err, "region N1, N2 (irrational columns)");
        }
        flint_free(secs);
        for (i = 0; i < nsec; i++) rs_alg_clear(cand + i);
    } else {
        for (i = 0; i < nsec; i++) rs_alg_clear(cand + i);
    }
    for (i = 0; i < ncand + 1; i++) flint_free(sgs[i]);
    flint_free(sgs);
    flint_free(sec);
    free(cand);
    flint_free(zero_line);
    for (k = 0; k < c->nf; k++) fmpz_poly_clear(norms + k);
    flint_free(norms);
    for (j = 0; j <= n; j++) fmpq_poly_clear(pc + j);
    flint_free(pc);
    fmpz_mpoly_clear(ma, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
    fmpz_poly_clear(u);
    fmpq_poly_clear(m); fmpq_poly_clear(A); fmpq_poly_clear(B); fmpq_poly_clear(v);
    return r;
}

/* every column: sectors between the critical N1 values, sections at them */
static int cad_lift(cad_t *c)
{
    slong i;
    int r = RS_OK;
    for (i = 0; i <= 2 * c->ncrit && r == RS_OK; i++) {
        fmpq_t a0;
        fmpq_init(a0);
        if (i % 2 == 0) {
            rs_alg_between(a0, i > 0 ? c->crit + i / 2 - 1 : NULL, i / 2 < c->ncrit ? c->crit + i / 2 : NULL);
            r = cad_column(c, a0, 1, i);
        } else if (c->crit[i / 2].rational) {
            r = cad_column(c, c->crit[i / 2].q, 0, i);
        } else {
            /* an irrational N1 value: is it inside the domain at all? */
            rs_alg_t *al = c->crit + i / 2;
            const rs_bound_t *b = c->bounds + c->av;
            int in = 1;
            if (b->has_lo) { rs_alg_t e; rs_alg_init(&e); e.rational = 1; fmpq_set(e.q, b->lo); in &= rs_alg_cmp(al, &e) > 0; rs_alg_clear(&e); }
            if (b->has_hi) { rs_alg_t e; rs_alg_init(&e); e.rational = 1; fmpq_set(e.q, b->hi); in &= rs_alg_cmp(al, &e) < 0; rs_alg_clear(&e); }
            if (in && fmpz_poly_degree(al->minpoly) <= (c->cx != NULL ? CAD_MAX_LINE_DEGREE_CX : CAD_MAX_LINE_DEGREE)) {
                r = cad_column_alg(c, al, i);
            } else if (in) {
                cell_t *e = cad_new_cell(c, 1, i);
                e->a = rs_alg_json(al, c->an);
                e->b = json_null();
                e->why = "line degree above 8";
                c->undecided_lines++;
            }
        }
        fmpq_clear(a0);
    }
    return r;
}

/* ---- the formula --------------------------------------------------------- */

/* masks: bit 0 "< 0", bit 1 "= 0", bit 2 "> 0"; 7: no condition */
static int sg_bit(signed char s) { return s < 0 ? 1 : (s == 0 ? 2 : 4); }

static int conj_holds(const unsigned char *m, const signed char *sg, slong nf)
{
    slong k;
    for (k = 0; k < nf; k++) if (!(m[k] & sg_bit(sg[k]))) return 0;
    return 1;
}

/* 1 when no decided cell of another status satisfies m */
static int conj_safe(const cad_t *c, const unsigned char *m, rs_status_t target)
{
    slong i;
    for (i = 0; i < c->ncells; i++) {
        const cell_t *e = c->cells + i;
        if (!e->decided || e->outside || e->st == target) continue;
        if (conj_holds(m, e->sg, c->nf)) return 0;
    }
    return 1;
}

/* the cells of status target as an OR of ANDs; *conflict when a cell of
 * another status has the same signs as one of them */
static unsigned char **cad_formula(slong *nout, int *conflict, const cad_t *c, rs_status_t target)
{
    unsigned char **F = NULL;
    slong n = 0, i, k, j;
    static const unsigned char widen[] = {7, 6, 3, 5};   /* drop, >= 0, <= 0, != 0 */
    for (i = 0; i < c->ncells; i++) {
        const cell_t *e = c->cells + i;
        unsigned char *m;
        int dup = 0;
        if (!e->decided || e->outside || e->st != target) continue;
        for (j = 0; j < n && !dup; j++) dup = conj_holds(F[j], e->sg, c->nf);
        if (dup) continue;
        m = flint_malloc(c->nf);
        for (k = 0; k < c->nf; k++) m[k] = (unsigned char) sg_bit(e->sg[k]);
        if (!conj_safe(c, m, target)) { *conflict = 1; flint_free(m); continue; }
        /* widen: domain ends first, then projection factors, then the rest */
        for (j = 0; j < 3; j++) {
            int kd = j == 0 ? K_DOMAIN : (j == 1 ? K_PROJ : K_BOUNDARY);
            slong w;
            for (k = c->nf - 1; k >= 0; k--) {
                if (c->kind[k] != kd) continue;
                for (w = 0; w < 4; w++) {
                    unsigned char keep = m[k];
                    if ((widen[w] & keep) != keep || widen[w] == keep) continue;
                    m[k] = widen[w];
                    if (conj_safe(c, m, target)) break;
                    m[k] = keep;
                }
            }
        }
        F = flint_realloc(F, (n + 1) * sizeof(unsigned char *));
        F[n++] = m;
    }
    /* drop conjunctions contained in another one */
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            int sub = 1;
            if (i == j || F[i] == NULL || F[j] == NULL) continue;
            for (k = 0; k < c->nf && sub; k++) sub = (F[i][k] & F[j][k]) == F[i][k];
            if (sub) { flint_free(F[i]); F[i] = NULL; break; }
        }
    }
    for (i = 0, j = 0; i < n; i++) if (F[i] != NULL) F[j++] = F[i];
    *nout = j;
    return F;
}

static char *cad_polystr(const cad_t *c, slong k)
{
    return rs_polyfmt_fmpz_mpoly(c->f + k, (const char **) c->s->vars, c->s->zctx);
}

static json_t *cad_formula_json(const cad_t *c, unsigned char **F, slong n)
{
    static const char *rel[8] = {NULL, "< 0", "= 0", "<= 0", "> 0", "!= 0", ">= 0", NULL};
    json_t *a = json_array();
    slong i, k;
    for (i = 0; i < n; i++) {
        json_t *cj = json_array();
        for (k = 0; k < c->nf; k++) {
            char *ps, buf[16];
            size_t len;
            char *t;
            if (F[i][k] == 7 || F[i][k] == 0) continue;
            ps = cad_polystr(c, k);
            snprintf(buf, sizeof buf, " %s", rel[F[i][k]]);
            len = strlen(ps) + strlen(buf) + 1;
            t = malloc(len);
            snprintf(t, len, "%s%s", ps, buf);
            json_array_append_new(cj, json_string(t));
            free(t);
            free(ps);
        }
        json_array_append_new(a, cj);
    }
    return a;
}

/* "POLY REL 0" at (x, y), re-parsed from the text with FLINT's parser */
static int cond_eval(int *holds, const char *cond, const cad_t *c, const fmpq_t x, const fmpq_t y)
{
    const rs_scheme_struct *s = c->s;
    char *poly = strdup(cond), *sp = strrchr(poly, ' '), *relp;
    fmpq_mpoly_t P;
    fmpq_t val;
    fmpq *pt;
    slong i;
    int sg, ok = 0;
    if (sp == NULL) { free(poly); return 0; }
    *sp = '\0';                 /* "POLY REL" */
    relp = strrchr(poly, ' ');
    if (relp == NULL) { free(poly); return 0; }
    *relp++ = '\0';
    fmpq_mpoly_init(P, s->ctx);
    fmpq_init(val);
    pt = _fmpq_vec_init(s->nvars);
    if (fmpq_mpoly_set_str_pretty(P, poly, (const char **) s->vars, s->ctx) == 0) {
        fmpq_set(pt + c->av, x);
        fmpq_set(pt + c->bv, y);
        for (i = 0; i < s->nvars; i++)
            if (i != c->av && i != c->bv && fmpq_mpoly_degree_si(P, i, s->ctx) > 0) break;
        if (i == s->nvars) {
            fmpq_mpoly_struct *vp = P;
            fmpq **pp = flint_malloc(s->nvars * sizeof(fmpq *));
            for (i = 0; i < s->nvars; i++) pp[i] = pt + i;
            ok = fmpq_mpoly_evaluate_all_fmpq(val, vp, pp, s->ctx);
            flint_free(pp);
            sg = fmpq_sgn(val);
            if (strcmp(relp, ">") == 0) *holds = sg > 0;
            else if (strcmp(relp, ">=") == 0) *holds = sg >= 0;
            else if (strcmp(relp, "<") == 0) *holds = sg < 0;
            else if (strcmp(relp, "<=") == 0) *holds = sg <= 0;
            else if (strcmp(relp, "=") == 0) *holds = sg == 0;
            else if (strcmp(relp, "!=") == 0) *holds = sg != 0;
            else ok = 0;
        }
    }
    _fmpq_vec_clear(pt, s->nvars);
    fmpq_mpoly_clear(P, s->ctx);
    fmpq_clear(val);
    free(poly);
    return ok;
}

static int dnf_holds(int *holds, const json_t *dnf, const cad_t *c, const fmpq_t x, const fmpq_t y)
{
    size_t i, j;
    *holds = 0;
    for (i = 0; i < json_array_size(dnf) && !*holds; i++) {
        const json_t *cj = json_array_get(dnf, i);
        int all = 1;
        for (j = 0; j < json_array_size(cj) && all; j++)
            if (!cond_eval(&all, json_string_value(json_array_get(cj, j)), c, x, y)) return 0;
        *holds = all;
    }
    return 1;
}

/* a random rational in (lo, hi) (n_randint: deterministic per run) */
static void rand_in(fmpq_t out, flint_rand_t st, const rs_bound_t *b, double dlo, double dhi)
{
    fmpq_t lo, hi, t;
    fmpq_init(lo); fmpq_init(hi); fmpq_init(t);
    if (b->has_lo) fmpq_set(lo, b->lo); else fmpq_set_si(lo, (slong) (dlo - 2), 1);
    if (b->has_hi) fmpq_set(hi, b->hi); else fmpq_set_si(hi, (slong) (dhi + 2), 1);
    if (b->has_lo && !b->has_hi && fmpq_cmp(hi, lo) <= 0) { fmpq_set(hi, lo); fmpz_add_ui(fmpq_numref(hi), fmpq_numref(hi), 4 * fmpz_get_ui(fmpq_denref(hi))); }
    if (b->has_hi && !b->has_lo && fmpq_cmp(lo, hi) >= 0) { fmpq_set(lo, hi); fmpz_sub_ui(fmpq_numref(lo), fmpq_numref(lo), 4 * fmpz_get_ui(fmpq_denref(lo))); }
    fmpq_sub(t, hi, lo);
    fmpq_mul_si(t, t, (slong) n_randint(st, 9972) + 1);
    {
        fmpz_t d;
        fmpz_init_set_ui(d, 9973);
        fmpq_div_fmpz(t, t, d);
        fmpz_clear(d);
    }
    fmpq_add(out, lo, t);
    fmpq_clear(lo); fmpq_clear(hi); fmpq_clear(t);
}

/* step 4's check: the re-parsed formula against the exact point verdict */
static int cad_cross_check(json_t *o, cad_t *c, const json_t *stable, const json_t *marginal, int complete)
{
    flint_rand_t st;
    slong i, agree = 0, tried = 0;
    double alo = c->ncrit ? rs_alg_double(c->crit) : 0, ahi = c->ncrit ? rs_alg_double(c->crit + c->ncrit - 1) : 0;
    fmpq vals[2];
    int r = RS_OK;
    json_t *bad = json_array();
    flint_randinit(st);
    fmpq_init(vals + 0); fmpq_init(vals + 1);
    for (i = 0; i < CAD_CHECK_POINTS && r == RS_OK; i++) {
        rs_status_t ps;
        int hs, hm;
        r = rs_budget_check(c->run->err, "region N1, N2 (cross-check)");
        if (r != RS_OK) break;
        rand_in(vals + 0, st, c->bounds + c->av, alo, ahi);
        rand_in(vals + 1, st, c->bounds + c->bv, c->blo, c->bhi);
        r = cad_point_status(&ps, c, vals);
        if (r == RS_ERR_UNDECIDED && c->qd != NULL) {   /* a repeated circle root there: not compared */
            rs_error_init(c->run->err);
            r = RS_OK;
            continue;
        }
        if (r != RS_OK) break;
        if (!dnf_holds(&hs, stable, c, vals + 0, vals + 1)
            || (marginal != NULL ? !dnf_holds(&hm, marginal, c, vals + 0, vals + 1) : (hm = 0, 0))) {
            hs = -1;
            hm = -1;
        }
        tried++;
        if (hs == (ps == RS_STATUS_STABLE) && hm == (ps == RS_STATUS_MARGINAL)) {
            agree++;
        } else {
            json_array_append_new(bad, json_pack("{s:o,s:o,s:s}", c->an, rs_json_fmpq(vals + 0), c->bn,
                                                 rs_json_fmpq(vals + 1), "status", cad_st_name(c, ps)));
        }
    }
    /* disagreement where the formula claims completeness: a bug (exit 3) */
    if (r == RS_OK && agree != tried && complete) c->run->outcome |= RS_OUTCOME_INCONSISTENT;
    json_object_set_new(o, "cross_check", json_pack("{s:I,s:I,s:o,s:s}", "points", (json_int_t) tried,
        "agree", (json_int_t) agree, "disagree_at", bad, "method",
        c->qd != NULL ? c->qd->check_method
        : c->cx != NULL && c->cx->norm != NULL ? "the stable and marginal formulas re-parsed from their text and "
        "evaluated exactly at random rational points, against the exact point verdict over Q(i) (Schur-Cohn over "
        "Q(i) and Bilharz)"
        : c->cx != NULL ? "the stable formula re-parsed from its text and evaluated exactly at random rational points, "
        "against the exact point verdict over Q(i) (Schur-Cohn over Q(i) and Bilharz)"
        : "the formula re-parsed from its text and evaluated exactly at random rational points of the domain, "
        "against the exact point verdict (Routh and Schur-Cohn counts)"));
    fmpq_clear(vals + 0); fmpq_clear(vals + 1);
    flint_randclear(st);
    return r;
}

/* step 5: arcs (1-D sections in 2-D columns) and whether they separate */
/* the sign variations of (1 + t)^n e((xl + xr t)/(1 + t)): an upper bound
 * on the roots of e in (xl, xr) with the same parity (Descartes' rule on the
 * interval mapped onto t > 0), exact when 0 or 1 */
static slong upoly_variations(const fmpz_poly_t e, const fmpq_t xl, const fmpq_t xr)
{
    fmpq_poly_t lin, q;
    fmpz_poly_t z;
    fmpz_t one;
    fmpq_t w;
    slong i, nv = 0;
    int last = 0;
    fmpq_poly_init(lin); fmpq_poly_init(q);
    fmpz_poly_init(z);
    fmpz_init_set_ui(one, 1);
    fmpq_init(w);
    /* x = xl + (xr - xl) s maps s in (0, 1) onto (xl, xr); s = 1/(1 + t) */
    fmpq_poly_set_coeff_fmpq(lin, 0, xl);
    fmpq_sub(w, xr, xl);
    fmpq_poly_set_coeff_fmpq(lin, 1, w);
    fmpq_poly_set_fmpz_poly(q, e);
    fmpq_poly_compose(q, q, lin);
    fmpq_poly_get_numerator(z, q);
    fmpz_poly_reverse(z, z, fmpz_poly_length(z));
    fmpz_poly_taylor_shift(z, z, one);
    for (i = 0; i < fmpz_poly_length(z); i++) {
        int sg = fmpz_sgn(z->coeffs + i);
        if (sg == 0) continue;
        if (last != 0 && sg != last) nv++;
        last = sg;
    }
    fmpq_poly_clear(lin); fmpq_poly_clear(q);
    fmpz_poly_clear(z);
    fmpz_clear(one);
    fmpq_clear(w);
    return nv;
}

/* e has no real root in [xl, xr] (exact) */
static int upoly_no_root_in(const fmpz_poly_t e, const fmpq_t xl, const fmpq_t xr)
{
    fmpq_t v;
    int ok;
    fmpq_init(v);
    fmpz_poly_evaluate_fmpq(v, e, xl);
    ok = !fmpq_is_zero(v);
    fmpz_poly_evaluate_fmpq(v, e, xr);
    ok = ok && !fmpq_is_zero(v);
    fmpq_clear(v);
    return ok && (fmpz_poly_degree(e) < 1 || upoly_variations(e, xl, xr) == 0);
}

/* Exactly: xl < al < xr, al is the only root of its minimal polynomial in
 * [xl, xr], and the horizontal segment y = b0, xl <= x <= xr meets the zero
 * set of no polynomial except on the line x = al.  Then (xl, b0) and
 * (xr, b0) lie in the 2-D cells left and right of the vertical arc through
 * (al, b0): the segment's halves are connected and meet no section. */
static int cad_side_proved(const cad_t *c, const fmpq_t xl, const fmpq_t xr, const fmpq_t b0, rs_alg_t *al)
{
    const fmpz_mpoly_ctx_struct *ctx = c->s->zctx;
    fmpz_poly_t m, u, g;
    fmpz_mpoly_t t;
    slong k;
    int ok = 1;
    fmpz_poly_init(m); fmpz_poly_init(u); fmpz_poly_init(g);
    fmpz_mpoly_init(t, ctx);
    if (al->rational) {
        fmpz_t nn;                      /* m = den x - num */
        fmpz_init(nn);
        fmpz_neg(nn, fmpq_numref(al->q));
        fmpz_poly_set_coeff_fmpz(m, 1, fmpq_denref(al->q));
        fmpz_poly_set_coeff_fmpz(m, 0, nn);
        fmpz_clear(nn);
        ok = fmpq_cmp(xl, al->q) < 0 && fmpq_cmp(al->q, xr) < 0;
    } else {
        arb_t bl, br;
        arb_init(bl); arb_init(br);
        arb_set_fmpq(bl, xl, al->prec + 64);
        arb_set_fmpq(br, xr, al->prec + 64);
        fmpz_poly_set(m, al->minpoly);
        ok = arb_lt(bl, al->x) && arb_lt(al->x, br) && upoly_variations(m, xl, xr) == 1;
        arb_clear(bl); arb_clear(br);
    }
    for (k = 0; k < c->nf && ok; k++) {
        rs_an_forall_subst(t, c->f + k, c->bv, b0, ctx);
        if (!fmpz_mpoly_get_fmpz_poly(u, t, c->av, ctx) || fmpz_poly_is_zero(u)) { ok = 0; break; }
        if (fmpz_poly_degree(u) < 1) continue;
        /* the squarefree part without the line's own factor */
        rs_fmpz_poly_squarefree_part(u, u);
        if (fmpz_poly_divides(g, u, m)) fmpz_poly_swap(u, g);
        ok = upoly_no_root_in(u, xl, xr);
    }
    fmpz_poly_clear(m); fmpz_poly_clear(u); fmpz_poly_clear(g);
    fmpz_mpoly_clear(t, ctx);
    return ok;
}

static void cad_boundary(json_t *o, const cad_t *c)
{
    json_t *arcs = json_array(), *bnd = json_array(), *marcs = json_array(), *mcur = json_array();
    slong *nsep = flint_calloc(c->nf, sizeof(slong)), *ntot = flint_calloc(c->nf, sizeof(slong)), i, k;
    slong *nmarg = flint_calloc(c->nf, sizeof(slong));
    for (i = 1; i + 1 < c->ncells; i++) {
        const cell_t *e = c->cells + i, *lo = e - 1, *hi = e + 1;
        int sep, marg;
        if (e->dim != 1 || e->sec < 0 || lo->col != e->col || hi->col != e->col || lo->dim != 2 || hi->dim != 2)
            continue;
        if (e->outside || lo->outside || hi->outside || !lo->decided || !hi->decided) continue;
        sep = lo->st != hi->st;
        /* a marginal arc between two sides of one other status: where the
         * status changes without bounding the stable set (issue 13: listed
         * apart from the boundary) */
        marg = !sep && e->decided && e->st == RS_STATUS_MARGINAL && lo->st != RS_STATUS_MARGINAL;
        for (k = 0; k < c->nf; k++) {
            if (e->sg[k] != 0 || c->kind[k] != K_BOUNDARY) continue;
            ntot[k]++;
            if (sep) nsep[k]++;
            if (marg) nmarg[k]++;
        }
        if (marg) {
            char *ps = cad_polystr(c, e->sec);
            json_array_append_new(marcs, json_pack("{s:s,s:O,s:O,s:s,s:s}", "poly", ps, c->an, e->a, c->bn, e->b,
                                                   "on", cad_st_name(c, e->st), "sides", cad_st_name(c, lo->st)));
            free(ps);
        }
        if (sep) {
            char *ps = cad_polystr(c, e->sec);
            json_array_append_new(arcs, json_pack("{s:s,s:O,s:O,s:s,s:s}", "poly", ps, c->an, e->a, c->bn, e->b,
                                                  "below", cad_st_name(c, lo->st), "above", cad_st_name(c, hi->st)));
            free(ps);
        }
    }
    /* vertical arcs: segments of a column over a critical value, their
     * sides decided exactly at (a0 -+ delta, b0), delta halved until the
     * segment between them provably meets no other zero set
     * (cad_side_proved): the two points lie in the adjacent cells */
    for (i = 0; i < c->ncells; i++) {
        const cell_t *e = c->cells + i;
        rs_status_t side[2];
        fmpq vals[2];
        fmpq_t d, a0, xl, xr;
        double gap = 1;
        slong ci = e->col / 2, j, tries;
        int ok = 1;
        if (e->dim != 1 || e->col % 2 == 0 || e->outside || !json_is_string(e->b)) continue;
        if (ci > 0) gap = FLINT_MIN(gap, rs_alg_double(c->crit + ci) - rs_alg_double(c->crit + ci - 1));
        if (ci + 1 < c->ncrit) gap = FLINT_MIN(gap, rs_alg_double(c->crit + ci + 1) - rs_alg_double(c->crit + ci));
        fmpq_init(vals + 0); fmpq_init(vals + 1); fmpq_init(d); fmpq_init(a0);
        fmpq_init(xl); fmpq_init(xr);
        fmpq_one(d);
        while (fmpq_get_d(d) > gap / 1024) fmpq_div_2exp(d, d, 1);
        fmpq_set_str(vals + 1, json_string_value(e->b), 10);
        fmpq_canonicalise(vals + 1);
        for (tries = 0; ; tries++) {
            if (c->crit[ci].rational) {
                fmpq_set(a0, c->crit[ci].q);
            } else {
                /* an irrational line: a0 within d/2 of it (a0 -+ d on its two sides) */
                arf_t mid;
                slong prec = 64;
                arf_init(mid);
                for (;;) {
                    rs_alg_refine(c->crit + ci, prec);
                    if (mag_cmp_2exp_si(arb_radref(c->crit[ci].x), -1) < 0
                        && mag_get_d(arb_radref(c->crit[ci].x)) < fmpq_get_d(d) / 4) break;
                    prec *= 2;
                }
                arf_set(mid, arb_midref(c->crit[ci].x));
                arf_get_fmpq(a0, mid);
                arf_clear(mid);
            }
            fmpq_sub(xl, a0, d);
            fmpq_add(xr, a0, d);
            if (cad_side_proved(c, xl, xr, vals + 1, c->crit + ci)) break;
            if (tries == 60) { ok = 0; break; }
            fmpq_div_2exp(d, d, 1);
        }
        for (j = 0; j < 2 && ok; j++) {
            fmpq_set(vals + 0, j == 0 ? xl : xr);
            ok = cad_point_status(side + j, c, vals) == RS_OK;
        }
        rs_error_init(c->run->err);
        fmpq_clear(vals + 0); fmpq_clear(vals + 1); fmpq_clear(d); fmpq_clear(a0);
        fmpq_clear(xl); fmpq_clear(xr);
        if (!ok) continue;
        for (k = 0; k < c->nf; k++) {
            if (e->sg[k] != 0 || c->kind[k] != K_BOUNDARY || fmpz_mpoly_degree_si(c->f + k, c->bv, c->s->zctx) > 0)
                continue;
            ntot[k]++;
            if (side[0] != side[1]) {
                char *ps = cad_polystr(c, k);
                nsep[k]++;
                json_array_append_new(arcs, json_pack("{s:s,s:O,s:O,s:s,s:s}", "poly", ps, c->an, e->a, c->bn, e->b,
                                                      "left", cad_st_name(c, side[0]), "right", cad_st_name(c, side[1])));
                free(ps);
            } else if (e->decided && e->st == RS_STATUS_MARGINAL && side[0] != RS_STATUS_MARGINAL) {
                char *ps = cad_polystr(c, k);
                nmarg[k]++;
                json_array_append_new(marcs, json_pack("{s:s,s:O,s:O,s:s,s:s}", "poly", ps, c->an, e->a, c->bn,
                                                       e->b, "on", cad_st_name(c, e->st), "sides",
                                                       cad_st_name(c, side[0])));
                free(ps);
            }
        }
    }
    for (k = 0; k < c->nf; k++) {
        char *ps;
        if (c->kind[k] != K_BOUNDARY || nsep[k] == 0) continue;
        ps = cad_polystr(c, k);
        json_array_append_new(bnd, json_string(ps));
        free(ps);
    }
    for (k = 0; k < c->nf; k++) {
        char *ps;
        if (c->kind[k] != K_BOUNDARY || nmarg[k] == 0 || nsep[k] > 0) continue;
        ps = cad_polystr(c, k);
        json_array_append_new(mcur, json_string(ps));
        free(ps);
    }
    json_object_set_new(o, "boundary", bnd);
    json_object_set_new(o, "arcs", arcs);
    json_object_set_new(o, "marginal_curves", mcur);
    json_object_set_new(o, "marginal_arcs", marcs);
    {
        json_t *cand = json_array();
        for (k = 0; k < c->nf; k++) {
            char *ps;
            if (c->kind[k] != K_BOUNDARY) continue;
            ps = cad_polystr(c, k);
            json_array_append_new(cand, json_pack("{s:s,s:I,s:I}", "poly", ps, "arcs", (json_int_t) ntot[k],
                                                  "separating", (json_int_t) nsep[k]));
            free(ps);
        }
        json_object_set_new(o, "candidates", cand);
    }
    flint_free(nsep);
    flint_free(ntot);
    flint_free(nmarg);
}

/* a polynomial in QEPCAD B's syntax: products by juxtaposition */
static void qe_poly(FILE *f, const cad_t *c, const fmpz_mpoly_t g, int neg)
{
    fmpz_mpoly_t h;
    char *ps, *t;
    fmpz_mpoly_init(h, c->s->zctx);
    if (neg) fmpz_mpoly_neg(h, g, c->s->zctx); else fmpz_mpoly_set(h, g, c->s->zctx);
    ps = rs_polyfmt_fmpz_mpoly(h, (const char **) c->s->vars, c->s->zctx);
    for (t = ps; *t; t++) if (*t == '*') *t = ' ';
    fputs(ps, f);
    free(ps);
    fmpz_mpoly_clear(h, c->s->zctx);
}

/* The same question for QEPCAD B, from recstab's own conditions: p stable
 * iff q(z) = (1-z)^n p((1+z)/(1-z)) is Hurwitz of degree n, i.e. (Routh-
 * Hurwitz) every coefficient and D_1..D_{n-1} positive, for q or for -q
 * (D_k(-q) = (-1)^k D_k(q)).  "qepcad_input": the stable set in the plane;
 * "qepcad_input_for_all": the N1 values stable for every admissible N2. */
static void cad_qepcad(json_t *o, cad_t *c)
{
    const rs_scheme_struct *s = c->s;
    slong lv = s->lambda_var, k, br, pass;
    rs_hurwitz_t h;
    fmpz_mpoly_t qz;
    int *sign = flint_calloc(s->nvars, sizeof(int));
    fmpz_mpoly_init(qz, s->zctx);
    rs_hurwitz_init(h);
    rs_bilinear_fmpz_mpoly(qz, c->v->cp->p, lv, s->zctx);
    if (fmpz_mpoly_degree_si(qz, lv, s->zctx) >= 1
        && rs_hurwitz_compute(h, qz, lv, (const rs_sign_t *) sign, s->zctx, c->run->err) == RS_OK) {
        for (pass = 0; pass < 2; pass++) {
            char *buf = NULL;
            size_t len = 0;
            FILE *f = open_memstream(&buf, &len);
            fprintf(f, "[ recstab: %s of the scheme, from its Routh-Hurwitz conditions ]\n(%s,%s)\n%d\n",
                    pass == 0 ? "stable set" : "uniform range", c->an, c->bn, pass == 0 ? 2 : 1);
            /* QEPCAD wants the quantifier first: (A N2)[ dom1 /\ [ dom2 ==> S ] ] */
            if (pass == 1) fprintf(f, "(A %s)", c->bn);
            fputs("[", f);
            for (k = 0; k < c->nf; k++) {
                if (c->kind[k] != K_DOMAIN || (pass == 1 && fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx) > 0))
                    continue;
                fputc(' ', f);
                qe_poly(f, c, c->f + k, 0);
                fprintf(f, " %s 0 /\\", c->closed[k] ? ">=" : ">");
            }
            if (pass == 1) {
                int any = 0;
                fputs(" [ [", f);
                for (k = 0; k < c->nf; k++) {
                    if (c->kind[k] != K_DOMAIN || fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx) <= 0) continue;
                    fprintf(f, "%s", any ? " /\\ " : " ");
                    qe_poly(f, c, c->f + k, 0);
                    fprintf(f, " %s 0", c->closed[k] ? ">=" : ">");
                    any = 1;
                }
                fprintf(f, "%s ] ==>", any ? "" : " 0 = 0");
            }
            fputs(" [", f);
            for (br = 0; br < 2; br++) {
                fprintf(f, "%s[", br ? " \\/ " : " ");
                for (k = 0; k <= h->n; k++) {
                    fputs(k ? " /\\ " : " ", f);
                    qe_poly(f, c, h->coeffs + k, br);
                    fputs(" > 0", f);
                }
                for (k = 1; k < h->n; k++) {
                    fputs(" /\\ ", f);
                    qe_poly(f, c, h->minors + k - 1, br && (k % 2 == 1));
                    fputs(" > 0", f);
                }
                fputs(" ]", f);
            }
            fputs(pass == 0 ? " ] ].\nfinish\n" : " ] ] ].\nfinish\n", f);
            fclose(f);
            json_object_set_new(o, pass == 0 ? "qepcad_input" : "qepcad_input_for_all", json_string(buf));
            free(buf);
        }
    }
    rs_error_init(c->run->err);
    rs_hurwitz_clear(h, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    flint_free(sign);
}

static void cad_clear(cad_t *c)
{
    slong i;
    for (i = 0; i < c->nf; i++) fmpz_mpoly_clear(c->f + i, c->s->zctx);
    flint_free(c->f);
    flint_free(c->kind);
    flint_free(c->closed);
    for (i = 0; i < c->ncrit; i++) rs_alg_clear(c->crit + i);
    free(c->crit);
    for (i = 0; i < c->nfac; i++) { flint_free(c->fac[i].idx); flint_free(c->fac[i].exp); }
    flint_free(c->fac);
    for (i = 0; i < c->ncells; i++) {
        flint_free(c->cells[i].sg);
        json_decref(c->cells[i].a);
        json_decref(c->cells[i].b);
    }
    flint_free(c->cells);
    if (c->bounds != NULL) {
        rs_bounds_clear(c->bounds, c->nb);
        flint_free(c->bounds);
    }
}

static json_t *cad_cells_json(const cad_t *c)
{
    json_t *a = json_array();
    slong i;
    for (i = 0; i < c->ncells; i++) {
        const cell_t *e = c->cells + i;
        const char *st = e->outside ? "outside" : (e->decided ? cad_st_name(c, e->st) : "undecided");
        json_t *o = json_pack("{s:I,s:O,s:O,s:s}", "dim", (json_int_t) e->dim, c->an, e->a, c->bn, e->b, "status", st);
        /* a section without a tower: its status is certified by root balls (strictly inside / outside) */
        if (e->balls && !e->outside) json_object_set_new(o, "decided_by", json_string("root balls"));
        if (!e->decided && !e->outside && e->why != NULL) json_object_set_new(o, "undecided_because", json_string(e->why));
        json_array_append_new(a, o);
    }
    return a;
}

/* ---- the map's boundary (issue 13 part 3): only separating arcs ---------- */

typedef struct {
    slong col, k, j;     /* sector column, polynomial, its j-th real root there */
    int sep;
} arc_t;

struct rs_region_arcs_struct {
    cad_t c;
    arc_t *arcs;
    slong narcs;
    slong *nsep;         /* per polynomial: separating arcs (vertical ones included) */
    /* the complex form (rs_region_arcs_new_cx): conditions arrive in the
     * scheme's context src and are moved to the plane's by gmap */
    const fmpz_mpoly_ctx_struct *src;
    slong *gmap;
};

static void cad_arc_table(rs_region_arcs_t *A)
{
    cad_t *c = &A->c;
    slong i, k;
    A->nsep = flint_calloc(c->nf, sizeof(slong));
    for (i = 0; i < c->ncells; i++) {
        const cell_t *e = c->cells + i;
        int sep;
        if (e->dim != 1 || e->col % 2 != 0 || i == 0 || i + 1 >= c->ncells) continue;
        sep = e[-1].col == e->col && e[1].col == e->col && e[-1].decided && e[1].decided && !e[-1].outside
              && !e[1].outside && e[-1].st != e[1].st;
        for (k = 0; k < c->nf; k++) {
            slong j = 0, t;
            if (e->sg[k] != 0 || c->kind[k] != K_BOUNDARY) continue;
            for (t = i - 1; t >= 0 && c->cells[t].col == e->col; t--)
                if (c->cells[t].dim == 1 && c->cells[t].sg[k] == 0) j++;
            A->arcs = flint_realloc(A->arcs, (A->narcs + 1) * sizeof(arc_t));
            A->arcs[A->narcs].col = e->col;
            A->arcs[A->narcs].k = k;
            A->arcs[A->narcs].j = j;
            A->arcs[A->narcs].sep = sep;
            A->narcs++;
            if (sep) A->nsep[k]++;
        }
    }
    /* vertical lines: a polynomial in N1 alone separates where the cells on
     * its two sides differ (cad_boundary's test, counted per polynomial) */
    {
        json_t *o = json_object();
        const json_t *arcs;
        size_t t;
        cad_boundary(o, c);
        arcs = json_object_get(o, "arcs");
        for (t = 0; t < json_array_size(arcs); t++) {
            const json_t *a = json_array_get(arcs, t);
            if (json_object_get(a, "left") == NULL) continue;
            for (k = 0; k < c->nf; k++) {
                char *ps = cad_polystr(c, k);
                if (strcmp(ps, json_string_value(json_object_get(a, "poly"))) == 0) A->nsep[k]++;
                free(ps);
            }
        }
        json_decref(o);
    }
}

/* the plane's decomposition and its arc table for a set-up A (freed on failure) */
static int arcs_decompose(rs_region_arcs_t **out, rs_region_arcs_t *A)
{
    cad_t *c = &A->c;
    int r = cad_critical(c);
    if (r == RS_OK) r = cad_project(c);
    if (r == RS_OK) r = cad_lift(c);
    if (r != RS_OK) { rs_region_arcs_free(A); return r; }
    cad_arc_table(A);
    *out = A;
    return RS_OK;
}

int rs_region_arcs_new(rs_region_arcs_t **out, rs_run_t *run, const rs_variant_t *v, slong v1, slong v2)
{
    rs_region_arcs_t *A = flint_calloc(1, sizeof(rs_region_arcs_t));
    cad_t *c = &A->c;
    slong i;
    *out = NULL;
    c->run = run;
    c->v = v;
    c->s = v->s;
    c->av = v1;
    c->bv = v2;
    c->an = run->c->params[v1].name;
    c->bn = run->c->params[v2].name;
    c->blo = -1;
    c->bhi = 1;
    c->nb = run->c->nparams;
    c->bounds = flint_malloc((run->c->nparams + 1) * sizeof(rs_bound_t));
    rs_bounds_init(c->bounds, run->c->nparams);   /* no assumptions: the whole plane */
    for (i = 0; i < run->c->nparams; i++)
        if (i != v1 && i != v2 && fmpz_mpoly_degree_si(v->cp->p, i, v->s->zctx) > 0) {
            rs_region_arcs_free(A);
            return RS_ERR_INPUT;
        }
    return arcs_decompose(out, A);
}

int rs_region_arcs_new_cx(rs_region_arcs_t **out, rs_run_t *run, const rs_region_cx_t *cx,
                          const fmpz_mpoly_ctx_t src, const slong *gmap, slong nsrc)
{
    rs_region_arcs_t *A = flint_calloc(1, sizeof(rs_region_arcs_t));
    cad_t *c = &A->c;
    *out = NULL;
    c->run = run;
    c->s = cx->s;
    c->cx = cx;
    c->av = 0;
    c->bv = 1;
    c->an = cx->s->vars[0];
    c->bn = cx->s->vars[1];
    c->blo = -1;
    c->bhi = 1;
    c->nb = 2;
    c->bounds = flint_malloc(3 * sizeof(rs_bound_t));
    rs_bounds_init(c->bounds, 2);   /* the whole plane */
    A->src = src;
    A->gmap = flint_malloc(nsrc * sizeof(slong));
    memcpy(A->gmap, gmap, nsrc * sizeof(slong));
    return arcs_decompose(out, A);
}

void rs_region_arcs_free(rs_region_arcs_t *A)
{
    if (A == NULL) return;
    flint_free(A->gmap);
    cad_clear(&A->c);
    flint_free(A->arcs);
    flint_free(A->nsep);
    flint_free(A);
}

/* the real roots of f(x, .) in increasing order (doubles; n returned) */
static slong arcs_roots(double *rt, const cad_t *c, slong k, double x)
{
    const rs_scheme_struct *s = c->s;
    slong d = fmpz_mpoly_degree_si(c->f + k, c->bv, s->zctx), j, n = 0, t;
    double *a = flint_calloc(d + 1, sizeof(double)), *z = flint_calloc(2 * d + 2, sizeof(double));
    fmpz_mpoly_t cf;
    fmpz_poly_t u;
    fmpz_mpoly_init(cf, s->zctx);
    fmpz_poly_init(u);
    for (j = 0; j <= d; j++) {
        ulong e = (ulong) j;
        fmpz_mpoly_get_coeff_vars_ui(cf, c->f + k, &c->bv, &e, 1, s->zctx);
        if (fmpz_mpoly_get_fmpz_poly(u, cf, c->av, s->zctx)) {
            slong i;
            for (i = fmpz_poly_degree(u); i >= 0; i--) a[j] = a[j] * x + fmpz_get_d(u->coeffs + i);
        }
    }
    while (d > 0 && a[d] == 0) d--;
    if (d >= 1) {
        gsl_poly_complex_workspace *w = gsl_poly_complex_workspace_alloc((size_t) d + 1);
        if (gsl_poly_complex_solve(a, (size_t) d + 1, w, z) == 0) {
            double scale = 1;
            for (j = 0; j < d; j++) scale = FLINT_MAX(scale, fabs(z[2 * j]));
            for (j = 0; j < d; j++) if (fabs(z[2 * j + 1]) <= 1e-7 * scale) rt[n++] = z[2 * j];
        }
        gsl_poly_complex_workspace_free(w);
    }
    for (j = 1; j < n; j++) for (t = j; t > 0 && rt[t - 1] > rt[t]; t--) { double q = rt[t]; rt[t] = rt[t - 1]; rt[t - 1] = q; }
    flint_free(a);
    flint_free(z);
    fmpz_mpoly_clear(cf, s->zctx);
    fmpz_poly_clear(u);
    return n;
}

/* the distance from x to the nearest real root of f_k, a polynomial in N1 alone */
static double arcs_vertical_dist(const cad_t *c, slong k, double x)
{
    const rs_scheme_struct *s = c->s;
    fmpz_poly_t u;
    double best = 1e300;
    fmpz_poly_init(u);
    if (fmpz_mpoly_get_fmpz_poly(u, c->f + k, c->av, s->zctx) && fmpz_poly_degree(u) >= 1) {
        slong d = fmpz_poly_degree(u), j;
        double *a = flint_calloc(d + 1, sizeof(double)), *z = flint_calloc(2 * d + 2, sizeof(double));
        gsl_poly_complex_workspace *w;
        for (j = 0; j <= d; j++) a[j] = fmpz_get_d(u->coeffs + j);
        w = gsl_poly_complex_workspace_alloc((size_t) d + 1);
        if (gsl_poly_complex_solve(a, (size_t) d + 1, w, z) == 0) {
            double scale = 1;
            for (j = 0; j < d; j++) scale = FLINT_MAX(scale, fabs(z[2 * j]));
            for (j = 0; j < d; j++)
                if (fabs(z[2 * j + 1]) <= 1e-7 * scale) best = FLINT_MIN(best, fabs(z[2 * j] - x));
        }
        gsl_poly_complex_workspace_free(w);
        flint_free(a);
        flint_free(z);
    }
    fmpz_poly_clear(u);
    return best;
}

/* 1 when the boundary point (x, y) of condition cond lies on an arc that
 * separates two statuses (or cannot be placed: kept); 0 also when cond has
 * no critical factor (its zero set is not where a status can change);
 * cond NULL: the point lies on some boundary factor (a z-plane locus
 * point), the nearest arc of any of them decides */
static int arcs_keep(const rs_region_arcs_t *A, const fmpz_mpoly_t cond, double x, double y, int nudged);

int rs_region_arcs_keep(const rs_region_arcs_t *A, const fmpz_mpoly_t cond, double x, double y)
{
    int keep;
    fmpz_mpoly_t m;
    if (A->gmap == NULL || cond == NULL) return arcs_keep(A, cond, x, y, 0);
    fmpz_mpoly_init(m, A->c.s->zctx);
    fmpz_mpoly_compose_fmpz_mpoly_gen(m, cond, A->gmap, A->src, A->c.s->zctx);
    keep = arcs_keep(A, m, x, y, 0);
    fmpz_mpoly_clear(m, A->c.s->zctx);
    return keep;
}

static int arcs_keep(const rs_region_arcs_t *A, const fmpz_mpoly_t cond, double x, double y, int nudged)
{
    const cad_t *c = &A->c;
    slong i, k, col = -1, best_k = -1, best_j = -1;
    double best = 1e300, *rt;
    int factor = 0;
    for (i = 0; i < c->ncrit; i++) {
        double ci = rs_alg_double(c->crit + i);
        if (fabs(ci - x) <= 1e-12 * FLINT_MAX(1, fabs(ci))) {
            /* on a critical line: the arcs just beside it, on either side */
            double d = 1e-9 * FLINT_MAX(1, fabs(x));
            if (nudged) return 1;
            return arcs_keep(A, cond, x - d, y, 1) || arcs_keep(A, cond, x + d, y, 1);
        }
        if (x < ci) break;
    }
    col = 2 * i;
    for (k = 0; k < c->nf; k++) {
        fmpz_mpoly_t q;
        slong d, n, j;
        int divides;
        if (c->kind[k] != K_BOUNDARY) continue;
        fmpz_mpoly_init(q, c->s->zctx);
        divides = cond == NULL || fmpz_mpoly_divides(q, cond, c->f + k, c->s->zctx);
        fmpz_mpoly_clear(q, c->s->zctx);
        if (!divides) continue;
        factor = 1;
        d = fmpz_mpoly_degree_si(c->f + k, c->bv, c->s->zctx);
        if (d <= 0) {
            /* a vertical line: its distance to the point competes with the
             * arcs' (a point on a line that separates nothing is dropped even
             * when another factor's arc passes near it) */
            double dist = arcs_vertical_dist(c, k, x);
            if (dist < best) { best = dist; best_k = k; best_j = -2; }
            continue;
        }
        rt = flint_malloc(d * sizeof(double));
        n = arcs_roots(rt, c, k, x);
        for (j = 0; j < n; j++)
            if (fabs(rt[j] - y) < best) { best = fabs(rt[j] - y); best_k = k; best_j = j; }
        flint_free(rt);
    }
    /* no critical factor: the status is the same on both sides */
    if (!factor) return 0;
    if (best_k < 0) return 1;
    if (best_j == -2) return A->nsep[best_k] > 0;
    for (i = 0; i < A->narcs; i++)
        if (A->arcs[i].col == col && A->arcs[i].k == best_k && A->arcs[i].j == best_j) return A->arcs[i].sep;
    return 1;
}

/* the separating polynomials and the counts, for the map's JSON */
json_t *rs_region_arcs_json(const rs_region_arcs_t *A)
{
    const cad_t *c = &A->c;
    json_t *a = json_array();
    slong k, i;
    for (k = 0; k < c->nf; k++) {
        slong tot = 0;
        char *ps;
        if (c->kind[k] != K_BOUNDARY) continue;
        for (i = 0; i < A->narcs; i++) tot += A->arcs[i].k == k;
        ps = cad_polystr(c, k);
        json_array_append_new(a, json_pack("{s:s,s:I,s:I}", "poly", ps, "arcs", (json_int_t) tot, "separating",
                                           (json_int_t) A->nsep[k]));
        free(ps);
    }
    return a;
}

/* steps 1-5 and the result object (c set up; c cleared by the caller) */
static int cad_solve(cad_t *c, json_t *substituted)
{
    int r = cad_critical(c);
    json_t *o;
    if (r == RS_OK) r = cad_project(c);
    if (r == RS_OK) r = cad_lift(c);
    if (r != RS_OK) return r;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("region"));
    json_object_set_new(o, "params", json_pack("[s,s]", c->an, c->bn));
    json_object_set_new(o, "substituted", substituted != NULL ? json_deep_copy(substituted) : json_object());
    json_object_set_new(o, "symbolic", json_false());
    {
        unsigned char **Fs, **Fm;
        slong ns, nm, k;
        int conflict = 0, conflict_m = 0, complete;
        json_t *fo = json_object(), *proj = json_array(), *cv = json_array();
        Fs = cad_formula(&ns, &conflict, c, RS_STATUS_STABLE);
        /* complex mode without norm: the cells are stable or not (the marginal set is not separated) */
        int cxm = c->cx == NULL || c->cx->norm != NULL;
        /* in the complex plane a clash of the marginal formula (a marginal
         * cell with the signs of a not-stable one, e.g. a circle-locus cell
         * left open) makes marginal_complete false, not formula_complete:
         * the stable formula does not depend on it */
        Fm = !cxm ? NULL : cad_formula(&nm, c->cx != NULL ? &conflict_m : &conflict, c, RS_STATUS_MARGINAL);
        if (!cxm) nm = 0;
        json_object_set_new(fo, "stable", cad_formula_json(c, Fs, ns));
        json_object_set_new(fo, "marginal", !cxm ? json_null() : cad_formula_json(c, Fm, nm));
        for (k = 0; k < ns; k++) flint_free(Fs[k]);
        for (k = 0; k < nm; k++) flint_free(Fm[k]);
        flint_free(Fs);
        flint_free(Fm);
        complete = !conflict && c->undecided_lines == 0;
        for (k = 0; k < c->ncells; k++) if (!c->cells[k].decided && !c->cells[k].outside) complete = 0;
        json_object_set_new(o, "formula", fo);
        json_object_set_new(o, "formula_complete", json_boolean(complete));
        if (!complete)
            json_object_set_new(o, "formula_note", json_string(conflict
                ? "two cells of different status have the same signs: the formula is exact except there"
                : c->cx != NULL
                ? "some cells over irrational critical values of the first parameter are not decided (a sign "
                  "the norms and balls did not separate, a line of degree above 12, or signs and root balls that "
                  "disagree; each such cell says why in undecided_because): the formula is exact off those cells"
                : c->qd != NULL
                ? "some cells are not decided (over irrational critical values of the first parameter: a "
                  "section with a root on the circle whose algebraic tower has degree above 64, a sign the "
                  "norms and balls did not separate, a line of degree above 8; or a system's repeated circle "
                  "root, at a rational sample too; each such cell says why in undecided_because): the formula "
                  "is exact off those cells"
                : "some cells over irrational critical values of the first parameter are not decided (a "
                  "section with a root on the circle whose algebraic tower has degree above 64, a sign the "
                  "norms and balls did not separate, a line of degree above 8, or a system's repeated circle "
                  "root): the formula is exact off those cells"));
        cad_boundary(o, c);
        if (c->cx == NULL && c->qd == NULL) cad_qepcad(o, c);
        json_object_set_new(o, "cells", cad_cells_json(c));
        for (k = 0; k < c->ncrit; k++) json_array_append_new(cv, rs_alg_json(c->crit + k, c->an));
        json_object_set_new(o, "critical_values", cv);
        for (k = 0; k < c->nf; k++) {
            char *ps = cad_polystr(c, k);
            json_array_append_new(proj, json_pack("{s:s,s:s}", "poly", ps, "kind",
                c->kind[k] == K_BOUNDARY ? "critical" : (c->kind[k] == K_DOMAIN ? "assumption" : "projection")));
            free(ps);
        }
        json_object_set_new(o, "projection", proj);
        {
            /* the formula speaks of the admissible points only */
            json_t *dom = json_array();
            for (k = 0; k < c->nf; k++) {
                char *ps, buf[600];
                if (c->kind[k] != K_DOMAIN) continue;
                ps = cad_polystr(c, k);
                snprintf(buf, sizeof buf, "%s %s 0", ps, c->closed[k] ? ">=" : ">");
                json_array_append_new(dom, json_string(buf));
                free(ps);
            }
            json_object_set_new(o, "domain", dom);
        }
        json_object_set_new(o, "undecided_lines", json_integer(c->undecided_lines));
        json_object_set_new(o, "method", json_string(c->qd != NULL ? c->qd->method : c->cx != NULL
            ? "cylindrical algebraic decomposition of the plane (Collins) of z = x + i y: critical polynomials "
              "|a_n|^2 and the division-free Schur-Cohn deltas of p over Q(i)[x, y] (stable iff all > 0), their "
              "projection onto x, each cell's signs; rational samples re-decided by the point verdict over Q(i)"
            : "cylindrical algebraic decomposition of the plane (Collins): critical polynomials (leading "
            "coefficient, p(1), p(-1), D_{n-1} of the bilinear q, discriminant), their projection onto the "
            "first parameter (leading coefficients, discriminants, resultants), one exact verdict per cell"));
        if (c->cx != NULL && c->cx->norm != NULL) {
            json_object_set_new(o, "complex_plane", json_string(c->cx->name));
            json_object_set_new(o, "marginal_complete", json_boolean(complete && !conflict_m && c->marginal_undecided == 0));
            json_object_set_new(o, "marginal_undecided_cells", json_integer(c->marginal_undecided));
            if (c->rel_skipped > 0) {
                char buf[300];
                snprintf(buf, sizeof buf, "%ld circle-locus cells not tried: the marginal tests in fields without "
                         "the full tower stop at a sum of %d over deg(field)^2", (long) c->rel_skipped,
                         CAD_MARGINAL_REL_COST);
                json_object_set_new(o, "marginal_limit", json_string(buf));
            }
            json_object_set_new(o, "marginal_note", json_string("marginal: roots on the circle, all simple, the "
                                "others inside; cells cut also by the circle locus (Res_w(A, B) of q(i w) = A + i B, "
                                "p(-1)) and the discriminant of p; decided by the point verdict over Q(i) at "
                                "rational samples, at algebraic ones by the norms |p(rho lambda)|^2 in the sample's field "
                                "(rho = 1 and n(n+1)/2 rotations with |rho| = 1: a marginal norm makes p marginal, all "
                                "unstable make p unstable; cells a norm cannot decide are counted in "
                                "marginal_undecided_cells)"));
        } else if (c->cx != NULL) {
            json_object_set_new(o, "complex_plane", json_string(c->cx->name));
            json_object_set_new(o, "marginal_note", json_string("region re(z), im(z) separates stable from not "
                                "stable; the marginal set (roots on the circle) lies on the boundary and is not "
                                "computed here: map re(z) ..., im(z) ... decides it per point"));
        }
        r = cad_cross_check(o, c, json_object_get(fo, "stable"), json_object_get(fo, "marginal"), complete);
    }
    {
        /* the report says which side decided: cells whose status came from
         * root balls (no tower) are counted */
        slong k, nb = 0;
        for (k = 0; k < c->ncells; k++) nb += c->cells[k].balls && !c->cells[k].outside;
        if (nb == 0) {
            json_object_set_new(o, "decided_by", json_string("exact"));
        } else {
            char buf[200];
            snprintf(buf, sizeof buf, "exact, but %ld section cell%s over irrational lines by certified root balls "
                     "(Arb: every root strictly inside, or one strictly outside)", (long) nb, nb == 1 ? "" : "s");
            json_object_set_new(o, "decided_by", json_string(buf));
        }
    }
    if (r == RS_OK) json_array_append_new(c->run->results, o);
    else json_decref(o);
    return r;
}

/* the plane (av, bv) of v with the assume lines' bounds, nothing computed */
static void cad_plane_init(cad_t *c, rs_run_t *run, const rs_variant_t *v, slong av, slong bv)
{
    slong i;
    memset(c, 0, sizeof *c);
    c->av = av;
    c->bv = bv;
    c->an = run->c->params[av].name;
    c->bn = run->c->params[bv].name;
    c->run = run;
    c->v = v;
    c->s = v->s;
    c->blo = -1;
    c->bhi = 1;
    c->nb = run->c->nparams;
    c->bounds = flint_malloc((run->c->nparams + 1) * sizeof(rs_bound_t));
    rs_bounds_init(c->bounds, run->c->nparams);
    for (i = 0; i < run->c->nassume; i++) rs_bounds_add(c->bounds, &run->c->assume[i], run->c, run->err);
}

int rs_region2_variant(rs_variant_t **v, rs_run_t *run, const rs_an_req_t *req)
{
    const char *keep[2];
    rs_assign_t *a = NULL;
    slong na = 0, i;
    int r;
    keep[0] = run->c->params[req->u.region.param].name;
    keep[1] = run->c->params[req->u.region.param2].name;
    rs_run_assignments(run, &a, &na, keep, 2, req->u.region.at, req->u.region.nat);
    r = rs_run_variant(v, run, a, na);
    rs_assign_free(a, na);
    for (i = 0; r == RS_OK && i < run->c->nparams; i++)
        if (i != req->u.region.param && i != req->u.region.param2
            && fmpz_mpoly_degree_si((*v)->cp->p, i, (*v)->s->zctx) > 0)
        {
            char msg[400];
            snprintf(msg, sizeof msg, "'%s' is symbolic: region N1, N2 decides two parameters; set the others "
                     "(region %s, %s at %s=VALUE)", run->c->params[i].name, keep[0], keep[1], run->c->params[i].name);
            r = rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "%s", msg);
        }
    return r;
}

int rs_an_region_cad(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    cad_t c;
    int r = rs_region2_variant(&v, run, req);
    if (r != RS_OK) return r;
    cad_plane_init(&c, run, v, req->u.region.param, req->u.region.param2);
    if (rs_bound_empty(c.bounds + c.av) || rs_bound_empty(c.bounds + c.bv)) {
        r = rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "%s", "the assumptions are contradictory");
        cad_clear(&c);
        return r;
    }
    r = cad_solve(&c, v->assigned);
    cad_clear(&c);
    return r;
}

int rs_an_region_cad_cells(json_t **cells, rs_run_t *run, const rs_variant_t *v, slong av, slong bv,
                           const fmpz_mpoly_struct *dom, const int *closed, slong ndom)
{
    cad_t c;
    slong i;
    int r;
    *cells = NULL;
    for (i = 0; i < run->c->nparams; i++)
        if (i != av && i != bv && fmpz_mpoly_degree_si(v->cp->p, i, v->s->zctx) > 0) return RS_ERR_INPUT;
    cad_plane_init(&c, run, v, av, bv);
    r = rs_bound_empty(c.bounds + av) || rs_bound_empty(c.bounds + bv) ? RS_ERR_INPUT : cad_critical(&c);
    for (i = 0; i < ndom && r == RS_OK; i++) {
        fmpz_mpoly_t g;
        fmpz_mpoly_init(g, c.s->zctx);
        fmpz_mpoly_set(g, dom + i, c.s->zctx);
        if (!fmpz_mpoly_is_fmpz(g, c.s->zctx)) cad_push(&c, g, K_DOMAIN, closed[i]);   /* the sign matters */
        fmpz_mpoly_clear(g, c.s->zctx);
    }
    if (r == RS_OK) r = cad_project(&c);
    if (r == RS_OK) r = cad_lift(&c);
    if (r == RS_OK) *cells = cad_cells_json(&c);
    cad_clear(&c);
    return r;
}

int rs_an_region_cad_qd(rs_run_t *run, const rs_variant_t *v, slong av, slong bv, const rs_region_qd_t *qd)
{
    cad_t c;
    int r;
    cad_plane_init(&c, run, v, av, bv);
    c.qd = qd;
    r = rs_bound_empty(c.bounds + av) || rs_bound_empty(c.bounds + bv) ? RS_ERR_INPUT : cad_solve(&c, v->assigned);
    cad_clear(&c);
    return r;
}

int rs_an_region_cad_cx(rs_run_t *run, const rs_region_cx_t *cx)
{
    cad_t c;
    int r;
    memset(&c, 0, sizeof c);
    c.run = run;
    c.s = cx->s;
    c.cx = cx;
    c.av = 0;
    c.bv = 1;
    c.an = cx->s->vars[0];
    c.bn = cx->s->vars[1];
    c.blo = -1;
    c.bhi = 1;
    c.nb = 2;
    c.bounds = flint_malloc(3 * sizeof(rs_bound_t));
    rs_bounds_init(c.bounds, 2);   /* the whole plane */
    r = cad_solve(&c, cx->substituted);
    cad_clear(&c);
    return r;
}
