# lib.sh - what the shell suites share: the pass and fail counts, a failure line, a
# temporary folder removed when the suite ends, a time limit, the checks of a PPM image,
# and the closing line `N passed, N failed`.
# Sourced from the repository root as `. tests/lib.sh`. See LICENSE for copyright and licence.

passed=0
failed=0
# What a failure line begins with: the suite's file name (`cli.sh: ...`).
label=$(basename "$0")

# ok: one check passed. bad WHAT: one check failed, said on one line.
ok() { passed=$((passed + 1)); }
bad() {
	echo "$label: $*"
	failed=$((failed + 1))
}

# summary: the suite's last command, `N passed, N failed`; its status says whether all passed.
summary() {
	echo "$passed passed, $failed failed"
	[ "$failed" -eq 0 ]
}

# rt_absolute: $RT (default ./rt) made absolute, so that a test may run from another folder.
rt_absolute() {
	RT=${RT:-./rt}
	case $RT in
	/*) ;;
	*) RT=$(pwd)/$RT ;;
	esac
}

# make_tmp: $tmp, a new folder (rt-SUITE.XXXXXX) removed however the suite ends.
make_tmp() {
	tmp=$(mktemp -d "${TMPDIR:-/tmp}/rt-$(basename "$0" .sh).XXXXXX") || exit 1
	trap 'rm -rf "$tmp"' EXIT
	trap 'exit 1' HUP INT TERM
}

# within SECONDS COMMAND...: COMMAND, stopped after SECONDS with status 124 (a hang is a
# failure, not a stuck test run); with no timeout(1) on the machine, COMMAND unbounded.
if command -v timeout >/dev/null 2>&1; then
	has_timeout=1
else
	has_timeout=
fi
within() {
	if [ -n "$has_timeout" ]; then
		timeout "$@"
	else
		shift
		"$@"
	fi
}

# run ARGS...: $RT with standard output in $tmp/out, standard error in $tmp/err and the
# exit status in $status; within $run_limit seconds when the suite sets it.
# shellcheck disable=SC2034 # status is the suites' to read
run() {
	if [ -n "${run_limit:-}" ]; then
		within "$run_limit" "$RT" "$@" >"$tmp/out" 2>"$tmp/err"
	else
		"$RT" "$@" >"$tmp/out" 2>"$tmp/err"
	fi
	status=$?
}

# size_of FILE: its length in bytes.
size_of() { wc -c <"$1" | tr -d ' '; }

# ppm_header_is FILE W H: FILE begins with exactly the P6 header of a WxH image.
ppm_header_is() {
	printf 'P6\n%d %d\n255\n' "$2" "$3" >"$tmp/header"
	dd if="$1" bs="$(size_of "$tmp/header")" count=1 2>/dev/null | cmp -s - "$tmp/header"
}

# ppm_size W H: the bytes of a WxH P6 image, header and pixels.
ppm_size() {
	printf 'P6\n%d %d\n255\n' "$1" "$2" >"$tmp/header"
	echo $(($(size_of "$tmp/header") + $1 * $2 * 3))
}
