/* sweep_poly.c -- the model of the equations for sweeps and maps
 * (sweep_impl.h): p(lambda; point) evaluated exactly as an integer
 * polynomial at every grid point (the charpoly with the other parameters
 * substituted, scaled by the denominators), its certified verdict by the
 * ladder (ladder.h) with Routh and Schur-Cohn as the exact rung, "singular"
 * where the degree in lambda drops, semisimplicity for a system's repeated
 * circle roots, and the certified radius / modes the request asks for. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz_vec.h>
#include <flint/fmpq_vec.h>
#include <arb.h>
#include <acb.h>
#include "analysis/sweep_impl.h"
#include "numeric/grid.h"
#include "numeric/modes.h"
#include "recstab/radius.h"
#include "recstab/rootcount.h"
#include "recstab/semisimple.h"
#include "recstab/routh.h"
#include "recstab/jury.h"
#include "analysis/registry.h"
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"
#include <acb_poly.h>

struct rs_sweep_poly_struct {
    rs_run_t *run;
    int kind;                           /* RS_SWEEP_OF_* */
    int is_map;
    int first_level;                    /* of the ladder (--sweep-level) */
    rs_grid_terms_t T;
    fmpz *U1, *U2;                      /* power tables */
    slong K1, K2;                       /* points per axis (K2 = 1 for sweeps) */
    slong npoints;
    /* modes */
    slong nref;
    fmpq *refval;                       /* npoints * nref reference values */
    fmpq *hval;                         /* npoints time steps */
    slong max_prec;
    /* the point verdict of systems: the variant and the swept parameters */
    const rs_variant_t *v;
    slong var[2];
    const fmpq *x[2];                   /* axis values (x[1] NULL for sweeps) */
};
typedef struct rs_sweep_poly_struct job_t;

/* ---- the exact rung ------------------------------------------------------------------------- */

static int exact_count(rs_rootcount_t rc, const fmpz_poly_t p, rs_error_t err)
{
    rs_routh_t ro;
    rs_jury_t ju;
    int r;
    rs_routh_init(ro);
    rs_jury_init(ju);
    r = rs_routh_fmpz_poly(ro, p, err);
    if (r == RS_OK) r = rs_jury_count_fmpz_poly(ju, p, err);
    if (r == RS_OK) {
        *rc = *ro->count;
        if (!rs_rootcount_equal(ro->count, ju->count))
            r = rs_error_set(err, RS_ERR_INCONSISTENT,
                             "Routh (bilinear) and Schur-Cohn counts disagree at a sweep point");
    }
    rs_routh_clear(ro);
    rs_jury_clear(ju);
    return r;
}

/* The ladder's exact rung (ladder.h): Routh and Schur-Cohn, which must
 * agree; arg, when not NULL, is an rs_rootcount_struct that gets the counts. */
static int exact_rung(rs_ladder_count_t *c, const fmpz_poly_t p, void *arg, rs_error_t err)
{
    rs_rootcount_t rc;
    int r;
    rs_rootcount_init(rc);
    r = exact_count(rc, p, err);
    if (r == RS_OK) {
        c->inside = rc->inside;
        c->on = rc->on;
        c->outside = rc->outside;
        c->max_on_mult = rs_rootcount_max_on_mult(rc);
        c->status = (int) rs_rootcount_status(rc);
        if (arg != NULL) *(rs_rootcount_struct *) arg = *rc;
    }
    rs_rootcount_clear(rc);
    return r;
}

int rs_sweep_decide(rs_sweep_point_t *pt, const fmpz_poly_t p, rs_error_t err)
{
    return rs_ladder_decide(pt, p, RS_LEVEL_FAST, exact_rung, NULL, err);
}

/* ---- one point ------------------------------------------------------------------------------ */

static void point_poly(fmpz_poly_t P, const job_t *J, slong idx)
{
    slong i = idx % J->K1, j = idx / J->K1;
    rs_grid_terms_eval(P, &J->T, J->U1 + i * (J->T.d1 + 1), J->is_map ? J->U2 + j * (J->T.d2 + 1) : NULL);
}

