/* analysis_numeric.c -- certified numeric analyses: radius (Arb, with the
 * GSL double baseline on request), modes (equivalent continuous
 * eigenvalues, damping, frequency error) and simulate (the scheme's own
 * equations stepped in ball arithmetic). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <arb.h>
#include <acb.h>
#include <arb_mat.h>
#include "recstab/budget.h"
#include "analysis/impl.h"
#include "analysis/registry.h"
#include "numeric/modes.h"
#include "recstab/radius.h"
#include "recstab/rootcount.h"
#include "util/polyfmt.h"


/* A root enclosure as midpoint strings re, im and one radius covering the
 * ball and the rounding of both printed midpoints (rounded up to double). */
static json_t *acb_json(const acb_t z, slong digits)
{
    json_t *o = json_object();
    mag_t mr, mi;
    arf_t a;
    char *re, *im;
    mag_init(mr);
    mag_init(mi);
    arf_init(a);
    re = rs_radius_str_ball(mr, acb_realref(z), digits);
    im = rs_radius_str_ball(mi, acb_imagref(z), digits);
    json_object_set_new(o, "re", json_string(re));
    json_object_set_new(o, "im", json_string(im));
    mag_max(mr, mr, mi);
    arf_set_mag(a, mr);
    json_object_set_new(o, "radius", json_real(arf_get_d(a, ARF_RND_UP)));
    flint_free(re);
    flint_free(im);
    mag_clear(mr);
    mag_clear(mi);
    arf_clear(a);
    return o;
}

/* ---- radius ---------------------------------------------------------------------- */

/* When the radius interval contains 1 but no root lies on the circle (so
 * rho != 1), more digits separate it from 1: raise them (x4 per round, while
 * the precision stays within --max-prec) until upper < 1 or lower > 1.  rr
 * keeps the most precise result; returns the digits it was computed with
 * (digits when no refinement ran or none helped). */
static slong radius_refine(rs_radius_t rr, rs_run_t *run, const fmpz_poly_t p, const rs_rootcount_t rc,
                              const char *method, slong digits)
{
    slong cap = (slong) ((double) (run->opt->max_prec > 0 ? run->opt->max_prec : RS_RADIUS_MAX_PREC_DEFAULT)
                         / 3.33) - 12, d = digits, got = digits;
    rs_radius_t r2;
    int r;
    if (rc->on > 0 || strcmp(rs_radius_verdict(rr), "undecided") != 0) return digits;
    rs_radius_init(r2);
    while (d < cap && strcmp(rs_radius_verdict(rr), "undecided") == 0) {
        d = FLINT_MIN(4 * d, cap);
        if (strcmp(method, "companion") == 0)
            r = rs_radius_fmpz_poly_companion(r2, p, d, run->opt->max_prec, run->err);
        else
            r = rs_radius_fmpz_poly(r2, p, d, run->opt->max_prec, run->err);
        if (r != RS_OK) {                 /* out of precision: stays undecided */
            rs_error_init(run->err);
            break;
        }
        rs_radius_swap(rr, r2);
        got = d;
    }
    rs_radius_clear(r2);
    return got;
}

