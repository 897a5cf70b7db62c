/* driver.c -- one case run as the command runs it (--set, --analyse,
 * --emit, the run's options), the exit status and the --json document;
 * and the one-call API over them.  The recstab command calls these too,
 * so the command and the API cannot drift apart. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <jansson.h>
#include <flint/flint.h>
#include "recstab/api.h"
#include "recstab/casefile.h"
#include "recstab/model.h"
#include "recstab/str.h"
#include "util/polytext.h"
#include "analysis/sweep_impl.h"

void rs_run_options_default(rs_run_options_t *ro)
{
    memset(ro, 0, sizeof *ro);
    rs_options_default(&ro->opt);
}

/* The case's requests replaced by the --analyse ones (a leading
 * "analyse "/"analyze " is dropped). */
static void replace_requests(rs_case_t c, const rs_run_options_t *ro)
{
    int k;
    rs_case_clear_requests(c);
    for (k = 0; k < ro->nanalyses; k++) {
        const char *t = ro->analyses[k];
        while (*t == ' ') t++;
        if (strncmp(t, "analyse ", 8) == 0 || strncmp(t, "analyze ", 8) == 0) t += 8;
        rs_case_add_request(c, t, "--analyse", 0, 0);
    }
}

/* --emit equations: {"case", "equations"} of the lowered model. */
static int emit_doc(json_t **doc, const rs_case_t c, const char *path, rs_error_t err)
{
    rs_model_t m;
    int r;
    rs_model_init(m);
    r = rs_model_lower(m, c, err);
    if (r == RS_OK) {
        char *shown = rs_utf8_escape(path), *eqs = rs_model_emit_equations(m);
        *doc = json_object();
        json_object_set_new(*doc, "case", json_string(shown));
        json_object_set_new(*doc, "equations",
                            json_string(eqs ? eqs : "# no builder statements: the case's own equations\n"));
        flint_free(shown);
        flint_free(eqs);
    }
    rs_model_clear(m);
    return r;
}

int rs_run_case(json_t **doc, int *outcome, const char *path, const char *text,
                const rs_run_options_t *ro, rs_error_t err)
{
    rs_case_t c;
    int r, k;
    *doc = NULL;
    *outcome = 0;
    rs_case_init(c);
    r = text != NULL ? rs_case_parse_string(c, path, text, strlen(text), err)
                     : rs_case_parse_file(c, path, err);
    for (k = 0; r == RS_OK && k < ro->nsets; k++)
        r = rs_case_set_value(c, ro->sets[k], err);
    if (r == RS_OK && ro->nanalyses > 0) replace_requests(c, ro);
    if (r == RS_OK && ro->emit) r = emit_doc(doc, c, path, err);
    else if (r == RS_OK) r = rs_analysis_run(doc, outcome, c, &ro->opt, err);
    rs_case_clear(c);
    return r;
}

int rs_run_exit_status(int code, int outcome, int worst)
{
    /* an internal error is a bug, like two methods disagreeing */
    if (code != RS_OK) return (code == RS_ERR_INCONSISTENT || code == RS_ERR_INTERNAL) ? 3 : 2;
    if (outcome & RS_OUTCOME_INCONSISTENT) return 3;
    if ((outcome & RS_OUTCOME_FAILED) && worst == 0) return 1;
    return worst;
}

json_t *rs_run_json_document(json_t *docs, int ncases)
{
    size_t i, k;
    /* one shape for one case or many: readers never test which it is */
    (void) ncases;
    for (i = 0; i < json_array_size(docs); i++) {
        json_t *res = json_object_get(json_array_get(docs, i), "results");
        /* the rows are in "rows": the CSV text for files and plots goes */
        for (k = 0; k < json_array_size(res); k++) {
            json_object_del(json_array_get(res, k), "table");
            json_object_del(json_array_get(res, k), "table_spool");
            json_object_del(json_array_get(res, k), "boundary_table");
            json_object_del(json_array_get(res, k), "locus_table");
            json_object_del(json_array_get(res, k), "plot_ranges");
        }
    }
    return json_pack("{s:O}", "cases", docs);
}

