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
#               (the function objects of tiny/system/controlDict)
#   referenceOutput
#               rheology.dat, profiles.dat and the fields of the function
#               objects are, byte for byte, those the solver wrote itself
#               before the function objects (reference/, see there); built
#               for another instruction set than reference/'s (x86-64,
#               WSF_ARCH_FLAGS empty), the same text with every number
#               within 1e-7 relative: FMA and wider vectors round
#               otherwise, and the 22548 steps of the run amplify that to
#               4e-10 with AVX2 and FMA (to more with wider vectors);
#               an output error of the function objects is of order 1
#   functionObjectsOff
#               without function objects: the state is written, the log
#               has the progress (with CPU seconds) and the peak memory, no
#               rheology.dat, profiles or fields
#   functionObjectEntries
#               the entries of the function objects: contributions, fields,
#               nBins, writeInterval, writeAtStart
#   userFunctionObject
#               a function object of the test's own (userFunctionObject/,
#               library suspensionTestFunctionObjects) finds the cloud by
#               name and writes the particle count and strain of each step
#   outputEntry the output entries of earlier versions in
#               suspensionProperties are an error naming the function objects
#   restart     a run restarted from a written time matches the
#               uninterrupted run bitwise (2 threads, contacts with history),
#               and so does its steady-state summary (rheologySummary.dat)
#   stopAtPrecision
#               the run ends at the first write time at which etaR is
#               trusted within the precision, writing its state
#   badPrecision
#               a precision outside (0, 1) is a FatalIOError naming it
#   implicitRun the implicitEuler and overdamped integrators: contacts set
#               the step, CG statistics in the log and in rheology.dat
#   implicitRestart
#               restart as above with implicitEuler and overdamped and
#               adaptive steps (maxDisplacement): the warm start and the
#               step bound come from the stored velocities and their rates
#               (dUdt, dOmegadt); a cloud without the rates restarts, not
#               bitwise
#   dimensionalInput
#               tiny/ written in SI units (units dimensional) gives the same
#               reduced parameters and the same first rheology.dat row
#   failure     a blown-up run writes its last good state (the state the
#               run writes when it stops at that time, particle by
#               particle) and exits non-zero, as does an implicit run whose
#               velocity solve fails; the state continues
#   criticalLoadRun, criticalLoadDimensional
#               contact type criticalLoadContact: read (in reduced and in SI
#               units), reported and run
#   bad*, dimensionalConflict, missingRadiusFile, emptyRadiusFile
#               one bad input each: a FatalIOError naming the file and the
#               entry, before any time step
#   smallBox    the box-rule error names the smallest N, which packs, while
#               N - 1 is refused by the same rule
#   trimodalPopulation
#               a discrete population (a = 1, 1.5, 2 at equal volumes)
#               packs to phi = 0.55; d holds the three radii in the
#               requested volume fractions; the log reports them
#   radiusFile  population type file: the radii of d are those of the file
#   killRestart 30 kills (-9) of a frictional run that writes every outer
#               step, half at a random moment, half in the middle of a
#               write call (faultInjection/writeFaults.C: a torn write,
#               then SIGKILL), each followed by a restart: every restart
#               starts from a complete time (an incomplete one set aside),
#               and the finished run's times are bitwise the uninterrupted
#               run's
#   incompleteTime
#               a latest time truncated by hand, one without its state and
#               one with only uniform/time: the restart sets them aside
#               with a log line and starts from the latest complete time;
#               startFrom startTime naming an incomplete time is an error
#               naming the latest complete one
#   failedWrite a write that fails (a file size limit, ulimit -f: what a
#               full disk does to a write) stops the run with an error
#               naming the file; the earlier times are intact, the failed
#               one has no state and is set aside by the restart
#   badControls deltaT <= 0, an endTime before the start time, a number
#               out of range (1e999) in controlDict or suspensionProperties,
#               an unknown integration/threads: FatalIOErrors naming the
#               file and the entry
#   oversizedCase
#               a population too large for the machine's memory is refused
#               by makeSuspension -boxOnly, makeSuspension and the solver
#               before any packing, with the estimate and the limit
#   nonFiniteState
#               a stored state with a NaN velocity is a FatalIOError naming
#               the file; a run that blows up under OpenFOAM's floating-
#               point trap stops with the cause and its last good state
#   legacyContacts
#               a time whose contact history is in the folder of earlier
#               versions (lagrangian/suspensionContacts, pairs either way
#               round) restarts bitwise
#   parallelRun a packing decomposed (decomposePar) and run on
#               2 and 2x2 processes (mpirun, oversubscribed), then
#               reconstructed: the particles, the contact count, the
#               rheology, profiles and alpha of each write time are the
#               serial run's to 1e-9 (velocityVerlet and implicitEuler)
#   parallelRestart
#               decompose, run on 2 processes, reconstruct, decompose for 3,
#               run, reconstruct, run serially: the last time (particles and
#               contact history) and the rheology rows are the uninterrupted
#               serial run's to 1e-9; the same chain at writePrecision 10
#               warns that decomposePar and reconstructPar rounded the state
#   parallelSteadyState
#               over 8 strain units, the steady etaR of 3 packings on 2
#               processes is that of the same 3 serially within the error
#               bars (their scatter), and not bitwise
#   parallelIncompleteTime
#               the latest time incomplete on one processor is set aside on
#               every one, and the run continues from the time before
#   parallelRepeat
#               the same decomposed run twice, the second restarted from
#               the processors' middle time: bitwise the same files
#   parallelFailure
#               an overlap running away on one process stops every process
#               (no hang) with the last good state written and complete on
#               each, and the run continues from it
#   parallelPacking
#               makeSuspension -parallel packs the decomposed case: the run
#               is the one from the serial packing decomposed; into a time
#               whose uniform decomposePar linked to the case's, each
#               process writes a state of its own
#   parallelMeshSampled
#               a flow known on the mesh only (meshSampled: the wavy shear
#               sampled at the cells) on 2 processes gives the serial
#               particles, rheology and profiles to 1e-9: each processor
#               knows its own cells
#   parallelInput
#               a decomposeParDict the slabs cannot follow (method, n) or a
#               mesh they do not fit is a FatalIOError naming the file and
#               the entry
#------------------------------------------------------------------------------
set -euo pipefail

binDir=$1
export WM_PROJECT_DIR=$2
test=$3
export PATH="$binDir:$PATH"
# wmake-built programs find the libraries next to them ($FOAM_USER_LIBBIN),
# and the test's own function-object library
export LD_LIBRARY_PATH="$binDir/../lib${WSF_TEST_FO_LIB_DIR:+:$WSF_TEST_FO_LIB_DIR}${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OMP_NUM_THREADS=1
export OMP_WAIT_POLICY=PASSIVE

source=$(cd "$(dirname "$0")/tiny" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/suspensionFoamTest.XXXXXX")
[ -n "${WSF_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
solver=wavyShearFoam
. "$(dirname "$0")/../caseTestFunctions.sh"

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

# The number of columns of a '# Time ...' header of a function object's
# .dat file, and the column (from 1, as awk's $k) of the name $2 in it
columns()
{
    grep -m1 "^# Time" "$1" | awk '{ print NF - 1 }'
}
column()
{
    grep -m1 "^# Time" "$1" \
        | awk -v name="$2" '{ for (k = 2; k <= NF; ++k) if ($k == name) print k - 1 }'
}
# The rows of the .dat file $1 in the columns, by name, of the '# Time'
# header of $2 (fails if $1 lacks one of them)
selectedColumns()
{
    awk -v header="$(grep -m1 "^# Time" "$2")" '
        /^# Time/ {
            for (k = 2; k <= NF; ++k) col[$k] = k - 1
            m = split(header, want)
            for (j = 2; j <= m; ++j) if (!(want[j] in col)) exit 2
            next
        }
        /^#/ { next }
        {
            line = $col[want[2]]
            for (j = 3; j <= m; ++j) line = line " " $col[want[j]]
            print line
        }' "$1"
}

# Whether every column of the .dat file $2 missing from the '# Time' header
# of $1 is an etaR_ column (a stress contribution) that is zero in every row
newColumnsAreZero()
{
    awk -v header="$(grep -m1 "^# Time" "$1")" '
        /^# Time/ {
            m = split(header, want)
            for (j = 2; j <= m; ++j) known[want[j]] = 1
            for (k = 2; k <= NF; ++k) {
                if ($k in known) continue
                if ($k !~ /^etaR_/) exit 1
                extra[k - 1] = 1
            }
            next
        }
        /^#/ { next }
        { for (k in extra) if ($k + 0 != 0) exit 1 }' "$2"
}

