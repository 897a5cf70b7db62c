/* dblstr.c -- see util/dblstr.h.  A double x > 0 is M 2^E exactly (M < 2^53
 * an integer), an n-digit decimal d 10^q (d < 10^17 < 2^57); both sides are
 * compared after moving the powers of 5 onto integers below 2^126 and the
 * powers of 2 onto a shift, in unsigned 128-bit arithmetic.  That bounds q
 * to [-31, 126 - log2(d)] / log2 5 (for 17 digits about [-31, 29]). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/dblstr.h"

typedef unsigned __int128 u128_t;

static int bitlen128(u128_t x)
{
    uint64_t hi = (uint64_t) (x >> 64), lo = (uint64_t) x;
    if (hi != 0) return 128 - __builtin_clzll(hi);
    return lo != 0 ? 64 - __builtin_clzll(lo) : 0;
}

/* the sign of d 10^q - x (x > 0 finite, d >= 1), 2 outside the handled range */
static int cmp_dec(uint64_t d, int q, double x)
{
    int ex, s, k;
    double f = frexp(x, &ex);
    uint64_t M = (uint64_t) ldexp(f, 53);   /* exact: f has at most 53 bits */
    u128_t L = d, R = M, p5 = 1;
    /* 5^|q| times the side's integer must stay below 2^127 */
    if (q < -400 || q > 400 || (q >= 0 ? bitlen128(L) : 53) + (int) ceil(2.3219280949 * (q >= 0 ? q : -q)) > 126)
        return 2;
    for (k = 0; k < (q >= 0 ? q : -q); k++) p5 *= 5;
    if (q >= 0) L *= p5;
    else R *= p5;
    /* L 2^q vs R 2^(ex - 53) */
    s = q - (ex - 53);
    if (s >= 0) {
        if (bitlen128(L) + s > 127) return 1;   /* L 2^s >= 2^127 > R */
        L <<= s;
    } else {
        if (bitlen128(R) - s > 127) return -1;
        R <<= -s;
    }
    return L > R ? 1 : L < R ? -1 : 0;
}

void rs_dblstr_format(char *out, int neg, const char *D, long k, long e, int trim)
{
    long i, len = 0;
    if (trim)
        while (k > 1 && D[k - 1] == '0') k--;
    if (neg) out[len++] = '-';
    if (e >= -4 && e <= k) {
        if (e <= 0) {
            out[len++] = '0';
            out[len++] = '.';
            for (i = 0; i < -e; i++) out[len++] = '0';
            for (i = 0; i < k; i++) out[len++] = D[i];
        } else
            for (i = 0; i < k; i++) {
                if (i == e) out[len++] = '.';
                out[len++] = D[i];
            }
        out[len] = '\0';
    } else {
        out[len++] = D[0];
        if (k > 1) out[len++] = '.';
        for (i = 1; i < k; i++) out[len++] = D[i];
        sprintf(out + len, "e%+ld", e - 1);
    }
}

/* |x| to nearest at n digits by printf: d (n digits) and q, |x| ~ d 10^q */
static int near_digits(uint64_t *d, int *q, double ax, int n)
{
    char tmp[48], *end;
    int i;
    long k10;
    snprintf(tmp, sizeof tmp, "%.*e", n - 1, ax);
    *d = (uint64_t) (tmp[0] - '0');
    for (i = 0; i < n - 1; i++) *d = *d * 10 + (uint64_t) (tmp[2 + i] - '0');
    i = n > 1 ? n + 1 : 1;
    if (tmp[i] != 'e') return 0;
    k10 = strtol(tmp + i + 1, &end, 10);
    if (*end != '\0' || k10 < -400 || k10 > 400) return 0;
    *q = (int) k10 - n + 1;
    return 1;
}

/* the n decimal digits of d (d < 10^n) into D, NUL-terminated */
static void put_digits(char *D, uint64_t d, int n)
{
    int i;
    for (i = n - 1; i >= 0; i--) {
        D[i] = (char) ('0' + d % 10);
        d /= 10;
    }
    D[n] = '\0';
}

int rs_dblstr_round(char *buf, double x, int n, int dir)
{
    uint64_t d, lo10 = 1, hi10;
    int q, c = 2, it, neg = x < 0, dm;
    double ax = fabs(x);
    char D[24];
    if (n < 1 || n > 17 || !isfinite(x) || x == 0) return -1;
    dm = neg ? -dir : dir;   /* the direction of |x| */
    for (it = 1; it < n; it++) lo10 *= 10;
    hi10 = lo10 * 10;   /* d in [lo10, hi10) */
    if (!near_digits(&d, &q, ax, n)) return -1;
    /* printf rounded to nearest: at most one step outward; loop for safety */
    for (it = 0; it < 4; it++) {
        c = cmp_dec(d, q, ax);
        if (c == 2) return -1;
        if (c == 0 || dm == 0 || (dm < 0) == (c < 0)) break;
        if (dm < 0) {
            if (d == lo10) { d = hi10 - 1; q--; }
            else d--;
        } else {
            if (d == hi10 - 1) { d = lo10; q++; }
            else d++;
        }
    }
    if (it == 4) return -1;
    put_digits(D, d, n);
    rs_dblstr_format(buf, neg, D, n, (long) q + n, c == 0);
    return (int) strlen(buf);
}

/* the exponent e with 2^(e-1) <= |x| < 2^e (arf_abs_bound_lt_2exp_si) */
static int ebound(double x)
{
    int e;
    frexp(x, &e);
    return e;
}

