/* heap.c -- rs_cli_heap_prepare: see heap.h.
 *
 * Why: a small `region ... for all` run touches about 120 fresh 4 KB heap
 * pages, each a page fault (about 18 us each on the benchmark machine, where
 * the whole run is 30-40 ms of CPU); one huge page replaces them (HHT-alpha:
 * 482 -> 356 faults, -4 ms median CPU; bench/README.md, issue 13). */
#define _GNU_SOURCE
#include <malloc.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>
#include "heap.h"

/* the block that fills the heap up to the boundary: never freed (its pages
 * are never touched), kept reachable for leak checkers */
static void *heap_skip;

void rs_cli_heap_prepare(void)
{
#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
    const uintptr_t huge = (uintptr_t) 2 << 20;
    uintptr_t t0, a, hi;
    void *p;
    /* the top pad makes every heap growth reach past the huge page, and
     * keeps it mapped when the top is trimmed (a trim below it would split
     * it); the skip block must come from the heap, not from mmap */
    if (!mallopt(M_TOP_PAD, 4 << 20) || !mallopt(M_MMAP_THRESHOLD, 4 << 20))
        return;
    p = malloc(100000);   /* bigger than any bin so far: the top's start */
    if (p == NULL) goto restore;
    t0 = (uintptr_t) p;
    free(p);
    a = (t0 + 16384 + huge - 1) & ~(huge - 1);
    heap_skip = malloc(a - t0 - 64);   /* the next block starts at about a */
    hi = (uintptr_t) sbrk(0);
    if (heap_skip != NULL && (uintptr_t) heap_skip == t0 && hi >= a + huge)
        madvise((void *) a, huge, MADV_HUGEPAGE);
restore:
    mallopt(M_MMAP_THRESHOLD, 128 << 10);   /* glibc's default */
#endif
}
