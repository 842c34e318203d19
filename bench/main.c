/* quiltc-bench: each stage's timings, briefly (the machine is shared). */
#include "bench.h"

int main(void)
{
    bench_graph();
    bench_tour();
    return 0;
}
