/* an_radius.c -- `radius`: the certified spectral radius (Arb, with the
 * GSL double baseline on request) checked against the exact verdict, and
 * radius / stability of the numeric model kinds (matrix recurrences with
 * exp, sin, ... entries; exactly integrated co-simulation). */
#include <math.h>
#include <string.h>
#include <flint/fmpz_vec.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "lower/recurrence.h"
#include "recstab/cosim.h"
#include "recstab/jury.h"
#include "numeric/cosim_fast.h"

/* ---- radius ---------------------------------------------------------------------- */

/* When the radius interval contains 1 but no root lies on the circle (so
 * rho != 1), more digits separate it from 1: raise them (x4 per round, while
 * the precision stays within --max-prec) until upper < 1 or lower > 1.  rr
 * keeps the most precise result; returns the digits it was computed with
 * (digits when no refinement ran or none helped). */
static slong radius_refine(rs_radius_t rr, rs_run_t *run, const fmpz_poly_t p, const rs_rootcount_t rc,
                              const char *method, slong digits)
{
    slong cap = (slong) ((double) (run->opt->max_prec > 0 ? run->opt->max_prec : RS_RADIUS_MAX_PREC_DEFAULT)
                         / 3.33) - 12, d = digits, got = digits;
    rs_radius_t r2;
    int r;
    if (rc->on > 0 || strcmp(rs_radius_verdict(rr), "undecided") != 0) return digits;
    rs_radius_init(r2);
    while (d < cap && strcmp(rs_radius_verdict(rr), "undecided") == 0) {
        d = FLINT_MIN(4 * d, cap);
        if (strcmp(method, "companion") == 0)
            r = rs_radius_fmpz_poly_companion(r2, p, d, run->opt->max_prec, run->err);
        else
            r = rs_radius_fmpz_poly(r2, p, d, run->opt->max_prec, run->err);
        if (r != RS_OK) {                 /* out of precision: stays undecided */
            rs_error_init(run->err);
            break;
        }
        rs_radius_swap(rr, r2);
        got = d;
    }
    rs_radius_clear(r2);
    return got;
}

/* The exact count (Routh on the bilinear transform and Schur-Cohn, which
 * must agree), said in o: count_methods, count_agree, schur_cohn_route. */
static int radius_count_exact(rs_rootcount_t rc, rs_run_t *run, const fmpz_poly_t p, json_t *o)
{
    json_t *t = json_object();
    int r = rs_run_exact_count(rc, run, p, t);
    if (r == RS_OK && json_object_get(t, "methods") != NULL) {
        json_object_set(o, "count_methods", json_object_get(t, "methods"));
        json_object_set(o, "count_agree", json_object_get(t, "agree"));
        json_object_set(o, "schur_cohn_route", json_object_get(t, "schur_cohn_route"));
        if (json_object_get(t, "schur_cohn_count") != NULL)
            json_object_set(o, "schur_cohn_count", json_object_get(t, "schur_cohn_count"));
    }
    json_decref(t);
    return r;
}

/* The highest precision worth a Schur-Cohn table in balls before the
 * exact minors modulo primes: their jury.c estimate, n (1 + log2(n) / 2 +
 * log2 |a|^2) / 61 primes, times 4 (a table at P bits costs about P/6
 * primes at degree 500; a failed attempt is paid too). */
static slong radius_schur_ball_cap(const fmpz_poly_t p)
{
    slong n = fmpz_poly_degree(p);
    double lb = 2.0 * (double) FLINT_ABS(_fmpz_vec_max_bits(p->coeffs, n + 1)) + log2((double) n + 1.0);
    return (slong) (4.0 * (double) n * (1.0 + 0.5 * log2((double) n) + lb) / 61.0);
}

/* The count above degree 64.  Schur-Cohn (exact, on p) gives it; when every
 * certified root ball lies off the unit circle the balls count too, and the
 * two must agree (the Routh array costs 15-45 s at degree 500, Schur-Cohn
 * about 1 s).  A ball on the circle leaves it to Routh + Schur-Cohn as below
 * degree 65.  Says which in count_methods / count_agree. */
