/* bench_radius.c -- time to a certified spectral radius vs. GSL double.
 *
 * Build and run (from the repository root; links the sources directly):
 *   gcc -std=c11 -D_POSIX_C_SOURCE=200809L -Wall -Wextra -O2 -Iinclude \
 *       -I/usr/include/flint src/util/error.c src/util/budget.c src/numeric/radius.c \
 *       bench/bench_radius.c \
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
 * No assertions: this only measures.
 *
 * With --accuracy OUTDIR (driver: bench/bench_accuracy.sh) it instead runs
 * the accuracy-vs-time comparison with PARI/GP and MPSolve described above
 * acc_main below. */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
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

/* median seconds of fn(r, p, digits), repeated for about `budget` seconds
 * (3 to 1000 runs); *rc = last status */
static double time_fn(radius_fn fn, rs_radius_t r, const fmpz_poly_t p,
                      slong digits, double budget, int *rc)
{
    double t[1000], start = now(), t0;
    int n = 0;
    rs_error_t err;
    rs_error_init(err);
    do {
        t0 = now();
        *rc = fn(r, p, digits, 0, err);
        t[n++] = now() - t0;
    } while (n < 1000 && (n < 3 || now() - start < budget));
    qsort(t, n, sizeof(double), cmp_double);
    return t[n / 2];
}

