#!/usr/bin/env bash
#------------------------------------------------------------------------------
# Every tutorial (wavyShearFoam and suspensionCoupledFoam) run serially
# (./Allrun) and on 2 processes
# (./Allrun-parallel: decomposePar, mpirun, reconstructPar) from the same
# packing, over its first STEPS sampling intervals: the largest relative
# difference of each rheology column and of the particles' x and u at the
# last time, and the contact counts (issue 32; docs/parallel.md).
#   docs/validation/parallel-tutorials.sh [STEPS]
# Writes parallel-tutorials.csv here. Run as root: OpenMPI is allowed to.
#------------------------------------------------------------------------------
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
. "$root/etc/bashrc"
steps=${1:-10}
work=$(mktemp -d "${TMPDIR:-/tmp}/parallelTutorials.XXXXXX")
trap 'rm -rf "$work"' EXIT
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out="$here/parallel-tutorials.csv"
echo "tutorial,rows,last_time,max_rel_etaR,max_rel_sigma,max_rel_N1,max_rel_x,max_rel_u,contacts_serial,contacts_parallel,serial_s,parallel_s" > "$out"

# The entries of an ascii cloud field, one per line, by origId
byId()
{
    paste <(awk '/^\($/ { on = 1; next } /^\)$/ { on = 0 } on' "$1/origId") \
          <(awk '/^\($/ { on = 1; next } /^\)$/ { on = 0 } on' "$1/$2" | tr -d '()') | sort -n
}

for tutorial in "$root"/tutorials/*/*/; do
    tutorial=${tutorial%/}
    [ -x "$tutorial/Allrun-parallel" ] || continue
    name=${tutorial#"$root/tutorials/"}
    for mode in serial parallel; do
        c="$work/${name//\//-}.$mode"
        cp -r "$tutorial" "$c"
        dt=$(foamDictionary -entry deltaT -value "$c/system/controlDict")
        end=$(awk -v d="$dt" -v n="$steps" 'BEGIN { printf "%.12g", d*n }')
        foamDictionary -entry endTime -set "$end" "$c/system/controlDict" > /dev/null
        foamDictionary -entry writeInterval -set "$steps" "$c/system/controlDict" > /dev/null
        foamDictionary -entry writeControl -set timeStep "$c/system/controlDict" > /dev/null
        foamDictionary -entry writeFormat -set ascii "$c/system/controlDict" > /dev/null
        start=$(date +%s.%N)
        if [ $mode = serial ]; then (cd "$c" && ./Allrun > /dev/null); else (cd "$c" && ./Allrun-parallel > /dev/null); fi
        awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f\n", e - s }' > "$c.seconds"
    done
    s="$work/${name//\//-}.serial"
    p="$work/${name//\//-}.parallel"
    last=$(cd "$s" && foamListTimes -latestTime 2>/dev/null | tail -1)
    [ -d "$p/$last" ] || { echo "$name: no $last on 2 processes" >&2; exit 1; }
    dat=$(ls "$s"/postProcessing/rheology/0/rheology.dat)
    cols=$(python3 - "$dat" "${dat/$s/$p}" <<'PY'
import sys
def rows(f):
    head = None; out = []
    for line in open(f):
        if line.startswith('# Time'): head = line[1:].split()
        elif not line.startswith('#'): out.append([float(v) for v in line.split()])
    return head, out
h, a = rows(sys.argv[1]); _, b = rows(sys.argv[2])
assert len(a) == len(b), (len(a), len(b))
def rel(name):
    k = h.index(name)
    return max(abs(x[k] - y[k])/max(abs(x[k]), 1e-300) for x, y in zip(a, b))
print(f"{len(a)},{rel('etaR'):.2e},{rel('sigma'):.2e},{rel('N1'):.2e}")
PY
)
    diffs=$(for f in x U; do
        paste <(byId "$s/$last/lagrangian/suspension" $f) <(byId "$p/$last/lagrangian/suspension" $f) \
          | awk '{ for (k = 2; k <= 4; ++k) { d = $k - $(k + 4); d = d < 0 ? -d : d; s = $k < 0 ? -$k : $k
                   if (s > m) m = s; if (d > dm) dm = d } } END { printf "%.2e,", dm/m }'
    done)
    nc() { foamDictionary -entry nContacts -value "$1/$last/uniform/suspensionState"; }
    echo "$name,${cols%%,*},$last,${cols#*,},${diffs}$(nc "$s"),$(nc "$p"),$(cat "$s.seconds"),$(cat "$p.seconds")" | tee -a "$out"
done
