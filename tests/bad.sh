#!/bin/sh
# bad.sh - hostile input from outside: every malformed scene in tests/bad/ is refused with
# its message and line, every valid but unusual one in tests/good/ renders, and a run that
# fails or is killed never damages an existing output file.
# Run from the repository root as `RT=./rt sh tests/bad.sh`; prints `bad.sh: NAME: what`
# per failure and ends with `N passed, N failed` (one count per case).
# See LICENSE for copyright and licence.
#
# Each case's first line says what rt must do:
#   # expect LINE: FRAGMENT            (tests/bad: the error's line and a fixed-string part)
#   # expect ok                        (tests/good: an image and nothing on stderr)
#   # expect warning LINE: FRAGMENT    (tests/good: an image and exactly that warning)
# A UTF-16 case carries this line in UTF-16: its NUL and byte-order-mark bytes are dropped
# before reading it (so are a UTF-8 mark's and a CR).

. tests/lib.sh
RT=${RT:-./rt}
# Bytes, not characters: the cases hold invalid UTF-8 on purpose.
LC_ALL=C
export LC_ALL
# A hang is a failure, not a stuck test run: every run stops after 10 s (lib.sh's run).
run_limit=10
make_tmp

# ---- helpers (ok, run, size_of and the PPM checks are in tests/lib.sh) ----------------

problems=0
# problem NAME WHAT: one failure line; the case fails.
problem() {
	echo "$label: $1: $2"
	problems=$((problems + 1))
}

# start_case / end_case: a case passes when no check in it found a problem.
start_case() { problems=0; }
end_case() {
	if [ "$problems" -eq 0 ]; then ok; else failed=$((failed + 1)); fi
}

# expectation FILE: the first line without its `# expect ` (and without NUL, BOM and CR).
expectation() {
	dd if="$1" bs=512 count=1 2>/dev/null | tr -d '\000\357\273\277\376\377\r' | head -n 1 | sed -n 's/^# expect //p'
}

# describe_status: a readable account of $status.
describe_status() {
	if [ "$status" -eq 124 ] && [ -n "$has_timeout" ]; then
		echo "timed out after $run_limit s"
	elif [ "$status" -gt 128 ]; then
		echo "killed by signal $((status - 128))"
	else
		echo "exit status $status"
	fi
}

lines_of() { wc -l <"$1" | tr -d ' '; }
first_err() { head -n 3 "$tmp/err" | cut -c 1-200; }

# scene_size FILE: "W H" from the last `resolution` in the scene (a later `v` replaces an
# earlier one); comments removed and every whitespace byte a separator, as rt reads it.
scene_size() {
	tr '\r\f\v\t' '    ' <"$1" | sed 's/#.*//' | awk '
		{ for (i = 1; i <= NF; i++) {
			if (want == 2) { w = $i; want = 1 }
			else if (want == 1) { h = $i; want = 0 }
			else if ($i == "resolution") want = 2
		} }
		END { print w " " h }'
}

# check_ppm NAME FILE W H: FILE is exactly a P6 header for WxH and W*H*3 bytes.
check_ppm() {
	ppm_header_is "$2" "$3" "$4" || problem "$1" "the image does not start with 'P6 $3 $4 255'"
	want=$(ppm_size "$3" "$4")
	got=$(size_of "$2")
	[ "$got" -eq "$want" ] || problem "$1" "the image is $got bytes, expected $want"
}

# A folder holding one file with known content: an -o run must leave it exactly so.
printf 'precious\n' >"$tmp/precious"
fresh_o() {
	rm -rf "$tmp/o"
	mkdir "$tmp/o"
	cp "$tmp/precious" "$tmp/o/image.ppm"
}

# check_o_untouched NAME: only image.ppm is in $tmp/o, and it still holds "precious".
check_o_untouched() {
	cmp -s "$tmp/precious" "$tmp/o/image.ppm" || problem "$1" "-o changed the existing file"
	left=$(ls -A "$tmp/o")
	[ "$left" = image.ppm ] || problem "$1" "-o left behind: $(ls -A "$tmp/o" | tr '\n' ' ')"
}

