#!/bin/bash
#------------------------------------------------------------------------------
# The paper's headline case at its size: Table 3 NW and YW of Monti et al.
# (2021), N = 65536, every force, the paper's 4 a0 attraction range, mu_C = 1
# (tutorials/wavyShear/NW and YW with nParticles 65536), from the same packing
# (same population and seed), implicitEuler, for docs/validation.md's fig. 10.
#
#   docs/validation/table3-65536.sh [-e END] [-t THREADS] [NW|YW ...]
#
#   -e END       strain to run to (default 3); rerun with a larger END to go on
#   -t THREADS   OpenMP threads per run (default 2); the cases run in turn
#   NW YW        the cases (default both, NW first)
#
# Steps: NW at the default safety 0.2; YW at safety 0.1, as validation.md
# recommends for a non-uniform flow: its local shear rate reaches
# 1 + 20 (2 pi/Ly) = 2.4 times the mean in this box (Ly = 87.9), so the
# largest local strain per step, 2.4 x 1.3e-4, is about NW's 2.6e-4.
# Each case is run by runCase (etc/caseFunctions) under
# run/validation/table3-65536/<case>: set up once (box, mesh, packing), then
# restarted from its latest write whenever the script is run again, so the
# run can be chunked over sessions. A write every 0.05 strain in binary
# (24-25 MB), the last two kept; the rheology every 0.01 strain, the
# profiles (32 bins across y) at every write. Then
#   docs/validation/table3-65536.py    (figure and table of validation.md)
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" > /dev/null 2>&1
. "$root/etc/caseFunctions" || exit 1

end=3 threads=2
while getopts e:t: opt; do
    case $opt in
        e) end=$OPTARG ;; t) threads=$OPTARG ;;
        *) sed -n 2,24p "$0"; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
cases=${*:-"NW YW"}
runRoot=${WSF_VALIDATION_DIR:-$root/run/validation}/table3-65536

export OMP_NUM_THREADS=$threads
setup="setEntry system/controlDict writeInterval 5 \
    && setEntry system/controlDict writeFormat binary \
    && setEntry system/controlDict functions/profiles/nBins 32"
# In braces, so that bash reads the loop whole before it runs it: editing
# this file during a run of hours cannot change what the run reads next
{
status=0
for c in $cases; do
    case $c in
        NW) safety=0.2 ;;
        YW) safety=0.1 ;;
        *) echo "table3-65536.sh: unknown case '$c'" >&2; exit 2 ;;
    esac
    WSF_CASE_SETUP=$setup runCase "$runRoot/$c" "$root/tutorials/wavyShear/$c" "$end" 0.01 \
        population/nParticles=65536 integration/integrator=implicitEuler \
        integration/safety=$safety || status=1
done
exit $status
}
