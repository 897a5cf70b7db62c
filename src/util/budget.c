/* budget.c -- wall-time and memory budget (see budget.h for the global state). */
#define _GNU_SOURCE
#include <limits.h>
#include <malloc.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <sys/mman.h>
#include <time.h>
#include <unistd.h>
#include <gmp.h>
#include <jansson.h>
#include "recstab/budget.h"

static _Atomic double deadline_start;   /* monotonic seconds at the start */
static _Atomic double time_limit;       /* seconds, <= 0 none */
static _Atomic long memory_limit;       /* bytes, <= 0 none */
static _Atomic long memory_used;        /* counted bytes (may dip below 0: blocks from before) */
static _Atomic int exceeded;            /* 0, 1 time, 2 memory */
static _Atomic int claimed;             /* the first hit writes exceeded_what */
static _Atomic int installed;
static void (*_Atomic fatal_hook)(const char *msg);
static char exceeded_what[128];          /* written once, by the first to set exceeded */

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double) ts.tv_sec + 1e-9 * (double) ts.tv_nsec;
}

static void format_limit(char *buf, size_t len, int which, const char *what)
{
    if (which == 1)
        snprintf(buf, len, "time limit of %g s reached during %s; raise it with --time-limit",
                 atomic_load(&time_limit), what);
    else
        snprintf(buf, len, "memory limit of %ld MB reached during %s; raise it with --memory-limit",
                 atomic_load(&memory_limit) >> 20, what);
}

/* ---- counting allocators ---------------------------------------------------- */

/* bytes as a counter delta (requests past LONG_MAX / 2 fail anyway) */
static long as_count(size_t n)
{
    return n > (size_t) LONG_MAX / 2 ? LONG_MAX / 2 : (long) n;
}

/* Each thread sums its allocations and frees locally and adds the sum to
 * memory_used (one atomic, one limit test) once it passes +-FLUSH bytes:
 * the counting was ~10 % of all instructions with an atomic and a limit
 * test per call.  The shared count lags by under FLUSH per thread, far below
 * the limit's resolution (MB); a request of FLUSH or more is counted before
 * the call, so a huge request past the limit reaches the hook before FLINT
 * aborts on its failed malloc. */
#define FLUSH (256L << 10)
/* initial-exec: no __tls_get_addr call per allocation in librecstab.so */
static _Thread_local long pending __attribute__((tls_model("initial-exec")));

/* Past the limit, FLINT would abort on a failed malloc sooner or later, so
 * the command's hook ends the run with a message first. */
static void count_flush(long n)
{
    long lim = atomic_load(&memory_limit);
    long used = atomic_fetch_add(&memory_used, n) + n;
    void (*hook)(const char *) = atomic_load(&fatal_hook);
    if (lim > 0 && used > lim && hook != NULL) {
        char msg[300];
        format_limit(msg, sizeof msg, 2, "an allocation");
        hook(msg);
    }
}

static inline void count(long n)
{
    long t = pending + n;
    if (t < FLUSH && t > -FLUSH) {
        pending = t;
        return;
    }
    pending = 0;
    count_flush(t);
}

/* after a counted-before call: the block's real size instead of the request */
static void count_fix(void *p, long counted)
{
    count((p != NULL ? (long) malloc_usable_size(p) : 0) - counted);
}

/* The two pools below hide blocks from AddressSanitizer (a freed block is
 * reused without going through its allocator), so a sanitizer build does
 * without them: every allocation then goes to malloc and is checked. */
#if defined(__SANITIZE_ADDRESS__)
#define RS_BUDGET_POOLS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RS_BUDGET_POOLS 0
#endif
#endif
#ifndef RS_BUDGET_POOLS
#define RS_BUDGET_POOLS 1
#endif

/* ---- a cache of small freed blocks ---------------------------------------------
 * FLINT and GMP allocate and free many small blocks (an exact run of a
 * small case: ~20 000 allocations of under 256 bytes); glibc's calloc never
 * uses its per-thread cache (tcache) and that cache holds 7 blocks per size,
 * so most of them took glibc's slow paths (about a quarter of the analysis's
 * instructions).  Each thread keeps up to CACHE_DEPTH freed blocks per size
 * class and hands them out again.  A block is classed by its usable size
 * rounded down, a request by its size rounded up, so a block always holds
 * the request whatever the allocator.  Cached blocks stay counted as used
 * (they are held): only blocks that go back to glibc are uncounted, so the
 * memory budget sees at least what the process holds.  A thread's cache is
 * emptied when it exits; the main thread's is left to the process's exit. */
