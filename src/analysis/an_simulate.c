/* an_simulate.c -- `simulate`: the case's equations stepped in ball
 * arithmetic from a seeded random start, the measured growth per step
 * cross-checked against the exact verdict. */
#include <math.h>
#include <string.h>
#include <stdio.h>
#include <arb_mat.h>
#include <acb.h>
#include <fmpq_poly.h>
#include "analysis/registry.h"
#include "analysis/an_qd.h"
#include "stability/schur_complex.h"

/* ---- simulate: cross-check against the exact verdict ---------------------------- */

#define SIM_CHECK_MIN_STEPS 64
#define SIM_CHECK_SPREAD 1e6   /* norm ratio a bounded trajectory may show between the windows */

/* The measured growth g (log g = loggr, from log-norm averages over windows
 * centred near 3N/8 and 7N/8, N/2 apart) against the exact verdict at the
 * same point.  Allowed without contradiction: polynomial growth n^m from
 * defective circle roots (m < d = deg p; a Jordan block of a system is no
 * longer than the root's multiplicity) shifts log g by about
 * m ln(7/3) / (N/2); a bounded trajectory (semisimple circle roots, stable
 * transients) by at most ln(SIM_CHECK_SPREAD) / (N/2).  Beyond their sum
 * tau: growth clearly above 1 with a stable or marginal verdict, or clear
 * decay with a root outside the circle, is an inconsistency (exit 3).
 * Unstable only through a defective circle root (no root outside) grows
 * polynomially: its g tends to 1 and is not checked for decay. */
const char *rs_simulate_disagreement(double *tau, rs_status_t st, slong outside, double log_growth, slong degree,
                                     slong steps)
{
    *tau = ((double) degree * log(7.0 / 3.0) + log(SIM_CHECK_SPREAD)) / ((double) steps / 2);
    if (steps < SIM_CHECK_MIN_STEPS) return NULL;
    if (log_growth > *tau && (st == RS_STATUS_STABLE || st == RS_STATUS_MARGINAL))
        return "the run grows clearly faster than polynomially while the exact verdict says bounded";
    if (log_growth < -*tau && st == RS_STATUS_UNSTABLE && outside > 0)
        return "the run decays clearly while the exact verdict has a root outside the unit circle";
    return NULL;
}

/* o's "verdict" (the exact point verdict st, rc) and "check" (the run's log
 * growth lg against it by rs_simulate_disagreement; a disagreement is an
 * inconsistency, exit 3) */
static void sim_verdict_check(rs_run_t *run, json_t *o, rs_status_t st, const rs_rootcount_t rc, double lg,
                              slong degree, slong steps, const char *decided_by)
{
    double tau;
    const char *why = rs_simulate_disagreement(&tau, st, rc->outside, lg, degree, steps);
    json_t *vd = json_object(), *chk;
    rs_json_add_count(vd, rc);
    json_object_set_new(vd, "status", json_string(rs_status_name(st)));
    json_object_set_new(vd, "decided_by", json_string(decided_by));
    json_object_set_new(o, "verdict", vd);
    if (isnan(lg)) {
        /* no growth measured (the state became exactly zero or not finite):
         * the exact verdict alone, nothing to compare (h-truth6: a dead-beat
         * p = lambda had no verdict beside "growth": null); no "check" */
        return;
    }
    chk = json_object();
    json_object_set_new(chk, "log_growth", json_real(lg));
    json_object_set_new(chk, "threshold", json_real(tau));
    json_object_set_new(chk, "rule", json_string("|log growth| beyond (deg p * ln(7/3) + ln 1e6) / (steps/2): "
                                                 "polynomial growth of defective circle roots and bounded "
                                                 "oscillation stay below it"));
    json_object_set_new(chk, "consistent", json_boolean(why == NULL));
    if (why != NULL) {
        json_object_set_new(chk, "disagreement", json_string(why));
        run->outcome |= RS_OUTCOME_INCONSISTENT;
    }
    json_object_set_new(o, "check", chk);
}

