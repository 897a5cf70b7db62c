/* derivation.c -- Markdown and LaTeX derivations from result documents. */
#include <ctype.h>
#include <string.h>
#include "recstab/derivation.h"

static const char *js(const json_t *o, const char *k)
{
    const json_t *v = json_object_get(o, k);
    return json_is_string(v) ? json_string_value(v) : NULL;
}

static long long ji(const json_t *o, const char *k)
{
    return (long long) json_integer_value(json_object_get(o, k));
}

/* ---- LaTeX formatting of expressions ---------------------------------------- */

static const char *const greek[] = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta",
                                    "kappa", "lambda", "mu", "nu", "xi", "pi", "rho", "sigma", "tau",
                                    "phi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda",
                                    "Xi", "Pi", "Sigma", "Phi", "Psi", "Omega", NULL};

static void tex_name(FILE *out, const char *n, size_t len)
{
    char buf[80];
    size_t i;
    if (len >= sizeof buf) len = sizeof buf - 1;
    memcpy(buf, n, len);
    buf[len] = '\0';
    for (i = 0; greek[i]; i++)
        if (strcmp(buf, greek[i]) == 0) { fprintf(out, "\\%s", buf); return; }
    if (len == 1) { fputs(buf, out); return; }
    fputs("\\mathit{", out);
    for (i = 0; i < len; i++) {
        if (buf[i] == '_') fputs("\\_", out);
        else fputc(buf[i], out);
    }
    fputc('}', out);
}

void rs_derivation_tex_poly(FILE *out, const char *s)
{
    size_t i = 0, n = strlen(s);
    int prev_num = 0;
    while (i < n) {
        char ch = s[i];
        if (isdigit((unsigned char) ch)) {
            size_t j = i, k;
            while (j < n && isdigit((unsigned char) s[j])) j++;
            if (j < n && s[j] == '/' && j + 1 < n && isdigit((unsigned char) s[j + 1])) {
                k = j + 1;
                while (k < n && isdigit((unsigned char) s[k])) k++;
                fprintf(out, "\\tfrac{%.*s}{%.*s}", (int) (j - i), s + i, (int) (k - j - 1), s + j + 1);
                i = k;
            } else {
                fprintf(out, "%.*s", (int) (j - i), s + i);
                i = j;
            }
            prev_num = 1;
            continue;
        }
        if (isalpha((unsigned char) ch) || ch == '_') {
            size_t j = i;
            while (j < n && (isalnum((unsigned char) s[j]) || s[j] == '_')) j++;
            tex_name(out, s + i, j - i);
            i = j;
            prev_num = 0;
            continue;
        }
        if (ch == '^') {
            size_t j = i + 1;
            if (j < n && s[j] == '-') j++;
            while (j < n && isalnum((unsigned char) s[j])) j++;
            fprintf(out, "^{%.*s}", (int) (j - i - 1), s + i + 1);
            i = j;
            continue;
        }
        if (ch == '*') {
            fputs(i + 1 < n && isdigit((unsigned char) s[i + 1]) && prev_num ? " \\cdot " : "\\,", out);
            i++;
            continue;
        }
        if (ch == '!' && i + 1 < n && s[i + 1] == '=') { fputs(" \\neq ", out); i += 2; continue; }
        if (ch == '>' && i + 1 < n && s[i + 1] == '=') { fputs(" \\geq ", out); i += 2; continue; }
        if (ch == '<' && i + 1 < n && s[i + 1] == '=') { fputs(" \\leq ", out); i += 2; continue; }
        if (ch == '[') { fputs("_{", out); i++; continue; }
        if (ch == ']') { fputs("}", out); i++; continue; }
        if (ch == '#' || ch == '%' || ch == '&' || ch == '$' || ch == '{' || ch == '}') {
            fprintf(out, "\\%c", ch);
            i++;
            continue;
        }
        if (ch == '\\' || ch == '~') { i++; continue; }
        fputc(ch, out);
        prev_num = 0;
        i++;
    }
}

