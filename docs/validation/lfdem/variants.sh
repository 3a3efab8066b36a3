#!/bin/bash
# Three builds of LF_DEM for the frictionless comparison of run.sh: LF_DEM as
# it is, and LF_DEM with one of its two departures from our model changed to
# ours (a one-line edit each, checked to have happened):
#   stock       LF_DEM as fetched
#   ourSprings  normal contact force kn h for every pair (LF_DEM: kn ro h,
#               ro the pair's mean radius; Contact::setSpringConstants)
#   ourCutoff   lubrication while the gap h < lub_max_gap a0 for every pair
#               (LF_DEM: h < lub_max_gap ro; System::calcLubricationRange)
#
#   variants.sh SRC_TREE OUTDIR [COMMIT]
#
# SRC_TREE: an LF_DEM source tree (git archive of github ryseto/LF_DEM, see
# docs/performance/lfdem/README.md); each variant is a copy under
# OUTDIR/<variant>, built by docs/performance/lfdem/build.sh (binary
# OUTDIR/<variant>/LF_DEM/LF_DEM).
set -eo pipefail
here=$(cd "$(dirname "$0")" && pwd)
src=${1:?usage: variants.sh SRC_TREE OUTDIR [COMMIT]}
out=${2:?usage: variants.sh SRC_TREE OUTDIR [COMMIT]}
commit=${3:-00fa7cc094d6fe4c459faa478116defd3468a33d}
[ -f "$src/LF_DEM/Contact.cpp" ] || { echo "$src: not an LF_DEM source tree" >&2; exit 1; }
mkdir -p "$out"

# edit <tree> <file> <sed expression> <text the edited file must then hold>
edit()
{
    sed -i -e "$3" "$1/LF_DEM/$2"
    grep -qF "$4" "$1/LF_DEM/$2" || { echo "variants.sh: the edit of $2 did not apply" >&2; exit 1; }
}

for v in stock ourSprings ourCutoff; do
    rm -rf "${out:?}/$v"
    cp -r "$src" "$out/$v"
    find "$out/$v" \( -name '*.o' -o -name LF_DEM -type f \) -delete
    case $v in
        ourSprings)
            edit "$out/$v" Contact.cpp \
                's/kn_scaled = ro_12\*ro_12\*sys->p.kn;/kn_scaled = ro_12*sys->p.kn;/' \
                'kn_scaled = ro_12*sys->p.kn;' ;;
        ourCutoff)
            edit "$out/$v" System.cpp \
                's/return (2+p.lub_max_gap)\*0.5\*(radius\[i\]+radius\[j\]);/return radius[i]+radius[j]+p.lub_max_gap;/' \
                'return radius[i]+radius[j]+p.lub_max_gap;' ;;
    esac
    echo "== $v"
    "$here/../../performance/lfdem/build.sh" "$out/$v" "$commit" > "$out/$v.build.log" 2>&1 \
        || { echo "build of $v failed, see $out/$v.build.log" >&2; exit 1; }
    [ -x "$out/$v/LF_DEM/LF_DEM" ] || { echo "no binary for $v" >&2; exit 1; }
done
echo "LF_DEM variants in $out: stock ourSprings ourCutoff"
