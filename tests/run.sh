#!/bin/sh
# run.sh - runs every test of rt and ends with one line `N passed, N failed`.
# Called by `make test` after the binaries are built:
#   unit tests (normal and ASan+UBSan builds), command-line tests, golden renders, the
#   malformed and unusual scenes of tests/bad and tests/good (bad.sh), fixed point against
#   the reference (fixed.sh) and the hard scenes against the visibility oracle in every
#   number type (watertight.sh), the documentation against the program (docs.sh), the
#   programs' code free of load-time patches (textrel.sh), and the tree's search against
#   the search object by object (tree.sh).
cd "$(dirname "$0")/.." || exit 1
. tests/lib.sh

# Adds a suite's `N passed, N failed` line (the last line of its output) to the totals,
# with the seconds it took: the time since the suite before it ended (each suite runs in
# the command substitution of its own call, just before the call).
suite_end=$(date +%s)
tally() {
	name=$1
	out=$2
	now=$(date +%s)
	took="($((now - suite_end)) s)"
	suite_end=$now
	line=$(printf '%s\n' "$out" | tail -n 1)
	p=$(printf '%s\n' "$line" | sed -n 's/^\([0-9][0-9]*\) passed, \([0-9][0-9]*\) failed$/\1/p')
	f=$(printf '%s\n' "$line" | sed -n 's/^\([0-9][0-9]*\) passed, \([0-9][0-9]*\) failed$/\2/p')
	if [ -z "$p" ]; then
		printf '%s\n' "$out"
		echo "$name: did not finish (no summary line) $took"
		failed=$((failed + 1))
		return
	fi
	printf '%s\n' "$out" | grep -v '^[0-9]* passed, [0-9]* failed$' | sed "s|^|$name: |"
	echo "$name: $line $took"
	passed=$((passed + p))
	failed=$((failed + f))
}

tally unit "$(./build/unit-tests 2>&1)"
tally unit-sanitized "$(./build/san/unit-tests 2>&1)"
tally unit-float "$(./build/unit-tests-float 2>&1)"
tally unit-long-double "$(./build/unit-tests-ref 2>&1)"
# The hierarchy's suite with the wide tree's boxes tested one by one in plain C (hosts
# without SSE) and four at a time by SSE (processors without AVX), which must find what
# the program's own search finds.
tally unit-scalar-bvh "$(./build/unit-tests-scalar bvh 2>&1)"
tally unit-sse-bvh "$(./build/unit-tests-sse bvh 2>&1)"
tally unit-fixed "$(./build/unit-tests-fixed 2>&1)"
tally unit-fixed-sanitized "$(./build/san/unit-tests-fixed 2>&1)"
# Every fuzzing corpus input and every bad and good scene, parsed and rendered tiny under
# ASan+UBSan.
set -- tests/fuzz/corpus/*
[ -d tests/bad ] && set -- "$@" tests/bad/*.nff
[ -d tests/good ] && set -- "$@" tests/good/*.nff
tally fuzz-replay "$(./build/san/replay "$@" 2>&1)"
tally fuzz-replay-fixed "$(./build/san/replay-fixed "$@" 2>&1)"
# LeakSanitizer's scan at exit reads every page of rt's static arrays (2.2 GiB of bss in
# the default build): 12 s a run on a machine where a page first touched costs ~10 us.
# rt allocates nothing, so it has no leak to find; AddressSanitizer and UBSan stay on.
ASAN_OPTIONS="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export ASAN_OPTIONS
# The capacity limits' scenes (tests/bad/97-99) run on a build of small capacities.
LIMITS_RT=$(pwd)/build/rt-limits
export LIMITS_RT
for script in tests/cli.sh tests/golden.sh tests/bad.sh tests/parallel.sh tests/antialias.sh; do
	[ -f "$script" ] || continue
	name=$(basename "$script" .sh)
	tally "$name" "$(RT=./rt sh "$script" 2>&1)"
	tally "$name-sanitized" "$(RT=./build/san/rt sh "$script" 2>&1)"
done
tally fixed "$(sh tests/fixed.sh 2>&1)"
tally docs "$(RT=./rt sh tests/docs.sh 2>&1)"
# MemorySanitizer (uninitialised reads) where clang is present: `make test` built these.
if command -v clang >/dev/null 2>&1; then
	tally unit-msan "$(./build/msan/unit-tests 2>&1)"
	tally unit-fixed-msan "$(./build/msan/unit-tests-fixed 2>&1)"
	tally fuzz-replay-msan "$(./build/msan/replay "$@" 2>&1)"
	tally fuzz-replay-fixed-msan "$(./build/msan/replay-fixed "$@" 2>&1)"
	tally fixed-msan "$(FIXED=build/msan/rt-fixed FP_CHECK=0 sh tests/fixed.sh 2>&1)"
else
	echo "msan: skipped (no clang; MemorySanitizer needs it)"
fi
tally watertight "$(sh tests/watertight.sh 2>&1)"
# No program's code is patched when it is loaded (the code model, Makefile).
tally textrel "$(sh tests/textrel.sh 2>&1)"
# The tree's search against the search object by object (no sanitizer: it is the answers
# that are compared, and the sanitized builds run the same scenes above).
tally tree "$(RT=./rt sh tests/tree.sh 2>&1)"
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
	tally mcu "$(sh tests/mcu.sh 2>&1)"
else
	echo "mcu: skipped (no arm-none-eabi-gcc; the MCU build needs it)"
fi
summary
