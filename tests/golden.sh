#!/bin/sh
# golden.sh - renders every scene in scenes/ small and compares it with its reference
# in tests/golden/NAME.ppm, within the tolerance stated (and argued) in tests/imgcmp.py:
# every channel within 2 of the reference, and at most 0.5% of the pixels different.
# Run from the repository root: RT=./rt sh tests/golden.sh (RT defaults to ./rt).
# Prints `golden.sh: NAME: what differs` per failure and ends with `N passed, N failed`.
# The references are made by tools/update-golden; the size of each render is taken
# from its reference's header (rt writes it on the second line: "W H").
# See LICENSE for copyright and licence.
. tests/lib.sh
RT=${RT:-./rt}
PYTHON=${PYTHON:-python3}
make_tmp

for scene in scenes/*.nff; do
	[ -f "$scene" ] || continue
	name=$(basename "$scene" .nff)
	ref=tests/golden/$name.ppm
	if [ ! -f "$ref" ]; then
		bad "$name: no reference $ref (make it with tools/update-golden $name)"
		continue
	fi
	size=$(sed -n '2{s/^\([0-9][0-9]*\) \([0-9][0-9]*\)$/\1x\2/p;q;}' "$ref")
	if [ -z "$size" ]; then
		bad "$name: cannot read the size from $ref"
		continue
	fi
	if ! "$RT" -s "$size" -o "$tmp/$name.ppm" "$scene" 2>"$tmp/$name.err"; then
		bad "$name: rt failed: $(head -n 1 "$tmp/$name.err")"
		continue
	fi
	if [ -s "$tmp/$name.err" ]; then
		bad "$name: unexpected output on standard error: $(head -n 1 "$tmp/$name.err")"
		continue
	fi
	if ! why=$("$PYTHON" tests/imgcmp.py "$tmp/$name.ppm" "$ref" 2>&1); then
		bad "$name: $why"
		continue
	fi
	ok
done

# A reference whose scene is gone is stale.
for ref in tests/golden/*.ppm; do
	[ -f "$ref" ] || continue
	name=$(basename "$ref" .ppm)
	[ -f "scenes/$name.nff" ] || bad "$name: reference $ref has no scene scenes/$name.nff"
done

summary
