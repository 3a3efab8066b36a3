#!/bin/bash
# Extensibility check: add a pair model to a scratch copy of this checkout
# exactly as the user guide's "Adding a force model" says (registerModel.sh:
# the header HarmonicRepulsion.H, its registry line, its test), and show that
# nothing else has to change: the diff of the copy, a build of everything
# (./Allwmake), every other ctest test, and a case run with the model on whose
# rheology has the model's own column. Minutes (a full build); not part of
# ctest.
#
#   tests/extensibility/addModel.sh [SCRATCH_DIR]
#
# SCRATCH_DIR (default ${TMPDIR:-/tmp}/wsf-addModel, emptied first) holds the
# copy (src/), its OpenFOAM user directory (home/: the copy's libraries and
# programs go there, not to this checkout's $FOAM_USER_LIBBIN) and the case
# (case/). Exits non-zero at the first step that fails.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
scratch=${1:-${TMPDIR:-/tmp}/wsf-addModel}
jobs=${JOBS:-$(nproc)}
rm -rf "$scratch"
mkdir -p "$scratch/src" "$scratch/home"
scratch=$(cd "$scratch" && pwd)
src=$scratch/src

# The checkout as it is (tracked and new files, not the build)
(cd "$root" && git ls-files -z --cached --others --exclude-standard \
    | xargs -0 tar -c -f - 2>/dev/null) | tar -x -C "$src"
git -C "$src" init -q
git -C "$src" add -A
git -C "$src" -c user.name=check -c user.email=check@localhost commit -q -m base

"$here/registerModel.sh" "$src"
git -C "$src" add -A
echo "== the change (git diff --stat of the copy)"
git -C "$src" diff --cached --stat
git -C "$src" diff --cached -- src/suspension/forces/ForceModels.H

# In the copy's own environment: OpenFOAM's user directory under home/
inCopy()
{
    env -i HOME="$scratch/home" USER="$(id -un)" PATH=/usr/local/bin:/usr/bin:/bin \
        WSF_ARCH_FLAGS="${WSF_ARCH_FLAGS--march=native}" \
        bash -c '. "$1"/etc/bashrc > /dev/null && cd "$2" && shift 2 && "$@"' \
        _ "$src" "$@"
}

echo "== build (log: $scratch/build.log)"
inCopy "$src" ./Allwmake -j"$jobs" > "$scratch/build.log" 2>&1 \
    || { tail -30 "$scratch/build.log" >&2; echo "the copy does not build" >&2; exit 1; }

echo "== docs/models.md, generated from the registry (suspensionModels)"
inCopy "$src" sh -c 'suspensionModels > docs/models.md'
git -C "$src" diff --stat -- docs/models.md

# Every test but extensibility.registryTakesANewModel, which adds the model
# to a tree that does not have it yet (the copy has it now)
echo "== ctest (log: $scratch/ctest.log)"
inCopy "$src" ctest --test-dir build -j"$jobs" -E '^extensibility[.]' \
    > "$scratch/ctest.log" 2>&1 \
    || { grep -E "tests passed|Failed|\*\*\*" "$scratch/ctest.log" >&2; exit 1; }
grep "tests passed" "$scratch/ctest.log"
grep -q "HarmonicRepulsion.TwoSpheresThroughThePairLoop" "$scratch/ctest.log" \
    || { echo "the model's test did not run" >&2; exit 1; }

echo "== a case with the model on (tests/suspensionFoam/tiny)"
case=$scratch/case
cp -r "$src/tests/suspensionFoam/tiny" "$case"
cat >> "$case/constant/suspensionProperties" <<'DICT'

harmonicRepulsion
{
    active      true;
    stiffness   100;
    range       0.1;
}
DICT
inCopy "$case" sh -c 'foamDictionary -entry endTime -set 0.02 system/controlDict > /dev/null
    makeSuspension -boxOnly > log.makeBox 2>&1 && blockMesh > log.blockMesh 2>&1 \
    && makeSuspension > log.makeSuspension 2>&1 && wavyShearFoam > log.wavyShearFoam 2>&1' \
    || { tail -20 "$case"/log.* >&2; echo "the case did not run" >&2; exit 1; }
grep -m1 "harmonicRepulsion" "$case/log.wavyShearFoam" \
    || { echo "the start-up log does not name the model" >&2; exit 1; }
dat=$case/postProcessing/rheology/0/rheology.dat
awk '/^# Time/ { for (k = 2; k <= NF; ++k) if ($k == "etaR_harmonic") c = k - 1; next }
     /^#/ { next }
     { n++; if ($c + 0 != 0) nz++ }
     END {
         if (!c) { print "rheology.dat has no column etaR_harmonic"; exit 1 }
         printf "rheology.dat: etaR_harmonic non-zero in %d of %d rows\n", nz, n
         exit !(nz > 0)
     }' "$dat"
echo "== the model was added by its header, its registry line and its test"
