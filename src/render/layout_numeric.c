/* layout_numeric.c -- the layouts of the numeric analyses (radius, modes,
 * simulate, sweep and map) and of any other result: report lines only, the
 * derivations show none of them. */
#include <stdlib.h>
#include <string.h>
#include <flint/flint.h>
#include "recstab/radius.h"
#include "render_impl.h"

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

/* Which two methods counted the roots inside (and agreed), and by which
 * Schur-Cohn route (radius results: count_methods, schur_cohn_route). */
static void count_line(rs_render_t *r, const json_t *o)
{
    const json_t *m = json_object_get(o, "count_methods"), *rt = json_object_get(o, "schur_cohn_route");
    const json_t *bits = rt != NULL ? json_object_get(rt, "precision_bits") : NULL;
    const char *a = json_string_value(json_array_get(m, 0)), *b = json_string_value(json_array_get(m, 1));
    const char *ag = json_is_true(json_object_get(o, "count_agree")) ? "agree" : "DISAGREE";
    char buf[400];
    if (a == NULL || b == NULL) return;
    if (bits != NULL)
        snprintf(buf, sizeof buf, "%s and %s %s (%s, %lld bits)", a, b, ag, rs_render_jstr(rt, "method"),
                 (long long) json_integer_value(bits));
    else if (rt != NULL)
        snprintf(buf, sizeof buf, "%s and %s %s (%s)", a, b, ag, rs_render_jstr(rt, "method"));
    else
        snprintf(buf, sizeof buf, "%s and %s %s", a, b, ag);
    rs_render_line(r, "counted by", "%s", buf);
}

void rs_render_radius(rs_render_t *r, const json_t *o)
{
    const json_t *roots = json_object_get(o, "roots");
    size_t i;
    /* singular (an_radius.c): the reason, no radius */
    if (json_object_get(o, "rho") == NULL && rs_render_jstr(o, "singular") != NULL) {
        rs_render_vanishing(r, o);
        return;
    }
    rs_render_line(r, "method", "%s", rs_render_jstr(o, "method"));
    if (json_is_true(json_object_get(o, "certified"))) {
        char buf[160];
        rs_render_line(r, "rho", "%s", rs_render_jstr(o, "rho"));
        rs_render_line(r, "certified", "[%s,", rs_render_jstr(o, "lower"));
        rs_render_line(r, "", " %s]", rs_render_jstr(o, "upper"));
        snprintf(buf, sizeof buf, "%lld digits asked, %lld bits used", rs_render_jint(o, "digits"), rs_render_jint(o, "precision_bits"));
        rs_render_line(r, "precision", "%s", buf);
        for (i = 0; i < json_array_size(roots); i++) {
            /* whole strings: cutting a printed decimal short is not a rounding */
            const json_t *z = json_array_get(roots, i);
            const char *re = rs_render_jstr(z, "re"), *im = rs_render_jstr(z, "im"), *ab = rs_render_jstr(z, "abs");
            char *rad = radius_up(json_real_value(json_object_get(z, "radius")));
            size_t len = strlen(re) + strlen(im) + strlen(ab) + strlen(rad) + 32;
            char *rb = malloc(len);
            snprintf(rb, len, "%s %s %si +- %s  |.| = %s", re, im[0] == '-' ? "-" : "+", im[0] == '-' ? im + 1 : im,
                     rad, ab);
            rs_render_line(r, i == 0 ? "roots" : "", "%s", rb);
            free(rb);
            flint_free(rad);
        }
        if (json_object_get(o, "verdict_digits") != NULL) {
            snprintf(buf, sizeof buf, "raised to %lld digits to separate the interval from 1", rs_render_jint(o, "verdict_digits"));
            rs_render_line(r, "refined", "%s", buf);
        }
        rs_render_line(r, "from radius", "%s", rs_render_jstr(o, "verdict_from_radius"));
        /* "count": the ball table counted, no exact method (an_radius.c) */
        rs_render_line(r, json_object_get(o, "count_certified") != NULL ? "count" : "exact",
                       "%s (consistent with the radius)", rs_render_jstr(o, "exact_status"));
        count_line(r, o);
        rs_render_line(r, "verdict", "%s (certified by the radius interval)", rs_render_jstr(o, "status"));
        rs_render_line(r, "monolithic", "%s (exact integration of the coupled system: the reference)", rs_render_jstr(o, "monolithic_rho"));
    } else {
        char buf[64];
        snprintf(buf, sizeof buf, "%.17g (double precision, NOT certified)", json_real_value(json_object_get(o, "rho")));
        rs_render_line(r, "rho", "%s", buf);
        rs_render_line(r, "exact", "%s", rs_render_jstr(o, "exact_status"));
    }
    rs_render_assigned(r, o);
}

