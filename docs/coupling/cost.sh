#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The cost of the mesh side of suspensionCoupledFoam (docs/coupling.md):
# tutorials/coupled/kolmogorov at N = 4096 (phi = 0.35; 1 x 32 x 1 cells),
# 1 strain unit in outer steps of 0.01 (2 engine steps and a shorter one
# each) and of 0.1 (the tutorial's: 21 engine steps), on THREADS (1)
# threads and on each process count of PROCS ("1"; e.g. "1 2": decomposed
# in y, mpirun), REPEAT (5) times each, alternated. Prints, per run, the solver's
# own split of the outer steps' wall seconds (particles; mesh side:
# coarse-graining with the stresslets it needs, solve, flow update) and
# writes them to cost.csv beside this script (anew), with the process's CPU
# seconds and peak RSS (/usr/bin/time -v).
#
#   docs/coupling/cost.sh [workDir]      (default: /tmp/couplingCost)
#
# Run it alone on the machine: the shares are of wall time.
#------------------------------------------------------------------------------
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${1:-/tmp/couplingCost}
threads=${THREADS:-1}
repeat=${REPEAT:-5}
procs=${PROCS:-1}
. "$root/etc/bashrc"
export OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=PASSIVE
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

c=$work/N4096
if [ ! -d "$c/0" ]; then
    rm -rf "$c"
    mkdir -p "$work"
    cp -r "$root/tutorials/coupled/kolmogorov" "$c"
    foamDictionary -entry population/nParticles -set 4096 "$c/constant/suspensionProperties" > /dev/null
    sed -i 's/(1 16 1)/(1 32 1)/' "$c/system/blockMeshDict"
    foamDictionary -entry endTime -set 1 "$c/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 1000 "$c/system/controlDict" > /dev/null
    (cd "$c" && makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1 \
        && makeSuspension > log.makeSuspension 2>&1)
fi

# The decomposed case of P processes: slabs in y
decomposed()
{
    local d=$work/N4096.P$1
    if [ ! -d "$d/processor0/0" ]; then
        rm -rf "$d"
        cp -r "$c" "$d"
        printf '%s\n' \
            "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }" \
            "numberOfSubdomains $1;" "method simple;" "coeffs { n (1 $1 1); }" \
            > "$d/system/decomposeParDict"
        (cd "$d" && decomposePar > log.decomposePar 2>&1)
    fi
    echo "$d"
}

csv=$here/cost.csv
echo "N,threads,processes,outerStep,run,wallOuterSteps,particles,coarseGraining,solve,flowUpdate,meshShare,cpuSeconds,peakRSSMB" > "$csv"
for r in $(seq 1 "$repeat"); do
for P in $procs; do
for outer in 0.01 0.1; do
    if [ "$P" = 1 ]; then
        d=$c
        rm -rf "$d"/0.* "$d"/[1-9]* "$d/postProcessing"
        run=(suspensionCoupledFoam)
    else
        d=$(decomposed "$P")
        rm -rf "$d"/processor*/0.* "$d"/processor*/[1-9]* "$d/postProcessing"
        run=(mpirun --oversubscribe -np "$P" -x OMP_NUM_THREADS -x OMP_WAIT_POLICY suspensionCoupledFoam -parallel)
    fi
    foamDictionary -entry deltaT -set "$outer" "$d/system/controlDict" > /dev/null
    # /usr/bin/time -v over mpirun: the CPU of all processes, the peak RSS
    # of the largest
    (cd "$d" && /usr/bin/time -v "${run[@]}" > log.run 2> log.time)
    line=$(grep "^Coupling: wall seconds" "$d/log.run")
    echo "$line"
    cpu=$(awk -F: '/User time/ { u = $2 } /System time/ { s = $2 } END { print u + s }' "$d/log.time")
    rss=$(awk -F: '/Maximum resident/ { print int($2/1024) }' "$d/log.time")
    echo "$line" | sed 's/[:,()%]/ /g' | awk -v t="$threads" -v P="$P" -v o="$outer" -v r="$r" -v cpu="$cpu" -v rss="$rss" '
        { for (i = 1; i <= NF; ++i) {
              if ($i == "steps") total = $(i + 1)
              if ($i == "particles") p = $(i + 1)
              if ($i == "coarse-graining") cg = $(i + 1)
              if ($i == "solve") s = $(i + 1)
              if ($i == "new" && $(i + 1) == "flow") fu = $(i + 2)
          } }
        END { printf "4096,%s,%s,%s,%s,%s,%s,%s,%s,%s,%.4f,%s,%s\n", t, P, o, r, total, p, cg, s, fu,
                     (cg + s + fu)/total, cpu, rss }' >> "$csv"
done
done
done
echo "$csv"
