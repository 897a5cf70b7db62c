/* sweep.h -- 1-D sweeps and 2-D stability maps (analyses `sweep` and `map`).
 *
 * The analyses themselves run through rs_analysis_run like every other
 * analysis; this header holds the settings they take from the run's options
 * (rs_options_t.sweep: sharding, the point limit, a progress callback) and
 * the per-point certified verdict used by them, for library users who want
 * it directly.
 *
 * Every point of a sweep or map gets a certified verdict, decided by the
 * first level that can:
 *   fast     GSL double roots (gsl_poly_complex_solve), then Arb root
 *            inclusion at 64 bits on the EXACT integer polynomial
 *            (_acb_poly_validate_roots: each disc n|p(m)/p'(m)| around an
 *            approximate root m holds a root; pairwise disjoint discs hold
 *            exactly one each).  Stable when all n discs are disjoint and
 *            inside the open unit disc; unstable when some disc lies outside
 *            the closed unit disc.
 *   prec128  acb_poly_find_roots at 128 bits seeded with the double roots,
 *            same test;
 *   prec256  the same at 256 bits;
 *   exact    Routh on the bilinear transform and Schur-Cohn (rs_run_exact_count),
 *            which always decides (roots on the circle, repeated roots).
 * Roots exactly on the circle (marginal) always end at the exact level.
 *
 * Parallelism: the points are computed with OpenMP (every core unless
 * omp_set_num_threads / OMP_NUM_THREADS say otherwise) into per-point
 * results; tables and JSON are built serially afterwards, so the output does
 * not depend on the thread count.  With -DRS_MPI the points of each shard are
 * further split over the MPI ranks (contiguous blocks) and gathered on every
 * rank (MPI_Allgatherv), so every rank builds the same JSON. */
#ifndef RECSTAB_SWEEP_H
#define RECSTAB_SWEEP_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_SWEEP_MAX_POINTS_DEFAULT 4000000

typedef struct {
    slong shard_index;    /* I of --shard I/N (1-based) */
    slong shard_count;    /* N (1: no sharding) */
    slong max_points;     /* points per sweep or map (RS_ERR_LIMIT past it) */
    /* called from one thread at a time, at most every ~0.2 s, and once with
     * done == total at the end; NULL for none.  what: "sweep w", "map x,y". */
    void (*progress)(void *arg, const char *what, slong done, slong total);
    void *progress_arg;
    /* benchmarking: the ladder starts at this level (RS_LEVEL_*; default
     * RS_LEVEL_FAST), or RS_LEVEL_DOUBLE: GSL double roots only, verdict
     * from max |root| vs 1 with no certificate (decided_by "double") */
    int first_level;
} rs_sweep_options_t;

/* shard 1/1, RS_SWEEP_MAX_POINTS_DEFAULT, no progress, RS_LEVEL_FAST.  The
 * options of a run are rs_options_t.sweep (analysis.h): no process-wide state. */
void rs_sweep_options_default(rs_sweep_options_t *o);

/* The rows of shard I/N (1-based) of npoints points: the contiguous block
 * [*lo, *hi) with lo = floor((I-1)*P/N), hi = floor(I*P/N). */
void rs_sweep_shard_range(slong *lo, slong *hi, slong npoints, slong I, slong N);

/* Certified verdict levels. */
enum { RS_LEVEL_FAST = 0, RS_LEVEL_PREC128 = 1, RS_LEVEL_PREC256 = 2, RS_LEVEL_EXACT = 3,
       RS_LEVEL_DOUBLE = 4 /* uncertified, benchmarking only */ };
extern const char *const rs_sweep_level_names[5]; /* "fast", "prec128", "prec256", "exact", "double" */

typedef struct {
    int status;          /* RS_OK, or the error code of this point */
    int verdict;         /* rs_status_t (0 stable, 1 marginal, 2 unstable, 3 singular); -1: p == 0 here */
    int level;           /* RS_LEVEL_* that decided */
    int isolated;        /* 1 when [rho_lower, rho_upper] came from isolating enclosures */
    double rho_lower;    /* certified: rho >= rho_lower (rounded down) */
    double rho_upper;    /* certified: rho <= rho_upper (rounded up; +inf unknown) */
    int repeated_on;     /* exact level: none outside, a repeated circle root (unstable
                            for a scalar recurrence; a system decides by semisimplicity) */
} rs_sweep_point_t;

/* The certified verdict (and radius bounds when the deciding level isolated
 * every root) of the roots of p, by the ladder above; thread-safe for
 * distinct arguments, but switch GSL's error handler off first
 * (gsl_set_error_handler_off) when calling from several threads. */
int rs_sweep_decide(rs_sweep_point_t *pt, const fmpz_poly_t p, rs_error_t err);

#ifdef __cplusplus
}
#endif
#endif