static void tex_text(FILE *out, const char *s)
{
    for (; s && *s; s++) {
        switch (*s) {
        case '#': case '%': case '&': case '$': case '_': case '{': case '}':
            fprintf(out, "\\%c", *s); break;
        case '\\': fputs("\\textbackslash{}", out); break;
        case '^': fputs("\\^{}", out); break;
        case '~': fputs("\\~{}", out); break;
        case '<': fputs("$<$", out); break;
        case '>': fputs("$>$", out); break;
        default:
            if ((unsigned char) *s < 128) fputc(*s, out);
            else fputc('?', out);
        }
    }
}

static void tex_math(FILE *out, const char *s)
{
    fputc('$', out);
    rs_derivation_tex_poly(out, s ? s : "");
    fputc('$', out);
}

/* endpoint: rational string, algebraic object, or null */
static const char *endpoint(const json_t *e, int hi)
{
    if (e == NULL || json_is_null(e)) return hi ? "inf" : "-inf";
    if (json_is_string(e)) return json_string_value(e);
    return js(e, "approx");
}

/* ---- LaTeX ------------------------------------------------------------------- */

void rs_derivation_latex_begin(FILE *out)
{
    fputs("\\documentclass[10pt]{article}\n"
          "\\usepackage{amsmath}\n"
          "\\setlength{\\textwidth}{16cm}\\setlength{\\oddsidemargin}{0cm}\n"
          "\\setlength{\\textheight}{23cm}\\setlength{\\topmargin}{-1cm}\n"
          "\\setlength{\\parindent}{0pt}\\setlength{\\parskip}{4pt}\n"
          "\\sloppy\n"
          "\\begin{document}\n", out);
}

void rs_derivation_latex_end(FILE *out)
{
    fputs("\\end{document}\n", out);
}

static void latex_count(FILE *out, const json_t *o)
{
    fprintf(out, "Verdict: \\textbf{%s}: %lld roots inside, %lld on, %lld outside the unit circle",
            js(o, "status"), ji(o, "inside"), ji(o, "on"), ji(o, "outside"));
    if (ji(o, "at_one")) fprintf(out, "; $\\lambda = 1$ with multiplicity %lld", ji(o, "at_one"));
    if (ji(o, "at_minus_one")) fprintf(out, "; $\\lambda = -1$ with multiplicity %lld", ji(o, "at_minus_one"));
    fputs(".\n\n", out);
}

/* "never" (no branch can hold) or "branches" (an OR of condition lists) of
 * a hurwitz/region result; 1 if printed, 0 if the result has neither. */
static int tex_branches(FILE *out, const json_t *o)
{
    const json_t *br = json_object_get(o, "branches");
    size_t i, j;
    if (js(o, "never") != NULL) {
        tex_text(out, js(o, "never"));
        fputs(".\n\n", out);
        return 1;
    }
    if (!json_is_array(br)) return 0;
    fputs("All $|\\lambda| < 1$ if and only if every condition of one branch holds (the sign of the leading "
          "coefficient of $q$ is not fixed by the assumptions):\n\\begin{itemize}\n", out);
    for (i = 0; i < json_array_size(br); i++) {
        fprintf(out, "\\item %s: ", i == 0 ? "either" : "or");
        for (j = 0; j < json_array_size(json_array_get(br, i)); j++) {
            if (j) fputs(", ", out);
            tex_math(out, json_string_value(json_array_get(json_array_get(br, i), j)));
        }
        fputc('\n', out);
    }
    fputs("\\end{itemize}\n", out);
    return 1;
}

static void latex_rows(FILE *out, const json_t *rows)
{
    size_t i, j, w = 0;
    for (i = 0; i < json_array_size(rows); i++)
        if (json_array_size(json_array_get(rows, i)) > w) w = json_array_size(json_array_get(rows, i));
    fputs("\\[\\begin{array}{r|", out);
    for (j = 0; j < w; j++) fputc('l', out);
    fputs("}\n", out);
    for (i = 0; i < json_array_size(rows); i++) {
        const json_t *row = json_array_get(rows, i);
        fprintf(out, "z^{%zu}", json_array_size(rows) - 1 - i);
        for (j = 0; j < w; j++) {
            fputs(" & ", out);
            if (j < json_array_size(row)) rs_derivation_tex_poly(out, json_string_value(json_array_get(row, j)));
        }
        fputs(" \\\\\n", out);
    }
    fputs("\\end{array}\\]\n", out);
}

