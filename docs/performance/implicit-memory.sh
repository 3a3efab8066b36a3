#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Memory of the implicit step at the paper's size: this tree's engine (a
# Release build, ./Allwmake) against that of a reference commit, paired (A B
# A B ...), REPEATS pairs of
#   suspensionBenchmark -case table3 -N 65536 -steps 3 -attractionCutoff 4
#                       -integrator implicitEuler
# on one thread; appends to implicit-memory.csv next to this script (whole
# process under /usr/bin/time -v, then the benchmark's row, whose
# peak_rss_MB is read before its rebuild timings copy the state) and prints
# the medians of both peaks.
#   docs/performance/implicit-memory.sh [REPEATS] [REFERENCE-COMMIT]
# The reference defaults to ec362d2, the last before the diagonal blocks of
# the resistance were summed in setStep instead of kept per particle.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
. "$here/../../etc/bashrc" > /dev/null 2>&1
. "$here/benchmarkFunctions"
repeats=${1:-5}
commit=${2:-ec362d2}
new="$FOAM_USER_APPBIN/suspensionBenchmark"
ref=$(referenceBenchmark "$commit")
csv=$here/implicit-memory.csv
this=$(git -C "$WSF_PROJECT_DIR" rev-parse --short HEAD)
git -C "$WSF_PROJECT_DIR" diff --quiet HEAD -- src || this=$this+changes

rows=$(startCsv "$csv" engine,repeat,cpu_s,wall_s,time_v_max_rss_MB, "$new" -header)
args="-case table3 -N 65536 -steps 3 -attractionCutoff 4 -integrator implicitEuler"
for r in $(seq "$repeats"); do
    timedBenchmark "$csv" "$this" "$new" "$r" 1 $args > /dev/null
    timedBenchmark "$csv" "$commit" "$ref" "$r" 1 $args > /dev/null
done

# Medians over this invocation: whole process and the benchmark's peak
tail -n +"$rows" "$csv" | awk -F, -v h="$(head -1 "$csv")" "$awkMedian"'
    BEGIN { n = split(h, c, ","); for (k = 1; k <= n; ++k) if (c[k] == "peak_rss_MB") col = k
            if (!col) { print "implicit-memory.sh: no peak_rss_MB column" > "/dev/stderr"; exit 1 } }
    { m = ++count[$1]; w[$1, m] = $5; e[$1, m] = $col }
    END { for (name in count) {
              for (k = 1; k <= count[name]; ++k) { a[k] = w[name, k]; b[k] = e[name, k] }
              printf "%-8s whole process %.1f MB, engine %.1f MB (medians of %d)\n",
                  name, median(a, count[name]), median(b, count[name]), count[name] } }'