/* loggr NULL: no growth measured, the exact verdict alone */
static int simulate_check(rs_run_t *run, json_t *o, const rs_variant_t *v, const fmpz_poly_t p, const arb_t loggr,
                          slong steps)
{
    rs_rootcount_t rc;
    rs_status_t st;
    int r;
    if ((loggr != NULL && fmpz_poly_degree(p) < 1) || steps < SIM_CHECK_MIN_STEPS) return RS_OK;
    /* the point verdict: semisimple repeated circle roots of systems are
     * marginal, a singular point is not compared */
    r = rs_run_point_status(&st, rc, run, v, NULL, NULL, 0);
    if (r != RS_OK) { rs_rootcount_clear(rc); return r; }
    sim_verdict_check(run, o, st, rc, loggr != NULL ? arf_get_d(arb_midref(loggr), ARF_RND_NEAR) : NAN,
                      fmpz_poly_degree(p), steps, "exact");
    rs_rootcount_clear(rc);
    return RS_OK;
}

/* ---- simulate ------------------------------------------------------------------------ */

/* coefficient of lambda^k of a (numeric) entry as a ball: over Q(sqrt d)
 * (rk sdirk2) the entry is a polynomial in sqrt(d), evaluated at its ball */
static void entry_coeff(arb_t out, const fmpq_mpoly_t e, slong k, const rs_scheme_t s, slong prec)
{
    fmpq_t c;
    arb_t sd, t;
    slong v[2] = {s->lambda_var, s->sqrt_var}, j, top;
    ulong ex[2];
    arb_zero(out);
    if (k < 0) return;
    top = s->sqrt_d > 0 ? fmpq_mpoly_degree_si(e, s->sqrt_var, s->ctx) : 0;
    fmpq_init(c);
    arb_init(sd);
    arb_init(t);
    if (s->sqrt_d > 0) arb_sqrt_ui(sd, (ulong) s->sqrt_d, prec);
    for (j = top; j >= 0; j--) {    /* Horner in sqrt(d) */
        fmpq_mpoly_t m;
        fmpq_mpoly_init(m, s->ctx);
        ex[0] = (ulong) k;
        ex[1] = (ulong) j;
        fmpq_mpoly_get_coeff_vars_ui(m, e, v, ex, s->sqrt_d > 0 ? 2 : 1, s->ctx);
        if (fmpq_mpoly_is_zero(m, s->ctx)) fmpq_zero(c);
        else fmpq_mpoly_get_fmpq(c, m, s->ctx);
        arb_set_fmpq(t, c, prec);
        if (j < top) arb_mul(out, out, sd, prec);
        arb_add(out, out, t, prec);
        fmpq_mpoly_clear(m, s->ctx);
    }
    fmpq_clear(c);
    arb_clear(sd);
    arb_clear(t);
}

/* The recurrence stepped by simulate: for each unknown u its shifts mu_u..M_u
 * in the equations, the matrix L of the coefficients of u[n+M_u] (and its
 * inverse), the history of each unknown and the other coefficients as balls;
 * scalar: the recurrence of p itself (L singular or absent). */
typedef struct {
    slong n, prec;
    int scalar;
    slong *Mu, *mu;
    arb_mat_t L, Linv;
    arb_ptr *hist;      /* per unknown: values at n+m_u .. n+M_u (newest last) */
    arb_ptr *cf;        /* the coefficient of u[n+sft] in equation i: cf[i n + u][sft - mu_u] */
    arb_ptr rhs, znew;
} sim_t;

/* the shifts of each unknown and L; the scalar recurrence of p (pc[0..N],
 * balls) when L is singular or the case is a `char` polynomial */
