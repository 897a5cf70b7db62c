/* typed_roots.c -- the typed C API on a polynomial built with FLINT: where
 * its roots lie relative to the unit circle, by Schur-Cohn (rs_jury_*) and
 * by exact factorisation + certified isolation (rs_rootcount_factor), two
 * independent methods that must agree.
 *
 * Expected verdicts from the roots in closed form:
 *   2 l^2 - 2 l + 1: l = (1 +- i)/2, |l|^2 = 1/2  -> stable (2 inside)
 *   l^2 + 1:         l = +-i, simple               -> marginal (2 on)
 *   l^2 + 2 l + 1:   l = -1 twice                  -> unstable (double root on the circle) */
#include <stdio.h>
#include <recstab/recstab.h>

static int check(const char *name, const slong *c, slong len, rs_status_t want)
{
    fmpz_poly_t p;
    rs_jury_t j;
    rs_rootcount_t rc;
    rs_error_t err;
    slong k;
    int ok = 0;
    fmpz_poly_init(p);
    for (k = 0; k < len; k++) fmpz_poly_set_coeff_si(p, k, c[k]);
    rs_jury_init(j);
    rs_rootcount_init(rc);
    rs_error_init(err);
    if (rs_jury_fmpz_poly(j, p, err) == RS_OK && rs_rootcount_factor(rc, p, err) == RS_OK) {
        ok = rs_rootcount_equal(j->count, rc) && rs_rootcount_status(rc) == want;
        printf("%-16s inside %ld, on %ld, outside %ld: %s (%s)\n", name, (long) rc->inside, (long) rc->on,
               (long) rc->outside, rs_status_name(rs_rootcount_status(rc)),
               rs_rootcount_equal(j->count, rc) ? "Schur-Cohn agrees" : "Schur-Cohn DISAGREES");
    } else {
        char msg[2 * RS_ERROR_MSG_LEN];
        rs_error_format(msg, sizeof msg, err);
        printf("%s: error %s\n", name, msg);
    }
    rs_error_clear(err);
    rs_rootcount_clear(rc);
    rs_jury_clear(j);
    fmpz_poly_clear(p);
    return ok;
}

int main(void)
{
    static const slong a[] = {1, -2, 2}, b[] = {1, 0, 1}, c[] = {1, 2, 1};
    int ok = 1;
    ok &= check("2l^2 - 2l + 1", a, 3, RS_STATUS_STABLE);
    ok &= check("l^2 + 1", b, 3, RS_STATUS_MARGINAL);
    ok &= check("l^2 + 2l + 1", c, 3, RS_STATUS_UNSTABLE);
    puts(ok ? "typed_roots: verdicts as expected" : "typed_roots: UNEXPECTED verdict");
    flint_cleanup();
    return ok ? 0 : 1;
}