static void latex_result(FILE *out, const json_t *o)
{
    const char *a = js(o, "analysis");
    size_t i;
    if (a == NULL) return;
    if (strcmp(a, "charpoly") == 0) {
        fputs("\\subsection*{Characteristic polynomial}\n"
              "The determinant of the $\\lambda$-matrix, computed fraction-free", out);
        if (ji(o, "removed_lambda_power") > 0)
            fprintf(out, ", with the factor $\\lambda^{%lld}$ (roots at 0) divided out", ji(o, "removed_lambda_power"));
        fputs(":\n\n$p(\\lambda) = ", out);
        rs_derivation_tex_poly(out, js(o, "poly"));
        fprintf(out, "$\n\n(degree %lld, content %s).\n\n", ji(o, "degree"), js(o, "content"));
    } else if (strcmp(a, "bilinear") == 0) {
        fputs("\\subsection*{Bilinear transform}\n"
              "With $\\lambda = \\frac{1+z}{1-z}$, $|\\lambda| < 1 \\iff \\operatorname{Re} z < 0$; "
              "$q(z) = (1-z)^n\\, p\\!\\left(\\frac{1+z}{1-z}\\right)$:\n\n$q(z) = ", out);
        rs_derivation_tex_poly(out, js(o, "poly"));
        fprintf(out, "$\n\nDegree drop %lld (roots at $\\lambda=-1$), $z=0$ of multiplicity %lld (roots at "
                     "$\\lambda = 1$); $p(1) = ", ji(o, "degree_drop"), ji(o, "zero_mult"));
        rs_derivation_tex_poly(out, js(o, "p_at_1"));
        fputs("$, $p(-1) = ", out);
        rs_derivation_tex_poly(out, js(o, "p_at_minus_1"));
        fputs("$.\n\n", out);
    } else if (strcmp(a, "routh") == 0) {
        const json_t *ev = json_object_get(o, "events");
        fputs("\\subsection*{Routh array of $q(z)$}\n", out);
        latex_rows(out, json_object_get(o, "rows"));
        for (i = 0; i < json_array_size(ev); i++) {
            fputs("\\emph{Singular step:} ", out);
            tex_text(out, js(json_array_get(ev, i), "text"));
            fputs("\n\n", out);
        }
        if (js(o, "note")) { tex_text(out, js(o, "note")); fputs("\n\n", out); }
        if (js(o, "status")) latex_count(out, o);
    } else if (strcmp(a, "hurwitz") == 0) {
        const json_t *m = json_object_get(o, "minors"), *c = json_object_get(o, "conditions");
        const json_t *d = json_object_get(o, "dropped");
        fputs("\\subsection*{Hurwitz minors and Li\\'enard--Chipart conditions}\n", out);
        for (i = 0; i < json_array_size(m); i++) {
            fprintf(out, "$D_{%zu} = ", i + 1);
            rs_derivation_tex_poly(out, json_string_value(json_array_get(m, i)));
            fputs("$\n\n", out);
        }
        if (!tex_branches(out, o)) {
        fputs("All roots of $q$ have negative real part (all $|\\lambda| < 1$) if and only if:\n\\begin{itemize}\n", out);
        for (i = 0; i < json_array_size(c); i++) {
            fputs("\\item ", out);
            tex_math(out, json_string_value(json_array_get(c, i)));
            fputc('\n', out);
        }
        if (json_array_size(c) == 0) fputs("\\item (every condition holds under the assumptions)\n", out);
        fputs("\\end{itemize}\n", out);
        }
        for (i = 0; i < json_array_size(d); i++) {
            const json_t *e = json_array_get(d, i);
            fputs("Factor ", out);
            tex_math(out, js(e, "factor"));
            fprintf(out, " of $%s$ dropped: ", js(e, "from"));
            tex_text(out, js(e, "reason"));
            fputs(".\n\n", out);
        }
    } else if (strcmp(a, "stability") == 0 || strcmp(a, "jury") == 0) {
        fprintf(out, "\\subsection*{%s}\n", strcmp(a, "jury") == 0 ? "Schur--Cohn test on $p(\\lambda)$"
                                                                     : "Stability at the given values");
        if (json_is_true(json_object_get(o, "symbolic"))) {   /* symbolic Schur-Cohn conditions */
            const json_t *c = json_object_get(o, "conditions");
            fputs("All $|\\lambda| < 1$ if and only if:\n\\begin{itemize}\n", out);
            for (i = 0; i < json_array_size(c); i++) {
                fputs("\\item ", out);
                tex_math(out, json_string_value(json_array_get(c, i)));
                fputc('\n', out);
            }
            fputs("\\end{itemize}\n", out);
            return;
        }
        latex_count(out, o);
    } else if (strcmp(a, "region") == 0) {
        const json_t *iv = json_object_get(o, "intervals");
        fprintf(out, "\\subsection*{Stability region in $");
        rs_derivation_tex_poly(out, js(o, "param"));
        fputs("$}\n", out);
        if (json_is_true(json_object_get(o, "symbolic"))) {
            const json_t *c = json_object_get(o, "conditions");
            if (tex_branches(out, o)) return;
            fputs("Stable if and only if:\n\\begin{itemize}\n", out);
            for (i = 0; i < json_array_size(c); i++) {
                fputs("\\item ", out);
                tex_math(out, json_string_value(json_array_get(c, i)));
                fputc('\n', out);
            }
            fputs("\\end{itemize}\n", out);
            return;
        }
        fputs("\\begin{itemize}\n", out);
        for (i = 0; i < json_array_size(iv); i++) {
            const json_t *e = json_array_get(iv, i);
            fprintf(out, "\\item %s: $", js(e, "status"));
            rs_derivation_tex_poly(out, js(o, "param"));
            fprintf(out, " \\in %s%s, %s%s$", json_is_true(json_object_get(e, "lo_closed")) ? "[" : "(",
                    endpoint(json_object_get(e, "lo"), 0), endpoint(json_object_get(e, "hi"), 1),
                    json_is_true(json_object_get(e, "hi_closed")) ? "]" : ")");
            if (json_is_object(json_object_get(e, "hi"))) {
                fputs(" (upper end: a root of ", out);
                tex_math(out, js(json_object_get(e, "hi"), "minpoly"));
                fputs(")", out);
            }
            fputc('\n', out);
        }
        fputs("\\end{itemize}\n", out);
    } else if (strcmp(a, "limit") == 0) {
        const json_t *r = json_object_get(o, "roots");
        fputs("\\subsection*{Limit $", out);
        rs_derivation_tex_poly(out, js(o, "param"));
        fprintf(out, " \\to %s$}\nThe roots tend to: ", strcmp(js(o, "to"), "inf") == 0 ? "\\infty" : "0");
        for (i = 0; i < json_array_size(r); i++) {
            fprintf(out, "%s", i ? ", " : "");
            tex_math(out, js(json_array_get(r, i), "value"));
            fprintf(out, " ($\\times %lld$)", ji(json_array_get(r, i), "multiplicity"));
        }
        fputs(".\n\n", out);
    } else if (strcmp(a, "claim") == 0 || strcmp(a, "expect") == 0) {
        fputs(strcmp(a, "claim") == 0 ? "\\subsection*{Claim}\n" : "\\subsection*{Printed polynomial}\n", out);
        fputs("\\texttt{", out);
        tex_text(out, js(o, "text"));
        fprintf(out, "}: \\textbf{%s}.\n\n", js(o, "status"));
        if (json_is_object(json_object_get(o, "counterexample"))) {
            const char *k;
            json_t *v;
            int first = 1;
            fputs("Counterexample: $", out);
            json_object_foreach(json_object_get(o, "counterexample"), k, v) {
                if (!first) fputs(",\\ ", out);
                rs_derivation_tex_poly(out, k);
                fputs(" = ", out);
                rs_derivation_tex_poly(out, json_string_value(v));
                first = 0;
            }
            fputs("$. ", out);
            latex_count(out, json_object_get(o, "at_counterexample"));
        }
        if (js(o, "difference") && strcmp(js(o, "difference"), "0") != 0) {
            fputs("Printed minus derived: $", out);
            rs_derivation_tex_poly(out, js(o, "difference"));
            fputs("$.\n\n", out);
        }
        if (json_is_array(json_object_get(o, "certificate"))) {
            const json_t *c = json_object_get(o, "certificate");
            fputs("Certificate: after the substitutions below (each $s \\geq 0$), every coefficient of the "
                  "numerator is non-negative:\n\\begin{itemize}\n", out);
            for (i = 0; i < json_array_size(c); i++) {
                const char *k;
                json_t *v;
                fputs("\\item ", out);
                tex_math(out, js(json_array_get(c, i), "condition"));
                fputs(" $> 0$ with ", out);
                json_object_foreach(json_object_get(json_array_get(c, i), "substitution"), k, v) {
                    fputs("$", out);
                    rs_derivation_tex_poly(out, k);
                    fputs(" = ", out);
                    rs_derivation_tex_poly(out, json_string_value(v));
                    fputs("$ ", out);
                }
                fputc('\n', out);
            }
            fputs("\\end{itemize}\n", out);
        }
    }
}

