/* an_routh.c -- `routh`: the exact Routh array of q(z), singular cases
 * (zero pivot, zero row, degree drop, q(0) = 0) handled and named. */
#include <stdio.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "recstab/bilinear.h"
#include "recstab/routh.h"

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

/* The fraction-free Routh array of q(z) with symbolic parameters into o. */
static int routh_symbolic(rs_run_t *run, const rs_request_t *q, const rs_variant_t *v, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    rs_routh_mpoly_t rm;
    fmpz_mpoly_t qz;
    slong i, j;
    int r;
    fmpz_mpoly_init(qz, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, s->lambda_var, s->zctx);
    rs_routh_mpoly_init(rm);
    r = rs_routh_mpoly(rm, qz, s->lambda_var, s->zctx, run->err);
    if (r == RS_OK) {
        json_t *rows = json_array();
        for (i = 0; i < rm->nrows; i++) {
            json_t *row = json_array();
            for (j = 0; j < rm->rowlen[i]; j++)
                json_array_append_new(row, rs_json_zpoly(rm->rows[i] + j, s));
            json_array_append_new(rows, row);
        }
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "rows", rows);
        routh_symbolic_events(o, v, qz, rm);
        /* the fraction-free first column is f_0 = r_0, f_k = r_1 r_2 ... r_k (r the textbook
         * column): "one sign" would be wrong where q's leading coefficient is negative */
        json_object_set_new(o, "note", json_string(rm->zero_row >= 0 ?
            "fraction-free rows; the zero row means roots symmetric about z = 0 for every parameter "
            "value (on the imaginary axis, i.e. on the unit circle, or pairs +-z): never asymptotically "
            "stable; the auxiliary polynomial's roots that lie on the imaginary axis are on the unit circle" :
            "fraction-free rows (each divided exactly by the pivot three rows up): first column f_0 = r_0, "
            "f_k = r_1 r_2 ... r_k (r the textbook column); valid where the first-column entries do not "
            "vanish: all roots have Re z < 0 iff every r_k has the sign of r_0, i.e. sign f_k = (sign f_0)^k "
            "(all positive when f_0 > 0, alternating when f_0 < 0)"));
    } else if (r == RS_ERR_MATH) {
        /* a pivot vanishes identically: say so and point to the exact tools */
        char msg[RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "%s", run->err->msg);
        r = rs_req_error(run, q, q->text, RS_ERR_MATH,
                         "symbolic Routh array is singular for every parameter value (%s); set the "
                         "parameters (set/--set) for the exact singular-case treatment, or use hurwitz", msg);
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