/* the row arrays of the document, swapped with placeholders while dumping */
typedef struct {
    json_t **arr;
    json_t **owner;
    const char **key;
    json_t **ph;       /* the placeholder strings put in their place */
    size_t n;
} rowsets_t;

static void rowsets_swap(rowsets_t *rs, json_t *top)
{
    static const char *const keys[] = {"rows", "boundary_rows"};
    json_t *docs = json_object_get(top, "cases");
    size_t i, k;
    int m;
    for (i = 0; i < json_array_size(docs); i++) {
        json_t *res = json_object_get(json_array_get(docs, i), "results");
        for (k = 0; k < json_array_size(res); k++) {
            json_t *o = json_array_get(res, k);
            const char *a = json_string_value(json_object_get(o, "analysis"));
            if (a == NULL || (strcmp(a, "sweep") != 0 && strcmp(a, "map") != 0)) continue;
            for (m = 0; m < 2; m++) {
                json_t *r = json_object_get(o, keys[m]);
                char ph[48];
                /* an array, or a spooled table's {"spool": id, "count": n} */
                if (!json_is_array(r) && !(json_is_object(r) && json_object_get(r, "spool") != NULL)) continue;
                rs->arr = realloc(rs->arr, (rs->n + 1) * sizeof(json_t *));
                rs->owner = realloc(rs->owner, (rs->n + 1) * sizeof(json_t *));
                rs->key = realloc(rs->key, (rs->n + 1) * sizeof(char *));
                rs->ph = realloc(rs->ph, (rs->n + 1) * sizeof(json_t *));
                rs->arr[rs->n] = json_incref(r);
                rs->owner[rs->n] = o;
                rs->key[rs->n] = keys[m];
                snprintf(ph, sizeof ph, "\001rows %zu\001", rs->n);
                rs->ph[rs->n] = json_string(ph);
                json_object_set_new(o, keys[m], rs->ph[rs->n]);
                rs->n++;
            }
        }
    }
}

/* The long strings of the document (issue 17: the conditions of a 6-mass
 * chain, 363 MB, whose copy and per-character scan in json_dumps took half
 * of a --json run), swapped with placeholders while dumping and written
 * straight to f: the same bytes as jansson's. */
typedef struct {
    json_t **str;      /* a reference to each string */
    json_t **owner;    /* the object or array holding it */
    char **key;        /* its key in an object (malloc'd), or NULL */
    size_t *index;     /* its index in an array */
    size_t n;
} bigstrs_t;

/* strings from this many bytes on are streamed; short ones are not worth
 * a placeholder (and the snapshot cases' outputs exercise both) */
#define BIGSTR_MIN_BYTES 1024

static void bigstrs_push(bigstrs_t *b, json_t *str, json_t *owner, const char *key, size_t index)
{
    char ph[48];
    b->str = realloc(b->str, (b->n + 1) * sizeof(json_t *));
    b->owner = realloc(b->owner, (b->n + 1) * sizeof(json_t *));
    b->key = realloc(b->key, (b->n + 1) * sizeof(char *));
    b->index = realloc(b->index, (b->n + 1) * sizeof(size_t));
    b->str[b->n] = json_incref(str);
    b->owner[b->n] = owner;
    b->key[b->n] = key != NULL ? strdup(key) : NULL;
    b->index[b->n] = index;
    snprintf(ph, sizeof ph, "\001str %zu\001", b->n);
    if (key != NULL) json_object_set_new(owner, key, json_string(ph));   /* same place in the order */
    else json_array_set_new(owner, index, json_string(ph));
    b->n++;
}

