/* bench_cosim.c -- time to a certified co-simulation spectral radius.
 *
 * Build and run (from the repository root; links the sources directly):
 *   gcc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -O2 -Iinclude \
 *       -I/usr/include/flint src/util/error.c src/util/budget.c src/numeric/radius.c \
 *       src/numeric/cosim.c \
 *       bench/bench_cosim.c -o /tmp/bench_cosim -lflint-arb -lflint -lgsl \
 *       -lgslcblas -lmpfr -lgmp -lm && /tmp/bench_cosim
 *
 * Li et al.'s force/force model (symmetric: all alphas 1; unsymmetric: all
 * 10) at c1 = 1, d1 = 1/2, explicit and implicit, K = 0..3, 30 and 128
 * digits: median in-process wall time (CLOCK_MONOTONIC) of rs_cosim_radius
 * (model set up once; each call rebuilds the exponentials, the recurrence
 * and certifies), over repeats until ~0.2 s.  Also the monolithic radius.
 * No assertions: this only measures. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "recstab/cosim.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmpd(const void *a, const void *b)
{
    double x = *(const double *) a, y = *(const double *) b;
    return (x > y) - (x < y);
}

typedef int (*rfn)(rs_radius_t, const rs_cosim_t, slong, slong, rs_error_t);

static double bench(rfn f, const rs_cosim_t cs, slong digits, rs_radius_t r,
                    int *rc)
{
    double t[1000], start = now();
    rs_error_t err;
    int n = 0;
    while (n < 1000 && (n < 5 || now() - start < 0.2)) {
        double t0 = now();
        *rc = f(r, cs, digits, 0, err);
        t[n++] = now() - t0;
    }
    qsort(t, n, sizeof t[0], cmpd);
    return t[n / 2];
}

int main(void)
{
    const char *alpha[2] = { "1", "10" };
    int a, method, K, rc, di;
    const slong digs[2] = { 30, 128 };
    rs_cosim_t cs;
    rs_radius_t r;
    rs_error_t err;
    fmpq_t c1, d1, al;

    fmpq_init(c1);
    fmpq_init(d1);
    fmpq_init(al);
    fmpq_set_si(c1, 1, 1);
    fmpq_set_si(d1, 1, 2);
    rs_cosim_init(cs, 2, 2);
    rs_radius_init(r);
    printf("%-12s %-9s %2s %6s %10s %6s  %s\n", "model", "method", "K",
           "digits", "ms", "prec", "rho");
    for (a = 0; a < 2; a++) {
        fmpq_set_str(al, alpha[a], 10);
        rs_cosim_li_ff(cs, c1, d1, al, al, al, al, al, err);
        for (method = 0; method < 2; method++)
            for (K = 0; K <= RS_COSIM_MAX_ORDER; K++)
                for (di = 0; di < 2; di++) {
                    double t;
                    char *s;
                    cs->method = method;
                    cs->order = K;
                    t = bench(rs_cosim_radius, cs, digs[di], r, &rc);
                    s = arb_get_str(r->rho, 15, ARB_STR_NO_RADIUS);
                    printf("%-12s %-9s %2d %6ld %10.3f %6ld  %s%s\n",
                           a ? "unsym(10)" : "sym(1)",
                           method ? "implicit" : "explicit", K,
                           (long) digs[di], 1e3 * t, (long) r->prec, s,
                           rc == RS_OK ? "" : "  (FAILED)");
                    flint_free(s);
                }
        {
            double t = bench(rs_cosim_monolithic_radius, cs, 128, r, &rc);
            printf("%-12s %-9s %2s %6d %10.3f %6ld\n",
                   a ? "unsym(10)" : "sym(1)", "mono", "-", 128, 1e3 * t,
                   (long) r->prec);
        }
    }
    rs_radius_clear(r);
    rs_cosim_clear(cs);
    fmpq_clear(c1);
    fmpq_clear(d1);
    fmpq_clear(al);
    flint_cleanup();
    return 0;
}
