/* layout_exact.c -- the layouts of the exact analyses (charpoly, expect,
 * bilinear, routh, hurwitz, jury, stability, region, limit, claim) and the
 * blocks they share; each written once for the three backends. */
#include <stdlib.h>
#include <string.h>
#include "render_impl.h"

#define js rs_render_jstr
#define ji rs_render_jint

/* d of a result over Q(sqrt d), read from its "over" ("Q(sqrt 3)"); the
 * field is the model's, so no layout may name Q(sqrt 2) itself */
static const char *qd_d(const json_t *o, char *buf, size_t n)
{
    const char *over = js(o, "over");
    long d;
    if (over == NULL || sscanf(over, "Q(sqrt %ld)", &d) != 1) return "d";
    snprintf(buf, n, "%ld", d);
    return buf;
}

/* ---- blocks shared by several layouts -------------------------------------------- */

/* The values substituted ("at") and the parameters p does not depend on. */
void rs_render_assigned(rs_render_t *r, const json_t *o)
{
    const json_t *sub = json_object_get(o, "substituted");
    const json_t *nip = json_object_get(o, "not_in_p"), *vif = json_object_get(o, "valid_if");
    const char *key;
    json_t *val;
    size_t i;
    int first = 1;
    for (i = 0; i < json_array_size(nip); i++) {
        if (i == 0) rs_render_label(r, "not in p");
        rs_render_textf(r, "%s%s%s", i == 0 ? "" : ", ", json_string_value(json_array_get(nip, i)),
                        i + 1 == json_array_size(nip)
                            ? (vif != NULL ? " (only in p's factor free of lambda: no value needed)\n"
                                           : " (p does not depend on them: no value needed)\n") : "");
    }
    /* that factor's zeros: p vanishes identically there, the result does not hold */
    for (i = 0; i < json_array_size(vif); i++) {
        if (i == 0) rs_render_label(r, "valid if");
        rs_render_textf(r, "%s%s%s", i == 0 ? "" : " and ", json_string_value(json_array_get(vif, i)),
                        i + 1 == json_array_size(vif) ? " (elsewhere p vanishes identically: singular)\n" : "");
    }
    if (!json_is_object(sub) || json_object_size(sub) == 0) return;
    rs_render_label(r, "at");
    json_object_foreach((json_t *) sub, key, val) {
        rs_render_textf(r, "%s%s = %s", first ? "" : ", ", key, json_string_value(val));
        first = 0;
    }
    rs_render_textf(r, "\n");
}

/* The derivation's sentence of the values a result was taken at (its
 * "substituted" values, and "at"): nothing when there are none. */
static void taken_at(rs_render_t *r, const json_t *o)
{
    const json_t *sub = json_object_get(o, "substituted");
    const char *key;
    json_t *val;
    int first = 1;
    if (!json_is_object(sub) || json_object_size(sub) == 0) return;
    rs_render_say(r, "Taken at ", "Taken at ");
    json_object_foreach((json_t *) sub, key, val) {
        rs_render_say(r, first ? "$" : ", $", first ? "$" : ", $");
        rs_render_poly(r, key);
        rs_render_say(r, " = ", " = ");
        rs_render_poly(r, json_string_value(val));
        rs_render_say(r, "$", "$");
        first = 0;
    }
    rs_render_say(r, ".\n\n", ".\n\n");
}

/* A labelled line of the array's members joined by sep (strings as they are,
 * other values as compact JSON). */
void rs_render_string_list(rs_render_t *r, const char *label, const json_t *arr, const char *sep)
{
    size_t i;
    if (!json_is_array(arr) || json_array_size(arr) == 0) return;
    rs_render_label(r, label);
    for (i = 0; i < json_array_size(arr); i++) {
        const json_t *v = json_array_get(arr, i);
        if (i > 0) rs_render_textf(r, "%s", sep);
        if (json_is_string(v)) rs_render_textf(r, "%s", json_string_value(v));
        else {
            char *s = json_dumps(v, JSON_COMPACT | JSON_ENCODE_ANY);
            rs_render_textf(r, "%s", s);
            free(s);
        }
    }
    rs_render_textf(r, "\n");
}

/* the conditions checked against exact point verdicts */
void rs_render_sample_check(rs_render_t *r, const json_t *o)
{
    const json_t *c = json_object_get(o, "sample_check");
    if (c == NULL) return;
    if (json_is_true(json_object_get(c, "agree"))) {
        rs_render_linef(r, "checked", "conditions agree with the exact verdict at %lld admissible rational points",
                        ji(c, "points"));
    } else {
        char *pt = json_dumps(json_object_get(c, "point"), JSON_COMPACT | JSON_SORT_KEYS);
        rs_render_linef(r, "checked", "DISAGREEMENT at %s: the conditions say %s, the exact verdict is %s", pt,
                        js(c, "conditions_say"), js(c, "exact_verdict"));
        free(pt);
    }
}

static void condition_list(rs_render_t *r, const json_t *c, const char *md, const char *tex, const char *empty);

/* "never" (no branch can hold) or "branches" (an OR of condition lists);
 * 1 if the result has either (then printed), else 0. */
static int branches(rs_render_t *r, const json_t *o)
{
    const json_t *br = json_object_get(o, "branches");
    size_t i, j;
    if (js(o, "never") != NULL) {
        rs_render_line(r, "never", "%s", js(o, "never"));
        rs_render_esc(r, js(o, "never"));
        rs_render_say(r, ".\n\n", ".\n\n");
        /* a set that can never all hold (never_from "conditions"): the
         * conditions shown after the reason, as found (the text report
         * lists them with condition_lines) */
        if (js(o, "never_from") == NULL) return 1;
        if (!json_is_array(br)) {
            if (json_array_size(json_object_get(o, "conditions")) > 0)
                condition_list(r, json_object_get(o, "conditions"), "The conditions as found:\n\n",
                               "The conditions as found:\n", NULL);
            return 1;
        }
    }
    if (!json_is_array(br)) return 0;
    rs_render_say(r, "All |lambda| < 1 if and only if every condition of one branch holds (the sign of the leading "
                     "coefficient of q is not fixed by the assumptions):\n\n",
                  "All $|\\lambda| < 1$ if and only if every condition of one branch holds (the sign of the "
                  "leading coefficient of $q$ is not fixed by the assumptions):\n");
    rs_render_list_begin(r);
    for (i = 0; i < json_array_size(br); i++) {
        const json_t *b = json_array_get(br, i);
        rs_render_item_begin(r);
        rs_render_say(r, i == 0 ? "either: " : "or: ", i == 0 ? "either: " : "or: ");
        for (j = 0; j < json_array_size(b); j++) {
            const char *c = json_string_value(json_array_get(b, j));
            rs_render_line(r, j > 0 ? "and" : i > 0 ? "or" : js(o, "never") != NULL ? "conditions" : "stable iff",
                           "%s", c);
            if (j) rs_render_say(r, ", ", ", ");
            rs_render_math(r, c);
        }
        rs_render_item_end(r);
    }
    rs_render_list_end(r);
    return 1;
}

/* The derivation's list of conditions, after its sentence; empty (if given)
 * is the item for an empty list. */
/* A condition as math, except a trailing " (not expanded)" or " (not
 * factored)" (hurwitz.h), which is words and is printed as text. */
static void condition_math(rs_render_t *r, const char *c)
{
    const char *tail = " (not expanded)";
    size_t n, t;
    /* prose only: the text report says nothing here (its condition lines
     * are condition_lines'), so no copy of a 27 MB condition (issue 17) */
    if (r->be->kind == RS_RENDER_TEXT) return;
    n = strlen(c);
    if (n > 15 && strcmp(c + n - 15, " (not factored)") == 0) tail = " (not factored)";
    t = strlen(tail);
    if (n > t && strcmp(c + n - t, tail) == 0) {
        char *head = malloc(n - t + 1);
        if (head != NULL) {
            memcpy(head, c, n - t);
            head[n - t] = '\0';
            rs_render_math(r, head);
            free(head);
            rs_render_say(r, tail, tail);
            return;
        }
    }
    rs_render_math(r, c);
}

