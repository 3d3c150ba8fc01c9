#!/bin/sh
# cli.sh - the command line from outside: options, exit status, messages and output bytes.
# Run from the repository root as `RT=./rt sh tests/cli.sh`; ends with `N passed, N failed`.
# See LICENSE for copyright and licence.

. tests/lib.sh
rt_absolute
make_tmp

# ---- helpers (ok, bad, run, size_of and the PPM checks are in tests/lib.sh) ----------

# expect_status WHAT N: the last run exited with N.
expect_status() {
	if [ "$status" -eq "$2" ]; then ok; else bad "$1: exit status $status, expected $2"; fi
}

# expect_err WHAT TEXT: standard error holds TEXT (a fixed string).
expect_err() {
	if grep -q -F -e "$2" "$tmp/err"; then ok; else
		bad "$1: stderr lacks '$2' (got: $(head -n 3 "$tmp/err"))"
	fi
}

# expect_no_stdout WHAT: nothing at all was written to standard output.
expect_no_stdout() {
	if [ -s "$tmp/out" ]; then bad "$1: unexpected output on stdout"; else ok; fi
}

# expect_no_stderr WHAT
expect_no_stderr() {
	if [ -s "$tmp/err" ]; then bad "$1: unexpected stderr: $(head -n 3 "$tmp/err")"; else ok; fi
}

# expect_ppm WHAT FILE W H: FILE is exactly a P6 header for WxH plus W*H*3 bytes.
expect_ppm() {
	if ppm_header_is "$2" "$3" "$4"; then ok; else bad "$1: header is not 'P6 $3 $4 255'"; fi
	want=$(ppm_size "$3" "$4")
	got=$(size_of "$2")
	if [ "$got" -eq "$want" ]; then ok; else bad "$1: $got bytes, expected $want"; fi
}

