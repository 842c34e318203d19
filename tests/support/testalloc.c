#include "testalloc.h"

#include <stdlib.h>
#include <string.h>

/* Each block carries its size in a header so mismatched old sizes are caught. */
typedef union header { size_t size; long double ld; void *p; } header;

void *testalloc_fn(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    testalloc *t = ud;
    header *h = ptr != NULL ? (header *)ptr - 1 : NULL;

    if (h != NULL && h->size != old_size)
        t->size_mismatch = 1;
    if (new_size == 0) {
        if (h != NULL) {
            t->live_blocks--;
            t->live_bytes -= h->size;
            free(h);
        }
        return NULL;
    }
    if (t->fail_at != 0 && t->allocs + 1 == t->fail_at) {
        t->fail_at = 0; /* fail once */
        t->allocs++;
        return NULL;
    }
    t->allocs++;
    {
        size_t old = h != NULL ? h->size : 0;
        header *n = realloc(h, sizeof *n + new_size);

        if (n == NULL)
            return NULL;
        if (h == NULL)
            t->live_blocks++;
        n->size = new_size;
        t->live_bytes = t->live_bytes - old + new_size;
        if (t->live_bytes > t->peak_bytes)
            t->peak_bytes = t->live_bytes;
        return n + 1;
    }
}
