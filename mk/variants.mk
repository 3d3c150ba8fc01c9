# mk/variants.mk - the other builds of the same sources: number types, algorithm forms,
# clang, the sanitizers and MemorySanitizer; included by the Makefile.

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
VARIANT_FLAGS_small = -DRT_REAL_DOUBLE -DRT_MAX_OBJECTS=4096 -DRT_MAX_VERTICES=16384 \
	-DRT_MAX_PLANES=4096 -DRT_PARALLEL_POOL=65536L
# The capacities rt had before they reached the millions: tests/bad's limit cases run on it.
VARIANT_FLAGS_limits = -DRT_REAL_DOUBLE -DRT_MAX_OBJECTS=16384 -DRT_MAX_VERTICES=65536 \
	-DRT_MAX_PLANES=4096
# The wide tree's boxes tested by the plain C loop, as hosts without SSE build it, and
# four at a time with SSE, as on processors without AVX.
VARIANT_FLAGS_scalar = -DRT_REAL_DOUBLE -DRT_NO_SIMD=1
VARIANT_FLAGS_sse = -DRT_REAL_DOUBLE -DRT_NO_AVX=1
# No hierarchy, but the checks the build with one makes (config.h): every object tested
# for every ray, to compare with the tree's search (tests/tree.sh).
VARIANT_FLAGS_no-tree = -DRT_REAL_DOUBLE -DRT_USE_BVH=0 -DRT_HOST_CHECKS=1
VARIANT_FLAGS_sphere-textbook = -DRT_REAL_DOUBLE -DRT_NAIVE=RT_NAIVE_SPHERE
VARIANT_FLAGS_hedron-per-face = -DRT_REAL_DOUBLE -DRT_NAIVE=RT_NAIVE_HEDRON
VARIANT_FLAGS_offset-fixed = -DRT_REAL_DOUBLE -DRT_NAIVE=RT_NAIVE_OFFSET
VARIANT_FLAGS_float-textbook = -DRT_REAL_FLOAT -DRT_NAIVE=RT_NAIVE_SPHERE
VARIANT_FLAGS_float-per-face = -DRT_REAL_FLOAT -DRT_NAIVE=RT_NAIVE_HEDRON
VARIANT_FLAGS_float-offset-fixed = -DRT_REAL_FLOAT -DRT_NAIVE=RT_NAIVE_OFFSET
TYPES = float double ref fixed
ALGORITHMS = sphere-textbook hedron-per-face offset-fixed float-textbook float-per-face \
	     float-offset-fixed
VARIANT_CFLAGS = $(WARN) $(HOST_MODEL) -ffp-contract=off $(VARIANT_FLAGS_$*)

variants: $(TYPES:%=build/rt-%)

# The same strict warnings with clang (installed by tools/need if missing), every type.
# Each is refused if its code would be patched when loaded (text relocations: the code
# model, Makefile).
build/clang/rt-%: $(SRC) $(HDR)
	@sh tools/need clang
	$(call whole-program,clang,$(WARN) $(CLANG_MODEL) -ffp-contract=off $(VARIANT_FLAGS_$*) -O2, \
		$(SRC),-lm)
	@if readelf -d $@ 2> /dev/null | grep -q TEXTREL; then \
		echo "$@: text relocations (readelf -d shows TEXTREL)"; rm -f $@; exit 1; fi
check-clang: $(TYPES:%=build/clang/rt-%)

# The unit tests in every number type (each type's tolerances are in the tests).
build/unit-tests-%: $(LIB_SRC) $(TEST_SRC) $(HDR) $(TEST_HDR)
	$(call whole-program,$(CC),$(RT_CFLAGS) $(VARIANT_FLAGS_$*) $(TEST_CAPACITIES) -Isrc \
		$(CPPFLAGS) $(CFLAGS),$(LIB_SRC) $(TEST_SRC),$(LINK_LIBS))
