#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Performance matrix of docs/performance.md: runs suspensionBenchmark for each
# case, N and thread count, `repeats` times, under /usr/bin/time -v (peak RSS),
# and writes benchmark.csv (one row per run) next to this script.
#   docs/performance/run.sh [repeats]        (default 3)
# Needs a Release build (./Allwmake). Takes ~20 minutes on 2 cores.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
. etc/bashrc
repeats="${1:-3}"
bench="$FOAM_USER_APPBIN/suspensionBenchmark"
out="$here/benchmark.csv"

{
    printf 'repeat,'
    "$bench" -header | sed 's/$/,time_v_max_rss_MB/'
} > "$out"

run() {
    local r=$1 threads=$2; shift 2
    local log
    log=$(mktemp)
    row=$(OMP_NUM_THREADS=$threads /usr/bin/time -v "$bench" "$@" 2> "$log")
    rss=$(awk -F: '/Maximum resident set size/ {printf "%.1f", $2/1024}' "$log")
    rm -f "$log"
    echo "$r,$row,$rss" | tee -a "$out"
}

for r in $(seq 1 "$repeats"); do
    for threads in 1 2; do
        run "$r" "$threads" -case table1 -N 1000 -steps 50 -brute
        run "$r" "$threads" -case table1 -N 1000 -steps 20 -integrator implicitEuler
        run "$r" "$threads" -case table1 -N 1000 -steps 20 -integrator overdamped
        run "$r" "$threads" -case table3 -N 4096 -steps 20 -brute -attractionCutoff 0.5
        run "$r" "$threads" -case table3 -N 4096 -steps 10 -attractionCutoff 4
        run "$r" "$threads" -case table3 -N 16384 -steps 10 -attractionCutoff 0.5
        run "$r" "$threads" -case table3 -N 65536 -steps 5 -attractionCutoff 0.5
    done
done
echo "wrote $out"
