/* fuzz_options.c -- structured libFuzzer harness: leading bytes pick one of
 * the bundled cases, one analysis and the command-line settings; the rest of
 * the input is that analysis' options and extra case lines.  The cases are
 * valid, so every input reaches the analysis' option parsing and its
 * mathematics.
 *
 *   byte 0   case: FUZZ_CASES[b % n] (its own analyse/expect/claim lines dropped)
 *   byte 1   analysis: FUZZ_ANALYSES[b % n]
 *   byte 2   bits 0-2: --max-prec 64 << (b % 5), i.e. 64 ... 1024;
 *            bits 3-5: --sweep-level (fast, prec128, prec256, exact, double; mod 5);
 *            bits 6-7: --shard 1/1, 1/2, 2/2, 2/3
 *   rest     first line: appended to the analysis word ("h from 0 to 1 steps 4");
 *            further lines: "--set NAME=VALUE" goes to rs_case_set_value (as the
 *            command's --set), any other line is appended to the case before
 *            the analysis ("set h = 1/3", "assume h < 2", a second "analyse ...")
 *
 * The text actually run is an ordinary case file; FUZZ_SHOW=1 prints it with
 * its options on stderr, so a finding replays with the command
 * (build/recstab --max-prec P ... FILE) and goes to tests/fuzz/regress/.
 * Caps: as fuzz_analyses (fuzz_common.h). */
#include "fuzz_common.h"

static const char *const FUZZ_CASES[] = {
    "cases/textbook/trapezoidal.case",               /* one symbolic parameter */
    "cases/textbook/bdf2.case",
    "cases/textbook/newmark-average-acceleration.case",
    "cases/textbook/central-difference.case",
    "cases/park-staggered.case",                     /* several parameters, region ... at */
    "cases/olivier2019-GS12-ee-ei.case",             /* builders, every value set */
    "cases/li-explicit-k1.case",                     /* exact co-simulation (numeric only) */
    "cases/recurrence-exact-oscillator.case",        /* exp/sin entries (numeric only) */
    "cases/recurrence-forward-euler.case",           /* polynomial matrix recurrence */
    "cases/hard/double-on-circle.case",              /* char, roots on the circle */
    "cases/hard/plus-minus-one.case",
    "cases/textbook/forward-euler.case",
    "cases/hard/algebraic-system-jordan.case",       /* no assumptions, algebraic ends */
    "cases/hard/free-sign-linear.case",              /* leading coefficient of either sign */
    "cases/hard/algebraic-singular.case",
    "cases/hard/root-at-minus-one.case",
};
#define FUZZ_NCASES ((int) (sizeof FUZZ_CASES / sizeof FUZZ_CASES[0]))

static const char *const FUZZ_ANALYSES[] = {
    "analyse region", "claim", "analyse limit", "analyse radius", "analyse modes",
    "analyse simulate", "analyse sweep", "analyse map", "analyse routh", "analyse jury",
    "analyse hurwitz", "analyse bilinear", "analyse stability", "analyse charpoly",
    "expect charpoly", "expect bilinear",
};
#define FUZZ_NANALYSES ((int) (sizeof FUZZ_ANALYSES / sizeof FUZZ_ANALYSES[0]))

static char *fuzz_case_text[FUZZ_NCASES];

static int is_request_line(const char *line)
{
    while (*line == ' ' || *line == '\t')
        line++;
    return strncmp(line, "analyse", 7) == 0 || strncmp(line, "analyze", 7) == 0
           || strncmp(line, "expect", 6) == 0 || strncmp(line, "claim", 5) == 0;
}

/* The case file's text without its request lines (malloc'd). */
static char *load_case(const char *rel)
{
    char path[1024], line[4096];
    size_t len = 0, cap = 1 << 16;
    char *text = malloc(cap);
    int dropping = 0;
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", RS_SOURCE_DIR, rel);
    f = fopen(path, "r");
    if (f == NULL || text == NULL) {
        fprintf(stderr, "fuzz_options: cannot read %s\n", path);
        abort();
    }
    text[0] = '\0';
    while (fgets(line, sizeof line, f) != NULL) {
        size_t n = strlen(line);
        int continued = n >= 2 && line[n - 2] == '\\';
        if (dropping || is_request_line(line)) {
            dropping = continued;   /* with its continuation lines */
            continue;
        }
        if (len + n + 1 > cap)
            abort();
        memcpy(text + len, line, n + 1);
        len += n;
    }
    fclose(f);
    return text;
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    int i;
    (void) argc;
    (void) argv;
    fuzz_setup();
    for (i = 0; i < FUZZ_NCASES; i++)
        fuzz_case_text[i] = load_case(FUZZ_CASES[i]);
    return 0;
}

