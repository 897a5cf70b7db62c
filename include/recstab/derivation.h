/* derivation.h -- the whole derivation of a case for teaching: equations,
 * lambda-matrix, p(lambda), the substitution lambda = (1+z)/(1-z), q(z),
 * the Routh array with its singular steps, the conditions and the region or
 * claim results, as Markdown or as a LaTeX document (pdflatex, amsmath). */
#ifndef RECSTAB_DERIVATION_H
#define RECSTAB_DERIVATION_H

#include <stdio.h>
#include <jansson.h>

#ifdef __cplusplus
extern "C" {
#endif

/* doc: a result document made with rs_options_t.with_scheme = 1. */
void rs_derivation_markdown(FILE *out, const json_t *doc);

/* A complete LaTeX document when standalone, else the body only (so that
 * several cases can share one document). */
void rs_derivation_latex(FILE *out, const json_t *doc, int standalone);
void rs_derivation_latex_begin(FILE *out);
void rs_derivation_latex_end(FILE *out);

/* A polynomial or condition string ("3/2*m^2*muh - lambda >= 0") in LaTeX. */
void rs_derivation_tex_poly(FILE *out, const char *s);

#ifdef __cplusplus
}
#endif
#endif
