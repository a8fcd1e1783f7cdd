# whitted-view, the OpenGL viewer (viewer/).  `make viewer` builds it; it is
# part of `make all` only when freeglut's pkg-config file is there, so the
# rest builds without GL.  Its pure modules (no GL) are unit-tested always.
# The end-to-end test runs whenever Xvfb (and freeglut) are installed and
# says NOT RUN otherwise; without xdotool or ImageMagick it fails, naming
# the missing tool.
VIEWER_SRC := $(wildcard viewer/*.c)
VIEWER_OBJ := $(VIEWER_SRC:%.c=$(BUILD)/%.o)
# The modules without GL, linked into their unit tests.
VIEWER_PURE := fly_camera mesh command
VIEWER_TEST_BIN := $(VIEWER_PURE:%=$(BUILD)/san/tests/viewer/test_%)
VIEWER_HAVE_GL := $(shell pkg-config --exists glut gl 2>/dev/null && echo yes)
VIEWER_GL_CFLAGS := $(shell pkg-config --cflags glut gl 2>/dev/null)
VIEWER_GL_LIBS := $(shell pkg-config --libs glut gl 2>/dev/null || echo -lglut -lGL)

OPTIONAL_PKGS += freeglut3-dev xvfb xauth xdotool imagemagick
TEST_BIN += $(VIEWER_TEST_BIN)
CHECK_TARGETS += viewer-e2e
INSTALL_PROGRAMS += $(if $(VIEWER_HAVE_GL),whitted-view)
ALL_TARGETS += $(if $(VIEWER_HAVE_GL),$(BUILD)/whitted-view)

.PHONY: viewer viewer-e2e
ifeq ($(VIEWER_HAVE_GL),yes)
viewer: $(BUILD)/whitted-view
else
viewer:
	@echo "viewer: freeglut3-dev is not installed (run 'make deps' as root)" >&2; exit 1
endif

$(BUILD)/viewer/%.o: ALL_CFLAGS += -Iviewer $(VIEWER_GL_CFLAGS)
$(BUILD)/san/viewer/%.o: ALL_CFLAGS += -Iviewer
$(BUILD)/san/tests/viewer/%.o: ALL_CFLAGS += -Iviewer -Itests

$(BUILD)/whitted-view: $(VIEWER_OBJ) $(BUILD)/libwhitted.a
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(VIEWER_GL_LIBS) $(LDLIBS)

$(BUILD)/san/tests/viewer/test_%: $(BUILD)/san/tests/viewer/test_%.o $(BUILD)/san/viewer/%.o \
		$(BUILD)/san/tests/support.o $(BUILD)/san/libwhitted.a
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(SAN) -o $@ $^ -lcmocka $(LDLIBS)

viewer-e2e:
	@if [ -z "$(VIEWER_HAVE_GL)" ]; then \
		echo "viewer-e2e: NOT RUN (freeglut3-dev is not installed)"; \
	elif ! command -v Xvfb >/dev/null 2>&1; then \
		echo "viewer-e2e: NOT RUN (Xvfb is not installed: apt-get install xvfb)"; \
	else \
		$(MAKE) --no-print-directory $(BUILD)/whitted $(BUILD)/whitted-view && \
		tests/viewer/e2e.sh $(BUILD)/whitted-view $(BUILD)/whitted; \
	fi
