# make fuzz [FUZZ_SECONDS=60] [FUZZ_TARGETS="svg_region pat"]: builds the
# libFuzzer targets (tests/fuzz/fuzz_*.c) with clang, ASan and UBSan into
# build-fuzz/ and runs each for FUZZ_SECONDS on a copy of its seed corpus
# (tests/fuzz/corpus/<target>/) plus its regression inputs
# (tests/fuzz/regress/<target>/). A crash, leak, timeout or broken invariant
# fails the run and leaves the input in build-fuzz/artifacts/<target>/.
#
# `make test` also builds each target with a plain main
# (tests/fuzz/replay_main.c) into $(BUILD)/fuzz-replay/, and
# tests/check_fuzz_regress.sh replays every corpus and regression file.
FUZZ_CC      ?= clang
FUZZ_BUILD   ?= build-fuzz
FUZZ_SECONDS ?= 60
FUZZ_TARGETS ?= svg_region motif pat points generate job read
FUZZ_ALL     := svg_region motif pat points generate job read

FUZZ_SAN      = -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS   = -g -O1 $(WARN) -ffp-contract=off -Iinclude -Isrc/core $(FUZZ_SAN)
FUZZ_T_CFLAGS = $(FUZZ_CFLAGS) -Wno-missing-prototypes -D_POSIX_C_SOURCE=200809L \
                -Itests/support -Itests/fuzz $(JSON_CFLAGS)
FUZZ_LIB_OBJ := $(LIB_SRC:%.c=$(FUZZ_BUILD)/obj/%.o)
FUZZ_BINS    := $(FUZZ_ALL:%=$(FUZZ_BUILD)/fuzz_%)
FUZZ_DEPS     = tests/fuzz/fuzz_common.h tests/support/testalloc.c tests/support/testalloc.h
# the job target links the job reader and the CLI helpers it uses
FUZZ_JOB_CLI := cli/job_parse.c cli/json_fields.c cli/job_budget.c cli/json_strict.c cli/util.c cli/escape.c cli/pattern_opts.c cli/ignored_opts.c cli/region_load.c cli/motifs_load.c

$(FUZZ_BUILD)/obj/src/%.o: src/%.c $(FUZZ_BUILD)/obj/src/%.d
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(DEPFLAGS) -fsanitize=fuzzer-no-link -c $< -o $@

$(FUZZ_BUILD)/libquiltc.a: $(FUZZ_LIB_OBJ)
	rm -f $@
	$(AR) rcs $@ $(FUZZ_LIB_OBJ)

$(FUZZ_BUILD)/fuzz_job: tests/fuzz/fuzz_job.c $(FUZZ_JOB_CLI) cli/cli.h cli/job.h $(FUZZ_DEPS) $(FUZZ_BUILD)/libquiltc.a
	$(FUZZ_CC) $(FUZZ_T_CFLAGS) -fsanitize=fuzzer -o $@ $< $(FUZZ_JOB_CLI) \
	    tests/support/testalloc.c $(FUZZ_BUILD)/libquiltc.a $(JSON_LIBS) $(LIBM)

$(FUZZ_BUILD)/fuzz_%: tests/fuzz/fuzz_%.c $(FUZZ_DEPS) $(FUZZ_BUILD)/libquiltc.a
	$(FUZZ_CC) $(FUZZ_T_CFLAGS) -fsanitize=fuzzer -o $@ $< tests/support/testalloc.c \
	    $(FUZZ_BUILD)/libquiltc.a $(LIBM)

.PHONY: fuzz fuzz-build
fuzz-build: $(FUZZ_BINS)

fuzz: fuzz-build
	@FUZZ_BUILD=$(FUZZ_BUILD) sh tests/fuzz/run_fuzz.sh $(FUZZ_SECONDS) $(FUZZ_TARGETS)

# The replay drivers: the same targets with a plain main, built like the tests
# (objects from the tests' rule, the job reader from the CLI's objects).
REPLAY_BINS := $(FUZZ_ALL:%=$(BUILD)/fuzz-replay/fuzz_%)
REPLAY_OBJ  := $(BUILD)/obj/tests/fuzz/replay_main.o $(BUILD)/obj/tests/support/testalloc.o
REPLAY_JOB_CLI_OBJ := $(FUZZ_JOB_CLI:%.c=$(BUILD)/obj/%.o)

.SECONDARY: $(FUZZ_ALL:%=$(BUILD)/obj/tests/fuzz/fuzz_%.o)

$(BUILD)/fuzz-replay/fuzz_job: $(BUILD)/obj/tests/fuzz/fuzz_job.o $(REPLAY_OBJ) $(REPLAY_JOB_CLI_OBJ) $(BUILD)/libquiltc.a
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $^ $(JSON_LIBS) $(LIBM)

$(BUILD)/fuzz-replay/fuzz_%: $(BUILD)/obj/tests/fuzz/fuzz_%.o $(REPLAY_OBJ) $(BUILD)/libquiltc.a
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) $(LDFLAGS) -o $@ $^ $(LIBM)

test check: $(REPLAY_BINS)

# fuzz_generate spends its time in the pipeline's arithmetic loops, where
# comparison tracing buys little: its library copy is built without it.
FUZZ_GEN_OBJ := $(LIB_SRC:%.c=$(FUZZ_BUILD)/objg/%.o)

$(FUZZ_BUILD)/objg/src/%.o: src/%.c $(FUZZ_BUILD)/objg/src/%.d
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) $(DEPFLAGS) -fsanitize=fuzzer-no-link -fno-sanitize-coverage=trace-cmp -c $< -o $@

$(FUZZ_BUILD)/libquiltc-gen.a: $(FUZZ_GEN_OBJ)
	rm -f $@
	$(AR) rcs $@ $(FUZZ_GEN_OBJ)

$(FUZZ_BUILD)/fuzz_generate: tests/fuzz/fuzz_generate.c $(FUZZ_DEPS) $(FUZZ_BUILD)/libquiltc-gen.a
	$(FUZZ_CC) $(FUZZ_T_CFLAGS) -fsanitize=fuzzer -o $@ $< tests/support/testalloc.c \
	    $(FUZZ_BUILD)/libquiltc-gen.a $(LIBM)

DEP_FILES += $(FUZZ_ALL:%=$(BUILD)/obj/tests/fuzz/fuzz_%.d) $(BUILD)/obj/tests/fuzz/replay_main.d \
             $(FUZZ_LIB_OBJ:.o=.d) $(FUZZ_GEN_OBJ:.o=.d) $(FUZZ_JOB_CLI:%.c=$(BUILD)/obj/%.d)
