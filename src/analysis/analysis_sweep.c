/* analysis_sweep.c -- 1-D sweeps and 2-D stability maps, certified per point.
 *
 *   sweep NAME from A to B steps K [log] [of radius|modes|stability] [h=EXPR reference=EXPR[,EXPR]]
 *   map NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]
 *
 * Points are exact rationals; p(lambda; point) is evaluated exactly as an
 * integer polynomial (the charpoly with the other parameters substituted,
 * scaled by the denominators).  The per-point work runs in an OpenMP loop
 * into a result array; tables (CSV text) and JSON are built serially from
 * it, so the output is the same for every thread count.  See sweep.h for the
 * verdict ladder and README "Sweeps and maps" for the formats. */
#include <math.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef RS_MPI
#include <mpi.h>
#endif
#include <arb.h>
#include <acb.h>
#include <acb_poly.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>
#include "recstab/budget.h"
#include "analysis/impl.h"
#include "analysis/sweep_impl.h"
#include "numeric/modes.h"
#include "recstab/sweep.h"
#include "recstab/radius.h"
#include "recstab/rootcount.h"
#include "recstab/semisimple.h"
#include "recstab/routh.h"
#include "recstab/jury.h"
#include "recstab/hurwitz.h"
#include "util/polyfmt.h"

#define SW_MAX_REFS 4
#define SW_MAX_TOKENS 32
#define SW_TEXT_ROWS_MAX 200


/* ---- process-wide options ------------------------------------------------------ */

void rs_sweep_options_default(rs_sweep_options_t *o)
{
    o->shard_index = 1;
    o->shard_count = 1;
    o->max_points = RS_SWEEP_MAX_POINTS_DEFAULT;
    o->progress = NULL;
    o->progress_arg = NULL;
    o->first_level = RS_LEVEL_FAST;
}


void rs_sweep_shard_range(slong *lo, slong *hi, slong npoints, slong I, slong N)
{
    if (N < 1) N = 1;
    if (I < 1) I = 1;
    if (I > N) I = N;
    *lo = (I - 1) * (npoints / N) + ((I - 1) * (npoints % N)) / N;
    *hi = I * (npoints / N) + (I * (npoints % N)) / N;
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

/* ---- the certified verdict of one polynomial --------------------------------------- */

static int exact_count(rs_rootcount_t rc, const fmpz_poly_t p, rs_error_t err)
{
    rs_routh_t ro;
    rs_jury_t ju;
    int r;
    rs_routh_init(ro);
    rs_jury_init(ju);
    r = rs_routh_fmpz_poly(ro, p, err);
    if (r == RS_OK) r = rs_jury_fmpz_poly(ju, p, err);
    if (r == RS_OK) {
        *rc = *ro->count;
        if (!rs_rootcount_equal(ro->count, ju->count))
            r = rs_error_set(err, RS_ERR_INCONSISTENT,
                             "Routh (bilinear) and Schur-Cohn counts disagree at a sweep point");
    }
    rs_routh_clear(ro);
    rs_jury_clear(ju);
    return r;
}

/* The ladder's exact rung (ladder.h): Routh and Schur-Cohn, which must
 * agree; arg, when not NULL, is an rs_rootcount_struct that gets the counts. */
static int exact_rung(rs_ladder_count_t *c, const fmpz_poly_t p, void *arg, rs_error_t err)
{
    rs_rootcount_t rc;
    int r;
    rs_rootcount_init(rc);
    r = exact_count(rc, p, err);
    if (r == RS_OK) {
        c->inside = rc->inside;
        c->on = rc->on;
        c->outside = rc->outside;
        c->max_on_mult = rs_rootcount_max_on_mult(rc);
        c->status = (int) rs_rootcount_status(rc);
        if (arg != NULL) *(rs_rootcount_struct *) arg = *rc;
    }
    rs_rootcount_clear(rc);
    return r;
}

int rs_sweep_decide(rs_sweep_point_t *pt, const fmpz_poly_t p, rs_error_t err)
{
    return rs_ladder_decide(pt, p, RS_LEVEL_FAST, exact_rung, NULL, err);
}

/* ---- request parsing ------------------------------------------------------------------ */

typedef struct { const char *s; size_t n; } tok_t;

/* Splits at white space, ',' is a token of its own; stops at the first word
 * containing '=' (options), returned in *opts. */
static slong tokenize(tok_t *t, slong max, const char *text, const char **opts)
{
    slong n = 0;
    const char *p = text;
    *opts = NULL;
    for (;;) {
        size_t len;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '\0') break;
        if (*p == ',') len = 1;
        else {
            len = strcspn(p, " \t,");
            if (memchr(p, '=', len) != NULL) { *opts = p; break; }
        }
        if (n < max) { t[n].s = p; t[n].n = len; }
        n++;
        p += len;
    }
    return n;
}

static int tok_is(const tok_t *t, const char *w)
{
    return strlen(w) == t->n && strncmp(t->s, w, t->n) == 0;
}

static int tok_number(fmpq_t q, const tok_t *t)
{
    char buf[128];
    rs_error_t e;
    if (t->n >= sizeof buf) return RS_ERR_INPUT;
    memcpy(buf, t->s, t->n);
    buf[t->n] = '\0';
    rs_error_init(e);
    return rs_expr_parse_number(q, buf, e);
}

static int tok_long(slong *out, const tok_t *t)
{
    char buf[32], *end;
    long x;
    if (t->n == 0 || t->n >= sizeof buf) return 0;
    memcpy(buf, t->s, t->n);
    buf[t->n] = '\0';
    errno = 0;
    x = strtol(buf, &end, 10);
    if (*end != '\0') return 0;
    if (errno == ERANGE) x = (x > 0) ? WORD_MAX : WORD_MIN;   /* clamped: a limit error, not a wrap */
    *out = x;
    return 1;
}

static char *tok_str(const tok_t *t)
{
    char *s = malloc(t->n + 1);
    memcpy(s, t->s, t->n);
    s[t->n] = '\0';
    return s;
}

static int tok_error(rs_run_t *run, const rs_request_t *q, const tok_t *t, const char *fmt)
{
    char *w = tok_str(t);
    int r = rs_req_error(run, q, t->s, RS_ERR_INPUT, fmt, w);
    free(w);
    return r;
}

/* ---- exact evaluation of p at grid points ------------------------------------------------- */

typedef struct {
    slong n;          /* terms */
    fmpz *c;
    slong *el, *e1, *e2;
    slong dl, d1, d2; /* degrees in lambda, param 1, param 2 */
} terms_t;

static void terms_init(terms_t *T, const fmpz_mpoly_t p, slong lv, slong v1, slong v2,
                       const fmpz_mpoly_ctx_t ctx)
{
    slong i, len = fmpz_mpoly_length(p, ctx);
    slong *e = flint_malloc(ctx->minfo->nvars * sizeof(slong));
    T->n = len;
    T->c = _fmpz_vec_init(len > 0 ? len : 1);
    T->el = flint_calloc(len + 1, sizeof(slong));
    T->e1 = flint_calloc(len + 1, sizeof(slong));
    T->e2 = flint_calloc(len + 1, sizeof(slong));
    T->dl = T->d1 = T->d2 = 0;
    for (i = 0; i < len; i++) {
        fmpz_mpoly_get_term_exp_si(e, p, i, ctx);
        fmpz_mpoly_get_term_coeff_fmpz(T->c + i, p, i, ctx);
        T->el[i] = lv >= 0 ? e[lv] : 0;
        T->e1[i] = e[v1];
        T->e2[i] = v2 >= 0 ? e[v2] : 0;
        if (T->el[i] > T->dl) T->dl = T->el[i];
        if (T->e1[i] > T->d1) T->d1 = T->e1[i];
        if (T->e2[i] > T->d2) T->d2 = T->e2[i];
    }
    flint_free(e);
}

static void terms_clear(terms_t *T)
{
    _fmpz_vec_clear(T->c, T->n > 0 ? T->n : 1);
    flint_free(T->el);
    flint_free(T->e1);
    flint_free(T->e2);
}

