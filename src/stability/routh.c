/* routh.c -- see include/recstab/routh.h
 *
 * Numeric array.  Row i holds the coefficients of an even or odd polynomial
 * R_i(z) (entries: z^N, z^(N-2), ... for the row's nominal degree N).  Each
 * new row is the exact remainder R_{i+2} = rem(R_i, R_{i+1}) over Q; in the
 * regular case that is literally the textbook Routh row.  The count does not
 * read signs off the first column but uses the theorem behind it: with
 * R_i(i w) = i^{D_i} rho_i(w) (D_i = actual degree), the rho_i form, up to
 * known signs, a Sturm chain of the real and imaginary parts of q(i w), so
 *     #{Re z < 0} - #{Re z > 0} = c * (V(-inf) - V(+inf))
 * (Cauchy index / argument principle, c = (-1)^(leading zeros of row 1)).
 * That identity holds for any degree gaps, so:
 *  - zero first entry, row not zero: the row is kept with its leading zeros
 *    and the next row is the exact remainder (a generalised Routh step, in the
 *    spirit of Benidir-Picinbono) -- no epsilon, no perturbation;
 *  - zero row: the last non-zero row is G = gcd(even part, odd part), the
 *    auxiliary polynomial; it holds every root symmetric about 0, all the
 *    imaginary-axis roots with their full multiplicity.  The array continues
 *    with G' (the array of G + G', whose right-half-plane roots are those of
 *    G since G(i w) is real and G'(i w) imaginary); a repeated zero row then
 *    yields gcd(G, G'), which lowers every multiplicity by one, so the number
 *    of distinct axis roots of each multiplicity falls out exactly.
 * Degree drop of q (lambda = -1) and q(0) = 0 (lambda = 1) are split off
 * first, so every auxiliary polynomial is even with G(0) != 0.
 *
 * Symbolic array: fraction-free rows T_i = Delta_{i-1} * r_i (Delta_k the
 * Hurwitz minors, r_i the rational Routh row), computed as
 *     T_i[j] = (T_{i-1}[0] T_{i-2}[j+1] - T_{i-2}[0] T_{i-1}[j+1]) / T_{i-3}[0]
 * for i >= 4 (no division for i = 2, 3), which is exact because every T_i[j]
 * is a minor of the Hurwitz matrix.  The first column is Delta_1, ..., Delta_m. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <flint/fmpq_poly.h>
#include "recstab/budget.h"
#include "recstab/routh.h"
#include "recstab/bilinear.h"

void rs_routh_init(rs_routh_t r)
{
    memset(r, 0, sizeof(rs_routh_struct));
    rs_rootcount_init(r->count);
}

void rs_routh_clear(rs_routh_t r)
{
    slong i, j;
    for (i = 0; i < r->nrows; i++) {
        for (j = 0; j < r->rowlen[i]; j++)
            fmpq_clear(r->rows[i] + j);
        flint_free(r->rows[i]);
    }
    flint_free(r->rows);
    flint_free(r->rowlen);
    flint_free(r->rowpow);
    for (i = 0; i < r->neps; i++) {
        for (j = 0; j < r->epslen[i]; j++)
            fmpz_poly_q_clear(r->eps[i] + j);
        flint_free(r->eps[i]);
    }
    flint_free(r->eps);
    flint_free(r->epslen);
    flint_free(r->epssign);
    for (i = 0; i < r->nevents; i++)
        free(r->events[i].text);
    free(r->events);
    rs_rootcount_clear(r->count);
    memset(r, 0, sizeof(rs_routh_struct));
}

/* Append R as a row of nominal degree `nominal`; returns its index. */
static slong routh_push_row(rs_routh_t r, const fmpq_poly_t R, slong nominal)
{
    slong len = nominal / 2 + 1, l, i = r->nrows;

    r->rows = flint_realloc(r->rows, (i + 1) * sizeof(fmpq *));
    r->rowlen = flint_realloc(r->rowlen, (i + 1) * sizeof(slong));
    r->rowpow = flint_realloc(r->rowpow, (i + 1) * sizeof(slong));
    r->rowpow[i] = nominal;
    r->rows[i] = flint_malloc(len * sizeof(fmpq));
    for (l = 0; l < len; l++) {
        fmpq_init(r->rows[i] + l);
        fmpq_poly_get_coeff_fmpq(r->rows[i] + l, R, nominal - 2 * l);
    }
    r->rowlen[i] = len;
    r->nrows = i + 1;
    return i;
}

