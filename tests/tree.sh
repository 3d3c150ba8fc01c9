#!/bin/sh
# tree.sh - the search through the hierarchy finds what the search object by object finds:
# the default build ($RT) against build/rt-no-tree (no hierarchy, but the checks the build
# with one makes: config.h, RT_HOST_CHECKS), the image and the --ids image at 48x36, on
# the bundled scenes, the hard cases, tests/good, the SPD scenes at size factors 1 and 2
# (where SPD_DIR, by default ../shared/spd, has them)
# and every fourth scene of the fuzz corpus (the whole corpus agrees in float, double and
# long double; a quarter keeps the suite to a minute).
# Run from the repository root as `RT=./rt sh tests/tree.sh`; ends with `N passed, N failed`.
# See LICENSE for copyright and licence.

. tests/lib.sh
rt_absolute
make_tmp
run_limit=60
NO_TREE=${NO_TREE:-$(pwd)/build/rt-no-tree}
SPD_DIR=${SPD_DIR:-$(dirname "$(pwd)")/shared/spd}
if [ ! -x "$NO_TREE" ]; then
	bad "no $NO_TREE (make build/rt-no-tree)"
	summary
	exit
fi
# The SPD scenes are not part of the repository: compared where they are found.
[ -d "$SPD_DIR/nff" ] || echo "SPD scenes not found in $SPD_DIR/nff (SPD_DIR): left out"

# same FILE: both builds' image and --ids image of FILE are the same bytes, with the same
# exit status (a scene either refuses gives the same error status in both). The tree's
# image run (ids empty: --stats in its place) reports its statistics into $tmp/stats
# (the objects counted below).
same() {
	for ids in "" --ids; do
		within "$run_limit" "$RT" -q -j 1 -s 48x36 ${ids:---stats} "$1" >"$tmp/tree" \
			2>"$tmp/stats$ids"
		tree_status=$?
		within "$run_limit" "$NO_TREE" -q -j 1 -s 48x36 $ids "$1" >"$tmp/all" 2>/dev/null
		all_status=$?
		if [ "$tree_status" -eq "$all_status" ] && cmp -s "$tmp/tree" "$tmp/all"; then
			ok
		else
			bad "$1${ids:+ $ids}: through the tree (status $tree_status) and object by object (status $all_status) differ"
		fi
	done
}

# Scenes of RT_BVH_MIN_OBJECTS (12) objects or more get a tree: how many of them were
# compared, so that the suite shows it compared the tree's search at all.
with_tree=0
n=0
for f in scenes/*.nff scenes/hard/*.nff tests/good/*.nff "$SPD_DIR"/nff/*-s1.nff \
	"$SPD_DIR"/nff/*-s2.nff tests/fuzz/corpus/*; do
	[ -f "$f" ] || continue
	case $f in
	tests/fuzz/corpus/*)
		n=$((n + 1))
		[ $((n % 4)) -eq 1 ] || continue
		;;
	esac
	same "$f"
	objects=$(sed -n 's/^objects: //p' "$tmp/stats")
	[ "${objects:-0}" -ge 12 ] && with_tree=$((with_tree + 1))
done
if [ "$with_tree" -ge 100 ]; then ok; else
	bad "only $with_tree of the scenes compared had a tree (12 objects or more)"
fi
summary