# ---- malformed scenes: refused, with the expected line and message -------------------

for f in tests/bad/*.nff; do
	[ -f "$f" ] || continue
	name=$(basename "$f" .nff)
	start_case
	exp=$(expectation "$f")
	line=${exp%%: *}
	fragment=${exp#*: }
	case $line in
	'' | *[!0-9]*)
		problem "$name" "first line is not '# expect LINE: FRAGMENT'"
		end_case
		continue
		;;
	esac

	# A capacity's limit is tested on a build of the old, small capacities (LIMITS_RT,
	# build/rt-limits): a scene past 2 M objects would be tens of megabytes.
	case $fragment in
	*RT_MAX_*) rt_saved=$RT RT=${LIMITS_RT:-$RT} ;;
	*) rt_saved=$RT ;;
	esac
	run "$f"
	[ "$status" -eq 1 ] || problem "$name" "$(describe_status), expected 1"
	[ -s "$tmp/out" ] && problem "$name" "wrote to stdout"
	n=$(lines_of "$tmp/err")
	if [ "$n" -ne 1 ]; then
		problem "$name" "$n lines on stderr, expected 1: $(first_err)"
	else
		message=$(cat "$tmp/err")
		case $message in
		"rt: $f:$line: warning: "*) problem "$name" "a warning, not an error: $message" ;;
		"rt: $f:$line: "*"$fragment"*) ;;
		"rt: $f:$line: "*) problem "$name" "message lacks '$fragment': $message" ;;
		*) problem "$name" "expected 'rt: $f:$line: ...', got: $message" ;;
		esac
	fi

	# The same failure with -o over an existing file.
	fresh_o
	run -o "$tmp/o/image.ppm" "$f"
	[ "$status" -eq 1 ] || problem "$name" "-o: $(describe_status), expected 1"
	[ -s "$tmp/out" ] && problem "$name" "-o: wrote to stdout"
	check_o_untouched "$name"
	RT=$rt_saved
	end_case
done

# ---- valid but unusual scenes: rendered, with the expected warning or none ------------

for f in tests/good/*.nff; do
	[ -f "$f" ] || continue
	name=good/$(basename "$f" .nff)
	start_case
	exp=$(expectation "$f")
	case $exp in
	ok) line= ;;
	'warning '[0-9]*': '*)
		exp=${exp#warning }
		line=${exp%%: *}
		fragment=${exp#*: }
		;;
	*)
		problem "$name" "first line is not '# expect ok' or '# expect warning LINE: FRAGMENT'"
		end_case
		continue
		;;
	esac

	run "$f"
	[ "$status" -eq 0 ] || problem "$name" "$(describe_status), expected 0: $(first_err)"
	if [ -z "$line" ]; then
		[ -s "$tmp/err" ] && problem "$name" "unexpected stderr: $(first_err)"
	else
		n=$(lines_of "$tmp/err")
		message=$(cat "$tmp/err")
		if [ "$n" -ne 1 ]; then
			problem "$name" "$n lines on stderr, expected 1 warning: $(first_err)"
		else
			case $message in
			"rt: $f:$line: warning: "*"$fragment"*) ;;
			*) problem "$name" "expected 'rt: $f:$line: warning: ...$fragment...', got: $message" ;;
			esac
		fi
	fi
	# shellcheck disable=SC2046 # split on purpose: "W H" into $1 and $2
	set -- $(scene_size "$f")
	if [ $# -ne 2 ]; then
		problem "$name" "no 'resolution W H' found in the scene"
	else
		check_ppm "$name" "$tmp/out" "$1" "$2"
	fi

	# With -o the same image replaces the existing file, and nothing else is left.
	cp "$tmp/out" "$tmp/image.ppm"
	fresh_o
	run -o "$tmp/o/image.ppm" "$f"
	[ "$status" -eq 0 ] || problem "$name" "-o: $(describe_status), expected 0"
	[ -s "$tmp/out" ] && problem "$name" "-o: wrote to stdout"
	cmp -s "$tmp/image.ppm" "$tmp/o/image.ppm" || problem "$name" "-o: the file differs from stdout's image"
	left=$(ls -A "$tmp/o")
	[ "$left" = image.ppm ] || problem "$name" "-o: left behind: $(ls -A "$tmp/o" | tr '\n' ' ')"
	end_case
done

# ---- a run killed mid-render ----------------------------------------------------------
# The target is replaced only by the final rename, so it is untouched; rt also removes its
# temporary file when a signal stops it. The render is far too large to finish first.

if sleep 0.1 2>/dev/null; then
	nap=0.1
	naps=200 # 20 s
else
	nap=1
	naps=20
fi

# wait_for_temp NAME: waits until rt's temporary file is beside image.ppm (mid-render).
wait_for_temp() {
	tries=0
	while [ "$(ls -A "$tmp/o" | wc -l)" -lt 2 ] && [ "$tries" -lt "$naps" ]; do
		sleep "$nap"
		tries=$((tries + 1))
	done
	[ "$(ls -A "$tmp/o" | wc -l)" -ge 2 ] || problem "$1" "no temporary file appeared"
}

# Every signal whose default ends the process: rt removes its temporary file and then ends
# as the signal ends it, with the same exit status as a process that does not catch it.
# rt starts with every signal at its default (a background job of this shell would have
# SIGINT and SIGQUIT ignored, python3 SIGPIPE and SIGXFSZ, and rt keeps ignored signals
# ignored); no core files.
ulimit -c 0 2>/dev/null
for sig in TERM HUP PIPE INT QUIT ALRM USR1 USR2 XCPU XFSZ VTALRM PROF; do
	name="killed by SIG$sig"
	start_case
	fresh_o
	expected=$(python3 -c 'import os, signal, sys
for s in (signal.SIGINT, signal.SIGQUIT, signal.SIGPIPE, signal.SIGXFSZ): signal.signal(s, signal.SIG_DFL)
os.execvp("sh", ["sh", "-c", "kill -s " + sys.argv[1] + " $$"])' "$sig" >/dev/null 2>&1; echo $?)
	python3 -c 'import os, signal, sys
for s in (signal.SIGINT, signal.SIGQUIT, signal.SIGPIPE, signal.SIGXFSZ): signal.signal(s, signal.SIG_DFL)
os.execvp(sys.argv[1], sys.argv[1:])' "$RT" -s 8192x8192 -o "$tmp/o/image.ppm" scenes/showpiece.nff \
		2>/dev/null &
	pid=$!
	wait_for_temp "$name"
	kill -s "$sig" "$pid" 2>/dev/null
	{ wait "$pid"; } 2>/dev/null # the shell reports the signal death otherwise
	status=$?
	[ "$status" -gt 128 ] && [ "$status" -eq "$expected" ] ||
		problem "$name" "$(describe_status), expected $expected (death by the signal)"
	check_o_untouched "$name"
	end_case
done

# A signal the caller ignores (nohup's SIGHUP) stays ignored: the run goes on.
name="ignored SIGHUP"
start_case
fresh_o
(
	trap '' HUP
	exec "$RT" -s 8192x8192 -o "$tmp/o/image.ppm" scenes/showpiece.nff 2>/dev/null
) &
pid=$!
wait_for_temp "$name"
kill -s HUP "$pid" 2>/dev/null
sleep "$nap"
kill -s 0 "$pid" 2>/dev/null || problem "$name" "rt died of a signal it was told to ignore"
kill -s TERM "$pid" 2>/dev/null
{ wait "$pid"; } 2>/dev/null
check_o_untouched "$name"
end_case

summary
