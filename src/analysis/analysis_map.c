/* analysis_map.c -- the map analysis of the equations and its exact
 * stability boundary:
 *
 *   map NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]
 *
 * The points are computed by the engine (sweep_engine.c) with the model of
 * the equations (sweep_poly.c); the table is the engine's, as for every
 * model kind.  Where p is symbolic in both parameters the boundary is added:
 * the zero sets of the reduced Lienard-Chipart conditions and of p(1), p(-1)
 * found from exact signs at the grid points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>
#include "analysis/sweep_impl.h"
#include "numeric/grid.h"
#include "recstab/budget.h"
#include "recstab/hurwitz.h"
#include "stability/schur_complex.h"
#include "stability/routh_complex.h"
#include <flint/fmpz_mpoly_factor.h>
#include "analysis/an_region.h"

typedef struct {
    fmpz_mpoly_t f;
    char *origin;
} bcond_t;

/* The candidate polynomials of the boundary into bc (*nb of them): the
 * non-constant reduced Lienard-Chipart conditions, then p(1), p(-1) unless
 * constant or already listed up to sign.  RS_OK, or the error of hurwitz
 * (p(1), p(-1) are listed all the same). */
static int boundary_candidates(bcond_t **out, slong *nb, rs_run_t *run, const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    rs_hurwitz_t h;
    fmpz_mpoly_t qz;
    bcond_t *bc;
    slong c, n = 0;
    int r;
    fmpz_mpoly_init(qz, s->zctx);
    rs_hurwitz_init(h);
    r = rs_run_hurwitz(h, run, v, qz);
    bc = calloc((size_t) ((r == RS_OK ? h->ncond : 0) + 2), sizeof(bcond_t));
    for (c = 0; r == RS_OK && c < h->ncond; c++) {
        if (h->cond[c].trivially_true || fmpz_mpoly_is_fmpz(h->cond[c].reduced, s->zctx)) continue;
        fmpz_mpoly_init(bc[n].f, s->zctx);
        fmpz_mpoly_set(bc[n].f, h->cond[c].reduced, s->zctx);
        bc[n].origin = strdup(h->cond[c].origin);
        n++;
    }
    for (c = 0; c < 2; c++) {
        fmpz_t one;
        fmpz_mpoly_t neg;
        slong k;
        int dup = 0;
        fmpz_init(one);
        fmpz_set_si(one, c == 0 ? 1 : -1);
        fmpz_mpoly_init(bc[n].f, s->zctx);
        fmpz_mpoly_evaluate_one_fmpz(bc[n].f, v->cp->p, s->lambda_var, one, s->zctx);
        fmpz_clear(one);
        fmpz_mpoly_init(neg, s->zctx);
        fmpz_mpoly_neg(neg, bc[n].f, s->zctx);
        for (k = 0; k < n; k++)
            if (fmpz_mpoly_equal(bc[k].f, bc[n].f, s->zctx) || fmpz_mpoly_equal(bc[k].f, neg, s->zctx)) dup = 1;
        fmpz_mpoly_clear(neg, s->zctx);
        if (dup || fmpz_mpoly_is_fmpz(bc[n].f, s->zctx)) { fmpz_mpoly_clear(bc[n].f, s->zctx); continue; }
        bc[n].origin = strdup(c == 0 ? "p(1)" : "p(-1)");
        n++;
    }
    rs_hurwitz_clear(h, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    *out = bc;
    *nb = n;
    return r;
}

/* Exact signs sg and double approximations val of f at every grid point
 * (index j*K1 + i); rows are skipped once the budget ran out (the run
 * reports the limit). */
static void boundary_signs(signed char *sg, double *val, const fmpz_mpoly_t f, const rs_variant_t *v, slong v1,
                           slong v2, const fmpq *x1, slong K1, const fmpq *x2, slong K2)
{
    rs_grid_terms_t T;
    fmpz *U1, *U2, *g;
    double *bx1 = malloc((size_t) K1 * sizeof(double)), *bx2 = malloc((size_t) K2 * sizeof(double));
    slong i, j;
    rs_grid_terms_init(&T, f, -1, v1, v2, v->s->zctx);
    U1 = rs_grid_powers(x1, K1, T.d1);
    U2 = rs_grid_powers(x2, K2, T.d2);
    /* log2 of den^d per axis value, for the double approximations */
    for (i = 0; i < K1; i++) bx1[i] = (double) T.d1 * log2(fmpz_get_d(fmpq_denref(x1 + i)));
    for (j = 0; j < K2; j++) bx2[j] = (double) T.d2 * log2(fmpz_get_d(fmpq_denref(x2 + j)));
#pragma omp parallel for schedule(dynamic, 4) private(i, g)
    for (j = 0; j < K2; j++) {
        slong k;
        fmpz_t w;
        if (rs_budget_check(NULL, "the map's boundary") != RS_OK) continue;
        g = _fmpz_vec_init(T.d1 + 1);
        fmpz_init(w);
        for (k = 0; k < T.n; k++)
            fmpz_addmul(g + T.e1[k], T.c + k, U2 + j * (T.d2 + 1) + T.e2[k]);
        for (i = 0; i < K1; i++) {
            slong e;
            double m;
            fmpz_zero(w);
            for (k = 0; k <= T.d1; k++) fmpz_addmul(w, g + k, U1 + i * (T.d1 + 1) + k);
            sg[j * K1 + i] = (signed char) fmpz_sgn(w);
            m = fmpz_get_d_2exp(&e, w);
            val[j * K1 + i] = m == 0 ? 0 : m * exp2((double) e - bx1[i] - bx2[j]);
        }
        fmpz_clear(w);
        _fmpz_vec_clear(g, T.d1 + 1);
    }
    free(bx1);
    free(bx2);
    _fmpz_vec_clear(U1, K1 * (T.d1 + 1));
    _fmpz_vec_clear(U2, K2 * (T.d2 + 1));
    rs_grid_terms_clear(&T);
}

/* The boundary rows of condition c: zeros, then sign changes along rows
 * (fixed x2, crossing in x1), then along columns; the number of rows. */
/* A: the arcs of the plane's decomposition (NULL: every row is kept); a
 * row on an arc that separates nothing is dropped, counted in *dropped */
#define KEEP(x, y) (A == NULL || rs_region_arcs_keep(A, cf, (x), (y)) || ((*dropped)++, 0))
static slong boundary_rows(FILE *f, slong c, const signed char *sg, const double *val, const fmpq *x1, slong K1,
                           const fmpq *x2, slong K2, const rs_region_arcs_t *A, const fmpz_mpoly_t cf, slong *dropped)
{
    slong i, j, n = 0;
    for (j = 0; j < K2; j++)
        for (i = 0; i < K1; i++) {
            slong a = j * K1 + i;
            double xa = fmpq_get_d(x1 + i), y = fmpq_get_d(x2 + j);
            if (sg[a] == 0) {
                if (!KEEP(xa, y)) continue;
                fprintf(f, "%ld,%.15g,%.15g,zero\n", (long) c + 1, xa, y);
                n++;
            } else if (i + 1 < K1 && sg[a] * sg[a + 1] < 0) {
                double tt = val[a] / (val[a] - val[a + 1]), xb = fmpq_get_d(x1 + i + 1);
                if (!(tt >= 0 && tt <= 1)) tt = 0.5;
                if (!KEEP(xa + tt * (xb - xa), y)) continue;
                fprintf(f, "%ld,%.15g,%.15g,row\n", (long) c + 1, xa + tt * (xb - xa), y);
                n++;
            }
        }
    for (i = 0; i < K1; i++)
        for (j = 0; j + 1 < K2; j++) {
            slong a = j * K1 + i, b = (j + 1) * K1 + i;
            if (sg[a] * sg[b] < 0) {
                double ya = fmpq_get_d(x2 + j), yb = fmpq_get_d(x2 + j + 1);
                double tt = val[a] / (val[a] - val[b]);
                if (!(tt >= 0 && tt <= 1)) tt = 0.5;
                if (!KEEP(fmpq_get_d(x1 + i), ya + tt * (yb - ya))) continue;
                fprintf(f, "%ld,%.15g,%.15g,column\n", (long) c + 1, fmpq_get_d(x1 + i), ya + tt * (yb - ya));
                n++;
            }
        }
    return n;
}
#undef KEEP

/* Boundary of the stability region: sign changes of the reduced
 * Lienard-Chipart conditions and of p(1), p(-1) along grid rows and
 * columns (exact signs at grid points, crossing interpolated linearly).  Its
 * rows in shard 1 only, the header in every shard, so shards merge by
 * concatenation. */
static void map_boundary_rows(json_t *o, json_t *b, rs_run_t *run, const rs_variant_t *v,
                              const rs_sweep_request_t *R, const fmpq *x1, const fmpq *x2, bcond_t *bc, slong nb,
                              rs_region_arcs_t *A, const char *method);

static void map_boundary(json_t *o, rs_run_t *run, const rs_variant_t *v, const rs_sweep_request_t *R,
                         const fmpq *x1, const fmpq *x2)
{
    slong v1 = R->axis[0].var, v2 = R->axis[1].var;
    bcond_t *bc;
    slong nb;
    rs_region_arcs_t *A = NULL;
    json_t *b = json_object();
    rs_error_struct saved = *run->err;
    if (boundary_candidates(&bc, &nb, run, v) != RS_OK) {
        json_object_set_new(b, "hurwitz_error", json_string(run->err->msg));
        *run->err = saved;
    }
    /* only the arcs that separate two statuses are drawn (the plane's
     * decomposition, an_region_cad.c; every other parameter set) */
    if (rs_region_arcs_new(&A, run, v, v1, v2) != RS_OK) *run->err = saved;
    map_boundary_rows(o, b, run, v, R, x1, x2, bc, nb, A,
        "zero sets of the reduced Lienard-Chipart conditions of q(z) (hurwitz) and of p(1), p(-1): exact signs "
        "at the grid points, a crossing between two neighbours of a row (column) placed by linear "
        "interpolation of the values; 'zero' rows are grid points where the polynomial vanishes exactly");
}

/* the rows of the candidates bc (taken: cleared here) into o's "boundary"
 * (b) and "boundary_table"; A (taken, may be NULL) filters them */
static void map_boundary_rows(json_t *o, json_t *b, rs_run_t *run, const rs_variant_t *v,
                              const rs_sweep_request_t *R, const fmpq *x1, const fmpq *x2, bcond_t *bc, slong nb,
                              rs_region_arcs_t *A, const char *method)
{
    slong v1 = R->axis[0].var, v2 = R->axis[1].var, K1 = R->axis[0].count, K2 = R->axis[1].count;
    slong c, npts = 0, dropped = 0;
    json_t *conds = json_array();
    char *buf = NULL;
    size_t len = 0;
    FILE *f;
    f = open_memstream(&buf, &len);
    fprintf(f, "condition,%s,%s,scan\n", R->axis[0].name, R->axis[1].name);
    for (c = 0; c < nb; c++) {
        double *val = malloc((size_t) (K1 * K2) * sizeof(double));
        signed char *sg = malloc((size_t) (K1 * K2));
        json_array_append_new(conds, json_pack("{s:I,s:s,s:o}", "index", (json_int_t) c + 1, "origin",
                                               bc[c].origin, "poly", rs_json_zpoly(bc[c].f, v->s)));
        boundary_signs(sg, val, bc[c].f, v, v1, v2, x1, K1, x2, K2);
        if (run->opt->sweep.shard_index == 1) npts += boundary_rows(f, c, sg, val, x1, K1, x2, K2, A, bc[c].f, &dropped);
        free(val);
        free(sg);
    }
    fclose(f);
    json_object_set_new(b, "conditions", conds);
    json_object_set_new(b, "points", json_integer(npts));
    if (A != NULL) {
        json_object_set_new(b, "separating_arcs", rs_region_arcs_json(A));
        json_object_set_new(b, "dropped_points", json_integer(dropped));
        rs_region_arcs_free(A);
    }
    json_object_set_new(b, "method", json_string(method));
    json_object_set_new(o, "boundary", b);
    json_object_set_new(o, "boundary_table", json_string(buf));
    json_object_set_new(b, "columns", json_pack("[s,s,s,s]", "condition", R->axis[0].name, R->axis[1].name, "scan"));
    rs_sweep_json_rows(o, "boundary_rows", buf, run->opt->sweep.json_rows);
    free(buf);
    for (c = 0; c < nb; c++) {
        fmpz_mpoly_clear(bc[c].f, v->s->zctx);
        free(bc[c].origin);
    }
    free(bc);
}

/* the boundary overlay of a map whose p depends on both axes */
typedef struct {
    rs_run_t *run;
    const rs_variant_t *v;
    const rs_sweep_request_t *R;
    fmpq *const *xs;
} map_deco_t;

static void map_decorate(json_t *o, void *arg)
{
    map_deco_t *d = arg;
    const rs_sweep_axis_t *X = d->R->axis;
    if (fmpz_mpoly_degree_si(d->v->cp->p, X[0].var, d->v->s->zctx) > 0
        && fmpz_mpoly_degree_si(d->v->cp->p, X[1].var, d->v->s->zctx) > 0)
        map_boundary(o, d->run, d->v, d->R, d->xs[0], d->xs[1]);
}

/* the boundary at complex set values: p = re + i im over Q(i)[N1, N2];
 * the candidates are the distinct irreducible factors of |a_n|^2 and of the
 * Schur-Cohn deltas (stable iff all > 0: rs_schur_cx_conds), their zero
 * sets found from exact signs at the grid points as for real p */
typedef struct {
    rs_sweep_cx_t *J;
    rs_run_t *run;
    const rs_variant_t *v;
    const rs_sweep_request_t *R;
    fmpq *const *xs;
} cx_deco_t;

static void cx_bcond_add(bcond_t **bc, slong *nb, const fmpz_mpoly_t g, const char *origin, const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_factor_t fac;
    slong k, j;
    if (fmpz_mpoly_is_fmpz(g, ctx)) return;
    fmpz_mpoly_factor_init(fac, ctx);
    if (!fmpz_mpoly_factor(fac, g, ctx)) { fmpz_mpoly_factor_clear(fac, ctx); return; }
    for (k = 0; k < fac->num; k++) {
        int dup = 0;
        if (fmpz_mpoly_is_fmpz(fac->poly + k, ctx)) continue;
        for (j = 0; j < *nb && !dup; j++) dup = fmpz_mpoly_equal((*bc)[j].f, fac->poly + k, ctx);
        if (dup) continue;
        *bc = realloc(*bc, (size_t) (*nb + 1) * sizeof(bcond_t));
        fmpz_mpoly_init((*bc)[*nb].f, ctx);
        fmpz_mpoly_set((*bc)[*nb].f, fac->poly + k, ctx);
        (*bc)[*nb].origin = strdup(origin);
        (*nb)++;
    }
    fmpz_mpoly_factor_clear(fac, ctx);
}

/* the plane (N1, N2, lambda) of the separating arcs: p = re + i im there;
 * everything the decomposition points at, alive until the arcs are freed */
typedef struct {
    rs_scheme_struct xs;
    char *vars[3];
    fmpz_mpoly_t re, im;
    slong n;
    rs_run_t *run;
    rs_schur_cx_conds_t cc;
    rs_region_cx_t cx;
} cx_plane_t;

/* p(x, y, lambda) at rational (x, y) as a polynomial in lambda */
static void cx_plane_eval(fmpq_poly_t out, const fmpz_mpoly_t f, const fmpq_t x, const fmpq_t y, const cx_plane_t *P)
{
    slong i, len = fmpz_mpoly_length(f, P->xs.zctx);
    ulong ex[3];
    fmpq_t c, t;
    fmpq_init(c); fmpq_init(t);
    fmpq_poly_zero(out);
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_exp_ui(ex, f, i, P->xs.zctx);
        fmpz_mpoly_get_term_coeff_fmpz(fmpq_numref(c), f, i, P->xs.zctx);
        fmpz_one(fmpq_denref(c));
        fmpq_pow_si(t, x, (slong) ex[0]);
        fmpq_mul(c, c, t);
        fmpq_pow_si(t, y, (slong) ex[1]);
        fmpq_mul(c, c, t);
        fmpq_poly_get_coeff_fmpq(t, out, (slong) ex[2]);
        fmpq_add(t, t, c);
        fmpq_poly_set_coeff_fmpq(out, (slong) ex[2], t);
    }
    fmpq_clear(c); fmpq_clear(t);
}

