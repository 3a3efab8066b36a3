#!/bin/bash
# Compile time and object size of the pair loop (src/suspension/forces/
# ForceField.C) with the registry as it is and with one more pair model
# (tests/extensibility/registerModel.sh: HarmonicRepulsion, an independent
# model with its own contribution), for each revision given.
#
#   compile-time.sh [-r REPS] [REV ...]      (default: HEAD; "." is the work tree)
#
# Each revision is exported (git archive; "." copies the work tree) to a
# scratch folder and ForceField.C compiled REPS times (default 3) per
# registry with the build's own command (ninja -t commands, from build/),
# one compile at a time. Output: one CSV row per compile on stdout
# (rev, models, rep, wall_s, cpu_s, object_kB).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
reps=3
while getopts r: opt; do
    case $opt in
        r) reps=$OPTARG ;;
        *) sed -n 2,13p "$0"; exit 1 ;;
    esac
done
shift $((OPTIND - 1))
[ "$#" -gt 0 ] || set -- HEAD
object=src/suspension/CMakeFiles/suspension.dir/forces/ForceField.C.o
command=$(ninja -C "$root/build" -t commands "$object" | tail -1)
[ -n "$command" ] || { echo "no compile command for $object in $root/build" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/compile-time.XXXXXX")
trap 'rm -rf "$work"' EXIT

echo "rev,models,rep,wall_s,cpu_s,object_kB"
for rev in "$@"; do
    tree=$work/tree
    rm -rf "$tree"; mkdir -p "$tree"
    if [ "$rev" = . ]; then
        (cd "$root" && git ls-files -z --cached --others --exclude-standard \
            | xargs -0 tar -c -f - 2>/dev/null) | tar -x -C "$tree"
        name=worktree
    else
        git -C "$root" archive "$rev" | tar -x -C "$tree"
        name=$(git -C "$root" rev-parse --short "$rev")
    fi
    for variant in registry registry+1; do
        if [ "$variant" = registry+1 ]; then
            bash "$root/tests/extensibility/registerModel.sh" "$tree"
        fi
        models=$(grep -c '^    [A-Za-z]*,\?$' <(sed -n '/^using PairModels = ModelList/,/^>;/p' \
            "$tree/src/suspension/forces/ForceModels.H"))
        cmd=${command//$root\/src/$tree\/src}
        cmd=${cmd//-o $object/-o $work/ForceField.o}
        cmd=${cmd//-MF $object.d/-MF $work/ForceField.o.d}
        for rep in $(seq 1 "$reps"); do
            rm -f "$work/ForceField.o"
            (cd "$root/build" && /usr/bin/time -f "%e %U %S" -o "$work/time" bash -c "$cmd")
            read -r wall user sys < "$work/time"
            kB=$(( $(stat -c %s "$work/ForceField.o") / 1024 ))
            echo "$name,$models,$rep,$wall,$(awk -v u="$user" -v s="$sys" 'BEGIN { print u + s }'),$kB"
        done
    done
done
