# The POV-Ray cross-validation: scene2pov (the exporter), imgcmp (the image
# comparison) and `make povcheck`, which renders every scene in scenes/ with
# whitted and with POV-Ray and compares them.  povcheck joins `make check`
# only where povray is installed; elsewhere check says it was NOT RUN.
POV_EXPORT_SRC := pov_export/export.c pov_export/main.c
POV_EXPORT_OBJ := $(POV_EXPORT_SRC:%.c=$(BUILD)/%.o)

ALL_TARGETS += $(BUILD)/scene2pov $(BUILD)/imgcmp
INSTALL_PROGRAMS += scene2pov
# povray is optional: without it `make check` still runs and says that
# povcheck was NOT RUN (.ci/run installs it, so CI always runs it).
OPTIONAL_PKGS += povray povray-includes

$(BUILD)/pov_export/%.o: ALL_CFLAGS += -Ipov_export

$(BUILD)/scene2pov: $(POV_EXPORT_OBJ) $(BUILD)/libwhitted.a
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/imgcmp: $(BUILD)/tests/tools/imgcmp.o $(BUILD)/tests/tools/imgio.o
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDLIBS)

# Test-only: the altered images that imgcmp's own tests compare.
$(BUILD)/imgfilter: $(BUILD)/tests/tools/imgfilter.o $(BUILD)/tests/tools/imgio.o
	$(CC) $(ALL_CFLAGS) -o $@ $^ $(LDLIBS)

.PHONY: povcheck imgcmptest povcheck-not-run
CHECK_TARGETS += imgcmptest
ifneq ($(shell command -v povray 2>/dev/null),)
CHECK_TARGETS += povcheck
else
CHECK_TARGETS += povcheck-not-run
endif

imgcmptest: all $(BUILD)/imgfilter
	@tests/tools/imgcmp-test.sh

povcheck: all
	@tests/povcheck.sh

povcheck-not-run:
	@echo "povcheck: NOT RUN: povray is not installed (apt-get install povray); nothing was compared"