static void condition_list(rs_render_t *r, const json_t *c, const char *md, const char *tex, const char *empty)
{
    size_t i;
    rs_render_say(r, md, tex);
    rs_render_list_begin(r);
    for (i = 0; i < json_array_size(c); i++) {
        const char *ci = json_string_value(json_array_get(c, i));
        rs_render_item_begin(r);
        /* a constant condition such as 0 > 0 is said in words: it fails
         * for every value of the parameters */
        if (ci != NULL && strncmp(ci, "0 > 0", 5) == 0 && ci[5] == '\0')
            rs_render_say(r, "a condition that is identically false (its polynomial is the constant 0): no "
                             "parameter value has every $|\\lambda| < 1$",
                          "a condition that is identically false (its polynomial is the constant 0): no "
                          "parameter value has every $|\\lambda| < 1$");
        else condition_math(r, ci);
        rs_render_item_end(r);
    }
    if (json_array_size(c) == 0 && empty != NULL) {
        rs_render_item_begin(r);
        rs_render_say(r, empty, empty);
        rs_render_item_end(r);
    }
    rs_render_list_end(r);
}

/* The report's condition lines: first, then next (none when the result says
 * "never" and never_counts). */
static void condition_lines(rs_render_t *r, const json_t *o, const char *first, const char *next, int never_counts)
{
    const json_t *c = json_object_get(o, "conditions");
    size_t i;
    for (i = 0; i < json_array_size(c) && !(never_counts && js(o, "never") != NULL); i++)
        rs_render_line(r, i == 0 ? first : next, "%s", json_string_value(json_array_get(c, i)));
}

/* the conditions on the bilinear image q (hurwitz's Lienard-Chipart ones,
 * routh's first column over Q(sqrt d)): the branches or "never" when there
 * are, else the list; KIND names them when none is left */
static void bilinear_conditions(rs_render_t *r, const json_t *o, const char *kind)
{
    const json_t *conds = json_object_get(o, "conditions");
    if (!branches(r, o)) {
        if (json_array_size(conds) == 0)
            rs_render_linef(r, "conditions", "none left: every %s condition holds under the assumptions", kind);
        condition_list(r, conds, "All |lambda| < 1 if and only if:\n\n",
                       "All roots of $q$ have negative real part (all $|\\lambda| < 1$) if and only if:\n",
                       "(every condition holds under the assumptions)");
    }
    condition_lines(r, o, "conditions", "", js(o, "never_from") == NULL);
}

/* ---- the layouts ------------------------------------------------------------------ */

void rs_render_charpoly(rs_render_t *r, const json_t *o)
{
    long long removed = ji(o, "removed_lambda_power");
    rs_render_line(r, "p(lambda)", "%s", js(o, "poly"));
    rs_render_linef(r, "degree", "%lld", ji(o, "degree"));
    if (removed > 0) rs_render_linef(r, "removed", "lambda^%lld (roots at 0) divided out", removed);
    rs_render_line(r, "content", "%s (det = content * lambda^k * p)", js(o, "content"));
    rs_render_line(r, "param factor", "%s (common factor of all coefficients)", js(o, "param_content"));
    rs_render_line(r, "verdict", "%s", js(o, "status"));
    rs_render_line(r, "singular", "%s", js(o, "singular"));
    rs_render_assigned(r, o);
    rs_render_string_list(r, "assuming", json_object_get(o, "nonzero_assumptions"), ", ");

    rs_render_heading(r, "Characteristic polynomial", "Characteristic polynomial");
    rs_render_say(r, "p(lambda) = det of the lambda-matrix (fraction-free)",
                  "The determinant of the $\\lambda$-matrix, computed fraction-free");
    if (removed > 0)
        rs_render_sayf(r, ", lambda^%lld (roots at 0) divided out",
                       ", with the factor $\\lambda^{%lld}$ (roots at 0) divided out", removed);
    rs_render_say(r, ":\n\n$$p(\\lambda) = ", ":\n\n$p(\\lambda) = ");
    rs_render_poly(r, js(o, "poly"));
    rs_render_sayf(r, "$$\n\ndegree %lld, content %s.\n\n", "$\n\n(degree %lld, content %s).\n\n", ji(o, "degree"),
                   js(o, "content"));
}

/* The derivation's paragraph of a claim or an expect. */
static void claim_prose(rs_render_t *r, const json_t *o)
{
    const json_t *ce = json_object_get(o, "counterexample");
    const char *diff = js(o, "difference");
    rs_render_code(r, js(o, "text"));
    rs_render_sayf(r, ": **%s**.\n\n", ": \\textbf{%s}.\n\n", js(o, "status"));
    if (json_is_object(ce)) {
        const char *k;
        json_t *v;
        const json_t *at = json_object_get(o, "at_counterexample");
        int first = 1;
        /* no free parameter: the scheme itself (was an empty "$$") */
        if (json_object_size(ce) == 0) rs_render_say(r, "Counterexample: the scheme as given", "Counterexample: the "
                                                     "scheme as given");
        else rs_render_say(r, "Counterexample: $", "Counterexample: $");
        json_object_foreach((json_t *) ce, k, v) {
            if (!first) rs_render_say(r, ",\\ ", ",\\ ");
            rs_render_poly(r, k);
            rs_render_say(r, " = ", " = ");
            rs_render_poly(r, json_string_value(v));
            first = 0;
        }
        rs_render_say(r, json_object_size(ce) == 0 ? ". " : "$. ", json_object_size(ce) == 0 ? ". " : "$. ");
        /* a singular point has a reason, no counts (they were printed as 0, 0, 0) */
        if (json_object_get(at, "inside") == NULL && js(at, "reason") != NULL) {
            rs_render_sayf(r, "Verdict: **%s**: ", "Verdict: \\textbf{%s}: ", js(at, "status"));
            rs_render_esc(r, js(at, "reason"));
            rs_render_say(r, ".\n\n", ".\n\n");
        } else {
            rs_render_count(r, at, RS_RENDER_PROSE);
        }
        /* how a counterexample the search missed was found (for-all region,
         * plane decomposition): the JSON's found_by */
        if (js(o, "found_by") != NULL) {
            rs_render_say(r, "Found by ", "Found by ");
            rs_render_esc(r, js(o, "found_by"));
            rs_render_say(r, ".\n\n", ".\n\n");
        }
    }
    if (diff != NULL && strcmp(diff, "0") != 0) {
        rs_render_say(r, "Printed minus derived: ", "Printed minus derived: ");
        rs_render_math(r, diff);
        rs_render_say(r, "\n\n", ".\n\n");
    }
}

void rs_render_expect(rs_render_t *r, const json_t *o)
{
    const char *st = js(o, "status");
    rs_render_line(r, "checks", "%s", js(o, "text"));
    rs_render_line(r, "status", "%s", st);
    if (st && strcmp(st, "different") == 0) {
        rs_render_line(r, "derived", "%s", js(o, "derived"));
        rs_render_line(r, "printed", "%s", js(o, "expected_normalised"));
        rs_render_line(r, "difference", "%s", js(o, "difference"));
        rs_render_line(r, "ratio", "printed = (%s) * derived", js(o, "ratio"));
    }
    rs_render_assigned(r, o);
    rs_render_heading(r, "Printed polynomial", "Printed polynomial");
    claim_prose(r, o);
}

void rs_render_bilinear(rs_render_t *r, const json_t *o)
{
    rs_render_line(r, "q(z)", "%s", js(o, "poly"));
    rs_render_line(r, "", "%s", "q(z) = (1-z)^n p((1+z)/(1-z)): |lambda| < 1 <=> Re z < 0");
    rs_render_linef(r, "degree", "%lld (degree drop %lld = roots at lambda = -1; z = 0 of multiplicity %lld = "
                    "roots at lambda = 1)", ji(o, "degree"), ji(o, "degree_drop"), ji(o, "zero_mult"));
    rs_render_line(r, "p(1)", "%s (lambda = 1 is a root where this vanishes)", js(o, "p_at_1"));
    rs_render_line(r, "p(-1)", "%s (lambda = -1 is a root where this vanishes)", js(o, "p_at_minus_1"));
    rs_render_assigned(r, o);

    rs_render_heading(r, "Bilinear transform", "Bilinear transform");
    rs_render_say(r, "lambda = (1+z)/(1-z) maps |lambda| < 1 onto Re z < 0; q(z) = (1-z)^n p((1+z)/(1-z)):\n\n"
                     "$$q(z) = ",
                  "With $\\lambda = \\frac{1+z}{1-z}$, $|\\lambda| < 1 \\iff \\operatorname{Re} z < 0$; "
                  "$q(z) = (1-z)^n\\, p\\!\\left(\\frac{1+z}{1-z}\\right)$:\n\n$q(z) = ");
    rs_render_poly(r, js(o, "poly"));
    rs_render_sayf(r, "$$\n\ndegree drop %lld (roots at $\\lambda = -1$), $z = 0$ of multiplicity %lld (roots at "
                      "$\\lambda = 1$); $p(1) = ",
                   "$\n\nDegree drop %lld (roots at $\\lambda=-1$), $z=0$ of multiplicity %lld (roots at "
                   "$\\lambda = 1$); $p(1) = ", ji(o, "degree_drop"), ji(o, "zero_mult"));
    rs_render_poly(r, js(o, "p_at_1"));
    rs_render_say(r, "$, $p(-1) = ", "$, $p(-1) = ");
    rs_render_poly(r, js(o, "p_at_minus_1"));
    rs_render_say(r, "$.\n\n", "$.\n\n");
}