/* rs_radius_double in the shape of the certified routes */
static int radius_double(rs_radius_t r, const fmpz_poly_t p, slong digits, slong max_prec, rs_error_t err)
{
    (void) digits;
    (void) max_prec;
    return rs_radius_double(r, p, err);
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

static int classic_main(void)
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
            ta = time_fn(rs_radius_fmpz_poly, r, p, digits, 0.2, &rc);
            tb = time_fn(rs_radius_fmpz_poly_complex_roots, ref, p, digits, 0.2, &rcb);
            if (bits[b] <= 1024 && (deg <= 12 || bits[b] <= 128))
                tc = time_fn(rs_radius_fmpz_poly_companion, ref, p, digits, 0.2, &rcc);
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
        td = time_fn(radius_double, r, p, 0, 0.1, &rc);
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

/* ======================================================================
 * --accuracy: what accuracy costs in time (driver: bench/bench_accuracy.sh)
 *
 *   bench_radius --accuracy OUTDIR [--work DIR] [--gp CMD] [--mpsolve CMD]
 *                [--budget SECONDS]
 *
 * For each polynomial of acc_make_poly and each level B in {53, 128, 256,
 * 512, 1024, 4096} bits it requests D = floor(B log10 2) digits (15, 38, 77,
 * 154, 308, 1233; plus 30 and 128 digits for the dense degree-12 polynomial,
 * the two targets) from
 *   recstab  rs_radius_fmpz_poly (certified), in this process: median over
 *            repeated calls (at least 3, until --budget seconds, at most
 *            1000) of CLOCK_PROCESS_CPUTIME_ID and of CLOCK_MONOTONIC;
 *   PARI/GP  polroots after default(realprecision, D), all jobs in ONE gp
 *            process (start-up excluded): one untimed call (its roots are
 *            the ones scored), then calls repeated until >= 3 and >= budget
 *            ms of getabstime() (CPU ms); time = CPU / calls (mean);
 *            getwalltime() recorded as well;
 *   MPSolve  the command  mpsolve -j1 -Ga -o D -Ob -p EXPR  (default
 *            algorithm, goal "approximate", D guaranteed digits, one worker
 *            thread like the others), one fresh process per
 *            run, repeated like recstab; median of wall (fork..waitpid) and
 *            of the child's user+system CPU (getrusage RUSAGE_CHILDREN).
 *            Process start-up IS included; each run is paired with a run of
 *            the same command on x - 1 (the start-up floor) and the "-start"
 *            column is the median of the paired differences;
 *   GSL      rs_radius_double (uncertified double baseline), at 15 digits.
 * Each peer's roots are scored against a certified reference computed once
 * per polynomial at ACC_REF_DIGITS digits (> 1233): rho digits =
 * -log10(|rho_peer - rho_cert| / rho_cert) with rho_peer = max |root|, and
 * roots digits = -log10(H / rho_cert), H the Hausdorff distance between the
 * peer's root set and the certified root set; both capped at the reference
 * accuracy.  Reported times are CPU times (CSV also has wall).
 * Writes OUTDIR/accuracy-vs-time.{txt,csv,dat}; raw peer output in --work
 * (default build/accuracy).  No assertions: this only measures. */

#define ACC_NPOLY 15
#define ACC_MAXJOBS 128
#define ACC_REF_DIGITS 1280
#define ACC_PREC 8192          /* arithmetic for scoring */
#define ACC_DENSE 14           /* index of the dense degree-12 polynomial */
#define ACC_MPS_LIMIT 30       /* CPU seconds per MPSolve process */

static void acc_park(fmpz_poly_t p, slong m, slong muh, slong wh, slong anum,
                     slong aden)
{
    /* aden * [A (4 (l-1)^2 + wh^2 (l+1)^2)
               - 2 m muh wh^2 ((1 + alpha) l - alpha)(l+1)^2],
       A = (3 + 2(1+m) muh) l^2 - 4 l + 1, alpha = anum/aden; made primitive */
    fmpz_poly_t A, B, C, D;
    fmpz_poly_init(A);
    fmpz_poly_init(B);
    fmpz_poly_init(C);
    fmpz_poly_init(D);
    quadratic(A, 3 + 2 * (1 + m) * muh, -4, 1);
    quadratic(B, 4 + wh * wh, -8 + 2 * wh * wh, 4 + wh * wh);
    fmpz_poly_mul(p, A, B);
    fmpz_poly_scalar_mul_si(p, p, aden);
    linear(C, aden + anum, -anum);
    quadratic(D, 1, 2, 1);
    fmpz_poly_mul(C, C, D);
    fmpz_poly_scalar_mul_si(C, C, 2 * m * muh * wh * wh);
    fmpz_poly_sub(p, p, C);
    fmpz_poly_primitive_part(p, p);
    fmpz_poly_clear(A);
    fmpz_poly_clear(B);
    fmpz_poly_clear(C);
    fmpz_poly_clear(D);
}

static void acc_ten_pow(fmpz_t c, ulong e)
{
    fmpz_set_ui(c, 10);
    fmpz_pow_ui(c, c, e);
}

static const char *acc_make_poly(fmpz_poly_t p, int which)
{
    static const slong d12[13] = { 3, -7, 11, 2, -5, 13, -1, 4, 9, -6, 8, -2,
                                   17 };
    fmpz_poly_t f;
    fmpz_t c;
    slong k;
    const char *name = "?";
    fmpz_poly_init(f);
    fmpz_init(c);
    fmpz_poly_zero(p);
    switch (which) {
    case 0: /* (l-1)^2 + w^2, w = 1/2 */
        quadratic(p, 4, -8, 5);
        name = "fwd-Euler w=1/2";
        break;
    case 1: /* (1+w^2) l^2 - 2 l + 1 */
        quadratic(p, 5, -8, 4);
        name = "bwd-Euler w=1/2";
        break;
    case 2: /* (l-1)^2 + w^2 (l+1)^2 / 4 */
        quadratic(p, 17, -30, 17);
        name = "trapezoid w=1/2";
        break;
    case 3: /* l^2 - (2 - w^2) l + 1 */
        quadratic(p, 4, -7, 4);
        name = "central-diff w=1/2";
        break;
    case 4: /* (3l^2 - 4l + 1)^2 + 4 w^2 l^4 */
        quadratic(f, 3, -4, 1);
        fmpz_poly_mul(p, f, f);
        fmpz_poly_get_coeff_fmpz(c, p, 4);
        fmpz_add_ui(c, c, 1);
        fmpz_poly_set_coeff_fmpz(p, 4, c);
        name = "BDF2 w=1/2";
        break;
    case 5:
        acc_park(p, 1, 1, 1, 1, 2);
        name = "Park (1,1,1,1/2)";
        break;
    case 6:
        acc_park(p, 10, 1, 1, 1, 1);
        name = "Park (10,1,1,1)";
        break;
    case 7:
        acc_park(p, 100, 1000, 5, 5, 4);
        name = "Park (100,1000,5,5/4)";
        break;
    case 8: /* Olivier, Jacobi forward Euler, degree 6 */
        fmpz_poly_set_coeff_si(p, 6, 10000);
        fmpz_poly_set_coeff_si(p, 5, -40000);
        fmpz_poly_set_coeff_si(p, 4, 62200);
        fmpz_poly_set_coeff_si(p, 3, -44400);
        fmpz_poly_set_coeff_si(p, 2, 12321);
        fmpz_poly_set_coeff_si(p, 0, -100);
        name = "Olivier Jacobi-FE deg 6";
        break;
    case 9: /* (10^10 l - (10^10 - 1))^6 (2l - 1)(4l + 3) */
        acc_ten_pow(c, 10);
        fmpz_poly_set_coeff_fmpz(f, 1, c);
        fmpz_sub_ui(c, c, 1);
        fmpz_neg(c, c);
        fmpz_poly_set_coeff_fmpz(f, 0, c);
        fmpz_poly_pow(p, f, 6);
        linear(f, 2, -1);
        fmpz_poly_mul(p, p, f);
        linear(f, 4, 3);
        fmpz_poly_mul(p, p, f);
        name = "cluster 6x(1-1e-10)";
        break;
    case 10: /* (10^80 l^2 - 1)(3l - 1) */
        acc_ten_pow(c, 80);
        fmpz_poly_set_coeff_fmpz(f, 2, c);
        fmpz_poly_set_coeff_si(f, 0, -1);
        linear(p, 3, -1);
        fmpz_poly_mul(p, p, f);
        name = "tiny roots 1e-40";
        break;
    case 11: /* (l^2 + 1)^2 (2l - 1) */
        quadratic(f, 1, 0, 1);
        fmpz_poly_mul(p, f, f);
        linear(f, 2, -1);
        fmpz_poly_mul(p, p, f);
        name = "(l^2+1)^2 (l-1/2)";
        break;
    case 12: /* prod_{k=1}^{40} (41 l - k) (4 l^2 + 1)^2 */
        fmpz_poly_one(p);
        for (k = 1; k <= 40; k++) {
            linear(f, 41, -k);
            fmpz_poly_mul(p, p, f);
        }
        quadratic(f, 4, 0, 1);
        fmpz_poly_mul(p, p, f);
        fmpz_poly_mul(p, p, f);
        name = "degree 44";
        break;
    case 13: /* (10^15 l - 1)(10^5 l - 1)(2 l - 1)(l - 10^5) */
        acc_ten_pow(c, 15);
        fmpz_poly_set_coeff_fmpz(p, 1, c);
        fmpz_poly_set_coeff_si(p, 0, -1);
        linear(f, 100000, -1);
        fmpz_poly_mul(p, p, f);
        linear(f, 2, -1);
        fmpz_poly_mul(p, p, f);
        linear(f, 1, -100000);
        fmpz_poly_mul(p, p, f);
        name = "wide coefficients";
        break;
    default: /* fixed "random" dense integer polynomial, as in the classic run */
        for (k = 0; k < 13; k++)
            fmpz_poly_set_coeff_si(p, k, d12[k]);
        name = "dense degree 12";
        break;
    }
    fmpz_poly_clear(f);
    fmpz_clear(c);
    return name;
}

typedef struct {
    int ok;                /* 0 = not run, 1 = ok, -1 = error, -2 = CPU limit */
    double cpu, wall;      /* seconds per call (see header) */
    double net_cpu, net_wall; /* MPSolve: minus the paired start-up floor */
    int reps;
    double dig_rho, dig_roots;
} acc_peer;

typedef struct {
    int poly;
    slong digits, bits;    /* bits = 0: extra target level */
    int rc;
    double cpu, wall;
    int reps;
    slong cert, prec;
    int consistent;
    acc_peer gp, mps;
} acc_job;

typedef struct {
    const char *name;
    slong deg;
    char *expr;            /* "17*x^12-2*x^11+..." for gp and MPSolve */
    rs_radius_t ref;
    double refdig;
    double gsl_cpu, gsl_wall, gsl_dig_rho, gsl_dig_roots;
    int gsl_rc;
} acc_poly;

static double cpu_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

static double median_of(double *t, int n)
{
    qsort(t, n, sizeof(double), cmp_double);
    return (n % 2) ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

/* -log10(e), e a relative error ball; cap when e may be 0 */
static double acc_digits(const arb_t e, double cap)
{
    arb_t t;
    double d;
    if (arb_contains_zero(e) || arf_is_zero(arb_midref(e)))
        return cap;
    arb_init(t);
    arb_set_arf(t, arb_midref(e));
    arb_abs(t, t);
    arb_log_base_ui(t, t, 10, 64);
    d = -arf_get_d(arb_midref(t), ARF_RND_NEAR);
    arb_clear(t);
    return d > cap ? cap : d;
}

/* score peer roots z[0..n) against the reference */
static void acc_score(double *dig_rho, double *dig_roots, acb_srcptr z,
                      slong n, const acc_poly *P)
{
    const rs_radius_struct *ref = P->ref;
    arb_t a, best, worst, t, e;
    slong i, j;
    arb_init(a);
    arb_init(best);
    arb_init(worst);
    arb_init(t);
    arb_init(e);
    /* rho digits */
    arb_zero(a);
    for (i = 0; i < n; i++) {
        acb_abs(t, z + i, ACC_PREC);
        arb_max(a, a, t, ACC_PREC);
    }
    arb_sub(e, a, ref->rho, ACC_PREC);
    arb_abs(e, e);
    arb_div(e, e, ref->rho, ACC_PREC);
    *dig_rho = acc_digits(e, P->refdig);
    /* Hausdorff distance (squared, midpoints) between the two root sets */
    arb_zero(worst);
    for (int dir = 0; dir < 2; dir++) {
        slong na = dir ? n : ref->nroots, nb = dir ? ref->nroots : n;
        acb_srcptr A = dir ? z : ref->roots, B = dir ? ref->roots : z;
        for (i = 0; i < na; i++) {
            arb_pos_inf(best);
            for (j = 0; j < nb; j++) {
                arb_sub(t, acb_realref(A + i), acb_realref(B + j), ACC_PREC);
                arb_sqr(t, t, ACC_PREC);
                arb_sub(e, acb_imagref(A + i), acb_imagref(B + j), ACC_PREC);
                arb_sqr(e, e, ACC_PREC);
                arb_add(t, t, e, ACC_PREC);
                if (arf_cmp(arb_midref(t), arb_midref(best)) < 0)
                    arb_set(best, t);
            }
            if (arf_cmp(arb_midref(best), arb_midref(worst)) > 0)
                arb_set(worst, best);
        }
    }
    if (n != ref->nroots) {
        *dig_roots = 0.0; /* wrong number of roots */
    } else {
        arb_sqrt(worst, worst, ACC_PREC);
        arb_div(worst, worst, ref->rho, ACC_PREC);
        *dig_roots = acc_digits(worst, P->refdig);
    }
    arb_clear(a);
    arb_clear(best);
    arb_clear(worst);
    arb_clear(t);
    arb_clear(e);
}

static void acc_time_rs(acc_job *J, const fmpz_poly_t p, rs_radius_t r,
                        double budget)
{
    static double tw[1000], tc[1000];
    double start = now(), w0, c0;
    int n = 0;
    rs_error_t err;
    rs_error_init(err);
    do {
        w0 = now();
        c0 = cpu_now();
        J->rc = rs_radius_fmpz_poly(r, p, J->digits, 0, err);
        tc[n] = cpu_now() - c0;
        tw[n] = now() - w0;
        n++;
    } while (n < 1000 && (n < 3 || now() - start < budget));
    J->reps = n;
    J->cpu = median_of(tc, n);
    J->wall = median_of(tw, n);
    J->cert = J->rc == RS_OK ? got_digits(r->rho) : -1;
    J->prec = r->prec;
    rs_error_clear(err);
}

/* fork + exec argv with stdout to `out` (stdin, stderr /dev/null) and a CPU
 * limit; returns the exit status (>= 0), -2 if killed (e.g. by the limit),
 * -1 if it could not be started; *wall and *cpu (child user + system) in s. */
static int acc_spawn(char *const argv[], const char *out, int cpu_limit,
                     double *wall, double *cpu)
{
    struct rusage r0, r1;
    double w0;
    pid_t pid;
    int st;
    getrusage(RUSAGE_CHILDREN, &r0);
    w0 = now();
    pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        struct rlimit rl;
        int fo = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        int fn = open("/dev/null", O_RDWR);
        if (fo < 0 || fn < 0)
            _exit(126);
        dup2(fn, 0);
        dup2(fo, 1);
        dup2(fn, 2);
        rl.rlim_cur = rl.rlim_max = (rlim_t) cpu_limit;
        setrlimit(RLIMIT_CPU, &rl);
        execvp(argv[0], argv);
        _exit(127);
    }
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR)
            return -1;
    *wall = now() - w0;
    getrusage(RUSAGE_CHILDREN, &r1);
    *cpu = (double) (r1.ru_utime.tv_sec - r0.ru_utime.tv_sec)
         + 1e-6 * (double) (r1.ru_utime.tv_usec - r0.ru_utime.tv_usec)
         + (double) (r1.ru_stime.tv_sec - r0.ru_stime.tv_sec)
         + 1e-6 * (double) (r1.ru_stime.tv_usec - r0.ru_stime.tv_usec);
    if (WIFEXITED(st))
        return WEXITSTATUS(st);
    return -2;
}

