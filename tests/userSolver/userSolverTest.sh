#!/usr/bin/env bash
#------------------------------------------------------------------------------
# A user's own solver: build tests/userSolver with wmake from its own
# Make/files and Make/options against the installed libraries (in a copy, its
# program in a temporary FOAM_USER_APPBIN), then run it on the tiny case of
# tests/suspensionFoam: it must select the flow, evolve the cloud and write.
#   userSolverTest.sh <projectDir>
#------------------------------------------------------------------------------
set -euo pipefail
project=$1
. "$project/etc/bashrc"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE

work=$(mktemp -d "${TMPDIR:-/tmp}/userSolverTest.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "FAILED: $*" >&2; tail -n 30 "$work"/log.* >&2 2>/dev/null || true; exit 1; }

cp -r "$project/tests/userSolver" "$work/src"
rm -rf "$work/src/Make/linux64"* "$work/src/userSolverTest.sh"
mkdir -p "$work/bin"
(cd "$work/src" && FOAM_USER_APPBIN="$work/bin" wmake > "$work/log.wmake" 2>&1) \
    || fail "wmake of the user solver"
[ -x "$work/bin/userSolver" ] || fail "no userSolver in the temporary FOAM_USER_APPBIN"

cp -r "$project/tests/suspensionFoam/tiny" "$work/case"
cd "$work/case"
makeSuspension -boxOnly > "$work/log.makeBox" 2>&1 || fail makeSuspension
blockMesh > "$work/log.blockMesh" 2>&1 || fail blockMesh
"$work/bin/userSolver" > "$work/log.userSolver" 2>&1 || fail "userSolver run"
grep -q "^userSolver: U at the centre (" "$work/log.userSolver" || fail "no flow sample in the log"
grep -q "^End" "$work/log.userSolver" || fail "no End"
# the case's function objects ran on the cloud of this solver too
[ "$(grep -vc '^#' postProcessing/rheology/0/rheology.dat)" -eq 4 ] \
    || fail "rheology.dat of the function object: not 4 rows"
ls 0.004/lagrangian/suspension/positions > /dev/null 2>&1 || fail "no cloud written at the end time 0.004"
echo "userSolver: built with wmake, ran and wrote the cloud"
