/* test_polytext.c -- long polynomials printed straight into the report
 * (rs_options_t.polytext, util/polytext.h; issue 17).  The reference is the
 * route without it: the same case run with every polynomial a jansson
 * string, rendered by rs_report_text and dumped by rs_run_json_dumps.
 *  - the 4-mass chain of bench/make_chain_case.sh (its minors D_5..D_8 have
 *    hundreds to thousands of terms, so they are held back) with a title
 *    that looks like a placeholder: text and --json byte-identical to the
 *    reference, the look-alike title printed as itself;
 *  - the registry alone: a polynomial whose names need JSON escapes written
 *    as jansson dumps the string rs_polyfmt_fmpz_mpoly prints; held writes
 *    print the same text each time; after rs_polytext_keep the caller's
 *    polynomial is 0 and the text unchanged. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <jansson.h>
#include "recstab/api.h"
#include "recstab/report.h"
#include "util/polytext.h"
#include "util/polyfmt.h"

static char *chain_case(int n)
{
    char cmd[128], *buf = NULL;
    size_t len = 0, got;
    char chunk[4096];
    FILE *p;
    snprintf(cmd, sizeof cmd, "sh bench/make_chain_case.sh %d", n);
    p = popen(cmd, "r");
    assert_non_null(p);
    /* a title of the case's own that looks like the first placeholder */
    buf = strdup("title \001poly 0\001\n");
    len = strlen(buf);
    while ((got = fread(chunk, 1, sizeof chunk, p)) > 0) {
        buf = realloc(buf, len + got + 1);
        memcpy(buf + len, chunk, got);
        len += got;
    }
    buf[len] = '\0';
    assert_int_equal(pclose(p), 0);
    return buf;
}

static json_t *run(const char *text, rs_polytext_struct *pt)
{
    rs_run_options_t ro;
    rs_error_t err;
    json_t *doc = NULL;
    int outcome = 0;
    rs_run_options_default(&ro);
    ro.opt.polytext = pt;
    rs_error_init(err);
    assert_int_equal(rs_run_case(&doc, &outcome, "chain4.case", text, &ro, err), RS_OK);
    assert_int_equal(outcome, 0);
    rs_error_clear(err);
    return doc;
}

static void test_chain_same_bytes(void **state)
{
    char *text = chain_case(4), *ref_txt = NULL, *txt = NULL, *ref_json, *json = NULL;
    size_t ref_len = 0, len = 0, jlen = 0;
    rs_polytext_t pt;
    json_t *ref_doc, *doc, *docs, *top;
    FILE *f;
    (void) state;
    rs_polytext_init(pt);
    ref_doc = run(text, NULL);
    doc = run(text, pt);
    /* held back at all: otherwise the comparison says nothing */
    assert_true(pt->nph >= 4);

    f = open_memstream(&ref_txt, &ref_len);
    rs_report_text(f, ref_doc);
    fclose(f);
    f = open_memstream(&txt, &len);
    rs_report_text_polytext(f, doc, pt);
    fclose(f);
    assert_int_equal(len, ref_len);
    assert_memory_equal(txt, ref_txt, len);
    assert_non_null(strstr(txt, "\001poly 0\001"));   /* the title, as itself */
    assert_null(strstr(txt, "\001poly 1\001"));

    docs = json_pack("[O]", ref_doc);
    top = rs_run_json_document(docs, 1);
    ref_json = rs_run_json_dumps(top);
    json_decref(top);
    json_decref(docs);
    docs = json_pack("[O]", doc);
    top = rs_run_json_document(docs, 1);
    f = open_memstream(&json, &jlen);
    assert_int_equal(rs_run_json_dumpf_polytext(f, top, NULL, NULL, pt), 0);
    fclose(f);
    json_decref(top);
    json_decref(docs);
    assert_non_null(ref_json);
    assert_int_equal(jlen, strlen(ref_json));
    assert_memory_equal(json, ref_json, jlen);

    free(ref_txt);
    free(txt);
    free(ref_json);
    free(json);
    json_decref(ref_doc);
    json_decref(doc);
    rs_polytext_clear(pt);
    free(text);
}

static void test_registry(void **state)
{
    const char *vars[2] = {"a\"b", "c\\d"};
    fmpz_mpoly_ctx_t ctx;
    fmpz_mpoly_t p;
    rs_polytext_t pt;
    json_t *ph, *line, *ref;
    char *want_text, *want_json, *out = NULL;
    size_t len = 0;
    FILE *f;
    int i;
    (void) state;
    fmpz_mpoly_ctx_init(ctx, 2, ORD_LEX);
    fmpz_mpoly_init(p, ctx);
    assert_int_equal(fmpz_mpoly_set_str_pretty(p, "-3*x1^2*x2 + 123456789012345678901234567890*x2 - 7", NULL, ctx),
                     0);
    assert_int_equal(fmpz_mpoly_length(p, ctx), 3);
    want_text = rs_polyfmt_fmpz_mpoly(p, vars, ctx);
    assert_non_null(strstr(want_text, "123456789012345678901234567890"));
    ref = json_string(want_text);
    want_json = json_dumps(ref, JSON_ENCODE_ANY);
    json_decref(ref);

    rs_polytext_init(pt);
    ph = rs_polytext_defer(pt, p, vars, ctx, "> 0", &line);
    assert_non_null(line);
    assert_int_equal(rs_polytext_find(pt, ph), 0);
    assert_int_equal(rs_polytext_find(pt, line), 1);
    ref = json_string(json_string_value(ph));   /* the same text, another string */
    assert_int_equal(rs_polytext_find(pt, ref), -1);
    assert_int_equal(rs_polytext_find_value(pt, json_string_value(ref)), -1);
    json_decref(ref);

    rs_polytext_hold(pt, 0);
    rs_polytext_hold(pt, 0);
    f = open_memstream(&out, &len);
    for (i = 0; i < 3; i++) {   /* two held writes, then one printed afresh */
        assert_int_equal(rs_polytext_write(f, pt, 0, 1), 0);
        fputc('|', f);
    }
    rs_polytext_keep(pt);
    assert_true(fmpz_mpoly_is_zero(p, ctx));
    assert_int_equal(rs_polytext_write(f, pt, 0, 0), 0);
    fputc('|', f);
    assert_int_equal(rs_polytext_write(f, pt, 1, 0), 0);
    fclose(f);
    {
        char *expect = malloc(4 * strlen(want_json) + 2 * strlen(want_text) + 16);
        sprintf(expect, "%s|%s|%s|%s|%s > 0", want_json, want_json, want_json, want_text, want_text);
        assert_string_equal(out, expect);
        free(expect);
    }
    free(out);
    json_decref(ph);
    json_decref(line);
    rs_polytext_clear(pt);
    free(want_text);
    free(want_json);
    fmpz_mpoly_clear(p, ctx);
    fmpz_mpoly_ctx_clear(ctx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_chain_same_bytes),
        cmocka_unit_test(test_registry),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
