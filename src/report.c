/* report.c -- text rendering of result documents. */
#include <string.h>
#include "recstab/report.h"

#define LABEL_W 12

static const char *jstr(const json_t *o, const char *key)
{
    const json_t *v = json_object_get(o, key);
    return json_is_string(v) ? json_string_value(v) : NULL;
}

static void line(FILE *out, const char *label, const char *fmt, const char *a)
{
    fprintf(out, "  %-*s ", LABEL_W, label ? label : "");
    fprintf(out, fmt, a);
    fputc('\n', out);
}

static void print_assigned(FILE *out, const json_t *o)
{
    const json_t *sub = json_object_get(o, "substituted");
    const char *key;
    json_t *val;
    int first = 1;
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
    line(out, "claim", "%s", jstr(o, "text"));
    line(out, "status", "%s", st);
    if (st && strcmp(st, "different") == 0) {
        if (jstr(o, "derived")) line(out, "derived", "%s", jstr(o, "derived"));
        if (jstr(o, "expected_normalised")) line(out, "printed", "%s", jstr(o, "expected_normalised"));
        line(out, "difference", "%s", jstr(o, "difference"));
        if (jstr(o, "ratio")) line(out, "ratio", "printed = (%s) * derived", jstr(o, "ratio"));
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
