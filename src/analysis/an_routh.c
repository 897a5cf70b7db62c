/* an_routh.c -- `routh`: the exact Routh array of q(z), singular cases
 * (zero pivot, zero row, degree drop, q(0) = 0) handled and named. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "recstab/bilinear.h"
#include "recstab/routh.h"
#include "util/polyfmt.h"

static const char *event_name(rs_routh_event_kind_t k)
{
    switch (k) {
    case RS_ROUTH_EVENT_DEGREE_DROP: return "degree_drop";
    case RS_ROUTH_EVENT_ZERO_AT_ORIGIN: return "zero_at_origin";
    case RS_ROUTH_EVENT_ZERO_PIVOT: return "zero_pivot";
    case RS_ROUTH_EVENT_ZERO_ROW: return "zero_row";
    }
    return "?";
}

/* The exact Routh array of p (numbers) into o. */
static int routh_numeric(rs_run_t *run, const rs_variant_t *v, const fmpz_poly_t p, json_t *o)
{
    rs_routh_t ro;
    json_t *rows, *pw, *ev;
    slong i, j;
    int r;
    rs_routh_init(ro);
    r = rs_routh_fmpz_poly(ro, p, run->err);
    if (r != RS_OK) {
        rs_routh_clear(ro);
        return r;
    }
    rows = json_array();
    pw = json_array();
    ev = json_array();
    for (i = 0; i < ro->nrows; i++) {
        json_t *row = json_array();
        for (j = 0; j < ro->rowlen[i]; j++)
            json_array_append_new(row, rs_json_fmpq(ro->rows[i] + j));
        json_array_append_new(rows, row);
        json_array_append_new(pw, json_integer(ro->rowpow[i]));
    }
    if (ro->neps > 0) {
        /* zero pivot: the textbook rows (one per power) in Q(eps) for
         * display; the exact generalised rows are kept beside them */
        json_t *er = json_array(), *ep = json_array(), *es = json_array();
        for (i = 0; i < ro->neps; i++) {
            json_t *row = json_array();
            for (j = 0; j < ro->epslen[i]; j++) {
                char *str = fmpz_poly_q_get_str_pretty(ro->eps[i] + j, "eps");
                json_array_append_new(row, json_string(str));
                flint_free(str);
            }
            json_array_append_new(er, row);
            json_array_append_new(ep, json_integer(ro->neps - 1 - i));
            json_array_append_new(es, json_integer(ro->epssign[i]));
        }
        json_object_set_new(o, "generalised_rows", rows);
        json_object_set_new(o, "generalised_powers", pw);
        json_object_set_new(o, "epsilon_signs", es);
        json_object_set_new(o, "epsilon_note", json_string(
            "rows: the textbook array computed exactly in Q(eps), each zero first entry replaced by eps; "
            "epsilon_signs: the first column as eps -> 0+; the count is decided by the exact generalised "
            "step (generalised_rows, remainders of the two rows above, powers in generalised_powers)"));
        rows = er;
        pw = ep;
    }
    json_object_set_new(o, "powers", pw);
    for (i = 0; i < ro->nevents; i++)
        json_array_append_new(ev, json_pack("{s:s,s:I,s:I,s:s}", "kind",
                              event_name(ro->events[i].kind), "row", (json_int_t) ro->events[i].row,
                              "count", (json_int_t) ro->events[i].count, "text",
                              ro->events[i].text ? ro->events[i].text : ""));
    json_object_set_new(o, "symbolic", json_false());
    json_object_set_new(o, "rows", rows);
    json_object_set_new(o, "events", ev);
    json_object_set_new(o, "sign_changes", json_integer(ro->sign_changes));
    /* the array is q's of p = det/lambda^k: the k roots at 0 (z = -1) count inside */
    rs_run_count_zeros(ro->count, v, p);
    rs_json_add_count(o, ro->count);
    r = rs_run_numeric_verdict(run, p, ro->count, o);
    rs_routh_clear(ro);
    return r;
}

/* The events of a symbolic array: a degree drop of q for every value, a
 * row vanishing identically. */
