/* an_modes.c -- `modes`: for each root the equivalent continuous
 * eigenvalue ln(lambda)/h, damping ratio and, for the principal roots of each
 * reference frequency, the relative frequency error. */
#include <math.h>
#include <stdlib.h>
#include "analysis/registry.h"
#include "numeric/modes.h"

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
            json_object_set_new(m, "damping_ratio", rs_json_arb(xi, digits));
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
    r = rs_run_numeric_variant(run, &v);
    if (r != RS_OK) return r;
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, q, v, "modes");
    if (r != RS_OK) { fmpz_poly_clear(p); return r; }
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
    if (r != RS_OK) {
        for (i = 0; i < nref; i++) arb_clear(refs[i]);
        free(refs);
        arb_clear(h);
        fmpz_poly_clear(p);
        return r;
    }
    rs_radius_init(rr);
    r = rs_radius_fmpz_poly(rr, p, 30, run->opt->max_prec, run->err);
    if (r != RS_OK) {
        for (i = 0; i < nref; i++) arb_clear(refs[i]);
        free(refs);
        arb_clear(h);
        rs_radius_clear(rr);
        fmpz_poly_clear(p);
        return r;
    }
    o = json_object();
    json_object_set_new(o, "analysis", json_string("modes"));
    rs_an_modes_json(o, rr, h, refs, nref, prec, digits);
    json_object_set_new(o, "decided_by", json_string("certified"));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_array_append_new(run->results, o);
    for (i = 0; i < nref; i++) arb_clear(refs[i]);
    free(refs);
    arb_clear(h);
    rs_radius_clear(rr);
    fmpz_poly_clear(p);
    return RS_OK;
}
