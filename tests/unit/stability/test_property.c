/* test_property.c -- the three exact counting methods (Routh on the
 * bilinear transform, Schur-Cohn, factorisation + certified isolation)
 * against polynomials whose root locations are known by construction, and
 * against each other on plain random polynomials.
 *
 * Iterations: env RS_PROPERTY_N (default 10000 planted + 10000/2 random, about 1.5 s);
 * seed: env RS_PROPERTY_SEED (default 20240607). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testutil.h"
#include <flint/fmpz_poly.h>
#include "recstab/rootcount.h"
#include "recstab/routh.h"
#include "recstab/jury.h"
#include "recstab/bilinear.h"

static unsigned long long rng_state;

/* how often each singular case was met, to show the property test reaches
 * them: Routh events by kind, regular Schur-Cohn tables */
static long seen_event[4], seen_regular_table, seen_repeated_zero_row;

static unsigned long long rng_next(void)
{
    /* splitmix64: reproducible on every platform */
    unsigned long long z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* uniform in [lo, hi] */
static long rng_range(long lo, long hi)
{
    return lo + (long) (rng_next() % (unsigned long long) (hi - lo + 1));
}

static long env_long(const char *name, long def)
{
    const char *s = getenv(name);
    return (s != NULL && *s != '\0') ? strtol(s, NULL, 10) : def;
}

/* distinct circle roots of the construction, keyed by cos(theta) = num/den
 * in lowest terms (lambda = 1: 1/1, lambda = -1: -1/1) */
typedef struct { long num, den, mult; } circle_key;

typedef struct {
    rs_rootcount_t rc;
    circle_key keys[64];
    int nkeys;
} expect_t;

static long gcd_l(long a, long b)
{
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    while (b != 0) { long t = a % b; a = b; b = t; }
    return a;
}

static void expect_circle(expect_t *ex, long num, long den, long mult)
{
    long g = gcd_l(num, den);
    int i;
    num /= g;
    den /= g;
    for (i = 0; i < ex->nkeys; i++)
        if (ex->keys[i].num == num && ex->keys[i].den == den) {
            ex->keys[i].mult += mult;
            return;
        }
    ex->keys[ex->nkeys].num = num;
    ex->keys[ex->nkeys].den = den;
    ex->keys[ex->nkeys].mult = mult;
    ex->nkeys++;
}

static void expect_finish(expect_t *ex)
{
    int i;
    for (i = 0; i < ex->nkeys; i++) {
        const circle_key *k = ex->keys + i;
        long slot = k->mult < RS_ROOTCOUNT_MAXMULT ? k->mult
                                                   : RS_ROOTCOUNT_MAXMULT - 1;
        if (k->den == 1 && k->num == 1) {
            ex->rc->at_one += k->mult;
            ex->rc->on += k->mult;
            ex->rc->on_mult[slot] += 1;
        } else if (k->den == 1 && k->num == -1) {
            ex->rc->at_minus_one += k->mult;
            ex->rc->on += k->mult;
            ex->rc->on_mult[slot] += 1;
        } else { /* a conjugate pair */
            ex->rc->on += 2 * k->mult;
            ex->rc->on_mult[slot] += 2;
        }
    }
}

static void mul_factor(fmpz_poly_t p, const fmpz_poly_t f, long e)
{
    long i;
    for (i = 0; i < e; i++)
        fmpz_poly_mul(p, p, f);
}

/* one planted factor of degree <= budget; returns its degree times e */
static long plant_factor(fmpz_poly_t p, expect_t *ex, long budget)
{
    fmpz_poly_t f;
    long kind, e, deg, D, a1, b1, r;

    fmpz_poly_init(f);
    e = rng_range(1, 4) == 1 ? rng_range(2, 3) : 1;   /* repeated factors */
    for (;;) {
        kind = rng_range(0, 7);
        deg = (kind >= 4 && kind <= 6) ? 2 : 1;
        if (deg * e <= budget)
            break;
        if (e > 1)
            e = 1;
    }
    D = rng_range(1, 9);
    switch (kind) {
    case 0: /* D lambda - r, |r| < D: inside (r = 0 gives lambda) */
        r = rng_range(-(D - 1), D - 1);
        fmpz_poly_set_coeff_si(f, 1, D);
        fmpz_poly_set_coeff_si(f, 0, -r);
        ex->rc->inside += e;
        break;
    case 1: /* D lambda - r, |r| > D: outside */
        r = rng_range(D + 1, 3 * D + 5) * (rng_range(0, 1) ? 1 : -1);
        fmpz_poly_set_coeff_si(f, 1, D);
        fmpz_poly_set_coeff_si(f, 0, -r);
        ex->rc->outside += e;
        break;
    case 2: /* lambda - 1 */
        fmpz_poly_set_coeff_si(f, 1, 1);
        fmpz_poly_set_coeff_si(f, 0, -1);
        expect_circle(ex, 1, 1, e);
        break;
    case 3: /* lambda + 1 */
        fmpz_poly_set_coeff_si(f, 1, 1);
        fmpz_poly_set_coeff_si(f, 0, 1);
        expect_circle(ex, -1, 1, e);
        break;
    case 4: /* complex pair a +- ib, a = a1/D, b = b1/D, a^2 + b^2 < 1 */
    case 5: /* same, a^2 + b^2 > 1 */
        if (kind == 4 && D == 1)
            D = 2;
        do {
            a1 = rng_range(-2 * D, 2 * D);
            b1 = rng_range(1, 2 * D);
        } while ((kind == 4) != (a1 * a1 + b1 * b1 < D * D)
                 || a1 * a1 + b1 * b1 == D * D);
        /* D^2 lambda^2 - 2 a1 D lambda + (a1^2 + b1^2) */
        fmpz_poly_set_coeff_si(f, 2, D * D);
        fmpz_poly_set_coeff_si(f, 1, -2 * a1 * D);
        fmpz_poly_set_coeff_si(f, 0, a1 * a1 + b1 * b1);
        if (kind == 4)
            ex->rc->inside += 2 * e;
        else
            ex->rc->outside += 2 * e;
        break;
    case 6: /* circle pair: D lambda^2 - 2 c1 lambda + D, |c1| < D */
        D = rng_range(2, 9);
        a1 = rng_range(-(D - 1), D - 1);
        fmpz_poly_set_coeff_si(f, 2, D);
        fmpz_poly_set_coeff_si(f, 1, -2 * a1);
        fmpz_poly_set_coeff_si(f, 0, D);
        expect_circle(ex, a1, D, e);
        break;
    default: /* lambda: root at 0, inside */
        fmpz_poly_set_coeff_si(f, 1, 1);
        ex->rc->inside += e;
        break;
    }
    mul_factor(p, f, e);
    fmpz_poly_clear(f);
    return deg * e;
}

static void report(const char *what, const fmpz_poly_t p,
                   const rs_rootcount_t got, const rs_rootcount_t want)
{
    char *s = fmpz_poly_get_str_pretty(p, "x");
    fprintf(stderr, "%s mismatch on p = %s\n"
            "  got  in %ld on %ld out %ld at1 %ld atm1 %ld maxmult %ld\n"
            "  want in %ld on %ld out %ld at1 %ld atm1 %ld maxmult %ld\n",
            what, s, got->inside, got->on, got->outside, got->at_one,
            got->at_minus_one, rs_rootcount_max_on_mult(got), want->inside,
            want->on, want->outside, want->at_one, want->at_minus_one,
            rs_rootcount_max_on_mult(want));
    flint_free(s);
}

/* run the three methods; compare with `want` (or with each other when
 * want == NULL); returns 1 on agreement */
static int check_all(const fmpz_poly_t p, const rs_rootcount_t want)
{
    rs_routh_t r;
    rs_jury_t j;
    rs_rootcount_t f;
    rs_error_t err;
    int ok = 1, s1, s2, s3;
    const rs_rootcount_struct *ref;

    rs_routh_init(r);
    rs_jury_init(j);
    rs_rootcount_init(f);
    rs_error_init(err);
    s1 = rs_routh_fmpz_poly(r, p, err);
    if (s1 != RS_OK) fprintf(stderr, "routh: %s\n", err->msg);
    {
        slong i, zr = 0;
        for (i = 0; i < r->nevents; i++) {
            seen_event[r->events[i].kind]++;
            zr += r->events[i].kind == RS_ROUTH_EVENT_ZERO_ROW;
        }
        seen_repeated_zero_row += zr > 1;
    }
    s2 = rs_jury_fmpz_poly(j, p, err);
    if (s2 != RS_OK) fprintf(stderr, "jury: %s\n", err->msg);
    seen_regular_table += j->table_regular;
    s3 = rs_rootcount_factor(f, p, err);
    if (s3 != RS_OK) fprintf(stderr, "factor: %s\n", err->msg);
    if (s1 != RS_OK || s2 != RS_OK || s3 != RS_OK) {
        report("status", p, f, f);
        ok = 0;
    } else {
        ref = want != NULL ? want : f;
        if (!rs_rootcount_equal(r->count, ref)) {
            report("routh", p, r->count, ref);
            ok = 0;
        }
        if (!rs_rootcount_equal(j->count, ref)) {
            report("jury", p, j->count, ref);
            ok = 0;
        }
        if (!rs_rootcount_equal(f, ref)) {
            report("factor", p, f, ref);
            ok = 0;
        }
    }
    rs_routh_clear(r);
    rs_jury_clear(j);
    rs_rootcount_clear(f);
    rs_error_clear(err);
    return ok;
}

static void print_seen(const char *what)
{
    printf("%s: events drop %ld origin %ld zero-pivot %ld zero-row %ld, "
           "repeated zero rows %ld, regular Schur-Cohn tables %ld\n", what,
           seen_event[0], seen_event[1], seen_event[2], seen_event[3],
           seen_repeated_zero_row, seen_regular_table);
    memset(seen_event, 0, sizeof(seen_event));
    seen_regular_table = seen_repeated_zero_row = 0;
}

/* Expected counts from the planted factors (linear factors inside / outside
 * / at +-1, complex pairs inside / outside, circle pairs, powers of lambda,
 * repeated factors). */
static void test_planted(void **state)
{
    long n = env_long("RS_PROPERTY_N", 10000), it, failures = 0;
    (void) state;
    rng_state = (unsigned long long) env_long("RS_PROPERTY_SEED", 20240607);

    for (it = 0; it < n; it++) {
        fmpz_poly_t p;
        expect_t ex;
        long target = rng_range(1, 12), deg = 0;

        memset(&ex, 0, sizeof(ex));
        fmpz_poly_init(p);
        fmpz_poly_one(p);
        while (deg < target)
            deg += plant_factor(p, &ex, target - deg);
        if (rng_range(0, 1))   /* content must not matter */
            fmpz_poly_scalar_mul_si(p, p, -rng_range(1, 6));
        ex.rc->degree = deg;
        expect_finish(&ex);
        failures += !check_all(p, ex.rc);
        fmpz_poly_clear(p);
        if (failures > 5)
            break;
    }
    print_seen("planted");
    assert_int_equal(failures, 0);
}

/* Random integer polynomials (coefficients in [-4, 4], some palindromic or
 * squared to provoke circle roots and singular arrays): no construction
 * knowledge, the three methods must agree. */
static void test_random_agree(void **state)
{
    long n = env_long("RS_PROPERTY_N", 10000) / 2, it, failures = 0;
    (void) state;
    rng_state = (unsigned long long) env_long("RS_PROPERTY_SEED", 20240607) + 1;

    for (it = 0; it < n; it++) {
        fmpz_poly_t p, t;
        long deg = rng_range(1, 8), i, style = rng_range(0, 4);

        fmpz_poly_init(p);
        fmpz_poly_init(t);
        do {
            fmpz_poly_zero(p);
            for (i = 0; i <= deg; i++)
                fmpz_poly_set_coeff_si(p, i, rng_range(-4, 4));
        } while (fmpz_poly_degree(p) < 1);
        if (style == 4 && deg >= 3) {
            /* provoke a zero Routh pivot: build q(z) with q_{m-1} = 0 or
             * q_m = 1, q_{m-3} = q_{m-1} q_{m-2} (row 1 or row 2 starts with
             * 0), then p(lambda) = bilinear(q(-z))(-lambda), whose bilinear
             * transform is q up to a constant. */
            fmpz_poly_set_coeff_si(p, deg, 1);
            if (rng_range(0, 1))
                fmpz_poly_set_coeff_si(p, deg - 1, 0);
            else
                fmpz_poly_set_coeff_si(p, deg - 3,
                    fmpz_get_si(p->coeffs + deg - 1)
                    * fmpz_get_si(p->coeffs + deg - 2));
            for (i = 1; i <= deg; i += 2)
                fmpz_neg(p->coeffs + i, p->coeffs + i);
            rs_bilinear_fmpz_poly(p, p);
            for (i = 1; i < fmpz_poly_length(p); i += 2)
                fmpz_neg(p->coeffs + i, p->coeffs + i);
        } else if (style == 1) {   /* palindromic: p + p* */
            fmpz_poly_reverse(t, p, deg + 1);
            fmpz_poly_add(p, p, t);
        } else if (style == 2) {   /* repeated factor */
            fmpz_poly_set(t, p);
            fmpz_poly_truncate(t, 3);
            if (fmpz_poly_degree(t) >= 1)
                fmpz_poly_mul(p, p, t);
        }
        if (!fmpz_poly_is_zero(p))
            failures += !check_all(p, NULL);
        fmpz_poly_clear(p);
        fmpz_poly_clear(t);
        if (failures > 5)
            break;
    }
    print_seen("random");
    assert_int_equal(failures, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_planted),
        cmocka_unit_test(test_random_agree),
    };
    int rc = cmocka_run_group_tests(tests, NULL, NULL);
    flint_cleanup();
    return rc;
}
