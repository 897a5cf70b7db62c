/* an_limit.c -- `limit NAME -> 0|inf`: the limits of the roots with their
 * multiplicities (spurious roots, stiff decay). */
#include <stdlib.h>
#include <string.h>
#include <arb.h>
#include <acb.h>
#include <arb_fmpz_poly.h>
#include <math.h>
#include "analysis/registry.h"
#include "util/polyfmt.h"

/* ---- limit ------------------------------------------------------------------- */

/* the roots of f (with multiplicity) as JSON: rationals exactly, other
 * algebraic roots by minimal polynomial and a 20-digit value */
static void roots_json(json_t *arr, const fmpz_poly_t f)
{
    fmpz_poly_factor_t fac;
    slong i, k;
    if (fmpz_poly_degree(f) < 1) return;
    fmpz_poly_factor_init(fac);
    fmpz_poly_factor(fac, f);
    for (i = 0; i < fac->num; i++) {
        const fmpz_poly_struct *g = fac->p + i;
        slong d = fmpz_poly_degree(g), e = fac->exp[i];
        if (d < 1) continue;
        if (d == 1) {
            fmpq_t x;
            fmpq_init(x);
            fmpq_set_fmpz_frac(x, g->coeffs + 0, g->coeffs + 1);
            fmpq_neg(x, x);
            json_array_append_new(arr, json_pack("{s:o,s:I,s:f}", "value", rs_json_fmpq(x),
                                                 "multiplicity", (json_int_t) e, "abs", fabs(fmpq_get_d(x))));
            fmpq_clear(x);
        } else {
            acb_ptr r = _acb_vec_init(d);
            char *mp = rs_polyfmt_fmpz_poly(g, "lambda");
            rs_radius_complex_roots(r, g, 96);
            for (k = 0; k < d; k++) {
                char *re = arb_get_str(acb_realref(r + k), 20, ARB_STR_NO_RADIUS);
                char *im = arb_get_str(acb_imagref(r + k), 20, ARB_STR_NO_RADIUS);
                char *val = malloc(strlen(re) + strlen(im) + 8);
                arb_t ab;
                arb_init(ab);
                acb_abs(ab, r + k, 96);
                if (arb_is_zero(acb_imagref(r + k))) sprintf(val, "%s", re);
                else sprintf(val, "%s %s %si", re, im[0] == '-' ? "-" : "+", im[0] == '-' ? im + 1 : im);
                json_array_append_new(arr, json_pack("{s:s,s:s,s:I,s:I,s:f}", "value", val, "minpoly", mp,
                                                     "root_index", (json_int_t) k, "multiplicity", (json_int_t) e,
                                                     "abs", arf_get_d(arb_midref(ab), ARF_RND_NEAR)));
                arb_clear(ab);
                free(val);
                flint_free(re);
                flint_free(im);
            }
            free(mp);
            _acb_vec_clear(r, d);
        }
    }
    fmpz_poly_factor_clear(fac);
}

/* limit NAME -> 0|inf */
int rs_an_limit_parse(rs_an_req_t *req, rs_run_t *run)
{
    const rs_request_t *q = req->q;
    const char *rest = req->rest, *t;
    char name[80];
    t = rs_req_read_name(rest, name);
    if (t == NULL)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "expected a parameter name after limit, found '%s'", rest);
    req->u.limit.param = rs_case_param_index(run->c, name);
    if (req->u.limit.param < 0)
        return rs_req_error(run, q, rest, RS_ERR_INPUT, "'%s' is not a parameter", name);
    t = rs_req_skip_blanks(t);
    if (strncmp(t, "->", 2) != 0)
        return rs_req_error(run, q, t, RS_ERR_INPUT, "expected '-> 0' or '-> inf' after the name, found '%s'", t);
    t = rs_req_skip_blanks(t + 2);
    if (strcmp(t, "0") == 0) req->u.limit.to_inf = 0;
    else if (strcmp(t, "inf") == 0 || strcmp(t, "infinity") == 0 || strcmp(t, "oo") == 0) req->u.limit.to_inf = 1;
    else return rs_req_error(run, q, t, RS_ERR_INPUT, "expected 0 or inf, found '%s'", t);
    return RS_OK;
}

int rs_an_limit(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const char *rest = req->rest;
    const char *name = run->c->params[req->u.limit.param].name;
    slong tv = req->u.limit.param, d, k, j, dl;
    rs_variant_t *v;
    const rs_scheme_struct *s;
    int to_inf = req->u.limit.to_inf, r;
    fmpz_poly_t c;
    json_t *o, *roots;
    r = rs_run_variant_one_free(&v, run, q, rest, tv, "limit");
    if (r != RS_OK) return r;
    s = v->s;
    d = fmpz_mpoly_degree_si(v->cp->p, tv, s->zctx);
    dl = v->cp->degree;
    fmpz_poly_init(c);
    /* t -> 0: the lowest non-zero coefficient in t; t -> inf: the highest */
    if (to_inf) {
        rs_run_coeff_in(c, v->cp->p, tv, d < 0 ? 0 : d, s);
    } else {
        for (j = 0; j <= d; j++) {
            rs_run_coeff_in(c, v->cp->p, tv, j, s);
            if (!fmpz_poly_is_zero(c)) break;
        }
    }
    o = json_object();
    json_object_set_new(o, "analysis", json_string("limit"));
    json_object_set_new(o, "param", json_string(name));
    json_object_set_new(o, "to", json_string(to_inf ? "inf" : "0"));
    {
        char *lp = rs_polyfmt_fmpz_poly(c, "lambda");
        json_object_set_new(o, "limit_poly", json_string(lp));
        free(lp);
    }
    roots = json_array();
    roots_json(roots, c);
    k = dl - fmpz_poly_degree(c);
    if (k > 0)
        json_array_append_new(roots, json_pack("{s:s,s:I}", "value", "inf", "multiplicity", (json_int_t) k));
    json_object_set_new(o, "roots", roots);
    {
        /* summary: every finite limit root at 0 (stiff decay), and the largest modulus */
        size_t i;
        int all_zero = (k == 0);
        double maxabs = 0;
        for (i = 0; i < json_array_size(roots); i++) {
            json_t *rt = json_array_get(roots, i);
            json_t *ab = json_object_get(rt, "abs");
            if (ab == NULL) { all_zero = 0; continue; }
            if (json_real_value(ab) != 0.0) all_zero = 0;
            if (json_real_value(ab) > maxabs) maxabs = json_real_value(ab);
        }
        json_object_set_new(o, "all_roots_to_zero", json_boolean(all_zero));
        json_object_set_new(o, "roots_to_infinity", json_integer(k));
        json_object_set_new(o, "max_abs", json_real(maxabs));
    }
    rs_run_emit_exact(run, v, o);
    fmpz_poly_clear(c);
    return RS_OK;
}