void rs_derivation_latex(FILE *out, const json_t *doc, int standalone)
{
    const json_t *sc = json_object_get(doc, "scheme"), *res = json_object_get(doc, "results");
    size_t i, j;
    if (standalone) rs_derivation_latex_begin(out);
    fputs("\\section*{", out);
    tex_text(out, js(doc, "title") ? js(doc, "title") : js(doc, "case"));
    fputs("}\n", out);
    if (sc != NULL) {
        const json_t *eqs = json_object_get(sc, "equations"), *lets = json_object_get(sc, "lets");
        const json_t *M = json_object_get(sc, "matrix"), *as = json_object_get(sc, "assume");
        if (json_array_size(as) > 0) {
            fputs("Assumptions: ", out);
            for (i = 0; i < json_array_size(as); i++) {
                if (i) fputs(", ", out);
                tex_math(out, json_string_value(json_array_get(as, i)));
            }
            fputs(".\n\n", out);
        }
        if (json_array_size(eqs) > 0) {
            fputs("\\subsection*{Difference equations}\n\\begin{align*}\n", out);
            for (i = 0; i < json_array_size(lets); i++) {
                rs_derivation_tex_poly(out, json_string_value(json_array_get(lets, i)));
                fputs(" \\\\\n", out);
            }
            for (i = 0; i < json_array_size(eqs); i++) {
                rs_derivation_tex_poly(out, json_string_value(json_array_get(eqs, i)));
                fputs(i + 1 < json_array_size(eqs) ? " \\\\\n" : "\n", out);
            }
            fputs("\\end{align*}\n", out);
            fputs("\\subsection*{The $\\lambda$-matrix}\nWith $x_{n+k} \\mapsto \\lambda^k$ (each row shifted so "
                  "that its lowest power is $\\lambda^0$):\n{\\small\\[\\left(\\begin{array}{", out);
            for (j = 0; j < json_array_size(M); j++) fputc('c', out);
            fputs("}\n", out);
            for (i = 0; i < json_array_size(M); i++) {
                const json_t *row = json_array_get(M, i);
                for (j = 0; j < json_array_size(row); j++) {
                    if (j) fputs(" & ", out);
                    rs_derivation_tex_poly(out, json_string_value(json_array_get(row, j)));
                }
                fputs(" \\\\\n", out);
            }
            fputs("\\end{array}\\right)\\]}\n", out);
        }
    }
    for (i = 0; i < json_array_size(res); i++) latex_result(out, json_array_get(res, i));
    if (standalone) rs_derivation_latex_end(out);
}

