/* an_modes.c -- `modes`: for each root the equivalent continuous
 * eigenvalue ln(lambda)/h, damping ratio and, for the principal roots of each
 * reference frequency, the relative frequency error. */
#include <math.h>
#include <stdlib.h>
#include <fmpz.h>
#include <fmpq_poly.h>
#include <acb_poly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "numeric/modes.h"
#include "stability/routh_complex.h"
#include "stability/schur_complex.h"

/* ---- modes ------------------------------------------------------------------------ */

/* A numeric request expression (parameters allowed, at their set values). */
static int eval_number(arb_t out, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v, const char *text,
                       slong prec)
{
    fmpq_t a;
    int r;
    fmpq_init(a);
    r = rs_req_eval_points(a, 1, run, q, v, text, -1, NULL, 1, NULL);
    if (r == RS_OK) arb_set_fmpq(out, a, prec);
    fmpq_clear(a);
    return r;
}

/* "h", "modes", "spurious", "note" of o from the certified roots rr (every
 * model kind: the equations' p, the co-simulation's one-step map) */
void rs_an_modes_json(json_t *o, const rs_radius_t rr, const arb_t h, const arb_t *refs, slong nref, slong prec,
                      slong digits)
{
    /* principal roots: for each reference w0, the root with Im >= 0 closest to
     * exp(i w0 h) and its conjugate; every other root is spurious */
    int *principal = calloc((size_t) rr->nroots + 1, sizeof(int));
    json_t *modes, *spur;
    slong i;
    rs_modes_principal(principal, rr, h, (arb_srcptr) refs, nref, prec);
    json_object_set_new(o, "h", rs_json_arb(h, digits));
    modes = json_array();
    spur = json_array();
    for (i = 0; i < rr->nroots; i++) {
        json_t *m = json_object();
        arb_t sig, om, mag, xi, err;
        arb_init(sig); arb_init(om); arb_init(mag); arb_init(xi); arb_init(err);
        json_object_set_new(m, "root", rs_json_acb(rr->roots + i, digits));
        if (acb_is_zero(rr->roots + i)) {
            json_object_set_new(m, "note", json_string("root at 0: no continuous equivalent"));
        } else {
            rs_modes_continuous(sig, om, mag, xi, rr->roots + i, h, prec);
            json_object_set_new(m, "sigma", rs_json_arb(sig, digits));
            json_object_set_new(m, "omega", rs_json_arb(om, digits));
            if (arb_is_finite(xi)) {
                json_object_set_new(m, "damping_ratio", rs_json_arb(xi, digits));
            } else {   /* -sigma/|lambda_c| with lambda_c = 0 (or not certified away from 0): 0/0 */
                json_object_set_new(m, "damping_ratio", json_null());
                json_object_set_new(m, "damping_note", json_string(arb_is_zero(mag)
                    ? "undefined: lambda = 1, so lambda_c = 0" : "undefined: |lambda_c| is not certified away from 0"));
            }
            if (principal[i]) {
                arb_sub(err, mag, refs[principal[i] - 1], prec);
                arb_div(err, err, refs[principal[i] - 1], prec);
                json_object_set_new(m, "reference", rs_json_arb(refs[principal[i] - 1], digits));
                json_object_set_new(m, "frequency_error", rs_json_arb(err, digits));
            }
        }
        json_array_append_new((principal[i] || nref == 0) ? modes : spur, m);
        arb_clear(sig); arb_clear(om); arb_clear(mag); arb_clear(xi); arb_clear(err);
    }
    json_object_set_new(o, "modes", modes);
    json_object_set_new(o, "spurious", spur);
    json_object_set_new(o, "note", json_string(
        "lambda_c = ln(lambda)/h = sigma +- i omega (principal logarithm); damping ratio = -sigma/|lambda_c|; "
        "frequency error = (|lambda_c| - omega0)/omega0 for the principal roots of each reference omega0"));
    free(principal);
}

