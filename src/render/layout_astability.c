/* layout_astability.c -- the layout of `analyse astability`: the text report
 * keeps its key/value lines (rs_render_generic); the derivations read the
 * same document as a textbook would argue: the boundary locus, A-stability
 * with the proof that decided it (or the counterexample), the A(alpha) angle,
 * the real and imaginary stability intervals with their exact ends, the limit
 * at infinity and L-stability. */
#include <stdlib.h>
#include <string.h>
#include "render_impl.h"

#define js rs_render_jstr

/* a JSON number or string as text (integers, rationals "p/q", "-inf") */
static void num_str(char *buf, size_t n, const json_t *v)
{
    if (json_is_integer(v)) snprintf(buf, n, "%lld", (long long) json_integer_value(v));
    else if (json_is_real(v)) snprintf(buf, n, "%.17g", json_real_value(v));
    else if (json_is_string(v)) snprintf(buf, n, "%s", json_string_value(v));
    else snprintf(buf, n, "?");
}

/* an end over Q(sqrt d) is the string "root of MINPOLY in [LO, HI]"
 * (rs_qd_end_get_str): 1 and its parts (free them), else 0 */
static int qd_end_parse(const char *s, char **mp, char **lo, char **hi)
{
    const char *in, *comma, *close;
    if (s == NULL || strncmp(s, "root of ", 8) != 0 || (in = strstr(s, " in [")) == NULL
        || (comma = strstr(in, ", ")) == NULL || (close = strrchr(comma, ']')) == NULL)
        return 0;
    *mp = strndup(s + 8, (size_t) (in - s - 8));
    *lo = strndup(in + 5, (size_t) (comma - in - 5));
    *hi = strndup(comma + 2, (size_t) (close - comma - 2));
    return 1;
}

/* the digits LO and HI share (a truncation of every number between them),
 * when they share one after the point; else LO */
static char *qd_end_digits(const char *lo, const char *hi)
{
    size_t n = 0;
    const char *dot = strchr(lo, '.');
    if (strchr(lo, 'e') != NULL || strchr(hi, 'e') != NULL || dot == NULL || lo[0] != hi[0]) return strdup(lo);
    while (lo[n] != '\0' && lo[n] == hi[n]) n++;
    if (n <= (size_t) (dot - lo) + 1) return strdup(lo);
    return strndup(lo, n);
}

/* one end of an interval inside math already opened: +-infinity, a rational,
 * or an algebraic number by its certified digits (its definition follows the
 * interval, in ends_defined) */
static void interval_end(rs_render_t *r, const json_t *e, int hi)
{
    char buf[64], *mp, *lo, *up;
    const char *s = json_is_string(e) ? json_string_value(e) : NULL;
    if (e == NULL || json_is_null(e) || (s && strcmp(s, hi ? "inf" : "-inf") == 0)) {
        rs_render_say(r, hi ? "\\infty" : "-\\infty", hi ? "\\infty" : "-\\infty");
        return;
    }
    if (qd_end_parse(s, &mp, &lo, &up)) {
        /* the shared digits, then "\\ldots" (the root lies in [lo, up]) */
        char *dg = qd_end_digits(lo, up);
        rs_render_poly(r, dg);
        if (strcmp(dg, lo) != 0) rs_render_say(r, "\\ldots", "\\ldots");
        free(dg); free(mp); free(lo); free(up);
        return;
    }
    if (json_is_object(e)) {
        if (js(e, "minpoly") == NULL && js(e, "exact") != NULL) rs_render_poly(r, js(e, "exact"));
        else rs_render_poly(r, js(e, "certified") ? js(e, "certified") : js(e, "exact"));
        return;
    }
    num_str(buf, sizeof buf, e);
    rs_render_poly(r, buf);
}

