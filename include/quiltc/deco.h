/*
 * Decoration (paper §5, §7.1): the pattern families. Each family has its
 * own header; this one gathers them.
 */
#ifndef QUILTC_DECO_H
#define QUILTC_DECO_H

#include "core.h"

#endif
