/* bench_cosim_fast.c -- what one point of a co-simulation map costs, by
 * stage, to size a double-precision fast path (issue 14 part 3).
 *
 * Build and run (from the repository root, after make all):
 *   gcc -std=c11 -D_POSIX_C_SOURCE=200809L -O2 -Iinclude -Isrc -I/usr/include/flint \
 *       bench/bench_cosim_fast.c build/librecstab.a -o /tmp/bench_cosim_fast \
 *       -lflint-arb -lflint -lgsl -lgslcblas -ljansson -lmpfr -lgmp -lm -fopenmp && /tmp/bench_cosim_fast
 *
 * Li et al.'s force/force model, explicit k = 1, c1 = 101/100, d1 = 1/5,
 * every alpha 1 (cases/li-explicit-k1.case), acc1 on 64 values in [0, 3]:
 * median in-process CPU time per point (one thread) of
 *   certified   rs_cosim_radius(6 digits): today's map point
 *   transition  the one-step map alone (matrix exponentials, Arb, 64 bits)
 *   double      transition at 64 bits -> doubles -> GSL eigenvalues: an
 *               uncertified estimate of the radius (what a fast path starts from)
 *   eig64       transition at 64 bits -> acb_mat_approx_eig_qr and
 *               acb_mat_eig_simple at 64 bits: a low-precision certification
 *               of the eigenvalues
 *   fast Arb    rs_cosim_fast_radius (64 bits: the Arb Gershgorin route)
 *   dbl map     rs_cosim_dbl_transition: the one-step map in interval
 *               double (cosim_dbl.h; the model set before the clock starts:
 *               a map evaluates it from its numeric forms, cosim_forms.h)
 *   dbl radius  rs_cosim_dbl_radius: the certified radius in interval
 *               double (the maps' first route)
 * and how often the double estimate's verdict (rho < 1) agrees with the
 * certified one.  No assertions: this only measures. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <acb_mat.h>
#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_eigen.h>
#include "recstab/cosim.h"
#include "numeric/cosim_fast.h"
#include "numeric/cosim_dbl.h"

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);   /* CPU: the machine is shared */
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmpd(const void *a, const void *b)
{
    double x = *(const double *) a, y = *(const double *) b;
    return (x > y) - (x < y);
}

enum { NPTS = 64, REPS = 5, NST = 7 };

/* the uncertified double radius of M (GSL Hessenberg-QR), or -1 */
static double rho_double(const arb_mat_t M, gsl_matrix *G, gsl_vector_complex *ev, gsl_eigen_nonsymm_workspace *w)
{
    slong i, j, d = arb_mat_nrows(M);
    double rho = 0;
    for (i = 0; i < d; i++)
        for (j = 0; j < d; j++) gsl_matrix_set(G, i, j, arf_get_d(arb_midref(arb_mat_entry(M, i, j)), ARF_RND_NEAR));
    if (gsl_eigen_nonsymm(G, ev, w) != 0) return -1;
    for (i = 0; i < d; i++) {
        double a = gsl_complex_abs(gsl_vector_complex_get(ev, i));
        if (a > rho) rho = a;
    }
    return rho;
}

