/* sweep_engine.c -- the one engine of sweeps and maps for every model kind
 * (sweep_impl.h): the shard of the points, their computation (numeric/
 * engine.c: OpenMP, MPI, progress, budget), point errors, the limit
 * messages, the map's columns and table, the JSON summary. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#include "recstab/budget.h"
#include "analysis/sweep_impl.h"
#include "numeric/engine.h"
#include "numeric/grid.h"

void rs_sweep_options_default(rs_sweep_options_t *o)
{
    o->shard_index = 1;
    o->shard_count = 1;
    o->max_points = RS_SWEEP_MAX_POINTS_DEFAULT;
    o->progress = NULL;
    o->progress_arg = NULL;
    o->first_level = RS_LEVEL_FAST;
    o->json_rows = -1;
}

void rs_sweep_shard_range(slong *lo, slong *hi, slong npoints, slong I, slong N)
{
    rs_grid_shard_range(lo, hi, npoints, I, N);
}

double rs_sweep_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* npoints as a double: K + 1 or K1 * K2 may not fit into a slong */
int rs_sweep_limit_error(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc)
{
    char msg[400];
    /* exact below 2^53, rounded (and said so) above */
    snprintf(msg, sizeof msg, npoints < 9007199254740992.0 ? "%s has %.0f points, more than the limit of %ld points "
             "per sweep or map (raise it with --max-points N)" : "%s has about %.4g points, more than the limit of "
             "%ld points per sweep or map (raise it with --max-points N)", desc, npoints, (long) run->opt->sweep.max_points);
    return rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", msg);
}

/* Before allocating: the points must fit into what is left of the budget.
 * 1 us and sizeof(rs_sweep_row_t) + two rationals per point are lower bounds (the
 * fastest sweep measured, degree 1 on one thread, takes about 4 us). */
int rs_sweep_estimate(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc)
{
    char msg[RS_ERROR_MSG_LEN];
    rs_error_t e;
    rs_error_init(e);
    if (rs_budget_estimate(e, desc, npoints * 1e-6, npoints * (double) (sizeof(rs_sweep_row_t) + 2 * sizeof(fmpq))) == RS_OK)
        return RS_OK;
    snprintf(msg, sizeof msg, "%s", e->msg);
    return rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", msg);
}

/* the engine's callback: one point of the model */
static void engine_point(void *pt, slong idx, void *arg)
{
    const rs_sweep_model_t *m = arg;
    rs_error_t e;
    rs_error_init(e);
    m->point(pt, idx, m->model, e);
}

/* first failing point: recompute serially for its message */
static int point_errors(rs_run_t *run, const rs_request_t *q, const rs_sweep_model_t *m, const rs_sweep_row_t *rows,
                        slong lo, slong n, const char *desc)
{
    slong i;
    /* points skipped after the budget ran out: no table from them */
    if (rs_budget_exceeded()) return rs_budget_error(run->err);
    for (i = 0; i < n; i++)
        if (rows[i].d.status != RS_OK) {
            rs_sweep_row_t tmp;
            rs_error_t e;
            char msg[RS_ERROR_MSG_LEN + 200];
            int code;
            rs_error_init(e);
            memset(&tmp, 0, sizeof tmp);
            m->point(&tmp, lo + i, m->model, e);
            code = tmp.d.status != RS_OK ? tmp.d.status : rows[i].d.status;
            if (code == RS_ERR_INCONSISTENT) run->outcome |= RS_OUTCOME_INCONSISTENT;
            snprintf(msg, sizeof msg, "at point %ld (%s): %s", (long) (lo + i), desc,
                     e->msg[0] ? e->msg : rs_error_code_name(code));
            return rs_req_error(run, q, q->text, code, "%s", msg);
        }
    return RS_OK;
}

int rs_sweep_compute(rs_sweep_row_t **rows, slong *lo, slong *hi, rs_run_t *run, const rs_request_t *q,
                     const rs_sweep_model_t *m, slong npoints, const char *what, const char *desc)
{
    const rs_sweep_options_t *so = &run->opt->sweep;
    rs_engine_t e;
    rs_grid_shard_range(lo, hi, npoints, so->shard_index, so->shard_count);
    *rows = calloc((size_t) (*hi - *lo + 1), sizeof(rs_sweep_row_t));
    e.point = engine_point;
    e.arg = (void *) m;
    e.serial = m->serial;
    e.progress = so->progress;
    e.progress_arg = so->progress_arg;
    e.what = what;
    rs_engine_run(*rows, sizeof(rs_sweep_row_t), *lo, *hi, &e);
    return point_errors(run, q, m, *rows, *lo, *hi - *lo, desc);
}

void rs_sweep_rows_free(rs_sweep_row_t *rows, slong n)
{
    (void) n;
    free(rows);
}

