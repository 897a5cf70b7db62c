/* report.c -- text rendering of result documents. */
#include <stdlib.h>
#include <string.h>
#include <flint/flint.h>
#include "recstab/report.h"
#include "recstab/radius.h"

#define LABEL_W 12

static const char *jstr(const json_t *o, const char *key)
{
    const json_t *v = json_object_get(o, key);
    return json_is_string(v) ? json_string_value(v) : NULL;
}

static void line(FILE *out, const char *label, const char *fmt, const char *a)
{
    if (a == NULL) return;   /* a member this result does not have */
    fprintf(out, "  %-*s ", LABEL_W, label ? label : "");
    fprintf(out, fmt, a);
    fputc('\n', out);
}

static void print_assigned(FILE *out, const json_t *o)
{
    const json_t *sub = json_object_get(o, "substituted");
    const char *key;
    json_t *val;
    const json_t *nip = json_object_get(o, "not_in_p");
    size_t i;
    int first = 1;
    for (i = 0; i < json_array_size(nip); i++)
        fprintf(out, "%s%s%s", i == 0 ? "  not in p     " : ", ", json_string_value(json_array_get(nip, i)),
                i + 1 == json_array_size(nip) ? " (p does not depend on them: no value needed)\n" : "");
    if (!json_is_object(sub) || json_object_size(sub) == 0) return;
    fprintf(out, "  %-*s ", LABEL_W, "at");
    json_object_foreach((json_t *) sub, key, val) {
        fprintf(out, "%s%s = %s", first ? "" : ", ", key, json_string_value(val));
        first = 0;
    }
    fputc('\n', out);
}

static void print_string_list(FILE *out, const char *label, const json_t *arr, const char *sep)
{
    size_t i;
    if (!json_is_array(arr) || json_array_size(arr) == 0) return;
    fprintf(out, "  %-*s ", LABEL_W, label);
    for (i = 0; i < json_array_size(arr); i++) {
        const json_t *v = json_array_get(arr, i);
        if (i > 0) fputs(sep, out);
        if (json_is_string(v)) fputs(json_string_value(v), out);
        else {
            char *s = json_dumps(v, JSON_COMPACT | JSON_ENCODE_ANY);
            fputs(s, out);
            free(s);
        }
    }
    fputc('\n', out);
}

static void r_charpoly(FILE *out, const json_t *o)
{
    char buf[128];
    line(out, "p(lambda)", "%s", jstr(o, "poly"));
    snprintf(buf, sizeof buf, "%lld", (long long) json_integer_value(json_object_get(o, "degree")));
    line(out, "degree", "%s", buf);
    if (json_integer_value(json_object_get(o, "removed_lambda_power")) > 0) {
        snprintf(buf, sizeof buf, "lambda^%lld (roots at 0) divided out",
                 (long long) json_integer_value(json_object_get(o, "removed_lambda_power")));
        line(out, "removed", "%s", buf);
    }
    line(out, "content", "%s (det = content * lambda^k * p)", jstr(o, "content"));
    if (jstr(o, "param_content"))
        line(out, "param factor", "%s (common factor of all coefficients)", jstr(o, "param_content"));
    print_assigned(out, o);
    print_string_list(out, "assuming", json_object_get(o, "nonzero_assumptions"), ", ");
}

static void r_expect(FILE *out, const json_t *o)
{
    const char *st = jstr(o, "status");
    line(out, "checks", "%s", jstr(o, "text"));
    line(out, "status", "%s", st);
    if (st && strcmp(st, "different") == 0) {
        if (jstr(o, "derived")) line(out, "derived", "%s", jstr(o, "derived"));
        if (jstr(o, "expected_normalised")) line(out, "printed", "%s", jstr(o, "expected_normalised"));
        line(out, "difference", "%s", jstr(o, "difference"));
        if (jstr(o, "ratio")) line(out, "ratio", "printed = (%s) * derived", jstr(o, "ratio"));
    }
    print_assigned(out, o);
}


static long long jint(const json_t *o, const char *key)
{
    return (long long) json_integer_value(json_object_get(o, key));
}

