/* api.h -- running a whole case: the one-call API and the driver that the
 * recstab command runs too (src/analysis/driver.c), so that the command and
 * the API produce the same document and the same exit status. */
#ifndef RECSTAB_API_H
#define RECSTAB_API_H

#include <jansson.h>
#include "recstab/error.h"
#include "recstab/analysis.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the command line adds to a case: --set values, --analyse requests
 * (replacing the case's own), --emit equations, and the run's options. */
typedef struct {
    const char *const *sets;      /* "NAME=VALUE" each, like --set */
    int nsets;
    const char *const *analyses;  /* "ANALYSIS [OPTIONS]", "expect ...", "claim ...", like --analyse */
    int nanalyses;
    int emit;                     /* 1: {"case", "equations"} instead of the analyses */
    rs_options_t opt;             /* rs_options_default, then changed as needed */
} rs_run_options_t;

/* Defaults: no --set, the case's own requests, the command's option defaults. */
void rs_run_options_default(rs_run_options_t *ro);

/* One case, from its text (text != NULL; path names it in messages and
 * locates its includes) or read from path ("-": stdin), with ro applied:
 * RS_OK and *doc the case's JSON document (*outcome: RS_OUTCOME_* bits), or
 * an error code with err filled and *doc NULL.  Never prints. */
int rs_run_case(json_t **doc, int *outcome, const char *path, const char *text,
                const rs_run_options_t *ro, rs_error_t err);

/* The exit status of the command: 2 for an error code (3 for
 * RS_ERR_INCONSISTENT and RS_ERR_INTERNAL), else from the outcome bits
 * (1 a claim or expectation failed, 3 two methods disagreed, 0 done),
 * never better than worst (the status of earlier cases, 0 for none). */
int rs_run_exit_status(int code, int outcome, int worst);

/* The document `recstab --json` prints for the documents of the cases of a
 * run (a JSON array docs): always {"cases": [DOC, ...]}, whatever the number
 * of cases (ncases is not used: the shape never depends on it).  The CSV
 * text of the sweeps and maps ("table", "boundary_table": what the command
 * writes to --csv files) is removed from docs; their "rows" stay.  A new
 * reference. */
json_t *rs_run_json_document(json_t *docs, int ncases);

/* The document as `recstab --json` prints it (malloc'd, free()): indented
 * two spaces, each row of "rows" and "boundary_rows" on one line, a final
 * newline; NULL when memory ran out. */
char *rs_run_json_dumps(json_t *top);
/* The same for documents whose maps were streamed to files
 * (rs_sweep_options_t.table_spool): spool(arg, id) gives back the stream
 * of table id (read from its start), whose rows are written as "rows". */
char *rs_run_json_dumps_spool(json_t *top, FILE *(*spool)(void *arg, slong id), void *arg);
/* The same written to f (a map's rows go from its spool to f one at a
 * time); 0, or -1 when memory ran out (f's own errors: ferror(f)). */
int rs_run_json_dumpf(FILE *f, json_t *top, FILE *(*spool)(void *arg, slong id), void *arg);
/* The same for documents whose long polynomials wait in pt (rs_options_t
 * .polytext, str.h): each printed where its placeholder is. */
int rs_run_json_dumpf_polytext(FILE *f, json_t *top, FILE *(*spool)(void *arg, slong id), void *arg,
                               rs_polytext_t pt);

/* The one-call API: runs case_text (named source_name in messages, includes
 * relative to it; NULL: "<string>") exactly as `recstab --json` would and
 * returns the command's exit status, 0 done, 1 a claim or expectation
 * failed, 2 bad input or a limit, 3 two of recstab's methods disagree.
 * *json receives the document as the command prints it (free it with
 * rs_free); on status 2 and errors without a document (and 3 from an
 * internal error), {"error": {"code", "message", "file", "line", "col"}}
 * with the message the command prints on stderr.  *json is NULL only when
 * memory ran out or json is NULL. */
int rs_analyse_json(const char *case_text, const char *source_name, char **json);

/* rs_analyse_json with --set, --analyse and the options of ro (NULL: the
 * defaults). */
int rs_analyse_json_opt(const char *case_text, const char *source_name,
                        const rs_run_options_t *ro, char **json);

/* flags of rs_analyse_json_with: the document carries "scheme" (the
 * equations and lambda-matrix that --markdown and --latex show) */
#define RS_RUN_SCHEME 1

/* rs_analyse_json with --set values ("NAME=VALUE") and --analyse requests,
 * each a NULL-terminated list (NULL: none), flags (RS_RUN_*) and the
 * budget: time_limit seconds and memory_limit MB (< 0: the command's
 * defaults, 600 s and half of the RAM; 0: none), as --time-limit and
 * --memory-limit; for callers that cannot build rs_run_options_t (ctypes,
 * other languages). */
int rs_analyse_json_with(const char *case_text, const char *source_name, const char *const *sets,
                         const char *const *analyses, int flags, double time_limit, long memory_limit,
                         char **json);

/* Frees what the library returned to the caller (rs_analyse_json's *json). */
void rs_free(void *p);

#ifdef __cplusplus
}
#endif
#endif
