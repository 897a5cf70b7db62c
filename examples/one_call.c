/* one_call.c -- the one-call API: a case as text in, the JSON document that
 * `recstab --json` prints out, with the command's exit status.
 *
 * The case is the central-difference scheme on x'' = -omega^2 x (w = omega h);
 * its characteristic polynomial is lambda^2 - (2 - w^2) lambda + 1, whose
 * roots stay on the unit circle for 0 < w < 2 (Hughes, The Finite Element
 * Method, ch. 9): the claim "bounded when w < 2" holds (status 0) and
 * "bounded when w < 3" is refuted (status 1). */
#include <stdio.h>
#include <string.h>
#include <recstab/recstab.h>

static const char *scheme =
    "title Central difference\n"
    "param w\n"
    "assume w > 0\n"
    "unknown x\n"
    "eq x[n+1] - 2*x[n] + x[n-1] + w^2*x[n] = 0\n";

/* runs the scheme with one claim line; prints and returns the status */
static int run(const char *claim)
{
    char text[512], *json = NULL;
    int status;
    snprintf(text, sizeof text, "%s%s\n", scheme, claim);
    status = rs_analyse_json(text, "central-difference.case", &json);
    printf("%-32s -> status %d, %s", claim, status, json != NULL && strstr(json, "\"error\"") ? "error document\n" : "");
    if (json != NULL && strstr(json, "\"error\"") == NULL)
        printf("document of %zu bytes\n", strlen(json));
    rs_free(json);
    return status;
}

int main(void)
{
    int ok = 1;
    ok &= run("claim bounded when w < 2") == 0;
    ok &= run("claim bounded when w < 3") == 1;
    ok &= run("claim bounded when w <") == 2;   /* bad input: the error as JSON */
    puts(ok ? "one_call: statuses as expected" : "one_call: UNEXPECTED status");
    return ok ? 0 : 1;
}