/* The most significant digits worth trying for [lo, hi] (lo, hi of one
 * sign, finite, at most n): about the digits where lo and hi first differ,
 * plus 3; n when lo = hi. */
static long first_digits(double lo, double hi, long n)
{
    long k0;
    if (lo == hi)
        k0 = n;
    else {
        /* the exponent of the exact width hi - lo = s + t (TwoSum): below
         * s's when s rounded up to a power of 2 */
        double s = hi - lo, bp = s - hi, ap = s - bp, t = (hi - ap) + (-lo - bp);
        int ew = ebound(s);
        if (t < 0 && frexp(s, &ew) == 0.5) ew--;
        else ew = ebound(s);
        k0 = (long) ((double) (ebound(lo) - ew) * 0.30103) + 3;
    }
    if (k0 < 1) k0 = 1;
    if (k0 > n) k0 = n;
    return k0;
}

int rs_dblstr_interval(char *buf, double lo, double hi, int n)
{
    long k, k0;
    char a[48], b[48];
    if (n < 1) n = 1;
    if (n > 17 || !isfinite(lo) || !isfinite(hi) || !(lo <= hi) || lo == 0 || hi == 0 || (lo < 0) != (hi < 0))
        return -1;
    k0 = first_digits(lo, hi, n);
    for (k = k0; k >= 1; k--) {
        snprintf(a, sizeof a, "%.*e", (int) k - 1, lo);
        snprintf(b, sizeof b, "%.*e", (int) k - 1, hi);
        if (strcmp(a, b) == 0) break;
    }
    if (k < 1) return -1;
    return rs_dblstr_round(buf, fabs(lo) <= fabs(hi) ? lo : hi, (int) k, 0);
}

/* ---- the three cells of one interval from two conversions --------------- */

static uint64_t pow10u(int k)
{
    uint64_t p = 1;
    while (k-- > 0) p *= 10;
    return p;
}

/* the nearest n-digit decimal d 10^q of x > 0 by printf, checked exactly to
 * lie within half a unit of its last digit of x; 0 if not (or out of range) */
static int near_checked(uint64_t *d, int *q, double x, int n)
{
    if (!near_digits(d, q, x, n)) return 0;
    /* (10 d -+ 5) 10^(q-1) = d 10^q -+ half a unit */
    return cmp_dec(10 * *d - 5, *q - 1, x) <= 0 && cmp_dec(10 * *d + 5, *q - 1, x) >= 0;
}

/* x's nearest k-digit decimal from its nearest n-digit one d 10^q (k < n):
 * the same unless d's dropped tail is exactly half a unit (then 0: x may
 * lie on either side); else |x - d 10^q| <= half a unit of digit n keeps x's
 * tail on d's side of the k-digit midpoint */
static int reround(uint64_t *dk, int *qk, uint64_t d, int q, int n, int k)
{
    uint64_t p = pow10u(n - k), hi = d / p, rem = d % p;
    if (rem * 2 == p) return 0;
    if (rem * 2 > p) hi++;
    *qk = q + (n - k);
    if (hi == pow10u(k)) {
        hi /= 10;
        ++*qk;
    }
    *dk = hi;
    return 1;
}

/* the directed n-digit bound of x from its checked nearest d 10^q: one step
 * outward when on the wrong side; exact: the decimal equals x */
static int directed(char *buf, uint64_t d, int q, double x, int n, int dir)
{
    char D[24];
    uint64_t lo10 = pow10u(n - 1);
    int c = cmp_dec(d, q, x);
    if (c == 2) return -1;
    if (c != 0 && (dir < 0) != (c < 0)) {
        if (dir < 0) {
            if (d == lo10) { d = 10 * lo10 - 1; q--; }
            else d--;
        } else {
            if (d == 10 * lo10 - 1) { d = lo10; q++; }
            else d++;
        }
    }
    put_digits(D, d, n);
    rs_dblstr_format(buf, 0, D, n, (long) q + n, c == 0);
    return 0;
}

int rs_dblstr_bounds(char *rho, char *lower, char *upper, double lo, double hi, int n)
{
    uint64_t dl, dh, a, b;
    int ql, qh, qa, qb, k, k0, c;
    char D[24];
    if (n < 1 || n > 17 || !(lo > 0) || !(lo <= hi) || !isfinite(hi)) return -1;
    if (!near_checked(&dl, &ql, lo, n) || !near_checked(&dh, &qh, hi, n)) return -1;
    if (directed(lower, dl, ql, lo, n, -1) != 0 || directed(upper, dh, qh, hi, n, 1) != 0) return -1;
    k0 = (int) first_digits(lo, hi, n);   /* as rs_dblstr_interval */
    for (k = k0; k >= 1; k--) {
        if (k == n) {
            a = dl; qa = ql;
            b = dh; qb = qh;
        } else if ((!reround(&a, &qa, dl, ql, n, k) && !near_checked(&a, &qa, lo, k))
                   || (!reround(&b, &qb, dh, qh, n, k) && !near_checked(&b, &qb, hi, k)))
            return -1;   /* a half-unit tail: printf at k digits decides */
        if (a == b && qa == qb) break;
    }
    if (k < 1) return -1;
    c = cmp_dec(a, qa, lo);
    if (c == 2) return -1;
    put_digits(D, a, k);
    rs_dblstr_format(rho, 0, D, k, (long) qa + k, c == 0);
    return 0;
}
