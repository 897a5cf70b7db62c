/* analysis/impl.h -- what the analysis files share: the run of a case and
 * its variants, the exact point verdict and the JSON helpers (run.c), the
 * symbolic stability conditions (conditions.c).  The one-analysis files
 * (an_*.c) include this and registry.h, never each other; the sweeps and
 * maps add sweep_impl.h.  Private: not installed. */
#ifndef RECSTAB_ANALYSIS_IMPL_H
#define RECSTAB_ANALYSIS_IMPL_H

#include <jansson.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include "recstab/analysis.h"
#include "recstab/scheme.h"
#include "recstab/charpoly.h"
#include "recstab/radius.h"
#include "recstab/rootcount.h"
#include "recstab/jury.h"
#include "recstab/cond.h"
#include "recstab/hurwitz.h"

typedef struct {
    char *key;            /* "name=value;..." of the substituted values */
    json_t *assigned;     /* the same as a JSON object */
    rs_scheme_t s;        /* scheme with those values substituted */
    rs_charpoly_t cp;
    int have_cp;
    int status;           /* RS_OK or the error building it */
    rs_error_struct err;  /* that error, given again with the cached variant */
    int singular;         /* the values drop the degree of det A in lambda:
                             the implicit step cannot be solved there */
    int vanishes;         /* the values make det A(lambda) vanish identically
                             (status RS_ERR_MATH): singular, no recurrence */
    json_t *not_in_p;     /* parameters given a placeholder value because p does
                             not depend on them (rs_run_numeric_variant), or NULL */
    json_t *valid_if;     /* with not_in_p: "f != 0" for the factors of p's
                             parameter content (p = 0 where one vanishes), or NULL */
} rs_variant_t;

typedef struct {
    const char *name;
    slong var;
    fmpq_t value;
} rs_assign_t;

typedef struct {
    const rs_case_struct *c;
    const rs_model_struct *m;  /* the case lowered, once per run */
    const rs_options_t *opt;
    rs_variant_t **variants;
    slong nvariants;
    json_t *results;
    int outcome;
    rs_error_struct *err;
    rs_scheme_t sym;      /* the case's scheme, all parameters symbolic */
    int have_sym;
    slong deg_lower;      /* degree of det A over Q(params) is >= this (-1: none known) */
    slong deg_exact;      /* ... and equals this (-1: not computed yet) */
} rs_run_t;

/* The case's set values except the parameters in keep[], overridden and
 * extended by extra[]. Free with rs_assign_free. */
int rs_run_assignments(rs_run_t *run, rs_assign_t **out, slong *nout,
                       const char *const *keep, slong nkeep,
                       const rs_assign_t *extra, slong nextra);
void rs_assign_free(rs_assign_t *a, slong n);
/* The variant at the case's set values with parameter tv kept symbolic; an
 * input error at `at` ("WHAT needs the other parameters set to numbers")
 * when another parameter is still free (run.c). */
int rs_run_variant_one_free(rs_variant_t **v, rs_run_t *run, const rs_request_t *q, const char *at, slong tv,
                            const char *what);
/* Cached: scheme + charpoly with the assignments substituted. */
int rs_run_variant(rs_variant_t **out, rs_run_t *run, const rs_assign_t *a, slong n);
/* Top degree in lambda of det A (the degree of p plus the power of lambda
 * split off). */
slong rs_charpoly_top_degree(const rs_charpoly_t cp);
/* *singular = 1 when a polynomial whose det has top degree `top` (after
 * substituting values) lost degree against det A over Q(params). */
int rs_run_is_singular(int *singular, rs_run_t *run, slong top);
/* The verdict at a point where every parameter is a number: the exact counts
 * rc of p, made "singular" when the step cannot be solved, and for a system
 * with a repeated circle root decided by the semisimplicity of the
 * lambda-matrix of v->s with vars[i] = vals[i] (i < nv) substituted.  Writes
 * "status" (and "singular", "circle_roots", "rule") into o when o != NULL. */