/* U[g*(d+1) + e] = num_g^e den_g^(d-e) */
static fmpz *powers_table(const fmpq *vals, slong nv, slong d)
{
    fmpz *U = _fmpz_vec_init(nv * (d + 1));
    slong g, e;
    fmpz_t t;
    fmpz_init(t);
    for (g = 0; g < nv; g++)
        for (e = 0; e <= d; e++) {
            fmpz_pow_ui(U + g * (d + 1) + e, fmpq_numref(vals + g), (ulong) e);
            fmpz_pow_ui(t, fmpq_denref(vals + g), (ulong) (d - e));
            fmpz_mul(U + g * (d + 1) + e, U + g * (d + 1) + e, t);
        }
    fmpz_clear(t);
    return U;
}

/* den1^d1 den2^d2 p(lambda; x1, x2) */
static void eval_point(fmpz_poly_t P, const terms_t *T, const fmpz *u1, const fmpz *u2)
{
    slong i;
    fmpz_t w;
    fmpz_init(w);
    fmpz_poly_zero(P);
    fmpz_poly_fit_length(P, T->dl + 1);
    _fmpz_vec_zero(P->coeffs, T->dl + 1);
    for (i = 0; i < T->n; i++) {
        if (u2 != NULL) {
            fmpz_mul(w, u1 + T->e1[i], u2 + T->e2[i]);
            fmpz_addmul(P->coeffs + T->el[i], T->c + i, w);
        } else {
            fmpz_addmul(P->coeffs + T->el[i], T->c + i, u1 + T->e1[i]);
        }
    }
    _fmpz_poly_set_length(P, T->dl + 1);
    _fmpz_poly_normalise(P);
    fmpz_clear(w);
}

/* ---- per-point results ----------------------------------------------------------------------- */

enum { OF_RADIUS = 0, OF_STABILITY = 1, OF_MODES = 2 };
static const char *const of_names[3] = {"radius", "stability", "modes"};

typedef struct {
    rs_sweep_point_t d;
    int inside, on, outside;            /* exact counts (of stability sweeps), else -1 */
    int nmodes;                         /* references found */
    /* damping ratio, frequency error, omega per reference: certified
     * [mode_lo, mode_hi] (doubles rounded outward); NAN when not found */
    double mode_lo[3 * SW_MAX_REFS], mode_hi[3 * SW_MAX_REFS];
} pt_t;

typedef struct {
    rs_run_t *run;
    const rs_request_t *q;
    int kind;                           /* OF_* */
    int is_map;
    terms_t T;
    fmpz *U1, *U2;                      /* power tables */
    slong K1, K2;                       /* points per axis (K2 = 1 for sweeps) */
    slong npoints;
    /* modes */
    slong nref;
    fmpq *refval;                       /* npoints * nref reference values */
    fmpq *hval;                         /* npoints time steps */
    slong max_prec;
    /* the point verdict of systems: the variant and the swept parameters */
    const rs_variant_t *v;
    slong var[2];
    const fmpq *x[2];                   /* axis values (x[1] NULL for sweeps) */
} job_t;

static void point_poly(fmpz_poly_t P, const job_t *J, slong idx)
{
    slong i = idx % J->K1, j = idx / J->K1;
    eval_point(P, &J->T, J->U1 + i * (J->T.d1 + 1), J->is_map ? J->U2 + j * (J->T.d2 + 1) : NULL);
}

/* [*lo, *hi] contains x (doubles rounded outward; +-inf when x is not finite). */
static void arb_bounds_d(double *lo, double *hi, const arb_t x)
{
    arf_t t;
    arf_init(t);
    arb_get_lbound_arf(t, x, 64);
    *lo = arf_is_nan(t) ? -INFINITY : arf_get_d(t, ARF_RND_FLOOR);
    arb_get_ubound_arf(t, x, 64);
    *hi = arf_is_nan(t) ? INFINITY : arf_get_d(t, ARF_RND_CEIL);
    arf_clear(t);
}

/* Damping ratio, frequency error and omega of the principal root (Im >= 0)
 * of each reference at point idx, as `modes` reports them. */
static void point_modes(pt_t *pt, const job_t *J, slong idx, const rs_radius_t rr)
{
    slong prec = 128, k, i;
    arb_t h, sig, om, mag, zeta;
    arb_ptr refs = _arb_vec_init(J->nref);
    int *principal = calloc((size_t) rr->nroots + 1, sizeof(int));
    arb_init(h); arb_init(sig); arb_init(om); arb_init(mag); arb_init(zeta);
    arb_set_fmpq(h, J->hval + idx, prec);
    for (k = 0; k < J->nref; k++) arb_set_fmpq(refs + k, J->refval + idx * J->nref + k, prec);
    rs_modes_principal(principal, rr, h, refs, J->nref, prec);
    for (k = 0; k < 3 * SW_MAX_REFS; k++) pt->mode_lo[k] = pt->mode_hi[k] = NAN;
    for (k = 0; k < J->nref; k++)
        for (i = 0; i < rr->nroots; i++) {
            const acb_struct *z = rr->roots + i;
            if (principal[i] != k + 1 || acb_is_zero(z)) continue;
            if (arf_sgn(arb_midref(acb_imagref(z))) < 0 && !arb_is_zero(acb_imagref(z))) continue;
            rs_modes_continuous(sig, om, mag, zeta, z, h, prec);
            arb_bounds_d(pt->mode_lo + 3 * k, pt->mode_hi + 3 * k, zeta);
            arb_sub(mag, mag, refs + k, prec);
            arb_div(mag, mag, refs + k, prec);
            arb_bounds_d(pt->mode_lo + 3 * k + 1, pt->mode_hi + 3 * k + 1, mag);
            arb_bounds_d(pt->mode_lo + 3 * k + 2, pt->mode_hi + 3 * k + 2, om);
            pt->nmodes++;
            break;
        }
    free(principal);
    _arb_vec_clear(refs, J->nref);
    arb_clear(h); arb_clear(sig); arb_clear(om); arb_clear(mag); arb_clear(zeta);
}

/* What the polynomial alone cannot say: the step is singular where the
 * degree in lambda drops, and a repeated circle root of a system is bounded
 * when semisimple (rs_semisimple_verdict on the lambda-matrix there). */
static int point_system(pt_t *pt, const job_t *J, slong idx, const fmpz_poly_t P,
                        const rs_rootcount_struct *known, rs_error_t err)
{
    slong i = idx % J->K1, j = idx / J->K1;
    fmpq vals[2];
    rs_rootcount_t rc;
    rs_semisimple_t ss;
    rs_status_t st;
    fmpz_poly_t pp;
    int r;
    if (fmpz_poly_is_zero(P)) return RS_OK;
    if (J->v->singular || fmpz_poly_degree(P) < J->T.dl) {
        pt->d.verdict = RS_STATUS_SINGULAR;
        pt->d.level = RS_LEVEL_EXACT;
        pt->d.rho_lower = 0;
        pt->d.rho_upper = INFINITY;
        return RS_OK;
    }
    if (!(pt->d.repeated_on && pt->d.verdict == RS_STATUS_UNSTABLE) || J->v->s->from_char) return RS_OK;
    vals[0] = J->x[0][i];
    if (J->is_map) vals[1] = J->x[1][j];
    fmpz_poly_init(pp);
    fmpz_poly_primitive_part(pp, P);
    rs_rootcount_init(rc);
    rs_semisimple_init(ss);
    /* the ladder's exact rung kept no counts; a stability sweep has them */
    r = known != NULL ? (*rc = *known, RS_OK) : exact_count(rc, pp, err);
    if (r == RS_OK)
        r = rs_semisimple_verdict(&st, ss, J->v->s, J->var, vals, J->is_map ? 2 : 1, pp, rc, 0, err);
    if (r == RS_OK) pt->d.verdict = (int) st;
    rs_semisimple_clear(ss);
    rs_rootcount_clear(rc);
    fmpz_poly_clear(pp);
    return r;
}