/* Repeated circle roots: semisimple or a Jordan block, and which rule. */
static void print_circle_roots(FILE *out, const json_t *o)
{
    const json_t *cr = json_object_get(o, "circle_roots");
    size_t i;
    int any = 0;
    line(out, "singular", "%s", jstr(o, "singular"));
    line(out, "note", "%s", jstr(o, "dead_beat"));
    for (i = 0; i < json_array_size(cr); i++) {
        const json_t *e = json_array_get(cr, i);
        char buf[1024];
        if (jint(e, "multiplicity") < 2) continue;
        snprintf(buf, sizeof buf, "%s (x%lld): %s (dim ker A = %lld)", jstr(e, "factor"),
                 jint(e, "multiplicity"), json_is_true(json_object_get(e, "semisimple")) ? "semisimple"
                 : "Jordan block", jint(e, "kernel_dim"));
        line(out, any ? "" : "circle roots", "%s", buf);
        any = 1;
    }
    if (any) line(out, "rule", "%s", jstr(o, "rule"));
}

static void print_count(FILE *out, const json_t *o)
{
    const json_t *m = json_object_get(o, "on_multiplicities");
    size_t i;
    fprintf(out, "  %-*s %s: %lld inside, %lld on, %lld outside the unit circle", LABEL_W, "verdict",
            jstr(o, "status"), jint(o, "inside"), jint(o, "on"), jint(o, "outside"));
    if (jint(o, "at_one") > 0) fprintf(out, "; lambda = 1 (x%lld)", jint(o, "at_one"));
    if (jint(o, "at_minus_one") > 0) fprintf(out, "; lambda = -1 (x%lld)", jint(o, "at_minus_one"));
    for (i = 0; i < json_array_size(m); i++) {
        const json_t *e = json_array_get(m, i);
        fprintf(out, "%s%lld circle root%s of multiplicity %lld", i == 0 ? "; " : ", ",
                jint(e, "roots"), jint(e, "roots") == 1 ? "" : "s", jint(e, "multiplicity"));
    }
    fputc('\n', out);
    print_circle_roots(out, o);
}

static void print_decided(FILE *out, const json_t *o)
{
    const json_t *agree = json_object_get(o, "agree");
    if (json_is_boolean(agree))
        fprintf(out, "  %-*s %s (%s)\n", LABEL_W, "decided by", jstr(o, "decided_by"),
                json_is_true(agree) ? "Routh on q(z) and Schur-Cohn on p(lambda) agree"
                                    : "DISAGREEMENT between Routh and Schur-Cohn: internal inconsistency");
    else if (jstr(o, "decided_by"))
        line(out, "decided by", "%s", jstr(o, "decided_by"));
}

static void r_bilinear(FILE *out, const json_t *o)
{
    char buf[200];
    line(out, "q(z)", "%s", jstr(o, "poly"));
    line(out, "", "%s", "q(z) = (1-z)^n p((1+z)/(1-z)): |lambda| < 1 <=> Re z < 0");
    snprintf(buf, sizeof buf, "%lld (degree drop %lld = roots at lambda = -1; z = 0 of multiplicity %lld = roots at lambda = 1)",
             jint(o, "degree"), jint(o, "degree_drop"), jint(o, "zero_mult"));
    line(out, "degree", "%s", buf);
    line(out, "p(1)", "%s (lambda = 1 is a root where this vanishes)", jstr(o, "p_at_1"));
    line(out, "p(-1)", "%s (lambda = -1 is a root where this vanishes)", jstr(o, "p_at_minus_1"));
    print_assigned(out, o);
}

static void print_rows(FILE *out, const json_t *rows, slong deg, const json_t *powers)
{
    size_t i, j;
    for (i = 0; i < json_array_size(rows); i++) {
        const json_t *row = json_array_get(rows, i);
        char lab[32];
        /* each row's own power: the generalised step may skip powers */
        snprintf(lab, sizeof lab, "z^%ld", json_is_integer(json_array_get(powers, i))
                 ? (long) json_integer_value(json_array_get(powers, i)) : (long) (deg - (slong) i));
        fprintf(out, "  %-*s ", LABEL_W, lab);
        for (j = 0; j < json_array_size(row); j++)
            fprintf(out, "%s%s", j ? "   " : "", json_string_value(json_array_get(row, j)));
        fputc('\n', out);
    }
}

