#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Engine v2 against the engine before it, paired: each case runs the two
# suspensionBenchmark binaries in turn (A B A B ...), `repeats` pairs, under
# /usr/bin/time -v (CPU seconds, wall seconds, peak RSS), and writes
# engine-v2.csv next to this script; engine-v2.py makes the table of
# docs/performance.md from it.
#   docs/performance/engine-v2.sh [repeats] [reference-benchmark]
# The reference defaults to the engine of commit 743b88a (the last before
# engine v2), built into /tmp/wsf-engine-743b88a (engine only, ~3 min;
# benchmarkFunctions).
# Needs a Release build of this tree (./Allwmake). Two threads are used only
# by the thread-scaling cases: run it on an otherwise idle machine.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$here/../.."
cd "$top"
. etc/bashrc
repeats="${1:-5}"
new="$FOAM_USER_APPBIN/suspensionBenchmark"
. "$here/benchmarkFunctions"
ref="${2:-$(referenceBenchmark 743b88a)}"
out="$here/engine-v2.csv"

{
    printf 'engine,repeat,cpu_s,wall_s,time_v_max_rss_MB,'
    "$new" -header
} > "$out"

# run <engine name> <binary> <repeat> <threads> <args...>
run() { timedBenchmark "$out" "$@"; }

# paired <threads> <args...>: new and reference in turn
paired() {
    local threads=$1; shift
    for r in $(seq 1 "$repeats"); do
        run v2 "$new" "$r" "$threads" "$@"
        run reference "$ref" "$r" "$threads" "$@"
    done
}

paired 1 -case table3 -N 4096 -steps 30 -attractionCutoff 4
paired 1 -case table3 -N 4096 -steps 30 -attractionCutoff 0.5
paired 1 -case table1 -N 1000 -steps 30 -integrator implicitEuler
paired 2 -case table3 -N 65536 -steps 5 -attractionCutoff 4
# thread scaling of v2 at N = 65536: one and two threads in turn
for r in $(seq 1 "$repeats"); do
    run v2 "$new" "$r" 1 -case table3 -N 65536 -steps 10 -attractionCutoff 0.5
    run v2 "$new" "$r" 2 -case table3 -N 65536 -steps 10 -attractionCutoff 0.5
done
echo "wrote $out"
