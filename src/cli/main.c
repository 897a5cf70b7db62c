/* main.c -- the recstab command.  All output is staged (a temporary file,
 * spool.h) and written only when every case succeeded, so a failing run
 * leaves no partial output. */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <signal.h>
#include <time.h>
#include <sys/resource.h>
#include <jansson.h>
#include <gsl/gsl_errno.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef RS_MPI
#include <mpi.h>
#endif
#include "recstab/analysis.h"
#include "recstab/api.h"
#include "recstab/sweep.h"
#include "plot.h"
#include "spool.h"
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "recstab/report.h"
#include "recstab/derivation.h"
#include "recstab/hurwitz.h"

#ifndef RS_VERSION
#define RS_VERSION "0.0.0"
#endif

static void usage(FILE *f)
{
    fputs("usage: recstab [OPTIONS] CASE...      run the analyses each case lists (\"-\" reads stdin)\n"
          "  --json                         one JSON document on stdout\n"
          "  --set NAME=VALUE               add or override a set value (repeatable)\n"
          "  --analyse \"ANALYSIS [OPTIONS]\" replace the case's analyses (repeatable; also\n"
          "                                 accepts \"expect ...\" and \"claim ...\" lines)\n"
          "  --max-prec BITS                ceiling for certified numerics (default 65536)\n"
          "  --markdown, --latex            print the whole derivation (Markdown / a LaTeX document)\n"
          "  --csv FILE                     write the tables of the run's sweeps and maps, one per file\n"
          "                                 (FILE, STEM.2.csv, STEM.boundary.csv; atomically; - = stdout\n"
          "                                 for one table, the report then goes to stderr)\n"
          "  --json-rows N                  at most N rows of each sweep and map in the JSON (default all)\n"
          "  --plot FILE.pdf|.png|.svg      plot them with gnuplot (repeatable; sweeps of several cases overlaid)\n"
          "  --plot-size WxH                the plot's size in pixels (default 800x600 per panel)\n"
          "  --plot-script FILE             keep the gnuplot script (data included)\n"
          "  --progress                     progress of sweeps and maps on stderr also when not a terminal\n"
          "  --shard I/N                    compute only shard I of N of every sweep and map\n"
          "  --threads N                    OpenMP threads for sweeps and maps (default: all cores)\n"
          "  --max-points N                 limit of points per sweep or map (default 4000000)\n"
          "  --sweep-level LEVEL            benchmarking: start the verdict ladder at fast, prec128,\n"
          "                                 prec256 or exact; double = uncertified GSL roots only\n"
          "  --emit equations               print the unknowns and equations the builders generated\n"
          "  --time-limit SECONDS           wall time for the whole run (default 600; 0 = none)\n"
          "  --memory-limit MB              memory for the computation (default half of the RAM; 0 = none)\n"
          "  --row-share SECONDS            estimated seconds (a fixed cost model, not the clock) one Routh row\n"
          "                                 or one minor's composition may take before hurwitz leaves the\n"
          "                                 minors from it on not expanded (default: none; given alone it\n"
          "                                 replaces the expansion budget, as before)\n"
          "  --expand-seconds SECONDS       estimated seconds (the same model) all of hurwitz's Routh rows and\n"
          "                                 compositions together may take; the minor whose step would\n"
          "                                 cross it and the later ones are not expanded (default 6)\n"
          "  --list-analyses                the analyses, their options and the models they apply to\n"
          "  --help, --version\n"
          "exit status: 0 done; 1 an expectation or claim failed; 2 bad input or usage;\n"
          "             3 internal inconsistency (two independent methods disagree)\n"
          "analyses (--list-analyses for their options): ", f);
    rs_analysis_list(f, 1);
}

/* Progress of long sweeps and maps on stderr: on a terminal one line
 * rewritten in place; elsewhere (--progress) a line at most every 2 s.
 * The time left is extrapolated from the rate since the first point. */
typedef struct {
    int tty;
    char what[200];
    double t0, last;
} progress_t;

static double mono_seconds(void);

