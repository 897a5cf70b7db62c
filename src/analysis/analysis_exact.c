/* analysis_exact.c -- exact stability analyses: bilinear, routh, hurwitz,
 * jury, stability (this file), region, limit and claim (analysis_region.c). */
#include <stdlib.h>
#include <string.h>
#include "analysis/impl.h"
#include "analysis/registry.h"
#include "recstab/bilinear.h"
#include "recstab/routh.h"
#include "recstab/jury.h"
#include "recstab/hurwitz.h"
#include "recstab/rootcount.h"
#include "util/polyfmt.h"
#include "recstab/semisimple.h"
#include "recstab/cond.h"

/* The variant with the case's set values substituted. */
int rs_run_default_variant(rs_run_t *run, rs_variant_t **v)
{
    rs_assign_t *a;
    slong n;
    int r;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(v, run, a, n);
    rs_assign_free(a, n);
    return r;
}

/* Comma-separated parameters still symbolic in p (malloc'd, "" if none). */
char *rs_run_free_params(const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    size_t cap = 16, len = 0;
    char *out = malloc(cap);
    slong i;
    out[0] = '\0';
    for (i = 0; i < s->nvars; i++) {
        size_t need;
        if (i == s->lambda_var || fmpz_mpoly_degree_si(v->cp->p, i, s->zctx) <= 0) continue;
        need = strlen(s->vars[i]) + 3;
        if (len + need + 1 > cap) { cap = 2 * (len + need + 1); out = realloc(out, cap); }
        len += (size_t) sprintf(out + len, "%s%s", len ? ", " : "", s->vars[i]);
    }
    return out;
}

/* p as a univariate integer polynomial; error naming the free parameters
 * when some are still symbolic. */
int rs_run_numeric_poly(fmpz_poly_t p, rs_run_t *run, const rs_request_t *q,
                        const rs_variant_t *v, const char *what)
{
    if (!rs_charpoly_get_fmpz_poly(p, v->cp->p, v->s->lambda_var, v->s->zctx)) {
        char *fp = rs_run_free_params(v);
        char msg[512];
        snprintf(msg, sizeof msg, "%s needs every parameter set to a number; still symbolic: %s "
                 "(use set, --set, or region/claim for symbolic parameters)", what, fp);
        free(fp);
        return rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
    }
    return RS_OK;
}

void rs_json_add_count(json_t *o, const rs_rootcount_t rc)
{
    json_t *m = json_array();
    slong k;
    json_object_set_new(o, "status", json_string(rs_status_name(rs_rootcount_status(rc))));
    json_object_set_new(o, "degree", json_integer(rc->degree));
    json_object_set_new(o, "inside", json_integer(rc->inside));
    json_object_set_new(o, "on", json_integer(rc->on));
    json_object_set_new(o, "outside", json_integer(rc->outside));
    json_object_set_new(o, "at_one", json_integer(rc->at_one));
    json_object_set_new(o, "at_minus_one", json_integer(rc->at_minus_one));
    for (k = 1; k < RS_ROOTCOUNT_MAXMULT; k++)
        if (rc->on_mult[k] > 0)
            json_array_append_new(m, json_pack("{s:I,s:I}", "multiplicity", (json_int_t) k,
                                               "roots", (json_int_t) rc->on_mult[k]));
    json_object_set_new(o, "on_multiplicities", m);
}

/* The exact count of p by Routh (bilinear) and Schur-Cohn, which must agree:
 * a disagreement sets the inconsistency flag and says so in o. */
int rs_run_exact_count(rs_rootcount_t rc, rs_run_t *run, const fmpz_poly_t p, json_t *o)
{
    rs_routh_t ro;
    rs_jury_t ju;
    int r, agree = 1;
    if (fmpz_poly_degree(p) < 1) {
        /* det = c lambda^k: every root at 0 (dead-beat), nothing to count */
        rs_rootcount_init(rc);
        rc->degree = 0;
        if (o != NULL)
            json_object_set_new(o, "dead_beat", json_string(
                "det A = c*lambda^k: every root is 0 (dead-beat), spectral radius 0"));
        return RS_OK;
    }
    rs_routh_init(ro);
    rs_jury_init(ju);
    r = rs_routh_fmpz_poly(ro, p, run->err);
    if (r == RS_OK) r = rs_jury_fmpz_poly(ju, p, run->err);
    if (r == RS_OK) {
        agree = rs_rootcount_equal(ro->count, ju->count);
        *rc = *ro->count;
        if (!agree) {
            run->outcome |= RS_OUTCOME_INCONSISTENT;
            if (o != NULL) {
                json_t *d = json_object();
                rs_json_add_count(d, ju->count);
                json_object_set_new(o, "schur_cohn_count", d);
            }
        }
        if (o != NULL) {
            json_object_set_new(o, "methods", json_pack("[ss]", "routh (bilinear)", "schur-cohn"));
            json_object_set_new(o, "agree", json_boolean(agree));
        }
    }
    rs_routh_clear(ro);
    rs_jury_clear(ju);
    return r;
}

static json_t *circle_roots_json(const rs_semisimple_t ss)
{
    json_t *arr = json_array();
    slong i;
    for (i = 0; i < ss->nfactors; i++) {
        const rs_circle_factor_struct *f = ss->f + i;
        char *str = rs_polyfmt_fmpz_poly(f->factor, "lambda");
        json_array_append_new(arr, json_pack("{s:s,s:I,s:I,s:I,s:b}", "factor", str,
                                             "multiplicity", (json_int_t) f->mult,
                                             "roots", (json_int_t) f->on,
                                             "kernel_dim", (json_int_t) f->kernel,
                                             "semisimple", f->semisimple));
        free(str);
    }
    return arr;
}

