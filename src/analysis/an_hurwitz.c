/* an_hurwitz.c -- `hurwitz`: the Hurwitz minors and Lienard-Chipart
 * conditions of q(z), factored, checked at sample points. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "util/polyfmt.h"

/* Lienard-Chipart (the stated conditions) and Hurwitz's full criterion (every
 * D_k of the rational Hurwitz matrix at the point, rs_hurwitz_or_full_at)
 * side by side at the sample points; the first disagreement is kept. */
typedef struct {
    const rs_hurwitz_or_struct *hb;
    const rs_run_t *run;
    slong points;
    json_t *bad;
    int lc_says;
} full_check_t;

static int holds_both(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    full_check_t *fc = (full_check_t *) data;   /* our own, writable */
    int lc = rs_hurwitz_or_holds(fc->hb, pt, s->zctx), full;
    if (lc < 0) return lc;
    full = rs_hurwitz_or_full_at(fc->hb, pt, s->zctx);
    if (full < 0) return lc;
    fc->points++;
    if (full != lc && fc->bad == NULL) {
        fc->bad = rs_run_point_json(fc->run, pt, s->nvars);
        fc->lc_says = lc;
    }
    return lc;
}

/* The set values drop the degree of det A in lambda (v->singular): the
 * implicit step cannot be solved there, never stable whatever the minors of
 * the reduced q say (jury, stability and claim say singular) */
static int never_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    (void) data; (void) pt; (void) s;
    return 0;
}

static void hurwitz_singular(json_t *o)
{
    json_object_del(o, "branches");
    json_object_set_new(o, "conditions", json_array());
    json_object_set_new(o, "never", json_string(
        "the leading coefficient of det A(lambda) vanishes at these values (its degree in lambda drops): "
        "the implicit step cannot be solved; never asymptotically stable"));
    json_object_set_new(o, "verdict", json_string("never stable"));
}

/* a name prefix for the small ring's G_r that no parameter can be read as
 * (a parameter called G1 would make "G1 = ..." ambiguous): the first of
 * G, H, Q, W, G_, GG, ... no variable spells as prefix + digits */
static void
hurwitz_small_prefix(char *pre, size_t len, const rs_scheme_t s)
{
    static const char *const cand[] = {"G", "H", "Q", "W", "G_", "GG", "Gr_"};
    size_t c, k;
    slong v;
    for (c = 0; ; c++) {
        int clash = 0;
        if (c < sizeof(cand) / sizeof(cand[0]))
            snprintf(pre, len, "%s", cand[c]);
        else
            snprintf(pre, len, "G%zu_", c);
        for (v = 0; v < s->nvars && !clash; v++) {
            const char *n = s->vars[v];
            k = strlen(pre);
            if (strncmp(n, pre, k) == 0 && n[k] != '\0' && strspn(n + k, "0123456789") == strlen(n + k))
                clash = 1;
        }
        if (!clash)
            return;
    }
}

/* issue 17: the not-expanded minors over the small ring (h->small):
 * {"variables", "definitions": [{"name", "poly"}], "denominator",
 *  "note", "minors": [{"minor", "terms", "poly"}]} */
