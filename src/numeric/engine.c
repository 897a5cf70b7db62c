/* engine.c -- the point loop of every sweep and map (engine.h). */
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef RS_MPI
#include <mpi.h>
#endif
#include "recstab/budget.h"
#include "numeric/engine.h"
#include "numeric/grid.h"

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* this process's block [*mylo, *myhi) of [lo, hi): all of it without MPI */
static void my_block(slong *mylo, slong *myhi, slong lo, slong hi, int serial)
{
    *mylo = lo;
    *myhi = hi;
#ifdef RS_MPI
    {
        int mpi_on = 0, rank = 0, size = 1;
        MPI_Initialized(&mpi_on);
        if (mpi_on && !serial) {
            MPI_Comm_rank(MPI_COMM_WORLD, &rank);
            MPI_Comm_size(MPI_COMM_WORLD, &size);
            rs_grid_shard_range(mylo, myhi, hi - lo, rank + 1, size);
            *mylo += lo;
            *myhi += lo;
        }
    }
#else
    (void) serial;
#endif
}

/* every rank's block gathered on every rank */
static void gather(void *pts, size_t size, slong lo, slong hi, int serial)
{
#ifdef RS_MPI
    int mpi_on = 0, nranks = 1, rk;
    MPI_Initialized(&mpi_on);
    if (mpi_on) MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    if (mpi_on && nranks > 1 && !serial) {
        int *counts = malloc((size_t) nranks * sizeof(int)), *displs = malloc((size_t) nranks * sizeof(int));
        for (rk = 0; rk < nranks; rk++) {
            slong a, b;
            rs_grid_shard_range(&a, &b, hi - lo, rk + 1, nranks);
            counts[rk] = (int) ((b - a) * (slong) size);
            displs[rk] = (int) (a * (slong) size);
        }
        MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, pts, counts, displs, MPI_BYTE, MPI_COMM_WORLD);
        free(counts);
        free(displs);
    }
#else
    (void) pts; (void) size; (void) lo; (void) hi; (void) serial;
#endif
}

void rs_engine_run(void *pts, size_t size, slong lo, slong hi, const rs_engine_t *e)
{
    slong done = 0, mylo, myhi, k, total;
    double last = now_seconds(), scale;
    my_block(&mylo, &myhi, lo, hi, e->serial);
    /* a block of a longer loop reports the whole loop's points: this
     * process's share of the block scaled to the block */
    total = e->total > 0 ? e->total : myhi - mylo;
    scale = e->total > 0 && myhi > mylo ? (double) (hi - lo) / (double) (myhi - mylo) : 1.0;
#define ENGINE_DONE(d) (e->total > 0 ? e->done0 + (slong) ((double) (d) * scale) : (d))
    /* the start: the estimate of the time left counts from here */
    if (e->progress != NULL && myhi > mylo && (e->total <= 0 || e->done0 == 0)) e->progress(e->progress_arg, e->what, 0, total);
#pragma omp parallel for schedule(dynamic, 16) if (!e->serial)
    for (k = mylo; k < myhi; k++) {
        char *pt = (char *) pts + (size_t) (k - lo) * size;
        /* once the budget is exceeded the remaining points are skipped;
         * the caller reports the limit */
        if (rs_budget_check(NULL, e->what) != RS_OK) continue;
        memset(pt, 0, size);
        e->point(pt, k, e->arg);
        if (e->progress != NULL) {
            slong d;
#pragma omp atomic capture
            d = ++done;
#ifdef _OPENMP
            if (omp_get_thread_num() == 0)
#endif
            {
                double t = now_seconds();
                if (t - last > 0.2) {
                    last = t;
                    e->progress(e->progress_arg, e->what, ENGINE_DONE(d), total);
                }
            }
        }
    }
    gather(pts, size, lo, hi, e->serial);
    if (e->progress != NULL && (e->total <= 0 || e->done0 + (hi - lo) >= e->total))
        e->progress(e->progress_arg, e->what, total, total);
#undef ENGINE_DONE
}