# pixel FILE X Y: the three bytes of pixel (X, Y), as "R G B".
pixel() {
	w=$(sed -n 2p "$1" | cut -d ' ' -f 1)
	h=$(sed -n 2p "$1" | cut -d ' ' -f 2)
	# "P6\n" W " " H "\n255\n"
	hdr=$((${#w} + ${#h} + 9))
	set -- $(od -An -tu1 -j $((hdr + ($3 * w + $2) * 3)) -N 3 "$1" 2>/dev/null)
	echo "$1 $2 $3"
}

# expect_pixel WHAT FILE X Y "R G B"
expect_pixel() {
	got=$(pixel "$2" "$3" "$4")
	if [ "$got" = "$5" ]; then ok; else bad "$1: pixel ($3, $4) is '$got', expected '$5'"; fi
}

# stat_of NAME: the value of `NAME: value` in the last run's stderr.
stat_of() { sed -n "s/^$1: //p" "$tmp/err"; }

# expect_stat WHAT NAME OP VALUE, with OP one of test's -eq -gt ...
expect_stat() {
	v=$(stat_of "$2")
	case $v in
	'' | *[!0-9]*) bad "$1: $2 is '$v', not a whole number" ;;
	*) if [ "$v" "$3" "$4" ]; then ok; else bad "$1: $2 is $v, expected $3 $4"; fi ;;
	esac
}

# expect_same WHAT A B: byte-for-byte identical files.
expect_same() {
	if cmp -s "$2" "$3"; then ok; else bad "$1: $2 and $3 differ"; fi
}

# ---- scenes --------------------------------------------------------------------------

view() {
	printf 'v\nfrom %s\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution %s\n' "$1" "$2"
}

# A lit, diffuse sphere on a coloured background (b decodes to linear and back exactly).
{
	view "0 0 -10" "16 12"
	printf 'b 0.2 0.4 0.6\nl -5 5 -10\nf 1 0.5 0.2 0.8 0 1 0 1\ns 0 0 0 3\n'
} >"$tmp/ok.nff"

# The same scene with CRLF line ends, and without its final newline.
sed 's/$/\r/' "$tmp/ok.nff" >"$tmp/crlf.nff"
printf '%s' "$(cat "$tmp/ok.nff")" >"$tmp/nonl.nff"

# A mirror sphere (Ks > 0), a glass sphere (T > 0), and the eye inside a glass sphere.
{
	view "0 0 -10" "16 12"
	printf 'l -5 5 -10\nf 1 1 1 0.5 0.5 10 0 1\ns 0 0 0 3\n'
} >"$tmp/mirror.nff"
{
	view "0 0 -10" "16 12"
	printf 'b 0.2 0.4 0.6\nl -5 5 -10\nf 1 1 1 0 0 0 0.9 1.5\ns 0 0 0 3\n'
} >"$tmp/glass.nff"
{
	view "0 0 -1" "16 12"
	printf 'b 0.2 0.4 0.6\nl 0 0 -2\nf 0.9 0.9 1 0.2 0 0 0.8 1.3\ns 0 0 0 20\n'
	printf 'f 1 0 0 1 0 0 0 1\ns 0 0 8 2\n'
} >"$tmp/inside.nff"

# Nothing but a view and a background; and an object with no light at all.
{
	view "0 0 -10" "16 12"
	printf 'b 0.2 0.4 0.6\n'
} >"$tmp/empty.nff"
{
	view "0 0 -10" "16 12"
	printf 'b 0.2 0.4 0.6\ns 0 0 0 3\n'
} >"$tmp/unlit.nff"

# An error on line 9, and a skipped zero-radius sphere on line 8.
{
	view "0 0 -10" "16 12"
	printf 's 0 0 0 1\ns 0 0 zero 1\n'
} >"$tmp/bad.nff"
{
	view "0 0 -10" "16 12"
	printf 's 0 0 0 0\n'
} >"$tmp/warn.nff"

# ---- help, version, usage errors ----------------------------------------------------

run --help
expect_status "--help" 0
expect_no_stderr "--help"
if grep -q '^Usage: rt ' "$tmp/out"; then ok; else bad "--help: no 'Usage: rt' line on stdout"; fi

run --version
expect_status "--version" 0
expect_no_stderr "--version"
if grep -q '^rt [0-9]' "$tmp/out"; then ok; else bad "--version: no 'rt VERSION' on stdout"; fi

# --print-size: the image size the options give, without rendering.
run --print-size scenes/mcu-demo.nff
expect_status "--print-size" 0
if [ "$(cat "$tmp/out")" = "160 100" ]; then ok; else bad "--size: expected '160 100', got '$(cat "$tmp/out")'"; fi
run -s 33x21 --print-size scenes/mcu-demo.nff
if [ "$(cat "$tmp/out")" = "33 21" ]; then ok; else bad "--size -s 33x21: got '$(cat "$tmp/out")'"; fi
run --ascii --cols 40 --print-size scenes/mcu-demo.nff
if [ "$(cat "$tmp/out")" = "40 26" ]; then ok; else bad "--size --ascii --cols 40: got '$(cat "$tmp/out")'"; fi

# usage WHAT ARGS...: exit 2, nothing on stdout, a hint on stderr.
usage() {
	what=$1
	shift
	run "$@"
	expect_status "usage: $what" 2
	expect_no_stdout "usage: $what"
	expect_err "usage: $what" "rt: "
	expect_err "usage: $what" "Try 'rt --help'"
}
usage "no scene"
usage "unknown option" --frobnicate "$tmp/ok.nff"
usage "-s 0x5" -s 0x5 "$tmp/ok.nff"
usage "-s 10" -s 10 "$tmp/ok.nff"
usage "-s 5x" -s 5x "$tmp/ok.nff"
usage "-s x5" -s x5 "$tmp/ok.nff"
usage "-s -4x4" -s -4x4 "$tmp/ok.nff"
usage "-s 4x4x4" -s 4x4x4 "$tmp/ok.nff"
usage "-d 0" -d 0 "$tmp/ok.nff"
usage "-d 99" -d 99 "$tmp/ok.nff"
usage "-d x" -d x "$tmp/ok.nff"
usage "-d without a value" "$tmp/ok.nff" -d
usage "-o without a value" "$tmp/ok.nff" -o
usage "two scenes" "$tmp/ok.nff" "$tmp/ok.nff"
run -s 0x5 "$tmp/ok.nff"
expect_err "-s 0x5" "bad size '0x5'"
run -d 99 "$tmp/ok.nff"
expect_err "-d 99" "bad depth '99'"

# ---- scene errors -------------------------------------------------------------------

run "$tmp/none.nff"
expect_status "missing scene" 1
expect_no_stdout "missing scene"
expect_err "missing scene" "rt: $tmp/none.nff: cannot open"

run "$tmp/bad.nff"
expect_status "scene error" 1
expect_no_stdout "scene error"
expect_err "scene error" "rt: $tmp/bad.nff:9: expected a number (sphere centre), got 'zero'"
if [ "$(wc -l <"$tmp/err" | tr -d ' ')" -eq 1 ]; then ok; else bad "scene error: not one line"; fi

# A warning is not an error: the image is still written.
run "$tmp/warn.nff"
expect_status "warning" 0
expect_err "warning" "rt: $tmp/warn.nff:8: warning: sphere with radius 0; skipped"
expect_ppm "warning" "$tmp/out" 16 12

# ---- images ---------------------------------------------------------------------------

run "$tmp/ok.nff"
expect_status "render" 0
expect_no_stderr "render"
expect_ppm "render" "$tmp/out" 16 12
cp "$tmp/out" "$tmp/ok.ppm"
# Corner pixel: the background, b 0.2 0.4 0.6 = codes 51 102 153.
expect_pixel "render" "$tmp/ok.ppm" 0 0 "51 102 153"

run -s 7x5 "$tmp/ok.nff"
expect_status "-s 7x5" 0
expect_ppm "-s 7x5" "$tmp/out" 7 5
run -s 1x1 "$tmp/ok.nff"
expect_ppm "-s 1x1" "$tmp/out" 1 1

# Determinism: the same run twice gives the same bytes (glass exercises every ray kind).
run "$tmp/glass.nff"
cp "$tmp/out" "$tmp/glass1.ppm"
run "$tmp/glass.nff"
expect_same "determinism" "$tmp/glass1.ppm" "$tmp/out"
run --spd "$tmp/mirror.nff"
cp "$tmp/out" "$tmp/mirror1.ppm"
run --spd "$tmp/mirror.nff"
expect_same "determinism --spd" "$tmp/mirror1.ppm" "$tmp/out"

# ---- -o -------------------------------------------------------------------------------

mkdir "$tmp/o"
run "$tmp/ok.nff" -o "$tmp/o/image.ppm"
expect_status "-o" 0
expect_no_stdout "-o"
expect_no_stderr "-o"
expect_same "-o" "$tmp/ok.ppm" "$tmp/o/image.ppm"
if [ "$(ls -A "$tmp/o")" = image.ppm ]; then ok; else bad "-o: left behind: $(ls -A "$tmp/o")"; fi
# The image gets an ordinary file's mode, not mkstemp's private 0600.
(
	umask 022
	rm -f "$tmp/o/image.ppm"
	"$RT" "$tmp/ok.nff" -o "$tmp/o/image.ppm"
)
case $(ls -l "$tmp/o/image.ppm" 2>/dev/null) in
-rw-r--r--*) ok ;;
*) bad "-o: new file mode is $(ls -l "$tmp/o/image.ppm" | cut -c 1-10), expected -rw-r--r--" ;;
esac

# A failing scene leaves an existing file exactly as it was, and no temporary file.
mkdir "$tmp/keep"
printf 'precious\n' >"$tmp/keep/image.ppm"
cp "$tmp/keep/image.ppm" "$tmp/precious"
run "$tmp/bad.nff" -o "$tmp/keep/image.ppm"
expect_status "-o, failing scene" 1
expect_no_stdout "-o, failing scene"
expect_same "-o, failing scene" "$tmp/precious" "$tmp/keep/image.ppm"
if [ "$(ls -A "$tmp/keep")" = image.ppm ]; then ok; else
	bad "-o, failing scene: left behind: $(ls -A "$tmp/keep")"
fi
# A good scene replaces it, keeping its mode.
chmod 640 "$tmp/keep/image.ppm"
run "$tmp/ok.nff" -o "$tmp/keep/image.ppm"
expect_status "-o, replace" 0
expect_same "-o, replace" "$tmp/ok.ppm" "$tmp/keep/image.ppm"
case $(ls -l "$tmp/keep/image.ppm" 2>/dev/null) in
-rw-r-----*) ok ;;
*) bad "-o, replace: mode is $(ls -l "$tmp/keep/image.ppm" | cut -c 1-10), expected -rw-r-----" ;;
esac
if [ "$(ls -A "$tmp/keep")" = image.ppm ]; then ok; else
	bad "-o, replace: left behind: $(ls -A "$tmp/keep")"
