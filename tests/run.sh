#!/bin/sh
# run.sh - runs every test of rt and ends with one line `N passed, N failed`.
# Called by `make test` after the binaries are built:
#   unit tests (normal and ASan+UBSan builds), command-line tests, golden renders, the
#   malformed and unusual scenes of tests/bad and tests/good (bad.sh), fixed point against
#   the reference (fixed.sh) and the hard scenes against the visibility oracle in every
#   number type (watertight.sh), the documentation against the program (docs.sh), the
#   programs' code free of load-time patches (textrel.sh), and the tree's search against
#   the search object by object (tree.sh).
# The suites are independent (each works in a folder of its own), so they run one a
# processor, and their reports follow in the order below once all have ended.
cd "$(dirname "$0")/.." || exit 1
. tests/lib.sh

# LeakSanitizer's scan at exit reads every page of rt's static arrays (2.2 GiB of bss in
# the default build): 12 s a run on a machine where a page first touched costs ~10 us.
# rt allocates nothing, so it has no leak to find; AddressSanitizer and UBSan stay on for
# the suites that run programs. The unit tests and the corpus replay, built with the
# tests' small capacities, keep the scan.
no_leaks="detect_leaks=0${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
# The capacity limits' scenes (tests/bad/97-99) run on a build of small capacities.
LIMITS_RT=$(pwd)/build/rt-limits
export LIMITS_RT

# replay PROGRAM: every fuzzing corpus input and every bad and good scene, parsed and
# rendered tiny (under ASan+UBSan or MemorySanitizer, as PROGRAM was built).
replay() {
	set -- "$1" tests/fuzz/corpus/*
	[ -d tests/bad ] && set -- "$@" tests/bad/*.nff
	[ -d tests/good ] && set -- "$@" tests/good/*.nff
	"$@"
}

# run_suite NAME: runs the suite NAME (in a subshell of its own: what it exports stays
# there); its last line is `N passed, N failed`.
run_suite() {
	case $1 in
	unit* | fuzz-replay | fuzz-replay-fixed) ;;
	*)
		ASAN_OPTIONS=$no_leaks
		export ASAN_OPTIONS
		;;
	esac
	case $1 in
	unit) ./build/unit-tests ;;
	unit-sanitized) ./build/san/unit-tests ;;
	unit-float) ./build/unit-tests-float ;;
	unit-long-double) ./build/unit-tests-ref ;;
	# The hierarchy's suite with the wide tree's boxes tested one by one in plain C (hosts
	# without SSE) and four at a time by SSE (processors without AVX), which must find
	# what the program's own search finds.
	unit-scalar-bvh) ./build/unit-tests-scalar bvh ;;
	unit-sse-bvh) ./build/unit-tests-sse bvh ;;
	unit-fixed) ./build/unit-tests-fixed ;;
	unit-fixed-sanitized) ./build/san/unit-tests-fixed ;;
	fuzz-replay) replay ./build/san/replay ;;
	fuzz-replay-fixed) replay ./build/san/replay-fixed ;;
	cli | golden | bad | parallel | antialias) RT=./rt sh "tests/$1.sh" ;;
	*-sanitized) RT=./build/san/rt sh "tests/${1%-sanitized}.sh" ;;
	fixed) sh tests/fixed.sh ;;
	docs) RT=./rt sh tests/docs.sh ;;
	unit-msan) ./build/msan/unit-tests ;;
	unit-fixed-msan) ./build/msan/unit-tests-fixed ;;
	fuzz-replay-msan) replay ./build/msan/replay ;;
	fuzz-replay-fixed-msan) replay ./build/msan/replay-fixed ;;
	fixed-msan) FIXED=build/msan/rt-fixed FP_CHECK=0 sh tests/fixed.sh ;;
	watertight) sh tests/watertight.sh ;;
	# No program's code is patched when it is loaded (the code model, Makefile).
	textrel) sh tests/textrel.sh ;;
	# The tree's search against the search object by object (no sanitizer: it is the
	# answers that are compared, and the sanitized builds run the same scenes above).
	tree) RT=./rt sh tests/tree.sh ;;
	mcu) sh tests/mcu.sh ;;
	*) echo "run.sh: no suite $1" ;;
	esac
}

suites="unit unit-sanitized unit-float unit-long-double unit-scalar-bvh unit-sse-bvh"
suites="$suites unit-fixed unit-fixed-sanitized fuzz-replay fuzz-replay-fixed"
for script in cli golden bad parallel antialias; do
	[ -f "tests/$script.sh" ] && suites="$suites $script $script-sanitized"
done
suites="$suites fixed docs"
# MemorySanitizer (uninitialised reads) where clang is present: `make test` built these.
if command -v clang >/dev/null 2>&1; then
	suites="$suites unit-msan unit-fixed-msan fuzz-replay-msan fuzz-replay-fixed-msan fixed-msan"
	skipped_msan=
else
	skipped_msan="msan: skipped (no clang; MemorySanitizer needs it)"
fi
suites="$suites watertight textrel tree"
if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
	suites="$suites mcu"
	skipped_mcu=
else
	skipped_mcu="mcu: skipped (no arm-none-eabi-gcc; the MCU build needs it)"
fi

# Each worker takes the next suite no other has taken (mkdir either makes the claim or
# fails, at once) and leaves its output and its seconds in $tmp. The longest suites are
# offered first, so that no worker is left with one of them at the end.
make_tmp
# Interrupted (Ctrl-C, which the whole process group gets), the whole run stops: the
# workers and the suites they started ignore SIGINT, as background jobs of a script do,
# so the group is told with TERM (this script itself no longer listening for it). Sent
# HUP or TERM alone, the run ends its workers and leaves the rest of the group alone
# (make, or a script that called it).
worker_pids=
trap 'trap "" TERM; kill -TERM 0 2>/dev/null; exit 1' INT
trap 'kill -TERM $worker_pids 2>/dev/null; exit 1' HUP TERM
worker() {
	for name in tree watertight mcu bad-sanitized cli-sanitized bad cli $suites; do
		case " $suites " in *" $name "*) ;; *) continue ;; esac
		mkdir "$tmp/$name.claim" 2>/dev/null || continue
		start=$(date +%s)
		(run_suite "$name") >"$tmp/$name.out" 2>&1
		echo $(($(date +%s) - start)) >"$tmp/$name.seconds"
	done
}
# One worker a processor, at most eight (the suites run rt on every processor themselves).
workers=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
case $workers in '' | *[!0-9]* | 0) workers=1 ;; esac
[ "$workers" -gt 8 ] && workers=8
i=1
while [ "$i" -lt "$workers" ]; do
	worker &
	worker_pids="$worker_pids $!"
	i=$((i + 1))
done
worker
wait

# Adds a suite's `N passed, N failed` line (the last line of its output) to the totals,
# with the seconds it took.
tally() {
	name=$1
	out=$(cat "$tmp/$name.out" 2>/dev/null)
	took="($(cat "$tmp/$name.seconds" 2>/dev/null || echo '?') s)"
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

for name in $suites; do
	tally "$name"
done
[ -n "$skipped_msan" ] && echo "$skipped_msan"
[ -n "$skipped_mcu" ] && echo "$skipped_mcu"
summary
