/* main.c -- the recstab command.  All output is buffered and written only
 * when every case succeeded, so a failing run leaves no partial output. */
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
#include "recstab/sweep.h"
#include "plot.h"
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/scheme.h"
#include "recstab/report.h"
#include "recstab/derivation.h"

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
          "  --csv FILE                     write the tables of the run's sweeps and maps (atomically;\n"
          "                                 - = stdout, the report then goes to stderr)\n"
          "  --plot FILE.png|FILE.svg       plot them with gnuplot (sweeps of several cases overlaid)\n"
          "  --shard I/N                    compute only shard I of N of every sweep and map\n"
          "  --threads N                    OpenMP threads for sweeps and maps (default: all cores)\n"
          "  --max-points N                 limit of points per sweep or map (default 4000000)\n"
          "  --sweep-level LEVEL            benchmarking: start the verdict ladder at fast, prec128,\n"
          "                                 prec256 or exact; double = uncertified GSL roots only\n"
          "  --emit equations               print the unknowns and equations the builders generated\n"
          "  --time-limit SECONDS           wall time for the whole run (default 600; 0 = none)\n"
          "  --memory-limit MB              memory for the computation (default half of the RAM; 0 = none)\n"
          "  --list-analyses                the analyses, their options and the models they apply to\n"
          "  --help, --version\n"
          "exit status: 0 done; 1 an expectation or claim failed; 2 bad input or usage;\n"
          "             3 internal inconsistency (two independent methods disagree)\n"
          "analyses (--list-analyses for their options): ", f);
    rs_analysis_list(f, 1);
}

