#!/bin/bash
# Paired CPU timing of LF_DEM against wavyShearFoam for Table 1 FR of Monti et al. (2021)
# (N = 1000 bidisperse 1:1.4, equal volumes, phi = 0.5, mu = 1, lubrication to a gap 0.5,
# epsilon = 1e-3, k_hat = 4e5, kt/kn = 2/7, no rolling), both from the same packing.
#
#   run.sh [-r REPS] [-s START] [-e END] [-o OUTDIR]
#
# Environment:
#   LFDEM            LF_DEM binary (built by build.sh)           [required]
#
# Each "code" is LF_DEM (Euler, adaptive dt), ours with integrator overdamped, and ours with
# implicitEuler. Per repetition the codes run in turn (LF_DEM, overdamped, implicitEuler),
# each twice back to back: from strain 0 to START and from 0 to END. CPU per strain is
# (CPU(0..END) - CPU(0..START))/(END - START): set-up and the first START strain cancel
# (both codes are deterministic on one thread). Every run is one process on one thread,
# measured by /usr/bin/time -v; one run at a time.
# Output: OUTDIR/runs.csv (one row per timed run), OUTDIR/results.csv and
# OUTDIR/results.md (per repetition and medians, by summarise.py), run folders under OUTDIR/runs.
set -eo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
reps=5; start=0.05; end=0.2; out=$root/run/performance/lfdem
while getopts r:s:e:o: opt; do
    case $opt in
        r) reps=$OPTARG ;; s) start=$OPTARG ;; e) end=$OPTARG ;; o) out=$OPTARG ;;
        *) sed -n 2,25p "$0"; exit 1 ;;
    esac
done
LFDEM=${LFDEM:?set LFDEM to the LF_DEM binary built by build.sh}
WSF_PROJECT_DIR=$root
params=$here/lfdem_FR.txt
[ -x "$LFDEM" ] || { echo "no LF_DEM binary at $LFDEM (run build.sh)" >&2; exit 1; }
[ -x /usr/bin/time ] || { echo "needs /usr/bin/time (Debian package time)" >&2; exit 1; }

# Our environment (OpenFOAM + project); setEntry from etc/caseFunctions
set +eu
. "$WSF_PROJECT_DIR/etc/bashrc" > /dev/null 2>&1
. "$WSF_PROJECT_DIR/etc/caseFunctions"
set -e
command -v wavyShearFoam > /dev/null || { echo "wavyShearFoam not found after sourcing etc/bashrc" >&2; exit 1; }

mkdir -p "$out/runs"
out=$(cd "$out" && pwd)

# --- the packing: our frictional tutorial with lubrication delta 0.5, seed 1 -----------
base=$out/base
if [ ! -f "$base/setUpDone" ]; then
    rm -rf "$base"; mkdir -p "$base"
    cp -r "$WSF_PROJECT_DIR/tutorials/uniformShear/frictional/constant" \
          "$WSF_PROJECT_DIR/tutorials/uniformShear/frictional/system" "$base"
    d=$base/constant/suspensionProperties
    setEntry "$d" lubrication/delta 0.5
    setEntry "$d" integration/integrator overdamped
    setEntry "$d" population/seed 1
    (cd "$base" && makeSuspension -boxOnly > log.box 2>&1 && blockMesh > log.blockMesh 2>&1 \
        && makeSuspension > log.makeSuspension 2>&1)
    python3 "$here/foam2lfdem.py" "$base" "$base/lfdem_conf.dat"
    touch "$base/setUpDone"
fi

csv=$out/runs.csv
[ -f "$csv" ] || echo "rep,code,strain_end,user_s,sys_s,wall_s,maxrss_kB,load1,steps_total,steps_window,window_start,mean_cg_window,dir" > "$csv"

# timeRun <dir> <command...>: /usr/bin/time -v into <dir>/time.txt
timeRun()
{
    local dir=$1; shift
    (cd "$dir" && /usr/bin/time -v -o time.txt "$@" > log 2>&1)
}

# row <rep> <code> <strainEnd> <dir>: one CSV row from time.txt and the code's output
row()
{
    python3 "$here/summarise.py" --row "$1" "$2" "$3" "$4" "$start" >> "$csv"
}

runLfdem()   # <rep> <strainEnd>
{
    local dir=$out/runs/r$1_lfdem_$2
    rm -rf "$dir"; mkdir -p "$dir"
    cp "$base/lfdem_conf.dat" "$dir/conf.dat"
    { cat "$params"; echo "time_end = $2h;"; } > "$dir/params.txt"
    cat /proc/loadavg > "$dir/loadavg"
    OMP_THREAD_LIMIT=1 OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
        timeRun "$dir" "$LFDEM" -f -r 1h conf.dat params.txt
    row "$1" lfdem "$2" "$dir"
}

runOurs()    # <rep> <integrator> <strainEnd>
{
    local dir=$out/runs/r$1_$2_$3
    rm -rf "$dir"; mkdir -p "$dir"
    cp -r "$base/constant" "$base/system" "$base/0" "$dir"
    setEntry "$dir/constant/suspensionProperties" integration/integrator "$2"
    setEntry "$dir/system/controlDict" endTime "$3"
    cat /proc/loadavg > "$dir/loadavg"
    OMP_NUM_THREADS=1 timeRun "$dir" wavyShearFoam
    row "$1" "$2" "$3" "$dir"
}

for rep in $(seq 1 "$reps"); do
    for len in "$start" "$end"; do
        echo "rep $rep: LF_DEM to strain $len ($(date +%T))"; runLfdem "$rep" "$len"
    done
    for integ in overdamped implicitEuler; do
        for len in "$start" "$end"; do
            echo "rep $rep: ours $integ to strain $len ($(date +%T))"; runOurs "$rep" "$integ" "$len"
        done
    done
    tail -6 "$csv" | cut -d, -f1-8
done

python3 "$here/summarise.py" --summary "$csv" "$start" "$end" "$out/results.csv" > "$out/results.md"
cat "$out/results.md"
