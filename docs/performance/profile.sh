#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Cost of each kernel, and of each force model, for the paper's Table 3
# suspension (N = 4096, every force on, attraction cut at 0.5 a0 and at the
# paper's 4 a0): suspensionBenchmark with all models on and with each one
# switched off (-off), explicit and implicit, one thread, `repeats` times.
# Writes profile.csv next to this script; profile.py prints the medians.
#   docs/performance/profile.sh [repeats]        (default 3)
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
. etc/bashrc
repeats="${1:-3}"
bench="$FOAM_USER_APPBIN/suspensionBenchmark"
out="$here/profile.csv"
"$bench" -header | sed 's/^/repeat,/' > "$out"

run()
{
    local r=$1; shift
    echo "$r,$(OMP_NUM_THREADS=1 "$bench" -case table3 -N 4096 "$@")" | tee -a "$out"
}

all="-off lubrication -off contact -off repulsion -off attraction"
for r in $(seq 1 "$repeats"); do
    for integrator in "velocityVerlet -steps 20" "implicitEuler -steps 10"; do
        set -- $integrator
        opts="-integrator $*"
        run "$r" $opts -attractionCutoff 4
        run "$r" $opts -attractionCutoff 0.5
        for off in lubrication contact rolling repulsion attraction; do
            run "$r" $opts -attractionCutoff 0.5 -off $off
        done
        # Stokes drag alone: only the explicit scheme has a step limit
        [ "$1" = velocityVerlet ] && run "$r" $opts -attractionCutoff 0.5 $all
    done
done
