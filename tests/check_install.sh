#!/bin/sh
# make install into a staging DESTDIR; then a C program and a C++ one build
# against the installed headers and library through the generated quiltc.pc,
# and the installed quiltc and man page work.
. tests/cli_lib.sh
ROOT=$(pwd)
if [ "${BUILD:-build}" != build ]; then # the plain build covers it; sanitized objects need their runtime
    printf '\n-----------------------\n1 Tests 0 Failures 1 Ignored\nOK\n'
    exit 0
fi
STAGE="$WORK/stage"
PREFIX=/opt/quiltc
SONAME=$(make -s --no-print-directory -C "$ROOT" soname) # libquiltc.so.0.MINOR before 1.0, then .MAJOR

install_tree() {
    make -s -C "$ROOT" install DESTDIR="$STAGE" PREFIX=$PREFIX >/dev/null &&
        for f in bin/quiltc lib/libquiltc.a "lib/$SONAME" lib/libquiltc.so \
                 include/quiltc.h include/quiltc/pattern.h lib/pkgconfig/quiltc.pc \
                 share/man/man1/quiltc.1; do
            [ -e "$STAGE$PREFIX/$f" ] || { echo "missing $f"; return 1; }
        done
}
check install_honours_destdir_and_prefix install_tree

# The soname comes from QC_VERSION_* in core.h, and the installed names match it.
soname_from_version() {
    major=$(sed -n 's/^#define QC_VERSION_MAJOR \([0-9]*\)/\1/p' "$ROOT/include/quiltc/core.h")
    minor=$(sed -n 's/^#define QC_VERSION_MINOR \([0-9]*\)/\1/p' "$ROOT/include/quiltc/core.h")
    if [ "$major" = 0 ]; then want=libquiltc.so.0.$minor; else want=libquiltc.so.$major; fi
    [ "$SONAME" = "$want" ] || { echo "soname $SONAME, wanted $want"; return 1; }
    got=$(objdump -p "$ROOT/build/libquiltc.so" | awk '$1 == "SONAME" {print $2}')
    [ "$got" = "$want" ] || { echo "libquiltc.so has SONAME '$got', wanted $want"; return 1; }
    [ "$(readlink "$STAGE$PREFIX/lib/libquiltc.so")" = "$want" ]
}
check soname_follows_the_version soname_from_version

cat > "$WORK/use.c" <<'C'
#include <quiltc.h>
#include <stdio.h>
int main(void)
{
    qc_ctx ctx;
    qc_region r;
    qc_ctx_init(&ctx, NULL, NULL);
    if (qc_region_shape(&ctx, "circle:10", 1.0, &r) != QC_OK)
        return 1;
    printf("%s %.0f\n", qc_version(), qc_region_area(&r) > 78 ? 1.0 : 0.0);
    qc_region_free(&ctx, &r);
    return 0;
}
C
pc() { PKG_CONFIG_SYSROOT_DIR="$STAGE" PKG_CONFIG_PATH="$STAGE$PREFIX/lib/pkgconfig" pkg-config "$@" quiltc; }
c_program() {
    grep -q "prefix=$PREFIX" "$STAGE$PREFIX/lib/pkgconfig/quiltc.pc" &&
        cc -std=c99 -pedantic -Wall -Werror -o use use.c $(pc --cflags) $(pc --libs --static) &&
        LD_LIBRARY_PATH="$STAGE$PREFIX/lib" ./use | grep -q "^[0-9.]* 1$"
}
check c_program_links_through_pkg_config c_program

cxx_headers() {
    cp use.c use.cpp && g++ -std=c++11 -Wall -Wextra -Werror -pedantic -o usexx use.cpp \
        -I"$STAGE$PREFIX/include" "$STAGE$PREFIX/lib/libquiltc.a" -lm && ./usexx | grep -q ' 1$'
}
check headers_compile_and_link_as_cxx cxx_headers

installed_cli() {
    "$STAGE$PREFIX/bin/quiltc" --version | grep -q '^quiltc ' &&
        man -l "$STAGE$PREFIX/share/man/man1/quiltc.1" 2>/dev/null | grep -q 'quiltc generate' ||
        grep -q '^\.TH QUILTC 1' "$STAGE$PREFIX/share/man/man1/quiltc.1"
}
check installed_cli_and_man_page installed_cli

finish
