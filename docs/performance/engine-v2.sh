#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Engine v2 against the engine before it, paired: each case runs the two
# suspensionBenchmark binaries in turn (A B A B ...), `repeats` pairs, under
# /usr/bin/time -v (CPU seconds, wall seconds, peak RSS), and writes
# engine-v2.csv next to this script; engine-v2.py makes the table of
# docs/performance.md from it.
#   docs/performance/engine-v2.sh [repeats] [reference-benchmark]
# The reference defaults to the engine of commit 743b88a (the last before
# engine v2), built here into /tmp/wsf-reference (engine only, ~3 min).
# Needs a Release build of this tree (./Allwmake). Two threads are used only
# by the thread-scaling cases: run it on an otherwise idle machine.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$here/../.."
cd "$top"
. etc/bashrc
# Each binary finds its own engine library by its RUNPATH
unset LD_LIBRARY_PATH
repeats="${1:-5}"
new="$FOAM_USER_APPBIN/suspensionBenchmark"
ref="${2:-}"
if [ -z "$ref" ]; then
    refTree=/tmp/wsf-reference
    if [ ! -x "$refTree/platforms/linux64GccDPInt32Opt/bin/suspensionBenchmark" ]; then
        rm -rf "$refTree"
        git worktree add -f --detach "$refTree" 743b88a > /dev/null
        cmake -S "$refTree" -B "$refTree/build" -DCMAKE_BUILD_TYPE=Release \
            -DWSF_WITH_OPENFOAM=OFF -DWSF_WITH_TESTS=OFF > /dev/null
        cmake --build "$refTree/build" --target suspensionBenchmark -j 2 > /dev/null
    fi
    ref="$refTree/platforms/linux64GccDPInt32Opt/bin/suspensionBenchmark"
fi
out="$here/engine-v2.csv"

{
    printf 'engine,repeat,cpu_s,wall_s,time_v_max_rss_MB,'
    "$new" -header
} > "$out"

# run <engine name> <binary> <repeat> <threads> <args...>
run() {
    local name=$1 bin=$2 r=$3 threads=$4; shift 4
    local log row
    log=$(mktemp)
    row=$(OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=PASSIVE /usr/bin/time -v "$bin" "$@" 2> "$log")
    awk -F': ' -v name="$name" -v r="$r" -v row="$row" '
        /User time/ {u = $2} /System time/ {s = $2}
        /Elapsed \(wall clock\)/ {n = split($2, t, ":"); w = 0; for (k = 1; k <= n; ++k) w = 60*w + t[k]}
        /Maximum resident set size/ {m = $2/1024}
        END {printf "%s,%s,%.3f,%.3f,%.1f,%s\n", name, r, u + s, w, m, row}' "$log" \
        | tee -a "$out"
    rm -f "$log"
}

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
