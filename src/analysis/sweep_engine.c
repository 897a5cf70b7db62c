/* sweep_engine.c -- the one engine of sweeps and maps for every model kind
 * (sweep_impl.h): the shard of the points, their computation (numeric/
 * engine.c: OpenMP, MPI, progress, budget), point errors, the limit
 * messages, the map's columns and table, the JSON summary. */
#include <errno.h>
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
    o->table_spool = NULL;
    o->table_spool_arg = NULL;
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
static int estimate(rs_run_t *run, const rs_request_t *q, double npoints, double bytes, const char *desc)
{
    char msg[RS_ERROR_MSG_LEN];
    rs_error_t e;
    rs_error_init(e);
    if (rs_budget_estimate(e, desc, npoints * 1e-6, npoints * bytes) == RS_OK) return RS_OK;
    snprintf(msg, sizeof msg, "%s", e->msg);
    return rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", msg);
}

/* in memory every row of results stays to the end */
static int estimate_rows(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc)
{
    return estimate(run, q, npoints, (double) (sizeof(rs_sweep_row_t) + 2 * sizeof(fmpq)), desc);
}

/* a streamed sweep holds one block of rows: its values and the model's
 * per-point numbers (powers, time steps), two rationals a point, stay */
int rs_sweep_estimate(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc)
{
    if (run->opt->sweep.table_spool == NULL) return estimate_rows(run, q, npoints, desc);
    return estimate(run, q, npoints, (double) (2 * sizeof(fmpq)), desc);
}

/* a streamed map holds one block of rows: a rational per point (the
 * model's time steps) is what stays */
int rs_sweep_estimate_map(rs_run_t *run, const rs_request_t *q, double npoints)
{
    if (run->opt->sweep.table_spool == NULL) return estimate_rows(run, q, npoints, "the map");
    return estimate(run, q, npoints, (double) sizeof(fmpq), "the map");
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
    if (exact == 1) return json_string(tmp);
    d = strtod(tmp, &end);
    if (*end != '\0' || !isfinite(d)) return json_string(tmp);
    /* a column of reals (RS_SWEEP_COL_REAL): "-2" is -2.0 as its other cells */
    if (exact != RS_SWEEP_COL_REAL && strpbrk(tmp, ".eE") == NULL && fabs(d) < 9007199254740992.0)
        return json_integer((json_int_t) d);
    return json_real(d);
}

char *rs_sweep_exact_columns(const char *header, size_t n)
{
    const char *c = header, *nl = header + n;
    char *exact = calloc(n + 2, 1);
    slong ncol = 0;
    for (;;) {
        const char *e = c;
        while (e < nl && *e != ',') e++;
        exact[ncol++] = (e - c > 6 && strncmp(e - 6, "_exact", 6) == 0);
        if (e >= nl) break;
        c = e + 1;
    }
    exact[ncol] = 2;   /* the end of the flags */
    return exact;
}

json_t *rs_sweep_json_row(const char *p, size_t n, const char *exact)
{
    json_t *row = json_array();
    const char *c = p, *nl = p + n;
    int past = exact == NULL;   /* no header: no exact column */
    slong k;
    for (k = 0;; k++) {
        const char *e = c;
        if (!past && exact[k] == 2) past = 1;
        while (e < nl && *e != ',') e++;
        json_array_append_new(row, cell_json(c, (size_t) (e - c), past ? 0 : exact[k]));
        if (e >= nl) break;
        c = e + 1;
    }
    return row;
}

void rs_sweep_flag_real(char *flags, const json_t *real)
{
    size_t k, n = 0;
    while (flags[n] != 2) n++;
    for (k = 0; k < json_array_size(real); k++) {
        json_int_t c = json_integer_value(json_array_get(real, k));
        if (c >= 0 && (size_t) c < n) flags[c] = RS_SWEEP_COL_REAL;
    }
}

/* jansson's text of json_real(d) (jsonp_dtostr, precision 17): "%.17g",
 * ".0" when neither '.' nor 'e' shows, the exponent without '+' and
 * leading zeros */
static size_t put_real(char *out, double d)
{
    char b[64], *e;
    size_t len = (size_t) snprintf(b, sizeof b, "%.17g", d), i, j;
    if (strchr(b, '.') == NULL && strchr(b, 'e') == NULL) {
        b[len++] = '.';
        b[len++] = '0';
        b[len] = '\0';
    }
    e = strchr(b, 'e');
    if (e != NULL) {
        i = j = (size_t) (e - b) + 1;
        if (b[j] == '-') i = ++j;
        else if (b[j] == '+') j++;
        while (b[j] == '0') j++;
        memmove(b + i, b + j, len + 1 - j);
        len -= j - i;
    }
    memcpy(out, b, len);
    return len;
}