# Number of entries of an ascii IOField: the line before the first '(',
# or N of a uniform list N{value}
entries()
{
    awk '/^[0-9]+\{/ { sub(/\{.*/, ""); print; exit }
         /^\($/ { print prev; exit }
         { prev = $0 }' "$1"
}

properties=constant/suspensionProperties
control=system/controlDict
N=100

# Run case $1 to its end time: runCase <case> [what]
runCase()
{
    (cd "$work/$1" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "wavyShearFoam ${2:-$1}"
}

# The elements of a list-of-lists cloud field $1 as the solver writes it
# (ascii, compact: the offsets of the lists, then their elements), one per
# line after the index of its particle; $2 numbers per element
compactEntries()
{
    sed '1,/^\/\/ \* \* \*/d; /^\/\//d' "$1" \
  | sed -E 's/([0-9]+)\{([^}]*)\}/\1 uniform \2/g' | tr '()' '  ' \
  | awk -v w="$2" '{ for (k = 1; k <= NF; ++k) t[++n] = $k }
        END {
            m = t[1]; i = 2
            if (t[2] == "uniform") { for (p = 0; p < m; ++p) o[p] = t[3]; i = 4 }
            else { for (p = 0; p < m; ++p) o[p] = t[i++] }
            ++i                                 # the number of elements
            for (p = 0; p + 1 < m; ++p)
                for (e = o[p]; e < o[p + 1]; ++e) {
                    printf "%d", p
                    for (k = 0; k < w; ++k) printf " %s", t[i + e*w + k]
                    printf "\n"
                }
        }'
}

# The contact history in time directory $1, one contact per line: the two
# origIds, smaller first (the particle that carries it), and the stretches
# xiT, xiR oriented that way, sorted by the ids
byContact()
{
    local c=$1/lagrangian/suspension
    paste -d ' ' <(compactEntries "$c/contactId" 1) \
        <(compactEntries "$c/contactXiT" 3 | cut -d ' ' -f 2-) \
        <(compactEntries "$c/contactXiR" 3 | cut -d ' ' -f 2-) \
  | awk 'NR == FNR { id[NR - 1] = $1; next }
         { printf "%s %s", id[$1], $2; for (k = 3; k <= 8; ++k) printf " %.17g", $k; printf "\n" }' \
        <(listLines "$c/origId") - \
  | sort -k1,1n -k2,2n
}

# Replace the population of case $1 by the entries $2 (dictionary text)
setPopulation()
{
    local f="$work/$1/$properties"
    foamDictionary -entry population -remove "$f" > /dev/null 2>&1 \
        || fail "cannot remove the population"
    printf 'population\n{\n%s\n}\n' "$2" >> "$f"
}

# A trimodal population (a = 1, 1.5, 2 at equal volumes) with fractions $2
# of kind $3 (volumeFractions or numberFractions) for case $1
trimodal()
{
    setPopulation "$1" "type discrete; nParticles 300; volumeFraction 0.55;
seed 1; radii (1 1.5 2); $3 $2;"
}

# A population of the radii of file constant/radii of case $1, holding $2
radiusFile()
{
    setPopulation "$1" 'type file; file "<constant>/radii";
volumeFraction 0.3; seed 1;'
    printf '%b' "$2" > "$work/$1/constant/radii"
}

# The values of the ascii list field $1, one per line
values()
{
    awk '/^\(/ { inside = 1; next } /^\)/ { inside = 0 } inside' "$1"
}

# The rheology rows (but the processes' pair slots) of the .dat files $1
# and $2 are the same to $3
expectSameRheology()
{
    local cols="# Time strain sigma etaR N1 N2 Pi etaR_lubrication etaR_contact nContacts maxOverlap steps uFluct2"
    selectedColumns "$1" <(echo "$cols") > "$work/rows.a" || fail "columns of $1"
    selectedColumns "$2" <(echo "$cols") > "$work/rows.b" || fail "columns of $2"
    [ -s "$work/rows.a" ] || fail "no rows in $1"
    sameNumbers "$work/rows.a" "$work/rows.b" "$3" || fail "$1 differs from $2"
}

# Soft, dense: contacts with history form within the first write interval
# of a run to 0.1 written every 0.05
softDenseCase()
{
    newCase "$1"
    setEntry "$1" $properties population/volumeFraction 0.45
    setEntry "$1" $properties StokesNumber 1e-2
    setEntry "$1" $properties contact/stiffness 1e4
    setEntry "$1" $properties lubrication/epsilon 0.05
    setEntry "$1" system/controlDict endTime 0.1
    setEntry "$1" system/controlDict deltaT 0.01
    setEntry "$1" system/controlDict writeInterval 5
    mesh "$1"
}

# Contacts far too soft for the shear: the overlap runs away before 0.2
runawayCase()
{
    softDenseCase "$1"
    setEntry "$1" $properties contact/stiffness 30
    setEntry "$1" system/controlDict endTime 0.2
    setEntry "$1" system/controlDict writeInterval 2
}

# Run case $1 to 0.1 and a copy of it up to 0.05, $1.restarted, from 0.05
# (2 threads): the state at 0.1 and the rheology rows after 0.05 must be the
# same bitwise
expectExactRestart()
{
    local a=$work/$1 b=$work/$1.restarted
    export OMP_NUM_THREADS=2
    (cd "$a" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "uninterrupted run $1"
    contacts=$(awk '$1 == "nContacts" { print $2 + 0 }' \
        "$a/0.05/uniform/suspensionState")
    [ "$contacts" -gt 0 ] || fail "$1: no contact history at 0.05"

    mkdir "$b"
    cp -r "$a/constant" "$a/system" "$a/0" "$a/0.05" "$b"
    # what a run stopped at 0.05 had written of the rheology
    mkdir -p "$b/postProcessing/rheology/0"
    awk '/^#/ || $1 <= 0.05' "$a/postProcessing/rheology/0/rheology.dat" \
        > "$b/postProcessing/rheology/0/rheology.dat"
    (cd "$b" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "restarted run $1"
    grep -q "stored suspension" "$b/log.wavyShearFoam" \
        || fail "$1: the restart did not read the stored suspension"

    for f in lagrangian/suspension/* uniform/suspensionState particleStress alpha
    do
        for path in "$a"/0.1/$f; do
            rel=${path#"$a"/}
            cmp -s "$path" "$b/$rel" || fail "$1: $rel differs"
        done
    done
    # The rheology rows after the restart time, too
    diff <(awk '!/^#/ && $1 > 0.05' \
            "$a/postProcessing/rheology/0/rheology.dat") \
         <(awk '!/^#/' "$b/postProcessing/rheology/0.05/rheology.dat") \
        > /dev/null || fail "$1: rheology.dat rows differ"
    # and the steady-state summary covers the whole history: the same (a
    # rate that changes, $2 = programmed, has none)
    summary=postProcessing/rheology/0/rheologySummary.dat
    if [ "${2:-}" = programmed ]; then
        [ ! -e "$a/$summary" ] || fail "$1: a summary of a changing rate"
        return 0
    fi
    grep -q "from 10 rows" "$a/$summary" || fail "$1: summary not of 10 rows"
    cmp "$a/$summary" "$b/postProcessing/rheology/0.05/rheologySummary.dat" \
        >&2 || fail "$1: the restarted run's summary differs"
}

# Case $1 with Stokes drag alone (no lubrication, contact or
# electro-chemical forces), overdamped; spheres may pass through each other
dragOnlyCase()
{
    newCase "$1"
    for model in lubrication contact electroChemical/repulsion \
        electroChemical/attraction
    do
        setEntry "$1" $properties $model/active false
    done
    setEntry "$1" $properties integration/integrator overdamped
    setEntry "$1" $properties integration/maxOverlap 3
}

# The volume fraction of the packed radii of case $1 (0/lagrangian d) in
# its box
packedFraction()
{
    listLines "$work/$1/0/lagrangian/suspension/d" \
        | awk -v L="$(foamDictionary -entry box -value "$work/$1/0/uniform/suspensionState")" \
            '{ v += 3.14159265358979*$1*$1*$1/6 }
             END { gsub(/[()]/, "", L); split(L, b, " "); print v/(b[1]*b[2]*b[3]) }'
}

# The oscillatory shear rate of strain amplitude $2 and frequency $3 in
# case $1
setOscillation()
{
    foamDictionary -entry ambientFlow/shearRate -set \
        "{ type oscillatory; strainAmplitude $2; omega $3; }" \
        "$work/$1/$properties" > /dev/null 2>&1 || fail "cannot set shearRate"
}

# Rewrite the groups of case $1 in SI units (units dimensional) for
# a0 = 1 um, eta0 = 1 mPa s, gammaDot = 1000/s: the same reduced parameters
toDimensional()
{
    local f="$work/$1/$properties"
    for entry in StokesNumber lubrication/delta contact/stiffness \
        contact/stiffnessRatio contact/damping electroChemical/shearRateRatio \
        electroChemical/forceRatio electroChemical/repulsion/debyeLength
    do
        foamDictionary -entry $entry -remove "$f" > /dev/null 2>&1 \
            || fail "cannot remove $entry"
    done
    setEntry "$1" $properties population/radius 1e-6
    # Appended as text: foamDictionary would round to 6 digits
    cat >> "$f" <<'EOF'
units           dimensional;
dimensional
{
    a0              1e-6;                   // m
    eta0            1e-3;                   // Pa s
    gammaDot        1e3;                    // 1/s
    rho             1e3;                    // kg/m3: St = 1e-3
    deltaLub        5e-8;                   // m: 0.05 a0
    kn              0.4;                    // N/m: k_hat = 4e5
    kt              0.1142856;              // N/m: kt/kn = 0.285714
    gammaN          4e-11;                  // kg/s: gammaN gammaDot/kn = 1e-7
    FER             1e-12;                  // N: gammaDot/gammaDot0 = 1
    hamaker         6.315789473684211e-23;  // J: F^R/F^A = 19
    debyeLength     2e-8;                   // m: 0.02 a0
}
EOF
}

# A state made by hand from the time directory $1 (its files edited): the
# digests of the files removed from its state
handMade()
{
    foamDictionary -entry files -remove "$1/uniform/suspensionState" \
        > /dev/null 2>&1 || fail "cannot remove the digests of $1"
}

# The engine parameters of the start-up report of log $1
reducedReport()
{
    sed -n '/^Suspension (reduced units/,/^    integration/p' "$1"
}

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
    for column in strain shearRate sigma etaR N1 N2 Pi etaN etaR_stokes \
        etaR_lubrication etaR_contact etaR_repulsion etaR_attraction \
        nContacts maxOverlap steps deltaT uFluct2 pairSlots
    do
        grep "^# Time" "$dat" | grep -qw "$column" \
            || fail "rheology.dat: no column $column"
    done
    rows=$(grep -vc "^#" "$dat")
    [ "$rows" -eq 4 ] || fail "rheology.dat: $rows rows, expected 4"
    # every row has the header's columns; the rate is the constant 1, the
    # stress is etaR at that rate, the list has slots
    awk -v n="$(columns "$dat")" -v r="$(column "$dat" shearRate)" \
        -v s="$(column "$dat" sigma)" -v e="$(column "$dat" etaR)" \
        -v u="$(column "$dat" uFluct2)" -v p="$(column "$dat" pairSlots)" \
        '!/^#/ && (NF != n || $r != 1 || $s != $e || $u < 0 || $p < 1) { exit 1 }' \
        "$dat" || fail "rheology.dat: rows not of the header's columns and values"

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
        # OpenFOAM numbers new particles from this count: N at every write
        grep -q "particleCount *$N;" \
            "$work/c/$t/uniform/lagrangian/suspension/cloudProperties" \
            || fail "$t: cloudProperties particleCount is not $N"
        [ -f "$work/c/postProcessing/profiles/$t/profiles.dat" ] \
            || fail "$t: no profiles.dat"
    done
    ;;

restart)
    softDenseCase a
    expectExactRestart a
    ;;

programmedRestart)
    # Under an oscillating rate (two reversals to 0.1) the strain, the
    # rate and the offset are state: a restart continues bitwise, for the
    # explicit and an implicit integrator
    for integrator in velocityVerlet implicitEuler; do
        softDenseCase $integrator
        setEntry $integrator $properties integration/integrator $integrator
        setOscillation $integrator 0.004 60
        expectExactRestart $integrator programmed
        state="$work/$integrator/0.1/uniform/suspensionState"
        awk '$1 == "strain" { s = $2 + 0 } $1 == "shearRate" { r = $2 + 0 }
             END { exit !(s != 0 && r != 1) }' "$state" \
            || fail "$integrator: no strain and rate of the programme in $state"
    done
    # and under stress control (a stress that changes), whose rate is the
    # engine's
    softDenseCase stress
    setEntry stress $properties integration/integrator implicitEuler
    foamDictionary -entry ambientFlow/shearRate -remove "$work/stress/$properties" \
        > /dev/null 2>&1
    foamDictionary -entry ambientFlow/shearStress -add \
        "table ((0 5) (0.1 15))" "$work/stress/$properties" > /dev/null 2>&1 \
        || fail "cannot set shearStress"
    expectExactRestart stress programmed
    ;;

stressControlDilute)
    # Stokes drag alone, overdamped, under the shear stress 2: the rate is
    # sigma/(eta0 (1 + 2.5 phi)) in every row (the Stokes stresslets, eq.
    # 9a), phi that of the packed radii in the box
    dragOnlyCase c
    setEntry c $properties integration/deltaT 1e-4
    foamDictionary -entry ambientFlow/shearRate -remove "$work/c/$properties" \
        > /dev/null 2>&1
    foamDictionary -entry ambientFlow/shearStress -add 2 "$work/c/$properties" \
        > /dev/null 2>&1 || fail "cannot set shearStress"
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) || fail "makeSuspension"
    runCase c
    phi=$(packedFraction c)
    dat="$work/c/postProcessing/rheology/0/rheology.dat"
    awk -v phi="$phi" -v r="$(column "$dat" shearRate)" '
        !/^#/ { n++; rate = $r; expected = 2/(1 + 2.5*phi)
                if (rate < 0.99*expected || rate > 1.01*expected) bad++ }
        END { exit !(n == 4 && bad == 0) }' "$dat" \
        || fail "the rate is not 2/(1 + 2.5 phi), phi = $phi"
    grep -q "^strain .* rate .* sigma " "$work/c/log.wavyShearFoam" \
        || fail "the progress report does not give the rate in use"
    ;;

badShearStress)
    # Stress control with the explicit integrator, with a rate too, and a
    # stress that is zero over the run
    newCase c
    foamDictionary -entry ambientFlow/shearRate -remove "$work/c/$properties" \
        > /dev/null 2>&1
    foamDictionary -entry ambientFlow/shearStress -add 10 "$work/c/$properties" \
        > /dev/null 2>&1 || fail "cannot set shearStress"
    cp -r "$work/c" "$work/zero"
    cp -r "$work/c" "$work/both"
    expectInputError c "Stress control (entry 'shearStress'" \
        "integration/integrator implicitEuler or overdamped"
    setEntry zero $properties integration/integrator implicitEuler
    setEntry zero $properties ambientFlow/shearStress 0
    expectInputError zero "Entry 'shearStress'" "is 0 over the whole run"
    foamDictionary -entry ambientFlow/shearRate -add 1 "$work/both/$properties" \
        > /dev/null 2>&1
    expectInputError both "Entries 'shearRate' and 'shearStress'"
    ;;

oscillationDilute)
    # Stokes drag alone (no lubrication, contact or electro-chemical
    # forces), overdamped: the particles follow the flow, and the stress is
    # eta0 (1 + 2.5 phi) times the rate at every instant (the Stokes
    # stresslets, eq. 9a): eta' = 1 + 2.5 phi, G' = 0. phi is that of the
    # packed radii (lagrangian d) in the box; the step's mean rate is that
    # of a row, so G'/G'' = omega dt/2 = 0.0016. Rows start after the first
    # step: cycles 1 to 3 of [0, 4T] are sampled whole
    dragOnlyCase c
    setEntry c $properties ambientFlow/type uniformShear
    foamDictionary -entry ambientFlow/amplitude -remove "$work/c/$properties" \
        > /dev/null 2>&1
    foamDictionary -entry ambientFlow/periods -remove "$work/c/$properties" \
        > /dev/null 2>&1
    setOscillation c 0.5 2
    T=3.14159265358979                  # 2 pi/omega
    setEntry c $properties integration/deltaT "$(awk -v T=$T 'BEGIN { printf "%.15g", T/2000 }')"
    setEntry c $control deltaT "$(awk -v T=$T 'BEGIN { printf "%.15g", T/100 }')"
    setEntry c $control endTime "$(awk -v T=$T 'BEGIN { printf "%.15g", 4*T }')"
    setEntry c $control writeInterval 1000
    foamDictionary -entry functions/oscillation -set \
        "{ type suspensionOscillation; libs (suspensionFunctionObjects); discardCycles 0; }" \
        "$work/c/$control" > /dev/null 2>&1 || fail "cannot add the function object"
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) || fail "makeSuspension"
    runCase c
    phi=$(packedFraction c)
    summary="$work/c/postProcessing/oscillation/0/oscillationSummary.dat"
    [ -f "$summary" ] || fail "no oscillationSummary.dat"
    awk -v phi="$phi" '
        $1 == "etaP" { etaP = $2 } $1 == "Gp" { Gp = $2 } $1 == "Gpp" { Gpp = $2 }
        $1 == "gamma0" { g0 = $2; n = $4 }
        END {
            expected = 1 + 2.5*phi
            exit !(n == 3 && g0 > 0.4999 && g0 < 0.5001 \
                   && etaP > 0.99*expected && etaP < 1.01*expected \
                   && Gp > -0.01*Gpp && Gp < 0.01*Gpp)
        }' "$summary" \
        || { cat "$summary" >&2; fail "not eta' = 1 + 2.5 phi (phi = $phi) and G' = 0"; }
    ;;

badOscillation)
    # The oscillatory rate's entries, and the function object's omega
    newCase c
    setOscillation c 0 1
    expectInputError c suspensionProperties "strainAmplitude"
    newCase d
    setOscillation d 0.1 -2
    expectInputError d suspensionProperties "omega"
    # The function object's own entries: an error naming the entry and
    # controlDict before any step
    newCase e
    foamDictionary -entry functions/oscillation -set \
        "{ type suspensionOscillation; libs (suspensionFunctionObjects); }" \
        "$work/e/$control" > /dev/null 2>&1 || fail "cannot add the function object"
    newCase f
    setOscillation f 0.1 2
    foamDictionary -entry functions/oscillation -set \
        "{ type suspensionOscillation; libs (suspensionFunctionObjects); omega 0; }" \
        "$work/f/$control" > /dev/null 2>&1 || fail "cannot add the function object"
    for c in e f; do
        (cd "$work/$c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
            && fail "$c: wavyShearFoam accepted the function object"
        log="$work/$c/log.wavyShearFoam"
        grep -q "FOAM FATAL IO ERROR" "$log" || fail "$c: no FatalIOError"
        grep -q "controlDict.functions.oscillation" "$log" || fail "$c: no file named"
        grep -q "^strain " "$log" && fail "$c: time steps were taken"
    done
    grep -qF "needs the entry 'omega': the ambient flow's shearRate is 'constant'" \
        "$work/e/log.wavyShearFoam" || fail "e: the error does not name omega"
    grep -qF "Entry 'omega' 0 of function object oscillation is not positive" \
        "$work/f/log.wavyShearFoam" || fail "f: the error does not name omega"
    ;;

implicitRun)
    for integrator in implicitEuler overdamped; do
        newCase $integrator
        setEntry $integrator $properties integration/integrator $integrator
        (cd "$work/$integrator" && wavyShearFoam > log.wavyShearFoam 2>&1) \
            || fail "wavyShearFoam ($integrator)"
        log="$work/$integrator/log.wavyShearFoam"
        grep -q "integration  $integrator," "$log" \
            || fail "$integrator: no integrator in the start-up report"
        grep -q "CG solver    tolerance 1e-06, maxIterations 1000" "$log" \
            || fail "$integrator: no CG parameters in the start-up report"
        # Contacts are implicit: the explicit Coulomb force of a sliding
        # contact sets the step of this frictional case
        grep -q "binding limit slidingFriction" "$log" \
            || fail "$integrator: the step is not set by the sliding friction"
        grep -q "^strain .* CG [1-9][0-9]* iterations" "$log" \
            || fail "$integrator: no CG statistics in the progress report"

        dat="$work/$integrator/postProcessing/rheology/0/rheology.dat"
        grep "^# Time" "$dat" \
            | grep -q "pairSlots[[:space:]]*cgIterations[[:space:]]*cgResidual" \
            || fail "$integrator: rheology.dat: no CG columns"
        rows=$(grep -vc "^#" "$dat")
        [ "$rows" -eq 4 ] || fail "$integrator: $rows rows, expected 4"
        awk -v n="$(columns "$dat")" -v i="$(column "$dat" cgIterations)" \
            -v r="$(column "$dat" cgResidual)" \
            '!/^#/ && (NF != n || $i < 1 || $i > 1000 || $r > 1e-6) { exit 1 }' \
            "$dat" || fail "$integrator: rows without converged CG statistics"
    done
    ;;

implicitRestart)
    # Between steps the implicit integrators keep the velocities: the warm
    # start of CG, the inertia term of implicitEuler, the adaptive step bound
    for integrator in implicitEuler overdamped; do
        softDenseCase $integrator
        setEntry $integrator $properties integration/integrator $integrator
        setEntry $integrator $properties integration/maxDisplacement 1e-3
        expectExactRestart $integrator
        grep -q "outer step   0.01 >= " "$work/$integrator/log.wavyShearFoam" \
            || fail "$integrator: no adaptive step"
        # A cloud written before dUdt and dOmegadt existed restarts with
        # them 0: it runs, and (the warm start differs) not bitwise
        old=$work/$integrator.old
        cp -r "$work/$integrator.restarted" "$old"
        rm -rf "$old/0.1" "$old/postProcessing/rheology/0.05" \
            "$old"/0.05/lagrangian/suspension/d*dt
        handMade "$old/0.05"
        (cd "$old" && wavyShearFoam > log.wavyShearFoam 2>&1) \
            || fail "$integrator: restart from a cloud without dUdt"
        cmp -s "$work/$integrator/0.1/lagrangian/suspension/U" "$old/0.1/lagrangian/suspension/U" \
            && fail "$integrator: the restart without dUdt is bitwise exact"
    done
    ;;

dimensionalInput)
    newCase reduced
    newCase SI
    toDimensional SI
    mesh SI
    for c in reduced SI; do
        setEntry $c system/controlDict endTime 0.001
        (cd "$work/$c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
            || fail "wavyShearFoam ($c)"
    done
    si=$work/SI/log.wavyShearFoam
    grep -q "^Dimensional input" "$si" \
        || fail "no dimensional input in the start-up report"
    [ "$(grep -c "^    group  " "$si")" -eq 8 ] || fail "not 8 groups reported"
    grep -qF "contact/stiffness = 400000  (kn/(eta0 a0 gammaDot))" "$si" \
        || fail "no group formula in the report"
    [ "$(reducedReport "$si" | wc -l)" -eq 9 ] || fail "incomplete report"
    diff <(reducedReport "$work/reduced/log.wavyShearFoam") \
         <(reducedReport "$si") >&2 \
        || fail "the reduced parameters differ"
    dat=postProcessing/rheology/0/rheology.dat
    diff <(grep -v "^#" "$work/reduced/$dat") <(grep -v "^#" "$work/SI/$dat") \
        >&2 || fail "the first rheology.dat row differs"
    ;;

failure)
    runawayCase c
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

    # It is the state the same run writes at that time when it stops there
    # (a write every outer step to $last), particle by particle (the
    # restored state is re-sorted, as a restart is). Not bitwise: writing
    # at other times re-sorts at other times, which changes the sums' order
    # (the same write times give the same bits; 2e-12 here)
    mkdir "$work/ref"
    cp -r "$work/c/constant" "$work/c/system" "$work/ref"
    setEntry ref system/controlDict endTime "$last"
    setEntry ref system/controlDict writeInterval 1
    runCase ref "to the last good time $last"
    for field in x U omega F T S; do
        [ -s "$work/ref/$last/lagrangian/suspension/$field" ] \
            || fail "no $field at $last in the uninterrupted run"
        byId "$work/c/$last" $field > "$work/failed.$field"
        byId "$work/ref/$last" $field > "$work/ref.$field"
        sameNumbers "$work/failed.$field" "$work/ref.$field" 1e-9 \
            || fail "the last good $field differs from the run's own at $last"
    done
    byContact "$work/c/$last" > "$work/failed.contacts"
    byContact "$work/ref/$last" > "$work/ref.contacts"
    [ -s "$work/ref.contacts" ] || fail "no contacts at $last in the uninterrupted run"
    sameNumbers "$work/failed.contacts" "$work/ref.contacts" 1e-9 \
        || fail "the last good contact history differs from the run's own at $last"
    for entry in time steps nContacts offset; do
        foamDictionary -entry $entry -value "$work/c/$last/uniform/suspensionState" \
            > "$work/failed.$entry" || fail "no $entry in the last good state"
        foamDictionary -entry $entry -value "$work/ref/$last/uniform/suspensionState" \
            > "$work/ref.$entry" || fail "no $entry in the run's own state"
        sameNumbers "$work/failed.$entry" "$work/ref.$entry" 1e-9 \
            || fail "the last good state's $entry differs from the run's own at $last"
    done

    # An implicit run whose velocity solve fails (one CG iteration) also
    # writes its last good state, the state it started from
    newCase d
    setEntry d $properties integration/integrator implicitEuler
    foamDictionary -entry integration/solver -add "{ maxIterations 1; }" \
        "$work/d/$properties" > /dev/null 2>&1 || fail "cannot add integration/solver"
    if (cd "$work/d" && wavyShearFoam > log.wavyShearFoam 2>&1); then
        fail "the implicit run with one CG iteration did not stop"
    fi
    grep -q "did not converge" "$work/d/log.wavyShearFoam" || fail "no CG diagnostic"
    grep -q "last good state (time 0, " "$work/d/log.wavyShearFoam" \
        || fail "the unconverged run wrote no last good state at time 0"
    [ "$(entries "$work/d/0/lagrangian/suspension/x")" = "$N" ] \
        || fail "no last good cloud at time 0 of the unconverged run"

    # The last good state continues with stiffer contacts
    mv "$log" "$log.failed"
    setEntry c $properties contact/stiffness 1e4
    setEntry c system/controlDict endTime 0.2
    (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "no restart from the last good state $last"
    grep -q "stored suspension of .*/$last/" "$log" \
        || fail "the restart did not start from $last"
    ;;

killRestart)
    # A frictional run (contacts with history from the first outer steps)
    # that writes every outer step; the uninterrupted run is the reference
    softDenseCase ref
    setEntry ref system/controlDict writeInterval 1
    setEntry ref system/controlDict endTime 1
    (cd "$work/ref" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    cp -r "$work/ref" "$work/k"
    runCase ref "uninterrupted"
    times=$(cd "$work/ref" && foamListTimes 2>/dev/null)

    # The calls that write to disk in an outer step, to aim the kills at
    shim="$work/libwriteFaults.so"
    g++ -O1 -shared -fPIC -o "$shim" "$(dirname "$0")/faultInjection/writeFaults.C" -ldl \
        || fail "cannot build the fault injection library"
    cp -r "$work/k" "$work/count"
    setEntry count system/controlDict endTime 0.1
    (cd "$work/count" && LD_PRELOAD="$shim" WSF_FAULT_COUNT="$work/calls" \
        wavyShearFoam > log.wavyShearFoam 2>&1) || fail "the counting run"
    perStep=$(( $(cat "$work/calls")/10 ))
    [ "$perStep" -gt 10 ] || fail "only $perStep write calls an outer step"

    # 30 kills, each followed by the next trial's restart: half at a random
    # moment of the time loop, half at a random write call of the first 4
    # outer steps (a torn write, then SIGKILL)
    RANDOM=27
    kills=0
    for trial in $(seq 1 30); do
        log="$work/k/log.trial$trial"
        if [ $((trial % 2)) = 0 ]; then
            at=$((1 + RANDOM % (4*perStep)))
            (cd "$work/k" && LD_PRELOAD="$shim" WSF_FAULT_KILL_AT=$at \
                exec wavyShearFoam > "$log" 2>&1) && break
        else
            # at a random moment of the first 0.1 s of the time loop
            (cd "$work/k" && exec wavyShearFoam > "$log" 2>&1) &
            pid=$!
            while kill -0 $pid 2>/dev/null && ! grep -q "^Starting time loop" "$log"; do
                sleep 0.01
            done
            sleep "0.0$((RANDOM % 10))$((RANDOM % 10))"
            kill -9 $pid 2>/dev/null || true
            wait $pid && break
        fi
        kills=$((kills + 1))
        # A restart takes a complete time, or stops: the next trial's log
        grep -q "FOAM FATAL" "$log" && fail "trial $trial: $(grep -A3 'FOAM FATAL' "$log")"
    done
    [ "$kills" = 30 ] || fail "the run ended after $kills kills: lengthen it"
    runCase k "after the kills"
    grep -q "FOAM FATAL" "$work"/k/log.* && fail "a restart failed"
    restarts=$(cat "$work"/k/log.trial* "$work/k/log.wavyShearFoam" | grep -c "stored suspension of")
    aside=$(ls -d "$work"/k/*.incomplete* 2>/dev/null | wc -l)
    echo "killRestart: $kills kills, $restarts restarts, $aside incomplete times set aside"
    [ "$aside" -gt 0 ] || fail "no kill left an incomplete time (aim the kills)"

    # Every time of the finished run is the uninterrupted run's, bitwise
    for t in $times; do
        for f in "$work/ref/$t"/lagrangian/suspension/*; do
            rel=${f#"$work/ref/"}
            cmp -s "$f" "$work/k/$rel" || fail "$rel differs from the uninterrupted run"
        done
        state=uniform/suspensionState
        diff <(awk '$1 ~ /^(time|steps|nContacts|offset)$/' "$work/ref/$t/$state") \
             <(awk '$1 ~ /^(time|steps|nContacts|offset)$/' "$work/k/$t/$state") \
            > /dev/null || fail "$t: the state differs"
    done
    ;;

incompleteTime)
    newCase c
    setEntry c system/controlDict writeInterval 1
    runCase c "to 0.004"
    # 0.004 truncated, 0.003 without its state, a time 0.005 holding only
    # OpenFOAM's uniform/time
    x="$work/c/0.004/lagrangian/suspension/x"
    head -c 2000 "$x" > "$x.tmp" && mv "$x.tmp" "$x"
    rm "$work/c/0.003/uniform/suspensionState"
    mkdir -p "$work/c/0.005/uniform"
    cp "$work/c/0.002/uniform/time" "$work/c/0.005/uniform/time"
    cp -r "$work/c" "$work/s"
    setEntry c system/controlDict endTime 0.005
    runCase c "restart from the latest complete time"
    log="$work/c/log.wavyShearFoam"
    grep -q "Time 0.004 is incomplete (0.004/lagrangian/suspension/x holds 2000 bytes" "$log" \
        || fail "no log line for the truncated time"
    grep -q "Time 0.003 is incomplete (no uniform/suspensionState" "$log" \
        || fail "no log line for the time without its state"
    grep -q "Time 0.005 is incomplete (uniform/time but no suspension)" "$log" \
        || fail "no log line for the time with only uniform/time"
    grep -q "stored suspension of .*/0.002/uniform/suspensionState" "$log" \
        || fail "the restart did not start from 0.002"
    for t in 0.003 0.004 0.005; do
        [ -d "$work/c/$t.incomplete" ] || fail "$t not set aside"
    done
    [ "$(head -c 2000 "$work/c/0.004.incomplete/lagrangian/suspension/x" | cmp - "$work/s/0.004/lagrangian/suspension/x" && echo same)" = same ] \
        || fail "the incomplete time was changed"
    [ -f "$work/c/0.005/uniform/suspensionState" ] || fail "the run did not go on to 0.005"

    # startFrom startTime at an incomplete time: an error naming the
    # latest complete one, and nothing changed
    setEntry s system/controlDict startFrom startTime
    setEntry s system/controlDict startTime 0.004
    (cd "$work/s" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        && fail "a start from the incomplete time 0.004 was accepted"
    log="$work/s/log.wavyShearFoam"
    grep -q "FOAM FATAL IO ERROR" "$log" || fail "no FatalIOError"
    grep -q "time 0.002 holds a complete one" "$log" \
        || fail "the error does not name the latest complete time"
    grep -q "controlDict" "$log" || fail "the error does not name controlDict"
    [ -d "$work/s/0.004" ] && [ ! -e "$work/s/0.004.incomplete" ] \
        || fail "the incomplete start time was moved"
    ;;

failedWrite)
    newCase c
    setEntry c system/controlDict writeInterval 1
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    cp -r "$work/c/0" "$work/zero"
    size=$(stat -c %s "$work/c/0/lagrangian/suspension/x")
    # Files of a few kB are written whole, x (about $size bytes) is not: a
    # write then fails with EFBIG as it would with ENOSPC on a full disk
    if (cd "$work/c" && trap '' XFSZ && ulimit -f $(( (size - 1500)/1024 )) \
        && exec wavyShearFoam > log.wavyShearFoam 2>&1); then
        fail "the run went on past a failed write"
    fi
    log="$work/c/log.wavyShearFoam"
    # Ours, or OpenFOAM's own check of the stream (the cloud's positions)
    grep -qE "FOAM FATAL (IO )?ERROR" "$log" || fail "no FatalError"
    grep -qE "(Cannot write|error in IOstream|The file) .*0.001/lagrangian/suspension/" "$log" \
        || fail "the error does not name the file"
    [ ! -e "$work/c/0.001/uniform/suspensionState" ] \
        || fail "the failed time has a state"
    diff -r "$work/zero" "$work/c/0" > /dev/null || fail "time 0 changed"
    runCase c "after the failed write"
    grep -q "Time 0.001 is incomplete" "$work/c/log.wavyShearFoam" \
        || fail "the restart did not set the failed time aside"
    ;;

badControls)
    for value in 0 -0.001; do
        newCase "d$value"
        setEntry "d$value" $control deltaT "$value"
        expectInputError "d$value" controlDict "'deltaT'"
    done
    newCase t
    setEntry t $properties integration/threads sometimes
    expectInputError t suspensionProperties "'threads'" "adaptive or fixed"
    # (foamDictionary itself dies of the floating-point trap on 1e999)
    newCase huge
    sed -i 's/^\( *stiffness  *\)[^;]*;/\11e999;/' "$work/huge/$properties"
    grep -q "stiffness *1e999;" "$work/huge/$properties" || fail "cannot set 1e999"
    expectInputError huge suspensionProperties stiffness
    newCase hugeControl
    sed -i 's/^endTime .*/endTime 1e999;/' "$work/hugeControl/$control"
    (cd "$work/hugeControl" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        && fail "endTime 1e999 was accepted"
    grep -q "FOAM FATAL IO ERROR" "$work/hugeControl/log.wavyShearFoam" \
        || fail "endTime 1e999: no FatalIOError"
    grep -q "endTime" "$work/hugeControl/log.wavyShearFoam" \
        || fail "endTime 1e999: the error does not name the entry"
    # endTime before the start time of a restart
    newCase e
    runCase e "to 0.004"
    setEntry e $control endTime 0.002
    (cd "$work/e" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        && fail "an endTime before the start time was accepted"
    grep -q "FOAM FATAL IO ERROR" "$work/e/log.wavyShearFoam" || fail "no FatalIOError"
    grep -q "Entry 'endTime' = 0.002 in .*controlDict\" is before the start time 0.004" \
        "$work/e/log.wavyShearFoam" || fail "the error does not name endTime"
    ;;

oversizedCase)
    newCase c
    setEntry c $properties population/nParticles 100000000
    for program in "makeSuspension -boxOnly" makeSuspension wavyShearFoam; do
        log="$work/c/log.${program// /}"
        start=$(date +%s)
        (cd "$work/c" && timeout 60 $program > "$log" 2>&1) \
            && fail "$program accepted 10^8 particles"
        [ $(( $(date +%s) - start )) -lt 20 ] || fail "$program took too long to refuse"
        grep -q "FOAM FATAL IO ERROR" "$log" || fail "$program: no FatalIOError"
        grep -q "nParticles" "$log" || fail "$program: the error does not name nParticles"
        grep -qE "needs at least [0-9.]+ GB.* has [0-9.]+ GB" "$log" \
            || fail "$program: no estimate and limit"
    done
    ;;

nonFiniteState)
    newCase c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    # A binary state with a NaN velocity (ascii cannot hold one)
    setEntry c $control writeFormat binary
    runCase c "to 0.004"
    python3 - "$work/c/0.004/lagrangian/suspension/U" <<'PY' || fail "cannot write the NaN"
import struct, sys
f = sys.argv[1]
b = bytearray(open(f, "rb").read())
start = b.index(b"(", b.index(b"FoamFile") + 200) + 1      # the data of the list
b[start:start + 8] = struct.pack("d", float("nan"))
open(f, "wb").write(b)
PY
    handMade "$work/c/0.004"
    setEntry c $control endTime 0.006
    (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        && fail "a NaN velocity was accepted"
    log="$work/c/log.wavyShearFoam"
    grep -q "FOAM FATAL IO ERROR" "$log" || fail "no FatalIOError"
    grep -q "0.004/lagrangian/suspension/U" "$log" || fail "the error does not name the file"
    grep -q "must be finite" "$log" || fail "the error does not say why"

    # Explicit steps far above the stability limit, under OpenFOAM's
    # floating-point trap: the run stops with the cause, not SIGFPE
    newCase b
    setEntry b $properties integration/deltaT 0.05
    setEntry b $control endTime 0.2
    setEntry b $control deltaT 0.05
    if (cd "$work/b" && wavyShearFoam > log.wavyShearFoam 2>&1); then
        fail "an unstable run did not stop"
    fi
    log="$work/b/log.wavyShearFoam"
    grep -q "trapFpe: Floating point exception trapping enabled" "$log" \
        || fail "the run was not under the floating-point trap"
    grep -q "sigFpe\|printStack" "$log" && fail "the run died of a floating-point trap"
    grep -q "FOAM FATAL ERROR" "$log" || fail "no FatalError"
    grep -qE "non-finite|runaway overlap" "$log" || fail "no diagnostic"
    grep -q "last good state" "$log" || fail "no last good state reported"
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

badIntegrator)
    newCase c
    setEntry c $properties integration/integrator rungeKutta
    expectInputError c suspensionProperties integrator rungeKutta \
        velocityVerlet implicitEuler overdamped
    ;;

badSolver)
    newCase c
    setEntry c $properties integration/integrator overdamped
    foamDictionary -entry integration/solver -add '{ tolerance 1; }' \
        "$work/c/$properties" > /dev/null 2>&1
    expectInputError c suspensionProperties tolerance "(0, 1)"
    ;;

badDimensional)
    newCase c
    toDimensional c
    setEntry c $properties dimensional/kn -0.4
    expectInputError c suspensionProperties kn "(0, inf)"
    ;;

dimensionalConflict)
    # A group given as well as the SI quantities it is made from
    newCase c
    toDimensional c
    foamDictionary -entry contact/stiffness -add 4e5 "$work/c/$properties" \
        > /dev/null 2>&1
    expectInputError c suspensionProperties stiffness "units dimensional"
    ;;

badContactType)
    # Models sharing a dictionary are chosen by `type`
    newCase c
    foamDictionary -entry contact/type -add sticky "$work/c/$properties" \
        > /dev/null 2>&1
    expectInputError c suspensionProperties type sticky frictionalContact \
        criticalLoadContact
    ;;

badCriticalLoad)
    newCase c
    foamDictionary -entry contact/type -add criticalLoadContact \
        "$work/c/$properties" > /dev/null 2>&1
    foamDictionary -entry contact/criticalLoad -add -1 \
        "$work/c/$properties" > /dev/null 2>&1
    expectInputError c suspensionProperties criticalLoad "[0, inf)"
    ;;

