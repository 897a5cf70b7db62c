/* heap.h -- the command's heap on a transparent huge page (issue 13). */
#ifndef RECSTAB_CLI_HEAP_H
#define RECSTAB_CLI_HEAP_H

/* Call first in main, before anything large is allocated.  Moves glibc's
 * heap top to a 2 MB boundary and asks for that 2 MB to be one transparent
 * huge page (MADV_HUGEPAGE; the system's "madvise" mode), so that the first
 * 2 MB of the run's allocations cost one page fault instead of one per 4 KB
 * page.  Best effort: without glibc, THP or the address space nothing
 * changes but a few MB of untouched address space. */
void rs_cli_heap_prepare(void);

#endif
