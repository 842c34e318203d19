/* The libc allocator behind a NULL hook; firmware builds may leave this file out. */
#include <stdlib.h>

#include "internal.h"

void *qc_default_alloc(void *ud, void *ptr, size_t old_size, size_t new_size)
{
    (void)ud;
    (void)old_size;
    if (new_size == 0) {
        free(ptr);
        return NULL;
    }
    return realloc(ptr, new_size);
}