int rs_sweep_json_row_put(FILE *f, const char *p, size_t n, const char *exact)
{
    char stack[2048], *out = stack;
    const char *c = p, *nl = p + n;
    size_t len = 0, cap = n + 4, i;
    int past = exact == NULL, rc = 0;
    slong k;
    /* a cell of w bytes prints at most max(w + 2, 32) */
    for (i = 0; i < n; i++) cap += p[i] == ',' ? 36 : 0;
    cap += 36;
    if (cap > sizeof stack) out = malloc(cap);
    out[len++] = '[';
    for (k = 0;; k++) {
        const char *e = c;
        size_t w;
        int ex, fl;
        if (!past && exact[k] == 2) past = 1;
        fl = past ? 0 : exact[k];
        ex = fl == 1;
        while (e < nl && *e != ',') e++;
        w = (size_t) (e - c);
        if (k > 0) out[len++] = ',';
        if (w == 0) {
            memcpy(out + len, "null", 4);
            len += 4;
        } else {
            char tmp[160], *end;
            double d = 0;
            int num = 0;
            if (w < sizeof tmp && !ex) {
                memcpy(tmp, c, w);
                tmp[w] = '\0';
                d = strtod(tmp, &end);
                num = *end == '\0' && isfinite(d);
            }
            /* a column of reals (RS_SWEEP_COL_REAL) as in cell_json */
            if (num && fl != RS_SWEEP_COL_REAL && strpbrk(tmp, ".eE") == NULL && fabs(d) < 9007199254740992.0)
                len += (size_t) snprintf(out + len, 32, "%" JSON_INTEGER_FORMAT, (json_int_t) d);
            else if (num)
                len += put_real(out + len, d);
            else {
                for (i = 0; i < w; i++)
                    if ((unsigned char) c[i] < 0x20 || (unsigned char) c[i] >= 0x80 || c[i] == '"' || c[i] == '\\')
                        rc = -1;
                if (rc != 0) break;
                out[len++] = '"';
                memcpy(out + len, c, w);
                len += w;
                out[len++] = '"';
            }
        }
        if (e >= nl) break;
        c = e + 1;
    }
    out[len++] = ']';
    if (rc == 0) fwrite(out, 1, len, f);
    if (out != stack) free(out);
    return rc;
}

void rs_sweep_json_rows(json_t *o, const char *key, const char *table, slong cap)
{
    rs_sweep_json_rows_typed(o, key, table, cap, NULL);
}

