/* analysis/sweep_impl.h -- the sweep and map analyses as typed requests
 * (private to src/analysis/).
 *
 * A request is parsed once into an rs_sweep_request_t (syntax, parameter
 * names, numbers, `of ...`, the point limit of run->opt->sweep), with errors
 * at file:line:col of the request; running it needs the model (the variant
 * of the equations, or the co-simulation built per point) and cannot fail
 * on the request's syntax except for the `of modes` options h= and
 * reference=, whose expressions are evaluated per point at run time.
 *
 *   sweep NAME from A to B steps K [log] [of radius|modes|stability] [at NAME=VALUE, ...]
 *         [h=EXPR reference=EXPR[,EXPR]]
 *   map NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]
 *
 * One engine computes every sweep and map (src/analysis/sweep_engine.c over
 * src/numeric/engine.c and grid.c): the grid (rs_grid_value), the shard of
 * the points (--shard), the point limit (--max-points), the per-point verdict
 * codes, the CSV columns, the JSON summary, OpenMP/MPI and progress; the
 * model kind supplies only the verdict at a point (rs_sweep_model_t):
 *   equations          src/analysis/sweep_poly.c (p evaluated exactly, the
 *                      ladder of ladder.h, semisimplicity for systems)
 *   co-simulation      src/analysis/analysis_cosim.c (exact integration: the
 *                      certified radius; RS_SWEEP_UNDECIDED where it
 *                      cannot tell |lambda| from 1)
 *   matrix recurrence  has no sweep or map (numeric entries, radius and
 *                      stability only). */
#ifndef RECSTAB_ANALYSIS_SWEEP_IMPL_H
#define RECSTAB_ANALYSIS_SWEEP_IMPL_H

#include <stdio.h>
#include <flint/fmpq.h>
#include "analysis/impl.h"
#include "recstab/sweep.h"
#include "recstab/radius.h"

enum { RS_SWEEP_OF_RADIUS = 0, RS_SWEEP_OF_STABILITY = 1, RS_SWEEP_OF_MODES = 2 };
enum { RS_SWEEP_KIND_SWEEP = 0, RS_SWEEP_KIND_MAP = 1 };

typedef struct {
    char name[80];        /* the parameter */
    slong var;            /* its index in the case's parameters */
    fmpq_t from, to;      /* A, B */
    slong count;          /* sweep: K steps (K + 1 points); map: K points */
    const char *at;       /* the name in the request text (errors point here) */
    const char *from_at;  /* A in the request text */
} rs_sweep_axis_t;

typedef struct {
    int kind;             /* RS_SWEEP_KIND_* */
    slong naxes;          /* 1 (sweep) or 2 (map) */
    rs_sweep_axis_t axis[2];
    int logsp;            /* sweep: log spacing */
    int of;               /* RS_SWEEP_OF_* */
    const char *opts;     /* `of modes` options in the request text, or NULL */
    rs_assign_t *at;      /* sweep ... at NAME=VALUE, ...: values for this sweep only */
    slong nat;
} rs_sweep_request_t;

void rs_sweep_request_init(rs_sweep_request_t *r);
void rs_sweep_request_clear(rs_sweep_request_t *r);

/* Parse the text after `sweep` / `map` (rest, inside q->text) into r
 * (initialised); errors at the request's file:line:col, RS_ERR_INPUT or
 * RS_ERR_LIMIT (more points than run->opt->sweep.max_points).  The same
 * grammar serves every model kind: rs_map_request_parse is the map of the
 * equations and of exactly integrated co-simulations alike, except that
 * the co-simulation has no `of modes` (it never had: maps have none). */
int rs_sweep_request_parse(rs_sweep_request_t *r, rs_run_t *run, const rs_request_t *q, const char *rest);
int rs_map_request_parse(rs_sweep_request_t *r, rs_run_t *run, const rs_request_t *q, const char *rest);