/* the exact point verdict at (N1, N2) = (x, y): Schur-Cohn over Q(i) and Bilharz */
static int cx_plane_status(rs_status_t *st, const fmpq_t x, const fmpq_t y, void *arg)
{
    const cx_plane_t *P = arg;
    fmpq_poly_t re, im;
    int r;
    fmpq_poly_init(re); fmpq_poly_init(im);
    cx_plane_eval(re, P->re, x, y, P);
    cx_plane_eval(im, P->im, x, y, P);
    if (FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im)) < P->n) {
        *st = RS_STATUS_SINGULAR;   /* the leading coefficient vanishes: no step */
        r = RS_OK;
    } else r = rs_routh_complex_checked_status(st, re, im, P->n, P->run->err);
    if (r == RS_ERR_INCONSISTENT) P->run->outcome |= RS_OUTCOME_INCONSISTENT;
    fmpq_poly_clear(re); fmpq_poly_clear(im);
    return r;
}

static void cx_plane_clear(cx_plane_t *P)
{
    rs_schur_cx_conds_clear(&P->cc, P->xs.zctx);
    fmpz_mpoly_clear(P->re, P->xs.zctx); fmpz_mpoly_clear(P->im, P->xs.zctx);
    fmpz_mpoly_ctx_clear(P->xs.zctx);
    fmpq_mpoly_ctx_clear(P->xs.ctx);
}

