/* expr.c -- recursive-descent parser for case-file expressions. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <flint/fmpz.h>
#include "recstab/expr.h"
#include "recstab/str.h"

typedef struct {
    const rs_src_t *src;
    size_t pos;
    int depth;
    int height;            /* height of the tree the last parse_* returned */
    rs_error_struct *err;
} parser_t;

static int depth_enter(parser_t *p);

/* Tree height limit: long chains (a+b+c+...) are as deep as nesting for the
 * recursive walkers (free, copy, evaluation), so they are bounded too. */
#define RS_EXPR_MAX_HEIGHT 2000
/* Size limit of a constant computed by rs_expr_eval_const (numerator plus
 * denominator bits), checked before powers and after every operation. */
#define RS_EXPR_MAX_BITS 1000000

void rs_src_pos(const rs_src_t *src, size_t i, int *line, int *col)
{
    if (src->linemap != NULL) {
        size_t n = strlen(src->text);
        if (i > n) i = n;
        *line = src->linemap[i];
        *col = src->colmap[i];
    } else {
        *line = src->line;
        *col = src->col + (int) i;
    }
}

static void skip_ws(parser_t *p)
{
    const char *t = p->src->text;
    while (t[p->pos] == ' ' || t[p->pos] == '\t' || t[p->pos] == '\r')
        p->pos++;
}

/* A short printable description of what stands at position i. */
static void describe(char *buf, size_t len, const char *t, size_t i)
{
    unsigned char c = (unsigned char) t[i];
    if (c == '\0') {
        snprintf(buf, len, "end of line");
    } else if (isalpha(c) || c == '_') {
        size_t j = i;
        while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
        snprintf(buf, len, "'%.*s'", (int) (j - i > 40 ? 40 : j - i), t + i);
    } else if (isdigit(c)) {
        size_t j = i;
        while (isdigit((unsigned char) t[j]) || t[j] == '.') j++;
        snprintf(buf, len, "'%.*s'", (int) (j - i > 40 ? 40 : j - i), t + i);
    } else if (c < 32 || c >= 127) {
        snprintf(buf, len, "byte 0x%02x", c);
    } else {
        snprintf(buf, len, "'%c'", c);
    }
}

static int perr(parser_t *p, size_t at, const char *expected)
{
    int line, col;
    char found[64];
    describe(found, sizeof found, p->src->text, at);
    rs_src_pos(p->src, at, &line, &col);
    return rs_error_set_at(p->err, RS_ERR_INPUT, p->src->file, line, col,
                           "expected %s, found %s", expected, found);
}

static rs_expr_t *node_new(parser_t *p, rs_expr_kind_t kind, size_t at)
{
    rs_expr_t *e = flint_calloc(1, sizeof(rs_expr_t));
    e->kind = kind;
    fmpq_init(e->num);
    e->file = p->src->file;
    rs_src_pos(p->src, at, &e->line, &e->col);
    return e;
}

void rs_expr_free(rs_expr_t *e)
{
    if (e == NULL)
        return;
    rs_expr_free(e->a);
    rs_expr_free(e->b);
    fmpq_clear(e->num);
    flint_free(e->name);
    flint_free(e->lit);
    flint_free(e);
}

rs_expr_t *rs_expr_copy(const rs_expr_t *e)
{
    rs_expr_t *c;
    if (e == NULL)
        return NULL;
    c = flint_calloc(1, sizeof(rs_expr_t));
    *c = *e;
    fmpq_init(c->num);
    fmpq_set(c->num, e->num);
    c->name = e->name != NULL ? rs_strdup(e->name) : NULL;
    c->lit = e->lit != NULL ? rs_strdup(e->lit) : NULL;
    c->a = rs_expr_copy(e->a);
    c->b = rs_expr_copy(e->b);
    return c;
}

