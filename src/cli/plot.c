/* plot.c -- CSV files and gnuplot plots of the sweeps and maps of a run.
 * The library computes the tables (CSV text in the JSON elements); this file
 * only writes them and calls gnuplot (Debian gnuplot-nox). */
#include <errno.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <fcntl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <sys/stat.h>
#include <jansson.h>
#include "plot.h"
#include "spool.h"
#include "recstab/casefile.h"

typedef struct {
    const char *case_path;
    const char *title;
    json_t *el;
    json_t *labels;     /* the case's `label NAME = "TEXT"` values, or NULL */
} tab_t;

static const char *jstr(const json_t *o, const char *k)
{
    const json_t *v = json_object_get(o, k);
    return json_is_string(v) ? json_string_value(v) : NULL;
}

static size_t collect(json_t *docs, tab_t *out)
{
    size_t n = 0, i, k;
    for (i = 0; i < json_array_size(docs); i++) {
        json_t *d = json_array_get(docs, i), *res = json_object_get(d, "results");
        for (k = 0; k < json_array_size(res); k++) {
            json_t *o = json_array_get(res, k);
            const char *a = jstr(o, "analysis");
            if (a == NULL || (strcmp(a, "sweep") != 0 && strcmp(a, "map") != 0) || (jstr(o, "table") == NULL && rs_cli_spool_of(o) < 0))
                continue;
            if (out) {
                out[n].case_path = jstr(d, "case");
                out[n].title = jstr(d, "title");
                out[n].el = o;
                out[n].labels = json_object_get(d, "labels");
            }
            n++;
        }
    }
    return n;
}

size_t rs_cli_count_tables(json_t *docs) { return collect(docs, NULL); }

/* a user string inside a "# ..." line of the CSV: control characters
 * (a newline in a file name) would start a line of their own */
static void put_comment_text(FILE *f, const char *s)
{
    for (; s && *s; s++) fputc((unsigned char) *s < 0x20 || *s == 0x7f ? ' ' : *s, f);
}

static size_t count_rows(const char *t)
{
    size_t n = 0;
    for (; *t; t++) if (*t == '\n') n++;
    return n > 0 ? n - 1 : 0;   /* minus the column header */
}

/* ---- output files and their cleanup -------------------------------------------------
 * The outputs of the run and the plot's private folder are registered here;
 * every change of their state happens under `tidy_lock`, which the signal
 * thread takes before it removes temporaries, undoes renames and exits. */

static pthread_mutex_t tidy_lock = PTHREAD_MUTEX_INITIALIZER;
static rs_cli_out_t *tidy_outs[RS_CLI_MAX_OUTS];
static int ntidy_outs;
static char tidy_dir[4096];   /* the plot's private folder, "" when none */
static size_t tidy_dir_files;
static pid_t tidy_child;      /* gnuplot while it runs */

static void rm_dir(const char *dir, size_t nfiles);
static const char *ext_of(const char *path);

int rs_cli_out_init(rs_cli_out_t *o, const char *option, const char *path, char *err, size_t errlen)
{
    struct stat st;
    memset(o, 0, sizeof *o);
    o->option = option;
    o->path = path;
    if (strcmp(option, "--plot") == 0 && strcmp(ext_of(path), "png") != 0 && strcmp(ext_of(path), "svg") != 0
        && strcmp(ext_of(path), "pdf") != 0) {
        snprintf(err, errlen, "--plot: expected a file name ending in .pdf, .png or .svg, found '%s'", path);
        return -1;
    }
    if (strcmp(path, "-") == 0 && strcmp(option, "--csv") == 0) o->through = 1;
    else if (lstat(path, &st) != 0) {
        if (errno != ENOENT) {
            snprintf(err, errlen, "%s: cannot use '%s': %s", option, path, strerror(errno));
            return -1;
        }
    } else if (S_ISLNK(st.st_mode)) {
        snprintf(err, errlen, "%s: '%s' is a symbolic link: give the path of the file itself "
                 "(recstab replaces only regular files)", option, path);
        return -1;
    } else if (S_ISDIR(st.st_mode) || S_ISSOCK(st.st_mode)) {
        snprintf(err, errlen, "%s: '%s' is a %s: expected a file name", option, path,
                 S_ISDIR(st.st_mode) ? "folder" : "socket");
        return -1;
    } else if (S_ISREG(st.st_mode)) o->existed = 1;

    else o->through = 1;   /* a device or FIFO: written through, never replaced */
    pthread_mutex_lock(&tidy_lock);
    if (ntidy_outs < RS_CLI_MAX_OUTS) tidy_outs[ntidy_outs++] = o;
    pthread_mutex_unlock(&tidy_lock);
    return 0;
}

/* unlocked: removes the temporary, undoes a rename */
static void out_undo(rs_cli_out_t *o)
{
    if (o->tmp != NULL) unlink(o->tmp);
    if (o->renamed) {
        if (o->backup != NULL) rename(o->backup, o->path);
        else if (!o->existed) unlink(o->path);
        o->renamed = 0;
    }
}

static void out_forget(rs_cli_out_t *o)
{
    free(o->tmp);
    free(o->backup);
    o->tmp = o->backup = NULL;
}

void rs_cli_out_clear(rs_cli_out_t *o)
{
    int k;
    pthread_mutex_lock(&tidy_lock);
    out_undo(o);
    out_forget(o);
    for (k = 0; k < ntidy_outs; k++)
        if (tidy_outs[k] == o) tidy_outs[k] = tidy_outs[--ntidy_outs];
    pthread_mutex_unlock(&tidy_lock);
    if (o->owned) {
        free((char *) o->path);
        free(o);
    }
}

/* the stage: mkstemp beside the path (renamed onto it at the end), in
 * TMPDIR for a device, FIFO or stdout; returns an fd, o->tmp set */
static int stage_open(rs_cli_out_t *o, char *err, size_t errlen)
{
    const char *tdir = getenv("TMPDIR");
    size_t n = strlen(o->path) + (tdir ? strlen(tdir) : 0) + 32;
    char *tmp = malloc(n);
    int fd;
    if (o->through) snprintf(tmp, n, "%s/recstab-out.XXXXXX", tdir && *tdir ? tdir : "/tmp");
    else snprintf(tmp, n, "%s.tmp.XXXXXX", o->path);
    pthread_mutex_lock(&tidy_lock);
    fd = mkstemp(tmp);
    if (fd >= 0) o->tmp = tmp;
    pthread_mutex_unlock(&tidy_lock);
    if (fd >= 0) {
        mode_t m = umask(0);
        umask(m);
        fchmod(fd, 0666 & ~m);   /* mkstemp's 0600 would survive the rename */
    } else {
        snprintf(err, errlen, "cannot create a temporary file %s '%s': %s", o->through ? "for" : "beside",
                 o->path, strerror(errno));
        free(tmp);
    }
    return fd;
}