static void routh_symbolic_events(json_t *o, const rs_variant_t *v, const fmpz_mpoly_t qz, const rs_routh_mpoly_t rm)
{
    const rs_scheme_struct *s = v->s;
    slong drop = v->cp->degree - fmpz_mpoly_degree_si(qz, s->lambda_var, s->zctx);
    json_t *ev = json_array();
    if (drop > 0) {
        char txt[300];
        snprintf(txt, sizeof txt, "deg q = %ld < deg p = %ld for every parameter value: lambda = -1 is a "
                 "root of multiplicity %ld (z = infinity), on the unit circle; never asymptotically stable",
                 (long) (v->cp->degree - drop), (long) v->cp->degree, (long) drop);
        json_array_append_new(ev, json_pack("{s:s,s:I,s:I,s:s}", "kind", "degree_drop", "row",
                                            (json_int_t) 0, "count", (json_int_t) drop, "text", txt));
    }
    if (rm->zero_row >= 0) {
        char txt[300];
        snprintf(txt, sizeof txt, "row %ld vanished identically (roots symmetric about the origin for "
                 "every parameter value: on the imaginary axis, i.e. on the unit circle, or in pairs "
                 "+-z); replaced by the derivative of the auxiliary polynomial of row %ld",
                 (long) rm->zero_row, (long) rm->zero_row - 1);
        json_array_append_new(ev, json_pack("{s:s,s:I,s:s}", "kind", "zero_row", "row",
                                            (json_int_t) rm->zero_row, "text", txt));
    }
    if (json_array_size(ev) > 0) json_object_set_new(o, "events", ev);
    else json_decref(ev);
}

/* The first row whose first entry is 0 for every parameter value (the zero
 * row, before its replacement, counts), -1 if none.  Above the zero row the
 * fraction-free first entry of row k is the Hurwitz minor D_k (routh.h). */
static slong routh_null_pivot(const rs_routh_mpoly_t rm, const fmpz_mpoly_ctx_t ctx)
{
    slong k;
    if (rm->zero_row >= 0) return rm->zero_row;
    for (k = 0; k < rm->nrows; k++)
        if (fmpz_mpoly_is_zero(rm->rows[k] + 0, ctx)) return k;
    return -1;
}

/* A(z) := the auxiliary polynomial of row k (its entries on the powers
 * deg, deg - 2, ... of z); 1 if lc(A)^e q = Q A exactly (A divides q over
 * Q(params), as the zero row below it says), else 0 */
static int routh_auxiliary(fmpz_mpoly_t A, const rs_routh_mpoly_t rm, slong k, const fmpz_mpoly_t qz,
                           slong var, const fmpz_mpoly_ctx_t ctx)
{
    slong m = rm->nrows - 1, deg = m - k, j;
    fmpz_mpoly_t t, g, lhs;
    int ok;
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(g, ctx);
    fmpz_mpoly_init(lhs, ctx);
    fmpz_mpoly_zero(A, ctx);
    fmpz_mpoly_gen(g, var, ctx);
    for (j = 0; j < rm->rowlen[k] && deg - 2 * j >= 0; j++) {
        fmpz_mpoly_pow_ui(t, g, (ulong) (deg - 2 * j), ctx);
        fmpz_mpoly_mul(t, t, rm->rows[k] + j, ctx);
        fmpz_mpoly_add(A, A, t, ctx);
    }
    fmpz_mpoly_pow_ui(lhs, rm->rows[k] + 0, (ulong) (m - deg + 1), ctx);
    fmpz_mpoly_mul(lhs, lhs, qz, ctx);
    ok = !fmpz_mpoly_is_zero(A, ctx) && fmpz_mpoly_divides(t, lhs, A, ctx);
    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(g, ctx);
    fmpz_mpoly_clear(lhs, ctx);
    return ok;
}

/* routh's "never" checked at the sample points: the exact point verdict
 * (rs_run_sample_check) and hurwitz's conditions on the same q must both
 * say "not stable" there */
typedef struct {
    const rs_hurwitz_or_struct *hb;   /* NULL: no second route */
    const rs_run_t *run;
    json_t *bad;
    slong points;
} routh_cross_t;

static int routh_never_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    routh_cross_t *w = (routh_cross_t *) data;   /* our own, writable */
    int h;
    if (w->hb == NULL) return 0;
    h = rs_hurwitz_or_holds(w->hb, pt, s->zctx);
    if (h < 0) return 0;
    w->points++;
    if (h == 1 && w->bad == NULL) w->bad = rs_run_point_json(w->run, pt, s->nvars);
    return 0;
}

/* A first-column entry of the symbolic array is 0 for every parameter
 * value (row k): a q with every root in Re z < 0 has every Hurwitz minor
 * D_1 .. D_n nonzero (Hurwitz 1895), and that entry is D_k, so never
 * asymptotically stable -- for every value, also where earlier pivots
 * vanish (there D_k = 0 still).  A whole zero row adds the auxiliary
 * polynomial A(z) of the row above, a factor of q with roots symmetric
 * about z = 0.  k < 0: q's degree dropped (p(-1) = 0 for every value).
 * Cross-checked with hurwitz's conditions on the same q
 * (exit 3 if they hold somewhere or say always) and the exact point verdict. */
