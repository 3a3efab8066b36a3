#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Soak run of the engine under AddressSanitizer and UndefinedBehaviorSanitizer
# (docs/robustness.md, "Soak"): the frictional tutorial's suspension (Table 1
# FR: N = 1000, phi = 0.5, implicitEuler) for STEPS steps with the sanitized
# suspensionBenchmark of build-sanitize/ (./Allwmake --sanitize builds it),
# every finding fatal. Appends a row to soak.csv next to this script: steps,
# wall seconds, exit status and the number of sanitizer reports in the log.
#   docs/robustness/soak.sh [STEPS] [N]        (default 100000 1000)
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
top="$(cd "$here/../.." && pwd)"
. "$top/etc/bashrc" > /dev/null 2>&1
steps=${1:-100000}
N=${2:-1000}
bench=$top/build-sanitize/platform/bin/suspensionBenchmark
[ -x "$bench" ] || (cd "$top" && ./Allwmake --sanitize > /dev/null)
log=$(mktemp "${TMPDIR:-/tmp}/soak.XXXXXX.log")
csv=$here/soak.csv
[ -f "$csv" ] || echo "date,commit,N,steps,wall_s,exit,reports,log" > "$csv"
start=$(date +%s)
set +e
env -u LD_LIBRARY_PATH OMP_NUM_THREADS=1 \
    ASAN_OPTIONS=detect_leaks=1:halt_on_error=1 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$bench" -case table1 -N "$N" -steps "$steps" -integrator implicitEuler \
    > "$log" 2>&1
status=$?
set -e
reports=$(grep -cE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$log" || true)
echo "$(date +%F),$(git -C "$top" rev-parse --short HEAD),$N,$steps,$(( $(date +%s) - start )),$status,$reports,$log" >> "$csv"
tail -n 3 "$log"
echo "soak: exit $status, $reports sanitizer reports ($log)"
[ "$status" = 0 ] && [ "$reports" = 0 ]
