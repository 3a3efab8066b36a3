#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The engine from a fresh packing against the same packing sheared
# (suspensionBenchmark -preshear S), alternated, REPEATS of each, one thread:
#   Table 1 FR, N = 1000, S = 1:    velocityVerlet (-steps 200), implicitEuler (-steps 20)
#   Table 3,    N = 4096, S = 0.3:  velocityVerlet (-steps 50),  implicitEuler (-steps 20)
# (Table 3 as the benchmark sets it, rolling on, stops with a runaway
# overlap at strain 0.36 under implicitEuler at its automatic step: see
# docs/performance.md, "From a sheared state".)
# Rows (whole process under /usr/bin/time -v, then the benchmark's row) are
# appended to sheared-start.csv next to this script; prints the medians of
# contacts per particle, ns per particle-step, pair loop and implicit
# hydrodynamics ns and CG iterations, fresh and sheared.
#   docs/performance/sheared-start.sh [REPEATS]
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/bashrc" > /dev/null 2>&1
. "$here/benchmarkFunctions"
repeats=${1:-3}
bin="$FOAM_USER_APPBIN/suspensionBenchmark"
csv=$here/sheared-start.csv
this=$(git -C "$WSF_PROJECT_DIR" rev-parse --short HEAD)
git -C "$WSF_PROJECT_DIR" diff --quiet HEAD -- src || this=$this+changes

rows=$(startCsv "$csv" engine,repeat,cpu_s,wall_s,time_v_max_rss_MB, "$bin" -header)
runs=(
    "1 -case table1 -N 1000 -integrator velocityVerlet -steps 200"
    "1 -case table1 -N 1000 -integrator implicitEuler -steps 20"
    "0.3 -case table3 -N 4096 -integrator velocityVerlet -steps 50"
    "0.3 -case table3 -N 4096 -integrator implicitEuler -steps 20"
)
for r in $(seq "$repeats"); do
    for run in "${runs[@]}"; do
        read -r strain args <<< "$run"
        timedBenchmark "$csv" "$this" "$bin" "$r" 1 $args > /dev/null
        timedBenchmark "$csv" "$this" "$bin" "$r" 1 $args -preshear "$strain" > /dev/null
    done
done

# Medians over this invocation, per case, integrator and start
medianTable "$csv" "$rows" "case integrator preshear" \
    "contacts_per_particle ns_per_particle_step pairs_ns hydrodynamics_ns cg_iterations"