static int radius_count_high(rs_rootcount_t rc, rs_run_t *run, const fmpz_poly_t p, rs_radius_t rr,
                             json_t *o)
{
    rs_rootcount_t rb;
    rs_jury_t ju;
    slong bin = 0, bprec = 0;
    int r, agree, decided = 0;
    rs_rootcount_init(rb);
    rb->degree = fmpz_poly_degree(p);
    /* a ball that meets the circle while rho is certified away from 1 is
     * merely too wide (the roots off the top were kept at ~64 bits): refine
     * those balls (O(d) each) before the exact Routh array (14 s at degree
     * 500).  With 1 inside the radius interval the exact count decides. */
    if (!rs_radius_count_balls(&rb->inside, &rb->outside, rr, rb->degree) &&
        strcmp(rs_radius_verdict(rr), "undecided") != 0 &&
        rs_radius_refine_circle(rr, p,
                                FLINT_MIN(run->opt->max_prec > 0 ? run->opt->max_prec : RS_RADIUS_MAX_PREC_DEFAULT,
                                          4096)))
        json_object_set_new(o, "count_balls_refined", json_true());
    if (!rs_radius_count_balls(&rb->inside, &rb->outside, rr, rb->degree))
        return radius_count_exact(rc, run, p, o);
    /* Schur-Cohn first in ball arithmetic (outer.c): its precision is the
     * table's conditioning, while the exact minors need primes for every
     * bit of their coefficients (Wilkinson-type degree 200: 2048 bits,
     * 0.03 s, against 10 769 primes, 2.6 s).  Up to the precision whose
     * cost matches the primes' (measured: a table at P bits costs about
     * P/6 primes at degree 500), then the exact minors as before. */
    rs_jury_init(ju);
    r = rs_radius_schur_count(&decided, &bin, &bprec, p, radius_schur_ball_cap(p), run->err);
    if (r == RS_OK && decided) {
        ju->count->degree = rb->degree;
        ju->count->inside = bin;
        ju->count->outside = rb->degree - bin;
    } else if (r == RS_OK) {
        r = rs_jury_count_fmpz_poly(ju, p, run->err);
    }
    if (r == RS_OK) {
        agree = rs_rootcount_equal(rb, ju->count);
        *rc = *ju->count;
        json_object_set_new(o, "count_methods", json_pack("[ss]", "certified root balls", "schur-cohn"));
        json_object_set_new(o, "count_agree", json_boolean(agree));
        /* which route counted: the table in balls (certified signs), or
         * exactly, the minors' signs from word-size primes (jury.c) or the
         * integer table */
        json_object_set_new(o, "schur_cohn_route", decided
            ? json_pack("{s:s,s:I}", "method", "Schur-Cohn table in ball arithmetic, every row's constant sign "
                        "certified non-zero", "precision_bits", (json_int_t) bprec)
            : rs_json_jury_route(ju));
        if (decided)
            json_object_set_new(o, "count_certified", json_string("both counts are certified (ball arithmetic), "
                                "neither exact: the verdict rests on two independent certified counts"));
        if (!agree) {
            json_t *d = json_object();
            run->outcome |= RS_OUTCOME_INCONSISTENT;
            rs_json_add_count(d, rb);
            json_object_set_new(o, "ball_count", d);
        }
    }
    rs_jury_clear(ju);
    return r;
}

/* Only the roots that may be of largest modulus were refined to the digits
 * (above degree 64): say so, with a certified bound on the others' moduli. */
static void radius_outer_json(json_t *o, const rs_radius_t rr)
{
    arb_t a, top, rest;
    arf_t lb;
    slong i;
    char *s;
    arb_init(a);
    arb_init(top);
    arb_init(rest);
    arf_init(lb);
    for (i = 0; i < rr->nroots; i++) {        /* top: the largest lower bound */
        acb_abs(a, rr->roots + i, rr->prec);
        arb_get_lbound_arf(lb, a, rr->prec);
        if (i == 0 || arf_cmp(lb, arb_midref(top)) > 0) arb_set_arf(top, lb);
    }
    arb_zero(rest);
    for (i = 0; i < rr->nroots; i++) {        /* rest: the balls wholly below it */
        acb_abs(a, rr->roots + i, rr->prec);
        if (arb_lt(a, top)) arb_max(rest, rest, a, rr->prec);
    }
    arb_get_ubound_arf(lb, rest, rr->prec);
    arb_set_arf(rest, lb);
    s = rs_radius_str_upper(rest, 10);   /* a bound, not a result: 10 digits */
    json_object_set_new(o, "certified_outer_only", json_pack("{s:I,s:I,s:s,s:s}", "refined_roots", (json_int_t) rr->nouter,
        "roots", (json_int_t) rr->nroots, "others_within", s,
        "note", "only the roots that may be of largest modulus were certified to the requested digits; "
        "the others are certified isolating balls (about 60 bits) inside |lambda| <= others_within"));
    flint_free(s);
    arb_clear(a);
    arb_clear(top);
    arb_clear(rest);
    arf_clear(lb);
}

