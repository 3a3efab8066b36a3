#!/usr/bin/python3
"""Analyse the runs of docs/speed-vs-error/run.sh.

    docs/speed-vs-error/analyse.py [--quick]

timeStep: per case, the mean eta_r over the strains sampled by every run
(a common window from the same initial condition); error against the run
with the smallest step (velocityVerlet at safety 0.1, dt = 8.9e-8); cost =
CPU seconds per unit strain (one thread; CPU rather than wall time because
other runs shared the machine).
model: steady eta_r (block averages after the start-up) against the
reference parameters eps = 1e-3, delta_lub = 0.05 (Table 1).
meshFlow: U_inf sampled on meshes of n^3 cells against the analytic flow,
from the same initial condition: errors of the mean eta_r and of the
particle velocity profile, and the cost.
Writes timeStep.csv, model.csv, meshFlow.csv, work-precision.png,
mesh-flow.png and prints Markdown.
"""
import glob
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.dirname(here))
from rheologydata import (blockMeans, cpuSeconds, fillTables,  # noqa: E402
                          meanAndError, readRheology, wallSeconds, writeCsv)

quick = "--quick" in sys.argv
runs = os.path.join(os.environ.get("WSF_SPEED_DIR", os.path.join(root, "run", "speed-vs-error")),
                    "quick" if quick else "full")
out = os.path.join(runs, "results") if quick else here
os.makedirs(out, exist_ok=True)

CASES = ("frictionless", "frictional")
DISCARD = {"frictionless": 5.0, "frictional": 2.0}
MARKERS = {"implicitEuler": "o", "overdamped": "^", "velocityVerlet": "s"}


def timeStep():
    rows = []
    for case in CASES:
        runsOfCase = {}
        for d in sorted(glob.glob(os.path.join(runs, "timeStep", case, "*"))):
            r = readRheology(d)
            if r is not None:
                runsOfCase[os.path.basename(d)] = (d, r)
        if not runsOfCase:
            continue
        refLabel = min(runsOfCase, key=lambda k: runsOfCase[k][1]["deltaT"].mean())
        # The strains sampled by every run (runs may sample more often)
        common = set.intersection(*(set(np.round(r["strain"], 9)) for _, r in runsOfCase.values()))
        window = max(common)

        def atCommon(r):
            return np.isin(np.round(r["strain"], 9), list(common))

        ref = runsOfCase[refLabel][1]
        refMean = ref["etaR"][atCommon(ref)].mean()
        for label, (d, r) in runsOfCase.items():
            integrator, safety = re.match(r"(\w+)-safety([0-9.e-]+)", label).groups()
            sel = atCommon(r)
            mean = r["etaR"][sel].mean()
            rows.append({
                "case": case, "integrator": integrator, "safety": float(safety),
                "dt": float(r["deltaT"][sel].mean()), "window": float(window),
                "etaR_mean": float(mean), "reference": float(refMean),
                "relative_error": float(abs(mean - refMean)/refMean),
                "cpu_s_per_strain": cpuSeconds(d)/r["strain"][-1],
                "wall_s_per_strain": wallSeconds(d)/r["strain"][-1],
                "max_overlap": float(r["maxOverlap"][sel].max()),
                "cg_iterations": float(r["cgIterations"][sel].mean()) if "cgIterations" in r else float("nan"),
                "is_reference": label == refLabel})
    columns = ["case", "integrator", "safety", "dt", "window", "etaR_mean", "reference",
               "relative_error", "cpu_s_per_strain", "wall_s_per_strain", "max_overlap",
               "cg_iterations", "is_reference"]
    writeCsv(os.path.join(out, "timeStep.csv"), rows, columns)
    return rows


