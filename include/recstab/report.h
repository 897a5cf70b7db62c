/* report.h -- rendering analysis results (JSON documents) for people. */
#ifndef RECSTAB_REPORT_H
#define RECSTAB_REPORT_H

#include <stdio.h>
#include <jansson.h>
#include "recstab/str.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Aligned plain text: one block per analysis. */
void rs_report_text(FILE *out, const json_t *doc);
/* The same for a document whose long polynomials wait in pt (rs_options_t
 * .polytext): each printed where its placeholder is. */
void rs_report_text_polytext(FILE *out, const json_t *doc, rs_polytext_t pt);

#ifdef __cplusplus
}
#endif
#endif