criticalLoadRun)
    # The critical-load model from the case: read, reported, run
    newCase c
    foamDictionary -entry contact/type -add criticalLoadContact \
        "$work/c/$properties" > /dev/null 2>&1
    foamDictionary -entry contact/criticalLoad -add 0.1 \
        "$work/c/$properties" > /dev/null 2>&1
    setEntry c system/controlDict endTime 0.001
    (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "wavyShearFoam with criticalLoadContact"
    grep -q "^    criticalLoadContact .*F_CL = 0.1" "$work/c/log.wavyShearFoam" \
        || fail "the start-up report does not name the critical load"
    grep -q "^strain " "$work/c/log.wavyShearFoam" || fail "no step taken"
    ;;

criticalLoadDimensional)
    # F_CL in newtons with units dimensional: 1e-13 N is 0.1 in the force
    # scale eta0 a0^2 gammaDot = 1e-12 N of toDimensional
    newCase c
    toDimensional c
    foamDictionary -entry contact/type -add criticalLoadContact \
        "$work/c/$properties" > /dev/null 2>&1
    foamDictionary -entry dimensional/criticalLoad -add 1e-13 \
        "$work/c/$properties" > /dev/null 2>&1
    mesh c
    setEntry c system/controlDict endTime 0.001
    (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        || fail "wavyShearFoam with criticalLoadContact in SI units"
    grep -qF "contact/criticalLoad = 0.1  (F_CL/(eta0 a0^2 gammaDot))" \
        "$work/c/log.wavyShearFoam" || fail "no critical-load group reported"
    grep -q "^    criticalLoadContact .*F_CL = 0.1" "$work/c/log.wavyShearFoam" \
        || fail "the model does not use the converted critical load"
    ;;

badDeltaT)
    newCase c
    setEntry c $properties integration/deltaT fast
    expectInputError c suspensionProperties deltaT
    ;;