def model():
    rows = []
    for case in CASES:
        values = {}
        for d in sorted(glob.glob(os.path.join(runs, "model", case, "*"))):
            r = readRheology(d)
            if r is None or len(r["strain"]) < 4:
                continue
            start = 0.5*r["strain"][-1] if quick else min(DISCARD[case], 0.5*r["strain"][-1])
            blocks, blockStrain = blockMeans(r["strain"], r["etaR"], start, 8)
            m, e = meanAndError(blocks)
            values[os.path.basename(d)] = (m, e, cpuSeconds(d)/r["strain"][-1], r["strain"][-1], start)
        ref = values.get("epsilon1e-3")
        for label, (m, e, cost, strain, start) in values.items():
            parameter, value = re.match(r"(epsilon|delta)([0-9.e-]+)", label).groups()
            rows.append({
                "case": case, "parameter": parameter, "value": float(value), "etaR": m,
                "error_bar": e,
                "relative_difference": (m - ref[0])/ref[0] if ref else float("nan"),
                "reference_etaR": ref[0] if ref else float("nan"),
                "reference_error_bar": ref[1] if ref else float("nan"),
                "cpu_s_per_strain": cost, "strain": strain, "discarded_strain": start})
    columns = ["case", "parameter", "value", "etaR", "error_bar", "relative_difference",
               "reference_etaR", "reference_error_bar", "cpu_s_per_strain", "strain",
               "discarded_strain"]
    writeCsv(os.path.join(out, "model.csv"), rows, columns)
    return rows


def finalProfile(case):
    """Ux per y bin at the last write time that has a profile"""
    files = glob.glob(os.path.join(case, "postProcessing", "profiles", "*", "profiles.dat"))
    if not files:
        return None
    last = max(files, key=lambda f: float(os.path.basename(os.path.dirname(f))))
    return np.loadtxt(last, comments="#")


def meshFlow():
    """Analytic U_inf against U_inf sampled on meshes: errors of the mean
    eta_r over the common window and of the particle velocity profile at
    its end (largest bin difference over the wave amplitude 3.2)"""
    base = os.path.join(runs, "meshFlow")
    ref = readRheology(os.path.join(base, "analytic"))
    refProfile = finalProfile(os.path.join(base, "analytic"))
    if ref is None or refProfile is None:
        return []
    rows = []
    for d in sorted(glob.glob(os.path.join(base, "*"))):
        r = readRheology(d)
        profile = finalProfile(d)
        if r is None or profile is None:
            continue
        common = np.intersect1d(np.round(ref["strain"], 9), np.round(r["strain"], 9))
        mean = r["etaR"][np.isin(np.round(r["strain"], 9), common)].mean()
        refMean = ref["etaR"][np.isin(np.round(ref["strain"], 9), common)].mean()
        label = os.path.basename(d)
        rows.append({
            "flow": label, "cells": int(label[5:]) if label.startswith("cells") else 0,
            "etaR_mean": float(mean), "etaR_error": float(abs(mean - refMean)/refMean),
            "profile_error": float(np.abs(profile[:, 3] - refProfile[:, 3]).max()/3.2),
            "window": float(max(common)),
            "cpu_s_per_strain": cpuSeconds(d)/r["strain"][-1]})
    rows.sort(key=lambda r: r["cells"])
    writeCsv(os.path.join(out, "meshFlow.csv"), rows, ["flow", "cells", "etaR_mean", "etaR_error",
                                    "profile_error", "window", "cpu_s_per_strain"])
    return rows


def plot(tsRows, modelRows):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, case in zip(axes, CASES):
        for integrator, marker in MARKERS.items():
            sel = [r for r in tsRows if r["case"] == case and r["integrator"] == integrator
                   and not r["is_reference"]]
            if sel:
                ax.loglog([r["cpu_s_per_strain"] for r in sel],
                          [max(r["relative_error"], 1e-6) for r in sel], marker, ms=7,
                          label=f"{integrator} (time step)")
                for r in sel:
                    ax.annotate(f"{r['safety']:g}", (r["cpu_s_per_strain"], max(r["relative_error"], 1e-6)),
                                fontsize=7, xytext=(3, 3), textcoords="offset points")
        for parameter, marker in (("epsilon", "D"), ("delta", "v")):
            sel = [r for r in modelRows if r["case"] == case and r["parameter"] == parameter
                   and r["relative_difference"] != 0]
            if sel:
                ax.errorbar([r["cpu_s_per_strain"] for r in sel],
                            [abs(r["relative_difference"]) for r in sel],
                            yerr=[np.nan_to_num(r["error_bar"]/r["reference_etaR"]) for r in sel],
                            fmt=marker, capsize=3, label=f"{parameter} (model, steady)")
                for r in sel:
                    ax.annotate(f"{r['value']:g}", (r["cpu_s_per_strain"], abs(r["relative_difference"])),
                                fontsize=7, xytext=(3, -9), textcoords="offset points")
        for level in (0.02, 0.05):
            ax.axhline(level, color="grey", lw=0.8, ls=":")
        ax.set_xlabel("CPU seconds per unit strain (1 thread, N = 200)")
        ax.set_ylabel(r"relative error of $\eta_r$")
        ax.set_title(f"Table 1 {'FL' if case == 'frictionless' else 'FR'}, $\\phi$ = 0.5")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "work-precision.png"), dpi=120)
    plt.close(fig)


