/* A counting allocator for tests: checks sizes, counts live blocks and can fail the k-th allocation. */
#ifndef TESTALLOC_H
#define TESTALLOC_H

#include <stddef.h>

typedef struct testalloc {
    size_t live_blocks, live_bytes, peak_bytes;
    size_t allocs;      /* successful (re)allocations so far */
    size_t fail_at;     /* 1-based: the fail_at-th (re)allocation fails; 0 = never */
    int size_mismatch;  /* set if a free/realloc passed a wrong old size */
} testalloc;

void *testalloc_fn(void *ud, void *ptr, size_t old_size, size_t new_size);

#endif
