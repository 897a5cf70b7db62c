/* cosim_forms.c -- see numeric/cosim_forms.h.  The interval arithmetic on
 * scalars here follows cosim_dbl.c's error model (round to nearest, a
 * priori bounds with a safety factor). */
#include <float.h>
#include <math.h>
#include <string.h>
#include "numeric/cosim_forms.h"

#define U_ (0x1p-53)
#define ETA_ (DBL_TRUE_MIN)
#define MAXAX 4

typedef struct { double m, r; } ival;

static inline double up_(double x)
{
    return x * (1.0 + 32.0 * U_) + 8.0 * ETA_;
}

static ival imul1(ival a, ival b)
{
    ival c;
    c.m = a.m * b.m;
    c.r = up_(fabs(a.m) * b.r + a.r * (fabs(b.m) + b.r) + U_ * fabs(c.m));
    return c;
}

static ival iadd1(ival a, ival b)
{
    ival c;
    c.m = a.m + b.m;
    c.r = up_(a.r + b.r + U_ * fabs(c.m));
    return c;
}

/* a / b; ok = 0 when b's interval contains 0.  |a/b - am/bm| <= (ar + |am/bm| br) / (|bm| - br) */
static ival idiv1(ival a, ival b, int *ok)
{
    ival c;
    double lo = fabs(b.m) - b.r;
    c.m = a.m / b.m;
    if (!(lo > 0)) { *ok = 0; c.r = 0; return c; }
    lo = lo * (1.0 - 4 * U_);
    c.r = up_((a.r + fabs(c.m) * (1.0 + 4 * U_) * b.r) / lo + U_ * fabs(c.m));
    return c;
}

typedef struct { slong start, end; } range_t;

struct rs_cosim_nforms_struct {
    slong naxes, n, nf, m, nstate[2];
    slong *in_var;           /* W column of each coupling variable */
    int *second;             /* per state row: W(row, row + 1) = 1 */
    range_t *W;              /* n x (n + nf): the row forms' coefficients */
    range_t *Cf;             /* nf x n: the forces' coefficients */
    range_t *den;            /* n + nf: rows, then forces */
    slong nterms, alloc, maxdeg[MAXAX];
    double *cm, *cr;         /* the terms' coefficients */
    slong *ex;               /* their exponents in the axes, naxes per term */
    rs_cosim_dbl_t tmpl;     /* dimensions, method, order, H, Lagrange coefficients */
};

static void push_term(rs_cosim_nforms_struct *N, const fmpq_t c, const slong *e)
{
    slong k;
    if (N->nterms == N->alloc) {
        N->alloc = 2 * N->alloc + 16;
        N->cm = flint_realloc(N->cm, N->alloc * sizeof(double));
        N->cr = flint_realloc(N->cr, N->alloc * sizeof(double));
        N->ex = flint_realloc(N->ex, N->alloc * MAXAX * sizeof(slong));
    }
    rs_dbl_set_fmpq(N->cm + N->nterms, N->cr + N->nterms, c);
    for (k = 0; k < N->naxes; k++) {
        N->ex[N->nterms * MAXAX + k] = e[k];
        if (e[k] > N->maxdeg[k]) N->maxdeg[k] = e[k];
    }
    N->nterms++;
}

/* split p's terms: var = the single state/force variable in [lo, hi) of
 * degree 1 (-1: none allowed), the rest only axes.  Appends the terms whose
 * variable is `want` into a range; 0 when a term is outside that shape. */
