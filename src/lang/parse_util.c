/* parse_util.c -- helpers shared by the statement parsers (parse.h). */
#include <ctype.h>
#include <stdio.h>
#include <string.h>
#include "parse.h"

void _rs_skip_ws(const char *t, size_t *i)
{
    while (t[*i] == ' ' || t[*i] == '\t' || t[*i] == '\r')
        (*i)++;
}

int _rs_at_err(rs_stmt_t *x, size_t i, int code, const char *fmt, const char *found)
{
    int line, col;
    rs_src_pos(&x->src, i, &line, &col);
    return rs_error_set_at(x->err, code, x->src.file, line, col, fmt, found);
}

void _rs_describe(char *buf, size_t len, const char *t, size_t i)
{
    unsigned char ch = (unsigned char) t[i];
    if (ch == '\0')
        snprintf(buf, len, "end of line");
    else if (isalnum(ch) || ch == '_') {
        size_t j = i;
        while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
        snprintf(buf, len, "'%.*s'", (int) (j - i > 40 ? 40 : j - i), t + i);
    } else if (ch < 32 || ch >= 127)
        snprintf(buf, len, "byte 0x%02x", ch);
    else
        snprintf(buf, len, "'%c'", ch);
}

int _rs_expect_err(rs_stmt_t *x, size_t i, const char *expected)
{
    char found[64], msg[256];
    _rs_describe(found, sizeof found, x->src.text, i);
    snprintf(msg, sizeof msg, "expected %s, found %%s", expected);
    return _rs_at_err(x, i, RS_ERR_INPUT, msg, found);
}

/* A name was expected at i: says so, or that the name there is too long. */
int _rs_name_err(rs_stmt_t *x, size_t i, const char *expected)
{
    const char *t = x->src.text;
    if (isalpha((unsigned char) t[i]) || t[i] == '_') {
        size_t j = i;
        int line, col;
        while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
        rs_src_pos(&x->src, i, &line, &col);
        return rs_error_set_at(x->err, RS_ERR_LIMIT, x->src.file, line, col,
                               "name too long: %zu characters (limit 64)", j - i);
    }
    return _rs_expect_err(x, i, expected);
}

void _rs_set_loc(rs_stmt_t *x, rs_loc_t *l, size_t i)
{
    l->file = rs_strdup(x->src.file);
    rs_src_pos(&x->src, i, &l->line, &l->col);
}

char *_rs_read_ident(const char *t, size_t *i)
{
    size_t j = *i;
    char *s;
    if (!(isalpha((unsigned char) t[j]) || t[j] == '_'))
        return NULL;
    while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
    if (j - *i > 64)
        return NULL;
    s = rs_strndup(t + *i, j - *i);
    *i = j;
    return s;
}

char *_rs_read_token(const char *t, size_t *i)
{
    size_t j;
    char *s;
    while (t[*i] == ' ' || t[*i] == '\t') (*i)++;
    j = *i;
    while (t[j] && t[j] != ' ' && t[j] != '\t' && t[j] != ',') j++;
    if (j == *i) return NULL;
    s = rs_strndup(t + *i, j - *i);
    *i = j;
    return s;
}

rs_src_t _rs_src_from(const rs_src_t *src, size_t i, const char *text)
{
    rs_src_t s = *src;
    s.text = text != NULL ? text : src->text + i;
    if (src->linemap != NULL) {
        s.linemap = src->linemap + i;
        s.colmap = src->colmap + i;
    } else {
        s.col = src->col + (int) i;
    }
    return s;
}
