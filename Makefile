# quiltc: the core library (src/), the CLI (cli/), tests, benchmarks, wasm.
# GNU make. Overridable: CC, CFLAGS, LDFLAGS, PREFIX, DESTDIR, EMCC, USB,
# UNITY_DIR (a real Unity's src/; tests build in build-unity/), SAN=1
# (ASan+UBSan build in build-san/), WERROR=1. Objects carry -MMD -MP
# dependency files: touching a header rebuilds only what includes it.

CC      ?= cc
AR      ?= ar
CFLAGS  ?= -O2 -g
PREFIX  ?= /usr/local
DESTDIR ?=
USB     ?= 1
EMCC    ?= emcc

ifeq ($(SAN),1)
BUILD   ?= build-san
SANFLAGS = -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
else
ifdef UNITY_DIR
BUILD   ?= build-unity
else
BUILD   ?= build
endif
SANFLAGS =
endif

# The version, once, from the header: the soname follows it (semver: the
# major number, or 0.MINOR before 1.0, as qc_ctx_init's handshake does).
QC_VERSION_GET = $(shell sed -n 's/^\#define QC_VERSION_$(1) *\([0-9][0-9]*\).*/\1/p' include/quiltc/core.h)
QC_MAJOR := $(call QC_VERSION_GET,MAJOR)
QC_MINOR := $(call QC_VERSION_GET,MINOR)
QC_PATCH := $(call QC_VERSION_GET,PATCH)
ifeq ($(QC_MAJOR)$(QC_MINOR)$(QC_PATCH),)
$(error cannot read QC_VERSION_* from include/quiltc/core.h)
endif
ifeq ($(QC_MAJOR),0)
SO_ABI := 0.$(QC_MINOR)
else
SO_ABI := $(QC_MAJOR)
endif
SONAME := libquiltc.so.$(SO_ABI)
SO_FILE := libquiltc.so.$(QC_MAJOR).$(QC_MINOR).$(QC_PATCH)

WARN = -std=c99 -pedantic -Wall -Wextra -Wvla -Wshadow -Wstrict-prototypes \
       -Wmissing-prototypes -Wwrite-strings -Wdouble-promotion
ifeq ($(WERROR),1)
WARN += -Werror
endif

# -ffp-contract=off: no fused multiply-add, so native and WASM agree bit for bit.
BASE_CFLAGS = $(WARN) $(CFLAGS) $(SANFLAGS) -ffp-contract=off -Iinclude
DEPFLAGS    = -MMD -MP
LIB_CFLAGS  = $(BASE_CFLAGS) -fPIC -Isrc/core
LIBM        = -lm

