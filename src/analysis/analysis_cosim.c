/* analysis_cosim.c -- schemes whose subsystems are integrated exactly
 * (`integrate S exact H`, co-simulation coupling through coupling forces
 * and/or the partner's states, explicit or implicit order K): the recurrence has
 * matrix-exponential entries, so only the certified numeric analyses apply
 * (radius, and the verdict the radius certifies). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include "analysis/impl.h"
#include "analysis/registry.h"
#include "analysis/sweep_impl.h"
#include "numeric/grid.h"
#include "lower/cosim_model.h"
#include "numeric/cosim_ball.h"
#include "numeric/cosim_fast.h"
#include "numeric/cosim_dbl.h"
#include "numeric/cosim_forms.h"
#include "numeric/modes.h"
#include "util/dblstr.h"
#include "recstab/cosim.h"
#include "recstab/radius.h"

/* coefficient of variable v (degree <= 1 checked by the caller) */
static void lin_coeff(fmpq_t q, const fmpq_mpoly_t p, slong v, const rs_scheme_struct *ts)
{
    fmpq_mpoly_t t;
    ulong one = 1;
    fmpq_mpoly_init(t, ts->ctx);
    fmpq_mpoly_get_coeff_vars_ui(t, p, &v, &one, 1, ts->ctx);
    if (fmpq_mpoly_is_fmpq(t, ts->ctx) && !fmpq_mpoly_is_zero(t, ts->ctx)) fmpq_mpoly_get_fmpq(q, t, ts->ctx);
    else fmpq_zero(q);
    fmpq_mpoly_clear(t, ts->ctx);
}

/* every term of degree exactly 1, in the allowed variables [lo, hi) */
static int check_linear(const fmpq_mpoly_t p, slong lo, slong hi, const rs_scheme_struct *ts, const rs_loc_t *loc,
                        const char *what, const char *allowed, rs_error_t err)
{
    slong i, v, len = fmpq_mpoly_length(p, ts->ctx);
    slong *e = flint_malloc(ts->nvars * sizeof(slong));
    int r = RS_OK;
    for (i = 0; i < len && r == RS_OK; i++) {
        slong deg = 0, var = -1;
        fmpq_mpoly_get_term_exp_si(e, p, i, ts->ctx);
        for (v = 0; v < ts->nvars; v++) if (e[v]) { deg += e[v]; var = v; }
        if (deg != 1 || var < lo || var >= hi)
            r = rs_error_set_at(err, RS_ERR_INPUT, loc->file, loc->line, loc->col,
                                "expected %s linear and homogeneous in %s", what, allowed);
    }
    flint_free(e);
    return r;
}

/* W (row = state equation, columns = states then forces) and the macro step at the values */
static int cosim_rows_at(fmpq_mat_t W, fmpq_t h0, const rs_cosim_model_struct *F, const rs_case_struct *c,
                         const rs_cosim_vals_t *vals, rs_error_t err)
{
    const rs_scheme_struct *ts = F->ts;
    slong a, j, q2, row = 0, base = c->nparams, n = F->n, nf = F->nf;
    fmpq_mpoly_t p;
    fmpq_t q;
    int r = RS_OK;
    fmpq_mpoly_init(p, ts->ctx);
    fmpq_init(q);
    for (a = 0; a < 2 && r == RS_OK; a++) {
        for (j = 0; j < F->nstate[a] && r == RS_OK; j++, row++) {
            if (F->second[row]) { fmpq_one(fmpq_mat_entry(W, row, row + 1)); continue; }
            r = rs_cosim_model_form_at(p, F, row, c, vals, err);
            if (r == RS_OK)
                r = check_linear(p, base, base + n + nf, ts, F->loc[row], "a state equation",
                                 "the states (its own; the partner's are coupling inputs) and the coupling forces", err);
            for (q2 = 0; q2 < n + nf && r == RS_OK; q2++) {
                lin_coeff(q, p, base + q2, ts);
                fmpq_set(fmpq_mat_entry(W, row, q2), q);
            }
        }
        /* the macro step */
        if (r == RS_OK) r = rs_cosim_model_form_at(p, F, rs_cosim_model_step(F, a), c, vals, err);
        if (r == RS_OK) {
            const rs_loc_t *l = &c->subs[a].intloc;
            if (!fmpq_mpoly_is_fmpq(p, ts->ctx) || fmpq_mpoly_is_zero(p, ts->ctx))
                r = rs_error_set_at(err, RS_ERR_INPUT, l->file, l->line, l->col,
                                    "expected a positive number as the macro step%s", "");
            else {
                fmpq_mpoly_get_fmpq(q, p, ts->ctx);
                if (a == 1 && !fmpq_equal(q, h0))
                    r = rs_error_set_at(err, RS_ERR_INPUT, l->file, l->line, l->col,
                                        "both subsystems must use the same macro step%s", "");
                fmpq_set(h0, q);
            }
        }
    }
    fmpq_mpoly_clear(p, ts->ctx);
    fmpq_clear(q);
    return r;
}

/* Two subsystems integrated exactly, coupled through u = C z (rs_cosim_from_case in cosim.h),
 * at the values: a subsystem's equations are linear in its own states (-> A_i), in the coupling
 * forces and in the partner's states (-> B_i; each partner state used is one coupling variable,
 * displacement coupling / base-point excitation, with C row e_state; each force one, C row = the
 * coefficients of its expression in the states).  u = (partner states used, in state order; then
 * the forces). */