# Q16.16: the library is built as build/rt-fixed is, with no floating point
# (-mgeneral-regs-only on x86-64), file by file into build/fixed/. The tests themselves
# cannot do without it: they build their reference rays, rotations and expected values
# in double and compare through test.h's double checks. So the test files are built
# with -DRT_REAL_FIXED but without -mgeneral-regs-only, and linked with that library.
FIXED_LIB_OBJ = $(LIB_SRC:src/%.c=build/fixed/%.o)
FIXED_TEST_OBJ = $(TEST_SRC:tests/%.c=build/fixed/tests/%.o)
build/fixed/%.o: src/%.c
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(VARIANT_FLAGS_fixed) $(TEST_CAPACITIES) $(CPPFLAGS) $(CFLAGS) -c -o $@ $<
build/fixed/tests/%.o: tests/%.c
	@mkdir -p $(@D)
	$(CC) $(RT_CFLAGS) $(filter -D%,$(VARIANT_FLAGS_fixed)) $(TEST_CAPACITIES) -Isrc $(CPPFLAGS) \
		$(CFLAGS) -c -o $@ $<
build/unit-tests-fixed: $(FIXED_TEST_OBJ) $(FIXED_LIB_OBJ)
	$(CC) $(LDFLAGS) -o $@ $(FIXED_TEST_OBJ) $(FIXED_LIB_OBJ) $(LDLIBS) $(RT_LDLIBS)
algorithms: $(ALGORITHMS:%=build/rt-%)

build/rt-%: $(SRC) $(HDR) build/flags
	$(call whole-program,$(CC),$(VARIANT_CFLAGS) $(LTO) $(CPPFLAGS) $(CFLAGS),$(SRC),$(LINK_LIBS))

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
	$(call whole-program,$(CC),$(SAN_CFLAGS) $(TEST_CAPACITIES) -Isrc $(CPPFLAGS) -O1, \
		$(LIB_SRC) $(TEST_SRC),$(LINK_LIBS))
build/san/replay build/san/replay-fixed: build/san/replay%: $(REPLAY_SRC) $(HDR)
	$(call whole-program,$(CC),$(SAN_CFLAGS) -Isrc $(CPPFLAGS) -O1,$(REPLAY_SRC),$(LINK_LIBS))

# MemorySanitizer (reads of uninitialised memory, which ASan cannot see) where clang is
# present: unit tests, the corpus replay and the fixed-point program, in double and Q16.16.
MSAN_CC ?= clang
MSAN_FLAGS = -fsanitize=memory -fsanitize-memory-track-origins -fno-omit-frame-pointer -g -O1
MSAN_BUILDS = build/msan/unit-tests build/msan/unit-tests-fixed build/msan/replay \
	build/msan/replay-fixed build/msan/rt-fixed
MSAN_TEST = $(if $(shell command -v $(MSAN_CC)),$(MSAN_BUILDS))
MSAN_CFLAGS = $(WARN) $(CLANG_MODEL) -ffp-contract=off $(MSAN_FLAGS) $(if $*,-DRT_REAL_FIXED)
build/msan/unit-tests build/msan/unit-tests-fixed: build/msan/unit-tests%: $(SRC) $(TEST_SRC) \
		$(HDR) $(TEST_HDR)
	$(call whole-program,$(MSAN_CC),$(MSAN_CFLAGS) $(TEST_CAPACITIES) -Isrc,$(LIB_SRC) $(TEST_SRC),-lm)
build/msan/replay build/msan/replay-fixed: build/msan/replay%: $(REPLAY_SRC) $(HDR)
	$(call whole-program,$(MSAN_CC),$(MSAN_CFLAGS) -Isrc,$(REPLAY_SRC),-lm)
build/msan/rt-fixed: $(SRC) $(HDR)
	$(call whole-program,$(MSAN_CC),$(WARN) -ffp-contract=off $(MSAN_FLAGS) -DRT_REAL_FIXED,$(SRC),-lm)

.PHONY: variants algorithms check-clang

-include $(FIXED_LIB_OBJ:.o=.d) $(FIXED_TEST_OBJ:.o=.d)
