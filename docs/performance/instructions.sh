#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Instructions per particle-step of engine v2 and of the reference engine
# (of commit 743b88a, built as engine-v2.sh builds it, benchmarkFunctions), counted
# by valgrind's callgrind inside Simulation::step only: a figure that does
# not depend on the load of the machine. Writes instructions.csv.
#   docs/performance/instructions.sh [reference-benchmark]
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
. etc/bashrc
unset LD_LIBRARY_PATH
new="$FOAM_USER_APPBIN/suspensionBenchmark"
. "$here/benchmarkFunctions"
ref="${1:-$(referenceBenchmark 743b88a)}"
out="$here/instructions.csv"
steps=10
echo "engine,case,attractionCutoff,integrator,N,steps_counted,instructions,instructions_per_particle_step" > "$out"

count() {
    local name=$1 bin=$2 N=$3; shift 3
    local cg
    cg=$(mktemp)
    OMP_NUM_THREADS=1 valgrind --tool=callgrind --collect-atstart=no \
        --toggle-collect='suspension::Simulation::step*' --callgrind-out-file="$cg" \
        "$bin" -N "$N" -steps $steps "$@" > /dev/null 2>&1
    local ir
    ir=$(callgrind_annotate "$cg" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
    rm -f "$cg"
    # 5 warm-up steps and the timed ones are counted
    echo "$name,$*,$N,$((steps + 5)),$ir,$(awk -v i="$ir" -v n="$N" -v s=$((steps + 5)) 'BEGIN {printf "%.0f", i/(n*s)}')" \
        | sed 's/,-case /,/; s/ -attractionCutoff /,/; s/ -integrator /,/' | tee -a "$out"
}

for engine in v2 reference; do
    bin=$new
    [ "$engine" = reference ] && bin=$ref
    count $engine "$bin" 4096 -case table3 -attractionCutoff 4 -integrator velocityVerlet
    count $engine "$bin" 4096 -case table3 -attractionCutoff 0.5 -integrator velocityVerlet
    count $engine "$bin" 1000 -case table1 -attractionCutoff 0 -integrator implicitEuler
done
echo "wrote $out"
