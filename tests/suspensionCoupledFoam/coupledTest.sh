#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Case tests of suspensionCoupledFoam on the tiny case next to this script
# (Table 1 FL spheres, N = 100, phi = 0.3, a mesh of 1 x 16 x 1 cells, three
# cyclic pairs). Each test runs in its own temporary copy.
#
#   coupledTest.sh <binDir> <WM_PROJECT_DIR> <test>
#
# Tests:
#   run           a coupled run with feedback and Kolmogorov forcing: every
#                 outer step's momentum residual below 1e-10 and its stress
#                 conserved to 1e-13 (the solver's own measure), and the
#                 written sigmaP integrates to the sum of the written
#                 particle stresslets S to 1e-8 (sigmaP has 10 digits); amplitude.dat, profile.dat and the fields
#                 U, Uprime, sigmaP, sigmaPRelaxed, alphaP at the write
#                 times; the state lists Uprime and sigmaPRelaxed; the mean
#                 of phi across y is the packing's; suspensionPlot draws
#                 coupling.png and amplitude.png
#   particleFree  feedback off: u' on 8, 16 and 32 cells against
#                 F/(eta0 k^2) sin(k y) converges at second order (error
#                 ratios 3.8 to 4.2), and the flow the particles see (Uinf
#                 of suspensionFields, at the cell centres) is
#                 gammaDot y + u'
#   oneWay        feedback off and no force: the coupled run is bitwise the
#                 wavyShearFoam run in uniform shear from the same packing
#                 (u' stays exactly 0, so the engine is never told of a
#                 change and samples gammaDot y exactly)
#   restart       a coupled run restarted from a written time matches the
#                 uninterrupted run bitwise: particles, contact history,
#                 Uprime, sigmaPRelaxed, the amplitude rows
#   incompleteFlow
#                 a latest time whose Uprime is truncated is incomplete: the
#                 restart sets it aside and writes it anew, bitwise as before
#   parallel      decomposed on 2 processes in y (the mesh of 1 x 16 x 1
#                 cells) and on 2 x 2 (2 x 16 x 2 cells), against the
#                 serial run: particles, Uprime and sigmaPRelaxed at each
#                 write, the amplitude and profile rows, to 1e-9
#   parallelRestart
#                 2 processes to 0.05, reconstructed, decomposed for 4 to
#                 0.1, reconstructed: the uninterrupted serial run to 1e-9
#   notPeriodic, unknownForce, badCouplingStrain, narrowKernel,
#   meshNotSpanning, wrongFlow, halfStoredFlow
#                 one bad input each: a FatalIOError naming the file and the
#                 entry (or patch), before any time step
#------------------------------------------------------------------------------
set -euo pipefail

binDir=$1
export WM_PROJECT_DIR=$2
test=$3
export PATH="$binDir:$PATH"
export LD_LIBRARY_PATH="$binDir/../lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OMP_NUM_THREADS=1
export OMP_WAIT_POLICY=PASSIVE