/* Exact decimal: digits[.digits][e[+-]digits].  Scans at t+*i. */
static int scan_decimal(fmpq_t q, const char *t, size_t *i)
{
    size_t j = *i, k;
    fmpz_t num, den, tmp;
    slong exp10 = 0, frac = 0;
    if (!isdigit((unsigned char) t[j]) && !(t[j] == '.' && isdigit((unsigned char) t[j + 1])))
        return 0;
    fmpz_init(num); fmpz_init(den); fmpz_init(tmp);
    for (; isdigit((unsigned char) t[j]); j++) {
        fmpz_mul_ui(num, num, 10);
        fmpz_add_ui(num, num, (ulong) (t[j] - '0'));
    }
    if (t[j] == '.') {
        j++;
        for (; isdigit((unsigned char) t[j]); j++, frac++) {
            fmpz_mul_ui(num, num, 10);
            fmpz_add_ui(num, num, (ulong) (t[j] - '0'));
        }
    }
    k = j;
    if ((t[k] == 'e' || t[k] == 'E') &&
        (isdigit((unsigned char) t[k + 1]) ||
         ((t[k + 1] == '+' || t[k + 1] == '-') && isdigit((unsigned char) t[k + 2])))) {
        int neg = 0;
        k++;
        if (t[k] == '+' || t[k] == '-') { neg = (t[k] == '-'); k++; }
        for (; isdigit((unsigned char) t[k]); k++) {
            if (exp10 < 1000000) exp10 = exp10 * 10 + (t[k] - '0');
        }
        if (neg) exp10 = -exp10;
        j = k;
    }
    exp10 -= frac;
    if (exp10 > RS_EXPR_MAX_POW || exp10 < -RS_EXPR_MAX_POW) {
        fmpz_clear(num); fmpz_clear(den); fmpz_clear(tmp);
        return -1;
    }
    fmpz_one(den);
    fmpz_set_ui(tmp, 10);
    if (exp10 >= 0) {
        fmpz_pow_ui(tmp, tmp, (ulong) exp10);
        fmpz_mul(num, num, tmp);
    } else {
        fmpz_pow_ui(den, tmp, (ulong) (-exp10));
    }
    fmpq_set_fmpz_frac(q, num, den);
    fmpz_clear(num); fmpz_clear(den); fmpz_clear(tmp);
    *i = j;
    return 1;
}

static rs_expr_t *parse_expr(parser_t *p);
static rs_expr_t *parse_unary(parser_t *p);

/* the shift [n], [n+K] or [n-K] after a name (p->pos at '['), into e;
 * 0 and e freed on an error */
static int parse_shift(parser_t *p, rs_expr_t *e)
{
    const char *t = p->src->text;
    slong k = 0, sign = 1;
    size_t lb = p->pos;
    p->pos++;
    skip_ws(p);
    if (t[p->pos] != 'n' || isalnum((unsigned char) t[p->pos + 1]) || t[p->pos + 1] == '_') {
        perr(p, p->pos, "'n' in a shift such as x[n+1]");
        rs_expr_free(e);
        return 0;
    }
    p->pos++;
    skip_ws(p);
    if (t[p->pos] == '+' || t[p->pos] == '-') {
        sign = (t[p->pos] == '-') ? -1 : 1;
        e->shift_signed = (int) sign;
        p->pos++;
        skip_ws(p);
        if (!isdigit((unsigned char) t[p->pos])) {
            perr(p, p->pos, "an integer shift such as x[n+1]");
            rs_expr_free(e);
            return 0;
        }
        while (isdigit((unsigned char) t[p->pos])) {
            k = 10 * k + (t[p->pos] - '0');
            p->pos++;
            if (k > 100000) {
                int line, col;
                rs_src_pos(p->src, lb, &line, &col);
                rs_error_set_at(p->err, RS_ERR_LIMIT, p->src->file, line, col, "shift too large (limit 100000)");
                rs_expr_free(e);
                return 0;
            }
        }
        skip_ws(p);
    }
    if (t[p->pos] != ']') {
        perr(p, p->pos, "']' to close the shift");
        rs_expr_free(e);
        return 0;
    }
    p->pos++;
    e->shifted = 1;
    e->shift = sign * k;
    return 1;
}