int main(void)
{
    rs_cosim_t cs;
    rs_radius_t r;
    rs_error_t err;
    fmpq_t c1, d1, one, acc;
    double t[NST][NPTS * REPS], sum_rho = 0;
    rs_cosim_dbl_t dm;
    rs_radius_t rf;
    int k, p, agree = 0, certified = 0;
    slong d;
    fmpq_init(c1); fmpq_init(d1); fmpq_init(one); fmpq_init(acc);
    fmpq_set_si(c1, 101, 100);
    fmpq_set_si(d1, 1, 5);
    fmpq_one(one);
    rs_cosim_init(cs, 2, 2);
    rs_radius_init(r);
    rs_radius_init(rf);
    rs_cosim_dbl_init(dm);
    for (p = 0; p < NPTS; p++) {
        arb_mat_t M;
        acb_mat_t A, R;
        acb_ptr E, Ea;
        gsl_matrix *G;
        gsl_vector_complex *ev;
        gsl_eigen_nonsymm_workspace *w;
        double rd = 0, t0;
        fmpq_set_si(acc, 3 * p, NPTS - 1);
        rs_cosim_li_ff(cs, c1, d1, one, one, one, acc, one, err);
        cs->method = RS_COSIM_EXPLICIT;
        cs->order = 1;
        d = rs_cosim_transition_dim(cs);
        arb_mat_init(M, d, d);
        acb_mat_init(A, d, d);
        acb_mat_init(R, d, d);
        E = _acb_vec_init(d);
        Ea = _acb_vec_init(d);
        G = gsl_matrix_alloc(d, d);
        ev = gsl_vector_complex_alloc(d);
        w = gsl_eigen_nonsymm_alloc(d);
        for (k = 0; k < REPS; k++) {
            int rc;
            t0 = now();
            rc = rs_cosim_radius(r, cs, 6, 1024, err);
            t[0][p * REPS + k] = now() - t0;
            t0 = now();
            rs_cosim_transition(M, cs, 64, err);
            t[1][p * REPS + k] = now() - t0;
            t0 = now();
            rs_cosim_transition(M, cs, 64, err);
            rd = rho_double(M, G, ev, w);
            t[2][p * REPS + k] = now() - t0;
            t0 = now();
            rs_cosim_transition(M, cs, 64, err);
            acb_mat_set_arb_mat(A, M);
            acb_mat_approx_eig_qr(Ea, NULL, R, A, NULL, 0, 64);
            acb_mat_eig_simple(E, NULL, NULL, A, Ea, R, 64);
            t[3][p * REPS + k] = now() - t0;
            t0 = now();
            rs_cosim_fast_radius(rf, cs, 64, err);
            t[4][p * REPS + k] = now() - t0;
            rs_cosim_dbl_set_cosim(dm, cs, err);   /* a map builds it from its numeric forms */
            t0 = now();
            {
                double Tm[64], Tr[64];
                rs_cosim_dbl_transition(Tm, Tr, dm);
            }
            t[5][p * REPS + k] = now() - t0;
            t0 = now();
            rs_cosim_dbl_radius(rf, dm);
            t[6][p * REPS + k] = now() - t0;
            if (k == 0 && rc == RS_OK) {
                arb_t o;
                arb_init(o);
                arb_one(o);
                if (arb_lt(r->upper, o) || arb_gt(r->lower, o)) {
                    certified++;
                    if ((rd < 1) == arb_lt(r->upper, o)) agree++;
                }
                sum_rho += rd;
                arb_clear(o);
            }
        }
        gsl_eigen_nonsymm_free(w);
        gsl_vector_complex_free(ev);
        gsl_matrix_free(G);
        _acb_vec_clear(E, d);
        _acb_vec_clear(Ea, d);
        acb_mat_clear(R);
        acb_mat_clear(A);
        arb_mat_clear(M);
    }
    {
        const char *names[NST] = {"certified (full radius)", "transition (64 bits)", "double estimate",
                                  "eig64 certification", "fast Arb radius", "dbl map (interval double)",
                                  "dbl radius (interval double)"};
        for (k = 0; k < NST; k++) {
            qsort(t[k], NPTS * REPS, sizeof(double), cmpd);
            printf("%-28s median %8.1f us/point  (%7.0f points/s)\n", names[k], 1e6 * t[k][NPTS * REPS / 2],
                   1.0 / t[k][NPTS * REPS / 2]);
        }
    }
    printf("transition dimension %ld; double verdict agrees with the certified one at %d of %d decided points "
           "(mean double rho %.6f)\n", (long) d, agree, certified, sum_rho / NPTS);
    rs_radius_clear(r);
    rs_radius_clear(rf);
    rs_cosim_dbl_clear(dm);
    rs_cosim_clear(cs);
    fmpq_clear(c1); fmpq_clear(d1); fmpq_clear(one); fmpq_clear(acc);
    flint_cleanup();
    return 0;
}
