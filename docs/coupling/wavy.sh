#!/usr/bin/env bash
#------------------------------------------------------------------------------
# The paper's wavy case with back-reaction (docs/coupling.md): Table 3 YW
# (tutorials/wavyShear/YW) at N = 1024 (attraction cut at 0.5 a0, the
# smallest box of the 4 a0 cut-off needs N >= 2700; safety 0.1, as
# docs/validation.md section 4), from one packing:
#   imposed   wavyShearFoam in the wave of eq. (17), script-U = 20 gammaDot a0
#   coupled   suspensionCoupledFoam, Kolmogorov forcing F = 20 eta0 k^2 (the
#             particle-free fluid carries that wave), feedback on,
#             couplingStrain 0.5, kernel width 6 a0 (= 2 a_max), 16 rows
#
#   docs/coupling/wavy.sh [workDir]      (default: /tmp/wavy)
#
# STRAIN (4) strain units each, N (1024) particles, the two runs side by
# side (one thread each), restartable (a run continues from its latest
# write). Then docs/coupling/wavy.py writes wavy<TAG>.csv and wavy<TAG>.png
# beside this script (TAG: empty, or -N<N> for another N).
#------------------------------------------------------------------------------
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${1:-/tmp/wavy}
strain=${STRAIN:-4}
nParticles=${N:-1024}
. "$root/etc/bashrc"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
mkdir -p "$work"

setUp()
{
    local c=$work/$1
    [ -d "$c" ] && return 0
    mkdir -p "$c"
    cp -r "$root/tutorials/wavyShear/YW/constant" "$root/tutorials/wavyShear/YW/system" "$c"
    local p=$c/constant/suspensionProperties
    foamDictionary -entry population/nParticles -set "$nParticles" "$p" > /dev/null
    foamDictionary -entry electroChemical/attraction/cutoffGap -set 0.5 "$p" > /dev/null
    foamDictionary -entry integration/safety -set 0.1 "$p" > /dev/null
    local cd=$c/system/controlDict
    foamDictionary -entry deltaT -set 0.01 "$cd" > /dev/null
    foamDictionary -entry writeInterval -set 50 "$cd" > /dev/null
    foamDictionary -entry writeFormat -set binary "$cd" > /dev/null
    foamDictionary -entry functions/profiles/nBins -set 16 "$cd" > /dev/null
    foamDictionary -entry functions/fields -remove "$cd" > /dev/null
    (cd "$c" && makeSuspension -boxOnly > log.box 2>&1)
    if [ "$1" = coupled ]; then
        local k=$root/tutorials/coupled/kolmogorov
        cp "$k/system/blockMeshDict" "$k/system/fvSchemes" "$k/system/fvSolution" "$c/system"
        cp "$k/constant/couplingProperties" "$c/constant"
        foamDictionary -entry application -set suspensionCoupledFoam "$cd" > /dev/null
        foamDictionary -entry functions/coupling -set \
            "{ type suspensionCoupling; libs (suspensionFunctionObjects); writeControl timeStep; writeInterval 1; }" \
            "$cd" > /dev/null
        foamDictionary -entry ambientFlow -set "{ type meshField; shearRate 1; field Uprime; }" \
            "$p" > /dev/null
        local Ly F
        Ly=$(awk '$1 == "Ly" { sub(/;/, "", $2); print $2 }' "$c/constant/particleBox")
        F=$(awk -v Ly="$Ly" 'BEGIN { k = 2*3.14159265358979324/Ly; printf "%.10g", 20*k*k }')
        local cp=$c/constant/couplingProperties
        foamDictionary -entry bodyForce/amplitude -set "$F" "$cp" > /dev/null
        foamDictionary -entry couplingStrain -set 0.5 "$cp" > /dev/null
        foamDictionary -entry coarseGraining/width -set 6 "$cp" > /dev/null
    fi
    (cd "$c" && blockMesh > log.blockMesh 2>&1 && makeSuspension > log.makeSuspension 2>&1)
}

run()
{
    local c=$work/$1
    foamDictionary -entry endTime -set "$strain" "$c/system/controlDict" > /dev/null
    local app
    app=$(foamDictionary -entry application -value "$c/system/controlDict")
    (cd "$c" && /usr/bin/time -v "$app" >> log.run 2>> log.time)
}
export -f run
export work strain

for c in imposed coupled; do
    setUp "$c"
done
printf '%s\n' imposed coupled | xargs -P 2 -I{} bash -c 'run {}'

tag=""
[ "$nParticles" = 1024 ] || tag=-N$nParticles
"$here/wavy.py" "$work" "$here" "$tag"
