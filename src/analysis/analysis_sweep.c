/* analysis_sweep.c -- the sweep analysis of the equations, certified per
 * point, and the table entries of sweep and map:
 *
 *   sweep NAME from A to B steps K [log] [of radius|modes|stability] [at NAME=VALUE, ...]
 *         [h=EXPR reference=EXPR[,EXPR]]
 *
 * The request is parsed by sweep_request.c, the points computed by the
 * engine (sweep_engine.c) with the model of the equations (sweep_poly.c);
 * here: the sweep's columns, table and JSON element.  See README "Sweeps and
 * maps" for the formats. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpq_vec.h>
#include "analysis/sweep_impl.h"
#include "analysis/registry.h"
#include "numeric/grid.h"
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"
#include "analysis/an_qd.h"

/* index,NAME,NAME_exact, then the columns of `of` (nref references for modes) */
static json_t *sweep_columns(const char *name, int of, slong nref)
{
    static const char *const cst[] = {"verdict", "code", "inside", "on", "outside", "decided_by"};
    static const char *const crad[] = {"radius", "radius_lower", "radius_upper", "verdict", "code", "decided_by"};
    json_t *cols = json_array();
    char col[200];
    slong k;
    json_array_append_new(cols, json_string("index"));
    json_array_append_new(cols, json_string(name));
    snprintf(col, sizeof col, "%s_exact", name);
    json_array_append_new(cols, json_string(col));
    for (k = 0; k < 6; k++) json_array_append_new(cols, json_string(of == RS_SWEEP_OF_STABILITY ? cst[k] : crad[k]));
    for (k = 0; of == RS_SWEEP_OF_MODES && k < nref; k++) {
        snprintf(col, sizeof col, "damping_ratio_%ld", (long) k + 1);
        json_array_append_new(cols, json_string(col));
        snprintf(col, sizeof col, "frequency_error_%ld", (long) k + 1);
        json_array_append_new(cols, json_string(col));
        snprintf(col, sizeof col, "omega_%ld", (long) k + 1);
        json_array_append_new(cols, json_string(col));
    }
    return cols;
}

/* the cells of one row after index,NAME,NAME_exact */
static void sweep_row(FILE *f, const rs_sweep_row_t *p, int of, slong nref)
{
    slong k;
    int c;
    if (of == RS_SWEEP_OF_STABILITY) {
        if (p->d.verdict < 0) fprintf(f, "undefined,-1,,,,%s\n", "exact");
        /* a model with numerics only (exact integration) has no exact counts */
        else if (p->inside < 0) fprintf(f, "%s,%d,,,,%s\n", rs_sweep_verdict_name(p->d.verdict), p->d.verdict,
                                        rs_sweep_level_names[p->d.level]);
        else fprintf(f, "%s,%d,%d,%d,%d,%s\n", rs_sweep_verdict_name(p->d.verdict), p->d.verdict, p->inside,
                     p->on, p->outside, rs_sweep_level_names[p->d.level]);
        return;
    }
    rs_sweep_put_radius(f, p);
    fprintf(f, ",%s,%d,%s", rs_sweep_verdict_name(p->d.verdict), p->d.verdict,
            p->d.verdict < 0 ? "" : rs_sweep_level_names[p->d.level]);
    for (k = 0; of == RS_SWEEP_OF_MODES && k < nref; k++) {
        if (isnan(p->mode_lo[3 * k])) fputs(",,,", f);
        else for (c = 0; c < 3; c++) {
            fputc(',', f);
            rs_sweep_put_certified(f, p->mode_lo[3 * k + c], p->mode_hi[3 * k + c]);
        }
    }
    fputc('\n', f);
}

/* the CSV rows [lo, hi) of a block (rows[0] is point lo), written to the
 * table as each block is computed */
typedef struct {
    const fmpq *vals;
    int of;
    slong nref;
} sweep_rows_arg_t;

static void sweep_rows_put(FILE *f, const rs_sweep_row_t *rows, slong lo, slong hi, void *arg)
{
    const sweep_rows_arg_t *a = arg;
    slong i;
    for (i = lo; i < hi; i++) {
        fprintf(f, "%ld,", (long) i);
        rs_sweep_put_double_of(f, a->vals + i);
        fputc(',', f);
        rs_sweep_put_fmpq(f, a->vals + i);
        fputc(',', f);
        sweep_row(f, rows + (i - lo), a->of, a->nref);
    }
}

/* The run's shard of the sweep over vals computed by m into T (the maps'
 * block loop: one block of rows held, each written at once to the spool
 * or memory); *cols its columns (json_decref) */