/* ---- p over Q(i): its own roots -------------------------------------------------- */

static slong cdeg(const fmpq_poly_t re, const fmpq_poly_t im)
{
    return FLINT_MAX(fmpq_poly_degree(re), fmpq_poly_degree(im));
}

/* rr's roots (with multiplicity) of p = pr + i pi over Q(i), 100 relative bits */
static int modes_cx_roots(rs_radius_t rr, const fmpq_poly_t pr, const fmpq_poly_t pi, slong max_prec, rs_error_t err)
{
    int ok = rs_cx_roots(rr, pr, pi, 100, 2 * 100 + 64, max_prec);
    if (ok == 0)
        return rs_error_set(err, RS_ERR_LIMIT, "modes over Q(i): the roots of p were not isolated within the "
                            "precision limit (%ld bits)", (long) max_prec);
    if (ok < 0)
        return rs_error_set(err, RS_ERR_INCONSISTENT, "modes over Q(i): the squarefree decomposition's degrees "
                            "do not add up to p's degree %ld", (long) cdeg(pr, pi));
    return RS_OK;
}

/* the certified moduli against the exact counts over Q(i) (Schur-Cohn and
 * Bilharz): a root certified inside (outside) needs one counted there */
static int complex_check(rs_run_t *run, const rs_radius_t rr, const fmpq_poly_t pr, const fmpq_poly_t pi, json_t *o)
{
    rs_routh_complex_t t;
    rs_status_t st;
    slong n = cdeg(pr, pi), k, in = 0, out = 0, open = 0;
    int r, agree;
    rs_routh_complex_init(t);
    r = rs_routh_complex_checked_status(&st, pr, pi, n, run->err);
    if (r == RS_OK) r = rs_routh_complex_status(&st, t, pr, pi, n, run->err);
    if (r == RS_OK) {
        arb_t m, one;
        arb_init(m); arb_init(one);
        arb_one(one);
        for (k = 0; k < rr->nroots; k++) {
            acb_abs(m, rr->roots + k, 128);
            if (arb_lt(m, one)) in++;
            else if (arb_gt(m, one)) out++;
            else open++;
        }
        arb_clear(m); arb_clear(one);
        agree = in <= t->left && out <= t->right && (open > 0 || (in == t->left && out == t->right));
        json_object_set_new(o, "exact_check", json_pack("{s:s,s:I,s:I,s:I,s:I,s:I,s:I,s:b}", "status",
                            rs_status_name(st), "inside", (json_int_t) t->left,
                            "on", (json_int_t) (t->axis + (n - t->degree)), "outside", (json_int_t) t->right,
                            "certified_inside", (json_int_t) in, "certified_outside", (json_int_t) out,
                            "modulus_undecided", (json_int_t) open, "agree", agree));
        if (!agree) run->outcome |= RS_OUTCOME_INCONSISTENT;
    }
    rs_routh_complex_clear(t);
    return r;
}