void rs_sweep_json_shard(json_t *o, const rs_run_t *run, slong npoints, slong lo, slong hi)
{
    char sh[64];
    json_object_set_new(o, "points", json_integer(npoints));
    json_object_set_new(o, "computed", json_integer(hi - lo));
    snprintf(sh, sizeof sh, "%ld/%ld", (long) run->opt->sweep.shard_index, (long) run->opt->sweep.shard_count);
    json_object_set_new(o, "shard", json_string(sh));
    json_object_set_new(o, "row_range", json_pack("[I,I]", (json_int_t) lo, (json_int_t) hi));
}

/* One CSV cell as JSON: null when empty, a number when the whole cell is a
 * finite number (the exact NAME_exact columns stay strings: "1/3" and "3"
 * alike, so a column has one type), else the string ("inf", verdicts). */
static json_t *cell_json(const char *s, size_t n, int exact)
{
    char tmp[160], *end;
    double d;
    if (n == 0) return json_null();
    if (n >= sizeof tmp) return json_stringn(s, n);
    memcpy(tmp, s, n);
    tmp[n] = '\0';
    if (exact) return json_string(tmp);
    d = strtod(tmp, &end);
    if (*end != '\0' || !isfinite(d)) return json_string(tmp);
    if (strpbrk(tmp, ".eE") == NULL && fabs(d) < 9007199254740992.0) return json_integer((json_int_t) d);
    return json_real(d);
}

void rs_sweep_json_rows(json_t *o, const char *key, const char *table, slong cap)
{
    json_t *rows = json_array();
    const char *p = table, *nl;
    char *exact = NULL;
    slong nrow = 0, ncol = 0, k;
    char omitted[64];
    /* the header: which columns are exact */
    nl = strchr(p, '\n');
    if (nl != NULL) {
        const char *c = p;
        exact = calloc((size_t) (nl - p) + 2, 1);
        for (;;) {
            const char *e = c;
            while (e < nl && *e != ',') e++;
            exact[ncol++] = (e - c > 6 && strncmp(e - 6, "_exact", 6) == 0);
            if (e >= nl) break;
            c = e + 1;
        }
        p = nl + 1;
    } else p = "";
    for (; *p; p = nl + 1, nrow++) {
        nl = strchr(p, '\n');
        if (nl == NULL) nl = p + strlen(p);
        if (cap < 0 || nrow < cap) {
            json_t *row = json_array();
            const char *c = p;
            for (k = 0;; k++) {
                const char *e = c;
                while (e < nl && *e != ',') e++;
                json_array_append_new(row, cell_json(c, (size_t) (e - c), k < ncol && exact[k]));
                if (e >= nl) break;
                c = e + 1;
            }
            json_array_append_new(rows, row);
        }
        if (*nl == '\0') { nrow++; break; }
    }
    json_object_set_new(o, key, rows);
    if (cap >= 0 && nrow > cap) {
        snprintf(omitted, sizeof omitted, "%s_omitted", key);
        json_object_set_new(o, omitted, json_integer(nrow - cap));
    }
    free(exact);
}

/* ---- table cells ------------------------------------------------------------------------------ */

/* certified bounds printed outward: the decimal string of the neighbouring
 * double is on the safe side of the bound */
static void put_lower(FILE *f, double x)
{
    if (x == 0 || x == 1.0) fprintf(f, "%.17g", x);
    else fprintf(f, "%.17g", nextafter(x, -INFINITY));
}

static void put_upper(FILE *f, double x)
{
    if (isinf(x)) fputs("inf", f);
    else if (x == 0 || x == 1.0) fprintf(f, "%.17g", x);
    else fprintf(f, "%.17g", nextafter(x, INFINITY));
}

/* A point estimate in [lo, hi] with only its certified digits (every value
 * of [lo, hi] rounds to it, at most 15 digits); empty when no digit is. */
void rs_sweep_put_certified(FILE *f, double lo, double hi)
{
    arf_t a, b;
    char *s;
    arf_init(a);
    arf_init(b);
    arf_set_d(a, lo);
    arf_set_d(b, hi);
    s = rs_radius_interval_str(a, b, 15);
    if (s[0] != '[' && strcmp(s, "nan") != 0) fputs(s, f);
    flint_free(s);
    arf_clear(a);
    arf_clear(b);
}