static void sim_shifts(sim_t *sm, const rs_scheme_struct *s, arb_srcptr pc, slong N)
{
    slong n = sm->n, u, i;
    if (s->from_char) sm->scalar = 1;
    for (u = 0; u < n && !sm->scalar; u++) {
        sm->Mu[u] = WORD_MIN;
        sm->mu[u] = WORD_MAX;
        for (i = 0; i < n; i++) {
            const fmpq_mpoly_struct *e = s->M + i * n + u;
            slong lo;
            if (fmpq_mpoly_is_zero(e, s->ctx)) continue;
            if (fmpq_mpoly_degree_si(e, s->lambda_var, s->ctx) + s->row_shift[i] > sm->Mu[u])
                sm->Mu[u] = fmpq_mpoly_degree_si(e, s->lambda_var, s->ctx) + s->row_shift[i];
            lo = rs_scheme_min_degree(e->zpoly, s->lambda_var, s->ctx->zctx) + s->row_shift[i];
            if (lo < sm->mu[u]) sm->mu[u] = lo;
        }
        if (sm->Mu[u] == WORD_MIN) sm->scalar = 1;
    }
    for (i = 0; i < n && !sm->scalar; i++)
        for (u = 0; u < n; u++)
            entry_coeff(arb_mat_entry(sm->L, i, u), s->M + i * n + u, sm->Mu[u] - s->row_shift[i], s, sm->prec);
    if (!sm->scalar && !arb_mat_inv(sm->Linv, sm->L, sm->prec)) sm->scalar = 1;
    if (sm->scalar) {
        /* the scalar recurrence of p: c_N x[n+N] = -sum c_i x[n+i] */
        arb_mat_clear(sm->L);
        arb_mat_clear(sm->Linv);
        sm->n = 1;
        arb_mat_init(sm->L, 1, 1);
        arb_mat_init(sm->Linv, 1, 1);
        arb_set(arb_mat_entry(sm->L, 0, 0), pc + N);
        arb_inv(arb_mat_entry(sm->Linv, 0, 0), arb_mat_entry(sm->L, 0, 0), sm->prec);
        sm->Mu[0] = N;
        sm->mu[0] = 0;
    }
}

/* the generator of the random start for the `seed` option (one mapping for
 * every recurrence simulate runs) */
static void sim_rand_init(flint_rand_t st, slong seed)
{
    flint_randinit(st);
    flint_randseed(st, (ulong) seed + 1, (ulong) seed * 7919 + 3);
}

/* the recurrence, a seeded random start in [-1, 1] and the coefficients;
 * pc[0..N]: p's coefficients as balls, for the scalar recurrence */
static void sim_init(sim_t *sm, const rs_scheme_struct *s, arb_srcptr pc, slong N, slong prec, flint_rand_t st)
{
    slong n, u, i;
    fmpq_t c;
    fmpq_init(c);
    memset(sm, 0, sizeof *sm);
    sm->prec = prec;
    sm->n = n = s->from_char ? 1 : s->n;
    sm->Mu = flint_calloc(n, sizeof(slong));
    sm->mu = flint_calloc(n, sizeof(slong));
    arb_mat_init(sm->L, n, n);
    arb_mat_init(sm->Linv, n, n);
    sim_shifts(sm, s, pc, N);
    n = sm->n;
    sm->hist = flint_malloc(n * sizeof(arb_ptr));
    for (u = 0; u < n; u++) {
        slong len = sm->Mu[u] - sm->mu[u] + 1, j;
        sm->hist[u] = _arb_vec_init(len);
        for (j = 0; j < len - 1; j++) {       /* seeded random start in [-1, 1] */
            fmpq_set_si(c, (slong) n_randint(st, 2001) - 1000, 1000);
            arb_set_fmpq(sm->hist[u] + j, c, prec);
        }
    }
    sm->rhs = _arb_vec_init(n);
    sm->znew = _arb_vec_init(n);
    /* the coefficient of u[n+sft] in equation i, once, as balls */
    sm->cf = flint_malloc(n * n * sizeof(arb_ptr));
    for (i = 0; i < n; i++)
        for (u = 0; u < n; u++) {
            slong sft, len = sm->Mu[u] - sm->mu[u];
            arb_ptr cv = _arb_vec_init(len > 0 ? len : 1);
            for (sft = sm->mu[u]; sft < sm->Mu[u]; sft++) {
                if (sm->scalar) arb_set(cv + (sft - sm->mu[u]), pc + sft);
                else entry_coeff(cv + (sft - sm->mu[u]), s->M + i * n + u, sft - s->row_shift[i], s, prec);
            }
            sm->cf[i * n + u] = cv;
        }
    fmpq_clear(c);
}

