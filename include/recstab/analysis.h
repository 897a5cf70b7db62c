/* analysis.h -- running the analyses a case asks for.
 *
 * Only the analyses listed by the case (or --analyse) are computed
 * ("laziness"); each adds one JSON object to "results", in order.  The
 * characteristic polynomial is computed once per set of substituted values
 * and shared.  The library returns JSON (jansson); rendering to text,
 * Markdown or LaTeX is the report module's job. */
#ifndef RECSTAB_ANALYSIS_H
#define RECSTAB_ANALYSIS_H

#include <stdio.h>
#include <jansson.h>
#include "recstab/error.h"
#include "recstab/casefile.h"
#include "recstab/budget.h"
#include "recstab/sweep.h"
#include "recstab/str.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Outcome flags of a run (besides hard errors), or-ed together. */
enum {
    RS_OUTCOME_OK = 0,
    RS_OUTCOME_FAILED = 1,       /* an expectation or claim failed (exit 1) */
    RS_OUTCOME_INCONSISTENT = 2  /* two independent methods disagreed (exit 3) */
};

typedef struct {
    slong max_prec;        /* ceiling for certified numerics (bits) */
    slong default_digits;  /* radius digits when not given */
    int with_scheme;       /* add "scheme": equations and lambda-matrix (for derivations) */
    double time_limit;     /* seconds for the run (<= 0: none; budget.h) */
    double time_spent;     /* of which already used (e.g. by earlier cases) */
    slong memory_limit;    /* MB of counted memory (<= 0: none; budget.h) */
    rs_sweep_options_t sweep; /* sweeps and maps: shard, point limit, progress, first level (sweep.h) */
    struct rs_polytext_struct *polytext; /* NULL, or where long polynomials go until the report
                                            is written (str.h; the document holds placeholders) */
} rs_options_t;

void rs_options_default(rs_options_t *opt);

/* Lowers c (rs_model_lower, once) and runs every request of c on the
 * model.  On success *doc is the case's JSON document
 * {"case", "title", "params", "unknowns", "results": [...]} and *outcome
 * is RS_OUTCOME_*.  On error *doc is NULL. */
int rs_analysis_run(json_t **doc, int *outcome, const rs_case_t c,
                    const rs_options_t *opt, rs_error_t err);

/* The analyses recstab knows, from the registry (src/analysis/registry.c):
 * for each its synopsis (name, words, options), the model kinds it applies
 * to, what it gives and its options' ranges and defaults (`recstab
 * --list-analyses`); names_only: their names on one line (--help). */
void rs_analysis_list(FILE *out, int names_only);

#ifdef __cplusplus
}
#endif
#endif