fi

run "$tmp/ok.nff" -o "$tmp/no/such/dir/image.ppm"
expect_status "-o into a missing directory" 1
expect_no_stdout "-o into a missing directory"
expect_err "-o into a missing directory" "rt: $tmp/no/such/dir/image.ppm: "
if [ ! -e "$tmp/no" ]; then ok; else bad "-o into a missing directory: it was created"; fi

# A path far longer than a message: its start is cut, the line and the reason stay.
long=$tmp/$(awk 'BEGIN { while (length(s) < 250) s = s "d"; print s }')
mkdir -p "$long/$(basename "$long")"
long=$long/$(basename "$long")
cp "$tmp/bad.nff" "$long/bad.nff"
run "$long/bad.nff"
expect_status "a 500-byte path" 1
expect_err "a 500-byte path" "ddd/bad.nff:9: expected a number (sphere centre), got 'zero'"
expect_err "a 500-byte path" "rt: ..."

# One output per run: a second -o is a usage error, not a silent choice.
run "$tmp/ok.nff" -o "$tmp/o/a.ppm" -o "$tmp/o/b.ppm"
expect_status "-o twice" 2
expect_err "-o twice" "rt: more than one output file given ('$tmp/o/b.ppm')"
# A folder as the scene says what it is (it opens, and reads as nothing).
run "$tmp"
expect_status "a folder as the scene" 1
expect_err "a folder as the scene" "rt: $tmp: cannot read: Is a directory"

# ---- -o behaves as the shell's > where a user expects it to -----------------------------
mkdir "$tmp/rules"
cd "$tmp/rules" || exit 1
# A symbolic link: its target is replaced, the link stays a link.
printf 'old\n' >target.ppm
ln -s target.ppm link.ppm
run "$tmp/ok.nff" -o link.ppm
expect_status "-o through a symlink" 0
if [ -L link.ppm ]; then ok; else bad "-o through a symlink: the link was replaced"; fi
expect_same "-o through a symlink" "$tmp/ok.ppm" target.ppm
# A dangling link: the file it names is created.
ln -s made.ppm dangling.ppm
run "$tmp/ok.nff" -o dangling.ppm
expect_status "-o through a dangling symlink" 0
if [ -L dangling.ppm ]; then ok; else bad "-o through a dangling symlink: the link was replaced"; fi
expect_same "-o through a dangling symlink" "$tmp/ok.ppm" made.ppm
# Hard links stay one file: both names see the new image.
printf 'old\n' >first.ppm
ln first.ppm second.ppm
run "$tmp/ok.nff" -o first.ppm
expect_status "-o onto a hard link" 0
expect_same "-o onto a hard link" "$tmp/ok.ppm" second.ppm
if [ "$(ls -i first.ppm | cut -d' ' -f1)" = "$(ls -i second.ppm | cut -d' ' -f1)" ]; then ok; else
	bad "-o onto a hard link: the links were split"
fi
# A FIFO is written straight into, and its reader gets the image.
if mkfifo pipe.ppm 2>/dev/null; then
	# The reader gives up after 10 s: a FIFO replaced by a file would block it forever.
	within 10 cat pipe.ppm >from-pipe.ppm &
	reader=$!
	run "$tmp/ok.nff" -o pipe.ppm
	wait "$reader"
	expect_status "-o into a FIFO" 0
	expect_same "-o into a FIFO" "$tmp/ok.ppm" from-pipe.ppm
	if [ -p pipe.ppm ]; then ok; else bad "-o into a FIFO: it was replaced"; fi
fi
# Names of 246 to 255 bytes: the temporary name is cut to fit NAME_MAX, the file is not.
for n in 246 251 255; do
	name=$(awk -v n="$n" 'BEGIN { while (length(s) < n - 4) s = s "x"; print s ".ppm" }')
	run "$tmp/ok.nff" -o "$name"
	expect_status "-o with a $n-byte name" 0
	expect_same "-o with a $n-byte name" "$tmp/ok.ppm" "$name"
	rm -f "$name"
done
if [ "$(ls -A | grep -c tmp)" -eq 0 ]; then ok; else bad "-o rules: left behind: $(ls -A | grep tmp)"; fi
# As a user who owns none of it (root runs these as nobody): a file of mode 0444 is
# refused as the shell refuses it and kept; a writable file of another owner keeps its
# owner and inode; a writable file in a folder the user cannot write is written.
as_user=
if [ "$(id -u)" -ne 0 ]; then
	as_user=" "
elif command -v setpriv >/dev/null 2>&1; then
	as_user="setpriv --reuid=65534 --regid=65534 --clear-groups"
fi
if [ -n "$as_user" ]; then
	mkdir shared readonly
	cp "$tmp/ok.nff" shared/scene.nff
	chmod 777 shared
	printf 'old\n' >shared/locked.ppm
	chmod 444 shared/locked.ppm
	[ "$(id -u)" -eq 0 ] && chown 65534 shared/locked.ppm
	$as_user "$RT" shared/scene.nff -o shared/locked.ppm >"$tmp/out" 2>"$tmp/err"
	status=$?
	expect_status "-o onto a read-only file" 1
	expect_err "-o onto a read-only file" "rt: shared/locked.ppm: cannot write: Permission denied"
	if [ "$(cat shared/locked.ppm)" = old ]; then ok; else bad "-o onto a read-only file: it changed"; fi
	if [ "$(id -u)" -eq 0 ]; then
		printf 'old\n' >shared/theirs.ppm
		chmod 666 shared/theirs.ppm
		inode=$(ls -i shared/theirs.ppm | cut -d' ' -f1)
		$as_user "$RT" shared/scene.nff -o shared/theirs.ppm >"$tmp/out" 2>"$tmp/err"
		status=$?
		expect_status "-o onto another owner's file" 0
		expect_same "-o onto another owner's file" "$tmp/ok.ppm" shared/theirs.ppm
		if [ "$(ls -ln shared/theirs.ppm | awk '{ print $3 }')" = 0 ] &&
			[ "$(ls -i shared/theirs.ppm | cut -d' ' -f1)" = "$inode" ]; then ok; else
			bad "-o onto another owner's file: owner or inode changed"
		fi
	fi
	printf 'old\n' >readonly/open.ppm
	chmod 666 readonly/open.ppm
	chmod 555 readonly
	$as_user "$RT" shared/scene.nff -o readonly/open.ppm >"$tmp/out" 2>"$tmp/err"
	status=$?
	expect_status "-o in a read-only folder" 0
	expect_same "-o in a read-only folder" "$tmp/ok.ppm" readonly/open.ppm
	$as_user "$RT" shared/scene.nff -o readonly/new.ppm >"$tmp/out" 2>"$tmp/err"
	status=$?
	expect_status "-o, new file in a read-only folder" 1
	expect_err "-o, new file in a read-only folder" "rt: readonly/new.ppm: cannot create: Permission denied"
	chmod 755 readonly
