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

#ifdef __cplusplus
}
#endif
#endif
