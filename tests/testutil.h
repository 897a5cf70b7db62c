/* testutil.h -- shared helpers for the cmocka suites. */
#ifndef RECSTAB_TESTUTIL_H
#define RECSTAB_TESTUTIL_H
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>
#include <flint/fmpq.h>
#include <flint/fmpz_mpoly.h>
#include <stdio.h>
#include <string.h>
#include "recstab/casefile.h"
#include "recstab/scheme.h"
#include "recstab/analysis.h"

#ifndef RS_SOURCE_DIR
#define RS_SOURCE_DIR "."
#endif

/* Evaluates an integer multivariate polynomial at a rational point, term by
 * term (an independent check of FLINT-based results). */
static inline void tu_eval_fmpz_mpoly(fmpq_t out, const fmpz_mpoly_t p, fmpq *const *pt,
                                      const fmpz_mpoly_ctx_t ctx)
{
    slong i, v, nv = ctx->minfo->nvars;
    slong *e = flint_malloc(nv * sizeof(slong));
    fmpq_t term, pw;
    fmpq_init(term);
    fmpq_init(pw);
    fmpq_zero(out);
    for (i = 0; i < fmpz_mpoly_length(p, ctx); i++) {
        fmpz_mpoly_get_term_exp_si(e, p, i, ctx);
        fmpq_one(term);
        fmpz_set(fmpq_numref(term), p->coeffs + i);
        for (v = 0; v < nv; v++) {
            fmpq_pow_si(pw, pt[v], e[v]);
            fmpq_mul(term, term, pw);
        }
        fmpq_add(out, out, term);
    }
    fmpq_clear(term);
    fmpq_clear(pw);
    flint_free(e);
}
/* Runs a bundled case (path relative to the source tree) with the given
 * analysis requests (nreq < 0: the case's own); fails the test on an error. */
static inline json_t *tu_run_case(const char *rel, const char *const *req, int nreq, int *outcome)
{
    char path[1024];
    rs_case_t c;
    rs_error_t err;
    rs_options_t opt;
    json_t *doc = NULL;
    int i;
    snprintf(path, sizeof path, "%s/%s", RS_SOURCE_DIR, rel);
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&opt);
    if (rs_case_parse_file(c, path, err) != RS_OK) fail_msg("%s: %s", rel, err->msg);
    if (nreq >= 0) {
        rs_case_clear_requests(c);
        for (i = 0; i < nreq; i++) rs_case_add_request(c, req[i], "test", 1, 1);
    }
    if (rs_analysis_run(&doc, outcome, c, &opt, err) != RS_OK) fail_msg("%s: %s", rel, err->msg);
    rs_case_clear(c);
    return doc;
}
/* Runs case text with options opt (NULL: the defaults).  With code == NULL
 * an error fails the test; otherwise *code is the status and the document
 * is NULL on an error. */
static inline json_t *tu_run_text(const char *text, const rs_options_t *opt, int *outcome, int *code)
{
    rs_case_t c;
    rs_error_t err;
    rs_options_t def;
    json_t *doc = NULL;
    int r;
    rs_case_init(c);
    rs_error_init(err);
    rs_options_default(&def);
    r = rs_case_parse_string(c, "test.case", text, strlen(text), err);
    if (r == RS_OK) r = rs_analysis_run(&doc, outcome, c, opt != NULL ? opt : &def, err);
    rs_case_clear(c);
    if (code != NULL) *code = r;
    else if (r != RS_OK) fail_msg("%s: %s", text, err->msg);
    return doc;
}
/* JSON accessors of the analyses' documents: result i of a case, a string
 * member, an interval end as text ("inf" for null, "algebraic" for an
 * object) */
static inline const json_t *tu_result(const json_t *doc, size_t i)
{
    return json_array_get(json_object_get(doc, "results"), i);
}
static inline const char *tu_str(const json_t *o, const char *k)
{
    return json_string_value(json_object_get(o, k));
}
static inline const char *tu_end(const json_t *iv, const char *k)
{
    const json_t *e = json_object_get(iv, k);
    if (json_is_null(e)) return "inf";
    return json_is_string(e) ? json_string_value(e) : "algebraic";
}
/* an expected region interval, and the check of interval i of a region */
struct tu_iv { const char *lo; int lo_closed; const char *hi; int hi_closed; const char *status; };
static inline void tu_check_interval(const json_t *iv, const struct tu_iv *want, size_t i, const char *what)
{
    if (strcmp(tu_end(iv, "lo"), want->lo) != 0 || strcmp(tu_end(iv, "hi"), want->hi) != 0
        || json_is_true(json_object_get(iv, "lo_closed")) != want->lo_closed
        || json_is_true(json_object_get(iv, "hi_closed")) != want->hi_closed
        || strcmp(tu_str(iv, "status"), want->status) != 0)
        fail_msg("%s: interval %zu is %s%s, %s%s %s, expected %s%s, %s%s %s", what, i,
                 json_is_true(json_object_get(iv, "lo_closed")) ? "[" : "(", tu_end(iv, "lo"), tu_end(iv, "hi"),
                 json_is_true(json_object_get(iv, "hi_closed")) ? "]" : ")", tu_str(iv, "status"),
                 want->lo_closed ? "[" : "(", want->lo, want->hi, want->hi_closed ? "]" : ")", want->status);
}
#endif