else
	echo "cli.sh: -o as another user: skipped (running as root without setpriv)"
fi
cd - >/dev/null || exit 1

# Standard output that cannot be written.
if [ -w /dev/full ]; then
	# The short answers too: a help, a version or a size that was not written is a failure.
	for what in --help --version "--print-size $tmp/ok.nff"; do
		# shellcheck disable=SC2086 # "--print-size FILE" is two words
		"$RT" $what >/dev/full 2>"$tmp/err"
		status=$?
		expect_status "$what to /dev/full" 1
		expect_err "$what to /dev/full" "rt: write error: standard output: "
	done
	"$RT" "$tmp/ok.nff" >/dev/full 2>"$tmp/err"
	status=$?
	expect_status "stdout to /dev/full" 1
	expect_err "stdout to /dev/full" "rt: write error"
	# Larger than any stdio buffer: the write fails during the render, reported once.
	"$RT" -s 300x300 "$tmp/ok.nff" >/dev/full 2>"$tmp/err"
	status=$?
	expect_status "large image to /dev/full" 1
	expect_err "large image to /dev/full" "rt: write error"
	n=$(grep -c 'write error' "$tmp/err")
	if [ "$n" -eq 1 ]; then ok; else bad "large image to /dev/full: $n write errors"; fi
fi

# ---- --stats ---------------------------------------------------------------------------

run --stats "$tmp/mirror.nff"
expect_status "--stats" 0
expect_ppm "--stats" "$tmp/out" 16 12
for key in eye_rays eye_hits shadow_rays reflect_rays refract_rays seconds rays_per_second; do
	n=$(grep -c "^$key: [0-9][0-9.]*\$" "$tmp/err")
	if [ "$n" -eq 1 ]; then ok; else bad "--stats: $n lines '$key: value', expected 1"; fi
done
# Every line is `name: value`.
stat_line='^[a-z_]*: [0-9][0-9.]*$'
if grep -v -q "$stat_line" "$tmp/err"; then
	bad "--stats: a line is not 'name: value': $(grep -v "$stat_line" "$tmp/err" | head -n 1)"
else
	ok
fi
expect_stat "--stats" eye_rays -eq 192
expect_stat "mirror" eye_hits -gt 0
expect_stat "mirror" eye_hits -lt 192
expect_stat "mirror" shadow_rays -gt 0
expect_stat "mirror" reflect_rays -gt 0
expect_stat "mirror" refract_rays -eq 0

run --stats -d 1 "$tmp/mirror.nff"
expect_stat "-d 1" reflect_rays -eq 0
expect_stat "-d 1" eye_rays -eq 192

run --stats "$tmp/ok.nff"
expect_stat "no Ks" reflect_rays -eq 0
expect_stat "no Ks" refract_rays -eq 0

run --stats "$tmp/glass.nff"
expect_stat "glass" refract_rays -gt 0

# --spd shoots rays through the (W+1) x (H+1) pixel corners.
run --stats --spd -s 8x6 "$tmp/ok.nff"
expect_status "--spd" 0
expect_ppm "--spd" "$tmp/out" 8 6
expect_stat "--spd -s 8x6" eye_rays -eq 63
run --stats -s 8x6 "$tmp/ok.nff"
expect_stat "-s 8x6" eye_rays -eq 48

# Statistics go to stderr only: the image on stdout is the same with and without them.
run --stats "$tmp/ok.nff"
expect_same "--stats" "$tmp/ok.ppm" "$tmp/out"

# ---- unusual inputs ------------------------------------------------------------------

run "$tmp/crlf.nff"
expect_status "CRLF scene" 0
expect_no_stderr "CRLF scene"
expect_same "CRLF scene" "$tmp/ok.ppm" "$tmp/out"

# Lone CRs end lines too (old Mac files): a comment ends at one, and errors name the line.
{
	printf '# a comment, then the scene\n'
	cat "$tmp/ok.nff"
} | tr '\n' '\r' >"$tmp/cr.nff"
run "$tmp/cr.nff"
expect_status "CR scene" 0
expect_no_stderr "CR scene"
expect_same "CR scene" "$tmp/ok.ppm" "$tmp/out"
tr '\n' '\r' <"$tmp/bad.nff" >"$tmp/cr-bad.nff"
run "$tmp/cr-bad.nff"
expect_status "CR scene with an error" 1
expect_err "CR scene with an error" "rt: $tmp/cr-bad.nff:9: "
# CR LF counts one line, not two.
sed 's/$/\r/' "$tmp/bad.nff" >"$tmp/crlf-bad.nff"
run "$tmp/crlf-bad.nff"
expect_err "CRLF scene with an error" "rt: $tmp/crlf-bad.nff:9: "

run "$tmp/nonl.nff"
expect_status "no final newline" 0
expect_same "no final newline" "$tmp/ok.ppm" "$tmp/out"

run --stats "$tmp/inside.nff"
expect_status "eye inside glass" 0
expect_ppm "eye inside glass" "$tmp/out" 16 12
expect_stat "eye inside glass" eye_hits -eq 192
expect_stat "eye inside glass" refract_rays -gt 0

run --stats "$tmp/empty.nff"
expect_status "no objects" 0
expect_ppm "no objects" "$tmp/out" 16 12
expect_pixel "no objects" "$tmp/out" 0 0 "51 102 153"
expect_pixel "no objects" "$tmp/out" 8 6 "51 102 153"
expect_pixel "no objects" "$tmp/out" 15 11 "51 102 153"
expect_stat "no objects" eye_hits -eq 0

# No light and no ambient: the sphere is black, the background still shows.
run "$tmp/unlit.nff"
expect_status "no lights" 0
expect_pixel "no lights" "$tmp/out" 8 6 "0 0 0"
expect_pixel "no lights" "$tmp/out" 0 0 "51 102 153"

