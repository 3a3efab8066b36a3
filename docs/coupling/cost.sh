#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The cost of the mesh side of suspensionCoupledFoam (docs/coupling.md):
# tutorials/coupled/kolmogorov at N = 4096 (phi = 0.35; 1 x 32 x 1 cells),
# 1 strain unit in outer steps of 0.01 (2 engine steps and a shorter one
# each) and of 0.1 (the tutorial's: 21 engine steps), on THREADS (1)
# threads, REPEAT (5) times each, alternated. Prints, per run, the solver's
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
. "$root/etc/bashrc"
export OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=PASSIVE

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

csv=$here/cost.csv
echo "N,threads,outerStep,run,wallOuterSteps,particles,coarseGraining,solve,flowUpdate,meshShare,cpuSeconds,peakRSSMB" > "$csv"
for r in $(seq 1 "$repeat"); do
for outer in 0.01 0.1; do
    rm -rf "$c"/0.* "$c"/[1-9]* "$c/postProcessing"
    foamDictionary -entry deltaT -set "$outer" "$c/system/controlDict" > /dev/null
    (cd "$c" && /usr/bin/time -v suspensionCoupledFoam > log.run 2> log.time)
    line=$(grep "^Coupling: wall seconds" "$c/log.run")
    echo "$line"
    cpu=$(awk -F: '/User time/ { u = $2 } /System time/ { s = $2 } END { print u + s }' "$c/log.time")
    rss=$(awk -F: '/Maximum resident/ { print int($2/1024) }' "$c/log.time")
    echo "$line" | sed 's/[:,()%]/ /g' | awk -v t="$threads" -v o="$outer" -v r="$r" -v cpu="$cpu" -v rss="$rss" '
        { for (i = 1; i <= NF; ++i) {
              if ($i == "steps") total = $(i + 1)
              if ($i == "particles") p = $(i + 1)
              if ($i == "coarse-graining") cg = $(i + 1)
              if ($i == "solve") s = $(i + 1)
              if ($i == "new" && $(i + 1) == "flow") fu = $(i + 2)
          } }
        END { printf "4096,%s,%s,%s,%s,%s,%s,%s,%s,%.4f,%s,%s\n", t, o, r, total, p, cg, s, fu,
                     (cg + s + fu)/total, cpu, rss }' >> "$csv"
done
done
echo "$csv"
