#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Helpers of the case tests (tests/suspensionFoam/suspensionFoamTest.sh,
# tests/suspensionCoupledFoam/coupledTest.sh), sourced once these are set:
#   work    the test's temporary folder, a case per sub-folder
#   test    the test's name, for the messages
#   solver  the solver the bad-input tests run
#------------------------------------------------------------------------------

fail()
{
    echo "FAILED ($test): $*" >&2
    for log in "$work"/*/log.*; do
        [ -f "$log" ] && { echo "=== $log" >&2; tail -n 40 "$log" >&2; }
    done
    exit 1
}

# Set entries: setEntry <case> <file> <entry> <value>
setEntry()
{
    foamDictionary -entry "$3" -set "$4" "$work/$1/$2" > /dev/null 2>&1 \
        || fail "cannot set $3 in $2"
}

# Expect a FatalIOError before any step: expectInputError <case> <text>...
expectInputError()
{
    local c=$1
    shift
    if (cd "$work/$c" && $solver > log.$solver 2>&1); then
        fail "$solver accepted the bad input"
    fi
    local log="$work/$c/log.$solver"
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
