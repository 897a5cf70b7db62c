/* an_stability.c -- `stability` of the equations: every parameter set,
 * the exact verdict with root counts (Routh and Schur-Cohn must agree; a
 * char line over Q(i) also by the complex pair of an_complex.c). */
#include "analysis/registry.h"
#include "analysis/an_qd.h"

static int stability_real(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    rs_variant_t *v;
    fmpz_poly_t p;
    rs_rootcount_t rc;
    json_t *o;
    int r, done;
    r = rs_run_variant_or_vanishing(&v, &done, run, "stability", 1);
    if (r != RS_OK || done) return r;
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, q, v, "stability");
    if (r == RS_OK) {
        o = json_object();
        json_object_set_new(o, "analysis", json_string("stability"));
        rs_rootcount_init(rc);
        r = rs_run_exact_count(rc, run, p, o);
        if (r == RS_OK) {
            rs_status_t st;
            rs_run_count_zeros(rc, v, p);   /* det's roots at 0 count inside */
            rs_json_add_count(o, rc);
            r = rs_run_verdict(&st, run, v->s, NULL, NULL, 0, p, rc, v->singular, o);
            /* a char line over Q(i): its real block form decided; the complex
             * pair (Schur-Cohn over Q(i), Bilharz) must agree */
            if (r == RS_OK && v->s->complex_char && v->not_in_p == NULL)
                r = rs_an_complex_char_check(run, req, st, o);
        }
        if (r == RS_OK) {
            rs_run_emit_exact(run, v, o);
        } else {
            json_decref(o);
        }
        rs_rootcount_clear(rc);
    }
    fmpz_poly_clear(p);
    return r;
}

int rs_an_stability(rs_run_t *run, const rs_an_req_t *req)
{
    if (run->m->qd != NULL) return rs_an_qd_stability(run, req);   /* R over Q(sqrt d) */
    /* at complex set values: over Q(i) (an_complex.c) */
    if (rs_an_complex_mode(run)) return rs_an_complex_stability(run, req);
    return stability_real(run, req);
}
