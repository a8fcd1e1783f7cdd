# whitted: one Makefile; everything it makes goes under build/.
#   make            the library, whitted, scene2pov, whitted-view (with freeglut), tools
#   make plugins    the example plugins of plugins/ as build/plugins/*.so
#   make render     the example scene to out/scene.png (installs what is missing as root)
#   make check      every test suite, in the order of SUITES below
#   make bench      the benchmark against POV-Ray (not a test)
#   make deps       installs the missing Debian packages (as root) or prints the command;
#                   it also offers the benchmark's (Embree: optional)
#   make install    PREFIX=/usr/local: the programs, libwhitted.a, include/whitted/,
#                   whitted.pc (pkg-config), the man pages and lib/whitted/plugins/
#
# The library is compiled in three ways, each for one purpose:
#   build/           -O2: the programs and the library that is installed
#   build/san/       ASan + UBSan (with float-cast-overflow) and the tests' allocation
#                    failure switch: unit tests and fuzz-replay
#   build/portable/  -DACCEL_PORTABLE, the plain C twin of the SSE2 code: portablecheck
# and a fourth, build/fuzz/ (clang, libFuzzer), only for `make fuzz`.
MAKEFLAGS += --no-builtin-rules
.SUFFIXES:
.DELETE_ON_ERROR:
# `make` alone builds `all`, whichever rule comes first below.
.DEFAULT_GOAL := all

CC ?= cc
PREFIX ?= /usr/local
BUILD := build
CFLAGS ?= -O2 -g
WARN := -std=c99 -Wall -Wextra -Wpedantic -Wmissing-prototypes
# No contraction of a * b + c into one fused instruction, in any file: it
# rounds once where the source rounds twice, so a compiler that contracts
# by default (clang, or gcc outside ISO mode) with FMA in its target would
# make the packet paths' images differ from the single rays' by a bit.
FP := -ffp-contract=off
PNG_CFLAGS := $(shell pkg-config --cflags libpng 2>/dev/null)
PNG_LIBS := $(shell pkg-config --libs libpng 2>/dev/null || echo -lpng)
# The PNG's deflate: Intel's ISA-L where a program using it compiles and
# links with these flags (Debian's libisal-dev, which `make render` and
# `make deps` install where Debian has it), four times as fast as zlib's
# level 1; zlib otherwise (src/image/png_deflate.h).
HAVE_ISAL := $(shell t=$$(mktemp) && printf '\043include <isa-l/igzip_lib.h>\nint main(void) { struct isal_zstream z; isal_deflate_stateless_init(&z); return 0; }\n' | \
	$(CC) $(CFLAGS) -x c - -o $$t -lisal >/dev/null 2>&1 && echo yes; rm -f $$t)
DEFLATE_CFLAGS := $(if $(HAVE_ISAL),-DRT_HAVE_ISAL)
DEFLATE_LIBS := $(if $(HAVE_ISAL),-lisal)
# grade's zip files of submissions: libzip where pkg-config finds it
# (Debian's libzip-dev, offered like ISA-L); without it grade says that
# this build reads no zip files.
HAVE_ZIP := $(shell pkg-config --exists libzip 2>/dev/null && echo yes)
ZIP_CFLAGS := $(if $(HAVE_ZIP),-DRT_HAVE_LIBZIP $(shell pkg-config --cflags libzip))
ZIP_LIBS := $(if $(HAVE_ZIP),$(shell pkg-config --libs libzip))
ALL_CFLAGS := $(WARN) $(FP) $(CFLAGS) -Iinclude -Isrc $(PNG_CFLAGS) $(DEFLATE_CFLAGS) -pthread -MMD -MP
LDLIBS := $(PNG_LIBS) $(DEFLATE_LIBS) -lz -lm -pthread
# The sanitized build is the test build: it also has the allocator's
# failure switch (RT_TEST_HOOKS), which the installed library leaves out.
SAN := -fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer \
	-fno-sanitize-recover=all -DRT_TEST_HOOKS
VERSION := $(shell sed -n 's/^\#define RT_VERSION "\(.*\)"/\1/p' include/whitted/version.h)

# Debian packages: the build's, the suites' (make check installs them as
# root), and the benchmark's.  scripts/deps.sh looks for what each provides
# first (pkg-config, a header, a command), so that a system that has the
# libraries, Debian or not, needs none of them installed; cmocka is the
# tests' alone.
CORE_PKGS := build-essential pkg-config libpng-dev zlib1g-dev libstb-dev
# Offered to every build, not required: the faster PNG deflate (zlib is
# the fallback where Debian has no ISA-L for the architecture).
FAST_PKGS := libisal-dev libzip-dev
# The cross builds' (make windows: MinGW-w64, and wine for its suite;
# dpkg-dev unpacks Debian's zlib and libpng sources, scripts/third-party.sh).
WIN_PKGS := mingw-w64 wine wine64 dpkg-dev
# make web's (emscripten, whose optimiser needs node-acorn) and its
# browser suite's (node and npm for playwright-core, and chromium).
WEB_PKGS := emscripten node-acorn nodejs npm dpkg-dev
CHECK_PKGS := $(CORE_PKGS) libzip-dev libcmocka-dev valgrind python3 povray povray-includes \
	parallel openssh-client openssh-server rsync \
	freeglut3-dev xvfb xauth xdotool imagemagick man-db chromium fonts-liberation \
	$(WIN_PKGS) $(WEB_PKGS)