static void compute_point(pt_t *pt, const job_t *J, slong idx, rs_error_t err)
{
    fmpz_poly_t P;
    int r = RS_OK;
    memset(pt, 0, sizeof *pt);
    pt->inside = pt->on = pt->outside = -1;
    fmpz_poly_init(P);
    point_poly(P, J, idx);
    if (J->kind == OF_STABILITY && !J->is_map) {
        /* the exact verdict, with the counts */
        rs_rootcount_t rc;
        rs_rootcount_init(rc);
        pt->d.status = RS_OK;
        pt->d.verdict = -1;
        pt->d.rho_lower = 0;
        pt->d.rho_upper = INFINITY;
        if (!fmpz_poly_is_zero(P)) {
            if (fmpz_poly_degree(P) == 0) {
                pt->d.verdict = RS_STATUS_STABLE;
                pt->d.level = RS_LEVEL_EXACT;
                pt->inside = pt->on = pt->outside = 0;
            } else {
                r = rs_ladder_decide_exact(&pt->d, P, exact_rung, rc, err);
                pt->inside = (int) rc->inside;
                pt->on = (int) rc->on;
                pt->outside = (int) rc->outside;
            }
            if (r == RS_OK) r = point_system(pt, J, idx, P, fmpz_poly_degree(P) > 0 ? rc : NULL, err);
        }
        rs_rootcount_clear(rc);
        pt->d.status = r;
        fmpz_poly_clear(P);
        return;
    }
    r = rs_ladder_decide(&pt->d, P, J->run->opt->sweep.first_level, exact_rung, NULL, err);
    if (r == RS_OK) r = point_system(pt, J, idx, P, NULL, err);
    if (r == RS_OK && pt->d.verdict >= 0 && pt->d.verdict != RS_STATUS_SINGULAR && fmpz_poly_degree(P) >= 1
        && (J->kind == OF_MODES || (!pt->d.isolated && !(pt->d.rho_lower == 1.0 && pt->d.rho_upper == 1.0))
            || (J->kind == OF_RADIUS && !J->is_map))) {
        /* the certified radius to 15 digits (and the roots, for modes) */
        rs_radius_t rr;
        slong lv = 0;
        while (fmpz_is_zero(P->coeffs + lv)) lv++;
        rs_radius_init(rr);
        if (fmpz_poly_degree(P) - lv == 0) {
            pt->d.rho_lower = pt->d.rho_upper = 0;
        } else {
            r = rs_radius_fmpz_poly(rr, P, 15, J->max_prec, err);
            if (r == RS_OK) {
                double lo = rs_ladder_lower_d(rr->lower), hi = rs_ladder_upper_d(rr->upper);
                if (!(pt->d.rho_lower == 1.0 && pt->d.rho_upper == 1.0)) {
                    pt->d.rho_lower = lo;
                    pt->d.rho_upper = hi;
                }
                if (J->kind == OF_MODES) point_modes(pt, J, idx, rr);
            }
        }
        rs_radius_clear(rr);
    }
    pt->d.status = r;
    fmpz_poly_clear(P);
}

/* Computes points [lo, hi) into pts[0 .. hi-lo), in parallel; with MPI split
 * over the ranks and gathered. */
static void compute_range(pt_t *pts, const job_t *J, slong lo, slong hi, const char *what)
{
    const rs_sweep_options_t *so = &J->run->opt->sweep;
    slong done = 0, mylo = lo, myhi = hi;
    double last = now_seconds();
    gsl_error_handler_t *old = gsl_set_error_handler_off();
#ifdef RS_MPI
    slong total = hi - lo;
    int mpi_on = 0, rank = 0, size = 1;
    MPI_Initialized(&mpi_on);
    if (mpi_on) {
        MPI_Comm_rank(MPI_COMM_WORLD, &rank);
        MPI_Comm_size(MPI_COMM_WORLD, &size);
        rs_sweep_shard_range(&mylo, &myhi, total, rank + 1, size);
        mylo += lo;
        myhi += lo;
    }
#endif
    {
        slong k;
#pragma omp parallel for schedule(dynamic, 16)
        for (k = mylo; k < myhi; k++) {
            rs_error_t e;
            rs_error_init(e);
            /* once the budget is exceeded the remaining points are skipped;
             * rs_analysis_run reports the limit */
            if (rs_budget_check(NULL, what) != RS_OK) continue;
            compute_point(pts + (k - lo), J, k, e);
            if (so->progress != NULL) {
                slong d;
#pragma omp atomic capture
                d = ++done;
#ifdef _OPENMP
                if (omp_get_thread_num() == 0)
#endif
                {
                    double t = now_seconds();
                    if (t - last > 0.2) {
                        last = t;
                        so->progress(so->progress_arg, what, d, myhi - mylo);
                    }
                }
            }
        }
    }
#ifdef RS_MPI
    if (mpi_on && size > 1) {
        int *counts = malloc((size_t) size * sizeof(int)), *displs = malloc((size_t) size * sizeof(int));
        int rk;
        for (rk = 0; rk < size; rk++) {
            slong a, b;
            rs_sweep_shard_range(&a, &b, total, rk + 1, size);
            counts[rk] = (int) ((b - a) * (slong) sizeof(pt_t));
            displs[rk] = (int) (a * (slong) sizeof(pt_t));
        }
        MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, pts, counts, displs, MPI_BYTE, MPI_COMM_WORLD);
        free(counts);
        free(displs);
    }
#endif
    if (so->progress != NULL) so->progress(so->progress_arg, what, myhi - mylo, myhi - mylo);
    gsl_set_error_handler(old);
}

/* ---- output helpers ------------------------------------------------------------------------------ */

/* certified bounds printed outward: the decimal string of the neighbouring
 * double is on the safe side of the bound */
static void put_lower(FILE *f, double x)
{
    if (x == 0 || x == 1.0) fprintf(f, "%.17g", x);
    else fprintf(f, "%.17g", nextafter(x, -INFINITY));
}

static void put_upper(FILE *f, double x)
{
    if (isinf(x)) fputs("inf", f);
    else if (x == 0 || x == 1.0) fprintf(f, "%.17g", x);
    else fprintf(f, "%.17g", nextafter(x, INFINITY));
}

/* A point estimate in [lo, hi] with only its certified digits (every value
 * of [lo, hi] rounds to it, at most 15 digits); empty when no digit is. */
static void put_certified(FILE *f, double lo, double hi)
{
    arf_t a, b;
    char *s;
    arf_init(a);
    arf_init(b);
    arf_set_d(a, lo);
    arf_set_d(b, hi);
    s = rs_radius_interval_str(a, b, 15);
    if (s[0] != '[' && strcmp(s, "nan") != 0) fputs(s, f);
    flint_free(s);
    arf_clear(a);
    arf_clear(b);
}

static void put_radius(FILE *f, const rs_sweep_point_t *d)
{
    if (d->verdict < 0) { fputs(",,", f); return; }
    if (d->level == RS_LEVEL_DOUBLE) {
        /* benchmark baseline: an estimate, and no certified bound at all */
        fprintf(f, "%.15g,0,inf", d->rho_lower);
        return;
    }
    put_certified(f, d->rho_lower, d->rho_upper);
    fputc(',', f);
    put_lower(f, d->rho_lower);
    fputc(',', f);
    put_upper(f, d->rho_upper);
}

static const char *verdict_name(int v)
{
    return v < 0 ? "undefined" : rs_status_name((rs_status_t) v);
}

static void put_fmpq(FILE *f, const fmpq_t x)
{
    char *s = fmpq_get_str(NULL, 10, x);
    fputs(s, f);
    flint_free(s);
}

static void put_double_of(FILE *f, const fmpq_t x)
{
    fprintf(f, "%.15g", fmpq_get_d(x));
}

/* counts, seconds, etc. common to sweep and map elements */
static void add_summary(json_t *o, const pt_t *pts, slong n, double seconds)
{
    slong i, ver[5] = {0, 0, 0, 0, 0}, lev[5] = {0, 0, 0, 0, 0};
    json_t *v, *d;
    for (i = 0; i < n; i++) {
        if (pts[i].d.verdict < 0) ver[3]++;
        else if (pts[i].d.verdict == RS_STATUS_SINGULAR) ver[4]++;
        else ver[pts[i].d.verdict]++;
        if (pts[i].d.verdict >= 0) lev[pts[i].d.level]++;
    }
    v = json_pack("{s:I,s:I,s:I}", "stable", (json_int_t) ver[0], "marginal", (json_int_t) ver[1],
                  "unstable", (json_int_t) ver[2]);
    if (ver[3] > 0) json_object_set_new(v, "undefined", json_integer(ver[3]));
    if (ver[4] > 0) json_object_set_new(v, "singular", json_integer(ver[4]));
    if (lev[4] > 0) json_object_set_new(o, "uncertified", json_integer(lev[4]));
    d = json_pack("{s:I,s:I,s:I,s:I}", "fast", (json_int_t) lev[0], "prec128", (json_int_t) lev[1],
                  "prec256", (json_int_t) lev[2], "exact", (json_int_t) lev[3]);
    if (lev[4] > 0) json_object_set_new(d, "double", json_integer(lev[4]));
    json_object_set_new(o, "verdicts", v);
    json_object_set_new(o, "decided_by", d);
    json_object_set_new(o, "seconds", json_real(floor(seconds * 1e4 + 0.5) / 1e4));
#ifdef _OPENMP
    json_object_set_new(o, "threads", json_integer(omp_get_max_threads()));
#else
    json_object_set_new(o, "threads", json_integer(1));
#endif
    json_object_set_new(o, "csv", json_null());
}