static int radius_real(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_optval_t *dg = rs_an_opt(req, "digits");
    rs_variant_t *v;
    fmpz_poly_t p;
    rs_radius_t rr;
    rs_rootcount_t rc;
    const char *method = rs_an_opt_choice(req, "method");
    slong digits = dg->at != NULL ? dg->num : run->opt->default_digits, i;
    json_t *o, *roots;
    int r, done;
    r = rs_run_variant_or_vanishing(&v, &done, run, "radius", 1);
    if (r != RS_OK || done) return r;
    if (v->singular) {
        /* the implicit step cannot be solved: no recurrence, so no radius is
         * claimed (not even a dead-beat rho 0 of the reduced polynomial);
         * singular as stability says */
        o = json_object();
        json_object_set_new(o, "analysis", json_string("radius"));
        json_object_set_new(o, "status", json_string(rs_status_name(RS_STATUS_SINGULAR)));
        json_object_set_new(o, "exact_status", json_string(rs_status_name(RS_STATUS_SINGULAR)));
        json_object_set_new(o, "singular", json_string("the leading coefficient of det A(lambda) vanishes here: the "
                            "implicit step cannot be solved, so there is no recurrence and no spectral radius"));
        rs_run_emit_exact(run, v, o);
        return RS_OK;
    }
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, q, v, "radius");
    if (r != RS_OK) { fmpz_poly_clear(p); return r; }
    rs_radius_init(rr);
    rs_rootcount_init(rc);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("radius"));
    if (fmpz_poly_degree(p) < 1) {
        /* det A = c*lambda^k: every root is 0 (dead-beat), radius exactly 0 */
        rs_run_radius_dead_beat_json(o);
        if (!v->s->complex_char)
            rs_json_zero_roots(json_object_get(o, "roots"), v->cp->removed_lambda_power, digits);
        arb_zero(rr->lower);
        arb_zero(rr->upper);
        arb_zero(rr->rho);
    } else if (strcmp(method, "double") == 0) {
        r = rs_radius_double(rr, p, run->err);
        if (r == RS_OK) {
            json_object_set_new(o, "method", json_string("double (GSL gsl_poly_complex_solve, uncertified)"));
            json_object_set_new(o, "certified", json_false());
            json_object_set_new(o, "rho", json_real(rr->rho_double));
            roots = json_array();
            for (i = 0; i < rr->nroots; i++)
                json_array_append_new(roots, json_pack("{s:f,s:f}", "re",
                    arf_get_d(arb_midref(acb_realref(rr->roots + i)), ARF_RND_NEAR), "im",
                    arf_get_d(arb_midref(acb_imagref(rr->roots + i)), ARF_RND_NEAR)));
            json_object_set_new(o, "roots", roots);
        }
    } else {
        if (strcmp(method, "companion") == 0)
            r = rs_radius_fmpz_poly_companion(rr, p, digits, run->opt->max_prec, run->err);
        else
            r = rs_radius_fmpz_poly(rr, p, digits, run->opt->max_prec, run->err);
        if (r == RS_OK) {
            json_object_set_new(o, "method", json_string(
                rr->method == RS_RADIUS_METHOD_COMPANION ? "companion matrix, acb_mat_eig_simple/multiple (certified)"
                : rr->method == RS_RADIUS_METHOD_COMPLEX_ROOTS ? "arb_fmpz_poly_complex_roots on squarefree factors (certified)"
                : rr->method == RS_RADIUS_METHOD_FIND_ROOTS ? "Aberth-Ehrlich + inclusion discs, acb_poly_find_roots as fallback, on squarefree factors (certified)"
                : "certified enclosure"));
            rs_json_radius(o, rr, digits);
            roots = json_array();
            /* det's roots at 0 that charpoly.c divided out, first (none
             * left in p at the point: the variant's p is normalised there) */
            if (!v->s->complex_char) rs_json_zero_roots(roots, v->cp->removed_lambda_power, digits);
            for (i = 0; i < rr->nroots; i++) {
                json_t *z = rs_json_acb(rr->roots + i, digits);
                arb_t ab;
                arb_init(ab);
                acb_abs(ab, rr->roots + i, rr->prec);
                json_object_set_new(z, "abs", rs_json_arb(ab, digits));
                json_object_set_new(z, "multiplicity", json_integer(rr->mult ? rr->mult[i] : 1));
                arb_clear(ab);
                json_array_append_new(roots, z);
            }
            json_object_set_new(o, "roots", roots);
            if (rr->nouter > 0) radius_outer_json(o, rr);
        }
    }
    /* a char line with i: rr has p conj(p)'s roots (the block form); list p's own */
    if (r == RS_OK && v->s->complex_char) r = rs_an_complex_char_roots(run, req, o, digits);
    if (r == RS_OK) {
        /* the exact verdict at the same point decides; the radius must agree */
        if (fmpz_poly_degree(p) > RS_RADIUS_HIGH_DEGREE && strcmp(method, "double") != 0)
            r = radius_count_high(rc, run, p, rr, o);
        else   /* below degree 65 both exact counts run; the report says so */
            r = radius_count_exact(rc, run, p, o);
    }
    if (r == RS_OK) {
        rs_status_t st;
        int consistent = 1;
        r = rs_run_verdict(&st, run, v->s, NULL, NULL, 0, p, rc, v->singular, NULL);
        json_object_set_new(o, "exact_status", json_string(rs_status_name(st)));
        if (strcmp(method, "double") != 0) {
            const char *nv;
            slong got = radius_refine(rr, run, p, rc, method, digits);
            if (got > digits) {
                /* the printed bounds came from the refined run: reprint */
                rs_json_radius(o, rr, digits);
                json_object_set_new(o, "verdict_digits", json_integer(got));
            }
            /* only certified comparisons: a radius interval that contains 1
             * decides nothing, so it cannot contradict the exact count */
            nv = rs_radius_verdict(rr);
            if (strcmp(nv, "stable") == 0 && (rc->on > 0 || rc->outside > 0)) consistent = 0;
            if (strcmp(nv, "unstable") == 0 && rc->outside == 0) consistent = 0;
            json_object_set_new(o, "verdict_from_radius", json_string(strcmp(nv, "undecided") != 0 ? nv :
                "undecided numerically (the interval contains 1): the exact side decides"));
            json_object_set_new(o, "consistent", json_boolean(consistent));
            if (!consistent) run->outcome |= RS_OUTCOME_INCONSISTENT;
        }
        /* the ball table counted: two certified counts, no exact one */
        json_object_set_new(o, "decided_by", json_string(json_object_get(o, "count_certified") != NULL
                                                         ? "certified" : "exact"));
        json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
        json_array_append_new(run->results, o);
    } else {
        json_decref(o);
        r = rs_req_relocate(run, q, r, "radius");
    }
    rs_rootcount_clear(rc);
    rs_radius_clear(rr);
    fmpz_poly_clear(p);
    return r;
}