/* The first-column signs as eps -> 0+ (zero first entries replaced by eps). */
static void epsilon_signs(rs_render_t *r, const json_t *es)
{
    char buf[256];
    size_t i, n = 0;
    if (es == NULL) return;
    buf[0] = '\0';
    for (i = 0; i < json_array_size(es) && n + 4 < sizeof buf; i++) {
        json_int_t sg = json_integer_value(json_array_get(es, i));
        n += (size_t) snprintf(buf + n, sizeof buf - n, "%s%s", i ? " " : "", sg > 0 ? "+" : sg < 0 ? "-" : "0");
    }
    rs_render_line(r, "eps -> 0+", "first column signs %s (zero first entries replaced by eps)", buf);
}

static void routh_conditions(rs_render_t *r, const json_t *o);

/* routh over Q deciding "never" from its symbolic array (an_routh.c: a
 * first-column entry or a row 0 for every value, or q's degree dropped),
 * and hurwitz's route on the same q only when it disagrees (exit 3) */
static void routh_never(rs_render_t *r, const json_t *o)
{
    const json_t *cr = json_object_get(o, "cross_route");
    branches(r, o);
    if (js(o, "auxiliary") != NULL) {
        rs_render_line(r, "auxiliary", "A(z) = %s", js(o, "auxiliary"));
        if (json_is_false(json_object_get(o, "auxiliary_divides_q")))
            rs_render_line(r, "disagree", "%s", "A(z) does not divide q(z) (a bug: the zero row says it does)");
    }
    rs_render_line(r, "verdict", "%s", js(o, "verdict"));
    if (json_is_false(json_object_get(cr, "agree")))
        rs_render_linef(r, "disagree", "%s says %s (a bug: both are exact)", js(cr, "with"),
                        js(cr, "hurwitz_verdict"));
    rs_render_sample_check(r, o);
}

void rs_render_routh(rs_render_t *r, const json_t *o)
{
    const json_t *ev = json_object_get(o, "events");
    int sym = json_is_true(json_object_get(o, "symbolic"));
    size_t i;
    if (json_object_get(o, "chain") != NULL) {
        /* over Q(i): the Bilharz chain (an_complex.c) */
        rs_render_heading(r, "Bilharz chain of q(z) over Q(i)", "Bilharz chain of $q(z)$ over $Q(i)$");
        rs_render_line(r, "p(lambda)", "%s", js(o, "p"));
        rs_render_line(r, "q(z)", "%s", js(o, "q"));
        rs_render_line(r, "q(i w)", "A + i B, A = %s", js(o, "A"));
        rs_render_line(r, "", "B = %s", js(o, "B"));
        rs_render_line(r, "gcd(A, B)", "%s", js(o, "G"));
        rs_render_string_list(r, "chain", json_object_get(o, "chain"), "\n               ");
        rs_render_say(r, "With $z = i w$, $q(i w) = A(w) + i B(w)$, $A = ", "With $z = i w$, $q(i w) = A(w) + i B(w)$, $A = ");
        rs_render_poly(r, js(o, "A"));
        rs_render_say(r, "$, $B = ", "$, $B = ");
        rs_render_poly(r, js(o, "B"));
        rs_render_say(r, "$, $\\gcd(A, B) = ", "$, $\\gcd(A, B) = ");
        rs_render_poly(r, js(o, "G"));
        rs_render_say(r, "$ (its real roots: the roots on the axis). The signed remainder chain of A/G and B/G "
                      "counts the roots in Re z < 0 by its Cauchy index (Bilharz).\n\n",
                      "$ (its real roots: the roots on the axis). The signed remainder chain of $A/G$ and $B/G$ "
                      "counts the roots in $\\mathrm{Re}\\, z < 0$ by its Cauchy index (Bilharz).\n\n");
        rs_render_count(r, o, RS_RENDER_ALL);
        rs_render_assigned(r, o);
        return;
    }
    if (json_object_get(o, "bilharz") != NULL) {
        /* at complex set values over Q(sqrt d)(i): hurwitz's Bilharz conditions (an_qd_complex.c) */
        rs_render_hurwitz(r, o);
        return;
    }
    rs_render_heading(r, "Routh array of q(z)", "Routh array of $q(z)$");
    if (sym) rs_render_line(r, "array", "%s", "fraction-free, symbolic");
    rs_render_rows(r, json_object_get(o, "rows"), json_object_get(o, "powers"));
    if (!sym) epsilon_signs(r, json_object_get(o, "epsilon_signs"));
    for (i = 0; i < json_array_size(ev); i++) {
        const json_t *e = json_array_get(ev, i);
        rs_render_line(r, js(e, "kind"), "%s", js(e, "text"));
        rs_render_sayf(r, "*Singular step (%s):* ", "\\emph{Singular step:} ", js(e, "kind"));
        rs_render_esc(r, js(e, "text"));
        rs_render_say(r, "\n\n", "\n\n");
    }
    if (js(o, "note") != NULL) {
        if (sym) rs_render_line(r, "note", "%s", js(o, "note"));
        rs_render_esc(r, js(o, "note"));
        rs_render_say(r, "\n\n", "\n\n");
    }
    /* over Q(sqrt d) (an_qd_conds.c) the array ends in conditions and a verdict */
    if (sym && json_object_get(o, "conditions") != NULL) routh_conditions(r, o);
    else if (sym && js(o, "never") != NULL) routh_never(r, o);
    /* the report counts the numeric array; the derivation whatever has a status */
    rs_render_count(r, o, (sym ? 0 : RS_RENDER_TEXT) | (js(o, "status") ? RS_RENDER_PROSE : 0));
    rs_render_assigned(r, o);
}

/* the factors of the Lienard-Chipart conditions dropped, and why */
static void dropped_factors(rs_render_t *r, const json_t *dropped)
{
    size_t i;
    for (i = 0; i < json_array_size(dropped); i++) {
        const json_t *d = json_array_get(dropped, i);
        rs_render_linef(r, i == 0 ? "dropped" : "", "%s (in %s): %s", js(d, "factor"), js(d, "from"),
                        js(d, "reason"));
        rs_render_say(r, "Dropped factor ", "Factor ");
        rs_render_math(r, js(d, "factor"));
        rs_render_sayf(r, " of %s: ", " of $%s$ dropped: ", js(d, "from"));
        rs_render_esc(r, js(d, "reason"));
        rs_render_say(r, ".\n", ".\n\n");
    }
    rs_render_say(r, "\n", NULL);
}

/* routh's symbolic conditions over Q(sqrt d): the signs of the first column
 * as conditions, checked against hurwitz's and the exact point verdict (the
 * JSON had them; the text report stopped at the note) */
static void routh_conditions(rs_render_t *r, const json_t *o)
{
    const json_t *cc = json_object_get(o, "cross_check");
    bilinear_conditions(r, o, "first-column");
    dropped_factors(r, json_object_get(o, "dropped"));
    rs_render_string_list(r, "always true", json_object_get(o, "always_true"), ", ");
    rs_render_line(r, "verdict", "%s", js(o, "verdict"));
    if (cc != NULL)
        rs_render_linef(r, "cross-check", "%s: %s at %lld sample points", js(cc, "method"),
                        json_is_true(json_object_get(cc, "agree")) ? "agree" : "DISAGREE", ji(cc, "points"));
    rs_render_sample_check(r, o);
}