void rs_sweep_put_radius(FILE *f, const rs_sweep_row_t *row)
{
    const rs_sweep_point_t *d = &row->d;
    if (row->cells[0] != 0) { fputs(row->cells, f); return; }
    if (d->verdict < 0) { fputs(",,", f); return; }
    if (d->level == RS_LEVEL_DOUBLE) {
        /* benchmark baseline: an estimate, and no certified bound at all */
        fprintf(f, "%.15g,0,inf", d->rho_lower);
        return;
    }
    rs_sweep_put_certified(f, d->rho_lower, d->rho_upper);
    fputc(',', f);
    put_lower(f, d->rho_lower);
    fputc(',', f);
    put_upper(f, d->rho_upper);
}

const char *rs_sweep_verdict_name(int code)
{
    return code < 0 ? "undefined" : code == RS_SWEEP_UNDECIDED ? "undecided" : rs_status_name((rs_status_t) code);
}

void rs_sweep_put_fmpq(FILE *f, const fmpq_t x)
{
    char *s = fmpq_get_str(NULL, 10, x);
    fputs(s, f);
    flint_free(s);
}

void rs_sweep_put_double_of(FILE *f, const fmpq_t x)
{
    fprintf(f, "%.15g", fmpq_get_d(x));
}

/* ---- JSON ----------------------------------------------------------------------------------- */

/* counts, seconds, etc. common to sweep and map elements */
void rs_sweep_json_summary(json_t *o, const rs_sweep_row_t *rows, slong n, double seconds)
{
    /* ver: stable, marginal, unstable, undefined, singular, undecided;
     * lev: RS_LEVEL_* (fast .. exact, double, certified) */
    slong i, ver[6] = {0, 0, 0, 0, 0, 0}, lev[6] = {0, 0, 0, 0, 0, 0};
    json_t *v, *d;
    for (i = 0; i < n; i++) {
        int c = rows[i].d.verdict;
        ver[c < 0 ? 3 : c == RS_STATUS_SINGULAR ? 4 : c == RS_SWEEP_UNDECIDED ? 5 : c]++;
        if (c >= 0) lev[rows[i].d.level]++;
    }
    v = json_pack("{s:I,s:I,s:I}", "stable", (json_int_t) ver[0], "marginal", (json_int_t) ver[1],
                  "unstable", (json_int_t) ver[2]);
    if (ver[3] > 0) json_object_set_new(v, "undefined", json_integer(ver[3]));
    if (ver[4] > 0) json_object_set_new(v, "singular", json_integer(ver[4]));
    if (ver[5] > 0) json_object_set_new(v, "undecided", json_integer(ver[5]));
    if (lev[RS_LEVEL_DOUBLE] > 0) json_object_set_new(o, "uncertified", json_integer(lev[RS_LEVEL_DOUBLE]));
    d = json_pack("{s:I,s:I,s:I,s:I}", "fast", (json_int_t) lev[0], "prec128", (json_int_t) lev[1],
                  "prec256", (json_int_t) lev[2], "exact", (json_int_t) lev[3]);
    if (lev[RS_LEVEL_DOUBLE] > 0) json_object_set_new(d, "double", json_integer(lev[RS_LEVEL_DOUBLE]));
    if (lev[RS_LEVEL_CERTIFIED] > 0) json_object_set_new(d, "certified", json_integer(lev[RS_LEVEL_CERTIFIED]));
    json_object_set_new(o, "verdicts", v);
    json_object_set_new(o, "decided_by", d);
    json_object_set_new(o, "seconds", json_real(floor(seconds * 1e4 + 0.5) / 1e4));
#ifdef _OPENMP
    json_object_set_new(o, "threads", json_integer(omp_get_max_threads()));
#else
    json_object_set_new(o, "threads", json_integer(1));
#endif
    json_object_set_new(o, "csv", json_null());
}

json_t *rs_sweep_json_sets(rs_run_t *run, const char *const *keep, slong nkeep)
{
    rs_assign_t *a;
    slong n, i;
    json_t *o = json_object();
    rs_run_assignments(run, &a, &n, keep, nkeep, NULL, 0);
    for (i = 0; i < n; i++) json_object_set_new(o, a[i].name, rs_json_fmpq(a[i].value));
    rs_assign_free(a, n);
    return o;
}


/* index,i,j,NAME1,NAME2,NAME1_exact,NAME2_exact,verdict,code,radius,radius_lower,radius_upper,decided_by */
static json_t *map_columns(const rs_sweep_request_t *R)
{
    static const char *const c1[] = {"index", "i", "j"};
    static const char *const c2[] = {"verdict", "code", "radius", "radius_lower", "radius_upper", "decided_by"};
    json_t *cols = json_array();
    char col[200];
    slong k;
    for (k = 0; k < 3; k++) json_array_append_new(cols, json_string(c1[k]));
    json_array_append_new(cols, json_string(R->axis[0].name));
    json_array_append_new(cols, json_string(R->axis[1].name));
    for (k = 0; k < 2; k++) {
        snprintf(col, sizeof col, "%s_exact", R->axis[k].name);
        json_array_append_new(cols, json_string(col));
    }
    for (k = 0; k < 6; k++) json_array_append_new(cols, json_string(c2[k]));
    return cols;
}

