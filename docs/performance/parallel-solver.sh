#!/usr/bin/env bash
# wavyShearFoam itself on the paper's Table 3 (tutorials/wavyShear/NW at
# N = 65 536, implicitEuler), from one packing: 1 process x 1 thread,
# 1 x 2 threads, 2 processes x 1 thread (decomposePar, mpirun -parallel),
# the order rotated, each over 16 sampling intervals of 0.0005 (32 steps,
# one write at the end); what the engine benchmark leaves out (the outer
# steps' redistribution, the function objects, reading and writing)
# included in the whole run's figures.
#   docs/performance/parallel-solver.sh [REPEATS] [N]
# Writes parallel-solver.csv here: wall and user+system CPU seconds and
# the peak resident set of the whole run (the largest process's,
# /usr/bin/time), the solver's steps and its kernel seconds per step (the
# master's "Kernel times" total: the steps alone).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
. "$root/etc/bashrc"
repeats=${1:-5}
N=${2:-65536}
work=$(mktemp -d "${TMPDIR:-/tmp}/parallelSolver.XXXXXX")
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=PASSIVE
out="$here/parallel-solver.csv"
echo "repeat,P,threads,N,steps,wall_s,cpu_s,peak_rss_MB,kernel_s_per_step" > "$out"

packed="$work/packed"
cp -r "$root/tutorials/wavyShear/NW" "$packed"
(
    cd "$packed"
    foamDictionary -entry population/nParticles -set "$N" constant/suspensionProperties > /dev/null
    foamDictionary -entry endTime -set 0.008 system/controlDict > /dev/null
    foamDictionary -entry writeInterval -set 16 system/controlDict > /dev/null
    makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1
    OMP_NUM_THREADS=2 makeSuspension > log.makeSuspension 2>&1
    decomposePar > log.decomposePar 2>&1
)

run() # repeat P threads
{
    local c="$work/run"
    rm -rf "$c"
    cp -r "$packed" "$c"
    local cmd=(wavyShearFoam)
    [ "$2" -gt 1 ] && cmd=(mpirun --oversubscribe -np "$2" wavyShearFoam -parallel)
    (cd "$c" && OMP_NUM_THREADS=$3 /usr/bin/time -f "TIME %e %U %S %M" -o time.txt "${cmd[@]}" > log.run 2>&1)
    read -r _ e u s m < "$c/time.txt"
    local steps kernel
    steps=$(foamDictionary -entry steps -value "$( [ "$2" -gt 1 ] && echo "$c/processor0" || echo "$c")/0.008/uniform/suspensionState")
    kernel=$(awk '$1 == "total" && $4 == "over" { printf "%.4f", $2/$5 }' "$c/log.run")
    echo "$1,$2,$3,$N,$steps,$e,$(echo "$u + $s" | bc),$((m/1024)),$kernel" | tee -a "$out"
}
for r in $(seq 1 "$repeats"); do
    configs=("1 1" "2 1" "1 2")
    for k in 0 1 2; do
        c=${configs[$(( (k + r) % 3 ))]}
        run "$r" ${c% *} ${c#* }
    done
done
python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for k in sorted({(r["P"], r["threads"]) for r in rows}):
    sel = [r for r in rows if (r["P"], r["threads"]) == k]
    med = lambda c: statistics.median(float(r[c]) for r in sel)
    print(f"P={k[0]} threads={k[1]}: wall s {med('wall_s'):.1f}  cpu s {med('cpu_s'):.1f}"
          f"  peak RSS MB {med('peak_rss_MB'):.0f}  steps {med('steps'):.0f}"
          f"  kernel s/step {med('kernel_s_per_step'):.3f}  ({len(sel)} runs)")
PY