int rs_an_modes(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_optval_t *o_h = rs_an_opt(req, "h"), *o_ref = rs_an_opt(req, "reference");
    rs_variant_t *v;
    fmpz_poly_t p;
    rs_radius_t rr;
    const char *hs;
    arb_t h, *refs = NULL;
    slong nref = 0, i, prec = 128, digits = 15;
    json_t *o;
    int r;
    int qd = run->m->qd != NULL, cx = !qd && rs_an_complex_conds_applies(run);
    fmpq_poly_t pr, pi;
    json_t *at = NULL;
    fmpz_poly_init(p);
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    if (qd) {
        /* over Q(sqrt d): the variant only evaluates h and reference */
        r = rs_run_default_variant(run, &v);
    } else if (cx) {
        /* p over Q(i): its own roots, not those of the real block form p conj(p) */
        r = rs_an_complex_point_poly(pr, pi, &at, &v, run, req);
    } else {
        v = NULL;
        r = rs_run_numeric_variant(run, &v);
        if (r != RS_OK && v != NULL && v->vanishes) {   /* singular: no mode, as stability says */
            fmpz_poly_clear(p);
            fmpq_poly_clear(pr); fmpq_poly_clear(pi);
            return rs_run_failed_or_vanishing(run, r, v, "modes");
        }
        if (r == RS_OK) r = rs_run_numeric_poly(p, run, q, v, "modes");
        /* det = c lambda^k p: its roots at 0 are modes too (no continuous
         * equivalent), listed as over Q(i), where p keeps them */
        if (r == RS_OK) fmpz_poly_shift_left(p, p, v->cp->removed_lambda_power);
    }
    if (r != RS_OK) {
        fmpz_poly_clear(p);
        fmpq_poly_clear(pr); fmpq_poly_clear(pi);
        json_decref(at);
        return r;
    }
    arb_init(h);
    arb_one(h);
    /* options: h=EXPR (time step; default 1 for schemes scaled by h), reference=EXPR[,EXPR...] */
    hs = o_h->val;
    if (hs != NULL) {
        r = eval_number(h, run, q, v, hs, prec);
        /* ln(lambda)/h: a step must be positive */
        if (r == RS_OK && !arb_is_positive(h))
            r = rs_req_error(run, q, hs, RS_ERR_INPUT, "expected a time step h > 0, found '%s'", hs);
    }
    if (r == RS_OK && o_ref->nlist > 0) {
        refs = calloc((size_t) o_ref->nlist, sizeof(arb_t));
        for (i = 0; i < o_ref->nlist && r == RS_OK; i++) {
            arb_init(refs[nref]);
            r = eval_number(refs[nref], run, q, v, o_ref->list[i], prec);
            nref++;
        }
    }
    rs_radius_init(rr);
    o = NULL;
    /* a real dead-beat p = c (det A = c lambda^k, the roots at 0 divided out):
     * no mode, as `stability` and `radius` accept it */
    if (r == RS_OK && qd) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("modes"));
        r = rs_an_qd_modes_roots(rr, o, run, q, digits);
        if (r == RS_OK) {
            json_object_set_new(o, "roots_of", json_string(
                "p over Q(sqrt d)(i) at the set values (acb_poly_find_roots, validated; sqrt d a ball) and the "
                "roots at 0 the charpoly divided out"));
            rs_an_modes_json(o, rr, h, refs, nref, prec, digits);
            json_object_set_new(o, "decided_by", json_string("certified"));
            json_array_append_new(run->results, o);
        } else {
            json_decref(o);
        }
        o = NULL;
    } else if (r == RS_OK && (cx || fmpz_poly_degree(p) >= 1))
        r = cx ? modes_cx_roots(rr, pr, pi, run->opt->max_prec, run->err)
               : rs_radius_fmpz_poly(rr, p, 30, run->opt->max_prec, run->err);
    if (r == RS_OK && !qd) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("modes"));
        if (cx) {
            json_object_set_new(o, "over", json_string("Q(i)"));
            json_object_set_new(o, "at", at);
            at = NULL;
            json_object_set_new(o, "roots_of", json_string(
                "p over Q(i) itself (Yun's squarefree decomposition over Q(i), each factor's roots isolated by "
                "acb_poly_find_roots), not the real block form p conj(p)"));
        }
        rs_an_modes_json(o, rr, h, refs, nref, prec, digits);
        if (cx) r = complex_check(run, rr, pr, pi, o);
    }
    if (r == RS_OK && !qd) {
        json_object_set_new(o, "decided_by", json_string("certified"));
        json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
        /* det A drops its degree here: the modes are the reduced p's, the step singular (h-truth6) */
        if (v->singular) rs_json_set_singular_step(o);
        json_array_append_new(run->results, o);
    } else {
        json_decref(o);
    }
    for (i = 0; i < nref; i++) arb_clear(refs[i]);
    free(refs);
    arb_clear(h);
    rs_radius_clear(rr);
    fmpz_poly_clear(p);
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    json_decref(at);
    return r;
}