/* ---- Markdown ---------------------------------------------------------------- */

static void md_code(FILE *out, const char *s)
{
    fprintf(out, "`%s`", s ? s : "");
}

static void md_count(FILE *out, const json_t *o)
{
    fprintf(out, "Verdict: **%s** — %lld roots inside, %lld on, %lld outside the unit circle", js(o, "status"),
            ji(o, "inside"), ji(o, "on"), ji(o, "outside"));
    if (ji(o, "at_one")) fprintf(out, "; lambda = 1 (x%lld)", ji(o, "at_one"));
    if (ji(o, "at_minus_one")) fprintf(out, "; lambda = -1 (x%lld)", ji(o, "at_minus_one"));
    fputs(".\n\n", out);
}

/* Markdown form of tex_branches. */
static int md_branches(FILE *out, const json_t *o)
{
    const json_t *br = json_object_get(o, "branches");
    size_t i, j;
    if (js(o, "never") != NULL) {
        fprintf(out, "%s.\n\n", js(o, "never"));
        return 1;
    }
    if (!json_is_array(br)) return 0;
    fputs("All |lambda| < 1 if and only if every condition of one branch holds (the sign of the leading "
          "coefficient of q is not fixed by the assumptions):\n\n", out);
    for (i = 0; i < json_array_size(br); i++) {
        fputs(i == 0 ? "- either: " : "- or: ", out);
        for (j = 0; j < json_array_size(json_array_get(br, i)); j++) {
            if (j) fputs(", ", out);
            md_code(out, json_string_value(json_array_get(json_array_get(br, i), j)));
        }
        fputc('\n', out);
    }
    fputc('\n', out);
    return 1;
}

