#!/bin/bash
#------------------------------------------------------------------------------
# Work against precision at steady state (docs/speed-vs-error.md, "At steady
# state"): Table 1 FL or FR (phi = 0.5, N = 200) at the sampling interval a
# user runs (0.01), for each step safety, long enough that each steady eta_r
# carries an error bar of about 1 %. The numbers are the solver's own
# summaries (postProcessing/rheology/*/rheologySummary.dat of the function
# object suspensionRheology), tabulated by steady.py.
#
#   [CASE=frictional] [INTEGRATOR=overdamped] [EPSILON=1e-2] [DELTA=0.2] \
#   [TOLERANCE=1e-4] [NORMAL=implicit] [START=<time dir>] \
#   docs/speed-vs-error/steady.sh [strain] [safety ...]
#
# Defaults: CASE=frictionless, INTEGRATOR=implicitEuler, the template's
# lubrication epsilon (1e-3) and delta (0.05), CG tolerance and normal
# contact springs (integration/normalContact, auto); a setting away from the
# template's is part of the case name (e.g. implicitEuler-safety0.2-eps0.01,
# implicitEuler-safety0.2-tol1e-4, implicitEuler-safety0.2-normalimplicit).
# START=<case>/<time>: start from that stored state (a steady one) instead of
# a new packing, with its time as the start; only the strain after it counts.
#
# Cases under $WSF_SPEED_DIR/steady/<case>/ (default run/speed-vs-error),
# restartable
# (etc/caseFunctions): two at a time, one thread each.
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" && . "$root/etc/caseFunctions" || exit 1

strain=${1:-150}
[ $# -gt 0 ] && shift
safeties=${*:-"0.4 0.2 0.1 0.05"}
case=${CASE:-frictionless}
runRoot=${WSF_SPEED_DIR:-$root/run/speed-vs-error}/steady
template=$root/tutorials/uniformShear/$case

integrator=${INTEGRATOR:-implicitEuler}
extra=() suffix=
[ -n "${EPSILON:-}" ] && { extra+=(lubrication/epsilon="$EPSILON"); suffix+=-eps$EPSILON; }
[ -n "${DELTA:-}" ] && { extra+=(lubrication/delta="$DELTA"); suffix+=-delta$DELTA; }
[ -n "${TOLERANCE:-}" ] && { extra+=(integration/solver/tolerance="$TOLERANCE"); suffix+=-tol$TOLERANCE; }
[ -n "${NORMAL:-}" ] && { extra+=(integration/normalContact="$NORMAL"); suffix+=-normal$NORMAL; }
if [ -n "${START:-}" ]; then
    # Copy the stored state in as the case's first time and start from it
    START=$(cd "$START" && pwd) || exit 1
    startTime=${START##*/}
    suffix+=-from$startTime
    export WSF_CASE_SETUP="rm -rf 0 [1-9]* && cp -r '$START' . \
        && foamDictionary -entry startFrom -set latestTime system/controlDict > /dev/null"
    strain=$(awk -v a="$startTime" -v b="$strain" 'BEGIN { print a + b }')
fi

one()
{
    runCase "$runRoot/$case/$integrator-safety$1$suffix" "$template" \
        "$strain" 0.01 population/volumeFraction=0.5 \
        population/nParticles=200 \
        integration/integrator="$integrator" integration/safety="$1" \
        ${extra[@]+"${extra[@]}"}
}

failed=0
set -- $safeties
while [ $# -gt 0 ]; do
    one "$1" & a=$!
    b=
    if [ $# -gt 1 ]; then one "$2" & b=$!; fi
    wait $a || failed=1
    [ -n "$b" ] && { wait $b || failed=1; }
    shift; [ $# -gt 0 ] && shift
done
/usr/bin/python3 "$root/docs/speed-vs-error/steady.py" "$runRoot" || failed=1
exit $failed
