/* latex.c -- the LaTeX derivation backend (pdflatex, amsmath) and the LaTeX
 * form of polynomial and condition strings. */
#include <ctype.h>
#include <string.h>
#include "recstab/derivation.h"
#include "render_impl.h"

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
    if (len > 2 && buf[0] == 's' && buf[1] == '_') {
        /* the certificates' s_NAME: s with the parameter as its index */
        fputs("s_{", out);
        tex_name(out, buf + 2, len - 2);
        fputc('}', out);
        return;
    }
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
            } else if (j - i == 1 && s[i] == '1' && j < n && s[j] == '*'
                       && (i == 0 || strchr(" (+-", s[i - 1]) != NULL)) {
                i = j + 1;   /* 1*x is x */
                continue;
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
            if (j - i == 4 && strncmp(s + i, "sqrt", 4) == 0 && j + 1 < n && s[j] == '('
                && isdigit((unsigned char) s[j + 1])) {
                /* sqrt(d) of the Q(sqrt d) analyses (an_qd*.c): \sqrt{d}, not \mathit{sqrt}(d) */
                size_t k = j + 1;
                while (k < n && isdigit((unsigned char) s[k])) k++;
                if (k < n && s[k] == ')') {
                    fprintf(out, "\\sqrt{%.*s}", (int) (k - j - 1), s + j + 1);
                    i = k + 1;
                    prev_num = 0;
                    continue;
                }
            }
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

void rs_render_tex_text(FILE *out, const char *s)
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
        /* typewriter quotes as typed, not typographic ones; '|' is a dash in
         * OT1, "--" an en dash */
        case '`': fputs("\\textasciigrave{}", out); break;
        case '\'': fputs("\\textquotesingle{}", out); break;
        case '"': fputs("{\\ttfamily\\char34}", out); break;   /* OT1 has no \\textquotedbl */
        case '|': fputs("\\textbar{}", out); break;
        case '-': fputs(s[1] == '-' ? "-{}" : "-", out); break;
        default:
            /* control bytes and non-ASCII: '?' (no input encoding assumed) */
            if ((unsigned char) *s < 128 && ((unsigned char) *s >= 0x20 || *s == '\n')) fputc(*s, out);
            else fputc('?', out);
        }
    }
}

static void tex_poly(FILE *out, const char *s)
{
    rs_derivation_tex_poly(out, s ? s : "");
}

static void tex_math(FILE *out, const char *s)
{
    fputc('$', out);
    tex_poly(out, s);
    fputc('$', out);
}

static void tex_code(FILE *out, const char *s)
{
    fputs("\\texttt{", out);
    rs_render_tex_text(out, s);
    fputc('}', out);
}

/* ---- LaTeX ------------------------------------------------------------------- */

void rs_derivation_latex_begin(FILE *out)
{
    fputs("\\documentclass[10pt]{article}\n"
          "\\usepackage{amsmath}\n"
          "\\usepackage{textcomp}\n"
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
            rs_render_jstr(o, "status"), rs_render_jint(o, "inside"), rs_render_jint(o, "on"),
            rs_render_jint(o, "outside"));
    if (rs_render_jint(o, "at_one")) fprintf(out, "; $\\lambda = 1$ with multiplicity %lld", rs_render_jint(o, "at_one"));
    if (rs_render_jint(o, "at_minus_one")) fprintf(out, "; $\\lambda = -1$ with multiplicity %lld", rs_render_jint(o, "at_minus_one"));
    fputs(".\n\n", out);
}

static void latex_rows(FILE *out, const json_t *rows, const json_t *powers)
{
    size_t i, j, w = 0;
    for (i = 0; i < json_array_size(rows); i++)
        if (json_array_size(json_array_get(rows, i)) > w) w = json_array_size(json_array_get(rows, i));
    fputs("\\[\\begin{array}{r|", out);
    for (j = 0; j < w; j++) fputc('l', out);
    fputs("}\n", out);
    for (i = 0; i < json_array_size(rows); i++) {
        const json_t *row = json_array_get(rows, i);
        fprintf(out, "z^{%ld}", rs_render_row_power(rows, powers, i));
        for (j = 0; j < w; j++) {
            fputs(" & ", out);
            if (j < json_array_size(row)) rs_derivation_tex_poly(out, json_string_value(json_array_get(row, j)));
        }
        fputs(" \\\\\n", out);
    }
    fputs("\\end{array}\\]\n", out);
}

const rs_render_backend_t rs_render_latex_backend = {
    RS_RENDER_LATEX, NULL, NULL, NULL, rs_render_tex_text, tex_poly, tex_math, tex_code,
    latex_count, latex_rows, "\\subsection*{", "}\n",
    "\\begin{itemize}\n", "\\item ", "\n", "\\end{itemize}\n"
};
