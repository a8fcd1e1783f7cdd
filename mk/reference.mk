# refcheck: whitted against an independent renderer of scene-format.md
# (tests/reference/ref_render.py, plain Python) on random scenes and cameras.
.PHONY: refcheck
CHECK_TARGETS += refcheck
OPTIONAL_PKGS += python3
REFCHECK_SEED ?= 2026
REFCHECK_COUNT ?= 24

refcheck: $(BUILD)/whitted
	@if command -v python3 >/dev/null 2>&1; then \
		python3 tests/reference/random_check.py $(BUILD)/whitted $(REFCHECK_COUNT) $(REFCHECK_SEED) 80; \
	else echo "refcheck: NOT RUN: python3 is not installed"; fi
