/* an_region.h -- shared by the regions: the projection used by `region NAME
 * for all` and by the cylindrical decomposition of 2-D regions (sets of
 * irreducible integer polynomials, one elimination step), and the real
 * algebraic numbers and exact point statuses of an_region.c. */
#ifndef RECSTAB_AN_REGION_H
#define RECSTAB_AN_REGION_H
#include <arb.h>
#include <flint/fmpq_poly.h>
#include "analysis/registry.h"
#include "recstab/hurwitz.h"

/* a set of irreducible polynomials, each up to sign once */
typedef struct {
    fmpz_mpoly_struct *p;
    slong n, cap;
} rs_plist_t;

void rs_plist_init(rs_plist_t *l);
void rs_plist_clear(rs_plist_t *l, const fmpz_mpoly_ctx_t ctx);
/* the irreducible non-constant factors of f; with dom != NULL (bounds of
 * every variable, dom[tv]'s ends taken open) only the factors that can
 * vanish on the domain */
void rs_plist_add(rs_plist_t *l, const fmpz_mpoly_t f, slong tv, const rs_bound_t *dom, const fmpz_mpoly_ctx_t ctx);
/* Factorisations of rs_plist_add and of the conditions' p kept while a
 * region NAME for all runs (its per-condition and full projections meet the
 * same polynomials): rs_factor_memo_begin returns the memo in force before,
 * to be handed to rs_factor_memo_end, which frees this one. */
void *rs_factor_memo_begin(const fmpz_mpoly_ctx_t ctx);
void rs_factor_memo_end(void *outer);
/* fmpz_mpoly_factor(fac, f, ctx) through the memo in force (if any) */
int rs_factor_memo_factor(fmpz_mpoly_factor_t fac, const fmpz_mpoly_t f, const fmpz_mpoly_ctx_t ctx);
/* rs_hurwitz_compute(own, q, zvar, NULL, ctx, err), or the result for an
 * equal q kept in the memo in force (successful results only): *hp is own
 * or the memo's copy (valid until rs_factor_memo_end); own initialised and
 * cleared by the caller */
int rs_hurwitz_memo_compute(const rs_hurwitz_struct **hp, rs_hurwitz_t own, const fmpz_mpoly_t q,
                            slong zvar, const fmpz_mpoly_ctx_t ctx, rs_error_t err);
/* out += the projection of in with variable u (interval bu) eliminated:
 * leading coefficients (all coefficients where none has one sign on dom),
 * discriminants, pairwise resultants, values at bu's finite ends; u^g
 * deflated to u when u >= 0 and only powers of u^g occur; factors of one
 * sign on dom dropped.  Budget-checked: returns the budget's error. */
int rs_proj_eliminate(rs_plist_t *out, rs_run_t *run, const rs_plist_t *in, slong u, const rs_bound_t *bu,
                      slong tv, const rs_bound_t *dom, const fmpz_mpoly_ctx_t ctx);

/* A real root of an irreducible integer polynomial: the root number idx (in
 * increasing order) of minpoly; rational when deg minpoly == 1. */
typedef struct {
    fmpz_poly_t minpoly;
    slong idx;
    int rational;
    fmpq_t q;            /* the value when rational */
    arb_t x;             /* enclosure */
    slong prec;
    int boundary;        /* which critical polynomials vanish here (an_region.c's CRIT_*) */
} rs_alg_t;

void rs_alg_init(rs_alg_t *a);
void rs_alg_clear(rs_alg_t *a);
/* d := a (initialised) */
void rs_alg_set(rs_alg_t *d, const rs_alg_t *a);
/* the enclosure refined to at least prec bits */
void rs_alg_refine(rs_alg_t *a, slong prec);
/* -1, 0, 1 */
int rs_alg_cmp(rs_alg_t *a, rs_alg_t *b);
/* appends the real roots of f (non-zero) to *list */
void rs_alg_roots_append(rs_alg_t **list, slong *n, const fmpz_poly_t f, int boundary);
/* x[0..nreal) := the real roots of the irreducible g (degree >= 2, no
 * rational root), ascending, each in a ball of relative radius <= 2^-(prec+2),
 * by exact isolation (Descartes' rule on dyadic intervals, then bisection on
 * exact signs); returns 0 (x not all set) if it does not find nreal roots */