void rs_render_modes(rs_render_t *r, const json_t *o)
{
    const char *groups[] = {"modes", "spurious"};
    char buf2[300];
    size_t g, i, zeros = 0;
    rs_render_line(r, "h", "%s", rs_render_jstr(o, "h"));
    for (g = 0; g < 2; g++) {
        const json_t *m = json_object_get(o, groups[g]);
        int first = 1;
        for (i = 0; i < json_array_size(m); i++) {
            const json_t *e = json_array_get(m, i);
            char buf[400];
            if (rs_render_jstr(e, "sigma") == NULL) { zeros++; continue; }   /* a root at 0 */
            snprintf(buf, sizeof buf, "sigma %s omega %s damping %s%s%s", rs_render_jstr(e, "sigma"),
                     rs_render_jstr(e, "omega"), rs_render_jstr(e, "damping_ratio") ? rs_render_jstr(e, "damping_ratio") : "undefined", rs_render_jstr(e, "frequency_error") ? " freq.error " : "",
                     rs_render_jstr(e, "frequency_error") ? rs_render_jstr(e, "frequency_error") : "");
            rs_render_line(r, first ? (g == 0 ? "principal" : "spurious") : "", "%s", buf);
            first = 0;
        }
    }
    if (zeros > 0) rs_render_linef(r, "roots at 0", "%zu (no continuous equivalent)", zeros);
    rs_render_line(r, "verdict", "%s", rs_render_jstr(o, "status"));
    rs_render_line(r, "singular", "%s", rs_render_jstr(o, "singular"));
    if (json_object_get(o, "exact_check") != NULL) {
        /* over Q(i) or Q(sqrt d): p's own roots, their moduli against the exact counts */
        const json_t *ck = json_object_get(o, "exact_check"), *at = json_object_get(o, "at");
        const char *key;
        json_t *val;
        json_object_foreach((json_t *) at, key, val)
            rs_render_linef(r, "complex", "%s = %s", key, json_string_value(val));
        const char *over = rs_render_jstr(o, "over") ? rs_render_jstr(o, "over") : "Q(i)";
        if (json_object_get(ck, "inside") == NULL)   /* over Q(sqrt d): no exact verdict to compare */
            snprintf(buf2, sizeof buf2, "%s over %s; certified moduli not compared", rs_render_jstr(ck, "status"),
                     over);
        else
            snprintf(buf2, sizeof buf2, "%s over %s (%lld inside, %lld on, %lld outside); certified moduli %s",
                     rs_render_jstr(ck, "status"), over, rs_render_jint(ck, "inside"), rs_render_jint(ck, "on"),
                     rs_render_jint(ck, "outside"),
                     json_is_true(json_object_get(ck, "agree")) ? "agree" : "DISAGREE");
        rs_render_line(r, "exact", "%s", buf2);
    }
    rs_render_assigned(r, o);
}

void rs_render_simulate(rs_render_t *r, const json_t *o)
{
    char buf[200];
    snprintf(buf, sizeof buf, "%lld steps from a seeded random start (seed %lld), %lld bits", rs_render_jint(o, "steps"),
             rs_render_jint(o, "seed"), rs_render_jint(o, "precision_bits"));
    rs_render_line(r, "run", "%s", buf);
    rs_render_line(r, "recurrence", "%s", rs_render_jstr(o, "recurrence"));
    rs_render_line(r, "growth", "%s per step (measured)", rs_render_jstr(o, "growth") ? rs_render_jstr(o, "growth") : "undefined");
    if (rs_render_jstr(o, "radius")) rs_render_line(r, "radius", "%s (certified)", rs_render_jstr(o, "radius"));
    if (json_object_get(o, "check")) {
        const json_t *ck = json_object_get(o, "check");
        snprintf(buf, sizeof buf, "%s (exact): %s", rs_render_jstr(json_object_get(o, "verdict"), "status"),
                 json_is_true(json_object_get(ck, "consistent")) ? "consistent with the run"
                                                                : rs_render_jstr(ck, "disagreement"));
        rs_render_line(r, "verdict", "%s", buf);
    } else if (json_object_get(o, "verdict")) {   /* over Q(sqrt d): an undecided verdict is not compared */
        const json_t *vd = json_object_get(o, "verdict");
        rs_render_linef(r, "verdict", "%s (exact): %s", rs_render_jstr(vd, "status"),
                        rs_render_jstr(vd, "note") ? rs_render_jstr(vd, "note") : "not compared");
    }
    rs_render_assigned(r, o);
}