/* long strings, and every string that starts with \001 as the placeholders
 * do (a title "\001rows 0\001" of the case's own): then each "\u0001 at
 * the start of a value in the dump is a placeholder */
static int bigstr_is(const json_t *x, const rowsets_t *rs)
{
    size_t k;
    if (!json_is_string(x)) return 0;
    for (k = 0; k < rs->n; k++)
        if (x == rs->ph[k]) return 0;
    return json_string_length(x) >= BIGSTR_MIN_BYTES || (json_string_length(x) > 0 && json_string_value(x)[0] == '\001');
}

/* pt: each of its placeholders met is a write to come (rs_polytext_hold) */
static void bigstrs_swap(bigstrs_t *b, json_t *x, const rowsets_t *rs, rs_polytext_struct *pt)
{
    if (json_is_object(x)) {
        void *it;
        for (it = json_object_iter(x); it != NULL; it = json_object_iter_next(x, it)) {
            json_t *v = json_object_iter_value(it);
            if (!bigstr_is(v, rs)) bigstrs_swap(b, v, rs, pt);
            else {
                slong k = rs_polytext_find(pt, v);
                if (k >= 0) rs_polytext_hold(pt, k);
                bigstrs_push(b, v, x, json_object_iter_key(it), 0);
            }
        }
    } else if (json_is_array(x)) {
        size_t i;
        for (i = 0; i < json_array_size(x); i++) {
            json_t *v = json_array_get(x, i);
            if (!bigstr_is(v, rs)) bigstrs_swap(b, v, rs, pt);
            else {
                slong k = rs_polytext_find(pt, v);
                if (k >= 0) rs_polytext_hold(pt, k);
                bigstrs_push(b, v, x, NULL, i);
            }
        }
    }
}

static void bigstrs_restore(bigstrs_t *b)
{
    size_t k;
    for (k = 0; k < b->n; k++) {
        if (b->key[k] != NULL) json_object_set_new(b->owner[k], b->key[k], b->str[k]);
        else json_array_set_new(b->owner[k], b->index[k], b->str[k]);
        free(b->key[k]);
    }
    free(b->str);
    free(b->owner);
    free(b->key);
    free(b->index);
}

/* str as jansson dumps it (no JSON_ENSURE_ASCII, no JSON_ESCAPE_SLASH): a
 * string without '"', '\\' and control characters verbatim in quotes (its
 * UTF-8 was checked when it was made), any other through jansson */
static int bigstr_put(FILE *f, const json_t *str, rs_polytext_struct *pt)
{
    const char *p = json_string_value(str);
    size_t len = json_string_length(str), i;
    slong k = rs_polytext_find(pt, str);
    /* a polynomial held back: printed here (util/polytext.h) */
    if (k >= 0) return rs_polytext_write(f, pt, k, 1);
    for (i = 0; i < len; i++) {
        unsigned char c = (unsigned char) p[i];
        if (c < 0x20 || c == '"' || c == '\\') break;
    }
    if (i == len) {
        fputc('"', f);
        fwrite(p, 1, len, f);
        fputc('"', f);
    } else {
        char *t = json_dumps(str, JSON_ENCODE_ANY);
        fputs(t != NULL ? t : "null", f);
        free(t);
    }
    return 0;
}

/* The first count rows of the spooled table (its header line first) as
 * rows of the document, each on its own line at indent + 2. */
