#!/usr/bin/env bash
# The cost of a decomposed run (issue 32; docs/parallel.md): Table 1 FR
# spheres or Table 3, implicitEuler, one process with one and two threads
# against two processes with one thread each (OpenMPI), alternated, and a
# weak-scaling series (N/2 per process; P = 4 on 2 cores is
# oversubscribed; not with SERIES strong).
#   docs/performance/parallel.sh [N] [REPEATS] [STEPS] [CASE] [SERIES]
#   docs/performance/parallel.sh 16000 5 20                 # parallel.csv
#   docs/performance/parallel.sh 65536 5 20 table3 strong   # parallel-table3.csv
# Writes the CSV here: the benchmark's row (time per step, its part in
# communication, halo, bytes sent; the largest over the processes) with
# the whole run's user+system CPU seconds, wall seconds and peak resident
# set (the largest process's, /usr/bin/time).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
bin="$root/build/tests/parallelBenchmark"
N=${1:-16000}
repeats=${2:-5}
steps=${3:-20}
case=${4:-table1}
series=${5:-all}
out="$here/parallel.csv"
[ "$case" = table1 ] || out="$here/parallel-$case.csv"
export WM_PROJECT_DIR=${WM_PROJECT_DIR:-$(sed -n 's/^WSF_FOAM_ETC:PATH=//p' "$root/build/CMakeCache.txt")}
mpi=(mpirun --oversubscribe --allow-run-as-root)
echo "series,repeat,$("$bin" -header),cpu_s,wall_s,peak_rss_MB" > "$out"
run() # series repeat threads P N
{
    local cmd=("$bin" -case "$case" -N "$5" -steps "$steps")
    if [ "$4" -gt 1 ]; then cmd=("${mpi[@]}" -np "$4" "${cmd[@]}" -parallel); fi
    local row
    row=$( { OMP_NUM_THREADS=$3 /usr/bin/time -f "TIME %U %S %e %M" "${cmd[@]}" 2>&1 >&3 | grep '^TIME' >&2; } 3>&1 2>/tmp/parallelBench.time | grep -E '^table[0-9],' )
    read -r _ u s e m < /tmp/parallelBench.time
    echo "$1,$2,$row,$(printf "%.2f" "$(echo "$u + $s" | bc)"),$e,$((m/1024))" >> "$out"
}
for r in $(seq 1 "$repeats"); do
    # strong: the same N three ways, the order rotated
    configs=("1 1" "2 1" "1 2")
    for k in 0 1 2; do
        c=${configs[$(( (k + r) % 3 ))]}
        run strong "$r" ${c% *} ${c#* } "$N"
    done
    # weak: N/2 per process
    [ "$series" = strong ] && continue
    for P in 1 2 4; do
        run weak "$r" 1 "$P" $(( N/2*P ))
    done
done
python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
keys = sorted({(r["series"], int(r["P"]), int(r["threads"]), int(r["N"])) for r in rows})
for k in keys:
    sel = [r for r in rows if (r["series"], int(r["P"]), int(r["threads"]), int(r["N"])) == k]
    med = lambda c: statistics.median(float(r[c]) for r in sel)
    print(f"{k[0]:6s} P={k[1]} threads={k[2]} N={k[3]:6d}: s/step {med('s_per_step'):.4f}"
          f"  comm {med('comm_fraction')*100:.1f}%  ghosts/owned {med('ghosts_per_owned'):.3f}"
          f"  MB/step {med('MB_sent_per_step'):.2f}  CG {med('cg_iterations'):.1f}"
          f"  cpu s {med('cpu_s'):.1f}  wall s {med('wall_s'):.1f}  peak RSS MB {med('peak_rss_MB'):.0f}"
          f"  ({len(sel)} runs)")
PY
