#!/usr/bin/python3
"""Tables of docs/speed-vs-error/steady.sh: for each run under
RUNROOT/<case>/, the solver's own steady-state summary of eta_r (the latest
postProcessing/rheology/*/rheologySummary.dat), the mean step, the CPU
seconds per strain, and two differences, each with the error bar of a
difference of independent runs:

- "difference": a run of the template's settings (lubrication epsilon and
  delta, CG tolerance, normal contact springs) against the implicitEuler
  run of the smallest safety (the case's reference); a run with some of
  them changed (-eps, -delta, -tol, -normal in its name) against the run
  of the same integrator and safety with the most of its changes and no
  other (so that the step's own bias cancels); a run started from a stored steady state (-from<t>)
  against the reference;
- "to dt -> 0": against the zero-step limit a of the weighted straight-line
  fit eta_r = a + b dt over the case's implicitEuler runs (first order
  scheme; St = 1e-3, so overdamped, St -> 0, has the same limit within far
  less than these errors).

    steady.py RUNROOT      ->  docs/speed-vs-error/steady.csv, steady.md and
                               its table in docs/speed-vs-error.md
"""
import csv
import glob
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from rheologydata import cpuSeconds, fillTables, readRheology, readSummary  # noqa: E402

NAME = re.compile(r"(?P<integrator>\w+)-safety(?P<safety>[0-9.]+)"
                  r"(?:-eps(?P<eps>[0-9.eE+-]+?))?(?:-delta(?P<delta>[0-9.]+?))?"
                  r"(?:-tol(?P<tol>[0-9.eE+-]+?))?(?:-normal(?P<normal>[a-z]+))?"
                  r"(?:-from(?P<start>[0-9.]+))?$")


def readRuns(runRoot):
    rows = []
    for run in sorted(glob.glob(os.path.join(runRoot, "*", "*"))):
        m = NAME.match(os.path.basename(run))
        s = readSummary(run)
        if not m or not s:
            continue
        r = readRheology(run)
        start = float(m.group("start") or 0)
        strain = s["time"] - start
        rows.append(dict(
            case=os.path.basename(os.path.dirname(run)),
            integrator=m.group("integrator"), safety=float(m.group("safety")),
            settings=[x for x in (
                m.group("eps") and "ε = " + m.group("eps"),
                m.group("delta") and "δ = " + m.group("delta"),
                m.group("tol") and "CG tolerance " + m.group("tol"),
                m.group("normal") and "normal contact " + m.group("normal")) if x],
            start=m.group("start"),
            deltaT=float(r["deltaT"][-1]) if r is not None else float("nan"),
            # a run stopped before its end logs no CPU time: unknown
            strain=strain, cpu_s_per_strain=(cpuSeconds(run) or float("nan"))/strain,
            etaR=s["mean"], se=s["se"], corr=s["corr"], blocks=s["blocks"],
            used=s["used"], discarded=s["discarded"], trusted=s["trusted"]))
        row = rows[-1]
        row["variant"] = ", ".join(row["settings"] + (
            ["from strain " + row["start"]] if row["start"] else []))
    return rows


def zeroStepFit(rows):
    """Weighted (1/se^2) fit eta_r = a + b dt: a, its error, b, chi^2, dof"""
    w = [1/r["se"]**2 for r in rows]
    sw = sum(w)
    sx = sum(wi*r["deltaT"] for wi, r in zip(w, rows))
    sy = sum(wi*r["etaR"] for wi, r in zip(w, rows))
    sxx = sum(wi*r["deltaT"]**2 for wi, r in zip(w, rows))
    sxy = sum(wi*r["deltaT"]*r["etaR"] for wi, r in zip(w, rows))
    det = sw*sxx - sx*sx
    a = (sxx*sy - sx*sxy)/det
    b = (sw*sxy - sx*sy)/det
    chi2 = sum(wi*(r["etaR"] - a - b*r["deltaT"])**2 for wi, r in zip(w, rows))
    return a, math.sqrt(sxx/det), b, chi2, len(rows) - 2


def difference(r, ref):
    """(eta_r - ref)/ref in per cent and its error (independent runs)"""
    return (100*(r["etaR"] - ref["etaR"])/ref["etaR"],
            100*math.hypot(r["se"], ref["se"])/ref["etaR"])


