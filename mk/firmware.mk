# make firmware: the core alone (no CLI, no USB, no default allocator) as a
# Cortex-M4 static library with arm-none-eabi-gcc and newlib; prints its size.
ARM_CC     ?= arm-none-eabi-gcc
ARM_CFLAGS ?= -Os -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -ffunction-sections -fdata-sections
ARM_BUILD  ?= build-arm
ARM_SRC    := $(filter-out src/core/alloc_default.c,$(LIB_SRC))

.PHONY: firmware
firmware:
	@mkdir -p $(ARM_BUILD)
	@set -e; objs=""; for s in $(ARM_SRC); do \
	    o=$(ARM_BUILD)/$$(echo $$s | tr / _ | sed 's/\.c$$/.o/'); \
	    $(ARM_CC) $(WARN) $(ARM_CFLAGS) -ffp-contract=off -DQC_NO_DEFAULT_ALLOC -Iinclude -Isrc/core -c $$s -o $$o; \
	    objs="$$objs $$o"; done; \
	rm -f $(ARM_BUILD)/libquiltc.a; arm-none-eabi-ar rcs $(ARM_BUILD)/libquiltc.a $$objs
	@arm-none-eabi-size -t $(ARM_BUILD)/libquiltc.a | tail -n 1 | \
	    awk '{printf "firmware: libquiltc.a for Cortex-M4: text %d B, data %d B, bss %d B\n", $$1, $$2, $$3}'