static int cosim_at(rs_cosim_t cs, const rs_cosim_model_struct *F, const rs_case_struct *c, const rs_cosim_vals_t *vals,
                    rs_error_t err)
{
    const rs_scheme_struct *ts = F->ts;
    slong i, j, n = F->n, nf = F->nf, m = 0, base = c->nparams, *in_var;
    const slong *nstate = F->nstate;
    int r;
    fmpq_mpoly_t p;
    fmpq_t q, h0;
    fmpq_mat_t W;
    fmpq_mpoly_init(p, ts->ctx);
    fmpq_init(q);
    fmpq_init(h0);
    fmpq_mat_init(W, n, n + nf);
    in_var = flint_malloc((n + nf + 1) * sizeof(slong));
    r = cosim_rows_at(W, h0, F, c, vals, err);
    /* the coupling variables: W column of each (a partner state used, then every force) */
    if (r == RS_OK) {
        for (j = 0; j < n; j++) {
            int own = j < nstate[0] ? 0 : 1, used = 0;
            slong row;
            for (row = 0; row < n; row++)
                if ((row < nstate[0] ? 0 : 1) != own && !fmpq_is_zero(fmpq_mat_entry(W, row, j))) used = 1;
            if (used) in_var[m++] = j;
        }
        for (i = 0; i < nf; i++) in_var[m++] = n + i;
    }
    if (r == RS_OK) {
        slong mm = m > 0 ? m : 1;   /* uncoupled: one zero coupling variable */
        rs_cosim_set_dims_m(cs, nstate[0], nstate[1], mm);
        for (j = 0; j < n; j++) {
            slong ja = j < nstate[0] ? 0 : 1, jl = j - (ja ? nstate[0] : 0), k;
            fmpq_mat_struct *A = ja == 0 ? cs->A1 : cs->A2, *B = ja == 0 ? cs->B1 : cs->B2;
            for (k = 0; k < nstate[ja]; k++)
                fmpq_set(fmpq_mat_entry(A, jl, k), fmpq_mat_entry(W, j, (ja ? nstate[0] : 0) + k));
            for (k = 0; k < m; k++) {
                slong v = in_var[k];
                /* own states are in A, not inputs */
                if (v < n && (v < nstate[0] ? 0 : 1) == ja) continue;
                fmpq_set(fmpq_mat_entry(B, jl, k), fmpq_mat_entry(W, j, v));
            }
        }
        for (i = 0; i < m && r == RS_OK; i++) {
            slong v = in_var[i];
            if (v < n) {
                fmpq_one(fmpq_mat_entry(cs->C, i, v));
                continue;
            }
            r = rs_cosim_model_form_at(p, F, rs_cosim_model_force(F, v - n), c, vals, err);
            if (r == RS_OK) r = check_linear(p, base, base + n, ts, F->loc[rs_cosim_model_force(F, v - n)], "a coupling force",
                                             "the states", err);
            for (j = 0; j < n && r == RS_OK; j++) {
                lin_coeff(q, p, base + j, ts);
                fmpq_set(fmpq_mat_entry(cs->C, i, j), q);
            }
        }
    }
    if (r == RS_OK) {
        fmpq_set(cs->H, h0);
        cs->method = strcmp(c->couple, "implicit") == 0 ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT;
        cs->order = c->couple_order;
        cs->ext = c->couple_ext == 'D' ? RS_COSIM_EXT_D : c->couple_ext == 'I' ? RS_COSIM_EXT_I : RS_COSIM_EXT_NONE;
        if (c->couple_alpha != NULL) fmpq_set(cs->alpha_T, c->couple_alpha);
        r = rs_cosim_check(cs, err);
    }
    flint_free(in_var);
    fmpq_mat_clear(W);
    fmpq_mpoly_clear(p, ts->ctx);
    fmpq_clear(q);
    fmpq_clear(h0);
    return r;
}

/* The model at the values in one call (the forms built and cleared here;
 * a run builds them once: rs_model_lower, rs_model_cosim). */
static int cosim_build(rs_cosim_t cs, const rs_case_struct *c, const rs_cosim_vals_t *vals, rs_error_t err)
{
    rs_cosim_model_struct F;
    int r = rs_cosim_model_init(&F, c, err);
    if (r == RS_OK) r = cosim_at(cs, &F, c, vals, err);
    rs_cosim_model_clear(&F);
    return r;
}

int rs_cosim_from_case(rs_cosim_t cs, const rs_case_t c, rs_error_t err)
{
    rs_cosim_vals_t vals;
    int r;
    rs_cosim_vals_make(&vals, c, NULL, NULL, 0);
    r = cosim_build(cs, c, &vals, err);
    flint_free(vals.v);
    return r;
}

/* The co-simulation of the run's model at the case's set values (the forms
 * the run lowered once; rs_cosim_from_case builds its own). */
int rs_run_cosim(rs_cosim_t cs, rs_run_t *run)
{
    return rs_run_cosim_at(cs, run, NULL, NULL, 0);
}

int rs_run_cosim_at(rs_cosim_t cs, rs_run_t *run, const char *const *names, const fmpq *values, slong n)
{
    const rs_cosim_model_struct *F = rs_model_cosim(run->m, run->err);
    rs_cosim_vals_t vals;
    int r;
    if (F == NULL) return run->err->code;
    rs_cosim_vals_make(&vals, run->c, names, values, n);
    r = cosim_at(cs, F, run->c, &vals, run->err);
    flint_free(vals.v);
    return r;
}

/* ---- sweep and map: the model kind "exact integration" of the sweep engine ------------------ */