int rs_region_real_roots(arb_ptr x, const fmpz_poly_t g, slong nreal, slong prec);
/* sorted in increasing order */
void rs_alg_sort(rs_alg_t *a, slong n);
/* "p/q", or {minpoly, root_index, interval, approx} */
json_t *rs_alg_json(rs_alg_t *a, const char *var);
double rs_alg_double(rs_alg_t *a);
/* a simple rational strictly between a < b (NULL ends: infinite) */
void rs_alg_between(fmpq_t out, rs_alg_t *a, rs_alg_t *b);
/* The exact status of p(lambda; tv = t0), p depending on no other
 * parameter; 0 when undecided (a repeated non-real circle root of a system) */
int rs_alg_status(rs_status_t *out, const fmpz_mpoly_t p, slong tv, rs_alg_t *t0, const rs_scheme_t s);

/* Exact arithmetic in K = Q(t0) = Q[t]/(minpoly): elements are fmpq_polys
 * reduced mod the minimal polynomial.  The sign of x(t0); the status of
 * sum c_j lambda^j (j <= n, c_j in K), 0 when undecided (as rs_alg_status;
 * a system's repeated circle root is left undecided). */
int rs_alg_sign(const fmpq_poly_t x, rs_alg_t *t0);
int rs_alg_status_coeffs(rs_status_t *out, const fmpq_poly_struct *c, slong n, rs_alg_t *t0, const rs_scheme_t s);
/* A primitive element of Q(alpha, beta): gamma = beta + k alpha (small k),
 * alpha = A(gamma), beta = B(gamma), A, B reduced mod gamma's minimal
 * polynomial; gamma initialised by the caller.  0 when none found (budget). */
int rs_alg_primitive(rs_alg_t *gamma, fmpq_poly_t A, fmpq_poly_t B, rs_alg_t *alpha, rs_alg_t *beta);

/* The for-all region of parameter tv (every other parameter not set
 * quantified) on the interval dom_tv: *out {"intervals", "for_all", ...}
 * as `region NAME for all` prints them; a claim's cross-check. */
int rs_an_region_forall_on(json_t **out, rs_run_t *run, const rs_request_t *q, slong tv, const rs_bound_t *dom_tv);

/* The region of the one real parameter tv left in v's p over Q(i) (complex
 * set values substituted, every other parameter fixed in v) on the interval
 * dom_tv: *out {"intervals", "undecided_points", ...} as `region NAME` at
 * complex set values prints them (cells of |p|^2's critical values, each
 * decided over Q(i) and by the real gcd route); a claim's certificate. */
int rs_an_region_cx_on(json_t **out, rs_run_t *run, const rs_variant_t *v, slong tv, const rs_bound_t *dom_tv);

/* an_claim.c (issue 13): the for-all status at an irrational value a of tv
 * (one quantified parameter w left in v's p, w > 0, w >= 0 or free) when a
 * neighbouring cell is stable for every w.  Continuity gives every root in
 * the closed disc at a; bounded when no w on its range makes p's leading
 * coefficient or discriminant in lambda vanish at a (the norms
 * Res_t(minpoly, .) in w have no root there: Sturm and Arb counts); marginal
 * when moreover p(a, w0, +-1) = 0 at a root w0 of the norm Res_t(minpoly,
 * p(t, w, +-1)) (exact: that norm is the product over a's conjugates, the
 * others certified non-zero at w0 by Arb).  *decided 0 when this does not
 * apply or does not settle it; *ev the evidence, with "cross_check": p's
 * certified roots in lambda at w = 1 and at w0 (one certainly outside the
 * circle: RS_OUTCOME_INCONSISTENT, *decided 0, *ev says so). */
int rs_an_forall_alg_marginal(int *decided, json_t **ev, rs_run_t *run, const rs_variant_t *v, slong tv,
                              rs_alg_t *a);


int rs_an_region_cad(rs_run_t *run, const rs_an_req_t *req);
/* region N1, N2's variant: the case's set values and the request's `at`
 * with N1, N2 kept symbolic; an input error at the request when another
 * parameter is still symbolic */
int rs_region2_variant(rs_variant_t **v, rs_run_t *run, const rs_an_req_t *req);
/* The cells of the plane (av, bv) of v's p (no other free parameter), the
 * assume lines' bounds and the extra domain polynomials dom[i] > 0 (>= 0
 * where closed[i]) cutting it (a claim's condition): *cells their JSON as
 * in `region N1, N2` ("dim", the sample under each name, "status"), no
 * result added.  RS_ERR_INPUT when another parameter is free. */
int rs_an_region_cad_cells(json_t **cells, rs_run_t *run, const rs_variant_t *v, slong av, slong bv,
                           const fmpz_mpoly_struct *dom, const int *closed, slong ndom);

