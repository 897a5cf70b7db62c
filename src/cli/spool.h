/* spool.h -- the tables of the maps of a run, streamed to temporary files
 * as they are computed (rs_sweep_options_t.table_spool) instead of held in
 * memory, and read back when the CSV files, the plots and the JSON are
 * written.  Each is an unlinked file in TMPDIR: nothing is left behind,
 * whatever ends the run. */
#ifndef RECSTAB_CLI_SPOOL_H
#define RECSTAB_CLI_SPOOL_H

#include <stdio.h>
#include <jansson.h>
#include <flint/flint.h>

/* rs_sweep_options_t.table_spool (arg unused): a new spool and its id */
FILE *rs_cli_spool_open(void *arg, slong *id);
/* the spool of id, rewound (NULL: no such spool); arg unused */
FILE *rs_cli_spool_get(void *arg, slong id);
/* The spooled table of a map element (its "table_spool"), or -1. */
slong rs_cli_spool_of(const json_t *el);
/* Copies spool id to f from its start, without its header line when
 * skip_header; 0, or -1 when reading or writing failed. */
int rs_cli_spool_copy(FILE *f, slong id, int skip_header);
/* The whole spooled table as a string (malloc'd; NULL on failure). */
char *rs_cli_spool_text(slong id);
/* Closes every spool (their files go with them). */
void rs_cli_spools_close(void);

#endif
