/* analysis/an_qd.h -- the analyses of a model with R over Q(sqrt d)
 * (model.h's qd: rk sdirk2 on the test equation; an_qd.c).  Private. */
#ifndef RECSTAB_ANALYSIS_AN_QD_H
#define RECSTAB_ANALYSIS_AN_QD_H

#include "analysis/registry.h"

/* RS_OK, or an input error at the request's line when the model has qd and
 * the analysis is not one of charpoly, stability, astability */
int rs_an_qd_check(rs_run_t *run, const rs_an_req_t *req);
/* the case is Dahlquist's test equation: one subsystem, one state y' = F,
 * nothing else (R = N/D is read from p = D lambda - N) */
int rs_an_qd_test_equation(const rs_case_struct *c);
int rs_an_qd_charpoly(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_stability(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_astability(rs_run_t *run, const rs_an_req_t *req);
int rs_an_qd_radius(rs_run_t *run, const rs_an_req_t *req);

#endif
