/*
 * quiltc: free-motion quilting stitch paths for computer-controlled long-arm
 * machines. The umbrella header; each stage has its own under quiltc/.
 */
#ifndef QUILTC_H
#define QUILTC_H

#include "quiltc/core.h"
#include "quiltc/region.h"
#include "quiltc/sample.h"
#include "quiltc/graph.h"
#include "quiltc/tour.h"
#include "quiltc/curve.h"
#include "quiltc/motif.h"
#include "quiltc/deco.h"
#include "quiltc/stitch.h"
#include "quiltc/io.h"
#include "quiltc/pattern.h"
#include "quiltc/measure.h"
#include "quiltc/tile.h"
#include "quiltc/quilt.h"

#endif
