#!/usr/bin/python3
"""Tabulate the runs of docs/validation/run.sh and write docs/validation/.

    docs/validation/analyse.py [--quick]

Every number is the solver's own: for each run (seed) the latest
postProcessing/rheology/*/rheologySummary.dat that the function object
suspensionRheology writes (start-up transient by the MSER-5 rule, blocks of
two correlation strains; docs/user-guide.md, "The rheology with an error bar"). A point's
value is the mean over its seeds (initial configurations) weighted by their
errors, its error bar that of the weighted mean, scaled up when the seeds
scatter more than their error bars say (rheologydata.combineSeeds). Writes
<case>.csv (one row per point, columns below) and <case>.png, prints the
Markdown tables and puts them into docs/validation.md between its
<!-- table:<case> --> markers.
"""
import glob
import math
import os
import re
import sys
from collections import defaultdict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.dirname(os.path.dirname(here))
sys.path.insert(0, os.path.dirname(here))
from rheologydata import (combineSeeds, fillTables, readRheology,  # noqa: E402
                          readSummaries, wallSeconds, writeCsv)
quick = "--quick" in sys.argv
mode = "quick" if quick else "full"
runs = os.path.join(os.environ.get("WSF_VALIDATION_DIR", os.path.join(root, "run", "validation")), mode)
out = os.path.join(runs, "results") if quick else here    # quick: not in docs/

COLUMNS = ["case", "parameter", "x", "setting", "reference", "value", "error",
           "relative_difference", "N1", "N1_error", "N2", "N2_error",
           "Pi", "Pi_error", "share_stokes", "share_lubrication", "share_contact",
           "share_electroChemical", "seeds", "strain", "discarded_strain",
           "correlation_strain", "trusted", "wall_seconds"]
CONTRIBUTIONS = ("etaR_stokes", "etaR_lubrication", "etaR_contact",
                 "etaR_repulsion", "etaR_attraction")


def fitFrictionless(phi):
    """Paper fig. 7, black: Mari et al. (2014), frictionless"""
    return 1.4*(1 - phi/0.66)**-1.6


def fitFrictional(phi):
    """Paper fig. 7, red: Mari et al. (2014), mu_C = 1"""
    return 0.71*(1 - phi/0.575)**-2.3


def analysePoint(dirs):
    """The seeds' (case directories') summaries of one point combined"""
    summaries = [x for x in (readSummaries(d) for d in dirs) if x and "etaR" in x]
    if not summaries:
        return None
    etaR = [x["etaR"] for x in summaries]
    res = {"seeds": len(summaries),
           "strain": sum(x["time"] for x in etaR),
           "discarded_strain": sum(x["discarded"] for x in etaR),
           "correlation_strain": max(x["corr"] for x in etaR),
           "trusted": "yes" if all(x["trusted"] == "yes" for x in etaR) else "no",
           "wall_seconds": sum(wallSeconds(d) for d in dirs)}
    for name in ("etaR", "N1", "N2", "Pi") + CONTRIBUTIONS:
        res[name], res[name + "_error"] = combineSeeds([x[name] for x in summaries])
    particles = res["etaR"] - 1
    for c in ("stokes", "lubrication", "contact"):
        res["share_" + c] = res["etaR_" + c]/particles
    res["share_electroChemical"] = (res["etaR_repulsion"] + res["etaR_attraction"])/particles
    return res


def points(caseName):
    """{label without seed: [case directories]}"""
    groups = defaultdict(list)
    for d in sorted(glob.glob(os.path.join(runs, caseName, "*"))):
        if os.path.isdir(d):
            groups[re.sub(r"-seed\d+$", "", os.path.basename(d))].append(d)
    return groups


def row(caseName, parameter, x, setting, reference, res):
    rel = (res["etaR"] - reference)/reference if reference else float("nan")
    values = {"case": caseName, "parameter": parameter, "x": x, "setting": setting,
              "reference": reference, "value": res["etaR"], "error": res["etaR_error"],
              "relative_difference": rel}
    for k in COLUMNS:
        if k not in values:
            values[k] = res.get(k, float("nan"))
    return values


