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
 *   sweep NAME from A to B steps K [log] [of radius|modes|stability] [h=EXPR reference=EXPR[,EXPR]]
 *   map NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]
 *
 * One engine computes every sweep and map (src/analysis/sweep_engine.c): the
 * grid (rs_grid_value), the shard of the points (--shard), the point limit
 * (--max-points), the per-point verdict codes, the CSV columns, the JSON
 * summary; the model kind supplies only the verdict at a point. */
#ifndef RECSTAB_ANALYSIS_SWEEP_IMPL_H
#define RECSTAB_ANALYSIS_SWEEP_IMPL_H

#include <flint/fmpq.h>
#include "analysis/impl.h"
#include "recstab/sweep.h"

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

/* Run a parsed request: appends one JSON element to run->results. */
int rs_an_sweep_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *r);
int rs_an_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *r);
/* the map of a case whose subsystems are integrated exactly (analysis_cosim.c) */
int rs_an_cosim_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *r);

#endif