int rs_run_verdict(rs_status_t *st, rs_run_t *run, const rs_scheme_t s, const slong *vars,
                   const fmpq *vals, slong nv, const fmpz_poly_t p, const rs_rootcount_t rc,
                   int singular, json_t *o);

/* rs_run_verdict at the case's values for the counts rc of the numeric p:
 * the "status" of `jury` and `routh` as `stability` decides it (a system's
 * semisimple repeated circle root is marginal; a singular point singular),
 * not the scalar rule of the counts alone. */
int rs_run_numeric_verdict(rs_run_t *run, const fmpz_poly_t p, const rs_rootcount_t rc, json_t *o);

/* 1 when the point pp (every variable of s) satisfies the compiled
 * conditions cps and keeps every divisor of the equations non-zero. */
int rs_run_point_admissible(const rs_condpoly_t *cps, slong ncps, fmpq *const *pp, const rs_scheme_t s);

/* The exact verdict of variant v at vars[i] = vals[i] (i < nv), which set
 * every parameter still symbolic in v: p evaluated exactly, "singular"
 * where its degree in lambda drops or it vanishes identically, else the
 * counts rc (Routh and Schur-Cohn, which must agree)
 * judged by rs_run_verdict. */
/* w = v's characteristic polynomial with vars[k] = vals[k] (k < nv; vars
 * NULL: the variables 0..nv-1) as a polynomial in lambda; 0 when a
 * parameter is still symbolic. */
int rs_run_charpoly_at(fmpq_poly_t w, const rs_variant_t *v, const slong *vars, const fmpq *vals, slong nv);
int rs_run_point_status(rs_status_t *st, rs_rootcount_t rc, rs_run_t *run, const rs_variant_t *v,
                        const slong *vars, const fmpq *vals, slong nv);

/* The variant for analyses that need every parameter set: the default one,
 * except that parameters p does not depend on (they occur nowhere, or only in
 * p's parameter content) get a placeholder value keeping that content and the
 * non-zero assumptions non-zero; v->not_in_p names them. */
int rs_run_numeric_variant(rs_run_t *run, rs_variant_t **v);
/* Close an exact result o of variant v ("substituted", "decided_by":
 * "exact") and append it to the run's results (takes o). */
void rs_run_emit_exact(rs_run_t *run, const rs_variant_t *v, json_t *o);
/* v->vanishes: the `what` result at those values is "singular" with the
 * reason (as region lists such a point), run->err cleared; RS_OK. */
int rs_run_emit_vanishing(rs_run_t *run, const rs_variant_t *v, const char *what);
/* The numeric (numeric != 0) or default variant; where it vanishes the
 * `what` result is emitted as rs_run_emit_vanishing does and *done = 1. */
int rs_run_variant_or_vanishing(rs_variant_t **v, int *done, rs_run_t *run, const char *what, int numeric);
/* The status r of a failed variant request, or (when v says det A vanishes
 * identically there) the `what` result of rs_run_emit_vanishing and RS_OK:
 * `return rs_run_failed_or_vanishing(run, r, v, "modes");` */
int rs_run_failed_or_vanishing(rs_run_t *run, int r, const rs_variant_t *v, const char *what);
/* "status": "singular" and the reason, as stability says it, for a result
 * at set values where det A drops its degree in lambda (v->singular)
 * without vanishing: charpoly and modes print p of the reduced degree */
void rs_json_set_singular_step(json_t *o);

json_t *rs_json_fmpq(const fmpq_t q);
json_t *rs_json_zpoly(const fmpz_mpoly_t p, const rs_scheme_t s);
/* rs_json_zpoly's string, and in *line (if rel given) the condition line
 * "TEXT rel" (rs_cond_string's text) from the same printing; printed in
 * *scratch (size *cap, grown as needed, the caller frees it) when given, so
 * that a run printing many large polynomials reuses pages already touched. */
