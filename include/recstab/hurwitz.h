/* hurwitz.h -- Hurwitz minors and Lienard-Chipart conditions of the
 * bilinear polynomial q(z; params), exactly, factored over Q.
 *
 * With q = a_n z^n + ... + a_0 and a_n > 0, all roots of q have Re z < 0 iff
 * (Lienard-Chipart) a_0, a_2, a_4, ... > 0 (constant term and every other
 * coefficient from it) and D_{n-1}, D_{n-3}, ... > 0.  The Hurwitz matrix has
 * entry a_{n-(2j-i)} in row i, column j (1-based; 0 outside 0..n), so
 * D_1 = a_{n-1}, D_2 = a_{n-1} a_{n-2} - a_n a_{n-3}.  The minors D_1..D_n
 * are the Bareiss pivots of the Hurwitz matrix, computed fraction-free over
 * Z[params] by the equivalent fraction-free Routh scheme; past an
 * identically-zero pivot each further D_k is a determinant computed by
 * Bareiss with row pivoting.  Each condition
 * is factored (fmpz_mpoly_factor); factors that are positive under the
 * case's sign assumptions are dropped and listed as such. */
#ifndef RECSTAB_HURWITZ_H
#define RECSTAB_HURWITZ_H

#include <flint/flint.h>
#include <flint/fmpz_mpoly.h>
#include <flint/fmpz_mpoly_factor.h>
#include <flint/fmpq.h>
#include "recstab/error.h"
#include "recstab/cond.h"   /* rs_sign_t */