LIB_SRC := $(sort $(wildcard src/*/*.c))
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)

# The CLI: libusb and cJSON live only here.
CLI_SRC := $(sort $(wildcard cli/*.c))
ifeq ($(USB),0)
CLI_SRC := $(filter-out cli/usb_%.c,$(CLI_SRC)) cli/usb_none.c
USB_CFLAGS =
USB_LIBS =
else
CLI_SRC := $(filter-out cli/usb_none.c,$(CLI_SRC))
USB_CFLAGS := $(shell pkg-config --cflags libusb-1.0 2>/dev/null)
USB_LIBS   := $(shell pkg-config --libs libusb-1.0 2>/dev/null || echo -lusb-1.0)
endif
CLI_SRC := $(sort $(CLI_SRC))
JSON_CFLAGS := $(shell pkg-config --cflags libcjson 2>/dev/null)
JSON_LIBS   := $(shell pkg-config --libs libcjson 2>/dev/null || echo -lcjson)
CLI_OBJ := $(CLI_SRC:%.c=$(BUILD)/obj/%.o)
CLI_CFLAGS = $(BASE_CFLAGS) -D_POSIX_C_SOURCE=200809L $(USB_CFLAGS) $(JSON_CFLAGS)
CLI_LIBS   = $(USB_LIBS) $(JSON_LIBS) $(LIBM)

# Tests: a real Unity when UNITY_DIR names its src/, else our compatible harness.
# unity.c and tests/support/ are compiled once into objects every test links.
ifdef UNITY_DIR
UNITY_SRC    = $(UNITY_DIR)/unity.c
UNITY_CFLAGS = -I$(UNITY_DIR) -DUNITY_INCLUDE_DOUBLE -DUNITY_SUPPORT_64
# vendored code: built as C99, not held to our warning set
UNITY_OBJ_CFLAGS = -std=c99 $(CFLAGS) $(SANFLAGS) $(UNITY_CFLAGS)
else
UNITY_SRC    = tests/unity/unity.c
UNITY_CFLAGS = -Itests/unity
UNITY_OBJ_CFLAGS = $(TEST_CFLAGS)
endif
UNITY_OBJ    := $(BUILD)/obj/unity/unity.o
TEST_SRC     := $(sort $(wildcard tests/test_*.c))
TEST_BIN     := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
TEST_SUPPORT := $(sort $(wildcard tests/support/*.c))
TEST_SUPPORT_OBJ := $(TEST_SUPPORT:%.c=$(BUILD)/obj/%.o)
TEST_CFLAGS   = $(BASE_CFLAGS) -Wno-missing-prototypes -D_POSIX_C_SOURCE=200809L \
                $(UNITY_CFLAGS) -Itests/support -Isrc/core
# A double handed to an integer assert is cut to an integer (Unity casts): warn.
TEST_SRC_CFLAGS = $(TEST_CFLAGS) -Wfloat-conversion

BENCH_SRC := $(sort $(wildcard bench/*.c))

.PHONY: all lib test check lint install uninstall clean bench wasm serve gallery fuzz
all: $(BUILD)/libquiltc.a $(BUILD)/libquiltc.so $(BUILD)/quiltc

lib: $(BUILD)/libquiltc.a

# Each object also depends on its .d file, so an object without one (an old
# build directory) is rebuilt once to get it; the .d files list the headers.
# They are named as targets (no recipe), so make neither fails on a missing
# one nor treats it as an intermediate file.
DEP_FILES = $(patsubst %.o,%.d,$(LIB_OBJ) $(CLI_OBJ) $(UNITY_OBJ) $(TEST_SUPPORT_OBJ) \
                               $(TEST_SRC:%.c=$(BUILD)/obj/%.o))

$(BUILD)/obj/src/%.o: src/%.c $(BUILD)/obj/src/%.d
	@mkdir -p $(dir $@)
	$(CC) $(LIB_CFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/cli/%.o: cli/%.c $(BUILD)/obj/cli/%.d
	@mkdir -p $(dir $@)
	$(CC) $(CLI_CFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/obj/tests/%.o: tests/%.c $(BUILD)/obj/tests/%.d
	@mkdir -p $(dir $@)
	$(CC) $(TEST_SRC_CFLAGS) -Itests/fuzz $(JSON_CFLAGS) $(DEPFLAGS) -c $< -o $@

# test objects are kept (not deleted as intermediate files) for the next run
.SECONDARY: $(TEST_SRC:%.c=$(BUILD)/obj/%.o)

$(UNITY_OBJ): $(UNITY_SRC) $(UNITY_OBJ:.o=.d)
	@mkdir -p $(dir $@)
	$(CC) $(UNITY_OBJ_CFLAGS) $(DEPFLAGS) -c $< -o $@

$(BUILD)/libquiltc.a: $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(AR) rcs $@ $(LIB_OBJ)

$(BUILD)/libquiltc.so: $(LIB_OBJ)
	$(CC) -shared $(SANFLAGS) $(LDFLAGS) -Wl,-soname,$(SONAME) -o $@ $(LIB_OBJ) $(LIBM)

$(BUILD)/quiltc: $(CLI_OBJ) $(BUILD)/libquiltc.a
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $(CLI_OBJ) $(BUILD)/libquiltc.a $(CLI_LIBS)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(UNITY_OBJ) $(TEST_SUPPORT_OBJ) $(BUILD)/libquiltc.a
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $< $(UNITY_OBJ) $(TEST_SUPPORT_OBJ) $(BUILD)/libquiltc.a $(LIBM)

# Every test binary and tests/check_*.sh script runs; the last line is "N passed, M failed".
test check: all $(TEST_BIN)
	@BUILD=$(BUILD) sh tests/run_tests.sh $(TEST_BIN)

# The core has no mutable globals and calls no I/O, clock, rand or exit.
lint: $(BUILD)/libquiltc.a
	@sh tests/lint_core.sh $(BUILD)/libquiltc.a

bench: $(BUILD)/libquiltc.a
	@mkdir -p $(BUILD)/bench
	$(CC) $(BASE_CFLAGS) -O2 -D_POSIX_C_SOURCE=200809L -Isrc/core $(LDFLAGS) -o $(BUILD)/bench/quiltc-bench $(BENCH_SRC) $(BUILD)/libquiltc.a $(LIBM)
	$(BUILD)/bench/quiltc-bench $(BENCH_ONLY)

quiltc.pc: quiltc.pc.in Makefile
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(shell sed -n 's/^#define QC_VERSION_STRING "\(.*\)"/\1/p' include/quiltc/core.h)|' $< > $@

install: all quiltc.pc
	install -d $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include/quiltc \
	           $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 644 $(BUILD)/libquiltc.a $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(BUILD)/libquiltc.so $(DESTDIR)$(PREFIX)/lib/$(SO_FILE)
	ln -sf $(SO_FILE) $(DESTDIR)$(PREFIX)/lib/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(PREFIX)/lib/libquiltc.so
	install -m 644 include/quiltc.h $(DESTDIR)$(PREFIX)/include/
	install -m 644 $(wildcard include/quiltc/*.h) $(DESTDIR)$(PREFIX)/include/quiltc/
	install -m 755 $(BUILD)/quiltc $(DESTDIR)$(PREFIX)/bin/
	install -m 644 quiltc.pc $(DESTDIR)$(PREFIX)/lib/pkgconfig/
	install -m 644 docs/quiltc.1 $(DESTDIR)$(PREFIX)/share/man/man1/

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/lib/libquiltc.a $(DESTDIR)$(PREFIX)/lib/libquiltc.so* \
	      $(DESTDIR)$(PREFIX)/bin/quiltc $(DESTDIR)$(PREFIX)/lib/pkgconfig/quiltc.pc \
	      $(DESTDIR)$(PREFIX)/share/man/man1/quiltc.1
	rm -rf $(DESTDIR)$(PREFIX)/include/quiltc $(DESTDIR)$(PREFIX)/include/quiltc.h

# Every build directory: build, build-san, build-unity, build-clang,
# build-arm, build-arm-lib, build-fuzz, and any other BUILD=build-*.
clean:
	rm -rf build build-* $(filter-out build build-%,$(BUILD)) quiltc.pc

# make soname: the soname the library is linked with (tests/check_install.sh).
.PHONY: soname
soname:
	@echo $(SONAME)

-include $(wildcard mk/*.mk)
$(DEP_FILES):
-include $(wildcard $(DEP_FILES))