/* "where X is the real root k (ascending) of P" for each algebraic end */
static void ends_defined(rs_render_t *r, const json_t *iv)
{
    size_t i;
    int first = 1;
    for (i = 0; i < json_array_size(iv); i++) {
        const json_t *e = json_array_get(iv, i);
        const char *ex = js(e, "exact"), *mp = js(e, "minpoly"), *of;
        char *qmp, *qlo, *qhi;
        if (json_is_string(e) && qd_end_parse(json_string_value(e), &qmp, &qlo, &qhi)) {
            /* over Q(sqrt d): the root of the norm polynomial in [lo, hi] */
            char *dg = qd_end_digits(qlo, qhi);
            if (i == 1 && json_equal(e, json_array_get(iv, 0))) { free(dg); free(qmp); free(qlo); free(qhi); continue; }
            rs_render_say(r, first ? " where $" : "; $", first ? " where $" : "; $");
            rs_render_poly(r, dg);
            if (strcmp(dg, qlo) != 0) rs_render_say(r, "\\ldots", "\\ldots");
            rs_render_say(r, "$ stands for the root of $", "$ stands for the root of $");
            rs_render_poly(r, qmp);
            rs_render_say(r, "$ (in $x$) in $[", "$ (in $x$) in $[");
            rs_render_poly(r, qlo);
            rs_render_say(r, ", ", ", ");
            rs_render_poly(r, qhi);
            rs_render_say(r, "]$", "]$");
            free(dg); free(qmp); free(qlo); free(qhi);
            first = 0;
            continue;
        }
        if (!json_is_object(e) || mp == NULL || ex == NULL) continue;
        if (i == 1 && json_equal(e, json_array_get(iv, 0))) continue;
        of = strstr(ex, " of ");
        rs_render_say(r, first ? " where $" : "; $", first ? " where $" : "; $");
        rs_render_poly(r, js(e, "certified") ? js(e, "certified") : "?");
        rs_render_say(r, "$ stands for the ", "$ stands for the ");
        if (of != NULL) {
            char *pre = strndup(ex, (size_t) (of - ex));
            rs_render_esc(r, pre);
            free(pre);
        } else rs_render_esc(r, "root");
        rs_render_say(r, " of $", " of $");
        rs_render_poly(r, mp);
        rs_render_say(r, "$", "$");
        first = 0;
    }
}

/* "q in (-inf, 0]" from the interval and its detail (open/closed ends) */
static void interval(rs_render_t *r, const json_t *o, const char *key, const char *lead, const char *var)
{
    char dk[64];
    const json_t *iv = json_object_get(o, key), *d;
    snprintf(dk, sizeof dk, "%s_detail", key);
    d = json_object_get(o, dk);
    if (!json_is_array(iv) || json_is_true(json_object_get(d, "empty"))) {
        rs_render_say(r, lead, lead);
        rs_render_say(r, " is empty: no point of it is stable.\n\n", " is empty: no point of it is stable.\n\n");
        return;
    }
    rs_render_say(r, lead, lead);
    rs_render_say(r, " is $", " is $");
    rs_render_poly(r, var);
    rs_render_say(r, " \\in ", " \\in ");
    rs_render_say(r, json_is_true(json_object_get(d, "lo_closed")) ? "[" : "(",
                  json_is_true(json_object_get(d, "lo_closed")) ? "[" : "(");
    interval_end(r, json_array_get(iv, 0), 0);
    rs_render_say(r, ", ", ", ");
    interval_end(r, json_array_get(iv, 1), 1);
    rs_render_say(r, json_is_true(json_object_get(d, "hi_closed")) ? "]$" : ")$",
                  json_is_true(json_object_get(d, "hi_closed")) ? "]$" : ")$");
    ends_defined(r, iv);
    if (json_is_false(json_object_get(d, "ends_decided")))
        rs_render_say(r, " (whether an end itself is stable is not decided)",
                      " (whether an end itself is stable is not decided)");
    rs_render_say(r, ".\n\n", ".\n\n");
}

