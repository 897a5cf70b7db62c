/* an_jury.c -- `jury`: Schur-Cohn on p(lambda) directly, numeric or with
 * the symbolic Schur-Cohn (Jury) conditions, cross-checked against Routh. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "recstab/routh.h"
#include "recstab/jury.h"
#include "recstab/positivity.h"
#include "util/polyfmt.h"

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

/* The second exact route to the same question (h-truth6): the
 * Lienard-Chipart conditions of the bilinear image q(z) = (z - 1)^n
 * p((z + 1)/(z - 1)), hurwitz's code on the same p.  Both describe the set
 * where every |lambda| < 1, so at each sample point they must agree (else
 * exit 3), and a "never" proved by either is the answer of both.  Only for
 * p of at most this many terms: the minors of a large q cost more than the
 * table (issue 17's chains) */
#define JURY_CROSS_MAX_TERMS 400

typedef struct {
    const jury_conds_t *jc;
    const rs_hurwitz_or_struct *hb;   /* NULL: no second route */
    const rs_run_t *run;
    json_t *bad;                      /* the first point where the routes differ */
    int table_says;
    slong points;
} jury_cross_t;

static int jury_conds_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s);

static int jury_cross_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    jury_cross_t *w = (jury_cross_t *) data;   /* our own, writable */
    int t = jury_conds_holds(w->jc, pt, s), h;
    if (w->hb == NULL || t < 0) return t;
    h = rs_hurwitz_or_holds(w->hb, pt, s->zctx);
    if (h < 0) return t;
    w->points++;
    if (h != t && w->bad == NULL) {
        w->bad = rs_run_point_json(w->run, pt, s->nvars);
        w->table_says = t;
    }
    return t;
}

/* hb := the bilinear image's branches; 1 if computed, 0 if skipped (too
 * large, or hurwitz's code stopped: the table's answer stands alone, said in
 * cross_route.skipped) */
static int jury_cross_route(rs_hurwitz_or_t hb, rs_run_t *run, const rs_variant_t *v, json_t *cr)
{
    fmpz_mpoly_t qz;
    int r;
    if (fmpz_mpoly_length(v->cp->p, v->s->zctx) > JURY_CROSS_MAX_TERMS) {
        json_object_set_new(cr, "skipped", json_string("p has too many terms for a second symbolic route"));
        return 0;
    }
    fmpz_mpoly_init(qz, v->s->zctx);
    r = rs_run_hurwitz_or(hb, run, v, qz);
    fmpz_mpoly_clear(qz, v->s->zctx);
    if (r != RS_OK) {
        json_object_set_new(cr, "skipped", json_string(run->err->msg));
        rs_error_init(run->err);   /* the table's answer goes on */
        return 0;
    }
    return 1;
}

/* delta_k with more than rs_jury_factor_whole_terms() terms is factored
 * through its known factors a_k - a_0 and a_k + a_0 (issue 17: row 5 of the
 * 4-mass chain's table has a 229 723-term delta whose whole factorisation
 * ran past 40 s, its two halves have 10 382 terms each); smaller ones whole,
 * as before, so the order of the factors printed is unchanged where the
 * table finished */

/* f = the factorisation of (ak - a0)(ak + a0), each half factored on its
 * own and equal irreducible factors merged; 0 if FLINT failed */
static int jury_factor_halves(fmpz_mpoly_factor_t f, const fmpz_mpoly_t ak, const fmpz_mpoly_t a0,
                              const fmpz_mpoly_ctx_t ctx)
{
    fmpz_mpoly_factor_t h;
    fmpz_mpoly_t d;
    slong side, i, j;
    int ok = 1;
    fmpz_mpoly_factor_init(h, ctx);
    fmpz_mpoly_init(d, ctx);
    fmpz_mpoly_factor_one(f, ctx);
    for (side = 0; side < 2 && ok; side++) {
        if (side == 0) fmpz_mpoly_sub(d, ak, a0, ctx);
        else fmpz_mpoly_add(d, ak, a0, ctx);
        ok = fmpz_mpoly_factor(h, d, ctx);
        if (!ok) break;
        fmpz_mul(f->constant, f->constant, h->constant);
        for (i = 0; i < h->num; i++) {
            for (j = 0; j < f->num; j++)
                if (fmpz_mpoly_equal(f->poly + j, h->poly + i, ctx)) break;
            if (j < f->num) fmpz_add(f->exp + j, f->exp + j, h->exp + i);
            else fmpz_mpoly_factor_append_fmpz_swap(f, h->poly + i, h->exp + i, ctx);
        }
    }
    fmpz_mpoly_factor_clear(h, ctx);
    fmpz_mpoly_clear(d, ctx);
    return ok;
}

