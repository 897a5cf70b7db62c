/* expr.h -- expressions of the case-file language.
 *
 * EXPR: integers, decimals (exact: 0.1 = 1/10), rationals via '/', names,
 * shifted sequences NAME[n], NAME[n+K], NAME[n-K], + - * / ^ (integer
 * powers), parentheses, unary minus, and 10^-40 style powers.  Parsing builds
 * a tree whose nodes keep their source line and column for error messages;
 * meaning (parameter, unknown, let) is assigned later by the scheme module. */
#ifndef RECSTAB_EXPR_H
#define RECSTAB_EXPR_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include "recstab/error.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    RS_EXPR_NUM,   /* exact rational */
    RS_EXPR_NAME,  /* identifier, optionally shifted */
    RS_EXPR_ADD, RS_EXPR_SUB, RS_EXPR_MUL, RS_EXPR_DIV, RS_EXPR_POW,
    RS_EXPR_NEG,
    RS_EXPR_CALL   /* NAME(EXPR): exp, log, sqrt, sin, cos, ... (numeric only) */
} rs_expr_kind_t;

typedef struct rs_expr_struct {
    rs_expr_kind_t kind;
    const char *file;                /* source file of the node: not owned (the case's
                                        file list or the caller's rs_src_t keeps it) */
    int line, col;                   /* source position of the node */
    fmpq_t num;                      /* RS_EXPR_NUM */
    char *lit;                       /* RS_EXPR_NUM: its spelling ("0.5", "1e-3"), or NULL */
    char *name;                      /* RS_EXPR_NAME, RS_EXPR_CALL */
    int shifted;                     /* NAME[n+K] written */
    slong shift;                     /* K */
    int shift_signed;                /* K written with a sign: +1 '+', -1 '-' (x[n+0], x[n-0] print back) */
    int paren;                       /* pairs of parentheses written around the node */
    struct rs_expr_struct *a, *b;    /* operands */
} rs_expr_struct;
typedef rs_expr_struct rs_expr_t;

/* The file of node e, or dflt for a node without one. */
static inline const char *rs_expr_file(const rs_expr_t *e, const char *dflt)
{
    return e->file != NULL ? e->file : dflt;
}

/* Source text being parsed: where errors point. */
typedef struct {
    const char *file;   /* file name for messages */
    const char *text;   /* the statement text (continuations joined) */
    int line;           /* line of text[0] */
    int col;            /* column of text[0] */
    const int *linemap; /* optional: for joined continuation lines, linemap[i]
                           and colmap[i] give the source position of text[i] */
    const int *colmap;
} rs_src_t;

/* Parse text[*pos ..] as one expression; stops at end, ',', '=', ';' or a
 * comparison operator at depth 0 and leaves *pos there.  *out is NULL on
 * error.  Limits: nesting depth RS_EXPR_MAX_DEPTH, exponents |k| <= RS_EXPR_MAX_POW. */
#define RS_EXPR_MAX_DEPTH 200
#define RS_EXPR_MAX_POW 100000
int rs_expr_parse(rs_expr_t **out, const rs_src_t *src, size_t *pos,
                  rs_error_t err);

/* Parse a whole string as one expression (nothing may follow). */
int rs_expr_parse_all(rs_expr_t **out, const rs_src_t *src, rs_error_t err);

/* Parse an exact number "12", "0.1", "3/2", "-2.5e-3", "10^-40" (used by
 * `set` and --set).  Returns RS_OK or RS_ERR_INPUT. */
int rs_expr_parse_number(fmpq_t q, const char *s, rs_error_t err);

/* Evaluate a tree made only of numbers and + - * / ^ (errors name the node;
 * src->file is used for messages). */
int rs_expr_eval_const(fmpq_t q, const rs_expr_t *e, const rs_src_t *src,
                       rs_error_t err);

/* The same over Q(i): the name i (when the case declares nothing of that
 * name: the caller checks) is the imaginary unit; q = re + i im. */
int rs_expr_eval_const_complex(fmpq_t re, fmpq_t im, const rs_expr_t *e, const rs_src_t *src,
                               rs_error_t err);

/* rs_expr_parse_number over Q(i) (--set NAME=A+B*i). */
int rs_expr_parse_complex(fmpq_t re, fmpq_t im, const char *s, rs_error_t err);

void rs_expr_free(rs_expr_t *e);
rs_expr_t *rs_expr_copy(const rs_expr_t *e);

/* Building trees (the lowering stage's builders): every new node takes the
 * position (file, line, col) it is given; operands are owned by the result. */
rs_expr_t *rs_expr_new_num(slong v, const char *file, int line, int col);
rs_expr_t *rs_expr_new_name(const char *name, int shifted, slong shift,
                            const char *file, int line, int col);
rs_expr_t *rs_expr_new_op(rs_expr_kind_t kind, rs_expr_t *a, rs_expr_t *b,
                          const char *file, int line, int col);
/* e with one more pair of parentheses around it (printing only). */
rs_expr_t *rs_expr_paren(rs_expr_t *e);

/* Structural equality: kinds, numbers, names and shifts (positions,
 * parentheses and spellings ignored). */
int rs_expr_equal(const rs_expr_t *a, const rs_expr_t *b);

/* The tree as case-file text (flint_malloc'd): "a + b", "a - b", "a*b",
 * "a/b", "a^b", "-a", "f(a)", numbers as spelled, the written parentheses
 * (and those the operator precedence needs). */
char *rs_expr_str(const rs_expr_t *e);
/* "LHS = RHS" printed the same way (an equation's text). */
char *rs_expr_eq_str(const rs_expr_t *lhs, const rs_expr_t *rhs);

/* Source position of text[i] in src. */
void rs_src_pos(const rs_src_t *src, size_t i, int *line, int *col);

#ifdef __cplusplus
}
#endif
#endif