# ---- previews and image formats -------------------------------------------------------
run --ascii --cols 60 scenes/mirror-spheres.nff
expect_status "--ascii" 0
if awk 'length($0) > 60 { bad = 1 } END { exit bad }' "$tmp/out"; then ok; else
	bad "--ascii --cols 60: a line is longer than 60"
fi
if LC_ALL=C grep -q '[^ -~]' "$tmp/out"; then bad "--ascii: a byte outside printable ASCII"; else ok; fi
# 320x240 at 60 columns: 45 square pixels tall, so 23 lines of two pixels each.
if [ "$(wc -l <"$tmp/out" | tr -d ' ')" -eq 23 ]; then ok; else
	bad "--ascii --cols 60: $(wc -l <"$tmp/out") lines, expected 23"
fi
if cmp -s "$tmp/out" tests/golden/mirror-spheres-40.txt; then ok; else
	"$RT" --ascii --cols 40 scenes/mirror-spheres.nff >"$tmp/out"
	cmp -s "$tmp/out" tests/golden/mirror-spheres-40.txt && ok ||
		bad "--ascii --cols 40: differs from tests/golden/mirror-spheres-40.txt"
fi
esc=$(printf '\033')
COLORTERM=truecolor NO_COLOR= run --ansi --cols 30 scenes/mirror-spheres.nff
if grep -q "${esc}\[38;2;" "$tmp/out" && grep -q "${esc}\[48;2;" "$tmp/out"; then ok; else
	bad "--ansi with COLORTERM=truecolor: no 24-bit colours"
fi
if awk -v e="$esc" '$0 !~ (e "\\[0m$") { bad = 1 } END { exit bad }' "$tmp/out"; then ok; else
	bad "--ansi: a line does not end with a reset"
fi
COLORTERM= NO_COLOR= run --ansi --cols 30 scenes/mirror-spheres.nff
if grep -q "${esc}\[38;5;" "$tmp/out" && ! grep -q "${esc}\[38;2;" "$tmp/out"; then ok; else
	bad "--ansi without COLORTERM: expected 256 colours only"
fi
# The 256-colour palette entry is the nearest in OKLab (a perceptual space), not in RGB:
# this green (52, 157, 69) is (0, 175, 95), index 35; RGB distance chose (95, 175, 95), a
# paler green. An exact palette colour (135, 95, 0), index 94, stays itself.
for case in "0.20392 0.61569 0.27059:35" "0.52941 0.37255 0:94"; do
	printf 'b %s\nv\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 8 6\n' \
		"${case%%:*}" >"$tmp/flat.nff"
	COLORTERM= NO_COLOR= run --ansi --cols 4 "$tmp/flat.nff"
	if grep -q "${esc}\[38;5;${case#*:}m${esc}\[48;5;${case#*:}m" "$tmp/out"; then ok; else
		bad "256 colours: background ${case%%:*} is not palette colour ${case#*:}"
	fi
done
# A colour asked for on the command line wins over NO_COLOR and TERM (no-color.org); the
# preview rt chooses for a terminal itself honours both (below, under `script`).
NO_COLOR=1 COLORTERM=truecolor run --ansi --cols 30 scenes/mirror-spheres.nff
if grep -q "${esc}\[38;2;" "$tmp/out"; then ok; else bad "NO_COLOR with --ansi: no colours"; fi
NO_COLOR=1 TERM=dumb run -o "$tmp/asked.ans" --cols 30 scenes/mirror-spheres.nff
if grep -q "$esc" "$tmp/asked.ans"; then ok; else bad "NO_COLOR, TERM=dumb, -o .ans: no colours"; fi
run -o "$tmp/image.png" scenes/glass.nff
expect_status "-o .png" 0
"$RT" scenes/glass.nff >"$tmp/image.ppm"
if python3 tests/pngcheck.py "$tmp/image.png" "$tmp/image.ppm"; then ok; else
	bad "-o .png: decoded pixels differ from the PPM"
fi
run -o "$tmp/preview.txt" --cols 30 scenes/glass.nff
expect_status "-o .txt" 0
if grep -q "$esc" "$tmp/preview.txt" || [ ! -s "$tmp/preview.txt" ]; then bad "-o .txt: not plain text"; else ok; fi
COLORTERM=truecolor run -o "$tmp/preview.ans" --cols 30 scenes/glass.nff
if grep -q "${esc}\[38;2;" "$tmp/preview.ans"; then ok; else bad "-o .ans: no colour escapes"; fi
run -o "$tmp/image.xyz" scenes/glass.nff
expect_status "-o with an unknown extension" 2
run -o "$tmp/image.png" --ascii scenes/glass.nff
expect_status "-o .png with --ascii" 2
run --ascii --rows 0:4 scenes/glass.nff
expect_status "--rows with a preview" 2
# PNG of any size, streamed: 4000x2200 (the encoder once held the whole image, and refused
# past 2048x2048), a view of the background only, so that it renders fast.
printf 'v from 0 0 -5 at 0 0 0 up 0 1 0 angle 40 hither 0.01 resolution 8 6\nb 0.2 0.4 0.6\n' \
	>"$tmp/sky.nff"
run -s 4000x2200 -o "$tmp/big.png" "$tmp/sky.nff"
expect_status "PNG 4000x2200" 0
run -s 4000x2200 -o "$tmp/big.ppm" "$tmp/sky.nff"
if python3 tests/pngcheck.py "$tmp/big.png" "$tmp/big.ppm"; then ok; else
	bad "PNG 4000x2200: decoded pixels differ from the PPM"
fi
rm -f "$tmp/big.png" "$tmp/big.ppm"

# ---- bands -----------------------------------------------------------------------
# Bands rendered by separate runs and joined (one header, then each band's pixels) are
# byte-identical to the whole image, with centre and with corner (--spd) sampling.
for sampling in "" --spd; do
	"$RT" $sampling -s 37x23 scenes/glass.nff >"$tmp/whole.ppm" 2>/dev/null
	printf 'P6\n37 23\n255\n' >"$tmp/joined.ppm"
	for band in 0:1 1:9 9:10 10:23; do
		"$RT" $sampling -s 37x23 --rows "$band" scenes/glass.nff >"$tmp/band.ppm" 2>/dev/null
		tail -n +4 "$tmp/band.ppm" >>"$tmp/joined.ppm"
	done
	if cmp -s "$tmp/whole.ppm" "$tmp/joined.ppm"; then ok; else
		bad "bands $sampling: joined bands differ from the whole image"
	fi