int rs_run_verdict(rs_status_t *st, rs_run_t *run, const rs_scheme_t s, const slong *vars,
                   const fmpq *vals, slong nv, const fmpz_poly_t p, const rs_rootcount_t rc,
                   int singular, json_t *o)
{
    rs_semisimple_t ss;
    int r = RS_OK;
    if (singular) {
        *st = RS_STATUS_SINGULAR;
        if (o != NULL) {
            json_object_set_new(o, "status", json_string(rs_status_name(*st)));
            json_object_set_new(o, "singular", json_string(
                "the leading coefficient of det A(lambda) vanishes here: the implicit step cannot be solved "
                "(the counts are those of the reduced polynomial)"));
        }
        return RS_OK;
    }
    rs_semisimple_init(ss);
    r = rs_semisimple_verdict(st, ss, s, vars, vals, nv, p, rc, o != NULL, run->err);
    if (r == RS_OK && o != NULL && rc->on > 0) {
        json_object_set_new(o, "circle_roots", circle_roots_json(ss));
        json_object_set_new(o, "rule", json_string(ss->system ?
            "system: a circle root is bounded iff semisimple (dim ker A(lambda0) = its multiplicity in det A)" :
            "scalar recurrence: a repeated circle root is unstable"));
    }
    rs_semisimple_clear(ss);
    if (o != NULL && r == RS_OK)
        json_object_set_new(o, "status", json_string(rs_status_name(*st)));
    return r;
}

int rs_run_point_admissible(const rs_condpoly_t *cps, slong ncps, fmpq *const *pp, const rs_scheme_t s)
{
    slong k;
    int ok = 1;
    for (k = 0; k < ncps && ok; k++) ok = rs_condpoly_holds(cps + k, pp, s) == 1;
    for (k = 0; k < s->nnonzero && ok; k++) {
        fmpq_t z;
        fmpq_init(z);
        fmpq_mpoly_evaluate_all_fmpq(z, s->nonzero + k, pp, s->ctx);
        ok = !fmpq_is_zero(z);
        fmpq_clear(z);
    }
    return ok;
}

int rs_run_point_status(rs_status_t *st, rs_rootcount_t rc, rs_run_t *run, const rs_variant_t *v,
                        const slong *vars, const fmpq *vals, slong nv)
{
    const rs_scheme_struct *s = v->s;
    fmpq_mpoly_t q;
    fmpq_poly_t w;
    fmpz_poly_t u;
    slong k;
    int r = RS_OK;
    fmpq_mpoly_init(q, s->ctx);
    fmpq_poly_init(w);
    fmpz_poly_init(u);
    fmpq_one(q->content);
    fmpz_mpoly_set(q->zpoly, v->cp->p, s->zctx);
    fmpq_mpoly_reduce(q, s->ctx);
    for (k = 0; k < nv; k++)
        fmpq_mpoly_evaluate_one_fmpq(q, q, vars[k], vals + k, s->ctx);
    rs_rootcount_init(rc);
    if (!fmpq_mpoly_get_fmpq_poly(w, q, s->lambda_var, s->ctx)) {
        r = rs_error_set(run->err, RS_ERR_INTERNAL, "point verdict: a parameter is still symbolic");
    } else if (v->singular || fmpq_poly_is_zero(w) || fmpq_poly_degree(w) < v->cp->degree) {
        /* the leading coefficient of det A vanishes here: no step can be solved */
        *st = RS_STATUS_SINGULAR;
    } else {
        fmpq_poly_get_numerator(u, w);
        fmpz_poly_primitive_part(u, u);
        r = rs_run_exact_count(rc, run, u, NULL);
        if (r == RS_OK) r = rs_run_verdict(st, run, s, vars, vals, nv, u, rc, 0, NULL);
    }
    fmpz_poly_clear(u);
    fmpq_poly_clear(w);
    fmpq_mpoly_clear(q, s->ctx);
    return r;
}

/* ---- conditions checked at sample points ----------------------------------- */

/* Candidate values of one parameter inside its assumed interval b: both
 * signs when the sign is free (a free-sign leading coefficient must meet
 * both branches), spread over bounded intervals. */
static slong sample_candidates(fmpq *c, const rs_bound_t *b)
{
    static const slong num[] = {1, 3, 1, 7, 2, 5, 1, 11, 9, 4};
    static const slong den[] = {2, 1, 3, 2, 1, 3, 1, 4, 7, 1};
    slong n = 0, i;
    fmpq_t t, w;
    fmpq_init(t);
    fmpq_init(w);
    if (b->fixed) {
        fmpq_set(c + n++, b->lo);
    } else if (b->has_lo && b->has_hi) {
        fmpq_sub(w, b->hi, b->lo);
        for (i = 1; i < 10; i++) {       /* lo + w*i/10, never an end */
            fmpq_mul_si(t, w, i);
            fmpz_mul_ui(fmpq_denref(t), fmpq_denref(t), 10);
            fmpq_canonicalise(t);
            fmpq_add(c + n++, b->lo, t);
        }
    } else {
        for (i = 0; i < 10; i++) {
            fmpq_set_si(t, num[i], (ulong) den[i]);
            if (b->has_lo) fmpq_add(c + n++, b->lo, t);
            else if (b->has_hi) fmpq_sub(c + n++, b->hi, t);
            else { if (i % 2) fmpq_neg(t, t); fmpq_set(c + n++, t); }
        }
    }
    fmpq_clear(t);
    fmpq_clear(w);
    return n;
}

/* p(lambda) at the rational point pp as an integer polynomial (denominators
 * cleared: same roots). */
