# make wasm: the unchanged core + wasm/quiltc_wasm.c as build/web/quiltc.mjs + .wasm, with the page.
# Debian's emscripten needs the system Node modules (acorn) on NODE_PATH.
WASM_DIR   = $(BUILD)/web
WASM_FLAGS = -O2 -std=c99 -ffp-contract=off -Iinclude -Isrc/core \
             -sMODULARIZE=1 -sEXPORT_ES6=1 -sEXPORT_NAME=createQuiltc -sENVIRONMENT=web,worker \
             -sFILESYSTEM=0 -sALLOW_MEMORY_GROWTH=1 -sASSERTIONS=0 \
             -sEXPORTED_FUNCTIONS=@wasm/exports.txt \
             -sEXPORTED_RUNTIME_METHODS=ccall,cwrap,UTF8ToString,stringToUTF8,lengthBytesUTF8,HEAPU8,HEAPU32,HEAPF64
WASM_SRC   = $(LIB_SRC) wasm/quiltc_wasm.c

.PHONY: wasm serve
wasm: $(WASM_DIR)/quiltc.mjs $(patsubst wasm/web/%,$(WASM_DIR)/%,$(wildcard wasm/web/*))

$(WASM_DIR)/quiltc.mjs: $(WASM_SRC) $(HEADERS) src/core/internal.h wasm/exports.txt
	@mkdir -p $(WASM_DIR)
	NODE_PATH=/usr/share/nodejs $(EMCC) $(WASM_FLAGS) $(WASM_SRC) -o $@

$(WASM_DIR)/%: wasm/web/%
	@mkdir -p $(WASM_DIR)
	cp $< $@

serve: wasm
	@echo "quiltc page: http://localhost:8000/"
	cd $(WASM_DIR) && python3 -m http.server 8000