/* The separating arcs of the (N1, N2) plane at complex set values (issue 13
 * part 3 as for real p): the decomposition of the plane by the same Schur-Cohn
 * conditions (stable iff |a_n|^2 > 0 and every delta > 0), an arc kept when
 * the cells on its two sides differ. NULL (every factor drawn) when the
 * decomposition fails or a parameter other than the axes is left; P (set up
 * here, cleared by the caller after the arcs) holds what they point at. */
static rs_region_arcs_t *cx_map_arcs(cx_plane_t *P, cx_deco_t *d)
{
    const rs_scheme_struct *s = d->v->s;
    const rs_sweep_axis_t *X = d->R->axis;
    slong *gmap = flint_malloc(s->nvars * sizeof(slong)), k;
    rs_region_arcs_t *A = NULL;
    rs_error_struct saved = *d->run->err;
    memset(P, 0, sizeof *P);
    P->vars[0] = (char *) X[0].name; P->vars[1] = (char *) X[1].name; P->vars[2] = (char *) "lambda";
    fmpq_mpoly_ctx_init(P->xs.ctx, 3, ORD_LEX);
    fmpz_mpoly_ctx_init(P->xs.zctx, 3, ORD_LEX);
    P->xs.nvars = 3;
    P->xs.lambda_var = 2;
    P->xs.vars = P->vars;
    P->run = d->run;
    fmpz_mpoly_init(P->re, P->xs.zctx); fmpz_mpoly_init(P->im, P->xs.zctx);
    rs_schur_cx_conds_init(&P->cc);
    for (k = 0; k < s->nvars; k++) {
        gmap[k] = k == X[0].var ? 0 : k == X[1].var ? 1 : k == s->lambda_var ? 2 : -1;
        if (gmap[k] < 0 && (fmpz_mpoly_degree_si(d->J->re, k, s->zctx) > 0
                            || fmpz_mpoly_degree_si(d->J->im, k, s->zctx) > 0)) goto out;
    }
    fmpz_mpoly_compose_fmpz_mpoly_gen(P->re, d->J->re, gmap, s->zctx, P->xs.zctx);
    fmpz_mpoly_compose_fmpz_mpoly_gen(P->im, d->J->im, gmap, s->zctx, P->xs.zctx);
    P->n = FLINT_MAX(fmpz_mpoly_degree_si(P->re, 2, P->xs.zctx), fmpz_mpoly_degree_si(P->im, 2, P->xs.zctx));
    if (P->n < 1 || !rs_schur_cx_conds(&P->cc, P->re, P->im, 2, P->xs.zctx)) goto out;
    P->cx.s = &P->xs;
    P->cx.lead = P->cc.lead;
    P->cx.delta = P->cc.delta;
    P->cx.ndelta = P->cc.ndelta;
    P->cx.status = cx_plane_status;
    P->cx.arg = P;
    P->cx.name = X[0].name;
    P->cx.substituted = d->v->assigned;
    if (rs_region_arcs_new_cx(&A, d->run, &P->cx, s->zctx, gmap, s->nvars) != RS_OK) {
        A = NULL;
        *d->run->err = saved;
    }
out:
    flint_free(gmap);
    return A;
}