static void p_at_point(fmpz_poly_t u, const rs_variant_t *v, fmpq *const *pp)
{
    const rs_scheme_struct *s = v->s;
    fmpz_mpoly_t c;
    fmpq_poly_t f;
    fmpq_t x;
    slong j;
    fmpz_mpoly_init(c, s->zctx);
    fmpq_poly_init(f);
    fmpq_init(x);
    for (j = 0; j <= v->cp->degree; j++) {
        rs_charpoly_coeff(c, v->cp->p, j, s->lambda_var, s->zctx);
        rs_hurwitz_eval(x, c, pp, s->zctx);
        fmpq_poly_set_coeff_fmpq(f, j, x);
    }
    fmpq_poly_get_numerator(u, f);
    fmpz_mpoly_clear(c, s->zctx);
    fmpq_poly_clear(f);
    fmpq_clear(x);
}

#define SAMPLE_POINTS 12
#define SAMPLE_TRIES 80

/* Checks conditions (holds(data, point) = 1 stable, 0 not, -1 on a boundary)
 * against the exact verdict (Routh and Schur-Cohn on p at the point) at a
 * few deterministic rational points that satisfy the assume lines and the
 * non-zero assumptions; points where p loses degree are skipped.  Adds
 * "sample_check" to o; a disagreement marks the run inconsistent (exit 3). */
int rs_run_sample_check(rs_run_t *run, const rs_variant_t *v, rs_holds_fn holds, const void *data, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    slong np = run->c->nparams, i, j, k, ncp = 0, nok = 0, maxpts = SAMPLE_POINTS;
    rs_bound_t *b = flint_malloc((np + 1) * sizeof(rs_bound_t));
    rs_condpoly_t *cps = calloc((size_t) run->c->nassume + 1, sizeof(rs_condpoly_t));
    fmpq *cand = _fmpq_vec_init(10 * (np + 1)), *pt = _fmpq_vec_init(s->nvars);
    fmpq **pp = flint_malloc(s->nvars * sizeof(fmpq *));
    slong *ncand = flint_calloc(np + 1, sizeof(slong));
    json_t *chk = json_object(), *bad = NULL;
    rs_error_t e2;
    const char *key;
    json_t *val;
    int r = RS_OK;

    rs_error_init(e2);
    rs_bounds_init(b, np);
    for (i = 0; i < run->c->nassume; i++) rs_bounds_add(b, &run->c->assume[i], run->c, e2);
    json_object_foreach(v->assigned, key, val) {      /* set values and `at` values */
        slong idx = rs_case_param_index(run->c, key);
        if (idx < 0 || fmpq_set_str(b[idx].lo, json_string_value(val), 10) != 0) continue;
        fmpq_canonicalise(b[idx].lo);
        fmpq_set(b[idx].hi, b[idx].lo);
        b[idx].fixed = b[idx].has_lo = b[idx].has_hi = b[idx].lo_closed = b[idx].hi_closed = 1;
    }
    for (i = 0; i < run->c->nassume; i++) {
        if (rs_condpoly_compile(cps + ncp, &run->c->assume[i], s, run->c, e2) != RS_OK) break;
        ncp++;
    }
    for (i = 0; i < s->nvars; i++) pp[i] = pt + i;
    for (k = 0; k < np; k++) ncand[k] = rs_bound_empty(b + k) ? 0 : sample_candidates(cand + 10 * k, b + k);
    {
        char *fp = rs_run_free_params(v);
        if (*fp == '\0') maxpts = 1;   /* nothing varies */
        free(fp);
    }
    for (j = 0; j < SAMPLE_TRIES && nok < maxpts && r == RS_OK && bad == NULL; j++) {
        int ok = 1, says;
        fmpz_poly_t u;
        for (k = 0; k < np && ok; k++) {
            if (ncand[k] == 0) { ok = 0; break; }
            /* a different stride per parameter: the points mix the candidates */
            fmpq_set(pt + k, cand + 10 * k + (j * (2 * k + 1) + j / ncand[k] + k) % ncand[k]);
        }
        if (!ok || !rs_run_point_admissible(cps, ncp, pp, s)) continue;
        fmpz_poly_init(u);
        p_at_point(u, v, pp);
        says = holds(data, pp, s);
        if (fmpz_poly_degree(u) == v->cp->degree && says >= 0) {
            rs_rootcount_t rc;
            rs_status_t st;
            rs_rootcount_init(rc);
            r = rs_run_exact_count(rc, run, u, NULL);
            st = rs_rootcount_status(rc);
            nok++;
            if (r == RS_OK && (st == RS_STATUS_STABLE) != (says == 1)) {
                bad = json_object();
                for (k = 0; k < np; k++)
                    if (fmpz_mpoly_degree_si(v->cp->p, k, s->zctx) > 0)
                        json_object_set_new(bad, run->c->params[k].name, rs_json_fmpq(pt + k));
                json_object_set_new(chk, "point", bad);
                json_object_set_new(chk, "conditions_say", json_string(says ? "stable" : "not stable"));
                json_object_set_new(chk, "exact_verdict", json_string(rs_status_name(st)));
                rs_json_add_count(chk, rc);
            }
            rs_rootcount_clear(rc);
        }
        fmpz_poly_clear(u);
    }
    json_object_set_new(chk, "points", json_integer(nok));
    json_object_set_new(chk, "agree", json_boolean(bad == NULL));
    json_object_set_new(chk, "against", json_string("exact verdict (Routh and Schur-Cohn) at rational points "
                                                    "satisfying the assumptions"));
    json_object_set_new(o, "sample_check", chk);
    if (bad != NULL) run->outcome |= RS_OUTCOME_INCONSISTENT;
    for (i = 0; i < ncp; i++) rs_condpoly_clear(cps + i, s);
    free(cps);
    rs_bounds_clear(b, np);
    flint_free(b);
    _fmpq_vec_clear(cand, 10 * (np + 1));
    _fmpq_vec_clear(pt, s->nvars);
    flint_free(pp);
    flint_free(ncand);
    return r;
}

