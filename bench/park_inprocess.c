/* park_inprocess.c -- the Park pipeline in-process (issue 17): the one-call
 * API rs_analyse_json_with on cases/park-staggered.case with the three
 * analyses SymPy's peer (bench/sympy_park.py) computes -- charpoly,
 * bilinear, hurwitz -- N times in one process, so that neither side pays
 * for exec, dynamic loading or the Python import.
 *
 *   build/park_inprocess [-n N] [CASE]       (make bench builds and runs it)
 *
 * Prints the CPU time of the first call (cold: FLINT's and the library's
 * first allocations) and the median, minimum and mean CPU per call of the
 * N calls after it (CLOCK_PROCESS_CPUTIME_ID: robust to the load of a
 * shared machine), and checks that every call returned status 0 with the
 * same document, bytes after the "seconds" keys aside (exit 3 otherwise).
 * Last lines, machine-readable for bench/run.sh:
 *   inprocess_first_cpu_ms: X
 *   inprocess_median_cpu_ms: X */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <recstab/recstab.h>

static double cpu_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *) a, y = *(const double *) b;
    return (x > y) - (x < y);
}

/* the document with every "seconds": VALUE blanked, in place */
static void blank_seconds(char *s)
{
    const char *key = "\"seconds\":";
    char *p = s;
    while ((p = strstr(p, key)) != NULL) {
        p += strlen(key);
        while (*p == ' ') p++;
        while (*p != '\0' && *p != ',' && *p != '\n' && *p != '}') *p++ = ' ';
    }
}

static char *read_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = NULL;
    long n;
    if (f == NULL) return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0
        && (text = malloc((size_t) n + 1)) != NULL) {
        if (fread(text, 1, (size_t) n, f) != (size_t) n) { free(text); text = NULL; }
        else text[n] = '\0';
    }
    fclose(f);
    return text;
}

int main(int argc, char **argv)
{
    const char *path = "cases/park-staggered.case";
    const char *analyses[] = { "charpoly", "bilinear", "hurwitz", NULL };
    long n = 200, k;
    char *text, *first = NULL, *json;
    double *t, t0, t_first, sum = 0;
    int status, bad = 0, i;

    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-n") == 0 && i + 1 < argc) n = strtol(argv[++i], NULL, 10);
        else path = argv[i];
    }
    if (n < 1) n = 1;
    if ((text = read_file(path)) == NULL) {
        fprintf(stderr, "park_inprocess: cannot read %s\n", path);
        return 2;
    }
    if ((t = malloc(sizeof *t * (size_t) n)) == NULL) { free(text); return 2; }

    t0 = cpu_ms();
    status = rs_analyse_json_with(text, path, NULL, analyses, 0, -1, -1, &first);
    t_first = cpu_ms() - t0;
    if (first == NULL || status != 0) {
        fprintf(stderr, "park_inprocess: status %d on the first call\n%s\n", status,
                first != NULL ? first : "(no document)");
        rs_free(first); free(t); free(text);
        return 3;
    }
    blank_seconds(first);
    for (k = 0; k < n; k++) {
        json = NULL;
        t0 = cpu_ms();
        status = rs_analyse_json_with(text, path, NULL, analyses, 0, -1, -1, &json);
        t[k] = cpu_ms() - t0;
        sum += t[k];
        if (json != NULL) blank_seconds(json);
        if (status != 0 || json == NULL || strcmp(json, first) != 0) bad = 1;
        rs_free(json);
    }
    qsort(t, (size_t) n, sizeof *t, cmp_double);
    printf("park_inprocess: %s, analyses charpoly + bilinear + hurwitz, 1 + %ld calls of rs_analyse_json_with\n",
           path, n);
    printf("first call:  %.3f ms CPU\n", t_first);
    printf("next %ld:    median %.3f ms, min %.3f ms, mean %.3f ms CPU per call\n", n, t[n / 2], t[0],
           sum / (double) n);
    printf("documents:   %s\n", bad ? "DIFFER between calls" : "identical on every call");
    printf("inprocess_first_cpu_ms: %.3f\n", t_first);
    printf("inprocess_median_cpu_ms: %.3f\n", t[n / 2]);
    rs_free(first); free(t); free(text);
    return bad ? 3 : 0;
}
