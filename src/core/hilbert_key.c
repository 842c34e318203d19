/* Position along a Hilbert curve: the insertion order of the Delaunay stage
 * (16 bits per axis) and the point order of the tour stage (32 bits). */
#include "internal.h"

/* Branch-free rotations: the quadrant bits are random for scattered input. */
uint64_t qc__hilbert_key(uint32_t x, uint32_t y, unsigned bits)
{
    uint32_t s;
    uint64_t d = 0;

    for (s = (uint32_t)1 << (bits - 1); s > 0; s >>= 1) {
        uint32_t rx = (x & s) != 0, ry = (y & s) != 0;
        uint32_t swap = (uint32_t)0 - (ry ^ 1u), flip = swap & ((uint32_t)0 - rx);
        uint32_t t;

        d += (uint64_t)s * s * ((3u * rx) ^ ry);
        x ^= flip; /* only the bits below s matter from here on */
        y ^= flip;
        t = (x ^ y) & swap;
        x ^= t;
        y ^= t;
    }
    return d;
}