/* drops a failed stage */
static void stage_drop(rs_cli_out_t *o)
{
    pthread_mutex_lock(&tidy_lock);
    if (o->tmp != NULL) unlink(o->tmp);
    out_forget(o);
    pthread_mutex_unlock(&tidy_lock);
}

int rs_cli_out_rename(rs_cli_out_t **outs, int n, char *err, size_t errlen)
{
    int k, bad = 0;
    pthread_mutex_lock(&tidy_lock);
    for (k = 0; k < n && !bad; k++) {
        rs_cli_out_t *o = outs[k];
        struct stat st;
        if (o->through || o->tmp == NULL) continue;
        /* the path may have changed since rs_cli_out_init */
        if (lstat(o->path, &st) == 0 && !S_ISREG(st.st_mode)) {
            snprintf(err, errlen, "%s: '%s' is no longer a regular file; nothing written", o->option, o->path);
            bad = 1;
            break;
        }
        o->existed = (lstat(o->path, &st) == 0);
        if (o->existed) {
            /* a hard link keeps the old file until the run is final */
            size_t m = strlen(o->tmp) + 8;
            o->backup = malloc(m);
            snprintf(o->backup, m, "%s.old", o->tmp);
            if (link(o->path, o->backup) != 0) {
                snprintf(err, errlen, "%s: cannot keep the old '%s' while replacing it: %s", o->option, o->path,
                         strerror(errno));
                free(o->backup);
                o->backup = NULL;
                bad = 1;
                break;
            }
        }
        if (rename(o->tmp, o->path) != 0) {
            snprintf(err, errlen, "%s: cannot rename '%s' to '%s': %s", o->option, o->tmp, o->path, strerror(errno));
            if (o->backup != NULL) { unlink(o->backup); free(o->backup); o->backup = NULL; }
            bad = 1;
            break;
        }
        free(o->tmp);
        o->tmp = NULL;
        o->renamed = 1;
    }
    if (bad)
        for (k = 0; k < n; k++) { out_undo(outs[k]); if (outs[k]->backup) unlink(outs[k]->backup); }
    pthread_mutex_unlock(&tidy_lock);
    return bad ? -1 : 0;
}

int rs_cli_out_write_through(rs_cli_out_t *o, char *err, size_t errlen)
{
    char buf[65536];
    int in, outfd, bad = 0;
    ssize_t got = 0;
    if (!o->through || o->tmp == NULL) return 0;
    in = open(o->tmp, O_RDONLY);
    outfd = strcmp(o->path, "-") == 0 ? 1 : open(o->path, O_WRONLY | O_NOCTTY);  /* no O_CREAT, no O_TRUNC */
    if (in < 0 || outfd < 0) bad = 1;
    while (!bad && (got = read(in, buf, sizeof buf)) > 0) {
        ssize_t off = 0;
        while (off < got) {
            ssize_t w = write(outfd, buf + off, (size_t) (got - off));
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) { bad = 1; break; }
            off += w;
        }
    }
    if (got < 0) bad = 1;
    if (bad) snprintf(err, errlen, "%s: cannot write '%s': %s", o->option, o->path, strerror(errno));
    if (in >= 0) close(in);
    if (outfd > 1 && close(outfd) != 0 && !bad) {
        snprintf(err, errlen, "%s: cannot write '%s': %s", o->option, o->path, strerror(errno));
        bad = 1;
    }
    stage_drop(o);
    return bad ? -1 : 0;
}

void rs_cli_out_undo(rs_cli_out_t **outs, int n)
{
    int k;
    pthread_mutex_lock(&tidy_lock);
    for (k = 0; k < n; k++) {
        out_undo(outs[k]);
        if (outs[k]->backup != NULL) unlink(outs[k]->backup);
        out_forget(outs[k]);
    }
    pthread_mutex_unlock(&tidy_lock);
}

void rs_cli_out_done(rs_cli_out_t **outs, int n)
{
    int k;
    pthread_mutex_lock(&tidy_lock);
    for (k = 0; k < n; k++) {
        if (outs[k]->backup != NULL) unlink(outs[k]->backup);
        outs[k]->renamed = 0;
        out_forget(outs[k]);
    }
    pthread_mutex_unlock(&tidy_lock);
}

/* Waits for SIGINT/SIGTERM (blocked in every other thread); holds the lock
 * until _exit so that main cannot commit or exit meanwhile. */
static void *signal_thread(void *arg)
{
    sigset_t *set = arg;
    int sig = 0, k;
    static const char msg[] = "recstab: interrupted; temporaries removed\n";
    if (sigwait(set, &sig) != 0) return NULL;
    pthread_setcancelstate(PTHREAD_CANCEL_DISABLE, NULL);   /* waitpid is a cancellation point */
    pthread_mutex_lock(&tidy_lock);
    if (tidy_child > 0) {
        kill(tidy_child, SIGKILL);
        waitpid(tidy_child, NULL, 0);
    }
    for (k = 0; k < ntidy_outs; k++) {
        out_undo(tidy_outs[k]);
        if (tidy_outs[k]->backup != NULL) unlink(tidy_outs[k]->backup);
    }
    if (tidy_dir[0]) rm_dir(tidy_dir, tidy_dir_files);
    if (write(2, msg, sizeof msg - 1) < 0) sig += 0;
    _exit(128 + sig);
}

static pthread_t signal_th;
static int signal_th_running;

int rs_cli_signals_start(void)
{
    static sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    /* before any other thread exists: they inherit the mask */
    if (pthread_sigmask(SIG_BLOCK, &set, NULL) != 0) return -1;
    if (pthread_create(&signal_th, NULL, signal_thread, &set) != 0) {
        pthread_sigmask(SIG_UNBLOCK, &set, NULL);
        return -1;
    }
    signal_th_running = 1;
    return 0;
}

void rs_cli_signals_stop(void)
{
    if (!signal_th_running) return;
    pthread_cancel(signal_th);   /* acts in sigwait; a signal being handled ends in _exit */
    pthread_join(signal_th, NULL);
    signal_th_running = 0;
}

/* The path of CSV file k (0: the --csv path itself) of table t (1-based)
 * or of its boundary: STEM.t.csv, STEM.boundary.csv, STEM.t.boundary.csv
 * beside PATH = STEM.csv (PATH.t... when PATH has no extension). */