int rs_an_radius(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_optval_t *dg = rs_an_opt(req, "digits");
    rs_variant_t *v;
    fmpz_poly_t p;
    rs_radius_t rr;
    rs_rootcount_t rc;
    const char *method = rs_an_opt_choice(req, "method");
    slong digits = dg->at != NULL ? dg->num : run->opt->default_digits, i;
    json_t *o, *roots;
    int r;
    r = rs_run_numeric_variant(run, &v);
    if (r != RS_OK) return r;
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, q, v, "radius");
    if (r != RS_OK) { fmpz_poly_clear(p); return r; }
    rs_radius_init(rr);
    rs_rootcount_init(rc);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("radius"));
    if (fmpz_poly_degree(p) < 1) {
        /* det A = c*lambda^k: every root is 0 (dead-beat), radius exactly 0 */
        json_object_set_new(o, "method", json_string("exact: det A = c*lambda^k, every root is 0"));
        json_object_set_new(o, "certified", json_true());
        json_object_set_new(o, "lower", json_string("0"));
        json_object_set_new(o, "upper", json_string("0"));
        json_object_set_new(o, "rho", json_string("0"));
        json_object_set_new(o, "roots", json_array());
        arb_zero(rr->lower);
        arb_zero(rr->upper);
        arb_zero(rr->rho);
    } else if (strcmp(method, "double") == 0) {
        r = rs_radius_double(rr, p, run->err);
        if (r == RS_OK) {
            json_object_set_new(o, "method", json_string("double (GSL gsl_poly_complex_solve, uncertified)"));
            json_object_set_new(o, "certified", json_false());
            json_object_set_new(o, "rho", json_real(rr->rho_double));
            roots = json_array();
            for (i = 0; i < rr->nroots; i++)
                json_array_append_new(roots, json_pack("{s:f,s:f}", "re",
                    arf_get_d(arb_midref(acb_realref(rr->roots + i)), ARF_RND_NEAR), "im",
                    arf_get_d(arb_midref(acb_imagref(rr->roots + i)), ARF_RND_NEAR)));
            json_object_set_new(o, "roots", roots);
        }
    } else {
        if (strcmp(method, "companion") == 0)
            r = rs_radius_fmpz_poly_companion(rr, p, digits, run->opt->max_prec, run->err);
        else
            r = rs_radius_fmpz_poly(rr, p, digits, run->opt->max_prec, run->err);
        if (r == RS_OK) {
            json_object_set_new(o, "method", json_string(
                rr->method == RS_RADIUS_METHOD_COMPANION ? "companion matrix, acb_mat_eig_simple/multiple (certified)"
                : rr->method == RS_RADIUS_METHOD_COMPLEX_ROOTS ? "arb_fmpz_poly_complex_roots on squarefree factors (certified)"
                : rr->method == RS_RADIUS_METHOD_FIND_ROOTS ? "acb_poly_find_roots + validation on squarefree factors (certified)"
                : "certified enclosure"));
            rs_json_radius(o, rr, digits);
            roots = json_array();
            for (i = 0; i < rr->nroots; i++) {
                json_t *z = acb_json(rr->roots + i, digits);
                arb_t ab;
                arb_init(ab);
                acb_abs(ab, rr->roots + i, rr->prec);
                json_object_set_new(z, "abs", rs_json_arb(ab, digits));
                json_object_set_new(z, "multiplicity", json_integer(rr->mult ? rr->mult[i] : 1));
                arb_clear(ab);
                json_array_append_new(roots, z);
            }
            json_object_set_new(o, "roots", roots);
        }
    }
    if (r == RS_OK) {
        /* the exact verdict at the same point decides; the radius must agree */
        r = rs_run_exact_count(rc, run, p, NULL);
    }
    if (r == RS_OK) {
        rs_status_t st;
        int consistent = 1;
        r = rs_run_verdict(&st, run, v->s, NULL, NULL, 0, p, rc, v->singular, NULL);
        json_object_set_new(o, "exact_status", json_string(rs_status_name(st)));
        if (v->singular)
            json_object_set_new(o, "singular", json_string("the leading coefficient of det A(lambda) vanishes "
                                "here: the step cannot be solved; the radius is that of the reduced polynomial"));
        if (strcmp(method, "double") != 0 && !v->singular) {
            const char *nv;
            slong got = radius_refine(rr, run, p, rc, method, digits);
            if (got > digits) {
                /* the printed bounds came from the refined run: reprint */
                rs_json_radius(o, rr, digits);
                json_object_set_new(o, "verdict_digits", json_integer(got));
            }
            /* only certified comparisons: a radius interval that contains 1
             * decides nothing, so it cannot contradict the exact count */
            nv = rs_radius_verdict(rr);
            if (strcmp(nv, "stable") == 0 && (rc->on > 0 || rc->outside > 0)) consistent = 0;
            if (strcmp(nv, "unstable") == 0 && rc->outside == 0) consistent = 0;
            json_object_set_new(o, "verdict_from_radius", json_string(strcmp(nv, "undecided") != 0 ? nv :
                "undecided numerically (the interval contains 1): the exact side decides"));
            json_object_set_new(o, "consistent", json_boolean(consistent));
            if (!consistent) run->outcome |= RS_OUTCOME_INCONSISTENT;
        }
        json_object_set_new(o, "decided_by", json_string("exact"));
        json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
        json_array_append_new(run->results, o);
    } else {
        json_decref(o);
        r = rs_req_relocate(run, q, r, "radius");
    }
    rs_rootcount_clear(rc);
    rs_radius_clear(rr);
    fmpz_poly_clear(p);
    return r;
}