/* "KEY N, KEY N" of an object of counts into buf (nonzero counts only when skip0) */
static void counts_str(char *buf, size_t size, const json_t *c, int skip0)
{
    const char *key;
    json_t *val;
    size_t off = 0;
    buf[0] = '\0';
    json_object_foreach((json_t *) c, key, val) {
        if (skip0 && json_integer_value(val) == 0) continue;
        off += (size_t) snprintf(buf + off, off < size ? size - off : 0, "%s%s %lld", off ? ", " : "", key,
                                 (long long) json_integer_value(val));
    }
}

/* a parameter name as inline math: re(z) as \mathrm{Re}\,z */
static void param_math(rs_render_t *r, const char *name)
{
    size_t n = strlen(name);
    if (n > 4 && name[n - 1] == ')' && (strncmp(name, "re(", 3) == 0 || strncmp(name, "im(", 3) == 0)) {
        char inner[80];
        snprintf(inner, sizeof inner, "%.*s", (int) (n - 4), name + 3);
        rs_render_sayf(r, "$\\mathrm{%s}\\,", "$\\mathrm{%s}\\,", name[0] == 'r' ? "Re" : "Im");
        rs_render_poly(r, inner);
        rs_render_say(r, "$", "$");
    } else rs_render_math(r, name);
}

/* pre, the text s escaped, post (the same words in both derivations); nothing when s is NULL */
static void say_esc(rs_render_t *r, const char *pre, const char *s, const char *post)
{
    if (s == NULL) return;
    rs_render_say(r, pre, pre);
    rs_render_esc(r, s);
    rs_render_say(r, post, post);
}

/* the derivations' summary of a sweep or map: the grid, the counts, which
 * side decided, the field and methods, the boundary and the files */
