/* spool.c -- the maps' tables streamed to temporary files (spool.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <unistd.h>
#include <sys/sendfile.h>
#include <sys/stat.h>
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

/* The rest of sp copied to f by the kernel (sendfile): the report of a
 * 6-mass chain is 220 MB, and reading it back through a buffer and writing
 * it out again was 6 % of that run (issue 17, h-chain12).  0 when done, -1
 * on a write error, 1 when the kernel cannot copy to f (a memory stream, or
 * a descriptor sendfile refuses before writing anything): then stdio's
 * copy.  sp's position is left where it was (each use rewinds it). */
static int _copy_kernel(FILE *f, FILE *sp)
{
    int fo = fileno(f), fi = fileno(sp);
    off_t off = ftello(sp);
    struct stat st;
    int wrote = 0;
    if (fo < 0 || fi < 0 || off < 0 || fstat(fi, &st) != 0 || fflush(f) != 0) return 1;
    while (off < st.st_size) {
        size_t want = (size_t) (st.st_size - off) < ((size_t) 1 << 30) ? (size_t) (st.st_size - off) : (size_t) 1 << 30;
        ssize_t k = sendfile(fo, fi, &off, want);
        if (k < 0 && errno == EINTR) continue;
        if (k <= 0) return (!wrote && k < 0 && (errno == EINVAL || errno == ENOSYS)) ? 1 : -1;
        wrote = 1;
    }
    return 0;
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
    switch (_copy_kernel(f, sp)) {
    case 0: return 0;
    case -1: return -1;
    default: break;   /* not a file descriptor the kernel copies to */
    }
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
