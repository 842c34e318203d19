/* Retrace (measures-and-peers.md): the path resampled every 0.005 in; a
 * sample is retraced when an earlier sample more than 0.3 in back along the
 * path lies within 0.01 in; passes count the separate earlier visits. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "retrace.h"

#define STEP (0.005 * 25.4)
#define NEAR (0.01 * 25.4)
#define BACK (0.3 * 25.4)
#define MAXNB 8192

typedef struct sample {
    double x, y, s;
} sample;

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static size_t hash(long cx, long cy, size_t mask)
{
    unsigned long long h = (unsigned long long)cx * 0x9E3779B97F4A7C15ull ^
                           (unsigned long long)cy * 0xC2B2AE3D27D4EB4Full;
    return (size_t)(h >> 17) & mask;
}

int retrace_measure(const qc_vec2 *p, size_t n, const uint32_t *ends, size_t nends,
                    double *share, size_t *passes)
{
    sample *sm = NULL;
    size_t ns = 0, cap = 0, i, b = 0, q, hmask, *head = NULL, *next = NULL, most = 1;
    double s = 0.0, retraced = 0.0, *nb = malloc(MAXNB * sizeof *nb);

    for (q = 0; q < (ends ? nends : 1); q++) {
        size_t e = ends ? ends[q] : n;
        for (i = b; i < e; i++) {
            double len = i > b ? hypot(p[i].x - p[i - 1].x, p[i].y - p[i - 1].y) : 0.0;
            size_t m = i > b ? (size_t)ceil(len / STEP) : 1, k;
            for (k = i > b ? 1 : 0; k <= (i > b ? m : 0); k++) {
                double t = i > b ? (double)k / (double)m : 0.0;
                if (ns == cap) {
                    cap = cap ? 2 * cap : 1024;
                    sm = realloc(sm, cap * sizeof *sm);
                    if (sm == NULL)
                        return -1;
                }
                sm[ns].x = i > b ? p[i - 1].x + (p[i].x - p[i - 1].x) * t : p[i].x;
                sm[ns].y = i > b ? p[i - 1].y + (p[i].y - p[i - 1].y) * t : p[i].y;
                sm[ns].s = s + (i > b ? len * t : 0.0);
                ns++;
            }
            s += len;
        }
        s += 2 * BACK; /* a jump: the next piece is another pass */
        b = e;
    }
    for (hmask = 1; hmask < 2 * ns; hmask <<= 1)
        ;
    head = malloc(hmask * sizeof *head);
    next = malloc((ns ? ns : 1) * sizeof *next);
    if (head == NULL || next == NULL || nb == NULL) {
        free(sm), free(head), free(next), free(nb);
        return -1;
    }
    hmask--;
    memset(head, 0xff, (hmask + 1) * sizeof *head);
    for (i = 0; i < ns; i++) {
        long cx = (long)floor(sm[i].x / NEAR), cy = (long)floor(sm[i].y / NEAR), dx, dy;
        size_t cnt = 0, groups = 0, k, h;
        for (dx = -1; dx <= 1; dx++)
            for (dy = -1; dy <= 1; dy++)
                for (k = head[hash(cx + dx, cy + dy, hmask)]; k != (size_t)-1; k = next[k]) {
                    if (sm[i].s - sm[k].s <= BACK)
                        continue;
                    if (hypot(sm[i].x - sm[k].x, sm[i].y - sm[k].y) > NEAR)
                        continue;
                    if (cnt < MAXNB)
                        nb[cnt++] = sm[k].s;
                }
        if (cnt > 0) {
            retraced += STEP;
            qsort(nb, cnt, sizeof *nb, cmp_d);
            for (k = 0; k < cnt; k++)
                if (k == 0 || nb[k] - nb[k - 1] > BACK)
                    groups++;
            if (groups + 1 > most)
                most = groups + 1;
        }
        h = hash(cx, cy, hmask);
        next[i] = head[h];
        head[h] = i;
    }
    *share = ns > 1 ? fmin(1.0, retraced / (STEP * (double)(ns - 1))) : 0.0;
    *passes = most;
    free(sm), free(head), free(next), free(nb);
    return 0;
}
