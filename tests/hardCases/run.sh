#!/bin/bash
#------------------------------------------------------------------------------
# Hard cases: short runs where suspension codes tend to fail, each checked
# and reported on one PASS/FAIL line; exits non-zero if any fails.
#
#   tests/hardCases/run.sh [--quick] [case ...]
#
# Checks (from rheology.dat, written by the function object suspensionRheology): the run reaches its end
# time (a NaN or a runaway overlap stops the solver with a diagnostic and a
# non-zero exit), the largest overlap stays below 5% of the smaller radius,
# every eta_r is finite. The long run also checks that the particle count,
# the pair slots (contact-history memory) and <|u - U_inf|^2> do not drift
# (last fifth against the second fifth of the run: within 20%, beyond the
# fluctuations of a 100-particle system).
# Cases run under run/hardCases/<mode>/ (restartable, etc/caseFunctions),
# with the implicit integrator unless named otherwise. --quick: shorter.
#------------------------------------------------------------------------------
set -u
root=$(cd "${0%/*}/../.." && pwd)
. "$root/etc/bashrc" && . "$root/etc/caseFunctions" || exit 1

mode=full
scale=1
if [ "${1:-}" = "--quick" ]; then mode=quick; scale=0.2; shift; fi
runRoot=${WSF_HARD_DIR:-$root/run/hardCases}/$mode
tutorials=$root/tutorials
failures=0

strain() { awk -v s="$1" -v f="$scale" 'BEGIN { print s*f }'; }