/* rs_json_zpoly_line, or placeholders printed when the report is written
 * (util/polytext.h) for a long p when run->opt->polytext is set: then p is
 * borrowed, unchanged until rs_run_polytext_keep takes it (and leaves 0) */
json_t *rs_run_json_zpoly_line(const rs_run_t *run, fmpz_mpoly_t p, const rs_scheme_t s, const char *rel,
                               json_t **line, char **scratch, size_t *cap);
void rs_run_polytext_keep(const rs_run_t *run);
json_t *rs_json_zpoly_line(const fmpz_mpoly_t p, const rs_scheme_t s, const char *rel, json_t **line,
                           char **scratch, size_t *cap);
/* "poly REL" for a condition (REL "> 0", "!= 0"); malloc'd, free(). */
char *rs_cond_string(const fmpz_mpoly_t p, const rs_scheme_t s, const char *rel);
json_t *rs_json_coeffs(const fmpz_mpoly_t p, slong var, const rs_scheme_t s);
json_t *rs_json_nonzero(const rs_scheme_t s);
json_t *rs_charpoly_json(const rs_variant_t *v);
void rs_compare_poly(json_t *o, const fmpq_mpoly_t expected, const fmpz_mpoly_t derived,
                     const fmpz_mpoly_t derived_raw, slong var, const rs_scheme_t s,
                     const char *varname);
/* p collected in powers of variable var, printed with the name varname. */
json_t *rs_json_collected(const fmpz_mpoly_t p, slong var, const rs_scheme_t s,
                          const char *varname);

#define RS_DIGITS_MAX 20000   /* digits= of radius requests */

/* The case's set values as {NAME: "p/q"}. */
json_t *rs_json_sets(const rs_case_t c);
/* A ball as a decimal string with only its certified digits (at most `digits`). */
json_t *rs_json_arb(const arb_t x, slong digits);
/* certified, lower, upper, rho, digits, precision_bits of a radius. */
void rs_json_radius(json_t *o, const rs_radius_t rr, slong digits);

const char *rs_req_skip_word(const char *t);
int rs_req_error(rs_run_t *run, const rs_request_t *q, const char *at, int code,
                 const char *fmt, const char *a);
void rs_req_src(rs_src_t *src, const rs_request_t *q);
/* An error from a library call that carries no place of its own: put at
 * the request, the message prefixed "what: ".  Returns code. */
int rs_req_relocate(rs_run_t *run, const rs_request_t *q, int code, const char *what);
/* The request's expression at text, at the case's set values and, when
 * var >= 0, at var = vals[i]: out[i * stride] for i < npoints (var < 0:
 * one value).  *end (unless NULL) is set past the expression.  A value
 * that still has a parameter or divides by zero is an error at text. */
int rs_req_eval_points(fmpq *out, slong stride, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v,
                       const char *text, slong var, const fmpq *vals, slong npoints, const char **end);



/* Simulate's cross-check (src/analysis/an_simulate.c): NULL when a measured
 * log growth per step over `steps` steps is compatible with the exact verdict
 * (status st, `outside` roots outside the circle, p of degree `degree`), else
 * why not; *tau is the threshold on |log growth| (see the source for why). */
const char *rs_simulate_disagreement(double *tau, rs_status_t st, slong outside, double log_growth, slong degree,
                                     slong steps);

/* Sign information for the parameters from the case's `assume` lines
 * (RS_SIGN_* of hurwitz.h per variable, lambda's entry unknown). */
int *rs_run_signs(rs_run_t *run, const rs_scheme_t s);
/* The parameters' intervals from the case's `assume` lines (params first,
 * nparams entries); free with rs_run_bounds_clear. */
rs_bound_t *rs_run_bounds(rs_run_t *run);
void rs_run_bounds_clear(rs_bound_t *b, rs_run_t *run);

/* {name: value} of a sample point pt (one fmpq per parameter, the first n) */
json_t *rs_run_point_json(const rs_run_t *run, fmpq *const *pt, slong n);