/* ---- modes ------------------------------------------------------------------------ */

/* A numeric request expression (parameters allowed, at their set values). */
static int eval_number(arb_t out, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v, const char *text,
                       slong prec)
{
    fmpq_t a;
    int r;
    fmpq_init(a);
    r = rs_req_eval_points(a, 1, run, q, v, text, -1, NULL, 1, NULL);
    if (r == RS_OK) arb_set_fmpq(out, a, prec);
    fmpq_clear(a);
    return r;
}

int rs_an_modes(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_optval_t *o_h = rs_an_opt(req, "h"), *o_ref = rs_an_opt(req, "reference");
    rs_variant_t *v;
    fmpz_poly_t p;
    rs_radius_t rr;
    const char *hs;
    arb_t h, *refs = NULL;
    slong nref = 0, i, prec = 128, digits = 15;
    int *principal;
    json_t *o, *modes, *spur;
    int r;
    r = rs_run_numeric_variant(run, &v);
    if (r != RS_OK) return r;
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, q, v, "modes");
    if (r != RS_OK) { fmpz_poly_clear(p); return r; }
    arb_init(h);
    arb_one(h);
    /* options: h=EXPR (time step; default 1 for schemes scaled by h), reference=EXPR[,EXPR...] */
    hs = o_h->val;
    if (hs != NULL) {
        r = eval_number(h, run, q, v, hs, prec);
        /* ln(lambda)/h: a step must be positive */
        if (r == RS_OK && !arb_is_positive(h))
            r = rs_req_error(run, q, hs, RS_ERR_INPUT, "expected a time step h > 0, found '%s'", hs);
    }
    if (r == RS_OK && o_ref->nlist > 0) {
        refs = calloc((size_t) o_ref->nlist, sizeof(arb_t));
        for (i = 0; i < o_ref->nlist && r == RS_OK; i++) {
            arb_init(refs[nref]);
            r = eval_number(refs[nref], run, q, v, o_ref->list[i], prec);
            nref++;
        }
    }
    if (r != RS_OK) {
        for (i = 0; i < nref; i++) arb_clear(refs[i]);
        free(refs);
        arb_clear(h);
        fmpz_poly_clear(p);
        return r;
    }
    rs_radius_init(rr);
    r = rs_radius_fmpz_poly(rr, p, 30, run->opt->max_prec, run->err);
    if (r != RS_OK) {
        for (i = 0; i < nref; i++) arb_clear(refs[i]);
        free(refs);
        arb_clear(h);
        rs_radius_clear(rr);
        fmpz_poly_clear(p);
        return r;
    }
    /* principal roots: for each reference w0, the root with Im >= 0 closest to
     * exp(i w0 h) and its conjugate; every other root is spurious */
    principal = calloc((size_t) rr->nroots + 1, sizeof(int));
    rs_modes_principal(principal, rr, h, (arb_srcptr) refs, nref, prec);
    o = json_object();
    json_object_set_new(o, "analysis", json_string("modes"));
    json_object_set_new(o, "h", rs_json_arb(h, digits));
    modes = json_array();
    spur = json_array();
    for (i = 0; i < rr->nroots; i++) {
        json_t *m = json_object();
        arb_t sig, om, mag, xi, err;
        arb_init(sig); arb_init(om); arb_init(mag); arb_init(xi); arb_init(err);
        json_object_set_new(m, "root", acb_json(rr->roots + i, digits));
        if (acb_is_zero(rr->roots + i)) {
            json_object_set_new(m, "note", json_string("root at 0: no continuous equivalent"));
        } else {
            rs_modes_continuous(sig, om, mag, xi, rr->roots + i, h, prec);
            json_object_set_new(m, "sigma", rs_json_arb(sig, digits));
            json_object_set_new(m, "omega", rs_json_arb(om, digits));
            json_object_set_new(m, "damping_ratio", rs_json_arb(xi, digits));
            if (principal[i]) {
                arb_sub(err, mag, refs[principal[i] - 1], prec);
                arb_div(err, err, refs[principal[i] - 1], prec);
                json_object_set_new(m, "reference", rs_json_arb(refs[principal[i] - 1], digits));
                json_object_set_new(m, "frequency_error", rs_json_arb(err, digits));
            }
        }
        json_array_append_new((principal[i] || nref == 0) ? modes : spur, m);
        arb_clear(sig); arb_clear(om); arb_clear(mag); arb_clear(xi); arb_clear(err);
    }
    json_object_set_new(o, "modes", modes);
    json_object_set_new(o, "spurious", spur);
    json_object_set_new(o, "note", json_string(
        "lambda_c = ln(lambda)/h = sigma +- i omega (principal logarithm); damping ratio = -sigma/|lambda_c|; "
        "frequency error = (|lambda_c| - omega0)/omega0 for the principal roots of each reference omega0"));
    json_object_set_new(o, "decided_by", json_string("certified"));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    json_array_append_new(run->results, o);
    free(principal);
    for (i = 0; i < nref; i++) arb_clear(refs[i]);
    free(refs);
    arb_clear(h);
    rs_radius_clear(rr);
    fmpz_poly_clear(p);
    return RS_OK;
}

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