/* p(x) of the polynomial as stated, det = content * lambda^k * p: the
 * normalisation (content, its sign) undone. */
static json_t *p_at_stated(const rs_variant_t *v, slong x)
{
    const rs_scheme_struct *s = v->s;
    fmpq_mpoly_t t;
    fmpz_t xx;
    char *str;
    json_t *j;
    fmpq_mpoly_init(t, s->ctx);
    fmpz_init_set_si(xx, x);
    fmpz_mpoly_evaluate_one_fmpz(t->zpoly, v->cp->p, s->lambda_var, xx, s->zctx);
    fmpq_set(t->content, v->cp->content);
    if (x < 0 && (v->cp->removed_lambda_power & 1)) fmpq_neg(t->content, t->content);
    fmpq_mpoly_reduce(t, s->ctx);
    str = rs_polyfmt_fmpq_mpoly(t, (const char **) s->vars, s->ctx);
    j = json_string(str);
    free(str);
    fmpz_clear(xx);
    fmpq_mpoly_clear(t, s->ctx);
    return j;
}

/* ---- bilinear ------------------------------------------------------------- */

int rs_an_bilinear(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_t qz, t;
    json_t *o;
    slong d, lv;
    int r;
    (void) req;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    lv = s->lambda_var;
    fmpz_mpoly_init(qz, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, lv, s->zctx);
    d = fmpz_mpoly_degree_si(qz, lv, s->zctx);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("bilinear"));
    json_object_set_new(o, "var", json_string("z"));
    json_object_set_new(o, "degree", json_integer(d));
    json_object_set_new(o, "coeffs", rs_json_coeffs(qz, lv, s));
    json_object_set_new(o, "poly", rs_json_collected(qz, lv, s, "z"));
    json_object_set_new(o, "degree_drop", json_integer(v->cp->degree - d));
    json_object_set_new(o, "zero_mult", json_integer(rs_scheme_min_degree(qz, lv, s->zctx)));
    /* where lambda = -1 / lambda = 1 become roots: p(-1) = 0 / p(1) = 0 */
    json_object_set_new(o, "p_at_1", p_at_stated(v, 1));
    json_object_set_new(o, "p_at_minus_1", p_at_stated(v, -1));
    rs_run_emit_exact(run, v, o);
    fmpz_mpoly_clear(qz, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
    return RS_OK;
}

/* ---- routh ---------------------------------------------------------------- */

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

int rs_an_routh(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_poly_t p;
    json_t *o, *rows;
    slong i, j;
    int r;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("routh"));
    json_object_set_new(o, "var", json_string("z"));
    rows = json_array();
    fmpz_poly_init(p);
    if (rs_charpoly_get_fmpz_poly(p, v->cp->p, s->lambda_var, s->zctx)) {
        rs_routh_t ro;
        json_t *ev = json_array();
        rs_routh_init(ro);
        r = rs_routh_fmpz_poly(ro, p, run->err);
        if (r == RS_OK) {
            json_t *pw = json_array();
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
            rs_json_add_count(o, ro->count);
            rows = NULL;
        } else {
            json_decref(ev);
        }
        rs_routh_clear(ro);
    } else {
        rs_routh_mpoly_t rm;
        fmpz_mpoly_t qz;
        fmpz_mpoly_init(qz, s->zctx);
        rs_bilinear_fmpz_mpoly(qz, v->cp->p, s->lambda_var, s->zctx);
        rs_routh_mpoly_init(rm);
        r = rs_routh_mpoly(rm, qz, s->lambda_var, s->zctx, run->err);
        if (r == RS_OK) {
            for (i = 0; i < rm->nrows; i++) {
                json_t *row = json_array();
                for (j = 0; j < rm->rowlen[i]; j++)
                    json_array_append_new(row, rs_json_zpoly(rm->rows[i] + j, s));
                json_array_append_new(rows, row);
            }
            slong drop = v->cp->degree - fmpz_mpoly_degree_si(qz, s->lambda_var, s->zctx);
            json_t *ev = json_array();
            json_object_set_new(o, "symbolic", json_true());
            json_object_set_new(o, "rows", rows);
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
            json_object_set_new(o, "note", json_string(rm->zero_row >= 0 ?
                "fraction-free rows; valid where the first-column entries do not vanish: a sign change in the "
                "first column is a root with Re z > 0 (|lambda| > 1); the auxiliary polynomial's roots that lie "
                "on the imaginary axis are on the unit circle" :
                "fraction-free rows (each divided exactly by the pivot three rows up); valid where the "
                "first-column entries do not vanish: all roots have Re z < 0 iff the first column has one sign"));
            rows = NULL;
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
    }
    fmpz_poly_clear(p);
    json_decref(rows);
    if (r != RS_OK) { json_decref(o); return r; }
    rs_run_emit_exact(run, v, o);
    return RS_OK;
}

/* ---- hurwitz -------------------------------------------------------------- */

static void append_unique(json_t *arr, const char *str)
{
    size_t i;
    for (i = 0; i < json_array_size(arr); i++)
        if (strcmp(json_string_value(json_array_get(arr, i)), str) == 0) return;
    json_array_append_new(arr, json_string(str));
}

static json_t *factor_str(const fmpz_mpoly_t f, const rs_scheme_t s)
{
    return rs_json_zpoly(f, s);
}