# check <name> <case dir> <end strain>: the PASS/FAIL line
check()
{
    local name=$1 dir=$2 end=$3
    local dat
    dat=$(ls "$dir"/postProcessing/rheology/*/rheology.dat 2> /dev/null)
    if [ -z "$dat" ]; then
        echo "FAIL $name: no rheology.dat ($dir)"; failures=$((failures + 1)); return
    fi
    local line
    line=$(awk -v end="$end" '
        /^# Time/ { for (i = 2; i <= NF; i++) col[$i] = i - 1; next }
        /^#/ { next }
        { n++; s = $col["strain"]; e = $col["etaR"]; o = $col["maxOverlap"]
          if (s > last) last = s
          if (o > maxo) maxo = o
          if (e != e + 0 || e == "nan" || e == "inf" || e == "-inf") bad++
          sum += e }
        END { ok = (n > 0 && last >= end - 1e-9 && maxo < 0.05 && !bad)
              printf "%s %d %.4g %.4g %.4g %d\n", ok ? "PASS" : "FAIL", n, last, maxo, n ? sum/n : 0, bad }' $dat)
    set -- $line
    echo "$1 $name: strain $3 of $end, max overlap/a_min $4 (< 0.05), mean eta_r $5, $6 non-finite"
    [ "$1" = PASS ] || failures=$((failures + 1))
}

# hard <name> <template> <end strain> [entry=value ...]
hard()
{
    local name=$1 template=$2 end=$3
    shift 3
    local dir=$runRoot/$name
    runCase "$dir" "$tutorials/$template" "$end" "$(awk -v e="$end" 'BEGIN { print e/20 }')" \
        integration/integrator=implicitEuler "$@" > /dev/null
    check "$name" "$dir" "$end"
}

denseFrictionless()
{
    hard denseFrictionless uniformShear/frictionless "$(strain 1)" population/volumeFraction=0.60
}
denseFrictional()
{
    # 2.6% below the frictional jamming point 0.575: eta_r -> O(10^3), and
    # the default stiffness (k = 4e5) is too soft for such stresses; the
    # stiff variant shows what a user who follows the advice gets
    hard denseFrictional uniformShear/frictional "$(strain 0.5)" population/nParticles=200 \
        population/volumeFraction=0.56
    hard denseFrictionalStiff uniformShear/frictional "$(strain 0.5)" population/nParticles=200 \
        population/volumeFraction=0.56 contact/stiffness=4e6
}
sizeRatio3()
{
    hard sizeRatio3 uniformShear/frictional "$(strain 0.2)" population/nParticles=700 \
        population/sizeRatio=3 population/volumeRatio=0.25
}
sizeRatio10()
{
    # 3 cut-offs of the big spheres across the box: N = 5400 with V2/V1 = 4
    hard sizeRatio10 uniformShear/frictional "$(strain 0.05)" population/nParticles=5400 \
        population/sizeRatio=10 population/volumeRatio=4
}
stiff()
{
    hard stiff4e6 uniformShear/frictional "$(strain 0.2)" population/nParticles=200 \
        contact/stiffness=4e6
}
strongAttraction()
{
    # Table 2: the lowest shear rate with F^R/F^A = 1, lambda_D = 0.013
    hard strongAttraction uniformShear/shearThickening "$(strain 0.2)" \
        electroChemical/shearRateRatio=1e-5 electroChemical/forceRatio=1 \
        electroChemical/repulsion/debyeLength=0.013
}
reversingShear()
{
    # Table 3 YW: script-U = 20 gammaDot a0 over one period, so the local
    # shear rate 1 + 20 (2 pi/Ly) cos(2 pi y/Ly) changes sign; 1024 spheres
    # with the attraction cut at 0.5 a0 (the box holds 3 cut-offs)
    hard reversingShear wavyShear/YW "$(strain 0.1)" population/nParticles=1024 \
        electroChemical/attraction/cutoffGap=0.5
}
overlappingStart()
{
    # A careless start: packed at phi = 0.60, then every diameter 2% larger
    # (overlaps up to 4% of the radius); the run must relax it
    WSF_CASE_SETUP='f=0/lagrangian/suspension/d;
        awk "/^\(/ { inside = 1; print; next } /^\)/ { inside = 0 }
             { if (inside) printf \"%.12g\n\", 1.02*\$1; else print }" "$f" > "$f.new" && mv "$f.new" "$f"' \
    hard overlappingStart uniformShear/frictionless "$(strain 0.2)" population/volumeFraction=0.60
}
longRun()
{
    # 103 strain units of the frictional case with 100 particles: 4e5 steps
    # at the default step (2.56e-4)
    local name=longRun dir=$runRoot/longRun end
    end=$(strain 103)
    runCase "$dir" "$tutorials/uniformShear/frictional" "$end" 0.1 \
        integration/integrator=implicitEuler population/nParticles=100 > /dev/null
    check "$name" "$dir" "$end"
    local line
    line=$(awk '
        /^# Time/ { for (i = 2; i <= NF; i++) col[$i] = i - 1; next }
        /^#/ { next }
        { n++; s[n] = $col["steps"]; p[n] = $col["pairSlots"]; u[n] = $col["uFluct2"] }
        END { a = int(n/5); b = int(2*n/5); c = int(4*n/5)
              for (i = a + 1; i <= b; i++) { p1 += p[i]; u1 += u[i] }
              for (i = c + 1; i <= n; i++) { p2 += p[i]; u2 += u[i] }
              p1 /= b - a; u1 /= b - a; p2 /= n - c; u2 /= n - c
              ok = (p2 < 1.2*p1 && p2 > p1/1.2 && u2 < 1.2*u1 && u2 > u1/1.2)
              printf "%s %d %.4g %.4g %.4g %.4g\n", ok ? "PASS" : "FAIL", s[n], p1, p2, u1, u2 }' \
        "$dir"/postProcessing/rheology/*/rheology.dat)
    set -- $line
    local count
    count=$(cd "$dir" && n=$(foamListTimes -latestTime | tail -1) && sed -n '/^[0-9][0-9]*$/{p;q}' "$n/lagrangian/suspension/d")
    [ "$count" = 100 ] || set -- FAIL "$2" "$3" "$4" "$5" "$6"
    echo "$1 longRunDrift: $2 steps, $count particles, pair slots $3 -> $4, <|u - U_inf|^2> $5 -> $6"
    [ "$1" = PASS ] || failures=$((failures + 1))
}

cases=${*:-"denseFrictionless denseFrictional sizeRatio3 sizeRatio10 stiff strongAttraction reversingShear overlappingStart longRun"}
for c in $cases; do
    case $c in
        denseFrictionless|denseFrictional|sizeRatio3|sizeRatio10|stiff|strongAttraction|reversingShear|overlappingStart|longRun) $c ;;
        *) echo "run.sh: unknown case '$c'" >&2; exit 2 ;;
    esac
done
echo "hard cases: $failures failed"
[ $failures -eq 0 ]