static rs_expr_t *parse_primary(parser_t *p)
{
    const char *t = p->src->text;
    size_t start;
    rs_expr_t *e;
    skip_ws(p);
    start = p->pos;
    if (t[p->pos] == '(') {
        if (!depth_enter(p))
            return NULL;
        p->pos++;
        e = parse_expr(p);
        p->depth--;
        if (e == NULL)
            return NULL;
        skip_ws(p);
        if (t[p->pos] != ')') {
            perr(p, p->pos, "')' to close the '(' opened before");
            rs_expr_free(e);
            return NULL;
        }
        p->pos++;
        e->paren++;
        return e;
    }
    if (isdigit((unsigned char) t[p->pos]) || (t[p->pos] == '.' && isdigit((unsigned char) t[p->pos + 1]))) {
        fmpq_t q;
        size_t i = p->pos;
        int r;
        fmpq_init(q);
        r = scan_decimal(q, t, &i);
        if (r < 0) {
            int line, col;
            rs_src_pos(p->src, start, &line, &col);
            rs_error_set_at(p->err, RS_ERR_LIMIT, p->src->file, line, col,
                            "decimal exponent out of range (limit |e| <= %d)", RS_EXPR_MAX_POW);
            fmpq_clear(q);
            return NULL;
        }
        e = node_new(p, RS_EXPR_NUM, start);
        p->height = 1;
        fmpq_swap(e->num, q);
        fmpq_clear(q);
        e->lit = rs_strndup(t + p->pos, i - p->pos);
        p->pos = i;
        if (isalpha((unsigned char) t[p->pos]) || t[p->pos] == '_') {
            perr(p, p->pos, "an operator after a number (write 2*h, not 2h)");
            rs_expr_free(e);
            return NULL;
        }
        return e;
    }
    if (isalpha((unsigned char) t[p->pos]) || t[p->pos] == '_') {
        size_t j = p->pos;
        while (isalnum((unsigned char) t[j]) || t[j] == '_') j++;
        if (j - p->pos > 64) {
            perr(p, p->pos, "a name of at most 64 characters");
            return NULL;
        }
        e = node_new(p, RS_EXPR_NAME, start);
        p->height = 1;
        e->name = flint_malloc(j - p->pos + 1);
        memcpy(e->name, t + p->pos, j - p->pos);
        e->name[j - p->pos] = '\0';
        p->pos = j;
        skip_ws(p);
        if (t[p->pos] == '(') {
            /* a function call NAME(EXPR); meaning is checked by the evaluators */
            rs_expr_t *arg;
            p->pos++;
            arg = parse_expr(p);
            if (arg == NULL) { rs_expr_free(e); return NULL; }
            skip_ws(p);
            if (t[p->pos] != ')') {
                perr(p, p->pos, "')' to close the function call");
                rs_expr_free(arg);
                rs_expr_free(e);
                return NULL;
            }
            p->pos++;
            e->kind = RS_EXPR_CALL;
            e->a = arg;
            p->height = p->height + 1;
            return e;
        }
        if (t[p->pos] == '[' && !parse_shift(p, e))
            return NULL;
        return e;
    }
    perr(p, p->pos, "an expression (number, name or '(')");
    return NULL;
}

/* Joins a (height ha) and b (height p->height, or none) under a new node;
 * frees both and returns NULL when the tree gets too high. */
static rs_expr_t *binary_h(parser_t *p, rs_expr_kind_t k, size_t at, rs_expr_t *a, int ha, rs_expr_t *b)
{
    rs_expr_t *e;
    int h = (b != NULL && p->height > ha) ? p->height : ha;
    if (h + 1 > RS_EXPR_MAX_HEIGHT) {
        int line, col;
        rs_src_pos(p->src, at, &line, &col);
        rs_error_set_at(p->err, RS_ERR_LIMIT, p->src->file, line, col,
                        "expression too deep: over %d levels of operators (limit %d; split long sums with let)",
                        RS_EXPR_MAX_HEIGHT, RS_EXPR_MAX_HEIGHT);
        rs_expr_free(a);
        rs_expr_free(b);
        return NULL;
    }
    e = node_new(p, k, at);
    e->a = a;
    e->b = b;
    p->height = h + 1;
    return e;
}

/* power := primary ('^' unary)?   (right associative through unary) */
static rs_expr_t *parse_power(parser_t *p)
{
    rs_expr_t *a, *b;
    size_t at;
    int ha;
    a = parse_primary(p);
    if (a == NULL)
        return NULL;
    ha = p->height;
    skip_ws(p);
    if (p->src->text[p->pos] != '^')
        return a;
    at = p->pos;
    p->pos++;
    b = parse_unary(p);
    if (b == NULL) {
        rs_expr_free(a);
        return NULL;
    }
    return binary_h(p, RS_EXPR_POW, at, a, ha, b);
}

/* One more level of nesting; an error past RS_EXPR_MAX_DEPTH (the parser is
 * recursive, so depth is bounded before the stack is). */
static int depth_enter(parser_t *p)
{
    if (++p->depth <= RS_EXPR_MAX_DEPTH)
        return 1;
    {
        int line, col;
        rs_src_pos(p->src, p->pos, &line, &col);
        rs_error_set_at(p->err, RS_ERR_LIMIT, p->src->file, line, col,
                        "expression nested too deeply (limit %d levels of parentheses and signs)",
                        RS_EXPR_MAX_DEPTH);
    }
    return 0;
}