def markdown(rows, withShares=False):
    head = ("| point | reference | eta_r | ± | difference | N1 | N2 | strain (seeds) "
            "| discarded | correlation strain | trusted | wall s |")
    sep = "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|"
    lines = [head, sep]
    for r in rows:
        ref = "" if not r["reference"] or math.isnan(r["reference"]) else f"{r['reference']:.3g}"
        diff = "" if math.isnan(r["relative_difference"]) else f"{100*r['relative_difference']:+.1f}%"
        lines.append(
            f"| {r['setting']} {r['parameter']} = {r['x']:g} | {ref} | {r['value']:.4g} | "
            f"{r['error']:.2g} | {diff} | {r['N1']:.3g} | {r['N2']:.3g} | "
            f"{r['strain']:.3g} ({r['seeds']}) | {r['discarded_strain']:.2g} | "
            f"{r['correlation_strain']:.2g} | {r['trusted']} | {r['wall_seconds']:.0f} |")
    if withShares:
        lines += ["", "| point | Stokes | lubrication | contact | electro-chemical |",
                  "|---|---:|---:|---:|---:|"]
        for r in rows:
            lines.append(
                f"| {r['setting']} {r['parameter']} = {r['x']:g} | {100*r['share_stokes']:.0f}% | "
                f"{100*r['share_lubrication']:.0f}% | {100*r['share_contact']:.0f}% | "
                f"{100*r['share_electroChemical']:.0f}% |")
    return "\n".join(lines)


def jamming(caseName, fit, fitLabel, title):
    rows = []
    for label, dirs in sorted(points(caseName).items()):
        m = re.search(r"phi([0-9.]+)", label)
        res = analysePoint(dirs)
        if not m or res is None:
            continue
        phi = float(m.group(1))
        d = re.search(r"delta([0-9.]+)", label)
        setting = f"delta_lub={d.group(1)}" if d else "delta_lub=0.05"
        rows.append(row(caseName, "phi", phi, setting, fit(phi), res))
    if not rows:
        return []
    fig, ax = plt.subplots(figsize=(5, 4))
    phis = np.linspace(0.38, max(r["x"] for r in rows) + 0.01, 200)
    ax.semilogy(phis, fit(phis), "k-", label=fitLabel)
    for setting, marker in (("delta_lub=0.05", "o"), ("delta_lub=0.2", "s")):
        sel = [r for r in rows if r["setting"] == setting]
        if sel:
            ax.errorbar([r["x"] for r in sel], [r["value"] for r in sel],
                        yerr=[r["error"] for r in sel], fmt=marker, capsize=3,
                        label="this code, " + setting.replace("_lub", r"$_{lub}$/a$_0$"))
    ax.set_xlabel(r"$\phi$")
    ax.set_ylabel(r"$\eta_r$")
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, caseName + ".png"), dpi=120)
    plt.close(fig)
    return rows


def shearThickening():
    rows = []
    plateaux = {}
    for label, dirs in sorted(points("shearThickening").items()):
        res = analysePoint(dirs)
        if res is None:
            continue
        m = re.match(r"lambda([0-9.]+)-ratio([0-9.]+)-rate(.+)", label)
        if m:
            rows.append(row("shearThickening", "shearRateRatio", float(m.group(3)),
                            f"lambda_D={m.group(1)} F^R/F^A={m.group(2)}", float("nan"), res))
        else:
            mu = label.split("mu")[-1]
            plateaux[mu] = res
            rows.append(row("shearThickening", "mu_C", float(mu),
                            "no electro-chemical forces", float("nan"), res))
    if not rows:
        return []
    rows.sort(key=lambda r: (r["setting"], r["x"]))
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for setting, marker in (("lambda_D=0.045 F^R/F^A=19", "o"), ("lambda_D=0.013 F^R/F^A=1", "s")):
        sel = sorted((r for r in rows if r["setting"] == setting), key=lambda r: r["x"])
        if sel:
            ax.errorbar([r["x"] for r in sel], [r["value"] for r in sel],
                        yerr=[r["error"] for r in sel], fmt=marker + "-", capsize=3,
                        label=setting.replace("lambda_D", r"$\lambda_D$/a$_0$"))
    styles = {"0": ("k--", r"frictionless, no e.-c. forces"),
              "0.5": ("r--", r"$\mu_C$ = 0.5, no e.-c. forces")}
    for mu, res in plateaux.items():
        style, lab = styles.get(mu, ("g:", f"mu {mu}"))
        ax.axhline(res["etaR"], ls=style[1:], color=style[0], label=lab)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(r"$\dot\gamma/\dot\gamma_0$")
    ax.set_ylabel(r"$\eta_r$")
    ax.set_title(r"Table 2 SI: N = 512, $\phi$ = 0.46, $\mu_C$ = 0.5")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "shearThickening.png"), dpi=120)
    plt.close(fig)
    return rows