badShearRate)
    # The rate is a scalar Function1 of time: a vector, or a type that is
    # not one, is an error naming the entry
    newCase c
    setEntry c $properties ambientFlow/shearRate "(1 0 0)"
    expectInputError c suspensionProperties "shearRate"
    newCase d
    setEntry d $properties ambientFlow/shearRate "sinus"
    expectInputError d suspensionProperties "Unknown Function1 type sinus for shearRate"
    ;;

badAmbientFlowEntry)
    # The wave's amplitude left under uniformShear, which has none
    newCase c
    setEntry c $properties ambientFlow/type uniformShear
    expectInputError c suspensionProperties "Unknown entry 'amplitude'" \
        ambientFlow
    ;;

smallBox)
    # 3 neighbour cut-offs do not fit into the box of 30 spheres; the error
    # names the smallest N that fits, which makeSuspension packs (the same
    # rule), while N - 1 is refused by the solver
    newCase c
    setEntry c $properties population/nParticles 30
    mesh c
    expectInputError c suspensionProperties "every box length must be at least 3 R" \
        "largest interaction gap + Verlet skin" "single image"
    n=$(sed -n 's/.*smallest number of particles that fits is N = \([0-9]*\) .*/\1/p' \
        "$work/c/log.wavyShearFoam")
    [ -n "$n" ] || fail "the error names no smallest N"
    newCase below
    setEntry below $properties population/nParticles $((n - 1))
    mesh below
    expectInputError below suspensionProperties \
        "smallest number of particles that fits is N = $n "
    newCase fits
    setEntry fits $properties population/nParticles $n
    mesh fits
    (cd "$work/fits" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension refused the smallest N = $n"
    [ "$(entries "$work/fits/0/lagrangian/suspension/d")" = "$n" ] \
        || fail "not $n particles packed"
    ;;

trimodalPopulation)
    # phi = 0.55 reached: the solid volume of d over the box of particleBox;
    # each radius's volume fraction within one particle of 1/3 (of the
    # largest, the coarsest step: the fractions sum to 1, so the others
    # take up its rounding)
    newCase c
    trimodal c "(0.3333333 0.3333333 0.3333334)" volumeFractions
    mesh c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    box=$(awk '/^L[xyz]/ { sub(";", "", $2); printf "%s ", $2 }' \
        "$work/c/constant/particleBox")
    values "$work/c/0/lagrangian/suspension/d" | awk -v box="$box" '
        { n[$1]++; v[$1] += $1^3; V += $1^3; N++; if ($1 > dMax) dMax = $1 }
        END {
            split(box, L, " ")
            phi = V*3.141592653589793/6/(L[1]*L[2]*L[3])
            if (N != 300) { print "N = " N; exit 1 }
            if (phi < 0.55*(1 - 1e-9) || phi > 0.55*(1 + 1e-9)) {
                print "phi = " phi; exit 1 }
            k = 0
            for (d in n) {
                k++
                if (d != 2 && d != 3 && d != 4) { print "diameter " d; exit 1 }
                share = v[d]/V
                one = dMax^3/V
                if (share - 1/3 > one || 1/3 - share > one) {
                    print "d = " d ": volume fraction " share; exit 1 }
            }
            if (k != 3) { print k " distinct diameters"; exit 1 }
        }' > "$work/c/check" || fail "trimodal d: $(cat "$work/c/check")"
    grep -q "radii        3 radii: 1 (n = .*), 1.5 (n = .*), 2 (n = " \
        "$work/c/log.makeSuspension" || fail "the log does not report the 3 radii"
    ;;

