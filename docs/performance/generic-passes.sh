#!/usr/bin/env bash
#------------------------------------------------------------------------------
# What the generic pair pass costs at run time: each case runs, in turn and
# `repeats` times (A B C A B C ...), one thread, under /usr/bin/time -v,
#   reference    the engine of commit e879dce (one pass compiled per model
#                combination), built into /tmp/wsf-engine-e879dce
#                (benchmarkFunctions);
#   specialised  this tree as it runs (the combination's own pass);
#   generic      this tree with -genericPasses (every model set through the
#                generic pass: what a combination without a pass of its own
#                costs).
# Rows go to generic-passes.csv next to this script.
#   docs/performance/generic-passes.sh [repeats] [reference-benchmark]
# Needs a Release build of this tree (./Allwmake); run on an idle machine.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
. etc/bashrc
repeats="${1:-5}"
new="$FOAM_USER_APPBIN/suspensionBenchmark"
. "$here/benchmarkFunctions"
ref="${2:-$(referenceBenchmark e879dce)}"
out="$here/generic-passes.csv"

{
    printf 'run,repeat,cpu_s,wall_s,time_v_max_rss_MB,'
    "$new" -header
} > "$out"

# rotated <name> <args...>: the three variants in turn, `repeats` times
rotated() {
    local name=$1; shift
    for r in $(seq 1 "$repeats"); do
        timedBenchmark "$out" "${name}_e879dce" "$ref" "$r" 1 "$@"
        timedBenchmark "$out" "${name}_specialised" "$new" "$r" 1 "$@"
        timedBenchmark "$out" "${name}_generic" "$new" "$r" 1 "$@" -genericPasses
    done
}

rotated table3 -case table3 -N 4096 -steps 300 -attractionCutoff 4
rotated table1 -case table1 -N 1000 -steps 2000
rotated table1i -case table1 -N 1000 -steps 1000 -integrator implicitEuler
