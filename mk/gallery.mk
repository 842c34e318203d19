# make gallery: every line "NAME ARGS..." of gallery/*.txt becomes build/gallery/NAME.svg and .pat
gallery: $(BUILD)/quiltc
	@mkdir -p $(BUILD)/gallery
	@cat gallery/*.txt 2>/dev/null | grep -v '^#' | grep -v '^ *$$' | while read -r name args; do \
	    echo "gallery: $$name"; \
	    $(BUILD)/quiltc generate $$args -o $(BUILD)/gallery/$$name.svg || exit 1; \
	    $(BUILD)/quiltc generate $$args -o $(BUILD)/gallery/$$name.pat || exit 1; \
	done