/* Symbolic conditions checked against the exact point verdict
 * (src/analysis/run.c): holds(data, point, s) is 1 (stable), 0 (not) or
 * -1 (a condition vanishes: skipped) at point[v] for every variable. */
typedef int (*rs_holds_fn)(const void *data, fmpq *const *point, const rs_scheme_struct *s);
int rs_run_sample_check(rs_run_t *run, const rs_variant_t *v, rs_holds_fn holds, const void *data, json_t *o);
/* Checks made by their own loops (over Q(i), over Q(sqrt d)): chk's first
 * disagreement (point, what the conditions say, the exact verdict), then
 * o's "sample_check" {points, agree, against, ...}; a disagreement marks
 * the run inconsistent (exit 3). */
void rs_run_sample_disagree(json_t *chk, json_t *point, int says, const char *verdict);
void rs_run_sample_check_set(rs_run_t *run, json_t *o, json_t *chk, slong points, int agree, const char *against);
/* The rational points of those loops: the parameters a or b depends on
 * (not lambda, not the variable skip) take small rationals of both signs,
 * 0 and a large one, mixed by a stride per parameter; the set values stand
 * in the others, so the assume lines on set parameters are checked too.
 * rs_sample_pts_next: 1 with the next admissible point in P->pp, 0 after
 * RS_SAMPLE_PTS_TRIES tries; rs_sample_pts_json: the free values. */
#define RS_SAMPLE_PTS_TRIES 200
typedef struct {
    const rs_scheme_struct *s;
    slong nfree, *fv, ncp, j;
    rs_condpoly_t *cps;
    fmpq *pt;
    fmpq **pp;
} rs_sample_pts_t;
void rs_sample_pts_init(rs_sample_pts_t *P, rs_run_t *run, const rs_variant_t *v, const fmpz_mpoly_t a,
                        const fmpz_mpoly_t b, slong skip);
int rs_sample_pts_next(rs_sample_pts_t *P);
json_t *rs_sample_pts_json(const rs_sample_pts_t *P);
void rs_sample_pts_clear(rs_sample_pts_t *P);

/* Shared steps of the analyses (run.c, conditions.c), once here instead of
 * copied into each caller.  rs_run_default_variant: the variant at the case's
 * set values; rs_run_free_params: its free parameters as "a, b" (malloc'd);
 * rs_run_numeric_poly: p at the request's point (what names it in errors);
 * rs_run_exact_count: the exact root count of p, added to o;
 * rs_run_hurwitz: the Hurwitz/Lienard-Chipart conditions of qz;
 * rs_run_symbolic_conditions: the symbolic stability conditions into o. */
int rs_run_default_variant(rs_run_t *run, rs_variant_t **v);
char *rs_run_free_params(const rs_variant_t *v);
int rs_run_numeric_poly(fmpz_poly_t p, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v,
                        const char *what);
int rs_run_exact_count(rs_rootcount_t rc, rs_run_t *run, const fmpz_poly_t p, json_t *o);
void rs_json_add_count(json_t *o, const rs_rootcount_t rc);
/* det A = c lambda^k p: p's count rc (p at the point, or NULL) plus the k
 * roots at 0 charpoly.c divided out, inside; at_zero their multiplicity */
void rs_run_count_zeros(rs_rootcount_t rc, const rs_variant_t *v, const fmpz_poly_t p);
/* det A = c lambda^k with c a polynomial in the parameters (dead-beat where
 * c != 0, no polynomial where c = 0): the factors of c whose sign the
 * assumptions do not settle appended to conds as "f != 0", their product in
 * kept (1 when none); holds at a point as rs_holds_fn with data = kept */
void rs_run_dead_beat_nonzero(fmpz_mpoly_t kept, json_t *conds, rs_run_t *run, const rs_scheme_t s,
                              const fmpz_mpoly_t c);
int rs_run_nonzero_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s);
/* the entry of a root at 0 in a radius's "roots" (exact, |.| = 0) of the
 * given multiplicity; k of them appended to roots */