static void md_result(FILE *out, const json_t *o)
{
    const char *a = js(o, "analysis");
    size_t i, j;
    if (a == NULL) return;
    if (strcmp(a, "charpoly") == 0) {
        fputs("### Characteristic polynomial\n\np(lambda) = det of the lambda-matrix (fraction-free)", out);
        if (ji(o, "removed_lambda_power") > 0)
            fprintf(out, ", lambda^%lld (roots at 0) divided out", ji(o, "removed_lambda_power"));
        fputs(":\n\n    p(lambda) = ", out);
        fputs(js(o, "poly"), out);
        fprintf(out, "\n\ndegree %lld, content %s.\n\n", ji(o, "degree"), js(o, "content"));
    } else if (strcmp(a, "bilinear") == 0) {
        fputs("### Bilinear transform\n\nlambda = (1+z)/(1-z) maps |lambda| < 1 onto Re z < 0; "
              "q(z) = (1-z)^n p((1+z)/(1-z)):\n\n    q(z) = ", out);
        fputs(js(o, "poly"), out);
        fprintf(out, "\n\ndegree drop %lld (roots at lambda = -1), z = 0 of multiplicity %lld (roots at lambda = 1); "
                     "p(1) = ", ji(o, "degree_drop"), ji(o, "zero_mult"));
        md_code(out, js(o, "p_at_1"));
        fputs(", p(-1) = ", out);
        md_code(out, js(o, "p_at_minus_1"));
        fputs(".\n\n", out);
    } else if (strcmp(a, "routh") == 0) {
        const json_t *rows = json_object_get(o, "rows"), *ev = json_object_get(o, "events");
        size_t w = 0;
        fputs("### Routh array of q(z)\n\n", out);
        for (i = 0; i < json_array_size(rows); i++)
            if (json_array_size(json_array_get(rows, i)) > w) w = json_array_size(json_array_get(rows, i));
        fputs("| row |", out);
        for (j = 0; j < w; j++) fprintf(out, " %zu |", j + 1);
        fputs("\n|---|", out);
        for (j = 0; j < w; j++) fputs("---|", out);
        fputc('\n', out);
        for (i = 0; i < json_array_size(rows); i++) {
            const json_t *row = json_array_get(rows, i);
            fprintf(out, "| z^%zu |", json_array_size(rows) - 1 - i);
            for (j = 0; j < w; j++) {
                fputc(' ', out);
                if (j < json_array_size(row)) md_code(out, json_string_value(json_array_get(row, j)));
                fputs(" |", out);
            }
            fputc('\n', out);
        }
        fputc('\n', out);
        for (i = 0; i < json_array_size(ev); i++)
            fprintf(out, "*Singular step (%s):* %s\n\n", js(json_array_get(ev, i), "kind"), js(json_array_get(ev, i), "text"));
        if (js(o, "note")) fprintf(out, "%s\n\n", js(o, "note"));
        if (js(o, "status")) md_count(out, o);
    } else if (strcmp(a, "hurwitz") == 0) {
        const json_t *m = json_object_get(o, "minors"), *c = json_object_get(o, "conditions");
        const json_t *d = json_object_get(o, "dropped");
        fputs("### Hurwitz minors and Lienard-Chipart conditions\n\n", out);
        for (i = 0; i < json_array_size(m); i++) {
            fprintf(out, "- D_%zu = ", i + 1);
            md_code(out, json_string_value(json_array_get(m, i)));
            fputc('\n', out);
        }
        fputc('\n', out);
        if (!md_branches(out, o)) {
        fputs("All |lambda| < 1 if and only if:\n\n", out);
        for (i = 0; i < json_array_size(c); i++) {
            fputs("- ", out);
            md_code(out, json_string_value(json_array_get(c, i)));
            fputc('\n', out);
        }
        if (json_array_size(c) == 0) fputs("- (every condition holds under the assumptions)\n", out);
        fputc('\n', out);
        }
        for (i = 0; i < json_array_size(d); i++) {
            fputs("Dropped factor ", out);
            md_code(out, js(json_array_get(d, i), "factor"));
            fprintf(out, " of %s: %s.\n", js(json_array_get(d, i), "from"), js(json_array_get(d, i), "reason"));
        }
        fputc('\n', out);
    } else if (strcmp(a, "stability") == 0 || strcmp(a, "jury") == 0) {
        fprintf(out, "### %s\n\n", strcmp(a, "jury") == 0 ? "Schur-Cohn test on p(lambda)" : "Stability at the given values");
        if (json_is_true(json_object_get(o, "symbolic"))) {   /* symbolic Schur-Cohn conditions */
            const json_t *c = json_object_get(o, "conditions");
            fputs("All |lambda| < 1 if and only if:\n\n", out);
            for (i = 0; i < json_array_size(c); i++) {
                fputs("- ", out);
                md_code(out, json_string_value(json_array_get(c, i)));
                fputc('\n', out);
            }
            fputc('\n', out);
            return;
        }
        md_count(out, o);
    } else if (strcmp(a, "region") == 0) {
        const json_t *iv = json_object_get(o, "intervals");
        fprintf(out, "### Stability region in %s\n\n", js(o, "param"));
        if (json_is_true(json_object_get(o, "symbolic"))) {
            const json_t *c = json_object_get(o, "conditions");
            if (md_branches(out, o)) return;
            fputs("Stable if and only if:\n\n", out);
            for (i = 0; i < json_array_size(c); i++) {
                fputs("- ", out);
                md_code(out, json_string_value(json_array_get(c, i)));
                fputc('\n', out);
            }
            fputc('\n', out);
            return;
        }
        for (i = 0; i < json_array_size(iv); i++) {
            const json_t *e = json_array_get(iv, i);
            fprintf(out, "- **%s**: %s in %s%s, %s%s", js(e, "status"), js(o, "param"),
                    json_is_true(json_object_get(e, "lo_closed")) ? "[" : "(", endpoint(json_object_get(e, "lo"), 0),
                    endpoint(json_object_get(e, "hi"), 1), json_is_true(json_object_get(e, "hi_closed")) ? "]" : ")");
            if (json_is_object(json_object_get(e, "hi"))) {
                fputs(" (upper end: a root of ", out);
                md_code(out, js(json_object_get(e, "hi"), "minpoly"));
                fputc(')', out);
            }
            fputc('\n', out);
        }
        fputc('\n', out);
    } else if (strcmp(a, "limit") == 0) {
        const json_t *r = json_object_get(o, "roots");
        fprintf(out, "### Limit %s -> %s\n\nThe roots tend to: ", js(o, "param"), js(o, "to"));
        for (i = 0; i < json_array_size(r); i++)
            fprintf(out, "%s%s (x%lld)", i ? ", " : "", js(json_array_get(r, i), "value"),
                    ji(json_array_get(r, i), "multiplicity"));
        fputs(".\n\n", out);
    } else if (strcmp(a, "claim") == 0 || strcmp(a, "expect") == 0) {
        fprintf(out, "### %s\n\n", strcmp(a, "claim") == 0 ? "Claim" : "Printed polynomial");
        md_code(out, js(o, "text"));
        fprintf(out, ": **%s**.\n\n", js(o, "status"));
        if (json_is_object(json_object_get(o, "counterexample"))) {
            const char *k;
            json_t *v;
            int first = 1;
            fputs("Counterexample: ", out);
            json_object_foreach(json_object_get(o, "counterexample"), k, v) {
                fprintf(out, "%s%s = %s", first ? "" : ", ", k, json_string_value(v));
                first = 0;
            }
            fputs(". ", out);
            md_count(out, json_object_get(o, "at_counterexample"));
        }
        if (js(o, "difference") && strcmp(js(o, "difference"), "0") != 0) {
            fputs("Printed minus derived: ", out);
            md_code(out, js(o, "difference"));
            fputs("\n\n", out);
        }
        if (json_is_array(json_object_get(o, "certificate"))) {
            const json_t *c = json_object_get(o, "certificate");
            fputs("Certificate (after each substitution, s >= 0, every coefficient of the numerator is "
                  "non-negative):\n\n", out);
            for (i = 0; i < json_array_size(c); i++) {
                const char *k;
                json_t *v;
                fputs("- ", out);
                md_code(out, js(json_array_get(c, i), "condition"));
                fputs(" > 0 with", out);
                json_object_foreach(json_object_get(json_array_get(c, i), "substitution"), k, v)
                    fprintf(out, " %s = %s;", k, json_string_value(v));
                fputc('\n', out);
            }
            fputc('\n', out);
        }
    }
}

