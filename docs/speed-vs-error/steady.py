#!/usr/bin/python3
"""Table of docs/speed-vs-error/steady.sh: for each case under RUNROOT, the
solver's own steady-state summary of eta_r (the latest
postProcessing/rheology/*/rheologySummary.dat), the mean step, the CPU
seconds per strain, and the difference to the implicitEuler case of the
smallest safety with the error bar of that difference (the two runs are
independent), and to the zero-step limit of implicitEuler (a weighted
straight-line fit over its cases; St = 1e-3, so overdamped, St -> 0, has the
same limit within far less than these errors).

    steady.py RUNROOT      ->  docs/speed-vs-error/steady.csv, steady.md
"""
import glob
import math
import os
import re
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, ".."))
from rheologydata import cpuSeconds, readRheology, readSummary  # noqa: E402


def main(runRoot):
    rows = []
    for case in sorted(glob.glob(os.path.join(runRoot, "*", "*"))):
        s = readSummary(case)
        if not s:
            continue
        m = re.search(r"(\w+)-safety([0-9.]+)$", case)
        r = readRheology(case)
        cpu = cpuSeconds(case)
        rows.append(dict(
            case=os.path.basename(os.path.dirname(case)),
            integrator=m.group(1), safety=float(m.group(2)),
            deltaT=float(r["deltaT"][-1]) if r is not None else float("nan"),
            strain=s["time"], cpu_s_per_strain=cpu/s["time"],
            etaR=s["mean"], se=s["se"], corr=s["corr"], blocks=s["blocks"],
            used=s["used"], discarded=s["discarded"], trusted=s["trusted"]))
    if not rows:
        sys.exit("steady.py: no summaries under " + runRoot)
    # The scheme is first order: eta_r = a + b dt, weighted by 1/se^2; a is
    # the zero-step limit (its error from the fit's covariance)
    fitRows = [r for r in rows if r["integrator"] == "implicitEuler"]
    w = [1/r["se"]**2 for r in fitRows]
    sw = sum(w)
    sx = sum(wi*r["deltaT"] for wi, r in zip(w, fitRows))
    sy = sum(wi*r["etaR"] for wi, r in zip(w, fitRows))
    sxx = sum(wi*r["deltaT"]**2 for wi, r in zip(w, fitRows))
    sxy = sum(wi*r["deltaT"]*r["etaR"] for wi, r in zip(w, fitRows))
    det = sw*sxx - sx*sx
    a = (sxx*sy - sx*sxy)/det
    b = (sw*sxy - sx*sy)/det
    aErr = math.sqrt(sxx/det)
    chi2 = sum(wi*(r["etaR"] - a - b*r["deltaT"])**2 for wi, r in zip(w, fitRows))
    ref = min(fitRows, key=lambda r: r["safety"])
    for r in rows:
        d = r["etaR"] - ref["etaR"]
        e = math.hypot(r["se"], ref["se"]) if r is not ref else 0.0
        r["bias_pct"] = 100*d/ref["etaR"]
        r["bias_err_pct"] = 100*e/ref["etaR"]
        r["bias0_pct"] = 100*(r["etaR"] - a)/a
        r["bias0_err_pct"] = 100*math.hypot(r["se"], aErr)/a
    rows.sort(key=lambda r: (r["integrator"] != "implicitEuler", r["integrator"], -r["safety"]))

    cols = ["case", "integrator", "safety", "deltaT", "strain", "cpu_s_per_strain",
            "etaR", "se", "corr", "blocks", "used", "discarded", "trusted",
            "bias_pct", "bias_err_pct", "bias0_pct", "bias0_err_pct"]
    with open(os.path.join(here, "steady.csv"), "w") as f:
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(str(r[c]) for c in cols) + "\n")
    with open(os.path.join(here, "steady.md"), "w") as f:
        f.write("Table written by `docs/speed-vs-error/steady.py` from the runs of "
                "`docs/speed-vs-error/steady.sh` (steady.csv); ηr ± one standard "
                "error from the solver's rheologySummary.dat; difference to safety "
                "%g (implicitEuler) ± the error of the difference.\n\n" % ref["safety"])
        f.write("| case | integrator | safety | Δt (mean) | strain | discarded | ηr | ± | "
                "difference | ± | to Δt → 0 | ± | CPU s/strain | trusted |\n")
        f.write("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n")
        for r in rows:
            f.write("| %s | %s | %g | %.3g | %g | %.3g | %.4g | %.2g | %s | %s | %+.2f %% | %.2f %% | %.3g | %s |\n" % (
                r["case"], r["integrator"], r["safety"], r["deltaT"], r["strain"], r["discarded"],
                r["etaR"], r["se"],
                "reference" if r is ref else "%+.2f %%" % r["bias_pct"],
                "" if r is ref else "%.2f %%" % r["bias_err_pct"],
                r["bias0_pct"], r["bias0_err_pct"],
                r["cpu_s_per_strain"], r["trusted"]))
        f.write("\nZero-step limit (weighted fit ηr = a + b Δt over the mean steps of "
                "implicitEuler): a = %.4g ± %.2g, b = %.4g; χ² = %.2g for %d degrees of freedom.\n"
                % (a, aErr, b, chi2, len(fitRows) - 2))
    print(open(os.path.join(here, "steady.md")).read())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else
         os.path.join(here, "..", "..", "run", "speed-vs-error", "steady"))