/* [*lo, *hi] contains x (doubles rounded outward; +-inf when x is not finite). */
static void arb_bounds_d(double *lo, double *hi, const arb_t x)
{
    arf_t t;
    arf_init(t);
    arb_get_lbound_arf(t, x, 64);
    *lo = arf_is_nan(t) ? -INFINITY : arf_get_d(t, ARF_RND_FLOOR);
    arb_get_ubound_arf(t, x, 64);
    *hi = arf_is_nan(t) ? INFINITY : arf_get_d(t, ARF_RND_CEIL);
    arf_clear(t);
}

void rs_sweep_row_modes(rs_sweep_row_t *pt, const rs_radius_t rr, const fmpq_t hq, const fmpq *refq, slong nref)
{
    slong prec = 128, k, i;
    arb_t h, sig, om, mag, zeta;
    arb_ptr refs = _arb_vec_init(nref);
    int *principal = calloc((size_t) rr->nroots + 1, sizeof(int));
    arb_init(h); arb_init(sig); arb_init(om); arb_init(mag); arb_init(zeta);
    arb_set_fmpq(h, hq, prec);
    for (k = 0; k < nref; k++) arb_set_fmpq(refs + k, refq + k, prec);
    rs_modes_principal(principal, rr, h, refs, nref, prec);
    for (k = 0; k < 3 * RS_SWEEP_MAX_REFS; k++) pt->mode_lo[k] = pt->mode_hi[k] = NAN;
    for (k = 0; k < nref; k++)
        for (i = 0; i < rr->nroots; i++) {
            const acb_struct *z = rr->roots + i;
            if (principal[i] != k + 1 || acb_is_zero(z)) continue;
            if (arf_sgn(arb_midref(acb_imagref(z))) < 0 && !arb_is_zero(acb_imagref(z))) continue;
            rs_modes_continuous(sig, om, mag, zeta, z, h, prec);
            arb_bounds_d(pt->mode_lo + 3 * k, pt->mode_hi + 3 * k, zeta);
            arb_sub(mag, mag, refs + k, prec);
            arb_div(mag, mag, refs + k, prec);
            arb_bounds_d(pt->mode_lo + 3 * k + 1, pt->mode_hi + 3 * k + 1, mag);
            arb_bounds_d(pt->mode_lo + 3 * k + 2, pt->mode_hi + 3 * k + 2, om);
            pt->nmodes++;
            break;
        }
    free(principal);
    _arb_vec_clear(refs, nref);
    arb_clear(h); arb_clear(sig); arb_clear(om); arb_clear(mag); arb_clear(zeta);
}

/* What the polynomial alone cannot say: the step is singular where the
 * degree in lambda drops, and a repeated circle root of a system is bounded
 * when semisimple (rs_semisimple_verdict on the lambda-matrix there). */
static int point_system(rs_sweep_row_t *pt, const job_t *J, slong idx, const fmpz_poly_t P,
                        const rs_rootcount_struct *known, rs_error_t err)
{
    slong i = idx % J->K1, j = idx / J->K1;
    fmpq vals[2];
    rs_rootcount_t rc;
    rs_semisimple_t ss;
    rs_status_t st;
    fmpz_poly_t pp;
    int r;
    if (fmpz_poly_is_zero(P)) return RS_OK;
    if (J->v->singular || fmpz_poly_degree(P) < J->T.dl) {
        pt->d.verdict = RS_STATUS_SINGULAR;
        pt->d.level = RS_LEVEL_EXACT;
        pt->d.rho_lower = 0;
        pt->d.rho_upper = INFINITY;
        return RS_OK;
    }
    if (!(pt->d.repeated_on && pt->d.verdict == RS_STATUS_UNSTABLE) || J->v->s->from_char) return RS_OK;
    vals[0] = J->x[0][i];
    if (J->is_map) vals[1] = J->x[1][j];
    fmpz_poly_init(pp);
    fmpz_poly_primitive_part(pp, P);
    rs_rootcount_init(rc);
    rs_semisimple_init(ss);
    /* the ladder's exact rung kept no counts; a stability sweep has them */
    r = known != NULL ? (*rc = *known, RS_OK) : exact_count(rc, pp, err);
    if (r == RS_OK)
        r = rs_semisimple_verdict(&st, ss, J->v->s, J->var, vals, J->is_map ? 2 : 1, pp, rc, 0, err);
    if (r == RS_OK) pt->d.verdict = (int) st;
    rs_semisimple_clear(ss);
    rs_rootcount_clear(rc);
    fmpz_poly_clear(pp);
    return r;
}