static rs_expr_t *parse_unary(parser_t *p)
{
    const char *t = p->src->text;
    skip_ws(p);
    if (t[p->pos] == '-' || t[p->pos] == '+') {
        size_t at = p->pos;
        int neg = (t[p->pos] == '-');
        rs_expr_t *a;
        if (!depth_enter(p))
            return NULL;
        p->pos++;
        a = parse_unary(p);
        p->depth--;
        if (a == NULL || !neg)
            return a;
        return binary_h(p, RS_EXPR_NEG, at, a, p->height, NULL);
    }
    return parse_power(p);
}

/* operand (op operand)*, left associative, for one precedence level */
static rs_expr_t *parse_chain(parser_t *p, rs_expr_t *(*operand)(parser_t *), char op1, rs_expr_kind_t k1,
                              char op2, rs_expr_kind_t k2)
{
    const char *t = p->src->text;
    rs_expr_t *a = operand(p), *b;
    while (a != NULL) {
        size_t at;
        rs_expr_kind_t k;
        int ha = p->height;
        skip_ws(p);
        if (t[p->pos] != op1 && t[p->pos] != op2)
            break;
        at = p->pos;
        k = (t[p->pos] == op1) ? k1 : k2;
        p->pos++;
        b = operand(p);
        if (b == NULL) {
            rs_expr_free(a);
            return NULL;
        }
        a = binary_h(p, k, at, a, ha, b);
    }
    return a;
}

static rs_expr_t *parse_term(parser_t *p)
{
    return parse_chain(p, parse_unary, '*', RS_EXPR_MUL, '/', RS_EXPR_DIV);
}

/* Terms of a long sum t0 k1 t1 k2 t2 ... (k: ADD or SUB) */
typedef struct {
    rs_expr_t **t;
    int *h;                /* heights of the terms */
    rs_expr_kind_t *k;     /* k[j] joins t[j-1] and t[j] */
    size_t *at;            /* where k[j] stands */
} sum_terms_t;

static rs_expr_kind_t sum_kind(const sum_terms_t *s, slong j, int flip)
{
    return flip ? (s->k[j] == RS_EXPR_ADD ? RS_EXPR_SUB : RS_EXPR_ADD) : s->k[j];
}

/* The balanced tree of t[l..r) (signs flipped when flip: the range stands
 * after a '-'): a - b + c = a - (b - c).  Consumes the terms, also on error;
 * p->height is the tree's height. */
static rs_expr_t *sum_balanced(parser_t *p, const sum_terms_t *s, slong l, slong r, int flip)
{
    slong mid = l + (r - l) / 2, j;
    rs_expr_t *a, *b;
    int ha;
    rs_expr_kind_t k;
    if (r - l == 1) {
        p->height = s->h[l];
        return s->t[l];
    }
    k = sum_kind(s, mid, flip);
    a = sum_balanced(p, s, l, mid, flip);
    if (a == NULL) {
        for (j = mid; j < r; j++) rs_expr_free(s->t[j]);
        return NULL;
    }
    ha = p->height;
    b = sum_balanced(p, s, mid, r, flip ^ (k == RS_EXPR_SUB));
    if (b == NULL) {
        rs_expr_free(a);
        return NULL;
    }
    return binary_h(p, k, s->at[mid], a, ha, b);
}

/* Sums longer than this are built balanced: a flat sum is not nesting, and
 * its height (which bounds the recursive walkers) stays logarithmic.  Short
 * sums keep the left-associative tree they always had. */
#define RS_EXPR_FLAT_SUM 64

