/* numeric/cosim_fast.h -- the fast certified spectral radius of a
 * co-simulation's one-step map (issue 14 part 3, maps `of radius`): the
 * map as a ball matrix at low precision (rs_cosim_ball_transition of the
 * reduced realisation, as rs_cosim_radius uses), its eigenvectors in double
 * (GSL), then one certification in Arb: Gershgorin discs of V^{-1} T V,
 * V^{-1} enclosed by Arb, so every disc bound holds for the exact map.
 * Private to the library (not installed). */
#ifndef RECSTAB_NUMERIC_COSIM_FAST_H
#define RECSTAB_NUMERIC_COSIM_FAST_H

#include "recstab/cosim.h"
#include "recstab/radius.h"

/* r->lower <= rho(T) <= r->upper (r->rho a ball over both), T the exact
 * one-step map of cs, certified at prec bits (64 suffices for double
 * eigenvectors).  RS_ERR_UNDECIDED when the certificate fails (the discs of
 * the dominant eigenvalues overlap: clusters, defective or nearly defective
 * eigenvalues, an implicit Jacobian not certified invertible): the caller
 * falls back to rs_cosim_radius.  Other codes: cs invalid (err set). */
int rs_cosim_fast_radius(rs_radius_t r, const rs_cosim_t cs, slong prec, rs_error_t err);

/* The cross-check of a map's fast radii (analysis_cosim.c, every 64th
 * point): the same ball map of the reduced realisation at prec, GSL's double
 * eigenvalues and eigenvectors as approximations, every eigenvalue
 * certified in a ball by van der Hoeven & Mourrain
 * (acb_mat_eig_simple_vdhoeven_mourrain), r->lower <= rho <= r->upper from
 * those balls.  Independent of the interval-double radius (cosim_dbl.c:
 * numeric forms, Taylor exponential in double, Gershgorin on W T V) but for
 * the case text; cheaper than rs_cosim_radius (no Arb QR, no precision
 * loop).  RS_ERR_UNDECIDED when an eigenvalue is not certified simple: the
 * caller takes rs_cosim_radius. */
int rs_cosim_check_radius(rs_radius_t r, const rs_cosim_t cs, slong prec, rs_error_t err);

/* The second method where the eigenvalues of T are not isolated (a double
 * eigenvalue of exp(A h): rs_cosim_radius gives only an enclosure): T's
 * characteristic polynomial as real balls (arb_mat_charpoly of the same ball
 * map), *where = 1 when Schur's recursion certifies every root strictly
 * inside (rs_radius_balls_inside), -1 when |det T| > 1 (the product of the
 * moduli exceeds 1: a root outside), 0 when neither holds up to maxprec. */
int rs_cosim_check_inside(int *where, const rs_cosim_t cs, slong maxprec, rs_error_t err);

#endif
