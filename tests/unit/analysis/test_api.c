/* test_api.c -- the one-call API (recstab/api.h) against the command.
 * The expected values are the command's own output: the API must give the
 * document `recstab --json CASE` prints (keys that vary between runs,
 * "seconds", "seconds_points" and "threads", removed from both) and the
 * same exit status, for every case file under cases/ and every bad-input
 * file tests/bad/NAME.case without options (NAME.args), where the API's
 * {"error": {"message"}} must be the command's stderr line without
 * "recstab: ".  The exit statuses of rs_run_exit_status come from the
 * README's definition (0 done, 1 a claim or expectation failed, 2 bad input
 * or a limit, 3 two methods disagree or an internal error; the worst case
 * wins). */
#include "testutil.h"
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/wait.h>
#include <jansson.h>
#include "recstab/api.h"

static char *slurp(FILE *f)
{
    char *buf = NULL;
    size_t len = 0, n;
    char chunk[65536];
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) {
        buf = realloc(buf, len + n + 1);
        memcpy(buf + len, chunk, n);
        len += n;
    }
    if (buf == NULL) buf = calloc(1, 1);
    else buf[len] = '\0';
    return buf;
}

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *s;
    if (f == NULL) return NULL;
    s = slurp(f);
    fclose(f);
    return s;
}

/* drops the keys that vary from run to run, everywhere in j */
static void strip_volatile(json_t *j)
{
    size_t k;
    const char *key;
    json_t *v;
    if (json_is_array(j)) {
        json_array_foreach(j, k, v) strip_volatile(v);
    } else if (json_is_object(j)) {
        json_object_del(j, "seconds");
        json_object_del(j, "seconds_points");
        json_object_del(j, "threads");
        json_object_foreach(j, key, v) strip_volatile(v);
    }
}

static char *normalised(const char *text)
{
    json_error_t e;
    json_t *j = json_loads(text, 0, &e);
    char *s;
    if (j == NULL) return NULL;
    strip_volatile(j);
    s = json_dumps(j, JSON_INDENT(2) | JSON_PRESERVE_ORDER);
    json_decref(j);
    return s;
}

