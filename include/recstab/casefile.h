/* casefile.h -- the case-file language: parsing a .case file into an
 * rs_case_t (no mathematics yet; see scheme.h for meaning).
 *
 * Line-oriented; '#' starts a comment; a line ending in '\' continues on
 * the next.  Statements: title, param, assume, unknown, let, eq, char, set,
 * analyse (analyze), expect, claim.  Every item keeps its file:line:col. */
#ifndef RECSTAB_CASEFILE_H
#define RECSTAB_CASEFILE_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include "recstab/error.h"
#include "recstab/expr.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_CASE_MAX_BYTES (16L * 1024 * 1024) /* whole file */
#define RS_CASE_MAX_LINE 65536                /* one logical statement */
#define RS_CASE_MAX_NAMES 256                 /* params + unknowns + lets */

typedef struct {
    char *file;       /* file the item came from */
    int line, col;
} rs_loc_t;

typedef struct {
    char *name;
    rs_loc_t loc;
} rs_name_t;

typedef enum { RS_CMP_LT, RS_CMP_LE, RS_CMP_GT, RS_CMP_GE, RS_CMP_NE, RS_CMP_EQ } rs_cmp_t;

/* A comparison chain e0 op0 e1 [op1 e2], e.g. 0 <= alpha <= 2. */
typedef struct {
    slong n;               /* number of expressions (2 or 3) */
    rs_expr_t *e[3];
    rs_cmp_t op[2];
    char *text;            /* source text of the condition */
    rs_loc_t loc;
} rs_cond_t;

typedef struct {
    char *name;
    int shifted;           /* let NAME[n+K] = ... */
    slong shift;           /* K */
    rs_expr_t *e;
    rs_loc_t loc;
    char *text;            /* source text after `let` */
} rs_let_t;

typedef struct {
    rs_expr_t *lhs, *rhs;
    rs_loc_t loc;
    char *text;            /* source text "lhs = rhs" */
} rs_eq_t;

typedef struct {
    char *name;
    fmpq_t value;
    rs_loc_t loc;
} rs_set_t;

/* An analysis request: the text after `analyse`, or a whole `expect ...` /
 * `claim ...` line (text starts with that keyword). */
typedef struct {
    char *text;
    rs_loc_t loc;          /* position of text[0] */
} rs_request_t;

typedef struct {
    char *path;            /* as given ("-" for stdin) */
    char *title;
    slong nparams;   rs_name_t *params;
    slong nunknowns; rs_name_t *unknowns;
    slong nassume;   rs_cond_t *assume;
    slong nlets;     rs_let_t *lets;
    slong neqs;      rs_eq_t *eqs;
    rs_expr_t *charexpr;   /* `char EXPR`, or NULL */
    rs_loc_t charloc;
    slong nsets;     rs_set_t *sets;
    slong nrequests; rs_request_t *requests;
    rs_loc_t unknown_loc;  /* first `unknown` statement */
} rs_case_struct;
typedef rs_case_struct rs_case_t[1];

void rs_case_init(rs_case_t c);
void rs_case_clear(rs_case_t c);

/* Parse the text of a case file.  `path` is used in messages. */
int rs_case_parse_string(rs_case_t c, const char *path, const char *text,
                         size_t len, rs_error_t err);
/* Read and parse a file ("-" reads stdin). */
int rs_case_parse_file(rs_case_t c, const char *path, rs_error_t err);

/* Index of a parameter / unknown / let by name, or -1. */
slong rs_case_param_index(const rs_case_t c, const char *name);
slong rs_case_unknown_index(const rs_case_t c, const char *name);
slong rs_case_let_index(const rs_case_t c, const char *name);

/* Add or override `set NAME = VALUE` (from --set NAME=VALUE); errors if NAME
 * is not a parameter. */
int rs_case_set_value(rs_case_t c, const char *assignment, rs_error_t err);

/* Drop every request (for --analyse) / append one. */
void rs_case_clear_requests(rs_case_t c);
void rs_case_add_request(rs_case_t c, const char *text, const char *file,
                         int line, int col);

/* Parse one condition chain from src at *pos (stops at ',' or the word
 * 'and' or end). */
int rs_cond_parse(rs_cond_t *cond, const rs_src_t *src, size_t *pos,
                  rs_error_t err);
void rs_cond_clear(rs_cond_t *cond);

/* Name validity helpers. */
int rs_name_is_reserved(const char *name); /* lambda, z, n */

#ifdef __cplusplus
}
#endif
#endif
