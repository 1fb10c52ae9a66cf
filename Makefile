# tarn: `make demo` renders scenes/pond.json to pond.png; `make test` runs every test.
# Both install missing Debian packages first (scripts/ensure-deps.sh).

BUILD ?= build/release
SAN ?= 0
CC ?= cc

# A short line a file built ("  CC      build/release/core/raster/raster.o", LD, AR,
# and in firmware/firmware.mk BAKE, RUN, ...); make V=1 prints every command in
# full instead, make -s neither. A recipe shows its line with $(call show,TAG,FILE)
# and runs its command as $(Q)command; a command that is always hidden (@) is
# printed with V=1 by $(call show_command,COMMAND).
V ?= 0
ifeq ($(V),1)
Q :=
show = @:
show_command = @printf '%s\n' '$(subst ','\'',$(strip $(1)))'
else
Q := @
show = @printf '  %-7s %s\n' '$(1)' '$(2)'
show_command = @:
endif
ifneq ($(findstring s,$(firstword -$(MAKEFLAGS))),)
show = @:
show_command = @:
endif

# Parallel by default: as many jobs as cores, unless a -j was given. (GNU make 4.3
# shows no -j of the command line in MAKEFLAGS while it reads the makefiles, but a
# -j given there outranks this one; a make run by another make finds the caller's
# -j in the MAKEFLAGS of its environment and shares the caller's jobs.) A recipe line
# that runs a program which runs make itself (tarn sweep, the check scripts) starts
# with + so that the jobs are passed on to it.
ifeq ($(filter -j% --jobs%,$(shell printenv MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 1)
endif
# Goals given together are made one after another when one of them is not a file of
# a build (make clean all, make firmware-run bench-target): clean would remove what
# the other builds, and two loops over the boards would build the same files at
# once. Each goal's own work (and the makes it runs) still takes the jobs.
ifneq ($(filter-out 0 1,$(words $(MAKECMDGOALS))),)
ifneq ($(filter-out build/% $(BUILD)/%,$(MAKECMDGOALS)),)
.NOTPARALLEL:
endif
endif

WARN := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes -Wmissing-prototypes
OPT := -O2 -g
ifeq ($(SAN),1)
OPT := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
endif
# the frame drawn in parts by threads at once (tests/test_frame_parts.c), under
# ThreadSanitizer: the parts share nothing the core writes
ifeq ($(SAN),thread)
OPT := -O1 -g -fno-omit-frame-pointer -fsanitize=thread
endif

CORE_CFLAGS := -std=c99 -pedantic $(WARN) $(OPT) -Icore -Icore/include
# Display backends, each optional and found by pkg-config: libgpiod 1.x (Debian 12)
# or 2.x for GPIO lines, hidapi for the MCP2210 bridge; without one, a stub says so.
GPIOD_VERSION := $(shell pkg-config --modversion libgpiod 2>/dev/null)
GPIO_LINES_SRC := $(if $(GPIOD_VERSION),$(if $(filter 1.%,$(GPIOD_VERSION)),host/display/gpio_lines_gpiod1.c,host/display/gpio_lines_gpiod2.c),host/display/gpio_lines_none.c)
HIDAPI_PKG := $(shell pkg-config --exists hidapi-hidraw 2>/dev/null && echo hidapi-hidraw)
MCP2210_USB_SRC := $(if $(HIDAPI_PKG),host/display/mcp2210_hidapi.c,host/display/mcp2210_hidapi_none.c)
# tarn view's window: SDL2 when pkg-config finds it, else a stub that says so.
SDL2_PKG := $(shell pkg-config --exists sdl2 2>/dev/null && echo sdl2)
VIEW_WINDOW_SRC := $(if $(SDL2_PKG),host/view/view_window_sdl.c,host/view/view_window_none.c)
HOST_PKGS := libpng jansson libgif $(if $(GPIOD_VERSION),libgpiod) $(HIDAPI_PKG) $(SDL2_PKG)
# host/ is in folders by job (host/*/README.md); every folder is on the include path,
# so a host header is included by its name alone wherever it lives.
HOST_INCLUDES := -Icore -Icore/include $(patsubst %/,-I%,$(sort $(wildcard host/*/)))
HOST_CFLAGS := -std=c99 $(WARN) $(OPT) -D_POSIX_C_SOURCE=200809L $(HOST_INCLUDES) \
	$(shell pkg-config --cflags $(HOST_PKGS) 2>/dev/null)
HOST_LIBS := $(shell pkg-config --libs $(HOST_PKGS) 2>/dev/null) -lm -pthread
# tests/test_view.c reads tarn view's window back from the X server: libX11 comes
# with libsdl2-dev.
TEST_LIBS := $(shell pkg-config --libs cmocka zlib $(if $(SDL2_PKG),x11) 2>/dev/null)

CORE_SRC := $(wildcard core/*/*.c)
HOST_SRC := $(filter-out host/cli/main.c host/display/gpio_lines_gpiod%.c host/display/gpio_lines_none.c \
	host/display/mcp2210_hidapi%.c host/view/view_window_%.c,$(wildcard host/*/*.c)) $(GPIO_LINES_SRC) \
	$(MCP2210_USB_SRC) $(VIEW_WINDOW_SRC)
# test_gpio_lines_gpiod1.c emulates libgpiod 1.x at its calls: only with that backend
TEST_SRC := $(filter-out $(if $(filter %gpiod1.c,$(GPIO_LINES_SRC)),,tests/test_gpio_lines_gpiod1.c),\
	$(wildcard tests/test_*.c))
TEST_SUPPORT_SRC := $(filter-out $(TEST_SRC),$(wildcard tests/*.c))

CORE_OBJ := $(CORE_SRC:%.c=$(BUILD)/%.o)
HOST_OBJ := $(HOST_SRC:%.c=$(BUILD)/%.o)
TEST_SUPPORT_OBJ := $(TEST_SUPPORT_SRC:%.c=$(BUILD)/%.o)
TEST_BIN := $(TEST_SRC:tests/%.c=$(BUILD)/tests/%)
TARN := $(BUILD)/tarn

.PHONY: all demo test check deps deps-test core-purity bench-panels sweep-docs docs-figures golden clean lib libtarn install
.DELETE_ON_ERROR:
.SECONDARY:

# (a recipe, so that make says nothing when tarn is up to date)
all: $(TARN)
	@:

deps:
	@scripts/ensure-deps.sh demo

deps-test:
	@scripts/ensure-deps.sh test

demo: deps
	@$(MAKE) --no-print-directory $(TARN)
	$(TARN) render scenes/pond.json -o pond.png
	@echo "wrote pond.png"

# The whole suite: the emulated boards run (their streams are compared with the host
# by tests/test_firmware.c), one sweep of several qualities on qemu-m0
# (tests/check_firmware_sweep.sh), tarn sweep's quick grid and the published
# presets re-measured (tests/check_sweep.sh), a plain build, then the same tests under ASan + UBSan,
# then the frame in parts, by threads at once, under ThreadSanitizer,
# then the check that core/ stays integer-only on a Cortex-M0, then the core as a
# package (make install, CMake, PlatformIO: tests/check_packages.sh), then the firmware's
# sizes, stack and counter, and the stack bound on chains of known shape
# (tests/check_stack_bound.sh), then every measured figure of the docs against what the
# code measures now (tests/check_doc_figures.sh), then the fuzz targets' seed corpora
# and a short run of each (tests/fuzz/fuzz.mk).
# A step that fails is noted in build/test-failed and the next one runs, so that one
# run finds every failure; the last lines name the steps (and suites) that failed,
# if any, then the cmocka suites' totals, "tests: N passed, F failed, S skipped",
# and the exit status is non-zero if anything failed.
TEST_FAILED := build/test-failed
# $(call test_failed,STEP): a step's tail that notes it when it fails
test_failed = || echo '$(1)' >> $(TEST_FAILED)
test: deps-test
	@mkdir -p build && rm -f $(TEST_FAILED) $(foreach b,release san,build/$(b)/summary build/$(b)/failed)
	@$(MAKE) --no-print-directory firmware-run BOARD= $(call test_failed,make firmware-run)
	@tests/check_ram_code.sh $(call test_failed,tests/check_ram_code.sh)
	+@tests/check_firmware_sweep.sh $(call test_failed,tests/check_firmware_sweep.sh)
	@$(MAKE) --no-print-directory all $(call test_failed,make $(TARN))
	+@TARN_BIN=$(TARN) tests/check_sweep.sh $(call test_failed,tests/check_sweep.sh)
	@$(MAKE) --no-print-directory check BUILD=build/release SAN=0 || \
		echo "make check BUILD=build/release: $$(cat build/release/failed 2>/dev/null | tr '\n' ' ')" >> $(TEST_FAILED)
	@$(MAKE) --no-print-directory check BUILD=build/san SAN=1 || \
		echo "make check BUILD=build/san SAN=1: $$(cat build/san/failed 2>/dev/null | tr '\n' ' ')" >> $(TEST_FAILED)
	@$(MAKE) --no-print-directory BUILD=build/tsan SAN=thread build/tsan/tests/test_frame_parts && \
		TSAN_OPTIONS=halt_on_error=1 build/tsan/tests/test_frame_parts >build/tsan/test_frame_parts.log 2>&1 && \
		echo "threads: the frame in parts under ThreadSanitizer: no race" || \
		{ tail -30 build/tsan/test_frame_parts.log; echo 'tests/test_frame_parts.c under ThreadSanitizer' >> $(TEST_FAILED); }
	@$(MAKE) --no-print-directory core-purity $(call test_failed,make core-purity)
	@tests/check_packages.sh $(call test_failed,tests/check_packages.sh)
	@TARN_BIN=build/release/tarn WATER_COST_OUT=build/release/water-cost.txt tests/check_water_cost.sh \
		$(call test_failed,tests/check_water_cost.sh)
	@$(MAKE) --no-print-directory firmware-check BOARD= $(call test_failed,make firmware-check)
	@tests/check_stack_bound.sh $(call test_failed,tests/check_stack_bound.sh)
	+@tests/check_firmware_link.sh $(call test_failed,tests/check_firmware_link.sh)
	@BUILD=build/release tests/check_layering.sh $(call test_failed,tests/check_layering.sh)
	@tests/check_doc_paths.sh $(call test_failed,tests/check_doc_paths.sh)
	@TARN_BIN=build/release/tarn tests/check_doc_figures.sh $(call test_failed,tests/check_doc_figures.sh)
	@$(MAKE) --no-print-directory fuzz-replay $(call test_failed,make fuzz-replay)
	@if [ -s $(TEST_FAILED) ]; then echo "make test: failed:"; sed 's/ *$$//; s/^/  /' $(TEST_FAILED); fi; \
	cat build/release/summary build/san/summary 2>/dev/null | \
		awk '{p += $$1; f += $$2; s += $$3} END {printf "tests: %d passed, %d failed, %d skipped\n", p, f, s}'; \
	[ ! -s $(TEST_FAILED) ]

check: $(TARN) $(TEST_BIN)
	@TARN_BIN=$(TARN) SUMMARY_FILE=$(BUILD)/summary FAILED_FILE=$(BUILD)/failed tests/run_suites.sh $(TEST_BIN)

# Re-records tests/golden/frames.txt, the checksums of the frames tests/test_golden.c
# draws: only for a change meant to move pixels, which its commit says.
golden: $(BUILD)/tests/test_golden
	@mkdir -p tests/golden
	@TARN_GOLDEN_RECORD=1 $(BUILD)/tests/test_golden

core-purity:
	@BUILD=build/m0 tests/check_core_purity.sh

# Bytes per frame, bytes per second and fps of every panel link, from counted bytes
# at the link's clock (docs/panels.md); make bench-target has the boards' figures.
bench-panels: $(TARN)
	@TARN_BIN=$(TARN) scripts/bench-panels.sh

# The speed/accuracy map of docs/sweep.md: the full sweep of the pond (refraction)
# and the lake (none) on the host, qemu-m0 and qemu-rv32, and each knob value's
# worst case over scenes/extremes, into docs/sweep/.
SWEEP_SCENES := pond lake
sweep-docs: deps-test
	@$(MAKE) --no-print-directory $(TARN)
	+$(TARN) sweep $(SWEEP_SCENES:%=scenes/%.json) --out build/sweep --extremes scenes/extremes
	@mkdir -p docs/sweep
	cp build/sweep/sweep.csv build/sweep/front.md build/sweep/stability.md $(SWEEP_SCENES:%=build/sweep/%.png) docs/sweep/

# Every measured figure of README.md and docs/ from its command, in place
# (scripts/docs_figures.py; tests/check_doc_figures.sh holds the docs to them in make
# test): the sweep's pages first (make sweep-docs, timed for docs/sweep.md), the
# emulated boards' runs, then every block, keyed number and image. DOCS_SWEEP=0 keeps
# docs/sweep/ as it is (and the figures docs/sweep.md copies from it).
DOCS_SWEEP ?= 1
docs-figures: deps-test
	@$(MAKE) --no-print-directory BUILD=build/release SAN=0 build/release/tarn build/release/tests/test_raster
	@if [ "$(DOCS_SWEEP)" = 1 ]; then \
		start=$$(date +%s) && $(MAKE) --no-print-directory BUILD=build/release SAN=0 sweep-docs && \
		mkdir -p build/figures && echo $$(($$(date +%s) - start)) > build/figures/sweep-docs.seconds; \
	fi
	@$(MAKE) --no-print-directory firmware-run BOARD=
	@TARN_BIN=build/release/tarn scripts/docs_figures.py write

$(TARN): $(BUILD)/host/cli/main.o $(HOST_OBJ) $(CORE_OBJ)
	$(call show,LD,$@)
	$(Q)$(CC) $(OPT) -o $@ $^ $(HOST_LIBS)

$(BUILD)/tests/%: $(BUILD)/tests/%.o $(TEST_SUPPORT_OBJ) $(HOST_OBJ) $(CORE_OBJ)
	$(call show,LD,$@)
	$(Q)$(CC) $(OPT) -o $@ $^ $(HOST_LIBS) $(TEST_LIBS)

$(BUILD)/core/%.o: core/%.c
	@mkdir -p $(dir $@)
	$(call show,CC,$@)
	$(Q)$(CC) $(CORE_CFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/host/%.o: host/%.c
	@mkdir -p $(dir $@)
	$(call show,CC,$@)
	$(Q)$(CC) $(HOST_CFLAGS) -MMD -MP -c -o $@ $<

$(BUILD)/tests/%.o: tests/%.c
	@mkdir -p $(dir $@)
	$(call show,CC,$@)
	$(Q)$(CC) $(HOST_CFLAGS) -Itests $(shell pkg-config --cflags cmocka 2>/dev/null) -MMD -MP -c -o $@ $<

clean:
	rm -rf build pond.png

# ---- The core as an installed library: make lib, make install -------------------
# make lib (or make libtarn) archives the core's objects, and nothing else, into
# build/release/libtarn.a: the CORE rules above compile them in the release build
# (BUILD=build/release SAN=0), whatever BUILD and SAN this make was given.
# make install [PREFIX=/usr/local] [DESTDIR=] puts that library in $(PREFIX)/lib, the
# public headers (core/include/tarn/*.h, never an *_internal.h) in
# $(PREFIX)/include/tarn/, and $(PREFIX)/lib/pkgconfig/tarn.pc, made from
# core/tarn.pc.in with the prefix and the version tarn_version.h holds (the one place
# it is written). Programs then `#include "tarn/tarn.h"` and build with
# `pkg-config --cflags --libs tarn`. docs/packages.md has the other ways in: CMake
# (core/CMakeLists.txt) and PlatformIO (core/library.json).
PREFIX ?= /usr/local
TARN_LIB := build/release/libtarn.a
TARN_PUBLIC_HEADERS := $(wildcard core/include/tarn/*.h)
# TARN_VERSION_MAJOR and the others' values, read only when a recipe needs them
tarn_version_part = $(shell awk '$$2 == "TARN_VERSION_$(1)" {print $$3}' core/include/tarn/tarn_version.h)
TARN_VERSION = $(call tarn_version_part,MAJOR).$(call tarn_version_part,MINOR).$(call tarn_version_part,PATCH)

lib libtarn:
	@$(MAKE) --no-print-directory BUILD=build/release SAN=0 $(TARN_LIB)

# q, not r: members are appended by name as given, so two stages may hold files of
# the same name; the archive is made anew each time so a removed file leaves it.
$(BUILD)/libtarn.a: $(CORE_OBJ)
	@rm -f $@
	$(call show,AR,$@)
	$(Q)$(AR) qcs $@ $^

install: lib
	install -d $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/include/tarn
	install -m 644 $(TARN_LIB) $(DESTDIR)$(PREFIX)/lib/libtarn.a
	install -m 644 $(TARN_PUBLIC_HEADERS) $(DESTDIR)$(PREFIX)/include/tarn/
	sed -e 's|@TARN_PC_PREFIX@|$(PREFIX)|' -e 's|@TARN_VERSION@|$(TARN_VERSION)|' \
		core/tarn.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/tarn.pc

# This build's own: every host object is under $(BUILD), and firmware.mk includes
# its build's. (Reading every build's, thousands of files once the boards and the
# tests' builds are made, cost each make about 2.5 s: five of them a firmware
# measurement.)
-include $(shell find $(BUILD) -name '*.d' 2>/dev/null)

# Firmware for the boards in boards/: make firmware [BOARD=name], make bench-target.
include firmware/firmware.mk

# Fuzzing with libFuzzer: make fuzz, make fuzz-replay.
include tests/fuzz/fuzz.mk
