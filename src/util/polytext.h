/* polytext.h -- long polynomials printed only when the report is written
 * (the registry of recstab/str.h's rs_polytext_t; issue 17). */
#ifndef RECSTAB_POLYTEXT_H
#define RECSTAB_POLYTEXT_H

#include <stdio.h>
#include <jansson.h>
#include <flint/flint.h>
#include <flint/fmpz_mpoly.h>
#include "recstab/str.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A placeholder string (a new reference) standing for p's text as
 * rs_polyfmt_fmpz_mpoly_into prints it with vars (copied).  p is borrowed:
 * the caller keeps it unchanged until rs_polytext_keep, which takes it over
 * (no copy of a polynomial with 637 163 multi-word coefficients).  With
 * line != NULL, *line the placeholder of the same text followed by
 * " tail" (NULL when tail is NULL).  The same p deferred again is one
 * polynomial. */
json_t *rs_polytext_defer(rs_polytext_t pt, fmpz_mpoly_t p, const char *const *vars,
                          const fmpz_mpoly_ctx_t ctx, const char *tail, json_t **line);
/* Every borrowed polynomial moved into pt (fmpz_mpoly_swap; the caller's
 * are left 0, to be cleared as usual). */
void rs_polytext_keep(rs_polytext_t pt);
/* The placeholder x (a json_t of rs_polytext_defer's, not a string with its
 * text) or the value s of one (json_string_value's pointer): its index, or
 * -1 when it is none of pt's. */
slong rs_polytext_find(const rs_polytext_t pt, const json_t *x);
slong rs_polytext_find_value(const rs_polytext_t pt, const char *s);
/* One more write of placeholder k is to come: its text is printed once and
 * kept until the last of them (without holds each write prints it). */
void rs_polytext_hold(rs_polytext_t pt, slong k);
/* The text of placeholder k to f, plain or as a JSON string (quoted and
 * escaped as jansson dumps it); 0, or -1 when memory ran out. */
int rs_polytext_write(FILE *f, rs_polytext_t pt, slong k, int json);

#ifdef __cplusplus
}
#endif
#endif