/* A map's boundary overlay ("boundary", "boundary_table", "boundary_rows")
 * from the zero sets of the distinct irreducible factors of g[0..ng) (in
 * v's zctx, only R's axes free; origin[k] names g[k]): exact signs at the
 * grid points xs[0] x xs[1], crossings interpolated, as the map of p does;
 * every factor is drawn (no decomposition of the plane) */
void rs_an_map_boundary_factors(json_t *o, rs_run_t *run, const rs_variant_t *v, const rs_sweep_request_t *R,
                                fmpq *const *xs, const fmpz_mpoly_struct *g, char *const *origin, slong ng,
                                const char *method);

/* Run a parsed request: appends one JSON element to run->results. */
int rs_an_sweep_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *r);
int rs_an_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *r);
/* the map of a case whose subsystems are integrated exactly (analysis_cosim.c) */
int rs_an_cosim_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *r);

/* ---- the engine (sweep_engine.c), shared by the model kinds ---------------------- */

#define RS_SWEEP_MAX_REFS 4      /* references of `of modes` */

/* Verdict codes of the CSV `code` column: rs_status_t (0 stable, 1 marginal,
 * 2 unstable, 3 singular), -1 undefined (p vanishes identically there), and
 * RS_SWEEP_UNDECIDED: a model with numerics only (exact integration) whose
 * certified radius interval contains 1 -- not "marginal", which is an exact
 * verdict (roots on the circle, all semisimple). */
#define RS_SWEEP_UNDECIDED 4

/* The result of one point. */
typedef struct {
    rs_sweep_point_t d;                 /* verdict, level, radius bounds */
    int inside, on, outside;            /* exact counts (of stability sweeps), else -1 */
    int nmodes;                         /* references found */
    /* damping ratio, frequency error, omega per reference: certified
     * [mode_lo, mode_hi] (doubles rounded outward); NAN when not found */
    double mode_lo[3 * RS_SWEEP_MAX_REFS], mode_hi[3 * RS_SWEEP_MAX_REFS];
    char cells[128];                    /* "radius,lower,upper" written by the model, or empty:
                                           from d (inside the row: rows travel as bytes, MPI) */
} rs_sweep_row_t;

/* A model kind: the verdict at grid point idx (index = j*K1 + i of a map). */
typedef struct {
    void (*point)(rs_sweep_row_t *row, slong idx, void *model, rs_error_t err);
    void *model;
    int serial;                         /* not thread-safe: one point after another, no MPI split */
} rs_sweep_model_t;

double rs_sweep_now(void);
/* The modes columns of a sweep row from the certified roots rr of one point
 * (sweep_poly.c): per reference the damping ratio, frequency error and
 * omega of its principal root (Im >= 0) for the step h, bounds rounded
 * outward; the polynomial and the co-simulation sweeps of modes share it */
void rs_sweep_row_modes(rs_sweep_row_t *row, const rs_radius_t rr, const fmpq_t h, const fmpq *refs, slong nref);
/* errors at the request: more than --max-points points; more than the budget allows */
int rs_sweep_limit_error(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc);
int rs_sweep_estimate(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc);
/* the same for a map (less memory per point when streamed: table_spool) */
int rs_sweep_estimate_map(rs_run_t *run, const rs_request_t *q, double npoints);
/* "points", "computed", "shard", "row_range" ([lo, hi) of the shard) */
void rs_sweep_json_shard(json_t *o, const rs_run_t *run, slong npoints, slong lo, slong hi);
/* o[key]: the rows of a CSV table (header line, then rows) as arrays of
 * cells in the order of its columns (numbers, null for empty cells,
 * strings for text and the exact NAME_exact columns); only the first cap
 * rows when cap >= 0, and then o[key + "_omitted"]: how many were left out. */
void rs_sweep_json_rows(json_t *o, const char *key, const char *table, slong cap);
/* The same one row at a time: the flags of a header line of n bytes (which
 * columns are NAME_exact; malloc'd), and the row of the n bytes at line
 * (no newline) as its JSON array. */