/* A stability sweep: the exact verdict with the counts. */
static int point_stability(rs_sweep_row_t *pt, const job_t *J, slong idx, const fmpz_poly_t P, rs_error_t err)
{
    rs_rootcount_t rc;
    int r = RS_OK;
    pt->d.verdict = -1;
    pt->d.rho_lower = 0;
    pt->d.rho_upper = INFINITY;
    if (fmpz_poly_is_zero(P)) return RS_OK;
    rs_rootcount_init(rc);
    if (fmpz_poly_degree(P) == 0) {
        pt->d.verdict = RS_STATUS_STABLE;
        pt->d.level = RS_LEVEL_EXACT;
        pt->inside = pt->on = pt->outside = 0;
    } else {
        r = rs_ladder_decide_exact(&pt->d, P, exact_rung, rc, err);
        pt->inside = (int) rc->inside;
        pt->on = (int) rc->on;
        pt->outside = (int) rc->outside;
    }
    pt->inside += (int) J->v->cp->removed_lambda_power;   /* det's roots at 0 divided out of p */
    if (r == RS_OK) r = point_system(pt, J, idx, P, fmpz_poly_degree(P) > 0 ? rc : NULL, err);
    rs_rootcount_clear(rc);
    return r;
}

/* The certified radius to 15 digits (and the roots, for modes) where the
 * ladder's bounds are not enough. */
static int point_radius(rs_sweep_row_t *pt, const job_t *J, slong idx, const fmpz_poly_t P, rs_error_t err)
{
    rs_radius_t rr;
    slong lv = 0;
    int r = RS_OK;
    while (fmpz_is_zero(P->coeffs + lv)) lv++;
    if (fmpz_poly_degree(P) - lv == 0) {
        pt->d.rho_lower = pt->d.rho_upper = 0;
        return RS_OK;
    }
    rs_radius_init(rr);
    r = rs_radius_fmpz_poly(rr, P, 15, J->max_prec, err);
    if (r == RS_OK) {
        double lo = rs_ladder_lower_d(rr->lower), hi = rs_ladder_upper_d(rr->upper);
        if (!(pt->d.rho_lower == 1.0 && pt->d.rho_upper == 1.0)) {
            pt->d.rho_lower = lo;
            pt->d.rho_upper = hi;
        }
        if (J->kind == RS_SWEEP_OF_MODES) rs_sweep_row_modes(pt, rr, J->hval + idx, J->refval + idx * J->nref, J->nref);
    }
    rs_radius_clear(rr);
    return r;
}

/* the model's callback (rs_sweep_model_t) */
static void compute_point(rs_sweep_row_t *pt, slong idx, void *model, rs_error_t err)
{
    const job_t *J = model;
    fmpz_poly_t P;
    int r;
    memset(pt, 0, sizeof *pt);
    pt->inside = pt->on = pt->outside = -1;
    fmpz_poly_init(P);
    point_poly(P, J, idx);
    if (J->kind == RS_SWEEP_OF_STABILITY && !J->is_map) {
        r = point_stability(pt, J, idx, P, err);
    } else {
        r = rs_ladder_decide(&pt->d, P, J->first_level, exact_rung, NULL, err);
        if (r == RS_OK) r = point_system(pt, J, idx, P, NULL, err);
        if (r == RS_OK && pt->d.verdict >= 0 && pt->d.verdict != RS_STATUS_SINGULAR && fmpz_poly_degree(P) >= 1
            && (J->kind == RS_SWEEP_OF_MODES || (!pt->d.isolated && !(pt->d.rho_lower == 1.0 && pt->d.rho_upper == 1.0))
                || (J->kind == RS_SWEEP_OF_RADIUS && !J->is_map)))
            r = point_radius(pt, J, idx, P, err);
    }
    pt->d.status = r;
    fmpz_poly_clear(P);
}