void rs_derivation_markdown(FILE *out, const json_t *doc)
{
    const json_t *sc = json_object_get(doc, "scheme"), *res = json_object_get(doc, "results");
    size_t i, j;
    fprintf(out, "## %s\n\n", js(doc, "title") ? js(doc, "title") : js(doc, "case"));
    if (sc != NULL) {
        const json_t *eqs = json_object_get(sc, "equations"), *lets = json_object_get(sc, "lets");
        const json_t *M = json_object_get(sc, "matrix"), *as = json_object_get(sc, "assume");
        if (json_array_size(as) > 0) {
            fputs("Assumptions: ", out);
            for (i = 0; i < json_array_size(as); i++) {
                if (i) fputs(", ", out);
                md_code(out, json_string_value(json_array_get(as, i)));
            }
            fputs(".\n\n", out);
        }
        if (json_array_size(eqs) > 0) {
            fputs("### Difference equations\n\n", out);
            for (i = 0; i < json_array_size(lets); i++)
                fprintf(out, "    let %s\n", json_string_value(json_array_get(lets, i)));
            for (i = 0; i < json_array_size(eqs); i++)
                fprintf(out, "    %s\n", json_string_value(json_array_get(eqs, i)));
            fputs("\n### The lambda-matrix\n\nx[n+k] -> lambda^k, each row shifted so that its lowest power is "
                  "lambda^0:\n\n", out);
            for (i = 0; i < json_array_size(M); i++) {
                const json_t *row = json_array_get(M, i);
                fputs("    [ ", out);
                for (j = 0; j < json_array_size(row); j++)
                    fprintf(out, "%s%s", j ? " | " : "", json_string_value(json_array_get(row, j)));
                fputs(" ]\n", out);
            }
            fputc('\n', out);
        }
    }
    for (i = 0; i < json_array_size(res); i++) md_result(out, json_array_get(res, i));
}
