#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Threads on a busy machine (docs/performance.md, "Threads beside another
# program"): Table 3 YW (tutorials/wavyShear/YW, implicitEuler) packed at N
# particles, run from its packing to strain T under /usr/bin/time, with
#   1t           OMP_NUM_THREADS=1
#   2t adaptive  OMP_NUM_THREADS=2, integration/threads adaptive (default)
#   2t fixed     OMP_NUM_THREADS=2, integration/threads fixed
# each on the idle machine and beside a CPU-bound program on core 1
# (taskset -c 1 yes), alternated run by run, REPEATS times. Appends to
# busy-core.csv next to this script (wall, user, sys seconds, peak RSS) and
# prints, per N and load, the medians and the paired ratios to 1t. Other
# wavyShearFoam processes are stopped (SIGSTOP) while it runs.
#   docs/performance/busy-core.sh [-r REPEATS] [-N "4096 65536"] [-T "0.01 0.001"]
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" > /dev/null 2>&1
repeats=5
sizes="4096 65536"
ends="0.01 0.001"
while getopts r:N:T: opt; do
    case $opt in
        r) repeats=$OPTARG ;;
        N) sizes=$OPTARG ;;
        T) ends=$OPTARG ;;
        *) sed -n 2,15p "$0"; exit 2 ;;
    esac
done
work=$(mktemp -d)
csv=$here/busy-core.csv
commit=$(git -C "$top" rev-parse --short HEAD)
[ -f "$csv" ] || echo "date,commit,N,endTime,load,run,repeat,wall_s,user_s,sys_s,maxRSS_kB" > "$csv"

stopped=$(pgrep -x wavyShearFoam | tr '\n' ' ' || true)
hog=
cleanup()
{
    [ -z "$hog" ] || kill "$hog" 2> /dev/null || true
    [ -z "$stopped" ] || kill -CONT $stopped
    rm -rf "$work"
}
trap cleanup EXIT
[ -z "$stopped" ] || kill -STOP $stopped

set -- $ends
for N in $sizes; do
    T=$1; shift
    base=$work/base$N-$T
    cp -r "$top/tutorials/wavyShear/YW" "$base"
    (
        cd "$base"
        foamDictionary -entry population/nParticles -set "$N" constant/suspensionProperties > /dev/null
        foamDictionary -entry endTime -set "$T" system/controlDict > /dev/null
        foamDictionary -entry writeInterval -set 1000 system/controlDict > /dev/null
        foamDictionary -entry functions -remove system/controlDict > /dev/null
        makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1 \
            && makeSuspension > log.makeSuspension 2>&1
    ) || { echo "busy-core.sh: setting up N = $N failed (see $base)" >&2; exit 1; }

    for load in idle busy; do
        if [ $load = busy ]; then
            taskset -c 1 yes > /dev/null &
            hog=$!
        fi
        for r in $(seq 1 "$repeats"); do
            for run in 1t 2t-adaptive 2t-fixed; do
                d=$work/$run
                rm -rf "$d"
                cp -r "$base" "$d"
                threads=2
                mode=adaptive
                case $run in
                    1t) threads=1 ;;
                    2t-fixed) mode=fixed ;;
                esac
                foamDictionary -entry integration/threads -set $mode \
                    "$d/constant/suspensionProperties" > /dev/null
                (cd "$d" && OMP_NUM_THREADS=$threads /usr/bin/time -f "%e,%U,%S,%M" \
                    -o time wavyShearFoam > log 2>&1) \
                    || { echo "busy-core.sh: run $run failed (see $d/log)" >&2; exit 1; }
                echo "$(date +%F),$commit,$N,$T,$load,$run,$r,$(cat "$d/time")" >> "$csv"
            done
        done
        if [ $load = busy ]; then
            kill "$hog"
            hog=
        fi
    done
done

# Medians of this commit's rows, and the paired ratios to 1t (repeat by repeat)
python3 - "$csv" "$commit" <<'PY'
import csv, statistics, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["commit"] == sys.argv[2]]
cases = sorted({(int(r["N"]), float(r["endTime"]), r["load"]) for r in rows})
for N, T, load in cases:
    sel = [r for r in rows
           if int(r["N"]) == N and float(r["endTime"]) == T and r["load"] == load]
    ref = {r["repeat"]: float(r["wall_s"]) for r in sel if r["run"] == "1t"}
    line = []
    for run in ("1t", "2t-adaptive", "2t-fixed"):
        rs = [r for r in sel if r["run"] == run]
        wall = statistics.median(float(r["wall_s"]) for r in rs)
        cpu = statistics.median(float(r["user_s"]) + float(r["sys_s"]) for r in rs)
        ratio = statistics.median(float(r["wall_s"])/ref[r["repeat"]] for r in rs)
        line.append(f"{run} wall {wall:.2f} s (x{ratio:.2f} of 1t), CPU {cpu:.2f} s")
    print(f"N = {N}, strain {T}, {load} ({len(ref)} repeats): " + "; ".join(line))
PY
