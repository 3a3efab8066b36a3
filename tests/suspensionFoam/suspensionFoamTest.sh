#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Case tests of wavyShearFoam and makeSuspension on the tiny case next to this
# script (N = 100, phi = 0.3). Each test runs in its own temporary copy.
#
#   suspensionFoamTest.sh <binDir> <WM_PROJECT_DIR> <test>
#
# Tests:
#   run         a short run: exit 0, rheology.dat header and rows, N entries
#               in every cloud field, fields and profiles at the write times
#   restart     a run restarted from a written time matches the
#               uninterrupted run bitwise (2 threads, contacts with history)
#   failure     a blown-up run writes its last good state and exits non-zero
#   bad*        one bad input each: a FatalIOError naming the file and the
#               entry, before any time step
#------------------------------------------------------------------------------
set -euo pipefail

binDir=$1
export WM_PROJECT_DIR=$2
test=$3
export PATH="$binDir:$PATH"
export OMP_NUM_THREADS=1
export OMP_WAIT_POLICY=PASSIVE

source=$(cd "$(dirname "$0")/tiny" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/suspensionFoamTest.XXXXXX")
trap 'rm -rf "$work"' EXIT

fail()
{
    echo "FAILED ($test): $*" >&2
    for log in "$work"/*/log.*; do
        [ -f "$log" ] && { echo "=== $log" >&2; tail -n 40 "$log" >&2; }
    done
    exit 1
}

# Mesh case $1 on the box of its population
mesh()
{
    (
        cd "$work/$1"
        makeSuspension -boxOnly > log.makeBox 2>&1
        blockMesh > log.blockMesh 2>&1
    ) || fail "meshing case $1"
}

# Copy the tiny case to $work/$1, mesh it
newCase()
{
    cp -r "$source" "$work/$1"
    mesh "$1"
}

# Set entries: setEntry <case> <file> <entry> <value>
setEntry()
{
    foamDictionary -entry "$3" -set "$4" "$work/$1/$2" > /dev/null 2>&1 \
        || fail "cannot set $3 in $2"
}

# Number of entries of an ascii IOField: the line before the first '(',
# or N of a uniform list N{value}
entries()
{
    awk '/^[0-9]+\{/ { sub(/\{.*/, ""); print; exit }
         /^\($/ { print prev; exit }
         { prev = $0 }' "$1"
}

# Expect a FatalIOError before any step: expectInputError <case> <text>...
expectInputError()
{
    local c=$1
    shift
    if (cd "$work/$c" && wavyShearFoam > log.wavyShearFoam 2>&1); then
        fail "wavyShearFoam accepted the bad input"
    fi
    local log="$work/$c/log.wavyShearFoam"
    grep -q "FOAM FATAL IO ERROR" "$log" || fail "no FatalIOError"
    for text in "$@"; do
        grep -qF -- "$text" "$log" || fail "the error does not name '$text'"
    done
    grep -q "^strain " "$log" && fail "time steps were taken"
    [ ! -e "$work/$c/postProcessing/rheology" ] || fail "rheology.dat written"
    [ "$(cd "$work/$c" && foamListTimes -noZero 2>/dev/null)" = "" ] \
        || fail "a time directory was written"
    return 0
}

properties=constant/suspensionProperties
N=100

case "$test" in

run)
    newCase c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "wavyShearFoam"

    dat="$work/c/postProcessing/rheology/0/rheology.dat"
    [ -f "$dat" ] || fail "no rheology.dat"
    grep -q "^# Time" "$dat" || fail "rheology.dat: no column header"
    for column in strain etaR N1 N2 Pi etaN etaR_stokes etaR_lubrication \
        etaR_contact etaR_repulsion etaR_attraction nContacts maxOverlap \
        steps deltaT
    do
        grep "^# Time" "$dat" | grep -qw "$column" \
            || fail "rheology.dat: no column $column"
    done
    rows=$(grep -vc "^#" "$dat")
    [ "$rows" -eq 4 ] || fail "rheology.dat: $rows rows, expected 4"
    awk '!/^#/ && NF != 16 { exit 1 }' "$dat" \
        || fail "rheology.dat: rows without 16 columns"

    for t in 0 0.002 0.004; do
        cloud="$work/c/$t/lagrangian/suspension"
        for f in positions x d U omega F T S origId; do
            [ -f "$cloud/$f" ] || fail "$t: no $f"
            n=$(entries "$cloud/$f")
            [ "$n" = "$N" ] || fail "$t/$f: $n entries, expected $N"
        done
        for f in Uinf gradUinf shearRateInf particleStress alpha; do
            [ -f "$work/c/$t/$f" ] || fail "$t: no field $f"
        done
        grep -q "nParticles *$N;" "$work/c/$t/uniform/suspensionState" \
            || fail "$t: suspensionState"
        [ -f "$work/c/postProcessing/profiles/$t/profiles.dat" ] \
            || fail "$t: no profiles.dat"
    done
    ;;