char *rs_sweep_exact_columns(const char *header, size_t n);
json_t *rs_sweep_json_row(const char *line, size_t n, const char *exact);
/* Columns of reals: the flags of rs_sweep_exact_columns with the columns
 * listed in real (a JSON array of 0-based indices) marked
 * RS_SWEEP_COL_REAL, whose numeric cells are JSON reals even when written
 * without a point ("-2": -2.0).  A spooled table's "rows" {"spool": id,
 * "count": N, "real": [...]} carries them to rs_run_json_dumps_spool;
 * rs_sweep_json_rows_typed is rs_sweep_json_rows with them. */
#define RS_SWEEP_COL_REAL 3
void rs_sweep_flag_real(char *flags, const json_t *real);
void rs_sweep_json_rows_typed(json_t *o, const char *key, const char *table, slong cap, const json_t *real);
/* The compact JSON text of rs_sweep_json_row(line, n, exact) (what
 * json_dumps(JSON_COMPACT) prints for it, byte for byte) written to f
 * without building the jansson values: 0, or -1 with nothing written when
 * a text cell would need escaping or a UTF-8 check (then dump the row). */
int rs_sweep_json_row_put(FILE *f, const char *line, size_t n, const char *exact);
/* "verdicts", "decided_by", "seconds", "threads", "csv" of the rows of T
 * (rs_sweep_map_table, which counts them block by block) */
typedef struct rs_sweep_table_struct rs_sweep_table_t;
void rs_sweep_json_summary(json_t *o, const rs_sweep_table_t *T, double seconds);
/* {NAME: value} of the case's set values except keep[] */
json_t *rs_sweep_json_sets(rs_run_t *run, const char *const *keep, slong nkeep);
/* The rest of a map run for every model kind: the shard of the grid
 * xs[0] x xs[1] computed by m block by block, its map element, then
 * decorate(o, arg) when not NULL (the boundary), the timings since t0, and
 * the element appended to the run's results. */
typedef void (*rs_sweep_decorate_fn)(json_t *o, void *arg);
int rs_sweep_map_finish(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R, const rs_sweep_model_t *m,
                        const fmpq *const *xs, double t0, rs_sweep_decorate_fn decorate, void *arg);
/* A table with its own columns (a 1-D sweep, the z-plane map of
 * an_complex.c) on the maps' engine and block loop: the run's shard
 * [lo, hi) of npoints points computed by m block by block (OpenMP, budget,
 * progress; a point's error is recomputed serially for its message and put
 * at the request, "at point N (desc): ..."), header (a CSV line with its
 * newline) then each block written by put(f, rows, b, bhi, arg) to the
 * run's table spool (spool: its id, text NULL) or in memory (text, spool
 * -1); verdicts: stable, marginal, unstable, undefined, singular,
 * undecided; levels: the deciding levels RS_LEVEL_* of the defined ones.
 * Only one block of rows is held, whatever npoints. */
typedef void (*rs_sweep_rows_fn)(FILE *f, const rs_sweep_row_t *rows, slong lo, slong hi, void *arg);
struct rs_sweep_table_struct {
    slong lo, hi;
    slong verdicts[6];
    slong levels[6];
    char *text;
    slong spool;
};
int rs_sweep_map_table(rs_sweep_table_t *T, rs_run_t *run, const rs_request_t *q, const rs_sweep_model_t *m,
                       slong npoints, const char *what, const char *desc, const char *header, rs_sweep_rows_fn put,
                       void *arg);
void rs_sweep_table_clear(rs_sweep_table_t *T);
/* T's "table" and "rows" (the first cap, rs_sweep_json_rows) in memory, or
 * spooled "table_spool" and "rows" {"spool": id, "count": N}, with
 * "rows_omitted" past cap (as a map's) */
void rs_sweep_table_json(json_t *o, const rs_sweep_table_t *T, slong cap);
/* the CSV header line of the column names cols, with its newline (malloc'd; NULL: no memory) */
char *rs_sweep_header_line(const json_t *cols);
/* table cells */
void rs_sweep_put_radius(FILE *f, const rs_sweep_row_t *row);
void rs_sweep_put_certified(FILE *f, double lo, double hi);
const char *rs_sweep_verdict_name(int code);
void rs_sweep_put_fmpq(FILE *f, const fmpq_t x);          /* exact: p/q */
void rs_sweep_put_double_of(FILE *f, const fmpq_t x);     /* %.15g */