static char *csv_path_of(const char *path, size_t t, int boundary)
{
    const char *slash = strrchr(path, '/'), *dot = strrchr(path, '.');
    size_t stem, n = strlen(path) + 48;
    char *p = malloc(n), num[32] = "";
    if (dot == NULL || (slash != NULL && dot < slash) || dot == path || dot[-1] == '/') dot = path + strlen(path);
    stem = (size_t) (dot - path);
    if (t > 1) snprintf(num, sizeof num, ".%zu", t);
    snprintf(p, n, "%.*s%s%s%s", (int) stem, path, num, boundary ? ".boundary" : "", dot);
    return p;
}

/* One table into its own staged file: "# " comment lines, then the
 * table (its header line first), or the spooled table `spool` when table
 * is NULL (copied: a map's table is never held in memory whole). */
static int csv_write_one(rs_cli_out_t *o, const char *comments, const char *table, slong spool, char *err,
                         size_t errlen)
{
    int fd = stage_open(o, err, errlen), bad = 0;
    FILE *f;
    if (fd < 0) return -1;
    f = fdopen(fd, "w");
    fputs(comments, f);
    if (table != NULL) fputs(table, f);
    else if (rs_cli_spool_copy(f, spool, 0) != 0) bad = 1;
    if (fflush(f) != 0 || ferror(f)) bad = 1;
    if (fclose(f) != 0) bad = 1;
    if (bad) {
        snprintf(err, errlen, "cannot write '%s': %s", o->tmp, strerror(errno));
        stage_drop(o);
        return -1;
    }
    return 0;
}

static void set_path_key(json_t *tab, const char *key, const char *path)
{
    char *shown = rs_utf8_escape(path);   /* json_string refuses invalid UTF-8 */
    json_object_set_new(tab, key, json_string(shown));
    flint_free(shown);
}

/* a further file of the run (a table after the first, a boundary) */
static rs_cli_out_t *csv_extra(rs_cli_outs_t *set, const char *path, char *err, size_t errlen)
{
    rs_cli_out_t *x;
    if (set->n >= RS_CLI_MAX_OUTS) {
        snprintf(err, errlen, "--csv: more than %d files in one run", RS_CLI_MAX_OUTS);
        return NULL;
    }
    x = calloc(1, sizeof *x);
    if (rs_cli_out_init(x, "--csv", strdup(path), err, errlen) != 0) {
        free((char *) x->path);
        free(x);
        return NULL;
    }
    x->owned = 1;
    set->o[set->n++] = x;
    return x;
}

int rs_cli_csv_stage(rs_cli_out_t *o, rs_cli_outs_t *set, json_t *docs, long shard_index, long shard_count,
                     char *err, size_t errlen)
{
    const char *path = o->path;
    size_t n = collect(docs, NULL), i;
    tab_t *tabs = calloc(n + 1, sizeof(tab_t));
    int rc = 0;
    collect(docs, tabs);
    if (o->through && (n > 1 || (n == 1 && jstr(tabs[0].el, "boundary_table") != NULL))) {
        snprintf(err, errlen, "--csv: the run has more than one table (one file each: FILE.csv, FILE.2.csv, "
                 "FILE.boundary.csv, ...): give a regular file name, not '%s'", path);
        free(tabs);
        return -1;
    }
    if (n == 0) rc = csv_write_one(o, "# recstab: no sweep or map in this run\n", "", -1, err, errlen);
    for (i = 0; i < n && rc == 0; i++) {
        json_t *tab = tabs[i].el;
        const char *bt = jstr(tab, "boundary_table");
        char *cbuf = NULL, *tpath = i == 0 ? NULL : csv_path_of(path, i + 1, 0);
        size_t clen = 0;
        FILE *c = open_memstream(&cbuf, &clen);
        rs_cli_out_t *to = i == 0 ? o : csv_extra(set, tpath, err, errlen);
        fprintf(c, "# recstab table %zu: case=", i + 1);
        put_comment_text(c, tabs[i].case_path);
        fputs("; title=", c);
        put_comment_text(c, tabs[i].title);
        fputs("; analysis=", c);
        put_comment_text(c, jstr(tab, "text"));
        fprintf(c, "; points=%lld\n", (long long) json_integer_value(json_object_get(tab, "points")));
        if (shard_count > 1) {
            json_t *rows = json_object_get(tab, "row_range");
            fprintf(c, "# shard %ld/%ld: rows %lld-%lld of table %zu\n", shard_index, shard_count,
                    (long long) json_integer_value(json_array_get(rows, 0)),
                    (long long) json_integer_value(json_array_get(rows, 1)) - 1, i + 1);
        }
        fclose(c);
        if (to == NULL) rc = -1;
        else rc = csv_write_one(to, cbuf, jstr(tab, "table"), rs_cli_spool_of(tab), err, errlen);
        free(cbuf);
        if (rc == 0) set_path_key(tab, "csv", i == 0 ? path : tpath);
        free(tpath);
        if (rc == 0 && bt != NULL) {
            json_t *conds = json_object_get(json_object_get(tab, "boundary"), "conditions");
            char *bpath = csv_path_of(path, i + 1, 1);
            size_t k;
            cbuf = NULL;
            clen = 0;
            c = open_memstream(&cbuf, &clen);
            fprintf(c, "# recstab boundary of table %zu: case=", i + 1);
            put_comment_text(c, tabs[i].case_path);
            fputs("; conditions:", c);
            for (k = 0; k < json_array_size(conds); k++) {
                json_t *cd = json_array_get(conds, k);
                fprintf(c, "%s %lld (%s) %s > 0", k ? ";" : "",
                        (long long) json_integer_value(json_object_get(cd, "index")), jstr(cd, "origin"), jstr(cd, "poly"));
            }
            fputc('\n', c);
            if (shard_count > 1)
                fprintf(c, "# shard %ld/%ld: boundary rows only in shard 1\n", shard_index, shard_count);
            fclose(c);
            to = csv_extra(set, bpath, err, errlen);
            rc = to == NULL ? -1 : csv_write_one(to, cbuf, bt, -1, err, errlen);
            if (rc == 0) set_path_key(tab, "boundary_csv", bpath);
            free(cbuf);
            free(bpath);
        }
    }
    free(tabs);
    return rc;
}

