/* text.c -- the text report backend: aligned "label  value" lines. */
#include "render_impl.h"

#define LABEL_W 12

static void text_label(FILE *out, const char *label)
{
    fprintf(out, "  %-*s ", LABEL_W, label ? label : "");
}

static void text_field(FILE *out, const char *label, const char *fmt, va_list ap)
{
    text_label(out, label);
    vfprintf(out, fmt, ap);
    fputc('\n', out);
}

static void text_textf(FILE *out, const char *fmt, va_list ap)
{
    vfprintf(out, fmt, ap);
}

/* prose values: the report shows them through its own lines */
static void text_none(FILE *out, const char *s)
{
    (void) out;
    (void) s;
}

static void line(FILE *out, const char *label, const char *a)
{
    if (a != NULL) fprintf(out, "  %-*s %s\n", LABEL_W, label, a);
}

/* Repeated circle roots: semisimple or a Jordan block, and which rule. */
static void text_circle_roots(FILE *out, const json_t *o)
{
    const json_t *cr = json_object_get(o, "circle_roots");
    size_t i;
    int any = 0;
    line(out, "singular", rs_render_jstr(o, "singular"));
    line(out, "note", rs_render_jstr(o, "dead_beat"));
    for (i = 0; i < json_array_size(cr); i++) {
        const json_t *e = json_array_get(cr, i);
        if (rs_render_jint(e, "multiplicity") < 2) continue;
        fprintf(out, "  %-*s %s (x%lld): %s (dim ker A = %lld)\n", LABEL_W, any ? "" : "circle roots",
                rs_render_jstr(e, "factor"), rs_render_jint(e, "multiplicity"),
                json_is_true(json_object_get(e, "semisimple")) ? "semisimple" : "Jordan block",
                rs_render_jint(e, "kernel_dim"));
        any = 1;
    }
    if (any) line(out, "rule", rs_render_jstr(o, "rule"));
}

static void text_count(FILE *out, const json_t *o)
{
    const json_t *m = json_object_get(o, "on_multiplicities");
    size_t i;
    fprintf(out, "  %-*s %s: %lld inside, %lld on, %lld outside the unit circle", LABEL_W, "verdict",
            rs_render_jstr(o, "status"), rs_render_jint(o, "inside"), rs_render_jint(o, "on"),
            rs_render_jint(o, "outside"));
    if (rs_render_jint(o, "at_zero") > 0) fprintf(out, "; lambda = 0 (x%lld)", rs_render_jint(o, "at_zero"));
    if (rs_render_jint(o, "at_one") > 0) fprintf(out, "; lambda = 1 (x%lld)", rs_render_jint(o, "at_one"));
    if (rs_render_jint(o, "at_minus_one") > 0)
        fprintf(out, "; lambda = -1 (x%lld)", rs_render_jint(o, "at_minus_one"));
    for (i = 0; i < json_array_size(m); i++) {
        const json_t *e = json_array_get(m, i);
        fprintf(out, "%s%lld circle root%s of multiplicity %lld", i == 0 ? "; " : ", ", rs_render_jint(e, "roots"),
                rs_render_jint(e, "roots") == 1 ? "" : "s", rs_render_jint(e, "multiplicity"));
    }
    fputc('\n', out);
    text_circle_roots(out, o);
}

/* one line per row, labelled by its power of z: the generalised step may skip
 * powers, so each row's own power when given */
static void text_rows(FILE *out, const json_t *rows, const json_t *powers)
{
    size_t i, j;
    for (i = 0; i < json_array_size(rows); i++) {
        const json_t *row = json_array_get(rows, i);
        char lab[32];
        snprintf(lab, sizeof lab, "z^%ld", rs_render_row_power(rows, powers, i));
        fprintf(out, "  %-*s ", LABEL_W, lab);
        for (j = 0; j < json_array_size(row); j++)
            fprintf(out, "%s%s", j ? "   " : "", json_string_value(json_array_get(row, j)));
        fputc('\n', out);
    }
}

const rs_render_backend_t rs_render_text_backend = {
    RS_RENDER_TEXT, text_field, text_label, text_textf, text_none, text_none, text_none, text_none,
    text_count, text_rows, "", "", "", "", "", ""
};
