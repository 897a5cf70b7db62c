/* error.c -- see include/recstab/error.h */
#include <pthread.h>
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include "recstab/error.h"

void rs_error_init(rs_error_t err)
{
    memset(err, 0, sizeof(rs_error_struct));
}

void rs_error_clear(rs_error_t err)
{
    (void) err;
}

int rs_error_vset(rs_error_t err, int code, const char *fmt, va_list ap)
{
    if (err == NULL)
        return code;
    err->code = code;
    err->file[0] = '\0';
    err->line = err->col = 0;
    vsnprintf(err->msg, sizeof(err->msg), fmt, ap);
    return code;
}

int rs_error_set(rs_error_t err, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rs_error_vset(err, code, fmt, ap);
    va_end(ap);
    return code;
}

int rs_error_set_at(rs_error_t err, int code, const char *file, int line,
                    int col, const char *fmt, ...)
{
    va_list ap;
    if (err == NULL)
        return code;
    va_start(ap, fmt);
    rs_error_vset(err, code, fmt, ap);
    va_end(ap);
    snprintf(err->file, sizeof(err->file), "%s", file ? file : "");
    err->line = line;
    err->col = col;
    return code;
}

void rs_error_format(char *buf, size_t len, const rs_error_t err)
{
    if (err->file[0] != '\0' && err->line > 0)
        snprintf(buf, len, "%s:%d:%d: %s", err->file, err->line,
                 err->col > 0 ? err->col : 1, err->msg);
    else if (err->file[0] != '\0')
        snprintf(buf, len, "%s: %s", err->file, err->msg);
    else
        snprintf(buf, len, "%s", err->msg);
}

const char *rs_error_code_name(int code)
{
    switch (code) {
    case RS_OK: return "ok";
    case RS_ERR_INPUT: return "input";
    case RS_ERR_LIMIT: return "limit";
    case RS_ERR_MATH: return "math";
    case RS_ERR_INCONSISTENT: return "inconsistent";
    case RS_ERR_IO: return "io";
    case RS_ERR_INTERNAL: return "internal";
    case RS_ERR_UNDECIDED: return "undecided";
    default: return "unknown";
    }
}

static pthread_once_t gsl_once = PTHREAD_ONCE_INIT;

static void gsl_off(void)
{
    gsl_set_error_handler_off();
}

void rs_gsl_quiet(void)
{
    pthread_once(&gsl_once, gsl_off);
}
