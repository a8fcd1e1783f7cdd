# Speed: the scene generator and `make bench` (bench/), the check that the
# image does not depend on the number of threads, and the check that the
# plain C twin of the SSE2 code gives the same images.
ALL_TARGETS += $(BUILD)/gen_scene
CHECK_TARGETS += threadcheck portablecheck

.PHONY: bench threadcheck portablecheck

$(BUILD)/gen_scene: $(BUILD)/bench/gen.o
	$(CC) $(ALL_CFLAGS) -o $@ $^ -lm

# Not a test: it times whitted against POV-Ray and prints a table (see
# docs/benchmark.md).  bc and time are the only extra tools it needs.
bench: all
	@scripts/deps.sh bc time
	@bench/bench.sh

threadcheck: all
	@bench/threadcheck.sh

# whitted built again with ACCEL_PORTABLE, in a build directory of its own.
portablecheck: all
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/portable CFLAGS="$(CFLAGS) -DACCEL_PORTABLE" \
		$(BUILD)/portable/whitted >/dev/null
	@bench/portablecheck.sh $(BUILD)/whitted $(BUILD)/portable/whitted