def profileSeries(case):
    """{strain: profile rows} of every write of <case>, in strain order"""
    out = {}
    for f in glob.glob(os.path.join(case, "postProcessing", "profiles", "*", "profiles.dat")):
        out[float(os.path.basename(os.path.dirname(f)))] = np.loadtxt(f, comments="#")
    return dict(sorted(out.items()))


def readProfiles(case, start):
    """Mean profile over the write times after `start`"""
    files = [p for t, p in profileSeries(case).items() if t > start]
    if not files:
        return None
    return np.mean(files, axis=0), len(files)


def plotFig10(histories, profiles, title, path):
    """The paper's fig. 10: eta_r histories ({label: readRheology}), and
    from the mean profiles ({label: readProfiles}) the particles' and the
    ambient streamwise velocity and shear rate across y"""
    fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
    for label, h in histories.items():
        if h is not None:
            axes[0].plot(h["strain"], h["etaR"], lw=0.8, label=label)
    for label, p in profiles.items():
        if p is None:
            continue
        prof, n = p
        y, ux, uinf, rate = prof[:, 0], prof[:, 3], prof[:, 4], prof[:, 5]
        axes[1].plot(ux, y, "o", ms=4, label=f"{label}: particles ({n} times)")
        axes[1].plot(uinf, y, "-", label=f"{label}: $U_\\infty$")
        local = np.gradient(ux, y[1] - y[0])
        axes[2].plot(local, y, "o", ms=4, label=f"{label}: d$u_x$/dy of particles")
        axes[2].plot(rate, y, "-", label=f"{label}: d$U_\\infty$/dy")
    axes[0].set_xlabel(r"strain $\dot\gamma t$")
    axes[0].set_ylabel(r"$\eta_r$")
    axes[0].set_yscale("log")
    axes[0].legend(fontsize=8)
    axes[0].set_title(title)
    axes[1].set_xlabel(r"$u_x/(\dot\gamma a_0)$")
    axes[1].set_ylabel(r"$y/a_0$")
    axes[1].legend(fontsize=6)
    axes[1].set_title("streamwise velocity (fig. 10)")
    axes[2].set_xlabel(r"local shear rate$/\dot\gamma$")
    axes[2].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def wavy():
    rows = []
    histories = {}
    profiles = {}
    for label, dirs in sorted(points("wavy").items()):
        res = analysePoint(dirs)
        if res is None:
            continue
        rows.append(row("wavy", "N", float(label.split("-N")[-1]), label.split("-")[0],
                        float("nan"), res))
        histories[label] = readRheology(dirs[0])
        start = readSummaries(dirs[0])["etaR"]["discarded"]
        profiles[label] = readProfiles(dirs[0], start)
    if not rows:
        return []
    plotFig10(histories, profiles, "Table 3: same initial condition",
              os.path.join(out, "wavy.png"))
    return rows


def dilute():
    rows = []
    for label, dirs in sorted(points("dilute").items()):
        res = analysePoint(dirs)
        if res is None:
            continue
        phi = float(label.replace("phi", ""))
        rows.append(row("dilute", "phi", phi, "monodisperse", 1 + 2.5*phi, res))
    return rows


def main():
    tables = {}
    tables["frictionless"] = jamming(
        "frictionless", fitFrictionless, r"1.4 (1 - $\phi$/0.66)$^{-1.6}$",
        "Table 1 FL: N = 200, frictionless")
    tables["frictional"] = jamming(
        "frictional", fitFrictional, r"0.71 (1 - $\phi$/0.575)$^{-2.3}$",
        r"Table 1 FR: N = 1000, $\mu_C$ = 1")
    tables["shearThickening"] = shearThickening()
    tables["wavy"] = wavy()
    tables["dilute"] = dilute()
    text = []
    sections = {}
    for name, rows in tables.items():
        if rows:
            path = writeCsv(os.path.join(out, name + ".csv"), rows, COLUMNS)
            sections[name] = (f"Table written by `docs/validation/analyse.py` from "
                              f"`{os.path.relpath(path, root)}`:\n\n"
                              + markdown(rows, withShares=name != "dilute"))
            text.append(f"\n### {name}\n\n" + sections[name])
    print("\n".join(text))
    if not quick:
        fillTables(os.path.join(root, "docs", "validation.md"), sections)


if __name__ == "__main__":
    main()