int rs_run_hurwitz(rs_hurwitz_t h, rs_run_t *run, const rs_variant_t *v, fmpz_mpoly_t qz)
{
    const rs_scheme_struct *s = v->s;
    int *sign = rs_run_signs(run, s);
    int r;
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, s->lambda_var, s->zctx);
    /* q losing degree for every value is a root lambda = -1 for every value:
     * conditions of the lower-degree q would ignore it */
    if (fmpz_mpoly_degree_si(qz, s->lambda_var, s->zctx) < v->cp->degree) {
        flint_free(sign);
        rs_hurwitz_clear(h, s->zctx);
        return rs_error_set(run->err, RS_ERR_MATH, "hurwitz: p(-1) = 0 for every parameter value (lambda = -1 "
                            "is a root): never asymptotically stable");
    }
    r = rs_hurwitz_compute(h, qz, s->lambda_var, (const rs_sign_t *) sign, s->zctx, run->err);
    flint_free(sign);
    return r;
}

/* The conditions of q(z) for every admissible sign of its leading
 * coefficient (an OR of branches), q(z) into qz.  charpoly's normalisation
 * makes the lex-leading term of p positive: that fixes no sign of a symbolic
 * coefficient (and lc q = (-1)^n p(-1) is another coefficient anyway), so
 * only the assumptions may drop a branch. */
static int rs_run_hurwitz_or(rs_hurwitz_or_t hb, rs_run_t *run, const rs_variant_t *v, fmpz_mpoly_t qz)
{
    const rs_scheme_struct *s = v->s;
    int *sign = rs_run_signs(run, s);
    int r;
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, s->lambda_var, s->zctx);
    r = rs_hurwitz_or_compute(hb, qz, s->lambda_var, v->cp->degree, (const rs_sign_t *) sign, s->zctx, run->err);
    flint_free(sign);
    return r;
}

static int hurwitz_or_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    return rs_hurwitz_or_holds((const rs_hurwitz_or_struct *) data, pt, s->zctx);
}

/* Every stated condition of one branch: "reduced > 0" and "factor != 0". */
static json_t *branch_json(const rs_hurwitz_t h, const rs_scheme_t s)
{
    json_t *a = json_array();
    slong i, k;
    for (i = 0; i < h->ncond; i++) {
        char *line;
        if (h->cond[i].trivially_true) continue;
        line = rs_cond_string(h->cond[i].reduced, s, "> 0");
        append_unique(a, line);
        free(line);
    }
    for (i = 0; i < h->ncond; i++)
        for (k = 0; k < h->cond[i].factors->num; k++)
            if (!h->cond[i].dropped[k] && h->cond[i].even[k]) {
                char *line = rs_cond_string(h->cond[i].factors->poly + k, s, "!= 0");
                append_unique(a, line);
                free(line);
            }
    return a;
}

/* Why no branch exists (lambda = -1 or 1 a root for every value), or NULL. */
static const char *hurwitz_never_reason(const rs_hurwitz_or_t hb, char *buf, size_t len)
{
    if (hb->degree_drop > 0)
        snprintf(buf, len, "p(-1) = 0 for every parameter value: lambda = -1 is a root (multiplicity %ld: q(z) "
                 "has degree %ld less); never asymptotically stable", (long) hb->degree_drop, (long) hb->degree_drop);
    else if (hb->zero_mult > 0)
        snprintf(buf, len, "p(1) = 0 for every parameter value: lambda = 1 is a root (multiplicity %ld: z^%ld "
                 "divides q(z)); never asymptotically stable", (long) hb->zero_mult, (long) hb->zero_mult);
    else
        return NULL;
    return buf;
}

/* "conditions" (one branch) or "branches" (an OR of two), "never" when
 * no branch can hold; returns 1 if every condition of a branch holds under
 * the assumptions, -1 if no branch can hold, 0 otherwise. */
static int rs_json_hurwitz_or(json_t *o, const rs_hurwitz_or_t hb, const rs_scheme_t s)
{
    char buf[300];
    const char *why = hurwitz_never_reason(hb, buf, sizeof buf);
    slong i;
    if (why != NULL) {
        json_object_set_new(o, "conditions", json_pack("[s]", "0 > 0"));
        json_object_set_new(o, "never", json_string(why));
        return -1;
    }
    if (hb->nbranch == 2) {
        json_t *br = json_array();
        for (i = 0; i < 2; i++) json_array_append_new(br, branch_json(hb->branch + i, s));
        json_object_set_new(o, "branches", br);
        json_object_set_new(o, "branches_note", json_string(
            "stable iff every condition of one branch holds (the sign of the leading coefficient of q(z) is "
            "not fixed by the assumptions; Lienard-Chipart applies to q or -q, whichever has it positive)"));
        return 0;
    }
    for (i = 0; i < hb->branch[0].ncond; i++)
        if (hb->branch[0].cond[i].trivially_false) return -1;
    for (i = 0; i < hb->branch[0].ncond; i++)
        if (!hb->branch[0].cond[i].trivially_true) return 0;
    return 1;
}

/* Conditions equivalent to stability for every admissible value into o:
 * "conditions" (one branch: every stated condition, non-zero ones
 * included), "branches" (an OR) or "never"; checked at sample points.
 * Returns as rs_json_hurwitz_or through *verdict, or an error code. */