/* p = A + i B over Q(i)[params] (an_complex_conds.c) */
static void complex_p(rs_render_t *r, const json_t *o)
{
    const json_t *at = json_object_get(o, "at");
    const char *key;
    json_t *val;
    if (js(o, "p0") != NULL) {
        /* over Q(sqrt d) (an_qd_conds.c): p = p0 + sqrt(d) p1 */
        rs_render_linef(r, "p(lambda)", "p0 + sqrt(d)*p1 (over %s, %s)", js(o, "over"),
                        js(o, "rk") != NULL ? js(o, "rk") : js(o, "method"));
        rs_render_line(r, "p0", "%s", js(o, "p0"));
        rs_render_line(r, "p1", "%s", js(o, "p1"));
        rs_render_say(r, "Over ", "Over ");
        rs_render_esc(r, js(o, "over"));
        rs_render_say(r, ", $p = p_0 + \\sqrt{d}\\,p_1$ with $p_0 = ", ", $p = p_0 + \\sqrt{d}\\,p_1$ with $p_0 = ");
        rs_render_poly(r, js(o, "p0"));
        rs_render_say(r, "$, $p_1 = ", "$, $p_1 = ");
        rs_render_poly(r, js(o, "p1"));
        rs_render_say(r, "$; every product is reduced by $\\sqrt{d}^2 = d$, each condition is $c_0 + \\sqrt{d}\\,c_1 > 0$ "
                      "with $c_0, c_1$ polynomials in the parameters, decided exactly by comparing $c_0^2$ with "
                      "$d\\,c_1^2$.\n\n",
                      "$; every product is reduced by $\\sqrt{d}^2 = d$, each condition is $c_0 + \\sqrt{d}\\,c_1 > 0$ "
                      "with $c_0, c_1$ polynomials in the parameters, decided exactly by comparing $c_0^2$ with "
                      "$d\\,c_1^2$.\n\n");
        return;
    }
    rs_render_linef(r, "p(lambda)", "%s + i*(%s) (over %s)", js(o, "p_re"), js(o, "p_im"), js(o, "over"));
    json_object_foreach((json_t *) at, key, val) rs_render_linef(r, "complex", "%s = %s", key, json_string_value(val));
}

/* region and claim over Q(sqrt d)(i) (an_qd_complex.c): the field and the complex set values */
static void qdc_over_at(rs_render_t *r, const json_t *o, int over)
{
    const char *key;
    json_t *val;
    if (js(o, "over") == NULL || strstr(js(o, "over"), "sqrt") == NULL || strstr(js(o, "over"), "(i)") == NULL
        || !json_is_object(json_object_get(o, "at")))
        return;
    if (over) rs_render_linef(r, "over", "%s", js(o, "over"));   /* a claim's "decided by" names it */
    json_object_foreach(json_object_get(o, "at"), key, val)
        rs_render_linef(r, "complex", "%s = %s", key, json_string_value(val));
    if (!over) return;   /* the claim's sentence names the field */
    rs_render_say(r, "The cells are decided over ", "The cells are decided over ");
    rs_render_esc(r, js(o, "over"));
    json_object_foreach(json_object_get(o, "at"), key, val) {
        rs_render_say(r, ", at $", ", at $");
        rs_render_poly(r, key);
        rs_render_say(r, " = ", " = ");
        rs_render_poly(r, json_string_value(val));
        rs_render_say(r, "$", "$");
    }
    rs_render_say(r, ".\n\n", ".\n\n");
}

/* the not-expanded minors over the small ring (issue 17): their sizes and
 * the definitions here, the polynomials in --json (small_ring) */
static void small_ring(rs_render_t *r, const json_t *sr)
{
    const json_t *d, *m;
    size_t i;
    char buf[160];
    if (sr == NULL) return;
    json_array_foreach(json_object_get(sr, "definitions"), i, d) {
        snprintf(buf, sizeof buf, "%s =", js(d, "name"));
        rs_render_line(r, i == 0 ? "small ring" : "", "%s", buf);
        rs_render_line(r, "", "%s", js(d, "poly"));
    }
    rs_render_line(r, "", "%s", js(sr, "note"));
    json_array_foreach(json_object_get(sr, "minors"), i, m) {
        long long k = (long long) json_integer_value(json_object_get(m, "minor"));
        long long terms = (long long) json_integer_value(json_object_get(m, "terms"));
        if (strcmp(js(sr, "denominator"), "1") == 0)
            snprintf(buf, sizeof buf, "D_%lld = P_%lld, exact with %lld terms (--json small_ring)", k, k, terms);
        else
            snprintf(buf, sizeof buf, "D_%lld = P_%lld / %s^%lld, P_%lld exact with %lld terms (--json small_ring)",
                     k, k, js(sr, "denominator"), k, k, terms);
        rs_render_line(r, "", "%s", buf);
    }
    rs_render_say(r, "Small ring: the not-expanded minors were formed exactly as polynomials in the "
                  "substitution route's variables; the JSON output holds them",
                  "Small ring: the not-expanded minors were formed exactly as polynomials in the "
                  "substitution route's variables; the JSON output holds them");
    /* the variables' definitions, so the prose report alone says what they are */
    json_array_foreach(json_object_get(sr, "definitions"), i, d) {
        rs_render_say(r, i == 0 ? ", with $" : ", $", i == 0 ? ", with $" : ", $");
        rs_render_poly(r, js(d, "name"));
        rs_render_say(r, " = ", " = ");
        rs_render_poly(r, js(d, "poly"));
        rs_render_say(r, "$", "$");
    }
    rs_render_say(r, ".\n\n", ".\n\n");
}

/* hurwitz and jury's bilinear route: why some minors are "not expanded"
 * (and which budget limit, if one, left minors or factorisations out) */
static void not_expanded(rs_render_t *r, const json_t *o)
{
    if (js(o, "limit_note") != NULL) {
        rs_render_line(r, "limit", "%s", js(o, "limit_note"));
        rs_render_say(r, "Budget: ", "Budget: ");
        rs_render_esc(r, js(o, "limit_note"));
        rs_render_say(r, ".\n\n", ".\n\n");
    }
    if (js(o, "not_expanded_note") == NULL) return;
    if (js(o, "not_expanded_reason") != NULL)
        rs_render_line(r, "stopped at", "%s", js(o, "not_expanded_reason"));
    rs_render_line(r, "not expanded", "%s", js(o, "not_expanded_note"));
    rs_render_say(r, "Not expanded: ", "Not expanded: ");
    rs_render_esc(r, js(o, "not_expanded_note"));
    rs_render_say(r, ".\n\n", ".\n\n");
    small_ring(r, json_object_get(o, "small_ring"));
}

/* which coefficient or minor each listed condition comes from (the JSON's
 * "details", one per condition not trivially true, in the same order), and
 * those false for every value: "conditions -1 > 0" alone did not say that
 * a_0 = -2 < 0 is the reason */
static void hurwitz_origins(rs_render_t *r, const json_t *o)
{
    const json_t *conds = json_object_get(o, "conditions"), *det = json_object_get(o, "details"), *d;
    char buf[1024];
    size_t i, len = 0, n = 0;
    buf[0] = '\0';
    json_array_foreach(det, i, d) {
        if (json_is_true(json_object_get(d, "trivially_true"))) continue;
        n++;
        if (len + 80 < sizeof buf)
            len += (size_t) snprintf(buf + len, sizeof buf - len, "%s%s%s", len ? ", " : "", js(d, "origin"),
                                     json_is_true(json_object_get(d, "trivially_false")) ? " (false for every value)"
                                                                                         : "");
    }
    if (n > 0 && n == json_array_size(conds)) rs_render_line(r, "from", "%s", buf);
    if (json_is_true(json_object_get(o, "negated")))
        rs_render_line(r, "negated", "%s", "the conditions are those of -q(z) (the same roots)");
}

