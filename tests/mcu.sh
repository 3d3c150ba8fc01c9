#!/bin/sh
# mcu.sh - the microcontroller build under qemu: the same bytes as the host's fixed-point
# build (build/rt-fixed) on a Cortex-M0 and a Cortex-M3, and the budgets of issue #5:
# no heap and no soft float linked, M0 text <= 24 KiB, data + bss + worst-case stack
# <= 16 KiB. Run by `make test-mcu` (and by `make test` when the cross compiler exists).
cd "$(dirname "$0")/.." || exit 1
. tests/lib.sh
label=FAIL # its failure lines read `FAIL: what`
make_tmp

check() { # check DESCRIPTION COMMAND...
	what=$1
	shift
	if "$@"; then ok; else bad "$what"; fi
}

TEXT_LIMIT=24576 # bytes of flash code on the M0 (24 KiB)
RAM_LIMIT=16384  # bytes of RAM on both boards (16 KiB)
DEPTH=$(sed -n 's/^#define RT_MAX_DEPTH \([0-9]*\).*/\1/p' src/config.h)

# run_mcu BOARD ELF OUT ERR ARGS...: rt under qemu, its argv given by semihosting.
# Its variables are its own (mcu_*): the callers' board and elf stay as they are.
run_mcu() {
	mcu_board=$1 mcu_elf=$2 mcu_out=$3 mcu_err=$4
	shift 4
	mcu_args="arg=rt"
	for a in "$@"; do mcu_args="$mcu_args,arg=$a"; done
	within 600 qemu-system-arm -M "$mcu_board" -display none -serial none -monitor none \
		-semihosting-config "enable=on,target=native,$mcu_args" -kernel "$mcu_elf" \
		>"$mcu_out" 2>"$mcu_err"
}

for cpu in m0 m3; do
	elf=build/mcu/rt-$cpu.elf
	case $cpu in m0) board=microbit ;; m3) board=mps2-an385 ;; esac

	# Budgets, from the linked ELF.
	syms=$(arm-none-eabi-nm "$elf" | awk '{print $NF}')
	for bad_sym in malloc calloc realloc free _sbrk _malloc_r; do
		printf '%s\n' "$syms" | grep -qx "$bad_sym" && bad "$cpu: $bad_sym is linked" || ok
	done
	floats=$(printf '%s\n' "$syms" | grep -E '^__aeabi_[fd]|^__(add|sub|mul|div)[sd]f3$' | tr '\n' ' ')
	check "$cpu: soft-float routines linked: $floats" [ -z "$floats" ]
	set -- $(arm-none-eabi-size "$elf" | awk 'NR == 2 {print $1, $2, $3}')
	text=$1 data=$2 bss=$3
	stack=$(python3 tools/mcu-stack --depth "$DEPTH" "build/mcu/$cpu" "$elf" |
		sed -n 's/^worst_case_stack_bytes: //p')
	check "$cpu: worst-case stack not derived" [ -n "$stack" ]
	ram=$((data + bss + ${stack:-$RAM_LIMIT}))
	echo "$cpu: text $text, data $data, bss $bss, worst-case stack ${stack:-?} (depth $DEPTH): RAM $ram of $RAM_LIMIT"
	check "$cpu: RAM $ram > $RAM_LIMIT" [ "$ram" -le "$RAM_LIMIT" ]
	if [ "$cpu" = m0 ]; then
		check "m0: text $text > $TEXT_LIMIT" [ "$text" -le "$TEXT_LIMIT" ]
	fi

	# The kernels' unit tests on the board itself (its assembly forms of fixed.h).
	run_mcu "$board" "build/mcu/kernels-$cpu.elf" "$tmp/mcu.out" "$tmp/mcu.err"
	status=$?
	check "$cpu: kernel tests: status $status: $(cat "$tmp/mcu.err")" [ "$status" -eq 0 ]
	check "$cpu: kernel tests did not run" grep -q '^[1-9][0-9]* passed, 0 failed$' "$tmp/mcu.err"

	# Renders: the bytes the host's fixed-point build writes, with the same options.
	# mcu-glass: refraction and absorption; polyhedron: convex polyhedra, and --ascii the
	# ASCII preview; mcu-demo: the benchmark, also as object IDs.
	n=0
	for run in "scenes/mcu-demo.nff" "scenes/mcu-glass.nff" "-s 160x120 scenes/polyhedron.nff" \
		"--ascii --cols 72 scenes/polyhedron.nff" "--ids scenes/mcu-demo.nff" \
		"-d 8 -s 40x30 scenes/mcu-glass.nff"; do
		n=$((n + 1))
		# shellcheck disable=SC2086 # the options split into words on purpose
		run_mcu "$board" "$elf" "$tmp/mcu.out" "$tmp/mcu.err" $run
		status=$?
		# shellcheck disable=SC2086
		./build/rt-fixed $run >"$tmp/host.out" 2>"$tmp/host.err"
		check "$cpu: rt $run: exit status $status" [ "$status" -eq 0 ]
		check "$cpu: rt $run: output differs from build/rt-fixed" cmp -s "$tmp/mcu.out" "$tmp/host.out"
		check "$cpu: rt $run: empty output" [ -s "$tmp/mcu.out" ]
	done

	# Errors: the same message and status as on the host.
	for scene in tests/bad/20-missing-number.nff tests/bad/64-resolution-zero.nff; do
		run_mcu "$board" "$elf" "$tmp/mcu.out" "$tmp/mcu.err" "$scene"
		status=$?
		./build/rt-fixed "$scene" >"$tmp/host.out" 2>"$tmp/host.err"
		check "$cpu: $scene: status $status, not 1" [ "$status" -eq 1 ]
		check "$cpu: $scene: message differs from the host's" cmp -s "$tmp/mcu.err" "$tmp/host.err"
		check "$cpu: $scene: output written" [ ! -s "$tmp/mcu.out" ]
	done
	# Past the MCU's capacities: a clear error naming the capacity, not a crash.
	run_mcu "$board" "$elf" "$tmp/mcu.out" "$tmp/mcu.err" scenes/glass.nff
	status=$?
	check "$cpu: glass.nff: status $status, not 1" [ "$status" -eq 1 ]
	check "$cpu: glass.nff: no capacity named" grep -q 'RT_MAX_[A-Z]* = ' "$tmp/mcu.err"
	# Cones and patches are left out of the M0-sized build (RT_SHAPE_CONE=0,
	# RT_SHAPE_PATCH=0): refused by name.
	run_mcu "$board" "$elf" "$tmp/mcu.out" "$tmp/mcu.err" scenes/cones.nff
	check "$cpu: cones.nff: status not 1" [ $? -eq 1 ]
	check "$cpu: cones.nff: the switch is not named" grep -q 'RT_SHAPE_CONE' "$tmp/mcu.err"
	printf 'v\nfrom 0 -5 0\nat 0 0 0\nup 0 0 1\nangle 40\nhither 0.1\nresolution 8 8\n%s\n' \
		'pp 3 0 0 0 0 -1 0 1 0 0 0 -1 0 0 1 0 -1 0' >"$tmp/patch.nff"
	run_mcu "$board" "$elf" "$tmp/mcu.out" "$tmp/mcu.err" "$tmp/patch.nff"
	check "$cpu: a patch: status not 1" [ $? -eq 1 ]
	check "$cpu: a patch: the switch is not named" grep -q 'RT_SHAPE_PATCH' "$tmp/mcu.err"
	run_mcu "$board" "$elf" "$tmp/mcu.out" "$tmp/mcu.err" scenes/mcu-demo.nff --rows
	check "$cpu: a usage error gives status 2" [ $? -eq 2 ]
	run_mcu "$board" "$elf" "$tmp/mcu.out" "$tmp/mcu.err" no-such-file.nff
	check "$cpu: a missing file gives status 1" [ $? -eq 1 ]
	check "$cpu: a missing file is named" grep -q '^rt: no-such-file.nff: cannot open' "$tmp/mcu.err"