static json_t *
hurwitz_small_ring(const rs_hurwitz_struct *h, const rs_scheme_t s)
{
    json_t *o = json_object(), *vars = json_array(), *defs = json_array(), *mins = json_array();
    char **names = flint_malloc(h->small_nvars * sizeof(char *));
    slong i, v;
    char *str, pre[32];
    int named0 = 0;

    hurwitz_small_prefix(pre, sizeof(pre), s);
    for (i = 0; i < h->small_nvars; i++) {
        names[i] = flint_malloc(64);
        snprintf(names[i], 64, "%s%ld", pre, (long) i);
        if (i == 0 && fmpz_mpoly_length(h->small_img + 0, s->zctx) == 1
            && fmpz_mpoly_total_degree_si(h->small_img + 0, s->zctx) == 1
            && fmpz_is_one(h->small_img[0].coeffs + 0))
            for (v = 0; v < s->nvars; v++)
                if (fmpz_mpoly_degree_si(h->small_img + 0, v, s->zctx) == 1)
                {
                    flint_free(names[0]);
                    names[0] = flint_malloc(strlen(s->vars[v]) + 1);
                    strcpy(names[0], s->vars[v]);
                    named0 = 1;
                }
        json_array_append_new(vars, json_string(names[i]));
        if (i > 0 || !named0) {
            str = rs_scheme_zpoly_str(h->small_img + i, s);
            json_array_append_new(defs, json_pack("{s:s,s:s}", "name", names[i], "poly", str));
            flint_free(str);
        }
    }
    str = fmpz_get_str(NULL, 10, h->small_L);
    json_object_set_new(o, "variables", vars);
    json_object_set_new(o, "definitions", defs);
    json_object_set_new(o, "denominator", json_string(str));
    flint_free(str);
    json_object_set_new(o, "note", json_string(
        "each not-expanded minor exactly as D_k = P_k / denominator^k, P_k a polynomial in the variables above "
        "with the definitions substituted (the substitution route's ring; formed by evaluation modulo primes at "
        "the weights' candidate monomials and interpolation, with a proven coefficient bound); the conditions "
        "D_k > 0 are decided at sample points by P_k, and Hurwitz's full criterion checks them there"));
    for (i = 0; i < h->n; i++) {
        if (fmpz_mpoly_is_zero(h->small + i, h->small_ctx))
            continue;
        str = fmpz_mpoly_get_str_pretty(h->small + i, (const char **) names, h->small_ctx);
        json_array_append_new(mins, json_pack("{s:I,s:I,s:s}", "minor", (json_int_t) (i + 1), "terms",
                                              (json_int_t) fmpz_mpoly_length(h->small + i, h->small_ctx),
                                              "poly", str));
        flint_free(str);
    }
    json_object_set_new(o, "minors", mins);
    for (i = 0; i < h->small_nvars; i++)
        flint_free(names[i]);
    flint_free(names);
    return o;
}

/* det A = c lambda^k: once the roots at 0 are divided out p (and q) is a
 * constant c, so there is no Hurwitz minor: every root is 0 where c != 0,
 * and where c = 0 there is no polynomial (hurwitz.c refuses degree 0; jury
 * and stability say the same) */
static int hurwitz_dead_beat(rs_run_t *run, const rs_variant_t *v)
{
    json_t *o = json_object(), *conds = json_array();
    fmpz_mpoly_t kept;
    int r;
    fmpz_mpoly_init(kept, v->s->zctx);
    rs_run_dead_beat_nonzero(kept, conds, run, v->s, v->cp->p);
    json_object_set_new(o, "analysis", json_string("hurwitz"));
    json_object_set_new(o, "var", json_string("z"));
    json_object_set_new(o, "degree", json_integer(0));
    json_object_set_new(o, "p_at_1", rs_json_p_at(v, 1));
    json_object_set_new(o, "p_at_minus_1", rs_json_p_at(v, -1));
    json_object_set_new(o, "minors", json_array());
    json_object_set_new(o, "nonzero", json_array());
    json_object_set_new(o, "dead_beat", json_string(
        "det A = c*lambda^k: every root is 0 (dead-beat), spectral radius 0; q(z) is a constant"));
    json_object_set_new(o, "verdict", json_string(json_array_size(conds) == 0
        ? "stable under the assumptions (dead-beat: every root is 0)"
        : "stable iff the conditions hold (dead-beat there: every root is 0; where c = 0 det A vanishes "
          "identically)"));
    json_object_set_new(o, "conditions", conds);
    if (v->singular) hurwitz_singular(o);
    /* c != 0 against the exact point verdict */
    r = rs_run_sample_check(run, v, v->singular ? never_holds : rs_run_nonzero_holds, kept, o);
    fmpz_mpoly_clear(kept, v->s->zctx);
    if (r == RS_OK) rs_run_emit_exact(run, v, o);
    else json_decref(o);
    return r;
}

/* "a_2 = a^2 + 2*a + 1 > 0, i.e. 1 > 0 once (a + 1)^2 is taken out (...)"
 * for a condition whose factors all went (even powers kept as != 0, factors
 * of one sign under the assumptions dropped); a static buffer, used at once */