/* sweep NAME from A to B steps K [log] [of radius|stability] and
 * map NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]: the certified
 * radius at every grid point, through the engine of every sweep and map
 * (sweep_engine.c: shards, --max-points, codes, columns, summary).  With no
 * exact side, a radius interval that contains 1 is RS_SWEEP_UNDECIDED. */
typedef struct {
    rs_run_t *run;
    const rs_sweep_request_t *R;
    const fmpq *x[2];                 /* the axis values: x[0][i] (and x[1][j] of a map) */
    const rs_cosim_model_struct *F;   /* the linear forms (the run's model) */
    rs_cosim_nforms_struct *NF;       /* their numeric forms (cosim_forms.h; NULL: not applicable) */
    /* with NF: subsystem s's block of the one-step map (rs_cosim_dbl_sub),
     * once per value of the one axis its rows depend on (preax[s]; -1: on
     * none, one block), preok[s][v] where it was computed; pre[s] NULL:
     * every point computes its own */
    double *pre[2];
    unsigned char *preok[2];
    slong preax[2], prelen[2];
    /* sweep ... of modes: per point the step h, the nref references
     * (refval[idx * nref + k]) and the certified eigenvalues (eig[idx]) */
    slong npoints, nref;
    fmpq *hval, *refval;
    json_t **eig;
} cosim_map_t;

/* the co-simulation at grid point idx (a sweep's index; a map's j*K1 + i) */
static int cosim_map_build(rs_cosim_t cs, const cosim_map_t *M, slong idx, rs_error_t err)
{
    slong K1 = M->R->naxes == 2 ? M->R->axis[0].count : WORD_MAX;
    const char *names[2];
    fmpq vv[2];
    rs_cosim_vals_t vals;
    int r;
    names[0] = M->R->axis[0].name;
    names[1] = M->R->axis[1].name;
    vv[0] = M->x[0][idx % K1];
    if (M->R->naxes == 2) vv[1] = M->x[1][idx / K1];
    rs_cosim_vals_make(&vals, M->run->c, names, vv, M->R->naxes);
    r = cosim_at(cs, M->F, M->run->c, &vals, err);
    flint_free(vals.v);
    return r;
}

/* the certified radius (6 digits) at the point, or its best certified
 * enclosure when the eigenvalues cannot be isolated */
static int cosim_point_radius(rs_radius_t rr, const rs_cosim_t cs, slong max_prec, rs_error_t err)
{
    int r = rs_cosim_radius(rr, cs, 6, max_prec, err);
    if (r == RS_ERR_UNDECIDED && arb_is_finite(rr->lower) && arb_is_finite(rr->upper)) r = RS_OK;
    return r;
}

/* the radius a point decided by a fast route is checked against (check
 * set): van der Hoeven-Mourrain on the Arb map (rs_cosim_check_radius),
 * where it certifies; else, and for the cells of an undecided point, the
 * full certified radius */
static int cosim_check_radius(rs_radius_t rr, const rs_cosim_t cs, int check, slong max_prec, rs_error_t err)
{
    if (check) {
        rs_error_t e;
        int r;
        rs_error_init(e);
        r = rs_cosim_check_radius(rr, cs, 64, e);
        rs_error_clear(e);
        if (r == RS_OK) return r;
    }
    return cosim_point_radius(rr, cs, max_prec, err);
}

/* the verdict (RS_STATUS_* or RS_SWEEP_UNDECIDED) from a certified radius */
static int radius_verdict(const rs_radius_t rr)
{
    arb_t one;
    int v;
    arb_init(one);
    arb_one(one);
    v = arb_lt(rr->upper, one) ? RS_STATUS_STABLE : arb_gt(rr->lower, one) ? RS_STATUS_UNSTABLE : RS_SWEEP_UNDECIDED;
    arb_clear(one);
    return v;
}

/* The fast verdict of `of stability` (issue 14 part 3): a Stein certificate
 * for the point's one-step map at 64 bits (rs_cosim_ball_stein, its linear
 * system in double), no eigenvalues; RS_SWEEP_UNDECIDED when it cannot tell
 * (near |lambda| = 1: the certified radius decides then). */
static int cosim_fast_verdict(const rs_cosim_t cs)
{
    slong d = rs_cosim_transition_dim(cs);
    arb_mat_t T;
    rs_error_t e;
    int v = RS_SWEEP_UNDECIDED, st;
    arb_mat_init(T, d, d);
    rs_error_init(e);
    if (rs_cosim_transition(T, cs, 64, e) == RS_OK) {
        st = rs_cosim_ball_stein(T, 64);
        v = st == RS_COSIM_BALL_STABLE ? RS_STATUS_STABLE : st == RS_COSIM_BALL_UNSTABLE ? RS_STATUS_UNSTABLE
                                                                                       : RS_SWEEP_UNDECIDED;
    }
    arb_mat_clear(T);
    return v;
}

/* the verdict and the radius cells (bounds rounded outward, 17 digits);
 * the estimate's certified digits are those of rho, or with bounds set
 * (the interval-double radius: lower and upper are doubles, rho their
 * 64-bit union ball, a little wider) those of [lower, upper] itself */
/* an exact double (the interval-double radius's bounds): 1 and *d */
static int exact_dbl(double *d, const arb_t x)
{
    const arf_struct *m = arb_midref(x);
    if (!mag_is_zero(arb_radref(x)) || arf_bits(m) > 53 || arf_cmpabs_2exp_si(m, 1000) >= 0
        || arf_cmpabs_2exp_si(m, -1000) <= 0)
        return 0;
    *d = arf_get_d(m, ARF_RND_NEAR);
    return 1;
}