void rs_render_hurwitz(rs_render_t *r, const json_t *o)
{
    const json_t *minors = json_object_get(o, "minors");
    size_t i;
    if (js(o, "p0") != NULL) {
        /* over Q(sqrt d): the Hurwitz minors of q (an_qd_conds.c) */
        char db[24];
        const char *d = qd_d(o, db, sizeof db);
        rs_render_heading_begin(r);
        rs_render_sayf(r, "Hurwitz minors of q(z) over Q(sqrt %s)", "Hurwitz minors of $q(z)$ over $\\mathbb{Q}(\\sqrt{%s})$", d);
        rs_render_heading_end(r);
        complex_p(r, o);
        rs_render_line(r, "method", "%s", js(o, "method"));
    } else if (js(o, "over") != NULL) {
        /* over Q(i): the Bilharz conditions (an_complex_conds.c) */
        /* over Q(i), or over Q(sqrt d)(i) (an_qd_complex.c) */
        rs_render_heading_begin(r);
        rs_render_sayf(r, "Bilharz conditions of q(z) over %s", "Bilharz conditions of $q(z)$ over $%s$", js(o, "over"));
        rs_render_heading_end(r);
        complex_p(r, o);
        rs_render_line(r, "q(i w)", "conj(c) i^-n q(i w) = P + i Q, P = %s", js(o, "P"));
        rs_render_line(r, "", "Q = %s", js(o, "Q"));
        rs_render_say(r, "With $c$ the leading coefficient of $q$, $\\bar c\\, i^{-n} q(i w) = P(w) + i Q(w)$, $P = ",
                      "With $c$ the leading coefficient of $q$, $\\bar c\\, i^{-n} q(i w) = P(w) + i Q(w)$, $P = ");
        rs_render_poly(r, js(o, "P"));
        rs_render_say(r, "$, $Q = ", "$, $Q = ");
        rs_render_poly(r, js(o, "Q"));
        rs_render_say(r, "$; the fraction-free signed remainder chain of $P$ and $Q$ (Bilharz) gives:\n\n",
                      "$; the fraction-free signed remainder chain of $P$ and $Q$ (Bilharz) gives:\n\n");
    } else {
        rs_render_heading(r, "Hurwitz minors and Lienard-Chipart conditions",
                          "Hurwitz minors and Li\\'enard--Chipart conditions");
    }
    for (i = 0; i < json_array_size(minors); i++) {
        const char *m = json_string_value(json_array_get(minors, i));
        char lab[32];
        snprintf(lab, sizeof lab, "D_%zu", i + 1);
        rs_render_line(r, lab, "%s", m);
        if (strcmp(m, "not expanded") == 0) {
            /* words, not a polynomial (hurwitz.h) */
            rs_render_sayf(r, "- $D_{%zu}$: not expanded\n", "$D_{%zu}$: not expanded\n\n", i + 1);
            continue;
        }
        rs_render_sayf(r, "- $D_{%zu} = ", "$D_{%zu} = ", i + 1);
        rs_render_poly(r, m);
        rs_render_say(r, "$\n", "$\n\n");
    }
    rs_render_say(r, "\n", NULL);
    bilinear_conditions(r, o, "Lienard-Chipart");
    if (js(o, "never") == NULL) hurwitz_origins(r, o);
    rs_render_string_list(r, "and", json_object_get(o, "nonzero"), ", ");
    dropped_factors(r, json_object_get(o, "dropped"));
    rs_render_string_list(r, "always true", json_object_get(o, "always_true"), ", ");
    not_expanded(r, o);
    rs_render_line(r, "p(1)", "%s (lambda = 1 is a root where this vanishes)", js(o, "p_at_1"));
    rs_render_line(r, "p(-1)", "%s (lambda = -1 is a root where this vanishes)", js(o, "p_at_minus_1"));
    rs_render_line(r, "verdict", "%s", js(o, "verdict"));
    if (js(o, "over") != NULL && json_object_get(o, "inside") != NULL) rs_render_count(r, o, RS_RENDER_TEXT);
    rs_render_sample_check(r, o);
    rs_render_assigned(r, o);
}

/* jury and stability: the derivation's Schur-Cohn conditions when symbolic */
static int schur_cohn_prose(rs_render_t *r, const json_t *o, const char *md, const char *tex)
{
    rs_render_heading(r, md, tex);
    if (!json_is_true(json_object_get(o, "symbolic"))) return 0;
    if (js(o, "never") != NULL) return 1;   /* said by branches() with its reason */
    condition_list(r, json_object_get(o, "conditions"), "All |lambda| < 1 if and only if:\n\n",
                   "All $|\\lambda| < 1$ if and only if:\n", NULL);
    return 1;
}

void rs_render_jury(rs_render_t *r, const json_t *o)
{
    const json_t *cc = json_object_get(o, "cross_check");
    int sym = schur_cohn_prose(r, o, "Schur-Cohn test on p(lambda)", "Schur--Cohn test on $p(\\lambda)$");
    rs_render_line(r, "method", "%s", js(o, "method"));
    if (sym) {
        if (js(o, "over") != NULL) complex_p(r, o);
        /* the bilinear route's OR of branches or its "never" (issue 17) */
        if (!branches(r, o)) {
            if (json_array_size(json_object_get(o, "conditions")) == 0)
                rs_render_line(r, "conditions", "%s", "none left: every Schur-Cohn condition holds under the "
                                                      "assumptions");
            condition_lines(r, o, "stable iff", "and", 0);
        } else if (js(o, "never_from") != NULL && json_object_get(o, "branches") == NULL) {
            condition_lines(r, o, "conditions", "and", 0);
        }
        /* with "never" only: the other symbolic reports stay as they were */
        if (js(o, "never") != NULL) rs_render_line(r, "verdict", "%s", js(o, "verdict"));
        rs_render_line(r, "route", "%s", js(o, "route_reason"));
        /* the second exact route (hurwitz's on the bilinear image) said only
         * when it disagrees at a point: the run exits 3 */
        {
            const json_t *cr = json_object_get(o, "cross_route");
            if (json_is_false(json_object_get(cr, "agree")))
                rs_render_linef(r, "disagree", "%s: the Schur-Cohn conditions say %s at a sample point, the bilinear "
                               "image's Lienard-Chipart conditions the opposite (a bug: both are exact)",
                               js(cr, "with"), js(cr, "table_says"));
        }
        not_expanded(r, o);
        if (js(o, "over") != NULL && json_object_get(o, "inside") != NULL) rs_render_count(r, o, RS_RENDER_TEXT);
        rs_render_line(r, "note", "%s", js(o, "note"));
        rs_render_sample_check(r, o);
        rs_render_assigned(r, o);
        return;
    }
    if (json_is_true(json_object_get(o, "table_regular")))
        rs_render_string_list(r, "table rows", json_object_get(o, "rows"), "\n               ");
    else
        rs_render_line(r, "table", "%s", "singular Jury table: decided through gcd(p, p*) and the Schur-Cohn form");
    rs_render_count(r, o, RS_RENDER_ALL);
    rs_render_line(r, "cross-check", "%s", json_is_true(json_object_get(cc, "agree"))
                                               ? "Routh (bilinear) agrees" : "DISAGREES with Routh (bilinear)");
    rs_render_assigned(r, o);
}

/* Which method decided, and whether Routh and Schur-Cohn agree. */
static void decided_by(rs_render_t *r, const json_t *o)
{
    const json_t *agree = json_object_get(o, "agree");
    if (json_is_boolean(agree) && js(o, "over") != NULL)
        rs_render_linef(r, "decided by", "%s (%s)", js(o, "decided_by"),
                        json_is_true(agree) ? "Schur-Cohn over Q(i) on p(lambda) and Bilharz on q(z) agree"
                                            : "DISAGREEMENT between the complex tests: internal inconsistency");
    else if (json_is_boolean(agree))
        rs_render_linef(r, "decided by", "%s (%s)", js(o, "decided_by"),
                        json_is_true(agree) ? "Routh on q(z) and Schur-Cohn on p(lambda) agree"
                                            : "DISAGREEMENT between Routh and Schur-Cohn: internal inconsistency");
    else
        rs_render_line(r, "decided by", "%s", js(o, "decided_by"));
}

/* over Q(sqrt d) (rk sdirk2, an_qd.c): |R(z)|^2 decided exactly on the
 * test equation, else Schur-Cohn and the certified roots of p */