/* ---- numeric recurrences ------------------------------------------------------ */

static int rec_radius(rs_run_t *run, slong digits, int stability, const rs_request_t *q)
{
    slong prec, K = 0, i;
    rs_radius_t rr;
    json_t *o;
    int r = RS_ERR_UNDECIDED;
    rs_radius_init(rr);
    for (prec = 3.33 * digits + 64; prec <= run->opt->max_prec; prec *= 2) {
        acb_mat_struct *A = NULL;
        r = rs_recurrence_matrices(&A, &K, run->m, prec, run->err);
        if (r == RS_OK) r = rs_radius_matrix_poly(rr, A, K, digits, run->opt->max_prec, run->err);
        for (i = 0; A && i <= K; i++) acb_mat_clear(A + i);
        flint_free(A);
        if (r != RS_ERR_UNDECIDED && r != RS_ERR_LIMIT) break;
        rs_error_init(run->err);
    }
    if (r != RS_OK) {
        rs_radius_clear(rr);
        /* out of precision is a resource limit of the request */
        if (run->err->file[0] == '\0' && r == RS_ERR_UNDECIDED) r = RS_ERR_LIMIT;
        return rs_req_relocate(run, q, r, "radius");
    }
    o = json_object();
    json_object_set_new(o, "analysis", json_string(stability ? "stability" : "radius"));
    json_object_set_new(o, "method", json_string("block companion matrix of the recurrence, entries in Arb "
                                                 "(certified eigenvalue enclosures)"));
    rs_json_radius(o, rr, digits);
    json_object_set_new(o, "status", json_string(rs_radius_verdict(rr)));
    json_object_set_new(o, "decided_by", json_string("certified"));
    json_object_set_new(o, "substituted", rs_json_sets(run->c));
    json_array_append_new(run->results, o);
    rs_radius_clear(rr);
    return RS_OK;
}

/* ---- exactly integrated co-simulation ------------------------------------------ */