static void r_routh(FILE *out, const json_t *o)
{
    const json_t *rows = json_object_get(o, "rows");
    const json_t *ev = json_object_get(o, "events");
    size_t i;
    slong deg = (slong) json_array_size(rows) - 1;
    if (json_is_true(json_object_get(o, "symbolic"))) {
        line(out, "array", "%s", "fraction-free, symbolic");
        print_rows(out, rows, deg, NULL);
        for (i = 0; i < json_array_size(ev); i++)
            line(out, jstr(json_array_get(ev, i), "kind"), "%s", jstr(json_array_get(ev, i), "text"));
        line(out, "note", "%s", jstr(o, "note"));
        print_assigned(out, o);
        return;
    }
    print_rows(out, rows, deg, json_object_get(o, "powers"));
    if (json_object_get(o, "epsilon_signs") != NULL) {
        const json_t *es = json_object_get(o, "epsilon_signs");
        char buf[256];
        size_t n = 0;
        for (i = 0; i < json_array_size(es) && n + 4 < sizeof buf; i++) {
            json_int_t sg = json_integer_value(json_array_get(es, i));
            n += (size_t) snprintf(buf + n, sizeof buf - n, "%s%s", i ? " " : "", sg > 0 ? "+" : sg < 0 ? "-" : "0");
        }
        line(out, "eps -> 0+", "first column signs %s (zero first entries replaced by eps)", buf);
    }
    for (i = 0; i < json_array_size(ev); i++) {
        const json_t *e = json_array_get(ev, i);
        char lab[40];
        snprintf(lab, sizeof lab, "%s", jstr(e, "kind"));
        line(out, lab, "%s", jstr(e, "text"));
    }
    print_count(out, o);
    print_assigned(out, o);
}

/* "branches" (an OR of condition lists) or the reason no branch exists;
 * returns 1 if either was printed. */
static int print_branches(FILE *out, const json_t *o)
{
    const json_t *br = json_object_get(o, "branches");
    size_t i, j;
    if (jstr(o, "never") != NULL) {
        line(out, "never", "%s", jstr(o, "never"));
        return 1;
    }
    if (!json_is_array(br)) return 0;
    for (i = 0; i < json_array_size(br); i++) {
        const json_t *b = json_array_get(br, i);
        for (j = 0; j < json_array_size(b); j++)
            line(out, j > 0 ? "and" : i == 0 ? "stable iff" : "or", "%s", json_string_value(json_array_get(b, j)));
    }
    return 1;
}

/* the conditions checked against exact point verdicts */
static void print_sample_check(FILE *out, const json_t *o)
{
    const json_t *c = json_object_get(o, "sample_check");
    char buf[300];
    if (c == NULL) return;
    if (json_is_true(json_object_get(c, "agree"))) {
        snprintf(buf, sizeof buf, "conditions agree with the exact verdict at %lld admissible rational points",
                 jint(c, "points"));
    } else {
        char *pt = json_dumps(json_object_get(c, "point"), JSON_COMPACT | JSON_SORT_KEYS);
        snprintf(buf, sizeof buf, "DISAGREEMENT at %s: the conditions say %s, the exact verdict is %s", pt,
                 jstr(c, "conditions_say"), jstr(c, "exact_verdict"));
        free(pt);
    }
    line(out, "checked", "%s", buf);
}

static void r_hurwitz(FILE *out, const json_t *o)
{
    const json_t *minors = json_object_get(o, "minors");
    const json_t *conds = json_object_get(o, "conditions");
    const json_t *dropped = json_object_get(o, "dropped");
    size_t i;
    for (i = 0; i < json_array_size(minors); i++) {
        char lab[16];
        snprintf(lab, sizeof lab, "D_%zu", i + 1);
        line(out, lab, "%s", json_string_value(json_array_get(minors, i)));
    }
    if (print_branches(out, o)) {
        /* an OR of condition sets: printed by print_branches */
    } else if (json_array_size(conds) == 0) {
        line(out, "conditions", "%s", "none left: every Lienard-Chipart condition holds under the assumptions");
    }
    for (i = 0; i < json_array_size(conds) && jstr(o, "never") == NULL; i++)
        line(out, i == 0 ? "conditions" : "", "%s", json_string_value(json_array_get(conds, i)));
    print_string_list(out, "and", json_object_get(o, "nonzero"), ", ");
    for (i = 0; i < json_array_size(dropped); i++) {
        const json_t *d = json_array_get(dropped, i);
        char buf[512];
        snprintf(buf, sizeof buf, "%s (in %s): %s", jstr(d, "factor"), jstr(d, "from"), jstr(d, "reason"));
        line(out, i == 0 ? "dropped" : "", "%s", buf);
    }
    print_string_list(out, "always true", json_object_get(o, "always_true"), ", ");
    line(out, "p(1)", "%s (lambda = 1 is a root where this vanishes)", jstr(o, "p_at_1"));
    line(out, "p(-1)", "%s (lambda = -1 is a root where this vanishes)", jstr(o, "p_at_minus_1"));
    line(out, "verdict", "%s", jstr(o, "verdict"));
    print_sample_check(out, o);
    print_assigned(out, o);
}

