/* render_impl.h -- private to src/render/: one walker of the result document,
 * three backends (text report, Markdown, LaTeX) supplying its primitives.
 *
 * The layout of each analysis (layout_exact.c, layout_numeric.c) is written
 * once, against the primitives below. Two kinds of primitive are specific to
 * one view of the document, because the outputs are interfaces and differ in
 * what they show:
 *   - rs_render_line/_linef/_textf: the aligned "label  value" lines of the
 *     text report (ignored by the derivations);
 *   - rs_render_say/_sayf: the sentences of the derivation, worded once for
 *     Markdown and once for LaTeX (ignored by the text report).
 * Everything else (headings, verdict counts, Routh rows, lists, math, code) is
 * a shared block every backend formats its own way. */
#ifndef RS_RENDER_IMPL_H
#define RS_RENDER_IMPL_H

#include <stdarg.h>
#include <stdio.h>
#include <jansson.h>
#include "recstab/str.h"

/* backend kinds, also used as masks of which backends a block is for */
#define RS_RENDER_TEXT 1
#define RS_RENDER_MARKDOWN 2
#define RS_RENDER_LATEX 4
#define RS_RENDER_PROSE (RS_RENDER_MARKDOWN | RS_RENDER_LATEX)
#define RS_RENDER_ALL (RS_RENDER_TEXT | RS_RENDER_PROSE)

typedef struct {
    int kind;
    /* text report lines (NULL in the derivations) */
    void (*field)(FILE *out, const char *label, const char *fmt, va_list ap);
    void (*label)(FILE *out, const char *label);
    void (*textf)(FILE *out, const char *fmt, va_list ap);
    /* values inside prose (no-ops in the text report) */
    void (*esc)(FILE *out, const char *s);    /* a string as running text */
    void (*poly)(FILE *out, const char *s);   /* a polynomial inside math already opened */
    void (*math)(FILE *out, const char *s);   /* a polynomial or condition as inline math */
    void (*code)(FILE *out, const char *s);   /* case-file text */
    /* shared blocks */
    void (*count)(FILE *out, const json_t *o);                        /* inside/on/outside */
    void (*rows)(FILE *out, const json_t *rows, const json_t *powers); /* a Routh array */
    const char *heading_begin, *heading_end;
    const char *list_begin, *item_begin, *item_end, *list_end;
} rs_render_backend_t;

typedef struct {
    FILE *out;
    const rs_render_backend_t *be;
    rs_polytext_struct *pt;   /* placeholders of long polynomials printed here, or NULL (str.h) */
} rs_render_t;

extern const rs_render_backend_t rs_render_text_backend;
extern const rs_render_backend_t rs_render_markdown_backend;
extern const rs_render_backend_t rs_render_latex_backend;

/* JSON access: NULL / 0 for a missing member */
const char *rs_render_jstr(const json_t *o, const char *key);
long long rs_render_jint(const json_t *o, const char *key);

/* text report: "  LABEL        VALUE" with fmt applied to a; nothing when a is
 * NULL (a member this result does not have) */
void rs_render_line(rs_render_t *r, const char *label, const char *fmt, const char *a);
void rs_render_linef(rs_render_t *r, const char *label, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
void rs_render_textf(rs_render_t *r, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* the start of a report line composed with rs_render_textf: "  LABEL        " */
void rs_render_label(rs_render_t *r, const char *label);

/* derivation sentences: md for Markdown, tex for LaTeX (NULL: nothing); the
 * _f form formats both with the same arguments (a format may use fewer) */
void rs_render_say(rs_render_t *r, const char *md, const char *tex);
void rs_render_sayf(rs_render_t *r, const char *md, const char *tex, ...);

void rs_render_esc(rs_render_t *r, const char *s);
void rs_render_poly(rs_render_t *r, const char *s);
void rs_render_math(rs_render_t *r, const char *s);
void rs_render_code(rs_render_t *r, const char *s);

/* a heading with fixed wording (md, tex); _begin/_end around composed ones */
void rs_render_heading(rs_render_t *r, const char *md, const char *tex);
void rs_render_heading_begin(rs_render_t *r);
void rs_render_heading_end(rs_render_t *r);

/* verdict counts, for the backends in mask only */
void rs_render_count(rs_render_t *r, const json_t *o, int mask);
/* The power of z labelling row i of a Routh table: the row's own power from
 * "powers" (a generalised step may skip powers), else deg - i. */
long rs_render_row_power(const json_t *rows, const json_t *powers, size_t i);
void rs_render_rows(rs_render_t *r, const json_t *rows, const json_t *powers);

/* a bulleted list (derivations) */
void rs_render_list_begin(rs_render_t *r);
void rs_render_item_begin(rs_render_t *r);
void rs_render_item_end(rs_render_t *r);
void rs_render_list_end(rs_render_t *r);

/* per-analysis layouts */
typedef void (*rs_render_layout_fn)(rs_render_t *r, const json_t *result);

void rs_render_charpoly(rs_render_t *r, const json_t *o);
void rs_render_expect(rs_render_t *r, const json_t *o);
void rs_render_bilinear(rs_render_t *r, const json_t *o);
void rs_render_routh(rs_render_t *r, const json_t *o);
void rs_render_hurwitz(rs_render_t *r, const json_t *o);
void rs_render_jury(rs_render_t *r, const json_t *o);
void rs_render_stability(rs_render_t *r, const json_t *o);
void rs_render_vanishing(rs_render_t *r, const json_t *o);
void rs_render_region(rs_render_t *r, const json_t *o);
void rs_render_limit(rs_render_t *r, const json_t *o);
void rs_render_astability(rs_render_t *r, const json_t *o);   /* layout_astability.c */
void rs_render_claim(rs_render_t *r, const json_t *o);
/* region and claim of exact integration (layout_cosim.c), called by the two above */
void rs_render_cosim_region(rs_render_t *r, const json_t *o);
void rs_render_cosim_claim(rs_render_t *r, const json_t *o);
void rs_render_radius(rs_render_t *r, const json_t *o);
void rs_render_modes(rs_render_t *r, const json_t *o);
void rs_render_simulate(rs_render_t *r, const json_t *o);
void rs_render_sweep(rs_render_t *r, const json_t *o);
void rs_render_generic(rs_render_t *r, const json_t *o);

/* text report blocks shared by several layouts */
void rs_render_assigned(rs_render_t *r, const json_t *o);
void rs_render_string_list(rs_render_t *r, const char *label, const json_t *arr, const char *sep);
void rs_render_sample_check(rs_render_t *r, const json_t *o);

/* endpoint of a region interval: rational string, algebraic object ("approx"),
 * or null (-inf / inf) */
const char *rs_render_endpoint(const json_t *e, int hi);

/* LaTeX text escaping (used by the LaTeX backend and the document title) */
void rs_render_tex_text(FILE *out, const char *s);

#endif
