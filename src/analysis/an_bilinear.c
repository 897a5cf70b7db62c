/* an_bilinear.c -- `bilinear`: q(z) = (1-z)^n p((1+z)/(1-z)), its degree
 * drop, the multiplicity of z = 0, p(1) and p(-1). */
#include "analysis/registry.h"
#include "recstab/bilinear.h"
#include "analysis/an_qd.h"

/* ---- bilinear ------------------------------------------------------------- */

static int bilinear_real(rs_run_t *run, const rs_an_req_t *req)
{
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_mpoly_t qz, t;
    json_t *o;
    slong d, lv;
    int r;
    (void) req;
    r = rs_run_default_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    lv = s->lambda_var;
    fmpz_mpoly_init(qz, s->zctx);
    fmpz_mpoly_init(t, s->zctx);
    rs_bilinear_fmpz_mpoly(qz, v->cp->p, lv, s->zctx);
    d = fmpz_mpoly_degree_si(qz, lv, s->zctx);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("bilinear"));
    json_object_set_new(o, "var", json_string("z"));
    json_object_set_new(o, "degree", json_integer(d));
    json_object_set_new(o, "coeffs", rs_json_coeffs(qz, lv, s));
    json_object_set_new(o, "poly", rs_json_collected(qz, lv, s, "z"));
    json_object_set_new(o, "degree_drop", json_integer(v->cp->degree - d));
    json_object_set_new(o, "zero_mult", json_integer(rs_scheme_min_degree(qz, lv, s->zctx)));
    /* where lambda = -1 / lambda = 1 become roots: p(-1) = 0 / p(1) = 0 */
    json_object_set_new(o, "p_at_1", rs_json_p_at(v, 1));
    json_object_set_new(o, "p_at_minus_1", rs_json_p_at(v, -1));
    rs_run_emit_exact(run, v, o);
    fmpz_mpoly_clear(qz, s->zctx);
    fmpz_mpoly_clear(t, s->zctx);
    return RS_OK;
}

int rs_an_bilinear(rs_run_t *run, const rs_an_req_t *req)
{
    /* at complex set values: over Q(i) (an_complex.c) */
    if (rs_an_complex_mode(run)) return rs_an_complex_bilinear(run, req);
    /* rk sdirk2, sdirk3: over Q(sqrt d) (an_qd_map.c) */
    if (run->m->qd != NULL) return rs_an_qd_bilinear(run, req);
    return bilinear_real(run, req);
}