/* read "re im" decimal pairs (MPSolve -Ob) */
static slong acc_read_mps(acb_ptr z, slong max, const char *path)
{
    FILE *f = fopen(path, "r");
    static char re[20000], im[20000];
    slong n = 0;
    if (!f)
        return -1;
    while (n < max && fscanf(f, "%19999s %19999s", re, im) == 2) {
        if (arb_set_str(acb_realref(z + n), re, ACC_PREC)
            || arb_set_str(acb_imagref(z + n), im, ACC_PREC)) {
            n = -1;
            break;
        }
        n++;
    }
    if (n >= 0 && fscanf(f, "%19999s", re) == 1)
        n = -1; /* more roots than expected, or garbage */
    fclose(f);
    return n;
}

static void acc_run_mpsolve(const char *cmd, acc_job *J, const acc_poly *P,
                            const char *work, double budget, acb_ptr z)
{
    /* each rep: the start-up floor (same options on x - 1), then the job;
       net = median of the paired differences (start-up noise on a loaded
       machine is +-5 ms, more than many whole solves) */
    static double tw[64], tc[64], dw[64], dc[64];
    char dig[32], out[4096], fout[4096];
    char *argv[] = { (char *) cmd, "-j1", "-Ga", "-o", dig, "-Ob", "-p",
                     P->expr, NULL };
    char *fargv[] = { (char *) cmd, "-j1", "-Ga", "-o", dig, "-Ob", "-p",
                      "x-1", NULL };
    double start = now(), w, c, fw, fc;
    int n = 0, rc;
    slong nz;
    snprintf(dig, sizeof dig, "%ld", (long) J->digits);
    snprintf(out, sizeof out, "%s/mpsolve.out", work);
    snprintf(fout, sizeof fout, "%s/mpsolve-floor.out", work);
    J->mps.ok = -1;
    do {
        if (acc_spawn(fargv, fout, ACC_MPS_LIMIT, &fw, &fc) != 0)
            return;
        rc = acc_spawn(argv, out, ACC_MPS_LIMIT, &w, &c);
        if (rc != 0) {
            if (rc == -2)
                J->mps.ok = -2; /* killed: CPU limit */
            return;
        }
        tw[n] = w;
        tc[n] = c;
        dw[n] = w - fw;
        dc[n] = c - fc;
        n++;
    } while (n < 64 && (n < 5 || now() - start < budget)
             && now() - start < 5.0);
    nz = acc_read_mps(z, P->deg, out);
    if (nz != P->deg)
        return;
    J->mps.ok = 1;
    J->mps.reps = n;
    J->mps.cpu = median_of(tc, n);
    J->mps.wall = median_of(tw, n);
    J->mps.net_cpu = median_of(dc, n);
    J->mps.net_wall = median_of(dw, n);
    acc_score(&J->mps.dig_rho, &J->mps.dig_roots, z, nz, P);
}