static void put_duration(FILE *f, double s)
{
    if (s < 60) fprintf(f, "%.0f s", s);
    else if (s < 3600) fprintf(f, "%d min %02d s", (int) (s / 60), (int) s % 60);
    else fprintf(f, "%d h %02d min", (int) (s / 3600), (int) (s / 60) % 60);
}

static void progress(void *arg, const char *what, slong done, slong total)
{
    progress_t *p = arg;
    double now = mono_seconds();
    if (strcmp(p->what, what) != 0 || done == 0) {
        /* a new sweep or map: its clock starts now */
        snprintf(p->what, sizeof p->what, "%s", what);
        p->t0 = now;
        p->last = 0;
    }
    if (done >= total) {
        if (p->tty) fputs("\r\033[K", stderr);
        else {
            fprintf(stderr, "recstab: %s: %ld/%ld points done in ", what, (long) done, (long) total);
            put_duration(stderr, now - p->t0);
            fputc('\n', stderr);
        }
        p->what[0] = '\0';
        fflush(stderr);
        return;
    }
    if (!p->tty && now - p->last < 2.0) return;
    p->last = now;
    fprintf(stderr, "%srecstab: %s: %ld/%ld points (%ld%%)", p->tty ? "\r" : "", what, (long) done, (long) total,
            (long) (100 * done / (total > 0 ? total : 1)));
    if (done > 0 && now - p->t0 > 0.5) {
        fputs(", about ", stderr);
        put_duration(stderr, (now - p->t0) * (double) (total - done) / (double) done);
        fputs(" left", stderr);
    }
    fputs(p->tty ? "\033[K" : "\n", stderr);
    fflush(stderr);
}

static int parse_long(const char *s, long lo, long hi, long *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (*s == '\0' || *end != '\0' || v < lo || v > hi) return 0;
    *out = v;
    return 1;
}

/* The budget's backstops for work that cannot reach a cooperative check
 * (one long FLINT call, one huge allocation): print and end at once, which
 * is safe here as output is only written after every case succeeded. */
static void budget_fatal(const char *msg)
{
    static const char pre[] = "recstab: ";
    if (write(2, pre, sizeof pre - 1) >= 0 && write(2, msg, strlen(msg)) >= 0) (void) !write(2, "\n", 1);
    _exit(2);
}

static char budget_alarm_msg[200];   /* formatted before the alarm is armed */

static double mono_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

static void budget_alarm(int sig)
{
    (void) sig;
    budget_fatal(budget_alarm_msg);
}

/* GMP and MPFR put their temporaries on the stack: a square root at the
 * default precision ceiling (65536 bits) needs 12-16 MB (--set c1=0 on the
 * Li cases overflowed the usual 8 MB).  The main thread's stack grows up to
 * the soft limit read at fault time, so raising it here is enough. */