static void sweep_prose(rs_render_t *r, const json_t *o)
{
    const json_t *params = json_object_get(o, "params"), *ranges = json_object_get(o, "ranges");
    const json_t *b = json_object_get(o, "boundary"), *conds = json_object_get(b, "conditions");
    const json_t *d = json_object_get(o, "decided_by");
    int map = json_is_array(params);
    const char *of = rs_render_jstr(o, "of"), *over = rs_render_jstr(o, "over");
    char buf[512];
    size_t k;
    long long exact = json_integer_value(json_object_get(d, "exact")), all = rs_render_jint(o, "computed");
    rs_render_heading_begin(r);
    if (map) {
        rs_render_sayf(r, "Map of the %s over (", "Map of the %s over (", of ? of : "stability");
        param_math(r, json_string_value(json_array_get(params, 0)));
        rs_render_say(r, ", ", ", ");
        param_math(r, json_string_value(json_array_get(params, 1)));
        rs_render_say(r, ")", ")");
    } else {
        rs_render_sayf(r, "Sweep of the %s along ", "Sweep of the %s along ", of ? of : "stability");
        param_math(r, rs_render_jstr(o, "param"));
    }
    rs_render_heading_end(r);
    rs_render_say(r, "Request ", "Request ");
    rs_render_code(r, rs_render_jstr(o, "text"));
    if (map) {
        for (k = 0; k < 2; k++) {
            const json_t *rg = json_array_get(ranges, k);
            rs_render_say(r, k ? "; " : ": ", k ? "; " : ": ");
            param_math(r, json_string_value(json_array_get(params, k)));
            rs_render_sayf(r, " from %s to %s (%lld values)", " from $%s$ to $%s$ (%lld values)",
                           json_string_value(json_array_get(rg, 0)), json_string_value(json_array_get(rg, 1)),
                           (long long) json_integer_value(json_array_get(rg, 2)));
        }
        rs_render_sayf(r, ", %lld grid points", ", %lld grid points", rs_render_jint(o, "points"));
        if (rs_render_jstr(o, "complex_plane") != NULL)
            rs_render_sayf(r, " of the complex plane of $%s$ (equal axes in the plot)",
                           " of the complex plane of $%s$ (equal axes in the plot)", rs_render_jstr(o, "complex_plane"));
    } else {
        rs_render_sayf(r, ": from %s to %s in %lld %s steps, %lld points", ": from $%s$ to $%s$ in %lld %s steps, "
                       "%lld points", rs_render_jstr(o, "from"), rs_render_jstr(o, "to"), rs_render_jint(o, "steps"),
                       rs_render_jstr(o, "spacing") ? rs_render_jstr(o, "spacing") : "linear", rs_render_jint(o, "points"));
    }
    rs_render_sayf(r, " (%lld computed).\n\n", " (%lld computed).\n\n", all);
    counts_str(buf, sizeof buf, json_object_get(o, "verdicts"), 0);
    rs_render_sayf(r, "Verdicts: %s.\n\n", "Verdicts: %s.\n\n", buf);
    counts_str(buf, sizeof buf, d, 1);
    rs_render_sayf(r, "Decided by: %s (%s).\n\n", "Decided by: %s (%s).\n\n", buf,
                   exact == all ? "every point on the exact side" : exact == 0
                   ? "every point by a certified radius at the level named, the numeric side"
                   : "exact: the exact side; the others by a certified radius at the level named, the numeric side");
    if (over != NULL) {
        say_esc(r, "Over ", over, "");
        say_esc(r, " (", rs_render_jstr(o, "rk"), ")");
        rs_render_say(r, ": ", ": ");
        if (json_is_array(json_object_get(o, "methods")))
            for (k = 0; k < json_array_size(json_object_get(o, "methods")); k++)
                say_esc(r, k ? " and " : "", json_string_value(json_array_get(json_object_get(o, "methods"), k)), "");
        else say_esc(r, "", rs_render_jstr(o, "method"), "");
        rs_render_say(r, ".", ".");
        say_esc(r, " Cross-check: ", rs_render_jstr(json_object_get(o, "cross_check"), "method"), ".");
        say_esc(r, " Radius: ", rs_render_jstr(o, "radius_method"), ".");
        say_esc(r, " Note: ", rs_render_jstr(o, "note"), ".");
        rs_render_say(r, "\n\n", "\n\n");
    }
    if (rs_render_jstr(o, "boundary_locus") != NULL) {
        const json_t *lp = json_object_get(o, "locus_points");
        say_esc(r, "Boundary locus (overlaid on the plot): ", rs_render_jstr(o, "boundary_locus"), "");
        if (lp != NULL)
            rs_render_sayf(r, "; %lld points drawn, %lld dropped", "; %lld points drawn, %lld dropped",
                           rs_render_jint(lp, "drawn"), rs_render_jint(lp, "dropped"));
        rs_render_say(r, ".\n\n", ".\n\n");
    }
    if (json_array_size(conds) > 0) {
        rs_render_sayf(r, "Boundary overlay (%lld points on the grid) from the zero sets of:\n\n",
                       "Boundary overlay (%lld points on the grid) from the zero sets of:\n\n", rs_render_jint(b, "points"));
        rs_render_list_begin(r);
        for (k = 0; k < json_array_size(conds); k++) {
            const json_t *c = json_array_get(conds, k);
            rs_render_item_begin(r);
            if (json_is_string(json_object_get(c, "poly"))) rs_render_math(r, rs_render_jstr(c, "poly"));
            say_esc(r, " (", rs_render_jstr(c, "origin"), ")");
            rs_render_item_end(r);
        }
        rs_render_list_end(r);
        say_esc(r, "", rs_render_jstr(b, "method"), ".\n\n");
    }
    if (rs_render_jstr(o, "csv") != NULL) {
        rs_render_say(r, "Table written to ", "Table written to ");
        rs_render_code(r, rs_render_jstr(o, "csv"));
        rs_render_say(r, ".\n\n", ".\n\n");
    } else {
        rs_render_say(r, "Every row: ", "Every row: ");
        rs_render_code(r, "--csv FILE");
        rs_render_say(r, " or ", " or ");
        rs_render_code(r, "--json");
        rs_render_say(r, ".\n\n", ".\n\n");
    }
}

