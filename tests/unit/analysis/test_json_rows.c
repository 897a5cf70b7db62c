/* test_json_rows.c -- the rows of sweeps and maps written as JSON text
 * directly (rs_sweep_json_row_put, issue 14 part 3) are the bytes jansson
 * dumps for the same row (rs_sweep_json_row + json_dumps(JSON_COMPACT)):
 * 20000 random rows of map-like cells (integers, decimals in every printf
 * form, exponents, inf/nan, verdict words, fractions in NAME_exact columns,
 * empty and long cells); rows with cells that need JSON escaping are
 * refused (-1, nothing written).  jansson is the reference.
 * The document's long strings (issue 17: written straight to the output by
 * rs_run_json_dumpf) are the bytes json_dumps writes: random documents with
 * strings around the threshold, with quotes, backslashes, control
 * characters, multi-byte UTF-8, slashes and \001, some shared. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <cmocka.h>
#include <jansson.h>
#include "analysis/sweep_impl.h"
#include "recstab/api.h"

static uint64_t st = 0x243f6a8885a308d3ULL;

static uint64_t rng(void)   /* xorshift64*: reproducible */
{
    st ^= st >> 12;
    st ^= st << 25;
    st ^= st >> 27;
    return st * 2685821657736338717ULL;
}

static double unif(void)
{
    return (double) (rng() >> 11) * 0x1p-53;
}

/* one random cell (no comma, no newline) into c */
static void cell(char *c, size_t cap)
{
    static const char *const words[] = {"stable", "unstable", "undecided", "certified", "fast", "inf", "-inf",
                                        "nan", "3/59", "-1/2", "0x1A", " 12", "1e400", "12abc", ".5", "5.",
                                        "-0", "0", "1e5", "1E5", "9007199254740993", "-9007199254740992",
                                        "+7", "1/3"};
    double x = (unif() - 0.5) * pow(10.0, (double) ((long) (rng() % 80) - 40));
    switch (rng() % 10) {
    case 0: snprintf(c, cap, "%s", words[rng() % (sizeof words / sizeof words[0])]); break;
    case 1: snprintf(c, cap, "%ld", (long) (rng() % 2000000) - 1000000); break;
    case 2: snprintf(c, cap, "%.17g", x); break;
    case 3: snprintf(c, cap, "%.15g", x); break;
    case 4: snprintf(c, cap, "%.3e", x); break;
    case 5: snprintf(c, cap, "%g", floor(x)); break;
    case 6: c[0] = '\0'; break;
    case 7: snprintf(c, cap, "%.17g", 1.0 + unif() * 1e-12); break;
    case 8: memset(c, '7', 170); c[170] = '\0'; break;   /* a long cell stays a string */
    default: snprintf(c, cap, "%.6f", x); break;
    }
}

static void test_rows_as_jansson(void **state)
{
    const char *header = "index,i,j,acc1,c1,acc1_exact,c1_exact,verdict,code,radius,radius_lower,radius_upper,decided_by";
    char *exact = rs_sweep_exact_columns(header, strlen(header));
    char *typed = rs_sweep_exact_columns(header, strlen(header));
    json_t *real = json_pack("[i, i]", 3, 4);   /* acc1, c1 as columns of reals (z-plane maps) */
    char line[4096], c[256];
    long r, k, ncols;
    (void) state;
    rs_sweep_flag_real(typed, real);
    json_decref(real);
    for (r = 0; r < 20000; r++) {
        char *mine = NULL, *ref;
        size_t mlen = 0;
        FILE *f;
        json_t *row;
        const char *flags;
        ncols = r % 7 == 0 ? 1 + (long) (rng() % 20) : 13;   /* other widths than the header's too */
        line[0] = '\0';
        for (k = 0; k < ncols; k++) {
            cell(c, sizeof c);
            if (k) strcat(line, ",");
            strcat(line, c);
        }
        f = open_memstream(&mine, &mlen);
        flags = r % 11 == 0 ? NULL : r % 3 == 0 ? typed : exact;
        assert_int_equal(rs_sweep_json_row_put(f, line, strlen(line), flags), 0);
        fclose(f);
        row = rs_sweep_json_row(line, strlen(line), flags);
        ref = json_dumps(row, JSON_COMPACT | JSON_ENCODE_ANY);
        if (strcmp(mine, ref) != 0) fail_msg("row '%s':\n mine %s\n jansson %s", line, mine, ref);
        free(ref);
        free(mine);
        json_decref(row);
    }
    free(exact);
    free(typed);
}