/* the CSV text: the column header, then rows [lo, hi) (malloc'd) */
static char *map_table(const json_t *cols, const rs_sweep_request_t *R, const fmpq *const *xs,
                       const rs_sweep_row_t *rows, slong lo, slong hi)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    slong k, i, K1 = R->axis[0].count;
    for (k = 0; k < (slong) json_array_size(cols); k++)
        fprintf(f, "%s%s", k ? "," : "", json_string_value(json_array_get(cols, k)));
    fputc('\n', f);
    for (i = lo; i < hi; i++) {
        const rs_sweep_row_t *p = rows + (i - lo);
        slong ii = i % K1, jj = i / K1;
        fprintf(f, "%ld,%ld,%ld,", (long) i, (long) ii, (long) jj);
        rs_sweep_put_double_of(f, xs[0] + ii);
        fputc(',', f);
        rs_sweep_put_double_of(f, xs[1] + jj);
        fputc(',', f);
        rs_sweep_put_fmpq(f, xs[0] + ii);
        fputc(',', f);
        rs_sweep_put_fmpq(f, xs[1] + jj);
        fprintf(f, ",%s,%d,", rs_sweep_verdict_name(p->d.verdict), p->d.verdict);
        rs_sweep_put_radius(f, p);
        fprintf(f, ",%s\n", p->d.verdict < 0 ? "" : rs_sweep_level_names[p->d.level]);
    }
    fclose(f);
    return buf;
}

json_t *rs_sweep_map_json(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R, const fmpq *const *xs,
                          const rs_sweep_row_t *rows, slong lo, slong hi)
{
    const rs_sweep_axis_t *X = R->axis;
    json_t *o = json_object(), *cols = map_columns(R);
    const char *keep[2];
    char *buf;
    keep[0] = X[0].name;
    keep[1] = X[1].name;
    json_object_set_new(o, "analysis", json_string("map"));
    json_object_set_new(o, "params", json_pack("[s,s]", X[0].name, X[1].name));
    json_object_set_new(o, "ranges", json_pack("[[o,o,I],[o,o,I]]", rs_json_fmpq(X[0].from), rs_json_fmpq(X[0].to),
                                               (json_int_t) X[0].count, rs_json_fmpq(X[1].from),
                                               rs_json_fmpq(X[1].to), (json_int_t) X[1].count));
    json_object_set_new(o, "grid", json_pack("[I,I]", (json_int_t) X[0].count, (json_int_t) X[1].count));
    json_object_set_new(o, "of", json_string(rs_sweep_of_names[R->of]));
    rs_sweep_json_shard(o, run, X[0].count * X[1].count, lo, hi);
    json_object_set_new(o, "columns", cols);
    buf = map_table(cols, R, xs, rows, lo, hi);
    rs_sweep_json_summary(o, rows, hi - lo, 0);
    json_object_set_new(o, "substituted", rs_sweep_json_sets(run, keep, 2));
    json_object_set_new(o, "text", json_string(q->text));
    json_object_set_new(o, "table", json_string(buf));
    rs_sweep_json_rows(o, "rows", buf, run->opt->sweep.json_rows);
    free(buf);
    return o;
}

int rs_sweep_map_finish(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R, const rs_sweep_model_t *m,
                        const fmpq *const *xs, double t0, rs_sweep_decorate_fn decorate, void *arg)
{
    const rs_sweep_axis_t *X = R->axis;
    slong npoints = X[0].count * X[1].count, lo = 0, hi = 0;
    rs_sweep_row_t *rows = NULL;
    char what[200], desc[200];
    double t_points;
    int r;
    snprintf(what, sizeof what, "map %s,%s", X[0].name, X[1].name);
    snprintf(desc, sizeof desc, "index = j*%ld + i of %s[i], %s[j]", (long) X[0].count, X[0].name, X[1].name);
    r = rs_sweep_compute(&rows, &lo, &hi, run, q, m, npoints, what, desc);
    t_points = rs_sweep_now() - t0;
    if (r == RS_OK) {
        json_t *o = rs_sweep_map_json(run, q, R, xs, rows, lo, hi);
        if (decorate != NULL) decorate(o, arg);
        json_object_set_new(o, "seconds", json_real(floor((rs_sweep_now() - t0) * 1e4 + 0.5) / 1e4));
        json_object_set_new(o, "seconds_points", json_real(floor(t_points * 1e4 + 0.5) / 1e4));
        json_array_append_new(run->results, o);
    }
    rs_sweep_rows_free(rows, hi - lo);
    return r;
}
