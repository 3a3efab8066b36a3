#!/usr/bin/env bash
#------------------------------------------------------------------------------
# suspensionPlot on the function-object output of tests/suspensionFoam/
# reference, its folders renamed as a user's controlDict may name them: both
# PNGs are written (valid PNG headers, not empty), a time given as 0.0020
# finds folder 0.002, and a time without profiles is an error. The marks of
# the steady state on rheology.png: without a rheologySummary.dat the plot
# is written unmarked and the log says so; with one (written here in the
# layout of suspensionRheology) the start-up and the mean of etaR with its
# error bar are marked and reported, a mean without an error bar too; of a
# restarted run the summary of the latest start time is used; a summary
# that cannot be read is an error naming it (no traceback). A rate that
# changes draws programme.png, reversal.png and lissajous.png; a constant
# one none of them.
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
cp "$work/log" "$work/log.plain"
cp "$work/postProcessing/plots/rheology.png" "$work/rheology.plain.png"
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

# No summary: unmarked, and said
grep -q "no rheologySummary.dat in .*myRheology yet" "$work/log.plain" 2>/dev/null \
    || fail "a missing summary is not reported"
[ -s "$work/rheology.plain.png" ] || fail "no rheology.png without a summary"

# summary <file> <stdError> <trusted>: a rheologySummary.dat of the layout of
# suspensionRheology for the reference run (strain 0.001 to 0.004)
summary()
{
    cat > "$1" <<SUMMARY
# Steady-state rheology at time 0.004 (strain 0.004), from 4 rows of postProcessing/myRheology/*/rheology*.dat
# start-up transient: MSER-5 rule on etaR, strain 0.001 to 0.002 discarded (strainDiscarded adds, for each quantity, the oldest samples that do not fill a block)
# error bars: means of blocks of two correlation strains, trusted with >= 8 blocks over >= 1 strain
# etaR = 2.33 +/- $2 (0.43 %, 2 blocks of 0.001 strain): too few blocks to trust; for the precision 2 % about 0.5 more steady strain is needed
# quantity                    mean      stdError  relError correlationStrain blockStrain  blocks  strainUsed strainDiscarded  trusted
  etaR                        2.33          $2     0.0043            0.0005       0.001       2       0.002           0.002       $3
  N1                         -0.21          0.01     0.048            0.0005       0.001       2       0.002           0.002       no
SUMMARY
}
rheo=$work/postProcessing/myRheology
summary "$rheo/0/rheologySummary.dat" 0.01 no
"$plot" -case "$work" > "$work/log" 2>&1 || { cat "$work/log"; fail "suspensionPlot with a summary"; }
grep -q "marked etaR = 2.33 +/- 0.01 over strain 0.002 to 0.004, not trusted, from $rheo/0/rheologySummary.dat" \
    "$work/log" || { cat "$work/log"; fail "the steady state is not marked as the summary says"; }
cmp -s "$work/rheology.plain.png" "$work/postProcessing/plots/rheology.png" \
    && fail "rheology.png with a summary is the plot without one"

# A mean without an error bar (too few blocks: nan)
summary "$rheo/0/rheologySummary.dat" nan no
"$plot" -case "$work" > "$work/log" 2>&1 || { cat "$work/log"; fail "suspensionPlot with a nan error bar"; }
grep -q "marked etaR = 2.33 +/- nan" "$work/log" || fail "a mean without an error bar is not marked"

# A restart at 0.002: its summary (the whole run) is the one marked
mkdir "$rheo/0.002"
{ sed -n '1,2p;5,$p' "$rheo/0/rheology.dat"; } > "$rheo/0.002/rheology.dat"
summary "$rheo/0.002/rheologySummary.dat" 0.02 yes
"$plot" -case "$work" > "$work/log" 2>&1 || { cat "$work/log"; fail "suspensionPlot of a restarted run"; }
grep -q "marked etaR = 2.33 +/- 0.02 over strain 0.002 to 0.004, trusted, from $rheo/0.002/rheologySummary.dat" \
    "$work/log" || { cat "$work/log"; fail "not the summary of the latest start time"; }

# A summary that is not one: an error naming it, no traceback
echo "# not a summary" > "$rheo/0.002/rheologySummary.dat"
if "$plot" -case "$work" > "$work/log" 2>&1; then
    fail "no error for an unreadable summary"
fi
grep -q "cannot read $rheo/0.002/rheologySummary.dat" "$work/log" || { cat "$work/log"; fail "the error does not name the summary"; }
grep -q Traceback "$work/log" && fail "a traceback instead of an error"


# A constant rate draws no programme plots; a rate that reverses (the
# reference rows with the rate's sign changed half-way) and an oscillation
# summary draw programme.png, reversal.png and lissajous.png
grep -q "programme.png\|lissajous.png\|reversal.png" "$work/log" \
    && fail "programme plots of a constant rate"
rm -r "$rheo/0.002"
awk 'BEGIN { OFS = "\t" } /^#/ { print; next } { n++; if (n > 2) { $3 = -$3; $4 = -$4 } print }' \
    "$rheo/0/rheology.dat" > "$work/reversed.dat"
mv "$work/reversed.dat" "$rheo/0/rheology.dat"
mkdir -p "$work/postProcessing/osc/0"
printf '# Oscillatory shear at omega = 1000, time 0.004: 1 whole cycles\n' \
    > "$work/postProcessing/osc/0/oscillationSummary.dat"
"$plot" -case "$work" > "$work/log" 2>&1 || { cat "$work/log"; fail "suspensionPlot of a programme"; }
for png in programme reversal lissajous; do
    f=$work/postProcessing/plots/$png.png
    grep -q "wrote $f" "$work/log" || fail "$png.png not written for a programme"
    [ "$(stat -c %s "$f")" -gt 10000 ] || fail "$png.png is almost empty"
done
echo "suspensionPlot: both plots of renamed function-object folders, the steady state marked from rheologySummary.dat, the programme plots of a rate that changes"
