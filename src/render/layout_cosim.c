/* layout_cosim.c -- the region and claim of exactly integrated subsystems
 * (an_cosim_region.c): certified by Stein certificates over parameter boxes,
 * so their report names enclosures, unseparated runs and sub-boxes instead of
 * the exact endpoints and re-checked certificates of the equations' region
 * and claim (layout_exact.c hands these results over here). */
#include <string.h>
#include "render/render_impl.h"

static const char *js(const json_t *o, const char *k) { return rs_render_jstr(o, k); }

static const char *enc(const json_t *o, const char *key, size_t i)
{
    return json_string_value(json_array_get(json_object_get(o, key), i));
}

void rs_render_cosim_region(rs_render_t *r, const json_t *o)
{
    const json_t *iv = json_object_get(o, "intervals"), *tr = json_object_get(o, "transitions"),
                 *un = json_object_get(o, "unseparated");
    size_t i;
    rs_render_heading_begin(r);
    rs_render_say(r, "Certified stability region in ", "Certified stability region in $");
    rs_render_poly(r, js(o, "param"));
    rs_render_say(r, NULL, "$");
    rs_render_heading_end(r);
    rs_render_say(r, "Every sub-interval below is certified by a Stein certificate P - M^T P M > 0 for the ball "
                     "one-step map M over the whole sub-interval (matrix exponentials in Arb ball arithmetic); "
                     "each transition lies inside its enclosure.\n\n",
                  "Every sub-interval below is certified by a Stein certificate $P - M^T P M \\succ 0$ for the ball "
                  "one-step map $M$ over the whole sub-interval (matrix exponentials in Arb ball arithmetic); "
                  "each transition lies inside its enclosure.\n\n");
    rs_render_list_begin(r);
    for (i = 0; i < json_array_size(iv); i++) {
        const json_t *v = json_array_get(iv, i);
        rs_render_linef(r, js(v, "status"), "%s in %s%s, %s%s", js(o, "param"),
                        json_object_get(v, "lo_enclosure") ? "(" : "[", js(v, "lo"), js(v, "hi"),
                        json_object_get(v, "hi_enclosure") ? ")" : "]");
        rs_render_item_begin(r);
        rs_render_sayf(r, "**%s**: %s in %s%s, %s%s", "\\textbf{%s}: $%s \\in %s%s, %s%s$", js(v, "status"),
                       js(o, "param"), json_object_get(v, "lo_enclosure") ? "(" : "[", js(v, "lo"), js(v, "hi"),
                       json_object_get(v, "hi_enclosure") ? ")" : "]");
        rs_render_item_end(r);
    }
    rs_render_list_end(r);
    for (i = 0; i < json_array_size(tr); i++) {
        const json_t *t = json_array_get(tr, i);
        rs_render_linef(r, "transition", "%s -> %s, in [%s, %s]", js(t, "from"), js(t, "to"), enc(t, "enclosure", 0),
                        enc(t, "enclosure", 1));
        rs_render_sayf(r, "Transition %s to %s: %s in [%s, %s].\n\n",
                       "Transition %s to %s: $%s \\in [%s, %s]$.\n\n", js(t, "from"), js(t, "to"), js(o, "param"),
                       enc(t, "enclosure", 0), enc(t, "enclosure", 1));
    }
    for (i = 0; i < json_array_size(un); i++) {
        const json_t *u = json_array_get(un, i);
        rs_render_linef(r, "unseparated", "[%s, %s]: %s", enc(u, "enclosure", 0), enc(u, "enclosure", 1),
                        js(u, "reason"));
        rs_render_sayf(r, "Not separated: [%s, %s] (%s).\n\n", "Not separated: $[%s, %s]$ (%s).\n\n",
                       enc(u, "enclosure", 0), enc(u, "enclosure", 1), js(u, "reason"));
    }
    rs_render_linef(r, "certified", "%s (%lld boxes, %lld bits)",
                    json_is_true(json_object_get(o, "certified")) ? "every transition enclosed narrower than 10^-digits"
                                                                  : "no: see the unseparated runs",
                    rs_render_jint(o, "boxes"), rs_render_jint(o, "precision_bits"));
    rs_render_assigned(r, o);
}

/* {"NAME": ["lo", "hi"], ...} or {"NAME": "value", ...} on one line */
static void box_line(rs_render_t *r, const char *label, const json_t *b)
{
    char buf[1024] = "";
    const char *k;
    const json_t *v;
    json_object_foreach((json_t *) b, k, v) {
        size_t n = strlen(buf);
        if (json_is_array(v))
            snprintf(buf + n, sizeof buf - n, "%s%s <= %s <= %s", n ? ", " : "", json_string_value(json_array_get(v, 0)),
                     k, json_string_value(json_array_get(v, 1)));
        else
            snprintf(buf + n, sizeof buf - n, "%s%s = %s", n ? ", " : "", k, json_string_value(v));
    }
    rs_render_line(r, label, "%s", buf);
}

void rs_render_cosim_claim(rs_render_t *r, const json_t *o)
{
    const char *st = js(o, "status");
    rs_render_line(r, "claim", "%s", js(o, "text"));
    rs_render_line(r, "status", "%s", st);
    if (json_object_get(o, "counterexample")) box_line(r, "counterexample", json_object_get(o, "counterexample"));
    if (json_object_get(o, "failed_at")) box_line(r, "failed at", json_object_get(o, "failed_at"));
    if (json_object_get(o, "centre")) box_line(r, "centre", json_object_get(o, "centre"));
    if (json_object_get(o, "not_proved")) rs_render_line(r, "not proved", "%s", js(o, "not_proved"));
    if (json_object_get(o, "proved_by")) rs_render_line(r, "proved by", "%s", js(o, "proved_by"));
    if (json_object_get(o, "certificate"))
        rs_render_line(r, "certificate", "%s", js(json_object_get(o, "certificate"), "kind"));
    rs_render_linef(r, "boxes", "%lld sub-boxes evaluated in ball arithmetic", rs_render_jint(o, "boxes_checked"));
    rs_render_assigned(r, o);
    rs_render_heading(r, "Claim", "Claim");
    /* the claim as code (Markdown fences it, LaTeX escapes its specials) */
    rs_render_code(r, js(o, "text"));
    rs_render_sayf(r, ": %s (%lld sub-boxes, Stein certificates over ball one-step maps).\n\n",
                   ": %s (%lld sub-boxes, Stein certificates over ball one-step maps).\n\n",
                   st, rs_render_jint(o, "boxes_checked"));
    if (json_object_get(o, "not_proved")) {
        rs_render_say(r, "Not proved: ", "Not proved: ");
        rs_render_esc(r, js(o, "not_proved"));   /* prose: escaped, not code */
        rs_render_say(r, ".\n\n", ".\n\n");
    }
}