static void radius_cells_of(rs_sweep_row_t *row, const rs_radius_t rr, int bounds)
{
    char a[RS_DBLSTR_SIZE], b[RS_DBLSTR_SIZE], c[RS_DBLSTR_SIZE], *rho, *lo, *hi;
    double l, u;
    row->d.verdict = radius_verdict(rr);
    row->d.level = RS_LEVEL_CERTIFIED;
    /* doubles: the three cells from two conversions (util/dblstr.h, the
     * same strings as below) */
    if (bounds && exact_dbl(&l, rr->lower) && exact_dbl(&u, rr->upper) && rs_dblstr_bounds(a, b, c, l, u, 17) == 0) {
        snprintf(row->cells, sizeof row->cells, "%s,%s,%s", a, b, c);
        return;
    }
    rho = bounds ? rs_radius_interval_str(arb_midref(rr->lower), arb_midref(rr->upper), 17)
                 : rs_radius_arb_str(rr->rho, 17);
    lo = rs_radius_str_lower(rr->lower, 17);
    hi = rs_radius_str_upper(rr->upper, 17);
    snprintf(row->cells, sizeof row->cells, "%s,%s,%s", rho[0] == '[' ? "" : rho, lo, hi);
    flint_free(rho);
    flint_free(lo);
    flint_free(hi);
}

static void radius_cells(rs_sweep_row_t *row, const rs_radius_t rr)
{
    radius_cells_of(row, rr, 0);
}

#define COSIM_PRE_MAX_DOUBLES (1L << 20)   /* 8 MB a subsystem */

/* M->pre: a subsystem whose rows depend on no axis, or (a map) on one axis
 * only, gets its exponential and gains once per value of that axis: the
 * doubles every point of that value would compute (rs_cosim_nforms_at
 * gives its A_s and B_s the same doubles along the other axis) */
static void cosim_pre_build(cosim_map_t *M)
{
    const rs_sweep_request_t *R = M->R;
    rs_cosim_dbl_t d;
    int s;
    rs_cosim_dbl_init(d);
    for (s = 0; s < 2; s++) {
        unsigned mask = rs_cosim_nforms_sub_axes(M->NF, s);
        slong ax, cnt = 1, v, len = 0;
        fmpq vv[2];
        if (mask == 0) ax = -1;
        else if (R->naxes == 2 && (mask == 1u || mask == 2u)) {
            ax = mask == 1u ? 0 : 1;
            cnt = R->axis[ax].count;
        } else
            continue;
        vv[0] = M->x[0][0];
        if (R->naxes == 2) vv[1] = M->x[1][0];
        for (v = 0; v < cnt && !rs_budget_exceeded(); v++) {
            int ok;
            if (ax >= 0) vv[ax] = M->x[ax][v];
            ok = rs_cosim_nforms_at(d, M->NF, vv);
            if (M->pre[s] == NULL) {
                len = rs_cosim_dbl_sub_len(d, s);
                if (len < 1 || cnt * len > COSIM_PRE_MAX_DOUBLES) break;
                M->pre[s] = flint_malloc(cnt * len * sizeof(double));
                M->preok[s] = flint_calloc(cnt, 1);
                M->preax[s] = ax;
                M->prelen[s] = len;
            }
            M->preok[s][v] = ok && rs_cosim_dbl_sub(M->pre[s] + v * len, d, s);
        }
    }
    rs_cosim_dbl_clear(d);
}

static void cosim_pre_free(cosim_map_t *M)
{
    int s;
    for (s = 0; s < 2; s++) {
        flint_free(M->pre[s]);
        flint_free(M->preok[s]);
        M->pre[s] = NULL;
        M->preok[s] = NULL;
    }
}

/* subsystem s's precomputed block at grid point idx, or NULL */
static const double *cosim_pre_at(const cosim_map_t *M, int s, slong idx)
{
    slong K1 = M->R->naxes == 2 ? M->R->axis[0].count : WORD_MAX, v;
    if (M->pre[s] == NULL) return NULL;
    v = M->preax[s] < 0 ? 0 : M->preax[s] == 0 ? idx % K1 : idx / K1;
    return M->preok[s][v] ? M->pre[s] + v * M->prelen[s] : NULL;
}

/* the interval-double certified radius at grid point idx from the numeric
 * forms; 1 when it decides the verdict (an interval excluding 1) */
static int cosim_dbl_point(rs_radius_t rf, const cosim_map_t *M, slong idx)
{
    slong K1 = M->R->naxes == 2 ? M->R->axis[0].count : WORD_MAX;
    fmpq vv[2];
    rs_cosim_dbl_t d;
    const double *pre[2];
    int ok;
    vv[0] = M->x[0][idx % K1];
    if (M->R->naxes == 2) vv[1] = M->x[1][idx / K1];
    rs_cosim_dbl_init(d);
    pre[0] = cosim_pre_at(M, 0, idx);
    pre[1] = cosim_pre_at(M, 1, idx);
    ok = rs_cosim_nforms_at(d, M->NF, vv) && rs_cosim_dbl_radius_pre(rf, d, pre) == RS_OK
         && radius_verdict(rf) != RS_SWEEP_UNDECIDED;
    rs_cosim_dbl_clear(d);
    return ok;
}

/* sweep ... of modes at point idx: the certified eigenvalues of the
 * one-step map (15 digits) into M->eig[idx], and the modes columns as the
 * sweeps of modes of the equations report them (rs_sweep_row_modes).
 * Only with every eigenvalue isolated (RS_OK): else the cells stay empty. */
