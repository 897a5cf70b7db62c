/* fuzz_analyses.c -- libFuzzer harness: a whole case file whose own
 * `analyse`, `expect` and `claim` lines select the analyses and their
 * options, run through rs_case_parse_string -> rs_analysis_run -> the text
 * report, the Markdown and LaTeX derivations and the JSON output.
 *
 * Inputs over the caps of fuzz_common.h (size, unknowns, analyses, long
 * numbers) are only parsed. */
#include "fuzz_common.h"

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void) argc;
    (void) argv;
    fuzz_setup();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rs_case_t c;
    rs_model_t m;
    rs_error_t err;
    rs_options_t opt;
    char *text = fuzz_text(data, size);
    int r;
    if (text == NULL)
        return 0;
    rs_case_init(c);
    rs_model_init(m);
    rs_error_init(err);
    r = rs_case_parse_string(c, FUZZ_CASE_PATH, text, size, err);
    if (r == RS_OK) r = rs_model_lower(m, c, err);
    fuzz_check_error(r, err);
    if (r == RS_OK && size <= FUZZ_MAX_RUN_BYTES && fuzz_numbers_small(text, size) && fuzz_case_small(c, m)) {
        fuzz_options(&opt, FUZZ_MAX_PREC);
        fuzz_run(c, &opt);
    }
    rs_model_clear(m);
    rs_case_clear(c);
    free(text);
    return 0;
}
