#!/bin/bash
#------------------------------------------------------------------------------
# Peak resident memory of the OpenFOAM side at the paper's size: Table 3 NW
# (tutorials/wavyShear/NW: every force, the 4 a0 attraction range) with
# nParticles N, implicitEuler, one thread, to strain 0.002 with a write every
# 0.001 (8 engine steps, two writes), each program under /usr/bin/time -v.
#
#   docs/performance/solver-memory.sh [N]        (default 65536)
#
# Case and logs in run/performance/memory/<N>; prints one CSV row per
# program (commit,N,program,maxrss_kB) and appends it to
# docs/performance/solver-memory.csv. makeSuspension -boxOnly is the
# baseline of an OpenFOAM program that holds no particles.
#------------------------------------------------------------------------------
set -eu
root=$(cd "${0%/*}/../.." && pwd)
set +u
. "$root/etc/bashrc" > /dev/null 2>&1
. "$root/etc/caseFunctions"
set -u
N=${1:-65536}
dir=$root/run/performance/memory/$N
csv=$root/docs/performance/solver-memory.csv
commit=$(git -C "$root" rev-parse --short HEAD)

rm -rf "$dir"; mkdir -p "$dir"
cp -r "$root/tutorials/wavyShear/NW/constant" "$root/tutorials/wavyShear/NW/system" "$dir"
setEntry "$dir/constant/suspensionProperties" population/nParticles "$N"
setEntry "$dir/constant/suspensionProperties" integration/integrator implicitEuler
setEntry "$dir/system/controlDict" endTime 0.002
setEntry "$dir/system/controlDict" deltaT 0.0005
setEntry "$dir/system/controlDict" writeInterval 2

[ -f "$csv" ] || echo "commit,N,program,maxrss_kB" > "$csv"
export OMP_NUM_THREADS=1
cd "$dir"
for step in "makeSuspension -boxOnly:box" "blockMesh:blockMesh" \
            "makeSuspension:makeSuspension" "wavyShearFoam:wavyShearFoam"; do
    cmd=${step%%:*} log=log.${step##*:}
    /usr/bin/time -v $cmd > "$log" 2>&1 || { echo "$cmd failed, see $dir/$log" >&2; exit 1; }
    kB=$(awk -F': ' '/Maximum resident set size/ { print $2 }' "$log")
    echo "$commit,$N,$cmd,$kB" | tee -a "$csv"
done