static void cosim_point_modes(rs_sweep_row_t *row, const cosim_map_t *M, slong idx, const rs_radius_t rr)
{
    slong i;
    json_t *ev = json_array();
    for (i = 0; i < rr->nroots; i++) json_array_append_new(ev, rs_json_acb(rr->roots + i, 15));
    M->eig[idx] = ev;
    rs_sweep_row_modes(row, rr, M->hval + idx, M->refval + idx * M->nref, M->nref);
}

#define COSIM_CROSSCHECK_EVERY 64   /* fast verdicts re-derived from the certified radius */

/* the model's callback: the verdict the certified radius gives (6 digits),
 * the radius cells from its balls (bounds rounded outward, 17 digits); for
 * `of stability` the fast Stein verdict first (no radius cells), every 64th
 * such point cross-checked against the radius (exit 3 on disagreement) */
static void cosim_map_point(rs_sweep_row_t *row, slong idx, void *model, rs_error_t err)
{
    const cosim_map_t *M = model;
    rs_cosim_t cs;
    rs_radius_t rr, rf;
    slong max_prec = M->run->opt->max_prec < 1024 ? M->run->opt->max_prec : 1024;
    int fast = RS_SWEEP_UNDECIDED, have_fast = 0, from_dbl = 0, modes = M->R->of == RS_SWEEP_OF_MODES;
    slong c;
    memset(row, 0, sizeof *row);
    row->d.verdict = -1;
    row->inside = row->on = row->outside = -1;
    rs_radius_init(rf);
    for (c = 0; c < 3 * RS_SWEEP_MAX_REFS; c++) row->mode_lo[c] = row->mode_hi[c] = NAN;
    /* `of radius`: the interval-double radius from the numeric forms first
     * (cosim_dbl.h, no exact model built); the exact model only where it
     * cannot decide and at every 64th point (the cross-check below) */
    if (M->NF != NULL && M->R->of == RS_SWEEP_OF_RADIUS) {
        have_fast = from_dbl = cosim_dbl_point(rf, M, idx);
        if (have_fast && idx % COSIM_CROSSCHECK_EVERY != 0) {
            radius_cells_of(row, rf, 1);
            rs_radius_clear(rf);
            return;
        }
    }
    rs_cosim_init(cs, 1, 1);
    rs_radius_init(rr);
    row->d.status = cosim_map_build(cs, M, idx, err);
    if (row->d.status == RS_OK && M->R->of == RS_SWEEP_OF_STABILITY) {
        fast = cosim_fast_verdict(cs);
        if (fast != RS_SWEEP_UNDECIDED) {
            row->d.verdict = fast;
            row->d.level = RS_LEVEL_CERTIFIED;
            snprintf(row->cells, sizeof row->cells, ",,");
        }
    }
    /* `of radius`: the fast certified radius (cosim_fast.h) first, the full
     * one where its certificate fails and at every 64th point to cross-check */
    if (row->d.status == RS_OK && M->R->of != RS_SWEEP_OF_STABILITY && !have_fast) {
        rs_error_t e;
        rs_error_init(e);
        /* an interval containing 1 goes the full route, as before */
        if (rs_cosim_fast_radius(rf, cs, 64, e) == RS_OK && (fast = radius_verdict(rf)) != RS_SWEEP_UNDECIDED)
            have_fast = 1;
        else
            fast = RS_SWEEP_UNDECIDED;
        rs_error_clear(e);
    }
    /* RS_ERR_UNDECIDED (eigenvalues not isolated, e.g. two equal subsystems'
     * repeated eigenvalues): the enclosure certified so far still decides
     * when it excludes 1, else the point is undecided -- not undefined */
    /* `of modes`: the full certified eigenvalues at every point (15 digits),
     * checked against the fast radius as above */
    if (row->d.status == RS_OK && modes) {
        rs_error_t e;
        rs_error_init(e);
        if (rs_cosim_radius(rr, cs, 15, max_prec, e) == RS_OK) {
            cosim_point_modes(row, M, idx, rr);
            if (have_fast && (arb_lt(rf->upper, rr->lower) || arb_gt(rf->lower, rr->upper)))
                row->d.status = rs_error_set(err, RS_ERR_INCONSISTENT,
                                             "the fast certified radius and the full certified radius disagree");
            else if (!have_fast)
                radius_cells(row, rr);
            rs_radius_clear(rr);
            rs_radius_init(rr);
        } else if (!have_fast && cosim_point_radius(rr, cs, max_prec, err) == RS_OK)
            radius_cells(row, rr);
        rs_error_clear(e);
    }
    if (row->d.status == RS_OK && !modes
        && (have_fast ? idx % COSIM_CROSSCHECK_EVERY == 0
                      : fast == RS_SWEEP_UNDECIDED || idx % COSIM_CROSSCHECK_EVERY == 0)
        && cosim_check_radius(rr, cs, have_fast || fast != RS_SWEEP_UNDECIDED, max_prec, err) == RS_OK) {
        int v = radius_verdict(rr);
        if (have_fast) {
            /* both certified: the enclosures must meet, the verdicts agree */
            if (arb_lt(rf->upper, rr->lower) || arb_gt(rf->lower, rr->upper)
                || (v != RS_SWEEP_UNDECIDED && fast != RS_SWEEP_UNDECIDED && v != fast))
                row->d.status = rs_error_set(err, RS_ERR_INCONSISTENT,
                                             "the fast certified radius and the full certified radius disagree");
        } else if (fast != RS_SWEEP_UNDECIDED) {
            if (v != RS_SWEEP_UNDECIDED && v != fast)
                row->d.status = rs_error_set(err, RS_ERR_INCONSISTENT,
                                             "the Stein certificate (%s) and the certified radius (%s) disagree",
                                             rs_status_name((rs_status_t) fast), rs_status_name((rs_status_t) v));
        } else
            radius_cells(row, rr);
    }
    if (row->d.status == RS_OK && have_fast) radius_cells_of(row, rf, from_dbl);
    rs_radius_clear(rf);
    rs_radius_clear(rr);
    rs_cosim_clear(cs);
}