static void sim_clear(sim_t *sm)
{
    slong u, i, n = sm->n;
    for (u = 0; u < n; u++) _arb_vec_clear(sm->hist[u], sm->Mu[u] - sm->mu[u] + 1);
    flint_free(sm->hist);
    for (i = 0; i < n * n; i++)
        _arb_vec_clear(sm->cf[i], sm->Mu[i % n] - sm->mu[i % n] > 0 ? sm->Mu[i % n] - sm->mu[i % n] : 1);
    flint_free(sm->cf);
    _arb_vec_clear(sm->rhs, n);
    _arb_vec_clear(sm->znew, n);
    arb_mat_clear(sm->L);
    arb_mat_clear(sm->Linv);
    flint_free(sm->Mu);
    flint_free(sm->mu);
}

/* Refuses a run the time limit cannot hold: multiply-adds per step (L^-1
 * and the history terms) at about 0.5 ns (prec/64)^1.6 each, a lower bound
 * of the measured cost (20000 steps of a 2x2 system at 65536 bits take 9 s). */
static int sim_estimate(const sim_t *sm, rs_run_t *run, const rs_an_req_t *req, slong steps)
{
    double ops = (double) sm->n * (double) sm->n, limbs = sm->prec / 64.0;
    slong u;
    int r;
    for (u = 0; u < sm->n; u++) ops += (double) sm->n * (double) (sm->Mu[u] - sm->mu[u] + 1);
    r = rs_budget_estimate(run->err, "simulate", (double) steps * ops * 0.5e-9 * pow(limbs > 1 ? limbs : 1, 1.6),
                           (double) ops * (double) sm->prec / 8.0);
    if (r != RS_OK) {
        char msg[RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "%s", run->err->msg);
        r = rs_req_error(run, req->q, req->rest, RS_ERR_LIMIT, "%s", msg);
    }
    return r;
}

/* One step: the newest value of every unknown; norm = max |value| over
 * the histories (t1 scratch). */
static void sim_step(sim_t *sm, arb_t norm, arb_t t1)
{
    slong n = sm->n, prec = sm->prec, i, u;
    for (i = 0; i < n; i++) {
        arb_zero(sm->rhs + i);
        for (u = 0; u < n; u++) {
            slong k2, len = sm->Mu[u] - sm->mu[u];
            for (k2 = 0; k2 < len; k2++)
                if (!arb_is_zero(sm->cf[i * n + u] + k2))
                    arb_addmul(sm->rhs + i, sm->cf[i * n + u] + k2, sm->hist[u] + k2, prec);
        }
        arb_neg(sm->rhs + i, sm->rhs + i);
    }
    for (u = 0; u < n; u++) {
        arb_zero(sm->znew + u);
        for (i = 0; i < n; i++) arb_addmul(sm->znew + u, arb_mat_entry(sm->Linv, u, i), sm->rhs + i, prec);
        /* midpoint arithmetic at the working precision: propagated ball
         * radii grow like the sum of |coefficients|^n, not like rho^n, and
         * would swamp the measurement; the growth is a measurement */
        mag_zero(arb_radref(sm->znew + u));
    }
    /* shift histories, newest value last */
    arb_zero(norm);
    for (u = 0; u < n; u++) {
        slong len = sm->Mu[u] - sm->mu[u] + 1, j;
        arb_set(sm->hist[u] + len - 1, sm->znew + u);
        for (j = 0; j < len; j++) {
            arb_abs(t1, sm->hist[u] + j);
            arb_max(norm, norm, t1, prec);
        }
        /* the known values for the next step move one place down */
        for (j = 0; j + 1 < len; j++) arb_swap(sm->hist[u] + j, sm->hist[u] + j + 1);
    }
}

/* growth per step from the window averages of log |z| over [N/4, N/2) and
 * [3N/4, N) (sums in lognorm_mid, lognorm_end), cross-checked; the radius
 * beside it */
/* window sums of log |state| over (N/4, N/2] and (3N/4, N]: the oscillation
 * of complex modes averages out */
static void sim_window_add(arb_t lm, arb_t le, const arb_t norm, slong step, slong steps, arb_t t)
{
    if (step > steps / 4 && step <= steps / 2) { arb_log(t, norm, 64); arb_add(lm, lm, t, 64); }
    if (step > steps - steps / 4) { arb_log(t, norm, 64); arb_add(le, le, t, 64); }
}

/* lg = log growth per step from the two window sums (averages, slope
 * between the windows' centres); o gets "growth" (exp lg), or null and a
 * note when a window is not finite; returns whether lg was measured */
