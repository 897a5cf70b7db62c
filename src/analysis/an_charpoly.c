/* an_charpoly.c -- `charpoly`: p(lambda) = det of the lambda-matrix,
 * fraction-free, lambda^k and the rational content split off. */
#include <stdlib.h>
#include "analysis/registry.h"
#include "util/polyfmt.h"
#include "analysis/an_qd.h"

json_t *rs_charpoly_json(const rs_variant_t *v)
{
    const rs_scheme_struct *s = v->s;
    json_t *o = json_object();
    char *str;
    json_object_set_new(o, "analysis", json_string("charpoly"));
    json_object_set_new(o, "var", json_string("lambda"));
    json_object_set_new(o, "degree", json_integer(v->cp->degree));
    json_object_set_new(o, "coeffs", rs_json_coeffs(v->cp->p, s->lambda_var, s));
    json_object_set_new(o, "removed_lambda_power", json_integer(v->cp->removed_lambda_power));
    json_object_set_new(o, "content", rs_json_fmpq(v->cp->content));
    str = rs_polyfmt_collected(v->cp->p, s->lambda_var, (const char **) s->vars, s->zctx);
    json_object_set_new(o, "poly", json_string(str));
    free(str);
    if (!fmpz_mpoly_is_fmpz(v->cp->param_content, s->zctx))
        json_object_set_new(o, "param_content", rs_json_zpoly(v->cp->param_content, s));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_object_set_new(o, "nonzero_assumptions", rs_json_nonzero(s));
    json_object_set_new(o, "decided_by", json_string("exact"));
    return o;
}

static int charpoly_real(rs_run_t *run, const rs_an_req_t *req)
{
    rs_assign_t *a;
    slong n;
    rs_variant_t *v = NULL;
    int r;
    (void) req;
    rs_run_assignments(run, &a, &n, NULL, 0, NULL, 0);
    r = rs_run_variant(&v, run, a, n);
    rs_assign_free(a, n);
    /* det A identically 0 at the set values: singular, as stability says */
    if (r != RS_OK) return rs_run_failed_or_vanishing(run, r, v, "charpoly");
    {
        json_t *o = rs_charpoly_json(v);
        if (v->singular) rs_json_set_singular_step(o);   /* the degree drops here: as stability says */
        json_array_append_new(run->results, o);
    }
    return RS_OK;
}

int rs_an_charpoly(rs_run_t *run, const rs_an_req_t *req)
{
    if (run->m->qd != NULL) return rs_an_qd_charpoly(run, req);   /* R over Q(sqrt d) */
    /* at complex set values: over Q(i) (an_complex.c) */
    if (rs_an_complex_mode(run)) return rs_an_complex_charpoly(run, req);
    return charpoly_real(run, req);
}
