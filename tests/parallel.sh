#!/bin/sh
# parallel.sh - -j: every output the same bytes at every job count, and a render that
# ends early (a signal, a closed pipe, a worker killed) leaves no process, no temporary
# file and no changed output behind.
# Run from the repository root as `RT=./rt sh tests/parallel.sh`; ends with `N passed, N failed`.
# See LICENSE for copyright and licence.

. tests/lib.sh
rt_absolute
make_tmp
run_limit=120

# same_at_every_j WHAT ARGS...: rt ARGS at -j 1, 2, 3 and 7 writes the same standard
# output and the same standard error (less --stats's timings and rates), status 0.
same_at_every_j() {
	what=$1
	shift
	for j in 1 2 3 7; do
		run -j "$j" "$@"
		if [ "$status" -ne 0 ]; then
			bad "$what at -j $j: exit status $status ($(head -n 2 "$tmp/err"))"
			return
		fi
		grep -v 'second' "$tmp/err" >"$tmp/err-$j"
		mv "$tmp/out" "$tmp/out-$j"
	done
	if [ ! -s "$tmp/out-1" ]; then
		bad "$what: -j 1 wrote nothing"
		return
	fi
	for j in 2 3 7; do
		if cmp -s "$tmp/out-1" "$tmp/out-$j" && cmp -s "$tmp/err-1" "$tmp/err-$j"; then ok; else
			bad "$what: -j $j differs from -j 1"
		fi
	done
}

# ---- every output, the same bytes -------------------------------------------------------
same_at_every_j "PPM" -s 96x72 scenes/showpiece.nff
same_at_every_j "PPM, glass" -s 64x48 scenes/glass.nff
same_at_every_j "--spd" --spd -s 64x48 scenes/showpiece.nff
same_at_every_j "--ids" --ids -s 64x48 scenes/showpiece.nff
same_at_every_j "--rows" --rows 10:27 -s 64x48 scenes/showpiece.nff
same_at_every_j "--rows --spd" --spd --rows 3:4 -s 64x48 scenes/showpiece.nff
same_at_every_j "--ascii" --ascii --cols 50 scenes/showpiece.nff
same_at_every_j "--ansi, 256 colours" --ansi --cols 50 scenes/glass.nff
COLORTERM=truecolor same_at_every_j "--ansi, 24-bit" --ansi --cols 50 scenes/glass.nff
same_at_every_j "--stats counts" --stats -s 64x48 scenes/showpiece.nff
same_at_every_j "more workers than rows" -s 9x2 scenes/showpiece.nff
same_at_every_j "depth 1" -d 1 -s 40x30 scenes/showpiece.nff
same_at_every_j "PNG" -s 64x48 -o - -f png scenes/showpiece.nff
# A line renders alike whatever lines its process traced before. This scene is at the
# edge of Q16.16's range, where a cone's test reports hits outside its box: a blocker
# remembered from an earlier line shadowed what the hierarchy lit, and -j changed pixels.
if [ -x build/rt-fixed ]; then
	saved_rt=$RT
	RT=$(pwd)/build/rt-fixed
	same_at_every_j "Q16.16, edge of range" -s 48x36 \
		tests/fuzz/corpus/42c56d3d63f5cdc416ebc1ac0c11527251c58b48
	RT=$saved_rt
fi

# The counts --stats prints are the workers' summed: at -j 2 the eye rays are the image's.
run -j 2 --stats -s 40x30 scenes/showpiece.nff
if grep -qx 'eye_rays: 1200' "$tmp/err"; then ok; else
	bad "--stats at -j 2: eye_rays is not 40 x 30 ($(grep eye_rays "$tmp/err"))"
fi

# Without room for the shared pool one process renders: the same bytes, status 0. The
# address space is held to the least -j 1 needs (found by halving, in KiB) and 512 KiB
# more, less than the pool -j maps (RT_PARALLEL_POOL colours and ids, 28 MiB in double). A
# sanitized build reserves terabytes and runs under no such limit: skipped there.
wide_under_limit() {
	sh -c 'ulimit -v "$1" && exec "$2" -j "$3" -s 8000x2 -o "$4" scenes/showpiece.nff' \
		sh "$1" "$RT" "$2" "$tmp/limit-$2.ppm" 2>/dev/null
}
if wide_under_limit 67108864 1; then
	low=1024
	high=67108864
	while [ $((high - low)) -gt 64 ]; do
		mid=$(((low + high) / 2))
		if wide_under_limit "$mid" 1; then high=$mid; else low=$mid; fi
	done
	wide_under_limit "$high" 1
	if wide_under_limit $((high + 512)) 2 && cmp -s "$tmp/limit-1.ppm" "$tmp/limit-2.ppm"; then
		ok
	else
		bad "-j 2 without room for its window ($((high + 512)) KiB) is not -j 1's image"
	fi
fi

# With standard output closed, a socket could take its number and the image would go to a
# worker (which crashed on it): every -j reports the write error as -j 1 does. With
# standard input closed the image is -j 1's.
for j in 1 2 3; do
	"$RT" -j "$j" -s 96x72 scenes/showpiece.nff >&- 2>"$tmp/closed-err-$j"
	echo $? >>"$tmp/closed-err-$j"
	"$RT" -j "$j" -s 32x24 scenes/showpiece.nff <&- >"$tmp/closed-in-$j" 2>&1
done
for j in 2 3; do
	if cmp -s "$tmp/closed-err-1" "$tmp/closed-err-$j" && grep -q "write error" "$tmp/closed-err-$j"
	then ok; else
		bad "-j $j with standard output closed: $(tr '\n' ' ' <"$tmp/closed-err-$j")"
	fi
	if [ -s "$tmp/closed-in-1" ] && cmp -s "$tmp/closed-in-1" "$tmp/closed-in-$j"; then ok; else
		bad "-j $j with standard input closed differs from -j 1"
	fi
