/* bench_radius.c -- time to a certified spectral radius vs. GSL double.
 *
 * Build and run (from the repository root; links the sources directly):
 *   gcc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -O2 -Iinclude \
 *       -I/usr/include/flint src/error.c src/radius.c bench/bench_radius.c \
 *       -o /tmp/bench_radius -lflint-arb -lflint -lgsl -lgslcblas -lmpfr \
 *       -lgmp -lm && /tmp/bench_radius
 *
 * For each polynomial and each precision level B in {53,128,256,512,1024,
 * 4096} bits it asks for digits = floor(B*log10(2)) certified digits and
 * prints the median wall time (CLOCK_MONOTONIC, repeated until ~0.2 s or
 * 1000 runs) of the default route (rs_radius_fmpz_poly = GSL-seeded
 * acb_poly_find_roots), of arb_fmpz_poly_complex_roots and of the companion
 * matrix route (skipped where it would take seconds), the digits actually
 * certified and the working precision.  Last, the GSL double baseline: its
 * time and its number of correct digits against the certified value.
 * No assertions: this only measures. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "recstab/radius.h"

typedef int (*radius_fn)(rs_radius_t, const fmpz_poly_t, slong, slong,
                         rs_error_t);

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *) a, y = *(const double *) b;
    return (x > y) - (x < y);
}

/* median seconds of fn(r, p, digits); *rc = last status */
static double time_fn(radius_fn fn, rs_radius_t r, const fmpz_poly_t p,
                      slong digits, int *rc)
{
    double t[1000], start = now(), t0;
    int n = 0;
    rs_error_t err;
    rs_error_init(err);
    do {
        t0 = now();
        *rc = fn(r, p, digits, 0, err);
        t[n++] = now() - t0;
    } while (n < 1000 && (n < 3 || now() - start < 0.2));
    qsort(t, n, sizeof(double), cmp_double);
    return t[n / 2];
}

static double time_double(rs_radius_t r, const fmpz_poly_t p, int *rc)
{
    double t[1000], start = now(), t0;
    int n = 0;
    rs_error_t err;
    rs_error_init(err);
    do {
        t0 = now();
        *rc = rs_radius_double(r, p, err);
        t[n++] = now() - t0;
    } while (n < 1000 && (n < 3 || now() - start < 0.1));
    qsort(t, n, sizeof(double), cmp_double);
    return t[n / 2];
}

static void fmt_time(char *buf, size_t len, double s)
{
    if (s < 1e-3)
        snprintf(buf, len, "%7.1f us", s * 1e6);
    else if (s < 1.0)
        snprintf(buf, len, "%7.2f ms", s * 1e3);
    else
        snprintf(buf, len, "%7.2f s ", s);
}

static void linear(fmpz_poly_t f, slong a1, slong a0)
{
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 1, a1);
    fmpz_poly_set_coeff_si(f, 0, a0);
}

static void quadratic(fmpz_poly_t f, slong a2, slong a1, slong a0)
{
    fmpz_poly_zero(f);
    fmpz_poly_set_coeff_si(f, 2, a2);
    fmpz_poly_set_coeff_si(f, 1, a1);
    fmpz_poly_set_coeff_si(f, 0, a0);
}

#define NPOLY 8

static const char *make_poly(fmpz_poly_t p, int which)
{
    fmpz_poly_t f;
    fmpz_t c;
    slong k;
    static const slong d12[13] = { 3, -7, 11, 2, -5, 13, -1, 4, 9, -6, 8, -2,
                                   17 };
    const char *name;
    fmpz_poly_init(f);
    fmpz_init(c);
    switch (which) {
    case 0: /* w = 1/2 */
        quadratic(p, 4, -8, 5);
        name = "fwd Euler w=1/2";
        break;
    case 1:
        quadratic(p, 5, -8, 4);
        name = "bwd Euler w=1/2";
        break;
    case 2: /* (1+w^2/4) l^2 - 2(1-w^2/4) l + (1+w^2/4), w = 1/2 */
        quadratic(p, 17, -30, 17);
        name = "trapezoid w=1/2";
        break;
    case 3:
        quadratic(p, 4, -7, 4);
        name = "central d. w=1/2";
        break;
    case 4: /* (10^10 l - (10^10-1))^6 (2l-1) */
        fmpz_set_ui(c, 10);
        fmpz_pow_ui(c, c, 10);
        fmpz_poly_zero(f);
        fmpz_poly_set_coeff_fmpz(f, 1, c);
        fmpz_sub_ui(c, c, 1);
        fmpz_neg(c, c);
        fmpz_poly_set_coeff_fmpz(f, 0, c);
        fmpz_poly_pow(p, f, 6);
        linear(f, 2, -1);
        fmpz_poly_mul(p, p, f);
        name = "cluster 6x(1-1e-10)";
        break;
    case 5:
        fmpz_poly_zero(p);
        for (k = 0; k < 13; k++)
            fmpz_poly_set_coeff_si(p, k, d12[k]);
        name = "dense degree 12";
        break;
    case 6:
        fmpz_poly_one(p);
        for (k = 1; k <= 40; k++) {
            linear(f, 41, -k);
            fmpz_poly_mul(p, p, f);
        }
        name = "deg 40 roots k/41";
        break;
    default:
        fmpz_poly_one(p);
        for (k = 0; k < 40; k++) {
            fmpz_poly_zero(f);
            fmpz_one(c);
            fmpz_mul_2exp(c, c, 20);
            fmpz_poly_set_coeff_fmpz(f, 1, c);
            fmpz_one(c);
            fmpz_mul_2exp(c, c, k);
            fmpz_neg(c, c);
            fmpz_poly_set_coeff_fmpz(f, 0, c);
            fmpz_poly_mul(p, p, f);
        }
        name = "deg 40 roots 2^k";
        break;
    }
    fmpz_poly_clear(f);
    fmpz_clear(c);
    return name;
}

