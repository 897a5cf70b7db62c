/* an_expect.c -- `expect charpoly|bilinear POLY`: a printed polynomial
 * compared with the derived p(lambda) or q(z) (equal, proportional,
 * different); with the imaginary unit i in POLY, exactly over Q(i). */
#include <stdlib.h>
#include <string.h>
#include "analysis/registry.h"
#include "recstab/bilinear.h"
#include "util/polyfmt.h"

/* the name i: the imaginary unit (reserved, no case can declare it) */
static int uses_i(const rs_expr_t *e, const rs_model_t m)
{
    if (e == NULL) return 0;
    if (e->kind == RS_EXPR_NAME && strcmp(e->name, "i") == 0) return 1;
    return uses_i(e->a, m) || uses_i(e->b, m);
}

/* the first undeclared name other than the imaginary unit */
static const rs_expr_t *undeclared_but_i(const rs_expr_t *e, const rs_model_t m)
{
    const rs_expr_t *u;
    if (e == NULL) return NULL;
    if (e->kind == RS_EXPR_NAME) return strcmp(e->name, "i") == 0 ? NULL : rs_an_undeclared_name(e, m);
    if ((u = undeclared_but_i(e->a, m)) != NULL) return u;
    return undeclared_but_i(e->b, m);
}

/* "A + i*(B)" */
static char *cx_mpoly_str(const fmpq_mpoly_t re, const fmpq_mpoly_t im, const rs_scheme_struct *s)
{
    char *a = rs_polyfmt_fmpq_mpoly(re, (const char **) s->vars, s->ctx);
    char *b = rs_polyfmt_fmpq_mpoly(im, (const char **) s->vars, s->ctx);
    char *out = malloc(strlen(a) + strlen(b) + 16);
    if (fmpq_mpoly_is_zero(im, s->ctx)) strcpy(out, a);
    else if (fmpq_mpoly_is_zero(re, s->ctx)) sprintf(out, "i*(%s)", b);
    else sprintf(out, "%s + i*(%s)", a, b);
    free(a); free(b);
    return out;
}

/* (er + i ei) = c (dr + i di) for some c in Q(i): 1 and c when so */
static int cx_ratio(fmpq_t cr, fmpq_t ci, const fmpq_mpoly_t er, const fmpq_mpoly_t ei, const fmpq_mpoly_t dr,
                    const fmpq_mpoly_t di, const fmpq_mpoly_ctx_t ctx)
{
    const fmpq_mpoly_struct *pick = fmpq_mpoly_is_zero(dr, ctx) ? di : dr;
    ulong *ex;
    fmpq_t a, b, x, y, m;
    fmpq_mpoly_t t, u;
    int ok;
    if (fmpq_mpoly_is_zero(pick, ctx)) return 0;
    ex = flint_malloc((size_t) ctx->zctx->minfo->nvars * sizeof(ulong));
    fmpq_init(a); fmpq_init(b); fmpq_init(x); fmpq_init(y); fmpq_init(m);
    fmpq_mpoly_init(t, ctx); fmpq_mpoly_init(u, ctx);
    fmpq_mpoly_get_term_exp_ui(ex, pick, 0, ctx);
    fmpq_mpoly_get_coeff_fmpq_ui(a, dr, ex, ctx);
    fmpq_mpoly_get_coeff_fmpq_ui(b, di, ex, ctx);
    fmpq_mpoly_get_coeff_fmpq_ui(x, er, ex, ctx);
    fmpq_mpoly_get_coeff_fmpq_ui(y, ei, ex, ctx);
    /* c = (x + i y)/(a + i b) = (x + i y)(a - i b)/(a^2 + b^2) */
    fmpq_mul(m, a, a);
    fmpq_addmul(m, b, b);
    fmpq_mul(cr, x, a);
    fmpq_addmul(cr, y, b);
    fmpq_div(cr, cr, m);
    fmpq_mul(ci, y, a);
    fmpq_submul(ci, x, b);
    fmpq_div(ci, ci, m);
    /* er == cr dr - ci di and ei == cr di + ci dr */
    fmpq_mpoly_scalar_mul_fmpq(t, dr, cr, ctx);
    fmpq_mpoly_scalar_mul_fmpq(u, di, ci, ctx);
    fmpq_mpoly_sub(t, t, u, ctx);
    ok = fmpq_mpoly_equal(t, er, ctx);
    fmpq_mpoly_scalar_mul_fmpq(t, di, cr, ctx);
    fmpq_mpoly_scalar_mul_fmpq(u, dr, ci, ctx);
    fmpq_mpoly_add(t, t, u, ctx);
    ok = ok && fmpq_mpoly_equal(t, ei, ctx) && !fmpq_is_zero(m) && !(fmpq_is_zero(cr) && fmpq_is_zero(ci));
    fmpq_clear(a); fmpq_clear(b); fmpq_clear(x); fmpq_clear(y); fmpq_clear(m);
    fmpq_mpoly_clear(t, ctx); fmpq_mpoly_clear(u, ctx);
    flint_free(ex);
    return ok;
}

