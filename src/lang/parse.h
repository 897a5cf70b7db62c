/* parse.h -- private to src/lang/: the state of one parse (the case being
 * filled, the include bookkeeping) and the helpers the statement parsers
 * share.  Not installed. */
#ifndef RS_LANG_PARSE_H
#define RS_LANG_PARSE_H

#include <string.h>
#include <sys/types.h>
#include "recstab/casefile.h"

/* a file read in this parse, by device and inode: each is read once, and
 * one still being read (open) is an include cycle */
typedef struct {
    dev_t dev;
    ino_t ino;
    int open;
} rs_include_t;

typedef struct {
    rs_case_struct *c;
    rs_error_struct *err;
    int include_depth;
    slong nincludes; rs_include_t *includes;
    slong include_bytes;   /* bytes read by include */
} rs_parser_t;

/* one logical statement being parsed */
typedef struct {
    rs_parser_t *p;
    rs_case_struct *c;
    rs_src_t src;          /* src.file is one of c->files */
    rs_error_struct *err;
} rs_stmt_t;

/* room for arr[n], zeroed */
#define RS_GROW(arr, n) ((arr) = flint_realloc((arr), ((n) + 1) * sizeof(*(arr))), \
                         memset(&(arr)[n], 0, sizeof(*(arr))))

void _rs_skip_ws(const char *t, size_t *i);
/* the error code; the message fmt has one %s (found) */
int _rs_at_err(rs_stmt_t *x, size_t i, int code, const char *fmt, const char *found);
/* "expected EXPECTED, found <what stands at i>" */
int _rs_expect_err(rs_stmt_t *x, size_t i, const char *expected);
int _rs_name_err(rs_stmt_t *x, size_t i, const char *expected);
void _rs_describe(char *buf, size_t len, const char *t, size_t i);
void _rs_set_loc(rs_stmt_t *x, rs_loc_t *l, size_t i);
/* an identifier of at most 64 characters at *i (advanced), or NULL */
char *_rs_read_ident(const char *t, size_t *i);
/* a word up to a blank or ',' (method names, numbers), or NULL */
char *_rs_read_token(const char *t, size_t *i);
/* the source of text[i..] (the same positions), or of a copy of n bytes */
rs_src_t _rs_src_from(const rs_src_t *src, size_t i, const char *text);

/* `set NAME = v` (replacing an earlier value of NAME) */
void _rs_case_set_one(rs_case_struct *c, const char *name, const fmpq_t v, const char *file, int line, int col);
/* a complex value (a real one when im = 0), replacing any earlier value of name */
void _rs_case_set_complex(rs_case_struct *c, const char *name, const fmpq_t re, const fmpq_t im,
                          const char *file, int line, int col);

/* statements of stmt_builder.c / stmt_recurrence.c (keyword read; i after it) */
int _rs_builder_is_keyword(const char *word);
int _rs_st_builder(rs_stmt_t *x, const char *keyword, size_t i);
int _rs_st_state_equation(rs_stmt_t *x, const char *state, size_t i);
int _rs_st_recurrence(rs_stmt_t *x, size_t i);

#endif