/* the boundary locus: q as a function of lambda = exp(i phi), or p(lambda, q) = 0 on the circle */
static void locus(rs_render_t *r, const json_t *o, const char *q)
{
    const char *b = js(o, "boundary_locus"), *cut, *p;
    const json_t *bt = json_object_get(o, "boundary_locus_t");
    if (b == NULL) return;
    rs_render_say(r, "*Boundary locus.* A root crosses the unit circle only where $\\lambda = e^{i\\varphi}$ "
                     "is a root, so the boundary of the stability region lies on the curve ",
                  "\\emph{Boundary locus.} A root crosses the unit circle only where $\\lambda = e^{i\\varphi}$ "
                  "is a root, so the boundary of the stability region lies on the curve ");
    if ((p = strstr(b, ", p = ")) != NULL && strncmp(b, "p(lambda", 8) == 0) {
        rs_render_say(r, "$p(\\lambda, ", "$p(\\lambda, ");
        rs_render_poly(r, q);
        rs_render_say(r, ") = 0$, $0 \\le \\varphi < 2\\pi$, with $p = ", ") = 0$, $0 \\le \\varphi < 2\\pi$, with $p = ");
        rs_render_poly(r, p + 6);
        rs_render_say(r, "$.", "$.");
    } else if ((cut = strstr(b, ", lambda = exp(i*phi)")) != NULL) {
        char *lhs = strndup(b, (size_t) (cut - b));
        rs_render_say(r, "$", "$");
        rs_render_poly(r, lhs);
        rs_render_say(r, "$, $\\lambda = e^{i\\varphi}$, $0 \\le \\varphi < 2\\pi$ ($p$ is linear in $",
                      "$, $\\lambda = e^{i\\varphi}$, $0 \\le \\varphi < 2\\pi$ ($p$ is linear in $");
        rs_render_poly(r, q);
        rs_render_say(r, "$, so $p = 0$ is solved for it).", "$, so $p = 0$ is solved for it).");
        free(lhs);
    } else {
        rs_render_code(r, b);
        rs_render_say(r, ".", ".");
    }
    if (js(bt, "re_numerator") && js(bt, "im_numerator")) {
        rs_render_say(r, " With $t = \\tan(\\varphi/2)$ it is rational in $t$: over a common positive denominator "
                         "the numerator of $\\operatorname{Re}",
                      " With $t = \\tan(\\varphi/2)$ it is rational in $t$: over a common positive denominator "
                      "the numerator of $\\operatorname{Re}");
        rs_render_poly(r, q);
        rs_render_say(r, "$ is $", "$ is $");
        rs_render_poly(r, js(bt, "re_numerator"));
        rs_render_say(r, "$ and that of $\\operatorname{Im}", "$ and that of $\\operatorname{Im}");
        rs_render_poly(r, q);
        rs_render_say(r, "$ is $", "$ is $");
        rs_render_poly(r, js(bt, "im_numerator"));
        rs_render_say(r, "$.", "$.");
    }
    rs_render_say(r, "\n\n", "\n\n");
}

/* a point q = re + i im of the evidence, as math */
static void point(rs_render_t *r, const json_t *c, const char *q)
{
    char re[128], im[128];
    num_str(re, sizeof re, json_object_get(c, "re"));
    num_str(im, sizeof im, json_object_get(c, "im"));
    rs_render_say(r, "$", "$");
    rs_render_poly(r, q);
    rs_render_say(r, " = ", " = ");
    rs_render_poly(r, re);
    if (im[0] == '-') {
        rs_render_say(r, " - ", " - ");
        rs_render_poly(r, im + 1);
    } else {
        rs_render_say(r, " + ", " + ");
        rs_render_poly(r, im);
    }
    rs_render_say(r, "\\,i$", "\\,i$");
}