void rs_cli_trim_tables(json_t *docs, int have_csv, size_t max_rows)
{
    size_t n = collect(docs, NULL), i;
    tab_t *tabs = calloc(n + 1, sizeof(tab_t));
    collect(docs, tabs);
    for (i = 0; i < n; i++) {
        json_t *o = tabs[i].el;
        slong sp = rs_cli_spool_of(o);
        size_t rows = sp >= 0 ? (size_t) json_integer_value(json_object_get(o, "computed")) : count_rows(jstr(o, "table"));
        const char *bt = jstr(o, "boundary_table");
        if (sp >= 0 && !have_csv && rows <= max_rows) {
            /* a small spooled table is shown in the report, as one held in memory */
            char *text = rs_cli_spool_text(sp);
            json_object_set_new(o, "table", json_string(text != NULL ? text : ""));
            free(text);
        }
        if (have_csv || rows > max_rows || (bt && count_rows(bt) > max_rows)) {
            if (!have_csv) {
                char note[160];
                snprintf(note, sizeof note, "%zu rows: write the table with --csv FILE", rows);
                json_object_set_new(o, "table_note", json_string(note));
            }
            json_object_del(o, "table");
            json_object_del(o, "boundary_table");
        }
    }
    free(tabs);
}

/* ---- gnuplot ---------------------------------------------------------------------- */

/* User text (titles, file and parameter names, the output path) as a gnuplot
 * double-quoted string that is data only: letters, digits, blanks and valid
 * non-ASCII UTF-8 stay, other ASCII is written as an octal escape (so no
 * quote, backquote, '@', backslash or newline reaches the script's command
 * lines), control characters become blanks and invalid bytes U+FFFD. */
static void put_q(FILE *f, const char *s)
{
    size_t n = s ? strlen(s) : 0, i = 0;
    int esc = 0;   /* the last thing written was an octal escape */
    fputc('"', f);
    while (i < n) {
        unsigned char ch = (unsigned char) s[i];
        int k = rs_utf8_seq_len(s + i, n - i);
        if (k == 0) fputs("\357\277\275", f);
        else if (k > 1) fwrite(s + i, 1, (size_t) k, f);
        else if (ch < 0x20 || ch == 0x7f) fputc(' ', f);
        /* a digit right after an escape is escaped too: gnuplot reads
         * "\0567" as one number */
        else if ((ch >= '0' && ch <= '9' && !esc) || ((ch | 0x20) >= 'a' && (ch | 0x20) <= 'z') || ch == ' ')
            fputc(ch, f);
        else {
            fprintf(f, "\\%03o", ch);
            esc = 1;
            i++;
            continue;
        }
        esc = 0;
        i += k > 0 ? (size_t) k : 1;
    }
    fputc('"', f);
}

/* A file name for gnuplot: "|cmd" as an output and "<cmd" as a data file
 * would run cmd, so a relative name gets "./" in front. */
static void put_path(FILE *f, const char *path)
{
    char *p = malloc(strlen(path) + 3);
    sprintf(p, "%s%s", path[0] == '/' ? "" : "./", path);
    put_q(f, p);
    free(p);
}

/* the name of a table's datablock in the script ($t0, $b0: the rows of
 * table 0 and of its boundary); the script holds the data, so a kept
 * --plot-script runs on its own */
static void put_table(FILE *f, const char *dir, char kind, size_t i)
{
    (void) dir;
    fprintf(f, "$%c%zu", kind, i);
}

/* a table's rows (without its header line) as the datablock $KIND I;
 * table NULL: the spooled table `spool`, copied */
static void put_datablock(FILE *g, char kind, size_t i, const char *table, slong spool)
{
    const char *nl = table != NULL ? strchr(table, '\n') : NULL;
    fprintf(g, "$%c%zu << EOD\n", kind, i);
    if (nl != NULL) fputs(nl + 1, g);
    else if (table == NULL) rs_cli_spool_copy(g, spool, 1);
    fputs("EOD\n", g);
}

static const char *ext_of(const char *path)
{
    const char *d = strrchr(path, '.');
    return d ? d + 1 : "";
}


/* A label in LaTeX notation as plain Unicode text for gnuplot (its
 * terminals run noenhanced: no markup from user text reaches them): Greek
 * letters and a few symbols from their macros, digits and signs after _ and
 * ^ as sub- and superscripts, $ and braces dropped. */
static void latex_to_text(char *out, size_t n, const char *in)
{
    static const char *const mac[][2] = {
        {"alpha", "\u03b1"}, {"beta", "\u03b2"}, {"gamma", "\u03b3"}, {"delta", "\u03b4"}, {"epsilon", "\u03b5"},
        {"varepsilon", "\u03b5"}, {"zeta", "\u03b6"}, {"eta", "\u03b7"}, {"theta", "\u03b8"}, {"iota", "\u03b9"},
        {"kappa", "\u03ba"}, {"lambda", "\u03bb"}, {"mu", "\u03bc"}, {"nu", "\u03bd"}, {"xi", "\u03be"},
        {"pi", "\u03c0"}, {"rho", "\u03c1"}, {"sigma", "\u03c3"}, {"tau", "\u03c4"}, {"phi", "\u03c6"},
        {"varphi", "\u03c6"}, {"chi", "\u03c7"}, {"psi", "\u03c8"}, {"omega", "\u03c9"}, {"Gamma", "\u0393"},
        {"Delta", "\u0394"}, {"Theta", "\u0398"}, {"Lambda", "\u039b"}, {"Xi", "\u039e"}, {"Pi", "\u03a0"},
        {"Sigma", "\u03a3"}, {"Phi", "\u03a6"}, {"Psi", "\u03a8"}, {"Omega", "\u03a9"}, {"Re", "Re"},
        {"Im", "Im"}, {"cdot", "\u00b7"}, {"times", "\u00d7"}, {"le", "\u2264"}, {"ge", "\u2265"},
        {"infty", "\u221e"}, {"ell", "\u2113"}, {",", " "}, {";", " "}, {" ", " "}};
    static const char *const sub[] = {"\u2080", "\u2081", "\u2082", "\u2083", "\u2084", "\u2085", "\u2086",
                                      "\u2087", "\u2088", "\u2089"};
    static const char *const sup[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074", "\u2075", "\u2076",
                                      "\u2077", "\u2078", "\u2079"};
    size_t o = 0, i = 0, k;
    int script = 0;   /* 1 after _, 2 after ^, until the group or character ends */
    int group = 0;
    out[0] = '\0';
    while (in[i] && o + 8 < n) {
        const char *put = NULL;
        char one[2] = {0, 0};
        if (in[i] == '$' || ((in[i] == '{' || in[i] == '}') && !(in[i] == '}' && group))) { i++; continue; }
        if (in[i] == '}' && group) { group = 0; script = 0; i++; continue; }
        if ((in[i] == '_' || in[i] == '^') && in[i + 1]) {
            script = in[i] == '_' ? 1 : 2;
            i++;
            if (in[i] == '{') { group = 1; i++; }
            continue;
        }
        if (in[i] == '\\') {
            size_t j = i + 1, len;
            while (((in[j] | 0x20) >= 'a' && (in[j] | 0x20) <= 'z')) j++;
            if (j == i + 1 && in[j]) j++;
            len = j - i - 1;
            for (k = 0; k < sizeof mac / sizeof mac[0]; k++)
                if (strlen(mac[k][0]) == len && strncmp(mac[k][0], in + i + 1, len) == 0) put = mac[k][1];
            if (put == NULL) { one[0] = in[i + 1]; put = one; len = in[i + 1] ? 1 : 0; j = i + 1 + len; }
            i = j;
            if (in[i] == ' ' && put != one) i++;   /* the blank ending a macro name */
        } else if (script && in[i] >= '0' && in[i] <= '9') {
            const char *const *digits = script == 1 ? sub : sup;   /* not (c ? sub : sup)[k]: UBSan mis-sizes it */
            put = digits[in[i] - '0'];
            i++;
        } else if (script == 2 && in[i] == '-') { put = "\u207b"; i++; }
        else if (script == 2 && in[i] == '+') { put = "\u207a"; i++; }
        else if (script == 1 && strchr("aehijklmnoprstuvx", in[i]) != NULL && in[i] != '\0') {
            static const char *const sl[] = {"\u2090", "\u2091", "\u2095", "\u1d62", "\u2c7c", "\u2096", "\u2097",
                                             "\u2098", "\u2099", "\u2092", "\u209a", "\u1d63", "\u209b", "\u209c",
                                             "\u1d64", "\u1d65", "\u2093"};
            put = sl[strchr("aehijklmnoprstuvx", in[i]) - "aehijklmnoprstuvx"];
            i++;
        } else {
            /* a character that has no sub/superscript form: written as it is */
            size_t m = (size_t) rs_utf8_seq_len(in + i, strlen(in + i));
            if (m == 0) m = 1;
            if (o + m + 1 < n) { memcpy(out + o, in + i, m); o += m; }
            i += m;
            if (!group) script = 0;
            continue;
        }
        if (!group) script = 0;
        if (o + strlen(put) + 1 < n) { memcpy(out + o, put, strlen(put)); o += strlen(put); }
    }
    out[o] = '\0';
}

