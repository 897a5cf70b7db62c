/* closed_forms.h -- polynomials whose roots are known in closed form (each
 * worked out in its comment), shared by the counting suites (rootcount,
 * Routh, Schur-Cohn) so that every method is held to the same table. */
#ifndef RECSTAB_TEST_CLOSED_FORMS_H
#define RECSTAB_TEST_CLOSED_FORMS_H
#include <flint/fmpz_poly.h>
#include "recstab/rootcount.h"

/* p from integer coefficients, highest degree first */
static inline void poly_set(fmpz_poly_t p, slong deg, const long *c)
{
    slong i;
    fmpz_poly_zero(p);
    for (i = 0; i <= deg; i++)
        fmpz_poly_set_coeff_si(p, deg - i, c[i]);
}

typedef struct {
    const char *name;
    slong deg;
    long c[8];                 /* highest first */
    slong in, on, out, at1, atm1;
    slong mult1, mult2;        /* distinct circle roots of multiplicity 1, 2 */
    rs_status_t status;
} closed_case;

/* Expected values: roots in closed form, worked out in each comment. */
static const closed_case cases[] = {
    /* lambda - 1/2: root 1/2 */
    {"2l-1", 1, {2, -1}, 1, 0, 0, 0, 0, 0, 0, RS_STATUS_STABLE},
    /* lambda - 2: root 2 */
    {"l-2", 1, {1, -2}, 0, 0, 1, 0, 0, 0, 0, RS_STATUS_UNSTABLE},
    /* lambda^2 + 1: +-i */
    {"l2+1", 2, {1, 0, 1}, 0, 2, 0, 0, 0, 2, 0, RS_STATUS_MARGINAL},
    /* (lambda - 1)^2: double root 1 */
    {"(l-1)^2", 2, {1, -2, 1}, 0, 2, 0, 2, 0, 0, 1, RS_STATUS_UNSTABLE},
    /* (lambda + 1)(3 lambda - 1): -1 and 1/3 */
    {"(l+1)(3l-1)", 2, {3, 2, -1}, 1, 1, 0, 0, 1, 1, 0, RS_STATUS_MARGINAL},
    /* lambda^2 - lambda + 1: e^{+-i pi/3} */
    {"l2-l+1", 2, {1, -1, 1}, 0, 2, 0, 0, 0, 2, 0, RS_STATUS_MARGINAL},
    /* (lambda^2 + 1)^2: +-i double */
    {"(l2+1)^2", 4, {1, 0, 2, 0, 1}, 0, 4, 0, 0, 0, 0, 2, RS_STATUS_UNSTABLE},
    /* lambda^3: triple root 0 */
    {"l3", 3, {1, 0, 0, 0}, 3, 0, 0, 0, 0, 0, 0, RS_STATUS_STABLE},
    /* forward Euler, x'' = -w^2 x, w = 1/2, times 4: 4l^2 - 8l + 5,
     * roots 1 +- i/2, |.|^2 = 5/4 */
    {"fe w=1/2", 2, {4, -8, 5}, 0, 0, 2, 0, 0, 0, 0, RS_STATUS_UNSTABLE},
    /* backward Euler (1+w^2) l^2 - 2 l + 1, w = 1/2, times 4: 5l^2 - 8l + 4,
     * roots (4 +- 2i)/5, |.|^2 = 4/5 */
    {"be w=1/2", 2, {5, -8, 4}, 2, 0, 0, 0, 0, 0, 0, RS_STATUS_STABLE},
    /* backward Euler w = 1: 2l^2 - 2l + 1, roots (1 +- i)/2 */
    {"be w=1", 2, {2, -2, 1}, 2, 0, 0, 0, 0, 0, 0, RS_STATUS_STABLE},
    /* trapezoid (4+w^2) l^2 - (8-2w^2) l + (4+w^2), w = 1/2, times 4:
     * 17l^2 - 30l + 17, product of roots 1, discriminant 900-1156 < 0 */
    {"trap w=1/2", 2, {17, -30, 17}, 0, 2, 0, 0, 0, 2, 0, RS_STATUS_MARGINAL},
    /* central difference l^2 - (2-w^2) l + 1, w = 2: (l+1)^2 */
    {"cd w=2", 2, {1, 2, 1}, 0, 2, 0, 0, 2, 0, 1, RS_STATUS_UNSTABLE},
    /* central difference w = 1: l^2 - l + 1, e^{+-i pi/3} */
    {"cd w=1", 2, {1, -1, 1}, 0, 2, 0, 0, 0, 2, 0, RS_STATUS_MARGINAL},
    /* lambda (lambda^2 + 1): 0, +-i */
    {"l3+l", 3, {1, 0, 1, 0}, 1, 2, 0, 0, 0, 2, 0, RS_STATUS_MARGINAL},
    /* lambda^4 - 1: 1, -1, +-i */
    {"l4-1", 4, {1, 0, 0, 0, -1}, 0, 4, 0, 1, 1, 4, 0, RS_STATUS_MARGINAL},
    /* (lambda - 2)(2 lambda - 1): reciprocal pair 2, 1/2 */
    {"(l-2)(2l-1)", 2, {2, -5, 2}, 1, 0, 1, 0, 0, 0, 0, RS_STATUS_UNSTABLE},
    /* 7: constant, no roots */
    {"7", 0, {7}, 0, 0, 0, 0, 0, 0, 0, RS_STATUS_STABLE},
};

#endif
