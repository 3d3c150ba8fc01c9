# rt - a minimal recursive ray tracer. `make` builds ./rt, `make test` runs every test.
# The user owns CC, CFLAGS, CPPFLAGS, LDFLAGS and LDLIBS; rt's own flags come first.
# This file builds, tests and installs rt; the other builds are in mk/: variants.mk
# (number types, algorithm forms, clang, sanitizers), mcu.mk (the microcontroller) and
# dev.mk (fuzzing, static analysis). A program a target needs and lacks is installed by
# tools/need.

PREFIX ?= /usr/local
BINDIR = $(PREFIX)/bin
MANDIR = $(PREFIX)/share/man/man1

CC ?= cc
CFLAGS ?= -O3
WARN = -std=c99 -pedantic -Wall -Wextra -Wshadow -Wdouble-promotion -Wstrict-prototypes \
       -Wmissing-prototypes -Wpointer-arith -Wcast-qual -Wvla -Werror
# x86-64's default code model holds static data to 2 GiB; rt's capacities (millions of
# objects, config.h) take more, so host builds there use the medium model, which puts
# large arrays beyond it: the same bytes, the same time on SPD balls and gears, 5-8 %
# more building a million spheres (whose whole run is no slower: reading a scene a block
# at a time, lexer.c, gained as much). clang takes the large model instead: clang 14's
# medium model writes a function's address into the code as an absolute constant, which
# a position-independent program must patch when it is loaded (a text relocation: the
# linker warns of it, and a hardened system refuses it), where its large model reaches
# it through the GOT, at the same speed (SPD balls and teapot-s12, 7 alternating runs).
# The clang builds' model is known without asking clang, which the clang targets install
# only as they run (tools/need). Both are empty beyond x86-64.
HOST_X86_64 := $(filter x86_64-%,$(shell $(CC) -dumpmachine 2>/dev/null))
HOST_MODEL := $(if $(HOST_X86_64),$(if $(findstring clang,$(shell $(CC) --version 2>/dev/null)), \
	      -mcmodel=large,-mcmodel=medium))
CLANG_MODEL := $(if $(HOST_X86_64),-mcmodel=large)
# No FMA contraction: the hard cases are decided by rounding (numerics.md section 9).
RT_CFLAGS = $(WARN) $(HOST_MODEL) -ffp-contract=off -MMD -MP
# rt and the builds of each number type are optimised across files (link-time
# optimisation) where the compiler and linker can: the search calls each shape's test,
# the plane's distance and the vector helpers in other files, and inlined they cost 2-5 %
# less CPU time on the SPD scenes (docs/speed.md); the images are the same bytes.
# `make LTO=` builds without it (build/flags, below, rebuilds what it changes); a
# compiler that cannot gets none. Asked once a make (a simple variable: a recursive one
# would compile the test at every use).
ifeq ($(origin LTO),undefined)
LTO := $(shell printf 'int main(void) { return 0; }\n' | \
	 $(CC) -flto=auto -x c -o /dev/null - > /dev/null 2>&1 && echo -flto=auto)
endif
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
# The unit tests' scenes are small, and a dozen of them are static: capacities that keep
# them within the 2 GiB of static data x86-64's default code model allows, and that model
# (config.h's sizes change nothing the tests check; every build of them uses these; gcc's
# address sanitizer meets a section conflict with the medium model and these sizes).
TEST_CAPACITIES = -DRT_MAX_OBJECTS=65536 -DRT_MAX_VERTICES=262144 -DRT_MAX_PLANES=65536 \
		  $(if $(HOST_MODEL),-mcmodel=small)
TEST_LIB_OBJ = $(LIB_SRC:src/%.c=build/obj/test-lib/%.o)

# Besides the file-by-file builds (rt, the unit tests in double and Q16.16), every build
# (number types, sanitizers, clang, fuzzing, the microcontroller) is a whole program in
# one compiler call, made by this one recipe:
# $(call whole-program,COMPILER,FLAGS,SOURCES,LIBRARIES) builds $@.
define whole-program
@mkdir -p $(@D)
$(1) $(2) -o $@ $(3) $(4)
endef

all: rt

# What the objects and the builds of each type are made with, kept in build/flags: the
# file is written again when it changes (another CC, LTO, CFLAGS...), and what depends
# on it is then built again. Without it a change of LTO rebuilt nothing, and objects of
# one compiler's link-time optimisation went to another's linker.
BUILD_FLAGS = $(CC) $(LTO) $(CPPFLAGS) $(CFLAGS) $(LDFLAGS)
WRITE_BUILD_FLAGS = mkdir -p build && printf '%s\n' '$(BUILD_FLAGS)' > build/flags
ifneq ($(BUILD_FLAGS),$(shell cat build/flags 2> /dev/null))
$(shell $(WRITE_BUILD_FLAGS))
endif
# Made again after a clean in the same make (make clean rt).
build/flags:
	@$(WRITE_BUILD_FLAGS)

# Linked with the compiler's flags: with link-time optimisation the code is made there.
rt: $(OBJ)
	$(CC) $(if $(LTO),$(LTO) $(HOST_MODEL) -ffp-contract=off $(CFLAGS)) $(LDFLAGS) -o $@ \
		$(OBJ) $(LDLIBS) $(RT_LDLIBS)

build/obj/%.o: src/%.c build/flags
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(LTO) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

build/obj/tests/%.o: tests/%.c build/flags
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(TEST_CAPACITIES) -Isrc $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

build/obj/test-lib/%.o: src/%.c build/flags
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(TEST_CAPACITIES) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<

build/unit-tests: $(TEST_OBJ) $(TEST_LIB_OBJ)
	$(CC) $(LDFLAGS) -o $@ $(TEST_OBJ) $(TEST_LIB_OBJ) $(LDLIBS) $(RT_LDLIBS)

include mk/variants.mk mk/mcu.mk mk/dev.mk

# Everything tests/run.sh runs; MemorySanitizer's builds where clang is present
# (MSAN_TEST, mk/variants.mk), the MCU's where the cross compiler is (MCU_TEST, mk/mcu.mk).
TEST_PROGRAMS = rt build/unit-tests build/san/rt build/san/unit-tests build/san/replay \
	build/san/replay-fixed build/unit-tests-float build/unit-tests-ref \
	build/unit-tests-scalar build/unit-tests-sse build/unit-tests-fixed \
	build/san/unit-tests-fixed build/rt-fixed build/rt-ref build/rt-float build/rt-small \
	build/rt-limits build/rt-no-tree $(MSAN_TEST) $(MCU_TEST)
# They are built a job a processor unless the caller chose (-j): twenty-odd whole
# programs, most of a fresh checkout's test time when built one after another. Given -j,
# they are test's own prerequisites, in the caller's make (which sees -j in MAKEFLAGS
# only once the makefiles are read, hence the second expansion): a make of its own
# could build them at the same time as another goal of the caller's (make -j2 rt test).
TEST_JOBS := $(shell getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
.SECONDEXPANSION:
test: $$(if $$(filter -j%,$$(MAKEFLAGS)),$$(TEST_PROGRAMS))
	@$(if $(filter -j%,$(MAKEFLAGS)),:,$(MAKE) --no-print-directory -j$(TEST_JOBS) test-programs)
	@sh tests/run.sh
test-programs: $(TEST_PROGRAMS)

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

.PHONY: all test test-programs install uninstall clean

-include $(OBJ:.o=.d) $(TEST_OBJ:.o=.d) $(TEST_LIB_OBJ:.o=.d)
