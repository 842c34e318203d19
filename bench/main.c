/* quiltc-bench: each stage's timings, briefly (the machine is shared). */
#include "bench.h"

int main(void)
{
    bench_graph();
    bench_tour();
    bench_pebbling();
    bench_families();
    bench_meander();
    bench_quilt();
    return 0;
}