/* `recstab --json path`: stdout, stderr and the exit status */
static int run_command(const char *path, char **out, char **err)
{
    const char *build = getenv("BUILD") != NULL ? getenv("BUILD") : "build";
    char cmd[2048], errpath[64];
    FILE *p;
    int st;
    snprintf(errpath, sizeof errpath, "/tmp/test_api_err.%ld", (long) getpid());
    snprintf(cmd, sizeof cmd, "'%s/recstab' --json '%s' 2>%s", build, path, errpath);
    p = popen(cmd, "r");
    assert_non_null(p);
    *out = slurp(p);
    st = pclose(p);
    *err = read_file(errpath);
    unlink(errpath);
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

/* the API on path's text, named path, against the command */
static int compare_one(const char *path)
{
    char *text = read_file(path), *json = NULL, *out, *err;
    int status, want, ok = 1;
    assert_non_null(text);
    status = rs_analyse_json(text, path, &json);
    want = run_command(path, &out, &err);
    assert_non_null(json);
    if (status != want) {
        fprintf(stderr, "%s: API status %d, command %d\n", path, status, want);
        ok = 0;
    } else if (want <= 1 || (want == 3 && out[0] != '\0')) {
        char *a = normalised(json), *b = normalised(out);
        if (a == NULL || b == NULL || strcmp(a, b) != 0) {
            fprintf(stderr, "%s: the API's document differs from the command's\n", path);
            ok = 0;
        }
        free(a);
        free(b);
    } else {
        /* no document: the command's message on stderr is the API's error */
        json_t *j = json_loads(json, 0, NULL);
        const char *msg = json_string_value(json_object_get(json_object_get(j, "error"), "message"));
        size_t n = strlen(err);
        if (out[0] != '\0' || msg == NULL || strncmp(err, "recstab: ", 9) != 0 || n < 10
            || strncmp(err + 9, msg, n - 10) != 0 || strlen(msg) != n - 10) {
            fprintf(stderr, "%s: API error '%s', command stderr '%s'\n", path, msg ? msg : "(none)", err);
            ok = 0;
        }
        json_decref(j);
    }
    rs_free(json);
    free(text);
    free(out);
    free(err);
    return ok;
}

static void compare_list(const char *find)
{
    FILE *p = popen(find, "r");
    char line[1024];
    int n = 0, bad = 0;
    assert_non_null(p);
    while (fgets(line, sizeof line, p) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        if (line[0] == '\0') continue;
        n++;
        bad += !compare_one(line);
    }
    pclose(p);
    assert_true(n >= 20);   /* the list was found */
    assert_int_equal(bad, 0);
}

static void test_api_every_case_as_command(void **state)
{
    (void) state;
    compare_list("find cases -name '*.case' | sort");
}

static void test_api_bad_input_as_command(void **state)
{
    (void) state;
    compare_list("for f in tests/bad/*.case; do [ -f \"${f%.case}.args\" ] || echo \"$f\"; done");
}

static void test_api_exit_status(void **state)
{
    (void) state;
    assert_int_equal(rs_run_exit_status(RS_OK, RS_OUTCOME_OK, 0), 0);
    assert_int_equal(rs_run_exit_status(RS_OK, RS_OUTCOME_FAILED, 0), 1);
    assert_int_equal(rs_run_exit_status(RS_OK, RS_OUTCOME_INCONSISTENT, 0), 3);
    assert_int_equal(rs_run_exit_status(RS_OK, RS_OUTCOME_FAILED | RS_OUTCOME_INCONSISTENT, 0), 3);
    assert_int_equal(rs_run_exit_status(RS_OK, RS_OUTCOME_FAILED, 3), 3);   /* the worst case wins */
    assert_int_equal(rs_run_exit_status(RS_OK, RS_OUTCOME_OK, 1), 1);
    assert_int_equal(rs_run_exit_status(RS_ERR_INPUT, 0, 0), 2);
    assert_int_equal(rs_run_exit_status(RS_ERR_LIMIT, 0, 0), 2);
    assert_int_equal(rs_run_exit_status(RS_ERR_INCONSISTENT, 0, 0), 3);
    assert_int_equal(rs_run_exit_status(RS_ERR_INTERNAL, 0, 0), 3);
}

/* --set and --analyse through rs_analyse_json_with: central difference at
 * w = 3 has p = l^2 + 7 l + 1 (2 - w^2 = -7), roots (-7 +- sqrt 45)/2, one
 * of modulus (7 + sqrt 45)/2 > 1: unstable (Hughes, ch. 9: w > 2). */
static void test_api_with_sets_and_analyses(void **state)
{
    const char *sets[] = {"w=3", NULL}, *an[] = {"stability", NULL};
    char *text = read_file("cases/textbook/central-difference.case"), *json = NULL;
    json_t *j, *r;
    (void) state;
    assert_non_null(text);
    assert_int_equal(rs_analyse_json_with(text, "cases/textbook/central-difference.case", sets, an, 0, -1, -1, &json), 0);
    j = json_loads(json, 0, NULL);
    assert_non_null(j);
    /* one shape for every run: {"cases": [DOC]} */
    assert_int_equal(json_array_size(json_object_get(j, "cases")), 1);
    r = json_array_get(json_object_get(json_array_get(json_object_get(j, "cases"), 0), "results"), 0);
    assert_string_equal(json_string_value(json_object_get(r, "analysis")), "stability");
    assert_non_null(strstr(json, "\"unstable\""));
    assert_null(json_object_get(json_array_get(json_object_get(j, "cases"), 0), "scheme"));
    json_decref(j);
    rs_free(json);
    /* RS_RUN_SCHEME: the document carries the scheme, as under --markdown */
    assert_int_equal(rs_analyse_json_with(text, "x.case", sets, an, RS_RUN_SCHEME, -1, -1, &json), 0);
    j = json_loads(json, 0, NULL);
    assert_non_null(json_object_get(json_array_get(json_object_get(j, "cases"), 0), "scheme"));
    json_decref(j);
    rs_free(json);
    /* a name the case does not declare: exit 2, the error as a document */
    sets[0] = "nosuch=1";
    assert_int_equal(rs_analyse_json_with(text, "x.case", sets, NULL, 0, -1, -1, &json), 2);
    assert_non_null(strstr(json, "\"error\""));
    rs_free(json);
    /* the time budget: the engine counts at least 1 us per point
     * (rs_sweep_estimate, a fixed lower bound, not a measurement), so a map
     * of 2000 x 1000 points needs 2 s and a 1 s limit refuses it before it
     * runs: code "limit", exit 2, as with --time-limit 1 */
    assert_int_equal(rs_analyse_json_with("param a\nparam b\nunknown x\neq x[n+1] = a*x[n]\n", "m.case", NULL,
                                          (const char *[]){"map a -2 2 2000, b 0 1 1000", NULL}, 0, 1, -1, &json), 2);
    assert_non_null(strstr(json, "\"code\": \"limit\""));
    assert_non_null(strstr(json, "time limit of 1 s"));
    rs_free(json);
    free(text);
}

static void test_api_null_arguments(void **state)
{
    char *json = NULL;
    (void) state;
    assert_int_equal(rs_analyse_json(NULL, NULL, &json), 2);
    assert_non_null(strstr(json, "no case text"));
    rs_free(json);
    /* json NULL: the status alone; x[n+1] = x[n]/2 (root 1/2) has no
     * request that could fail */
    assert_int_equal(rs_analyse_json("unknown x\neq x[n+1] = x[n]/2\n", NULL, NULL), 0);
    rs_free(NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_api_exit_status),
        cmocka_unit_test(test_api_with_sets_and_analyses),
        cmocka_unit_test(test_api_null_arguments),
        cmocka_unit_test(test_api_every_case_as_command),
        cmocka_unit_test(test_api_bad_input_as_command),
    };
    if (chdir(RS_SOURCE_DIR) != 0) return 1;
    return cmocka_run_group_tests(tests, NULL, NULL);
}
