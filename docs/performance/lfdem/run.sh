#!/bin/bash
# Paired CPU timing of LF_DEM against wavyShearFoam for Table 1 FR of Monti et al. (2021)
# (N = 1000 bidisperse 1:1.4, equal volumes, phi = 0.5, mu = 1, lubrication to a gap 0.5,
# epsilon = 1e-3, k_hat = 4e5, kt/kn = 2/7, no rolling), both from the same packing.
#
#   run.sh [-r REPS] [-s START] [-e END] [-b BASE] [-o OUTDIR]
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
# -b BASE (a whole number of strain units, default 0): every code starts from the state at
# strain BASE instead of the packing, so the window BASE+START..BASE+END is at steady state.
# That state is ours, sheared once from the packing with implicitEuler to BASE (out of the
# timing); our runs restart from its full state (velocities, contact history), LF_DEM from its
# positions (foam2lfdem.py --time BASE; its springs start at zero); at a whole strain the
# Lees-Edwards offset is a whole box length, that is none.
# Output: OUTDIR/runs.csv (one row per timed run), OUTDIR/results.csv and
# OUTDIR/results.md (per repetition and medians, by summarise.py), run folders under OUTDIR/runs.
set -eo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
reps=5; start=0.05; end=0.2; baseStrain=0; out=$root/run/performance/lfdem
while getopts r:s:e:b:o: opt; do
    case $opt in
        r) reps=$OPTARG ;; s) start=$OPTARG ;; e) end=$OPTARG ;; b) baseStrain=$OPTARG ;;
        o) out=$OPTARG ;;
        *) sed -n 2,24p "$0"; exit 1 ;;
    esac
done
[[ $baseStrain =~ ^[0-9]+$ ]] || { echo "-b BASE must be a whole number of strain units" >&2; exit 1; }
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

# --- the start state: the packing, or (-b) ours sheared to strain BASE ---------------
# start_case: the case every run starts from; startTime: its time directory
start_case=$base startTime=0
if [ "$baseStrain" -gt 0 ]; then
    start_case=$out/steady$baseStrain startTime=$baseStrain
    if [ ! -f "$start_case/setUpDone" ]; then
        rm -rf "$start_case"; mkdir -p "$start_case"
        cp -r "$base/constant" "$base/system" "$base/0" "$start_case"
        setEntry "$start_case/constant/suspensionProperties" integration/integrator implicitEuler
        setEntry "$start_case/system/controlDict" endTime "$startTime"
        (cd "$start_case" && OMP_NUM_THREADS=1 wavyShearFoam > log.wavyShearFoam 2>&1) \
            || { echo "shearing to strain $startTime failed, see $start_case/log.wavyShearFoam" >&2; exit 1; }
        [ -d "$start_case/$startTime/lagrangian" ] || { echo "no state at $start_case/$startTime" >&2; exit 1; }
        python3 "$here/foam2lfdem.py" "$start_case" "$start_case/lfdem_conf.dat" --time "$startTime"
        touch "$start_case/setUpDone"
    fi
fi

csv=$out/runs.csv
[ -f "$csv" ] || echo "rep,code,strain_end,user_s,sys_s,wall_s,maxrss_kB,load1,steps_total,steps_window,window_start,mean_cg_window,dir" > "$csv"

# timeRun <dir> <command...>: /usr/bin/time -v into <dir>/time.txt
timeRun()
{
    local dir=$1; shift
    (cd "$dir" && /usr/bin/time -v -o time.txt "$@" > log 2>&1)
}

# row <rep> <code> <strainEnd> <dir> [<startTime>]: one CSV row from time.txt and the code's output
row()
{
    python3 "$here/summarise.py" --row "$1" "$2" "$3" "$4" "$start" "${5:-0}" >> "$csv"
}

runLfdem()   # <rep> <strainEnd>
{
    local dir=$out/runs/r$1_lfdem_$2
    rm -rf "$dir"; mkdir -p "$dir"
    cp "$start_case/lfdem_conf.dat" "$dir/conf.dat"
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
    cp -r "$start_case/constant" "$start_case/system" "$start_case/$startTime" "$dir"
    setEntry "$dir/constant/suspensionProperties" integration/integrator "$2"
    setEntry "$dir/system/controlDict" endTime "$(awk -v a="$startTime" -v b="$3" 'BEGIN { print a + b }')"
    cat /proc/loadavg > "$dir/loadavg"
    OMP_NUM_THREADS=1 timeRun "$dir" wavyShearFoam
    row "$1" "$2" "$3" "$dir" "$startTime"
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

{
    if [ "$startTime" != 0 ]; then
        echo "Every run from the state at strain $startTime: the strains below count from it."
        echo
    fi
    python3 "$here/summarise.py" --summary "$csv" "$start" "$end" "$out/results.csv"
} > "$out/results.md"
cat "$out/results.md"
