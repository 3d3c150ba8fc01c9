# rt - a minimal recursive ray tracer. `make` builds ./rt, `make test` runs every test.
# The user owns CC, CFLAGS, CPPFLAGS, LDFLAGS and LDLIBS; rt's own flags come first.

PREFIX ?= /usr/local
BINDIR = $(PREFIX)/bin
MANDIR = $(PREFIX)/share/man/man1

CC ?= cc
CFLAGS ?= -O2
WARN = -std=c99 -pedantic -Wall -Wextra -Wshadow -Wdouble-promotion -Wstrict-prototypes \
       -Wmissing-prototypes -Wpointer-arith -Wcast-qual -Wvla -Werror
# No FMA contraction: the hard cases are decided by rounding (numerics.md section 9).
RT_CFLAGS = $(WARN) -ffp-contract=off -MMD -MP
LDLIBS ?=
RT_LDLIBS = -lm

SRC = $(wildcard src/*.c)
LIB_SRC = $(filter-out src/main.c,$(SRC))
OBJ = $(SRC:src/%.c=build/obj/%.o)
LIB_OBJ = $(LIB_SRC:src/%.c=build/obj/%.o)

HDR = $(wildcard src/*.h)
TEST_SRC = $(wildcard tests/*.c)
TEST_HDR = $(wildcard tests/*.h)
TEST_OBJ = $(TEST_SRC:tests/%.c=build/obj/tests/%.o)
# The corpus replay: the fuzz harness's entry point (tests/fuzz/fuzz_scene.c) fed files.
REPLAY_SRC = $(LIB_SRC) tests/fuzz/fuzz_scene.c tests/fuzz/replay.c
LINK_LIBS = $(LDLIBS) $(RT_LDLIBS)

# Besides the file-by-file builds (rt, the unit tests in double and Q16.16), every build
# (number types, sanitizers, clang, fuzzing, the microcontroller) is a whole program in
# one compiler call, made by this one recipe:
# $(call whole-program,COMPILER,FLAGS,SOURCES,LIBRARIES) builds $@.
define whole-program
@mkdir -p $(@D)
$(1) $(2) -o $@ $(3) $(4)
endef

# `make test` runs the MCU tests too (tests/mcu.sh) when the cross compiler is there.
MCU_CC ?= arm-none-eabi-gcc
MCU_TEST = $(if $(shell command -v $(MCU_CC)),mcu-ready)

all: rt

rt: $(OBJ)
	$(CC) $(LDFLAGS) -o $@ $(OBJ) $(LDLIBS) $(RT_LDLIBS)

build/obj/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

build/obj/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) -Isrc $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

build/unit-tests: $(TEST_OBJ) $(LIB_OBJ)
	$(CC) $(LDFLAGS) -o $@ $(TEST_OBJ) $(LIB_OBJ) $(LDLIBS) $(RT_LDLIBS)

# The sanitizer build of everything, for the test run.
SAN_FLAGS = -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g
# A name ending in -fixed is the Q16.16 build ($* is then -fixed).
SAN_CFLAGS = $(RT_CFLAGS) $(SAN_FLAGS) $(if $*,-DRT_REAL_FIXED)
build/san/rt: $(SRC) $(HDR)
	$(call whole-program,$(CC),$(RT_CFLAGS) $(SAN_FLAGS) $(CPPFLAGS) -O1,$(SRC),$(LINK_LIBS))
# The fixed-point unit tests under the sanitizers too (integer overflow is what they
# would catch there).
build/san/unit-tests build/san/unit-tests-fixed: build/san/unit-tests%: $(SRC) $(TEST_SRC) \
		$(HDR) $(TEST_HDR)
	$(call whole-program,$(CC),$(SAN_CFLAGS) -Isrc $(CPPFLAGS) -O1,$(LIB_SRC) $(TEST_SRC),$(LINK_LIBS))
build/san/replay build/san/replay-fixed: build/san/replay%: $(REPLAY_SRC) $(HDR)
	$(call whole-program,$(CC),$(SAN_CFLAGS) -Isrc $(CPPFLAGS) -O1,$(REPLAY_SRC),$(LINK_LIBS))

# MemorySanitizer (reads of uninitialised memory, which ASan cannot see) where clang is
# present: unit tests, the corpus replay and the fixed-point program, in double and Q16.16.
MSAN_CC ?= clang
MSAN_FLAGS = -fsanitize=memory -fsanitize-memory-track-origins -fno-omit-frame-pointer -g -O1
MSAN_BUILDS = build/msan/unit-tests build/msan/unit-tests-fixed build/msan/replay \
	build/msan/replay-fixed build/msan/rt-fixed
MSAN_TEST = $(if $(shell command -v $(MSAN_CC)),$(MSAN_BUILDS))
MSAN_CFLAGS = $(WARN) -ffp-contract=off $(MSAN_FLAGS) $(if $*,-DRT_REAL_FIXED)
build/msan/unit-tests build/msan/unit-tests-fixed: build/msan/unit-tests%: $(SRC) $(TEST_SRC) \
		$(HDR) $(TEST_HDR)
	$(call whole-program,$(MSAN_CC),$(MSAN_CFLAGS) -Isrc,$(LIB_SRC) $(TEST_SRC),-lm)
build/msan/replay build/msan/replay-fixed: build/msan/replay%: $(REPLAY_SRC) $(HDR)
	$(call whole-program,$(MSAN_CC),$(MSAN_CFLAGS) -Isrc,$(REPLAY_SRC),-lm)
build/msan/rt-fixed: $(SRC) $(HDR)
	$(call whole-program,$(MSAN_CC),$(WARN) -ffp-contract=off $(MSAN_FLAGS) -DRT_REAL_FIXED,$(SRC),-lm)

# One source, several builds: the number types and the naive algorithm forms, each a
# whole program built in one compiler call (build/rt-NAME).
VARIANT_FLAGS_float = -DRT_REAL_FLOAT
VARIANT_FLAGS_double = -DRT_REAL_DOUBLE
VARIANT_FLAGS_ref = -DRT_REAL_LONG_DOUBLE
# The fixed-point build has no floating point at all: on x86-64 the compiler proves it
# (-mgeneral-regs-only refuses any float), and it needs no libm.
VARIANT_FLAGS_fixed = -DRT_REAL_FIXED $(if $(filter x86_64,$(shell uname -m)),-mgeneral-regs-only)
# For hosts with little address space (README, "Memory"): a 16 MiB PNG arena (PNG up to
# 640x480 and a little more) and 4,096 objects.
VARIANT_FLAGS_small = -DRT_REAL_DOUBLE -DRT_PNG_ARENA_BYTES=16777216L -DRT_MAX_OBJECTS=4096
VARIANT_FLAGS_sphere-textbook = -DRT_REAL_DOUBLE -DRT_SPHERE_TEXTBOOK=1
VARIANT_FLAGS_hedron-per-face = -DRT_REAL_DOUBLE -DRT_HEDRON_PER_FACE=1
VARIANT_FLAGS_offset-fixed = -DRT_REAL_DOUBLE -DRT_OFFSET_FIXED=1
VARIANT_FLAGS_float-textbook = -DRT_REAL_FLOAT -DRT_SPHERE_TEXTBOOK=1
VARIANT_FLAGS_float-per-face = -DRT_REAL_FLOAT -DRT_HEDRON_PER_FACE=1
VARIANT_FLAGS_float-offset-fixed = -DRT_REAL_FLOAT -DRT_OFFSET_FIXED=1
TYPES = float double ref fixed
ALGORITHMS = sphere-textbook hedron-per-face offset-fixed float-textbook float-per-face \
	     float-offset-fixed
VARIANT_CFLAGS = $(WARN) -ffp-contract=off $(VARIANT_FLAGS_$*)

variants: $(TYPES:%=build/rt-%)

# The same strict warnings with clang (installed with apt-get if missing), every type.
build/clang/rt-%: $(SRC) $(HDR)
	@command -v clang >/dev/null || { apt-get update && apt-get install -y clang; }
	$(call whole-program,clang,$(VARIANT_CFLAGS) -O2,$(SRC),-lm)
check-clang: $(TYPES:%=build/clang/rt-%)

# The unit tests in every number type (each type's tolerances are in the tests).
build/unit-tests-%: $(LIB_SRC) $(TEST_SRC) $(HDR) $(TEST_HDR)
	$(call whole-program,$(CC),$(RT_CFLAGS) $(VARIANT_FLAGS_$*) -Isrc $(CPPFLAGS) $(CFLAGS), \
		$(LIB_SRC) $(TEST_SRC),$(LINK_LIBS))
# Q16.16: the library is built as build/rt-fixed is, with no floating point
# (-mgeneral-regs-only on x86-64), file by file into build/fixed/. The tests themselves
# cannot do without it: they build their reference rays, rotations and expected values
# in double and compare through test.h's double checks. So the test files are built
# with -DRT_REAL_FIXED but without -mgeneral-regs-only, and linked with that library.
FIXED_LIB_OBJ = $(LIB_SRC:src/%.c=build/fixed/%.o)
FIXED_TEST_OBJ = $(TEST_SRC:tests/%.c=build/fixed/tests/%.o)
build/fixed/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(VARIANT_FLAGS_fixed) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<
build/fixed/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(filter -D%,$(VARIANT_FLAGS_fixed)) -Isrc $(CPPFLAGS) $(CFLAGS) -c -o $@ $<
build/unit-tests-fixed: $(FIXED_TEST_OBJ) $(FIXED_LIB_OBJ)
	$(CC) $(LDFLAGS) -o $@ $(FIXED_TEST_OBJ) $(FIXED_LIB_OBJ) $(LDLIBS) $(RT_LDLIBS)
algorithms: $(ALGORITHMS:%=build/rt-%)

build/rt-%: $(SRC) $(HDR)
	$(call whole-program,$(CC),$(VARIANT_CFLAGS) $(CPPFLAGS) $(CFLAGS),$(SRC),$(LINK_LIBS))

test: rt build/unit-tests build/san/rt build/san/unit-tests build/san/replay build/san/replay-fixed \
      build/unit-tests-float build/unit-tests-ref build/unit-tests-fixed build/san/unit-tests-fixed build/rt-fixed build/rt-ref \
      build/rt-float build/rt-small $(MSAN_TEST) $(MCU_TEST)
	@sh tests/run.sh

# Fuzzing with libFuzzer (clang): `make fuzz FUZZ_SECONDS=600` (FUZZ_TYPE=fixed fuzzes
# the Q16.16 build). New inputs collect in build/fuzz/new; `make fuzz-merge` minimises
# them into tests/fuzz/corpus.
FUZZ_SECONDS ?= 60
FUZZ_TYPE ?= double
FUZZ_CC ?= clang
FUZZ_FLAGS = -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -g -O1
build/fuzz/fuzz-scene-%: $(LIB_SRC) tests/fuzz/fuzz_scene.c $(HDR)
	@command -v $(FUZZ_CC) >/dev/null || { apt-get update && apt-get install -y clang; }
	$(call whole-program,$(FUZZ_CC),-std=c99 -Wall -Wextra -Werror -ffp-contract=off $(FUZZ_FLAGS) \
		$(filter -D%,$(VARIANT_FLAGS_$*)) -Isrc,$(LIB_SRC) tests/fuzz/fuzz_scene.c,-lm)
build/fuzz/fuzz-scene: build/fuzz/fuzz-scene-double
	cp build/fuzz/fuzz-scene-double $@

fuzz: build/fuzz/fuzz-scene-$(FUZZ_TYPE)
	@mkdir -p build/fuzz/new build/fuzz/crashes
	build/fuzz/fuzz-scene-$(FUZZ_TYPE) -max_total_time=$(FUZZ_SECONDS) -max_len=65536 \
		-timeout=10 -artifact_prefix=build/fuzz/crashes/ -dict=tests/fuzz/nff.dict \
		build/fuzz/new tests/fuzz/corpus

fuzz-merge: build/fuzz/fuzz-scene
	build/fuzz/fuzz-scene -merge=1 -max_len=65536 tests/fuzz/corpus build/fuzz/new

# Static analysis of src/: cppcheck and clang-tidy, each clean with a short suppression
# list that says why (tests/lint/cppcheck.supp, .clang-tidy). Installs the tools from
# Debian's packages when they are missing.
CPPCHECK ?= cppcheck
CLANG_TIDY ?= clang-tidy
# cppcheck checks the floating-point configurations, then Q16.16 fixed point on its own.
CPPCHECK_FLAGS = --enable=warning,style,performance,portability --std=c99 --error-exitcode=1 \
	--inline-suppr --suppressions-list=tests/lint/cppcheck.supp --config-exclude=src/vendor \
	--quiet -Isrc
lint:
	@command -v $(CPPCHECK) >/dev/null || { apt-get update && apt-get install -y cppcheck; }
	@command -v $(CLANG_TIDY) >/dev/null || { apt-get update && apt-get install -y clang-tidy; }
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

# The microcontroller build: the fixed-point renderer, freestanding (no C library: its
# own semihosting layer in src/mcu/), for a Cortex-M0 (qemu `microbit`, 16 KiB RAM) and
# a Cortex-M3 (qemu `mps2-an385`, given the same 16 KiB). `make test-mcu` runs it under
# qemu and compares its output with build/rt-fixed; docs/mcu.md has the budgets.
MCU_HOST_ONLY = src/main.c src/output.c src/term.c src/png.c src/stdio_io.c src/bvh.c
# The C library stand-ins are built apart, without link-time optimisation: the calls to
# memcpy and memset the compiler itself emits must find them after it.
MCU_LIBC = src/mcu/libc.c
MCU_SRC = $(filter-out $(MCU_HOST_ONLY),$(SRC)) $(filter-out $(MCU_LIBC),$(wildcard src/mcu/*.c))
# Capacities for 16 KiB of RAM: the scene, row buffers and stack must all fit.
MCU_CAPACITIES = -DRT_MAX_OBJECTS=24 -DRT_MAX_LIGHTS=4 -DRT_MAX_MATERIALS=8 \
	-DRT_MAX_VERTICES=32 -DRT_MAX_POLY_VERTS=16 -DRT_MAX_PLANES=40 -DRT_MAX_HEDRON_PLANES=12 \
	-DRT_MAX_WIDTH=160 -DRT_MAX_HEIGHT=160 -DRT_MAX_SCENE_WIDTH=8192 -DRT_MAX_SCENE_HEIGHT=8192 \
	-DRT_MAX_MEDIA=4 -DRT_CORNER_SAMPLING=0 -DRT_SHAPE_CONE=0 -DRT_SHAPE_PATCH=0 \
	-DRT_PREVIEW_COLOR=0
MCU_DEFINES = -DRT_REAL_FIXED -DRT_USE_BVH=0 $(MCU_CAPACITIES)
# -fsigned-char: plain char as on the x86-64 host, so both builds read bytes alike.
# --param max-completely-peel-times=1: loops of a few passes (the parser's over three
# axes, in 64-bit arithmetic) stay loops; unrolled they cost 184 bytes of M0 flash, and
# the renderer's instructions per pixel are the same. -fno-tree-forwprop -fipa-pta
# -fno-move-loop-invariants -fno-early-inlining: 348 bytes less M0 flash (measured each
# alone and together) for 0.4 % more instructions per pixel (mcu-demo, mcu-glass), and a
# smaller worst-case stack. -fno-tree-fre -fno-ipa-pure-const: 68 bytes more, and the
# instructions per pixel back to within 0.1 % of what they were.
MCU_CFLAGS = $(WARN) -Os -fno-inline-small-functions -fno-jump-tables --param max-completely-peel-times=1 \
	-fno-tree-forwprop -fipa-pta -fno-move-loop-invariants -fno-early-inlining \
	-fno-tree-fre -fno-ipa-pure-const -mthumb -mfloat-abi=soft -ffreestanding -fsigned-char \
	-ffunction-sections -fdata-sections -Isrc -Isrc/mcu $(MCU_DEFINES)
# The whole program is optimised as one unit (-flto, one partition): 23% less flash than
# file by file. Its stack use per function and call graph land in build/mcu/CPU/ for
# tools/mcu-stack.
MCU_LINK = -nostdlib -nostartfiles -Wl,--gc-sections -Lsrc/mcu
MCU_LDFLAGS = -flto -flto-partition=one -fstack-usage -fcallgraph-info=su $(MCU_LINK)
MCU_CPU_m0 = cortex-m0
MCU_CPU_m3 = cortex-m3
MCU_BOARD_m0 = microbit
MCU_BOARD_m3 = mps2-an385
MCU_MAP = -Wl,-Map=$(@:.elf=.map)

build/mcu/m0/libc.o build/mcu/m3/libc.o: build/mcu/%/libc.o: $(MCU_LIBC) | mcu-tools
	@mkdir -p $(@D)
	$(MCU_CC) $(MCU_CFLAGS) -mcpu=$(MCU_CPU_$*) -c -o $@ $(MCU_LIBC)
# A build with a scene compiled in (tools/scene2c), for a board with no host to read
# files from: `make mcu-builtin SCENE=scenes/X.nff` makes build/mcu/rt-m0-builtin.elf,
# which renders it when no scene is named.
SCENE ?= scenes/mcu-demo.nff
build/mcu/builtin-scene.c: $(SCENE) tools/scene2c FORCE
	@mkdir -p $(@D)
	python3 tools/scene2c $(SCENE) $@.new
	@cmp -s $@.new $@ && rm $@.new || mv $@.new $@
build/mcu/rt-m0-builtin.elf: $(MCU_SRC) $(wildcard src/*.h src/mcu/*.h) build/mcu/m0/libc.o \
		build/mcu/builtin-scene.c src/mcu/sections.ld src/mcu/microbit.ld
	$(call whole-program,$(MCU_CC),$(MCU_CFLAGS) -mcpu=$(MCU_CPU_m0) -DRT_BUILTIN_SCENE=1 -flto \
		$(filter-out -fstack-usage -fcallgraph-info=su,$(MCU_LDFLAGS)) -T microbit.ld,$(MCU_SRC) \
		build/mcu/builtin-scene.c build/mcu/m0/libc.o,-lgcc)
mcu-builtin: build/mcu/rt-m0-builtin.elf
FORCE:

.SECONDEXPANSION:
build/mcu/rt-%.elf: $(MCU_SRC) $(wildcard src/*.h src/mcu/*.h) build/mcu/%/libc.o \
		src/mcu/sections.ld src/mcu/$$(MCU_BOARD_$$*).ld
	@mkdir -p build/mcu/$*
	rm -f build/mcu/$*/*.ci build/mcu/$*/*.su
	$(call whole-program,$(MCU_CC),$(MCU_CFLAGS) -mcpu=$(MCU_CPU_$*) -flto $(MCU_LDFLAGS) \
		-T $(MCU_BOARD_$*).ld $(MCU_MAP) -dumpdir build/mcu/$*/,$(MCU_SRC) build/mcu/$*/libc.o,-lgcc)