static void raise_stack_limit(void)
{
    struct rlimit rl;
    rlim_t want = (rlim_t) 256 << 20;
    if (getrlimit(RLIMIT_STACK, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY || rl.rlim_cur >= want) return;
    rl.rlim_cur = (rl.rlim_max == RLIM_INFINITY || rl.rlim_max > want) ? want : rl.rlim_max;
    setrlimit(RLIMIT_STACK, &rl);
}

/* The command line, parsed once and passed down (no globals). */
typedef struct {
    int json, markdown, latex, emit;
    const char **sets, **analyses, **cases;
    int nsets, nanalyses, ncases;
    const char *csv_path, **plot_paths, *plot_script;
    int nplots, progress;
    long plot_w, plot_h;   /* --plot-size, 0: the default per panel */
    long shard_i, shard_n, threads, max_points, json_rows;
    int first_level;
    int rank;              /* MPI rank (0 without MPI): only rank 0 writes */
    rs_options_t opt;
} cli_t;

/* Checks the --csv / --plot / --plot-script targets before any work and
 * starts the signal thread (before OpenMP starts threads: they inherit its
 * signal mask).  set->o[0] is --csv when given, then the plots, then the
 * script; the CSV stage adds its further files later. */
static int outputs_init(const cli_t *cli, rs_cli_outs_t *set, rs_cli_out_t **csv, rs_cli_out_t **script)
{
    char msg[1200];
    int k;
    *csv = *script = NULL;
    set->n = 0;
    if (cli->nplots + 2 > RS_CLI_MAX_OUTS) {
        snprintf(msg, sizeof msg, "at most %d --plot options", RS_CLI_MAX_OUTS - 2);
        goto fail;
    }
    for (k = -1; k <= cli->nplots; k++) {
        const char *path = k < 0 ? cli->csv_path : k < cli->nplots ? cli->plot_paths[k] : cli->plot_script;
        const char *opt = k < 0 ? "--csv" : k < cli->nplots ? "--plot" : "--plot-script";
        rs_cli_out_t *o;
        if (path == NULL) continue;
        o = calloc(1, sizeof *o);
        set->o[set->n++] = o;
        if (rs_cli_out_init(o, opt, path, msg, sizeof msg) != 0) {
            set->n--;
            free(o);
            goto fail;
        }
        if (k < 0) *csv = o;
        if (k == cli->nplots) *script = o;
    }
    if (cli->plot_script != NULL && cli->nplots == 0) {
        snprintf(msg, sizeof msg, "--plot-script needs a --plot FILE (the output the script writes)");
        goto fail;
    }
    if (set->n > 0) {
        /* a closed stdout must fail the write (and undo the files), not kill us */
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = SIG_IGN;
        sigaction(SIGPIPE, &sa, NULL);
    }
    if (rs_cli_signals_start() != 0) {
        snprintf(msg, sizeof msg, "cannot install the SIGINT/SIGTERM cleanup");
        goto fail;
    }
    return 0;
fail:
    fprintf(stderr, "recstab: %s\n", msg);
    return -1;
}

/* Commits the run: the staged files renamed onto their paths, devices,
 * FIFOs and "-" written through, then the report; a failure at any step
 * puts the replaced files back (exit 2).  The report goes to stderr when
 * the CSV takes stdout. */
static int outputs_commit(rs_cli_out_t **outs, int nouts, slong report, const char *buf, size_t len, FILE *to)
{
    char msg[1200];
    int k;
    if (rs_cli_out_rename(outs, nouts, msg, sizeof msg) != 0) goto fail;
    for (k = 0; k < nouts; k++)
        if (rs_cli_out_write_through(outs[k], msg, sizeof msg) != 0) goto undo;
    if ((report >= 0 && rs_cli_spool_copy(to, report, 0) != 0) || (buf != NULL && fwrite(buf, 1, len, to) != len)
        || fflush(to) != 0) {
        snprintf(msg, sizeof msg, "cannot write output: %s%s", strerror(errno),
                 nouts > 0 ? " (no --csv/--plot file written)" : "");
        goto undo;
    }
    rs_cli_out_done(outs, nouts);
    return 0;
undo:
    rs_cli_out_undo(outs, nouts);
fail:
    fprintf(stderr, "recstab: %s\n", msg);
    return -1;
}


/* Usage errors print to stderr and give exit status 2. */
static int usage_error(const char *fmt, const char *a, const char *b, int with_usage)
{
    fputs("recstab: ", stderr);
    fprintf(stderr, fmt, a, b);
    fputc('\n', stderr);
    if (with_usage) usage(stderr);
    return 2;
}

/* --shard I/N into cli; 0 or the exit status */
static int parse_shard(cli_t *cli, const char *val)
{
    char *slash, tmp[64];
    snprintf(tmp, sizeof tmp, "%s", val);
    slash = strchr(tmp, '/');
    if (slash != NULL) {
        *slash = '\0';
        if (parse_long(tmp, 1, 1000000000L, &cli->shard_i) && parse_long(slash + 1, 1, 1000000000L, &cli->shard_n)
            && cli->shard_i <= cli->shard_n) return 0;
    }
    return usage_error("--shard expects I/N with 1 <= I <= N (e.g. 2/4), found '%s'%s", val, "", 0);
}

/* The options of the sweeps and maps and the output files, with a value:
 * 0 or the exit status. */
static int parse_sweep_option(cli_t *cli, const char *a, const char *val)
{
    static const char *const lv[] = {"fast", "prec128", "prec256", "exact", "double"};
    int k;
    if (strcmp(a, "--csv") == 0) cli->csv_path = val;
    else if (strcmp(a, "--plot") == 0) cli->plot_paths[cli->nplots++] = val;
    else if (strcmp(a, "--plot-script") == 0) cli->plot_script = val;
    else if (strcmp(a, "--plot-size") == 0) {
        char tmp[64], *x;
        snprintf(tmp, sizeof tmp, "%s", val);
        x = strchr(tmp, 'x');
        if (x != NULL) *x = '\0';
        if (x == NULL || !parse_long(tmp, 100, 20000, &cli->plot_w) || !parse_long(x + 1, 100, 20000, &cli->plot_h))
            return usage_error("--plot-size expects WIDTHxHEIGHT in pixels from 100 to 20000 (e.g. 1200x900), found '%s'%s",
                               val, "", 0);
    } else if (strcmp(a, "--json-rows") == 0) {
        if (!parse_long(val, 0, 1000000000000L, &cli->json_rows))
            return usage_error("--json-rows expects a number of rows (0 or more), found '%s'%s", val, "", 0);
    }
    else if (strcmp(a, "--threads") == 0) {
        if (!parse_long(val, 1, 4096, &cli->threads))
            return usage_error("--threads expects a number of threads from 1 to 4096, found '%s'%s", val, "", 0);
    } else if (strcmp(a, "--sweep-level") == 0) {
        cli->first_level = -1;
        for (k = 0; k < 5; k++) if (strcmp(val, lv[k]) == 0) cli->first_level = k;
        if (cli->first_level < 0)
            return usage_error("--sweep-level expects fast, prec128, prec256, exact or double, found '%s'%s", val, "", 0);
    } else if (strcmp(a, "--max-points") == 0) {
        if (!parse_long(val, 1, 1000000000000L, &cli->max_points))
            return usage_error("--max-points expects a positive number of points, found '%s'%s", val, "", 0);
    } else return parse_shard(cli, val);
    return 0;
}

/* One argument at argv[*i] (advanced past its value): 0, or the exit
 * status to end with (--help, --version, --list-analyses: 0; errors: 2). */
static int parse_arg(cli_t *cli, int argc, char **argv, int *i)
{
    const char *a = argv[*i];
    if (strcmp(a, "--json") == 0) cli->json = 1;
    else if (strcmp(a, "--markdown") == 0) cli->markdown = 1;
    else if (strcmp(a, "--emit") == 0 || strcmp(a, "--emit=equations") == 0) {
        if (strcmp(a, "--emit") == 0) {
            if (*i + 1 >= argc || strcmp(argv[*i + 1], "equations") != 0)
                return usage_error("--emit expects 'equations'%s%s", "", "", 0);
            (*i)++;
        }
        cli->emit = 1;
    }
    else if (strcmp(a, "--latex") == 0) cli->latex = 1;
    else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) { usage(stdout); return 0; }
    else if (strcmp(a, "--version") == 0) { printf("recstab %s\n", RS_VERSION); return 0; }
    else if (strcmp(a, "--list-analyses") == 0) { rs_analysis_list(stdout, 0); return 0; }
    else if (strcmp(a, "--progress") == 0) cli->progress = 1;
    else if (strcmp(a, "--csv") == 0 || strcmp(a, "--plot") == 0 || strcmp(a, "--shard") == 0
             || strcmp(a, "--plot-script") == 0 || strcmp(a, "--plot-size") == 0 || strcmp(a, "--json-rows") == 0
             || strcmp(a, "--threads") == 0 || strcmp(a, "--max-points") == 0
             || strcmp(a, "--sweep-level") == 0) {
        if (*i + 1 >= argc) return usage_error("%s needs a value%s", a, "", 1);
        if (parse_sweep_option(cli, a, argv[++*i]) != 0) return 2;
    } else if (strcmp(a, "--set") == 0 || strcmp(a, "--analyse") == 0 || strcmp(a, "--analyze") == 0
               || strcmp(a, "--max-prec") == 0) {
        if (*i + 1 >= argc) return usage_error("%s needs a value%s", a, "", 1);
        if (strcmp(a, "--set") == 0) cli->sets[cli->nsets++] = argv[++*i];
        else if (strcmp(a, "--max-prec") == 0) {
            long v;
            if (!parse_long(argv[++*i], 16, 10000000, &v))
                return usage_error("--max-prec expects bits between 16 and 10000000, found '%s'%s", argv[*i], "", 0);
            cli->opt.max_prec = v;
        } else cli->analyses[cli->nanalyses++] = argv[++*i];
    } else if (strcmp(a, "--time-limit") == 0 || strcmp(a, "--memory-limit") == 0) {
        long v;
        if (*i + 1 >= argc || !parse_long(argv[*i + 1], 0, 100000000L, &v))
            return usage_error("%s expects a whole number (0 = no limit) up to 100000000, found '%s'", a,
                               *i + 1 < argc ? argv[*i + 1] : "nothing", 0);
        if (a[2] == 't') cli->opt.time_limit = (double) v;
        else cli->opt.memory_limit = v;
        (*i)++;
    } else if (strcmp(a, "--row-share") == 0 || strcmp(a, "--expand-seconds") == 0) {
        /* the per-row share and the expansion budget of the not-expanded
         * mode of `hurwitz` (issue 17) */
        char *end = NULL;
        double v = 0.0;
        if (*i + 1 < argc) v = strtod(argv[*i + 1], &end);
        if (*i + 1 >= argc || argv[*i + 1][0] == '\0' || *end != '\0' || !(v >= 0.0 && v <= 1e8))
            return usage_error("%s expects seconds between 0 and 100000000, found '%s'", a,
                               *i + 1 < argc ? argv[*i + 1] : "nothing", 0);
        if (a[2] == 'r') rs_hurwitz_set_row_seconds(v);
        else rs_hurwitz_set_expand_seconds(v);
        (*i)++;
    } else if (strncmp(a, "--set=", 6) == 0) cli->sets[cli->nsets++] = a + 6;
    else if (strncmp(a, "--analyse=", 10) == 0 || strncmp(a, "--analyze=", 10) == 0)
        cli->analyses[cli->nanalyses++] = a + 10;
    else if (a[0] == '-' && a[1] != '\0') return usage_error("unknown option '%s'%s", a, "", 1);
    else cli->cases[cli->ncases++] = a;
    return -1;
}