static int simulate_check(rs_run_t *run, json_t *o, const rs_variant_t *v, const fmpz_poly_t p, const arb_t loggr,
                          slong steps)
{
    rs_rootcount_t rc;
    json_t *chk, *vd;
    double tau, lg;
    const char *why = NULL;
    rs_status_t st;
    int r;
    if (fmpz_poly_degree(p) < 1 || steps < SIM_CHECK_MIN_STEPS) return RS_OK;
    /* the point verdict: semisimple repeated circle roots of systems are
     * marginal, a singular point is not compared */
    r = rs_run_point_status(&st, rc, run, v, NULL, NULL, 0);
    if (r != RS_OK) { rs_rootcount_clear(rc); return r; }
    lg = arf_get_d(arb_midref(loggr), ARF_RND_NEAR);
    why = rs_simulate_disagreement(&tau, st, rc->outside, lg, fmpz_poly_degree(p), steps);
    vd = json_object();
    rs_json_add_count(vd, rc);
    json_object_set_new(vd, "status", json_string(rs_status_name(st)));
    json_object_set_new(vd, "decided_by", json_string("exact"));
    json_object_set_new(o, "verdict", vd);
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
    rs_rootcount_clear(rc);
    return RS_OK;
}

/* ---- simulate ------------------------------------------------------------------------ */

/* coefficient of lambda^k of a (numeric) entry */
static void entry_coeff(fmpq_t c, const fmpq_mpoly_t e, slong k, const rs_scheme_t s)
{
    fmpq_mpoly_t t;
    ulong kk;
    slong lv = s->lambda_var;
    if (k < 0) { fmpq_zero(c); return; }
    kk = (ulong) k;
    fmpq_mpoly_init(t, s->ctx);
    fmpq_mpoly_get_coeff_vars_ui(t, e, &lv, &kk, 1, s->ctx);
    if (fmpq_mpoly_is_zero(t, s->ctx)) fmpq_zero(c);
    else fmpq_mpoly_get_fmpq(c, t, s->ctx);
    fmpq_mpoly_clear(t, s->ctx);
}

