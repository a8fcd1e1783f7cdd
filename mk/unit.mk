# The unit tests: tests/shapes/ includes support.h from tests/, and the
# tests find ../shared (the real scene files of the course) beside the
# repository, in CI as here; WHITTED_SHARED_DIR overrides it at run time.
UNIT_SHARED_DIR ?= $(abspath ../shared)
$(BUILD)/san/tests/%.o: ALL_CFLAGS += -Itests -DRT_TEST_SHARED_DIR='"$(UNIT_SHARED_DIR)"'