void rs_json_zero_roots(json_t *roots, slong k, slong digits);
/* a dead-beat radius (det A = c lambda^k, every root 0): its exact fields in o */
void rs_run_radius_dead_beat_json(json_t *o);
json_t *rs_json_jury_route(const rs_jury_t ju);
int rs_run_hurwitz(rs_hurwitz_t h, rs_run_t *run, const rs_variant_t *v, fmpz_mpoly_t qz);
int rs_run_symbolic_conditions(rs_run_t *run, const rs_variant_t *v, json_t *o, int *verdict);
/* why a Hurwitz minor is "not expanded" (hurwitz, and jury's bilinear route) */
extern const char rs_hurwitz_not_expanded_note[];
/* "limit_note": the first branch's budget message (h->limit_note), if any
 * and not set already (issue 17: the only clock-dependent decision), and
 * "not_expanded_reason": which step the row share or the expansion budget stopped (h->stop_note) */
void rs_json_hurwitz_limit_note(json_t *o, const rs_hurwitz_struct *h);
int rs_run_symbolic_conditions_dropped(rs_run_t *run, const rs_variant_t *v, json_t *o, int *verdict,
                                       json_t *dropped);
/* conditions.c: the OR of Hurwitz branches of qz (over the sign of its
 * leading coefficient), 1/0/-1 at a point as rs_holds_fn, as JSON (returns
 * the verdict: 1 always, 0 never, -1 conditions); a condition factor as
 * text; str appended to arr unless there. */
int rs_run_hurwitz_or(rs_hurwitz_or_t hb, rs_run_t *run, const rs_variant_t *v, fmpz_mpoly_t qz);
int rs_run_hurwitz_or_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s);
int rs_json_hurwitz_or(json_t *o, const rs_hurwitz_or_t hb, const rs_scheme_t s);
/* Condition sets that can never all hold (conditions.c): rs_conds_never
 * decides cheaply and exactly for c[i] > 0 (a constant <= 0, c' = -k c with
 * k > 0, one parameter's conditions without a common solution in its
 * interval, or two whose sum is provably < 0 under the intervals); the
 * reason appended to *why (rs_str_catf: any length; the caller frees it).
 * rs_run_conds_never: the same on
 * poly[i] > 0 (ne[i]: a "!= 0" one, left out), intervals from the assume
 * lines.  rs_run_hurwitz_or_never: every branch so: "never" into o, 1.
 * rs_run_sample_check_never: rs_run_sample_check, and with "never" in o
 * no sample may satisfy the conditions (else exit 3). */
int rs_conds_never(char **why, const fmpz_mpoly_struct *const *c, slong n, const rs_bound_t *b,
                   slong nb, const rs_scheme_struct *s);
int rs_run_conds_never(char **why, rs_run_t *run, const fmpz_mpoly_struct *poly, const int *ne,
                       slong n, const rs_scheme_struct *s);
void rs_json_set_never_conditions(json_t *o, const char *why);
int rs_run_hurwitz_or_never(rs_run_t *run, json_t *o, const rs_hurwitz_or_t hb, const rs_scheme_struct *s);
int rs_run_sample_check_never(rs_run_t *run, const rs_variant_t *v, rs_holds_fn holds, const void *data,
                              json_t *o);
json_t *rs_json_factor(const fmpz_mpoly_t f, const rs_scheme_t s);
void rs_json_append_unique(json_t *arr, const char *str);

/* run.c: blanks skipped; a name (letters, digits, _; at most 64 characters
 * into buf) read after blanks, NULL when none starts there; the number of
 * variables of p other than lambda and `except` that occur; the coefficient
 * of t^j of p (variable tv, no other free one) as a polynomial in lambda. */
const char *rs_req_skip_blanks(const char *t);
const char *rs_req_read_name(const char *t, char *buf);
slong rs_run_count_free(const fmpz_mpoly_t p, const rs_scheme_t s, slong except);
void rs_run_coeff_in(fmpz_poly_t out, const fmpz_mpoly_t p, slong tv, slong j, const rs_scheme_t s);

