#!/bin/bash
#------------------------------------------------------------------------------
# The solver of this tree against that of another built tree, paired: from
# the same kept write of a case, the same window, one thread each, the two
# alternated (this tree first) REPEATS times, each under /usr/bin/time -v in
# a fresh copy of the case holding only the start time.
#
#   docs/performance/solver-pair.sh CASE START END [REPEATS] [REFERENCE]
#   docs/performance/solver-pair.sh --threads CASE START END [REPEATS]
#
# --threads  pairs this tree on one thread against this tree on two (the
#            second labelled <commit>/2threads) instead of two trees
#
# CASE       a case with a write at START (e.g. sheared from its packing)
# START END  the window: startFrom latestTime at START, endTime END, one
#            write at the end
# REPEATS    pairs (default 5)
# REFERENCE  "HOME:TREE" of the other solver: a checkout TREE built with
#            ./Allwmake under HOME=HOME, so that its programs are not this
#            tree's (default /tmp/mainhome:/tmp/wsf-main)
#
# Appends to docs/performance/solver-pair.csv one row per run: commit,
# repeat, N, start, end, CPU s (user+sys), wall s, peak RSS kB of the whole
# process, engine steps, the solver's kernel times (ns per particle-step:
# all, implicit hydrodynamics, pair loop), mean CG iterations of the
# samples, etaR at END.
#------------------------------------------------------------------------------
set -eu
root=$(cd "${0%/*}/../.." && pwd)
. "$root/docs/performance/benchmarkFunctions"
threadsMode=false
if [ "${1:-}" = --threads ]; then threadsMode=true; shift; fi
case=$(cd "$1" && pwd); start=$2; end=$3; repeats=${4:-5}
reference=${5:-/tmp/mainhome:/tmp/wsf-main}
refHome=${reference%%:*}; refTree=${reference#*:}
csv=$root/docs/performance/solver-pair.csv
work=$(mktemp -d)
[ -f "$csv" ] || echo "commit,repeat,N,start,end,cpu_s,wall_s,maxrss_kB,steps,ns_per_particle_step,hydrodynamics_ns,pairLoop_ns,cg_iterations,etaR" > "$csv"
[ -d "$case/$start" ] || { echo "solver-pair.sh: no time $start in $case" >&2; exit 1; }

# run <label> <home> <tree> <repeat> [threads]
run()
{
    local label=$1 home=$2 tree=$3 r=$4 threads=${5:-1} c=$work/case
    rm -rf "$c"; mkdir -p "$c"
    cp -r "$case/constant" "$case/system" "$case/$start" "$c"
    (
        set +eu
        cd "$c"
        windowCase "$home" "$tree" "$end"
        OMP_NUM_THREADS=$threads OMP_WAIT_POLICY=PASSIVE /usr/bin/time -v \
            wavyShearFoam > log.wavyShearFoam 2> log.time
    ) || { echo "solver-pair.sh: $label failed, see $c" >&2; exit 1; }
    local dat=$c/postProcessing/rheology/$start/rheology.dat
    awk -F': ' -v label="$label" -v r="$r" -v s="$start" -v e="$end" \
        -v dat="$dat" -v solverLog="$c/log.wavyShearFoam" '
        /User time/ {u = $2} /System time/ {y = $2} /Maximum resident/ {m = $2}
        /Elapsed \(wall clock\)/ {n = split($2, t, ":"); w = 0; for (k = 1; k <= n; ++k) w = 60*w + t[k]}
        END {
            while ((getline line < solverLog) > 0) {
                if (line ~ /population/) { split(line, p, "N = "); split(p[2], q, ","); N = q[1] }
                nf = split(line, f, /[ \t]+/)
                if (f[2] == "hydrodynamics" || f[2] == "pairLoop") ns[f[2]] = f[5]
                if (f[2] == "total") { steps = f[6]; ns["total"] = f[8] }
            }
            while ((getline line < dat) > 0) {
                if (line ~ /^#/) { nh = split(line, h, /[ \t]+/); for (k = 1; k <= nh; ++k) col[h[k]] = k - 1; continue }
                split(line, f, /[ \t]+/); last = f[col["etaR"]]; cg += f[col["cgIterations"]]; ncg++
            }
            printf "%s,%s,%s,%s,%s,%.2f,%.2f,%s,%s,%.1f,%.1f,%.1f,%.2f,%s\n", label, r, N, s, e, u + y, w, m,
                steps, ns["total"], ns["hydrodynamics"], ns["pairLoop"], ncg ? cg/ncg : 0, last
        }' "$c/log.time" | tee -a "$csv"
}

this=$(git -C "$root" rev-parse --short HEAD)
git -C "$root" diff --quiet HEAD -- src || this=$this+changes
for r in $(seq "$repeats"); do
    run "$this" "$HOME" "$root" "$r"
    if $threadsMode; then
        run "$this/2threads" "$HOME" "$root" "$r" 2
    else
        run "$(git -C "$refTree" rev-parse --short HEAD)" "$refHome" "$refTree" "$r"
    fi
done
rm -rf "$work"