def plotMeshFlow(rows):
    sel = [r for r in rows if r["cells"] > 0]
    if not sel:
        return
    fig, ax = plt.subplots(figsize=(5.5, 4))
    cost = [r["cpu_s_per_strain"] for r in sel]
    ax.loglog(cost, [max(r["etaR_error"], 1e-6) for r in sel], "o-", label=r"$\eta_r$ (mean over the window)")
    ax.loglog(cost, [max(r["profile_error"], 1e-6) for r in sel], "s-",
              label=r"particle $u_x$ profile (max over y, / wave amplitude)")
    for r in sel:
        ax.annotate(f"{r['cells']}", (r["cpu_s_per_strain"], max(r["profile_error"], 1e-6)),
                    fontsize=7, xytext=(3, 3), textcoords="offset points")
    analytic = [r for r in rows if r["cells"] == 0]
    if analytic:
        ax.axvline(analytic[0]["cpu_s_per_strain"], color="grey", ls=":", label="analytic $U_\\infty$ (cost)")
    ax.set_xlabel("CPU seconds per unit strain (1 thread)")
    ax.set_ylabel("relative error against analytic $U_\\infty$")
    ax.set_title("wavyShear/small: $U_\\infty$ sampled on n$^3$ cells")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "mesh-flow.png"), dpi=120)
    plt.close(fig)


def tables(ts, mo, mf):
    """The three Markdown tables of docs/speed-vs-error.md"""
    t = ["| case | integrator | safety | Δt | mean ηr (window) | error | CPU s/strain | max overlap | CG its |",
         "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in sorted(ts, key=lambda r: (r["case"], r["integrator"], r["safety"])):
        error = "reference" if r["is_reference"] else f"{100*r['relative_error']:.2f}%"
        cg = "–" if np.isnan(r["cg_iterations"]) else f"{r['cg_iterations']:.0f}"
        t.append(f"| {r['case']} | {r['integrator']} | {r['safety']:g} | {r['dt']:.3g} | "
                 f"{r['etaR_mean']:.4f} | {error} | {r['cpu_s_per_strain']:.3g} | "
                 f"{r['max_overlap']:.2g} | {cg} |")
    m = ["| case | parameter | value | ηr | ± | difference to ε = 10⁻³, δ_lub = 0.05 | CPU s/strain | strain |",
         "|---|---|---:|---:|---:|---:|---:|---:|"]
    for r in sorted(mo, key=lambda r: (r["case"], r["parameter"], r["value"])):
        m.append(f"| {r['case']} | {r['parameter']} | {r['value']:g} | {r['etaR']:.4g} | {r['error_bar']:.2g} | "
                 f"{100*r['relative_difference']:+.1f}% | {r['cpu_s_per_strain']:.3g} | {r['strain']:g} |")
    f = ["| U∞ | cells | mean ηr (window) | ηr error | profile error | CPU s/strain |",
         "|---|---:|---:|---:|---:|---:|"]
    for r in mf:
        f.append(f"| {'analytic' if r['cells'] == 0 else 'meshSampled'} | {r['cells'] or '–'} | "
                 f"{r['etaR_mean']:.4f} | {100*r['etaR_error']:.2f}% | {100*r['profile_error']:.2f}% | "
                 f"{r['cpu_s_per_strain']:.3g} |")
    note = "Table written by `docs/speed-vs-error/analyse.py` from `docs/speed-vs-error/{}.csv`:\n\n"
    return {"timeStep": note.format("timeStep") + "\n".join(t),
            "model": note.format("model") + "\n".join(m),
            "meshFlow": note.format("meshFlow") + "\n".join(f)}


def main():
    ts = timeStep()
    mo = model()
    mf = meshFlow()
    plot(ts, mo)
    plotMeshFlow(mf)
    sections = tables(ts, mo, mf)
    print("\n\n".join(sections.values()))
    if not quick:
        fillTables(os.path.join(root, "docs", "speed-vs-error.md"), sections)


if __name__ == "__main__":
    main()
