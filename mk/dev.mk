# mk/dev.mk - developer targets: fuzzing with libFuzzer and static analysis (lint);
# included by the Makefile.

# Fuzzing with libFuzzer (clang): `make fuzz FUZZ_SECONDS=600` (FUZZ_TYPE=fixed fuzzes
# the Q16.16 build). New inputs collect in build/fuzz/new; `make fuzz-merge` minimises
# them into tests/fuzz/corpus.
FUZZ_SECONDS ?= 60
FUZZ_TYPE ?= double
FUZZ_CC ?= clang
FUZZ_FLAGS = -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -g -O1 \
	     $(CLANG_MODEL)
build/fuzz/fuzz-scene-%: $(LIB_SRC) tests/fuzz/fuzz_scene.c $(HDR)
	@sh tools/need $(FUZZ_CC) clang
	$(call whole-program,$(FUZZ_CC),-std=c99 -Wall -Wextra -Werror -ffp-contract=off $(FUZZ_FLAGS) \
		$(filter -D%,$(VARIANT_FLAGS_$*)) -Isrc,$(LIB_SRC) tests/fuzz/fuzz_scene.c,-lm)
build/fuzz/fuzz-scene: build/fuzz/fuzz-scene-double
	cp build/fuzz/fuzz-scene-double $@

# No resident-memory limit (-rss_limit_mb=0): AddressSanitizer's shadow of rt's static
# arrays is resident past libFuzzer's default 2 GiB from the first input, which it would
# report as out of memory; rt allocates nothing, so the limit would find nothing.
FUZZ_RUN_FLAGS = -max_len=65536 -rss_limit_mb=0
fuzz: build/fuzz/fuzz-scene-$(FUZZ_TYPE)
	@mkdir -p build/fuzz/new build/fuzz/crashes
	build/fuzz/fuzz-scene-$(FUZZ_TYPE) -max_total_time=$(FUZZ_SECONDS) $(FUZZ_RUN_FLAGS) \
		-timeout=10 -artifact_prefix=build/fuzz/crashes/ -dict=tests/fuzz/nff.dict \
		build/fuzz/new tests/fuzz/corpus

fuzz-merge: build/fuzz/fuzz-scene
	build/fuzz/fuzz-scene -merge=1 $(FUZZ_RUN_FLAGS) tests/fuzz/corpus build/fuzz/new

# Static analysis of src/: cppcheck and clang-tidy, each clean with a short suppression
# list that says why (tests/lint/cppcheck.supp, .clang-tidy). Installs the tools from
# Debian's packages when they are missing (tools/need).
CPPCHECK ?= cppcheck
CLANG_TIDY ?= clang-tidy
# cppcheck checks the floating-point configurations, then Q16.16 fixed point on its own.
CPPCHECK_FLAGS = --enable=warning,style,performance,portability --std=c99 --error-exitcode=1 \
	--inline-suppr --suppressions-list=tests/lint/cppcheck.supp \
	--quiet -Isrc
lint:
	@sh tools/need $(CPPCHECK) cppcheck
	@sh tools/need $(CLANG_TIDY) clang-tidy
	$(CPPCHECK) $(CPPCHECK_FLAGS) -URT_REAL_FIXED $(SRC)
	$(CPPCHECK) $(CPPCHECK_FLAGS) -DRT_REAL_FIXED $(SRC)
	@# The microcontroller's own files, as its build sees them (clang-tidy is left out:
	@# their inline assembly names ARM registers, which a host parse rejects).
	$(CPPCHECK) $(CPPCHECK_FLAGS) -Isrc/mcu $(MCU_DEFINES) $(wildcard src/mcu/*.c)
	@# Its stderr counts the warnings it found and dropped (system headers, disabled
	@# checks) per file: kept out of the way, the rest shown, the status kept.
	@mkdir -p build
	$(CLANG_TIDY) --quiet $(SRC) -- -std=c99 -Isrc 2>build/clang-tidy.err; \
	status=$$?; grep -v 'warnings* generated\.$$' build/clang-tidy.err >&2; exit $$status
	@echo "lint: clean"

.PHONY: fuzz fuzz-merge lint
