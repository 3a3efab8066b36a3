#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Time the random packing of makeSuspension (docs/user-guide.md, "Population"):
# the Table 1 mixture (a2/a1 = 1.4, V2/V1 = 1) at phi = 0.60 with N = 200
# and 1000, the Table 3 mixture (a2/a1 = 3, V2/V1 = 0.25) at phi = 0.55 with
# N = 4096 and at phi = 0.5 with N = 65536, one thread, REPEATS runs each
# in turn. Writes packing.csv next to this script (whole process: wall,
# user and system seconds, peak RSS) and prints the medians. The whole
# process includes OpenFOAM's start-up and the writing of the packing;
# `makeSuspension -boxOnly` alone, timed the same way, is its floor.
#   docs/performance/packing.sh [REPEATS]      (default 5)
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" > /dev/null 2>&1
. "$top/etc/caseFunctions"
. "$here/benchmarkFunctions"
repeats=${1:-5}
export OMP_NUM_THREADS=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
csv=$here/packing.csv
commit=$(git -C "$top" rev-parse --short HEAD)

# prepare <name> <template> <N> <phi>: a case with its box and mesh
prepare()
{
    cp -r "$top/tutorials/$2" "$work/$1"
    setEntry "$work/$1/constant/suspensionProperties" population/nParticles "$3"
    setEntry "$work/$1/constant/suspensionProperties" population/volumeFraction "$4"
    (cd "$work/$1" && makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1)
}
prepare table1-N200 uniformShear/frictionless 200 0.60
prepare table1-N1000 uniformShear/frictionless 1000 0.60
prepare table3-N4096 wavyShear/NW 4096 0.55
prepare table3-N65536 wavyShear/NW 65536 0.5

[ -f "$csv" ] || echo "date,commit,case,repeat,program,wall_s,user_s,sys_s,maxrss_kB" > "$csv"
rows=$(($(wc -l < "$csv") + 1))
for r in $(seq "$repeats"); do
    for c in table1-N200 table1-N1000 table3-N4096 table3-N65536; do
        for program in "makeSuspension -boxOnly" makeSuspension; do
            rm -rf "$work/$c/0"
            (cd "$work/$c" && /usr/bin/time -f "%e,%U,%S,%M" -o time $program > log 2>&1)
            echo "$(date +%F),$commit,$c,$r,$program,$(cat "$work/$c/time")" >> "$csv"
        done
    done
done

# Medians over this invocation's repeats: CPU (user + sys) of the packing
# run and of the -boxOnly floor, wall of the packing run
tail -n +"$rows" "$csv" | sort -t, -k3,3 -k5,5 | awk -F, "$awkMedian"'
    function flush() {
        if (key != "") printf "%-14s %-24s CPU s %.2f  wall s %.2f\n", c, p, median(cpu, n), median(wall, n) }
    { if ($3 "," $5 != key) { flush(); key = $3 "," $5; c = $3; p = $5; n = 0 }
      n++; cpu[n] = $7 + $8; wall[n] = $6 }
    END { flush() }'
