#!/bin/bash
#------------------------------------------------------------------------------
# Does the summaries' error bar match the scatter between independent runs?
# Table 1 FL at one phi and delta_lub, NSEEDS packings (seeds 1..NSEEDS), each
# run STRAIN units with implicitEuler; then seeds.py compares the standard
# deviation of the seeds' steady eta_r with their stated standard errors.
#
#   docs/validation/seeds.sh [phi] [delta] [nSeeds] [strain]
#
# Cases under run/validation/seeds/, restartable (etc/caseFunctions), two at
# a time, one thread each.
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" && . "$root/etc/caseFunctions" || exit 1

phi=${1:-0.50} delta=${2:-0.05} nSeeds=${3:-8} strain=${4:-30}
runRoot=${WSF_VALIDATION_DIR:-$root/run/validation}/seeds

one()
{
    runCase "$runRoot/delta$delta-phi$phi-seed$1" \
        "$root/tutorials/uniformShear/frictionless" "$strain" 0.01 \
        integration/integrator=implicitEuler population/volumeFraction="$phi" \
        population/seed="$1" lubrication/delta="$delta"
}

failed=0
seed=1
while [ $seed -le "$nSeeds" ]; do
    one $seed & a=$!
    b=
    if [ $((seed + 1)) -le "$nSeeds" ]; then one $((seed + 1)) & b=$!; fi
    wait $a || failed=1
    [ -n "$b" ] && { wait $b || failed=1; }
    seed=$((seed + 2))
done
/usr/bin/python3 "$root/docs/validation/seeds.py" "$runRoot" || failed=1
exit $failed