/* first failing point: recompute serially for its message */
static int point_errors(rs_run_t *run, const rs_request_t *q, const job_t *J, const pt_t *pts, slong lo,
                        slong n, const char *param_desc)
{
    slong i;
    /* points skipped after the budget ran out: no table from them */
    if (rs_budget_exceeded()) return rs_budget_error(run->err);
    for (i = 0; i < n; i++)
        if (pts[i].d.status != RS_OK) {
            pt_t tmp;
            rs_error_t e;
            char msg[RS_ERROR_MSG_LEN + 200];
            int code;
            rs_error_init(e);
            compute_point(&tmp, J, lo + i, e);
            code = tmp.d.status != RS_OK ? tmp.d.status : pts[i].d.status;
            if (code == RS_ERR_INCONSISTENT) run->outcome |= RS_OUTCOME_INCONSISTENT;
            snprintf(msg, sizeof msg, "at point %ld (%s): %s", (long) (lo + i), param_desc,
                     e->msg[0] ? e->msg : rs_error_code_name(code));
            return rs_req_error(run, q, q->text, code, "%s", msg);
        }
    return RS_OK;
}

static int check_free(rs_run_t *run, const rs_request_t *q, const rs_variant_t *v, slong v1, slong v2,
                      const char *what)
{
    const rs_scheme_struct *s = v->s;
    slong i;
    for (i = 0; i < s->nvars; i++) {
        if (i == s->lambda_var || i == v1 || i == v2) continue;
        if (fmpz_mpoly_degree_si(v->cp->p, i, s->zctx) > 0) {
            char msg[600];
            snprintf(msg, sizeof msg, "%s needs every other parameter set to a number; still symbolic: %s "
                     "(use set or --set)", what, s->vars[i]);
            return rs_req_error(run, q, q->text, RS_ERR_INPUT, "%s", msg);
        }
    }
    return RS_OK;
}

/* npoints as a double: K + 1 or K1 * K2 may not fit into a slong */
static int limit_error(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc)
{
    char msg[400];
    /* exact below 2^53, rounded (and said so) above */
    snprintf(msg, sizeof msg, npoints < 9007199254740992.0 ? "%s has %.0f points, more than the limit of %ld points "
             "per sweep or map (raise it with --max-points N)" : "%s has about %.4g points, more than the limit of "
             "%ld points per sweep or map (raise it with --max-points N)", desc, npoints, (long) run->opt->sweep.max_points);
    return rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", msg);
}

/* Before allocating: the points must fit into what is left of the budget.
 * 1 us and sizeof(pt_t) + two rationals per point are lower bounds (the
 * fastest sweep measured, degree 1 on one thread, takes about 4 us). */
static int estimate_points(rs_run_t *run, const rs_request_t *q, double npoints, const char *desc)
{
    char msg[RS_ERROR_MSG_LEN];
    rs_error_t e;
    rs_error_init(e);
    if (rs_budget_estimate(e, desc, npoints * 1e-6, npoints * (double) (sizeof(pt_t) + 2 * sizeof(fmpq))) == RS_OK)
        return RS_OK;
    snprintf(msg, sizeof msg, "%s", e->msg);
    return rs_req_error(run, q, q->text, RS_ERR_LIMIT, "%s", msg);
}

static int parse_of(rs_run_t *run, const rs_request_t *q, const tok_t *t, slong nt, slong *pos, int *kind,
                    int allow_modes)
{
    *kind = OF_RADIUS;
    if (*pos < nt && tok_is(t + *pos, "of")) {
        if (*pos + 1 >= nt)
            return rs_req_error(run, q, t[*pos].s, RS_ERR_INPUT, "expected radius, %s after 'of'",
                                allow_modes ? "modes or stability" : "or stability");
        if (tok_is(t + *pos + 1, "radius")) *kind = OF_RADIUS;
        else if (tok_is(t + *pos + 1, "stability")) *kind = OF_STABILITY;
        else if (allow_modes && tok_is(t + *pos + 1, "modes")) *kind = OF_MODES;
        else return tok_error(run, q, t + *pos + 1, allow_modes
                              ? "expected radius, modes or stability after 'of', found '%s'"
                              : "expected radius or stability after 'of', found '%s'");
        *pos += 2;
    }
    if (*pos < nt) return tok_error(run, q, t + *pos, "unexpected '%s' at the end of the request");
    return RS_OK;
}

static json_t *set_values_json(rs_run_t *run, const char *const *keep, slong nkeep)
{
    rs_assign_t *a;
    slong n, i;
    json_t *o = json_object();
    rs_run_assignments(run, &a, &n, keep, nkeep, NULL, 0);
    for (i = 0; i < n; i++) json_object_set_new(o, a[i].name, rs_json_fmpq(a[i].value));
    rs_assign_free(a, n);
    return o;
}

/* ---- modes options: h=EXPR reference=EXPR[,EXPR...] evaluated per point ------------------- */

static int parse_modes_opts(job_t *J, rs_run_t *run, const rs_request_t *q, const rs_variant_t *v,
                            const char *opts, slong var, const fmpq *vals)
{
    const char *t = opts;
    int have_ref = 0, r = RS_OK;
    slong i;
    J->hval = _fmpq_vec_init(J->npoints);
    for (i = 0; i < J->npoints; i++) fmpq_one(J->hval + i);
    J->nref = 0;
    J->refval = NULL;
    while (t != NULL && *t) {
        const char *end = t;
        while (*t == ' ' || *t == '\t') t++;
        if (*t == '\0') break;
        if (strncmp(t, "h=", 2) == 0) {
            r = rs_req_eval_points(J->hval, 1, run, q, v, t + 2, var, vals, J->npoints, &end);
            for (i = 0; i < J->npoints && r == RS_OK; i++)
                if (fmpq_sgn(J->hval + i) <= 0)
                    r = rs_req_error(run, q, t + 2, RS_ERR_INPUT,
                                     "expected a time step h > 0 at every point, found '%s'", t + 2);
        } else if (strncmp(t, "reference=", 10) == 0) {
            fmpq *tmp = _fmpq_vec_init(J->npoints);
            const char *u = t + 10;
            have_ref = 1;
            for (;;) {
                if (J->nref >= SW_MAX_REFS) {
                    _fmpq_vec_clear(tmp, J->npoints);
                    return rs_req_error(run, q, u, RS_ERR_LIMIT, "at most 4 references, found more at '%s'", u);
                }
                r = rs_req_eval_points(tmp, 1, run, q, v, u, var, vals, J->npoints, &end);
                if (r != RS_OK) break;
                {
                    fmpq *nr = _fmpq_vec_init(J->npoints * (J->nref + 1));
                    slong k, p;
                    for (p = 0; p < J->npoints; p++) {
                        for (k = 0; k < J->nref; k++)
                            fmpq_set(nr + p * (J->nref + 1) + k, J->refval + p * J->nref + k);
                        fmpq_set(nr + p * (J->nref + 1) + J->nref, tmp + p);
                    }
                    if (J->refval) _fmpq_vec_clear(J->refval, J->npoints * J->nref);
                    J->refval = nr;
                    J->nref++;
                }
                if (*end != ',') break;
                u = end + 1;
            }
            _fmpq_vec_clear(tmp, J->npoints);
        } else {
            return rs_req_error(run, q, t, RS_ERR_INPUT, "expected an option (h=, reference=), found '%s'", t);
        }
        if (r != RS_OK) return r;
        /* the expression parser stops after trailing blanks: the next option
         * may already start here */
        if (end > t && (end[-1] == ' ' || end[-1] == '\t')) end--;
        if (*end != '\0' && *end != ' ' && *end != '\t')
            return rs_req_error(run, q, end, RS_ERR_INPUT, "expected a space or the end after the value, found '%s'",
                                end);
        t = end;
    }
    if (!have_ref)
        return rs_req_error(run, q, q->text, RS_ERR_INPUT,
                            "sweep ... of modes needs reference=EXPR (the exact frequency of the mode, e.g. "
                            "reference=w with h=1 for a scaled w = omega*h), found '%s'", q->text);
    return RS_OK;
}

