/* fuzz_common.h -- shared pieces of the libFuzzer harnesses: the caps that
 * keep one input from running for minutes, the run through the analyses and
 * every renderer, and the invariants checked on every input.
 *
 * Caps (the resource budget of issue 11 is not the harnesses' job; these
 * only keep known-big computations out so that the fuzzer looks for bugs):
 *   - at most FUZZ_MAX_UNKNOWNS unknowns (FUZZ_MAX_UNKNOWNS_SET when every
 *     parameter is set) and FUZZ_MAX_REQUESTS analyses;
 *   - no integer over FUZZ_MAX_DIGITS digits in the case text (this bounds
 *     exponents such as lambda^1000 or 10^-1000, simulate steps=, prec=,
 *     digits=, sweep steps; see fuzz_numbers_small);
 *   - --max-prec FUZZ_MAX_PREC and at most FUZZ_MAX_POINTS sweep/map points;
 *   - the run's budget (budget.h): FUZZ_TIME_LIMIT seconds, FUZZ_MEMORY_LIMIT
 *     MB; hitting it is an ordinary RS_ERR_LIMIT, a libFuzzer timeout (10 s)
 *     or RSS overflow (2 GB) means a loop without a budget check.
 *
 * Invariants (abort() = a finding):
 *   - success produces a document, an error carries a message;
 *   - no RS_ERR_INTERNAL / RS_ERR_INCONSISTENT error and no
 *     RS_OUTCOME_INCONSISTENT outcome: both mean two of recstab's own methods
 *     disagreed, i.e. a bug (set FUZZ_ALLOW_INCONSISTENT=1 to only count them);
 *   - the text report, Markdown and LaTeX renderings of the document run
 *     (ASan/UBSan watch them) and the LaTeX holds none of the primitives that
 *     touch files or redefine TeX (\input, \write, \def, ...): user text
 *     must come out escaped (fuzz_check_latex). */
#ifndef RECSTAB_FUZZ_COMMON_H
#define RECSTAB_FUZZ_COMMON_H

#include <ctype.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <jansson.h>
#include <gsl/gsl_errno.h>
#include "recstab/analysis.h"
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "recstab/derivation.h"
#include "recstab/report.h"
#include "recstab/sweep.h"

#ifndef RS_SOURCE_DIR
#define RS_SOURCE_DIR "."
#endif
/* Inputs are parsed as if they were a file in cases/, so that the seeds'
 * relative `include include/...` lines resolve. */
#define FUZZ_CASE_PATH RS_SOURCE_DIR "/cases/fuzz.case"

#define FUZZ_MAX_RUN_BYTES 4096
#define FUZZ_MAX_UNKNOWNS 4
#define FUZZ_MAX_UNKNOWNS_SET 8
#define FUZZ_MAX_REQUESTS 12
#define FUZZ_MAX_DIGITS 3
#define FUZZ_MAX_FRAC_DIGITS 12
#define FUZZ_MAX_PREC 1024
#define FUZZ_MAX_POINTS 64
#define FUZZ_TIME_LIMIT 5.0         /* s, budget.h; libFuzzer's -timeout is 25 (Makefile: FUZZ_TIMEOUT) */
#define FUZZ_MEMORY_LIMIT 1024      /* MB, budget.h; -rss_limit_mb is 2048 */

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerInitialize(int *argc, char ***argv);

static FILE *fuzz_sink;

static inline void fuzz_setup(void)
{
    gsl_set_error_handler_off();   /* once, as the recstab command does (sweep.h) */
    fuzz_sink = fopen("/dev/null", "w");
    if (fuzz_sink == NULL)
        abort();
}

/* data as a NUL-terminated string (malloc'd), or NULL */
static inline char *fuzz_text(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (text == NULL)
        return NULL;
    if (size > 0)
        memcpy(text, data, size);
    text[size] = '\0';
    return text;
}

/* 1 when, outside comments, no integer in s has more than FUZZ_MAX_DIGITS
 * digits (FUZZ_MAX_FRAC_DIGITS after '.' or '/': 0.1234 and 1/1000 are cheap,
 * lambda^1000 and steps=100000 are not) */
static inline int fuzz_numbers_small(const char *s, size_t n)
{
    size_t i, run = 0, cap = FUZZ_MAX_DIGITS;
    int comment = 0;
    for (i = 0; i < n; i++) {
        if (s[i] == '#')
            comment = 1;
        else if (s[i] == '\n')
            comment = 0;
        if (comment || !isdigit((unsigned char) s[i])) {
            run = 0;
            continue;
        }
        if (run == 0)
            cap = (i > 0 && (s[i - 1] == '.' || s[i - 1] == '/')) ? FUZZ_MAX_FRAC_DIGITS : FUZZ_MAX_DIGITS;
        if (++run > cap)
            return 0;
    }
    return 1;
}