/* one route of the A-stability decision: the proof, or why it fails */
static void evidence(rs_render_t *r, const json_t *e, const char *q)
{
    const char *route = js(e, "route");
    const json_t *c = json_object_get(e, "counterexample");
    rs_render_item_begin(r);
    if (route && strncmp(route, "boundary locus", 14) == 0) {
        rs_render_say(r, "*Boundary locus route* (Hairer–Wanner II, §V.1): ",
                      "\\emph{Boundary locus route} (Hairer--Wanner II, \\S V.1): ");
        if (json_is_true(json_object_get(e, "re_locus_nonnegative"))
            && json_is_true(json_object_get(e, "lambda_minus_one_point_ok"))
            && json_is_true(json_object_get(e, "leading_coefficient_zero_ok"))) {
            rs_render_say(r, "the numerator of $\\operatorname{Re}", "the numerator of $\\operatorname{Re}");
            rs_render_poly(r, q);
            rs_render_say(r, "(t)$ is $\\ge 0$ for every real $t$ (decided exactly), and neither the point "
                             "$\\lambda = -1$ ($t = \\infty$) nor a zero of the leading coefficient lies in "
                             "$\\operatorname{Re}",
                          "(t)$ is $\\ge 0$ for every real $t$ (decided exactly), and neither the point "
                          "$\\lambda = -1$ ($t = \\infty$) nor a zero of the leading coefficient lies in "
                          "$\\operatorname{Re}");
            rs_render_poly(r, q);
            rs_render_say(r, " < 0$: the open left half-plane meets no boundary point, so it is one region "
                             "of constant root counts; at $",
                          " < 0$: the open left half-plane meets no boundary point, so it is one region "
                          "of constant root counts; at $");
            rs_render_poly(r, q);
            rs_render_sayf(r, " = -1$ the scheme is **%s**, hence so is every point of it.",
                           " = -1$ the scheme is \\textbf{%s}, hence so is every point of it.",
                           js(e, "status_at_minus_one") ? js(e, "status_at_minus_one") : "?");
        } else {
            if (json_is_false(json_object_get(e, "re_locus_nonnegative"))) {
                rs_render_say(r, "the locus enters $\\operatorname{Re}", "the locus enters $\\operatorname{Re}");
                rs_render_poly(r, q);
                rs_render_say(r, " < 0$", " < 0$");
                if (js(e, "t") || json_is_integer(json_object_get(e, "t"))) {
                    char t[64];
                    num_str(t, sizeof t, json_object_get(e, "t"));
                    rs_render_say(r, " (at $t = ", " (at $t = ");
                    rs_render_poly(r, t);
                    rs_render_say(r, "$)", "$)");
                }
            } else if (json_is_false(json_object_get(e, "lambda_minus_one_point_ok")))
                rs_render_say(r, "the point of $\\lambda = -1$ lies in the open left half-plane",
                              "the point of $\\lambda = -1$ lies in the open left half-plane");
            else if (json_is_false(json_object_get(e, "leading_coefficient_zero_ok")))
                rs_render_say(r, "a zero of the leading coefficient lies in the open left half-plane",
                              "a zero of the leading coefficient lies in the open left half-plane");
            else
                rs_render_sayf(r, "the scheme is %s at $q = -1$", "the scheme is %s at $q = -1$",
                               js(e, "status_at_minus_one") ? js(e, "status_at_minus_one") : "?");
            if (json_is_object(c)) {
                rs_render_say(r, "; at ", "; at ");
                point(r, c, q);
                rs_render_sayf(r, " the scheme is exactly **%s**", " the scheme is exactly \\textbf{%s}",
                               js(c, "status") ? js(c, "status") : "?");
            }
            rs_render_say(r, ".", ".");
        }
    } else if (route && strncmp(route, "E-polynomial", 12) == 0) {
        rs_render_say(r, "*E-polynomial route* (one-step method, $R = N/D$; Hairer–Wanner II, §IV.3): "
                         "$E(y) = |D(iy)|^2 - |N(iy)|^2 = ",
                      "\\emph{E-polynomial route} (one-step method, $R = N/D$; Hairer--Wanner II, \\S IV.3): "
                      "$E(y) = |D(iy)|^2 - |N(iy)|^2 = ");
        rs_render_poly(r, js(e, "E"));
        if (json_is_true(json_object_get(e, "E_nonnegative")))
            rs_render_say(r, " \\ge 0$ for every real $y$ (so $|R| \\le 1$ on the imaginary axis)",
                          " \\ge 0$ for every real $y$ (so $|R| \\le 1$ on the imaginary axis)");
        else {
            char y[64];
            /* over Q: "counterexample_imag"; over Q(sqrt d): "E_negative_at" */
            num_str(y, sizeof y, json_object_get(e, json_object_get(e, "counterexample_imag") != NULL
                                                    ? "counterexample_imag" : "E_negative_at"));
            rs_render_say(r, "$ is negative at $y = ", "$ is negative at $y = ");
            rs_render_poly(r, y);
            rs_render_say(r, "$, where $|R(iy)| > 1$", "$, where $|R(iy)| > 1$");
        }
        if (json_is_true(json_object_get(e, "poles_in_right_half_plane")))
            rs_render_say(r, "; every pole of $R$ lies in $\\operatorname{Re}", "; every pole of $R$ lies in $\\operatorname{Re}");
        else
            rs_render_say(r, "; some pole of $R$ lies in $\\operatorname{Re}", "; some pole of $R$ lies in $\\operatorname{Re}");
        rs_render_poly(r, q);
        if (json_is_true(json_object_get(e, "poles_in_right_half_plane")))
            rs_render_say(r, " > 0$", " > 0$");
        else
            rs_render_say(r, " \\le 0$", " \\le 0$");
        if (json_is_true(json_object_get(e, "E_nonnegative")) && json_is_true(json_object_get(e, "poles_in_right_half_plane")))
            rs_render_say(r, ": $R$ is analytic in the left half-plane and, by the maximum principle, "
                             "$|R| \\le 1$ there.",
                          ": $R$ is analytic in the left half-plane and, by the maximum principle, "
                          "$|R| \\le 1$ there.");
        else rs_render_say(r, ".", ".");
    } else if (route && strncmp(route, "any method: rays", 16) == 0) {
        const json_t *fp = json_object_get(e, "first_point_outside");
        rs_render_say(r, "*Rays route* (any $p$): on the rays $", "\\emph{Rays route} (any $p$): on the rays $");
        rs_render_poly(r, q);
        rs_render_say(r, " = -s\\,(1 - i\\,u)$, $s > 0$, a root meets the unit circle only on curves in $(s, u)$ "
                         "(the resultant in $t$ of the real and imaginary parts of the bilinear transform, and "
                         "$\\lambda = -1$); ",
                      " = -s\\,(1 - i\\,u)$, $s > 0$, a root meets the unit circle only on curves in $(s, u)$ "
                      "(the resultant in $t$ of the real and imaginary parts of the bilinear transform, and "
                      "$\\lambda = -1$); ");
        rs_render_sayf(r, "their %lld critical values of $u > 0$ bound the cells, %lld of them decided exactly on "
                          "rational points of one ray",
                       "their %lld critical values of $u > 0$ bound the cells, %lld of them decided exactly on "
                       "rational points of one ray",
                       (long long) json_integer_value(json_object_get(e, "critical_u")),
                       (long long) json_integer_value(json_object_get(e, "cells_decided")));
        if (json_is_object(fp)) {
            rs_render_say(r, "; at ", "; at ");
            point(r, fp, q);
            rs_render_sayf(r, " the scheme is exactly **%s**.", " the scheme is exactly \\textbf{%s}.",
                           js(fp, "status") ? js(fp, "status") : "?");
        } else rs_render_say(r, ": every ray of the open left half-plane lies in the region.",
                             ": every ray of the open left half-plane lies in the region.");
    } else {
        rs_render_code(r, route ? route : "?");
    }
    rs_render_item_end(r);
}

