/* str.h -- string copies and UTF-8 checks shared by every stage (util). */
#ifndef RECSTAB_STR_H
#define RECSTAB_STR_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Copies of strings (flint_malloc'd; free with flint_free). */
char *rs_strdup(const char *s);
char *rs_strndup(const char *s, size_t n);
/* Appends printf-style text to *s (flint_realloc'd; *s NULL starts an empty
 * string; free with flint_free): text of any length, never cut. */
void rs_str_catf(char **s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* Length (1 to 4) of the valid UTF-8 sequence at s (n bytes readable), 0
 * when the bytes there are none (overlong forms and surrogates included,
 * as jansson judges them). */
int rs_utf8_seq_len(const char *s, size_t n);
/* Copy of s (flint_malloc'd) with every byte that is not part of valid
 * UTF-8 written as \xNN: file names in text and JSON output. */
char *rs_utf8_escape(const char *s);

/* Long polynomials held back from a run's document and printed only when
 * the report is written (issue 17: the minors of a 6-mass chain are 220 MB
 * of text, copied once more into jansson's strings).  The document holds a
 * short placeholder string for each; rs_report_text_polytext and
 * rs_run_json_dumpf_polytext print the polynomial where the placeholder
 * is (recognised by the json_t itself, never by its text).  A run fills it
 * when rs_options_t.polytext points to one (one thread at a time); every
 * other reader of such a document sees the placeholders.  Its fields are
 * util/polytext.c's. */
typedef struct rs_polytext_struct {
    struct rs_polytext_poly_s *poly;   /* the polynomials, each with its own context and names */
    struct rs_polytext_ph_s *ph;       /* the placeholders standing for them */
    long npoly, nph, alloc_poly, alloc_ph;
    char *scratch;                     /* the printing buffer of text used once */
    size_t cap;
} rs_polytext_struct;
typedef rs_polytext_struct rs_polytext_t[1];

void rs_polytext_init(rs_polytext_t pt);
/* Frees the polynomials and drops the registry's references to the
 * placeholders (the documents keep theirs). */
void rs_polytext_clear(rs_polytext_t pt);

#ifdef __cplusplus
}
#endif
#endif