static int collect(rs_cosim_nforms_struct *N, range_t *out, const fmpq_mpoly_t p, slong want, slong lo, slong hi,
                   const slong *av, const rs_scheme_struct *ts)
{
    slong i, v, k, len = fmpq_mpoly_length(p, ts->ctx), e[MAXAX];
    slong *ex = flint_malloc((ts->nvars + 1) * sizeof(slong));
    fmpq_t c;
    int ok = 1;
    fmpq_init(c);
    out->start = N->nterms;
    for (i = 0; i < len && ok; i++) {
        slong var = -1;
        fmpq_mpoly_get_term_exp_si(ex, p, i, ts->ctx);
        for (k = 0; k < N->naxes; k++) e[k] = ex[av[k]];
        for (v = 0; v < ts->nvars && ok; v++) {
            int axis = 0;
            if (ex[v] == 0) continue;
            for (k = 0; k < N->naxes; k++) if (av[k] == v) axis = 1;
            if (axis) continue;
            if (v >= lo && v < hi && ex[v] == 1 && var < 0) var = v;
            else ok = 0;
        }
        if (ok && want < 0 && var >= 0) ok = 0;
        if (ok && want >= 0 && var < 0) ok = 0;   /* not homogeneous */
        if (ok && var == want) {
            fmpq_mpoly_get_term_coeff_fmpq(c, p, i, ts->ctx);
            push_term(N, c, e);
        }
    }
    out->end = N->nterms;
    fmpq_clear(c);
    flint_free(ex);
    return ok;
}

void rs_cosim_nforms_free(rs_cosim_nforms_struct *N)
{
    if (N == NULL) return;
    flint_free(N->in_var);
    flint_free(N->second);
    flint_free(N->W);
    flint_free(N->Cf);
    flint_free(N->den);
    flint_free(N->cm);
    flint_free(N->cr);
    flint_free(N->ex);
    rs_cosim_dbl_clear(N->tmpl);
    flint_free(N);
}

