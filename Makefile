# whitted: one Makefile, everything built under build/.
#   make            library, whitted, scene2pov
#   make render     the example scene to out/scene.png (installs what is missing)
#   make check      every test
#   make bench      the benchmark against POV-Ray (not a test)
#   make deps       install missing Debian packages (as root) or print the command
MAKEFLAGS += --no-builtin-rules
.SUFFIXES:

CC ?= cc
PREFIX ?= /usr/local
BUILD := build
CFLAGS ?= -O2 -g
WARN := -std=c99 -Wall -Wextra -Wpedantic -Wmissing-prototypes
PNG_CFLAGS := $(shell pkg-config --cflags libpng 2>/dev/null)
PNG_LIBS := $(shell pkg-config --libs libpng 2>/dev/null || echo -lpng)
ALL_CFLAGS := $(WARN) $(CFLAGS) -Iinclude $(PNG_CFLAGS) -pthread -MMD -MP
LDLIBS := $(PNG_LIBS) -lm -pthread
SAN := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all

CORE_PKGS := build-essential pkg-config libpng-dev libcmocka-dev
CHECK_PKGS := $(CORE_PKGS) valgrind
# Needed by some suites only; installed as root, otherwise those say NOT RUN.
OPTIONAL_PKGS :=

LIB_SRC := $(filter-out src/main.c,$(wildcard src/*.c)) $(wildcard src/shapes/*.c)
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/%.o)
SAN_OBJ := $(LIB_SRC:%.c=$(BUILD)/san/%.o)
TEST_SRC := $(wildcard tests/test_*.c) $(wildcard tests/shapes/test_*.c)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/san/tests/%)

# Each part of the project adds its own targets in mk/NAME.mk: programs to
# ALL_TARGETS, Debian packages to CHECK_PKGS (or OPTIONAL_PKGS when their
# tests can say NOT RUN without them), and the test targets that
# `make check` runs, in order, to CHECK_TARGETS.
ALL_TARGETS := $(BUILD)/libwhitted.a $(BUILD)/whitted
INSTALL_PROGRAMS := whitted
CHECK_TARGETS := unit clitest valgrind

.PHONY: all render check unit clitest valgrind deps check-deps install clean
all: build-all
-include mk/*.mk
.PHONY: build-all
build-all: $(ALL_TARGETS)

$(BUILD)/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(BUILD)/san/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -O1 $(SAN) -c $< -o $@

$(BUILD)/libwhitted.a: $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/san/libwhitted.a: $(SAN_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/whitted: $(BUILD)/src/main.o $(BUILD)/libwhitted.a
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/san/whitted: $(BUILD)/san/src/main.o $(BUILD)/san/libwhitted.a
	$(CC) $(ALL_CFLAGS) $(SAN) -o $@ $^ $(LDLIBS)

$(BUILD)/san/tests/%: $(BUILD)/san/tests/%.o $(BUILD)/san/tests/support.o $(BUILD)/san/libwhitted.a
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(SAN) -o $@ $^ -lcmocka $(LDLIBS)

deps check-deps:
	@scripts/deps.sh $(CHECK_PKGS)
	@scripts/deps.sh --optional $(OPTIONAL_PKGS)

render:
	@scripts/deps.sh $(CORE_PKGS)
	@$(MAKE) --no-print-directory all
	@mkdir -p out
	$(BUILD)/whitted -o out/scene.png scenes/scene.txt
	@echo "wrote out/scene.png"

unit: $(TEST_BIN)
	@tests/run-unit.sh $(TEST_BIN)

clitest: all
	@tests/cli/run.sh

valgrind: all
	@tests/valgrind.sh

check: check-deps
	@$(MAKE) --no-print-directory all $(TEST_BIN)
	@for t in $(CHECK_TARGETS); do $(MAKE) --no-print-directory $$t || exit 1; done

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib $(DESTDIR)$(PREFIX)/include/whitted
	for p in $(INSTALL_PROGRAMS); do install -m 755 $(BUILD)/$$p $(DESTDIR)$(PREFIX)/bin/$$p; done
	install -m 644 $(BUILD)/libwhitted.a $(DESTDIR)$(PREFIX)/lib/libwhitted.a
	cp -R include/. $(DESTDIR)$(PREFIX)/include/whitted/

clean:
	rm -rf $(BUILD) out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