static int acc_run_gp(const char *cmd, acc_job *jobs, int nj, acc_poly *P,
                      const char *work, double budget, acb_ptr z)
{
    char script[4096], out[4096];
    char *argv[] = { (char *) cmd, "-q", "-f", script, NULL };
    FILE *f;
    int i, rc;
    double w, c;
    static char line[4096];
    snprintf(script, sizeof script, "%s/peers.gp", work);
    snprintf(out, sizeof out, "%s/gp.out", work);
    f = fopen(script, "w");
    if (!f)
        return -1;
    fprintf(f, "\\\\ generated by bench_radius --accuracy; gp -q -f %s\n"
            "default(parisizemax, 1000000000);\n"
            "ex(x) = if(type(x) != \"t_REAL\", x = x * 1.); if(x == 0, \"0 0\","
            " my(k = bitprecision(x) - 1 - exponent(x));"
            " Str(truncate(shift(x, k)), \" \", k));\n", script);
    for (i = 0; i < nj; i++) {
        fprintf(f, "p = %s;\ndefault(realprecision, %ld);\n"
                "iferr(r = polroots(p); n = 0; t = getabstime(); w = getwalltime();"
                " until(n >= 3 && getabstime() - t >= %d, polroots(p); n++);"
                " c = getabstime() - t; w = getwalltime() - w;"
                " printf(\"job %%d %%d %%d %%d %%d\\n\", %d, c, w, n, #r);"
                " for(i = 1, #r, print(ex(real(r[i])), \" \", ex(imag(r[i])))),"
                " E, printf(\"job %%d error\\n\", %d));\n",
                P[jobs[i].poly].expr, (long) jobs[i].digits,
                (int) (budget * 1000), i, i);
    }
    fprintf(f, "quit\n");
    fclose(f);
    printf("running %s -q -f %s (one process, %d jobs) ...\n", cmd, script,
           nj);
    rc = acc_spawn(argv, out, 240, &w, &c);
    printf("  gp exit %d, %.1f s wall\n", rc, w);
    f = fopen(out, "r");
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        int id, cms, wms, reps, nr;
        acc_job *J;
        if (sscanf(line, "job %d %d %d %d %d", &id, &cms, &wms, &reps, &nr) != 5)
            continue;
        if (id < 0 || id >= nj)
            continue;
        J = jobs + id;
        J->gp.ok = -1;
        if (nr != P[J->poly].deg)
            continue;
        for (i = 0; i < nr; i++) {
            fmpz_t m;
            slong k;
            int part;
            fmpz_init(m);
            for (part = 0; part < 2; part++) {
                arb_ptr x = part ? acb_imagref(z + i) : acb_realref(z + i);
                char ms[8192];
                long kk;
                if (fscanf(f, "%8191s %ld", ms, &kk) != 2
                    || fmpz_set_str(m, ms, 10)) {
                    nr = -1;
                    break;
                }
                k = kk;
                arb_set_fmpz(x, m);
                arb_mul_2exp_si(x, x, -k);
            }
            fmpz_clear(m);
            if (nr < 0)
                break;
        }
        if (nr < 0)
            continue;
        J->gp.ok = 1;
        J->gp.reps = reps;
        J->gp.cpu = 1e-3 * cms / reps;
        J->gp.wall = 1e-3 * wms / reps;
        acc_score(&J->gp.dig_rho, &J->gp.dig_roots, z, nr, P + J->poly);
    }
    fclose(f);
    for (i = 0; i < nj; i++)
        if (jobs[i].gp.ok == 0)
            jobs[i].gp.ok = -1; /* missing from the output: error / limit */
    return 0;
}

