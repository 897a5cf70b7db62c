/* conditions.c -- the symbolic stability conditions (Hurwitz /
 * Lienard-Chipart of q(z), an OR of branches over the sign of its leading
 * coefficient) as JSON, shared by hurwitz, region and the maps' boundary. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "analysis/impl.h"
#include "recstab/bilinear.h"
#include "recstab/positivity.h"
#include "recstab/str.h"

void rs_json_append_unique(json_t *arr, const char *str)
{
    size_t i;
    for (i = 0; i < json_array_size(arr); i++)
        if (strcmp(json_string_value(json_array_get(arr, i)), str) == 0) return;
    json_array_append_new(arr, json_string(str));
}

json_t *rs_json_factor(const fmpz_mpoly_t f, const rs_scheme_t s)
{
    return rs_json_zpoly(f, s);
}

const char rs_hurwitz_not_expanded_note[] =
    "these Hurwitz minors were not expanded: the estimated cost of the next fraction-free Routh row or "
    "composition (a fixed model of term counts, degrees and coefficient sizes, not the clock, so the same "
    "minors at any load) would have taken the estimates of all expansion steps over the expansion budget "
    "(--expand-seconds), exceeded a per-step row share (--row-share) or what was left of the budget (then "
    "limit_note names the limit); their conditions D_k > 0 are decided at each sample point by the exact "
    "rational determinant of the k x k Hurwitz matrix there";

void rs_json_hurwitz_limit_note(json_t *o, const rs_hurwitz_struct *h)
{
    if (h->limit_note[0] != '\0' && json_object_get(o, "limit_note") == NULL)
        json_object_set_new(o, "limit_note", json_string(h->limit_note));
    if (h->expanded < h->n && h->stop_note[0] != '\0' && json_object_get(o, "not_expanded_reason") == NULL)
        json_object_set_new(o, "not_expanded_reason", json_string(h->stop_note));
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
int rs_run_hurwitz_or(rs_hurwitz_or_t hb, rs_run_t *run, const rs_variant_t *v, fmpz_mpoly_t qz)
{
    const rs_scheme_struct *s = v->s;
    const rs_case_struct *c = run->c;
    int *sign = rs_run_signs(run, s);
    /* the parameters' intervals for the factors' sign tests (interval
     * mapping before Polya, issue 17); params are the first variables */
    rs_bound_t *b = rs_run_bounds(run);
    int r;
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, s->lambda_var, s->zctx);
    r = rs_hurwitz_or_compute_bounds(hb, qz, s->lambda_var, v->cp->degree, (const rs_sign_t *) sign, b,
                                     FLINT_MIN(c->nparams, s->nvars), s->zctx, run->err);
    rs_run_bounds_clear(b, run);
    flint_free(sign);
    return r;
}