void rs_render_sweep(rs_render_t *r, const json_t *o)
{
    const char *tab = rs_render_jstr(o, "table");
    const json_t *v = json_object_get(o, "verdicts"), *d = json_object_get(o, "decided_by");
    const char *key;
    json_t *val;
    char buf[512];
    size_t off = 0;
    sweep_prose(r, o);
    rs_render_line(r, "request", "%s", rs_render_jstr(o, "text"));
    buf[0] = '\0';
    json_object_foreach((json_t *) v, key, val)
        off += (size_t) snprintf(buf + off, off < sizeof buf ? sizeof buf - off : 0, "%s%s %lld", off ? ", " : "",
                                 key, (long long) json_integer_value(val));
    rs_render_line(r, "verdicts", "%s", buf);
    off = 0;
    buf[0] = '\0';
    json_object_foreach((json_t *) d, key, val)
        off += (size_t) snprintf(buf + off, off < sizeof buf ? sizeof buf - off : 0, "%s%s %lld", off ? ", " : "",
                                 key, (long long) json_integer_value(val));
    rs_render_line(r, "decided by", "%s", buf);
    snprintf(buf, sizeof buf, "%lld points in %.3f s", (long long) json_integer_value(json_object_get(o, "points")),
             json_real_value(json_object_get(o, "seconds")));
    rs_render_line(r, "computed", "%s", buf);
    rs_render_line(r, "csv", "%s", rs_render_jstr(o, "csv"));
    rs_render_line(r, "note", "%s", rs_render_jstr(o, "table_note"));
    /* a map over Q(sqrt d)(i) (an_qd_map.c) names its field and what undecided means */
    if (rs_render_jstr(o, "over") != NULL && strstr(rs_render_jstr(o, "over"), "sqrt") != NULL) {
        rs_render_line(r, "over", "%s", rs_render_jstr(o, "over"));
        rs_render_line(r, "method", "%s", rs_render_jstr(o, "rk"));
        rs_render_line(r, "undecided", "%s", rs_render_jstr(o, "note"));
    }
    if (tab != NULL) {
        /* the table, columns aligned; a cell is never cut (a cut decimal
         * is a different number: an outward-rounded bound cut short is no
         * longer a bound), its column widens instead */
        enum { MAXCOL = 128, MAXROWS = 60 };
        size_t width[MAXCOL];
        const char *p;
        int rowsn, pass;
        for (pass = 0; pass < MAXCOL; pass++) width[pass] = 17;
        for (pass = 0; pass < 2; pass++) {
            p = tab;
            rowsn = 0;
            while (*p && rowsn < MAXROWS) {
                const char *nl = strchr(p, '\n');
                size_t len = nl ? (size_t) (nl - p) : strlen(p);
                size_t i = 0, col = 0;
                if (pass) rs_render_textf(r, "    ");
                while (i < len) {
                    size_t j = i, w;
                    while (j < len && p[j] != ',') j++;
                    w = col < MAXCOL ? width[col] : 17;
                    if (!pass && col < MAXCOL && j - i > w) width[col] = j - i;
                    if (pass) rs_render_textf(r, "%-*.*s ", (int) w, (int) (j - i), p + i);
                    i = j + 1;
                    col++;
                }
                if (pass) rs_render_textf(r, "\n");
                rowsn++;
                p += len + (nl ? 1 : 0);
            }
        }
        if (*p) rs_render_textf(r, "    ... (all rows: --csv FILE)\n");
    }
    rs_render_assigned(r, o);
}

/* Fallback: every member except "analysis" as key: value. */
void rs_render_generic(rs_render_t *r, const json_t *o)
{
    const char *key;
    json_t *val;
    json_object_foreach((json_t *) o, key, val) {
        if (strcmp(key, "analysis") == 0) continue;
        if (json_is_string(val)) rs_render_line(r, key, "%s", json_string_value(val));
        else {
            char *s = json_dumps(val, JSON_COMPACT | JSON_ENCODE_ANY);
            rs_render_line(r, key, "%s", s);
            free(s);
        }
    }
}