int rs_run_symbolic_conditions(rs_run_t *run, const rs_variant_t *v, json_t *o, int *verdict)
{
    const rs_scheme_struct *s = v->s;
    rs_hurwitz_or_t hb;
    fmpz_mpoly_t qz;
    int r;
    fmpz_mpoly_init(qz, s->zctx);
    rs_hurwitz_or_init(hb);
    r = rs_run_hurwitz_or(hb, run, v, qz);
    if (r == RS_OK) {
        *verdict = rs_json_hurwitz_or(o, hb, s);
        if (hb->nbranch == 1 && json_object_get(o, "never") == NULL)
            json_object_set_new(o, "conditions", branch_json(hb->branch + 0, s));
        r = rs_run_sample_check(run, v, hurwitz_or_holds, hb, o);
    }
    rs_hurwitz_or_clear(hb, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    return r;
}

int rs_an_hurwitz(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    rs_hurwitz_or_t hb;
    const rs_hurwitz_struct *h;
    fmpz_mpoly_t qz;
    json_t *o, *minors, *conds, *nonzero, *dropped, *always, *details;
    slong i, k;
    int r, verdict;
    (void) req;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    fmpz_mpoly_init(qz, s->zctx);
    rs_hurwitz_or_init(hb);
    r = rs_run_hurwitz_or(hb, run, v, qz);
    if (r != RS_OK) {
        rs_hurwitz_or_clear(hb, s->zctx);
        fmpz_mpoly_clear(qz, s->zctx);
        return r;
    }
    h = hb->branch + 0;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("hurwitz"));
    json_object_set_new(o, "var", json_string("z"));
    json_object_set_new(o, "degree", json_integer(hb->nbranch > 0 ? h->n : v->cp->degree));
    json_object_set_new(o, "negated", json_boolean(h->negated));
    json_object_set_new(o, "p_at_1", p_at_stated(v, 1));
    json_object_set_new(o, "p_at_minus_1", p_at_stated(v, -1));
    minors = json_array();
    for (i = 0; i < h->n; i++) json_array_append_new(minors, rs_json_zpoly(h->minors + i, s));
    json_object_set_new(o, "minors", minors);
    conds = json_array();
    nonzero = json_array();
    dropped = json_array();
    always = json_array();
    details = json_array();
    for (i = 0; i < h->ncond; i++) {
        const rs_hurwitz_cond_struct *c = h->cond + i;
        json_t *d = json_object(), *fl = json_array();
        json_object_set_new(d, "origin", json_string(c->origin));
        json_object_set_new(d, "poly", rs_json_zpoly(c->poly, s));
        for (k = 0; k < c->factors->num; k++) {
            json_t *f = json_object();
            json_object_set_new(f, "factor", factor_str(c->factors->poly + k, s));
            json_object_set_new(f, "exponent", json_integer(fmpz_get_si(c->factors->exp + k)));
            json_object_set_new(f, "dropped", json_boolean(c->dropped[k]));
            json_array_append_new(fl, f);
            if (c->dropped[k]) {
                json_t *dd = json_object();
                json_object_set_new(dd, "factor", factor_str(c->factors->poly + k, s));
                json_object_set_new(dd, "from", json_string(c->origin));
                json_object_set_new(dd, "reason", json_string("of one sign under the assumptions"));
                json_array_append_new(dropped, dd);
            } else if (c->even[k]) {
                char *line = rs_cond_string(c->factors->poly + k, s, "!= 0");
                json_array_append_new(nonzero, json_string(line));
                free(line);
            }
        }
        json_object_set_new(d, "factors", fl);
        json_object_set_new(d, "reduced", rs_json_zpoly(c->reduced, s));
        json_object_set_new(d, "trivially_true", json_boolean(c->trivially_true));
        json_object_set_new(d, "trivially_false", json_boolean(c->trivially_false));
        json_array_append_new(details, d);
        if (c->trivially_true) {
            json_array_append_new(always, json_string(c->origin));
        } else {
            char *line = rs_cond_string(c->reduced, s, "> 0");
            json_array_append_new(conds, json_string(line));
            free(line);
        }
    }
    if (hb->nbranch == 1) {
        json_object_set_new(o, "conditions", conds);
        json_object_set_new(o, "nonzero", nonzero);
    } else {
        json_decref(conds);
        json_decref(nonzero);
    }
    verdict = rs_json_hurwitz_or(o, hb, s);
    json_object_set_new(o, "dropped", dropped);
    json_object_set_new(o, "always_true", always);
    json_object_set_new(o, "details", details);
    json_object_set_new(o, "verdict", json_string(verdict > 0 ? "stable under the assumptions"
                                                  : verdict < 0 ? "never stable"
                                                  : hb->nbranch == 2 ? "stable iff one branch holds"
                                                  : "stable iff the conditions hold"));
    r = rs_run_sample_check(run, v, hurwitz_or_holds, hb, o);
    if (r == RS_OK) rs_run_emit_exact(run, v, o);
    else json_decref(o);
    rs_hurwitz_or_clear(hb, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    return r;
}

/* ---- jury / stability ----------------------------------------------------- */

/* Symbolic Schur-Cohn (Jury) conditions: with p_n = p and
 * p_{k-1} = (lead(p_k) p_k - p_k(0) p_k^*)/lambda (p^* the reciprocal), all
 * roots lie inside the circle iff delta_k = lead(p_k)^2 - p_k(0)^2 > 0 for
 * k = n..1 (Schur 1917; Jury's table).  Each reduced polynomial is divided by
 * the content of its coefficients (a non-zero factor of the parameters does
 * not move roots and enters delta squared).  Generic: where a delta vanishes
 * the exact numeric test decides. */
/* The symbolic Schur-Cohn conditions as polynomials: poly > 0, or
 * poly != 0 when ne[i] (for the check at sample points). */
typedef struct {
    slong n;
    fmpz_mpoly_struct *poly;
    int *ne;
    const fmpz_mpoly_ctx_struct *ctx;
} jury_conds_t;

static void jury_conds_add(jury_conds_t *c, const fmpz_mpoly_t p, int ne)
{
    c->poly = flint_realloc(c->poly, (c->n + 1) * sizeof(fmpz_mpoly_struct));
    c->ne = flint_realloc(c->ne, (c->n + 1) * sizeof(int));
    fmpz_mpoly_init(c->poly + c->n, c->ctx);
    fmpz_mpoly_set(c->poly + c->n, p, c->ctx);
    c->ne[c->n++] = ne;
}

static void jury_conds_clear(jury_conds_t *c)
{
    slong i;
    for (i = 0; i < c->n; i++) fmpz_mpoly_clear(c->poly + i, c->ctx);
    flint_free(c->poly);
    flint_free(c->ne);
}

/* 1 if every condition holds, 0 if one fails, -1 if one vanishes (a
 * condition identically 0 > 0 just fails) */
static int jury_conds_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    const jury_conds_t *c = data;
    slong i;
    int ok = 1;
    for (i = 0; i < c->n; i++) {
        int sg;
        if (fmpz_mpoly_is_zero(c->poly + i, s->zctx)) { ok = 0; continue; }
        sg = rs_hurwitz_sign_at(c->poly + i, pt, s->zctx);
        if (sg == 0) return -1;
        if (!c->ne[i] && sg < 0) ok = 0;
    }
    return ok;
}