int rs_run_hurwitz_or_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
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
        if (h->cond[i].not_expanded) {
            /* no polynomial to print (hurwitz.h) */
            char buf[64];
            snprintf(buf, sizeof buf, "%s > 0 (not expanded)", h->cond[i].origin);
            rs_json_append_unique(a, buf);
            continue;
        }
        line = rs_cond_string(h->cond[i].reduced, s, "> 0");
        rs_json_append_unique(a, line);
        free(line);
    }
    for (i = 0; i < h->ncond; i++)
        for (k = 0; k < h->cond[i].factors->num; k++)
            if (!h->cond[i].dropped[k] && h->cond[i].even[k]) {
                char *line = rs_cond_string(h->cond[i].factors->poly + k, s, "!= 0");
                rs_json_append_unique(a, line);
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

/* "NAME op END" of one end of a parameter's assumed interval, appended */
static void bound_text(char *buf, size_t len, const char *name, const rs_bound_t *b)
{
    char *lo = b != NULL && b->has_lo ? fmpq_get_str(NULL, 10, b->lo) : NULL;
    char *hi = b != NULL && b->has_hi ? fmpq_get_str(NULL, 10, b->hi) : NULL;
    if (lo != NULL && hi != NULL)
        snprintf(buf, len, "%s %s %s %s %s", lo, b->lo_closed ? "<=" : "<", name, b->hi_closed ? "<=" : "<", hi);
    else if (lo != NULL)
        snprintf(buf, len, "%s %s %s", name, b->lo_closed ? ">=" : ">", lo);
    else if (hi != NULL)
        snprintf(buf, len, "%s %s %s", name, b->hi_closed ? "<=" : "<", hi);
    else
        snprintf(buf, len, "%s real", name);   /* not reached from rs_conds_never */
    flint_free(lo);
    flint_free(hi);
}

/* Whether the conditions c[i] > 0 (i < n) can never all hold for the values
 * the bounds b (nb parameters, the first variables) allow, decided cheaply
 * and exactly (no sample): a constant <= 0; two conditions c, c' with
 * c' = -k c, k > 0 rational (lc(c) c' = lc(c') c with leading coefficients
 * of opposite signs); the conditions in one parameter alone without a
 * common solution in its interval (rs_positivity_none_positive); or two
 * conditions whose sum is provably < 0 under the bounds.  1 and the
 * reason appended to *why, else 0.  Only a subset is needed to be empty, so the
 * other conditions ("!= 0" ones included) may be left out.  The reason
 * ends without "never asymptotically stable" (the caller adds it once). */
/* conditions longer than this are left out of the pairwise sum test */
#define RS_CONDS_NEVER_PAIR_TERMS 200

int rs_conds_never(char **why, const fmpz_mpoly_struct *const *c, slong n, const rs_bound_t *b,
                   slong nb, const rs_scheme_struct *s)
{
    const fmpz_mpoly_ctx_struct *ctx = s->zctx;
    const fmpz_mpoly_struct **one = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct *));
    slong *var = flint_malloc((n + 1) * sizeof(slong));
    fmpz_mpoly_t t, u;
    slong i, j, v, m;
    int found = 0;
    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(u, ctx);
    for (i = 0; i < n && !found; i++) {
        if (fmpz_mpoly_is_fmpz(c[i], ctx) && (fmpz_mpoly_is_zero(c[i], ctx) || fmpz_sgn(c[i]->coeffs) < 0)) {
            char *li = rs_cond_string(c[i], s, "> 0");
            rs_str_catf(why, "the condition %s never holds", li);
            free(li);
            found = 1;
        }
        for (j = i + 1; j < n && !found && !fmpz_mpoly_is_zero(c[i], ctx); j++) {
            if (fmpz_mpoly_is_zero(c[j], ctx) || fmpz_sgn(c[i]->coeffs) == fmpz_sgn(c[j]->coeffs)
                || fmpz_mpoly_length(c[i], ctx) != fmpz_mpoly_length(c[j], ctx))
                continue;
            fmpz_mpoly_scalar_mul_fmpz(t, c[j], c[i]->coeffs, ctx);
            fmpz_mpoly_scalar_mul_fmpz(u, c[i], c[j]->coeffs, ctx);
            if (fmpz_mpoly_equal(t, u, ctx)) {
                char *li = rs_cond_string(c[i], s, "> 0"), *lj = rs_cond_string(c[j], s, "> 0");
                rs_str_catf(why, "the conditions %s and %s contradict (one is a negative multiple of the "
                            "other, both strict): no value satisfies both", li, lj);
                free(li);
                free(lj);
                found = 1;
            }
        }
    }
    /* per parameter, the conditions in it alone against its interval (each
     * condition's one variable found once: the minors can be large) */
    for (i = 0; i < n && !found; i++) var[i] = rs_positivity_single_var(c[i], ctx);
    for (v = 0; v < s->nvars && !found; v++) {
        if (v == s->lambda_var) continue;
        for (m = 0, i = 0; i < n; i++)
            if (var[i] == v) one[m++] = c[i];
        if (m > 0 && rs_positivity_none_positive(one, m, v, v < nb ? b + v : NULL, ctx)) {
            char range[200];
            /* "no value with a >= 1", or "no real value of a" with no bound */
            if (v < nb && (b[v].has_lo || b[v].has_hi)) {
                bound_text(range, sizeof range, s->vars[v], b + v);
                rs_str_catf(why, "no value with %s satisfies ", range);
            } else {
                rs_str_catf(why, "no real value of %s satisfies ", s->vars[v]);
            }
            for (i = 0; i < m; i++) {
                char *li = rs_cond_string(one[i], s, "> 0");
                rs_str_catf(why, "%s%s", i == 0 ? "" : " and ", li);
                free(li);
            }
            rs_str_catf(why, " (real roots isolated, one exact sample in each gap of the admissible interval)");
            found = 1;
        }
    }
    /* two conditions whose sum is < 0 for every value the assumptions allow
     * (the coefficient test, Polya and the interval mapping of
     * rs_positivity_sign_bounds: sufficient, exact) cannot both be > 0
     * (SymPy's p6 under b0, b1, b3 > 0).  Only small conditions: the test
     * runs on every pair */
    if (!found && n > 1) {
        int *sign = flint_calloc(s->nvars + 1, sizeof(int));
        if (b != NULL) rs_bounds_signs(sign, b, FLINT_MIN(nb, s->nvars));
        for (i = 0; i < n && !found; i++) {
            if (fmpz_mpoly_length(c[i], ctx) > RS_CONDS_NEVER_PAIR_TERMS) continue;
            for (j = i + 1; j < n && !found; j++) {
                if (fmpz_mpoly_length(c[j], ctx) > RS_CONDS_NEVER_PAIR_TERMS) continue;
                fmpz_mpoly_add(t, c[i], c[j], ctx);
                if (fmpz_mpoly_is_zero(t, ctx)
                    || rs_positivity_sign_bounds(t, (const rs_sign_t *) sign, b, nb, ctx, NULL) >= 0)
                    continue;
                {
                    char *li = rs_cond_string(c[i], s, "> 0"), *lj = rs_cond_string(c[j], s, "> 0");
                    char *st = rs_cond_string(t, s, "< 0");
                    rs_str_catf(why, "the conditions %s and %s cannot both hold: their sum is negative for "
                                "every value the assumptions allow (%s)", li, lj, st);
                    free(li);
                    free(lj);
                    free(st);
                    found = 1;
                }
            }
        }
        flint_free(sign);
    }
    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(u, ctx);
    flint_free(one);
    flint_free(var);
    return found;
}