/* region re(z), im(z) (an_complex.c): the plane of z = x + i y from given
 * conditions.  s: a context of x, y, lambda (variables 0, 1, 2; ctx, zctx,
 * nvars, vars, lambda_var used); stable iff lead > 0 and every delta > 0;
 * status: the exact point verdict at rational (x, y) (re-checks every
 * rational sample and the formula). */
typedef int (*rs_region_cx_status_fn)(rs_status_t *st, const fmpq_t x, const fmpq_t y, void *arg);
typedef struct {
    const rs_scheme_struct *s;
    const fmpz_mpoly_struct *lead, *delta;
    slong ndelta;
    rs_region_cx_status_fn status;
    void *arg;
    const char *name;
    json_t *substituted;
    /* the marginal set (NULL norm: stable / not stable only): extra
     * polynomials in (x, y) whose zero sets hold every point where a root
     * reaches the circle or doubles, and norm = p conj(p) in Z[x, y, lambda]
     * (roots: p's and their conjugates) for exact verdicts at algebraic
     * samples (its marginal is p's; its unstable is p's or a circle root
     * of p with its conjugate); norm[0 .. nnorm): norm[k] = |p(rho_k
     * lambda)|^2 up to a positive factor, |rho_k| = 1, rho_0 = 1, the
     * rho_k^2 distinct: nnorm > n(n+1)/2 (n = deg p) decides every cell */
    const fmpz_mpoly_struct *extra;
    slong nextra;
    const fmpz_mpoly_struct *norm;
    slong nnorm;
} rs_region_cx_t;
int rs_an_region_cad_cx(rs_run_t *run, const rs_region_cx_t *cx);

/* region N1, N2 over Q(sqrt d) (an_qd_region2.c): the plane (av, bv) of v
 * (p = p0 + sqrt(d) p1, no other free parameter) cut by the given rational
 * critical polynomials (norms c0^2 - d c1^2 of the Q(sqrt d) ones) instead
 * of p's own, each cell decided by the callbacks: point at a rational
 * sample (RS_OK, or the error of a disagreement of its routes), field at
 * (N1, N2) = (A, B)(g) in Q(g) = Q[x]/(minpoly g) (1 decided, 0 not; a
 * disagreement of its routes marks the run inconsistent).  method and
 * check_method: the result's "method" and its cross-check's. */
typedef struct {
    const fmpz_mpoly_struct *crit;
    slong ncrit;
    int (*point)(rs_status_t *st, const fmpq *vals, void *arg);
    int (*field)(rs_status_t *st, const fmpq_poly_t A, const fmpq_poly_t B, rs_alg_t *g, void *arg);
    void *arg;
    const char *method, *check_method;
    int complex_p;   /* v's p is not the model's (complex set values, an_qd_cx2.c): no balls on it */
} rs_region_qd_t;
int rs_an_region_cad_qd(rs_run_t *run, const rs_variant_t *v, slong av, slong bv, const rs_region_qd_t *qd);
/* f (in variables av, bv only) at (A(g), B(g)) in Q(g) = Q[x]/(m) */
void rs_region_eval_field(fmpq_poly_t out, const fmpz_mpoly_t f, slong av, slong bv, const fmpq_poly_t A,
                          const fmpq_poly_t B, const fmpq_poly_t m, const fmpz_mpoly_ctx_t ctx);

/* The map's exact boundary drawn only where it separates (issue 13 part 3):
 * the decomposition of the (v1, v2) plane of variant v, then per boundary
 * point of a condition whether its arc separates two statuses. */
typedef struct rs_region_arcs_struct rs_region_arcs_t;
int rs_region_arcs_new(rs_region_arcs_t **out, rs_run_t *run, const rs_variant_t *v, slong v1, slong v2);
/* the same over a complex plane's given conditions (cx: stable / not
 * stable, norm NULL); conditions passed to rs_region_arcs_keep are in src
 * (nsrc variables), variable k of src being gmap[k] of cx->s (-1: absent) */
int rs_region_arcs_new_cx(rs_region_arcs_t **out, rs_run_t *run, const rs_region_cx_t *cx,
                          const fmpz_mpoly_ctx_t src, const slong *gmap, slong nsrc);
void rs_region_arcs_free(rs_region_arcs_t *A);
/* cond NULL: (x, y) on any boundary factor (a sampled z-plane locus point) */
int rs_region_arcs_keep(const rs_region_arcs_t *A, const fmpz_mpoly_t cond, double x, double y);
json_t *rs_region_arcs_json(const rs_region_arcs_t *A);
#endif