/* The label of a parameter or column name: the case's `label` text, else
 * the name itself. */
static void label_of(char *out, size_t n, const tab_t *t, const char *name)
{
    const char *l = t != NULL ? jstr(t->labels, name) : NULL;
    if (l != NULL) latex_to_text(out, n, l);
    else snprintf(out, n, "%s", name ? name : "");
}

/* A table's legend: the case's title (else its path), and the values the
 * sweep was taken at (`sweep ... at NAME=VALUE`). */
static const char *legend(const tab_t *t)
{
    static __thread char buf[1024];
    json_t *at = json_object_get(t->el, "at");
    const char *key;
    json_t *val;
    size_t o;
    snprintf(buf, sizeof buf, "%s", t->title ? t->title : t->case_path);
    if (json_object_size(at) == 0) return buf;
    o = strlen(buf);
    json_object_foreach(at, key, val) {
        char lab[256];
        label_of(lab, sizeof lab, t, key);
        if (o < sizeof buf)
            o += (size_t) snprintf(buf + o, sizeof buf - o, ", %s = %s", lab,
                                   json_string_value(val) ? json_string_value(val) : "?");
    }
    return buf;
}

static int col_index(const json_t *o, const char *name)
{
    const json_t *cols = json_object_get(o, "columns");
    size_t k;
    for (k = 0; k < json_array_size(cols); k++)
        if (strcmp(json_string_value(json_array_get(cols, k)), name) == 0) return (int) k + 1;
    return 0;
}

/* The common head of a sweep panel: the x label lists the swept parameters
 * of every sweep `of` kind, log scale when any of them is log-spaced. */
static void sweep_panel_start(FILE *g, const tab_t *tabs, size_t n, const char *kind)
{
    char xl[512] = "";
    int logx = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        const json_t *o = tabs[i].el;
        char prm[256];
        if (strcmp(jstr(o, "analysis"), "sweep") != 0 || strcmp(jstr(o, "of"), kind) != 0) continue;
        label_of(prm, sizeof prm, tabs + i, jstr(o, "param"));
        if (strcmp(jstr(o, "spacing"), "log") == 0) logx = 1;
        if (strstr(xl, prm) == NULL && strlen(xl) + strlen(prm) + 3 < sizeof xl) {
            if (xl[0]) strcat(xl, ", ");
            strcat(xl, prm);
        }
    }
    /* the legend right of the panel: never over the axis labels */
    fputs("reset\nset datafile separator ','\nset key outside right top vertical\nset grid\n", g);
    fputs("set xlabel ", g);
    put_q(g, xl);
    fputc('\n', g);
    if (logx) fputs("set logscale x\n", g);
}

static void rm_dir(const char *dir, size_t nfiles)
{
    char p[4096];
    size_t i;
    for (i = 0; i < nfiles; i++) {
        snprintf(p, sizeof p, "%s/t%zu.csv", dir, i);
        unlink(p);
        snprintf(p, sizeof p, "%s/b%zu.csv", dir, i);
        unlink(p);
    }
    snprintf(p, sizeof p, "%s/plot.gp", dir);
    unlink(p);
    snprintf(p, sizeof p, "%s/gnuplot.log", dir);
    unlink(p);
    rmdir(dir);
}

/* removes the plot's private folder */
static void plot_dir_drop(const char *dir, size_t n)
{
    pthread_mutex_lock(&tidy_lock);
    rm_dir(dir, n);
    tidy_dir[0] = '\0';
    pthread_mutex_unlock(&tidy_lock);
}

/* What one --plot draws: the tables, the folder their CSV files go to, and
 * the panels they need. */
typedef struct {
    tab_t *tabs;
    size_t n, nmaps, npanels;
    char dir[4096];
    int has_kind[3];   /* sweeps of radius, stability, modes */
    int nmodes;        /* mode panels per quantity (0: one principal-mode panel) */
} plot_t;

static const char *const plot_kinds[3] = {"radius", "stability", "modes"};

static int is_sweep_of(const json_t *tab, const char *kind)
{
    return strcmp(jstr(tab, "analysis"), "sweep") == 0 && strcmp(jstr(tab, "of"), kind) == 0;
}