static void r_jury(FILE *out, const json_t *o)
{
    const json_t *cc = json_object_get(o, "cross_check");
    if (json_is_true(json_object_get(o, "symbolic"))) {
        const json_t *c = json_object_get(o, "conditions");
        size_t i;
        line(out, "method", "%s", jstr(o, "method"));
        if (json_array_size(c) == 0)
            line(out, "conditions", "%s", "none left: every Schur-Cohn condition holds under the assumptions");
        for (i = 0; i < json_array_size(c); i++)
            line(out, i == 0 ? "stable iff" : "and", "%s", json_string_value(json_array_get(c, i)));
        line(out, "note", "%s", jstr(o, "note"));
        print_sample_check(out, o);
        print_assigned(out, o);
        return;
    }
    line(out, "method", "%s", jstr(o, "method"));
    if (json_is_true(json_object_get(o, "table_regular")))
        print_string_list(out, "table rows", json_object_get(o, "rows"), "\n               ");
    else
        line(out, "table", "%s", "singular Jury table: decided through gcd(p, p*) and the Schur-Cohn form");
    print_count(out, o);
    line(out, "cross-check", "%s", json_is_true(json_object_get(cc, "agree")) ? "Routh (bilinear) agrees"
                                                                            : "DISAGREES with Routh (bilinear)");
    print_assigned(out, o);
}

static void r_radius(FILE *out, const json_t *o);

static void r_stability(FILE *out, const json_t *o)
{
    if (json_object_get(o, "inside") == NULL) { r_radius(out, o); return; }
    print_count(out, o);
    print_decided(out, o);
    print_assigned(out, o);
}

static const char *endpoint(char *buf, size_t len, const json_t *e, int hi)
{
    if (json_is_null(e) || e == NULL) snprintf(buf, len, "%s", hi ? "inf" : "-inf");
    else if (json_is_string(e)) snprintf(buf, len, "%s", json_string_value(e));
    else snprintf(buf, len, "%s", jstr(e, "approx"));
    return buf;
}

static void r_region(FILE *out, const json_t *o)
{
    const json_t *ivs = json_object_get(o, "intervals");
    const json_t *pts = json_object_get(o, "undecided_points");
    size_t i;
    if (json_is_true(json_object_get(o, "symbolic"))) {
        const json_t *c = json_object_get(o, "conditions");
        if (!print_branches(out, o) && json_array_size(c) == 0)
            line(out, "stable iff", "%s", "true: every condition holds under the assumptions");
        for (i = 0; i < json_array_size(c) && jstr(o, "never") == NULL; i++)
            line(out, i == 0 ? "stable iff" : "and", "%s", json_string_value(json_array_get(c, i)));
        line(out, "note", "%s", jstr(o, "note"));
        print_sample_check(out, o);
        print_assigned(out, o);
        return;
    }
    for (i = 0; i < json_array_size(ivs); i++) {
        const json_t *iv = json_array_get(ivs, i);
        char a[128], b[128], lab[160];
        endpoint(a, sizeof a, json_object_get(iv, "lo"), 0);
        endpoint(b, sizeof b, json_object_get(iv, "hi"), 1);
        if (strcmp(a, b) == 0) snprintf(lab, sizeof lab, "%s = %s", jstr(o, "param"), a);
        else snprintf(lab, sizeof lab, "%s in %s%s, %s%s", jstr(o, "param"),
                      json_is_true(json_object_get(iv, "lo_closed")) ? "[" : "(", a, b,
                      json_is_true(json_object_get(iv, "hi_closed")) ? "]" : ")");
        fprintf(out, "  %-10s %s\n", jstr(iv, "status"), lab);
    }
    /* algebraic endpoints in exact form */
    for (i = 0; i < json_array_size(ivs); i++) {
        const json_t *hi = json_object_get(json_array_get(ivs, i), "hi");
        if (json_is_object(hi) && (i + 1 == json_array_size(ivs) ||
            !json_equal(hi, json_object_get(json_array_get(ivs, i + 1), "hi")))) {
            char buf[600];
            snprintf(buf, sizeof buf, "%s is root %lld (from below, 0-based) of %s", jstr(hi, "approx"),
                     jint(hi, "root_index"), jstr(hi, "minpoly"));
            line(out, "where", "%s", buf);
        }
    }
    for (i = 0; i < json_array_size(pts); i++) {
        const json_t *p = json_array_get(pts, i);
        char buf[128];
        endpoint(buf, sizeof buf, json_object_get(p, "value"), 0);
        line(out, "undecided", "%s (status at this point itself not decided exactly)", buf);
    }
    print_assigned(out, o);
}