static int routh_never(rs_run_t *run, const rs_request_t *q, const rs_variant_t *v, const fmpz_mpoly_t qz,
                       const rs_routh_mpoly_t rm, slong k, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    slong m = rm->nrows - 1;
    char *why = NULL;
    json_t *cr = json_pack("{s:s}", "with", "hurwitz (Lienard-Chipart conditions of the same q(z))");
    routh_cross_t w = {NULL, run, NULL, 0};
    rs_hurwitz_or_t hb;
    fmpz_mpoly_t qh;
    int r, hv = -1;
    if (rm->zero_row >= 0) {
        fmpz_mpoly_t A;
        const char **names = flint_malloc(s->nvars * sizeof(char *));
        char *as;
        slong i;
        int ok;
        for (i = 0; i < s->nvars; i++) names[i] = s->vars[i];
        names[s->lambda_var] = "z";
        fmpz_mpoly_init(A, s->zctx);
        ok = routh_auxiliary(A, rm, k - 1, qz, s->lambda_var, s->zctx);
        as = rs_polyfmt_fmpz_mpoly(A, names, s->zctx);
        json_object_set_new(o, "auxiliary", json_string(as));
        json_object_set_new(o, "auxiliary_divides_q", json_boolean(ok));
        rs_str_catf(&why, "row %ld (z^%ld) vanished identically, and its first entry is the Hurwitz minor D_%ld: "
                    "0 for every parameter value, while a q(z) with every root in Re z < 0 has every D_k nonzero "
                    "(Hurwitz); the auxiliary polynomial A(z) = %s of row %ld divides q(z) (where its leading "
                    "coefficient is nonzero), its roots symmetric about z = 0: on the imaginary axis (|lambda| = 1) "
                    "or in pairs +-z, one with Re z > 0 (|lambda| > 1); never asymptotically stable",
                    (long) k, (long) (m - k), (long) k, as, (long) (k - 1));
        free(as);
        flint_free(names);
        fmpz_mpoly_clear(A, s->zctx);
        if (!ok) run->outcome |= RS_OUTCOME_INCONSISTENT;   /* a theorem failed: a bug */
    } else if (k < 0) {
        rs_str_catf(&why, "p(-1) = 0 for every parameter value: deg q = %ld < deg p = %ld, lambda = -1 is a root "
                    "(z = infinity), on the unit circle; never asymptotically stable", (long) m,
                    (long) v->cp->degree);
    } else if (k == m) {
        /* D_n = q(0) D_{n-1}, D_{n-1} not identically 0 (the array went on) */
        rs_str_catf(&why, "the last row (z^0), the Hurwitz minor D_%ld = q(0) D_%ld, is 0 for every parameter value: "
                    "q(0) = 0, z = 0 (lambda = 1) is a root, on the unit circle; never asymptotically stable",
                    (long) m, (long) (m - 1));
    } else {
        rs_str_catf(&why, "the first entry of row %ld (z^%ld), the Hurwitz minor D_%ld, is 0 for every parameter "
                    "value (a zero pivot; the row itself is not zero): a q(z) with every root in Re z < 0 has "
                    "every D_k nonzero (Hurwitz); never asymptotically stable", (long) k, (long) (m - k), (long) k);
    }
    json_object_set_new(o, "never", json_string(why));
    json_object_set_new(o, "verdict", json_string("never stable"));
    flint_free(why);
    /* the second route: hurwitz on the same q */
    rs_hurwitz_or_init(hb);
    fmpz_mpoly_init(qh, s->zctx);
    r = rs_run_hurwitz_or(hb, run, v, qh);
    if (r == RS_OK) {
        json_t *ho = json_object();
        /* rs_json_hurwitz_or: 1 always, -1 never, 0 conditions */
        hv = rs_json_hurwitz_or(ho, hb, s);
        if (hv >= 0 && rs_run_hurwitz_or_never(run, ho, hb, s)) hv = -1;
        json_decref(ho);
        json_object_set_new(cr, "hurwitz_verdict", json_string(hv < 0 ? "never stable" : hv == 1
                            ? "always stable" : "stable iff the conditions hold"));
        w.hb = hb;
    } else {
        json_object_set_new(cr, "skipped", json_string(run->err->msg));
        rs_error_init(run->err);   /* routh's answer stands alone */
        r = RS_OK;
    }
    r = rs_run_sample_check(run, v, routh_never_holds, &w, o);
    if (w.hb != NULL) {
        json_object_set_new(cr, "points", json_integer(w.points));
        json_object_set_new(cr, "agree", json_boolean(w.bad == NULL && hv != 1));
        if (w.bad != NULL) json_object_set_new(cr, "point", w.bad);
        /* two theorems about the same q: a bug */
        if (w.bad != NULL || hv == 1) run->outcome |= RS_OUTCOME_INCONSISTENT;
    }
    json_object_set_new(o, "cross_route", cr);
    (void) q;
    rs_hurwitz_or_clear(hb, s->zctx);
    fmpz_mpoly_clear(qh, s->zctx);
    return r;
}