here=$(cd "$(dirname "$0")" && pwd)
source=$here/tiny
work=$(mktemp -d "${TMPDIR:-/tmp}/coupledTest.XXXXXX")
[ -n "${WSF_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
solver=suspensionCoupledFoam
. "$here/../caseTestFunctions.sh"

# Copy the tiny case to $work/$1 (with the cells $2, "(nx ny nz)", and
# the writePrecision $3, if given), mesh it, pack it
newCase()
{
    cp -r "$source" "$work/$1"
    [ -z "${2:-}" ] || setBlocks "$1" "$2"
    [ -z "${3:-}" ] || setEntry "$1" system/controlDict writePrecision "$3"
    (
        cd "$work/$1"
        makeSuspension -boxOnly > log.makeBox 2>&1
        blockMesh > log.blockMesh 2>&1
        makeSuspension > log.makeSuspension 2>&1
    ) || fail "setting up case $1"
}

runCoupled()
{
    (cd "$work/$1" && suspensionCoupledFoam > log.suspensionCoupledFoam 2>&1) \
        || fail "suspensionCoupledFoam $1"
}

values() { python3 "$here/fieldValues.py" "$@"; }

# Cases $1 and $2 at times $3...: the particles, the flow's state (Uprime,
# sigmaPRelaxed) and the profile rows the same to 1e-9, and the amplitude
# rows of those times
expectSameFlow()
{
    local a=$1 b=$2 t f
    shift 2
    for t in "$@"; do
        expectSameParticles $a $t $b 1e-9
        for f in Uprime sigmaPRelaxed; do
            values "$work/$a/$t/$f" > "$work/$a.$t.$f"
            values "$work/$b/$t/$f" > "$work/$b.$t.$f"
            sameNumbers "$work/$a.$t.$f" "$work/$b.$t.$f" 1e-9 \
                || fail "$f at $t of $a differs from $b's"
        done
        rows "$work/$a/postProcessing/coupling/$t/profile.dat" > "$work/$a.$t.profile"
        rows "$work/$b/postProcessing/coupling/$t/profile.dat" > "$work/$b.$t.profile"
        sameNumbers "$work/$a.$t.profile" "$work/$b.$t.profile" 1e-9 \
            || fail "the profile at $t of $a differs from $b's"
        cat "$work/$a"/postProcessing/coupling/*/amplitude.dat \
            | awk -v t=$t '!/^#/ && ($1 - t)^2 < 1e-20' > "$work/$a.$t.amplitude"
        awk -v t=$t '!/^#/ && ($1 - t)^2 < 1e-20' "$work/$b/postProcessing/coupling/0/amplitude.dat" \
            > "$work/$b.$t.amplitude"
        [ -s "$work/$b.$t.amplitude" ] || fail "no amplitude row at $t in $b"
        sameNumbers "$work/$a.$t.amplitude" "$work/$b.$t.amplitude" 1e-9 \
            || fail "the amplitude at $t of $a differs from $b's"
    done
}

properties=constant/suspensionProperties
coupling=constant/couplingProperties
control=system/controlDict

case "$test" in
run)
    newCase a
    runCoupled a
    log=$work/a/log.suspensionCoupledFoam
    [ "$(grep -c '^coupling ' "$log")" -eq 11 ] || fail "not 11 coupling lines"
    awk '/^coupling / {
            for (i = 1; i < NF; ++i) {
                if ($i == "residual" && $(i + 1) > 1e-10) bad = "residual " $(i + 1)
                if ($i == "to" && $(i + 1) > 1e-13) bad = "conservation " $(i + 1)
            }
         } END { if (bad) { print bad; exit 1 } }' "$log" \
        || fail "the momentum balance or the stress conservation"
    rows=$(grep -vc '^#' "$work/a/postProcessing/coupling/0/amplitude.dat")
    [ "$rows" -eq 10 ] || fail "amplitude.dat has $rows rows, not 10"
    for t in 0.05 0.1; do
        for f in U Uprime sigmaP sigmaPRelaxed alphaP; do
            [ -f "$work/a/$t/$f" ] || fail "no $t/$f"
        done
        [ "$(grep -vc '^#' "$work/a/postProcessing/coupling/$t/profile.dat")" -eq 16 ] \
            || fail "profile.dat of $t has not 16 rows"
        for f in Uprime sigmaPRelaxed; do
            grep -q "^ *$f$" "$work/a/$t/uniform/suspensionState" \
                || fail "the state of $t does not list $f"
        done
    done
    # The spread stress integrates to the particles' stresslets: sigmaP of
    # the function object (cells of equal volume, 10 digits) against the
    # cloud's S (17 digits), both of time 0.1
    python3 - "$work/a" <<'PY' || fail "the integral of sigmaP is not the particles' sum"
import re, sys
case = sys.argv[1]
box = open(case + "/constant/particleBox").read()
L = [float(re.search(k + r"\s+([0-9.e+-]+);", box).group(1)) for k in ("Lx", "Ly", "Lz")]
def tensors(path, start):
    text = open(path).read()
    text = text[text.index(start):] if start else text
    return [[float(x) for x in t.split()] for t in re.findall(r"\(([^()]*)\)", text)
            if len(t.split()) == 6]
cells = tensors(case + "/0.1/sigmaP", "internalField")[:16]
particles = tensors(case + "/0.1/lagrangian/suspension/S", "")
mesh = sum(c[1] for c in cells)*L[0]*L[1]*L[2]/len(cells)
total = sum(p[1] for p in particles)
print("integral of sigmaP_xy", mesh, "sum of S_xy", total)
sys.exit(0 if abs(mesh - total) <= 1e-8*abs(total) else 1)
PY
    # suspensionPlot draws the coupled flow
    if /usr/bin/python3 -c "import matplotlib" 2> /dev/null; then
        suspensionPlot -case "$work/a" > "$work/a/log.plot" 2>&1 || fail "suspensionPlot"
        for png in coupling amplitude; do
            f=$work/a/postProcessing/plots/$png.png
            [ "$(head -c 8 "$f" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] \
                || fail "suspensionPlot wrote no $png.png"
        done
    fi
    # phi integrates to the packing's (the spread volumes are conserved)
    awk '!/^#/ { s += $9; n++ } END { if (s/n < 0.299 || s/n > 0.301) exit 1 }' \
        "$work/a/postProcessing/coupling/0.1/profile.dat" \
        || fail "the mean of phi across y is not 0.3"
    ;;

particleFree)
    errors=""
    for n in 8 16 32; do
        cp -r "$source" "$work/n$n"
        sed -i "s/(1 16 1)/(1 $n 1)/" "$work/n$n/system/blockMeshDict"
        setEntry n$n $coupling feedback off
        setEntry n$n $control endTime 0.01
        setEntry n$n $control writeInterval 1
        setEntry n$n $control writePrecision 17     # Uinf, written by suspensionFields
        (
            cd "$work/n$n"
            makeSuspension -boxOnly > log.makeBox 2>&1
            blockMesh > log.blockMesh 2>&1
            makeSuspension > log.makeSuspension 2>&1
        ) || fail "setting up n$n"
        runCoupled n$n
        Ly=$(awk '$1 == "Ly" { sub(/;/, "", $2); print $2 }' "$work/n$n/constant/particleBox")
        F=$(awk '$1 == "amplitude" { sub(/;/, "", $2); print $2 }' "$work/n$n/$coupling")
        err=$(paste <(values "$work/n$n/0.01/Uprime" 0) \
                    <(values "$work/n$n/0.01/Uinf" 0) \
            | awk -v n=$n -v Ly=$Ly -v F=$F '
                { j = NR - 1; y = (j + 0.5)*Ly/n; k = 2*3.14159265358979324/Ly
                  e = $1 - F/(k*k)*sin(k*y); if (e < 0) e = -e; if (e > m) m = e
                  d = $2 - (y + $1); if (d < 0) d = -d; if (d > dmax) dmax = d }
                END { if (dmax > 1e-10) { print "seen " dmax; exit 1 } print m }') \
            || fail "the particles do not see gammaDot y + u' on $n cells: $err"
        errors="$errors $err"
    done
    echo "max |u' - F/(k^2) sin(ky)| on 8, 16, 32 cells:$errors"
    echo "$errors" | awk '{ r1 = $1/$2; r2 = $2/$3; print "ratios", r1, r2
        if (r1 < 3.8 || r1 > 4.2 || r2 < 3.8 || r2 > 4.2) exit 1 }' \
        || fail "not second order:$errors"
    ;;

oneWay)
    newCase coupled
    setEntry coupled $coupling feedback off
    foamDictionary -entry bodyForce -remove "$work/coupled/$coupling" > /dev/null
    foamDictionary -entry bodyForce -set "{ type none; }" "$work/coupled/$coupling" > /dev/null
    cp -r "$work/coupled" "$work/oneWay"
    rm -f "$work"/oneWay/log.*
    setEntry oneWay $control application wavyShearFoam
    foamDictionary -entry functions -set "{}" "$work/oneWay/$control" > /dev/null
    foamDictionary -entry ambientFlow -set "{ type uniformShear; shearRate 1; }" \
        "$work/oneWay/$properties" > /dev/null
    runCoupled coupled
    (cd "$work/oneWay" && wavyShearFoam > log.wavyShearFoam 2>&1) || fail "wavyShearFoam"
    for f in x U omega F T S; do
        cmp -s "$work/coupled/0.1/lagrangian/suspension/$f" \
               "$work/oneWay/0.1/lagrangian/suspension/$f" \
            || fail "lagrangian/suspension/$f differs from the one-way run"
    done
    values "$work/coupled/0.1/Uprime" 0 2>/dev/null | awk '$1 != 0 { exit 1 }' \
        || grep -q "uniform (0 0 0)" "$work/coupled/0.1/Uprime" \
        || fail "u' is not exactly 0"
    ;;

restart|incompleteFlow)
    newCase a
    runCoupled a
    mkdir "$work/b"
    cp -r "$work/a/constant" "$work/a/system" "$work/a/0" "$work/a/0.05" "$work/b"
    if [ "$test" = incompleteFlow ]; then
        cp -r "$work/a/0.1" "$work/b"
        head -c 400 "$work/a/0.1/Uprime" > "$work/b/0.1/Uprime"
    fi
    runCoupled b
    log=$work/b/log.suspensionCoupledFoam
    grep -q "stored suspension" "$log" || fail "the restart did not read the stored suspension"
    if [ "$test" = incompleteFlow ]; then
        grep -q "Uprime" "$log" && grep -q "0.1.incomplete" "$log" \
            || fail "the truncated Uprime did not set 0.1 aside"
        [ -d "$work/b/0.1.incomplete" ] || fail "no 0.1.incomplete"
    fi
    for f in lagrangian/suspension/x lagrangian/suspension/U \
        lagrangian/suspension/contactXiT Uprime sigmaPRelaxed; do
        cmp -s "$work/a/0.1/$f" "$work/b/0.1/$f" || fail "0.1/$f differs"
    done
    diff <(awk '!/^#/ && $1 > 0.05' "$work/a/postProcessing/coupling/0/amplitude.dat") \
         <(awk '!/^#/' "$work/b/postProcessing/coupling/0.05/amplitude.dat") > /dev/null \
        || fail "amplitude.dat rows differ"
    ;;

parallel)
    for layout in "2 1" "2 2"; do
        c=p${layout/ /x}
        newCase $c "$([ "$layout" = "2 2" ] && echo "(2 16 2)" || echo "(1 16 1)")" 17
        cp -r "$work/$c" "$work/$c.serial"
        decomposeDict $c $layout
        inCase $c decomposePar
        runParallel $c $((${layout/ /*}))
        inCase $c reconstructPar
        runCoupled $c.serial
        expectSameFlow $c $c.serial 0.05 0.1
    done
    ;;

parallelRestart)
    newCase a "" 17
    cp -r "$work/a" "$work/a.serial"
    runCoupled a.serial
    setEntry a $control endTime 0.05
    decomposeDict a 2 1
    inCase a decomposePar
    runParallel a 2
    inCase a reconstructPar -latestTime
    rm -r "$work/a"/processor*
    setEntry a $control endTime 0.1
    decomposeDict a 4 1
    inCase a decomposePar -latestTime
    runParallel a 4
    grep -q "stored suspension of .*/0.05/uniform" "$work/a/log.$solver.4" \
        || fail "the 4 processes did not continue from 0.05"
    inCase a reconstructPar -latestTime
    expectSameFlow a a.serial 0.1
    ;;

notPeriodic)
    cp -r "$source" "$work/c"
    python3 - "$work/c/system/blockMeshDict" <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = re.sub(r"boundary\s*\(.*?\n\);", "boundary\n(\n);\n\ndefaultPatch { name box; type patch; }", s, flags=re.S)
open(p, "w").write(s)
PY
    (cd "$work/c" && makeSuspension -boxOnly > log.makeBox 2>&1 && blockMesh > log.blockMesh 2>&1) \
        || fail "meshing"
    expectInputError c "polyMesh/boundary" "Patch 'box'" "type patch"
    ;;

unknownForce)
    newCase c
    setEntry c $coupling bodyForce/type wobbly
    expectInputError c "couplingProperties" "wobbly" "kolmogorov"
    ;;