/* (pr + i pi) with every parameter that has a complex set value replaced by it */
static void cx_subst(fmpq_mpoly_t pr, fmpq_mpoly_t pi, const rs_run_t *run, const rs_scheme_struct *s)
{
    fmpq_mpoly_t nr, ni;
    fmpq_t c;
    ulong *ue = flint_malloc((size_t) s->nvars * sizeof(ulong));
    slong *ex = flint_malloc((size_t) s->nvars * sizeof(slong));
    slong i, v;
    int part;
    fmpq_mpoly_init(nr, s->ctx); fmpq_mpoly_init(ni, s->ctx);
    fmpq_init(c);
    for (part = 0; part < 2; part++) {
        const fmpq_mpoly_struct *src = part ? pi : pr;
        for (i = 0; i < fmpq_mpoly_length(src, s->ctx); i++) {
            fmpq_mpoly_get_term_coeff_fmpq(c, src, i, s->ctx);
            fmpq_mpoly_get_term_exp_ui(ue, src, i, s->ctx);
            for (v = 0; v < s->nvars; v++) ex[v] = (slong) ue[v];
            rs_cx_add_term(nr, ni, c, part, ex, run, s);   /* c i^part */
        }
    }
    fmpq_mpoly_sort_terms(nr, s->ctx); fmpq_mpoly_combine_like_terms(nr, s->ctx);
    fmpq_mpoly_sort_terms(ni, s->ctx); fmpq_mpoly_combine_like_terms(ni, s->ctx);
    fmpq_mpoly_swap(pr, nr, s->ctx);
    fmpq_mpoly_swap(pi, ni, s->ctx);
    fmpq_mpoly_clear(nr, s->ctx); fmpq_mpoly_clear(ni, s->ctx);
    fmpq_clear(c);
    flint_free(ue); flint_free(ex);
}

static void zpoly_to_q(fmpq_mpoly_t out, const fmpz_mpoly_t p, const rs_scheme_struct *s)
{
    slong i;
    ulong *ex = flint_malloc((size_t) s->nvars * sizeof(ulong));
    fmpz_t c;
    fmpz_init(c);
    fmpq_mpoly_zero(out, s->ctx);
    for (i = 0; i < fmpz_mpoly_length(p, s->zctx); i++) {
        fmpz_mpoly_get_term_coeff_fmpz(c, p, i, s->zctx);
        fmpz_mpoly_get_term_exp_ui(ex, p, i, s->zctx);
        fmpq_mpoly_push_term_fmpz_ui(out, c, ex, s->ctx);
    }
    fmpq_mpoly_sort_terms(out, s->ctx);
    fmpq_mpoly_combine_like_terms(out, s->ctx);
    fmpz_clear(c);
    flint_free(ex);
}


/* expect charpoly with i: the printed er + i ei against p = re + i im over
 * Q(i) (rs_run_cx_poly: complex set values substituted, a char line with i
 * read from its block), also against lambda^k p (the raw determinant) */
