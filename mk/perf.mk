# Speed: the scene generator and `make bench` (bench/), and the check that
# the image does not depend on the number of threads.
ALL_TARGETS += $(BUILD)/gen_scene
CHECK_TARGETS += threadcheck

.PHONY: bench threadcheck

$(BUILD)/gen_scene: $(BUILD)/bench/gen.o
	$(CC) $(ALL_CFLAGS) -o $@ $^ -lm

# Not a test: it times whitted against POV-Ray and prints a table (see
# docs/benchmark.md).  bc and time are the only extra tools it needs.
bench: all
	@scripts/deps.sh bc time
	@bench/bench.sh

threadcheck: all
	@bench/threadcheck.sh
