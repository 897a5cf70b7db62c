/* expr_build.c -- building, comparing and printing expression trees (the
 * lowering stage constructs its equations with these; nothing is re-parsed). */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "recstab/expr.h"
#include "recstab/str.h"

static rs_expr_t *node(rs_expr_kind_t kind, const char *file, int line, int col)
{
    rs_expr_t *e = flint_calloc(1, sizeof(rs_expr_t));
    e->kind = kind;
    fmpq_init(e->num);
    e->file = file;
    e->line = line;
    e->col = col;
    return e;
}

rs_expr_t *rs_expr_new_num(slong v, const char *file, int line, int col)
{
    rs_expr_t *e = node(RS_EXPR_NUM, file, line, col);
    fmpz_set_si(fmpq_numref(e->num), v);   /* the denominator is 1 from fmpq_init */
    return e;
}

rs_expr_t *rs_expr_new_name(const char *name, int shifted, slong shift, const char *file, int line, int col)
{
    rs_expr_t *e = node(RS_EXPR_NAME, file, line, col);
    e->name = rs_strdup(name);
    e->shifted = shifted;
    e->shift = shift;
    return e;
}

rs_expr_t *rs_expr_new_op(rs_expr_kind_t kind, rs_expr_t *a, rs_expr_t *b, const char *file, int line, int col)
{
    rs_expr_t *e = node(kind, file, line, col);
    e->a = a;
    e->b = b;
    return e;
}

rs_expr_t *rs_expr_paren(rs_expr_t *e)
{
    e->paren++;
    return e;
}

int rs_expr_equal(const rs_expr_t *a, const rs_expr_t *b)
{
    if (a == NULL || b == NULL) return a == b;
    if (a->kind != b->kind) return 0;
    switch (a->kind) {
    case RS_EXPR_NUM:
        return fmpq_equal(a->num, b->num);
    case RS_EXPR_NAME:
        return strcmp(a->name, b->name) == 0 && a->shifted == b->shifted && a->shift == b->shift;
    case RS_EXPR_CALL:
        if (strcmp(a->name, b->name) != 0) return 0;
        break;
    default:
        break;
    }
    return rs_expr_equal(a->a, b->a) && rs_expr_equal(a->b, b->b);
}

/* ---------- printing ----------------------------------------------------- */

typedef struct { char *s; size_t len, cap; } buf_t;

static void put(buf_t *b, const char *fmt, ...)
{
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (b->len + (size_t) n + 1 > b->cap) {
        b->cap = 2 * (b->len + (size_t) n + 1);
        b->s = flint_realloc(b->s, b->cap);
    }
    va_start(ap, fmt);
    vsnprintf(b->s + b->len, (size_t) n + 1, fmt, ap);
    va_end(ap);
    b->len += (size_t) n;
}

/* binding strength: sums 1, products 2, unary minus 3, powers 4, atoms 5 */
static int prec(const rs_expr_t *e)
{
    switch (e->kind) {
    case RS_EXPR_ADD: case RS_EXPR_SUB: return 1;
    case RS_EXPR_MUL: case RS_EXPR_DIV: return 2;
    case RS_EXPR_NEG: return 3;
    case RS_EXPR_POW: return 4;
    default: return 5;
    }
}

static void print(buf_t *b, const rs_expr_t *e, int need_paren);

/* the operand o of e: parenthesised where the parser would not read the text back as this tree */
static void operand(buf_t *b, const rs_expr_t *e, const rs_expr_t *o, int right)
{
    int pe = prec(e), po = prec(o), need;
    if (e->kind == RS_EXPR_NEG) need = po < 3;
    else if (e->kind == RS_EXPR_POW) need = right ? po < 3 : po != 5;
    else need = right ? po <= pe : po < pe;
    print(b, o, need);
}

static void print(buf_t *b, const rs_expr_t *e, int need_paren)
{
    int k, np = e->paren > 0 ? e->paren : need_paren;
    static const char *const ops[] = {"", "", " + ", " - ", "*", "/", "^"};
    for (k = 0; k < np; k++) put(b, "(");
    switch (e->kind) {
    case RS_EXPR_NUM:
        if (e->lit != NULL) put(b, "%s", e->lit);
        else {
            char *q = fmpq_get_str(NULL, 10, e->num);
            put(b, "%s", q);
            flint_free(q);
        }
        break;
    case RS_EXPR_NAME:
        put(b, "%s", e->name);
        if (e->shifted && (e->shift != 0 || e->shift_signed))
            put(b, "[n%c%ld]", e->shift < 0 || (e->shift == 0 && e->shift_signed < 0) ? '-' : '+',
                (long) (e->shift < 0 ? -e->shift : e->shift));
        else if (e->shifted)
            put(b, "[n]");
        break;
    case RS_EXPR_CALL:
        put(b, "%s(", e->name);
        print(b, e->a, 0);
        put(b, ")");
        break;
    case RS_EXPR_NEG:
        put(b, "-");
        operand(b, e, e->a, 0);
        break;
    default:
        operand(b, e, e->a, 0);
        put(b, "%s", ops[e->kind]);
        operand(b, e, e->b, 1);
    }
    for (k = 0; k < np; k++) put(b, ")");
}

char *rs_expr_str(const rs_expr_t *e)
{
    buf_t b = {NULL, 0, 0};
    put(&b, "%s", "");
    if (e != NULL) print(&b, e, 0);
    return b.s;
}

char *rs_expr_eq_str(const rs_expr_t *lhs, const rs_expr_t *rhs)
{
    buf_t b = {NULL, 0, 0};
    put(&b, "%s", "");
    print(&b, lhs, 0);
    put(&b, " = ");
    print(&b, rhs, 0);
    return b.s;
}
