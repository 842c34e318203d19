/*
 * The family registry: QC_FAMILY_MAP's descriptors in id order (each lives
 * in its own src/deco/family_NAME.c), the one list the dispatch, the names
 * and the parameter scopes are read from.
 */
#include "internal.h"

#define FAMILY_PTR(id, name) &qc__family_##name,
static const qc_family_desc *const families[] = {QC_FAMILY_MAP(FAMILY_PTR)};
#undef FAMILY_PTR

#define NFAMILIES (sizeof families / sizeof families[0])

const qc_family_desc *qc_family_info(size_t i)
{
    return i < NFAMILIES ? families[i] : NULL;
}

const qc_family_desc *qc__family(int id)
{
    return id >= 1 && (size_t)id <= NFAMILIES ? families[id - 1] : NULL;
}
