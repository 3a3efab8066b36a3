#!/usr/bin/env bash
# The serial cost of the decomposition's bookkeeping (issue 32): this
# tree's suspensionBenchmark against another build's, alternated, one thread.
#   docs/performance/serial-overhead.sh OTHER_BIN [PAIRS]
# OTHER_BIN: the other build's suspensionBenchmark (run with its own
# library: env -u LD_LIBRARY_PATH). Writes serial-overhead.csv here.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
other=$1
pairs=${2:-5}
out="$here/serial-overhead.csv"
export OMP_NUM_THREADS=1
echo "pair,build,integrator,ns_per_particle_step,pairs_ns,user_s" > "$out"
run() # build binary integrator steps
{
    local t row
    t=$( { /usr/bin/time -f "%U" env -u LD_LIBRARY_PATH "$2" -case table3 -N 4096 \
            -integrator "$3" -steps "$4" > /tmp/serialOverhead.row; } 2>&1 | tail -1)
    row=$(tail -1 /tmp/serialOverhead.row)
    echo "$p,$1,$3,$(echo "$row" | cut -d, -f13),$(echo "$row" | cut -d, -f27),$t" >> "$out"
}
# Alternated: odd pairs run this build first, even pairs the other
for p in $(seq 1 "$pairs"); do
    for integrator in velocityVerlet:200 implicitEuler:60; do
        if (( p % 2 )); then order="this other"; else order="other this"; fi
        for b in $order; do
            if [ "$b" = this ]; then bin="$(command -v suspensionBenchmark)"; else bin=$other; fi
            run "$b" "$bin" "${integrator%%:*}" "${integrator##*:}"
        done
    done
done
# Medians per build and integrator
python3 - "$out" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for integrator in sorted({r["integrator"] for r in rows}):
    for b in ("this", "other"):
        sel = [r for r in rows if r["integrator"] == integrator and r["build"] == b]
        med = {k: statistics.median(float(r[k]) for r in sel)
               for k in ("ns_per_particle_step", "pairs_ns", "user_s")}
        print(f"{integrator:15s} {b:6s} median ns/particle-step {med['ns_per_particle_step']:.1f}"
              f"  pairs ns {med['pairs_ns']:.1f}  user s {med['user_s']:.2f}  ({len(sel)} runs)")
PY
