# make wasm: the unchanged core + wasm/quiltc_wasm.c as build/web/quiltc.mjs + .wasm, with the page.
# Debian's emscripten needs the system Node modules (acorn) on NODE_PATH.
# make serve: serves build/web on http://127.0.0.1:8000/ only (SERVE_PORT=...; any static server works).
# $(BUILD)/tests/qcw_native: the same bindings built natively (tests/wasm/identity.mjs).
WASM_DIR    = $(BUILD)/web
WASM_OBJDIR = $(BUILD)/wasm-obj
WASM_EMCC   = NODE_PATH=/usr/share/nodejs $(EMCC)
# -Os -flto: the page's first load has a 500 KB budget (page.test.mjs);
# -O3's module no longer fits it, nor -Os's once each unit is optimised
# alone (440 KB; across units 390 KB). The bytes it makes are the same
# (identity.mjs): neither changes a floating-point operation.
WASM_OPT    = -Os -flto
WASM_CFLAGS = $(WARN) $(WASM_OPT) -ffp-contract=off -DNDEBUG -Iinclude -Isrc/core -Iwasm
WASM_LDFLAGS = $(WASM_OPT) -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createQuiltc \
             -sENVIRONMENT=web,worker -sFILESYSTEM=0 -sALLOW_MEMORY_GROWTH=1 \
             -sASSERTIONS=0 -sEXPORTED_FUNCTIONS=@wasm/exports.txt \
             -sEXPORTED_RUNTIME_METHODS=UTF8ToString,stringToUTF8,lengthBytesUTF8,HEAPU8,HEAPU32,HEAPF64
WASM_BIND_SRC = wasm/quiltc_wasm.c wasm/quiltc_wasm_top.c wasm/qcw_text.c
WASM_OBJ    = $(patsubst %.c,$(WASM_OBJDIR)/%.o,$(LIB_SRC) $(WASM_BIND_SRC))
WASM_PAGE   = $(patsubst wasm/web/%,$(WASM_DIR)/%,$(wildcard wasm/web/*))

.PHONY: wasm serve
wasm: $(WASM_DIR)/quiltc.mjs $(WASM_PAGE)

$(WASM_OBJDIR)/%.o: %.c $(WASM_OBJDIR)/%.d
	@mkdir -p $(dir $@)
	$(WASM_EMCC) $(WASM_CFLAGS) $(DEPFLAGS) -c $< -o $@

$(WASM_DIR)/quiltc.mjs: $(WASM_OBJ) wasm/exports.txt
	@mkdir -p $(WASM_DIR)
	$(WASM_EMCC) $(WASM_LDFLAGS) $(WASM_OBJ) -o $@

$(WASM_DIR)/%: wasm/web/%
	@mkdir -p $(WASM_DIR)
	cp $< $@

$(BUILD)/tests/qcw_native: tests/wasm/qcw_native.c $(WASM_BIND_SRC) wasm/quiltc_wasm.h wasm/qcw_internal.h $(BUILD)/libquiltc.a
	@mkdir -p $(dir $@)
	$(CC) $(BASE_CFLAGS) $(LDFLAGS) -Iwasm -o $@ tests/wasm/qcw_native.c $(WASM_BIND_SRC) $(BUILD)/libquiltc.a $(LIBM)

SERVE_PORT ?= 8000
serve: wasm
	@echo "quiltc page: http://127.0.0.1:$(SERVE_PORT)/ (this machine only; Ctrl-C stops)"
	cd $(WASM_DIR) && python3 -m http.server --bind 127.0.0.1 $(SERVE_PORT)

DEP_FILES += $(WASM_OBJ:.o=.d)