rs_cosim_nforms_struct *rs_cosim_nforms_new(const rs_cosim_model_struct *F, const rs_case_struct *c,
                                            const char *const *axis, slong naxes)
{
    const rs_scheme_struct *ts = F->ts;
    rs_cosim_nforms_struct *N;
    slong n = F->n, nf = F->nf, base = c->nparams, i, k, q, row, av[MAXAX];
    fmpq_mpoly_t p, dp;
    fmpq_t h[2];
    rs_error_t err;
    int ok = 1, method, ext;
    if (naxes < 1 || naxes > MAXAX) return NULL;
    ext = c->couple_ext == 'D' || c->couple_ext == 'I';
    method = c->couple != NULL && strcmp(c->couple, "implicit") == 0 ? RS_COSIM_IMPLICIT : RS_COSIM_EXPLICIT;
    if (ext || c->couple_order < 0 || c->couple_order > RS_COSIM_MAX_ORDER) return NULL;
    for (k = 0; k < naxes; k++) {
        av[k] = rs_case_param_index(F->tc, axis[k]);
        if (av[k] < 0 || av[k] >= base) return NULL;
    }
    N = flint_calloc(1, sizeof *N);
    N->naxes = naxes;
    N->n = n;
    N->nf = nf;
    N->nstate[0] = F->nstate[0];
    N->nstate[1] = F->nstate[1];
    N->W = flint_calloc(n * (n + nf) + 1, sizeof(range_t));
    N->Cf = flint_calloc(nf * n + 1, sizeof(range_t));
    N->den = flint_calloc(n + nf + 1, sizeof(range_t));
    N->second = flint_calloc(n + 1, sizeof(int));
    N->in_var = flint_malloc((n + nf + 1) * sizeof(slong));
    rs_cosim_dbl_init(N->tmpl);
    fmpq_mpoly_init(p, ts->ctx);
    fmpq_mpoly_init(dp, ts->ctx);
    fmpq_init(h[0]);
    fmpq_init(h[1]);
    rs_error_init(err);
    for (i = 0; i < F->nforms && ok; i++) {
        slong s, v;
        fmpq_mpoly_set(p, F->num + i, ts->ctx);
        fmpq_mpoly_set(dp, F->den + i, ts->ctx);
        /* every set value but the axes' */
        for (s = 0; s < c->nsets; s++) {
            int isaxis = 0;
            for (k = 0; k < naxes; k++) if (strcmp(c->sets[s].name, axis[k]) == 0) isaxis = 1;
            if (isaxis) continue;
            v = rs_case_param_index(F->tc, c->sets[s].name);
            if (v < 0) { ok = 0; break; }
            fmpq_mpoly_evaluate_one_fmpq(p, p, v, c->sets[s].value, ts->ctx);
            fmpq_mpoly_evaluate_one_fmpq(dp, dp, v, c->sets[s].value, ts->ctx);
        }
        if (!ok) break;
        if (i < n) {            /* a state row: states and forces, over its denominator */
            N->second[i] = F->second[i];
            if (F->second[i]) continue;
            ok = collect(N, N->den + i, dp, -1, 0, 0, av, ts);
            for (q = 0; q < n + nf && ok; q++) ok = collect(N, N->W + i * (n + nf) + q, p, base + q, base, base + n + nf, av, ts);
        } else if (i < n + 2) { /* a macro step: a constant, the same for both */
            if (!fmpq_mpoly_is_fmpq(p, ts->ctx) || !fmpq_mpoly_is_fmpq(dp, ts->ctx) || fmpq_mpoly_is_zero(dp, ts->ctx)) ok = 0;
            else {
                fmpq_t d;
                fmpq_init(d);
                fmpq_mpoly_get_fmpq(h[i - n], p, ts->ctx);
                fmpq_mpoly_get_fmpq(d, dp, ts->ctx);
                fmpq_div(h[i - n], h[i - n], d);
                fmpq_clear(d);
                ok = fmpq_sgn(h[i - n]) > 0;
            }
        } else {                /* a force: the states */
            slong f = i - n - 2;
            ok = collect(N, N->den + n + f, dp, -1, 0, 0, av, ts);
            for (q = 0; q < n && ok; q++) ok = collect(N, N->Cf + f * n + q, p, base + q, base, base + n, av, ts);
        }
    }
    ok = ok && fmpq_equal(h[0], h[1]);
    /* the generic coupling variables, in cosim_at's order */
    if (ok) {
        slong m = 0, j;
        for (j = 0; j < n; j++) {
            int own = j < N->nstate[0] ? 0 : 1, used = 0;
            for (row = 0; row < n; row++) {
                const range_t *rg = N->W + row * (n + nf) + j;
                if ((row < N->nstate[0] ? 0 : 1) != own && rg->end > rg->start) used = 1;
            }
            if (used) N->in_var[m++] = j;
        }
        for (i = 0; i < nf; i++) N->in_var[m++] = n + i;
        N->m = m;
        ok = m > 0 && m <= RS_COSIM_MAX_INPUTS && n <= RS_COSIM_MAX_DIM && rs_cosim_dbl_set_dims(N->tmpl, N->nstate[0], N->nstate[1], m, method, c->couple_order, err) == RS_OK;
        if (ok) ok = rs_dbl_set_fmpq(&N->tmpl->Hm, &N->tmpl->Hr, h[0]);
    }
    fmpq_mpoly_clear(p, ts->ctx);
    fmpq_mpoly_clear(dp, ts->ctx);
    fmpq_clear(h[0]);
    fmpq_clear(h[1]);
    rs_error_clear(err);
    if (!ok) {
        rs_cosim_nforms_free(N);
        return NULL;
    }
    return N;
}

/* the polynomial of range g at the powers pw (pw[k * (maxdeg + 1) + e] = x_k^e) */
static ival eval_range(const rs_cosim_nforms_struct *N, range_t g, const ival *pw, slong stride)
{
    ival s = {0, 0};
    slong t, k;
    for (t = g.start; t < g.end; t++) {
        ival a;
        a.m = N->cm[t];
        a.r = N->cr[t];
        for (k = 0; k < N->naxes; k++) {
            slong e = N->ex[t * MAXAX + k];
            if (e > 0) a = imul1(a, pw[k * stride + e]);
        }
        s = iadd1(s, a);
    }
    return s;
}

