/* methods.h -- exact coefficients of the integrators people use: Butcher
 * tableaux and their stability functions, Adams-Bashforth, Adams-Moulton
 * and BDF coefficients derived from their definitions (Hairer, Norsett,
 * Wanner, Solving ODEs I, III.1).  All arithmetic is over Q (Q(sqrt d) for
 * the tableaux with irrational entries). */
#ifndef RECSTAB_METHODS_H
#define RECSTAB_METHODS_H

#include <flint/flint.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>

#ifdef __cplusplus
extern "C" {
#endif

#define RS_METHODS_MAX_STAGES 8
#define RS_METHODS_MAX_STEPS 6

/* a Butcher tableau with s stages: A (row-major s x s), b; rational, or
 * over Q(sqrt d) when d > 0: the entries are then A + sqrt(d) A1, b + sqrt(d) b1
 * (A1, b1 NULL when d = 0) */
typedef struct {
    slong s;
    fmpq *A, *b;
    slong d;
    fmpq *A1, *b1;
} rs_tableau_struct;
typedef rs_tableau_struct rs_tableau_t[1];

void rs_tableau_init(rs_tableau_t t, slong s);
void rs_tableau_clear(rs_tableau_t t);

/* R(z) = 1 + z b^T (I - zA)^-1 1 = num/den in lowest terms, den(0) = 1,
 * for the tableau of `name` (euler, heun, midpoint, rk4, gauss2,
 * radau-iia2, radau-iia3, sdirk2).  Returns 0 for an unknown name, -1
 * when R is not in Q(z) (sdirk2: gamma = 1 - sqrt(2)/2 gives the
 * denominator (1 - gamma z)^2; num, den then hold the rational parts). */
int rs_methods_rk_stability_named(fmpq_poly_t num, fmpq_poly_t den, const char *name);

/* R = (n0 + sqrt(d) n1)/(d0 + sqrt(d) d1) over Q(sqrt d) for every named
 * tableau (d = 0 for the rational ones, n1 = d1 = 0 then), den(0) = 1,
 * not reduced to lowest terms; returns 0 for an unknown name, else 1.
 * sdirk2 gives d = 2, n0 + sqrt(2) n1 = 1 + (sqrt(2) - 1) z and
 * d0 + sqrt(2) d1 = (1 - gamma z)^2. */
int rs_methods_rk_stability_named_qd(fmpq_poly_t n0, fmpq_poly_t n1, fmpq_poly_t d0, fmpq_poly_t d1, slong *d,
                                     const char *name);

/* the same for a rational tableau */
void rs_tableau_stability(fmpq_poly_t num, fmpq_poly_t den, const rs_tableau_t t);

/* the tableau of `name` when its entries are rational, else a rational
 * tableau with the same stability function (a realization of R with the
 * stage vector 1: the same step x[n+1] = R(hF) x[n] for x' = F x + G u with
 * u frozen over the step).  Returns 0 for an unknown name, -1 when R is
 * not rational (t unchanged). */
int rs_tableau_named(rs_tableau_t t, const char *name);

/* the tableau of `name` exactly as written, over Q(sqrt d) when its
 * entries are irrational (sdirk2: d = 2, gamma = 1 - sqrt(2)/2); 0 for an
 * unknown name, else 1 */
int rs_tableau_named_qd(rs_tableau_t t, const char *name);
/* the realization above of R = num/den (den(0) = 1, deg num, deg den <= s) */
void rs_tableau_realize(rs_tableau_t t, const fmpq_poly_t num, const fmpq_poly_t den);

/* k-step Adams coefficients, the integral over [0, 1] of the Lagrange basis
 * at the nodes 0, -1, ..., -(k-1) (explicit: beta[j] multiplies f[n-j],
 * j < k) or 1, 0, ..., -(k-1) (implicit: beta[j] multiplies f[n+1-j],
 * j <= k), in units of h: x[n+1] - x[n] = h sum beta[j] f[...]. */
void rs_methods_adams(fmpq *beta, slong k, int implicit);

/* k-step BDF: the derivative at t = 1 of the polynomial interpolating
 * x[n+1-j] at t = 1 - j, j = 0..k: sum alpha[j] x[n+1-j] = h f[n+1]. */
void rs_methods_bdf(fmpq *alpha, slong k);

#ifdef __cplusplus
}
#endif
#endif