/* All arguments: -1 to go on, else the exit status. */
static int parse_args(cli_t *cli, int argc, char **argv)
{
    int i, r;
    for (i = 1; i < argc; i++)
        if ((r = parse_arg(cli, argc, argv, &i)) >= 0) return r;
    if (cli->json + cli->markdown + cli->latex > 1)
        return usage_error("choose one of --json, --markdown, --latex%s%s", "", "", 0);
    cli->opt.with_scheme = cli->markdown || cli->latex;
    return -1;
}

/* The sweeps' and maps' options (they travel in the run's options) and
 * threads, before the first case. */
static void sweep_setup(cli_t *cli, progress_t *pg)
{
#ifdef _OPENMP
    if (cli->threads > 0) omp_set_num_threads((int) cli->threads);
#endif
    cli->opt.sweep.shard_index = cli->shard_i;
    cli->opt.sweep.shard_count = cli->shard_n;
    cli->opt.sweep.max_points = cli->max_points;
    cli->opt.sweep.first_level = cli->first_level;
    cli->opt.sweep.json_rows = cli->json_rows;
    /* maps stream their tables to temporary files (spool.h), read back
     * when the outputs are written: never a whole map in memory */
    cli->opt.sweep.table_spool = rs_cli_spool_open;
    cli->opt.sweep.table_spool_arg = NULL;
    memset(pg, 0, sizeof *pg);
    pg->tty = isatty(2);
    if (cli->rank == 0 && (pg->tty || cli->progress)) {
        cli->opt.sweep.progress = progress;
        cli->opt.sweep.progress_arg = pg;
    }
}