static int sweep_table(rs_sweep_table_t *T, json_t **cols, rs_run_t *run, const rs_request_t *q,
                       const rs_sweep_request_t *R, const rs_sweep_model_t *m, const fmpq *vals, slong npoints,
                       slong nref)
{
    sweep_rows_arg_t a;
    char what[120], *header;
    int r;
    memset(T, 0, sizeof *T);
    T->spool = -1;
    *cols = sweep_columns(R->axis[0].name, R->of, nref);
    header = rs_sweep_header_line(*cols);
    if (header == NULL) return rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", "out of memory for the table");
    a.vals = vals;
    a.of = R->of;
    a.nref = nref;
    snprintf(what, sizeof what, "sweep %s", R->axis[0].name);
    r = rs_sweep_map_table(T, run, q, m, npoints, what, R->axis[0].name, header, sweep_rows_put, &a);
    free(header);
    return r;
}

/* the sweep element of the table T with columns cols (a reference taken) */
static json_t *sweep_json(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R, json_t *cols,
                          const rs_sweep_table_t *T, double seconds)
{
    const rs_sweep_axis_t *X = R->axis;
    json_t *o = json_object();
    const char *keep[1];
    json_object_set_new(o, "analysis", json_string("sweep"));
    json_object_set_new(o, "param", json_string(X[0].name));
    json_object_set_new(o, "from", rs_json_fmpq(X[0].from));
    json_object_set_new(o, "to", rs_json_fmpq(X[0].to));
    json_object_set_new(o, "steps", json_integer(X[0].count));
    json_object_set_new(o, "spacing", json_string(R->logsp ? "log" : "linear"));
    if (R->logsp)
        json_object_set_new(o, "rational_approximation", json_string(
            "interior points are the simplest rationals within 1e-13 relative of A*(B/A)^(i/K); "
            "the exact values are in the NAME_exact column"));
    json_object_set_new(o, "of", json_string(rs_sweep_of_names[R->of]));
    rs_sweep_json_shard(o, run, X[0].count + 1, T->lo, T->hi);
    json_object_set_new(o, "columns", json_incref(cols));
    rs_sweep_json_summary(o, T, seconds);
    keep[0] = X[0].name;
    {
        json_t *sub = rs_sweep_json_sets(run, keep, 1), *at;
        slong k;
        /* the values of `at` replace the case's for this sweep */
        if (R->nat > 0) {
            at = json_object();
            for (k = 0; k < R->nat; k++) {
                json_object_set_new(at, R->at[k].name, rs_json_fmpq(R->at[k].value));
                json_object_set_new(sub, R->at[k].name, rs_json_fmpq(R->at[k].value));
            }
            json_object_set_new(o, "at", at);
        }
        json_object_set_new(o, "substituted", sub);
    }
    json_object_set_new(o, "text", json_string(q->text));
    rs_sweep_table_json(o, T, run->opt->sweep.json_rows);
    return o;
}

int rs_sweep_variant(rs_variant_t **v, rs_run_t *run, const rs_sweep_request_t *R)
{
    rs_assign_t *a;
    slong n, k;
    const char *keep[2];
    int r;
    for (k = 0; k < R->naxes; k++) keep[k] = run->c->params[R->axis[k].var].name;
    rs_run_assignments(run, &a, &n, keep, R->naxes, R->at, R->nat);
    r = rs_run_variant(v, run, a, n);
    rs_assign_free(a, n);
    return r;
}

/* a sweep of a real parameter with the complex set values fixed */
static int cx_sweep_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R)
{
    slong K = R->axis[0].count, npoints = K + 1, i;
    rs_variant_t *v = NULL;
    rs_sweep_table_t T;
    json_t *cols = NULL;
    rs_sweep_model_t m;
    rs_sweep_cx_t J;
    fmpq *vals;
    double t0 = rs_sweep_now();
    int r = rs_sweep_estimate(run, q, (double) K + 1.0, "the sweep");
    if (r == RS_OK) r = rs_sweep_variant(&v, run, R);
    if (r != RS_OK) return r;
    r = rs_sweep_cx_init(&J, run, q, R, v);
    vals = _fmpq_vec_init(npoints);
    for (i = 0; i < npoints; i++) rs_grid_value(vals + i, R->axis[0].from, R->axis[0].to, i, K, R->logsp);
    if (r == RS_OK && R->of == RS_SWEEP_OF_MODES) r = rs_sweep_cx_modes(&J, run, q, R, v, vals, npoints);
    if (r == RS_OK) {
        J.vals[0] = vals;
        J.stride = npoints > 256 ? npoints / 256 : 1;   /* about 256 points certified beside the exact verdict */
        m.point = rs_sweep_cx_point;
        m.model = &J;
        m.serial = 0;
        r = sweep_table(&T, &cols, run, q, R, &m, vals, npoints, J.nref);
        if (r == RS_OK) {
            json_t *o = sweep_json(run, q, R, cols, &T, rs_sweep_now() - t0);
            json_object_set_new(o, "over", json_string("Q(i)"));
            json_object_set_new(o, "complex", rs_run_cx_at(run));
            json_object_set_new(o, "method", json_string(
                "p over Q(i) at each point: complex Schur-Cohn and Bilharz on the bilinear transform (must agree), "
                "p's own root counts; the radius certified from p conj(p) (the same moduli), of modes from p's own "
                "roots (Yun over Q(i), each factor's roots isolated by acb_poly_find_roots); the radius checked "
                "against the exact count at every point"));
            json_object_set_new(o, "cross_check", json_pack("{s:I,s:s}", "stride", (json_int_t) J.stride, "method",
                "every stride-th point also by the certified ladder on p conj(p) (stable iff p is, unstable where p "
                "is; exit 3 on disagreement)"));
            json_array_append_new(run->results, o);
        }
        rs_sweep_table_clear(&T);
        json_decref(cols);
    }
    _fmpq_vec_clear(vals, npoints);
    rs_sweep_cx_clear(&J);
    return r;
}