radiusFile)
    # 70 spheres of radius 1 and 30 of 1.4 from the file; d holds them
    newCase c
    radiusFile c "$(printf '1 %.0s' $(seq 70))\n$(printf '1.4\\n%.0s' $(seq 30))"
    mesh c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    [ "$(values "$work/c/0/lagrangian/suspension/d" \
        | awk '{ printf "%.12g\n", $1 }' | sort -g | uniq -c \
        | awk '{ printf "%s:%s ", $1, $2 }')" = "70:2 30:2.8 " ] \
        || fail "d is not the radii of the file"
    grep -q "2 radii: 1 (n = 70, .*), 1.4 (n = 30, " "$work/c/log.makeSuspension" \
        || fail "the log does not report the radii of the file"
    ;;

badFraction)
    newCase c
    trimodal c "(-0.1 0.6 0.5)" volumeFractions
    expectInputError c suspensionProperties "volumeFractions" "element 0 = -0.1"
    ;;

badFractionSum)
    newCase c
    trimodal c "(0.3 0.3 0.3)" numberFractions
    expectInputError c suspensionProperties "numberFractions" "sums to 0.9"
    ;;

bothFractions)
    newCase c
    trimodal c "(0.3 0.3 0.4); numberFractions (0.3 0.3 0.4)" volumeFractions
    expectInputError c suspensionProperties "exactly one of the entries 'volumeFractions' and 'numberFractions'"
    ;;