static void alpha(rs_render_t *r, const json_t *o, const char *q)
{
    const json_t *a = json_object_get(o, "alpha_degrees"), *ap = json_object_get(o, "alpha_degrees_approx");
    rs_render_say(r, "*A($\\alpha$).* ", "\\emph{$A(\\alpha)$.} ");
    if (json_is_integer(a)) {
        rs_render_sayf(r, "$\\alpha = %lld^\\circ$ exactly", "$\\alpha = %lld^\\circ$ exactly",
                       (long long) json_integer_value(a));
        if (json_integer_value(a) == 90) rs_render_say(r, " (the whole left half-plane).", " (the whole left half-plane).");
        else rs_render_say(r, ".", ".");
    } else if (json_is_object(a)) {
        char u[64];
        snprintf(u, sizeof u, "%.15g", json_real_value(json_object_get(a, "tan_alpha")));
        rs_render_say(r, "The largest sector $|\\arg(-", "The largest sector $|\\arg(-");
        rs_render_poly(r, q);
        rs_render_say(r, ")| < \\alpha$ inside the region has $\\alpha = \\arctan u$, $u$ the root of $",
                      ")| < \\alpha$ inside the region has $\\alpha = \\arctan u$, $u$ the root of $");
        rs_render_poly(r, js(a, "tan_alpha_minpoly"));
        rs_render_say(r, "$ near $", "$ near $");
        rs_render_poly(r, u);
        rs_render_say(r, "$, so $\\alpha = ", "$, so $\\alpha = ");
        if (js(o, "alpha_degrees_certified")) rs_render_poly(r, js(o, "alpha_degrees_certified"));
        else if (json_is_real(ap)) rs_render_sayf(r, "%.15g", "%.15g", json_real_value(ap));
        rs_render_say(r, "^\\circ$ (certified digits).", "^\\circ$ (certified digits).");
    } else {
        rs_render_say(r, "No angle", "No angle");
    }
    if (js(o, "alpha_note")) {
        rs_render_say(r, json_is_null(a) ? " (" : " (", json_is_null(a) ? " (" : " (");
        rs_render_esc(r, js(o, "alpha_note"));
        rs_render_say(r, ").", ").");
    } else if (json_is_null(a)) rs_render_say(r, ".", ".");
    rs_render_say(r, "\n\n", "\n\n");
}

