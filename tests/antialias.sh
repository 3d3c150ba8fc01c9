#!/bin/sh
# antialias.sh - -a from outside: smoother than one ray a pixel against a supersampled
# reference, extra rays only where the image changes, the same bytes at every -j, and
# its options checked.
# Run from the repository root as `RT=./rt sh tests/antialias.sh`; ends with `N passed, N failed`.
# See LICENSE for copyright and licence.

. tests/lib.sh
rt_absolute
make_tmp
run_limit=120

# eye_rays: the eye_rays count of the last run's --stats.
eye_rays() { sed -n 's/^eye_rays: //p' "$tmp/err"; }

# ---- nearer the true image ----------------------------------------------------------------
# showpiece at 64x48 against itself at 1024x768 averaged over 16x16 blocks in linear light:
# -a must be clearly nearer than one ray a pixel (measured: 23.7 dB and 39.1 dB), and
# its highest setting nearer still (46.5 dB).
run -s 1024x768 -o "$tmp/ref.ppm" scenes/showpiece.nff
one=$(run -s 64x48 -o "$tmp/one.ppm" scenes/showpiece.nff &&
	python3 tools/imagequality.py "$tmp/ref.ppm" 16 "$tmp/one.ppm")
aa=$(run -a -s 64x48 -o "$tmp/aa.ppm" scenes/showpiece.nff &&
	python3 tools/imagequality.py "$tmp/ref.ppm" 16 "$tmp/aa.ppm")
best=$(run -a --aa-depth 4 -s 64x48 -o "$tmp/best.ppm" scenes/showpiece.nff &&
	python3 tools/imagequality.py "$tmp/ref.ppm" 16 "$tmp/best.ppm")
if awk -v a="$one" -v b="$aa" -v c="$best" 'BEGIN { exit !(b >= a + 6 && c >= b + 2) }'; then ok; else
	bad "PSNR: one ray $one dB, -a $aa dB, highest $best dB (expected +6 dB, then +2 dB)"
fi

# ---- rays only where needed ---------------------------------------------------------------
# A view of nothing but the background: every square's corners agree, so -a traces the
# (W+1) x (H+1) corners and no more, and each pixel is the background.
printf 'v from 0 0 -5 at 0 0 0 up 0 1 0 angle 40 hither 0.01 resolution 8 6\nb 0.2 0.4 0.6\n' \
	>"$tmp/empty.nff"
run -a --aa-threshold 0 --aa-depth 4 --stats -s 40x30 -o "$tmp/empty-aa.ppm" "$tmp/empty.nff"
if [ "$(eye_rays)" = 1271 ]; then ok; else bad "an empty view: $(eye_rays) eye rays, expected 41 x 31"; fi
run -s 40x30 -o "$tmp/empty-one.ppm" "$tmp/empty.nff"
if cmp -s "$tmp/empty-aa.ppm" "$tmp/empty-one.ppm"; then ok; else bad "an empty view: -a changed its colour"; fi
# showpiece: more rays than the corners, far fewer than halving every pixel twice (25 a
# pixel; measured: 9 at this small size, where most pixels hold an edge).
run -a --stats -s 64x48 -o "$tmp/aa.ppm" scenes/showpiece.nff
rays=$(eye_rays)
if [ "$rays" -gt 3185 ] && [ "$rays" -lt $((64 * 48 * 12)) ]; then ok; else
	bad "showpiece -a: $rays eye rays, expected more than 65 x 49 and under 12 a pixel"
fi
# A thin object that the colours alone would not show: corners that see different
# objects are refined whatever the threshold.
run -a --aa-threshold 1 --stats -s 64x48 -o "$tmp/aa1.ppm" scenes/showpiece.nff
if [ "$(eye_rays)" -gt 3185 ]; then ok; else bad "threshold 1: no square refined where objects differ"; fi

# ---- every core, the same bytes -----------------------------------------------------------
for opts in "-a" "-a --aa-depth 3 --aa-threshold 0.1" "-a --ascii --cols 40"; do
	# shellcheck disable=SC2086 # the options are words
	run -j 1 $opts -s 48x36 scenes/glass.nff
	mv "$tmp/out" "$tmp/j1"
	for j in 2 3 7; do
		# shellcheck disable=SC2086
		run -j "$j" $opts -s 48x36 scenes/glass.nff
		if [ "$status" -eq 0 ] && cmp -s "$tmp/out" "$tmp/j1"; then ok; else
			bad "$opts at -j $j: differs from -j 1 (status $status)"
		fi
	done
done

# ---- options --------------------------------------------------------------------------------
for args in "--aa-depth 0" "--aa-depth 5" "--aa-depth x" "--aa-threshold 1.5" \
	"--aa-threshold -0.1" "--aa-threshold x" "--aa-threshold 0.5x" "-a --spd" "-a --ids"; do
	# shellcheck disable=SC2086
	run $args -s 8x8 scenes/showpiece.nff
	if [ "$status" -eq 2 ]; then ok; else bad "'$args': exit status $status, expected 2"; fi
done
run --aa-depth 1 --aa-threshold .5 -s 8x6 scenes/showpiece.nff
if [ "$status" -eq 0 ]; then ok; else bad "--aa-depth 1 --aa-threshold .5: status $status"; fi

summary