static void acc_fmt_ms(char *buf, size_t len, double s)
{
    double ms = s * 1e3;
    if (fabs(ms) < 0.1)
        snprintf(buf, len, "%.4f", ms);
    else if (ms < 10)
        snprintf(buf, len, "%.3f", ms);
    else if (ms < 1000)
        snprintf(buf, len, "%.1f", ms);
    else
        snprintf(buf, len, "%.0f", ms);
}

static void acc_fmt_dig(char *buf, size_t len, double d, double cap)
{
    if (d >= cap)
        snprintf(buf, len, ">=%.0f", cap);
    else
        snprintf(buf, len, "%.1f", d < 0 ? 0.0 : d);
}

static void acc_csv_row(FILE *f, const acc_poly *P, const acc_job *J,
                        const char *method, const char *status, double t,
                        double cpu, double wall, int reps, double drho,
                        double droots, long cert, long prec)
{
    fprintf(f, "\"%s\",%ld,%ld,%ld,%s,%s,", P->name, (long) P->deg,
            (long) J->digits, (long) J->bits, method, status);
    if (t >= 0)
        fprintf(f, "%.6e,%.6e,%.6e,%d,", t, cpu, wall, reps);
    else
        fprintf(f, ",,,,");
    if (drho >= 0)
        fprintf(f, "%.1f,%.1f,", drho, droots);
    else
        fprintf(f, ",,");
    if (cert >= 0)
        fprintf(f, "%ld,%ld\n", cert, prec);
    else
        fprintf(f, ",\n");
}