/* ---- the model ---------------------------------------------------------------------------- */

static int check_free(rs_run_t *run, const rs_request_t *q, const rs_variant_t *v, slong v1, slong v2,
                      const char *what)
{
    const rs_scheme_struct *s = v->s;
    slong i;
    for (i = 0; i < s->nvars; i++) {
        if (i == s->lambda_var || i == v1 || i == v2) continue;
        if (fmpz_mpoly_degree_si(v->cp->p, i, s->zctx) > 0) {
            char msg[600];
            snprintf(msg, sizeof msg, "%s needs every other parameter set to a number; still symbolic: %s "
                     "(use set or --set)", what, s->vars[i]);
            return rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
        }
    }
    return RS_OK;
}

static int parse_modes_opts(job_t *J, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v,
                            const char *opts, slong var, const fmpq *vals)
{
    const char *t = opts;
    int have_ref = 0, r = RS_OK;
    slong i;
    J->hval = _fmpq_vec_init(J->npoints);
    for (i = 0; i < J->npoints; i++) fmpq_one(J->hval + i);
    J->nref = 0;
    J->refval = NULL;
    while (t != NULL && *t) {
        const char *end = t;
        while (*t == ' ' || *t == '\t') t++;
        if (*t == '\0') break;
        if (strncmp(t, "h=", 2) == 0) {
            r = rs_req_eval_points(J->hval, 1, run, q, v, t + 2, var, vals, J->npoints, &end);
            for (i = 0; i < J->npoints && r == RS_OK; i++)
                if (fmpq_sgn(J->hval + i) <= 0)
                    r = rs_req_error(run, q, t + 2, RS_ERR_INPUT,
                                     "expected a time step h > 0 at every point, found '%s'", t + 2);
        } else if (strncmp(t, "reference=", 10) == 0) {
            fmpq *tmp = _fmpq_vec_init(J->npoints);
            const char *u = t + 10;
            have_ref = 1;
            for (;;) {
                if (J->nref >= RS_SWEEP_MAX_REFS) {
                    _fmpq_vec_clear(tmp, J->npoints);
                    return rs_req_error(run, q, u, RS_ERR_LIMIT, "at most 4 references, found more at '%s'", u);
                }
                r = rs_req_eval_points(tmp, 1, run, q, v, u, var, vals, J->npoints, &end);
                if (r != RS_OK) break;
                {
                    fmpq *nr = _fmpq_vec_init(J->npoints * (J->nref + 1));
                    slong k, p;
                    for (p = 0; p < J->npoints; p++) {
                        for (k = 0; k < J->nref; k++)
                            fmpq_set(nr + p * (J->nref + 1) + k, J->refval + p * J->nref + k);
                        fmpq_set(nr + p * (J->nref + 1) + J->nref, tmp + p);
                    }
                    if (J->refval) _fmpq_vec_clear(J->refval, J->npoints * J->nref);
                    J->refval = nr;
                    J->nref++;
                }
                if (*end != ',') break;
                u = end + 1;
            }
            _fmpq_vec_clear(tmp, J->npoints);
        } else {
            return rs_req_error(run, q, t, RS_ERR_INPUT, "expected an option (h=, reference=), found '%s'", t);
        }
        if (r != RS_OK) return r;
        /* the expression parser stops after trailing blanks: the next option
         * may already start here */
        if (end > t && (end[-1] == ' ' || end[-1] == '\t')) end--;
        if (*end != '\0' && *end != ' ' && *end != '\t')
            return rs_req_error(run, q, end, RS_ERR_INPUT, "expected a space or the end after the value, found '%s'",
                                end);
        t = end;
    }
    if (!have_ref)
        return rs_req_error(run, q, q->text, RS_ERR_INPUT,
                            "sweep ... of modes needs reference=EXPR (the exact frequency of the mode, e.g. "
                            "reference=w with h=1 for a scaled w = omega*h), found '%s'", q->text);
    return RS_OK;
}