/* One case run by the library's driver (--set, --analyse, --emit applied)
 * and its document appended to docs; 0, or the exit status after printing
 * the error.  *worst: the worst outcome so far (exit 1 or 3). */
static int run_case(const cli_t *cli, const char *path, json_t *docs, double t0, int *worst)
{
    rs_run_options_t ro;
    rs_error_t err;
    json_t *doc = NULL;
    int outcome = 0, r;
    ro.sets = cli->sets;
    ro.nsets = cli->nsets;
    ro.analyses = cli->analyses;
    ro.nanalyses = cli->nanalyses;
    ro.emit = cli->emit;
    ro.opt = cli->opt;
    ro.opt.time_spent = mono_seconds() - t0;
    rs_error_init(err);
    r = rs_run_case(&doc, &outcome, path, NULL, &ro, err);
    if (r != RS_OK) {
        char msg[2 * RS_ERROR_MSG_LEN];
        rs_error_format(msg, sizeof msg, err);
        fprintf(stderr, "recstab: %s\n", msg);
        return rs_run_exit_status(r, 0, 0);
    }
    *worst = rs_run_exit_status(RS_OK, outcome, *worst);
    json_array_append_new(docs, doc);
    return 0;
}

/* The report of every case in the chosen form. */
static void render(FILE *out, const cli_t *cli, json_t *docs)
{
    size_t k;
    if (cli->emit) {
        for (k = 0; k < json_array_size(docs); k++) {
            json_t *e = json_array_get(docs, k);
            fprintf(out, "# %s\n%s", json_string_value(json_object_get(e, "case")),
                    json_string_value(json_object_get(e, "equations")));
        }
    } else if (cli->json) {
        /* the rows of streamed maps go from their spools to out one by one */
        json_t *top = rs_run_json_document(docs, cli->ncases);
        rs_run_json_dumpf_polytext(out, top, rs_cli_spool_get, NULL, cli->opt.polytext);
        json_decref(top);
    } else if (cli->markdown) {
        for (k = 0; k < json_array_size(docs); k++) rs_derivation_markdown(out, json_array_get(docs, k));
    } else if (cli->latex) {
        rs_derivation_latex_begin(out);
        for (k = 0; k < json_array_size(docs); k++) rs_derivation_latex(out, json_array_get(docs, k), 0);
        rs_derivation_latex_end(out);
    } else {
        for (k = 0; k < json_array_size(docs); k++) {
            if (k > 0) fputc('\n', out);
            rs_report_text_polytext(out, json_array_get(docs, k), cli->opt.polytext);
        }
    }
}

