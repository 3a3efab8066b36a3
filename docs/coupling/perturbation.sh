#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Perturbation rheometry (docs/coupling.md): Table 1 FL mixtures at
# phi = 0.35 and 0.45, N = 500, in Kolmogorov forcing of two amplitudes
# (suspensionCoupledFoam), and the same mixtures in uniform shear
# (wavyShearFoam), all from the tutorial tutorials/coupled/kolmogorov.
#
#   docs/coupling/perturbation.sh [workDir]      (default: /tmp/perturbation)
#
# STRAIN (100) strain units each, COUPLING_STRAIN (10) the relaxation strain,
# CASES a list of name:phi:F instead of the nine (F = uniform: the one-way run
# in uniform shear; F with "off" after it: feedback off, the particles in the
# particle-free fluid's forced wave),
# TAG a suffix of the names of the tables and plots (perturbation$TAG.csv),
# outer steps of 0.01, a profile every 2 strain units. Runs the cases JOBS (2)
# at a time (one thread each), then docs/coupling/analyse.py writes
# perturbation.csv, migration.csv, momentum.csv and their plots beside this
# script. A case already run (its log ends with End) is
# not run again.
#------------------------------------------------------------------------------
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${1:-/tmp/perturbation}
strain=${STRAIN:-100}
couplingStrain=${COUPLING_STRAIN:-10}
. "$root/etc/bashrc"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
mkdir -p "$work"

# case <name> <phi> <F> (F = uniform: the one-way run in uniform shear)
setUp()
{
    local c=$work/$1
    [ -d "$c" ] && return 0
    cp -r "$root/tutorials/coupled/kolmogorov" "$c"
    sed -i "s/^\(    volumeFraction *\)[0-9.]*;/\1$2;/" "$c/constant/suspensionProperties"
    sed -i "s/^endTime .*/endTime         $strain;/; s/^deltaT .*/deltaT          0.01;/; s/^writeInterval .*/writeInterval   200;/" \
        "$c/system/controlDict"
    if [ "$3" = uniform ]; then
        sed -i 's/^application .*/application     wavyShearFoam;/' "$c/system/controlDict"
        sed -i '/^    coupling /,/^    }/d' "$c/system/controlDict"
        sed -i '/^ambientFlow/,/^}/c\ambientFlow\n{\n    type            uniformShear;\n    shearRate       1;\n}' \
            "$c/constant/suspensionProperties"
    else
        sed -i "s/^\(    amplitude *\)[0-9.]*;/\1${3%off};/; s/^couplingStrain .*/couplingStrain      $couplingStrain;/" \
            "$c/constant/couplingProperties"
        case "$3" in
            *off) sed -i "s/^feedback .*/feedback            off;/" "$c/constant/couplingProperties" ;;
        esac
    fi
}

run()
{
    local c=$work/$1
    if grep -qx End "$c/log.run" 2>/dev/null; then return 0; fi
    (
        cd "$c"
        makeSuspension -boxOnly > log.box 2>&1
        blockMesh > log.blockMesh 2>&1
        app=$(sed -n 's/^application *\([A-Za-z]*\);/\1/p' system/controlDict)
        /usr/bin/time -v "$app" > log.run 2> log.time
    )
}
export -f run
export work

cases=${CASES:-"phi0.35_F0:0.35:0 phi0.35_F0.1:0.35:0.1 phi0.35_F0.2:0.35:0.2
       phi0.35_F0.2off:0.35:0.2off phi0.35_uniform:0.35:uniform
       phi0.45_F0.2:0.45:0.2 phi0.45_F0.4:0.45:0.4 phi0.45_F0.2off:0.45:0.2off
       phi0.45_uniform:0.45:uniform"}
names=""
for c in $cases; do
    IFS=: read -r name phi F <<< "$c"
    setUp "$name" "$phi" "$F"
    names="$names $name"
done
printf '%s\n' $names | xargs -P "${JOBS:-2}" -I{} bash -c 'run {}'

"$here/analyse.py" "$work" "$here" "${TAG:-}"