badCouplingStrain)
    newCase c
    setEntry c $coupling couplingStrain 0
    expectInputError c "couplingProperties" "couplingStrain"
    ;;

narrowKernel)
    newCase c
    setEntry c $coupling coarseGraining/width 2
    expectInputError c "couplingProperties" "width" "2.8"
    ;;

meshNotSpanning)
    cp -r "$source" "$work/c"
    (cd "$work/c" && makeSuspension -boxOnly > log.makeBox 2>&1) || fail "box"
    sed -i 's/^scale .*/scale   0.9;/' "$work/c/system/blockMeshDict"
    (cd "$work/c" && blockMesh > log.blockMesh 2>&1) || fail "meshing"
    expectInputError c "mesh bounds" "particle box"
    ;;

wrongFlow)
    newCase c
    foamDictionary -entry ambientFlow -set "{ type uniformShear; shearRate 1; }" \
        "$work/c/$properties" > /dev/null
    expectInputError c "suspensionProperties" "ambientFlow" "meshField"
    # stress control is not taken; a rate programme is (the oscillation
    # runs)
    newCase d
    foamDictionary -entry ambientFlow/shearRate -remove "$work/d/$properties" > /dev/null
    foamDictionary -entry ambientFlow/shearStress -add 5 "$work/d/$properties" > /dev/null
    setEntry d $properties integration/integrator implicitEuler
    expectInputError d "suspensionProperties" "not stress control (entry 'shearStress')"
    newCase e
    foamDictionary -entry ambientFlow/shearRate -set \
        "{ type oscillatory; strainAmplitude 0.01; omega 20; }" "$work/e/$properties" > /dev/null
    setEntry e $control endTime 0.02
    runCoupled e
    ;;

halfStoredFlow)
    newCase a
    setEntry a $control endTime 0.05
    runCoupled a
    rm "$work/a/0.05/sigmaPRelaxed"
    # the time is no longer complete; take it as made by hand
    foamDictionary -entry files -remove "$work/a/0.05/uniform/suspensionState" > /dev/null
    setEntry a $control endTime 0.1
    if (cd "$work/a" && suspensionCoupledFoam > log.second 2>&1); then
        fail "a time with Uprime but no sigmaPRelaxed was accepted"
    fi
    grep -q "FOAM FATAL IO ERROR" "$work/a/log.second" || fail "no FatalIOError"
    grep -qF "sigmaPRelaxed" "$work/a/log.second" || fail "the error does not name sigmaPRelaxed"
    ;;

*)
    echo "coupledTest.sh: unknown test $test" >&2
    exit 2
    ;;
esac

echo "PASSED ($test)"