static slong got_digits(const arb_t rho)
{
    slong b;
    if (arb_is_exact(rho))
        return 99999;
    b = arb_rel_accuracy_bits(rho);
    return b <= 0 ? 0 : (slong) floor((double) b * 0.30102999566398120);
}

int main(void)
{
    static const slong bits[] = { 53, 128, 256, 512, 1024, 4096 };
    const int nb = (int) (sizeof(bits) / sizeof(bits[0]));
    fmpz_poly_t p;
    rs_radius_t r, ref;
    char t1[32], t2[32], t3[32];
    int w, b, rc;

    setvbuf(stdout, NULL, _IOLBF, 0);
    fmpz_poly_init(p);
    rs_radius_init(r);
    rs_radius_init(ref);
    printf("%-20s %5s %6s | %10s %10s %10s | %6s %5s\n", "polynomial", "bits",
           "digits", "default", "cplx_roots", "companion", "certif", "prec");
    for (w = 0; w < NPOLY; w++) {
        const char *name;
        double td, err_d, rho_ref;
        rs_error_t err;
        slong deg;
        fmpz_poly_zero(p);
        name = make_poly(p, w);
        deg = fmpz_poly_degree(p);
        for (b = 0; b < nb; b++) {
            slong digits = (slong) floor((double) bits[b] * 0.30102999566398120);
            double ta, tb, tc = -1.0;
            int rcb, rcc = 0;
            ta = time_fn(rs_radius_fmpz_poly, r, p, digits, &rc);
            tb = time_fn(rs_radius_fmpz_poly_complex_roots, ref, p, digits, &rcb);
            if (bits[b] <= 1024 && (deg <= 12 || bits[b] <= 128))
                tc = time_fn(rs_radius_fmpz_poly_companion, ref, p, digits,
                             &rcc);
            fmt_time(t1, sizeof t1, ta);
            fmt_time(t2, sizeof t2, tb);
            if (tc >= 0)
                fmt_time(t3, sizeof t3, tc);
            else
                snprintf(t3, sizeof t3, "%10s", "-");
            printf("%-20s %5ld %6ld | %10s %10s %10s | %6ld %5ld%s\n",
                   b == 0 ? name : "", (long) bits[b], (long) digits, t1, t2,
                   t3, rc == RS_OK ? (long) got_digits(r->rho) : -1L,
                   (long) r->prec,
                   (rc || rcb || rcc) ? "  (error)" : "");
        }
        /* double baseline against the certified value */
        rs_error_init(err);
        rs_radius_fmpz_poly(ref, p, 30, 0, err);
        rho_ref = arf_get_d(arb_midref(ref->rho), ARF_RND_NEAR);
        td = time_double(r, p, &rc);
        err_d = fabs(r->rho_double - rho_ref) / rho_ref;
        fmt_time(t1, sizeof t1, td);
        printf("%-20s %5s %6s | %10s  GSL double: rho %.17g, correct digits "
               "%.1f%s\n", "", "53", "dbl", t1, r->rho_double,
               err_d > 0 ? -log10(err_d) : 16.0,
               rc ? "  (error)" : "");
    }
    rs_radius_clear(r);
    rs_radius_clear(ref);
    fmpz_poly_clear(p);
    flint_cleanup();
    return 0;
}