static void job_clear(job_t *J)
{
    terms_clear(&J->T);
    if (J->U1) _fmpz_vec_clear(J->U1, J->K1 * (J->T.d1 + 1));
    if (J->U2) _fmpz_vec_clear(J->U2, J->K2 * (J->T.d2 + 1));
    if (J->refval) _fmpq_vec_clear(J->refval, J->npoints * J->nref);
    if (J->hval) _fmpq_vec_clear(J->hval, J->npoints);
}

static char *memstream_done(FILE *f, char **buf)
{
    fclose(f);
    return *buf;
}

/* ---- sweep ------------------------------------------------------------------------------------------- */

void rs_grid_value(fmpq_t x, const fmpq_t A, const fmpq_t B, slong i, slong K, int logsp)
{
    if (K == 0 || i == 0) { fmpq_set(x, A); return; }
    if (i == K) { fmpq_set(x, B); return; }
    if (!logsp) {
        fmpq_t t;
        fmpz_t k;
        fmpq_init(t);
        fmpz_init_set_si(k, K);
        fmpq_sub(t, B, A);
        fmpq_mul_si(t, t, i);
        fmpq_div_fmpz(t, t, k);
        fmpq_add(x, A, t);
        fmpq_clear(t);
        fmpz_clear(k);
    } else {
        arb_t a, b;
        fmpq_t m, lo, hi, eps;
        slong prec = 128;
        arb_init(a); arb_init(b);
        fmpq_init(m); fmpq_init(lo); fmpq_init(hi); fmpq_init(eps);
        arb_set_fmpq(a, A, prec);
        arb_set_fmpq(b, B, prec);
        arb_div(b, b, a, prec);
        arb_log(b, b, prec);
        arb_mul_si(b, b, i, prec);
        arb_div_si(b, b, K, prec);
        arb_exp(b, b, prec);
        arb_mul(b, b, a, prec);
        arf_get_fmpq(m, arb_midref(b));
        fmpq_set_si(eps, 1, 1);
        fmpz_set_ui(fmpq_denref(eps), 10);
        fmpz_pow_ui(fmpq_denref(eps), fmpq_denref(eps), 13);
        fmpq_mul(eps, eps, m);
        fmpq_sub(lo, m, eps);
        fmpq_add(hi, m, eps);
        fmpq_simplest_between(x, lo, hi);
        arb_clear(a); arb_clear(b);
        fmpq_clear(m); fmpq_clear(lo); fmpq_clear(hi); fmpq_clear(eps);
    }
}

void rs_sweep_request_init(rs_sweep_request_t *r)
{
    slong ax;
    memset(r, 0, sizeof *r);
    for (ax = 0; ax < 2; ax++) {
        fmpq_init(r->axis[ax].from);
        fmpq_init(r->axis[ax].to);
        r->axis[ax].var = -1;
    }
}

void rs_sweep_request_clear(rs_sweep_request_t *r)
{
    slong ax;
    for (ax = 0; ax < 2; ax++) {
        fmpq_clear(r->axis[ax].from);
        fmpq_clear(r->axis[ax].to);
    }
}

/* the parameter named by token t into ax */
static int parse_param(rs_sweep_axis_t *ax, rs_run_t *run, const rs_request_t *q, const tok_t *t)
{
    ax->at = t->s;
    if (t->n >= sizeof ax->name) return tok_error(run, q, t, "'%s' is not a parameter");
    memcpy(ax->name, t->s, t->n);
    ax->name[t->n] = '\0';
    ax->var = rs_case_param_index(run->c, ax->name);
    if (ax->var < 0) return tok_error(run, q, t, "'%s' is not a parameter");
    return RS_OK;
}

int rs_sweep_request_parse(rs_sweep_request_t *R, rs_run_t *run, const rs_request_t *q, const char *rest)
{
    tok_t t[SW_MAX_TOKENS];
    const char *opts;
    slong nt = tokenize(t, SW_MAX_TOKENS, rest, &opts), pos;
    rs_sweep_axis_t *ax = R->axis;
    int r;
    if (nt > SW_MAX_TOKENS) nt = SW_MAX_TOKENS;
    R->kind = RS_SWEEP_KIND_SWEEP;
    R->naxes = 1;
    if (nt < 7 || !tok_is(t + 1, "from") || !tok_is(t + 3, "to") || !tok_is(t + 5, "steps"))
        return rs_req_error(run, q, rest, RS_ERR_INPUT,
                            "expected 'sweep NAME from A to B steps K [log] [of radius|modes|stability]', found '%s'",
                            rest);
    r = parse_param(ax, run, q, t);
    if (r != RS_OK) return r;
    ax->from_at = t[2].s;
    if (tok_number(ax->from, t + 2) != RS_OK) return tok_error(run, q, t + 2, "expected a number after 'from', found '%s'");
    if (tok_number(ax->to, t + 4) != RS_OK) return tok_error(run, q, t + 4, "expected a number after 'to', found '%s'");
    if (!tok_long(&ax->count, t + 6) || ax->count < 1)
        return tok_error(run, q, t + 6, "expected a positive integer number of steps, found '%s'");
    pos = 7;
    if (pos < nt && tok_is(t + pos, "log")) { R->logsp = 1; pos++; }
    r = parse_of(run, q, t, nt, &pos, &R->of, 1);
    if (r == RS_OK && opts != NULL && R->of != OF_MODES)
        r = rs_req_error(run, q, opts, RS_ERR_INPUT, "options are only for 'of modes', found '%s'", opts);
    R->opts = opts;
    if (r == RS_OK && R->logsp && (fmpq_sgn(ax->from) <= 0 || fmpq_sgn(ax->to) <= 0))
        r = rs_req_error(run, q, ax->from_at, RS_ERR_INPUT, "log spacing needs A > 0 and B > 0, found '%s'", ax->from_at);
    if (r == RS_OK && ax->count >= run->opt->sweep.max_points)
        r = limit_error(run, q, (double) ax->count + 1.0, "the sweep");
    return r;
}

static int an_sweep(rs_run_t *run, const rs_request_t *q, const char *rest)
{
    rs_sweep_request_t R;
    int r;
    rs_sweep_request_init(&R);
    r = rs_sweep_request_parse(&R, run, q, rest);
    if (r == RS_OK) r = rs_an_sweep_run(run, q, &R);
    rs_sweep_request_clear(&R);
    return r;
}