static int sim_growth_json(arb_t lg, json_t *o, arb_t lm, arb_t le, slong steps, slong prec)
{
    slong a1 = steps / 4 + 1, b1 = steps / 2, a2 = steps - steps / 4 + 1, b2 = steps;
    arb_t g;
    if (steps < 8 || !arb_is_finite(le) || !arb_is_finite(lm)) {
        json_object_set_new(o, "growth", json_null());
        json_object_set_new(o, "note", json_string("the state became exactly zero or unbounded"));
        return 0;
    }
    arb_div_si(lm, lm, b1 - a1 + 1, prec);
    arb_div_si(le, le, b2 - a2 + 1, prec);
    arb_sub(lg, le, lm, prec);
    arb_mul_si(lg, lg, 2, prec);
    arb_div_si(lg, lg, (a2 + b2) - (a1 + b1), prec);
    arb_init(g);
    arb_exp(g, lg, prec);
    json_object_set_new(o, "growth", rs_json_arb(g, 15));
    json_object_set_new(o, "growth_approx", json_real(arf_get_d(arb_midref(g), ARF_RND_NEAR)));
    arb_clear(g);
    return 1;
}

static int simulate_growth(rs_run_t *run, json_t *o, const rs_variant_t *v, const fmpz_poly_t p, slong steps,
                           arb_t lognorm_mid, arb_t lognorm_end, slong prec)
{
    arb_t t1;
    rs_radius_t rr;
    int r = RS_OK;
    arb_init(t1);
    r = simulate_check(run, o, v, p, sim_growth_json(t1, o, lognorm_mid, lognorm_end, steps, prec) ? t1 : NULL,
                       steps);
    rs_radius_init(rr);
    if (rs_radius_fmpz_poly(rr, p, 15, run->opt->max_prec, run->err) == RS_OK)
        json_object_set_new(o, "radius", rs_json_arb(rr->rho, 15));
    else
        rs_error_init(run->err);
    rs_radius_clear(rr);
    arb_clear(t1);
    return r;
}

/* "analysis", "steps", "seed", "precision_bits" of a new simulate result */
static json_t *sim_json_head(slong steps, slong seed, slong prec)
{
    json_t *o = json_object();
    json_object_set_new(o, "analysis", json_string("simulate"));
    json_object_set_new(o, "steps", json_integer(steps));
    json_object_set_new(o, "seed", json_integer(seed));
    json_object_set_new(o, "precision_bits", json_integer(prec));
    return o;
}

static const char *sim_recurrence_str(const sim_t *sm)
{
    return sm->scalar ? "scalar recurrence of p(lambda) (the equations' leading matrix is singular or absent)"
                      : "the case's equations as written, solved for the newest value of every unknown at each step";
}

/* the equations' run: the time limit's estimate, then steps steps with the
 * window sums of log |state| in lm, le */
static int sim_run(sim_t *sm, rs_run_t *run, const rs_an_req_t *req, slong steps, arb_t lm, arb_t le)
{
    arb_t norm, t1, t2;
    slong step;
    int r;
    arb_init(norm); arb_init(t1); arb_init(t2);
    r = sim_estimate(sm, run, req, steps);
    for (step = 1; step <= steps && r == RS_OK; step++) {
        if ((r = rs_budget_check(run->err, "simulate")) != RS_OK) break;
        sim_step(sm, norm, t1);
        sim_window_add(lm, le, norm, step, steps, t2);
    }
    arb_clear(norm); arb_clear(t1); arb_clear(t2);
    return r;
}

/* ---- simulate at complex set values ------------------------------------------------- */

/* The scalar recurrence c_n x[k+n] = -sum_{j<n} c_j x[k+j] with complex
 * ball coefficients c[0..n] (acb midpoints at prec bits) from a seeded
 * random complex start in [-1, 1]^2: the window sums lm, le of log |x|. */
