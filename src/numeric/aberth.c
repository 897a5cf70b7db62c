/* aberth.c -- Aberth-Ehrlich root approximations in hardware double,
 * started from Newton-polygon points (Bini 1996, "Numerical computation of
 * polynomial zeros by means of Aberth's method", Numer. Algorithms 13).
 * Uncertified: the caller certifies the result in Arb. */
#include <complex.h>
#include <float.h>
#include <math.h>
#include "recstab/radius.h"

/* Bini's starting points: for each edge (i, j) of the upper convex hull of
 * (k, log|a_k|), j - i points on the circle of radius (|a_i|/|a_j|)^(1/(j-i))
 * (the moduli of that many roots are close to it), spread in angle. */
static void _rs_aberth_start(double complex *z, const double *a, slong d)
{
    slong *h = flint_malloc((d + 1) * sizeof(slong));
    double *y = flint_malloc((d + 1) * sizeof(double));
    slong nh = 0, i, k, idx = 0;

    for (i = 0; i <= d; i++) {
        if (a[i] == 0.0)
            continue;
        y[i] = log(fabs(a[i]));
        /* drop h[nh-1] while it lies on or below the chord h[nh-2] -> i */
        while (nh >= 2 && (y[h[nh - 1]] - y[h[nh - 2]]) * (double) (i - h[nh - 2])
                              <= (y[i] - y[h[nh - 2]]) * (double) (h[nh - 1] - h[nh - 2]))
            nh--;
        h[nh++] = i;
    }
    for (k = 0; k + 1 < nh; k++) {
        slong m = h[k + 1] - h[k];
        double r = exp((y[h[k]] - y[h[k + 1]]) / (double) m);
        for (i = 0; i < m; i++) {
            double t = 6.283185307179586 * ((double) i / (double) m + (double) h[k] / (double) d) + 0.4;
            z[idx++] = r * cexp(I * t);
        }
    }
    flint_free(h);
    flint_free(y);
}

/* Newton correction p(x)/p'(x) and whether |p(x)| is at the level of its
 * rounding error (a backward-stable root).  |x| > 1 evaluates the reversed
 * polynomial at 1/x so that x^d cannot overflow:
 * p(x) = x^d q(w), w = 1/x, p'/p = w (d - w q'(w)/q(w)). */
static double complex _rs_aberth_newton(int *conv, const double *a, slong d,
                                        double complex x)
{
    double complex p = 0, dp = 0, w;
    double s = 0, ax;
    slong i;

    if (cabs(x) <= 1.0) {
        ax = cabs(x);
        for (i = d; i >= 0; i--) {
            dp = dp * x + p;
            p = p * x + a[i];
            s = s * ax + fabs(a[i]);
        }
        *conv = cabs(p) <= 4.0 * DBL_EPSILON * (double) (d + 1) * s;
        return dp == 0 ? 0 : p / dp;
    }
    w = 1.0 / x;
    ax = cabs(w);
    for (i = 0; i <= d; i++) {
        dp = dp * w + p;
        p = p * w + a[i];
        s = s * ax + fabs(a[i]);
    }
    *conv = cabs(p) <= 4.0 * DBL_EPSILON * (double) (d + 1) * s;
    if (p == 0)
        return 0;
    return 1.0 / (w * ((double) d - w * dp / p));
}

int rs_radius_aberth_d(double *zr, const double *a, slong d, slong maxiter)
{
    double complex *z = flint_malloc(d * sizeof(double complex));
    char *done = flint_calloc(d, 1);
    slong it, i, j, left = d;
    int ok;

    _rs_aberth_start(z, a, d);
    for (it = 0; it < maxiter && left > 0; it++) {
        for (i = 0; i < d; i++) {
            double complex N, S = 0, c;
            int conv;
            if (done[i])
                continue;
            N = _rs_aberth_newton(&conv, a, d, z[i]);
            for (j = 0; j < d; j++)
                if (j != i)
                    S += 1.0 / (z[i] - z[j]);
            c = N / (1.0 - N * S);
            if (isfinite(creal(c)) && isfinite(cimag(c)))
                z[i] -= c;
            if (conv) {
                done[i] = 1;
                left--;
            }
        }
    }
    ok = left == 0;
    for (i = 0; i < d; i++) {
        zr[2 * i] = creal(z[i]);
        zr[2 * i + 1] = cimag(z[i]);
        if (!isfinite(zr[2 * i]) || !isfinite(zr[2 * i + 1]))
            ok = 0;
    }
    flint_free(z);
    flint_free(done);
    return ok ? (int) it : -1;
}