done
# Every malformed and every odd-but-valid scene (tests/bad, tests/good) on the M0: the
# same image, messages and exit status as the host's twin of the MCU build
# (build/rt-fixed-mcu: the same capacities and switches).
same=0
for scene in tests/bad/*.nff tests/good/*.nff; do
	run_mcu microbit build/mcu/rt-m0.elf "$tmp/mcu.out" "$tmp/mcu.err" -s 16x12 "$scene"
	status=$?
	./build/rt-fixed-mcu -s 16x12 "$scene" >"$tmp/host.out" 2>"$tmp/host.err"
	host_status=$?
	if [ "$status" -eq "$host_status" ] && cmp -s "$tmp/mcu.out" "$tmp/host.out" &&
		cmp -s "$tmp/mcu.err" "$tmp/host.err"; then
		same=$((same + 1))
	else
		bad "m0: $scene: status $status (host $host_status), or output or messages differ"
	fi
done
check "m0: no malformed or odd scene was compared" [ "$same" -gt 100 ]

# The build with a scene compiled in (make mcu-builtin: scenes/mcu-demo.nff by default)
# renders it with no scene named, and a named file still wins.
if [ -f build/mcu/rt-m0-builtin.elf ]; then
	name=$(sed -n 's/^const char rt_builtin_scene_name\[\] = "\(.*\)";$/\1/p' build/mcu/builtin-scene.c)
	run_mcu microbit build/mcu/rt-m0-builtin.elf "$tmp/mcu.out" "$tmp/mcu.err"
	check "builtin: exit status $?" [ $? -eq 0 ]
	./build/rt-fixed "$name" >"$tmp/host.out"
	check "builtin: output differs from build/rt-fixed $name" cmp -s "$tmp/mcu.out" "$tmp/host.out"
	run_mcu microbit build/mcu/rt-m0-builtin.elf "$tmp/mcu.out" "$tmp/mcu.err" -s 80x60 scenes/mcu-glass.nff
	./build/rt-fixed -s 80x60 scenes/mcu-glass.nff >"$tmp/host.out"
	check "builtin: a named scene does not win" cmp -s "$tmp/mcu.out" "$tmp/host.out"
fi
summary