static int cosim_radius(rs_run_t *run, slong digits, int stability, const rs_request_t *q)
{
    rs_cosim_t cs;
    rs_radius_t rr, rm;
    json_t *o;
    int r, partial = 0, mono = 0, inside = 0, stable = 0;
    rs_cosim_init(cs, 1, 1);
    r = rs_run_cosim(cs, run);
    if (r != RS_OK) { rs_cosim_clear(cs); return r; }
    rs_radius_init(rr);
    rs_radius_init(rm);
    r = rs_cosim_radius(rr, cs, digits, run->opt->max_prec, run->err);
    if (r == RS_ERR_UNDECIDED && rr->partial && arb_is_finite(rr->lower) && arb_is_finite(rr->upper)
        && strcmp(rs_radius_verdict(rr), "undecided") != 0) {
        /* eigenvalues not isolated (a double eigenvalue of exp(A h)), but the
         * certified enclosure excludes 1 and decides, as a sweep point does
         * (it was an exit 2 with a stable rho <= 0.85 certified) */
        partial = 1;
        rs_error_init(run->err);
        r = RS_OK;
        /* the enclosure's verdict checked by a second method: Schur's
         * recursion on T's ball characteristic polynomial (a failure to
         * certify leaves it unchecked, said in the JSON) */
        if (rs_cosim_check_inside(&inside, cs, run->opt->max_prec, run->err) != RS_OK) {
            rs_error_init(run->err);
            inside = 0;
        }
        stable = strcmp(rs_radius_verdict(rr), "stable") == 0;
        if ((stable && inside < 0) || (!stable && inside > 0)) run->outcome |= RS_OUTCOME_INCONSISTENT;
    }
    if (r == RS_OK && !partial) {   /* partial: the monolithic one has the same cluster */
        r = rs_cosim_monolithic_radius(rm, cs, digits, run->opt->max_prec, run->err);
        mono = (r == RS_OK);
    }
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string(stability ? "stability" : "radius"));
        json_object_set_new(o, "method", json_string("exact subsystem integration (matrix exponentials, Arb), "
                                                     "certified eigenvalues of the one-step map"));
        json_object_set_new(o, "coupling", json_pack("{s:s,s:I}", "method", cs->method == RS_COSIM_IMPLICIT ? "implicit" : "explicit",
                                                     "order", (json_int_t) cs->order));
        rs_json_radius(o, rr, digits);
        if (partial) {
            json_object_set_new(o, "note", json_string("eigenvalues not isolated (multiple eigenvalue or cluster): "
                                                       "the certified enclosure [lower, upper] decides, rho is not "
                                                       "to the digits requested"));
            json_object_set_new(o, "cross_check", json_pack("{s:s,s:s,s:b}",
                "method", "Schur's recursion on the ball characteristic polynomial of the one-step map",
                "result", inside > 0 ? "every root inside" : inside < 0 ? "a root outside (|det| > 1)" : "undecided",
                "agree", !((stable && inside < 0) || (!stable && inside > 0))));
        }
        json_object_set_new(o, "monolithic_rho", mono ? rs_json_arb(rm->rho, digits) : json_null());
        json_object_set_new(o, "status", json_string(rs_radius_verdict(rr)));
        json_object_set_new(o, "decided_by", json_string("certified"));
        json_object_set_new(o, "substituted", rs_json_sets(run->c));
        json_array_append_new(run->results, o);
    } else {
        r = rs_req_relocate(run, q, r, "radius");
    }
    rs_radius_clear(rr);
    rs_radius_clear(rm);
    rs_cosim_clear(cs);
    return r;
}

/* radius and stability of the numeric model kinds: one grammar, two engines */
static int numeric(rs_run_t *run, const rs_an_req_t *req, int stability)
{
    const rs_optval_t *d = rs_an_opt(req, "digits");
    slong digits = d->at != NULL ? d->num : run->opt->default_digits;
    if (run->m->kind == RS_MODEL_RECURRENCE) return rec_radius(run, digits, stability, req->q);
    return cosim_radius(run, digits, stability, req->q);
}

int rs_an_numeric_radius(rs_run_t *run, const rs_an_req_t *req)
{
    return numeric(run, req, 0);
}

int rs_an_numeric_stability(rs_run_t *run, const rs_an_req_t *req)
{
    return numeric(run, req, 1);
}

int rs_an_radius(rs_run_t *run, const rs_an_req_t *req)
{
    if (run->m->qd != NULL) return rs_an_qd_radius(run, req);   /* over Q(sqrt d) (an_qd.c) */
    /* at complex set values: over Q(i) (an_complex.c) */
    if (rs_an_complex_mode(run)) return rs_an_complex_radius(run, req);
    return radius_real(run, req);
}
