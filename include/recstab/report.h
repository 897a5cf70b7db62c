/* report.h -- rendering analysis results (JSON documents) for people. */
#ifndef RECSTAB_REPORT_H
#define RECSTAB_REPORT_H

#include <stdio.h>
#include <jansson.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Aligned plain text: one block per analysis. */
void rs_report_text(FILE *out, const json_t *doc);

#ifdef __cplusplus
}
#endif
#endif
