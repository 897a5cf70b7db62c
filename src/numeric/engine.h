/* numeric/engine.h -- the point loop of every sweep and map (private).
 *
 * The points [lo, hi) of a shard are computed into an array of per-point
 * results by a callback (the model kind's "verdict at this point"), with
 * OpenMP (every thread of omp_get_max_threads) and, built with -DRS_MPI,
 * split over the MPI ranks in contiguous blocks and gathered on every rank
 * (MPI_Allgatherv of the bytes), so every rank holds every result.  The
 * results do not depend on the thread or rank count.  Once the run's budget
 * (budget.h) is exceeded the remaining points are skipped: the caller checks
 * rs_budget_exceeded() afterwards. */
#ifndef RECSTAB_NUMERIC_ENGINE_H
#define RECSTAB_NUMERIC_ENGINE_H

#include <stddef.h>
#include <flint/flint.h>

/* Writes the result of point idx into *pt (size bytes, zeroed before). */
typedef void (*rs_engine_point_fn)(void *pt, slong idx, void *arg);
typedef void (*rs_engine_progress_fn)(void *arg, const char *what, slong done, slong total);

typedef struct {
    rs_engine_point_fn point;
    void *arg;
    int serial;           /* one point after another, in every process (the callback
                             is not thread-safe, or its results hold pointers) */
    rs_engine_progress_fn progress;   /* NULL: none; else at the start (done 0), at most every 0.2 s, and at the end */
    void *progress_arg;
    const char *what;     /* "sweep w", "map x,y": for progress and budget messages */
    /* a block of a longer loop (maps computed block by block): progress
     * counts done0 points before [lo, hi) out of total (0: [lo, hi) is all) */
    slong done0, total;
} rs_engine_t;

/* Points [lo, hi) into pts[0 .. hi-lo) (size bytes each). */
void rs_engine_run(void *pts, size_t size, slong lo, slong hi, const rs_engine_t *e);

#endif
