/* analysis_recurrence.c -- numeric matrix recurrences (entries with exp,
 * sin, ...): certified spectral radius from the block companion matrix, the
 * entries re-evaluated at doubled precision until it certifies. */
#include <stdlib.h>
#include <string.h>
#include "analysis/impl.h"
#include "analysis/registry.h"
#include "lower/recurrence.h"
#include "recstab/radius.h"

int rs_an_rec_radius(rs_run_t *run, slong digits, int stability, const rs_request_t *q)
{
    slong prec, K = 0, i;
    rs_radius_t rr;
    json_t *o;
    int r = RS_ERR_UNDECIDED;
    rs_radius_init(rr);
    for (prec = 3.33 * digits + 64; prec <= run->opt->max_prec; prec *= 2) {
        acb_mat_struct *A = NULL;
        r = rs_recurrence_matrices(&A, &K, run->m, prec, run->err);
        if (r == RS_OK) r = rs_radius_matrix_poly(rr, A, K, digits, run->opt->max_prec, run->err);
        for (i = 0; A && i <= K; i++) acb_mat_clear(A + i);
        flint_free(A);
        if (r != RS_ERR_UNDECIDED && r != RS_ERR_LIMIT) break;
        rs_error_init(run->err);
    }
    if (r != RS_OK) {
        rs_radius_clear(rr);
        /* out of precision is a resource limit of the request */
        if (run->err->file[0] == '\0' && r == RS_ERR_UNDECIDED) r = RS_ERR_LIMIT;
        return rs_req_relocate(run, q, r, "radius");
    }
    o = json_object();
    json_object_set_new(o, "analysis", json_string(stability ? "stability" : "radius"));
    json_object_set_new(o, "method", json_string("block companion matrix of the recurrence, entries in Arb "
                                                 "(certified eigenvalue enclosures)"));
    rs_json_radius(o, rr, digits);
    json_object_set_new(o, "status", json_string(rs_radius_verdict(rr)));
    json_object_set_new(o, "decided_by", json_string("certified"));
    json_object_set_new(o, "substituted", rs_json_sets(run->c));
    json_array_append_new(run->results, o);
    rs_radius_clear(rr);
    return RS_OK;
}