void rs_sweep_poly_free(rs_sweep_poly_t *J)
{
    if (J == NULL) return;
    rs_grid_terms_clear(&J->T);
    if (J->U1) _fmpz_vec_clear(J->U1, J->K1 * (J->T.d1 + 1));
    if (J->U2) _fmpz_vec_clear(J->U2, J->K2 * (J->T.d2 + 1));
    if (J->refval) _fmpq_vec_clear(J->refval, J->npoints * J->nref);
    if (J->hval) _fmpq_vec_clear(J->hval, J->npoints);
    free(J);
}

int rs_sweep_poly_new(rs_sweep_poly_t **out, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                      const rs_variant_t *v, const fmpq *const *xs, slong npoints)
{
    job_t *J;
    slong v2 = R->naxes > 1 ? R->axis[1].var : -1;
    int r;
    *out = NULL;
    r = check_free(run, q, v, R->axis[0].var, v2, R->kind == RS_SWEEP_KIND_MAP ? "map" : "sweep");
    if (r != RS_OK) return r;
    J = calloc(1, sizeof *J);
    J->run = run;
    J->kind = R->of;
    J->is_map = R->kind == RS_SWEEP_KIND_MAP;
    J->first_level = run->opt->sweep.first_level;
    J->K1 = J->is_map ? R->axis[0].count : npoints;
    J->K2 = J->is_map ? R->axis[1].count : 1;
    J->npoints = npoints;
    J->max_prec = run->opt->max_prec;
    rs_grid_terms_init(&J->T, v->cp->p, v->s->lambda_var, R->axis[0].var, v2, v->s->zctx);
    J->v = v;
    J->var[0] = R->axis[0].var;
    J->var[1] = v2;
    J->x[0] = xs[0];
    J->x[1] = J->is_map ? xs[1] : NULL;
    J->U1 = rs_grid_powers(xs[0], J->K1, J->T.d1);
    if (J->is_map) J->U2 = rs_grid_powers(xs[1], J->K2, J->T.d2);
    if (R->of == RS_SWEEP_OF_MODES) {
        r = parse_modes_opts(J, run, q, v, R->opts, R->axis[0].var, xs[0]);
        if (r != RS_OK) {
            rs_sweep_poly_free(J);
            return r;
        }
    }
    *out = J;
    return RS_OK;
}

void rs_sweep_poly_model(rs_sweep_model_t *m, rs_sweep_poly_t *J)
{
    m->point = compute_point;
    m->model = J;
    m->serial = 0;
}

slong rs_sweep_poly_nref(const rs_sweep_poly_t *J)
{
    return J->nref;
}

/* ---- complex set values: p over Q(i) per point ------------------------------------------ */