/* M over the axis values x (x[1] NULL for a sweep): the run's forms, then
 * the case's own errors (a parameter still symbolic, an equation not
 * linear) at their place, before any point runs */
static int cosim_grid_init(cosim_map_t *M, rs_sweep_model_t *m, rs_run_t *run, const rs_sweep_request_t *R,
                           const fmpq *x0, const fmpq *x1)
{
    int r;
    M->run = run;
    M->R = R;
    M->x[0] = x0;
    M->x[1] = x1;
    M->F = rs_model_cosim(run->m, run->err);
    M->NF = NULL;
    M->pre[0] = M->pre[1] = NULL;
    M->preok[0] = M->preok[1] = NULL;
    M->npoints = M->nref = 0;
    M->hval = M->refval = NULL;
    M->eig = NULL;
    r = M->F != NULL ? RS_OK : run->err->code;
    if (r == RS_OK) {
        rs_cosim_t cs;
        rs_cosim_init(cs, 1, 1);
        r = cosim_map_build(cs, M, 0, run->err);
        rs_cosim_clear(cs);
    }
    if (r == RS_OK && R->of == RS_SWEEP_OF_RADIUS) {
        const char *names[2];
        names[0] = R->axis[0].name;
        names[1] = R->naxes == 2 ? R->axis[1].name : NULL;
        M->NF = rs_cosim_nforms_new(M->F, run->c, names, R->naxes);
        if (M->NF != NULL) cosim_pre_build(M);
    }
    m->point = cosim_map_point;
    m->model = M;
    m->serial = 0;       /* a point only reads the forms (their context included) */
    return r;
}

int rs_an_cosim_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R)
{
    const rs_sweep_axis_t *X = R->axis;
    cosim_map_t M;
    rs_sweep_model_t m;
    fmpq *xs[2];
    double t0 = rs_sweep_now();
    int r = rs_sweep_estimate_map(run, q, (double) X[0].count * (double) X[1].count);
    if (r != RS_OK) return r;
    xs[0] = rs_grid_axis(X[0].from, X[0].to, X[0].count);
    xs[1] = rs_grid_axis(X[1].from, X[1].to, X[1].count);
    r = cosim_grid_init(&M, &m, run, R, xs[0], xs[1]);
    if (r == RS_OK) r = rs_sweep_map_finish(run, q, R, &m, (const fmpq *const *) xs, t0, NULL, NULL);
    rs_cosim_nforms_free(M.NF);
    cosim_pre_free(&M);
    _fmpq_vec_clear(xs[0], X[0].count);
    _fmpq_vec_clear(xs[1], X[1].count);
    return r;
}

static int cosim_eval_at(fmpq_t out, const char **end, rs_run_t *run, const rs_request_t *q,
                         const rs_cosim_model_struct *F, const char *text, const char *name, const fmpq *vals,
                         slong npoints, fmpq *dst, slong stride);

/* the options of `of modes` (h=EXPR reference=EXPR[,EXPR]; keys checked by
 * the request parser) at every point: h defaults to the macro step H */
static int cosim_modes_opts(cosim_map_t *M, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                            slong npoints)
{
    const char *t = R->opts;
    slong i;
    int r = RS_OK, have_h = 0;
    fmpq_t dummy;
    fmpq_init(dummy);
    M->npoints = npoints;
    M->hval = _fmpq_vec_init(npoints);
    M->eig = calloc((size_t) npoints, sizeof(json_t *));
    while (r == RS_OK && t != NULL && *t) {
        const char *end = t;
        while (*t == ' ' || *t == '\t') t++;
        if (*t == '\0') break;
        if (strncmp(t, "h=", 2) == 0) {
            have_h = 1;
            r = cosim_eval_at(dummy, &end, run, q, M->F, t + 2, R->axis[0].name, M->x[0], npoints, M->hval, 1);
            for (i = 0; i < npoints && r == RS_OK; i++)
                if (fmpq_sgn(M->hval + i) <= 0)
                    r = rs_req_error(run, q, t + 2, RS_ERR_INPUT,
                                     "expected a time step h > 0 at every point, found '%s'", t + 2);
        } else if (strncmp(t, "reference=", 10) == 0) {
            const char *u = t + 10;
            for (;;) {
                fmpq *nr;
                slong k, p;
                if (M->nref >= RS_SWEEP_MAX_REFS)
                    return rs_req_error(run, q, u, RS_ERR_LIMIT, "at most 4 references, found more at '%s'", u);
                nr = _fmpq_vec_init(npoints * (M->nref + 1));
                for (p = 0; p < npoints; p++)
                    for (k = 0; k < M->nref; k++) fmpq_set(nr + p * (M->nref + 1) + k, M->refval + p * M->nref + k);
                r = cosim_eval_at(dummy, &end, run, q, M->F, u, R->axis[0].name, M->x[0], npoints, nr + M->nref,
                                  M->nref + 1);
                if (M->refval != NULL) _fmpq_vec_clear(M->refval, npoints * M->nref);
                M->refval = nr;
                M->nref++;
                if (r != RS_OK || *end != ',') break;
                u = end + 1;
            }
        } else
            r = rs_req_error(run, q, t, RS_ERR_INPUT, "expected an option (h=, reference=), found '%s'", t);
        if (r != RS_OK) break;
        /* the expression parser stops after trailing blanks */
        if (end > t && (end[-1] == ' ' || end[-1] == '\t')) end--;
        if (*end != '\0' && *end != ' ' && *end != '\t')
            r = rs_req_error(run, q, end, RS_ERR_INPUT, "expected a space or the end after the value, found '%s'", end);
        t = end;
    }
    if (r == RS_OK && !have_h) {
        /* the macro step of the model at each point */
        for (i = 0; i < npoints && r == RS_OK; i++) {
            rs_cosim_t cs;
            rs_cosim_init(cs, 1, 1);
            r = cosim_map_build(cs, M, i, run->err);
            if (r == RS_OK) fmpq_set(M->hval + i, cs->H);
            rs_cosim_clear(cs);
        }
    }
    fmpq_clear(dummy);
    return r;
}

