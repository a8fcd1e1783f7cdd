# The unit tests: where they find ../shared (the real scene files of the
# course).  The repository is cloned with shared/ beside it, in CI as here;
# WHITTED_SHARED_DIR overrides this at run time.
UNIT_SHARED_DIR ?= $(abspath ../shared)
$(BUILD)/san/tests/%.o: ALL_CFLAGS += -DRT_TEST_SHARED_DIR='"$(UNIT_SHARED_DIR)"'