int rs_cosim_nforms_at(rs_cosim_dbl_t d, const rs_cosim_nforms_struct *N, const fmpq *x)
{
    slong n = N->n, nf = N->nf, m = N->m, n0 = N->nstate[0], stride = 1, i, j, k;
    ival *pw, dv;
    int ok = 1;
    if (d->A1m == NULL || d->n1 != N->tmpl->n1 || d->n2 != N->tmpl->n2 || d->m != m) rs_cosim_dbl_set_like(d, N->tmpl);
    d->Hm = N->tmpl->Hm;
    d->Hr = N->tmpl->Hr;
    for (k = 0; k < N->naxes; k++) if (N->maxdeg[k] + 1 > stride) stride = N->maxdeg[k] + 1;
    pw = flint_malloc(N->naxes * stride * sizeof(ival));
    for (k = 0; k < N->naxes && ok; k++) {
        slong e;
        pw[k * stride].m = 1;
        pw[k * stride].r = 0;
        if (stride > 1) ok = rs_dbl_set_fmpq(&pw[k * stride + 1].m, &pw[k * stride + 1].r, x + k);
        for (e = 2; e < stride; e++) pw[k * stride + e] = imul1(pw[k * stride + e - 1], pw[k * stride + 1]);
    }
    memset(d->A1m, 0, 2 * (n0 * n0 + (n - n0) * (n - n0) + 2 * n * m) * sizeof(double));
    for (j = 0; j < n && ok; j++) {
        slong ja = j < n0 ? 0 : 1, jl = j - (ja ? n0 : 0), nj = ja ? n - n0 : n0, off = ja ? n0 : 0;
        double *Am = ja ? d->A2m : d->A1m, *Ar = ja ? d->A2r : d->A1r;
        if (N->second[j]) {
            /* X'' rows: X' = the next state (cosim_at: W(row, row + 1) = 1) */
            if (j + 1 - off < nj) Am[jl * nj + jl + 1] = 1;
            continue;
        }
        dv = eval_range(N, N->den[j], pw, stride);
        for (k = 0; k < nj && ok; k++) {
            ival v = idiv1(eval_range(N, N->W[j * (n + nf) + off + k], pw, stride), dv, &ok);
            Am[jl * nj + k] = v.m;
            Ar[jl * nj + k] = v.r;
        }
        for (k = 0; k < m && ok; k++) {
            slong w = N->in_var[k];
            ival v;
            if (w < n && (w < n0 ? 0 : 1) == ja) continue;   /* own states are in A */
            v = idiv1(eval_range(N, N->W[j * (n + nf) + w], pw, stride), dv, &ok);
            d->Bm[j * m + k] = v.m;
            d->Br[j * m + k] = v.r;
        }
    }
    for (i = 0; i < m && ok; i++) {
        slong w = N->in_var[i];
        if (w < n) {
            d->Cm[i * n + w] = 1;
            continue;
        }
        dv = eval_range(N, N->den[w], pw, stride);
        for (j = 0; j < n && ok; j++) {
            ival v = idiv1(eval_range(N, N->Cf[(w - n) * n + j], pw, stride), dv, &ok);
            d->Cm[i * n + j] = v.m;
            d->Cr[i * n + j] = v.r;
        }
    }
    flint_free(pw);
    return ok;
}

unsigned rs_cosim_nforms_sub_axes(const rs_cosim_nforms_struct *N, int s)
{
    slong n = N->n, nf = N->nf, n0 = N->nstate[0], j, q, t, k;
    unsigned mask = 0;
    for (j = s ? n0 : 0; j < (s ? n : n0); j++) {
        if (N->second[j]) continue;   /* a constant row */
        for (q = -1; q < n + nf; q++) {
            range_t g = q < 0 ? N->den[j] : N->W[j * (n + nf) + q];
            for (t = g.start; t < g.end; t++)
                for (k = 0; k < N->naxes; k++)
                    if (N->ex[t * MAXAX + k] > 0) mask |= 1u << k;
        }
    }
    return mask;
}