/* expr := term (('+'|'-') term)* */
static rs_expr_t *parse_sum(parser_t *p)
{
    const char *t = p->src->text;
    sum_terms_t s;
    slong n = 0, alloc = 0, j;
    rs_expr_t *e = parse_term(p), *res;
    if (e == NULL)
        return NULL;
    memset(&s, 0, sizeof s);
    for (;;) {
        if (n + 2 > alloc) {   /* t[n] now, k[n + 1] and at[n + 1] below */
            alloc = alloc ? 2 * alloc : 16;
            s.t = flint_realloc(s.t, alloc * sizeof *s.t);
            s.h = flint_realloc(s.h, alloc * sizeof *s.h);
            s.k = flint_realloc(s.k, alloc * sizeof *s.k);
            s.at = flint_realloc(s.at, alloc * sizeof *s.at);
        }
        s.t[n] = e;
        s.h[n] = p->height;
        n++;
        skip_ws(p);
        if (t[p->pos] != '+' && t[p->pos] != '-')
            break;
        s.k[n] = (t[p->pos] == '+') ? RS_EXPR_ADD : RS_EXPR_SUB;
        s.at[n] = p->pos;
        p->pos++;
        e = parse_term(p);
        if (e == NULL) {
            for (j = 0; j < n; j++) rs_expr_free(s.t[j]);
            res = NULL;
            goto done;
        }
    }
    if (n > RS_EXPR_FLAT_SUM) {
        res = sum_balanced(p, &s, 0, n, 0);
    } else {
        res = s.t[0];
        p->height = s.h[0];
        for (j = 1; j < n && res != NULL; j++) {
            int ha = p->height;
            p->height = s.h[j];
            res = binary_h(p, s.k[j], s.at[j], res, ha, s.t[j]);
        }
        for (; j < n; j++) rs_expr_free(s.t[j]);   /* after a failed join */
    }
done:
    flint_free(s.t); flint_free(s.h); flint_free(s.k); flint_free(s.at);
    return res;
}

/* no level of its own: a level is a '(' (parse_primary) or a sign
 * (parse_unary), one each, as the limit's message says (counted twice
 * before: 100 parentheses were "over 200") */
static rs_expr_t *parse_expr(parser_t *p)
{
    return parse_sum(p);
}

int rs_expr_parse(rs_expr_t **out, const rs_src_t *src, size_t *pos, rs_error_t err)
{
    parser_t p;
    p.src = src;
    p.pos = *pos;
    p.depth = 0;
    p.height = 0;
    p.err = err;
    *out = parse_expr(&p);
    *pos = p.pos;
    if (*out == NULL)
        return err->code ? err->code : RS_ERR_INPUT;
    return RS_OK;
}

int rs_expr_parse_all(rs_expr_t **out, const rs_src_t *src, rs_error_t err)
{
    size_t pos = 0;
    int r = rs_expr_parse(out, src, &pos, err);
    if (r != RS_OK)
        return r;
    while (src->text[pos] == ' ' || src->text[pos] == '\t' || src->text[pos] == '\r')
        pos++;
    if (src->text[pos] != '\0') {
        parser_t p;
        p.src = src; p.pos = pos; p.depth = 0; p.height = 0; p.err = err;
        rs_expr_free(*out);
        *out = NULL;
        return perr(&p, pos, "an operator or end of expression");
    }
    return RS_OK;
}