static int jury_symbolic(rs_run_t *run, const rs_variant_t *v, json_t *o)
{
    const rs_scheme_struct *s = v->s;
    slong lv = s->lambda_var, n = v->cp->degree, k, j;
    fmpz_mpoly_struct *a = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct));
    fmpz_mpoly_t t, u, g, delta;
    json_t *rows = json_array(), *conds = json_array(), *dropped = json_array();
    int *sign = rs_run_signs(run, s);
    int r = RS_OK;
    jury_conds_t jc;
    jc.n = 0; jc.poly = NULL; jc.ne = NULL; jc.ctx = s->zctx;
    for (j = 0; j <= n; j++) {
        fmpz_mpoly_init(a + j, s->zctx);
        rs_charpoly_coeff(a + j, v->cp->p, j, lv, s->zctx);
    }
    fmpz_mpoly_init(t, s->zctx); fmpz_mpoly_init(u, s->zctx);
    fmpz_mpoly_init(g, s->zctx); fmpz_mpoly_init(delta, s->zctx);
    for (k = n; k >= 1 && r == RS_OK; k--) {
        json_t *row = json_array();
        fmpz_mpoly_factor_t f;
        slong i;
        for (j = 0; j <= k; j++) json_array_append_new(row, rs_json_zpoly(a + j, s));
        json_array_append_new(rows, row);
        /* delta_k = a_k^2 - a_0^2 = (a_k - a_0)(a_k + a_0) */
        fmpz_mpoly_mul(t, a + k, a + k, s->zctx);
        fmpz_mpoly_mul(u, a + 0, a + 0, s->zctx);
        fmpz_mpoly_sub(delta, t, u, s->zctx);
        if (fmpz_mpoly_length(delta, s->zctx) > RS_CHARPOLY_MAX_TERMS) {
            r = rs_error_set(run->err, RS_ERR_LIMIT, "symbolic Schur-Cohn table: a condition has over %ld terms (limit)",
                             (long) RS_CHARPOLY_MAX_TERMS);
            json_decref(row);
            break;
        }
        fmpz_mpoly_factor_init(f, s->zctx);
        if (fmpz_mpoly_is_zero(delta, s->zctx)) {
            /* |p_k(0)| = |lead| for every value: the table is singular (e.g. a
             * self-reciprocal p, roots symmetric about the circle): never
             * asymptotically stable; the exact numeric test counts the roots */
            append_unique(conds, "0 > 0");
            jury_conds_add(&jc, delta, 0);
            json_object_set_new(o, "singular_row", json_integer(n - k));
            fmpz_mpoly_factor_clear(f, s->zctx);
            break;
        } else if (fmpz_mpoly_factor(f, delta, s->zctx)) {
            /* keep the factors whose sign is not settled by the assumptions */
            fmpz_mpoly_t kept;
            int neg = fmpz_sgn(f->constant) < 0;
            fmpz_mpoly_init(kept, s->zctx);
            fmpz_mpoly_one(kept, s->zctx);
            for (i = 0; i < f->num; i++) {
                int sg = rs_hurwitz_sign(f->poly + i, (const rs_sign_t *) sign, s->zctx);
                slong e = fmpz_get_si(f->exp + i);
                if (sg != 0) {
                    if (sg < 0 && (e & 1)) neg = !neg;
                    json_array_append_new(dropped, json_pack("{s:o,s:I}", "factor", rs_json_zpoly(f->poly + i, s),
                                                             "row", (json_int_t) (n - k)));
                    continue;
                }
                if (e & 1) fmpz_mpoly_mul(kept, kept, f->poly + i, s->zctx);
                else {
                    char *line = rs_cond_string(f->poly + i, s, "!= 0");
                    append_unique(conds, line);
                    jury_conds_add(&jc, f->poly + i, 1);
                    free(line);
                }
            }
            if (neg) fmpz_mpoly_neg(kept, kept, s->zctx);
            if (!fmpz_mpoly_is_one(kept, s->zctx)) {
                char *line = rs_cond_string(kept, s, "> 0");
                append_unique(conds, line);
                jury_conds_add(&jc, kept, 0);
                free(line);
            }
            fmpz_mpoly_clear(kept, s->zctx);
        }
        fmpz_mpoly_factor_clear(f, s->zctx);
        /* p_{k-1}: coefficient j = a_k a_{j+1} - a_0 a_{k-1-j}, j = 0..k-1 */
        {
            fmpz_mpoly_struct *b = flint_malloc(k * sizeof(fmpz_mpoly_struct));
            for (j = 0; j < k; j++) {
                fmpz_mpoly_init(b + j, s->zctx);
                fmpz_mpoly_mul(t, a + k, a + j + 1, s->zctx);
                fmpz_mpoly_mul(u, a + 0, a + k - 1 - j, s->zctx);
                fmpz_mpoly_sub(b + j, t, u, s->zctx);
            }
            /* divide by the content of the row */
            fmpz_mpoly_zero(g, s->zctx);
            for (j = 0; j < k; j++) {
                if (!fmpz_mpoly_gcd(g, g, b + j, s->zctx)) { fmpz_mpoly_one(g, s->zctx); break; }
            }
            if (!fmpz_mpoly_is_zero(g, s->zctx) && !fmpz_mpoly_is_one(g, s->zctx))
                for (j = 0; j < k; j++) fmpz_mpoly_divexact(b + j, b + j, g, s->zctx);
            for (j = 0; j <= k; j++) fmpz_mpoly_clear(a + j, s->zctx);
            for (j = 0; j < k; j++) a[j] = b[j];
            flint_free(b);
        }
    }
    for (j = 0; j <= k && j <= n; j++) fmpz_mpoly_clear(a + j, s->zctx);
    flint_free(a);
    fmpz_mpoly_clear(t, s->zctx); fmpz_mpoly_clear(u, s->zctx);
    fmpz_mpoly_clear(g, s->zctx); fmpz_mpoly_clear(delta, s->zctx);
    flint_free(sign);
    if (r == RS_OK) {
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "rows", rows);
        json_object_set_new(o, "conditions", conds);
        json_object_set_new(o, "dropped", dropped);
        json_object_set_new(o, "note", json_string(
            "Schur-Cohn reduction p_{k-1} = (lead p_k * p_k - p_k(0) p_k*)/lambda, each row divided by its content: "
            "all |lambda| < 1 iff every lead^2 - const^2 > 0 (Schur 1917, strict inequalities: exact for every "
            "value; where the leading coefficient of p vanishes the first condition fails)"));
        r = rs_run_sample_check(run, v, jury_conds_holds, &jc, o);
    } else {
        json_decref(rows);
        json_decref(conds);
        json_decref(dropped);
    }
    jury_conds_clear(&jc);
    return r;
}

