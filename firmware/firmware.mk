# firmware.mk: the firmware targets, included by the Makefile.
#
#   make firmware                 every board in boards/ (each folder with a board.mk)
#   make firmware BOARD=qemu-m0   one board: bakes its scene with build/release/tarn,
#                                 builds build/firmware/BOARD/firmware.elf
#   make firmware-run BOARD=...   also runs an emulated board under QEMU (-icount
#                                 shift=0): build/firmware/BOARD/panel.stream is what
#                                 it sent the panel, report.txt its report line, of
#                                 which it prints the figures (size, instructions a
#                                 pixel, stack peak), a line a scene
#   make bench-target             runs every emulated board and prints one line for
#                                 each of its scenes
#   make profile-target BOARD=qemu-m0 [TOP=N] [ANNOTATE="fn ..."]   where an
#                                 emulated board's instructions go, counted exactly:
#                                 by function, source file and source line, and
#                                 instruction by instruction in each ANNOTATE function
#   make firmware SCENE=my.json BAKE_FLAGS="--tile 16 --depth 16"   another scene
#   make firmware-run BOARD=qemu-m0-264k FW_BOARD_SCENE=scenes/pond-opaque.json
#                                 one of the board's own scenes (BOARD_SCENES)
#   make firmware-sweep BOARD=qemu-m0 POINTS=points.txt [SCENE=... BAKE_FLAGS=...]
#                                 one boot measures every quality of the points file
#                                 (tarn bake --points; firmware/sweep_main.c):
#                                 build/firmware-sweep/BOARD/report.txt, a line a point
#
# A board whose board.mk gives no BOARD_RUN is a real board: it is built (and
# size-, stack- and float-checked by firmware-check) but never run here.
#
# A board's scenes are BOARD_SCENES in its board.mk, each baked with its
# BOARD_BAKE_FLAGS (or the scene's own, BOARD_BAKE_FLAGS.NAME, and held to
# BOARD_CODE_BYTES_MAX.NAME instead of BOARD_CODE_BYTES_MAX where the board gives
# them) into a build of its own: the first in build/firmware/BOARD (the
# board's own build: profile-target, firmware-sweep), every other one in
# build/firmware/BOARD@NAME (NAME: the scene file's name without .json).
# make firmware, firmware-run, bench-target and firmware-check of a board do each
# of its scenes in turn.
#
# docs/firmware.md describes the boards, the stream and the figures.