static void spool_rows(FILE *f, FILE *sp, slong count, size_t indent, const json_t *real)
{
    char *line = NULL, *exact = NULL;
    size_t cap = 0;
    ssize_t n;
    slong r = 0;
    if (sp == NULL || fseek(sp, 0, SEEK_SET) != 0) return;
    if ((n = getline(&line, &cap, sp)) > 0) {
        exact = rs_sweep_exact_columns(line, (size_t) n - (line[n - 1] == '\n'));
        if (real != NULL) rs_sweep_flag_real(exact, real);
    }
    while (r < count && (n = getline(&line, &cap, sp)) > 0) {
        size_t len = (size_t) n - (line[n - 1] == '\n');
        fprintf(f, "%s\n%*s", r ? "," : "", (int) indent + 2, "");
        /* the row's text directly (the same bytes as the jansson dump) */
        if (rs_sweep_json_row_put(f, line, len, exact) != 0) {
            json_t *row = rs_sweep_json_row(line, len, exact);
            char *text = json_dumps(row, JSON_COMPACT | JSON_ENCODE_ANY);
            fputs(text ? text : "null", f);
            free(text);
            json_decref(row);
        }
        r++;
    }
    if (r > 0) fprintf(f, "\n%*s", (int) indent, "");
    free(line);
    free(exact);
}

char *rs_run_json_dumps(json_t *top)
{
    return rs_run_json_dumps_spool(top, NULL, NULL);
}

char *rs_run_json_dumps_spool(json_t *top, FILE *(*spool)(void *arg, slong id), void *arg)
{
    char *out = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&out, &len);
    int r;
    if (f == NULL) return NULL;
    r = rs_run_json_dumpf(f, top, spool, arg);
    fclose(f);
    if (r != 0) {
        free(out);
        return NULL;
    }
    return out;
}

int rs_run_json_dumpf(FILE *f, json_t *top, FILE *(*spool)(void *arg, slong id), void *arg)
{
    return rs_run_json_dumpf_polytext(f, top, spool, arg, NULL);
}

int rs_run_json_dumpf_polytext(FILE *f, json_t *top, FILE *(*spool)(void *arg, slong id), void *arg,
                               rs_polytext_t pt)
{
    rowsets_t rs = {NULL, NULL, NULL, NULL, 0};
    bigstrs_t bs = {NULL, NULL, NULL, NULL, 0};
    char *s;
    size_t k;
    int rc = -1;
    rowsets_swap(&rs, top);
    bigstrs_swap(&bs, top, &rs, pt);
    /* the document without its rows and long strings, which go straight
     * to f one by one */
    s = json_dumps(top, JSON_INDENT(2) | JSON_PRESERVE_ORDER);
    if (s == NULL) goto done;
    rc = 0;
    {
        const char *p = s;
        for (;;) {
            const char *q = strstr(p, "\"\\u0001"), *ls;
            size_t id, r, indent;
            if (q == NULL) break;
            if (strncmp(q + 7, "str ", 4) == 0) {
                id = (size_t) strtoul(q + 11, NULL, 10);
                fwrite(p, 1, (size_t) (q - p), f);
                if (id < bs.n && bigstr_put(f, bs.str[id], pt) != 0) rc = -1;
                p = strchr(q + 1, '"') + 1;
                continue;
            }
            if (strncmp(q + 7, "rows ", 5) != 0) {
                /* not a value (an object key): as it is */
                fwrite(p, 1, (size_t) (q + 1 - p), f);
                p = q + 1;
                continue;
            }
            id = (size_t) strtoul(q + 12, NULL, 10);
            fwrite(p, 1, (size_t) (q - p), f);
            /* the indentation of the key's line */
            for (ls = q; ls > s && ls[-1] != '\n'; ls--) {}
            for (indent = 0; ls[indent] == ' '; indent++) {}
            fputc('[', f);
            if (id < rs.n && json_is_object(rs.arr[id])) {
                json_t *sp = rs.arr[id];
                if (spool != NULL)
                    spool_rows(f, spool(arg, (slong) json_integer_value(json_object_get(sp, "spool"))),
                               (slong) json_integer_value(json_object_get(sp, "count")), indent,
                               json_object_get(sp, "real"));
                fputc(']', f);
                p = strchr(q + 1, '"') + 1;
                continue;
            }
            for (r = 0; id < rs.n && r < json_array_size(rs.arr[id]); r++) {
                char *row = json_dumps(json_array_get(rs.arr[id], r), JSON_COMPACT | JSON_ENCODE_ANY);
                fprintf(f, "%s\n%*s%s", r ? "," : "", (int) indent + 2, "", row ? row : "null");
                free(row);
            }
            if (r > 0) fprintf(f, "\n%*s", (int) indent, "");
            fputc(']', f);
            p = strchr(q + 1, '"') + 1;
        }
        fputs(p, f);
    }
    fputc('\n', f);
    free(s);
done:
    /* the document as it was */
    bigstrs_restore(&bs);
    for (k = 0; k < rs.n; k++) json_object_set_new(rs.owner[k], rs.key[k], rs.arr[k]);
    free(rs.arr);
    free(rs.owner);
    free(rs.key);
    free(rs.ph);
    return rc;
}