/* ---- complex set values: p over Q(i) per point (sweep_poly.c) ------------------------ */

/* The model of a sweep or map at complex set values: p = re + i im with the
 * values substituted (rs_run_cx_poly), the axes left.  A point: complex
 * Schur-Cohn and Bilharz (rs_routh_complex_checked_status, must agree) and
 * p's own counts (must agree); at every stride-th point (0: none) also the
 * certified ladder on p conj(p) (stable iff p is; unstable when p is),
 * a disagreement exit 3; `of radius`: the certified radius of p conj(p). */
typedef struct {
    const rs_scheme_struct *s;
    fmpz_mpoly_t re, im;
    slong n, naxes, var[2], K1, max_prec, stride;
    slong zeros;              /* det's roots at 0 divided out of p (counted inside) */
    const fmpq *vals[2];      /* axis values (read, not copied) */
    const char *names[2];
    int of;
    json_t *csat;             /* the complex set values (rs_run_cx_at), for the JSON */
    /* `of modes` (sweeps): per point the step and the references, p's own roots over Q(i) */
    slong npoints, nref;
    fmpq *hval, *refval;
} rs_sweep_cx_t;
/* p over Q(i) of v, checked: no axis has a complex value, every other
 * parameter is set, the degree does not drop for every point; errors at q */
int rs_sweep_cx_init(rs_sweep_cx_t *J, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                     const rs_variant_t *v);
void rs_sweep_cx_clear(rs_sweep_cx_t *J);
/* `of modes`: the options h= and reference= of R at the npoints values vals
 * of the swept parameter (as for real sweeps) */
int rs_sweep_cx_modes(rs_sweep_cx_t *J, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                      const rs_variant_t *v, const fmpq *vals, slong npoints);
void rs_sweep_cx_point(rs_sweep_row_t *pt, slong idx, void *model, rs_error_t err);
/* {NAME: "a+b*i"} of the complex set values */

/* ---- the model of exact integration (analysis_cosim.c) ------------------------------ */

/* The co-simulation model of a sweep over vals[0 .. K] (read, not copied):
 * m->model allocated (rs_cosim_sweep_model_free), or an error in run->err
 * at its place in the case (forms not built, a parameter still symbolic). */
int rs_cosim_sweep_model_new(rs_sweep_model_t *m, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                             const fmpq *vals, slong npoints);
void rs_cosim_sweep_model_free(rs_sweep_model_t *m);
/* `of modes`: the number of references, and the certified eigenvalues of
 * points [lo, hi) (one array of strings per point, null where not isolated) */
slong rs_cosim_sweep_nref(const rs_sweep_model_t *m);
json_t *rs_cosim_sweep_eigenvalues(const rs_sweep_model_t *m, slong lo, slong hi);

/* ---- the model of the equations (sweep_poly.c) ------------------------------------- */

/* the variant at every set value but the request's axes (analysis_sweep.c) */
int rs_sweep_variant(rs_variant_t **v, rs_run_t *run, const rs_sweep_request_t *R);

typedef struct rs_sweep_poly_struct rs_sweep_poly_t;
/* The model of variant v along the request's axes (values xs[0], xs[1]):
 * NULL with the error at the request when a parameter other than the axes
 * is still symbolic or the `of modes` options are wrong. */
int rs_sweep_poly_new(rs_sweep_poly_t **J, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                      const rs_variant_t *v, const fmpq *const *xs, slong npoints);
void rs_sweep_poly_free(rs_sweep_poly_t *J);
void rs_sweep_poly_model(rs_sweep_model_t *m, rs_sweep_poly_t *J);
slong rs_sweep_poly_nref(const rs_sweep_poly_t *J);

/* ---- request parsing helpers (sweep_request.c) ------------------------------------ */

extern const char *const rs_sweep_of_names[3];   /* "radius", "stability", "modes" */

#endif