static int acb_recurrence_run(arb_t lm, arb_t le, rs_run_t *run, const rs_an_req_t *req, acb_srcptr c, slong n,
                              slong steps, slong seed, slong prec)
{
    slong j, step;
    acb_ptr x = _acb_vec_init(n + 1);
    acb_t lcinv;
    arb_t norm, a, t2;
    fmpq_t qr, qi;
    flint_rand_t st;
    int r;
    acb_init(lcinv);
    arb_init(norm); arb_init(a); arb_init(t2);
    fmpq_init(qr); fmpq_init(qi);
    acb_inv(lcinv, c + n, prec);
    sim_rand_init(st, seed);
    for (j = 0; j < n; j++) {                   /* seeded random start in [-1, 1]^2 */
        fmpq_set_si(qr, (slong) n_randint(st, 2001) - 1000, 1000);
        fmpq_set_si(qi, (slong) n_randint(st, 2001) - 1000, 1000);
        arb_set_fmpq(acb_realref(x + j), qr, prec);
        arb_set_fmpq(acb_imagref(x + j), qi, prec);
    }
    /* the same cost model as the real scalar recurrence, four real products per complex one */
    r = rs_budget_estimate(run->err, "simulate", (double) steps * 4.0 * (double) (n + 1) * 0.5e-9
                           * pow(prec / 64.0 > 1 ? prec / 64.0 : 1, 1.6), (double) (n + 1) * (double) prec / 2.0);
    if (r != RS_OK) {
        char msg[RS_ERROR_MSG_LEN];
        snprintf(msg, sizeof msg, "%s", run->err->msg);
        r = rs_req_error(run, req->q, req->rest, RS_ERR_LIMIT, "%s", msg);
    }
    for (step = 1; step <= steps && r == RS_OK; step++) {
        if ((r = rs_budget_check(run->err, "simulate")) != RS_OK) break;
        acb_zero(x + n);
        for (j = 0; j < n; j++) acb_addmul(x + n, c + j, x + j, prec);
        acb_mul(x + n, x + n, lcinv, prec);
        acb_neg(x + n, x + n);
        /* midpoints: the growth is a measurement (see sim_step) */
        mag_zero(arb_radref(acb_realref(x + n)));
        mag_zero(arb_radref(acb_imagref(x + n)));
        arb_zero(norm);
        for (j = 1; j <= n; j++) {
            acb_abs(a, x + j, prec);
            arb_max(norm, norm, a, prec);
        }
        for (j = 0; j < n; j++) acb_swap(x + j, x + j + 1);
        sim_window_add(lm, le, norm, step, steps, t2);
    }
    flint_randclear(st);
    _acb_vec_clear(x, n + 1);
    acb_clear(lcinv);
    arb_clear(norm); arb_clear(a); arb_clear(t2);
    fmpq_clear(qr); fmpq_clear(qi);
    return r;
}

/* The scalar recurrence of p over Q(i) from a complex start; growth measured
 * as for real cases and checked against the exact Q(i) verdict
 * (rs_simulate_disagreement: exit 3). */
