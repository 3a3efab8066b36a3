#!/bin/bash
#------------------------------------------------------------------------------
# The solver's resident set through a window: wavyShearFoam from the kept
# write START of CASE to END, one thread, one write at the end, its VmRSS
# (/proc/<pid>/status) sampled every 0.1 s, under /usr/bin/time -v.
#
#   docs/performance/rss-trace.sh [--tree HOME:TREE] CASE START END [VAR=VALUE]...
#
# --tree     the solver of another built tree (a checkout TREE built with
#            ./Allwmake under HOME=HOME), labelled with its commit
# VAR=VALUE  environment of the run (e.g. MALLOC_MMAP_THRESHOLD_=131072),
#            written into the label
#
# Appends to docs/performance/rss-trace.csv one row per run: label, peak
# RSS kB (time -v), the smallest and largest VmRSS of the middle half of
# the samples (the steps, away from the start and the final write) in MB,
# CPU s (user+sys), and the trace, one sample in six, in MB.
#------------------------------------------------------------------------------
set -eu
root=$(cd "${0%/*}/../.." && pwd)
. "$root/docs/performance/benchmarkFunctions"
home=$HOME; tree=$root
if [ "${1:-}" = --tree ]; then home=${2%%:*}; tree=${2#*:}; shift 2; fi
case=$(cd "$1" && pwd); start=$2; end=$3; shift 3
csv=$root/docs/performance/rss-trace.csv
[ -d "$case/$start" ] || { echo "rss-trace.sh: no time $start in $case" >&2; exit 1; }
[ -f "$csv" ] || echo "label,maxrss_kB,steps_min_MB,steps_max_MB,cpu_s,trace_MB" > "$csv"

label=$(git -C "$tree" rev-parse --short HEAD)
git -C "$tree" diff --quiet HEAD -- src || label=$label+changes
[ $# -gt 0 ] && label="$label $*"

work=$(mktemp -d)
cp -r "$case/constant" "$case/system" "$case/$start" "$work"
(
    set +eu
    cd "$work"
    windowCase "$home" "$tree" "$end"
    env "$@" OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE /usr/bin/time -v \
        wavyShearFoam > log.wavyShearFoam 2> log.time &
    timer=$!
    sleep 0.05
    solver=$(pgrep -n -P "$timer" || true)
    while kill -0 "$timer" 2> /dev/null; do
        [ -n "$solver" ] && awk '/^VmRSS/ {print $2}' "/proc/$solver/status" 2> /dev/null
        sleep 0.1
    done > rss.txt
    wait "$timer"
) || { echo "rss-trace.sh: the run failed, see $work" >&2; exit 1; }

awk -v label="$label" '
    FNR == NR { v[++n] = $1/1000; next }
    /Maximum resident/ { split($0, f, ": "); m = f[2] }
    /User time/ { split($0, f, ": "); u = f[2] } /System time/ { split($0, f, ": "); s = f[2] }
    END {
        lo = 1e30; hi = 0
        for (k = int(n/4) + 1; k <= int(3*n/4); ++k) { if (v[k] < lo) lo = v[k]; if (v[k] > hi) hi = v[k] }
        t = ""; for (k = 6; k <= n; k += 6) t = t sprintf("%s%.0f", t == "" ? "" : " ", v[k])
        printf "%s,%s,%.1f,%.1f,%.2f,%s\n", label, m, lo, hi, u + s, t
    }' "$work/rss.txt" "$work/log.time" | tee -a "$csv"
rm -rf "$work"
