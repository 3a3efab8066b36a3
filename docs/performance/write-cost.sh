#!/usr/bin/env bash
#------------------------------------------------------------------------------
# What the commit of a write costs (docs/robustness.md, "What a write
# costs"): Table 3 YW (tutorials/wavyShear/YW) packed at N particles, then
# a run of one engine step that writes its end time, under /usr/bin/time,
# with the solver of this tree (A) and that of REFBIN (B: a folder of
# another build's programs, its libraries in REFBIN/../lib), alternated
# REPEATS times. Appends to write-cost.csv next to this script; prints the
# medians and the paired difference A - B.
#   docs/performance/write-cost.sh -b REFBIN [-r REPEATS] [-N 65536]
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" > /dev/null 2>&1
repeats=5
N=65536
refbin=
while getopts b:r:N: opt; do
    case $opt in
        b) refbin=$(cd "$OPTARG" && pwd) ;;
        r) repeats=$OPTARG ;;
        N) N=$OPTARG ;;
        *) sed -n 2,11p "$0"; exit 2 ;;
    esac
done
[ -n "$refbin" ] || { sed -n 2,11p "$0"; exit 2; }
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
csv=$here/write-cost.csv
commit=$(git -C "$top" rev-parse --short HEAD)
[ -f "$csv" ] || echo "date,commit,N,solver,repeat,wall_s,user_s,sys_s,bytes_written" > "$csv"

base=$work/base
cp -r "$top/tutorials/wavyShear/YW" "$base"
(
    cd "$base"
    foamDictionary -entry population/nParticles -set "$N" constant/suspensionProperties > /dev/null
    foamDictionary -entry functions -remove system/controlDict > /dev/null
    foamDictionary -entry writeInterval -set 1 system/controlDict > /dev/null
    makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1 \
        && makeSuspension > log.makeSuspension 2>&1
    # one engine step: the sampling interval is the step
    dt=$(awk '/time step    dt = / { print $5; exit }' log.makeSuspension)
    foamDictionary -entry deltaT -set "$dt" system/controlDict > /dev/null
    foamDictionary -entry endTime -set "$dt" system/controlDict > /dev/null
)
for r in $(seq 1 "$repeats"); do
    for solver in A B; do
        d=$work/$solver
        rm -rf "$d"
        cp -r "$base" "$d"
        if [ $solver = A ]; then
            cmd=(wavyShearFoam)
        else
            cmd=(env "LD_LIBRARY_PATH=$refbin/../lib:$LD_LIBRARY_PATH" "$refbin/wavyShearFoam")
            # a build before the digests reads a state without them
            foamDictionary -entry files -remove "$d/0/uniform/suspensionState" > /dev/null
        fi
        (cd "$d" && OMP_NUM_THREADS=1 /usr/bin/time -f "%e,%U,%S" -o time "${cmd[@]}" > log 2>&1) \
            || { echo "write-cost.sh: solver $solver failed (see $d/log)" >&2; exit 1; }
        t=$(ls "$d" | grep -E '^[0-9.eE+-]+$' | sort -g | tail -1)
        bytes=$(du -sb "$d/$t" | cut -f1)
        echo "$(date +%F),$commit,$N,$solver,$r,$(cat "$d/time"),$bytes" >> "$csv"
    done
done
python3 - "$csv" "$commit" "$N" <<'PY'
import csv, statistics, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["commit"] == sys.argv[2] and r["N"] == sys.argv[3]]
by = {s: {r["repeat"]: r for r in rows if r["solver"] == s} for s in "AB"}
def med(s, f): return statistics.median(float(r[f]) for r in by[s].values())
for s in "AB":
    print(f"{s}: wall {med(s, 'wall_s'):.2f} s, user {med(s, 'user_s'):.2f} s, sys {med(s, 'sys_s'):.2f} s, written {int(med(s, 'bytes_written'))/1e6:.1f} MB")
d = [float(by['A'][k]['wall_s']) - float(by['B'][k]['wall_s']) for k in by['A'] if k in by['B']]
c = [float(by['A'][k]['user_s']) + float(by['A'][k]['sys_s']) - float(by['B'][k]['user_s']) - float(by['B'][k]['sys_s']) for k in by['A'] if k in by['B']]
print(f"A - B, paired medians: wall {statistics.median(d):+.2f} s, CPU {statistics.median(c):+.2f} s ({len(d)} pairs)")
PY