static void cosim_modes_free(cosim_map_t *M)
{
    slong i;
    if (M->hval != NULL) _fmpq_vec_clear(M->hval, M->npoints);
    if (M->refval != NULL) _fmpq_vec_clear(M->refval, M->npoints * M->nref);
    if (M->eig != NULL) {
        for (i = 0; i < M->npoints; i++)
            if (M->eig[i] != NULL) json_decref(M->eig[i]);
        free(M->eig);
    }
    M->hval = M->refval = NULL;
    M->eig = NULL;
}

int rs_cosim_sweep_model_new(rs_sweep_model_t *m, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                             const fmpq *vals, slong npoints)
{
    cosim_map_t *M = flint_malloc(sizeof *M);
    int r = cosim_grid_init(M, m, run, R, vals, NULL);
    if (r == RS_OK && R->of == RS_SWEEP_OF_MODES) r = cosim_modes_opts(M, run, q, R, npoints);
    if (r != RS_OK) {
        rs_cosim_nforms_free(M->NF);
        cosim_pre_free(M);
        cosim_modes_free(M);
        flint_free(M);
        m->model = NULL;
    }
    return r;
}

slong rs_cosim_sweep_nref(const rs_sweep_model_t *m)
{
    return m->model == NULL ? 0 : ((const cosim_map_t *) m->model)->nref;
}

json_t *rs_cosim_sweep_eigenvalues(const rs_sweep_model_t *m, slong lo, slong hi)
{
    const cosim_map_t *M = m->model;
    json_t *a = json_array();
    slong i;
    for (i = lo; i < hi; i++)
        json_array_append_new(a, M->eig != NULL && M->eig[i] != NULL ? json_incref(M->eig[i]) : json_null());
    return a;
}

void rs_cosim_sweep_model_free(rs_sweep_model_t *m)
{
    if (m->model != NULL) {
        rs_cosim_nforms_free(((cosim_map_t *) m->model)->NF);
        cosim_pre_free(m->model);
        cosim_modes_free(m->model);
    }
    flint_free(m->model);
    m->model = NULL;
}

/* ---- modes: the eigenvalues of the one-step map as continuous modes ----------------------- */

/* A request expression (h=, reference=) at the case's set values, through
 * the forms' context (its first variables are the case's parameters). */
static int cosim_eval_number(arb_t out, rs_run_t *run, const rs_request_t *q, const rs_cosim_model_struct *F,
                             const char *text, slong prec)
{
    const fmpq_mpoly_ctx_struct *ctx = F->ts->ctx;
    rs_src_t src;
    rs_expr_t *e = NULL;
    fmpq_mpoly_t num, den;
    rs_cosim_vals_t vals;
    size_t pos = (size_t) (text - q->text);
    slong k;
    int r;
    rs_req_src(&src, q);
    r = rs_expr_parse(&e, &src, &pos, run->err);
    if (r != RS_OK) return r;
    fmpq_mpoly_init(num, ctx);
    fmpq_mpoly_init(den, ctx);
    r = rs_scheme_eval_poly(num, den, F->ts, F->tc, e, 0, run->err);
    rs_expr_free(e);
    rs_cosim_vals_make(&vals, run->c, NULL, NULL, 0);
    for (k = 0; k < vals.n && r == RS_OK; k++) {
        slong v = rs_case_param_index(F->tc, vals.v[k].name);
        fmpq_mpoly_evaluate_one_fmpq(num, num, v, vals.v[k].value, ctx);
        fmpq_mpoly_evaluate_one_fmpq(den, den, v, vals.v[k].value, ctx);
    }
    flint_free(vals.v);
    if (r == RS_OK && (!fmpq_mpoly_is_fmpq(num, ctx) || !fmpq_mpoly_is_fmpq(den, ctx) || fmpq_mpoly_is_zero(den, ctx)))
        r = rs_req_error(run, q, text, RS_ERR_INPUT, "expected a value of set parameters, found '%s'", text);
    if (r == RS_OK) {
        fmpq_t a, b;
        fmpq_init(a);
        fmpq_init(b);
        fmpq_mpoly_get_fmpq(a, num, ctx);
        fmpq_mpoly_get_fmpq(b, den, ctx);
        fmpq_div(a, a, b);
        arb_set_fmpq(out, a, prec);
        fmpq_clear(a);
        fmpq_clear(b);
    }
    fmpq_mpoly_clear(num, ctx);
    fmpq_mpoly_clear(den, ctx);
    return r;
}