/* run.c: a variant freed (rs_run_variant caches them in the run); a root
 * enclosure as {re, im, rad} strings; p(x) of the polynomial as stated
 * (content and sign of the normalisation undone) for x = 1, -1. */
void rs_variant_free(rs_variant_t *v);
json_t *rs_json_acb(const acb_t z, slong digits);
json_t *rs_json_p_at(const rs_variant_t *v, slong x);

/* complex_poly.c: p over Q(i)[real params] = re + i im (integral, primitive
 * together; the complex set values substituted, or a `char` line with i
 * read back from its block form), returns its degree in lambda (-1: zero);
 * rs_run_cx_eval: re or im at the point pt (every variable but lambda). */
slong rs_run_cx_poly(fmpz_mpoly_t re, fmpz_mpoly_t im, const rs_run_t *run, const rs_variant_t *v);
/* the same times lambda^k, k the roots at 0 charpoly.c divided out of a real
 * det (a char line with i keeps them in its block entries): the counts and
 * roots of det itself, and a dead-beat det = c lambda^k still has degree k */
slong rs_run_cx_poly_det(fmpz_mpoly_t re, fmpz_mpoly_t im, const rs_run_t *run, const rs_variant_t *v);
/* complex_poly.c: qr + i qi += c i^ib x^ex with the complex set values
 * substituted (their exponents in ex zeroed; terms pushed unsorted) */
void rs_cx_add_term(fmpq_mpoly_t qr, fmpq_mpoly_t qi, const fmpq_t c, int ib, slong *ex, const rs_run_t *run,
                    const rs_scheme_struct *s);
void rs_run_cx_eval(fmpq_poly_t out, const fmpz_mpoly_t p, fmpq *const *pt, const rs_scheme_struct *s);
/* The verdict over Q(i) at vars[i] = vals[i] (i < nv, every real parameter
 * still free in v): complex Schur-Cohn and Bilharz (must agree), rc p's own
 * counts (rs_routh_complex_rootcount, whose status must agree); real_st >= 0:
 * the real block form's verdict, which must agree too (RS_ERR_INCONSISTENT). */
/* rs_cx_isolate_sqfree: the distinct roots of a squarefree a = ar + i ai as
 * certified isolating balls of relative accuracy >= bits (a root at 0 split
 * off exactly), precision prec0 doubled up to max_prec (0: limit reached);
 * rs_cx_roots: rr gets p's roots with multiplicity (Yun over Q(i), then each
 * factor isolated; 1 done, 0 limit, -1 the factors' degrees do not add up);
 * rs_cx_poly_str: p as text in var; rs_cx_norm_check: the exact verdict st
 * against the certified ladder on p conj(p) (same moduli), which must say
 * stable iff st does and unstable when st does (RS_ERR_INCONSISTENT). */
int rs_cx_isolate_sqfree(acb_ptr out, const fmpq_poly_t ar, const fmpq_poly_t ai, slong bits, slong prec0,
                         slong max_prec);
int rs_cx_roots(rs_radius_t rr, const fmpq_poly_t pr, const fmpq_poly_t pi, slong bits, slong prec0, slong max_prec);
char *rs_cx_poly_str(const fmpq_poly_t re, const fmpq_poly_t im, const char *var);
/* rs_run_cx_at: the complex set values as {name: "a + b*i"} (the JSON's
 * "at" / "complex" / additions to "substituted") */
json_t *rs_run_cx_at(const rs_run_t *run);
int rs_cx_norm_check(rs_status_t st, const fmpq_poly_t re, const fmpq_poly_t im, rs_error_t err);
int rs_run_cx_point_status(rs_status_t *st, rs_rootcount_t rc, rs_run_t *run, const rs_variant_t *v,
                           const slong *vars, const fmpq *vals, slong nv, int real_st);

#endif