/* Every case, under the time limit's backstop: 0 or the exit status. */
static int run_cases(const cli_t *cli, json_t *docs, int *worst)
{
    double t0;
    int i, rc = 0;
    snprintf(budget_alarm_msg, sizeof budget_alarm_msg, "time limit of %g s reached; raise it with --time-limit",
             cli->opt.time_limit);
    t0 = mono_seconds();
    rs_budget_set_fatal(budget_fatal);
    if (cli->opt.time_limit > 0) {
        /* backstop one second after the limit; the cases share the limit */
        signal(SIGALRM, budget_alarm);
        alarm((unsigned) cli->opt.time_limit + 1);
    }
    for (i = 0; i < cli->ncases && rc == 0; i++) rc = run_case(cli, cli->cases[i], docs, t0, worst);
    alarm(0);   /* the analyses are done: no backstop while writing */
    return rc;
}

/* The sweep/map files staged beside their targets (renamed only once
 * everything succeeded), the report rendered and everything committed. */
static int write_outputs(const cli_t *cli, json_t *docs, rs_cli_outs_t *set, rs_cli_out_t *csv_out,
                         rs_cli_out_t *script_out, int worst)
{
    slong report = -1;
    char *outbuf = NULL;
    size_t outlen = 0;
    FILE *out;
    int rc;
    if (cli->rank == 0 && set->n > 0) {
        char msg[1200];
        if (cli->nplots > 0 && rs_cli_plot_stage(set->o + (csv_out != NULL), cli->nplots, script_out, cli->plot_w,
                                                 cli->plot_h, docs, msg, sizeof msg) != 0) {
            fprintf(stderr, "recstab: %s\n", msg);
            return 2;
        }
        if (csv_out != NULL && rs_cli_csv_stage(csv_out, set, docs, cli->shard_i, cli->shard_n, msg, sizeof msg) != 0) {
            fprintf(stderr, "recstab: %s\n", msg);
            return 2;
        }
    }
    if (!cli->json) rs_cli_trim_tables(docs, cli->csv_path != NULL, 200);
    /* the report is staged like the files (a map's JSON rows can be
     * hundreds of MB): an unlinked temporary file, copied out at the commit */
    /* (in memory when no temporary file can be made) */
    out = rs_cli_spool_open(NULL, &report);
    if (out == NULL) out = open_memstream(&outbuf, &outlen);
    render(out, cli, docs);
    if (report < 0) fclose(out);
    else if (fflush(out) != 0 || ferror(out)) {
        fprintf(stderr, "recstab: cannot write the report to its temporary file: %s\n", strerror(errno));
        return 2;
    }
    if (cli->rank != 0) {
        report = -1;
        outlen = 0;
    }
    rc = outputs_commit(set->o, cli->rank == 0 ? set->n : 0, report, outbuf, outlen,
                        cli->csv_path != NULL && strcmp(cli->csv_path, "-") == 0 ? stderr : stdout) != 0 ? 2 : worst;
    free(outbuf);
    return rc;
}

