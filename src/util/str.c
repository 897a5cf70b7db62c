/* str.c -- string copies and UTF-8 checks; see include/recstab/str.h. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <flint/flint.h>
#include "recstab/str.h"

char *rs_strdup(const char *s)
{
    size_t n = strlen(s);
    char *d = flint_malloc(n + 1);
    memcpy(d, s, n + 1);
    return d;
}

char *rs_strndup(const char *s, size_t n)
{
    char *d = flint_malloc(n + 1);
    memcpy(d, s, n);
    d[n] = '\0';
    return d;
}

void rs_str_catf(char **s, const char *fmt, ...)
{
    va_list ap;
    size_t len = *s != NULL ? strlen(*s) : 0;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    *s = flint_realloc(*s, len + (size_t) n + 1);
    va_start(ap, fmt);
    vsnprintf(*s + len, (size_t) n + 1, fmt, ap);
    va_end(ap);
}

int rs_utf8_seq_len(const char *s, size_t n)
{
    const unsigned char *u = (const unsigned char *) s;
    size_t need, k;
    unsigned long v;
    if (n == 0) return 0;
    if (u[0] < 0x80) return 1;
    if (u[0] >= 0xc2 && u[0] <= 0xdf) { need = 1; v = u[0] & 0x1f; }
    else if ((u[0] & 0xf0) == 0xe0) { need = 2; v = u[0] & 0x0f; }
    else if (u[0] >= 0xf0 && u[0] <= 0xf4) { need = 3; v = u[0] & 0x07; }
    else return 0;
    if (n <= need) return 0;
    for (k = 1; k <= need; k++) {
        if ((u[k] & 0xc0) != 0x80) return 0;
        v = (v << 6) | (u[k] & 0x3f);
    }
    if ((need == 2 && v < 0x800) || (need == 3 && (v < 0x10000 || v > 0x10ffff)) || (v >= 0xd800 && v <= 0xdfff))
        return 0;
    return (int) need + 1;
}

char *rs_utf8_escape(const char *s)
{
    size_t n = strlen(s), i = 0, o = 0;
    char *d = flint_malloc(4 * n + 1);
    while (i < n) {
        int k = rs_utf8_seq_len(s + i, n - i);
        if (k == 0) {
            snprintf(d + o, 5, "\\x%02x", (unsigned char) s[i]);
            o += 4;
            i++;
        } else {
            memcpy(d + o, s + i, (size_t) k);
            o += (size_t) k;
            i += (size_t) k;
        }
    }
    d[o] = '\0';
    return d;
}