/* progress of long sweeps and maps, only when stderr is a terminal */
static void progress(void *arg, const char *what, slong done, slong total)
{
    (void) arg;
    if (done >= total) fputs("\r\033[K", stderr);
    else fprintf(stderr, "\rrecstab: %s: %ld/%ld points (%ld%%)", what, (long) done, (long) total,
                 (long) (100 * done / (total > 0 ? total : 1)));
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

static int exit_code_for(int code)
{
    /* an internal error is a bug, like two methods disagreeing */
    return (code == RS_ERR_INCONSISTENT || code == RS_ERR_INTERNAL) ? 3 : 2;
}

/* Checks the --csv / --plot targets before any work and starts the signal
 * thread (before OpenMP starts threads: they inherit its signal mask). */
static int outputs_init(rs_cli_out_t *csv, const char *csv_path, rs_cli_out_t *plot, const char *plot_path,
                        rs_cli_out_t **outs, int *nouts)
{
    char msg[1200];
    *nouts = 0;
    if (csv_path != NULL) {
        if (rs_cli_out_init(csv, "--csv", csv_path, msg, sizeof msg) != 0) goto fail;
        outs[(*nouts)++] = csv;
    }
    if (plot_path != NULL) {
        if (rs_cli_out_init(plot, "--plot", plot_path, msg, sizeof msg) != 0) goto fail;
        outs[(*nouts)++] = plot;
    }
    if (*nouts > 0) {
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
static int outputs_commit(rs_cli_out_t **outs, int nouts, const char *report, size_t len, FILE *to)
{
    char msg[1200];
    int k;
    if (rs_cli_out_rename(outs, nouts, msg, sizeof msg) != 0) goto fail;
    for (k = 0; k < nouts; k++)
        if (rs_cli_out_write_through(outs[k], msg, sizeof msg) != 0) goto undo;
    if (fwrite(report, 1, len, to) != len || fflush(to) != 0) {
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

int main(int argc, char **argv)
{
    int json = 0, markdown = 0, latex = 0, emit = 0, i, worst = 0;
    const char **sets = calloc((size_t) argc, sizeof(char *));
    const char **analyses = calloc((size_t) argc, sizeof(char *));
    const char **cases = calloc((size_t) argc, sizeof(char *));
    int nsets = 0, nanalyses = 0, ncases = 0, rc = 0;
    rs_options_t opt;
    json_t *docs = json_array();
    char *outbuf = NULL;
    size_t outlen = 0;
    FILE *out;
    const char *csv_path = NULL, *plot_path = NULL;
    rs_cli_out_t csv_out, plot_out, *outs[2];
    int nouts = 0;
    long shard_i = 1, shard_n = 1, threads = 0, max_points = RS_SWEEP_MAX_POINTS_DEFAULT;
    int rank = 0, first_level = RS_LEVEL_FAST;
    double budget_t0;

#ifdef RS_MPI
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0) {
        /* every rank runs the same analyses; only rank 0 writes anything */
        if (freopen("/dev/null", "w", stdout) == NULL || freopen("/dev/null", "w", stderr) == NULL) return 2;
    }
#endif
    rs_options_default(&opt);
    /* GSL's error handler, set once for the whole process: off, so that a
     * failing GSL call (the sweep ladder's double root finder, OpenMP
     * workers included) returns its status instead of aborting */
    gsl_set_error_handler_off();
    raise_stack_limit();
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--json") == 0) json = 1;
        else if (strcmp(a, "--markdown") == 0) markdown = 1;
        else if (strcmp(a, "--emit") == 0 || strcmp(a, "--emit=equations") == 0) {
            if (strcmp(a, "--emit") == 0) {
                if (i + 1 >= argc || strcmp(argv[i + 1], "equations") != 0) {
                    fprintf(stderr, "recstab: --emit expects 'equations'\n");
                    rc = 2;
                    goto end;
                }
                i++;
            }
            emit = 1;
        }
        else if (strcmp(a, "--latex") == 0) latex = 1;
        else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) { usage(stdout); rc = 0; goto end; }
        else if (strcmp(a, "--version") == 0) { printf("recstab %s\n", RS_VERSION); rc = 0; goto end; }
        else if (strcmp(a, "--list-analyses") == 0) { rs_analysis_list(stdout, 0); rc = 0; goto end; }
        else if (strcmp(a, "--csv") == 0 || strcmp(a, "--plot") == 0 || strcmp(a, "--shard") == 0
                 || strcmp(a, "--threads") == 0 || strcmp(a, "--max-points") == 0
                 || strcmp(a, "--sweep-level") == 0) {
            const char *val;
            if (i + 1 >= argc) {
                fprintf(stderr, "recstab: %s needs a value\n", a);
                usage(stderr);
                rc = 2;
                goto end;
            }
            val = argv[++i];
            if (strcmp(a, "--csv") == 0) csv_path = val;
            else if (strcmp(a, "--plot") == 0) plot_path = val;
            else if (strcmp(a, "--threads") == 0) {
                if (!parse_long(val, 1, 4096, &threads)) {
                    fprintf(stderr, "recstab: --threads expects a number of threads from 1 to 4096, found '%s'\n", val);
                    rc = 2;
                    goto end;
                }
            } else if (strcmp(a, "--sweep-level") == 0) {
                static const char *const lv[] = {"fast", "prec128", "prec256", "exact", "double"};
                int k2;
                first_level = -1;
                for (k2 = 0; k2 < 5; k2++) if (strcmp(val, lv[k2]) == 0) first_level = k2;
                if (first_level < 0) {
                    fprintf(stderr, "recstab: --sweep-level expects fast, prec128, prec256, exact or double, found '%s'\n", val);
                    rc = 2;
                    goto end;
                }
            } else if (strcmp(a, "--max-points") == 0) {
                if (!parse_long(val, 1, 1000000000000L, &max_points)) {
                    fprintf(stderr, "recstab: --max-points expects a positive number of points, found '%s'\n", val);
                    rc = 2;
                    goto end;
                }
            } else {
                char *slash;
                const char *bad = NULL;
                char tmp[64];
                snprintf(tmp, sizeof tmp, "%s", val);
                slash = strchr(tmp, '/');
                if (slash == NULL) bad = val;
                else {
                    *slash = '\0';
                    if (!parse_long(tmp, 1, 1000000000L, &shard_i) || !parse_long(slash + 1, 1, 1000000000L, &shard_n)
                        || shard_i > shard_n) bad = val;
                }
                if (bad) {
                    fprintf(stderr, "recstab: --shard expects I/N with 1 <= I <= N (e.g. 2/4), found '%s'\n", val);
                    rc = 2;
                    goto end;
                }
            }
        } else if (strcmp(a, "--set") == 0 || strcmp(a, "--analyse") == 0 || strcmp(a, "--analyze") == 0
                 || strcmp(a, "--max-prec") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "recstab: %s needs a value\n", a);
                usage(stderr);
                rc = 2;
                goto end;
            }
            if (strcmp(a, "--set") == 0) sets[nsets++] = argv[++i];
            else if (strcmp(a, "--max-prec") == 0) {
                char *endp;
                long v = strtol(argv[++i], &endp, 10);
                if (*endp != '\0' || v < 16 || v > 10000000) {
                    fprintf(stderr, "recstab: --max-prec expects bits between 16 and 10000000, found '%s'\n", argv[i]);
                    rc = 2;
                    goto end;
                }
                opt.max_prec = v;
            } else analyses[nanalyses++] = argv[++i];
        } else if (strcmp(a, "--time-limit") == 0 || strcmp(a, "--memory-limit") == 0) {
            long v;
            if (i + 1 >= argc || !parse_long(argv[i + 1], 0, 100000000L, &v)) {
                fprintf(stderr, "recstab: %s expects a whole number (0 = no limit) up to 100000000, found '%s'\n",
                        a, i + 1 < argc ? argv[i + 1] : "nothing");
                rc = 2;
                goto end;
            }
            if (a[2] == 't') opt.time_limit = (double) v;
            else opt.memory_limit = v;
            i++;
        } else if (strncmp(a, "--set=", 6) == 0) sets[nsets++] = a + 6;
        else if (strncmp(a, "--analyse=", 10) == 0 || strncmp(a, "--analyze=", 10) == 0)
            analyses[nanalyses++] = a + 10;
        else if (a[0] == '-' && a[1] != '\0') {
            fprintf(stderr, "recstab: unknown option '%s'\n", a);
            usage(stderr);
            rc = 2;
            goto end;
        } else cases[ncases++] = a;
    }
    if (json + markdown + latex > 1) {
        fprintf(stderr, "recstab: choose one of --json, --markdown, --latex\n");
        rc = 2;
        goto end;
    }
    opt.with_scheme = markdown || latex;
    if (outputs_init(&csv_out, csv_path, &plot_out, plot_path, outs, &nouts) != 0) {
        rc = 2;
        goto end;
    }
#ifdef _OPENMP
    if (threads > 0) omp_set_num_threads((int) threads);
#endif
    opt.sweep.shard_index = shard_i;
    opt.sweep.shard_count = shard_n;
    opt.sweep.max_points = max_points;
    opt.sweep.first_level = first_level;
    if (rank == 0 && isatty(2)) opt.sweep.progress = progress;
    if (ncases == 0) {
        fprintf(stderr, "recstab: expected a case file (or - for stdin)\n");
        usage(stderr);
        rc = 2;
        goto end;
    }
    snprintf(budget_alarm_msg, sizeof budget_alarm_msg, "time limit of %g s reached; raise it with --time-limit",
             opt.time_limit);
    budget_t0 = mono_seconds();
    rs_budget_set_fatal(budget_fatal);
    if (opt.time_limit > 0) {
        /* backstop one second after the limit; the cases share the limit */
        signal(SIGALRM, budget_alarm);
        alarm((unsigned) opt.time_limit + 1);
    }
    for (i = 0; i < ncases; i++) {
        rs_case_t c;
        rs_error_t err;
        json_t *doc = NULL;
        int outcome = 0, r, k;
        rs_case_init(c);
        rs_error_init(err);
        r = rs_case_parse_file(c, cases[i], err);
        for (k = 0; r == RS_OK && k < nsets; k++)
            r = rs_case_set_value(c, sets[k], err);
        if (r == RS_OK && nanalyses > 0) {
            rs_case_clear_requests(c);
            for (k = 0; k < nanalyses; k++) {
                const char *t = analyses[k];
                char *line;
                while (*t == ' ') t++;
                line = malloc(strlen(t) + 1);
                strcpy(line, t);
                if (strncmp(line, "analyse ", 8) == 0 || strncmp(line, "analyze ", 8) == 0)
                    memmove(line, line + 8, strlen(line + 8) + 1);
                rs_case_add_request(c, line, "--analyse", 0, 0);
                free(line);
            }
        }
        if (r == RS_OK && emit) {
            rs_model_t m;
            rs_model_init(m);
            r = rs_model_lower(m, c, err);
            if (r == RS_OK) {
                json_t *e = json_object();
                char *shown = rs_utf8_escape(cases[i]);
                json_object_set_new(e, "case", json_string(shown));
                flint_free(shown);
                char *eqs = rs_model_emit_equations(m);
                json_object_set_new(e, "equations", json_string(eqs ? eqs : "# no builder statements: the case's own equations\n"));
                flint_free(eqs);
                json_array_append_new(docs, e);
                rs_model_clear(m);
                rs_case_clear(c);
                continue;
            }
            rs_model_clear(m);
        }
        if (r == RS_OK) {
            rs_options_t o = opt;
            o.time_spent = mono_seconds() - budget_t0;
            r = rs_analysis_run(&doc, &outcome, c, &o, err);
        }
        if (r != RS_OK) {
            char msg[2 * RS_ERROR_MSG_LEN];
            rs_error_format(msg, sizeof msg, err);
            fprintf(stderr, "recstab: %s\n", msg);
            rs_case_clear(c);
            rc = exit_code_for(r);
            goto end;
        }
        if (outcome & RS_OUTCOME_INCONSISTENT) worst = 3;
        else if ((outcome & RS_OUTCOME_FAILED) && worst == 0) worst = 1;
        json_array_append_new(docs, doc);
        rs_case_clear(c);
    }
    alarm(0);   /* the analyses are done: no backstop while writing */
    /* sweep/map files: staged beside their targets, renamed only once
     * everything succeeded */
    if (rank == 0 && (csv_path != NULL || plot_path != NULL)) {
        char msg[1200];
        if (plot_path != NULL && rs_cli_plot_stage(&plot_out, docs, msg, sizeof msg) != 0) {
            fprintf(stderr, "recstab: %s\n", msg);
            rc = 2;
            goto end;
        }
        if (csv_path != NULL && rs_cli_csv_stage(&csv_out, docs, shard_i, shard_n, msg, sizeof msg) != 0) {
            fprintf(stderr, "recstab: %s\n", msg);
            rc = 2;
            goto end;
        }
    }
    rs_cli_trim_tables(docs, csv_path != NULL, 200);
    out = open_memstream(&outbuf, &outlen);
    if (emit) {
        size_t k;
        for (k = 0; k < json_array_size(docs); k++) {
            json_t *e = json_array_get(docs, k);
            fprintf(out, "# %s\n%s", json_string_value(json_object_get(e, "case")),
                    json_string_value(json_object_get(e, "equations")));
        }
    } else if (json) {
        json_t *top = (ncases == 1) ? json_incref(json_array_get(docs, 0))
                                    : json_pack("{s:O}", "cases", docs);
        json_dumpf(top, out, JSON_INDENT(2) | JSON_PRESERVE_ORDER);
        fputc('\n', out);
        json_decref(top);
    } else if (markdown) {
        size_t k;
        for (k = 0; k < json_array_size(docs); k++) rs_derivation_markdown(out, json_array_get(docs, k));
    } else if (latex) {
        size_t k;
        rs_derivation_latex_begin(out);
        for (k = 0; k < json_array_size(docs); k++) rs_derivation_latex(out, json_array_get(docs, k), 0);
        rs_derivation_latex_end(out);
    } else {
        size_t k;
        for (k = 0; k < json_array_size(docs); k++) {
            if (k > 0) fputc('\n', out);
            rs_report_text(out, json_array_get(docs, k));
        }
    }
    fclose(out);
    if (rank != 0) outlen = 0;
    rc = outputs_commit(outs, rank == 0 ? nouts : 0, outbuf, outlen,
                        csv_path != NULL && strcmp(csv_path, "-") == 0 ? stderr : stdout) != 0 ? 2 : worst;
    free(outbuf);
end:
    for (i = 0; i < nouts; i++) rs_cli_out_clear(outs[i]);
    rs_cli_signals_stop();
    json_decref(docs);
    free(sets); free(analyses); free(cases);
#ifdef RS_MPI
    MPI_Finalize();
#endif
    return rc;
}
