# mk/mcu.mk - the microcontroller build (Cortex-M0 and M3), its tests under qemu and
# their tools; included by the Makefile.

# `make test` runs the MCU tests too (tests/mcu.sh) when the cross compiler is there.
MCU_CC ?= arm-none-eabi-gcc
MCU_TEST = $(if $(shell command -v $(MCU_CC)),mcu-ready)

# The microcontroller build: the fixed-point renderer, freestanding (no C library: its
# own semihosting layer in src/mcu/), for a Cortex-M0 (qemu `microbit`, 16 KiB RAM) and
# a Cortex-M3 (qemu `mps2-an385`, given the same 16 KiB). `make test-mcu` runs it under
# qemu and compares its output with build/rt-fixed; docs/mcu.md has the budgets.
MCU_HOST_ONLY = src/main.c src/output.c src/parallel.c src/workers.c src/antialias.c src/deflate.c src/term.c src/png.c src/stdio_io.c src/bvh.c src/bvh_build.c src/bvh_pieces.c src/bvh_small_split.c src/bvh_split.c
# The C library stand-ins are built apart, without link-time optimisation: the calls to
# memcpy and memset the compiler itself emits must find them after it.
MCU_LIBC = src/mcu/libc.c
MCU_SRC = $(filter-out $(MCU_HOST_ONLY),$(SRC)) $(filter-out $(MCU_LIBC),$(wildcard src/mcu/*.c))
# Capacities for 16 KiB of RAM: the scene, row buffers and stack must all fit.
MCU_CAPACITIES = -DRT_MAX_OBJECTS=24 -DRT_MAX_LIGHTS=4 -DRT_MAX_MATERIALS=8 \
	-DRT_MAX_VERTICES=32 -DRT_MAX_POLY_VERTS=16 -DRT_MAX_PLANES=40 -DRT_MAX_HEDRON_PLANES=12 \
	-DRT_MAX_WIDTH=160 -DRT_MAX_HEIGHT=160 -DRT_MAX_SCENE_WIDTH=8192 -DRT_MAX_SCENE_HEIGHT=8192 \
	-DRT_MAX_MEDIA=4 -DRT_CORNER_SAMPLING=0 -DRT_SHAPE_CONE=0 -DRT_SHAPE_PATCH=0 \
	-DRT_PREVIEW_COLOR=0 -DRT_COLOUR_PIPELINES=0 -DRT_READ_BUFFER=0
MCU_DEFINES = -DRT_REAL_FIXED -DRT_USE_BVH=0 -DRT_POLYGON_RUNS=0 -DRT_COLOUR_STEPS=256 -DRT_COLOUR_REPEATS=0 \
	$(MCU_CAPACITIES)
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
MCU_KERNEL_SRC = tests/mcu/kernels.c tests/test_fixed.c src/fixed.c src/fixed_func.c \
	src/fixed_text.c src/scale.c src/mcu/startup.c src/mcu/semihost.c
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

# qemu-system-arm is installed from Debian's packages when missing (tools/need).
mcu-ready: mcu mcu-builtin build/mcu/kernels-m0.elf build/mcu/kernels-m3.elf build/rt-fixed \
		build/rt-fixed-mcu
	@sh tools/need qemu-system-arm
# The cross compiler and the C headers it needs, likewise.
mcu-tools:
	@sh tools/need $(MCU_CC) gcc-arm-none-eabi libnewlib-arm-none-eabi
test-mcu: mcu-ready
	@sh tests/mcu.sh

.PHONY: mcu mcu-builtin FORCE mcu-ready mcu-tools test-mcu