#ifdef __cplusplus
extern "C" {
#endif

/* One condition "poly > 0" (or ">= 0" for the non-strict variants), with its
 * factorisation: constant * prod factor[i]^exp[i]. */
typedef struct {
    fmpz_mpoly_t poly;             /* the condition polynomial */
    char *origin;                  /* e.g. "a_0", "D_3" (malloc'd) */
    fmpz_mpoly_factor_t factors;   /* factorisation over Z */
    int *dropped;                  /* per factor: 1 if positive under assumptions
                                      (or provably negative: its sign is then
                                      folded into reduced) */
    int *even;                     /* per factor: 1 if its exponent is even; a
                                      kept even factor must only be non-zero */
    fmpz_mpoly_t reduced;          /* +-(product of the kept odd-exponent factors,
                                      each to the first power): where the kept
                                      even factors are non-zero, poly > 0 iff
                                      reduced > 0; +-1 or 0 when none is kept */
    int trivially_true;            /* every factor dropped, sign positive:
                                      condition always holds */
    int trivially_false;           /* reduced is a non-positive constant */
    int not_expanded;              /* a minor D_k left unexpanded (its row did
                                      not fit the expansion budget or the row share):
                                      poly, reduced are 0 and factors empty;
                                      its sign at a point comes from the Hurwitz
                                      matrix evaluated there (fmpq_mat_det) */
    slong minor;                   /* k for a condition D_k, else 0 */
    int factored;                  /* 1: factors is FLINT's full factorisation;
                                      0: only the cheap steps were affordable
                                      (integer content, monomial factors, trial
                                      division by the factors of the other
                                      conditions): the last factor is the
                                      cofactor, not factored, possibly reducible
                                      or with square factors -- the condition is
                                      still equivalent (issue 17) */
    int poly_shared;               /* 1: poly is the minor D_minor itself (the
                                      rs_hurwitz_struct's minors[minor - 1],
                                      not a copy: read only, cleared with the
                                      minors; issue 17) */
} rs_hurwitz_cond_struct;

#define RS_HURWITZ_NOTE_LEN 300

typedef struct {
    slong n;                       /* degree of q in z */
    fmpz_mpoly_struct *coeffs;     /* a_0 .. a_n (length n+1), params only */
    fmpz_mpoly_struct *minors;     /* D_1 .. D_n stored at [0 .. n-1] */
    slong expanded;                /* D_1 .. D_expanded are expanded; the later
                                      minors are 0 here and not expanded */
    slong ncond;
    rs_hurwitz_cond_struct *cond;  /* Lienard-Chipart conditions, in order:
                                      a_n, a_0, a_2, ..., D_{n-1}, D_{n-3}, ... */
    int negated;                   /* 1 if q was negated (a_n provably < 0
                                      wherever non-zero); coeffs, minors and
                                      conditions are those of -q then */
    int route;                     /* how the minors were formed: 0 directly
                                      over Z[params], 1 over the smaller
                                      coefficient ring of the substitution
                                      route (issue 17) */
    char limit_note[RS_HURWITZ_NOTE_LEN];
                                   /* "" or the budget's message when what is
                                      left of the time or memory budget (not
                                      the row share) left a minor unexpanded
                                      or a condition unfactored: the one
                                      decision that depends on the clock */
    char stop_note[RS_HURWITZ_NOTE_LEN];
                                   /* "" or which step the row share or the
                                      expansion budget stopped (the Routh row
                                      or the composition of which D_k, its
                                      estimate, which limit): deterministic */
    double expand_estimate;        /* the cost model's seconds for the
                                      expansion steps taken (Routh rows and
                                      compositions; rs_hurwitz_set_expand_seconds) */
    /* issue 17: on the substitution route (route 1), the minors not
       expanded, exactly over the small ring (x_v, G_1..G_s) by evaluation and
       interpolation (rs_hurwitz_set_small_terms):
       D_k = small[k-1](x_v, G) / small_L^k with x_v, G_r = small_img[0..s]
       (polynomials in ctx); small[k-1] is zero for the expanded minors.
       NULL small_ctx: none.  Their signs decide the not-expanded conditions
       at points (rs_hurwitz_minor_sign_at). */
    fmpz_mpoly_ctx_struct *small_ctx;
    fmpz_mpoly_struct *small;      /* n entries in small_ctx */
    fmpz_mpoly_struct *small_img;  /* small_nvars entries in ctx */
    slong small_nvars;
    fmpz_t small_L;
} rs_hurwitz_struct;
typedef rs_hurwitz_struct rs_hurwitz_t[1];

/* Per-row share of the budget (seconds; none by default, a negative value
 * restores that): a fraction-free Routh row or a composition of the
 * substitution route whose estimated cost (a fixed model of term counts,
 * degrees and coefficient sizes, never the clock:
 * rs_budget_mpoly_mul_seconds, 30x for heap products; issue 17) exceeds it,
 * or what is left of the budget (then limit_note), is not formed; that minor
 * and the later ones stay unexpanded (issue 17).  The share also bounds a
 * condition's full factorisation (2 s when none is set).  Setting a share
 * without an expansion budget turns the default expansion budget off (the
 * share alone decides, as before h-chain13).  Returns the previous value.
 * Documented global, like the budget itself (one run per process). */
double rs_hurwitz_set_row_seconds(double seconds);

/* Default expansion budget, model seconds: N = 6 of the chain of
 * bench/make_chain_case.sh is fully expanded within it (issue 17, h-chain13). */
#define RS_HURWITZ_EXPAND_SECONDS 6.0

/* Expansion budget (model seconds) over the whole set of minors of one
 * computation: a Routh row or composition is formed only while the cost
 * model's estimates of all expansion steps so far plus its own stay within
 * it (h->expand_estimate; fixed formulas, never the clock); otherwise that
 * minor and the later ones stay unexpanded and stop_note names the budget.
 * A negative value (the default) means RS_HURWITZ_EXPAND_SECONDS when no row
 * share is set and no expansion budget when one is.  Returns the previous
 * value.  Documented global like rs_hurwitz_set_row_seconds. */
double rs_hurwitz_set_expand_seconds(double seconds);

/* The substitution route of the minors (issue 17): when the coefficients of
 * q with respect to one parameter span a small space, the minors are formed
 * over Z[that parameter, a basis of the span] and composed back; chosen by
 * its cost estimate (1, the default), never (0: the direct route only,
 * for cross-checks) or whenever it applies (2, for tests).  Returns the previous value.  Documented global
 * like rs_hurwitz_set_row_seconds. */
int rs_hurwitz_set_subst(int on);

/* How the substitution route composes its minors back: 1 (default) by
 * Horner's scheme in a fixed variable order with the powers of the images
 * cached across all minors (issue 17, h-chain15), 0 by FLINT's
 * fmpz_mpoly_compose_fmpz_mpoly (cross-checks; the same polynomials).
 * Returns the previous value.  Documented global like rs_hurwitz_set_subst. */
int rs_hurwitz_set_compose(int cached);
/* Largest candidate support (monomials) of a minor left unexpanded on the
 * substitution route for which it is still formed exactly over the small
 * ring by evaluation and interpolation (h->small); 0 = never.  Default
 * 300000 (the 8-mass chain's D_15 has 251 330 candidates, about 100 s).
 * Returns the previous value. */
slong rs_hurwitz_set_small_terms(slong terms);

/* A condition of more than this many terms (default 200 000), or whose full
 * factorisation's estimate does not fit the row share (2 s when none is set) or what is left of
 * the budget, gets only the cheap factoring steps (issue 17; cond->factored
 * = 0).  0 forces the cheap steps everywhere (tests).  Returns the previous
 * value.  Documented global like rs_hurwitz_set_row_seconds. */
slong rs_hurwitz_set_factor_terms(slong terms);

/* Sign of the leading principal k x k minor of the Hurwitz matrix of h's
 * coefficients at the rational point vals: substituted first, then an exact
 * rational determinant (for the unexpanded minors). */
int rs_hurwitz_minor_sign_at(const rs_hurwitz_t h, slong k, fmpq *const *vals,
                             const fmpz_mpoly_ctx_t ctx);

void rs_hurwitz_init(rs_hurwitz_t h);
void rs_hurwitz_clear(rs_hurwitz_t h, const fmpz_mpoly_ctx_t ctx);

/* q: polynomial in ctx whose variable `zvar` is z; the other variables are
 * parameters with sign information sign[v] (length ctx nvars; entry for zvar
 * ignored; sign may be NULL: all unknown).  If the leading coefficient a_n
 * is provably negative wherever it is non-zero, q is negated (h->negated);
 * in any case "a_n > 0" is the first condition (trivially true when a_n is
 * provably positive).  h must be initialised; previous contents are cleared
 * (same ctx).  Errors: RS_ERR_INPUT (zvar out of range, q = 0, degree 0 in
 * z), RS_ERR_LIMIT (degree > 256, factoring failed); h is then empty.
 * Returns RS_OK or the error code. */
int rs_hurwitz_compute(rs_hurwitz_t h, const fmpz_mpoly_t q, slong zvar,
                       const rs_sign_t *sign, const fmpz_mpoly_ctx_t ctx,
                       rs_error_t err);
/* As rs_hurwitz_compute, but minors whose Routh row would exceed the per-row
 * budget share stay unexpanded (h->expanded < h->n, their conditions marked
 * not_expanded, decided at points by rs_hurwitz_minor_sign_at) instead of
 * being a limit error; rs_hurwitz_compute returns RS_ERR_LIMIT then. */
int rs_hurwitz_compute_partial(rs_hurwitz_t h, const fmpz_mpoly_t q, slong zvar,
                               const rs_sign_t *sign, const fmpz_mpoly_ctx_t ctx,
                               rs_error_t err);
/* As rs_hurwitz_compute_partial, and the factors' sign tests also use the
 * intervals bounds[0..nbounds-1] of the first variables (the parameters; the
 * interval mapping of rs_positivity_sign_bounds, issue 17).  bounds may be
 * NULL. */
int rs_hurwitz_compute_partial_bounds(rs_hurwitz_t h, const fmpz_mpoly_t q, slong zvar,
                                      const rs_sign_t *sign, const rs_bound_t *bounds,
                                      slong nbounds, const fmpz_mpoly_ctx_t ctx,
                                      rs_error_t err);

/* 1 if poly is provably > 0 for all variable values allowed by sign[]
 * (sufficient test: every monomial's coefficient positive, every variable in
 * it non-negative or of unknown sign in an even power, and some term
 * provably positive: all its variables > 0), -1 if provably < 0 (same for
 * -poly), 0 otherwise (also for poly = 0; sign may be NULL).  Even powers
 * of arbitrary-sign factors are also handled at the factor level in
 * rs_hurwitz_compute. */
int rs_hurwitz_sign(const fmpz_mpoly_t poly, const rs_sign_t *sign,
                    const fmpz_mpoly_ctx_t ctx);

/* Stability conditions valid for every parameter value the signs allow: an
 * OR of Lienard-Chipart condition sets.  Lienard-Chipart needs a_n > 0; where
 * the assumptions do not fix the sign of a_n, the set of q (with "a_n > 0")
 * and the set of -q (with "-a_n > 0") are both needed.  Either excludes
 * a_n = 0 (p(-1) = 0, a root lambda = -1).  When q loses degree for every
 * value (degree_drop > 0: lambda = -1 is always a root) or z divides q for
 * every value (zero_mult > 0: lambda = 1 is always a root) there is no
 * branch: never asymptotically stable. */
typedef struct {
    slong nbranch;                 /* 0, 1 or 2 */
    rs_hurwitz_struct branch[2];   /* [0]: q (negated when a_n is provably
                                      negative); [1]: -q (negated = 1) */
    int alive[2];                  /* 0: a condition is trivially false */
    slong degree_drop;             /* degree - deg_z q when > 0 */
    slong zero_mult;               /* z^k | q for every value: k */
} rs_hurwitz_or_struct;
typedef rs_hurwitz_or_struct rs_hurwitz_or_t[1];

void rs_hurwitz_or_init(rs_hurwitz_or_t hb);
void rs_hurwitz_or_clear(rs_hurwitz_or_t hb, const fmpz_mpoly_ctx_t ctx);

/* The branches for q, where `degree` is the degree q has for generic
 * values (the degree of p in lambda).  A branch is kept when it can hold; if
 * none can, branch 0 is kept (alive[0] = 0) to show why.  Errors as
 * rs_hurwitz_compute (degree 0 in z is an error only when degree is 0). */
int rs_hurwitz_or_compute(rs_hurwitz_or_t hb, const fmpz_mpoly_t q, slong zvar,
                          slong degree, const rs_sign_t *sign,
                          const fmpz_mpoly_ctx_t ctx, rs_error_t err);
/* The same with the parameters' intervals (rs_hurwitz_compute_partial_bounds). */
int rs_hurwitz_or_compute_bounds(rs_hurwitz_or_t hb, const fmpz_mpoly_t q, slong zvar,
                                 slong degree, const rs_sign_t *sign,
                                 const rs_bound_t *bounds, slong nbounds,
                                 const fmpz_mpoly_ctx_t ctx, rs_error_t err);

/* The stated conditions (reduced > 0, kept even factors != 0, trivially
 * true ones skipped) at a rational point vals[v] (all variables; z's entry
 * ignored): 1 if every condition of some live branch holds, 0 if none,
 * -1 if a condition of a live branch vanishes there (a boundary point). */
int rs_hurwitz_or_holds(const rs_hurwitz_or_t hb, fmpq *const *vals,
                        const fmpz_mpoly_ctx_t ctx);

/* Hurwitz's criterion itself at a rational point (every D_1..D_n of the
 * rational Hurwitz matrix > 0 after making a_n > 0, by one elimination),
 * independent of the Lienard-Chipart selection, the factors and the symbolic
 * minors: 1 stable, 0 not, -1 if a_n vanishes there.  The hurwitz analysis
 * compares it with rs_hurwitz_or_holds at its sample points (exit 3 on
 * disagreement). */
int rs_hurwitz_or_full_at(const rs_hurwitz_or_t hb, fmpq *const *vals,
                          const fmpz_mpoly_ctx_t ctx);

/* poly at the rational point vals[v] (all variables), exactly. */
void rs_hurwitz_eval(fmpq_t out, const fmpz_mpoly_t poly, fmpq *const *vals,
                     const fmpz_mpoly_ctx_t ctx);
/* Sign (-1, 0, 1) of poly at the rational point vals[v] (all variables),
 * exact: from doubles when their certified error bound decides it, else
 * from rs_hurwitz_eval's exact sum. */
int rs_hurwitz_sign_at(const fmpz_mpoly_t poly, fmpq *const *vals,
                       const fmpz_mpoly_ctx_t ctx);

/* Hurwitz matrix entry convention and minors for display: D_k as strings
 * are produced by the report module with fmpz_mpoly_get_str_pretty. */

#ifdef __cplusplus
}
#endif
#endif
