#!/bin/bash
#------------------------------------------------------------------------------
# Runs of docs/speed-vs-error.md (speed against error; implicit against
# explicit integration).
#
#   docs/speed-vs-error/run.sh [--quick] [study ...]
#
# studies:
#   timeStep  the same initial condition stepped to strain T = 0.25 with
#             each integrator and safety factor (the time step is safety x
#             the stability limit); the error of the mean eta_r over the
#             window against the smallest step isolates the time
#             discretisation from the sampling noise of a chaotic flow.
#   model     steady eta_r (20 strains frictionless, 8 frictional) for the
#             model parameters eps (gap regularisation) and delta_lub.
#   meshFlow  the wavy shear of tutorials/wavyShear/small from the same
#             initial condition to strain 0.5, with U_inf analytic and with
#             U_inf sampled on meshes of 8, 16, 32, 64 cells across the box
#             (ambientFlow type meshSampled).
# Cases: Table 1 FL and FR at phi = 0.5 with N = 200.
# Points are OpenFOAM cases under run/speed-vs-error/<mode>/, run by runCase
# (etc/caseFunctions), restartable; then docs/speed-vs-error/analyse.py.
# --quick: two points per study and short windows (a smoke test).
# Threads: OMP_NUM_THREADS (default 1).
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" && . "$root/etc/caseFunctions" || exit 1

mode=full
if [ "${1:-}" = "--quick" ]; then mode=quick; shift; fi
studies=${*:-"timeStep model meshFlow"}
runRoot=${WSF_SPEED_DIR:-$root/run/speed-vs-error}/$mode
failed=0

# The two cases at phi = 0.5, N = 200
caseEntries()
{
    case $1 in
        frictionless) echo "population/volumeFraction=0.5" ;;
        frictional) echo "population/volumeFraction=0.5 population/nParticles=200" ;;
    esac
}
template()
{
    echo "$root/tutorials/uniformShear/$1"
}

timeStep()
{
    # Sampling intervals above the largest step of each case (the sub-steps
    # land on them): frictionless dt = 0.021 at safety 0.9, frictional 1.2e-3
    local window=0.25 sampling_frictionless=0.025 sampling_frictional=0.005
    local implicit="0.01 0.02 0.05 0.1 0.2 0.5 0.9" explicit="0.2 0.1" overdamped="0.2"
    if [ $mode = quick ]; then
        window=0.02; implicit="0.05 0.2"; explicit="0.2"; overdamped=""
        sampling_frictionless=0.005
    fi
    local c s sampling
    for c in frictionless frictional; do
        sampling=$(eval echo \$sampling_$c)
        for s in $implicit; do
            runCase "$runRoot/timeStep/$c/implicitEuler-safety$s" "$(template $c)" $window $sampling \
                $(caseEntries $c) integration/integrator=implicitEuler integration/safety=$s || failed=1
        done
        for s in $overdamped; do
            runCase "$runRoot/timeStep/$c/overdamped-safety$s" "$(template $c)" $window $sampling \
                $(caseEntries $c) integration/integrator=overdamped integration/safety=$s || failed=1
        done
        for s in $explicit; do
            runCase "$runRoot/timeStep/$c/velocityVerlet-safety$s" "$(template $c)" $window $sampling \
                $(caseEntries $c) integration/integrator=velocityVerlet integration/safety=$s || failed=1
        done
    done
}

model()
{
    local epsilons="1e-2 1e-3 1e-4" deltas="0.1 0.2 0.5"   # reference: eps 1e-3, delta 0.05
    local end_frictionless=20 end_frictional=8
    if [ $mode = quick ]; then
        epsilons="1e-2"; deltas="0.2"; end_frictionless=0.2; end_frictional=0.05
    fi
    local c e d end
    for c in frictionless frictional; do
        end=$(eval echo \$end_$c)
        for e in $epsilons; do
            runCase "$runRoot/model/$c/epsilon$e" "$(template $c)" $end 0.01 \
                $(caseEntries $c) integration/integrator=implicitEuler lubrication/epsilon=$e || failed=1
        done
        for d in $deltas; do
            runCase "$runRoot/model/$c/delta$d" "$(template $c)" $end 0.01 \
                $(caseEntries $c) integration/integrator=implicitEuler lubrication/delta=$d || failed=1
        done
    done
}

meshFlow()
{
    local window=0.5 cells="8 16 32 64"
    if [ $mode = quick ]; then window=0.05; cells="8"; fi
    local small=$root/tutorials/wavyShear/small n
    runCase "$runRoot/meshFlow/analytic" "$small" $window 0.01 \
        integration/integrator=implicitEuler lubrication/epsilon=1e-2 || failed=1
    for n in $cells; do
        WSF_CASE_SETUP="foamDictionary -entry ambientFlow -set \
            '{ type meshSampled; flow { type wavyShear; shearRate 1; amplitude 3.2; periods 1; } }' \
            constant/suspensionProperties > /dev/null \
         && sed -i 's/(4 8 4)/($n $n $n)/' system/blockMeshDict \
         && blockMesh > log.blockMesh 2>&1" \
        runCase "$runRoot/meshFlow/cells$n" "$small" $window 0.01 \
            integration/integrator=implicitEuler lubrication/epsilon=1e-2 || failed=1
    done
}

for s in $studies; do
    case $s in
        timeStep|model|meshFlow) $s ;;
        *) echo "run.sh: unknown study '$s'" >&2; exit 2 ;;
    esac
done
exit $failed