static void cx_map_boundary(json_t *o, cx_deco_t *d)
{
    const rs_scheme_struct *s = d->v->s;
    const rs_sweep_axis_t *X = d->R->axis;
    rs_schur_cx_conds_t cc;
    bcond_t *bc = NULL;
    slong nb = 0, k;
    json_t *b;
    cx_plane_t P;
    rs_region_arcs_t *A;
    if (d->R->naxes < 2) return;
    /* p must depend on both axes (as for real p) */
    for (k = 0; k < 2; k++)
        if (fmpz_mpoly_degree_si(d->J->re, X[k].var, s->zctx) <= 0
            && fmpz_mpoly_degree_si(d->J->im, X[k].var, s->zctx) <= 0) return;
    rs_schur_cx_conds_init(&cc);
    if (!rs_schur_cx_conds(&cc, d->J->re, d->J->im, s->lambda_var, s->zctx)) {
        rs_schur_cx_conds_clear(&cc, s->zctx);
        json_object_set_new(o, "boundary_note", json_string("no boundary: the Schur-Cohn conditions over Q(i) grew "
                                                           "too large"));
        return;
    }
    cx_bcond_add(&bc, &nb, cc.lead, "|a_n|^2 (Schur-Cohn over Q(i))", s->zctx);
    for (k = 0; k < cc.ndelta && rs_budget_check(NULL, "the map's boundary") == RS_OK; k++) {
        char org[80];
        snprintf(org, sizeof org, "delta_%ld (Schur-Cohn over Q(i))", (long) k + 1);
        cx_bcond_add(&bc, &nb, cc.delta + k, org, s->zctx);
    }
    rs_schur_cx_conds_clear(&cc, s->zctx);
    b = json_object();
    A = cx_map_arcs(&P, d);
    map_boundary_rows(o, b, d->run, d->v, d->R, d->xs[0], d->xs[1], bc, nb, A, A != NULL
        ? "zero sets of the irreducible factors of |a_n|^2 and of the division-free Schur-Cohn deltas of p over "
          "Q(i)[N1, N2] (stable iff all > 0): exact signs at the grid points, a crossing between two neighbours of "
          "a row (column) placed by linear interpolation; only the arcs that separate stable from not stable cells "
          "of the plane's decomposition by the same conditions are drawn"
        : "zero sets of the irreducible factors of |a_n|^2 and of the division-free Schur-Cohn deltas of p over "
          "Q(i)[N1, N2] (stable iff all > 0): exact signs at the grid points, a crossing between two neighbours of "
          "a row (column) placed by linear interpolation; every factor is drawn (the plane's decomposition did not "
          "complete, so arcs separating nothing are included)");
    cx_plane_clear(&P);
}

