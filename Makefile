# quiltc: the core library (src/), the CLI (cli/), tests, benchmarks, wasm.
# GNU make. Overridable: CC, CFLAGS, LDFLAGS, PREFIX, DESTDIR, EMCC, USB,
# UNITY_DIR (a real Unity's src/), SAN=1 (ASan+UBSan build in build-san/),
# WERROR=1.

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
BUILD   ?= build
SANFLAGS =
endif

WARN = -std=c99 -pedantic -Wall -Wextra -Wvla -Wshadow -Wstrict-prototypes \
       -Wmissing-prototypes -Wwrite-strings -Wdouble-promotion
ifeq ($(WERROR),1)
WARN += -Werror
endif

# -ffp-contract=off: no fused multiply-add, so native and WASM agree bit for bit.
BASE_CFLAGS = $(WARN) $(CFLAGS) $(SANFLAGS) -ffp-contract=off -Iinclude
LIB_CFLAGS  = $(BASE_CFLAGS) -fPIC -Isrc/core
LIBM        = -lm

LIB_SRC := $(sort $(wildcard src/*/*.c))
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
HEADERS := include/quiltc.h $(sort $(wildcard include/quiltc/*.h))

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
ifdef UNITY_DIR
UNITY_SRC    = $(UNITY_DIR)/unity.c
UNITY_CFLAGS = -I$(UNITY_DIR) -DUNITY_INCLUDE_DOUBLE -DUNITY_SUPPORT_64
else
UNITY_SRC    = tests/unity/unity.c
UNITY_CFLAGS = -Itests/unity
endif
TEST_SRC     := $(sort $(wildcard tests/test_*.c))
TEST_BIN     := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
TEST_SUPPORT := $(sort $(wildcard tests/support/*.c))
TEST_CFLAGS   = $(BASE_CFLAGS) -Wno-missing-prototypes -D_POSIX_C_SOURCE=200809L \
                $(UNITY_CFLAGS) -Itests/support -Isrc/core

BENCH_SRC := $(sort $(wildcard bench/*.c))

.PHONY: all lib test check lint install uninstall clean bench wasm serve gallery fuzz
all: $(BUILD)/libquiltc.a $(BUILD)/libquiltc.so $(BUILD)/quiltc

lib: $(BUILD)/libquiltc.a

$(BUILD)/obj/src/%.o: src/%.c $(HEADERS) $(wildcard src/*/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(LIB_CFLAGS) -c $< -o $@

$(BUILD)/obj/cli/%.o: cli/%.c $(HEADERS) $(wildcard cli/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(CLI_CFLAGS) -c $< -o $@

$(BUILD)/libquiltc.a: $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	$(AR) rcs $@ $(LIB_OBJ)

$(BUILD)/libquiltc.so: $(LIB_OBJ)
	$(CC) -shared $(SANFLAGS) -Wl,-soname,libquiltc.so.0 -o $@ $(LIB_OBJ) $(LIBM)

$(BUILD)/quiltc: $(CLI_OBJ) $(BUILD)/libquiltc.a
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $(CLI_OBJ) $(BUILD)/libquiltc.a $(CLI_LIBS)

$(BUILD)/tests/%: tests/%.c $(UNITY_SRC) $(TEST_SUPPORT) $(BUILD)/libquiltc.a $(wildcard tests/support/*.h)
	@mkdir -p $(dir $@)
	$(CC) $(TEST_CFLAGS) -o $@ $< $(UNITY_SRC) $(TEST_SUPPORT) $(BUILD)/libquiltc.a $(LIBM)

# Every test binary and tests/check_*.sh script runs; the last line is "N passed, M failed".
test check: all $(TEST_BIN)
	@BUILD=$(BUILD) sh tests/run_tests.sh $(TEST_BIN)

# The core has no mutable globals and calls no I/O, clock, rand or exit.
lint: $(BUILD)/libquiltc.a
	@sh tests/lint_core.sh $(BUILD)/libquiltc.a

bench: $(BUILD)/libquiltc.a
	@mkdir -p $(BUILD)/bench
	$(CC) $(BASE_CFLAGS) -O2 -D_POSIX_C_SOURCE=200809L -Isrc/core -o $(BUILD)/bench/quiltc-bench $(BENCH_SRC) $(BUILD)/libquiltc.a $(LIBM)
	$(BUILD)/bench/quiltc-bench $(BENCH_ONLY)

quiltc.pc: quiltc.pc.in Makefile
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(shell sed -n 's/^#define QC_VERSION_STRING "\(.*\)"/\1/p' include/quiltc/core.h)|' $< > $@

install: all quiltc.pc
	install -d $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include/quiltc \
	           $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 644 $(BUILD)/libquiltc.a $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(BUILD)/libquiltc.so $(DESTDIR)$(PREFIX)/lib/libquiltc.so.0
	ln -sf libquiltc.so.0 $(DESTDIR)$(PREFIX)/lib/libquiltc.so
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

clean:
	rm -rf build build-san build-fuzz build-arm quiltc.pc

-include $(wildcard mk/*.mk)