/* cells that need escaping or a UTF-8 check: refused, nothing written */
static void test_refused(void **state)
{
    static const char *const rows[] = {"1,a\"b,2", "1,a\\b", "x\ty", "caf\xc3\xa9"};
    size_t i;
    (void) state;
    for (i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        char *buf = NULL;
        size_t len = 0;
        FILE *f = open_memstream(&buf, &len);
        assert_int_equal(rs_sweep_json_row_put(f, rows[i], strlen(rows[i]), NULL), -1);
        fclose(f);
        assert_int_equal(len, 0);
        free(buf);
    }
}

/* a random string of len bytes (whole UTF-8 characters) */
static json_t *rand_string(size_t len)
{
    static const char *const pieces[] = {"7", "c", "*", "^", " + ", "k1", "\"", "\\", "\n", "\t", "\001", "/",
                                         "\xc3\xa9", "\xe2\x82\xac", "\x7f", "u0001"};
    char *b = malloc(len + 8);
    size_t n = 0;
    json_t *s;
    int plain = rng() % 2 == 0;   /* half of them digits and operators only: written verbatim */
    while (n < len) {
        const char *p = pieces[rng() % (plain ? 6 : sizeof pieces / sizeof pieces[0])];
        memcpy(b + n, p, strlen(p));
        n += strlen(p);
    }
    s = json_stringn(b, n);
    free(b);
    assert_non_null(s);
    return s;
}

static void test_long_strings_as_jansson(void **state)
{
    int d;
    (void) state;
    for (d = 0; d < 40; d++) {
        json_t *top, *res = json_array(), *shared = rand_string(900 + rng() % 2000), *copy;
        char *mine, *ref;
        int k;
        for (k = 0; k < 4; k++) {
            json_t *o = json_object(), *arr = json_array(), *inner = json_object();
            int j;
            json_object_set_new(o, "analysis", json_string(k % 2 ? "jury" : "hurwitz"));
            for (j = 0; j < 5; j++) json_array_append_new(arr, rand_string(rng() % 3000));
            json_array_append(arr, shared);
            json_object_set_new(o, "conditions", arr);
            json_object_set(o, "poly", shared);
            json_object_set_new(inner, "factor", rand_string(1000 + rng() % 60));
            json_object_set_new(inner, "exponent", json_integer(k));
            json_object_set_new(o, "details", json_pack("[o, [o]]", inner, rand_string(rng() % 2500)));
            json_object_set_new(o, "tail", json_string("short"));
            json_array_append_new(res, o);
        }
        top = json_pack("{s:[{s:s, s:o}]}", "cases", "case", "t.case", "results", res);
        copy = json_deep_copy(top);
        mine = rs_run_json_dumps(top);
        ref = json_dumps(top, JSON_INDENT(2) | JSON_PRESERVE_ORDER);
        assert_non_null(mine);
        assert_non_null(ref);
        assert_int_equal(strlen(mine), strlen(ref) + 1);
        assert_memory_equal(mine, ref, strlen(ref));
        assert_true(json_equal(top, copy));   /* the document as it was */
        free(mine);
        free(ref);
        json_decref(copy);
        json_decref(shared);
        json_decref(top);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rows_as_jansson),
        cmocka_unit_test(test_refused),
        cmocka_unit_test(test_long_strings_as_jansson),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