static int acc_main(int argc, char **argv)
{
    static const slong grid_bits[] = { 53, 128, 256, 512, 1024, 4096 };
    const int nb = 6;
    const char *outdir = NULL, *work = "build/accuracy", *gp = NULL,
               *mps = NULL;
    double budget = 0.1, floor_wall = -1, floor_cpu = -1;
    static acc_poly P[ACC_NPOLY];
    static acc_job jobs[ACC_MAXJOBS];
    int nj = 0, i, b, w;
    fmpz_poly_t p;
    rs_radius_t r;
    acb_ptr z;
    char path[4096];
    FILE *ft, *fc, *fd;
    double t_start = now();

    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--accuracy") && i + 1 < argc)
            outdir = argv[++i];
        else if (!strcmp(argv[i], "--work") && i + 1 < argc)
            work = argv[++i];
        else if (!strcmp(argv[i], "--gp") && i + 1 < argc)
            gp = argv[++i];
        else if (!strcmp(argv[i], "--mpsolve") && i + 1 < argc)
            mps = argv[++i];
        else if (!strcmp(argv[i], "--budget") && i + 1 < argc)
            budget = atof(argv[++i]);
        else {
            fprintf(stderr, "usage: bench_radius [--accuracy OUTDIR [--work DIR]"
                    " [--gp CMD] [--mpsolve CMD] [--budget S]]\n");
            return 2;
        }
    }
    if (!outdir) {
        fprintf(stderr, "bench_radius: --accuracy OUTDIR is required with"
                " those options\n");
        return 2;
    }
    setvbuf(stdout, NULL, _IOLBF, 0);
    fmpz_poly_init(p);
    rs_radius_init(r);
    z = _acb_vec_init(64);

    /* polynomials, certified references, GSL baseline */
    for (w = 0; w < ACC_NPOLY; w++) {
        acc_poly *Q = P + w;
        rs_error_t err;
        static double tw[1000], tc[1000];
        double start, w0, c0;
        int n = 0;
        Q->name = acc_make_poly(p, w);
        Q->deg = fmpz_poly_degree(p);
        Q->expr = fmpz_poly_get_str_pretty(p, "x");
        rs_radius_init(Q->ref);
        rs_error_init(err);
        if (rs_radius_fmpz_poly(Q->ref, p, ACC_REF_DIGITS, 0, err) != RS_OK) {
            fprintf(stderr, "reference failed for %s\n", Q->name);
            return 1;
        }
        Q->refdig = (double) got_digits(Q->ref->rho);
        if (Q->refdig > 1300)
            Q->refdig = 1300; /* exact rho: still only 1280 digits asked */
        start = now();
        do {
            w0 = now();
            c0 = cpu_now();
            Q->gsl_rc = rs_radius_double(r, p, err);
            tc[n] = cpu_now() - c0;
            tw[n] = now() - w0;
            n++;
        } while (n < 1000 && (n < 3 || now() - start < budget / 2));
        Q->gsl_cpu = median_of(tc, n);
        Q->gsl_wall = median_of(tw, n);
        if (Q->gsl_rc == RS_OK)
            acc_score(&Q->gsl_dig_rho, &Q->gsl_dig_roots, r->roots, r->nroots,
                      Q);
        rs_error_clear(err);
        /* jobs: the grid, plus 30 and 128 digits for the dense degree 12 */
        for (b = 0; b < nb; b++) {
            slong d = (slong) floor((double) grid_bits[b] * 0.30102999566398120);
            if (w == ACC_DENSE && b == 1)
                jobs[nj++] = (acc_job) { .poly = w, .digits = 30, .bits = 0 };
            if (w == ACC_DENSE && b == 3)
                jobs[nj++] = (acc_job) { .poly = w, .digits = 128, .bits = 0 };
            jobs[nj++] = (acc_job) { .poly = w, .digits = d,
                                     .bits = grid_bits[b] };
        }
    }
    printf("%d polynomials, %d jobs; references at %d digits ready (%.1f s)\n",
           ACC_NPOLY, nj, ACC_REF_DIGITS, now() - t_start);

    /* recstab */
    for (i = 0; i < nj; i++) {
        acc_job *J = jobs + i;
        fmpz_poly_zero(p);
        acc_make_poly(p, J->poly);
        acc_time_rs(J, p, r, budget);
        J->consistent = J->rc == RS_OK && arb_overlaps(r->rho, P[J->poly].ref->rho);
    }
    printf("recstab done (%.1f s)\n", now() - t_start);

    /* PARI/GP */
    if (gp) {
        if (acc_run_gp(gp, jobs, nj, P, work, budget, z))
            printf("gp: could not write/read files in %s\n", work);
        printf("gp done (%.1f s)\n", now() - t_start);
    }

    /* MPSolve */
    if (mps) {
        static double tw[64], tc[64];
        char out[4096];
        char *fargv[] = { (char *) mps, "-j1", "-Ga", "-o", "15", "-Ob", "-p",
                          "x-1", NULL };
        int n;
        snprintf(out, sizeof out, "%s/mpsolve.out", work);
        for (n = 0; n < 20; n++)
            if (acc_spawn(fargv, out, 30, tw + n, tc + n) != 0)
                break;
        if (n == 20) {
            floor_wall = median_of(tw, n);
            floor_cpu = median_of(tc, n);
        }
        for (i = 0; i < nj; i++)
            acc_run_mpsolve(mps, jobs + i, P + jobs[i].poly, work, budget, z);
        printf("mpsolve done (%.1f s); start-up floor (x - 1): %.2f ms CPU, "
               "%.2f ms wall\n", now() - t_start, floor_cpu * 1e3,
               floor_wall * 1e3);
    }

    /* outputs */
    snprintf(path, sizeof path, "%s/accuracy-vs-time.txt", outdir);
    ft = fopen(path, "w");
    snprintf(path, sizeof path, "%s/accuracy-vs-time.csv", outdir);
    fc = fopen(path, "w");
    snprintf(path, sizeof path, "%s/accuracy-vs-time.dat", outdir);
    fd = fopen(path, "w");
    if (!ft || !fc || !fd) {
        fprintf(stderr, "cannot write to %s\n", outdir);
        return 1;
    }
    fprintf(fc, "polynomial,degree,digits,bits,method,status,time_s,cpu_s,"
            "wall_s,reps,digits_rho,digits_roots,certified_digits,prec\n");
    {
        FILE *outs[2] = { stdout, ft };
        int o;
        for (o = 0; o < 2; o++) {
            FILE *f = outs[o];
            if (floor_cpu >= 0)
                fprintf(f, "MPSolve start-up floor (x - 1, 20 processes): "
                        "%.2f ms CPU, %.2f ms wall\n", floor_cpu * 1e3,
                        floor_wall * 1e3);
            fprintf(f, "CPU ms per call (recstab, GSL: median in-process; PARI: "
                    "mean in one gp process; MPSolve: median per process, "
                    "\"-start\" = median of (job - start-up floor) over runs\n"
                    "paired with a run on x - 1; negative = below the noise).\n"
                    "cert = digits recstab certified; rho/roots = digits right "
                    "vs the certified reference (%d digits).  MPSolve "
                    "\"limit\": killed at %d s CPU.\n",
                    ACC_REF_DIGITS, ACC_MPS_LIMIT);
            fprintf(f, "%-23s %3s %5s | %9s %5s | %9s %6s %6s | %9s %9s %6s %6s | %8s %5s %5s\n",
                    "polynomial", "deg", "dig", "recstab", "cert", "PARI",
                    "rho", "roots", "MPSolve", "-start", "rho", "roots",
                    "GSL", "rho", "roots");
        }
    }
    for (i = 0; i < nj; i++) {
        acc_job *J = jobs + i;
        acc_poly *Q = P + J->poly;
        char a[32], cs[32], g1[32], g2[32], g3[32], m1[32], m2[32], m3[32], m4[32],
             s1[32], s2[32], s3[32], line[512];
        acc_fmt_ms(a, sizeof a, J->cpu);
        if (J->rc != RS_OK)
            snprintf(cs, sizeof cs, "err");
        else if (J->cert >= 99999)
            snprintf(cs, sizeof cs, "exact");
        else
            snprintf(cs, sizeof cs, "%ld", (long) J->cert);
        if (J->gp.ok == 1) {
            acc_fmt_ms(g1, sizeof g1, J->gp.cpu);
            acc_fmt_dig(g2, sizeof g2, J->gp.dig_rho, Q->refdig);
            acc_fmt_dig(g3, sizeof g3, J->gp.dig_roots, Q->refdig);
        } else {
            snprintf(g1, sizeof g1, "%s", J->gp.ok ? "fail" : "-");
            g2[0] = g3[0] = '\0';
        }
        if (J->mps.ok == 1) {
            acc_fmt_ms(m1, sizeof m1, J->mps.cpu);
            acc_fmt_ms(m2, sizeof m2, J->mps.net_cpu);
            acc_fmt_dig(m3, sizeof m3, J->mps.dig_rho, Q->refdig);
            acc_fmt_dig(m4, sizeof m4, J->mps.dig_roots, Q->refdig);
        } else {
            snprintf(m1, sizeof m1, "%s", J->mps.ok == -2 ? "limit"
                     : J->mps.ok ? "fail" : "-");
            m2[0] = m3[0] = m4[0] = '\0';
        }
        s1[0] = s2[0] = s3[0] = '\0';
        if (J->bits == 53) {
            acc_fmt_ms(s1, sizeof s1, Q->gsl_cpu);
            if (Q->gsl_rc == RS_OK) {
                acc_fmt_dig(s2, sizeof s2, Q->gsl_dig_rho, Q->refdig);
                acc_fmt_dig(s3, sizeof s3, Q->gsl_dig_roots, Q->refdig);
            } else
                snprintf(s2, sizeof s2, "err");
        }
        snprintf(line, sizeof line,
                 "%-23s %3ld %5ld | %9s %5s | %9s %6s %6s | %9s %9s %6s %6s | %8s %5s %5s%s%s\n",
                 (i == 0 || jobs[i - 1].poly != J->poly) ? Q->name : "",
                 (long) Q->deg, (long) J->digits, a, cs, g1, g2, g3,
                 m1, m2, m3, m4, s1, s2, s3, J->bits ? "" : "  (target)",
                 J->rc != RS_OK ? "  recstab ERROR"
                 : !J->consistent ? "  INCONSISTENT with reference" : "");
        fputs(line, stdout);
        fputs(line, ft);
        acc_csv_row(fc, Q, J, "recstab_certified", J->rc == RS_OK ? "ok" : "error",
                    J->cpu, J->cpu, J->wall, J->reps, -1, -1, (long) J->cert,
                    (long) J->prec);
        if (J->gp.ok)
            acc_csv_row(fc, Q, J, "pari_polroots", J->gp.ok == 1 ? "ok" : "fail",
                        J->gp.ok == 1 ? J->gp.cpu : -1, J->gp.cpu, J->gp.wall,
                        J->gp.reps, J->gp.ok == 1 ? J->gp.dig_rho : -1,
                        J->gp.dig_roots, -1, -1);
        if (J->mps.ok) {
            acc_csv_row(fc, Q, J, "mpsolve_process", J->mps.ok == 1 ? "ok"
                        : J->mps.ok == -2 ? "cpu_limit" : "fail",
                        J->mps.ok == 1 ? J->mps.cpu : -1, J->mps.cpu, J->mps.wall,
                        J->mps.reps, J->mps.ok == 1 ? J->mps.dig_rho : -1,
                        J->mps.dig_roots, -1, -1);
            if (J->mps.ok == 1)
                acc_csv_row(fc, Q, J, "mpsolve_minus_startup", "ok",
                            J->mps.net_cpu, J->mps.net_cpu, J->mps.net_wall,
                            J->mps.reps,
                            J->mps.dig_rho, J->mps.dig_roots, -1, -1);
        }
        if (J->bits == 53)
            acc_csv_row(fc, Q, J, "gsl_double", Q->gsl_rc == RS_OK ? "ok" : "error",
                        Q->gsl_cpu, Q->gsl_cpu, Q->gsl_wall, 0,
                        Q->gsl_rc == RS_OK ? Q->gsl_dig_rho : -1,
                        Q->gsl_dig_roots, -1, -1);
    }

    /* plot data: blocks (gnuplot index) = panels; columns digits, recstab,
       PARI, MPSolve process, MPSolve - start, GSL (ms); '?' = missing.
       Panel 0: geometric mean over all polynomials (a point only when every
       polynomial has a result); then single polynomials; last block:
       digits right, minimum over the polynomials. */
    {
        static const int panel_poly[] = { -1, ACC_DENSE, 7, 9, 12 };
        int pn;
        fprintf(fd, "# digits recstab_ms pari_ms mpsolve_proc_ms "
                "mpsolve_minus_start_ms gsl_ms\n");
        for (pn = 0; pn < 5; pn++) {
            fprintf(fd, "# panel %d: %s\n", pn,
                    panel_poly[pn] < 0 ? "geometric mean over all polynomials"
                                       : P[panel_poly[pn]].name);
            for (b = 0; b < nb; b++) {
                double s[5] = { 0, 0, 0, 0, 0 };
                int cnt[5] = { 0, 0, 0, 0, 0 }, np = 0, k;
                slong d = 0;
                for (i = 0; i < nj; i++) {
                    acc_job *J = jobs + i;
                    if (J->bits != grid_bits[b])
                        continue;
                    if (panel_poly[pn] >= 0 && J->poly != panel_poly[pn])
                        continue;
                    d = J->digits;
                    np++;
                    if (J->rc == RS_OK) { s[0] += log(J->cpu); cnt[0]++; }
                    if (J->gp.ok == 1) { s[1] += log(J->gp.cpu); cnt[1]++; }
                    if (J->mps.ok == 1) {
                        s[2] += log(J->mps.cpu); cnt[2]++;
                        /* below ~0.1 ms a process-level difference is
                           noise: drawn at 0.1 ms */
                        s[3] += log(fmax(J->mps.net_cpu, 1e-4)); cnt[3]++;
                    }
                    if (b == 0) { s[4] += log(P[J->poly].gsl_cpu); cnt[4]++; }
                }
                fprintf(fd, "%ld", (long) d);
                for (k = 0; k < 5; k++) {
                    if (cnt[k] == np && np > 0)
                        fprintf(fd, " %.6g", 1e3 * exp(s[k] / cnt[k]));
                    else
                        fprintf(fd, " ?");
                }
                fprintf(fd, "\n");
            }
            fprintf(fd, "\n\n");
        }
        fprintf(fd, "# panel 5: digits right (rho), minimum over polynomials:"
                " digits recstab_certified pari mpsolve gsl\n");
        for (b = 0; b < nb; b++) {
            double mn[4] = { 1e9, 1e9, 1e9, 1e9 };
            int miss[4] = { 0, 0, 0, 0 }, k;
            slong d = 0;
            for (i = 0; i < nj; i++) {
                acc_job *J = jobs + i;
                if (J->bits != grid_bits[b])
                    continue;
                d = J->digits;
                if (J->rc == RS_OK) mn[0] = fmin(mn[0], (double) J->cert);
                else miss[0] = 1;
                if (J->gp.ok == 1) mn[1] = fmin(mn[1], J->gp.dig_rho);
                else miss[1] = 1;
                if (J->mps.ok == 1) mn[2] = fmin(mn[2], J->mps.dig_rho);
                else miss[2] = 1;
                if (b == 0 && P[J->poly].gsl_rc == RS_OK)
                    mn[3] = fmin(mn[3], P[J->poly].gsl_dig_rho);
                else
                    miss[3] = 1;
            }
            fprintf(fd, "%ld", (long) d);
            for (k = 0; k < 4; k++) {
                if (!miss[k] && mn[k] < 1e9)
                    fprintf(fd, " %.1f", fmin(mn[k], 1300.0));
                else
                    fprintf(fd, " ?");
            }
            fprintf(fd, "\n");
        }
    }

    /* targets */
    {
        FILE *outs[2] = { stdout, ft };
        int o;
        for (i = 0; i < nj; i++) {
            acc_job *J = jobs + i;
            if (J->poly != ACC_DENSE || J->bits)
                continue;
            for (o = 0; o < 2; o++) {
                if (J->digits == 30)
                    fprintf(outs[o], "\ntarget 1: dense degree 12, 30 certified "
                            "digits in-process in < 1 ms: %.3f ms CPU (%.3f ms "
                            "wall), certified %ld digits -> %s\n",
                            J->cpu * 1e3, J->wall * 1e3, (long) J->cert,
                            J->rc == RS_OK && J->cert >= 30 && J->cpu < 1e-3
                            ? "met" : "NOT met");
                else if (J->gp.ok == 1)
                    fprintf(outs[o], "target 2: dense degree 12, 128 digits, "
                            "no slower than PARI polroots: recstab %.3f ms vs "
                            "PARI %.3f ms CPU (ratio %.2f) -> %s\n",
                            J->cpu * 1e3, J->gp.cpu * 1e3, J->cpu / J->gp.cpu,
                            J->cpu <= J->gp.cpu ? "met" : "NOT met");
                else
                    fprintf(outs[o], "target 2: PARI not run\n");
            }
        }
        /* the 128-bit level over every polynomial */
        {
            int faster = 0, tot = 0;
            double worst = 0;
            for (i = 0; i < nj; i++) {
                acc_job *J = jobs + i;
                if (J->bits != 128 || J->gp.ok != 1)
                    continue;
                tot++;
                faster += J->cpu <= J->gp.cpu;
                worst = fmax(worst, J->cpu / J->gp.cpu);
            }
            for (o = 0; o < 2 && tot; o++)
                fprintf(outs[o], "at 38 digits (128 bits): recstab no slower "
                        "than PARI on %d of %d polynomials; worst ratio "
                        "recstab/PARI %.2f\n", faster, tot, worst);
        }
    }
    fclose(ft);
    fclose(fc);
    fclose(fd);
    printf("wrote %s/accuracy-vs-time.{txt,csv,dat} (%.1f s total)\n", outdir,
           now() - t_start);

    for (w = 0; w < ACC_NPOLY; w++) {
        rs_radius_clear(P[w].ref);
        flint_free(P[w].expr);
    }
    _acb_vec_clear(z, 64);
    rs_radius_clear(r);
    fmpz_poly_clear(p);
    flint_cleanup();
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 1)
        return acc_main(argc, argv);
    return classic_main();
}
