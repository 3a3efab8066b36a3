#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The implicit operator against this machine's memory bandwidth: REPEATS
# alternated runs on 1 and 2 threads of
#   suspensionBenchmark -roofline -case table3 -N 65536 -steps 5
#                       -integrator implicitEuler
# (its Description says what each column counts), appended to roofline.csv
# next to this script; prints the medians per thread count.
#   docs/performance/roofline.sh [REPEATS] [N]
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/bashrc" > /dev/null 2>&1
. "$here/benchmarkFunctions"
repeats=${1:-5}
N=${2:-65536}
bin="$FOAM_USER_APPBIN/suspensionBenchmark"
csv=$here/roofline.csv
this=$(git -C "$WSF_PROJECT_DIR" rev-parse --short HEAD)
git -C "$WSF_PROJECT_DIR" diff --quiet HEAD -- src || this=$this+changes

rows=$(startCsv "$csv" engine, "$bin" -roofline -header)
for r in $(seq "$repeats"); do
    for threads in 1 2; do
        row=$(env -u LD_LIBRARY_PATH OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=PASSIVE \
            "$bin" -roofline -case table3 -N "$N" -steps 5 -integrator implicitEuler)
        echo "$this,$row" | tee -a "$csv"
    done
done

# Medians over this invocation, per thread count
medianTable "$csv" "$rows" threads \
    "product_ns iteration_ns product_GBs iteration_GBs triad_GBs read_GBs"
