/* outer.c -- what the certified root balls of a radius say beyond rho.
 *
 * rs_radius_count_balls: the count of the verdict read off the balls.  At
 * degree 500 the exact Routh array costs 15-45 s while the balls are already
 * there; when each of them lies strictly inside or strictly outside the
 * unit circle they count the roots rigorously, and the caller checks that
 * count against Schur-Cohn (an exact method on other arithmetic). */
#include "recstab/radius.h"

int rs_radius_count_balls(rs_rootcount_t rc, const rs_radius_t r, slong degree)
{
    slong i, in = 0, out = 0, prec = FLINT_MAX(r->prec, 64);
    arb_t a, one;
    int ok = 1;

    /* only isolating balls, one per root with multiplicity: a cluster ball
     * repeated k times would do as well, but is left to the exact side */
    if (!r->isolated || r->roots == NULL || r->nroots != degree || degree < 1)
        return 0;
    arb_init(a);
    arb_init(one);
    arb_one(one);
    for (i = 0; i < r->nroots && ok; i++) {
        acb_abs(a, r->roots + i, prec);
        if (arb_lt(a, one))
            in++;
        else if (arb_gt(a, one))
            out++;
        else
            ok = 0;   /* this ball meets the circle: the balls decide nothing */
    }
    arb_clear(a);
    arb_clear(one);
    if (!ok)
        return 0;
    rs_rootcount_init(rc);
    rc->degree = degree;
    rc->inside = in;
    rc->outside = out;
    return 1;
}