static int expect_cx(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    rs_assign_t *a;
    slong n, i;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpq_mpoly_t er, ei, den, dr, di, lp;
    fmpz_mpoly_t zr, zi;
    fmpq_t cr, ci;
    json_t *o;
    const char *status = "different";
    int r;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(&v, run, a, n);
    if (r != RS_OK) { rs_assign_free(a, n); return r; }
    s = v->s;
    fmpq_mpoly_init(er, s->ctx); fmpq_mpoly_init(ei, s->ctx); fmpq_mpoly_init(den, s->ctx);
    fmpq_mpoly_init(dr, s->ctx); fmpq_mpoly_init(di, s->ctx); fmpq_mpoly_init(lp, s->ctx);
    fmpz_mpoly_init(zr, s->zctx); fmpz_mpoly_init(zi, s->zctx);
    fmpq_init(cr); fmpq_init(ci);
    r = rs_scheme_eval_poly_cx(er, ei, den, s, run->c, req->u.expect.poly, 1, run->err);
    if (r == RS_OK) {
        for (i = 0; i < n; i++) {
            fmpq_mpoly_evaluate_one_fmpq(er, er, a[i].var, a[i].value, s->ctx);
            fmpq_mpoly_evaluate_one_fmpq(ei, ei, a[i].var, a[i].value, s->ctx);
        }
        cx_subst(er, ei, run, s);
        rs_run_cx_poly(zr, zi, run, v);
        zpoly_to_q(dr, zr, s);
        zpoly_to_q(di, zi, s);
        /* as the real path: "equal" to p with a positive leading term (as
         * rs_run_cx_poly gives it and charpoly over Q(i) prints it) or to the
         * raw determinant lambda^k p, else "proportional" with the ratio */
        if (cx_ratio(cr, ci, er, ei, dr, di, s->ctx)) status = fmpq_is_zero(ci) && fmpq_is_one(cr) ? "equal" : "proportional";
        else if (!s->complex_char && v->cp->removed_lambda_power > 0) {
            /* the raw determinant lambda^k p */
            fmpq_mpoly_gen(lp, s->lambda_var, s->ctx);
            fmpq_mpoly_pow_ui(lp, lp, (ulong) v->cp->removed_lambda_power, s->ctx);
            fmpq_mpoly_mul(dr, dr, lp, s->ctx);
            fmpq_mpoly_mul(di, di, lp, s->ctx);
            if (cx_ratio(cr, ci, er, ei, dr, di, s->ctx))
                status = fmpq_is_zero(ci) && fmpq_is_one(cr) ? "equal" : "proportional";
            fmpq_mpoly_div(dr, dr, lp, s->ctx);
            fmpq_mpoly_div(di, di, lp, s->ctx);
        }
        o = json_object();
        json_object_set_new(o, "analysis", json_string("expect"));
        json_object_set_new(o, "of", json_string("charpoly"));
        json_object_set_new(o, "text", json_string(q->text));
        json_object_set_new(o, "over", json_string("Q(i)"));
        json_object_set_new(o, "status", json_string(status));
        if (strcmp(status, "proportional") == 0) {
            char *c = rs_complex_str(cr, ci);
            json_object_set_new(o, "ratio", json_string(c));
            free(c);
        }
        if (strcmp(status, "different") == 0) {
            char *es = cx_mpoly_str(er, ei, s), *ds = cx_mpoly_str(dr, di, s);
            json_object_set_new(o, "expected", json_string(es));
            json_object_set_new(o, "derived", json_string(ds));
            free(es); free(ds);
            run->outcome |= RS_OUTCOME_FAILED;
        } else json_object_set_new(o, "difference", json_string("0"));
        {
            json_t *sub = json_deep_copy(v->assigned);
            json_object_update_new(sub, rs_run_cx_at(run));
            json_object_set_new(o, "substituted", sub);
        }
        json_array_append_new(run->results, o);
    }
    fmpq_mpoly_clear(er, s->ctx); fmpq_mpoly_clear(ei, s->ctx); fmpq_mpoly_clear(den, s->ctx);
    fmpq_mpoly_clear(dr, s->ctx); fmpq_mpoly_clear(di, s->ctx); fmpq_mpoly_clear(lp, s->ctx);
    fmpz_mpoly_clear(zr, s->zctx); fmpz_mpoly_clear(zi, s->zctx);
    fmpq_clear(cr); fmpq_clear(ci);
    rs_assign_free(a, n);
    return r;
}