def analyse(rows):
    fits = {}
    for case in sorted({r["case"] for r in rows}):
        own = [r for r in rows if r["case"] == case]
        base = [r for r in own if r["integrator"] == "implicitEuler" and not r["variant"]]
        if not base:
            continue
        ref = min(base, key=lambda r: r["safety"])
        fit = zeroStepFit(base) if len(base) > 2 else None
        fits[case] = fit
        for r in own:
            # A run with settings changed: against the run of the same
            # integrator and safety with the most of its settings and no
            # other (so that the step's bias and the settings it shares
            # cancel); otherwise the reference
            against = ref
            if r["settings"] and not r["start"]:
                subsets = [b for b in own if not b["start"]
                           and b["integrator"] == r["integrator"] and b["safety"] == r["safety"]
                           and set(b["settings"]) < set(r["settings"])]
                if subsets:
                    # of the largest, the one that differs in the last
                    # setting (a pair then differs in one setting only)
                    against = max(subsets, key=lambda b: (
                        len(b["settings"]),
                        b["settings"] == r["settings"][:len(b["settings"])]))
            r["against"] = ("" if r is ref else "%s at safety %g%s" % (
                against["integrator"], against["safety"],
                " (" + against["variant"] + ")" if against["variant"] else ""))
            r["bias_pct"], r["bias_err_pct"] = difference(r, against) if r is not ref else (0.0, 0.0)
            if fit:
                a, aErr = fit[0], fit[1]
                r["bias0_pct"] = 100*(r["etaR"] - a)/a
                r["bias0_err_pct"] = 100*math.hypot(r["se"], aErr)/a
            else:
                r["bias0_pct"] = r["bias0_err_pct"] = float("nan")
    rows[:] = [r for r in rows if "against" in r]
    rows.sort(key=lambda r: (r["case"] != "frictionless", r["case"], r["variant"] != "",
                             r["integrator"] != "implicitEuler", r["integrator"],
                             r["variant"], -r["safety"]))
    return fits


def write(rows, fits):
    cols = ["case", "integrator", "safety", "variant", "deltaT", "strain", "cpu_s_per_strain",
            "etaR", "se", "corr", "blocks", "used", "discarded", "trusted",
            "against", "bias_pct", "bias_err_pct", "bias0_pct", "bias0_err_pct"]
    with open(os.path.join(here, "steady.csv"), "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(cols)
        for r in rows:
            out.writerow([r[c] for c in cols])
    pct = lambda x: "" if math.isnan(x) else "%+.2f %%" % x  # noqa: E731
    err = lambda x: "" if math.isnan(x) else "%.2f %%" % x   # noqa: E731
    with open(os.path.join(here, "steady.md"), "w") as f:
        f.write("Table written by `docs/speed-vs-error/steady.py` from the runs of "
                "`docs/speed-vs-error/steady.sh` (steady.csv); ηr ± one standard "
                "error from the solver's rheologySummary.dat; strain: the strain "
                "run (after the stored state it started from, if any); difference "
                "to the run named under *against* ± the error of the difference "
                "(independent runs).\n\n")
        f.write("| case | integrator | safety | variant | Δt (mean) | strain | discarded | ηr | ± | "
                "against | difference | ± | to Δt → 0 | ± | CPU s/strain | trusted |\n")
        f.write("|---|---|---:|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---|\n")
        for r in rows:
            f.write("| %s | %s | %g | %s | %.3g | %g | %.3g | %.4g | %.2g | %s | %s | %s | %s | %s | %s | %s |\n" % (
                r["case"], r["integrator"], r["safety"], r["variant"], r["deltaT"],
                r["strain"], r["discarded"], r["etaR"], r["se"],
                r["against"] or "reference",
                pct(r["bias_pct"]) if r["against"] else "",
                err(r["bias_err_pct"]) if r["against"] else "",
                pct(r["bias0_pct"]), err(r["bias0_err_pct"]),
                "" if math.isnan(r["cpu_s_per_strain"]) else "%.3g" % r["cpu_s_per_strain"],
                r["trusted"]))
        for case, fit in fits.items():
            if fit:
                f.write("\n%s: zero-step limit (weighted fit ηr = a + b Δt over the mean steps "
                        "of implicitEuler): a = %.4g ± %.2g, b = %.4g; χ² = %.2g for %d "
                        "degrees of freedom.\n" % ((case,) + fit))
    table = open(os.path.join(here, "steady.md")).read()
    print(table)
    fillTables(os.path.join(here, "..", "speed-vs-error.md"), {"steady": table.strip()})


def main(runRoot):
    rows = readRuns(runRoot)
    if not rows:
        sys.exit("steady.py: no summaries under " + runRoot)
    write(rows, analyse(rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else
         os.path.join(here, "..", "..", "run", "speed-vs-error", "steady"))
