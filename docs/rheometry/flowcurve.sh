#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Steady flow curves under rate and under stress control (docs/rheometry.md),
# from the tutorial tutorials/uniformShear/frictional (Table 1 FR: implicitEuler,
# k_hat = 4e5, mu_C = 1, N = 1000 bidisperse 1:1.4):
#
#   docs/rheometry/flowcurve.sh [workDir]       (default: /tmp/flowcurve)
#
# TAG (FR) names the set; N (500), PHI (0.5), SEED (1: the packing's);
# CRITICAL_LOAD (none: the frictional contact of Table 1; a number F_CL:
# criticalLoadContact, friction only above the load F_CL [eta0 a0^2
# gammaDot], shear thickening); STIFFNESS (the tutorial's k_hat = 4e5:
# contact/stiffness); RATES ("1") the rate-controlled runs, STRESSES ("")
# the stress-controlled ones [eta0 gammaDot]; STRAIN (20) strain units each
# (a stress-controlled run for STRAIN ETA/sigma time units, ETA (50) a guess
# of its etaR: run the script again with a larger STRAIN or ETA to go on,
# from the last state).
# Outer steps of 0.01 strain, one thread each, the cases one after the other
# (a case whose log ends with End is not run again). Then
# docs/rheometry/analyse.py flowcurve writes flowcurve-$TAG.csv (the steady
# summaries: etaR = sigma/gammaDot with error bars; under stress control
# from the mean rate) and flowcurve.png.
#------------------------------------------------------------------------------
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${1:-/tmp/flowcurve}
tag=${TAG:-FR}
N=${N:-500}
phi=${PHI:-0.5}
seed=${SEED:-1}
fcl=${CRITICAL_LOAD:-}
stiffness=${STIFFNESS:-}
rates=${RATES:-1}
stresses=${STRESSES:-}
strain=${STRAIN:-20}
eta=${ETA:-50}
. "$root/etc/bashrc"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
mkdir -p "$work"

setUp()     # <case> <entry> <value>
{
    local c=$1
    [ -d "$c" ] && return 0
    cp -r "$root/tutorials/uniformShear/frictional" "$c"
    local p="$c/constant/suspensionProperties"
    foamDictionary -entry population/nParticles -set "$N" "$p" > /dev/null
    foamDictionary -entry population/volumeFraction -set "$phi" "$p" > /dev/null
    foamDictionary -entry population/seed -set "$seed" "$p" > /dev/null
    if [ -n "$fcl" ]; then
        foamDictionary -entry contact/type -add criticalLoadContact "$p" > /dev/null
        foamDictionary -entry contact/criticalLoad -add "$fcl" "$p" > /dev/null
    fi
    if [ -n "$stiffness" ]; then
        foamDictionary -entry contact/stiffness -set "$stiffness" "$p" > /dev/null
    fi
    foamDictionary -entry ambientFlow/shearRate -remove "$p" > /dev/null
    foamDictionary -entry "ambientFlow/$2" -add "$3" "$p" > /dev/null
    foamDictionary -entry writeInterval -set 200 "$c/system/controlDict" > /dev/null
    (cd "$c" && makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1 \
        && makeSuspension > log.makeSuspension 2>&1)
}

run()       # <case> <endTime>
{
    local c=$1
    if grep -qx End "$c/log.run" 2>/dev/null; then return 0; fi
    foamDictionary -entry endTime -set "$2" "$c/system/controlDict" > /dev/null
    foamDictionary -entry deltaT -set "$(awk -v t="$2" -v s="$strain" 'BEGIN { printf "%.6g", 0.01*t/s }')" \
        "$c/system/controlDict" > /dev/null
    [ -f "$c/log.run" ] && mv "$c/log.run" "$c/log.run.$(date +%s)"
    (cd "$c" && /usr/bin/time -v wavyShearFoam > log.run 2> "log.time.$(date +%s)")
}

for r in $rates; do
    c=$work/$tag-rate-$r
    setUp "$c" shearRate "$r"
    run "$c" "$(awk -v r="$r" -v s="$strain" 'BEGIN { printf "%.6g", s/r }')"
done
for s in $stresses; do
    c=$work/$tag-stress-$s
    setUp "$c" shearStress "$s"
    run "$c" "$(awk -v s="$strain" -v e="$eta" -v sigma="$s" 'BEGIN { printf "%.6g", s*e/sigma }')"
done
"$here/analyse.py" flowcurve "$work" "$tag"