/* the map's element at complex set values: over Q(i), the boundary of the
 * Schur-Cohn conditions over Q(i) overlaid */
static void cx_map_decorate(json_t *o, void *arg)
{
    cx_deco_t *d = arg;
    const rs_sweep_cx_t *J = d->J;
    cx_map_boundary(o, d);
    json_object_set_new(o, "over", json_string("Q(i)"));
    json_object_set(o, "complex", J->csat);
    json_object_set_new(o, "method", json_string(
        "p over Q(i) at each point: complex Schur-Cohn and Bilharz on the bilinear transform (must agree), p's own "
        "root counts; the radius certified from p conj(p) (the same moduli)"));
    json_object_set_new(o, "cross_check", json_pack("{s:I,s:s}", "stride", (json_int_t) J->stride, "method",
        "every stride-th point also by the certified ladder on p conj(p) (stable iff p is, unstable where p is; "
        "exit 3 on disagreement)"));
}

/* a map of two real parameters with the complex set values fixed */
static int cx_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R, const rs_variant_t *v,
                      fmpq *const *xs, double t0)
{
    slong npoints = R->axis[0].count * R->axis[1].count;
    rs_sweep_model_t m;
    rs_sweep_cx_t J;
    int r = rs_sweep_cx_init(&J, run, q, R, v);
    if (r == RS_OK) {
        J.vals[0] = xs[0];
        J.vals[1] = xs[1];
        J.stride = npoints > 256 ? npoints / 256 : 1;
        J.csat = rs_run_cx_at(run);
        m.point = rs_sweep_cx_point;
        m.model = &J;
        m.serial = 0;
        cx_deco_t d;
        d.J = &J;
        d.run = run;
        d.v = v;
        d.R = R;
        d.xs = xs;
        r = rs_sweep_map_finish(run, q, R, &m, (const fmpq *const *) xs, t0, cx_map_decorate, &d);
        json_decref(J.csat);
    }
    rs_sweep_cx_clear(&J);
    return r;
}