static int cx_simulate(rs_run_t *run, const rs_an_req_t *req, slong steps, slong seed, slong prec)
{
    fmpq_poly_t pr, pi;
    json_t *at = NULL, *o;
    rs_variant_t *v = NULL;
    slong n, j;
    acb_ptr c;
    arb_t lm, le, t1;
    fmpq_t qr, qi;
    int r;
    fmpq_poly_init(pr); fmpq_poly_init(pi);
    r = rs_an_complex_point_poly(pr, pi, &at, &v, run, req);
    n = FLINT_MAX(fmpq_poly_degree(pr), fmpq_poly_degree(pi));
    if (r == RS_OK && n < 1) {
        r = rs_req_error(run, req->q, req->rest, RS_ERR_INPUT, "simulate: p has degree %s in lambda at the complex "
                         "set values: no recurrence to run", n < 0 ? "-inf (it vanishes)" : "0");
    }
    if (r != RS_OK) {
        fmpq_poly_clear(pr); fmpq_poly_clear(pi);
        json_decref(at);
        return r;
    }
    c = _acb_vec_init(n + 1);
    arb_init(lm); arb_init(le); arb_init(t1);
    fmpq_init(qr); fmpq_init(qi);
    for (j = 0; j <= n; j++) {
        fmpq_poly_get_coeff_fmpq(qr, pr, j);
        fmpq_poly_get_coeff_fmpq(qi, pi, j);
        arb_set_fmpq(acb_realref(c + j), qr, prec);
        arb_set_fmpq(acb_imagref(c + j), qi, prec);
    }
    r = acb_recurrence_run(lm, le, run, req, c, n, steps, seed, prec);
    if (r == RS_OK) {
        o = sim_json_head(steps, seed, prec);
        json_object_set_new(o, "over", json_string("Q(i)"));
        json_object_set_new(o, "recurrence", json_string("scalar recurrence of p(lambda) over Q(i): complex "
                                                         "coefficients, complex states"));
        json_object_set_new(o, "arithmetic", json_string("Arb complex midpoints at the working precision"));
        if (sim_growth_json(t1, o, lm, le, steps, prec) && steps >= SIM_CHECK_MIN_STEPS) {
            rs_rootcount_t rc;
            rs_status_t vst;
            r = rs_run_point_status(&vst, rc, run, v, NULL, NULL, 0);
            if (r == RS_OK)
                sim_verdict_check(run, o, vst, rc, arf_get_d(arb_midref(t1), ARF_RND_NEAR), n, steps,
                                  "exact (complex Schur-Cohn and Bilharz over Q(i))");
            rs_rootcount_clear(rc);
        }
        if (r == RS_OK) {
            /* the radius: p conj(p) has p's moduli */
            fmpz_poly_t N;
            rs_radius_t rr;
            fmpz_poly_init(N);
            rs_radius_init(rr);
            rs_schur_complex_norm(N, pr, pi);
            if (rs_radius_fmpz_poly(rr, N, 15, run->opt->max_prec, run->err) == RS_OK)
                json_object_set_new(o, "radius", rs_json_arb(rr->rho, 15));
            else
                rs_error_init(run->err);
            rs_radius_clear(rr);
            fmpz_poly_clear(N);
        }
        json_object_set_new(o, "decided_by", json_string("time-domain run (measurement, not a certificate)"));
        {
            json_t *sub = json_deep_copy(v->assigned);
            json_object_update(sub, at);
            json_object_set_new(o, "substituted", sub);
        }
        if (r == RS_OK) json_array_append_new(run->results, o);
        else json_decref(o);
    }
    _acb_vec_clear(c, n + 1);
    arb_clear(lm); arb_clear(le); arb_clear(t1);
    fmpq_clear(qr); fmpq_clear(qi);
    fmpq_poly_clear(pr); fmpq_poly_clear(pi);
    json_decref(at);
    return r;
}

/* ---- simulate over Q(sqrt d) (rk sdirk2) --------------------------------------------- */

/* At real set values the case's equations as the rational path runs them,
 * their coefficients in Q(sqrt d) as balls (sqrt d enclosed); at complex
 * ones the scalar recurrence of p over Q(sqrt d)(i).  The growth is checked
 * against the exact verdict over Q(sqrt d)(i) (exit 3 on a disagreement);
 * no check when that verdict is undecided (a root on or near the circle). */