int rs_an_sweep_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R)
{
    const char *opts = R->opts;
    slong K = R->axis[0].count, idx = R->axis[0].var, lo, hi, i;
    int kind = R->of, logsp = R->logsp, r;
    const char *name = R->axis[0].name;
    const fmpq *A = R->axis[0].from, *B = R->axis[0].to;
    rs_variant_t *v;
    job_t J;
    fmpq *vals;
    pt_t *pts;
    double t0 = now_seconds();
    r = estimate_points(run, q, (double) K + 1.0, "the sweep");
    if (r != RS_OK) return r;
    {
        rs_assign_t *a;
        slong n;
        const char *keep[1];
        keep[0] = run->c->params[idx].name;
        rs_run_assignments(run, &a, &n, keep, 1, NULL, 0);
        r = rs_run_variant(&v, run, a, n);
        rs_assign_free(a, n);
    }
    if (r == RS_OK) r = check_free(run, q, v, idx, -1, "sweep");
    if (r != RS_OK) return r;

    memset(&J, 0, sizeof J);
    J.run = run;
    J.q = q;
    J.kind = kind;
    J.is_map = 0;
    J.K1 = K + 1;
    J.K2 = 1;
    J.npoints = K + 1;
    J.max_prec = run->opt->max_prec;
    terms_init(&J.T, v->cp->p, v->s->lambda_var, idx, -1, v->s->zctx);
    vals = _fmpq_vec_init(J.npoints);
    for (i = 0; i < J.npoints; i++) rs_grid_value(vals + i, A, B, i, K, logsp);
    J.v = v;
    J.var[0] = idx;
    J.x[0] = vals;
    J.U1 = powers_table(vals, J.npoints, J.T.d1);
    if (kind == OF_MODES) {
        r = parse_modes_opts(&J, run, q, v, opts, idx, vals);
        if (r != RS_OK) {
            job_clear(&J);
            _fmpq_vec_clear(vals, J.npoints);
            return r;
        }
    }
    rs_sweep_shard_range(&lo, &hi, J.npoints, run->opt->sweep.shard_index, run->opt->sweep.shard_count);
    pts = calloc((size_t) (hi - lo + 1), sizeof(pt_t));
    {
        char what[120];
        snprintf(what, sizeof what, "sweep %s", name);
        compute_range(pts, &J, lo, hi, what);
    }
    {
        char desc[200];
        char *xs = fmpq_get_str(NULL, 10, vals + (lo < hi ? lo : 0));
        snprintf(desc, sizeof desc, "%s", name);
        free(xs);
        r = point_errors(run, q, &J, pts, lo, hi - lo, desc);
    }
    if (r == RS_OK) {
        json_t *o = json_object(), *cols = json_array();
        FILE *f;
        char *buf = NULL;
        size_t len = 0;
        slong k;
        char col[200];
        json_object_set_new(o, "analysis", json_string("sweep"));
        json_object_set_new(o, "param", json_string(name));
        json_object_set_new(o, "from", rs_json_fmpq(A));
        json_object_set_new(o, "to", rs_json_fmpq(B));
        json_object_set_new(o, "steps", json_integer(K));
        json_object_set_new(o, "spacing", json_string(logsp ? "log" : "linear"));
        if (logsp)
            json_object_set_new(o, "rational_approximation", json_string(
                "interior points are the simplest rationals within 1e-13 relative of A*(B/A)^(i/K); "
                "the exact values are in the NAME_exact column"));
        json_object_set_new(o, "of", json_string(of_names[kind]));
        json_object_set_new(o, "points", json_integer(J.npoints));
        json_object_set_new(o, "computed", json_integer(hi - lo));
        {
            char sh[64];
            snprintf(sh, sizeof sh, "%ld/%ld", (long) run->opt->sweep.shard_index, (long) run->opt->sweep.shard_count);
            json_object_set_new(o, "shard", json_string(sh));
            json_object_set_new(o, "rows", json_pack("[I,I]", (json_int_t) lo, (json_int_t) hi));
        }
        /* columns */
        json_array_append_new(cols, json_string("index"));
        json_array_append_new(cols, json_string(name));
        snprintf(col, sizeof col, "%s_exact", name);
        json_array_append_new(cols, json_string(col));
        if (kind == OF_STABILITY) {
            const char *c[] = {"verdict", "code", "inside", "on", "outside", "decided_by"};
            for (k = 0; k < 6; k++) json_array_append_new(cols, json_string(c[k]));
        } else {
            const char *c[] = {"radius", "radius_lower", "radius_upper", "verdict", "code", "decided_by"};
            for (k = 0; k < 6; k++) json_array_append_new(cols, json_string(c[k]));
            if (kind == OF_MODES)
                for (k = 0; k < J.nref; k++) {
                    snprintf(col, sizeof col, "damping_ratio_%ld", (long) k + 1);
                    json_array_append_new(cols, json_string(col));
                    snprintf(col, sizeof col, "frequency_error_%ld", (long) k + 1);
                    json_array_append_new(cols, json_string(col));
                    snprintf(col, sizeof col, "omega_%ld", (long) k + 1);
                    json_array_append_new(cols, json_string(col));
                }
        }
        json_object_set_new(o, "columns", cols);
        /* the table */
        f = open_memstream(&buf, &len);
        for (k = 0; k < (slong) json_array_size(cols); k++)
            fprintf(f, "%s%s", k ? "," : "", json_string_value(json_array_get(cols, k)));
        fputc('\n', f);
        for (i = lo; i < hi; i++) {
            const pt_t *p = pts + (i - lo);
            fprintf(f, "%ld,", (long) i);
            put_double_of(f, vals + i);
            fputc(',', f);
            put_fmpq(f, vals + i);
            fputc(',', f);
            if (kind == OF_STABILITY) {
                if (p->d.verdict < 0) fprintf(f, "undefined,-1,,,,%s\n", "exact");
                else fprintf(f, "%s,%d,%d,%d,%d,%s\n", verdict_name(p->d.verdict), p->d.verdict, p->inside,
                             p->on, p->outside, rs_sweep_level_names[p->d.level]);
            } else {
                put_radius(f, &p->d);
                fprintf(f, ",%s,%d,%s", verdict_name(p->d.verdict), p->d.verdict,
                        p->d.verdict < 0 ? "" : rs_sweep_level_names[p->d.level]);
                if (kind == OF_MODES)
                    for (k = 0; k < J.nref; k++) {
                        if (isnan(p->mode_lo[3 * k])) fputs(",,,", f);
                        else for (int c = 0; c < 3; c++) {
                            fputc(',', f);
                            put_certified(f, p->mode_lo[3 * k + c], p->mode_hi[3 * k + c]);
                        }
                    }
                fputc('\n', f);
            }
        }
        memstream_done(f, &buf);
        add_summary(o, pts, hi - lo, now_seconds() - t0);
        {
            const char *keep[1];
            keep[0] = run->c->params[idx].name;
            json_object_set_new(o, "substituted", set_values_json(run, keep, 1));
        }
        json_object_set_new(o, "text", json_string(q->text));
        json_object_set_new(o, "table", json_string(buf));
        free(buf);
        json_array_append_new(run->results, o);
    }
    free(pts);
    job_clear(&J);
    _fmpq_vec_clear(vals, J.npoints);
    return r;
}

/* ---- map ------------------------------------------------------------------------------------------------- */

/* K points from A to B (K == 1: A) */
static fmpq *axis_values(const fmpq_t A, const fmpq_t B, slong K)
{
    fmpq *x = _fmpq_vec_init(K);
    slong i;
    for (i = 0; i < K; i++) rs_grid_value(x + i, A, B, i, K - 1, 0);
    return x;
}

typedef struct {
    fmpz_mpoly_t f;
    char *origin;
    char *text;
} bcond_t;

/* Boundary of the stability region: sign changes of the reduced
 * Lienard-Chipart conditions and of p(1), p(-1) along grid rows and
 * columns (exact signs at grid points, crossing interpolated linearly). */