/* Evaluate a constant expression tree to a rational (numbers, + - * / ^). */
int rs_expr_eval_const(fmpq_t q, const rs_expr_t *e, const rs_src_t *src, rs_error_t err)
{
    fmpq_t a, b;
    int r = RS_OK;
    if (e->kind == RS_EXPR_NUM) {
        fmpq_set(q, e->num);
        return RS_OK;
    }
    if (e->kind == RS_EXPR_NAME)
        return rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col,
                               "expected a number, found the name '%s'", e->name);
    if (e->kind == RS_EXPR_CALL)
        return rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col,
                               "expected an exact number, found the function call %s(...)", e->name);
    fmpq_init(a); fmpq_init(b);
    r = rs_expr_eval_const(a, e->a, src, err);
    if (r == RS_OK && e->b != NULL)
        r = rs_expr_eval_const(b, e->b, src, err);
    if (r == RS_OK) {
        switch (e->kind) {
        case RS_EXPR_ADD: fmpq_add(q, a, b); break;
        case RS_EXPR_SUB: fmpq_sub(q, a, b); break;
        case RS_EXPR_MUL: fmpq_mul(q, a, b); break;
        case RS_EXPR_NEG: fmpq_neg(q, a); break;
        case RS_EXPR_DIV:
            if (fmpq_is_zero(b))
                r = rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col,
                                    "division by zero");
            else
                fmpq_div(q, a, b);
            break;
        case RS_EXPR_POW:
            if (!fmpz_is_one(fmpq_denref(b)))
                r = rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col,
                                    "expected an integer power, found a fraction");
            else if (fmpz_bits(fmpq_numref(b)) > 20 || fmpz_get_si(fmpq_numref(b)) > RS_EXPR_MAX_POW || fmpz_get_si(fmpq_numref(b)) < -RS_EXPR_MAX_POW)
                r = rs_error_set_at(err, RS_ERR_LIMIT, src->file, e->line, e->col,
                                    "power too large (limit %d)", RS_EXPR_MAX_POW);
            else if (fmpq_is_zero(a) && fmpz_sgn(fmpq_numref(b)) < 0)
                r = rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col,
                                    "division by zero (0 to a negative power)");
            else if ((double) (fmpz_bits(fmpq_numref(a)) + fmpz_bits(fmpq_denref(a)))
                     * (double) FLINT_ABS(fmpz_get_si(fmpq_numref(b))) > RS_EXPR_MAX_BITS)
                r = rs_error_set_at(err, RS_ERR_LIMIT, src->file, e->line, e->col,
                                    "number too large: about %.0f bits (limit %d bits)",
                                    (double) (fmpz_bits(fmpq_numref(a)) + fmpz_bits(fmpq_denref(a)))
                                    * (double) FLINT_ABS(fmpz_get_si(fmpq_numref(b))), RS_EXPR_MAX_BITS);
            else
                fmpq_pow_si(q, a, fmpz_get_si(fmpq_numref(b)));
            break;
        default:
            r = rs_error_set(err, RS_ERR_INTERNAL, "bad node");
        }
        if (r == RS_OK && fmpz_bits(fmpq_numref(q)) + fmpz_bits(fmpq_denref(q)) > RS_EXPR_MAX_BITS)
            r = rs_error_set_at(err, RS_ERR_LIMIT, src->file, e->line, e->col,
                                "number too large: %lu bits (limit %d bits)",
                                (unsigned long) (fmpz_bits(fmpq_numref(q)) + fmpz_bits(fmpq_denref(q))),
                                RS_EXPR_MAX_BITS);
    }
    fmpq_clear(a); fmpq_clear(b);
    return r;
}

/* (ar + i ai)(br + i bi), into (qr, qi) (may alias neither input) */
static void cmul(fmpq_t qr, fmpq_t qi, const fmpq_t ar, const fmpq_t ai, const fmpq_t br, const fmpq_t bi)
{
    fmpq_mul(qr, ar, br);
    fmpq_submul(qr, ai, bi);
    fmpq_mul(qi, ar, bi);
    fmpq_addmul(qi, ai, br);
}

static slong cbits(const fmpq_t r, const fmpq_t i)
{
    /* a real number counts as rs_expr_eval_const counts it */
    return (slong) (fmpz_bits(fmpq_numref(r)) + fmpz_bits(fmpq_denref(r))
                    + (fmpq_is_zero(i) ? 0 : fmpz_bits(fmpq_numref(i)) + fmpz_bits(fmpq_denref(i))));
}

