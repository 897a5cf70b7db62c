/* cond_parse.c -- rs_cond_parse: a comparison chain e0 op0 e1 [op1 e2]
 * (`assume`, region and claim conditions). */
#include <string.h>
#include "parse.h"

void rs_cond_clear(rs_cond_t *cond)
{
    slong i;
    for (i = 0; i < 3; i++)
        rs_expr_free(cond->e[i]);
    flint_free(cond->text);
    rs_loc_clear(&cond->loc);
    memset(cond, 0, sizeof(rs_cond_t));
}

static int read_cmp(const char *t, size_t *i, rs_cmp_t *op)
{
    if (t[*i] == '<' && t[*i + 1] == '=') { *op = RS_CMP_LE; *i += 2; return 1; }
    if (t[*i] == '>' && t[*i + 1] == '=') { *op = RS_CMP_GE; *i += 2; return 1; }
    if (t[*i] == '!' && t[*i + 1] == '=') { *op = RS_CMP_NE; *i += 2; return 1; }
    if (t[*i] == '<') { *op = RS_CMP_LT; *i += 1; return 1; }
    if (t[*i] == '>') { *op = RS_CMP_GT; *i += 1; return 1; }
    if (t[*i] == '=' && t[*i + 1] == '=') { *op = RS_CMP_EQ; *i += 2; return 1; }
    if (t[*i] == '=') { *op = RS_CMP_EQ; *i += 1; return 1; }
    return 0;
}

int rs_cond_parse(rs_cond_t *cond, const rs_src_t *src, size_t *pos, rs_error_t err)
{
    const char *t = src->text;
    size_t i = *pos, start;
    int r;
    memset(cond, 0, sizeof(rs_cond_t));
    _rs_skip_ws(t, &i);
    start = i;
    cond->loc.file = rs_strdup(src->file ? src->file : "");
    rs_src_pos(src, i, &cond->loc.line, &cond->loc.col);
    r = rs_expr_parse(&cond->e[0], src, &i, err);
    if (r != RS_OK) { rs_cond_clear(cond); return r; }
    cond->n = 1;
    while (cond->n < 3) {
        rs_cmp_t op;
        _rs_skip_ws(t, &i);
        if (!read_cmp(t, &i, &op))
            break;
        cond->op[cond->n - 1] = op;
        r = rs_expr_parse(&cond->e[cond->n], src, &i, err);
        if (r != RS_OK) { rs_cond_clear(cond); return r; }
        cond->n++;
    }
    if (cond->n < 2) {
        int line, col;
        char found[64];
        _rs_describe(found, sizeof found, t, i);
        rs_src_pos(src, i, &line, &col);
        rs_cond_clear(cond);
        return rs_error_set_at(err, RS_ERR_INPUT, src->file, line, col,
                               "expected a comparison (<, <=, >, >=, !=) in the condition, found %s", found);
    }
    {
        size_t end = i;
        while (end > start && (t[end - 1] == ' ' || t[end - 1] == '\t')) end--;
        cond->text = rs_strndup(t + start, end - start);
    }
    *pos = i;
    return RS_OK;
}
