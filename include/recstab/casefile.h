/* casefile.h -- the case-file language: parsing a .case file into an
 * rs_case_t (no mathematics yet; see scheme.h for meaning).
 *
 * Line-oriented; '#' starts a comment; a line ending in '\' continues on
 * the next.  Statements: title, param, assume, unknown, let, eq, char, set, label,
 * analyse (analyze), expect, claim, include, recurrence and the builder
 * statements (subsystem, NAME' = EXPR, integrate, couple, iterations,
 * extrapolate, coupling force).  Every item keeps its file:line:col, and so
 * does every node of its expressions.  Parsing reads syntax only: meaning
 * (equations, matrices) is given by lowering, src/lower/ (model.h), which
 * only reads the case. */
#ifndef RECSTAB_CASEFILE_H
#define RECSTAB_CASEFILE_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include "recstab/error.h"
#include "recstab/expr.h"
#include "recstab/str.h"

#ifdef __cplusplus
extern "C" {
#endif

#define RS_CASE_MAX_BYTES (16L * 1024 * 1024) /* whole file */
#define RS_CASE_MAX_LINE (1024 * 1024)        /* one logical statement (a degree-500 char line with 400-digit coefficients fits) */
#define RS_CASE_MAX_INCLUDES 256              /* distinct files read by include */
#define RS_CASE_MAX_INCLUDE_BYTES (16L * 1024 * 1024) /* all of them together (16 MiB) */
#define RS_CASE_MAX_NAMES 256                 /* params + unknowns + lets */
#define RS_CASE_MAX_ITERATIONS 16             /* `iterations K` */
#define RS_CASE_MAX_EXTRAPOLATE 6             /* `extrapolate order K` */

typedef struct {
    char *file;       /* file the item came from */
    int line, col;
} rs_loc_t;

typedef struct {
    char *name;
    rs_loc_t loc;
    int angle;             /* `param NAME angle`: the exact variable is t = tan(NAME/2) */
    int complex;           /* `param NAME complex`: Re and Im are two real directions (z of y' = z y
                              may be named z here) */
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
    char *text;            /* source text "lhs = rhs" (in a model: the printed trees
                              of a generated equation) */
} rs_eq_t;

typedef struct {
    char *name;
    fmpq_t value;
    rs_loc_t loc;
} rs_set_t;

/* `set NAME = A + B*i` with B != 0 (or --set NAME=A+B*i): a complex value,
 * kept apart from the real ones so that every real route sees NAME unset;
 * the analyses that run over Q(i) (stability, radius, charpoly, bilinear,
 * routh) substitute it, the others refuse. */
typedef struct {
    char *name;
    fmpq_t re, im;
    rs_loc_t loc;
} rs_cset_t;

/* An analysis request: the text after `analyse`, or a whole `expect ...` /
 * `claim ...` line (text starts with that keyword). */
typedef struct {
    char *text;
    rs_loc_t loc;          /* position of text[0] */
} rs_request_t;

/* A term A_K z[n+K] of a matrix recurrence (lowered by src/lower/recurrence.c). */
typedef struct {
    slong k;               /* the shift K */
    slong rows, cols;
    rs_expr_t **entries;   /* rows * cols, row-major */
    rs_loc_t loc;
} rs_recterm_t;

/* Builder statements (lowered by src/lower/builder.c). */

/* NAME' = EXPR or NAME'' = EXPR inside a subsystem block */
typedef struct {
    char *state;           /* NAME */
    int order;             /* 1 or 2 (NAME'' = EXPR) */
    rs_expr_t *rhs;        /* EXPR */
    rs_loc_t loc;          /* position of NAME */
} rs_deq_t;

/* `coupling force NAME = EXPR` */
typedef struct {
    char *name;
    rs_expr_t *e;
    rs_loc_t loc;          /* position of NAME */
} rs_force_t;

/* `subsystem NAME state X V ...`, its state equations and its
 * `integrate NAME METHOD [ARG1 [ARG2]] STEP` */
typedef struct {
    char *name;
    rs_loc_t loc;
    slong nstates;   rs_name_t *states;
    slong ndeqs;     rs_deq_t *deqs;
    char *method;          /* integrator, NULL until `integrate` */
    rs_expr_t *arg1, *arg2; /* theta T / newmark B G, or NULL */
    rs_expr_t *step;       /* the step */
    rs_loc_t intloc;       /* position of METHOD */
    char *tableau;         /* rk NAME, or NULL */
    slong ntab; fmpq *tab; /* rk [A | b] inline: s*s + s entries, A by rows then b */
    slong korder;          /* adams-bashforth/adams-moulton/bdf K */
} rs_subsystem_t;

/* The case: a typed syntax tree of the statements read (the include files'
 * statements in place), plus the `--set` values and `--analyse` requests of
 * the command line.  Syntax only: the unknowns and equations the builders
 * and recurrence terms stand for are in the model (rs_model_lower, model.h). */
typedef struct {
    char *path;            /* as given ("-" for stdin) */
    char *title;
    slong nlabels;   char **label_names, **label_texts;   /* `label NAME = "TEXT"` */
    slong nparams;   rs_name_t *params;
    slong nunknowns; rs_name_t *unknowns;
    slong nassume;   rs_cond_t *assume;
    slong nlets;     rs_let_t *lets;
    slong neqs;      rs_eq_t *eqs;
    rs_expr_t *charexpr;   /* `char EXPR`, or NULL */
    rs_loc_t charloc;
    slong nsets;     rs_set_t *sets;
    slong ncsets;    rs_cset_t *csets;   /* complex set values (not in sets) */
    slong nrequests; rs_request_t *requests;
    /* builders */
    slong nsubs;     rs_subsystem_t *subs;
    char *couple;          /* jacobi, gauss-seidel, monolithic, explicit, implicit */
    char *couple_first, *couple_second;
    slong ncouple_seq; char **couple_seq;   /* gauss-seidel S1 S2 ... Sn: the order of integration */
    slong couple_order;    /* explicit/implicit order K */
    int couple_ext;        /* implicit ... extension D|I: 'D', 'I' or 0 */
    fmpq *couple_alpha;    /* extension I alpha_T = VALUE (NULL: 1/2) */
    rs_loc_t couple_loc;
    slong iterations;      /* 0 = none */
    slong extrapolate;     /* -1 = none (order 0 = hold the last value) */
    slong nforces;   rs_force_t *forces;   /* `coupling force` statements */
    slong nrec;      rs_recterm_t *rec;    /* `recurrence K = [...]` terms */
    /* the files read (the case file first): expression nodes point at these names */
    slong nfiles;    char **files;
} rs_case_struct;
typedef rs_case_struct rs_case_t[1];

void rs_case_init(rs_case_t c);
void rs_case_clear(rs_case_t c);
/* Clears of the sub-structures (each leaves its argument zeroed). */
void rs_loc_clear(rs_loc_t *l);
void rs_name_clear(rs_name_t *n);
void rs_let_clear(rs_let_t *l);
void rs_eq_clear(rs_eq_t *q);
void rs_set_clear(rs_set_t *s);
void rs_cset_clear(rs_cset_t *s);
void rs_request_clear(rs_request_t *q);
void rs_recterm_clear(rs_recterm_t *t);
void rs_deq_clear(rs_deq_t *d);
void rs_force_clear(rs_force_t *f);
void rs_subsystem_clear(rs_subsystem_t *s);

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
 * is not a parameter.  VALUE may be complex (A + B*i). */
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
int rs_name_is_reserved(const char *name); /* lambda, z, n, i */
/* Why name cannot be declared (a short phrase), or NULL when it can. */
const char *rs_name_reserved_why(const char *name);

#ifdef __cplusplus
}
#endif
#endif