static void routh_push_event(rs_routh_t r, rs_routh_event_kind_t kind,
                             slong row, slong count, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

static void routh_push_event(rs_routh_t r, rs_routh_event_kind_t kind,
                             slong row, slong count, const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    rs_routh_event_struct *ev;
    size_t n;

    va_start(ap, fmt);
    vsnprintf(buf, sizeof(buf), fmt, ap);
    va_end(ap);
    r->events = realloc(r->events,
                        (r->nevents + 1) * sizeof(rs_routh_event_struct));
    ev = r->events + r->nevents;
    ev->kind = kind;
    ev->row = row;
    ev->count = count;
    n = strlen(buf) + 1;
    ev->text = malloc(n);
    if (ev->text != NULL)
        memcpy(ev->text, buf, n);
    r->nevents++;
}

/* E/O split: lead gets the terms of q of the parity of deg q. */
static void split_parity(fmpq_poly_t lead, fmpq_poly_t other,
                         const fmpz_poly_t q)
{
    slong m = fmpz_poly_degree(q), i;
    fmpq_poly_zero(lead);
    fmpq_poly_zero(other);
    for (i = 0; i <= m; i++) {
        if ((m - i) % 2 == 0)
            fmpq_poly_set_coeff_fmpz(lead, i, q->coeffs + i);
        else
            fmpq_poly_set_coeff_fmpz(other, i, q->coeffs + i);
    }
}

/* One stretch of the array between zero rows.  A is already in the table,
 * B is the next row (nominal degree deg A - 1, possibly zero).  Runs the
 * remainder chain, pushing rows and zero-pivot events; G gets the last
 * non-zero row and *rhp the number of Re z > 0 roots of (A + B) / G. */
static int routh_segment(rs_routh_t r, fmpq_poly_t G, slong *rhp,
                         const fmpq_poly_t A, const fmpq_poly_t B, int c,
                         rs_error_t err)
{
    slong cap = fmpq_poly_degree(A) + 2, len, j, mB, num, vplus = 0, vminus = 0;
    slong *D = flint_malloc(cap * sizeof(slong));
    int *sg = flint_malloc(cap * sizeof(int));
    int *eps = flint_malloc(cap * sizeof(int));
    int lastp = 0, lastm = 0, status = RS_OK;
    fmpq_poly_t prev, cur, next;

    fmpq_poly_init(prev);
    fmpq_poly_init(cur);
    fmpq_poly_init(next);
    fmpq_poly_set(prev, A);
    fmpq_poly_set(cur, B);
    D[0] = fmpq_poly_degree(A);
    sg[0] = fmpz_sgn(fmpq_poly_numref(A) + D[0]);
    len = 1;
    while (!fmpq_poly_is_zero(cur)) {
        slong nominal = D[len - 1] - 1, row, zeros;
        /* a stop must reach the caller: its segment loop would take the
         * unfinished chain for a zero row and run past its arrays */
        if ((status = rs_budget_check(err, "the Routh array")) != RS_OK) break;
        row = routh_push_row(r, cur, nominal);
        zeros = (nominal - fmpq_poly_degree(cur)) / 2;
        if (zeros > 0)
            routh_push_event(r, RS_ROUTH_EVENT_ZERO_PIVOT, row, zeros,
                "row %ld starts with %ld zero entr%s but is not zero; the "
                "next row is the exact remainder of the two rows above "
                "(generalised Routh step, no epsilon).",
                row, zeros, zeros == 1 ? "y" : "ies");
        D[len] = fmpq_poly_degree(cur);
        sg[len] = fmpz_sgn(fmpq_poly_numref(cur) + D[len]);
        len++;
        fmpq_poly_rem(next, prev, cur);
        fmpq_poly_swap(prev, cur);
        fmpq_poly_swap(cur, next);
    }
    fmpq_poly_swap(G, prev);

    /* signs making rho_i a Sturm chain: rho_{j+2} = s_j rem(rho_j, rho_{j+1})
     * with s_j = (-1)^((D_j - D_{j+2}) / 2), and Sturm wants -rem. */
    for (j = 0; j < len; j++) {
        int sp, sm;
        if (j < 2)
            eps[j] = 1;
        else
            eps[j] = (((D[j - 2] - D[j]) / 2) % 2 == 0) ? -eps[j - 2]
                                                         : eps[j - 2];
        sp = eps[j] * sg[j];
        sm = (D[j] % 2 == 0) ? sp : -sp;
        if (j > 0 && sp != lastp)
            vplus++;
        if (j > 0 && sm != lastm)
            vminus++;
        lastp = sp;
        lastm = sm;
    }
    mB = D[0] - D[len - 1];
    num = mB - c * (vminus - vplus);
    if (status != RS_OK)
        num = 0;
    else if (num < 0 || num > 2 * mB || num % 2 != 0)
        status = rs_error_set(err, RS_ERR_INTERNAL,
            "Routh segment count inconsistent (degree %ld, index %ld)",
            mB, vminus - vplus);
    *rhp = num / 2;

    fmpq_poly_clear(prev);
    fmpq_poly_clear(cur);
    fmpq_poly_clear(next);
    flint_free(D);
    flint_free(sg);
    flint_free(eps);
    return status;
}

/* Sign of a rational function of eps as eps -> 0+. */
static int eps_sign(const fmpz_poly_q_t f)
{
    const fmpz_poly_struct *nu = fmpz_poly_q_numref(f), *de = fmpz_poly_q_denref(f);
    slong i = 0, j = 0;
    if (fmpz_poly_is_zero(nu))
        return 0;
    while (fmpz_is_zero(nu->coeffs + i)) i++;
    while (fmpz_is_zero(de->coeffs + j)) j++;
    return fmpz_sgn(nu->coeffs + i) * fmpz_sgn(de->coeffs + j);
}

/* The textbook array of q1 (degree m) in Q(eps), for display after a zero
 * pivot: row i has the power m - i; a zero first entry of a non-zero row
 * becomes eps, a zero row the derivative of the auxiliary polynomial of the
 * row above (as in the exact array). */
static void routh_epsilon_array(rs_routh_t r, const fmpz_poly_t q1)
{
    slong m = fmpz_poly_degree(q1), w = m / 2 + 1, i, j;
    fmpz_poly_q_t t, u;

    r->neps = m + 1;
    r->epslen = flint_malloc((m + 1) * sizeof(slong));
    r->eps = flint_malloc((m + 1) * sizeof(fmpz_poly_q_struct *));
    r->epssign = flint_malloc((m + 1) * sizeof(int));
    fmpz_poly_q_init(t);
    fmpz_poly_q_init(u);
    for (i = 0; i <= m; i++) {
        r->epslen[i] = w;
        r->eps[i] = flint_malloc(w * sizeof(fmpz_poly_q_struct));
        for (j = 0; j < w; j++) {
            fmpz_poly_q_init(r->eps[i] + j);
            if (i < 2 && m - i - 2 * j >= 0)
                fmpz_poly_set_fmpz(fmpz_poly_q_numref(r->eps[i] + j), q1->coeffs + m - i - 2 * j);
        }
    }
    for (i = 1; i <= m; i++) {
        fmpz_poly_q_struct *a = r->eps[i - 1], *b = r->eps[i];
        int zero = 1;
        if (i >= 2)
            for (j = 0; j < w; j++) {
                /* b[j] = (a'[0] b''[j+1] - b''[0] a'[j+1]) / a'[0], rows i-1, i-2 */
                const fmpz_poly_q_struct *p1 = r->eps[i - 1], *p2 = r->eps[i - 2];
                fmpz_poly_q_zero(b + j);
                if (j + 1 >= w) continue;
                fmpz_poly_q_mul(t, p1 + 0, p2 + j + 1);
                fmpz_poly_q_mul(u, p2 + 0, p1 + j + 1);
                fmpz_poly_q_sub(t, t, u);
                fmpz_poly_q_div(b + j, t, p1 + 0);
            }
        for (j = 0; j < w; j++)
            if (!fmpz_poly_q_is_zero(b + j)) zero = 0;
        if (zero && i < m) {
            /* derivative of the auxiliary polynomial of row i - 1 (power m-i+1) */
            for (j = 0; j < w; j++)
                fmpz_poly_q_scalar_mul_si(b + j, a + j, m - i + 1 - 2 * j > 0 ? m - i + 1 - 2 * j : 0);
        }
        if (fmpz_poly_q_is_zero(b + 0) && i < m) {
            zero = 1;
            for (j = 1; j < w; j++)
                if (!fmpz_poly_q_is_zero(b + j)) zero = 0;
            if (!zero) {
                fmpz_poly_q_zero(b + 0);
                fmpz_poly_set_coeff_si(fmpz_poly_q_numref(b + 0), 1, 1);
            }
        }
    }
    for (i = 0; i <= m; i++)
        r->epssign[i] = eps_sign(r->eps[i] + 0);
    fmpz_poly_q_clear(t);
    fmpz_poly_q_clear(u);
}

/* Roots of q1 (q1(0) != 0) in lambda terms, added to r->count. */
static int routh_count_reduced(rs_routh_t r, const fmpz_poly_t q1,
                               rs_error_t err)
{
    slong m = fmpz_poly_degree(q1), nseg = 0, j, mu, total = 0, imag;
    slong *rhp = flint_malloc((m + 2) * sizeof(slong));
    slong *gdeg = flint_malloc((m + 2) * sizeof(slong));
    slong *I = flint_malloc((m + 3) * sizeof(slong));
    fmpq_poly_t A, B, G;
    int c = 1, status = RS_OK;

    fmpq_poly_init(A);
    fmpq_poly_init(B);
    fmpq_poly_init(G);
    split_parity(A, B, q1);
    routh_push_row(r, A, m);
    if (!fmpq_poly_is_zero(B))
        c = (((m - 1 - fmpq_poly_degree(B)) / 2) % 2 == 0) ? 1 : -1;

    while (status == RS_OK) {
        status = routh_segment(r, G, rhp + nseg, A, B, c, err);
        gdeg[nseg] = fmpq_poly_degree(G);
        nseg++;
        if (status != RS_OK || gdeg[nseg - 1] == 0)
            break;
        /* zero row: continue with the derivative of the auxiliary poly */
        routh_push_event(r, RS_ROUTH_EVENT_ZERO_ROW, r->nrows, gdeg[nseg - 1],
            "row %ld is zero: the auxiliary polynomial of degree %ld from "
            "row %ld divides q and holds its roots symmetric about z = 0 "
            "(imaginary-axis ones lie on |lambda| = 1); the row is replaced "
            "by its derivative.", r->nrows, gdeg[nseg - 1], r->nrows - 1);
        fmpq_poly_swap(A, G);
        fmpq_poly_derivative(B, A);
        c = 1;
    }

    for (j = 0; j < r->nevents && status == RS_OK && r->neps == 0; j++)
        if (r->events[j].kind == RS_ROUTH_EVENT_ZERO_PIVOT)
            routh_epsilon_array(r, q1);

    if (status == RS_OK) {
        /* I[j] = imaginary-axis roots of G_j (with multiplicity) where
         * G_j = gcd(G_{j-1}, G_{j-1}'), from RHP(G_j) = sum of later rhp. */
        slong later = 0;
        I[nseg] = 0;
        for (j = nseg - 1; j >= 1; j--) {
            later += rhp[j];
            I[j] = gdeg[j - 1] - 2 * later;
        }
        total = later + rhp[0];
        imag = nseg > 1 ? I[1] : 0;
        for (mu = 1; mu < nseg; mu++) {
            slong ge = I[mu] - I[mu + 1];
            slong ge1 = (mu + 1 < nseg) ? I[mu + 1] - I[mu + 2] : 0;
            if (ge - ge1 < 0 || I[mu] < 0) {
                status = rs_error_set(err, RS_ERR_INTERNAL,
                    "negative imaginary-axis multiplicity count");
                break;
            }
            rs_rootcount_add_on(r->count, mu, ge - ge1);
        }
        r->count->outside += total;
        r->count->inside += m - total - imag;
        r->sign_changes = total;
        if (m - total - imag < 0)
            status = rs_error_set(err, RS_ERR_INTERNAL,
                                  "Routh count exceeds the degree");
    }

    fmpq_poly_clear(A);
    fmpq_poly_clear(B);
    fmpq_poly_clear(G);
    flint_free(rhp);
    flint_free(gdeg);
    flint_free(I);
    return status;
}

int rs_routh_fmpz_poly(rs_routh_t r, const fmpz_poly_t p, rs_error_t err)
{
    fmpz_poly_t q;
    slong n, d, k;
    int status = RS_OK;

    rs_routh_clear(r);
    rs_routh_init(r);
    if (fmpz_poly_is_zero(p))
        return rs_error_set(err, RS_ERR_INPUT,
                            "Routh array of the zero polynomial");
    n = fmpz_poly_degree(p);
    r->count->degree = n;

    fmpz_poly_init(q);
    rs_bilinear_fmpz_poly(q, p);
    d = rs_bilinear_degree_drop(p, q);
    k = rs_bilinear_zero_mult(q);
    if (d > 0) {
        r->count->at_minus_one = d;
        rs_rootcount_add_on(r->count, d, 1);
        routh_push_event(r, RS_ROUTH_EVENT_DEGREE_DROP, 0, d,
            "deg q = %ld < deg p = %ld: lambda = -1 is a root of "
            "multiplicity %ld (z = infinity), counted on the unit circle.",
            n - d, n, d);
    }
    if (k > 0) {
        r->count->at_one = k;
        rs_rootcount_add_on(r->count, k, 1);
        routh_push_event(r, RS_ROUTH_EVENT_ZERO_AT_ORIGIN, 0, k,
            "q(0) = 0: lambda = 1 is a root of multiplicity %ld (z = 0), "
            "counted on the unit circle; z^%ld is divided out.", k, k);
        fmpz_poly_shift_right(q, q, k);
    }
    status = routh_count_reduced(r, q, err);
    fmpz_poly_clear(q);
    if (status == RS_OK && r->count->inside + r->count->on
                           + r->count->outside != n)
        status = rs_error_set(err, RS_ERR_INTERNAL,
                              "Routh count does not add up to the degree");
    return status;
}

/* ---- symbolic (fraction-free) array ---------------------------------- */

void rs_routh_mpoly_init(rs_routh_mpoly_t r)
{
    memset(r, 0, sizeof(rs_routh_mpoly_struct));
}

void rs_routh_mpoly_clear(rs_routh_mpoly_t r, const fmpz_mpoly_ctx_t ctx)
{
    slong i, j;
    for (i = 0; i < r->nrows; i++) {
        for (j = 0; j < r->rowlen[i]; j++)
            fmpz_mpoly_clear(r->rows[i] + j, ctx);
        flint_free(r->rows[i]);
    }
    flint_free(r->rows);
    flint_free(r->rowlen);
    memset(r, 0, sizeof(rs_routh_mpoly_struct));
}

int rs_routh_mpoly(rs_routh_mpoly_t r, const fmpz_mpoly_t q, slong var,
                   const fmpz_mpoly_ctx_t ctx, rs_error_t err)
{
    slong m, i, j, nodiv = 0;
    fmpz_mpoly_t t, u;
    int status = RS_OK;
    double raw;
    rs_budget_calib_t cal;

    rs_routh_mpoly_clear(r, ctx);
    rs_budget_calib_init(&cal);
    r->zero_row = -1;
    m = fmpz_mpoly_degree_si(q, var, ctx);
    if (m < 0)
        return rs_error_set(err, RS_ERR_INPUT,
                            "Routh array of the zero polynomial");
    r->nrows = m + 1;
    r->rowlen = flint_malloc((m + 1) * sizeof(slong));
    r->rows = flint_malloc((m + 1) * sizeof(fmpz_mpoly_struct *));
    for (i = 0; i <= m; i++) {
        r->rowlen[i] = (m - i) / 2 + 1;
        r->rows[i] = flint_malloc(r->rowlen[i] * sizeof(fmpz_mpoly_struct));
        for (j = 0; j < r->rowlen[i]; j++)
            fmpz_mpoly_init(r->rows[i] + j, ctx);
    }
    for (i = 0; i <= FLINT_MIN(m, 1); i++)
        for (j = 0; j < r->rowlen[i]; j++) {
            ulong e = (ulong) (m - i - 2 * j);
            fmpz_mpoly_get_coeff_vars_ui(r->rows[i] + j, q, &var, &e, 1, ctx);
        }

    fmpz_mpoly_init(t, ctx);
    fmpz_mpoly_init(u, ctx);
    for (i = 2; i <= m && status == RS_OK; i++) {
        const fmpz_mpoly_struct *piv = r->rows[i - 1], *up = r->rows[i - 2];
        if (fmpz_mpoly_is_zero(piv, ctx)) {
            /* a whole row identically zero: roots symmetric about the origin
             * for every parameter value; continue with the derivative of the
             * auxiliary polynomial of the row above (textbook rule, exact) */
            int allzero = 1;
            for (j = 0; j < r->rowlen[i - 1]; j++)
                if (!fmpz_mpoly_is_zero(r->rows[i - 1] + j, ctx)) allzero = 0;
            if (allzero && r->zero_row < 0) {
                slong deg = m - (i - 2);
                for (j = 0; j < r->rowlen[i - 1] && deg - 2 * j > 0; j++)
                    fmpz_mpoly_scalar_mul_si(r->rows[i - 1] + j, up + j, deg - 2 * j, ctx);
                r->zero_row = i - 1;
                nodiv = i;   /* the Bareiss-type divisions no longer apply */
                if (!fmpz_mpoly_is_zero(piv, ctx)) { i--; continue; }
            }
        }
        if (fmpz_mpoly_is_zero(piv, ctx)) {
            status = rs_error_set(err, RS_ERR_MATH,
                "Routh pivot of row %ld is identically zero; specialise the "
                "parameters and use the exact numeric array", i - 1);
            break;
        }
        {
            /* one product can take minutes: estimate the row, and stop
             * between products when the budget runs out; the estimate is
             * calibrated on the rows already formed (rs_budget_calib_t) */
            raw = 0.0;
            for (j = 0; j < r->rowlen[i]; j++) {
                raw += rs_budget_mpoly_mul_seconds(piv, up + j + 1);
                if (j + 1 < r->rowlen[i - 1])
                    raw += rs_budget_mpoly_mul_seconds(up, r->rows[i - 1] + j + 1);
            }
            status = rs_budget_estimate(err, "a row of the symbolic Routh array",
                                        rs_budget_calib_begin(&cal, raw), 0.0);
        }
        for (j = 0; j < r->rowlen[i] && status == RS_OK; j++) {
            fmpz_mpoly_struct *out = r->rows[i] + j;
            if ((status = rs_budget_check(err, "the symbolic Routh array")) != RS_OK)
                break;
            /* t = piv * up[j+1] - up[0] * prev[j+1]; up always has j+1 */
            fmpz_mpoly_mul(t, piv, up + j + 1, ctx);
            if (j + 1 < r->rowlen[i - 1]) {
                fmpz_mpoly_mul(u, up, r->rows[i - 1] + j + 1, ctx);
                fmpz_mpoly_sub(t, t, u, ctx);
            }
            if (i >= 4 && i - 3 >= nodiv) {
                if (!fmpz_mpoly_divides(out, t, r->rows[i - 3], ctx))
                    status = rs_error_set(err, RS_ERR_INTERNAL,
                        "fraction-free Routh row %ld not divisible by the "
                        "pivot of row %ld", i, i - 3);
            } else
                fmpz_mpoly_swap(out, t, ctx);
        }
        if (status == RS_OK)
            rs_budget_calib_end(&cal);
    }
    fmpz_mpoly_clear(t, ctx);
    fmpz_mpoly_clear(u, ctx);
    return status;
}