static void map_boundary(json_t *o, rs_run_t *run, const rs_variant_t *v, slong v1, slong v2, const char *n1,
                         const char *n2, const fmpq *x1, slong K1, const fmpq *x2, slong K2)
{
    const rs_scheme_struct *s = v->s;
    rs_hurwitz_t h;
    fmpz_mpoly_t qz;
    bcond_t *bc = NULL;
    slong nb = 0, c, i, j, npts = 0;
    json_t *conds = json_array(), *b = json_object();
    rs_error_struct saved = *run->err;
    FILE *f;
    char *buf = NULL;
    size_t len = 0;
    int r;
    fmpz_mpoly_init(qz, s->zctx);
    rs_hurwitz_init(h);
    r = rs_run_hurwitz(h, run, v, qz);
    /* candidate polynomials */
    {
        slong ncand = (r == RS_OK ? h->ncond : 0) + 2;
        bc = calloc((size_t) ncand, sizeof(bcond_t));
        for (c = 0; r == RS_OK && c < h->ncond; c++) {
            if (h->cond[c].trivially_true || fmpz_mpoly_is_fmpz(h->cond[c].reduced, s->zctx)) continue;
            fmpz_mpoly_init(bc[nb].f, s->zctx);
            fmpz_mpoly_set(bc[nb].f, h->cond[c].reduced, s->zctx);
            bc[nb].origin = strdup(h->cond[c].origin);
            nb++;
        }
        for (c = 0; c < 2; c++) {
            fmpz_t one;
            slong k;
            int dup = 0;
            fmpz_init(one);
            fmpz_set_si(one, c == 0 ? 1 : -1);
            fmpz_mpoly_init(bc[nb].f, s->zctx);
            fmpz_mpoly_evaluate_one_fmpz(bc[nb].f, v->cp->p, s->lambda_var, one, s->zctx);
            fmpz_clear(one);
            for (k = 0; k < nb; k++) {
                fmpz_mpoly_t neg;
                fmpz_mpoly_init(neg, s->zctx);
                fmpz_mpoly_neg(neg, bc[nb].f, s->zctx);
                if (fmpz_mpoly_equal(bc[k].f, bc[nb].f, s->zctx) || fmpz_mpoly_equal(bc[k].f, neg, s->zctx)) dup = 1;
                fmpz_mpoly_clear(neg, s->zctx);
            }
            if (dup || fmpz_mpoly_is_fmpz(bc[nb].f, s->zctx)) { fmpz_mpoly_clear(bc[nb].f, s->zctx); continue; }
            bc[nb].origin = strdup(c == 0 ? "p(1)" : "p(-1)");
            nb++;
        }
    }
    if (r != RS_OK) {
        json_object_set_new(b, "hurwitz_error", json_string(run->err->msg));
        *run->err = saved;
    }
    f = open_memstream(&buf, &len);
    fprintf(f, "condition,%s,%s,scan\n", n1, n2);
    for (c = 0; c < nb; c++) {
        terms_t T;
        fmpz *U1, *U2, *g;
        double *val, *bx1, *bx2;
        signed char *sg;
        json_array_append_new(conds, json_pack("{s:I,s:s,s:o}", "index", (json_int_t) c + 1, "origin",
                                               bc[c].origin, "poly", rs_json_zpoly(bc[c].f, s)));
        terms_init(&T, bc[c].f, -1, v1, v2, s->zctx);
        U1 = powers_table(x1, K1, T.d1);
        U2 = powers_table(x2, K2, T.d2);
        val = malloc((size_t) (K1 * K2) * sizeof(double));
        sg = malloc((size_t) (K1 * K2));
        bx1 = malloc((size_t) K1 * sizeof(double));
        bx2 = malloc((size_t) K2 * sizeof(double));
        /* log2 of den^d per axis value, for the double approximations */
        for (i = 0; i < K1; i++) bx1[i] = (double) T.d1 * log2(fmpz_get_d(fmpq_denref(x1 + i)));
        for (j = 0; j < K2; j++) bx2[j] = (double) T.d2 * log2(fmpz_get_d(fmpq_denref(x2 + j)));
#pragma omp parallel for schedule(dynamic, 4) private(i, g)
        for (j = 0; j < K2; j++) {
            slong k;
            fmpz_t w;
            if (rs_budget_check(NULL, "the map's boundary") != RS_OK) continue;
            g = _fmpz_vec_init(T.d1 + 1);
            fmpz_init(w);
            for (k = 0; k < T.n; k++)
                fmpz_addmul(g + T.e1[k], T.c + k, U2 + j * (T.d2 + 1) + T.e2[k]);
            for (i = 0; i < K1; i++) {
                slong e;
                double m;
                fmpz_zero(w);
                for (k = 0; k <= T.d1; k++) fmpz_addmul(w, g + k, U1 + i * (T.d1 + 1) + k);
                sg[j * K1 + i] = (signed char) fmpz_sgn(w);
                m = fmpz_get_d_2exp(&e, w);
                val[j * K1 + i] = m == 0 ? 0 : m * exp2((double) e - bx1[i] - bx2[j]);
            }
            fmpz_clear(w);
            _fmpz_vec_clear(g, T.d1 + 1);
        }
        /* rows: fixed n2, crossings in n1 */
        for (j = 0; j < K2 && run->opt->sweep.shard_index == 1; j++)
            for (i = 0; i < K1; i++) {
                slong a = j * K1 + i;
                double xa = fmpq_get_d(x1 + i), y = fmpq_get_d(x2 + j);
                if (sg[a] == 0) {
                    fprintf(f, "%ld,%.15g,%.15g,zero\n", (long) c + 1, xa, y);
                    npts++;
                } else if (i + 1 < K1 && sg[a] * sg[a + 1] < 0) {
                    double tt = val[a] / (val[a] - val[a + 1]), xb = fmpq_get_d(x1 + i + 1);
                    if (!(tt >= 0 && tt <= 1)) tt = 0.5;
                    fprintf(f, "%ld,%.15g,%.15g,row\n", (long) c + 1, xa + tt * (xb - xa), y);
                    npts++;
                }
            }
        /* columns: fixed n1, crossings in n2 */
        for (i = 0; i < K1 && run->opt->sweep.shard_index == 1; i++)
            for (j = 0; j + 1 < K2; j++) {
                slong a = j * K1 + i, bidx = (j + 1) * K1 + i;
                if (sg[a] * sg[bidx] < 0) {
                    double ya = fmpq_get_d(x2 + j), yb = fmpq_get_d(x2 + j + 1);
                    double tt = val[a] / (val[a] - val[bidx]);
                    if (!(tt >= 0 && tt <= 1)) tt = 0.5;
                    fprintf(f, "%ld,%.15g,%.15g,column\n", (long) c + 1, fmpq_get_d(x1 + i), ya + tt * (yb - ya));
                    npts++;
                }
            }
        free(val);
        free(sg);
        free(bx1);
        free(bx2);
        _fmpz_vec_clear(U1, K1 * (T.d1 + 1));
        _fmpz_vec_clear(U2, K2 * (T.d2 + 1));
        terms_clear(&T);
    }
    memstream_done(f, &buf);
    json_object_set_new(b, "conditions", conds);
    json_object_set_new(b, "points", json_integer(npts));
    json_object_set_new(b, "method", json_string(
        "zero sets of the reduced Lienard-Chipart conditions of q(z) (hurwitz) and of p(1), p(-1): exact signs "
        "at the grid points, a crossing between two neighbours of a row (column) placed by linear "
        "interpolation of the values; 'zero' rows are grid points where the polynomial vanishes exactly"));
    json_object_set_new(o, "boundary", b);
    json_object_set_new(o, "boundary_table", json_string(buf));
    free(buf);
    for (c = 0; c < nb; c++) {
        fmpz_mpoly_clear(bc[c].f, s->zctx);
        free(bc[c].origin);
    }
    free(bc);
    rs_hurwitz_clear(h, s->zctx);
    fmpz_mpoly_clear(qz, s->zctx);
}

int rs_map_request_parse(rs_sweep_request_t *R, rs_run_t *run, const rs_request_t *q, const char *rest)
{
    tok_t t[SW_MAX_TOKENS];
    const char *opts;
    slong nt = tokenize(t, SW_MAX_TOKENS, rest, &opts), pos, ax, max = run->opt->sweep.max_points;
    rs_sweep_axis_t *X = R->axis;
    int r = RS_OK;
    if (nt > SW_MAX_TOKENS) nt = SW_MAX_TOKENS;
    R->kind = RS_SWEEP_KIND_MAP;
    R->naxes = 2;
    if (opts != NULL) return rs_req_error(run, q, opts, RS_ERR_INPUT, "unexpected option '%s' for map", opts);
    if (nt < 9 || !tok_is(t + 4, ","))
        return rs_req_error(run, q, rest, RS_ERR_INPUT,
                            "expected 'map NAME1 A1 B1 K1, NAME2 A2 B2 K2 [of radius|stability]', found '%s'", rest);
    for (ax = 0; ax < 2 && r == RS_OK; ax++) {
        const tok_t *u = t + 5 * ax;
        r = parse_param(X + ax, run, q, u);
        X[ax].from_at = u[1].s;
        if (r != RS_OK) break;
        else if (tok_number(X[ax].from, u + 1) != RS_OK) r = tok_error(run, q, u + 1, "expected a number (the first value), found '%s'");
        else if (tok_number(X[ax].to, u + 2) != RS_OK) r = tok_error(run, q, u + 2, "expected a number (the last value), found '%s'");
        else if (!tok_long(&X[ax].count, u + 3) || X[ax].count < 1)
            r = tok_error(run, q, u + 3, "expected a positive integer number of points, found '%s'");
    }
    if (r == RS_OK && X[0].var == X[1].var) r = tok_error(run, q, t + 5, "map needs two different parameters, found '%s' twice");
    pos = 9;
    if (r == RS_OK) r = parse_of(run, q, t, nt, &pos, &R->of, 0);
    /* K1 * K2 compared by division: the product may overflow */
    if (r == RS_OK && (X[0].count > max || X[1].count > max || X[0].count > max / X[1].count)) {
        char desc[200];
        snprintf(desc, sizeof desc, "the map (%ld x %ld)", (long) X[0].count, (long) X[1].count);
        r = limit_error(run, q, (double) X[0].count * (double) X[1].count, desc);
    }
    return r;
}

