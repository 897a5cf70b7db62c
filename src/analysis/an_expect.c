/* an_expect.c -- `expect charpoly|bilinear POLY`: a printed polynomial
 * compared with the derived p(lambda) or q(z) (equal, proportional,
 * different). */
#include <string.h>
#include "analysis/registry.h"
#include "recstab/bilinear.h"

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