done
run -s 37x23 --rows 9:10 scenes/glass.nff
expect_ppm "one band" "$tmp/out" 37 1
run -s 37x23 --rows 20:24 scenes/glass.nff
expect_status "band past the image" 2
expect_no_stdout "band past the image"
for rows in 5:5 7:3 x:4 4 -1:3; do
	run --rows "$rows" scenes/glass.nff
	expect_status "--rows $rows" 2
done

# ---- --time-limit ------------------------------------------------------------------
# 1,000 concentric glass spheres at depth 8: about 1 s of CPU at 64x64 and 16 s at 256x256
# (each ray meets every sphere); the limit ends it at 0.3 s wherever it is, the old file kept.
{
	printf 'v from 0 0 -30 at 0 0 0 up 0 1 0 angle 40 hither 0.01 resolution 64 64\n'
	printf 'l -4 3 -20\nl 4 3 -20\nf 0.9 0.9 0.9 0.1 0.5 30 0.9 1.5\n'
	awk 'BEGIN { for (i = 1; i <= 1000; i++) printf "s 0 0 0 %g\n", i * 0.01 }'
} >"$tmp/slow.nff"
mkdir "$tmp/limit"
echo kept >"$tmp/limit/old.ppm"
began=$(date +%s)
run -d 8 --time-limit 0.3 -o "$tmp/limit/old.ppm" "$tmp/slow.nff"
took=$(($(date +%s) - began))
expect_status "--time-limit" 1
expect_err "--time-limit" "slow.nff: the time limit of 0.3 seconds was reached; no image written"
if [ "$took" -le 5 ]; then ok; else bad "--time-limit 0.3: took $took s"; fi

# ---- terminals (through script(1), which gives rt a terminal) --------------------------
# The preview rt chooses for a terminal has no escape sequence under NO_COLOR or TERM=dumb;
# the progress bar (standard error on a terminal, a render of over a second) none under
# TERM=dumb, and its escapes under another TERM show the check can see them.
if command -v script >/dev/null 2>&1 && script -qec true /dev/null >/dev/null 2>&1; then
	for env in "NO_COLOR=1 TERM=xterm" "NO_COLOR= TERM=dumb"; do
		env $env script -qec "'$RT' --cols 30 scenes/mirror-spheres.nff" /dev/null \
			>"$tmp/tty" 2>&1
		if grep -q '#' "$tmp/tty" && ! grep -q "$esc" "$tmp/tty"; then ok; else
			bad "the preview on a terminal with $env: escape sequences, or no preview"
		fi
	done
	# (3 s: the bar shows once a row ends, from half a second on, and a row under the
	# sanitizers on a busy machine took over 1.5 s.)
	for term in xterm dumb; do
		TERM=$term script -qec "'$RT' -d 8 -s 256x256 --time-limit 3 -o '$tmp/bar.ppm' '$tmp/slow.nff'" \
			/dev/null >"$tmp/tty" 2>&1
		if [ $term = dumb ]; then
			if grep -q "$esc" "$tmp/tty"; then bad "TERM=dumb: the progress bar's escapes"; else ok; fi
		elif grep -q "rows" "$tmp/tty" && grep -q "$esc" "$tmp/tty"; then ok; else
			bad "TERM=xterm: no progress bar to see ($(head -c 200 "$tmp/tty"))"
		fi
	done
	# The preview fits the terminal's height too, a line kept for the prompt: a 4:3 scene
	# on a 160 x 30 terminal is 29 lines (the width alone gave 60); a tall, narrow one is
	# bound by its width.
	script -qec "stty rows 30 cols 160; '$RT' scenes/glass.nff" /dev/null >"$tmp/tty" 2>&1
	lines=$(wc -l <"$tmp/tty")
	if [ "$lines" -ge 20 ] && [ "$lines" -le 29 ]; then ok; else
		bad "preview on a 160x30 terminal: $lines lines"
	fi
	script -qec "stty rows 100 cols 40; '$RT' scenes/glass.nff" /dev/null >"$tmp/tty" 2>&1
	lines=$(wc -l <"$tmp/tty")
	if [ "$lines" -eq 15 ]; then ok; else bad "preview on a 40x100 terminal: $lines lines, expected 15"; fi
	# The bar is erased before the run ends: the time limit's message starts its own
	# line, and Ctrl-C (SIGINT) leaves no bar behind. (The bar is drawn as a row ends, from
	# half a second on; the limits leave time for a row under the sanitizers on a busy
	# machine.)
	cr=$(printf '\r')
	TERM=xterm script -qec "'$RT' -d 8 -s 256x256 --time-limit 3 -o '$tmp/bar.ppm' '$tmp/slow.nff'" \
		/dev/null >"$tmp/tty" 2>&1
	if grep -q "rows" "$tmp/tty" && grep -q "${cr}${esc}\[Krt: .*the time limit" "$tmp/tty"; then ok; else
		bad "the time limit's message follows the progress bar on its line"
	fi
	if command -v timeout >/dev/null 2>&1; then
		TERM=xterm script -qec "timeout -s INT 2 '$RT' -d 8 -s 128x128 -o '$tmp/bar.ppm' '$tmp/slow.nff'" \
			/dev/null >"$tmp/tty" 2>&1
		if grep -q "rows" "$tmp/tty" && [ "$(tail -c 4 "$tmp/tty" | od -An -c | tr -d ' ')" = '\r033[K' ]; then ok; else
			bad "Ctrl-C: the progress bar is left on the screen"
		fi
	fi
else
	echo "cli.sh: script(1) not found; the terminal checks are skipped"
fi
if [ "$(cat "$tmp/limit/old.ppm")" = kept ] && [ "$(ls "$tmp/limit")" = old.ppm ]; then ok; else
	bad "--time-limit: the old file or its folder changed: $(ls "$tmp/limit")"
fi
run -d 8 --time-limit 0.3 "$tmp/slow.nff"
expect_status "--time-limit to stdout" 1
expect_err "--time-limit to stdout" "the time limit of 0.3 seconds was reached; the image written so far is incomplete"
# A limit that is not reached changes nothing.
run --time-limit 1000 -s 31x17 scenes/glass.nff
cp "$tmp/out" "$tmp/limited.ppm"
run -s 31x17 scenes/glass.nff
expect_same "--time-limit not reached" "$tmp/out" "$tmp/limited.ppm"
for limit in 0 0.0000001 -1 abc 1.5s 2.5.1 .5 100000001 ''; do
	run --time-limit "$limit" scenes/glass.nff
	expect_status "--time-limit '$limit'" 2
	expect_err "--time-limit '$limit'" "bad time limit"