static void r_limit(FILE *out, const json_t *o)
{
    const json_t *roots = json_object_get(o, "roots");
    size_t i;
    char lab[80];
    snprintf(lab, sizeof lab, "%s -> %s", jstr(o, "param"), jstr(o, "to"));
    line(out, lab, "roots tend to the roots of %s", jstr(o, "limit_poly"));
    for (i = 0; i < json_array_size(roots); i++) {
        const json_t *r = json_array_get(roots, i);
        char buf[300];
        snprintf(buf, sizeof buf, "%s (multiplicity %lld)%s%s", jstr(r, "value"), jint(r, "multiplicity"),
                 jstr(r, "minpoly") ? ", root of " : "", jstr(r, "minpoly") ? jstr(r, "minpoly") : "");
        line(out, "", "%s", buf);
    }
    if (json_is_true(json_object_get(o, "all_roots_to_zero")))
        line(out, "", "%s", "every root tends to 0 (strong decay)");
    print_assigned(out, o);
}

static void r_claim(FILE *out, const json_t *o)
{
    const char *st = jstr(o, "status");
    char buf[128];
    line(out, "claim", "%s", jstr(o, "text"));
    line(out, "status", "%s", st);
    if (st && strcmp(st, "refuted") == 0) {
        const json_t *ce = json_object_get(o, "counterexample"), *at = json_object_get(o, "at_counterexample");
        const char *key;
        json_t *val;
        int first = 1;
        fprintf(out, "  %-*s ", LABEL_W, "counterexample");
        json_object_foreach((json_t *) ce, key, val) {
            fprintf(out, "%s%s = %s", first ? "" : ", ", key, json_string_value(val));
            first = 0;
        }
        if (first) fputs("the scheme as given (no free parameter)", out);
        fputc('\n', out);
        if (jstr(at, "reason")) {
            fprintf(out, "  %-*s %s: %s\n", LABEL_W, "verdict", jstr(at, "status"), jstr(at, "reason"));
        } else {
            print_count(out, at);
        }
    } else if (st && strcmp(st, "proved") == 0) {
        const json_t *c = json_object_get(o, "certificate");
        size_t i;
        for (i = 0; i < json_array_size(c); i++) {
            const json_t *e = json_array_get(c, i);
            const char *key;
            json_t *val;
            int first = 1;
            if (jstr(e, "text")) {
                line(out, i == 0 ? "certificate" : "", "%s", jstr(e, "text"));
                continue;
            }
            fprintf(out, "  %-*s %s > 0 since with ", LABEL_W, i == 0 ? "certificate" : "", jstr(e, "condition"));
            json_object_foreach(json_object_get(e, "substitution"), key, val) {
                fprintf(out, "%s%s = %s", first ? "" : ", ", key, json_string_value(val));
                first = 0;
            }
            fprintf(out, " (every s >= 0) the numerator's %lld coefficients are all >= 0",
                    jint(e, "transformed_terms"));
            if (jstr(e, "positive_factor")) fprintf(out, " after dividing by %s > 0", jstr(e, "positive_factor"));
            if (jint(e, "polya_power") > 0) fprintf(out, " times (1 + sum s)^%lld", jint(e, "polya_power"));
            fputc('\n', out);
        }
        line(out, "re-checked", "%s", "yes (independent evaluation at random points of the region)");
    } else {
        line(out, "tried", "%s", jstr(o, "tried"));
        if (jstr(o, "failed_at")) line(out, "failed at", "%s", jstr(o, "failed_at"));
    }
    snprintf(buf, sizeof buf, "%lld points checked exactly", jint(o, "points_checked"));
    line(out, "search", "%s", buf);
    print_assigned(out, o);
}