int rs_sweep_cx_init(rs_sweep_cx_t *J, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                     const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    slong k, a;
    int r = RS_OK;
    memset(J, 0, sizeof *J);
    J->s = s;
    J->naxes = R->naxes;
    J->of = R->of;
    J->max_prec = run->opt->max_prec;
    J->K1 = R->axis[0].count;
    fmpz_mpoly_init(J->re, s->zctx);
    fmpz_mpoly_init(J->im, s->zctx);
    for (a = 0; a < R->naxes; a++) {
        J->var[a] = R->axis[a].var;
        J->names[a] = R->axis[a].name;
        for (k = 0; r == RS_OK && k < run->c->ncsets; k++)
            if (strcmp(run->c->csets[k].name, R->axis[a].name) == 0) {
                char msg[300];
                snprintf(msg, sizeof msg, "expected a real parameter to %s, found '%s', which has a complex set "
                         "value", R->kind == RS_SWEEP_KIND_MAP ? "map" : "sweep", R->axis[a].name);
                r = rs_req_error(run, q, R->axis[a].at, RS_ERR_INPUT, "%s", msg);
            }
    }
    if (r != RS_OK) return r;
    J->n = rs_run_cx_poly(J->re, J->im, run, v);
    J->zeros = s->complex_char ? 0 : v->cp->removed_lambda_power;   /* a char line with i keeps them in p */
    for (k = 0; r == RS_OK && k < s->nvars; k++) {
        char msg[300];
        if (k == s->lambda_var || k == J->var[0] || (J->naxes > 1 && k == J->var[1])
            || (fmpz_mpoly_degree_si(J->re, k, s->zctx) <= 0 && fmpz_mpoly_degree_si(J->im, k, s->zctx) <= 0))
            continue;
        snprintf(msg, sizeof msg, "%s needs every other parameter set to a number (real or complex); still "
                 "symbolic: %s (use set or --set)", R->kind == RS_SWEEP_KIND_MAP ? "map" : "sweep", s->vars[k]);
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
    }
    if (r == RS_OK && (J->n < 1 || (!s->complex_char && J->n < v->cp->degree))) {
        char msg[300];
        snprintf(msg, sizeof msg, "%s: the leading coefficient of p vanishes at the complex set values at every "
                 "point: the implicit step cannot be solved", R->kind == RS_SWEEP_KIND_MAP ? "map" : "sweep");
        r = rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
    }
    return r;
}

int rs_sweep_cx_modes(rs_sweep_cx_t *J, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                      const rs_variant_t *v, const fmpq *vals, slong npoints)
{
    job_t *T = calloc(1, sizeof *T);   /* parse_modes_opts' fields only */
    int r;
    T->npoints = npoints;
    r = parse_modes_opts(T, run, q, v, R->opts, R->axis[0].var, vals);
    J->npoints = npoints;
    J->hval = T->hval;
    J->refval = T->refval;
    J->nref = T->nref;
    free(T);
    return r;
}

void rs_sweep_cx_clear(rs_sweep_cx_t *J)
{
    if (J->hval != NULL) _fmpq_vec_clear(J->hval, J->npoints);
    if (J->refval != NULL) _fmpq_vec_clear(J->refval, J->npoints * J->nref);
    J->hval = J->refval = NULL;
    if (J->s == NULL) return;
    fmpz_mpoly_clear(J->re, J->s->zctx);
    fmpz_mpoly_clear(J->im, J->s->zctx);
}