static int qd_simulate(rs_run_t *run, const rs_an_req_t *req, slong steps, slong seed, slong prec)
{
    json_t *o = sim_json_head(steps, seed, prec);
    rs_rootcount_t rc;
    rs_status_t vst = RS_STATUS_STABLE;
    rs_variant_t *v;
    acb_ptr c = NULL;
    arb_ptr pc = NULL;
    arb_t lm, le, t1;
    slong n = -1, j;
    int r, decided = 0;
    rs_rootcount_init(rc);
    arb_init(lm); arb_init(le); arb_init(t1);
    r = rs_an_qd_point(&c, &n, &decided, &vst, rc, o, run, req->q, prec);
    if (r == RS_OK && run->c->ncsets > 0) {
        json_object_set_new(o, "recurrence", json_string("scalar recurrence of p(lambda) over Q(sqrt d)(i): complex "
                                                         "coefficients (sqrt d a ball), complex states"));
        json_object_set_new(o, "arithmetic", json_string("Arb complex midpoints at the working precision"));
        r = acb_recurrence_run(lm, le, run, req, c, n, steps, seed, prec);
    } else if (r == RS_OK) {
        sim_t sm;
        flint_rand_t st;
        r = rs_run_default_variant(run, &v);
        if (r == RS_OK) {
            pc = _arb_vec_init(n + 1);
            for (j = 0; j <= n; j++) arb_set(pc + j, acb_realref(c + j));   /* real set values: p is real */
            sim_rand_init(st, seed);
            sim_init(&sm, v->s, pc, n, prec, st);
            json_object_set_new(o, "recurrence", json_string(sim_recurrence_str(&sm)));
            json_object_set_new(o, "arithmetic", json_string("Arb midpoints at the working precision, the "
                                                             "coefficients' sqrt(d) a ball"));
            r = sim_run(&sm, run, req, steps, lm, le);
            sim_clear(&sm);
            flint_randclear(st);
        }
    }
    if (r == RS_OK && sim_growth_json(t1, o, lm, le, steps, prec) && steps >= SIM_CHECK_MIN_STEPS) {
        if (decided)
            sim_verdict_check(run, o, vst, rc, arf_get_d(arb_midref(t1), ARF_RND_NEAR), n, steps,
                              "exact (Schur-Cohn over Q(sqrt d)(i) and the certified roots)");
        else
            json_object_set_new(o, "verdict", json_pack("{s:s,s:s}", "status", "undecided", "note", "not compared "
                                                        "with the run: a root on or too near the unit circle, "
                                                        "marginal and unstable not told apart over Q(sqrt d)"));
    }
    if (r == RS_OK) {
        json_object_set_new(o, "decided_by", json_string("time-domain run (measurement, not a certificate)"));
        json_array_append_new(run->results, o);
    } else {
        json_decref(o);
    }
    if (c != NULL) _acb_vec_clear(c, n + 1);
    if (pc != NULL) _arb_vec_clear(pc, n + 1);
    rs_rootcount_clear(rc);
    arb_clear(lm); arb_clear(le); arb_clear(t1);
    return r;
}

int rs_an_simulate(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_optval_t *o_steps = rs_an_opt(req, "steps"), *o_seed = rs_an_opt(req, "seed"),
                      *o_prec = rs_an_opt(req, "prec");
    slong steps = o_steps->at != NULL ? o_steps->num : 1000, seed = o_seed->at != NULL ? o_seed->num : 1;
    slong prec = o_prec->at != NULL ? o_prec->num : 128, j, N;
    rs_variant_t *v;
    fmpz_poly_t p;
    arb_ptr pc;
    sim_t sm;
    json_t *o;
    arb_t lognorm_mid, lognorm_end;
    flint_rand_t st;
    int r;
    if (run->m->qd != NULL) return qd_simulate(run, req, steps, seed, prec);
    if (run->c->ncsets > 0) return cx_simulate(run, req, steps, seed, prec);
    v = NULL;
    r = rs_run_numeric_variant(run, &v);
    /* det A identically 0: no recurrence to run, singular as stability says */
    if (r != RS_OK) return rs_run_failed_or_vanishing(run, r, v, "simulate");
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, req->q, v, "simulate");
    if (r != RS_OK) { fmpz_poly_clear(p); return r; }
    N = fmpz_poly_degree(p);
    pc = _arb_vec_init(N + 1);
    for (j = 0; j <= N; j++) arb_set_fmpz(pc + j, p->coeffs + j);
    sim_rand_init(st, seed);
    sim_init(&sm, v->s, pc, N, prec, st);
    arb_init(lognorm_mid); arb_init(lognorm_end);
    r = sim_run(&sm, run, req, steps, lognorm_mid, lognorm_end);
    if (r == RS_OK) {
        o = sim_json_head(steps, seed, prec);
        json_object_set_new(o, "recurrence", json_string(sim_recurrence_str(&sm)));
        json_object_set_new(o, "arithmetic", json_string("Arb midpoints at the working precision"));
        r = simulate_growth(run, o, v, p, steps, lognorm_mid, lognorm_end, prec);
        json_object_set_new(o, "decided_by", json_string("time-domain run (measurement, not a certificate)"));
        json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
        if (r == RS_OK) json_array_append_new(run->results, o);
        else json_decref(o);
    }
    sim_clear(&sm);
    _arb_vec_clear(pc, N + 1);
    arb_clear(lognorm_mid); arb_clear(lognorm_end);
    flint_randclear(st);
    fmpz_poly_clear(p);
    return r;
}