/* A root's radius (a double from the JSON) to 2 digits, rounded up. */
static char *radius_up(double r)
{
    arf_t a;
    char *s;
    arf_init(a);
    arf_set_d(a, r);
    s = rs_radius_arf_str(a, 2, ARF_RND_CEIL);
    arf_clear(a);
    return s;
}

static void r_radius(FILE *out, const json_t *o)
{
    const json_t *roots = json_object_get(o, "roots");
    size_t i;
    line(out, "method", "%s", jstr(o, "method"));
    if (json_is_true(json_object_get(o, "certified"))) {
        char buf[160];
        line(out, "rho", "%s", jstr(o, "rho"));
        line(out, "certified", "[%s,", jstr(o, "lower"));
        line(out, "", " %s]", jstr(o, "upper"));
        snprintf(buf, sizeof buf, "%lld digits asked, %lld bits used", jint(o, "digits"), jint(o, "precision_bits"));
        line(out, "precision", "%s", buf);
        for (i = 0; i < json_array_size(roots); i++) {
            /* whole strings: cutting a printed decimal short is not a rounding */
            const json_t *z = json_array_get(roots, i);
            const char *re = jstr(z, "re"), *im = jstr(z, "im"), *ab = jstr(z, "abs");
            char *rad = radius_up(json_real_value(json_object_get(z, "radius")));
            size_t len = strlen(re) + strlen(im) + strlen(ab) + strlen(rad) + 32;
            char *rb = malloc(len);
            snprintf(rb, len, "%s %s %si +- %s  |.| = %s", re, im[0] == '-' ? "-" : "+", im[0] == '-' ? im + 1 : im,
                     rad, ab);
            line(out, i == 0 ? "roots" : "", "%s", rb);
            free(rb);
            flint_free(rad);
        }
        if (json_object_get(o, "verdict_digits") != NULL) {
            snprintf(buf, sizeof buf, "raised to %lld digits to separate the interval from 1", jint(o, "verdict_digits"));
            line(out, "refined", "%s", buf);
        }
        line(out, "from radius", "%s", jstr(o, "verdict_from_radius"));
        line(out, "exact", "%s (consistent with the radius)", jstr(o, "exact_status"));
        line(out, "verdict", "%s (certified by the radius interval)", jstr(o, "status"));
        line(out, "monolithic", "%s (exact integration of the coupled system: the reference)", jstr(o, "monolithic_rho"));
    } else {
        char buf[64];
        snprintf(buf, sizeof buf, "%.17g (double precision, NOT certified)", json_real_value(json_object_get(o, "rho")));
        line(out, "rho", "%s", buf);
        line(out, "exact", "%s", jstr(o, "exact_status"));
    }
    print_assigned(out, o);
}

static void r_modes(FILE *out, const json_t *o)
{
    const char *groups[] = {"modes", "spurious"};
    size_t g, i;
    line(out, "h", "%s", jstr(o, "h"));
    for (g = 0; g < 2; g++) {
        const json_t *m = json_object_get(o, groups[g]);
        for (i = 0; i < json_array_size(m); i++) {
            const json_t *e = json_array_get(m, i);
            char buf[400];
            if (jstr(e, "sigma") == NULL) continue;
            snprintf(buf, sizeof buf, "sigma %s omega %s damping %s%s%s", jstr(e, "sigma"),
                     jstr(e, "omega"), jstr(e, "damping_ratio"), jstr(e, "frequency_error") ? " freq.error " : "",
                     jstr(e, "frequency_error") ? jstr(e, "frequency_error") : "");
            line(out, i == 0 ? (g == 0 ? "principal" : "spurious") : "", "%s", buf);
        }
    }
    print_assigned(out, o);
}

static void r_simulate(FILE *out, const json_t *o)
{
    char buf[200];
    snprintf(buf, sizeof buf, "%lld steps from a seeded random start (seed %lld), %lld bits", jint(o, "steps"),
             jint(o, "seed"), jint(o, "precision_bits"));
    line(out, "run", "%s", buf);
    line(out, "recurrence", "%s", jstr(o, "recurrence"));
    line(out, "growth", "%s per step (measured)", jstr(o, "growth") ? jstr(o, "growth") : "undefined");
    if (jstr(o, "radius")) line(out, "radius", "%s (certified)", jstr(o, "radius"));
    if (json_object_get(o, "check")) {
        const json_t *ck = json_object_get(o, "check");
        snprintf(buf, sizeof buf, "%s (exact): %s", jstr(json_object_get(o, "verdict"), "status"),
                 json_is_true(json_object_get(ck, "consistent")) ? "consistent with the run"
                                                                : jstr(ck, "disagreement"));
        line(out, "verdict", "%s", buf);
    }
    print_assigned(out, o);
}