/* rs_conds_never on conditions given as polynomials (ne[i]: a "!= 0" one,
 * left out; NULL: none), the intervals from the run's assume lines */
int rs_run_conds_never(char **why, rs_run_t *run, const fmpz_mpoly_struct *poly, const int *ne,
                       slong n, const rs_scheme_struct *s)
{
    const fmpz_mpoly_struct **c = flint_malloc((n + 1) * sizeof(fmpz_mpoly_struct *));
    rs_bound_t *b = rs_run_bounds(run);
    slong i, m = 0;
    int r;
    for (i = 0; i < n; i++)
        if (ne == NULL || !ne[i]) c[m++] = poly + i;
    r = rs_conds_never(why, c, m, b, FLINT_MIN(run->c->nparams, s->nvars), s);
    rs_run_bounds_clear(b, run);
    flint_free(c);
    return r;
}

/* "never" (the reason) with "never_from": "conditions" -- the stated
 * conditions stay in o and are printed after the reason -- and "verdict" */
void rs_json_set_never_conditions(json_t *o, const char *why)
{
    json_object_set_new(o, "never", json_string(why));
    json_object_set_new(o, "never_from", json_string("conditions"));
    json_object_set_new(o, "verdict", json_string("never stable"));
}

/* Hurwitz's branches all contradictory (rs_conds_never on each branch's
 * stated "> 0" conditions): "never" into o (the conditions stay) and 1;
 * 0 when some branch may hold or o already says never. */
int rs_run_hurwitz_or_never(rs_run_t *run, json_t *o, const rs_hurwitz_or_t hb, const rs_scheme_struct *s)
{
    char *why[2] = {NULL, NULL}, *all = NULL;
    rs_bound_t *b;
    const fmpz_mpoly_struct **c;
    slong k, i, m, nmax = 0;
    int never = hb->nbranch > 0;
    if (json_object_get(o, "never") != NULL || hb->nbranch == 0) return 0;
    /* one branch with an identically false condition: already "never
     * stable", said in words by the report (rs_json_hurwitz_or) */
    for (i = 0; hb->nbranch == 1 && i < hb->branch[0].ncond; i++)
        if (hb->branch[0].cond[i].trivially_false) return 0;
    for (k = 0; k < hb->nbranch; k++) nmax = FLINT_MAX(nmax, hb->branch[k].ncond);
    b = rs_run_bounds(run);
    c = flint_malloc((nmax + 1) * sizeof(fmpz_mpoly_struct *));
    for (k = 0; k < hb->nbranch && never; k++) {
        for (m = 0, i = 0; i < hb->branch[k].ncond; i++)
            if (!hb->branch[k].cond[i].trivially_true && !hb->branch[k].cond[i].not_expanded)
                c[m++] = hb->branch[k].cond[i].reduced;
        never = rs_conds_never(why + k, c, m, b, FLINT_MIN(run->c->nparams, s->nvars), s);
    }
    flint_free(c);
    rs_run_bounds_clear(b, run);
    if (never && hb->nbranch == 2)
        rs_str_catf(&all, "neither branch can hold: branch 1: %s; branch 2: %s; never asymptotically stable",
                    why[0], why[1]);
    else if (never)
        rs_str_catf(&all, "%s; never asymptotically stable", why[0]);
    if (never) rs_json_set_never_conditions(o, all);
    flint_free(why[0]);
    flint_free(why[1]);
    flint_free(all);
    return never;
}