done

# ---- standard streams --------------------------------------------------------------
# `-` is the scene on standard input (named <stdin> in messages), `-o -` the image on
# standard output, and -f names a format where no file name does.
"$RT" -s 16x12 scenes/glass.nff >"$tmp/glass.ppm"
run -s 16x12 - <scenes/glass.nff
expect_status "- from a file" 0
expect_same "- from a file" "$tmp/out" "$tmp/glass.ppm"
cat scenes/glass.nff | "$RT" -s 16x12 - >"$tmp/out" 2>"$tmp/err"
expect_same "- from a pipe" "$tmp/out" "$tmp/glass.ppm"
printf 'v\nfrom 0 0 0\n' >"$tmp/short.nff"
run - <"$tmp/short.nff"
expect_status "- with an error" 1
expect_err "- with an error" "rt: <stdin>:2: unexpected end of file"
run -s 16x12 -o - scenes/glass.nff
expect_same "-o -" "$tmp/out" "$tmp/glass.ppm"
run -s 16x12 -o - -f png scenes/glass.nff
cp "$tmp/out" "$tmp/stdout.png"
if python3 tests/pngcheck.py "$tmp/stdout.png" "$tmp/glass.ppm"; then ok; else
	bad "-o - -f png: not the PNG of the same image"
fi
run -s 16x12 -o "$tmp/noext" --format ppm scenes/glass.nff
expect_same "--format ppm, a name without an ending" "$tmp/noext" "$tmp/glass.ppm"
run -f gif scenes/glass.nff
expect_status "-f gif" 2
expect_err "-f gif" "bad format 'gif'"
run -o "$tmp/x.png" -f ppm scenes/glass.nff
expect_status "-o x.png -f ppm" 2
expect_err "-o x.png -f ppm" "conflicting output formats"
run -o "$tmp/noext" scenes/glass.nff
expect_status "-o without an ending or -f" 2
expect_err "-o without an ending or -f" "or give -f"

# ---- previews that fit ----------------------------------------------------------------
# LINES bounds a preview's height where standard output is no terminal, as COLUMNS its
# width: one line less, for the prompt. --cols is taken as given.
LINES=10 run --ascii scenes/glass.nff
if [ "$(wc -l <"$tmp/out")" -le 9 ] && [ "$(wc -l <"$tmp/out")" -ge 5 ]; then ok; else
	bad "LINES=10 --ascii: $(wc -l <"$tmp/out") lines"
fi
LINES=10 run --ascii --cols 30 scenes/glass.nff
if [ "$(wc -l <"$tmp/out")" -eq 12 ]; then ok; else bad "LINES=10 --cols 30: not 12 lines"; fi

# ---- names in either case --------------------------------------------------------------
# An image's name and size may be written in capitals: IMAGE.PNG is a PNG, 16X12 a size.
run -s 16X12 -o "$tmp/CAPS.PNG" scenes/glass.nff
expect_status "-s 16X12 -o CAPS.PNG" 0
"$RT" -s 16x12 scenes/glass.nff >"$tmp/caps.ppm"
if python3 tests/pngcheck.py "$tmp/CAPS.PNG" "$tmp/caps.ppm"; then ok; else
	bad "-o CAPS.PNG: not the PNG of the same image"
fi
run -s 16x12 -o "$tmp/Mixed.Ppm" scenes/glass.nff
expect_same "-o Mixed.Ppm" "$tmp/Mixed.Ppm" "$tmp/caps.ppm"

# ---- quiet ---------------------------------------------------------------------------
# -q and --quiet silence warnings (a skipped degenerate object) and nothing else: the
# image is the same, errors still print.
run -s 16x12 tests/good/16-zero-area-polygon.nff
expect_err "a skipped polygon warns" "warning:"
cp "$tmp/out" "$tmp/warned.ppm"
for q in -q --quiet; do
	run $q -s 16x12 tests/good/16-zero-area-polygon.nff
	expect_status "$q with a warning" 0
	expect_no_stderr "$q with a warning"
	expect_same "$q: the same image" "$tmp/out" "$tmp/warned.ppm"
	run $q tests/bad/58-from-equals-at.nff
	expect_status "$q with an error" 1
	expect_err "$q with an error" "58-from-equals-at.nff:2: view:"
done

# ---- scenes of many objects ----------------------------------------------------------------
# 70,000 spheres (past --ids' 16 bits, and past the 16,384 rt once held): small ones out of
# sight, then one in the middle of the view, object 70,000. --ids names it in a PPM of
# 24-bit IDs: the centre pixel's bytes are 70,000 = (1, 17, 112).
{
	printf 'v\nfrom 0 0 -10\nat 0 0 0\nup 0 1 0\nangle 10\nhither 0.01\nresolution 9 9\nl 0 0 -10\nf 1 1 1 1 0 0 0 1\n'
	awk 'BEGIN { for (i = 0; i < 69999; i++) printf "s %d %d 50 0.1\n", i % 300 + 100, int(i / 300) }'
	printf 's 0 0 0 1\n'
} >"$tmp/many.nff"
run --ids --stats -o "$tmp/many.ppm" "$tmp/many.nff"
expect_status "70,000 objects" 0
expect_err "70,000 objects" "objects: 70000"
expect_err "70,000 objects" "build_seconds: "
if ppm_header_is "$tmp/many.ppm" 9 9 && [ "$(tail -c +15 "$tmp/many.ppm" | od -An -tu1 -j 120 -N 3 | tr -s ' ')" = " 1 17 112" ]; then ok; else
	bad "--ids with 70,000 objects: not a PPM of 24-bit IDs with 70000 at the centre"
fi
run --ids -s 9x9 -o "$tmp/few.pgm" scenes/glass.nff
expect_status "--ids with one object" 0
if head -c 2 "$tmp/few.pgm" | grep -q P5; then ok; else bad "--ids with one object: not a 16-bit PGM"; fi

# ---- the colour pipeline -----------------------------------------------------------------
# A grey sphere (0.5, Kd 0.5) lit head-on: classic takes 0.5 as it is and writes 0.25 as 64
# (of 255); sRGB decodes 0.5 to 0.214, lights it to 0.107 and writes that as 92.
printf 'v\nfrom 0 0 -10\nat 0 0 0\nup 0 1 0\nangle 10\nhither 0.01\nresolution 9 9\nl 0 0 -10\nf 0.5 0.5 0.5 0.5 0 0 0 1\ns 0 0 0 1\n' \
	>"$tmp/lit.nff"