/* the plot's private folder under TMPDIR, registered for the signal handler */
static int plot_dir_make(plot_t *pl, char *err, size_t errlen)
{
    const char *tdir = getenv("TMPDIR");
    snprintf(pl->dir, sizeof pl->dir, "%s/recstab-plot.XXXXXX", tdir && *tdir ? tdir : "/tmp");
    pthread_mutex_lock(&tidy_lock);
    if (mkdtemp(pl->dir) != NULL) {
        snprintf(tidy_dir, sizeof tidy_dir, "%s", pl->dir);
        tidy_dir_files = pl->n;
    }
    pthread_mutex_unlock(&tidy_lock);
    if (tidy_dir[0] == '\0') {
        snprintf(err, errlen, "--plot: cannot create a temporary directory: %s", strerror(errno));
        return -1;
    }
    return 0;
}

/* Each table (and its exact boundary) as a CSV file in the folder; counts
 * the maps and the kinds of sweep. */
static void plot_write_tables(plot_t *pl)
{
    size_t i;
    int k;
    for (i = 0; i < pl->n; i++) {
        const char *a = jstr(pl->tabs[i].el, "analysis"), *of = jstr(pl->tabs[i].el, "of");
        if (strcmp(a, "map") == 0) pl->nmaps++;
        else for (k = 0; k < 3; k++) if (of && strcmp(of, plot_kinds[k]) == 0) pl->has_kind[k] = 1;
    }
}

/* modes sweeps: one panel per quantity and reference frequency (as the
 * frequency-error / damping-ratio panels of Olivier et al.'s Fig. 12.4) */
static void plot_count_panels(plot_t *pl)
{
    size_t i;
    for (i = 0; i < pl->n; i++) {
        const json_t *tab = pl->tabs[i].el;
        int m;
        if (!is_sweep_of(tab, "modes")) continue;
        for (m = 1; m <= 8; m++) {
            char cname[32];
            snprintf(cname, sizeof cname, "damping_ratio_%d", m);
            if (col_index(tab, cname) > 0 && m > pl->nmodes) pl->nmodes = m;
        }
    }
    pl->npanels = pl->nmaps + (size_t) (pl->has_kind[0] + pl->has_kind[1])
                  + (size_t) (pl->has_kind[2] ? 2 * (pl->nmodes > 0 ? pl->nmodes : 1) : 0);
}

/* The two axes of a map are the real and imaginary parts of one number:
 * their labels start with Re and Im (`label lr1 = "Re \\Lambda_1"`), or
 * their names differ only in r and i at one place (lr1, li1; xr, xi). */
static int complex_plane(const tab_t *t, const char *a, const char *b, const char *la, const char *lb)
{
    size_t k, na = strlen(a), diff = 0, at = 0;
    (void) t;
    if (strncmp(la, "Re", 2) == 0 && strncmp(lb, "Im", 2) == 0) return 1;
    /* map re(z) ..., im(z) ... */
    if (strncmp(a, "re(", 3) == 0 && strncmp(b, "im(", 3) == 0 && strcmp(a + 3, b + 3) == 0) return 1;
    if (na != strlen(b)) return 0;
    for (k = 0; k < na; k++)
        if (a[k] != b[k]) { diff++; at = k; }
    return diff == 1 && a[at] == 'r' && b[at] == 'i';
}

/* a map: one panel, the verdict (or the radius capped at 2) over the grid */
static void plot_map_panel(FILE *g, const plot_t *pl, size_t i)
{
    json_t *tab = pl->tabs[i].el, *params = json_object_get(tab, "params"), *grid = json_object_get(tab, "grid");
    int radius = strcmp(jstr(tab, "of"), "radius") == 0;
    int undecided = json_integer_value(json_object_get(json_object_get(tab, "verdicts"), "undecided")) > 0;
    int singular = json_integer_value(json_object_get(json_object_get(tab, "verdicts"), "singular")) > 0;
    int image = json_integer_value(json_array_get(grid, 0)) > 1 && json_integer_value(json_array_get(grid, 1)) > 1;
    char xl[256], yl[256];
    /* the legend (the boundary) above the panel, the colour box right of
     * it: neither covers an axis label */
    fputs("reset\nset datafile separator ','\nset key outside top center horizontal\n", g);
    fputs("set title ", g);
    put_q(g, legend(pl->tabs + i));
    label_of(xl, sizeof xl, pl->tabs + i, json_string_value(json_array_get(params, 0)));
    label_of(yl, sizeof yl, pl->tabs + i, json_string_value(json_array_get(params, 1)));
    fputs("\nset xlabel ", g);
    put_q(g, xl);
    fputs("\nset ylabel ", g);
    put_q(g, yl);
    fputs("\nset autoscale fix\n", g);
    /* a map over the complex plane (Re and Im of one number): one unit is
     * the same length on both axes */
    if (complex_plane(pl->tabs + i, json_string_value(json_array_get(params, 0)),
                      json_string_value(json_array_get(params, 1)), xl, yl))
        fputs("set size ratio -1\n", g);
    if (json_is_array(json_object_get(tab, "plot_ranges"))) {
        /* a complex-plane map: the boundary locus may leave the grid; keep to it */
        json_t *pr = json_object_get(tab, "plot_ranges");
        fprintf(g, "set xrange [%.17g:%.17g]\nset yrange [%.17g:%.17g]\n",
                json_number_value(json_array_get(json_array_get(pr, 0), 0)),
                json_number_value(json_array_get(json_array_get(pr, 0), 1)),
                json_number_value(json_array_get(json_array_get(pr, 1), 0)),
                json_number_value(json_array_get(json_array_get(pr, 1), 1)));
    }
    if (radius)
        fputs("set cbrange [0:2]\nset cblabel 'spectral radius (capped at 2)'\n"
              "set palette defined (0 '#1a9850', 0.999 '#d9ef8b', 1 '#fee08b', 2 '#d73027')\n", g);
    else {
        /* one band per verdict code present: 0 stable, 1 marginal, 2 unstable, 3 singular (the step is not
         * determined), 4 undecided (a root on or too near the circle, marginal and unstable not told apart
         * over Q(sqrt d)); beyond 2 only when present, so the usual key keeps three entries */
        static const char *const name[5] = {"stable", "marginal", "unstable", "singular", "undecided"};
        static const char *const colour[5] = {"#1a9850", "#fee08b", "#d73027", "#7b3294", "#bababa"};
        int top = undecided ? 4 : singular ? 3 : 2, k;
        fprintf(g, "set cbrange [-0.5:%d.5]\nset cbtics (", top);
        for (k = 0; k <= top; k++) fprintf(g, "%s'%s' %d", k ? ", " : "", name[k], k);
        fputs(")\nset palette defined (", g);
        for (k = 0; k <= top; k++)
            fprintf(g, "%s%g '%s', %g '%s'", k ? ", " : "", k - 0.5, colour[k], k + 0.5, colour[k]);
        fputs(")\n", g);
    }
    fputs("plot ", g);
    put_table(g, pl->dir, 't', i);
    fprintf(g, " using %d:%d:(", col_index(tab, json_string_value(json_array_get(params, 0))),
            col_index(tab, json_string_value(json_array_get(params, 1))));
    if (radius) fprintf(g, "$%d > 2 ? 2 : $%d", col_index(tab, "radius"), col_index(tab, "radius"));
    else fprintf(g, "$%d < 0 ? NaN : $%d", col_index(tab, "code"), col_index(tab, "code"));
    fprintf(g, ") with %s notitle", image ? "image" : "points pt 5 ps 1 palette");
    if (jstr(tab, "boundary_table"))
    {
        fputs(", ", g);
        put_table(g, pl->dir, 'b', i);
        /* at complex set values the conditions are Schur-Cohn's over Q(i) */
        fputs(jstr(tab, "over") != NULL && strcmp(jstr(tab, "over"), "Q(i)") == 0
              ? " using 2:3 with points pt 7 ps 0.4 lc rgb 'black' title 'exact boundary (Schur-Cohn over Q(i))'"
              : " using 2:3 with points pt 7 ps 0.4 lc rgb 'black' "
                "title 'exact boundary (Lienard-Chipart, p(1), p(-1))'", g);
    }
    if (jstr(tab, "locus_table")) {
        /* the complex plane of one parameter: its boundary locus on top */
        fputs(", ", g);
        put_table(g, pl->dir, 'l', i);
        fputs(" using 1:2 with points pt 7 ps 0.3 lc rgb 'black' title 'boundary locus (exact parametrisation)'", g);
    }
    fputc('\n', g);
}

