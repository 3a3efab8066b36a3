#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Two runs side by side on one thread each against one run on two threads:
# the throughput of the implicit step on a 2-core machine (docs/performance.md,
# "Table 3 at N = 65536"). From the latest write t0 of CASE (default the
# N = 65536 NW validation run), each repeat runs
#   a:      one copy with OMP_NUM_THREADS=2,
#   b1, b2: two copies with OMP_NUM_THREADS=1, started together,
# each to t0 + 0.02 under /usr/bin/time, and appends to side-by-side.csv next
# to this script: the rate of the last progress line (steps per second over
# t0 + 0.01 .. t0 + 0.02, past the start-up) and the whole process's wall,
# user and system seconds. Other wavyShearFoam processes are stopped
# (SIGSTOP) while it runs and continued at the end. Prints the medians over
# the repeats of the throughput ratio b/a (steps/s and whole-process) and of
# the CPU of one run on one thread over one on two.
#   docs/performance/side-by-side.sh [-r REPEATS] [CASE]
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" > /dev/null 2>&1
. "$here/benchmarkFunctions"
repeats=5
while getopts r: opt; do
    case $opt in
        r) repeats=$OPTARG ;;
        *) sed -n 2,17p "$0"; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
src=$(cd "${1:-$top/run/validation/table3-65536/NW}" && pwd)
t0=$(ls "$src" | grep -E '^[0-9.eE+-]+$' | sort -g | tail -1)
t1=$(awk -v t="$t0" 'BEGIN { print t + 0.02 }')
work=$(mktemp -d)
csv=$here/side-by-side.csv

stopped=$(pgrep -x wavyShearFoam | tr '\n' ' ' || true)
cleanup() { [ -z "$stopped" ] || kill -CONT $stopped; rm -rf "$work"; }
trap cleanup EXIT
[ -z "$stopped" ] || kill -STOP $stopped

for d in a b1 b2; do
    mkdir "$work/$d"
    cp -r "$src/constant" "$src/system" "$src/$t0" "$work/$d"
    foamDictionary -entry endTime -set "$t1" "$work/$d/system/controlDict" > /dev/null
done

[ -f "$csv" ] || echo "date,commit,case,t0,repeat,run,threads,steps_per_s,wall_s,user_s,sys_s" > "$csv"
commit=$(git -C "$top" rev-parse --short HEAD)
# run <dir> <threads> <repeat>: one solver run from t0, a CSV row
run() {
    local d=$work/$1
    # Only t0 is left: every repeat starts from it
    (cd "$d" && ls | grep -E '^[0-9.eE+-]+$' | grep -vx "$t0" | xargs -r rm -rf) || true
    rm -rf "$d/postProcessing"
    (cd "$d" && OMP_NUM_THREADS=$2 /usr/bin/time -f "%e,%U,%S" -o time \
        wavyShearFoam > log 2>&1)
    local rate
    rate=$(grep '^strain ' "$d/log" | tail -1 | sed 's/.* \([0-9.]*\) steps\/s.*/\1/')
    echo "$(date +%F),$commit,${src#$top/},$t0,$3,$1,$2,$rate,$(cat "$d/time")" >> "$csv"
}
rows=$(($(wc -l < "$csv") + 1))
for r in $(seq "$repeats"); do
    run a 2 "$r"
    run b1 1 "$r" & run b2 1 "$r" & wait
done

# Medians over this invocation's repeats
tail -n +"$rows" "$csv" | awk -F, "$awkMedian"'
    { rate[$5, $6] = $8; wall[$5, $6] = $9; cpu[$5, $6] = $10 + $11; n = $5 }
    END {
        for (r = 1; r <= n; r++) {
            s[r] = (rate[r, "b1"] + rate[r, "b2"])/rate[r, "a"]
            w[r] = 2*wall[r, "a"]/(wall[r, "b1"] > wall[r, "b2"] ? wall[r, "b1"] : wall[r, "b2"])
            c[r] = (cpu[r, "b1"] + cpu[r, "b2"])/(2*cpu[r, "a"])
        }
        printf "throughput b/a, steps/s past the start-up: median %.2f\n", median(s, n)
        printf "throughput b/a, whole processes:           median %.2f\n", median(w, n)
        printf "CPU of a run, 1 thread/2 threads:          median %.2f\n", median(c, n)
    }'