int main(int argc, char **argv)
{
    cli_t cli;
    progress_t pg;
    json_t *docs = json_array();
    rs_cli_outs_t set;
    rs_cli_out_t *csv_out = NULL, *script_out = NULL;
    rs_polytext_t pt;
    int i, worst = 0, rc;

    memset(&cli, 0, sizeof cli);
    set.n = 0;
    cli.sets = calloc((size_t) argc, sizeof(char *));
    cli.analyses = calloc((size_t) argc, sizeof(char *));
    cli.cases = calloc((size_t) argc, sizeof(char *));
    cli.shard_i = cli.shard_n = 1;
    cli.max_points = RS_SWEEP_MAX_POINTS_DEFAULT;
    cli.json_rows = -1;
    cli.plot_paths = calloc((size_t) argc, sizeof(char *));
    cli.first_level = RS_LEVEL_FAST;
#ifdef RS_MPI
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &cli.rank);
    if (cli.rank != 0) {
        /* every rank runs the same analyses; only rank 0 writes anything */
        if (freopen("/dev/null", "w", stdout) == NULL || freopen("/dev/null", "w", stderr) == NULL) return 2;
    }
#endif
    rs_options_default(&cli.opt);
    /* GSL's error handler, set once for the whole process: off, so that a
     * failing GSL call (the sweep ladder's double root finder, OpenMP
     * workers included) returns its status instead of aborting */
    gsl_set_error_handler_off();
    raise_stack_limit();
    rs_polytext_init(pt);
    rc = parse_args(&cli, argc, argv);
    if (rc >= 0) goto end;
    /* the text report and --json print long polynomials straight from the
     * polynomial (issue 17); the derivations read every string */
    if (!cli.markdown && !cli.latex && !cli.emit) cli.opt.polytext = pt;
    if (outputs_init(&cli, &set, &csv_out, &script_out) != 0) {
        rc = 2;
        goto end;
    }
    sweep_setup(&cli, &pg);
    if (cli.ncases == 0) {
        rc = usage_error("expected a case file (or - for stdin)%s%s", "", "", 1);
        goto end;
    }
    rc = run_cases(&cli, docs, &worst);
    if (rc == 0) rc = write_outputs(&cli, docs, &set, csv_out, script_out, worst);
end:
    /* rs_cli_out_clear frees the further CSV files the run made */
    for (i = 0; i < set.n; i++) {
        int owned = set.o[i]->owned;
        rs_cli_out_clear(set.o[i]);
        if (!owned) free(set.o[i]);
    }
    rs_cli_signals_stop();
    rs_cli_spools_close();
    json_decref(docs);
    rs_polytext_clear(pt);
    free(cli.sets); free(cli.analyses); free(cli.cases); free(cli.plot_paths);
#ifdef RS_MPI
    MPI_Finalize();
#endif
    return rc;
}