/* one sweep's curve(s) in the panel of kind k */
static void plot_sweep_curve(FILE *g, const plot_t *pl, size_t i, int k)
{
    json_t *tab = pl->tabs[i].el;
    int x = col_index(tab, jstr(tab, "param"));
    put_table(g, pl->dir, 't', i);
    if (k == 0) {
        fprintf(g, " using %d:%d with linespoints pt 7 ps 0.5 title ", x, col_index(tab, "radius"));
        put_q(g, legend(pl->tabs + i));
    } else if (k == 1) {
        fprintf(g, " using %d:($%d < 0 ? NaN : $%d) with steps title ", x,
                col_index(tab, "code"), col_index(tab, "code"));
        put_q(g, legend(pl->tabs + i));
    } else {
        char t2[600];
        fprintf(g, " using %d:%d with linespoints pt 7 ps 0.5 title ", x, col_index(tab, "damping_ratio_1"));
        snprintf(t2, sizeof t2, "%s: damping ratio", legend(pl->tabs + i));
        put_q(g, t2);
        fputs(", ", g);
        put_table(g, pl->dir, 't', i);
        fprintf(g, " using %d:%d with linespoints pt 6 ps 0.5 title ", x, col_index(tab, "frequency_error_1"));
        snprintf(t2, sizeof t2, "%s: frequency error", legend(pl->tabs + i));
        put_q(g, t2);
    }
}

/* sweeps: one panel per kind, every case overlaid */
static void plot_sweep_panels(FILE *g, const plot_t *pl)
{
    size_t i;
    int k;
    for (k = 0; k < 3; k++) {
        int first = 1;
        if (!pl->has_kind[k] || (k == 2 && pl->nmodes > 0)) continue;
        sweep_panel_start(g, pl->tabs, pl->n, plot_kinds[k]);
        if (k == 0) fputs("set ylabel 'spectral radius'\nset title 'certified spectral radius'\n", g);
        if (k == 1) fputs("set ylabel 'verdict'\nset yrange [-0.5:2.5]\nset ytics ('stable' 0, 'marginal' 1, "
                          "'unstable' 2)\nset title 'exact verdict'\n", g);
        if (k == 2) fputs("set ylabel 'damping ratio, frequency error'\nset title 'principal mode'\n", g);
        fputs("plot ", g);
        for (i = 0; i < pl->n; i++) {
            if (!is_sweep_of(pl->tabs[i].el, plot_kinds[k])) continue;
            if (!first) fputs(", ", g);
            first = 0;
            plot_sweep_curve(g, pl, i, k);
        }
        if (k == 0) fputs(", 1 with lines dt 2 lc rgb 'gray' title 'unit circle'", g);
        fputc('\n', g);
    }
}

/* modes sweeps with references: a panel per quantity and mode */
static void plot_mode_panels(FILE *g, const plot_t *pl)
{
    const char *qcol[2] = {"frequency_error", "damping_ratio"};
    const char *qlab[2] = {"relative frequency error", "damping ratio"};
    int qn, m;
    size_t i;
    for (qn = 0; qn < 2 && pl->nmodes > 0; qn++)
        for (m = 1; m <= pl->nmodes; m++) {
            int first = 1;
            char cname[48], ttl[128];
            sweep_panel_start(g, pl->tabs, pl->n, "modes");
            snprintf(ttl, sizeof ttl, "%s, mode %d", qlab[qn], m);
            fputs("set title ", g);
            put_q(g, ttl);
            fputs("\nset ylabel ", g);
            put_q(g, qlab[qn]);
            fputs("\nplot ", g);
            snprintf(cname, sizeof cname, "%s_%d", qcol[qn], m);
            for (i = 0; i < pl->n; i++) {
                json_t *tab = pl->tabs[i].el;
                if (!is_sweep_of(tab, "modes") || col_index(tab, cname) <= 0) continue;
                if (!first) fputs(", ", g);
                first = 0;
                put_table(g, pl->dir, 't', i);
                fprintf(g, " using %d:%d with linespoints pt 7 ps 0.4 title ",
                        col_index(tab, jstr(tab, "param")), col_index(tab, cname));
                put_q(g, legend(pl->tabs + i));
            }
            if (first) fputs("0 notitle", g);
            fputc('\n', g);
        }
}

/* The gnuplot script: the tables as datablocks, then for each output its
 * terminal (from the extension: pdfcairo, pngcairo, svg; size w x h pixels,
 * 0: 800 x 600 per panel; a PDF gets w/100 x h/100 inches) and every panel.
 * paths[k]: where output k is written (the staged file, or the final path
 * in a kept --plot-script). */