static void infinity(rs_render_t *r, const json_t *o, const char *q)
{
    const json_t *l = json_object_get(o, "limit_at_infinity"), *ls = json_object_get(o, "l_stable");
    char buf[64];
    rs_render_say(r, "*Limit at infinity.* As $", "\\emph{Limit at infinity.} As $");
    rs_render_poly(r, q);
    rs_render_say(r, " \\to \\infty$, ", " \\to \\infty$, ");
    if (json_is_string(l) && strcmp(json_string_value(l), "inf") == 0)
        rs_render_say(r, "some root tends to infinity (the leading coefficient in $\\lambda$ loses degree).",
                      "some root tends to infinity (the leading coefficient in $\\lambda$ loses degree).");
    else if (json_is_object(l)) {
        rs_render_say(r, "$\\max|\\lambda| \\to ", "$\\max|\\lambda| \\to ");
        rs_render_poly(r, js(l, "certified") ? js(l, "certified") : "?");
        rs_render_say(r, "$, the largest modulus of a root of $", "$, the largest modulus of a root of $");
        rs_render_poly(r, strncmp(js(l, "exact") ? js(l, "exact") : "", "max |root| of ", 14) == 0
                              ? js(l, "exact") + 14 : js(l, "exact") ? js(l, "exact") : "?");
        rs_render_say(r, "$.", "$.");
    } else {
        num_str(buf, sizeof buf, l);
        rs_render_say(r, "$\\max|\\lambda| \\to ", "$\\max|\\lambda| \\to ");
        rs_render_poly(r, buf);
        rs_render_say(r, "$ exactly.", "$ exactly.");
    }
    if (json_is_true(ls))
        rs_render_say(r, " Hence **L-stable**: A-stable, and every root tends to 0 (stiff decay).",
                      " Hence \\textbf{L-stable}: A-stable, and every root tends to 0 (stiff decay).");
    else if (json_is_false(ls))
        rs_render_say(r, json_is_true(json_object_get(o, "a_stable")) ? " Hence **not L-stable**: the limit is not 0."
                                                                      : " Hence **not L-stable** (not A-stable).",
                      json_is_true(json_object_get(o, "a_stable")) ? " Hence \\textbf{not L-stable}: the limit is not 0."
                                                                   : " Hence \\textbf{not L-stable} (not A-stable).");
    else rs_render_say(r, " L-stability is not decided.", " L-stability is not decided.");
    rs_render_say(r, "\n\n", "\n\n");
}

/* The text report's lines (rs_render_generic), alpha_degrees said as the
 * derivation says it (exact form, then the certified digits) instead of
 * its raw JSON object. */
static void report_lines(rs_render_t *r, const json_t *o)
{
    const json_t *a = json_object_get(o, "alpha_degrees"), *ap = json_object_get(o, "alpha_degrees_approx");
    json_t *c;
    char buf[512], deg[64];
    if (r->be->kind != RS_RENDER_TEXT || !json_is_object(a)) {
        rs_render_generic(r, o);
        return;
    }
    if (js(o, "alpha_degrees_certified")) snprintf(deg, sizeof deg, "%s (certified digits)",
                                                   js(o, "alpha_degrees_certified"));
    else snprintf(deg, sizeof deg, "%.15g (approx)", json_real_value(ap));
    snprintf(buf, sizeof buf, "(180/pi) atan(u) = %s, u = tan(alpha) the root of %s near %.15g", deg,
             js(a, "tan_alpha_minpoly") ? js(a, "tan_alpha_minpoly") : "?",
             json_real_value(json_object_get(a, "tan_alpha")));
    c = json_copy((json_t *) o);   /* shallow: the other values shared; key order kept */
    json_object_set_new(c, "alpha_degrees", json_string(buf));
    rs_render_generic(r, c);
    json_decref(c);
}

