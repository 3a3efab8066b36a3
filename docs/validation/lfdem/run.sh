#!/bin/bash
# Frictionless suspensions (Table 1 FL of Monti et al. 2021: N = 200,
# bidisperse 1:1.4, equal volumes, k_hat = 4e5, epsilon = 1e-3) with the
# lubrication to a gap 0.5, in wavyShearFoam and in LF_DEM with the same
# physics from the same packing, and in LF_DEM with either of its two
# departures from our model changed to ours (variants.sh): the steady-state
# eta_r of each, for docs/validation.md ("Against LF_DEM, frictionless").
#
#   run.sh [-e END] [-p "PHI ..."] [-o OUTDIR] [RUN ...]
#
# RUN: CODE-PHI-sSEED (or CODE-PHI: seed 1), CODE one of ours, oursStep4
# (ours at a quarter of the default step: integration/safety 0.05), stock,
# ourSprings, ourCutoff (default: all five at every PHI of -p, seed 1;
# default PHI 0.50 0.55, END 30 strain units). SEED is the packing's
# population/seed.
# Environment: LFDEM_VARIANTS, the OUTDIR of variants.sh (its
# <variant>/LF_DEM/LF_DEM binaries). Each run is one process on one thread
# in OUTDIR/<RUN>; a finished run is skipped, so two instances with
# different RUN lists share the machine's two cores. Ours runs through
# runCase (etc/caseFunctions: restarts where it stopped), an LF_DEM run that
# was stopped starts again. Then: analyse.py OUTDIR.
set -eo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
end=30; phis="0.50 0.55"; out=$root/run/validation/lfdem
while getopts e:p:o: opt; do
    case $opt in
        e) end=$OPTARG ;; p) phis=$OPTARG ;; o) out=$OPTARG ;;
        *) sed -n 2,21p "$0"; exit 1 ;;
    esac
done
shift $((OPTIND - 1))
variants=${LFDEM_VARIANTS:?set LFDEM_VARIANTS to the folder built by variants.sh}
runs=$*
if [ -z "$runs" ]; then
    for phi in $phis; do runs="$runs ours-$phi oursStep4-$phi stock-$phi ourSprings-$phi ourCutoff-$phi"; done
fi
awk -v e="$end" 'BEGIN { exit !(e + 0 > 0) }' || { echo "-e END must be a positive strain" >&2; exit 1; }

set +eu
. "$root/etc/bashrc" > /dev/null 2>&1
. "$root/etc/caseFunctions"
set -e
command -v wavyShearFoam > /dev/null || { echo "wavyShearFoam not found after sourcing etc/bashrc" >&2; exit 1; }
mkdir -p "$out"
out=$(cd "$out" && pwd)

# base <phi> <seed>: b = the packing (our frictionless tutorial,
# lubrication delta 0.5) and its LF_DEM configuration; made once (mkdir is
# the lock between instances)
base()
{
    b=$out/base-$1-s$2
    until [ -f "$b/setUpDone" ]; do
        if mkdir "$b.lock" 2> /dev/null; then
            rm -rf "$b"; mkdir -p "$b"
            local d=$b/constant/suspensionProperties
            if cp -r "$root/tutorials/uniformShear/frictionless/constant" \
                     "$root/tutorials/uniformShear/frictionless/system" "$b" \
                && setEntry "$d" population/volumeFraction "$1" \
                && setEntry "$d" population/seed "$2" \
                && setEntry "$d" lubrication/delta 0.5 \
                && (cd "$b" && makeSuspension -boxOnly > log.box 2>&1 \
                    && blockMesh > log.blockMesh 2>&1 && makeSuspension > log.makeSuspension 2>&1) \
                && python3 "$root/docs/performance/lfdem/foam2lfdem.py" "$b" "$b/lfdem_conf.dat" \
                    > "$b/log.foam2lfdem" 2>&1
            then
                touch "$b/setUpDone"; rmdir "$b.lock"
            else
                rmdir "$b.lock"; echo "set-up of $b failed, see its log.*" >&2; exit 1
            fi
        else
            sleep 5
        fi
    done
}

# LF_DEM's parameters: those of the frictional timing (lfdem_FR.txt) with
# the friction off
lfdemParams()
{
    sed -e 's/^friction_model = 1;/friction_model = 0;/' -e 's/^mu_static = 1;/mu_static = 0;/' \
        "$root/docs/performance/lfdem/lfdem_FR.txt"
    echo "time_end = ${end}h;"
}

for run in $runs; do
    [[ $run =~ ^(ours|oursStep4|stock|ourSprings|ourCutoff)-([0-9.]+)(-s([0-9]+))?$ ]] \
        || { echo "run $run is not CODE-PHI or CODE-PHI-sSEED, CODE one of" \
                  "ours oursStep4 stock ourSprings ourCutoff" >&2; exit 1; }
    code=${BASH_REMATCH[1]} phi=${BASH_REMATCH[2]} seed=${BASH_REMATCH[4]:-1}
    base "$phi" "$seed"
    dir=$out/$code-$phi-s$seed
    case $code in
        ours|oursStep4)
            runCase "$dir" "$b" "$end" 0.01 \
                $([ "$code" = oursStep4 ] && echo integration/safety=0.05) || exit 1
            cmp -s "$b/0/lagrangian/suspension/x" "$dir/0/lagrangian/suspension/x" \
                || { echo "$dir: not the packing of $b" >&2; exit 1; }
            ;;
        *)
            bin=$variants/$code/LF_DEM/LF_DEM
            [ -x "$bin" ] || { echo "no LF_DEM binary at $bin (run variants.sh)" >&2; exit 1; }
            if grep -qs "Job done ok" "$dir/log"; then echo "$dir: done"; continue; fi
            rm -rf "$dir"; mkdir -p "$dir"
            cp "$b/lfdem_conf.dat" "$dir/conf.dat"
            lfdemParams > "$dir/params.txt"
            grep -q "^friction_model = 0;" "$dir/params.txt" && grep -q "^mu_static = 0;" "$dir/params.txt" \
                || { echo "lfdem_FR.txt no longer has the friction entries run.sh turns off" >&2; exit 1; }
            echo "$dir: LF_DEM $code to strain $end ($(date +%T))"
            (cd "$dir" && OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 \
                /usr/bin/time -v -o time.txt "$bin" -f -r 1h conf.dat params.txt > log 2>&1) \
                || { echo "$dir: LF_DEM failed, see $dir/log" >&2; exit 1; }
            ;;
    esac
done