int rs_an_jury(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    fmpz_poly_t p;
    rs_jury_t ju;
    rs_routh_t ro;
    json_t *o, *rows;
    slong i;
    int r;
    (void) req;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    fmpz_poly_init(p);
    if (!rs_charpoly_get_fmpz_poly(p, v->cp->p, v->s->lambda_var, v->s->zctx)) {
        fmpz_poly_clear(p);
        o = json_object();
        json_object_set_new(o, "analysis", json_string("jury"));
        json_object_set_new(o, "method", json_string("Schur-Cohn (Jury) table, symbolic"));
        r = jury_symbolic(run, v, o);
        if (r != RS_OK) { json_decref(o); return r; }
        rs_run_emit_exact(run, v, o);
        return RS_OK;
    }
    rs_jury_init(ju);
    rs_routh_init(ro);
    r = rs_jury_fmpz_poly(ju, p, run->err);
    if (r == RS_OK) r = rs_routh_fmpz_poly(ro, p, run->err);
    if (r == RS_OK) {
        int agree = rs_rootcount_equal(ro->count, ju->count);
        o = json_object();
        json_object_set_new(o, "analysis", json_string("jury"));
        json_object_set_new(o, "method", json_string("Schur-Cohn (gcd with the reciprocal polynomial, "
                                                     "Schur-Cohn-Fujiwara inertia)"));
        json_object_set_new(o, "table_regular", json_boolean(ju->table_regular));
        rows = json_array();
        for (i = 0; i < ju->nrows; i++) {
            char *str = rs_polyfmt_fmpz_poly(ju->rows + i, "lambda");
            json_array_append_new(rows, json_string(str));
            free(str);
        }
        json_object_set_new(o, "rows", rows);
        json_object_set_new(o, "gcd_degree", json_integer(ju->gcd_degree));
        rs_json_add_count(o, ju->count);
        json_object_set_new(o, "cross_check", json_pack("{s:s,s:b}", "with", "routh (bilinear)", "agree", agree));
        if (!agree) run->outcome |= RS_OUTCOME_INCONSISTENT;
        rs_run_emit_exact(run, v, o);
    }
    rs_jury_clear(ju);
    rs_routh_clear(ro);
    fmpz_poly_clear(p);
    return r;
}

int rs_an_stability(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    rs_variant_t *v;
    fmpz_poly_t p;
    rs_rootcount_t rc;
    json_t *o;
    int r;
    r = rs_run_numeric_variant(run, &v);
    if (r != RS_OK) return r;
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, q, v, "stability");
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("stability"));
        rs_rootcount_init(rc);
        r = rs_run_exact_count(rc, run, p, o);
        if (r == RS_OK) {
            rs_status_t st;
            rs_json_add_count(o, rc);
            r = rs_run_verdict(&st, run, v->s, NULL, NULL, 0, p, rc, v->singular, o);
        }
        if (r == RS_OK) {
            rs_run_emit_exact(run, v, o);
        } else {
            json_decref(o);
        }
        rs_rootcount_clear(rc);
    }
    fmpz_poly_clear(p);
    return r;
}