int rs_expr_eval_const_complex(fmpq_t re, fmpq_t im, const rs_expr_t *e, const rs_src_t *src, rs_error_t err)
{
    fmpq_t ar, ai, br, bi, t;
    int r = RS_OK;
    if (e->kind == RS_EXPR_NAME && strcmp(e->name, "i") == 0 && !e->shifted) {
        fmpq_zero(re);
        fmpq_one(im);
        return RS_OK;
    }
    if (e->kind == RS_EXPR_NUM || e->kind == RS_EXPR_NAME || e->kind == RS_EXPR_CALL) {
        fmpq_zero(im);
        return rs_expr_eval_const(re, e, src, err);
    }
    fmpq_init(ar); fmpq_init(ai); fmpq_init(br); fmpq_init(bi); fmpq_init(t);
    r = rs_expr_eval_const_complex(ar, ai, e->a, src, err);
    if (r == RS_OK && e->b != NULL)
        r = rs_expr_eval_const_complex(br, bi, e->b, src, err);
    if (r == RS_OK) {
        switch (e->kind) {
        case RS_EXPR_ADD: fmpq_add(re, ar, br); fmpq_add(im, ai, bi); break;
        case RS_EXPR_SUB: fmpq_sub(re, ar, br); fmpq_sub(im, ai, bi); break;
        case RS_EXPR_NEG: fmpq_neg(re, ar); fmpq_neg(im, ai); break;
        case RS_EXPR_MUL: cmul(re, im, ar, ai, br, bi); break;
        case RS_EXPR_DIV:
            /* a / b = a conj(b) / |b|^2 */
            fmpq_mul(t, br, br);
            fmpq_addmul(t, bi, bi);
            if (fmpq_is_zero(t)) {
                r = rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col, "division by zero");
                break;
            }
            fmpq_neg(bi, bi);
            cmul(re, im, ar, ai, br, bi);
            fmpq_div(re, re, t);
            fmpq_div(im, im, t);
            break;
        case RS_EXPR_POW: {
            slong k, n;
            if (!fmpq_is_zero(bi) || !fmpz_is_one(fmpq_denref(br))) {
                r = rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col,
                                    "expected an integer power, found %s", fmpq_is_zero(bi) ? "a fraction"
                                    : "a complex number");
                break;
            }
            if (fmpz_bits(fmpq_numref(br)) > 20 || fmpz_cmp_si(fmpq_numref(br), RS_EXPR_MAX_POW) > 0 || fmpz_cmp_si(fmpq_numref(br), -RS_EXPR_MAX_POW) < 0) {
                r = rs_error_set_at(err, RS_ERR_LIMIT, src->file, e->line, e->col, "power too large (limit %d)",
                                    RS_EXPR_MAX_POW);
                break;
            }
            n = fmpz_get_si(fmpq_numref(br));
            if (fmpq_is_zero(ar) && fmpq_is_zero(ai) && n < 0) {
                r = rs_error_set_at(err, RS_ERR_INPUT, src->file, e->line, e->col,
                                    "division by zero (0 to a negative power)");
                break;
            }
            if ((double) cbits(ar, ai) * (double) FLINT_ABS(n) > RS_EXPR_MAX_BITS) {
                r = rs_error_set_at(err, RS_ERR_LIMIT, src->file, e->line, e->col,
                                    "number too large: about %.0f bits (limit %d bits)",
                                    (double) cbits(ar, ai) * (double) FLINT_ABS(n), RS_EXPR_MAX_BITS);
                break;
            }
            if (n < 0) {
                /* 1/a = conj(a)/|a|^2 */
                fmpq_mul(t, ar, ar);
                fmpq_addmul(t, ai, ai);
                fmpq_div(ar, ar, t);
                fmpq_neg(ai, ai);
                fmpq_div(ai, ai, t);
                n = -n;
            }
            fmpq_one(br); fmpq_zero(bi);   /* the power, by repeated squaring */
            for (k = n; k > 0; k >>= 1) {
                if (k & 1) { cmul(re, im, br, bi, ar, ai); fmpq_swap(re, br); fmpq_swap(im, bi); }
                if (k > 1) { cmul(re, im, ar, ai, ar, ai); fmpq_swap(re, ar); fmpq_swap(im, ai); }
            }
            fmpq_swap(re, br);
            fmpq_swap(im, bi);
            break;
        }
        default:
            r = rs_error_set(err, RS_ERR_INTERNAL, "bad node");
        }
        if (r == RS_OK && cbits(re, im) > 2 * RS_EXPR_MAX_BITS)
            r = rs_error_set_at(err, RS_ERR_LIMIT, src->file, e->line, e->col,
                                "number too large: %ld bits (limit %d bits)", (long) cbits(re, im),
                                2 * RS_EXPR_MAX_BITS);
    }
    fmpq_clear(ar); fmpq_clear(ai); fmpq_clear(br); fmpq_clear(bi); fmpq_clear(t);
    return r;
}

/* a source over the string s alone (no file, line 1) */
static void src_of_string(rs_src_t *src, const char *s)
{
    memset(src, 0, sizeof *src);
    src->file = "";
    src->text = s;
    src->line = 1;
    src->col = 1;
}

int rs_expr_parse_complex(fmpq_t re, fmpq_t im, const char *s, rs_error_t err)
{
    rs_src_t src;
    rs_expr_t *e = NULL;
    int r;
    src_of_string(&src, s);
    r = rs_expr_parse_all(&e, &src, err);
    if (r == RS_OK)
        r = rs_expr_eval_const_complex(re, im, e, &src, err);
    rs_expr_free(e);
    return r;
}

int rs_expr_parse_number(fmpq_t q, const char *s, rs_error_t err)
{
    rs_src_t src;
    rs_expr_t *e = NULL;
    int r;
    src_of_string(&src, s);
    r = rs_expr_parse_all(&e, &src, err);
    if (r == RS_OK)
        r = rs_expr_eval_const(q, e, &src, err);
    rs_expr_free(e);
    return r;
}