/* a sweep of a model over Q(sqrt d) (rk sdirk2, sdirk3): of stability or
 * radius, each point by an_qd_map.c's verdict (and certified radius) */
static int qd_sweep_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R)
{
    slong K = R->axis[0].count, npoints = K + 1, i;
    rs_variant_t *v = NULL;
    rs_sweep_table_t T;
    json_t *cols = NULL;
    rs_sweep_model_t m;
    fmpq *vals;
    double t0 = rs_sweep_now();
    int r = R->of != RS_SWEEP_OF_MODES ? rs_sweep_estimate(run, q, (double) K + 1.0, "the sweep")
            : rs_req_error(run, q, q->text, RS_ERR_INPUT, "over Q(sqrt d) a sweep is `of stability` or `of radius` "
                           "(exact per point, the radius certified); modes run at set values (analyse modes)%s", "");
    if (r == RS_OK) r = rs_sweep_variant(&v, run, R);
    if (r != RS_OK) return r;
    vals = _fmpq_vec_init(npoints);
    for (i = 0; i < npoints; i++) rs_grid_value(vals + i, R->axis[0].from, R->axis[0].to, i, K, R->logsp);
    r = rs_an_qd_sweep_model(&m, run, q, R, v, (const fmpq *const *) &vals);
    if (r == RS_OK) {
        r = sweep_table(&T, &cols, run, q, R, &m, vals, npoints, 0);
        if (r == RS_OK) {
            json_t *o = sweep_json(run, q, R, cols, &T, rs_sweep_now() - t0);
            rs_an_qd_sweep_json(o, run, NULL);
            json_array_append_new(run->results, o);
        }
        rs_sweep_table_clear(&T);
        json_decref(cols);
    }
    rs_an_qd_sweep_model_free(&m);
    _fmpq_vec_clear(vals, npoints);
    return r;
}

int rs_an_sweep_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R)
{
    slong K = R->axis[0].count, npoints = K + 1, i;
    rs_variant_t *v = NULL;
    rs_sweep_poly_t *J = NULL;
    rs_sweep_model_t m;
    rs_sweep_table_t T;
    json_t *cols = NULL;
    fmpq *vals;
    double t0 = rs_sweep_now();
    int cosim = run->m->kind == RS_MODEL_COSIM;
    int r;
    if (!cosim && run->c->ncsets > 0) return cx_sweep_run(run, q, R);
    if (!cosim && run->m->qd != NULL) return qd_sweep_run(run, q, R);
    r = rs_sweep_estimate(run, q, (double) K + 1.0, "the sweep");
    if (r == RS_OK && !cosim) r = rs_sweep_variant(&v, run, R);
    if (r != RS_OK) return r;
    vals = _fmpq_vec_init(npoints);
    for (i = 0; i < npoints; i++) rs_grid_value(vals + i, R->axis[0].from, R->axis[0].to, i, K, R->logsp);
    /* the model kind supplies the point: the equations, or exact integration */
    m.model = NULL;
    if (cosim) r = rs_cosim_sweep_model_new(&m, run, q, R, vals, npoints);
    else r = rs_sweep_poly_new(&J, run, q, R, v, (const fmpq *const *) &vals, npoints);
    if (r == RS_OK) {
        if (!cosim) rs_sweep_poly_model(&m, J);
        r = sweep_table(&T, &cols, run, q, R, &m, vals, npoints, cosim ? rs_cosim_sweep_nref(&m) : rs_sweep_poly_nref(J));
        if (r == RS_OK) {
            json_t *o = sweep_json(run, q, R, cols, &T, rs_sweep_now() - t0);
            /* exact integration, `of modes`: the certified eigenvalues of each row's one-step map */
            if (cosim && R->of == RS_SWEEP_OF_MODES)
                json_object_set_new(o, "eigenvalues", rs_cosim_sweep_eigenvalues(&m, T.lo, T.hi));
            json_array_append_new(run->results, o);
        }
        rs_sweep_table_clear(&T);
        json_decref(cols);
    }
    rs_sweep_poly_free(J);
    if (cosim) rs_cosim_sweep_model_free(&m);
    _fmpq_vec_clear(vals, npoints);
    return r;
}
