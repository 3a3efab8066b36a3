#!/usr/bin/env bash
#------------------------------------------------------------------------------
# suspensionPlot on the function-object output of tests/suspensionFoam/
# reference, its folders renamed as a user's controlDict may name them: both
# PNGs are written (valid PNG headers, not empty), a time given as 0.0020
# finds folder 0.002, and a time without profiles is an error.
#   suspensionPlotTest.sh <projectDir>
#------------------------------------------------------------------------------
set -euo pipefail
project=$1
plot=$project/applications/utilities/scripts/suspensionPlot
work=$(mktemp -d "${TMPDIR:-/tmp}/suspensionPlotTest.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*" >&2; exit 1; }

cp -r "$project/tests/suspensionFoam/reference/postProcessing" "$work/"
mv "$work/postProcessing/rheology" "$work/postProcessing/myRheology"
mv "$work/postProcessing/profiles" "$work/postProcessing/yProfiles"

"$plot" -case "$work" -time 0.0020 > "$work/log" 2>&1 || { cat "$work/log"; fail "suspensionPlot"; }
for png in rheology profiles; do
    f=$work/postProcessing/plots/$png.png
    grep -q "wrote $f" "$work/log" || fail "$png.png not reported"
    [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] \
        || fail "$png.png is not a PNG"
    [ "$(stat -c %s "$f")" -gt 10000 ] || fail "$png.png is almost empty"
done
if "$plot" -case "$work" -time 3 > "$work/log" 2>&1; then
    fail "no error for a time without profiles"
fi
grep -q "no profiles at time 3 (have: 0 0.002 0.004)" "$work/log" || fail "the error does not list the times"
echo "suspensionPlot: both plots of renamed function-object folders"
