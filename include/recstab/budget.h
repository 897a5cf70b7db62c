/* budget.h -- the resource budget of a run: wall time and memory.
 *
 * rs_analysis_run starts the budget of rs_options_t (time_limit seconds,
 * memory_limit MB) and the long loops (determinant, Routh/Hurwitz rows, root
 * refinement, claims, sweeps and maps, simulate) call rs_budget_check; work
 * whose size is known in advance is estimated first (rs_budget_estimate).
 * Exceeding the budget is RS_ERR_LIMIT with a message naming the limit.
 *
 * State (documented global): one budget is active per process, as the
 * memory it counts is the process's.  Memory is counted by wrapping the
 * GMP and FLINT allocators (installed on the first rs_budget_start; they
 * forward to malloc and count malloc_usable_size), so blocks allocated
 * before are only approximately counted.  Each thread keeps a small cache
 * of freed blocks of up to 248 bytes (64 per size) that it hands out again;
 * those stay counted as used until they go back to malloc.  Every field is atomic: checks are
 * safe from OpenMP workers.  Once a limit is hit the budget stays exceeded
 * until the next rs_budget_start, so every loop stops at its next check. */
#ifndef RECSTAB_BUDGET_H
#define RECSTAB_BUDGET_H

#include <time.h>
#include <flint/flint.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_BUDGET_TIME_DEFAULT 600.0   /* seconds */

/* half of the machine's RAM in MB (1024 if unknown) */
slong rs_budget_memory_default(void);

/* Starts a budget: time_limit seconds of which spent are already used (by
 * the caller's earlier work) and memory_limit MB of counted memory (<= 0:
 * no limit). */
void rs_budget_start(double time_limit, double spent, slong memory_limit);
/* Ends the budget (no limits until the next start). */
void rs_budget_stop(void);

/* RS_OK, or RS_ERR_LIMIT with "time limit of T s reached during WHAT; raise
 * it with --time-limit" (or the memory limit) in err (err may be NULL). */
int rs_budget_check(rs_error_t err, const char *what);
/* RS_OK, or RS_ERR_LIMIT if WHAT, estimated at seconds and bytes, would not
 * fit into what is left of the budget (the message gives the estimate). */
int rs_budget_estimate(rs_error_t err, const char *what, double seconds, double bytes);
/* Estimated seconds of fmpz_mpoly_mul(a, b): la lb term pairs (FLINT's heap
 * multiplication), about 4e-10 s per pair and limb of the result's
 * coefficients (measured: 34 000 x 34 000 terms of 110-bit coefficients in
 * 1.8-2.2 s, Debian 12, FLINT 2.9).  For rs_budget_estimate before products
 * that cannot be interrupted. */
double rs_budget_mpoly_mul_seconds(const fmpz_mpoly_t a, const fmpz_mpoly_t b);
/* A cost estimate calibrated on the work already done (rows of a
 * fraction-free recursion): begin returns raw times scale and starts the
 * clock, end sets scale = max(1, measured CPU / raw) when the step took at
 * least 0.05 s (the multiplication estimate runs 14-25x low on sparse
 * many-parameter rows and is right on dense ones; issue 17). */
typedef struct { double scale, raw; clock_t c0; } rs_budget_calib_t;
void rs_budget_calib_init(rs_budget_calib_t *c);
double rs_budget_calib_begin(rs_budget_calib_t *c, double raw);
void rs_budget_calib_end(rs_budget_calib_t *c);
/* 1 once a limit was hit (sticky until the next start); its message. */
int rs_budget_exceeded(void);
int rs_budget_error(rs_error_t err);

/* seconds since the start, counted bytes in use */
double rs_budget_elapsed(void);
slong rs_budget_memory_used(void);

/* Called (if set) when one allocation would pass the memory limit, before
 * FLINT would abort on a failed malloc: the command prints the message and
 * ends the process (the library itself never exits). */
void rs_budget_set_fatal(void (*fatal)(const char *msg));

#ifdef __cplusplus
}
#endif
#endif
