/* render.c -- the walker of a result document and the primitives the layouts
 * call; each primitive hands over to the current backend (render_impl.h). */
#include <string.h>
#include "recstab/report.h"
#include "recstab/derivation.h"
#include "render_impl.h"
#include "util/polytext.h"

const char *rs_render_jstr(const json_t *o, const char *key)
{
    const json_t *v = json_object_get(o, key);
    return json_is_string(v) ? json_string_value(v) : NULL;
}

long long rs_render_jint(const json_t *o, const char *key)
{
    return (long long) json_integer_value(json_object_get(o, key));
}

const char *rs_render_endpoint(const json_t *e, int hi)
{
    if (e == NULL || json_is_null(e)) return hi ? "inf" : "-inf";
    if (json_is_string(e)) return json_string_value(e);
    return rs_render_jstr(e, "approx");
}

/* ---- primitives ---------------------------------------------------------------- */

static void field(rs_render_t *r, const char *label, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    r->be->field(r->out, label, fmt, ap);
    va_end(ap);
}

void rs_render_line(rs_render_t *r, const char *label, const char *fmt, const char *a)
{
    slong k;
    if (a == NULL || r->be->field == NULL) return;
    /* a polynomial held back (util/polytext.h): the field as text_field
     * writes it, the text printed straight into the report */
    if (r->pt != NULL && r->be->kind == RS_RENDER_TEXT && strcmp(fmt, "%s") == 0
        && (k = rs_polytext_find_value(r->pt, a)) >= 0) {
        r->be->label(r->out, label);
        rs_polytext_write(r->out, r->pt, k, 0);
        fputc('\n', r->out);
        return;
    }
    field(r, label, fmt, a);
}

void rs_render_linef(rs_render_t *r, const char *label, const char *fmt, ...)
{
    va_list ap;
    if (r->be->field == NULL) return;
    va_start(ap, fmt);
    r->be->field(r->out, label, fmt, ap);
    va_end(ap);
}

void rs_render_textf(rs_render_t *r, const char *fmt, ...)
{
    va_list ap;
    if (r->be->textf == NULL) return;
    va_start(ap, fmt);
    r->be->textf(r->out, fmt, ap);
    va_end(ap);
}

void rs_render_label(rs_render_t *r, const char *label)
{
    if (r->be->label != NULL) r->be->label(r->out, label);
}

static const char *pick(const rs_render_t *r, const char *md, const char *tex)
{
    return r->be->kind == RS_RENDER_MARKDOWN ? md : r->be->kind == RS_RENDER_LATEX ? tex : NULL;
}

void rs_render_say(rs_render_t *r, const char *md, const char *tex)
{
    const char *s = pick(r, md, tex);
    if (s != NULL) fputs(s, r->out);
}

void rs_render_sayf(rs_render_t *r, const char *md, const char *tex, ...)
{
    const char *fmt = pick(r, md, tex);
    va_list ap;
    if (fmt == NULL) return;
    va_start(ap, tex);
    vfprintf(r->out, fmt, ap);
    va_end(ap);
}

void rs_render_esc(rs_render_t *r, const char *s) { r->be->esc(r->out, s); }
void rs_render_poly(rs_render_t *r, const char *s) { r->be->poly(r->out, s); }
void rs_render_math(rs_render_t *r, const char *s) { r->be->math(r->out, s); }
void rs_render_code(rs_render_t *r, const char *s) { r->be->code(r->out, s); }

void rs_render_heading_begin(rs_render_t *r) { fputs(r->be->heading_begin, r->out); }
void rs_render_heading_end(rs_render_t *r) { fputs(r->be->heading_end, r->out); }

void rs_render_heading(rs_render_t *r, const char *md, const char *tex)
{
    rs_render_heading_begin(r);
    rs_render_say(r, md, tex);
    rs_render_heading_end(r);
}

void rs_render_count(rs_render_t *r, const json_t *o, int mask)
{
    if (r->be->kind & mask) r->be->count(r->out, o);
}

long rs_render_row_power(const json_t *rows, const json_t *powers, size_t i)
{
    const json_t *p = json_array_get(powers, i);
    return json_is_integer(p) ? (long) json_integer_value(p) : (long) (json_array_size(rows) - 1 - i);
}

void rs_render_rows(rs_render_t *r, const json_t *rows, const json_t *powers)
{
    r->be->rows(r->out, rows, powers);
}

void rs_render_list_begin(rs_render_t *r) { fputs(r->be->list_begin, r->out); }
void rs_render_item_begin(rs_render_t *r) { fputs(r->be->item_begin, r->out); }
void rs_render_item_end(rs_render_t *r) { fputs(r->be->item_end, r->out); }
void rs_render_list_end(rs_render_t *r) { fputs(r->be->list_end, r->out); }

/* ---- the walker -------------------------------------------------------------------- */

typedef struct { const char *name; rs_render_layout_fn fn; } layout_t;

static const layout_t layouts[] = {
    {"charpoly", rs_render_charpoly},
    {"expect", rs_render_expect},
    {"bilinear", rs_render_bilinear},
    {"routh", rs_render_routh},
    {"hurwitz", rs_render_hurwitz},
    {"jury", rs_render_jury},
    {"stability", rs_render_stability},
    {"region", rs_render_region},
    {"limit", rs_render_limit},
    {"astability", rs_render_astability},
    {"claim", rs_render_claim},
    {"radius", rs_render_radius},
    {"modes", rs_render_modes},
    {"simulate", rs_render_simulate},
    {"sweep", rs_render_sweep},
    {"map", rs_render_sweep},
    {NULL, NULL}
};

