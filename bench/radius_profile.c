/* radius_profile.c -- where the time of `radius` goes at high degree.
 *
 *   make all && gcc -std=c11 -D_POSIX_C_SOURCE=200809L -O2 -Iinclude \
 *       -I/usr/include/flint bench/radius_profile.c build/librecstab.a \
 *       -o /tmp/radius_profile -fopenmp -lflint-arb -lflint -lgsl -lgslcblas \
 *       -ljansson -lmpfr -lgmp -lm
 *   /tmp/radius_profile DIGITS < coefficients     (c_0 .. c_d, one per line)
 *
 * Prints CPU seconds (CLOCK_PROCESS_CPUTIME_ID, one run each: the machine is
 * shared, wall time is not the work) of: the squarefree
 * factorisation, the GSL double roots, rs_radius_double, the default certified
 * radius rs_radius_fmpz_poly, the count read off its balls
 * (rs_radius_count_balls), and the exact counts (rs_routh_int_count, the
 * rational rs_routh_fmpz_poly -- skipped with NO_RATIONAL_ROUTH=1 --, and
 * rs_jury_fmpz_poly). */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <flint/fmpz_poly_factor.h>
#include "recstab/radius.h"
#include "recstab/routh.h"
#include "recstab/jury.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double) t.tv_sec + 1e-9 * (double) t.tv_nsec;
}

int main(int argc, char **argv)
{
    fmpz_poly_t p;
    fmpz_poly_factor_t fac;
    rs_radius_t r;
    rs_routh_t ro;
    rs_jury_t ju;
    rs_error_t err;
    long c, i = 0, digits = argc > 1 ? atol(argv[1]) : 30;
    double t;
    int rc;

    fmpz_poly_init(p);
    while (scanf("%ld", &c) == 1)
        fmpz_poly_set_coeff_si(p, i++, c);
    printf("degree %ld digits %ld\n", (long) fmpz_poly_degree(p), digits);
    fmpz_poly_factor_init(fac);
    t = now(); fmpz_poly_factor_squarefree(fac, p);
    printf("  squarefree factorisation   %8.3f s (%ld factors)\n", now() - t, (long) fac->num);
    fmpz_poly_factor_clear(fac);
    rs_radius_init(r);
    t = now(); rc = rs_radius_double(r, p, err);
    printf("  rs_radius_double (GSL)     %8.3f s rc %d\n", now() - t, rc);
    t = now(); rc = rs_radius_fmpz_poly(r, p, digits, 0, err);
    printf("  rs_radius_fmpz_poly        %8.3f s rc %d, %ld bits\n", now() - t, rc, (long) r->prec);
    {
        rs_rootcount_t rb;
        slong in = -1, out = -1;
        t = now(); rc = rs_radius_count_balls(&in, &out, r, fmpz_poly_degree(p));
        printf("  count from the balls       %8.3f s decisive %d (in %ld, out %ld)\n", now() - t, rc,
               (long) in, (long) out);
        t = now(); rc = rs_routh_int_count(rb, p, err);
        printf("  exact count: routh int PRS %8.3f s rc %d\n", now() - t, rc);
    }
    rs_radius_clear(r);
    if (getenv("NO_RATIONAL_ROUTH") != NULL)
        goto jury;
    rs_routh_init(ro);
    t = now(); rc = rs_routh_fmpz_poly(ro, p, err);
    printf("  exact count: routh         %8.3f s rc %d\n", now() - t, rc);
    rs_routh_clear(ro);
jury:
    rs_jury_init(ju);
    t = now(); rc = rs_jury_fmpz_poly(ju, p, err);
    printf("  exact count: schur-cohn    %8.3f s rc %d\n", now() - t, rc);
    rs_jury_clear(ju);
    fmpz_poly_clear(p);
    flint_cleanup();
    return 0;
}