mcu: build/mcu/rt-m0.elf build/mcu/rt-m3.elf

# The fixed-point kernels' unit tests on each board (tests/mcu/kernels.c): fixed.h's
# Thumb-1 assembly is compiled only there. Not optimised as one unit: only the kernels
# and their tests are in it.
MCU_KERNEL_SRC = tests/mcu/kernels.c tests/test_fixed.c src/fixed.c src/mcu/startup.c \
	src/mcu/semihost.c
build/mcu/kernels-%.elf: $(MCU_KERNEL_SRC) src/fixed.h tests/test.h build/mcu/%/libc.o \
		src/mcu/sections.ld src/mcu/$$(MCU_BOARD_$$*).ld
	$(call whole-program,$(MCU_CC),$(MCU_CFLAGS) -Itests -mcpu=$(MCU_CPU_$*) $(MCU_LINK) \
		-T $(MCU_BOARD_$*).ld,$(MCU_KERNEL_SRC) build/mcu/$*/libc.o,-lgcc)

# The instruction-counting qemu plugin (tools/mcu-cost), built for the host.
build/mcu/insncount.so: tools/mcu/insncount.c
	$(call whole-program,$(CC),-O2 -Wall -Wextra -shared -fPIC,tools/mcu/insncount.c,)

# The host's twin of the MCU build (build/rt-fixed-mcu, made as the other variants are):
# the same capacities and switches, for comparing every scene of tests/bad and tests/good
# byte for byte (messages included).
VARIANT_FLAGS_fixed-mcu = $(VARIANT_FLAGS_fixed) $(MCU_DEFINES)

