#!/bin/sh
# docs.sh - the documentation says what rt does: the manual page formats without a warning,
# README's option list is --help's, and the manual names every option --help lists.
# Run from the repository root as `RT=./rt sh tests/docs.sh`; ends with `N passed, N failed`.
# See LICENSE for copyright and licence.

. tests/lib.sh
RT=${RT:-./rt}
make_tmp

# The manual page, as man would format it, with every warning on (groff's -ww).
if command -v groff >/dev/null 2>&1; then
	groff -ww -z -man rt.1 >"$tmp/groff" 2>&1
	if [ -s "$tmp/groff" ]; then bad "rt.1: $(head -n 3 "$tmp/groff")"; else ok; fi
else
	echo "docs.sh: groff not found; the manual page's check is skipped"
fi

# README's option list is --help's, line for line (from -o, --output FILE to --version).
"$RT" --help | sed -n '/^  -o, --output FILE/,/^  --version/p' >"$tmp/help"
sed -n '/^  -o, --output FILE/,/^  --version/p' README.md >"$tmp/readme"
if [ -s "$tmp/help" ] && cmp -s "$tmp/help" "$tmp/readme"; then ok; else
	bad "README's option list differs from --help: $(diff "$tmp/help" "$tmp/readme" | head -n 4)"
fi

# Every option --help lists has its entry in the manual page (written there as \-\-name).
for option in $(grep -o -e '--[a-z-]*' -e '^  -[a-z]' "$tmp/help" | tr -d ' ' | sort -u); do
	escaped=$(printf '%s' "$option" | sed 's/-/\\\\-/g')
	if grep -q -e "$escaped" rt.1; then ok; else bad "rt.1 does not describe $option"; fi
done

summary