badFractionCount)
    newCase c
    trimodal c "(0.5 0.5)" volumeFractions
    expectInputError c suspensionProperties "volumeFractions" "2 fractions for 3 radii"
    ;;

badDiscreteRadius)
    newCase c
    setPopulation c "type discrete; nParticles 300; volumeFraction 0.3;
seed 1; radii (1 0 2); volumeFractions (0.3 0.3 0.4);"
    expectInputError c suspensionProperties "radii" "element 1 = 0"
    ;;

missingRadiusFile)
    newCase c
    radiusFile c "1 1"
    rm "$work/c/constant/radii"
    expectInputError c suspensionProperties "'file'" "cannot open" "constant/radii"
    ;;

emptyRadiusFile)
    newCase c
    radiusFile c " \n"
    expectInputError c suspensionProperties "'file'" "constant/radii holds no radii"
    ;;

badRadiusFileNumber)
    newCase c
    radiusFile c "1 1.2\n1.1 one 1"
    expectInputError c suspensionProperties "'file'" "radius 4 of" "'one', is not a number"
    ;;

badRadiusFileRadius)
    newCase c
    radiusFile c "1 1.2\n-1 1"
    expectInputError c suspensionProperties "'file'" "radius 3 of" "= -1 is outside (0, inf)"
    ;;

badRadiusFileCount)
    newCase c
    radiusFile c "1 1.2 1"
    foamDictionary -entry population/nParticles -add 4 "$work/c/$properties" \
        > /dev/null 2>&1 || fail "cannot add nParticles"
    expectInputError c suspensionProperties "nParticles" "does not match the 3 radii"
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
    handMade "$work/c/0"
    expectInputError c "0/lagrangian/suspension/d" "holds 99 entries"
    ;;

overlappingStart|jammedStart)
    # A cloud at time 0 whose diameters were made larger by hand: 3% at
    # phi = 0.5 (phi 0.55) is separated before the first step; 35% (phi
    # 1.2) cannot be and stops naming the cloud (300 spheres: the box holds
    # 3 cut-offs of the grown spheres)
    newCase c
    setEntry c $properties population/volumeFraction 0.5
    setEntry c $properties population/nParticles 300
    mesh c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    factor=1.03
    [ "$test" = jammedStart ] && factor=1.35
    d="$work/c/0/lagrangian/suspension/d"
    awk -v f=$factor '/^\(/ { inside = 1; print; next } /^\)/ { inside = 0 }
        { if (inside) printf "%.12g\n", f*$1; else print }' "$d" > "$d.tmp" \
        && mv "$d.tmp" "$d"
    handMade "$work/c/0"
    if [ "$test" = jammedStart ]; then
        expectInputError c "0/uniform/suspensionState" "cannot be separated" "jam"
    else
        (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
            || fail "wavyShearFoam"
        grep -q "overlapped; separated by FIRE" "$work/c/log.wavyShearFoam" \
            || fail "no report of the separated overlaps"
        # The radii in use are the cloud's, not the population's 1 and 1.4
        grep -q "radii        2 radii: 1.03 (n = .*), 1.442 (n = .*) (of the stored cloud)" \
            "$work/c/log.wavyShearFoam" || fail "the log does not report the cloud's radii"
        dat="$work/c/postProcessing/rheology/0/rheology.dat"
        awk -v o="$(column "$dat" maxOverlap)" '!/^#/ && $o > 0.01 { exit 1 }' "$dat" \
            || fail "overlaps above 1% of the radius after the start"
    fi
    ;;

referenceOutput)
    # reference/ holds what the solver wrote for tiny/ with makeSuspension,
    # on one thread (remade when rheology.dat took the columns shearRate
    # and sigma; every other number as the solver of commit 7834609, where
    # the cloud wrote its own output, had it but for round-off in one
    # entry of 0.004/particleStress):
    # the function objects must write the same numbers in the same files.
    # A change of the engine's numbers on purpose remakes them: these steps
    # on a copy of tiny/ (OMP_NUM_THREADS=1), then copy the 14 files
    # (find reference -type f)
    newCase c
    (cd "$work/c" && makeSuspension > log.makeSuspension 2>&1) \
        || fail "makeSuspension"
    runCase c
    reference=$(cd "$(dirname "$0")/reference" && pwd)
    n=0
    while IFS= read -r f; do
        [ -f "$work/c/$f" ] || fail "no $f"
        a=$reference/$f b=$work/c/$f
        if [ "${f##*/}" = rheology.dat ]; then
            # By column name: a pair model added since the reference was
            # made adds its column etaR_<contribution>, which must be zero
            # here (it is off); the reference's columns are compared
            [ "$(head -1 "$a")" = "$(head -1 "$b")" ] || fail "$f: first line differs"
            newColumnsAreZero "$a" "$b" || fail "$f: a column the reference lacks is not an etaR_ column of zeros"
            selectedColumns "$a" "$a" > "$work/ref.rows"
            selectedColumns "$b" "$a" > "$work/out.rows" || fail "$f lacks a column of the reference"
            a=$work/ref.rows b=$work/out.rows
        fi
        if [ -z "${WSF_TEST_ARCH_FLAGS:-}" ]; then
            cmp "$a" "$b" >&2 || fail "$f differs"
        else
            sameNumbers "$a" "$b" 1e-7 >&2 \
                || fail "$f differs (built with $WSF_TEST_ARCH_FLAGS)"
        fi
        n=$((n + 1))
    done < <(cd "$reference" && find . -type f | sed 's|^\./||' | sort)
    [ "$n" -eq 14 ] || fail "$n reference files, expected 14"
    ;;

stopAtPrecision)
    # Implicit, frictionless, sampled every 0.002, summarised every 0.05:
    # with stopAtPrecision the run ends at the first write time at which
    # etaR's error bar is trusted and within the precision, writing its
    # state; the same run ended one write time earlier is not yet precise
    newCase c
    setEntry c $properties integration/integrator implicitEuler
    setEntry c $properties contact/friction 0
    setEntry c $control endTime 2
    setEntry c $control deltaT 0.002
    setEntry c $control writeInterval 25
    setEntry c $control functions/rheology/precision 0.02
    setEntry c $control functions/rheology/minSteadyStrain 0.05
    setEntry c $control functions/rheology/stopAtPrecision true
    cp -r "$work/c" "$work/d"
    runCase c
    log="$work/c/log.wavyShearFoam"
    grep -q "(stopAtPrecision)" "$log" || fail "the run did not stop at precision"
    stop=$(sed -n 's/.*within the precision 0.02 at time \([0-9.e-]*\):.*/\1/p' "$log")
    [ -n "$stop" ] && awk -v t="$stop" 'BEGIN { exit !(t < 2) }' \
        || fail "stopped at '$stop', not before the end time 2"
    [ -f "$work/c/$stop/lagrangian/suspension/positions" ] \
        || fail "no state written at the stop time $stop"
    summary="$work/c/postProcessing/rheology/0/rheologySummary.dat"
    awk '$1 == "etaR" { ok = ($4 <= 0.02 && $10 == "yes") } END { exit !ok }' \
        "$summary" || fail "the summary at the stop is not trusted within 0.02"
    # One write interval (0.05) earlier: not precise yet
    before=$(awk -v t="$stop" 'BEGIN { printf "%g", t - 0.05 }')
    setEntry d $control endTime "$before"
    setEntry d $control functions/rheology/stopAtPrecision false
    runCase d
    grep -q "(stopAtPrecision)" "$work/d/log.wavyShearFoam" && fail "d stopped"
    awk '$1 == "etaR" { ok = ($4 <= 0.02 && $10 == "yes") } END { exit ok }' \
        "$work/d/postProcessing/rheology/0/rheologySummary.dat" \
        || fail "already precise at $before, one write time before the stop"
    ;;

badPrecision)
    newCase c
    setEntry c $control functions/rheology/precision 2
    (cd "$work/c" && wavyShearFoam > log.wavyShearFoam 2>&1) \
        && fail "wavyShearFoam accepted precision 2"
    log="$work/c/log.wavyShearFoam"
    grep -q "FOAM FATAL IO ERROR" "$log" || fail "no FatalIOError"
    grep -qF "Entry 'precision' 2 of function object rheology is not in (0, 1)" \
        "$log" || fail "the error does not name the entry and its range"
    grep -q "controlDict.functions.rheology" "$log" || fail "no file named"
    grep -q "^strain " "$log" && fail "time steps were taken"
    ;;

functionObjectsOff)
    newCase c
    foamDictionary -entry functions -remove "$work/c/$control" > /dev/null \
        2>&1 || fail "cannot remove functions"
    runCase c
    [ ! -e "$work/c/postProcessing" ] || fail "postProcessing written"
    for t in 0 0.002 0.004; do
        for f in lagrangian/suspension/x lagrangian/suspension/contactId \
            uniform/suspensionState
        do
            [ -f "$work/c/$t/$f" ] || fail "$t: no $f"
        done
        for f in Uinf gradUinf shearRateInf particleStress alpha; do
            [ ! -e "$work/c/$t/$f" ] || fail "$t: $f written"
        done
    done
    grep -q "^strain .* CPU [0-9.e+-]* s  peak RSS [0-9]* MB  ETA" \
        "$work/c/log.wavyShearFoam" \
        || fail "no progress report with the CPU time and memory"
    grep -q "^Peak resident memory [0-9.]* MB" "$work/c/log.wavyShearFoam" \
        || fail "no peak resident memory at the end"
    ;;

