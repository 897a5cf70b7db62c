/* analysis/an_qd.h -- the analyses of a model with R over Q(sqrt d)
 * (model.h's qd: rk sdirk2 on the test equation; an_qd.c).  Private. */
#ifndef RECSTAB_ANALYSIS_AN_QD_H
#define RECSTAB_ANALYSIS_AN_QD_H

#include "analysis/registry.h"
#include "algebra/qsqrt.h"
#include "analysis/an_region.h"
#include "analysis/sweep_impl.h"

/* RS_OK, or an input error at the request's line when the model has qd and
 * the analysis is not one of those an_qd.c lists (limit, map, sweep and bilinear with real
 * set values only; expect never) */
int rs_an_qd_check(rs_run_t *run, const rs_an_req_t *req);
/* the case is Dahlquist's test equation: one subsystem, one state y' = F,
 * nothing else (R = N/D is read from p = D lambda - N) */
int rs_an_qd_test_equation(const rs_case_struct *c);
int rs_an_qd_charpoly(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_stability(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_astability(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_radius(rs_run_t *run, const rs_an_req_t *req);
/* an_qd_conds.c: the Schur-Cohn and Hurwitz conditions over Q(sqrt d)[params] */
int rs_an_qd_jury(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_hurwitz(rs_run_t *run, const rs_an_req_t *req);
/* jury's conditions (hurwitz's when hurwitz and deg p <= 8) c0[k] +
 * sqrt(d) c1[k] > 0 (ne[k]: != 0), k < *n, on v's p (all |lambda| < 1 iff
 * they hold; an_qd_region2.c's cells and second route); the caller clears
 * the c0, c1 in v->s->zctx and flint_frees the arrays */
int rs_an_qd_jury_conds(fmpz_mpoly_struct **c0, fmpz_mpoly_struct **c1, int **ne, slong *n, rs_run_t *run,
                        const rs_an_req_t *req, rs_variant_t *v, int hurwitz);
/* the conditions c0[k] + sqrt(d) c1[k] > 0 (ne[k]: != 0), k < n, in s's zctx
 * (an_qd_conds.c; start with n = 0 and NULL arrays) */
typedef struct {
    slong n;
    fmpz_mpoly_struct *c0, *c1;
    int *ne;
    const rs_scheme_struct *s;
    int never;        /* proved never to hold together: rs_an_qd_conds_hold says 0 */
} rs_an_qd_conds_t;
/* f > 0 (f in s's zctx, sqrt(d) reduced) into q and the lists: the gcd of
 * its parts factored, factors of one sign under the assumptions (sign)
 * dropped, even ones as "!= 0"; 1 when nothing is left (always true), -1
 * when f is a constant <= 0 (never), else 0 */
int rs_an_qd_conds_add(rs_an_qd_conds_t *q, json_t *conds, json_t *parts, json_t *dropped, const fmpz_mpoly_t f,
                       const char *origin, const int *sign);
/* 1 when every condition of q holds at pt (every variable of s), else 0 */
int rs_an_qd_conds_hold(const rs_an_qd_conds_t *q, fmpq *const *pt);
void rs_an_qd_conds_clear(rs_an_qd_conds_t *q);
/* q's conditions (and alt's, when not NULL: they must say the same) against
 * the exact verdict (rs_an_qd_parts_stable of part[], degree n) at
 * admissible rational points of the free parameters of a and b (sqrt(d)'s
 * variable skipped): o's "sample_check" (against the exact verdict over
 * field) and, with alt, "cross_check" {alt_method, points, agree}; exit 3
 * when the verdict's two routes or the two lists ("%s conditions disagree"
 * with pair) disagree */
int rs_an_qd_conds_sample_check(rs_run_t *run, const rs_variant_t *v, const fmpz_mpoly_t a, const fmpz_mpoly_t b,
                                const fmpz_mpoly_struct *const *part, slong n, const rs_an_qd_conds_t *q,
                                const rs_an_qd_conds_t *alt, const char *field, const char *pair,
                                const char *alt_method, json_t *o, const rs_request_t *rq);
/* an_qd_never.c: 1 (the reason into buf) when q's conditions provably never
 * all hold under the assume lines (each split into the sign cases of c0,
 * c1 and the norm c0^2 - d c1^2, every choice refuted by rs_run_conds_never) */
int rs_an_qd_conds_never(char **why, rs_run_t *run, const rs_an_qd_conds_t *q);
/* an_qd_complex.c: jury (kind 0), hurwitz (1) and routh (2) at complex set
 * values: conditions over Q(sqrt d)(i)[params], Schur-Cohn and Bilharz
 * cross-checked at sample points against the exact point verdict */
int rs_an_qd_cx_conds(rs_run_t *run, const rs_an_req_t *req, int kind);
/* the exact verdict at pt of p = part[0] + sqrt(d) part[1] + i (part[2] +
 * sqrt(d) part[3]) (parts without sqrt(d), NULL: zero) of degree n in
 * lambda: 1 every root inside, 0 not (a degree drop: singular), -1 p
 * vanishes there, -2 Schur-Cohn over Q(sqrt d)(i) and the certified roots
 * disagree */
int rs_an_qd_parts_stable(const fmpz_mpoly_struct *const *part, slong n, fmpq *const *pt, const rs_scheme_struct *s);
/* the same, finer: 1 stable, 0 a root certified outside (unstable), -1 not
 * stable with no root certified outside (on or too near the circle), -2
 * the two disagree, -3 the degree drops (singular), -4 p vanishes */
int rs_an_qd_parts_verdict(const fmpz_mpoly_struct *const *part, slong n, fmpq *const *pt, const rs_scheme_struct *s);
/* an_qd_conds.c: region's cells of tv (the only free parameter) at complex
 * set values: cut at the real roots of the norms of q's (Schur-Cohn) and
 * alt's (Bilharz) conditions and of lead (|a_n|^2); each rational sample
 * decided by both lists and rs_an_qd_parts_verdict, each irrational cut by
 * both lists' exact signs (any disagreement exit 3); kind and the rest as
 * rs_an_qd_claim_part (kind -1: region's "intervals") */
int rs_an_qd_cx_cells(json_t *o, rs_run_t *run, const rs_request_t *rq, slong tv, const rs_an_qd_conds_t *q,
                      const rs_an_qd_conds_t *alt, const fmpz_mpoly_struct *const *part, slong n,
                      const fmpz_mpoly_t lead, const rs_bound_t *dom, int kind, int *verdict, json_t **counter);
/* region NAME (kind -1) and a claim's part (kind 0..2, as rs_an_qd_fiber)
 * at complex set values of other parameters (an_qd_complex.c) */
int rs_an_qd_cx_fiber(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                      slong tv, const rs_bound_t *dom, const rs_assign_t *extra, slong nextra);
/* 1 when a complex set value is of a parameter other than tv */
int rs_an_qd_cx_other(const rs_run_t *run, slong tv);
/* an_qd_region2.c: region N1, N2 over Q(sqrt d) (the rational CAD on the
 * norms of the critical polynomials, each cell decided over Q(sqrt d)) */
int rs_an_qd_region2(rs_run_t *run, const rs_an_req_t *req);
/* sqrt(d) as the positive root of x^2 - d; g = g0 + sqrt(d) g1 (g split at
 * sqrt(d)'s variable, or g0 = g and g1 = h1 when h1 != NULL): its norm
 * g0^2 - d g1^2 appended to crit (flint_realloc'd), with parts g0 and g1
 * too; 0 when the norm vanishes identically */
void rs_an_qd_sqrt_alg(rs_alg_t *sq, slong d);
int rs_an_qd_push_norm(fmpz_mpoly_struct **crit, slong *ncrit, const fmpz_mpoly_t g, const fmpz_mpoly_struct *h1,
                       int parts, const rs_scheme_struct *s);
/* region N1, N2 at complex set values of other parameters (an_qd_complex.c:
 * the model; an_qd_cx2.c: the plane of tv[0], tv[1] cut by the norms of
 * both lists' conditions and of |a_n|^2 = lead, each cell decided by both
 * lists and, at rational samples, rs_an_qd_parts_verdict; ex's keys added
 * to the result) */
int rs_an_qd_cx_region2(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_cx_plane(rs_run_t *run, const rs_an_req_t *req, const rs_variant_t *v, const slong *tv,
                      const rs_an_qd_conds_t *q, const rs_an_qd_conds_t *alt, const fmpz_mpoly_struct *const *part,
                      slong n, const fmpz_mpoly_t lead, json_t *ex);
/* the fraction-free Routh array over Q(sqrt d)[params], its conditions
 * cross-checked against hurwitz's and the point verdict at sample points */
int rs_an_qd_routh(rs_run_t *run, const rs_an_req_t *req);
/* region NAME [at P=V, ...]: exact intervals over Q(sqrt d), or the conditions with other parameters free */
int rs_an_qd_region(rs_run_t *run, const rs_an_req_t *req);
/* a claim's part over Q(sqrt d): the exact region of tv (every other parameter
 * set) on dom, kind 0 stable, 1 bounded, 2 unstable; *verdict 1 proved, -1
 * refuted (*counter {NAME: value, "status"}), 0 undecided; the region's cells
 * into o's "region" */
int rs_an_qd_claim_part(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                        slong tv, const rs_bound_t *dom);
/* rs_an_qd_claim_part at the case's set values overridden and extended by
 * extra[0..nextra) (tv free; nextra = 0: the default variant) */
int rs_an_qd_fiber(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                   slong tv, const rs_bound_t *dom, const rs_assign_t *extra, slong nextra);
/* region NAME for all [Q] over Q(sqrt d) (an_qd_forall.c) */
int rs_an_qd_region_forall(rs_run_t *run, const rs_an_req_t *req);
/* {"lo", "hi", "lo_closed", "hi_closed", "status", "lo_approx", "hi_approx"}
 * of an interval of region's cells (NULL ends: infinite) */
json_t *rs_an_qd_interval_json(rs_alg_t *lo, rs_alg_t *hi, int lo_closed, int hi_closed, const char *status,
                               const char *name);
/* a claim (kind 0 stable, 1 bounded, 2 unstable) on the box b[tv] x
 * b[qvs[0]] x ... (b: every parameter's bounds, the assumptions in them)
 * by the same cells (kind 2: "unstable at every point" in place of "for
 * every point stable"): *verdict 1 proved, -1 refuted (*counter), 0
 * undecided; the cells of tv into o's "region" */
int rs_an_qd_claim_forall(int *verdict, json_t **counter, json_t *o, rs_run_t *run, const rs_an_req_t *req, int kind,
                          slong tv, const slong *qvs, slong nq, const rs_bound_t *b);
/* the norms c0^2 - d c1^2 of p's leading coefficient, of its discriminant
 * and of jury's conditions (the default variant: every unset parameter
 * free) into l (rs_plist_add with tv, dom); *s the scheme of their zctx */
/* n = c0^2 - d c1^2, the norm of c0 + sqrt(d) c1 (an_qd_conds.c): zero
 * exactly where c0 + sqrt(d) c1 or its conjugate vanishes */
void rs_an_qd_mpoly_norm(fmpz_mpoly_t n, const fmpz_mpoly_t c0, const fmpz_mpoly_t c1, const rs_scheme_struct *s);
int rs_an_qd_forall_norms(rs_plist_t *l, const rs_scheme_struct **s, rs_run_t *run, const rs_an_req_t *req,
                          slong tv, const rs_bound_t *dom);
/* the exact verdict over Q(sqrt d) of the default variant's p at the
 * rational point pt (every scheme variable): 1 stable, 0 not stable, -1 p
 * vanishes, -2 Schur-Cohn and the certified roots disagree, -3 no variant */
int rs_an_qd_point_verdict(rs_run_t *run, const rs_an_req_t *req, fmpq *const *pt);
/* the exact status at tv = t0 (algebraic), the other parameters at the set
 * values and extra[]: over Q(t0, sqrt d) = Q(gamma); 0 when undecided */
int rs_an_qd_alg_status(rs_status_t *st, rs_run_t *run, const rs_an_req_t *req, slong tv, rs_alg_t *t0,
                        const rs_assign_t *extra, slong nextra);
/* the same at tv = t0 and qv = q0 both algebraic (the other parameters at
 * the set values and extra[]), over Q(t0, sqrt d, q0) = Q(gamma) */
int rs_an_qd_alg2_status(rs_status_t *st, rs_run_t *run, const rs_an_req_t *req, slong tv, rs_alg_t *t0, slong qv,
                         rs_alg_t *q0, const rs_assign_t *extra, slong nextra);

/* an_qd_forall2.c: the status at a point with up to three irrational
 * coordinates by the certified signs of jury's conditions over Q(sqrt d)
 * (the default variant's, computed once by rs_qd_signs_init; NULL-safe
 * clear): ex[] rational, a[k] at parameter av[k]; 1 decided (stable, or
 * unstable with every condition away from 0), 0 when a condition's ball
 * keeps 0 at 4096 bits or the leading coefficient's does */
typedef struct rs_qd_signs_s rs_qd_signs_t;
int rs_qd_signs_init(rs_qd_signs_t **g, rs_run_t *run, const rs_an_req_t *req);
void rs_qd_signs_clear(rs_qd_signs_t *g);
int rs_qd_signs_status(rs_status_t *st, rs_qd_signs_t *g, rs_run_t *run, const rs_assign_t *ex, slong nex,
                       const slong *av, rs_alg_t *const *a, slong na);

/* an_astability.c: A(alpha) of the one-step method R = N/D over Q(sqrt d)
 * by the rays z = -s (1 - i u): *inside 1 every ray inside (A-stable, deg
 * 90, *out NULL), 0 *out the angle (0 or {"exact", "tan_alpha_minpoly", ...}
 * as over Q) with *ev its evidence (the first point outside, re-checked
 * exactly), -1 the route does not apply */
int rs_an_astability_alpha_qd(json_t **out, json_t **ev, arb_t deg, int *inside, const rs_qdpoly_t N,
                              const rs_qdpoly_t D, slong d, rs_error_t err);
/* an_astability.c: an interval end as astability's JSON writes it: integers
 * as numbers, other rationals and algebraic numbers as {"exact", "minpoly",
 * "approx", "certified"} (refines a) */
json_t *rs_an_alg_end_json(rs_alg_t *a, const char *var);
/* "Q(sqrt d)" for the JSON key "over" and the texts (flint_free it) */
char *rs_an_qd_over_str(slong d);
/* "A0 + sqrt(d)*(A1)" (A0, A1 polynomials of s without sqrt(d); flint_free
 * it); spaced: "a - c^2" as the conditions print, else FLINT's "a-c^2" */
char *rs_an_qd_mpoly_str(const fmpz_mpoly_t a0, const fmpz_mpoly_t a1, const rs_scheme_struct *s, int spaced);
/* "over", the method ("method", or "rk" when o names its test) and p0, p1 */
void rs_an_qd_json_p(json_t *o, const fmpz_mpoly_t p0, const fmpz_mpoly_t p1, rs_run_t *run);

/* simulate at the set values: p there as complex balls z[0..*n] (prec bits,
 * sqrt d a ball; _acb_vec_clear(*z, *n + 1)), the exact verdict (*decided 1:
 * st, rc from Schur-Cohn over Q(sqrt d)(i) and the certified roots), o's
 * "over", "rk", "p0", "p1", "poly", "at_zero_divided_out", "radius", "substituted";
 * an input error when p is constant there */
int rs_an_qd_point(acb_ptr *z, slong *n, int *decided, rs_status_t *st, rs_rootcount_t rc, json_t *o,
                   rs_run_t *run, const rs_request_t *q, slong prec);
/* modes at the set values: rr's roots (the certified isolated roots of p to
 * digits, and the roots at 0 the charpoly divided out), o's "over", "rk",
 * "p0", "p1", "poly", "exact_check" (certified moduli against the Schur-Cohn
 * counts; a disagreement marks the run inconsistent) and "substituted" */
int rs_an_qd_modes_roots(rs_radius_t rr, json_t *o, rs_run_t *run, const rs_request_t *q, slong digits);

/* an_qd_map.c: map re(NAME), im(NAME) over Q(sqrt d) (an_complex.c's map).
 * p = sum_k (CR[k] + sqrt(d) CS[k]) NAME^k with CR[k], CS[k] in Q[lambda],
 * K its degree in NAME, *n in lambda (every other parameter set: v one free);
 * clear as an_complex.c's coefficients */
int rs_an_qd_zplane_coeffs(fmpq_poly_struct **CR, fmpq_poly_struct **CS, slong *K, slong *n, const rs_variant_t *v,
                           slong param);
/* the verdict code at a point of p = re0 + sqrt(d) re1 + i (im0 + sqrt(d)
 * im1) of degree n: stable, unstable, singular (the degree drops), -1 (p
 * vanishes) or RS_SWEEP_UNDECIDED (a root on or too near the circle); by
 * Schur-Cohn over Q(sqrt d)(i) and the certified roots, RS_ERR_INCONSISTENT
 * when they disagree */
int rs_an_qd_zplane_verdict(int *code, const fmpq_poly_t re0, const fmpq_poly_t im0, const fmpq_poly_t re1,
                            const fmpq_poly_t im1, slong n, slong d);
/* "A0 + sqrt(d)*(A1)" of polynomials in lambda (malloc'd) */
char *rs_an_qd_fmpq_poly_str(const fmpq_poly_t a0, const fmpq_poly_t a1, slong d);
/* the map's "over", "rk", "methods", "cross_check" (checked points),
 * verdicts' "undecided" and its note */
void rs_an_qd_zplane_json(json_t *o, rs_run_t *run, slong undecided, slong checked);
/* bilinear at real set values over Q(sqrt d): q(z) = q0 + sqrt(d) q1 */
int rs_an_qd_bilinear(rs_run_t *run, const rs_an_req_t *req);
/* sweep NAME ... and map N1 ..., N2 ... of real parameters over Q(sqrt d)
 * (of stability or radius): the engine's model at the axis values vals[k]
 * (read, not copied) of R's axes, every other parameter set (errors at q);
 * each point by rs_an_qd_zplane_verdict, `of radius` also the certified
 * radius of p (sqrt d a ball), checked against the verdict; free it with
 * rs_an_qd_sweep_model_free (also after an error) */
int rs_an_qd_sweep_model(rs_sweep_model_t *m, rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R,
                         const rs_variant_t *v, const fmpq *const *vals);
void rs_an_qd_sweep_model_free(rs_sweep_model_t *m);
/* map N1 ..., N2 ... of two real parameters over Q(sqrt d) (every other
 * parameter set): the engine's map with rs_an_qd_sweep_model, the boundary
 * from the norms of jury's conditions (every factor drawn) */
int rs_an_qd_map(rs_run_t *run, const rs_an_req_t *req);
/* the sweep's "over", "rk" and "method" */
void rs_an_qd_sweep_json(json_t *o, rs_run_t *run, const json_t *verdicts);

#endif