#define CACHE_CLASSES 16                   /* usable sizes 24 .. 248 bytes */
#define CACHE_DEPTH 64
typedef struct {
    int n[CACHE_CLASSES];
    void *blk[CACHE_CLASSES][CACHE_DEPTH];
} bcache_t;
/* a pointer only: a few bytes of initial-exec TLS (the library may be dlopen'ed) */
static _Thread_local bcache_t *tcache_ __attribute__((tls_model("initial-exec")));
static pthread_key_t cache_key;
static pthread_once_t cache_once = PTHREAD_ONCE_INIT;

static void cache_release(void *arg)
{
    bcache_t *c = arg;
    int i, j;
    for (i = 0; i < CACHE_CLASSES; i++)
        for (j = 0; j < c->n[i]; j++) {
            count(-(long) malloc_usable_size(c->blk[i][j]));
            free(c->blk[i][j]);
        }
    tcache_ = NULL;
    free(c);
}

static void cache_key_make(void)
{
    if (pthread_key_create(&cache_key, cache_release) != 0) cache_key = (pthread_key_t) -1;
}

static bcache_t *cache_get(void)
{
    bcache_t *c = tcache_;
    if (c != NULL) return c;
    pthread_once(&cache_once, cache_key_make);
    if (cache_key == (pthread_key_t) -1 || (c = calloc(1, sizeof(bcache_t))) == NULL) return NULL;
    if (pthread_setspecific(cache_key, c) != 0) { free(c); return NULL; }
    tcache_ = c;
    return c;
}

/* a request of n bytes: the class whose smallest block (16 c + 8) holds it */
static inline size_t cache_class_req(size_t n)
{
    return n <= 24 ? 1 : (n - 8 + 15) >> 4;
}

static inline void *cache_pop(size_t n)
{
    bcache_t *c = tcache_;
    size_t k = cache_class_req(n);
    if (!RS_BUDGET_POOLS || c == NULL || k >= CACHE_CLASSES || c->n[k] == 0) return NULL;
    return c->blk[k][--c->n[k]];
}

/* ---- GMP's two-limb blocks ------------------------------------------------------
 * FLINT 2.9 fills its cache of big integers 4064 at a time, each mpz_init2'd
 * with two limbs (16 bytes) through GMP's allocator: 4064 mallocs and about
 * 130 KB of heap written (every chunk header), about 1 M instructions and 35
 * page faults in any run that meets one integer past 62 bits, though such a
 * run uses a few hundred of them.  GMP's requests of at most 16 bytes are
 * carved from a reserved region instead, whose pages are touched only when a
 * block is written; freed ones go on the freeing thread's list.  The region
 * is counted as used 4 KB at a time as it is carved (never returned); when it
 * is full, or could not be reserved, GMP's blocks come from malloc as before.
 * Every free and realloc (FLINT's or GMP's) checks the range first, so a
 * block always goes back to where it came from. */
#define SLAB_BLOCK 16
#define SLAB_REGION (16L << 20)
#define SLAB_CHUNK 4096L
static char *slab_base;                  /* set once by install() */
static _Atomic long slab_top;            /* bytes of the region handed to threads */
static _Thread_local char *slab_cur __attribute__((tls_model("initial-exec")));
static _Thread_local char *slab_end __attribute__((tls_model("initial-exec")));
static _Thread_local void *slab_list __attribute__((tls_model("initial-exec")));

static inline int in_slab(const void *p)
{
    return slab_base != NULL && (uintptr_t) p - (uintptr_t) slab_base < (uintptr_t) SLAB_REGION;
}

static void *slab_alloc(void)
{
    void *p = slab_list;
    if (slab_base == NULL) return NULL;
    if (p != NULL) {
        slab_list = *(void **) p;
        return p;
    }
    if (slab_cur == slab_end) {
        long off;
        if (atomic_load(&slab_top) >= SLAB_REGION) return NULL;   /* full: malloc's */
        off = atomic_fetch_add(&slab_top, SLAB_CHUNK);
        if (off + SLAB_CHUNK > SLAB_REGION) return NULL;
        count(SLAB_CHUNK);
        slab_cur = slab_base + off;
        slab_end = slab_cur + SLAB_CHUNK;
    }
    p = slab_cur;
    slab_cur += SLAB_BLOCK;
    return p;
}

static inline void slab_release(void *p)
{
    *(void **) p = slab_list;
    slab_list = p;
}

/* ---- large blocks on transparent huge pages --------------------------------------
 * The exact engine's large blocks (the composed minors, their printed text:
 * 27 MB strings for a 6-mass chain) are fresh mappings written once, and
 * with 4 KB pages each page is a fault: 150 000 faults, about 15 % of that
 * run on this VM (issue 17, h-chain12).  glibc maps every such block on its
 * own (its header says so: IS_MMAPPED, bit 1 of the size word, the mapping
 * starting 16 bytes before the block), so the whole mapping is advised for
 * huge pages (the kernel's "madvise" mode) without splitting any other
 * mapping; blocks from the heap, or from another allocator, are left alone.
 * Only the page size of memory the block already holds changes. */