/* {"error": {...}} for a run that ended with err (the command prints the
 * formatted message on stderr). */
static char *error_json(const rs_error_t err)
{
    char msg[2 * RS_ERROR_MSG_LEN];
    json_t *e;
    char *s;
    rs_error_format(msg, sizeof msg, err);
    e = json_pack("{s:{s:s,s:s,s:s,s:i,s:i}}", "error", "code", rs_error_code_name(err->code),
                  "message", msg, "file", err->file, "line", err->line, "col", err->col);
    if (e == NULL) /* the message or file name is not UTF-8 */
        e = json_pack("{s:{s:s,s:s}}", "error", "code", rs_error_code_name(err->code),
                      "message", "(a message that is not valid UTF-8)");
    s = json_dumps(e, JSON_INDENT(2) | JSON_PRESERVE_ORDER);
    json_decref(e);
    return s;
}

int rs_analyse_json_opt(const char *case_text, const char *source_name,
                        const rs_run_options_t *ro, char **json)
{
    rs_run_options_t dflt;
    rs_error_t err;
    json_t *doc = NULL, *docs, *top;
    int outcome = 0, r, status;
    char *out;
    if (ro == NULL) {
        rs_run_options_default(&dflt);
        ro = &dflt;
    }
    if (source_name == NULL) source_name = "<string>";
    /* GSL's default handler would abort the caller's process (error.h) */
    rs_gsl_quiet();
    rs_error_init(err);
    if (case_text == NULL) r = rs_error_set(err, RS_ERR_INPUT, "no case text (NULL)");
    else r = rs_run_case(&doc, &outcome, source_name, case_text, ro, err);
    status = rs_run_exit_status(r, outcome, 0);
    if (r != RS_OK) out = error_json(err);
    else {
        docs = json_array();
        json_array_append_new(docs, doc);
        top = rs_run_json_document(docs, 1);
        out = rs_run_json_dumps(top);
        json_decref(top);
        json_decref(docs);
    }
    rs_error_clear(err);
    if (json != NULL) *json = out;
    else free(out);
    return status;
}

int rs_analyse_json(const char *case_text, const char *source_name, char **json)
{
    return rs_analyse_json_opt(case_text, source_name, NULL, json);
}

int rs_analyse_json_with(const char *case_text, const char *source_name, const char *const *sets,
                         const char *const *analyses, int flags, double time_limit, long memory_limit,
                         char **json)
{
    rs_run_options_t ro;
    rs_run_options_default(&ro);
    ro.opt.with_scheme = (flags & RS_RUN_SCHEME) != 0;
    if (time_limit >= 0) ro.opt.time_limit = time_limit;
    if (memory_limit >= 0) ro.opt.memory_limit = memory_limit;
    ro.sets = sets;
    ro.analyses = analyses;
    while (sets != NULL && sets[ro.nsets] != NULL) ro.nsets++;
    while (analyses != NULL && analyses[ro.nanalyses] != NULL) ro.nanalyses++;
    return rs_analyse_json_opt(case_text, source_name, &ro, json);
}

void rs_free(void *p)
{
    free(p);
}
