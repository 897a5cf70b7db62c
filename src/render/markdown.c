/* markdown.c -- the Markdown derivation backend. */
#include "recstab/derivation.h"
#include <string.h>
#include "render_impl.h"

/* user text (titles, names, reasons) as running text: every character
 * Markdown (CommonMark, GitHub, pandoc) could read as markup is
 * backslash-escaped, as rs_render_tex_text escapes LaTeX's */
static void md_raw(FILE *out, const char *s)
{
    if (s == NULL) {
        fputs("(null)", out);   /* as glibc prints a NULL %s */
        return;
    }
    for (; *s; s++) {
        if (strchr("\\`*_[]<#|~$&", *s) != NULL)
            fputc('\\', out);
        fputc(*s, out);
    }
}

/* case-file text as a code span: the fence is one backtick longer than the
 * longest run inside (CommonMark), padded when s starts or ends with one */
static void md_code(FILE *out, const char *s)
{
    size_t run = 0, longest = 0, i, n;
    const char *c;
    int pad;
    if (s == NULL) s = "";
    for (c = s; *c; c++) {
        run = (*c == '`') ? run + 1 : 0;
        if (run > longest) longest = run;
    }
    n = strlen(s);
    pad = n > 0 && (s[0] == '`' || s[n - 1] == '`');
    for (i = 0; i <= longest; i++) fputc('`', out);
    if (pad) fputc(' ', out);
    fputs(s, out);
    if (pad) fputc(' ', out);
    for (i = 0; i <= longest; i++) fputc('`', out);
}

/* math in $...$ (GitHub, Jupyter, pandoc), the LaTeX form of the derivation */
static void md_poly(FILE *out, const char *s)
{
    rs_derivation_tex_poly(out, s ? s : "");
}

static void md_math(FILE *out, const char *s)
{
    fputc('$', out);
    md_poly(out, s);
    fputc('$', out);
}

static void md_count(FILE *out, const json_t *o)
{
    fprintf(out, "Verdict: **%s** — %lld roots inside, %lld on, %lld outside the unit circle",
            rs_render_jstr(o, "status"), rs_render_jint(o, "inside"), rs_render_jint(o, "on"),
            rs_render_jint(o, "outside"));
    if (rs_render_jint(o, "at_one")) fprintf(out, "; lambda = 1 (x%lld)", rs_render_jint(o, "at_one"));
    if (rs_render_jint(o, "at_minus_one")) fprintf(out, "; lambda = -1 (x%lld)", rs_render_jint(o, "at_minus_one"));
    fputs(".\n\n", out);
}

/* a table with a column per entry, each row labelled by its power of z */
static void md_rows(FILE *out, const json_t *rows, const json_t *powers)
{
    size_t i, j, w = 0;
    for (i = 0; i < json_array_size(rows); i++)
        if (json_array_size(json_array_get(rows, i)) > w) w = json_array_size(json_array_get(rows, i));
    fputs("| row |", out);
    for (j = 0; j < w; j++) fprintf(out, " %zu |", j + 1);
    fputs("\n|---|", out);
    for (j = 0; j < w; j++) fputs("---|", out);
    fputc('\n', out);
    for (i = 0; i < json_array_size(rows); i++) {
        const json_t *row = json_array_get(rows, i);
        fprintf(out, "| $z^{%ld}$ |", rs_render_row_power(rows, powers, i));
        for (j = 0; j < w; j++) {
            fputc(' ', out);
            if (j < json_array_size(row)) md_math(out, json_string_value(json_array_get(row, j)));
            fputs(" |", out);
        }
        fputc('\n', out);
    }
    fputc('\n', out);
}

const rs_render_backend_t rs_render_markdown_backend = {
    RS_RENDER_MARKDOWN, NULL, NULL, NULL, md_raw, md_poly, md_math, md_code,
    md_count, md_rows, "### ", "\n\n", "", "- ", "\n", "\n"
};