int rs_an_simulate(rs_run_t *run, const rs_an_req_t *req)
{
    const rs_request_t *q = req->q;
    const rs_optval_t *o_steps = rs_an_opt(req, "steps"), *o_seed = rs_an_opt(req, "seed"),
                      *o_prec = rs_an_opt(req, "prec");
    rs_variant_t *v;
    const rs_scheme_struct *s;
    fmpz_poly_t p;
    slong steps = 1000, seed = 1, prec = 128, n, i, u, step;
    slong *Mu = NULL, *mu = NULL;
    int r, scalar = 0;
    json_t *o;
    arb_mat_t L, Linv;
    arb_ptr *hist = NULL;      /* per unknown: values at n+m_u .. n+M_u (newest last) */
    arb_ptr rhs, znew, *cf;
    arb_t norm, lognorm_mid, lognorm_end, t1, t2;
    fmpq_t c;
    flint_rand_t st;
    if (o_steps->at != NULL) steps = o_steps->num;
    if (o_seed->at != NULL) seed = o_seed->num;
    if (o_prec->at != NULL) prec = o_prec->num;
    r = rs_run_numeric_variant(run, &v);
    if (r != RS_OK) return r;
    s = v->s;
    fmpz_poly_init(p);
    r = rs_run_numeric_poly(p, run, q, v, "simulate");
    if (r != RS_OK) { fmpz_poly_clear(p); return r; }
    fmpq_init(c);
    flint_randinit(st);
    flint_randseed(st, (ulong) seed + 1, (ulong) seed * 7919 + 3);
    /* the recurrence of the equations as written: for each unknown u its
     * largest shift M_u; the coefficients of u[n+M_u] form L */
    n = s->from_char ? 1 : s->n;
    Mu = flint_calloc(n, sizeof(slong));
    mu = flint_calloc(n, sizeof(slong));
    arb_mat_init(L, n, n);
    arb_mat_init(Linv, n, n);
    if (s->from_char) {
        scalar = 1;
    } else {
        for (u = 0; u < n; u++) {
            Mu[u] = WORD_MIN;
            mu[u] = WORD_MAX;
            for (i = 0; i < n; i++) {
                const fmpq_mpoly_struct *e = s->M + i * n + u;
                if (fmpq_mpoly_is_zero(e, s->ctx)) continue;
                if (fmpq_mpoly_degree_si(e, s->lambda_var, s->ctx) + s->row_shift[i] > Mu[u])
                    Mu[u] = fmpq_mpoly_degree_si(e, s->lambda_var, s->ctx) + s->row_shift[i];
                {
                    slong lo = rs_scheme_min_degree(e->zpoly, s->lambda_var, s->ctx->zctx) + s->row_shift[i];
                    if (lo < mu[u]) mu[u] = lo;
                }
            }
            if (Mu[u] == WORD_MIN) { scalar = 1; break; }
        }
        for (i = 0; i < n && !scalar; i++)
            for (u = 0; u < n; u++) {
                entry_coeff(c, s->M + i * n + u, Mu[u] - s->row_shift[i], s);
                arb_set_fmpq(arb_mat_entry(L, i, u), c, prec);
            }
        if (!scalar && !arb_mat_inv(Linv, L, prec)) scalar = 1;
    }
    if (scalar) {
        /* the scalar recurrence of p: c_N x[n+N] = -sum c_i x[n+i] */
        slong N = fmpz_poly_degree(p);
        arb_mat_clear(L);
        arb_mat_clear(Linv);
        n = 1;
        arb_mat_init(L, 1, 1);
        arb_mat_init(Linv, 1, 1);
        arb_set_fmpz(arb_mat_entry(L, 0, 0), p->coeffs + N);
        arb_inv(arb_mat_entry(Linv, 0, 0), arb_mat_entry(L, 0, 0), prec);
        Mu[0] = N;
        mu[0] = 0;
    }
    hist = flint_malloc(n * sizeof(arb_ptr));
    for (u = 0; u < n; u++) {
        slong len = Mu[u] - mu[u] + 1, j;
        hist[u] = _arb_vec_init(len);
        for (j = 0; j < len - 1; j++) {       /* seeded random start in [-1, 1] */
            fmpq_set_si(c, (slong) n_randint(st, 2001) - 1000, 1000);
            arb_set_fmpq(hist[u] + j, c, prec);
        }
    }
    rhs = _arb_vec_init(n);
    znew = _arb_vec_init(n);
    arb_init(norm); arb_init(lognorm_mid); arb_init(lognorm_end); arb_init(t1); arb_init(t2);
    /* the coefficient of u[n+sft] in equation i, once, as balls */
    cf = flint_malloc(n * n * sizeof(arb_ptr));
    for (i = 0; i < n; i++)
        for (u = 0; u < n; u++) {
            slong sft, len = Mu[u] - mu[u];
            arb_ptr cv = _arb_vec_init(len > 0 ? len : 1);
            for (sft = mu[u]; sft < Mu[u]; sft++) {
                if (scalar) {
                    fmpz_set(fmpq_numref(c), p->coeffs + sft);
                    fmpz_one(fmpq_denref(c));
                } else entry_coeff(c, s->M + i * n + u, sft - s->row_shift[i], s);
                arb_set_fmpq(cv + (sft - mu[u]), c, prec);
            }
            cf[i * n + u] = cv;
        }
    {
        /* multiply-adds per step (L^-1 and the history terms) at about
         * 0.5 ns (prec/64)^1.6 each: a lower bound of the measured cost
         * (20000 steps of a 2x2 system at 65536 bits take 9 s) */
        double ops = (double) n * (double) n, limbs = prec / 64.0;
        for (u = 0; u < n; u++) ops += (double) n * (double) (Mu[u] - mu[u] + 1);
        r = rs_budget_estimate(run->err, "simulate", (double) steps * ops * 0.5e-9 * pow(limbs > 1 ? limbs : 1, 1.6),
                               (double) ops * (double) prec / 8.0);
        if (r != RS_OK) {
            char msg[RS_ERROR_MSG_LEN];
            snprintf(msg, sizeof msg, "%s", run->err->msg);
            r = rs_req_error(run, q, req->rest, RS_ERR_LIMIT, "%s", msg);
        }
    }
    for (step = 1; step <= steps && r == RS_OK; step++) {
        if ((r = rs_budget_check(run->err, "simulate")) != RS_OK) break;
        for (i = 0; i < n; i++) {
            arb_zero(rhs + i);
            for (u = 0; u < n; u++) {
                slong k2, len = Mu[u] - mu[u];
                for (k2 = 0; k2 < len; k2++)
                    if (!arb_is_zero(cf[i * n + u] + k2))
                        arb_addmul(rhs + i, cf[i * n + u] + k2, hist[u] + k2, prec);
            }
            arb_neg(rhs + i, rhs + i);
        }
        for (u = 0; u < n; u++) {
            arb_zero(znew + u);
            for (i = 0; i < n; i++) arb_addmul(znew + u, arb_mat_entry(Linv, u, i), rhs + i, prec);
            /* midpoint arithmetic at the working precision: propagated ball
             * radii grow like the sum of |coefficients|^n, not like rho^n, and
             * would swamp the measurement; the growth is a measurement */
            mag_zero(arb_radref(znew + u));
        }
        /* shift histories, newest value last */
        arb_zero(norm);
        for (u = 0; u < n; u++) {
            slong len = Mu[u] - mu[u] + 1, j;
            arb_set(hist[u] + len - 1, znew + u);
            for (j = 0; j < len; j++) {
                arb_abs(t1, hist[u] + j);
                arb_max(norm, norm, t1, prec);
            }
            /* the known values for the next step move one place down */
            for (j = 0; j + 1 < len; j++) arb_swap(hist[u] + j, hist[u] + j + 1);
        }
        /* window averages of log |z| over [N/4, N/2) and [3N/4, N): the
         * oscillation of complex modes averages out */
        if (step > steps / 4 && step <= steps / 2) { arb_log(t2, norm, 64); arb_add(lognorm_mid, lognorm_mid, t2, 64); }
        if (step > steps - steps / 4) { arb_log(t2, norm, 64); arb_add(lognorm_end, lognorm_end, t2, 64); }
    }
    if (r != RS_OK) goto done;
    o = json_object();
    json_object_set_new(o, "analysis", json_string("simulate"));
    json_object_set_new(o, "steps", json_integer(steps));
    json_object_set_new(o, "seed", json_integer(seed));
    json_object_set_new(o, "precision_bits", json_integer(prec));
    json_object_set_new(o, "recurrence", json_string(scalar ? "scalar recurrence of p(lambda) (the equations' "
                                                              "leading matrix is singular or absent)"
                                                            : "the case's equations as written, solved for the "
                                                              "newest value of every unknown at each step"));
    json_object_set_new(o, "arithmetic", json_string("Arb midpoints at the working precision"));
    /* growth per step over the second half: (|z_N| / |z_{N/2}|)^(1/(N - N/2)) */
    if (steps >= 8 && arb_is_finite(lognorm_end) && arb_is_finite(lognorm_mid)) {
        slong a1 = steps / 4 + 1, b1 = steps / 2, a2 = steps - steps / 4 + 1, b2 = steps;
        /* averages over [a1, b1] and [a2, b2]; centres (a+b)/2 */
        arb_div_si(lognorm_mid, lognorm_mid, b1 - a1 + 1, prec);
        arb_div_si(lognorm_end, lognorm_end, b2 - a2 + 1, prec);
        arb_sub(t1, lognorm_end, lognorm_mid, prec);
        arb_mul_si(t1, t1, 2, prec);
        arb_div_si(t1, t1, (a2 + b2) - (a1 + b1), prec);
        arb_exp(t2, t1, prec);
        json_object_set_new(o, "growth", rs_json_arb(t2, 15));
        json_object_set_new(o, "growth_approx", json_real(arf_get_d(arb_midref(t2), ARF_RND_NEAR)));
        r = simulate_check(run, o, v, p, t1, steps);
    } else {
        json_object_set_new(o, "growth", json_null());
        json_object_set_new(o, "note", json_string("the state became exactly zero or unbounded"));
    }
    {
        rs_radius_t rr;
        rs_radius_init(rr);
        if (rs_radius_fmpz_poly(rr, p, 15, run->opt->max_prec, run->err) == RS_OK)
            json_object_set_new(o, "radius", rs_json_arb(rr->rho, 15));
        else
            rs_error_init(run->err);
        rs_radius_clear(rr);
    }
    json_object_set_new(o, "decided_by", json_string("time-domain run (measurement, not a certificate)"));
    json_object_set_new(o, "substituted", json_deep_copy(v->assigned));
    if (r == RS_OK) json_array_append_new(run->results, o);
    else json_decref(o);
done:
    for (u = 0; u < n; u++) _arb_vec_clear(hist[u], Mu[u] - mu[u] + 1);
    flint_free(hist);
    for (i = 0; i < n * n; i++) _arb_vec_clear(cf[i], Mu[i % n] - mu[i % n] > 0 ? Mu[i % n] - mu[i % n] : 1);
    flint_free(cf);
    _arb_vec_clear(rhs, n);
    _arb_vec_clear(znew, n);
    arb_clear(norm); arb_clear(lognorm_mid); arb_clear(lognorm_end); arb_clear(t1); arb_clear(t2);
    arb_mat_clear(L);
    arb_mat_clear(Linv);
    flint_free(Mu);
    flint_free(mu);
    fmpq_clear(c);
    flint_randclear(st);
    fmpz_poly_clear(p);
    return r;
}

