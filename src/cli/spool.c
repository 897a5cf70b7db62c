/* spool.c -- the maps' tables streamed to temporary files (spool.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "spool.h"

/* the run's spools: one command run, one list (the command is the only user) */
static FILE **spools;
static slong nspools;

FILE *rs_cli_spool_open(void *arg, slong *id)
{
    const char *tdir = getenv("TMPDIR");
    char path[4096];
    FILE *f, **more;
    int fd;
    (void) arg;
    snprintf(path, sizeof path, "%s/recstab-table.XXXXXX", tdir && *tdir ? tdir : "/tmp");
    fd = mkstemp(path);
    if (fd < 0) return NULL;
    unlink(path);   /* gone with the last descriptor, whatever ends the run */
    f = fdopen(fd, "w+");
    more = realloc(spools, (size_t) (nspools + 1) * sizeof(FILE *));
    if (f == NULL || more == NULL) {
        if (f != NULL) fclose(f);
        else close(fd);
        if (more != NULL) spools = more;
        return NULL;
    }
    spools = more;
    spools[nspools] = f;
    *id = nspools++;
    return f;
}

FILE *rs_cli_spool_get(void *arg, slong id)
{
    (void) arg;
    if (id < 0 || id >= nspools || fflush(spools[id]) != 0 || fseek(spools[id], 0, SEEK_SET) != 0) return NULL;
    return spools[id];
}

slong rs_cli_spool_of(const json_t *el)
{
    const json_t *v = json_object_get(el, "table_spool");
    return json_is_integer(v) ? (slong) json_integer_value(v) : -1;
}

int rs_cli_spool_copy(FILE *f, slong id, int skip_header)
{
    FILE *sp = rs_cli_spool_get(NULL, id);
    char buf[1 << 16];
    size_t n;
    int c;
    if (sp == NULL) return -1;
    if (skip_header)
        while ((c = getc(sp)) != EOF && c != '\n') {}
    while ((n = fread(buf, 1, sizeof buf, sp)) > 0)
        if (fwrite(buf, 1, n, f) != n) return -1;
    return ferror(sp) ? -1 : 0;
}

char *rs_cli_spool_text(slong id)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    int r;
    if (f == NULL) return NULL;
    r = rs_cli_spool_copy(f, id, 0);
    fclose(f);
    if (r != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}

void rs_cli_spools_close(void)
{
    slong k;
    for (k = 0; k < nspools; k++) fclose(spools[k]);
    free(spools);
    spools = NULL;
    nspools = 0;
}