static void stability_qd(rs_render_t *r, const json_t *o)
{
    const json_t *sf = json_object_get(o, "stability_function");
    char db[24];
    const char *d = qd_d(o, db, sizeof db);
    rs_render_heading_begin(r);
    rs_render_sayf(r, "Stability at the given values over Q(sqrt %s)",
                   "Stability at the given values over $\\mathbb{Q}(\\sqrt{%s})$", d);
    rs_render_heading_end(r);
    taken_at(r, o);
    rs_render_say(r, "The method (", "The method (");
    rs_render_esc(r, js(o, "method"));
    rs_render_sayf(r, ") has coefficients in Q(sqrt %s): its stage equations carry $\\sqrt{%s}$ exactly, and the "
                   "characteristic polynomial is $p = p_0 + \\sqrt{%s}\\,p_1$ with rational $p_0$, $p_1$.",
                   ") has coefficients in $\\mathbb{Q}(\\sqrt{%s})$: its stage equations carry $\\sqrt{%s}$ exactly, "
                   "and the characteristic polynomial is $p = p_0 + \\sqrt{%s}\\,p_1$ with rational $p_0$, $p_1$.",
                   d, d, d);
    if (sf != NULL) {
        rs_render_say(r, " On the test equation $p = D\\,\\lambda - N$ with $R = N/D$, $N = ",
                      " On the test equation $p = D\\,\\lambda - N$ with $R = N/D$, $N = ");
        rs_render_poly(r, js(sf, "N"));
        rs_render_say(r, "$, $D = ", "$, $D = ");
        rs_render_poly(r, js(sf, "D"));
        rs_render_say(r, "$", "$");
        if (js(o, "abs_R_squared") != NULL) {
            rs_render_say(r, "; here $|R|^2 = ", "; here $|R|^2 = ");
            rs_render_poly(r, js(o, "abs_R_squared"));
            rs_render_sayf(r, "$, compared with 1 by the exact sign in Q(sqrt %s)",
                           "$, compared with 1 by the exact sign in $\\mathbb{Q}(\\sqrt{%s})$", d);
        }
        rs_render_say(r, ".", ".");
    } else if (js(o, "poly") != NULL) {
        rs_render_say(r, " At these values:\n\n$$p(\\lambda) = ", " At these values:\n\n$p(\\lambda) = ");
        rs_render_poly(r, js(o, "poly"));
        rs_render_sayf(r, "$$\n\nSchur-Cohn's recursion with exact signs in Q(sqrt %s)(i) and the certified roots "
                       "(Arb, $\\sqrt{%s}$ as a ball) answer independently and must agree.",
                       "$\n\nSchur--Cohn's recursion with exact signs in $\\mathbb{Q}(\\sqrt{%s})(i)$ and the "
                       "certified roots (Arb, $\\sqrt{%s}$ as a ball) answer independently and must agree.", d, d);
    }
    rs_render_sayf(r, " Verdict: **%s** (decided by exact arithmetic).\n\n",
                   " Verdict: \\textbf{%s} (decided by exact arithmetic).\n\n", js(o, "status"));
    rs_render_line(r, "status", "%s", js(o, "status"));
    if (js(o, "abs_R_squared") != NULL) rs_render_line(r, "|R(z)|^2", "%s", js(o, "abs_R_squared"));
    if (js(o, "poly") != NULL) rs_render_linef(r, "p(lambda)", "%s (over %s)", js(o, "poly"), js(o, "over"));
    /* the counts of the counting Schur-Cohn recursion, as the rational path prints them */
    if (json_object_get(o, "inside") != NULL) rs_render_count(r, o, RS_RENDER_ALL);
    if (js(o, "note") != NULL) rs_render_line(r, "note", "%s", js(o, "note"));
    if (json_object_get(o, "stability_function") != NULL)
        rs_render_line(r, "decided by", "%s (|R(z)|^2 in Q(sqrt d), Schur-Cohn over Q(sqrt d)(i) and the certified "
                       "root agree)", js(o, "decided_by"));
    else
        rs_render_linef(r, "decided by", "%s (Schur-Cohn over Q(sqrt d)(i): %s; certified roots: %s)",
                       js(o, "decided_by"), json_is_true(json_object_get(o, "schur_cohn_stable")) ? "stable"
                       : "not strictly stable", js(o, "roots_certified") ? js(o, "roots_certified") : "none");
    rs_render_assigned(r, o);
}

/* any analysis at values where det A vanishes identically (run.c's
 * rs_run_emit_vanishing): no counts, the verdict and its reason */
void rs_render_vanishing(rs_render_t *r, const json_t *o)
{
    rs_render_sayf(r, "Verdict of `%s`: **%s**: ", "Verdict of \\texttt{%s}: \\textbf{%s}: ", js(o, "analysis"),
                   js(o, "status"));
    rs_render_esc(r, js(o, "singular"));
    rs_render_say(r, ".\n\n", ".\n\n");
    rs_render_line(r, "verdict", "%s", js(o, "status"));
    rs_render_line(r, "singular", "%s", js(o, "singular"));
    rs_render_line(r, "decided by", "%s", js(o, "decided_by"));
    rs_render_assigned(r, o);
}

void rs_render_stability(rs_render_t *r, const json_t *o)
{
    int sym;
    if (json_object_get(o, "stability_function") != NULL || json_object_get(o, "p0") != NULL) {
        stability_qd(r, o);
        return;
    }
    sym = schur_cohn_prose(r, o, "Stability at the given values", "Stability at the given values");
    if (json_object_get(o, "inside") == NULL) {
        /* a co-simulation's stability is its certified radius in the report */
        rs_render_radius(r, o);
        rs_render_count(r, o, sym ? 0 : RS_RENDER_PROSE);
        return;
    }
    if (js(o, "over") != NULL) rs_render_line(r, "p(lambda)", "%s (over Q(i))", js(o, "p"));
    rs_render_count(r, o, RS_RENDER_TEXT | (sym ? 0 : RS_RENDER_PROSE));
    decided_by(r, o);
    if (json_object_get(o, "complex_check") != NULL)
        rs_render_linef(r, "over Q(i)", "%s by Schur-Cohn over Q(i) and Bilharz on p = %s (agrees)",
                        js(json_object_get(o, "complex_check"), "status"),
                        js(json_object_get(o, "complex_check"), "p"));
    rs_render_assigned(r, o);
}

static const char *endpoint(const json_t *e, int hi)
{
    const char *s = rs_render_endpoint(e, hi);
    return s ? s : "(null)";
}

/* the region as intervals of one parameter, each with its status */
static void region_intervals(rs_render_t *r, const json_t *o)
{
    const json_t *ivs = json_object_get(o, "intervals");
    const char *param = js(o, "param");
    size_t i;
    rs_render_list_begin(r);
    for (i = 0; i < json_array_size(ivs); i++) {
        const json_t *iv = json_array_get(ivs, i), *hi = json_object_get(iv, "hi");
        const char *a = endpoint(json_object_get(iv, "lo"), 0), *b = endpoint(hi, 1);
        const char *open = json_is_true(json_object_get(iv, "lo_closed")) ? "[" : "(";
        const char *close = json_is_true(json_object_get(iv, "hi_closed")) ? "]" : ")";
        if (strcmp(a, b) == 0) rs_render_textf(r, "  %-10s %s = %s\n", js(iv, "status"), param, a);
        else rs_render_textf(r, "  %-10s %s in %s%s, %s%s\n", js(iv, "status"), param, open, a, b, close);
        rs_render_item_begin(r);
        rs_render_sayf(r, "**%s**: $", "%s: $", js(iv, "status"));
        rs_render_poly(r, param);
        rs_render_sayf(r, " \\in %s%s, %s%s$", " \\in %s%s, %s%s$", open,
                       strcmp(a, "-inf") == 0 ? "-\\infty" : a, strcmp(b, "inf") == 0 ? "\\infty" : b, close);
        if (json_is_object(hi)) {
            rs_render_say(r, " (upper end: a root of ", " (upper end: a root of ");
            rs_render_math(r, js(hi, "minpoly"));
            rs_render_say(r, ")", ")");
        }
        rs_render_item_end(r);
    }
    rs_render_list_end(r);
}

/* the report's exact form of algebraic endpoints, and the undecided points */
static void region_where(rs_render_t *r, const json_t *o)
{
    const json_t *ivs = json_object_get(o, "intervals");
    const json_t *pts = json_object_get(o, "undecided_points");
    size_t i;
    for (i = 0; i < json_array_size(ivs); i++) {
        const json_t *hi = json_object_get(json_array_get(ivs, i), "hi");
        if (json_is_object(hi) && (i + 1 == json_array_size(ivs) ||
            !json_equal(hi, json_object_get(json_array_get(ivs, i + 1), "hi"))))
            rs_render_linef(r, "where", "%s is root %lld (from below, 0-based) of %s", js(hi, "approx"),
                            ji(hi, "root_index"), js(hi, "minpoly"));
    }
    for (i = 0; i < json_array_size(ivs); i++) {
        const json_t *iv = json_array_get(ivs, i);
        if (js(iv, "note") != NULL && json_is_boolean(json_object_get(iv, "vanishes")))
            rs_render_linef(r, "singular", "%s = %s: %s", js(o, "param"), endpoint(json_object_get(iv, "lo"), 0),
                            js(iv, "note"));
    }
    for (i = 0; i < json_array_size(pts); i++)
        rs_render_linef(r, "undecided", "%s (status at this point itself not decided exactly)",
                        endpoint(json_object_get(json_array_get(pts, i), "value"), 0));
}

