#!/bin/bash
#------------------------------------------------------------------------------
# The paper's headline case at its size: Table 3 NW and YW of Monti et al.
# (2021), N = 65536, every force, the paper's 4 a0 attraction range, mu_C = 1
# (tutorials/wavyShear/NW and YW with nParticles 65536), from the same packing
# (same population and seed), implicitEuler, for docs/validation.md's fig. 10.
#
#   docs/validation/table3-65536.sh [-e END] [-t THREADS] [NW|YW ...]
#   docs/validation/table3-65536.sh -k [NW|YW ...]
#
#   -e END       strain to run to (default 3); rerun with a larger END to go on
#   -t THREADS   OpenMP threads per run (default 2); the cases run in turn
#   -k           keep: pack the latest write of each case's run (the files a
#                restart reads, 11-12 MB compressed) into
#                docs/validation/table3-65536/<case>/restart.tar.xz, so that
#                the run can go on from a checkout on another machine: a run
#                that finds no run folder and such a file starts from it
#   NW YW        the cases (default both, NW first)
#
# Steps: NW at the default safety 0.2; YW at safety 0.1, as validation.md
# recommends for a non-uniform flow: its local shear rate reaches
# 1 + 20 (2 pi/Ly) = 2.4 times the mean in this box (Ly = 87.9), so the
# largest local strain per step, 2.4 x 1.3e-4, is about NW's 2.6e-4.
# Each case is run by runCase (etc/caseFunctions) under
# $WSF_VALIDATION_DIR/table3-65536/<case> (default run/validation in this
# checkout; set it to a folder outside the checkout where the checkout is
# laid anew between sessions): set up once (box, mesh, packing), then
# restarted from its latest write whenever the script is run again, so the
# run can be chunked over sessions. A write every 0.05 strain in binary
# (21-25 MB), the last two kept; the rheology every 0.01 strain, the
# profiles (32 bins across y) at every write. Then
#   docs/validation/table3-65536.py    (figure and table of validation.md)
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" > /dev/null 2>&1
. "$root/etc/caseFunctions" || exit 1

end=3 threads=2 keep=false
while getopts e:t:k opt; do
    case $opt in
        e) end=$OPTARG ;; t) threads=$OPTARG ;; k) keep=true ;;
        *) sed -n 2,33p "$0"; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
cases=${*:-"NW YW"}
runRoot=${WSF_VALIDATION_DIR:-$root/run/validation}/table3-65536
kept=$root/docs/validation/table3-65536

# keepRestart <case>: the latest write of the run and what its restart
# reads besides (set-up, dictionaries, postProcessing, logs), without the
# fields written only for viewing (positions, coordinates, S, Eulerian)
keepRestart()
{
    local dir=$runRoot/$1 latest p real
    # Not while a solver runs in it (the lock holds the script's pid, and a
    # solver outlives a killed script): a write may be half made
    real=$(cd "$dir" 2> /dev/null && pwd -P) || { echo "table3-65536.sh: no run $dir" >&2; return 1; }
    for p in /proc/[0-9]*; do
        if [ "$(readlink "$p/cwd" 2> /dev/null)" = "$real" ]; then
            echo "table3-65536.sh: process ${p#/proc/} runs in $dir;" \
                "stop it (its last write stays) before -k" >&2
            return 1
        fi
    done
    latest=$(cd "$dir" 2> /dev/null && foamListTimes -latestTime -noZero | tail -1)
    [ -n "$latest" ] && [ -f "$dir/$latest/uniform/suspensionState" ] \
        || { echo "table3-65536.sh: no complete write of $1 in $dir" >&2; return 1; }
    mkdir -p "$kept/$1"
    # setUpDone last: a pack that is unpacked part way is not taken as set up
    if (
        cd "$dir" && tar -cJf "$kept/$1/restart.tar.xz.part" constant system \
            postProcessing log.* $(ls wallSeconds 2> /dev/null) "$latest/uniform" \
            "$latest"/lagrangian/suspension/{x,d,U,omega,F,T,dUdt,dOmegadt,origId} \
            "$latest"/lagrangian/suspension/{contactId,contactXiT,contactXiR} setUpDone
    ); then
        mv "$kept/$1/restart.tar.xz.part" "$kept/$1/restart.tar.xz" \
     && echo "$dir: write $latest kept in $kept/$1/restart.tar.xz"
    else
        rm -f "$kept/$1/restart.tar.xz.part"
        return 1
    fi
}

export OMP_NUM_THREADS=$threads
setup="setEntry system/controlDict writeInterval 5 \
    && setEntry system/controlDict writeFormat binary \
    && setEntry system/controlDict functions/profiles/nBins 32"
# In braces, so that bash reads the loop whole before it runs it: editing
# this file during a run of hours cannot change what the run reads next
{
status=0
for c in $cases; do
    if $keep; then
        keepRestart "$c" || status=1
        continue
    fi
    if [ ! -e "$runRoot/$c/setUpDone" ] && [ -f "$kept/$c/restart.tar.xz" ]; then
        rm -rf "$runRoot/$c.part" && mkdir -p "$runRoot/$c.part" \
         && tar -xJf "$kept/$c/restart.tar.xz" -C "$runRoot/$c.part" \
         && rm -rf "$runRoot/$c" && mv "$runRoot/$c.part" "$runRoot/$c" \
         && echo "$runRoot/$c: from $kept/$c/restart.tar.xz" || { status=1; continue; }
    fi
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