# centre_red FILE: the red sample of the middle pixel of a 9x9 PPM.
centre_red() { tail -c +16 "$1" | od -An -tu1 -j 120 -N 1 | tr -d ' '; }
run -o "$tmp/lit-srgb.ppm" "$tmp/lit.nff"
run --colours classic -o "$tmp/lit-classic.ppm" "$tmp/lit.nff"
if [ "$(centre_red "$tmp/lit-srgb.ppm")" -ge 88 ] && [ "$(centre_red "$tmp/lit-srgb.ppm")" -le 94 ] &&
	[ "$(centre_red "$tmp/lit-classic.ppm")" -ge 60 ] && [ "$(centre_red "$tmp/lit-classic.ppm")" -le 66 ]; then ok; else
	bad "colour pipelines: centre red $(centre_red "$tmp/lit-srgb.ppm") (sRGB, expected 88-94), $(centre_red "$tmp/lit-classic.ppm") (classic, expected 60-66)"
fi
# The scene command does the same; the command line wins over it.
{ echo "colours classic"; cat "$tmp/lit.nff"; } >"$tmp/lit-c.nff"
run -o "$tmp/lit-c.ppm" "$tmp/lit-c.nff"
if cmp -s "$tmp/lit-c.ppm" "$tmp/lit-classic.ppm"; then ok; else bad "'colours classic' differs from --colours classic"; fi
run --colours srgb -o "$tmp/lit-c.ppm" "$tmp/lit-c.nff"
if cmp -s "$tmp/lit-c.ppm" "$tmp/lit-srgb.ppm"; then ok; else bad "--colours srgb does not win over the scene's command"; fi
# After a colour it would change, the command is an error; so is an unknown pipeline.
{ cat "$tmp/lit.nff"; echo "colours classic"; } >"$tmp/lit-late.nff"
run "$tmp/lit-late.nff"
expect_status "colours after f" 1
expect_err "colours after f" "lit-late.nff:11: colours: must come before the first colour (line 9 has one)"
printf 'colours grey\n' >"$tmp/grey.nff"
run "$tmp/grey.nff"
expect_status "colours grey" 1
expect_err "colours grey" "grey.nff:1: colours: expected srgb or classic, got 'grey'"
run --colours grey "$tmp/lit.nff"
expect_status "--colours grey" 2

# ---- GNU option forms ------------------------------------------------------------------
# Every form of an option gives the bytes of its plain form.
run -s 32x24 -d 3 -o "$tmp/forms-plain.ppm" scenes/glass.nff
for forms in "-s32x24 -d3 -o$tmp/forms.ppm" "--size=32x24 --depth=3 --output=$tmp/forms.ppm" \
	"--size 32x24 --depth 3 --output $tmp/forms.ppm" "--si 32x24 --dep=3 --out $tmp/forms.ppm" \
	"-qs 32x24 -d 3 -o $tmp/forms.ppm" "-d 3 -o $tmp/forms.ppm -- scenes/glass.nff -s32x24"; do
	rm -f "$tmp/forms.ppm"
	case $forms in
	*--\ *) set -- ;;
	*) set -- scenes/glass.nff ;;
	esac
	# shellcheck disable=SC2086 # the forms are words
	run $forms "$@"
	if [ "$forms" = "-d 3 -o $tmp/forms.ppm -- scenes/glass.nff -s32x24" ]; then
		# After --, -s32x24 is a second scene: refused.
		expect_status "-- then an option-like operand" 2
		expect_err "-- then an option-like operand" "more than one scene given ('-s32x24')"
		continue
	fi
	if [ "$status" -eq 0 ] && cmp -s "$tmp/forms.ppm" "$tmp/forms-plain.ppm"; then ok; else
		bad "option forms '$forms': status $status, or another image"
	fi
done
# A scene whose name begins with a dash, after --.
cp scenes/glass.nff "$tmp/-dash.nff"
(cd "$tmp" && "$RT" -s 32x24 -d 3 -o dash.ppm -- -dash.nff) 2>"$tmp/err"
if cmp -s "$tmp/dash.ppm" "$tmp/forms-plain.ppm"; then ok; else bad "-- -dash.nff: $(head -n 2 "$tmp/err")"; fi
run -h
if [ "$status" -eq 0 ] && grep -q "^Usage: rt" "$tmp/out"; then ok; else bad "-h: status $status, no usage"; fi
run --he
if [ "$status" -eq 0 ] && grep -q "^Usage: rt" "$tmp/out"; then ok; else bad "--he: status $status, no usage"; fi
run --a scenes/glass.nff
expect_status "--a (ambiguous)" 2
expect_err "--a (ambiguous)" "option '--a' is ambiguous: --antialias --aa-threshold --aa-depth --ascii --ansi"
run --stats=yes scenes/glass.nff
expect_status "--stats=yes" 2
expect_err "--stats=yes" "option '--stats' takes no value"
run -qx scenes/glass.nff
expect_status "-qx" 2
expect_err "-qx" "unknown option '-x'"
run scenes/glass.nff -o
expect_status "-o at the end" 2
expect_err "-o at the end" "option '-o' needs a value"
run --output= scenes/glass.nff
expect_status "--output=" 2
run --cols=40 --ascii scenes/glass.nff
if [ "$status" -eq 0 ] && [ "$(head -n 1 "$tmp/out" | wc -c)" -eq 41 ]; then ok; else
	bad "--cols=40: status $status, first line $(head -n 1 "$tmp/out" | wc -c) bytes"
fi

# ---- memory --------------------------------------------------------------------------
# The small-memory build (make build/rt-small) renders, PNG too, in 40 MB of address space,
# where the default build (109 MiB of static arrays, README "Memory") cannot even start.
if [ -x build/rt-small ]; then
	if (ulimit -v 40000 && build/rt-small -s 64x48 -o "$tmp/small.png" scenes/glass.nff &&
		build/rt-small -s 64x48 -o "$tmp/small.ppm" scenes/glass.nff) 2>"$tmp/err" &&
		python3 tests/pngcheck.py "$tmp/small.png" "$tmp/small.ppm"; then ok; else
		bad "build/rt-small under ulimit -v 40000: $(head -n 2 "$tmp/err")"
	fi
fi

summary
