#!/bin/sh
# ctest extensibility.registryTakesANewModel: the registry of this tree takes
# the model of this folder by registerModel.sh (header, registry line,
# test), and the pair loop (forces/ForceField.C) and the model's test then
# compile (syntax only: seconds). addModel.sh builds, tests and runs the
# whole code with it.
#
#   registryCheck.sh PROJECT_DIR CXX EIGEN_INCLUDE_DIR
set -eu
project=$1 cxx=$2 eigen=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/registryCheck.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/src" "$work/tests/suspension"
cp -r "$project/src/suspension" "$work/src/"
bash "$project/tests/extensibility/registerModel.sh" "$work"
grep -q HarmonicRepulsion "$work/src/suspension/forces/ForceModels.H"
for f in "$work/src/suspension/forces/ForceField.C" \
         "$work/tests/suspension/testHarmonicRepulsion.C"
do
    "$cxx" -std=c++17 -fopenmp -fsyntax-only -I "$work/src/suspension" \
        -I "$eigen" "$f"
done
