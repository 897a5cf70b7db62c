/* ladder.h -- the certified verdict of one integer polynomial, decided by
 * the first level that can (src/numeric/ladder.c):
 *   fast     GSL double roots (gsl_poly_complex_solve), then the Newton
 *            inclusion disc n|p(m)/p'(m)| around each approximate root m,
 *            verified in double arithmetic with a priori rounding-error
 *            bounds, else by Arb at 64 bits on the EXACT integer polynomial
 *            (_acb_poly_validate_roots: pairwise disjoint discs hold exactly
 *            one root each).  Stable when all n discs are disjoint and inside
 *            the open unit disc; unstable when some disc lies outside the
 *            closed unit disc.
 *   prec128  acb_poly_find_roots at 128 bits seeded with the double roots,
 *            same test;
 *   prec256  the same at 256 bits;
 *   exact    the exact root count, which always decides (roots on the
 *            circle, repeated roots).  It is injected (rs_ladder_exact_fn):
 *            the numeric stage does not depend on the exact (stability)
 *            stage; sweep.h's rs_sweep_decide supplies Routh on the bilinear
 *            transform and Schur-Cohn.
 * Roots exactly on the circle (marginal) always end at the exact level. */
#ifndef RECSTAB_LADDER_H
#define RECSTAB_LADDER_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include <arb.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Certified verdict levels. */
enum { RS_LEVEL_FAST = 0, RS_LEVEL_PREC128 = 1, RS_LEVEL_PREC256 = 2, RS_LEVEL_EXACT = 3,
       RS_LEVEL_DOUBLE = 4, /* uncertified, benchmarking only */
       RS_LEVEL_CERTIFIED = 5 /* certified numerics with no exact side (maps of exactly
                                 integrated co-simulations), not a rung of this ladder */ };
extern const char *const rs_sweep_level_names[6]; /* "fast", "prec128", "prec256", "exact", "double", "certified" */

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

/* What the exact rung reports about p (roots counted with multiplicity). */
typedef struct {
    slong inside, on, outside;
    slong max_on_mult;   /* largest multiplicity of a root on the circle (0: none) */
    int status;          /* rs_status_t of p as a scalar recurrence */
} rs_ladder_count_t;

/* The exact rung: the counts of the primitive polynomial p; arg is the
 * caller's (e.g. where to keep its own form of the counts). */
typedef int (*rs_ladder_exact_fn)(rs_ladder_count_t *c, const fmpz_poly_t p, void *arg, rs_error_t err);

/* The verdict of p by the ladder, starting at first_level (RS_LEVEL_FAST for
 * the certified ladder; RS_LEVEL_DOUBLE: GSL double roots only, verdict from
 * max |root| vs 1 with no certificate).  Thread-safe for distinct arguments
 * when exact is; GSL's error handler must be off (gsl_set_error_handler_off,
 * done once at the start of the recstab command). */
int rs_ladder_decide(rs_sweep_point_t *pt, const fmpz_poly_t p, int first_level, rs_ladder_exact_fn exact,
                     void *arg, rs_error_t err);
/* The exact rung alone (p of degree >= 1): verdict, repeated_on and the
 * radius bounds the counts imply (exactly 1 with a root on the circle). */
int rs_ladder_decide_exact(rs_sweep_point_t *pt, const fmpz_poly_t p, rs_ladder_exact_fn exact, void *arg,
                           rs_error_t err);

/* A double below (above) every point of x, >= 0 for the lower bound. */
double rs_ladder_lower_d(const arb_t x);
double rs_ladder_upper_d(const arb_t x);

#ifdef __cplusplus
}
#endif
#endif