/* The fraction-free Routh array of q(z) with symbolic parameters into o. */
static int routh_symbolic(rs_run_t *run, const rs_request_t *q, const rs_variant_t *v, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    rs_routh_mpoly_t rm;
    fmpz_mpoly_t qz;
    slong i, j, nrows;
    int r;
    fmpz_mpoly_init(qz, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, s->lambda_var, s->zctx);
    rs_routh_mpoly_init(rm);
    r = rs_routh_mpoly(rm, qz, s->lambda_var, s->zctx, run->err);
    nrows = rm->nrows;
    /* a pivot identically 0: the rows up to it, and routh decides (routh_never) */
    if (r == RS_ERR_MATH) {
        rs_error_init(run->err);
        r = RS_OK;
        nrows = routh_null_pivot(rm, s->zctx) + 1;
    }
    if (r == RS_OK) {
        json_t *rows = json_array();
        slong k = routh_null_pivot(rm, s->zctx);
        for (i = 0; i < nrows; i++) {
            json_t *row = json_array();
            for (j = 0; j < rm->rowlen[i]; j++)
                json_array_append_new(row, rs_json_zpoly(rm->rows[i] + j, s));
            json_array_append_new(rows, row);
        }
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "rows", rows);
        if (nrows < rm->nrows) {
            /* stopped at a zero pivot: the rows' powers, as the numeric array gives them */
            json_t *pw = json_array();
            for (i = 0; i < nrows; i++) json_array_append_new(pw, json_integer(rm->nrows - 1 - i));
            json_object_set_new(o, "powers", pw);
        }
        routh_symbolic_events(o, v, qz, rm);
        /* the fraction-free first column is f_0 = r_0, f_k = r_1 r_2 ... r_k (r the textbook
         * column): "one sign" would be wrong where q's leading coefficient is negative */
        json_object_set_new(o, "note", json_string(rm->zero_row >= 0 ?
            "fraction-free rows; the zero row means roots symmetric about z = 0 for every parameter "
            "value (on the imaginary axis, i.e. on the unit circle, or pairs +-z): never asymptotically "
            "stable; the auxiliary polynomial's roots that lie on the imaginary axis are on the unit circle" :
            k >= 0 ? "fraction-free rows (each divided exactly by the pivot three rows up) up to the first "
            "pivot that is 0 for every parameter value; the first entry of row k is the Hurwitz minor D_k" :
            "fraction-free rows (each divided exactly by the pivot three rows up): first column f_0 = r_0, "
            "f_k = r_1 r_2 ... r_k (r the textbook column); valid where the first-column entries do not "
            "vanish: all roots have Re z < 0 iff every r_k has the sign of r_0, i.e. sign f_k = (sign f_0)^k "
            "(all positive when f_0 > 0, alternating when f_0 < 0)"));
        if (k >= 0 || fmpz_mpoly_degree_si(qz, s->lambda_var, s->zctx) < v->cp->degree)
            r = routh_never(run, q, v, qz, rm, k, o);
    }
    rs_routh_mpoly_clear(rm, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    return r;
}

static int routh_real(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    fmpz_poly_t p;
    json_t *o;
    int done, r = rs_run_variant_or_vanishing(&v, &done, run, "routh", 0);
    if (r != RS_OK || done) return r;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("routh"));
    json_object_set_new(o, "var", json_string("z"));
    fmpz_poly_init(p);
    if (rs_charpoly_get_fmpz_poly(p, v->cp->p, v->s->lambda_var, v->s->zctx) && v->s->complex_char
        && v->not_in_p == NULL) {
        /* a char line over Q(i): Bilharz on p itself (the block form's table
         * would count p's and conj(p)'s roots) */
        fmpz_poly_clear(p);
        json_decref(o);
        return rs_an_complex_routh(run, req);
    }
    if (rs_charpoly_get_fmpz_poly(p, v->cp->p, v->s->lambda_var, v->s->zctx))
        r = routh_numeric(run, v, p, o);
    else
        r = routh_symbolic(run, req->q, v, o);
    fmpz_poly_clear(p);
    if (r != RS_OK) { json_decref(o); return r; }
    rs_run_emit_exact(run, v, o);
    return RS_OK;
}

int rs_an_routh(rs_run_t *run, const rs_an_req_t *req)
{
    if (run->m->qd != NULL)   /* over Q(sqrt d) (an_qd_conds.c), at complex set values over Q(sqrt d)(i) */
        return run->c->ncsets > 0 ? rs_an_qd_cx_conds(run, req, 2) : rs_an_qd_routh(run, req);
    /* at complex set values: over Q(i) (an_complex.c) */
    if (rs_an_complex_mode(run)) return rs_an_complex_routh(run, req);
    return routh_real(run, req);
}
