#!/bin/bash
#------------------------------------------------------------------------------
# Validation runs of docs/validation.md (issue: validation against the paper).
#
#   docs/validation/run.sh [--quick] [case ...]
#
# cases: frictionless frictional shearThickening wavy dilute (default: all).
# Each point is an OpenFOAM case under run/validation/<mode>/<case>/<point>,
# copied from a tutorial with its entries changed by foamDictionary, and run
# with wavyShearFoam (implicitEuler) by runCase (etc/caseFunctions): a point
# that has reached its end time is skipped, one that has not restarts from
# its latest written time, so the script can be stopped and rerun at will.
# Then run docs/validation/analyse.py [--quick].
#
# --quick: two or three points per case and short strains (a smoke test of
# the whole chain, minutes); full: the numbers of docs/validation.md.
# Threads: OMP_NUM_THREADS (default 1 per run).
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" && . "$root/etc/caseFunctions" || exit 1

mode=full
if [ "${1:-}" = "--quick" ]; then mode=quick; shift; fi
cases=${*:-"frictionless frictional shearThickening wavy dilute"}
runRoot=${WSF_VALIDATION_DIR:-$root/run/validation}/$mode
failed=0

# point <case> <label> <tutorial> <endTime> <sampling> [entry=value ...]
point()
{
    local case=$1 label=$2 tutorial=$3 endTime=$4 sampling=$5
    shift 5
    runCase "$runRoot/$case/$label" "$root/tutorials/$tutorial" "$endTime" "$sampling" \
        integration/integrator=implicitEuler "$@"
}

# Paper Table 1 FL: N = 200, a2/a1 = 1.4, V2/V1 = 1, mu_C = 0
frictionless()
{
    local phis="0.40 0.45 0.50 0.53 0.55 0.57" deltas="0.05 0.2" end=30 dense="0.55 0.57"
    if [ $mode = quick ]; then phis="0.45 0.55"; deltas="0.05"; end=1; dense=""; fi
    local phi delta seed
    for delta in $deltas; do
        for phi in $phis; do
            for seed in 1 $(echo " $dense " | grep -q " $phi " && echo 2); do
                point frictionless "delta$delta-phi$phi-seed$seed" uniformShear/frictionless \
                    $end 0.01 population/volumeFraction=$phi population/seed=$seed \
                    lubrication/delta=$delta || failed=1
            done
        done
    done
}

# Paper Table 1 FR: N = 1000, mu_C = 1, delta_lub = 0.05. At phi = 0.54 the
# contacts of k^ = 4e5 reach overlaps of 0.09-0.11 a in steady shear (the
# stress sets them, not the step: 0.086 and 0.091 for two seeds at safety
# 0.4, 0.1 at the default 0.2), so the stopping limit maxOverlap is raised
# there from 0.1 to 0.15 (a limit on a runaway, not a model parameter;
# docs/validation.md, "phi = 0.54 and the overlap limit"). A case set up
# before keeps its entries (runCase sets them once): set it in the case's
# constant/suspensionProperties. 10 strain units per run, more where 10 left
# the error bar untrusted (correlation strains 2.4 and 2.2 over 10): 30 at
# phi = 0.40, 20 per seed at 0.54 (then 1.2 and 0.93, trusted)
frictional()
{
    local phis="0.40 0.45 0.48 0.50 0.52 0.54" end=10 dense="0.52 0.54"
    if [ $mode = quick ]; then phis="0.45"; end=0.2; dense=""; fi
    local phi seed e
    for phi in $phis; do
        e=$end
        if [ $mode = full ]; then
            case $phi in 0.40) e=30 ;; 0.54) e=20 ;; esac
        fi
        for seed in 1 $(echo " $dense " | grep -q " $phi " && echo 2); do
            point frictional "phi$phi-seed$seed" uniformShear/frictional \
                $e 0.01 population/volumeFraction=$phi population/seed=$seed \
                $([ $phi = 0.54 ] && echo integration/maxOverlap=0.15) || failed=1
        done
    done
}

# Paper Table 2 SI: N = 512, phi = 0.46, mu_C = 0.5, against gammaDot/gammaDot0,
# and the engine's own plateaux without electro-chemical forces
shearThickening()
{
    local rates="1e-5 1e-4 1e-3 1e-2 1e-1 1 10" settings="0.045:19 0.013:1" end=3
    if [ $mode = quick ]; then rates="1e-3 1"; settings="0.045:19"; end=0.1; fi
    local s rate
    for s in $settings; do
        for rate in $rates; do
            point shearThickening "lambda${s%:*}-ratio${s#*:}-rate$rate" uniformShear/shearThickening \
                $end 0.01 electroChemical/shearRateRatio=$rate \
                electroChemical/forceRatio=${s#*:} \
                electroChemical/repulsion/debyeLength=${s%:*} || failed=1
        done
    done
    local mu
    for mu in 0 0.5; do
        point shearThickening "noElectroChemical-mu$mu" uniformShear/shearThickening \
            $end 0.01 contact/friction=$mu electroChemical/repulsion/active=false \
            electroChemical/attraction/active=false || failed=1
    done
}

# Paper Table 3 NW and YW from the same initial condition (same seed). With
# N = 1024 the box (22 a0) holds 3 neighbour cut-offs only if the attraction
# is cut at 0.5 a0 rather than the paper's 4 a0 (which needs N >= 2700);
# the paper's run is tutorials/wavyShear/YW with nParticles 65536.
wavy()
{
    local N=1024 end=2
    if [ $mode = quick ]; then N=1024; end=0.02; fi
    local t
    for t in NW YW; do
        WSF_CASE_SETUP="setEntry system/controlDict functions/profiles/nBins 16" \
            point wavy "$t-N$N" wavyShear/$t $end 0.01 population/nParticles=$N \
            electroChemical/attraction/cutoffGap=0.5 || failed=1
    done
}

# Einstein's 1 + 2.5 phi: monodisperse, no contact needed, lubrication on
dilute()
{
    local phis="0.01 0.02 0.05" end=100
    if [ $mode = quick ]; then phis="0.02"; end=0.2; fi
    local phi
    for phi in $phis; do
        point dilute "phi$phi" uniformShear/frictionless $end 0.01 \
            population/type=monodisperse population/volumeFraction=$phi \
            population/sizeRatio=~remove population/volumeRatio=~remove || failed=1
    done
}

for c in $cases; do
    case $c in
        frictionless|frictional|shearThickening|wavy|dilute) $c ;;
        *) echo "run.sh: unknown case '$c'" >&2; exit 2 ;;
    esac
done
exit $failed
