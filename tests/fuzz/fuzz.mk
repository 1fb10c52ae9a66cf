# fuzz.mk: the libFuzzer targets (clang from Debian), included by the Makefile.
#
#   make fuzz [FUZZ_SECONDS=600]   runs each target for FUZZ_SECONDS, its corpus
#                                  growing in build/fuzz/corpus/TARGET; a finding
#                                  stops the run and leaves build/fuzz/TARGET-crash-*
#   make fuzz-replay               (part of make test) runs every input of the seed
#                                  corpora in tests/fuzz/corpus/ once, then each
#                                  target for FUZZ_SHORT_SECONDS from them
#
# Every target is built with AddressSanitizer and UndefinedBehaviorSanitizer, every
# report fatal. A target's seeds are the files in tests/fuzz/corpus/TARGET/; a finding
# worth keeping is copied there with a name that says what it was.

FUZZ_TARGETS := fuzz_scene_load fuzz_obj_load fuzz_png_texture fuzz_bake fuzz_core
FUZZ_SECONDS ?= 600
FUZZ_SHORT_SECONDS ?= 8
FUZZ_DIR := build/fuzz
FUZZ_CC := clang
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
FUZZ_CFLAGS := -std=c99 -Wall -Wextra -Werror -g -O1 $(FUZZ_SAN) -fsanitize=fuzzer-no-link -D_POSIX_C_SOURCE=200809L \
	$(HOST_INCLUDES) -Itests/fuzz $(shell pkg-config --cflags $(HOST_PKGS) 2>/dev/null)
FUZZ_LIB_OBJ := $(CORE_SRC:%.c=$(FUZZ_DIR)/%.o) $(HOST_SRC:%.c=$(FUZZ_DIR)/%.o) $(FUZZ_DIR)/tests/fuzz/fuzz_input.o
FUZZ_BIN := $(FUZZ_TARGETS:%=$(FUZZ_DIR)/%)
# libFuzzer's options for every run: a slow input is a finding (the renderer must
# not hang), as is one that needs more than 1 GB.
FUZZ_OPTIONS := -timeout=20 -rss_limit_mb=1024 -print_final_stats=1

.PHONY: fuzz fuzz-replay fuzz-build fuzz-deps

fuzz-deps:
	@command -v $(FUZZ_CC) >/dev/null 2>&1 || { echo "tarn: clang not found; install it: sudo apt-get install clang libclang-rt-14-dev" >&2; exit 1; }

fuzz-build: fuzz-deps $(FUZZ_BIN)

$(FUZZ_DIR)/%.o: %.c | fuzz-deps
	@mkdir -p $(dir $@)
	$(call show,CC,$@)
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) -MMD -MP -c -o $@ $<

$(FUZZ_DIR)/fuzz_%: $(FUZZ_DIR)/tests/fuzz/fuzz_%.o $(FUZZ_LIB_OBJ)
	$(call show,LD,$@)
	$(Q)$(FUZZ_CC) $(FUZZ_SAN) -fsanitize=fuzzer -o $@ $^ $(HOST_LIBS)

# Each target's line says which of them it is and when it and the whole run end, so
# that an hour's run shows how far it has come.
fuzz: fuzz-build
	@n=0; count=$(words $(FUZZ_TARGETS)); for t in $(FUZZ_TARGETS); do \
		n=$$((n + 1)); now=$$(date +%s); \
		mkdir -p $(FUZZ_DIR)/corpus/$$t || exit 1; \
		echo "== $$t ($$n of $$count) for $(FUZZ_SECONDS) s: ends about $$(date -d @$$((now + $(FUZZ_SECONDS))) +%H:%M)," \
			"the last target about $$(date -d @$$((now + (count - n + 1) * $(FUZZ_SECONDS))) +%H:%M)"; \
		$(FUZZ_DIR)/$$t $(FUZZ_OPTIONS) -max_total_time=$(FUZZ_SECONDS) -artifact_prefix=$(FUZZ_DIR)/$$t- \
			$(FUZZ_DIR)/corpus/$$t tests/fuzz/corpus/$$t > $(FUZZ_DIR)/$$t.log 2>&1; \
		status=$$?; grep -E "^stat::|^Done|ERROR|SUMMARY" $(FUZZ_DIR)/$$t.log | tail -8; \
		[ $$status -eq 0 ] || { echo "FAIL: $$t found something: $(FUZZ_DIR)/$$t.log"; exit 1; }; \
	done

fuzz-replay: fuzz-build
	@for t in $(FUZZ_TARGETS); do \
		$(FUZZ_DIR)/$$t $(FUZZ_OPTIONS) -runs=0 tests/fuzz/corpus/$$t > $(FUZZ_DIR)/$$t.replay.log 2>&1 || \
			{ tail -30 $(FUZZ_DIR)/$$t.replay.log; echo "FAIL: $$t: a seed of tests/fuzz/corpus/$$t"; exit 1; }; \
		mkdir -p $(FUZZ_DIR)/short/$$t; \
		$(FUZZ_DIR)/$$t $(FUZZ_OPTIONS) -max_total_time=$(FUZZ_SHORT_SECONDS) -artifact_prefix=$(FUZZ_DIR)/$$t- \
			$(FUZZ_DIR)/short/$$t tests/fuzz/corpus/$$t > $(FUZZ_DIR)/$$t.short.log 2>&1 || \
			{ tail -30 $(FUZZ_DIR)/$$t.short.log; echo "FAIL: $$t: a finding in $(FUZZ_SHORT_SECONDS) s"; exit 1; }; \
		echo "fuzz $$t: $$(ls tests/fuzz/corpus/$$t | wc -l) seeds replayed, $$(sed -n 's/^stat::number_of_executed_units: *//p' $(FUZZ_DIR)/$$t.short.log) inputs in $(FUZZ_SHORT_SECONDS) s, no finding"; \
	done

-include $(shell find $(FUZZ_DIR) -name '*.d' 2>/dev/null)
