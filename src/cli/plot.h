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

/* An output file of the run (--csv FILE, --plot FILE).  A regular file, or
 * a new one, is staged beside its path (PATH.tmp.XXXXXX) and renamed onto
 * it; a device, a FIFO or "-" (stdout, --csv only) is staged in TMPDIR and
 * written through, never replaced; a symbolic link or a folder is refused.
 * SIGINT/SIGTERM (rs_cli_signals_start) remove what is staged and undo
 * renames not yet final. */
typedef struct {
    const char *path, *option;
    int through;      /* device, FIFO or stdout: written through */
    int existed;      /* a regular file was at path */
    char *tmp;        /* the staged content (malloc'd name) */
    char *backup;     /* hard link to the replaced file until the run is final */
    int renamed;      /* tmp is at path; rs_cli_out_undo puts the old file back */
    int owned;        /* made by the run (a further CSV file): path and the struct are malloc'd */
} rs_cli_out_t;

/* Every output file of a run: --csv (and the further CSV files it takes),
 * each --plot, --plot-script. */
#define RS_CLI_MAX_OUTS 256
typedef struct {
    rs_cli_out_t *o[RS_CLI_MAX_OUTS];
    int n;
} rs_cli_outs_t;

/* Checks what is at path (before any work: errors come early); 0, or -1
 * with a message in err. */
int rs_cli_out_init(rs_cli_out_t *o, const char *option, const char *path, char *err, size_t errlen);
/* Removes a temporary or undoes a rename that rs_cli_out_done did not make final. */
void rs_cli_out_clear(rs_cli_out_t *o);

/* Writes the tables of the run, one per file: the first into o's stage,
 * table t > 1 into STEM.t.csv and the exact boundary of a map into
 * STEM.boundary.csv (STEM.t.boundary.csv) beside o's path STEM.csv, each
 * with "# " comment lines before its one header line; the further files
 * are added to set.  shard_index/shard_count add the "# shard" lines.  Sets
 * "csv" (and "boundary_csv") in every element written.  0 on success, else
 * -1 with a message in err (o written through, stdout, takes one table). */
int rs_cli_csv_stage(rs_cli_out_t *o, rs_cli_outs_t *set, json_t *docs, long shard_index, long shard_count,
                     char *err, size_t errlen);

/* Renders the tables with gnuplot into the stage of every plot (terminal
 * from the extension: .pdf pdfcairo, .png pngcairo, .svg svg; w x h pixels,
 * 0: 800 x 600 per panel), in one gnuplot run; script (or NULL) receives
 * the gnuplot script, data included, writing the final paths. */
int rs_cli_plot_stage(rs_cli_out_t **plots, int nplots, rs_cli_out_t *script, long w, long h, json_t *docs,
                      char *err, size_t errlen);

/* The commit, all or nothing for the regular files: rs_cli_out_rename moves
 * every stage onto its path (keeping the old files as hard links), undoing
 * all of them when one fails; rs_cli_out_write_through then writes a device,
 * FIFO or stdout; rs_cli_out_undo puts the old files back (a later failure),
 * rs_cli_out_done makes the renames final. */
int rs_cli_out_rename(rs_cli_out_t **outs, int n, char *err, size_t errlen);
int rs_cli_out_write_through(rs_cli_out_t *o, char *err, size_t errlen);
void rs_cli_out_undo(rs_cli_out_t **outs, int n);
void rs_cli_out_done(rs_cli_out_t **outs, int n);

/* Blocks SIGINT and SIGTERM in the calling thread (call it before any
 * other thread starts) and hands them to a thread that stops gnuplot,
 * removes the temporaries, undoes renames and exits 130 / 143. */
int rs_cli_signals_start(void);
/* Ends that thread (signals stay blocked: the process is about to exit). */
void rs_cli_signals_stop(void);

/* After the files are written: drops the bulky "table"/"boundary_table"
 * members from the output documents when a CSV file holds them or when a
 * table has more than max_rows rows. */
void rs_cli_trim_tables(json_t *docs, int have_csv, size_t max_rows);

#endif
