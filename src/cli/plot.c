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
#include "recstab/casefile.h"

typedef struct {
    const char *case_path;
    const char *title;
    json_t *el;
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
            if (a == NULL || (strcmp(a, "sweep") != 0 && strcmp(a, "map") != 0) || jstr(o, "table") == NULL)
                continue;
            if (out) {
                out[n].case_path = jstr(d, "case");
                out[n].title = jstr(d, "title");
                out[n].el = o;
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
static rs_cli_out_t *tidy_outs[4];
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
    if (strcmp(option, "--plot") == 0 && strcmp(ext_of(path), "png") != 0 && strcmp(ext_of(path), "svg") != 0) {
        snprintf(err, errlen, "--plot: expected a file name ending in .png or .svg, found '%s'", path);
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
    if (ntidy_outs < 4) tidy_outs[ntidy_outs++] = o;
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

int rs_cli_csv_stage(rs_cli_out_t *o, json_t *docs, long shard_index, long shard_count, char *err, size_t errlen)
{
    const char *path = o->path;
    size_t n = collect(docs, NULL), i, t = 0;
    tab_t *tabs = calloc(n + 1, sizeof(tab_t));
    FILE *f;
    int fd, bad = 0;
    collect(docs, tabs);
    fd = stage_open(o, err, errlen);
    if (fd < 0) { free(tabs); return -1; }
    f = fdopen(fd, "w");
    if (n == 0) fputs("# recstab: no sweep or map in this run\n", f);
    for (i = 0; i < n; i++) {
        json_t *tab = tabs[i].el;
        const char *bt = jstr(tab, "boundary_table");
        t++;
        fprintf(f, "# recstab table %zu: case=", t);
        put_comment_text(f, tabs[i].case_path);
        fputs("; title=", f);
        put_comment_text(f, tabs[i].title);
        fputs("; analysis=", f);
        put_comment_text(f, jstr(tab, "text"));
        fprintf(f, "; points=%lld\n", (long long) json_integer_value(json_object_get(tab, "points")));
        if (shard_count > 1) {
            json_t *rows = json_object_get(tab, "rows");
            fprintf(f, "# shard %ld/%ld: rows %lld-%lld of table %zu\n", shard_index, shard_count,
                    (long long) json_integer_value(json_array_get(rows, 0)),
                    (long long) json_integer_value(json_array_get(rows, 1)) - 1, t);
        }
        fputs(jstr(tab, "table"), f);
        {
            char *shown = rs_utf8_escape(path);   /* json_string refuses invalid UTF-8 */
            json_object_set_new(tab, "csv", json_string(shown));
            flint_free(shown);
        }
        if (bt != NULL) {
            json_t *conds = json_object_get(json_object_get(tab, "boundary"), "conditions");
            size_t k;
            t++;
            fprintf(f, "# recstab table %zu: boundary of table %zu; case=", t, t - 1);
            put_comment_text(f, tabs[i].case_path);
            fputs("; conditions:", f);
            for (k = 0; k < json_array_size(conds); k++) {
                json_t *c = json_array_get(conds, k);
                fprintf(f, "%s %lld (%s) %s > 0", k ? ";" : "",
                        (long long) json_integer_value(json_object_get(c, "index")), jstr(c, "origin"), jstr(c, "poly"));
            }
            fputc('\n', f);
            if (shard_count > 1)
                fprintf(f, "# shard %ld/%ld: boundary rows only in shard 1\n", shard_index, shard_count);
            fputs(bt, f);
        }
    }
    if (fflush(f) != 0 || ferror(f)) bad = 1;
    if (fclose(f) != 0) bad = 1;
    free(tabs);
    if (bad) {
        snprintf(err, errlen, "cannot write '%s': %s", o->tmp, strerror(errno));
        stage_drop(o);
        return -1;
    }
    return 0;
}

void rs_cli_trim_tables(json_t *docs, int have_csv, size_t max_rows)
{
    size_t n = collect(docs, NULL), i;
    tab_t *tabs = calloc(n + 1, sizeof(tab_t));
    collect(docs, tabs);
    for (i = 0; i < n; i++) {
        json_t *o = tabs[i].el;
        size_t rows = count_rows(jstr(o, "table"));
        const char *bt = jstr(o, "boundary_table");
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

/* the quoted name of a table file in the plot's private folder */
static void put_table(FILE *f, const char *dir, char kind, size_t i)
{
    char p[4096 + 64];
    snprintf(p, sizeof p, "%s/%c%zu.csv", dir, kind, i);
    put_path(f, p);
}

static const char *ext_of(const char *path)
{
    const char *d = strrchr(path, '.');
    return d ? d + 1 : "";
}

static int write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    int ok;
    if (!f) return -1;
    ok = fputs(text, f) >= 0;
    if (fclose(f) != 0) ok = 0;
    return ok ? 0 : -1;
}

static const char *legend(const tab_t *t)
{
    return t->title ? t->title : t->case_path;
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
        const char *prm = jstr(o, "param");
        if (strcmp(jstr(o, "analysis"), "sweep") != 0 || strcmp(jstr(o, "of"), kind) != 0) continue;
        if (strcmp(jstr(o, "spacing"), "log") == 0) logx = 1;
        if (strstr(xl, prm) == NULL && strlen(xl) + strlen(prm) + 3 < sizeof xl) {
            if (xl[0]) strcat(xl, ", ");
            strcat(xl, prm);
        }
    }
    fputs("reset session\nset datafile separator ','\nset key outside bottom center horizontal\nset grid\n", g);
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
    char p[4096 + 64];
    size_t i;
    int k;
    for (i = 0; i < pl->n; i++) {
        const char *a = jstr(pl->tabs[i].el, "analysis"), *of = jstr(pl->tabs[i].el, "of");
        snprintf(p, sizeof p, "%s/t%zu.csv", pl->dir, i);
        write_file(p, jstr(pl->tabs[i].el, "table"));
        if (jstr(pl->tabs[i].el, "boundary_table")) {
            snprintf(p, sizeof p, "%s/b%zu.csv", pl->dir, i);
            write_file(p, jstr(pl->tabs[i].el, "boundary_table"));
        }
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

/* a map: one panel, the verdict (or the radius capped at 2) over the grid */
static void plot_map_panel(FILE *g, const plot_t *pl, size_t i)
{
    json_t *tab = pl->tabs[i].el, *params = json_object_get(tab, "params"), *grid = json_object_get(tab, "grid");
    int radius = strcmp(jstr(tab, "of"), "radius") == 0;
    int image = json_integer_value(json_array_get(grid, 0)) > 1 && json_integer_value(json_array_get(grid, 1)) > 1;
    fputs("reset session\nset datafile separator ','\nset key outside bottom center horizontal\n", g);
    fputs("set title ", g);
    put_q(g, legend(pl->tabs + i));
    fputs("\nset xlabel ", g);
    put_q(g, json_string_value(json_array_get(params, 0)));
    fputs("\nset ylabel ", g);
    put_q(g, json_string_value(json_array_get(params, 1)));
    fputs("\nset autoscale fix\n", g);
    if (radius)
        fputs("set cbrange [0:2]\nset cblabel 'spectral radius (capped at 2)'\n"
              "set palette defined (0 '#1a9850', 0.999 '#d9ef8b', 1 '#fee08b', 2 '#d73027')\n", g);
    else
        fputs("set cbrange [-0.5:2.5]\nset cbtics ('stable' 0, 'marginal' 1, 'unstable' 2)\n"
              "set palette defined (-0.5 '#1a9850', 0.5 '#1a9850', 0.5 '#fee08b', 1.5 '#fee08b', "
              "1.5 '#d73027', 2.5 '#d73027')\n", g);
    fputs("plot ", g);
    put_table(g, pl->dir, 't', i);
    fprintf(g, " skip 1 using %d:%d:(", col_index(tab, json_string_value(json_array_get(params, 0))),
            col_index(tab, json_string_value(json_array_get(params, 1))));
    if (radius) fprintf(g, "$%d > 2 ? 2 : $%d", col_index(tab, "radius"), col_index(tab, "radius"));
    else fprintf(g, "$%d < 0 ? NaN : $%d", col_index(tab, "code"), col_index(tab, "code"));
    fprintf(g, ") with %s notitle", image ? "image" : "points pt 5 ps 1 palette");
    if (jstr(tab, "boundary_table"))
    {
        fputs(", ", g);
        put_table(g, pl->dir, 'b', i);
        fputs(" skip 1 using 2:3 with points pt 7 ps 0.4 lc rgb 'black' "
              "title 'exact boundary (Lienard-Chipart, p(1), p(-1))'", g);
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
        fprintf(g, " skip 1 using %d:%d with linespoints pt 7 ps 0.5 title ", x, col_index(tab, "radius"));
        put_q(g, legend(pl->tabs + i));
    } else if (k == 1) {
        fprintf(g, " skip 1 using %d:($%d < 0 ? NaN : $%d) with steps title ", x,
                col_index(tab, "code"), col_index(tab, "code"));
        put_q(g, legend(pl->tabs + i));
    } else {
        char t2[600];
        fprintf(g, " skip 1 using %d:%d with linespoints pt 7 ps 0.5 title ", x, col_index(tab, "damping_ratio_1"));
        snprintf(t2, sizeof t2, "%s: damping ratio", legend(pl->tabs + i));
        put_q(g, t2);
        fputs(", ", g);
        put_table(g, pl->dir, 't', i);
        fprintf(g, " skip 1 using %d:%d with linespoints pt 6 ps 0.5 title ", x, col_index(tab, "frequency_error_1"));
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
                fprintf(g, " skip 1 using %d:%d with linespoints pt 7 ps 0.4 title ",
                        col_index(tab, jstr(tab, "param")), col_index(tab, cname));
                put_q(g, legend(pl->tabs + i));
            }
            if (first) fputs("0 notitle", g);
            fputc('\n', g);
        }
}

/* the gnuplot script: terminal and output (the staged file), then every panel */
static void plot_write_script(const plot_t *pl, const rs_cli_out_t *o, const char *ext)
{
    char p[4096 + 64];
    int cols = pl->npanels > 1 ? 2 : 1, rows = (int) ((pl->npanels + (size_t) cols - 1) / (size_t) cols);
    FILE *g;
    size_t i;
    snprintf(p, sizeof p, "%s/plot.gp", pl->dir);
    g = fopen(p, "w");
    if (strcmp(ext, "png") == 0) fprintf(g, "set terminal pngcairo size %d,%d noenhanced\n", 800 * cols, 600 * rows);
    else fprintf(g, "set terminal svg size %d,%d noenhanced\n", 800 * cols, 600 * rows);
    fputs("set output ", g);
    put_path(g, o->tmp);
    fputs("\nset datafile separator ','\nset key outside bottom center horizontal\nset grid\n", g);
    if (pl->npanels > 1) fprintf(g, "set multiplot layout %d,%d\n", rows, cols);
    for (i = 0; i < pl->n; i++)
        if (strcmp(jstr(pl->tabs[i].el, "analysis"), "map") == 0) plot_map_panel(g, pl, i);
    plot_sweep_panels(g, pl);
    plot_mode_panels(g, pl);
    if (pl->npanels > 1) fputs("unset multiplot\n", g);
    fputs("set output\n", g);
    fclose(g);
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

int rs_cli_plot_stage(rs_cli_out_t *o, json_t *docs, char *err, size_t errlen)
{
    const char *ext = ext_of(o->path);
    plot_t pl;
    int fd, rc = -1;
    memset(&pl, 0, sizeof pl);
    pl.n = collect(docs, NULL);
    if (pl.n == 0) {
        snprintf(err, errlen, "--plot: the run has no sweep or map to plot");
        return -1;
    }
    if (strcmp(ext, "png") != 0 && strcmp(ext, "svg") != 0) {
        snprintf(err, errlen, "--plot: expected a file name ending in .png or .svg, found '%s'", o->path);
        return -1;
    }
    pl.tabs = calloc(pl.n + 1, sizeof(tab_t));
    collect(docs, pl.tabs);
    if (plot_dir_make(&pl, err, errlen) != 0) {
        free(pl.tabs);
        return -1;
    }
    plot_write_tables(&pl);
    plot_count_panels(&pl);
    fd = stage_open(o, err, errlen);
    if (fd >= 0) {
        close(fd);
        plot_write_script(&pl, o, ext);
        if (plot_run_gnuplot(pl.dir, err, errlen) == 0 && plot_check_output(o, err, errlen) == 0) rc = 0;
        else stage_drop(o);
    }
    plot_dir_drop(pl.dir, pl.n);
    free(pl.tabs);
    return rc;
}
