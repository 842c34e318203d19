/* quiltc-bench: each stage's timings, briefly (the machine is shared).
 * With arguments, only the sections named (graph lattice tour pebbling
 * families tsplib ...), e.g. `build/bench/quiltc-bench lattice`. */
#include <string.h>

#include "bench.h"

static const struct {
    const char *name;
    void (*run)(void);
} sections[] = {{"graph", bench_graph},       {"lattice", bench_lattice},
                {"tour", bench_tour},         {"tsplib", bench_tsplib},
                {"pebbling", bench_pebbling},
                {"families", bench_families}, {"meander", bench_meander},
                {"families1m", bench_families_1m},
                {"quilt", bench_quilt}};

int main(int argc, char **argv)
{
    size_t k;
    int i;

    for (k = 0; k < sizeof sections / sizeof *sections; k++) {
        int want = argc < 2 && sections[k].run != bench_families_1m; /* opt-in */
        for (i = 1; i < argc; i++)
            want |= strcmp(argv[i], sections[k].name) == 0;
        if (want)
            sections[k].run();
    }
    return 0;
}