/* 1 when every parameter of c has a `set` value (the determinant is then
 * univariate in lambda, or in the one parameter a region/sweep frees) */
static inline int fuzz_all_params_set(const rs_case_t c)
{
    slong i, j;
    for (i = 0; i < c->nparams; i++) {
        for (j = 0; j < c->nsets; j++)
            if (strcmp(c->sets[j].name, c->params[i].name) == 0)
                break;
        if (j == c->nsets)
            return 0;
    }
    return 1;
}

/* 1 when a parsed case (lowered into m) is small enough to run its analyses (the builders'
 * states are unknowns too): symbolic determinants of more than a few
 * unknowns are the budget's business, numeric ones (the Olivier cases:
 * 8 unknowns, every value set) take milliseconds */
static inline int fuzz_case_small(const rs_case_t c, const rs_model_t m)
{
    if (c->nrequests > FUZZ_MAX_REQUESTS)
        return 0;
    return m->nunknowns <= FUZZ_MAX_UNKNOWNS
           || (m->nunknowns <= FUZZ_MAX_UNKNOWNS_SET && fuzz_all_params_set(c));
}

static inline void fuzz_options(rs_options_t *opt, slong max_prec)
{
    rs_options_default(opt);
    opt->max_prec = max_prec;
    opt->time_limit = FUZZ_TIME_LIMIT;
    opt->memory_limit = FUZZ_MEMORY_LIMIT;
    opt->with_scheme = 1;          /* the derivations need the scheme */
    opt->sweep.max_points = FUZZ_MAX_POINTS;
}

static inline void fuzz_check_error(int r, const rs_error_t err)
{
    if (r == RS_OK)
        return;
    if (err->msg[0] == '\0')
        abort();                   /* every error carries a message */
    if (r == RS_ERR_INTERNAL)
        abort();
    if (r == RS_ERR_INCONSISTENT && getenv("FUZZ_ALLOW_INCONSISTENT") == NULL)
        abort();
}

/* LaTeX primitives that read or write files, run commands or redefine the
 * language: case text (titles, names, equations) must never produce them */
static inline void fuzz_check_latex(const char *tex)
{
    static const char *const bad[] = {"\\input", "\\include", "\\write", "\\openout", "\\openin",
                                      "\\read", "\\immediate", "\\catcode", "\\def", "\\csname",
                                      "\\newcommand", "\\renewcommand", "\\special", NULL};
    int i;
    for (i = 0; bad[i] != NULL; i++)
        if (strstr(tex, bad[i]) != NULL)
            abort();
}

/* every renderer over one result document */
static inline void fuzz_render(const json_t *doc)
{
    char *s = NULL;
    size_t n = 0;
    FILE *mem;
    rs_report_text(fuzz_sink, doc);
    rs_derivation_markdown(fuzz_sink, doc);
    mem = open_memstream(&s, &n);
    if (mem == NULL)
        abort();
    rs_derivation_latex(mem, doc, 1);
    rs_derivation_latex_begin(mem);
    rs_derivation_latex(mem, doc, 0);
    rs_derivation_latex_end(mem);
    fclose(mem);
    fuzz_check_latex(s);
    free(s);
    s = json_dumps(doc, JSON_INDENT(2) | JSON_PRESERVE_ORDER);
    if (s == NULL)
        abort();                   /* the JSON output must serialise */
    free(s);
}

/* Run c's analyses and render the result; checks the invariants. */
static inline void fuzz_run(rs_case_t c, const rs_options_t *opt)
{
    rs_error_t err;
    json_t *doc = NULL;
    int outcome = 0, r;
    rs_error_init(err);
    r = rs_analysis_run(&doc, &outcome, c, opt, err);
    if (r == RS_OK && doc == NULL)
        abort();                   /* success must produce a document */
    if (r != RS_OK && doc != NULL)
        abort();                   /* an error leaves no document */
    fuzz_check_error(r, err);
    if (r == RS_OK) {
        if ((outcome & RS_OUTCOME_INCONSISTENT) && getenv("FUZZ_ALLOW_INCONSISTENT") == NULL)
            abort();
        fuzz_render(doc);
        json_decref(doc);
    }
}

#endif
