#!/bin/sh
# textrel.sh - every program `make test` built loads without its code being patched: no
# text relocations (TEXTREL in `readelf -d`), which the linker warns of and hardened
# systems refuse to load. clang's medium code model made them (the Makefile's HOST_MODEL
# and CLANG_MODEL say how they are avoided). Run from the repository root after `make
# test`'s builds; ends with `N passed, N failed`. See LICENSE for copyright and licence.

. tests/lib.sh

if ! command -v readelf > /dev/null 2>&1; then
	echo "textrel.sh: readelf not found; the check is skipped"
	summary
	exit
fi
checked=0
for program in rt build/rt-* build/unit-tests* build/san/* build/msan/*; do
	[ -f "$program" ] && [ -x "$program" ] || continue
	checked=$((checked + 1))
	if readelf -d "$program" 2> /dev/null | grep -q TEXTREL; then
		bad "$program has text relocations (readelf -d shows TEXTREL)"
	else
		ok
	fi
done
# The programs make test builds are here: a check of none would prove nothing.
if [ "$checked" -ge 10 ]; then ok; else bad "only $checked programs found to check"; fi
summary