/* Compare an expected polynomial (fmpq, in the variant's variables, values
 * substituted) with the derived one; fills status/difference into o. */
void rs_compare_poly(json_t *o, const fmpq_mpoly_t expected, const fmpz_mpoly_t derived,
                     const fmpz_mpoly_t derived_raw, slong var, const rs_scheme_t s,
                     const char *varname)
{
    fmpz_mpoly_t e, d;
    fmpq_t scale;
    const char *status;
    fmpz_mpoly_init(e, s->zctx);
    fmpz_mpoly_init(d, s->zctx);
    fmpq_init(scale);
    rs_charpoly_fmpq_to_fmpz(e, scale, expected, s->ctx);
    if (fmpq_is_one(scale) && fmpz_mpoly_equal(e, derived_raw, s->zctx))
        status = "equal";
    else if (fmpq_is_one(scale) && fmpz_mpoly_equal(e, derived, s->zctx))
        status = "equal";
    else {
        fmpq_t g;
        fmpq_init(g);
        rs_charpoly_normalise(e, g, var, s->zctx);
        fmpq_clear(g);
        status = fmpz_mpoly_equal(e, derived, s->zctx) ? "proportional" : "different";
    }
    json_object_set_new(o, "status", json_string(status));
    if (strcmp(status, "different") == 0) {
        fmpz_mpoly_sub(d, e, derived, s->zctx);
        json_object_set_new(o, "difference", rs_json_collected(d, var, s, varname));
        json_object_set_new(o, "expected_normalised", rs_json_collected(e, var, s, varname));
        json_object_set_new(o, "derived", rs_json_collected(derived, var, s, varname));
        {
            /* is the printed one a multiple of ours by a parameter factor? */
            fmpz_mpoly_t qt;
            fmpz_mpoly_init(qt, s->zctx);
            if (fmpz_mpoly_divides(qt, e, derived, s->zctx) && fmpz_mpoly_degree_si(qt, var, s->zctx) == 0)
                json_object_set_new(o, "ratio", rs_json_zpoly(qt, s));
            fmpz_mpoly_clear(qt, s->zctx);
        }
    } else {
        json_object_set_new(o, "difference", json_string("0"));
    }
    fmpz_mpoly_clear(e, s->zctx);
    fmpz_mpoly_clear(d, s->zctx);
    fmpq_clear(scale);
}

/* expect charpoly|bilinear POLY: the polynomial parsed up front */
int rs_an_expect_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *what = req->rest;
    rs_src_t src;
    size_t pos;
    int r;
    if (strncmp(what, "charpoly", 8) == 0 && (what[8] == ' ' || what[8] == '\t'))
        req->u.expect.bilinear = 0;
    else if (strncmp(what, "bilinear", 8) == 0 && (what[8] == ' ' || what[8] == '\t'))
        req->u.expect.bilinear = 1;
    else
        return rs_req_error(run, q, what, RS_ERR_INPUT,
                            "expected 'charpoly' or 'bilinear' followed by a polynomial, found '%s'", what);
    rs_req_src(&src, q);
    pos = (size_t) (rs_req_skip_word(what) - q->text);
    r = rs_expr_parse(&req->u.expect.poly, &src, &pos, run->err);
    if (r == RS_OK && q->text[pos] != '\0')
        return rs_req_error(run, q, q->text + pos, RS_ERR_INPUT,
                            "expected an operator or end of line, found '%s'", q->text + pos);
    if (r == RS_OK && uses_i(req->u.expect.poly, run->m)) {
        /* the imaginary unit: compared over Q(i) (charpoly only) */
        const rs_expr_t *u = undeclared_but_i(req->u.expect.poly, run->m);
        if (u != NULL)
            return rs_error_set_at(run->err, RS_ERR_INPUT, q->loc.file, u->line, u->col,
                                   "unknown name '%s' (expected a declared param, unknown or let)", u->name);
        if (req->u.expect.bilinear)
            return rs_req_error(run, q, what, RS_ERR_INPUT, "expect bilinear with the imaginary unit i: compare the "
                                "characteristic polynomial over Q(i) instead (expect charpoly ...)%s", "");
        return RS_OK;
    }
    if (r == RS_OK) r = rs_an_check_names(run, q, req->u.expect.poly);
    return r;
}