restart)
    # Soft, dense: contacts with history form within the first write interval
    newCase a
    setEntry a $properties population/volumeFraction 0.45
    setEntry a $properties StokesNumber 1e-2
    setEntry a $properties contact/stiffness 1e4
    setEntry a $properties lubrication/epsilon 0.05
    setEntry a system/controlDict endTime 0.1
    setEntry a system/controlDict deltaT 0.01
    setEntry a system/controlDict writeInterval 5
    mesh a
    export OMP_NUM_THREADS=2

    (cd "$work/a" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "uninterrupted run"
    contacts=$(awk '/nContacts/ { print $2 + 0 }' \
        "$work/a/0.05/uniform/suspensionState")
    [ "$contacts" -gt 0 ] || fail "no contact history at 0.05"

    mkdir "$work/b"
    cp -r "$work/a/constant" "$work/a/system" "$work/a/0" "$work/a/0.05" \
        "$work/b"
    (cd "$work/b" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "restarted run"
    grep -q "stored suspension" "$work/b/log.wavyShearFoam" \
        || fail "the restart did not read the stored suspension"

    for f in lagrangian/suspension/* lagrangian/suspensionContacts/* \
        uniform/suspensionState particleStress alpha
    do
        for path in "$work"/a/0.1/$f; do
            rel=${path#"$work"/a/}
            cmp -s "$path" "$work/b/$rel" || fail "$rel differs"
        done
    done
    # The rheology rows after the restart time, too
    diff <(awk '!/^#/ && $1 > 0.05' \
            "$work/a/postProcessing/rheology/0/rheology.dat") \
         <(awk '!/^#/' "$work/b/postProcessing/rheology/0.05/rheology.dat") \
        > /dev/null || fail "rheology.dat rows differ"
    ;;

failure)
    # Contacts far too soft for the shear: the overlap runs away
    newCase c
    setEntry c $properties population/volumeFraction 0.45
    setEntry c $properties StokesNumber 1e-2
    setEntry c $properties contact/stiffness 30
    setEntry c $properties lubrication/epsilon 0.05
    setEntry c system/controlDict endTime 0.2
    setEntry c system/controlDict deltaT 0.01
    mesh c
    if (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1); then
        fail "the run did not stop"
    fi
    log="$work/c/log.wavyShearFoam"
    grep -q "FOAM FATAL ERROR" "$log" || fail "no FatalError"
    grep -q "runaway overlap" "$log" || fail "no diagnostic"
    grep -q "last good state" "$log" || fail "no last good state reported"
    last=$(cd "$work/c" && foamListTimes -latestTime 2>/dev/null | tail -1)
    [ -f "$work/c/$last/uniform/time" ] || fail "no uniform/time at $last"
    n=$(entries "$work/c/$last/lagrangian/suspension/x")
    [ "$n" = "$N" ] || fail "last good cloud at $last: $n entries"

    # The last good state continues with stiffer contacts
    mv "$log" "$log.failed"
    setEntry c $properties contact/stiffness 1e4
    setEntry c system/controlDict endTime 0.2
    (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "no restart from the last good state $last"
    grep -q "stored suspension of .*/$last/" "$log" \
        || fail "the restart did not start from $last"
    ;;

badVolumeFraction)
    newCase c
    setEntry c $properties population/volumeFraction 0.8
    expectInputError c suspensionProperties volumeFraction "(0, 0.74)"
    ;;

badRadius)
    newCase c
    setEntry c $properties population/radius -1
    expectInputError c suspensionProperties radius
    ;;

missingEntry)
    newCase c
    foamDictionary -entry contact/friction -remove "$work/c/$properties" \
        > /dev/null 2>&1
    expectInputError c suspensionProperties friction
    ;;

misspeltEntry)
    newCase c
    foamDictionary -entry contact/rollingFriction -remove \
        "$work/c/$properties" > /dev/null 2>&1
    foamDictionary -entry contact/rolingFriction -add 1 \
        "$work/c/$properties" > /dev/null 2>&1
    expectInputError c suspensionProperties rolingFriction
    ;;

badStencil)
    newCase c
    setEntry c $properties integration/stencil quarter
    expectInputError c suspensionProperties quarter
    ;;

badDeltaT)
    newCase c
    setEntry c $properties integration/deltaT fast
    expectInputError c suspensionProperties deltaT
    ;;

badShearRate)
    newCase c
    setEntry c $properties ambientFlow/shearRate 2
    expectInputError c suspensionProperties "shear rate"
    ;;

smallBox)
    # 3 neighbour cut-offs do not fit into the box of 30 spheres
    newCase c
    setEntry c $properties population/nParticles 30
    mesh c
    expectInputError c suspensionProperties "neighbour cut-offs"
    ;;

meshMismatch)
    newCase c
    setEntry c constant/particleBox Lx 12
    (cd "$work/c" && blockMesh > log.blockMesh 2>&1) || fail "blockMesh"
    expectInputError c suspensionProperties "mesh bounds"
    ;;

truncatedCloud)
    newCase c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    x="$work/c/0/lagrangian/suspension/x"
    head -n 60 "$x" > "$x.tmp" && mv "$x.tmp" "$x"
    expectInputError c "0/lagrangian/suspension/x"
    ;;

inconsistentCloud)
    # d holds one entry less than the state gives
    newCase c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    d="$work/c/0/lagrangian/suspension/d"
    awk -v n=$N '
        $0 == n && !done { print n - 1; skip = 1; next }
        skip == 1 && $0 == "(" { print; skip = 2; next }
        skip == 2 { skip = 0; done = 1; next }
        { print }' "$d" > "$d.tmp" && mv "$d.tmp" "$d"
    expectInputError c "0/lagrangian/suspension/d" "holds 99 entries"
    ;;

*)
    echo "unknown test $test" >&2
    exit 2
    ;;
esac

echo "PASSED ($test)"

#------------------------------------------------------------------------------