FW_BOARDS := $(sort $(patsubst boards/%/board.mk,%,$(wildcard boards/*/board.mk)))
FW_TARN := build/release/tarn
FW_TIMEOUT ?= 120
# The times (ms) of the frames firmware/main.c streams, compared byte for byte with
# the host's frames by tests/test_firmware.c; the second is also the frame the
# core renders alone, and the one make bench-target's panel_psnr measures.
FW_TIMES := 0,1000,5000

.PHONY: firmware firmware-run fw-run firmware-check bench-target profile-target firmware-sweep fw-dirs

# The program an emulated board runs: main (firmware/main.c, the measured run) or
# sweep (firmware/sweep_main.c: every point of the bake's --points, one boot), which
# make firmware-sweep selects.
FW_MAIN ?= $(if $(filter firmware-sweep,$(MAKECMDGOALS)),sweep,main)

ifeq ($(BOARD),)

profile-target:
	@echo "tarn: make profile-target needs BOARD= one of the emulated boards" >&2; exit 1

firmware-sweep:
	@echo "tarn: make firmware-sweep needs BOARD= one of the emulated boards, and POINTS=FILE" >&2; exit 1

firmware:
	@for b in $(FW_BOARDS); do $(MAKE) --no-print-directory firmware BOARD=$$b || exit 1; done

firmware-run:
	@for b in $(FW_BOARDS); do $(MAKE) --no-print-directory firmware-run BOARD=$$b || exit 1; done

# firmware-run without the result lines, for firmware-check (make test has printed them)
fw-run:
	@for b in $(FW_BOARDS); do $(MAKE) --no-print-directory fw-run BOARD=$$b || exit 1; done

bench-target:
	@for b in $(FW_BOARDS); do $(MAKE) --no-print-directory -s bench-target BOARD=$$b || exit 1; done

# make test: every board built, run and compared with the host, byte for byte; the
# real boards built and checked, and their bad builds (too little RAM, no compiler)
# failing as they should. The builds to check: each board's, a directory a scene
# (fw-dirs).
firmware-check: fw-run
	@tests/check_firmware.sh $$(for b in $(FW_BOARDS); do $(MAKE) --no-print-directory -s fw-dirs BOARD=$$b || exit 1; done)
	+@tests/check_real_boards.sh

else ifeq ($(filter $(BOARD),$(FW_BOARDS)),)

firmware firmware-run fw-run bench-target firmware-check profile-target firmware-sweep fw-dirs:
	@echo "tarn: no board '$(BOARD)'; the boards are: $(FW_BOARDS)" >&2; exit 1

else ifeq ($(filter $(FW_MAIN),main sweep),)

firmware firmware-run fw-run bench-target firmware-check profile-target firmware-sweep:
	@echo "tarn: no program FW_MAIN='$(FW_MAIN)'; expected main or sweep" >&2; exit 1

else ifeq ($(FW_MAIN)$(POINTS),sweep)

firmware firmware-run fw-run bench-target firmware-check profile-target firmware-sweep:
	@echo "tarn: the sweep needs POINTS=FILE: one line of quality options per point (docs/firmware.md)" >&2; exit 1

else

include boards/$(BOARD)/board.mk
# the board's board.mk and what it includes (boards/common/*.mk, another board's board.mk)
FW_BOARD_MK := $(filter boards/%,$(MAKEFILE_LIST))

ifeq ($(BOARD_SCENES),)
$(error tarn: boards/$(BOARD)/board.mk gives no BOARD_SCENES)
endif
# FW_BOARD_SCENE: which of the board's scenes this make builds (the first unless
# given); one not in the list is refused
FW_BOARD_SCENE ?= $(firstword $(BOARD_SCENES))
ifeq ($(filter $(FW_BOARD_SCENE),$(BOARD_SCENES)),)
$(error tarn: FW_BOARD_SCENE=$(FW_BOARD_SCENE) is not one of $(BOARD)'s scenes: $(BOARD_SCENES))
endif
# $(1): one of the board's scenes; its build's directory
fw_scene_dir = build/firmware/$(BOARD)$(if $(filter-out $(firstword $(BOARD_SCENES)),$(1)),@$(basename $(notdir $(1))))
# every scene in turn: a board of several scenes asked for itself (no SCENE,
# FW_BUILD_DIR or FW_BOARD_SCENE given)
FW_EACH_SCENE := $(if $(SCENE)$(FW_BUILD_DIR)$(filter-out file,$(origin FW_BOARD_SCENE)),,$(word 2,$(BOARD_SCENES)))
# FW_BUILD_DIR: another build directory, for builds of other scenes beside the board's own
FW_DIR := $(if $(FW_BUILD_DIR),$(FW_BUILD_DIR),$(if $(filter sweep,$(FW_MAIN)),build/firmware-sweep/$(BOARD),$(if \
	$(SCENE),build/firmware/$(BOARD),$(call fw_scene_dir,$(FW_BOARD_SCENE)))))
FW_SCENE := $(if $(SCENE),$(SCENE),$(FW_BOARD_SCENE))
FW_SCENE_LABEL := $(basename $(notdir $(FW_SCENE)))
# a scene's own flags and code budget, where the board gives them
fw_scene_value = $(if $(filter undefined,$(origin $(1).$(FW_SCENE_LABEL))),$($(1)),$($(1).$(FW_SCENE_LABEL)))
FW_BAKE_FLAGS := $(if $(SCENE),$(BAKE_FLAGS),$(if $(BAKE_FLAGS),$(BAKE_FLAGS),$(call fw_scene_value,BOARD_BAKE_FLAGS)))
FW_CODE_BYTES_MAX := $(call fw_scene_value,BOARD_CODE_BYTES_MAX)
# the sweep's points: baked with the scene (host/bake/bake_points.h)
FW_POINTS_FLAGS := $(if $(filter sweep,$(FW_MAIN)),--points $(POINTS))
FW_ELF := $(FW_DIR)/firmware.elf

ifeq ($(BOARD_ARCH),arm)
FW_CROSS := arm-none-eabi-
FW_CROSS_PKG := gcc-arm-none-eabi and libnewlib-arm-none-eabi
FW_LIBS := -lc -lgcc
FW_LIBC_SRC :=
else
FW_CROSS := riscv64-unknown-elf-
FW_CROSS_PKG := gcc-riscv64-unknown-elf
# the board's multilib (rv32imac/ilp32; rv32im/ilp32 for rv32imc, which has none of
# its own): named without _zicsr, since -march with it would select the default
# (rv64) one
FW_LIBS = $(shell $(FW_CROSS)gcc $(subst _zicsr,,$(BOARD_CPU)) -print-libgcc-file-name 2>/dev/null)
FW_LIBC_SRC := firmware/libc/string.c
FW_LIBC_INCLUDE := -Ifirmware/libc
endif
FW_QEMU_PKG := $(if $(filter qemu-system-arm,$(BOARD_QEMU)),qemu-system-arm,qemu-system-misc)

# Through ccache where it is installed (make test installs it): a board's builds of
# other scenes and qualities compile most of the core to the same objects.
FW_CCACHE := $(shell command -v ccache 2>/dev/null)
FW_CC := $(FW_CCACHE) $(FW_CROSS)gcc
FW_CFLAGS := -std=c99 -Wall -Wextra -Werror -O2 -g -ffreestanding -fno-common \
	-ffunction-sections -fdata-sections -fstack-usage $(BOARD_CPU) \
	-Icore -Icore/include -Ifirmware $(BOARD_INCLUDE) $(FW_LIBC_INCLUDE)
# The program: an emulated board runs the measured run and sends the panel stream
# through its writes; a real board shows the scene forever through SPI and DMA.
ifneq ($(value BOARD_RUN),)
FW_PROGRAM_SRC := firmware/$(if $(filter sweep,$(FW_MAIN)),sweep_main.c,main.c) firmware/report.c \
	firmware/stream_transport.c
else
FW_PROGRAM_SRC := firmware/display_main.c firmware/dma_transport.c
endif
FW_SRC := $(FW_PROGRAM_SRC) firmware/panel_sink.c $(FW_LIBC_SRC) $(BOARD_SRC) \
	$(wildcard core/*/*.c) $(FW_DIR)/scene.c
FW_OBJ := $(patsubst %,$(FW_DIR)/obj/%.o,$(basename $(patsubst $(FW_DIR)/%,%,$(FW_SRC))))

# A board that boots through a second stage (RP2040: BOARD_BOOT2, its 252 bytes of
# code) gets it checksummed by a host tool and placed in the .boot2 section; a board
# with BOARD_UF2_FAMILY gets firmware.uf2 besides firmware.elf.
FW_TOOLS := build/tools
FW_HOST_CC := cc
ifneq ($(BOARD_BOOT2),)
FW_OBJ += $(FW_DIR)/obj/boot2_crc.o
endif
FW_OUTPUTS := $(FW_ELF) $(if $(BOARD_UF2_FAMILY),$(FW_DIR)/firmware.uf2)

fw-dirs:
	@echo $(foreach s,$(BOARD_SCENES),$(call fw_scene_dir,$(s)))

ifneq ($(FW_EACH_SCENE),)
firmware firmware-run fw-run bench-target firmware-check:
	@for s in $(BOARD_SCENES); do $(MAKE) --no-print-directory $@ BOARD=$(BOARD) FW_BOARD_SCENE=$$s || exit 1; done
else
firmware: $(FW_OUTPUTS)
	@echo "$(FW_ELF): $$(firmware/image_sizes.sh $(FW_CROSS) $(FW_ELF))"

ifneq ($(value BOARD_RUN),)
fw-run: $(FW_DIR)/report.txt

# the run's figures from its report line ("target board=B scene=S size=WxH
# insn_per_pixel=N ..."): "B S WxH: insn_per_pixel=N render_insn_per_pixel=N
# stack_peak_bytes=N"; a report of another form as it is
firmware-run: fw-run
	@sed -e 's/^target board=\([^ ]*\) scene=\([^ ]*\) size=\([^ ]*\) /\1 \2 \3: /' \
		-e 's/ frame_insn=[^ ]*//' -e 's/ counter_check=[^ ]*//' -e q $(FW_DIR)/report.txt

bench-target: $(FW_DIR)/report.txt $(FW_ELF)
	@tests/check_firmware.sh --bench $(FW_DIR)

firmware-check: $(FW_DIR)/report.txt
	@tests/check_firmware.sh $(FW_DIR)
else
# a real board: built, never run here
fw-run: $(FW_OUTPUTS)

firmware-run: fw-run
	@echo "$(BOARD) is a real board: built ($(FW_OUTPUTS)), not run" >&2

bench-target: $(FW_OUTPUTS)
	@echo "$(BOARD) is a real board: no emulated run to measure" >&2

firmware-check: $(FW_OUTPUTS) $(FW_DIR)/firmware.conf
	@tests/check_firmware.sh $(FW_DIR)
endif
endif

ifneq ($(value BOARD_RUN),)
firmware-sweep: $(FW_DIR)/report.txt
	@cat $<

profile-target: $(FW_ELF) | fw-qemu
	@scripts/profile-target.py --top $(or $(TOP),30) $(foreach f,$(ANNOTATE),--annotate $(f)) --tools $(FW_CROSS) $(FW_ELF) -- \
		$(call BOARD_RUN,$(FW_ELF),$(FW_DIR)/profile.stream,$(FW_DIR)/profile.report)
else
profile-target firmware-sweep: $(FW_OUTPUTS)
	@echo "$(BOARD) is a real board: no emulated run to measure" >&2
endif

# what tests/check_firmware.sh and tests/test_firmware.c need to know about the build
$(FW_DIR)/firmware.conf: $(FW_BOARD_MK) firmware/firmware.mk FORCE
	@mkdir -p $(FW_DIR)
	@printf '%s\n' "board=$(BOARD)" "scene=$(FW_SCENE)" "label=$(FW_SCENE_LABEL)" \
		"bake_flags=$(FW_BAKE_FLAGS)" "times=$(FW_TIMES)" "stream_only=$(FW_STREAM_ONLY)" "cores=$(FW_CORES)" "core_split=$(FW_CORE_SPLIT)" "dither=1" "cross=$(FW_CROSS)" \
		"stack_bytes=$(BOARD_STACK_BYTES)" "stack_entry=$(BOARD_STACK_ENTRY)" "emulated=$(if $(value BOARD_RUN),1,0)" \
		"code_bytes_max=$(FW_CODE_BYTES_MAX)" "program=$(FW_MAIN)" "points=$(POINTS)" "ram_code=$(BOARD_RAM_CODE)" \
		"vertex_cache_slots=$(BOARD_VERTEX_CACHE_SLOTS)" > $@.tmp
	@if cmp -s $@.tmp $@; then rm $@.tmp; else mv $@.tmp $@; fi

.PHONY: FORCE fw-toolchain fw-qemu
FORCE:

fw-toolchain:
	@command -v $(FW_CROSS)gcc >/dev/null 2>&1 || { echo "tarn: $(FW_CROSS)gcc not found; install it: sudo apt-get install $(FW_CROSS_PKG)" >&2; exit 1; }

fw-qemu:
	@command -v $(BOARD_QEMU) >/dev/null 2>&1 || { echo "tarn: $(BOARD_QEMU) not found; install it: sudo apt-get install $(FW_QEMU_PKG)" >&2; exit 1; }

ifneq ($(TARN),$(FW_TARN))
$(FW_TARN): FORCE
	@$(MAKE) --no-print-directory BUILD=build/release SAN=0 $(FW_TARN)
endif

# The scene as const C: scene_scene, scene_config, SCENE_MEMORY_BYTES; scene_link.h
# holds the TARN_LINK_* switches that leave the effects the scene does not use out of
# the core's objects.
FW_BAKE := $(strip $(FW_TARN) bake $(FW_SCENE) -o $(FW_DIR)/scene.c --name scene $(FW_BAKE_FLAGS) $(FW_POINTS_FLAGS))
$(FW_DIR)/scene.c: $(FW_SCENE) $(FW_TARN) $(FW_DIR)/firmware.conf $(if $(FW_POINTS_FLAGS),$(POINTS)) | fw-toolchain
	@mkdir -p $(FW_DIR)
	$(call show,BAKE,$@)
	$(call show_command,$(FW_BAKE))
	@$(FW_BAKE) $(if $(Q),> /dev/null,>&2)

# The bake writes these; the empty recipe makes make look at their times again after
# it runs (a rule without one keeps the times from before the bake), so that
# scene_link.opts follows a bake that changed the switches.
$(FW_DIR)/scene.h $(FW_DIR)/scene_link.h: $(FW_DIR)/scene.c
	@:

# The core takes scene_link.h's switches as -D options (a response file), not as
# -include scene_link.h: the preprocessed source then names no file of this build,
# so a file the switches leave alone is the same object in every build, and ccache
# serves it from another.
$(FW_DIR)/scene_link.opts: $(FW_DIR)/scene_link.h
	@sed -n 's/^#define \(TARN_LINK_[A-Z0-9_]*\) \(.*\)$$/-D\1="\2"/p' $< > $@.tmp && mv $@.tmp $@

# The board's cores (BOARD_CORES in board.mk, 1 unless given): with more than one,
# the core is built with the code that shares a frame out (TARN_LINK_PARTS) and the
# measured run also renders the frame in that many parts (firmware/main.c).
# make profile-target counts one run of the streamed frames on one core
# (FW_STREAM_ONLY): no frame drawn again, alone or in parts, that the profile would
# count as the frame's own work.
FW_STREAM_ONLY := $(if $(filter profile-target,$(MAKECMDGOALS)),1,0)
FW_CORES := $(if $(filter 1,$(FW_STREAM_ONLY)),1,$(or $(BOARD_CORES),1))
FW_LINK_PARTS := $(if $(filter-out 1,$(FW_CORES)),1,0)
# How a board of two cores shares a frame out (BOARD_CORE_SPLIT, or
# BOARD_CORE_SPLIT.NAME for one of its scenes): "parts", memory of its own for each
# core (tarn_render_frame_part), unless given; or "pipeline", one ring of strips
# for both (tarn_strip_pipeline_begin), where two rings would not fit the RAM.
FW_CORE_SPLIT := $(or $(call fw_scene_value,BOARD_CORE_SPLIT),parts)
ifeq ($(filter parts pipeline,$(FW_CORE_SPLIT)),)
$(error BOARD_CORE_SPLIT of $(BOARD): "$(FW_CORE_SPLIT)"; expected parts or pipeline)
endif
FW_PIPELINE := $(if $(filter 1,$(FW_CORES)),0,$(if $(filter pipeline,$(FW_CORE_SPLIT)),1,0))
# The core's one setting that is not a switch (tarn_config.h): a board with RAM
# keeps more vertices in the walk's cache (BOARD_VERTEX_CACHE_SLOTS; 16 unless given).
FW_CORE_OBJ := $(filter $(FW_DIR)/obj/core/%,$(FW_OBJ))
$(FW_CORE_OBJ): $(FW_DIR)/scene_link.opts $(FW_DIR)/firmware.conf
$(FW_CORE_OBJ): FW_DEFINES = $(strip $(file < $(FW_DIR)/scene_link.opts)) -DTARN_LINK_PARTS=$(FW_LINK_PARTS) \
	$(if $(BOARD_VERTEX_CACHE_SLOTS),-DTARN_VERTEX_CACHE_SLOTS=$(BOARD_VERTEX_CACHE_SLOTS)u)

$(FW_OBJ): firmware/firmware.mk $(FW_BOARD_MK)
FW_MAIN_OBJ := $(patsubst %,$(FW_DIR)/obj/firmware/%.o,main sweep_main display_main)
$(FW_MAIN_OBJ): $(FW_DIR)/scene.h $(FW_DIR)/firmware.conf
$(FW_MAIN_OBJ): FW_DEFINES = -I$(FW_DIR) -DFW_SCENE_LABEL='"$(FW_SCENE_LABEL)"' -DFW_BOARD_NAME='"$(BOARD)"' -DFW_TIMES=$(FW_TIMES) \
	-DFW_PARTS=$(FW_CORES) -DFW_PIPELINE=$(FW_PIPELINE) -DFW_STREAM_ONLY=$(FW_STREAM_ONLY) -DFW_STACK_BYTES=$(BOARD_STACK_BYTES)
$(FW_DIR)/obj/firmware/libc/string.o: FW_DEFINES = -fno-builtin -fno-tree-loop-distribute-patterns -fno-strict-aliasing
# Code that runs once a frame, or once a water object a tile (the scene check and the
# backdrop's, the motion, the view and water setup, the camera's unit vectors, the presets, the report), is compiled for
# size (on top of the scene_link.h switches): it is far below 0.1% of the
# instructions, and -Os takes about 700 bytes off the M0's 32 KB. On a board with a
# code budget (BOARD_CODE_BYTES_MAX) so are the tile loop (core/frame/frame.c), once a
# tile, and the vertices' transform, clipping and projection (core/geometry/vertex.c,
# core/geometry/clip.c, core/geometry/project.c), which a static view mostly spares:
# -Os takes about 1,240 bytes more off for 4 instructions a pixel of the M0's pond;
# and the triangle setup (core/raster/triangle_setup.c), where -Os took 520 bytes
# and 6 instructions a pixel off, and 48 bytes off the deepest stack.
FW_SIZE_OBJ := $(patsubst %,$(FW_DIR)/obj/%.o,$(basename $(wildcard core/scene/*.c)) core/geometry/view core/math/normalise \
	core/water/water_setup core/water/underwater_setup core/frame/layout core/frame/status firmware/report \
	$(if $(BOARD_CODE_BYTES_MAX),core/frame/frame core/geometry/vertex core/geometry/clip core/geometry/project core/raster/triangle_setup))
$(FW_SIZE_OBJ): FW_DEFINES += -Os
# Where flash allows (a board without BOARD_CODE_BYTES_MAX), the stages that run
# once a pixel of water, a vertex, a triangle or a bin, and the arithmetic they
# call, are compiled for speed: -O3's inlining and unrolling take about 6% off the
# moving pond's instructions a pixel on qemu-m0-264k and about 2% off the opaque
# pond's, for about 4 KB of code. Not the opaque span loops (core/raster/raster.c):
# there -O3 made the opaque pond about 4% slower.
FW_SPEED_OBJ := $(if $(BOARD_CODE_BYTES_MAX),,$(filter-out $(FW_SIZE_OBJ),$(patsubst %.c,$(FW_DIR)/obj/%.o,\
	$(wildcard core/water/*.c core/math/*.c core/geometry/*.c core/tile/*.c) core/raster/triangle_setup.c)))
$(FW_SPEED_OBJ): FW_DEFINES += -O3
# Code a board runs from RAM (BOARD_RAM_CODE: folders or files of the core), where its
# flash is slow to fetch from: each object's sections are renamed .ram.* once it is
# compiled, and the link script copies them into RAM with .data at reset
# (boards/common/cortex_m_sections.ld). Calls between RAM and flash go through the
# linker's long-branch veneers: they are a frame's few, not a pixel's.
FW_RAM_OBJ := $(patsubst %.c,$(FW_DIR)/obj/%.o,$(foreach p,$(BOARD_RAM_CODE),$(if $(filter %.c,$(p)),$(p),$(wildcard $(p)/*.c))))
$(FW_RAM_OBJ): FW_PLACE = $(FW_CROSS)objcopy --prefix-alloc-sections=.ram $@

$(FW_DIR)/obj/%.o: %.c | fw-toolchain
	@mkdir -p $(dir $@)
	$(call show,CC,$@)
	$(Q)$(FW_CC) $(FW_CFLAGS) $(FW_DEFINES) -MMD -MP -c -o $@ $<
	$(if $(FW_PLACE),$(Q)$(FW_PLACE))

$(FW_DIR)/obj/%.o: $(FW_DIR)/%.c | fw-toolchain
	@mkdir -p $(dir $@)
	$(call show,CC,$@)
	$(Q)$(FW_CC) $(FW_CFLAGS) -MMD -MP -c -o $@ $<

$(FW_DIR)/obj/%.o: %.S | fw-toolchain
	@mkdir -p $(dir $@)
	$(call show,AS,$@)
	$(Q)$(FW_CC) $(BOARD_CPU) $(BOARD_INCLUDE) -MMD -MP -c -o $@ $<

# A link that overflows a memory region names the region and the bytes over; the
# note after it says what to change. A linked image whose deepest call chain
# (firmware/stack_bound.sh: the objects' calls and frames, no recursion allowed) needs more
# stack than the board reserves is refused too.
FW_LINK = $(FW_CROSS)gcc $(BOARD_CPU) -nostdlib -nostartfiles -T $(BOARD_LDSCRIPT) -Lboards/common \
	-Wl,--gc-sections -Wl,-Map=$(FW_DIR)/firmware.map -Wl,--defsym=__stack_size=$(BOARD_STACK_BYTES) \
	-o $(FW_ELF) $(FW_OBJ) $(FW_LIBS)
# Where each core's stack starts, for the bound below (firmware/stack_bound.sh's
# arguments): core 0's, and on a real board of two cores core 1's
# (BOARD_SECOND_STACK_ENTRY, display_main.c's), whose stack is as large.
FW_STACK_ENTRIES := "$(BOARD_STACK_ENTRY)" $(if $(BOARD_SECOND_STACK_ENTRY),"$(BOARD_SECOND_STACK_ENTRY)")
$(FW_ELF): $(FW_OBJ) $(BOARD_LDSCRIPT) $(wildcard boards/common/*.ld) | fw-toolchain
	$(call show,LD,$@)
	$(call show_command,$(FW_LINK))
	@if ! $(FW_LINK) 2> $(FW_DIR)/link.err; then \
		cat $(FW_DIR)/link.err >&2; \
		if grep -q "region .RAM. overflowed" $(FW_DIR)/link.err; then \
			echo "tarn: $(BOARD) has too little RAM for $(FW_SCENE) [$(strip $(FW_BAKE_FLAGS) $(FW_POINTS_FLAGS))]: the renderer needs" \
				"$$(sed -n 's/^#define SCENE_MEMORY_BYTES //p' $(FW_DIR)/scene.h) bytes and the stack $(BOARD_STACK_BYTES);" \
				"bake with a smaller --tile (or --depth 16, --apron off where they are not set yet;" \
				"tarn memory SCENE QUALITY shows the bytes)$(if $(findstring --static-view off,$(FW_BAKE_FLAGS)),;" \
				"without --static-view off the frame's cluster bins come from flash instead)" >&2; fi; \
		if grep -q "region .FLASH. overflowed" $(FW_DIR)/link.err; then \
			echo "tarn: $(BOARD)'s flash cannot hold $(FW_SCENE): use smaller textures or fewer mesh segments" \
				"$(if $(findstring --static-view off,$(FW_BAKE_FLAGS)),,(or bake with --static-view off: its meshes take less flash than static vertices and bins))" \
				"$(if $(findstring --backdrop on,$(FW_BAKE_FLAGS))$(findstring --backdrop still,$(FW_BAKE_FLAGS)),(or bake without --backdrop: its picture takes a palette index a pixel))" \
				"(the header of $(FW_DIR)/scene.c counts the bytes)" >&2; fi; \
		rm -f $@; exit 1; fi
	@cat $(FW_DIR)/link.err >&2; rm -f $(FW_DIR)/link.err
	@for entry in $(FW_STACK_ENTRIES); do \
	bound=$$(firmware/stack_bound.sh $(FW_CROSS) $(FW_DIR)/obj $$entry 2>&1 | sed -n 's/^stack_bytes=//p'); \
	if [ -z "$$bound" ] || [ "$$bound" -gt $(BOARD_STACK_BYTES) ]; then \
		firmware/stack_bound.sh $(FW_CROSS) $(FW_DIR)/obj $$entry >&2; \
		case $$entry in "$(BOARD_SECOND_STACK_ENTRY)") chain="core 1's deepest call chain";; *) chain="deepest call chain";; esac; \
		echo "tarn: $(BOARD)'s $$chain needs $${bound:-an unknown number of} bytes of stack;" \
			"it reserves $(BOARD_STACK_BYTES) (BOARD_STACK_BYTES in boards/$(BOARD)/board.mk)" >&2; \
		rm -f $@; exit 1; fi; done

# The host tools (firmware/tools/): the boot2 checksum and the UF2 writer.
$(FW_TOOLS)/%: firmware/tools/%.c
	@mkdir -p $(dir $@)
	$(call show,HOSTCC,$@)
	$(Q)$(FW_HOST_CC) -std=c99 -Wall -Wextra -Werror -O2 -o $@ $<

# boot2: assembled and linked where the bootrom runs it (it is position-independent
# anyway), cut to its bytes, then padded to 252 with the CRC32 the bootrom checks
# appended, as a .boot2 section.
$(FW_DIR)/boot2.bin: $(BOARD_BOOT2) boards/$(BOARD)/board.mk | fw-toolchain
	@mkdir -p $(dir $@)
	$(call show,LD,$(FW_DIR)/boot2.elf)
	$(Q)$(FW_CROSS)gcc $(BOARD_CPU) -nostdlib -nostartfiles -Wl,-Ttext=0x20041f00 -Wl,-e,boot2_entry -o $(FW_DIR)/boot2.elf $<
	$(call show,OBJCOPY,$@)
	$(Q)$(FW_CROSS)objcopy -O binary -j .text $(FW_DIR)/boot2.elf $@

$(FW_TOOLS)/boot2_crc: firmware/tools/crc32_boot2.h

$(FW_DIR)/boot2_crc.S: $(FW_DIR)/boot2.bin $(FW_TOOLS)/boot2_crc
	$(call show,GEN,$@)
	$(Q)$(FW_TOOLS)/boot2_crc $< $@

$(FW_DIR)/obj/boot2_crc.o: $(FW_DIR)/boot2_crc.S | fw-toolchain
	@mkdir -p $(dir $@)
	$(call show,AS,$@)
	$(Q)$(FW_CC) $(BOARD_CPU) -c -o $@ $<

# UF2 for a bootloader that takes files (RP2040: hold BOOTSEL, copy the file): the
# flash image from its lowest load address, in 256-byte blocks.
$(FW_DIR)/firmware.uf2: $(FW_ELF) $(FW_TOOLS)/uf2
	$(call show,OBJCOPY,$(FW_DIR)/firmware.bin)
	$(Q)$(FW_CROSS)objcopy -O binary $(FW_ELF) $(FW_DIR)/firmware.bin
	$(call show,UF2,$@)
	$(Q)$(FW_TOOLS)/uf2 $(FW_DIR)/firmware.bin $(BOARD_FLASH_BASE) $(BOARD_UF2_FAMILY) $@

# One emulated run. QEMU's exit status is the firmware's.
$(FW_DIR)/report.txt: $(FW_ELF) | fw-qemu
	@rm -f $@ $@.tmp $(FW_DIR)/panel.stream $(FW_DIR)/panel.stream.tmp
	$(call show,RUN,$(FW_DIR) ($(BOARD_QEMU) -icount shift=0))
	$(call show_command,timeout $(FW_TIMEOUT) $(call BOARD_RUN,$(FW_ELF),$(FW_DIR)/panel.stream.tmp,$@.tmp))
	@timeout $(FW_TIMEOUT) $(call BOARD_RUN,$(FW_ELF),$(FW_DIR)/panel.stream.tmp,$@.tmp) \
		< /dev/null; status=$$?; \
	if [ $$status -ne 0 ]; then echo "tarn: $(BOARD) exited with status $$status" \
		"$$( [ $$status -eq 124 ] && echo '(timed out after $(FW_TIMEOUT) s)')" >&2; \
		cat $@.tmp >&2 2>/dev/null; exit 1; fi
	@mv $(FW_DIR)/panel.stream.tmp $(FW_DIR)/panel.stream && mv $@.tmp $@

-include $(FW_OBJ:.o=.d)

endif
