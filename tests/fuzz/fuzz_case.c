/* fuzz_case.c -- libFuzzer harness over the case-file parser, the expression
 * engine and a cheap analysis run (charpoly only).
 *
 *   make fuzz FUZZ_SECONDS=600        (see the Makefile)
 *
 * Inputs longer than 4 KB or with more than 6 unknowns are only parsed, so
 * that slow determinants do not hide parser bugs behind timeouts. */
#include "fuzz_common.h"

#define FUZZ_MAX_RUN_UNKNOWNS 6

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rs_case_t c;
    rs_model_t m;
    rs_error_t err;
    char *text = malloc(size + 1);
    int r;
    if (text == NULL)
        return 0;
    if (size > 0)
        memcpy(text, data, size);
    text[size] = '\0';
    rs_case_init(c);
    rs_model_init(m);
    rs_error_init(err);
    r = rs_case_parse_string(c, FUZZ_CASE_PATH, text, size, err);
    if (r == RS_OK) r = rs_model_lower(m, c, err);
    if (r == RS_OK && size <= FUZZ_MAX_RUN_BYTES && m->nunknowns <= FUZZ_MAX_RUN_UNKNOWNS) {
        json_t *doc = NULL;
        int outcome = 0;
        rs_options_t opt;
        fuzz_options(&opt, FUZZ_MAX_PREC);   /* the budget: an uninterruptible product is refused */
        rs_case_clear_requests(c);
        rs_case_add_request(c, "charpoly", "fuzz", 0, 0);
        rs_error_init(err);
        r = rs_analysis_run(&doc, &outcome, c, &opt, err);
        if (r == RS_OK && doc == NULL)
            abort();            /* success must produce a document */
        json_decref(doc);
    }
    if (r != RS_OK && err->msg[0] == '\0')
        abort();                /* every error carries a message */
    rs_model_clear(m);
    rs_case_clear(c);
    free(text);
    return 0;
}
