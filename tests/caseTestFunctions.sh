#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Helpers of the case tests (tests/suspensionFoam/suspensionFoamTest.sh,
# tests/suspensionCoupledFoam/coupledTest.sh), sourced once these are set:
#   work    the test's temporary folder, a case per sub-folder
#   test    the test's name, for the messages
#   solver  the solver the bad-input tests run (and runParallel's default)
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

# The entries of an ascii IOField $1, one per line, parentheses removed
# (a uniform list N{value} repeated N times)
listLines()
{
    awk '/^[0-9]+\{/ { n = $0; sub(/\{.*/, "", n); v = $0; sub(/^[0-9]+\{/, "", v)
                       sub(/\}.*/, "", v); for (k = 0; k < n; ++k) print v; exit }
         /^\($/ { on = 1; next } /^\)$/ { on = 0 } on' "$1" | tr -d '()'
}

# The entries of cloud field $2 in time directory $1, one per line after
# the particle's origId, sorted by it
byId()
{
    local cloud=$1/lagrangian/suspension
    paste <(listLines "$cloud/origId") <(listLines "$cloud/$2") | sort -n
}

# The data rows of a .dat file
rows()
{
    grep -v "^#" "$1"
}

# sameNumbers <a> <b> <tol>: the same lines and words (split at blanks and
# parentheses), numbers equal within tol relative to the larger (and 1e-12
# absolute, for round-off about zero); prints the first difference
sameNumbers()
{
    paste -d '\n' "$1" "$2" | awk -v tol="$3" -v na="$(wc -l < "$1")" \
        -v nb="$(wc -l < "$2")" '
        BEGIN { if (na != nb) { print na " against " nb " lines"; bad = 1; exit } }
        NR % 2 == 1 { a = $0; next }
        {
            b = $0
            gsub(/[()]/, " & ", a); gsub(/[()]/, " & ", b)
            n = split(a, x, /[ \t]+/); m = split(b, y, /[ \t]+/)
            if (n != m) { print "line " NR/2 ": " n " against " m " words"; bad = 1; exit }
            for (k = 1; k <= n; ++k) {
                if (x[k] == y[k]) continue
                num = "^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$"
                if (x[k] !~ num || y[k] !~ num) { print "line " NR/2 ": " x[k] " against " y[k]; bad = 1; exit }
                d = x[k] - y[k]; if (d < 0) d = -d
                s = (x[k] < 0 ? -x[k] : x[k]); t = (y[k] < 0 ? -y[k] : y[k])
                if (t > s) s = t
                if (d > tol*s + 1e-12) { print "line " NR/2 ": " x[k] " against " y[k]; bad = 1; exit }
            }
        }
        END { exit bad }'
}

# Decompose case $1 into $2 slabs in y and $3 in z (method simple)
decomposeDict()
{
    printf '%s\n' \
        "FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }" \
        "numberOfSubdomains $(($2*$3));" "method          simple;" \
        "coeffs          { n (1 $2 $3); }" > "$work/$1/system/decomposeParDict"
}

# The cells of the mesh of case $1 in x, y and z: $2 = "(nx ny nz)"
setBlocks()
{
    sed -i -E "s/^( *hex \([0-9 ]+\)) \([0-9 ]+\)/\1 $2/" \
        "$work/$1/system/blockMeshDict"
    grep -qF "$2" "$work/$1/system/blockMeshDict" || fail "no blocks $2"
}

# Run the OpenFOAM utility $2 (with its arguments) in case $1
inCase()
{
    local c=$1
    shift
    (cd "$work/$c" && "$@" > "log.$1.$RANDOM" 2>&1) || fail "$* in case $c"
}

# mpirun on $1 processes, oversubscribed, with this environment
mpiRun()
{
    local P=$1
    shift
    mpirun --oversubscribe --allow-run-as-root -np "$P" -x PATH \
        -x LD_LIBRARY_PATH -x WM_PROJECT_DIR -x OMP_NUM_THREADS \
        -x OMP_WAIT_POLICY "$@" -parallel
}

# Run program $3 (default: the solver) of case $1 on $2 processes, its
# log log.<program>.<P>; fails unless it succeeds
runParallel()
{
    (cd "$work/$1" && mpiRun "$2" "${3:-$solver}" > "log.${3:-$solver}.$2" 2>&1) \
        || fail "${3:-$solver} of case $1 on $2 processes"
}

# The particles (x, U, omega by id) of time $2 of cases $1 and $3 are the
# same to $4
expectSameParticles()
{
    local field
    for field in x U omega; do
        byId "$work/$1/$2" $field > "$work/$1.$2.$field"
        byId "$work/$3/$2" $field > "$work/$3.$2.$field"
        [ -s "$work/$3.$2.$field" ] || fail "no $field at $2 in $3"
        sameNumbers "$work/$1.$2.$field" "$work/$3.$2.$field" "$4" \
            || fail "$field at $2 of $1 differs from $3's"
    done
}
