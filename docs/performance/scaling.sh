#!/bin/bash
#------------------------------------------------------------------------------
# CPU per strain against N for Table 1 FR (tutorials/uniformShear/frictional:
# phi = 0.5, mu_C = 1, delta_lub = 0.05, implicitEuler), one thread.
#
#   docs/performance/scaling.sh [reps] [N ...]        (default: 3, 1000 4000)
#
# Each N is run once from its packing to strain 0.2 (runCase, restartable),
# then, per repetition, a copy of that state from 0.2 to 0.4 under
# /usr/bin/time -v, the N alternated within a repetition (paired on the
# shared machine). Rows (user + sys CPU s per strain, wall, peak RSS, steps
# per strain, mean CG iterations of the window) go to
# docs/performance/scaling.csv.
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" && . "$root/etc/caseFunctions" || exit 1
reps=${1:-3}
[ $# -gt 0 ] && shift
Ns=${*:-"1000 4000"}
runRoot=${WSF_PERFORMANCE_DIR:-$root/run/performance}/scaling
csv=$root/docs/performance/scaling.csv
from=0.2 to=0.4

for N in $Ns; do
    runCase "$runRoot/N$N" "$root/tutorials/uniformShear/frictional" $from 0.01 \
        population/nParticles=$N || exit 1
done

echo "N,rep,cpu_s_per_strain,wall_s_per_strain,peak_rss_MB,steps_per_strain,mean_cg_iterations,load1" > "$csv"
for rep in $(seq 1 "$reps"); do
    for N in $Ns; do
        w=$runRoot/N$N-window
        rm -rf "$w" && cp -r "$runRoot/N$N" "$w" && rm -rf "$w"/postProcessing "$w"/log.*
        setEntry "$w/system/controlDict" endTime $to || exit 1
        load=$(cut -d' ' -f1 /proc/loadavg)
        (cd "$w" && /usr/bin/time -v -o time.txt wavyShearFoam > log.wavyShearFoam 2>&1) \
            || { echo "scaling.sh: $w failed" >&2; exit 1; }
        awk -v N=$N -v rep=$rep -v span="$(awk -v a=$from -v b=$to 'BEGIN { print b - a }')" \
            -v load="$load" '
            FILENAME ~ /time.txt/ {
                if (/User time/) cpu += $NF
                if (/System time/) cpu += $NF
                if (/Elapsed/) { n = split($NF, t, ":"); wall = 0
                    for (i = 1; i <= n; i++) wall = 60*wall + t[i] }
                if (/Maximum resident/) rss = $NF/1024
                next
            }
            /^# Time/ { for (i = 1; i <= NF; i++) { if ($i == "steps") cs = i - 1
                                                     if ($i == "cgIterations") cc = i - 1 } }
            !/^#/ { if (!rows) { t0 = $1; s0 = $cs }   # steps: the total so far
                    t1 = $1; s1 = $cs; cg += $cc; rows++ }
            END { printf "%d,%d,%.2f,%.2f,%.0f,%.0f,%.1f,%s\n", N, rep, cpu/span,
                  wall/span, rss, (s1 - s0)/(t1 - t0), cg/rows, load }' \
            "$w/time.txt" "$w"/postProcessing/rheology/*/rheology.dat >> "$csv"
        tail -1 "$csv"
    done
done
