# Hostile input: the error-file and CLI tests, valgrind, the fuzz harness.
#   make faults       output faults: missing and read-only directories, a
#                     file-size limit, a full device, SIGINT and SIGTERM
#   make fuzz         builds the libFuzzer target with clang and runs it for
#                     FUZZ_SECONDS (default 600) on tests/fuzz/corpus and tests/errors
#   make fuzz-replay  runs every corpus and error file through the same harness, built
#                     with $(CC) and ASan/UBSan (part of make check)
FUZZ_SECONDS ?= 600
FUZZ_CC ?= clang
FUZZ_DIR := $(BUILD)/fuzz
FUZZ_FLAGS := -std=c99 -g -O1 -Iinclude $(PNG_CFLAGS) -pthread \
	-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -MMD -MP
FUZZ_OBJ := $(LIB_SRC:%.c=$(FUZZ_DIR)/%.o)

CHECK_TARGETS += faults fuzz-replay

.PHONY: fuzz fuzz-replay faults fuzz-cc-check
fuzz-cc-check:
	@command -v $(FUZZ_CC) >/dev/null || { echo "fuzz: $(FUZZ_CC) is missing (Debian: clang libclang-rt-14-dev)"; exit 1; }
faults: all
	@tests/cli/faults.sh

$(FUZZ_DIR)/%.o: %.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) -c $< -o $@

$(FUZZ_DIR)/fuzz_scene: tests/fuzz/fuzz_scene.c tests/fuzz/harness.c tests/fuzz/harness.h $(FUZZ_OBJ)
	$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer -Itests/fuzz -o $@ tests/fuzz/fuzz_scene.c \
		tests/fuzz/harness.c $(FUZZ_OBJ) $(LDLIBS)

# gcc's -fsanitize=undefined leaves out float-cast-overflow (clang's, which
# the fuzzer uses, has it), so the replay build adds it: its own objects.
REPLAY_SAN := $(SAN) -fsanitize=float-cast-overflow
REPLAY_OBJ := $(LIB_SRC:%.c=$(BUILD)/replay/%.o)
$(BUILD)/replay/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -O1 $(REPLAY_SAN) -c $< -o $@

$(BUILD)/replay/fuzz_replay: tests/fuzz/replay.c tests/fuzz/harness.c tests/fuzz/harness.h $(REPLAY_OBJ)
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -O1 $(REPLAY_SAN) -Itests/fuzz -o $@ tests/fuzz/replay.c tests/fuzz/harness.c \
		$(REPLAY_OBJ) $(LDLIBS)

fuzz: fuzz-cc-check $(FUZZ_DIR)/fuzz_scene
	@mkdir -p $(FUZZ_DIR)/corpus $(FUZZ_DIR)/artifacts
	$(FUZZ_DIR)/fuzz_scene -max_total_time=$(FUZZ_SECONDS) \
		-dict=tests/fuzz/scene.dict -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
		-artifact_prefix=$(FUZZ_DIR)/artifacts/ -print_final_stats=1 \
		$(FUZZ_DIR)/corpus tests/fuzz/corpus tests/errors

fuzz-replay: $(BUILD)/replay/fuzz_replay
	@$(BUILD)/replay/fuzz_replay tests/fuzz/corpus tests/errors