/* modes [h=EXPR] [reference=EXPR[,EXPR]]: the modes element of the
 * equations (an_modes.c) over the certified eigenvalues of the one-step map
 * (30 digits); h defaults to the macro step H, the step of that map */
int rs_an_cosim_modes(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_optval_t *o_h = rs_an_opt(req, "h"), *o_ref = rs_an_opt(req, "reference");
    const rs_cosim_model_struct *F = rs_model_cosim(run->m, run->err);
    rs_cosim_vals_t vals;
    rs_cosim_t cs;
    rs_radius_t rr;
    arb_t h, *refs = NULL;
    slong nref = 0, i, prec = 128, digits = 15;
    int r;
    json_t *o;
    if (F == NULL) return run->err->code;
    rs_cosim_init(cs, 1, 1);
    rs_radius_init(rr);
    arb_init(h);
    rs_cosim_vals_make(&vals, run->c, NULL, NULL, 0);
    r = cosim_at(cs, F, run->c, &vals, run->err);
    flint_free(vals.v);
    if (r == RS_OK) {
        arb_set_fmpq(h, cs->H, prec);
        if (o_h->val != NULL) {
            r = cosim_eval_number(h, run, q, F, o_h->val, prec);
            /* ln(lambda)/h: a step must be positive */
            if (r == RS_OK && !arb_is_positive(h))
                r = rs_req_error(run, q, o_h->val, RS_ERR_INPUT, "expected a time step h > 0, found '%s'", o_h->val);
        }
    }
    if (r == RS_OK && o_ref->nlist > 0) {
        refs = calloc((size_t) o_ref->nlist, sizeof(arb_t));
        for (i = 0; i < o_ref->nlist && r == RS_OK; i++) {
            arb_init(refs[nref]);
            r = cosim_eval_number(refs[nref], run, q, F, o_ref->list[i], prec);
            nref++;
        }
    }
    if (r == RS_OK) {
        r = rs_cosim_radius(rr, cs, 30, run->opt->max_prec, run->err);
        if (r != RS_OK) r = rs_req_relocate(run, q, r, "modes");
    }
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("modes"));
        json_object_set_new(o, "method", json_string("exact subsystem integration (matrix exponentials, Arb), "
                                                     "certified eigenvalues of the one-step map"));
        rs_an_modes_json(o, rr, h, refs, nref, prec, digits);
        json_object_set_new(o, "decided_by", json_string("certified"));
        json_object_set_new(o, "substituted", rs_json_sets(run->c));
        json_array_append_new(run->results, o);
    }
    for (i = 0; i < nref; i++) arb_clear(refs[i]);
    free(refs);
    arb_clear(h);
    rs_radius_clear(rr);
    rs_cosim_clear(cs);
    return r;
}

/* A request expression (sweep ... of modes: h=, reference=) at every point
 * of the sweep: the case's set values and NAME = vals[i] substituted through
 * the forms' context; the value into dst[i * stride]; *end after it. */
static int cosim_eval_at(fmpq_t out, const char **end, rs_run_t *run, const rs_request_t *q,
                         const rs_cosim_model_struct *F, const char *text, const char *name, const fmpq *vals,
                         slong npoints, fmpq *dst, slong stride)
{
    const fmpq_mpoly_ctx_struct *ctx = F->ts->ctx;
    rs_src_t src;
    rs_expr_t *e = NULL;
    fmpq_mpoly_t num, den, a, b;
    size_t pos = (size_t) (text - q->text);
    slong i, k;
    int r;
    rs_req_src(&src, q);
    r = rs_expr_parse(&e, &src, &pos, run->err);
    if (r != RS_OK) return r;
    *end = q->text + pos;
    fmpq_mpoly_init(num, ctx);
    fmpq_mpoly_init(den, ctx);
    fmpq_mpoly_init(a, ctx);
    fmpq_mpoly_init(b, ctx);
    r = rs_scheme_eval_poly(num, den, F->ts, F->tc, e, 0, run->err);
    rs_expr_free(e);
    for (i = 0; i < npoints && r == RS_OK; i++) {
        rs_cosim_vals_t vv;
        rs_cosim_vals_make(&vv, run->c, &name, vals + i, 1);
        fmpq_mpoly_set(a, num, ctx);
        fmpq_mpoly_set(b, den, ctx);
        for (k = 0; k < vv.n; k++) {
            slong v = rs_case_param_index(F->tc, vv.v[k].name);
            fmpq_mpoly_evaluate_one_fmpq(a, a, v, vv.v[k].value, ctx);
            fmpq_mpoly_evaluate_one_fmpq(b, b, v, vv.v[k].value, ctx);
        }
        flint_free(vv.v);
        if (!fmpq_mpoly_is_fmpq(a, ctx) || !fmpq_mpoly_is_fmpq(b, ctx) || fmpq_mpoly_is_zero(b, ctx))
            r = rs_req_error(run, q, text, RS_ERR_INPUT,
                             "expected a value of set parameters and the swept one, found '%s'", text);
        else {
            fmpq_t bb;
            fmpq_init(bb);
            fmpq_mpoly_get_fmpq(out, a, ctx);
            fmpq_mpoly_get_fmpq(bb, b, ctx);
            fmpq_div(dst + i * stride, out, bb);
            fmpq_clear(bb);
        }
    }
    fmpq_mpoly_clear(num, ctx);
    fmpq_mpoly_clear(den, ctx);
    fmpq_mpoly_clear(a, ctx);
    fmpq_mpoly_clear(b, ctx);
    return r;
}