#define HUGE_MIN (4L << 20)

static void huge_advise(void *p, size_t n)
{
#if RS_BUDGET_POOLS && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
    size_t sz;
    char *start;
    long pg;
    if (p == NULL || n < (size_t) HUGE_MIN) return;   /* every allocation passes here: the size first */
    pg = sysconf(_SC_PAGESIZE);
    if (pg <= 0) return;
    sz = ((const size_t *) p)[-1];
    start = (char *) p - 2 * sizeof(size_t);
    if (!(sz & 2) || ((uintptr_t) start & (uintptr_t) (pg - 1)) != 0) return;
    sz &= ~(size_t) 7;
    sz &= ~(size_t) (pg - 1);
    if (sz >= n) (void) madvise(start, sz, MADV_HUGEPAGE);
#else
    (void) p;
    (void) n;
#endif
}

/* jansson's strings (every printed polynomial is copied into one) */
static void *j_malloc(size_t n)
{
    void *p = malloc(n);
    huge_advise(p, n);
    return p;
}

static void b_free(void *p)
{
    long u;
    if (p == NULL) return;
    if (in_slab(p)) { slab_release(p); return; }
    u = (long) malloc_usable_size(p);
    if (RS_BUDGET_POOLS && u >= 24 && ((u - 8) >> 4) < CACHE_CLASSES) {
        bcache_t *c = cache_get();
        size_t k = (size_t) (u - 8) >> 4;        /* rounded down: 16 k + 8 <= u */
        if (c != NULL && c->n[k] < CACHE_DEPTH) {
            c->blk[k][c->n[k]++] = p;
            return;
        }
    }
    count(-u);
    free(p);
}

static void *b_malloc(size_t n)
{
    void *p;
    if (n < (size_t) FLUSH) {
        if ((p = cache_pop(n)) != NULL) return p;
        p = malloc(n);
        if (p != NULL) count((long) malloc_usable_size(p));
        return p;
    }
    count_flush(as_count(n));
    p = malloc(n);
    count_fix(p, as_count(n));
    huge_advise(p, n);
    return p;
}

static void *b_calloc(size_t k, size_t n)
{
    long c = (n != 0 && k > ((size_t) -1) / n) ? LONG_MAX / 2 : as_count(k * n);
    void *p;
    if (c < FLUSH) {
        if ((p = cache_pop((size_t) c)) != NULL) return memset(p, 0, (size_t) c);
        p = calloc(k, n);
        if (p != NULL) count((long) malloc_usable_size(p));
        return p;
    }
    count_flush(c);
    p = calloc(k, n);
    count_fix(p, c);
    huge_advise(p, (size_t) c);
    return p;
}

static void *b_realloc(void *q, size_t n)
{
    long old, c = as_count(n);
    void *p;
    if (in_slab(q)) {                      /* a GMP block outgrown (or shrunk) */
        if (n <= SLAB_BLOCK && n > 0) return q;
        if (n == 0) { slab_release(q); return NULL; }
        if ((p = b_malloc(n)) != NULL) {
            memcpy(p, q, SLAB_BLOCK);
            slab_release(q);
        }
        return p;
    }
    old = (q != NULL) ? (long) malloc_usable_size(q) : 0;
    if (n == 0 && q != NULL) {   /* glibc: frees q, returns NULL */
        b_free(q);
        return NULL;
    }
    if (c - old < FLUSH) {
        p = realloc(q, n);
        if (p != NULL) count((long) malloc_usable_size(p) - old);
        return p;
    }
    count_flush(c - old);
    p = realloc(q, n);
    if (p != NULL) count_fix(p, c);
    else count(old - c);   /* q is unchanged */
    huge_advise(p, n);
    return p;
}

static void *g_realloc(void *p, size_t old, size_t n) { (void) old; return b_realloc(p, n); }
static void g_free(void *p, size_t n) { (void) n; b_free(p); }

/* GMP's allocations: the small ones from the region */
static void *g_malloc(size_t n)
{
    void *p;
    if (n <= SLAB_BLOCK && (p = slab_alloc()) != NULL) return p;
    return b_malloc(n);
}

/* FLINT's and GMP's default allocators are malloc/realloc/free, so blocks
 * from before the switch are freed correctly (only counted approximately). */
static void install(void)
{
    int expect = 0;
    void *r;
    if (!atomic_compare_exchange_strong(&installed, &expect, 1)) return;
    /* address space only: a page is backed when a block in it is written */
    r = RS_BUDGET_POOLS ? mmap(NULL, (size_t) SLAB_REGION, PROT_READ | PROT_WRITE,
                               MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0) : MAP_FAILED;
    slab_base = r == MAP_FAILED ? NULL : r;
    __flint_set_memory_functions(b_malloc, b_calloc, b_realloc, b_free);
    mp_set_memory_functions(g_malloc, g_realloc, g_free);
    /* malloc's own blocks, so those made before are freed the same way */
    json_set_alloc_funcs(j_malloc, free);
}