done

# ---- the job count ----------------------------------------------------------------------
for j in 0 65 x -1 ''; do
	run -j "$j" -s 8x8 scenes/showpiece.nff
	if [ "$status" -eq 2 ] && grep -q "bad job count" "$tmp/err"; then ok; else
		bad "-j '$j': status $status, expected 2 and 'bad job count'"
	fi
done
run --jobs 2 -s 8x8 scenes/showpiece.nff
if [ "$status" -eq 0 ]; then ok; else bad "--jobs 2: exit status $status"; fi

# ---- ending early -------------------------------------------------------------------------
# 1,000 concentric glass spheres at depth 8: many seconds at 256x256 (slow.sh), so each
# ending below meets a render in full flight.
{
	printf 'v from 0 0 -30 at 0 0 0 up 0 1 0 angle 40 hither 0.01 resolution 64 64\n'
	printf 'l -4 3 -20\nl 4 3 -20\nf 0.9 0.9 0.9 0.1 0.5 30 0.9 1.5\n'
	awk 'BEGIN { for (i = 1; i <= 1000; i++) printf "s 0 0 0 %g\n", i * 0.01 }'
} >"$tmp/slow.nff"

# no_process_left WHAT: no process still runs on slow.nff (the workers included), after
# a moment for the stopped ones to go.
no_process_left() {
	n=0
	while pgrep -f "$tmp/slow.nff" >/dev/null 2>&1 && [ $n -lt 20 ]; do
		sleep 0.1
		n=$((n + 1))
	done
	if pgrep -f "$tmp/slow.nff" >/dev/null 2>&1; then
		bad "$1: processes left: $(pgrep -a -f "$tmp/slow.nff" | head -n 3)"
		pkill -KILL -f "$tmp/slow.nff"
	else
		ok
	fi
}

# output_kept WHAT: the old output file is as it was, and no temporary file sits beside it.
output_kept() {
	if [ "$(cat "$tmp/end/old.ppm")" = kept ] && [ "$(ls "$tmp/end")" = old.ppm ]; then ok; else
		bad "$1: the output folder holds $(ls "$tmp/end" | tr '\n' ' ')"
	fi
}

# started PID: waits (up to 5 s) until PID has worker processes; their IDs in $children.
started() {
	n=0
	children=
	while [ -z "$children" ] && [ $n -lt 50 ]; do
		sleep 0.1
		children=$(pgrep -P "$1")
		n=$((n + 1))
	done
	[ -n "$children" ]
}

mkdir "$tmp/end"
for sig in TERM HUP INT; do
	echo kept >"$tmp/end/old.ppm"
	# INT through timeout(1): a background job of a script ignores SIGINT.
	if [ "$sig" = INT ]; then
		timeout -s INT 0.5 "$RT" -j 2 -d 8 -s 256x256 -o "$tmp/end/old.ppm" "$tmp/slow.nff" 2>"$tmp/err"
		status=$?
		expected=124
	else
		"$RT" -j 2 -d 8 -s 256x256 -o "$tmp/end/old.ppm" "$tmp/slow.nff" 2>"$tmp/err" &
		pid=$!
		started "$pid" || bad "SIG$sig: no workers started"
		kill -"$sig" "$pid"
		wait "$pid" 2>/dev/null
		status=$?
		case $sig in
		HUP) expected=129 ;;
		*) expected=143 ;;
		esac
	fi
	if [ "$status" -eq "$expected" ]; then ok; else
		bad "SIG$sig: exit status $status, expected $expected"
	fi
	output_kept "SIG$sig"
	no_process_left "SIG$sig"
done

# A closed pipe: the reader takes 100 bytes and goes; rt ends by SIGPIPE at its next
# write, at once. Timed from the reader's going, not from the start, and at depth 2: the
# output goes out a buffer (4 KiB) at a time, and at depth 8 under the sanitizers on a
# busy machine one buffer's pixels took 6 s; at depth 2 it takes a fifth of a second, and
# the whole image 16 s.
{
	"$RT" -j 2 -d 2 -s 256x256 "$tmp/slow.nff" 2>"$tmp/err"
	echo $? >"$tmp/pipe-status"
	date +%s >"$tmp/pipe-ended"
} | {
	head -c 100 >/dev/null
	date +%s >"$tmp/pipe-closed"
}
waited=$(($(cat "$tmp/pipe-ended") - $(cat "$tmp/pipe-closed")))
if [ "$(cat "$tmp/pipe-status")" -eq 141 ] && [ "$waited" -lt 3 ]; then ok; else
	bad "SIGPIPE: status $(cat "$tmp/pipe-status") $waited s after the reader went, expected 141 at once"
fi
no_process_left "SIGPIPE"

# A worker killed mid-render: rt says so once, stops the others, exits 1, writes nothing.
echo kept >"$tmp/end/old.ppm"
"$RT" -j 2 -d 8 -s 256x256 -o "$tmp/end/old.ppm" "$tmp/slow.nff" 2>"$tmp/err" &
pid=$!
if started "$pid"; then
	kill -KILL $(echo "$children" | head -n 1)
	wait "$pid" 2>/dev/null
	status=$?
	if [ "$status" -eq 1 ]; then ok; else bad "worker killed: exit status $status, expected 1"; fi
	if [ "$(grep -c . "$tmp/err")" -eq 1 ] && grep -q "was ended by signal 9" "$tmp/err"; then ok; else
		bad "worker killed: stderr is not one line naming signal 9: $(head -n 3 "$tmp/err")"
	fi
else
	bad "worker killed: no workers started"
	kill "$pid"
fi
output_kept "worker killed"
no_process_left "worker killed"

summary