functionObjectEntries)
    newCase c
    setEntry c $control functions/rheology/contributions "(contact stokes)"
    setEntry c $control functions/rheology/writeInterval 2
    setEntry c $control functions/profiles/nBins 3
    setEntry c $control functions/profiles/writeAtStart false
    setEntry c $control functions/fields/fields "(alpha Uinf)"
    runCase c
    dat="$work/c/postProcessing/rheology/0/rheology.dat"
    grep "^# Time" "$dat" | grep -q "etaN[[:space:]]*etaR_contact[[:space:]]*etaR_stokes[[:space:]]*nContacts" \
        || fail "rheology.dat: not the columns etaR_contact etaR_stokes"
    [ "$(grep "^# Time" "$dat" | grep -o "etaR_" | wc -l)" -eq 2 ] \
        || fail "rheology.dat: other contributions"
    [ "$(rows "$dat" | wc -l)" -eq 2 ] || fail "rheology.dat: not 2 rows"
    awk -v n="$(columns "$dat")" '!/^#/ && NF != n { exit 1 }' "$dat" \
        || fail "rheology.dat: rows not of the header's columns"
    # The numbers of the full rows (reference/) of the steps written, in
    # the columns this file has, found by name in the reference's header
    diff <(rows "$dat" | awk '{ $1 = $1; print }') \
         <(selectedColumns "$(dirname "$0")/reference/postProcessing/rheology/0/rheology.dat" "$dat" \
            | awk 'NR % 2 == 0') >&2 \
        || fail "rheology.dat: not the numbers of the reference rows"
    [ ! -e "$work/c/postProcessing/profiles/0" ] \
        || fail "profiles written at the start (writeAtStart false)"
    for t in 0.002 0.004; do
        p="$work/c/postProcessing/profiles/$t/profiles.dat"
        [ "$(rows "$p" | wc -l)" -eq 3 ] || fail "$t: not 3 bins"
        [ "$(rows "$p" | awk '{ n += $2 } END { print n }')" -eq $N ] \
            || fail "$t: the bins do not hold the $N particles"
    done
    for t in 0 0.002 0.004; do
        for f in alpha Uinf; do
            [ -f "$work/c/$t/$f" ] || fail "$t: no $f"
        done
        for f in gradUinf shearRateInf particleStress; do
            [ ! -e "$work/c/$t/$f" ] || fail "$t: $f written"
        done
    done

    # Unknown names stop the run with an error naming the valid ones
    newCase bad
    setEntry bad $control functions/fields/fields "(alpha sigma)"
    if (cd "$work/bad" && wavyShearFoam > log.wavyShearFoam 2>&1); then
        fail "the unknown field was accepted"
    fi
    grep -q "Unknown field 'sigma'" "$work/bad/log.wavyShearFoam" \
        || fail "no error naming the unknown field"
    grep -q "Valid fields: .*particleStress" "$work/bad/log.wavyShearFoam" \
        || fail "the error does not list the valid fields"
    ;;

userFunctionObject)
    [ -n "${WSF_TEST_FO_LIB_DIR:-}" ] || fail "WSF_TEST_FO_LIB_DIR not set"
    newCase c
    foamDictionary -entry functions/count -add \
        "{ type particleCount; libs (suspensionTestFunctionObjects); writeControl timeStep; writeInterval 1; }" \
        "$work/c/$control" > /dev/null 2>&1 || fail "cannot add count"
    runCase c
    dat="$work/c/postProcessing/count/0/particleCount.dat"
    [ -f "$dat" ] || fail "no particleCount.dat"
    [ "$(rows "$dat" | wc -l)" -eq 4 ] || fail "particleCount.dat: not 4 rows"
    awk -v n=$N '!/^#/ && $2 != n { exit 1 }' "$dat" \
        || fail "particleCount.dat: a count is not $N"
    # It ran after the step of its time: strain = gammaDot t = t
    awk '!/^#/ && ($3 - $1)^2 > (1e-9*$1)^2 { exit 1 }' "$dat" \
        || fail "particleCount.dat: the strain is not that of the time"
    # The strain it saw is the one of the rheology row of the same time
    diff <(rows "$dat" | awk '{ print $1, $3 + 0 }') \
         <(rows "$work/c/postProcessing/rheology/0/rheology.dat" \
            | awk '{ print $1, $2 + 0 }') >&2 \
        || fail "particleCount.dat: the strain differs from rheology.dat"
    ;;

parallelRun)
    for integrator in velocityVerlet implicitEuler; do
        for layout in "2 1" "2 2"; do
            c=$integrator.${layout/ /x}
            softDenseCase $c
            setEntry $c $properties integration/integrator $integrator
            setEntry $c system/controlDict writePrecision 17
            inCase $c makeSuspension
            cp -r "$work/$c" "$work/$c.serial"
            decomposeDict $c $layout
            inCase $c decomposePar
            runParallel $c $((${layout/ /*}))
            grep -q "Warning" "$work/$c/log.$solver".* && fail "$c: a warning"
            inCase $c reconstructPar
            runCase $c.serial
            for t in 0.05 0.1; do
                expectSameParticles $c $t $c.serial 1e-9
                n=$(foamDictionary -entry nContacts -value "$work/$c/$t/uniform/suspensionState")
                m=$(foamDictionary -entry nContacts -value "$work/$c.serial/$t/uniform/suspensionState")
                [ "$n" = "$m" ] || fail "$c: $n contacts at $t, the serial run $m"
                sameNumbers "$work/$c/postProcessing/profiles/$t/profiles.dat" \
                    "$work/$c.serial/postProcessing/profiles/$t/profiles.dat" 1e-9 \
                    || fail "$c: profiles at $t"
                values "$work/$c/$t/alpha" > "$work/alpha.a"
                values "$work/$c.serial/$t/alpha" > "$work/alpha.b"
                sameNumbers "$work/alpha.a" "$work/alpha.b" 1e-9 || fail "$c: alpha at $t"
            done
            [ "$n" -gt 0 ] || fail "$c: no contacts"
            expectSameRheology "$work/$c/postProcessing/rheology/0/rheology.dat" \
                "$work/$c.serial/postProcessing/rheology/0/rheology.dat" 1e-9
        done
    done
    ;;

parallelRestart)
    for precision in 17 10; do
        c=chain$precision
        softDenseCase $c
        setBlocks $c "(4 6 4)"
        mesh $c
        setEntry $c system/controlDict writePrecision $precision
        setEntry $c system/controlDict endTime 0.05
        inCase $c makeSuspension
        cp -r "$work/$c" "$work/$c.serial"
        setEntry $c.serial system/controlDict endTime 0.15
        runCase $c.serial
        decomposeDict $c 2 1
        inCase $c decomposePar
        runParallel $c 2
        inCase $c reconstructPar -latestTime
        rm -r "$work/$c"/processor*
        decomposeDict $c 3 1
        setEntry $c system/controlDict endTime 0.1
        inCase $c decomposePar -latestTime
        runParallel $c 3
        inCase $c reconstructPar -latestTime
        setEntry $c system/controlDict endTime 0.15
        runCase $c
        grep -q "stored suspension of .*/0.1/uniform" "$work/$c/log.$solver" \
            || fail "$c: the serial run did not continue from 0.1"
        if [ $precision = 17 ]; then
            grep -q "Warning" "$work/$c"/log.$solver* && fail "a warning at writePrecision 17"
            expectSameParticles $c 0.15 $c.serial 1e-9
            byContact "$work/$c/0.15" > "$work/chain.contacts"
            byContact "$work/$c.serial/0.15" > "$work/serial.contacts"
            [ -s "$work/serial.contacts" ] || fail "no contacts at 0.15"
            sameNumbers "$work/chain.contacts" "$work/serial.contacts" 1e-9 \
                || fail "the contact history at 0.15 differs"
            awk '/^#/ || $1 > 0.1' "$work/$c.serial/postProcessing/rheology/0/rheology.dat" \
                > "$work/serial.rows"
            expectSameRheology "$work/$c/postProcessing/rheology/0.1/rheology.dat" \
                "$work/serial.rows" 1e-9
        else
            grep -q "writePrecision 10" "$work/$c/log.$solver.3" \
                || fail "no warning of the rounded state at writePrecision 10"
        fi
    done
    ;;

parallelSteadyState)
    # Over 8 strain units the decomposed run leaves the serial trajectory
    # (round-off grows) but keeps its statistics: the steady etaR of 3
    # packings (seeds 1-3) on 2 processes against the same 3 serially, the
    # means within 3 standard errors of their difference (from the runs'
    # scatter: at N = 100 a run's own block error bar is too small)
    steady()
    {
        awk '$1 == "etaR" && NF > 5 { print $2 }' \
            "$work/$1/postProcessing/rheology/0/rheologySummary.dat"
    }
    for seed in 1 2 3; do
        softDenseCase s$seed
        setEntry s$seed $properties population/seed $seed
        setEntry s$seed $properties contact/stiffness 1e5
        setEntry s$seed $properties integration/integrator implicitEuler
        setEntry s$seed system/controlDict endTime 8
        setEntry s$seed system/controlDict writeInterval 800
        inCase s$seed makeSuspension
        cp -r "$work/s$seed" "$work/p$seed"
        decomposeDict p$seed 2 1
        inCase p$seed decomposePar
        runParallel p$seed 2
        runCase s$seed
        echo "$(steady s$seed) $(steady p$seed)"
    done > "$work/etaR"
    cat "$work/etaR"
    awk '{ s[NR] = $1; p[NR] = $2; ms += $1/3; mp += $2/3; if ($1 == $2) same = 1 }
         END {
             for (k = 1; k <= 3; ++k) { vs += (s[k] - ms)^2/2; vp += (p[k] - mp)^2/2 }
             d = ms - mp; e = sqrt(vs/3 + vp/3)
             printf "parallelSteadyState: etaR serial %.3f, 2 processes %.3f, difference %.3f +/- %.3f\n", ms, mp, d, e
             exit !(d*d <= 9*e*e && !same && NR == 3)
         }' "$work/etaR" || fail "the steady etaR of 2 processes is not the serial one"
    ;;

parallelIncompleteTime)
    # A time incomplete on one processor (its state lost) is set aside on
    # every processor, and the run continues from the latest time complete
    # on all
    softDenseCase c
    inCase c makeSuspension
    decomposeDict c 2 1
    inCase c decomposePar
    runParallel c 2
    rm "$work/c/processor1/0.1/uniform/suspensionState"
    setEntry c system/controlDict endTime 0.15
    runParallel c 2
    log=$work/c/log.$solver.2
    grep -q "^\[1\] Time 0.1 is incomplete (no uniform/suspensionState" "$log" \
        || fail "processor1 did not set 0.1 aside"
    grep -q "^\[0\] Time 0.1 is incomplete (complete here, not on every processor)" "$log" \
        || fail "processor0 did not set 0.1 aside"
    grep -q "stored suspension of .*processor0/0.05/uniform" "$log" \
        || fail "the run did not continue from 0.05"
    for q in 0 1; do
        [ -d "$work/c/processor$q/0.1.incomplete" ] || fail "no processor$q/0.1.incomplete"
        grep -q "^files" "$work/c/processor$q/0.15/uniform/suspensionState" \
            || fail "no complete state at 0.15 on processor$q"
    done
    ;;

parallelRepeat)
    # The same decomposed run twice, the second stopped at 0.05 and
    # restarted from the processors' 0.05: bitwise the same
    softDenseCase c
    inCase c makeSuspension
    decomposeDict c 2 1
    inCase c decomposePar
    cp -r "$work/c" "$work/d"
    runParallel c 2
    setEntry d system/controlDict endTime 0.05
    runParallel d 2
    setEntry d system/controlDict endTime 0.1
    runParallel d 2
    grep -q "stored suspension of .*processor0/0.05/uniform" "$work/d/log.$solver.2" \
        || fail "the second run did not restart from 0.05"
    for f in "$work"/c/processor*/0.1/lagrangian/suspension/* \
        "$work"/c/processor*/0.1/uniform/suspensionState; do
        cmp -s "$f" "$work/d/${f#"$work"/c/}" || fail "${f#"$work"/c/} differs"
    done
    diff <(awk '!/^#/ && $1 > 0.05' "$work/c/postProcessing/rheology/0/rheology.dat") \
         <(awk '!/^#/' "$work/d/postProcessing/rheology/0.05/rheology.dat") > /dev/null \
        || fail "the rheology rows after the restart differ"
    ;;