static const char *hurwitz_constant_line(const rs_hurwitz_cond_struct *c, const rs_scheme_struct *s)
{
    static char line[1200];
    char *red = rs_polyfmt_fmpz_mpoly(c->reduced, (const char **) s->vars, s->zctx);
    size_t at;
    slong k;
    if (fmpz_mpoly_length(c->poly, s->zctx) <= 40) {
        char *full = rs_polyfmt_fmpz_mpoly(c->poly, (const char **) s->vars, s->zctx);
        snprintf(line, sizeof line, "%s = %s > 0, i.e. %s > 0 once ", c->origin, full, red);
        free(full);
    } else {
        snprintf(line, sizeof line, "%s > 0, i.e. %s > 0 once ", c->origin, red);
    }
    for (k = 0; k < c->factors->num; k++) {
        char *f = rs_polyfmt_fmpz_mpoly(c->factors->poly + k, (const char **) s->vars, s->zctx);
        slong e = fmpz_get_si(c->factors->exp + k);
        at = strlen(line);
        if (e > 1) snprintf(line + at, sizeof line - at, "%s(%s)^%ld", k > 0 ? " " : "", f, (long) e);
        else snprintf(line + at, sizeof line - at, "%s(%s)", k > 0 ? " " : "", f);
        free(f);
    }
    at = strlen(line);
    snprintf(line + at, sizeof line - at, " %s taken out (even powers are kept as != 0, factors of one sign "
             "under the assumptions dropped)", c->factors->num > 1 ? "are" : "is");
    free(red);
    return line;
}

