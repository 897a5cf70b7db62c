/* modes.c -- continuous-time modes of certified roots; see modes.h. */
#include "numeric/modes.h"

void rs_modes_continuous(arb_t sigma, arb_t omega, arb_t mag, arb_t zeta, const acb_t root, const arb_t h,
                         slong prec)
{
    acb_t c;
    acb_init(c);
    acb_log(c, root, prec);
    acb_div_arb(c, c, h, prec);
    arb_set(sigma, acb_realref(c));
    arb_set(omega, acb_imagref(c));
    if (arb_contains_zero(acb_imagref(root)) && arb_is_negative(acb_realref(root))) {
        /* a root on (or a ball across) the negative real axis: the principal
         * arg is +-pi up to the ball, and acb_log returns [-pi, pi] ("0e+1",
         * damping nan); |omega| h = pi - atan(|im|/|re|) encloses it (the sign
         * is the +- of sigma +- i omega) */
        arb_t t, u;
        arb_init(t); arb_init(u);
        arb_abs(t, acb_imagref(root));
        arb_abs(u, acb_realref(root));
        arb_div(t, t, u, prec);
        arb_atan(t, t, prec);
        arb_const_pi(omega, prec);
        arb_sub(omega, omega, t, prec);
        arb_div(omega, omega, h, prec);
        acb_abs(u, root, prec);
        arb_log(sigma, u, prec);
        arb_div(sigma, sigma, h, prec);
        arb_clear(t); arb_clear(u);
    }
    arb_hypot(mag, sigma, omega, prec);
    arb_div(zeta, sigma, mag, prec);
    arb_neg(zeta, zeta);
    acb_clear(c);
}

void rs_modes_principal(int *principal, const rs_radius_t rr, const arb_t h, arb_srcptr refs,
                        slong nref, slong prec)
{
    slong i, k;
    for (i = 0; i < rr->nroots; i++) principal[i] = 0;
    for (k = 0; k < nref; k++) {
        acb_t target, d, cj;
        arb_t best, dist;
        slong bi = -1;
        acb_init(target); acb_init(d); acb_init(cj);
        arb_init(best); arb_init(dist);
        arb_mul(acb_imagref(target), refs + k, h, prec);
        acb_exp(target, target, prec);
        for (i = 0; i < rr->nroots; i++) {
            if (principal[i] || arf_sgn(arb_midref(acb_imagref(rr->roots + i))) < 0) continue;
            acb_sub(d, rr->roots + i, target, prec);
            acb_abs(dist, d, prec);
            if (bi < 0 || arf_cmp(arb_midref(dist), arb_midref(best)) < 0) { bi = i; arb_set(best, dist); }
        }
        if (bi >= 0) {
            principal[bi] = (int) (k + 1);
            acb_conj(cj, rr->roots + bi);
            for (i = 0; i < rr->nroots && !arb_is_zero(acb_imagref(rr->roots + bi)); i++)
                if (i != bi && !principal[i] && acb_overlaps(cj, rr->roots + i)) {
                    principal[i] = (int) (k + 1);
                    break;
                }
        }
        acb_clear(target); acb_clear(d); acb_clear(cj);
        arb_clear(best); arb_clear(dist);
    }
}