/* The sample check, and where o says "never" its cross-check: no admissible
 * sample point may satisfy the conditions (holds = 1 there contradicts the
 * exact emptiness proof: exit 3). */
typedef struct {
    rs_holds_fn holds;
    const void *data;
    int held;
} never_check_t;

static int never_check_holds(const void *data, fmpq *const *pt, const rs_scheme_struct *s)
{
    never_check_t *w = (never_check_t *) data;   /* our own, writable */
    int h = w->holds(w->data, pt, s);
    if (h == 1) w->held = 1;
    return h;
}

int rs_run_sample_check_never(rs_run_t *run, const rs_variant_t *v, rs_holds_fn holds, const void *data, json_t *o)
{
    never_check_t w = {holds, data, 0};
    json_t *chk;
    int r;
    if (json_object_get(o, "never") == NULL) return rs_run_sample_check(run, v, holds, data, o);
    r = rs_run_sample_check(run, v, never_check_holds, &w, o);
    chk = json_object_get(o, "sample_check");
    if (r == RS_OK && chk != NULL) {
        json_object_set_new(chk, "never_confirmed", json_boolean(!w.held));
        if (w.held) {
            json_object_set_new(chk, "agree", json_false());
            run->outcome |= RS_OUTCOME_INCONSISTENT;
        }
    }
    return r;
}

/* "conditions" (one branch) or "branches" (an OR of two), "never" when
 * no branch can hold; returns 1 if every condition of a branch holds under
 * the assumptions, -1 if no branch can hold, 0 otherwise. */
int rs_json_hurwitz_or(json_t *o, const rs_hurwitz_or_t hb, const rs_scheme_t s)
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
    return rs_run_symbolic_conditions_dropped(run, v, o, verdict, NULL);
}

/* The same, and when dropped != NULL (jury's bilinear route, issue 17)
 * every factor dropped as of one sign under the assumptions appended to it
 * as {"factor", "from"}, and "not_expanded_note" when a minor was not
 * expanded. */
int rs_run_symbolic_conditions_dropped(rs_run_t *run, const rs_variant_t *v, json_t *o, int *verdict,
                                       json_t *dropped)
{
    const rs_scheme_struct *s = v->s;
    rs_hurwitz_or_t hb;
    fmpz_mpoly_t qz;
    slong b, i, k;
    int r;
    fmpz_mpoly_init(qz, s->zctx);
    rs_hurwitz_or_init(hb);
    r = rs_run_hurwitz_or(hb, run, v, qz);
    if (r == RS_OK) {
        *verdict = rs_json_hurwitz_or(o, hb, s);
        if (rs_run_hurwitz_or_never(run, o, hb, s)) *verdict = -1;
        if (hb->nbranch == 1 && json_object_get(o, "never") == NULL)
            json_object_set_new(o, "conditions", branch_json(hb->branch + 0, s));
        for (b = 0; dropped != NULL && b < hb->nbranch; b++) {
            if (hb->branch[b].expanded < hb->branch[b].n && json_object_get(o, "not_expanded_note") == NULL)
                json_object_set_new(o, "not_expanded_note", json_string(rs_hurwitz_not_expanded_note));
            rs_json_hurwitz_limit_note(o, hb->branch + b);
        }
        for (b = 0; dropped != NULL && b < hb->nbranch; b++)
            for (i = 0; i < hb->branch[b].ncond; i++)
                for (k = 0; k < hb->branch[b].cond[i].factors->num; k++)
                    if (hb->branch[b].cond[i].dropped[k])
                        json_array_append_new(dropped, json_pack("{s:o,s:s}", "factor",
                            rs_json_factor(hb->branch[b].cond[i].factors->poly + k, s),
                            "from", hb->branch[b].cond[i].origin));
        r = rs_run_sample_check_never(run, v, rs_run_hurwitz_or_holds, hb, o);
    }
    rs_hurwitz_or_clear(hb, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
    return r;
}