void rs_sweep_json_rows_typed(json_t *o, const char *key, const char *table, slong cap, const json_t *real)
{
    json_t *rows = json_array();
    const char *p = table, *nl;
    char *exact = NULL;
    slong nrow = 0;
    char omitted[64];
    /* the header: which columns are exact */
    nl = strchr(p, '\n');
    if (nl != NULL) {
        exact = rs_sweep_exact_columns(p, (size_t) (nl - p));
        if (real != NULL) rs_sweep_flag_real(exact, real);
        p = nl + 1;
    } else p = "";
    for (; *p; p = nl + 1, nrow++) {
        nl = strchr(p, '\n');
        if (nl == NULL) nl = p + strlen(p);
        if (cap < 0 || nrow < cap) json_array_append_new(rows, rs_sweep_json_row(p, (size_t) (nl - p), exact));
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

/* the verdicts and deciding levels of rows counted, block by block */
typedef struct {
    /* ver: stable, marginal, unstable, undefined, singular, undecided;
     * lev: RS_LEVEL_* (fast .. exact, double, certified) */
    slong ver[6], lev[6];
} tally_t;

static void tally_add(tally_t *t, const rs_sweep_row_t *rows, slong n)
{
    slong i;
    for (i = 0; i < n; i++) {
        int c = rows[i].d.verdict;
        t->ver[c < 0 ? 3 : c == RS_STATUS_SINGULAR ? 4 : c == RS_SWEEP_UNDECIDED ? 5 : c]++;
        if (c >= 0) t->lev[rows[i].d.level]++;
    }
}

static void json_summary_of(json_t *o, const tally_t *t, double seconds)
{
    const slong *ver = t->ver, *lev = t->lev;
    json_t *v, *d;
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

/* counts, seconds, etc. common to sweep and map elements */
void rs_sweep_json_summary(json_t *o, const rs_sweep_table_t *T, double seconds)
{
    tally_t t;
    memcpy(t.ver, T->verdicts, sizeof t.ver);
    memcpy(t.lev, T->levels, sizeof t.lev);
    json_summary_of(o, &t, seconds);
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

/* the CSV table: the column header line */
static void map_table_header(FILE *f, const json_t *cols)
{
    slong k;
    for (k = 0; k < (slong) json_array_size(cols); k++)
        fprintf(f, "%s%s", k ? "," : "", json_string_value(json_array_get(cols, k)));
    fputc('\n', f);
}

char *rs_sweep_header_line(const json_t *cols)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (f == NULL) return NULL;
    map_table_header(f, cols);
    fclose(f);
    return buf;
}

/* the CSV table: rows [lo, hi), rows[0] being point lo */
static void map_table_rows(FILE *f, const rs_sweep_request_t *R, const fmpq *const *xs, const rs_sweep_row_t *rows,
                           slong lo, slong hi)
{
    slong i, K1 = R->axis[0].count;
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
}

/* The table of n rows: its text buf (the default) into "table" and "rows"
 * (the first cap), else (spooled, id) "table_spool" and {"spool": id,
 * "count": N} as "rows" (rs_run_json_dumps_spool writes them), and
 * "rows_omitted" past cap. */
static void table_json(json_t *o, const char *buf, slong id, slong cap, slong n)
{
    if (buf != NULL) {
        json_object_set_new(o, "table", json_string(buf));
        rs_sweep_json_rows(o, "rows", buf, cap);
        return;
    }
    json_object_set_new(o, "table_spool", json_integer(id));
    json_object_set_new(o, "rows", json_pack("{s:I,s:I}", "spool", (json_int_t) id, "count",
                                             (json_int_t) (cap >= 0 && n > cap ? cap : n)));
    if (cap >= 0 && n > cap) json_object_set_new(o, "rows_omitted", json_integer(n - cap));
}

void rs_sweep_table_json(json_t *o, const rs_sweep_table_t *T, slong cap)
{
    table_json(o, T->spool >= 0 ? NULL : (T->text != NULL ? T->text : ""), T->spool, cap, T->hi - T->lo);
}

/* The map element of rows [lo, hi) whose verdicts t counted, its table
 * written to f (header and rows): the table text buf (the default) into
 * "table" and "rows", else (spooled, id) {"spool": id, "count": N} as
 * "rows".  Keys in the order readers have always seen. */
static json_t *map_json(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R, json_t *cols,
                        const tally_t *t, slong lo, slong hi, const char *buf, slong id)
{
    const rs_sweep_axis_t *X = R->axis;
    json_t *o = json_object();
    const char *keep[2];
    slong cap = run->opt->sweep.json_rows;
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
    json_summary_of(o, t, 0);
    json_object_set_new(o, "substituted", rs_sweep_json_sets(run, keep, 2));
    json_object_set_new(o, "text", json_string(q->text));
    table_json(o, buf, id, cap, hi - lo);
    return o;
}

/* Points per block of a map or sweep: the per-point results of one block
 * only are held (rs_sweep_row_t is a few hundred bytes), each block's rows
 * go to the table as soon as it is computed. */
#define MAP_BLOCK 32768

/* The table's stream: the run's spool (*id) when it has one, else in
 * memory (*buf, complete once closed); *spooled which. */
static FILE *table_open(const rs_sweep_options_t *so, slong *id, char **buf, size_t *len, int *spooled)
{
    FILE *f = NULL;
    /* no spool (none asked for, or no temporary file could be made): in memory */
    if (so->table_spool != NULL) f = so->table_spool(so->table_spool_arg, id);
    *spooled = f != NULL;
    if (f == NULL) f = open_memstream(buf, len);
    return f;
}

/* Points [lo, hi) computed by m block by block, counted into t, each
 * block's rows written by put(f, rows, b, bhi, arg) once computed: a
 * point's error ends the map or sweep at the first block that has one
 * (its first failing point, as when computed at once). */
static int map_blocks(rs_run_t *run, const rs_request_t *q, const rs_sweep_model_t *m, slong lo, slong hi,
                      const char *what, const char *desc, FILE *f, tally_t *t, rs_sweep_rows_fn put, void *arg)
{
    const rs_sweep_options_t *so = &run->opt->sweep;
    rs_sweep_row_t *rows = calloc((size_t) (hi > lo ? (hi - lo < MAP_BLOCK ? hi - lo : MAP_BLOCK) : 1),
                                  sizeof(rs_sweep_row_t));
    rs_engine_t e;
    slong b;
    int r = RS_OK;
    e.point = engine_point;
    e.arg = (void *) m;
    e.serial = m->serial;
    e.progress = so->progress;
    e.progress_arg = so->progress_arg;
    e.what = what;
    e.total = hi - lo;
    for (b = lo; b < hi && r == RS_OK; b += MAP_BLOCK) {
        slong bhi = hi - b < MAP_BLOCK ? hi : b + MAP_BLOCK;
        e.done0 = b - lo;
        rs_engine_run(rows, sizeof(rs_sweep_row_t), b, bhi, &e);
        r = point_errors(run, q, m, rows, b, bhi - b, desc);
        if (r != RS_OK) break;
        tally_add(t, rows, bhi - b);
        put(f, rows, b, bhi, arg);
    }
    free(rows);
    return r;
}

typedef struct {
    const rs_sweep_request_t *R;
    const fmpq *const *xs;
} map_rows_arg_t;

static void map_rows_put(FILE *f, const rs_sweep_row_t *rows, slong lo, slong hi, void *arg)
{
    const map_rows_arg_t *a = arg;
    map_table_rows(f, a->R, a->xs, rows, lo, hi);
}

int rs_sweep_map_finish(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R, const rs_sweep_model_t *m,
                        const fmpq *const *xs, double t0, rs_sweep_decorate_fn decorate, void *arg)
{
    const rs_sweep_axis_t *X = R->axis;
    const rs_sweep_options_t *so = &run->opt->sweep;
    slong npoints = X[0].count * X[1].count, lo = 0, hi = 0, id = 0;
    json_t *cols = map_columns(R);
    char what[200], desc[200], *buf = NULL;
    size_t len = 0;
    double t_points;
    tally_t t;
    map_rows_arg_t ra;
    FILE *f;
    int r, spooled;
    snprintf(what, sizeof what, "map %s,%s", X[0].name, X[1].name);
    snprintf(desc, sizeof desc, "index = j*%ld + i of %s[i], %s[j]", (long) X[0].count, X[0].name, X[1].name);
    memset(&t, 0, sizeof t);
    rs_grid_shard_range(&lo, &hi, npoints, so->shard_index, so->shard_count);
    f = table_open(so, &id, &buf, &len, &spooled);
    map_table_header(f, cols);
    ra.R = R;
    ra.xs = xs;
    r = map_blocks(run, q, m, lo, hi, what, desc, f, &t, map_rows_put, &ra);
    t_points = rs_sweep_now() - t0;
    if (r == RS_OK && spooled && (fflush(f) != 0 || ferror(f)))
        r = rs_req_error(run, q, q->text, RS_ERR_IO, "cannot write the map's table to its temporary file: %s",
                         strerror(errno));
    /* the caller's spool stays open; the in-memory table is complete once closed */
    if (!spooled) fclose(f);
    if (r == RS_OK) {
        json_t *o = map_json(run, q, R, json_incref(cols), &t, lo, hi, spooled ? NULL : buf, id);
        if (decorate != NULL) decorate(o, arg);
        json_object_set_new(o, "seconds", json_real(floor((rs_sweep_now() - t0) * 1e4 + 0.5) / 1e4));
        json_object_set_new(o, "seconds_points", json_real(floor(t_points * 1e4 + 0.5) / 1e4));
        json_array_append_new(run->results, o);
    }
    json_decref(cols);
    free(buf);
    return r;
}

void rs_sweep_table_clear(rs_sweep_table_t *T)
{
    free(T->text);
    T->text = NULL;
}

int rs_sweep_map_table(rs_sweep_table_t *T, rs_run_t *run, const rs_request_t *q, const rs_sweep_model_t *m,
                       slong npoints, const char *what, const char *desc, const char *header, rs_sweep_rows_fn put,
                       void *arg)
{
    const rs_sweep_options_t *so = &run->opt->sweep;
    size_t len = 0;
    slong id = 0;
    tally_t t;
    FILE *f;
    int r, spooled;
    memset(T, 0, sizeof *T);
    memset(&t, 0, sizeof t);
    T->spool = -1;
    rs_grid_shard_range(&T->lo, &T->hi, npoints, so->shard_index, so->shard_count);
    f = table_open(so, &id, &T->text, &len, &spooled);
    if (f == NULL)
        return rs_req_error(run, q, q->text, RS_ERR_IO, "cannot open a stream for the table: %s", strerror(errno));
    fputs(header, f);
    r = map_blocks(run, q, m, T->lo, T->hi, what, desc, f, &t, put, arg);
    if (r == RS_OK && spooled && (fflush(f) != 0 || ferror(f))) {
        char msg[300];
        snprintf(msg, sizeof msg, "cannot write the %s table to its temporary file: %s",
                 strncmp(what, "sweep", 5) == 0 ? "sweep's" : "map's", strerror(errno));
        r = rs_req_error(run, q, q->text, RS_ERR_IO, "%s", msg);
    }
    if (!spooled) fclose(f);
    else T->spool = id;
    memcpy(T->verdicts, t.ver, sizeof T->verdicts);
    memcpy(T->levels, t.lev, sizeof T->levels);
    return r;
}