void rs_sweep_cx_point(rs_sweep_row_t *pt, slong idx, void *model, rs_error_t err)
{
    const rs_sweep_cx_t *J = model;
    const rs_scheme_struct *s = J->s;
    fmpq *x = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc((size_t) s->nvars * sizeof(fmpq *));
    fmpq_poly_t pr, pi;
    rs_rootcount_t rc;
    rs_status_t st;
    slong k;
    int r = RS_OK;
    memset(pt, 0, sizeof *pt);
    pt->inside = pt->on = pt->outside = -1;
    pt->d.verdict = -1;
    pt->d.rho_lower = 0;
    pt->d.rho_upper = INFINITY;
    pt->d.level = RS_LEVEL_EXACT;
    for (k = 0; k < s->nvars; k++) pp[k] = x + k;
    if (J->naxes == 1) {
        fmpq_set(x + J->var[0], J->vals[0] + idx);
    } else {
        fmpq_set(x + J->var[0], J->vals[0] + idx % J->K1);
        fmpq_set(x + J->var[1], J->vals[1] + idx / J->K1);
    }
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    rs_rootcount_init(rc);
    rs_run_cx_eval(pr, J->re, pp, s);
    rs_run_cx_eval(pi, J->im, pp, s);
    if (fmpq_poly_is_zero(pr) && fmpq_poly_is_zero(pi)) {
        /* undefined: p vanishes identically here */
    } else if (FLINT_MAX(fmpq_poly_degree(pr), fmpq_poly_degree(pi)) < J->n) {
        pt->d.verdict = RS_STATUS_SINGULAR;
    } else if ((r = rs_routh_complex_checked_status(&st, pr, pi, J->n, err)) == RS_OK) {
        rs_routh_complex_rootcount(rc, pr, pi);
        if (rs_rootcount_status(rc) != st)
            r = rs_error_set(err, RS_ERR_INCONSISTENT, "over Q(i): complex Schur-Cohn and Bilharz say %s, p's "
                             "root counts say %s", rs_status_name(st), rs_status_name(rs_rootcount_status(rc)));
        if (r == RS_OK && J->stride > 0 && idx % J->stride == 0) r = rs_cx_norm_check(st, pr, pi, err);
        pt->d.verdict = (int) st;
        pt->inside = (int) (rc->inside + J->zeros);
        pt->on = (int) rc->on;
        pt->outside = (int) rc->outside;
        pt->d.repeated_on = rs_rootcount_max_on_mult(rc) > 1;
        if (rc->on > 0 && rc->outside == 0) pt->d.rho_lower = pt->d.rho_upper = 1.0;   /* exact */
        if (r == RS_OK && J->of == RS_SWEEP_OF_MODES && J->n >= 1) {
            rs_radius_t rr;
            rs_radius_init(rr);
            if (rs_cx_roots(rr, pr, pi, 60, 128, J->max_prec) == 1 && rr->nroots == J->n) {
                rs_sweep_row_modes(pt, rr, J->hval + idx, J->refval + idx * J->nref, J->nref);
                if (!(pt->d.rho_lower == 1.0 && pt->d.rho_upper == 1.0)) {
                    /* the radius from the same certified roots (not a second root finding on p conj(p)) */
                    rs_radius_set_rho(rr, rr->roots, rr->nroots, 128);
                    pt->d.rho_lower = rs_ladder_lower_d(rr->lower);
                    pt->d.rho_upper = rs_ladder_upper_d(rr->upper);
                    pt->d.isolated = 1;
                }
            } else {
                r = rs_error_set(err, RS_ERR_LIMIT, "modes over Q(i): the roots of p were not isolated within the "
                                 "precision limit (%ld bits)", (long) J->max_prec);
            }
            rs_radius_clear(rr);
        }
        if (r == RS_OK && J->of == RS_SWEEP_OF_RADIUS && !(pt->d.rho_lower == 1.0 && pt->d.rho_upper == 1.0)) {
            fmpz_poly_t N;
            fmpz_poly_init(N);
            rs_schur_complex_norm(N, pr, pi);
            for (k = 0; k < fmpz_poly_length(N) && fmpz_is_zero(N->coeffs + k); k++) ;
            if (fmpz_poly_degree(N) - k <= 0) {
                pt->d.rho_lower = pt->d.rho_upper = 0;
            } else {
                rs_radius_t rr;
                rs_radius_init(rr);
                r = rs_radius_fmpz_poly(rr, N, 15, J->max_prec, err);
                if (r == RS_OK) {
                    pt->d.rho_lower = rs_ladder_lower_d(rr->lower);
                    pt->d.rho_upper = rs_ladder_upper_d(rr->upper);
                    pt->d.isolated = 1;
                }
                rs_radius_clear(rr);
            }
            fmpz_poly_clear(N);
        }
    }
    /* the certified radius against the exact count: stable needs rho < 1, a
     * root outside rho > 1 (exit 3 otherwise) */
    if (r == RS_OK && pt->d.verdict >= 0 && pt->d.isolated
        && ((pt->d.verdict == RS_STATUS_STABLE && pt->d.rho_lower >= 1.0)
            || (rc->outside > 0 && pt->d.rho_upper <= 1.0)))
        r = rs_error_set(err, RS_ERR_INCONSISTENT, "over Q(i): the exact count says %s (%ld outside), the "
                         "certified radius is in [%.17g, %.17g]", rs_status_name((rs_status_t) pt->d.verdict),
                         (long) rc->outside, pt->d.rho_lower, pt->d.rho_upper);
    pt->d.status = r;
    rs_rootcount_clear(rc);
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    _fmpq_vec_clear(x, s->nvars);
    flint_free(pp);
}