/* one side of region N1, N2's formula: an OR of ANDs as text */
static void region2_dnf(rs_render_t *r, const json_t *dnf, const char *label, const char *md)
{
    char buf[4096] = "";
    size_t i, j;
    if (json_is_null(dnf)) {
        /* region re(z), im(z): stable / not stable only */
        rs_render_line(r, label, "%s", "not computed (on the boundary; map re(z), im(z) decides it per point)");
        return;
    }
    for (i = 0; i < json_array_size(dnf); i++) {
        const json_t *cj = json_array_get(dnf, i);
        size_t n = strlen(buf);
        snprintf(buf + n, sizeof buf - n, "%s%s", i ? " or " : "", json_array_size(dnf) > 1 ? "(" : "");
        for (j = 0; j < json_array_size(cj); j++) {
            n = strlen(buf);
            snprintf(buf + n, sizeof buf - n, "%s%s", j ? " and " : "", json_string_value(json_array_get(cj, j)));
        }
        if (json_array_size(cj) == 0) { n = strlen(buf); snprintf(buf + n, sizeof buf - n, "true"); }
        n = strlen(buf);
        if (json_array_size(dnf) > 1) snprintf(buf + n, sizeof buf - n, ")");
    }
    rs_render_line(r, label, "%s", json_array_size(dnf) ? buf : "never (no cell)");
    if (json_array_size(dnf) == 0) return;
    rs_render_say(r, md, md);
    rs_render_list_begin(r);
    for (i = 0; i < json_array_size(dnf); i++) {
        const json_t *cj = json_array_get(dnf, i);
        rs_render_item_begin(r);
        if (json_array_size(cj) == 0) rs_render_say(r, "everywhere in the domain", "everywhere in the domain");
        for (j = 0; j < json_array_size(cj); j++) {
            if (j) rs_render_say(r, " and ", " and ");
            rs_render_math(r, json_string_value(json_array_get(cj, j)));
        }
        rs_render_item_end(r);
    }
    rs_render_list_end(r);
}

/* region N1, N2: the formula, the boundary, the decomposition's size */
static void region2(rs_render_t *r, const json_t *o)
{
    const json_t *pa = json_object_get(o, "params"), *fo = json_object_get(o, "formula");
    const json_t *b = json_object_get(o, "boundary"), *cc = json_object_get(o, "cross_check");
    size_t i;
    rs_render_heading_begin(r);
    rs_render_sayf(r, "Stability region in (%s, %s)", "Stability region in $(%s, %s)$",
                   json_string_value(json_array_get(pa, 0)), json_string_value(json_array_get(pa, 1)));
    rs_render_heading_end(r);
    rs_render_say(r, "A cylindrical decomposition of the plane into cells, one exact verdict per cell; "
                  "the sets as sign conditions of the critical polynomials:\n\n",
                  "A cylindrical decomposition of the plane into cells, one exact verdict per cell; "
                  "the sets as sign conditions of the critical polynomials:\n\n");
    if (js(o, "over") != NULL)   /* over Q(sqrt d): the polynomials are norms */
    {
        rs_render_linef(r, "over", "%s: %s", js(o, "over"), js(o, "norm_note") != NULL ? js(o, "norm_note") : "");
        rs_render_sayf(r, "The coefficients lie in %s; the polynomials below are norms $g_0^2 - d\\,g_1^2$ of "
                       "polynomials $g_0 + \\sqrt{d}\\,g_1$ over it: exact, but possibly of higher degree than the "
                       "true boundary curve (a norm also vanishes on its conjugate's curve, whose arcs separate "
                       "nothing).\n\n", "The coefficients lie in %s; the polynomials below are norms "
                       "$g_0^2 - d\\,g_1^2$ of polynomials $g_0 + \\sqrt{d}\\,g_1$ over it: exact, but possibly of "
                       "higher degree than the true boundary curve (a norm also vanishes on its conjugate's curve, "
                       "whose arcs separate nothing).\n\n", js(o, "over"));
    }
    region2_dnf(r, json_object_get(fo, "stable"), "stable iff", "Stable if and only if one of:\n\n");
    region2_dnf(r, json_object_get(fo, "marginal"), "marginal iff", "Marginally stable if and only if one of:\n\n");
    for (i = 0; i < json_array_size(json_object_get(o, "domain")); i++)
        rs_render_line(r, i ? "" : "where", "%s (assumed)", json_string_value(json_array_get(json_object_get(o, "domain"), i)));
    for (i = 0; i < json_array_size(b); i++)
        rs_render_line(r, i ? "" : "boundary", "%s = 0", json_string_value(json_array_get(b, i)));
    /* curves marginal between two sides of one status: no boundary of the
     * stable set, but where the status changes */
    b = json_object_get(o, "marginal_curves");
    for (i = 0; i < json_array_size(b); i++)
        rs_render_line(r, i ? "" : "marginal on", "%s = 0 (a curve, no boundary: one status on both sides)",
                       json_string_value(json_array_get(b, i)));
    rs_render_linef(r, "cells", "%zu (%lld critical values of %s)", json_array_size(json_object_get(o, "cells")),
                    (long long) json_array_size(json_object_get(o, "critical_values")),
                    json_string_value(json_array_get(pa, 0)));
    if (!json_is_true(json_object_get(o, "formula_complete")))
        rs_render_line(r, "incomplete", "%s", js(o, "formula_note"));
    rs_render_linef(r, "re-checked", "%lld of %lld random rational points agree with the exact point verdict",
                    ji(cc, "agree"), ji(cc, "points"));
    decided_by(r, o);
    rs_render_assigned(r, o);
}

void rs_render_region(rs_render_t *r, const json_t *o)
{
    if (json_object_get(o, "transitions") != NULL) {   /* exact integration: certified over boxes */
        rs_render_cosim_region(r, o);
        return;
    }
    if (json_is_array(json_object_get(o, "params"))) { region2(r, o); return; }   /* region N1, N2 */
    rs_render_heading_begin(r);
    rs_render_say(r, "Stability region in $", "Stability region in $");
    rs_render_poly(r, js(o, "param"));
    rs_render_say(r, "$", "$");
    rs_render_heading_end(r);
    taken_at(r, o);
    if (json_is_true(json_object_get(o, "symbolic"))) {
        const json_t *c = json_object_get(o, "conditions");
        if (!branches(r, o)) {
            if (json_array_size(c) == 0)
                rs_render_line(r, "stable iff", "%s", "true: every condition holds under the assumptions");
            condition_list(r, c, "Stable if and only if:\n\n", "Stable if and only if:\n", NULL);
        }
        condition_lines(r, o, "stable iff", "and", 1);
        rs_render_line(r, "note", "%s", js(o, "note"));
        rs_render_sample_check(r, o);
        rs_render_assigned(r, o);
        return;
    }
    region_intervals(r, o);
    region_where(r, o);
    qdc_over_at(r, o, 1);
    if (json_is_array(json_object_get(o, "for_all"))) {   /* region NAME for all [...] */
        const json_t *fa = json_object_get(o, "for_all");
        char names[256] = "";
        size_t i;
        for (i = 0; i < json_array_size(fa); i++)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", i ? ", " : "",
                     json_string_value(json_array_get(fa, i)));
        rs_render_linef(r, "for all", "%s%s (each interval: a re-checked certificate, or an exact counterexample)",
                        names[0] ? names : "(no other parameter)", json_array_size(fa) ? " admissible" : "");
    }
    rs_render_assigned(r, o);
}

void rs_render_limit(rs_render_t *r, const json_t *o)
{
    const json_t *roots = json_object_get(o, "roots");
    const char *to = js(o, "to");
    char lab[80];
    size_t i;
    snprintf(lab, sizeof lab, "%s -> %s", js(o, "param"), to);
    rs_render_line(r, lab, "roots tend to the roots of %s", js(o, "limit_poly"));
    rs_render_heading_begin(r);
    rs_render_say(r, "Limit $", "Limit $");
    rs_render_poly(r, js(o, "param"));
    rs_render_say(r, " \\to ", " \\to ");
    rs_render_say(r, to && strcmp(to, "inf") == 0 ? "\\infty" : "0", to && strcmp(to, "inf") == 0 ? "\\infty" : "0");
    rs_render_say(r, "$", "$");
    rs_render_heading_end(r);
    rs_render_say(r, "The roots tend to: ", "The roots tend to: ");
    for (i = 0; i < json_array_size(roots); i++) {
        const json_t *z = json_array_get(roots, i);
        const char *mp = js(z, "minpoly");
        rs_render_linef(r, "", "%s (multiplicity %lld)%s%s", js(z, "value"), ji(z, "multiplicity"),
                        mp ? ", root of " : "", mp ? mp : "");
        rs_render_say(r, i ? ", $" : "$", i ? ", $" : "$");
        rs_render_poly(r, js(z, "value"));
        rs_render_sayf(r, "$ ($\\times %lld$)", "$ ($\\times %lld$)", ji(z, "multiplicity"));
    }
    rs_render_say(r, ".\n\n", ".\n\n");
    if (json_is_true(json_object_get(o, "all_roots_to_zero")))
        rs_render_line(r, "", "%s", "every root tends to 0 (strong decay)");
    rs_render_assigned(r, o);
}

