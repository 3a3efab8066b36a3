#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Amplitude sweeps of oscillatory shear (docs/rheometry.md): Table 1 at
# phi = 0.5 from the tutorial tutorials/rheometry/oscillatory, at one
# frequency, for a list of strain amplitudes.
#
#   docs/rheometry/amplitude.sh [workDir]      (default: /tmp/amplitude)
#
# FRICTION (0: FL; 1: FR), N (1000), OMEGA (1), PERIODS (8) per run,
# DISCARD (2) start-up cycles, AMPLITUDES ("0.02 0.1 0.5 1 2 5"), TAG (FL) a
# suffix of the tables (amplitude-$TAG.csv). Outer steps of T/100, a state
# every period (a run stopped part-way continues from it when the script is
# run again; a run whose log ends with End is not run again). One thread,
# the cases one after the other; then docs/rheometry/analyse.py amplitude
# writes amplitude-$TAG.csv and amplitude.png beside this script.
#------------------------------------------------------------------------------
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${1:-/tmp/amplitude}
friction=${FRICTION:-0}
N=${N:-1000}
omega=${OMEGA:-1}
periods=${PERIODS:-8}
discard=${DISCARD:-2}
amplitudes=${AMPLITUDES:-0.02 0.1 0.5 1 2 5}
tag=${TAG:-FL}
. "$root/etc/bashrc"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
mkdir -p "$work"

for g0 in $amplitudes; do
    c=$work/$tag-$g0
    if [ ! -d "$c" ]; then
        cp -r "$root/tutorials/rheometry/oscillatory" "$c"
        T=$(awk -v w="$omega" 'BEGIN { printf "%.15g", 2*3.14159265358979323846/w }')
        foamDictionary -entry population/nParticles -set "$N" "$c/constant/suspensionProperties" > /dev/null
        foamDictionary -entry contact/friction -set "$friction" "$c/constant/suspensionProperties" > /dev/null
        foamDictionary -entry ambientFlow/shearRate -set \
            "{ type oscillatory; strainAmplitude $g0; omega $omega; }" \
            "$c/constant/suspensionProperties" > /dev/null
        foamDictionary -entry deltaT -set "$(awk -v T="$T" 'BEGIN { printf "%.15g", T/100 }')" "$c/system/controlDict" > /dev/null
        foamDictionary -entry endTime -set "$(awk -v T="$T" -v n="$periods" 'BEGIN { printf "%.15g", n*T }')" "$c/system/controlDict" > /dev/null
        foamDictionary -entry writeInterval -set 100 "$c/system/controlDict" > /dev/null
        foamDictionary -entry functions/oscillation/discardCycles -set "$discard" "$c/system/controlDict" > /dev/null
        (cd "$c" && makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1 \
            && makeSuspension > log.makeSuspension 2>&1)
    fi
    if grep -qx End "$c/log.run" 2>/dev/null; then continue; fi
    [ -f "$c/log.run" ] && mv "$c/log.run" "$c/log.run.$(date +%s)"
    (cd "$c" && /usr/bin/time -v wavyShearFoam > log.run 2> log.time)
done
"$here/analyse.py" amplitude "$work" "$tag"