void rs_an_expect_req_clear(rs_an_req_t *req)
{
    rs_expr_free(req->u.expect.poly);
}

int rs_an_expect(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    int bil = req->u.expect.bilinear;
    rs_assign_t *a;
    slong n, i;
    rs_variant_t *v;
    fmpq_mpoly_t num, den;
    json_t *o;
    int r;
    if (uses_i(req->u.expect.poly, run->m)) return expect_cx(run, req);
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(&v, run, a, n);
    if (r != RS_OK) { rs_assign_free(a, n); return r; }
    fmpq_mpoly_init(num, v->s->ctx);
    fmpq_mpoly_init(den, v->s->ctx);
    r = rs_scheme_eval_poly(num, den, v->s, run->c, req->u.expect.poly, bil ? 2 : 1, run->err);
    if (r == RS_OK) {
        const fmpz_mpoly_ctx_struct *zctx = v->s->zctx;
        fmpz_mpoly_t raw, norm;
        for (i = 0; i < n; i++)
            fmpq_mpoly_evaluate_one_fmpq(num, num, a[i].var, a[i].value, v->s->ctx);
        fmpz_mpoly_init(raw, zctx);
        fmpz_mpoly_init(norm, zctx);
        if (bil) {
            /* q itself is "equal"; its normalised form for "proportional" */
            rs_bilinear_fmpz_mpoly(raw, v->cp->p, v->s->lambda_var, zctx);
            fmpz_mpoly_set(norm, raw, zctx);
            rs_charpoly_normalise(norm, NULL, v->s->lambda_var, zctx);
        } else {
            /* the raw determinant lambda^k * p, for "equal" */
            fmpz_mpoly_gen(raw, v->s->lambda_var, zctx);
            fmpz_mpoly_pow_ui(raw, raw, (ulong) v->cp->removed_lambda_power, zctx);
            fmpz_mpoly_mul(raw, v->cp->p, raw, zctx);
            fmpz_mpoly_set(norm, v->cp->p, zctx);
        }
        o = json_object();
        json_object_set_new(o, "analysis", json_string("expect"));
        json_object_set_new(o, "of", json_string(bil ? "bilinear" : "charpoly"));
        json_object_set_new(o, "text", json_string(q->text));
        if (fmpq_mpoly_is_zero(num, v->s->ctx)) {
            json_object_set_new(o, "status", json_string("different"));
            json_object_set_new(o, "difference", rs_json_zpoly(norm, v->s));
        } else {
            rs_compare_poly(o, num, norm, raw, v->s->lambda_var, v->s, bil ? "z" : "lambda");
        }
        json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
        if (run->c->ncsets > 0) {
            /* an identity in the parameters: the complex-valued ones compared as symbols */
            json_t *ks = json_array();
            for (i = 0; i < run->c->ncsets; i++) json_array_append_new(ks, json_string(run->c->csets[i].name));
            json_object_set_new(o, "kept_symbolic", ks);
            json_object_set_new(o, "note", json_string("parameters with a complex set value are compared as symbols "
                                                       "(the printed polynomial is an identity in them)"));
        }
        if (strcmp(json_string_value(json_object_get(o, "status")), "different") == 0)
            run->outcome |= RS_OUTCOME_FAILED;
        json_array_append_new(run->results, o);
        fmpz_mpoly_clear(raw, zctx);
        fmpz_mpoly_clear(norm, zctx);
    }
    fmpq_mpoly_clear(num, v->s->ctx);
    fmpq_mpoly_clear(den, v->s->ctx);
    rs_assign_free(a, n);
    return r;
}