/* The Schur-Cohn question through the bilinear transform (issue 17):
 * lambda = (z + 1)/(z - 1) maps |lambda| < 1 onto Re z < 0, so every root
 * of p is inside the circle iff every root of q(z) = (z - 1)^n
 * p((z + 1)/(z - 1)) has negative real part (with deg q = n, which the
 * Hurwitz branches take care of): the Lienard-Chipart conditions of q
 * describe the same region as the Schur-Cohn table's.  They are not the
 * table's polynomials (its minors are congruent to q's Hermite form, not
 * equal), so the report says which route spoke.  The table's rows formed
 * before the switch are not reported (they answer nothing alone); the
 * exact point verdict (Routh and Schur-Cohn at each sample point) still
 * checks the conditions.  dropped: emptied of the table's, then q's
 * factors of one sign; row: the table's row that gave way, terms: its
 * delta's. */
static int jury_bilinear(rs_run_t *run, const rs_variant_t *v, json_t *o, json_t *dropped, slong row,
                         slong terms)
{
    char buf[400];
    int verdict, r;
    json_array_clear(dropped);
    r = rs_run_symbolic_conditions_dropped(run, v, o, &verdict, dropped);
    if (r != RS_OK) {
        json_decref(dropped);
        return r;
    }
    json_object_set_new(o, "method", json_string("Schur-Cohn conditions through the bilinear transform "
                                                 "(Lienard-Chipart of q(z)), symbolic"));
    json_object_set_new(o, "symbolic", json_true());
    json_object_set_new(o, "rows", json_array());
    json_object_set_new(o, "dropped", dropped);
    json_object_set_new(o, "route", json_string("bilinear"));
    /* an identically false set: the verdict as the table route and hurwitz say it */
    if (verdict < 0) json_object_set_new(o, "verdict", json_string("never stable"));
    snprintf(buf, sizeof buf, "row %ld of the Schur-Cohn table has a lead^2 - const^2 of %ld terms (over %ld): "
             "the conditions are those of q(z) = (z - 1)^n p((z + 1)/(z - 1)) instead, where D_k are the Hurwitz "
             "minors of q", (long) row, (long) terms, (long) rs_jury_bilinear_terms());
    json_object_set_new(o, "route_reason", json_string(buf));
    json_object_set_new(o, "note", json_string(
        "lambda = (z + 1)/(z - 1) maps |lambda| < 1 onto Re z < 0: all |lambda| < 1 iff q(z) = (z - 1)^n "
        "p((z + 1)/(z - 1)) is Hurwitz stable, i.e. iff its Lienard-Chipart conditions hold (the same region "
        "as the Schur-Cohn table's conditions, not the same polynomials; strict inequalities, exact for every "
        "value)"));
    return RS_OK;
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
    rs_budget_calib_t cal;
    slong switched = 0;   /* terms of the delta at which the table gave way */
    /* the parameters' intervals for the factors' sign tests (interval
     * mapping before Polya, issue 17, as hurwitz does): a factor of one sign
     * on 0 < h < 1 but not for every h > 0 is dropped; params come first */
    const rs_case_struct *c = run->c;
    rs_bound_t *bd = rs_run_bounds(run);
    slong nb = FLINT_MIN(c->nparams, s->nvars);
    jc.n = 0; jc.poly = NULL; jc.ne = NULL; jc.ctx = s->zctx;
    rs_budget_calib_init(&cal);
    for (j = 0; j <= n; j++) {
        fmpz_mpoly_init(a + j, s->zctx);
        rs_charpoly_coeff(a + j, v->cp->p, j, lv, s->zctx);
    }
    fmpz_mpoly_init(t, s->zctx); fmpz_mpoly_init(u, s->zctx);
    fmpz_mpoly_init(g, s->zctx); fmpz_mpoly_init(delta, s->zctx);
    if (n == 0) {
        /* dead-beat p = c: no row, stable iff c != 0 */
        rs_run_dead_beat_nonzero(t, conds, run, s, a + 0);
        if (!fmpz_mpoly_is_one(t, s->zctx)) jury_conds_add(&jc, t, 1);
    }
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
        if (fmpz_mpoly_length(delta, s->zctx) > rs_jury_bilinear_terms()) {
            /* the table's rows grow past what factoring and the content
             * gcds can carry (issue 17): the bilinear route answers */
            switched = fmpz_mpoly_length(delta, s->zctx);
            break;
        }
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
            rs_json_append_unique(conds, "0 > 0");
            jury_conds_add(&jc, delta, 0);
            json_object_set_new(o, "singular_row", json_integer(n - k));
            /* said as hurwitz says an identically false set ("never",
             * "verdict"), not as a bare 0 > 0 */
            {
                char why[400];
                snprintf(why, sizeof why, "|p_k(0)| = |lead p_k| for every parameter value in row %ld of the "
                         "Schur-Cohn table (lead^2 - const^2 = 0 identically): the product of that row's roots "
                         "has modulus 1, so one lies on or outside the unit circle, and all |lambda| < 1 needs "
                         "every row's roots inside (Schur-Cohn); never asymptotically stable", (long) (n - k));
                json_object_set_new(o, "never", json_string(why));
                json_object_set_new(o, "verdict", json_string("never stable"));
            }
            fmpz_mpoly_factor_clear(f, s->zctx);
            break;
        } else if (fmpz_mpoly_length(delta, s->zctx) > rs_jury_factor_whole_terms()
                   ? jury_factor_halves(f, a + k, a + 0, s->zctx) : fmpz_mpoly_factor(f, delta, s->zctx)) {
            /* keep the factors whose sign is not settled by the assumptions */
            fmpz_mpoly_t kept;
            int neg = fmpz_sgn(f->constant) < 0;
            fmpz_mpoly_init(kept, s->zctx);
            fmpz_mpoly_one(kept, s->zctx);
            for (i = 0; i < f->num; i++) {
                int sg = rs_positivity_sign_bounds(f->poly + i, (const rs_sign_t *) sign, bd, nb, s->zctx, NULL);
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
                    rs_json_append_unique(conds, line);
                    jury_conds_add(&jc, f->poly + i, 1);
                    free(line);
                }
            }
            if (neg) fmpz_mpoly_neg(kept, kept, s->zctx);
            if (!fmpz_mpoly_is_one(kept, s->zctx)) {
                char *line = rs_cond_string(kept, s, "> 0");
                rs_json_append_unique(conds, line);
                jury_conds_add(&jc, kept, 0);
                free(line);
            }
            fmpz_mpoly_clear(kept, s->zctx);
        }
        fmpz_mpoly_factor_clear(f, s->zctx);
        /* p_{k-1}: coefficient j = a_k a_{j+1} - a_0 a_{k-1-j}, j = 0..k-1;
         * the row's products estimated first (calibrated on the rows formed,
         * as the Routh and Hurwitz rows): the 5-mass chain's table took 2.6 GB
         * before its time limit (issue 17) */
        if (k > 1) {
            double raw = 0.0;
            for (j = 0; j < k; j++)
                raw += rs_budget_mpoly_mul_seconds(a + k, a + j + 1)
                     + rs_budget_mpoly_mul_seconds(a + 0, a + k - 1 - j);
            r = rs_budget_estimate(run->err, "a row of the symbolic Schur-Cohn table",
                                   rs_budget_calib_begin(&cal, raw), 0.0);
            if (r != RS_OK) break;
        }
        {
            fmpz_mpoly_struct *b = flint_malloc(k * sizeof(fmpz_mpoly_struct));
            for (j = 0; j < k; j++) {
                fmpz_mpoly_init(b + j, s->zctx);
                if (r == RS_OK) r = rs_budget_check(run->err, "the symbolic Schur-Cohn table");
                if (r != RS_OK) continue;
                fmpz_mpoly_mul(t, a + k, a + j + 1, s->zctx);
                fmpz_mpoly_mul(u, a + 0, a + k - 1 - j, s->zctx);
                fmpz_mpoly_sub(b + j, t, u, s->zctx);
            }
            if (k > 1) rs_budget_calib_end(&cal);
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
    rs_run_bounds_clear(bd, run);
    if (r == RS_OK && switched > 0) {
        json_decref(rows);
        json_decref(conds);
        r = jury_bilinear(run, v, o, dropped, n - k, switched);
    } else if (r == RS_OK) {
        json_object_set_new(o, "symbolic", json_true());
        json_object_set_new(o, "rows", rows);
        json_object_set_new(o, "conditions", conds);
        json_object_set_new(o, "dropped", dropped);
        json_object_set_new(o, "note", json_string(
            "Schur-Cohn reduction p_{k-1} = (lead p_k * p_k - p_k(0) p_k*)/lambda, each row divided by its content: "
            "all |lambda| < 1 iff every lead^2 - const^2 > 0 (Schur 1917, strict inequalities: exact for every "
            "value; where the leading coefficient of p vanishes the first condition fails)"));
        char *why = NULL;
        rs_hurwitz_or_t hb;
        json_t *cr = json_pack("{s:s}", "with", "hurwitz (Lienard-Chipart of the bilinear image q(z))");
        jury_cross_t w = {&jc, NULL, run, NULL, 0, 0};
        rs_hurwitz_or_init(hb);
        if (jury_cross_route(hb, run, v, cr)) w.hb = hb;
        /* a set that can never all hold: said as the singular row says it */
        if (json_object_get(o, "never") == NULL && rs_run_conds_never(&why, run, jc.poly, jc.ne, jc.n, s)) {
            rs_str_catf(&why, "; never asymptotically stable");
            rs_json_set_never_conditions(o, why);
            json_object_set_new(cr, "never_proved_by", json_string("jury"));
        } else if (json_object_get(o, "never") != NULL) {
            json_object_set_new(cr, "never_proved_by", json_string("jury"));
        }
        if (w.hb != NULL) {
            /* the bilinear image's own "never" (SymPy's p6: D_2 = 0
             * identically, while the table's conditions admit no relation
             * rs_conds_never sees): the answer of this route too, the table's
             * conditions kept and checked against it at the sample points */
            json_t *ho = json_object();
            int hv = rs_json_hurwitz_or(ho, hb, s);
            if (hv >= 0 && rs_run_hurwitz_or_never(run, ho, hb, s)) hv = -1;
            if (hv < 0) {
                const char *hw = json_string_value(json_object_get(ho, "never"));
                json_object_set_new(cr, "never", json_string(hw != NULL ? hw : "a condition never holds"));
                if (json_object_get(o, "never") == NULL) {
                    flint_free(why);
                    why = NULL;
                    rs_str_catf(&why, "the bilinear image q(z) = (z - 1)^n p((z + 1)/(z - 1)) (hurwitz's "
                                "route, the same question) proves it: %s", hw != NULL ? hw : "a condition never holds");
                    rs_json_set_never_conditions(o, why);
                    json_object_set_new(o, "never_from", json_string("bilinear"));
                    json_object_set_new(cr, "never_proved_by", json_string("hurwitz"));
                } else {
                    json_object_set_new(cr, "never_proved_by", json_string("both"));
                }
            }
            json_decref(ho);
        }
        flint_free(why);
        r = rs_run_sample_check_never(run, v, jury_cross_holds, &w, o);
        if (w.hb != NULL) {
            json_object_set_new(cr, "points", json_integer(w.points));
            json_object_set_new(cr, "agree", json_boolean(w.bad == NULL));
            if (w.bad != NULL) {
                /* two theorems about the same set: a bug */
                json_object_set_new(cr, "point", w.bad);
                json_object_set_new(cr, "table_says", json_string(w.table_says ? "stable" : "not stable"));
                run->outcome |= RS_OUTCOME_INCONSISTENT;
            }
        }
        rs_hurwitz_or_clear(hb, s->zctx);
        json_object_set_new(o, "cross_route", cr);
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
    int r, done;
    if (run->m->qd != NULL)   /* over Q(sqrt d) (an_qd_conds.c), at complex set values over Q(sqrt d)(i) */
        return run->c->ncsets > 0 ? rs_an_qd_cx_conds(run, req, 0) : rs_an_qd_jury(run, req);
    if (rs_an_complex_conds_applies(run)) return rs_an_complex_jury(run, req);
    r = rs_run_variant_or_vanishing(&v, &done, run, "jury", 0);
    if (r != RS_OK || done) return r;
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
        rs_run_count_zeros(ju->count, v, p);   /* det's roots at 0 count inside */
        rs_json_add_count(o, ju->count);
        json_object_set_new(o, "cross_check", json_pack("{s:s,s:b}", "with", "routh (bilinear)", "agree", agree));
        if (!agree) run->outcome |= RS_OUTCOME_INCONSISTENT;
        r = rs_run_numeric_verdict(run, p, ju->count, o);
        if (r == RS_OK) rs_run_emit_exact(run, v, o);
        else json_decref(o);
    }
    rs_jury_clear(ju);
    rs_routh_clear(ro);
    fmpz_poly_clear(p);
    return r;
}