static rs_render_layout_fn layout_of(const char *name)
{
    size_t k;
    for (k = 0; name != NULL && layouts[k].name; k++)
        if (strcmp(layouts[k].name, name) == 0) return layouts[k].fn;
    return rs_render_generic;
}

/* Title: "case FILE: TITLE" in the report, the title (else the file) as the
 * section heading of a derivation. */
static void render_title(rs_render_t *r, const json_t *doc)
{
    const char *title = rs_render_jstr(doc, "title");
    rs_render_textf(r, "case %s%s%s\n", rs_render_jstr(doc, "case"), title ? ": " : "", title ? title : "");
    rs_render_say(r, "## ", "\\section*{");
    rs_render_esc(r, title ? title : rs_render_jstr(doc, "case"));
    rs_render_say(r, "\n\n", "}\n");
}

static void render_matrix(rs_render_t *r, const json_t *M)
{
    size_t i, j;
    rs_render_say(r, "### The lambda-matrix\n\nWith $x_{n+k} \\mapsto \\lambda^k$ (each row shifted so that its "
                     "lowest power is $\\lambda^0$):\n\n$$\n\\left(\\begin{array}{",
                  "\\subsection*{The $\\lambda$-matrix}\nWith $x_{n+k} \\mapsto \\lambda^k$ (each "
                  "row shifted so that its lowest power is $\\lambda^0$):\n{\\small\\[\\left(\\begin{array}{");
    for (j = 0; j < json_array_size(M); j++) rs_render_say(r, "c", "c");
    rs_render_say(r, "}\n", "}\n");
    for (i = 0; i < json_array_size(M); i++) {
        const json_t *row = json_array_get(M, i);
        for (j = 0; j < json_array_size(row); j++) {
            if (j) rs_render_say(r, " & ", " & ");
            rs_render_poly(r, json_string_value(json_array_get(row, j)));
        }
        rs_render_say(r, " \\\\\n", " \\\\\n");
    }
    rs_render_say(r, "\\end{array}\\right)\n$$\n\n", "\\end{array}\\right)\\]}\n");
}

/* The scheme of a derivation: assumptions, difference equations, lambda-matrix. */
static void render_scheme(rs_render_t *r, const json_t *sc)
{
    const json_t *eqs = json_object_get(sc, "equations"), *lets = json_object_get(sc, "lets");
    const json_t *as = json_object_get(sc, "assume");
    size_t i;
    if (json_array_size(as) > 0) {
        rs_render_say(r, "Assumptions: ", "Assumptions: ");
        for (i = 0; i < json_array_size(as); i++) {
            if (i) rs_render_say(r, ", ", ", ");
            rs_render_math(r, json_string_value(json_array_get(as, i)));
        }
        rs_render_say(r, ".\n\n", ".\n\n");
    }
    if (json_array_size(eqs) == 0) return;
    /* one display, every equation aligned at its = */
    rs_render_say(r, "### Difference equations\n\n$$\n\\begin{aligned}\n",
                  "\\subsection*{Difference equations}\n\\begin{align*}\n");
    for (i = 0; i < json_array_size(lets) + json_array_size(eqs); i++) {
        int is_let = i < json_array_size(lets);
        const char *e = json_string_value(json_array_get(is_let ? lets : eqs, is_let ? i : i - json_array_size(lets)));
        const char *eq = e != NULL ? strstr(e, " = ") : NULL;
        int last = i + 1 == json_array_size(lets) + json_array_size(eqs);
        if (eq != NULL) {
            char *lhs = strndup(e, (size_t) (eq - e));
            rs_render_poly(r, lhs);
            free(lhs);
            rs_render_say(r, " &= ", " &= ");
            rs_render_poly(r, eq + 3);
        } else rs_render_poly(r, e);
        if (is_let) rs_render_say(r, " && \\text{(let)}", " && \\text{(let)}");
        rs_render_say(r, last ? "\n" : " \\\\\n", last ? "\n" : " \\\\\n");
    }
    rs_render_say(r, "\\end{aligned}\n$$\n\n", "\\end{align*}\n");
    render_matrix(r, json_object_get(sc, "matrix"));
}

static void render_doc(FILE *out, const rs_render_backend_t *be, const json_t *doc, rs_polytext_struct *pt)
{
    rs_render_t r;
    const json_t *res = json_object_get(doc, "results");
    size_t i;
    r.out = out;
    r.be = be;
    r.pt = pt;
    render_title(&r, doc);
    if (be->kind != RS_RENDER_TEXT && json_object_get(doc, "scheme") != NULL)
        render_scheme(&r, json_object_get(doc, "scheme"));
    for (i = 0; i < json_array_size(res); i++) {
        const json_t *o = json_array_get(res, i);
        const char *name = rs_render_jstr(o, "analysis");
        rs_render_textf(&r, "\n%s\n", name ? name : "?");
        /* det A = 0 at the set values: one layout for every analysis */
        if (json_is_true(json_object_get(o, "vanishes"))) rs_render_vanishing(&r, o);
        else layout_of(name)(&r, o);
    }
}

void rs_report_text(FILE *out, const json_t *doc)
{
    render_doc(out, &rs_render_text_backend, doc, NULL);
}

void rs_report_text_polytext(FILE *out, const json_t *doc, rs_polytext_t pt)
{
    render_doc(out, &rs_render_text_backend, doc, pt);
}

void rs_derivation_markdown(FILE *out, const json_t *doc)
{
    render_doc(out, &rs_render_markdown_backend, doc, NULL);
}

void rs_derivation_latex(FILE *out, const json_t *doc, int standalone)
{
    if (standalone) rs_derivation_latex_begin(out);
    render_doc(out, &rs_render_latex_backend, doc, NULL);
    if (standalone) rs_derivation_latex_end(out);
}