void rs_render_astability(rs_render_t *r, const json_t *o)
{
    const char *q = js(o, "param") ? js(o, "param") : "z";
    const json_t *sub = json_object_get(o, "substituted"), *ev = json_object_get(o, "evidence");
    const json_t *as = json_object_get(o, "a_stable"), *val;
    const char *key;
    size_t i;
    int first = 1;
    report_lines(r, o);
    if (!(r->be->kind & RS_RENDER_PROSE)) return;
    rs_render_heading_begin(r);
    rs_render_say(r, "Stability region of $y' = ", "Stability region of $y' = ");
    rs_render_poly(r, q);
    rs_render_say(r, "\\,y$ (A-stability)", "\\,y$ (A-stability)");
    rs_render_heading_end(r);
    rs_render_say(r, "The scheme applied to the test equation with $", "The scheme applied to the test equation with $");
    rs_render_poly(r, q);
    rs_render_say(r, " \\in \\mathbb{C}$", " \\in \\mathbf{C}$");
    json_object_foreach((json_t *) sub, key, val) {
        rs_render_say(r, first ? ", at $" : ", $", first ? ", at $" : ", $");
        rs_render_poly(r, key);
        rs_render_say(r, " = ", " = ");
        rs_render_poly(r, json_is_string(val) ? json_string_value(val) : "?");
        rs_render_say(r, "$", "$");
        first = 0;
    }
    if (js(o, "over")) {
        rs_render_say(r, " (coefficients in ", " (coefficients in ");
        rs_render_esc(r, js(o, "over"));
        rs_render_say(r, ")", ")");
    }
    rs_render_say(r, "; its stability region is the set of $", "; its stability region is the set of $");
    rs_render_poly(r, q);
    rs_render_say(r, "$ where the characteristic polynomial $p(\\lambda, ",
                  "$ where the characteristic polynomial $p(\\lambda, ");
    rs_render_poly(r, q);
    rs_render_say(r, ")$ has every root in $|\\lambda| \\le 1$, those on the circle simple.\n\n",
                  ")$ has every root in $|\\lambda| \\le 1$, those on the circle simple.\n\n");
    locus(r, o, q);
    /* A-stability and its proof */
    if (json_is_true(as))
        rs_render_say(r, "*A-stability.* The method is **A-stable**: the closed left half-plane lies in the region.",
                      "\\emph{A-stability.} The method is \\textbf{A-stable}: the closed left half-plane lies in the region.");
    else if (json_is_false(as))
        rs_render_say(r, "*A-stability.* The method is **not A-stable**.",
                      "\\emph{A-stability.} The method is \\textbf{not A-stable}.");
    else {
        rs_render_say(r, "*A-stability.* Not decided", "\\emph{A-stability.} Not decided");
        if (js(o, "a_stable_note")) {
            rs_render_say(r, ": ", ": ");
            rs_render_esc(r, js(o, "a_stable_note"));
        }
        rs_render_say(r, ".", ".");
    }
    if (json_array_size(ev) > 0) {
        const char *lead = json_array_size(ev) > 2 ? " All three routes apply, and they agree:"
                           : json_array_size(ev) > 1 ? " Both routes apply, and they agree:"
                           : json_is_true(as) ? " Proof:" : " Evidence:";
        rs_render_say(r, lead, lead);
        rs_render_say(r, "\n\n", "\n");
        rs_render_list_begin(r);
        for (i = 0; i < json_array_size(ev); i++) evidence(r, json_array_get(ev, i), q);
        rs_render_list_end(r);
        rs_render_say(r, "", "\n");
    } else rs_render_say(r, "\n\n", "\n\n");
    alpha(r, o, q);
    rs_render_say(r, "*Axes.* ", "\\emph{Axes.} ");
    interval(r, o, "real_interval", "The real stability interval", q);
    rs_render_say(r, "The imaginary stability interval (points $", "The imaginary stability interval (points $");
    rs_render_poly(r, q);
    rs_render_say(r, " = i\\,y$)", " = i\\,y$)");
    interval(r, o, "imag_interval", "", "y");
    infinity(r, o, q);
    if (js(o, "decided_by")) {
        rs_render_say(r, "Decided by: ", "Decided by: ");
        rs_render_esc(r, js(o, "decided_by"));
        rs_render_say(r, " arithmetic.\n\n", " arithmetic.\n\n");
    }
}
