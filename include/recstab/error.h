/* error.h -- error reporting for librecstab.
 *
 * The library never prints and never exits: every fallible function returns
 * an int status (RS_OK = 0) and fills an rs_error_t with a message.  The CLI
 * maps codes to exit statuses (input/limit -> 2, inconsistent -> 3). */
#ifndef RECSTAB_ERROR_H
#define RECSTAB_ERROR_H

#include <stdarg.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

enum {
    RS_OK = 0,
    RS_ERR_INPUT = 1,        /* malformed case file, bad option, bad value */
    RS_ERR_LIMIT = 2,        /* a resource limit (degree, terms, precision) */
    RS_ERR_MATH = 3,         /* mathematically impossible request (singular det, ...) */
    RS_ERR_INCONSISTENT = 4, /* two independent methods disagree: a bug */
    RS_ERR_IO = 5,           /* file system */
    RS_ERR_INTERNAL = 6,     /* should not happen */
    RS_ERR_UNDECIDED = 7     /* numeric method could not decide within limits */
};

#define RS_ERROR_MSG_LEN 1024
#define RS_ERROR_FILE_LEN 512

typedef struct {
    int code;
    char file[RS_ERROR_FILE_LEN]; /* empty when the error has no location */
    int line;                     /* 1-based, 0 when unknown */
    int col;                      /* 1-based, 0 when unknown */
    char msg[RS_ERROR_MSG_LEN];
} rs_error_struct;

typedef rs_error_struct rs_error_t[1];

void rs_error_init(rs_error_t err);
void rs_error_clear(rs_error_t err);

/* Set code and a printf-style message; returns code so that callers can
 * write `return rs_error_set(err, RS_ERR_INPUT, "...")`.  err may be NULL. */
int rs_error_set(rs_error_t err, int code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
int rs_error_set_at(rs_error_t err, int code, const char *file, int line,
                    int col, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
int rs_error_vset(rs_error_t err, int code, const char *fmt, va_list ap);

/* "file:line:col: msg" (or just msg) into buf. */
void rs_error_format(char *buf, size_t len, const rs_error_t err);

/* Short name of a code, e.g. "input". */
const char *rs_error_code_name(int code);

/* GSL's error handler switched off for the whole process, once and
 * thread-safely (pthread_once): GSL's default handler aborts the process
 * when a routine fails (a root finder that does not converge, a singular
 * LU), and a handler saved and restored around each call races between
 * threads.  rs_analyse_json and the co-simulation's double eigenvectors
 * call it; a program that uses the typed API from several threads calls
 * it (or gsl_set_error_handler_off) before starting them.  A program that
 * wants its own GSL handler sets it after the first call. */
void rs_gsl_quiet(void);

#ifdef __cplusplus
}
#endif
#endif