int rs_an_hurwitz(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    rs_hurwitz_or_t hb;
    rs_hurwitz_struct *h;   /* its polynomials lent to the report (rs_run_json_zpoly_line) */
    fmpz_mpoly_t qz;
    json_t *o, *minors, *conds, *nonzero, *dropped, *always, *details;
    char *scratch = NULL;   /* one printing buffer for every polynomial (rs_json_zpoly_line) */
    size_t cap = 0;
    slong i, k;
    int r, verdict, done;
    if (run->m->qd != NULL)   /* over Q(sqrt d) (an_qd_conds.c), at complex set values over Q(sqrt d)(i) */
        return run->c->ncsets > 0 ? rs_an_qd_cx_conds(run, req, 1) : rs_an_qd_hurwitz(run, req);
    if (rs_an_complex_conds_applies(run)) return rs_an_complex_hurwitz(run, req);
    r = rs_run_variant_or_vanishing(&v, &done, run, "hurwitz", 0);
    if (r != RS_OK || done) return r;
    if (v->cp->degree < 1) return hurwitz_dead_beat(run, v);
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
    json_object_set_new(o, "p_at_1", rs_json_p_at(v, 1));
    json_object_set_new(o, "p_at_minus_1", rs_json_p_at(v, -1));
    minors = json_array();
    for (i = 0; i < h->n; i++)
        json_array_append_new(minors, i < h->expanded
                                          ? rs_run_json_zpoly_line(run, h->minors + i, s, NULL, NULL, &scratch, &cap)
                                          : json_string("not expanded"));
    json_object_set_new(o, "minors", minors);
    if (hb->nbranch > 0 && h->expanded < h->n) {
        json_t *ne = json_array();
        for (i = h->expanded; i < h->n; i++) json_array_append_new(ne, json_integer(i + 1));
        json_object_set_new(o, "not_expanded", ne);
        json_object_set_new(o, "not_expanded_note", json_string(rs_hurwitz_not_expanded_note));
        if (h->small_ctx != NULL)
            json_object_set_new(o, "small_ring", hurwitz_small_ring(h, s));
    }
    for (i = 0; i < hb->nbranch; i++)
        rs_json_hurwitz_limit_note(o, hb->branch + i);
    conds = json_array();
    nonzero = json_array();
    dropped = json_array();
    always = json_array();
    details = json_array();
    for (i = 0; i < h->ncond; i++) {
        rs_hurwitz_cond_struct *c = h->cond + i;
        json_t *d = json_object(), *fl = json_array(), *jred, *jline = NULL;
        json_object_set_new(d, "origin", json_string(c->origin));
        /* the same strings shared, not printed again (jansson counts the
         * references): a minor's condition is the minor itself, and a lone
         * kept factor is the reduced condition -- each 60 MB of text for the
         * 637 163-term D_11 of a 6-mass chain (issue 17) */
        if (c->minor >= 1 && c->minor <= h->expanded && !c->not_expanded)
            json_object_set(d, "poly", json_array_get(minors, (size_t) (c->minor - 1)));
        else
            json_object_set_new(d, "poly", rs_run_json_zpoly_line(run, c->poly, s, NULL, NULL, &scratch, &cap));
        /* the condition line "reduced > 0" printed with the reduced
         * condition, not formatted again from its 27 MB string (D_11 of a
         * 6-mass chain, issue 17) */
        jred = rs_run_json_zpoly_line(run, c->reduced, s,
                                  c->trivially_true || c->not_expanded ? NULL
                                  : c->factored ? "> 0" : "> 0 (not factored)", &jline, &scratch, &cap);
        for (k = 0; k < c->factors->num; k++) {
            json_t *f = json_object();
            if (fmpz_mpoly_equal(c->factors->poly + k, c->reduced, s->zctx))
                json_object_set(f, "factor", jred);
            else
                json_object_set_new(f, "factor", rs_run_json_zpoly_line(run, c->factors->poly + k, s, NULL, NULL,
                                                                    &scratch, &cap));
            json_object_set_new(f, "exponent", json_integer(fmpz_get_si(c->factors->exp + k)));
            json_object_set_new(f, "dropped", json_boolean(c->dropped[k]));
            json_array_append_new(fl, f);
            if (c->dropped[k]) {
                json_t *dd = json_object();
                json_object_set_new(dd, "factor", rs_json_factor(c->factors->poly + k, s));
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
        json_object_set_new(d, "reduced", jred);
        json_object_set_new(d, "trivially_true", json_boolean(c->trivially_true));
        json_object_set_new(d, "trivially_false", json_boolean(c->trivially_false));
        json_array_append_new(details, d);
        json_object_set_new(d, "not_expanded", json_boolean(c->not_expanded));
        if (!c->factored) json_object_set_new(d, "factored", json_false());
        if (c->trivially_true) {
            json_array_append_new(always, json_string(c->origin));
        } else if (c->not_expanded) {
            char line[64];
            snprintf(line, sizeof line, "%s > 0 (not expanded)", c->origin);
            json_array_append_new(conds, json_string(line));
        } else if (fmpz_mpoly_is_fmpz(c->reduced, s->zctx) && !fmpz_mpoly_is_fmpz(c->poly, s->zctx)) {
            /* a bare "1 > 0" does not say which coefficient it was: the
             * condition before its factors were taken out (h-truth6) */
            json_array_append_new(conds, json_string(hurwitz_constant_line(c, s)));
            json_decref(jline);
        } else {
            /* rs_cond_string's text; the cofactor of a condition too large
             * for a full factorisation (hurwitz.h) is said to be one in words */
            json_array_append_new(conds, jline);
        }
    }
    free(scratch);
    if (hb->nbranch == 1) {
        json_object_set_new(o, "conditions", conds);
        json_object_set_new(o, "nonzero", nonzero);
    } else {
        json_decref(conds);
        json_decref(nonzero);
    }
    verdict = rs_json_hurwitz_or(o, hb, s);
    /* singular set values override any contradiction found (hurwitz_singular below) */
    if (!v->singular && rs_run_hurwitz_or_never(run, o, hb, s)) verdict = -1;
    json_object_set_new(o, "dropped", dropped);
    json_object_set_new(o, "always_true", always);
    json_object_set_new(o, "details", details);
    json_object_set_new(o, "verdict", json_string(verdict > 0 ? "stable under the assumptions"
                                                  : verdict < 0 ? "never stable"
                                                  : hb->nbranch == 2 ? "stable iff one branch holds"
                                                  : "stable iff the conditions hold"));
    if (v->singular) hurwitz_singular(o);
    {
        full_check_t fc = {hb, run, 0, NULL, 0};
        json_t *chk;
        r = rs_run_sample_check_never(run, v, v->singular ? never_holds : holds_both, &fc, o);
        chk = json_object_get(o, "sample_check");
        if (r == RS_OK && chk != NULL) {
            json_object_set_new(chk, "full_hurwitz_points", json_integer(fc.points));
            if (fc.bad != NULL && json_is_true(json_object_get(chk, "agree"))) {
                /* the two criteria are theorems about the same q: a bug */
                json_object_set_new(chk, "agree", json_false());
                json_object_set_new(chk, "point", fc.bad);
                fc.bad = NULL;
                json_object_set_new(chk, "conditions_say", json_string(fc.lc_says ? "stable" : "not stable"));
                json_object_set_new(chk, "exact_verdict", json_string(
                    fc.lc_says ? "not stable by Hurwitz's full criterion (D_1..D_n at the point)"
                               : "stable by Hurwitz's full criterion (D_1..D_n at the point)"));
                run->outcome |= RS_OUTCOME_INCONSISTENT;
            }
        }
        if (fc.bad != NULL) json_decref(fc.bad);
    }
    if (r == RS_OK) rs_run_emit_exact(run, v, o);
    else json_decref(o);
    rs_run_polytext_keep(run);   /* before the polynomials lent to the report go */
    rs_hurwitz_or_clear(hb, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    return r;
}