# qemu-system-arm is installed from Debian's packages when missing.
mcu-ready: mcu mcu-builtin build/mcu/kernels-m0.elf build/mcu/kernels-m3.elf build/rt-fixed \
		build/rt-fixed-mcu
	@command -v qemu-system-arm >/dev/null || { apt-get update && apt-get install -y qemu-system-arm; }
# The cross compiler and the C headers it needs, likewise.
mcu-tools:
	@command -v $(MCU_CC) >/dev/null || { apt-get update && \
		apt-get install -y gcc-arm-none-eabi libnewlib-arm-none-eabi; }
test-mcu: mcu-ready
	@sh tests/mcu.sh


install: rt
	mkdir -p $(DESTDIR)$(BINDIR) $(DESTDIR)$(MANDIR)
	cp rt $(DESTDIR)$(BINDIR)/rt
	chmod 755 $(DESTDIR)$(BINDIR)/rt
	cp rt.1 $(DESTDIR)$(MANDIR)/rt.1
	chmod 644 $(DESTDIR)$(MANDIR)/rt.1

uninstall:
	rm -f $(DESTDIR)$(BINDIR)/rt $(DESTDIR)$(MANDIR)/rt.1

clean:
	rm -rf build rt

.PHONY: all mcu mcu-builtin FORCE mcu-ready mcu-tools test-mcu test install uninstall clean fuzz fuzz-merge variants algorithms check-clang lint

-include $(OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(FIXED_LIB_OBJ:.o=.d) $(FIXED_TEST_OBJ:.o=.d)