parallelFailure)
    # The overlap runs away at one pair, on one process, and the run stops
    # on both
    runawayCase c
    inCase c makeSuspension
    decomposeDict c 2 1
    inCase c decomposePar
    rc=0
    (cd "$work/c" && timeout 120 bash -c "$(declare -f mpiRun); mpiRun 2 $solver" \
        > log.failed 2>&1) || rc=$?
    [ $rc = 0 ] && fail "the run did not stop"
    [ $rc = 124 ] && fail "the run hung"
    log=$work/c/log.failed
    grep -q "runaway overlap" "$log" || fail "no diagnostic"
    grep -q "last good state" "$log" || fail "no last good state reported"
    last=$(cd "$work/c/processor0" && ls -d 0.* | sort -g | tail -1)
    for q in 0 1; do
        end=$(cd "$work/c/processor$q" && ls -d 0.* | sort -g | tail -1)
        [ "$end" = "$last" ] || fail "processor$q ends at $end, not $last"
        grep -q "^files" "$work/c/processor$q/$last/uniform/suspensionState" \
            || fail "processor$q: no complete state at $last"
    done
    # A run to just after it continues from it
    setEntry c system/controlDict endTime "$(awk -v t="$last" 'BEGIN { print t + 0.01 }')"
    (cd "$work/c" && timeout 120 bash -c "$(declare -f mpiRun); mpiRun 2 $solver" \
        > log.continued 2>&1) || true
    grep -q "stored suspension of .*processor0/$last/uniform" "$work/c/log.continued" \
        || fail "the run did not continue from $last"
    ;;

parallelPacking)
    softDenseCase c
    decomposeDict c 2 1
    setEntry c system/controlDict writePrecision 17
    cp -r "$work/c" "$work/serial"
    inCase c decomposePar
    runParallel c 2 makeSuspension
    runParallel c 2
    inCase c reconstructPar -withZero
    inCase serial makeSuspension
    inCase serial decomposePar
    runParallel serial 2
    inCase serial reconstructPar -withZero
    byId "$work/c/0" x > "$work/c.x"
    byId "$work/serial/0" x > "$work/serial.x"
    [ -s "$work/serial.x" ] || fail "no packing"
    sameNumbers "$work/c.x" "$work/serial.x" 1e-12 || fail "the packings differ"
    expectSameParticles c 0.1 serial 1e-12
    # A time decomposePar linked (each processor's uniform a link to the
    # case's): every process writes a state of its own, the case's stays
    rm -r "$work/c"/processor* "$work/c/0/lagrangian" "$work/c/0/uniform/suspensionState"
    inCase c decomposePar -time 0
    [ -L "$work/c/processor0/0/uniform" ] || fail "decomposePar did not link uniform"
    runParallel c 2 makeSuspension
    [ ! -e "$work/c/0/uniform/suspensionState" ] || fail "a process wrote into the case's uniform"
    for q in 0 1; do
        [ ! -L "$work/c/processor$q/0/uniform" ] || fail "processor$q/0/uniform is still a link"
        grep -q "^files" "$work/c/processor$q/0/uniform/suspensionState" \
            || fail "no complete state in processor$q/0"
    done
    ;;

parallelMeshSampled)
    softDenseCase m
    foamDictionary -entry ambientFlow -remove "$work/m/$properties" > /dev/null 2>&1 \
        || fail "cannot remove ambientFlow"
    printf '%s\n' "ambientFlow" "{" "    type meshSampled;" \
        "    flow { type wavyShear; shearRate 1; amplitude 2; periods 1; }" "}" \
        >> "$work/m/$properties"
    setEntry m system/controlDict writePrecision 17
    inCase m makeSuspension
    cp -r "$work/m" "$work/m.serial"
    decomposeDict m 2 1
    inCase m decomposePar
    runParallel m 2
    grep -q "Selecting ambientFlow meshSampled" "$work/m/log.$solver.2" \
        || fail "the parallel run did not sample the flow on the mesh"
    inCase m reconstructPar
    runCase m.serial
    for t in 0.05 0.1; do
        expectSameParticles m $t m.serial 1e-9
        sameNumbers "$work/m/postProcessing/profiles/$t/profiles.dat" \
            "$work/m.serial/postProcessing/profiles/$t/profiles.dat" 1e-9 \
            || fail "profiles at $t"
    done
    expectSameRheology "$work/m/postProcessing/rheology/0/rheology.dat" \
        "$work/m.serial/postProcessing/rheology/0/rheology.dat" 1e-9
    ;;

parallelInput)
    softDenseCase c
    inCase c makeSuspension
    decomposeDict c 2 1
    inCase c decomposePar
    # expectParallelError <what> <text>...: the solver on 2 processes stops
    # before any step with a log naming each text
    expectParallelError()
    {
        if (cd "$work/c" && mpiRun 2 $solver > log.bad 2>&1); then
            fail "$solver accepted $1"
        fi
        shift
        for text in "$@"; do
            grep -qF -- "$text" "$work/c/log.bad" || fail "the error does not name '$text'"
        done
        grep -q "^strain " "$work/c/log.bad" && fail "time steps were taken"
        return 0
    }
    sed -i 's/^method .*/method          scotch;/' "$work/c/system/decomposeParDict"
    expectParallelError "method scotch" "FOAM FATAL IO ERROR" decomposeParDict "'method' = scotch"
    decomposeDict c 2 1
    sed -i 's/(1 2 1)/(2 1 1)/' "$work/c/system/decomposeParDict"
    expectParallelError "n (2 1 1)" "FOAM FATAL IO ERROR" decomposeParDict "coeffs/n"
    # A mesh of 3 cells in y cut in 2: the cut is not the slabs'
    rm -r "$work/c"
    softDenseCase c
    setBlocks c "(4 3 4)"
    mesh c
    inCase c makeSuspension
    decomposeDict c 2 1
    inCase c decomposePar
    expectParallelError "a mesh off the slabs" "FOAM FATAL IO ERROR" decomposeParDict "not its slab" "multiple of 2"
    ;;

legacyContacts)
    # A time of an earlier version, its contact history in
    # lagrangian/suspensionContacts (idI, idJ, xiT, xiR; some pairs stored
    # the other way round, their stretches negated): the restart from it
    # continues bitwise as from the time itself
    softDenseCase a
    runCase a
    mkdir "$work/b"
    cp -r "$work/a/constant" "$work/a/system" "$work/a/0" "$work/a/0.05" "$work/b"
    cloud=$work/b/0.05/lagrangian/suspension
    old=$work/b/0.05/lagrangian/suspensionContacts
    mkdir "$old"
    byContact "$work/a/0.05" \
      | awk '{ if (NR % 2) print; else printf "%s %s %.17g %.17g %.17g %.17g %.17g %.17g\n",
               $2, $1, -$3, -$4, -$5, -$6, -$7, -$8 }' > "$work/contacts"
    [ -s "$work/contacts" ] || fail "no contacts at 0.05"
    # legacyField <name> <class> <awk print of a line>
    legacyField()
    {
        {
            echo "FoamFile { version 2.0; format ascii; class $2; object $1; }"
            wc -l < "$work/contacts"
            echo "("
            awk "{ $3 }" "$work/contacts"
            echo ")"
        } > "$old/$1"
    }
    legacyField idI labelField 'print $1'
    legacyField idJ labelField 'print $2'
    legacyField xiT vectorField 'printf "(%s %s %s)\n", $3, $4, $5'
    legacyField xiR vectorField 'printf "(%s %s %s)\n", $6, $7, $8'
    rm "$cloud"/contactId "$cloud"/contactXiT "$cloud"/contactXiR
    # The digests removed as written (foamDictionary would round the rest)
    state=$work/b/0.05/uniform/suspensionState
    awk '/^files/ { skip = 1 } !skip { print } skip && /^}/ { skip = 0 }' \
        "$state" > "$state.edited"
    mv "$state.edited" "$state"
    grep -q "^files" "$state" && fail "the digests are still there"
    runCase b
    grep -q "stored suspension of .*0.05/uniform" "$work/b/log.$solver" \
        || fail "the restart did not read the stored suspension"
    for f in "$work"/a/0.1/lagrangian/suspension/*; do
        cmp -s "$f" "$work/b/0.1/lagrangian/suspension/${f##*/}" \
            || fail "0.1/lagrangian/suspension/${f##*/} differs"
    done
    ;;

outputEntry)
    newCase c
    foamDictionary -entry output -add "{ rheologyInterval 1; }" \
        "$work/c/$properties" > /dev/null 2>&1
    expectInputError c suspensionProperties "rheologyInterval" \
        suspensionRheology writeInterval profileBins suspensionProfiles
    ;;

*)
    echo "unknown test $test" >&2
    exit 2
    ;;
esac

echo "PASSED ($test)"

#------------------------------------------------------------------------------
