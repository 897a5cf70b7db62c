/* dblstr.h -- directed decimal strings of doubles without MPFR (issue 14
 * part 3: the radius cells of fast maps).  The results are the strings
 * rs_radius_arf_str / rs_radius_interval_str (numeric/radius.c) print for
 * the same double, byte for byte: n significant digits, fixed notation when
 * -4 <= e <= n (value 0.D * 10^e) else d.ddde+X, trailing zeros dropped only
 * when the decimal equals x exactly.
 *
 * The digits come from snprintf "%.*e" (round to nearest); the direction is
 * then certified by comparing the decimal with x exactly in 128-bit integer
 * arithmetic and stepping the last digit outward when it lies on the wrong
 * side.  No rounding-mode switch, no global state: thread safe.
 *
 * Each function returns the length written to buf (size >= RS_DBLSTR_SIZE),
 * or -1 when it does not handle the input (0, inf, nan, |x| below about
 * 10^(n-32) or above 10^(n+28) for n digits, an interval with no certain
 * digit or around 0): the caller
 * takes the MPFR route then. */
#ifndef RS_UTIL_DBLSTR_H
#define RS_UTIL_DBLSTR_H

#include <stddef.h>

#define RS_DBLSTR_SIZE 64

/* x rounded to n (1..17) significant digits: dir < 0 down (toward -inf),
 * dir > 0 up (toward +inf), dir == 0 to nearest (ties to even) */
int rs_dblstr_round(char *buf, double x, int n, int dir);

/* rs_radius_interval_str (lo, hi) for doubles: the longest k <= n digits to
 * which every point of [lo, hi] rounds alike, printed */
int rs_dblstr_interval(char *buf, double lo, double hi, int n);

/* The three map cells of an interval 0 < lo <= hi at once, from one printf
 * of each end: rho = rs_dblstr_interval(lo, hi, n), lower =
 * rs_dblstr_round(lo, n, -1), upper = rs_dblstr_round(hi, n, +1) (each
 * buffer RS_DBLSTR_SIZE).  The shorter roundings of the interval's digit
 * count are derived from the n-digit ones (exact unless a dropped tail is
 * exactly half a unit: then printf at that count).  0, or -1 as above. */
int rs_dblstr_bounds(char *rho, char *lower, char *upper, double lo, double hi, int n);

/* sign * 0.D * 10^e (D: k digits) as rs_radius_arf_str prints it (trim:
 * drop trailing zeros); out needs k + 48 + max(0, -e) bytes */
void rs_dblstr_format(char *out, int neg, const char *D, long k, long e, int trim);

#endif
