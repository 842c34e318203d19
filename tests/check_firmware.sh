#!/bin/sh
# The core as firmware links it (make firmware: Cortex-M4, newlib, no
# default allocator): it references nothing beyond libgcc, libm, string
# functions, qsort, strtod and vsnprintf; a program with a static arena
# (tests/firmware/fw_main.c) links against it; and the same program built for
# 32-bit Arm Thumb with newlib runs under qemu-arm and writes, for every
# family, the very bytes the native CLI writes. Ignored without
# arm-none-eabi-gcc (or qemu-arm for the last case) and in sanitizer builds.
. tests/cli_lib.sh
ROOT=$(pwd)
ARM_FLAGS="-mthumb -mfloat-abi=hard -ffunction-sections -fdata-sections -ffp-contract=off"
M4="-Os -mcpu=cortex-m4 -mfpu=fpv4-sp-d16 $ARM_FLAGS"
A7="-Os -march=armv7-a+fp $ARM_FLAGS" # a CPU qemu-arm runs; newlib semihosting by SVC

if [ "${BUILD:-build}" != build ] || ! command -v arm-none-eabi-gcc >/dev/null 2>&1; then
    printf '\n-----------------------\n1 Tests 0 Failures 1 Ignored\nOK\n'
    echo "arm-none-eabi-gcc missing or a sanitizer build: skipped"
    exit 0
fi
FAMILIES=$(./build/quiltc list families) # the library's list (qc_family_info)

# fw_lib CFLAGS LIBDIR: the core for CFLAGS into LIBDIR (once).
fw_lib() {
    [ -f "$2/libquiltc.a" ] || make -s -C "$ROOT" firmware ARM_BUILD="$2" ARM_CFLAGS="$1" >/dev/null
}

# fw_link CFLAGS LIBDIR OUT: fw_main linked against that core to OUT.
fw_link() {
    fw_lib "$1" "$2" &&
        arm-none-eabi-gcc $1 -std=c99 -Wall -Wextra -Werror -I"$ROOT/include" -o "$3" \
            "$ROOT/tests/firmware/fw_main.c" "$2/libquiltc.a" -lm -specs=rdimon.specs \
            -Wl,--gc-sections
}

no_os_symbols() {
    fw_lib "$M4" "$WORK/m4" || return 1
    extra=$(arm-none-eabi-nm -u "$WORK/m4/libquiltc.a" | awk 'NF == 2 {print $2}' | sort -u |
        grep -v -E '^(qc_|__aeabi_)' |
        grep -v -x -E 'ceil|floor|fmax|fmin|fmod|sqrt|mem(chr|cmp|cpy|move|set)|qsort' |
        grep -v -x -E 'str(chr|cmp|cspn|len|ncmp|ncpy|rchr|tod)|vsnprintf')
    [ -z "$extra" ] || { echo "the core references: $extra"; return 1; }
}
check core_references_no_os_heap_or_io no_os_symbols

m4_links() {
    fw_link "$M4" "$WORK/m4" "$WORK/fw-m4.elf" && arm-none-eabi-size "$WORK/fw-m4.elf" &&
        ! arm-none-eabi-nm "$WORK/fw-m4.elf" | grep -q ' qc_default_alloc$'
}
check cortex_m4_program_links_without_the_default_allocator m4_links

same_bytes_on_arm() {
    fw_link "$A7" "$WORK/a7" "$WORK/fw-a7.elf" || return 1
    for f in $FAMILIES; do
        qemu-arm "$WORK/fw-a7.elf" "$f" 10 7 >"$f-arm.pat" || { echo "$f: arm run failed"; return 1; }
        "$QC" generate --family "$f" --units mm --region rect:100x100 --spacing 10 --seed 7 \
            --tie 3 -o "$f.pat" || return 1
        cmp "$f.pat" "$f-arm.pat" || return 1
    done
}
if command -v qemu-arm >/dev/null 2>&1; then
    check arm_thumb_newlib_build_writes_the_native_bytes same_bytes_on_arm
    finish
else
    printf '\n-----------------------\n%d Tests %d Failures 1 Ignored\n' $((T_RUN + 1)) "$T_FAIL"
    echo "qemu-arm is missing: the run on Arm was skipped"
    [ "$T_FAIL" -eq 0 ] && echo OK || echo FAIL
fi