/* --set lines of rest (each "--set NAME=VALUE") into sets, the other lines
 * after the first into lines; both NUL-separated in buffers of restlen+1 */
static void split_lines(char *lines, char *sets, const char *rest, size_t restlen)
{
    const char *p = memchr(rest, '\n', restlen), *end = rest + restlen;
    size_t nl = 0, ns = 0;
    while (p != NULL && p < end) {
        const char *q = p + 1, *e = memchr(q, '\n', (size_t) (end - q));
        size_t n;
        if (e == NULL)
            e = end;
        n = (size_t) (e - q);
        if (n > 6 && strncmp(q, "--set ", 6) == 0) {
            memcpy(sets + ns, q + 6, n - 6);
            ns += n - 6;
            sets[ns++] = '\0';
        } else {
            memcpy(lines + nl, q, n);
            nl += n;
            lines[nl++] = '\n';
        }
        p = (e < end) ? e : NULL;
    }
    lines[nl] = '\0';
    sets[ns] = '\0';
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const slong shards[4][2] = {{1, 1}, {1, 2}, {2, 2}, {2, 3}};
    const char *base, *what, *rest, *nl, *set;
    size_t restlen, optlen, len;
    slong max_prec;
    char *text, *lines, *sets;
    rs_case_t c;
    rs_model_t m;
    rs_error_t err;
    rs_options_t opt;
    rs_sweep_options_t sw;
    int r;
    if (size < 3 || size > FUZZ_MAX_RUN_BYTES)
        return 0;
    base = fuzz_case_text[data[0] % FUZZ_NCASES];
    what = FUZZ_ANALYSES[data[1] % FUZZ_NANALYSES];
    max_prec = 64L << ((data[2] & 7) % 5);
    rs_sweep_options_default(&sw);
    sw.max_points = FUZZ_MAX_POINTS;
    sw.first_level = ((data[2] >> 3) & 7) % 5;
    sw.shard_index = shards[data[2] >> 6][0];
    sw.shard_count = shards[data[2] >> 6][1];
    rest = (const char *) data + 3;
    restlen = size - 3;
    if (memchr(rest, '\0', restlen) != NULL || !fuzz_numbers_small(rest, restlen))
        return 0;
    nl = memchr(rest, '\n', restlen);
    optlen = nl ? (size_t) (nl - rest) : restlen;
    lines = malloc(restlen + 1);
    sets = malloc(restlen + 1);
    len = strlen(base) + restlen + strlen(what) + 8;
    text = malloc(len);
    if (text == NULL || lines == NULL || sets == NULL)
        abort();
    split_lines(lines, sets, rest, restlen);
    /* base, the extra lines, then the analysis line */
    snprintf(text, len, "%s\n%s%s %.*s\n", base, lines, what, (int) optlen, rest);
    if (getenv("FUZZ_SHOW") != NULL) {
        fprintf(stderr, "# --max-prec %ld --sweep-level %s --shard %ld/%ld", (long) max_prec,
                rs_sweep_level_names[sw.first_level], (long) sw.shard_index, (long) sw.shard_count);
        for (set = sets; *set != '\0'; set += strlen(set) + 1)
            fprintf(stderr, " --set '%s'", set);
        fprintf(stderr, "\n%s", text);
    }
    rs_case_init(c);
    rs_model_init(m);
    rs_error_init(err);
    r = rs_case_parse_string(c, FUZZ_CASE_PATH, text, strlen(text), err);
    if (r == RS_OK) r = rs_model_lower(m, c, err);
    for (set = sets; r == RS_OK && *set != '\0'; set += strlen(set) + 1)
        r = rs_case_set_value(c, set, err);
    fuzz_check_error(r, err);
    if (r == RS_OK && fuzz_case_small(c, m)) {
        fuzz_options(&opt, max_prec);
        opt.sweep = sw;
        fuzz_run(c, &opt);
    }
    rs_model_clear(m);
    rs_case_clear(c);
    free(text);
    free(lines);
    free(sets);
    return 0;
}