int rs_an_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R)
{
    const rs_sweep_axis_t *X = R->axis;
    slong npoints = X[0].count * X[1].count;
    rs_variant_t *v;
    rs_sweep_poly_t *J = NULL;
    rs_sweep_model_t m;
    fmpq *xs[2];
    double t0 = rs_sweep_now();
    int r = rs_sweep_estimate_map(run, q, (double) X[0].count * (double) X[1].count);
    if (r == RS_OK) r = rs_sweep_variant(&v, run, R);
    if (r != RS_OK) return r;
    xs[0] = rs_grid_axis(X[0].from, X[0].to, X[0].count);
    xs[1] = rs_grid_axis(X[1].from, X[1].to, X[1].count);
    if (run->c->ncsets > 0) {
        r = cx_map_run(run, q, R, v, xs, t0);
        _fmpq_vec_clear(xs[0], X[0].count);
        _fmpq_vec_clear(xs[1], X[1].count);
        return r;
    }
    r = rs_sweep_poly_new(&J, run, q, R, v, (const fmpq *const *) xs, npoints);
    if (r == RS_OK) {
        map_deco_t d;
        d.run = run;
        d.v = v;
        d.R = R;
        d.xs = xs;
        rs_sweep_poly_model(&m, J);
        r = rs_sweep_map_finish(run, q, R, &m, (const fmpq *const *) xs, t0, map_decorate, &d);
    }
    rs_sweep_poly_free(J);
    _fmpq_vec_clear(xs[0], X[0].count);
    _fmpq_vec_clear(xs[1], X[1].count);
    return r;
}

void rs_an_map_boundary_factors(json_t *o, rs_run_t *run, const rs_variant_t *v, const rs_sweep_request_t *R,
                                fmpq *const *xs, const fmpz_mpoly_struct *g, char *const *origin, slong ng,
                                const char *method)
{
    bcond_t *bc = NULL;
    slong nb = 0, k;
    for (k = 0; k < ng && rs_budget_check(NULL, "the map's boundary") == RS_OK; k++)
        cx_bcond_add(&bc, &nb, g + k, origin[k], v->s->zctx);
    map_boundary_rows(o, json_object(), run, v, R, xs[0], xs[1], bc, nb, NULL, method);
}
