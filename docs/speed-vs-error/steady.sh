#!/bin/bash
#------------------------------------------------------------------------------
# Work against precision at steady state (docs/speed-vs-error.md, "At steady
# state"): Table 1 FL (phi = 0.5, N = 200, implicitEuler) at the sampling
# interval a user runs (0.01), for each step safety, long enough that each
# steady eta_r carries an error bar of well under 1 %. The numbers are the
# solver's own summaries (postProcessing/rheology/*/rheologySummary.dat of
# the function object suspensionRheology), tabulated by steady.py.
#
#   [INTEGRATOR=overdamped] docs/speed-vs-error/steady.sh [strain] [safety ...]
# (default integrator: implicitEuler)
#
# Cases under run/speed-vs-error/steady/, restartable (etc/caseFunctions):
# two at a time, one thread each.
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" && . "$root/etc/caseFunctions" || exit 1

strain=${1:-150}
shift
safeties=${*:-"0.4 0.2 0.1 0.05"}
runRoot=${WSF_SPEED_DIR:-$root/run/speed-vs-error}/steady
template=$root/tutorials/uniformShear/frictionless

integrator=${INTEGRATOR:-implicitEuler}

one()
{
    runCase "$runRoot/frictionless/$integrator-safety$1" "$template" \
        "$strain" 0.01 population/volumeFraction=0.5 \
        integration/integrator="$integrator" integration/safety="$1"
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
