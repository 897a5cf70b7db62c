/* plot.h -- the CLI side of sweeps and maps: the CSV file of a run and its
 * gnuplot rendering, both written to a temporary name beside the target
 * (TARGET.tmp.XXXXXX) and renamed only when the whole run succeeded. */
#ifndef RECSTAB_CLI_PLOT_H
#define RECSTAB_CLI_PLOT_H

#include <stddef.h>
#include <jansson.h>

/* Number of sweep/map elements with a table in the documents (array of case
 * documents). */
size_t rs_cli_count_tables(json_t *docs);

/* Writes every table of the run into a temporary file beside path; *tmp gets
 * its name (malloc'd).  shard_index/shard_count add the "# shard" lines.
 * Sets "csv": path in every element written.  0 on success, else -1 with a
 * message in err. */
int rs_cli_csv_stage(const char *path, json_t *docs, long shard_index, long shard_count, char **tmp,
                     char *err, size_t errlen);

/* Renders the tables with gnuplot (terminal from the extension: .png
 * pngcairo, .svg svg) into a temporary file beside path. */
int rs_cli_plot_stage(const char *path, json_t *docs, char **tmp, char *err, size_t errlen);

/* rename(tmp, path); 0 on success. */
int rs_cli_commit(const char *tmp, const char *path, char *err, size_t errlen);

/* After the files are written: drops the bulky "table"/"boundary_table"
 * members from the output documents when a CSV file holds them or when a
 * table has more than max_rows rows. */
void rs_cli_trim_tables(json_t *docs, int have_csv, size_t max_rows);

#endif
