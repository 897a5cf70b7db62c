/* sweep.h -- 1-D sweeps and 2-D stability maps (analyses `sweep` and `map`).
 *
 * The analyses themselves run through rs_analysis_run like every other
 * analysis; this header holds the settings they take from the run's options
 * (rs_options_t.sweep: sharding, the point limit, a progress callback) and
 * the per-point certified verdict used by them, for library users who want
 * it directly.
 *
 * Every point of a sweep or map gets a certified verdict from the ladder of
 * ladder.h (fast, prec128, prec256, exact), the exact rung being Routh on the
 * bilinear transform and Schur-Cohn (which must agree).
 *
 * Parallelism: the points are computed with OpenMP (every core unless
 * omp_set_num_threads / OMP_NUM_THREADS say otherwise) into per-point
 * results; tables and JSON are built serially afterwards, so the output does
 * not depend on the thread count.  With -DRS_MPI the points of each shard are
 * further split over the MPI ranks (contiguous blocks) and gathered on every
 * rank (MPI_Allgatherv), so every rank builds the same JSON.
 *
 * GSL's error handler: a program that runs sweeps or maps (rs_analysis_run)
 * or calls rs_sweep_decide switches it off once, before (the recstab command
 * does so at the start of main): GSL's default handler aborts the process
 * when the double root finder of the ladder fails, and the library does not
 * change process-wide state behind its caller's back. */
#ifndef RECSTAB_SWEEP_H
#define RECSTAB_SWEEP_H

#include <stdio.h>
#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include "recstab/error.h"
#include "recstab/ladder.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_SWEEP_MAX_POINTS_DEFAULT 4000000

typedef struct {
    slong shard_index;    /* I of --shard I/N (1-based) */
    slong shard_count;    /* N (1: no sharding) */
    slong max_points;     /* points per sweep or map (RS_ERR_LIMIT past it) */
    /* called from one thread at a time: once with done == 0 at the start, at most every ~0.2 s, and once with
     * done == total at the end; NULL for none.  what: "sweep w", "map x,y". */
    void (*progress)(void *arg, const char *what, slong done, slong total);
    void *progress_arg;
    /* benchmarking: the ladder starts at this level (RS_LEVEL_*; default
     * RS_LEVEL_FAST), or RS_LEVEL_DOUBLE: GSL double roots only, verdict
     * from max |root| vs 1 with no certificate (decided_by "double") */
    int first_level;
    /* rows of each sweep and map in the JSON document ("rows",
     * "boundary_rows"): all when < 0 (the default), else the first json_rows
     * and "rows_omitted" (--json-rows N) */
    slong json_rows;
    /* Maps streamed: when not NULL, called once per map; the map's CSV
     * table (header line, then each block of rows as soon as it is
     * computed) is written to the stream it returns (open for writing and
     * reading, owned by the caller) instead of being held in memory: the
     * map element then has "table_spool": the id the call stored in *id
     * and no "table"; its "rows" is {"spool": id, "count": N}, the first N
     * rows of the table, which rs_run_json_dumps_spool writes as the rows.
     * NULL (the default): "table" and "rows" in the element. */
    FILE *(*table_spool)(void *arg, slong *id);
    void *table_spool_arg;
} rs_sweep_options_t;

/* shard 1/1, RS_SWEEP_MAX_POINTS_DEFAULT, no progress, RS_LEVEL_FAST, every row.  The
 * options of a run are rs_options_t.sweep (analysis.h): no process-wide state. */
void rs_sweep_options_default(rs_sweep_options_t *o);

/* The rows of shard I/N (1-based) of npoints points: the contiguous block
 * [*lo, *hi) with lo = floor((I-1)*P/N), hi = floor(I*P/N). */
void rs_sweep_shard_range(slong *lo, slong *hi, slong npoints, slong I, slong N);

/* The certified verdict (and radius bounds when the deciding level isolated
 * every root) of the roots of p: rs_ladder_decide from RS_LEVEL_FAST with
 * Routh and Schur-Cohn as the exact rung; thread-safe for distinct
 * arguments.  GSL's error handler must be off (gsl_set_error_handler_off):
 * GSL's default handler aborts the process when its root finder fails. */
int rs_sweep_decide(rs_sweep_point_t *pt, const fmpz_poly_t p, rs_error_t err);

#ifdef __cplusplus
}
#endif
#endif