static int an_map(rs_run_t *run, const rs_request_t *q, const char *rest)
{
    rs_sweep_request_t R;
    int r;
    rs_sweep_request_init(&R);
    r = rs_map_request_parse(&R, run, q, rest);
    if (r == RS_OK) r = rs_an_map_run(run, q, &R);
    rs_sweep_request_clear(&R);
    return r;
}

int rs_an_map_run(rs_run_t *run, const rs_request_t *q, const rs_sweep_request_t *R)
{
    slong K[2], idx[2], lo, hi, i;
    int kind = R->of, r;
    const char *name[2];
    const fmpq *A[2], *B[2];
    rs_variant_t *v;
    job_t J;
    fmpq *xs[2];
    pt_t *pts;
    double t0 = now_seconds(), t_points = 0;
    for (i = 0; i < 2; i++) {
        K[i] = R->axis[i].count;
        idx[i] = R->axis[i].var;
        name[i] = R->axis[i].name;
        A[i] = R->axis[i].from;
        B[i] = R->axis[i].to;
    }
    r = estimate_points(run, q, (double) K[0] * (double) K[1], "the map");
    if (r == RS_OK) {
        rs_assign_t *a;
        slong n;
        const char *keep[2];
        keep[0] = run->c->params[idx[0]].name;
        keep[1] = run->c->params[idx[1]].name;
        rs_run_assignments(run, &a, &n, keep, 2, NULL, 0);
        r = rs_run_variant(&v, run, a, n);
        rs_assign_free(a, n);
        if (r == RS_OK) r = check_free(run, q, v, idx[0], idx[1], "map");
    }
    if (r != RS_OK) return r;
    memset(&J, 0, sizeof J);
    J.run = run;
    J.q = q;
    J.kind = kind;
    J.is_map = 1;
    J.K1 = K[0];
    J.K2 = K[1];
    J.npoints = K[0] * K[1];
    J.max_prec = run->opt->max_prec;
    terms_init(&J.T, v->cp->p, v->s->lambda_var, idx[0], idx[1], v->s->zctx);
    xs[0] = axis_values(A[0], B[0], K[0]);
    xs[1] = axis_values(A[1], B[1], K[1]);
    J.v = v;
    J.var[0] = idx[0];
    J.var[1] = idx[1];
    J.x[0] = xs[0];
    J.x[1] = xs[1];
    J.U1 = powers_table(xs[0], K[0], J.T.d1);
    J.U2 = powers_table(xs[1], K[1], J.T.d2);
    rs_sweep_shard_range(&lo, &hi, J.npoints, run->opt->sweep.shard_index, run->opt->sweep.shard_count);
    pts = calloc((size_t) (hi - lo + 1), sizeof(pt_t));
    {
        char what[200];
        snprintf(what, sizeof what, "map %s,%s", name[0], name[1]);
        compute_range(pts, &J, lo, hi, what);
    }
    {
        char desc[200];
        snprintf(desc, sizeof desc, "index = j*%ld + i of %s[i], %s[j]", (long) K[0], name[0], name[1]);
        r = point_errors(run, q, &J, pts, lo, hi - lo, desc);
    }
    t_points = now_seconds() - t0;
    if (r == RS_OK) {
        json_t *o = json_object(), *cols = json_array();
        FILE *f;
        char *buf = NULL;
        size_t len = 0;
        slong k;
        char col[200];
        const char *keep[2];
        keep[0] = run->c->params[idx[0]].name;
        keep[1] = run->c->params[idx[1]].name;
        json_object_set_new(o, "analysis", json_string("map"));
        json_object_set_new(o, "params", json_pack("[s,s]", name[0], name[1]));
        json_object_set_new(o, "ranges", json_pack("[[o,o,I],[o,o,I]]", rs_json_fmpq(A[0]), rs_json_fmpq(B[0]),
                                                   (json_int_t) K[0], rs_json_fmpq(A[1]), rs_json_fmpq(B[1]),
                                                   (json_int_t) K[1]));
        json_object_set_new(o, "grid", json_pack("[I,I]", (json_int_t) K[0], (json_int_t) K[1]));
        json_object_set_new(o, "of", json_string(of_names[kind]));
        json_object_set_new(o, "points", json_integer(J.npoints));
        json_object_set_new(o, "computed", json_integer(hi - lo));
        {
            char sh[64];
            snprintf(sh, sizeof sh, "%ld/%ld", (long) run->opt->sweep.shard_index, (long) run->opt->sweep.shard_count);
            json_object_set_new(o, "shard", json_string(sh));
            json_object_set_new(o, "rows", json_pack("[I,I]", (json_int_t) lo, (json_int_t) hi));
        }
        {
            const char *c1[] = {"index", "i", "j"};
            for (k = 0; k < 3; k++) json_array_append_new(cols, json_string(c1[k]));
            json_array_append_new(cols, json_string(name[0]));
            json_array_append_new(cols, json_string(name[1]));
            snprintf(col, sizeof col, "%s_exact", name[0]);
            json_array_append_new(cols, json_string(col));
            snprintf(col, sizeof col, "%s_exact", name[1]);
            json_array_append_new(cols, json_string(col));
        }
        {
            const char *c2[] = {"verdict", "code", "radius", "radius_lower", "radius_upper", "decided_by"};
            for (k = 0; k < 6; k++) json_array_append_new(cols, json_string(c2[k]));
        }
        json_object_set_new(o, "columns", cols);
        f = open_memstream(&buf, &len);
        for (k = 0; k < (slong) json_array_size(cols); k++)
            fprintf(f, "%s%s", k ? "," : "", json_string_value(json_array_get(cols, k)));
        fputc('\n', f);
        for (i = lo; i < hi; i++) {
            const pt_t *p = pts + (i - lo);
            slong ii = i % K[0], jj = i / K[0];
            fprintf(f, "%ld,%ld,%ld,", (long) i, (long) ii, (long) jj);
            put_double_of(f, xs[0] + ii);
            fputc(',', f);
            put_double_of(f, xs[1] + jj);
            fputc(',', f);
            put_fmpq(f, xs[0] + ii);
            fputc(',', f);
            put_fmpq(f, xs[1] + jj);
            fprintf(f, ",%s,%d,", verdict_name(p->d.verdict), p->d.verdict);
            put_radius(f, &p->d);
            fprintf(f, ",%s\n", p->d.verdict < 0 ? "" : rs_sweep_level_names[p->d.level]);
        }
        memstream_done(f, &buf);
        add_summary(o, pts, hi - lo, 0);
        json_object_set_new(o, "substituted", set_values_json(run, keep, 2));
        json_object_set_new(o, "text", json_string(q->text));
        json_object_set_new(o, "table", json_string(buf));
        free(buf);
        /* the exact boundary where p is symbolic in both parameters (its rows
         * in shard 1 only, the header in every shard, so shards merge by
         * concatenation) */
        if (fmpz_mpoly_degree_si(v->cp->p, idx[0], v->s->zctx) > 0
            && fmpz_mpoly_degree_si(v->cp->p, idx[1], v->s->zctx) > 0)
            map_boundary(o, run, v, idx[0], idx[1], name[0], name[1], xs[0], K[0], xs[1], K[1]);
        json_object_set_new(o, "seconds", json_real(floor((now_seconds() - t0) * 1e4 + 0.5) / 1e4));
        json_object_set_new(o, "seconds_points", json_real(floor(t_points * 1e4 + 0.5) / 1e4));
        json_array_append_new(run->results, o);
    }
    free(pts);
    job_clear(&J);
    _fmpq_vec_clear(xs[0], K[0]);
    _fmpq_vec_clear(xs[1], K[1]);
    return r;
}

const rs_analysis_entry_t rs_analysis_sweep[] = {
    {"sweep", an_sweep},
    {"map", an_map},
    {NULL, NULL}
};