static void plot_write_script(FILE *g, const plot_t *pl, rs_cli_out_t **plots, int nplots, const char *const *paths,
                              long w, long h)
{
    int cols = pl->npanels > 1 ? 2 : 1, rows = (int) ((pl->npanels + (size_t) cols - 1) / (size_t) cols), k;
    size_t i;
    if (w <= 0) { w = 800L * cols; h = 600L * rows; }
    fputs("# recstab plot script: the tables of the run as datablocks, then each --plot output\n", g);
    for (i = 0; i < pl->n; i++) {
        put_datablock(g, 't', i, jstr(pl->tabs[i].el, "table"), rs_cli_spool_of(pl->tabs[i].el));
        if (jstr(pl->tabs[i].el, "boundary_table"))
            put_datablock(g, 'b', i, jstr(pl->tabs[i].el, "boundary_table"), -1);
        if (jstr(pl->tabs[i].el, "locus_table")) put_datablock(g, 'l', i, jstr(pl->tabs[i].el, "locus_table"), -1);
    }
    for (k = 0; k < nplots; k++) {
        const char *ext = ext_of(plots[k]->path);
        if (strcmp(ext, "png") == 0) fprintf(g, "set terminal pngcairo size %ld,%ld noenhanced\n", w, h);
        else if (strcmp(ext, "pdf") == 0)
            fprintf(g, "set terminal pdfcairo size %gin,%gin noenhanced\n", (double) w / 100, (double) h / 100);
        else fprintf(g, "set terminal svg size %ld,%ld noenhanced\n", w, h);
        fputs("set output ", g);
        put_path(g, paths[k]);
        fputc('\n', g);
        if (pl->npanels > 1) fprintf(g, "set multiplot layout %d,%d\n", rows, cols);
        for (i = 0; i < pl->n; i++)
            if (strcmp(jstr(pl->tabs[i].el, "analysis"), "map") == 0) plot_map_panel(g, pl, i);
        plot_sweep_panels(g, pl);
        plot_mode_panels(g, pl);
        if (pl->npanels > 1) fputs("unset multiplot\n", g);
        fputs("set output\n", g);
    }
}

/* Runs gnuplot on the script (registered for the signal handler while it
 * runs); its log becomes the message when it fails. */
static int plot_run_gnuplot(const char *dir, char *err, size_t errlen)
{
    char p[4096 + 64], msg[300] = "";
    int status = 0;
    pid_t pid;
    FILE *lf;
    fflush(stdout);
    pthread_mutex_lock(&tidy_lock);   /* a signal now finds gnuplot registered */
    pid = fork();
    if (pid == 0) {
        int fd;
        sigset_t none;
        sigemptyset(&none);
        pthread_sigmask(SIG_SETMASK, &none, NULL);
        snprintf(p, sizeof p, "%s/gnuplot.log", dir);
        fd = open(p, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        if (fd >= 0) { dup2(fd, 1); dup2(fd, 2); close(fd); }
        /* "./" keeps a relative TMPDIR starting with '-' from being an option */
        snprintf(p, sizeof p, "%s%s/plot.gp", dir[0] == '/' ? "" : "./", dir);
        execlp("gnuplot", "gnuplot", p, (char *) NULL);
        _exit(127);
    }
    tidy_child = pid;
    pthread_mutex_unlock(&tidy_lock);
    if (pid > 0 && waitpid(pid, &status, 0) < 0) pid = -1;
    pthread_mutex_lock(&tidy_lock);
    tidy_child = 0;
    pthread_mutex_unlock(&tidy_lock);
    if (pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 0) return 0;
    snprintf(p, sizeof p, "%s/gnuplot.log", dir);
    lf = fopen(p, "r");
    if (lf) {
        size_t m = fread(msg, 1, sizeof msg - 1, lf);
        msg[m] = '\0';
        fclose(lf);
    }
    if (pid > 0 && WIFEXITED(status) && WEXITSTATUS(status) == 127)
        snprintf(err, errlen, "--plot: gnuplot not found (Debian: apt-get install gnuplot-nox)");
    else
        snprintf(err, errlen, "--plot: gnuplot failed: %s", msg);
    return -1;
}

/* the staged output must hold what gnuplot wrote */
static int plot_check_output(const rs_cli_out_t *o, char *err, size_t errlen)
{
    struct stat st;
    if (stat(o->tmp, &st) != 0 || st.st_size == 0) {
        snprintf(err, errlen, "--plot: gnuplot wrote nothing");
        return -1;
    }
    return 0;
}

int rs_cli_plot_stage(rs_cli_out_t **plots, int nplots, rs_cli_out_t *script, long w, long h, json_t *docs,
                      char *err, size_t errlen)
{
    plot_t pl;
    int fd, rc = 0, k;
    const char **paths = calloc((size_t) nplots + 1, sizeof(char *));
    char p[4096 + 64];
    FILE *g;
    memset(&pl, 0, sizeof pl);
    pl.n = collect(docs, NULL);
    if (pl.n == 0) {
        snprintf(err, errlen, "--plot: the run has no sweep or map to plot");
        free(paths);
        return -1;
    }
    pl.tabs = calloc(pl.n + 1, sizeof(tab_t));
    collect(docs, pl.tabs);
    plot_write_tables(&pl);
    plot_count_panels(&pl);
    if (script != NULL) {
        /* the kept script writes the final files */
        for (k = 0; k < nplots; k++) paths[k] = plots[k]->path;
        fd = stage_open(script, err, errlen);
        if (fd < 0) rc = -1;
        else {
            g = fdopen(fd, "w");
            plot_write_script(g, &pl, plots, nplots, paths, w, h);
            if (fclose(g) != 0) {
                snprintf(err, errlen, "--plot-script: cannot write '%s': %s", script->tmp, strerror(errno));
                stage_drop(script);
                rc = -1;
            }
        }
    }
    if (rc == 0 && nplots > 0 && plot_dir_make(&pl, err, errlen) != 0) rc = -1;
    else if (rc == 0 && nplots > 0) {
        for (k = 0; k < nplots && rc == 0; k++) {
            fd = stage_open(plots[k], err, errlen);
            if (fd < 0) rc = -1;
            else { close(fd); paths[k] = plots[k]->tmp; }
        }
        snprintf(p, sizeof p, "%s/plot.gp", pl.dir);
        if (rc == 0 && (g = fopen(p, "w")) != NULL) {
            plot_write_script(g, &pl, plots, nplots, paths, w, h);
            fclose(g);
            if (plot_run_gnuplot(pl.dir, err, errlen) != 0) rc = -1;
            for (k = 0; k < nplots && rc == 0; k++) rc = plot_check_output(plots[k], err, errlen);
        } else if (rc == 0) {
            snprintf(err, errlen, "--plot: cannot write '%s': %s", p, strerror(errno));
            rc = -1;
        }
        if (rc != 0) for (k = 0; k < nplots; k++) stage_drop(plots[k]);
        plot_dir_drop(pl.dir, pl.n);
    }
    free(paths);
    free(pl.tabs);
    return rc;
}