BENCH_PKGS := bc
# Offered, not required: the benchmark's Embree column (make deps installs it).
BENCH_OPT_PKGS := libembree-dev

# ---- the library ----------------------------------------------------------
LIB_MODULES := base syntax export shapes plugin accel scene render scenefile image dist grade
# The platform layer (src/base/platform.h): one file a system; the
# Windows cross build (make windows) takes the other.
PLATFORM_SRC ?= src/base/platform_posix.c
# The vector kernels: one source a module, written over base/lanes.h and
# compiled once per set of instructions this build has (SIMD_SETS), each
# object with its -m flags and -DRT_SIMD_KERNEL=SET (src/base/simd.h).  On
# x86-64 the baseline (SSE2), AVX2 and AVX-512; elsewhere the baseline.
# Not on 32-bit x86, whose baseline does its doubles in the x87 unit:
# vector code beside it would round differently, so there every path is
# the plain C one.
KERNEL_SRC := src/accel/accel_kernels.c src/render/render_kernels.c src/shapes/solve_kernels.c
SIMD_SETS := base
ifneq ($(filter x86_64% amd64%,$(shell $(CC) -dumpmachine)),)
SIMD_SETS := base avx2 avx512
ALL_CFLAGS += -DRT_SIMD_X86_KERNELS
endif
SIMD_FLAGS_avx2 := -mavx2
SIMD_FLAGS_avx512 := -mavx512f
KERNEL_OBJ = $(foreach s,$(SIMD_SETS),$(KERNEL_SRC:%.c=$(1)/%_$(s).o))
LIB_SRC := $(filter-out src/base/platform_%.c $(KERNEL_SRC),$(foreach m,$(LIB_MODULES),$(wildcard src/$(m)/*.c))) \
	$(PLATFORM_SRC)
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/%.o) $(call KERNEL_OBJ,$(BUILD))
SAN_OBJ := $(LIB_SRC:%.c=$(BUILD)/san/%.o) $(call KERNEL_OBJ,$(BUILD)/san)

# ---- the programs ---------------------------------------------------------
# src/cli/tool.c, scene_opts.c and the rest of TOOLS_SRC are shared by the three programs: the
# option parsing and the printing that the library never does.
TOOLS_SRC := src/cli/tool.c src/cli/scene_opts.c src/cli/scene_operands.c src/cli/scene_jobs.c src/cli/plugin_opts.c src/cli/suggest.c
WHITTED_SRC := $(filter-out $(TOOLS_SRC),$(wildcard src/cli/*.c))
POV_SRC := $(wildcard pov_export/*.c)
VIEWER_SRC := $(wildcard viewer/*.c)
VIEWER_PURE := fly_camera command
VIEWER_HAVE_GL := $(shell pkg-config --exists glut gl 2>/dev/null && echo yes)
VIEWER_GL_CFLAGS := $(shell pkg-config --cflags glut gl 2>/dev/null)
VIEWER_GL_LIBS := $(shell pkg-config --libs glut gl 2>/dev/null || echo -lglut -lGL)

PROGRAMS := whitted scene2pov $(if $(VIEWER_HAVE_GL),whitted-view)
TOOLS := gen_scene imgcmp imgfilter walltime

# ---- the example plugins (whitted/plugin.h) --------------------------------
# One C file each under plugins/, built as the tutorial of docs/plugins.md
# builds one: against the installed headers only, -fPIC -shared.
PLUGIN_SRC := $(wildcard plugins/*.c)
PLUGINS := $(PLUGIN_SRC:plugins/%.c=$(BUILD)/plugins/%.so)
$(BUILD)/plugins/%.so: plugins/%.c $(wildcard include/whitted/*.h)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(FP) $(CFLAGS) -Iinclude -fPIC -shared -o $@ $< -lm
plugins: $(PLUGINS)

# ---- the tests ------------------------------------------------------------
UNIT_SRC := $(wildcard tests/unit/*/test_*.c)
UNIT_BIN := $(UNIT_SRC:tests/%.c=$(BUILD)/san/tests/%)
UNIT_DATA_DIR ?= $(abspath tests/data)

# The suites of `make check`, in this order: the fast and local first (the
# library's units, then the programs end to end, then hostile input), the
# slow cross-validations last.  README's "Tests" lists the same.
SUITES := layout unit clitest dialects manpages valgrind disttest faults fuzz-replay threadcheck features \
	portablecheck wintest imgcmptest povcheck refcheck mistakecheck comparetest explaintest reportcheck webtest viewer-e2e \
	install-test newshape newisa plugintest embreecheck

.PHONY: web webtest windows wintest all render check deps check-deps install clean bench fuzz fuzz-images fuzz-plugins plugins FORCE \
	$(SUITES)
all: $(BUILD)/libwhitted.a $(PROGRAMS:%=$(BUILD)/%) $(TOOLS:%=$(BUILD)/%)

$(BUILD)/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -c $< -o $@

$(BUILD)/san/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -O1 $(SAN) -c $< -o $@
# A kernel source's object for each set (KERNEL_SRC).
define SIMD_KERNEL_RULES
$(BUILD)/%_$(1).o: %.c
	@mkdir -p $$(@D)
	$$(CC) $$(ALL_CFLAGS) $$(SIMD_FLAGS_$(1)) -DRT_SIMD_KERNEL=$(1) -DRT_SIMD_KERNEL_$(1) -c $$< -o $$@
$(BUILD)/san/%_$(1).o: %.c
	@mkdir -p $$(@D)
	$$(CC) $$(ALL_CFLAGS) $$(SIMD_FLAGS_$(1)) -DRT_SIMD_KERNEL=$(1) -DRT_SIMD_KERNEL_$(1) -O1 $$(SAN) -c $$< -o $$@
endef
$(foreach s,$(SIMD_SETS),$(eval $(call SIMD_KERNEL_RULES,$(s))))

# The AVX-512 walk's float box tests widen their answers with fused
# multiply-adds (every processor with AVX-512 has them; base/simd.c asks);
# everywhere else -ffp-contract=off keeps a * b + c two roundings.
%/accel/accel_kernels_avx512.o: ALL_CFLAGS += -mfma

# What RT_HAVE_ISAL decides is compiled anew when the library the build
# found changes (libisal-dev installed or removed since the last build).
DEFLATE_OBJ := $(foreach d,$(BUILD) $(BUILD)/san $(BUILD)/fuzz,\
	$(d)/src/image/png_deflate_isal.o $(d)/src/image/png_deflate.o) \
	$(BUILD)/san/tests/unit/image/test_png_deflate.o
$(DEFLATE_OBJ): $(BUILD)/deflate.flags
$(BUILD)/deflate.flags: FORCE
	@mkdir -p $(@D)
	@echo '$(DEFLATE_CFLAGS)' | cmp -s - $@ || echo '$(DEFLATE_CFLAGS)' > $@
FORCE:

$(BUILD)/libwhitted.a: $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/san/libwhitted.a: $(SAN_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/libwhitted-tools.a: $(TOOLS_SRC:%.c=$(BUILD)/%.o)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/san/libwhitted-tools.a: $(TOOLS_SRC:%.c=$(BUILD)/san/%.o)
	@rm -f $@
	ar rcs $@ $^

$(BUILD)/src/cli/grade_zip.o $(BUILD)/san/src/cli/grade_zip.o: ALL_CFLAGS += $(ZIP_CFLAGS)
$(BUILD)/whitted: $(WHITTED_SRC:%.c=$(BUILD)/%.o) $(BUILD)/libwhitted-tools.a $(BUILD)/libwhitted.a
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(ZIP_LIBS) $(LDLIBS)
# whitted sanitized, for the suites' runs of the paths that unit tests do
# not reach (compare's camera refit).
$(BUILD)/san/whitted: $(WHITTED_SRC:%.c=$(BUILD)/san/%.o) $(BUILD)/san/libwhitted-tools.a \
	$(BUILD)/san/libwhitted.a
	$(CC) $(ALL_CFLAGS) $(SAN) -o $@ $^ $(ZIP_LIBS) $(LDLIBS)

$(BUILD)/pov_export/%.o: ALL_CFLAGS += -Ipov_export
$(BUILD)/scene2pov: $(POV_SRC:%.c=$(BUILD)/%.o) $(BUILD)/libwhitted-tools.a $(BUILD)/libwhitted.a
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/viewer/%.o: ALL_CFLAGS += -Iviewer $(VIEWER_GL_CFLAGS)
$(BUILD)/whitted-view: $(VIEWER_SRC:%.c=$(BUILD)/%.o) $(BUILD)/libwhitted-tools.a $(BUILD)/libwhitted.a
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(VIEWER_GL_LIBS) $(LDLIBS)

# The benchmark's Embree reference (bench/embree_accel.c): whitted with
# Embree 3 linked in place of src/accel/, and the builds of both timed on
# the same primitives (bench/embree_build.c); only where libembree-dev is.
EMBREE_LIB_OBJ := $(filter-out $(BUILD)/src/accel/%,$(LIB_OBJ)) $(BUILD)/bench/embree_accel.o
$(BUILD)/whitted-embree: $(WHITTED_SRC:%.c=$(BUILD)/%.o) $(BUILD)/libwhitted-tools.a $(EMBREE_LIB_OBJ)
	$(CC) $(ALL_CFLAGS) -o $@ $^ -lembree3 $(ZIP_LIBS) $(LDLIBS)
$(BUILD)/embree_build: $(BUILD)/bench/embree_build.o $(BUILD)/libwhitted.a
	$(CC) $(ALL_CFLAGS) -o $@ $^ -lembree3 $(LDLIBS)

$(BUILD)/gen_scene: $(BUILD)/bench/gen.o
	$(CC) $(ALL_CFLAGS) -o $@ $^ -lm

$(BUILD)/walltime: $(BUILD)/bench/walltime.o
	$(CC) $(ALL_CFLAGS) -o $@ $^

$(BUILD)/imgcmp $(BUILD)/imgfilter: $(BUILD)/%: $(BUILD)/tests/tools/%.o $(BUILD)/tests/tools/imgio.o
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDLIBS)

# Unit tests: one program per test file, the sanitized library, and the
# viewer's GL-free modules for the viewer's tests.
$(BUILD)/san/tests/%.o: ALL_CFLAGS += -Itests/unit -Iviewer \
	-DRT_TEST_DATA_DIR='"$(UNIT_DATA_DIR)"' -DRT_TEST_PLUGIN_DIR='"$(abspath $(BUILD))/plugins"'
# The plugins' and the loader's tests load the plugins of build/plugins/.
$(filter $(BUILD)/san/tests/unit/plugins/% $(BUILD)/san/tests/unit/plugin/%,$(UNIT_BIN)): $(PLUGINS)
# test_abi loads plugins built for the versions beside this one, which
# the loader must refuse (tests/plugins/bad_abi.c).
TEST_PLUGINS := $(BUILD)/test-plugins/abi_prev.so $(BUILD)/test-plugins/abi_next.so
$(TEST_PLUGINS): $(BUILD)/test-plugins/abi_%.so: tests/plugins/bad_abi.c $(wildcard include/whitted/*.h)
	@mkdir -p $(@D)
	$(CC) $(WARN) $(CFLAGS) -Iinclude -fPIC -shared \
		-DBAD_ABI='(WHITTED_PLUGIN_ABI $(if $(filter prev,$*),-,+) 1)' -o $@ $<
$(BUILD)/san/tests/unit/plugin/test_abi: | $(TEST_PLUGINS)
$(BUILD)/san/tests/unit/viewer/test_%: $(BUILD)/san/tests/unit/viewer/test_%.o \
	$(BUILD)/san/viewer/%.o $(BUILD)/san/tests/unit/support.o $(BUILD)/san/libwhitted-tools.a \
	$(BUILD)/san/libwhitted.a
	$(CC) $(ALL_CFLAGS) $(SAN) -o $@ $^ -lcmocka $(LDLIBS)
$(BUILD)/san/viewer/%.o: ALL_CFLAGS += -Iviewer
$(BUILD)/san/tests/%: $(BUILD)/san/tests/%.o $(BUILD)/san/tests/unit/support.o \
	$(BUILD)/san/libwhitted-tools.a $(BUILD)/san/libwhitted.a
	$(CC) $(ALL_CFLAGS) $(SAN) -o $@ $^ -lcmocka $(LDLIBS)

# The fuzz harness, replayed over the corpus with the sanitized library.
$(BUILD)/san/fuzz_replay: tests/fuzz/replay.c tests/fuzz/harness.c tests/fuzz/harness.h \
	$(BUILD)/san/libwhitted.a
	$(CC) $(ALL_CFLAGS) -O1 $(SAN) -Itests/fuzz -o $@ tests/fuzz/replay.c tests/fuzz/harness.c \
		$(BUILD)/san/libwhitted.a $(LDLIBS)

# The image readers' fuzz harness, replayed over tests/fuzz/images.
$(BUILD)/san/fuzz_image_replay: tests/fuzz/replay.c tests/fuzz/image_harness.c tests/fuzz/harness.h \
	$(BUILD)/san/libwhitted.a
	$(CC) $(ALL_CFLAGS) -O1 $(SAN) -Itests/fuzz -DRT_FUZZ_TARGET=fuzz_image_one -o $@ \
		tests/fuzz/replay.c tests/fuzz/image_harness.c $(BUILD)/san/libwhitted.a $(LDLIBS)

# The plugin loader's checks' fuzz harness, replayed over tests/fuzz/plugins.
$(BUILD)/san/fuzz_plugin_replay: tests/fuzz/replay.c tests/fuzz/plugin_harness.c tests/fuzz/harness.h \
	$(BUILD)/san/libwhitted.a
	$(CC) $(ALL_CFLAGS) -O1 $(SAN) -Itests/fuzz -DRT_FUZZ_TARGET=fuzz_plugin_one -o $@ \
		tests/fuzz/replay.c tests/fuzz/plugin_harness.c $(BUILD)/san/libwhitted.a $(LDLIBS)

# ---- the cross builds' libraries: zlib, libpng, stb_image -----------------
# make windows and make web compile Debian's sources of zlib and libpng
# (and libstb-dev's header) into their programs: MinGW-w64 has no libpng,
# and emscripten's ports would be fetched from the network.
# scripts/third-party.sh fetches and unpacks them once, under
# build/third_party/.
THIRD := $(BUILD)/third_party
ZLIB_C := adler32 compress crc32 deflate infback inffast inflate \
	inftrees trees uncompr zutil
LIBPNG_C := png pngerror pngget pngmem pngpread pngread pngrio pngrtran pngrutil pngset \
	pngtrans pngwio pngwrite pngwtran pngwutil
THIRD_SRC := $(ZLIB_C:%=$(THIRD)/zlib/%.c) $(LIBPNG_C:%=$(THIRD)/libpng/%.c)
THIRD_CFLAGS := -I$(THIRD)/zlib -I$(THIRD)/libpng -isystem $(THIRD)/include
$(THIRD)/.stamp: scripts/third-party.sh
	@scripts/third-party.sh $(THIRD)
	@touch $@
$(THIRD_SRC): $(THIRD)/.stamp
	@test -f $@

# ---- make windows: whitted.exe and scene2pov.exe --------------------------
# Cross-built with Debian's MinGW-w64 (the POSIX thread model, for
# pthreads), static: zlib, libpng and stb_image built in, the C runtime's
# and winpthreads' libraries linked in, so each .exe runs alone.  The
# platform layer is src/base/platform_windows.c: no plugins, no huge
# pages (whitted.exe --version says so).  The AVX2 and AVX-512 files are
# compiled without their instruction sets: GCC does not align the stack
# of Windows' x64 calling convention to the 32 bytes their spills need
# (GCC bug 54412), and every walk gives the same image.  make wintest
# runs them under wine against the Linux build.
WIN_CC ?= x86_64-w64-mingw32-gcc-posix
WIN := $(BUILD)/windows
# -Wno-format: MinGW's GCC checks format(printf) as Microsoft's printf,
# which has no %zu, though the functions behind it are MinGW's C99 ones
# (__USE_MINGW_ANSI_STDIO); the native builds check the formats.
WIN_CFLAGS := $(WARN) -Wno-format $(FP) -O2 -Iinclude -Isrc $(THIRD_CFLAGS) \
	-D__USE_MINGW_ANSI_STDIO=1 -MMD -MP
WIN_LIB_SRC := $(filter-out src/base/platform_posix.c,$(LIB_SRC)) src/base/platform_windows.c
WIN_LIBS := -static -lpsapi -lm -pthread
$(WIN)/third/%.o: $(THIRD)/%.c
	@mkdir -p $(@D)
	$(WIN_CC) -std=c99 -O2 $(FP) $(THIRD_CFLAGS) -w -c $< -o $@
$(WIN)/%.o: %.c $(THIRD)/.stamp
	@mkdir -p $(@D)
	$(WIN_CC) $(WIN_CFLAGS) -c $< -o $@
WIN_THIRD_OBJ := $(THIRD_SRC:$(THIRD)/%.c=$(WIN)/third/%.o)
# The kernels in the baseline's instructions alone (see the AVX note above).
$(WIN)/%_base.o: %.c $(THIRD)/.stamp
	@mkdir -p $(@D)
	$(WIN_CC) $(WIN_CFLAGS) -DRT_SIMD_KERNEL=base -DRT_SIMD_KERNEL_base -c $< -o $@
WIN_LIB_OBJ := $(WIN_LIB_SRC:%.c=$(WIN)/%.o) $(KERNEL_SRC:%.c=$(WIN)/%_base.o) \
	$(TOOLS_SRC:%.c=$(WIN)/%.o) $(WIN_THIRD_OBJ)
$(WIN)/pov_export/%.o: WIN_CFLAGS += -Ipov_export
$(WIN)/whitted.exe: $(WHITTED_SRC:%.c=$(WIN)/%.o) $(WIN_LIB_OBJ)
	@echo "$(WIN_CC) -o $@ ... $(WIN_LIBS)"
	@$(WIN_CC) -o $@ $^ $(WIN_LIBS)
$(WIN)/scene2pov.exe: $(POV_SRC:%.c=$(WIN)/%.o) $(WIN_LIB_OBJ)
	@echo "$(WIN_CC) -o $@ ... $(WIN_LIBS)"
	@$(WIN_CC) -o $@ $^ $(WIN_LIBS)
windows:
	@scripts/deps.sh $(filter-out wine wine64,$(WIN_PKGS))
	@$(MAKE) --no-print-directory $(WIN)/whitted.exe $(WIN)/scene2pov.exe
	@echo "built $(WIN)/whitted.exe and $(WIN)/scene2pov.exe"
wintest: all plugins windows
	@tests/windows/run.sh $(WIN) $(BUILD)

# ---- make web: the page (build/web/index.html) ----------------------------
# The library, whitted's command line and web/web_api.c compiled by
# Debian's emscripten into one WebAssembly module, its SSE2 paths into
# WebAssembly SIMD (-msimd128 -msse2: the same operations, so the same
# bytes), zlib and libpng from Debian's sources; then web/bundle.py puts
# it, the page's script and style into one index.html (the module inlined
# in base64: no server, no network; it opens from disk and from any
# static host) and copies the screenshot-free folder's few files.  The
# workers are made from that inlined text (a Blob), as a page opened from
# disk may start no worker from a file.
WEB := $(BUILD)/web
WEB_OBJ_DIR := $(BUILD)/wasm
EMCC ?= emcc
WEB_CFLAGS := $(WARN) $(FP) -O3 -msimd128 -msse2 -Iinclude -Isrc $(THIRD_CFLAGS) -MMD -MP
WEB_LDFLAGS := -O3 -msimd128 -sMODULARIZE=1 -sEXPORT_NAME=createWhittedModule \
	-sENVIRONMENT=worker -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=33554432 \
	-sTOTAL_STACK=16777216 -sEXIT_RUNTIME=0 -sINVOKE_RUN=0 -sFILESYSTEM=1 \
	-sEXPORTED_FUNCTIONS=_web_argv_reset,_web_argv_push,_web_cli,_web_render_begin,_web_render_width,_web_render_height,_web_render_rows,_web_render_end,_malloc,_free \
	-sEXPORTED_RUNTIME_METHODS=['FS','ccall','UTF8ToString'] --no-entry
WEB_SRC := $(LIB_SRC) $(TOOLS_SRC) $(WHITTED_SRC) web/web_api.c
$(WEB_OBJ_DIR)/third/%.o: $(THIRD)/%.c
	@mkdir -p $(@D)
	$(EMCC) -std=c99 -O3 $(FP) $(THIRD_CFLAGS) -w -c $< -o $@
$(WEB_OBJ_DIR)/%.o: %.c $(THIRD)/.stamp
	@mkdir -p $(@D)
	$(EMCC) $(WEB_CFLAGS) -c $< -o $@
# The kernels once, in WebAssembly's SIMD (the baseline's SSE2 turned).
$(WEB_OBJ_DIR)/%_base.o: %.c $(THIRD)/.stamp
	@mkdir -p $(@D)
	$(EMCC) $(WEB_CFLAGS) -DRT_SIMD_KERNEL=base -DRT_SIMD_KERNEL_base -c $< -o $@
# Debian's emscripten runs its optimiser under node with Debian's acorn
# (node-acorn, in /usr/share/nodejs), which a node from elsewhere does not
# look for.
$(WEB_OBJ_DIR)/whitted-wasm.js: export NODE_PATH := /usr/share/nodejs$(if $(NODE_PATH),:$(NODE_PATH))
# whitted's main is the page's whitted_main (web_api.c calls it).
$(WEB_OBJ_DIR)/src/cli/main.o: WEB_CFLAGS += -Dmain=whitted_main -Wno-missing-prototypes
$(WEB_OBJ_DIR)/whitted-wasm.js: $(WEB_SRC:%.c=$(WEB_OBJ_DIR)/%.o) $(KERNEL_SRC:%.c=$(WEB_OBJ_DIR)/%_base.o) \
	$(THIRD_SRC:$(THIRD)/%.c=$(WEB_OBJ_DIR)/third/%.o)
	@echo "$(EMCC) -o $@ ... $(WEB_LDFLAGS)"
	@$(EMCC) -o $@ $^ $(WEB_LDFLAGS)
$(WEB)/index.html: $(WEB_OBJ_DIR)/whitted-wasm.js web/bundle.py $(wildcard web/*.js web/*.html web/*.css)
	@mkdir -p $(@D)
	python3 web/bundle.py $(WEB_OBJ_DIR)/whitted-wasm.js web $(WEB)
web:
	@scripts/deps.sh $(filter-out npm,$(WEB_PKGS))
	@$(MAKE) --no-print-directory $(WEB)/index.html
	@echo "built $(WEB)/index.html ($$(du -sh $(WEB) | cut -f1)): open it in a browser"
# The page in headless chromium against build/whitted (tests/web/run.mjs).
webtest: all web
	@tests/web/run.sh $(BUILD)

# ---- make check -----------------------------------------------------------
# check-deps installs first; the suites then run in a new make, so that what
# it installed (povray, freeglut) is seen.  Each suite decides at run time
# whether it can run, and says NOT RUN (and why) only when its tools are
# really missing.
check: check-deps
	@$(MAKE) --no-print-directory all plugins $(UNIT_BIN) $(BUILD)/san/fuzz_replay \
		$(BUILD)/san/fuzz_image_replay $(BUILD)/san/fuzz_plugin_replay
	@for t in $(SUITES); do $(MAKE) --no-print-directory $$t || exit 1; done

check-deps:
	@scripts/deps.sh $(CHECK_PKGS)
	@scripts/deps.sh --optional $(FAST_PKGS)

deps: check-deps
	@scripts/deps.sh --optional $(BENCH_PKGS) $(BENCH_OPT_PKGS)

render:
	@scripts/deps.sh $(CORE_PKGS)
	@scripts/deps.sh --optional $(FAST_PKGS)
	@$(MAKE) --no-print-directory all
	@mkdir -p out
	$(BUILD)/whitted -o out/scene.png scenes/scene.txt
	@echo "wrote out/scene.png"

layout: all
	@python3 tests/layout/modules.py $(BUILD)
unit: $(UNIT_BIN)
	@tests/unit/run.sh $(UNIT_BIN)
clitest: all
	@tests/cli/run.sh
dialects: all
	@tests/cli/dialects.sh
manpages: all
	@tests/cli/manpages.sh
valgrind: all plugins
	@tests/valgrind.sh
disttest: all
	@tests/dist/run.sh
faults: all
	@tests/cli/faults.sh
# With the example plugins loaded, so that the corpus's plugin seeds reach
# their parsers and intersections.
fuzz-replay: $(BUILD)/san/fuzz_replay $(BUILD)/san/fuzz_image_replay $(BUILD)/san/fuzz_plugin_replay plugins
	@WHITTED_PLUGIN_PATH=$(BUILD)/plugins $(BUILD)/san/fuzz_replay tests/fuzz/corpus tests/errors
	@$(BUILD)/san/fuzz_image_replay tests/fuzz/images
	@$(BUILD)/san/fuzz_plugin_replay tests/fuzz/plugins
threadcheck: all
	@bench/threadcheck.sh
features: all plugins
	@tests/features/run.sh
portablecheck: all
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/portable CFLAGS="$(CFLAGS) -DACCEL_PORTABLE" \
		$(BUILD)/portable/whitted >/dev/null
	@bench/portablecheck.sh $(BUILD)/whitted $(BUILD)/portable/whitted
imgcmptest: all
	@tests/tools/imgcmp-test.sh
	@tests/tools/walltime-test.sh
povcheck: all plugins
	@tests/povcheck.sh
embreecheck: all
	@bench/embreecheck.sh
refcheck: all
	@python3 tests/reference/random_check.py $(BUILD)/whitted 24 2026 80
mistakecheck: all
	@python3 tests/reference/mistakes_check.py $(BUILD)/whitted $(UNIT_DATA_DIR)
comparetest: all $(BUILD)/san/whitted
	@tests/cli/compare.sh $(BUILD)/whitted
	@tests/cli/compare_order.sh $(BUILD)/whitted
	@tests/cli/compare_real.sh $(BUILD)/whitted $(BUILD)/san/whitted
explaintest: all
	@tests/cli/explain.sh
reportcheck: all
	@tests/cli/report.sh $(BUILD)/whitted
viewer-e2e: all plugins
	@if [ -z "$(VIEWER_HAVE_GL)" ]; then \
		echo "viewer-e2e: NOT RUN: freeglut3-dev is not installed (make deps)"; exit 1; \
	fi
	@tests/viewer/e2e.sh $(BUILD)/whitted-view $(BUILD)/whitted
install-test: all plugins
	@tests/cli/install-test.sh
newshape: all
	@tests/cli/newshape.sh
newisa: all
	@tests/cli/newisa.sh
plugintest: all plugins
	@tests/cli/plugins.sh

# ---- fuzzing (not part of check) ------------------------------------------
#   make fuzz   builds the libFuzzer target with clang and runs it for
#               FUZZ_SECONDS (default 600) on tests/fuzz/corpus and tests/errors
FUZZ_SECONDS ?= 600
FUZZ_CC ?= clang
FUZZ_FLAGS := -std=c99 -g -O1 -Iinclude -Isrc $(PNG_CFLAGS) -pthread \
	-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -MMD -MP
$(BUILD)/fuzz/%.o: %.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) -c $< -o $@
$(BUILD)/fuzz/%_base.o: %.c
	@mkdir -p $(@D)
	$(FUZZ_CC) $(FUZZ_FLAGS) -DRT_SIMD_KERNEL=base -DRT_SIMD_KERNEL_base -c $< -o $@
FUZZ_LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/fuzz/%.o) $(KERNEL_SRC:%.c=$(BUILD)/fuzz/%_base.o)
$(BUILD)/fuzz/fuzz_scene: tests/fuzz/fuzz_scene.c tests/fuzz/harness.c tests/fuzz/harness.h \
	$(FUZZ_LIB_OBJ)
	$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer -Itests/fuzz -o $@ tests/fuzz/fuzz_scene.c \
		tests/fuzz/harness.c $(FUZZ_LIB_OBJ) $(LDLIBS)
$(BUILD)/fuzz/fuzz_image: tests/fuzz/fuzz_image.c tests/fuzz/image_harness.c tests/fuzz/harness.h \
	$(FUZZ_LIB_OBJ)
	$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer -Itests/fuzz -o $@ tests/fuzz/fuzz_image.c \
		tests/fuzz/image_harness.c $(FUZZ_LIB_OBJ) $(LDLIBS)
$(BUILD)/fuzz/fuzz_plugin: tests/fuzz/fuzz_plugin.c tests/fuzz/plugin_harness.c tests/fuzz/harness.h \
	$(FUZZ_LIB_OBJ)
	$(FUZZ_CC) $(FUZZ_FLAGS) -fsanitize=fuzzer -Itests/fuzz -o $@ tests/fuzz/fuzz_plugin.c \
		tests/fuzz/plugin_harness.c $(FUZZ_LIB_OBJ) $(LDLIBS)
#   make fuzz-plugins  the same for the plugin loader's checks, on tests/fuzz/plugins
fuzz-plugins: $(BUILD)/fuzz/fuzz_plugin
	@mkdir -p $(BUILD)/fuzz/plugins $(BUILD)/fuzz/artifacts
	$(BUILD)/fuzz/fuzz_plugin -max_total_time=$(FUZZ_SECONDS) -max_len=65536 -timeout=10 \
		-rss_limit_mb=2048 -artifact_prefix=$(BUILD)/fuzz/artifacts/ -print_final_stats=1 \
		$(BUILD)/fuzz/plugins tests/fuzz/plugins
#   make fuzz-images   the same for the image readers (and tiles), on tests/fuzz/images
fuzz-images: $(BUILD)/fuzz/fuzz_image
	@mkdir -p $(BUILD)/fuzz/images $(BUILD)/fuzz/artifacts
	$(BUILD)/fuzz/fuzz_image -max_total_time=$(FUZZ_SECONDS) -max_len=16384 -timeout=10 \
		-rss_limit_mb=2048 -artifact_prefix=$(BUILD)/fuzz/artifacts/ -print_final_stats=1 \
		$(BUILD)/fuzz/images tests/fuzz/images

fuzz: $(BUILD)/fuzz/fuzz_scene plugins
	@mkdir -p $(BUILD)/fuzz/corpus $(BUILD)/fuzz/artifacts
	WHITTED_PLUGIN_PATH=$(BUILD)/plugins $(BUILD)/fuzz/fuzz_scene -max_total_time=$(FUZZ_SECONDS) \
		-dict=tests/fuzz/scene.dict -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
		-artifact_prefix=$(BUILD)/fuzz/artifacts/ -print_final_stats=1 \
		$(BUILD)/fuzz/corpus tests/fuzz/corpus tests/errors

# ---- the benchmark (not a test; see docs/benchmark.md) ---------------------
bench: all
	@scripts/deps.sh $(BENCH_PKGS)
	@scripts/deps.sh --optional $(BENCH_OPT_PKGS)
	@if [ -f /usr/include/embree3/rtcore.h ]; then \
		$(MAKE) --no-print-directory $(BUILD)/whitted-embree $(BUILD)/embree_build; fi
	@bench/bench.sh
	@if command -v emcc >/dev/null 2>&1 && command -v chromium >/dev/null 2>&1; then \
		$(MAKE) --no-print-directory web >/dev/null && tests/web/run.sh $(BUILD) --install-only && \
		node bench/web-bench.mjs $(BUILD)/web/index.html $(BUILD)/whitted scenes/scene.txt \
			$(BUILD)/node/node_modules; \
	else echo "web row: not run (emscripten or chromium missing: make deps)"; fi

# ---- installing -----------------------------------------------------------
MAN_PAGES := $(wildcard docs/man/*.1)
install: all plugins
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig \
		$(DESTDIR)$(PREFIX)/include/whitted $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 $(PROGRAMS:%=$(BUILD)/%) $(DESTDIR)$(PREFIX)/bin/
	install -m 644 $(BUILD)/libwhitted.a $(DESTDIR)$(PREFIX)/lib/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' \
		-e 's|@DEFLATE_LIBS@ |$(DEFLATE_LIBS:%=% )|g' whitted.pc.in \
		> $(DESTDIR)$(PREFIX)/lib/pkgconfig/whitted.pc
	install -m 644 include/whitted/*.h $(DESTDIR)$(PREFIX)/include/whitted/
	$(if $(MAN_PAGES),install -m 644 $(MAN_PAGES) $(DESTDIR)$(PREFIX)/share/man/man1/)
	install -d $(DESTDIR)$(PREFIX)/lib/whitted/plugins
	install -m 644 $(PLUGINS) $(DESTDIR)$(PREFIX)/lib/whitted/plugins/

clean:
	rm -rf $(BUILD) out

-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)
