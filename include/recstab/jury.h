/* jury.h -- unit-circle root location directly on p(lambda): the
 * Schur-Cohn test, exact, with every singular case.
 *
 * Independent of the bilinear/Routh route, so the two can cross-check each
 * other.  Method: g = gcd(p, p*) (p* the reciprocal polynomial) carries every
 * root on the circle and every pair (r, 1/conj r); its circle roots are counted
 * exactly through x = lambda + 1/lambda and Sturm sequences on [-2, 2]; the
 * rest of g splits evenly.  h = p / g has gcd(h, h*) = 1, so its Schur-Cohn
 * (Fujiwara) Hermitian matrix is non-singular and its inertia, computed
 * exactly from the sign pattern of its characteristic polynomial (all roots
 * real: Descartes' rule is exact), gives the roots inside and outside.  When
 * the classical Schur-Cohn/Jury table of p is regular its rows are kept
 * for reports. */
#ifndef RECSTAB_JURY_H
#define RECSTAB_JURY_H

#include <flint/flint.h>
#include <flint/fmpz_poly.h>
#include "recstab/error.h"
#include "recstab/rootcount.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Which exact route counted the roots of p (of h = p0 / gcd(p0, p0*) when
 * that gcd is not 1) off the unit circle. */
typedef enum {
    RS_JURY_ROUTE_TABLE = 0,   /* the integer Schur-Cohn table (Rouche) */
    RS_JURY_ROUTE_MODULAR,     /* the minors' signs modulo primes (CRT) */
    RS_JURY_ROUTE_MATRIX,      /* inertia of the Schur-Cohn matrix */
    RS_JURY_ROUTE_GCD          /* nothing left off gcd(p0, p0*) */
} rs_jury_route_t;

typedef struct {
    rs_rootcount_t count;
    int table_regular;       /* 1 if the classical Jury table had no singular step */
    slong nrows;             /* rows of the Schur-Cohn table (when regular) */
    fmpz_poly_struct *rows;  /* successive rows F_k, each divided exactly by
                                |F_{k-2}(0)| (Bareiss-like, jury.c) and made
                                primitive up to degree 64 (the report's rows;
                                rs_jury_count_fmpz_poly keeps only signs) */
    slong gcd_degree;        /* degree of gcd(p, p*) split off */
    slong modular_primes;    /* rs_jury_count_fmpz_poly: primes of the regular
                                table's minors (0: the integer table ran) */
    int route;               /* rs_jury_route_t: what counted the roots off
                                the circle (of p, or of h = p0 / gcd) */
} rs_jury_struct;
typedef rs_jury_struct rs_jury_t[1];

void rs_jury_init(rs_jury_t j);
void rs_jury_clear(rs_jury_t j);
int rs_jury_fmpz_poly(rs_jury_t j, const fmpz_poly_t p, rs_error_t err);
/* The same count without the rows (nrows, rows: the sign of each row's
 * constant term and its degree only).  Above degree 32 a regular table is
 * counted from the signs of the Schur-Cohn minors D_1..D_n, rebuilt from
 * word-size primes under a Hadamard bound (jury.c); a table singular or
 * defective modulo the first prime goes to the integer table. */
int rs_jury_count_fmpz_poly(rs_jury_t j, const fmpz_poly_t p, rs_error_t err);
/* 1 when every root of c[0] + c[1] x + ... + c[n] x^n (n >= 1, c[n] != 0)
 * lies strictly inside the unit circle, else 0: Schur's recursion in exact
 * integers, |c_n| > |c_0| at every step, c <- (c_n c - c_0 c*)/x, each row
 * divided by its content.  Decides only this case (0 also where the table
 * would be singular), which makes it much cheaper than the count: a screen
 * for points that cannot refute a stable or bounded claim. */
int rs_jury_all_inside(const fmpz *c, slong n);

/* The symbolic table of `jury` factors a lead^2 - const^2 of more than this
 * many terms (default 20 000) through its halves lead - const and
 * lead + const, smaller ones whole; sets it (tests: 0 = always the halves)
 * and returns the previous value. */
slong rs_jury_set_factor_whole_terms(slong terms);
slong rs_jury_factor_whole_terms(void);

/* The symbolic table of `jury` gives way to the bilinear route (the
 * Lienard-Chipart conditions of q(z) = (z - 1)^n p((z + 1)/(z - 1)), the
 * same region) at the first lead^2 - const^2 of more than this many terms
 * (default 20 000: the rows of the chains of issue 17 grow past 700 000
 * terms, while the cases' tables stay under it); sets it (tests: 0 = the
 * bilinear route from the first row, a huge value = the table throughout)
 * and returns the previous value. */
slong rs_jury_set_bilinear_terms(slong terms);
slong rs_jury_bilinear_terms(void);

#ifdef __cplusplus
}
#endif
#endif
