#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Cost of a stress-controlled step against a rate-controlled one
# (docs/rheometry.md): tutorials/rheometry/reversal (Table 1 FR, N = 200,
# phi = 0.5) run to its state at t = 5 (rate 1), then from that state 0.3
# time units at the rate 1 and at the stress 67 (about its sigma), one
# thread, alternated RUNS (5) times, /usr/bin/time -v of each whole process.
#
#   docs/rheometry/cost.sh [workDir]       (default: /tmp/rheometryCost)
#
# Writes cost.csv beside this script: per control the medians and ranges of
# CPU (user + system) and wall seconds and the paired CPU ratio.
#------------------------------------------------------------------------------
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=${1:-/tmp/rheometryCost}
runs=${RUNS:-5}
. "$root/etc/bashrc"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
mkdir -p "$work"
if [ ! -d "$work/start/5" ]; then
    rm -rf "$work/start"
    cp -r "$root/tutorials/rheometry/reversal" "$work/start"
    foamDictionary -entry endTime -set 5 "$work/start/system/controlDict" > /dev/null
    foamDictionary -entry writeInterval -set 500 "$work/start/system/controlDict" > /dev/null
    (cd "$work/start" && ./Allrun > /dev/null 2>&1)
fi
for c in rate stress; do
    rm -rf "${work:?}/$c"
    mkdir "$work/$c"
    cp -r "$work/start/constant" "$work/start/system" "$work/start/5" "$work/$c/"
    d=$work/$c/system/controlDict
    foamDictionary -entry startFrom -set startTime "$d" > /dev/null
    foamDictionary -entry startTime -set 5 "$d" > /dev/null
    foamDictionary -entry endTime -set 5.3 "$d" > /dev/null
    foamDictionary -entry writeInterval -set 100000 "$d" > /dev/null
    foamDictionary -entry functions -remove "$d" > /dev/null
    p=$work/$c/constant/suspensionProperties
    foamDictionary -entry ambientFlow/shearRate -remove "$p" > /dev/null
done
foamDictionary -entry ambientFlow/shearRate -add 1 "$work/rate/constant/suspensionProperties" > /dev/null
foamDictionary -entry ambientFlow/shearStress -add 67 "$work/stress/constant/suspensionProperties" > /dev/null
for k in $(seq "$runs"); do
    for c in rate stress; do
        (cd "$work/$c" && rm -rf 5.3 && /usr/bin/time -v wavyShearFoam > log 2> "time.$k")
    done
done
/usr/bin/python3 - "$work" "$runs" "$here/cost.csv" <<'PY'
import re, statistics, sys
work, runs, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
def figures(c, k):
    t = open("%s/%s/time.%d" % (work, c, k)).read()
    cpu = sum(float(re.search(r"%s time \(seconds\): ([0-9.]+)" % w, t).group(1)) for w in ("User", "System"))
    p = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([0-9:.]+)", t).group(1).split(":")
    wall = sum(float(x)*60**i for i, x in enumerate(reversed(p)))
    return cpu, wall
f = {c: [figures(c, k) for k in range(1, runs + 1)] for c in ("rate", "stress")}
steps = {c: re.search(r"over ([0-9]+) steps", open("%s/%s/log" % (work, c)).read()).group(1) for c in f}
ratio = [s[0]/r[0] for s, r in zip(f["stress"], f["rate"])]
with open(out, "w") as o:
    o.write("control,engine_steps,runs,cpu_s_median,cpu_s_min,cpu_s_max,wall_s_median,wall_s_min,wall_s_max,paired_cpu_ratio_median,paired_cpu_ratio_min,paired_cpu_ratio_max\n")
    for c in ("rate", "stress"):
        cpu = [x[0] for x in f[c]]; wall = [x[1] for x in f[c]]
        r = ("%.3f,%.3f,%.3f" % (statistics.median(ratio), min(ratio), max(ratio))) if c == "stress" else ",,"
        o.write("%s,%s,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%s\n" % (c, steps[c], runs, statistics.median(cpu), min(cpu), max(cpu),
                statistics.median(wall), min(wall), max(wall), r))
print(open(out).read())
PY
