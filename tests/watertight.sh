#!/bin/sh
# watertight.sh - the hard scenes of scenes/hard/ that stress visibility, checked in every
# number type against tests/oracle.py, an exact visibility oracle: shared edges on tilted
# planes and through the eye's own coordinates, fans of slivers, non-planar quads, a
# telephoto view, eyes and lights a hair above a floor, a sphere seen at grazing incidence.
# Limits (the watertight rule's promise): double and long double 0 pixels wrong, no false
# shadow and no false light; float at most 0.1 % of the pixels in each; Q16.16 fixed point
# at most 1 %, or, for the scenes it cannot hold, a refusal by name.
# Run from the repository root after `make rt build/rt-float build/rt-ref build/rt-fixed`;
# ends with `N passed, N failed`. See LICENSE for copyright and licence.
. tests/lib.sh
FLOAT=${FLOAT:-build/rt-float}
DOUBLE=${DOUBLE:-./rt}
REF=${REF:-build/rt-ref}
FIXED=${FIXED:-build/rt-fixed}
make_tmp

# Visibility scenes are judged by their object ids; the near-surface ones by their shading
# too (false shadows and lights).
ids_scenes="tilted-grid tilted-grid-45 nonplanar-quads eye-axis-grid telephoto fan-slivers"
image_scenes="near-light near-light-9 grazing-sphere near-eye-fixed"
# Scenes that Q16.16 cannot hold: an eye 1e-9 above a floor, and a sphere 2e4 away from a
# 0.2 detail (the extent-to-feature rule).
fixed_refuses="near-light-9 near-eye-fixed grazing-sphere"

# check TYPE BINARY SCENE MODE LIMIT: renders and judges one scene; LIMIT is a percentage.
check() {
	type=$1 bin=$2 scene=$3 mode=$4 limit=$5
	file=scenes/hard/$scene.nff
	out=$tmp/$type-$scene
	if [ "$type" = fixed ] && case " $fixed_refuses " in *" $scene "*) true ;; *) false ;; esac; then
		if "$bin" --ids -o "$out.pgm" "$file" 2>"$out.err"; then
			echo "$type $scene: rendered, expected a refusal"
			return 1
		fi
		if grep -q "^rt: $file: cannot be rendered in Q16.16 fixed point: " "$out.err" &&
			[ ! -e "$out.pgm" ]; then
			return 0
		fi
		echo "$type $scene: not refused by name: $(cat "$out.err")"
		return 1
	fi
	if ! "$bin" --ids -o "$out.pgm" "$file" 2>"$out.err"; then
		echo "$type $scene: refused: $(cat "$out.err")"
		return 1
	fi
	set -- --ids "$out.pgm"
	if [ "$mode" = image ]; then
		"$bin" -o "$out.ppm" "$file" || return 1
		set -- "$@" --image "$out.ppm"
	fi
	python3 tests/oracle.py "$file" "$@" >"$out.txt" 2>/dev/null || {
		echo "$type $scene: the oracle failed"
		return 1
	}
	# Every count line reads `... N of M ...`: each N must be within LIMIT % of the pixels.
	pixels=$(sed -n 's/^wrong [0-9]* of \([0-9]*\) pixels.*/\1/p' "$out.txt")
	awk -v pixels="$pixels" -v limit="$limit" -v what="$type $scene" '
		/^(wrong|false shadows|false lights) / {
			for (i = 1; i <= NF; i++) if ($i ~ /^[0-9]+$/) { n = $i; break }
			if (n > pixels * limit / 100) { print what ": " $0; bad = 1 }
		}
		END { exit bad }' "$out.txt"
}

run_type() {
	type=$1 bin=$2 limit=$3
	for scene in $ids_scenes; do
		if check "$type" "$bin" "$scene" ids "$limit"; then echo ok; else echo bad; fi
	done
	for scene in $image_scenes; do
		if check "$type" "$bin" "$scene" image "$limit"; then echo ok; else echo bad; fi
	done
}

# Two types at a time: the oracle is the slow part.
run_type double "$DOUBLE" 0 >"$tmp/double.log" &
run_type float "$FLOAT" 0.1 >"$tmp/float.log"
wait
run_type ref "$REF" 0 >"$tmp/ref.log" &
run_type fixed "$FIXED" 1 >"$tmp/fixed.log"
wait
for type in double float ref fixed; do
	grep -v '^ok$' "$tmp/$type.log" | grep -v '^bad$'
	passed=$((passed + $(grep -c '^ok$' "$tmp/$type.log")))
	failed=$((failed + $(grep -c '^bad$' "$tmp/$type.log")))
done
summary