static void r_sweep(FILE *out, const json_t *o)
{
    const char *tab = jstr(o, "table");
    const json_t *v = json_object_get(o, "verdicts"), *d = json_object_get(o, "decided_by");
    const char *key;
    json_t *val;
    char buf[512];
    size_t off = 0;
    line(out, "request", "%s", jstr(o, "text"));
    buf[0] = '\0';
    json_object_foreach((json_t *) v, key, val)
        off += (size_t) snprintf(buf + off, off < sizeof buf ? sizeof buf - off : 0, "%s%s %lld", off ? ", " : "",
                                 key, (long long) json_integer_value(val));
    line(out, "verdicts", "%s", buf);
    off = 0;
    buf[0] = '\0';
    json_object_foreach((json_t *) d, key, val)
        off += (size_t) snprintf(buf + off, off < sizeof buf ? sizeof buf - off : 0, "%s%s %lld", off ? ", " : "",
                                 key, (long long) json_integer_value(val));
    line(out, "decided by", "%s", buf);
    snprintf(buf, sizeof buf, "%lld points in %.3f s", (long long) json_integer_value(json_object_get(o, "points")),
             json_real_value(json_object_get(o, "seconds")));
    line(out, "computed", "%s", buf);
    line(out, "csv", "%s", jstr(o, "csv"));
    line(out, "note", "%s", jstr(o, "table_note"));
    if (tab != NULL) {
        /* the table, columns aligned */
        const char *p = tab;
        int rowsn = 0;
        while (*p && rowsn < 60) {
            const char *nl = strchr(p, '\n');
            size_t len = nl ? (size_t) (nl - p) : strlen(p);
            size_t i = 0;
            fputs("    ", out);
            while (i < len) {
                size_t j = i;
                while (j < len && p[j] != ',') j++;
                fprintf(out, "%-18.*s", (int) (j - i > 17 ? 17 : j - i), p + i);
                i = j + 1;
            }
            fputc('\n', out);
            rowsn++;
            p += len + (nl ? 1 : 0);
        }
        if (*p) fputs("    ... (all rows: --csv FILE)\n", out);
    }
    print_assigned(out, o);
}

/* Fallback: every member except "analysis" as key: value. */
static void r_generic(FILE *out, const json_t *o)
{
    const char *key;
    json_t *val;
    json_object_foreach((json_t *) o, key, val) {
        if (strcmp(key, "analysis") == 0) continue;
        if (json_is_string(val)) line(out, key, "%s", json_string_value(val));
        else {
            char *s = json_dumps(val, JSON_COMPACT | JSON_ENCODE_ANY);
            line(out, key, "%s", s);
            free(s);
        }
    }
}

typedef void (*render_fn)(FILE *, const json_t *);
typedef struct { const char *name; render_fn fn; } renderer_t;



static const renderer_t renderers[] = {
    {"charpoly", r_charpoly},
    {"expect", r_expect},
    {"bilinear", r_bilinear},
    {"routh", r_routh},
    {"hurwitz", r_hurwitz},
    {"jury", r_jury},
    {"stability", r_stability},
    {"region", r_region},
    {"limit", r_limit},
    {"claim", r_claim},
    {"radius", r_radius},
    {"modes", r_modes},
    {"simulate", r_simulate},
    {"sweep", r_sweep},
    {"map", r_sweep},
    {NULL, NULL}
};

void rs_report_text(FILE *out, const json_t *doc)
{
    const json_t *res = json_object_get(doc, "results");
    size_t i;
    const char *title = jstr(doc, "title");
    fprintf(out, "case %s%s%s\n", jstr(doc, "case"), title ? ": " : "", title ? title : "");
    for (i = 0; i < json_array_size(res); i++) {
        const json_t *o = json_array_get(res, i);
        const char *name = jstr(o, "analysis");
        render_fn fn = r_generic;
        size_t k;
        for (k = 0; renderers[k].name; k++)
            if (name && strcmp(renderers[k].name, name) == 0) fn = renderers[k].fn;
        fprintf(out, "\n%s\n", name ? name : "?");
        fn(out, o);
    }
}