/* "k = v, ..." of a JSON object of strings, in the report */
static void assignments(rs_render_t *r, const json_t *obj)
{
    const char *key;
    json_t *val;
    int first = 1;
    json_object_foreach((json_t *) obj, key, val) {
        rs_render_textf(r, "%s%s = %s", first ? "" : ", ", key, json_string_value(val));
        first = 0;
    }
}

/* the report's proof of a claim: one line per condition */
static void certificate_lines(rs_render_t *r, const json_t *c)
{
    size_t i;
    for (i = 0; i < json_array_size(c); i++) {
        const json_t *e = json_array_get(c, i);
        const char *label = i == 0 ? "certificate" : "";
        if (js(e, "text")) {
            rs_render_line(r, label, "%s", js(e, "text"));
            continue;
        }
        rs_render_label(r, label);
        rs_render_textf(r, "%s > 0 since with ", js(e, "condition"));
        assignments(r, json_object_get(e, "substitution"));
        if (ji(e, "transformed_terms") == 1)
            rs_render_textf(r, " (every s >= 0) the numerator's one coefficient is >= 0");
        else
            rs_render_textf(r, " (every s >= 0) the numerator's %lld coefficients are all >= 0",
                            ji(e, "transformed_terms"));
        if (js(e, "positive_factor")) rs_render_textf(r, " after dividing by %s > 0", js(e, "positive_factor"));
        if (ji(e, "polya_power") > 0) rs_render_textf(r, " times (1 + sum s)^%lld", ji(e, "polya_power"));
        rs_render_textf(r, "\n");
    }
    rs_render_line(r, "re-checked", "%s", "yes (independent evaluation at random points of the region)");
}

/* the derivation's proof of a claim: for each condition the substitution
 * that makes it evident, typeset as equations ($w = \frac{2 s_w}{1 + s_w}$) */
static void certificate_prose(rs_render_t *r, const json_t *c)
{
    size_t i;
    rs_render_say(r, "Certificate: after the substitutions below (each $s \\geq 0$), every coefficient of the "
                     "numerator is non-negative:\n\n",
                  "Certificate: after the substitutions below (each $s \\geq 0$), every coefficient of the "
                  "numerator is non-negative:\n");
    rs_render_list_begin(r);
    for (i = 0; i < json_array_size(c); i++) {
        const json_t *e = json_array_get(c, i);
        const char *k;
        json_t *v;
        int first = 1;
        rs_render_item_begin(r);
        if (js(e, "text") != NULL) {
            rs_render_esc(r, js(e, "text"));
            rs_render_item_end(r);
            continue;
        }
        rs_render_say(r, "$", "$");
        rs_render_poly(r, js(e, "condition"));
        rs_render_say(r, " > 0$ by ", " > 0$ by ");
        json_object_foreach(json_object_get(e, "substitution"), k, v) {
            rs_render_say(r, first ? "$" : ",\\quad ", first ? "$" : ",\\quad ");
            rs_render_poly(r, k);
            rs_render_say(r, " = ", " = ");
            rs_render_poly(r, json_string_value(v));
            first = 0;
        }
        if (!first) rs_render_say(r, "$", "$");
        else rs_render_say(r, "no substitution (its coefficients are non-negative as they are)",
                           "no substitution (its coefficients are non-negative as they are)");
        rs_render_item_end(r);
    }
    rs_render_list_end(r);
}

/* the for-all region's cross-check and explanation of a claim (issue 13) */
static void explanation_lines(rs_render_t *r, const json_t *o)
{
    const json_t *cc = json_object_get(o, "cross_check"), *ex = json_object_get(o, "explanation");
    if (cc != NULL)
        rs_render_linef(r, "region check", "%s%s%s", js(cc, "status"),
                        js(cc, "message") || js(cc, "reason") ? ": " : "",
                        js(cc, "message") ? js(cc, "message") : js(cc, "reason") ? js(cc, "reason") : "");
    if (ex != NULL) rs_render_line(r, "explanation", "%s", js(ex, "summary"));
}

static void explanation_prose(rs_render_t *r, const json_t *o)
{
    const json_t *ex = json_object_get(o, "explanation");
    if (ex == NULL) return;
    rs_render_say(r, "Region of the claim's parameter for all others: ",
                  "Region of the claim's parameter for all others: ");
    rs_render_code(r, js(ex, "summary"));
    rs_render_say(r, ".\n\n", ".\n\n");
}

void rs_render_claim(rs_render_t *r, const json_t *o)
{
    const char *st = js(o, "status");
    if (json_object_get(o, "boxes_checked") != NULL) {   /* exact integration: certified over boxes */
        rs_render_cosim_claim(r, o);
        return;
    }
    rs_render_line(r, "claim", "%s", js(o, "text"));
    rs_render_line(r, "status", "%s", st);
    if (json_is_array(json_object_get(o, "region"))) {
        /* over Q(sqrt d) (an_qd_conds.c): decided on the exact region of one parameter */
        char db[24];
        const char *d = qd_d(o, db, sizeof db);
        if (json_object_get(o, "counterexample") != NULL) {
            rs_render_label(r, "counterexample");
            assignments(r, json_object_get(o, "counterexample"));
            rs_render_textf(r, "%s\n", "");
        }
        rs_render_linef(r, "decided by", "the exact region over %s (%lld cells; samples cross-checked: %lld)",
                        js(o, "over"), (long long) json_array_size(json_object_get(o, "region")),
                        ji(o, "cross_checked_samples"));
        qdc_over_at(r, o, 0);
        rs_render_assigned(r, o);
        rs_render_heading(r, "Claim", "Claim");
        taken_at(r, o);
        rs_render_say(r, "Claim ", "Claim ");
        rs_render_code(r, js(o, "text"));   /* a code span: no escapes inside */
        if (json_object_get(o, "for_all") != NULL)   /* two free parameters: region ... for all's cells */
            rs_render_sayf(r, ": **%s**, decided on the exact region over Q(sqrt %s) of one free parameter for every "
                           "value of the other.\n\n", ": \\textbf{%s}, decided on the exact region over "
                           "$\\mathbb{Q}(\\sqrt{%s})$ of one free parameter for every value of the other.\n\n", st, d);
        else   /* "(i)": at complex set values (an_qd_complex.c) */
            rs_render_sayf(r, ": **%s**, decided on the exact region over Q(sqrt %s)%s of the one free parameter.\n\n",
                           ": \\textbf{%s}, decided on the exact region over $\\mathbb{Q}(\\sqrt{%s})%s$ of the one "
                           "free parameter.\n\n", st, d, strstr(js(o, "over") ? js(o, "over") : "", "(i)") ? "(i)" : "");
        return;
    }
    if (st && strcmp(st, "refuted") == 0) {
        const json_t *ce = json_object_get(o, "counterexample"), *at = json_object_get(o, "at_counterexample");
        rs_render_label(r, "counterexample");
        assignments(r, ce);
        rs_render_textf(r, "%s\n", json_object_size(ce) == 0 ? "the scheme as given (no free parameter)" : "");
        if (js(o, "angles")) rs_render_line(r, "angles", "%s", js(o, "angles"));
        if (js(at, "reason")) rs_render_linef(r, "verdict", "%s: %s", js(at, "status"), js(at, "reason"));
        else rs_render_count(r, at, RS_RENDER_TEXT);
        if (js(at, "counts_of")) rs_render_line(r, "counts of", "%s", js(at, "counts_of"));
        rs_render_line(r, "found by", "%s", js(o, "found_by"));
    } else if (st && strcmp(st, "proved") == 0) {
        certificate_lines(r, json_object_get(o, "certificate"));
    } else {
        rs_render_line(r, "tried", "%s", js(o, "tried"));
        rs_render_line(r, "failed at", "%s", js(o, "failed_at"));
    }
    rs_render_linef(r, "search", "%lld points checked exactly", ji(o, "points_checked"));
    explanation_lines(r, o);
    rs_render_assigned(r, o);
    rs_render_heading(r, "Claim", "Claim");
    taken_at(r, o);
    claim_prose(r, o);
    explanation_prose(r, o);
    if (json_is_array(json_object_get(o, "certificate"))) certificate_prose(r, json_object_get(o, "certificate"));
}
