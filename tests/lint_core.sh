#!/bin/sh
# Proves from the object code that the core has no mutable globals (no
# .data/.bss/common symbols) and calls no I/O, clock, rand, exit or libm
# transcendental (their results differ across platforms; see src/core/qmath.c).
lib=${1:-build/libquiltc.a}
status=0
# objdump names each symbol's section: writable data is .data*, .bss*, COMMON;
# .data.rel.ro holds const tables of pointers (read-only after relocation).
# (AddressSanitizer's one-byte __odr_asan.* markers for extern constants, and
# clang's sanitizer descriptors __unnamed_N, are instrumentation, not state: C
# code cannot name a global __unnamed_N.)
globals=$(objdump -t "$lib" 2>/dev/null | grep -E ' O (\.data|\.bss|\*COM\*)' | grep -v -E ' O \.data\.rel\.ro' |
    grep -v -E ' (__odr_asan\.|__unnamed_[0-9]+$)')
if [ -n "$globals" ]; then
    echo "lint: mutable globals in the core:"
    echo "$globals"
    status=1
fi
banned='fopen|fclose|fread|fwrite|fprintf|printf|puts|putchar|fputs|fputc|fgets|getc|fgetc|scanf|fscanf|open|close|read|write|stat|time|clock|clock_gettime|gettimeofday|rand|srand|random|exit|_exit|abort|system|getenv|malloc|calloc|realloc|free|sin|cos|tan|atan|atan2|exp|log|pow|hypot|asin|acos|sinh|cosh|tanh|cbrt|expm1|log1p'
# malloc/realloc/free are allowed only in the default allocator's object.
calls=$(nm -A -u "$lib" 2>/dev/null | grep -v 'alloc_default.o:' | awk '{print $NF}' | sed 's/@.*//' | grep -E "^($banned)$" | sort -u)
if [ -n "$calls" ]; then
    echo "lint: the core calls forbidden functions:"
    nm -A -u "$lib" | grep -v 'alloc_default.o:' | grep -E " U ($banned)(@|$)"
    status=1
fi
[ $status -eq 0 ] && echo "lint: core clean ($(nm -A "$lib" | grep -c ' T ') functions, no mutable globals, no I/O, clock, rand, exit or libm transcendentals)"
exit $status