/* ---- the budget --------------------------------------------------------------- */

slong rs_budget_memory_default(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || size <= 0) return 1024;
    return (slong) (((double) pages * (double) size) / 2.0 / 1048576.0);
}

void rs_budget_start(double seconds, double spent, slong megabytes)
{
    install();
    atomic_store(&exceeded, 0);
    atomic_store(&claimed, 0);
    atomic_store(&deadline_start, now() - spent);
    atomic_store(&time_limit, seconds);
    atomic_store(&memory_limit, megabytes > 0 ? (long) megabytes << 20 : 0);
}

void rs_budget_stop(void)
{
    atomic_store(&time_limit, 0.0);
    atomic_store(&memory_limit, 0);
}

void rs_budget_set_fatal(void (*fatal)(const char *msg))
{
    atomic_store(&fatal_hook, fatal);
}

double rs_budget_elapsed(void)
{
    return now() - atomic_load(&deadline_start);
}

slong rs_budget_memory_used(void)
{
    long u = atomic_load(&memory_used) + pending;
    return u > 0 ? u : 0;
}

int rs_budget_exceeded(void)
{
    return atomic_load(&exceeded) != 0;
}

int rs_budget_error(rs_error_t err)
{
    int which = atomic_load(&exceeded);
    char msg[300];
    if (which == 0) return RS_OK;
    /* loops that skip their remaining work ask once per item with no err:
     * no message to format (900 000 snprintf calls took a second under ASan) */
    if (err == NULL) return RS_ERR_LIMIT;
    format_limit(msg, sizeof msg, which, exceeded_what);
    return rs_error_set(err, RS_ERR_LIMIT, "%s", msg);
}

/* records the first limit hit and what was running */
static int hit(rs_error_t err, int which, const char *what)
{
    int expect = 0;
    if (atomic_compare_exchange_strong(&claimed, &expect, 1)) {
        snprintf(exceeded_what, sizeof exceeded_what, "%s", what);
        atomic_store(&exceeded, which);
    }
    while (atomic_load(&exceeded) == 0) ;   /* another thread is writing the message */
    return rs_budget_error(err);
}

int rs_budget_check(rs_error_t err, const char *what)
{
    double tl = atomic_load(&time_limit);
    long ml = atomic_load(&memory_limit);
    if (atomic_load(&exceeded)) return rs_budget_error(err);
    if (tl > 0 && now() - atomic_load(&deadline_start) >= tl) return hit(err, 1, what);
    if (ml > 0 && atomic_load(&memory_used) + pending > ml) return hit(err, 2, what);
    return RS_OK;
}

int rs_budget_estimate(rs_error_t err, const char *what, double seconds, double bytes)
{
    double tl = atomic_load(&time_limit), left = tl - rs_budget_elapsed();
    long ml = atomic_load(&memory_limit);
    int r = rs_budget_check(err, what);
    if (r != RS_OK) return r;
    /* compared with what is left, reported against the limit (the message
     * must not depend on how long parsing took) */
    if (tl > 0 && seconds > left)
        return rs_error_set(err, RS_ERR_LIMIT,
                            "%s would take about %.3g s (estimated), more than the time limit of %g s allows; "
                            "raise it with --time-limit", what, seconds, tl);
    if (ml > 0 && bytes > (double) (ml - rs_budget_memory_used()))
        return rs_error_set(err, RS_ERR_LIMIT,
                            "%s would need about %.3g MB (estimated), more than the memory limit of %ld MB allows; "
                            "raise it with --memory-limit", what, bytes / 1048576.0, ml >> 20);
    return RS_OK;
}

double rs_budget_mpoly_mul_seconds(const fmpz_mpoly_t a, const fmpz_mpoly_t b)
{
    double limbs = 1.0 + (double) (FLINT_ABS(fmpz_mpoly_max_bits(a)) + FLINT_ABS(fmpz_mpoly_max_bits(b))) / 64.0;
    return 4e-10 * (double) a->length * (double) b->length * limbs;
}

void rs_budget_calib_init(rs_budget_calib_t *c)
{
    c->scale = 1.0;
    c->raw = 0.0;
    c->c0 = clock();
}

double rs_budget_calib_begin(rs_budget_calib_t *c, double raw)
{
    c->raw = raw;
    c->c0 = clock();
    return raw * c->scale;
}

void rs_budget_calib_end(rs_budget_calib_t *c)
{
    double cpu = (double) (clock() - c->c0) / CLOCKS_PER_SEC;
    if (cpu >= 0.05 && c->raw > 0.0)
        c->scale = cpu / c->raw > 1.0 ? cpu / c->raw : 1.0;
}
